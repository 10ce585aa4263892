r"""Speed ratings: ISO 15312 thermal reference speed and DIN 732 thermally safe operating speed.

ISO 15312 defines the *thermal speed rating* n_θr: the inner-ring speed at which the friction power
of an open bearing under reference conditions equals the heat flow its seating surfaces carry away,
a reference heat flow density q_r times a reference surface A_r, with the outer ring (housing washer)
at 70 °C and the ambient at 20 °C.  DIN 732 scales it to operating conditions, n_θ = f_n n_θr, with
the speed ratio f_n from the heat the actual machine dissipates and the friction moments at the
actual load and viscosity.

This module holds the standards' equations as pure functions; the root finding on thermobear's own
losses (the model's n_θr) and on the coupled thermal model (the safe speed of a scene's own cooling)
live in :mod:`thermobear.coupled.speeds`.

What was verified and what was not (``unconfirmed``):

* Reference conditions — 70 °C on the stationary outer ring, 20 °C ambient, radial load 0.05 C0
  (radial bearings), axial load 0.02 C0 (thrust bearings), mineral oil with ν = 12 mm²/s (radial,
  ISO VG 32) or 24 mm²/s (thrust, ISO VG 68) at 70 °C, oil bath up to the middle of the lowest
  rolling element, open bearing with Normal clearance: as quoted from ISO 15312:2003 by SKF [2]_.
  Thrust ball bearings lie outside ISO 15312 (kinematic effects) [3]_ and outside DIN 732 [4]_.
* Reference heat flow density q_r = 16 kW/m² up to A_r = 50 000 mm² and
  q_r = 16 (A_r / 50 000 mm²)^-0.34 kW/m² beyond (radial bearings), 20 kW/m² and the exponent −0.16
  (thrust bearings); reference surfaces A_r = π B (D + d) (radial) and π/2 (D² − d²) (thrust, both
  washers' faces): ISO 15312 [1]_ as quoted by Schaeffler [7]_ (the standard's text was not available);
  SKF [5]_ shows the radial curve (16 kW/m² flat, falling beyond).
* DIN 732 [4]_: heat flows Φ = k_q A_s ΔT_A + 0.0286 kW/(l/min K) V_L ΔT_L + Φ_E, the lubricant
  parameter K_L (the share of the heat that M0 would produce at n_θr), the load parameter K_P (M1's share),
  the balance K_L f_n^(5/3) + K_P f_n = 1 and its approximation below: as quoted from the standard's draft
  (DIN 732-2) in Schaeffler's catalogue HR 1 [7]_ (the standard's own text was not available).  The
  approximation's constants are checked against the balance it approximates: within 5.7 % (median 0.7 %)
  over its stated range 0.01 ≤ K_L, K_P ≤ 10 (tests/test_speeds.py) — read with the parameters exchanged
  it errs by up to 150 %, as this module did before (validation/CHANGES.md).  k_q read as the reference
  heat flow density per 50 K (ISO 15312's reference temperature difference), 320 W/(m² K): inside the
  0.2–1.0·10⁻⁶ kW/(mm² K) Schaeffler gives for seating surfaces up to 25 000 mm² [7]_.
* Friction moments of the Palmgren form the standards use, M0 = 10⁻⁷ f0 (ν n)^(2/3) d_m³,
  M1 = f1 P1 d_m, with Palmgren's coefficients as tabulated by Harris & Kotzalas [6]_ (ISO 15312
  Annex A's f0r, f1r were not available): unconfirmed as the standards' values.

References
----------
.. [1] ISO 15312:2003 (and :2018), Rolling bearings — Thermal speed rating — Calculation.
.. [2] SKF, "Reference speeds" (principles of bearing selection, speeds and vibration), skf.com:
       the ISO 15312:2003 reference conditions.
.. [3] ISO 15312:2018 scope (as published, e.g. DS/ISO 15312 on standards.globalspec.com): thrust ball
       bearings excluded "as kinematic effects do not allow the thermal speed rating to be applied".
.. [4] DIN 732:2010, Wälzlager — Thermisch zulässige Betriebsdrehzahl — Berechnung und Beiwerte
       (din.de abstract: thrust ball bearings excluded; bearings without rubbing seals).
.. [5] SKF, "Reference speed" (diagram 1: reference heat flow density vs reference surface), skf.com.
.. [6] Harris, T. A., Kotzalas, M. N. (2007). Essential Concepts of Bearing Technology, 5th ed.,
       ch. "Friction in rolling bearings" (Palmgren's f0, f1 and P1).
.. [7] Schaeffler (2006). *Rolling Bearings*, catalogue HR 1, "Speeds": thermal reference speed (p. 62:
       q_r, A_r) and thermally safe operating speed after DIN 732-2 (draft) (p. 63: k_q, the oil's heat
       flow, K_L, K_P, the balance and the approximation of f_n for 0.01 ≤ K_L, K_P ≤ 10).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


from thermobear.arrays import checked, out
from thermobear.errors import InputError, NoConvergence
from thermobear.lazy import lazy_module

optimize = lazy_module("scipy.optimize")    # brentq: loaded by its first use

__all__ = ["ReferenceConditions", "reference_conditions", "reference_surface", "reference_heat_flow_density",
           "palmgren_coefficients", "palmgren_load", "palmgren_moments", "din732_heat_flow",
           "din732_parameters", "din732_speed_ratio", "din732_balance_ratio", "standard_reference_speed", "seating_heat_transfer_coefficient", "Q_R_W_M2",
           "A_R_KNEE_M2", "DT_REFERENCE_K"]

Q_R_W_M2 = 16.0e3              #: radial bearings' reference heat flow density up to the knee [W/m²] (ISO 15312 via [7])
A_R_KNEE_M2 = 50_000e-6        #: reference surface where q_r starts to fall [m²] (ISO 15312 via [7])
Q_R_EXPONENT = -0.34           #: exponent of the radial q_r beyond the knee [-] (ISO 15312 via [7])
Q_R_THRUST_W_M2 = 20.0e3       #: thrust bearings' reference heat flow density up to the knee [W/m²] (ISO 15312 via [7])
Q_R_THRUST_EXPONENT = -0.16    #: exponent of the thrust q_r beyond the knee [-] (ISO 15312 via [7])
DT_REFERENCE_K = 50.0          #: 70 °C bearing − 20 °C ambient (ISO 15312 via SKF)
DIN732_OIL_W_PER_L_MIN_K = 28.6   #: lubricant heat flow 0.0286 kW/(l/min K) (DIN 732 via [7])
_KINDS = ("deep_groove", "angular_contact", "thrust")


@dataclass(frozen=True)
class ReferenceConditions:
    """ISO 15312 reference conditions of a bearing kind (as quoted by SKF [2]_ in :mod:`this module
    <thermobear.rating.speeds>`).

    Attributes
    ----------
    T_C : float            stationary outer ring / housing washer [°C]
    T_ambient_C : float    ambient [°C]
    load_fraction : float  reference load / C0 [-] (radial load, thrust bearings axial)
    nu_cSt : float         kinematic viscosity of the mineral oil at T_C [mm²/s]
    load : str             ``"Fr"`` or ``"Fa"``
    in_scope : bool        False for thrust ball bearings (excluded by ISO 15312)
    """

    T_C: float
    T_ambient_C: float
    load_fraction: float
    nu_cSt: float
    load: str
    in_scope: bool = True


def _kind(kind):
    if kind not in _KINDS:
        raise InputError("kind", kind, f"one of {', '.join(_KINDS)}")
    return kind


def reference_conditions(kind: str) -> ReferenceConditions:
    """ISO 15312 reference conditions for ``kind`` (``deep_groove``, ``angular_contact``, ``thrust``).

    >>> reference_conditions("deep_groove").nu_cSt, reference_conditions("thrust").load_fraction
    (12.0, 0.02)
    """
    if _kind(kind) == "thrust":
        return ReferenceConditions(70.0, 20.0, 0.02, 24.0, "Fa", in_scope=False)
    return ReferenceConditions(70.0, 20.0, 0.05, 12.0, "Fr")


def reference_surface(bore, outer_diameter, width, kind):
    r"""Heat-emitting reference surface A_r of ISO 15312 [m²].

    Parameters
    ----------
    bore, outer_diameter : array_like   d, D [m]
    width : array_like                  B (thrust bearings: height, unused) [m]
    kind : str                          ``deep_groove``, ``angular_contact`` or ``thrust``

    Returns
    -------
    float or ndarray   A_r [m²]

    Notes
    -----
    .. math:: A_r = \pi B (D + d) \ \text{(radial)}, \qquad A_r = \tfrac{\pi}{2} (D^2 - d^2) \ \text{(thrust)}

    the bore and outside cylinders of the rings, or the outer faces of a thrust bearing's two washers
    (ISO 15312 [1]_ as quoted in [7]_, p. 64).

    Examples
    --------
    6208 (40 × 80 × 18 mm): π 18 (80 + 40) = 6786 mm².

    >>> round(float(reference_surface(0.040, 0.080, 0.018, "deep_groove")) * 1e6, 1)
    6785.8
    """
    d = checked("bore", bore, lo=0.0, what=" [m]")
    D = checked("outer_diameter", outer_diameter, lo=0.0, what=" [m]")
    if np.any(np.asarray(D) <= np.asarray(d)):
        raise InputError("outer_diameter", outer_diameter, "must exceed the bore")
    if _kind(kind) == "thrust":
        return out(np.pi / 2.0 * (D ** 2 - d ** 2))
    return out(np.pi * checked("width", width, lo=0.0, what=" [m]") * (D + d))


def reference_heat_flow_density(A_r, kind: str = "deep_groove"):
    r"""Reference heat flow density q_r of ISO 15312 [W/m²] as a function of A_r [m²].

    Parameters
    ----------
    A_r : array_like   reference surface (:func:`reference_surface`) [m²]
    kind : str         ``deep_groove``, ``angular_contact`` (radial) or ``thrust``

    Notes
    -----
    .. math:: q_r = q_0 \quad (A_r \le 50\,000\ \mathrm{mm^2}), \qquad
              q_r = q_0 \left(\frac{A_r}{50\,000\ \mathrm{mm^2}}\right)^{m}

    radial bearings q_0 = 16 kW/m², m = −0.34; thrust bearings q_0 = 20 kW/m², m = −0.16 (ISO 15312 [1]_
    as quoted in [7]_, p. 62).  The reference heat flow is Φ_r = q_r A_r; it grows as A_r^(1+m) beyond
    the knee.

    Examples
    --------
    >>> float(reference_heat_flow_density(6785.8e-6)), round(float(reference_heat_flow_density(0.1)), 1)
    (16000.0, 12640.7)
    >>> round(float(reference_heat_flow_density(0.1, "thrust")), 1)
    17900.5
    """
    A = checked("A_r", A_r, lo=0.0, what=" [m²]")
    q0, m = (Q_R_THRUST_W_M2, Q_R_THRUST_EXPONENT) if _kind(kind) == "thrust" else (Q_R_W_M2, Q_R_EXPONENT)
    return out(q0 * np.minimum(1.0, (A / A_R_KNEE_M2) ** m))


def seating_heat_transfer_coefficient(A_s):
    """DIN 732's heat transfer coefficient of the bearing seating surface k_q [W/(m² K)], read as ISO
    15312's reference heat flow density per its 50 K reference temperature difference: 320 W/(m² K) up to
    50 000 mm², inside the 200–1000 W/(m² K) Schaeffler [7]_ gives for seating surfaces up to 25 000 mm² (a
    reading, not the standard's own value).

    >>> float(seating_heat_transfer_coefficient(0.005))
    320.0
    """
    return out(reference_heat_flow_density(A_s) / DT_REFERENCE_K)


#: Palmgren's f0 by bearing kind and lubrication (Harris & Kotzalas [6]_; unconfirmed, module docstring).
_F0 = {"deep_groove": {"grease": 2.0, "oil_air": 1.0, "oil_bath": 2.0, "oil_jet": 4.0},
       "angular_contact": {"grease": 2.0, "oil_air": 1.7, "oil_bath": 3.3, "oil_jet": 6.6},
       "thrust": {"grease": 5.5, "oil_air": 0.8, "oil_bath": 1.5, "oil_jet": 3.0}}


def palmgren_coefficients(kind: str, supply: str, P0, C0):
    r"""Palmgren's friction coefficients f0 [-] and f1 [-] (Harris & Kotzalas [6]_, unconfirmed).

    Parameters
    ----------
    kind : str       ``deep_groove``, ``angular_contact`` or ``thrust``
    supply : str     ``grease``, ``oil_air``, ``oil_bath`` or ``oil_jet``
    P0 : array_like  static equivalent load (thrust bearings: the axial load) [N]
    C0 : array_like  basic static load rating [N]

    Notes
    -----
    .. math:: f_1 = 0.0008\,(P_0/C_0)^{0.5}\ \text{(deep groove)}, \quad
              0.001\,(P_0/C_0)^{0.33}\ \text{(angular contact)}, \quad
              0.0012\,(F_a/C_0)^{0.33}\ \text{(thrust)}

    (deep groove: the middle of Palmgren's 0.0007–0.0009).

    >>> f0, f1 = palmgren_coefficients("deep_groove", "oil_bath", 0.05, 1.0)
    >>> f0, round(float(f1), 7)
    (2.0, 0.0001789)
    """
    if supply not in _F0[_kind(kind)]:
        raise InputError("supply", supply, f"one of {', '.join(_F0[kind])} (Palmgren's f0 table)")
    ratio = checked("P0", P0, lo=0.0, strict=False, what=" [N]") / checked("C0", C0, lo=0.0, what=" [N]")
    f1 = {"deep_groove": 0.0008 * ratio ** 0.5, "angular_contact": 0.001 * ratio ** 0.33,
          "thrust": 0.0012 * ratio ** 0.33}[kind]
    return _F0[kind][supply], out(f1)


def palmgren_load(kind: str, Fa, Fr, alpha=0.0):
    r"""Palmgren's load P1 of the load-dependent friction moment [N] (Harris & Kotzalas [6]_).

    Notes
    -----
    .. math:: P_1 = \max(3.3 F_a - 0.1 F_r,\ F_r)\ \text{(deep groove)}, \quad
              \max(0.9 F_a \cot\alpha - 0.1 F_r,\ F_r)\ \text{(angular contact)}, \quad
              F_a\ \text{(thrust)}

    >>> float(palmgren_load("deep_groove", 0.0, 950.0)), float(palmgren_load("deep_groove", 1000.0, 950.0))
    (950.0, 3205.0)
    """
    Fa = checked("Fa", Fa, lo=0.0, strict=False, what=" [N]")
    Fr = checked("Fr", Fr, lo=0.0, strict=False, what=" [N]")
    if _kind(kind) == "thrust":
        return out(Fa)
    axial = 3.3 * Fa if kind == "deep_groove" else 0.9 * Fa / np.tan(np.maximum(alpha, 1e-9))
    return out(np.maximum(axial - 0.1 * Fr, Fr))


def palmgren_moments(n_rpm, nu_cSt, P1, dm, f0, f1):
    r"""Load-independent and load-dependent friction moments M0, M1 of the Palmgren form [N m].

    Parameters
    ----------
    n_rpm : array_like    speed [rpm]
    nu_cSt : array_like   kinematic viscosity at the operating temperature [mm²/s]
    P1 : array_like       load of the friction moment [N]
    dm : array_like       pitch diameter [m]
    f0, f1 : array_like   coefficients [-]

    Notes
    -----
    With d_m in mm and the moments in N mm (ISO 15312 [1]_, DIN 732 [4]_, Palmgren via [6]_):

    .. math:: M_0 = 10^{-7} f_0 (\nu n)^{2/3} d_m^3 \quad (\nu n \ge 2000), \qquad
              M_0 = 160 \cdot 10^{-7} f_0 d_m^3 \quad (\nu n < 2000), \qquad M_1 = f_1 P_1 d_m

    Examples
    --------
    >>> M0, M1 = palmgren_moments(10000.0, 12.0, 950.0, 0.060, 2.0, 0.000179)
    >>> round(float(M0), 4), round(float(M1), 4)
    (0.1051, 0.0102)
    """
    n = checked("n_rpm", n_rpm, lo=0.0, strict=False, what=" [rpm]")
    nu = checked("nu_cSt", nu_cSt, lo=0.0, what=" [mm²/s]")
    dm_mm = checked("dm", dm, lo=0.0, what=" [m]") * 1e3
    M0 = 1e-7 * f0 * np.maximum(nu * n, 2000.0) ** (2.0 / 3.0) * dm_mm ** 3 * 1e-3
    return out(M0), out(checked("P1", P1, lo=0.0, strict=False, what=" [N]") * f1 * dm_mm * 1e-3)


def din732_heat_flow(A_s, dT_A, *, k_q=None, oil_flow_L_min=0.0, dT_oil=0.0, Phi_external=0.0):
    r"""Heat flow a bearing arrangement dissipates, DIN 732 [4]_ [W] (unconfirmed, module docstring).

    Parameters
    ----------
    A_s : array_like             bearing seating surface [m²] (as A_r)
    dT_A : array_like            mean bearing temperature − ambient [K]
    k_q : array_like, optional   heat transfer coefficient of the seating surface [W/(m² K)]
                                 (default :func:`seating_heat_transfer_coefficient`)
    oil_flow_L_min : array_like  circulating oil flow [l/min]
    dT_oil : array_like          oil outlet − inlet temperature [K]
    Phi_external : array_like    heat from external sources [W] (negative: heating)

    Notes
    -----
    .. math:: \Phi = k_q A_s \Delta T_A + 0.0286\ \tfrac{\mathrm{kW}}{\mathrm{l/min\,K}}\,\dot V_L\,\Delta T_L
              - \Phi_E

    >>> round(float(din732_heat_flow(6785.8e-6, 45.0)), 2)
    97.72
    """
    A = checked("A_s", A_s, lo=0.0, what=" [m²]")
    kq = seating_heat_transfer_coefficient(A) if k_q is None else checked("k_q", k_q, lo=0.0, strict=False, what=" [W/(m² K)]")
    oil = checked("oil_flow_L_min", oil_flow_L_min, lo=0.0, strict=False, what=" [l/min]")
    return out(kq * A * checked("dT_A", dT_A, lo=-np.inf, what=" [K]") + DIN732_OIL_W_PER_L_MIN_K * oil * dT_oil
               - Phi_external)


def din732_parameters(n_theta_r_rpm, M0, M1, Phi):
    r"""DIN 732's lubricant parameter K_L and load parameter K_P [-] (DIN 732 [4]_ as quoted in [7]_).

    Parameters
    ----------
    n_theta_r_rpm : array_like  thermal reference speed [rpm]
    M0 : array_like             load-independent friction moment at n_θr and the operating viscosity [N m]
    M1 : array_like             load-dependent friction moment at the operating load [N m]
    Phi : array_like            heat flow dissipated at the limit temperature [W]

    Returns
    -------
    K_L, K_P : array   the lubricant parameter (M0's share) and the load parameter (M1's share) [-]

    Notes
    -----
    .. math:: K_L = \frac{\pi n_{\theta r} M_0}{30\, \Phi}, \qquad K_P = \frac{\pi n_{\theta r} M_1}{30\, \Phi}

    the shares of the dissipated heat that the two moments would produce at n_θr.  The operating
    heat balance at n = f_n n_θr (M0 ∝ n^(2/3)) is then K_L f_n^(5/3) + K_P f_n = 1.

    >>> K_L, K_P = din732_parameters(10000.0, 0.1, 0.01, 115.2)
    >>> round(float(K_L), 4), round(float(K_P), 4)
    (0.9091, 0.0909)
    """
    w = np.pi / 30.0 * checked("n_theta_r_rpm", n_theta_r_rpm, lo=0.0, what=" [rpm]")
    P = checked("Phi", Phi, lo=0.0, what=" [W] (no heat dissipated: no safe speed)")
    return (out(w * checked("M0", M0, lo=0.0, strict=False, what=" [N m]") / P),
            out(w * checked("M1", M1, lo=0.0, strict=False, what=" [N m]") / P))


def din732_speed_ratio(K_L, K_P):
    r"""DIN 732's speed ratio f_n = n_θ / n_θr from K_L and K_P, by the standard's approximation [-].

    Notes
    -----
    .. math:: f_n = \frac{490.77}{1 + 498.78\,K_L^{0.599} + 852.88\,K_P^{0.963}
              - 504.5\,K_L^{0.055} K_P^{0.832}}

    with the lubricant parameter K_L and the load parameter K_P (:func:`din732_parameters`): an
    approximation of the root of K_L f_n^(5/3) + K_P f_n = 1 (DIN 732 [4]_ as quoted in [7]_, for
    0.01 ≤ K_L, K_P ≤ 10), within 5.7 % of that root (:func:`din732_balance_ratio`) over the range.

    >>> round(float(din732_speed_ratio(0.5, 0.5)), 3)
    0.991
    """
    KL = checked("K_L", K_L, lo=0.0, strict=False, what=" [-]")
    KP = checked("K_P", K_P, lo=0.0, strict=False, what=" [-]")
    den = 1.0 + 498.78 * KL ** 0.599 + 852.88 * KP ** 0.963 - 504.5 * KL ** 0.055 * KP ** 0.832
    return out(490.77 / den)


def din732_balance_ratio(K_L, K_P, *, tol: float = 1e-13):
    r"""The root f of the operating heat balance that DIN 732's f_n approximates [-] (DIN 732 [4]_,
    :func:`din732_speed_ratio`).

    Notes
    -----
    .. math:: K_L f^{5/3} + K_P f = 1

    (:func:`din732_parameters`: K_L the lubricant parameter, M0 ∝ n^(2/3); K_P the load parameter).  The left
    side increases with f from 0, so the root is unique; Newton from the smaller of the two single-term roots
    K_L^(−3/5) and 1/K_P — both above it, and the left side convex — approaches it from above without overshoot.
    Infinite where K_L = K_P = 0 (no heat to balance).

    >>> round(float(din732_balance_ratio(0.5, 0.5)), 12), round(float(din732_balance_ratio(1.421, 0.303)), 3)
    (1.0, 0.702)
    """
    KL = checked("K_L", K_L, lo=0.0, strict=False, what=" [-]")
    KP = checked("K_P", K_P, lo=0.0, strict=False, what=" [-]")
    KL, KP = np.broadcast_arrays(np.asarray(KL, float), np.asarray(KP, float))
    with np.errstate(divide="ignore"):
        f = np.minimum(np.where(KL > 0, KL ** -0.6, np.inf), np.where(KP > 0, 1.0 / KP, np.inf))
    live = np.isfinite(f)
    for _ in range(100):
        x = np.where(live, f, 1.0)                      # (no arithmetic on the infinite ones)
        slope = np.where(live, (5.0 / 3.0) * x ** (2.0 / 3.0) * KL + KP, 1.0)
        step = np.where(live, (x ** (5.0 / 3.0) * KL + x * KP - 1.0) / slope, 0.0)
        f = np.where(live, f - step, f)
        if np.all(np.abs(step) <= tol * np.maximum(f, 1.0)):
            return out(f)
    raise NoConvergence("DIN 732 balance: Newton did not converge", iterations=100)


def standard_reference_speed(A_r, dm, P1r, f0r, f1r, nu_r_cSt=12.0, *, n_max_rpm=1e6, kind: str = "deep_groove"):
    r"""Thermal speed rating n_θr by ISO 15312's own equations (Palmgren-form friction) [rpm].

    Parameters
    ----------
    A_r : float        reference surface [m²]
    dm : float         pitch diameter [m]
    P1r : float        reference load [N]
    f0r, f1r : float   the standard's friction coefficients at reference conditions [-]
    nu_r_cSt : float   reference viscosity [mm²/s]
    n_max_rpm : float  upper end of the search [rpm]
    kind : str         the bearing kind of q_r (:func:`reference_heat_flow_density`)

    Returns
    -------
    (n_rpm, residual_W, iterations)

    Notes
    -----
    The root of the reference heat balance (ISO 15312 [1]_):

    .. math:: \frac{\pi n_{\theta r}}{30} \left[M_0(n_{\theta r}, \nu_r) + M_1(P_{1r})\right] = q_r A_r

    with :func:`palmgren_moments` and :func:`reference_heat_flow_density`; the left side grows
    monotonically with n, so the bracket [0, n_max] holds one root when it holds any.

    >>> n, res, it = standard_reference_speed(6785.8e-6, 0.060, 950.0, 2.0, 0.000179)
    >>> round(n, -1), abs(res) < 1e-6
    (9360.0, True)
    """
    Phi = float(reference_heat_flow_density(A_r, kind) * A_r)

    def balance(n):
        M0, M1 = palmgren_moments(n, nu_r_cSt, P1r, dm, f0r, f1r)
        return np.pi / 30.0 * n * float(M0 + M1) - Phi

    if balance(n_max_rpm) <= 0.0:
        raise NoConvergence(f"ISO 15312 heat balance: the reference heat flow {Phi:.4g} W is reached at no speed up "
                            f"to {n_max_rpm:.4g} rpm", residual=-balance(n_max_rpm))
    n, r = optimize.brentq(balance, 0.0, n_max_rpm, xtol=1e-9, rtol=1e-12, full_output=True)
    return float(n), float(balance(n)), int(r.iterations)
