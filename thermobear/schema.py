"""One strict schema for every table a user or a data file writes.

A table (a scene section, an inline lubricant or bearing, a data file's entry) is described by a
mapping ``key → Field``; :func:`check_table` returns the typed values or raises
:class:`~thermobear.errors.InputError` naming the field, the value and what is accepted:

* an unknown key lists the accepted ones (a misspelt key never silently changes the answer);
* a number is a TOML integer or float (never a boolean, never text), finite, inside its range;
* a boolean is a TOML boolean (``"false"`` is text, not false);
* a choice is one of its listed values;
* text is text; a list of names is a list of text; a table is a table.

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
from dataclasses import dataclass

from thermobear.errors import InputError

__all__ = ["Field", "check_table", "check_value", "describe"]


@dataclass(frozen=True)
class Field:
    """What one key accepts.

    kind : "number" | "integer" | "bool" | "choice" | "text" | "names" | "table" | "any"
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


def check_value(value, f: Field, where: str):
    """The typed value of one key (see :class:`Field`), or InputError naming ``where``."""
    k = f.kind
    if k in ("number", "integer"):
        what = "a whole number" if k == "integer" else "a number"
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise InputError(where, value, f"must be {what} {f.range_text()} (a TOML number, without quotes)")
        v = float(value)
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
