"""``thermobear run``: a scene with the least model it needs, and what it reports."""
from __future__ import annotations

import re
import warnings
from dataclasses import dataclass

import numpy as np

from thermobear.arrays import instance_of
from thermobear.coupled.blend import blend_losses
from thermobear.coupled.limits import emit, film_preload_warnings, point_warnings
from thermobear.coupled.preload import loaded_scene, preload_lines
from thermobear.coupled.ratings import Ratings, check_static_safety, scene_ratings
from thermobear.coupled.sources import scene_losses
from thermobear.coupled.steady import SCENE_LOADS, SteadyState, steady_state
from thermobear.loads import check_loads
from thermobear.errors import OutsideValidity
from thermobear.models import plan_many
from thermobear.scene import Scene

__all__ = ["RunResult", "Prescribed", "solve", "heat_flows", "heat_flow_table"]

#: the sign convention of the heat-flow table
HEAT_FLOW_SIGN = ("W leaving the machine through each path into a fixed-temperature boundary (ambient air, frame, "
                  "a held shaft end, an imposed node) or the oil stream; positive: out; the paths sum to the power loss")


def heat_flows(st: SteadyState) -> dict:
    """Where the heat goes at a steady state: per loss part the nodes it heats, per path the W leaving.

    Returns ``{"sign": ..., "sources_W": {part: {node: W}}, "out_W": {path: W}, "out_to": {path: boundary},
    "out_by_group_W": {group: W}}`` (groups: :func:`path_group`)."""
    groups: dict = {}
    for k, v in st.heat_out_W.items():
        g = path_group(k, st.heat_out_to.get(k, ""))
        groups[g] = groups.get(g, 0.0) + v
    return {"sign": HEAT_FLOW_SIGN, "sources_W": {p: n for p, n in st.heat_sources_W.items() if any(n.values())},
            "out_W": st.heat_out_W, "out_to": st.heat_out_to, "out_by_group_W": groups}


def path_group(path: str, boundary: str) -> str:
    """A readable group of a path: the body its cell belongs to (cell suffixes of the builders'
    discretisation dropped: ``housing_left_1_r5`` → ``housing_left``) and the surface it leaves by
    (``ambient_sides``, ``frame_mounting``, ``ambient_end``); the oil stream by its name.

    >>> path_group("housing_left_1_r5--ambient_sides", "ambient"), path_group("oil_stream", "stream")
    ('housing → ambient_sides', 'oil_stream → stream')
    """
    if "--" not in path:
        return f"{path} → {boundary}"
    src, surface = path.split("--", 1)
    body = re.sub(r"(_seat)?(_\d+)?(_r\d+)?$", "", src) or src
    if re.fullmatch(r"housing_(left|right)", body):       # axial slices of one housing
        body = "housing"
    return f"{body} → {surface}"


def heat_flow_table(st: SteadyState, P_W: float) -> list:
    """Lines of the text table of :func:`heat_flows` (paths grouped by body and surface)."""
    hf = heat_flows(st)
    lines = ["Heat sources (loss part → node, W)"]
    for part, nodes in hf["sources_W"].items():
        lines.append(f"  {part:18s} " + ", ".join(f"{n} {w:.3f}" for n, w in nodes.items() if w))
    lines += ["", "Heat leaving (W out of the machine into a fixed-temperature boundary or the oil stream; the paths "
              "sum to the power loss)", f"  {'path (body → surface)':44s} {'W':>10s} {'share':>7s}"]
    total = 0.0
    for g, w in sorted(hf["out_by_group_W"].items(), key=lambda kv: -abs(kv[1])):
        total += w
        lines.append(f"  {g:44s} {w:10.4f} {100 * w / P_W if P_W > 0 else 0.0:6.1f} %")
    lines.append(f"  {'total':44s} {total:10.4f} (power loss {P_W:.4f} W)")
    return lines


@dataclass(frozen=True)
class Prescribed:
    """A prescribed temperature [°C] as the ratings read a solved state (:func:`~thermobear.coupled.ratings.
    scene_ratings`): the contacts, rings, balls, shaft and housing all at ``T``."""

    T: float

    @property
    def T_C(self) -> dict:
        return {"contacts (prescribed)": self.T}

    @property
    def roles(self) -> dict:
        return dict.fromkeys(("inner", "outer", "ball"), "contacts (prescribed)")


@dataclass
class RunResult:
    """What ``thermobear run`` reports.

    Attributes
    ----------
    scene : Scene
    P_W : float                power loss [W]
    torque_Nm : float          friction torque on the rotating ring [N m]
    breakdown_W : dict         loss family → W
    T_C : dict                 node → °C (prescribed: the contacts' temperature)
    models_used : dict         model → (choice, reason)
    losses : LossResult        the loss result (per contact)
    steady : SteadyState       the coupled solution (None when the temperature is prescribed)
    warnings : list            OutsideValidity warnings of the answer (the ratings' included)
    ratings : Ratings          C0, C, s0, p_max, κ, a_ISO, lives, clearance at the steady state or at the
                               prescribed temperature (every part at it: :class:`Prescribed`;
                               :func:`~thermobear.coupled.ratings.scene_ratings`); None at rest
    """

    scene: Scene
    P_W: float
    torque_Nm: float
    breakdown_W: dict
    T_C: dict
    models_used: dict
    losses: object
    steady: SteadyState | None = None
    warnings: list = None
    ratings: Ratings | None = None

    def as_dict(self) -> dict:
        r = self.losses
        d = {"scene": self.scene.name, "bearing": self.scene.bearing.name, "n_rpm": self.scene.n_rpm,
             "Fa_N": self.scene.Fa, "Fr_N": self.scene.Fr, "T_C": self.T_C, "P_W": self.P_W,
             "torque_Nm": self.torque_Nm, "breakdown_W": self.breakdown_W,
             "models_used": {k: {"choice": v[0], "reason": v[1]} for k, v in self.models_used.items()},
             "warnings": [w.as_dict() for w in self.warnings or []]}
        if getattr(r, "contacts", None):
            d["balls"] = {"Q_inner_N": r.contacts["inner"]["Q"], "Q_outer_N": r.contacts["outer"]["Q"],
                          "alpha_deg": np.rad2deg(r.contacts["inner"]["alpha"]),
                          "regime_inner": r.contacts["inner"]["regime"], "regime_outer": r.contacts["outer"]["regime"]}
        if self.steady is not None:
            d["solver"] = {"iterations": self.steady.iterations, "residual_K": self.steady.residual_K,
                           "energy_balance_W": self.steady.energy_balance_W}
            d["T_contacts_C"] = self.steady.T_contacts_C
            d["heat_flows_W"] = self.steady.heat_flows_W
            d["heat_flows"] = heat_flows(self.steady)
            if self.steady.preload:
                d["preload"] = self.steady.preload
        if self.ratings is not None:
            r = self.ratings.as_dict()
            del r["warnings"]                   # in the answer's warnings
            d["ratings"] = r
            d.update(s0=r["s0"], kappa=r["kappa"], a_ISO=r["a_ISO"], L10m_h=r["L10m_h"],
                     clearance_um={k: r["clearance_um"][k] for k in ("mounted", "operating", "used", "applies", "why")
                                   if k in r["clearance_um"]})
        return d

    def summary(self) -> str:
        s = self.scene
        pair = "" if s.arrangement is None else f" on the {s.arrangement.replace('_', '-')} pair"
        lines = [f"thermobear — {s.name}: {s.bearing.name}, {s.n_rpm:g} rpm, Fa {s.Fa:g} N, Fr {s.Fr:g} N{pair}, "
                 f"{s.lubricant.name} ({s.supply})", "", "Temperatures [°C]"]
        for k, v in self.T_C.items():
            lines.append(f"  {k:18s} {v:8.2f}" + ("   imposed (thermal.fixed_C)" if k in s.T_fixed_C else ""))
        lines += ["", f"Power loss {self.P_W:.3f} W   (friction torque {self.torque_Nm * 1e3:.2f} N mm)"]
        for k, v in self.breakdown_W.items():
            share = 100 * v / self.P_W if self.P_W > 0 else 0.0
            lines.append(f"  {k:12s} {v:10.4f} W  {share:5.1f} %")
        lines += ["", "Models used"]
        for k, v in self.models_used.items():
            if k == "node_roles":
                continue
            lines.append(f"  {k:18s} {str(v[0]):40s} {v[1]}")
        if self.steady is not None and self.steady.preload:
            lines += ["", "Preload of the pair", *preload_lines(self.steady.preload)]
        if self.steady is not None:
            lines += ["", *heat_flow_table(self.steady, self.P_W)]
            lines += ["", f"Fixed point: {self.steady.iterations} iterations, residual {self.steady.residual_K:.1e} K, "
                          f"energy balance {self.steady.energy_balance_W:.1e} W"]
        if self.ratings is not None:
            lines += [""] + self.ratings.lines()
        return "\n".join(lines)


def solve(scene: Scene) -> RunResult:
    """Run a scene with the least model it needs (a thermal network only when the temperature is not
    prescribed).

    >>> import thermobear as tb
    >>> r = solve(tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")))
    >>> r.P_W > 0, r.steady.iterations < 10
    (True, True)
    """
    scene = instance_of(scene, Scene, "scene")
    check_loads(scene.bearing, scene.Fa, scene.Fr, scene.M, scene.n_rpm, Fz=scene.Fz, My=scene.My,
                names=SCENE_LOADS)             # before any solve, as steady_states
    check_static_safety(scene)
    if scene.T_C is not None:
        alts = plan_many([scene])[0]
        if isinstance(alts, Exception):
            raise alts
        with warnings.catch_warnings():        # the answer's validity: point_warnings below
            warnings.simplefilter("ignore", OutsideValidity)
            # the model choice's dry loads are the loads (solved once); across a switch, the blend
            each = [scene_losses(scene, models=a.models, dry=None if a.dry is None else a.dry.load()) for a in alts]
            r = blend_losses([(a.weight, e) for a, e in zip(alts, each)])
        T = float(scene.T_C)
        ws = point_warnings(scene, r, [T, T, T])
        rt = None
        if scene.n_rpm > 0:        # the ratings at the prescribed temperature: life, κ, clearance of every part at T
            rt = scene_ratings(scene, Prescribed(T), losses=r)
            ws += [w for w in rt.warnings if str(w) not in map(str, ws)]
        # a preload by the films, each film alternative with its own dry loads (a blend keeps one's contacts)
        ws += [w for w in film_preload_warnings(scene, [(e, a.dry) for a, e in zip(alts, each)
                                                        if a.models["load_model"][0] == "film"])
               if str(w) not in map(str, ws)]
        emit(ws)
        return RunResult(scene=scene, P_W=float(r.P_W), torque_Nm=float(r.torque_Nm),
                         breakdown_W={k: float(v) for k, v in r.breakdown_W.items()},
                         T_C=Prescribed(T).T_C, models_used=r.models_used, losses=r,
                         warnings=ws, ratings=rt)
    st = steady_state(scene)
    rt = None
    if scene.n_rpm > 0:
        rt = scene_ratings(loaded_scene(scene, st), st)          # a pair's loaded bearing under its loads
        emit(rt.warnings)
    return RunResult(scene=scene, P_W=st.P_W, torque_Nm=st.torque_Nm, breakdown_W=dict(st.breakdown_W), T_C=st.T_C,
                     models_used=st.models_used, losses=st.losses, steady=st,
                     warnings=list(st.warnings) + (rt.warnings if rt else []), ratings=rt)
