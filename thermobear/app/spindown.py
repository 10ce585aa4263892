r"""Spin-down (deceleration) tests: J dω/dt = -T(ω), its closed forms and the fits.

A rotor of inertia J [kg m²] released at ω0 [rad/s] decelerates under the
friction torque T(ω) [N m] of the bearing(s) it rides on (seed 001 §3.2).  With T = K ω^n:

* n ≠ 1:  ω(t)^(1-n) = ω0^(1-n) - (1 - n)(K/J) t; for n < 1 the rotor stops at
  t_stop = J ω0^(1-n)/((1 - n) K) after turning φ_max = J ω0^(2-n)/((2 - n) K);
* n = 1:  ω = ω0 exp(-K t/J), φ_max = J ω0/K (never stops).

Seed 001 fits K and n from the stop time t_max and total angle φ_max filmed
by a camera (its eqs 20–21); with noisy ω(t) a least-squares fit of the
closed form is better.  Both are here, plus the dry-friction (n = 0) torque of
its eq 18 and a numerical integrator for any T(ω).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from thermobear.coupled import scene_losses
from thermobear.errors import InputError, NoConvergence
from thermobear.lazy import lazy_module
from thermobear.models import plan

optimize = lazy_module("scipy.optimize")    # least_squares: loaded by its first use
integrate = lazy_module("scipy.integrate")  # solve_ivp: loaded by the first spin-down

__all__ = ["torque_power_law", "omega_power_law", "angle_power_law", "stop_time",
           "total_angle", "SpinDown", "integrate_spin_down", "PowerLawFit",
           "fit_from_stop", "dry_torque_from_stop", "fit_power_law", "spin_down_runs"]


def _pos(name, v, what=""):
    v = np.asarray(v, dtype=float)
    if np.any(~np.isfinite(v)) or np.any(v <= 0):
        raise InputError(name, v, f"must be finite and > 0{what}")
    return v


def _exp_n(n):
    n = np.asarray(n, dtype=float)
    if np.any(~np.isfinite(n)) or np.any(n < 0) or np.any(n >= 2):
        raise InputError("n", n, "torque exponent must lie in [0, 2)")
    return n


def _out(x):
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x


def torque_power_law(omega, K, n):
    r"""Friction torque T = K ω^n [N m] (ω [rad/s] ≥ 0, K [N m s^n], n [-]).

    >>> round(torque_power_law(10.0, 3.213e-5, 0.339), 8)
    7.013e-05
    """
    return _out(np.asarray(K, float) * np.clip(np.asarray(omega, float), 0.0, None) ** np.asarray(n, float))


def stop_time(omega0, K, n, J):
    r"""Time to stop from ω0 under T = K ω^n, n < 1: t = J ω0^(1-n)/((1-n) K) [s]; ∞ for n ≥ 1.

    >>> round(stop_time(10.0, 1e-3, 0.0, 1e-3), 6)
    10.0
    """
    omega0, K, J, n = _pos("omega0", omega0, " [rad/s]"), _pos("K", K), _pos("J", J, " [kg m^2]"), _exp_n(n)
    with np.errstate(divide="ignore"):
        t = np.where(n < 1, J * omega0 ** (1 - n) / ((1 - n) * K), np.inf)
    return _out(t)


def total_angle(omega0, K, n, J):
    r"""Angle turned until stop (n < 1) or t → ∞ (1 ≤ n < 2): φ = J ω0^(2-n)/((2-n) K) [rad].

    >>> round(total_angle(10.0, 1e-3, 0.0, 1e-3), 6)
    50.0
    """
    omega0, K, J, n = _pos("omega0", omega0), _pos("K", K), _pos("J", J), _exp_n(n)
    return _out(J * omega0 ** (2 - n) / ((2 - n) * K))


def omega_power_law(t, omega0, K, n, J):
    r"""Speed during a spin-down with T = K ω^n [rad/s] (seed 001 eq 20).

    Parameters
    ----------
    t : array_like    time since release [s] (≥ 0)
    omega0 : float    initial speed [rad/s]
    K : float         torque coefficient [N m (rad/s)^-n]
    n : float         exponent, 0 ≤ n < 2 [-]
    J : float         rotating inertia [kg m²]

    Notes
    -----
    ω = [ω0^(1-n) - (1-n) K t/J]^(1/(1-n)) (0 after the stop for n < 1);
    ω = ω0 exp(-K t/J) for n = 1.

    >>> round(omega_power_law(5.0, 10.0, 1e-3, 0.0, 1e-3), 6), omega_power_law(20.0, 10.0, 1e-3, 0.0, 1e-3)
    (5.0, 0.0)
    """
    t = np.asarray(t, dtype=float)
    if np.any(t < 0) or np.any(~np.isfinite(t)):
        raise InputError("t", t, "times must be finite and >= 0 [s]")
    omega0, K, J, n = _pos("omega0", omega0), _pos("K", K), _pos("J", J), _exp_n(n)
    if abs(float(n) - 1.0) < 1e-12:
        return _out(omega0 * np.exp(-K * t / J))
    base = omega0 ** (1 - n) - (1 - n) * K * t / J
    return _out(np.where(base > 0, np.abs(base) ** (1.0 / (1 - n)), 0.0))


def angle_power_law(t, omega0, K, n, J):
    r"""Angle turned since release with T = K ω^n [rad] (seed 001 eq 21).

    Notes
    -----
    φ = J/((2-n) K) [ω0^(2-n) - ω(t)^(2-n)] (energy-like integral of eq 20);
    φ = J ω0/K (1 - exp(-K t/J)) for n = 1.

    >>> round(angle_power_law(10.0, 10.0, 1e-3, 0.0, 1e-3), 6)
    50.0
    """
    omega0, K, J, n = _pos("omega0", omega0), _pos("K", K), _pos("J", J), _exp_n(n)
    w = np.asarray(omega_power_law(t, omega0, K, n, J))
    return _out(J / ((2 - n) * K) * (omega0 ** (2 - n) - w ** (2 - n)))


@dataclass(frozen=True)
class SpinDown:
    """Result of :func:`integrate_spin_down`.

    Attributes
    ----------
    t : ndarray       times [s]
    omega : ndarray   speed [rad/s]
    phi : ndarray     angle turned [rad]
    t_stop : float    stop time [s] (inf if the rotor did not stop before t_end)
    nfev : int        right-hand-side evaluations
    """

    t: np.ndarray
    omega: np.ndarray
    phi: np.ndarray
    t_stop: float
    nfev: int


def integrate_spin_down(J, torque, omega0, t_end, *, t_eval=None, rtol=1e-10, atol=None):
    r"""Integrate J dω/dt = -T(ω), dφ/dt = ω from ω0 until stop or t_end.

    Parameters
    ----------
    J : float          rotating inertia [kg m²]
    torque : callable  T(ω) [N m] for ω ≥ 0 (vectorised not required); must be ≥ 0
    omega0 : float     initial speed [rad/s]
    t_end : float      last time [s]
    t_eval : array_like, optional   output times (default: solver steps)
    rtol, atol : float tolerances of :func:`scipy.integrate.solve_ivp` (RK45 → DOP853)

    Returns
    -------
    SpinDown

    Raises
    ------
    NoConvergence   if the integrator fails
    InputError      if T(ω) < 0 or not finite

    Notes
    -----
    A stop event (ω = 0) ends the run; later requested times get ω = 0.  For
    T ∝ ω^n, n < 1, the speed reaches zero tangentially (ω ∝ (t_stop - t)^(1/(1-n))),
    so t_stop is located to about 1e-5 relative (n ≈ 0.65) while ω(t) and φ(t)
    keep the integrator's tolerance.

    Examples
    --------
    >>> r = integrate_spin_down(1e-3, lambda w: 1e-3, 10.0, 20.0)
    >>> round(r.t_stop, 6), round(float(r.phi[-1]), 5)
    (10.0, 50.0)
    """
    J, omega0 = float(_pos("J", J)), float(_pos("omega0", omega0))
    t_end = float(_pos("t_end", t_end, " [s]"))
    atol = omega0 * 1e-12 if atol is None else atol

    def rhs(t, y):
        w = max(y[0], 0.0)
        T = float(torque(w))
        if not np.isfinite(T) or T < 0:
            raise InputError("torque(omega)", T, f"must be finite and >= 0 at omega = {w:g} rad/s")
        return [-T / J if w > 0 else 0.0, w]

    def stopped(t, y):
        return y[0]
    stopped.terminal, stopped.direction = True, -1

    sol = integrate.solve_ivp(rhs, (0.0, t_end), [omega0, 0.0], method="DOP853", rtol=rtol,
                    atol=[atol, atol], events=stopped, dense_output=True)
    if sol.status < 0:
        raise NoConvergence(f"spin-down integration failed: {sol.message}", iterations=sol.nfev,
                            last=sol.y[:, -1] if sol.y.size else None)
    t_stop = float(sol.t_events[0][0]) if sol.t_events[0].size else np.inf
    if t_eval is None:
        t, y = sol.t, sol.y
    else:
        t = np.asarray(t_eval, dtype=float)
        inside = t <= sol.t[-1]
        y = np.empty((2, t.size))
        y[:, inside] = sol.sol(t[inside])
        y[0, ~inside], y[1, ~inside] = 0.0, sol.y[1, -1]
    return SpinDown(t=t, omega=np.clip(y[0], 0.0, None), phi=y[1], t_stop=t_stop, nfev=int(sol.nfev))


def dry_torque_from_stop(omega0, t_max, phi_max, J):
    r"""Constant (dry) friction torque from stop time and angle (seed 001 eq 18) [N m].

    Notes
    -----
    With T constant, ω = ω0 - T t/J and φ = ω0 t - T t²/(2J), so
    T = 2 J (ω0 t_max - φ_max)/t_max².  Physically consistent data have
    φ_max = ω0 t_max/2 (the stop condition); the two estimates of T (this one
    and J ω0/t_max) differ when they are not.

    >>> round(dry_torque_from_stop(10.0, 10.0, 50.0, 1e-3), 9)
    0.001
    """
    omega0, t_max, phi_max, J = (_pos(n, v) for n, v in
                                 (("omega0", omega0), ("t_max", t_max), ("phi_max", phi_max), ("J", J)))
    T = 2.0 * J * (omega0 * t_max - phi_max) / t_max**2
    if np.any(T <= 0):
        raise InputError("phi_max", phi_max, "must be < omega0 t_max for a decelerating rotor")
    return _out(T)


@dataclass(frozen=True)
class PowerLawFit:
    """Fitted T = K ω^n.

    Attributes
    ----------
    K : float         [N m (rad/s)^-n]
    n : float         [-]
    residual : float  RMS of the speed residual [rad/s] (0 for the exact two-point fit)
    iterations : int  function evaluations (0 for the closed form)
    method : str      "stop" (t_max, φ_max) or "least_squares"
    cov : ndarray     covariance of (ln K, n) from the Jacobian (least squares only)
    """

    K: float
    n: float
    residual: float
    iterations: int
    method: str
    cov: np.ndarray | None = field(default=None, compare=False)


def fit_from_stop(omega0, t_max, phi_max, J):
    r"""K and n of T = K ω^n from the stop time and total angle (seed 001 eqs 20–21).

    Parameters
    ----------
    omega0 : float   initial speed [rad/s]
    t_max : float    time at stop [s]
    phi_max : float  angle turned until stop [rad]
    J : float        rotating inertia [kg m²]

    Returns
    -------
    PowerLawFit

    Notes
    -----
    The two conditions ω(t_max) = 0 and φ(t_max) = φ_max have a closed-form
    solution: with r = φ_max/(ω0 t_max) = (1 - n)/(2 - n),
    n = (1 - 2r)/(1 - r) and K = J ω0^(1-n)/((1 - n) t_max).
    A rotor that stops needs n < 1, i.e. 0 < r < 1/2 (r = 1/2: constant torque,
    n = 0; r > 1/2 would need a torque rising as the rotor slows, n < 0).

    Examples
    --------
    >>> f = fit_from_stop(10.0, 10.0, 50.0, 1e-3)
    >>> round(f.n, 12), round(f.K, 12)
    (0.0, 0.001)
    """
    omega0, t_max, phi_max, J = (float(_pos(n, v)) for n, v in
                                 (("omega0", omega0), ("t_max", t_max), ("phi_max", phi_max), ("J", J)))
    r = phi_max / (omega0 * t_max)
    if not 0.0 < r <= 0.5:
        raise InputError("phi_max/(omega0 t_max)", r,
                         "must lie in (0, 0.5] for a power-law torque with 0 <= n < 1 that stops the rotor")
    n = (1.0 - 2.0 * r) / (1.0 - r)
    K = J * omega0 ** (1.0 - n) / ((1.0 - n) * t_max)
    return PowerLawFit(K=K, n=n, residual=0.0, iterations=0, method="stop")


def fit_power_law(t, omega, J, *, omega0=None, n0=0.5, max_nfev=200, tol=1e-12):
    r"""Least-squares fit of the spin-down closed form to measured ω(t).

    Parameters
    ----------
    t : array_like      times since release [s]
    omega : array_like  measured speeds [rad/s]
    J : float           rotating inertia [kg m²]
    omega0 : float, optional   known initial speed [rad/s]; else fitted too
    n0 : float          starting exponent
    max_nfev : int      evaluation budget

    Returns
    -------
    PowerLawFit  (method "least_squares"; residual = RMS speed error [rad/s])

    Raises
    ------
    NoConvergence   the optimiser did not converge within max_nfev, or the
                    Jacobian is singular (e.g. data that do not decelerate)

    Notes
    -----
    Unknowns ln K and n (and ω0), 0 ≤ n ≤ 1.95, on
    :func:`omega_power_law` (fitting the integrated speed is better with noise than
    differentiating ω, the classic argument for coast-down tests).  Start: n0 and the K that matches the mean deceleration.

    Examples
    --------
    >>> tt = np.linspace(0.0, 20.0, 50)
    >>> w = omega_power_law(tt, 15.0, 3.0e-5, 0.35, 2.0e-4)
    >>> f = fit_power_law(tt, w, 2.0e-4, omega0=15.0)
    >>> round(f.K * 1e5, 4), round(f.n, 4)
    (3.0, 0.35)
    """
    t = np.asarray(t, dtype=float)
    w = np.asarray(omega, dtype=float)
    if t.shape != w.shape or t.ndim != 1 or t.size < 3:
        raise InputError("t, omega", (t.shape, w.shape), "need 1-D arrays of equal length >= 3")
    if np.any(~np.isfinite(t)) or np.any(~np.isfinite(w)) or np.any(t < 0) or np.any(w < 0):
        raise InputError("t, omega", None, "must be finite, t >= 0 and omega >= 0")
    J = float(_pos("J", J))
    fit_w0 = omega0 is None
    w0 = float(np.max(w)) if fit_w0 else float(_pos("omega0", omega0))
    moving = w > 0
    span = max(float(t[moving].max()) if moving.any() else float(t.max()), 1e-300)
    decel = max((w0 - float(w[moving].min() if moving.any() else 0.0)) / span, 1e-300)
    n_start = float(np.clip(n0, 0.0, 1.9))
    K0 = J * decel / max(w0, 1e-300) ** n_start

    def model(p):
        lnK, n = p[0], p[1]
        w0_ = p[2] if fit_w0 else w0
        return np.asarray(omega_power_law(t, max(w0_, 1e-300), np.exp(lnK), n, J))

    p0 = [np.log(K0), n_start] + ([w0] if fit_w0 else [])
    lo = [-np.inf, 0.0] + ([0.0] if fit_w0 else [])
    hi = [np.inf, 1.95] + ([np.inf] if fit_w0 else [])
    try:
        res = optimize.least_squares(lambda p: model(p) - w, p0, bounds=(lo, hi), x_scale="jac",
                            max_nfev=max_nfev, xtol=tol, ftol=tol, gtol=tol)
    except (ValueError, FloatingPointError) as exc:
        raise NoConvergence(f"spin-down fit failed: {exc}", iterations=0) from None
    rms = float(np.sqrt(np.mean(res.fun**2)))
    if not res.success or res.status == 0:
        raise NoConvergence(f"spin-down fit did not converge: {res.message}", iterations=int(res.nfev),
                            residual=rms, last=res.x)
    JTJ = res.jac.T @ res.jac
    if np.linalg.cond(JTJ) > 1e14:
        raise NoConvergence("spin-down fit is ill-posed (singular Jacobian: data do not fix K and n)",
                            iterations=int(res.nfev), residual=rms, last=res.x)
    dof = max(t.size - len(p0), 1)
    cov = np.linalg.inv(JTJ) * (rms**2 * t.size / dof)
    return PowerLawFit(K=float(np.exp(res.x[0])), n=float(res.x[1]), residual=rms,
                       iterations=int(res.nfev), method="least_squares", cov=cov[:2, :2])


def _torque_table(scene, models, n_rpm) -> np.ndarray:
    """The scene's friction torque [N m] at the speeds ``n_rpm`` [rpm] with ``models``: one vectorised
    evaluation, or one per speed when the model choice took the film load model (its loads are solved at
    one speed per call: the films of each speed carry their share)."""
    if models["load_model"][0] == "film":
        return np.array([float(scene_losses(scene.with_(n_rpm=float(n)), models=models).torque_Nm) for n in n_rpm])
    return np.asarray(scene_losses(scene, models=models, n_rpm=n_rpm).torque_Nm, float)


def spin_down_runs(scene, J, rpms, *, n_table: int = 80) -> list:
    r"""Coast-downs of a scene's rotor from each initial speed, fitted as seed 001 does.

    The friction torque T(ω) of the scene (prescribed temperature) is tabulated on a log grid of
    speeds (one vectorised loss evaluation), interpolated log-log (power law below the grid), and
    J dω/dt = −T(ω) is integrated until the rotor stops (:func:`integrate_spin_down`).  From the
    stop time t_max and the angle φ_max, K* and n follow as in seed 001 eqs 20–21
    (:func:`fit_from_stop`).  K* and n do not depend on J (t_max ∝ J); J sets only the time scale.

    Parameters
    ----------
    scene : Scene       with a prescribed temperature (operation.T_C)
    J : float           rotating inertia [kg m²]
    rpms : list         initial speeds [rpm]

    Returns
    -------
    list of dict   per initial speed: n0_rpm, omega0_rad_s, T0_Nm, t_stop_s, phi_max_rad, K_star, n,
                   T_fit_at_omega0_Nm and the integration (``_sd``)
    """
    out = []
    for rpm in rpms:
        sc = scene.with_(n_rpm=rpm)
        models = plan(sc)[0]
        w0 = rpm * np.pi / 30.0
        wg = w0 * np.logspace(-5, 0, n_table)
        Tg = _torque_table(sc, models, wg * 30.0 / np.pi)
        if np.any(~np.isfinite(Tg)) or np.any(Tg <= 0):
            raise InputError("spin-down", rpm, "the model torque must be > 0 at every speed below the initial one")
        lw, lT = np.log(wg), np.log(Tg)
        n_low = (lT[1] - lT[0]) / (lw[1] - lw[0])

        def torque(w, lw=lw, lT=lT, n_low=n_low, Tg=Tg, wg=wg):
            if w <= 0:
                return 0.0
            if w < wg[0]:
                return float(Tg[0] * (w / wg[0]) ** max(n_low, 0.0))
            return float(np.exp(np.interp(np.log(w), lw, lT)))

        t_guess = J * w0 / Tg[-1] * 50.0
        sd = integrate_spin_down(J, torque, w0, t_guess, rtol=1e-9)
        if not np.isfinite(sd.t_stop):
            raise InputError("spin-down", rpm, f"the rotor does not stop within {t_guess:.3g} s (torque exponent >= 1)")
        fit = fit_from_stop(w0, sd.t_stop, float(sd.phi[-1]), J)
        out.append({"n0_rpm": rpm, "omega0_rad_s": w0, "T0_Nm": float(Tg[-1]), "t_stop_s": sd.t_stop,
                    "phi_max_rad": float(sd.phi[-1]), "K_star": fit.K, "n": fit.n,
                    "T_fit_at_omega0_Nm": fit.K * w0 ** fit.n, "_sd": sd})
    return out
