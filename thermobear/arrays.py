"""Small array helpers shared by the physics modules (input checks, scalar-or-array output)."""
from __future__ import annotations

import dataclasses

import numpy as np

from thermobear.errors import InputError


def checked(name, v, *, lo=0.0, strict=True, what=""):
    """``v`` as a float array, finite and > lo (``strict``) or >= lo; else InputError naming ``name``.

    >>> checked("Q", [1.0, 2.0]).tolist()
    [1.0, 2.0]
    """
    v = np.asarray(v, dtype=float)
    if v.size and not _within(v, lo, strict):
        rel = ">" if strict else ">="
        raise InputError(name, v, f"must be finite and {rel} {lo:g}{what}")
    return v


def instance_of(value, cls, field: str, lookup=None, *, needs=()):
    """An object argument: ``value`` when it is a ``cls`` (or has every attribute in ``needs``), a catalogue
    name through ``lookup`` (e.g. :func:`~thermobear.contact.geometry.bearing`) where one is given; else
    InputError naming ``field`` and what it accepts.

    >>> instance_of(2.0, float, "x")
    2.0
    >>> try:
    ...     instance_of("7210", dict, "brg")
    ... except InputError as e:
    ...     print(e)
    brg = '7210' — must be a dict
    """
    if isinstance(value, cls) or (needs and all(hasattr(value, a) for a in needs)):
        return value
    if lookup is not None and isinstance(value, str):
        try:
            return lookup(value)
        except InputError as exc:          # the catalogue's answer, under the argument's name
            raise InputError(field, value, exc.expected) from None
    shown = value if isinstance(value, (str, int, float)) else type(value).__name__
    raise InputError(field, shown, f"must be a {cls.__name__}" + (" or its catalogue name" if lookup else ""))


def _within(v, lo, strict):
    """All finite and > lo (>= lo): two reductions (a few values: compared as Python floats); NaN fails
    every comparison."""
    if v.size <= _FEW:
        vals = v.ravel().tolist()
        return all(lo < x < _INF for x in vals) if strict else all(lo <= x < _INF for x in vals)
    mn, mx = _MIN(v, None), _MAX(v, None)
    return bool((mn > lo if strict else mn >= lo) and mx < _INF)


_INF = float("inf")
_FEW = 16
_MIN, _MAX = np.minimum.reduce, np.maximum.reduce


def above(v, lo=0.0, strict=True) -> bool:
    """All values of the float array ``v`` > lo (>= lo); +inf passes, NaN fails (a few values compared as
    Python floats, more by one reduction).

    >>> above(np.array([1.0, np.inf])), above(np.array([0.0, np.nan]), strict=False)
    (True, False)
    """
    if v.size <= _FEW:
        vals = v.ravel().tolist()
        return all(x > lo for x in vals) if strict else all(x >= lo for x in vals)
    m = _MIN(v, None)
    return bool(m > lo if strict else m >= lo)


def within(v, lo, hi) -> bool:
    """All values of the float array ``v`` in [lo, hi]; NaN fails.

    >>> within(np.array([20.0, 30.0]), -20.0, 150.0), within(np.array([np.nan]), 0.0, 1.0)
    (True, False)
    """
    if v.size <= _FEW:
        return all(lo <= x <= hi for x in v.ravel().tolist())
    return bool(lo <= _MIN(v, None) and _MAX(v, None) <= hi)


def finite_range(v):
    """(min, max) of a non-empty float array, or None if any value is NaN or ±inf."""
    mn, mx = v.min(), v.max()
    return (mn, mx) if (mn > -np.inf and mx < np.inf) else None


def out(x):
    """A 0-d result as a Python float, anything else as a float array.

    >>> out(np.array(2.0)), out([1, 2]).tolist()
    (2.0, [1.0, 2.0])
    """
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x


#: Fields that never carry the operating-point axis (per-ball azimuths: their length Z may equal B).
UNBATCHED = frozenset({"psi"})


def take(obj, index, B: int):
    """The operating point(s) ``index`` of a batched result: every array whose leading axis has
    length ``B`` is indexed along it, recursively through dataclasses, dicts, lists and tuples; the
    rest (per-ball azimuths — fields named in :data:`UNBATCHED` —, scalars, objects) is kept.

    A dataclass is rebuilt field by field without running its ``__init__`` (the slice of a checked
    result is checked).

    >>> take({"P_W": np.array([1.0, 2.0]), "psi": np.zeros(3)}, 1, 2)["P_W"]
    np.float64(2.0)
    """
    if isinstance(obj, np.ndarray):
        return obj[index] if obj.ndim >= 1 and obj.shape[0] == B else obj
    t = type(obj)
    if t is dict:
        return {k: v if k in UNBATCHED else take(v, index, B) for k, v in obj.items()}
    if t is list or t is tuple:
        return t(take(v, index, B) for v in obj)
    if not hasattr(t, "__dataclass_fields__") or isinstance(obj, type):
        return obj
    new = object.__new__(t)
    for f in dataclasses.fields(obj):
        v = getattr(obj, f.name)
        object.__setattr__(new, f.name, v if f.name in UNBATCHED else take(v, index, B))
    return new


def smooth_weight(c, lo: float, hi: float):
    r"""Weight of the upper model across a switch band: 0 at ``c <= lo``, 1 at ``c >= hi``, the C¹
    smoothstep in between.

    .. math:: w = 3 t^2 - 2 t^3, \qquad t = \min(1, \max(0, (c - lo)/(hi - lo)))

    >>> float(smooth_weight(0.05, 0.0, 0.1)), float(smooth_weight(1.0, 0.0, 0.1))
    (0.5, 1.0)
    """
    t = np.clip((np.asarray(c, float) - lo) / (hi - lo), 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)
