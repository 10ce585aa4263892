r"""Dynamic load rating, equivalent load and rating life of ball bearings (ISO 281:2007).

* basic dynamic load rating C from the internal geometry (Tables 1, 2, 4);
* dynamic equivalent load P = X Fr + Y Fa (Tables 3, 5);
* basic rating life L10 = (C/P)³ [10⁶ revolutions];
* modified rating life L10m = a_ISO L10 with the life modification factor a_ISO of the
  systems approach: viscosity ratio κ = ν/ν1, contamination factor e_C (the standard's
  simplified table), fatigue load limit C_u (the standard's approximation from C0).

Inputs are SI (m, N, m²/s; speeds in rpm as the name says); the standard's mm and mm²/s
appear only inside.  Tables are cited by number and content; the numbers are those we recall for
ISO 281:2007 [1] (the standard itself was not at hand), the content names each table unambiguously.

References
----------
[1] ISO 281:2007, Rolling bearings — Dynamic load ratings and rating life: Table 1 (b_m),
    Table 2 (f_c, radial ball bearings), Table 3 (X, Y, e, radial ball bearings), Table 4
    (f_c, thrust ball bearings), clause "Life modification factor for systems approach"
    (a_ISO, κ, ν1, e_C, C_u).
[2] ISO/TR 1281-1:2008 and ISO/TR 1281-2:2008, Explanatory notes on ISO 281 (the
    Lundberg–Palmgren form behind f_c; the a_ISO model).
[3] Harris, T. A. (2001) Rolling Bearing Analysis, 4th ed., Wiley, ch. 18 (fatigue life: basic theory
    and rating standards; the Lundberg–Palmgren raceway capacities behind f_c).
"""
from __future__ import annotations

import numpy as np

from thermobear.arrays import checked, out
from thermobear.errors import InputError
from thermobear.rating.iso76 import table_lookup

__all__ = ["B_M_BALL", "FC_GAMMA_RADIAL", "FC_RADIAL", "FC_THRUST", "CONTAMINATION_LEVELS",
           "A_ISO_MAX", "fc_radial", "fc_thrust", "dynamic_load_rating", "radial_load_factors",
           "dynamic_equivalent_load", "basic_rating_life", "reference_viscosity", "viscosity_ratio",
           "contamination_factor", "fatigue_load_limit", "life_modification_factor",
           "modified_rating_life"]

#: Rating factor b_m of ISO 281:2007 Table 1 for radial (except filling-slot) and thrust ball bearings.
B_M_BALL = 1.3

#: γ = D cos α / dm grid of ISO 281:2007 Table 2.
FC_GAMMA_RADIAL = np.round(np.arange(1, 41) * 0.01, 2)
#: f_c of ISO 281:2007 Table 2, column "single-row radial contact groove ball bearings and single-
#: and double-row angular contact groove ball bearings" (valid for groove radii ≤ 0.52 D inner,
#: ≤ 0.53 D outer).
FC_RADIAL = np.array([
    29.1, 35.8, 40.3, 43.8, 46.7, 49.1, 51.1, 52.8, 54.3, 55.5,      # 0.01 ... 0.10
    56.6, 57.5, 58.2, 58.8, 59.3, 59.6, 59.8, 59.9, 60.0, 59.9,      # 0.11 ... 0.20
    59.8, 59.6, 59.3, 59.0, 58.6, 58.2, 57.7, 57.1, 56.6, 56.0,      # 0.21 ... 0.30
    55.3, 54.6, 53.9, 53.2, 52.4, 51.7, 50.9, 50.0, 49.2, 48.4])     # 0.31 ... 0.40

#: f_c of ISO 281:2007 Table 4 (thrust ball bearings) by nominal contact angle [deg]:
#: (γ grid, f_c).  γ = D cos α / dm for α < 90°, γ = D / dm for α = 90°.
FC_THRUST = {
    45.0: (np.round(np.arange(1, 31) * 0.01, 2), np.array([
        42.1, 51.7, 58.2, 63.3, 67.3, 70.7, 73.5, 75.9, 78.0, 79.7,
        81.1, 82.3, 83.3, 84.1, 84.7, 85.1, 85.4, 85.5, 85.5, 85.4,
        85.2, 84.9, 84.5, 84.0, 83.4, 82.8, 82.0, 81.3, 80.4, 79.6])),
    60.0: (np.round(np.arange(1, 21) * 0.01, 2), np.array([
        39.2, 48.1, 54.2, 58.9, 62.6, 65.8, 68.4, 70.7, 72.6, 74.2,
        75.5, 76.6, 77.5, 78.3, 78.8, 79.2, 79.5, 79.6, 79.6, 79.5])),
    75.0: (np.round(np.arange(1, 11) * 0.01, 2), np.array([
        37.3, 45.9, 51.7, 56.1, 59.7, 62.7, 65.2, 67.3, 69.2, 70.7])),
    90.0: (np.round(np.arange(1, 35) * 0.01, 2), np.array([
        36.7, 45.2, 51.1, 55.7, 59.5, 62.9, 65.8, 68.5, 71.0, 73.3,
        75.4, 77.4, 79.3, 81.1, 82.7, 84.4, 85.9, 87.4, 88.8, 90.2,
        91.5, 92.8, 94.1, 95.3, 96.4, 97.6, 98.7, 99.8, 100.8, 101.9,
        102.9, 103.9, 104.8, 105.8])),
}

# ISO 281:2007 Table 3, single-row radial ball bearings, Fa/Fr > e (X, Y); Fa/Fr <= e: X = 1, Y = 0.
#: deep groove: relative axial load f0 Fa / C0r, e, Y (X = 0.56)
_DG_REL = np.array([0.172, 0.345, 0.689, 1.03, 1.38, 2.07, 3.45, 5.17, 6.89])
_DG_E = np.array([0.19, 0.22, 0.26, 0.28, 0.30, 0.34, 0.38, 0.42, 0.44])
_DG_Y = np.array([2.30, 1.99, 1.71, 1.55, 1.45, 1.31, 1.15, 1.04, 1.00])
_DG_X = 0.56
#: angular contact, α = 15°: relative axial load i Fa / C0r, e, Y (X = 0.44)
_AC15_REL = np.array([0.015, 0.029, 0.058, 0.087, 0.12, 0.17, 0.29, 0.44, 0.58])
_AC15_E = np.array([0.38, 0.40, 0.43, 0.46, 0.47, 0.50, 0.55, 0.56, 0.56])
_AC15_Y = np.array([1.47, 1.40, 1.30, 1.23, 1.19, 1.12, 1.02, 1.00, 1.00])
_AC15_X = 0.44
#: angular contact, α = 20° ... 45°: (X, Y, e), independent of the load
_AC_CONST = {20.0: (0.43, 1.00, 0.57), 25.0: (0.41, 0.87, 0.68), 30.0: (0.39, 0.76, 0.80),
             35.0: (0.37, 0.66, 0.95), 40.0: (0.35, 0.57, 1.14), 45.0: (0.33, 0.50, 1.34)}

#: Contamination factor e_C, ISO 281:2007 simplified table: level -> ((lo, hi) for dm < 100 mm,
#: (lo, hi) for dm >= 100 mm).
CONTAMINATION_LEVELS = {
    "extreme_cleanliness": ((1.0, 1.0), (1.0, 1.0)),
    "high_cleanliness": ((0.6, 0.8), (0.8, 0.9)),
    "normal_cleanliness": ((0.5, 0.6), (0.6, 0.8)),
    "slight_contamination": ((0.3, 0.5), (0.4, 0.6)),
    "typical_contamination": ((0.1, 0.3), (0.2, 0.4)),
    "severe_contamination": ((0.0, 0.1), (0.0, 0.1)),
    "very_severe_contamination": ((0.0, 0.0), (0.0, 0.0)),
}

#: Upper limit of a_ISO in ISO 281:2007 ("a_ISO ≤ 50").
A_ISO_MAX = 50.0
_KAPPA_RANGE = (0.1, 4.0)


def fc_radial(gamma):
    r"""Dynamic load rating factor f_c of radial and angular contact ball bearings [N/mm^1.8].

    Parameters
    ----------
    gamma : array_like   γ = D cos α / dm [-], 0.01 ... 0.40

    Returns
    -------
    float or ndarray  f_c, linear interpolation in ISO 281:2007 Table 2

    Examples
    --------
    >>> fc_radial(0.1), round(fc_radial(0.2644), 3)
    (55.5, 57.98)
    """
    return table_lookup(gamma, FC_GAMMA_RADIAL, FC_RADIAL, "gamma = D cos(alpha)/dm (ISO 281 Table 2)")


def fc_thrust(gamma, alpha):
    r"""Dynamic load rating factor f_c of thrust ball bearings [N/mm^1.8].

    Parameters
    ----------
    gamma : float   γ = D cos α / dm for α < 90°, D / dm for α = 90° [-]
    alpha : float   nominal contact angle [rad], 45° ... 75° or 90°

    Returns
    -------
    float  f_c from ISO 281:2007 Table 4, linear in γ within a column and linear in α
    between the 45°, 60° and 75° columns

    Notes
    -----
    ISO 281 tabulates 45°, 60°, 75° and 90°; the 90° column uses another γ (D/dm) and
    another rating formula, so angles in (75°, 90°) are refused (InputError).

    Examples
    --------
    >>> round(fc_thrust(0.146, np.pi / 2), 2)
    82.06
    """
    a = float(np.rad2deg(alpha))
    if abs(a - 90.0) < 1e-6:
        g, f = FC_THRUST[90.0]
        return table_lookup(gamma, g, f, "gamma = D/dm (ISO 281 Table 4, alpha = 90°)")
    if not 45.0 - 1e-9 <= a <= 75.0 + 1e-9:
        raise InputError("alpha", alpha, "ISO 281 Table 4 covers thrust ball bearings with α in "
                         "[45°, 75°] or α = 90° [rad]")
    cols = sorted(k for k in FC_THRUST if k < 90.0)
    lo = max(c for c in cols if c <= a + 1e-9)
    hi = min(c for c in cols if c >= a - 1e-9)
    f_lo = table_lookup(gamma, *FC_THRUST[lo], f"gamma (ISO 281 Table 4, alpha = {lo:g}°)")
    if hi == lo:
        return f_lo
    f_hi = table_lookup(gamma, *FC_THRUST[hi], f"gamma (ISO 281 Table 4, alpha = {hi:g}°)")
    return out(f_lo + (f_hi - f_lo) * (a - lo) / (hi - lo))


def dynamic_load_rating(D, dm, Z, alpha, kind, i=1, b_m=B_M_BALL):
    r"""Basic dynamic load rating C of a ball bearing [N] (ISO 281:2007, radial and thrust forms).

    Parameters
    ----------
    D : float       ball diameter [m]
    dm : float      pitch diameter [m]
    Z : int         balls per row [-]
    alpha : float   nominal contact angle [rad] (0 deep groove)
    kind : str      ``"deep_groove"``, ``"angular_contact"`` (radial rating C_r) or ``"thrust"`` (C_a)
    i : int         number of rows [-]
    b_m : float     rating factor for contemporary material and manufacture [-] (Table 1: 1.3)

    Returns
    -------
    float  C [N]

    Notes
    -----
    With D in mm and C in N (ISO 281:2007, radial ball bearings):

    .. math::

        C_r = b_m f_c (i\cos\alpha)^{0.7} Z^{2/3} D_w^{1.8} \quad (D_w \le 25.4\ \mathrm{mm}),
        \qquad C_r = 3.647\, b_m f_c (i\cos\alpha)^{0.7} Z^{2/3} D_w^{1.4} \quad (D_w > 25.4\ \mathrm{mm})

    thrust ball bearings, α ≠ 90°: C_a = b_m f_c (cos α)^0.7 tan α Z^(2/3) D_w^1.8;
    α = 90°: C_a = b_m f_c Z^(2/3) D_w^1.8 (3.647 D_w^1.4 for D_w > 25.4 mm in both).
    f_c from Table 2 (radial, γ = D cos α/dm) or Table 4 (thrust).  The radial table holds
    for groove radii ≤ 0.52 D (inner) and ≤ 0.53 D (outer); larger radii lower the rating
    below this value (the standard's note).

    Examples
    --------
    ISO/TS 16281 example bearing (6305 internals):

    >>> round(dynamic_load_rating(11.5e-3, 43.5e-3, 7, 0.0, "deep_groove"))
    22381
    """
    if kind not in ("deep_groove", "angular_contact", "thrust"):
        raise InputError("kind", kind, "must be one of deep_groove, angular_contact, thrust")
    D = float(checked("D", D, what=" [m]"))
    dm = float(checked("dm", dm, what=" [m]"))
    Z = float(checked("Z", Z, what=" (balls)"))
    a = float(alpha)
    D_mm = D * 1e3
    size = D_mm**1.8 if D_mm <= 25.4 else 3.647 * D_mm**1.4
    if kind == "thrust":
        if abs(np.cos(a)) < 1e-9:
            return float(b_m * fc_thrust(D / dm, a) * Z ** (2.0 / 3.0) * size)
        return float(b_m * fc_thrust(D * np.cos(a) / dm, a) * np.cos(a) ** 0.7 * np.tan(a)
                     * Z ** (2.0 / 3.0) * size)
    return float(b_m * fc_radial(D * np.cos(a) / dm) * (i * np.cos(a)) ** 0.7 * Z ** (2.0 / 3.0) * size)


def radial_load_factors(Fa_rel, alpha, kind):
    r"""Factors X, Y and the limit e of a single-row radial ball bearing (ISO 281:2007 Table 3).

    Parameters
    ----------
    Fa_rel : array_like  relative axial load: f0 Fa / C0r for deep groove bearings,
                         i Fa / C0r for angular contact at 15° (ignored at 20°–45°) [-]
    alpha : float        nominal contact angle [rad]: 0 for deep groove, 15°–45° angular contact
    kind : str           ``"deep_groove"`` or ``"angular_contact"``

    Returns
    -------
    (X, Y, e)  for Fa/Fr > e [-]; for Fa/Fr ≤ e use X = 1, Y = 0

    Notes
    -----
    Linear interpolation in the relative axial load (deep groove, 15°) and in α between the
    tabulated angles, as the standard's notes prescribe; below the first tabulated relative
    load the first row applies, above the last the last row.  Some makers tabulate the 15°
    row against f0 Fa/C0r (a grid ≈ 12.3× larger); with f0 ≈ 12–16 the two differ by < 3 % in Y.

    Examples
    --------
    >>> radial_load_factors(1.03, 0.0, "deep_groove")
    (0.56, 1.55, 0.28)
    >>> radial_load_factors(0.0, np.deg2rad(40.0), "angular_contact")
    (0.35, 0.57, 1.14)
    """
    rel = checked("Fa_rel", Fa_rel, strict=False, what=" (relative axial load)")
    if kind == "deep_groove":
        r = np.clip(rel, _DG_REL[0], _DG_REL[-1])
        return _DG_X, out(np.interp(r, _DG_REL, _DG_Y)), out(np.interp(r, _DG_REL, _DG_E))
    if kind != "angular_contact":
        raise InputError("kind", kind, "radial load factors exist for deep_groove and angular_contact")
    a = float(np.rad2deg(alpha))
    if not 15.0 - 1e-9 <= a <= 45.0 + 1e-9:
        raise InputError("alpha", alpha, "ISO 281 Table 3 covers angular contact ball bearings with α in "
                         "[15°, 45°] [rad]")

    def at(angle):
        if angle == 15.0:
            r = np.clip(rel, _AC15_REL[0], _AC15_REL[-1])
            return _AC15_X, np.interp(r, _AC15_REL, _AC15_Y), np.interp(r, _AC15_REL, _AC15_E)
        return _AC_CONST[angle]

    grid = [15.0] + sorted(_AC_CONST)
    lo = max(g for g in grid if g <= a + 1e-9)
    hi = min(g for g in grid if g >= a - 1e-9)
    Xl, Yl, el = at(lo)
    if hi == lo:
        return out(Xl), out(Yl), out(el)
    Xh, Yh, eh = at(hi)
    w = (a - lo) / (hi - lo)
    return out(Xl + w * (Xh - Xl)), out(Yl + w * (Yh - Yl)), out(el + w * (eh - el))


def dynamic_equivalent_load(Fr, Fa, X, Y, e):
    r"""Dynamic equivalent load P = X Fr + Y Fa for Fa/Fr > e, else Fr [N] (ISO 281:2007).

    Parameters
    ----------
    Fr, Fa : array_like  radial and axial load [N], ≥ 0
    X, Y, e : array_like factors of :func:`radial_load_factors` [-]

    Returns
    -------
    float or ndarray  P [N]

    Examples
    --------
    >>> dynamic_equivalent_load(1000.0, 500.0, 0.56, 1.55, 0.28)
    1335.0
    """
    Fr = checked("Fr", Fr, strict=False, what=" [N]")
    Fa = checked("Fa", Fa, strict=False, what=" [N]")
    big = Fa > np.asarray(e) * Fr
    return out(np.where(big, X * Fr + Y * Fa, Fr))


def basic_rating_life(C, P):
    r"""Basic rating life L10 = (C/P)³ of a ball bearing [10⁶ revolutions] (ISO 281:2007).

    Parameters
    ----------
    C : array_like  basic dynamic load rating [N]
    P : array_like  dynamic equivalent load [N], > 0

    Returns
    -------
    float or ndarray  L10 [10⁶ rev]

    Notes
    -----
    An unloaded bearing (P = 0) has no finite fatigue life: InputError, as for any P that
    makes (C/P)³ overflow; the function never returns inf or NaN.

    Examples
    --------
    >>> basic_rating_life(30000.0, 3000.0)
    1000.0
    """
    C = checked("C", C, what=" [N]")
    P = checked("P", P, what=" [N] (an unloaded bearing has no finite rating life)")
    with np.errstate(over="ignore"):
        L = (C / P) ** 3
    if not np.all(np.isfinite(L)):
        raise InputError("P", P, "so small against C that (C/P)^3 overflows; no finite rating life [N]")
    return out(L)


def reference_viscosity(n_rpm, dm):
    r"""Reference kinematic viscosity ν1 for adequate lubrication [m²/s] (ISO 281:2007).

    Parameters
    ----------
    n_rpm : array_like  rotational speed [rpm], > 0
    dm : array_like     pitch diameter [m] (the standard's mean diameter D_pw)

    Returns
    -------
    float or ndarray  ν1 [m²/s]

    Notes
    -----
    With n in r/min, D_pw in mm and ν1 in mm²/s:

    .. math::

        \nu_1 = 45\,000\, n^{-0.83} D_{pw}^{-0.5} \quad (n < 1000), \qquad
        \nu_1 = 4\,500\, n^{-0.5} D_{pw}^{-0.5} \quad (n \ge 1000)

    (the two branches differ by 2 % at 1000 r/min, as in the standard).

    Examples
    --------
    >>> round(reference_viscosity(3000.0, 70e-3) * 1e6, 3)
    9.82
    """
    n = checked("n_rpm", n_rpm, what=" [rpm] (the reference viscosity needs a speed)")
    dm_mm = checked("dm", dm, what=" [m]") * 1e3
    nu1 = np.where(n < 1000.0, 45000.0 * n**-0.83, 4500.0 * n**-0.5) * dm_mm**-0.5
    return out(nu1 * 1e-6)


def viscosity_ratio(nu, nu1):
    r"""Viscosity ratio κ = ν / ν1 [-] (ISO 281:2007).

    Parameters
    ----------
    nu : array_like   operating kinematic viscosity of the lubricant (base oil for a grease) [m²/s]
    nu1 : array_like  reference viscosity of :func:`reference_viscosity` [m²/s]

    Returns
    -------
    float or ndarray  κ [-]

    Examples
    --------
    >>> viscosity_ratio(20e-6, 10e-6)
    2.0
    """
    return out(checked("nu", nu, what=" [m^2/s]") / checked("nu1", nu1, what=" [m^2/s]"))


def contamination_factor(level, dm, bound="mid"):
    r"""Contamination factor e_C of the ISO 281:2007 simplified approach [-].

    Parameters
    ----------
    level : str or float  one of :data:`CONTAMINATION_LEVELS` (``"extreme_cleanliness"`` ...
                          ``"very_severe_contamination"``), or a value in [0, 1] used as is
    dm : float            pitch diameter [m] (the table has columns dm < 100 mm and ≥ 100 mm)
    bound : str           ``"mid"`` (default), ``"low"`` or ``"high"`` end of the tabulated range

    Returns
    -------
    float  e_C [-]

    Notes
    -----
    The simplified table of ISO 281:2007 gives a range per cleanliness level, for
    D_pw < 100 mm / ≥ 100 mm: extreme cleanliness 1 / 1; high cleanliness 0.8–0.6 / 0.9–0.8;
    normal cleanliness 0.6–0.5 / 0.8–0.6; slight contamination 0.5–0.3 / 0.6–0.4; typical
    contamination 0.3–0.1 / 0.4–0.2; severe contamination 0.1–0 / 0.1–0; very severe 0 / 0.
    The middle of the range is the default; the standard's detailed approach (ISO 4406
    codes, filtration, κ dependence) is not implemented.

    Examples
    --------
    >>> contamination_factor("normal_cleanliness", 70e-3)
    0.55
    >>> contamination_factor("normal_cleanliness", 120e-3, bound="high")
    0.8
    """
    if not isinstance(level, str):
        v = float(level)
        if not 0.0 <= v <= 1.0:
            raise InputError("contamination", level, "a contamination factor e_C must lie in [0, 1]")
        return v
    if level not in CONTAMINATION_LEVELS:
        raise InputError("contamination", level, f"must be one of {', '.join(CONTAMINATION_LEVELS)} "
                         "or a value e_C in [0, 1]")
    if bound not in ("mid", "low", "high"):
        raise InputError("bound", bound, "must be mid, low or high")
    lo, hi = CONTAMINATION_LEVELS[level][0 if float(dm) < 0.1 else 1]
    return {"low": lo, "high": hi, "mid": 0.5 * (lo + hi)}[bound]


def fatigue_load_limit(C0, dm):
    r"""Fatigue load limit C_u of a ball bearing from its static rating [N] (ISO 281:2007).

    Parameters
    ----------
    C0 : array_like  basic static load rating [N]
    dm : array_like  pitch diameter [m]

    Returns
    -------
    float or ndarray  C_u [N]

    Notes
    -----
    The standard's approximation for ball bearings:

    .. math::

        C_u = C_0 / 22 \quad (D_{pw} \le 100\ \mathrm{mm}), \qquad
        C_u = \frac{C_0}{22} \left(\frac{100}{D_{pw}}\right)^{0.5} \quad (D_{pw} > 100\ \mathrm{mm})

    Examples
    --------
    >>> fatigue_load_limit(22000.0, 70e-3), round(fatigue_load_limit(22000.0, 400e-3), 1)
    (1000.0, 500.0)
    """
    C0 = checked("C0", C0, what=" [N]")
    dm_mm = checked("dm", dm, what=" [m]") * 1e3
    return out(C0 / 22.0 * np.where(dm_mm > 100.0, np.sqrt(100.0 / np.maximum(dm_mm, 100.0)), 1.0))


def life_modification_factor(kappa, eC_Cu_P, kind="radial"):
    r"""Life modification factor a_ISO of ball bearings (ISO 281:2007, systems approach) [-].

    Parameters
    ----------
    kappa : array_like    viscosity ratio κ [-], > 0; evaluated at κ = 0.1 below 0.1 and at κ = 4
                          above 4 (the standard's range)
    eC_Cu_P : array_like  e_C C_u / P [-], ≥ 0
    kind : str            ``"radial"`` or ``"thrust"`` ball bearings

    Returns
    -------
    float or ndarray  a_ISO [-], in [0.1, 50]

    Notes
    -----
    Radial ball bearings (thrust: e_C C_u / P replaced by e_C C_u / (3 P)):

    .. math::

        a_{ISO} = 0.1\left[1 - \left(2.5671 - \frac{x}{\kappa^{y}}\right)^{0.83}
                  \left(\frac{e_C C_u}{P}\right)^{1/3}\right]^{-9.3}

    with (x, y) = (2.2649, 0.054381) for 0.1 ≤ κ < 0.4, (1.9987, 0.19087) for 0.4 ≤ κ < 1 and
    (1.9987, 0.071739) for 1 ≤ κ ≤ 4 (ISO 281:2007 eqs for radial ball bearings; the three branches meet at 1,
    and at 0.4 to 3e-5 in the bracket — the exponents rounded to 0.054 / 0.19 / 0.071, a_ISO moves by up to 7 %
    near κ = 0.1).  a_ISO is capped at
    :data:`A_ISO_MAX` = 50, also where the bracket would vanish (fatigue-load-limit regime);
    at κ = 0.1 it is ≈ 0.1 whatever the load.

    Examples
    --------
    >>> round(life_modification_factor(1.0, 0.5 * 1000.0 / 2000.0), 3)
    10.57
    >>> life_modification_factor(4.0, 10.0)
    50.0
    """
    if kind not in ("radial", "thrust"):
        raise InputError("kind", kind, "must be radial or thrust")
    k = np.clip(checked("kappa", kappa, what=" (viscosity ratio)"), *_KAPPA_RANGE)
    r = checked("eC_Cu_P", eC_Cu_P, strict=False, what=" (e_C C_u / P)")
    if kind == "thrust":
        r = r / 3.0
    x = np.where(k < 0.4, 2.2649, 1.9987)
    y = np.where(k < 0.4, 0.054381, np.where(k < 1.0, 0.19087, 0.071739))
    bracket = 1.0 - (2.5671 - x / k**y) ** 0.83 * r ** (1.0 / 3.0)
    floor = (A_ISO_MAX / 0.1) ** (-1.0 / 9.3)        # bracket at which a_ISO reaches the cap
    a = np.where(bracket > floor, 0.1 * np.maximum(bracket, floor) ** -9.3, A_ISO_MAX)
    return out(np.minimum(a, A_ISO_MAX))


def modified_rating_life(a_ISO, L10, a1=1.0):
    r"""Modified rating life L_nm = a1 a_ISO L10 [10⁶ revolutions] (ISO 281:2007).

    Parameters
    ----------
    a_ISO : array_like  life modification factor [-]
    L10 : array_like    basic rating life [10⁶ rev]
    a1 : float          life modification factor for reliability [-] (1 for 90 %)

    Returns
    -------
    float or ndarray  L_nm [10⁶ rev]

    Examples
    --------
    >>> modified_rating_life(2.0, 1000.0)
    2000.0
    """
    return out(a1 * checked("a_ISO", a_ISO, what="") * checked("L10", L10, what=" [1e6 rev]"))
