r"""Quasi-static load distribution in a ball bearing with rigid rings (Jones 1960; Harris 2001).

Low-speed form (``load_distribution``): equal inner and outer contact angles,
no centrifugal force or gyroscopic moment (seed 004 eqs 6–8, generalised to a
tilt θ and a moment M; ISO/TS 16281 rigid-ring model).

Geometry of ball j at azimuth ψ_j = 2πj/Z (ψ = 0 in the direction of the radial
load), inner-ring displacements δa (axial), δr (radial), θ (tilt) measured from
the concentric, centred ring position (ISO/TS 16281 convention: δa includes the
take-up of the axial play A sin α0):

    A1_j = δa + ℜ_i θ cos ψ_j                (axial separation of the groove centres)
    A2_j = A cos α0 + δr cos ψ_j            (radial separation; A cos α0 = A − Pd/2)
    A_j = √(A1_j² + A2_j²),  tan α_j = A1_j / A2_j,  Q_j = K_n · max(A_j − A, 0)^1.5

Equilibrium of the inner ring:

    F_a = Σ Q_j sin α_j,   F_r = Σ Q_j cos α_j cos ψ_j,   M = Σ Q_j sin α_j ℜ_i cos ψ_j

solved by Newton's method with the analytic (symmetric) Jacobian, vectorised
over the balls and over a batch of load cases, with a backtracking line search
and starting values from the pure-axial closed form and Stribeck's radial
estimate.  The moment uses the arm ℜ_i (radius of the inner groove-centre
locus), the one conjugate to θ, so the Jacobian is the stiffness matrix.

The high-speed form (centrifugal force and gyroscopic moment, outer-race
control, Jones 1960) is in :mod:`thermobear.loads.highspeed`;
:func:`needs_high_speed` states when a scene needs it.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermobear.errors import InputError, NoConvergence, NoEquilibrium
from thermobear.contact.geometry import BallBearing

__all__ = ["LoadDistribution", "load_distribution", "axial_contact_angle", "needs_high_speed",
           "STIFFNESS_MODES"]

STIFFNESS_MODES = ("nominal", "per_ball")
_TOL = 1e-12          # relative equilibrium residual at which Newton stops
_MAXIT = 60
_HALVINGS = 30        # line-search halvings per Newton step

@dataclass(frozen=True)
class LoadDistribution:
    """Result of the quasi-static load distribution.

    Scalars (or arrays with a leading batch axis when the loads are arrays).

    Attributes
    ----------
    delta_a, delta_r : inner-ring axial / radial displacement from the centred position [m]
    theta : tilt [rad] (0 when held)
    Q_i, Q_o : ball–inner / ball–outer contact loads, per ball [N] (equal in the low-speed form)
    alpha_i, alpha_o : contact angles per ball [rad]
    psi : ball azimuths [rad], shape (Z,)
    delta_n : total elastic approach per ball [m]
    residual : max relative equilibrium residual [-]
    iterations : Newton iterations used
    Fa, Fr, M : the applied loads [N], [N], [N m]
    """

    delta_a: np.ndarray
    delta_r: np.ndarray
    theta: np.ndarray
    Q_i: np.ndarray
    Q_o: np.ndarray
    alpha_i: np.ndarray
    alpha_o: np.ndarray
    psi: np.ndarray
    delta_n: np.ndarray
    residual: float
    iterations: int
    Fa: np.ndarray
    Fr: np.ndarray
    M: np.ndarray

    @property
    def Q(self):
        """Ball load [N] (= Q_i = Q_o in the low-speed form)."""
        return self.Q_i

    @property
    def loaded(self):
        """Boolean mask of balls in contact."""
        return self.Q_i > 0


def axial_contact_angle(brg: BallBearing, Fa, Kn=None, tol: float = 1e-14):
    r"""Contact angle under a pure axial load, all balls equal [rad].

    Solves  F_a / (Z K_n A^1.5) = sin α (cos α0 / cos α − 1)^1.5  (Harris 2001 eq 7.36,
    written with A = (fi + fo − 1) D so that no B^1.5 factor is lost) by a vectorised
    bracketed Newton iteration on α ∈ (α0, π/2).

    Parameters
    ----------
    brg : BallBearing
    Fa : array_like   axial load [N], ≥ 0
    Kn : float        ball stiffness [N/m^1.5] (default: ``brg.Kn()`` at the nominal angle)

    Returns
    -------
    ndarray  contact angle α [rad]; α0 where Fa = 0

    Examples
    --------
    >>> from thermobear.contact.geometry import bearing
    >>> b = bearing("iso-dgbb")
    >>> a = axial_contact_angle(b, 1000.0)
    >>> Kn, A = b.Kn(), b.A
    >>> lhs = 1000.0 / (b.Z * Kn * A**1.5)
    >>> rhs = np.sin(a) * (1.0 / np.cos(a) - 1.0) ** 1.5
    >>> bool(abs(lhs / rhs - 1) < 1e-12)
    True
    """
    Fa = np.asarray(Fa, dtype=float)
    Kn = brg.Kn() if Kn is None else Kn
    a0 = brg.alpha0
    target = Fa / (brg.Z * Kn * brg.A**1.5)
    c0 = np.cos(a0)
    if brg.kind == "thrust" and a0 >= np.pi / 2 - 1e-12:
        # α stays 90°: the approach is Fa/(Z Kn) ^ (2/3) along the axis
        return np.full_like(Fa, np.pi / 2)

    def g(al):
        t = np.maximum(c0 / np.cos(al) - 1.0, 0.0)
        return np.sin(al) * t**1.5 - target, t

    lo = np.full_like(Fa, a0)
    hi = np.full_like(Fa, np.pi / 2 - 1e-9)
    # start: small-deflection estimate t ≈ (target / sin α0)^(2/3) or for α0 = 0, α ≈ (2 target)^(1/4)
    if a0 > 1e-6:
        al = np.arccos(np.clip(c0 / (1.0 + (target / max(np.sin(a0), 1e-12)) ** (2 / 3)), -1, 1))
    else:
        al = np.arccos(1.0 / (1.0 + np.sqrt(np.maximum(2.0 * target, 0.0)) ** (2 / 3)))
    al = np.clip(al, a0 + 1e-12, np.pi / 2 - 1e-9)
    for _ in range(100):
        f, t = g(al)
        lo = np.where(f < 0, al, lo)
        hi = np.where(f > 0, al, hi)
        dfd = np.cos(al) * t**1.5 + 1.5 * np.tan(al) ** 2 * np.sqrt(t) * c0
        step = f / np.where(dfd > 0, dfd, np.inf)
        new = al - step
        out = (new <= lo) | (new >= hi) | ~np.isfinite(new)
        new = np.where(out, 0.5 * (lo + hi), new)
        if (np.abs(new - al) <= tol * np.maximum(1.0, np.abs(al))).all():
            al = new
            break
        al = new
    return np.where(Fa > 0, al, a0)


def needs_high_speed(brg: BallBearing, n_rpm, Q_typical, threshold: float = 0.05, rotating: str = "inner"):
    r"""Does the centrifugal ball force matter against the contact load?

    Criterion (documented choice): the low-speed form is used when the ball
    centrifugal force F_c = ½ m dm ω_c² (Harris 2001 eq 8.9, ω_c = ½ω(1 ∓ γ) the cage
    speed with the inner / outer ring rotating) is below ``threshold`` (5 %) of the typical
    ball load.  At the threshold the high-speed solution
    (:mod:`thermobear.loads.highspeed`) has |Q_o − Q_i|/Q ≈ 0.04 and contact angles
    moved by 1.3–1.4° (218 at two loads, 7210 at 450 and 2000 N; tests/test_loads_highspeed.py).
    Returns a boolean (array) and the ratio F_c / Q.

    The seed 004 7210 at 6500 rpm under Fa = 450 N (ball load ≈ 47 N): F_c ≈ 25 N, so
    the criterion asks for the high-speed form although seed 004 neglects it (N dm < 1e6
    was its argument); at 1000 rpm it does not:

    >>> from thermobear.contact.geometry import bearing
    >>> need, ratio = needs_high_speed(bearing("7210"), [1000.0, 6500.0], 450.0 / (15 * np.sin(0.698)))
    >>> need.tolist(), np.round(ratio, 3).tolist()
    ([False, True], [0.013, 0.541])
    """
    omega = np.asarray(n_rpm, dtype=float) * np.pi / 30.0
    gamma = brg.gamma(brg.alpha0)
    omega_c = 0.5 * omega * (1.0 - gamma if rotating == "inner" else 1.0 + gamma)
    Fc = 0.5 * brg.ball_mass * brg.dm * omega_c**2
    ratio = Fc / np.maximum(np.asarray(Q_typical, dtype=float), 1e-300)
    return ratio > threshold, ratio


def _check_loads(brg, Fa, Fr, M):
    for nm, v in (("Fa", Fa), ("Fr", Fr)):
        if np.any(~np.isfinite(v)) or np.any(v < 0):
            raise InputError(nm, v, "load must be finite and >= 0 [N] (Fa pushes the inner ring along +x; Fr acts at psi = 0)")
    if M is not None and np.any(~np.isfinite(M)):
        raise InputError("M", M, "moment must be finite [N m]")
    if brg.kind == "thrust" and np.any(Fr > 0):
        raise NoEquilibrium(
            f"a thrust ball bearing carries no radial load (its washers are not radially located): Fr = {np.max(Fr):g} N; "
            "carry Fr with a radial bearing")
    if brg.kind == "thrust" and np.any((Fa <= 0) & ((np.abs(M) if M is not None else 0) > 0)):
        raise NoEquilibrium("a thrust ball bearing cannot carry a moment without an axial load (balls would lift off)")
    if brg.kind == "angular_contact" and np.any((Fa <= 0) & (Fr > 0)):
        raise NoEquilibrium(
            "a single angular contact bearing under radial load needs an axial load to hold it against its "
            f"shoulder (Fa = 0, Fr = {np.max(Fr):g} N): give the axial reaction or preload of the arrangement")


def _geometry(y, brg, c_psi, A):
    """Groove-centre separations A1, A2, A_j [m] and the signed approach s = A_j − A [m]
    (negative: a gap) at scaled unknowns y; shapes (nb, Z).

    y = (δa'/A, δr/A, θ R/A) with δa' the axial displacement from the position where
    the balls just touch at α0.  The approach is formed without cancellation,
    s = [2A(sin α0 d1 + cos α0 d2) + d1² + d2²] / (A_j + A), so that tiny loads
    (|s| ≪ A) keep full relative precision."""
    sa0, ca0 = np.sin(brg.alpha0), np.cos(brg.alpha0)
    d1 = A * (y[:, 0:1] + y[:, 2:3] * c_psi)
    d2 = A * (y[:, 1:2] * c_psi)
    A1 = A * sa0 + d1
    A2 = A * ca0 + d2
    Aj = np.hypot(A1, A2)
    s = (2.0 * A * (sa0 * d1 + ca0 * d2) + d1 * d1 + d2 * d2) / (Aj + A)
    return A1, A2, Aj, s


def _batch_loads(brg, Fa, Fr, M):
    """Loads broadcast to one batch axis and checked: (shape, Fa, Fr, M or None, M or 0) [N, N m]."""
    Fa_in, Fr_in = np.asarray(Fa, dtype=float), np.asarray(Fr, dtype=float)
    M_in = None if M is None else np.asarray(M, dtype=float)
    shape = np.broadcast_shapes(Fa_in.shape, Fr_in.shape, () if M_in is None else M_in.shape)
    Fa_b = np.broadcast_to(Fa_in, shape).ravel()
    Fr_b = np.broadcast_to(Fr_in, shape).ravel()
    M_b = None if M_in is None else np.broadcast_to(M_in, shape).ravel()
    _check_loads(brg, Fa_b, Fr_b, M_b)
    return shape, Fa_b, Fr_b, M_b, (M_b if M_b is not None else np.zeros_like(Fa_b))


def _state(y, brg, Kn_mode, c_psi, A, R):
    """Ball geometry and dry (Hertz) forces at scaled unknowns y; shapes (nb, Z) (see _geometry)."""
    A1, A2, Aj, s = _geometry(y, brg, c_psi, A)
    s = np.maximum(s, 0.0)
    sa, ca = A1 / Aj, A2 / Aj
    if Kn_mode == "per_ball":
        Kn = brg.Kn(np.arctan2(A1, A2))
    else:
        Kn = brg.Kn()
    Q = Kn * s**1.5
    dQ = 1.5 * Kn * np.sqrt(s)
    return A1, A2, Aj, s, sa, ca, Q, dQ


def _backtrack(y_t, dy, n0, trial_norm, halvings: int = _HALVINGS):
    """Backtracking line search, vectorised over a batch: the step y_t + λ dy with the largest
    λ ∈ {1, ½, ¼, …} whose residual norm ``trial_norm(trial)`` (per case) satisfies the Armijo-type
    decrease n < (1 − 10⁻⁴ λ) n0.  A case that finds none takes the smallest step anyway (escapes a
    flat region).  Returns the new unknowns (batch, n)."""
    lam = np.ones(dy.shape[0])
    best = y_t.copy()
    accepted = np.zeros(dy.shape[0], bool)
    for _ in range(halvings):
        trial = y_t + lam[:, None] * dy
        ok = (trial_norm(trial) < (1.0 - 1e-4 * lam) * n0) & ~accepted
        best[ok] = trial[ok]
        accepted |= ok
        if accepted.all():
            break
        lam = np.where(accepted, lam, lam * 0.5)
    stuck = ~accepted
    best[stuck] = y_t[stuck] + lam[stuck, None] * dy[stuck]
    return best


def load_distribution(brg: BallBearing, Fa=0.0, Fr=0.0, M=None, n_rpm=0.0, *, stiffness: str = "nominal",
                      tol: float = _TOL, maxiter: int = _MAXIT, _y0=None, _cont: bool = True) -> LoadDistribution:
    r"""Quasi-static (low-speed) load distribution, rigid rings.

    Parameters
    ----------
    brg : BallBearing
    Fa : array_like    axial load on the inner ring [N], ≥ 0
    Fr : array_like    radial load on the inner ring [N], ≥ 0, acting towards ψ = 0
    M : array_like     tilting moment [N m]; ``None`` holds the tilt at θ = 0 (shaft held by two bearings)
    n_rpm : float      shaft speed [rpm]; not used by this low-speed form (accepted for a signature
                       common with :func:`thermobear.loads.highspeed.load_distribution_high_speed`;
                       whether a scene needs that form is :func:`needs_high_speed`'s question)
    stiffness : str    ``"nominal"`` (K_n at the nominal contact angle: ISO/TS 16281 practice, default)
                       or ``"per_ball"`` (K_n re-evaluated at each ball's contact angle)

    Returns
    -------
    LoadDistribution   fields gain a leading batch axis when the loads are arrays

    Raises
    ------
    NoEquilibrium      loads the bearing cannot carry (radial load on a thrust bearing,
                       radial load without axial on a single angular contact bearing)
    NoConvergence      Newton did not reach the tolerance (carries the residual)

    Notes
    -----
    Seed 004 eqs 6–8; Harris 2001 §7.4; Jones 1960.  See the module docstring for
    the equations and conventions.  A case whose Newton iteration fails from the
    closed-form start is solved again by continuation in the load magnitude: the same
    load ratios ×10, ×100, ... until it converges, then back down to the given loads
    in steps of √10, each step started from the last solution (at very light loads
    the solution is almost pure geometry — the contact angles of the few loaded
    balls set by Fa/Fr — and the Hertz approach too small to guide Newton there).

    Examples
    --------
    ISO/TS 16281 reference case (Fr = 1000 N, no clearance: δr = 15.1101 µm):

    >>> from thermobear.contact.geometry import bearing
    >>> ld = load_distribution(bearing("iso-dgbb"), Fa=0.0, Fr=1000.0)
    >>> round(ld.delta_r * 1e6, 3), ld.residual < 1e-9
    (15.11, True)
    """
    if stiffness not in STIFFNESS_MODES:
        raise InputError("stiffness", stiffness, f"must be one of {', '.join(STIFFNESS_MODES)}")
    shape, Fa_b, Fr_b, M_b, Mv = _batch_loads(brg, Fa, Fr, M)
    tilt_free = M_b is not None

    Z, A, R = brg.Z, brg.A, brg.R_inner_locus
    psi = 2.0 * np.pi * np.arange(Z) / Z
    c_psi = np.cos(psi)[None, :]
    nb = Fa_b.size
    Kn0 = brg.Kn()
    F_app = np.stack([Fa_b, Fr_b, Mv / R], axis=1)           # moment as a force at arm R
    scale = np.maximum(np.max(np.abs(F_app), axis=1), 1e-300)
    zero = np.max(np.abs(F_app), axis=1) == 0.0

    # --- starting values -----------------------------------------------------
    y = np.zeros((nb, 3))
    if brg.kind == "thrust":
        Qb = Fa_b / Z
        y[:, 0] = (Qb / Kn0) ** (2.0 / 3.0) / A
    else:
        # axial part: pure-axial closed form for Fa (plus a share of Fr for angular contact)
        Fa_eff = Fa_b + (1.25 * Fr_b * np.tan(brg.alpha0) if brg.kind == "angular_contact" else 0.0)
        al = axial_contact_angle(brg, Fa_eff, Kn0)
        y[:, 0] = np.where(Fa_eff > 0, np.cos(brg.alpha0) * np.tan(al) - np.sin(brg.alpha0),
                           -np.sin(brg.alpha0))
        # radial part: Stribeck Q_max ≈ 5 Fr / (Z cos α) plus half the clearance
        ca0 = np.cos(np.where(Fa_eff > 0, al, brg.alpha0))
        Qmax = 5.0 * Fr_b / (Z * np.maximum(ca0, 0.2))
        # the clearance is taken up radially only when no axial load has taken it up already
        dr0 = (Qmax / Kn0) ** (2.0 / 3.0) / np.maximum(ca0, 0.2) + np.where(Fa_eff > 0, 0.0, brg.Pd / 2.0)
        y[:, 1] = np.where(Fr_b > 0, dr0 / A, 0.0)
    if tilt_free:
        # a moment larger than the other loads: tilt until the balls at psi = 0 and pi carry it
        Fm_eq = 4.0 * np.abs(Mv) / (R * Z) * Z          # rough axial load of the most loaded balls
        mdom = np.abs(Mv) / R > np.maximum(Fa_b, Fr_b)
        if np.any(mdom) and brg.kind != "thrust":
            al_m = axial_contact_angle(brg, Fm_eq[mdom], Kn0)
            y[mdom, 2] = np.sign(Mv[mdom]) * (np.cos(brg.alpha0) * np.tan(al_m))

    if _y0 is not None:                 # continuation (see _continue_in_load): the last solution
        y = np.array(_y0, float).reshape(nb, 3)
    active = [0, 1, 2] if tilt_free else [0, 1]
    na = len(active)
    sums = _sum_matrix(c_psi[0])

    def residual_and_jac(yv):
        A1, A2, Aj, s, sa, ca, Q, dQ = _state(yv, brg, stiffness, c_psi, A, R)
        # per-ball stiffness g = dQ n nᵀ + (Q/A_j) e eᵀ and forces Q n, summed over the balls by one
        # product with the lever arms of dA/dy = A (1, 0, c), A (0, c, 0) (see _sum_matrix)
        Qa = np.where(Aj > 0, Q / Aj, 0.0)
        P = np.empty((yv.shape[0], 5, Z))
        g11, g12, g22 = P[:, 0], P[:, 1], P[:, 2]
        np.multiply(Q, sa, out=P[:, 3])
        np.multiply(Q, ca, out=P[:, 4])
        dQs, Qas = dQ * sa, Qa * ca
        np.add(dQs * sa, Qas * ca, out=g11)
        np.multiply(dQs - Qa * sa, ca, out=g12)
        np.add(dQ * ca * ca, Qa * sa * sa, out=g22)
        out = P.reshape(-1, 5 * Z) @ sums
        res = (out[:, 9:] - F_app) / scale[:, None]
        J = out[:, _JAC].reshape(-1, 3, 3)
        J *= A / scale[:, None, None]
        return res, J

    it = 0
    if True:
        res, J = residual_and_jac(y)
        norm = np.max(np.abs(res[:, active]), axis=1)
        norm[zero] = 0.0
        floor = np.zeros(nb, bool)      # at the floating-point floor: below 1e-9 and no longer improving
        for it in range(1, maxiter + 1):
            todo = (norm > tol) & ~floor
            every = bool(todo.all())
            if not every and not todo.any():
                it -= 1
                break
            prev = norm.copy()
            if every:
                # every case: the full Newton step first, its residual and Jacobian kept when accepted
                Jt = J if tilt_free else J[:, :2, :2]
                try:
                    dy_a = -np.linalg.solve(Jt, res[:, active, None])[..., 0]
                except np.linalg.LinAlgError:           # a case with no ball in contact: general path below
                    every = False
            if every:
                trial = y.copy()
                trial[:, active] += dy_a
                r_t, J_t = residual_and_jac(trial)
                n_t = np.max(np.abs(r_t[:, active]), axis=1)
                if (n_t < (1.0 - 1e-4) * norm).all():
                    y, res, J, norm = trial, r_t, J_t, n_t
                else:
                    dy = np.zeros((nb, 3))
                    dy[:, active] = dy_a

                    def trial_norm(tr):
                        r_t, _ = residual_and_jac_partial(tr, todo, brg, stiffness, c_psi, A, R, F_app, scale)
                        return np.max(np.abs(r_t[:, active]), axis=1)

                    y = _backtrack(y, dy, norm, trial_norm)
                    res, J = residual_and_jac(y)
                    norm = np.max(np.abs(res[:, active]), axis=1)
            else:
                Jt = J[todo][:, active][:, :, active]
                # regularise rows of a singular Jacobian (no ball in contact): push towards contact
                det_ok = np.abs(np.linalg.det(Jt)) > 1e-300
                Jt[~det_ok] += np.eye(na)[None] * 1e-3
                dy = np.zeros((int(todo.sum()), 3))
                try:
                    dy[:, active] = -np.linalg.solve(Jt, res[todo][:, active][..., None])[..., 0]
                except np.linalg.LinAlgError:       # singular even regularised: those cases fail below
                    norm[todo] = np.nan
                    break

                def trial_norm(trial):
                    r_t, _ = residual_and_jac_partial(trial, todo, brg, stiffness, c_psi, A, R, F_app, scale)
                    return np.max(np.abs(r_t[:, active]), axis=1)

                y[todo] = _backtrack(y[todo], dy, norm[todo], trial_norm)
                res, J = residual_and_jac(y)
                norm = np.max(np.abs(res[:, active]), axis=1)
            norm[zero] = 0.0
            floor |= todo & (norm <= 1e-9) & (norm > 0.5 * prev)
        else:
            it = maxiter
    extra_it = 0                        # Newton iterations spent by continuation (see Notes)
    thr = max(tol, 1e-9)                # (a NaN residual — a singular step, an overflow — counts as failed)
    if _cont and brg.kind != "thrust" and np.any(~(norm <= thr)):
        for k in np.flatnonzero(~(norm <= thr)):
            if brg.kind == "angular_contact":       # balls over the low shoulder: no equilibrium (raised below)
                A1, _, _, _, _, _, Q, _ = _state(y[k:k + 1], brg, stiffness, c_psi, A, R)
                if np.any((Q > 0) & (A1 <= 0)):
                    continue
            got = _continue_in_load(brg, Fa_b[k], Fr_b[k], Mv[k] if tilt_free else None, stiffness, tol, maxiter)
            if got is not None:
                y[k], norm[k], n_it = got
                extra_it = max(extra_it, n_it)
    if np.any(~(norm <= thr)):
        k = int(np.argmax(np.where(norm <= thr, -1.0, np.nan_to_num(norm, nan=np.inf))))
        if brg.kind == "angular_contact":
            A1, A2, Aj, s_, sa, ca, Q, dQ = _state(y[k:k + 1], brg, stiffness, c_psi, A, R)
            if np.any((Q > 0) & (A1 <= 0)):
                raise NoEquilibrium(
                    f"angular contact bearing: Fa = {Fa_b[k]:g} N is too small for Fr = {Fr_b[k]:g} N, "
                    f"M = {Mv[k]:g} N m — the balls would have to run over the low shoulder (contact angle <= 0)",
                    iterations=it, residual=float(norm[k]), last=y[k] * np.array([A, A, A / R]))
        raise NoConvergence(
            f"load distribution did not reach equilibrium for Fa = {Fa_b[k]:g} N, Fr = {Fr_b[k]:g} N, "
            f"M = {Mv[k]:g} N m: relative residual {norm[k]:.3g} after {it} Newton iterations",
            iterations=it, residual=float(norm[k]), last=y[k] * np.array([A, A, A / R]))

    A1, A2, Aj, s, sa, ca, Q, dQ = _state(y, brg, stiffness, c_psi, A, R)
    Q = np.where(zero[:, None], 0.0, Q)
    alpha = np.where(Q > 0, np.arctan2(A1, A2), brg.alpha0 if brg.kind != "deep_groove" else np.arctan2(A1, A2))
    if brg.kind == "angular_contact" and np.any((Q > 0) & (alpha <= 0)):
        raise NoEquilibrium("angular contact bearing: a loaded ball would need a contact angle <= 0 "
                            "(contact over the low shoulder); the axial load is too small for the radial load")
    da = np.where(zero, 0.0, y[:, 0] * A + A * np.sin(brg.alpha0))   # from the centred position
    dr = np.where(zero, 0.0, y[:, 1] * A)
    th = np.where(zero, 0.0, y[:, 2] * A / R)
    if brg.kind == "deep_groove":
        alpha = np.where(zero[:, None], 0.0, alpha)
    out_shape = shape
    def sh(v):
        return v.reshape(out_shape) if out_shape else float(v[0])
    def shz(v):
        return v.reshape(out_shape + (Z,)) if out_shape else v[0]
    return LoadDistribution(
        delta_a=sh(da), delta_r=sh(dr), theta=sh(th), Q_i=shz(Q), Q_o=shz(Q.copy()),
        alpha_i=shz(alpha), alpha_o=shz(alpha.copy()), psi=psi, delta_n=shz(np.where(zero[:, None], 0.0, s)),
        residual=float(norm.max()) if norm.size else 0.0, iterations=int(it) + extra_it,
        Fa=np.asarray(Fa, dtype=float), Fr=np.asarray(Fr, dtype=float), M=Mv.reshape(out_shape) if out_shape else float(Mv[0]))


def _continue_in_load(brg, Fa, Fr, M, stiffness, tol, maxiter):
    """Scaled unknowns y (3,), the residual and the Newton iterations spent, for one load case by
    continuation in the load magnitude (see :func:`load_distribution`, Notes); None when no scaled case
    converges either."""
    from thermobear.errors import SolverError
    A, R = brg.A, brg.R_inner_locus
    spent = [0]

    def solve(f, y0=None):
        ld = load_distribution(brg, Fa=f * Fa, Fr=f * Fr, M=None if M is None else f * M, stiffness=stiffness,
                               tol=tol, maxiter=maxiter, _y0=y0, _cont=False)
        spent[0] += ld.iterations
        return np.array([(ld.delta_a - A * np.sin(brg.alpha0)) / A, ld.delta_r / A, ld.theta * R / A]), ld.residual

    for k in range(1, 7):                       # up: ×10 … ×1e6 until one converges from the closed-form start
        try:
            y, res = solve(10.0 ** k)
            break
        except SolverError:
            continue
    else:
        return None
    for j in range(2 * k - 1, -1, -1):          # down in steps of √10, each from the last solution
        try:
            y, res = solve(10.0 ** (j / 2), y)
        except SolverError:
            return None
    return y, res, spent[0]


_JAC = np.array([0, 1, 2, 1, 3, 4, 2, 4, 5])   # symmetric 3×3 Jacobian from its six distinct sums


def _sum_matrix(c):
    """(5 Z, 12) matrix turning per-ball rows (g11, g12, g22, Q sin α, Q cos α) [each Z long] into the
    sums Σ g11, Σ g12 c, Σ g11 c, Σ g22 c², Σ g12 c², Σ g11 c² (Jacobian) and Σ Q sin α, Σ Q cos α c,
    Σ Q sin α c (ring forces); c = cos ψ."""
    Z = c.size
    M = np.zeros((5, Z, 12))
    one, c2 = np.ones(Z), c * c
    for row, col, w in ((0, 0, one), (1, 1, c), (0, 2, c), (2, 3, c2), (1, 4, c2), (0, 5, c2),
                        (3, 9, one), (4, 10, c), (3, 11, c)):
        M[row, :, col] = w
    return M.reshape(5 * Z, 12)


def residual_and_jac_partial(y, todo, brg, stiffness, c_psi, A, R, F_app, scale):
    """Residual only, for a subset of the batch (line search)."""
    A1, A2, Aj, s, sa, ca, Q, dQ = _state(y, brg, stiffness, c_psi, A, R)
    fa_j, fr_j = Q * sa, Q * ca
    Fm = np.stack([fa_j.sum(1), (fr_j * c_psi).sum(1), (fa_j * c_psi).sum(1)], axis=1)
    return (Fm - F_app[todo]) / scale[todo][:, None], None
