r"""Thermal elements: the edges of a thermal network, each a conductance between two nodes.

Each element family wraps a physics function of :mod:`thermobear.thermal.conduction` (shells,
plane walls, ball–race constrictions, joints) or :mod:`thermobear.thermal.convection` (convection,
radiation, advection); those functions are re-exported here.  An element holds its SI parameters —
numbers, or arrays over a batch of operating points — and returns its conductance at the node
temperatures of every operating point at once.  Which element joins which nodes is data
(``networks/*.toml``, or a network built by :mod:`thermobear.thermal.builders`).

=================  ==========================================================================================
``type``           conductance
=================  ==========================================================================================
``conductance``    given ``G_W_K`` or ``R_K_W``
``shell``          :func:`~thermobear.thermal.conduction.shell_conductance`
``planar``         :func:`~thermobear.thermal.conduction.planar_conductance`
``interface``      h A (a fitted or clamped joint, ``h_W_m2K`` e.g. from
                   :func:`~thermobear.thermal.conduction.joint_conductance`)
``ball_race_contact``  :func:`~thermobear.thermal.conduction.ball_race_conductance`
``convection``     h A with a NAMED ``correlation`` (:data:`CORRELATIONS`)
``radiation``      :func:`~thermobear.thermal.convection.h_radiation` A
``advection``      :func:`~thermobear.thermal.convection.advection_conductance` (one-way)
=================  ==========================================================================================
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from thermobear.arrays import checked
from thermobear.lubrication.air import T_RANGE_K as AIR_T_RANGE_K
from thermobear.lubrication.air import air_properties
from thermobear.lubrication.film import film_thickness
from thermobear.thermal.conduction import (ball_race_conductance, constriction_resistance, meniscus_conductance,  # noqa: F401
                                           thermal_effusivity,
                                           planar_conductance, shell_conductance)
from thermobear.thermal.convection import (HARRIS_COEFFICIENTS, SIGMA_SB, advection_conductance,  # noqa: F401
                                           air_film_properties, h_forced_cylinder, h_forced_plate,
                                           h_free_horizontal_plate, h_free_vertical_plate, h_harris,
                                           h_natural_horizontal_cylinder, h_radiation, h_rotating_cylinder,
                                           mixed_convection, oil_air_properties)
from thermobear.units import ZERO_C_K
from thermobear.validity import T_LUBRICANT_REFUSE_C

__all__ = [
    "SIGMA_SB", "shell_conductance", "planar_conductance", "constriction_resistance",
    "ball_race_conductance", "h_harris", "HARRIS_COEFFICIENTS", "oil_air_properties",
    "h_natural_horizontal_cylinder", "h_forced_cylinder", "h_forced_plate", "h_radiation",
    "advection_conductance", "Element", "ELEMENT_TYPES", "CORRELATIONS", "CORRELATION_KEYS",
    "STRING_KEYS", "MATERIAL_KEYS",
]

# ---------------------------------------------------------------------------
# network elements: parameters in SI (numbers or arrays over the operating points)
# ---------------------------------------------------------------------------
def _oil_T(T_K):
    """Temperature [°C] for the oil's property correlations, held inside their accepted range: an
    iterate of a coupled solve may overshoot transiently; an equilibrium beyond the limit is
    reported as runaway by the solver, not as an error from a property call."""
    return np.clip(np.asarray(T_K, float) - ZERO_C_K, *T_LUBRICANT_REFUSE_C)


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

    ``exchange = "rolling"``: the surfaces' exchange as they roll through the contacts at the
    contacts' entrainment speeds (``contacts.<side>.u_m_s``; the materials' k, ρ, c_p), through the
    lubricant's central film (Hamrock–Dowson, :func:`~thermobear.lubrication.film.film_thickness`, at
    the mean of the two nodes' temperatures and the contacts' loads and radii), and with ``h_meniscus_m``
    the conduction through the lubricant filling the gap around each loaded contact out to that gap
    (:func:`~thermobear.thermal.conduction.meniscus_conductance`) — with the mechanics' contacts only;
    the fallback contacts are stationary.  Default ``"stationary"``.
    """

    def depends_on(self):
        return (self.i, self.j) if self.p.get("exchange") == "rolling" else ()    # the film at the nodes' mean

    def conductance(self, Ti, Tj, oil=None, shared=None):
        p = self.p
        kb = p["k_ball_W_mK"] if "k_ball_W_mK" in p else p["material_ball"].k
        kr = p["k_ring_W_mK"] if "k_ring_W_mK" in p else p["material_ring"].k
        if "u_m" not in p:
            return ball_race_conductance(kb, kr, p["a_m"], p["b_m"])
        mb, mr = p["material_ball"], p["material_ring"]
        film = {}
        if oil is not None and "Q_N" in p:
            T_C = _oil_T(0.5 * (np.asarray(Ti, float) + np.asarray(Tj, float)))     # (B,): a per-point oil's axis
            Q = p["Q_N"]
            run = (Q > 0) & (p["u_m"] > 0)
            h = film_thickness(np.where(run, Q, 1.0), p["Rx_m"], p["Ry_m"], np.where(run, p["u_m"], 1.0),
                               oil.eta(T_C)[..., None], oil.alpha_p_at(T_C)[..., None], p["E_prime"], kind="central")
            film = dict(h_film=np.where(run, h, 0.0), k_film=np.asarray(oil.k_th(T_C), float)[..., None])
        G = ball_race_conductance(kb, kr, p["a_m"], p["b_m"], u=p["u_m"], e_ball=thermal_effusivity(kb, mb.rho, mb.cp),
                                  e_ring=thermal_effusivity(kr, mr.rho, mr.cp), **film)
        if film and "h_meniscus_m" in p:
            Gm = meniscus_conductance(film["k_film"], p["Rx_m"], p["Ry_m"], np.where(run, h, 1.0), p["h_meniscus_m"])
            G = G + np.sum(np.where(run & (p["a_m"] > 0), Gm, 0.0), axis=-1)
        return G


class Convection(Element):
    """Convection from a surface (node 0) to a fluid (node 1) with a NAMED correlation.

    ``correlation``: ``harris`` / ``flat_plate_laminar`` (oil–air mixture, needs ``u_m_s``,
    ``x_m``, ``oil_fraction`` and the lubricant), ``natural_horizontal_cylinder`` (``D_m``),
    ``forced_cylinder`` (``D_m``, ``u_air_m_s``), ``forced_plate`` (``L_m``, ``u_air_m_s``),
    ``plate_vertical`` (``L_m`` the height), ``plate_up`` / ``plate_down`` (``L_m`` = area /
    perimeter; the top face / the underside of a body) — free convection, mixed (n = 3) with a
    forced flow along the plate when ``u_air_m_s`` is given (flow length ``x_m``, default ``L_m``),
    in air or, with ``fluid = "oil"``, in the lubricant — ``rotating_cylinder`` (``D_m``,
    ``omega_rad_s``: rotation, free convection and an optional cross flow ``u_air_m_s`` mixed,
    n = 3), ``given`` (``h_W_m2K``).  Always ``A_m2``.
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
            props = oil_air_properties(X, oil.rho(T_C), oil.nu(T_C), oil.k_th(T_C), oil.cp(T_C), T_C + ZERO_C_K)
        if shared is not None:
            shared[key] = props
        return props

    def _free_fluid(self, Ti, Tj, oil):
        """Film properties for the free-convection laws (None: air)."""
        if self.p.get("fluid", "air") != "oil":
            return None
        Tf = 0.5 * (np.asarray(Ti, float) + np.asarray(Tj, float))
        T_C = _oil_T(Tf)
        rho, cp, k = oil.rho(T_C), oil.cp(T_C), oil.k_th(T_C)
        nu = oil.nu(T_C) * 1e-6
        lo, hi = np.maximum(T_C - 1.0, T_LUBRICANT_REFUSE_C[0]), np.minimum(T_C + 1.0, T_LUBRICANT_REFUSE_C[1])
        beta = (oil.rho(lo) - oil.rho(hi)) / ((hi - lo) * rho)      # −(1/ρ) dρ/dT, ±1 K inside the oil's range
        return {"k": k, "nu": nu, "Pr": nu * rho * cp / k, "beta": beta}

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
        if c == "forced_plate":
            return h_forced_plate(p["u_air_m_s"], p["L_m"], Ti, Tj)
        if c == "rotating_cylinder":
            h = mixed_convection(h_rotating_cylinder(p["omega_rad_s"], p["D_m"], Ti, Tj),
                                 h_natural_horizontal_cylinder(Ti, Tj, p["D_m"]))
            return mixed_convection(h, h_forced_cylinder(p["u_air_m_s"], p["D_m"], Ti, Tj)) if "u_air_m_s" in p else h
        fluid = self._free_fluid(Ti, Tj, oil)
        h = (h_free_vertical_plate(Ti, Tj, p["L_m"], fluid) if c == "plate_vertical" else
             h_free_horizontal_plate(Ti, Tj, p["L_m"], "up" if c == "plate_up" else "down", fluid))
        if "u_air_m_s" in p:
            h = mixed_convection(h_forced_plate(p["u_air_m_s"], p.get("x_m", p["L_m"]), Ti, Tj), h)
        return h

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
                "forced_plate", "plate_vertical", "plate_up", "plate_down", "rotating_cylinder", "given")

#: Element families: class, required keys, optional keys, "one of" groups.  Numeric keys carry
#: their unit in the name (``_m``, ``_m2``, ``_W_mK`` ...); dimensionless ones (beta, emissivity,
#: oil_fraction, n_balls) are listed as such.
ELEMENT_TYPES = {
    "conductance": dict(cls=Conductance, required=(), optional=(), one_of=(("G_W_K", "R_K_W"),)),
    "shell": dict(cls=Shell, required=("r1_m", "r2_m", "L_m"), optional=(), one_of=(("k_W_mK", "material"),)),
    "planar": dict(cls=Planar, required=("A_m2", "length_m"), optional=(), one_of=(("k_W_mK", "material"),)),
    "interface": dict(cls=Interface, required=("h_W_m2K", "A_m2"), optional=(), one_of=()),
    "ball_race_contact": dict(cls=BallRaceContact, required=("contact",),
                              optional=("a_fallback_m", "b_fallback_m", "n_balls", "Q_fallback_N", "exchange",
                                        "h_meniscus_m"),
                              one_of=(("k_ball_W_mK", "material_ball"), ("k_ring_W_mK", "material_ring"))),
    "convection": dict(cls=Convection, required=("correlation", "A_m2"),
                       optional=("u_m_s", "x_m", "oil_fraction", "fluid", "D_m", "L_m", "u_air_m_s", "h_W_m2K",
                                 "omega_rad_s"),
                       one_of=()),
    "radiation": dict(cls=Radiation, required=("emissivity", "A_m2"), optional=(), one_of=()),
    "advection": dict(cls=Advection, required=("Q_m3_s", "beta"), optional=("rho_kg_m3", "cp_J_kgK"), one_of=()),
}

#: Keys each convection correlation needs (checked on load).
CORRELATION_KEYS = {
    "harris": ("u_m_s", "x_m"), "flat_plate_laminar": ("u_m_s", "x_m"),
    "natural_horizontal_cylinder": ("D_m",), "forced_cylinder": ("D_m", "u_air_m_s"),
    "forced_plate": ("L_m", "u_air_m_s"), "given": ("h_W_m2K",), "plate_vertical": ("L_m",),
    "plate_up": ("L_m",), "plate_down": ("L_m",), "rotating_cylinder": ("D_m", "omega_rad_s"),
}

#: Keys that are strings, not numbers or expressions.
STRING_KEYS = {"contact": ("inner", "outer"), "correlation": CORRELATIONS, "fluid": ("oil_air", "oil", "air"),
               "exchange": ("stationary", "rolling")}
MATERIAL_KEYS = ("material", "material_ball", "material_ring")
