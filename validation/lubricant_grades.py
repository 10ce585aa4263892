"""ISO VG oil grades (mineral and PAO) and a few generic greases: writes materials/lubricants/*.toml.

Oils "iso-vg-<grade>-mineral" and "iso-vg-<grade>-pao" for ISO VG 10 ... 460 (ISO 3448: the grade is the
kinematic viscosity at 40 °C in mm²/s, ±10 %):

* nu40 = the grade (mid-point of the ISO 3448 class);
* nu100 from nu40 and a viscosity index, by ASTM D2270 (Procedure A for VI <= 100, B above), inverted
  for nu100 with the standard's L/H table (thermobear.lubrication.viscosity_index, materials/astm_d2270_LH.toml) — the same route the
  project took for mol-liton-00 (VI 100 -> 6.185 mm²/s at 40 mm²/s, reproduced in the tests);
* VI: mineral 100 — API 1509 Annex E puts API Group I/II base oils at 80 <= VI < 120, and 100 is the value
  the project already uses for its mineral estimates (mol-liton-00, seed001-oil-a/b); PAO 140 — API Group IV;
  PAO base stocks of 6-40 mm²/s at 100 °C have VI of about 135-150 (Rudnick & Shubkin, "Poly(alpha-olefins)",
  in Synthetic Lubricants and High-Performance Functional Fluids, 2nd ed., 1999, ch. 1); a single value per
  family, so low grades of a real PAO line sit lower (PAO 4: about 125) and high blends higher;
* rho15: mineral — log-linear in nu40 through the two mineral oils with published densities in the seeds
  (seed 004 Table 3: 864.6 kg/m³ at 36.6 mm²/s; seed 002 Table 1: base oil of MG1, 0.90 g/cm³ at 230 mm²/s),
  extrapolated outside them (VG 10: 840, VG 460: 913 kg/m³, inside the 820-920 kg/m³ of paraffinic to
  naphthenic base oils);
  PAO — 830 kg/m³, the PAO base oil of seed 002 (PG1, 47 mm²/s), for all grades (PAO 4-100 span about
  820-855 kg/m³);
* pressure-viscosity: Gold et al. (2001) alpha = s nu^t, s 9.90 / 7.38 1/GPa, t 0.14 / 0.13 for mineral /
  PAO (seed 002 Table 1), at the operating viscosity (thermobear.lubrication.lubricant.gold_alpha_p);
* thermal: Cragoe (1929) for the mineral oils (thermal = "cragoe"); for PAO, Cragoe's petroleum-oil fit
  does not apply and the constants of seed002-pg1 are used (k 0.145 W/(m K), cp 2150 J/(kg K), estimated).

Uncertainty of the estimated values (``uncertainty.<key>`` in each file, thermobear.schema.check_uncertainty):
an oil's nu40 within ISO 3448's ±10 % of the grade (any oil sold as the grade); nu100 between the viscosity indices the sources above give for the family (mineral: VI 80-120, API 1509
Annex E Groups I/II; PAO: VI 125-150, Rudnick & Shubkin 1999), each end by D2270 inverted as for the nominal;
rho15 of mineral grades +-25 kg/m³ about the anchor fit (paraffinic to naphthenic base oils of one grade),
of PAO 820-855 kg/m³ (the span of PAO 4-100 above); k and cp of PAO the typical ranges quoted per value;
a grease's base-oil nu40 the class range of its note; its temperature limits +-10 K (makers' limits of a class).

Greases "grease-<thickener>-<base oil>-vg<grade>-nlgi2": the base oil is the grade above (all film and
friction models use the base oil, as for the seed greases); thickener, NLGI class and temperature range
are labels (NLGI 2 in the description: the Lubricant loader has no key for it).

Run:  python validation/lubricant_grades.py
"""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from thermobear.lubrication.viscosity_index import nu100_from_vi as _nu100_from_vi, viscosity_index

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "materials" / "lubricants"
GRADES = (10, 15, 22, 32, 46, 68, 100, 150, 220, 320, 460)
VI = {"mineral": 100.0, "pao": 140.0}
VI_RANGE = {"mineral": (80.0, 120.0), "pao": (125.0, 150.0)}     # API 1509 Annex E Groups I/II; Rudnick & Shubkin 1999
GOLD = {"mineral": (9.90, 0.14), "pao": (7.38, 0.13)}
RHO_ANCHORS = ((36.6, 864.6), (230.0, 900.0))      # seed 004 Table 3; seed 002 Table 1 (MG1 base oil)
RHO_PAO = 830.0                                    # seed 002 Table 1 (PG1 base oil)


def nu100_from_vi(nu40, vi):
    """Kinematic viscosity at 100 °C [mm²/s] of an oil with nu40 [mm²/s] and viscosity index vi
    (thermobear.lubrication.viscosity_index: ASTM D2270 inverted), as a float."""
    return float(_nu100_from_vi(nu40, vi))


def rho15(family, nu40):
    """Density at 15 °C [kg/m³] (see the module docstring for the anchors)."""
    if family == "pao":
        return RHO_PAO
    (n1, r1), (n2, r2) = RHO_ANCHORS
    return r1 + (r2 - r1) * (np.log10(nu40) - np.log10(n1)) / (np.log10(n2) - np.log10(n1))


def oil_lines(grade, family, name=None, kind="oil", extra=()):
    nu100 = nu100_from_vi(float(grade), VI[family])
    s, t = GOLD[family]
    fam = "mineral" if family == "mineral" else "PAO"
    name = name or f"iso-vg-{grade}-{family}"
    rho = float(rho15(family, grade))
    lines = [f'name = "{name}"', f'kind = "{kind}"']
    lines += list(extra) or [f'description = "ISO VG {grade} {fam} oil (generic grade, VI {VI[family]:g}; '
                              f'validation/lubricant_grades.py)"']
    lines += [
        f'base_oil = "{fam}"',
        f"nu40_cSt = {float(grade)!r:<22s}# ISO 3448 grade ISO VG {grade} (mid-point, mm²/s at 40 °C)",
        f"nu100_cSt = {round(nu100, 3)!r:<21s}# ASTM D2270 inverted for VI {VI[family]:g} (validation/lubricant_grades.py)",
        f"rho15_kg_m3 = {round(rho, 1)!r:<19s}# estimated: " + (
            "log-linear in nu40 through seed 004 (864.6 at 36.6) and seed 002 MG1 (900 at 230)"
            if family == "mineral" else "seed 002 Table 1, PAO base oil of PG1 (0.83 g/cm³)"),
        f"gold_s_1_GPa = {s!r:<19s}# Gold et al. (2001) {fam} fit, seed 002 Table 1: alpha = s nu^t",
        f"gold_t = {t!r:<25s}# Gold et al. (2001), seed 002 Table 1",
    ]
    if family == "mineral":
        lines.append('thermal = "cragoe"                # k_th, cp from Cragoe (1929) petroleum-oil correlations with rho15')
    else:
        lines += ["k_W_mK = 0.145                    # estimated: typical PAO 0.14-0.15 W/(m K), as seed002-pg1",
                  "cp_J_kgK = 2150.0                 # estimated: typical PAO 2.1-2.2 kJ/(kg K), as seed002-pg1"]
    est = ["nu100_cSt", "rho15_kg_m3"] + ([] if family == "mineral" else ["k_W_mK", "cp_J_kgK"])
    lines.append("estimated = [" + ", ".join(f'"{e}"' for e in est) + "]")
    lines.append(f"# nu100_cSt: viscosity index {VI[family]:g} assumed for {fam} oils (API 1509 Annex E groups; "
                 "module docstring of validation/lubricant_grades.py).")
    lo_vi, hi_vi = VI_RANGE[family]
    if kind == "oil":                   # (a grease's base oil: the class range of its note, grease_lines)
        lines.append('uncertainty.nu40_cSt = { factor = [0.9, 1.1], source = "ISO 3448: an oil of the grade has a kinematic '
                     'viscosity at 40 °C within ±10 % of the grade\'s mid-point (any value in the class: uniform)" }')
    lines.append(f"uncertainty.nu100_cSt = {{ range = [{round(nu100_from_vi(float(grade), lo_vi), 3)!r}, "
                 f"{round(nu100_from_vi(float(grade), hi_vi), 3)!r}], source = \"ASTM D2270 inverted for VI {lo_vi:g}-"
                 f"{hi_vi:g}, the {fam} base-oil range (validation/lubricant_grades.py)\" }}")
    if family == "mineral":
        lines.append('uncertainty.rho15_kg_m3 = { offset = [-25.0, 25.0], source = "reasoning: paraffinic to naphthenic '
                     'base oils of one grade, 820-920 kg/m³ overall (validation/lubricant_grades.py)" }')
    else:
        lines += ['uncertainty.rho15_kg_m3 = { range = [820.0, 855.0], source = "PAO 4-100 base stocks span about '
                  '820-855 kg/m³ (validation/lubricant_grades.py)" }',
                  'uncertainty.k_W_mK = { range = [0.14, 0.15], source = "typical PAO 0.14-0.15 W/(m K), as '
                  'seed002-pg1" }',
                  'uncertainty.cp_J_kgK = { range = [2100.0, 2200.0], source = "typical PAO 2.1-2.2 kJ/(kg K), as '
                  'seed002-pg1" }']
    return lines, nu100


#: (name, thickener, family, grade, T_min, T_max, range note)
GREASES = [
    ("grease-lithium-mineral-vg100-nlgi2", "lithium soap (12-hydroxystearate)", "mineral", 100, -30, 120,
     "general-purpose bearing grease; base oils of this class 90-150 mm²/s at 40 °C"),
    ("grease-lithium-complex-mineral-vg150-nlgi2", "lithium complex soap", "mineral", 150, -30, 150,
     "higher-temperature bearing grease; base oils of this class 100-220 mm²/s at 40 °C"),
    ("grease-polyurea-mineral-vg100-nlgi2", "polyurea", "mineral", 100, -40, 150,
     "electric-motor bearing grease; base oils of this class 70-120 mm²/s at 40 °C"),
    ("grease-lithium-pao-vg22-nlgi2", "lithium soap", "pao", 22, -50, 110,
     "low-temperature / high-speed bearing grease; PAO base oils of this class 15-32 mm²/s at 40 °C"),
]


#: base-oil nu40 range of each grease class [mm²/s] (the notes above)
CLASS_NU40 = {"grease-lithium-mineral-vg100-nlgi2": (90.0, 150.0), "grease-lithium-complex-mineral-vg150-nlgi2":
              (100.0, 220.0), "grease-polyurea-mineral-vg100-nlgi2": (70.0, 120.0),
              "grease-lithium-pao-vg22-nlgi2": (15.0, 32.0)}


def grease_lines(name, thickener, family, grade, tmin, tmax, note):
    fam = "mineral" if family == "mineral" else "PAO"
    extra = [f'description = "Generic {thickener} grease, NLGI 2, {fam} base oil ISO VG {grade} (estimated class '
             f'values, validation/lubricant_grades.py)"',
             f'thickener = "{thickener}"          # label; the models use the base oil']
    lines, nu100 = oil_lines(grade, family, name=name, kind="grease", extra=extra)
    i = next(k for k, ln in enumerate(lines) if ln.startswith("estimated"))
    lines[i:i] = [f"grease_T_min_C = {tmin:<16d}# estimated: usual lower limit of this grease class",
                  f"grease_T_max_C = {tmax:<16d}# estimated: usual upper limit of this grease class"]
    lines[i + 2] = lines[i + 2].replace("]", ', "nu40_cSt", "grease_T_min_C", "grease_T_max_C"]')
    lines += [f"# nu40_cSt: estimated, {note}; NLGI 2 (265-295 worked penetration, the usual bearing",
              "#   consistency) is stated in the description only (no loader key for it)."]
    lo, hi = CLASS_NU40[name]
    lines += [f'uncertainty.nu40_cSt = {{ range = [{lo!r}, {hi!r}], source = "base oils of this grease class '
              f'{lo:g}-{hi:g} mm²/s at 40 °C (note above)" }}',
              'uncertainty.grease_T_min_C = { offset = [-10.0, 10.0], source = "reasoning: makers\' limits of one grease '
              'class differ by about 10 K" }',
              'uncertainty.grease_T_max_C = { offset = [-10.0, 10.0], source = "reasoning: makers\' limits of one grease '
              'class differ by about 10 K" }']
    return lines, nu100


def main() -> int:
    rows = []
    for family in ("mineral", "pao"):
        for g in GRADES:
            lines, nu100 = oil_lines(g, family)
            head = [f"# ISO VG {g} {('mineral' if family == 'mineral' else 'PAO')} oil: generic grade written by "
                    "validation/lubricant_grades.py (sources in its docstring and per value)."]
            (OUT / f"iso-vg-{g}-{family}.toml").write_text("\n".join(head + lines) + "\n", encoding="utf-8")
            rows.append((f"iso-vg-{g}-{family}", g, nu100, viscosity_index(g, nu100), rho15(family, g)))
    for args in GREASES:
        lines, nu100 = grease_lines(*args)
        head = [f"# {args[0]}: generic grease written by validation/lubricant_grades.py (estimated class values)."]
        (OUT / f"{args[0]}.toml").write_text("\n".join(head + lines) + "\n", encoding="utf-8")
        rows.append((args[0], args[3], nu100, viscosity_index(args[3], nu100), rho15(args[2], args[3])))
    print(f"{'name':45s} {'nu40':>6s} {'nu100':>8s} {'VI':>6s} {'rho15':>6s}")
    for r in rows:
        print(f"{r[0]:45s} {r[1]:6g} {r[2]:8.3f} {r[3]:6.1f} {r[4]:6.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
