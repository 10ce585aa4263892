"""Benchmark suite (not tests): the speed targets of issue 14, each measured on this tree and on a
previous revision in the same run, reported as the ratio of the two and against its target.

Run ``python validation/bench_all.py [--ref REV] [--ref-python PYTHON] [--no-profile]``;
``run_all.py`` calls :func:`run` and puts the text in ``validation/report/report.md``.

The previous revision (default :data:`REF`, the last one before the one-pipeline redesign) is
exported with ``git archive`` into a temporary folder and timed by the same workload functions in a
child process with ``PYTHONPATH`` on it (``--ref-python``: that revision's own interpreter, e.g.
one with numba, its optional compiled kernels).  Each tree is timed in its own child process,
single-threaded BLAS, alternately, so both see the same machine load; CPU time of the process
(``time.process_time``) is reported for the in-process workloads, wall time for the whole
``thermobear run`` process.  Times are never asserted in tests.

Targets (issue 14):

1. one coupled steady point (seed 004 scene)                 ≤ 1.5 ms (median of 20 new points)
2. 1000-point coupled sweep, 2000–8000 rpm × Fa, one core    ≤ 0.3 s
3. ``thermobear run examples/seed004_oil_jet_7210.toml``     ≤ 0.7 s (whole process)
4. 3600 s heat-up transient (seed 004)                       no slower than the previous revision
5. local losses of 1000 operating points (batch)             (reported, no target)
6. load distribution of 1000 combined-load cases (batch)     (reported, no target)
7. 1000 uncertainty samples of the seed-004 steady state     ≤ 2 s (issue 17; this tree only)
"""
from __future__ import annotations

import cProfile
import io
import json
import os
import pstats
import subprocess
import sys
import tarfile
import tempfile
import time
import tomllib
import warnings
from pathlib import Path

import numpy as np

from _common import median_time

#: the revision before the one-pipeline redesign (issue 14): numba kernels, solver.py
REF = "601717d"
ROOT = Path(__file__).resolve().parents[1]
SCENE = "seed004_oil_jet_7210.toml"
TARGETS = {"steady_point": 1.5e-3, "sweep_1000": 0.3, "run_process": 0.7, "transient_3600": None,
           "losses_1000": None, "loads_1000": None}
LABELS = {"steady_point": "coupled steady point (seed 004; median of 20 new points)",
          "sweep_1000": "1000-point coupled sweep, 2000–8000 rpm × 10 Fa, one core",
          "run_process": "`thermobear run examples/seed004_oil_jet_7210.toml` (whole process, byte-compiled, best of 3)",
          "transient_3600": "3600 s heat-up transient (seed 004; machine prepared once; median of 3)",
          "losses_1000": "local losses, batch of 1000 points (loads, speeds, temperatures differ)",
          "loads_1000": "load distribution, batch of 1000 combined-load cases (7210)"}
_SINGLE = {k: "1" for k in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")}
_PYC = Path(tempfile.gettempdir()) / "thermobear-bench-pyc"


# ----------------------------------------------------------------- workloads (run in a child process)
def _api():
    """The few entry points the workloads need, from whichever revision is on the path."""
    import thermobear as tb
    try:
        from thermobear.app.sweep import run_sweep
    except ImportError:                                  # before the app/ package
        from thermobear.sweep import run_sweep
    return tb, run_sweep


def _cpu(fn, repeat: int) -> float:
    return median_time(fn, repeat, clock=time.process_time)   # warm-up call first: imports, preparation


def measure(which: str) -> float:
    """CPU time [s] of one workload on the thermobear found on ``sys.path``."""
    tb, run_sweep = _api()
    s = tb.load_scene(tb.example_path(SCENE))
    if which == "steady_point":
        # the machine prepared once, as for any series of points: explicitly where the API has it
        # (tb.prepare), by the hidden caches of the revisions before it
        kw = {"prepared": tb.prepare(s)} if hasattr(tb, "prepare") else {}
        tb.steady_state(s, **kw)
        ts = []
        for k in range(1, 21):                            # each timed call a new operating point
            sc = s.with_(n_rpm=s.n_rpm * (1.0 + k * 1e-4))
            t0 = time.process_time()
            tb.steady_state(sc, **kw)
            ts.append(time.process_time() - t0)
        return float(np.median(ts))
    if which == "sweep_1000":
        grid = {"n_rpm": list(np.linspace(2000.0, 8000.0, 100)), "Fa_N": list(np.linspace(300.0, 750.0, 10))}
        t0 = time.process_time()
        run_sweep(s, grid, processes=1)
        return time.process_time() - t0
    if which == "transient_3600":
        # the machine prepared once, as for the steady point (the revisions before tb.prepare: their caches)
        kw = {"prepared": tb.prepare(s)} if hasattr(tb, "prepare") else {}
        return _cpu(lambda: tb.transient(s, 3600.0, **kw), 3)
    rng = np.random.default_rng(6)
    b, n = s.bearing, 1000
    Fr = rng.uniform(50, 1500, n)
    Fa = Fr * np.tan(b.alpha0) * 1.05 + rng.uniform(50, 700, n)
    if which == "loads_1000":
        return _cpu(lambda: tb.load_distribution(b, Fa=Fa, Fr=Fr), 5)
    if which == "losses_1000":
        nn, TT = rng.uniform(1000, 8000, n), rng.uniform(30, 70, n)
        return _cpu(lambda: tb.bearing_losses(b, s.lubricant, Fa=Fa, Fr=Fr, n_rpm=nn, T_C=TT,
                                              oil_flow_m3_s=s.oil_flow), 3)
    raise ValueError(which)


# ----------------------------------------------------------------- the two trees
def export(rev: str, into: Path) -> Path:
    """The source tree of ``rev`` (``git archive``) in ``into``; returns its root."""
    data = subprocess.run(["git", "-C", str(ROOT), "archive", rev], check=True, capture_output=True).stdout
    with tarfile.open(fileobj=io.BytesIO(data)) as tar:
        tar.extractall(into, filter="data")
    return into


def _child(python: str, tree: Path, which: str) -> float:
    env = {**os.environ, **_SINGLE, "PYTHONPATH": str(tree)}
    if which == "run_process":             # the tree's own console script (its module moved between revisions)
        mod, func = tomllib.loads((tree / "pyproject.toml").read_text())["project"]["scripts"]["thermobear"].split(":")
        script = f"import sys; from {mod} import {func}; sys.exit({func}())"
        # as on a user's machine, where the installed modules are byte-compiled: the first (untimed)
        # run writes each tree's .pyc files into a cache folder of its own, outside both trees
        env.pop("PYTHONDONTWRITEBYTECODE", None)
        env["PYTHONPYCACHEPREFIX"] = str(_PYC / tree.name)
        ts = []
        for _ in range(4):
            t0 = time.perf_counter()
            subprocess.run([python, "-c", script, "run", str(tree / "examples" / SCENE)], env=env, check=True,
                           capture_output=True, cwd=tree)
            ts.append(time.perf_counter() - t0)
        return min(ts[1:])
    code = (f"import sys, warnings; sys.path.insert(0, {str(Path(__file__).parent)!r}); "
            f"warnings.simplefilter('ignore'); import bench_all, json; "
            f"print(json.dumps(bench_all.measure({which!r})))")
    out = subprocess.run([python, "-c", code], env=env, check=True, capture_output=True, text=True, cwd=tree)
    return float(json.loads(out.stdout.strip().splitlines()[-1]))


def compare(ref: str = REF, ref_python: str | None = None) -> list:
    """``[(key, this tree [s], previous revision [s]), ...]`` measured alternately in one run."""
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        old = export(ref, Path(tmp))
        for key in TARGETS:
            new_t = _child(sys.executable, ROOT, key)
            old_t = _child(ref_python or sys.executable, old, key)
            rows.append((key, new_t, old_t))
    return rows


def _fmt(x: float) -> str:
    return f"{x * 1e3:.1f} ms" if x < 1.0 else f"{x:.2f} s"


def table(rows, ref: str) -> list:
    L = [f"| benchmark | this tree | previous ({ref}) | ratio (this / previous) | target | verdict |",
         "|---|---|---|---|---|---|"]
    for key, new_t, old_t in rows:
        target = TARGETS[key]
        if target is None and key == "transient_3600":
            verdict = "met" if new_t <= old_t else f"**missed ×{new_t / old_t:.3g}**"
            tgt = "≤ previous"
        elif target is None:
            verdict, tgt = "–", "–"
        else:
            verdict, tgt = ("met" if new_t <= target else f"**missed ×{new_t / target:.3g}**"), _fmt(target)
        L.append(f"| {LABELS[key]} | {_fmt(new_t)} | {_fmt(old_t)} | {new_t / old_t:.2f} | {tgt} | {verdict} |")
    return L


def _profile(fn, n: int = 14) -> str:
    pr = cProfile.Profile()
    pr.enable()
    fn()
    pr.disable()
    st = pstats.Stats(pr)
    rows = sorted(((tt, ct, nc, f"{f.split('/thermobear/')[-1]}:{line}({func})")
                   for (f, line, func), (cc, nc, tt, ct, _) in st.stats.items()), reverse=True)
    lines = [f"total {st.total_tt:.3f} s; top by own time (own s, cumulative s, calls):"]
    return "\n".join(lines + [f"  {tt:7.3f} {ct:7.3f} {nc:7d}  {name}" for tt, ct, nc, name in rows[:n]])


def profiles() -> list:
    """cProfile hot spots of the steady point and the transient on this tree."""
    tb, _ = _api()
    s = tb.load_scene(tb.example_path(SCENE))
    pre = tb.prepare(s)                       # as the benchmarks: the machine prepared once
    tb.steady_state(s, prepared=pre)
    pts = [s.with_(n_rpm=s.n_rpm * (1.0 + k * 1e-4)) for k in range(101, 121)]
    out = ["Hot spots (cProfile, this tree; the machine prepared once, as in the benchmarks):", ""]
    for name, fn in (("20 coupled steady points (seed 004)", lambda: [tb.steady_state(p, prepared=pre) for p in pts]),
                     ("3600 s transient (seed 004)", lambda: tb.transient(s, 3600.0, prepared=pre))):
        out += [f"**{name}**", "", "```", _profile(fn), "```", ""]
    return out


def uncertainty_line() -> list:
    """The issue-17 benchmark (1000 uncertainty samples), when this tree has it."""
    try:
        sys.path.insert(0, str(Path(__file__).parent))
        import bench_uncertainty
    except ImportError:
        return []
    r = bench_uncertainty.bench(1000)                 # its own one-core child process
    t = r["seconds"] if isinstance(r, dict) else float(r)
    return ["", f"1000 uncertainty samples of the seed-004 steady state (issue 17; one core): {t:.2f} s "
                f"(target ≤ 2 s: {'met' if t <= 2.0 else 'missed'})."]


def run(full: bool = False, profile: bool = True, ref: str = REF, ref_python: str | None = None) -> str:
    """The benchmark section of the validation report (``full`` is accepted for run_all's interface:
    the sweep is always the full 1000 points)."""
    warnings.simplefilter("ignore")
    rows = compare(ref, ref_python)
    L = table(rows, ref)
    L += ["", f"Both trees timed in child processes of one run, alternately (single-threaded BLAS; CPU time "
              f"of the process for in-process workloads, wall time for the whole `thermobear run`); the previous "
              f"revision {ref} run by `{ref_python or sys.executable}`."]
    L += uncertainty_line()
    if profile:
        L += [""] + profiles()
    return "\n".join(L)


def _arg(argv, name, default=None):
    return argv[argv.index(name) + 1] if name in argv else default


if __name__ == "__main__":
    a = sys.argv
    print(run(profile="--no-profile" not in a, ref=_arg(a, "--ref", REF), ref_python=_arg(a, "--ref-python")))
