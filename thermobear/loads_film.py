r"""Quasi-static load distribution with the lubricant film in the contact law (prototype).

The rigid-ring load distribution of :mod:`thermobear.loads` treats each contact as dry:
a ball carries Q = K_n s^1.5 when the geometric approach s of its groove centres is
positive and nothing when there is a gap.  For lightly loaded balls the central film is
as thick as, or thicker than, the elastic approach (validation/report/seed004_trends.md,
"The film against the elastic approach"; seed 004: Darul et al. 2024, §5.3.5, §6,
Figs 13, 18, 19, where low-loaded balls stay in the IVR regime with a finite force).
Here the film enters the contact law of each ball (both contacts in series):

    s_j = δ_el(Q_j) − h_i(Q_j, α_j) − h_o(Q_j, α_j),    δ_el = (Q / K_n)^(2/3)

s_j the geometric approach of the groove-curvature centres (negative: a gap) [m],
δ_el the Hertz approach of both contacts (Harris 2001 eq 7.3 for K_n) [m], h_i, h_o
the Nijenbanning–Venner–Moes (1994) central films of the inner and outer contact at
the ball's load, at R_x of each contact at the ball's contact angle α_j, at the given
entrainment speeds, viscosity and pressure–viscosity coefficient
(:func:`thermobear.film.film_thickness_nvm`).  Because h_c falls with Q (∝ Q^-2 in the
rigid iso-viscous limit) and δ_el rises, the law is smooth and monotone, and every
ball carries a load Q > 0 for every s: a gap carries the hydrodynamic load of a film
as thick as the gap (a flooded inlet is assumed).  (Each NVM asymptote falls with Q or,
H_RP, does not depend on it; for the blend d ln h_c / d ln Q < 0 is checked numerically,
Q = 1e-6–1e4 N on the 7210 contacts in tests/test_loads_film.py; the per-ball inversion is
bracketed, so it does not rely on it.)

What the film does to the distribution (tests/test_loads_film.py): in a radial bearing the
films share the radial load out (the most loaded ball carries less, the least loaded more);
in an angular contact bearing under a fixed axial load the films add to the approach, the
contact angles fall and the most loaded ball may carry slightly more than dry, while the
balls outside the load zone carry a few newtons across their gaps.

Ring geometry and equilibrium are those of :mod:`thermobear.loads` (Jones 1960; Harris
2001 §7.4; seed 004 eqs 6–8; ISO/TS 16281 rigid rings, low-speed form: one contact
angle and one load per ball, no centrifugal force):

    A1_j = A sin α0 + δa' + ℜ_i θ cos ψ_j,   A2_j = A cos α0 + δr cos ψ_j
    s_j = √(A1_j² + A2_j²) − A,   tan α_j = A1_j / A2_j
    F_a = Σ Q_j sin α_j,   F_r = Σ Q_j cos α_j cos ψ_j,   M = Σ Q_j sin α_j ℜ_i cos ψ_j

Numerics.  The ring displacements are found by Newton's method with the analytic
Jacobian of the film law (∂Q/∂s = 1/G_Q and ∂Q/∂α = −G_α/G_Q, G(Q, α) the right-hand
side of the law; not symmetric once ∂Q/∂α ≠ 0) and a backtracking line search, started
from the dry solution of :func:`thermobear.loads.load_distribution`.  At every iterate
the law is inverted for each ball by a vectorised, bracketed (safeguarded) Newton
iteration in x = ln Q (a Newton step below the tolerance ends it, also when x has just become an
end of the bracket).  Derivatives: dδ_el/d ln Q = (2/3) δ_el analytically; the film
derivatives d(h_i + h_o)/d ln Q and ∂G/∂α by central differences (steps 1e-5 in ln Q,
1e-6 rad in α) of the public NVM function.  The geometric approach is formed without
cancellation by :mod:`thermobear.loads`' geometry (signed: a gap is s < 0, which the dry
law clips and the film law needs); the load checks are that module's too.

Approximations (prototype): one viscosity and one α_p for every contact (one
temperature), entrainment speeds given (e.g. at the nominal angle), low-speed form (the
centrifugal force is left to the caller, as :func:`thermobear.losses.prepare_contacts`
adds it to the outer contacts), fully flooded inlets, NVM central film (the film that
carries the load is the central one; the minimum film or a starved inlet would give less).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .errors import InputError, NoConvergence, NoEquilibrium
from .film import film_thickness_nvm
from .geometry import BallBearing
from .loads import STIFFNESS_MODES, LoadDistribution, _backtrack, _batch_loads, _geometry, load_distribution

__all__ = ["FilmLoadDistribution", "film_load_distribution", "film_contact_law"]

_TOL = 1e-12          # relative equilibrium residual at which Newton stops
_MAXIT = 60
_EPS_LNQ = 1e-5       # central-difference step in ln Q [-]
_EPS_ALPHA = 1e-6     # central-difference step in the contact angle [rad]
_LNQ_MIN, _LNQ_MAX = -600.0, 40.0      # bracket limits of ln(Q / 1 N)
_XTOL = 1e-13         # convergence of the per-ball inversion in ln Q (relative load)


@dataclass(frozen=True)
class FilmLoadDistribution(LoadDistribution):
    """:class:`thermobear.loads.LoadDistribution` of the film contact law, with the film data.

    Extra attributes (per ball, shape batch + (Z,))
    ------------------------------------------------
    delta_geo : geometric approach of the groove centres s [m] (negative: a gap bridged by the film)
    h_i, h_o : NVM central film of the inner / outer contact at the ball's load [m]
    stiffness_n : dQ/ds of the film law at the solution [N/m]
    law_residual : max |G(Q) − s| / (δ_el + h_i + h_o) over the balls [-]
    inversion_iterations : max per-ball inversion iterations at the last iterate

    ``delta_n`` holds the elastic (Hertz) approach δ_el of both contacts [m].
    """

    delta_geo: np.ndarray = None
    h_i: np.ndarray = None
    h_o: np.ndarray = None
    stiffness_n: np.ndarray = None
    law_residual: float = 0.0
    inversion_iterations: int = 0


class _Film:
    """Film-law context: bearing, film inputs broadcast to (nb, Z), stiffness mode."""

    def __init__(self, brg, u_i, u_o, eta, alpha_p, stiffness):
        self.brg, self.u_i, self.u_o, self.eta, self.ap, self.stiffness = brg, u_i, u_o, eta, alpha_p, stiffness
        self.Ep = brg.E_prime
        self.Kn0 = brg.Kn()

    def rows(self, rows):
        """The same law for a subset of the load cases (rows of the (nb, Z) inputs)."""
        return _Film(self.brg, self.u_i[rows], self.u_o[rows], self.eta[rows], self.ap[rows], self.stiffness)

    def parts(self, Q, alpha):
        """δ_el, h_i, h_o at loads Q > 0 and contact angles α, shapes (nb, Z) [m]."""
        b = self.brg
        Kn = b.Kn(alpha) if self.stiffness == "per_ball" else self.Kn0
        d_el = (Q / Kn) ** (2.0 / 3.0)
        h_i = np.asarray(film_thickness_nvm(Q, b.Rx_i(alpha), b.Ry_i, self.u_i, self.eta, self.ap, self.Ep))
        h_o = np.asarray(film_thickness_nvm(Q, b.Rx_o(alpha), b.Ry_o, self.u_o, self.eta, self.ap, self.Ep))
        return d_el, h_i, h_o

    def G(self, Q, alpha):
        d_el, h_i, h_o = self.parts(Q, alpha)
        return d_el - h_i - h_o

    def G_lnQ(self, Q, alpha, d_el):
        """dG/d ln Q: (2/3) δ_el analytically, the films by a central difference in ln Q [m]."""
        e = np.exp(_EPS_LNQ)
        _, hip, hop = self.parts(Q * e, alpha)
        _, him, hom = self.parts(Q / e, alpha)
        return (2.0 / 3.0) * d_el - ((hip + hop) - (him + hom)) / (2.0 * _EPS_LNQ)

    def G_alpha(self, Q, alpha):
        """∂G/∂α at fixed Q by a central difference [m/rad]."""
        return (self.G(Q, alpha + _EPS_ALPHA) - self.G(Q, alpha - _EPS_ALPHA)) / (2.0 * _EPS_ALPHA)


def _invert(law: _Film, s, alpha, Q0):
    """Solve G(Q, α) = s for Q > 0 per ball: bracketed Newton in x = ln Q (vectorised).

    Returns (Q, δ_el, h_i, h_o, G_lnQ, iterations, relative law residual)."""
    x = np.log(np.clip(Q0, np.exp(_LNQ_MIN + 1.0), np.exp(_LNQ_MAX - 1.0)))
    lo = np.full(x.shape, np.nan)
    hi = np.full(x.shape, np.nan)
    d_el, h_i, h_o = law.parts(np.exp(x), alpha)
    f = d_el - h_i - h_o - s
    lo = np.where(f < 0, x, lo)
    hi = np.where(f > 0, x, hi)
    # expand the bracket: step in ln Q doubling from 1 until G − s changes sign
    step = np.ones_like(x)
    xe = x.copy()
    for _ in range(12):
        need_hi = np.isnan(hi) & ~(f == 0)
        need_lo = np.isnan(lo) & ~(f == 0)
        if not (need_hi.any() or need_lo.any()):
            break
        xe = np.where(need_hi, np.minimum(xe + step, _LNQ_MAX), np.where(need_lo, np.maximum(xe - step, _LNQ_MIN), xe))
        fe = law.G(np.exp(xe), alpha) - s
        hi = np.where(need_hi & (fe > 0), xe, hi)
        lo = np.where(need_hi & (fe <= 0), xe, lo)
        lo = np.where(need_lo & (fe < 0), xe, lo)
        hi = np.where(need_lo & (fe >= 0), xe, hi)
        step *= 2.0
    if np.any((np.isnan(lo) | np.isnan(hi)) & (f != 0)):
        bad = (np.isnan(lo) | np.isnan(hi)) & (f != 0)
        k = np.unravel_index(int(np.argmax(bad)), bad.shape)
        raise NoConvergence(
            f"film contact law: no load in [e^{_LNQ_MIN:g}, e^{_LNQ_MAX:g}] N gives the approach s = {s[k]:.4g} m "
            f"(ball {k[-1]}, alpha = {alpha[k]:.4g} rad)", iterations=0, residual=float(np.abs(f[k])))
    lo = np.where(np.isnan(lo), x, lo)
    hi = np.where(np.isnan(hi), x, hi)
    done = f == 0
    it = 0
    for it in range(1, 101):
        Q = np.exp(x)
        d_el, h_i, h_o = law.parts(Q, alpha)
        f = d_el - h_i - h_o - s
        lo = np.where(f < 0, x, lo)
        hi = np.where(f > 0, x, hi)
        dG = law.G_lnQ(Q, alpha, d_el)
        step = f / np.where(dG > 0, dG, np.inf)
        xn = x - step
        # a Newton step below the tolerance is convergence, even when x itself has just become an end
        # of the bracket (xn may then round onto it; bisecting there would throw x away from the root)
        small = (np.abs(step) <= _XTOL * np.maximum(1.0, np.abs(x))) & (dG > 0)
        outside = (~((xn > lo) & (xn < hi)) | ~np.isfinite(xn) | (dG <= 0)) & ~small
        xn = np.where(outside, 0.5 * (lo + hi), xn)
        xn = np.where(done, x, xn)
        xtol = _XTOL * np.maximum(1.0, np.abs(x))
        conv = small | (np.abs(xn - x) <= xtol) | (hi - lo <= xtol)
        x = xn
        done = done | conv
        if done.all():
            break
    Q = np.exp(x)
    d_el, h_i, h_o = law.parts(Q, alpha)
    scale = d_el + h_i + h_o
    rel = np.abs(d_el - h_i - h_o - s) / scale
    dG = law.G_lnQ(Q, alpha, d_el)
    if not done.all():
        k = np.unravel_index(int(np.argmax(np.where(done, 0.0, rel))), rel.shape)
        raise NoConvergence(
            f"film contact law: per-ball inversion did not converge (ball {k[-1]}, s = {s[k]:.4g} m): "
            f"relative residual {rel[k]:.3g} after {it} iterations", iterations=it, residual=float(rel.max()))
    return Q, d_el, h_i, h_o, dG, it, float(rel.max()) if rel.size else 0.0


def film_contact_law(brg: BallBearing, Q, alpha, *, u_i, u_o, eta, alpha_p, stiffness: str = "nominal"):
    r"""Geometric approach of a ball's groove centres under the film contact law [m].

    s = (Q / K_n)^(2/3) − h_i(Q) − h_o(Q)   (module docstring; NVM 1994 central films).

    Parameters
    ----------
    brg : BallBearing
    Q : array_like        ball load [N], > 0
    alpha : array_like    contact angle [rad]
    u_i, u_o : array_like mean entrainment speeds of the inner / outer contact [m/s], > 0
    eta : array_like      dynamic viscosity [Pa s], > 0
    alpha_p : array_like  pressure–viscosity coefficient [1/Pa], ≥ 0
    stiffness : str       ``"nominal"`` (K_n at the nominal angle) or ``"per_ball"`` (at α)

    Returns
    -------
    (s, delta_el, h_i, h_o)  arrays [m]

    Examples
    --------
    A lightly loaded 7210 ball (5 N) at 4800 rpm in a 22 mPa s oil: the films exceed
    the elastic approach, the groove centres stand apart (s < 0).

    >>> from thermobear.geometry import bearing
    >>> s, d, hi, ho = film_contact_law(bearing("7210"), 5.0, 0.698, u_i=8.63, u_o=8.63, eta=0.0221, alpha_p=2e-8)
    >>> bool(s < 0), bool(hi + ho > d)
    (True, True)
    """
    if stiffness not in STIFFNESS_MODES:
        raise InputError("stiffness", stiffness, f"must be one of {', '.join(STIFFNESS_MODES)}")
    Q = _pos("Q", Q)
    alpha = np.asarray(alpha, dtype=float)
    law = _Film(brg, _pos("u_i", u_i), _pos("u_o", u_o), _pos("eta", eta), _nonneg("alpha_p", alpha_p), stiffness)
    d_el, h_i, h_o = law.parts(Q, alpha)
    return d_el - h_i - h_o, d_el, h_i, h_o


def _pos(name, v):
    a = np.asarray(v, dtype=float)
    if a.size and (not np.all(np.isfinite(a)) or np.any(a <= 0)):
        raise InputError(name, v, "must be finite and > 0 (the film law needs a film: eta > 0, u > 0, Q > 0)")
    return a


def _nonneg(name, v):
    a = np.asarray(v, dtype=float)
    if a.size and (not np.all(np.isfinite(a)) or np.any(a < 0)):
        raise InputError(name, v, "must be finite and >= 0 [1/Pa]")
    return a


def film_load_distribution(brg: BallBearing, Fa=0.0, Fr=0.0, M=None, *, u_i, u_o, eta, alpha_p,
                           stiffness: str = "nominal", tol: float = _TOL,
                           maxiter: int = _MAXIT) -> FilmLoadDistribution:
    r"""Low-speed, rigid-ring load distribution with the EHL/IVR film in each ball's contact law.

    Parameters
    ----------
    brg : BallBearing
    Fa : array_like      axial load on the inner ring [N], ≥ 0
    Fr : array_like      radial load on the inner ring [N], ≥ 0, acting towards ψ = 0
    M : array_like       tilting moment [N m]; ``None`` holds the tilt at θ = 0
    u_i, u_o : array_like  mean entrainment speed of the inner / outer contacts [m/s], > 0;
                         broadcast to batch + (Z,) (a scalar, one value per ball, or per case and ball),
                         e.g. :func:`thermobear.kinematics.entrainment_speed` at the nominal angle
    eta : array_like     dynamic viscosity [Pa s], > 0, broadcast to the batch (one temperature per case)
    alpha_p : array_like pressure–viscosity coefficient [1/Pa], ≥ 0, broadcast to the batch
    stiffness : str      ``"nominal"`` (K_n at the nominal angle, default) or ``"per_ball"``
    tol : float          relative equilibrium residual at which Newton stops [-]

    Returns
    -------
    FilmLoadDistribution  (a :class:`thermobear.loads.LoadDistribution`: can be passed as ``load=`` to
    :func:`thermobear.solver.scene_losses`); every ball has Q > 0

    Raises
    ------
    InputError      bad loads or film inputs, or no load at all (the film law needs one)
    NoEquilibrium   as :func:`thermobear.loads.load_distribution` (loads the bearing cannot carry), or a
                    ball would need a contact angle ≤ 0 (angular contact)
    NoConvergence   the ring equilibrium or a per-ball inversion did not converge (carries the residual)

    Notes
    -----
    Contact law per ball  s_j = (Q_j/K_n)^(2/3) − h_i(Q_j) − h_o(Q_j)  (NVM 1994 central films,
    :func:`thermobear.film.film_thickness_nvm`); ring equilibrium of Jones (1960) / Harris (2001 §7.4),
    seed 004 eqs 6–8.  Motivation: seed 004 (Darul 2024) §5.3.5, §6: low-loaded balls in IVR with a
    finite force.  See the module docstring for the equations, numerics and approximations.

    Examples
    --------
    7210 under Fa 450 N, Fr 750 N at 4800 rpm, mineral oil at 50 °C: the dry distribution loads
    3 of the 15 balls, the film law all of them (the others across a film as thick as their gap).

    >>> from thermobear.geometry import bearing
    >>> from thermobear.loads import load_distribution
    >>> b = bearing("7210")
    >>> ld = film_load_distribution(b, 450.0, 750.0, u_i=8.63, u_o=8.63, eta=0.0221, alpha_p=2e-8)
    >>> dry = load_distribution(b, 450.0, 750.0)
    >>> int((dry.Q > 0).sum()), int((ld.Q > 0).sum()), ld.residual < 1e-10
    (3, 15, True)
    """
    if stiffness not in STIFFNESS_MODES:
        raise InputError("stiffness", stiffness, f"must be one of {', '.join(STIFFNESS_MODES)}")
    shape, Fa_b, Fr_b, M_b, Mv = _batch_loads(brg, Fa, Fr, M)
    tilt_free = M_b is not None
    Z, A, R = brg.Z, brg.A, brg.R_inner_locus
    nb = Fa_b.size
    F_app = np.stack([Fa_b, Fr_b, Mv / R], axis=1)
    zero = np.max(np.abs(F_app), axis=1) == 0.0
    if np.any(zero):
        raise InputError("Fa, Fr, M", (float(Fa_b[zero][0]), float(Fr_b[zero][0]), float(Mv[zero][0])),
                         "the film load distribution needs a load (every ball carries a film force)")
    scale = np.max(np.abs(F_app), axis=1)

    # film inputs broadcast to (nb, Z)
    def per_ball(name, v, check):
        a = check(name, v)
        try:
            return np.broadcast_to(a, shape + (Z,)).reshape(nb, Z)
        except ValueError:
            raise InputError(name, v, f"must broadcast to the load batch {shape} + (Z = {Z},)") from None

    def per_case(name, v, check):
        a = check(name, v)
        try:
            return np.broadcast_to(a, shape).reshape(nb, 1)
        except ValueError:
            raise InputError(name, v, f"must broadcast to the load batch {shape}") from None

    law = _Film(brg, per_ball("u_i", u_i, _pos), per_ball("u_o", u_o, _pos), per_case("eta", eta, _pos),
                per_case("alpha_p", alpha_p, _nonneg), stiffness)

    psi = 2.0 * np.pi * np.arange(Z) / Z
    c_psi = np.cos(psi)[None, :]
    active = [0, 1, 2] if tilt_free else [0, 1]
    na = len(active)

    # start: the dry solution (ring displacements scaled by A, as in thermobear.loads)
    dry = load_distribution(brg, Fa=Fa_b, Fr=Fr_b, M=M_b, stiffness=stiffness)
    y = np.stack([(np.asarray(dry.delta_a) - A * np.sin(brg.alpha0)) / A, np.asarray(dry.delta_r) / A,
                  np.asarray(dry.theta) * R / A], axis=1)
    Qw = np.maximum(np.asarray(dry.Q_i).reshape(nb, Z), 1e-6 * (scale[:, None] / Z))   # warm start

    def evaluate(yv, Q0, rows=slice(None)):
        """Residual, Jacobian and per-ball state at scaled displacements yv (rows of the batch)."""
        sub = law.rows(rows)
        A1, A2, Aj, s = _geometry(yv, brg, c_psi, A)
        al = np.arctan2(A1, A2)
        Q, d_el, h_i, h_o, GQ, nit, rel = _invert(sub, s, al, Q0)
        sa, ca = A1 / Aj, A2 / Aj
        fa, fr = Q * sa, Q * ca
        Fm = np.stack([fa.sum(1), (fr * c_psi).sum(1), (fa * c_psi).sum(1)], axis=1)
        res = (Fm - F_app[rows]) / scale[rows, None]
        # per-ball derivatives: Q(s, α), ∂Q/∂s = 1/G_Q = Q/G_lnQ, ∂Q/∂α = −G_α/G_Q
        Qs = Q / GQ
        Qal = -sub.G_alpha(Q, al) * Qs
        dQ1 = Qs * sa + Qal * ca / Aj            # dQ/dA1
        dQ2 = Qs * ca - Qal * sa / Aj            # dQ/dA2
        g = np.empty(Q.shape + (2, 2))           # d(fa, fr)/d(A1, A2)
        g[..., 0, 0] = dQ1 * sa + Q * ca * ca / Aj
        g[..., 0, 1] = dQ2 * sa - Q * sa * ca / Aj
        g[..., 1, 0] = dQ1 * ca - Q * sa * ca / Aj
        g[..., 1, 1] = dQ2 * ca + Q * sa * sa / Aj
        c = np.broadcast_to(c_psi, Q.shape)
        one, nil = np.ones_like(c), np.zeros_like(c)
        Wt = np.stack([np.stack([one, nil], -1), np.stack([nil, c], -1), np.stack([c, nil], -1)], -2)  # (..,3,2)
        P = A * np.stack([np.stack([one, nil, c], -1), np.stack([nil, c, nil], -1)], -2)             # (..,2,3)
        J = np.einsum("bjik,bjkl,bjlm->bim", Wt, g, P) / scale[rows, None, None]
        state = dict(Q=Q, d_el=d_el, h_i=h_i, h_o=h_o, s=s, alpha=al, Qs=Qs, nit=nit, rel=rel)
        return res, J, state

    res, J, st = evaluate(y, Qw)
    norm = np.max(np.abs(res[:, active]), axis=1)
    floor = np.zeros(nb, bool)
    it = 0
    for it in range(1, maxiter + 1):
        todo = (norm > tol) & ~floor
        if not np.any(todo):
            it -= 1
            break
        rows = np.flatnonzero(todo)
        Jt = J[rows][:, active][:, :, active]
        dy = np.zeros((rows.size, 3))
        dy[:, active] = -np.linalg.solve(Jt, res[rows][:, active][..., None])[..., 0]
        Q_t = st["Q"][rows]

        def trial_norm(trial, Q_t=Q_t, rows=rows):
            try:
                r_t, _, _ = evaluate(trial, Q_t, rows)
            except NoConvergence:                       # the law's inversion failed there: reject the trial
                return np.full(rows.size, np.inf)
            return np.max(np.abs(r_t[:, active]), axis=1)

        y[rows] = _backtrack(y[rows], dy, norm[rows], trial_norm)
        prev = norm.copy()
        res, J, st = evaluate(y, st["Q"])
        norm = np.max(np.abs(res[:, active]), axis=1)
        floor |= todo & (norm <= 1e-9) & (norm > 0.5 * prev)
    else:
        it = maxiter
    if np.any(norm > max(tol, 1e-9)):
        k = int(np.argmax(norm))
        raise NoConvergence(
            f"film load distribution did not reach equilibrium for Fa = {Fa_b[k]:g} N, Fr = {Fr_b[k]:g} N, "
            f"M = {Mv[k]:g} N m: relative residual {norm[k]:.3g} after {it} Newton iterations",
            iterations=it, residual=float(norm.max()), last=y[k] * np.array([A, A, A / R]))
    Q, al = st["Q"], st["alpha"]
    if brg.kind == "angular_contact" and np.any(al <= 0):
        raise NoEquilibrium("angular contact bearing: a ball would need a contact angle <= 0 (contact over the "
                            "low shoulder); the axial load is too small for the radial load", iterations=it,
                            residual=float(norm.max()))
    if not (np.all(np.isfinite(Q)) and np.all(Q > 0)):
        raise NoConvergence("film load distribution: a ball load is not finite and positive", iterations=it,
                            residual=float(norm.max()))
    da = y[:, 0] * A + A * np.sin(brg.alpha0)
    dr = y[:, 1] * A
    th = y[:, 2] * A / R

    def sh(v):
        return v.reshape(shape) if shape else float(v[0])

    def shz(v):
        return v.reshape(shape + (Z,)) if shape else v[0]

    return FilmLoadDistribution(
        delta_a=sh(da), delta_r=sh(dr), theta=sh(th), Q_i=shz(Q), Q_o=shz(Q.copy()),
        alpha_i=shz(al), alpha_o=shz(al.copy()), psi=psi, delta_n=shz(st["d_el"]),
        residual=float(norm.max()), iterations=int(it), Fa=np.asarray(Fa, dtype=float), Fr=np.asarray(Fr, dtype=float),
        M=Mv.reshape(shape) if shape else float(Mv[0]),
        delta_geo=shz(st["s"]), h_i=shz(st["h_i"]), h_o=shz(st["h_o"]), stiffness_n=shz(st["Qs"]),
        law_residual=st["rel"], inversion_iterations=int(st["nit"]))
