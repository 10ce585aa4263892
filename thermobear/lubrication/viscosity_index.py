r"""Viscosity index of an oil from its kinematic viscosities at 40 and 100 °C (ASTM D2270 [1]_), and its inverse.

With Y the kinematic viscosity at 100 °C and U at 40 °C [mm²/s], L and H the viscosities at 40 °C of the
standard's VI 0 and VI 100 reference oils of the same Y (its Table 1, interpolated linearly, 2 ≤ Y ≤ 70 mm²/s;
above 70 its formulas)

.. math::

    VI = 100\,\frac{L - U}{L - H} \quad (U \ge H), \qquad
    VI = \frac{10^N - 1}{0.00715} + 100, \quad N = \frac{\log_{10} H - \log_{10} U}{\log_{10} Y} \quad (U < H)

(Procedures A and B).  :func:`nu100_from_vi` inverts it for Y at a given U and VI (the route by which the bundled
ISO VG grades get their ν100, ``validation/lubricant_grades.py``, and by which a sampled grade tolerance keeps the
viscosity index, :meth:`thermobear.lubrication.lubricant.Lubricant.sampled`).

References
----------
.. [1] ASTM D2270, *Standard Practice for Calculating Viscosity Index from Kinematic Viscosity at 40 °C and
   100 °C*: Table 1 (L, H), Procedures A and B, the worked examples (U 73.30, Y 8.86 → VI 92.43; U 22.83,
   Y 5.05 → VI 156).
"""
from __future__ import annotations

import numpy as np

from thermobear.arrays import checked, out
from thermobear.errors import InputError
from thermobear.files import data_dir, read_toml

__all__ = ["astm_d2270_LH", "viscosity_index", "nu100_from_vi"]

_Y_TABLE_MAX = 70.0      #: above this ν100 [mm²/s] the standard's formulas replace its table


def _table():
    t = read_toml(str(data_dir("materials") / "astm_d2270_LH.toml"))
    return np.asarray(t["Y_mm2_s"]), np.asarray(t["L_mm2_s"]), np.asarray(t["H_mm2_s"])


def astm_d2270_LH(Y):
    r"""L and H of ASTM D2270 [mm²/s]: the 40 °C viscosities of the VI 0 and VI 100 reference oils whose viscosity
    at 100 °C is Y [mm²/s] (Table 1 interpolated, 2 ≤ Y ≤ 70; above 70 the standard's formulas
    L = 0.8353 Y² + 14.67 Y − 216, H = 0.1684 Y² + 11.85 Y − 97).

    >>> L, H = astm_d2270_LH(8.86)
    >>> round(float(L), 2), round(float(H), 2)
    (119.94, 69.48)
    """
    y, L, H = _table()
    Yv = checked("nu100_cSt", Y, lo=0.0, what=" [mm²/s]")
    if Yv.size and float(Yv.min()) < y[0]:
        raise InputError("nu100_cSt", Y, f"ASTM D2270 is defined from {y[0]:g} mm²/s at 100 °C")
    big = Yv > _Y_TABLE_MAX
    Lv = np.where(big, 0.8353 * Yv**2 + 14.67 * Yv - 216.0, np.interp(Yv, y, L))
    Hv = np.where(big, 0.1684 * Yv**2 + 11.85 * Yv - 97.0, np.interp(Yv, y, H))
    return out(Lv), out(Hv)


def viscosity_index(nu40_cSt, nu100_cSt):
    r"""ASTM D2270 viscosity index [-] of an oil of kinematic viscosities ν40, ν100 [mm²/s] (module docstring).

    >>> round(float(viscosity_index(73.30, 8.86)), 2), round(float(viscosity_index(22.83, 5.05)))
    (92.43, 156)
    """
    U = checked("nu40_cSt", nu40_cSt, lo=0.0, what=" [mm²/s]")
    Y = checked("nu100_cSt", nu100_cSt, lo=0.0, what=" [mm²/s]")
    L, H = (np.asarray(v, float) for v in astm_d2270_LH(Y))
    with np.errstate(divide="ignore", invalid="ignore"):
        N = (np.log10(H) - np.log10(U)) / np.log10(Y)
        vi = np.where(U >= H, (L - U) / (L - H) * 100.0, (10.0**N - 1.0) / 0.00715 + 100.0)
    return out(vi)


def nu100_from_vi(nu40_cSt, vi, *, tol_cSt: float = 1e-10):
    r"""Kinematic viscosity at 100 °C [mm²/s] of an oil with ν40 [mm²/s] and viscosity index ``vi`` [-]: ASTM D2270
    inverted, by bisection on ν100 in [2, 0.9 ν40] mm²/s (the index falls as ν100 falls at a given ν40), elementwise.

    >>> round(float(nu100_from_vi(40.0, 100.0)), 3)
    6.185
    >>> [round(float(v), 3) for v in nu100_from_vi([45.0, 50.0], 100.0)]
    [6.67, 7.136]
    """
    U = checked("nu40_cSt", nu40_cSt, lo=0.0, what=" [mm²/s]")
    V = np.broadcast_to(np.asarray(vi, float), np.broadcast_shapes(U.shape, np.shape(vi)))
    U = np.broadcast_to(U, V.shape)
    lo, hi = np.full(V.shape, 2.0), np.minimum(0.9 * U, 500.0)
    if np.any(hi <= lo):
        raise InputError("nu40_cSt", nu40_cSt, "ASTM D2270's inversion needs ν40 above 2.2 mm²/s")
    f_lo = np.asarray(viscosity_index(U, lo)) - V
    f_hi = np.asarray(viscosity_index(U, hi)) - V
    if np.any(np.sign(f_lo) == np.sign(f_hi)):
        raise InputError("vi", vi, "a viscosity index that some ν100 in [2, 0.9 ν40] mm²/s gives at this ν40")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        f = np.asarray(viscosity_index(U, mid)) - V
        left = np.sign(f) == np.sign(f_lo)
        lo, f_lo = np.where(left, mid, lo), np.where(left, f, f_lo)
        hi = np.where(left, hi, mid)
        if float(np.max(hi - lo)) <= tol_cSt:
            break
    return out(0.5 * (lo + hi))
