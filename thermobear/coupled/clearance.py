r"""Temperature → clearance → loads → losses → temperatures: the clearance of the coupled steady state.

The free contact angle of a deep groove bearing follows its diametral clearance (cos α0 = 1 − P_d/(2A),
Harris & Kotzalas 2007 [1] ch. 2), so the load distribution, the contacts and the losses depend on the clearance
the bearing runs with; that clearance depends on the fits and on the temperatures of rings, balls, shaft and
housing (:func:`thermobear.contact.fits.operating_clearance`: Lamé fits, free thermal and centrifugal growth,
[1] ch. 3).  A negative clearance is a radial preload: the load distribution places the groove centres
A − P_d/2 apart with the rings centred ([1] ch. 2 and 7; :attr:`~thermobear.contact.geometry.BallBearing.A_r0`),
every ball carrying Q_0 = K_n (−P_d/2)^1.5 without load (:func:`~thermobear.contact.fits.clearance_preload`).
With ``models.clearance = "operating"`` (:func:`thermobear.models.clearance_choice`) the steady state is the
fixed point

.. math:: P_{d} = g(P_d) = P_{d,op}\bigl(T(P_d)\bigr)

solved by direct iteration (each step a full coupled steady state with the bearing at P_d, started from the
bearing's own clearance), into negative clearances as into positive ones.  The slope of g — how much a change of
the clearance moves the ring temperature difference — is small for a radially loaded bearing, so 2–5 steps reach
``tol_m``.  A preloaded answer carries a named warning (:func:`~thermobear.coupled.ratings.preload_warnings`:
the compression and Q_0).

Runaway (:class:`~thermobear.errors.ThermalPreloadRunaway`, with the clearance history and the last residual).
More preload makes more heat, a hotter inner ring and more preload: the iteration diverges when that gain
reaches 1, g′ ≥ 1.  Its sign, from two steps k − 1, k: with the clearance negative and falling
(r_k = g(P_k) − P_k < 0), the step does not shrink, |r_k| ≥ |r_{k−1}| — equivalently the secant slope
(g_k − g_{k−1})/(P_k − P_{k−1}) ≥ 1, so that g(P) − P only falls further as the preload grows: no fixed point
ahead.  Also a runaway: a step at a negative clearance whose coupled steady state has no solution (its thermal
fixed point runs away, :class:`~thermobear.errors.ThermalRunaway`, or its contacts are overloaded), and
``_MAXITER`` steps still moving to more preload.  ``"mounted"``: the fits at 20 °C, one step.

Batching: a point's bearing changes with its clearance, and a load solve batches points of one bearing, so the
steps after the first solve each point of the loop as a family of its own (the points of one step in one call);
cost ≈ (iterations + 1) single-point steady states per point, each with its own network preparation.

References
----------
.. [1] Harris, T. A., Kotzalas, M. N. (2007), *Essential Concepts of Bearing Technology*, 5th ed., CRC Press
   (ch. 2 clearance and free contact angle; ch. 3 interference fits and thermal expansion; ch. 7 load
   distribution under radial load with a clearance or preload).
"""
from __future__ import annotations

import dataclasses

from thermobear.coupled.ratings import preload_warnings, scene_clearance
from thermobear.errors import ContactLimit, InputError, NoConvergence, ThermalPreloadRunaway, ThermalRunaway

__all__ = ["clearance_loop", "preload_runaway", "scene_at_clearance", "heat_up_preload_warnings", "CLEARANCE_TOL_M"]

CLEARANCE_TOL_M = 1e-8          #: fixed-point tolerance on the clearance [m]
_MAXITER = 25


def _choice(r) -> str:
    return r.models_used.get("clearance", ("given",))[0]


def scene_at_clearance(scene, Pd):
    """The scene with its bearing at clearance ``Pd`` [m] (the network and everything else unchanged)."""
    return dataclasses.replace(scene, bearing=scene.bearing.with_(Pd=float(Pd)))


def preload_runaway(scene, c: dict, history: list, what: str) -> ThermalPreloadRunaway:
    """The named error of a radial preload that runs away: ``c`` the clearance dict at the last state
    (:func:`~thermobear.coupled.ratings.scene_clearance`), ``history`` the loop's or heat-up's steps (its last
    residual, operating − used clearance, is the error's ``residual`` [m]), ``what`` how it ran away.

    >>> T = {"inner ring": 220.4, "outer ring": 20.0, "balls": 198.1}
    >>> c = dict(unmounted=13.0, mounted=1.69, operating=-171.0, shaft_fit="k5", housing_fit="H7", temperatures_C=T)
    >>> e = preload_runaway(None, c, [dict(used_um=-146.4, operating_um=-171.0)], "no fixed point")
    >>> round(e.residual * 1e6, 1), e.clearance_history_m, round(e.dT_inner_outer_K, 1)
    (24.6, [-0.000171], 200.4)
    """
    T = c["temperatures_C"]
    dT = T["inner ring"] - T["outer ring"]
    last = history[-1] if history else {}
    res = abs(last.get("operating_um", c["operating"]) - last.get("used_um", 0.0)) * 1e-6
    return ThermalPreloadRunaway(
        f"thermal preload runaway: {what} — {c['unmounted']:.3g} µm unmounted, {c['mounted']:.3g} µm mounted "
        f"({c['shaft_fit']} / {c['housing_fit']}), {c['operating']:.3g} µm with the inner ring at "
        f"{T['inner ring']:.1f} °C, outer ring {T['outer ring']:.1f} °C (ΔT {dT:.1f} K), balls {T['balls']:.1f} °C: "
        "a larger clearance group, a looser fit or a cooler shaft is needed", iterations=len(history),
        residual=res, last=c, history=history,
        clearance_history_m=[h["operating_um"] * 1e-6 for h in history], dT_inner_outer_K=float(dT),
        mounted_m=float(c["mounted"]) * 1e-6)


def _running_away(hist: list, tol_m: float) -> bool:
    """The loop's steps move to more preload without shrinking (module docstring): at a negative clearance,
    r_k = g_k − P_k < 0 and |r_k| ≥ |r_{k−1}| (the secant slope of g ≥ 1), beyond the tolerance."""
    if len(hist) < 2:
        return False
    (a, b) = ((h["operating_um"] * 1e-6, h["used_um"] * 1e-6) for h in hist[-2:])
    r0, r1 = a[0] - a[1], b[0] - b[1]
    return b[1] < 0 and r1 < -tol_m and r0 < 0 and abs(r1) >= abs(r0)


def heat_up_preload_warnings(scene, c, T_end_C, roles, hist: list, t_end_s: float) -> list:
    """The named radial-preload warning of a heat-up (:func:`~thermobear.coupled.ratings.preload_warnings`): ``c`` the
    operating clearance of its last piece where its loads followed it (``models.clearance = "operating"``), else
    None — then the operating clearance at its end state ``T_end_C`` (node → °C; ``roles`` of the network; None: not
    checked), as the ratings check a steady state (thrust bearings and bearings without bore / OD: none).  ``hist``,
    the heat-up's clearance history, gets the end's entry."""
    b = scene.bearing
    if c is None and T_end_C is not None and b.kind != "thrust" and None not in (b.bore, b.outer_diameter):
        c = scene_clearance(scene, T_end_C, roles)
        hist.append(dict(t_s=t_end_s, operating_um=c["operating"]))
    if c is None or not c["operating"] < 0:
        return []
    t = hist[-1]["t_s"]
    return preload_warnings(b, c["operating"] * 1e-6, c, f"during the heat-up, at t = {t:g} s"
                            + ("" if t == t_end_s else " (its last piece's start)"))


def _step(scene, r, used, hist, tol_m):
    """One step of a point: (done state or error, or None and the next clearance [m])."""
    c = scene_clearance(scene, r.T_C, r.roles)
    if _choice(r) == "mounted":
        target = c["mounted"] * 1e-6
        if abs(target - used) <= tol_m:
            return _answer(scene, r, c, used, hist, "mounted", "the fits at 20 °C"), None
        return None, target
    g = c["operating"] * 1e-6
    T = c["temperatures_C"]
    hist.append(dict(iteration=len(hist) + 1, used_um=used * 1e6, operating_um=c["operating"],
                     T_inner_ring_C=T["inner ring"], T_outer_ring_C=T["outer ring"], T_balls_C=T["balls"],
                     dT_inner_outer_K=T["inner ring"] - T["outer ring"], P_W=r.P_W))
    if abs(g - used) <= tol_m:
        return _answer(scene, r, c, used, hist, "operating", "fixed point"), None
    if _running_away(hist, tol_m):
        return preload_runaway(scene, c, hist, "each step of the clearance loop adds at least as much preload as "
                               "the last (the heat of the preload consumes more clearance than it took: no fixed "
                               "point)"), None
    if len(hist) >= _MAXITER:
        if g < used < 0:
            return preload_runaway(scene, c, hist, f"the clearance loop still moves to more preload after "
                                   f"{_MAXITER} steps"), None
        return NoConvergence(f"operating clearance: no fixed point within {_MAXITER} steps (last "
                             f"{used * 1e6:.4g} → {c['operating']:.4g} µm)", iterations=len(hist),
                             residual=abs(g - used), history=hist), None
    return None, g


def _answer(scene, r, c, used, hist, choice, how):
    dT = c["temperatures_C"]["inner ring"] - c["temperatures_C"]["outer ring"]
    res = abs(c["operating"] * 1e-6 - used) if choice == "operating" else 0.0
    clear = {**c, "used": used * 1e6, "iterations": max(len(hist), 1), "residual_um": res * 1e6,
             "history": list(hist), "choice": choice}
    reason = (f"{how}: {c['unmounted']:.3g} µm unmounted → {c['mounted']:.3g} µm mounted ({c['shaft_fit']} / "
              f"{c['housing_fit']}) → {used * 1e6:.3g} µm in the loads" +
              (f", inner ring {dT:.1f} K above the outer ({len(hist)} steps, residual {res * 1e6:.1e} µm)"
               if choice == "operating" else ""))
    warned = r.warnings
    if used < 0:
        why = ("the fits consume the clearance at mounting" if choice == "mounted" else
               "the fits and the ring temperatures consume the clearance")
        warned = warned + preload_warnings(scene.bearing, used, c, f"{why}, in the loads")
    return dataclasses.replace(r, clearance_um=clear, models_used={**r.models_used, "clearance": (choice, reason)},
                               warnings=warned)


def _stopped(scene, r, Pd, hist, c):
    """A step's error at a negative clearance ``Pd`` [m] — the steady state at that preload runs away or its
    contacts are overloaded — as the preload's runaway (the error as its cause); other errors as they are."""
    overload = isinstance(r, ContactLimit) or isinstance(r, InputError) and r.field == "Fa, Fr, M"
    if Pd >= 0 or c is None or not (isinstance(r, ThermalRunaway) or overload):
        return r
    e = preload_runaway(scene, c, hist, f"the coupled steady state at {Pd * 1e6:.3g} µm has no solution "
                        f"({type(r).__name__}: {' '.join(str(r).split())[:200]})")
    e.__cause__ = r
    return e


def clearance_loop(scenes, first: list, solve, *, tol_m: float = CLEARANCE_TOL_M) -> list:
    """The steady states of ``scenes`` at their clearance (module docstring).

    Parameters
    ----------
    scenes : list of Scene   the operating points
    first : list             their steady states (or errors) at the bearing's own clearance
    solve : callable         ``solve(scenes) -> list`` of steady states or errors, without this loop
    tol_m : float            fixed-point tolerance on the clearance [m]

    Returns
    -------
    list   per point: the state of the points whose clearance is ``given`` unchanged; of the others the
           state at the fixed point (``clearance_um`` with ``used``, ``iterations``, ``residual_um`` and the
           ``history``; a negative one, a radial preload, with its warning), or the error that stopped it
           (:class:`~thermobear.errors.ThermalPreloadRunaway` where the preload runs away)

    Examples
    --------
    The oil-jet 6208 (CN, 13 µm) on k5 / H7, through :func:`thermobear.steady_state` (which runs this loop): the
    fits and the warm inner ring consume the clearance, the answer is preloaded.

    >>> import dataclasses, warnings
    >>> import thermobear as tb
    >>> s = tb.load_scene(tb.example_path("block_6208_oil_jet.toml"))
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore")
    ...     st = tb.steady_state(dataclasses.replace(s, shaft_fit="k5", housing_fit="H7"))
    >>> round(st.clearance_um["used"], 2), st.clearance_um["iterations"], round(st.P_W, 1)
    (-5.55, 3, 33.0)
    """
    out = list(first)
    used = {i: sc.bearing.Pd for i, (sc, r) in enumerate(zip(scenes, first))
            if not isinstance(r, Exception) and _choice(r) != "given"}
    hist = {i: [] for i in used}
    live = dict.fromkeys(used)
    while live:
        nxt = {}
        for i in live:
            done, pd = _step(scenes[i], out[i], used[i], hist[i], tol_m)
            if done is not None:
                out[i] = done
            else:
                nxt[i] = pd
        if not nxt:
            break
        idx = list(nxt)
        last = {i: scene_clearance(scenes[i], out[i].T_C, out[i].roles) for i in idx}
        for i, r in zip(idx, solve([scene_at_clearance(scenes[i], nxt[i]) for i in idx])):
            used[i], out[i] = nxt[i], _stopped(scenes[i], r, nxt[i], hist[i], last[i])
        live = {i: None for i in idx if not isinstance(out[i], Exception)}
    return out
