"""Measured temperatures against the model's 5–95 % bands over its estimated inputs.

Every estimated value the seed scenes use carries a range in its data file (``uncertainty.<key>``,
with its source or reasoning; thermobear.schema.check_uncertainty).  Here the scenes are solved over
Latin-hypercube samples of all of them (thermobear.coupled.uncertainty, seed 0) and the measurements
are set against the bands — no parameter is calibrated:

* seed 002 (Cousseau et al.), 51107 grease thrust bearing: thermocouple III (housing-washer node),
  Table 3 at 1000 rpm (MG1 49.8, MG2 47.6, EG1 41.6, PG1 42.1, PG2 39.3 °C) and MG1 at 2000 rpm (65 °C,
  §4.2) — the points of validation/seed002_thermal.py, here with the network's prior estimates (its
  seat conductance uncalibrated);
* seed 004 (Darul et al. 2024), 7210 oil jet, test 1: the inner ring at t = 1000 s of the heat-up
  (Fig. 8: ≈ 55 °C at 3200 rpm, ≈ 90 °C at 8070 rpm) — the readings of
  validation/seed004_heatup_sensitivity.py and seed004_trends.py — and the steady state.

* networks built from dimensions (examples/block_6208_oil_jet.toml, block_6208_grease.toml; no
  measurement): the bands without and with the network builders' estimated constants
  (materials/network_builders.toml).

For a measurement outside its band, the regression of the output on the draws (slope per draw unit,
thermobear.coupled.sensitivity) says how far each of the most influential inputs would have to move,
alone, for the median to reach the measurement, and whether that lies inside the input's range.
Writes validation/report/uncertainty.md and report/uncertainty_seed004_heatup.png.

Run:  python validation/uncertainty.py   (≈ 1–2 min)
"""
from __future__ import annotations

import sys
import time
import warnings
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _common import REPORT_DIR, write_report  # noqa: E402

import thermobear as tb  # noqa: E402

N_STEADY = 256
N_HEATUP = 128
SEED = 0
SEED002 = tb.load_scene(tb.example_path("seed002_grease_thrust_51107.toml"))
SEED004 = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
CASES_002 = [("MG1", 1000.0, 49.8), ("MG1", 2000.0, 65.0), ("MG2", 1000.0, 47.6), ("EG1", 1000.0, 41.6),
             ("PG1", 1000.0, 42.1), ("PG2", 1000.0, 39.3)]      # seed 002 Table 3; §4.2 text (2000 rpm)
PAPER_004 = {3200.0: 55.0, 8070.0: 90.0}                        # seed 004 Fig. 8, inner ring at 1000 s
T_HEATUP_S = 1000.0


def _num(v, fmt) -> str:
    return "—" if v is None else format(v, fmt)


def _ranking(rk, title: str, top: int = 8) -> list:
    """The table of a ranking (``UncertaintyResult.sensitivity[key]``), its title with how it ranks, and the
    caveat where the draws do not determine the regression (its SRCs and slopes withheld)."""
    r2 = "" if rk["r2"] is None else f", R² {rk['r2']:.2f}"
    out = ["", f"Inputs ranked for {title} ({rk['ranked_by']}{r2}):", ""]
    if rk.get("caveat"):
        c = rk["caveat"]
        out += [f"Caveat: {c['message'] if isinstance(c, dict) and 'message' in c else c}", ""]
    out += ["| input | SRC | slope per draw unit | rank correlation |", "|---|---|---|---|"]
    return out + [f"| `{e['address']}` | {_num(e['src'], '+.3f')} | {_num(e['slope'], '+.4g')} | "
                  f"{e['spearman']:+.3f} |" for e in rk["inputs"][:top]]


def _needed(res, key, measured, top=3) -> list:
    """For the ``top`` inputs of output ``key``: the draw that alone would bring the median to
    ``measured`` (linear in the regression slope), and whether it is inside the input's range."""
    rk = res.sensitivity.get(key)
    if rk is None or rk["r2"] is None:
        return ["(no regression slope: the draws do not determine it, see the ranking's caveat)"]
    p50 = float(np.ravel(res.bands[key]["p50"])[-1])
    by = {i.address: i for i in res.inputs}
    out = []
    for e in rk["inputs"][:top]:
        i = by[e["address"]]
        u = i.uncertainty
        if e["slope"] == 0:
            continue
        X = res.X[:, res.inputs.index(i)]
        draw = float(np.median(X)) + (measured - p50) / e["slope"]
        inside = u.lo <= draw <= u.hi
        what = {"factor": f"factor {draw:.3g}", "offset": f"offset {draw:+.3g}"}.get(u.kind, f"{draw:.4g}")
        out.append(f"`{i.address}` {what} (range {u.lo:g} … {u.hi:g}{', inside' if inside else ', OUTSIDE'})")
    return out


def seed002(lines):
    ins = tb.coupled.uncertainty.uncertain_inputs(SEED002)
    d = sum(i.level == "family" for i in ins)
    lines += ["## Seed 002 — 51107 grease thrust bearing, thermocouple III (housing-washer node)", "",
              f"{N_STEADY} samples per point (all {len(ins)} estimated "
              "inputs of the scene, the grease, the bearing catalogue entry, the network and its steel; "
              f"bearing geometry in {max(8, 2 * (d + 1))} families). The network's prior estimates (nothing calibrated).", "",
              "| grease | n [rpm] | measured [°C] | nominal [°C] | p5 | p50 | p95 [°C] | inside | failed | "
              "would have to move (alone, for the median) |", "|---|---|---|---|---|---|---|---|---|---|"]
    inside = 0
    for g, n, Tm in CASES_002:
        sc = SEED002.with_(lubricant=f"seed002-{g.lower()}", n_rpm=n)
        r = tb.steady_state(sc, uncertainty=N_STEADY, seed=SEED)
        b = r.bands["T_C.housing_washer"]
        ok = b["p5"] <= Tm <= b["p95"]
        inside += ok
        move = "" if ok else "; ".join(_needed(r, "T_C.housing_washer", Tm))
        lines.append(f"| {g} | {n:g} | {Tm:g} | {r.nominal.T_C['housing_washer']:.1f} | {b['p5']:.1f} | "
                     f"{b['p50']:.1f} | {b['p95']:.1f} | {'yes' if ok else 'no'} | {len(r.failed)} | {move} |")
        if (g, n) == ("MG1", 1000.0):
            first = r
    rk = first.sensitivity["T_C.housing_washer"]
    lines += ["", f"{inside} of {len(CASES_002)} measurements inside their 5–95 % band."]
    lines += _ranking(rk, "T_III (MG1, 1000 rpm)")
    return lines


def seed004(lines):
    lines += ["", "## Seed 004 — 7210 oil jet, test 1: inner ring at 1000 s (Fig. 8) and at steady state", "",
              f"Heat-up: {N_HEATUP} samples per speed, each bearing-geometry family integrated as one batched "
              f"system; steady state: {N_STEADY} samples.", "",
              "| n [rpm] | Fig. 8 at 1000 s [°C] | nominal at 1000 s | p5 | p50 | p95 [°C] | inside | failed | "
              "steady p5 … p95 [°C] | would have to move (alone, for the median at 1000 s) |",
              "|---|---|---|---|---|---|---|---|---|---|"]
    runs = {}
    for n, Tm in PAPER_004.items():
        sc = SEED004.with_(n_rpm=n)
        tr = tb.transient(sc, T_HEATUP_S, uncertainty=N_HEATUP, seed=SEED,
                          t_eval=np.linspace(0.0, T_HEATUP_S, 41)[1:])
        st = tb.steady_state(sc, uncertainty=N_STEADY, seed=SEED)
        runs[n] = tr
        b = {q: float(tr.bands["T_C.inner_ring"][q][-1]) for q in ("p5", "p50", "p95")}
        ok = b["p5"] <= Tm <= b["p95"]
        move = "" if ok else "; ".join(_needed(tr, "T_C.inner_ring", Tm))
        sb = st.bands["T_C.inner_ring"]
        nom = float(np.interp(T_HEATUP_S, tr.nominal.t_s, tr.nominal.T_C["inner_ring"]))
        lines.append(f"| {n:g} | ≈ {Tm:g} | {nom:.1f} | {b['p5']:.1f} | {b['p50']:.1f} | {b['p95']:.1f} | "
                     f"{'yes' if ok else 'no'} | {len(tr.failed)} | {sb['p5']:.1f} … {sb['p95']:.1f} | {move} |")
    rk = runs[3200.0].sensitivity["T_C.inner_ring"]
    lines += _ranking(rk, "the inner ring at 1000 s (3200 rpm)")
    _plot(runs)
    lines += ["", "![inner-ring heat-up bands](uncertainty_seed004_heatup.png)"]
    return lines


BUILT = [("block_6208_oil_jet.toml", "6208, oil jet, block housing"),
         ("block_6208_grease.toml", "6208, grease, block housing")]


def _from_builders(i) -> bool:
    """An input whose range the builders' data give: a family draw (``builder.<key>``) or a per-point range
    the builder writes on one element or node (its source names the data file)."""
    return i.address.startswith("builder.") or "network_builders.toml" in i.uncertainty.source


def built(lines):
    """Scenes whose network is built from their dimensions (thermobear.thermal.builders): the bands with
    and without the builders' estimates (materials/network_builders.toml, ``builder.<key>``) sampled."""
    lines += ["", "## Networks built from dimensions — the builders' estimates (no measurement)", "",
              f"{N_STEADY} steady samples of each scene, seed {SEED}: once without the builders' estimated constants "
              "(the seats' roughness, the microhardness and gas parameter of the seats' joint conductance, the "
              "housing's emissivity, the mounting joint, the rings' and cavity's fills: "
              "`materials/network_builders.toml`; and the per-point ranges the builder writes on the seal's, the cage's "
              "and the bath's elements), once with them (drawn per family with the bearing's geometry; "
              "the families of each run in the last column). The width the builders' estimates add is the spread the built networks' bands "
              "understated before they had ranges.", "",
              "| scene | output | nominal | p5 … p95 without | p5 … p95 with | failed (with) | families (without, with) |",
              "|---|---|---|---|---|---|---|"]
    ranked = None
    for ex, what in BUILT:
        sc = tb.load_scene(tb.example_path(ex))
        ins = tb.coupled.uncertainty.uncertain_inputs(sc)
        r0 = tb.coupled.uncertainty.steady_uncertainty(
            sc, N_STEADY, seed=SEED, inputs=[i for i in ins if not _from_builders(i)])
        r1 = tb.coupled.uncertainty.steady_uncertainty(sc, N_STEADY, seed=SEED, nominal=r0.nominal)
        ranked = ranked or r1
        for key in ("T_C.balls", "T_C.outer_ring", "T_C.housing", "P_W"):
            b0, b1 = r0.bands[key], r1.bands[key]
            nom = r0.nominal.P_W if key == "P_W" else r0.nominal.T_C[key[4:]]
            lines.append(f"| {what} | {key} | {nom:.2f} | {b0['p5']:.2f} … {b0['p95']:.2f} | "
                         f"{b1['p5']:.2f} … {b1['p95']:.2f} | {len(r1.failed)} | {r0.groups}, {r1.groups} |")
    rk = ranked.sensitivity["T_C.housing"]
    lines += _ranking(rk, "the housing of the oil-jet scene")
    return lines


def _plot(runs):
    try:
        import matplotlib                          # noqa: PLC0415  (the optional plot extra)
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt            # noqa: PLC0415
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    for c, (n, r) in zip(("C0", "C3"), runs.items()):
        b = r.bands["T_C.inner_ring"]
        ax.fill_between(r.t_s, b["p5"], b["p95"], color=c, alpha=0.2, lw=0, label=f"{n:g} rpm, 5–95 % band")
        ax.plot(r.nominal.t_s, r.nominal.T_C["inner_ring"], "-", color=c, label=f"{n:g} rpm, nominal")
        ax.plot([T_HEATUP_S], [PAPER_004[n]], "o", color=c, mfc="white", ms=8, label=f"{n:g} rpm, seed 004 Fig. 8")
    ax.set_xlabel("time [s]"), ax.set_ylabel("inner ring [°C]"), ax.grid(alpha=0.3), ax.legend(fontsize=7)
    ax.set_title("Seed 004 test 1: inner-ring heat-up, bands over the estimated inputs")
    fig.tight_layout()
    fig.savefig(REPORT_DIR / "uncertainty_seed004_heatup.png", dpi=110)
    plt.close(fig)


def main() -> int:
    warnings.simplefilter("ignore", tb.ExtrapolationWarning)
    warnings.simplefilter("ignore", tb.OutsideValidity)
    t0 = time.perf_counter()
    L = ["# Measurements against the bands over the estimated inputs", "",
         "Generated by `validation/uncertainty.py` (seed 0, Latin hypercube; `thermobear.coupled.uncertainty`). "
         "Every estimated value of the seed scenes' data is drawn from the range next to it in its data file; "
         "nothing is calibrated. A band is the 5–95 % spread of the model over those ranges: a measurement "
         "outside it says the ranges (or the model) miss something, and the last column names the inputs that "
         "would have to move, and how far, to reach it.", ""]
    L = seed002(L)
    L = seed004(L)
    L = built(L)
    L += ["", "Moves are linear extrapolations of the regression slope (per draw unit: × for a factor, K for an "
          "offset, the key's unit for a range). Far outside an input's range (an osculation below 0.5, a ball "
          "that no longer fits) they only say that this input alone cannot close the gap. Family-level "
          "inputs (the bearing's geometry; a built network's builder estimates) are drawn at 8 levels, or 2 (d + 1) "
          "for d of them (34 for the built scenes), one family each: their slopes rest on that many draws, and "
          "a small effect among them (the emissivity beside the mounting joint) is not resolved in the ranking. The support "
          "block's offset is held from t = 0 in the heat-up (an upper bound on its effect, as in "
          "seed004_support_heat.md)."]
    L += ["", f"Run time {time.perf_counter() - t0:.0f} s."]
    path = write_report("uncertainty.md", L)
    print("\n".join(L))
    print(f"written {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
