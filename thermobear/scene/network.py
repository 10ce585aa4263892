"""The scene's thermal network: which file, with the scene's overrides and imposed temperatures.

A scene names a bundled network (``networks/<name>.toml``) or a path (absolute, relative to the
scene file, or — for a scene built in code — to the working directory), or describes its machine
(``[shaft]``, ``[housing]`` and the lubrication keys of ``[lubricant]``): the network is then
built from those dimensions (:func:`machine_from_sections` → a
:class:`~thermobear.thermal.builders.Machine`, ``scene.network``; :func:`thermobear.thermal.builders.build_network`).
:func:`network_spec` returns its table with ``[thermal.parameters]`` applied and the ``[thermal]
fixed_C`` nodes turned into fixed-temperature boundaries; every name the scene uses (parameters,
imposed nodes, ``[rig.map]`` targets) is checked against the network here, when the scene is read.
"""
from __future__ import annotations

import copy
import re
from pathlib import Path

from thermobear import validity
from thermobear.contact.materials import material_names
from thermobear.errors import InputError
from thermobear.files import data_dir, names_in, read_toml
from thermobear.schema import Field
from thermobear.thermal.builders import Housing, Lubrication, Machine, Shaft, build_network
from thermobear.thermal.network import ROLES

__all__ = ["network_path", "network_spec", "network_nodes", "network_table", "heat_receiving_nodes",
           "machine_from_sections", "lubrication_of", "check_lubrication_keys", "PARAMETRIC", "SHAFT_FIELDS",
           "HOUSING_FIELDS"]

PARAMETRIC = "parametric"     #: the network name of a network built from the scene's dimensions

_KEEP_ON_IMPOSE = ("description", "measured_by", "source")


def _temperature(doc):
    return Field.number("°C", *validity.T_LUBRICANT_REFUSE_C, doc=doc)


_LENGTH = dict(unit="mm", lo=0.0, hi=1e4, lo_open=True)
#: ``[shaft]``: the shaft of a parametric network (thermobear.thermal.builders; defaults there).
SHAFT_FIELDS = {
    "diameter_mm": Field.number(**_LENGTH, doc="shaft diameter (the bearing bore; a stepped shaft is not modelled)"),
    "bore_mm": Field.number("mm", 0.0, 1e4, doc="bore of a hollow shaft (default 0: solid)"),
    "length_left_mm": Field.number("mm", 0.0, 1e4, doc="from the bearing's side face to the shaft end (default 2.5 d)"),
    "length_right_mm": Field.number("mm", 0.0, 1e4, doc="the same on the right"),
    "material": Field.text("material name (default steel-c45)"),
    "end_left": Field.choice("free", "fixed", "adiabatic", doc="free: convection; fixed: held at T_end_left_C; "
                             "adiabatic: a symmetry plane"),
    "end_right": Field.choice("free", "fixed", "adiabatic", doc="the same on the right"),
    "T_end_left_C": _temperature("temperature of a fixed left end (default ambient)"),
    "T_end_right_C": _temperature("temperature of a fixed right end (default ambient)"),
    "surface": Field.choice("air", "enclosed", doc="the shaft outside the housing in the room's air, or enclosed"),
    "interference_um": Field.number("µm", -1e3, 1e3, doc="diametral interference of the inner ring's seat, negative: "
                                    "clearance (default: probable k5/m5 fit, g6 for a rotating outer ring)"),
    "fit_h_W_m2K": Field.number("W/(m² K)", 0.0, 1e8, lo_open=True, doc="the seat's joint conductance, given"),
}
#: ``[housing]``: the housing of a parametric network.
HOUSING_FIELDS = {
    "type": Field.choice("block", "pillow", "flange", doc="rectangular block, pillow block, flanged housing"),
    "material": Field.text("material name (default cast-iron-gjl-250)"),
    "axial_length_mm": Field.number(**_LENGTH, doc="length along the shaft (default 2 × bearing width)"),
    "height_mm": Field.number(**_LENGTH, doc="block: outer height (default 2 × bearing OD)"),
    "depth_mm": Field.number(**_LENGTH, doc="block: outer depth across the shaft (default 2 × bearing OD)"),
    "outer_diameter_mm": Field.number(**_LENGTH, doc="pillow / flange: body diameter (default 2 × bearing OD)"),
    "centre_height_mm": Field.number(**_LENGTH, doc="shaft axis above the mounting face (block: half the height; "
                                     "pillow: 0.7 × body diameter)"),
    "base_length_mm": Field.number(**_LENGTH, doc="pillow: length of the foot across the shaft (default 2.5 × body "
                                   "diameter)"),
    "offset_mm": Field.number("mm", -1e4, 1e4, doc="axial position of the housing's centre from the bearing's (default 0)"),
    "end_left": Field.choice("air", "mounted", "adiabatic", doc="left end face (flange: mounted by default)"),
    "end_right": Field.choice("air", "mounted", "adiabatic", doc="right end face (default air)"),
    "mounting": Field.choice("frame", "none", doc="bolted to a frame at ambient (default) or not"),
    "mounting_h_W_m2K": Field.number("W/(m² K)", 0.0, 1e7, lo_open=True, doc="mounting joint (default 3600, "
                                     "Bergman Table 3.2)"),
    "frame_material": Field.text("material of the frame (default steel-c45)"),
    "air": Field.choice("still", "forced", doc="air around the housing"),
    "air_speed_m_s": Field.number("m/s", 0.0, 100.0, lo_open=True, doc="forced air speed"),
    "emissivity": Field.number("-", 0.0, 1.0, lo_open=True, doc="of the housing's outside (default 0.8)"),
    "interference_um": Field.number("µm", -1e3, 1e3, doc="diametral interference of the outer ring's seat, negative: "
                                    "clearance (default: probable H7 fit, N7 for a rotating outer ring)"),
    "fit_h_W_m2K": Field.number("W/(m² K)", 0.0, 1e8, lo_open=True, doc="the seat's joint conductance, given"),
}


def network_path(name: str, scene_path: str | None = None) -> Path:
    """File of a bundled network name or of a path (absolute, relative to the scene file, else to
    the working directory); InputError naming ``thermal.network`` when there is none."""
    names = names_in(data_dir("networks"))
    if name in names:
        return (data_dir("networks") / f"{name}.toml").resolve()
    path = Path(name)
    if scene_path and not path.is_absolute():
        path = Path(scene_path).resolve().parent / path
    if not path.is_file():
        raise InputError("thermal.network", name, f"unknown network; known: {', '.join(names)} "
                         "or a path to a .toml file")
    return path.resolve()


def heat_receiving_nodes(nodes) -> set:
    """Nodes that receive the loss heat (contact, ball and mixture roles, :data:`ROLES`)."""
    return {next((c for c in cands if c in nodes), None) for cands in ROLES.values()} - {None}


def _impose(spec: dict, fixed: dict, name: str) -> None:
    """Turn the nodes of ``fixed`` (node → °C, measured) into fixed-temperature nodes, in place.

    This is how seed 004 (Darul et al. 2024, §4.5) uses its network: the inner- and outer-ring
    thermocouple readings are boundary conditions and the network gives the ball and mixture
    temperatures.  Nodes that receive the loss heat cannot be imposed — their heat would vanish
    into the boundary; impose the ring node next to them."""
    nodes = spec.get("nodes", {})
    sinks = heat_receiving_nodes(nodes)
    for node, T in fixed.items():
        if node not in nodes:
            raise InputError(f"thermal.fixed_C.{node}", T, f"no node '{node}' in network {name}; known: "
                             f"{', '.join(nodes)}")
        if node in sinks:
            raise InputError(f"thermal.fixed_C.{node}", T, "this node receives the loss heat and cannot be imposed; "
                             "impose a ring/housing node instead (e.g. inner_ring, outer_ring), or set "
                             "operation.T_C to prescribe the contact temperature")
        kept = {k: v for k, v in nodes[node].items() if k in _KEEP_ON_IMPOSE}
        kept["T_C"] = T if isinstance(T, str) else float(T)     # a number, or an expression of the context
        kept["source"] = "imposed by the scene (thermal.fixed_C)"
        nodes[node] = kept


def _override(spec: dict, parameters: dict, name: str) -> None:
    """Apply ``"<element or node>.<parameter>" = value`` overrides, in place."""
    elements = spec.get("elements", [])
    nodes = spec.get("nodes", {})
    read = set()
    for key, val in parameters.items():
        if "." not in key:                # a context value the network reads as scene.<key>
            read = read or _scene_names(spec)
            if key not in read:
                raise InputError(f"thermal.parameters.{key}", val, f"network {name} reads no scene value '{key}' "
                                 f"(it reads {', '.join(sorted(read)) or 'none'}); a node's or element's parameter is "
                                 "'<name>.<parameter>'")
            continue
        target, param = key.rsplit(".", 1)
        hits = [e for e in elements if e.get("name") == target]
        if target in nodes:
            hits.append(nodes[target])
        if not hits:
            known = [e.get("name") for e in elements] + list(nodes)
            raise InputError(f"thermal.parameters.{key}", val, f"no element or node '{target}' in network "
                             f"{name}; known: {', '.join(str(k) for k in known)}")
        for h in hits:
            if param not in h:
                raise InputError(f"thermal.parameters.{key}", val,
                                 f"'{target}' has no parameter '{param}'; it has: {', '.join(sorted(h))}")
            h[param] = val
            if isinstance(h.get("uncertainty"), dict):      # the scene's value replaces the estimate and its range
                h["uncertainty"] = {k: v for k, v in h["uncertainty"].items() if k != param}


def _scene_names(spec) -> set:
    """The scene values a network's expressions read (``scene.<name>`` in any of its strings)."""
    out: set = set()

    def walk(v):
        if isinstance(v, str):
            out.update(re.findall(r"\bscene\.([A-Za-z_]\w*)", v))
        elif isinstance(v, dict):
            for x in v.values():
                walk(x)
        elif isinstance(v, (list, tuple)):
            for x in v:
                walk(x)
    walk(spec)
    return out


def network_spec(network: str, scene_path: str | None = None, *, parameters: dict | None = None,
                 fixed_C: dict | None = None) -> dict:
    """A network's table with parameter overrides applied and measured temperatures imposed.

    Parameters
    ----------
    network : str       bundled network name or path (see :func:`network_path`)
    scene_path : str    the scene file, for relative paths
    parameters : dict   ``"<element or node>.<parameter>" = value`` (``[thermal.parameters]``)
    fixed_C : dict      node → imposed temperature [°C] (``[thermal] fixed_C``)

    Returns
    -------
    dict   a fresh copy (the caller may change it)

    >>> spec = network_spec("one_node", parameters={"bearing_to_ambient.G_W_K": 0.8})
    >>> spec["elements"][0]["G_W_K"]
    0.8
    """
    spec = network_table(network, scene_path)
    _impose(spec, dict(fixed_C or {}), str(network))
    _override(spec, dict(parameters or {}), str(network))
    return spec


def network_table(network, scene_path: str | None = None) -> dict:
    """A fresh copy of a network's table: a file's (bundled name or path), or built from a
    :class:`~thermobear.thermal.builders.Machine`."""
    if isinstance(network, Machine):
        return build_network(network).spec
    return copy.deepcopy(read_toml(str(network_path(str(network), scene_path))))


def network_nodes(network, scene_path: str | None = None) -> list:
    """Node names of a network (no overrides applied)."""
    if isinstance(network, Machine):
        return list(build_network(network).spec["nodes"])
    return list(read_toml(str(network_path(str(network), scene_path))).get("nodes", {}))


def _material(v, where):
    if v is not None and v not in material_names():
        raise InputError(where, v, f"one of the bundled materials: {', '.join(material_names())}")
    return v


def _only_for(sec: dict, where: str, keys: tuple, ok: bool, why: str):
    for k in keys:
        if k in sec and not ok:
            raise InputError(f"{where}.{k}", sec[k], why)


def _housing(h: dict, seals: str = "none") -> Housing:
    """``seals``: the bearing's closures (``bearing.seals``: none, shields or contact seals)."""
    t = h.get("type", "block")
    _only_for(h, "housing", ("height_mm", "depth_mm"), t == "block", f"applies to block housings (type = {t!r})")
    _only_for(h, "housing", ("outer_diameter_mm",), t != "block", "applies to pillow and flange housings (a block "
              "takes height_mm and depth_mm)")
    _only_for(h, "housing", ("base_length_mm",), t == "pillow", f"applies to pillow blocks (type = {t!r})")
    _only_for(h, "housing", ("centre_height_mm",), t != "flange", "a flange housing has no centre height")
    _only_for(h, "housing", ("air_speed_m_s",), h.get("air") == "forced", 'give air = "forced" with an air speed')
    if h.get("air") == "forced" and not h.get("air_speed_m_s", 0.0) > 0:
        raise InputError("housing.air_speed_m_s", h.get("air_speed_m_s"), 'forced air needs a speed > 0 [m/s]')
    mm = {k: (h[f"{k}_mm"] * 1e-3 if f"{k}_mm" in h else None)
          for k in ("axial_length", "height", "depth", "outer_diameter", "centre_height", "base_length")}
    return Housing(type=t, material=_material(h.get("material", "cast-iron-gjl-250"), "housing.material"),
                   offset=h.get("offset_mm", 0.0) * 1e-3, end_left=h.get("end_left"), end_right=h.get("end_right", "air"),
                   mounting=h.get("mounting", "frame"), mounting_h_W_m2K=h.get("mounting_h_W_m2K"),
                   frame_material=_material(h.get("frame_material", "steel-c45"), "housing.frame_material"),
                   air=h.get("air", "still"), air_speed=h.get("air_speed_m_s", 0.0),
                   **({"emissivity": h["emissivity"]} if "emissivity" in h else {}),   # else the builders' estimate
                   interference=h["interference_um"] * 1e-6 if "interference_um" in h else None,
                   fit_h_W_m2K=h.get("fit_h_W_m2K"), seals=seals, **mm)


def _shaft(s: dict) -> Shaft:
    for side in ("left", "right"):
        _only_for(s, "shaft", (f"T_end_{side}_C",), s.get(f"end_{side}") == "fixed",
                  f'applies to a fixed end (end_{side} = "fixed")')
    return Shaft(diameter=s["diameter_mm"] * 1e-3 if "diameter_mm" in s else None, bore=s.get("bore_mm", 0.0) * 1e-3,
                 length_left=s["length_left_mm"] * 1e-3 if "length_left_mm" in s else None,
                 length_right=s["length_right_mm"] * 1e-3 if "length_right_mm" in s else None,
                 material=_material(s.get("material", "steel-c45"), "shaft.material"),
                 end_left=s.get("end_left", "free"), end_right=s.get("end_right", "free"),
                 T_end_left_C=s.get("T_end_left_C"), T_end_right_C=s.get("T_end_right_C"),
                 surface=s.get("surface", "air"),
                 interference=s["interference_um"] * 1e-6 if "interference_um" in s else None,
                 fit_h_W_m2K=s.get("fit_h_W_m2K"))


def check_lubrication_keys(lub: dict, supply: str) -> None:
    """InputError when a lubrication key of ``[lubricant]`` does not apply to the supply."""
    _only_for(lub, "lubricant", ("oil_level_mm", "sump_volume_L"), supply == "oil_bath", f"applies to supply = "
              f'"oil_bath" (supply = {supply!r})')
    _only_for(lub, "lubricant", ("grease_fill",), supply == "grease", f'applies to supply = "grease" (supply = {supply!r})')
    _only_for(lub, "lubricant", ("air_flow_L_min",), supply == "oil_air", f'applies to supply = "oil_air" (supply = '
              f"{supply!r})")
    _only_for(lub, "lubricant", ("oil_feed",), supply == "oil_jet", f'applies to supply = "oil_jet" (supply = {supply!r})')


def lubrication_of(lub: dict, lubricant, supply: str) -> Lubrication:
    """The network's view of the lubrication (``[lubricant]`` keys already typed): the lubricant's
    volumetric heat capacity and conductivity at 40 °C (capacities and grease conduction are fixed
    per network)."""
    check_lubrication_keys(lub, supply)
    T = 40.0
    return Lubrication(supply=supply, feed=lub.get("oil_feed", "jet"), beta=lub.get("jet_penetration"),
                       oil_level=lub["oil_level_mm"] * 1e-3 if "oil_level_mm" in lub else None,
                       sump_volume=lub["sump_volume_L"] * 1e-3 if "sump_volume_L" in lub else None,
                       grease_fill=lub.get("grease_fill"), air_flow=lub.get("air_flow_L_min", 0.0) * 1e-3 / 60.0,
                       rho_cp=float(lubricant.rho(T) * lubricant.cp(T)), k=float(lubricant.k_th(T)))


def machine_from_sections(shaft: dict, housing: dict, lub: dict, *, bearing, lubricant, supply: str, rotating: str,
                          n_rpm: float, T_ambient_C: float, Fa: float, Fr: float, name: str = PARAMETRIC,
                          seals: str = "none") -> Machine:
    """The machine of a scene from its typed ``[shaft]``, ``[housing]`` and ``[lubricant]`` tables
    (edge units converted to SI here, once).  ``n_rpm``, ``T_ambient_C``, ``Fa``, ``Fr``: the scene's
    operating point, at which the discretisation rule estimates the convection and a clearance fit's
    seat pressure (the network reads every operating point's own speed and temperatures)."""
    return Machine(bearing=bearing, shaft=_shaft(shaft), housing=_housing(housing, seals),
                   lubrication=lubrication_of(lub, lubricant, supply), rotating=rotating, n_rpm=float(n_rpm),
                   T_ambient_C=float(T_ambient_C), Fa=float(Fa), Fr=float(Fr), name=name)
