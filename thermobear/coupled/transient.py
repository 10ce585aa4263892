r"""Heat-up of a scene: the thermal network integrated in time with the losses re-evaluated.

.. math:: C_f \frac{dT_f}{dt} = S\, P(C T_f) - A_{ff}(T) T_f - A_{fb}(T) T_b

with the loss parts P at the coupled temperatures (:mod:`thermobear.coupled.sources`) and the
network of :mod:`thermobear.thermal`; integrated by :func:`thermobear.thermal.solve_transient`
(BDF).  A schedule changes the operating point at given times (speed, loads, inlet and ambient
temperatures, oil flow, lubricant): each segment gets its own loads, contacts and network (a
step may change boundary temperatures, convection and contact ellipses, not only the losses).
With the film load model the loads depend on the film temperature T_f, the mean contact temperature:
its loads are solved on a grid of film temperatures 3 K apart (each node once, :class:`_FilmCells`), and
inside a cell [T_j, T_j+1] the losses — and where the film model is the dominant alternative, the network's
conductances (its contact ellipses and speeds) — are interpolated linearly in T_f between the two nodes'
solutions (:class:`~thermobear.coupled.blend.StackedBlend`), so that the loads follow the temperatures
continuously.  A segment is run in pieces, one per cell: a piece ends at the integrator's step where T_f has
left its cell by a tenth of its width (``until`` of :func:`~thermobear.thermal.solve_transient`), and the
integrator goes on from piece to piece (``continue_from``: its order, step size and Jacobian kept; it starts
afresh only at a schedule's step, or where the sources step beyond the tolerances' scale).  Once the film
temperature settles — at its present rate it would move less than 0.25 K over the longer of the rest of the
segment and the time the segment has run, asked at each piece's start (a piece in a cell lasts at most as long
as the segment has run, so that the question comes up again) — the heat-up goes on in cells eight times finer
(0.375 K: an interpolation error 64 times smaller), till it moves 2 K away: it ends at the steady state, the
same for every run length past settling (a 16002 in an oil bath at −10 °C settled 0.17 K off the fixed point in
its 3 K cell, and the loads held at the settled film temperature moved its inner ring's end by up to 0.28 K
with the run's length; in the fine cells its end is one state from 1e4 to 1e6 s, 3 mK off the fixed point,
validation/CHANGES.md).
Where the loads jump at a film temperature (a ball lifting off; the film temperature has no fixed point,
:func:`thermobear.coupled.steady.steady_state` names the jump) the cell's interpolation settles across the jump,
and the fine cell's loads there change the losses by more than 1 %: the heat-up goes on with the grid cell's
interpolated loads, where it stays at the jump, and says so (a named OutsideValidity warning, also where a run
ends settled inside a grid cell whose loads at its film temperature change the losses by more than 1 %).  Against
pieces of 0.05 K
(loads at each piece's start), at rtol = atol = 1e-8, the cells keep seed 004's heat-ups (3200 rpm; 4800 rpm
under 1300 N radial; 8070 rpm under 750 N) within 1.7, 2.2 and 0.8 mK and the oil-bath 6208's, whose losses
vary with T_f in 0.3 % waves about 6 K long, within 76 mK, where pieces of ≈ 2 K held at their start
temperature gave 6, 53, 63 and 161 mK (validation/CHANGES.md).

One bearing of a preloaded pair (``[bearing] arrangement``) runs its loaded bearing in pieces under the pair's loads
at the ring and ball temperatures of each piece's start, a piece ending where they drift by more than 2 % (the warm-up
overshoot of a position preload, its runaway: :mod:`thermobear.coupled.transient_pair`, ``TransientRun.preload``).

A logged boundary (``boundary``: node → temperatures sampled at times, e.g. the room, an outer
ring, the oil inlet as a rig logged them) imposes those nodes, linear between the samples
(:class:`thermobear.thermal.solve.LinearBoundary`), and varies them continuously through every
segment and piece: the schedule and the boundary reach the integrator through the same
``fixed_C(t)`` of :func:`thermobear.thermal.solve_transient`.
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import numpy as np

from thermobear.coupled.limits import emit, film_load_preload_warnings, point_warnings, runaway_at, runaway_in
from thermobear.coupled.clearance import heat_up_preload_warnings, preload_runaway, scene_at_clearance
from thermobear.coupled.ratings import check_static_safety, scene_clearance
from thermobear.coupled.pipeline import Family, family_film_loads, family_loads, film_temperature_C, stack_loads
from thermobear.coupled.pointmodel import PointModel, heat_sources, point_model
from thermobear.coupled.preload import check_pair_static_safety, scene_pair_loads
from thermobear.coupled.sources import loss_sources, prepared_for
from thermobear.coupled.transient_pair import load_follower
from thermobear.errors import InputError, OutsideValidity, SolverError, ThermalPreloadRunaway, ThermalRunaway
from thermobear.losses import prepare_contacts
from thermobear.arrays import instance_of, take
from thermobear.coupled.blend import FilmNetwork, StackedBlend
from thermobear.models import Alternative, plan_many
from thermobear.scene import Scene
from thermobear.scene.scene import SECTIONS
from thermobear.schema import Field, check_value, real_number
from thermobear.thermal import solve_transient
from thermobear.thermal.solve import LinearBoundary
from thermobear.units import ZERO_C_K
from thermobear.validity import T_LUBRICANT_REFUSE_C

__all__ = ["TransientRun", "transient", "PointModel", "point_model", "heat_sources"]

_C0 = ZERO_C_K                 # [K] at 0 °C (thermobear.units)
_FILM_DT0_S = 20.0      # first piece of a film-load-model transient [s]
_FILM_DRIFT_K = 2.0     # film-temperature drift per piece [K] where the loads are re-solved at each piece's start
_FILM_CELL_K = 3.0      # film temperatures at which the film loads are solved: a grid this far apart [K]
_FILM_AHEAD = 8         # grid nodes whose film loads are solved in one batched call (the node met and the next 7)
_FILM_SETTLED_K = 0.25  # a heat-up whose film temperature moves less to the end goes on in the fine cells there [K]
_FILM_FINE = 8          # the fine cells of a settled heat-up: the grid's cut in this many (interpolation error ∝ w²)
_CLEAR_DRIFT_M = 0.5e-6  # operating-clearance drift per piece [m] (models.clearance = "operating")
_JUMP_REL = 0.01        # a settled heat-up whose fine cell's loads change its losses by more: a jump of the loads
                        # (the blended model switches keep their steps below 1 %, thermobear.models.BLEND_BANDS)


@dataclass
class TransientRun:
    """Heat-up of a scene.

    Attributes
    ----------
    t_s : ndarray            times [s]
    T_C : dict               node → temperatures [°C] (arrays over t_s)
    P_W : ndarray            total power loss [W]
    breakdown_W : dict       loss family → power [W] over t_s
    models_used : dict       model → (choice, reason) of the first segment; "schedule" lists the choices
                             that later schedule steps change (e.g. the film load model from a radial step)
    roles : dict             role → node
    warnings : list          OutsideValidity warnings of the run
    completed : bool         False when the run was stopped early (what was integrated is kept)
    preload : dict | None    of a preloaded pair's bearing: its preload through the heat-up (cold, peak, end [N],
                             history; :mod:`thermobear.coupled.transient_pair`)
    """

    t_s: np.ndarray
    T_C: dict
    P_W: np.ndarray
    breakdown_W: dict
    models_used: dict
    roles: dict = field(default_factory=dict)
    warnings: list = field(default_factory=list)
    completed: bool = True
    preload: dict | None = None


def _segments(scene: Scene, schedule, t_end_s):
    """[(t_start, scene)] of a schedule ``[(t_s, overrides), ...]``: times increasing, in [0, t_end)."""
    if schedule is not None and not isinstance(schedule, (list, tuple)):
        raise InputError("schedule", type(schedule).__name__, "a list of steps (t_s, {override: value, ...})")
    out = [(0.0, scene)]
    for k, step in enumerate(schedule or []):
        if not (isinstance(step, (list, tuple)) and len(step) == 2 and isinstance(step[1], dict)):
            raise InputError(f"schedule[{k}]", step, "a step (t_s, {override: value, ...})")
        t, ch = real_number(step[0]), step[1]
        if t is None or not (np.isfinite(t) and 0 <= t < t_end_s):
            raise InputError(f"schedule[{k}].t_s", step[0], f"step times must lie in [0, {t_end_s:g}) s")
        if k > 0 and t <= out[-1][0]:
            raise InputError(f"schedule[{k}].t_s", t, f"step times must increase (the step before is at "
                             f"{out[-1][0]:g} s; two steps at one time would be merged)")
        out.append((t, out[-1][1].with_(**ch)))
    return out


def _film_of(T_state, roles, scene) -> float:
    """Mean contact temperature [°C], ¼ (2 T_ball + T_inner + T_outer), of a start temperature or a state
    (node → °C; a dict start's nodes left out at the start the integrator gives them, :func:`_T_nodes`), else
    the scene's default (:func:`~thermobear.coupled.pipeline.film_temperature_C`)."""
    if not isinstance(T_state, dict):
        return float(T_state) if np.ndim(T_state) == 0 and T_state is not None else film_temperature_C(scene)
    T_all = _T_nodes(T_state, roles, scene)
    T = sum(w * float(T_all[roles[r]]) for r, w in _FILM_WEIGHTS)
    return float(T) if np.isfinite(T) else film_temperature_C(scene)


_FILM_WEIGHTS = (("ball", 0.5), ("inner", 0.25), ("outer", 0.25))   # of the mean contact temperature (_film_of)


def _pieces(scenes, t_end_s):
    bounds = [t for t, _ in scenes] + [float(t_end_s)]
    return [(ts, bounds[k + 1], sc, k == len(scenes) - 1) for k, (ts, sc) in enumerate(scenes) if bounds[k + 1] > ts]


def transient(scene: Scene, t_end_s: float, *, schedule=None, T0_C=None, t_eval=None, rtol: float = 1e-5,
              atol: float = 1e-3, load=None, stop=None, prepared=None, boundary=None) -> TransientRun:
    """Heat-up of a scene on its thermal network, losses re-evaluated as temperatures change.

    Parameters
    ----------
    scene : Scene
    t_end_s : float          end time [s]
    schedule : list          optional steps ``[(t_s, {"n_rpm": ..., "Fa": ..., ...}), ...]`` applied
                             from t_s on (:meth:`Scene.with_` overrides); times must increase
    T0_C : float or dict     start temperature of the free nodes [°C] (default: ambient)
    t_eval : array_like      output times [s]
    rtol, atol : float       BDF tolerances (atol in K): the defaults keep the seed 004 heat-up (3600 s,
                             every node at 37 output times) within 5 mK and the power within 2e-4 of
                             a rtol = atol = 1e-8 solution
    load : LoadDistribution  loads to use instead of the model's (one operating point: no schedule)
    stop : callable          ``stop() -> bool``, checked during the integration: True ends the run
                             early, keeping what was integrated (``completed`` False)
    prepared : Prepared      :func:`~thermobear.coupled.sources.prepare` of the scene's family, reused
                             (with ``boundary``: of the scene with those nodes imposed)
    boundary : LinearBoundary  logged temperatures of nodes [°C] at times [s] on the run's clock
                             (:class:`~thermobear.thermal.solve.LinearBoundary`, or a pair
                             ``(t_s, {node: T_C})``): the nodes are imposed (``T_fixed_C``, a node
                             receiving loss heat is refused) and follow the samples, linear between
                             them; the samples must cover [0, t_end_s] (no extrapolation)

    Returns
    -------
    TransientRun             of one bearing of a preloaded pair with its ``preload`` through the heat-up (cold,
                             peak and end preload, the history; :mod:`thermobear.coupled.transient_pair`)

    Raises
    ------
    ThermalPreloadRunaway    a pair's preload that runs away (what was integrated in its ``last``)
    """
    scene, T0_C = instance_of(scene, Scene, "scene"), _start_of(T0_C)
    t_end_s, rtol, atol = (check_value(v, _POSITIVE[k], k) for k, v in (("t_end_s", t_end_s), ("rtol", rtol),
                                                                          ("atol", atol)))
    if stop is not None and not callable(stop):
        raise InputError("stop", type(stop).__name__, "a callable stop() -> bool, or None")
    if load is not None and schedule:
        raise InputError("load", "LoadDistribution", "injected loads hold one operating point: no schedule")
    if t_eval is not None:
        t_eval = np.asarray(t_eval, float)
        if t_eval.ndim != 1 or np.any(~np.isfinite(t_eval)) or np.any((t_eval < 0) | (t_eval > t_end_s)) \
                or np.any(np.diff(t_eval) <= 0):
            raise InputError("t_eval", t_eval, f"output times must increase within [0, {t_end_s}] s")
    if boundary is not None:
        boundary, scene = _imposed(boundary, scene, t_end_s)
    segments = _segments(scene, schedule, t_end_s)
    for t_s, sc in segments:                                    # every step's loads, before any solve
        try:                                                    # (a pair: its loaded bearing, cold at speed)
            if sc.arrangement is None:
                check_static_safety(sc)
            else:
                check_pair_static_safety(sc, scene_pair_loads(sc, None), "cold at speed")
        except InputError as exc:
            if t_s == 0.0:
                raise
            raise InputError(f"schedule step at t = {t_s:g} s: {exc.field}", exc.value, exc.expected) from None
    pre, follow = prepared_for(scene, prepared), load_follower(scene, load)    # a pair: its loads follow the heat-up
    return _run(_pieces(segments, t_end_s), scene, T0_C, t_eval, rtol, atol, load, stop, pre, boundary, follow)


_POSITIVE = {k: Field.number(u, 0.0, lo_open=True) for k, u in (("t_end_s", "s"), ("rtol", "-"), ("atol", "K"))}


def _start_of(T0_C):
    """``T0_C`` checked: None, a temperature [°C] or node → temperature, in a scene temperature's range."""
    if isinstance(T0_C, dict):
        return {check_value(n, Field.text(), "T0_C (node)"): check_value(v, SECTIONS["thermal"]["T_ambient_C"],
                                                                        f"T0_C[{n!r}]") for n, v in T0_C.items()}
    return None if T0_C is None else check_value(T0_C, SECTIONS["thermal"]["T_ambient_C"], "T0_C")


def _imposed(boundary, scene: Scene, t_end_s):
    """The boundary, checked to cover [0, t_end_s], and the scene with its nodes imposed at t = 0."""
    if not isinstance(boundary, LinearBoundary):
        try:
            t_s, T_C = boundary
        except (TypeError, ValueError):
            raise InputError("boundary", type(boundary).__name__, "a LinearBoundary or (t_s, {node: T_C})") from None
        boundary = LinearBoundary.of(t_s, T_C)
    t0, t1 = boundary.span_s
    if t0 > 0.0 or t1 < t_end_s:
        raise InputError(boundary.source, f"[{t0:g}, {t1:g}] s", f"the logged boundary must cover the run [0, "
                         f"{t_end_s:g}] s (a log is not extrapolated)")
    return boundary, scene.with_(T_fixed_C={**scene.T_fixed_C, **boundary(0.0)})


def _run(pieces, scene, T0_C, t_eval, rtol, atol, load, stop, pre, boundary, follow) -> TransientRun:
    T_state = scene.T_ambient_C if T0_C is None else T0_C
    out_t, out_T, out_rep, first, seg_changes, seen = [], {}, {}, None, {}, set()
    film_dt, completed, i, plans, clear_hist, prev, kept = None, True, -1, {}, [], None, (None, None, None, None)
    cells: dict = {}        # scene (id) → its _FilmCells: the loads solved for it during the run
    last_film = None        # (film temperature's rate at its end [K/s], scene) of the last piece
    settling = _Settling()  # per scene: where its heat-up settled (fine cells there), past a jump of the loads
    c, mounted = None, {}   # the last piece's operating clearance; scene (id) → (it at its mounted clearance, alts)
    with warnings.catch_warnings():
        # property calls at the integrator's trial states may lie beyond a correlation's data; the
        # validity of the states reported is checked once, on the series (limits.point_warnings)
        warnings.simplefilter("ignore", OutsideValidity)
        while i + 1 < len(pieces):
            i += 1
            (ts, te, sc0, last_seg), roles = pieces[i], (first[1] if first else pre.coupling.roles)
            sc = follow.piece(sc0, ts, _T_nodes(T_state, roles, sc0), roles)     # a pair's: its loaded bearing
            if id(sc) not in plans:           # film pieces of one step share its scene: planned once
                plans[id(sc)] = _alternatives(sc, load)
            alts = plans[id(sc)]
            choice = alts[0].models["clearance"][0] if load is None else "given"
            clear, sc_p = choice == "operating", sc
            if choice != "given":             # the clearance at the piece's start temperatures
                c = _piece_clearance(sc, T_state, roles, clear_hist, ts)
            if clear:                         # the loads at it (negative: a radial preload)
                sc_p = scene_at_clearance(sc, c["operating"] * 1e-6)
                alts = _alternatives(sc_p, load)
            elif choice == "mounted":         # the loads at the fits' clearance at 20 °C, one bearing for the run
                if id(sc) not in mounted:
                    sc_m = scene_at_clearance(sc, c["mounted"] * 1e-6)
                    mounted[id(sc)] = (sc_m, _alternatives(sc_m, load))
                sc_p, alts = mounted[id(sc)]
            models = max(alts, key=lambda a: a.weight).models
            film = load is None and any(a.models["load_model"][0] == "film" for a in alts)
            T_film, split, nodes = (_film_of(T_state, roles, sc) if film else None), False, (None,)
            fc = cells.setdefault(id(sc_p), _FilmCells(sc_p, T_film if film else 0.0))
            t_max, settled = np.inf, False
            if film and not clear:     # a cell of the film grid, a fine one where the heat-up has settled
                nodes, t_max, settled = settling.cell(fc, T_film, ts, te, sc, last_film)
            elif film:                 # a piece at its own operating clearance: a scene of its own
                nodes = (T_film,)
            if clear or len(nodes) == 1 and film:    # pieces of ≈ _FILM_DRIFT_K / _CLEAR_DRIFT_M of drift, loads at start
                film_dt = min(_FILM_DT0_S, te - ts) if film_dt is None else film_dt
            dt = min(film_dt if clear or len(nodes) == 1 and film else np.inf, follow.length_s())   # a pair's: its drift
            if ts + dt < te - 1e-9 * te:
                pieces.insert(i + 1, (ts + dt, te, sc0, last_seg))
                te, last_seg, split = ts + dt, False, True
            pm, sources = _sources_of(kept, sc_p, alts, load, pre, fc, nodes)
            if settled and kept[0] is sc_p and len(kept[1]) == 2 and settling.jumps(
                    sc, T_film, ts, _loss_step(kept[3], sources, pm.network, T_state)):  # the fine cell's loads
                nodes, t_max = fc.cell(T_film), np.inf      # against the grid cell's: a jump, the grid cell's stay
                pm, sources = _sources_of(kept, sc_p, alts, load, pre, fc, nodes)
            kept = (sc_p, nodes, pm, sources)
            net, cp = pm.network, pm.coupling
            first = first or (models, cp.roles, list(net.nodes))
            changed = {k: v for k, v in models.items() if first[0].get(k, (None,))[0] != v[0]}
            if changed and id(sc0) not in seen:
                seen.add(id(sc0))
                seg_changes[ts] = changed
            if list(net.nodes) != first[2]:
                raise InputError("schedule", ts, "a step may not change the thermal network's nodes")
            seg = None
            if t_eval is not None:   # points in [ts, te) belong to this segment (right-continuous at steps)
                want = t_eval[(t_eval >= ts) & ((t_eval < te) | (last_seg & (t_eval <= te)))]
                seg = np.union1d(want - ts, [te - ts])
            tr = solve_transient(net, sources, te - ts, T0_C=None if prev else _T0(T_state, net), t_eval=seg,
                                 rtol=rtol, atol=atol, stop=stop, continue_from=prev,
                                 fixed_C=None if boundary is None else boundary.shifted(ts),
                                 until=follow.until(net, cp.roles, _cell_exit(nodes, net, cp.roles, t_max) if len(nodes)
                                                    > 1 else _drift_exit(nodes[0], net, cp.roles) if film else None))
            if tr.completed and tr.t.size and float(tr.t[-1]) < te - ts:     # it left its film cell: the rest from there
                pieces.insert(i + 1, (ts + float(tr.t[-1]), te, sc0, last_seg))
                te, last_seg, split = ts + float(tr.t[-1]), False, True
            prev = tr if split and tr.completed else None  # the next piece goes on with this one's integrator
            _append(out_t, out_T, out_rep, tr, ts, te, t_eval, last_seg)
            T_state = _T_nodes_of(tr, net) if tr.t.size else T_state
            if not tr.completed:           # stopped: what was integrated, to the time it reached
                completed, te = False, (ts + float(tr.t[-1]) if tr.t.size else ts)
                break
            if film:           # the film temperature's rate at the end: its crossing of the next cell, or settling
                last_film = (float(tr.end_rate_K_s()[0] @ _film_weights(net, cp.roles)), sc)
            if film or clear:  # next piece: ≈ _FILM_DRIFT_K of film-temperature drift, _CLEAR_DRIFT_M of clearance
                f = [_FILM_DRIFT_K / max(abs(_film_of(T_state, cp.roles, sc) - T_film), 1e-9)] if film else []
                if clear:
                    c1 = scene_clearance(sc, _T_nodes(T_state, cp.roles, sc), cp.roles)["operating"]
                    f.append(_CLEAR_DRIFT_M / max(abs(c1 - c["operating"]) * 1e-6, 1e-15))
                film_dt = (te - ts) * float(np.clip(min(f), 0.5, 4.0))
            try:
                runaway_at(T_state, te)
                follow.ended(te, _T_nodes(T_state, cp.roles, sc0), cp.roles)   # a pair: the next piece's loads
            except (ThermalRunaway, ThermalPreloadRunaway) as e:  # a radial or pair's preload: its runaway (.last)
                err = follow.runaway(e, te) or (preload_runaway(sc, c, clear_hist, f"during the heat-up at t = {te:g} s "
                                                                f"({e})") if clear and c["operating"] < 0 else None)
                if err is None:
                    raise
                err.last = follow.finish(_assemble(out_t, out_T, out_rep, first, seg_changes, [], False))
                raise err from e
        if completed and film and len(nodes) == 2 and settling.warning is None and id(sc) not in settling.at:
            # ends settled inside a grid cell: the loads there?
            settling.warning = _settled_jump(kept, alts, load, pre, fc, T_state, cp.roles, last_film,
                                             te - settling.started.get(id(sc), ts), te)
    got = []
    if out_t and np.concatenate(out_t).size:        # (stopped before its first output time: no warnings to give)
        ro, cat = first[1], np.concatenate
        Tb = cat(out_T[ro["ball"]])
        x = [0.5 * (Tb + cat(out_T[ro["inner"]])), 0.5 * (Tb + cat(out_T[ro["outer"]])), cat(out_T[ro["oil"]])]
        runaway_in(x, cat(out_t))
        seal = cat(out_T["seal"]).max() if "seal" in out_T else None      # a built network's seal node
        for sc in follow.scenes(pieces[:i + 1]):
            got += [w for w in point_warnings(sc, None, np.concatenate(x), T_seal_C=seal) if str(w) not in map(str, got)]
        for fc in cells.values():             # the film loads it passed: a preload by the films (cold, viscous oil)
            got += [w for w in fc.preload_warnings() if str(w) not in map(str, got)]
    got += [settling.warning] if settling.warning is not None else []
    end = first and load is None and _T_nodes(T_state, first[1], pieces[i][2])
    got += heat_up_preload_warnings(pieces[i][2], c if choice == "operating" else None, end or None,
                                    first[1] if first else None, clear_hist, te) + follow.warnings(end, roles, te)
    if choice != "given" and c is not None and c["operating" if choice == "operating" else "mounted"] < 0:
        got = [w for w in got if w.quantity != "unloaded"]    # the loads at a radial preload: every ball loaded
    emit(got)
    return follow.finish(_assemble(out_t, out_T, out_rep, first, seg_changes, got, completed))


def _append(out_t, out_T, out_rep, tr, ts, te, t_eval, last_seg):
    """A piece's times (absolute [s]), node temperatures and report appended to the run's lists: the times of
    ``t_eval`` (all the integrator's without), the step's instant left to the next segment."""
    t_abs = np.asarray(tr.t) + ts
    keep = np.ones(t_abs.size, bool) if t_eval is None else np.isin(np.round(t_abs, 9), np.round(t_eval, 9))
    if not last_seg and tr.completed:
        keep &= t_abs < te                    # the step's instant is reported by the next segment
    out_t.append(t_abs[keep])
    for n, v in tr.T_C.items():
        out_T.setdefault(n, []).append(np.asarray(v)[keep])
    for n, v in tr.report.items():
        out_rep.setdefault(n, []).append(np.asarray(v, float)[keep])


class _Settling:
    """Where the heat-up of each scene (id) settles: the time its first piece started (``started`` [s]), the film
    temperature it settled at (``at`` [°C]: its pieces then in the fine cells there), the scenes past a jump of the
    loads (``jumped``: the grid's cells to the end) and the jump's warning (``warning``, the first)."""

    def __init__(self):
        self.started, self.at, self.jumped, self.warning = {}, {}, set(), None

    def cell(self, fc: "_FilmCells", T_film, ts, te, sc, last_film) -> tuple:
        """(nodes, t_max [s], settled) of a piece of scene ``sc`` in [ts, te] starting at the film temperature
        ``T_film`` [°C]: its grid cell, ended after ``t_max`` (twice the expected crossing, at most as long as
        the scene has run: whether it settles is asked again), until the film temperature settles — at its rate at
        the end of the last piece (``last_film``) it would move less than ``_FILM_SETTLED_K`` over the longer of
        the rest and the time the scene has run; from then on (``settled`` True on the first), the fine cell
        there, till it moves ``_FILM_DRIFT_K`` away."""
        ran = ts - self.started.setdefault(id(sc), ts)
        nodes = fc.cell(T_film)
        t_cross, drift = _crossing(fc, nodes, T_film, max(te - ts, ran), last_film, sc)
        at = self.at.get(id(sc))
        if at is not None and abs(T_film - at) > _FILM_DRIFT_K:       # moved on from where it settled
            del self.at[id(sc)]
        elif at is None and drift <= _FILM_SETTLED_K and id(sc) not in self.jumped:
            self.at[id(sc)] = T_film
            return fc.cell(T_film, fine=True), np.inf, True
        if id(sc) in self.at:
            return fc.cell(T_film, fine=True), np.inf, False
        return nodes, min(np.inf if t_cross is None else 2.0 * t_cross, max(ran, _FILM_DT0_S)), False

    def jumps(self, sc, T_film, t_s, step) -> bool:
        """True where a heat-up of scene ``sc`` settled at ``T_film`` [°C] (at ``t_s`` [s]), whose fine cell's loads
        change the losses by ``step`` [-] against its grid cell's, past a jump of the loads (``step`` >
        ``_JUMP_REL``): it goes on in its grid cells, and the jump's warning (:func:`_jump_warning`) says so."""
        if step <= _JUMP_REL:
            return False
        self.jumped.add(id(sc))
        del self.at[id(sc)]
        self.warning = self.warning or _jump_warning(T_film, t_s, step)
        return True


def _sources_of(kept, sc_p, alts, load, pre, fc, nodes) -> tuple:
    """(point model, heat sources) of a piece of scene ``sc_p`` in the film cell ``nodes``: the last piece's
    (``kept``) in the same scene and cell, else :func:`_piece_model` (its family, network and coupling the last
    piece's where they serve, :func:`_dominant_kept`)."""
    if kept[0] is sc_p and kept[1] == nodes:
        return kept[2], kept[3]
    pm = _piece_model(sc_p, alts, load, pre if pre.serves(sc_p) else None, fc, nodes,
                      dominant=kept[2] if kept[0] is sc_p and _dominant_kept(alts) else None)
    return pm, heat_sources(pm)


def _settled_jump(kept, alts, load, pre, fc, T_state, roles, last_film, elapsed_s, t_s):
    """The jump warning (:func:`_jump_warning`) of a heat-up that ends settled — its film temperature, at its rate
    at the end, moving less than ``_FILM_SETTLED_K`` over the ``elapsed_s`` it ran — inside a grid cell (its losses
    interpolated between the cell's nodes; one that settled earlier went on in the fine cells, checked then), where
    the loads solved at its film temperature change the losses by more than ``_JUMP_REL`` (one more load solve);
    else None."""
    sc_p, _, _, sources = kept
    if last_film is None or abs(last_film[0]) * elapsed_s > _FILM_SETTLED_K:
        return None
    T_end = _film_of(T_state, roles, sc_p)
    try:
        held = _piece_model(sc_p, alts, load, pre if pre.serves(sc_p) else None, fc, (T_end,))
        step = _loss_step(sources, heat_sources(held), held.network, T_state)
    except (InputError, SolverError):      # a check after the run: it never costs the run (no warning then)
        return None
    return _jump_warning(T_end, t_s, step) if step > _JUMP_REL else None


def _film_weights(net, roles) -> np.ndarray:
    """(n,): the film temperature c · T of node temperatures T — the mean contact temperature,
    ¼ (2 T_ball + T_inner + T_outer) = ½ (x_inner + x_outer) (:func:`_film_of`)."""
    c = np.zeros(len(net.nodes))
    for role, w in _FILM_WEIGHTS:
        c[net.index[roles[role]]] += w
    return c


def _crossing(cells: "_FilmCells", nodes, T_film, horizon, last, scene) -> tuple:
    """(time [s] until the film temperature ``T_film`` [°C] leaves the cell ``nodes`` by a tenth of its width,
    its drift [K] over ``horizon`` [s]) at its rate at the end of the last piece (``last``: that rate [K/s] and
    the piece's scene); (None, inf) without a last piece of this scene."""
    if last is None or last[1] is not scene:
        return None, np.inf
    rate = last[0]
    gap = (nodes[1] - T_film if rate > 0 else T_film - nodes[0]) + 0.1 * cells.step
    return gap / max(abs(rate), 1e-12), abs(rate) * horizon


def _cell_exit(nodes, net, roles, t_max=np.inf):
    """``until(t, T_K)`` of :func:`~thermobear.thermal.solve_transient`: True once the film temperature (the
    mean contact temperature of the node temperatures) has left the film cell ``nodes`` by a tenth of its width,
    so that the next piece starts inside the next cell — or after ``t_max`` [s] (the heat-up slowing down: whether
    it has settled in this cell is asked again, :meth:`_Settling.cell`)."""
    c, w = _film_weights(net, roles), 0.1 * (nodes[-1] - nodes[0])
    lo, hi = nodes[0] - w + _C0, nodes[-1] + w + _C0

    def until(t, T_K) -> bool:
        T = float((T_K @ c)[0])
        return T < lo or T > hi or t > t_max
    return until


def _drift_exit(T_film, net, roles):
    """``until(t, T_K)`` of a piece whose film loads are held at ``T_film`` [°C] (a piece at its own operating
    clearance): True once the film temperature has drifted from it by more than ``_FILM_DRIFT_K``, so that the next
    piece re-solves the loads where the heat-up went (a piece's length comes from the drift rate of the last one)."""
    c = _film_weights(net, roles)
    lo, hi = T_film - _FILM_DRIFT_K + _C0, T_film + _FILM_DRIFT_K + _C0

    def until(t, T_K) -> bool:
        T = float((T_K @ c)[0])
        return T < lo or T > hi
    return until


def _T_nodes_of(tr, net) -> dict:
    """Free node → its temperature [°C] at the end of a piece (as ``T_state``)."""
    return {n: float(np.asarray(v)[-1]) for n, v in tr.T_C.items() if n in net.free_nodes}


def _loss_step(before, after, net, T_state) -> float:
    """Relative change [-] of the total loss at the node temperatures ``T_state`` (free node → °C) from the
    sources ``before`` to ``after`` (:func:`heat_sources`)."""
    T = net.T_fixed_K.copy()
    for n, v in T_state.items():
        T[:, net.index[n]] = v + _C0
    P0, P1 = (float(s(0.0, T)[0].sum()) for s in (before, after))
    return abs(P1 - P0) / max(abs(P0), 1e-300)


def _jump_warning(T_held, t_s, step) -> OutsideValidity:
    """The named warning of a heat-up that had settled at the film temperature ``T_held`` [°C] (at ``t_s`` [s])
    where the film loads solved there have losses ``step`` [-] off those of the cell's loads interpolated in the
    film temperature, more than ``_JUMP_REL``: the loads jump at that film temperature (the settled state is that
    of the interpolation across the jump), it has no fixed point there."""
    return OutsideValidity(
        f"film load model: the heat-up settled at a film temperature of {T_held:.2f} °C (t = {t_s:.4g} s), where the "
        f"loads solved at that temperature change the losses by {100 * step:.3g} %: the loads jump there and the film "
        f"temperature has no fixed point (thermobear run names the jump); the heat-up stays at the jump, the loads "
        f"interpolated across it between the film temperatures of its cell ({_FILM_CELL_K:g} K apart)",
        quantity="film load jump", value=T_held, limit="a film temperature the loads do not jump at",
        source="thermobear.coupled.transient", field="models.load_model")


def _alternatives(sc: Scene, load) -> list:
    """The model alternatives of a piece (:func:`~thermobear.models.plan_many`); injected loads: the
    dominant one alone."""
    alts = plan_many([sc])[0]
    if isinstance(alts, Exception):
        raise alts
    if load is not None or len(alts) == 1:
        a = max(alts, key=lambda a: a.weight)
        return [Alternative(a.models, a.dry, 1.0)]
    return alts


def _dominant_kept(alts) -> bool:
    """True when the network of a blended piece (its dominant alternative's) does not depend on the film
    temperature: local losses across a switch band, the dominant's loads not of the film load model."""
    if len(alts) == 1 or alts[0].models["losses"][0] != "local":
        return False
    return max(alts, key=lambda a: a.weight).models["load_model"][0] != "film"


class _FilmCells:
    """The film temperatures at which a scene's alternatives have their loads during a heat-up: for the film
    load model the nodes of a grid T0 + j Δ [°C] (the cells its losses are interpolated over), of the grid
    ``_FILM_FINE`` times finer where the heat-up settles, and the film temperatures of the pieces at their own
    operating clearance and of the check after a run — each solved once per alternative,
    its Newton started from the alternative's nearest film temperature solved (the same loads, other films: the
    same equilibrium in fewer iterations; :func:`~thermobear.coupled.pipeline.family_film_loads`); the other
    alternatives' loads once."""

    def __init__(self, scene: Scene, T0: float, step: float | None = None):
        self.scene, self.T0, self.step, self.solved = scene, float(T0), _FILM_CELL_K if step is None else step, {}
        self.used: dict = {}          # (k, T) asked for by a piece → the alternative's dry solution (the checks)

    def preload_warnings(self) -> list:
        """The film-preload warning of the film loads the heat-up used (:func:`film_load_preload_warnings`)."""
        return film_load_preload_warnings(self.scene, [(T, self.solved[(k, T)][0], dry) for (k, T), dry in
                                                       self.used.items() if T is not None and dry is not None])

    def cell(self, T_film, fine: bool = False) -> tuple:
        """The grid's film temperatures (T_lo, T_hi) [°C] around ``T_film`` (``fine``: of the grid ``_FILM_FINE``
        times finer, whose every ``_FILM_FINE``-th node is the grid's), inside the lubricant's range (a cell
        reaching past its limit ends there: the heat-up beyond is a runaway,
        :func:`~thermobear.coupled.limits.runaway_at`)."""
        n = _FILM_FINE if fine else 1
        j, w = math.floor((T_film - self.T0) / self.step * n), self.step / n
        lo, hi = T_LUBRICANT_REFUSE_C
        a, b = max(self.T0 + j / n * self.step, lo), min(self.T0 + (j + 1) / n * self.step, hi)
        if b - a < 1e-9 * w:                  # at the range's end itself: the last cell inside it
            a, b = (b - w, b) if b >= hi else (a, a + w)
        return a, b

    def load(self, k: int, alt, T=None):
        """One-point loads of alternative ``k`` (``alt``): with the films at ``T`` [°C], or its own (not of the
        film load model).  A grid node met in a heat-up (or cool-down) is solved in one batched call with the next
        ``_FILM_AHEAD`` − 1 nodes it is moving towards, each from the same start (a batch of eight costs two to
        three times one solve; a heat-up crosses 7–20 nodes of 3 K); should that batch fail, the node alone."""
        self.used[(k, T)] = alt.dry
        if (k, T) not in self.solved:
            if T is None:
                fam = Family(scenes=(self.scene,), index=(0,), models=alt.models, dry=(alt.dry,))
                self.solved[(k, T)] = (take(family_loads(fam), 0, 1), None)
                return self.solved[(k, T)][0]
            near = [(abs(T_j - T), T_j) for kk, T_j in self.solved if kk == k and T_j is not None]
            start = self.solved[(k, min(near)[1])][1] if near else None
            ahead = self._ahead(k, T, min(near)[1]) if near else []
            try:
                self._solve(k, alt, [T] + ahead, start)
            except (InputError, SolverError):
                if not ahead:
                    raise
                self._solve(k, alt, [T], start)
        return self.solved[(k, T)][0]

    def _ahead(self, k: int, T: float, T_from: float) -> list:
        """The grid nodes after ``T`` in the direction from ``T_from`` not solved yet (none off the grid)."""
        j = (T - self.T0) / self.step
        if abs(j - round(j)) > 1e-9:
            return []
        d = 1 if T > T_from else -1
        nodes = [self.T0 + (round(j) + m * d) * self.step for m in range(1, _FILM_AHEAD)]  # as cell() makes them
        lo, hi = T_LUBRICANT_REFUSE_C
        return [T_m for T_m in nodes if (k, T_m) not in self.solved and lo <= T_m <= hi]

    def _solve(self, k: int, alt, Ts: list, start):
        K = len(Ts)
        fam = Family(scenes=(self.scene,) * K, index=tuple(range(K)), models=alt.models, dry=(alt.dry,) * K)
        ld, sol = family_film_loads(fam, Ts, None if start is None else take(start, np.zeros(K, int), 1))
        for i, T in enumerate(Ts):
            self.solved[(k, T)] = (take(ld, i, K), take(sol, np.array([i]), K))


def _piece_model(sc: Scene, alts, load, prepared, cells: _FilmCells, nodes, dominant=None) -> PointModel:
    """The point model of a piece (``load``: injected loads instead of the alternatives'): across a switch band
    its heat sources are the weighted losses of the alternatives, evaluated as stacked points of one batch
    (:class:`~thermobear.coupled.blend.StackedBlend`) on the network of the dominant one, so that a heat-up
    ends at the blended steady state.  An alternative of the film load model has its loads at the film
    temperatures of ``nodes`` (of ``cells``): with two, its losses interpolated between them in the film
    temperature (the loads follow it continuously); with one, held there.  ``dominant``: the point model of an
    earlier piece of the same scene whose family, network and coupling serve (:func:`_dominant_kept`)."""
    k_dom = int(np.argmax([a.weight for a in alts]))
    dom = alts[k_dom]
    film = [a.models["load_model"][0] == "film" and load is None for a in alts]
    if load is not None or alts[0].models["losses"][0] != "local" or (len(alts) == 1 and not film[0]):
        # one source: injected loads, the global model (its loads only the network's), one alternative of given loads
        ld = load if load is not None else cells.load(k_dom, dom, nodes[0] if film[k_dom] else None)
        return point_model(sc, dom.models, load=ld, prepared=prepared, dry=dom.dry)
    rows = [(a, cells.load(k, a, j if film[k] else None), film[k] and len(nodes) > 1 and j == nodes[0],
             film[k] and len(nodes) > 1 and j == nodes[-1])
            for k, a in enumerate(alts) for j in (nodes if film[k] else (None,))]
    pm = dominant or point_model(sc, dom.models, load=cells.load(k_dom, dom, nodes[0] if film[k_dom] else None),
                                 prepared=prepared)
    if film[k_dom] and len(nodes) > 1:       # the dominant's network follows the film temperature as its losses do
        hi = point_model(sc, dom.models, load=cells.load(k_dom, dom, nodes[-1]), prepared=prepared).network
        pm = PointModel(family=pm.family, coupling=pm.coupling, source=pm.source,
                        network=FilmNetwork.between(pm.network, hi, _film_weights(pm.network, pm.coupling.roles),
                                                             nodes[0], nodes[-1]))
    K, m = len(rows), dom.models
    fam = Family(scenes=(sc,) * K, index=tuple(range(K)), models=m, dry=(None,) * K)
    cs = prepare_contacts(sc.bearing, fam.values("Fa"), fam.values("Fr"), fam.values("n_rpm"),
                          M=None if sc.M is None else fam.values("M"), rotating=sc.rotating,
                          hertz_method=m["hertz"][0], load=stack_loads([r[1] for r in rows]), control=m["kinematics"][0],
                          centrifugal=np.array([r[0].models["high_speed"][0] != "yes" for r in rows]))
    lower, upper = np.array([r[2] for r in rows]), np.array([r[3] for r in rows])
    return PointModel(family=pm.family, network=pm.network, coupling=pm.coupling,
                      source=StackedBlend(loss_sources(fam, cs), [r[0].weight for r in rows],
                                          film=(lower, upper, nodes[0], nodes[-1]) if lower.any()
                                          else None))


def _T_nodes(T_state, roles, scene) -> dict:
    """Node → °C of a piece's start state (a uniform start: the roles' nodes at that temperature; a dict start
    that leaves a role's node out: that node imposed, else where the integrator starts it,
    :func:`~thermobear.thermal.solve_transient`: at the ambient)."""
    if isinstance(T_state, dict):
        missing = [n for n in roles.values() if n not in T_state]
        start = scene.T_fixed_C.get("ambient", scene.T_ambient_C)
        return {**{n: start for n in missing}, **scene.T_fixed_C, **T_state} if missing else T_state
    return {n: float(T_state) for n in roles.values()}


def _piece_clearance(sc: Scene, T_state, roles, hist: list, t_s: float) -> dict:
    """The operating clearance [µm] (:func:`~thermobear.coupled.ratings.scene_clearance`) at a piece's start,
    appended to the heat-up's clearance history."""
    c = scene_clearance(sc, _T_nodes(T_state, roles, sc), roles)
    T = c["temperatures_C"]
    hist.append(dict(t_s=t_s, operating_um=c["operating"], T_inner_ring_C=T["inner ring"],
                     T_outer_ring_C=T["outer ring"], T_balls_C=T["balls"],
                     dT_inner_outer_K=T["inner ring"] - T["outer ring"]))
    return c


def _T0(T_state, net):
    """Start temperatures of a segment: a number, or node → °C restricted to the free nodes."""
    if isinstance(T_state, dict):
        return {n: v for n, v in T_state.items() if n in net.free_nodes}
    return T_state


def _assemble(out_t, out_T, out_rep, first, seg_changes, got, completed) -> TransientRun:
    cat = lambda parts: np.concatenate(parts) if parts else np.zeros(0)  # noqa: E731
    rep = {n: cat(v) for n, v in out_rep.items()}
    used = dict(first[0])
    if seg_changes:
        used["schedule"] = ("models change with the schedule", "; ".join(
            f"from t = {t:g} s: " + ", ".join(f"{k} {v[0]} ({v[1]})" for k, v in ch.items())
            for t, ch in sorted(seg_changes.items())))
    return TransientRun(t_s=cat(out_t), T_C={n: cat(v) for n, v in out_T.items()}, P_W=rep.get("P_W", np.zeros(0)),
                        breakdown_W={n[2:]: v for n, v in rep.items() if n.startswith("P_") and n != "P_W"},
                        models_used=used, roles=first[1], warnings=list(got), completed=completed)
