"""Where the local model's excess torque on seed 002 comes from, and what each added physics removes.

Seed 002 (Cousseau et al.): 51107 thrust ball bearing, F_a = 7000 N, greases, 1000 and 2000 rpm, at the
measured temperatures.  For every case this script sets side by side

1. the measured torque and the authors' SKF split M_rr / M_sl (Table 3, 1000 rpm; recalibrated R1, S1);
2. the local model's components (rolling, sliding = Heathcote micro-slip, pivoting = spin, hysteresis)
   as it was (constant full-film μ_e = 0.05, isothermal inlet, fully flooded) and with each physics of
   issue 17 added in turn: the base oil's traction law (:mod:`thermobear.losses.traction`), inlet
   shear heating (:mod:`thermobear.lubrication.thermal_film`), kinematic replenishment (SKF Φ_rs on
   the rolling force);
3. the contact conditions the literature values depend on (p_max, slip-to-roll of the spin, Λ, h_c),
   and the film's traction coefficient against slip at these conditions;
4. the sensitivity of the result to the one uncertain traction parameter, the Eyring stress τ0;
5. the same decomposition for seed 001 (low speeds) and seed 004 (P ratio), where targets remain.

No parameter is taken from the scored torques.  Run:  python validation/seed002_local_diagnosis.py
(writes validation/report/seed002_local_diagnosis.md)
"""
from __future__ import annotations

import csv
import io
import warnings
from pathlib import Path

import numpy as np

from _common import write_report

import thermobear as tb
from thermobear.coupled.pipeline import scene_contacts
from thermobear.errors import ExtrapolationWarning
from thermobear.losses import evaluate_losses
from thermobear.losses.skf import K_RS, phi_ish, phi_rs, skf_K_z
from thermobear.losses.traction import STRIP_NODES, strip_traction_coefficient
from thermobear.lubrication.lubricant import Lubricant
from thermobear.models import plan

HERE = Path(__file__).resolve().parent
STEPS = (("as before (μ_e 0.05, isothermal, flooded)", {}),
         ("+ traction law", {"traction": "eyring"}),
         ("+ inlet shear heating", {"traction": "eyring", "inlet_heating": True}),
         ("+ replenishment Φ_rs", {"traction": "eyring", "inlet_heating": True, "starvation": True}))
PARTS = ("rolling", "sliding", "pivoting", "hysteresis")


def _cases():
    text = (HERE / "data" / "seed002_greases.csv").read_text(encoding="utf-8")
    rows = [r for r in csv.DictReader(io.StringIO("\n".join(l for l in text.splitlines() if not l.startswith("#"))))
            if r["Mrr_Nmm"]]
    out = [(r["grease"], 1000.0, float(r["T_1000rpm_C"]), float(r["Mrr_Nmm"]) + float(r["Msl_Nmm"]),
            float(r["Mrr_Nmm"]), float(r["Msl_Nmm"])) for r in rows]
    return out + [("MG1", 2000.0, 65.0, 155.0, None, None), ("PG2", 2000.0, 53.0, 110.0, None, None)]


def _losses(scene, T, lub=None, **opts):
    models, dry = plan(scene)
    cs = scene_contacts(scene, models, dry)
    return cs, evaluate_losses(cs, lub or scene.lubricant, T, supply=scene.supply, Rq_ball=scene.Rq_ball,
                               Rq_ring=scene.Rq_ring, mu_boundary=scene.mu_boundary, drag=False, **opts)


def _torque_Nmm(r, n):
    om = n * np.pi / 30.0
    return {k: 1e3 * r.breakdown_W[k] / om for k in PARTS}, 1e3 * r.P_W / om


def seed002_tables(base, tau0=None):
    lines, errs = [], {s: [] for s, _ in STEPS}
    for g, n, T, M, Mrr, Msl in _cases():
        sc = base.with_(lubricant=f"seed002-{g.lower()}", n_rpm=n, T_C=T)
        lub = sc.lubricant
        if tau0 is not None:
            lub = _with_tau0(lub, tau0)
        for label, opts in STEPS:
            cs, r = _losses(sc, T, lub, **opts)
            parts, tot = _torque_Nmm(r, n)
            errs[label].append(tot / M - 1)
            if tau0 is None:
                skf = f"{Mrr:.1f} / {Msl:.1f}" if Mrr is not None else "–"
                lines.append(f"| {g} {n:g} rpm | {M:.1f} | {skf} | {label} | "
                             + " | ".join(f"{parts[k]:.1f}" for k in PARTS) + f" | {tot:.1f} | {100 * (tot / M - 1):+.0f} % |")
    rms = {k: 100 * float(np.sqrt(np.mean(np.square(v)))) for k, v in errs.items()}
    return lines, rms


def _with_tau0(lub, tau0):
    new = object.__new__(Lubricant)
    new.__dict__.update(lub.__dict__)
    new.eyring_stress = float(tau0)
    return new


def contact_conditions(base):
    out = ["| case | p_max [GPa] | a, b [mm] | u [m/s] | spin slip/roll at x = a | h_c [µm] | Λ | μ_f spin | "
           "μ_f micro-slip | φ_T | Φ_rs |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for g, n, T, *_ in _cases():
        sc = base.with_(lubricant=f"seed002-{g.lower()}", n_rpm=n, T_C=T)
        cs, r = _losses(sc, T, **STEPS[-1][1])
        c = r.contacts["inner"]
        Q, a, b, u = (float(np.asarray(x)[..., 0, 0]) for x in (cs.Q, cs.a, cs.b, cs.u))
        pmax = 1.5 * Q / (np.pi * a * b)
        sp = abs(float(np.asarray(cs.spin)[..., 0, 0]))
        args = (float(c["h_c"][0]), float(c["eta"][0]), sc.lubricant.alpha_p_at(T), sc.lubricant.eyring_stress,
                sc.lubricant.limiting_shear)
        mu_h, mu_s = strip_traction_coefficient(cs.slips[..., 0, 0, :, :], cs.p_strip[..., 0, 0, :, :], *args)
        b_ = sc.bearing
        pr = float(phi_rs(n, sc.lubricant.nu(T), b_.bore * 1e3, b_.outer_diameter * 1e3, skf_K_z(b_.kind),
                          K_RS["grease"]))
        _, r0 = _losses(sc, T)
        phiT = float(c["h_c"][0]) / float(r0.contacts["inner"]["h_c"][0])
        out.append(f"| {g} {n:g} rpm | {pmax / 1e9:.2f} | {a * 1e3:.3f}, {b * 1e3:.3f} | {u:.2f} | "
                   f"{sp * a / u:.3f} | {float(c['h_c'][0]) * 1e6:.3f} | {float(c['Lambda'][0]):.2f} | "
                   f"{float(mu_s):.4f} | {float(mu_h):.4f} | {phiT:.3f} | {pr:.3f} |")
    return out


def traction_curve(base):
    """μ of the film at uniform slip (not the strip average) at MG1, 1000 rpm, against slide-to-roll."""
    sc = base.with_(lubricant="seed002-mg1", n_rpm=1000.0, T_C=49.8)
    cs, r = _losses(sc, 49.8, **STEPS[-1][1])
    c = r.contacts["inner"]
    u = float(np.asarray(cs.u)[..., 0, 0])
    pm = cs.p_strip[..., 0, 0, 0, :]
    rows = ["| slide-to-roll | μ (Eyring, τ0 5 MPa) |", "|---|---|"]
    for srr in (1e-4, 1e-3, 3e-3, 1e-2, 3e-2, 0.1):
        mu = strip_traction_coefficient(np.full(pm.shape, srr * u), pm, float(c["h_c"][0]), float(c["eta"][0]),
                                        sc.lubricant.alpha_p_at(49.8), 5e6, 0.075)
        rows.append(f"| {srr:g} | {float(mu):.4f} |")
    return rows


def other_seeds():
    out = []
    base = tb.load_scene(tb.example_path("seed001_spin_down_3ball.toml"))
    raw = {k: dict(v) for k, v in base.raw.items()}
    out += ["| seed 001 case | Λ | regime | rolling | sliding | pivoting | hysteresis | rolling share |",
            "|---|---|---|---|---|---|---|---|"]
    for d, Q, rpm in ((6.35, 0.125, 60.0), (6.35, 0.125, 210.0)):
        raw["bearing"].update(D_mm=d, fi=4.16 / d, fo=4.16 / d)
        raw["operation"].update(n_rpm=rpm, Fa_N=3 * Q)
        sc = tb.scene.scene_from_dict(raw)
        _, r = _losses(sc, 26.5, **{"traction": "eyring"})
        parts, tot = _torque_Nmm(r, rpm)
        c = r.contacts["inner"]
        out.append(f"| d {d} mm, {Q} N, {rpm:g} rpm | {float(np.min(c['Lambda'])):.1f} | {c['regime'][0]} | "
                   + " | ".join(f"{parts[k] * 1e3:.3f}" for k in PARTS) + f" | {parts['rolling'] / tot:.2f} |")
    out += ["", "(seed 001 torques in µN m.)", ""]
    sc4 = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    out += ["| seed 004, 50 °C | P(3200) [W] | P(6500) [W] | ratio |", "|---|---|---|---|"]
    for label, opts in STEPS:
        P = []
        for n in (3200.0, 6500.0):
            s = sc4.with_(n_rpm=n, T_C=50.0)
            models, dry = plan(s)
            cs = scene_contacts(s, models, dry)
            r = evaluate_losses(cs, s.lubricant, 50.0, supply=s.supply, oil_flow_m3_s=s.oil_flow, Rq_ball=s.Rq_ball,
                                Rq_ring=s.Rq_ring, drag=bool(models["drag"][0]), **opts)
            P.append(float(r.P_W))
        out.append(f"| {label} | {P[0]:.1f} | {P[1]:.1f} | {P[1] / P[0]:.2f} |")
    return out


def main():
    warnings.simplefilter("ignore", ExtrapolationWarning)
    base = tb.load_scene(tb.example_path("seed002_grease_thrust_51107.toml"))
    rows, rms = seed002_tables(base)
    lines = ["# Seed 002: where the local model's excess comes from", "",
             "Generated by `validation/seed002_local_diagnosis.py`. 51107, F_a 7000 N, greases at the measured "
             "temperatures (base-oil properties), Jones–Harris loads, exact Hertz, no drag (grease, n d_m < 1e5). "
             "Torques in N mm. SKF split: the authors' Table 3 (their recalibrated R1, S1; it includes Φ_ish Φ_rs).",
             "", "## Components, step by step", "",
             "| case | measured | SKF M_rr / M_sl | local model | rolling | sliding | pivoting | hysteresis | total | error |",
             "|---|---|---|---|---|---|---|---|---|---|", *rows, "",
             "| model | RMS error over the 7 cases |", "|---|---|",
             *[f"| {k} | {v:.1f} % |" for k, v in rms.items()], "",
             "## Contact conditions (inner washer contact, all physics on)", "", *contact_conditions(base), "",
             "Spin slip/roll ω_s a/u: the spin of the thrust contact slips at ≤ 3–4 % of the rolling speed at the "
             "ends of the major axis and less inside, where an EHL film at 1.5–2 GPa has not reached its plateau "
             "traction.  The constant μ_e = 0.05 charged the whole ellipse with it.", "",
             "## The film's traction at these conditions (MG1, 1000 rpm, uniform slip)", "", *traction_curve(base), ""]
    sens = ["## Sensitivity to the Eyring stress τ0 (all physics on)", "",
            "| τ0 [MPa] | RMS error |", "|---|---|"]
    for t0 in (2.5e6, 5e6, 10e6):
        sens.append(f"| {t0 / 1e6:g} | {seed002_tables(base, t0)[1][STEPS[-1][0]]:.1f} % |")
    lines += sens + ["", "τ0 = 5 MPa is the middle of the 2–10 MPa that Johnson & Tevaarwerk (1977) and Evans & "
                     "Johnson (1986) report for mineral and synthetic base oils (recalled; "
                     "materials/lubricant_traction.toml).  It was set before scoring and is not fitted: the "
                     "torques scale nearly with it, so this parameter carries most of the remaining uncertainty.",
                     "", "## Seed 001 and seed 004", "", *other_seeds(), "", _diagnosis_text(rms)]
    write_report("seed002_local_diagnosis.md", lines)
    print("\n".join(lines))


def _diagnosis_text(rms):
    return "\n".join([
        "## Diagnosis", "",
        f"* **Pivoting (spin) was the largest excess.**  At μ_e = 0.05 the spin of the 18 contacts costs "
        "~98 N mm on MG1, more than the authors' whole sliding torque (88.5).  The film's Eyring law at the "
        "contacts' pressure and slip gives μ_f ≈ 0.03 for the spin of mineral oils and less for the esters "
        "(lower α_p): pivoting falls by 40–80 %.  The Heathcote micro-slip falls likewise.",
        "* **Rolling** (Houpert EHL, 115 N mm on MG1) exceeds the authors' M_rr (86.8, which also holds the "
        "hysteresis) by a third.  Inlet shear heating (φ_T ≈ 0.97 here) removes 3–5 %; grease replenishment "
        "(SKF Φ_rs 0.80 for MG1 at 1000 rpm, 0.9 for the thin oils) removes 10–20 %.",
        "* **Hysteresis** (Houpert 1999, seed 000 eq 25): 37 N mm for every grease, 20–34 % of the measured "
        "torques.  Written as Johnson's rolling resistance M = c α Q b it implies a hysteresis loss factor "
        "α ≈ 0.03, several times the fraction of a percent usually quoted for hardened steel (not checked "
        "here).  It is the largest remaining suspect: the PAO/ester greases (PG1, PG2), whose viscous terms "
        "are smallest, are the ones still over-predicted (+22 … +34 %).",
        f"* With the three additions the RMS error is {rms[STEPS[-1][0]]:.1f} % (from {rms[STEPS[0][0]]:.1f} %).",
        "* Mixed lubrication: PG1 and PG2 run at Λ < 1 with the estimated roughness (Rq 0.05 / 0.1 µm); the "
        "boundary share of seed 000 eq 18 (μ_a 0.11) then adds 10–20 N mm.  The seed's roughness is not "
        "measured, so Λ itself is uncertain by the roughness estimate.",
        "* **Traction of the ester / PAO oils is too low to be trusted.**  μ_f of the spin is 0.002–0.005 for "
        "EG1, PG1, PG2 (table above): Roelands' η(p) with the index Z that matches their Gold α_p (11–12 GPa⁻¹ "
        "at 0.2 GPa) gives only 10²–10³ Pa s at 2 GPa, so the film is nearly Newtonian; measured EHL traction "
        "of such oils at these pressures is of order 0.02–0.05.  Their small totals are then partly the "
        "compensation of two errors (too little traction, too much hysteresis).  What is missing: a "
        "pressure–viscosity law measured to EHL pressures for these base oils (Bair's free-volume forms), "
        "not available for the seed-002 oils.",
        "* Seed 001 (3 balls, 0.1–0.6 N): the hydrodynamic rolling force is 99 % of the torque at 60 and 210 "
        "rpm (table above).  At 60 rpm Λ = 0.6, but even the boundary μ on the slip (sliding, pivoting) "
        "is < 1 % of the torque, and an asperity share of the load would lower the film's rolling force, "
        "not raise it; inlet heating and replenishment are < 1 % there (choose_models leaves them off).  "
        "The low-speed deficit (−35 … −42 % at 60 rpm) is in the speed exponent of the rolling force itself "
        "(the measured n of T ∝ ω^n is lower than the U^0.64–0.75 of the Biboulet/Houpert fits): the "
        "physics still missing is a rolling resistance that does not vanish with speed (meniscus and "
        "viscous drag of the balls in the bath, or the rig's own losses), not a film effect.",
    ])


if __name__ == "__main__":
    main()
