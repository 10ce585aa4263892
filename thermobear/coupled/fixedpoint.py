r"""Thermo-mechanical coupling: the fixed point T = G(T) and thermal runaway.

The losses depend on the temperatures of balls, rings and oil (viscosity), and
the thermal network turns the losses into temperatures.  The steady operating
point is the fixed point of the update map G: coupled temperatures → losses →
network → new temperatures (the coupling of Pouly et al. 2010, Tribology Transactions 53:957,
and of seed 004 §4.5).

* :func:`solve_coupled` solves T = G(T) on a small vector with Anderson
  mixing (Walker & Ni 2011, type II; a multi-secant method), step clipping and
  restarts, with damped Picard as the fallback.  It stops when the temperature
  change is below ``tol_K`` AND the losses evaluated at the returned
  temperatures equal, within ``tol_energy_rel``, the losses the network
  dissipated to produce them.
* A converged point is checked for stability: the loop gain (largest real part
  of the eigenvalues of dG/dT, by finite differences) must be < 1, i.e. heat
  generation must grow more slowly with temperature than dissipation.  An
  accelerated solver could otherwise land on an unstable equilibrium.
* Thermal runaway (no stable equilibrium: dP/dT exceeds the dissipation
  conductance) is confirmed on the physical heating path — plain Picard from
  the start temperatures, which for a monotone system is the sequence of
  quasi-steady states a bearing heating from ambient goes through.  It is
  declared when that path, heating monotonically, passes ``T_limit_K`` or
  heats by non-decreasing increments over four steps with a loop gain ≥ 1
  at its iterate, unless the update maps the limit below itself: then a
  hotter equilibrium lies between (losses that rise in a step with
  temperature, e.g. a starved cold state whose replenishment recovers, whose
  cool equilibrium ends at a fold), which the path goes on to reach; it is
  found by the same map iterated down from the limit (a monotone map between
  a sub- and a super-solution has a fixed point between them: Amann 1976,
  SIAM Review 18:620) — and raised
  as :class:`~thermobear.errors.ThermalRunaway` with the reason, the last
  iterate and the history.  Divergence or oscillation that is not runaway
  raises :class:`~thermobear.errors.NoConvergence`.

"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from thermobear.errors import InputError, NoConvergence, ThermalRunaway
from thermobear.units import ZERO_C_K

__all__ = ["CoupledResult", "solve_coupled", "loop_gain"]


@dataclass
class CoupledResult:
    """Converged coupled temperatures.

    Attributes
    ----------
    T_K : ndarray             coupled temperatures [K]
    P_W : float or None       total loss at T_K (when the update reports it) [W]
    iterations : int          fixed-point iterations
    evaluations : int         calls of the update (incl. verification and stability check)
    residual_K : float        max |G(T) − T| at the returned point [K]
    energy_residual_rel : float  |P(T) − P_used| / P: losses at the returned T versus the
                              losses the network dissipated to produce T (NaN without P)
    loop_gain : float         largest real eigenvalue of dG/dT at T (NaN if not checked);
                              < 1 for a stable equilibrium
    history : list of dict    per iteration: T_K, residual_K, mean_residual_K, P_W, step
    method : str              what converged ("anderson", "picard", "picard-damped")
    steady : object           network solution at T (solve_network_coupled only)
    sources_W, report : dict  losses mapped to nodes and the loss report (idem)
    """

    T_K: np.ndarray
    P_W: float | None
    iterations: int
    evaluations: int
    residual_K: float
    energy_residual_rel: float
    loop_gain: float
    history: list
    method: str
    steady: object = field(default=None, repr=False)
    sources_W: dict = field(default_factory=dict, repr=False)
    report: dict = field(default_factory=dict, repr=False)


class _Update:
    """Wraps the user's update: counts calls, normalises (T[, P]) and checks finiteness."""

    def __init__(self, update, n):
        self.update, self.n, self.count = update, n, 0

    def __call__(self, x):
        self.count += 1
        out = self.update(np.array(x, dtype=float))
        if isinstance(out, tuple):
            g, P = out
            P = float(P)
        else:
            g, P = out, None
        g = np.atleast_1d(np.asarray(g, dtype=float))
        if g.shape != (self.n,):
            raise InputError("update", g.shape, f"must return {self.n} temperatures (same shape as T0_K)")
        return g, P


def loop_gain(update, T_K, delta_K: float = 1e-2):
    """Largest real part of the eigenvalues of dG/dT at ``T_K`` (forward differences).

    A stable thermal equilibrium has loop gain < 1: a small temperature rise
    raises the losses by less than the network can dissipate.

    >>> round(loop_gain(lambda T: 300.0 + 0.5 * (T - 300.0), np.array([320.0])), 6)
    0.5
    """
    T = np.atleast_1d(np.asarray(T_K, dtype=float))
    f = _Update(update, T.size)
    g0, _ = f(T)
    J = np.empty((T.size, T.size))
    for k in range(T.size):                 # n ≤ ~10 coupled temperatures
        Tk = T.copy()
        Tk[k] += delta_K
        J[:, k] = (f(Tk)[0] - g0) / delta_K
    return float(np.max(np.linalg.eigvals(J).real))


def solve_coupled(update: Callable, T0_K, *, tol_K: float = 1e-6, tol_energy_rel: float = 1e-6,
                  max_iter: int = 100, method: str = "anderson", memory: int = 5,
                  damping: float = 1.0, max_step_K: float = 50.0, T_limit_K: float = 573.15,
                  check_stability: bool = True) -> CoupledResult:
    r"""Solve the coupled fixed point T = G(T) (losses ↔ temperatures).

    Parameters
    ----------
    update : callable       ``update(T_K) -> T_new_K`` or ``-> (T_new_K, P_W)``: the network
                            temperatures produced by the losses evaluated at ``T_K``; P_W the
                            total loss [W] (enables the energy criterion)
    T0_K : array_like       start (e.g. ambient) [K]; also the start of the physical heating path
    tol_K : float           tolerance on max |G(T) − T| [K]
    tol_energy_rel : float  tolerance on |P(T) − P_used| / P
    max_iter : int          iteration budget (per phase)
    method : str            ``"anderson"`` (default) or ``"picard"`` (with ``damping``)
    memory : int            Anderson depth m
    damping : float         Picard relaxation β in (0, 1]: T ← T + β (G(T) − T)
    max_step_K : float      largest accelerated step [K]
    T_limit_K : float       physical limit (default 300 °C): a heating path beyond it is runaway
    check_stability : bool  verify the loop gain at the solution (n extra evaluations)

    Returns
    -------
    CoupledResult

    Raises
    ------
    ThermalRunaway  heat generation grows faster with T than dissipation (reason, history)
    NoConvergence   oscillation, stagnation or budget exhausted without runaway

    Examples
    --------
    Losses falling with temperature (viscosity), one node, 2 W/K to 20 °C:

    >>> P = lambda T: 200.0 * np.exp(-(T - 293.15) / 40.0)
    >>> r = solve_coupled(lambda T: (293.15 + P(T) / 2.0, P(T).sum()), [293.15])
    >>> round(float(r.T_K[0] - 293.15 - P(r.T_K)[0] / 2.0), 6), r.iterations < 10, r.loop_gain < 0
    (0.0, True, True)
    """
    x0 = np.atleast_1d(np.asarray(T0_K, dtype=float)).copy()
    if np.any(~np.isfinite(x0) | (x0 <= 0)):
        raise InputError("T0_K", T0_K, "start temperatures must be finite and > 0 [K]")
    if method not in ("anderson", "picard"):
        raise InputError("method", method, "'anderson' or 'picard'")
    if not 0 < damping <= 1:
        raise InputError("damping", damping, "must lie in (0, 1]")
    ev = _Update(update, x0.size)
    opts = dict(tol_K=tol_K, tol_energy_rel=tol_energy_rel, max_iter=max_iter, T_limit_K=T_limit_K)
    if method == "picard":
        res = _picard(ev, x0, damping, **opts)
    else:
        res = _anderson(ev, x0, memory, max_step_K, **opts)
        if res is None:                                  # failed: decide on the physical path
            res = _physical_path(ev, x0, **opts)
    if check_stability:
        res.loop_gain = loop_gain(lambda T: ev(T)[0], res.T_K)
        if res.loop_gain >= 1.0:
            if res.method == "anderson":                 # may have landed on an unstable branch
                res = _physical_path(ev, x0, **opts)
                res.loop_gain = loop_gain(lambda T: ev(T)[0], res.T_K)
            if res.loop_gain >= 1.0:
                raise ThermalRunaway(
                    f"the equilibrium at T = {_fmt(res.T_K)} K is unstable (loop gain {res.loop_gain:.3g} ≥ 1: "
                    "the losses grow faster with temperature than the network dissipates)",
                    iterations=res.iterations, residual=res.residual_K, last=res.T_K, history=res.history)
    res.evaluations = ev.count
    return res


def _fmt(x):
    return np.array2string(np.asarray(x), precision=2, separator=", ")


def _record(history, x, g, P, step):
    f = g - x
    history.append(dict(iteration=len(history), T_K=x.copy(), residual_K=float(np.max(np.abs(f))),
                        mean_residual_K=float(np.mean(f)), P_W=P, step=step))
    return f


def _energy(P_used, P_now):
    if P_used is None or P_now is None:
        return float("nan")
    return abs(P_now - P_used) / max(abs(P_now), abs(P_used), 1e-300)


def _verify(ev, g, P, history, tol_K, tol_energy_rel):
    """Picard step to x_v = G(x): converged when G(x_v) ≈ x_v and P(x_v) ≈ P(x)."""
    xv = g.copy()
    gv, Pv = ev(xv)
    fv = _record(history, xv, gv, Pv, "verify")
    e = _energy(P, Pv)
    ok = np.all(np.isfinite(gv)) and np.max(np.abs(fv)) <= tol_K and (math.isnan(e) or e <= tol_energy_rel)
    return ok, xv, gv, Pv, fv, e


def _result(x, P, f, e, history, method):
    return CoupledResult(T_K=x, P_W=P, iterations=len(history), evaluations=0,
                         residual_K=float(np.max(np.abs(f))), energy_residual_rel=e,
                         loop_gain=float("nan"), history=history, method=method)


def _anderson(ev, x0, memory, max_step_K, *, tol_K, tol_energy_rel, max_iter, T_limit_K):
    """Anderson mixing (type II, mixing 1) with step clipping and restarts; None on failure."""
    history: list = []
    x = x0.copy()
    g, P = ev(x)
    if not np.all(np.isfinite(g)):
        return None
    f = _record(history, x, g, P, "start")
    Xs, Gs, Fs = [x], [g], [f]
    memory = max(1, min(memory, x0.size))       # more differences than unknowns: rank-deficient
    best, stall = float(np.max(np.abs(f))), 0
    for _ in range(max_iter):
        if np.max(np.abs(f)) <= tol_K:
            ok, x, g, P, f, e = _verify(ev, g, P, history, tol_K, tol_energy_rel)
            if ok:
                return _result(x, P, f, e, history, "anderson")
            Xs, Gs, Fs = [x], [g], [f]
            continue
        if len(Fs) > 1:
            dF = np.diff(np.array(Fs), axis=0).T          # n × m
            dG = np.diff(np.array(Gs), axis=0).T
            gamma = np.linalg.lstsq(dF, f, rcond=None)[0]
            x_new = g - dG @ gamma
        else:
            x_new = g.copy()
        step = x_new - x
        big = np.max(np.abs(step))
        if big > max_step_K:
            step *= max_step_K / big
        x_new = np.clip(x + step, x0.min() - 50.0 if x0.min() > 60.0 else 10.0, T_limit_K)
        g_new, P_new = ev(x_new)
        if not np.all(np.isfinite(g_new)):
            return None
        f_new = _record(history, x_new, g_new, P_new, "anderson")
        r = float(np.max(np.abs(f_new)))
        if r > 10.0 * best and len(Fs) > 1:               # blow-up: restart the memory here
            Xs, Gs, Fs = [], [], []
        x, g, P, f = x_new, g_new, P_new, f_new
        Xs, Gs, Fs = (Xs + [x])[-(memory + 1):], (Gs + [g])[-(memory + 1):], (Fs + [f])[-(memory + 1):]
        if r < 0.5 * best:
            best, stall = r, 0
        else:
            best, stall = min(best, r), stall + 1
        if stall >= 10 or (np.max(x) >= T_limit_K and np.mean(f) > 0):
            return None
    return None


def _picard(ev, x0, damping, *, tol_K, tol_energy_rel, max_iter, T_limit_K, label=None):
    """Damped Picard T ← T + β (G(T) − T) with runaway and oscillation detection."""
    history: list = []
    x = x0.copy()
    g, P = ev(x)
    f = _record(history, x, g, P, "start")
    steps: list = []                                       # mean temperature increments
    bounded = False                                        # the update maps the limit below itself
    method = label or ("picard" if damping == 1.0 else "picard-damped")
    for _ in range(max_iter):
        if not np.all(np.isfinite(g)):
            if all(s > 0 for s in steps):
                raise ThermalRunaway("the update returned non-finite temperatures on a monotone heating path",
                                     iterations=len(history), last=x, history=history)
            raise NoConvergence("the update returned non-finite temperatures", iterations=len(history),
                                last=x, history=history)
        if np.max(np.abs(f)) <= tol_K:
            ok, xv, gv, Pv, fv, e = _verify(ev, g, P, history, tol_K, tol_energy_rel)
            if ok:
                return _result(xv, Pv, fv, e, history, method)
            x, g, P, f = xv, gv, Pv, fv
            continue
        heating = len(steps) >= 1 and all(s > 0 for s in steps) and np.mean(f) > 0
        accelerating = (not bounded and len(steps) >= 4
                        and all(b >= a for a, b in zip(steps[-4:-1], steps[-3:])))
        if heating and accelerating and np.max(g) <= T_limit_K:
            # growing increments alone are not proof: a stable but non-normal map (e.g. a Jordan block
            # with eigenvalues < 1) amplifies its differences for a few steps.  Decide on the loop gain.
            lam = loop_gain(lambda T: ev(T)[0], x)
            accelerating = bool(np.isfinite(lam) and lam >= 1.0)
            if accelerating:
                # nor is a loop gain ≥ 1 here: past the fold where a cool equilibrium ends, the path may be
                # crossing to a hotter one (:func:`_past_fold`)
                bounded, hot = _past_fold(ev, x, history, label, tol_K=tol_K, tol_energy_rel=tol_energy_rel,
                                          max_iter=max_iter, T_limit_K=T_limit_K)
                if hot is not None:
                    return hot
                accelerating = not bounded
        if heating and (np.max(g) > T_limit_K or accelerating):
            why = (f"passes the limit T_limit_K = {T_limit_K:g} K ({T_limit_K - ZERO_C_K:g} °C)"
                   if np.max(g) > T_limit_K else "heats by growing increments")
            gain = (f"path gain dT_out/dT_in ≈ {steps[-1] / steps[-2]:.3g}" if len(steps) >= 2 and steps[-2]
                    else f"{len(steps)} heating step{'s' * (len(steps) != 1)}")
            raise ThermalRunaway(
                f"thermal runaway: the heating path from T0 {why} (mean residual +{np.mean(f):.3g} K, "
                f"{gain}: the losses grow faster with temperature than the dissipation)",
                iterations=len(history), residual=float(np.max(np.abs(f))), last=x, history=history)
        x_new = x + damping * f
        steps.append(float(np.mean(x_new - x)))
        x = x_new
        g, P = ev(x)
        f = _record(history, x, g, P, method)
        if len(steps) >= 4:
            last = steps[-4:]
            alternating = all(a * b < 0 for a, b in zip(last[:-1], last[1:]))
            growing = all(abs(b) >= abs(a) for a, b in zip(last[:-1], last[1:]))
            if alternating and growing:
                mu = steps[-1] / steps[-2]                   # increment ratio = 1 − β + β λ near a fixed point
                raise NoConvergence(
                    f"{method} (damping {damping:g}) oscillates without decaying (ratio of successive "
                    f"increments {mu:.3g}): strong negative feedback of the losses on temperature; use "
                    "method='anderson' or a smaller damping (β < 2/(1 − λ) for a loop gain λ < −1)",
                    iterations=len(history), residual=float(np.max(np.abs(f))), last=x, history=history)
    raise NoConvergence(f"{method}: max |G(T) − T| = {np.max(np.abs(f)):.3g} K after {max_iter} iterations",
                        iterations=len(history), residual=float(np.max(np.abs(f))), last=x, history=history)


def _past_fold(ev, x, history, label, *, T_limit_K, **opts):
    """(bounded, hotter equilibrium or None) of a heating path at ``x`` that heats by growing increments with a
    loop gain ≥ 1.  Where the update maps the limit below itself (``bounded``), a monotone path from below stays
    below it and settles between (a monotone map between a sub- and a super-solution has a fixed point between
    them: Amann 1976, SIAM Review 18:620); the same map iterated down from the limit settles on the hotter
    equilibrium the path goes on to reach, where no third lies between (checked: not below the path).  Where the
    update is not defined at the limit (a lubricant's range) nothing is proven: not bounded."""
    try:
        g_lim, _ = ev(np.full_like(x, T_limit_K))
    except InputError:
        return False, None
    bounded = bool(np.all(np.isfinite(g_lim)) and np.all(g_lim <= T_limit_K))
    if not bounded or label == "picard-from-limit":
        return bounded, None
    try:
        down = _picard(ev, np.full_like(x, T_limit_K), 1.0, T_limit_K=T_limit_K, label="picard-from-limit", **opts)
    except (NoConvergence, ThermalRunaway, InputError):      # not a verdict on the heating path
        return bounded, None
    if not np.all(down.T_K >= x - opts["tol_K"]):
        return bounded, None
    down.history = history + down.history
    return bounded, down

def _physical_path(ev, x0, **opts):
    """Plain Picard from T0 (decides runaway); where it creeps monotonically (a loop gain just below 1, near
    the fold where the equilibrium ends), restarted from Aitken's extrapolation of its last increments; on
    oscillation, Picard damped by the estimated gain."""
    try:
        return _picard(ev, x0, 1.0, **opts)
    except ThermalRunaway:
        raise
    except NoConvergence as exc:
        h = exc.history
        if len(h) < 3:
            raise
        d1 = np.mean(h[-1]["T_K"] - h[-2]["T_K"])
        d0 = np.mean(h[-2]["T_K"] - h[-3]["T_K"])
        lam = d1 / d0 if d0 else -1.0
        if 0.0 < lam < 1.0:
            return _creeping(ev, h, lam, exc, **opts)
        beta = float(np.clip(1.0 / (1.0 - lam), 0.02, 0.9)) if lam < 0 else 0.5
        try:
            return _picard(ev, x0, beta, **opts)
        except NoConvergence as exc2:
            raise NoConvergence(f"accelerated and damped (β = {beta:.3g}) iterations failed: {exc2.reason}",
                                iterations=exc2.iterations, residual=exc2.residual, last=exc2.last,
                                history=exc2.history) from None


def _creeping(ev, h, lam, exc, restarts: int = 5, **opts):
    r"""Picard restarted from Aitken's Δ² extrapolation of a monotonically creeping path: increments
    shrinking by the ratio λ ∈ (0, 1) sum to the fixed point at x + Δx λ/(1 − λ) (Aitken 1926); the
    restarted Picard decides convergence or runaway from there.  NoConvergence ``exc`` when the restarts
    do not settle.  (Aitken, A. C. 1926, "On Bernoulli's numerical solution of algebraic equations",
    Proc. R. Soc. Edinburgh 46, 289–305.)"""
    for _ in range(restarts):
        x = h[-1]["T_K"] + (h[-1]["T_K"] - h[-2]["T_K"]) * lam / (1.0 - lam)
        try:
            res = _picard(ev, np.minimum(x, opts["T_limit_K"]), 1.0, **opts)
            res.method = "picard-aitken"
            return res
        except ThermalRunaway:
            raise
        except NoConvergence as again:
            h = again.history
            if len(h) < 3:
                break
            d1, d0 = np.mean(h[-1]["T_K"] - h[-2]["T_K"]), np.mean(h[-2]["T_K"] - h[-3]["T_K"])
            lam = d1 / d0 if d0 else -1.0
            if not 0.0 < lam < 1.0:
                break
    raise exc
