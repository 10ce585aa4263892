r"""Scene files: a bearing, its lubricant, loads, speed, and how heat leaves it.

A scene is a TOML file with units in the key names, converted to SI once here.
Sections (see ``examples/README.md`` for every key)::

    [scene]      name, description, source
    [bearing]    catalog = "7210"  and/or inline D_mm, dm_mm, Z, fi, fo, Pd_mm, alpha0_deg,
                 kind, bore_mm, outer_diameter_mm, width_mm, series, C0_kN, materials
    [lubricant]  name = "seed004-mineral" or inline nu40_cSt, nu100_cSt, rho15_kg_m3, alpha_p_1_Pa;
                 supply = "oil_jet" | "grease" | "oil_bath" | "oil_air" | "dry_film";
                 flow_L_h, T_in_C (oil jet); Rq_ball_um, Rq_ring_um (roughness);
                 mu_boundary, mu_full_film (mixed-lubrication friction, seed 000 eq 18)
    [operation]  n_rpm, Fa_N, Fr_N, M_Nm (tilt free) ; rotating = "inner" | "outer";
                 T_C (prescribed bearing/contact temperature: no thermal network needed)
    [thermal]    network = "oil_jet_ball_bearing" | ... ; T_ambient_C ; [thermal.parameters];
                 fixed_C = { inner_ring = 52.0, outer_ring = 48.0 }  (measured temperatures imposed
                 on nodes, as seed 004 §4.5 does with its IR/OR thermocouples: the rest is solved)
    [models]     optional overrides: rolling, hertz, load_model, drag, sliding, ...

Every bad value raises :class:`~thermobear.errors.InputError` naming the field,
the value and what is expected.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from thermobear.files import read_toml
from thermobear.errors import InputError
from thermobear.contact.geometry import BallBearing, bearing, bearing_from_dict

__all__ = ["Scene", "load_scene", "scene_from_dict", "SUPPLIES"]

SUPPLIES = ("oil_jet", "grease", "oil_bath", "oil_air", "dry_film")
_SECTIONS = ("scene", "bearing", "lubricant", "operation", "thermal", "models", "rig")


@dataclass(frozen=True)
class Scene:
    """A validated scene in SI units.

    Attributes
    ----------
    name : str
    bearing : BallBearing
    lubricant : object            thermobear.lubrication.lubricant.Lubricant
    supply : str                  lubrication method (``SUPPLIES``)
    n_rpm : float                 speed of the rotating ring [rpm] (edge unit, kept for reporting)
    omega : float                 its angular speed [rad/s]
    rotating : str                ``"inner"`` or ``"outer"``
    Fa, Fr : float                axial / radial load [N]
    M : float | None              tilting moment [N m]; None holds the tilt
    T_C : float | None            prescribed contact temperature [°C] (None: solve the thermal network)
    oil_flow : float              supplied oil flow [m^3/s] (oil jet)
    T_oil_in_C : float | None     oil inlet temperature [°C]
    T_ambient_C : float           ambient temperature [°C]
    Rq_ball, Rq_ring : float      RMS roughness [m]
    mu_boundary, mu_full_film : float   friction coefficients of seed 000 eq 18 [-]
    network : str | None          thermal network name (networks/<name>.toml)
    network_parameters : dict     overrides of the network's parameters
    T_fixed_C : dict              node → imposed temperature [°C] (measured rig temperatures; the
                                  node becomes a fixed-temperature boundary of the network)
    models : dict                 model overrides (see thermobear.coupled.solver)
    source : str                  where the scene comes from
    path : str | None             file it was read from
    raw : dict                    the parsed TOML (for tools that need more)
    """

    name: str
    bearing: BallBearing
    lubricant: object
    supply: str
    n_rpm: float
    rotating: str = "inner"
    Fa: float = 0.0
    Fr: float = 0.0
    M: float | None = None
    T_C: float | None = None
    oil_flow: float = 0.0
    T_oil_in_C: float | None = None
    T_ambient_C: float = 20.0
    Rq_ball: float = 0.05e-6
    Rq_ring: float = 0.1e-6
    mu_boundary: float = 0.11
    mu_full_film: float = 0.05
    network: str | None = None
    network_parameters: dict = field(default_factory=dict)
    T_fixed_C: dict = field(default_factory=dict)
    models: dict = field(default_factory=dict)
    source: str = ""
    path: str | None = None
    raw: dict = field(default_factory=dict, repr=False, compare=False)

    @property
    def omega(self) -> float:
        """Angular speed of the rotating ring [rad/s]."""
        return self.n_rpm * np.pi / 30.0

    @property
    def omega_i(self) -> float:
        """Inner-ring speed [rad/s]."""
        return self.omega if self.rotating == "inner" else 0.0

    @property
    def omega_o(self) -> float:
        """Outer-ring speed [rad/s]."""
        return self.omega if self.rotating == "outer" else 0.0

    def with_(self, **changes) -> "Scene":
        """Copy with operating values changed, in the scene's own edge units.

        Accepted keys: n_rpm, Fa (or Fa_N), Fr (Fr_N), M (M_Nm), T_C, T_oil_in_C, T_ambient_C,
        oil_flow_L_h, lubricant (name, table or object), bearing (catalog name, table or BallBearing),
        network_parameters (merged), T_fixed_C (node → °C, replaces; ``{}`` clears) and models
        (merged); each value is checked as in a scene file.

        >>> from thermobear.scene.scene import load_scene
        >>> import thermobear
        >>> s = load_scene(thermobear.example_path("seed004_oil_jet_7210.toml"))
        >>> s.with_(n_rpm=6500, Fr=1500).Fr
        1500.0
        """
        alias = {"Fa_N": "Fa", "Fr_N": "Fr", "M_Nm": "M"}
        kw = {}
        for k, v in changes.items():
            k = alias.get(k, k)
            where = f"scene.with_({k})"
            if k in ("n_rpm", "Fa", "Fr", "T_C", "T_oil_in_C", "T_ambient_C", "M"):
                if v is None and k in ("T_C", "T_oil_in_C", "M"):
                    kw[k] = None
                else:
                    kw[k] = _num({k: v}, k, "scene.with_")
            elif k == "oil_flow_L_h":
                kw["oil_flow"] = _num({k: v}, k, "scene.with_", lo=0.0) * 1e-3 / 3600.0
            elif k == "lubricant":
                if isinstance(v, (str, dict)):
                    kw[k] = _lubricant_of(v["name"] if isinstance(v, dict) and set(v) == {"name"} else v,
                                          where="lubricant")
                elif all(hasattr(v, a) for a in ("eta", "nu", "rho", "alpha_p_at")):
                    kw[k] = v
                else:
                    raise InputError(where, v, "a lubricant name, a table of its properties, or a Lubricant")
            elif k == "T_fixed_C":
                kw[k] = _fixed_temperatures(v, where)
            elif k in ("network_parameters", "models"):
                if not isinstance(v, dict):
                    raise InputError(where, v, "must be a table (dict)")
                merged = {**getattr(self, k), **v}
                probe = {"thermal": {"parameters": merged}} if k == "network_parameters" else {"models": merged}
                _check_overrides(probe)
                kw[k] = merged
            elif k == "bearing":
                from thermobear.contact.geometry import BallBearing
                if isinstance(v, str):
                    kw[k] = bearing(v)
                elif isinstance(v, dict):
                    kw[k] = _bearing_of(v)
                elif isinstance(v, BallBearing):
                    kw[k] = v
                else:
                    raise InputError(where, v, "a catalog name, a bearing table, or a BallBearing")
            else:
                raise InputError(where, v, "unknown override; accepted: n_rpm, Fa, Fr, M, T_C, T_oil_in_C, "
                                 "T_ambient_C, oil_flow_L_h, lubricant, bearing, network_parameters, T_fixed_C, "
                                 "models")
        new = dataclasses.replace(self, **kw)
        _validate_operation(new)
        return new


def _lubricant_of(spec, where="lubricant"):
    from thermobear.lubrication.lubricant import Lubricant, lubricant  # lubricant sits below scene in the data flow
    if isinstance(spec, str):
        return lubricant(spec)
    if isinstance(spec, dict):
        if "name" in spec and not any(k in spec for k in ("nu40_cSt", "eta_Pa_s")):
            return lubricant(spec["name"])
        return Lubricant.from_dict(spec, where=where) if hasattr(Lubricant, "from_dict") else Lubricant(**spec)
    return spec


def _num(sec: dict, key: str, where: str, default=None, lo=None, hi=None, lo_open=False, required=False):
    if key not in sec:
        if required:
            raise InputError(f"{where}.{key}", None, "missing required field")
        return default
    v = sec[key]
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise InputError(f"{where}.{key}", v, "must be a number")
    v = float(v)
    if not np.isfinite(v):
        raise InputError(f"{where}.{key}", v, "must be finite")
    if lo is not None and (v < lo or (lo_open and v == lo)):
        rng = f"> {lo}" if lo_open else f">= {lo}"
        raise InputError(f"{where}.{key}", v, f"must be {rng}" + (f" and <= {hi}" if hi is not None else ""))
    if hi is not None and v > hi:
        raise InputError(f"{where}.{key}", v, f"must be <= {hi}")
    return v


def _check_keys(sec: dict, allowed: set, where: str):
    if not isinstance(sec, dict):
        raise InputError(where, sec, "must be a table")
    for k in sec:
        if k not in allowed:
            raise InputError(f"{where}.{k}", sec[k], f"unknown key; accepted: {', '.join(sorted(allowed))}")


_BEARING_INLINE = {"D_mm", "dm_mm", "Z", "fi", "fo", "Pd_mm", "alpha0_deg", "kind", "bore_mm",
                   "outer_diameter_mm", "width_mm", "series", "C0_kN", "ball_material", "ring_material",
                   "name", "description", "source", "estimated"}


def _bearing_of(sec: dict) -> BallBearing:
    _check_keys(sec, _BEARING_INLINE | {"catalog"}, "bearing")
    if "catalog" in sec:
        base = bearing(str(sec["catalog"]))
        over = {k: v for k, v in sec.items() if k != "catalog"}
        if not over:
            return base
        from thermobear.contact.geometry import _catalog
        merged = {**_catalog()[sec["catalog"]], **over}
        return bearing_from_dict(merged, name=str(sec["catalog"]), where="bearing")
    return bearing_from_dict(sec, name=sec.get("name", "custom"), where="bearing")


_MODEL_KEYS = {"rolling", "hertz", "load_model", "drag", "kinematics", "stiffness", "high_speed", "losses",
               "skf_R1", "skf_S1", "skf_mu_EHL"}


def _fixed_temperatures(v, where="thermal.fixed_C") -> dict:
    """Validate a node → imposed temperature table [°C] (measured rig temperatures)."""
    if v is None:
        return {}
    if not isinstance(v, dict):
        raise InputError(where, v, "a table of node = temperature [°C], e.g. { inner_ring = 50.0 }")
    out = {}
    for k, t in v.items():
        if not isinstance(k, str) or not k:
            raise InputError(where, k, "node names are text")
        if isinstance(t, bool) or not isinstance(t, (int, float)) or not np.isfinite(t) or not -60.0 <= t <= 250.0:
            raise InputError(f"{where}.{k}", t, "temperature must be a number in [-60, 250] °C")
        out[k] = float(t)
    return out


def _check_overrides(d: dict):
    """Validate a ``[models]`` table and ``[thermal.parameters]`` (shared by files and ``with_``)."""
    models = d.get("models", {})
    _check_keys(models, _MODEL_KEYS, "models")
    for k in ("skf_R1", "skf_S1", "skf_mu_EHL"):
        if k in models:
            _num(models, k, "models", lo=0.0, lo_open=True)
    if "kinematics" in models and models["kinematics"] not in ("outer", "inner", "radial"):
        raise InputError("models.kinematics", models["kinematics"], "ball spin control: 'outer', 'inner' or 'radial'")
    if "stiffness" in models and models["stiffness"] not in ("nominal", "per_ball"):
        raise InputError("models.stiffness", models["stiffness"], "'nominal' or 'per_ball'")
    params = d.get("thermal", {}).get("parameters", {})
    if not isinstance(params, dict):
        raise InputError("thermal.parameters", params, "must be a table of parameter = value")
    for k, v in params.items():
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not np.isfinite(v):
            raise InputError(f"thermal.parameters.{k}", v, "must be a finite number")


def _validate_operation(s: Scene):
    if s.rotating not in ("inner", "outer"):
        raise InputError("operation.rotating", s.rotating, "must be 'inner' or 'outer'")
    if not (np.isfinite(s.n_rpm) and s.n_rpm >= 0):
        raise InputError("operation.n_rpm", s.n_rpm, "speed must be >= 0 [rpm]")
    for nm in ("Fa", "Fr"):
        v = getattr(s, nm)
        if not (np.isfinite(v) and v >= 0):
            raise InputError(f"operation.{nm}_N", v, "load must be >= 0 [N]")
    if s.M is not None and not np.isfinite(s.M):
        raise InputError("operation.M_Nm", s.M, "moment must be finite [N m]")
    if not (np.isfinite(s.oil_flow) and s.oil_flow >= 0):
        raise InputError("lubricant.flow_L_h", s.oil_flow * 3.6e6, "oil flow must be >= 0 [L/h]")
    if s.supply == "oil_jet" and s.T_C is None and s.network is not None and s.T_oil_in_C is None:
        raise InputError("lubricant.T_in_C", None, "an oil-jet scene solved thermally needs the oil inlet temperature [°C]")
    if s.T_C is not None and not (-60.0 <= s.T_C <= 250.0):
        raise InputError("operation.T_C", s.T_C, "temperature must lie in [-60, 250] °C")
    for nm in ("T_ambient_C", "T_oil_in_C"):
        v = getattr(s, nm)
        if v is not None and not (-60.0 <= v <= 250.0):
            raise InputError(f"thermal.{nm}", v, "temperature must lie in [-60, 250] °C")


def scene_from_dict(d: dict, path: str | None = None) -> Scene:
    """Validate a parsed scene table and convert it to SI (see the module docstring)."""
    _check_keys(d, set(_SECTIONS), "scene file")
    meta = d.get("scene", {})
    _check_keys(meta, {"name", "description", "source"}, "scene")
    if "bearing" not in d:
        raise InputError("bearing", None, "missing section [bearing] (catalog = \"...\" or inline geometry)")
    brg = _bearing_of(d["bearing"])
    if "lubricant" not in d:
        raise InputError("lubricant", None, "missing section [lubricant] (name = \"...\" or inline properties)")
    lsec = dict(d["lubricant"])
    lkeys = {"supply", "flow_L_h", "T_in_C", "Rq_ball_um", "Rq_ring_um", "mu_boundary", "mu_full_film"}
    supply = lsec.get("supply", "oil_jet")
    if supply not in SUPPLIES:
        raise InputError("lubricant.supply", supply, f"must be one of {', '.join(SUPPLIES)}")
    lub_spec = {k: v for k, v in lsec.items() if k not in lkeys}
    if not lub_spec:
        raise InputError("lubricant.name", None, "give a lubricant name or its properties (nu40_cSt, nu100_cSt, ...)")
    lub = _lubricant_of(lub_spec["name"] if set(lub_spec) == {"name"} else lub_spec, where="lubricant")
    op = d.get("operation", {})
    _check_keys(op, {"n_rpm", "Fa_N", "Fr_N", "M_Nm", "rotating", "T_C"}, "operation")
    th = d.get("thermal", {})
    _check_keys(th, {"network", "T_ambient_C", "parameters", "fixed_C"}, "thermal")
    _check_overrides(d)
    params = th.get("parameters", {})
    if "network" in th and not isinstance(th["network"], str):
        raise InputError("thermal.network", th["network"], "must be a network name or a path (text)")
    models = d.get("models", {})

    s = Scene(
        name=str(meta.get("name", Path(path).stem if path else "scene")),
        bearing=brg, lubricant=lub, supply=supply,
        n_rpm=_num(op, "n_rpm", "operation", required=True, lo=0.0),
        rotating=str(op.get("rotating", "inner")),
        Fa=_num(op, "Fa_N", "operation", 0.0, lo=0.0),
        Fr=_num(op, "Fr_N", "operation", 0.0, lo=0.0),
        M=_num(op, "M_Nm", "operation", None),
        T_C=_num(op, "T_C", "operation", None, lo=-60.0, hi=250.0),
        oil_flow=_num(lsec, "flow_L_h", "lubricant", 0.0, lo=0.0) * 1e-3 / 3600.0,
        T_oil_in_C=_num(lsec, "T_in_C", "lubricant", None, lo=-60.0, hi=250.0),
        T_ambient_C=_num(th, "T_ambient_C", "thermal", 20.0, lo=-60.0, hi=250.0),
        Rq_ball=_num(lsec, "Rq_ball_um", "lubricant", 0.05, lo=0.0) * 1e-6,
        Rq_ring=_num(lsec, "Rq_ring_um", "lubricant", 0.1, lo=0.0) * 1e-6,
        mu_boundary=_num(lsec, "mu_boundary", "lubricant", 0.11, lo=0.0, hi=1.0),
        mu_full_film=_num(lsec, "mu_full_film", "lubricant", 0.05, lo=0.0, hi=1.0),
        network=th.get("network"), network_parameters=dict(params),
        T_fixed_C=_fixed_temperatures(th.get("fixed_C")),
        models=dict(models), source=str(meta.get("source", "")), path=path, raw=d)
    _validate_operation(s)
    return s


def load_scene(path) -> Scene:
    """Read and validate a scene file (TOML).

    >>> import thermobear
    >>> s = load_scene(thermobear.example_path("seed004_oil_jet_7210.toml"))
    >>> s.bearing.name, s.n_rpm, s.Fa, s.Fr
    ('7210', 3200.0, 450.0, 325.0)
    """
    p = Path(path)
    if not p.is_file():
        raise InputError("scene", str(path), "file not found")
    return scene_from_dict(read_toml(str(p.resolve())), path=str(p))
