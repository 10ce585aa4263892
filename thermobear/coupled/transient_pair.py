r"""The heat-up of one bearing of a preloaded pair: the loaded bearing's loads follow the pair's preload in time.

A pair scene (``[bearing] arrangement``, :mod:`thermobear.scene.pair`) is one bearing of a symmetric pair of angular
contact bearings whose position preload follows the rings' and balls' temperatures
(:func:`thermobear.loads.pair.pair_loads`; Harris & Kotzalas 2007 [1] ch. 3 and 8).  The steady state closes the
loop at its fixed point (:mod:`thermobear.coupled.preload`); in a heat-up the loads follow the temperatures as they
rise.  During a warm-up the inner ring and the balls, next to the heat, warm ahead of the outer ring and its
housing: the position preload overshoots its steady value before the housing catches up (the reason spindles are
run in) — or, where the heat of the preload warms the inner ring and balls into more preload faster than the housing
relieves it, runs away.

:func:`thermobear.coupled.transient.transient` runs such a heat-up in pieces, as it does for an operating clearance:
each piece runs the scene's bearing alone (:func:`~thermobear.coupled.preload.pair_scene`) under the pair's loads
at the ring and ball temperatures of its start (:func:`~thermobear.coupled.preload.pair_temperatures`, above the
mounting temperature :data:`~thermobear.contact.fits.T_REF_C`), and ends at the integrator's first step where the
pair's loads at the current temperatures have drifted from them by more than

.. math:: Δ = r \max(F_{a,k}, F_0), \qquad r = 0.02 \; (\texttt{PRELOAD\_DRIFT\_REL})

on the pair's preload or the loaded bearing's Fa or Fr (F_a,k the loaded bearing's axial load at the piece's
start, F_0 the cold preload); the integrator goes on from piece to piece.  A piece's length is also capped at the
time its loads take to drift by Δ at their rate over the last integrator step (at most four times the last piece's):
the integrator's steps grow long as the heat-up slows, and the drift is seen only at its steps.  Holding the loads at
a piece's start is a first-order (explicit) update of the loop: halving r about halves the change of the peak from
r = 0.04 on — seed 004's 7210 as a back-to-back pair at 450 N (a 1200 s heat-up past its peak, the pair at speed),
r = 0.08 → 0.04 → … → 0.0025: the peak preload 2390 → 2407 → 2421 → 2427 → 2431 → 2433 N; the end preload 2314,
2334, 2327, 2315, 2310, 2308 N and the inner ring's end 50.27, 50.52, 50.55, 50.47, 50.44, 50.43 °C scatter within
about 1 % and 0.1 K as the piece boundaries move (tests/test_pair_heatup.py): r = 0.02 keeps the heat-up within about 1 % of the preload and 0.1 K of its limit r → 0.  A settled heat-up holds loads within Δ of
those at its temperatures: it ends within about Δ of the steady fixed point (tests/test_pair_heatup.py: seed 004's
pair after 20 000 s).  A spring preload keeps its force: its loads once.

The answer (``TransientRun.preload``) gives the cold, peak and end preloads, the history of the pieces (their
start times, the preload and the loaded bearing's loads, the ring and ball temperatures) and the preload and loads
at the output times (at the temperatures, linear between the integrator's steps; its peak among them).  Warnings as the steady state's
(:func:`~thermobear.coupled.preload.thermal_preload_warnings`): at the end, and at the peak or the lowest preload
during the heat-up where those pass the limits (the pair losing its preload: play).

A preload that runs away raises :class:`~thermobear.errors.ThermalPreloadRunaway` (what was integrated in its
``last``, a :class:`~thermobear.coupled.transient.TransientRun`): the pair's loads at a piece's end beyond the model
(its warm rings closing the radial play, its contacts overloaded, no equilibrium, or the loaded bearing's static
safety below the refused limit), or the heat-up passing the lubricant's limit
(:func:`~thermobear.coupled.limits.runaway_at`) with the preload above the cold one.

References
----------
.. [1] Harris, T. A. & Kotzalas, M. N. (2007). *Essential Concepts of Bearing Technology*, 5th ed., CRC Press,
   ch. 3 (thermal expansion) and ch. 8 (bearing deflection and preloading: duplex pairs, position and spring
   preload).
"""
from __future__ import annotations

import numpy as np

from thermobear.coupled.preload import (pair_scene, pair_speed_rpm, pair_temperatures, scene_pair_loads,
                                        thermal_preload_warnings)
from thermobear.coupled.ratings import check_static_safety
from thermobear.errors import InputError, OutsideValidity, SolverError, ThermalPreloadRunaway, ThermalRunaway
from thermobear.loads.pair import PairLoads, pair_preload_offset
from thermobear.models import refuse_pair
from thermobear.units import ZERO_C_K
from thermobear.validity import LIMITS

__all__ = ["PRELOAD_DRIFT_REL", "HeldLoads", "PairHeatUp", "load_follower", "preload_line"]

#: The drift bound of a piece of a pair's heat-up, relative to the loaded bearing's axial load at its start (at
#: least the cold preload): a piece ends where the pair's loads at the current temperatures have moved that far
PRELOAD_DRIFT_REL = 0.02
_C0 = ZERO_C_K                 # [K] at 0 °C (thermobear.units)
_PARTS = ("inner ring", "outer ring", "balls")


def load_follower(scene, load=None) -> "HeldLoads":
    """The loads of a heat-up's pieces: a pair scene's :class:`PairHeatUp` (injected loads refused,
    :func:`~thermobear.models.refuse_pair`), else :class:`HeldLoads` (the scene's own)."""
    if scene.arrangement is None:
        return HeldLoads()
    if load is not None:
        refuse_pair(scene)
    return PairHeatUp()


class HeldLoads:
    """A scene that carries its own loads through a heat-up (not one of a pair): the hooks of
    :func:`thermobear.coupled.transient.transient`'s pieces leave it as it was."""

    def piece(self, scene, t_s: float, T_C: dict, roles: dict):
        """The scene a piece of ``scene`` starting at ``t_s`` [s] at the node temperatures ``T_C`` [°C] runs."""
        return scene

    def ended(self, t_s: float, T_C: dict, roles: dict) -> None:
        """A piece ended at ``t_s`` [s] at the node temperatures ``T_C`` [°C]."""

    def length_s(self) -> float:
        """The longest the piece that starts [s] may run (inf: as long as its segment)."""
        return np.inf

    def until(self, net, roles: dict, other):
        """The ``until(t, T_K)`` of a piece (:func:`~thermobear.thermal.solve_transient`), ``other`` the heat-up's."""
        return other

    def scenes(self, pieces) -> list:
        """The scenes the pieces ``[(t_start, t_end, scene, last), ...]`` ran (their validity warnings)."""
        return [p[2] for p in pieces]

    def runaway(self, exc, t_s: float):
        """The pair's :class:`~thermobear.errors.ThermalPreloadRunaway` of a piece's error ``exc`` at ``t_s`` [s], or
        None (not the preload's)."""
        return None

    def warnings(self, T_end_C, roles, t_s: float) -> list:
        """The named warnings of the heat-up's preload, ending at the node temperatures ``T_end_C`` [°C] at ``t_s``."""
        return []

    def finish(self, run):
        """The heat-up's :class:`~thermobear.coupled.transient.TransientRun` with its preload (None: no pair)."""
        return run


class PairHeatUp(HeldLoads):
    """The loads of a pair scene's loaded bearing through a heat-up (module docstring): per piece the pair's loads at
    the temperatures of its start, a piece ending where they drift by more than the bound; the history kept."""

    def __init__(self):
        self.rel = float(PRELOAD_DRIFT_REL)
        self.rows: list = []        # per piece's start (and the end): the preload, the loads, the temperatures
        self.held: dict = {}        # pair scene (id) → [offset [m] or None, cold PairLoads, a spring's scene, last PairLoads]
        self.current = None         # (pair scene, PairLoads) of the piece running
        self.at = None              # (pair scene, t_s, PairLoads, temperatures) at the last piece's end
        self.ran: list = []         # the pieces' single-bearing scenes
        self.steps: list = []       # as ``rows``, at the temperatures of each integrator step (the loads not used)
        self.length = np.inf        # of the piece running [s]

    def loads_at(self, sc, T) -> PairLoads:
        """The pair's loads of pair scene ``sc`` at the ring and ball temperatures ``T`` [°C] (None: the mounting one):
        :func:`~thermobear.coupled.preload.scene_pair_loads`, as the steady loop, at the scene's speed."""
        kind = sc.preload_kind or "position"
        if id(sc) not in self.held:
            self.held[id(sc)] = [pair_preload_offset(sc.bearing, sc.preload_force) if kind == "position" else None,
                                 None, None, None]
        held = self.held[id(sc)]
        try:                        # from the scene's last answer (a nearby one: fewer Newton steps)
            g = scene_pair_loads(sc, T, held[0], start=held[3])
        except SolverError:
            if held[3] is None:
                raise
            g = scene_pair_loads(sc, T, held[0])      # (from the low-speed pair's, as a first solve)
        held[3] = g
        return g

    def piece(self, scene, t_s, T_C, roles):
        T = pair_temperatures(T_C, roles)
        spring = (scene.preload_kind or "position") == "spring"
        if self.at is not None and self.at[0] is scene and self.at[1] == t_s:
            loads = self.at[2]                                  # the last piece's end: this one's start
        else:                                                   # the first piece, a schedule's step, a spring
            loads = self.loads_at(scene, None if spring else T)
        held = self.held[id(scene)]
        if held[1] is None:
            held[1] = self.loads_at(scene, None)                # its cold loads (the runaway's reference)
        if spring and held[2] is not None:                      # a constant force: one scene for the run
            return held[2]
        self.length = self._length(scene, loads, t_s)
        self.current = (scene, loads)
        self.rows.append(_row(t_s, loads, T))
        out = pair_scene(scene, loads)
        self.ran.append(out)
        if spring:
            held[2] = out
        return out

    def _length(self, sc, loads: PairLoads, t_s: float) -> float:
        """The length [s] of the piece of pair scene ``sc`` starting at ``t_s`` [s] under ``loads``: the time its loads
        take to drift by the bound at their rate over the last integrator step (at most four times the last piece's
        length; inf for the first): the ``until`` of a piece sees its drift only at the integrator's steps, which
        grow long as the heat-up slows."""
        last = [r for r in self.steps[-2:] if r["t_s"] <= t_s]
        if self.current is None or self.current[0] is not sc or len(last) < 2 or last[1]["t_s"] <= last[0]["t_s"] \
                or t_s <= self.rows[-1]["t_s"]:
            return np.inf
        a, b = last
        rate = max(abs(b[k] - a[k]) for k in ("preload_N", "Fa_N", "Fr_N")) / (b["t_s"] - a["t_s"])
        bound = self.rel * max(loads.Fa, sc.preload_force)
        return min(bound / max(rate, 1e-300), 4.0 * (t_s - self.rows[-1]["t_s"]))

    def length_s(self) -> float:
        return self.length

    def ended(self, t_s, T_C, roles):
        if self.current is None or (self.current[0].preload_kind or "position") == "spring":
            return
        sc = self.current[0]
        T = pair_temperatures(T_C, roles)
        try:
            g = self.loads_at(sc, T)
            check_static_safety(pair_scene(sc, g))
        except (InputError, SolverError) as exc:
            raise self._runaway(sc, T, t_s, _failure(exc)) from exc
        self.at = (sc, t_s, g, T)

    def until(self, net, roles, other):
        if self.current is None or (self.current[0].preload_kind or "position") == "spring":
            return other
        sc, base = self.current
        bound, index, t0 = self.rel * max(base.Fa, sc.preload_force), dict(net.index), self.rows[-1]["t_s"]

        def until(t, T_K) -> bool:
            T = pair_temperatures({n: float(T_K[0, j]) - _C0 for n, j in index.items()}, roles)
            try:
                g = self.loads_at(sc, T)
            except (InputError, SolverError):   # beyond the pair's model: the piece's end names it (ended)
                return True
            self.steps.append(_row(t0 + float(t), g, T))
            if other is not None and other(t, T_K):
                return True
            return max(abs(g.preload - base.preload), abs(g.Fa - base.Fa), abs(g.Fr - base.Fr)) > bound
        return until

    def scenes(self, pieces) -> list:
        """The first and last pieces' scenes and those of the lightest and heaviest loads (the validity warnings that
        depend on the loads: a bearing at speed without load)."""
        r = self.ran
        picked = [r[0], r[-1], min(r, key=lambda s: (s.Fa, s.Fr)), max(r, key=lambda s: (s.Fa, s.Fr))] if r else []
        return list({id(s): s for s in picked}.values())

    def runaway(self, exc, t_s):
        if isinstance(exc, ThermalPreloadRunaway):
            return exc
        sc, loads = self.current if self.current is not None else (None, None)
        if not isinstance(exc, ThermalRunaway) or sc is None or (sc.preload_kind or "position") == "spring" \
                or not loads.Fa > self.held[id(sc)][1].Fa:
            return None
        T = self.rows[-1]
        return self._runaway(sc, {k: T[f"T_{k.replace(' ', '_')}_C"] for k in _PARTS}, t_s,
                             f"the heat-up passes the lubricant's limit at a preload above the cold one ({exc})")

    def _runaway(self, sc, T: dict, t_s: float, what: str) -> ThermalPreloadRunaway:
        """The named error of the pair's preload running away at ``t_s`` [s] (``T`` the ring and ball temperatures)."""
        dT = T["inner ring"] - T["outer ring"]
        pre = [r["preload_N"] for r in self.rows]
        return ThermalPreloadRunaway(
            f"thermal preload runaway of a {sc.arrangement.replace('_', '-')} pair during the heat-up at t = {t_s:g} s: "
            f"{what} — cold preload {sc.preload_force:.4g} N, {pre[-1]:.4g} N at the last piece's start (peak "
            f"{max(pre):.4g} N) with the inner ring at {T['inner ring']:.1f} °C, outer ring {T['outer ring']:.1f} °C "
            f"(ΔT {dT:.1f} K), balls {T['balls']:.1f} °C: a lighter preload, a spring preload, more cooling or a "
            "slower run-in is needed (what was integrated: the error's last)",
            iterations=len(self.rows), residual=float(pre[-1] - pre[-2]) if len(pre) > 1 else 0.0,
            history=list(self.rows), preload_history_N=pre,
            dT_inner_outer_K=float(dT))

    def warnings(self, T_end_C, roles, t_s):
        if T_end_C and self.current is not None and (not self.rows or self.rows[-1]["t_s"] < t_s):
            sc, T = self.current[0], pair_temperatures(T_end_C, roles)
            spring = (sc.preload_kind or "position") == "spring"
            try:
                g = (self.at[2] if self.at is not None and self.at[1] == t_s and self.at[0] is sc else
                     self.current[1] if spring else self.loads_at(sc, T))
            except (InputError, SolverError):   # (an interrupted run's end beyond the pair's model: no end row)
                g = None
            if g is not None:
                self.rows.append(_row(t_s, g, T))
        if not self.rows:
            return []
        sc = self.current[0]
        T_of = lambda r: {k: r[f"T_{k.replace(' ', '_')}_C"] for k in _PARTS}  # noqa: E731
        end = self.rows[-1]
        fast = self.held[id(sc)][1].preload if pair_speed_rpm(sc) else None      # (the cold loads at speed)
        got = thermal_preload_warnings(sc, end["preload_N"], T_of(end), fast)
        seen = self._samples()
        lo, hi = LIMITS["thermal_preload"].warn
        for r, past in ((max(seen, key=lambda r: r["preload_N"]), lambda v: v > hi),      # the peak: too high only,
                        (min(seen, key=lambda r: r["preload_N"]), lambda v: v < lo)):     # the lowest: too low only
            if r is end or r["preload_N"] == end["preload_N"]:
                continue
            got += [OutsideValidity(f"during the heat-up, at t = {r['t_s']:.4g} s: {w.message}", quantity=w.quantity,
                                    value=w.value, limit=w.limit, source=w.source, field=w.field)
                    for w in thermal_preload_warnings(sc, r["preload_N"], T_of(r), fast) if past(w.value)]
        return got

    def _samples(self) -> list:
        """The history's entries and those at the integrator's steps up to its end, by time (the preload at the
        temperatures: its peak and lowest value)."""
        end = self.rows[-1]["t_s"]
        return sorted({r["t_s"]: r for r in self.steps + self.rows if r["t_s"] <= end}.values(), key=lambda r: r["t_s"])

    def finish(self, run):
        """``run`` with its ``preload`` (module docstring)."""
        if not self.rows:
            return run
        sc, rows, end, seen = self.current[0], self.rows, self.rows[-1], self._samples()
        t = np.array([r["t_s"] for r in seen])
        series = {k: np.interp(run.t_s, t, [r[k] for r in seen]) for k in ("preload_N", "Fa_N", "Fr_N")}
        peak, low = max(seen, key=lambda r: r["preload_N"]), min(seen, key=lambda r: r["preload_N"])
        kind = sc.preload_kind or "position"
        offset = self.held[id(sc)][0]
        run.preload = dict(
            arrangement=sc.arrangement, kind=kind, cold_N=sc.preload_force,
            offset_um=None if offset is None else offset * 1e6, drift_bound_rel=self.rel,
            start_N=rows[0]["preload_N"], peak_N=peak["preload_N"], peak_t_s=peak["t_s"], end_N=end["preload_N"],
            end_t_s=end["t_s"], min_N=low["preload_N"], min_t_s=low["t_s"], Fa_N=end["Fa_N"], Fr_N=end["Fr_N"],
            Fa_other_N=end["Fa_other_N"], pieces=len(rows) - 1, history=list(rows),
            series=dict(t_s=np.asarray(run.t_s), **series))
        return run


def _row(t_s: float, g: PairLoads, T: dict) -> dict:
    """One entry of a pair heat-up's history: at ``t_s`` [s] the pair's loads ``g`` at the temperatures ``T`` [°C]."""
    return dict(t_s=float(t_s), preload_N=g.preload, Fa_N=g.Fa, Fr_N=g.Fr, Fa_other_N=g.Fa_other,
                T_inner_ring_C=T["inner ring"], T_outer_ring_C=T["outer ring"], T_balls_C=T["balls"],
                dT_inner_outer_K=T["inner ring"] - T["outer ring"])


def _failure(exc) -> str:
    """What stopped the pair's loads at a piece's end (``exc``), for the runaway's message."""
    field = getattr(exc, "field", "")
    what = ("the rings and balls at these temperatures close the bearing's radial play (its free contact angle would "
            "pass 0)" if field.startswith("dT_") else
            "the warm pair's contacts are overloaded" if field.startswith("Fa, Fr, M") else
            "the loaded bearing's static safety falls below the refused limit" if field.startswith("operation") else
            f"the warm pair has no equilibrium ({type(exc).__name__})")
    return f"{what} [{' '.join(str(exc).split())[:200]}]"


def preload_line(p: dict | None) -> str | None:
    """The text line of a heat-up's preload (``TransientRun.preload``; None without), e.g. ``preload 300 N cold
    (606 N at the start) → peak 3900 N at 350 s → 2760 N at the end (3600 s); loaded bearing Fa …; 116 pieces of ≤ 2 %
    drift``."""
    if not p:
        return None
    if p["kind"] == "spring":
        return f"preload {p['cold_N']:.4g} N (spring: a constant force); loaded bearing Fa {p['Fa_N']:.4g} N, Fr " \
               f"{p['Fr_N']:.4g} N"
    start = f" ({p['start_N']:.4g} N at the start)" if abs(p["start_N"] - p["cold_N"]) > 5e-4 * p["cold_N"] else ""
    peak = (f" → peak {p['peak_N']:.4g} N at {p['peak_t_s']:.4g} s" if p["peak_N"] > (1 + 1e-3) * p["end_N"] else "")
    low = (f" (lowest {p['min_N']:.4g} N at {p['min_t_s']:.4g} s)" if p["min_N"] < min(p["start_N"], p["end_N"]) else "")
    return (f"preload {p['cold_N']:.4g} N cold{start}{peak} → {p['end_N']:.4g} N at the end ({p['end_t_s']:.4g} s){low}; "
            f"loaded bearing Fa {p['Fa_N']:.4g} N, Fr {p['Fr_N']:.4g} N; {p['pieces']} pieces of ≤ "
            f"{100 * p['drift_bound_rel']:g} % drift")
