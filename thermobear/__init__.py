"""thermobear: power loss and temperatures of rolling ball bearings.

Public names only; the pipeline and the one place each concern lives: ARCHITECTURE.md.
"""
from thermobear.errors import (ThermobearError, InputError, ContactLimit, SolverError,  # noqa: F401
                               NoEquilibrium, NoConvergence, ThermalRunaway, ThermalPreloadRunaway, NoSpeedRoot,
                               OutsideValidity, ExtrapolationWarning)
from thermobear.files import example_path  # noqa: F401
from thermobear.contact.materials import Material, material, material_names, reduced_modulus  # noqa: F401
from thermobear.contact.hertz import hertz, HertzContact  # noqa: F401
from thermobear.contact.geometry import BallBearing, bearing, bearing_names  # noqa: F401
from thermobear.contact.kinematics import ball_kinematics  # noqa: F401
from thermobear.lubrication.lubricant import Lubricant, lubricant, lubricant_names  # noqa: F401
from thermobear.lubrication.film import film_thickness, lubrication_regime  # noqa: F401
from thermobear.loads import load_distribution, LoadDistribution, needs_high_speed  # noqa: F401
from thermobear.loads.highspeed import load_distribution_high_speed, FilmInputs  # noqa: F401
from thermobear.loads.film import film_load_distribution, FilmLoadDistribution  # noqa: F401
from thermobear.loads.sets import Support, ShaftLoads, bearing_set, shaft_on_two_supports, shaft_loads  # noqa: F401
from thermobear.contact.fits import operating_clearance, OperatingClearance  # noqa: F401
from thermobear.losses import bearing_losses, LossResult, prepare_contacts, evaluate_losses  # noqa: F401
from thermobear.losses.rolling import rolling_force  # noqa: F401
from thermobear.losses.skf import skf_friction  # noqa: F401
from thermobear.losses.drag import drag_loss  # noqa: F401
from thermobear.thermal import load_network, prepare_network, solve_steady, solve_transient  # noqa: F401
from thermobear.scene import Scene, load_scene  # noqa: F401
from thermobear.rating import rating_life, RatingLife, iso16281_life  # noqa: F401
from thermobear.rating.maker_speeds import maker_speeds, MakerSpeeds  # noqa: F401
from thermobear.models import choose_models, open_contacts  # noqa: F401
from thermobear.coupled import (solve, steady_state, steady_states, transient, scene_losses, prepare,  # noqa: F401
                                Prepared, RunResult, SteadyState, TransientRun, UncertaintyResult)
from thermobear.app.sweep import run_sweep  # noqa: F401
from thermobear.app.rig import read_log, compare, RigLog  # noqa: F401
from thermobear.app.calibration import calibrate  # noqa: F401

__version__ = "0.1.0"
