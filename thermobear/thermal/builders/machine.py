r"""A bearing in its machine, described by dimensions: shaft, housing, lubrication → a thermal network.

:class:`Machine` holds a bearing (:class:`~thermobear.contact.geometry.BallBearing`), its
:class:`Shaft`, its :class:`Housing` and its :class:`Lubrication` (SI units; ``None`` = the
documented default, resolved from the bearing at build time).
:func:`thermobear.thermal.builders.build_network` turns it into a :class:`~thermobear.thermal.builders.spec.BuiltNetwork` whose table
:func:`thermobear.thermal.prepare_network` checks like a ``networks/*.toml`` file.  A machine is
immutable and compares by value: scenes that share it share one prepared network.

Defaults (each estimated, with the reasoning; the estimated constants — seat roughness, microhardness,
emissivity, mounting joint, fills — with their ranges in ``materials/network_builders.toml``,
:mod:`~thermobear.thermal.builders.estimates`):

* shaft diameter = the bearing bore; length either side 2.5 d — DIN 748-1 cylindrical shaft ends
  (long series) are 2.1–2.8 d long for d = 25–80 mm; steel C45; free ends in air.
* housing: a block 2 D high and 2 D deep (a wall of ½ D around the seat, the proportion of cast
  plummer blocks), 2 B long (room for a cover or seal of ½ B either side), the shaft axis at mid
  height; grey cast iron EN-GJL-250 (the material of SKF SNL/SE housings); bolted on its base to a
  steel frame at ambient; still air; emissivity 0.8 (painted cast iron: 0.8–0.95, Bergman et al.
  2011 Table A.11 lists paints at 0.8–0.98; a bare machined surface is lower).
* fits: the probable interference of a k5 (m5 above 100 mm) shaft and an H7 housing for a
  rotating inner ring, g6 / N7 for a rotating outer ring (:mod:`~thermobear.thermal.builders.fits`).
* mounting joint 3600 W/(m² K): an air-filled metal joint at 0.1 MPa (Bergman et al. 2011
  Table 3.2, aluminium/aluminium, 10 µm roughness: 2.75e-4 m² K/W); the frame below spreads the heat
  as a half-space at ambient (:func:`~thermobear.thermal.conduction.spreading_conductance`).
* grease fill 30 % of the bearing's free volume (usual fills of running bearings are 20–40 %).
* oil sump: the oil held below the level in the housing bore beside the bearing (a housing with a
  separate reservoir: give its volume).
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace

from thermobear.contact.geometry import BallBearing
from thermobear.errors import InputError
from thermobear.thermal.builders import estimates

__all__ = ["Shaft", "Housing", "Lubrication", "Machine", "check_machine", "SHAFT_ENDS", "HOUSING_TYPES",
           "HOUSING_ENDS", "SEALS", "OIL_FEEDS"]

SHAFT_ENDS = ("free", "fixed", "adiabatic")
HOUSING_TYPES = ("block", "pillow", "flange", "round")
HOUSING_ENDS = ("air", "mounted", "adiabatic")
SEALS = ("none", "shields", "contact")
OIL_FEEDS = ("jet", "circulating")


@dataclass(frozen=True)
class Shaft:
    """The shaft (SI; ``None``: the default of the module docstring).

    diameter [m], bore [m] (0: solid), length_left / length_right [m] from the bearing's side
    faces, material (name), end_left / end_right (``free``: convection from the end face,
    ``fixed``: held at T_end_*_C (default ambient), ``adiabatic``: a symmetry plane),
    surface (``air``: the lateral surface outside the housing exchanges with the room,
    ``enclosed``: it does not), interference [m] of the inner-ring seat (negative: clearance),
    fit_h_W_m2K (the joint conductance given, not computed), end_right_node / end_left_node (name of
    a fixed end's node).
    """

    diameter: float | None = None
    bore: float = 0.0
    length_left: float | None = None
    length_right: float | None = None
    material: str = "steel-c45"
    end_left: str = "free"
    end_right: str = "free"
    T_end_left_C: float | None = None
    T_end_right_C: float | None = None
    surface: str = "air"
    interference: float | None = None
    fit_h_W_m2K: float | None = None
    end_left_node: str = "shaft_end_left"
    end_right_node: str = "shaft_end_right"


@dataclass(frozen=True)
class Housing:
    """The housing (SI; ``None``: the default of the module docstring).

    type: ``block`` (rectangular, height × depth × axial_length), ``pillow`` (round body of
    outer_diameter on a foot: base_length across the shaft, centre_height above the mounting
    face), ``flange`` (round body of outer_diameter, its left end face bolted to a wall),
    ``round`` (round body, mounted through ``mounting_G_W_K`` only; rigs).  offset [m]: axial
    position of the housing's centre from the bearing's.  end_left / end_right: ``air``,
    ``mounted``, ``adiabatic`` (a symmetry plane).  mounting: ``frame`` or ``none``;
    mounting_h_W_m2K the joint, mounting_G_W_K a given total conductance instead.  air:
    ``still`` or ``forced`` at air_speed [m/s].  seals: ``none``, ``shields``, ``contact``
    (closures of the bearing's cavity; a ``seal`` node for contact seals).
    """

    type: str = "block"
    material: str = "cast-iron-gjl-250"
    axial_length: float | None = None
    height: float | None = None
    depth: float | None = None
    outer_diameter: float | None = None
    centre_height: float | None = None
    base_length: float | None = None
    offset: float = 0.0
    end_left: str | None = None
    end_right: str = "air"
    mounting: str = "frame"
    mounting_h_W_m2K: float | None = None
    mounting_G_W_K: float | None = None
    frame_material: str = "steel-c45"
    air: str = "still"
    air_speed: float = 0.0
    emissivity: float = field(default_factory=lambda: estimates.values()["emissivity"])   # 0.8 (the data's)
    interference: float | None = None
    fit_h_W_m2K: float | None = None
    seals: str = "none"
    shape_convection: str | None = None     # rigs: a round body's lateral law ("forced_cylinder" ...)


@dataclass(frozen=True)
class Lubrication:
    """How the bearing is lubricated, for the network (SI).

    supply (``oil_jet``, ``grease``, ``oil_bath``, ``oil_air``, ``dry_film``), feed (oil jet:
    ``jet`` with penetration beta, ``circulating``: all the oil through the bearing), beta (None:
    0.4 for jets, Brossier et al. 2021; 1 for circulating oil and oil–air), oil_level [m] (SKF's H:
    above the lowest point of the outer-ring raceway), sump_volume [m³], grease_fill [-], air_flow
    [m³/s] (oil–air), rho_cp [J/(m³ K)], k [W/(m K)] of the lubricant (at 40 °C), oil_air_C_J_K
    (the mixture's capacity given), contact_exchange (``rolling``: the balls' contacts as rolling,
    lubricated contacts with the lubricant around them; ``stationary``: the Hertz constriction alone, as
    the seed papers' hand networks).
    """

    supply: str = "oil_jet"
    feed: str = "jet"
    beta: float | None = None
    oil_level: float | None = None
    sump_volume: float | None = None
    grease_fill: float | None = None
    air_flow: float = 0.0
    rho_cp: float = 1.7e6
    k: float = 0.13
    oil_air_C_J_K: float | None = None
    contact_exchange: str = "rolling"


@dataclass(frozen=True)
class Machine:
    """A bearing in its machine (see the module docstring).

    bearing, shaft, housing, lubrication;  rotating (``inner`` / ``outer``);  n_rpm, T_ambient_C:
    the operating point at which the discretisation rule estimates the convection (the network
    itself reads the speed and the ambient of every operating point);  Fa, Fr [N]: loads for the
    seat pressure of a clearance fit and the contacts' fallback;  t_resolve_s, Bi_max: the
    discretisation rule's resolved time (None: steady state only) and cell Biot number;  cage: a cage node;  name, description,
    source, notes: of the network table;  estimates: drawn values of the builders' estimated constants,
    ``((key, value), ...)`` sorted (:func:`thermobear.thermal.builders.estimates.drawn`; empty: the data's,
    ``materials/network_builders.toml``);  cells: cell counts held per piece, ``((segment label, n), ...)``
    (the labels of :attr:`~thermobear.thermal.builders.BuiltNetwork.segments`; empty: the rule's counts)
    — a drawn machine keeps its nominal's cells, hence its nodes.
    """

    bearing: BallBearing
    shaft: Shaft = field(default_factory=Shaft)
    housing: Housing = field(default_factory=Housing)
    lubrication: Lubrication = field(default_factory=Lubrication)
    rotating: str = "inner"
    n_rpm: float = 0.0
    T_ambient_C: float = 20.0
    Fa: float = 0.0
    Fr: float = 0.0
    t_resolve_s: float | None = 100.0
    Bi_max: float = 0.1
    cage: bool = False
    name: str = "parametric"
    description: str = ""
    source: str = ""
    notes: str = ""
    estimates: tuple = ()
    cells: tuple = ()

    def __str__(self) -> str:
        return self.name

    def with_(self, **changes) -> "Machine":
        """A copy with fields replaced (``dataclasses.replace``)."""
        return replace(self, **changes)


def check_machine(m: Machine) -> None:
    """InputError naming the field when a choice is not one of its values."""
    for fld, v, allowed in (("shaft.end_left", m.shaft.end_left, SHAFT_ENDS),
                            ("shaft.end_right", m.shaft.end_right, SHAFT_ENDS),
                            ("housing.type", m.housing.type, HOUSING_TYPES),
                            ("housing.end_right", m.housing.end_right, HOUSING_ENDS),
                            ("housing.end_left", m.housing.end_left or "air", HOUSING_ENDS),
                            ("housing.mounting", m.housing.mounting, ("frame", "none")),
                            ("housing.air", m.housing.air, ("still", "forced")),
                            ("shaft.surface", m.shaft.surface, ("air", "enclosed")),
                            ("rotating", m.rotating, ("inner", "outer")),
                            ("housing.seals", m.housing.seals, SEALS),
                            ("lubricant.oil_feed", m.lubrication.feed, OIL_FEEDS),
                            ("lubrication.contact_exchange", m.lubrication.contact_exchange, ("rolling", "stationary"))):
        if v not in allowed:
            raise InputError(fld, v, f"one of {', '.join(allowed)}")
    b = m.bearing
    for k in ("bore", "outer_diameter", "width"):
        if getattr(b, k) is None:
            raise InputError(f"bearing.{k}_mm", None, "a parametric network needs the bearing's boundary dimensions")
