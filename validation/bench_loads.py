"""Benchmark (not a test): load distribution time per case, single and batched, static and high-speed.

Cases (numpy only; the machine may be busy: the minimum over the repeats is the robust figure, the
median is printed too):

* static, single case per bearing and a batch of 1000 combined-load cases (7210: Fa ≥ 1.1 Fr tan α0);
* high speed, the seed 004 point (7210, Fa 450 N, Fr 325 N, 3200 rpm) as a single case, and a batch
  of 1000 cases (7210, the same loads at 2000–8000 rpm).

Targets (issue: one shared Newton, no numba): static batch ≤ 20 µs/case; the seed 004 high-speed case
well under 1 ms.

Run::

    python validation/bench_loads.py                 # this checkout
    python validation/bench_loads.py --against main  # and a git revision, timed in the same run

``--against REV`` extracts REV with ``git archive`` into a temporary folder and runs this script there
(``--json``, the revision's package first on the path), so both are timed on the same machine within
seconds; the table gives the ratio REV / this checkout.
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

import thermobear as tb
from thermobear.loads.highspeed import load_distribution_high_speed

HERE = Path(__file__).resolve().parent
N_BATCH = 1000
SEED004 = dict(Fa=450.0, Fr=325.0, n_rpm=3200.0)


def _times(fn, repeat):
    """(minimum, median) wall time of ``fn()`` over ``repeat`` calls [s], after one untimed call."""
    fn()
    ts = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        ts.append(time.perf_counter() - t0)
    return float(np.min(ts)), float(np.median(ts))


def _loads(b, rng, n):
    if b.kind == "thrust":
        return rng.uniform(100, 7000, n), np.zeros(n)
    if b.kind == "angular_contact":
        Fr = rng.uniform(0, 1500, n)
        return Fr * np.tan(b.alpha0) * 1.1 + rng.uniform(50, 700, n), Fr
    return rng.uniform(0, 1500, n), rng.uniform(100, 3000, n)


def measure(quick: bool = False) -> dict:
    """Times [µs per case] keyed by case name, each (minimum, median, Newton iterations)."""
    warnings.simplefilter("ignore")
    rep1, repb = (21, 3) if quick else (101, 7)
    out = {}
    for name in ("iso-dgbb", "6210", "7210", "51107"):
        b = tb.bearing(name)
        rng = np.random.default_rng(1)
        Fa, Fr = _loads(b, rng, N_BATCH)
        t1 = _times(lambda: tb.load_distribution(b, Fa=float(Fa[0]), Fr=float(Fr[0])), rep1)
        tb_ = _times(lambda: tb.load_distribution(b, Fa=Fa, Fr=Fr), repb)
        it = tb.load_distribution(b, Fa=Fa, Fr=Fr).iterations
        out[f"static single {name}"] = (t1[0] * 1e6, t1[1] * 1e6, it)
        out[f"static batch {name}"] = (tb_[0] / N_BATCH * 1e6, tb_[1] / N_BATCH * 1e6, it)
    sc = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    b = sc.bearing
    t = _times(lambda: load_distribution_high_speed(b, **SEED004), rep1)
    out["high speed single seed 004"] = (t[0] * 1e6, t[1] * 1e6, load_distribution_high_speed(b, **SEED004).iterations)
    rng = np.random.default_rng(1)
    Fa, Fr = _loads(b, rng, N_BATCH)
    n = rng.uniform(2000.0, 8000.0, N_BATCH)
    t = _times(lambda: load_distribution_high_speed(b, Fa=Fa, Fr=Fr, n_rpm=n), max(repb // 2, 2))
    it = load_distribution_high_speed(b, Fa=Fa, Fr=Fr, n_rpm=n).iterations
    out["high speed batch 7210"] = (t[0] / N_BATCH * 1e6, t[1] / N_BATCH * 1e6, it)
    return out


def measure_revision(rev: str, quick: bool = False) -> dict:
    """:func:`measure` on a git revision, in a subprocess on a copy extracted by ``git archive``."""
    root = HERE.parent
    with tempfile.TemporaryDirectory(prefix="thermobear-rev-") as tmp:
        archive = subprocess.run(["git", "-C", str(root), "archive", rev], capture_output=True, check=True).stdout
        subprocess.run(["tar", "-x", "-C", tmp], input=archive, check=True)
        env = dict(os.environ, PYTHONPATH=tmp, THERMOBEAR_NUMBA="0")
        cmd = [sys.executable, str(HERE / "bench_loads.py"), "--json"] + (["--quick"] if quick else [])
        r = subprocess.run(cmd, cwd=tmp, env=env, capture_output=True, text=True, check=True)
    return {k: tuple(v) for k, v in json.loads(r.stdout.strip().splitlines()[-1]).items()}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--against", metavar="REV", help="also time this git revision (e.g. main) in the same run")
    ap.add_argument("--json", action="store_true", help="print the times as one JSON line")
    ap.add_argument("--quick", action="store_true", help="fewer repeats")
    args = ap.parse_args(argv)
    if args.json:
        print(json.dumps(measure(args.quick)))
        return None
    other = measure_revision(args.against, args.quick) if args.against else None
    rows = measure(args.quick)
    head = f"{'case':32s} {'min [µs/case]':>14s} {'median':>10s} {'iter':>5s}"
    if other:
        head += f" {args.against + ' min':>14s} {'ratio':>7s}"
    print(head)
    for k, (tmin, tmed, it) in rows.items():
        line = f"{k:32s} {tmin:14.1f} {tmed:10.1f} {it:5d}"
        if other and k in other:
            line += f" {other[k][0]:14.1f} {other[k][0] / tmin:6.2f}x"
        print(line)
    sb = rows["static batch 7210"][0]
    hs = rows["high speed single seed 004"][0]
    print(f"\nstatic batch 7210: {sb:.1f} µs/case (target 20 µs: {'met' if sb <= 20 else 'MISSED'}); "
          f"seed 004 high-speed case: {hs / 1000:.2f} ms (target well under 1 ms: "
          f"{'met' if hs <= 800 else 'MISSED'})")
    return rows


if __name__ == "__main__":
    main()
