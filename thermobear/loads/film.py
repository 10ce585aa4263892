r"""Quasi-static load distribution with the lubricant film in the contact law (prototype).

The rigid-ring load distribution of :mod:`thermobear.loads.static` treats each contact as dry:
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

Numerics.  The ring displacements are found by Newton's method with the analytic
Jacobian of the film law (∂Q/∂s = 1/G_Q and ∂Q/∂α = −G_α/G_Q, G(Q, α) the right-hand
side of the law; not symmetric once ∂Q/∂α ≠ 0) and a backtracking line search, started
from the dry solution of :func:`thermobear.loads.load_distribution`.  At every iterate
the law is inverted for each ball by a vectorised, bracketed (safeguarded) Newton
iteration in x = ln Q on a logarithmic form of the law that is nearly linear in x
(:func:`_invert`), warm-started from the loads of the last iterate carried to first
order.  All derivatives are analytic: dδ_el/d ln Q = (2/3) δ_el, and the films'
d ln h/d ln Q, d ln h/d ln R_x by the chain rule through the NVM blend (:class:`_NVMFixed`,
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
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermobear.errors import InputError, NoConvergence, NoEquilibrium
from thermobear.lubrication.film import _EXP_MAX as _NVM_EXP_MAX
from thermobear.lubrication.film import _TINY as _NVM_TINY
from thermobear.lubrication.film import _ln_asymptote_consts, film_thickness_nvm
from thermobear.contact.geometry import BallBearing
from thermobear.loads.static import STIFFNESS_MODES, LoadDistribution, _backtrack, _batch_loads, _geometry, load_distribution

__all__ = ["FilmLoadDistribution", "film_load_distribution", "film_contact_law"]

_TOL = 1e-12          # relative equilibrium residual at which Newton stops
_MAXIT = 60
_EPS_ALPHA = 1e-6     # central-difference step of K_n(α) (stiffness = "per_ball") [rad]
_LNQ_MIN, _LNQ_MAX = -600.0, 40.0      # bracket limits of ln(Q / 1 N)
_Q_MIN, _Q_MAX = np.exp(_LNQ_MIN + 1.0), np.exp(_LNQ_MAX - 1.0)   # warm starts clipped to these [N]
_CAP0 = 16.0          # largest first Newton step in ln Q while the bracket is one-sided (doubling)
_XTOL = 1e-13         # convergence of the per-ball inversion in ln Q (relative load): bracket, bisection
_XNEWTON = 1e-8       # a Newton step in ln Q this small is the last one (error ~ step^2 ~ 1e-16)


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


class _NVMFixed:
    r"""NVM central film at fixed R_x, R_y, u, η, α_p, E' and variable load, with its logarithmic derivatives.

    The load-independent groups are formed once, U2 = 2ηu/(E'R_x), ln L = ln(α_p E') + ¼ ln U2, D = R_x/R_y
    and the D-parts of the asymptotes (:func:`thermobear.lubrication.film._ln_asymptote_consts`); per load
    ln M = ln(Q/(E'R_x²)) − ¾ ln U2 and ln h = ln H(M, L, D) + ln R_x + ½ ln U2, with the operations of
    :func:`thermobear.lubrication.film.film_thickness_nvm` (the same bits).  The NVM (1994) blend (PHYSICS.md §5.2)

        ln H = ln(e^{s a} + e^{s b}) / s,   a = ⅔ ln(H_RI^1.5 + H_EI'^1.5),   H_EI' = (H_EI^-4 + h00^-4)^-¼,
        b = −⅛ ln(H_RP^-8 + H_EP^-8),       s = 1.5 (1 + e^{−1.2 r}),   r = H_EI / H_RI,

    is differentiated by the chain rule.  With the shares w_a = e^{s(a − ln H)}, w_b = e^{s(b − ln H)},
    p = H_RI^1.5 / (H_RI^1.5 + H_EI'^1.5), q = H_EI^-4 / (H_EI^-4 + h00^-4), t = H_RP^-8 / (H_RP^-8 + H_EP^-8):

        ∂ln H = w_a [p ∂ln H_RI + (1 − p)(q ∂ln H_EI + (1 − q) ∂ln h00)] + w_b [t ∂ln H_RP + (1 − t) ∂ln H_EP]
                + [w_a (a − ln H) + w_b (b − ln H)] / s · (−1.8 r e^{−1.2 r}) ∂ln r,

    ∂(ln H_RI, ln H_EI, ln H_RP, ln H_EP, ln h00) = (−2, −2/15, 0, −1/12, 0) per ln M, (0, 0, ⅔, ¾, 0) per
    ln L, (c'_RI, c'_EI, c'_RP, c'_EP, −1) per ln D (:func:`_ln_asymptote_dconsts`).  In the physical
    variables (R_y, η, α_p, E' fixed; H_M = ∂ln H/∂ln M etc.):

        ∂ln h/∂ln Q = H_M,   ∂ln h/∂ln u = −¾ H_M + ¼ H_L + ½,   ∂ln h/∂ln R_x = −5/4 H_M − ¼ H_L + H_D + ½.

    Checked against central differences of :func:`~thermobear.lubrication.film.film_thickness_nvm` in all four
    regimes (tests/test_loads_film.py).

    Examples
    --------
    7210 inner contact, 8.63 m/s, 22 mPa s: at 1 µN the rigid iso-viscous limit h ∝ (ηu)²/Q²
    (Moes H_RI ∝ M^-2), at 1 kN the EHL slopes (h ∝ Q^-0.067 u^0.72, cf. Hamrock–Dowson −0.067, 0.67).

    >>> nvm = _NVMFixed(4.23e-3, 0.1495, 8.63, 0.0221, 2e-8, 2.3e11)
    >>> for Q in (1e-6, 1e3):
    ...     ln_h, H_Q, shares = nvm.ln_h(Q)
    ...     print(round(float(H_Q), 3), round(float(nvm.grad(shares)[1]), 2))
    -2.0 2.0
    -0.066 0.72
    """

    def __init__(self, Rx, Ry, u, eta, alpha_p, Ep):
        U2 = 2.0 * eta * u / (Ep * Rx)
        self.ERx2 = Ep * Rx ** 2
        self.lnU2 = np.log(U2)
        self.lnL = np.log(np.clip(alpha_p * Ep, _NVM_TINY, None)) + 0.25 * self.lnU2
        self.D = Rx / Ry
        self.c = _ln_asymptote_consts(self.D)
        self.ln_RP = self.c[2] + (2.0 / 3.0) * self.lnL                     # H_RP does not depend on Q
        self.lnRx = np.log(Rx)

    def ln_h(self, Q):
        """(ln(h_c / 1 m), ∂ln h_c/∂ln Q, shares) at loads Q [N]; the blend shares are for :meth:`grad`."""
        c_RI, c_EI, c_RP, c_EP, ln_h00 = self.c
        lnM = np.log(Q / self.ERx2) - 0.75 * self.lnU2
        ln_RI, ln_EI = c_RI - 2.0 * lnM, c_EI - (2.0 / 15.0) * lnM          # film._ln_asymptotes_from
        ln_RP, ln_EP = self.ln_RP, c_EP - lnM / 12.0 + 0.75 * self.lnL
        A4 = np.logaddexp(-4.0 * ln_EI, -4.0 * ln_h00)                       # film._ln_branches
        A15 = np.logaddexp(1.5 * ln_RI, 1.5 * (-0.25 * A4))
        a = (2.0 / 3.0) * A15
        A8 = np.logaddexp(-8.0 * ln_RP, -8.0 * ln_EP)
        b = -0.125 * A8
        r_ln = ln_EI - ln_RI
        r = np.exp(np.minimum(np.maximum(r_ln, -_NVM_EXP_MAX), _NVM_EXP_MAX))
        e12 = np.exp(-1.2 * r)
        s = 1.5 * (1.0 + e12)
        As = np.logaddexp(s * a, s * b)
        ln_H = As / s
        # derivative: the shares of the blends
        wa, wb = np.exp(s * a - As), np.exp(s * b - As)
        p = np.exp(1.5 * ln_RI - A15)
        q = np.exp(-4.0 * ln_EI - A4)
        t = np.exp(-8.0 * ln_RP - A8)
        # ∂s/∂ln r = −1.8 r e^{−1.2 r} (where r is clipped, |ln r| ≥ 700, this is 0 to 1e-300 anyway)
        H_s = (wa * (a - ln_H) + wb * (b - ln_H)) / s * (-1.8 * r * e12)
        H_M = wa * (-2.0 * p - (2.0 / 15.0) * (1.0 - p) * q) - wb * (1.0 - t) / 12.0 + (28.0 / 15.0) * H_s
        return ln_H + self.lnRx + 0.5 * self.lnU2, H_M, (wa, wb, p, q, t, H_s, H_M)

    def grad(self, shares):
        """(∂ln h/∂ln R_x, ∂ln h/∂ln u) [-] from the ``shares`` an :meth:`ln_h` call returned."""
        wa, wb, p, q, t, H_s, H_M = shares
        H_L = wb * ((2.0 / 3.0) * t + 0.75 * (1.0 - t))
        dRI, dEI, dRP, dEP = _ln_asymptote_dconsts(self.D)
        H_D = (wa * (p * dRI + (1.0 - p) * (q * dEI - (1.0 - q))) + wb * (t * dRP + (1.0 - t) * dEP)
               + H_s * (dEI - dRI))
        return -1.25 * H_M - 0.25 * H_L + H_D + 0.5, -0.75 * H_M + 0.25 * H_L + 0.5


def _ln_asymptote_dconsts(D):
    """d c_k / d ln D of the D-parts of the NVM asymptotes (:func:`thermobear.lubrication.film._ln_asymptote_consts`),
    (c'_RI, c'_EI, c'_RP, c'_EP):  c_RI = ln 145 − (15/7) ln(1 + 0.796 D^(14/15)) − ln D,
    c_EI = ln 3.18 − (14/25) e − (ln D)/15,  c_RP = ln 1.29 − ⅔ ln(1 + 0.691 D),  c_EP = ln 1.48 − (7/20) e −
    (ln D)/24,  e = ln(1 + 0.006 ln D + 0.63 D^(4/7))."""
    D47, D1415 = D ** (4.0 / 7.0), D ** (14.0 / 15.0)
    de = (0.006 + 0.63 * (4.0 / 7.0) * D47) / (1.0 + 0.006 * np.log(D) + 0.63 * D47)
    return (-(15.0 / 7.0) * 0.796 * (14.0 / 15.0) * D1415 / (1.0 + 0.796 * D1415) - 1.0,
            -(14.0 / 25.0) * de - 1.0 / 15.0,
            -(2.0 / 3.0) * 0.691 * D / (1.0 + 0.691 * D),
            -(7.0 / 20.0) * de - 1.0 / 24.0)


class _FilmAt:
    r"""The film contact law at fixed contact angles as a function of x = ln(Q / 1 N):

        G(x) = δ_el − H,   δ_el = (e^x / K)^(2/3),   H = Σ_c h_c(e^x),   dG/dx = ⅔ δ_el − Σ_c h_c ∂ln h_c/∂ln Q,
        ∂G/∂α = −⅔ δ_el ∂ln K/∂α − Σ_c h_c (∂ln h_c/∂ln R_x ∂ln R_x,c/∂α + ∂ln h_c/∂ln u ∂ln u_c/∂α).

    ``pair``: the two films of a ball lie on a last axis of the :class:`_NVMFixed` arrays and are summed
    (low-speed form); otherwise one film per load (one contact per element, high-speed form).
    ``dlnRx``, ``dlnu``: ∂ln R_x,c/∂α, ∂ln u_c/∂α; ``dlnK``: ∂ln K/∂α (None: K does not vary)."""

    def __init__(self, K, nvm, pair, dlnRx, dlnu, dlnK=None):
        self.K, self.lnK, self.nvm, self.pair = K, np.log(K), nvm, pair
        self.dlnRx, self.dlnu, self.dlnK = dlnRx, dlnu, dlnK

    def ln_terms(self, x):
        """(ln H, ∂ln H/∂x, ln h_c, ∂ln h_c/∂ln Q, shares) at x = ln Q (h_c per contact on the last axis;
        the shares of the NVM blend for :meth:`G_alpha`)."""
        Q = np.exp(x)
        if not self.pair:
            ln_h, H_M, sh = self.nvm.ln_h(Q)
            return ln_h, H_M, ln_h, H_M, sh
        ln_h, H_M, sh = self.nvm.ln_h(Q[..., None])
        lnH = np.logaddexp(ln_h[..., 0], ln_h[..., 1])
        w = np.exp(ln_h - lnH[..., None])
        return lnH, w[..., 0] * H_M[..., 0] + w[..., 1] * H_M[..., 1], ln_h, H_M, sh

    def G_alpha(self, d_el, h, shares):
        """(∂G/∂α at fixed Q [m/rad], h ∂ln h/∂ln u [m] per contact) at a point evaluated by
        :meth:`ln_terms` (δ_el, h [m] and the ``shares`` of that point)."""
        g_Rx, g_u = self.nvm.grad(shares)
        ha = h * (g_Rx * self.dlnRx + g_u * self.dlnu)
        Ga = -(ha[..., 0] + ha[..., 1]) if self.pair else -ha
        if self.dlnK is not None:
            Ga = Ga - (2.0 / 3.0) * d_el * self.dlnK
        return Ga, h * g_u


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


def _carry(Q, G_lnQ, dG):
    """Loads Q [N] carried to first order to a point where the law's right-hand side has to change by dG
    [m] (G_lnQ = ∂G/∂ln Q [m] at Q): Q e^{dG / G_lnQ}, the exponent clipped to ±3 (a warm start only)."""
    with np.errstate(all="ignore"):
        d = dG / G_lnQ
    return Q * np.exp(np.clip(np.where(np.isfinite(d), d, 0.0), -3.0, 3.0))


def _invert(law: _FilmAt, s, alpha, Q0):
    r"""Solve G(Q) = s for Q > 0 per element at fixed contact angles (vectorised, bracketed Newton in x = ln Q).

    ``law``: the law at the angles (:class:`_FilmAt`); ``alpha`` names the angle in error messages;
    Q0 the warm start [N].  Returns (Q, δ_el, h, dG/d ln Q, ∂G/∂α, h ∂ln h/∂ln u, iterations, relative law
    residual), h and h ∂ln h/∂ln u per contact (last axis (inner, outer) when ``law.pair``).

    Newton runs on a form of δ_el − H = s in logarithms that is nearly linear in x (δ_el ∝ e^{2x/3},
    H ≈ ∝ e^{−k x}, k = 0–2), with the same root and sign as G − s:

        s > 0:  F = ln δ_el − ln(s + H),      F' = ⅔ − H/(s + H) · d ln H/dx
        s ≤ 0:  F = ln(δ_el − s) − ln H,      F' = ⅔ δ_el/(δ_el − s) − d ln H/dx

    (both logarithms of sums of positive terms; F' ≥ ⅔ min(1, δ_el/(δ_el − s)) > 0 where H falls with Q).
    Each evaluated point narrows a bracket [lo, hi] (sign of F).  Until both ends are known a Newton step
    is capped at 16, 32, 64 … in ln Q (a step along −F by the cap where F' ≤ 0); once bracketed a step that
    leaves it (or F' ≤ 0) is replaced by bisection.  A Newton step below 1e-13 max(1, |x|) ends it (also
    when x has just become an end of the bracket), as does a bracket that narrow.  The state returned is
    that of the last evaluation carried over the last step Δx (|Δx| ≤ 1e-13 max(1, |x|)) to first order,
    ln h ← ln h + ∂ln h/∂ln Q Δx (error O(Δx²)); dG/d ln Q and ∂G/∂α are those of the last evaluation."""
    x = np.log(np.minimum(np.maximum(Q0, _Q_MIN), _Q_MAX))
    pos = s > 0
    ln_s = np.log(np.abs(s), out=np.full(s.shape, -np.inf), where=s != 0)   # −inf at s = 0: T = ln δ_el
    lo = np.full(x.shape, -np.inf)
    hi = np.full(x.shape, np.inf)
    cap = None
    done = np.zeros(x.shape, bool)
    it = 0
    for it in range(1, 101):
        lnH, dlnH, ln_h, H_M, shares = law.ln_terms(x)
        lnd = (2.0 / 3.0) * (x - law.lnK)
        Pl = np.where(pos, lnH, lnd)
        T = np.logaddexp(ln_s, Pl)                         # ln(s + H) or ln(δ_el − s)
        E = np.exp(Pl - T)                                  # H/(s + H) or δ_el/(δ_el − s), in (0, 1]
        F = np.where(pos, lnd - T, T - lnH)
        dF = np.where(pos, 2.0 / 3.0 - E * dlnH, (2.0 / 3.0) * E - dlnH)
        xev = x
        lo = np.where(F < 0, x, lo)
        hi = np.where(F > 0, x, hi)
        good = dF > 0                                       # (F' = NaN or F = ±inf/NaN: not good)
        step = F / np.where(good, dF, np.inf)
        good &= np.isfinite(step)
        xn = x - step
        if good.all() and (np.all((xn > lo) & (xn < hi)) and (np.abs(step).max() <= _CAP0 if cap is None else True)
                           and xn.max() < _LNQ_MAX and xn.min() > _LNQ_MIN):
            # plain Newton: every step valid, inside the bracket and the range
            done |= np.abs(step) <= _XNEWTON
            x = xn
            if done.all():
                break
            continue
        if x.max() >= _LNQ_MAX or x.min() <= _LNQ_MIN:
            out = ((x >= _LNQ_MAX) & (F < 0)) | ((x <= _LNQ_MIN) & (F > 0))
            if np.any(out):
                k = np.unravel_index(int(np.argmax(out)), out.shape)
                raise NoConvergence(
                    f"film contact law: no load in [e^{_LNQ_MIN:g}, e^{_LNQ_MAX:g}] N gives the approach "
                    f"s = {s[k]:.4g} m (ball {k[1]}, alpha = {alpha[k]:.4g} rad)", iterations=it,
                    residual=float(np.abs(F[k])))
        if cap is None:
            cap = np.full(x.shape, _CAP0)
        done |= F == 0
        xtol = _XTOL * np.maximum(1.0, np.abs(x))
        small = (np.abs(step) <= _XNEWTON) & good
        bracketed = np.isfinite(lo) & np.isfinite(hi)
        # one-sided: the Newton step capped (a capped step along −F where F' ≤ 0); bracketed: bisection
        # where the step leaves the bracket
        xn1 = x + np.where(good, np.clip(-step, -cap, cap), np.where(F < 0, cap, -cap))
        xn2 = np.where(good & (xn > lo) & (xn < hi), xn,
                       0.5 * (np.where(bracketed, lo, x) + np.where(bracketed, hi, x)))
        xn = np.where(small, xn, np.clip(np.where(bracketed, xn2, xn1), _LNQ_MIN, _LNQ_MAX))
        cap = np.where(bracketed, cap, 2.0 * cap)
        xn = np.where(done, x, xn)
        conv = small | (np.abs(xn - x) <= xtol) | (hi - lo <= xtol)
        x = xn
        done |= conv
        if done.all():
            break
    h = np.exp(np.minimum(np.maximum(ln_h, -_NVM_EXP_MAX), _NVM_EXP_MAX))
    if not done.all():
        d_el = np.exp(lnd)
        hs = h.sum(-1) if law.pair else h
        rel = np.abs(d_el - hs - s) / (d_el + hs)
        k = np.unravel_index(int(np.argmax(np.where(done, 0.0, rel))), rel.shape)
        raise NoConvergence(
            f"film contact law: per-ball inversion did not converge (ball {k[1]}, s = {s[k]:.4g} m): "
            f"relative residual {rel[k]:.3g} after {it} iterations", iterations=it, residual=float(rel.max()))
    dx = x - xev                       # the last step (≤ 1e-8, or ≤ 1e-13 max(1, |x|) after bisection)
    Q = np.exp(x)
    d_el = (Q / law.K) ** (2.0 / 3.0)
    Ga, h_u = law.G_alpha(d_el, h, shares)
    if law.pair:
        h = np.exp(np.minimum(np.maximum(ln_h + H_M * dx[..., None], -_NVM_EXP_MAX), _NVM_EXP_MAX))
        hm = h * H_M
        hs, dG = h[..., 0] + h[..., 1], (2.0 / 3.0) * d_el - (hm[..., 0] + hm[..., 1])
    else:
        h = np.exp(np.minimum(np.maximum(ln_h + H_M * dx, -_NVM_EXP_MAX), _NVM_EXP_MAX))
        hs, dG = h, (2.0 / 3.0) * d_el - h * H_M
    rel = np.abs(d_el - hs - s) / (d_el + hs)
    if np.any(~(rel <= 1e-9)):                  # e.g. a film beyond e^700 m (clipped): no load gives s
        k = np.unravel_index(int(np.argmax(np.where(rel <= 1e-9, 0.0, 1.0))), rel.shape)
        raise NoConvergence(
            f"film contact law: no load in [e^{_LNQ_MIN:g}, e^{_LNQ_MAX:g}] N gives the approach s = {s[k]:.4g} m "
            f"(ball {k[1]}, alpha = {alpha[k]:.4g} rad): relative law residual {rel[k]:.3g}", iterations=it,
            residual=float(np.nanmax(rel)))
    return Q, d_el, h, dG, Ga, h_u, it, float(rel.max()) if rel.size else 0.0


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
                         e.g. :func:`thermobear.contact.kinematics.entrainment_speed` at the nominal angle
    eta : array_like     dynamic viscosity [Pa s], > 0, broadcast to the batch (one temperature per case)
    alpha_p : array_like pressure–viscosity coefficient [1/Pa], ≥ 0, broadcast to the batch
    stiffness : str      ``"nominal"`` (K_n at the nominal angle, default) or ``"per_ball"``
    tol : float          relative equilibrium residual at which Newton stops [-]

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
    >>> from thermobear.loads.static import load_distribution
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

    # start: the dry solution (ring displacements scaled by A, as in thermobear.loads.static)
    dry = load_distribution(brg, Fa=Fa_b, Fr=Fr_b, M=M_b, stiffness=stiffness)
    y = np.stack([(np.asarray(dry.delta_a) - A * np.sin(brg.alpha0)) / A, np.asarray(dry.delta_r) / A,
                  np.asarray(dry.theta) * R / A], axis=1)
    Qw = np.maximum(np.asarray(dry.Q_i).reshape(nb, Z), 1e-6 * (scale[:, None] / Z))   # warm start

    # dW/dg per ball (constant): Wt (3×2) maps (fa, fr) to the ring residuals, P (2×3) = d(A1, A2)/dy
    cz = np.broadcast_to(c_psi[0], (Z,))
    Wt = np.zeros((1, Z, 3, 2))
    Wt[0, :, 0, 0], Wt[0, :, 1, 1], Wt[0, :, 2, 0] = 1.0, cz, cz
    P = np.zeros((1, Z, 2, 3))
    P[0, :, 0, 0], P[0, :, 0, 2], P[0, :, 1, 1] = A, A * cz, A * cz

    def evaluate(yv, prev, rows=slice(None)):
        """Residual, Jacobian and per-ball state at scaled displacements yv (rows of the batch).  ``prev``:
        the state of an iterate (its loads carried to first order to yv give the inversion's warm start)
        or warm-start loads [N]."""
        sub = law.rows(rows)
        A1, A2, Aj, s = _geometry(yv, brg, c_psi, A)
        al = np.arctan2(A1, A2)
        if isinstance(prev, dict):
            dG = (s - prev["s"][rows]) - prev["Ga"][rows] * (al - prev["alpha"][rows])
            Q0 = _carry(prev["Q"][rows], prev["GQ"][rows], dG)
        else:
            Q0 = prev
        Q, d_el, h, GQ, Ga, _, nit, rel = _invert(sub.at(al), s, al, Q0)
        sa, ca = A1 / Aj, A2 / Aj
        fa, fr = Q * sa, Q * ca
        Fm = np.stack([fa.sum(1), (fr * c_psi).sum(1), (fa * c_psi).sum(1)], axis=1)
        res = (Fm - F_app[rows]) / scale[rows, None]
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
        J = (Wt @ g @ P).sum(1) / scale[rows, None, None]
        state = dict(Q=Q, d_el=d_el, h_i=h[..., 0], h_o=h[..., 1], s=s, alpha=al, Qs=Qs, GQ=GQ, Ga=Ga, nit=nit,
                     rel=rel)
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
        last = {}

        def trial_norm(trial, st=st, rows=rows, last=last):
            try:
                out = evaluate(trial, st, rows)
            except NoConvergence:                       # the law's inversion failed there: reject the trial
                return np.full(rows.size, np.inf)
            last.update(y=trial.copy(), out=out)
            return np.max(np.abs(out[0][:, active]), axis=1)

        y[rows] = _backtrack(y[rows], dy, norm[rows], trial_norm)
        prev = norm.copy()
        if rows.size == nb and "y" in last and np.array_equal(last["y"], y):
            res, J, st = last["out"]              # the accepted point is the last trial evaluated
        else:
            res, J, st = evaluate(y, st)
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
