"""Local worker processes: a pool whose workers leave Ctrl-C to the caller, and which no worker outlives.

The sweep's chunks (:mod:`thermobear.app.sweep`) and an uncertainty band's heat-ups
(:func:`thermobear.coupled.uncertainty.transient_uncertainty`) run their independent jobs here.
"""
from __future__ import annotations

import multiprocessing
import signal

import numpy as np

from thermobear.errors import InputError

__all__ = ["check_processes", "imap_unordered", "worker_signals"]


def check_processes(processes, field: str = "processes") -> int:
    """The number of worker processes, checked: an integer ≥ 1 (InputError naming ``field`` otherwise).

    >>> check_processes(2), check_processes(np.int64(3))
    (2, 3)
    """
    if isinstance(processes, (bool, np.bool_)) or not isinstance(processes, (int, np.integer)) or processes < 1:
        raise InputError(field, processes, "a number of worker processes >= 1")
    return int(processes)


def worker_signals():
    """Worker processes leave Ctrl-C to the parent, which terminates them (SIGTERM: end quietly)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


def imap_unordered(fn, jobs: list, processes: int):
    """``fn(job)`` of each of ``jobs`` in up to ``processes`` worker processes, yielded as they finish.

    ``fn`` is a module-level function and the jobs picklable (any start method).  Ctrl-C, SIGTERM, an error, or
    the caller leaving the loop terminates the workers: none outlives it.

    >>> sorted(imap_unordered(abs, [-2, 3, -1], 2))
    [1, 2, 3]
    """
    pool = multiprocessing.get_context().Pool(max(1, min(check_processes(processes), len(jobs))),
                                              initializer=worker_signals)
    try:
        yield from pool.imap_unordered(fn, jobs)
        pool.close()
    except BaseException:                   # Ctrl-C, SIGTERM, an error, the caller gone
        pool.terminate()
        raise
    finally:
        pool.join()
