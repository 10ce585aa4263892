"""Fidelity levels L0–L4 on the same scenes: error against every measured reference, and runtime.

Levels (each a function of a scene and operating points; importable):

* **L0** — SKF 2004 global model (:func:`thermobear.losses.skf.skf_friction`) at a given
  temperature, base-oil ν(T).  Two variants: ``L0`` with the series constants of
  ``materials/skf_constants.toml`` and SKF's μ_bl = 0.15, μ_EHL by base oil (the model as a user
  runs it), and ``L0-cal`` with R1, S1 backed out of ONE case (seed 002, MG1 at 1000 rpm, its
  Table 3 split) and scored only on the held-out cases (the other greases, 2000 rpm).
* **L1** — local contact model with nominal ball loads, no Jones–Harris: thrust / pure axial
  Q = Fa/(Z sin α0); radial part by Stribeck's zero-clearance distribution
  Q_j = 4.37 Fr/(Z cos α0) cos^1.5 ψ_j (|ψ_j| < 90°) plus a uniform axial share that closes the
  axial balance (clipped at 0), all at the free contact angle; Hamrock–Brewe Hertz approximations.
* **L2** — Jones–Harris (low speed, F_c added on the outer contact) + local losses at a given
  temperature; Hamrock–Brewe Hertz.
* **L3** — L2's loss model + the scene's thermal network, fixed point (:func:`thermobear.coupled.steady_state`)
  or heat-up (:func:`thermobear.coupled.transient`); the load model as :func:`thermobear.models.choose_models`
  takes it (dry Jones–Harris, or the film load law in a flooded bearing whose dry solution lifts or
  nearly lifts a ball off a race, blended across the switch band).
* **L4** — L3 with high-speed ball dynamics (:func:`thermobear.loads.highspeed.load_distribution_high_speed`,
  centrifugal force and gyroscopic moment inside the load distribution), exact Hertz and per-ball
  stiffness; the load model as L3's (the film load law where the dry solution nearly lifts a ball,
  blended across its band).  Thrust bearings: per-ball Jones–Harris (the high-speed model is
  radial/angular only).

The local levels L1–L4 run the film physics that :func:`thermobear.models.choose_models` picks for the
scene (issue 17): the base oil's Eyring / limiting-shear-stress traction instead of a constant μ_e
(:mod:`thermobear.losses.traction`; τ0 and τ_L/p by base-oil family from
``materials/lubricant_traction.toml``), the inlet shear heating of Gupta et al. 1992
(:mod:`thermobear.lubrication.thermal_film`) and SKF's replenishment factor Φ_rs on the rolling force
(K_rs of the supply).  None of their parameters comes from the scored cases.

Case families and references (all copied under ``validation/data``; the levels never see them):

* ``seed001 torque`` — 12 spin-down torques T_exp = K* ω^n at the initial speed (seed 001 Tables 1–2),
  3-ball rig at 26.5 °C.  L0 not applicable (the SKF constants describe complete catalogue bearings,
  not a cage-less 3-ball rig at 0.1–0.6 N; no 512-series constants either).
* ``seed002 torque`` — 51107, Fa 7000 N, 5 greases at 1000 rpm (Table 3: M_rr + M_sl is the measured
  total) and MG1, PG2 at 2000 rpm (§4.2: 155 and 110 N mm); L0–L2 at the measured temperature,
  L3–L4 predict it.  ``seed002 temperature`` — the same 7 measured temperatures (thermocouple III,
  node ``balls``), L3–L4 only.
* ``seed004 P ratio`` — "power ×3 when the speed is twice higher at equal OR–IR mean temperature"
  (seed 004 §5.3.1): P(6500)/P(3200) at 30, 50 and 70 °C against 3.  L0–L2 (no network) at a uniform
  T; L3–L4 as the paper compares and models (§4.5): both rings imposed at T, the balls and the oil–air
  mixture from the network (:func:`at_ring_temperature`).  ``seed004 IR temperature`` — IR temperature ≈ 55 °C at 3200 rpm and ≈ 90 °C at
  8070 rpm after 1000 s (§5.3.1), L3–L4 heat-up from 25 °C; error of the rise above 25 °C.

Runtime: median of repeats, per operating point, single (one point per call) and batched (all
points of the family; L0–L2 vectorised over speed and temperature, L3–L4 one solve per point).
The table ends with issue 17's targets (:data:`TARGETS`: an RMS error where the issue sets one; for every family
the highest level at least as accurate as the lowest, the error falling as fidelity rises), each met or missed, and
for a miss the physics still missing (:data:`MISSING`, from validation/report/seed004_fidelity_diagnosis.md).
Run ``python validation/fidelity.py`` for the table (``run_all.py`` puts it in the report).
"""
from __future__ import annotations

import csv
import dataclasses
import io
import math
import time
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from _common import median_time

import thermobear as tb
from thermobear.errors import ExtrapolationWarning, InputError, SolverError
from thermobear.losses.skf import MU_EHL, skf_friction
from thermobear.loads import LoadDistribution, axial_contact_angle, load_distribution
from thermobear.scene.scene import Scene, scene_from_dict
from thermobear.coupled import scene_losses, solve, steady_state, steady_states, transient
from thermobear.models import choose_models

HERE = Path(__file__).resolve().parent
DATA = HERE / "data"
LEVELS = ("L0", "L0-cal", "L1", "L2", "L3", "L4")
LEVEL_INFO = {
    "L0": "SKF 2004, catalogue constants, μ_bl 0.15, μ_EHL by base oil, at a given T",
    "L0-cal": "SKF 2004, R1, S1 backed out of seed 002 MG1 @ 1000 rpm (held-out scoring)",
    "L1": "local losses (film traction, inlet heating, replenishment as chosen), nominal ball loads (axial share "
          "+ Stribeck), Hamrock–Brewe Hertz, given T",
    "L2": "local losses (as L1), Jones–Harris, Hamrock–Brewe Hertz, given T",
    "L3": "L2 + thermal network (fixed point / heat-up; ring temperatures imposed where the reference compares at "
          "equal ring temperature) + the film load law where the scene needs it",
    "L4": "L3 + high-speed ball dynamics, exact Hertz, per-ball stiffness (load model as L3's)",
}
SKF_LUB = {"grease": "grease", "oil_jet": "oil_jet", "oil_air": "oil_air", "oil_bath": "oil_jet",
           "dry_film": "grease"}
#: boundary friction by base oil used by seed 002 §4.4 (after Brandão et al., independent of its torques)
MU_BL_SEED002 = {"mineral": 0.09, "PAO": 0.10, "ester": 0.11, "ester+vegetal": 0.11}
T_AMB_SEED004_C = 25.0           # examples/seed004_oil_jet_7210.toml (estimated laboratory air)


# ------------------------------------------------------------------------------------ the levels
def _mu_ehl(lub) -> float:
    return MU_EHL["mineral" if getattr(lub, "base_oil", "mineral") == "mineral" else "synthetic"]


def level0(scene: Scene, n_rpm, T_C, *, R1=None, S1=None, mu_bl=0.15):
    """SKF 2004 torque [N m] and power [W] at temperature T_C [°C] (vectorised over n, T)."""
    nu = np.asarray(scene.lubricant.nu(np.asarray(T_C, float)), float)
    r = skf_friction(scene.bearing, nu, np.asarray(n_rpm, float), scene.Fa, scene.Fr,
                     lubrication=SKF_LUB[scene.supply], R1=R1, S1=S1, mu_bl=mu_bl,
                     mu_EHL=_mu_ehl(scene.lubricant))
    return {"torque_Nm": np.asarray(r.M_total, float), "P_W": np.asarray(r.P_W, float)}


def nominal_load(brg, Fa: float, Fr: float) -> LoadDistribution:
    """L1 ball loads: uniform axial share + Stribeck radial distribution at the free contact angle.

    Q_r,j = 4.37 Fr/(Z cos α) cos^1.5 ψ_j for |ψ_j| < 90° (Stribeck 1901, zero clearance; Harris
    2001 eq 7.41 constant), Q_a = max(0, (Fa/sin α − Σ Q_r,j)/Z); α = α0, or the Harris eq 7.36
    angle of a deep-groove bearing under axial load; thrust: Q = Fa/Z.

    >>> ld = nominal_load(tb.bearing("7210"), 450.0, 0.0)
    >>> round(float(ld.Q_i.sum() * np.sin(ld.alpha_i[0])), 6)
    450.0
    """
    Z = brg.Z
    psi = 2.0 * np.pi * np.arange(Z) / Z
    if brg.kind == "thrust":
        al = brg.alpha0
        Q = np.full(Z, Fa / (Z * np.sin(al)))
    else:
        al = brg.alpha0 if brg.alpha0 > 1e-6 or Fa == 0 else float(axial_contact_angle(brg, Fa))
        c = np.cos(psi)
        Qr = np.where(c > 0, 4.37 * Fr / (Z * np.cos(al)) * np.clip(c, 0, None) ** 1.5, 0.0)
        Qa = max(0.0, (Fa / np.sin(al) - Qr.sum()) / Z) if Fa > 0 else 0.0
        Q = Qr + Qa
    dn = (Q / brg.Kn()) ** (2.0 / 3.0)
    return LoadDistribution(delta_a=0.0, delta_r=0.0, theta=0.0, Q_i=Q, Q_o=Q.copy(), alpha_i=np.full(Z, al),
                            alpha_o=np.full(Z, al), psi=psi, delta_n=dn, residual=0.0, iterations=0,
                            Fa=np.asarray(Fa), Fr=np.asarray(Fr), M=0.0)


def _approx(scene: Scene) -> Scene:
    """L1–L3: Hamrock–Brewe Hertz, low-speed load model (F_c only on the outer contact)."""
    return scene.with_(models={"hertz": "hamrock_brewe", "high_speed": False})


def _exact(scene: Scene) -> Scene:
    """L4's contact mechanics: exact Hertz and per-ball stiffness; the load model (dry Jones–Harris, the film
    load law, or their blend) as :func:`~thermobear.models.choose_models` takes it, as in L3."""
    return scene.with_(models={"hertz": "exact", "stiffness": "per_ball"})


def _batch_losses(scene, n_rpm, T_C, load, models):
    """bearing_losses over arrays of speed and temperature with one load (thermobear.app.sweep's path)."""
    return scene_losses(scene, T_C=np.asarray(T_C, float), models=models, n_rpm=np.asarray(n_rpm, float), load=load)


def _out(r):
    return {"torque_Nm": np.atleast_1d(np.asarray(r.torque_Nm, float)), "P_W": np.atleast_1d(np.asarray(r.P_W, float))}


def level1(scene: Scene, n_rpm, T_C):
    """Local losses with nominal loads at T_C [°C] (vectorised over n, T)."""
    sc = _approx(scene)
    models = choose_models(sc.with_(T_C=40.0))
    n = np.atleast_1d(np.asarray(n_rpm, float))
    models = _speed_models(sc, float(n.max()), models)
    return _out(_batch_losses(sc, n, np.broadcast_to(T_C, n.shape), nominal_load(sc.bearing, sc.Fa, sc.Fr), models))


def _speed_models(sc, n_rpm, models):
    """Model choices at the highest speed of a batch (drag and F_c flags depend on speed)."""
    m = choose_models(sc.with_(T_C=40.0, n_rpm=n_rpm))
    return {**models, "drag": m["drag"], "high_speed": m["high_speed"]}    # L1–L3 scenes fix high_speed = no


def level2(scene: Scene, n_rpm, T_C):
    """Jones–Harris + local losses at T_C [°C] (vectorised over n, T)."""
    sc = _approx(scene).with_(models={"load_model": "jones_harris"})
    n = np.atleast_1d(np.asarray(n_rpm, float))
    models = _speed_models(sc, float(n.max()), choose_models(sc.with_(T_C=40.0)))
    return _out(_batch_losses(sc, n, np.broadcast_to(T_C, n.shape),
                              load_distribution(sc.bearing, Fa=sc.Fa, Fr=sc.Fr, M=sc.M), models))


def _l4(sc: Scene) -> Scene:
    """L4: the high-speed ball equilibrium (F_c, M_g inside; thrust bearings: low speed), exact Hertz,
    per-ball stiffness; the load model as the scene needs it (dry, film or blended, as in L3)."""
    return sc.with_(models={"high_speed": sc.bearing.kind != "thrust"})


def level4_prescribed(scene: Scene, n_rpm, T_C):
    """L4 loss model at T_C [°C]: high-speed loads per speed, exact Hertz (one call per speed); across a
    switch band of the load model the alternatives blended (:func:`thermobear.coupled.solve`)."""
    out = {"torque_Nm": [], "P_W": []}
    for n, T in np.broadcast(np.atleast_1d(n_rpm), np.atleast_1d(T_C)):
        r = solve(_l4(_exact(scene).with_(n_rpm=float(n), T_C=float(T))))
        out["torque_Nm"].append(float(r.torque_Nm))
        out["P_W"].append(float(r.P_W))
    return {k: np.asarray(v) for k, v in out.items()}


def ring_nodes(scene: Scene) -> tuple:
    """(inner ring node, outer ring node) of a scene's network: its ``[rig] map`` of the IR / OR thermocouples
    (``T_IR_C``, ``T_OR_C``), else ``inner_ring`` / ``outer_ring``."""
    m = scene.raw.get("rig", {}).get("map", {})
    return m.get("T_IR_C", "inner_ring"), m.get("T_OR_C", "outer_ring")


def at_ring_temperature(level: str, scene: Scene, n_rpm, T_C):
    """L3 or L4 power [W] and torque [N m] with both rings imposed at T_C [°C], the balls and the oil–air
    mixture from the thermal network (one batched steady solve over the points).

    The comparison of seed 004 (§5.3.1: powers plotted against the OR–IR mean temperature) and its own
    model (§4.5: the measured ring temperatures imposed, the balls' from the network, each contact at the
    mean of its ring and ball): a coupled level scored at a prescribed uniform temperature would drop
    the network that defines it — the balls run hotter than the rings, the more the faster.
    """
    sc = (_approx(scene) if level == "L3" else _l4(_exact(scene))).with_(T_C=None)
    ir, orr = ring_nodes(scene)
    pts = [sc.with_(n_rpm=float(n), T_fixed_C={ir: float(T), orr: float(T)})
           for n, T in np.broadcast(np.atleast_1d(n_rpm), np.atleast_1d(T_C))]
    res = steady_states(pts)
    bad = [r for r in res if isinstance(r, Exception)]
    if bad:
        raise bad[0]
    return {"P_W": np.array([r.P_W for r in res]), "torque_Nm": np.array([r.torque_Nm for r in res]),
            "T_balls_C": np.array([r.T_C.get("balls", np.nan) for r in res])}


def level3(scene: Scene, t_end_s: float | None = None, node: str | None = None):
    """Thermal network + L2 losses: steady state, or the heat-up to t_end_s [s] from ambient."""
    sc = _approx(scene).with_(T_C=None)
    if t_end_s is None:
        st = steady_state(sc)
        return {"torque_Nm": float(st.losses.torque_Nm), "P_W": float(st.P_W), "T_C": dict(st.T_C),
                "iterations": st.iterations}
    tr = transient(sc, float(t_end_s))
    return {"P_W": float(tr.P_W[-1]), "T_C": {k: float(v[-1]) for k, v in tr.T_C.items()},
            "torque_Nm": float(tr.P_W[-1] / sc.omega)}


def level4(scene: Scene, t_end_s: float | None = None):
    """Thermal network + L4 losses (high-speed load, exact Hertz, per-ball stiffness)."""
    sc = _l4(_exact(scene).with_(T_C=None))
    if t_end_s is None:
        st = steady_state(sc)
        return {"torque_Nm": float(st.losses.torque_Nm), "P_W": float(st.P_W), "T_C": dict(st.T_C),
                "iterations": st.iterations}
    tr = transient(sc, float(t_end_s), t_eval=[float(t_end_s)])
    return {"P_W": float(tr.P_W[-1]), "T_C": {k: float(v[-1]) for k, v in tr.T_C.items()},
            "torque_Nm": float(tr.P_W[-1] / sc.omega)}


# ------------------------------------------------------------------------------------ references
def _csv(name):
    text = (DATA / name).read_text(encoding="utf-8")
    return list(csv.DictReader(io.StringIO("\n".join(l for l in text.splitlines() if not l.startswith("#")))))


@dataclass
class Case:
    """One measured operating point: scene, what was measured, at which temperature."""

    family: str
    name: str
    scene: Scene
    T_C: float                  # measured (or prescribed) temperature [°C]
    torque_Nm: float | None = None
    temp_node: str | None = None
    held_out: bool = True       # False: used to calibrate L0-cal
    extra: dict = field(default_factory=dict)


def seed001_cases() -> list[Case]:
    base = tb.load_scene(tb.example_path("seed001_spin_down_3ball.toml"))
    out = []
    for r in _csv("seed001_spin_down.csv"):
        d, Q, rpm = float(r["d_mm"]), float(r["Q_N"]), float(r["initial_rpm"])
        raw = {k: dict(v) for k, v in base.raw.items()}
        raw["bearing"].update(D_mm=d, fi=4.16 / d, fo=4.16 / d)          # groove radius 4.16 mm (seed 001 §3.1)
        raw["operation"].update(n_rpm=rpm, Fa_N=3 * Q)
        sc = scene_from_dict(raw)
        om = rpm * math.pi / 30
        out.append(Case("seed001 torque", f"T{r['table']} d{d:g} {rpm:g} rpm", sc, 26.5,
                        torque_Nm=float(r["K"]) * om ** float(r["n"])))
    return out


def seed002_cases() -> list[Case]:
    base = tb.load_scene(tb.example_path("seed002_grease_thrust_51107.toml"))
    node = base.raw["rig"]["map"]["T_III_C"]        # thermocouple III → the scene's [rig.map] node
    out = []
    rows = {r["grease"]: r for r in _csv("seed002_greases.csv") if r["Mrr_Nmm"]}
    for g, r in rows.items():
        sc = base.with_(lubricant=f"seed002-{g.lower()}", n_rpm=1000.0)
        out.append(Case("seed002", f"{g} 1000 rpm", sc, float(r["T_1000rpm_C"]),
                        torque_Nm=(float(r["Mrr_Nmm"]) + float(r["Msl_Nmm"])) * 1e-3, temp_node=node,
                        held_out=g != "MG1", extra={"Mrr_Nmm": float(r["Mrr_Nmm"]), "Msl_Nmm": float(r["Msl_Nmm"]),
                                                    "base_oil": r["base_oil"]}))
    for g, T, M in (("MG1", 65.0, 155.0), ("PG2", 53.0, 110.0)):      # seed 002 §4.2 (CSV header)
        sc = base.with_(lubricant=f"seed002-{g.lower()}", n_rpm=2000.0)
        out.append(Case("seed002", f"{g} 2000 rpm", sc, T, torque_Nm=M * 1e-3, temp_node=node,
                        extra={"base_oil": rows[g]["base_oil"]}))
    return out


def seed004_scene(n_rpm: float) -> Scene:
    return tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")).with_(n_rpm=n_rpm)


def calibrate_L0_seed002(case: Case):
    """R1, S1 from one Table 3 split (M_rr, M_sl) with the μ rule L0-cal predicts with (no μ_EHD of the paper)."""
    brg = case.scene.bearing
    nu = float(case.scene.lubricant.nu(case.T_C))
    mu_bl = MU_BL_SEED002[case.extra["base_oil"]]
    r = skf_friction(brg, nu, case.scene.n_rpm, case.scene.Fa, 0.0, lubrication="grease", R1=1.0, S1=1.0,
                     mu_bl=mu_bl, mu_EHL=_mu_ehl(case.scene.lubricant))
    return case.extra["Mrr_Nmm"] * 1e-3 / r.M_rr, case.extra["Msl_Nmm"] * 1e-3 / r.M_sl


# ------------------------------------------------------------------------------------ scoring
def _median_time(fn, repeat):
    """Every timed call computes its point from scratch (the solvers keep no per-point cache)."""
    return median_time(fn, repeat, warmup=False)


@dataclass
class Score:
    level: str
    family: str
    errors: list            # (case, model, reference, relative error)
    t_single_s: float
    t_batch_s: float        # per point
    note: str = ""
    failed: list = field(default_factory=list)    # (case, error class: reason)

    @property
    def rms(self) -> float:
        e = [x[3] for x in self.errors]
        return float(np.sqrt(np.mean(np.square(e)))) if e else float("nan")


def _group_by_scene(cases):
    """Vectorisable groups: cases that differ only in speed and temperature."""
    groups: dict = {}
    for c in cases:
        s = c.scene
        key = (s.lubricant.name, s.bearing, s.Fa, s.Fr)
        groups.setdefault(key, []).append(c)
    return list(groups.values())


def _why(exc) -> str:
    return f"{type(exc).__name__}: {str(exc)[:140]}"


_FAILS = (SolverError, InputError, FloatingPointError)


def _prescribed_score(level, fn, cases, family, repeat=5, note=""):
    failed: dict = {}

    def run_batch():
        res = {}
        for grp in _group_by_scene(cases):
            try:
                out = fn(grp[0].scene, [c.scene.n_rpm for c in grp], [c.T_C for c in grp])
            except _FAILS as exc:        # recorded, not hidden: the level cannot serve these cases
                failed.update({c.name: _why(exc) for c in grp})
                continue
            for c, m in zip(grp, out["torque_Nm"]):
                res[c.name] = float(m)
        return res
    try:                                                        # warm-up (imports, caches)
        fn(cases[0].scene, [cases[0].scene.n_rpm], [cases[0].T_C])
    except _FAILS:
        pass
    res = run_batch()
    errs = [(c.name, res[c.name], c.torque_Nm, res[c.name] / c.torque_Nm - 1) for c in cases if c.name in res]
    ok = [c for c in cases if c.name in res]
    if not ok:
        return Score(level, family, [], float("nan"), float("nan"), note, sorted(failed.items()))
    c0 = ok[0]
    t1 = _median_time(lambda: fn(c0.scene, [c0.scene.n_rpm], [c0.T_C]), repeat)
    tb_ = _median_time(run_batch, max(1, repeat // 2)) / len(cases)
    return Score(level, family, errs, t1, tb_, note, sorted(failed.items()))


def _coupled(level, fn, cases, quantities, warm=True):
    """Run a coupled level per case; quantities: {family: (case → (model, reference, error))}."""
    if warm:
        try:
            fn(cases[0])
        except _FAILS:
            pass
    errs = {f: [] for f in quantities}
    failed, ts = [], []
    run = fn
    for c in cases:
        t0 = time.perf_counter()
        try:
            r = run(c)
        except _FAILS as exc:
            failed.append((c.name, _why(exc)))
            continue
        ts.append(time.perf_counter() - t0)
        for fam, q in quantities.items():
            m, ref = q(c, r)
            errs[fam].append((c.name, m, ref, m / ref - 1))
    t1 = float(np.median(ts)) if ts else float("nan")
    tm = float(np.mean(ts)) if ts else float("nan")
    return {fam: (e, t1, tm, failed) for fam, e in errs.items()}


def _torque(c, r):
    return r["torque_Nm"], c.torque_Nm


def score_seed001(levels=LEVELS) -> list[Score]:
    cases = seed001_cases()
    out = []
    for lv, fn in (("L1", level1), ("L2", level2), ("L4", level4_prescribed)):
        if lv in levels:
            out.append(_prescribed_score(lv, fn, cases, "seed001 torque",
                                         note="high-speed load n/a (thrust): per-ball Jones–Harris, exact Hertz"
                                         if lv == "L4" else ""))
    if "L3" in levels:   # the rig has no network: one lumped node at the laboratory temperature
        def l3(c):
            return level3(dataclasses.replace(c.scene, network="one_node", T_C=None, T_ambient_C=26.5))
        e, t1, tm, failed = _coupled("L3", l3, cases, {"seed001 torque": _torque})["seed001 torque"]
        out.append(Score("L3", "seed001 torque", e, t1, tm,
                         "one_node network, 1 W/K to 26.5 °C (mW losses: no heating)", failed))
    return out


def score_seed002(levels=LEVELS) -> list[Score]:
    cases = seed002_cases()
    out = []
    cal = next(c for c in cases if not c.held_out)
    R1, S1 = calibrate_L0_seed002(cal)
    held = [c for c in cases if c.held_out]
    if "L0" in levels:
        out.append(_prescribed_score("L0", level0, cases, "seed002 torque", repeat=9,
                                     note="catalogue R1 = 1.03e-6, S1 = 1.6e-2"))
    if "L0-cal" in levels:
        def cal_fn(scene, n, T):
            return level0(scene, n, T, R1=R1, S1=S1, mu_bl=MU_BL_SEED002[scene.lubricant.base_oil])
        out.append(_prescribed_score("L0-cal", cal_fn, held, "seed002 torque", repeat=9,
                                     note=f"R1 = {R1:.4g}, S1 = {S1:.4g} from MG1 @ 1000 rpm; scored on the "
                                          f"{len(held)} held-out cases"))
    for lv, fn in (("L1", level1), ("L2", level2)):
        if lv in levels:
            out.append(_prescribed_score(lv, fn, cases, "seed002 torque", note="at the measured temperature"))

    def temp(c, r):
        amb = c.scene.T_ambient_C
        return r["T_C"][c.temp_node] - amb, c.T_C - amb
    for lv, fn in (("L3", level3), ("L4", level4)):
        if lv not in levels:
            continue
        res = _coupled(lv, lambda c, fn=fn: fn(c.scene), cases, {"seed002 torque": _torque,
                                                                 "seed002 temperature": temp})
        e, t1, tm, failed = res["seed002 torque"]
        out.append(Score(lv, "seed002 torque", e, t1, tm, "grease_thrust_four_ball network (estimated "
                         "housing, fans, 25 °C ambient)", failed))
        e, t1, tm, failed = res["seed002 temperature"]
        out.append(Score(lv, "seed002 temperature", e, t1, tm, "rise above 25 °C (estimated ambient) at node "
                         f"{cases[0].temp_node} (thermocouple III)", failed))
    return out


def score_seed004(levels=LEVELS) -> list[Score]:
    out = []
    T_list = np.array([30.0, 50.0, 70.0])
    sc = seed004_scene(3200.0)
    n = np.repeat([3200.0, 6500.0], T_list.size)
    T = np.tile(T_list, 2)
    fns = {"L0": level0, "L1": level1, "L2": level2,
           "L3": lambda s, n, T: at_ring_temperature("L3", s, n, T),
           "L4": lambda s, n, T: at_ring_temperature("L4", s, n, T)}
    notes = {"L0": "72B constants (SKF 10000 EN 72xx BECBP, transcribed: skf_constants.toml); uniform T",
             "L1": "uniform T (no network: balls and oil at the rings' temperature)",
             "L2": "uniform T (no network: balls and oil at the rings' temperature)",
             "L3": "rings imposed at T, balls and oil–air from the network (seed 004 §4.5)",
             "L4": "rings imposed at T, balls and oil–air from the network (seed 004 §4.5)"}
    for lv, fn in fns.items():
        if lv not in levels:
            continue
        note = notes[lv]
        try:
            fn(sc, [3200.0], [50.0])
            P = fn(sc, n, T)["P_W"]
        except _FAILS as exc:
            out.append(Score(lv, "seed004 P ratio", [], float("nan"), float("nan"), note,
                             [("P(6500)/P(3200)", _why(exc))]))
            continue
        ratio = P[T_list.size:] / P[:T_list.size]
        errs = [(f"P(6500)/P(3200) at {t:g} °C", float(r), 3.0, float(r) / 3.0 - 1) for t, r in zip(T_list, ratio)]
        t1 = _median_time(lambda fn=fn: fn(sc, [3200.0], [50.0]), 5)
        tbat = _median_time(lambda fn=fn: fn(sc, n, T), 3) / n.size
        out.append(Score(lv, "seed004 P ratio", errs, t1, tbat, note))
    ir = [Case("seed004 IR temperature", f"IR at 1000 s, {n_:g} rpm", seed004_scene(n_), T_)
          for n_, T_ in ((3200.0, 55.0), (8070.0, 90.0))]

    def temp(c, r):
        return r["T_C"]["inner_ring"] - T_AMB_SEED004_C, c.T_C - T_AMB_SEED004_C
    for lv, fn in (("L3", level3), ("L4", level4)):
        if lv in levels:
            e, t1, tm, failed = _coupled(lv, lambda c, fn=fn: fn(c.scene, 1000.0), ir,
                                         {"seed004 IR temperature": temp}, warm=False)["seed004 IR temperature"]
            out.append(Score(lv, "seed004 IR temperature", e, t1, tm, "heat-up 0–1000 s from 25 °C; rise above "
                             "25 °C; time per 1000 s transient", failed))
    return out


def score_all(levels=LEVELS) -> list[Score]:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)
        return score_seed001(levels) + score_seed002(levels) + score_seed004(levels)


def _ms(t: float) -> str:
    """A time [s] in ms, or "–" for a level that is not timed (its row repeats another level's model)."""
    return f"{1e3 * t:.3g}" if math.isfinite(t) else "–"


#: Issue 17's targets: an RMS error per family (where the issue sets one: family → (RMS, the levels it applies to)), and for every family "the highest level
#: at least as accurate as the lowest", the error falling as fidelity rises (L0-cal, calibrated on the family, apart).
TARGETS = {"seed004 P ratio": (0.10, ("L0", "L1", "L2", "L3", "L4")),
           "seed002 torque": (0.25, ("L1", "L2", "L3", "L4")),          # "with the local model"
           "seed001 torque": (0.15, ("L1", "L2", "L3", "L4"))}
LADDER = ("L0", "L1", "L2", "L3", "L4")
#: Where a target is missed: the physics still missing, with the evidence (keys: (family, level) for an RMS target,
#: (family, "La→Lb") for a step where the error rises).  A miss without an entry is reported as not diagnosed.
MISSING = {
    ("seed004 P ratio", "L0"):
        "SKF 2004's angular-contact sliding load grows with its centrifugal term F_g = R3 d_m⁴ n² (M_sl ×3.7 from "
        "3200 to 6500 rpm with the 72B constants of SKF 10000 EN; ×3.3 with the 2005 values recalled before) and weighs "
        "more as ν falls: ratio 4.1–5.1 (3.5–4.4 with the recalled values)",
    ("seed004 P ratio", "L2"):
        "no thermal network (contacts at the rings' T, while L3's network puts the balls −7 … +13 K from the rings "
        "at 3200 rpm and +7 … +31 K at 6500 rpm, the 30 °C jet cooling them) and a "
        "rolling force that jumps at the IVR / PVR boundary (seed 004 eqs 17, 19 meet only to ×0.5–0.9), crossed by "
        "the light contacts Jones–Harris leaves around ψ = 180°; with one rolling form L2 gives 10.8 % "
        "(seed004_fidelity_diagnosis.md §3, §5)",
    ("seed004 P ratio", "L1→L2"):
        "the IVR / PVR jump of the rolling force at the light contacts of the Jones–Harris loads (the step shrinks "
        "from +2.2 to +0.8 points with one rolling form; seed004_fidelity_diagnosis.md §3, §5)",
    ("seed004 P ratio", "L3→L4"):
        "ball attitude and cage speed from the contacts' traction: under Jones's outer-raceway control the balls "
        "outside the load zone pull the cage +6 % at 6500 rpm (drag ∝ ω_c³, inner spin); inner-raceway control gives "
        "ratios 2.3–2.9, outer 2.8–3.3, the measurement ≈ 3 lies between (seed004_fidelity_diagnosis.md §4, §5); "
        "both within the reference's ±9–14 % (§6)",
    ("seed004 IR temperature", "L3→L4"):
        "the rig's heat balance, not the level: L4 moves the inner ring ≤ 1 K against a 16–27 K gap (support blocks "
        "heating the shaft, shaft section, β: seed004_heatup_sensitivity.md, seed004_support_heat.md)",
    ("seed002 temperature", "L3→L4"):
        "nothing the level adds: exact instead of Hamrock–Brewe Hertz lowers the power 0.03–0.05 % and the "
        "temperature ≤ 0.013 K on a network 9–32 % too cool (estimated housing, fans, ambient; "
        "seed004_fidelity_diagnosis.md §8)",
    ("seed002 torque", "L2→L3"):
        "the predicted temperature instead of the measured one: the estimated rig network predicts rises 9–32 % "
        "too small, so the contacts are more viscous and the torque, already high at the measured temperature, "
        "higher",
}
_SEED001_MISSING = (
    "mixed lubrication at Table 1's Λ 0.27–0.63 (3 mm balls, 0.633 N): the measured torque rises as ω^0.12–0.37, the "
    "hydrodynamic forces as ω^0.67–0.86, so the model is 35 % low at 60 rpm and within 6 % at 210 rpm; the asperities "
    "cannot carry the difference (seed 001 §4.3: the dry torque, all load on asperities, is ≤ 12 % of the lubricated "
    "one; the load-sharing mixed force lowers the film's share and gives 29 %): seed001_spin_down.md")
MISSING.update({("seed001 torque", lv): _SEED001_MISSING for lv in ("L1", "L2", "L3", "L4")})


def targets(scores: list[Score]) -> str:
    """Markdown: each target of :data:`TARGETS` and the ladder rule per family, met or missed, and for a miss the
    physics still missing (:data:`MISSING`)."""
    by = {(s.level, s.family): s for s in scores if s.errors}
    fams = list(dict.fromkeys(s.family for s in scores))
    lines = ["Targets (issue 17) and, where one is missed, the physics still missing:", "",
             "| family | target | result | what is missing |", "|---|---|---|---|"]

    def why(key):
        return MISSING.get(key, "not diagnosed")
    for fam in fams:
        if fam in TARGETS:
            rms, levels = TARGETS[fam]
            for lv in levels:
                s = by.get((lv, fam))
                if s is not None:
                    ok = s.rms <= rms
                    lines.append(f"| {fam} | RMS ≤ {100 * rms:.0f} % | {lv} {100 * s.rms:.1f} %: "
                                 f"{'met' if ok else '**missed**'} | {'' if ok else why((fam, lv))} |")
        lvs = [lv for lv in LADDER if (lv, fam) in by]
        if len(lvs) < 2:
            continue
        r = {lv: round(100 * by[(lv, fam)].rms, 1) for lv in lvs}
        ok = r[lvs[-1]] <= r[lvs[0]]
        lines.append(f"| {fam} | highest level at least as accurate as the lowest | {lvs[-1]} {r[lvs[-1]]:.1f} % vs "
                     f"{lvs[0]} {r[lvs[0]]:.1f} %: {'met' if ok else '**missed**'} | "
                     f"{'' if ok else why((fam, f'{lvs[0]}→{lvs[-1]}'))} |")
        for a, b in zip(lvs, lvs[1:]):
            if r[b] > r[a] and not (not ok and (a, b) == (lvs[0], lvs[-1])):      # not the row above again
                lines.append(f"| {fam} | error falls as fidelity rises | {a} {r[a]:.1f} % → {b} {r[b]:.1f} %: "
                             f"**rises** | {why((fam, f'{a}→{b}'))} |")
    return "\n".join(lines)


def table(scores: list[Score]) -> str:
    """Markdown: level × family, RMS error and runtimes, then every case."""
    lines = ["| level | family | RMS rel. error | n | single [ms/pt] | batched [ms/pt] | note |",
             "|---|---|---|---|---|---|---|"]
    for s in scores:
        lines.append(f"| {s.level} | {s.family} | {100 * s.rms:.1f} % | {len(s.errors)} | "
                     f"{_ms(s.t_single_s)} | {_ms(s.t_batch_s)} | {s.note} |")
    lines += ["", targets(scores)]
    fails = [(s.level, s.family, c, why) for s in scores for c, why in s.failed]
    if fails:
        lines += ["", "Failed (the level could not serve these cases; not scored):", ""]
        lines += [f"* {lv} / {fam} / {c}: {why}" for lv, fam, c, why in fails]
    lines += ["", "Per case (model / reference, relative error; temperatures as rises above ambient [K]):", "",
              "| level | family | case | model | reference | error |", "|---|---|---|---|---|---|"]
    for s in scores:
        for name, m, ref, e in s.errors:
            lines.append(f"| {s.level} | {s.family} | {name} | {m:.4g} | {ref:.4g} | {100 * e:+.1f} % |")
    return "\n".join(lines)


def main():
    t0 = time.perf_counter()
    scores = score_all()
    print(table(scores))
    print(f"\n{time.perf_counter() - t0:.1f} s")
    return scores


if __name__ == "__main__":
    main()
