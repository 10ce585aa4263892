r"""Thermal networks as data: ``networks/*.toml`` → a checked template → a network at operating points.

A network file has a ``[nodes.<name>]`` table per node and an ``[[elements]]`` entry per
element (edge)::

    name = "one_node"
    [nodes.bearing]
    C_J_K = 400.0                  # heat capacity [J/K]  (or mass_kg / volume_m3 + material)
    [nodes.ambient]
    T_C = "scene.T_ambient_C"      # fixed temperature [°C] from the scene context
    [[elements]]
    name = "bearing_to_ambient"
    type = "conductance"
    between = ["bearing", "ambient"]
    G_W_K = 1.0
    estimated = ["G_W_K"]          # every value a paper does not give, reason in a comment
    uncertainty.G_W_K = { factor = [0.7, 1.3], source = "..." }   # how far it may lie (thermobear.schema)

Numeric parameters carry their unit in the key (``_m``, ``_m2``, ``_W_mK``, ``_W_m2K``,
``_m3_s`` ...) and are numbers or short expressions over the context
(:mod:`thermobear.thermal.expressions`).  Context names: ``bearing`` (D, dm, Z, bore,
outer_diameter, width [m], alpha0 [rad], ball_material, ring_material; for the contact fallback
Rx_i(α), Rx_o(α), Ry_i, Ry_o, E_prime), ``scene`` (T_ambient_C, T_oil_in_C, oil_flow_m3_s, n_rpm
and the scene's ``[thermal.parameters]`` values), ``op`` (what the physics computed for the
operating point: ``op.omega_rad_s`` ring speed, ``op.omega_cage_rad_s`` cage speed,
``op.omega_ball_rad_s`` ball spin speed about its own axis, ``op.oil_fraction`` oil volume fraction
of the oil–air mixture), ``oil`` (the lubricant) and ``contacts`` (``contacts.inner.a_m``/``b_m``
per-ball Hertz semi-axes [m], same for ``outer``).

Two steps, as the solvers use them:

* :func:`prepare_network` checks the table once — keys and units, element types, node names, that
  every free node has a path to a fixed-temperature node — resolves the materials and evaluates
  every value that reads only the bearing (volumes, areas, lengths): an immutable
  :class:`NetworkTemplate`;
* :meth:`NetworkTemplate.at` evaluates the rest for a batch of B operating points (scene values,
  speeds, contacts as arrays with a leading axis B) and probes every element once: a
  :class:`ThermalNetwork` whose conductances, matrices and derivatives are arrays over the B points.

Uncertainty: a node's or an element's ``uncertainty.<key>`` (any numeric key, a number or an
expression: :func:`thermobear.schema.check_uncertainty`) and the ``uncertainty`` of the materials it
uses (``k_W_mK``, ``rho_kg_m3``, ``cp_J_kgK``) are collected in :attr:`NetworkTemplate.uncertainty` by
address (``nodes.<node>.<key>``, ``elements.<element>.<key>``, ``materials.<material>.<key>``).  A
context ``sample`` — address → draws, one per operating point — moves those values point by point in
:meth:`NetworkTemplate.at` (factor × value, value + offset, or the drawn value): capacities, fixed
temperatures and conductances then differ per point within one batch.

Every failure raises :class:`~thermobear.errors.InputError` naming the file and the field.
"""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path

import networkx as nx
import numpy as np

from thermobear.contact.hertz import hertz
from thermobear.contact.materials import PROPERTIES, Material, material, material_names
from thermobear.errors import InputError
from thermobear.files import data_dir, names_in, read_toml
from thermobear.schema import check_uncertainty
from thermobear.thermal.elements import (CORRELATION_KEYS, ELEMENT_TYPES, HARRIS_COEFFICIENTS, MATERIAL_KEYS,
                                         STRING_KEYS, Element)
from thermobear.thermal.expressions import MISSING, compile_expression, lookup
from thermobear.thermal.instance import ThermalNetwork, Structure
from thermobear.units import ZERO_C_K

__all__ = ["NetworkTemplate", "ThermalNetwork", "prepare_network", "load_network", "network_names", "ROLES",
           "STATIC_ROOTS"]

#: Nodes that receive the losses, by role, each with its candidate node names in order of
#: preference: each contact's loss ½ to the ball and ½ to the race (Pouly et al. 2010), drag to the
#: oil–air mixture (seed 004 §4.5); the contact temperature is the mean of ball and race nodes.
#: Churning heats the oil bath (``bath``: a sump node where the network has one), seal friction the
#: seal (else the inner ring its lip runs on: its race node, so that a measured inner-ring node stays
#: imposable), cage losses the cage (else the mixture around it).
ROLES = {"inner": ("inner_race", "shaft_washer", "inner_ring", "bearing"),
         "outer": ("outer_race", "housing_washer", "outer_ring", "bearing"),
         "ball": ("balls", "bearing"),
         "oil": ("oil_air", "balls", "bearing"),
         "bath": ("oil_sump", "sump", "oil_bath", "oil_air", "balls", "bearing"),
         "seal": ("seal", "inner_race", "shaft_washer", "inner_ring", "bearing"),
         "cage": ("cage", "oil_air", "balls", "bearing")}

#: Context roots whose values do not change with the operating point: expressions reading only
#: these (and numbers) are evaluated once, by :func:`prepare_network`.
STATIC_ROOTS = frozenset({"bearing"})

# unit suffix → (lower bound, strict) checked on every numeric key
_POSITIVE = ("_m", "_m2", "_m3", "_kg", "_W_mK", "_W_m2K", "_J_K", "_kg_m3", "_J_kgK", "_W_K", "_K_W", "_N")
_NONNEG = ("_m3_s", "_m_s", "_kg_s", "_rad_s")
_DIMENSIONLESS = ("beta", "emissivity", "oil_fraction", "n_balls")
_NODE_KEYS = {"C_J_K", "mass_kg", "volume_m3", "material", "T_C", "description", "estimated", "measured_by",
              "source", "uncertainty"}
_NODE_NUMBERS = ("C_J_K", "mass_kg", "volume_m3", "T_C")
_NODE_INFO = ("description", "measured_by", "source", "estimated")
_ELEMENT_META = {"type", "between", "name", "description", "estimated", "source", "uncertainty"}
_TOP_KEYS = {"name", "description", "source", "nodes", "elements", "notes"}
_C0 = ZERO_C_K                 # [K] at 0 °C (thermobear.units)


def _check_value(fld, key, v):
    """A numeric parameter's value, checked by its key's unit suffix."""
    if key.endswith(_NONNEG):
        ok, what = np.all(v >= 0), "must be >= 0"
    elif key.endswith(_POSITIVE) or key == "n_balls":
        ok, what = np.all(v > 0), "must be > 0"
    elif key == "T_C":
        ok, what = np.all(v > -_C0), "must be above absolute zero [°C]"
    elif key in _DIMENSIONLESS:
        ok, what = True, ""
    else:
        raise InputError(fld, v, "key without a recognised unit suffix")
    if not ok:
        raise InputError(fld, v if np.ndim(v) == 0 else np.asarray(v), what)
    return v


# --------------------------------------------------------------------------- template
@dataclass(frozen=True)
class ElementTemplate:
    """One checked element entry: static parameters evaluated, the others compiled."""

    name: str
    type: str
    nodes: tuple
    i: int
    j: int
    static: dict
    dynamic: tuple          # (key, field, Expression)
    field: str              # "<file>: elements[<name>]"
    G_static: float | None = None   # the conductance [W/K] when it reads only the bearing and no temperature


@dataclass(frozen=True)
class NetworkTemplate:
    """A checked network table with everything that reads only the bearing evaluated.

    Attributes
    ----------
    name, source : str
    nodes : tuple                 node names; arrays follow this order
    index : dict                  node name → position
    fixed : ndarray of bool       True for fixed-temperature nodes
    C_J_K : ndarray               heat capacities [J/K] (NaN where the file gives none)
    T_fixed : tuple               (node index, field, static °C or Expression) of the fixed nodes
    elements : tuple              :class:`ElementTemplate` entries
    estimated : dict              "nodes.x" / "elements[y]" → list of estimated keys
    info : dict                   node → its description / measured_by / source (for reports)
    topology : Structure          matrix pattern and temperature dependence (the network's constant part)
    uncertainty : dict            address (``nodes.<n>.<key>``, ``elements.<e>.<key>``,
                                  ``materials.<m>.<key>``) → :class:`~thermobear.schema.Uncertainty`
    capacity : tuple              per free node with a capacity: (node index, key, value, Material or
                                  None) — how its capacity is made, for capacities per operating point
    """

    name: str
    source: str
    nodes: tuple
    index: dict
    fixed: np.ndarray
    C_J_K: np.ndarray
    T_fixed: tuple
    elements: tuple
    estimated: dict = field(default_factory=dict)
    info: dict = field(default_factory=dict)
    topology: Structure = None
    uncertainty: dict = field(default_factory=dict)
    capacity: tuple = ()

    @property
    def free_nodes(self) -> list:
        """Names of the nodes whose temperature is solved for."""
        return [n for n, f in zip(self.nodes, self.fixed) if not f]

    @property
    def fixed_nodes(self) -> list:
        """Names of the fixed-temperature nodes."""
        return [n for n, f in zip(self.nodes, self.fixed) if f]

    @property
    def graph(self) -> nx.MultiGraph:
        """The topology as a networkx MultiGraph (built at each access): nodes with ``fixed`` and
        ``C_J_K`` [J/K], one edge per element (key = element name) with its type and static
        parameters (materials by name)."""
        g = nx.MultiGraph(name=self.name)
        for i, n in enumerate(self.nodes):
            g.add_node(n, fixed=bool(self.fixed[i]), C_J_K=float(self.C_J_K[i]), **self.info.get(n, {}))
        for e in self.elements:
            g.add_edge(*e.nodes, key=e.name, type=e.type, advective=e.type == "advection", **{
                k: (v.name if isinstance(v, Material) else v) for k, v in e.static.items()
                if not isinstance(v, np.ndarray)})
        return g

    def at(self, context=None, *, oil=None, batch: int | None = None) -> "ThermalNetwork":
        """The network at B operating points: the operating-point values evaluated in ``context``
        (scalars, or arrays with a leading axis of length B), every element probed once.

        Parameters
        ----------
        context : mapping   scene, op, contacts, bearing … (see the module docstring)
        oil : Lubricant     the lubricant (fluid properties; default ``context["oil"]``)
        batch : int         B; default: the leading length of the context's arrays, else 1
        """
        ctx = dict(context or {})
        oil = oil if oil is not None else ctx.get("oil")
        B = _batch_size(ctx) if batch is None else int(batch)
        sample = self._sample(ctx.get("sample"), B)
        n = len(self.nodes)
        T_fixed = np.zeros((B, n))
        for k, fld, v in self.T_fixed:
            val = v if not hasattr(v, "value") else v.value(ctx, fld)
            val = _moved(sample, f"nodes.{self.nodes[k]}.T_C", val)
            T_fixed[:, k] = _check_value(fld, "T_C", np.broadcast_to(val, (B,))) + _C0
        elements = tuple(_instantiate(e, ctx, B, oil, sample) for e in self.elements)
        tmpl, C = self, None
        if sample:              # moved elements are evaluated per point; capacities per point
            tmpl = replace(self, elements=tuple(replace(t, G_static=None) if t.G_static is not None and _touched(t, sample)
                                                else t for t in self.elements))
            C = self._capacities(sample, B)
        return ThermalNetwork(template=tmpl, B=B, T_fixed_K=T_fixed, elements=elements, oil=oil,
                              structure=self.topology.at(tmpl, elements, T_fixed, oil), C_points=C)

    def _sample(self, sample, B) -> dict:
        """The context's draws: address → (Uncertainty, draws (B,) or a number); unknown addresses refused."""
        if not sample:
            return {}
        out = {}
        for addr, draws in sample.items():
            if addr not in self.uncertainty:
                raise InputError(f"sample.{addr}", None, f"no uncertain value of network {self.name} at this address; "
                                 f"it has: {', '.join(sorted(self.uncertainty)) or 'none'}")
            out[addr] = (self.uncertainty[addr], _per_point(draws, B, f"sample.{addr}"))
        return out

    def _capacities(self, sample, B):
        """(B, n) heat capacities [J/K] with the drawn volumes, masses, capacities and material
        densities and specific heats; None when no draw touches a capacity."""
        hit = [(k, key, val, m) for k, key, val, m in self.capacity
               if f"nodes.{self.nodes[k]}.{key}" in sample
               or (m is not None and any(f"materials.{m.name}.{q}" in sample for q in ("rho_kg_m3", "cp_J_kgK")))]
        if not hit:
            return None
        C = np.broadcast_to(self.C_J_K, (B, len(self.nodes))).copy()
        for k, key, val, m in hit:
            f = f"{self.source}: nodes.{self.nodes[k]}.{key}"
            c = _check_value(f, key, _moved(sample, f"nodes.{self.nodes[k]}.{key}", val))
            if m is not None:
                c = c * _material_value(sample, m, "cp_J_kgK")
            if key == "volume_m3":
                c = c * _material_value(sample, m, "rho_kg_m3")
            C[:, k] = _check_value(f, "C_J_K", c)
        return C


def _batch_size(ctx) -> int:
    """The leading length of the context's operating-point arrays (scene, op), else 1."""
    sizes = set()
    for root in ("scene", "op"):
        d = ctx.get(root)
        if isinstance(d, Mapping):
            sizes |= {np.shape(v)[0] for v in d.values() if isinstance(v, np.ndarray) and np.ndim(v) >= 1}
    if len(sizes) > 1:
        raise InputError("context", sorted(sizes), "operating-point arrays must share one length B")
    return sizes.pop() if sizes else 1


def _per_point(v, B, fld):
    """A value broadcast over the B operating points (scalars stay scalars)."""
    if np.ndim(v) == 0:
        return float(v)
    a = np.asarray(v, dtype=float)
    if a.shape[0] != B or a.ndim != 1:
        raise InputError(fld, a.shape, f"must be one value per operating point ({B},)")
    return a


def _moved(sample, addr, value):
    """``value`` moved by the draws of ``addr`` (unchanged when not sampled)."""
    hit = sample.get(addr)
    return value if hit is None else hit[0].apply(value, hit[1])


def _touched(e: ElementTemplate, sample) -> bool:
    """True when a draw moves a value of the element (its own, or its material's conductivity)."""
    return any(f"elements.{e.name}.{k}" in sample or (k in _MATERIAL_K and f"materials.{v.name}.k_W_mK" in sample)
               for k, v in e.static.items()) or any(f"elements.{e.name}.{k}" in sample for k, _, _ in e.dynamic)


def _material_value(sample, m: Material, key):
    """A material property (``k_W_mK``, ``rho_kg_m3``, ``cp_J_kgK``) moved by its draws."""
    return _moved(sample, f"materials.{m.name}.{key}", getattr(m, PROPERTIES[key]))


#: element material key → the conductivity key that replaces it when its material's k is drawn
_MATERIAL_K = {"material": "k_W_mK", "material_ball": "k_ball_W_mK", "material_ring": "k_ring_W_mK"}


def _instantiate(e: ElementTemplate, ctx, B, oil, sample=None) -> Element:
    p = dict(e.static)
    for key, fld, expr in e.dynamic:
        p[key] = _check_value(fld, key, _per_point(expr.value(ctx, fld), B, fld))
    if sample:
        for key in list(p):
            addr = f"elements.{e.name}.{key}"
            if addr in sample:
                p[key] = _check_value(f"{e.field}.{key}", key, _moved(sample, addr, p[key]))
            elif key in _MATERIAL_K and f"materials.{p[key].name}.k_W_mK" in sample:
                p[_MATERIAL_K[key]] = _check_value(f"{e.field}.{key}", "k_W_mK", _material_value(sample, p[key], "k_W_mK"))
    if e.type == "ball_race_contact":
        p["a_m"], p["b_m"], p["semi_axes_from"] = _semi_axes(e, p, ctx, B)
        if p.get("exchange") == "rolling" and p["semi_axes_from"] == "context":
            p.update(_rolling(e, p, ctx, B))
    if e.type in ("convection", "advection") and oil is None:
        needs = (e.type == "advection" and not ("rho_kg_m3" in p and "cp_J_kgK" in p)) or (
            e.type == "convection" and p["correlation"] in HARRIS_COEFFICIENTS and p.get("fluid", "oil_air") != "air"
        ) or (e.type == "convection" and p.get("fluid") == "oil")
        if needs:
            key = "correlation" if e.type == "convection" else "rho_kg_m3"
            raise InputError(f"{e.field}.{key}", p.get(key), "needs the lubricant 'oil' in the context (or give "
                             + ("fluid = \"air\")" if e.type == "convection" else "rho_kg_m3 and cp_J_kgK)"))
    return ELEMENT_TYPES[e.type]["cls"](name=e.name, type=e.type, nodes=e.nodes, i=e.i, j=e.j, p=p)


def _semi_axes(e: ElementTemplate, p, ctx, B):
    """Per-ball semi-axes of a raceway, (B, Z) [m]: the context's contacts, else the fallback."""
    side = p["contact"]
    contacts = ctx.get("contacts")
    if contacts is not None:
        c = lookup(contacts, side)
        a = lookup(c, "a_m") if c is not MISSING else MISSING
        b = lookup(c, "b_m") if c is not MISSING else MISSING
        if a is MISSING or b is MISSING:
            raise InputError(f"contacts.{side}.a_m", None, "context 'contacts' lacks the a_m/b_m arrays of this raceway")
        a, b = np.atleast_1d(np.asarray(a, float)), np.atleast_1d(np.asarray(b, float))
        if a.shape != b.shape:
            raise InputError(f"contacts.{side}.b_m", b.shape, f"must have the shape of a_m {a.shape}")
        return np.broadcast_to(a, (B, a.shape[-1])), np.broadcast_to(b, (B, b.shape[-1])), "context"
    if "a_fb" not in p:
        raise InputError(f"contacts.{side}.a_m", None,
                         "not in the context and no fallback (a_fallback_m + b_fallback_m, or Q_fallback_N) given")
    return (np.broadcast_to(p["a_fb"], (B, p["a_fb"].size)), np.broadcast_to(p["b_fb"], (B, p["b_fb"].size)),
            p["fallback_from"])


def _rolling(e: ElementTemplate, p, ctx, B) -> dict:
    """Per-ball entrainment speeds of a raceway's contacts (B, Z) from the context for a rolling ball–race
    exchange, with their loads, radii and the bearing's E' for the film where the context has them (the
    ball and ring materials need k, rho and cp)."""
    c = lookup(ctx["contacts"], p["contact"])
    u = lookup(c, "u_m_s")
    if u is MISSING:
        raise InputError(f"contacts.{p['contact']}.u_m_s", None,
                         "exchange = \"rolling\" needs the contacts' entrainment speeds in the context")
    for m in ("material_ball", "material_ring"):
        if m not in p or p[m].cp is None:
            raise InputError(f"{e.field}.{m}", None, "exchange = \"rolling\" needs a material with k, rho and cp "
                             "(the effusivity √(k ρ c_p))")
    shape = p["a_m"].shape
    out = {"u_m": np.broadcast_to(np.asarray(u, float), shape)}
    film = {k: lookup(c, k) for k in ("Q_N", "Rx_m", "Ry_m")}
    brg = ctx.get("bearing")
    Ep = lookup(brg, "E_prime") if brg is not None else MISSING
    if Ep is not MISSING and all(v is not MISSING for v in film.values()):
        out.update({k: np.broadcast_to(np.asarray(v, float), shape) for k, v in film.items()}, E_prime=float(Ep))
    return out


def _param(fld, key, v, ctx):
    """A numeric parameter: its checked value when static, else its compiled expression."""
    expr = compile_expression(v, fld)
    if expr.roots <= STATIC_ROOTS:
        val = expr.value(ctx, fld)
        if np.ndim(val):
            raise InputError(fld, v, "must evaluate to a single number")
        return _check_value(fld, key, val)
    return expr


def _resolve_material(value, ctx, fld) -> Material:
    if isinstance(value, str) and value in material_names():
        m = material(value)
    else:
        v = compile_expression(value, fld, numeric=False).value(ctx, fld) if isinstance(value, str) else value
        m = v if isinstance(v, Material) else material(str(v)) if isinstance(v, str) else None
        if m is None:
            raise InputError(fld, value, f"a material name ({', '.join(material_names())}) "
                                         "or a context name holding a Material")
    if m.k is None:
        raise InputError(fld, m.name, "material has no thermal conductivity k")
    return m


def _check_estimated(f, tbl, estimated):
    est = tbl.get("estimated", [])
    if not isinstance(est, list) or not all(isinstance(x, str) for x in est):
        raise InputError(f"{f}.estimated", est, "a list of key names")
    missing = [x for x in est if x not in tbl]
    if missing:
        raise InputError(f"{f}.estimated", missing[0], "lists a key the entry does not have")
    if est:
        estimated[f.split(": ", 1)[-1]] = list(est)


def _check_uncertainty(f, tbl, numbers, address, uncertainty):
    """The ``uncertainty`` table of a node or element: entries on its numeric keys, by address."""
    if "uncertainty" in tbl:
        for key, u in check_uncertainty(tbl["uncertainty"], {k: None for k in numbers if k in tbl}, f).items():
            uncertainty[f"{address}.{key}"] = u


def _material_uncertainty(m: Material, keys, uncertainty):
    """The uncertain properties ``keys`` of a material the network uses, by address."""
    for key in keys:
        if key in m.uncertainty:
            uncertainty[f"materials.{m.name}.{key}"] = m.uncertainty[key]


def _capacity(f, nd, ctx):
    """Heat capacity of a free node [J/K] (NaN when the file gives none) and how it is made
    (key, value, Material or None; None when the file gives none)."""
    has_C, has_m = "C_J_K" in nd, ("mass_kg" in nd) + ("volume_m3" in nd)
    if has_C and (has_m or "material" in nd):
        raise InputError(f"{f}.C_J_K", nd["C_J_K"], "give either C_J_K or mass_kg/volume_m3 with a material, not both")
    if has_C:
        C = _static_number(f"{f}.C_J_K", "C_J_K", nd["C_J_K"], ctx)
        return C, ("C_J_K", C, None)
    if has_m == 2:
        raise InputError(f"{f}.mass_kg", nd["mass_kg"], "give mass_kg or volume_m3, not both")
    if has_m == 0:
        return np.nan, None    # allowed for steady state; the transient solver asks for it
    if "material" not in nd:
        raise InputError(f"{f}.material", None, "needed with mass_kg or volume_m3 (for cp and rho)")
    m = _resolve_material(nd["material"], ctx, f"{f}.material")
    if m.cp is None:
        raise InputError(f"{f}.material", m.name, "material has no specific heat cp")
    if "mass_kg" in nd:
        mass = _static_number(f"{f}.mass_kg", "mass_kg", nd["mass_kg"], ctx)
        return mass * m.cp, ("mass_kg", mass, m)
    V = _static_number(f"{f}.volume_m3", "volume_m3", nd["volume_m3"], ctx)
    return m.rho * V * m.cp, ("volume_m3", V, m)


def _static_number(fld, key, v, ctx):
    val = _param(fld, key, v, ctx)
    if not isinstance(val, float):
        raise InputError(fld, v, "may read only the bearing (capacities are fixed per network)")
    return val


def _nodes(pre, nodes_tbl, ctx, estimated, uncertainty):
    """Node names, fixed mask, capacities, fixed temperatures, node info and how each capacity is made."""
    names = list(nodes_tbl)
    n = len(names)
    fixed, C, T_fixed, info, capacity = np.zeros(n, bool), np.full(n, np.nan), [], {}, []
    for i, (name, nd) in enumerate(nodes_tbl.items()):
        f = f"{pre}nodes.{name}"
        if not isinstance(nd, Mapping):
            raise InputError(f, nd, "each node is a table")
        bad = set(nd) - _NODE_KEYS
        if bad:
            k = sorted(bad)[0]
            raise InputError(f"{f}.{k}", nd[k], f"unknown node key; allowed: {', '.join(sorted(_NODE_KEYS))}")
        _check_estimated(f, nd, estimated)
        _check_uncertainty(f, nd, _NODE_NUMBERS, f"nodes.{name}", uncertainty)
        info[name] = {k: nd[k] for k in _NODE_INFO if k in nd and k != "estimated"}
        if "T_C" in nd:
            if {"C_J_K", "mass_kg", "volume_m3", "material"} & set(nd):
                raise InputError(f"{f}.T_C", nd["T_C"], "a fixed-temperature node takes no heat capacity or material")
            fixed[i] = True
            T_fixed.append((i, f"{f}.T_C", _param(f"{f}.T_C", "T_C", nd["T_C"], ctx)))
        else:
            C[i], how = _capacity(f, nd, ctx)
            if how is not None:
                capacity.append((i, *how))
                if how[2] is not None:
                    _material_uncertainty(how[2], ("rho_kg_m3", "cp_J_kgK") if how[0] == "volume_m3" else ("cp_J_kgK",),
                                          uncertainty)
    if not fixed.any():
        raise InputError(pre + "nodes", None, "at least one fixed-temperature node (T_C = ...) is required")
    return names, fixed, C, tuple(T_fixed), info, tuple(capacity)


def _element_checks(pre, k, e, index, estimated, seen):
    """The context-free checks of an element table; returns (name, field prefix, type, between)."""
    if not isinstance(e, Mapping):
        raise InputError(f"{pre}elements[{k}]", e, "each element is a table")
    between = e.get("between")
    name = e.get("name", f"{between[0]}--{between[1]}" if isinstance(between, list) and len(between) == 2 else str(k))
    f = f"{pre}elements[{name}]"
    if name in seen:
        raise InputError(f"{f}.name", name, "element names must be unique")
    seen.add(name)
    typ = e.get("type")
    if typ not in ELEMENT_TYPES:
        raise InputError(f"{f}.type", typ, f"one of {', '.join(ELEMENT_TYPES)}")
    if not (isinstance(between, list) and len(between) == 2 and all(isinstance(b, str) for b in between)):
        raise InputError(f"{f}.between", between, "a list of two node names")
    for b in between:
        if b not in index:
            raise InputError(f"{f}.between", b, f"unknown node; nodes: {', '.join(index)}")
    if between[0] == between[1]:
        raise InputError(f"{f}.between", between, "the two nodes must differ")
    schema = ELEMENT_TYPES[typ]
    allowed = set(schema["required"]) | set(schema["optional"]) | {x for g in schema["one_of"] for x in g}
    bad = set(e) - allowed - _ELEMENT_META
    if bad:
        kk = sorted(bad)[0]
        raise InputError(f"{f}.{kk}", e[kk], f"unknown key for type '{typ}'; allowed: {', '.join(sorted(allowed))}")
    for kk in schema["required"]:
        if kk not in e:
            raise InputError(f"{f}.{kk}", None, f"required for type '{typ}'")
    for group in schema["one_of"]:
        if len([g for g in group if g in e]) != 1:
            raise InputError(f"{f}.{group[0]}", None, f"give exactly one of {' / '.join(group)}")
    _check_estimated(f, e, estimated)
    return name, f, typ, between


def _element(pre, k, e, ctx, index, fixed, estimated, seen, uncertainty) -> ElementTemplate:
    name, f, typ, between = _element_checks(pre, k, e, index, estimated, seen)
    _check_uncertainty(f, e, [kk for kk in e if kk not in _ELEMENT_META and kk not in STRING_KEYS
                              and kk not in MATERIAL_KEYS], f"elements.{name}", uncertainty)
    static, dynamic = {}, []
    for kk, v in e.items():
        if kk in _ELEMENT_META:
            continue
        fld = f"{f}.{kk}"
        if kk in STRING_KEYS:
            if v not in STRING_KEYS[kk]:
                raise InputError(fld, v, f"one of {', '.join(STRING_KEYS[kk])}")
            static[kk] = v
        elif kk in MATERIAL_KEYS:
            static[kk] = _resolve_material(v, ctx, fld)
            _material_uncertainty(static[kk], ("k_W_mK",), uncertainty)
        else:
            val = _param(fld, kk, v, ctx)
            if isinstance(val, float):
                static[kk] = val
            else:
                dynamic.append((kk, fld, val))
    i, j = index[between[0]], index[between[1]]
    keys = set(static) | {d[0] for d in dynamic}
    if typ == "convection":
        for kk in CORRELATION_KEYS[static["correlation"]]:
            if kk not in keys:
                raise InputError(f"{f}.{kk}", None, f"required by correlation '{static['correlation']}'")
        if (static["correlation"] in HARRIS_COEFFICIENTS and static.get("fluid", "oil_air") == "oil_air"
                and "oil_fraction" not in keys):
            raise InputError(f"{f}.oil_fraction", None, "required for fluid = \"oil_air\"")
    if typ == "advection" and fixed[j]:
        raise InputError(f"{f}.between", between, "the downstream (second) node of an advection must be free")
    if typ == "ball_race_contact":
        static.update(_fallback_axes(f, static, ctx))
    G = None
    if not dynamic and typ != "ball_race_contact":
        el = ELEMENT_TYPES[typ]["cls"](name=name, type=typ, nodes=tuple(between), i=i, j=j, p=static)
        if not el.depends_on() and typ not in ("convection", "advection", "radiation"):
            try:
                G = float(el.conductance(None, None))
            except InputError as exc:
                raise InputError(f"{f}.{exc.field}", exc.value, exc.expected) from None
            if not (np.isfinite(G) and G >= 0):
                raise InputError(f, G, "conductance must be finite and >= 0 [W/K]")
    return ElementTemplate(name=name, type=typ, nodes=tuple(between), i=i, j=j, static=static, G_static=G,
                           dynamic=tuple(dynamic), field=f)


def _fallback_axes(f, p, ctx) -> dict:
    """The fallback semi-axes of a ball–race element (used when the context gives no contacts)."""
    n_balls = p.get("n_balls")
    if n_balls is None:
        b = ctx.get("bearing")
        n_balls = lookup(b, "Z") if b is not None else MISSING
        if n_balls is MISSING or not isinstance(n_balls, (int, float)):
            return {}
    n_balls = int(round(float(n_balls)))
    if "a_fallback_m" in p and "b_fallback_m" in p:
        return {"a_fb": np.full(n_balls, p["a_fallback_m"]), "b_fb": np.full(n_balls, p["b_fallback_m"]),
                "fallback_from": "fallback"}
    if "Q_fallback_N" in p:
        b_ = ctx.get("bearing")
        try:
            alpha, side = b_.alpha0, p["contact"]
            Rx = b_.Rx_i(alpha) if side == "inner" else b_.Rx_o(alpha)
            Ry = b_.Ry_i if side == "inner" else b_.Ry_o
            hc = hertz(p["Q_fallback_N"], Rx, Ry, b_.E_prime)
        except AttributeError as exc:
            raise InputError(f"{f}.Q_fallback_N", p["Q_fallback_N"],
                             f"needs bearing.alpha0, Rx_i/Rx_o, Ry_i/Ry_o, E_prime in the context ({exc})") from None
        return {"a_fb": np.full(n_balls, float(hc.a)), "b_fb": np.full(n_balls, float(hc.b)),
                "fallback_from": "fallback (Hertz at Q_fallback_N)"}
    return {}


def _check_reachable(pre, names, index, fixed, elements):
    """Every free node must see a fixed node: conduction both ways, advection upstream → downstream."""
    dg = nx.DiGraph()
    dg.add_nodes_from(names)
    for el in elements:
        dg.add_edge(el.nodes[0], el.nodes[1])
        if el.type != "advection":
            dg.add_edge(el.nodes[1], el.nodes[0])
    reach = set()
    for nm in names:
        if fixed[index[nm]]:
            reach |= {nm} | nx.descendants(dg, nm)
    for nm in names:
        if nm not in reach:
            raise InputError(f"{pre}nodes.{nm}", None,
                             "has no path to a fixed-temperature node (its temperature would be undetermined)")


def prepare_network(spec, context=None, *, source: str | None = None) -> NetworkTemplate:
    """Check a network table once and evaluate what reads only the bearing.

    Parameters
    ----------
    spec : str, Path or dict   a bundled network name, a ``.toml`` path, or the parsed table
    context : mapping          ``bearing`` (and any other names the static values read)
    source : str               name of the table in messages (default: the file or the table's name)

    Returns
    -------
    NetworkTemplate

    Examples
    --------
    >>> t = prepare_network("one_node", {"bearing": {"bore": 0.05, "outer_diameter": 0.09, "width": 0.02}})
    >>> t.nodes, t.free_nodes
    (('bearing', 'ambient'), ['bearing'])
    """
    ctx = dict(context or {})
    if isinstance(spec, Mapping):
        data, src = spec, source or (f"network {spec['name']}" if isinstance(spec.get("name"), str) else "<dict>")
    else:
        p = Path(spec)
        if p.suffix != ".toml" and not p.exists():
            names = network_names()
            if str(spec) not in names:
                raise InputError("network", str(spec), f"unknown network; known: {', '.join(names)}")
            p = data_dir("networks") / f"{spec}.toml"
        data, src = read_toml(str(p)), source or p.name
    pre = f"{src}: "
    unknown = set(data) - _TOP_KEYS
    if unknown:
        k = sorted(unknown)[0]
        raise InputError(pre + k, data[k], f"unknown top-level key; allowed: {', '.join(sorted(_TOP_KEYS))}")
    nodes_tbl, els = data.get("nodes"), data.get("elements")
    if not isinstance(nodes_tbl, Mapping) or not nodes_tbl:
        raise InputError(pre + "nodes", None, "a non-empty [nodes.<name>] table is required")
    if not isinstance(els, list) or not els:
        raise InputError(pre + "elements", None, "at least one [[elements]] entry is required")
    estimated: dict = {}
    uncertainty: dict = {}
    names, fixed, C, T_fixed, info, capacity = _nodes(pre, nodes_tbl, ctx, estimated, uncertainty)
    index = {nm: i for i, nm in enumerate(names)}
    seen: set = set()
    elements = tuple(_element(pre, k, e, ctx, index, fixed, estimated, seen, uncertainty) for k, e in enumerate(els))
    _check_reachable(pre, names, index, fixed, elements)
    for a in (fixed, C):
        a.setflags(write=False)
    probes = [ELEMENT_TYPES[e.type]["cls"](name=e.name, type=e.type, nodes=e.nodes, i=e.i, j=e.j,
                                           p={**e.static, **{k: 0.0 for k, _, _ in e.dynamic}}) for e in elements]
    return NetworkTemplate(name=data.get("name", src), source=src, nodes=tuple(names), index=index, fixed=fixed,
                           C_J_K=C, T_fixed=T_fixed, elements=elements, estimated=estimated, info=info,
                           topology=Structure.topology(fixed, probes), uncertainty=uncertainty, capacity=capacity)


def network_names() -> list:
    """Names of the bundled networks (``networks/*.toml``).

    >>> "one_node" in network_names()
    True
    """
    return names_in(data_dir("networks"))


def load_network(spec, context=None) -> ThermalNetwork:
    """Build a thermal network from a bundled name, a TOML path or a dict, at the operating points
    of ``context`` (:func:`prepare_network` then :meth:`NetworkTemplate.at`).

    Examples
    --------
    >>> net = load_network("one_node", {"scene": {"T_ambient_C": 20.0},
    ...                                 "bearing": {"bore": 0.05, "outer_diameter": 0.09, "width": 0.02}})
    >>> net.nodes, net.free_nodes, net.B
    (['bearing', 'ambient'], ['bearing'], 1)
    """
    ctx = dict(context or {})
    return prepare_network(spec, ctx).at(ctx)
