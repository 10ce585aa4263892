r"""SKF's requisite minimum load of ball bearings: radial (deep groove), axial (angular contact, thrust).

Below a minimum load the balls may skid: the inertia of balls and cage and the lubricant's drag
ask more traction than the lightly loaded contacts carry, and the sliding smears balls and
raceways.  SKF [1]_ gives for deep groove ball bearings

.. math:: F_{rm} = k_r \left(\frac{\nu n}{1000}\right)^{2/3} \left(\frac{d_m}{100}\right)^2 \quad [\mathrm{kN}]

with ν the operating viscosity [mm²/s], n the speed [r/min], d_m = (d + D)/2 [mm] and the minimum load
factor k_r of the product tables (``materials/minimum_load.toml``, per series).  "If minimum load
cannot be reached, consider preloading" [1]_: an axial preload meets it too.  thermobear's load and loss
models assume the balls roll (Jones's raceway control, no gross slip), so a load below F_rm is outside
what they describe (:data:`thermobear.validity.LIMITS` ``minimum_load``).

A single row angular contact ball bearing (single, or a pair in tandem) and a single direction thrust ball
bearing need a minimum axial load [1]_

.. math:: F_{am} = A \left(\frac{n}{1000}\right)^2 \quad [\mathrm{kN}]

with A the minimum (axial) load factor of the product tables, one value per bearing (it differs by cage and
variant: ``materials/minimum_load.toml`` holds SKF's BECBP / BEP row of each catalogue 72B / 73B designation
and the row of each 511 / 512 / 513 one, written by ``validation/minimum_load.py``).  Angular contact pairs
back-to-back or face-to-face take a minimum radial load with a k_r instead [1]_: not on file.

References
----------
.. [1] SKF (2018). *Rolling bearings*, PUB BU/P1 17000/1 EN: "Requisite minimum load" (p. 106), deep groove
   ball bearings "Loads" (p. 254) and product tables 1.1 (k_r); angular contact ball bearings "Loads"
   (p. 398) and product tables 3.1 (A); thrust ball bearings "Loads" (p. 469) and product tables 5.1 (A).
"""
from __future__ import annotations

from thermobear.arrays import checked, out
from thermobear.contact.geometry import bearing_table, canonical_designation
from thermobear.errors import InputError
from thermobear.files import data_dir, read_toml

__all__ = ["AXIAL_KINDS", "minimum_axial_load", "minimum_axial_load_factor", "minimum_load_factor",
           "minimum_radial_load"]

#: The bearing kinds with a minimum axial load factor A (the data file's sections).
AXIAL_KINDS = ("angular_contact", "thrust")


def _table() -> dict:
    return read_toml(str(data_dir("materials") / "minimum_load.toml"))


def minimum_load_factor(kind: str, series: str | None):
    """SKF's minimum load factor k_r [-] of a deep groove series (``materials/minimum_load.toml``), or None where
    none is on file (other kinds, series the file does not list).

    >>> minimum_load_factor("deep_groove", "63"), minimum_load_factor("angular_contact", "72B")
    (0.03, None)
    """
    if kind != "deep_groove" or series is None:
        return None
    row = _table()["deep_groove"]["k_r"].get(str(series))
    return None if row is None else float(row["value"])


def minimum_axial_load_factor(bearing):
    """SKF's minimum axial load factor A [-] of a catalogue angular contact or thrust bearing, with the SKF row it is
    of: ``(A, designation, source)``, or None where none is on file.

    Parameters
    ----------
    bearing : str or BallBearing   catalogue designation (``"7210"``, ``"7205 B"``, ``"51208"``; aliases resolved)
                                   or a bearing whose ``name`` is one (a scene's ``scene.bearing``)

    Returns
    -------
    tuple or None
        A [-] (F_am in kN, :func:`minimum_axial_load`), SKF's designation of the row (``"7210 BECBP"``) and its
        source line; None for a deep groove bearing, a series or size SKF's tables do not list (70 C/E, 719 C/E,
        7300 B, 51205-3ball) or a name outside the catalogue.

    Examples
    --------
    >>> minimum_axial_load_factor("7210B")[:2], minimum_axial_load_factor("51208")[0]
    ((0.014, '7210 BECBP'), 0.058)
    >>> minimum_axial_load_factor("6208") is None
    True
    """
    name = str(getattr(bearing, "name", bearing))
    rows = {}
    for kind in AXIAL_KINDS:
        rows.update(_table().get(kind, {}).get("A", {}))
    key = name if name in rows else canonical_designation(name)
    if key not in rows:
        try:
            key = bearing_table(name)["name"]               # an alias ("7210B" -> "7210")
        except InputError:                                  # not a catalogue designation
            return None
    r = rows.get(key)
    return None if r is None else (float(r["value"]), str(r["designation"]), str(r["source"]))


def minimum_axial_load(A, n_rpm):
    r"""SKF's requisite minimum axial load F_am of a single row angular contact ball bearing (single, or a pair in
    tandem) or a thrust ball bearing [N].

    Parameters
    ----------
    A : array_like       minimum (axial) load factor [-] of the product tables (:func:`minimum_axial_load_factor`;
                         F_am in kN with n in r/min)
    n_rpm : array_like   speed [rpm]

    Returns
    -------
    float or ndarray   F_am [N]

    Notes
    -----
    .. math:: F_{am} = 10^3\, A \left(\frac{n}{1000}\right)^2

    (SKF 2018 [1]_, pp. 398 and 469; kN there): the balls' and cage's inertia grow as n², and so does the load
    that keeps the balls rolling.

    Examples
    --------
    A 7210 BECBP (A = 0.014, SKF 2018 table 3.1) at 3 200 and 8 070 rpm:

    >>> [round(float(F)) for F in minimum_axial_load(0.014, [3200.0, 8070.0])]
    [143, 912]
    """
    a = checked("A", A, lo=0.0, what=" [-]")
    n = checked("n_rpm", n_rpm, lo=0.0, strict=False, what=" [rpm]")
    return out(1e3 * a * (n / 1000.0) ** 2)


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
