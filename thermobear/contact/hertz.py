r"""Hertz point contact: exact solution with elliptic integrals and fast approximations.

Conventions (Harris 2001, ch. 6): x is the rolling direction, y the transverse one;
``Rx``, ``Ry`` are the reduced radii of curvature in those directions
(1/R = 1/r_ball + 1/r_race, concave race negative); ``a`` is the semi-axis
along y (across the groove), ``b`` the semi-axis along x (rolling);
ellipticity ``kappa = a/b``; E' the reduced modulus
2/E' = (1-ν1²)/E1 + (1-ν2²)/E2.  All inputs and outputs in SI.

Every function takes scalars or numpy arrays (broadcast together).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermobear.arrays import out as _f
from scipy.special import ellipe, ellipk

from thermobear.errors import InputError, NoConvergence
from thermobear.validity import check

__all__ = ["HertzContact", "hertz", "ellipticity", "contact_stiffness", "series_stiffness",
           "METHODS", "RATIO_MAX"]

METHODS = ("exact", "hamrock_brewe", "brewe_hamrock", "houpert")
#: Largest Ry/Rx of a contact [-]: beyond it the curvature difference F(ρ) = (Ry/Rx − 1)/(Ry/Rx + 1) is
#: within 2e-10 of 1, the ellipticity iteration's tolerance on F (:func:`ellipticity`).
RATIO_MAX = 1e10


@dataclass(frozen=True)
class HertzContact:
    """Result of a Hertz point-contact calculation (arrays broadcast from the inputs).

    Attributes
    ----------
    a : ndarray       semi-axis across the rolling direction (along y) [m]
    b : ndarray       semi-axis in the rolling direction (along x) [m]
    delta : ndarray   approach of the two bodies [m]
    p_max : ndarray   maximum (central) pressure [Pa]
    kappa : ndarray   ellipticity a/b [-]
    K : ndarray       load-deflection constant, Q = K delta^1.5 [N/m^1.5]
    Ek : ndarray      complete elliptic integral of the first kind K(m) [-]
    Ee : ndarray      complete elliptic integral of the second kind E(m) [-]
    R : ndarray       1/(1/Rx + 1/Ry), curvature-sum radius [m]
    """

    a: np.ndarray
    b: np.ndarray
    delta: np.ndarray
    p_max: np.ndarray
    kappa: np.ndarray
    K: np.ndarray
    Ek: np.ndarray
    Ee: np.ndarray
    R: np.ndarray


def _f_rho(kappa):
    """Curvature difference F(ρ) as a function of ellipticity κ ≥ 1 (Hertz 1881; Harris 2001 ch. 6)."""
    m = 1.0 - 1.0 / kappa**2
    Ee, Ek = ellipe(m), ellipk(m)
    return ((kappa**2 + 1.0) * Ee - 2.0 * Ek) / ((kappa**2 - 1.0) * Ee)


def _f_rho_and_slope(kappa):
    """F(ρ)(κ) and dF/d ln κ, from one evaluation of the complete elliptic integrals.

    With q = κ², m = 1 − 1/q (dm/d ln κ = 2/q), dE/dm = (E − K)/(2m) and
    dK/dm = (E − (1 − m) K)/(2m(1 − m)) (Abramowitz & Stegun 1964, 17.3.10–11)."""
    q = kappa * kappa
    m = 1.0 - 1.0 / q
    Ee, Ek = ellipe(m), ellipk(m)
    dE = (Ee - Ek) / (m * q)                       # dE/d ln κ
    dK = (Ee - Ek / q) / m                         # dK/d ln κ
    num = (q + 1.0) * Ee - 2.0 * Ek
    den = (q - 1.0) * Ee
    dnum = 2.0 * q * Ee + (q + 1.0) * dE - 2.0 * dK
    dden = 2.0 * q * Ee + (q - 1.0) * dE
    return num / den, (dnum * den - num * dden) / (den * den)


def ellipticity(ratio_RyRx, tol: float = 1e-13, maxiter: int = 50):
    r"""Exact ellipticity κ = a/b of a Hertz point contact [-].

    Parameters
    ----------
    ratio_RyRx : array_like   Ry/Rx ≥ 1 (transverse over rolling radius) [-]
    tol : float               convergence tolerance on ln κ [-]
    maxiter : int             maximum number of Newton steps

    Returns
    -------
    ndarray  κ ≥ 1 [-]

    Notes
    -----
    κ solves the curvature-difference equation of Hertz (1881) [1]_ [2]_

    .. math::

        F(\rho) = \frac{R_y - R_x}{R_y + R_x} = \frac{(\kappa^2 + 1)\,\mathcal{E}(m) - 2\,\mathcal{K}(m)}
        {(\kappa^2 - 1)\,\mathcal{E}(m)},\qquad m = 1 - 1/\kappa^2

    with 𝒦, ℰ the complete elliptic integrals of parameter m (``scipy.special.ellipk``/``ellipe``).
    Vectorised Newton iteration on ln κ, started at the Hamrock & Brewe (1983) [3]_ estimate
    κ ≈ 1.0339 (Ry/Rx)^0.636, with the analytic slope of F and a bracketing safeguard; raises
    NoConvergence rather than return an unconverged value.  Nearly circular contacts
    (Ry/Rx − 1 < 1e-4, where F cancels 0/0 in floating point) take the leading-order root
    κ = (Ry/Rx)^(2/3).

    References
    ----------
    .. [1] Hertz H. (1881) Über die Berührung fester elastischer Körper. J. reine angew. Math. 92, 156–171.
    .. [2] Harris T. A. (2001) Rolling Bearing Analysis, 4th ed., Wiley, ch. 6.
    .. [3] Hamrock B. J., Brewe D. E. (1983) Simplified solution for stresses and deformations.
           J. Lubr. Technol. 105, 171–177.

    Examples
    --------
    >>> round(float(ellipticity(1.0)), 12)
    1.0
    >>> round(float(ellipticity(165.1 / 5.109)), 3)   # inner contact of a 209 bearing (f = 0.52)
    9.285
    """
    r = np.asarray(ratio_RyRx, dtype=float)
    if r.size and not (r.min() >= 1.0 - 1e-12 and r.max() <= RATIO_MAX):    # NaN fails both
        raise InputError("Ry/Rx", r, f"must be >= 1 (swap axes for Ry < Rx) and <= {RATIO_MAX:g}: beyond, "
                         f"F(rho) = (Ry/Rx - 1)/(Ry/Rx + 1) lies within 2e-10 of 1, the iteration's tolerance, "
                         f"and kappa is not determined in double precision")
    target = (r - 1.0) / (r + 1.0)
    # nearly circular (Ry/Rx − 1 < 1e-4): F(ρ) cancels 0/0 in floating point; κ = (Ry/Rx)^(2/3)
    # is the leading-order solution there (relative error O((r − 1)²) < 1e-8)
    circ = target < 5e-5
    any_circ = bool(circ.any())
    lo = np.ones_like(r)
    hi = np.maximum(2.0 * r, 2.0)          # κ < Ry/Rx for any ellipse with Ry/Rx > 1
    t = np.log(np.maximum(1.0339 * np.maximum(r, 1.0) ** 0.6360, 1.0 + 1e-9))    # Hamrock–Brewe start
    f = None
    done = False
    for it in range(maxiter):
        k = np.where(circ, 2.0, np.exp(t)) if any_circ else np.exp(t)
        F, dFdt = _f_rho_and_slope(k)
        f = F - target
        lo = np.where(f < 0, np.maximum(lo, k), lo)
        hi = np.where(f > 0, np.minimum(hi, k), hi)
        t_new = t - f / np.where(dFdt > 0, dFdt, 1.0)
        k_new = np.exp(t_new)
        bad = (k_new <= lo) | (k_new >= hi) | ~np.isfinite(k_new)
        if bad.any():
            t_new = np.where(bad, np.log(0.5 * (lo + hi)), t_new)
        done = bool(np.all(np.abs(t_new - t) < tol) or (any_circ and np.all(circ)))
        t = t_new
        if done:
            break
    kappa = np.where(circ, np.maximum(r, 1.0) ** (2.0 / 3.0), np.exp(t)) if any_circ else np.exp(t)
    if done and np.all(np.abs(np.where(circ, 0.0, f)) <= 1e-11):
        return kappa         # converged: the residual at the last evaluation, one step < tol away, is tiny
    res = np.where(circ, 0.0, _f_rho(np.where(circ, 2.0, kappa)) - target)
    if np.any(np.abs(res) > 1e-10):
        raise NoConvergence("Hertz ellipticity iteration did not converge",
                            iterations=it + 1, residual=float(np.max(np.abs(res))), last=kappa)
    return kappa


def _check(name, v, positive=True):
    v = np.asarray(v, dtype=float)
    if v.size and not ((v.min() > 0 if positive else v.min() > -np.inf) and v.max() < np.inf):   # NaN fails
        raise InputError(name, v, "must be finite and > 0")
    return v


def _size(a_Ry, b_Rx):
    """The Hertz size limit (:data:`thermobear.validity.LIMITS` ``hertz_size``): a/Ry and b/Rx."""
    rel = np.maximum(a_Ry, b_Rx)
    check("hertz_size", rel, "Q, Rx, Ry, E_prime", what="semi-axes a/Ry, b/Rx")


def hertz(Q, Rx, Ry, E_prime, method: str = "exact") -> HertzContact:
    r"""Hertz elliptical point contact of two elastic bodies.

    Parameters
    ----------
    Q : array_like        normal load [N] (≥ 0; zero gives a zero-size contact)
    Rx : array_like       reduced radius in the rolling direction [m]
    Ry : array_like       reduced radius across the rolling direction [m]
    E_prime : array_like  reduced modulus E' [Pa]
    method : str          ``"exact"`` (elliptic integrals), ``"hamrock_brewe"``
                          (Hamrock & Brewe 1983), ``"brewe_hamrock"`` (1977, κ = (Ry/Rx)^(2/π)),
                          ``"houpert"`` (a, b after Houpert 1999, seed 000 eqs 9–10;
                          δ and K from Hamrock–Brewe)

    Returns
    -------
    HertzContact

    Notes
    -----
    With R = 1/(1/Rx + 1/Ry), m = 1 - 1/κ² (Hertz 1881; Harris 2001 ch. 6):

    a = (6 κ² E Q R / (π E'))^(1/3),  b = (6 E Q R / (π κ E'))^(1/3),
    δ = K(m) [ (9 / (2 E R)) (Q / (π κ E'))² ]^(1/3),  p_max = 3 Q / (2 π a b),
    Q = K δ^1.5 with K = π κ E' (2 E R / (9 K(m)³))^(1/2).

    Hamrock–Brewe: κ ≈ 1.0339 (Ry/Rx)^0.6360, E ≈ 1.0003 + 0.5968 Rx/Ry,
    K ≈ 1.5277 + 0.6023 ln(Ry/Rx).  Houpert: a ≈ 1.3085 Rx k^0.4091 W^(1/3),
    b ≈ 1.1502 Rx k^-0.1876 W^(1/3), k = Ry/Rx, W = Q/(E' Rx²).
    If Ry < Rx the roles of the axes are swapped internally (a still lies along y).

    Examples
    --------
    Inner contact of a 209 deep-groove bearing (D 12.7 mm, f 0.52, Harris 2001 ch. 6) at
    Q = 4527 N (exact solution: a 2.545 mm, b 0.2742 mm, δ 26.98 µm, p_max 3.097 GPa):

    >>> c = hertz(4527.0, 5.109e-3, 165.1e-3, 228e9)
    >>> round(c.a * 1e3, 3), round(c.b * 1e3, 4), round(c.delta * 1e6, 2), round(c.p_max / 1e9, 3)
    (2.545, 0.2742, 26.98, 3.097)
    """
    if method not in METHODS:
        raise InputError("hertz method", method, f"must be one of {', '.join(METHODS)}")
    Q = np.asarray(Q, dtype=float)
    if Q.size and not (Q.min() >= 0 and Q.max() < np.inf):                  # NaN fails both
        raise InputError("Q", Q, "normal load must be finite and >= 0 [N]")
    Rx, Ry, E_prime = _check("Rx", Rx), _check("Ry", Ry), _check("E_prime", E_prime)
    try:
        np.broadcast_shapes(Q.shape, Rx.shape, Ry.shape, E_prime.shape)
    except ValueError:
        raise InputError("Q, Rx, Ry, E_prime", f"shapes {Q.shape}, {Rx.shape}, {Ry.shape}, {E_prime.shape}",
                         "must broadcast together (numpy rules)") from None
    swap = Ry < Rx
    any_swap = bool(swap.any())
    r_big, r_small = (np.where(swap, Rx, Ry), np.where(swap, Ry, Rx)) if any_swap else (Ry, Rx)
    with np.errstate(over="ignore"):
        ratio = r_big / r_small                           # inf: refused next
    if ratio.size and not ratio.max() <= RATIO_MAX:
        raise InputError("Rx, Ry", ratio, f"the larger over the smaller radius must be <= {RATIO_MAX:g} "
                         "(beyond, the ellipticity is not determined in double precision: ellipticity)")
    R = r_small / (1.0 + 1.0 / ratio)                     # 1/(1/Rx + 1/Ry), without overflow
    if method == "exact":
        kappa = ellipticity(ratio)
        m = 1.0 - 1.0 / kappa**2
        Ek, Ee = ellipk(m), ellipe(m)
    elif method in ("hamrock_brewe", "houpert"):
        kappa = 1.0339 * ratio**0.6360
        Ee = 1.0003 + 0.5968 / ratio
        Ek = 1.5277 + 0.6023 * np.log(ratio)
    else:  # brewe_hamrock 1977
        kappa = ratio ** (2.0 / np.pi)
        Ee = 1.0 + (np.pi / 2.0 - 1.0) / ratio
        Ek = np.pi / 2.0 + (np.pi / 2.0 - 1.0) * np.log(ratio)
    # a = c Q^(1/3) with the load-free coefficients c, each factor a cube root of its own: a load near
    # zero or a modulus at the edge of the float range gives a tiny or huge contact, never 0 × ∞
    q = np.cbrt(Q)
    with np.errstate(over="ignore", divide="ignore", invalid="ignore"):    # beyond the float range: refused below
        if method == "houpert":                       # W^(1/3) = (Q/(E' r_small²))^(1/3)
            w = r_small / (np.cbrt(E_prime) * np.cbrt(r_small) ** 2)
            c_big, c_small = 1.3085 * ratio**0.4091 * w, 1.1502 * ratio**-0.1876 * w
        else:
            rE = np.cbrt(R / np.pi) / np.cbrt(E_prime)
            c_big, c_small = np.cbrt(6.0 * kappa**2 * Ee) * rE, np.cbrt(6.0 * Ee / kappa) * rE
        a_big, a_small = c_big * q, c_small * q
        K = np.pi * kappa * E_prime * np.sqrt(2.0 * Ee * R / (9.0 * Ek**3))
        delta = (q / np.cbrt(K)) ** 2                 # (Q/K)^(2/3)
        p_max = 1.5 / np.pi * (q / c_big) / c_small   # 3Q/(2π a b)
    if any_swap:
        a, b, kappa = np.where(swap, a_small, a_big), np.where(swap, a_big, a_small), np.where(swap, 1.0 / kappa, kappa)
    else:
        a, b = a_big, a_small
    _size(a / Ry, b / Rx)
    if not all(np.all(np.isfinite(v)) for v in (K, delta, p_max)):
        raise InputError("Q, Rx, Ry, E_prime", E_prime, "the contact's stiffness, approach or pressure exceeds "
                         "the floating-point range: the modulus or the radii are beyond any solid's")
    return HertzContact(*(_f(v) for v in (a, b, delta, p_max, kappa,
                                          K, Ek, Ee, R)))



def contact_stiffness(Rx, Ry, E_prime, method: str = "exact"):
    r"""Load–deflection constant K of one point contact, Q = K δ^1.5 [N/m^1.5].

    Notes
    -----
    K = π κ E' (2 E(m) R / (9 K(m)³))^(1/2) (Harris 2001 ch. 6, from δ of the exact Hertz solution).

    >>> round(float(contact_stiffness(5.109e-3, 165.1e-3, 228e9)) / 1e10, 3)
    3.231
    """
    return hertz(0.0, Rx, Ry, E_prime, method=method).K


def series_stiffness(K_i, K_o):
    r"""Combined ball stiffness of the inner and outer contacts in series [N/m^1.5].

    Notes
    -----
    K_n = [K_i^(-2/3) + K_o^(-2/3)]^(-3/2), so that Q = K_n (δ_i + δ_o)^1.5
    (Harris 2001 eq 7.3).

    >>> round(series_stiffness(3.231e10, 3.416e10) / 1e10, 3)
    1.174
    """
    K_i, K_o = np.asarray(K_i, dtype=float), np.asarray(K_o, dtype=float)
    out = (K_i ** (-2.0 / 3.0) + K_o ** (-2.0 / 3.0)) ** -1.5
    return float(out) if out.ndim == 0 else out
