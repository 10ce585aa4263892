r"""Operating clearance of a mounted, warm, running ball bearing: fits, thermal and centrifugal expansion.

The unmounted radial (diametral) clearance P_d of a bearing at the reference temperature 20 °C (ISO 1 [6];
ISO 5753-1 groups: :func:`thermobear.contact.geometry.radial_clearance`) changes in service:

.. math::

    P_{d,op} = P_d + Δd_o − Δd_i − 2 ΔD

with the changes of the outer and inner raceway (groove-bottom) diameters d_o = d_m + D, d_i = d_m − D and
of the ball diameter D:

* interference fits (Lamé thick cylinders, plane stress [1], [2]): the seat pressure p of the inner ring on
  its (solid or hollow) shaft, :func:`fit_pressure`, expands the inner raceway by
  Δd_i = 4 p a² b / (E (b² − a²)) (a = d/2 the bore, b = d_i/2 the raceway radius: the ring's thinnest
  section, the effective outer radius — with a solid shaft of the same steel Δd_i = I d/d_i, the
  classical result [3] ch. 3); the outer ring in its housing contracts by 4 p f² e / (E (f² − e²))
  (e = d_o/2, f = D_o/2 its outside radius), :func:`lame_displacement`;
* the interferences themselves from the limits of the seats (ISO 286 tolerance classes: j5 … p6 shafts,
  H7 … P7 housings) and of the rings (ISO 492 normal class), :func:`fit_interference`
  (materials/iso286_fits.toml), corrected for the parts' temperatures (a warmer shaft tightens, a warmer
  inner ring loosens the inner fit; a warmer housing loosens the outer one);
* free thermal expansion of every part, α L (T − 20 °C);
* centrifugal expansion of the rotating inner ring (a rotating annular disc [1]), which also loosens
  its fit by the difference of the bore's and the shaft's growth, :func:`rotating_ring_displacement`.

A negative P_d,op is a radial preload: every ball is compressed by −P_d,op/2 with the rings centred,
:func:`clearance_preload`.  :func:`expanded_bearing` gives the bearing whose rings and balls have grown
by their temperatures (groove radii, pitch diameter, clearance, free contact angle): the load
distribution of :mod:`thermobear.loads` then carries the thermally induced preload (a duplex set:
:func:`thermobear.loads.sets.warm_bearing_set`).

References
----------
.. [1] Timoshenko, S. P. & Goodier, J. N. (1970). *Theory of Elasticity*, 3rd ed., McGraw-Hill, ch. 4
   (two-dimensional problems in polar coordinates: the thick-walled cylinder under internal and external
   pressure, and the rotating disc of uniform thickness, plane stress — the radial displacements u(r)).
.. [2] Budynas, R. G. & Nisbett, J. K. (2011). *Shigley's Mechanical Engineering Design*, 9th ed.,
   McGraw-Hill, §3–16 (press and shrink fits: the interface pressure of two cylinders of different
   materials).
.. [3] Harris, T. A. & Kotzalas, M. N. (2007). *Essential Concepts of Bearing Technology*, 5th ed., CRC Press,
   ch. 3 (interference fitting and clearance: effect of the fits on the clearance, differential thermal
   expansion).
.. [4] ISO 286-1:2010 and ISO 286-2:2010 (tolerance grades, fundamental deviations, limits of shafts and
   holes); ISO 492:2014 (bearing ring tolerances, normal class) — materials/iso286_fits.toml.
.. [5] ISO 5753-1:2009, radial internal clearance of radial ball bearings (materials/iso5753_clearance.toml).
.. [6] ISO 1:2016, standard reference temperature for geometrical product specification: 20 °C.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermobear.arrays import instance_of, within
from thermobear.contact.geometry import BallBearing, bearing
from thermobear.contact.materials import Material, material
from thermobear.errors import InputError
from thermobear.files import data_dir, lookup, read_toml
from thermobear.units import ZERO_C_K

__all__ = ["T_REF_C", "seat_deviations", "ring_deviations", "fit_interference", "lame_displacement",
           "fit_pressure", "rotating_ring_displacement", "raceway_growth", "seated_raceway_growth",
           "OperatingClearance", "operating_clearance",
           "clearance_preload", "expanded_bearing", "steel_expansion", "SHAFT_CLASSES", "HOUSING_CLASSES"]

T_REF_C = 20.0          #: reference temperature of sizes and clearances [°C] (ISO 1)
_INTERFERENCE = ("min", "mean", "max")
#: The tolerance classes of seats :func:`seat_deviations` knows (materials/iso286_fits.toml).
SHAFT_CLASSES = tuple(f"{z}{g}" for z in ("g", "h", "js", "k", "m", "n", "p") for g in (5, 6, 7)) + ("j5", "j6")
HOUSING_CLASSES = tuple(f"{z}{g}" for z in ("H", "JS") for g in (5, 6, 7)) + ("J7", "K7", "M7", "N7", "P7")


def _table() -> dict:
    return read_toml(str(data_dir("materials") / "iso286_fits.toml"))


def steel_expansion() -> float:
    """Linear thermal expansion coefficient of the bearing steel AISI 52100 [1/K] (materials/solids).

    >>> steel_expansion()
    1.25e-05
    """
    return float(lookup("materials", "solids", "aisi-52100", "material")["alpha_th_1_K"])


def _step(d_mm, over, incl, what):
    """Index of the size step over < d ≤ incl [mm]."""
    for k, (lo, hi) in enumerate(zip(over, incl)):
        if lo < d_mm <= hi:
            return k
    raise InputError(what, d_mm, f"nominal size must lie in ({over[0]}, {incl[-1]}] mm (the tabulated range)")


def seat_deviations(diameter, zone: str):
    r"""Limit deviations (lower, upper) of a shaft or housing seat of ISO 286 tolerance class ``zone`` [m].

    Parameters
    ----------
    diameter : float   nominal size [m], 3 mm < d ≤ 400 mm
    zone : str         a shaft class (lower-case letter: g, h, j, js, k, m, n, p; grades 5–7, e.g. ``"k5"``) or a
                       housing class (upper case: H, JS of grades 5–7; J7, K7, M7, N7, P7)

    Returns
    -------
    (lower, upper) deviation [m]

    Notes
    -----
    A shaft's limits are its fundamental deviation ei and ei + IT (g, h: es − IT and es, h: es = 0; js: ±IT/2), a
    hole's ES − IT and ES (H: EI = 0; JS: ±IT/2); IT grades and deviations of ISO 286-1:2010 Tables 1–5 [4].

    Examples
    --------
    >>> [round(v * 1e6) for v in seat_deviations(0.040, "k5")], [round(v * 1e6) for v in seat_deviations(0.080, "H7")]
    ([2, 13], [0, 30])
    >>> [round(v * 1e6) for v in seat_deviations(0.040, "g6")]
    [-25, -9]
    """
    t = _table()["iso286"]
    d_mm = float(diameter) * 1e3
    k = _step(d_mm, t["over_mm"], t["incl_mm"], f"seat diameter for {zone}")
    z = str(zone)
    letter, grade = z.rstrip("0123456789"), z[len(z.rstrip("0123456789")):]
    if f"IT{grade}" not in t["IT_um"]:
        raise InputError("zone", zone, f"tolerance grade must be one of {', '.join(t['IT_um'])}")
    it = float(t["IT_um"][f"IT{grade}"][k])
    if letter in ("js", "JS"):
        lo, hi = -0.5 * it, 0.5 * it
    elif letter == "h":
        lo, hi = -it, 0.0
    elif letter == "H":
        lo, hi = 0.0, it
    elif letter.islower() and letter in t["shaft_es_um"]:
        es = float(t["shaft_es_um"][letter][k])
        lo, hi = es - it, es
    elif letter.islower() and letter in t["shaft_ei_um"] and not (letter == "j" and grade == "7"):
        ei = float(t["shaft_ei_um"][letter][k])
        lo, hi = ei, ei + it
    elif z in t["hole_ES_um"]:
        es = float(t["hole_ES_um"][z][k])
        lo, hi = es - it, es
    else:
        known = ["g5-7", "h5-7", "js5-7", "j5", "j6", "k5-7", "m5-7", "n5-7", "p5-7", "H5-7", "JS5-7"] + list(t["hole_ES_um"])
        raise InputError("zone", zone, f"tolerance class not tabulated; known: {', '.join(known)}")
    return lo * 1e-6, hi * 1e-6


def ring_deviations(diameter, ring: str):
    """Limit deviations (lower, upper) of a bearing's mean bore (``ring="inner"``) or mean outside diameter
    (``"outer"``), ISO 492 normal tolerance class [m].

    >>> [round(v * 1e6) for v in ring_deviations(0.040, "inner")], [round(v * 1e6) for v in ring_deviations(0.080, "outer")]
    ([-12, 0], [-13, 0])
    """
    t = _table()["iso492_normal"]
    d_mm = float(diameter) * 1e3
    if ring == "inner":
        k = _step(d_mm, t["bore_over_mm"], t["bore_incl_mm"], "bearing bore")
        return float(t["bore_low_um"][k]) * 1e-6, 0.0
    if ring == "outer":
        k = _step(d_mm, t["outer_over_mm"], t["outer_incl_mm"], "bearing outside diameter")
        return float(t["outer_low_um"][k]) * 1e-6, 0.0
    raise InputError("ring", ring, "inner or outer")


def fit_interference(diameter, zone: str, ring: str):
    r"""Diametral interference of a bearing ring on its seat: (minimum, mean, maximum) [m], > 0 interference.

    Parameters
    ----------
    diameter : float   the bearing's bore (``ring="inner"``, shaft class ``zone``) or outside diameter (``"outer"``,
                       housing class ``zone``) [m]
    zone : str         ISO 286 class of the seat (:func:`seat_deviations`)
    ring : str         ``"inner"`` or ``"outer"``

    Notes
    -----
    Inner ring: I = shaft − bore, from (ei − 0) to (es − Δd_mp,low); outer ring: I = outside diameter − housing
    bore, from (ΔD_mp,low − ES) to (0 − EI); ISO 286 [4] and ISO 492 normal class.  The mean is the middle of
    the range (no surface smoothing; the effective interference of a rough seat is smaller, [3] ch. 3).

    Examples
    --------
    A 6208 (bore 40, outside 80 mm) on a k5 shaft in an H7 housing: 2–25 µm interference inside, a clearance
    fit (−43 … 0 µm) outside.

    >>> [round(v * 1e6, 1) for v in fit_interference(0.040, "k5", "inner")]
    [2.0, 13.5, 25.0]
    >>> [round(v * 1e6, 1) for v in fit_interference(0.080, "H7", "outer")]
    [-43.0, -21.5, 0.0]
    """
    lo_s, hi_s = seat_deviations(diameter, zone)
    lo_r, hi_r = ring_deviations(diameter, ring)
    if ring == "inner":
        if not zone[0].islower():
            raise InputError("zone", zone, "an inner ring sits on a shaft: a lower-case class (e.g. k5)")
        i_min, i_max = lo_s - hi_r, hi_s - lo_r
    else:
        if not zone[0].isupper():
            raise InputError("zone", zone, "an outer ring sits in a housing: an upper-case class (e.g. H7)")
        i_min, i_max = lo_r - hi_s, hi_r - lo_s
    return i_min, 0.5 * (i_min + i_max), i_max


def lame_displacement(r, a, b, p_in=0.0, p_out=0.0, E=210e9, nu=0.3):
    r"""Radial displacement of a thick cylinder under internal and external pressure (plane stress) [m].

    Parameters
    ----------
    r : array_like       radius where the displacement is wanted [m], a ≤ r ≤ b
    a, b : float         inner and outer radius [m], 0 ≤ a < b (a = 0: a solid cylinder, then p_in is unused)
    p_in, p_out : float  pressure on the inner and outer surface [Pa] (> 0 compresses the surface)
    E, nu : float        Young's modulus [Pa] and Poisson's ratio [-]

    Returns
    -------
    u : radial displacement [m] (> 0 outwards)

    Notes
    -----
    Lamé (Timoshenko & Goodier 1970 [1] ch. 4):

    .. math::

        u(r) = \frac{1}{E}\left[(1 − ν)\frac{p_i a^2 − p_o b^2}{b^2 − a^2}\, r
               + (1 + ν)\frac{(p_i − p_o)\, a^2 b^2}{(b^2 − a^2)\, r}\right]

    At the outer surface under internal pressure only: u(b) = 2 p_i a² b / (E (b² − a²)).

    Examples
    --------
    >>> round(float(lame_displacement(0.03, 0.02, 0.03, p_in=50e6)) * 1e6, 3)
    11.429
    """
    r = np.asarray(r, dtype=float)
    if not (0.0 <= a < b):
        raise InputError("a, b", (a, b), "radii must satisfy 0 <= a < b [m]")
    if a == 0.0:
        return (1.0 - nu) * (-p_out) * r / E
    k = b * b - a * a
    return ((1.0 - nu) * (p_in * a * a - p_out * b * b) / k * r + (1.0 + nu) * (p_in - p_out) * a * a * b * b / (k * r)) / E


def fit_pressure(interference, d, inner_bore, outer_diameter, E_inner=210e9, nu_inner=0.3, E_outer=210e9,
                 nu_outer=0.3):
    r"""Interface pressure of two fitted cylinders (a shaft in a ring, a ring in a housing) [Pa].

    Parameters
    ----------
    interference : array_like  diametral interference [m]; ≤ 0 (a clearance fit) gives 0
    d : float                  diameter of the interface [m]
    inner_bore : float         bore of the inner member [m] (0: a solid shaft)
    outer_diameter : float     outside diameter of the outer member [m] (``inf``: a thick housing)
    E_inner, nu_inner, E_outer, nu_outer : float   elastic constants of the inner / outer member [Pa, -]

    Notes
    -----
    Equal and opposite radial displacements close the radial interference I/2 (Budynas & Nisbett 2011 [2]
    §3–16, from Lamé [1]), with c = inner_bore/2, R = d/2, o = outer_diameter/2:

    .. math::

        p = \frac{I/2}{\frac{R}{E_o}\left(\frac{o^2 + R^2}{o^2 − R^2} + ν_o\right)
            + \frac{R}{E_i}\left(\frac{R^2 + c^2}{R^2 − c^2} − ν_i\right)}

    Examples
    --------
    A 40 mm solid steel shaft in an inner ring of raceway diameter 48 mm, 13.5 µm interference:

    >>> round(float(fit_pressure(13.5e-6, 0.040, 0.0, 0.048)) / 1e6, 2)
    10.83
    """
    I = np.asarray(interference, dtype=float)
    R = 0.5 * d
    c, o = 0.5 * inner_bore, 0.5 * outer_diameter
    if not (0.0 <= c < R < o):
        raise InputError("diameters", (inner_bore, d, outer_diameter), "need inner_bore < d < outer_diameter [m]")
    outer = 1.0 if np.isinf(o) else (o * o + R * R) / (o * o - R * R)
    flex = R / E_outer * (outer + nu_outer) + R / E_inner * ((R * R + c * c) / (R * R - c * c) - nu_inner)
    return np.maximum(0.5 * I / flex, 0.0)


def rotating_ring_displacement(r, a, b, omega, rho=7830.0, E=210e9, nu=0.3):
    r"""Radial displacement of a ring (annular disc, plane stress, free edges) spinning at ω [m].

    Parameters
    ----------
    r : array_like    radius [m], a ≤ r ≤ b
    a, b : float      inner and outer radius [m] (a = 0: a solid disc)
    omega : array_like  angular speed [rad/s]
    rho, E, nu : float  density [kg/m³], Young's modulus [Pa], Poisson's ratio [-]

    Notes
    -----
    Timoshenko & Goodier 1970 [1] ch. 4 (rotating disc):

    .. math::

        u(r) = \frac{ρ ω^2}{8 E}\left[(3 + ν)(1 − ν)(a^2 + b^2)\, r + (3 + ν)(1 + ν)\frac{a^2 b^2}{r} − (1 − ν^2) r^3\right]

    (a = 0: u = (1 − ν) ρ ω² r [(3 + ν) b² − (1 + ν) r²] / (8E)); at the outer edge
    u(b) = ρ ω² b [(3 + ν) a² + (1 − ν) b²] / (4E).

    Examples
    --------
    An inner ring 40/48 mm at 10 000 rpm grows by 0.42 µm at its raceway (radius):

    >>> w = 10000 * np.pi / 30
    >>> round(float(rotating_ring_displacement(0.024, 0.020, 0.024, w)) * 1e6, 3)
    0.423
    """
    r = np.asarray(r, dtype=float)
    w2 = np.asarray(omega, dtype=float) ** 2
    if not (0.0 <= a < b):
        raise InputError("a, b", (a, b), "radii must satisfy 0 <= a < b [m]")
    if a == 0.0:
        return (1.0 - nu) * rho * w2 * r * ((3.0 + nu) * b * b - (1.0 + nu) * r * r) / (8.0 * E)
    return rho * w2 / (8.0 * E) * ((3.0 + nu) * (1.0 - nu) * (a * a + b * b) * r + (3.0 + nu) * (1.0 + nu) * a * a * b * b / r
                                   - (1.0 - nu * nu) * r ** 3)


def raceway_growth(brg: BallBearing, n_rpm):
    r"""Centrifugal growth of a rotating inner ring's raceway (its groove bottom, radius) [m].

    The inner ring as a free annular disc from its bore d/2 to its raceway d_i/2 = (d_m − D)/2, spinning at n
    (:func:`rotating_ring_displacement`, Timoshenko & Goodier 1970 [1] ch. 4; the ring's own material):

    .. math:: u_i = u\bigl(d_i/2;\ a = d/2,\ b = d_i/2,\ ω = π n / 30\bigr)

    The raceway diameter grows by 2u_i and the operating diametral clearance falls by as much
    (:func:`operating_clearance`); the groove curvature centre moves out with it (:func:`expanded_bearing`'s
    ``u_inner``).  This is the free ring's growth: on an interference seat the fit's relief takes back part of it
    (:func:`seated_raceway_growth`; Harris & Kotzalas 2007 [3] ch. 3).

    Parameters
    ----------
    brg : BallBearing   needs ``bore`` where n > 0
    n_rpm : array_like  speed of the inner ring [rpm]

    Returns
    -------
    ndarray or float    u_i [m] (0.0 without a bore at rest)

    Examples
    --------
    A 7014C (bore 70 mm, raceway ≈ 78.5 mm) at 12 000 rpm: about 3 µm on the radius.

    >>> from thermobear.contact.geometry import bearing
    >>> round(float(raceway_growth(bearing("7014C"), 12000.0)) * 1e6, 2)
    2.96
    """
    w = np.asarray(n_rpm, dtype=float) * np.pi / 30.0
    if np.any(w > 0) and brg.bore is None:
        raise InputError("bearing.bore", None, "the centrifugal growth of the inner ring needs its bore [m]")
    if brg.bore is None:
        return 0.0
    rm, d_i = brg.ring_material, brg.dm - brg.D
    return rotating_ring_displacement(0.5 * d_i, 0.5 * brg.bore, 0.5 * d_i, w, rm.rho, rm.E, rm.nu)


def seated_raceway_growth(brg: BallBearing, n_rpm, *, shaft: str | None = None, I_inner_m=None,
                          shaft_bore: float = 0.0, shaft_material=None, interference: str = "mean"):
    r"""Growth of a rotating inner ring's raceway on its seat at speed (radius) [m]: the free ring's centrifugal
    growth (:func:`raceway_growth`) less the relief of its fit — the ring's bore grows more than the shaft's, the
    interference falls and with it the fit's expansion of the raceway (Lamé; Harris & Kotzalas 2007 [3] ch. 3) —, as
    :func:`operating_clearance`'s inner terms give them at 20 °C:

    .. math:: u = −\tfrac12 \left[P_{d,op}(n) − P_{d,op}(0)\right] = u_i − \tfrac12\left[Δ_{fit}(n) − Δ_{fit}(0)\right]

    Parameters
    ----------
    brg : BallBearing           needs ``bore``
    n_rpm : array_like          speed of the inner ring and shaft [rpm]
    shaft, I_inner_m, shaft_bore, shaft_material, interference : the seat, as :func:`operating_clearance` (neither
                                ``shaft`` nor ``I_inner_m``: a free ring, :func:`raceway_growth`)

    Returns
    -------
    ndarray or float            u [m]

    Examples
    --------
    A 7014C at 12 000 rpm: a free ring grows 2.96 µm on its raceway's radius; on a solid steel shaft with 16 µm
    interference the seat takes back most of it.

    >>> from thermobear.contact.geometry import bearing
    >>> b = bearing("7014C")
    >>> [round(float(u) * 1e6, 2) for u in (raceway_growth(b, 12000.0), seated_raceway_growth(b, 12000.0, I_inner_m=16e-6))]
    [2.96, 0.62]
    """
    n = np.asarray(n_rpm, dtype=float)
    if shaft is None and I_inner_m is None:
        return raceway_growth(brg, n)
    oc = operating_clearance(brg, shaft=shaft, I_inner_m=I_inner_m, shaft_bore=shaft_bore,
                             shaft_material=shaft_material, interference=interference,
                             n_rpm=np.stack([np.zeros_like(n), n]))
    return -0.5 * (oc.Pd[1] - oc.Pd[0])


@dataclass(frozen=True)
class OperatingClearance:
    """Operating radial clearance of a bearing and its parts (diametral, [m]; leading axes as the inputs).

    Attributes
    ----------
    Pd : operating diametral clearance [m] (negative: a radial preload, :func:`clearance_preload`)
    Pd_unmounted : the bearing's clearance at 20 °C before mounting [m]
    fit_inner, fit_outer : change of the clearance by the fits at temperature and speed [m] (≤ 0)
    thermal : change by the free thermal expansion of rings and balls [m]
    centrifugal : change by the centrifugal growth of the inner raceway [m] (≤ 0)
    interference_inner, interference_outer : diametral interferences at temperature and speed [m] (≤ 0: loose)
    pressure_inner, pressure_outer : seat pressures [Pa]
    """

    Pd: np.ndarray
    Pd_unmounted: float
    fit_inner: np.ndarray
    fit_outer: np.ndarray
    thermal: np.ndarray
    centrifugal: np.ndarray
    interference_inner: np.ndarray
    interference_outer: np.ndarray
    pressure_inner: np.ndarray
    pressure_outer: np.ndarray


def operating_clearance(brg: BallBearing, *, shaft: str | None = None, housing: str | None = None,
                        T_inner_C=T_REF_C, T_outer_C=T_REF_C, T_ball_C=None, T_shaft_C=None, T_housing_C=None,
                        n_rpm=0.0, interference: str = "mean", shaft_bore: float = 0.0,
                        housing_diameter: float = np.inf, Pd_unmounted: float | None = None,
                        alpha_ring: float | None = None, alpha_ball: float | None = None,
                        alpha_shaft: float | None = None, alpha_housing: float | None = None,
                        shaft_material=None, housing_material=None, I_inner_m=None,
                        I_outer_m=None) -> OperatingClearance:
    r"""Operating radial clearance of a mounted bearing at its temperatures and speed.

    Parameters
    ----------
    brg : BallBearing          needs ``bore`` and ``outer_diameter`` for a fit (or its catalogue name)
    shaft, housing : str       ISO 286 classes of the seats (``"k5"``, ``"H7"``); ``None``: no fit on that ring
    T_inner_C, T_outer_C : array_like  ring temperatures [°C]
    T_ball_C : array_like      ball temperature [°C] (default: the mean of the rings')
    T_shaft_C, T_housing_C : array_like  seat temperatures [°C] (default: those of the ring they carry)
    n_rpm : array_like         inner-ring (and shaft) speed [rpm]
    interference : str         ``"min"``, ``"mean"`` (default) or ``"max"`` of the fits' ranges (:func:`fit_interference`)
    shaft_bore : float         bore of a hollow shaft [m] (0: solid)
    housing_diameter : float   outside diameter of the housing around the outer ring [m] (``inf``: thick)
    Pd_unmounted : float       clearance before mounting [m] (default: the bearing's ``Pd``)
    alpha_ring, alpha_ball, alpha_shaft, alpha_housing : float  thermal expansion coefficients [1/K]
                               (default: AISI 52100, :func:`steel_expansion`)
    shaft_material, housing_material : Material   elastic constants of the seats (default: the ring material), or
                               a material's catalogue name (:func:`~thermobear.contact.materials.material`)
    I_inner_m, I_outer_m : float  diametral interference of a seat at 20 °C [m] (negative: clearance), given instead
                               of its class's (e.g. the seat of a machine's network); a ring with neither sits free

    Returns
    -------
    OperatingClearance

    Notes
    -----
    P_d,op = P_d + Δd_o − Δd_i − 2ΔD (module docstring): d_i = d_m − D and d_o = d_m + D are the raceway
    (groove-bottom) diameters — the effective outer diameter of the inner ring and inner diameter of the outer
    ring in the Lamé formulae, and the diameters that expand with temperature; interference at temperature
    I_i,T = I_i + α_s d (T_s − 20) − α_r d (T_i − 20) − 2 [u_ω,ring(d/2) − u_ω,shaft(d/2)],
    I_o,T = I_o − α_h D (T_h − 20) + α_r D (T_o − 20).  Fits per Lamé (:func:`fit_pressure`,
    :func:`lame_displacement`), rotation per :func:`rotating_ring_displacement` and :func:`raceway_growth` (Timoshenko & Goodier 1970;
    Harris & Kotzalas 2007 ch. 3).

    Examples
    --------
    A 6208 C3 (24 µm unmounted, the group's mid value) on a k5 shaft in an H7 housing, inner ring 70 °C, outer
    ring 55 °C: the mean fit (13.5 µm) takes 11.3 µm, the warmer inner ring another 11.3 µm.

    >>> from thermobear.contact.geometry import bearing
    >>> b = bearing("6208").with_(Pd=24e-6, clearance_group="C3")
    >>> oc = operating_clearance(b, shaft="k5", housing="H7", T_inner_C=70.0, T_outer_C=55.0)
    >>> [round(float(v) * 1e6, 2) for v in (oc.Pd, oc.fit_inner, oc.thermal)]
    [1.36, -11.31, -11.34]
    """
    if interference not in _INTERFERENCE:
        raise InputError("interference", interference, f"must be one of {', '.join(_INTERFERENCE)}")
    brg = instance_of(brg, BallBearing, "brg", bearing)
    shaft_material, housing_material = (None if m is None else instance_of(m, Material, name, material) for m, name
                                        in ((shaft_material, "shaft_material"), (housing_material, "housing_material")))
    a_st = None
    alphas = []
    for v in (alpha_ring, alpha_ball, alpha_shaft, alpha_housing):
        if v is None:
            a_st = steel_expansion() if a_st is None else a_st
            v = a_st
        if not (np.isfinite(v) and 0 <= v < 1e-3):
            raise InputError("alpha", v, "thermal expansion coefficient must lie in [0, 1e-3) [1/K]")
        alphas.append(float(v))
    a_r, a_b, a_s, a_h = alphas
    Ti, To = np.asarray(T_inner_C, dtype=float), np.asarray(T_outer_C, dtype=float)
    Tb = 0.5 * (Ti + To) if T_ball_C is None else np.asarray(T_ball_C, dtype=float)
    Ts = Ti if T_shaft_C is None else np.asarray(T_shaft_C, dtype=float)
    Th = To if T_housing_C is None else np.asarray(T_housing_C, dtype=float)
    for name, v in (("T_inner_C", Ti), ("T_outer_C", To), ("T_ball_C", Tb), ("T_shaft_C", Ts), ("T_housing_C", Th)):
        if not np.all(np.isfinite(v)) or np.any(v < -ZERO_C_K):
            raise InputError(name, v, "temperature must be finite and above absolute zero [°C]")
    w = np.asarray(n_rpm, dtype=float) * np.pi / 30.0
    Pd0 = brg.Pd if Pd_unmounted is None else float(Pd_unmounted)
    rm = brg.ring_material
    sm, hm = shaft_material or rm, housing_material or rm
    d_i, d_o, D = brg.dm - brg.D, brg.dm + brg.D, brg.D
    thermal = a_r * d_o * (To - T_REF_C) - a_r * d_i * (Ti - T_REF_C) - 2.0 * a_b * D * (Tb - T_REF_C)
    u_w = raceway_growth(brg, n_rpm)
    zero = 0.0 * (Ti + To + Tb + Ts + Th + w)
    I_i = I_o = p_i = p_o = fit_i = fit_o = zero
    if shaft is not None or I_inner_m is not None:
        d = _needs(brg.bore, "bore", "a shaft fit")
        a, b = 0.5 * d, 0.5 * d_i
        I0 = (fit_interference(d, shaft, "inner")[_INTERFERENCE.index(interference)] if I_inner_m is None
              else _finite(I_inner_m, "I_inner_m"))
        loosen = 2.0 * (rotating_ring_displacement(a, a, b, w, rm.rho, rm.E, rm.nu)
                        - rotating_ring_displacement(a, 0.5 * shaft_bore, a, w, sm.rho, sm.E, sm.nu))
        I_i = I0 + a_s * d * (Ts - T_REF_C) - a_r * d * (Ti - T_REF_C) - loosen + zero
        p_i = fit_pressure(I_i, d, shaft_bore, d_i, sm.E, sm.nu, rm.E, rm.nu)
        fit_i = -2.0 * lame_displacement(b, a, b, p_in=p_i, E=rm.E, nu=rm.nu)
    if housing is not None or I_outer_m is not None:
        Dh = _needs(brg.outer_diameter, "outer_diameter", "a housing fit")
        e, f = 0.5 * d_o, 0.5 * Dh
        I0 = (fit_interference(Dh, housing, "outer")[_INTERFERENCE.index(interference)] if I_outer_m is None
              else _finite(I_outer_m, "I_outer_m"))
        I_o = I0 - a_h * Dh * (Th - T_REF_C) + a_r * Dh * (To - T_REF_C) + zero
        p_o = fit_pressure(I_o, Dh, d_o, housing_diameter, rm.E, rm.nu, hm.E, hm.nu)
        fit_o = 2.0 * lame_displacement(e, e, f, p_out=p_o, E=rm.E, nu=rm.nu)
    cf = -2.0 * u_w
    Pd = Pd0 + thermal + fit_i + fit_o + cf
    return OperatingClearance(Pd=Pd, Pd_unmounted=float(Pd0), fit_inner=fit_i, fit_outer=fit_o, thermal=thermal,
                              centrifugal=cf, interference_inner=I_i, interference_outer=I_o, pressure_inner=p_i,
                              pressure_outer=p_o)


def _finite(v, name) -> float:
    if not within(np.atleast_1d(np.asarray(v, dtype=float)), -1e-3, 1e-3) or np.size(v) != 1:
        raise InputError(name, v, "a seat's diametral interference: one finite number within ±1 mm [m]")
    return float(v)


def _needs(v, name, what):
    if v is None:
        raise InputError(f"bearing.{name}", None, f"{what} needs the bearing's {name} [m]")
    return float(v)


def clearance_preload(brg: BallBearing, Pd):
    r"""Ball load of a radial bearing mounted with a negative operating clearance, rings centred [N].

    .. math:: Q = K_n \left(\max(−P_d, 0)/2\right)^{1.5}

    Every ball is compressed by −P_d/2 between the centred rings (contact angle 0; K_n the ball's two Hertz
    contacts in series at the nominal angle, as the load distribution of :mod:`thermobear.loads`).

    >>> from thermobear.contact.geometry import bearing
    >>> round(float(clearance_preload(bearing("6208"), -4e-6)), 1)
    34.0
    """
    Pd = np.asarray(Pd, dtype=float)
    return brg.Kn() * (np.maximum(-Pd, 0.0) / 2.0) ** 1.5


def expanded_bearing(brg: BallBearing, dT_inner=0.0, dT_outer=0.0, dT_ball=None, *, alpha_ring=None,
                     alpha_ball=None, u_inner: float = 0.0) -> BallBearing:
    r"""The bearing with its rings and balls grown by their temperature rises (uniform free expansion).

    Parameters
    ----------
    brg : BallBearing
    dT_inner, dT_outer, dT_ball : float   temperature rises of the inner ring, outer ring and balls [K]
                          (dT_ball default: the mean of the rings')
    alpha_ring, alpha_ball : float        thermal expansion coefficients [1/K] (default AISI 52100)
    u_inner : float      radial growth of the inner raceway beyond the thermal one [m]: the centrifugal growth of a
                          rotating inner ring (:func:`raceway_growth`; 0: at rest)

    Returns
    -------
    BallBearing          D, d_m, f_i, f_o and the clearance (free contact angle) of the warm bearing

    Notes
    -----
    Each part scales by ε = α ΔT: the ball D(1 + ε_b), the inner groove radius r_i = f_i D and the radius of
    the inner groove-curvature centres c_i = d_m/2 + (r_i − D/2) cos α0 by (1 + ε_i), the outer r_o and
    c_o = d_m/2 − (r_o − D/2) cos α0 by (1 + ε_o) (cos α0 = A_r0/A, :attr:`BallBearing.A_r0`, > 1 for a bearing
    already preloaded).  Then A' = r_i' + r_o' − D', the radial distance of the groove centres

    .. math:: c_i' − c_o' = A_{r0}' = A' − P_d'/2

    (A' cos α0' with a clearance), and d_m' = d_m + ε_i (d_m − D)/2 + ε_o (d_m + D)/2 (the raceway bottoms).  The
    centrifugal growth u_i of a rotating inner ring moves its groove (bottom and curvature centre) out as a whole:
    c_i' and d_m' grow by u_i (its groove radius by u_i r_i / (d_i/2), ~10⁻⁴ of u_i: left out).  A
    deep groove bearing whose clearance closes (c_i' − c_o' > A') comes back with the negative clearance
    P_d' = 2 (A' − c_i' + c_o'), a radial preload (:func:`clearance_preload`); an angular contact bearing's is
    refused (its contact angle would pass 0).

    Examples
    --------
    A 7205B with its inner ring 30 K warmer than the outer: the free contact angle falls from 40° to 37.9°.

    >>> from thermobear.contact.geometry import bearing
    >>> warm = expanded_bearing(bearing("7205B"), 30.0, 0.0, 15.0)
    >>> round(float(np.degrees(warm.alpha0)), 1)
    37.9

    A 6208 (13 µm) with its inner ring 40 K warmer than the outer (balls 20 K): −17.2 µm, a radial preload.

    >>> round(expanded_bearing(bearing("6208"), 40.0, 0.0).Pd * 1e6, 2)
    -17.23
    """
    a_r = steel_expansion() if alpha_ring is None else float(alpha_ring)
    a_b = steel_expansion() if alpha_ball is None else float(alpha_ball)
    dTb = 0.5 * (dT_inner + dT_outer) if dT_ball is None else dT_ball
    ei, eo, eb = a_r * float(dT_inner), a_r * float(dT_outer), a_b * float(dTb)
    D, ca = brg.D, (np.cos(brg.alpha0) if brg.Pd >= 0 else brg.A_r0 / brg.A)
    ri, ro = brg.fi * D, brg.fo * D
    ci = (0.5 * brg.dm + (ri - 0.5 * D) * ca) * (1.0 + ei)
    co = (0.5 * brg.dm - (ro - 0.5 * D) * ca) * (1.0 + eo)
    D2 = D * (1.0 + eb)
    A2 = ri * (1.0 + ei) + ro * (1.0 + eo) - D2
    dm2 = brg.dm + ei * 0.5 * (brg.dm - D) + eo * 0.5 * (brg.dm + D)
    u = float(u_inner)
    if not np.isfinite(u):
        raise InputError("u_inner", u_inner, "the inner raceway's growth must be finite [m]")
    if u != 0.0:
        ci, dm2 = ci + u, dm2 + u
    radial = ci - co
    warm = dict(D=D2, dm=dm2, fi=ri * (1.0 + ei) / D2, fo=ro * (1.0 + eo) / D2)
    if radial >= A2:
        if brg.kind == "deep_groove":      # the clearance closed: a radial preload
            return brg.with_(Pd=2.0 * (A2 - radial), **warm)
        raise InputError("dT_inner", dT_inner, f"the warm bearing has no clearance left (radial distance of the groove "
                         f"centres {radial * 1e6:.4g} µm >= A = {A2 * 1e6:.4g} µm, the inner ring's growth at speed "
                         f"{u * 1e6:.3g} µm of it): its contact angle would pass 0")
    return brg.with_(alpha0=float(np.arccos(radial / A2)), **warm)
