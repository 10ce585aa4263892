"""Timing helper shared by the validation scripts (benchmarks are scripts, never timed tests)."""
from __future__ import annotations

import time

import numpy as np


def median_time(fn, repeat: int = 7, warmup: bool = True) -> float:
    """Median wall time of ``fn()`` over ``repeat`` calls [s], after one untimed warm-up call."""
    if warmup:
        fn()
    ts = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        ts.append(time.perf_counter() - t0)
    return float(np.median(ts))
