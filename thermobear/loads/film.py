r"""Quasi-static load distribution with the lubricant film in the contact law (prototype).

The rigid-ring load distribution of :mod:`thermobear.loads.static` treats each contact as dry:
a ball carries Q = K_n s^1.5 when the geometric approach s of its groove centres is
positive and nothing when there is a gap.  For lightly loaded balls the central film is
as thick as, or thicker than, the elastic approach (validation/report/seed004_trends.md,
"The film against the elastic approach"; seed 004: Darul et al. 2024, §5.3.5, §6,
Figs 13, 18, 19, where low-loaded balls stay in the IVR regime with a finite force).
Here the film enters the contact law of each ball (both contacts in series):

.. math::

    s_j = δ_{el}(Q_j) − h_i(Q_j, α_j) − h_o(Q_j, α_j), \qquad δ_{el} = (Q / K_n)^{2/3}

s_j the geometric approach of the groove-curvature centres (negative: a gap) [m],
δ_el the Hertz approach of both contacts (Harris 2001 eq 7.3 for K_n) [m], h_i, h_o
the Nijenbanning–Venner–Moes (1994) central films of the inner and outer contact at
the ball's load, at R_x of each contact at the ball's contact angle α_j, at the given
entrainment speeds, viscosity and pressure–viscosity coefficient
(:func:`thermobear.lubrication.film.film_thickness_nvm`).  Because h_c falls with Q (∝ Q^-2 in the
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

Ring geometry and equilibrium are those of :mod:`thermobear.loads.static` (Jones 1960; Harris
2001 §7.4; seed 004 eqs 6–8; ISO/TS 16281 rigid rings, low-speed form: one contact
angle and one load per ball, no centrifugal force):

    A1_j = A sin α0 + δa' + ℜ_i θ cos ψ_j,   A2_j = A cos α0 + δr cos ψ_j
    s_j = √(A1_j² + A2_j²) − A,   tan α_j = A1_j / A2_j
    F_a = Σ Q_j sin α_j,   F_r = Σ Q_j cos α_j cos ψ_j,   M = Σ Q_j sin α_j ℜ_i cos ψ_j

Numerics.  The ring displacements are found by the shared damped Newton
(:mod:`thermobear.loads.newton`) with the analytic
Jacobian of the film law (∂Q/∂s = 1/G_Q and ∂Q/∂α = −G_α/G_Q, G(Q, α) the right-hand
side of the law; not symmetric once ∂Q/∂α ≠ 0) and a backtracking line search, started
from the dry solution of :func:`thermobear.loads.load_distribution`.  At every iterate
the law is inverted for each ball by a vectorised, bracketed (safeguarded) Newton
iteration in x = ln Q on a logarithmic form of the law that is nearly linear in x
(:func:`thermobear.loads.filmlaw._invert`), warm-started from the loads of the last iterate
carried to first order.  All derivatives are analytic: dδ_el/d ln Q = (2/3) δ_el, and the films'
d ln h/d ln Q, d ln h/d ln R_x by the chain rule through the NVM blend
(:class:`thermobear.loads.filmlaw._NVMFixed`,
checked against central differences in tests/test_loads_film.py); only ∂ ln K_n/∂α with
``stiffness="per_ball"`` is a central difference (1e-6 rad).  The geometric approach is
formed without cancellation by :mod:`thermobear.loads.static`' geometry (signed: a gap is
s < 0, which the dry law clips and the film law needs); the load checks are that
module's too.

Approximations (prototype): one viscosity and one α_p for every contact (one
temperature), entrainment speeds given (e.g. at the nominal angle), low-speed form (the
centrifugal force is left to the caller, as :func:`thermobear.losses.prepare_contacts`
adds it to the outer contacts), fully flooded inlets, NVM central film (the film that
carries the load is the central one; the minimum film or a starved inlet would give less).

References
----------
.. [1] Darul, Ł. et al. (2024). *Lubricants* 12:14 (seed 004), §2.2 eqs 6–8, §5.3.5, §6.
.. [2] Jones, A. B. (1960). *J. Basic Eng.* 82(2):309–320.
.. [3] Harris, T. A. (2001). *Rolling Bearing Analysis*, 4th ed., Wiley, ch. 7.
.. [4] Nijenbanning, G., Venner, C. H. & Moes, H. (1994). *Wear* 176(2):217–229.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermobear.contact.geometry import BallBearing
from thermobear.errors import InputError, NoConvergence, NoEquilibrium
from thermobear.loads.filmlaw import _FilmAt, _NVMFixed, _carry, _invert, invert_error
from thermobear.loads.newton import NewtonOptions, RowState, newton
from thermobear.loads.rings import (LoadDistribution, arm_length, azimuths, check_stiffness, force_scale, levers,
                                    ring_direction, ring_loads, unbatch)
from thermobear.loads.static import _StaticProblem, load_distribution_static
from thermobear.lubrication.film import film_thickness_nvm

__all__ = ["FilmLoadDistribution", "film_load_distribution", "film_contact_law"]

_TOL = 1e-12          # relative equilibrium residual at which Newton stops
_MAXIT = 60
_EPS_ALPHA = 1e-6     # central-difference step of K_n(α) (stiffness = "per_ball") [rad]

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
        self.Ry = np.array([brg.Ry_i, brg.Ry_o])
        self.u = np.stack(np.broadcast_arrays(u_i, u_o), axis=-1)                 # (nb, Z, 2)
        self.eta2, self.ap2 = eta[..., None], alpha_p[..., None]

    def rows(self, rows):
        """The same law for a subset of the load cases (rows of the (nb, Z) inputs)."""
        return _Film(self.brg, self.u_i[rows], self.u_o[rows], self.eta[rows], self.ap[rows], self.stiffness)

    def at(self, alpha):
        r"""The law at contact angles α [rad], both films on a last axis (:class:`_FilmAt`):
        R_x,c = (D/2)(1 ∓ γ'cos α), ∂ln R_x,c/∂α = ±γ' sin α / (1 ∓ γ'cos α), u fixed; with
        ``stiffness="per_ball"`` ∂ln K_n/∂α by a central difference (1e-6 rad) of K_n(α)."""
        b = self.brg
        Rx = np.stack([b.Rx_i(alpha), b.Rx_o(alpha)], axis=-1)
        dlnRx = (b.D / b.dm) * np.sin(alpha)[..., None] * np.array([0.5, -0.5]) * b.D / Rx
        if self.stiffness == "per_ball":
            Kn = b.Kn(alpha)
            dlnK = (np.log(b.Kn(alpha + _EPS_ALPHA)) - np.log(b.Kn(alpha - _EPS_ALPHA))) / (2.0 * _EPS_ALPHA)
        else:
            Kn, dlnK = self.Kn0, None
        return _FilmAt(Kn, _NVMFixed(Rx, self.Ry, self.u, self.eta2, self.ap2, self.Ep), True, dlnRx, 0.0, dlnK)

    def parts(self, Q, alpha):
        """δ_el, h_i, h_o at loads Q > 0 and contact angles α, shapes (nb, Z) [m] (public NVM function)."""
        b = self.brg
        Kn = b.Kn(alpha) if self.stiffness == "per_ball" else self.Kn0
        d_el = (Q / Kn) ** (2.0 / 3.0)
        h_i = np.asarray(film_thickness_nvm(Q, b.Rx_i(alpha), b.Ry_i, self.u_i, self.eta, self.ap, self.Ep))
        h_o = np.asarray(film_thickness_nvm(Q, b.Rx_o(alpha), b.Ry_o, self.u_o, self.eta, self.ap, self.Ep))
        return d_el, h_i, h_o

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

    >>> from thermobear.contact.geometry import bearing
    >>> s, d, hi, ho = film_contact_law(bearing("7210"), 5.0, 0.698, u_i=8.63, u_o=8.63, eta=0.0221, alpha_p=2e-8)
    >>> bool(s < 0), bool(hi + ho > d)
    (True, True)
    """
    check_stiffness(stiffness)
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



class _FilmState(RowState):
    """Residual, Jacobian and per-ball film data at one iterate (leading axis: the load cases)."""

    FIELDS = ("y", "res", "J", "norm", "Q", "d_el", "h_i", "h_o", "s", "alpha", "Qs", "GQ", "Ga", "nit", "rel",
              "fail", "codes")


class _FilmProblem:
    """The low-speed equilibrium with the film law as a problem of :func:`thermobear.loads.newton.newton`.

    Unknowns and geometry those of :class:`thermobear.loads.static._StaticProblem`; per ball the law is
    inverted for Q, warm-started from the state of the current Newton iterate (``prev``, frozen by
    :meth:`refresh` before each step) carried to first order, or from the loads ``Q0`` at the start."""

    def __init__(self, ring, law, Q0):
        self.ring, self.law, self.Q0, self.prev = ring, law, Q0, None
        Z, A = ring.Z, ring.A
        W = levers(Z, ring.ndof)                                   # (2, ndof, Z)
        # per ball (constant): Wt (ndof×2) maps (fa, fr) to the ring residuals, P (2×ndof) = d(A1, A2)/dy
        self.Wt = W.transpose(2, 1, 0)[None]
        self.P = A * W.transpose(2, 0, 1)[None]
        self.Wa, self.Wr = W[0].T, W[1].T

    def rows(self, idx):
        new = _FilmProblem.__new__(_FilmProblem)
        new.__dict__.update(self.__dict__)
        new.ring, new.law = self.ring.rows(idx), self.law.rows(idx)
        new.Q0 = None if self.Q0 is None else self.Q0[idx]
        new.prev = None if self.prev is None else self.prev.take(idx)
        return new

    def refresh(self, y, st):
        self.prev = st
        return st

    def evaluate(self, y):
        ring, Z = self.ring, self.ring.Z
        AA, Aj, s = ring.geometry(y)
        A1, A2 = AA[:, :Z], AA[:, Z:]
        al = np.arctan2(A1, A2)
        p = self.prev
        Q0 = self.Q0 if p is None else _carry(p.Q, p.GQ, (s - p.s) - p.Ga * (al - p.alpha))
        Q, d_el, h, GQ, Ga, _, nit, rel, fail = _invert(self.law.at(al), s, al, Q0)
        sa, ca = A1 / Aj, A2 / Aj
        fa, fr = Q * sa, Q * ca
        Fm = fa @ self.Wa + fr @ self.Wr
        st = _FilmState.__new__(_FilmState)
        st.res = (Fm - ring.F_app) * ring.inv_scale
        # per-ball derivatives: Q(s, α), ∂Q/∂s = 1/G_Q = Q/G_lnQ, ∂Q/∂α = −G_α/G_Q
        Qs = Q / GQ
        Qal = -Ga * Qs
        QA = Q / Aj
        dQ1 = Qs * sa + Qal * ca / Aj            # dQ/dA1
        dQ2 = Qs * ca - Qal * sa / Aj            # dQ/dA2
        g = np.empty(Q.shape + (2, 2))           # d(fa, fr)/d(A1, A2)
        g[..., 0, 0] = dQ1 * sa + QA * ca * ca
        g[..., 0, 1] = dQ2 * sa - QA * sa * ca
        g[..., 1, 0] = dQ1 * ca - QA * sa * ca
        g[..., 1, 1] = dQ2 * ca + QA * sa * sa
        st.J = (self.Wt @ g @ self.P).sum(1) * ring.inv_scale[:, :, None]
        st.codes, st.fail = fail, fail.any(axis=1)
        norm = np.abs(st.res * ring.free).max(axis=1)
        st.norm = np.where(st.fail, np.nan, norm)
        nb = y.shape[0]
        st.y, st.Q, st.d_el, st.h_i, st.h_o, st.s, st.alpha = y, Q, d_el, h[..., 0], h[..., 1], s, al
        st.Qs, st.GQ, st.Ga, st.nit, st.rel = Qs, GQ, Ga, np.full(nb, nit), np.full(nb, rel)
        return st

    def direction(self, st):
        return ring_direction(st.J, st.res, self.ring.free)


def film_load_distribution(brg: BallBearing, Fa=0.0, Fr=0.0, M=None, *, u_i, u_o, eta, alpha_p, Fz=0.0, My=None,
                           stiffness: str = "nominal", tol: float = _TOL,
                           maxiter: int = _MAXIT, tilt_arm: str = "groove", start=None) -> FilmLoadDistribution:
    r"""Low-speed, rigid-ring load distribution with the EHL/IVR film in each ball's contact law.

    Parameters
    ----------
    brg : BallBearing
    Fa : array_like      axial load on the inner ring [N], ≥ 0
    Fr : array_like      radial load on the inner ring along y (towards ψ = 0) [N]
    M : array_like       moment in the x–y plane [N m]; ``M`` and ``My`` ``None`` hold the tilts at 0
    u_i, u_o : array_like  mean entrainment speed of the inner / outer contacts [m/s], > 0;
                         broadcast to batch + (Z,) (a scalar, one value per ball, or per case and ball),
                         e.g. :func:`thermobear.contact.kinematics.entrainment_speed` at the nominal angle
    eta : array_like     dynamic viscosity [Pa s], > 0, broadcast to the batch (one temperature per case)
    alpha_p : array_like pressure–viscosity coefficient [1/Pa], ≥ 0, broadcast to the batch
    stiffness : str      ``"nominal"`` (K_n at the nominal angle, default) or ``"per_ball"``
    Fz, My : array_like  radial load along z [N] and moment about +y [N m] (:mod:`thermobear.loads.rings`)
    tol : float          relative equilibrium residual at which Newton stops [-]
    maxiter : int        Newton iterations at most
    tilt_arm : str       ``"groove"`` (ℜ_i, default) or ``"pitch"`` (d_m/2): :data:`thermobear.loads.rings.TILT_ARMS`
    start : LoadDistribution, optional
                         a solution of these same load cases (the batch shape of the loads), dry or with the
                         film (e.g. at another film temperature): Newton starts from it instead of from the dry
                         solution solved here

    Returns
    -------
    FilmLoadDistribution  (a :class:`thermobear.loads.LoadDistribution`: can be passed as ``load=`` to
    :func:`thermobear.coupled.solver.scene_losses`); every ball has Q > 0

    Raises
    ------
    InputError      bad loads or film inputs, or no load at all (the film law needs one)
    NoEquilibrium   as :func:`thermobear.loads.load_distribution` (loads the bearing cannot carry), or a
                    ball would need a contact angle ≤ 0 (angular contact)
    NoConvergence   the ring equilibrium or a per-ball inversion did not converge (carries the residual)

    Notes
    -----
    Contact law per ball  s_j = (Q_j/K_n)^(2/3) − h_i(Q_j) − h_o(Q_j)  (NVM 1994 central films,
    :func:`thermobear.lubrication.film.film_thickness_nvm`); ring equilibrium of Jones (1960) / Harris (2001 §7.4),
    seed 004 eqs 6–8.  Motivation: seed 004 (Darul 2024) §5.3.5, §6: low-loaded balls in IVR with a
    finite force.  See the module docstring for the equations, numerics and approximations.

    Examples
    --------
    7210 under Fa 450 N, Fr 750 N at 4800 rpm, mineral oil at 50 °C: the dry distribution loads
    3 of the 15 balls, the film law all of them (the others across a film as thick as their gap).

    >>> from thermobear.contact.geometry import bearing
    >>> from thermobear.loads import load_distribution
    >>> b = bearing("7210")
    >>> ld = film_load_distribution(b, 450.0, 750.0, u_i=8.63, u_o=8.63, eta=0.0221, alpha_p=2e-8)
    >>> dry = load_distribution(b, 450.0, 750.0)
    >>> int((dry.Q > 0).sum()), int((ld.Q > 0).sum()), ld.residual < 1e-10
    (3, 15, True)
    """
    check_stiffness(stiffness)
    loads = ring_loads(brg, Fa, Fr, M, Fz, My)
    shape, nb, nd = loads.shape, loads.nb, loads.ndof
    Z, A, R = brg.Z, brg.A, arm_length(brg, tilt_arm)
    F_app = loads.applied(R)
    zero = np.max(np.abs(F_app), axis=1) == 0.0
    if np.any(zero) and brg.Pd >= 0:        # (a radial preload loads every ball without a load)
        raise InputError("Fa, Fr, M", loads.case(int(np.argmax(zero))),
                         "the film load distribution needs a load or a radial preload (every ball carries a film "
                         "force)")
    scale = force_scale(brg, F_app)
    law = _Film(brg, _per_ball("u_i", u_i, _pos, shape, Z), _per_ball("u_o", u_o, _pos, shape, Z),
                _per_case("eta", eta, _pos, shape), _per_case("alpha_p", alpha_p, _nonneg, shape), stiffness)
    # start: the dry solution (ring displacements scaled by A, as in thermobear.loads.static)
    F = loads.F
    if start is not None and np.shape(start.Q_i) == shape + (Z,):
        dry = start
    else:
        dry = load_distribution_static(brg, Fa=F[:, 0], Fr=F[:, 1], M=F[:, 2] if loads.tilt_free else None,
                                       Fz=F[:, 3], My=F[:, 4] if loads.tilt_free else None, stiffness=stiffness,
                                       tilt_arm=tilt_arm)
    y = np.stack([(np.reshape(dry.delta_a, nb) - brg.A_a0) / A, np.reshape(dry.delta_r, nb) / A,
                  np.reshape(dry.theta, nb) * R / A, np.reshape(dry.delta_z, nb) / A,
                  np.reshape(dry.theta_y, nb) * R / A][:nd], axis=1)
    Qw = np.maximum(np.asarray(dry.Q_i).reshape(nb, Z), 1e-6 * (scale[:, None] / Z))   # warm start
    pb = _FilmProblem(_StaticProblem(brg, F_app, scale, loads.free(), stiffness), law, Qw)
    r = newton(pb, y, NewtonOptions(tol=tol, maxiter=maxiter))
    y, norm, st, its = r.z, r.norm, r.state, r.iterations
    bad = ~(norm <= max(tol, 1e-9))
    if bad.any():
        k = int(np.argmax(np.where(bad, np.nan_to_num(norm, nan=np.inf), -1.0)))
        if st.fail[k]:
            raise invert_error(st.codes[k:k + 1], st.s[k:k + 1], st.alpha[k:k + 1], st.nit[k])
        raise NoConvergence(
            f"film load distribution did not reach equilibrium for {loads.case(k)}: relative residual "
            f"{norm[k]:.3g} after {its[k]} Newton iterations",
            iterations=int(its[k]), residual=float(norm[k]), last=y[k] * np.array([A, A, A / R, A, A / R])[:nd])
    Q, al = st.Q, st.alpha
    if brg.kind == "angular_contact" and np.any(al <= 0):
        raise NoEquilibrium("angular contact bearing: a ball would need a contact angle <= 0 (contact over the "
                            "low shoulder); the axial load is too small for the radial load",
                            iterations=int(its.max()), residual=float(norm.max()))
    if not (np.all(np.isfinite(Q)) and np.all(Q > 0)):
        raise NoConvergence("film load distribution: a ball load is not finite and positive",
                            iterations=int(its.max()), residual=float(norm.max()))
    da = y[:, 0] * A + brg.A_a0
    dz, thy = (y[:, 3] * A, y[:, 4] * A / R) if nd == 5 else (np.zeros(nb), np.zeros(nb))
    return FilmLoadDistribution(
        delta_a=unbatch(shape, da), delta_r=unbatch(shape, y[:, 1] * A), theta=unbatch(shape, y[:, 2] * A / R),
        delta_z=unbatch(shape, dz), theta_y=unbatch(shape, thy),
        Q_i=unbatch(shape, Q, True), Q_o=unbatch(shape, Q.copy(), True), alpha_i=unbatch(shape, al, True),
        alpha_o=unbatch(shape, al.copy(), True), psi=azimuths(Z), delta_n=unbatch(shape, st.d_el, True),
        residual=float(norm.max()), iterations=int(its.max()), **loads.result_fields(Fa, Fr),
        delta_geo=unbatch(shape, st.s, True), h_i=unbatch(shape, st.h_i, True), h_o=unbatch(shape, st.h_o, True),
        stiffness_n=unbatch(shape, st.Qs, True), law_residual=float(st.rel.max()),
        inversion_iterations=int(st.nit.max()))


def _per_ball(name, v, check, shape, Z):
    """Film input broadcast to (nb, Z)."""
    a = check(name, v)
    try:
        return np.broadcast_to(a, shape + (Z,)).reshape(-1, Z)
    except ValueError:
        raise InputError(name, v, f"must broadcast to the load batch {shape} + (Z = {Z},)") from None


def _per_case(name, v, check, shape):
    """Film input broadcast to (nb, 1)."""
    a = check(name, v)
    try:
        return np.broadcast_to(a, shape).reshape(-1, 1)
    except ValueError:
        raise InputError(name, v, f"must broadcast to the load batch {shape}") from None
