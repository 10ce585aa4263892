"""Regenerate ``validation/report/``: every validation script, the fidelity levels, the charts.

Run from the repository root (a fresh clone with thermobear installed)::

    python validation/run_all.py [--no-bench] [--ref-python PYTHON]

1. runs every other ``validation/*.py`` script as a subprocess (the seed reproductions write their
   own ``report/*.md``; the output of the others is kept in report.md), two at a time;
2. scores the fidelity levels L0–L4 (:mod:`fidelity`) and draws ``report/speed_accuracy.png``
   (error against runtime per operating point, log scales, one point per level and case family);
3. runs the stability maps (:mod:`stability`) → ``report/stability_map.png``;
4. runs the benchmark suite (:mod:`bench_all`);
5. writes ``report/report.md`` with the key numbers and links.

Nothing here is asserted: the tests are in ``tests/``.  Target: well under 10 minutes on 2 cores.
"""
from __future__ import annotations

import os
import subprocess
import sys
import time
import warnings
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
REPORT = HERE / "report"
sys.path.insert(0, str(HERE))
OWN = {"run_all.py", "fidelity.py", "stability.py", "bench_all.py", "bench_uncertainty.py",
       "air_table.py"}        # air_table.py regenerates a data file from CoolProp: run it by hand
LEVEL_COLORS = {"L0": "#1f77b4", "L0-cal": "#17becf", "L1": "#ff7f0e", "L2": "#2ca02c", "L3": "#d62728",
                "L4": "#9467bd"}
FAMILY_MARKERS = {"seed001 torque": "o", "seed002 torque": "s", "seed002 temperature": "D",
                  "seed004 P ratio": "^", "seed004 IR temperature": "v"}


TIMED = {"bench_loads.py", "film_criterion.py", "seed004_film_whatif.py"}   # they time things: run alone, after
# the rest (timings taken on a busy machine mislead)


def run_scripts(timeout_s=600, timed=False, workers=2):
    scripts = sorted(p for p in HERE.glob("*.py") if p.name not in OWN and not p.name.startswith("_")
                     and (p.name in TIMED) == timed)
    env = dict(os.environ, MPLBACKEND="Agg")

    def one(p):
        t0 = time.perf_counter()
        try:
            r = subprocess.run([sys.executable, str(p)], cwd=HERE.parent, capture_output=True, text=True,
                               timeout=timeout_s, env=env)
            code, out, err = r.returncode, r.stdout, r.stderr
        except subprocess.TimeoutExpired:
            code, out, err = "timeout", "", f"timed out after {timeout_s} s"
        return p.name, code, time.perf_counter() - t0, out, err

    with ThreadPoolExecutor(max_workers=workers) as ex:
        return list(ex.map(one, scripts))


def speed_accuracy_chart(scores, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(10, 6.5))
    for s in scores:
        if not s.errors or not np.isfinite(s.t_batch_s):
            continue
        c, m = LEVEL_COLORS.get(s.level, "k"), FAMILY_MARKERS.get(s.family, "x")
        ax.scatter(s.t_batch_s, 100 * s.rms, c=c, marker=m, s=80, edgecolors="k")
        if np.isfinite(s.t_single_s) and abs(s.t_single_s / s.t_batch_s - 1) > 0.1:
            ax.scatter(s.t_single_s, 100 * s.rms, facecolors="none", edgecolors=c, marker=m, s=80)
            ax.plot([s.t_batch_s, s.t_single_s], [100 * s.rms] * 2, c=c, lw=0.6, ls=":")
        ax.annotate(s.level, (s.t_batch_s, 100 * s.rms), fontsize=7, xytext=(4, 3), textcoords="offset points")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("runtime per operating point [s] (filled: batched; hollow: one point per call)")
    ax.set_ylabel("RMS relative error against measurements [%]")
    ax.set_title("thermobear fidelity levels: accuracy against speed")
    h = [plt.Line2D([], [], ls="", marker="o", c=c, label=l) for l, c in LEVEL_COLORS.items()]
    h += [plt.Line2D([], [], ls="", marker=m, c="gray", label=f) for f, m in FAMILY_MARKERS.items()]
    ax.legend(handles=h, fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def main(argv=()):
    t_start = time.perf_counter()
    REPORT.mkdir(parents=True, exist_ok=True)
    warnings.simplefilter("ignore")
    import fidelity
    import stability
    import bench_all

    with ThreadPoolExecutor(max_workers=1) as bg:       # scripts in subprocesses while we score here
        fut = bg.submit(run_scripts)
        t0 = time.perf_counter()
        with np.errstate(all="ignore"):
            scores = fidelity.score_all()
        t_fid = time.perf_counter() - t0
        speed_accuracy_chart(scores, REPORT / "speed_accuracy.png")
        scripts = fut.result()
    scripts = sorted(scripts + run_scripts(timed=True, workers=1))      # the benchmark scripts alone
    t0 = time.perf_counter()
    stab = stability.run(REPORT / "stability_map.png", processes=2)
    t_stab = time.perf_counter() - t0
    t0 = time.perf_counter()
    bench = "(skipped: --no-bench)" if "--no-bench" in argv else bench_all.run(
        ref_python=argv[argv.index("--ref-python") + 1] if "--ref-python" in argv else None)
    t_bench = time.perf_counter() - t0

    by = {(s.level, s.family): s for s in scores}
    L = []
    w = L.append
    w("# thermobear validation report\n")
    w(f"Generated by `python validation/run_all.py` ({time.strftime('%Y-%m-%d %H:%M')}, "
      f"{os.cpu_count()} cores, Python {sys.version.split()[0]}). Do not edit: regenerate.\n")
    w("## Seed reproductions and other validation scripts\n")
    w("| script | exit | time [s] | report |")
    w("|---|---|---|---|")
    for name, code, dt, out, err in scripts:
        md = REPORT / (Path(name).stem + ".md")
        link = f"[{md.name}]({md.name})" if md.exists() else "output below"
        w(f"| `{name}` | {code} | {dt:.1f} | {link} |")
    for name, code, dt, out, err in scripts:
        md = REPORT / (Path(name).stem + ".md")
        if code != 0 or not md.exists():
            tail = (out.strip().splitlines() or [""])[-15:] if code == 0 else (err.strip().splitlines() or [""])[-15:]
            w(f"\n<details><summary><code>{name}</code> (exit {code})</summary>\n\n```\n" + "\n".join(tail)
              + "\n```\n</details>")
    w("\n## Speed against accuracy: fidelity levels\n")
    w("![speed vs accuracy](speed_accuracy.png)\n")
    for lv, info in fidelity.LEVEL_INFO.items():
        w(f"* **{lv}** — {info}")
    w("\nEvery level is run on the same scenes and scored against every measured reference "
      "(`validation/fidelity.py` docstring lists them).  No level is tuned to a reference it is scored "
      "on: L0-cal backs R1, S1 out of seed 002 MG1 at 1000 rpm and is scored on the other 6 cases.\n")
    w(fidelity.table(scores))
    w("\n### Reading the chart\n")

    def rms(lv, fam):
        s = by.get((lv, fam))
        return f"{100 * s.rms:.0f} %" if s and s.errors else "n/a"
    def t(lv, fam):
        x = by.get((lv, fam))
        return x.t_batch_s if x and x.errors else float("nan")
    s1 = [lv for lv in ("L1", "L2", "L3", "L4") if (lv, "seed001 torque") in by]
    w("* Seed 001 (3-ball rig, mW losses): " + ", ".join(f"{lv} {rms(lv, 'seed001 torque')}" for lv in s1)
      + f" at {t('L2', 'seed001 torque') * 1e3:.2g} ms (L2) to {t('L3', 'seed001 torque') * 1e3:.2g} ms (L3) per "
      "point: the symmetric thrust load needs no Jones–Harris and the rig no thermal network, so the "
      "higher levels cost more for the same number.  The model is low at low speed (see "
      "seed001_spin_down.md: Λ 0.3–0.6 in Table 1, asperity contact the rolling model does not contain).")
    w(f"* Seed 002 (51107, 7000 N, grease): SKF with catalogue constants {rms('L0', 'seed002 torque')}, with "
      f"R1, S1 from one grease {rms('L0-cal', 'seed002 torque')} on the 6 held-out cases; local model at the "
      f"measured temperature {rms('L2', 'seed002 torque')} (the 51107's D, Z, f are estimated and grease is "
      f"modelled as its base oil); coupled levels: torque {rms('L3', 'seed002 torque')}, temperature rise "
      f"{rms('L3', 'seed002 temperature')} (network of the rig estimated: housing, fans and ambient are not "
      "published).")
    ir = by.get(("L3", "seed004 IR temperature"))
    ratio = ", ".join(f"{e[0].split(', ')[-1]}: {e[1]:.0f} K vs {e[2]:.0f} K" for e in ir.errors) if ir else "n/a"
    l4 = [x for x in scores if x.level == "L4" and x.family.startswith("seed004")]
    l4txt = "; ".join(f"{x.family}: {rms('L4', x.family)}" + (f" ({len(x.failed)} failed)" if x.failed else "")
                      for x in l4)
    w(f"* Seed 004 (7210, oil jet): P(6500)/P(3200) at equal temperature (measured ≈ 3; L0–L2 at a uniform T, "
      f"L3–L4 with both rings imposed, balls from the network): L0 {rms('L0', 'seed004 P ratio')}, L1 "
      f"{rms('L1', 'seed004 P ratio')}, L2 {rms('L2', 'seed004 P ratio')}, L3 {rms('L3', 'seed004 P ratio')}, L4 "
      f"{rms('L4', 'seed004 P ratio')} (why each step moves: seed004_fidelity_diagnosis.md).  "
      f"IR temperature rise after 1000 s, L3: {ratio} (model vs measured).  L4: {l4txt}.")
    w("* Model no more than a scene needs: where a cheaper level gives the same error, "
      "`thermobear.coupled.choose_models` already picks it (closed form for symmetric loads, no network "
      "when T is prescribed).\n")
    w("## Stability: where methods fail\n")
    w("![stability map](stability_map.png)\n")
    w(stab)
    w("\n## Performance benchmarks\n")
    w(bench)
    w(f"\n---\nRun time: fidelity {t_fid:.0f} s, stability {t_stab:.0f} s, benchmarks {t_bench:.0f} s, "
      f"total {time.perf_counter() - t_start:.0f} s.")
    (REPORT / "report.md").write_text("\n".join(L) + "\n", encoding="utf-8")
    print(f"written {REPORT / 'report.md'} in {time.perf_counter() - t_start:.0f} s")
    bad = [n for n, c, *_ in scripts if c != 0]
    if bad:
        print("scripts that failed:", ", ".join(bad))
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
