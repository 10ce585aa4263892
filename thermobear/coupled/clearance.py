r"""Temperature → clearance → loads → losses → temperatures: the clearance of the coupled steady state.

The free contact angle of a deep groove bearing follows its diametral clearance (cos α0 = 1 − P_d/(2A),
Harris & Kotzalas 2007 [1] §2.2), so the load distribution, the contacts and the losses depend on the clearance
the bearing runs with; that clearance depends on the fits and on the temperatures of rings, balls, shaft and
housing (:func:`thermobear.contact.fits.operating_clearance`: Lamé fits, free thermal and centrifugal growth).
With ``models.clearance = "operating"`` (:func:`thermobear.models.clearance_choice`) the steady state is the
fixed point

.. math:: P_{d} = g(P_d) = P_{d,op}\bigl(T(P_d)\bigr)

solved by direct iteration (each step a full coupled steady state with the bearing at P_d, started from the
bearing's own clearance); the slope of g — how much a change of the clearance moves the ring temperature
difference — is small for a radially loaded bearing, so 2–5 steps reach ``tol_m``.  When g(P_d) ≤ 0 the next
step solves at P_d = 0 (the least clearance the rigid-ring model represents); if that state too consumes its
clearance, no fixed point with a clearance exists: :class:`~thermobear.errors.ThermalPreloadRunaway`, with the
clearance history and the inner–outer ring temperature difference.  ``"mounted"``: one step, the fits at 20 °C.

Batching: a point's bearing changes with its clearance, and a load solve batches points of one bearing, so the
steps after the first solve each point of the loop as a family of its own (the points of one step in one call);
cost ≈ (iterations + 1) single-point steady states per point, each with its own network preparation.

References
----------
.. [1] Harris, T. A., Kotzalas, M. N. (2007), *Essential Concepts of Bearing Technology*, 5th ed., CRC Press
   (§2.2 clearance and free contact angle; ch. 3 interference fits and thermal expansion).
"""
from __future__ import annotations

import dataclasses

from thermobear.coupled.ratings import scene_clearance
from thermobear.errors import InputError, NoConvergence, ThermalPreloadRunaway

__all__ = ["clearance_loop", "preload_runaway", "scene_at_clearance", "CLEARANCE_TOL_M"]

CLEARANCE_TOL_M = 1e-8          #: fixed-point tolerance on the clearance [m]
_MAXITER = 25


def _choice(r) -> str:
    return r.models_used.get("clearance", ("given",))[0]


def scene_at_clearance(scene, Pd):
    """The scene with its bearing at clearance ``Pd`` [m] (the network and everything else unchanged)."""
    return dataclasses.replace(scene, bearing=scene.bearing.with_(Pd=float(Pd)))


def preload_runaway(scene, c: dict, history: list, what: str) -> ThermalPreloadRunaway:
    """The named error of a consumed clearance: ``c`` the clearance dict at the state that consumed it
    (:func:`~thermobear.coupled.ratings.scene_clearance`), ``history`` the loop's or heat-up's steps."""
    T = c["temperatures_C"]
    dT = T["inner ring"] - T["outer ring"]
    return ThermalPreloadRunaway(
        f"thermal preload: the operating clearance is consumed {what} — {c['unmounted']:.3g} µm unmounted, "
        f"{c['mounted']:.3g} µm mounted ({c['shaft_fit']} / {c['housing_fit']}), {c['operating']:.3g} µm with the "
        f"inner ring at {T['inner ring']:.1f} °C, outer ring {T['outer ring']:.1f} °C (ΔT {dT:.1f} K), balls "
        f"{T['balls']:.1f} °C; the rigid-ring load distribution cannot carry a radial preload: a larger clearance "
        "group, a looser fit or a cooler shaft is needed", iterations=len(history),
        residual=float(c["operating"]) * 1e-6, last=c, history=history,
        clearance_history_m=[h["operating_um"] * 1e-6 for h in history], dT_inner_outer_K=float(dT),
        mounted_m=float(c["mounted"]) * 1e-6)


def _step(scene, r, used, hist, tol_m):
    """One step of a point: (done state or error, or None and the next clearance [m])."""
    c = scene_clearance(scene, r.T_C, r.roles)
    if _choice(r) == "mounted":
        target = c["mounted"] * 1e-6
        if target <= 0:
            return InputError("bearing.shaft_fit", c["shaft_fit"], f"the fits consume the clearance at mounting "
                              f"({c['unmounted']:.3g} → {c['mounted']:.3g} µm): a looser fit or a larger clearance "
                              "group (the rigid-ring model carries no radial preload)"), None
        if abs(target - used) <= tol_m:
            return _answer(r, c, used, hist, "mounted", "the fits at 20 °C"), None
        return None, target
    g = c["operating"] * 1e-6
    T = c["temperatures_C"]
    hist.append(dict(iteration=len(hist) + 1, used_um=used * 1e6, operating_um=c["operating"],
                     T_inner_ring_C=T["inner ring"], T_outer_ring_C=T["outer ring"], T_balls_C=T["balls"],
                     dT_inner_outer_K=T["inner ring"] - T["outer ring"], P_W=r.P_W))
    if abs(g - used) <= tol_m and g > 0:
        return _answer(r, c, used, hist, "operating", "fixed point"), None
    if g <= 0:
        if used <= 0:
            return preload_runaway(scene, c, hist, "even with the clearance closed to 0 in the loads"), None
        return None, 0.0
    if len(hist) >= _MAXITER:
        return NoConvergence(f"operating clearance: no fixed point within {_MAXITER} steps (last "
                             f"{used * 1e6:.4g} → {c['operating']:.4g} µm)", iterations=len(hist),
                             residual=abs(g - used), history=hist), None
    return None, g


def _answer(r, c, used, hist, choice, how):
    dT = c["temperatures_C"]["inner ring"] - c["temperatures_C"]["outer ring"]
    res = abs(c["operating"] * 1e-6 - used) if choice == "operating" else 0.0
    clear = {**c, "used": used * 1e6, "iterations": max(len(hist), 1), "residual_um": res * 1e6,
             "history": list(hist)}
    reason = (f"{how}: {c['unmounted']:.3g} µm unmounted → {c['mounted']:.3g} µm mounted ({c['shaft_fit']} / "
              f"{c['housing_fit']}) → {used * 1e6:.3g} µm in the loads" +
              (f", inner ring {dT:.1f} K above the outer ({len(hist)} steps, residual {res * 1e6:.1e} µm)"
               if choice == "operating" else ""))
    return dataclasses.replace(r, clearance_um=clear, models_used={**r.models_used, "clearance": (choice, reason)})


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
           ``history``), or the error that stopped it (:class:`~thermobear.errors.ThermalPreloadRunaway`)
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
        for i, r in zip(idx, solve([scene_at_clearance(scenes[i], nxt[i]) for i in idx])):
            used[i], out[i] = nxt[i], r
        live = {i: None for i in idx if not isinstance(out[i], Exception)}
    return out
