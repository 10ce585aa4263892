"""The builders' estimated constants, from ``materials/network_builders.toml``, and their ranges.

Every value a network built from dimensions takes where a scene gives none — the seats' roughness,
the microhardness and gas parameter of the joint correlation, the housing's emissivity, the mounting
joint, the rings' and the cavity's fills, the seal's rubber, the cage's pocket film — lives in one
data file with its unit, source and range (``uncertainty.<key>``, :func:`thermobear.schema.check_uncertainty`),
read through :func:`thermobear.files.read_toml`.

A :class:`~thermobear.thermal.builders.Machine` takes drawn values of the family-level estimates
(:data:`FAMILY_KEYS`: they shape the discretisation or spread over many elements) through its
``estimates`` field (:func:`drawn`); :func:`sampled_keys` lists those a machine reads (a value the
scene gives is the scene's, not sampled).  The per-point estimates (:data:`POINT_KEYS`) are written
with their range on the one element that holds them, where the network's ``sample`` context moves them.
"""
from __future__ import annotations

from dataclasses import replace

from thermobear.files import data_dir, read_toml
from thermobear.schema import Field, check_table, check_uncertainty

__all__ = ["FIELDS", "FAMILY_KEYS", "POINT_KEYS", "values", "uncertainty", "value", "machine_value", "drawn",
           "sampled_keys", "point_uncertainty"]

FILE = "network_builders.toml"

FIELDS = {
    "name": Field.text(), "description": Field.text(),
    "Ra_shaft_seat_m": Field.number("m", 0.0, lo_open=True, doc="roughness Ra of a shaft seat"),
    "Ra_housing_seat_m": Field.number("m", 0.0, lo_open=True, doc="roughness Ra of a housing seat"),
    "Ra_ring_seat_m": Field.number("m", 0.0, lo_open=True, doc="roughness Ra of a ring's bore and outside surface"),
    "H_micro_Pa": Field.number("Pa", 0.0, lo_open=True, doc="microhardness of the softer member of a seat"),
    "M_gas_m": Field.number("m", 0.0, doc="gas rarefaction parameter of the air in a joint's gaps"),
    "emissivity": Field.number("-", 0.0, 1.0, lo_open=True, doc="of the housing's outside"),
    "R_mount_m2K_W": Field.number("m2 K/W", 0.0, lo_open=True, doc="contact resistance of the mounting face"),
    "ring_fill": Field.number("-", 0.0, 1.0, lo_open=True, doc="share of a ring's annulus that is steel"),
    "oil_held": Field.number("-", 0.0, 1.0, doc="share of the free volume held as oil in a lubricated cavity"),
    "grease_fill": Field.number("-", 0.0, 1.0, lo_open=True, doc="grease fill of the free volume"),
    "k_seal_W_mK": Field.number("W/(m K)", 0.0, lo_open=True, doc="conductivity of a contact seal's rubber"),
    "cage_film_m": Field.number("m", 0.0, lo_open=True, doc="oil film in a cage pocket"),
    "meniscus_gap_m": Field.number("m", 0.0, lo_open=True, doc="gap at which the lubricant around a ball-race contact ends"),
    "k_air_still_W_mK": Field.number("W/(m K)", 0.0, lo_open=True, doc="air of a still cavity"),
    "web_fraction": Field.number("-", 0.0, 1.0, lo_open=True, doc="pillow block's web width / body diameter"),
    **{k: Field.number("-", 1.0, 1.0, doc=f"multiplier of {e[1]}.{e[2]} as the builder writes it")
       for k, e in {"bath_mixing": (0, "oil_air--oil_sump", "G_W_K"), "sump_capacity": (0, "oil_sump", "C_J_K"),
                    "seal_capacity": (0, "seal", "C_J_K"), "seal_lip_area": (0, "seal--inner_ring", "A_m2"),
                    "seal_rubber_length": (0, "seal--outer_ring", "L_m"), "cage_capacity": (0, "cage", "volume_m3"),
                    "cage_area": (0, "cage--oil_air", "A_m2"), "cage_spot": (0, "cage--balls", "A_m2")}.items()},
    "estimated": Field.names("keys whose values are estimates"),
    "uncertainty": Field.table("ranges of the estimated values (thermobear.schema.check_uncertainty)"),
}
#: drawn per family (the network built again with the draws): key → what it moves
FAMILY_KEYS = {
    "Ra_shaft_seat_m": "the inner seat's joint (with the ring's Ra)",
    "Ra_housing_seat_m": "the outer seat's joint",
    "Ra_ring_seat_m": "both seats' joints",
    "H_micro_Pa": "both seats' joints (and the correlation's pressure bound)",
    "M_gas_m": "both seats' joints (the gaps' air)",
    "emissivity": "the housing's radiation (every face) and its discretisation",
    "R_mount_m2K_W": "the mounting joint (every mounted cell)",
    "ring_fill": "the rings' capacities",
    "oil_held": "the cavity mixture's capacity",
    "grease_fill": "the grease's capacity and conduction",
    "k_air_still_W_mK": "the still mixture's conduction from both races",
    "web_fraction": "a pillow block's web (every outer cell) and its covered side",
    "meniscus_gap_m": "both raceways' contacts (the lubricant around each)",
}
#: drawn per point: key → (element or node, its key) holding the value (the multipliers: the value × a factor)
POINT_KEYS = {"k_seal_W_mK": ("seal--outer_ring", "k_W_mK"), "cage_film_m": ("cage--balls", "length_m"),
              "bath_mixing": ("oil_air--oil_sump", "G_W_K"), "sump_capacity": ("oil_sump", "C_J_K"),
              "seal_capacity": ("seal", "C_J_K"), "seal_lip_area": ("seal--inner_ring", "A_m2"),
              "seal_rubber_length": ("seal--outer_ring", "L_m"), "cage_capacity": ("cage", "volume_m3"),
              "cage_area": ("cage--oil_air", "A_m2"), "cage_spot": ("cage--balls", "A_m2")}


def _table() -> tuple:
    where = f"materials/{FILE}"
    t = check_table(read_toml(str(data_dir("materials") / FILE)), FIELDS, where)
    numbers = {k: f for k, f in FIELDS.items() if f.kind == "number"}
    return t, check_uncertainty(t.get("uncertainty", {}), {k: numbers[k] for k in t if k in numbers}, where)


def values() -> dict:
    """Key → nominal value of the builders' estimates [SI, the key's unit].

    >>> values()["H_micro_Pa"]
    3000000000.0
    """
    t, _ = _table()
    return {k: v for k, v in t.items() if FIELDS[k].kind == "number"}


def uncertainty() -> dict:
    """Key → :class:`~thermobear.schema.Uncertainty` of the builders' estimates.

    >>> uncertainty()["emissivity"].lo
    0.6
    """
    return _table()[1]


def value(m, key: str) -> float:
    """The value of an estimate a machine uses: its drawn value (``m.estimates``), else the data's."""
    return dict(m.estimates).get(key, values()[key]) if m is not None else values()[key]


def machine_value(m, key: str) -> float:
    """The value of an estimate a machine uses [the key's unit]: the housing's emissivity, the grease fill and
    the mounting joint (as R = 1/h) as the machine holds them, the constants as drawn or the data's.

    >>> from thermobear.contact.geometry import bearing
    >>> from thermobear.thermal.builders.machine import Machine
    >>> machine_value(Machine(bearing("6208")), "k_air_still_W_mK") == values()["k_air_still_W_mK"]
    True
    """
    if key == "emissivity":
        return m.housing.emissivity
    if key == "grease_fill" and m.lubrication.grease_fill is not None:
        return m.lubrication.grease_fill
    if key == "R_mount_m2K_W" and m.housing.mounting_h_W_m2K is not None:
        return 1.0 / m.housing.mounting_h_W_m2K
    return value(m, key)


def drawn(m, draws: dict, cells: dict | None = None):
    """A machine with drawn family-level estimates (key → value): the housing's emissivity and the
    grease fill go to their fields, the mounting joint to ``mounting_h_W_m2K``, the constants to
    ``estimates``; ``cells`` (segment label → count, a nominal build's) holds its discretisation."""
    m = replace(m, estimates=tuple(sorted({**dict(m.estimates), **draws}.items())))
    if cells:
        m = replace(m, cells=tuple(sorted(cells.items())))
    if "emissivity" in draws:
        m = replace(m, housing=replace(m.housing, emissivity=float(draws["emissivity"])))
    if "grease_fill" in draws:
        m = replace(m, lubrication=replace(m.lubrication, grease_fill=float(draws["grease_fill"])))
    if "R_mount_m2K_W" in draws:
        m = replace(m, housing=replace(m.housing, mounting_h_W_m2K=1.0 / float(draws["R_mount_m2K_W"])))
    return m


def _default(given, key, convert=float) -> bool:
    """True when a machine's field holds the builders' default (not given, or given as the default:
    a scene written by ``thermobear init`` spells the defaults out)."""
    if given is None:
        return True
    ref = convert(values()[key])
    return abs(float(given) - ref) <= 1e-4 * abs(ref)


def sampled_keys(m) -> list:
    """The family-level estimates a machine reads (in :data:`FAMILY_KEYS` order): the seats' when a
    seat's joint is computed, the emissivity and mounting joint when they are the defaults, the fills
    of its lubrication."""
    h, lub = m.housing, m.lubrication
    inner = m.shaft.fit_h_W_m2K is None
    outer = h.fit_h_W_m2K is None
    keys = {"Ra_shaft_seat_m": inner, "Ra_housing_seat_m": outer, "Ra_ring_seat_m": inner or outer,
            "H_micro_Pa": inner or outer, "M_gas_m": inner or outer,
            "emissivity": h.emissivity > 0 and _default(h.emissivity, "emissivity"),
            "R_mount_m2K_W": (h.mounting_G_W_K is None and h.mounting != "none"
                              and _default(h.mounting_h_W_m2K, "R_mount_m2K_W", lambda r: 1.0 / r)),
            "ring_fill": True,
            "oil_held": lub.supply != "grease" and lub.oil_air_C_J_K is None,
            "grease_fill": lub.supply == "grease" and lub.oil_air_C_J_K is None
            and _default(lub.grease_fill, "grease_fill"),
            "k_air_still_W_mK": True, "web_fraction": h.type == "pillow",
            "meniscus_gap_m": lub.contact_exchange == "rolling"}
    return [k for k in FAMILY_KEYS if keys[k]]


def point_uncertainty(*keys: str) -> dict:
    """The ``uncertainty`` table the builder writes on the element or node holding per-point estimates
    (the network file's syntax: ``{range | factor = [lo, hi], distribution, source}`` by its key)."""
    unc = uncertainty()
    return {POINT_KEYS[k][1]: {**unc[k].as_dict(), "source": f"{unc[k].source} (materials/{FILE} {k})"} for k in keys}
