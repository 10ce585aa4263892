"""thermobear: power loss and temperatures of rolling bearings.

Public names only; see README.md for the map of modules.
"""
from thermobear.errors import (ThermobearError, InputError, SolverError, NoEquilibrium, NoConvergence,
                     ThermalRunaway, OutsideValidity, ExtrapolationWarning)
from thermobear.contact.materials import Material, material, material_names, reduced_modulus
from thermobear.contact.hertz import hertz, HertzContact
from thermobear.files import example_path
from thermobear.contact.geometry import BallBearing, bearing, bearing_names
from thermobear.loads.static import load_distribution, LoadDistribution, needs_high_speed
from thermobear.loads.highspeed import load_distribution_high_speed, FilmInputs
from thermobear.loads.film import film_load_distribution, FilmLoadDistribution
from thermobear.rating import rating_life, RatingLife
from thermobear.contact.kinematics import ball_kinematics
from thermobear.lubrication.lubricant import Lubricant, lubricant, lubricant_names
from thermobear.lubrication.film import film_thickness, lubrication_regime
from thermobear.losses.rolling import rolling_force
from thermobear.losses.skf import skf_friction
from thermobear.losses.drag import drag_loss
from thermobear.losses.local import bearing_losses, LossResult, prepare_contacts, evaluate_losses
from thermobear.thermal import load_network, solve_steady, solve_transient
from thermobear.scene.scene import Scene, load_scene
from thermobear.coupled.solver import solve, steady_state, transient, choose_models, open_contacts
from thermobear.app.sweep import run_sweep
from thermobear.app.rig import read_log, compare, calibrate, RigLog

__version__ = "0.1.0"
