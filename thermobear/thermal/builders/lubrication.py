r"""Lubrication in the network: the cavity's mixture, the oil supplied and drained, a bath, grease.

* The mixture node ``oil_air`` (every supply): its capacity is the bearing's free volume of air
  with 5 % of it held as oil films and droplets (estimated: the hand-written seed-004 network's 2 g
  of oil in a 7210), or with the grease fill; the races and balls exchange with it by the laminar
  flat plate (:mod:`~thermobear.thermal.builders.bearing`) in the oil–air mixture of the operating
  point (``op.oil_fraction``: Parker's for jets and oil–air) or, for grease and dry films, in air.
* Oil jet: one-way advection from the inlet (``scene.T_oil_in_C``) through the mixture of the
  penetrating share β of the flow (0.4, Brossier et al. 2021, as seed 004 §4.5 uses; the rest
  splashes off and is not modelled).  Circulating oil: all of it (β = 1) passes through the
  bearing and drains at the mixture's temperature.
* Oil–air (and oil mist): the oil (β = 1) and the carrier air (its volume flow at the inlet,
  ρ c_p of air at the inlet temperature) both pass through the mixture.
* Oil bath: a node ``oil_sump`` for the bath.  The level H (SKF's: above the lowest point of the
  outer-ring raceway; default D/2, the middle of the lowest ball — SKF's recommendation for an
  oil bath at rest) immerses the share f(r) = arccos(−y/r)/π of each circle of radius r turning
  through it (y = H − (dm + D)/2, the level relative to the axis; for the balls the circle a quarter
  diameter outside their pitch circle, the mean of their lower halves, estimated): that share of the
  races' and balls' areas exchanges with the sump in oil, the rest with the mixture.  The mixture and the
  bath mix as the balls carry their immersed share of the free volume around at the cage's
  speed, G = ρ c_p f_b V_free ω_c/(2π) (estimated), with conduction through the oil as a floor.
  The bath wets the housing's bore below the level beside the bearing: free convection of a
  vertical plate in oil (Churchill–Chu; a lower bound — the bearing stirs the bath).  Without a
  given volume the bath is the oil in the housing's bore below the level beside the bearing plus the
  bearing's immersed free volume; a given volume of a separate reservoir wets 5 V^⅔ (an open cube).
  A flow (``flow_L_h``, none by default) circulates through the bath: advection from the inlet
  into the sump.
* Grease: the fill (default 30 % of the free volume) bridges the races and the mixture: plane-wall
  conduction through the grease (the lubricant's conductivity) over the fill's share of the pitch
  cylinder, half a ball diameter thick each side (estimated).
"""
from __future__ import annotations

import math

import numpy as np

from thermobear.errors import InputError
from thermobear.lubrication.air import air_properties
from thermobear.thermal.builders import estimates
from thermobear.thermal.builders.axisym import Body
from thermobear.thermal.builders.bearing import free_volume
from thermobear.thermal.builders.layout import Layout
from thermobear.thermal.builders.machine import Machine
from thermobear.thermal.builders.spec import NetworkSpec

__all__ = ["add_mixture", "add_supply", "immersed_share", "BETA_JET"]

BETA_JET = 0.4       #: penetrating share of an oil jet (Brossier et al. 2021; seed 004 §4.5)
# estimated (materials/network_builders.toml, with their ranges): oil_held, the share of the free volume
# held as oil in a lubricated cavity; grease_fill, the grease fill of the free volume (usual fills 20–40 %)
RHO_CP_AIR = 1.1 * 1007.0    #: air near 50 °C [J/(m³ K)] (materials/air_1atm.toml)


def immersed_share(level_y: float, r: float) -> float:
    r"""Share of a circle of radius r (centre on the axis) below a level at height y [-].

    .. math:: f = \frac{1}{\pi}\arccos\left(\mathrm{clip}(-y/r, -1, 1)\right)

    >>> immersed_share(-1.0, 1.0), immersed_share(0.0, 1.0), immersed_share(2.0, 1.0)
    (0.0, 0.5, 1.0)
    """
    return float(np.arccos(np.clip(-level_y / r, -1.0, 1.0)) / math.pi)


def _level(m: Machine, lay: Layout) -> float:
    H = m.lubrication.oil_level
    if H is None:
        raise InputError("lubricant.oil_level_mm", None, "an oil bath in a parametric housing needs its level above "
                         f"the outer raceway's lowest point (SKF's static level, the lowest ball's centre: D/2 = "
                         f"{lay.D / 2 * 1e3:.3g} mm)")
    if H <= 0:
        raise InputError("lubricant.oil_level_mm", H * 1e3, "an oil bath needs a level above the outer raceway's "
                         "lowest point (> 0)")
    H_max = lay.R_seat + (lay.dm + lay.D) / 2       # the bath fills the housing's bore
    if H > H_max:
        raise InputError("lubricant.oil_level_mm", H * 1e3, f"at most {H_max * 1e3:.4g} mm: there the bath fills the "
                         f"housing's bore ({2 * lay.R_seat * 1e3:.4g} mm across); SKF's static level is the lowest "
                         f"ball's centre, D/2 = {lay.D / 2 * 1e3:.3g} mm")
    return H - (lay.dm + lay.D) / 2


def add_mixture(spec: NetworkSpec, m: Machine, lay: Layout):
    """The mixture node (and the bath's): returns (fluid keys of the internal convection, sump or None)
    with sump = (node, {race or balls node: immersed share})."""
    lub, V = m.lubrication, free_volume(lay)
    if lub.supply == "grease":
        fill = lub.grease_fill if lub.grease_fill is not None else estimates.value(m, "grease_fill")
        C, what = V * (fill * lub.rho_cp + (1 - fill) * RHO_CP_AIR), f"grease ({fill:.0%} of the free volume) and air"
    else:
        held = estimates.value(m, "oil_held")
        C, what = V * (held * lub.rho_cp + (1 - held) * RHO_CP_AIR), "air and the oil held in the cavity"
    if lub.oil_air_C_J_K is not None:
        C, what = lub.oil_air_C_J_K, "given"
    spec.node("oil_air", C_J_K=C, estimated=["C_J_K"], description=f"the bearing cavity's mixture: {what}")
    fluid = ({"fluid": "air"} if lub.supply in ("grease", "dry_film") else
             {"fluid": "oil_air", "oil_fraction": "op.oil_fraction"})
    if lub.supply != "oil_bath":
        return fluid, None
    y = _level(m, lay)
    thrust = m.bearing.kind == "thrust"
    shares = {("shaft_washer" if thrust else "inner_race"): immersed_share(y, (lay.dm - lay.D) / 2),
              "balls": immersed_share(y, lay.dm / 2 + lay.D / 4),
              ("housing_washer" if thrust else "outer_race"): immersed_share(y, (lay.dm + lay.D) / 2)}
    V_sump, _ = _sump_volume(m, lay, y)
    spec.node("oil_sump", C_J_K=V_sump * lub.rho_cp, estimated=["C_J_K"],
              uncertainty=estimates.point_uncertainty("sump_capacity") if lub.sump_volume is None else None,
              description=f"the oil bath: {V_sump * 1e3:.3g} L, level {(y + (lay.dm + lay.D) / 2) * 1e3:.3g} mm above "
                          "the outer raceway's lowest point")
    return fluid, ("oil_sump", shares)


def _sump_volume(m: Machine, lay: Layout, y: float) -> tuple:
    """(volume [m³], wetted area of the housing [m²]) of the bath."""
    R = lay.R_seat
    depth = max(y + R, 0.0)                         # oil depth in the housing's bore
    seg = 0.0 if depth <= 0 else R**2 * math.acos((R - depth) / R) - (R - depth) * math.sqrt(max(2 * R * depth - depth**2, 0.0))
    arc = 0.0 if depth <= 0 else 2 * R * math.acos((R - depth) / R)
    overhang = lay.L_h - lay.B
    V_def = seg * overhang + immersed_share(y, lay.dm / 2) * free_volume(lay)
    if m.lubrication.sump_volume is None:
        return V_def, arc * overhang
    V = m.lubrication.sump_volume
    return V, 5.0 * V ** (2.0 / 3.0)


def _bath(spec, m, lay, housing: Body, sump):
    lub, y = m.lubrication, _level(m, lay)
    node, shares = sump
    V = free_volume(lay)
    f_b = max(shares.values())                 # the outer race dips as soon as there is a level
    floor = lub.k * f_b * math.pi * lay.dm * lay.B / (lay.D / 2)
    spec.element("oil_air--oil_sump", "conductance", ("oil_air", node), estimated=["G_W_K"],
                 uncertainty=estimates.point_uncertainty("bath_mixing"),
                 G_W_K=f"{lub.rho_cp * f_b * V / (2 * math.pi)!r} * abs(op.omega_cage_rad_s) + {floor!r}",
                 description="the balls carry their immersed share of the free volume around at the cage's speed "
                             "(estimated); conduction through the oil as the floor")
    _, A_w = _sump_volume(m, lay, y)
    depth = max(y + lay.R_seat, 1e-3)
    cells = (housing.face("inner", (lay.z_h0, -lay.B / 2)) + housing.face("inner", (lay.B / 2, lay.z_h1))) or \
        housing.face("inner", (-lay.B / 2, lay.B / 2))
    L = sum(z1 - z0 for _, z0, z1 in cells)
    if A_w > 0:
        for cell, z0, z1 in cells:
            name = spec.element(f"{cell.name}--{node}", "convection", (cell.name, node), correlation="plate_vertical",
                                fluid="oil", L_m=depth, A_m2=A_w * (z1 - z0) / L,
                                description="the bath on the housing's wetted wall: free convection in oil "
                                            "(a lower bound: the bearing stirs the bath)")
            spec.surface(element=name, body="housing", face="inner", r=(cell.r0, cell.r0), z=(z0, z1), to=node,
                         kind="convection")
    spec.fixed("oil_inlet", "scene.T_oil_in_C", description="oil supply (inlet temperature; ambient if not given)")
    spec.element("oil_stream", "advection", ("oil_inlet", node), Q_m3_s="scene.oil_flow_m3_s", beta=1.0,
                 description="oil circulated through the bath (flow_L_h; none by default), drained at the bath's "
                             "temperature")


def add_supply(spec: NetworkSpec, m: Machine, lay: Layout, housing: Body, sump) -> None:
    """Oil supplied to the mixture (jets, circulating oil, oil–air), the bath's exchanges, grease."""
    lub = m.lubrication
    if sump is not None:
        _bath(spec, m, lay, housing, sump)
    elif lub.supply in ("oil_jet", "oil_air"):
        spec.fixed("oil_inlet", "scene.T_oil_in_C", description="oil supply (inlet temperature; ambient if not given)")
        jet = lub.supply == "oil_jet" and lub.feed == "jet"
        beta = lub.beta if lub.beta is not None else (BETA_JET if jet else 1.0)
        spec.element("oil_stream", "advection", ("oil_inlet", "oil_air"), Q_m3_s="scene.oil_flow_m3_s", beta=beta,
                     description=("oil jet: the penetrating share β (Brossier et al. 2021; seed 004 §4.5)" if jet else
                                  "all the oil through the bearing, drained at the mixture's temperature"))
        if lub.supply == "oil_air" and lub.air_flow > 0:
            air = air_properties(293.15)
            spec.element("air_stream", "advection", ("oil_inlet", "oil_air"), Q_m3_s=lub.air_flow, beta=1.0,
                         rho_kg_m3=float(air["rho"]), cp_J_kgK=float(air["cp"]),
                         description="the carrier air through the bearing (its volume at 20 °C, 1 atm)")
    if lub.supply == "grease":
        fill = lub.grease_fill if lub.grease_fill is not None else estimates.value(m, "grease_fill")
        thrust = m.bearing.kind == "thrust"
        for race in (("shaft_washer", "housing_washer") if thrust else ("inner_race", "outer_race")):
            spec.element(f"{race}--oil_air_grease", "planar", (race, "oil_air"), k_W_mK=lub.k,
                         A_m2=fill * math.pi * lay.dm * lay.B, length_m=lay.D / 2, estimated=["A_m2", "length_m"],
                         description=f"conduction through the grease fill ({fill:.0%}) across half the gap")
