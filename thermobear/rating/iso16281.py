r"""Reference rating life of a ball bearing from its computed load distribution (ISO/TS 16281:2008).

ISO/TS 16281 replaces the equivalent-load route of ISO 281 (P = X Fr + Y Fa) by the
actual ball loads of a load-distribution solution (here :mod:`thermobear.loads`):

1. basic dynamic load ratings of the raceways, per ball contact, Q_ci (inner ring or shaft
   washer) and Q_ce (outer ring or housing washer), from the bearing's rating C;
2. dynamic equivalent ball loads Q_ei, Q_ee — the cubic mean of the ball loads for the
   ring that rotates relative to the load, the 10/3-power mean for the ring that is
   stationary relative to the load;
3. ring lives (Q_c/Q_e)³ combined with the Weibull slope 10/9 of ball bearings into the
   basic reference rating life L10r [10⁶ rev], and the reference load P_ref = C L10r^(-1/3).

Equations as implemented in the public ISO/TS 16281 example code minzhun/ISO16281
(``BallBearing.py``, whose comments number them eqs 19–29), which reproduces the
standard's example set; see tests/test_rating_iso16281.py for the reference cases.

:func:`reference_life` takes the ball loads of any :class:`~thermobear.loads.LoadDistribution` (five
degrees of freedom, either form); :func:`iso16281_life` solves the load distribution with the standard's
conventions first — rigid rings, low speed, K_n at the nominal contact angle, the pitch radius d_m/2 as the
arm of tilts and moments (the convention the reference examples are computed with: their tilts and the
pure-moment life are reproduced with it to 2e-4, and missed by 1–2.4 % with the groove-centre radius ℜ_i,
validation/report/iso_ts_16281.md).
The constants 0.407 and 0.389 are the Lundberg–Palmgren ratios F_r/(Z Q_e cos α) of a
rotating and a stationary ring under a half-circle load zone (Harris 2001 ch. 18),
so that L10r = 1 at F_r = C for a zero-clearance radial bearing.

References
----------
[1] ISO/TS 16281:2008, Rolling bearings — Methods for calculating the modified reference
    rating life for universally loaded bearings (ball bearings: raceway ratings, equivalent
    rolling element loads, reference rating life).
[2] minzhun/ISO16281 (GitHub), BallBearing.py and Test_BallBearing.py: an implementation of
    [1] with the 7-ball example bearing and its published reference results.
[3] Harris, T. A. (2001) Rolling Bearing Analysis, 4th ed., Wiley, ch. 18 (Lundberg–Palmgren raceway
    capacities, load-zone integrals).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermobear.arrays import checked, out
from thermobear.contact.geometry import BallBearing
from thermobear.errors import InputError
from thermobear.loads import LoadDistribution, load_distribution
from thermobear.rating.iso281 import dynamic_load_rating

__all__ = ["raceway_load_ratings", "equivalent_ball_loads", "reference_rating_life", "ReferenceLife", "rating_angle",
           "reference_life", "iso16281_life", "system_life"]

_WEIBULL_BALL = 10.0 / 9.0       # Weibull slope of ball bearings (ISO 281 / ISO/TS 16281)


def raceway_load_ratings(C, Z, alpha, gamma, fi, fo, kind, i=1):
    r"""Basic dynamic load ratings of the raceways per ball contact, Q_ci and Q_ce [N].

    Parameters
    ----------
    C : float       basic dynamic load rating of the bearing [N] (ISO 281, C_r or C_a)
    Z : int         balls per row [-]
    alpha : float   nominal contact angle [rad] (0 deep groove, π/2 flat thrust)
    gamma : float   D cos α / dm [-]
    fi, fo : float  inner / outer osculation r/D [-]
    kind : str      ``"deep_groove"``, ``"angular_contact"`` or ``"thrust"``
    i : int         rows [-]

    Returns
    -------
    (Q_ci, Q_ce)  [N]

    Notes
    -----
    Radial ball bearings, with :math:`\varphi = \left[\frac{f_i (2 f_o - 1)}{f_o (2 f_i - 1)}\right]^{0.41}`:

    .. math::

        Q_{ci} = \frac{C}{0.407\, Z\, (i \cos\alpha)^{0.7}}
                 \left[1 + \left(1.044 \left(\tfrac{1-\gamma}{1+\gamma}\right)^{1.72}\varphi\right)^{10/3}\right]^{0.3},
        \quad
        Q_{ce} = \frac{C}{0.389\, Z\, (i \cos\alpha)^{0.7}}
                 \left[1 + \left(1.044 \left(\tfrac{1-\gamma}{1+\gamma}\right)^{1.72}\varphi\right)^{-10/3}\right]^{0.3}

    thrust ball bearings: the factor 0.407 (0.389) (i cos α)^0.7 becomes sin α, 1.044 becomes 1, and
    for α = 90° the γ term drops out (ISO/TS 16281 eqs 19–24 as numbered in [2]).

    Examples
    --------
    >>> [round(q, 1) for q in raceway_load_ratings(23400.0, 7, 0.0, 11.5 / 43.5, 0.52, 0.53, "deep_groove")]
    [8423.2, 18288.7]
    """
    if kind not in ("deep_groove", "angular_contact", "thrust"):
        raise InputError("kind", kind, "must be one of deep_groove, angular_contact, thrust")
    C = float(checked("C", C, what=" [N]"))
    for name, f in (("fi", fi), ("fo", fo)):
        if not f > 0.5:
            raise InputError(name, f, "osculation must be > 0.5")
    phi = (fi * (2.0 * fo - 1.0) / (fo * (2.0 * fi - 1.0))) ** 0.41
    g = (1.0 - gamma) / (1.0 + gamma)
    if kind == "thrust":
        thrust90 = abs(np.cos(alpha)) < 1e-9
        x = phi if thrust90 else g**1.72 * phi
        base = C / (Z * np.sin(alpha))
        return (float(base * (1.0 + x ** (10.0 / 3.0)) ** 0.3),
                float(base * (1.0 + x ** (-10.0 / 3.0)) ** 0.3))
    x = 1.044 * g**1.72 * phi
    row = Z * (i * np.cos(alpha)) ** 0.7
    return (float(C / (0.407 * row) * (1.0 + x ** (10.0 / 3.0)) ** 0.3),
            float(C / (0.389 * row) * (1.0 + x ** (-10.0 / 3.0)) ** 0.3))


def equivalent_ball_loads(Q_i, Q_o, rotating="inner"):
    r"""Dynamic equivalent ball loads of the inner and outer raceway, Q_ei and Q_ee [N].

    Parameters
    ----------
    Q_i, Q_o : array_like  ball–inner and ball–outer contact loads [N], balls on the last axis
    rotating : str         ``"inner"`` (inner ring rotates relative to the load) or ``"outer"``

    Returns
    -------
    (Q_ei, Q_ee)  [N], one per load case (leading axes)

    Notes
    -----
    ISO/TS 16281 eqs 25–28 (numbering of [2]): for the ring rotating relative to the load
    :math:`Q_e = (\frac{1}{Z}\sum_j Q_j^{3})^{1/3}`, for the ring stationary relative to the
    load :math:`Q_e = (\frac{1}{Z}\sum_j Q_j^{10/3})^{0.3}`.

    Examples
    --------
    >>> [round(float(q), 2) for q in equivalent_ball_loads([100.0, 0.0], [100.0, 0.0])]
    [79.37, 81.23]
    """
    Qi = checked("Q_i", Q_i, strict=False, what=" [N]")
    Qo = checked("Q_o", Q_o, strict=False, what=" [N]")
    cube = lambda q: np.mean(q**3, axis=-1) ** (1.0 / 3.0)            # noqa: E731
    ten3 = lambda q: np.mean(q ** (10.0 / 3.0), axis=-1) ** 0.3       # noqa: E731
    if rotating == "inner":
        return out(cube(Qi)), out(ten3(Qo))
    if rotating == "outer":
        return out(ten3(Qi)), out(cube(Qo))
    raise InputError("rotating", rotating, "must be inner or outer (the ring that rotates relative to the load)")


@dataclass(frozen=True)
class ReferenceLife:
    """ISO/TS 16281 basic reference rating life and its parts.

    Attributes
    ----------
    L10r : basic reference rating life [10⁶ rev]
    L_inner, L_outer : lives of the inner / outer raceway [10⁶ rev]
    Q_ci, Q_ce : raceway load ratings per ball [N]
    Q_ei, Q_ee : equivalent ball loads [N]
    P_ref : dynamic equivalent reference load C L10r^(-1/3) [N]
    """

    L10r: float
    L_inner: float
    L_outer: float
    Q_ci: float
    Q_ce: float
    Q_ei: float
    Q_ee: float
    P_ref: float


def reference_rating_life(C, Q_ci, Q_ce, Q_ei, Q_ee):
    r"""Basic reference rating life L10r of a ball bearing [10⁶ revolutions] (ISO/TS 16281).

    Parameters
    ----------
    C : float              basic dynamic load rating [N] (for P_ref)
    Q_ci, Q_ce : float     raceway load ratings (:func:`raceway_load_ratings`) [N]
    Q_ei, Q_ee : array_like equivalent ball loads (:func:`equivalent_ball_loads`) [N], > 0

    Returns
    -------
    ReferenceLife

    Notes
    -----
    .. math::

        L_{10r} = \left[\left(\frac{Q_{ci}}{Q_{ei}}\right)^{-10/3}
                  + \left(\frac{Q_{ce}}{Q_{ee}}\right)^{-10/3}\right]^{-9/10},
        \qquad P_{ref} = C\, L_{10r}^{-1/3}

    i.e. ring lives (Q_c/Q_e)³ combined with the Weibull slope e = 10/9 (eq 29 of [2]).
    An unloaded bearing (all Q_e = 0) has no finite life: InputError.

    Examples
    --------
    >>> round(reference_rating_life(23400.0, 8423.2, 18288.7, 1000.0, 1100.0).L10r, 1)
    546.9
    """
    Q_ei = checked("Q_ei", Q_ei, what=" [N] (an unloaded bearing has no finite rating life)")
    Q_ee = checked("Q_ee", Q_ee, what=" [N] (an unloaded bearing has no finite rating life)")
    Li = (Q_ci / Q_ei) ** 3
    Lo = (Q_ce / Q_ee) ** 3
    L = (Li**-_WEIBULL_BALL + Lo**-_WEIBULL_BALL) ** (-1.0 / _WEIBULL_BALL)
    return ReferenceLife(L10r=out(L), L_inner=out(Li), L_outer=out(Lo), Q_ci=float(Q_ci), Q_ce=float(Q_ce),
                         Q_ei=out(Q_ei), Q_ee=out(Q_ee), P_ref=out(C * L ** (-1.0 / 3.0)))


def rating_angle(brg: BallBearing) -> float:
    """Nominal contact angle of the ratings [rad]: 0 deep groove, α0 otherwise (ISO 76, ISO 281, ISO/TS 16281).

    >>> from thermobear.contact.geometry import bearing
    >>> rating_angle(bearing("iso-dgbb")), round(float(np.degrees(rating_angle(bearing("7210")))), 1)
    (0.0, 40.0)
    """
    return 0.0 if brg.kind == "deep_groove" else float(brg.alpha0)


def reference_life(brg: BallBearing, ld: LoadDistribution, C=None, *, rotating: str = "inner", i: int = 1):
    r"""ISO/TS 16281 basic reference rating life L10r of the ball loads of a load distribution.

    Parameters
    ----------
    brg : BallBearing
    ld : LoadDistribution  any batch (leading axes), any form; its Q_i load the inner raceway, Q_o the outer
    C : float              basic dynamic load rating [N]; default ISO 281 from the geometry
                           (:func:`thermobear.rating.iso281.dynamic_load_rating`)
    rotating : str         the ring rotating relative to the load, ``"inner"`` or ``"outer"``
    i : int                rows [-]

    Returns
    -------
    ReferenceLife          one value per load case (floats for one case)

    Notes
    -----
    :func:`raceway_load_ratings` at the rating angle (:func:`rating_angle`), :func:`equivalent_ball_loads`,
    :func:`reference_rating_life` (ISO/TS 16281 eqs 19–29 as numbered in [2]).

    Examples
    --------
    >>> from thermobear.contact.geometry import bearing
    >>> b = bearing("iso-dgbb")
    >>> round(float(reference_life(b, load_distribution(b, Fr=1000.0), 23400.0).L10r))
    13163
    """
    a = rating_angle(brg)
    C = dynamic_load_rating(brg.D, brg.dm, brg.Z, a, brg.kind, i) if C is None else C
    Q_ci, Q_ce = raceway_load_ratings(C, brg.Z, a, brg.D * np.cos(a) / brg.dm, brg.fi, brg.fo, brg.kind, i)
    return reference_rating_life(C, Q_ci, Q_ce, *equivalent_ball_loads(ld.Q_i, ld.Q_o, rotating))


def iso16281_life(brg: BallBearing, C=None, *, Fa=0.0, Fr=0.0, M=None, Fz=0.0, My=None, rotating: str = "inner",
                  tilt_arm: str = "pitch"):
    r"""Load distribution and reference rating life with the conventions of ISO/TS 16281.

    Parameters
    ----------
    brg : BallBearing
    C : float             basic dynamic load rating [N] (default: ISO 281 from the geometry)
    Fa, Fr, Fz : array_like  axial load and the radial loads along y (ψ = 0) and z (ψ = 90°) [N]
    M, My : array_like    moments in the x–y plane and about +y [N m] (``None``: tilts held;
                          :func:`thermobear.loads.load_distribution`)
    rotating : str        ``"inner"`` or ``"outer"`` (the ring rotating relative to the load)
    tilt_arm : str        ``"pitch"`` (d_m/2, the standard's reference examples; default) or ``"groove"`` (ℜ_i)

    Returns
    -------
    (ReferenceLife, LoadDistribution)

    Examples
    --------
    ISO/TS 16281 example 6: the 7-ball example bearing without clearance under a moment of 1 N m about the
    radial axis through the first ball (our y): L10r = 785 145 (reference), tilt 3.6957 mrad.

    >>> from thermobear.contact.geometry import bearing
    >>> life, ld = iso16281_life(bearing("iso-dgbb").with_(Pd=0.0), 23400.0, My=1.0)
    >>> round(float(life.L10r), -1), round(ld.theta_y * 1e3, 4)
    (785310.0, 3.6956)
    """
    ld = load_distribution(brg, Fa=Fa, Fr=Fr, M=M, Fz=Fz, My=My, form="static", stiffness="nominal",
                           tilt_arm=tilt_arm)
    return reference_life(brg, ld, C, rotating=rotating), ld


def system_life(lives, e: float = _WEIBULL_BALL):
    r"""Rating life of a set of bearings (or raceways) that fails with its first member [10⁶ rev].

    .. math:: L = \left(\sum_k L_k^{-e}\right)^{-1/e}

    with the Weibull slope e = 10/9 of ball bearings (Lundberg & Palmgren 1947; Harris 2001 ch. 18, the
    same combination as the raceways in :func:`reference_rating_life`).

    Parameters
    ----------
    lives : array_like   the members' lives [10⁶ rev] on the last axis, > 0
    e : float            Weibull slope [-]

    >>> round(float(system_life([1000.0, 1000.0])), 1)
    535.9
    """
    L = checked("lives", lives, what=" [10^6 rev]")
    return out(np.sum(L ** -e, axis=-1) ** (-1.0 / e))
