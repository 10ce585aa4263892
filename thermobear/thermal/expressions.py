r"""Safe arithmetic expressions of a network file, compiled once.

Numeric parameters of a network are numbers or short expressions over a context
(``"bearing.bore / 2"``, ``"pi * bearing.outer_diameter * bearing.width"``): numbers, context
names (mappings or objects, dotted), + − * / **, parentheses, the functions sqrt, log, log10,
exp, sin, cos, tan, radians, abs, min, max and the constant pi — nothing else.  Context values may
be numpy arrays (one value per operating point): every operation broadcasts.

:func:`compile_expression` parses an expression once and returns an :class:`Expression` whose
:meth:`~Expression.value` evaluates it in a context; :meth:`~Expression.roots` tells which context
names it reads (a network evaluates the ones that read only the bearing once, the rest for every
batch of operating points).
"""
from __future__ import annotations

import ast
import math
import operator
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from thermobear.errors import InputError

__all__ = ["Expression", "compile_expression", "evaluate", "evaluate_object", "lookup", "MISSING"]

_FUNCS = {"sqrt": np.sqrt, "log": np.log, "log10": np.log10, "exp": np.exp, "sin": np.sin,
          "cos": np.cos, "tan": np.tan, "radians": np.radians, "abs": np.abs, "min": np.minimum,
          "max": np.maximum}
_CONSTS = {"pi": math.pi}
_BINOPS = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
           ast.Pow: operator.pow}
MISSING = object()        #: what :func:`lookup` returns for an absent name
_NONE_MSG = ("has no value in this scene (None), but the network reads it: give it in the scene (a bearing's "
             "bore_mm, outer_diameter_mm, width_mm) or use a network that does not need it")
_NUM_TYPES = (int, float, np.floating, np.integer, np.ndarray)


def lookup(obj, name):
    """``obj[name]`` for a mapping, ``obj.name`` for an object; a sentinel when absent."""
    if isinstance(obj, Mapping):
        return obj.get(name, MISSING)
    return getattr(obj, name, MISSING)


class _Fail:
    """Error reporting of one evaluation: the field and the expression text."""

    def __init__(self, field, expr):
        self.field, self.expr = field, expr

    def __call__(self, why):
        raise InputError(self.field, self.expr, why)


def _num(f, node):
    """A compiled node that must give a number (or an array of numbers)."""
    if (isinstance(node, ast.Constant) and type(node.value) in (int, float)
            or isinstance(node, ast.Name) and node.id in _CONSTS):
        return f

    def num(ctx, fail):
        v = f(ctx, fail)
        if type(v) is not float and (isinstance(v, (bool, str)) or not isinstance(v, _NUM_TYPES)):
            fail(f"'{ast.unparse(node)}' " + (_NONE_MSG if v is None else "is not a number"))
        return v
    return num


def _compile(node):
    """The expression tree as nested closures ``f(context, fail)``."""
    if isinstance(node, ast.Constant):
        if isinstance(node.value, bool) or not isinstance(node.value, (int, float)):
            msg = f"only numbers are allowed as constants, not {node.value!r}"
            return lambda ctx, fail: fail(msg)
        val = float(node.value)
        return lambda ctx, fail: val
    if isinstance(node, ast.BinOp) and type(node.op) in _BINOPS:
        fa, fb = _num(_compile(node.left), node.left), _num(_compile(node.right), node.right)
        op = _BINOPS[type(node.op)]

        def binop(ctx, fail):
            a, b = fa(ctx, fail), fb(ctx, fail)
            try:
                with np.errstate(divide="raise", over="raise", invalid="raise"):
                    return op(a, b)
            except (ZeroDivisionError, OverflowError, ValueError, FloatingPointError) as exc:
                fail(f"cannot be evaluated: {exc}")
        return binop
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
        fo = _num(_compile(node.operand), node.operand)
        neg = isinstance(node.op, ast.USub)
        return lambda ctx, fail: -fo(ctx, fail) if neg else +fo(ctx, fail)
    if isinstance(node, ast.Name):
        name = node.id
        if name in _CONSTS:
            c = _CONSTS[name]
            return lambda ctx, fail: c

        def name_(ctx, fail):
            v = lookup(ctx, name)
            if v is MISSING:
                fail(f"unknown name '{name}'; the context provides: "
                     + ", ".join(sorted(map(str, ctx.keys())) if isinstance(ctx, Mapping) else []))
            return v
        return name_
    if isinstance(node, ast.Attribute):
        attr = node.attr
        if attr.startswith("_"):
            msg = f"private attribute '{attr}' is not allowed"
            return lambda ctx, fail: fail(msg)
        fbase = _compile(node.value)

        def attr_(ctx, fail):
            base = fbase(ctx, fail)
            if isinstance(base, (float, int, np.ndarray)):
                fail(f"attribute '{attr}' of a number is not allowed")
            v = lookup(base, attr)
            if v is MISSING:
                fail(f"unknown name '{ast.unparse(node)}' in the context")
            return v
        return attr_
    if isinstance(node, ast.Call):
        if not isinstance(node.func, ast.Name) or node.func.id not in _FUNCS or node.keywords:
            msg = f"only the functions {', '.join(sorted(_FUNCS))} may be called"
            return lambda ctx, fail: fail(msg)
        fn, fargs = _FUNCS[node.func.id], [_num(_compile(a), a) for a in node.args]
        if fn in (np.minimum, np.maximum) and len(fargs) != 2:
            msg = f"{node.func.id}() takes two arguments"
            return lambda ctx, fail: fail(msg)

        def call(ctx, fail):
            args = [g(ctx, fail) for g in fargs]
            try:
                with np.errstate(divide="raise", over="raise", invalid="raise"):
                    return fn(*args)
            except (ValueError, TypeError, FloatingPointError, OverflowError) as exc:
                fail(f"cannot be evaluated: {exc}")
        return call
    msg = (f"'{type(node).__name__}' is not allowed (numbers, names, + - * / **, "
           f"{', '.join(sorted(_FUNCS))}, pi)")
    return lambda ctx, fail: fail(msg)


def _roots(tree) -> frozenset:
    """The root context names an expression reads."""
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name) and node.id not in _CONSTS and node.id not in _FUNCS:
            out.add(node.id)
    return frozenset(out)


@dataclass(frozen=True)
class Expression:
    """A compiled expression (see :func:`compile_expression`)."""

    text: str
    fn: object
    roots: frozenset
    numeric: bool

    def value(self, context, field: str = "expression"):
        """The value in ``context``: a float, or a float array when a context value is an array;
        InputError naming ``field`` when it cannot be evaluated or is not finite."""
        fail = _Fail(field, self.text)
        v = self.fn(context, fail)
        if not self.numeric:
            return v
        if isinstance(v, float):
            if not math.isfinite(v):
                fail("evaluates to a non-finite value")
            return float(v)
        v = float(v) if np.ndim(v) == 0 else np.asarray(v, dtype=float)
        if not np.all(np.isfinite(v)):
            fail("evaluates to a non-finite value")
        return v


def compile_expression(expr, field: str = "expression", numeric: bool = True) -> Expression:
    """Parse a number or an expression string once (InputError naming ``field`` when it is not one).

    ``numeric=False``: a (dotted) name giving any object (e.g. ``bearing.ring_material``).

    >>> e = compile_expression("bearing.bore / 2 + sqrt(4) * 1e-3")
    >>> e.value({"bearing": {"bore": 0.05}}), sorted(e.roots)
    (0.027, ['bearing'])
    """
    if isinstance(expr, bool):
        raise InputError(field, expr, "a number or an arithmetic expression string")
    if isinstance(expr, (int, float)):
        v = float(expr)
        return Expression(str(expr), lambda ctx, fail: v, frozenset(), numeric)
    if not isinstance(expr, str) or len(expr) > 400:
        raise InputError(field, expr, "a number or an arithmetic expression string (≤ 400 characters)")
    try:
        tree = ast.parse(expr.strip(), mode="eval")
    except SyntaxError as exc:
        raise InputError(field, expr, f"not a valid arithmetic expression ({exc.msg})") from None
    if not numeric and not isinstance(tree.body, (ast.Name, ast.Attribute)):
        raise InputError(field, expr, "a name or a dotted context name")
    fn = _compile(tree.body)
    return Expression(expr, _num(fn, tree.body) if numeric else fn, _roots(tree), numeric)


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
    return compile_expression(expr, field).value(context or {}, field)


def evaluate_object(expr, context, field):
    """Resolve a dotted context name (``bearing.ball_material``) to any object."""
    return compile_expression(expr, field, numeric=False).value(context, field)
