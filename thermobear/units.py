"""Unit conversions used at the edges (scene files, CLI, data files).

Inside thermobear everything is SI: m, N, Pa, Pa s, rad/s, W, K (°C where the
name says ``_C``).  These few helpers are the only place the factors live.

>>> rpm_to_rad_s(30.0 / 3.141592653589793)
1.0
>>> round(C_to_K(40.0), 2)
313.15
"""
from __future__ import annotations

import numpy as np

MM = 1e-3            #: metres per millimetre
UM = 1e-6            #: metres per micrometre
GPA = 1e9            #: pascal per gigapascal
CST = 1e-6           #: m^2/s per centistoke (mm^2/s)
ZERO_C_K = 273.15    #: kelvin at 0 °C
NMM = 1e-3           #: newton metre per newton millimetre
L_PER_H = 1e-3 / 3600.0   #: m^3/s per litre per hour


def mm_to_m(x):
    """Millimetres to metres."""
    return np.asarray(x, dtype=float) * MM if np.ndim(x) else float(x) * MM


def rpm_to_rad_s(n_rpm):
    """Revolutions per minute to rad/s: ω = π n / 30."""
    return np.asarray(n_rpm, dtype=float) * (np.pi / 30.0) if np.ndim(n_rpm) else float(n_rpm) * np.pi / 30.0


def rad_s_to_rpm(omega):
    """rad/s to revolutions per minute."""
    return np.asarray(omega, dtype=float) * (30.0 / np.pi) if np.ndim(omega) else float(omega) * 30.0 / np.pi


def C_to_K(T_C):
    """Degrees Celsius to kelvin."""
    return np.asarray(T_C, dtype=float) + ZERO_C_K if np.ndim(T_C) else float(T_C) + ZERO_C_K


def K_to_C(T_K):
    """Kelvin to degrees Celsius."""
    return np.asarray(T_K, dtype=float) - ZERO_C_K if np.ndim(T_K) else float(T_K) - ZERO_C_K


def deg_to_rad(x):
    """Degrees to radians."""
    return np.asarray(x, dtype=float) * (np.pi / 180.0) if np.ndim(x) else float(x) * np.pi / 180.0
