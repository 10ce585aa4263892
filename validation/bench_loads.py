"""Benchmark (not a test): load distribution time per case, single and batched.

Target (issue 2): <= 100 µs per case in a batch of 1 000 combined Fr + Fa cases.
Run:  python validation/bench_loads.py
"""
from __future__ import annotations


import numpy as np

from _common import median_time

from thermobear.contact.geometry import bearing
from thermobear.loads.static import load_distribution


def timeit(fn, repeat=7):
    return median_time(fn, repeat, warmup=False)


def main():
    rng = np.random.default_rng(1)
    n = 1000
    print(f"{'bearing':10s} {'single [µs]':>12s} {'batch 1000 [µs/case]':>22s} {'iterations':>10s}")
    rows = {}
    for name in ("iso-dgbb", "6210", "7210", "51107"):
        b = bearing(name)
        if b.kind == "thrust":
            Fa, Fr = rng.uniform(100, 7000, n), np.zeros(n)
        elif b.kind == "angular_contact":
            Fr = rng.uniform(0, 1500, n)
            Fa = Fr * np.tan(b.alpha0) * 1.1 + rng.uniform(50, 700, n)
        else:
            Fa, Fr = rng.uniform(0, 1500, n), rng.uniform(100, 3000, n)
        t1 = timeit(lambda: load_distribution(b, Fa=float(Fa[0]), Fr=float(Fr[0])), repeat=51)
        tb = timeit(lambda: load_distribution(b, Fa=Fa, Fr=Fr))
        it = load_distribution(b, Fa=Fa, Fr=Fr).iterations
        rows[name] = (t1 * 1e6, tb / n * 1e6)
        print(f"{name:10s} {t1 * 1e6:12.1f} {tb / n * 1e6:22.1f} {it:10d}")
    worst = max(v[1] for v in rows.values())
    print(f"\nworst batched time {worst:.1f} µs/case; target 100 µs/case -> {'met' if worst <= 100 else 'MISSED'}")
    return rows


if __name__ == "__main__":
    main()
