"""Seed 004 (Darul et al. 2024), issue 17: why a higher fidelity level is not always closer to "power ×3
when the speed is twice higher at equal OR–IR mean temperature" (§5.3.1), and what is still missing.

1. Checks first: every level runs the same scene (loads, speeds, oil flow through the bearing), at the
   temperature it claims; the coupled levels L3–L4 compared as the paper compares (both rings at T, the
   balls and the oil–air mixture from the network, seed 004 §4.5) — :func:`fidelity.at_ring_temperature`.
2. The step L1 → L2 → L4 decomposed at one uniform temperature (the mechanics alone: nominal loads →
   Jones–Harris → exact Hertz → per-ball stiffness → high-speed form → the film load law as chosen), per
   loss family and per contact, at 3200 and 6500 rpm and 30 / 50 / 70 °C; the step L3 → L4 at equal ring
   temperature.  Each step's change of the ratio is split exactly into the families' shares,
   Δr = Σ_f (ΔP_6500,f − r_A ΔP_3200,f) / P_3200,B.
3. The high-speed form at 6500 rpm against Jones (1960) / Harris (2001): the ball equations at the
   solution, each ball's no-slip orbital speed under outer-raceway control from first principles, Jones's
   raceway-control criterion, the cage speed and what it drives (drag ∝ ω_c³, entrainment, spin).
4. What-ifs (not fixes): the raceway-control hypothesis, one rolling-force form for every regime, drag,
   inlet shear heating and replenishment switched off.
5. The reference's own uncertainty (seed 004 §5.1.3: torquemeter 0.02 N m, thermocouples 0.5 °C; "×3"
   read from a figure), what the model would need to give 3, and which term grows too fast with speed.
6. The two other families where the higher level is not better: seed 004 inner-ring heat-up, seed 002
   temperature (L3 against L4).

Nothing is fitted.  Run:  python validation/seed004_fidelity_diagnosis.py
(writes validation/report/seed004_fidelity_diagnosis.md)
"""
from __future__ import annotations

import math
import warnings

import numpy as np
from scipy.special import ellipe

import fidelity as F
from _common import write_report

from thermobear.coupled import scene_losses, steady_state
from thermobear.errors import ExtrapolationWarning, OutsideValidity
from thermobear.loads.highspeed import load_distribution_high_speed_full
from thermobear.models import choose_models, plan_many

SPEEDS = (3200.0, 6500.0)
TEMPS = (30.0, 50.0, 70.0)
FAM = ("rolling", "sliding", "pivoting", "hysteresis", "drag")
PER_CONTACT = ("rolling", "sliding", "pivoting", "hysteresis")
MEASURED = 3.0
TORQUEMETER_NM = 0.02            # seed 004 §5.1.3
THERMOCOUPLE_K = 0.5             # seed 004 §5.1.3
N_BEARINGS = 2                   # the measurement block holds two 7210 (seed 004 §5.1.1)
L2M = {"hertz": "hamrock_brewe", "high_speed": False, "load_model": "jones_harris"}
EXACT = {**L2M, "hertz": "exact"}
PERBALL = {**EXACT, "stiffness": "per_ball"}
HSDRY = {**PERBALL, "high_speed": True}
L4M = {"hertz": "exact", "stiffness": "per_ball", "high_speed": True}          # load model chosen
L3M = {"hertz": "hamrock_brewe", "high_speed": False}                          # load model chosen
LADDER = (("L1: nominal loads (axial share + Stribeck), HB Hertz", None),
          ("L2: Jones–Harris low-speed form, dry law", L2M),
          ("+ exact Hertz", EXACT),
          ("+ per-ball stiffness", PERBALL),
          ("+ high-speed form (Jones 1960), dry law", HSDRY),
          ("+ film load law as chosen = L4", L4M))


def base():
    return F.seed004_scene(3200.0)


# ------------------------------------------------------------------------------------------ evaluation
def _parts(r) -> dict:
    """Family × contact powers [W] of one loss result (drag, and the families summed)."""
    c = r.contacts
    out = {f"{f}_{s[0]}": float(np.sum(c[s][f"P_{f}"])) for f in PER_CONTACT for s in ("inner", "outer")}
    out["drag"] = float(r.breakdown_W["drag"])
    out["P"] = float(r.P_W)
    return out


def uniform(models, n, T) -> dict:
    """Powers at a uniform T [°C] (balls, rings, oil): L1 (``models`` None, or holding the key ``"L1"`` with
    what-if choices) or the given models, every model
    alternative of a switch band solved and blended (weights of :func:`thermobear.models.plan_many`)."""
    sc = base().with_(n_rpm=n, T_C=T)
    if models is None or "L1" in models:
        s1 = F._approx(sc).with_(models={k: v for k, v in (models or {}).items() if k != "L1"})
        m1 = F._speed_models(s1, n, choose_models(s1.with_(T_C=40.0)))
        return _parts(scene_losses(s1, T_C=T, models=m1, load=F.nominal_load(s1.bearing, s1.Fa, s1.Fr)))
    sc = sc.with_(models=models)
    acc: dict = {}
    for a in plan_many([sc])[0]:
        p = _parts(scene_losses(sc, models=a.models, dry=None if a.dry is None else a.dry.load()))
        for k, v in p.items():
            acc[k] = acc.get(k, 0.0) + a.weight * v
    return acc


def rings(models, n, T):
    """Steady state with both rings at T [°C], balls and oil–air from the network."""
    return steady_state(base().with_(T_C=None, n_rpm=n, models=models, T_fixed_C={"inner_ring": T, "outer_ring": T}))


def _ratio(P):
    return P[SPEEDS[1]] / P[SPEEDS[0]]


def rms(ratios) -> float:
    return float(np.sqrt(np.mean([(r / MEASURED - 1) ** 2 for r in ratios])))


def contributions(a: dict, b: dict, keys) -> dict:
    """Exact split of r_B − r_A over the keys: (ΔP65_k − r_A ΔP32_k) / P32_B (a, b: {n: parts})."""
    n0, n1 = SPEEDS
    rA = a[n1]["P"] / a[n0]["P"]
    return {k: (b[n1][k] - a[n1][k] - rA * (b[n0][k] - a[n0][k])) / b[n0]["P"] for k in keys}


# ------------------------------------------------------------------------------------------ 1. checks
def checks(L):
    L += ["## 1. Same scene, the temperature each level claims", "",
          "Every level reads `examples/seed004_oil_jet_7210.toml` with only the speed changed (Fa 450 N, Fr 325 N per "
          "bearing, 10 L/h injected, β = 0.4 through the bearing).  Contact and oil temperatures as each level sees "
          "them at 6500 rpm and a nominal 50 °C:", "",
          "| level | Fa / Fr [N] | oil through the bearing [L/h] | inner / outer contact, oil–air [°C] | load model |",
          "|---|---|---|---|---|"]
    sc = base().with_(n_rpm=6500.0)
    flow = sc.oil_flow * sc.jet_penetration * 3.6e6
    for lv in ("L1", "L2"):
        L.append(f"| {lv} | {sc.Fa:g} / {sc.Fr:g} | {flow:.2f} | 50 / 50, 50 (uniform: no network) | "
                 f"{'nominal loads' if lv == 'L1' else 'Jones–Harris (dry)'} |")
    for lv, m in (("L3", L3M), ("L4", L4M)):
        st = rings(m, 6500.0, 50.0)
        T = {k: st.T_C[v] for k, v in st.roles.items()}
        blend = st.models_used.get("blend", (st.models_used["load_model"][0],))[0]
        L.append(f"| {lv} | {sc.Fa:g} / {sc.Fr:g} | {flow:.2f} | {0.5 * (T['inner'] + T['ball']):.1f} / "
                 f"{0.5 * (T['outer'] + T['ball']):.1f}, {T['oil']:.1f} (rings 50; races {T['inner']:.1f} / "
                 f"{T['outer']:.1f}, balls {T['ball']:.1f}) | {blend} |")
    L += ["", "* **Defect (fixed): L3's ratio was L2's value and L4's was taken at a uniform T.**  Both levels are "
          "defined by their thermal network, but the P ratio scored them without it.  Seed 004 plots the measured "
          "power against the OR–IR mean temperature (§5.3.1) and its own model imposes the measured ring "
          "temperatures and solves the balls (§4.5, contact temperature = mean of ring and ball).  The balls run "
          "hotter than the rings, the more the faster (table §2), which lowers P(6500) more than P(3200).  "
          "`fidelity.at_ring_temperature` now scores L3 and L4 that way (test: "
          "`tests/test_fidelity.py::test_coupled_levels_compare_at_equal_ring_temperature`).  L0–L2 have no "
          "network: a uniform T is what they can claim.",
          "* **Defect (fixed): L4 forced the dry Jones–Harris law.**  L3 runs the load model `choose_models` takes "
          "(here the film load law, blended with the dry law while the least loaded contact carries < 10 % of the "
          "greatest); L4 forced the dry law (a choice older than the film law) and so had less physics than L3.  "
          "L4 now keeps L3's choice, and its prescribed-T answer is the blend, not the dominant alternative "
          "(tests: `test_level4_keeps_the_load_model_level3_takes`, `test_level4_at_prescribed_temperature_is_the_blend`).",
          "* Loads, speeds and flows: identical across the levels (the same scene object with `n_rpm` changed); "
          "the film options (traction law, inlet heating, replenishment, drag) are the scene's choices at every "
          "level.", ""]


# ------------------------------------------------------------------------------------------ 2. ratios
def ratio_table(L):
    L += ["## 2. The ratio per level", "",
          "P per bearing [W] at 3200 / 6500 rpm.  L0–L2 at a uniform T, L3–L4 with both rings at T (balls: their "
          "network temperature).  Before the fixes: L3 = L2's values, L4 at a uniform T with the dry law.", "",
          "| level | 30 °C | 50 °C | 70 °C | RMS vs 3 |", "|---|---|---|---|---|"]
    out = {}
    sc = base()
    n = np.repeat(SPEEDS, len(TEMPS))
    T = np.tile(TEMPS, len(SPEEDS))
    rows = [("L0", F.level0(sc, n, T)["P_W"]), ("L1", F.level1(sc, n, T)["P_W"]), ("L2", F.level2(sc, n, T)["P_W"])]
    old4 = [uniform(HSDRY, nn, tt)["P"] for nn, tt in zip(n, T)]
    rows.append(("L4 before (uniform T, dry law)", np.array(old4)))
    balls = {}
    for lv in ("L3", "L4"):
        r = F.at_ring_temperature(lv, sc, n, T)
        rows.append((lv, r["P_W"]))
        balls[lv] = r["T_balls_C"]
    dflt = [rings({}, nn, tt) for nn, tt in zip(n, T)]
    rows.append(("default models (as `thermobear run` chooses), rings at T", np.array([d.P_W for d in dflt])))
    blend = " / ".join(dflt[i].models_used.get("blend", ("–",))[0] for i in (1, 4))
    for name, P in rows:
        k = len(TEMPS)
        rat = P[k:] / P[:k]
        out[name] = (P, rat)
        cells = " | ".join(f"{P[i]:.1f} / {P[k + i]:.1f}: **×{rat[i]:.3f}**" for i in range(k))
        L.append(f"| {name} | {cells} | {100 * rms(rat):.1f} % |")
    L += ["", f"The default models blend, at 3200 / 6500 rpm (50 °C): {blend} (the high-speed form "
          "across F_c/Q = 0.035–0.07, the film load law while the least loaded contact carries < 10 % of the greatest; "
          "`thermobear.models.BLEND_BANDS`).  L4 takes the high-speed form throughout (it tends to the low-speed form "
          "as n → 0) and the film / dry blend as chosen.", "",
          "Balls at equal ring temperature [°C] (3200 / 6500 rpm): " + "; ".join(
        f"{lv}: " + ", ".join(f"rings {t:g}: {b[i]:.1f} / {b[i + len(TEMPS)]:.1f}" for i, t in enumerate(TEMPS))
        for lv, b in balls.items()), ""]
    return out


# ------------------------------------------------------------------------------------------ 3. decomposition
def ladder(L):
    """Uniform-T ladder L1 → L4, ratio per step and the families' shares of each step."""
    res = {name: {T: {n: uniform(m, n, T) for n in SPEEDS} for T in TEMPS} for name, m in LADDER}
    L += ["## 3. The step L1 → L2 → L4 at one uniform temperature (the mechanics alone)", "",
          "Each row adds one model to the row above; all at the same uniform T (so only the mechanics differ).", "",
          "| step | 30 °C | 50 °C | 70 °C | RMS vs 3 |", "|---|---|---|---|---|"]
    for name, _ in LADDER:
        rat = [_ratio({n: res[name][T][n]["P"] for n in SPEEDS}) for T in TEMPS]
        L.append(f"| {name} | " + " | ".join(f"×{r:.3f}" for r in rat) + f" | {100 * rms(rat):.1f} % |")
    keys = [f"{f}_{s}" for f in PER_CONTACT for s in "io"] + ["drag"]
    L += ["", "Share of each step's change of the ratio by family and contact (i inner, o outer; Δr exact sum; "
          "columns with every share below 0.005 left out):", ""]
    names = [n for n, _ in LADDER]
    steps = [(names[0], names[1]), (names[1], names[3]), (names[3], names[4]), (names[4], names[5])]
    rows = []
    for a, b in steps:
        for T in TEMPS:
            c = contributions(res[a][T], res[b][T], keys)
            rows.append((f"{a.split(':')[0]} → {b.split(':')[0].split(' =')[0]}", T, c))
    used = [k for k in keys if any(abs(c[k]) >= 0.005 for _, _, c in rows)]
    L += ["| step | T [°C] | Δr | " + " | ".join(used) + " |", "|---" * (3 + len(used)) + "|"]
    for st, T, c in rows:
        L.append(f"| {st} | {T:g} | {sum(c.values()):+.3f} | " + " | ".join(f"{c[k]:+.3f}" for k in used) + " |")
    L += ["", "Powers at 50 °C by family and contact [W] (3200 → 6500 rpm):", "",
          "| step | " + " | ".join(keys) + " | P |", "|---" * (len(keys) + 2) + "|"]
    for name in names:
        r = res[name][50.0]
        L.append(f"| {name} | " + " | ".join(f"{r[3200.0][k]:.2f} → {r[6500.0][k]:.2f}" for k in keys + ["P"]) + " |")
    L.append("")
    return res


def ring_step(L):
    """L3 → L4 at equal ring temperature, by family (blended breakdowns)."""
    L += ["### L3 → L4 at equal ring temperature", "",
          "| T [°C] | L3: P 3200 / 6500 [W] | L4: P 3200 / 6500 [W] | Δr | " + " | ".join(FAM) + " | L4 blend weights "
          "(3200 / 6500 rpm) |", "|---" * (5 + len(FAM)) + "|"]
    out = {}
    for T in TEMPS:
        st = {lv: {n: rings(m, n, T) for n in SPEEDS} for lv, m in (("L3", L3M), ("L4", L4M))}
        p = {lv: {n: {**{f: float(s.breakdown_W[f]) for f in FAM}, "P": s.P_W} for n, s in d.items()}
             for lv, d in st.items()}
        c = contributions(p["L3"], p["L4"], FAM)
        alt = {n: [rings({**HSDRY, "load_model": lm}, n, T).P_W for lm in ("jones_harris", "film")] for n in SPEEDS}
        p["spread"] = max(abs(a / b - 1) for a, b in alt.values())
        p["dr"] = c
        bl = " / ".join(st["L4"][n].models_used.get("blend", ("–",))[0] for n in SPEEDS)
        L.append(f"| {T:g} | {p['L3'][3200.0]['P']:.1f} / {p['L3'][6500.0]['P']:.1f} | {p['L4'][3200.0]['P']:.1f} / "
                 f"{p['L4'][6500.0]['P']:.1f} | {sum(c.values()):+.3f} | " + " | ".join(f"{c[f]:+.3f}" for f in FAM)
                 + f" | {bl} |")
        out[T] = p
    L.append("")
    return out


# ------------------------------------------------------------------------------------------ 4. high speed
def own_orbital_speed(alpha_i, alpha_o, D, dm, omega):
    """Each ball's no-slip orbital speed and ball spin vector under outer-raceway control, from first
    principles (not the library's kinematics): rolling without slip at both contact centres and no spin at
    the outer contact, in the cage frame; contact points C ± (D/2)(sin α, cos α) (x axial, r radial)."""
    out = []
    for ai, ao in zip(np.atleast_1d(alpha_i), np.atleast_1d(alpha_o)):
        ro, ri = dm / 2 + D / 2 * math.cos(ao), dm / 2 - D / 2 * math.cos(ai)
        A = np.array([[D / 2 * math.cos(ao), -D / 2 * math.sin(ao), ro],          # outer: ball = ring (−ω_m)
                      [-D / 2 * math.cos(ai), D / 2 * math.sin(ai), ri],          # inner: ball = ring (ω − ω_m)
                      [math.sin(ao), math.cos(ao), math.sin(ao)]])                # outer: no spin
        wx, wr, wm = np.linalg.solve(A, [0.0, omega * ri, 0.0])
        out.append((wm, math.atan2(wr, wx)))
    return np.array(out)


def high_speed_check(L):
    sc = base()
    b, n = sc.bearing, 6500.0
    w = n * math.pi / 30
    ld, ex = load_distribution_high_speed_full(b, Fa=sc.Fa, Fr=sc.Fr, n_rpm=n, stiffness="per_ball")
    Qi, Qo, ai, ao = (np.asarray(x, float) for x in (ld.Q_i, ld.Q_o, ld.alpha_i, ld.alpha_o))
    Mg, Fc, li, lo = np.asarray(ex.Mg), np.asarray(ex.Fc), float(ex.lambda_i), float(ex.lambda_o)
    res_a = Qi * np.sin(ai) - Qo * np.sin(ao) + Mg / b.D * (li * np.cos(ai) - lo * np.cos(ao))
    res_r = Qi * np.cos(ai) - Qo * np.cos(ao) - Mg / b.D * (li * np.sin(ai) - lo * np.sin(ao)) + Fc
    own = own_orbital_speed(ai, ao, b.D, b.dm, w)
    cage = float(np.sum(Qi * own[:, 0]) / np.sum(Qi))
    gp = b.D / b.dm
    beta_h = np.arctan(np.sin(ao) / (np.cos(ao) + gp))          # Harris 2001: outer-raceway control
    r = scene_losses(base().with_(n_rpm=n, T_C=50.0, models=HSDRY))
    c = r.contacts
    Ei = ellipe(1 - (np.asarray(c["inner"]["b"]) / np.asarray(c["inner"]["a"])) ** 2)
    Eo = ellipe(1 - (np.asarray(c["outer"]["b"]) / np.asarray(c["outer"]["a"])) ** 2)
    crit = Qo * np.asarray(c["outer"]["a"]) * Eo * np.cos(ai - ao) / (Qi * np.asarray(c["inner"]["a"]) * Ei)
    wc_ls = uniform_cage(L2M, n)
    L += ["## 4. The high-speed form at 6500 rpm against Jones (1960) / Harris (2001)", "",
          f"Dry high-speed solution, per-ball stiffness (Fa {sc.Fa:g} N, Fr {sc.Fr:g} N); F_c = ½ m d_m ω_c², "
          f"M_g = J ω_R ω_c sin β; own ω_m: each ball's no-slip orbital speed under outer-raceway control "
          f"solved here from first principles (`own_orbital_speed`); β_H: Harris's tan β = sin α_o / (cos α_o + "
          f"D/d_m); M_o/M_i: Jones's raceway-control ratio Q_o a_o E(κ_o) cos(α_i − α_o) / (Q_i a_i E(κ_i)) (> 1: "
          "outer control).", "",
          "| ψ [°] | Q_i / Q_o [N] | α_i / α_o [°] | β / β_H [°] | own ω_m / ω | F_c [N] | M_g [mN m] | ball "
          "residual axial / radial [N] | M_o/M_i | inner ω_s D / (2 u) |", "|---" * 10 + "|"]
    roll_i = np.abs(np.asarray(c["inner"]["u"])) * 2 / b.D
    for j in range(0, b.Z // 2 + 1):
        L.append(f"| {np.degrees(ld.psi[j]):.0f} | {Qi[j]:.1f} / {Qo[j]:.1f} | {np.degrees(ai[j]):.1f} / "
                 f"{np.degrees(ao[j]):.1f} | {abs(np.degrees(ex.beta[j])):.2f} / {np.degrees(beta_h[j]):.2f} | "
                 f"{own[j, 0] / w:.4f} | {Fc[j]:.2f} | {1e3 * Mg[j]:.2f} | {res_a[j]:.1e} / {res_r[j]:.1e} | "
                 f"{crit[j]:.2f} | {abs(np.asarray(c['inner']['spin'])[j]) / roll_i[j]:.2f} |")
    wc = float(np.mean(ex.omega_c))
    L += ["", f"* The ball equations of Jones / Harris §8.2 hold at the solution (residuals above, against loads of "
          f"10–200 N); β equals Harris's outer-control angle; Jones's criterion gives outer control at every ball "
          f"(M_o/M_i {crit.min():.2f}–{crit.max():.2f}): the form is Jones's model as published.",
          f"* Cage speed: the library's {wc / w:.4f} ω; recomputed here, Σ Q_i ω_m / Σ Q_i = {cage / w:.4f} ω "
          f"(the library's common-cage rule, `contact.kinematics.common_cage_speed`, over the own speeds above).  "
          f"The low-speed form (its own loads, α ≈ 40°) runs its cage at {wc_ls / w:.4f} ω (epicyclic): "
          f"the high-speed cage is {100 * (wc / wc_ls - 1):+.1f} % faster, because the balls outside the load "
          f"zone (α_i − α_o up to {np.degrees((ai - ao).max()):.0f}°) would orbit at up to {own[:, 0].max() / w:.3f} ω "
          f"under outer-raceway control and carry {100 * Qi[np.abs(np.cos(ld.psi)) < 0.75].sum() / Qi.sum():.0f} % "
          "of the cage's Q_i weight.",
          f"* What it drives: drag ∝ ω_c³ (×{(wc / wc_ls) ** 3:.3f}), the outer entrainment speed "
          f"u_o ∝ ω_c (1 + γ' cos α_o) up and the inner one down, and the inner contacts' spin "
          f"(spin/roll up to {np.max(np.abs(np.asarray(c['inner']['spin'])) / roll_i):.2f}; pivoting ×2, §3).",
          "* **Defect found on the way (fixed, no default number moves):** the high-speed ball equilibrium always took "
          "outer-raceway control, whatever `models.kinematics` said, so `kinematics = \"inner\"` ran inner-control "
          "contact kinematics on outer-control loads; the loads now take the scene's control (`models.high_speed_control`; "
          "test: `tests/test_loads_highspeed.py::test_scene_loads_and_kinematics_share_the_raceway_control`).  The "
          "inner-control what-if of §5 relies on it.", ""]
    return wc / wc_ls, float(np.degrees((ai - ao).max())), float(own[:, 0].max() / own[0, 0])


def uniform_cage(models, n):
    r = scene_losses(base().with_(n_rpm=n, T_C=50.0, models=models))
    return float(np.mean(r.omega_c))


# ------------------------------------------------------------------------------------------ 5. what-ifs
def what_ifs(L):
    rows = [("as the level is", {}), ("rolling force: one form (Biboulet PVR) in every regime", {"rolling": "biboulet_pvr"}),
            ("no drag", {"drag": False}), ("no inlet shear heating (Gupta φ_T = 1)", {"inlet_heating": False}),
            ("no replenishment factor (Φ_rs = 1)", {"starvation": False}),
            ("neither φ_T nor Φ_rs", {"inlet_heating": False, "starvation": False})]
    L += ["## 5. What-ifs (diagnosis only: none is applied)", "",
          "Ratio P(6500)/P(3200) at 30 / 50 / 70 °C and its RMS error.  L1, L2 and the L4 model at a uniform T, L4 "
          "at equal ring temperature.", "",
          "| variant | L1, uniform T | L2, uniform T | L4, uniform T | L4, rings at T |", "|---|---|---|---|---|"]
    out = {}
    L1M = {"L1": True}
    for name, extra in rows:
        cells = []
        for m, kind in ((L1M, "u"), (L2M, "u"), (L4M, "u"), (L4M, "r")):
            mm = {**m, **extra}
            rat = []
            for T in TEMPS:
                P = {n: (uniform(mm, n, T)["P"] if kind == "u" else rings(mm, n, T).P_W) for n in SPEEDS}
                rat.append(_ratio(P))
            cells.append(", ".join(f"×{x:.2f}" for x in rat) + f" ({100 * rms(rat):.1f} %)")
            out[(name, "L1" if m is L1M else "L4" if m is L4M else "L2", kind)] = rat
        L.append(f"| {name} | " + " | ".join(cells) + " |")
    rat_i, rat_iu, dP = [], [], []
    inner = {**HSDRY, "kinematics": "inner"}          # the loads and the contacts' kinematics both (commit 705823b)
    for T in TEMPS:
        P = {n: rings(inner, n, T).P_W for n in SPEEDS}
        Pu = {n: uniform(inner, n, T)["P"] for n in SPEEDS}
        rat_i.append(_ratio(P))
        rat_iu.append(_ratio(Pu))
        dP.append(1.0 - P[SPEEDS[1]] / rings(HSDRY, SPEEDS[1], T).P_W)
    out["inner"], out["inner_dP"] = rat_i, dP
    L.append("| inner-raceway control (Jones's alternative hypothesis: β from zero spin at the inner contact, λ_i = 2; "
             "loads and kinematics), dry law | – | – | " + ", ".join(f"×{x:.2f}" for x in rat_iu)
             + f" ({100 * rms(rat_iu):.1f} %) | " + ", ".join(f"×{x:.2f}" for x in rat_i) + f" ({100 * rms(rat_i):.1f} %) |")
    L += ["", f"Inner- instead of outer-raceway control lowers P(6500) at equal ring temperature by "
          f"{100 * min(dP):.0f}–{100 * max(dP):.0f} % (dry law, both solved in full).", ""]
    return out


# ------------------------------------------------------------------------------------------ 6. reference
def within_band(ratios, band) -> str:
    """Per level: how many of the three temperatures lie within ±1 RSS band of 3."""
    out = []
    for name, (_, rat) in ratios.items():
        if "before" in name:
            continue
        k = sum(abs(r / MEASURED - 1) <= band[T] for r, T in zip(rat, TEMPS))
        out.append(f"{name} {k} of {len(TEMPS)}")
    return ", ".join(out)


def reference(L, P4):
    """The ratio's uncertainty from seed 004's stated accuracies, with the L4 powers as the size of the torques."""
    L += ["## 6. How well \"×3\" is known", "",
          "Seed 004 §5.1.3: torquemeter accuracy 0.02 N m (10 N m full scale) on the whole shaft, from which the "
          "support blocks' calibrated torque is subtracted; thermocouples 0.5 °C; the statement \"multiplied by "
          "3\" is read from Fig. 9b over OR–IR mean temperatures of 25–70 °C.  The two bearings' torque is sized "
          "with the L4 powers at equal ring temperature (the paper's model matches its measured speed trend, "
          "Fig. 14a); dP/dT from the same powers.", "",
          "| T [°C] | 2 × P 3200 / 6500 [W] | torque 3200 / 6500 [N m] | torquemeter 3200 / 6500 | 0.5 °C on T | "
          "ratio ± (RSS) | ratio ± (worst case) | L4 ratio | error / RSS |", "|---" * 9 + "|"]
    band = {}
    k = len(TEMPS)
    P, rat = P4
    for i, T in enumerate(TEMPS):
        p32, p65 = N_BEARINGS * P[i], N_BEARINGS * P[k + i]
        M32, M65 = p32 / (SPEEDS[0] * math.pi / 30), p65 / (SPEEDS[1] * math.pi / 30)
        e32, e65 = TORQUEMETER_NM / M32, TORQUEMETER_NM / M65
        j = min(i + 1, k - 1) if i < k - 1 else i - 1
        dlnP = abs(math.log(P[j] / P[i]) / (TEMPS[j] - TEMPS[i]))
        eT = dlnP * THERMOCOUPLE_K
        rss = math.sqrt(e32 ** 2 + e65 ** 2 + 2 * eT ** 2)
        worst = e32 + e65 + 2 * eT
        band[T] = rss
        L.append(f"| {T:g} | {p32:.0f} / {p65:.0f} | {M32:.3f} / {M65:.3f} | ±{100 * e32:.1f} / ±{100 * e65:.1f} % | "
                 f"±{100 * eT:.1f} % per point | ±{100 * rss:.1f} % | ±{100 * worst:.1f} % | ×{rat[i]:.3f} | "
                 f"{(rat[i] / MEASURED - 1) / rss:+.2f} |")
    L += ["", f"* From the instruments alone the ratio is known to ±{100 * min(band.values()):.0f}–"
          f"{100 * max(band.values()):.0f} % (RSS; the support blocks' calibration adds an unstated share); a ratio "
          "stated to one significant figure (\"3\") spans 2.5–3.5 (±17 %), and one number for 25–70 °C says "
          "nothing of a trend with temperature smaller than that.  The ≤ 10 % target is inside the reference's own "
          "uncertainty: levels that differ by a few per cent of RMS (L1 … L4) are not distinguished by it.", ""]
    return band


def needs(L, P4, fam4):
    """What P(6500) would have to be for ×3, the effective speed exponent, the families' exponents."""
    P, rat = P4
    k = len(TEMPS)
    x = math.log(SPEEDS[1] / SPEEDS[0])
    L += ["## 7. What the model would need to give ×3, and which term grows too fast", "",
          f"Speed exponent m of P ∝ n^m between 3200 and 6500 rpm (×3 ⇔ m = {math.log(3) / x:.2f}); L4 at equal "
          "ring temperature, by family (blended breakdowns):", "",
          "| T [°C] | ratio | P(6500) for ×3 | m (total) | " + " | ".join(f"m {f}" for f in FAM)
          + " | drag share 3200 / 6500 | ratio without drag |", "|---" * (6 + len(FAM)) + "|"]
    for i, T in enumerate(TEMPS):
        p = fam4[T]["L4"]
        m = {f: math.log(p[6500.0][f] / p[3200.0][f]) / x if p[3200.0][f] > 0 else float("nan") for f in FAM}
        nod = (p[6500.0]["P"] - p[6500.0]["drag"]) / (p[3200.0]["P"] - p[3200.0]["drag"])
        L.append(f"| {T:g} | ×{rat[i]:.3f} | {MEASURED * P[i]:.1f} W ({100 * (MEASURED / rat[i] - 1):+.1f} %) | "
                 f"{math.log(rat[i]) / x:.2f} | " + " | ".join(f"{m[f]:.2f}" for f in FAM)
                 + f" | {100 * p[3200.0]['drag'] / p[3200.0]['P']:.0f} / {100 * p[6500.0]['drag'] / p[6500.0]['P']:.0f} %"
                 f" | ×{nod:.3f} |")
    L.append("")


# ------------------------------------------------------------------------------------------ 8. other families
def _rms_pct(errs) -> float:
    return 100 * float(np.sqrt(np.mean(np.square(errs))))


def other_families(L):
    L += ["## 8. The other families where L4 is not better than L3", ""]
    rows, e = [], {"L3": [], "L4": []}
    for n, ref in ((3200.0, 55.0), (8070.0, 90.0)):
        sc = F.seed004_scene(n)
        r = {"L3": F.level3(sc, 1000.0), "L4": F.level4(sc, 1000.0)}
        for lv in r:
            e[lv].append((r[lv]["T_C"]["inner_ring"] - F.T_AMB_SEED004_C) / (ref - F.T_AMB_SEED004_C) - 1)
        rows.append(f"{n:g} rpm: L3 {r['L3']['T_C']['inner_ring']:.2f} °C at {r['L3']['P_W']:.1f} W, L4 "
                    f"{r['L4']['T_C']['inner_ring']:.2f} °C at {r['L4']['P_W']:.1f} W (rig ≈ {ref:g} °C)")
    L += [f"* **Seed 004 inner ring at 1000 s** (heat-up from 25 °C; RMS error of the rise L3 {_rms_pct(e['L3']):.1f} %, "
          f"L4 {_rms_pct(e['L4']):.1f} %): " + "; ".join(rows) + ".  L4's high-speed form moves the inner ring by ≤ 1 K, "
          "cooler at 3200 rpm (less power) and hotter at 8070 rpm (more power: the outer-control kinematics of §4 "
          "grow with speed), against a model–rig gap of 16–27 K that is in the rig's heat balance (support blocks, "
          "shaft, β: `seed004_heatup_sensitivity.md`, `seed004_support_heat.md`).  Over two points the RMS weighs "
          "the larger 3200 rpm error more: the two levels differ by tenths of a per cent, which measures the "
          "network, not the level.", ""]
    d = []
    for c in F.seed002_cases():
        s3 = steady_state(F._approx(c.scene).with_(T_C=None))
        s4 = steady_state(F._l4(F._exact(c.scene)).with_(T_C=None))
        d.append((c, s3, s4))
    amb = d[0][0].scene.T_ambient_C
    eT = {k: [s.T_C[c.temp_node] - amb for c, *ss in d for s in [ss[k]]] for k in (0, 1)}
    ref = [c.T_C - amb for c, *_ in d]
    errT = {k: [m / r - 1 for m, r in zip(eT[k], ref)] for k in (0, 1)}
    errM = {k: [ss[k].torque_Nm / c.torque_Nm - 1 for c, *ss in d] for k in (0, 1)}
    dT = [b - a for a, b in zip(eT[0], eT[1])]
    dP = [s4.P_W / s3.P_W - 1 for c, s3, s4 in d]
    c0, s3, s4 = d[0]
    parts = ", ".join(f"{f} {s3.breakdown_W[f]:.3f} → {s4.breakdown_W[f]:.3f}" for f in ("rolling", "pivoting",
                                                                                          "hysteresis", "sliding"))
    L += [f"* **Seed 002 temperature / torque** (RMS L3 {_rms_pct(errT[0]):.2f} / {_rms_pct(errM[0]):.2f} %, L4 "
          f"{_rms_pct(errT[1]):.2f} / {_rms_pct(errM[1]):.2f} %): the 51107 under a pure thrust load has no high-speed "
          "form (thrust) and all balls equal, so L4 differs from L3 only by the exact Hertz ellipse instead of "
          f"Hamrock–Brewe's: power {100 * min(dP):+.3f} … {100 * max(dP):+.3f} %, thermocouple III "
          f"{min(dT):+.3f} … {max(dT):+.3f} K (e.g. {c0.name} [W]: {parts}).  The model is "
          f"{-100 * max(errT[0]):.0f}–{-100 * min(errT[0]):.0f} % too cool at every case (estimated rig network), so "
          "a slightly lower power reads as a slightly larger error; a hundredth of a kelvin is far below any "
          "thermocouple's accuracy and carries no information.", ""]


# ------------------------------------------------------------------------------------------ reading
def reading(L, ratios, band, wi, hs, steps):
    wc_gain, dal, fast = hs
    dr = {T: steps[T]["dr"] for T in TEMPS}
    share = {f: [dr[T][f] / sum(dr[T].values()) for T in TEMPS] for f in ("drag", "rolling", "pivoting")}
    d32 = [100 * (steps[T]["L4"][3200.0]["P"] / steps[T]["L3"][3200.0]["P"] - 1) for T in TEMPS]
    d65 = [100 * (steps[T]["L4"][6500.0]["P"] / steps[T]["L3"][6500.0]["P"] - 1) for T in TEMPS]
    spread = max(steps[T]["spread"] for T in TEMPS)
    one_rms = {lv: 100 * rms(wi[("rolling force: one form (Biboulet PVR) in every regime", lv, "u")]) for lv in ("L1", "L2")}

    def rng(x, f="{:.0f}"):
        lo, hi = f.format(min(x)), f.format(max(x))
        return lo if lo == hi else f"{lo} … {hi}"
    e = {k: 100 * rms(v[1]) for k, v in ratios.items()}
    trend = {k: v[1][-1] - v[1][0] for k, v in ratios.items() if "before" not in k and k != "L0"}
    one = "rolling force: one form (Biboulet PVR) in every regime"
    f3 = ", ".join
    L += ["## 9. Diagnosis", "",
          f"* **Two scoring defects, fixed** (§1): L3 (was L2's {e['L2']:.1f} %) and L4 (was "
          f"{e['L4 before (uniform T, dry law)']:.1f} % at a uniform T with the dry law) are now scored as the paper "
          f"compares: L3 {e['L3']:.1f} %, L4 {e['L4']:.1f} %, both within the ≤ 10 % target.  Ladder: L0 "
          f"{e['L0']:.1f} → L1 {e['L1']:.1f} → L2 {e['L2']:.1f} → L3 {e['L3']:.1f} → L4 {e['L4']:.1f} %: the highest "
          "level is more accurate than the lowest; two steps rise: L1 → L2 and L3 → L4.",
          "* **L1 → L2** (§3): at 30 °C the ratio falls mostly through the outer contacts' rolling at 3200 rpm.  The "
          "Jones–Harris loads leave the balls around ψ = 180° with 8–11 N on the outer race (3200 rpm) and 0–3 N on the inner "
          "(L1's uniform axial share: ≥ 12 N inner, ≥ 20 N outer); such light contacts sit near the IVR / PVR "
          "boundary, whose two rolling forms (Houpert IVR, Biboulet PVR: seed 004 eqs 17, 19) meet only to "
          "×0.5–0.9 (`losses/rolling.py`), and they cross it at other loads at 3200 and 6500 rpm.  With one form in "
          f"every regime the ratios are L1 {f3(f'×{x:.2f}' for x in wi[(one, 'L1', 'u')])}, L2 "
          f"{f3(f'×{x:.2f}' for x in wi[(one, 'L2', 'u')])} (§5; RMS {one_rms['L1']:.1f} → {one_rms['L2']:.1f} %): "
          f"the step shrinks from {e['L2'] - e['L1']:+.1f} to {one_rms['L2'] - one_rms['L1']:+.1f} points, the load "
          "distribution's own effect.",
          f"* **L3 → L4** (§3, §4): at equal ring temperature the high-speed form changes P(3200) by "
          f"{rng(d32, '{:+.1f}')} % and P(6500) by {rng(d65, '{:+.1f}')} % (Δr {rng([sum(v.values()) for v in dr.values()], '{:+.2f}')}; "
          f"shares: drag {rng([100 * x for x in share['drag']])} %, rolling {rng([100 * x for x in share['rolling']])} %, "
          f"pivoting {rng([100 * x for x in share['pivoting']])} %).  Its cage "
          f"runs {100 * (wc_gain - 1):+.1f} % faster at 6500 rpm than the low-speed form's: under outer-raceway "
          f"control the balls outside the load zone (α_i − α_o up to {dal:.0f}°) would orbit up to "
          f"{100 * (fast - 1):.0f} % faster than the most loaded one and pull the load-weighted cage, which raises the "
          "drag ∝ ω_c³, the outer entrainment "
          "speed and the inner spin.  The form is Jones's model as published (§4 checks it at every ball), so this "
          "is the raceway-control hypothesis at work: with inner-raceway control the L4 ratio at equal ring "
          f"temperature would be {f3(f'×{x:.2f}' for x in wi['inner'])} (§5) — the measured ≈ 3 lies between the "
          "two hypotheses.",
          f"* **The trend with temperature** is the same at every local level: the ratio rises by "
          f"{min(trend.values()):.2f}–{max(trend.values()):.2f} from 30 to 70 °C.  At 30 °C inlet shear heating and "
          "replenishment (φ_T and Φ_rs fall with n·ν) and the hotter balls at 6500 rpm hold the rolling's speed "
          "exponent near 1.3 (§7); at 70 °C they fade (exponent ≈ 1.6, the U^0.64–0.75 of the rolling forms) and the "
          "drag (exponent 2.1–2.2: ∝ ω_c³ X with Parker's X ∝ 1/n) lifts the ratio: without drag the L4 ratio at 70 °C "
          "is ≈ 3.0 (§7).",
          f"* **The reference** (§6) is known to ±{100 * min(band.values()):.0f}–{100 * max(band.values()):.0f} % "
          "per temperature from the torquemeter alone, stated as one number for 25–70 °C.  Points within ±1 RSS: "
          f"{within_band(ratios, band)}.  The ≤ 10 % target lies inside the reference's own uncertainty; the "
          "differences between L1 … L4 (a few per cent of RMS) are below what it resolves.",
          f"* **The blended alternatives of L4 are sound here**: the film and dry laws differ by at most "
          f"{100 * spread:.1f} % in power at these points at equal ring temperature (the least loaded contact carries "
          "5–7 % of the greatest: weights 0.28 / 0.44 on the film law at 3200 / 6500 rpm, §2) and move the ratio by "
          "≤ 0.015 at a uniform T (§3).", "",
          "### Physics still missing", "",
          "1. **Ball attitude and cage speed from the contacts' traction** (a quasi-dynamic ball equilibrium with the "
          "film's traction) instead of Jones's raceway-control hypothesis: outer and inner control bracket the "
          f"6500 rpm power by {100 * min(wi['inner_dP']):.0f}–{100 * max(wi['inner_dP']):.0f} %; measurements of an "
          "angular-contact bearing's cage speed ratio suggest race control for slip rather than for pivoting "
          "(\"Basic speed ratio of an angular contact bearing\", ASME J. Lubr. Technol. 102(3):391, 1980).  This "
          "is what makes L4 worse than L3 here.",
          "2. **A rolling force continuous across the IVR / PVR / EHL boundaries** for lightly loaded contacts (seed "
          "004 eqs 17–19 meet only to ×0.5–0.9): what makes L2 worse than L1.",
          "3. **The drag's size and speed law** (`seed004_drag.md`: 13–21 % of the power against the paper's ≈ 5 %; "
          "Pouly's A_c and c_d not recovered): what lifts the ratio at 70 °C.",
          "4. **The measured temperature dependence of the ratio** (Fig. 9b itself, not available): with it the "
          "inlet-heating and replenishment reductions (Gupta et al. 1992; SKF's Φ_rs, a global model's factor "
          "applied here to each contact) could be checked at 30 °C, where they set the ratio.", ""]


HEADER = ("# Seed 004 — fidelity levels and the ×2 speed ratio (issue 17)\n\nGenerated by "
          "`validation/seed004_fidelity_diagnosis.py`.  Scene `examples/seed004_oil_jet_7210.toml` (7210 ACBB, Fa 450 N, "
          "Fr 325 N per bearing, oil jet 10 L/h at 30 °C; D = 12.7 mm and f = 0.52 estimated).  Reference: \"at an "
          "identical [OR–IR] mean temperature, power losses are multiplied by 3 when the speed is twice higher\" "
          "(seed 004 §5.3.1, 25–70 °C), scored as P(6500)/P(3200) at 30, 50, 70 °C (`validation/fidelity.py`).  "
          "Nothing is fitted.\n")


def main() -> int:
    warnings.simplefilter("ignore", ExtrapolationWarning)
    warnings.simplefilter("ignore", OutsideValidity)
    L = [HEADER]
    checks(L)
    ratios = ratio_table(L)
    ladder(L)
    fam4 = ring_step(L)
    steps = fam4
    hs = high_speed_check(L)
    wi = what_ifs(L)
    band = reference(L, ratios["L4"])
    needs(L, ratios["L4"], steps)
    other_families(L)
    reading(L, ratios, band, wi, hs, steps)
    path = write_report("seed004_fidelity_diagnosis.md", L)
    print("P(6500)/P(3200) RMS: " + ", ".join(f"{k.split(' ')[0]} {100 * rms(v[1]):.1f} %" for k, v in ratios.items()
                                             if "before" not in k) + f"  -> {path}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
