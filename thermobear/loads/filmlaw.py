r"""The film contact law of a ball–race contact: δ = δ_el(Q) − h(Q), and its inversion.

For lightly loaded balls the central film is as thick as, or thicker than, the elastic approach
(seed 004 [1]: Darul et al. 2024, §5.3.5, §6, Figs 13, 18, 19: low-loaded balls stay in the IVR
regime with a finite force).  With the film in the contact law a contact c obeys

.. math::

    δ_c = δ_{el,c}(Q_c) − h_c(Q_c, α_c), \qquad δ_{el,c} = (Q_c / K_c)^{2/3}

δ_c the signed approach of the contact (negative: a gap bridged by the film) [m], K_c the Hertz
constant (Harris 2001 [2] eq 7.3 form; both contacts in series with K_n in the low-speed form), h_c
the Nijenbanning–Venner–Moes central film [3] (:func:`thermobear.lubrication.film.film_thickness_nvm`).
Because h_c falls with Q (∝ Q^-2 in the rigid iso-viscous limit) and δ_el rises, the law is smooth
and monotone, and a contact carries Q > 0 for every δ: a gap carries the hydrodynamic load of a film
as thick as the gap (a flooded inlet is assumed).

This module holds the pieces the low-speed (:mod:`thermobear.loads.film`) and the high-speed
(:mod:`thermobear.loads.highspeed`, ``film=``) forms share: the NVM film at fixed geometry with its
logarithmic derivatives (:class:`_NVMFixed`), the law at fixed contact angles (:class:`_FilmAt`) and
its per-contact inversion for Q (:func:`_invert`), vectorised over every contact of a batch, and the
high-speed form's law of both contacts of every ball with caged entrainment speeds (:class:`_FilmLaw`),
and the lubricant data the high-speed form takes (:class:`FilmInputs`, checked by :func:`film_inputs`).

References
----------
.. [1] Darul, Ł. et al. (2024). *Lubricants* 12:14 (seed 004).
.. [2] Harris, T. A. (2001). *Rolling Bearing Analysis*, 4th ed., Wiley, ch. 7.
.. [3] Nijenbanning, G., Venner, C. H. & Moes, H. (1994). Film thickness in elastohydrodynamically
   lubricated elliptic contacts. *Wear* 176(2):217–229.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermobear.errors import InputError, NoConvergence
from thermobear.lubrication.nvm import EXP_MAX as _NVM_EXP_MAX
from thermobear.lubrication.nvm import TINY as _NVM_TINY
from thermobear.lubrication.nvm import ln_asymptote_consts

__all__ = ["invert_error", "FilmInputs", "film_inputs"]

_LNQ_MIN, _LNQ_MAX = -600.0, 40.0      # bracket limits of ln(Q / 1 N)
_Q_MIN, _Q_MAX = np.exp(_LNQ_MIN + 1.0), np.exp(_LNQ_MAX - 1.0)   # warm starts clipped to these [N]
_CAP0 = 16.0          # largest first Newton step in ln Q while the bracket is one-sided (doubling)
_XTOL = 1e-13         # convergence of the per-ball inversion in ln Q (relative load): bracket, bisection
_XNEWTON = 1e-8       # a Newton step in ln Q this small is the last one (error ~ step^2 ~ 1e-16)


class _NVMFixed:
    r"""NVM central film at fixed R_x, R_y, u, η, α_p, E' and variable load, with its logarithmic derivatives.

    The load-independent groups are formed once, U2 = 2ηu/(E'R_x), ln L = ln(α_p E') + ¼ ln U2, D = R_x/R_y
    and the D-parts of the asymptotes (:func:`thermobear.lubrication.nvm.ln_asymptote_consts`); per load
    ln M = ln(Q/(E'R_x²)) − ¾ ln U2 and ln h = ln H(M, L, D) + ln R_x + ½ ln U2, with the operations of
    :func:`thermobear.lubrication.film.film_thickness_nvm` (the same bits).  The NVM (1994) blend [3]

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
        self.c = ln_asymptote_consts(self.D)
        self.ln_RP = self.c[2] + (2.0 / 3.0) * self.lnL                     # H_RP does not depend on Q
        self.lnRx = np.log(Rx)
        # load-free parts of ln_h (each the same operation as in the public function: the same bits)
        self.m8RP, self.m4h00 = -8.0 * self.ln_RP, -4.0 * self.c[4]
        self.L34, self.U34, self.U12 = 0.75 * self.lnL, 0.75 * self.lnU2, 0.5 * self.lnU2

    def ln_h(self, Q):
        """(ln(h_c / 1 m), ∂ln h_c/∂ln Q, shares) at loads Q [N]; the blend shares are for :meth:`grad`."""
        c_RI, c_EI, c_EP = self.c[0], self.c[1], self.c[3]
        lnM = np.log(Q / self.ERx2) - self.U34
        ln_RI, ln_EI = c_RI - 2.0 * lnM, c_EI - (2.0 / 15.0) * lnM          # film._ln_asymptotes_from
        ln_EP = c_EP - lnM / 12.0 + self.L34
        m4EI = -4.0 * ln_EI
        A4 = np.logaddexp(m4EI, self.m4h00)                                  # film._ln_branches
        RI15 = 1.5 * ln_RI
        A15 = np.logaddexp(RI15, 1.5 * (-0.25 * A4))                         # ln(H_RI^1.5 + H_EI'^1.5)
        a = (2.0 / 3.0) * A15
        m8EP = -8.0 * ln_EP
        A8 = np.logaddexp(self.m8RP, m8EP)
        b = -0.125 * A8
        r_ln = ln_EI - ln_RI
        r = np.exp(np.minimum(np.maximum(r_ln, -_NVM_EXP_MAX), _NVM_EXP_MAX))
        e12 = np.exp(-1.2 * r)
        s = 1.5 * (1.0 + e12)
        sa, sb = s * a, s * b
        As = np.logaddexp(sa, sb)
        ln_H = As / s
        # derivative: the shares of the blends
        wa, wb = np.exp(sa - As), np.exp(sb - As)
        p = np.exp(RI15 - A15)
        q = np.exp(m4EI - A4)
        t = np.exp(self.m8RP - A8)
        # ∂s/∂ln r = −1.8 r e^{−1.2 r} (where r is clipped, |ln r| ≥ 700, this is 0 to 1e-300 anyway)
        H_s = (wa * (a - ln_H) + wb * (b - ln_H)) / s * (-1.8 * r * e12)
        H_M = wa * (-2.0 * p - (2.0 / 15.0) * (1.0 - p) * q) - wb * (1.0 - t) / 12.0 + (28.0 / 15.0) * H_s
        return ln_H + self.lnRx + self.U12, H_M, (wa, wb, p, q, t, H_s, H_M)

    def grad(self, shares):
        """(∂ln h/∂ln R_x, ∂ln h/∂ln u) [-] from the ``shares`` an :meth:`ln_h` call returned."""
        wa, wb, p, q, t, H_s, H_M = shares
        H_L = wb * ((2.0 / 3.0) * t + 0.75 * (1.0 - t))
        dRI, dEI, dRP, dEP = _ln_asymptote_dconsts(self.D)
        H_D = (wa * (p * dRI + (1.0 - p) * (q * dEI - (1.0 - q))) + wb * (t * dRP + (1.0 - t) * dEP)
               + H_s * (dEI - dRI))
        return -1.25 * H_M - 0.25 * H_L + H_D + 0.5, -0.75 * H_M + 0.25 * H_L + 0.5


def _ln_asymptote_dconsts(D):
    """d c_k / d ln D of the D-parts of the NVM asymptotes (:func:`thermobear.lubrication.nvm.ln_asymptote_consts`),
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


def _carry(Q, G_lnQ, dG):
    """Loads Q [N] carried to first order to a point where the law's right-hand side has to change by dG
    [m] (G_lnQ = ∂G/∂ln Q [m] at Q): Q e^{dG / G_lnQ}, the exponent clipped to ±3 (a warm start only)."""
    with np.errstate(all="ignore"):
        d = dG / G_lnQ
    return Q * np.exp(np.clip(np.where(np.isfinite(d), d, 0.0), -3.0, 3.0))


def _residual(pos, sides, ln_s, lnH, dlnH, lnd):
    """(F, F') of :func:`_invert`'s logarithmic form at ln H, d ln H/dx and ln δ_el (``sides``: 1 every
    s > 0, −1 every s ≤ 0, 0 both: then per element by ``pos``)."""
    if sides > 0:
        T = np.logaddexp(ln_s, lnH)                     # ln(s + H)
        return lnd - T, 2.0 / 3.0 - np.exp(lnH - T) * dlnH
    if sides < 0:
        T = np.logaddexp(ln_s, lnd)                     # ln(δ_el − s)
        return T - lnH, (2.0 / 3.0) * np.exp(lnd - T) - dlnH
    Pl = np.where(pos, lnH, lnd)
    T = np.logaddexp(ln_s, Pl)                          # ln(s + H) or ln(δ_el − s)
    E = np.exp(Pl - T)                                  # H/(s + H) or δ_el/(δ_el − s), in (0, 1]
    return np.where(pos, lnd - T, T - lnH), np.where(pos, 2.0 / 3.0 - E * dlnH, (2.0 / 3.0) * E - dlnH)


def _invert(law: _FilmAt, s, alpha, Q0):
    r"""Solve G(Q) = s for Q > 0 per element at fixed contact angles (vectorised, bracketed Newton in x = ln Q).

    ``law``: the law at the angles (:class:`_FilmAt`); ``alpha`` (for messages); Q0 the warm start [N].
    Returns (Q, δ_el, h, dG/d ln Q, ∂G/∂α, h ∂ln h/∂ln u, iterations, relative law residual, fail), h and
    h ∂ln h/∂ln u per contact (last axis (inner, outer) when ``law.pair``), the residual the largest over
    the elements that did not fail, ``fail`` per element: 0 solved, 1 no load in [e^-600, e^40] N gives
    the approach, 2 not converged (:func:`invert_error` turns it into a NoConvergence).

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
    sides = 1 if pos.all() else -1 if not pos.any() else 0     # every s > 0, every s ≤ 0, or both
    ln_s = np.log(np.abs(s), out=np.full(s.shape, -np.inf), where=s != 0)   # −inf at s = 0: T = ln δ_el
    lo = np.full(x.shape, -np.inf)
    hi = np.full(x.shape, np.inf)
    cap = None
    done = np.zeros(x.shape, bool)
    fail = np.zeros(x.shape, np.int8)
    it = 0
    for it in range(1, 101):
        lnH, dlnH, ln_h, H_M, shares = law.ln_terms(x)
        F, dF = _residual(pos, sides, ln_s, lnH, dlnH, (2.0 / 3.0) * (x - law.lnK))
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
        if x.max() >= _LNQ_MAX or x.min() <= _LNQ_MIN:      # at an end of the range, the root beyond it
            out = (((x >= _LNQ_MAX) & (F < 0)) | ((x <= _LNQ_MIN) & (F > 0))) & ~done
            fail[out] = 1
            done |= out
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
    fail[~done] = 2
    dx = x - xev                       # the last step (≤ 1e-8, or ≤ 1e-13 max(1, |x|) after bisection)
    Q = np.exp(x)
    d_el = (Q / law.K) ** (2.0 / 3.0)
    h = np.exp(np.minimum(np.maximum(ln_h, -_NVM_EXP_MAX), _NVM_EXP_MAX))
    Ga, h_u = law.G_alpha(d_el, h, shares)
    if law.pair:
        h = np.exp(np.minimum(np.maximum(ln_h + H_M * dx[..., None], -_NVM_EXP_MAX), _NVM_EXP_MAX))
        hm = h * H_M
        hs, dG = h[..., 0] + h[..., 1], (2.0 / 3.0) * d_el - (hm[..., 0] + hm[..., 1])
    else:
        h = np.exp(np.minimum(np.maximum(ln_h + H_M * dx, -_NVM_EXP_MAX), _NVM_EXP_MAX))
        hs, dG = h, (2.0 / 3.0) * d_el - h * H_M
    rel = np.abs(d_el - hs - s) / (d_el + hs)
    fail[(fail == 0) & ~(rel <= 1e-9)] = 1      # e.g. a film beyond e^700 m (clipped): no load gives s
    rel_ok = rel[fail == 0]
    return Q, d_el, h, dG, Ga, h_u, it, float(rel_ok.max()) if rel_ok.size else 0.0, fail


def invert_error(fail, s, alpha, iterations):
    """The NoConvergence for the first contact :func:`_invert` could not solve (``fail`` its codes; s [m] and
    α [rad] of every contact, the ball index on axis 1)."""
    k = np.unravel_index(int(np.argmax(fail != 0)), fail.shape)
    if fail[k] == 1:
        msg = (f"film contact law: no load in [e^{_LNQ_MIN:g}, e^{_LNQ_MAX:g}] N gives the approach "
               f"s = {s[k]:.4g} m (ball {k[1]}, alpha = {alpha[k]:.4g} rad)")
    else:
        msg = (f"film contact law: per-ball inversion did not converge (ball {k[1]}, s = {s[k]:.4g} m) "
               f"after {iterations} iterations")
    return NoConvergence(msg, iterations=int(iterations), residual=float("nan"))


class _FilmLaw:
    r"""Film contact law of both contacts of every ball, on the (nb, 2Z) [inner | outer] layout.

    δ_c = (Q_c/K_c)^(2/3) − h_c(Q_c, α_c)   with h_c the NVM central film
    (:func:`thermobear.lubrication.film.film_thickness_nvm`) at R_x,c = (D/2)(1 ∓ γ'cos α_c), R_y,c, the mean
    entrainment speed u_c = v_c (d_m/2)(1 ∓ γ'cos α_c), v = (|ω − ω_cage|, ω_cage) (caged kinematics,
    :func:`thermobear.contact.kinematics.caged_ball_kinematics`, outer ring fixed), one η and α_p per case.
    :meth:`at` gives the law at fixed angles that :func:`thermobear.loads.filmlaw._invert` inverts."""

    def __init__(self, brg, eta, alpha_p, K=None, v=None):
        self.brg, self.eta, self.ap, self.K, self.v = brg, eta, alpha_p, K, v
        Z = brg.Z
        self.Ep = brg.E_prime
        self.gp = brg.D / brg.dm
        self.sgn = np.repeat([-1.0, 1.0], Z)
        self.Ry = np.repeat([brg.Ry_i, brg.Ry_o], Z)

    def take(self, m):
        """The per-case data of a subset of the batch (eta, alpha_p have shape (nb, 1))."""
        return _FilmLaw(self.brg, self.eta[m], self.ap[m])

    def bind(self, K, v):
        """The law with the contact constants K [N/m^1.5] and orbital speed factors v [rad/s] set
        (broadcast to (nb, 2Z))."""
        return _FilmLaw(self.brg, self.eta, self.ap, K, v)

    def at(self, alpha):
        r"""The law at contact angles α [rad], shape (nb, 2Z) (:class:`thermobear.loads.filmlaw._FilmAt`):
        R_x and u both ∝ 1 ∓ γ'cos α, ∂ln R_x/∂α = ∂ln u/∂α = ±γ' sin α / (1 ∓ γ'cos α); K held."""
        gc = self.sgn * (self.gp * np.cos(alpha))
        fac = 1.0 + gc
        dln = -self.sgn * (self.gp * np.sin(alpha)) / fac
        nvm = _NVMFixed(0.5 * self.brg.D * fac, self.Ry, self.v * (0.5 * self.brg.dm) * fac, self.eta, self.ap,
                        self.Ep)
        return _FilmAt(self.K, nvm, False, dln, dln)


@dataclass(frozen=True)
class FilmInputs:
    """Lubricant data of the film contact law: one temperature for every contact of a load case.

    Attributes
    ----------
    eta : array_like      dynamic viscosity at the inlets [Pa s], > 0 (scalar or one per load case)
    alpha_p : array_like  pressure–viscosity coefficient [1/Pa], ≥ 0 (scalar or one per load case)
    """

    eta: float
    alpha_p: float


def film_inputs(film, shape):
    """Validated η [Pa s] and α_p [1/Pa] of ``film`` (mapping or :class:`FilmInputs`), shape (nb, 1)."""
    if isinstance(film, FilmInputs):
        film = {"eta": film.eta, "alpha_p": film.alpha_p}
    if not hasattr(film, "keys") or set(film.keys()) != {"eta", "alpha_p"}:
        raise InputError("film", film, "None, FilmInputs(eta, alpha_p) or a dict with exactly the keys "
                         "'eta' [Pa s] and 'alpha_p' [1/Pa]")
    out = []
    for key, lo in (("eta", "> 0 [Pa s]"), ("alpha_p", ">= 0 [1/Pa]")):
        a = np.asarray(film[key], dtype=float)
        bad = ~np.isfinite(a) | ((a <= 0) if key == "eta" else (a < 0))
        if np.any(bad):
            raise InputError(f"film.{key}", film[key], f"must be finite and {lo}")
        try:
            a = np.broadcast_to(a, shape)
        except ValueError:
            raise InputError(f"film.{key}", film[key], f"must broadcast to the load batch {shape}") from None
        out.append(a.reshape(-1, 1).copy())
    return out
