"""The resolved dimensions of a machine: every default of :mod:`~thermobear.thermal.builders.machine`
turned into numbers (SI), and the convection estimates the discretisation rule reads.

Coordinates: z along the shaft, 0 at the bearing's mid-plane (the bearing spans ±B/2), r from
the shaft axis.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from thermobear.contact.materials import material
from thermobear.errors import InputError
from thermobear.thermal.builders import estimates
from thermobear.thermal.builders.fits import probable_interference, seat_conductance, seat_sigma
from thermobear.thermal.builders.machine import Machine
from thermobear.thermal.conduction import spreading_conductance
from thermobear.thermal.convection import (h_free_vertical_plate, h_harris, h_natural_horizontal_cylinder,
                                           h_radiation, h_rotating_cylinder, mixed_convection)
from thermobear.lubrication.air import air_properties
from thermobear.units import ZERO_C_K

__all__ = ["Layout", "layout", "seat_interferences", "DT_REF_K", "H_MOUNT_W_M2K"]

DT_REF_K = 20.0          #: surface excess over ambient at which the rule estimates free convection [K]
#: bolted joint, Bergman et al. 2011 Table 3.2 (air, 0.1 MPa) [W/(m² K)]: the data's nominal
#: (materials/network_builders.toml ``R_mount_m2K_W``; a machine reads its own, :func:`_mounting`)
H_MOUNT_W_M2K = 1.0 / estimates.values()["R_mount_m2K_W"]
_C0 = ZERO_C_K                 # [K] at 0 °C (thermobear.units)


@dataclass(frozen=True)
class Layout:
    """Numbers of a machine (SI); see the module docstring for the coordinates."""

    B: float
    bore: float
    OD: float
    dm: float
    D: float
    Z: int
    # shaft
    r_s: float
    r_si: float
    z_s0: float
    z_s1: float
    # housing
    shape: str                 # "block" | "round"
    R_seat: float
    R_h: float
    z_h0: float
    z_h1: float
    height: float              # block: height; round: outer diameter
    depth: float               # block: depth across the shaft; round: outer diameter
    centre_height: float
    foot: bool
    base_length: float
    foot_height: float
    end_left: str
    end_right: str
    mount_area: float          # area of the mounting face [m²] (0: none)
    mount_G: float             # its conductance joint + frame (or the given one) [W/K]
    mount_h: float             # joint conductance per area (the part the solids do not resolve) [W/(m² K)]
    delta_inner: float         # diametral interference of the inner seat [m]
    delta_outer: float
    h_inner: float             # joint conductance of the inner seat [W/(m² K)]
    h_outer: float             # of the outer seat (thrust: of the housing washer's face)
    # operating point of the rule
    omega_shaft: float         # shaft speed [rad/s]
    T_amb_K: float

    @property
    def L_h(self) -> float:
        return self.z_h1 - self.z_h0


def _housing_dims(m: Machine, OD: float, B: float) -> dict:
    h = m.housing
    L_h = h.axial_length if h.axial_length is not None else 2.0 * B
    if h.type == "block":
        H = h.height if h.height is not None else 2.0 * OD
        W = h.depth if h.depth is not None else 2.0 * OD
        for key, v in (("height_mm", H), ("depth_mm", W)):
            if v <= 1.05 * OD:
                raise InputError(f"housing.{key}", v * 1e3, f"must leave a wall around the bearing's {OD * 1e3:g} mm seat")
        R_h = math.sqrt(H * W / math.pi)
        hc = h.centre_height if h.centre_height is not None else H / 2
        if not OD / 2 < hc < H - OD / 2:
            raise InputError("housing.centre_height_mm", hc * 1e3, f"the seat must lie inside the block ({OD / 2 * 1e3:g} "
                             f"to {(H - OD / 2) * 1e3:g} mm)")
        return dict(shape="block", R_h=R_h, height=H, depth=W, centre_height=hc, foot=False, base_length=0.0,
                    foot_height=0.0, L_h=L_h)
    Dh = h.outer_diameter if h.outer_diameter is not None else 2.0 * OD
    if Dh <= OD * 1.02:
        raise InputError("housing.outer_diameter_mm", Dh * 1e3, f"must exceed the bearing's {OD * 1e3:g} mm")
    foot = h.type == "pillow"
    hc = h.centre_height if h.centre_height is not None else (0.7 * Dh if foot else Dh / 2)
    if foot and hc <= Dh / 2:
        raise InputError("housing.centre_height_mm", hc * 1e3, "must exceed half the body diameter (room for the foot)")
    base = (h.base_length if h.base_length is not None else 2.5 * Dh) if foot else 0.0
    return dict(shape="round", R_h=Dh / 2, height=Dh, depth=Dh, centre_height=hc, foot=foot, base_length=base,
                foot_height=hc - Dh / 2 if foot else 0.0, L_h=L_h)


def _mounting(m: Machine, d: dict, end_left: str, end_right: str, R_seat: float) -> tuple:
    """(area, G, h) of the mounting face."""
    h = m.housing
    if h.mounting == "none" and h.mounting_G_W_K is None:
        return 0.0, 0.0, 0.0
    if h.type == "flange" or "mounted" in (end_left, end_right):
        A = math.pi * (d["R_h"] ** 2 - R_seat**2) * ((end_left == "mounted") + (end_right == "mounted"))
    elif d["foot"]:
        A = d["base_length"] * d["L_h"]
    elif d["shape"] == "block":
        A = d["depth"] * d["L_h"]
    else:
        A = math.pi * d["R_h"] * d["L_h"] * 0.25          # round body on a saddle: a quarter of its side
    if h.mounting_G_W_K is not None:
        return A, float(h.mounting_G_W_K), float(h.mounting_G_W_K) / A if A > 0 else 0.0
    hj = h.mounting_h_W_m2K if h.mounting_h_W_m2K is not None else 1.0 / estimates.value(m, "R_mount_m2K_W")
    G_sp = float(spreading_conductance(material(h.frame_material).k, A)) if A > 0 else 0.0
    G = 1.0 / (1.0 / (hj * A) + 1.0 / G_sp) if A > 0 else 0.0
    return A, G, G / A if A > 0 else 0.0


def layout(m: Machine) -> Layout:
    """Resolve every default of a machine into numbers (InputError when the parts do not fit)."""
    b, s, h = m.bearing, m.shaft, m.housing
    B, OD = b.width, b.outer_diameter
    d_s = s.diameter if s.diameter is not None else b.bore
    if abs(d_s - b.bore) > 1e-3 * b.bore:
        raise InputError("shaft.diameter_mm", d_s * 1e3, f"the inner ring's seat is the bearing bore {b.bore * 1e3:g} mm")
    if not 0 <= s.bore < 0.9 * d_s:
        raise InputError("shaft.bore_mm", s.bore * 1e3, f"a hollow shaft's bore must be below 0.9 × {d_s * 1e3:g} mm")
    L_l = s.length_left if s.length_left is not None else 2.5 * d_s
    L_r = s.length_right if s.length_right is not None else 2.5 * d_s
    d = _housing_dims(m, OD, B)
    z_h0, z_h1 = h.offset - d["L_h"] / 2, h.offset + d["L_h"] / 2
    if z_h0 > -B / 2 + 1e-9 or z_h1 < B / 2 - 1e-9:
        raise InputError("housing.axial_length_mm", d["L_h"] * 1e3, "the housing must cover the bearing's width "
                         f"{B * 1e3:g} mm (offset {h.offset * 1e3:g} mm)")
    unmounted = h.mounting == "none" and h.mounting_G_W_K is None
    end_left = h.end_left if h.end_left is not None else ("mounted" if h.type == "flange" and not unmounted else "air")
    if unmounted and "mounted" in (end_left, h.end_right):
        raise InputError("housing.mounting", h.mounting, 'an end face is mounted (end_left / end_right = "mounted"): '
                         'give mounting = "frame"')
    A, G, hm = _mounting(m, d, end_left, h.end_right, OD / 2)
    inner_rot = m.rotating == "inner"
    (dl, _), (do, _) = seat_interferences(m)
    h_in, h_out = _seat_h(m, d["R_h"], dl, do)
    return Layout(B=B, bore=b.bore, OD=OD, dm=b.dm, D=b.D, Z=int(b.Z), r_s=d_s / 2, r_si=s.bore / 2,
                  z_s0=-B / 2 - L_l, z_s1=B / 2 + L_r, shape=d["shape"], R_seat=OD / 2, R_h=d["R_h"], z_h0=z_h0,
                  z_h1=z_h1, height=d["height"], depth=d["depth"], centre_height=d["centre_height"], foot=d["foot"],
                  base_length=d["base_length"], foot_height=d["foot_height"], end_left=end_left,
                  end_right=h.end_right, mount_area=A, mount_G=G, mount_h=hm, delta_inner=dl, delta_outer=do,
                  h_inner=h_in, h_outer=h_out,
                  omega_shaft=(m.n_rpm * math.pi / 30.0) if inner_rot else 0.0, T_amb_K=m.T_ambient_C + _C0)


def seat_interferences(m: Machine) -> tuple:
    """((δ_inner, why), (δ_outer, why)): the diametral interference [m] (negative: clearance) of the inner ring's
    seat on the shaft and of the outer ring's in the housing, and where each comes from: the machine's
    ``interference`` when given, else the probable interference of the usual fit (:mod:`thermobear.thermal.builders.fits`:
    shaft k5, m5 above 100 mm, housing H7 under a rotating inner ring; shaft g6, housing N7 under a rotating outer
    ring).  The seats of the network's joints, and of the operating clearance of its scene's ratings."""
    b, inner_rot = m.bearing, m.rotating == "inner"
    out = []
    for given, d, seat, where in ((m.shaft.interference, b.bore, ("k5" if b.bore <= 0.1 else "m5") if inner_rot
                                   else "g6", "shaft"),
                                  (m.housing.interference, b.outer_diameter, "H7" if inner_rot else "N7", "housing")):
        out.append((given, f"[{where}] interference_um") if given is not None else
                   (probable_interference(d, seat), f"{seat} (probable)"))
    return tuple(out)


def _seat_h(m: Machine, R_h: float, delta_inner: float, delta_outer: float) -> tuple:
    """Joint conductances of the seats [W/(m² K)]: given, or from the fits (thermobear.thermal.builders.fits)."""
    b, thrust = m.bearing, m.bearing.kind == "thrust"
    est = {k: estimates.value(m, k) for k in ("Ra_shaft_seat_m", "Ra_housing_seat_m", "Ra_ring_seat_m", "H_micro_Pa",
                                                "M_gas_m")}
    joint = {"H_micro_Pa": est["H_micro_Pa"], "M_gas_m": est["M_gas_m"]}
    h_in = m.shaft.fit_h_W_m2K
    if h_in is None:
        h_in, _ = seat_conductance(delta_inner, b.bore, m.shaft.bore, b.dm if thrust else b.dm - b.D,
                                   material(m.shaft.material), b.ring_material,
                                   seat_sigma(est["Ra_shaft_seat_m"], est["Ra_ring_seat_m"]), **joint)
    h_out = m.housing.fit_h_W_m2K
    if h_out is None:
        sigma = seat_sigma(est["Ra_housing_seat_m"], est["Ra_ring_seat_m"])
        if thrust:       # the washer's face pressed on the housing's shoulder by the axial load
            A = math.pi / 4 * (b.outer_diameter**2 - b.bore**2)
            h_out, _ = seat_conductance(-1e-9, b.outer_diameter, 0.0, 2 * R_h, b.ring_material,
                                        material(m.housing.material), sigma, F_r_N=2 * m.Fa,
                                        width_m=A / b.outer_diameter, **joint)
        else:
            h_out, _ = seat_conductance(delta_outer, b.outer_diameter, b.dm + b.D, 2 * R_h, b.ring_material,
                                        material(m.housing.material), sigma, F_r_N=m.Fr, width_m=b.width, **joint)
    return float(h_in), float(h_out)


# --------------------------------------------------------------------------- reference convection
def h_shaft_ref(lay: Layout) -> float:
    """Convection of the shaft's lateral surface in the room at the rule's reference state [W/(m² K)]."""
    T, Ta = lay.T_amb_K + DT_REF_K, lay.T_amb_K
    D = 2 * lay.r_s
    return float(mixed_convection(h_rotating_cylinder(lay.omega_shaft, D, T, Ta), h_natural_horizontal_cylinder(T, Ta, D)))


def h_cavity_ref(lay: Layout, x: float) -> float:
    """Convection between a surface and the air of the housing's cavity (driven by the shaft) [W/(m² K)]."""
    air = air_properties(lay.T_amb_K + DT_REF_K)
    u = 0.5 * lay.omega_shaft * lay.r_s
    return float(h_harris(air["k"], air["Pr"], u, air["nu"], max(x, 1e-3), "flat_plate_laminar"))


def h_housing_ref(lay: Layout, emissivity: float) -> float:
    """Free convection and radiation of the housing's outside at the rule's reference state [W/(m² K)]."""
    T, Ta = lay.T_amb_K + DT_REF_K, lay.T_amb_K
    conv = (h_free_vertical_plate(T, Ta, lay.height) if lay.shape == "block"
            else h_natural_horizontal_cylinder(T, Ta, lay.height))
    return float(np.asarray(conv)) + (float(h_radiation(emissivity, T, Ta)) if emissivity > 0 else 0.0)
