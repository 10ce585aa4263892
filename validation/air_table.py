"""Write the 1 atm dry-air table ``materials/air_1atm.toml`` from CoolProp, with its cubic-spline pieces.

Run it when CoolProp's air model changes (``pip install -e ".[coolprop]"``)::

    python validation/air_table.py materials/air_1atm.toml

The table holds density, viscosity, conductivity and c_p on 200–600 K at 1 K steps from ``PropsSI``
(Lemmon et al. 2000 pseudo-pure air; Lemmon & Jacobsen 2004 transport), and per property the
coefficients of scipy's not-a-knot ``CubicSpline`` through those values, four per 1 K interval
(v = c3 + s (c2 + s (c1 + s c0)), s = T − T_i): :mod:`thermobear.lubrication.air` evaluates the
pieces without importing scipy.interpolate.  With ``--from-table`` the values are kept and only the
pieces are rewritten (no CoolProp needed).  tests/test_air.py checks the shipped file against the
installed CoolProp and the pieces against scipy.
"""
from __future__ import annotations

import sys

import numpy as np
from scipy.interpolate import CubicSpline

from thermobear.files import read_toml
from thermobear.lubrication.air import P_ATM, T_RANGE_K

KEYS = {"rho": ("rho_kg_m3", "D"), "mu": ("mu_Pa_s", "V"), "k": ("k_W_mK", "L"), "cp": ("cp_J_kgK", "C")}


def coolprop_values(T):
    """Property columns at the grid temperatures from CoolProp's PropsSI (and its version)."""
    import CoolProp                                          # optional dependency (the coolprop extra)
    from CoolProp.CoolProp import PropsSI
    return {k: np.asarray(PropsSI(code, "T", T, "P", P_ATM, "Air"), float) for k, (_, code) in KEYS.items()}, \
        CoolProp.__version__


def spline_pieces(T, v) -> np.ndarray:
    """(n_intervals, 4) coefficients c0..c3 of the not-a-knot cubic spline through (T, v)."""
    return CubicSpline(T, v).c.T


def write(path, values: dict, version: str) -> None:
    T = np.arange(T_RANGE_K[0], T_RANGE_K[1] + 0.5, 1.0)
    lines = ["# Dry air at 1 atm, 200-600 K in 1 K steps, and the pieces of a cubic spline through each column",
             f"# Source: CoolProp {version} PropsSI(\"D\"|\"V\"|\"L\"|\"C\", \"T\", T, \"P\", 101325, \"Air\")",
             "# (Lemmon et al. 2000 pseudo-pure air; Lemmon & Jacobsen 2004 viscosity and conductivity).",
             "# spline_<column>: per 1 K interval c0, c1, c2, c3 of scipy's not-a-knot CubicSpline,",
             "# v = c3 + s (c2 + s (c1 + s c0)), s = T - T_i.",
             "# Written by validation/air_table.py; checked against the installed CoolProp and scipy by tests/test_air.py.",
             'name = "air_1atm"', f'coolprop_version = "{version}"', f"p_Pa = {P_ATM!r}",
             "T_K = [" + ", ".join(f"{t:.1f}" for t in T) + "]"]
    for k, (col, _) in KEYS.items():
        lines.append(f"{col} = [" + ", ".join(repr(float(x)) for x in values[k]) + "]")
    for k, (col, _) in KEYS.items():
        lines.append(f"spline_{col} = [" + ", ".join(repr(float(x)) for x in spline_pieces(T, values[k]).ravel()) + "]")
    with open(path, "w", encoding="utf-8") as fh:
        fh.write("\n".join(lines) + "\n")


def main(argv) -> int:
    path = argv[0] if argv else "materials/air_1atm.toml"
    T = np.arange(T_RANGE_K[0], T_RANGE_K[1] + 0.5, 1.0)
    if "--from-table" in argv:
        d = read_toml(path)
        values = {k: np.asarray(d[col], float) for k, (col, _) in KEYS.items()}
        version = d.get("coolprop_version", "8.0.0")
    else:
        values, version = coolprop_values(T)
    write(path, values, version)
    print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main([a for a in sys.argv[1:]]))
