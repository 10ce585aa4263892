"""Helpers shared by the validation scripts: timing (benchmarks are scripts, never timed tests) and
writing a report table to validation/report/."""
from __future__ import annotations

import time
from pathlib import Path

import numpy as np


def median_time(fn, repeat: int = 7, warmup: bool = True, clock=time.perf_counter) -> float:
    """Median time of ``fn()`` over ``repeat`` calls [s], after one untimed warm-up call (``clock``:
    wall time by default; ``time.process_time`` for the CPU time of the process)."""
    if warmup:
        fn()
    ts = []
    for _ in range(repeat):
        t0 = clock()
        fn()
        ts.append(clock() - t0)
    return float(np.median(ts))


REPORT_DIR = Path(__file__).resolve().parent / "report"


def write_report(name: str, lines) -> Path:
    """Write ``lines`` (a string or a list of lines) to ``validation/report/<name>`` and return the path."""
    text = lines if isinstance(lines, str) else "\n".join(lines)
    REPORT_DIR.mkdir(parents=True, exist_ok=True)
    path = REPORT_DIR / name
    path.write_text(text.rstrip("\n") + "\n", encoding="utf-8")
    return path
