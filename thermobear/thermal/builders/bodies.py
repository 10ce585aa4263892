"""Shaft and housing: bodies of revolution cut by the one rule (:mod:`~thermobear.thermal.builders.axisym`),
their faces exchanging heat with the room, the housing's cavity, a frame or a fixed shaft end.

Faces and their laws (each a network element per cell of the face, the cell's share of the area):

* shaft, outside the housing: rotating cylinder in air (Kays & Bjorklund) mixed with free
  convection (Churchill–Chu) and an optional cross flow (Churchill–Bernstein), n = 3; inside the
  housing: the cavity's air, laminar flat plate at half the shaft's surface speed (estimated: the
  mean of a Couette flow between the turning shaft and the still housing); free end faces: vertical
  plate (Churchill–Chu) of the shaft's diameter; fixed ends: the half cell's axial conduction to the
  held temperature.
* housing, block: the two side faces (parallel to the shaft) vertical plates of the block's
  height, the top an upward-facing plate, the base a downward-facing plate or the mounting joint;
  round bodies: horizontal cylinder (free) or cross flow (forced); end faces: vertical plates;
  radiation of every face in air to the room (ε of the housing).  Forced air: each plate law mixed
  (n = 3) with the forced flat plate at the given speed over the face's extent across the shaft.
* a pillow block's foot is one node under the body (solid, base_length × axial length × the height
  from the mounting face to the body), joined to the body's outer cells through a web half the body's
  diameter wide (estimated).
"""
from __future__ import annotations

import math
from dataclasses import replace

from thermobear.contact.materials import material
from thermobear.thermal.builders.axisym import Body, revolution_body, segment_count
from thermobear.thermal.conduction import solid_cylinder_conductance
from thermobear.thermal.builders.faces import AMBIENT, housing_faces
from thermobear.thermal.builders.layout import Layout, h_cavity_ref, h_housing_ref, h_shaft_ref
from thermobear.thermal.builders.machine import Machine
from thermobear.thermal.builders.spec import NetworkSpec

__all__ = ["add_shaft", "add_housing"]



def _diffusivity(mat: str) -> float:
    m = material(mat)
    return m.k / (m.rho * m.cp)


def _pieces(z0, zb0, zb1, z1, zc0, zc1):
    """Axial pieces of a body around the bearing (zb0..zb1), cut where the housing starts and ends
    (zc0, zc1): [(label, a, b, inside, from_start)] in z order (empty pieces dropped)."""
    cuts = [("left", z0, min(zc0, zb0), False, False), ("left", max(z0, zc0), zb0, True, False),
            ("seat", zb0, zb1, True, True), ("right", zb1, min(z1, zc1), True, True),
            ("right", max(zb1, zc1), z1, False, True)]
    return [c for c in cuts if c[2] - c[1] > 1e-4]          # pieces shorter than 0.1 mm dropped


def _kept(m: Machine, key: str, seg):
    """A piece's segmentation, its count held at the machine's ``cells`` (a drawn machine keeps the cells
    of its nominal, so that its nodes are the nominal's) when it names the piece."""
    n = dict(m.cells).get(key)
    return seg if n is None else replace(seg, n=int(n))


def _cut(spec, m, body_name, pieces, R_of, G_of, a):
    """The axial counts of the pieces and the numbering offsets (cells counted from the bearing)."""
    out, j_left, j_right = [], 0, 0
    for label, za, zb, inside, from_start in pieces:
        L = zb - za
        seg = segment_count(L, R_of(L), G_of(L, inside, label), a, t_resolve_s=m.t_resolve_s, Bi_max=m.Bi_max)
        where = " (inside the housing)" if inside and label != "seat" and body_name == "shaft" else ""
        seg = spec.segments[f"{body_name} {label}{where}"] = _kept(m, f"{body_name} {label}{where}", seg)
        out.append((label, za, zb, seg.n, from_start, inside))
    # numbering: from the bearing outward on each side
    for q in sorted(range(len(out)), key=lambda q: -out[q][1]):      # left pieces, nearest first
        if out[q][0] == "left":
            out[q] = out[q] + (j_left,)
            j_left += out[q][3]
    for q in sorted(range(len(out)), key=lambda q: out[q][1]):
        if out[q][0] == "right":
            out[q] = out[q] + (j_right,)
            j_right += out[q][3]
        elif out[q][0] == "seat":
            out[q] = out[q] + (0,)
    return out


def _namer(base, pieces):
    """Cell names: ``<base>`` the cell under the bearing's mid-plane at the bearing's side, ``<base>_seat_j``
    the other cells under the bearing (left to right), ``<base>_left_j`` / ``<base>_right_j`` the cells
    beside it counted from the bearing outward, ``_r2``, ``_r3`` … the further radial cells."""
    n_seat = next(p[3] for p in pieces if p[0] == "seat")

    def name(label, j, i):
        if label == "seat":
            s = base if j - 1 == n_seat // 2 else f"{base}_seat_{j}"
        else:
            s = f"{base}_{label}_{j}"
        return s if i == 0 else f"{s}_r{i + 1}"
    return name


def add_shaft(spec: NetworkSpec, m: Machine, lay: Layout, cavity: str) -> Body:
    """The shaft: cells, lateral exchange (room or housing cavity), ends."""
    sh = m.shaft
    mat = material(sh.material)
    A = math.pi * (lay.r_s**2 - lay.r_si**2)
    h_out, a = h_shaft_ref(lay), _diffusivity(sh.material)
    exposed = sh.surface == "air"

    def G_of(L, inside, label):
        if label == "seat":          # the ring's seat: the joint in series with the half cell
            return 1.0 / (1.0 / (lay.h_inner * 2 * math.pi * lay.r_s * L) + 1.0 / float(solid_cylinder_conductance(mat.k, L)))
        h = h_cavity_ref(lay, L) if inside else (h_out if exposed else 0.0)
        return h * 2 * math.pi * lay.r_s * L
    pieces = _cut(spec, m, "shaft", _pieces(lay.z_s0, -lay.B / 2, lay.B / 2, lay.z_s1, lay.z_h0, lay.z_h1),
                  lambda L: L / (mat.k * A), G_of, a)
    L_tot = lay.z_s1 - lay.z_s0
    R_r = (1 / (8 * math.pi * mat.k * L_tot) if lay.r_si == 0 else
           math.log(lay.r_s / lay.r_si) / (2 * math.pi * mat.k * L_tot))
    G_all = sum(G_of(p[2] - p[1], p[5], p[0]) for p in pieces)      # everything the shaft exchanges
    seg_r = _kept(m, "shaft radial", segment_count(lay.r_s - lay.r_si, R_r, G_all, a, t_resolve_s=m.t_resolve_s,
                                                   Bi_max=m.Bi_max))
    spec.segments["shaft radial"] = seg_r
    body = revolution_body(spec, "shaft", lay.r_si, lay.r_s, [(p[0], p[1], p[2], p[3], p[4], p[6]) for p in pieces],
                           sh.material, seg_r.n, cell_name=_namer("shaft", pieces), radial_from="outer",
                           description="shaft")
    w = "op.omega_inner_rad_s"
    for label, za, zb, n, fs, inside, _ in pieces:
        if label == "seat" or (not inside and not exposed):
            continue
        for cell, z0, z1 in body.face("outer", (za, zb)):
            area = 2 * math.pi * lay.r_s * (z1 - z0)
            if inside:
                name = spec.element(f"{cell.name}--{cavity}", "convection", (cell.name, cavity),
                                    correlation="flat_plate_laminar", fluid="air", x_m=zb - za, A_m2=area,
                                    u_m_s=f"0.5 * abs({w}) * {lay.r_s!r}",
                                    description="shaft in the housing's cavity: laminar plate at half the "
                                                "surface speed (estimated Couette mean)")
            else:
                kw = {"u_air_m_s": m.housing.air_speed} if m.housing.air == "forced" else {}
                name = spec.element(f"{cell.name}--{AMBIENT}", "convection", (cell.name, AMBIENT),
                                    correlation="rotating_cylinder", D_m=2 * lay.r_s, omega_rad_s=f"abs({w})",
                                    A_m2=area, description="shaft in the room: rotation, free convection"
                                    + (" and the cross flow" if kw else "") + " mixed (n = 3)", **kw)
            spec.surface(element=name, body="shaft", face="outer", r=(lay.r_s, lay.r_s), z=(z0, z1),
                         to=cavity if inside else AMBIENT, kind="convection")
    _shaft_ends(spec, m, lay, body)
    return body


def _shaft_ends(spec, m, lay, body):
    sh = m.shaft
    for side, end, T, node in (("left", sh.end_left, sh.T_end_left_C, sh.end_left_node),
                               ("right", sh.end_right, sh.T_end_right_C, sh.end_right_node)):
        z = lay.z_s0 if side == "left" else lay.z_s1
        if end == "fixed":
            spec.fixed(node, T if T is not None else "scene.T_ambient_C",
                       description=f"the shaft's {side} end, held at a temperature"
                       + ("" if T is not None else " (ambient)"))
        for cell, r0, r1 in body.face(side):
            if end == "fixed":
                name = spec.element(f"{cell.name}--{node}", "planar", (cell.name, node), material=sh.material,
                                    A_m2=math.pi * (r1**2 - r0**2), length_m=0.5 * (cell.z1 - cell.z0),
                                    description="half cell to the held end")
                spec.surface(element=name, body="shaft", face=side, r=(r0, r1), z=(z, z), to=node, kind="fixed")
            elif end == "free":
                name = spec.element(f"{cell.name}--{AMBIENT}_end", "convection", (cell.name, AMBIENT),
                                    correlation="plate_vertical", L_m=2 * lay.r_s, A_m2=math.pi * (r1**2 - r0**2),
                                    description="free end face of the shaft: vertical plate")
                spec.surface(element=name, body="shaft", face=side, r=(r0, r1), z=(z, z), to=AMBIENT,
                             kind="convection")


def add_housing(spec: NetworkSpec, m: Machine, lay: Layout, cavity: str) -> Body:
    """The housing: cells and the exchange of its faces (room, frame, cavity)."""
    h = m.housing
    mat = material(h.material)
    A_ann = math.pi * (lay.R_h**2 - lay.R_seat**2)
    a = _diffusivity(h.material)
    h_ref = h_housing_ref(lay, h.emissivity)
    perimeter = 2 * lay.height + 2 * lay.depth if lay.shape == "block" else 2 * math.pi * lay.R_h

    def G_of(L, inside, label):
        seat = lay.h_outer * math.pi * lay.OD * L if label == "seat" else 0.0
        return seat + h_ref * perimeter * L + lay.mount_G * L / lay.L_h
    pieces = _cut(spec, m, "housing", _pieces(lay.z_h0, -lay.B / 2, lay.B / 2, lay.z_h1, lay.z_h0, lay.z_h1),
                  lambda L: L / (mat.k * A_ann), G_of, a)
    n_ends = (lay.end_left != "adiabatic") + (lay.end_right != "adiabatic")
    G_all = sum(G_of(p[2] - p[1], p[5], p[0]) for p in pieces) + h_ref * A_ann * n_ends   # everything it exchanges
    seg_r = _kept(m, "housing radial", segment_count(lay.R_h - lay.R_seat, math.log(lay.R_h / lay.R_seat)
                                                     / (2 * math.pi * mat.k * lay.L_h), G_all, a,
                                                     t_resolve_s=m.t_resolve_s, Bi_max=m.Bi_max))
    spec.segments["housing radial"] = seg_r
    body = revolution_body(spec, "housing", lay.R_seat, lay.R_h, [(p[0], p[1], p[2], p[3], p[4], p[6]) for p in pieces],
                           h.material, seg_r.n, cell_name=_namer("housing", pieces), radial_from="inner",
                           description=f"housing ({h.type}, {h.material})")
    housing_faces(spec, m, lay, body, cavity)
    return body
