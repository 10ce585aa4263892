"""The bearing inside its machine: rings, balls, the cavity's mixture, the seats, seals and cage.

Nodes keep the names the solver looks for (:data:`thermobear.thermal.ROLES`): ``inner_ring``
(bore side) and ``inner_race`` (raceway side) of the inner ring, ``balls``, ``outer_race`` and
``outer_ring`` of the outer ring, ``oil_air`` (the mixture in the cavity); thrust bearings
``shaft_washer`` and ``housing_washer``.  Optional: ``seal`` (the contact seals' lips, where their
friction heat arises), ``cage``.  The ring model is the hand-written seed-004 network's (Pouly et
al. 2010 as described by seed 004 §4.5): each ring two nodes joined by the radial shell between its
bore and its raceway, ½ of the ring annulus each (0.8 of it for the groove and chamfers, estimated),
the balls one node joined to each raceway by the Hertz contacts' constriction conductance, the
races and balls to the mixture by the laminar flat-plate law at their speeds relative to the cage.

Seats (:mod:`~thermobear.thermal.builders.fits`): the ring's node is the temperature of its seat face,
the body's cell joins it through the joint in series with the half cell.

Closures: without seals the bearing's cavity and the housing's are one (``oil_air``); shields or
seals close the bearing, and the housing's cavity becomes a node ``housing_air`` of its own.
Contact seals add a node ``seal``: the lips on the inner ring's shoulders (2 seals, lip band
0.5 mm wide; the heat enters the ring's steel over a depth of the band's width, estimated), joined
to the outer ring through the seal's rubber (NBR, k = 0.25 W/(m K), 2 mm thick, estimated).
Shields: the mixture reaches the outer ring through the shields' faces (steel, clamped in the
outer ring), laminar plate at the cage's speed.
"""
from __future__ import annotations

import math

from thermobear.contact.materials import material
from thermobear.thermal.builders import estimates
from thermobear.thermal.builders.axisym import Body
from thermobear.thermal.builders.layout import Layout
from thermobear.thermal.builders.machine import Machine
from thermobear.thermal.builders.spec import NetworkSpec

__all__ = ["add_rings", "add_thrust_washers", "add_seats", "add_closures", "add_cage", "free_volume"]

# estimated (materials/network_builders.toml, with their ranges): ring_fill, the share of a ring's annulus
# that is steel (groove, chamfers; as the hand network); k_seal_W_mK, nitrile rubber (NBR) 0.2–0.3 W/(m K);
# cage_film_m, the pocket film; k_air_still_W_mK, the still mixture's air; the seal's and cage's multipliers
_I, _O, _C, _W = "op.omega_inner_rad_s", "op.omega_outer_rad_s", "op.omega_cage_rad_s", "op.omega_ball_rad_s"


def free_volume(lay: Layout) -> float:
    """Free volume of the bearing between its raceway diameters, minus the balls [m³]."""
    return math.pi / 4 * ((lay.dm + lay.D) ** 2 - (lay.dm - lay.D) ** 2) * lay.B - lay.Z * math.pi * lay.D**3 / 6


def _exchange(m: Machine) -> dict:
    """Keys of the ball–race contact elements: rolling, lubricated contacts with the lubricant around them out
    to the estimated meniscus gap (``contact_exchange = "rolling"``), or the Hertz constriction alone."""
    if m.lubrication.contact_exchange == "stationary":
        return {"estimated": ["Q_fallback_N"]}
    return {"exchange": "rolling", "h_meniscus_m": estimates.value(m, "meniscus_gap_m"),
            "estimated": ["Q_fallback_N", "h_meniscus_m"]}


def q_fallback(m: Machine, lay: Layout) -> float:
    """Ball load for the contacts when the mechanics gives none [N]: the axial load shared by all balls,
    or Stribeck's 4.37 F_r/(Z cos α) (zero clearance), at least 1 N (the solver's contacts replace it)."""
    a = m.bearing.alpha0 or 0.0
    q_ax = m.Fa / (lay.Z * math.sin(a)) if a > 1e-6 else 0.0
    q_r = 4.37 * m.Fr / (lay.Z * math.cos(a)) if a < math.pi / 2 - 1e-6 else 0.0
    return max(q_ax, q_r, 1.0)


def _mixture_links(spec, lay, links, fluid, sump):
    """Convection of races and balls to the mixture (the immersed share to the sump, in oil)."""
    for node, u, x, A in links:
        f_sump = sump[1].get(node, 0.0) if sump else 0.0
        if f_sump < 1.0:
            spec.element(f"{node}--oil_air", "convection", (node, "oil_air"), correlation="flat_plate_laminar",
                         u_m_s=u, x_m=x, A_m2=A * (1 - f_sump), **fluid,
                         description="laminar flat plate (Bergman eq 7.23), speed relative to the cage"
                         + (f"; {1 - f_sump:.3f} of the area above the oil level" if f_sump else ""))
        if f_sump > 0.0:
            spec.element(f"{node}--{sump[0]}", "convection", (node, sump[0]), correlation="flat_plate_laminar",
                         fluid="oil", u_m_s=u, x_m=x, A_m2=A * f_sump,
                         description=f"the {f_sump:.3f} of the area below the oil level, in the bath's oil")


def add_rings(spec: NetworkSpec, m: Machine, lay: Layout, fluid: dict, sump=None) -> None:
    """Rings, balls and the mixture of a radial bearing (nodes and their elements)."""
    d, D, dm, OD, B = lay.bore, lay.D, lay.dm, lay.OD, lay.B
    ring_fill = estimates.value(m, "ring_fill")
    v_in = 0.5 * ring_fill * math.pi / 4 * ((dm - D) ** 2 - d**2) * B
    v_out = 0.5 * ring_fill * math.pi / 4 * (OD**2 - (dm + D) ** 2) * B
    est = ["volume_m3"]
    spec.node("inner_ring", volume_m3=v_in, material="bearing.ring_material", estimated=est,
              description="inner ring, bore half (its bore face's temperature)")
    spec.node("inner_race", volume_m3=v_in, material="bearing.ring_material", estimated=est,
              description="inner ring, raceway half (receives the inner contacts' heat)")
    spec.node("balls", volume_m3=lay.Z * math.pi * D**3 / 6, material="bearing.ball_material")
    spec.node("outer_race", volume_m3=v_out, material="bearing.ring_material", estimated=est,
              description="outer ring, raceway half")
    spec.node("outer_ring", volume_m3=v_out, material="bearing.ring_material", estimated=est,
              description="outer ring, outside half (its seat face's temperature)")
    Q = q_fallback(m, lay)
    exchange = _exchange(m)
    spec.element("inner_ring_radial", "shell", ("inner_ring", "inner_race"), material="bearing.ring_material",
                 r1_m=d / 2, r2_m=(dm - D) / 2, L_m=B)
    for side, a, b in (("inner", "inner_race", "balls"), ("outer", "balls", "outer_race")):
        spec.element(f"{side}_contacts", "ball_race_contact", (a, b), contact=side,
                     material_ball="bearing.ball_material", material_ring="bearing.ring_material", Q_fallback_N=Q,
                     **exchange, description="Hertz contacts (the mechanics' semi-axes; the fallback load only "
                     "without them)" + (", the surfaces' exchange as they roll through them, through the oil film, "
                                        "and the lubricant around them out to the meniscus gap" if len(exchange) > 1 else ""))
    spec.element("outer_ring_radial", "shell", ("outer_race", "outer_ring"), material="bearing.ring_material",
                 r1_m=(dm + D) / 2, r2_m=OD / 2, L_m=B)
    links = [("inner_race", f"abs({_I} - {_C}) * {(dm - D) / 2!r}", B, math.pi * (dm - D) * B),
             ("balls", f"{_W} * {D / 2!r}", D, lay.Z * math.pi * D**2),
             ("outer_race", f"abs({_O} - {_C}) * {(dm + D) / 2!r}", B, math.pi * (dm + D) * B)]
    _mixture_links(spec, lay, links, fluid, sump)
    for race in ("inner_race", "outer_race"):        # still mixture: conduction across half the gap
        spec.element(f"{race}--oil_air_conduction", "planar", (race, "oil_air"), k_W_mK=estimates.value(m, "k_air_still_W_mK"),
                     A_m2=math.pi * dm * B, length_m=D / 2, estimated=["k_W_mK"],
                     description="conduction through the still mixture (air) across half the raceway gap: "
                                 "the floor of the exchange at standstill")


def add_thrust_washers(spec: NetworkSpec, m: Machine, lay: Layout, fluid: dict, sump=None) -> None:
    """Washers and balls of a thrust bearing (the seed-002 hand network's model)."""
    d, D, dm, OD, H = lay.bore, lay.D, lay.dm, lay.OD, lay.B
    v = estimates.value(m, "ring_fill") * math.pi / 4 * (OD**2 - d**2) * 0.3 * H
    for node in ("shaft_washer", "housing_washer"):
        spec.node(node, volume_m3=v, material="bearing.ring_material", estimated=["volume_m3"],
                  description=f"{node.replace('_', ' ')}: 0.3 × the bearing's height thick, 0.8 for the groove")
    spec.node("balls", volume_m3=lay.Z * math.pi * D**3 / 6, material="bearing.ball_material")
    Q = q_fallback(m, lay)
    for side, a, b in (("inner", "shaft_washer", "balls"), ("outer", "balls", "housing_washer")):
        spec.element(f"{a if side == 'inner' else b}_contacts", "ball_race_contact", (a, b), contact=side,
                     material_ball="bearing.ball_material", material_ring="bearing.ring_material", Q_fallback_N=Q,
                     **_exchange(m))
    A_face = math.pi * dm * D
    links = [("shaft_washer", f"abs({_I} - {_C}) * {dm / 2!r}", D, A_face), ("balls", f"{_W} * {D / 2!r}", D,
             lay.Z * math.pi * D**2), ("housing_washer", f"abs({_O} - {_C}) * {dm / 2!r}", D, A_face)]
    _mixture_links(spec, lay, links, fluid, sump)
    for w in ("shaft_washer", "housing_washer"):
        spec.element(f"{w}--oil_air_conduction", "planar", (w, "oil_air"), k_W_mK=estimates.value(m, "k_air_still_W_mK"), A_m2=A_face,
                     length_m=D / 2, estimated=["k_W_mK"], description="conduction through the still mixture")


def _seat(spec, body: Body, face, z_range, ring, h, what):
    for cell, z0, z1 in body.face(face, z_range):
        r = cell.r1 if face == "outer" else cell.r0
        A = 2 * math.pi * r * (z1 - z0)
        G_half = body.half_conductance(cell, face, (z0, z1))
        name = spec.element(f"{cell.name}--{ring}_fit", "conductance", (cell.name, ring),
                            G_W_K=1.0 / (1.0 / (h * A) + 1.0 / G_half), estimated=["G_W_K"],
                            description=f"{what}: joint h = {h:.4g} W/m2K over {A * 1e6:.0f} mm2 in series with the "
                                        f"half cell {G_half:.4g} W/K")
        spec.surface(element=name, body=body.name, face=face, r=(r, r), z=(z0, z1), to=ring, kind="joint",
                     h_W_m2K=h, G_W_K=h * A)


def add_seats(spec: NetworkSpec, m: Machine, lay: Layout, shaft: Body, housing: Body) -> dict:
    """The rings' (or washers') seats on the shaft and in the housing; returns their h [W/(m² K)]."""
    thrust = m.bearing.kind == "thrust"
    seat = (-lay.B / 2, lay.B / 2)
    inner, outer = ("shaft_washer", "housing_washer") if thrust else ("inner_ring", "outer_ring")
    h_in, h_out = lay.h_inner, lay.h_outer
    _seat(spec, shaft, "outer", seat, inner, h_in, "inner seat")
    if thrust:
        A = math.pi / 4 * (lay.OD**2 - lay.bore**2)
        cells = housing.face("inner", seat)
        L = sum(z1 - z0 for _, z0, z1 in cells)
        for cell, z0, z1 in cells:
            G_face = h_out * A * (z1 - z0) / L
            name = spec.element(f"{cell.name}--{outer}_face", "conductance", (cell.name, outer), G_W_K=G_face,
                                estimated=["G_W_K"],
                                description=f"housing washer's face on the housing's shoulder: h = {h_out:.4g} W/m2K "
                                            f"over {A * 1e6:.0f} mm2 (the shoulder is not part of the housing's "
                                            "annulus: the joint acts on the seat cells' nodes)")
            spec.surface(element=name, body="housing", face="inner", r=(cell.r0, cell.r0), z=(z0, z1), to=outer,
                         kind="exchange", G_W_K=G_face)
    else:
        _seat(spec, housing, "inner", seat, outer, h_out, "outer seat")
    return {"inner": h_in, "outer": h_out}


def add_closures(spec: NetworkSpec, m: Machine, lay: Layout) -> str:
    """Seals or shields closing the bearing; returns the node of the housing's cavity air."""
    seals = m.housing.seals
    d_sh = lay.dm - 0.5 * lay.D                 # inner-ring shoulder (estimated: half a ball inside the pitch)
    d_or = lay.dm + 0.5 * lay.D                 # outer-ring shoulder
    if seals == "contact":
        band = 0.5e-3
        A_lip = 2 * math.pi * d_sh * band * 2
        spec.node("seal", C_J_K=2 * math.pi * d_sh * 2e-3 * 1e-3 * 1200.0 * 1500.0 * 2, estimated=["C_J_K"],
                  uncertainty=estimates.point_uncertainty("seal_capacity"),
                  description="contact seals' lips (2 seals): the lip band, 2 mm x 1 mm of NBR each "
                              "(rho 1200 kg/m3, cp 1500 J/kg K)")
        spec.element("seal--inner_ring", "planar", ("seal", "inner_ring"), material="bearing.ring_material",
                     A_m2=A_lip, length_m=band, estimated=["A_m2", "length_m"],
                     uncertainty=estimates.point_uncertainty("seal_lip_area"),
                     description="lip band 0.5 mm wide on each shoulder; the heat enters the ring over a depth "
                                 "of the band's width")
        spec.element("seal--outer_ring", "shell", ("seal", "outer_ring"), k_W_mK=estimates.value(m, "k_seal_W_mK"),
                     r1_m=d_sh / 2, r2_m=d_or / 2, L_m=2 * 2e-3, estimated=["k_W_mK", "L_m"],
                     uncertainty=estimates.point_uncertainty("k_seal_W_mK", "seal_rubber_length"),
                     description="through the seals' rubber (2 seals, 2 mm thick) to the outer ring's groove")
        spec.element("seal--oil_air", "convection", ("seal", "oil_air"), correlation="flat_plate_laminar",
                     fluid="air", u_m_s=f"abs({_I} - {_C}) * {d_sh / 2!r}", x_m=(d_or - d_sh) / 2,
                     A_m2=2 * math.pi / 4 * (d_or**2 - d_sh**2),
                     description="the seals' inner faces in the cavity")
    elif seals == "shields":
        spec.element("oil_air--outer_ring_shields", "convection", ("outer_ring", "oil_air"),
                     correlation="flat_plate_laminar", fluid="air", u_m_s=f"abs({_O} - {_C}) * {lay.dm / 2!r}",
                     x_m=(d_or - d_sh) / 2, A_m2=2 * math.pi / 4 * (d_or**2 - d_sh**2),
                     description="the shields (steel, clamped in the outer ring) in the cavity's mixture")
    if seals == "none":
        return "oil_air"
    overhang = (lay.z_h1 - lay.z_h0) - lay.B
    if overhang <= 1e-9:
        return "oil_air"
    V = math.pi * (lay.R_seat**2 - lay.r_s**2) * overhang
    spec.node("housing_air", C_J_K=V * 1.1 * 1007.0,
              description="air in the housing's cavity beside the closed bearing (rho 1.1 kg/m3, cp 1007 J/kg K)")
    spec.element("housing_air--outer_ring_side", "convection", ("outer_ring", "housing_air"), correlation="plate_vertical",
                 L_m=lay.OD, A_m2=2 * math.pi / 4 * (lay.OD**2 - d_or**2),
                 description="the outer ring's side faces in the cavity's air")
    return "housing_air"


def add_cage(spec: NetworkSpec, m: Machine, lay: Layout) -> None:
    """A steel cage (pressed, estimated 1 mm thick over the pitch cylinder, 60 % of it open for the
    balls): in the mixture at its own speed, and through the lubricated pockets to the balls."""
    A = math.pi * lay.dm * lay.B * 0.4 * 2
    spec.node("cage", volume_m3=0.5 * A * 1e-3, material="aisi-52100", estimated=["volume_m3", "material"],
              uncertainty=estimates.point_uncertainty("cage_capacity"),
              description="pressed steel cage (estimated)")
    spec.element("cage--oil_air", "convection", ("cage", "oil_air"), correlation="flat_plate_laminar", fluid="air",
                 u_m_s=f"abs({_C}) * {lay.dm / 2!r}", x_m=lay.B, A_m2=A, estimated=["A_m2"],
                 uncertainty=estimates.point_uncertainty("cage_area"),
                 description="both faces of the cage in the mixture at the cage's pitch speed")
    film = estimates.value(m, "cage_film_m")
    spec.element("cage--balls", "planar", ("cage", "balls"), k_W_mK=0.13, A_m2=lay.Z * math.pi * (0.2 * lay.D) ** 2,
                 length_m=film, estimated=["k_W_mK", "A_m2", "length_m"], uncertainty=estimates.point_uncertainty("cage_film_m", "cage_spot"),
                 description=f"pocket contacts through a {film * 1e6:.3g} µm oil film over a spot of 0.2 D radius per ball")
