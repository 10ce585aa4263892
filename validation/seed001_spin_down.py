"""Seed 001 (Bălan et al. 2015): EHL partitions and the spin-down torques of Tables 1–2.

Run:  python validation/seed001_spin_down.py
Writes validation/report/seed001_spin_down.md and prints the same text.

Rig (seed 001 §2–3): modified 51205, three balls between two thrust races with
groove radius 4.16 mm, no cage, two drops of mineral oil, 26–27 °C.  Per ball
load Q; T_z = 6 r F_R (3 balls × 2 contacts, r = 18 mm, v = ω r/2), hysteresis,
pivoting and inertia neglected as in the paper (their size is printed below).
The experimental torques are T_exp = K* ω^n at the initial speed of each run
(Tables 1–2; they include the dry torque, 2–12 % of the total, §4.3).
"""
from __future__ import annotations

import csv
import io
import math
from pathlib import Path

import numpy as np

from _common import write_report

from thermobear.lubrication.film import film_thickness, lubrication_regime
from thermobear.losses import rolling as R
from thermobear.losses import sliding as S
from thermobear.contact.hertz import hertz
from thermobear.lubrication.lubricant import lubricant
from thermobear.app.spindown import fit_from_stop, stop_time, total_angle

HERE = Path(__file__).resolve().parent
E_PRIME = 2.3e11          # seed 001 §2: E* ≈ 2.3e11 Pa for steel on steel
R_TRACK = 0.018           # pitch radius of the 51205: dm 36 mm (seed 000 §3)
GROOVE = 4.16e-3          # seed 001 §3.1
SIGMA = math.hypot(0.06e-6, 0.03e-6)


def read_tables():
    text = (HERE / "data" / "seed001_spin_down.csv").read_text(encoding="utf-8")
    rows = list(csv.DictReader(io.StringIO("\n".join(l for l in text.splitlines() if not l.startswith("#")))))
    return [{k: (v if k == "table" else float(v)) for k, v in r.items()} for r in rows]


def radii(d):
    return d / 2, GROOVE * (d / 2) / (GROOVE - d / 2)


def torque(model, d, Q, eta, omega):
    Rx, Ry = radii(d)
    return 6 * R_TRACK * R.rolling_force(Q, Rx, Ry, omega * R_TRACK / 2, eta, E_PRIME, model=model)


def local_exponent(model, d, Q, eta, omega, h=1e-4):
    return (math.log(torque(model, d, Q, eta, omega * (1 + h))) - math.log(torque(model, d, Q, eta, omega))) \
        / math.log(1 + h)


def mixed_section(w, rows, alpha_p):
    """Mixed lubrication: the load-sharing rolling resistance (rolling_force_mixed) against Tables 1-2."""
    w("## Mixed lubrication: the asperity share of the rolling resistance (load sharing)\n")
    w("`thermobear.losses.rolling.rolling_force_mixed`: the film carries (1 − Q_a/Q) Q (Johnson, Greenwood & Poon "
      "1972 load sharing; Q_a/Q(Λ) of seed 001 App. A), the asperities Q_a.  The film's force is the transition "
      "model at the film-borne load; the asperity term c_rr,a Q_a is 0 here (the asperities' hysteresis and micro-slip "
      "are the local model's MER and μ(Λ) terms).  'bound' adds the largest asperity rolling resistance seed 001 "
      "allows: its dry torque (all load on asperities) is at most 12 % of the lubricated torque (§4.3), so the "
      "asperity share adds at most Q_a/Q × 12 % of T_exp.\n")
    w("| table | rpm | Λ | Q_a/Q | T_exp [N m] | T transition (err) | T mixed (err) | T mixed + bound (err) |")
    w("|---|---|---|---|---|---|---|---|")
    errs = {"transition": [], "mixed": [], "bound": []}
    for r in rows:
        d, Q, eta = r["d_mm"] * 1e-3, r["Q_N"], r["eta_Pa_s"]
        om = r["initial_rpm"] * math.pi / 30
        t_exp = r["K"] * om ** r["n"]
        Rx, Ry = radii(d)
        u = om * R_TRACK / 2
        lam = film_thickness(Q, Rx, Ry, u, eta, alpha_p, E_PRIME, kind="min") / SIGMA
        s = float(S.asperity_load_share(lam))
        t_tr = torque("biboulet_transition", d, Q, eta, om)
        t_mx = 6 * R_TRACK * float(R.rolling_force_mixed(Q, Rx, Ry, u, eta, E_PRIME, lam))
        t_bd = t_mx + 0.12 * s * t_exp
        e = {"transition": t_tr / t_exp - 1, "mixed": t_mx / t_exp - 1, "bound": t_bd / t_exp - 1}
        for k, v in e.items():
            errs[k].append(v)
        w(f"| {r['table']} | {r['initial_rpm']:.0f} | {lam:.2f} | {s:.2f} | {t_exp:.3g} | {t_tr:.3g} "
          f"({100 * e['transition']:+.0f} %) | {t_mx:.3g} ({100 * e['mixed']:+.0f} %) | {t_bd:.3g} "
          f"({100 * e['bound']:+.0f} %) |")
    rms = {k: 100 * math.sqrt(np.mean(np.square(v))) for k, v in errs.items()}
    w(f"\nRMS over both tables: transition {rms['transition']:.1f} %, mixed {rms['mixed']:.1f} %, mixed + bound "
      f"{rms['bound']:.1f} %.\n")
    w("* The film share *lowers* the rolling force: every hydrodynamic force here is load controlled "
      "(F_R ∝ Q^(1/3) at a given partition), so taking load off the film lowers it (−13 % at Λ = 0.27, partly offset "
      "by the lighter film leaning towards the larger IVR force).  Load sharing moves the prediction away from the "
      "measurements at every point.")
    w("* The asperity share cannot close the gap either: even the whole dry torque of seed 001 §4.3 on the "
      "asperity share leaves Table 1 at 60 rpm far below the measurement, because the gap there (≈ 35–40 % of "
      "T_exp) is three times the largest dry torque (12 %).")
    w("* What the data ask for is a resistance nearly independent of speed (Table 1 n = 0.12–0.37) and 3× the dry "
      "rolling resistance at Λ ≈ 0.3, fading by Λ ≈ 0.6.  Candidates not in the model: the roughness effect on the "
      "inlet Poiseuille flow itself (Patir & Cheng 1978 average flow model: pressure-flow factor φ_x < 1 for "
      "h/σ ≲ 3 raises the inlet pressure gradient and hence F_R, more as Λ falls) — that needs an average-Reynolds "
      "IVR/EHL solution (φ_x varies across the inlet, where h runs from h_min to many σ), not a rescaling of the "
      "smooth closed forms; and α_p of the oil (estimated) which sets Λ.  Table 2's deficit is the model choice, not mixing: "
      "Biboulet's IVR force (the paper's recommendation for EHL partition < 50 %, §4.5) is within 11 % RMS.\n")


def main():
    out = []
    w = out.append
    alpha_p = lubricant("seed001-oil-b").alpha_p_at(26.5)
    w("# Seed 001 (Bălan et al. 2015) — EHL partition and spin-down torques\n")
    w(f"E' = {E_PRIME:.3g} Pa, r = {R_TRACK * 1e3:.0f} mm, v = ω r/2, groove radius 4.16 mm, "
      f"T_z = 6 r F_R.  α_p = {alpha_p:.3g} 1/Pa (estimated; enters Λ and the regime only).\n")

    # ------------------------------------------------------------- §4.4 EHL partition
    w("## EHL partition, d 6.35 mm, Q 0.125 N (paper §4.4: 41 % at 60 rpm → 21 % at 210 rpm)\n")
    w("| η [Pa s] | " + " | ".join(f"{n} rpm" for n in (60, 90, 120, 150, 180, 210)) + " |")
    w("|---|" + "---|" * 6)
    Rx, Ry = radii(6.35e-3)
    for eta in (0.05, 0.08):
        om = np.array([60, 90, 120, 150, 180, 210]) * math.pi / 30
        p = R.ehl_partition(0.125, Rx, Ry, om * R_TRACK / 2, eta, E_PRIME)
        w(f"| {eta} | " + " | ".join(f"{100 * v:.1f} %" for v in p) + " |")
    w("\nη = 0.05 Pa s reproduces 41 % → 21 % (the stated range, \"between 40 % and 20 %\").\n")

    # ------------------------------------------------------------- Tables 1-2
    rows = read_tables()
    w("## Experimental torque at the initial speed vs model (T_exp = K* ω0^n)\n")
    summary = {}
    for table, label in (("1", "Table 1: d 3 mm, Q 0.633 N, η 0.05 Pa s"),
                         ("2", "Table 2: d 6.35 mm, Q 0.125 N, η 0.05 Pa s")):
        w(f"### {label}\n")
        w("| rpm | EHL partition | regime | Λ | T_exp [N m] | T IVR [N m] (err) | T transition [N m] (err) "
          "| n exp | n IVR | n trans |")
        w("|---|---|---|---|---|---|---|---|---|---|")
        errs = {"biboulet_ivr": [], "biboulet_transition": []}
        parts, n_exps, n_trs = [], [], []
        for r in (r for r in rows if r["table"] == table):
            d, Q, eta = r["d_mm"] * 1e-3, r["Q_N"], r["eta_Pa_s"]
            om = r["initial_rpm"] * math.pi / 30
            t_exp = r["K"] * om ** r["n"]
            Rx, Ry = radii(d)
            u = om * R_TRACK / 2
            part = R.ehl_partition(Q, Rx, Ry, u, eta, E_PRIME)
            reg = lubrication_regime(Q, Rx, Ry, u, eta, alpha_p, E_PRIME).code
            lam = film_thickness(Q, Rx, Ry, u, eta, alpha_p, E_PRIME, kind="min") / SIGMA
            t_ivr, t_tr = torque("biboulet_ivr", d, Q, eta, om), torque("biboulet_transition", d, Q, eta, om)
            e_ivr, e_tr = t_ivr / t_exp - 1, t_tr / t_exp - 1
            errs["biboulet_ivr"].append(e_ivr)
            errs["biboulet_transition"].append(e_tr)
            parts.append(part)
            n_exps.append(r["n"])
            n_trs.append(local_exponent("biboulet_transition", d, Q, eta, om))
            w(f"| {r['initial_rpm']:.0f} | {100 * part:.0f} % | {reg} | {lam:.2f} | {t_exp:.3g} | "
              f"{t_ivr:.3g} ({100 * e_ivr:+.0f} %) | {t_tr:.3g} ({100 * e_tr:+.0f} %) | {r['n']:.3f} | "
              f"{local_exponent('biboulet_ivr', d, Q, eta, om):.3f} | "
              f"{local_exponent('biboulet_transition', d, Q, eta, om):.3f} |")
        rms = {k: math.sqrt(np.mean(np.square(v))) for k, v in errs.items()}
        best = min(rms, key=rms.get)
        summary[table] = (rms, best, parts, n_exps, n_trs)
        w(f"\nRMS relative error: IVR {100 * rms['biboulet_ivr']:.0f} %, transition "
          f"{100 * rms['biboulet_transition']:.0f} % → best: **{best}**.\n")
    w("## Which model fits which table\n")
    for table, what in (("1", "3 mm balls, 0.633 N"), ("2", "6.35 mm balls, 0.125 N")):
        rms, best, part, n_exp, n_tr = summary[table]
        w(f"* Table {table} ({what}, EHL partition {100 * min(part):.0f}–{100 * max(part):.0f} %): "
          f"best **{best}** (RMS {100 * rms[best]:.0f} %; other model "
          f"{100 * max(rms.values()):.0f} %).")
    w("* Paper (§4.4–4.5): transition equation when the EHL partition exceeds 50 %, IVR equation when "
      "IVR dominates (Q = 0.125 N).  Reproduced.")
    dom, tra = [], []
    for r in rows:
        om = r["initial_rpm"] * math.pi / 30
        t_exp, d = r["K"] * om ** r["n"], r["d_mm"] * 1e-3
        dom.append(torque("biboulet_dominant", d, r["Q_N"], r["eta_Pa_s"], om) / t_exp - 1)
        tra.append(torque("biboulet_transition", d, r["Q_N"], r["eta_Pa_s"], om) / t_exp - 1)
    lo, hi = R.DOMINANT_BAND
    w(f"* The paper's rule as one model, `biboulet_dominant` (`losses.rolling.rolling_force_biboulet_dominant`: the "
      f"IVR equation below an EHL partition of {100 * lo:.0f} %, the transition equation above {100 * hi:.0f} %, a C¹ "
      f"blend in between), which the seed-001 scene uses: RMS {100 * math.sqrt(np.mean(np.square(dom))):.0f} % on "
      f"the 12 cases (per case {', '.join(f'{100 * e:+.0f}' for e in dom)} %), against "
      f"{100 * math.sqrt(np.mean(np.square(tra))):.0f} % for the transition equation alone (the scene's choice "
      "before).  The rule is the paper's conclusion from these same runs: the score shows that thermobear "
      "reproduces the paper's model, not an independent prediction.")
    w("* The experimental values include the dry torque (2–12 % of the total, §4.3), which the paper "
      "subtracts before comparing in its figures; subtracting it would lower T_exp by that much.")
    rms1, _, _, n1, nt1 = summary["1"]
    _, _, _, n2, nt2 = summary["2"]
    w(f"* Speed exponent: the IVR model has n = 2/3, close to Table 2's {min(n2):.2f}–{max(n2):.2f}.  "
      f"The transition model's local exponent at Table 1's conditions is {min(nt1):.2f}–{max(nt1):.2f} "
      f"(above both 2/3 and 3/4: as speed rises the weight shifts towards the larger IVR force), against the fitted {min(n1):.2f}–{max(n1):.2f}: "
      "the measured Table 1 torque rises much more slowly with speed than any of the models, so the "
      "transition model is 40 % low at 60 rpm and within 10 % at 210 rpm.  A Λ of 0.3–0.6 "
      "(mixed lubrication, asperity contact) for these runs is a plausible cause the model does not contain.\n")

    mixed_section(w, rows, alpha_p)

    # ------------------------------------------------------------- neglected terms (App. A)
    w("## Terms the paper neglects (App. A), at 60 and 210 rpm, relative to T_FR = 6 r F_R (transition)\n")
    w("| case | rpm | MER term 6 r MER/d | pivoting 3 MP (μ App. A) | ratio to T_FR |")
    w("|---|---|---|---|---|")
    for d, Q in ((3e-3, 0.633), (6.35e-3, 0.633)):
        Rx, Ry = radii(d)
        a = hertz(Q, Rx, Ry, E_PRIME).a
        for rpm in (60, 210):
            om = rpm * math.pi / 30
            u = om * R_TRACK / 2
            lam = film_thickness(Q, Rx, Ry, u, 0.05, alpha_p, E_PRIME, kind="min") / SIGMA
            mu = S.mixed_friction_balan(lam, mu_ehl=0.03, mu_a=0.11)
            t_mer = 6 * R_TRACK * S.hysteresis_moment(Q, d, Ry / Rx) / d
            t_mp = 3 * S.pivoting_moment(mu, Q, a, Ry / Rx)
            t_fr = torque("biboulet_transition", d, Q, 0.05, om)
            w(f"| d {d * 1e3:.2f} mm, Q {Q} N | {rpm} | {t_mer:.3g} | {t_mp:.3g} | {100 * (t_mer + t_mp) / t_fr:.1f} % |")
    w("\nThe paper quotes 5.6 % → 2.6 % (3 mm) and 2.6 % → 0.4 % (6.35 mm) including inertia.  Here "
      "the 6.35 mm shares agree in order of magnitude; for 3 mm at 60 rpm we get about twice the "
      "paper's share, because App. A's load sharing at Λ ≈ 0.27 gives μ ≈ 0.09 and the k-dependent "
      "MP (eq 11) is used — the paper does not print its μ.  Neglecting these terms costs < 4 % "
      "above 60 rpm.\n")

    # ------------------------------------------------------------- spin-down method
    w("## Spin-down method round trip (seed 001 eqs 20–21)\n")
    J = 2.0e-4   # kg m², illustrative (the disc inertia is not published); K*, n do not depend on it
    w("For each Table 2 run, (t_max, φ_max) generated from the published K*, n with an illustrative "
      f"J = {J:g} kg m², then fitted back with `thermobear.app.spindown.fit_from_stop`:\n")
    w("| rpm | K* paper | n paper | t_max [s] | φ_max [rad] | K* fit | n fit |")
    w("|---|---|---|---|---|---|---|")
    for r in (r for r in rows if r["table"] == "2"):
        om = r["initial_rpm"] * math.pi / 30
        tm, ph = stop_time(om, r["K"], r["n"], J), total_angle(om, r["K"], r["n"], J)
        f = fit_from_stop(om, tm, ph, J)
        w(f"| {r['initial_rpm']:.0f} | {r['K']:.4g} | {r['n']:.3f} | {tm:.1f} | {ph:.1f} | {f.K:.4g} | {f.n:.3f} |")

    # ------------------------------------------------------------- auto continuity
    w("\n## Continuity of `rolling_force(model=\"auto\")` across regime boundaries\n")
    w("Seed 004 switches formulas by regime (IVR → Houpert IVR, PVR → Biboulet PVR with c_Bib, "
      "EHL → Houpert EHL).  Jump F(after)/F(before) at each boundary of a fine load sweep "
      "(regimes from thermobear.lubrication.film.lubrication_regime):\n")
    w("| contact | boundary | at Q [N] | jump ratio |")
    w("|---|---|---|---|")
    q = np.logspace(-4, 4, 20001)
    cases = [("seed 000 (D 7.938, f 0.53), u 0.0942 m/s, η 0.089, α_p 2.5e-8", 3.969e-3, 70.12e-3, 0.0942, 0.089, 2.5e-8),
             ("7210-like inner (Rx 5.2 mm, Ry 160 mm), u 9 m/s, η 0.02, α_p 2e-8", 5.2e-3, 0.16, 9.0, 0.02, 2e-8)]
    for name, Rx, Ry, u, eta, ap in cases:
        reg = lubrication_regime(q, Rx, Ry, u, eta, ap, E_PRIME).code
        f = R.rolling_force(q, Rx, Ry, u, eta, E_PRIME, model="auto", alpha_p=ap, regime=reg)
        for i in np.nonzero(reg[1:] != reg[:-1])[0]:
            w(f"| {name} | {reg[i]} → {reg[i + 1]} | {q[i]:.3g} | {f[i + 1] / f[i]:.3f} |")
    w("\nThe IVR → PVR drop (−40…−47 %) comes mostly from c_Bib ≈ 0.5 at M ≈ 10 (B&H's truncation "
      "coefficient at 2a/L = 1, which seed 004 applies throughout) and from Houpert's IVR being "
      "≈ 0.65 × Biboulet's; the PVR → EHL step (−6…−16 %) from Houpert's EHL fit vs 0.85 × "
      "Biboulet's EHL asymptote.  `biboulet_transition` and `biboulet_pvr(truncation=None)` are "
      "continuous by construction.\n")
    text = "\n".join(out)
    write_report("seed001_spin_down.md", text)
    print(text)


if __name__ == "__main__":
    main()
