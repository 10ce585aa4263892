r"""Drag loss of the balls moving through the oil–air mixture (Pouly et al. 2010).

Seed 004 (Darul et al. 2024, eq 21) uses Pouly's form

    P_drag = ρ_mix c_d Z (A_c / 2) (ω_c dm / 2)^3                         [W]

i.e. each of the Z balls, cross-section A_c, moves at the cage pitch-line speed
v = ω_c dm/2 through a homogeneous mixture of density ρ_mix and feels the sphere
drag ½ ρ_mix c_d A_c v²; the power is Z F v.

What is and is not confirmed (searches of the public corpus for Pouly 2010's own
definitions found nothing beyond seed 004's wording):

* A_c: seed 004 calls it "the cross-sectional area"; taken as the ball's frontal
  area πD²/4 (no cage-shielding correction).  Unconfirmed; override with ``A_c``.
* ρ_mix = X ρ_oil + (1 − X) ρ_air and μ_mix = X μ_oil + (1 − X) μ_air (linear
  rules, unconfirmed – textbook).
* X from Parker (1984, NASA TP-2275, as quoted by Harris), X = 1e5 W^0.37 / (n dm^1.7)
  with W in cm³/min, n in r/min, dm in mm; W is the flow *through the bearing*: of an oil jet only a
  share β passes (seed 004 §4.5: β ≈ 0.4, Brossier et al. 2021; the scene's
  ``lubricant.jet_penetration``; validation/report/seed004_drag.md).  The number is used as the volume
  *fraction* (default ``convention="fraction"``), not as a percent: this is what
  seed 004 §6 implies — "multiplying the oil flow rate by 1.5 leads to an increase
  of drag losses equal to 16 %" — since 1.5^0.37 = 1.162 only if ρ_mix is dominated
  by the oil term (X ≈ 7e-2 for the 7210 at 8070 r/min); read as a percent
  (X ≈ 7e-4) the mixture is mostly air and ×1.5 flow gives ≈ +5 %.  It also gives
  the typical 0.5–10 % of jet-lubricated bearings.  ``convention="percent"`` is
  kept to show the alternative.
* c_d: smooth-sphere correlation of Clift & Gauvin (1970) from ChEDL ``fluids``
  (``fluids.drag.Clift_Gauvin``; valid Re ≤ 2e5, reduces to Stokes' 24/Re as Re → 0).
  Pouly used "a sphere C_d(Re) curve" (recalled, unconfirmed).
* Air density and viscosity from CoolProp (``PropsSI('D'|'V', 'T', T, 'P', p, 'Air')``).
"""
from __future__ import annotations

import math
import numbers
import warnings
from dataclasses import dataclass

import numpy as np
from fluids.drag import drag_sphere, drag_sphere_correlations

from thermobear.arrays import above
from thermobear.errors import ExtrapolationWarning, InputError
from thermobear.lubrication.air import air_properties as _air

__all__ = ["oil_volume_fraction_parker", "cavity_oil_fraction", "mixture_density", "mixture_viscosity", "air_properties",
           "drag_coefficient_sphere", "drag_power_pouly", "drag_loss", "DragLoss", "immersed_fraction",
           "churning_loss", "ChurningLoss"]

_P_ATM = 101325.0


def _pos(name, x, allow_zero=False):
    """``x`` (a Python float, or as a float array) checked finite and > 0 (>= 0) (NaN and ±inf fail: an infinite
    density, speed or diameter has no finite drag)."""
    if isinstance(x, float):
        lo, a = (x if math.isfinite(x) else -1.0), x
    else:
        a = np.asarray(x, dtype=float)
        lo = 1.0 if above(a, 0.0, not allow_zero) and np.all(np.isfinite(a)) else -1.0
    if not (lo >= 0 if allow_zero else lo > 0):
        raise InputError(name, x, "must be finite and " + (">= 0" if allow_zero else "> 0"))
    return a


def _out(x):
    if type(x) is float:
        return x
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x


def oil_volume_fraction_parker(W_oil_cm3_min, n_rpm, dm_mm, convention="fraction"):
    r"""Oil volume fraction X of the bearing cavity, Parker (1984) [-].

    Parameters
    ----------
    W_oil_cm3_min : array_like  oil flow rate through the bearing [cm³/min] (1 L/h = 16.67 cm³/min)
    n_rpm : array_like          shaft speed [r/min], > 0
    dm_mm : float               pitch diameter [mm]
    convention : str            "fraction" (default): the formula's number is the fraction;
                                "percent": it is a percentage (divided by 100 here)

    Returns
    -------
    ndarray  X in [0, 1].  Values above 1 (very low speed) are clipped to 1 with an
             ExtrapolationWarning: the correlation is outside its range there.

    Notes
    -----
    .. math::

        X = \frac{10^5\, W^{0.37}}{n\, d_m^{1.7}}

    (Parker 1984, NASA TP-2275, as quoted by Harris & Kotzalas 2007; the constant and the
    convention are recalled, not checked against the report).  See the module notes for the
    evidence (seed 004 §6) behind the fraction convention.

    Examples
    --------
    Seed 004: 7210, dm 70 mm, 10 L/h, 6500 r/min:

    >>> round(float(oil_volume_fraction_parker(10 * 1000 / 60, 6500, 70.0)), 4)
    0.0746
    """
    W = _pos("W_oil_cm3_min", W_oil_cm3_min, allow_zero=True)
    n = _pos("n_rpm", n_rpm)
    dm = _pos("dm_mm", dm_mm)
    if convention not in ("fraction", "percent"):
        raise InputError("convention", convention, "must be 'fraction' or 'percent'")
    X = 1e5 * W ** 0.37 / (n * dm ** 1.7)
    if convention == "percent":
        X = X / 100.0
    if (X if isinstance(X, float) else np.max(X)) > 1.0:
        warnings.warn(f"Parker's oil fraction exceeds 1 (max {np.max(X):.3g}); clipped to 1 — "
                      "speed too low for the correlation", ExtrapolationWarning, stacklevel=2)
        X = np.minimum(X, 1.0)
    return _out(X)


def cavity_oil_fraction(supply: str, oil_flow_m3_s, n_rpm, dm_m):
    r"""Oil volume fraction of the mixture in a bearing's cavity by the supply [-].

    Parameters
    ----------
    supply : str               ``oil_jet`` or ``oil_air``: Parker's fraction of the oil flow through the bearing
                               (:func:`oil_volume_fraction_parker`); any other supply (grease, oil bath, dry
                               film): 0 (the balls run in air; a bath's drag is the churning term)
    oil_flow_m3_s : array_like oil flow through the bearing [m³/s]
    n_rpm : array_like         shaft speed [r/min], ≥ 0 (0: no mixture is churned up, X = 0)
    dm_m : float               pitch diameter [m]

    Returns
    -------
    ndarray  X in [0, 1], the shape of the broadcast inputs

    Notes
    -----
    Parker's correlation (Parker 1984) gives the cavity's share of the oil flow that passes through it and
    speed; an oil–air supply passes its oil the same way, only less of it (a few mL/h: X of the order of 1 %
    at moderate speed, falling as 1/n).

    Examples
    --------
    >>> round(float(cavity_oil_fraction("oil_air", 0.005e-3 / 3600, 3700.0, 0.06)), 4)
    0.0102
    >>> float(cavity_oil_fraction("grease", 0.0, 3700.0, 0.06))
    0.0
    """
    n = np.asarray(n_rpm, dtype=float)
    W = np.broadcast_to(np.asarray(oil_flow_m3_s, dtype=float) * 1e6 * 60.0, n.shape)     # [cm³/min]
    X = np.zeros(np.broadcast_shapes(n.shape, W.shape))
    run = n > 0
    if supply in ("oil_jet", "oil_air") and run.any():
        X[run] = oil_volume_fraction_parker(W[run], n[run], dm_m * 1e3)
    return X


def _fraction(X):
    if isinstance(X, float):
        lo = hi = X
    else:
        X = np.asarray(X, dtype=float)
        lo, hi = (X.min(), X.max()) if X.size else (0.0, 0.0)
    if not (lo >= 0 and hi <= 1):                                   # NaN fails too
        raise InputError("X", X, "oil volume fraction must lie in [0, 1]")
    return X


def _mix(X, v_oil, v_air):
    """Linear mixing rule X v_oil + (1 − X) v_air (of :func:`mixture_density`, :func:`mixture_viscosity`)."""
    return X * v_oil + (1.0 - X) * v_air


def mixture_density(X, rho_oil, rho_air):
    r"""Density of the homogeneous oil–air mixture ρ_mix = X ρ_oil + (1 − X) ρ_air [kg/m³].

    Parameters
    ----------
    X : array_like        oil volume fraction [-], 0..1
    rho_oil, rho_air : array_like  densities [kg/m³]

    Examples
    --------
    >>> mixture_density(0.0, 860.0, 1.2), mixture_density(1.0, 860.0, 1.2)
    (1.2, 860.0)
    """
    return _out(_mix(_fraction(X), np.asarray(rho_oil, dtype=float), np.asarray(rho_air, dtype=float)))


def mixture_viscosity(X, mu_oil, mu_air):
    r"""Dynamic viscosity of the mixture μ_mix = X μ_oil + (1 − X) μ_air [Pa s] (linear rule, unconfirmed).

    Examples
    --------
    >>> mixture_viscosity(0.5, 0.04, 2e-5)
    0.02001
    """
    return _out(_mix(_fraction(X), np.asarray(mu_oil, dtype=float), np.asarray(mu_air, dtype=float)))


def air_properties(T_K, p_Pa=_P_ATM):
    r"""Density [kg/m³] and dynamic viscosity [Pa s] of dry air from CoolProp (tabulated, :mod:`thermobear.lubrication.air`).

    Parameters
    ----------
    T_K : array_like   temperature [K]
    p_Pa : float       pressure [Pa]

    Examples
    --------
    >>> rho, mu = air_properties(303.15)
    >>> round(rho, 3), round(mu * 1e6, 2)
    (1.165, 18.69)
    """
    p = _air(_pos("T_K", T_K), _pos("p_Pa", p_Pa))
    return _out(p["rho"]), _out(p["mu"])


def drag_coefficient_sphere(Re, method="Clift_Gauvin"):
    r"""Drag coefficient of a smooth sphere C_d(Re) from ChEDL ``fluids`` [-].

    Parameters
    ----------
    Re : array_like   sphere Reynolds number ρ v D / μ [-], > 0
    method : str      a key of ``fluids.drag.drag_sphere_correlations``; default
                      "Clift_Gauvin" (Clift & Gauvin 1970):
                      C_d = 24/Re (1 + 0.152 Re^0.677) + 0.417 / (1 + 5070 Re^−0.94),
                      valid Re ≤ 2e5.  "Stokes" gives 24/Re.

    Notes
    -----
    Beyond a correlation's documented range an ExtrapolationWarning is issued and
    the value is still computed.  Correlations that ``fluids`` writes for scalars
    only are evaluated point by point (slower).

    Examples
    --------
    >>> round(float(drag_coefficient_sphere(200.0)), 4)
    0.7905
    >>> float(drag_coefficient_sphere(0.01, "Stokes"))
    2400.0
    """
    return _out(_cd(_pos("Re", Re), method))


def _cd(Re, method):
    """C_d of :func:`drag_coefficient_sphere` on checked Reynolds numbers ``Re`` (> 0)."""
    if method not in drag_sphere_correlations:
        raise InputError("method", method, f"must be one of {', '.join(drag_sphere_correlations)}")
    func, _, Re_max = drag_sphere_correlations[method]
    if Re_max is not None and (Re if isinstance(Re, float) else np.max(Re)) > Re_max:
        warnings.warn(f"sphere Reynolds number up to {np.max(Re):.3g} exceeds the {method} range "
                      f"(Re <= {Re_max:.3g})", ExtrapolationWarning, stacklevel=3)
    try:
        return func(Re)
    except (TypeError, ValueError):
        return np.vectorize(lambda r: drag_sphere(r, Method=method), otypes=[float])(Re)


def drag_power_pouly(rho_mix, c_d, Z, D, omega_c, dm, A_c=None):
    r"""Drag power of the balls of one bearing, Pouly et al. (2010) [W].

    Parameters
    ----------
    rho_mix : array_like  mixture density [kg/m³]
    c_d : array_like      drag coefficient of a ball [-]
    Z : int               number of balls
    D : float             ball diameter [m]
    omega_c : array_like  cage angular speed [rad/s]
    dm : float            pitch diameter [m]
    A_c : float           cross-sectional area of a ball [m²]; default πD²/4 (unconfirmed)

    Notes
    -----
    P_drag = ρ_mix c_d Z (A_c/2) (ω_c dm/2)^3   (seed 004 eq 21, after Pouly et al. 2010,
    Tribol. Trans. 53:957–967).

    Examples
    --------
    >>> round(float(drag_power_pouly(60.0, 0.45, 15, 12.7e-3, 300.0, 70e-3)), 2)
    29.7
    """
    return _out(_pouly(np.asarray(rho_mix, dtype=float), np.asarray(c_d, dtype=float), Z, D,
                       np.asarray(omega_c, dtype=float) * dm / 2.0, A_c))


def _pouly(rho_mix, c_d, Z, D, v, A_c=None):
    """Pouly's drag power at the pitch-line speed v [m/s] (formula of :func:`drag_power_pouly`) [W]."""
    A = np.pi * D ** 2 / 4.0 if A_c is None else A_c
    return rho_mix * c_d * Z * (A / 2.0) * abs(v) ** 3


@dataclass(frozen=True)
class DragLoss:
    """Drag loss and the quantities behind it (arrays broadcast over operating points).

    P_W [W], v [m/s] ball pitch-line speed, X [-] oil fraction, rho_mix [kg/m³],
    mu_mix [Pa s], Re [-], c_d [-], rho_air [kg/m³], mu_air [Pa s].
    """

    P_W: np.ndarray
    v: np.ndarray
    X: np.ndarray
    rho_mix: np.ndarray
    mu_mix: np.ndarray
    Re: np.ndarray
    c_d: np.ndarray
    rho_air: np.ndarray
    mu_air: np.ndarray


def drag_loss(Z, D, dm, omega_c, X, rho_oil, mu_oil, T_K, p_Pa=_P_ATM, cd_method="Clift_Gauvin", A_c=None, *,
              check=True):
    r"""Drag loss of the balls through the oil–air mixture (Pouly 2010; seed 004 eq 21) [W].

    Parameters
    ----------
    Z : int               number of balls
    D : float             ball diameter [m]
    dm : float            pitch diameter [m]
    omega_c : array_like  cage angular speed [rad/s], > 0
    X : array_like        oil volume fraction [-] (see :func:`oil_volume_fraction_parker`)
    rho_oil : array_like  oil density at the mixture temperature [kg/m³]
    mu_oil : array_like   oil dynamic viscosity at the mixture temperature [Pa s]
    T_K : array_like      mixture temperature [K] (air properties from CoolProp)
    p_Pa : float          cavity pressure [Pa]
    cd_method : str       sphere-drag correlation of ``fluids`` (default Clift–Gauvin)
    A_c : float           ball cross-section [m²]; default πD²/4
    check : bool          False: the inputs are already checked (a bearing's geometry, a lubricant's values,
                          a fraction in [0, 1]; the temperature range is checked always)

    Returns
    -------
    DragLoss   P_W and the intermediate quantities

    Notes
    -----
    v = ω_c dm/2, ρ_mix = X ρ_oil + (1 − X) ρ_air, μ_mix = X μ_oil + (1 − X) μ_air,
    Re = ρ_mix v D / μ_mix, c_d = C_d(Re), P = ρ_mix c_d Z (A_c/2) v³.

    Examples
    --------
    Seed 004, 7210 (Z 15, D 12.7 mm estimated, dm 70 mm, 40°) at 6500 r/min, 10 L/h, 30 °C
    (ρ_oil 857 kg/m³, μ_oil 0.0494 Pa s from the seed 004 oil):

    >>> import numpy as np
    >>> wc = 6500 * np.pi / 30 * (1 - 12.7 / 70 * np.cos(np.radians(40))) / 2
    >>> X = oil_volume_fraction_parker(10 * 1000 / 60, 6500, 70.0)
    >>> r = drag_loss(15, 12.7e-3, 70e-3, wc, X, 857.0, 0.0494, 303.15)
    >>> round(r.P_W, 1), round(r.Re), round(r.c_d, 3)
    (26.8, 2287, 0.403)
    """
    if check:
        if isinstance(Z, bool) or not isinstance(Z, numbers.Real) or not math.isfinite(Z) or int(Z) != Z or Z < 1:
            raise InputError("Z", Z, "number of balls must be an integer >= 1")
        if A_c is not None:
            _pos("A_c", A_c)
        _pos("D", D)
        _pos("dm", dm)
        omega_c, X = _pos("omega_c", omega_c), _fraction(X)
        rho_oil, mu_oil, p_Pa = _pos("rho_oil", rho_oil), _pos("mu_oil", mu_oil), _pos("p_Pa", p_Pa)
    wc = omega_c
    air = _air(T_K, p_Pa)                                 # checks the temperature range
    rho_air, mu_air = air["rho"], air["mu"]
    rho_mix = _mix(X, rho_oil, rho_air)
    mu_mix = _mix(X, mu_oil, mu_air)
    v = wc * dm / 2.0
    Re = rho_mix * v * D / mu_mix
    c_d = _cd(Re, cd_method)
    P = _pouly(rho_mix, c_d, Z, D, v, A_c)
    Xb = X if isinstance(P, float) else X + np.zeros_like(P)      # the fraction of each operating point
    return DragLoss(P_W=_out(P), v=_out(v), X=_out(Xb), rho_mix=_out(rho_mix), mu_mix=_out(mu_mix), Re=_out(Re),
                    c_d=_out(c_d), rho_air=_out(rho_air), mu_air=_out(mu_air))


# --------------------------------------------------------------------------- oil bath
_PSI = np.linspace(0.0, np.pi, 721)          # ball positions from the lowest point (the path is symmetric)


def _segment_below(t):
    """Fraction of a unit disk on the side x <= t of a chord at distance t from its centre."""
    t = np.clip(t, -1.0, 1.0)
    return 1.0 - (np.arccos(t) - t * np.sqrt(1.0 - t * t)) / np.pi


def immersed_fraction(H, dm, D):
    r"""Share of the balls' drag that acts in an oil bath of level H [-] (horizontal shaft).

    Parameters
    ----------
    H : array_like    oil level above the lowest point of the outer-ring raceway (the lowest point a
                      ball reaches) [m], >= 0
    dm : float        pitch diameter [m]
    D : float         ball diameter [m]

    Returns
    -------
    ndarray  w in [0, 1]: the immersed share of each ball's frontal disk, averaged over the ball
             path (0 for H = 0, 1 once H >= dm + D)

    Notes
    -----
    A ball at angle ψ from the lowest point has its centre at height y_c = −(dm/2) cos ψ; the oil
    surface is at y_s = −(dm + D)/2 + H.  Its frontal disk (radius D/2, normal to the orbital motion)
    spans heights y_c ± (D/2)|cos ψ|; the share of the disk below the surface is the circular segment

    .. math::

        a(\psi) = 1 - \frac{\arccos \tau - \tau\sqrt{1-\tau^2}}{\pi},\qquad
        \tau = \frac{y_s - y_c}{(D/2)\,|\cos\psi|}\ \text{clipped to } [-1, 1],

    and :math:`w = \frac{1}{\pi}\int_0^{\pi} a(\psi)\, d\psi` (trapezoidal rule, 721 points).
    Geometry only: the bath is taken flat and at rest (no level drop or splash with speed).

    Examples
    --------
    6208 (dm 60 mm, D 11.9 mm): level at the lowest ball centre, at the shaft axis, over the top:

    >>> [round(float(immersed_fraction(H, 60e-3, 11.9e-3)), 3) for H in (5.95e-3, 35.95e-3, 80e-3)]
    [0.059, 0.501, 1.0]
    """
    H = np.asarray(H, dtype=float)
    if H.size and not (H.min() >= 0 and H.max() < np.inf):
        raise InputError("oil_level_mm", H, "oil level must be finite and >= 0")
    R = 0.5 * D
    h = (-(0.5 * (dm + D)) + H[..., None] + 0.5 * dm * np.cos(_PSI)) / R
    k = np.abs(np.cos(_PSI))
    tau = np.where(k > 1e-12, h / np.where(k > 1e-12, k, 1.0), np.sign(h) * 2.0)
    a = _segment_below(tau)
    w = (a.sum(axis=-1) - 0.5 * (a[..., 0] + a[..., -1])) / (_PSI.size - 1)     # trapezoidal mean, uniform ψ
    return _out(np.clip(w, 0.0, 1.0))


@dataclass(frozen=True)
class ChurningLoss:
    """Churning loss of the balls in an oil bath and the quantities behind it (arrays over operating points).

    P_W [W], immersion [-] (:func:`immersed_fraction`), v [m/s] ball pitch-line speed, Re [-], c_d [-]
    (in the oil)."""

    P_W: np.ndarray
    immersion: np.ndarray
    v: np.ndarray
    Re: np.ndarray
    c_d: np.ndarray


def churning_loss(Z, D, dm, omega_c, immersion, rho_oil, mu_oil, cd_method="Clift_Gauvin", A_c=None):
    r"""Churning loss of the balls passing through an oil bath: Pouly's drag in oil, weighted by immersion [W].

    Parameters
    ----------
    Z : int                  number of balls
    D, dm : float            ball and pitch diameter [m]
    omega_c : array_like     cage angular speed [rad/s], >= 0
    immersion : array_like   share of the ball path in the oil [-] (:func:`immersed_fraction`)
    rho_oil, mu_oil : array_like  density [kg/m³] and dynamic viscosity [Pa s] of the bath oil
    cd_method : str          sphere-drag correlation (:func:`drag_coefficient_sphere`)
    A_c : float              ball cross-section [m²]; default πD²/4

    Returns
    -------
    ChurningLoss   P_W and the quantities behind it

    Notes
    -----
    .. math::

        P = w\, \rho_{oil}\, c_d(Re)\, Z\, \frac{A_c}{2} \left(\omega_c \frac{d_m}{2}\right)^3,\qquad
        Re = \frac{\rho_{oil} v D}{\mu_{oil}}

    Seed 004 eq 21 (Pouly et al. 2010) for balls in pure oil (X = 1), weighted by the immersed share w
    of the ball path: each ball feels the sphere drag of the bath while it crosses it.  The bath is at
    rest; the rings' and cage's churning and the pumping through the bearing are not in it (SKF's
    empirical drag term lumps them, :func:`thermobear.losses.skf.drag_moment_skf2018_Nmm`).  0 at
    standstill (Stokes drag: P ∝ ω_c²) and for an empty bath (w = 0).

    Examples
    --------
    6208 (Z 9, D 11.9 mm, dm 60 mm) at a cage speed of 130 rad/s, level at the lowest ball centre,
    oil at 40 °C (ρ 860 kg/m³, μ 0.032 Pa s):

    >>> w = immersed_fraction(5.95e-3, 60e-3, 11.9e-3)
    >>> r = churning_loss(9, 11.9e-3, 60e-3, 130.0, w, 860.0, 0.032)
    >>> round(float(r.P_W), 3), round(float(r.Re)), round(float(r.c_d), 3)
    (0.662, 1247, 0.442)
    """
    if int(Z) != Z or Z < 1:
        raise InputError("Z", Z, "number of balls must be an integer >= 1")
    _pos("D", D)
    _pos("dm", dm)
    wc = _pos("omega_c", omega_c, allow_zero=True)
    w = _fraction(immersion)
    rho, mu = _pos("rho_oil", rho_oil), _pos("mu_oil", mu_oil)
    v = np.asarray(wc, dtype=float) * dm / 2.0
    moving = v > 0
    Re = np.where(moving, rho * v * D / mu, 1.0)
    c_d = np.where(moving, _cd(Re, cd_method), 0.0)
    P = np.where(moving, w * _pouly(rho, c_d, Z, D, v, A_c), 0.0)
    return ChurningLoss(P_W=_out(P), immersion=_out(w + 0.0 * P), v=_out(v), Re=_out(np.where(moving, Re, 0.0)),
                        c_d=_out(c_d))
