"""Benchmark (not a test): 1 000 samples of the seed-004 steady state with its uncertain inputs (target 2 s).

``tb.steady_state(scene, uncertainty=1000)`` on examples/seed004_oil_jet_7210.toml: the nominal
steady state, 1 000 Latin-hypercube samples of its 46 estimated inputs (scene, lubricant, network,
material and bearing geometry in 8 families), solved by the batched steady solver, then the bands and
the ranking.  The target held (0.65 s) until the point's model choice came to lie in two switch
bands: each sample is now solved for three blended alternatives, one on the film load model (its
fixed point re-solves the loads), with Eyring traction and the inlet-heating and replenishment factors
— ≈ 4.6 s (×7, both measured in one run), the nominal point alone ≈ 0.1 s.
Timed on one core: a child process with single-threaded BLAS (``OPENBLAS_NUM_THREADS=1`` … set before
numpy loads — BLAS threads sharing one pinned core slow the least-squares ranking tenfold) pinned to one
CPU where the OS allows it; the CPU time of the process (``time.process_time``, as ``bench_all.py``: the
wall time of a core shared with other work swings ×2), median of ``repeat`` runs after one warm-up run;
the stages (sampling, solving, statistics) are timed apart on one run.  Never asserted in tests.

Run:  python validation/bench_uncertainty.py [N]      (``bench(n)`` returns the numbers as a dict)
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from contextlib import contextmanager
from pathlib import Path

if __name__ == "__main__":                  # the timing child: one BLAS thread, set before numpy loads
    for _v in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
        os.environ[_v] = "1"

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _common import median_time  # noqa: E402

import thermobear as tb  # noqa: E402
from thermobear.coupled.sensitivity import bands, ranking  # noqa: E402
from thermobear.coupled.steady import steady_state as nominal_steady_state  # noqa: E402
from thermobear.coupled.uncertainty import steady_outputs, sample_scenes  # noqa: E402

TARGET_S = 2.0
SCENE = "seed004_oil_jet_7210.toml"


@contextmanager
def one_core():
    """Pin the process to one CPU while timing (Linux); elsewhere, leave it as it is."""
    get, put = getattr(os, "sched_getaffinity", None), getattr(os, "sched_setaffinity", None)
    if get is None or put is None:
        yield None
        return
    before = get(0)
    try:
        put(0, {min(before)})
        yield min(before)
    finally:
        put(0, before)


def _stages(scene, n) -> dict:
    """Seconds of each stage of one run (the same work as steady_state(..., uncertainty=n))."""
    t = [time.process_time()]
    nominal_steady_state(scene)
    t.append(time.process_time())
    sm = sample_scenes(scene, n, seed=0)
    t.append(time.process_time())
    res = tb.steady_states(sm.scenes)
    t.append(time.process_time())
    out = steady_outputs(res)
    bands(out)
    ranking(sm.inputs, sm.X, out)
    t.append(time.process_time())
    names = ("nominal", "sampling", "batched solve", "bands and ranking")
    return {k: t[i + 1] - t[i] for i, k in enumerate(names)}


def bench(n: int = 1000, repeat: int = 3) -> dict:
    """Time ``tb.steady_state(seed-004 scene, uncertainty=n)`` in a one-core child process (module
    docstring); returns the numbers (seconds)."""
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1", MKL_NUM_THREADS="1")
    r = subprocess.run([sys.executable, str(Path(__file__).resolve()), str(n), str(repeat), "--json"], env=env,
                       capture_output=True, text=True, check=True)
    return json.loads(r.stdout)


def _bench_here(n: int, repeat: int) -> dict:
    """The timing itself, in this process."""
    scene = tb.load_scene(tb.example_path(SCENE))
    with one_core() as cpu:
        holder = {}

        def run():
            holder["r"] = tb.steady_state(scene, uncertainty=n)
        t = median_time(run, repeat, clock=time.process_time)
        stages = _stages(scene, n)
    r = holder["r"]
    return {"n": n, "seconds": t, "target_s": TARGET_S if n == 1000 else TARGET_S * n / 1000,
            "met": t <= TARGET_S * n / 1000, "per_sample_ms": 1e3 * t / n, "cpu": cpu, "repeat": repeat,
            "inputs": len(r.inputs), "groups": r.groups, "failed": len(r.failed), "stages_s": stages}


def report(d: dict) -> str:
    """The numbers as a few lines of text."""
    lines = [f"{d['n']} samples of the seed-004 steady state ({d['inputs']} estimated inputs, bearing geometry in "
             f"{d['groups']} families): {d['seconds']:.2f} s CPU on one core (CPU {d['cpu']}), median of {d['repeat']} — "
             f"target {d['target_s']:g} s {'met' if d['met'] else 'MISSED'}; {d['per_sample_ms']:.2f} ms per sample; "
             f"{d['failed']} failed samples",
             "stages of one run: " + ", ".join(f"{k} {v:.2f} s" for k, v in d["stages_s"].items())]
    return "\n".join(lines)


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if a != "--json"]
    d = _bench_here(int(args[0]) if args else 1000, int(args[1]) if len(args) > 1 else 3)
    print(json.dumps(d) if "--json" in sys.argv else report(d))
