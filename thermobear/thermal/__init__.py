"""Thermal networks: data files → a checked template → a network at operating points (network.py),
element physics (elements.py), safe expressions (expressions.py), steady and transient solution
(solve.py)."""
from thermobear.thermal.expressions import evaluate  # noqa: F401
from thermobear.thermal.network import (ROLES, NetworkTemplate, ThermalNetwork, load_network,  # noqa: F401
                                        network_names, prepare_network)
from thermobear.thermal.solve import (SteadyResult, TransientResult, solve_steady, solve_transient,  # noqa: F401
                                      sources_matrix, split_losses)

__all__ = ["ThermalNetwork", "NetworkTemplate", "prepare_network", "load_network", "network_names", "evaluate",
           "ROLES", "SteadyResult", "TransientResult", "solve_steady", "solve_transient", "split_losses",
           "sources_matrix"]
