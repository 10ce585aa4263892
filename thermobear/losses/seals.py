r"""Friction of the contact seals of a bearing (SKF 2004 seal model).

SKF's model of the frictional moment of a sealed bearing [1]_ adds, for contact seals, a moment
that depends on the seal type, the bearing's outside diameter class and the seal counterface
diameter d_s only (not on speed, load or temperature):

.. math::

    M_{seal} = K_{S1}\, d_s^{\beta} + K_{S2} \quad [\mathrm{N\,mm}],\ d_s\ [\mathrm{mm}]

with K_S1, K_S2, β from SKF's table 4 (``materials/skf_constants.toml`` ``[seals]``, a source per
row).  The constants are those of a bearing with two seals; with one seal SKF takes half the
moment, except RSL seals of deep groove ball bearings with D > 25 mm, whose value holds for one
seal as for two [1]_.  Shields (Z, RZ: no contact) add nothing.  The power is M_seal ω.

The function :func:`seal_moment_Nmm` works in SKF's units (mm, N mm); :func:`seal_friction`
returns SI (N m, W).

References
----------
.. [1] SKF General Catalogue 6000 EN (2005), "The SKF model for calculating the frictional moment",
   "Frictional moment of seals", table 4; unchanged in SKF Rolling bearings 17000 EN (2018).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermobear.errors import InputError
from thermobear.files import data_dir, read_toml
from thermobear.units import NMM

__all__ = ["SEAL_TYPES", "CONTACT_SEALS", "BALL_SEALS", "seal_material", "SealFriction", "seal_moment_Nmm", "seal_constants", "seal_friction",
           "seal_counterface_estimate_mm"]

#: Seal designations a scene may name: ``"none"``, ``"shield"`` (Z, RZ: non-contact, no friction) and
#: SKF's contact seals (RSL, RSH, RS1 for ball bearings; LS, CS, CS2, CS5 are roller-bearing seals).
SEAL_TYPES = ("none", "shield", "RSL", "RSH", "RS1", "LS", "CS", "CS2", "CS5")
#: The contact seals (those with a friction moment).
CONTACT_SEALS = SEAL_TYPES[2:]
#: The seals a ball bearing's scene may name: none, shields and SKF's ball-bearing contact seals.
BALL_SEALS = SEAL_TYPES[:5]
_SAME_ROW = {"CS2": "CS", "CS5": "CS"}      # SKF table 4 gives one row for CS, CS2 and CS5


def seal_moment_Nmm(ds_mm, K_S1, K_S2, beta):
    r"""Frictional moment of the seals M_seal = K_S1 d_s^β + K_S2 [N mm] (SKF 2004 [1]_).

    Parameters
    ----------
    ds_mm : array_like   seal counterface diameter [mm]
    K_S1, K_S2, beta : float  SKF seal constants (:func:`seal_constants`; e.g. RS1 seals of a deep
                         groove bearing, D <= 62 mm: K_S1 = 0.023, K_S2 = 2, β = 2.25)

    Returns
    -------
    ndarray   moment of a bearing with two seals [N mm]

    Examples
    --------
    >>> round(float(seal_moment_Nmm(30.0, 0.023, 2.0, 2.25)), 2)
    50.45
    """
    return K_S1 * np.asarray(ds_mm, dtype=float) ** beta + K_S2


def seal_material() -> dict:
    """The lip material of the contact seals (``materials/skf_constants.toml`` ``[seals.material]``): its name, upper
    operating temperature ``T_max_C`` and brief limit ``T_brief_C`` [°C], and their source.

    >>> m = seal_material()
    >>> m["name"], m["T_max_C"], m["T_brief_C"]
    ('NBR', 100.0, 120.0)
    """
    return dict(read_toml(str(data_dir("materials") / "skf_constants.toml"))["seals"]["material"])


def _rows():
    return read_toml(str(data_dir("materials") / "skf_constants.toml"))["seals"]["rows"]


def seal_constants(seal_type: str, kind: str, D_mm: float) -> dict:
    """SKF's seal constants (K_S1, K_S2, beta, d_s, one_seal_full) of a seal type on a bearing kind
    with outside diameter ``D_mm`` [mm] (``materials/skf_constants.toml``).

    Raises InputError naming ``bearing.seals`` when the type is unknown, is not a seal of this
    bearing kind, or the outside diameter is outside SKF's rows.

    >>> c = seal_constants("RS1", "deep_groove", 80.0)
    >>> c["K_S1"], c["K_S2"], c["beta"]
    (0.018, 20.0, 2.25)
    """
    if seal_type not in CONTACT_SEALS:
        raise InputError("bearing.seals", seal_type, f"a contact seal ({', '.join(CONTACT_SEALS)}) for SKF's "
                         "seal model; 'none' and 'shield' have no seal friction")
    name = _SAME_ROW.get(seal_type, seal_type)
    rows = [r for r in _rows() if r["type"] == name]
    mine = [r for r in rows if r["kind"] == kind]
    if not mine:
        kinds = sorted({r["kind"] for r in rows})
        raise InputError("bearing.seals", seal_type, f"SKF gives {seal_type} seal constants for "
                         f"{', '.join(kinds)} bearings, not for a {kind} bearing")
    for r in mine:
        if r["D_over_mm"] < D_mm <= r["D_incl_mm"]:
            return {k: r[k] for k in ("K_S1", "K_S2", "beta", "d_s", "one_seal_full")}
    span = f"{min(r['D_over_mm'] for r in mine):g} < D <= {max(r['D_incl_mm'] for r in mine):g} mm"
    raise InputError("bearing.seals", seal_type, f"SKF's {seal_type} constants for {kind} bearings cover "
                     f"{span}; this bearing has D = {D_mm:g} mm")


def seal_counterface_estimate_mm(d_mm, D_mm):
    r"""Estimated seal counterface diameter d_s of a bearing without its product-table value [mm].

    .. math:: d_s \approx d + 0.25\,(D - d)

    Between the inner-ring recess d2 and shoulder d1 that SKF's product tables give for the seal
    counterface: 6208 d2 = 49.1 mm (-2RSH), d1 = 52.6 mm; 6210 d1 = 62.5 mm (SKF product tables, as
    transcribed in github.com/JRaposo-m/SKF-Bearing-Selection-Tool); the estimate gives 50 and 60 mm.
    An estimate: give ``bearing.seal_diameter_mm`` from the product table where it is known.

    >>> seal_counterface_estimate_mm(40.0, 80.0)
    50.0
    """
    return float(d_mm) + 0.25 * (float(D_mm) - float(d_mm))


@dataclass(frozen=True)
class SealFriction:
    """Seal friction of a bearing (arrays broadcast over operating points).

    M_Nm [N m] moment of the bearing's seals, P_W [W] power M ω, K_S1, K_S2, beta the SKF constants,
    n_seals the number of seals, ds_mm the counterface diameter [mm]."""

    M_Nm: object
    P_W: object
    K_S1: float
    K_S2: float
    beta: float
    n_seals: int
    ds_mm: float


def seal_friction(seal_type: str, kind: str, D_mm: float, ds_mm: float, n_rpm, n_seals: int = 2) -> SealFriction:
    r"""Friction moment and power of a bearing's contact seals, SKF 2004 [1]_.

    Parameters
    ----------
    seal_type : str     ``"none"``, ``"shield"`` or an SKF contact seal (:data:`SEAL_TYPES`)
    kind : str          bearing kind (``"deep_groove"``, ``"angular_contact"``, ...)
    D_mm : float        bearing outside diameter [mm] (selects SKF's row)
    ds_mm : float       seal counterface diameter [mm]
    n_rpm : array_like  speed of the rotating ring [r/min], >= 0
    n_seals : int       seals on the bearing: 0, 1 or 2

    Returns
    -------
    SealFriction   M_Nm [N m], P_W [W]

    Notes
    -----
    M = K_S1 d_s^β + K_S2 for two seals, half of it for one (RSL, deep groove, D > 25 mm: the same
    for one seal), converted once to N m; P = M ω, ω = π n / 30.  No seal ("none", "shield", or
    ``n_seals = 0``) → 0.

    Examples
    --------
    6208-2RS1 (D 80 mm, d_s 52.6 mm) at 3000 r/min: M = 0.018 × 52.6^2.25 + 20 = 154.1 N mm, 48.4 W.

    >>> r = seal_friction("RS1", "deep_groove", 80.0, 52.6, 3000.0)
    >>> round(r.M_Nm * 1e3, 1), round(float(r.P_W), 1)
    (154.1, 48.4)
    """
    if seal_type not in SEAL_TYPES:
        raise InputError("bearing.seals", seal_type, f"one of {', '.join(SEAL_TYPES)}")
    if n_seals not in (0, 1, 2):
        raise InputError("bearing.seal_sides", n_seals, "0, 1 or 2 seals")
    n = np.asarray(n_rpm, dtype=float)
    if n.size and not (n.min() >= 0 and n.max() < np.inf):
        raise InputError("n_rpm", n_rpm, "speed must be finite and >= 0 [rpm]")
    if seal_type in ("none", "shield") or n_seals == 0:
        zero = 0.0 * n
        return SealFriction(M_Nm=0.0, P_W=zero if zero.ndim else float(zero), K_S1=0.0, K_S2=0.0, beta=0.0,
                            n_seals=n_seals, ds_mm=float(ds_mm))
    if not (np.isfinite(ds_mm) and ds_mm > 0):
        raise InputError("bearing.seal_diameter_mm", ds_mm, "seal counterface diameter must be > 0 [mm]")
    c = seal_constants(seal_type, kind, float(D_mm))
    share = 1.0 if (n_seals == 2 or c["one_seal_full"]) else 0.5
    M = share * float(seal_moment_Nmm(ds_mm, c["K_S1"], c["K_S2"], c["beta"])) * NMM
    P = M * n * np.pi / 30.0
    return SealFriction(M_Nm=M, P_W=P if P.ndim else float(P), K_S1=c["K_S1"], K_S2=c["K_S2"], beta=c["beta"],
                        n_seals=n_seals, ds_mm=float(ds_mm))


