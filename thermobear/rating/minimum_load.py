r"""SKF's requisite minimum load of a deep groove ball bearing.

Below a minimum load the balls may skid: the inertia of balls and cage and the lubricant's drag
ask more traction than the lightly loaded contacts carry, and the sliding smears balls and
raceways.  SKF [1]_ gives for deep groove ball bearings

.. math:: F_{rm} = k_r \left(\frac{\nu n}{1000}\right)^{2/3} \left(\frac{d_m}{100}\right)^2 \quad [\mathrm{kN}]

with ν the operating viscosity [mm²/s], n the speed [r/min], d_m = (d + D)/2 [mm] and the minimum load
factor k_r of the product tables (``materials/minimum_load.toml``, per series).  "If minimum load
cannot be reached, consider preloading" [1]_: an axial preload meets it too.  thermobear's load and loss
models assume the balls roll (Jones's raceway control, no gross slip), so a load below F_rm is outside
what they describe (:data:`thermobear.validity.LIMITS` ``minimum_load``).

References
----------
.. [1] SKF (2018). *Rolling bearings*, PUB BU/P1 17000/1 EN: "Requisite minimum load" (p. 106), deep groove
   ball bearings "Loads" (p. 254) and product tables 1.1 (k_r).
"""
from __future__ import annotations

from thermobear.arrays import checked, out
from thermobear.errors import InputError
from thermobear.files import data_dir, read_toml

__all__ = ["minimum_load_factor", "minimum_radial_load"]


def minimum_load_factor(kind: str, series: str | None):
    """SKF's minimum load factor k_r [-] of a deep groove series (``materials/minimum_load.toml``), or None where
    none is on file (other kinds, series the file does not list).

    >>> minimum_load_factor("deep_groove", "63"), minimum_load_factor("angular_contact", "72B")
    (0.03, None)
    """
    if kind != "deep_groove" or series is None:
        return None
    row = read_toml(str(data_dir("materials") / "minimum_load.toml"))["deep_groove"]["k_r"].get(str(series))
    return None if row is None else float(row["value"])


def minimum_radial_load(k_r, nu_cSt, n_rpm, dm):
    r"""SKF's requisite minimum radial load F_rm of a deep groove ball bearing [N].

    Parameters
    ----------
    k_r : array_like     minimum load factor [-] (:func:`minimum_load_factor`)
    nu_cSt : array_like  operating kinematic viscosity [mm²/s]
    n_rpm : array_like   speed [rpm]
    dm : array_like      pitch (mean) diameter [m]

    Returns
    -------
    float or ndarray   F_rm [N]

    Notes
    -----
    .. math:: F_{rm} = 10^3\, k_r \left(\frac{\nu n}{1000}\right)^{2/3} \left(\frac{d_m}{100\ \mathrm{mm}}\right)^2

    (SKF 2018 [1]_, p. 254; kN there).  It grows with viscosity and speed: a cold start needs more.

    Examples
    --------
    SKF's worked example (rope sheave, section C.2: 6207, k_r 0.025, ν 210 mm²/s at its coldest 20 °C, d_m
    53.5 mm, 2 450 r/min) prints F_rm = 0.44 kN; its equation gives 0.459 kN (4 % more, the rounding of an
    intermediate value, we suppose: the equation is what is implemented):

    >>> round(float(minimum_radial_load(0.025, 210.0, 2450.0, 0.0535)))
    459
    """
    k = checked("k_r", k_r, lo=0.0, what=" [-]")
    nu = checked("nu_cSt", nu_cSt, lo=0.0, what=" [mm²/s]")
    n = checked("n_rpm", n_rpm, lo=0.0, strict=False, what=" [rpm]")
    d = checked("dm", dm, lo=0.0, what=" [m]")
    if d.size and float(d.max()) > 10.0:
        raise InputError("dm", d, "pitch diameter in metres (got more than 10 m: millimetres?)")
    return out(1e3 * k * (nu * n / 1000.0) ** (2.0 / 3.0) * (d * 1e3 / 100.0) ** 2)
