r"""Dry-air properties from CoolProp, tabulated for speed.

CoolProp's ``PropsSI`` (Lemmon et al. 2000 pseudo-pure air; Lemmon & Jacobsen
2004 transport) costs about a millisecond per call, and importing CoolProp
about 1.7 s per process.  At the cavity pressure (1 atm) this module reads (once, at
import: :data:`AIR_1ATM`, an immutable :class:`AirTable`) density, viscosity, conductivity and
c_p on 200–600 K at 1 K steps from
``materials/air_1atm.toml`` — a table written from ``PropsSI`` by
``validation/air_table.py`` (its header names the CoolProp version), with the
pieces of a not-a-knot cubic spline through each column — and evaluates the
pieces (relative error < 1e-6 against ``PropsSI``; tests/test_air.py checks the
shipped table against the installed CoolProp and the pieces against scipy).
Other pressures go to ``PropsSI`` directly (CoolProp is imported only then: its
import costs ~1.7 s).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermobear.errors import InputError
from thermobear.files import data_dir, read_toml

__all__ = ["air_properties", "air_table", "AirTable", "AIR_1ATM", "P_ATM", "T_RANGE_K"]

P_ATM = 101325.0          #: cavity pressure used for the table [Pa]
T_RANGE_K = (200.0, 600.0)
_KEYS = ("rho", "mu", "k", "cp")


def _propssi(T, p):
    from CoolProp.CoolProp import PropsSI
    return {"rho": PropsSI("D", "T", T, "P", p, "Air"), "mu": PropsSI("V", "T", T, "P", p, "Air"),
            "k": PropsSI("L", "T", T, "P", p, "Air"), "cp": PropsSI("C", "T", T, "P", p, "Air")}


_TABLE_KEYS = {"rho": "rho_kg_m3", "mu": "mu_Pa_s", "k": "k_W_mK", "cp": "cp_J_kgK"}


def _grid_K() -> np.ndarray:
    return np.arange(T_RANGE_K[0], T_RANGE_K[1] + 0.5, 1.0)


@dataclass(frozen=True, eq=False)
class AirTable:
    """The 1 atm air table's spline (:func:`air_table`): ``c`` (4, n_intervals, 4 properties), read-only,
    coefficients c0..c3 of v = c3 + s (c2 + s (c1 + s c0)), s = T − T_i; ``pieces`` the same as nested
    tuples of Python floats, per interval and property (one temperature: no arrays)."""

    c: np.ndarray
    pieces: tuple


def air_table(path=None) -> AirTable:
    """The cubic pieces of ``materials/air_1atm.toml`` (or ``path``), read through
    :func:`thermobear.files.read_toml` and checked: they must pass through the tabulated values at the
    knots.  :data:`AIR_1ATM` holds the bundled table, read once when this module is imported."""
    d = read_toml(str(data_dir("materials") / "air_1atm.toml") if path is None else str(path))
    where, fix = "materials/air_1atm.toml", " (regenerate it with validation/air_table.py)"
    vals, pieces = [], []
    try:
        T = np.asarray(d["T_K"], float)
        for k in _KEYS:
            vals.append(np.asarray(d[_TABLE_KEYS[k]], float))
            pieces.append(np.asarray(d["spline_" + _TABLE_KEYS[k]], float))
    except (KeyError, TypeError, ValueError) as exc:
        raise InputError(where, str(exc), "columns T_K, " + ", ".join(_TABLE_KEYS.values()) + " and their spline_ "
                         "pieces, of numbers" + fix) from None
    if not np.array_equal(T, _grid_K()) or d.get("p_Pa") != P_ATM:
        raise InputError(where, d.get("p_Pa"), f"a 1 K grid on {T_RANGE_K} K at {P_ATM} Pa" + fix)
    n = T.size - 1
    if any(v.shape != T.shape or not np.all(np.isfinite(v) & (v > 0)) for v in vals) or \
            any(p.shape != (4 * n,) or not np.all(np.isfinite(p)) for p in pieces):
        raise InputError(where, None, f"{T.size} finite, positive values and {4 * n} spline coefficients per column" + fix)
    c = np.stack([p.reshape(n, 4).T for p in pieces], axis=-1)      # (4, n, 4 properties)
    knots = np.stack(vals, axis=-1)
    if not (np.allclose(c[3], knots[:-1], rtol=1e-12, atol=0.0)
            and np.allclose(_cubic(*c, 1.0), knots[1:], rtol=1e-9, atol=0.0)):
        raise InputError(where, None, "spline pieces through the tabulated values" + fix)
    c.flags.writeable = False
    rows = c.transpose(1, 2, 0).tolist()                             # (n, 4 properties, 4 coefficients)
    return AirTable(c=c, pieces=tuple(tuple(tuple(q) for q in r) for r in rows))


_FEW = 8        # up to this many temperatures, the pieces are evaluated one Python float at a time


def _at(tab, T):
    """(rho, mu, k, cp) of the table ``tab`` at one temperature T [K] (a Python float in range)."""
    i = min(int(T - T_RANGE_K[0]), len(tab.pieces) - 1)
    s = T - (T_RANGE_K[0] + i)
    return tuple(_cubic(*cq, s) for cq in tab.pieces[i])


def _cubic(c0, c1, c2, c3, s):
    """One cubic piece of the table's spline at s = T − T_i [K] (floats or arrays)."""
    return c3 + s * (c2 + s * (c1 + s * c0))


def air_properties(T_K, p_Pa=P_ATM, *, table=None):
    r"""Dry-air properties [SI] at temperature ``T_K`` [K] and pressure ``p_Pa`` [Pa].

    ``table``: the 1 atm spline (:func:`air_table`); default the bundled :data:`AIR_1ATM`.

    Returns
    -------
    dict  rho [kg/m³], mu [Pa s], k [W/(m K)], cp [J/(kg K)], nu = mu/rho [m²/s],
          Pr = mu cp / k [-]; floats for scalar input, arrays otherwise

    Examples
    --------
    >>> p = air_properties(300.0)
    >>> round(p["rho"], 3), round(p["k"], 4), round(p["Pr"], 3)
    (1.177, 0.0264, 0.707)
    """
    tab = AIR_1ATM if table is None else table
    if isinstance(T_K, float) and p_Pa == P_ATM and T_RANGE_K[0] <= T_K <= T_RANGE_K[1]:
        rho, mu, k, cp = _at(tab, float(T_K))                       # one temperature: Python floats
        return {"rho": rho, "mu": mu, "k": k, "cp": cp, "nu": mu / rho, "Pr": mu * cp / k}
    T = np.asarray(T_K, dtype=float)
    few = T.size <= _FEW
    Ts = T.ravel().tolist() if few else None
    if T.size and not (all(T_RANGE_K[0] <= t <= T_RANGE_K[1] for t in Ts) if few else
                       (T.min() >= T_RANGE_K[0] and T.max() <= T_RANGE_K[1])):      # NaN fails too
        raise InputError("T_K", T_K, f"air properties are provided for {T_RANGE_K[0]:g}..{T_RANGE_K[1]:g} K")
    if not (np.isfinite(p_Pa) and p_Pa > 0):
        raise InputError("p_Pa", p_Pa, "pressure must be > 0 [Pa]")
    if abs(p_Pa - P_ATM) < 1e-9 * P_ATM:
        if few:             # a few temperatures: the pieces on Python floats (the same operations)
            v = np.array([_at(tab, t) for t in Ts]).reshape(T.shape + (4,))
        else:
            c = tab.c
            i = np.minimum((T - T_RANGE_K[0]).astype(np.intp), c.shape[1] - 1)
            s = (T - (T_RANGE_K[0] + i))[..., None]
            v = _cubic(*c[:, i], s)
        out = {k: v[..., q] for q, k in enumerate(_KEYS)}
    else:
        out = {k: np.asarray(v, float) for k, v in _propssi(T, float(p_Pa)).items()}
    out["nu"] = out["mu"] / out["rho"]
    out["Pr"] = out["mu"] * out["cp"] / out["k"]
    if T.ndim == 0:
        return {k: float(v) for k, v in out.items()}
    return out


#: The bundled 1 atm air table (:func:`air_table` of ``materials/air_1atm.toml``), read once at import:
#: an immutable constant of the package, like its other data tables.
AIR_1ATM = air_table()
