r"""Thermal elements: conductances between two nodes of a thermal network.

Pure functions (scalars or numpy arrays, broadcast) give the conductance G [W/K] or the
heat-transfer coefficient h [W/(m² K)] of each element family [1]_, [2]_:

=========================  ==============================================  ===================================
element                    model                                           function
=========================  ==============================================  ===================================
radial conduction          G = 2π k L / ln(r2/r1)                          :func:`shell_conductance`
planar conduction          G = k A / ℓ                                     :func:`planar_conductance`
ball–race contact          R = 𝔎(e)/(2π k a) per body per contact          :func:`ball_race_conductance`
convection in the bearing  h = C k Pr^⅓ (u/(ν x))^½                        :func:`h_harris`
free convection, cylinder  Churchill–Chu (ChEDL ``ht``)                    :func:`h_natural_horizontal_cylinder`
forced convection          Churchill–Bernstein cylinder / flat plate       :func:`h_forced_cylinder`, :func:`h_forced_plate`
radiation (linearised)     h = ε σ (T1²+T2²)(T1+T2)                        :func:`h_radiation`
oil advection (one-way)    G = ρ c_p Q̇ β                                   :func:`advection_conductance`
=========================  ==============================================  ===================================

The element kinds at the end (:data:`ELEMENT_TYPES`) wrap these functions as network elements:
each holds its SI parameters — numbers, or arrays over a batch of operating points — and returns
its conductance at the node temperatures of every operating point at once.  Which element joins
which nodes is data (``networks/*.toml``).

References
----------
.. [1] Pouly, F., Changenet, C., Ville, F., Velex, P., Damiens, B., 2010, "Power loss predictions
   in high-speed rolling element bearings using thermal networks", Tribology Transactions 53,
   957–967.
.. [2] Bergman, T. L., Lavine, A. S., Incropera, F. P., DeWitt, D. P., 2011, *Fundamentals of Heat
   and Mass Transfer*, 7th ed., Wiley: eq 3.33 (cylindrical shell), eq 3.6 (plane wall), eq 7.23
   (laminar flat plate, local Nusselt 0.332 Re^½ Pr^⅓), eq 1.8–1.9 (radiation).
.. [3] Yovanovich, M. M., 1971, "Thermal constriction resistance between contacting metallic
   paraboloids", AIAA Progress in Astronautics 24, 337–358; Muzychka, Y. S., Yovanovich, M. M.,
   2001, "Thermal resistance models for non-circular moving heat sources", J. Heat Transfer 123,
   1028–1034 (the elliptical isothermal contact, R = 𝔎(e)/(2π k a)).
.. [4] Harris, T. A., 2001, *Rolling Bearing Analysis*, 4th ed., Wiley, ch. 15 (heat transfer in
   bearings: Nu_x = C Re_x^½ Pr^⅓ for components in the oil–air mixture, C = 0.0332).
.. [5] Churchill, S. W., Chu, H. H. S., 1975, Int. J. Heat Mass Transfer 18, 1049–1053;
   Churchill, S. W., Bernstein, M., 1977, J. Heat Transfer 99, 300–306 (via ChEDL ``ht``).
.. [6] Brossier, P., Niel, D., Changenet, C., Ville, F., Belmonte, J., 2021, "Experimental and
   numerical investigations on rolling element bearing thermal behaviour", Tribology
   International 153, 106666 (oil penetration coefficient β of oil-jet lubrication).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from ht.conv_external import Nu_cylinder_Churchill_Bernstein
from ht.conv_external import Nu_horizontal_plate_laminar_Baehr, Nu_horizontal_plate_turbulent_Schlichting
from ht.conv_free_immersed import Nu_horizontal_cylinder_Churchill_Chu
from scipy.special import ellipk

from thermobear.arrays import checked, out as _out
from thermobear.errors import InputError
from thermobear.lubrication.air import T_RANGE_K as AIR_T_RANGE_K
from thermobear.lubrication.air import air_properties
from thermobear.validity import T_LUBRICANT_REFUSE_C

__all__ = [
    "SIGMA_SB", "shell_conductance", "planar_conductance", "constriction_resistance",
    "ball_race_conductance", "h_harris", "HARRIS_COEFFICIENTS", "oil_air_properties",
    "h_natural_horizontal_cylinder", "h_forced_cylinder", "h_forced_plate", "h_radiation",
    "advection_conductance", "Element", "ELEMENT_TYPES", "CORRELATIONS", "CORRELATION_KEYS",
    "STRING_KEYS", "MATERIAL_KEYS",
]

SIGMA_SB = 5.670374419e-8   #: Stefan–Boltzmann constant [W/(m² K⁴)] (CODATA 2018, exact)
G_N = 9.80665               #: standard gravity [m/s²]

#: Named coefficients C of the convection law h = C k Pr^⅓ (u/(ν x))^½.
HARRIS_COEFFICIENTS = {
    "harris": 0.0332,               # Harris 2001 ch. 15 [4]
    "flat_plate_laminar": 0.332,    # laminar flat plate, local Nusselt [2] eq 7.23: 10× Harris's
}


# ---------------------------------------------------------------------------
# conduction
# ---------------------------------------------------------------------------
def shell_conductance(k, L, r1, r2):
    r"""Conductance of radial conduction through a cylindrical shell [W/K].

    Parameters
    ----------
    k : array_like       thermal conductivity [W/(m K)]
    L : array_like       axial length (ring width) [m]
    r1, r2 : array_like  inner and outer radius, 0 < r1 < r2 [m]

    Returns
    -------
    float or ndarray  G [W/K]

    Notes
    -----
    .. math:: G = \frac{2 \pi k L}{\ln(r_2 / r_1)}

    (Bergman et al. 2011 eq 3.33 [2]).

    Examples
    --------
    >>> round(shell_conductance(42.7, 0.02, 0.025, 0.0286), 2)
    39.9
    """
    k, L, r1, r2 = (checked(n, v) for n, v in (("k_W_mK", k), ("L_m", L), ("r1_m", r1), ("r2_m", r2)))
    if np.any(r2 <= r1):
        raise InputError("r2_m", _out(r2), f"outer radius must exceed the inner radius r1_m = {_out(r1)}")
    return _out(2.0 * np.pi * k * L / np.log(r2 / r1))


def planar_conductance(k, A, length):
    r"""Conductance of one-dimensional planar (or axial) conduction [W/K].

    Parameters
    ----------
    k : array_like       thermal conductivity [W/(m K)]
    A : array_like       cross-section normal to the heat flow [m²]
    length : array_like  conduction length ℓ [m]

    Returns
    -------
    float or ndarray  G [W/K]

    Notes
    -----
    .. math:: G = \frac{k A}{\ell}

    (Bergman et al. 2011 eq 3.6 [2]).

    Examples
    --------
    >>> planar_conductance(40.0, 1e-3, 0.1)
    0.4
    """
    return _out(checked("k_W_mK", k) * checked("A_m2", A) / checked("length_m", length))


def constriction_resistance(k, a, b):
    r"""Constriction resistance of one body at an elliptical isothermal contact [K/W].

    Parameters
    ----------
    k : array_like    thermal conductivity of the body [W/(m K)]
    a, b : array_like semi-axes of the Hertz ellipse [m] (either order; the
                      larger one is the major semi-axis)

    Returns
    -------
    float or ndarray  R [K/W]

    Notes
    -----
    .. math:: R = \frac{\mathfrak{K}(m)}{2 \pi k a_{major}}, \quad m = 1 - (a_{minor}/a_{major})^2

    (Yovanovich 1971; Muzychka & Yovanovich 2001 [3]); 𝔎 is the complete elliptic integral of
    the first kind with *parameter* m = e² (``scipy.special.ellipk``).  For a circle 𝔎(0) = π/2
    and R = 1/(4 k a).  Stationary, isothermal contact: at Péclet numbers u b/(2κ) ≫ 1 the moving
    heat source lowers R (a ×2–5 uncertainty, not modelled).

    Examples
    --------
    >>> r = constriction_resistance(40.0, 1e-3, 1e-3)     # circle: 1/(4 k a)
    >>> round(r, 6), round(1 / (4 * 40.0 * 1e-3), 6)
    (6.25, 6.25)
    """
    k, a, b = checked("k_W_mK", k), checked("a_m", a), checked("b_m", b)
    major, minor = np.maximum(a, b), np.minimum(a, b)
    return _out(ellipk(1.0 - (minor / major) ** 2) / (2.0 * np.pi * k * major))


def ball_race_conductance(k_ball, k_ring, a, b):
    r"""Total conductance of the ball–race contacts of one raceway [W/K].

    Parameters
    ----------
    k_ball, k_ring : array_like  conductivities of ball and ring [W/(m K)] (broadcast against
                                 the leading axes of ``a``)
    a, b : array_like            per-ball Hertz semi-axes [m], shape (..., Z); a ball with
                                 a = 0 or b = 0 is unloaded and conducts nothing

    Returns
    -------
    float or ndarray  G [W/K], summed over the last axis

    Notes
    -----
    One constriction per body (:func:`constriction_resistance`), the two bodies in series, the
    contacts in parallel [1]_, [3]_:

    .. math:: G = \sum_{balls} \frac{1}{R_{ball} + R_{ring}}

    Examples
    --------
    >>> G = ball_race_conductance(42.7, 42.7, [1e-3, 1e-3, 0.0], [2e-4, 2e-4, 0.0])
    >>> G1 = 1 / (2 * constriction_resistance(42.7, 1e-3, 2e-4))
    >>> round(G / G1, 12)
    2.0
    """
    a, b = np.broadcast_arrays(np.asarray(a, dtype=float), np.asarray(b, dtype=float))
    checked("contacts.a_m", a, strict=False)
    checked("contacts.b_m", b, strict=False)
    kb = checked("k_W_mK", k_ball)[..., None]
    kr = checked("k_W_mK", k_ring)[..., None]
    loaded = (a > 0) & (b > 0)
    aa, bb = np.where(loaded, a, 1.0), np.where(loaded, b, 1.0)
    major, minor = np.maximum(aa, bb), np.minimum(aa, bb)
    Km = ellipk(1.0 - (minor / major) ** 2)
    R = Km / (2.0 * np.pi * major) * (1.0 / kb + 1.0 / kr)
    return _out(np.sum(np.where(loaded, 1.0 / R, 0.0), axis=-1))


# ---------------------------------------------------------------------------
# convection
# ---------------------------------------------------------------------------
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
    """
    L, u = checked("L_m", L), checked("u_air_m_s", u_inf)
    _, air = _film_air(T_s_K, T_inf_K)
    Re = u * L / air["nu"]
    Nu = np.where(Re < 5e5, Nu_horizontal_plate_laminar_Baehr(Re, air["Pr"]),
                  Nu_horizontal_plate_turbulent_Schlichting(np.maximum(Re, 5e5), air["Pr"]))
    return _out(Nu * air["k"] / L)


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


# ---------------------------------------------------------------------------
# network elements: parameters in SI (numbers or arrays over the operating points)
# ---------------------------------------------------------------------------
def _oil_T(T_K):
    """Temperature [°C] for the oil's property correlations, held inside their accepted range: an
    iterate of a coupled solve may overshoot transiently; an equilibrium beyond the limit is
    reported as runaway by the solver, not as an error from a property call."""
    return np.clip(np.asarray(T_K, float) - 273.15, *T_LUBRICANT_REFUSE_C)


@dataclass(frozen=True)
class Element:
    """One element (edge) of a thermal network.

    Attributes
    ----------
    name : str            unique element name
    type : str            element family (key of :data:`ELEMENT_TYPES`)
    nodes : tuple         (node_0, node_1); for ``advection`` (upstream, downstream)
    i, j : int            node indices
    p : dict              parameters (SI, keys as in the network file): numbers, or arrays over the
                          operating points (shape (B,)); materials as Material objects
    """

    name: str
    type: str
    nodes: tuple
    i: int
    j: int
    p: dict = field(repr=False)
    advective = False               #: one-way link (upwind), not a symmetric conductance

    def depends_on(self) -> tuple:
        """Indices of the nodes whose temperatures the conductance depends on."""
        return ()

    def conductance(self, Ti, Tj, oil=None, shared=None):
        """Conductance [W/K] at the temperatures ``Ti``, ``Tj`` [K] of its two nodes (arrays over the
        operating points); ``oil`` the lubricant (fluid properties), ``shared`` a dict in which
        elements evaluated at the same temperatures share fluid properties."""
        raise TypeError(f"{type(self).__name__} is an element base class: it has no conductance of its own")


def _k(p, key="k_W_mK", mat="material"):
    return p[key] if key in p else p[mat].k


class Conductance(Element):
    """A given conductance ``G_W_K`` or resistance ``R_K_W``."""

    def conductance(self, Ti, Tj, oil=None, shared=None):
        return self.p["G_W_K"] if "G_W_K" in self.p else 1.0 / self.p["R_K_W"]


class Shell(Element):
    """Radial conduction through a cylindrical shell (:func:`shell_conductance`)."""

    def conductance(self, Ti, Tj, oil=None, shared=None):
        return shell_conductance(_k(self.p), self.p["L_m"], self.p["r1_m"], self.p["r2_m"])


class Planar(Element):
    """Planar / axial conduction (:func:`planar_conductance`)."""

    def conductance(self, Ti, Tj, oil=None, shared=None):
        return planar_conductance(_k(self.p), self.p["A_m2"], self.p["length_m"])


class Interface(Element):
    """Thermal contact conductance of a fitted or clamped joint: G = h_c A."""

    def conductance(self, Ti, Tj, oil=None, shared=None):
        return checked("h_W_m2K", self.p["h_W_m2K"]) * checked("A_m2", self.p["A_m2"])


class BallRaceContact(Element):
    """Ball–race Hertz contacts of one raceway, balls in parallel (:func:`ball_race_conductance`).

    The per-ball semi-axes ``a_m``, ``b_m`` (shape (..., Z)) come from the mechanics (the network
    reads ``contacts.<inner|outer>.a_m`` / ``.b_m``), else from the element's fallback.
    """

    def conductance(self, Ti, Tj, oil=None, shared=None):
        kb = self.p["k_ball_W_mK"] if "k_ball_W_mK" in self.p else self.p["material_ball"].k
        kr = self.p["k_ring_W_mK"] if "k_ring_W_mK" in self.p else self.p["material_ring"].k
        return ball_race_conductance(kb, kr, self.p["a_m"], self.p["b_m"])


class Convection(Element):
    """Convection from a surface (node 0) to a fluid (node 1) with a NAMED correlation.

    ``correlation``: ``harris`` / ``flat_plate_laminar`` (oil–air mixture, needs ``u_m_s``,
    ``x_m``, ``oil_fraction`` and the lubricant), ``natural_horizontal_cylinder`` (``D_m``),
    ``forced_cylinder`` (``D_m``, ``u_air_m_s``), ``forced_plate`` (``L_m``, ``u_air_m_s``),
    ``given`` (``h_W_m2K``).  Always ``A_m2``.
    """

    def depends_on(self):
        c = self.p["correlation"]
        return () if c == "given" else (self.j,) if c in HARRIS_COEFFICIENTS else (self.i, self.j)

    def _fluid(self, Tf, oil, shared):
        """Properties of the fluid node at ``Tf`` [K] (harris-type laws), shared per state."""
        p = self.p
        fluid = p.get("fluid", "oil_air")
        X = 0.0 if fluid == "air" else 1.0 if fluid == "oil" else p["oil_fraction"]
        key = (self.j, fluid, X.tobytes() if isinstance(X, np.ndarray) else X)
        if shared is not None and key in shared:
            return shared[key]
        if fluid == "air":
            props = air_properties(np.clip(Tf, *AIR_T_RANGE_K))
        else:
            T_C = _oil_T(Tf)
            props = oil_air_properties(X, oil.rho(T_C), oil.nu(T_C), oil.k_th(T_C), oil.cp(T_C), T_C + 273.15)
        if shared is not None:
            shared[key] = props
        return props

    def h(self, Ti, Tj, oil=None, shared=None):
        """Heat-transfer coefficient [W/(m² K)] at the node temperatures [K]."""
        p, c = self.p, self.p["correlation"]
        if c == "given":
            return p["h_W_m2K"]
        if c in HARRIS_COEFFICIENTS:
            props = self._fluid(Tj, oil, shared)
            return h_harris(props["k"], props["Pr"], p["u_m_s"], props["nu"], p["x_m"], c)
        if c == "natural_horizontal_cylinder":
            return h_natural_horizontal_cylinder(Ti, Tj, p["D_m"])
        if c == "forced_cylinder":
            return h_forced_cylinder(p["u_air_m_s"], p["D_m"], Ti, Tj)
        return h_forced_plate(p["u_air_m_s"], p["L_m"], Ti, Tj)

    def conductance(self, Ti, Tj, oil=None, shared=None):
        return self.h(Ti, Tj, oil, shared) * self.p["A_m2"]


class Radiation(Element):
    """Linearised radiation from node 0 (surface, ``A_m2``, ``emissivity``) to node 1."""

    def depends_on(self):
        return (self.i, self.j)

    def conductance(self, Ti, Tj, oil=None, shared=None):
        return h_radiation(self.p["emissivity"], Ti, Tj) * self.p["A_m2"]


class Advection(Element):
    """One-way oil stream from node 0 (upstream, e.g. the fixed oil inlet) through node 1.

    G = ρ c_p Q̇ β (:func:`advection_conductance`), with ρ, c_p given (``rho_kg_m3``,
    ``cp_J_kgK``) or those of the lubricant at the upstream temperature.
    """

    advective = True

    def depends_on(self):
        return () if ("rho_kg_m3" in self.p and "cp_J_kgK" in self.p) else (self.i,)

    def conductance(self, Ti, Tj, oil=None, shared=None):
        p = self.p
        T_C = _oil_T(Ti)
        rho = p["rho_kg_m3"] if "rho_kg_m3" in p else oil.rho(T_C)
        cp = p["cp_J_kgK"] if "cp_J_kgK" in p else oil.cp(T_C)
        return advection_conductance(rho, cp, p["Q_m3_s"], p["beta"])


CORRELATIONS = ("harris", "flat_plate_laminar", "natural_horizontal_cylinder", "forced_cylinder",
                "forced_plate", "given")

#: Element families: class, required keys, optional keys, "one of" groups.  Numeric keys carry
#: their unit in the name (``_m``, ``_m2``, ``_W_mK`` ...); dimensionless ones (beta, emissivity,
#: oil_fraction, n_balls) are listed as such.
ELEMENT_TYPES = {
    "conductance": dict(cls=Conductance, required=(), optional=(), one_of=(("G_W_K", "R_K_W"),)),
    "shell": dict(cls=Shell, required=("r1_m", "r2_m", "L_m"), optional=(), one_of=(("k_W_mK", "material"),)),
    "planar": dict(cls=Planar, required=("A_m2", "length_m"), optional=(), one_of=(("k_W_mK", "material"),)),
    "interface": dict(cls=Interface, required=("h_W_m2K", "A_m2"), optional=(), one_of=()),
    "ball_race_contact": dict(cls=BallRaceContact, required=("contact",),
                              optional=("a_fallback_m", "b_fallback_m", "n_balls", "Q_fallback_N"),
                              one_of=(("k_ball_W_mK", "material_ball"), ("k_ring_W_mK", "material_ring"))),
    "convection": dict(cls=Convection, required=("correlation", "A_m2"),
                       optional=("u_m_s", "x_m", "oil_fraction", "fluid", "D_m", "L_m", "u_air_m_s", "h_W_m2K"),
                       one_of=()),
    "radiation": dict(cls=Radiation, required=("emissivity", "A_m2"), optional=(), one_of=()),
    "advection": dict(cls=Advection, required=("Q_m3_s", "beta"), optional=("rho_kg_m3", "cp_J_kgK"), one_of=()),
}

#: Keys each convection correlation needs (checked on load).
CORRELATION_KEYS = {
    "harris": ("u_m_s", "x_m"), "flat_plate_laminar": ("u_m_s", "x_m"),
    "natural_horizontal_cylinder": ("D_m",), "forced_cylinder": ("D_m", "u_air_m_s"),
    "forced_plate": ("L_m", "u_air_m_s"), "given": ("h_W_m2K",),
}

#: Keys that are strings, not numbers or expressions.
STRING_KEYS = {"contact": ("inner", "outer"), "correlation": CORRELATIONS, "fluid": ("oil_air", "oil", "air")}
MATERIAL_KEYS = ("material", "material_ball", "material_ring")
