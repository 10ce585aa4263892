r"""Nijenbanning–Venner–Moes (1994) central film asymptotes, their blend, the Moes regime map.

Moes' dimensionless groups (sum-velocity convention, Moes 1992): M = W (2U)^(-3/4) (load),
L = G (2U)^(1/4) (lubricant), D = Rx/Ry ≤ 1, with the Hamrock groups U = η u/(E' Rx) (u the mean
entrainment speed), G = α_p E', W = Q/(E' Rx²).  The four asymptotic central films (rigid /
elastic × iso- / piezo-viscous) and their blend are those of Nijenbanning, Venner & Moes (1994);
the regime of a contact is the dominant term of the blend (seed 004 §3.2 rebuilds the Moes map
the same way).  Computed in logarithms, so that M → 0 or ∞ gives no overflow.  The functions of
:mod:`thermobear.lubrication.film` that start from loads and speeds use these.

References
----------
Moes H. (1992) Optimum similarity analysis with applications to elastohydrodynamic lubrication.
Wear 159, 57–66.
Nijenbanning G., Venner C. H., Moes H. (1994) Film thickness in elastohydrodynamically lubricated
elliptic contacts. Wear 176, 217–229.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermobear.arrays import above, finite_range
from thermobear.errors import InputError

__all__ = ["REGIMES", "TINY", "EXP_MAX", "moes_N", "ln_asymptote_consts", "nvm_asymptotes", "nvm_H", "Regime",
           "moes_regime", "MoesMapBoundaries", "moes_map_boundaries"]

REGIMES = ("IVR", "IVE", "PVR", "EHL")
_REGIME_CODES = np.array(REGIMES, dtype="<U3")

#: Floor inside the logarithms of the Moes groups (zero load / zero speed limits) [-].
TINY = 1e-300
#: Clip of exponents so that ratios stay finite (e^700 ≈ 1e304) [-].
EXP_MAX = 700.0


# ---------------------------------------------------------------------------
# input checks: one comparison per number, one reduction per array
# ---------------------------------------------------------------------------
def _arr(name, v, *, positive=False, nonneg=False):
    """``v`` as a float (a Python float) or float array, checked: > 0 (``positive``), >= 0
    (``nonneg``) by its minimum alone, which NaN fails too (an infinite value passes: the formulas
    take it as their limit); otherwise finite."""
    if type(v) is float:                  # one number: plain comparisons, no array
        lo = hi = v
    else:
        a = np.asarray(v, dtype=float)
        if not a.size:
            return a
        if positive or nonneg:
            if above(a, 0.0, strict=positive):
                return a
            lo, hi = a.min(), 0.0
        else:
            r = finite_range(a)
            lo, hi = r if r is not None else (np.nan, np.nan)
        v = a
    if not (lo > 0 if positive else lo >= 0 if nonneg else -np.inf < lo and hi < np.inf):
        raise InputError(name, v, "must be > 0" if positive else "must be >= 0" if nonneg else "must be finite")
    return v


def _out(x, *inputs):
    x = np.asarray(x, dtype=float)
    return float(x) if all(np.ndim(i) == 0 for i in inputs) else x


# ---------------------------------------------------------------------------
# NVM asymptotes and blend
# ---------------------------------------------------------------------------
def moes_N(M, D):
    r"""Seed 004's load parameter N = M D^(1/2) = W (2U)^(-3/4) λ^(1/2), λ = Rx/Ry.

    Parameters
    ----------
    M : array_like  Moes load parameter [-]
    D : array_like  Rx/Ry (seed 004's λ) [-]

    Returns
    -------
    ndarray  N [-]

    Notes
    -----
    Seed 004 eq 9 prints N = W* (2U*)^(3/4) λ^(1/2); the exponent of 2U* must
    be −3/4 (a minus sign lost in the text): N is used as a load parameter in
    the Biboulet PVR transition N/6.6 (seed 004 eq 19), which seed 000 eq 23
    writes M = 0.5549 k^-0.6029 W U^-0.75 — load over a power of speed.  With
    +3/4 N would grow with speed.

    Examples
    --------
    >>> round(moes_N(8064.0, 0.0309), 1)
    1417.5
    """
    return _out(np.asarray(M, dtype=float) * np.sqrt(np.asarray(D, dtype=float)), M, D)


def ln_asymptote_consts(D):
    r"""The D-dependent parts of the logarithms of the four NVM asymptotes and of the h00 cap.

    Parameters
    ----------
    D : array_like  Rx/Ry, 0 < D ≤ 1 [-]

    Returns
    -------
    (c_RI, c_EI, c_RP, c_EP, ln_h00) : tuple of ndarray  [-]

    Notes
    -----
    With these constants the asymptotes of :func:`nvm_asymptotes` are

    .. math::

        \ln H_{RI} = c_{RI} - 2 \ln M,\quad \ln H_{EI} = c_{EI} - \tfrac{2}{15} \ln M,\quad
        \ln H_{RP} = c_{RP} + \tfrac{2}{3} \ln L,\quad
        \ln H_{EP} = c_{EP} - \tfrac{1}{12} \ln M + \tfrac{3}{4} \ln L

    and h00 = 1.8 D^-1 (Nijenbanning, Venner & Moes 1994 [1]_).  A caller evaluating many loads or
    temperatures at one geometry (e.g. the film load model, :mod:`thermobear.loads.film`) computes
    them once.

    References
    ----------
    .. [1] Nijenbanning G., Venner C. H., Moes H. (1994) Wear 176, 217–229.

    Examples
    --------
    >>> [round(float(c), 3) for c in ln_asymptote_consts(1.0)]
    [3.722, 0.883, -0.096, 0.221, 0.588]
    """
    lnD = np.log(D)
    e = np.log1p(0.006 * lnD + 0.63 * D ** (4.0 / 7.0))
    c_RI = np.log(145.0) - (15.0 / 7.0) * np.log1p(0.796 * D ** (14.0 / 15.0)) - lnD
    c_EI = np.log(3.18) - (14.0 / 25.0) * e - lnD / 15.0
    c_RP = np.log(1.29) - (2.0 / 3.0) * np.log1p(0.691 * D)
    c_EP = np.log(1.48) - (7.0 / 20.0) * e - lnD / 24.0
    ln_h00 = np.log(1.8) - lnD
    return c_RI, c_EI, c_RP, c_EP, ln_h00


def _ln_asymptotes_from(consts, lnM, lnL):
    """Logs of the four NVM asymptotes and of h00 from :func:`ln_asymptote_consts` and ln M, ln L."""
    c_RI, c_EI, c_RP, c_EP, ln_h00 = consts
    return (c_RI - 2.0 * lnM, c_EI - (2.0 / 15.0) * lnM, c_RP + (2.0 / 3.0) * lnL,
            c_EP - lnM / 12.0 + 0.75 * lnL, ln_h00)


def _ln_asymptotes(lnM, lnL, D, consts=None):
    """Natural logs of the four NVM asymptotes and of the h00 cap (Nijenbanning, Venner & Moes 1994);
    ``consts``: :func:`ln_asymptote_consts` of D, if computed already."""
    return _ln_asymptotes_from(ln_asymptote_consts(D) if consts is None else consts, lnM, lnL)


def _clip(x, lo, hi):
    """``np.clip`` without its overhead (same values)."""
    return np.minimum(np.maximum(x, lo), hi)


def _ln_branches(lnM, lnL, D, with_H=True, consts=None):
    """ln H (with ``with_H``), ln iso, ln piezo and the logs of the four asymptotes of the NVM blend."""
    ln_RI, ln_EI, ln_RP, ln_EP, ln_h00 = _ln_asymptotes(lnM, lnL, D, consts)
    ln_EIc = -0.25 * np.logaddexp(-4.0 * ln_EI, -4.0 * ln_h00)          # (H_EI^-4 + h00^-4)^(-1/4)
    ln_iso = (2.0 / 3.0) * np.logaddexp(1.5 * ln_RI, 1.5 * ln_EIc)      # (H_RI^1.5 + H_EI'^1.5)^(2/3)
    ln_piezo = -0.125 * np.logaddexp(-8.0 * ln_RP, -8.0 * ln_EP)        # (H_RP^-8 + H_EP^-8)^(-1/8)
    if not with_H:
        return ln_iso, ln_piezo, ln_RI, ln_EI, ln_RP, ln_EP
    s = 1.5 * (1.0 + np.exp(-1.2 * np.exp(_clip(ln_EI - ln_RI, -EXP_MAX, EXP_MAX))))
    ln_H = np.logaddexp(s * ln_iso, s * ln_piezo) / s
    return ln_H, ln_iso, ln_piezo, ln_RI, ln_EI, ln_RP, ln_EP


def _lnML(M, L):
    M = np.asarray(M, dtype=float)
    L = np.asarray(L, dtype=float)
    return np.log(_clip(M, TINY, 1.0 / TINY)), np.log(_clip(L, TINY, 1.0 / TINY))


def _check_MLD(M, L, D):
    M = _arr("M", np.where(np.isposinf(np.asarray(M, dtype=float)), 1.0 / TINY, M), nonneg=True)
    L = _arr("L", L, nonneg=True)
    D = _arr("D", D, positive=True)
    if np.any(D > 1.0 + 1e-12):
        raise InputError("D = Rx/Ry", D, "must lie in (0, 1]")
    return M, L, D


@dataclass(frozen=True)
class _Asym:
    H_RI: np.ndarray
    H_EI: np.ndarray
    H_RP: np.ndarray
    H_EP: np.ndarray


def nvm_asymptotes(M, L, D):
    r"""The four asymptotic central films of Nijenbanning, Venner & Moes (1994).

    Parameters
    ----------
    M, L : array_like  Moes load and lubricant parameters [-]
    D : array_like     Rx/Ry [-]

    Returns
    -------
    object with H_RI, H_EI, H_RP, H_EP [-]  (H = (h/Rx)(2U)^(-1/2)):
        H_RI = 145 (1 + 0.796 D^(14/15))^(-15/7) D^-1 M^-2
        H_EI = 3.18 (1 + 0.006 ln D + 0.63 D^(4/7))^(-14/25) D^(-1/15) M^(-2/15)
        H_RP = 1.29 (1 + 0.691 D)^(-2/3) L^(2/3)
        H_EP = 1.48 (1 + 0.006 ln D + 0.63 D^(4/7))^(-7/20) D^(-1/24) M^(-1/12) L^(3/4)

    Notes
    -----
    Nijenbanning, Venner & Moes, Wear 176 (1994) 217–229; the coefficients agree with a public
    implementation that cites the paper (the paper itself could not be consulted here).

    Examples
    --------
    >>> a = nvm_asymptotes(8064.0, 23.9, 0.0309)
    >>> round(float(a.H_EP), 2)
    8.55
    """
    M, L, D = _check_MLD(M, L, D)
    lnM, lnL = _lnML(M, L)
    ln = _ln_asymptotes(lnM, lnL, D)[:4]
    vals = [np.exp(_clip(x, -EXP_MAX, EXP_MAX)) for x in ln]
    return _Asym(*[_out(v, M, L, D) for v in vals])


def nvm_H(M, L, D):
    r"""Dimensionless central film H = (h_c/Rx)(2U)^(-1/2) of Nijenbanning, Venner & Moes.

    Parameters
    ----------
    M, L : array_like  Moes load and lubricant parameters [-] (see :func:`moes_parameters`)
    D : array_like     Rx/Ry, 0 < D ≤ 1 [-]

    Returns
    -------
    ndarray  H [-]

    Notes
    -----
    H = { [H_RI^(3/2) + (H_EI^-4 + h00^-4)^(-3/8)]^(2s/3) + (H_RP^-8 + H_EP^-8)^(-s/8) }^(1/s),
    s = 1.5 (1 + exp(−1.2 H_EI/H_RI)),  h00 = 1.8 D^-1
    (Nijenbanning, Venner & Moes 1994; asymptotes in :func:`nvm_asymptotes`).

    Form implemented: the dimensionally consistent one, in
    which both branches enter as H^s (the point-contact analogue of Moes'
    line-contact blend (iso^s + piezo^s)^(1/s)).  A public implementation
    raises the iso branch to 2/(3s) instead of 2s/3, which adds H to H^s; it
    cannot be right at both ends (at low M it does not tend to H_RI).  The two
    agree where the piezo branch dominates (209 inner contact: 8.65 vs 8.63).
    The original paper could not be consulted here.  Computed in logarithms
    so that M → 0 or ∞ gives no overflow.

    Examples
    --------
    >>> round(float(nvm_H(8064.0, 23.9, 0.0309)), 2)
    8.65
    """
    M, L, D = _check_MLD(M, L, D)
    lnM, lnL = _lnML(M, L)
    ln_H = _ln_branches(lnM, lnL, D)[0]
    return _out(np.exp(_clip(ln_H, -EXP_MAX, EXP_MAX)), M, L, D)


# ---------------------------------------------------------------------------
# Regime
# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class Regime:
    """Lubrication regime per contact (arrays broadcast from the inputs).

    Attributes
    ----------
    code : ndarray of str       "IVR" | "IVE" | "PVR" | "EHL"
    ln_iso_over_piezo : ndarray ln(iso branch / piezo branch) of the NVM blend [-];
                                > 0 → iso-viscous (IVR or IVE), < 0 → piezo-viscous
    ln_RI_over_EI : ndarray     ln(H_RI / H_EI) (iso asymptotes) [-]; > 0 → rigid (IVR)
    ln_EP_over_RP : ndarray     ln(H_EP / H_RP) (piezo branch) [-]; > 0 → rigid (PVR)
    M, L, D : ndarray           Moes parameters used [-]
    index : ndarray of int      the code as a position in :data:`REGIMES`

    Properties ``iso_over_piezo``, ``RI_over_EI``, ``EP_over_RP`` give the ratios themselves
    (e^±700 at most) and ``H`` the NVM dimensionless central film (:func:`nvm_H` of M, L, D).

    A ratio near 1 means the contact sits near that boundary of the Moes map;
    |log10(ratio)| is the distance in decades.  An unloaded contact (Q = 0)
    has code "IVR" and M = 0; its ratios and H are finite but floored values
    (1e±304 at most) with no physical meaning.
    """

    code: np.ndarray
    ln_iso_over_piezo: np.ndarray
    ln_RI_over_EI: np.ndarray
    ln_EP_over_RP: np.ndarray
    M: np.ndarray
    L: np.ndarray
    D: np.ndarray
    index: np.ndarray

    @property
    def iso_over_piezo(self):
        """Iso branch / piezo branch of the NVM blend [-]."""
        return _exp_out(self.ln_iso_over_piezo)

    @property
    def RI_over_EI(self):
        """H_RI / H_EI [-]."""
        return _exp_out(self.ln_RI_over_EI)

    @property
    def EP_over_RP(self):
        """H_EP / H_RP [-]."""
        return _exp_out(self.ln_EP_over_RP)

    @property
    def H(self):
        """NVM dimensionless central film H = (h_c/Rx)(2U)^(-1/2) [-] (:func:`nvm_H`)."""
        return nvm_H(self.M, self.L, self.D)


def _exp_out(x):
    v = np.exp(_clip(x, -EXP_MAX, EXP_MAX))
    return float(v) if np.ndim(v) == 0 else v


def _regime_from_ln(lnM, lnL, D, loaded, scalar, consts=None):
    """:class:`Regime` from ln M, ln L and D (``consts``: :func:`ln_asymptote_consts` of D, if known)."""
    ln_iso, ln_piezo, ln_RI, ln_EI, ln_RP, ln_EP = _ln_branches(lnM, lnL, D, with_H=False, consts=consts)
    d_ip, d_re, d_ep = ln_iso - ln_piezo, ln_RI - ln_EI, ln_EP - ln_RP
    # iso branch dominant: IVR (0) if H_RI ≥ H_EI else IVE (1); piezo: PVR (2) if H_RP ≤ H_EP else EHL (3)
    idx = np.where(d_ip >= 0, d_re < 0, 2 + (d_ep < 0)) * loaded                 # unloaded: IVR
    code = _REGIME_CODES[idx]
    M = np.exp(_clip(lnM, -EXP_MAX, EXP_MAX)) * loaded                            # unloaded: 0
    L = np.exp(_clip(lnL, -EXP_MAX, EXP_MAX))
    fields = (d_ip, d_re, d_ep, M, L, D)
    if scalar:
        return Regime(str(code), *[float(f) for f in fields], int(idx))
    return Regime(code, *[np.asarray(f, dtype=float) for f in fields], idx)


def moes_regime(M, L, D):
    r"""Lubrication regime on the Moes map from M, L and D = Rx/Ry.

    Parameters
    ----------
    M, L : array_like  Moes load and lubricant parameters [-] (M = inf allowed: u → 0)
    D : array_like     Rx/Ry, 0 < D ≤ 1 [-]

    Returns
    -------
    Regime  codes and the dominant-term ratios

    Notes
    -----
    Dominant term of the NVM blend (Nijenbanning, Venner & Moes 1994; seed 004 §3.2, which
    rebuilds the Moes map from the asymptotes "as explained in [27]"):
    iso-viscous if the iso branch (H_RI^1.5 + H_EI'^1.5)^(2/3) exceeds the
    piezo branch (H_RP^-8 + H_EP^-8)^(-1/8) (H_EI' = (H_EI^-4 + h00^-4)^(-1/4));
    within the iso branch rigid if H_RI > H_EI (where the two asymptotes
    cross, as a Moes map draws them; the blending cap h00 is not used here);
    within the piezo branch rigid if H_RP < H_EP.  These cut-offs are
    derived, not published.

    Examples
    --------
    >>> moes_regime(8064.0, 23.9, 0.0309).code
    'EHL'
    >>> moes_regime([1.0, 1e4], [0.5, 20.0], 0.05).code.tolist()
    ['IVR', 'EHL']
    """
    scalar = all(np.ndim(x) == 0 for x in (M, L, D))
    M, L, D = _check_MLD(M, L, D)
    lnM, lnL = _lnML(M, L)
    return _regime_from_ln(lnM, lnL, D, M > 0, scalar)


# ---------------------------------------------------------------------------
# Moes map boundaries
# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class MoesMapBoundaries:
    """Regime boundaries on the (M, L) Moes map for one D = Rx/Ry.

    Attributes
    ----------
    D : float                     Rx/Ry [-]
    M : ndarray                   grid of M [-]
    L_iso_piezo : ndarray         L where iso branch = piezo branch, at each M
                                  (below: iso-viscous, above: piezo-viscous)
    M_rigid_elastic_iso : float   M where H_RI = H_EI (left: IVR, right: IVE);
                                  meaningful below L_iso_piezo
    L_rigid_elastic_piezo : ndarray  L where H_RP = H_EP, at each M
                                  (L = M (C_RP/C_EP)^12; above: PVR, below: EHL);
                                  meaningful above L_iso_piezo
    """

    D: float
    M: np.ndarray
    L_iso_piezo: np.ndarray
    M_rigid_elastic_iso: float
    L_rigid_elastic_piezo: np.ndarray


def moes_map_boundaries(D, M=None):
    r"""Boundary curves of the Moes regime map for plotting.

    Parameters
    ----------
    D : float          Rx/Ry, 0 < D ≤ 1 [-]
    M : array_like     values of M at which to give the curves [-]
                       (default: 200 points log-spaced over 1e-1 … 1e5)

    Returns
    -------
    MoesMapBoundaries

    Notes
    -----
    Same criteria as :func:`moes_regime`.  H_RP = H_EP is explicit:
    ln L = 12 (ln C_RP − ln C_EP) + ln M.  H_RI = H_EI is a root in M found by
    bisection on ln M; iso = piezo is found for all M at once by a vectorised
    bisection on ln L (the piezo branch increases monotonically with L).
    Computed here: D = 1 → M ≈ 4.6 and M ≈ 45 L; D = 0.1 → 23 and 15 L (derived boundaries,
    not published cut-offs).

    Examples
    --------
    >>> b = moes_map_boundaries(1.0, M=[100.0])
    >>> round(b.M_rigid_elastic_iso, 1), round(float(100.0 / b.L_rigid_elastic_piezo[0]), 1)
    (4.6, 44.7)
    """
    D = float(D)
    if not (np.isfinite(D) and 0.0 < D <= 1.0):
        raise InputError("D = Rx/Ry", D, "must lie in (0, 1]")
    M = np.logspace(-1, 5, 200) if M is None else _arr("M", M, positive=True)
    lnM = np.log(M)
    lnCRP = np.log(1.29) - (2.0 / 3.0) * np.log1p(0.691 * D)
    lnCEP = np.log(1.48) - (7.0 / 20.0) * np.log1p(0.006 * np.log(D) + 0.63 * D ** (4.0 / 7.0)) - np.log(D) / 24.0
    L_re_piezo = np.exp(12.0 * (lnCRP - lnCEP) + lnM)

    # H_RI = H_EI : g(lnM) = ln_RI - ln_EI, strictly decreasing in lnM
    lo, hi = np.array(-60.0), np.array(60.0)
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        ln = _ln_branches(mid, np.array(0.0), D)
        g = ln[3] - ln[4]
        lo, hi = np.where(g > 0, mid, lo), np.where(g > 0, hi, mid)
    M_re_iso = float(np.exp(0.5 * (lo + hi)))

    # iso = piezo : for each M, bisection on lnL of ln_piezo - ln_iso (increasing in lnL)
    lo = np.full_like(lnM, -60.0)
    hi = np.full_like(lnM, 60.0)
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        ln = _ln_branches(lnM, mid, D)
        f = ln[2] - ln[1]
        lo, hi = np.where(f < 0, mid, lo), np.where(f < 0, hi, mid)
    L_iso_piezo = np.exp(0.5 * (lo + hi))
    return MoesMapBoundaries(D=D, M=M, L_iso_piezo=L_iso_piezo, M_rigid_elastic_iso=M_re_iso,
                             L_rigid_elastic_piezo=L_re_piezo)
