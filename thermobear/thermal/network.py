r"""Thermal networks as data: ``networks/*.toml`` → a checked networkx graph.

A network file has a ``[nodes.<name>]`` table per node and an
``[[elements]]`` entry per element (edge)::

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

Numeric parameters carry their unit in the key (``_m``, ``_m2``, ``_W_mK``,
``_W_m2K``, ``_m3_s`` ...) and are numbers or short arithmetic expressions over
the context (``"bearing.bore / 2"``, ``"pi * bearing.outer_diameter * bearing.width"``),
evaluated by :func:`evaluate`, which accepts numbers, context names, + − * / **,
parentheses and the functions sqrt, log, log10, exp, sin, cos, tan, radians,
abs, min, max and the constant pi — nothing else.

Context names (provided by the caller): ``bearing`` (D, dm, Z, bore,
outer_diameter, width [m], alpha0 [rad], ball_material, ring_material, and
for the contact fallback Rx_i(α), Rx_o(α), Ry_i, Ry_o, E_prime), ``scene``
(n_rpm, T_ambient_C, T_oil_in_C, oil_flow_m3_s ...), ``oil`` (a lubricant
with rho(T_C) [kg/m³], nu(T_C) [cSt], k_th(T_C) [W/(m K)], cp(T_C) [J/(kg K)])
and optionally ``contacts`` (``contacts.inner.a_m``/``b_m`` per-ball Hertz
semi-axes [m], same for ``outer``).  Mappings and objects both work.

Loading checks units (keys), element types, node names, that every free node
has a path to a fixed-temperature node, and probes every element once; any
failure raises :class:`~thermobear.errors.InputError` naming the file and field.
"""
from __future__ import annotations

import ast
import math
import operator
from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cached_property, lru_cache
from pathlib import Path

import networkx as nx
import numpy as np

from thermobear.files import data_dir, names_in, read_toml
from thermobear.errors import InputError
from thermobear.contact.materials import Material, material, material_names
from thermobear.thermal.elements import (CORRELATION_KEYS, ELEMENT_TYPES, HARRIS_COEFFICIENTS, MATERIAL_KEYS,
                       STRING_KEYS, Element)

__all__ = ["ThermalNetwork", "load_network", "network_names", "evaluate", "ROLES"]

#: Nodes that receive the losses, by role, each with its candidate node names in order of
#: preference: each contact's loss ½ to the ball and ½ to the race (Pouly et al. 2010), drag to the
#: oil–air mixture (seed 004 §4.5); the contact temperature is the mean of ball and race nodes.
ROLES = {"inner": ("inner_race", "shaft_washer", "inner_ring", "bearing"),
         "outer": ("outer_race", "housing_washer", "outer_ring", "bearing"),
         "ball": ("balls", "bearing"),
         "oil": ("oil_air", "balls", "bearing")}

_FUNCS = {"sqrt": np.sqrt, "log": np.log, "log10": np.log10, "exp": np.exp, "sin": np.sin,
          "cos": np.cos, "tan": np.tan, "radians": np.radians, "abs": abs, "min": min, "max": max}
_CONSTS = {"pi": math.pi}
_BINOPS = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
           ast.Pow: operator.pow}
_PLAIN_FUNCS = frozenset({"abs", "min", "max"})     # Python built-ins: no floating-point state to watch
_MISSING = object()


def _get(obj, name):
    if type(obj) is dict or isinstance(obj, Mapping):
        return obj.get(name, _MISSING)
    return getattr(obj, name, _MISSING)


class _Evaluator:
    def __init__(self, context, field, expr):
        self.ctx, self.field, self.expr = context or {}, field, expr

    def fail(self, why):
        raise InputError(self.field, self.expr, why)

    def visit(self, node):
        if isinstance(node, ast.Constant):
            if isinstance(node.value, bool) or not isinstance(node.value, (int, float)):
                self.fail(f"only numbers are allowed as constants, not {node.value!r}")
            return float(node.value)
        if isinstance(node, ast.BinOp) and type(node.op) in _BINOPS:
            a, b = self.num(node.left), self.num(node.right)
            try:
                return _BINOPS[type(node.op)](a, b)
            except (ZeroDivisionError, OverflowError, ValueError) as exc:
                self.fail(f"cannot be evaluated: {exc}")
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            v = self.num(node.operand)
            return -v if isinstance(node.op, ast.USub) else +v
        if isinstance(node, ast.Name):
            if node.id in _CONSTS:
                return _CONSTS[node.id]
            v = _get(self.ctx, node.id)
            if v is _MISSING:
                self.fail(f"unknown name '{node.id}'; the context provides: "
                          + ", ".join(sorted(map(str, self.ctx.keys())) if isinstance(self.ctx, Mapping) else []))
            return v
        if isinstance(node, ast.Attribute):
            if node.attr.startswith("_"):
                self.fail(f"private attribute '{node.attr}' is not allowed")
            base = self.visit(node.value)
            if isinstance(base, (float, int, np.ndarray)):
                self.fail(f"attribute '{node.attr}' of a number is not allowed")
            v = _get(base, node.attr)
            if v is _MISSING:
                self.fail(f"unknown name '{ast.unparse(node)}' in the context")
            return v
        if isinstance(node, ast.Call):
            if not isinstance(node.func, ast.Name) or node.func.id not in _FUNCS or node.keywords:
                self.fail(f"only the functions {', '.join(sorted(_FUNCS))} may be called")
            args = [self.num(a) for a in node.args]
            try:
                with np.errstate(all="raise"):
                    return _FUNCS[node.func.id](*args)
            except (ValueError, TypeError, FloatingPointError, OverflowError) as exc:
                self.fail(f"cannot be evaluated: {exc}")
        self.fail(f"'{type(node).__name__}' is not allowed (numbers, names, + - * / **, "
                  f"{', '.join(sorted(_FUNCS))}, pi)")

    def num(self, node):
        v = self.visit(node)
        if isinstance(v, (bool, str)) or not isinstance(v, (int, float, np.floating, np.integer, np.ndarray)):
            self.fail(f"'{ast.unparse(node)}' " + (_NONE_MSG if v is None else "is not a number"))
        return v


_NONE_MSG = ("has no value in this scene (None), but the network reads it: give it in the scene (a bearing's "
             "bore_mm, outer_diameter_mm, width_mm) or use a network that does not need it")


_NUM_TYPES = (int, float, np.floating, np.integer, np.ndarray)


def _compile(node, as_num: bool):
    """The expression tree as nested closures ``f(ev)`` (``ev`` an :class:`_Evaluator`, for the
    context and the error messages): the checks and messages of :meth:`_Evaluator.visit` /
    :meth:`_Evaluator.num`, in the same order, without walking the tree again at every evaluation
    (networks are rebuilt for every operating point)."""
    f = _compile_visit(node)
    if not as_num:
        return f
    src = None

    if (isinstance(node, ast.Constant) and type(node.value) in (int, float)
            or isinstance(node, ast.Name) and node.id in _CONSTS):
        return f                            # a number: nothing to check

    def num(ev):
        v = f(ev)
        if type(v) is not float and (isinstance(v, (bool, str)) or not isinstance(v, _NUM_TYPES)):
            ev.fail(f"'{src or ast.unparse(node)}' " + (_NONE_MSG if v is None else "is not a number"))
        return v
    return num


def _compile_visit(node):
    if isinstance(node, ast.Constant):
        if isinstance(node.value, bool) or not isinstance(node.value, (int, float)):
            msg = f"only numbers are allowed as constants, not {node.value!r}"
            return lambda ev: ev.fail(msg)
        val = float(node.value)
        return lambda ev: val
    if isinstance(node, ast.BinOp) and type(node.op) in _BINOPS:
        fa, fb, op = _compile(node.left, True), _compile(node.right, True), _BINOPS[type(node.op)]

        def binop(ev):
            a, b = fa(ev), fb(ev)
            try:
                return op(a, b)
            except (ZeroDivisionError, OverflowError, ValueError) as exc:
                ev.fail(f"cannot be evaluated: {exc}")
        return binop
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
        fo = _compile(node.operand, True)
        if isinstance(node.op, ast.USub):
            return lambda ev: -fo(ev)
        return lambda ev: +fo(ev)
    if isinstance(node, ast.Name):
        name = node.id
        if name in _CONSTS:
            c = _CONSTS[name]
            return lambda ev: c

        def name_(ev):
            v = _get(ev.ctx, name)
            if v is _MISSING:
                ev.fail(f"unknown name '{name}'; the context provides: "
                        + ", ".join(sorted(map(str, ev.ctx.keys())) if isinstance(ev.ctx, Mapping) else []))
            return v
        return name_
    if isinstance(node, ast.Attribute):
        attr = node.attr
        if attr.startswith("_"):
            msg = f"private attribute '{attr}' is not allowed"
            return lambda ev: ev.fail(msg)
        fbase = _compile_visit(node.value)

        def attr_(ev):
            base = fbase(ev)
            if isinstance(base, (float, int, np.ndarray)):
                ev.fail(f"attribute '{attr}' of a number is not allowed")
            v = _get(base, attr)
            if v is _MISSING:
                ev.fail(f"unknown name '{ast.unparse(node)}' in the context")
            return v
        return attr_
    if isinstance(node, ast.Call):
        if not isinstance(node.func, ast.Name) or node.func.id not in _FUNCS or node.keywords:
            msg = f"only the functions {', '.join(sorted(_FUNCS))} may be called"
            return lambda ev: ev.fail(msg)
        fn, fargs = _FUNCS[node.func.id], [_compile(a, True) for a in node.args]
        if node.func.id in _PLAIN_FUNCS:
            def call_plain(ev):
                args = [g(ev) for g in fargs]
                try:
                    return fn(*args)
                except (ValueError, TypeError, OverflowError) as exc:
                    ev.fail(f"cannot be evaluated: {exc}")
            return call_plain

        def call(ev):
            args = [g(ev) for g in fargs]
            try:
                with np.errstate(all="raise"):
                    return fn(*args)
            except (ValueError, TypeError, FloatingPointError, OverflowError) as exc:
                ev.fail(f"cannot be evaluated: {exc}")
        return call
    msg = (f"'{type(node).__name__}' is not allowed (numbers, names, + - * / **, "
           f"{', '.join(sorted(_FUNCS))}, pi)")
    return lambda ev: ev.fail(msg)


@lru_cache(maxsize=1024)
def _compiled(expr: str):
    """:func:`_compile` of a parsed expression string, cached per string (raises SyntaxError)."""
    return _compile(_parse(expr).body, True)


@lru_cache(maxsize=1024)
def _parse(expr: str):
    """Parsed expression (cached per string: networks are rebuilt for every operating point; the
    tree is only read by :class:`_Evaluator`, never modified)."""
    return ast.parse(expr.strip(), mode="eval")


def evaluate(expr, context=None, field="expression"):
    """Evaluate a number or a short arithmetic expression over a context, safely.

    Parameters
    ----------
    expr : float or str   the value or expression
    context : mapping     names available to the expression (objects or mappings)
    field : str           field named in the error message

    Returns
    -------
    float (or ndarray when a context value is an array)

    Examples
    --------
    >>> evaluate("bearing.bore / 2 + sqrt(4) * 1e-3", {"bearing": {"bore": 0.05}})
    0.027
    >>> evaluate("__import__('os')", {}, "x")
    Traceback (most recent call last):
    ...
    thermobear.errors.InputError: x = "__import__('os')" — only the functions abs, cos, exp, log, log10, max, min, radians, sin, sqrt, tan may be called
    """
    if isinstance(expr, bool):
        raise InputError(field, expr, "a number or an arithmetic expression string")
    if isinstance(expr, (int, float)):
        return float(expr)
    if not isinstance(expr, str) or len(expr) > 400:
        raise InputError(field, expr, "a number or an arithmetic expression string (≤ 400 characters)")
    try:
        fn = _compiled(expr)
    except SyntaxError as exc:
        raise InputError(field, expr, f"not a valid arithmetic expression ({exc.msg})") from None
    v = fn(_Evaluator(context, field, expr))
    if isinstance(v, float):                      # also numpy float64
        if not math.isfinite(v):
            raise InputError(field, expr, "evaluates to a non-finite value")
        return float(v)
    v = float(v) if np.ndim(v) == 0 else np.asarray(v, dtype=float)
    if not np.all(np.isfinite(v)):
        raise InputError(field, expr, "evaluates to a non-finite value")
    return v


# unit suffix → (lower bound, strict) checked on every numeric key
_POSITIVE = ("_m", "_m2", "_m3", "_kg", "_W_mK", "_W_m2K", "_J_K", "_kg_m3", "_J_kgK", "_W_K",
             "_K_W", "_N")
_NONNEG = ("_m3_s", "_m_s", "_kg_s")
_DIMENSIONLESS = ("beta", "emissivity", "oil_fraction", "n_balls")
_NODE_KEYS = {"C_J_K", "mass_kg", "volume_m3", "material", "T_C", "description", "estimated",
              "measured_by", "source"}
_ELEMENT_META = {"type", "between", "name", "description", "estimated", "source"}
_TOP_KEYS = {"name", "description", "source", "nodes", "elements", "notes"}


def _check_value(fld, key, v):
    if key.endswith(_NONNEG):
        ok = np.all(v >= 0)
        what = "must be >= 0"
    elif key.endswith(_POSITIVE) or key == "n_balls":
        ok = np.all(v > 0)
        what = "must be > 0"
    elif key == "T_C":
        ok = np.all(v > -273.15)
        what = "must be above absolute zero [°C]"
    elif key in _DIMENSIONLESS:
        ok = True
        what = ""
    else:  # pragma: no cover - every schema key is covered above
        raise InputError(fld, v, "key without a recognised unit suffix")
    if not ok:
        raise InputError(fld, v if np.ndim(v) == 0 else np.asarray(v), what)
    return v


def _resolve_material(value, ctx, fld):
    if isinstance(value, Material):
        m = value
    elif isinstance(value, str) and value in material_names():
        m = material(value)
    else:
        v = evaluate_object(value, ctx, fld)
        m = v if isinstance(v, Material) else material(str(v)) if isinstance(v, str) else None
        if m is None:
            raise InputError(fld, value, f"a material name ({', '.join(material_names())}) "
                                         "or a context name holding a Material")
    if m.k is None:
        raise InputError(fld, m.name, "material has no thermal conductivity k")
    return m


def evaluate_object(expr, ctx, fld):
    """Resolve a dotted context name (``bearing.ball_material``) to any object."""
    if not isinstance(expr, str):
        raise InputError(fld, expr, "a name or a dotted context name")
    try:
        tree = _parse(expr)
    except SyntaxError:
        raise InputError(fld, expr, "a material name or a dotted context name") from None
    if not isinstance(tree.body, (ast.Name, ast.Attribute)):
        raise InputError(fld, expr, "a material name or a dotted context name")
    return _compiled_object(expr)(_Evaluator(ctx, fld, expr))


@lru_cache(maxsize=256)
def _compiled_object(expr: str):
    """:func:`_compile` of a (dotted) name, any object as the result; cached per string."""
    return _compile(_parse(expr).body, False)


@dataclass
class ThermalNetwork:
    """A checked thermal network (build it with :func:`load_network`).

    Attributes
    ----------
    name : str
    nodes : list of str           node names; arrays below follow this order
    index : dict                  node name → position
    fixed : ndarray of bool       True for fixed-temperature nodes
    T_fixed_K : ndarray           fixed temperatures [K] (free nodes: 0, unused)
    C_J_K : ndarray               heat capacities [J/K] (NaN where the file gives none)
    elements : list of Element
    graph : networkx.MultiGraph   nodes and elements with their data (edge key = element name), built
                                  from the arrays and elements above on first access
    estimated : dict              "nodes.x" / "elements[y]" → list of estimated keys
    source : str                  file the network came from
    """

    name: str
    nodes: list
    index: dict
    fixed: np.ndarray
    T_fixed_K: np.ndarray
    C_J_K: np.ndarray
    elements: list
    estimated: dict = field(default_factory=dict)
    source: str = ""

    @cached_property
    def graph(self) -> nx.MultiGraph:
        """The network as a networkx MultiGraph: nodes with ``fixed`` and ``T_C`` [°C] or ``C_J_K``
        [J/K], one edge per element (key = element name) with its type, ``advective`` and evaluated
        parameters (materials by name).  Built on first access (the solvers do not need it)."""
        graph = nx.MultiGraph(name=self.name)
        for i, name in enumerate(self.nodes):
            graph.add_node(name, fixed=bool(self.fixed[i]),
                           **({"T_C": self.T_fixed_K[i] - 273.15} if self.fixed[i] else {"C_J_K": self.C_J_K[i]}))
        for el in self.elements:
            graph.add_edge(*el.nodes, key=el.name, type=el.type, advective=el.advective, **{
                kk: (vv.name if isinstance(vv, Material) else vv) for kk, vv in el.p.items()})
        return graph

    @property
    def free_nodes(self) -> list:
        """Names of the nodes whose temperature is solved for."""
        return [n for n, f in zip(self.nodes, self.fixed) if not f]

    @property
    def fixed_nodes(self) -> list:
        """Names of the fixed-temperature nodes."""
        return [n for n, f in zip(self.nodes, self.fixed) if f]

    @property
    def T_dependent(self) -> bool:
        """True when some element conductance depends on temperature."""
        return any(e.T_dependent for e in self.elements)

    def conductances(self, T_K) -> np.ndarray:
        """Conductance of every element [W/K] at node temperatures ``T_K`` (all nodes, K)."""
        return np.array([e.conductance(T_K) for e in self.elements], dtype=float)

    def initial_T_K(self) -> np.ndarray:
        """Node temperatures with every free node at the mean fixed temperature [K]."""
        T = self.T_fixed_K.copy()
        T[~self.fixed] = self.T_fixed_K[self.fixed].mean()
        return T


def network_names() -> list:
    """Names of the bundled networks (``networks/*.toml``).

    >>> "one_node" in network_names()
    True
    """
    return names_in(data_dir("networks"))


def load_network(spec, context=None, *, _frozen: bool = False) -> ThermalNetwork:
    """Build a thermal network from a bundled name, a TOML path or a dict.

    Parameters
    ----------
    spec : str, Path or dict   ``"oil_jet_ball_bearing"``, a path to a ``.toml`` file,
                               or the parsed table itself
    context : mapping          bearing, scene, oil, contacts (see module docstring)

    Returns
    -------
    ThermalNetwork

    Examples
    --------
    >>> net = load_network("one_node", {"scene": {"T_ambient_C": 20.0},
    ...                                 "bearing": {"bore": 0.05, "outer_diameter": 0.09, "width": 0.02}})
    >>> net.nodes, net.free_nodes
    (['bearing', 'ambient'], ['bearing'])
    """
    ctx = dict(context or {})
    if isinstance(spec, Mapping):
        data = spec if _frozen else dict(spec)
        src = f"network {spec['name']}" if isinstance(spec.get("name"), str) else "<dict>"
    else:
        p = Path(spec)
        if p.suffix != ".toml" and not p.exists():
            names = network_names()
            if str(spec) not in names:
                raise InputError("network", str(spec), f"unknown network; known: {', '.join(names)}")
            p = data_dir("networks") / f"{spec}.toml"
        data, src = read_toml(str(p)), p.name
    return _build(data, ctx, src, _frozen and isinstance(spec, Mapping))


# id(spec) -> (spec, estimated, static leaves) of specs built once with every check (see _build's ``frozen``)
_CHECKED: dict = {}
# (id(spec), values of the static leaves) -> (spec, {field: checked value}) (see _static_values)
_STATIC: dict = {}
#: Context roots whose values do not change with the operating point (a bearing's geometry and
#: materials); expressions reading only these are evaluated once per set of values they read.
_STATIC_ROOTS = frozenset({"bearing"})


def _build(data, ctx, src, frozen: bool = False) -> ThermalNetwork:
    """Check and build a network.  ``frozen`` (private, for :mod:`thermobear.coupled.solver`, which rebuilds
    the same never-modified table for every operating point): once such a table passed every check,
    later builds of the same object skip the checks that do not depend on the context (keys, element
    types and schemas, node names, reachability) and only evaluate, check and probe the values; the
    values that read nothing but the bearing (volumes, areas, lengths, materials: see
    :func:`_static_values`) and the plain numbers are taken from the build with the same bearing
    values."""
    pre = f"{src}: "
    memo = _CHECKED.get(id(data)) if frozen else None
    trusted = memo is not None and memo[0] is data
    if trusted:
        return _assemble(data, ctx, src, pre, trusted=True, estimated=dict(memo[1]),
                         static=_static_values(data, ctx, memo[2]))
    net = _assemble(data, ctx, src, pre, trusted=False, estimated={})
    if frozen:
        if len(_CHECKED) > 64:
            _CHECKED.clear()
        _CHECKED[id(data)] = (data, dict(net.estimated), _spec_leaves(data))
    return net


@lru_cache(maxsize=1024)
def _leaves(expr: str):
    """The context names an expression reads, as (root, attribute, ...) paths, when every root is in
    ``_STATIC_ROOTS``; None when it reads another root (scene, contacts, oil ...) or does not parse."""
    try:
        tree = _parse(expr)
    except SyntaxError:
        return None
    out = set()
    todo = [tree.body]
    while todo:
        node = todo.pop()
        if isinstance(node, ast.Attribute):
            path, base = [], node
            while isinstance(base, ast.Attribute):
                path.append(base.attr)
                base = base.value
            if not isinstance(base, ast.Name):
                return None
            if base.id not in _STATIC_ROOTS:
                return None
            out.add((base.id, *reversed(path)))
        elif isinstance(node, ast.Name):
            if node.id in _CONSTS:
                continue
            if node.id not in _STATIC_ROOTS:
                return None
            out.add((node.id,))
        elif isinstance(node, ast.Call):
            todo.extend(node.args)          # the function name is not a context name
        else:
            todo.extend(ast.iter_child_nodes(node))
    return frozenset(out)


def _static_expr(v) -> bool:
    """True for an expression string that reads only static context names (``_STATIC_ROOTS``)."""
    return isinstance(v, str) and len(v) <= 400 and _leaves(v) is not None


def _spec_leaves(data) -> tuple:
    """Every static context name (path) that the expressions of a checked table read, sorted."""
    out = set()
    tables = list(data["nodes"].values()) + list(data["elements"])
    for tbl in tables:
        for k, v in tbl.items():
            if k in _ELEMENT_META or k in STRING_KEYS or k in ("description", "measured_by", "source"):
                continue
            if _static_expr(v):
                out |= _leaves(v)
    return tuple(sorted(out))


def _static_values(data, ctx, leaves):
    """Checked values of the static entries of a checked table for this context (field → value),
    shared by every build whose context gives the same values to ``leaves`` (the static names the
    table reads): a pure cache, keyed on the values actually read (a bearing changed in any of them
    gets its own entry).  Filled by the first build of each key; None when a value cannot be read or
    hashed (the build then evaluates everything, with the usual errors)."""
    vals = []
    for path in leaves:
        v = _get(ctx, path[0])
        for a in path[1:]:
            if v is _MISSING:
                break
            v = _get(v, a)
        if v is _MISSING:
            return None
        vals.append(v)
    key = (id(data), tuple(vals))
    try:
        hit = _STATIC.get(key)
    except TypeError:                   # an unhashable value (e.g. an array): no sharing
        return None
    if hit is not None and hit[0] is data:
        return hit[1]
    if len(_STATIC) > 256:
        _STATIC.clear()
    d: dict = {}
    _STATIC[key] = (data, d)
    return d


def _assemble(data, ctx, src, pre, trusted, estimated, static=None) -> ThermalNetwork:
    unknown = set() if trusted else set(data) - _TOP_KEYS
    if unknown:
        k = sorted(unknown)[0]
        raise InputError(pre + k, data[k], f"unknown top-level key; allowed: {', '.join(sorted(_TOP_KEYS))}")
    nodes_tbl = data.get("nodes")
    if not isinstance(nodes_tbl, Mapping) or not nodes_tbl:
        raise InputError(pre + "nodes", None, "a non-empty [nodes.<name>] table is required")
    els = data.get("elements")
    if not isinstance(els, list) or not els:
        raise InputError(pre + "elements", None, "at least one [[elements]] entry is required")

    names = list(nodes_tbl)
    index = {n: i for i, n in enumerate(names)}
    n = len(names)
    fixed, T_fixed, C = np.zeros(n, bool), np.zeros(n), np.full(n, np.nan)
    values: dict = {}          # expression string → value, for this build's context (a repeated expression once)
    for name, nd in nodes_tbl.items():
        f = f"{pre}nodes.{name}"
        if not trusted:
            if not isinstance(nd, Mapping):
                raise InputError(f, nd, "each node is a table")
            bad = set(nd) - _NODE_KEYS
            if bad:
                k = sorted(bad)[0]
                raise InputError(f"{f}.{k}", nd[k], f"unknown node key; allowed: {', '.join(sorted(_NODE_KEYS))}")
            _check_estimated(f, nd, estimated)
        i = index[name]
        if "T_C" in nd:
            if {"C_J_K", "mass_kg", "volume_m3", "material"} & set(nd):
                raise InputError(f"{f}.T_C", nd["T_C"], "a fixed-temperature node takes no heat capacity or material")
            fixed[i] = True
            T_fixed[i] = _check_value(f"{f}.T_C", "T_C", _evaluate_once(values, nd["T_C"], ctx, f"{f}.T_C")) + 273.15
        elif static is not None:
            c = static.get(f)
            if c is None:
                c = _capacity(f, nd, ctx)
                if all(_static_expr(nd[k]) or isinstance(nd[k], (int, float)) or k == "material"
                       and nd[k] in material_names() for k in ("C_J_K", "mass_kg", "volume_m3", "material")
                       if k in nd):
                    static[f] = c
            C[i] = c
        else:
            C[i] = _capacity(f, nd, ctx)
    if not fixed.any():
        raise InputError(pre + "nodes", None, "at least one fixed-temperature node (T_C = ...) is required")

    elements, seen = [], set()
    for k, e in enumerate(els):
        elements.append(_element(pre, k, e, ctx, index, fixed, estimated, seen, trusted, static, values))

    # every free node must see a fixed node: conduction both ways, advection upstream → downstream
    if not trusted:
        _check_reachable(pre, names, index, fixed, elements)

    net = ThermalNetwork(name=data.get("name", src), nodes=names, index=index, fixed=fixed,
                         T_fixed_K=T_fixed, C_J_K=C, elements=elements, estimated=estimated, source=src)
    # probe every element once at a representative state, naming the element on failure (the elements
    # share their fluid-property evaluations, as in the solvers: Element._conductance_shared)
    T_probe = net.initial_T_K() + np.where(fixed, 0.0, 10.0)
    shared: dict = {}
    for el in elements:
        if static is not None:
            # the memoised conductance of a temperature-independent element of the last build with these
            # bearing values (Element._memo keeps it only where the parameters are equal)
            memo = static.get(("G", el.name))
            if memo is not None:
                el.__dict__["_tb_G"] = memo
        try:
            G = el._conductance_shared(T_probe, shared)
        except InputError as exc:
            raise InputError(f"{pre}elements[{el.name}].{exc.field}", exc.value, exc.expected) from None
        if not (np.isfinite(G) and G >= 0):
            raise InputError(f"{pre}elements[{el.name}]", G, "conductance must be finite and >= 0 [W/K]")
        if static is not None and "_tb_G" in el.__dict__ and not el.p.get("semi_axes_from") == "context":
            static[("G", el.name)] = el.__dict__["_tb_G"]
    return net


def _check_reachable(pre, names, index, fixed, elements):
    """Every free node must see a fixed node: conduction both ways, advection upstream → downstream."""
    dg = nx.DiGraph()
    dg.add_nodes_from(names)
    for el in elements:
        dg.add_edge(el.nodes[0], el.nodes[1])
        if not el.advective:
            dg.add_edge(el.nodes[1], el.nodes[0])
    reach = set()
    for nm in names:
        if fixed[index[nm]]:
            reach |= {nm} | nx.descendants(dg, nm)
    for nm in names:
        if nm not in reach:
            raise InputError(f"{pre}nodes.{nm}", None,
                             "has no path to a fixed-temperature node (its temperature would be undetermined)")


def _check_estimated(f, tbl, estimated):
    est = tbl.get("estimated", [])
    if not isinstance(est, list) or not all(isinstance(x, str) for x in est):
        raise InputError(f"{f}.estimated", est, "a list of key names")
    missing = [x for x in est if x not in tbl]
    if missing:
        raise InputError(f"{f}.estimated", missing[0], "lists a key the entry does not have")
    if est:
        estimated[f.split(": ", 1)[-1]] = list(est)


def _capacity(f, nd, ctx):
    has_C = "C_J_K" in nd
    has_m = ("mass_kg" in nd) + ("volume_m3" in nd)
    if has_C and (has_m or "material" in nd):
        raise InputError(f"{f}.C_J_K", nd["C_J_K"], "give either C_J_K or mass_kg/volume_m3 with a material, not both")
    if has_C:
        return _check_value(f"{f}.C_J_K", "C_J_K", evaluate(nd["C_J_K"], ctx, f"{f}.C_J_K"))
    if has_m == 2:
        raise InputError(f"{f}.mass_kg", nd["mass_kg"], "give mass_kg or volume_m3, not both")
    if has_m == 0:
        return np.nan          # allowed for steady state; the transient solver asks for it
    if "material" not in nd:
        raise InputError(f"{f}.material", None, "needed with mass_kg or volume_m3 (for cp and rho)")
    m = _resolve_material(nd["material"], ctx, f"{f}.material")
    if m.cp is None:
        raise InputError(f"{f}.material", m.name, "material has no specific heat cp")
    if "mass_kg" in nd:
        mass = _check_value(f"{f}.mass_kg", "mass_kg", evaluate(nd["mass_kg"], ctx, f"{f}.mass_kg"))
    else:
        mass = m.rho * _check_value(f"{f}.volume_m3", "volume_m3", evaluate(nd["volume_m3"], ctx, f"{f}.volume_m3"))
    return float(mass * m.cp)


def _element_checks(pre, k, e, index, estimated, seen):
    """The context-free checks of an element table; returns (name, field prefix, type, between, schema)."""
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
    if typ == "ball_race_contact":
        allowed.add("Q_fallback_N")
    bad = set(e) - allowed - _ELEMENT_META
    if bad:
        kk = sorted(bad)[0]
        raise InputError(f"{f}.{kk}", e[kk], f"unknown key for type '{typ}'; allowed: {', '.join(sorted(allowed))}")
    for kk in schema["required"]:
        if kk not in e:
            raise InputError(f"{f}.{kk}", None, f"required for type '{typ}'")
    for group in schema["one_of"]:
        got = [g for g in group if g in e]
        if len(got) != 1:
            raise InputError(f"{f}.{group[0]}", None, f"give exactly one of {' / '.join(group)}")
    _check_estimated(f, e, estimated)
    return name, f, typ, between, schema


def _evaluate_once(values, expr, ctx, fld):
    """:func:`evaluate` of an expression string once per build (``values``: string → value for this
    build's context; an expression repeated in the table gives the same value)."""
    if not isinstance(expr, str):
        return evaluate(expr, ctx, fld)
    v = values.get(expr, _MISSING)
    if v is _MISSING:
        v = values[expr] = evaluate(expr, ctx, fld)
    return v


def _element(pre, k, e, ctx, index, fixed, estimated, seen, trusted=False, static=None, values=None) -> Element:
    head = static.get(("element", k)) if static is not None and trusted else None
    template = None
    if head is not None:                    # the names and fields of this table entry, from an earlier build
        name, f, typ, between, schema, items, template = head
    else:
        if trusted:                         # a table that passed every check below before (see _build)
            between = e["between"]
            name = e.get("name", f"{between[0]}--{between[1]}")
            f = f"{pre}elements[{name}]"
            typ = e["type"]
            schema = ELEMENT_TYPES[typ]
        else:
            name, f, typ, between, schema = _element_checks(pre, k, e, index, estimated, seen)
        items = [(kk, v, f"{f}.{kk}") for kk, v in e.items() if kk not in _ELEMENT_META]

    if template is not None:                # the static values in place, the others evaluated below
        p, todo = template[0].copy(), template[1]
    else:
        p, todo = {}, items
    for kk, v, fld in todo:
        if static is not None:
            hit = static.get(fld, _MISSING)
            if hit is not _MISSING:             # a static value (see _static_values), checked before
                p[kk] = hit
                continue
        if kk in STRING_KEYS:
            if v not in STRING_KEYS[kk]:
                raise InputError(fld, v, f"one of {', '.join(STRING_KEYS[kk])}")
            p[kk] = v
            if static is not None:
                static[fld] = v
        elif kk in MATERIAL_KEYS:
            p[kk] = _resolve_material(v, ctx, fld)
            if static is not None and (_static_expr(v) or isinstance(v, str) and v in material_names()):
                static[fld] = p[kk]
        else:
            val = evaluate(v, ctx, fld) if values is None else _evaluate_once(values, v, ctx, fld)
            if np.ndim(val):
                raise InputError(fld, v, "must evaluate to a single number")
            p[kk] = _check_value(fld, kk, val)
            if static is not None and (_static_expr(v) or type(v) in (int, float)):   # the bearing's, or a number
                static[fld] = p[kk]
    if static is not None and trusted and head is None:
        # every static field of this entry is known now: the next builds copy them (keys in table order)
        # and evaluate only the rest
        template = ({kk: static.get(fld) for kk, v, fld in items}, [t for t in items if t[2] not in static])
        static[("element", k)] = (name, f, typ, between, schema, items, template)

    i, j = index[between[0]], index[between[1]]
    if typ == "convection":
        for kk in CORRELATION_KEYS[p["correlation"]]:
            if kk not in p:
                raise InputError(f"{f}.{kk}", None, f"required by correlation '{p['correlation']}'")
        if p["correlation"] in HARRIS_COEFFICIENTS and p.get("fluid", "oil_air") != "air":
            if _get(ctx, "oil") is _MISSING:
                raise InputError(f"{f}.correlation", p["correlation"],
                                 "needs the lubricant 'oil' in the context (or fluid = \"air\")")
            if p.get("fluid", "oil_air") == "oil_air" and "oil_fraction" not in p:
                raise InputError(f"{f}.oil_fraction", None, "required for fluid = \"oil_air\"")
    if typ == "advection":
        if fixed[j]:
            raise InputError(f"{f}.between", between, "the downstream (second) node of an advection must be free")
        if not ("rho_kg_m3" in p and "cp_J_kgK" in p) and _get(ctx, "oil") is _MISSING:
            raise InputError(f"{f}.rho_kg_m3", None, "give rho_kg_m3 and cp_J_kgK or put the lubricant 'oil' in the context")
    if typ == "ball_race_contact":
        p["a_m"], p["b_m"], p["semi_axes_from"] = _semi_axes(f, p, ctx)
    return schema["cls"](name=name, type=typ, nodes=tuple(between), i=i, j=j, p=p, context=ctx)


def _semi_axes(f, p, ctx):
    """Per-ball semi-axes of a raceway: context arrays, else a fallback (see BallRaceContact)."""
    side = p["contact"]
    contacts = _get(ctx, "contacts")
    if contacts is not _MISSING:
        c = _get(contacts, side)
        a = _get(c, "a_m") if c is not _MISSING else _MISSING
        b = _get(c, "b_m") if c is not _MISSING else _MISSING
        if a is _MISSING or b is _MISSING:
            raise InputError(f"contacts.{side}.a_m", None, "context 'contacts' lacks the a_m/b_m arrays of this raceway")
        a, b = np.atleast_1d(np.asarray(a, float)), np.atleast_1d(np.asarray(b, float))
        if a.shape != b.shape:
            raise InputError(f"contacts.{side}.b_m", b, f"must have the shape of a_m {a.shape}")
        return a, b, "context"
    n_balls = p.get("n_balls")
    if n_balls is None:
        bearing = _get(ctx, "bearing")
        z = _get(bearing, "Z") if bearing is not _MISSING else _MISSING
        if z is _MISSING:
            raise InputError(f"{f}.n_balls", None, "no contacts in the context: give n_balls or bearing.Z")
        n_balls = z
    n_balls = int(round(float(n_balls)))
    if "a_fallback_m" in p and "b_fallback_m" in p:
        return np.full(n_balls, p["a_fallback_m"]), np.full(n_balls, p["b_fallback_m"]), "fallback"
    if "Q_fallback_N" in p:
        from thermobear.contact.hertz import hertz
        b_ = _get(ctx, "bearing")
        try:
            alpha = b_.alpha0
            Rx = b_.Rx_i(alpha) if side == "inner" else b_.Rx_o(alpha)
            Ry = b_.Ry_i if side == "inner" else b_.Ry_o
            hc = hertz(p["Q_fallback_N"], Rx, Ry, b_.E_prime)
        except AttributeError as exc:
            raise InputError(f"{f}.Q_fallback_N", p["Q_fallback_N"],
                             f"needs bearing.alpha0, Rx_i/Rx_o, Ry_i/Ry_o, E_prime in the context ({exc})") from None
        return np.full(n_balls, float(hc.a)), np.full(n_balls, float(hc.b)), "fallback (Hertz at Q_fallback_N)"
    raise InputError(f"contacts.{side}.a_m", None,
                     "not in the context and no fallback (a_fallback_m + b_fallback_m, or Q_fallback_N) given")
