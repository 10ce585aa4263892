"""Catalogue of the common ball bearing series: boundary dimensions -> estimated internal geometry ->
ISO 281 / ISO 76 load ratings.  Writes materials/bearings/<series>.toml and validation/report/catalogue.md.

Series: deep groove 618, 619, 160, 60, 62, 63; angular contact 72 B, 73 B (40°); spindle 70 C/E, 719 C/E
(15°/25°); thrust 511, 512, 513; bores 10-100 mm.  Boundary dimensions: validation/data/
iso_dimension_series.toml (ISO 15 / ISO 104 dimension plans, source per table).

Internal geometry: ONE method, the deep groove ball bearing design method of the Chinese bearing-design
practice (GB/T 273.3 = ISO 15 boundary dimensions), as published in "深沟球轴承设计方法" (deep groove
ball bearing design method), https://xiaomilidoc.com/p-10044630.html:
  §2.1  ball diameter Dw = Kw (D - d), Kw from its Table 1 by diameter series and bore (middle of the
        range used here), then the nearest standard ball;
  §2.2  pitch diameter dm = P = 0.5 (D + d);
  §2.3  ball number from the filling angle psi = 2 (Z - 1) asin(Dw/dm): here the largest Z whose psi does
        not exceed the §2.6 limit (195° diameter series 8, 9, 0; 194° series 2; 193° series 3), and, where
        that psi falls below the §2.6 minimum of 180°, dm enlarged (§2.5.4: at most to 1.03 P) so that one
        more ball fits at the limit;
  §3.1-3.2 groove radii Ri = 0.515 Dw, Re = 0.525 Dw (fi = 0.515, fo = 0.525).
Deviations, stated: (a) standard balls are taken from the inch series in 1/64 in steps (the balls of the
makers' bearings compared in the report: 5/16, 17/64, 29/64, 1/2 in), not the method's metric-first list;
(b) the method covers Conrad-assembled deep groove bearings only.  Angular contact and spindle bearings
(counterbored outer ring, no filling-angle limit) keep the method's ball size and pitch diameter and take
Z = round(pi dm / (1.2 Dw)) (ball pitch 1.2 Dw, the estimate already used for the seed thrust bearings in
materials/bearings.toml; no published rule found); thrust bearings take dm = (d + D)/2, Dw = nearest
1/64 in ball to 0.72 (D - d)/2 (the ratio of the one thrust bearing with a published ball size, the 51205
of seed 000, which therefore is no independent check), fi = fo = 0.53 (seed 000) and the same Z rule.
Radial clearance of the deep groove bearings: ISO 5753-1 group CN (mid value at load time).
C and C0 are computed from that geometry with thermobear.rating (ISO 281:2007, ISO 76:2006).

Run:  python validation/catalogue.py
"""
from __future__ import annotations

import math
import sys
import tomllib
from pathlib import Path

import numpy as np

from _common import write_report

from thermobear.contact.geometry import BallBearing, bearing, bearing_from_dict
from thermobear.rating.life import load_ratings

ROOT = Path(__file__).resolve().parents[1]
DIMENSIONS = Path(__file__).resolve().parent / "data" / "iso_dimension_series.toml"
OUT_DIR = ROOT / "materials" / "bearings"
METHOD_URL = "https://xiaomilidoc.com/p-10044630.html"
INCH = 25.4

#: Kw ranges of the method's Table 1, by diameter series group and bore (d <= 35, 35 < d <= 120, d > 120 mm).
KW = {"890": [(0.24, 0.31), (0.25, 0.32), (0.24, 0.30)],
      "2": [(0.29, 0.31), (0.31, 0.32), (0.26, 0.31)],
      "3": [(0.28, 0.32), (0.32, 0.32), (0.29, 0.31)]}
#: Maximum filling angle of the method's §2.6 [deg] by diameter series group.
PSI_MAX = {"890": 195.0, "2": 194.0, "3": 193.0}
PITCH_PER_BALL = 1.2          # ball pitch / Dw for counterbored angular contact and thrust bearings
THRUST_BALL_FRACTION = 0.72   # Dw / ((D - d)/2): 51205 of seed 000 (7.938 / 11)

#: series -> (kind, dimension series, diameter-series group, contact angle [deg], suffix)
SERIES = {
    "618": ("deep_groove", "18", "890", None, ""), "619": ("deep_groove", "19", "890", None, ""),
    "160": ("deep_groove", "00", "890", None, ""), "60": ("deep_groove", "10", "890", None, ""),
    "62": ("deep_groove", "02", "2", None, ""), "63": ("deep_groove", "03", "3", None, ""),
    "72B": ("angular_contact", "02", "2", 40.0, "B"), "73B": ("angular_contact", "03", "3", 40.0, "B"),
    "70C": ("angular_contact", "10", "890", 15.0, "C"), "70E": ("angular_contact", "10", "890", 25.0, "E"),
    "719C": ("angular_contact", "19", "890", 15.0, "C"), "719E": ("angular_contact", "19", "890", 25.0, "E"),
    "511": ("thrust", "11", None, 90.0, ""), "512": ("thrust", "12", None, 90.0, ""),
    "513": ("thrust", "13", None, 90.0, ""),
}


def designation(series: str, d: float) -> str:
    """ISO 15 / ISO 104 designation: series digits + bore code (+ contact-angle suffix)."""
    code = {10: "00", 12: "01", 15: "02", 17: "03"}.get(int(d), f"{int(d) // 5:02d}")
    digits = series.rstrip("BCE")
    return f"{digits}{code}{SERIES[series][4]}"


def nearest_ball(x_mm: float) -> float:
    """Nearest ball of the inch series in 1/64 in steps [mm]."""
    return round(round(x_mm / (INCH / 64)) * INCH / 64, 4)


def kw_range(group: str, d_mm: float) -> tuple[float, float]:
    row = 0 if d_mm <= 35 else (1 if d_mm <= 120 else 2)
    return KW[group][row]


def deep_groove_geometry(d, D, group):
    """The method for a Conrad deep groove bearing: Dw, dm, Z, filling angle and the notes."""
    lo, hi = kw_range(group, d)
    kw = 0.5 * (lo + hi)
    Dw = nearest_ball(kw * (D - d))
    P = 0.5 * (D + d)
    half = np.degrees(np.arcsin(Dw / P))
    Z = int(np.floor(PSI_MAX[group] / (2.0 * half))) + 1
    dm, note = P, f"largest Z with 2(Z-1) asin(Dw/dm) <= {PSI_MAX[group]:g} deg"
    if 2 * (Z - 1) * half < 180.0:                                   # §2.5.4: enlarge dm by up to 3 %
        dm_fit = Dw / np.sin(np.radians(PSI_MAX[group] / (2.0 * Z)))
        if dm_fit <= 1.03 * P:
            dm, Z = round(float(dm_fit), 3), Z + 1
            note = (f"filling angle < 180 deg at P = {P:g} mm: dm enlarged to fit Z at "
                    f"{PSI_MAX[group]:g} deg (method 2.5.4, <= 1.03 P)")
    psi = 2 * (Z - 1) * np.degrees(np.arcsin(Dw / dm))
    return dict(D_mm=Dw, dm_mm=dm, Z=Z, fi=0.515, fo=0.525), dict(kw=kw, psi=psi, z_note=note)


def angular_geometry(d, D, group):
    """Angular contact / spindle: the method's ball and pitch diameter, Z from a ball pitch of 1.2 Dw."""
    lo, hi = kw_range(group, d)
    kw = 0.5 * (lo + hi)
    Dw = nearest_ball(kw * (D - d))
    dm = 0.5 * (D + d)
    Z = int(round(np.pi * dm / (PITCH_PER_BALL * Dw)))
    return dict(D_mm=Dw, dm_mm=dm, Z=Z, fi=0.515, fo=0.525), dict(kw=kw, psi=None, z_note="Z = round(pi dm / (1.2 Dw))")


def thrust_geometry(d, D):
    Dw = nearest_ball(THRUST_BALL_FRACTION * 0.5 * (D - d))
    dm = 0.5 * (D + d)
    Z = int(round(np.pi * dm / (PITCH_PER_BALL * Dw)))
    return dict(D_mm=Dw, dm_mm=dm, Z=Z, fi=0.53, fo=0.53), dict(kw=None, psi=None, z_note="Z = round(pi dm / (1.2 Dw))")


def estimate(series: str, d, D, B) -> tuple[dict, dict]:
    """Catalogue entry (unit-suffixed keys) and the notes of one bearing of a series."""
    kind, plan, group, alpha, _ = SERIES[series]
    if kind == "deep_groove":
        geo, info = deep_groove_geometry(d, D, group)
    elif kind == "angular_contact":
        geo, info = angular_geometry(d, D, group)
    else:
        geo, info = thrust_geometry(d, D)
    e = dict(kind=kind, series=series, bore_mm=float(d), outer_diameter_mm=float(D), width_mm=float(B), **geo)
    if kind == "deep_groove":
        e["clearance_group"] = "CN"
    else:
        e["alpha0_deg"] = alpha
    brg = bearing_from_dict(e, name=designation(series, d))
    C, C0 = load_ratings(brg)
    e["C_kN"], e["C0_kN"] = round(C / 1e3, 3), round(C0 / 1e3, 3)
    info.update(plan=plan, brg=brg)
    return e, info


def _fmt(v):
    if isinstance(v, str):
        return f'"{v}"'
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_fmt(x) for x in v) + "]"
    if isinstance(v, float):
        return repr(round(v, 6))
    return str(v)


def uncertainty_lines(e: dict, kind: str) -> list[str]:
    """The ranges of the estimated internal geometry (thermobear.schema.check_uncertainty), each bounded
    by what still fits: balls of D on dm need D <= dm sin(pi/Z)."""
    D, dm, Z = e["D_mm"], e["dm_mm"], e["Z"]
    step = 25.4 / 64.0
    fit = lambda z: dm * math.sin(math.pi / z)  # noqa: E731
    hi_D = min(D + step, math.floor(fit(Z) * 1e4) / 1e4)
    hi_Z = Z + 1 if D <= fit(Z + 1) else Z
    osc = ((0.52, 0.54, "thrust grooves of 0.52-0.54 D about the 0.53 of the 51205 (seed 000)"),) * 2 if kind == "thrust" \
        else ((0.51, 0.52, "inner grooves 0.51-0.52 D about the method's 0.515 (method 3.1)"),
              (0.52, 0.53, "outer grooves 0.52-0.53 D about the method's 0.525 (method 3.2)"))
    return [f'uncertainty.D_mm = {{ range = [{round(D - step, 4)!r}, {round(hi_D, 4)!r}], source = "reasoning: the next '
            f'1/64 in ball either side of the nearest to Kw (D - d), at most what fits on dm" }}',
            f'uncertainty.dm_mm = {{ factor = [0.99, 1.01], source = "reasoning: makers place the pitch circle within '
            f'about 1 % of (d + D)/2" }}',
            f'uncertainty.Z = {{ range = [{Z - 1}, {hi_Z}], source = "reasoning: one ball either way of the 1.2 Dw '
            f'spacing rule, as many as fit (draws that do not fit together are refused, counted as failed samples)" }}',
            f'uncertainty.fi = {{ range = [{osc[0][0]}, {osc[0][1]}], source = "reasoning: {osc[0][2]}" }}',
            f'uncertainty.fo = {{ range = [{osc[1][0]}, {osc[1][1]}], source = "reasoning: {osc[1][2]}" }}']


def toml_entry(name: str, e: dict, info: dict, plan_src: str) -> list[str]:
    kind = e["kind"]
    std = "ISO 104" if kind == "thrust" else "ISO 15"
    what = {"deep_groove": "Deep groove ball bearing", "angular_contact": f"Angular contact ball bearing, "
            f"{e.get('alpha0_deg', 0):g}°", "thrust": "Thrust ball bearing"}[kind]
    src = {
        "bore_mm": f"{std} dimension series {info['plan']}", "outer_diameter_mm": f"{std} dimension series {info['plan']}",
        "width_mm": f"{std} dimension series {info['plan']}" + (" (height H)" if kind == "thrust" else ""),
        "D_mm": ("estimated: nearest 1/64 in ball to " + (f"Kw (D - d), Kw {info['kw']:.3f}" if info["kw"]
                 else f"{THRUST_BALL_FRACTION} (D - d)/2")),
        "dm_mm": "estimated: " + ("(d + D)/2" if abs(e["dm_mm"] - 0.5 * (e["bore_mm"] + e["outer_diameter_mm"])) < 1e-9
                                  else "enlarged, method 2.5.4"),
        "Z": "estimated: " + info["z_note"] + (f" (filling angle {info['psi']:.1f} deg)" if info["psi"] else ""),
        "fi": "estimated: " + ("Ri = 0.515 Dw (method 3.1)" if kind != "thrust" else "as the 51205 of seed 000"),
        "fo": "estimated: " + ("Re = 0.525 Dw (method 3.2)" if kind != "thrust" else "as the 51205 of seed 000"),
        "alpha0_deg": "nominal contact angle of the series" + (" (suffix B 40°, C 15°, E 25°)" if kind != "thrust" else ""),
        "clearance_group": "ISO 5753-1 normal group; Pd = mid of its range for the bore",
        "C_kN": "computed: ISO 281:2007 from this geometry (thermobear.rating)",
        "C0_kN": "computed: ISO 76:2006 from this geometry (thermobear.rating)",
    }
    lines = [f'["{name}"]', f'description = "{what} {name} (boundary dimensions {std}; internal geometry '
             f'estimated, validation/catalogue.py)"']
    for k in ("kind", "series", "bore_mm", "outer_diameter_mm", "width_mm", "D_mm", "dm_mm", "Z", "fi", "fo",
              "alpha0_deg", "clearance_group", "C_kN", "C0_kN"):
        if k in e:
            line = f"{k} = {_fmt(e[k])}"
            lines.append(f"{line:<32s}# {src[k]}" if k in src else line)
    lines.append('estimated = ["D_mm", "dm_mm", "Z", "fi", "fo"]')
    lines += uncertainty_lines(e, kind)
    how = (f"{METHOD_URL}" if kind == "deep_groove" else f"ball size and dm after {METHOD_URL}, Z and "
           + ("thrust ball fraction" if kind == "thrust" else "no filling-angle limit") + ": stated extension")
    lines.append(f'source = "dimensions: {plan_src}; internal geometry: {how} (validation/catalogue.py)"')
    return lines + [""]


def build() -> dict:
    """All series: {series: [(name, entry, info)]}, seed designations left out (kept from bearings.toml)."""
    plans = tomllib.loads(DIMENSIONS.read_text(encoding="utf-8"))
    seeds = tomllib.loads((ROOT / "materials" / "bearings.toml").read_text(encoding="utf-8"))
    taken = set(seeds) | {a for s in seeds.values() for a in s.get("aliases", ())}
    out = {}
    for series, (kind, plan, *_rest) in SERIES.items():
        rows = []
        for d, D, B in plans[plan]["rows"]:
            name = designation(series, d)
            e, info = estimate(series, d, D, B)
            rows.append((name, e, info, name in taken))
        out[series] = (plans[plan]["source"], rows)
    return out


def write_files(cat: dict) -> int:
    OUT_DIR.mkdir(parents=True, exist_ok=True)
    n = 0
    for series, (src, rows) in cat.items():
        head = [f"# Series {series}: generated by validation/catalogue.py — do not edit by hand; rerun the script.",
                "# Units in the keys (mm, deg, kN); every value names its source; estimated values are listed in",
                "# `estimated` (method and reasoning: validation/catalogue.py docstring, validation/report/catalogue.md).",
                f"# Boundary dimensions: {src}.", ""]
        body = []
        for name, e, info, seed in rows:
            if seed:
                body += [f"# {name}: the seed bearing of materials/bearings.toml (published data) is used instead.", ""]
                continue
            body += toml_entry(name, e, info, src)
            n += 1
        (OUT_DIR / f"{series}.toml").write_text("\n".join(head + body).rstrip() + "\n", encoding="utf-8")
    return n


# ---- comparison with public internal geometries and with makers' ratings -------------------------------
#: (designation, Z, D [mm] or None, dm [mm] or None, alpha [deg], source)
PUBLIC_GEOMETRY = [
    ("6203", 8, 6.746, 28.50, 0.0, "CWRU Bearing Data Center, fan-end SKF 6203-2RS JEM (0.2656 in, 1.122 in; "
     "D/dm = 0.2366 as its cage frequency 0.3817)"),
    ("6205", 9, 7.940, 39.04, 0.0, "CWRU Bearing Data Center, drive-end SKF 6205-2RS JEM (0.3126 in, 1.537 in; "
     "D/dm = 0.2034 as its cage frequency 0.39828)"),
    ("6209", 9, 12.7, 65.0, 0.0, "Harris (2001) 209 example bearing, as recalled in tests/test_geometry.py"),
    ("6210", 10, None, 70.0, 0.0, "seed 004 (Darul et al. 2024) Table 1: Z, dm"),
    ("6305", 7, 11.5, 43.5, 0.0, "ISO/TS 16281 example bearing (a 6305: minzhun/ISO16281 Test_BallBearing.py)"),
    ("7210B", 15, None, 70.0, 40.0, "seed 004 Table 1: Z, dm, 40°"),
    ("7218B", 16, 22.23, 125.3, 40.0, "Harris (2001) 218 example, as recalled in validation/highspeed_218.py"),
    ("71910E", 25, 6.35, 62.11, 25.0, "SKF 71910 ACD as quoted in EOSCogniton/Ressources2020 S71910_ISO281.py "
     "(Dw 6.35, (D2 + d2)/2 = 62.11 mm; secondary source)"),
    ("51205", None, 7.938, 36.0, 90.0, "seed 000 §3: D, dm (its D set the thrust ball fraction: not independent)"),
]
#: (designation, C [kN], C0 [kN], maker / source)
MAKER_RATINGS = [
    ("61800", 1.72, 0.83, "SKF (gumyr/bd_warehouse single_row_deep_groove_ball_bearing_parameters.csv)"),
    ("61900", 2.7, 1.27, "SKF (bd_warehouse CSV)"),
    ("6000", 4.75, 1.96, "SKF (bd_warehouse CSV)"),
    ("6200", 5.4, 2.36, "SKF (bd_warehouse CSV)"),
    ("6300", 8.52, 3.4, "SKF (bd_warehouse CSV)"),
    ("6203", 9.55, 4.8, "Japanese maker table, gist nagae/8756dc2de16082219e1ae6a80a73dfb3"),
    ("6204", 12.8, 6.6, "Japanese maker table (gist nagae)"),
    ("6205", 14.0, 7.85, "Japanese maker table (gist nagae)"),
    ("6206", 19.5, 11.3, "Japanese maker table (gist nagae)"),
    ("6305", 23.4, None, "ISO/TS 16281 example set (minzhun/ISO16281: C = 23 400 N for the 6305)"),
    ("6210", None, 23.2, "SKF, as stored for the seed 6210 in materials/bearings.toml"),
    ("7200B", 7.02, 3.35, "SKF 7200 BECBP (bd_warehouse single_row_angular_contact_ball_bearing_parameters.csv)"),
    ("7202B", 8.8, 4.65, "SKF 7202 BECBP (bd_warehouse CSV)"),
    ("7203B", 11.0, 5.85, "SKF 7203 BECBM (bd_warehouse CSV)"),
    ("7303B", 15.9, 8.3, "SKF 7303 BECBP (bd_warehouse CSV)"),
    ("7304B", 19.0, 10.0, "SKF 7304 BECBPH (bd_warehouse CSV)"),
    ("7305B", 26.5, 15.3, "SKF 7305 BECBPH (bd_warehouse CSV)"),
]


def _pct(a, b):
    return f"{(a / b - 1) * 100:+.1f} %"


def report(cat: dict, n_written: int) -> list[str]:
    est = {name: (e, info) for _s, (_src, rows) in cat.items() for name, e, info, _seed in rows}
    L = ["# Catalogue of the common ball bearing series: estimated internal geometry and ISO ratings", "",
         "Generated by `validation/catalogue.py`; writes `materials/bearings/<series>.toml` "
         f"({n_written} bearings; the seed bearings of `materials/bearings.toml` are kept where a designation "
         "coincides: 6210, 7210 (= 7210B), 51107, 51205).", "",
         "## Method", "",
         f"One published method: the deep groove ball bearing design method ({METHOD_URL}): Dw = Kw (D − d) with "
         "the middle of its Kw range (Table 1), the nearest standard ball; dm = (d + D)/2; the largest Z whose "
         "filling angle 2 (Z − 1) asin(Dw/dm) stays within its limit (195° diameter series 8/9/0, 194° series 2, "
         "193° series 3), dm enlarged by at most 3 % when the filling angle would fall below 180°; fi = 0.515, "
         "fo = 0.525.  Stated deviations: balls from the 1/64 in series; angular contact, spindle and thrust "
         "bearings (no filling-angle limit) take Z = round(π dm / (1.2 Dw)); thrust balls 0.72 (D − d)/2 (from the "
         "51205) and fi = fo = 0.53 (seed 000).  C, C0 from this geometry by ISO 281:2007 and ISO 76:2006 "
         "(`thermobear.rating`), not copied from a maker.", "",
         "## Estimated against public internal geometries", "",
         "| bearing | Z est / pub | D est / pub [mm] | dm est / pub [mm] | C(est) / C(pub geometry) | "
         "C0(est) / C0(pub geometry) | source |", "|---|---|---|---|---|---|---|"]
    errs = []
    for name, Z, Dp, dmp, a, src in PUBLIC_GEOMETRY:
        e, info = est[name]
        b = info["brg"]
        Zp = Z if Z is not None else b.Z
        Dq = Dp if Dp is not None else e["D_mm"]
        pub = BallBearing(D=Dq * 1e-3, dm=dmp * 1e-3, Z=Zp, fi=b.fi, fo=b.fo, kind=b.kind,
                          alpha0=None if b.kind == "deep_groove" else np.deg2rad(a))
        (C, C0), (Cp, C0p) = load_ratings(b), load_ratings(pub)
        z = f"{b.Z} / {Z}" if Z is not None else f"{b.Z} / –"
        dd = f"{e['D_mm']:.3f} / {Dp:.3f}" if Dp is not None else f"{e['D_mm']:.3f} / –"
        L.append(f"| {name} | {z} | {dd} | {e['dm_mm']:.2f} / {dmp:.2f} | {_pct(C, Cp)} | {_pct(C0, C0p)} | {src} |")
        if Z is not None:
            errs.append(b.Z - Z)
    low = [f"{n} ({i['psi']:.0f}°)" for n, (e, i) in est.items() if i["psi"] is not None and i["psi"] < 180.0]
    L += ["", "C(pub geometry) uses the published Z, D, dm with the estimate filling any value not published "
          "(marked –) and the method's osculations, so the columns isolate the geometry estimate.  Ball-count "
          f"errors: {', '.join(f'{x:+d}' for x in errs)}.", "",
          "Deep groove bearings whose filling angle stays below the method's 180° minimum (one more ball would "
          "need dm larger than the method's 1.03 P; kept with the smaller Z, which underestimates C by about "
          f"(Z/(Z+1))^(2/3)): {', '.join(low) if low else 'none'}.", "",
          "## Computed ratings against makers' published ratings (sanity check, not adjusted)", "",
          "| bearing | C est [kN] | C maker [kN] | diff | C0 est [kN] | C0 maker [kN] | diff | maker, source |",
          "|---|---|---|---|---|---|---|---|"]
    for name, Cm, C0m, src in MAKER_RATINGS:
        b = bearing(name)
        C, C0 = load_ratings(b)
        L.append(f"| {name} | {C / 1e3:.2f} | {Cm if Cm else '–'} | {_pct(C / 1e3, Cm) if Cm else '–'} | "
                 f"{C0 / 1e3:.2f} | {C0m if C0m else '–'} | {_pct(C0 / 1e3, C0m) if C0m else '–'} | {src} |")
    L += ["", "Makers' deep groove ratings carry their own rating factors (e.g. SKF's for its Explorer class), "
          "so a few per cent either way is expected even for an exact geometry; 6210 and 7210 are the seed "
          "bearings (Z, dm of seed 004, D 12.7 mm estimated).", ""]
    return L


def main() -> int:
    cat = build()
    n = write_files(cat)
    lines = report(cat, n)
    write_report("catalogue.md", lines)
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
