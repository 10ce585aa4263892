"""One strict schema for every table a user or a data file writes.

A table (a scene section, an inline lubricant or bearing, a data file's entry) is described by a
mapping ``key → Field``; :func:`check_table` returns the typed values or raises
:class:`~thermobear.errors.InputError` naming the field, the value and what is accepted:

* an unknown key lists the accepted ones (a misspelt key never silently changes the answer);
* a number is a TOML integer or float (never a boolean, never text), finite, inside its range;
* a boolean is a TOML boolean (``"false"`` is text, not false);
* a choice is one of its listed values;
* text is text; a list of names is a list of text; a table is a table; an interval is ``[lo, hi]``.

An estimated value may say how far it may lie from its nominal: an ``uncertainty`` table next to it
(:func:`check_uncertainty`, :class:`Uncertainty`), one syntax for every data file — materials,
lubricants, bearings, network nodes and elements, scene sections::

    k_W_mK = 42.7
    estimated = ["k_W_mK"]
    uncertainty.k_W_mK = { range = [40.0, 46.6], source = "ASM Handbook vol. 1: 40-46.6 W/(m K)" }
    # or { factor = [0.8, 1.25], distribution = "lognormal", source = "..." }  (times the nominal value)
    # or { offset = [-3.0, 3.0], distribution = "normal", source = "..." }     (plus, in the key's unit)

>>> from thermobear.schema import Field, check_table
>>> fields = {"n_rpm": Field.number("rpm", lo=0.0), "drag": Field.flag()}
>>> check_table({"n_rpm": 3200, "drag": False}, fields, "operation")
{'n_rpm': 3200.0, 'drag': False}
>>> try:
...     check_table({"drag": "false"}, fields, "models")
... except Exception as e:
...     print(e)
models.drag = 'false' — must be true or false (a TOML boolean, without quotes)
"""
from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

import numpy as np
from scipy.special import ndtri

from thermobear.errors import InputError

__all__ = ["Field", "check_table", "check_value", "real_number", "describe", "Uncertainty", "check_uncertainty",
           "UNCERTAINTY_FIELDS", "UNCERTAINTY_KINDS", "DISTRIBUTIONS"]


@dataclass(frozen=True)
class Field:
    """What one key accepts.

    kind : "number" | "integer" | "bool" | "choice" | "text" | "names" | "table" | "interval" | "any"
    unit : the key's unit (for messages and documentation)
    lo, hi : accepted range (numbers, integers); ``lo_open`` / ``hi_open`` exclude the ends
    choices : accepted values of a choice
    doc : one line for the documentation
    required : the table must hold the key
    """

    kind: str
    unit: str = "-"
    lo: float | None = None
    hi: float | None = None
    lo_open: bool = False
    hi_open: bool = False
    choices: tuple = ()
    doc: str = ""
    required: bool = False

    @classmethod
    def number(cls, unit="-", lo=None, hi=None, *, lo_open=False, hi_open=False, doc="", required=False):
        """A finite real number (TOML integer or float) in [lo, hi] (ends excluded when open)."""
        return cls("number", unit, lo, hi, lo_open, hi_open, doc=doc, required=required)

    @classmethod
    def integer(cls, unit="-", lo=None, hi=None, *, doc="", required=False):
        """A whole number (TOML integer, or a float with no fraction) in [lo, hi]."""
        return cls("integer", unit, lo, hi, doc=doc, required=required)

    @classmethod
    def flag(cls, doc="", required=False):
        """A TOML boolean."""
        return cls("bool", doc=doc, required=required)

    @classmethod
    def choice(cls, *choices, doc="", required=False):
        """One of ``choices`` (text)."""
        return cls("choice", choices=tuple(choices), doc=doc, required=required)

    @classmethod
    def text(cls, doc="", required=False):
        """Text."""
        return cls("text", doc=doc, required=required)

    @classmethod
    def names(cls, doc=""):
        """A list of text."""
        return cls("names", doc=doc)

    @classmethod
    def table(cls, doc=""):
        """A table (checked by its owner)."""
        return cls("table", doc=doc)

    @classmethod
    def interval(cls, unit="-", doc=""):
        """Two finite numbers ``[lo, hi]`` with lo <= hi."""
        return cls("interval", unit, doc=doc)

    @classmethod
    def anything(cls, doc=""):
        """Any TOML value (checked by its owner)."""
        return cls("any", doc=doc)

    def range_text(self) -> str:
        lo, hi = self.lo, self.hi
        u = "" if self.unit in ("-", "") else f" [{self.unit}]"
        if lo is not None and hi is not None:
            return f"in {'(' if self.lo_open else '['}{lo:g}, {hi:g}{')' if self.hi_open else ']'}{u}"
        if lo is not None:
            return f"{'>' if self.lo_open else '>='} {lo:g}{u}"
        if hi is not None:
            return f"{'<' if self.hi_open else '<='} {hi:g}{u}"
        return f"finite{u}"


def real_number(value):
    """``value`` as a float when it is a real number — a Python or numpy integer or float, or a 0-d
    numeric array — else None (a bool, text, a complex number, an array of several values).

    >>> real_number(3), real_number(np.float32(0.5)), real_number(np.array(2)), real_number(True), real_number("1")
    (3.0, 0.5, 2.0, None, None)
    """
    if isinstance(value, np.ndarray) and value.ndim == 0 and value.dtype.kind in "iuf":
        value = value[()]
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        return None
    try:
        return float(value)
    except OverflowError:                 # an integer beyond the float range: refused as not finite
        return float("inf") if value > 0 else float("-inf")


def check_value(value, f: Field, where: str):
    """The typed value of one key (see :class:`Field`), or InputError naming ``where``.  A number may be
    any real number (:func:`real_number`: numpy scalars and 0-d arrays too), converted to float once."""
    k = f.kind
    if k in ("number", "integer"):
        what = "a whole number" if k == "integer" else "a number"
        v = real_number(value)
        if v is None:
            raise InputError(where, value, f"must be {what} {f.range_text()} (a TOML number, without quotes)")
        if not math.isfinite(v):
            raise InputError(where, value, f"must be finite: {what} {f.range_text()}")
        if k == "integer" and v != int(v):
            raise InputError(where, value, f"must be {what} {f.range_text()}")
        if ((f.lo is not None and (v < f.lo or (f.lo_open and v == f.lo)))
                or (f.hi is not None and (v > f.hi or (f.hi_open and v == f.hi)))):
            raise InputError(where, value, f"must be {f.range_text()}")
        return int(v) if k == "integer" else v
    if k == "bool":
        if not isinstance(value, bool):
            raise InputError(where, value, "must be true or false (a TOML boolean, without quotes)")
        return value
    if k == "choice":
        if not isinstance(value, str) or value not in f.choices:
            raise InputError(where, value, f"must be one of {', '.join(map(str, f.choices))}")
        return value
    if k == "text":
        if not isinstance(value, str):
            raise InputError(where, value, "must be text (in quotes)")
        return value
    if k == "names":
        if not isinstance(value, (list, tuple)) or not all(isinstance(v, str) for v in value):
            raise InputError(where, value, "must be a list of names, e.g. [\"D_mm\", \"fi\"]")
        return tuple(value)
    if k == "interval":
        pair = [real_number(v) for v in value] if isinstance(value, (list, tuple)) else []
        if len(pair) != 2 or None in pair or not all(map(math.isfinite, pair)) or pair[0] > pair[1]:
            raise InputError(where, value, "must be two finite numbers [lo, hi] with lo <= hi")
        return (pair[0], pair[1])
    if k == "table":
        if not isinstance(value, dict):
            raise InputError(where, value, "must be a table, e.g. { key = value }")
        return value
    return value


def check_table(table, fields: dict, where: str, *, extra=None) -> dict:
    """Typed values of a table: every key known (``fields``), every value of its kind.

    Parameters
    ----------
    table : dict       the parsed TOML table
    fields : dict      key → :class:`Field`
    where : str        the table's name in messages (e.g. ``"lubricant"``, ``"bearing"``)
    extra : callable   optional ``extra(key) -> Field | None`` for keys of an open family
                       (e.g. per-node temperatures); None: the key is unknown

    Returns
    -------
    dict   key → typed value, for the keys present (missing optional keys are left out)
    """
    if not isinstance(table, dict):
        raise InputError(where, table, "must be a table ([section] or { key = value })")
    out = {}
    for key, value in table.items():
        f = fields.get(key)
        if f is None and extra is not None:
            f = extra(key)
        if f is None:
            raise InputError(f"{where}.{key}", value, f"unknown key; accepted: {', '.join(sorted(fields))}")
        out[key] = check_value(value, f, f"{where}.{key}")
    for key, f in fields.items():
        if f.required and key not in table:
            raise InputError(f"{where}.{key}", None, f"missing required key ({f.doc or f.kind})")
    return out


def describe(fields: dict) -> list:
    """Rows ``(key, kind/unit, accepted, doc)`` of a field table (for documentation and ``init``)."""
    rows = []
    for key, f in fields.items():
        acc = (", ".join(map(str, f.choices)) if f.kind == "choice" else f.range_text()
               if f.kind in ("number", "integer") else "true / false" if f.kind == "bool" else f.kind)
        rows.append((key, f.unit, acc, f.doc))
    return rows


# --------------------------------------------------------------------------- uncertainty of estimated values
UNCERTAINTY_KINDS = ("factor", "offset", "range")
DISTRIBUTIONS = ("uniform", "normal", "lognormal")
_Z95 = 1.6448536269514722     # standard normal 95 % quantile: [lo, hi] of a normal / lognormal is its 5-95 % interval

#: The keys of one uncertainty entry (``uncertainty.<key> = { ... }``): exactly one of factor / offset / range.
UNCERTAINTY_FIELDS = {
    "factor": Field.interval("-", doc="[lo, hi] times the nominal value (which may be an expression)"),
    "offset": Field.interval("key's unit", doc="[lo, hi] added to the nominal value"),
    "range": Field.interval("key's unit", doc="[lo, hi] absolute values"),
    "distribution": Field.choice(*DISTRIBUTIONS, doc="uniform: [lo, hi] is the support; normal, lognormal: "
                                 "[lo, hi] is the 5-95 % interval (default uniform)"),
    "source": Field.text("where the range comes from, or the reasoning behind it", required=True),
}


@dataclass(frozen=True)
class Uncertainty:
    """How far an estimated value may lie from its nominal, and how its draws are distributed.

    Attributes
    ----------
    kind : str           ``"factor"`` (the value times a draw), ``"offset"`` (the value plus a draw, in
                         the key's unit) or ``"range"`` (the draw is the value)
    lo, hi : float       ``uniform``: the support of the draws; ``normal`` / ``lognormal``: their
                         5 % and 95 % quantiles (the normal's mean is the mid-point, the lognormal's
                         median the geometric mean)
    distribution : str   ``"uniform"``, ``"normal"`` or ``"lognormal"``
    source : str         where the range comes from, or the reasoning
    integer : bool       a whole-number key (e.g. a number of balls): uniform draws of a range are the
                         whole numbers lo … hi, equally likely; other draws are rounded

    >>> u = Uncertainty("factor", 0.8, 1.25, "lognormal", "x")
    >>> [round(float(v), 4) for v in u.quantile([0.05, 0.5, 0.95])]
    [0.8, 1.0, 1.25]
    >>> float(u.apply(2.0, 1.1)), float(Uncertainty("offset", -1.0, 1.0).apply(20.0, 0.5))
    (2.2, 20.5)
    """

    kind: str
    lo: float
    hi: float
    distribution: str = "uniform"
    source: str = ""
    integer: bool = False

    def quantile(self, u):
        """Draws at probabilities ``u`` in (0, 1) (array_like): the inverse distribution function."""
        u = np.asarray(u, dtype=float)
        if self.integer and self.kind == "range":
            if self.distribution == "uniform":
                return np.minimum(np.floor(self.lo + u * (self.hi - self.lo + 1.0)), self.hi)
            return np.round(Uncertainty(self.kind, self.lo, self.hi, self.distribution).quantile(u))
        if self.distribution == "uniform":
            return self.lo + u * (self.hi - self.lo)
        if self.distribution == "normal":
            return 0.5 * (self.lo + self.hi) + 0.5 * (self.hi - self.lo) / _Z95 * ndtri(u)
        a, b = math.log(self.lo), math.log(self.hi)
        return np.exp(0.5 * (a + b) + 0.5 * (b - a) / _Z95 * ndtri(u))

    def apply(self, nominal, draw):
        """The value at ``draw`` (a number or an array over operating points) of a ``nominal`` value."""
        if self.kind == "factor":
            return nominal * draw
        if self.kind == "offset":
            return nominal + draw
        return draw + 0.0 * nominal

    def as_dict(self) -> dict:
        return {self.kind: [self.lo, self.hi], "distribution": self.distribution, "source": self.source}


def check_uncertainty(table, values: dict, where: str) -> dict:
    """The typed ``uncertainty`` table of a data table: key → :class:`Uncertainty`.

    Parameters
    ----------
    table : dict     ``{key: {factor|offset|range = [lo, hi], distribution = ..., source = ...}}``
    values : dict    the numeric keys the uncertainty may name → their :class:`Field` (bounds of an
                     absolute ``range``), or None for a value without a field (e.g. an expression)
    where : str      the table's name in messages

    A key that is not a numeric value of the table is refused with the accepted keys; so is an entry
    with none or two of factor / offset / range, a non-positive factor or lognormal bound, and an
    absolute range outside the key's accepted values.

    >>> check_uncertainty({"k_W_mK": {"range": [40, 46.6], "source": "ASM"}},
    ...                   {"k_W_mK": Field.number("W/(m K)", 0.0)}, "aisi-52100")["k_W_mK"].hi
    46.6
    """
    table = check_value(table, Field.table(), f"{where}.uncertainty")
    out = {}
    for key, entry in table.items():
        w = f"{where}.uncertainty.{key}"
        if key not in values:
            raise InputError(w, entry, "names no numeric value of this table; accepted: "
                             + (", ".join(sorted(values)) or "none"))
        e = check_table(entry, UNCERTAINTY_FIELDS, w)
        kinds = [k for k in UNCERTAINTY_KINDS if k in e]
        if len(kinds) != 1:
            raise InputError(w, entry, "give exactly one of factor = [lo, hi], offset = [lo, hi], range = [lo, hi]")
        kind = kinds[0]
        lo, hi = e[kind]
        dist = e.get("distribution", "uniform")
        if (kind == "factor" or dist == "lognormal") and lo <= 0.0:
            raise InputError(f"{w}.{kind}", [lo, hi], "a factor or a lognormal interval must be > 0")
        f = values[key]
        if kind == "range" and f is not None:
            for v in (lo, hi):
                check_value(v, f, f"{w}.range")
        out[key] = Uncertainty(kind, lo, hi, dist, e["source"], integer=f is not None and f.kind == "integer")
    return out
