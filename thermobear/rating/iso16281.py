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
from thermobear.errors import InputError

__all__ = ["raceway_load_ratings", "equivalent_ball_loads", "reference_rating_life", "ReferenceLife"]

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
