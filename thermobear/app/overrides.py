"""``--set key=value``: the command line's overrides of a scene, each checked as in a scene file.

A key is a :meth:`~thermobear.scene.Scene.with_` override (``n_rpm``, ``Fa_N``, ``T_C``, ``lubricant``,
``bearing``, ``seals``, ...) or one of the prefixed forms:

* ``models.<key>`` forces a model (the scene's ``[models]`` table);
* ``fixed_C.<node>`` imposes a measured node temperature [°C] (``[thermal] fixed_C``);
* ``parameters.<name>`` sets a network parameter (``[thermal.parameters]``);
* a scene file's number as it is written there, with or without its section (``lubricant.flow_L_h``,
  ``flow_L_h``, ``operation.n_rpm``, ``T_in_C``): the with_ key that sets it;
* ``bearing.<key>`` sets a key of the scene's ``[bearing]`` table (``clearance_group``, ``Pd_mm``, ``D_mm``, ...:
  :data:`thermobear.contact.geometry.FIELDS`; ``clearance_group`` alone means ``bearing.clearance_group``): the
  bearing is rebuilt from the file's table (or the ``bearing`` given) with the keys set.

An unknown key is refused naming ``--set <key>`` and what is accepted.
"""
from __future__ import annotations

import tomllib

from thermobear.contact.geometry import FIELDS as BEARING_KEYS
from thermobear.errors import InputError
from thermobear.scene import load_scene
from thermobear.scene.scene import FILE_KEYS, WITH_KEYS

__all__ = ["overrides", "load_scene_with", "SET_FORMS"]

#: ``--set`` keys whose value is a name (a catalogue designation, a lubricant), never a number
_NAMED = ("bearing", "lubricant", "bearing.catalog", "bearing.series", "bearing.name")   # text that may read as a number
_TABLES = (("fixed_C.", "T_fixed_C"), ("models.", "models"), ("parameters.", "network_parameters"))
#: the prefixed forms ``--set`` takes besides the Scene.with_ keys
SET_FORMS = ("models.<key>, fixed_C.<node>, parameters.<name>, bearing.<key> (a [bearing] key: clearance_group, "
             "Pd_mm, D_mm, ...; clearance_group alone is bearing.clearance_group)")
_BARE_BEARING = ("clearance_group",)             # [bearing] keys --set takes without the prefix
#: a scene file's key as written, with or without its section (``lubricant.flow_L_h``, ``flow_L_h``, ``T_in_C``) →
#: its with_ key; a bare key only where one section has it
_AS_WRITTEN = {**{a.split(".", 1)[1]: k for a, k in FILE_KEYS.items()
                  if sum(b.split(".", 1)[1] == a.split(".", 1)[1] for b in FILE_KEYS) == 1}, **FILE_KEYS}


def _value(text: str):
    """A ``--set`` value read as TOML (``6500``, ``true``, ``"skf"``); a bare word stays text."""
    try:
        return tomllib.loads(f"v = {text}")["v"]
    except tomllib.TOMLDecodeError:
        return text.strip()


def _bearing_key(key: str, val, out: dict, table: dict):
    """``bearing.<key>``: a key of the bearing's table, or a with_ key of the [bearing] section (seals, cage)."""
    if key in BEARING_KEYS or key == "catalog":
        table[key] = val
    elif key in WITH_KEYS:
        out[key] = val
    else:
        raise InputError(f"--set bearing.{key}", val, "not a key --set takes: bearing.<key> takes the bearing's "
                         f"table keys ({', '.join(BEARING_KEYS)}), seals, seal_sides, cage, shaft_fit, housing_fit; "
                         "set other [bearing] keys in the scene file")


def overrides(items, bearing_table: dict | None = None) -> dict:
    """``--set key=value`` items → :meth:`Scene.with_` keyword arguments (``models.<key>``, ``fixed_C.<node>``,
    ``parameters.<name>`` go into their tables; ``bearing.<key>`` into ``bearing``, the table ``bearing_table``
    — the scene file's ``[bearing]`` — or the ``bearing`` given, with the keys set).

    >>> overrides(["n_rpm=6500", "clearance_group=C3"], {"catalog": "6208"})
    {'n_rpm': 6500, 'bearing': {'catalog': '6208', 'clearance_group': 'C3'}}
    """
    out: dict = {}
    table: dict = {}
    for it in items or []:
        if "=" not in it:
            raise InputError("--set", it, "expected key=value, e.g. --set n_rpm=6500 or --set models.losses=skf")
        k, v = (s.strip() for s in it.split("=", 1))
        val = _value(v)
        if k in _NAMED and isinstance(val, (int, float)) and not isinstance(val, bool):
            val = v                    # a catalogue designation that reads as a number: 6308, 51110
        prefixed = next(((p, t) for p, t in _TABLES if k.startswith(p)), None)
        if prefixed:
            out.setdefault(prefixed[1], {})[k[len(prefixed[0]):]] = val
        elif k.startswith("bearing.") or k in _BARE_BEARING:
            _bearing_key(k.removeprefix("bearing."), val, out, table)
        elif k in WITH_KEYS:
            out[k] = val
        elif k in _AS_WRITTEN:
            out[_AS_WRITTEN[k]] = val
        else:
            raise InputError(f"--set {k}", val, f"unknown key; accepted: {', '.join(WITH_KEYS)}, a scene file's "
                             f"number as written (e.g. lubricant.flow_L_h, T_in_C), {SET_FORMS}")
    if table:
        base = out.get("bearing", bearing_table or {})
        base = {"catalog": base} if isinstance(base, str) else dict(base)
        out["bearing"] = {**base, **table}
    return out


def load_scene_with(path, sets=None):
    """The scene of a file with the ``--set`` overrides applied (each checked as in a scene file)."""
    scene = load_scene(path)
    if sets:
        ov = overrides(sets, scene.raw.get("bearing"))
        if "T_fixed_C" in ov:
            ov["T_fixed_C"] = {**scene.T_fixed_C, **ov["T_fixed_C"]}
        # an error of a key given as the file writes it (flow_L_h) names that key, not the with_ key it set
        given = {_AS_WRITTEN[k]: k for k in (it.split("=", 1)[0].strip() for it in sets)
                 if k in _AS_WRITTEN and k not in WITH_KEYS}
        try:
            scene = scene.with_(**ov)
        except InputError as e:
            if e.field not in given:
                raise
            raise type(e)(given[e.field], e.value, e.expected) from None
    return scene
