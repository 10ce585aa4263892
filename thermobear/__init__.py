"""thermobear: power loss and temperatures of rolling bearings.

Public names only; see README.md for the map of modules.
"""
from .errors import (ThermobearError, InputError, SolverError, NoEquilibrium, NoConvergence,
                     ThermalRunaway, OutsideValidity, ExtrapolationWarning)
from .materials import Material, material, material_names, reduced_modulus
from .hertz import hertz, HertzContact

__version__ = "0.1.0"
