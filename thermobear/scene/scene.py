r"""Scene files: a bearing, its lubricant, loads, speed, and how heat leaves it.

A scene is a TOML file with units in the key names, converted to SI once here.  Every section
and every inline table is checked by one strict schema (:mod:`thermobear.schema`): an unknown key
is refused with the list of accepted ones, every number must be a TOML number in its range,
every boolean a TOML boolean, every choice one of its listed values.  Sections (the keys of
:data:`SECTIONS`; ``examples/README.md`` has the table)::

    [scene]      name, description, source
    [bearing]    catalog = "7210" and/or inline geometry (thermobear.contact.geometry keys); seals,
                 seal_sides, seal_diameter_mm; cage, cage_land_width_mm, cage_land_clearance_mm; shaft_fit,
                 housing_fit; arrangement, preload_N, preload (one bearing of a preloaded pair: scene/pair.py)
    [lubricant]  name = "seed004-mineral" or inline properties (thermobear.lubrication.lubricant keys);
                 supply, flow_L_h, T_in_C, Rq_ball_um, Rq_ring_um, mu_boundary, mu_full_film, K_rs, oil_level_mm
    [operation]  n_rpm, Fa_N, Fr_N, M_Nm (tilt free), Fz_N, My_Nm (out of plane; tilt free), rotating,
                 T_C (prescribed temperature), contamination (ISO 281 e_C level)
    [thermal]    network, T_ambient_C, [thermal.parameters], fixed_C = { node = °C }
    [shaft]      the shaft, [housing] the housing: the thermal network built from these dimensions
                 (network = "parametric", implied by either section; lubricant keys oil_level_mm,
                 sump_volume_L, grease_fill, air_flow_L_min, oil_feed)
    [models]     overrides of the model choice (thermobear.models.choose_models)
    [rig]        J_kg_m2, [rig.map] channel = "node" | "input" | "ignore" | "impose:<node>"

A section's estimated numbers may say how far they may lie: ``uncertainty.<key> = { ... }`` next to
them (:func:`thermobear.schema.check_uncertainty`; [operation], [lubricant], [thermal], [rig]),
collected in :attr:`Scene.uncertainty` by address (``"thermal.T_ambient_C"``).

Every bad value raises :class:`~thermobear.errors.InputError` naming the field, the value and
what is accepted; names the scene uses inside its network (parameters, imposed nodes, rig map
targets) are checked against the network when the scene is read.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from thermobear import validity
from thermobear.contact.fits import HOUSING_CLASSES, SHAFT_CLASSES
from thermobear.contact.geometry import BallBearing, bearing, bearing_from_dict, bearing_table
from thermobear.contact.hertz import METHODS as HERTZ_METHODS
from thermobear.errors import InputError
from thermobear.files import read_toml
from thermobear.losses.cage import GUIDANCE
from thermobear.rating.iso281 import CONTAMINATION_LEVELS
from thermobear.losses.local import ROLLING_MODELS, TRACTION_MODELS
from thermobear.losses.seals import BALL_SEALS, CONTACT_SEALS, seal_constants
from thermobear.lubrication.lubricant import FIELDS as LUBRICANT_FIELDS
from thermobear.lubrication.lubricant import Lubricant, lubricant
from thermobear.schema import Field, check_table, check_uncertainty, check_value
from thermobear.scene.network import (HOUSING_FIELDS, PARAMETRIC, SHAFT_FIELDS, check_lubrication_keys,
                                     lubrication_of, machine_from_sections, network_nodes, network_spec)
from thermobear.scene.pair import PAIR_FIELDS, PAIR_WITH, check_pair
from thermobear.thermal.builders import Machine

__all__ = ["Scene", "load_scene", "scene_from_dict", "SUPPLIES", "SECTIONS", "MODEL_FIELDS", "RIG_TARGETS",
           "SHAFT_FIELDS", "HOUSING_FIELDS", "WITH_KEYS", "FILE_KEYS"]

SUPPLIES = ("oil_jet", "grease", "oil_bath", "oil_air", "dry_film")
_T_LO, _T_HI = validity.T_LUBRICANT_REFUSE_C


def _temperature(doc):
    return Field.number("°C", _T_LO, _T_HI, doc=doc)


#: ``[models]``: every key can be forced (``--set models.<key>=<value>`` on the command line).
MODEL_FIELDS = {
    "rolling": Field.choice(*ROLLING_MODELS, doc="hydrodynamic rolling force model"),
    "hertz": Field.choice(*HERTZ_METHODS, doc="Hertz solution"),
    "load_model": Field.choice("closed_form", "jones_harris", "film", doc="load distribution model"),
    "drag": Field.flag("drag of the balls in the oil–air mixture"),
    "kinematics": Field.choice("outer", "inner", "radial", doc="ball spin control"),
    "stiffness": Field.choice("nominal", "per_ball", doc="contact stiffness at the nominal or each ball's angle"),
    "high_speed": Field.flag("Jones high-speed ball equilibrium"),
    "losses": Field.choice("local", "skf", doc="per-contact local model or SKF 2004 global model"),
    "churning": Field.flag("churning of the balls in an oil bath (needs an oil level)"),
    "seals": Field.flag("friction of contact seals (SKF 2004)"),
    "cage": Field.flag("cage land and ball-pocket friction (ring-guided cage)"),
    "skf_R1": Field.number("-", 0.0, None, lo_open=True, doc="SKF rolling constant R1"),
    "skf_S1": Field.number("-", 0.0, None, lo_open=True, doc="SKF sliding constant S1"),
    "skf_mu_EHL": Field.number("-", 0.0, 1.0, lo_open=True, doc="SKF full-film sliding friction"),
    "traction": Field.choice(*TRACTION_MODELS, doc="full-film traction: constant mu_full_film or the oil's Eyring law"),
    "inlet_heating": Field.flag("thermal film reduction by inlet shear heating (Gupta et al. 1992)"),
    "starvation": Field.flag("kinematic replenishment: SKF phi_rs on the rolling force"),
    "clearance": Field.choice("given", "mounted", "operating", doc="clearance of the load distribution: the "
                              "bearing's as given, mounted (fits at 20 °C), or operating (fits, ring temperatures "
                              "and speed of the solution: a fixed point; deep groove bearings)"),
}

_UNCERTAINTY = Field.table("ranges of estimated values: uncertainty.<key> = { range | factor | offset = [lo, hi], "
                           "distribution, source } (thermobear.schema.check_uncertainty)")

#: The supplies that feed an oil (a grease there is refused: its thickener does not flow to the contacts)
OIL_SUPPLIES = ("oil_bath", "oil_jet", "oil_air")

_SUPPLY_FIELDS = {
    "supply": Field.choice(*SUPPLIES, doc="lubrication method"),
    "flow_L_h": Field.number("L/h", 0.0, 1e5, doc="oil flow through the bearing"),
    "T_in_C": _temperature("oil inlet temperature"),
    "Rq_ball_um": Field.number("µm", 0.0, 10.0, doc="RMS roughness of the balls"),
    "Rq_ring_um": Field.number("µm", 0.0, 10.0, doc="RMS roughness of the races"),
    "mu_boundary": Field.number("-", 0.0, 1.0, doc="boundary friction coefficient (seed 000 eq 18)"),
    "mu_full_film": Field.number("-", 0.0, 1.0, doc="full-film friction coefficient (seed 000 eq 18)"),
    "K_rs": Field.number("-", 0.0, 1e-6, doc="replenishment constant of SKF's starvation factor phi_rs (default SKF "
                         "2004: 3e-8 oil jet and oil bath, 6e-8 grease and oil-air; a rig's own: calibrate --param K_rs)"),
    "oil_level_mm": Field.number("mm", 0.0, 1e4, doc="oil-bath level above the lowest point of the outer-ring "
                                 "raceway (SKF's H), horizontal shaft; not given: no churning (a parametric housing "
                                 "with an oil bath needs it)"),
    "jet_penetration": Field.number("-", 0.0, 1.0, lo_open=True, doc="share of the supplied jet flow that passes "
                                    "through the bearing (seed 004 §4.5 β); default 1: flow_L_h passes whole"),
    "sump_volume_L": Field.number("L", 0.0, 1e5, lo_open=True, doc="oil bath: volume of the bath (default: the oil "
                                  "in the housing's bore below the level)"),
    "grease_fill": Field.number("-", 0.0, 1.0, lo_open=True, doc="grease: fill of the bearing's free volume "
                                "(default 0.3)"),
    "air_flow_L_min": Field.number("L/min", 0.0, 1e5, doc="oil–air / oil mist: carrier air flow (at 20 °C, 1 atm)"),
    "oil_feed": Field.choice("jet", "circulating", doc="oil_jet: a jet (penetration 0.4) or circulating oil through "
                             "the bearing (all of it)"),
}

#: ``[bearing]`` keys besides the geometry: seals and cage (defaults: no seal; a ball-centred cage).
_BEARING_FIELDS = {
    "seals": Field.choice(*BALL_SEALS, doc="seal type: none, shield (non-contact) or an SKF ball-bearing contact seal"),
    "seal_sides": Field.integer("-", 0, 2, doc="number of seals (default 2 with seals, 0 without)"),
    "seal_diameter_mm": Field.number("mm", 0.0, None, lo_open=True, doc="seal counterface diameter d_s (SKF "
                                     "product table d1/d2); default estimated d + 0.25 (D - d)"),
    "cage": Field.choice(*GUIDANCE, doc="cage centring: balls (default), inner_ring or outer_ring land"),
    "shaft_fit": Field.choice(*SHAFT_CLASSES, doc="ISO 286 tolerance class of the shaft seat (operating clearance); "
                              "default: the catalogue-typical fit for the load"),
    "housing_fit": Field.choice(*HOUSING_CLASSES, doc="ISO 286 tolerance class of the housing seat; default: the "
                                "catalogue-typical fit for the load"),
    "cage_land_width_mm": Field.number("mm", 0.0, None, lo_open=True, doc="axial width of the cage lands, "
                                       "summed; default estimated B/4"),
    "cage_land_clearance_mm": Field.number("mm", 0.0, None, lo_open=True, doc="radial cage-land clearance; "
                                           "default estimated 0.5 % of the land diameter"),
    **PAIR_FIELDS,
}

#: Every section's keys (``bearing``: ``catalog`` plus the geometry keys of
#: :func:`thermobear.contact.geometry.bearing_from_dict`, checked there; ``lubricant``: the supply
#: keys plus :data:`thermobear.lubrication.lubricant.FIELDS`).
SECTIONS = {
    "scene": {"name": Field.text("scene name"), "description": Field.text(), "source": Field.text()},
    "bearing": {"catalog": Field.text("catalogue designation (thermobear list bearings)"), **_BEARING_FIELDS},
    "lubricant": {**_SUPPLY_FIELDS, **LUBRICANT_FIELDS},
    "operation": {
        "uncertainty": _UNCERTAINTY,
        "n_rpm": Field.number("rpm", 0.0, None, doc="speed of the rotating ring", required=True),
        "Fa_N": Field.number("N", 0.0, None, doc="axial load"),
        "Fr_N": Field.number("N", 0.0, None, doc="radial load (towards ψ = 0)"),
        "M_Nm": Field.number("N m", doc="tilting moment (tilt free); absent: tilt held"),
        "Fz_N": Field.number("N", doc="radial load along z, at ψ = 90° from Fr (five degrees of freedom)"),
        "My_Nm": Field.number("N m", doc="moment about y, tilting in the x–z plane (tilt free); absent with M_Nm: "
                              "tilts held"),
        "contamination": Field.choice(*CONTAMINATION_LEVELS, doc="ISO 281:2007 cleanliness level of the "
                                      "lubricant (e_C, life modification factor a_ISO); default normal_cleanliness"),
        "rotating": Field.choice("inner", "outer", doc="rotating ring"),
        "T_C": _temperature("prescribed contact temperature (no thermal network)"),
    },
    "thermal": {
        "uncertainty": _UNCERTAINTY,
        "network": Field.text('bundled network name, a .toml path, or "parametric" (built from [shaft], [housing])'),
        "T_ambient_C": _temperature("ambient temperature"),
        "parameters": Field.table('"<element or node>.<parameter>" = value overrides'),
        "fixed_C": Field.table("node = measured temperature [°C], imposed"),
    },
    "models": MODEL_FIELDS,
    "shaft": SHAFT_FIELDS,
    "housing": HOUSING_FIELDS,
    "rig": {"uncertainty": _UNCERTAINTY,
            "J_kg_m2": Field.number("kg m^2", 0.0, None, lo_open=True, doc="rotating inertia (spin-down)"),
            "map": Field.table('log channel = "node" | "input" | "ignore" | "impose:<node>"')},
}
#: Special targets of ``[rig.map]`` besides node names (``"impose:<node>"`` imposes the channel).
RIG_TARGETS = ("input", "ignore")
_IMPOSE = "impose:"


@dataclass(frozen=True)
class Scene:
    """A validated scene in SI units.

    Attributes
    ----------
    name : str
    bearing : BallBearing
    lubricant : Lubricant
    supply : str                  lubrication method (``SUPPLIES``)
    n_rpm : float                 speed of the rotating ring [rpm] (edge unit, kept for reporting)
    omega : float                 its angular speed [rad/s]
    rotating : str                ``"inner"`` or ``"outer"``
    Fa, Fr : float                axial / radial load [N]
    M : float | None              tilting moment [N m]; None holds the tilt (with My None)
    Fz : float                    radial load along z, at ψ = 90° [N]
    My : float | None             moment about y [N m]; M and My None hold both tilts, either frees both
    contamination : str           ISO 281 cleanliness level (e_C of a_ISO)
    shaft_fit, housing_fit : str | None   ISO 286 tolerance classes of the seats (None: a machine's seats, else the
                                  catalogue-typical fit for the load, :func:`thermobear.coupled.ratings.scene_clearance`)
    arrangement : str | None      the bearing is one of a preloaded pair (``back_to_back``, ``face_to_face``;
                                  :mod:`thermobear.scene.pair`): Fa, Fr act on the pair; None: a single bearing
    preload_force : float | None  the pair's cold mounted preload [N]; preload_kind: ``position`` (None) or ``spring``;
                                  pair_spacer: the spacers' length between the pair's bearings [m] (None: 0)
    T_C : float | None            prescribed contact temperature [°C] (None: solve the thermal network)
    oil_flow : float              supplied oil flow [m^3/s] (oil jet)
    jet_penetration : float       share of it that passes through the bearing [-] (seed 004 §4.5 β;
                                  default 1): the flow of Parker's oil fraction (drag)
    oil_level : float | None      oil-bath level above the lowest point of the outer-ring raceway [m]
                                  (SKF's H; horizontal shaft); None: not given (no churning)
    T_oil_in_C : float | None     oil inlet temperature [°C]
    T_ambient_C : float           ambient temperature [°C]
    Rq_ball, Rq_ring : float      RMS roughness [m]
    mu_boundary, mu_full_film : float   friction coefficients of seed 000 eq 18 [-]
    K_rs : float | None           replenishment constant of SKF's Φ_rs [-] (None: SKF's of the supply,
                                  :func:`thermobear.models.replenishment_constant`)
    network : str | Machine | None  thermal network name or path, or the machine a network is built
                                  from (``[shaft]``, ``[housing]``; ``str(network) == "parametric"``)
    network_parameters : dict     overrides of the network's parameters
    T_fixed_C : dict              node → imposed temperature [°C] (measured rig temperatures; the
                                  node becomes a fixed-temperature boundary of the network)
    models : dict                 model overrides (see thermobear.models.choose_models)
    seals : str                   seal type (``none``, ``shield`` or an SKF contact seal)
    seal_sides : int              number of seals, 0–2
    seal_diameter : float | None  seal counterface diameter [m] (None: estimated)
    cage : str                    cage centring: ``balls``, ``inner_ring`` or ``outer_ring``
    cage_land_width, cage_land_clearance : float | None   cage land width and radial clearance [m]
                                  (None: estimated)
    rig_J_kg_m2 : float | None    rotating inertia of a spin-down rig [kg m²]
    rig_map : dict                log channel → node or special target (``[rig.map]``)
    uncertainty : dict            ``"<section>.<key>"`` → :class:`~thermobear.schema.Uncertainty` of the
                                  scene's estimated numbers (the lubricant, bearing, network and materials
                                  carry their own)
    samples : dict                drawn values moving the lubricant's and the network's estimated values
                                  at this operating point, by address (``"lubricant.rho15_kg_m3"``,
                                  ``"nodes.<n>.<key>"``, ``"elements.<e>.<key>"``, ``"materials.<m>.<key>"``):
                                  set by :mod:`thermobear.coupled.uncertainty`, applied point by point
                                  within a family
    source : str                  where the scene comes from
    path : str | None             file it was read from
    raw : dict                    the parsed TOML (for tools that need more)
    """

    name: str
    bearing: BallBearing
    lubricant: object
    supply: str
    n_rpm: float
    rotating: str = "inner"
    Fa: float = 0.0
    Fr: float = 0.0
    M: float | None = None
    T_C: float | None = None
    Fz: float = 0.0
    My: float | None = None
    contamination: str = "normal_cleanliness"
    shaft_fit: str | None = None
    housing_fit: str | None = None
    arrangement: str | None = None
    preload_force: float | None = None
    preload_kind: str | None = None
    pair_spacer: float | None = None
    oil_flow: float = 0.0
    jet_penetration: float = 1.0
    T_oil_in_C: float | None = None
    T_ambient_C: float = 20.0
    Rq_ball: float = 0.05e-6
    Rq_ring: float = 0.1e-6
    mu_boundary: float = 0.11
    mu_full_film: float = 0.05
    K_rs: float | None = None
    network: str | Machine | None = None
    network_parameters: dict = field(default_factory=dict)
    T_fixed_C: dict = field(default_factory=dict)
    models: dict = field(default_factory=dict)
    oil_level: float | None = None
    seals: str = "none"
    seal_sides: int = 0
    seal_diameter: float | None = None
    cage: str = "balls"
    cage_land_width: float | None = None
    cage_land_clearance: float | None = None
    rig_J_kg_m2: float | None = None
    rig_map: dict = field(default_factory=dict)
    uncertainty: dict = field(default_factory=dict)
    samples: dict = field(default_factory=dict)
    source: str = ""
    path: str | None = None
    raw: dict = field(default_factory=dict, repr=False, compare=False)

    @property
    def omega(self) -> float:
        """Angular speed of the rotating ring [rad/s]."""
        return self.n_rpm * np.pi / 30.0

    @property
    def omega_i(self) -> float:
        """Inner-ring speed [rad/s]."""
        return self.omega if self.rotating == "inner" else 0.0

    @property
    def omega_o(self) -> float:
        """Outer-ring speed [rad/s]."""
        return self.omega if self.rotating == "outer" else 0.0

    def with_(self, **changes) -> "Scene":
        """Copy with values changed, in the scene's own edge units, each checked as in a scene file.

        Accepted keys: n_rpm, Fa (or Fa_N), Fr (Fr_N), M (M_Nm; None holds the tilt), T_C (None: solve
        the network), T_oil_in_C, T_ambient_C, oil_flow_L_h, jet_penetration, oil_level_mm (None: not
        given), Rq_ball_um, Rq_ring_um, mu_boundary, mu_full_film, K_rs (None: SKF's), rotating, supply, lubricant (name, table
        or Lubricant), bearing (catalogue name, table or BallBearing), seals, seal_sides, cage, shaft_fit, housing_fit
        (ISO 286 classes; None: not stated), arrangement, preload_N, preload (a pair; None clears), network,
        network_parameters (merged), T_fixed_C (node → °C, replaces; ``{}`` clears), models (merged) and
        samples (address → number, replaces).

        >>> from thermobear.scene import load_scene
        >>> import thermobear
        >>> s = load_scene(thermobear.example_path("seed004_oil_jet_7210.toml"))
        >>> s.with_(n_rpm=6500, Fr=1500).Fr
        1500.0
        """
        kw = {}
        for k, v in sorted(changes.items(), key=lambda kv: kv[0] == "seal_sides"):   # sides after seals
            k = _ALIASES.get(k, k)
            if k not in _WITH:
                raise InputError(f"scene.with_({k})", v, f"unknown override; accepted: {', '.join(_WITH)}")
            kw.update(_WITH[k](self, v, k))
        new = dataclasses.replace(self, **kw)
        if new.network == PARAMETRIC:                                   # named now: build it from the sections
            new = dataclasses.replace(new, network=_machine(new))
        elif isinstance(new.network, Machine) and _MACHINE_KEYS & set(kw):
            new = dataclasses.replace(new, network=_machine(new, at=new.network))  # the machine follows its bearing
        _check_scene(new, network_changed=bool({"network", "network_parameters", "T_fixed_C", *_MACHINE_KEYS} & set(kw)))
        return new


# --------------------------------------------------------------------------- sections → Scene
def _with_number(section, key, attr, scale=1.0, nullable=False):
    """An override of ``[section] key``, checked by that key's field (errors name the override)."""
    def f(scene, v, name):
        if v is None and nullable:
            return {attr: None}
        return {attr: check_value(v, SECTIONS[section][key], name) * scale}
    f.address = f"{section}.{key}"
    return f


def _with_table(attr):
    def f(scene, v, name):
        if not isinstance(v, dict):
            raise InputError(name, v, "must be a table (dict)")
        if attr == "models":
            return {attr: {**scene.models, **check_table(v, MODEL_FIELDS, "models")}}
        if attr == "network_parameters":
            return {attr: {**scene.network_parameters, **_parameters(v)}}
        return {attr: _fixed(v)}
    return f


def _with_object(attr):
    def f(scene, v, name):
        if attr == "lubricant":
            if isinstance(v, Lubricant):
                return {attr: v}
            return {attr: _lubricant_of(v if isinstance(v, dict) else {"name": v}, name)}
        if isinstance(v, BallBearing):
            return {attr: v}
        if isinstance(v, str):
            return {attr: bearing(v)}
        return {attr: _bearing_of(v)}
    return f


_ALIASES = {"Fa_N": "Fa", "Fr_N": "Fr", "M_Nm": "M", "Fz_N": "Fz", "My_Nm": "My"}
_WITH = {
    "n_rpm": _with_number("operation", "n_rpm", "n_rpm"),
    "Fa": _with_number("operation", "Fa_N", "Fa"),
    "Fr": _with_number("operation", "Fr_N", "Fr"),
    "M": _with_number("operation", "M_Nm", "M", nullable=True),
    "Fz": _with_number("operation", "Fz_N", "Fz"),
    "My": _with_number("operation", "My_Nm", "My", nullable=True),
    "contamination": lambda s, v, name: {"contamination": check_value(v, SECTIONS["operation"]["contamination"],
                                                                      name)},
    "T_C": _with_number("operation", "T_C", "T_C", nullable=True),
    "T_oil_in_C": _with_number("lubricant", "T_in_C", "T_oil_in_C", nullable=True),
    "T_ambient_C": _with_number("thermal", "T_ambient_C", "T_ambient_C"),
    "oil_flow_L_h": _with_number("lubricant", "flow_L_h", "oil_flow", scale=1e-3 / 3600.0),
    "Rq_ball_um": _with_number("lubricant", "Rq_ball_um", "Rq_ball", scale=1e-6),
    "Rq_ring_um": _with_number("lubricant", "Rq_ring_um", "Rq_ring", scale=1e-6),
    "mu_boundary": _with_number("lubricant", "mu_boundary", "mu_boundary"),
    "mu_full_film": _with_number("lubricant", "mu_full_film", "mu_full_film"),
    "K_rs": _with_number("lubricant", "K_rs", "K_rs", nullable=True),
    "samples": lambda s, v, name: {"samples": check_table(v, {}, name, extra=lambda k: Field.number(doc="drawn value"))},
    "oil_level_mm": _with_number("lubricant", "oil_level_mm", "oil_level", scale=1e-3, nullable=True),
    "jet_penetration": _with_number("lubricant", "jet_penetration", "jet_penetration"),
    "seals": lambda s, v, name: {"seals": check_value(v, SECTIONS["bearing"]["seals"], name),
                                 "seal_sides": _default_sides(check_value(v, SECTIONS["bearing"]["seals"], name))},
    "seal_sides": lambda s, v, name: {"seal_sides": check_value(v, SECTIONS["bearing"]["seal_sides"], name)},
    "cage": lambda s, v, name: {"cage": check_value(v, SECTIONS["bearing"]["cage"], name)},
    "shaft_fit": lambda s, v, name: {"shaft_fit": None if v is None else check_value(v, SECTIONS["bearing"]["shaft_fit"],
                                                                                        name)},
    "housing_fit": lambda s, v, name: {"housing_fit": None if v is None else
                                       check_value(v, SECTIONS["bearing"]["housing_fit"], name)},
    "rotating": lambda s, v, name: {"rotating": check_value(v, SECTIONS["operation"]["rotating"], name)},
    "supply": lambda s, v, name: {"supply": check_value(v, SECTIONS["lubricant"]["supply"], name)},
    "network": lambda s, v, name: {"network": check_value(v, SECTIONS["thermal"]["network"], name)},
    "lubricant": _with_object("lubricant"),
    "bearing": _with_object("bearing"),
    "network_parameters": _with_table("network_parameters"),
    "T_fixed_C": _with_table("T_fixed_C"),
    "models": _with_table("models"),
    **PAIR_WITH,
}
#: the keys :meth:`Scene.with_` accepts, with their aliases in the scene file's units (Fa_N, ...)
WITH_KEYS = tuple(_WITH) + tuple(_ALIASES)
#: a scene file's number as ``"<section>.<key>"`` (``"lubricant.flow_L_h"``) → the :meth:`Scene.with_` key that sets it
FILE_KEYS = {f.address: k for k, f in _WITH.items() if hasattr(f, "address")}


def _lubricant_of(sec: dict, where: str):
    """The lubricant of a ``[lubricant]`` table without its supply keys: a catalogue name alone, or
    inline properties (the name then labels them; uncertainty entries on them go with them)."""
    props = {k: v for k, v in sec.items() if k not in _SUPPLY_FIELDS}
    unc = {k: v for k, v in props.pop("uncertainty", {}).items() if k not in _SUPPLY_FIELDS}
    if unc:
        props["uncertainty"] = unc
    if not props:
        raise InputError(f"{where}.name", None, "give a lubricant name or its properties (nu40_cSt, nu100_cSt, ...)")
    typed = check_table(props, LUBRICANT_FIELDS, where)
    if set(typed) == {"name"}:
        return lubricant(typed["name"])
    if not ({"nu40_cSt", "eta_ref_Pa_s", "eta_Pa_s"} & set(props)):
        raise InputError(f"{where}", ", ".join(sorted(set(props) - {"name"})),
                         "with a catalogue name give no other lubricant properties; inline properties need "
                         "nu40_cSt, nu100_cSt, rho15_kg_m3 (or eta_ref_Pa_s at T_ref_C)")
    return Lubricant.from_dict(props, where=where)


def _default_sides(seals: str) -> int:
    """Seals on the bearing when the scene does not say: 2 for a sealed or shielded bearing (…-2RS1,
    …-2Z), 0 without seals."""
    return 0 if seals == "none" else 2


def _bearing_of(sec: dict) -> BallBearing:
    check_value(sec, Field.table(), "bearing")
    sec = {k: v for k, v in sec.items() if k not in _BEARING_FIELDS}
    if "catalog" in sec:
        name = check_value(sec["catalog"], SECTIONS["bearing"]["catalog"], "bearing.catalog")
        base = bearing(name)
        over = {k: v for k, v in sec.items() if k != "catalog"}
        if not over:
            return base
        table = bearing_table(name)
        if ("clearance_group" in over and not {"Pd_mm", "alpha0_deg"} & set(over)
                and table.get("kind", "deep_groove") == "deep_groove"):
            # the scene's clearance group replaces a clearance the catalogue states (a seed bearing's Pd_mm): an
            # explicit Pd_mm would win over it inside one table, and the group would be dropped silently
            gone = ("Pd_mm", "alpha0_deg")
            table = {k: ({u: r for u, r in v.items() if u not in gone} if k == "uncertainty" else v)
                     for k, v in table.items() if k not in gone}
        unc = table.get("uncertainty", {})       # a value the scene gives replaces the estimate and its range
        unc = {**{k: v for k, v in unc.items() if k not in over}, **over.get("uncertainty", {})}
        merged = {**table, **over, "uncertainty": unc} if unc else {k: v for k, v in {**table, **over}.items()
                                                                     if k != "uncertainty"}
        try:
            return bearing_from_dict(merged, name=base.name, where="bearing")
        except InputError as e:              # the catalogue's bearing holds: say what the scene changed
            changed = [f"{k} = {v!r} (catalogue: {table[k]!r})" if k in table else f"{k} = {v!r}"
                       for k, v in over.items() if k != "uncertainty" and table.get(k) != v]
            raise InputError(e.field, e.value, f"{e.expected}; the scene changes {base.name}'s "
                             + ", ".join(changed)) from None
    return bearing_from_dict(sec, name=sec.get("name", "custom"), where="bearing")


def _scene_uncertainty(d: dict) -> dict:
    """``"<section>.<key>"`` → Uncertainty of the scene's own numbers (a [lubricant] section's entries on
    lubricant properties belong to its inline lubricant)."""
    out = {}
    for sec in ("operation", "lubricant", "thermal", "rig"):
        t = d.get(sec, {})
        table = t.get("uncertainty", {})
        if sec == "lubricant" and isinstance(table, dict):
            table = {k: v for k, v in table.items() if k in _SUPPLY_FIELDS}
        fields = {k: f for k, f in SECTIONS[sec].items() if f.kind in ("number", "integer") and k in t}
        if sec == "lubricant":
            fields = {k: f for k, f in fields.items() if k in _SUPPLY_FIELDS}
        out.update({f"{sec}.{k}": u for k, u in check_uncertainty(table, fields, sec).items()})
    return out


def _parameters(params: dict) -> dict:
    """``[thermal.parameters]``: name → finite number."""
    return check_table(params, {}, "thermal.parameters", extra=lambda k: Field.number(doc="network parameter"))


def _fixed(v) -> dict:
    """``[thermal] fixed_C``: node → imposed temperature [°C] (measured rig temperatures)."""
    if v is None:
        return {}
    return check_table(v, {}, "thermal.fixed_C", extra=lambda k: _temperature("imposed node temperature"))


def _rig_map(v) -> dict:
    return check_table(v, {}, "rig.map", extra=lambda k: Field.text("node name, input, ignore or impose:<node>"))


def _default_penetration(supply: str, lsec: dict) -> float:
    """Share of the supplied oil that passes through the bearing when the scene does not say: 0.4 for a
    jet (estimated: seed 004 §4.5's β after Brossier et al. 2021), all of it for circulating oil and the
    other supplies."""
    return 0.4 if supply == "oil_jet" and lsec.get("oil_feed", "jet") == "jet" else 1.0


#: The scene values a parametric network is built from (besides its [shaft] and [housing] tables): a
#: :meth:`Scene.with_` of any of them builds the machine again (seals and shields close the cavity and add
#: a seal node, the oil level sets the sump and the balls' share in the bath, the jet's penetration the
#: oil stream through the bearing).
_MACHINE_KEYS = frozenset({"bearing", "lubricant", "supply", "rotating", "seals", "oil_level", "jet_penetration"})


def _machine(s: Scene, at: Machine | None = None) -> Machine:
    """The machine of a parametric scene, from its ``[shaft]``, ``[housing]`` and ``[lubricant]`` tables
    and the scene's bearing, lubrication, seals and oil level, at the scene's own operating point (what the
    discretisation rule reads) — or, built again for an override (``at``: the machine the scene had), at
    that machine's operating point, so that an override changes no cell count (a schedule step, a sweep's
    points: one network)."""
    d = s.raw or {}
    sh = check_table(d.get("shaft", {}), SHAFT_FIELDS, "shaft")
    ho = check_table(d.get("housing", {}), HOUSING_FIELDS, "housing")
    lub = check_table(d.get("lubricant", {}), SECTIONS["lubricant"], "lubricant") if "lubricant" in d else {}
    lub = {k: v for k, v in lub.items() if k != "oil_level_mm"}            # the scene's own (an override's)
    if s.oil_level is not None:
        lub["oil_level_mm"] = s.oil_level * 1e3
    closure = "contact" if s.seals in CONTACT_SEALS else "shields" if s.seals == "shield" else "none"
    old = s.network if isinstance(s.network, Machine) else None
    if old is not None and not d:
        return dataclasses.replace(old, bearing=s.bearing, rotating=s.rotating,
                                   lubrication=lubrication_of(lub, s.lubricant, s.supply),
                                   housing=dataclasses.replace(old.housing, seals=closure))
    if s.supply == "oil_jet":
        lub = {**lub, "jet_penetration": s.jet_penetration}       # the drag's and the network's share alike
    op = (dict(n_rpm=s.n_rpm, T_ambient_C=s.T_ambient_C, Fa=s.Fa, Fr=float(np.hypot(s.Fr, s.Fz))) if at is None
          else dict(n_rpm=at.n_rpm, T_ambient_C=at.T_ambient_C, Fa=at.Fa, Fr=at.Fr))
    return machine_from_sections(sh, ho, lub, bearing=s.bearing, lubricant=s.lubricant, supply=s.supply,
                                 rotating=s.rotating, seals=closure, **op)


def _network_of(d: dict, th: dict):
    """The scene's network: a name or path, or ``"parametric"`` when it describes its machine."""
    described = [k for k in ("shaft", "housing") if k in d]
    net = th.get("network")
    if described and net not in (None, PARAMETRIC):
        raise InputError("thermal.network", net, f"[{'], ['.join(described)}] describe the machine of a parametric "
                         'network: remove them, or the network name (or write network = "parametric")')
    return PARAMETRIC if described else net


def _check_scene(s: Scene, network_changed: bool = True):
    """Checks that involve more than one key (and the network's names)."""
    if s.supply == "oil_jet" and s.T_C is None and s.network is not None and s.T_oil_in_C is None:
        raise InputError("lubricant.T_in_C", None, "an oil-jet scene solved thermally needs the oil inlet temperature [°C]")
    if s.bearing.dm is not None:
        validity.check("n_dm", s.n_rpm * s.bearing.dm * 1e3, "operation.n_rpm", warn=False, given=s.n_rpm)
    _check_added(s)
    check_pair(s)
    if s.network is None:
        if s.T_fixed_C:
            raise InputError("thermal.fixed_C", s.T_fixed_C, "imposed node temperatures need a thermal network")
        return
    if network_changed:
        network_spec(s.network, s.path, parameters=s.network_parameters, fixed_C=s.T_fixed_C)
    if s.rig_map and network_changed:             # the rig's channels against the nodes of a new network
        nodes = network_nodes(s.network, s.path)
        for ch, target in s.rig_map.items():
            node = target[len(_IMPOSE):] if target.startswith(_IMPOSE) else target
            if target not in RIG_TARGETS and node not in nodes:
                raise InputError(f"rig.map.{ch}", target, f"unknown node; the network {s.network} has: "
                                 f"{', '.join(nodes)} (or input, ignore, impose:<node>)")


def _check_added(s: Scene):
    """Lubricant, oil level, seals and cage against the supply and the bearing."""
    if getattr(s.lubricant, "kind", "oil") == "grease" and s.supply in OIL_SUPPLIES:
        raise InputError("lubricant.name", s.lubricant.name, f"is a grease; supply = {s.supply!r} needs an oil "
                         "(thermobear list lubricants), or supply = \"grease\"")
    if s.oil_level is not None and s.supply in ("grease", "dry_film"):
        raise InputError("lubricant.oil_level_mm", s.oil_level * 1e3, f"an oil level needs an oil supply "
                         f"(oil_bath, oil_jet or oil_air), not {s.supply}")
    if s.seals == "none" and s.seal_sides:
        raise InputError("bearing.seal_sides", s.seal_sides, "0 without seals (bearing.seals = 'none')")
    if s.seals != "none" and not s.seal_sides:
        raise InputError("bearing.seal_sides", s.seal_sides, f"1 or 2 with bearing.seals = '{s.seals}' "
                         "(or seals = 'none')")
    if s.seals in CONTACT_SEALS:
        if s.bearing.outer_diameter is None:
            raise InputError("bearing.outer_diameter_mm", None, "SKF's seal constants are chosen by the outside "
                             "diameter: give it")
        seal_constants(s.seals, s.bearing.kind, s.bearing.outer_diameter * 1e3)     # refuses what SKF does not cover
    if s.cage != "balls" and (s.bearing.bore is None or s.bearing.outer_diameter is None or s.bearing.width is None):
        raise InputError("bearing.cage", s.cage, "a ring-guided cage's land is estimated from the bore, outside "
                         "diameter and width: give them")


def scene_from_dict(d: dict, path: str | None = None) -> Scene:
    """Validate a parsed scene table and convert it to SI (see the module docstring)."""
    check_table(d, {k: Field.table() for k in SECTIONS}, "scene file")
    if "bearing" not in d:
        raise InputError("bearing", None, "missing section [bearing] (catalog = \"...\" or inline geometry)")
    if "lubricant" not in d:
        raise InputError("lubricant", None, "missing section [lubricant] (name = \"...\" or inline properties)")
    meta = check_table(d.get("scene", {}), SECTIONS["scene"], "scene")
    op = check_table(d.get("operation", {}), SECTIONS["operation"], "operation")
    lsec = check_table(d["lubricant"], SECTIONS["lubricant"], "lubricant")
    th = check_table(d.get("thermal", {}), SECTIONS["thermal"], "thermal")
    models = check_table(d.get("models", {}), MODEL_FIELDS, "models")
    rig = check_table(d.get("rig", {}), SECTIONS["rig"], "rig")
    bx = check_table({k: v for k, v in d["bearing"].items() if k in _BEARING_FIELDS}, _BEARING_FIELDS, "bearing") \
        if isinstance(d["bearing"], dict) else {}
    mm = (lambda v: None if v is None else v * 1e-3)  # noqa: E731
    s = Scene(
        name=meta.get("name", Path(path).stem if path else "scene"),
        bearing=_bearing_of(d["bearing"]), lubricant=_lubricant_of(d["lubricant"], "lubricant"),
        supply=lsec.get("supply", "oil_jet"), n_rpm=op["n_rpm"], rotating=op.get("rotating", "inner"),
        Fa=op.get("Fa_N", 0.0), Fr=op.get("Fr_N", 0.0), M=op.get("M_Nm"), T_C=op.get("T_C"),
        Fz=op.get("Fz_N", 0.0), My=op.get("My_Nm"), contamination=op.get("contamination", "normal_cleanliness"),
        shaft_fit=bx.get("shaft_fit"), housing_fit=bx.get("housing_fit"), arrangement=bx.get("arrangement"),
        preload_force=bx.get("preload_N"), preload_kind=bx.get("preload"), pair_spacer=mm(bx.get("spacer_mm")),
        oil_flow=lsec.get("flow_L_h", 0.0) * 1e-3 / 3600.0, jet_penetration=lsec.get("jet_penetration", _default_penetration(lsec.get("supply", "oil_jet"), lsec)),
        T_oil_in_C=lsec.get("T_in_C"),
        T_ambient_C=th.get("T_ambient_C", 20.0), Rq_ball=lsec.get("Rq_ball_um", 0.05) * 1e-6,
        Rq_ring=lsec.get("Rq_ring_um", 0.1) * 1e-6, mu_boundary=lsec.get("mu_boundary", 0.11),
        mu_full_film=lsec.get("mu_full_film", 0.05), K_rs=lsec.get("K_rs"), network=_network_of(d, th),
        network_parameters=_parameters(th.get("parameters", {})), T_fixed_C=_fixed(th.get("fixed_C")),
        models=models, oil_level=mm(lsec.get("oil_level_mm")), seals=bx.get("seals", "none"),
        seal_sides=bx.get("seal_sides", _default_sides(bx.get("seals", "none"))),
        seal_diameter=mm(bx.get("seal_diameter_mm")), cage=bx.get("cage", "balls"),
        cage_land_width=mm(bx.get("cage_land_width_mm")), cage_land_clearance=mm(bx.get("cage_land_clearance_mm")),
        rig_J_kg_m2=rig.get("J_kg_m2"), rig_map=_rig_map(rig.get("map", {})),
        uncertainty=_scene_uncertainty(d), source=meta.get("source", ""), path=path, raw=d)
    check_lubrication_keys(lsec, s.supply)
    if s.network == PARAMETRIC:
        s = dataclasses.replace(s, network=_machine(s))
    _check_scene(s)
    return s


def load_scene(path) -> Scene:
    """Read and validate a scene file (TOML).

    >>> import thermobear
    >>> s = load_scene(thermobear.example_path("seed004_oil_jet_7210.toml"))
    >>> s.bearing.name, s.n_rpm, s.Fa, s.Fr
    ('7210', 3200.0, 450.0, 325.0)
    """
    p = Path(path)
    if not p.is_file():
        raise InputError("scene", str(path), "file not found" if not p.exists() else "is not a file")
    return scene_from_dict(read_toml(str(p.resolve())), path=str(p))
