r"""Convection, radiation and advection of a thermal network: heat-transfer coefficients.

Pure functions (scalars or numpy arrays, broadcast) giving a heat-transfer coefficient h
[W/(m² K)] or an advective conductance G [W/K]:

===============================  ==============================================  =======================================
element                          model                                           function
===============================  ==============================================  =======================================
convection in the bearing        h = C k Pr^⅓ (u/(ν x))^½                        :func:`h_harris`
free convection, cylinder        Churchill–Chu (ChEDL ``ht``)                    :func:`h_natural_horizontal_cylinder`
free convection, vertical plate  Churchill–Chu (ChEDL ``ht``)                    :func:`h_free_vertical_plate`
free convection, horizontal      VDI Heat Atlas (ChEDL ``ht``)                   :func:`h_free_horizontal_plate`
forced convection                Churchill–Bernstein cylinder / flat plate       :func:`h_forced_cylinder`, :func:`h_forced_plate`
rotating shaft in still air      Nu = 0.133 Re_Ω^⅔ Pr^⅓                          :func:`h_rotating_cylinder`
mixed free and forced            Nu³ = Nu_F³ + Nu_N³                             :func:`mixed_convection`
radiation (linearised)           h = ε σ (T1²+T2²)(T1+T2)                        :func:`h_radiation`
oil advection (one-way)          G = ρ c_p Q̇ β                                   :func:`advection_conductance`
===============================  ==============================================  =======================================

Free-convection laws take the fluid's properties at the film temperature as a mapping ``fluid``
(k [W/(m K)], nu [m²/s], Pr [-], beta [1/K]); ``None`` is dry air at 1 atm
(:func:`air_film_properties`).

References
----------
.. [1] Pouly, F., Changenet, C., Ville, F., Velex, P., Damiens, B., 2010, "Power loss predictions
   in high-speed rolling element bearings using thermal networks", Tribology Transactions 53,
   957–967.
.. [2] Bergman, T. L., Lavine, A. S., Incropera, F. P., DeWitt, D. P., 2011, *Fundamentals of Heat
   and Mass Transfer*, 7th ed., Wiley: eq 7.23 (laminar flat plate, local Nusselt
   0.332 Re^½ Pr^⅓), eq 1.8–1.9 (radiation), §9.9 (mixed convection, Nu^n = Nu_F^n ± Nu_N^n, n = 3
   for transverse flows), the rotating-cylinder correlation of Kays & Bjorklund (ch. 7 problems).
.. [3] Churchill, S. W., Chu, H. H. S., 1975, "Correlating equations for laminar and turbulent free
   convection from a vertical plate", Int. J. Heat Mass Transfer 18, 1323–1329; VDI Heat Atlas,
   2nd ed., Springer 2010, section F2 (horizontal plates; via ChEDL ``ht``); Kays, W. M.,
   Bjorklund, I. S., 1958, "Heat transfer from a rotating cylinder with and without crossflow",
   Trans. ASME 80, 70–78 (Nu_D = 0.133 Re_Ω^⅔ Pr^⅓, Re_Ω = Ω D²/ν < 4.3e5, 0.7 < Pr < 670).
.. [4] Harris, T. A., 2001, *Rolling Bearing Analysis*, 4th ed., Wiley, ch. 15 (heat transfer in
   bearings: Nu_x = C Re_x^½ Pr^⅓ for components in the oil–air mixture, C = 0.0332).
.. [5] Churchill, S. W., Chu, H. H. S., 1975, Int. J. Heat Mass Transfer 18, 1049–1053;
   Churchill, S. W., Bernstein, M., 1977, J. Heat Transfer 99, 300–306 (via ChEDL ``ht``).
.. [6] Brossier, P., Niel, D., Changenet, C., Ville, F., Belmonte, J., 2021, "Experimental and
   numerical investigations on rolling element bearing thermal behaviour", Tribology
   International 153, 106666 (oil penetration coefficient β of oil-jet lubrication).
"""
from __future__ import annotations

import numpy as np
from ht.conv_external import Nu_cylinder_Churchill_Bernstein
from ht.conv_external import Nu_horizontal_plate_laminar_Baehr, Nu_horizontal_plate_turbulent_Schlichting
from ht.conv_free_immersed import (Nu_horizontal_cylinder_Churchill_Chu, Nu_horizontal_plate_VDI,
                                   Nu_vertical_plate_Churchill)

from thermobear.arrays import checked, out as _out
from thermobear.errors import InputError
from thermobear.lubrication.air import T_RANGE_K as AIR_T_RANGE_K
from thermobear.lubrication.air import air_properties

__all__ = ["SIGMA_SB", "G_N", "HARRIS_COEFFICIENTS", "h_harris", "oil_air_properties", "air_film_properties",
           "h_natural_horizontal_cylinder", "h_free_vertical_plate", "h_free_horizontal_plate", "h_forced_cylinder",
           "h_forced_plate", "h_rotating_cylinder", "mixed_convection", "h_radiation", "advection_conductance"]

SIGMA_SB = 5.670374419e-8   #: Stefan–Boltzmann constant [W/(m² K⁴)] (CODATA 2018, exact)
G_N = 9.80665               #: standard gravity [m/s²]

#: Named coefficients C of the convection law h = C k Pr^⅓ (u/(ν x))^½.
HARRIS_COEFFICIENTS = {
    "harris": 0.0332,               # Harris 2001 ch. 15 [4]
    "flat_plate_laminar": 0.332,    # laminar flat plate, local Nusselt [2] eq 7.23: 10× Harris's
}

#: ht's horizontal-plate law (scalar branches) over arrays
_NU_HORIZONTAL_PLATE = np.vectorize(Nu_horizontal_plate_VDI, otypes=[float])
#: ht's laminar flat-plate law in parallel flow (branches on Pr) over arrays
_NU_PLATE_LAMINAR = np.vectorize(Nu_horizontal_plate_laminar_Baehr, otypes=[float])


def h_harris(k, Pr, u, nu, x, coefficient="harris"):
    r"""Convection coefficient of a bearing component in the oil–air mixture [W/(m² K)].

    Parameters
    ----------
    k : array_like    fluid thermal conductivity [W/(m K)]
    Pr : array_like   fluid Prandtl number [-]
    u : array_like    surface speed relative to the fluid [m/s]
    nu : array_like   fluid kinematic viscosity [m²/s]
    x : array_like    characteristic length (ball diameter, ring width) [m]
    coefficient : str or float  ``"harris"`` (0.0332), ``"flat_plate_laminar"`` (0.332) or a number

    Returns
    -------
    float or ndarray  h [W/(m² K)]

    Notes
    -----
    .. math:: h = C\, k\, Pr^{1/3} \left(\frac{u}{\nu x}\right)^{1/2}, \quad Nu_x = C\, Re_x^{1/2} Pr^{1/3}

    Harris 2001 ch. 15 gives C = 0.0332 [4]_, ten times below laminar flat-plate theory (0.332,
    Bergman et al. 2011 eq 7.23 [2]_) for the same Re_x and Pr; which one Pouly et al. 2010 used is
    not stated, so the coefficient is a named choice of each network element.

    Examples
    --------
    >>> round(h_harris(0.03, 1.0, 10.0, 1e-5, 0.01), 3)      # 0.0332 * 0.03 * 1e4
    9.96
    >>> round(h_harris(0.03, 1.0, 10.0, 1e-5, 0.01, "flat_plate_laminar"), 2)
    99.6
    """
    if isinstance(coefficient, str):
        if coefficient not in HARRIS_COEFFICIENTS:
            raise InputError("correlation", coefficient, f"one of {sorted(HARRIS_COEFFICIENTS)}")
        C = HARRIS_COEFFICIENTS[coefficient]
    else:
        C = float(coefficient)
    k, Pr, nu, x = checked("k_W_mK", k), checked("Pr", Pr), checked("nu_m2_s", nu), checked("x_m", x)
    u = checked("u_m_s", u, strict=False)
    return _out(C * k * np.cbrt(Pr) * np.sqrt(u / (nu * x)))


def oil_air_properties(X, rho_oil, nu_oil_cSt, k_oil, cp_oil, T_K):
    r"""Properties of the oil–air mixture in the bearing cavity.

    Parameters
    ----------
    X : array_like           oil volume fraction, 0 ≤ X ≤ 1 [-]
    rho_oil : array_like     oil density [kg/m³]
    nu_oil_cSt : array_like  oil kinematic viscosity [mm²/s]
    k_oil, cp_oil : array_like  oil conductivity [W/(m K)] and specific heat [J/(kg K)]
    T_K : array_like         temperature (air properties, 200–600 K) [K]

    Returns
    -------
    dict  rho [kg/m³], mu [Pa s], k [W/(m K)], cp [J/(kg K)], nu [m²/s], Pr [-] of the mixture

    Notes
    -----
    Linear volume mixing of ρ, μ and k, mass-weighted c_p (Pouly et al. 2010 [1]_ for ρ and μ;
    the same rule for k is an estimate):

    .. math:: \rho_e = X \rho_o + (1 - X) \rho_a, \quad \mu_e = X \mu_o + (1 - X) \mu_a

    Examples
    --------
    >>> p = oil_air_properties(0.0, 860.0, 20.0, 0.13, 1950.0, 300.0)
    >>> round(p["k"], 4) == round(air_properties(300.0)["k"], 4)
    True
    """
    X = np.asarray(X, dtype=float)
    if X.size and not (X.min() >= 0.0 and X.max() <= 1.0):
        raise InputError("oil_fraction", _out(X), "oil volume fraction must lie in [0, 1]")
    air = air_properties(T_K)
    mu_oil = np.asarray(nu_oil_cSt, dtype=float) * 1e-6 * rho_oil
    rho = X * rho_oil + (1 - X) * air["rho"]
    mu = X * mu_oil + (1 - X) * air["mu"]
    k = X * k_oil + (1 - X) * air["k"]
    cp = (X * rho_oil * cp_oil + (1 - X) * air["rho"] * air["cp"]) / rho
    return {key: _out(v) for key, v in dict(rho=rho, mu=mu, k=k, cp=cp, nu=mu / rho, Pr=mu * cp / k).items()}


def _film_air(T_s_K, T_inf_K):
    """Air at the film temperature (held inside the table's 200–600 K)."""
    Tf = 0.5 * (np.asarray(T_s_K, float) + np.asarray(T_inf_K, float))
    return Tf, air_properties(np.clip(Tf, *AIR_T_RANGE_K))


def h_natural_horizontal_cylinder(T_s_K, T_inf_K, D):
    r"""Free-convection coefficient of a horizontal cylinder in still air [W/(m² K)].

    Parameters
    ----------
    T_s_K, T_inf_K : array_like  surface and ambient temperature [K]
    D : array_like               cylinder diameter [m]

    Returns
    -------
    float or ndarray  h = Nu_D k / D [W/(m² K)]

    Notes
    -----
    Churchill & Chu 1975 [5]_ (``ht.conv_free_immersed.Nu_horizontal_cylinder_Churchill_Chu``):

    .. math:: Nu_D = \left[0.60 + \frac{0.387\, Ra^{1/6}}{(1 + (0.559/Pr)^{9/16})^{8/27}}\right]^2

    air at the film temperature, Ra = Gr Pr, Gr = g β |ΔT| D³/ν², β = 1/T_film (ideal gas).

    Examples
    --------
    >>> round(h_natural_horizontal_cylinder(330.0, 300.0, 0.15), 2)
    4.76
    """
    D = checked("D_m", D)
    Tf, air = _film_air(T_s_K, T_inf_K)
    Gr = G_N / Tf * np.abs(np.asarray(T_s_K, float) - T_inf_K) * D**3 / air["nu"] ** 2
    return _out(Nu_horizontal_cylinder_Churchill_Chu(Pr=air["Pr"], Gr=Gr) * air["k"] / D)


def h_forced_cylinder(u_inf, D, T_s_K, T_inf_K):
    r"""Forced-convection coefficient of a cylinder in cross-flow of air [W/(m² K)].

    Parameters
    ----------
    u_inf : array_like           free-stream air speed [m/s]
    D : array_like               cylinder diameter [m]
    T_s_K, T_inf_K : array_like  surface and air temperature [K] (film properties)

    Returns
    -------
    float or ndarray  h = Nu_D k / D [W/(m² K)]

    Notes
    -----
    Churchill & Bernstein 1977 [5]_ (``ht.conv_external.Nu_cylinder_Churchill_Bernstein``; in ht
    1.2.0 the dispatcher ``Nu_external_cylinder(Method="Churchill-Bernstein")`` runs
    Sanitjai–Goldstein instead, 14 % higher here, so the specific function is called):

    .. math:: Nu_D = 0.3 + \frac{0.62 Re^{1/2} Pr^{1/3}}{[1 + (0.4/Pr)^{2/3}]^{1/4}}
              \left[1 + \left(\frac{Re}{282000}\right)^{5/8}\right]^{4/5}

    Examples
    --------
    >>> round(h_forced_cylinder(2.0, 0.1, 320.0, 300.0), 2)
    16.04
    """
    D, u = checked("D_m", D), checked("u_air_m_s", u_inf)
    _, air = _film_air(T_s_K, T_inf_K)
    return _out(Nu_cylinder_Churchill_Bernstein(Re=u * D / air["nu"], Pr=air["Pr"]) * air["k"] / D)


def h_forced_plate(u_inf, L, T_s_K, T_inf_K):
    r"""Mean forced-convection coefficient of a flat plate in parallel air flow [W/(m² K)].

    Parameters
    ----------
    u_inf : array_like           free-stream air speed [m/s]
    L : array_like               plate length in the flow direction [m]
    T_s_K, T_inf_K : array_like  surface and air temperature [K] (film properties)

    Returns
    -------
    float or ndarray  h = Nu_L k / L [W/(m² K)]

    Notes
    -----
    Laminar Baehr (Nu = 0.664 Re^½ Pr^⅓ for Pr 0.6–10), turbulent Schlichting above the transition
    Reynolds number 5e5, as ``ht.Nu_external_horizontal_plate`` selects them [5]_.

    Examples
    --------
    >>> round(h_forced_plate(2.0, 0.1, 320.0, 300.0), 2)    # laminar: 0.664 Re^½ Pr^⅓ k/L
    17.55
    >>> [round(float(h), 2) for h in h_forced_plate(2.0, 0.1, [320.0, 340.0], 300.0)]   # film temperatures per point
    [17.55, 17.51]
    """
    L, u = checked("L_m", L), checked("u_air_m_s", u_inf)
    _, air = _film_air(T_s_K, T_inf_K)
    Re = u * L / air["nu"]
    Nu = np.where(Re < 5e5, _NU_PLATE_LAMINAR(Re, air["Pr"]),
                  Nu_horizontal_plate_turbulent_Schlichting(np.maximum(Re, 5e5), air["Pr"]))
    return _out(Nu * air["k"] / L)


def air_film_properties(T_s_K, T_inf_K) -> dict:
    r"""Dry air at 1 atm at the film temperature ½(T_s + T_∞) for free convection.

    Parameters
    ----------
    T_s_K, T_inf_K : array_like  surface and fluid temperature [K]

    Returns
    -------
    dict  k [W/(m K)], nu [m²/s], Pr [-], beta = 1/T_film [1/K] (ideal gas)

    Examples
    --------
    >>> p = air_film_properties(320.0, 300.0)
    >>> round(p["beta"] * 310.0, 12)
    1.0
    """
    Tf, air = _film_air(T_s_K, T_inf_K)
    return {"k": air["k"], "nu": air["nu"], "Pr": air["Pr"], "beta": _out(1.0 / np.asarray(Tf, float))}


def _grashof(fluid, T_s_K, T_inf_K, L):
    f = air_film_properties(T_s_K, T_inf_K) if fluid is None else fluid
    dT = np.abs(np.asarray(T_s_K, float) - np.asarray(T_inf_K, float))
    return f, G_N * f["beta"] * dT * L**3 / f["nu"] ** 2


def h_free_vertical_plate(T_s_K, T_inf_K, L, fluid=None):
    r"""Free-convection coefficient of an isothermal vertical plate [W/(m² K)].

    Parameters
    ----------
    T_s_K, T_inf_K : array_like  surface and fluid temperature [K]
    L : array_like               plate height [m]
    fluid : mapping or None      k, nu, Pr, beta at the film temperature (None: air)

    Returns
    -------
    float or ndarray  h = Nu_L k / L [W/(m² K)]

    Notes
    -----
    Churchill & Chu 1975 [3]_, laminar to turbulent (``ht.conv_free_immersed.Nu_vertical_plate_Churchill``):

    .. math:: Nu_L = \left[0.825 + \frac{0.387\, Ra_L^{1/6}}{(1 + (0.492/Pr)^{9/16})^{8/27}}\right]^2,
              \quad Ra_L = \frac{g \beta |T_s - T_\infty| L^3}{\nu^2} Pr

    Examples
    --------
    >>> round(h_free_vertical_plate(330.0, 300.0, 0.1), 2)
    5.65
    """
    L = checked("L_m", L)
    f, Gr = _grashof(fluid, T_s_K, T_inf_K, L)
    return _out(Nu_vertical_plate_Churchill(Pr=f["Pr"], Gr=Gr) * f["k"] / L)


def h_free_horizontal_plate(T_s_K, T_inf_K, L, facing="up", fluid=None):
    r"""Free-convection coefficient of an isothermal horizontal plate [W/(m² K)].

    Parameters
    ----------
    T_s_K, T_inf_K : array_like  surface and fluid temperature [K]
    L : array_like               characteristic length A/P (area over perimeter) [m]
    facing : str                 ``"up"`` (the top face of a body) or ``"down"`` (its underside)
    fluid : mapping or None      k, nu, Pr, beta at the film temperature (None: air)

    Returns
    -------
    float or ndarray  h = Nu_L k / L [W/(m² K)]

    Notes
    -----
    VDI Heat Atlas F2 (``ht.conv_free_immersed.Nu_horizontal_plate_VDI`` [3]_): a hot face up (or a
    cold face down) drives the buoyant plume off the plate,

    .. math:: Nu = 0.766 (Ra f_2)^{1/5} \; (Ra f_2 < 7\cdot 10^4), \quad 0.15 (Ra f_2)^{1/3}, \quad
              f_2 = [1 + (0.322/Pr)^{0.55}]^{20/11}

    a hot face down (a cold face up) holds the fluid under it, Nu = 0.6 (Ra f_1)^{1/5},
    f_1 = [1 + (0.492/Pr)^{9/16}]^{-16/9}.

    Examples
    --------
    >>> up, down = h_free_horizontal_plate(330.0, 300.0, 0.05, "up"), h_free_horizontal_plate(330.0, 300.0, 0.05, "down")
    >>> round(up, 2), round(down, 2)
    (7.3, 3.28)
    """
    if facing not in ("up", "down"):
        raise InputError("facing", facing, "one of up, down")
    L = checked("L_m", L)
    f, Gr = _grashof(fluid, T_s_K, T_inf_K, L)
    hot = np.asarray(T_s_K, float) >= np.asarray(T_inf_K, float)
    buoyant = hot if facing == "up" else ~hot
    return _out(_NU_HORIZONTAL_PLATE(f["Pr"], Gr, buoyant) * f["k"] / L)


def h_rotating_cylinder(omega, D, T_s_K, T_inf_K):
    r"""Convection coefficient of a cylinder rotating about its axis in still air [W/(m² K)].

    Parameters
    ----------
    omega : array_like           angular speed, ≥ 0 [rad/s]
    D : array_like               diameter [m]
    T_s_K, T_inf_K : array_like  surface and air temperature [K] (film properties)

    Returns
    -------
    float or ndarray  h = Nu_D k / D [W/(m² K)] (the rotation alone; see :func:`mixed_convection`)

    Notes
    -----
    Kays & Bjorklund 1958 [3]_ (quoted by Bergman et al. 2011 [2]_):

    .. math:: Nu_D = 0.133\, Re_\Omega^{2/3} Pr^{1/3}, \quad Re_\Omega = \frac{\Omega D^2}{\nu}
              \quad (Re_\Omega < 4.3\cdot 10^5,\ 0.7 < Pr < 670)

    Examples
    --------
    >>> round(h_rotating_cylinder(314.16, 0.04, 320.0, 300.0), 2)    # 3000 rpm, 40 mm
    77.71
    """
    D, w = checked("D_m", D), checked("omega_rad_s", omega, strict=False)
    _, air = _film_air(T_s_K, T_inf_K)
    Re = w * D**2 / air["nu"]
    return _out(0.133 * Re ** (2.0 / 3.0) * np.cbrt(air["Pr"]) * air["k"] / D)


def mixed_convection(h_forced, h_free, n=3.0):
    r"""Heat-transfer coefficient of combined forced and free convection [W/(m² K)].

    Parameters
    ----------
    h_forced, h_free : array_like  the two coefficients alone [W/(m² K)]
    n : float                      exponent (3 for transverse flows about cylinders and plates)

    Returns
    -------
    float or ndarray  h [W/(m² K)]

    Notes
    -----
    Churchill's combination for assisting and transverse flows (Bergman et al. 2011 §9.9 [2]_):

    .. math:: h^n = h_F^n + h_N^n

    Examples
    --------
    >>> mixed_convection(3.0, 4.0, 2.0), mixed_convection(10.0, 0.0)
    (5.0, 10.0)
    """
    hf, hn = checked("h_forced_W_m2K", h_forced, strict=False), checked("h_free_W_m2K", h_free, strict=False)
    big, small = np.maximum(hf, hn), np.minimum(hf, hn)
    ratio = np.divide(small, big, out=np.zeros_like(big), where=big > 0)
    return _out(big * (1.0 + ratio**n) ** (1.0 / n))          # = (h_F^n + h_N^n)^(1/n), exact at either limit


def h_radiation(emissivity, T1_K, T2_K):
    r"""Linearised radiation coefficient of a small grey body in large surroundings [W/(m² K)].

    Parameters
    ----------
    emissivity : array_like  ε of the surface, 0 < ε ≤ 1 [-]
    T1_K, T2_K : array_like  surface and surroundings temperature [K]

    Returns
    -------
    float or ndarray  h [W/(m² K)]

    Notes
    -----
    .. math:: h = \varepsilon \sigma (T_1^2 + T_2^2)(T_1 + T_2)

    so that h (T1 − T2) = ε σ (T1⁴ − T2⁴) exactly (Bergman et al. 2011 eqs 1.7–1.9 [2]_; the
    secant form of 4 ε σ T_m³, re-evaluated at every iterate of the solvers).

    Examples
    --------
    >>> h = h_radiation(0.8, 350.0, 300.0)
    >>> round(h * 50.0, 6) == round(0.8 * SIGMA_SB * (350.0**4 - 300.0**4), 6)
    True
    """
    eps = np.asarray(emissivity, dtype=float)
    if eps.size and not (eps.min() > 0 and eps.max() <= 1):
        raise InputError("emissivity", _out(eps), "must lie in (0, 1]")
    T1, T2 = checked("T1_K", T1_K), checked("T2_K", T2_K)
    return _out(eps * SIGMA_SB * (T1**2 + T2**2) * (T1 + T2))


def advection_conductance(rho, cp, Q, beta):
    r"""Advective conductance of the oil stream through the bearing [W/K].

    Parameters
    ----------
    rho : array_like   oil density [kg/m³]
    cp : array_like    oil specific heat [J/(kg K)]
    Q : array_like     supplied oil flow [m³/s]
    beta : array_like  penetration coefficient: fraction of Q passing through the bearing,
                       0 < β ≤ 1 [-] (≈ 0.4 for oil jets, Brossier et al. 2021 [6]_, as seed 004 §4.5 uses)

    Returns
    -------
    float or ndarray  G [W/K]

    Notes
    -----
    .. math:: G = \rho\, c_p\, \dot Q\, \beta

    The heat carried away is Φ = G (T_mix − T_in): a one-way (upwind) link, only the downstream
    node's balance contains it.

    Examples
    --------
    >>> round(advection_conductance(864.6, 1950.0, 10 / 3.6e6, 0.4), 4)
    1.8733
    """
    beta = np.asarray(beta, dtype=float)
    if beta.size and not (beta.min() > 0 and beta.max() <= 1):
        raise InputError("beta", _out(beta), "penetration coefficient must lie in (0, 1]")
    return _out(checked("rho_kg_m3", rho) * checked("cp_J_kgK", cp) * checked("Q_m3_s", Q, strict=False) * beta)
