"""Losses coupled with the thermal network: the pipeline of a family of operating points (pipeline),
the losses as heat sources (sources), steady state (steady), heat-up (transient), the fixed point
with runaway detection (fixedpoint), the validity of an answer (limits), ``thermobear run`` (run),
and the bands over the estimated inputs (uncertainty, sensitivity)."""
from thermobear.coupled.pipeline import scene_contacts, scene_load, film_scene_load  # noqa: F401
from thermobear.coupled.run import RunResult, solve  # noqa: F401
from thermobear.coupled.sources import Prepared, prepare, scene_losses  # noqa: F401
from thermobear.coupled.steady import SteadyState, steady_states  # noqa: F401
from thermobear.coupled.transient import TransientRun  # noqa: F401
# steady_state and transient with their ``uncertainty=N`` option (bands over the estimated inputs)
from thermobear.coupled.uncertainty import UncertaintyResult, steady_state, transient  # noqa: F401
