r"""The hydrodynamic rolling-force formulas, one per model (pure, vectorised).

The dispatcher, the regime selection and the contacts prepared for repeated evaluation are in
:mod:`thermobear.losses.rolling`, which re-exports every public name of this module.

Each formula of the Biboulet & Houpert (2010) / seed 004 family is written once, split into its
speed-free coefficient (``_*_coeff``: load, radii, ellipse; computed once per contact set by
:class:`~thermobear.losses.rolling.RollingContacts`) and the power law in the speed (and
pressure–viscosity) parameter; the public functions below run both parts.

Conventions (those that reproduce the seeds' own numbers).  Two dimensionless speeds occur:

* seeds 000/001 write U = η u/(E' Rx) with the *mean* speed u, W = Q/(E' Rx²),
  k = Ry/Rx (radius ratio, ≥ 1 for ball–race contacts);
* Biboulet & Houpert 2010 and seed 004 write U_B = 2 η u/(E' Rx) (= 2U*), and
  κ = b/a ≤ 1 (ellipse ratio, rolling-direction over transverse semi-axis),
  β = (4/π) E(1-κ²)/(1 + Rx/Ry) ∈ [1, 4/π], Moes-type load parameter
  M_B = β^(1/4) κ W U_B^(-3/4), G = α_p E'.

The seed 000/001 transition parameter M = 0.5549 k^-0.6029 W U^-0.75 is B&H's
M_B re-expressed with the mean-speed U and a curve fit of κ(k) (checked:
0.1648 vs 0.168 at k = 17.7).

Zero load.  Every formula here is *load controlled*: the gap follows from Q, so
F_R → 0 as Q → 0 (W^(1/3) for Biboulet, W^0.364 for Houpert IVR, a ∝ Q^(1/3)
for the EHL/PVR forms) and is exactly 0 at Q = 0.  A ball in the unloaded zone
of a radial bearing is not at zero load in reality: its outer contact carries
the centrifugal force and its gap is set by the clearance, so it still brakes
(seed 004 finds those IVR contacts matter).  Pass the actual small load (e.g.
centrifugal force) of such contacts; do not rely on Q = 0 to model them.

References
----------
Biboulet N., Houpert L. (2010) Hydrodynamic force and moment in pure rolling
lubricated contacts. Part 2: point contacts. Proc. IMechE J 224, 777–787.
Seeds 000 (Ianuș et al.), 001 (Bălan et al. 2015), 004 (Darul et al. 2024).
"""
from __future__ import annotations

import numpy as np
from scipy.special import ellipe

from thermobear.arrays import above, out as _out, smooth_weight
from thermobear.contact.hertz import hertz
from thermobear.errors import InputError

__all__ = [
    "transition_parameter", "ehl_partition",
    "rolling_force_biboulet_ivr", "rolling_force_biboulet_ehl", "rolling_force_biboulet_transition",
    "rolling_force_biboulet_dominant", "DOMINANT_BAND",
    "biboulet_parameters", "truncation_coefficient",
    "rolling_force_houpert_ivr", "rolling_force_houpert_ehl", "rolling_force_biboulet_pvr",
]

_M_SPLIT = 6.6        # B&H 2010 eq 32 / seed 000 eq 20: transition at M = 6.6

#: EHL-partition band across which :func:`rolling_force_biboulet_dominant` passes from Biboulet's IVR
#: equation to the transition equation.  Seed 001 (§4.5, §5) draws the line where the EHL partition
#: passes 50 % and reports IVR-dominated runs with partitions of 20–60 % matched by the IVR equation and
#: EHL-dominated ones of 70–94 % by the transition equation; the ±10 % band around its 50 % is this
#: library's, so that the force has no step where the dominant regime changes.
DOMINANT_BAND = (0.4, 0.6)


# ----------------------------------------------------------------------------- helpers
def _num(name, v, *, strict=True, what=""):
    """``v`` (a Python float, or a float array) checked ≥ 0 (> 0 with ``strict``) with one comparison
    or one reduction, which NaN fails too; an infinite value passes (the formulas take it as their limit)."""
    if isinstance(v, float):
        ok, a = (v > 0 if strict else v >= 0), v
    else:
        a = np.asarray(v, dtype=float)
        ok = above(a, 0.0, strict)
    if not ok:
        raise InputError(name, v, f"must be finite and {'>' if strict else '>='} 0{what}")
    return a


def _inputs(Q, Rx, Ry, u, eta, E_prime):
    return (_num("Q", Q, strict=False, what=" [N]"), _num("Rx", Rx, what=" [m]"),
            _num("Ry", Ry, what=" [m]"), _num("u", u, strict=False, what=" (mean entrainment speed) [m/s]"),
            _num("eta", eta, what=" [Pa s]"), _num("E_prime", E_prime, what=" [Pa]"))


def _seed_groups(Q, Rx, Ry, u, eta, E_prime):
    """W, U (mean-speed convention), k = Ry/Rx of seeds 000/001."""
    return Q / (E_prime * Rx**2), eta * u / (E_prime * Rx), Ry / Rx


def _seed_forces(Q, Rx, Ry, u, eta, E_prime):
    """Biboulet's IVR and EHL forces (seed 000 eqs 21, 22) and 6.6/M (eq 23) of checked inputs:
    the one place these three formulas are written."""
    W, U, k = _seed_groups(Q, Rx, Ry, u, eta, E_prime)
    f_ivr = 2.9766 * E_prime * Rx**2 * k**0.3316 * np.cbrt(W) * np.cbrt(U) ** 2
    f_ehl = 7.5826 * E_prime * Rx**2 * k**0.4055 * np.cbrt(W) * U**0.75
    return f_ivr, f_ehl, _inv_M_seed(W, U, k)


def _transition(f_ivr, f_ehl, inv):
    """Biboulet's transition F_IVR/(1 + M/6.6) + (M/6.6)/(1 + M/6.6) F_EHL (seed 000 eq 20), ``inv`` = 6.6/M."""
    with np.errstate(invalid="ignore"):
        return np.where(np.isinf(inv), f_ivr, (f_ivr * inv + f_ehl) / (1.0 + inv))


def _partition(inv):
    """EHL partition (M/6.6)/(1 + M/6.6) of seed 000 eq 20 from ``inv`` = 6.6/M (0 where M = 0)."""
    return np.where(np.isinf(inv), 0.0, 1.0 / (1.0 + inv))


def _inv_M_seed(W, U, k):
    """6.6/M with M of seed 000 eq 23, finite everywhere (∞ where W = 0)."""
    num = _M_SPLIT * U**0.75
    den = 0.5549 * k**-0.6029 * W
    out = np.full(np.broadcast(num, den).shape, np.inf)
    np.divide(num, den, out=out, where=np.broadcast_to(den > 0, out.shape))
    return out


# ----------------------------------------------------------------------------- Biboulet (seeds 000/001)
def transition_parameter(Q, Rx, Ry, u, eta, E_prime):
    r"""IVR→EHL transition parameter M of Biboulet & Houpert (seed 000 eq 23).

    Parameters
    ----------
    Q : array_like        normal load [N]
    Rx, Ry : array_like   reduced radii in / across the rolling direction [m]
    u : array_like        mean entrainment speed (u1 + u2)/2 [m/s]
    eta : array_like      dynamic viscosity at the inlet [Pa s]
    E_prime : array_like  reduced modulus E' [Pa]

    Returns
    -------
    M [-]; ∞ where u = 0 and W > 0, 0 where Q = 0.

    Notes
    -----
    M = 0.5549 k^-0.6029 W U^-0.75, k = Ry/Rx, W = Q/(E' Rx²), U = η u/(E' Rx)
    (seed 000 eq 23; seed 001 eq 4 lost its minus signs in OCR).

    Examples
    --------
    Seed 001 §4.4, d = 6.35 mm, Q = 0.125 N, η = 0.05 Pa s, 60 rpm, r = 18 mm:

    >>> Rx, Ry = 3.175e-3, 4.16e-3 * 3.175e-3 / (4.16e-3 - 3.175e-3)
    >>> round(transition_parameter(0.125, Rx, Ry, 2 * 3.14159265 * 0.018 / 2, 0.05, 2.3e11), 2)
    4.56
    """
    Q, Rx, Ry, u, eta, E_prime = _inputs(Q, Rx, Ry, u, eta, E_prime)
    W, U, k = _seed_groups(Q, Rx, Ry, u, eta, E_prime)
    inv = _inv_M_seed(W, U, k)
    with np.errstate(divide="ignore"):
        M = np.where(W > 0, _M_SPLIT / inv, 0.0)
    return _out(M)


def ehl_partition(Q, Rx, Ry, u, eta, E_prime):
    r"""EHL share (M/6.6)/(1 + M/6.6) of the Biboulet transition (seed 000 eq 20) [-].

    Parameters as :func:`transition_parameter`.  0 at Q = 0, 1 at u = 0 (Q > 0).

    Examples
    --------
    Seed 001 §4.4 states 41 % at 60 rpm and 21 % at 210 rpm (d 6.35 mm, Q 0.125 N):

    >>> Rx, Ry = 3.175e-3, 4.16e-3 * 3.175e-3 / (4.16e-3 - 3.175e-3)
    >>> [round(ehl_partition(0.125, Rx, Ry, w * 0.018 / 2, 0.05, 2.3e11), 2) for w in (6.2832, 21.991)]
    [0.41, 0.21]
    """
    Q, Rx, Ry, u, eta, E_prime = _inputs(Q, Rx, Ry, u, eta, E_prime)
    W, U, k = _seed_groups(Q, Rx, Ry, u, eta, E_prime)
    return _out(_partition(_inv_M_seed(W, U, k)))


def rolling_force_biboulet_ivr(Q, Rx, Ry, u, eta, E_prime):
    r"""Hydrodynamic rolling force, iso-viscous rigid regime, fully flooded [N].

    Parameters
    ----------
    Q : array_like        normal load [N]
    Rx, Ry : array_like   reduced radii in / across the rolling direction [m]
    u : array_like        mean entrainment speed [m/s]
    eta : array_like      dynamic viscosity at the inlet [Pa s]
    E_prime : array_like  reduced modulus E' [Pa]

    Returns
    -------
    Force opposing rolling on each surface [N].

    Notes
    -----
    F = 2.9766 E' Rx² k^0.3316 W^(1/3) U^(2/3), k = Ry/Rx, W = Q/(E' Rx²),
    U = η u/(E' Rx)  (Biboulet & Houpert 2010 eq 31 re-fitted; seed 000 eq 21,
    seed 001 eq 1).  Power of the contact: 2 u F.

    Examples
    --------
    Seed 000 contact at 100 rpm (η 0.089 Pa s):

    >>> round(rolling_force_biboulet_ivr(1.42, 3.969e-3, 70.1e-3, 0.0942, 0.089, 2.3e11), 5)
    0.00897
    """
    return _out(_seed_forces(*_inputs(Q, Rx, Ry, u, eta, E_prime))[0])


def rolling_force_biboulet_ehl(Q, Rx, Ry, u, eta, E_prime):
    r"""Hydrodynamic rolling force, elastohydrodynamic regime, fully flooded [N].

    Parameters as :func:`rolling_force_biboulet_ivr`.

    Notes
    -----
    F = 7.5826 E' Rx² k^0.4055 W^(1/3) U^(3/4)  (B&H 2010 eq 31 EHL asymptote
    re-fitted; seed 000 eq 22, seed 001 eq 2).

    Examples
    --------
    >>> round(rolling_force_biboulet_ehl(1.42, 3.969e-3, 70.1e-3, 0.0942, 0.089, 2.3e11), 5)
    0.0034
    """
    return _out(_seed_forces(*_inputs(Q, Rx, Ry, u, eta, E_prime))[1])


def rolling_force_biboulet_transition(Q, Rx, Ry, u, eta, E_prime):
    r"""Hydrodynamic rolling force with Biboulet's IVR→EHL transition [N].

    Parameters as :func:`rolling_force_biboulet_ivr`.

    Notes
    -----
    F = F_IVR/(1 + M/6.6) + (M/6.6)/(1 + M/6.6) F_EHL, with M from
    :func:`transition_parameter` (seed 000 eqs 20–23; seed 001 eqs 3, 5).
    Tends to F_IVR as M → 0 and to F_EHL as M → ∞.

    Examples
    --------
    Seed 000 Table 1 prints F_R = 0.59e-2 N at 100 rpm:

    >>> round(rolling_force_biboulet_transition(1.42, 3.969e-3, 70.12e-3, 0.094248, 0.089, 2.3e11), 5)
    0.00605
    """
    return _out(_transition(*_seed_forces(*_inputs(Q, Rx, Ry, u, eta, E_prime))))


def rolling_force_biboulet_dominant(Q, Rx, Ry, u, eta, E_prime):
    r"""Hydrodynamic rolling force by the dominant regime: Biboulet's IVR equation where IVR dominates,
    his transition equation where EHL does (Bălan et al. 2015) [N].

    Parameters as :func:`rolling_force_biboulet_ivr`.

    Returns
    -------
    Force opposing rolling on each surface [N].

    Notes
    -----
    Bălan et al. (2015) [1]_ compare the spin-down torques of 3, 3.97 and 6.35 mm balls with Biboulet's
    IVR equation and his IVR→EHL transition equation: "a good correlation was obtained [with the
    transition equations] when the dominant lubrication regime was EHL.  When the dominant regime was IVR,
    the experimental total friction torque was in good correlation with Biboulet's IVR equation" (§5;
    §4.5: the transition equation, written for fully flooded inlets, where the EHL partition exceeds
    50 %).  With the EHL partition :math:`p = (M/6.6)/(1 + M/6.6)` (:func:`ehl_partition`) and the C¹
    smoothstep :math:`w(p)` of :data:`DOMINANT_BAND` (this library's band around the paper's 50 %):

    .. math:: F = (1 - w)\,F_{IVR} + w\,F_{transition}

    The rule is the paper's conclusion from these same spin-down runs: scored on them
    (validation/report/seed001_spin_down.md) it reproduces the paper's model, it is not an independent
    prediction.

    References
    ----------
    .. [1] Bălan M.R.D., Stamate V.C., Houpert L., Olaru D.N. (2015) Rolling friction torque in
       ball-race contacts operating in mixed lubrication conditions. Lubricants 3, 222–243, §4.5, §5.

    Examples
    --------
    Seed 001 Table 2 (d 6.35 mm, Q 0.125 N, η 0.05 Pa s, r 18 mm): at 120 rpm the EHL partition is
    29 %, the IVR equation's force; with 0.633 N on 3 mm balls (partition 91 %) the transition's:

    >>> Rx, Ry = 3.175e-3, 4.16e-3 * 3.175e-3 / (4.16e-3 - 3.175e-3)
    >>> u = 4 * 3.14159265 * 0.018 / 2
    >>> F = rolling_force_biboulet_dominant(0.125, Rx, Ry, u, 0.05, 2.3e11)
    >>> bool(F == rolling_force_biboulet_ivr(0.125, Rx, Ry, u, 0.05, 2.3e11))
    True
    """
    f_ivr, f_ehl, inv = _seed_forces(*_inputs(Q, Rx, Ry, u, eta, E_prime))
    f_tr = _transition(f_ivr, f_ehl, inv)
    w = smooth_weight(_partition(inv), *DOMINANT_BAND)
    return _out(f_ivr + w * (f_tr - f_ivr))


# ----------------------------------------------------------------------------- B&H 2010 / seed 004
def _checked_geometry(Q, Rx, Ry, u, E_prime, a, b):
    """Checked geometry of the B&H forms and its temperature-free groups: (Q, Rx, Ry, u, E_prime,
    a, kappa, beta) with κ = b/a and β of :func:`biboulet_parameters`."""
    Q = _num("Q", Q, strict=False, what=" [N]")
    Rx, Ry = _num("Rx", Rx, what=" [m]"), _num("Ry", Ry, what=" [m]")
    u = _num("u", u, strict=False, what=" (mean entrainment speed) [m/s]")
    E_prime = _num("E_prime", E_prime, what=" [Pa]")
    if (a is None) != (b is None):
        raise InputError("a, b", (a, b), "give both Hertz semi-axes or neither")
    if a is None:
        geo = hertz(1.0, Rx, Ry, E_prime)           # κ does not depend on load
        kappa = geo.b / geo.a
        a = geo.a * np.cbrt(Q)                      # a ∝ Q^(1/3)
    else:
        a = _num("a", a, strict=False, what=" (Hertz semi-axis across rolling) [m]")
        b = _num("b", b, strict=False, what=" (Hertz semi-axis along rolling) [m]")
        touching = a > 0
        kappa = np.where(touching, b / np.where(touching, a, 1.0), 1.0)
        if np.max(kappa) > 1.0 + 1e-12:
            raise InputError("b/a", kappa, "must be <= 1 (b along rolling is the short semi-axis; "
                             "formulas fitted for Ry >= Rx)")
    beta = (4.0 / np.pi) * ellipe(1.0 - kappa**2) / (1.0 + Rx / Ry)
    return Q, Rx, Ry, u, E_prime, a, kappa, beta


def _checked_bib(Q, Rx, Ry, u, eta, E_prime, a, b):
    """:func:`_checked_geometry` and the checked viscosity: (W, U2, Rx, Ry, E_prime, a, kappa, beta)."""
    Q, Rx, Ry, u, E_prime, a, kappa, beta = _checked_geometry(Q, Rx, Ry, u, E_prime, a, b)
    eta = _num("eta", eta, what=" [Pa s]")
    return Q / (E_prime * Rx**2), 2.0 * eta * u / (E_prime * Rx), Rx, Ry, E_prime, a, kappa, beta


def biboulet_parameters(Q, Rx, Ry, u, eta, E_prime, a=None, b=None):
    r"""Dimensionless groups of Biboulet & Houpert 2010 (their eqs 13–14, 41).

    Parameters
    ----------
    Q, Rx, Ry, u, eta, E_prime : as :func:`rolling_force_biboulet_ivr`
    a, b : array_like, optional   Hertz semi-axes across / along rolling [m];
                                  computed with :func:`thermobear.contact.hertz.hertz` (exact) if omitted

    Returns
    -------
    dict with
      ``U2``    2 η u/(E' Rx), B&H's U (= seed 004's 2U*) [-]
      ``W``     Q/(E' Rx²) [-]
      ``kappa`` b/a ≤ 1, ellipse ratio (B&H's κ, seed 004's k) [-]
      ``beta``  (4/π) E(1-κ²)/(1 + Rx/Ry) ∈ [1, 4/π] [-]
      ``M``     β^(1/4) κ W U2^(-3/4), Moes load parameter of B&H [-] (0 at Q = 0, ∞ at u = 0)
      ``a``, ``b``  semi-axes [m]

    Notes
    -----
    .. math::

        U = \frac{2 \eta u}{E' R_x},\quad W = \frac{Q}{E' R_x^2},\quad \kappa = \frac{b}{a},\quad
        \beta = \frac{4}{\pi} \frac{\mathcal{E}(1 - \kappa^2)}{1 + R_x/R_y},\quad
        M = \beta^{1/4} \kappa W U^{-3/4}

    (Biboulet & Houpert 2010 [1]_ eqs 13–14, 41).  Seed 004 writes N = W (2U*)^(-3/4) (Rx/Ry)^(1/2)
    (its eq 9) in the transition of eq 19 and M in c_Bib; both are B&H's M here (B&H 2010 eq 14,
    the source of eq 19).  (Rx/Ry)^(1/2) vs β^(1/4)κ differ by ~30 % at k ≈ 18.

    References
    ----------
    .. [1] Biboulet N., Houpert L. (2010) Proc. IMechE J 224, 777–787.

    Examples
    --------
    >>> p = biboulet_parameters(1.42, 3.969e-3, 70.12e-3, 0.0942, 0.089, 2.3e11)
    >>> round(p["kappa"], 3), round(p["beta"], 3), round(p["M"], 2)
    (0.156, 1.245, 7.27)
    """
    W, U2, Rx, Ry, E_prime, a, kappa, beta = _checked_bib(Q, Rx, Ry, u, eta, E_prime, a, b)
    with np.errstate(divide="ignore", invalid="ignore"):
        M = np.where(W > 0, beta**0.25 * kappa * W / U2**0.75, 0.0)
    return {"U2": _out(U2), "W": _out(W), "kappa": _out(kappa), "beta": _out(beta), "M": _out(M),
            "a": _out(a), "b": _out(kappa * a)}


def _c_bib(M, kappa):
    """c of B&H 2010 eq 36 (seed 004's c_Bib): the truncation coefficient at 2a/L = 1 (0 at M = 0:
    the caller silences the division by zero there)."""
    return 0.85 / (1.0 + 4.72 * M**-0.39 * kappa ** (0.484 * M**0.165))


def truncation_coefficient(M, kappa, ratio_2a_L=1.0):
    r"""Truncation coefficient C of the B&H point-contact rolling moment [-].

    Parameters
    ----------
    M : array_like           B&H load parameter M_B [-] (∞ allowed)
    kappa : array_like       ellipse ratio b/a ≤ 1 [-]
    ratio_2a_L : array_like  contact length 2a over the width available to the
                             film (race width or ball diameter) [-]; capped at 1

    Returns
    -------
    C ∈ (0, 1] [-]

    Notes
    -----
    .. math::

        C = \frac{1}{1 + (1/c - 1)\,(2a/L)^{(2 - \kappa)(0.0018 M + 1.33)}},\qquad
        c = \frac{0.85}{1 + 4.72\, M^{-0.39} \kappa^{0.484 M^{0.165}}}

    (Biboulet & Houpert 2010 [1]_ eqs 35–36).  c (value at 2a/L = 1) is seed 004's c_Bib of
    eq 19.  B&H fitted it on EHL runs only (0.2 ≤ M ≤ 800); c → 0 as M → 0.

    References
    ----------
    .. [1] Biboulet N., Houpert L. (2010) Proc. IMechE J 224, 777–787.

    Examples
    --------
    >>> round(truncation_coefficient(7.27, 0.156), 3), truncation_coefficient(7.27, 0.156, 0.0)
    (0.523, 1.0)
    """
    M = np.asarray(M, dtype=float)
    if np.any(np.isnan(M)) or np.any(M < 0):
        raise InputError("M", M, "must be >= 0 (inf allowed: zero speed)")
    kappa = _num("kappa", kappa, what=" (b/a)")
    r = np.minimum(_num("2a/L", ratio_2a_L, strict=False), 1.0)
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
        c = np.where(M > 0, _c_bib(M, kappa), 0.0)
        inv_c = np.where(c > 0, 1.0 / np.where(c > 0, c, 1.0) - 1.0, np.inf)
        C = np.where(r > 0, 1.0 / (1.0 + inv_c * r ** ((2.0 - kappa) * (0.0018 * M + 1.33))), 1.0)
    return _out(C)


def _houpert_ivr_coeff(W, Rx, Ry, E_prime):
    """Houpert's IVR force at U2 = 1 [N]: F = C U2^0.636 (:func:`rolling_force_houpert_ivr`)."""
    return 0.835 * (Rx / Ry) ** -0.358 * W**0.364 * E_prime * Rx**2


def _houpert_ivr(C, U2):
    """Houpert's IVR force from its coefficient :func:`_houpert_ivr_coeff` and U2 [N]."""
    return C * U2**0.636


def rolling_force_houpert_ivr(Q, Rx, Ry, u, eta, E_prime):
    r"""Houpert's IVR hydrodynamic rolling force (moderately starved) [N].

    Parameters as :func:`rolling_force_biboulet_ivr` (u is the mean speed).

    Notes
    -----
    .. math::

        F = 0.835\, \lambda^{-0.358} W^{0.364} (2U^*)^{0.636} E' R_x^2,\qquad
        \lambda = R_x/R_y,\ U^* = \frac{\eta u}{E' R_x},\ W = \frac{Q}{E' R_x^2}

    (seed 004 eq 17; Biboulet & Houpert 2010 [1]_ eq 28, a re-fit of Houpert 1987).  B&H 2010
    report it ≈ 0.6 × their fully-flooded IVR.

    References
    ----------
    .. [1] Biboulet N., Houpert L. (2010) Proc. IMechE J 224, 777–787.

    Examples
    --------
    >>> round(rolling_force_houpert_ivr(1.42, 3.969e-3, 70.12e-3, 0.0942, 0.089, 2.3e11), 5)
    0.00585
    """
    Q, Rx, Ry, u, eta, E_prime = _inputs(Q, Rx, Ry, u, eta, E_prime)
    W, U2 = Q / (E_prime * Rx**2), 2.0 * eta * u / (E_prime * Rx)
    return _out(_houpert_ivr(_houpert_ivr_coeff(W, Rx, Ry, E_prime), U2))


def _houpert_ehl_coeff(W, Rx, E_prime, a, kappa):
    """Houpert's EHL force at G = U2 = 1 [N]: F = C G^0.022 U2^0.656 (:func:`rolling_force_houpert_ehl`)."""
    return 0.674 * kappa**-0.043 * (2.0 * a / Rx) * (kappa * W) ** 0.133 * E_prime * Rx**2


def _houpert_ehl(C, G, U2, g_exponent=0.022):
    """Houpert's EHL force from its coefficient :func:`_houpert_ehl_coeff`, G and U2 [N]."""
    return C * G**g_exponent * U2**0.656


def rolling_force_houpert_ehl(Q, Rx, Ry, u, eta, E_prime, alpha_p, a=None, b=None, *,
                              g_exponent=0.022):
    r"""Houpert's EHL hydrodynamic rolling force [N].

    Parameters
    ----------
    Q, Rx, Ry, u, eta, E_prime : as :func:`rolling_force_biboulet_ivr`
    alpha_p : array_like   pressure–viscosity coefficient [1/Pa]
    a, b : array_like, optional   Hertz semi-axes across / along rolling [m] (exact Hertz if omitted)
    g_exponent : float     exponent of G (see Notes)

    Notes
    -----
    .. math::

        F = 0.674\, \kappa^{-0.043} \frac{2a}{R_x} G^{0.022} (\kappa W)^{0.133} (2U^*)^{0.656} E' R_x^2,
        \qquad \kappa = b/a,\ G = \alpha_p E'

    (Biboulet & Houpert 2010 [1]_ eq 29; seed 004 eq 18).  Seed 004 prints G*^0.22; B&H 2010 (its
    source) gives 0.022 in both forms of eq 29 and in the text ("piezoviscosity has almost no
    influence with a power 0.022").  At G ≈ 4600 the misprint would multiply F by 5.3.  We use 0.022.

    References
    ----------
    .. [1] Biboulet N., Houpert L. (2010) Proc. IMechE J 224, 777–787.

    Examples
    --------
    >>> round(rolling_force_houpert_ehl(1.42, 3.969e-3, 70.12e-3, 0.0942, 0.089, 2.3e11, 2.5e-8), 5)
    0.00198
    """
    if alpha_p is None:
        raise InputError("alpha_p", None, "pressure-viscosity coefficient [1/Pa] is required by houpert_ehl")
    alpha_p = _num("alpha_p", alpha_p, what=" [1/Pa]")
    W, U2, Rx, Ry, E_prime, a, kappa, beta = _checked_bib(Q, Rx, Ry, u, eta, E_prime, a, b)
    return _out(_houpert_ehl(_houpert_ehl_coeff(W, Rx, E_prime, a, kappa), alpha_p * E_prime, U2, g_exponent))


def _biboulet_pvr_coeffs(W, Rx, E_prime, a, kappa, beta, moving):
    """Speed-free factors of Biboulet's PVR force (:func:`rolling_force_biboulet_pvr`): E' Rx 2a
    (0 where masked), 0.77 β^(-1/3) κ^0.12, 1.8 β^(-1/4), den = β^(1/4) κ W (M = den U2^(-3/4); 1 where
    masked), 1 where masked (W = 0 or not ``moving``: u = 0) else 0, κ and 2a."""
    den = beta**0.25 * kappa * W
    ok = (den > 0) & moving
    return (E_prime * Rx * 2.0 * a * ok, 0.77 * beta ** (-1.0 / 3.0) * kappa**0.12, 1.8 * beta**-0.25,
            np.where(ok, den, 1.0), 1.0 - ok, kappa, 2.0 * a)


def _biboulet_pvr(coeffs, U2, truncation="seed004"):
    """Biboulet's PVR force from :func:`_biboulet_pvr_coeffs` and U2 [N]; 0 where W = 0 or U2 = 0."""
    C, c_ivr, c_ehl, den, masked, kappa, two_a = coeffs
    q = U2**0.75
    M = den / (q + masked)                                                # masked contacts: any M > 0
    r = _M_SPLIT / M                                                      # r = 6.6/M
    shape = (c_ivr * np.cbrt(U2) ** 2 * r + c_ehl * q) / (1.0 + r)        # ×(2a/Rx) E'Rx²: C
    if truncation is None:
        c = 1.0
    elif isinstance(truncation, str):
        if truncation != "seed004":
            raise InputError("truncation", truncation, "must be 'seed004', None or a width L [m]")
        c = _c_bib(M, kappa)
    else:
        L = _num("truncation", truncation, what=" (width L for 2a/L) [m]")
        c = truncation_coefficient(M, kappa, two_a / L)
    return C * shape * c                                                  # C = 0 where masked


def rolling_force_biboulet_pvr(Q, Rx, Ry, u, eta, E_prime, a=None, b=None, *,
                               truncation="seed004"):
    r"""Biboulet's single IVR→EHL (PVR) hydrodynamic rolling force [N].

    Parameters
    ----------
    Q, Rx, Ry, u, eta, E_prime : as :func:`rolling_force_biboulet_ivr`
    a, b : array_like, optional   Hertz semi-axes across / along rolling [m] (exact Hertz if omitted)
    truncation : ``"seed004"``, ``None`` or float
        ``"seed004"``: multiply by c_Bib (B&H eq 36, seed 004 eq 19);
        ``None``: fully flooded, untruncated (B&H eq 32);
        float L [m]: B&H eq 35 truncation with 2a/L (L race width or ball diameter).

    Notes
    -----
    .. math::

        F = c\, E' R_x (2a) \left[\frac{0.77 \beta^{-1/3} \kappa^{0.12} U^{-1/12} - 1.8 \beta^{-1/4}}
        {1 + M/6.6} + 1.8 \beta^{-1/4}\right] U^{3/4}

    with U = 2 η u/(E' Rx), κ = b/a, β, M from :func:`biboulet_parameters`
    (Biboulet & Houpert 2010 [1]_ eq 32; seed 004 eq 19).  Seed 004 prints "E' Rx² 2a", which is
    not a force; B&H write E' Rx² (2a/Rx).  Limits of the untruncated form:
    M → 0 gives B&H's IVR asymptote 0.77 β^(-1/3) κ^0.12 (2a/Rx) U^(2/3) E' Rx²,
    M → ∞ the EHL asymptote 1.8 β^(-1/4) (2a/Rx) U^(3/4) E' Rx² — the forms that
    seed 000 eqs 21–22 re-fit in k = Ry/Rx (agreement within a few %).
    With seed 004's c_Bib the force tends to 0.85 × EHL asymptote at large M and
    to 0 as M → 0 (c ∝ M^0.39): it does *not* reach the IVR form; c_Bib is B&H's
    truncation coefficient at 2a/L = 1 (ellipse as wide as the race), fitted
    on EHL runs only.

    References
    ----------
    .. [1] Biboulet N., Houpert L. (2010) Proc. IMechE J 224, 777–787.

    Examples
    --------
    >>> args = (1.42, 3.969e-3, 70.12e-3, 0.0942, 0.089, 2.3e11)
    >>> round(rolling_force_biboulet_pvr(*args, truncation=None), 5)
    0.00607
    >>> round(rolling_force_biboulet_pvr(*args), 5)
    0.00317
    """
    W, U2, Rx, Ry, E_prime, a, kappa, beta = _checked_bib(Q, Rx, Ry, u, eta, E_prime, a, b)
    return _out(_biboulet_pvr(_biboulet_pvr_coeffs(W, Rx, E_prime, a, kappa, beta, U2 > 0), U2, truncation))
