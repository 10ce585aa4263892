r"""The ``[bearing]`` keys of a preloaded pair of angular contact bearings (machine-tool spindles).

Spindle bearings are mounted in pairs, back to back (DB) or face to face (DF), their preload set cold by ground
faces or spacers (a position preload) or by springs (a constant force).  A scene with ``arrangement`` describes
**one** bearing of a symmetric pair of two equal bearings:

* ``arrangement`` — ``"back_to_back"`` or ``"face_to_face"`` (Harris & Kotzalas 2007 [1] ch. 8);
* ``preload_N`` — the cold mounted preload of the pair [N], the axial load each bearing carries at 20 °C at rest
  without external load (what spindle catalogues call a light, medium or heavy preload);
* ``preload`` — ``"position"`` (default: rigid, ground faces or spacers; the preload follows the speed — the balls'
  centrifugal force, the inner rings' centrifugal growth — and the rings' and balls' temperatures) or ``"spring"``
  (a constant force: no thermal or speed change);
* ``spacer_mm`` — equal inner and outer spacers between the two bearings [mm] (default 0: adjacent): over the
  spacer the shaft and the housing grow apart as they warm, which relieves a back-to-back pair's preload when the
  shaft runs warmer than the housing and adds to a face-to-face one's (Harris & Kotzalas 2007 [1] ch. 8).

Assumptions, stated where the scene is read: both bearings run the same temperatures (adjacent in one housing);
the scene's thermal network is that bearing's own share of the machine; the scene's ``operation.Fa_N`` acts on
the shaft and ``operation.Fr_N`` on the pair's centre (the two share it); the scene's bearing is the one of the pair
that carries the larger axial load (conservative: the loaded one).  Moments and out-of-plane loads on the pair are
not modelled (refused), nor a prescribed temperature (the preload follows the solved temperatures).  The loads of
the pair: :mod:`thermobear.loads.pair`; the thermal preload's fixed point: :mod:`thermobear.coupled.preload`.

References
----------
.. [1] Harris, T. A. & Kotzalas, M. N. (2007). *Essential Concepts of Bearing Technology*, 5th ed., CRC Press,
   ch. 8 (bearing deflection and preloading: duplex pairs, position and spring preload).
"""
from __future__ import annotations

from thermobear.errors import InputError
from thermobear.loads.pair import PAIR_ARRANGEMENTS, PRELOAD_KINDS
from thermobear.schema import Field, check_value

__all__ = ["PAIR_ARRANGEMENTS", "PRELOAD_KINDS", "PAIR_FIELDS", "PAIR_WITH", "check_pair"]


#: ``[bearing]`` keys of a preloaded pair (the scene's bearing is one of two equal ones)
PAIR_FIELDS = {
    "arrangement": Field.choice(*PAIR_ARRANGEMENTS, doc="the scene's bearing is one of a preloaded pair of angular "
                                "contact bearings, back to back (DB) or face to face (DF); the loaded one"),
    "preload_N": Field.number("N", 0.0, None, lo_open=True, doc="the pair's cold mounted preload (each bearing's axial "
                              "load at 20 °C without external load, as mounted: a catalogue's light / medium / heavy "
                              "preload is the unmounted set's — the seats' fits add to it, not applied here)"),
    "preload": Field.choice(*PRELOAD_KINDS, doc="position (default: ground faces or spacers, the preload follows "
                            "the temperatures) or spring (a constant force)"),
    "spacer_mm": Field.number("mm", 0.0, 1e3, doc="length of equal inner and outer spacers between the pair's "
                              "bearings (default 0: adjacent); the shaft and housing grow apart over it as they warm"),
}
_ATTRS = {"arrangement": "arrangement", "preload_N": "preload_force", "preload": "preload_kind", "spacer_mm": "pair_spacer"}
_SCALE = {"spacer_mm": 1e-3}           #: file unit → the Scene attribute's SI unit


def _with(key: str):
    """:meth:`Scene.with_` of ``[bearing] key`` (None clears it), checked by its field (in the file's unit)."""
    def f(scene, v, name):
        return {_ATTRS[key]: None if v is None else check_value(v, PAIR_FIELDS[key], name) * _SCALE.get(key, 1)}
    if PAIR_FIELDS[key].kind == "number":
        f.address = f"bearing.{key}"
    return f


#: :meth:`Scene.with_` keys of a pair, as the scene file names them
PAIR_WITH = {k: _with(k) for k in PAIR_FIELDS}


def check_pair(s) -> None:
    """The pair's keys against each other, the bearing and the loads (module docstring): InputError naming the
    field, its value and what is accepted; nothing for a scene without them."""
    given = [(f"bearing.{k}", getattr(s, a)) for k, a in _ATTRS.items() if getattr(s, a) is not None]
    if not given:
        return
    if s.arrangement is None:
        raise InputError(given[0][0], given[0][1], "a key of a preloaded pair needs its pair: bearing.arrangement = "
                         f"{' or '.join(map(repr, PAIR_ARRANGEMENTS))}")
    b = s.bearing
    if b.kind != "angular_contact":
        raise InputError("bearing.arrangement", s.arrangement, f"only for angular contact bearings (a preloaded pair); "
                         f"{b.name} is a {b.kind.replace('_', ' ')} bearing: remove the key")
    if s.preload_force is None:
        raise InputError("bearing.preload_N", None, f"a {s.arrangement} pair needs its cold mounted preload, > 0 [N]")
    if b.width is None:
        raise InputError("bearing.width_mm", None, "a pair needs the bearings' width B [mm] (their spacing)")
    for key, v in (("operation.M_Nm", s.M), ("operation.Fz_N", s.Fz or None), ("operation.My_Nm", s.My)):
        if v is not None:
            raise InputError(key, v, "a pair scene takes the shaft's Fa_N and Fr_N only (moments and out-of-plane "
                             "loads on the pair are not modelled): remove it, or bearing.arrangement")
    if s.T_C is not None:
        raise InputError("operation.T_C", s.T_C, "a pair's position preload follows the solved ring and ball "
                         "temperatures: remove operation.T_C (or bearing.arrangement)")
