r"""Static load rating, static equivalent load and contact pressure of ball bearings (ISO 76:2006).

ISO 76 defines the basic static load rating C0 as the load that produces a calculated
contact pressure of 4 200 MPa at the centre of the most heavily loaded ball–raceway
contact (4 600 MPa for self-aligning ball bearings, not covered here) [1].  For
ball bearings the standard writes C0 through a factor f0 tabulated against
γ = D cos α / dm (D ball diameter, dm pitch diameter, α nominal contact angle):

* radial and angular contact ball bearings   C0r = f0 i Z D² cos α      (D in mm, C0 in N)
* thrust ball bearings                       C0a = f0 Z D² sin α

f0 is interpolated linearly in γ, as the standard prescribes for intermediate values.
The tables are transcribed in :data:`F0_RADIAL` and :data:`F0_THRUST`; they are the
Hertz solution at 4 200 MPa for the standard's reference groove radii (inner 0.52 D,
outer 0.53 D radial; 0.54 D thrust) with the Stribeck factor 5 for radial bearings, which
tests/test_rating_iso76.py reproduces to 0.5 % from :func:`thermobear.contact.hertz.hertz`
(ISO/TR 10657 gives that derivation [2]).

Everything is SI at the interface (m, N, Pa, rad); the standard's mm appear only inside.

References
----------
[1] ISO 76:2006, Rolling bearings — Static load ratings: clauses "Radial ball bearings" (basic static
    radial load rating C0r, static equivalent radial load P0r, tables of X0/Y0 and of f0) and "Thrust
    ball bearings" (C0a, P0a, table of f0); guidance on the static safety factor s0.  Table numbers below
    (Table 1 X0/Y0, Table 2 f0 radial, Table 3 f0 thrust) are those we recall for the 2006 edition; the
    copy of the standard was not at hand, so each citation also names the table's content.
[2] ISO/TR 10657:2021, Explanatory notes on ISO 76 (derivation of f0 from the Hertz contact).
"""
from __future__ import annotations

import numpy as np

from thermobear.arrays import checked, out
from thermobear.errors import InputError
from thermobear.contact.hertz import hertz

__all__ = ["F0_GAMMA_RADIAL", "F0_RADIAL", "F0_GAMMA_THRUST", "F0_THRUST", "P0_REFERENCE_BALL_PA",
           "f0_radial", "f0_thrust", "static_load_rating", "static_equivalent_load",
           "static_safety_factor", "contact_pressures", "pressure_ratio"]

#: Reference contact pressure of ISO 76 for ball bearings other than self-aligning [Pa]
#: (ISO 76:2006, definition of C0; SKF catalogue "Static load ratings" quotes the same 4 200 MPa).
P0_REFERENCE_BALL_PA = 4.2e9

#: γ = D cos α / dm grid of ISO 76:2006 Table 2 (radial and angular contact groove ball bearings).
F0_GAMMA_RADIAL = np.round(np.arange(41) * 0.01, 2)
#: f0 of ISO 76:2006 Table 2, column "radial and angular contact groove ball bearings" [N/mm²].
F0_RADIAL = np.array([
    14.7, 14.9, 15.1, 15.3, 15.5, 15.7, 15.9, 16.1, 16.3, 16.5,      # 0.00 ... 0.09
    16.4, 16.1, 15.9, 15.6, 15.4, 15.2, 14.9, 14.7, 14.4, 14.2,      # 0.10 ... 0.19
    14.0, 13.7, 13.5, 13.2, 13.0, 12.8, 12.5, 12.3, 12.1, 11.8,      # 0.20 ... 0.29
    11.6, 11.4, 11.2, 10.9, 10.7, 10.5, 10.3, 10.0, 9.8, 9.6,        # 0.30 ... 0.39
    9.4])                                                            # 0.40
#: γ = D cos α / dm grid of ISO 76:2006 Table 3 (thrust ball bearings).
F0_GAMMA_THRUST = np.round(np.arange(36) * 0.01, 2)
#: f0 of ISO 76:2006 Table 3, thrust ball bearings [N/mm²].
F0_THRUST = np.array([
    61.6, 60.8, 59.9, 59.1, 58.3, 57.5, 56.7, 55.9, 55.1, 54.3,      # 0.00 ... 0.09
    53.5, 52.7, 51.9, 51.2, 50.4, 49.6, 48.8, 48.0, 47.3, 46.5,      # 0.10 ... 0.19
    45.7, 45.0, 44.2, 43.5, 42.7, 41.9, 41.2, 40.5, 39.7, 39.0,      # 0.20 ... 0.29
    38.2, 37.5, 36.8, 36.0, 35.3, 34.6])                             # 0.30 ... 0.35

#: Static radial factor X0 and axial factor Y0 of ISO 76:2006 Table 1 (single-row bearings):
#: deep groove X0 = 0.6, Y0 = 0.5; angular contact X0 = 0.5, Y0 by nominal contact angle [deg].
_X0_DEEP_GROOVE, _Y0_DEEP_GROOVE = 0.6, 0.5
_X0_ANGULAR = 0.5
_Y0_ANGLE_DEG = np.array([15.0, 20.0, 25.0, 30.0, 35.0, 40.0, 45.0])
_Y0_ANGULAR = np.array([0.46, 0.42, 0.38, 0.33, 0.29, 0.26, 0.22])

_KINDS = ("deep_groove", "angular_contact", "thrust")


def table_lookup(x, xs, ys, what):
    """Linear interpolation in a standard's table, InputError outside its range.

    Parameters
    ----------
    x : array_like   abscissa
    xs, ys : ndarray table (xs increasing)
    what : str       field name for the error

    Returns
    -------
    float or ndarray  interpolated ordinate
    """
    x = np.asarray(x, dtype=float)
    lo, hi = xs[0], xs[-1]
    if x.size and not (np.all(x >= lo - 1e-12) and np.all(x <= hi + 1e-12)):
        raise InputError(what, x, f"outside the standard's table, which covers {lo:g} ... {hi:g}")
    return out(np.interp(x, xs, ys))


def f0_radial(gamma):
    r"""Static load rating factor f0 of radial and angular contact ball bearings [N/mm²].

    Parameters
    ----------
    gamma : array_like   γ = D cos α / dm [-], 0 ... 0.40

    Returns
    -------
    float or ndarray  f0, linear interpolation in ISO 76:2006 Table 2 [N/mm²]

    Examples
    --------
    >>> f0_radial(0.10), round(f0_radial(0.2644), 3)
    (16.4, 12.412)
    """
    return table_lookup(gamma, F0_GAMMA_RADIAL, F0_RADIAL, "gamma = D cos(alpha)/dm (ISO 76 Table 2)")


def f0_thrust(gamma):
    r"""Static load rating factor f0 of thrust ball bearings [N/mm²].

    Parameters
    ----------
    gamma : array_like   γ = D cos α / dm [-], 0 ... 0.35 (0 for α = 90°)

    Returns
    -------
    float or ndarray  f0, linear interpolation in ISO 76:2006 Table 3 [N/mm²]

    Examples
    --------
    >>> f0_thrust(0.0)
    61.6
    """
    return table_lookup(gamma, F0_GAMMA_THRUST, F0_THRUST, "gamma = D cos(alpha)/dm (ISO 76 Table 3)")


def _check_kind(kind):
    if kind not in _KINDS:
        raise InputError("kind", kind, f"must be one of {', '.join(_KINDS)}")


def static_load_rating(D, dm, Z, alpha, kind, i=1):
    r"""Basic static load rating C0 of a ball bearing [N] (ISO 76:2006, basic static radial / axial load rating).

    Parameters
    ----------
    D : array_like      ball diameter [m]
    dm : array_like     pitch diameter [m]
    Z : array_like      balls per row [-]
    alpha : array_like  nominal contact angle [rad] (0 for deep groove, π/2 for a flat thrust bearing)
    kind : str          ``"deep_groove"``, ``"angular_contact"`` (radial rating C0r) or ``"thrust"`` (C0a)
    i : int             number of rows [-] (radial bearings)

    Returns
    -------
    float or ndarray  C0 [N]

    Notes
    -----
    .. math::

        C_{0r} = f_0\, i\, Z\, D_w^2 \cos\alpha, \qquad C_{0a} = f_0\, Z\, D_w^2 \sin\alpha,
        \qquad f_0 = f_0(D_w \cos\alpha / D_{pw})

    with D_w in mm and C0 in N; f0 from Table 2 (radial) or Table 3 (thrust) of ISO 76:2006.

    Examples
    --------
    ISO/TS 16281 example bearing (a 6305: Z 7, D 11.5 mm, dm 43.5 mm):

    >>> round(static_load_rating(11.5e-3, 43.5e-3, 7, 0.0, "deep_groove"))
    11491
    """
    _check_kind(kind)
    D = checked("D", D, what=" [m]")
    dm = checked("dm", dm, what=" [m]")
    Z = checked("Z", Z, what=" (balls)")
    a = np.asarray(alpha, dtype=float)
    D_mm2 = (D * 1e3) ** 2
    gamma = D * np.cos(a) / dm
    if kind == "thrust":
        return out(f0_thrust(np.where(np.abs(np.cos(a)) < 1e-12, 0.0, gamma)) * Z * D_mm2 * np.sin(a))
    return out(f0_radial(gamma) * i * Z * D_mm2 * np.cos(a))


def static_equivalent_load(Fr, Fa, alpha, kind):
    r"""Static equivalent load P0 of a single-row ball bearing [N] (ISO 76:2006, static equivalent radial / axial load).

    Parameters
    ----------
    Fr, Fa : array_like  radial and axial load [N], ≥ 0
    alpha : float        nominal contact angle [rad]; angular contact 15°–45°
    kind : str           ``"deep_groove"``, ``"angular_contact"`` or ``"thrust"``

    Returns
    -------
    float or ndarray  P0 [N]

    Notes
    -----
    Radial bearings: P0r = X0 Fr + Y0 Fa, and P0r = Fr when that is larger
    (Table 1: deep groove X0 0.6, Y0 0.5; angular contact X0 0.5, Y0 0.46 (15°) ... 0.22 (45°),
    linear in α between the tabulated angles).  Thrust: P0a = 2.3 Fr tan α + Fa,
    which is Fa for α = 90° (a flat thrust bearing carries no radial load: InputError).

    Examples
    --------
    >>> static_equivalent_load(1000.0, 1000.0, 0.0, "deep_groove")
    1100.0
    >>> round(static_equivalent_load(1000.0, 3000.0, 0.6981317, "angular_contact"), 1)
    1280.0
    """
    _check_kind(kind)
    Fr = checked("Fr", Fr, strict=False, what=" [N]")
    Fa = checked("Fa", Fa, strict=False, what=" [N]")
    if kind == "thrust":
        if abs(np.cos(alpha)) < 1e-9:
            if Fr.size and Fr.max() > 0:
                raise InputError("Fr", Fr, "a thrust ball bearing with α = 90° carries no radial load "
                                 "(ISO 76, static equivalent axial load); must be 0 [N]")
            return out(Fa)
        return out(2.3 * Fr * np.tan(alpha) + Fa)
    if kind == "deep_groove":
        X0, Y0 = _X0_DEEP_GROOVE, _Y0_DEEP_GROOVE
    else:
        a_deg = float(np.rad2deg(alpha))
        Y0 = table_lookup(a_deg, _Y0_ANGLE_DEG, _Y0_ANGULAR, "alpha [deg] (ISO 76 Table 1, angular contact)")
        X0 = _X0_ANGULAR
    return out(np.maximum(X0 * Fr + Y0 * Fa, Fr))


def static_safety_factor(C0, P0):
    r"""Static safety factor s0 = C0 / P0 [-] (ISO 76:2006, static safety factor guidance).

    Parameters
    ----------
    C0 : array_like  basic static load rating [N], > 0
    P0 : array_like  static equivalent load [N], > 0

    Returns
    -------
    float or ndarray  s0 [-]; s0 < 1 means the load exceeds the static rating

    Examples
    --------
    >>> static_safety_factor(11600.0, 5800.0)
    2.0
    """
    return out(checked("C0", C0, what=" [N]") / checked("P0", P0, what=" [N] (no load: s0 is unbounded)"))


def contact_pressures(brg, Q_i, Q_o, alpha_i, alpha_o):
    r"""Maximum Hertz pressure of every ball–inner and ball–outer contact [Pa].

    Parameters
    ----------
    brg : BallBearing          internal geometry and materials
    Q_i, Q_o : array_like      contact loads [N] (e.g. ``LoadDistribution.Q_i``, ``.Q_o``)
    alpha_i, alpha_o : array_like  contact angles [rad]

    Returns
    -------
    (p_i, p_o)  maximum contact pressures [Pa], shaped as the loads

    Notes
    -----
    p_max = 3 Q / (2 π a b) of the exact Hertz solution
    (:func:`thermobear.contact.hertz.hertz`) with the reduced radii of the bearing at the
    operating contact angle (Rx = D(1 ∓ γ)/2, Ry = f D/(2f − 1)).  Compare with
    :data:`P0_REFERENCE_BALL_PA` through :func:`pressure_ratio`.

    Examples
    --------
    >>> from thermobear.contact.geometry import bearing
    >>> p_i, p_o = contact_pressures(bearing("iso-dgbb"), 2000.0, 2000.0, 0.0, 0.0)
    >>> round(p_i / 1e9, 3), round(p_o / 1e9, 3)
    (2.647, 2.254)
    """
    E = brg.E_prime
    c_i = hertz(Q_i, brg.Rx_i(alpha_i), brg.Ry_i, E)
    c_o = hertz(Q_o, brg.Rx_o(alpha_o), brg.Ry_o, E)
    return c_i.p_max, c_o.p_max


def pressure_ratio(p_max):
    r"""Contact pressure relative to the ISO 76 reference of ball bearings, p_max / 4 200 MPa [-].

    Parameters
    ----------
    p_max : array_like  maximum contact pressure [Pa]

    Returns
    -------
    float or ndarray  ratio [-]; > 1 means the load exceeds what defines C0 (permanent
    deformation above about 1e-4 D, ISO 76:2006 definition of C0)

    Examples
    --------
    >>> pressure_ratio(4.62e9)
    1.1
    """
    return out(checked("p_max", p_max, strict=False, what=" [Pa]") / P0_REFERENCE_BALL_PA)
