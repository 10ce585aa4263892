"""thermobear: power loss and temperatures of rolling bearings.

Public names only; see README.md for the map of modules.
"""
from .errors import (ThermobearError, InputError, SolverError, NoEquilibrium, NoConvergence,
                     ThermalRunaway, OutsideValidity, ExtrapolationWarning)
from .materials import Material, material, material_names, reduced_modulus
from .hertz import hertz, HertzContact
from ._data import example_path
from .geometry import BallBearing, bearing, bearing_names
from .loads import load_distribution, LoadDistribution, needs_high_speed
from .loads_highspeed import load_distribution_high_speed, FilmInputs
from .loads_film import film_load_distribution, FilmLoadDistribution
from .kinematics import ball_kinematics
from .lubricant import Lubricant, lubricant, lubricant_names
from .film import film_thickness, lubrication_regime
from .friction.rolling import rolling_force
from .friction.skf import skf_friction
from .friction.drag import drag_loss
from .losses import bearing_losses, LossResult, prepare_contacts, evaluate_losses
from .thermal import load_network, solve_steady, solve_transient
from .scene import Scene, load_scene
from .solver import solve, steady_state, transient, choose_models, open_contacts
from .sweep import run_sweep
from .rig import read_log, compare, calibrate, RigLog

__version__ = "0.1.0"
