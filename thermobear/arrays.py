"""Small array helpers shared by the physics modules (input checks, scalar-or-array output)."""
from __future__ import annotations

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


def _within(v, lo, strict):
    """All finite and > lo (>= lo): two reductions; NaN fails every comparison."""
    mn, mx = v.min(), v.max()
    return bool((mn > lo if strict else mn >= lo) and mx < np.inf)


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
