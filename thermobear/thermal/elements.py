r"""Thermal elements: conductances between two nodes of a thermal network.

Pure functions (scalars or numpy arrays, broadcast) give the conductance
G [W/K] or the heat-transfer coefficient h [W/(m² K)] of each element family
(PHYSICS.md §8; Pouly et al. 2010; Brossier et al. 2021):

=========================  ==============================================  =======================
element                    model                                           function
=========================  ==============================================  =======================
radial conduction          G = 2π k L / ln(r2/r1)                          :func:`shell_conductance`
planar conduction          G = k A / ℓ                                     :func:`planar_conductance`
ball–race contact          R = 𝔎(e)/(2π k a) per body per contact          :func:`ball_race_conductance`
convection, Harris         h = C k Pr^⅓ (u/(ν x))^½, C = 0.0332            :func:`h_harris`
free convection, cylinder  Churchill–Chu (ChEDL ``ht``), air by CoolProp   :func:`h_natural_horizontal_cylinder`
forced convection          Churchill–Bernstein cylinder / flat plate       :func:`h_forced_cylinder`
radiation (linearised)     h = ε σ (T1²+T2²)(T1+T2)                        :func:`h_radiation`
oil advection (one-way)    G = ρ c_p Q̇ β                                   :func:`advection_conductance`
=========================  ==============================================  =======================

The classes at the end wrap these functions as network elements: each holds
its SI parameters (already evaluated from the network file) and returns its
conductance at the current node temperatures.  Only the element *families*
live here; which element joins which nodes is data (``networks/*.toml``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from thermobear.arrays import _within
from scipy.special import ellipk

from thermobear.lubrication.air import T_RANGE_K as _AIR_T_RANGE_K
from thermobear.lubrication.air import air_properties as _air_properties
from thermobear.errors import InputError
from thermobear.lubrication.lubricant import T_VALID_C as _T_VALID_C

__all__ = [
    "SIGMA_SB", "shell_conductance", "planar_conductance", "constriction_resistance",
    "ball_race_conductance", "h_harris", "HARRIS_COEFFICIENTS", "air_properties",
    "oil_air_properties", "h_natural_horizontal_cylinder", "h_forced_cylinder",
    "h_forced_plate", "h_radiation", "advection_conductance", "ELEMENT_TYPES",
]

SIGMA_SB = 5.670374419e-8   #: Stefan–Boltzmann constant [W/(m² K⁴)] (CODATA 2018, exact)

#: Named coefficients C of the convection law h = C k Pr^⅓ (u/(ν x))^½ (PHYSICS.md §8 item 4).
HARRIS_COEFFICIENTS = {
    "harris": 0.0332,               # Harris 2001 as quoted by PHYSICS.md §8 (unconfirmed - recalled)
    "flat_plate_laminar": 0.332,    # laminar flat plate, local Nusselt (Incropera), 10x larger
}


def _pos(name, v, strict=True):
    a = np.asarray(v, dtype=float)
    if a.size and not _within(a, 0.0, strict):
        raise InputError(name, v, "must be finite and " + ("> 0" if strict else ">= 0"))
    return a


def _out(x):
    return float(x) if np.ndim(x) == 0 else x


_FLOATS = (float, np.float64)


def _floats(*vs) -> bool:
    """True when every value is one Python (or numpy) float: the scalar fast paths below apply."""
    return all(type(v) in _FLOATS for v in vs)


def _all_pos(*vs) -> bool:
    """Floats all finite and > 0 (the check of :func:`_pos`)."""
    return all(0.0 < v < math.inf for v in vs)


# ---------------------------------------------------------------------------
# conduction
# ---------------------------------------------------------------------------
def shell_conductance(k, L, r1, r2):
    r"""Conductance of radial conduction through a cylindrical shell [W/K].

    Parameters
    ----------
    k : array_like    thermal conductivity [W/(m K)]
    L : array_like    axial length (ring width) [m]
    r1, r2 : array_like  inner and outer radius, 0 < r1 < r2 [m]

    Returns
    -------
    G = 2 π k L / ln(r2/r1)  [W/K]  (PHYSICS.md §8 item 1; Incropera eq 3.33).

    Examples
    --------
    >>> round(shell_conductance(42.7, 0.02, 0.025, 0.0286), 2)
    39.9
    """
    if _floats(k, L, r1, r2) and _all_pos(k, L, r1, r2) and r2 > r1:          # one element: no arrays
        return 2.0 * math.pi * k * L / math.log(r2 / r1)
    k, L, r1, r2 = (_pos(n, v) for n, v in (("k_W_mK", k), ("L_m", L), ("r1_m", r1), ("r2_m", r2)))
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
    G = k A / ℓ  [W/K]  (PHYSICS.md §8 item 2).

    Examples
    --------
    >>> planar_conductance(40.0, 1e-3, 0.1)
    0.4
    """
    if _floats(k, A, length) and _all_pos(k, A, length):                     # one element: no arrays
        return k * A / length
    k, A, length = _pos("k_W_mK", k), _pos("A_m2", A), _pos("length_m", length)
    return _out(k * A / length)


def constriction_resistance(k, a, b):
    r"""Constriction resistance of one body at an elliptical isothermal contact [K/W].

    Parameters
    ----------
    k : array_like    thermal conductivity of the body [W/(m K)]
    a, b : array_like semi-axes of the Hertz ellipse [m] (either order; the
                      larger one is the major semi-axis)

    Returns
    -------
    R = 𝔎(m) / (2 π k a_major), m = e² = 1 − (a_minor/a_major)²  [K/W]

    Notes
    -----
    Yovanovich / Muzychka (PHYSICS.md §8 item 3); 𝔎 is the complete elliptic
    integral of the first kind with *parameter* m = e² (``scipy.special.ellipk``,
    PHYSICS.md §12 pitfall 9).  For a circle 𝔎(0) = π/2 and R = 1/(4 k a).
    Stationary, isothermal contact: at Péclet numbers u b/(2κ) ≫ 1 the moving
    heat source lowers R (a ×2–5 uncertainty, not modelled).

    Examples
    --------
    >>> r = constriction_resistance(40.0, 1e-3, 1e-3)     # circle: 1/(4 k a)
    >>> round(r, 6), round(1 / (4 * 40.0 * 1e-3), 6)
    (6.25, 6.25)
    """
    k, a, b = _pos("k_W_mK", k), _pos("a_m", a), _pos("b_m", b)
    major, minor = np.maximum(a, b), np.minimum(a, b)
    m = 1.0 - (minor / major) ** 2
    return _out(ellipk(m) / (2.0 * np.pi * k * major))


def ball_race_conductance(k_ball, k_ring, a, b):
    r"""Total conductance of the ball–race contacts of one raceway [W/K].

    Parameters
    ----------
    k_ball, k_ring : float   conductivities of ball and ring [W/(m K)]
    a, b : array_like        per-ball Hertz semi-axes [m], shape (..., Z); a ball
                             with a = 0 or b = 0 is unloaded and conducts nothing

    Returns
    -------
    G = Σ_balls 1 / (R_ball + R_ring), R = 𝔎(e)/(2π k a) per body  [W/K]
    (PHYSICS.md §8 item 3: one constriction per body, bodies in series,
    contacts in parallel), summed over the last axis.

    Examples
    --------
    >>> G = ball_race_conductance(42.7, 42.7, [1e-3, 1e-3, 0.0], [2e-4, 2e-4, 0.0])
    >>> G1 = 1 / (2 * constriction_resistance(42.7, 1e-3, 2e-4))
    >>> round(G / G1, 12)
    2.0
    """
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    a, b = np.broadcast_arrays(a, b)
    if np.any(~np.isfinite(a) | ~np.isfinite(b) | (a < 0) | (b < 0)):
        raise InputError("contacts.a_m/b_m", a, "semi-axes must be finite and >= 0 [m]")
    loaded = (a > 0) & (b > 0)
    aa, bb = np.where(loaded, a, 1.0), np.where(loaded, b, 1.0)
    k_ball, k_ring = _pos("k_W_mK", k_ball), _pos("k_W_mK", k_ring)
    # constriction_resistance of each body; the ellipse (major axis, 𝔎(m)) is the same for both
    major, minor = np.maximum(aa, bb), np.minimum(aa, bb)
    Km = ellipk(1.0 - (minor / major) ** 2)
    R = Km / (2.0 * np.pi * k_ball * major) + Km / (2.0 * np.pi * k_ring * major)
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
    coefficient : str or float  ``"harris"`` (0.0332), ``"flat_plate_laminar"``
                      (0.332) or a number

    Returns
    -------
    h = C k Pr^⅓ (u / (ν x))^½  [W/(m² K)], i.e. Nu_x = C Re_x^½ Pr^⅓.

    Notes
    -----
    Harris 2001 as given in PHYSICS.md §8 item 4 (unconfirmed – recalled).  The
    (u/(ν x))^½ form is the dimensionally correct one (pitfall 11); Harris's
    0.0332 is 10× below laminar flat-plate theory (0.332, Incropera): which one
    Pouly 2010 used was not checked, so the coefficient is a named choice.

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
    k, Pr, nu, x = _pos("k_W_mK", k), _pos("Pr", Pr), _pos("nu_m2_s", nu), _pos("x_m", x)
    u = _pos("u_m_s", u, strict=False)
    return _out(C * k * np.cbrt(Pr) * np.sqrt(u / (nu * x)))


def air_properties(T_K, p_Pa=101325.0):
    r"""Dry-air properties (CoolProp, tabulated): see :func:`thermobear.lubrication.air.air_properties`.

    >>> p = air_properties(300.0)
    >>> round(p["rho"], 3), round(p["k"], 4), round(p["Pr"], 3)
    (1.177, 0.0264, 0.707)
    """
    return _air_properties(T_K, p_Pa)


def oil_air_properties(X, rho_oil, nu_oil_cSt, k_oil, cp_oil, T_K):
    r"""Properties of the oil–air mixture in the bearing cavity.

    Parameters
    ----------
    X : array_like           oil volume fraction, 0 ≤ X ≤ 1 [-]
    rho_oil : array_like     oil density [kg/m³]
    nu_oil_cSt : array_like  oil kinematic viscosity [mm²/s]
    k_oil, cp_oil : array_like  oil conductivity [W/(m K)] and specific heat [J/(kg K)]
    T_K : array_like         temperature (air properties) [K]

    Returns
    -------
    dict rho, mu, k, cp, nu, Pr of the mixture (SI).

    Notes
    -----
    Linear volume mixing of ρ, μ and k, mass-weighted c_p:
    ρ_e = Xρ_o + (1−X)ρ_a, μ_e = Xμ_o + (1−X)μ_a (PHYSICS.md §7.1, unconfirmed –
    textbook), k_e = Xk_o + (1−X)k_a (same rule, estimated).

    Examples
    --------
    >>> p = oil_air_properties(0.0, 860.0, 20.0, 0.13, 1950.0, 300.0)
    >>> round(p["k"], 4) == round(air_properties(300.0)["k"], 4)
    True
    """
    if _floats(X, rho_oil, nu_oil_cSt, k_oil, cp_oil, T_K) and 0.0 <= X <= 1.0:
        # one state (the thermal elements): the same arithmetic on Python floats
        air = _air_properties(T_K)
        mu_oil = nu_oil_cSt * 1e-6 * rho_oil
        rho = X * rho_oil + (1 - X) * air["rho"]
        mu = X * mu_oil + (1 - X) * air["mu"]
        k = X * k_oil + (1 - X) * air["k"]
        cp = (X * rho_oil * cp_oil + (1 - X) * air["rho"] * air["cp"]) / rho
        return dict(rho=rho, mu=mu, k=k, cp=cp, nu=mu / rho, Pr=mu * cp / k)
    X = np.asarray(X, dtype=float)
    if np.any(~np.isfinite(X) | (X < 0) | (X > 1)):
        raise InputError("oil_fraction", _out(X), "oil volume fraction must lie in [0, 1]")
    air = air_properties(T_K)
    mu_oil = np.asarray(nu_oil_cSt, dtype=float) * 1e-6 * rho_oil
    rho = X * rho_oil + (1 - X) * air["rho"]
    mu = X * mu_oil + (1 - X) * air["mu"]
    k = X * k_oil + (1 - X) * air["k"]
    cp = (X * rho_oil * cp_oil + (1 - X) * air["rho"] * air["cp"]) / rho
    return {key: _out(v) for key, v in dict(rho=rho, mu=mu, k=k, cp=cp, nu=mu / rho,
                                            Pr=mu * cp / k).items()}


def _film_air(T_s_K, T_inf_K):
    Tf = 0.5 * (np.asarray(T_s_K, float) + np.asarray(T_inf_K, float))
    from thermobear.lubrication.air import T_RANGE_K
    return Tf, air_properties(np.clip(Tf, *T_RANGE_K))   # properties held in the table's range


def h_natural_horizontal_cylinder(T_s_K, T_inf_K, D, method="Churchill-Chu"):
    r"""Free-convection coefficient of a horizontal cylinder in still air [W/(m² K)].

    Parameters
    ----------
    T_s_K, T_inf_K : float  surface and ambient temperature [K]
    D : float               cylinder diameter [m]
    method : str            correlation name passed to ``ht.Nu_horizontal_cylinder``

    Returns
    -------
    h = Nu_D k / D with Nu_D = [0.60 + 0.387 Ra^{1/6} / (1+(0.559/Pr)^{9/16})^{8/27}]²
    (Churchill & Chu 1975, via ChEDL ``ht``), air at the film temperature
    (CoolProp), Gr = g β |ΔT| D³/ν², β = 1/T_film (ideal gas).

    Examples
    --------
    >>> round(h_natural_horizontal_cylinder(330.0, 300.0, 0.15), 2)
    4.76
    """
    D = float(_pos("D_m", D))
    return _h_natural_cylinder(float(T_s_K), float(T_inf_K), D, method)


def _h_natural_cylinder(T_s_K: float, T_inf_K: float, D: float, method="Churchill-Chu") -> float:
    """:func:`h_natural_horizontal_cylinder` on checked floats (the network's fast path)."""
    import ht

    Tf = 0.5 * (T_s_K + T_inf_K)
    air = _air_properties(min(max(Tf, _AIR_T_RANGE_K[0]), _AIR_T_RANGE_K[1]))   # as _film_air
    dT = abs(T_s_K - T_inf_K)
    Gr = 9.80665 * (1.0 / Tf) * dT * D**3 / air["nu"] ** 2
    Nu = ht.Nu_horizontal_cylinder(Pr=air["Pr"], Gr=Gr, Method=method)
    return Nu * air["k"] / D


def h_forced_cylinder(u_inf, D, T_s_K, T_inf_K):
    r"""Forced-convection coefficient of a cylinder in cross-flow of air [W/(m² K)].

    Parameters
    ----------
    u_inf : float           free-stream air speed [m/s]
    D : float               cylinder diameter [m]
    T_s_K, T_inf_K : float  surface and air temperature [K] (film properties)

    Returns
    -------
    h = Nu_D k / D, Nu_D = 0.3 + 0.62 Re^½ Pr^⅓ / [1+(0.4/Pr)^⅔]^¼ [1+(Re/282000)^⅝]^⅘
    (Churchill & Bernstein 1977; ``ht.conv_external.Nu_cylinder_Churchill_Bernstein``),
    Re = u D/ν, air at the film temperature (CoolProp).

    Notes
    -----
    The specific ``ht`` function is called on purpose: in ht 1.2.0
    ``Nu_external_cylinder(..., Method="Churchill-Bernstein")`` dispatches to
    Sanitjai–Goldstein (14 % higher here).

    Examples
    --------
    >>> round(h_forced_cylinder(2.0, 0.1, 320.0, 300.0), 2)
    16.04
    """
    from ht.conv_external import Nu_cylinder_Churchill_Bernstein

    D, u = float(_pos("D_m", D)), float(_pos("u_air_m_s", u_inf))
    _, air = _film_air(T_s_K, T_inf_K)
    Nu = Nu_cylinder_Churchill_Bernstein(Re=u * D / air["nu"], Pr=air["Pr"])
    return Nu * air["k"] / D


def h_forced_plate(u_inf, L, T_s_K, T_inf_K):
    r"""Mean forced-convection coefficient of a flat plate in parallel air flow [W/(m² K)].

    Parameters
    ----------
    u_inf : float           free-stream air speed [m/s]
    L : float               plate length in the flow direction [m]
    T_s_K, T_inf_K : float  surface and air temperature [K] (film properties)

    Returns
    -------
    h = Nu_L k / L with ``ht.Nu_external_horizontal_plate`` (laminar Baehr,
    turbulent Schlichting, transition Re = 5e5), Re = u L/ν.

    Examples
    --------
    >>> round(h_forced_plate(2.0, 0.1, 320.0, 300.0), 2)    # laminar: 0.664 Re^½ Pr^⅓ k/L
    17.55
    """
    import ht

    L, u = float(_pos("L_m", L)), float(_pos("u_air_m_s", u_inf))
    _, air = _film_air(T_s_K, T_inf_K)
    Nu = ht.Nu_external_horizontal_plate(Re=u * L / air["nu"], Pr=air["Pr"], L=L)
    return Nu * air["k"] / L


def h_radiation(emissivity, T1_K, T2_K):
    r"""Linearised radiation coefficient of a small grey body in large surroundings [W/(m² K)].

    Parameters
    ----------
    emissivity : array_like  ε of the surface, 0 < ε ≤ 1 [-]
    T1_K, T2_K : array_like  surface and surroundings temperature [K]

    Returns
    -------
    h = ε σ (T1² + T2²)(T1 + T2), so that h (T1 − T2) = ε σ (T1⁴ − T2⁴) exactly
    (the secant form of PHYSICS.md §8 item 5's 4 ε σ T_m³; it is updated in
    the outer loop of the steady solver).

    Examples
    --------
    >>> h = h_radiation(0.8, 350.0, 300.0)
    >>> round(h * 50.0, 6) == round(0.8 * SIGMA_SB * (350.0**4 - 300.0**4), 6)
    True
    """
    eps = np.asarray(emissivity, dtype=float)
    if np.any(~np.isfinite(eps) | (eps <= 0) | (eps > 1)):
        raise InputError("emissivity", _out(eps), "must lie in (0, 1]")
    T1, T2 = _pos("T1_K", T1_K), _pos("T2_K", T2_K)
    return _out(eps * SIGMA_SB * (T1**2 + T2**2) * (T1 + T2))


def advection_conductance(rho, cp, Q, beta):
    r"""Advective conductance of the oil stream through the bearing [W/K].

    Parameters
    ----------
    rho : array_like   oil density [kg/m³]
    cp : array_like    oil specific heat [J/(kg K)]
    Q : array_like     supplied oil flow [m³/s]
    beta : array_like  penetration coefficient: fraction of Q passing through
                       the bearing, 0 < β ≤ 1 [-] (≈ 0.4, seed 004 §4.5 citing Brossier 2021)

    Returns
    -------
    G = ρ c_p Q β [W/K]; the heat carried away is Φ = G (T_mix − T_in)
    (PHYSICS.md §8 item 6).  A one-way (upwind) link: only the downstream
    node's balance contains it.

    Examples
    --------
    >>> round(advection_conductance(864.6, 1950.0, 10 / 3.6e6, 0.4), 4)
    1.8733
    """
    beta = np.asarray(beta, dtype=float)
    if np.any(~np.isfinite(beta) | (beta <= 0) | (beta > 1)):
        raise InputError("beta", _out(beta), "penetration coefficient must lie in (0, 1]")
    return _out(_pos("rho_kg_m3", rho) * _pos("cp_J_kgK", cp) * _pos("Q_m3_s", Q, strict=False) * beta)


# ---------------------------------------------------------------------------
# network elements (parameters already evaluated to SI by network.py)
# ---------------------------------------------------------------------------
@dataclass
class Element:
    """One element (edge) of a thermal network.

    Attributes
    ----------
    name : str            unique element name
    type : str            element family (key of ``ELEMENT_TYPES``)
    nodes : tuple         (node_0, node_1); for ``advection`` (upstream, downstream)
    i, j : int            node indices
    p : dict              evaluated parameters (SI, keys as in the network file)
    context : object      lubricant etc. for temperature-dependent properties
    """

    name: str
    type: str
    nodes: tuple
    i: int
    j: int
    p: dict
    context: dict = field(default_factory=dict, repr=False)
    advective = False           #: one-way link (upwind), not a symmetric conductance
    T_dependent = False         #: conductance depends on node temperatures

    def conductance(self, T_K) -> float:
        """Conductance [W/K] at node temperatures ``T_K`` (array over all nodes); each element type
        (the subclasses in ``ELEMENT_TYPES``) defines it."""
        raise TypeError(f"{type(self).__name__} is an element base class: it has no conductance of its own")

    def _T_nodes(self) -> tuple:
        """Indices of the nodes whose temperatures the conductance depends on (both by default)."""
        return (self.i, self.j) if self.T_dependent else ()

    def _conductance_shared(self, T_K, shared: dict) -> float:
        """:meth:`conductance`, with fluid properties shared between elements through ``shared``
        (a dict the caller keeps for one temperature state; the network solvers' fast path)."""
        return self.conductance(T_K)

    def _memo(self, compute):
        """``compute()`` (the conductance of a temperature-independent element) memoised on the
        element's parameter values: the network's load check and the solver's plan both evaluate
        it, for every operating point."""
        key = tuple((k, (v.shape, v.tobytes()) if isinstance(v, np.ndarray) else v) for k, v in self.p.items())
        hit = self.__dict__.get("_tb_G")
        if hit is not None and hit[0] == key:
            return hit[1]
        G = compute()
        self.__dict__["_tb_G"] = (key, G)
        return G


def _k(p, key="k_W_mK", mat="material"):
    return p[key] if key in p else p[mat].k


class Conductance(Element):
    """A given conductance ``G_W_K`` or resistance ``R_K_W``."""

    def conductance(self, T_K):
        return float(self.p["G_W_K"]) if "G_W_K" in self.p else 1.0 / float(self.p["R_K_W"])


class Shell(Element):
    """Radial conduction through a cylindrical shell (``shell_conductance``)."""

    def conductance(self, T_K):
        return self._memo(lambda: shell_conductance(_k(self.p), self.p["L_m"], self.p["r1_m"], self.p["r2_m"]))


class Planar(Element):
    """Planar / axial conduction (``planar_conductance``)."""

    def conductance(self, T_K):
        return self._memo(lambda: planar_conductance(_k(self.p), self.p["A_m2"], self.p["length_m"]))


class Interface(Element):
    """Thermal contact conductance of a fitted or clamped joint: G = h_c A."""

    def conductance(self, T_K):
        h, A = self.p["h_W_m2K"], self.p["A_m2"]
        if _floats(h, A) and _all_pos(h, A):
            return h * A
        return float(_pos("h_W_m2K", h) * _pos("A_m2", A))


class BallRaceContact(Element):
    """Ball–race Hertz contacts of one raceway, balls in parallel (``ball_race_conductance``).

    The per-ball semi-axes come from the mechanics through the context keys
    ``contacts.<inner|outer>.a_m`` and ``.b_m`` (arrays over the balls); when
    absent, the fallback ``a_fallback_m``/``b_fallback_m`` for ``n_balls``
    identical balls is used (network.py resolves this at build time and
    records which one was used in ``p["semi_axes_from"]``).
    """

    def conductance(self, T_K):
        kb = self.p["k_ball_W_mK"] if "k_ball_W_mK" in self.p else self.p["material_ball"].k
        kr = self.p["k_ring_W_mK"] if "k_ring_W_mK" in self.p else self.p["material_ring"].k
        return self._memo(lambda: ball_race_conductance(kb, kr, self.p["a_m"], self.p["b_m"]))


class Convection(Element):
    """Convection from a surface (node 0) to a fluid (node 1) with a NAMED correlation.

    ``correlation``: ``harris`` / ``flat_plate_laminar`` (oil–air mixture, needs
    ``u_m_s``, ``x_m``, ``oil_fraction`` and the lubricant ``oil`` in the
    context), ``natural_horizontal_cylinder`` (``D_m``), ``forced_cylinder``
    (``D_m``, ``u_air_m_s``), ``forced_plate`` (``L_m``, ``u_air_m_s``),
    ``given`` (``h_W_m2K``).  Always ``A_m2``.
    """

    @property
    def T_dependent(self):
        return self.p["correlation"] != "given"

    def _T_nodes(self) -> tuple:
        c = self.p["correlation"]
        return () if c == "given" else (self.j,) if c in HARRIS_COEFFICIENTS else (self.i, self.j)

    def _harris_props(self, Tf, shared=None) -> dict:
        """Properties of the fluid (node 1, at ``Tf`` [K]) for the harris-type laws; ``shared``
        caches them per (lubricant, fluid, oil fraction, temperature)."""
        p = self.p
        fluid = p.get("fluid", "oil_air")
        oil = self.context.get("oil") if fluid != "air" else None
        X = 0.0 if fluid == "air" else 1.0 if fluid == "oil" else p["oil_fraction"]
        key = ("harris", id(oil), fluid, X, Tf)
        if shared is not None and key in shared:
            return shared[key]
        if fluid == "air":
            props = air_properties(_air_T(Tf))
        else:
            T_C = _oil_T(Tf)
            props = oil_air_properties(X, oil.rho(T_C), oil.nu(T_C), oil.k_th(T_C), oil.cp(T_C), T_C + 273.15)
        if shared is not None:
            shared[key] = props
        return props

    def h(self, T_K) -> float:
        """Heat-transfer coefficient [W/(m² K)] at the current temperatures."""
        return self._h(T_K, None)

    def _h(self, T_K, _shared) -> float:
        p, c = self.p, self.p["correlation"]
        Ts, Tf = float(T_K[self.i]), float(T_K[self.j])
        if c == "given":
            return float(p["h_W_m2K"])
        if c in HARRIS_COEFFICIENTS:
            props = self._harris_props(Tf, _shared)
            if _shared is not None:        # parameters checked at load, properties from the tables: no re-check
                return (HARRIS_COEFFICIENTS[c] * props["k"] * math.cbrt(props["Pr"])
                        * math.sqrt(p["u_m_s"] / (props["nu"] * p["x_m"])))
            return h_harris(props["k"], props["Pr"], p["u_m_s"], props["nu"], p["x_m"], c)
        if c == "natural_horizontal_cylinder":
            if _shared is not None:        # D_m checked at load
                return _h_natural_cylinder(Ts, Tf, float(p["D_m"]))
            return h_natural_horizontal_cylinder(Ts, Tf, p["D_m"])
        if c == "forced_cylinder":
            return h_forced_cylinder(p["u_air_m_s"], p["D_m"], Ts, Tf)
        if c == "forced_plate":
            return h_forced_plate(p["u_air_m_s"], p["L_m"], Ts, Tf)
        raise InputError(f"elements[{self.name}].correlation", c, f"one of {CORRELATIONS}")

    def conductance(self, T_K):
        # the keys were checked on load (network.py: units, correlation names), the fluid properties
        # come from the tables: the fast path, without re-checking them
        return self._h(T_K, {}) * float(self.p["A_m2"])

    def _conductance_shared(self, T_K, shared):
        return self._h(T_K, shared) * float(self.p["A_m2"])


def _air_T(T_K: float) -> float:
    """Temperature [K] for the air table, held inside 200–600 K (see :func:`_oil_T`)."""
    return min(max(float(T_K), _AIR_T_RANGE_K[0]), _AIR_T_RANGE_K[1])


def _oil_T(T_K: float) -> float:
    """Temperature [°C] for the oil's property correlations, held inside their validity: an iterate of
    the coupled solve may overshoot transiently; an equilibrium beyond the limit is reported as runaway
    by the solver, not as an error from a property call."""
    return min(max(T_K - 273.15, _T_VALID_C[0]), _T_VALID_C[1])


class Radiation(Element):
    """Linearised radiation from node 0 (surface, ``A_m2``, ``emissivity``) to node 1."""

    T_dependent = True

    def conductance(self, T_K):
        eps, T1, T2 = self.p["emissivity"], float(T_K[self.i]), float(T_K[self.j])
        if not (_floats(eps) and 0.0 < eps <= 1.0 and T1 > 0.0 and T2 > 0.0 and T1 < math.inf and T2 < math.inf):
            # the checks of h_radiation and their errors
            return h_radiation(self.p["emissivity"], T_K[self.i], T_K[self.j]) * float(self.p["A_m2"])
        return eps * SIGMA_SB * (T1 * T1 + T2 * T2) * (T1 + T2) * float(self.p["A_m2"])   # h_radiation

    def _conductance_shared(self, T_K, shared):
        return self.conductance(T_K)


class Advection(Element):
    """One-way oil stream from node 0 (upstream, e.g. fixed oil inlet) through node 1.

    G = ρ c_p Q̇ β, with ρ, c_p given (``rho_kg_m3``, ``cp_J_kgK``) or taken from
    the context lubricant ``oil`` at the upstream temperature.
    """

    advective = True

    @property
    def T_dependent(self):
        return not ("rho_kg_m3" in self.p and "cp_J_kgK" in self.p)

    def _T_nodes(self) -> tuple:
        return (self.i,) if self.T_dependent else ()

    def conductance(self, T_K):
        p = self.p
        if "rho_kg_m3" in p and "cp_J_kgK" in p:
            rho, cp = p["rho_kg_m3"], p["cp_J_kgK"]
        else:
            T_C = _oil_T(float(T_K[self.i]))
            oil = self.context["oil"]
            rho = p["rho_kg_m3"] if "rho_kg_m3" in p else oil.rho(T_C)
            cp = p["cp_J_kgK"] if "cp_J_kgK" in p else oil.cp(T_C)
        Q, beta = p["Q_m3_s"], p["beta"]
        if not (_floats(rho, cp, Q, beta) and rho > 0.0 and cp > 0.0 and 0.0 < beta <= 1.0
                and Q >= 0.0 and rho * cp * Q < math.inf):
            return advection_conductance(rho, cp, Q, beta)              # the checks and their errors
        return rho * cp * Q * beta                                      # advection_conductance


CORRELATIONS = ("harris", "flat_plate_laminar", "natural_horizontal_cylinder",
                "forced_cylinder", "forced_plate", "given")

#: Element families: class, required keys, optional keys, "one of" groups.
#: Numeric keys carry their unit in the name (``_m``, ``_m2``, ``_W_mK`` ...);
#: dimensionless ones (beta, emissivity, oil_fraction, n_balls) are listed as such.
ELEMENT_TYPES = {
    "conductance": dict(cls=Conductance, required=(), optional=(), one_of=(("G_W_K", "R_K_W"),)),
    "shell": dict(cls=Shell, required=("r1_m", "r2_m", "L_m"), optional=(),
                  one_of=(("k_W_mK", "material"),)),
    "planar": dict(cls=Planar, required=("A_m2", "length_m"), optional=(),
                   one_of=(("k_W_mK", "material"),)),
    "interface": dict(cls=Interface, required=("h_W_m2K", "A_m2"), optional=(), one_of=()),
    "ball_race_contact": dict(cls=BallRaceContact, required=("contact",),
                              optional=("a_fallback_m", "b_fallback_m", "n_balls"),
                              one_of=(("k_ball_W_mK", "material_ball"),
                                      ("k_ring_W_mK", "material_ring"))),
    "convection": dict(cls=Convection, required=("correlation", "A_m2"),
                       optional=("u_m_s", "x_m", "oil_fraction", "fluid", "D_m", "L_m",
                                 "u_air_m_s", "h_W_m2K"), one_of=()),
    "radiation": dict(cls=Radiation, required=("emissivity", "A_m2"), optional=(), one_of=()),
    "advection": dict(cls=Advection, required=("Q_m3_s", "beta"),
                      optional=("rho_kg_m3", "cp_J_kgK"), one_of=()),
}

#: Keys each convection correlation needs (checked on load).
CORRELATION_KEYS = {
    "harris": ("u_m_s", "x_m"), "flat_plate_laminar": ("u_m_s", "x_m"),
    "natural_horizontal_cylinder": ("D_m",), "forced_cylinder": ("D_m", "u_air_m_s"),
    "forced_plate": ("L_m", "u_air_m_s"), "given": ("h_W_m2K",),
}

#: Keys that are strings, not numbers or expressions.
STRING_KEYS = {"contact": ("inner", "outer"), "correlation": CORRELATIONS,
               "fluid": ("oil_air", "oil", "air")}
MATERIAL_KEYS = ("material", "material_ball", "material_ring")

