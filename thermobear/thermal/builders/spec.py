"""The table a builder writes: nodes and elements as a network file has them, plus the geometry.

:class:`NetworkSpec` collects nodes and elements while a builder runs and returns the plain
network table (:meth:`NetworkSpec.table`) that :func:`thermobear.thermal.prepare_network` checks
like any ``networks/*.toml`` file.  Alongside, it keeps what a table cannot say: the cells of the
bodies of revolution (:class:`Cell`) and the faces through which they exchange heat
(:class:`Surface`), for documentation and for the finite-element reference
(``validation/network_fem.py``).  The result of a build is a :class:`BuiltNetwork`.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from thermobear.errors import InputError

__all__ = ["Cell", "Surface", "NetworkSpec", "BuiltNetwork"]


@dataclass(frozen=True)
class Cell:
    """An annular cell of a body of revolution (one network node).

    name : node name;  body : body name;  r0, r1 : inner and outer radius [m] (r0 = 0: a solid
    core);  z0, z1 : axial extent [m] (z = 0 at the bearing's mid-plane);  material : name
    """

    name: str
    body: str
    r0: float
    r1: float
    z0: float
    z1: float
    material: str


@dataclass(frozen=True)
class Surface:
    """A face of a body through which it exchanges heat with a node.

    element : the element carrying the exchange;  body : the body;  face : ``"outer"`` (r = r),
    ``"inner"`` (r = r), ``"left"`` / ``"right"`` (z = z);  r : (r0, r1) of the face [m] (a radial
    face: (r, r));  z : (z0, z1) [m] (an axial face: (z, z));  to : the node on the other side;
    kind : ``"convection"``, ``"radiation"``, ``"joint"`` (h_W_m2K: the joint alone, the solid's
    conduction not included), ``"fixed"`` (the face held at the node's temperature) or
    ``"exchange"`` (a conductance G_W_K spread over the face)
    """

    element: str
    body: str
    face: str
    r: tuple
    z: tuple
    to: str
    kind: str
    h_W_m2K: float | None = None
    G_W_K: float | None = None


@dataclass(frozen=True)
class BuiltNetwork:
    """A network built from dimensions.

    spec : dict        the network table (give it to :func:`thermobear.thermal.prepare_network`)
    cells : tuple      :class:`Cell` of every body of revolution
    surfaces : tuple   :class:`Surface` of every exchange through a body's face
    segments : dict    body → its discretisation (counts and the criterion values, see
                       :func:`thermobear.thermal.builders.axisym.segment_count`)
    """

    spec: dict
    cells: tuple = ()
    surfaces: tuple = ()
    segments: dict = field(default_factory=dict)

    @property
    def nodes(self) -> list:
        """Node names, in the table's order."""
        return list(self.spec["nodes"])

    def mean(self, T: dict, body: str) -> float:
        """Volume mean of a body's cell temperatures ``T`` (node → value) [the unit of T]."""
        cells = [c for c in self.cells if c.body == body]
        if not cells:
            raise InputError("body", body, f"one of {', '.join(sorted({c.body for c in self.cells}))}")
        v = [(c.r1**2 - c.r0**2) * (c.z1 - c.z0) for c in cells]
        return sum(w * T[c.name] for c, w in zip(cells, v)) / sum(v)


def _clean(d: dict) -> dict:
    return {k: v for k, v in d.items() if v is not None and v != [] and v != ()}


class NetworkSpec:
    """Collects a network table while a builder runs (nodes and elements in insertion order)."""

    def __init__(self, name: str, description: str = "", source: str = "", notes: str = ""):
        self.name, self.description, self.source, self.notes = name, description, source, notes
        self.nodes: dict = {}
        self.elements: list = []
        self.cells: list = []
        self.surfaces: list = []
        self.segments: dict = {}
        self._names: set = set()

    def node(self, name: str, *, C_J_K=None, volume_m3=None, mass_kg=None, material=None, T_C=None,
             description=None, estimated=(), source=None, measured_by=None, uncertainty=None) -> str:
        """Add a node (a free node with its capacity, or a fixed node with ``T_C``); returns its name."""
        if name in self.nodes:
            raise InputError(f"network {self.name}: nodes.{name}", name, "node names must be unique")
        self.nodes[name] = _clean(dict(C_J_K=C_J_K, volume_m3=volume_m3, mass_kg=mass_kg, material=material,
                                       T_C=T_C, description=description, source=source, measured_by=measured_by,
                                       estimated=list(estimated), uncertainty=uncertainty))
        return name

    def fixed(self, name: str, T_C, **info) -> str:
        """A fixed-temperature node (added once; a second call returns the existing one)."""
        return name if name in self.nodes else self.node(name, T_C=T_C, **info)

    def element(self, name: str, type: str, between, *, description=None, estimated=(), source=None,
                **params) -> str:
        """Add an element; returns its name."""
        if name in self._names:
            raise InputError(f"network {self.name}: elements[{name}]", name, "element names must be unique")
        self._names.add(name)
        self.elements.append(_clean(dict(name=name, type=type, between=list(between), description=description,
                                         source=source, estimated=list(estimated), **params)))
        return name

    def has_element(self, name: str) -> bool:
        return name in self._names

    def surface(self, **kw) -> Surface:
        s = Surface(**kw)
        self.surfaces.append(s)
        return s

    def table(self) -> dict:
        """The network table (a fresh dict; lists and tables copied)."""
        out = {"name": self.name}
        for k in ("description", "source", "notes"):
            if getattr(self, k):
                out[k] = getattr(self, k)
        out["nodes"] = {n: dict(v, estimated=list(v["estimated"])) if "estimated" in v else dict(v)
                        for n, v in self.nodes.items()}
        out["elements"] = [dict(e, between=list(e["between"])) for e in self.elements]
        return out

    def built(self) -> BuiltNetwork:
        return BuiltNetwork(spec=self.table(), cells=tuple(self.cells), surfaces=tuple(self.surfaces),
                            segments=dict(self.segments))
