"""The faces of a housing: its outside in the room, its mounting on a frame, its bore in the cavity.

See :mod:`~thermobear.thermal.builders.bodies` for the laws; each exchange is one element per cell
of the face, carrying the cell's share of the face's area, and one
:class:`~thermobear.thermal.builders.spec.Surface` record.
"""
from __future__ import annotations

import math

from thermobear.contact.materials import material
from thermobear.thermal.builders import estimates
from thermobear.thermal.builders.axisym import Body
from thermobear.thermal.builders.layout import Layout
from thermobear.thermal.builders.machine import Machine
from thermobear.thermal.builders.spec import NetworkSpec

__all__ = ["housing_faces", "AMBIENT", "FRAME"]

AMBIENT = "ambient"
FRAME = "frame"
# a pillow block's web under the body: web_fraction of its diameter wide (estimated, materials/network_builders.toml)


def _forced(m: Machine, x_m: float) -> dict:
    return {"u_air_m_s": m.housing.air_speed, "x_m": x_m} if m.housing.air == "forced" else {}


def _convect(spec, body, cell, face, r, z, law, A, label, **kw):
    name = spec.element(f"{cell.name}--{AMBIENT}_{label}", "convection", (cell.name, AMBIENT), A_m2=A,
                        correlation=law, **kw)
    spec.surface(element=name, body=body.name, face=face, r=r, z=z, to=AMBIENT, kind="convection")


def _radiate(spec, m, body, cell, face, r, z, A, label="radiation"):
    if m.housing.emissivity == 0:            # no radiation (a rig's network that neglects it)
        return
    name = spec.element(f"{cell.name}--{AMBIENT}_{label}", "radiation", (cell.name, AMBIENT),
                        emissivity=m.housing.emissivity, A_m2=A, estimated=["emissivity"])
    spec.surface(element=name, body=body.name, face=face, r=r, z=z, to=AMBIENT, kind="radiation")


def _joint(spec, body, cell, face, r, z, G_face, to, G_half, what):
    """A joint of conductance G_face in series with the half cell between the node and the face."""
    G = 1.0 / (1.0 / G_face + 1.0 / G_half) if G_half > 0 else G_face
    name = spec.element(f"{cell.name}--{to}_{what}", "conductance", (cell.name, to), G_W_K=G,
                        description=f"{what}: joint and frame {G_face:.4g} W/K in series with the half cell "
                                    f"{G_half:.4g} W/K")
    spec.surface(element=name, body=body.name, face=face, r=r, z=z, to=to, kind="joint", G_W_K=G_face)


def _block_sides(spec, m, lay, body, mounted_base):
    H, W, L = lay.height, lay.depth, lay.L_h
    L_top = W * L / (2 * (W + L))
    for cell, z0, z1 in body.face("outer"):
        dz, r, z = z1 - z0, (cell.r1, cell.r1), (z0, z1)
        _convect(spec, body, cell, "outer", r, z, "plate_vertical", 2 * H * dz, "sides", L_m=H, **_forced(m, W))
        _convect(spec, body, cell, "outer", r, z, "plate_up", W * dz, "top", L_m=L_top, **_forced(m, W))
        if mounted_base:
            _joint(spec, body, cell, "outer", r, z, lay.mount_G * dz / L, FRAME,
                   body.half_conductance(cell, "outer", z), "mounting")
        else:
            _convect(spec, body, cell, "outer", r, z, "plate_down", W * dz, "base", L_m=L_top, **_forced(m, W))
        _radiate(spec, m, body, cell, "outer", r, z, (2 * H + W + (0 if mounted_base else W)) * dz)


def _round_sides(spec, m, lay, body, covered, mounted_side):
    h = m.housing
    law = h.shape_convection or ("forced_cylinder" if h.air == "forced" else "natural_horizontal_cylinder")
    kw = {"u_air_m_s": h.air_speed} if law == "forced_cylinder" else {}
    for cell, z0, z1 in body.face("outer"):
        dz, r, z = z1 - z0, (cell.r1, cell.r1), (z0, z1)
        A = 2 * math.pi * lay.R_h * dz * (1 - covered)
        _convect(spec, body, cell, "outer", r, z, law, A, "side", D_m=2 * lay.R_h, **kw)
        _radiate(spec, m, body, cell, "outer", r, z, A)
        if mounted_side:
            _joint(spec, body, cell, "outer", r, z, lay.mount_G * dz / lay.L_h, FRAME,
                   body.half_conductance(cell, "outer", z), "mounting")


def _ends(spec, m, lay, body):
    A_ends = math.pi * (lay.R_h**2 - lay.R_seat**2)
    n_mounted = (lay.end_left == "mounted") + (lay.end_right == "mounted")
    for side, end in (("left", lay.end_left), ("right", lay.end_right)):
        zf = lay.z_h0 if side == "left" else lay.z_h1
        for cell, r0, r1 in body.face(side):
            A, r, z = math.pi * (r1**2 - r0**2), (r0, r1), (zf, zf)
            if end == "air":
                _convect(spec, body, cell, side, r, z, "plate_vertical", A, f"end_{side}", L_m=lay.height,
                         **_forced(m, lay.depth))
                _radiate(spec, m, body, cell, side, r, z, A, f"radiation_end_{side}")
            elif end == "mounted":
                _joint(spec, body, cell, side, r, z, lay.mount_G * A / (A_ends * n_mounted), FRAME,
                       body.half_conductance(cell, side, r), f"mounting_{side}")


def _bore(spec, lay, body, cavity):
    """The housing's bore beside the bearing, in the cavity's air (moved by the shaft)."""
    for label, za, zb in (("left", lay.z_h0, -lay.B / 2), ("right", lay.B / 2, lay.z_h1)):
        if zb - za <= 1e-9:
            continue
        for cell, z0, z1 in body.face("inner", (za, zb)):
            name = spec.element(f"{cell.name}--{cavity}", "convection", (cell.name, cavity),
                                correlation="flat_plate_laminar", fluid="air", x_m=zb - za,
                                A_m2=2 * math.pi * lay.R_seat * (z1 - z0),
                                u_m_s=f"0.5 * abs(op.omega_inner_rad_s) * {lay.r_s!r}",
                                description="housing bore in the cavity's air: laminar plate at half the shaft's "
                                            "surface speed (estimated Couette mean)")
            spec.surface(element=name, body="housing", face="inner", r=(lay.R_seat, lay.R_seat), z=(z0, z1),
                         to=cavity, kind="convection")


def _foot(spec, m, lay, body):
    """A pillow block's foot: one node under the body, its faces, its base on the frame."""
    h = m.housing
    mat = material(h.material)
    fh, L, bl, Dh = lay.foot_height, lay.L_h, lay.base_length, 2 * lay.R_h
    web = estimates.value(m, "web_fraction") * Dh
    spec.node("housing_foot", volume_m3=bl * L * fh, material=h.material, estimated=["volume_m3"],
              description=f"foot of the pillow block: solid {bl * 1e3:.0f} × {L * 1e3:.0f} × {fh * 1e3:.0f} mm")
    for cell, z0, z1 in body.face("outer"):
        G_web = mat.k * web * (z1 - z0) / (0.5 * fh)
        G_half = body.half_conductance(cell, "outer", (z0, z1))
        spec.element(f"{cell.name}--housing_foot", "conductance", (cell.name, "housing_foot"),
                     G_W_K=1.0 / (1.0 / G_web + 1.0 / G_half), estimated=["G_W_K"],
                     description=f"web {web * 1e3:.0f} mm wide down to the foot's centre, in series with the half cell")
    A_side, A_top = 2 * (bl + L) * fh, max(bl - web, 0.0) * L
    spec.element("housing_foot--ambient_sides", "convection", ("housing_foot", AMBIENT), correlation="plate_vertical",
                 L_m=fh, A_m2=A_side, **_forced(m, bl))
    if A_top > 0:
        spec.element("housing_foot--ambient_top", "convection", ("housing_foot", AMBIENT), correlation="plate_up",
                     L_m=A_top / (2 * (bl - web + L)), A_m2=A_top, **_forced(m, bl))
    if h.emissivity > 0:
        spec.element("housing_foot--ambient_radiation", "radiation", ("housing_foot", AMBIENT),
                     emissivity=h.emissivity, A_m2=A_side + A_top, estimated=["emissivity"])
    if lay.mount_area > 0:
        G_half = mat.k * bl * L / (0.5 * fh)
        spec.element("housing_foot--frame_mounting", "conductance", ("housing_foot", FRAME),
                     G_W_K=1.0 / (1.0 / lay.mount_G + 1.0 / G_half),
                     description="base on the frame: joint and frame in series with half the foot's height")
    else:
        spec.element("housing_foot--ambient_base", "convection", ("housing_foot", AMBIENT), correlation="plate_down",
                     L_m=bl * L / (2 * (bl + L)), A_m2=bl * L, **_forced(m, bl))


def housing_faces(spec: NetworkSpec, m: Machine, lay: Layout, body: Body, cavity: str) -> None:
    """Every exchange of the housing's faces (see :mod:`~thermobear.thermal.builders.bodies`)."""
    end_mounted = "mounted" in (lay.end_left, lay.end_right)
    if lay.mount_area > 0:
        spec.fixed(FRAME, "scene.T_ambient_C", description="the machine frame the housing is bolted to (ambient)")
    if lay.shape == "block":
        _block_sides(spec, m, lay, body, mounted_base=lay.mount_area > 0 and not end_mounted)
    else:
        covered = estimates.value(m, "web_fraction") / math.pi if lay.foot else 0.0
        _round_sides(spec, m, lay, body, covered, mounted_side=lay.mount_area > 0 and not (end_mounted or lay.foot))
    _ends(spec, m, lay, body)
    _bore(spec, lay, body, cavity)
    if lay.foot:
        _foot(spec, m, lay, body)
