"""Thermal networks: data files → graph (network.py), element physics (elements.py),
steady and transient solution (solve.py).  PHYSICS.md §8."""
from thermobear.thermal.network import ThermalNetwork, load_network, network_names, evaluate
from thermobear.thermal.solve import (SteadyResult, TransientResult, Flow, solve_steady, solve_transient,
                    split_losses, assemble)

__all__ = ["ThermalNetwork", "load_network", "network_names", "evaluate", "SteadyResult",
           "TransientResult", "Flow", "solve_steady", "solve_transient", "split_losses", "assemble"]
