r"""Temperature → preload → loads → losses → temperatures: the thermal preload of a position-preloaded pair.

A scene with ``[bearing] arrangement`` is one bearing of a symmetric pair of angular contact bearings
(:mod:`thermobear.scene.pair`: both run the same temperatures, the scene's network is that bearing's share of the
machine, the scene's bearing the one that carries the larger axial load).  Its loads come from the pair
(:func:`thermobear.loads.pair.pair_loads`): the external Fa, Fr on the pair's cold preload F_0, and — with a
position preload — the rings' and balls' temperatures above the mounting temperature (20 °C): the inner ring
running warmer than the outer and the balls warmer still, the inner ring grows radially against the outer ring
and the preload rises (Harris & Kotzalas 2007 [1] ch. 3 and 8).  More preload, more friction, a hotter inner ring
and more preload: the steady state is the fixed point

.. math:: F_{a,k} = g(F_{a,k}) = F_{a,k}\bigl(T_i(F_{a,k}),\, T_o(F_{a,k}),\, T_b(F_{a,k})\bigr)

solved by direct iteration, as the heat-up would reach it: each step a full coupled steady state of the bearing
under the loaded bearing's loads (F_a,k, F_r,k), its inner-ring, outer-ring and ball temperatures (nodes
``inner_ring`` / ``outer_ring``, else the inner / outer role; the ball role), the warm pair's loads again, until the
loads change by less than ``tol_N``.  The first step is at the cold preload at the scene's speed.  A spring preload
keeps its force: no loop, one steady state under the spring force and the external loads.

Runaway (:class:`~thermobear.errors.ThermalPreloadRunaway`, with the history of the loop and its warm preloads):
as for a radial preload (:mod:`thermobear.coupled.clearance`), the iteration diverges when the loop's gain g′
reaches 1.  From three steps with the load rising (r = g(F) − F > 0), the step not shrinking, r_k ≥ r_{k−1} (the
secant slope of g ≥ 1), and its growth not slowing, r_k / r_{k−1} ≥ r_{k−1} / r_{k−2} (the slope not falling): g(F) − F
only grows with the preload, no fixed point ahead (:func:`preload_step_runs_away`; the slope alone passes 1 for a
step or two from a light preload before the loop settles).  Also a runaway: a step at a preload above the cold one whose coupled steady state has no solution (its thermal fixed
point runs away, :class:`~thermobear.errors.ThermalRunaway`, or its contacts are overloaded), warm loads the pair
cannot carry (its contacts overloaded, or its rings grown through the clearance), and ``_MAXITER`` steps still
rising.  The answer carries a named warning where the warm preload passes twice the cold one
(:data:`thermobear.validity.LIMITS` ``thermal_preload``).

The fixed point is probed once for stability: the loop started at twice its axial load must fall back
(g(2F) < 2F), else a second, unstable equilibrium lies between and the answer says so (a named warning; the
probe's result in ``preload["probe"]``; a probe the models cannot evaluate — the warm rings closing the radial play
at 2F — says that the stability is not established).  The pair's loads are those at the scene's speed
(:func:`thermobear.loads.pair.pair_loads` with ``n_rpm``: each bearing's high-speed load–displacement, the balls'
centrifugal force, and the inner rings' centrifugal growth; Jones 1960, Harris & Kotzalas 2007 *Advanced Concepts*
ch. 1–3): the preload at speed, at any speed — the form reduces to the static one as n → 0, so it does not follow
the loaded bearing's own choice of form (``models.high_speed``), raceway control the scene's kinematics (outer
unless ``inner``).  The cold preload F_0 is mounted at rest; at speed, cold, the pair already carries more
(``preload["at_speed_cold_N"]``, the first step's).  A rotating outer ring keeps the static form (the high-speed
form is the inner ring's; so is the bearing's own, :func:`thermobear.models.choose_models`).  Cost: (iterations +
1) steady states per point (the probe included), the points of a step in one call.

References
----------
.. [1] Harris, T. A. & Kotzalas, M. N. (2007). *Essential Concepts of Bearing Technology*, 5th ed., CRC Press,
   ch. 3 (thermal expansion) and ch. 8 (bearing deflection and preloading: duplex pairs, position and spring
   preload).
"""
from __future__ import annotations

import dataclasses

from thermobear.contact.fits import T_REF_C, seated_raceway_growth
from thermobear.coupled.ratings import _node_T, check_static_safety, inner_seat
from thermobear.errors import (ContactLimit, InputError, NoConvergence, OutsideValidity, SolverError,
                               ThermalPreloadRunaway, ThermalRunaway)
from thermobear.loads.pair import PairLoads, pair_loads, pair_preload_offset
from thermobear.models import high_speed_control
from thermobear.validity import check, collect

__all__ = ["preload_loop", "pair_scene", "cold_pair", "pair_state", "check_pair_static_safety", "loaded_scene", "pair_temperatures", "pair_speed_rpm", "scene_pair_loads",
           "preload_step_runs_away",
           "preload_lines", "PRELOAD_TOL_N"]

PRELOAD_TOL_N = 1e-3          #: fixed-point tolerance on the loaded bearing's loads [N]
_MAXITER = 40


def pair_temperatures(T_C: dict, roles: dict) -> dict:
    """Inner-ring, outer-ring and ball temperatures [°C] of a solved state (node → °C; ``roles``: role → node): the
    nodes ``inner_ring`` / ``outer_ring``, else the inner / outer role's; the ball role's."""
    return {"inner ring": _node_T(T_C, roles, ("inner_ring",), "inner")[0],
            "outer ring": _node_T(T_C, roles, ("outer_ring",), "outer")[0],
            "balls": _node_T(T_C, roles, (), "ball")[0]}


def pair_scene(scene, loads):
    """The pair scene's bearing alone under the loaded bearing's ``loads`` (a :class:`~thermobear.loads.pair.PairLoads`,
    or an answer's ``preload`` dict with ``Fa_N``, ``Fr_N``; the network and everything else unchanged): a
    single-bearing scene."""
    Fa, Fr = (loads["Fa_N"], loads["Fr_N"]) if isinstance(loads, dict) else (loads.Fa, loads.Fr)
    return dataclasses.replace(scene, Fa=Fa, Fr=Fr, arrangement=None, preload_force=None, preload_kind=None,
                               pair_spacer=None)


def cold_pair(scene) -> tuple:
    """A pair scene's loads at the mounting temperature, as ``thermobear loads`` gives them: ``(data, lines,
    loaded, warnings)`` — the pair's preload, the loaded bearing's loads and the pair's stiffness at rest and at the
    scene's speed (:func:`pair_state`; the high-speed form where the inner ring rotates) as a JSON-ready dict [N,
    N/µm] and text lines, the loaded bearing's scene under its last loads (:func:`pair_scene`; each state's static
    safety checked: :func:`~thermobear.coupled.ratings.check_static_safety`), and the named warnings of a stiffness
    not evaluated."""
    data, lines, warned = {}, [], []
    fast = pair_speed_rpm(scene) is not None
    for state, rest in (("at_rest", True), ("at_speed", False)) if fast else (("at_rest", True),):
        g, w = pair_state(scene, None, None, rest, state.replace("_", " "))
        check_pair_static_safety(scene, g, "cold " + state.replace("_", " "))
        warned += w
        k = {} if g.stiffness is None else {"k_axial_N_um": g.stiffness[0] * 1e-6, "k_radial_N_um": g.stiffness[1] * 1e-6,
                                            "k_tilt_Nm_mrad": g.stiffness[2] * 1e-3}
        data[state] = dict(preload_N=g.preload, Fa_N=g.Fa, Fr_N=g.Fr, Fa_other_N=g.Fa_other, **k)
        lines.append(f"  {'at rest' if rest else f'at {scene.n_rpm:g} rpm'}: preload {g.preload:.4g} N; loaded bearing "
                     f"Fa {g.Fa:.4g} N, Fr {g.Fr:.4g} N (the other Fa {g.Fa_other:.4g} N)" + (
                         f"; stiffness axial {k['k_axial_N_um']:.4g}, radial {k['k_radial_N_um']:.4g} N/µm, tilt "
                         f"{k['k_tilt_Nm_mrad']:.4g} N m/mrad" if k else
                         "; stiffness not evaluated (warning)"))
    head = (f"{scene.arrangement.replace('_', '-')} pair, {scene.preload_kind or 'position'} preload "
            f"{scene.preload_force:g} N cold, under Fa {scene.Fa:g} N, Fr {scene.Fr:g} N, at the mounting temperature "
            f"{T_REF_C:g} °C (warm: `thermobear run`, the thermal preload)")
    return {"description": head, **data}, [head] + lines, pair_scene(scene, g), warned


def check_pair_static_safety(scene, loads: PairLoads, state: str) -> None:
    """Refuse (InputError naming the pair's preload and loads) a pair scene whose loaded bearing under ``loads`` (in
    ``state``, e.g. "at rest") is beyond the refused static safety
    (:func:`~thermobear.coupled.ratings.check_static_safety` of :func:`pair_scene`)."""
    try:
        check_static_safety(pair_scene(scene, loads))
    except InputError as exc:
        raise InputError("bearing.preload_N, operation (Fa_N, Fr_N)",
                         f"preload {scene.preload_force:g} N, Fa {scene.Fa:g} N, Fr {scene.Fr:g} N",
                         f"the pair's loaded bearing {state} carries Fa {loads.Fa:.4g} N, Fr {loads.Fr:.4g} N: "
                         f"{exc.expected}") from None


def pair_state(scene, T, offset: float | None, at_rest: bool, state: str) -> tuple:
    """``(PairLoads, warnings)``: a pair scene's loads with its stiffness (:func:`scene_pair_loads` ``with_stiffness``)
    at the temperatures ``T`` (None: the mounting temperature), at rest or at its speed; where the stiffness's load
    steps have no solution (a pair at the model's edge), the loads alone (``stiffness`` None) and a named
    OutsideValidity warning for ``state``.  A failure of the loads themselves is raised."""
    try:
        return scene_pair_loads(scene, T, offset, with_stiffness=True, at_rest=at_rest), []
    except (InputError, SolverError) as exc:
        g = scene_pair_loads(scene, T, offset, at_rest=at_rest)
        return g, [OutsideValidity(
            f"pair stiffness {state}: not evaluated — the pair's loads with the stiffness's load steps have no "
            f"solution ({type(exc).__name__}: {' '.join(str(exc).split())[:160]})", quantity="pair stiffness",
            value=float("nan"), limit="the pair's loads solved", source="thermobear.loads.pair.pair_loads (with_stiffness)",
            field="bearing.preload_N")]


def loaded_scene(scene, steady):
    """The scene as its bearing runs in a solved state: a pair scene's loaded bearing under the loads of the
    answer (``steady.preload``), any other scene as it is (e.g. for the ratings)."""
    p = getattr(steady, "preload", None)
    if scene.arrangement is None or not p:
        return scene
    return pair_scene(scene, p)


def preload_step_runs_away(history: list, tol_N: float = PRELOAD_TOL_N) -> bool:
    r"""The loop's steps raise the loaded bearing's axial load without shrinking, and their growth is not slowing
    (module docstring): with r = g(F) − F (``Fa_N`` − ``Fa_used_N``) of the last three steps,

    .. math:: r_k > \mathrm{tol}, \qquad r_k \ge r_{k-1} > 0, \qquad r_k\, r_{k-2} \ge r_{k-1}^2 .

    In direct iteration F_k = g(F_{k−1}), so r_k / r_{k−1} is the secant slope of g between the last two steps: the
    first condition is g′ ≥ 1 (the steps not shrinking, as :mod:`thermobear.coupled.clearance` names it), the second
    that this slope is not falling (g − F convex): then g(F) − F only grows with the preload, no fixed point ahead.
    The slope alone is not enough: from a light cold preload the force rises steeply with the interference (Hertz,
    F ∝ δ^1.5) and the loop's gain passes 1 for a step or two before the loss's response flattens and the loop
    settles (measured with the pair's static form: a 7014C pair at 16000 rpm, steps 13, 63, 136, 267 N, then
    101 N, settling at 1080 N).

    >>> h = [dict(Fa_used_N=431.0, Fa_N=450.0), dict(Fa_used_N=450.0, Fa_N=500.0), dict(Fa_used_N=500.0, Fa_N=640.0)]
    >>> preload_step_runs_away(h), preload_step_runs_away(h[:2])          # steps 19, 50, 140 N: growing faster
    (True, False)
    >>> preload_step_runs_away([h[0], h[1], dict(Fa_used_N=500.0, Fa_N=600.0)])   # 19, 50, 100 N: slope falling
    False
    """
    if len(history) < 3:
        return False
    r2, r1, r0 = (h["Fa_N"] - h["Fa_used_N"] for h in history[-3:])
    return r0 > tol_N and r0 >= r1 > 0 and r2 > 0 and r0 * r2 >= r1 * r1


def _runaway(scene, hist: list, T: dict, what: str) -> ThermalPreloadRunaway:
    """The named error of a pair's preload that runs away (``hist`` the loop's steps, ``T`` the last temperatures)."""
    dT = T["inner ring"] - T["outer ring"]
    last = hist[-1] if hist else {}
    pre = [h["preload_N"] for h in hist]
    return ThermalPreloadRunaway(
        f"thermal preload runaway of a {scene.arrangement.replace('_', '-')} pair: {what} — cold preload "
        f"{scene.preload_force:.4g} N" + (f", warm {pre[-1]:.4g} N" if pre else "") +
        f" with the inner ring at {T['inner ring']:.1f} °C, outer ring {T['outer ring']:.1f} °C (ΔT {dT:.1f} K), "
        f"balls {T['balls']:.1f} °C: a lighter preload, a spring preload, more cooling or less speed is needed",
        iterations=len(hist), residual=abs(last.get("Fa_N", 0.0) - last.get("Fa_used_N", 0.0)), last=last,
        history=hist, preload_history_N=pre, dT_inner_outer_K=float(dT))


def _warm_failure(exc, hist: list) -> str:
    """What stopped the pair's loads at a step's temperatures (``exc``), for the runaway's message: the rings and
    balls grown through the bearing's radial play, or overloaded contacts; with the loop's steps so far."""
    field = getattr(exc, "field", "")
    what = ("the rings and balls at these temperatures close the bearing's radial play (its free contact angle "
            "would pass 0: a radial preload on top of the axial one, beyond the model)" if field.startswith("dT_") else
            "the warm pair's contacts are overloaded" if field.startswith("Fa, Fr, M") else
            f"the warm pair has no equilibrium ({type(exc).__name__})")
    steps = [h["Fa_N"] - h["Fa_used_N"] for h in hist]
    if steps:
        what += (f"; the loop's steps of the loaded bearing's axial load {', '.join(f'{r:+.4g}' for r in steps)} N" +
                 (" were shrinking: a fixed point may lie just past what the model represents" if len(steps) > 1 and
                  abs(steps[-1]) < abs(steps[-2]) else ""))
    return f"{what} [{' '.join(str(exc).split())[:200]}]"


def thermal_preload_warnings(scene, warm: float, T: dict, at_speed_N: float | None = None) -> list:
    """The named warnings of a pair's warm preload (:data:`thermobear.validity.LIMITS` ``thermal_preload``): beyond
    twice the cold one, below half of it (0: the pair has play); ``at_speed_N``: the pair's preload at speed still
    cold [N], named beside (the share of the speed in the rise)."""
    lost = "; the pair has play (no preload left)" if warm <= 0.0 else ""
    fast = "" if at_speed_N is None else f" ({at_speed_N:.4g} N at speed, still cold)"
    with collect(replay=False) as got:
        check("thermal_preload", warm / scene.preload_force, "bearing.preload_N",
              what=f"{warm:.4g} N warm against {scene.preload_force:.4g} N cold at rest{fast}, inner ring "
                   f"{T['inner ring']:.1f} °C, outer ring {T['outer ring']:.1f} °C, balls {T['balls']:.1f} °C{lost}")
    return list(got)


def pair_speed_rpm(scene) -> float | None:
    """The speed of a pair scene's high-speed form [rpm]: the scene's where its inner ring rotates (the form of
    :func:`~thermobear.loads.pair.pair_loads` with ``n_rpm``), else None (the static form)."""
    return float(scene.n_rpm) if scene.rotating == "inner" else None


def scene_pair_loads(scene, T, offset: float | None = None, start: PairLoads | None = None, *,
                     with_stiffness: bool = False, at_rest: bool = False) -> PairLoads:
    """The loads of a pair scene's loaded bearing and the pair's preload (:func:`~thermobear.loads.pair.pair_loads`)
    at the ring and ball temperatures ``T`` [°C] (:func:`pair_temperatures`; None: the mounting temperature
    :data:`~thermobear.contact.fits.T_REF_C`), at the scene's speed where its inner ring rotates (the high-speed form
    of both bearings; else, or ``at_rest``, the static form), with its kinematics' raceway control; ``offset``: the
    position preload [m] when the caller has it (default :func:`~thermobear.loads.pair.pair_preload_offset`);
    ``start``: a nearby answer to start the high-speed solve from; ``with_stiffness``: the pair's axial and radial
    stiffness too.  The one evaluation the steady loop and the heat-up share."""
    kind = scene.preload_kind or "position"
    dT = {k: 0.0 if T is None else T[k] - T_REF_C for k in ("inner ring", "outer ring", "balls")}
    n = None if at_rest else pair_speed_rpm(scene)
    u = None if not n else float(seated_raceway_growth(scene.bearing, n, **inner_seat(scene)))
    return pair_loads(scene.bearing, scene.arrangement, scene.preload_force, kind, scene.Fa, scene.Fr,
                      spacer=scene.pair_spacer or 0.0, dT_inner=dT["inner ring"], dT_outer=dT["outer ring"],
                      dT_ball=dT["balls"], offset=offset, n_rpm=n,
                      control=high_speed_control(scene) if n else "outer", start=start, u_inner=u,
                      with_stiffness=with_stiffness)


class _Pair:
    """One point's loop (module docstring): its cold loads, the loads used, the history."""

    def __init__(self, scene, tol_N: float):
        self.scene, self.tol, self.hist = scene, tol_N, []
        self.kind = scene.preload_kind or "position"
        self.final, self.done = None, False       # the fixed point's answer, while its stability probe runs
        self.offset = (pair_preload_offset(scene.bearing, scene.preload_force) if self.kind == "position" else None)
        self.n_rpm = pair_speed_rpm(scene)
        self.cold = self.used = self.loads_at(None)

    def loads_at(self, T) -> PairLoads:
        """The pair's loads at the temperatures ``T`` (None: the mounting temperature): :func:`scene_pair_loads`."""
        return scene_pair_loads(self.scene, T, self.offset)

    def step(self, r):
        """(the point's answer or error, None) or (None, the scene of the next step)."""
        if self.done:
            return r, None
        if self.final is not None:                 # the probe above the fixed point came back
            return self.probed(r), None
        T = pair_temperatures(r.T_C, r.roles)
        if self.kind == "spring":                  # a constant force: the cold loads are the loads
            return self.answer(r, self.cold, T, self.scene.preload_force, 0.0), None
        try:
            g = self.loads_at(T)
        except (InputError, SolverError) as exc:
            e = _runaway(self.scene, self.hist, T, _warm_failure(exc, self.hist))
            e.__cause__ = exc
            return e, None
        res = max(abs(g.Fa - self.used.Fa), abs(g.Fr - self.used.Fr))
        self.hist.append(dict(iteration=len(self.hist) + 1, Fa_used_N=self.used.Fa, Fa_N=g.Fa, Fr_used_N=self.used.Fr,
                              Fr_N=g.Fr, Fa_other_N=g.Fa_other, preload_N=g.preload, T_inner_ring_C=T["inner ring"],
                              T_outer_ring_C=T["outer ring"], T_balls_C=T["balls"],
                              dT_inner_outer_K=T["inner ring"] - T["outer ring"], P_W=r.P_W))
        if res <= self.tol:
            self.final = (r, self.used, T, g.preload, res)
            return None, pair_scene(self.scene, self.probe_loads())
        if preload_step_runs_away(self.hist, self.tol):
            return _runaway(self.scene, self.hist, T, "each step of the preload loop adds at least as much load as "
                            "the last (the heat of the preload warms the inner ring and balls into more preload than "
                            "it took: no fixed point)"), None
        if len(self.hist) >= _MAXITER:
            if g.Fa > self.used.Fa:
                return _runaway(self.scene, self.hist, T, f"the preload loop still rises after {_MAXITER} steps"), None
            return NoConvergence(f"pair preload: no fixed point within {_MAXITER} steps (last {self.used.Fa:.6g} → "
                                 f"{g.Fa:.6g} N)", iterations=len(self.hist), residual=res, history=self.hist), None
        self.used = g
        return None, pair_scene(self.scene, g)

    def probe_loads(self) -> PairLoads:
        """The loaded bearing's loads of the stability probe: the fixed point's with the axial load doubled."""
        return dataclasses.replace(self.final[1], Fa=2.0 * self.final[1].Fa)

    def probed(self, r):
        r"""The fixed point's answer, with a named warning where the probe at twice its axial load does not fall back:
        there g(F) ≥ F (or no steady state at all), so g − F crosses 0 again above the fixed point — an unstable
        equilibrium, beyond which the preload rises to a second, hotter fixed point or runs away; a heat-up that
        overshoots (the inner ring and balls warming before the housing) can carry the pair across it."""
        self.done = True
        r0, used, T, warm, res = self.final
        out = self.answer(r0, used, T, warm, res)
        F, g = self.probe_loads().Fa, None
        if isinstance(r, ThermalRunaway):            # no steady state at 2F: the heat outgrows the cooling there
            got, above = f"no steady state ({type(r).__name__})", True
        elif isinstance(r, Exception):               # a model limit, not a verdict on stability
            got, above = f"not evaluated: {type(r).__name__}", None
        else:
            try:
                g = self.loads_at(pair_temperatures(r.T_C, r.roles)).Fa
                got, above = f"g = {g:.4g} N", g >= F
            except (InputError, SolverError) as exc:  # e.g. the warm rings closing the radial play at 2F
                got, above = f"not evaluated: {_warm_failure(exc, [])}", None
        out.preload["probe"] = dict(Fa_N=F, g_N=g, result=got, rises=above)
        if above is None:
            out.warnings.append(OutsideValidity(
                f"pair preload: its stability above the fixed point is not established — the loop started at twice "
                f"its axial load ({F:.4g} N) could not be evaluated ({got})", quantity="pair preload stability",
                value=F, limit="g(2 F) evaluated", source="thermobear.coupled.preload (the loop map g probed once)",
                field="bearing.preload_N"))
        elif above:
            out.warnings.append(OutsideValidity(
                f"pair preload: a second equilibrium above the fixed point — the loop started at twice its axial load "
                f"({F:.4g} N) does not fall back ({got}): between the two the preload is unstable, above it rises "
                "to a hotter state or runs away; a heat-up that overshoots (inner ring and balls warming before the "
                "housing) can carry the pair there", quantity="pair preload stability", value=F,
                limit="g(2 F) < 2 F", source="thermobear.coupled.preload (the loop map g probed once)",
                field="bearing.preload_N"))
        return out

    def stopped(self, r, T_last: dict):
        """A step's error at a preload above the cold one — its steady state runs away or its contacts are
        overloaded — as the preload's runaway (the error as its cause); other errors as they are (the stability
        probe's: the fixed point's answer, :meth:`probed`)."""
        if self.final is not None and not self.done and isinstance(r, Exception):
            return self.probed(r)
        overload = isinstance(r, ContactLimit) or isinstance(r, InputError) and r.field == "Fa, Fr, M"
        if not (isinstance(r, ThermalRunaway) or overload) or not self.used.Fa > self.cold.Fa:
            return r
        e = _runaway(self.scene, self.hist, T_last, f"the coupled steady state under Fa {self.used.Fa:.4g} N, Fr "
                     f"{self.used.Fr:.4g} N has no solution ({type(r).__name__}: {' '.join(str(r).split())[:200]})")
        e.__cause__ = r
        return e

    def balls_at_rings(self, T: dict, warm: float) -> float:
        """The warm preload [N] at the same ring temperatures with the balls at the rings' mean: the lower end of a
        bracket whose upper end is the answer's — the balls' temperature above the rings rests on the estimated
        ball–race conductance of the network and drives most of a position preload's rise (a spring: its force)."""
        if self.kind == "spring":
            return warm
        try:
            return self.loads_at({**T, "balls": 0.5 * (T["inner ring"] + T["outer ring"])}).preload
        except (InputError, SolverError):       # (a warm pair beyond the model even so: no lower end to give)
            return float("nan")

    def stiffness(self, T: dict) -> tuple:
        """The pair's axial and radial stiffness at its centre under the external loads [N/µm]
        (:func:`~thermobear.loads.pair.pair_loads` ``with_stiffness``): cold at rest (the catalogue's), cold at speed
        and warm at speed (at ``T``), as ``k_{axial,radial}_{cold,at_speed_cold,warm}_N_um`` and
        ``k_tilt_{...}_Nm_mrad`` [N m/mrad], and the named warnings
        of the states whose loads have no solution with the stiffness's load steps (those states left out)."""
        out, warned = {}, []
        for state, temps, rest in (("cold", None, True), ("at_speed_cold", None, False), ("warm", T, False)):
            try:
                g, w = pair_state(self.scene, temps, self.offset, rest, state.replace("_", " "))
            except (InputError, SolverError):   # (its loads solved in the loop: not reached; no stiffness to give)
                g, w = None, []
            warned += w
            if g is not None and g.stiffness is not None:
                out.update({f"k_axial_{state}_N_um": g.stiffness[0] * 1e-6, f"k_radial_{state}_N_um": g.stiffness[1] * 1e-6,
                            f"k_tilt_{state}_Nm_mrad": g.stiffness[2] * 1e-3})
        return out, warned

    def answer(self, r, used: PairLoads, T: dict, warm: float, res: float):
        """The point's state with its ``preload`` (loads used, warm preload, stiffness, history) and its models_used
        entry."""
        s, n = self.scene, max(len(self.hist), 1)
        stiff, stiff_warned = self.stiffness(T)
        pre = dict(arrangement=s.arrangement, kind=self.kind, cold_N=s.preload_force,
                   at_speed_cold_N=self.cold.preload, form="static" if self.n_rpm is None else "high_speed", warm_N=warm,
                   warm_balls_at_rings_N=self.balls_at_rings(T, warm),
                   offset_um=None if self.offset is None else self.offset * 1e6, Fa_N=used.Fa, Fr_N=used.Fr,
                   Fa_other_N=used.Fa_other, loaded=used.loaded, external_Fa_N=s.Fa, external_Fr_N=s.Fr,
                   **stiff, iterations=n, residual_N=res, history=list(self.hist), temperatures_C=dict(T))
        how = (f"spring: a constant {s.preload_force:.4g} N (no thermal change)" if self.kind == "spring" else
               f"position ({self.offset * 1e6:.3g} µm offset): {s.preload_force:.4g} N cold → {warm:.4g} N warm with the "
               f"inner ring {T['inner ring']:.1f} °C, outer ring {T['outer ring']:.1f} °C, balls {T['balls']:.1f} °C "
               f"(fixed point, {n} steps, residual {res:.1e} N)")
        form = ("static form: no centrifugal term in the preload" if self.n_rpm is None else
                f"high-speed form at {self.n_rpm:.6g} rpm: the spring keeps its force, the balls' centrifugal force "
                "sets the contacts" if self.kind == "spring" else
                f"high-speed form at {self.n_rpm:.6g} rpm: the balls' centrifugal force and the inner rings' growth on "
                f"their seat in the preload, {self.cold.preload:.4g} N at speed cold")
        reason = (f"{s.arrangement.replace('_', '-')} pair, {how}; the loaded bearing carries Fa {used.Fa:.4g} N, "
                  f"Fr {used.Fr:.4g} N (the pair under Fa {s.Fa:.4g} N, Fr {s.Fr:.4g} N; the other bearing Fa "
                  f"{used.Fa_other:.4g} N; {form})")
        warned = r.warnings + [w for w in thermal_preload_warnings(s, warm, T, self.cold.preload if self.n_rpm
                                                                                        else None) + stiff_warned
                               if str(w) not in map(str, r.warnings)]
        return dataclasses.replace(r, preload=pre, models_used={**r.models_used, "preload": (self.kind, reason)},
                                   warnings=warned)


def preload_loop(scenes, solve, *, tol_N: float = PRELOAD_TOL_N) -> list:
    """The steady states of ``scenes``, the pair scenes' at their preload's fixed point (module docstring).

    Parameters
    ----------
    scenes : list of Scene   the operating points (pair scenes and others)
    solve : callable         ``solve(scenes) -> list`` of steady states or errors of single-bearing scenes
    tol_N : float            fixed-point tolerance on the loaded bearing's loads [N]

    Returns
    -------
    list   per point: the state of a scene without a pair as ``solve`` gives it (the scenes without a pair solved
           in the first call, as given); of a pair scene the state of its loaded bearing at the fixed point
           (``preload`` with the cold and warm preloads, the loads, ``iterations``, ``residual_N`` and the
           ``history``), or the error that stopped it (:class:`~thermobear.errors.ThermalPreloadRunaway` where
           the preload runs away)
    """
    out: list = [None] * len(scenes)
    pairs, first = {}, {}
    for i, sc in enumerate(scenes):
        if sc.arrangement is None:
            first[i] = sc
            continue
        try:
            pairs[i] = _Pair(sc, tol_N)
            first[i] = pair_scene(sc, pairs[i].cold)
        except (InputError, SolverError) as exc:
            out[i] = exc
    for i, r in zip(first, solve(list(first.values()))):
        out[i] = r
    live = [i for i in pairs if not isinstance(out[i], Exception)]
    while live:
        nxt = {}
        for i in live:
            done, sc = pairs[i].step(out[i])
            if done is not None:
                out[i] = done
            else:
                nxt[i] = (sc, pair_temperatures(out[i].T_C, out[i].roles))
        for i, r in zip(nxt, solve([sc for sc, _ in nxt.values()]) if nxt else ()):
            out[i] = pairs[i].stopped(r, nxt[i][1])
        live = [i for i in nxt if not isinstance(out[i], Exception)]
    return out


def preload_lines(p: dict | None) -> list:
    """The text lines of a pair's preload (``SteadyState.preload``; none without)."""
    if not p:
        return []
    at = p.get("at_speed_cold_N")
    speed = (f"; {at:.4g} N at speed, cold" if p.get("form") == "high_speed" and p["kind"] == "position"
             and at is not None else "")
    head = (f"  preload ({p['arrangement'].replace('_', '-')} pair, {p['kind']}): cold {p['cold_N']:.4g} N, warm "
            f"{p['warm_N']:.4g} N ({p['warm_N'] / p['cold_N']:.3g} × cold{speed})")
    if p["kind"] == "position":
        head += f", fixed point in {p['iterations']} steps, residual {p['residual_N']:.1e} N"
    T = p["temperatures_C"]
    lo = p.get("warm_balls_at_rings_N")
    bracket = ([f"  with the balls at the rings' mean instead ({0.5 * (T['inner ring'] + T['outer ring']):.1f} °C): "
                f"{lo:.4g} N warm — the balls' temperature (the estimated ball–race conductance) makes the difference"]
               if p["kind"] == "position" and lo is not None and lo == lo else [])
    fast = p.get("form") == "high_speed"
    said = [f"{p[f'k_axial_{s}_N_um']:.4g}, {p[f'k_radial_{s}_N_um']:.4g} N/µm, {p[f'k_tilt_{s}_Nm_mrad']:.4g} N m/mrad {what}"
            for s, what in (("warm", "warm at speed" if fast else "warm"), ("cold", "cold at rest"),
                            ("at_speed_cold", "cold at speed")) if f"k_axial_{s}_N_um" in p and (fast or s != "at_speed_cold")]
    stiff = ([f"  stiffness at the pair's centre (axial, radial, tilt; the other displacements free): " + "; ".join(said)]
             if said else [])
    return [head] + bracket + [f"  loaded bearing: Fa {p['Fa_N']:.4g} N, Fr {p['Fr_N']:.4g} N (the other Fa {p['Fa_other_N']:.4g} N) "
                  f"under the pair's Fa {p['external_Fa_N']:.4g} N, Fr {p['external_Fr_N']:.4g} N; inner ring "
                  f"{T['inner ring']:.1f} °C, outer ring {T['outer ring']:.1f} °C, balls {T['balls']:.1f} °C"] + stiff
