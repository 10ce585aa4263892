"""Logged temperatures of fixed nodes as boundaries of a transient (:class:`LinearBoundary`)."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermobear.errors import InputError

__all__ = ["LinearBoundary"]


@dataclass(frozen=True)
class LinearBoundary:
    r"""Logged temperatures of fixed nodes as a ``fixed_C(t)`` of :func:`solve_transient`: linear
    between the samples, refused outside them (a log is not extrapolated).

    .. math:: T(t) = T_k + (T_{k+1} - T_k) \frac{t - t_k}{t_{k+1} - t_k}, \quad t_k \le t \le t_{k+1}

    Attributes
    ----------
    t_s : ndarray       sample times [s], strictly increasing
    T_C : dict          node → temperatures at t_s [°C]
    source : str        what the samples are (named in errors, e.g. the log's column)

    Examples
    --------
    >>> b = LinearBoundary.of([0.0, 60.0], {"ambient": [20.0, 26.0]})
    >>> b(15.0)
    {'ambient': 21.5}
    """

    t_s: np.ndarray
    T_C: dict
    source: str = "boundary"

    @classmethod
    def of(cls, t_s, T_C: dict, source: str = "boundary") -> "LinearBoundary":
        """Checked: times finite and strictly increasing (at least two), values finite [°C]."""
        t = np.asarray(t_s, float)
        if t.ndim != 1 or t.size < 2 or not np.all(np.isfinite(t)) or np.any(np.diff(t) <= 0):
            raise InputError(f"{source}: t_s", None, "at least two times, finite and strictly increasing [s]")
        vals = {}
        for node, v in T_C.items():
            a = np.asarray(v, float)
            if a.shape != t.shape or not np.all(np.isfinite(a)):
                raise InputError(f"{source}: {node}", None, f"{t.size} finite temperatures, one per time [°C]")
            vals[node] = a
        return cls(t_s=t, T_C=vals, source=source)

    @property
    def span_s(self) -> tuple:
        """(first, last) sample time [s]."""
        return float(self.t_s[0]), float(self.t_s[-1])

    def shifted(self, dt_s: float) -> "LinearBoundary":
        """The same samples with times t_s − dt_s (a run that starts at dt_s on the samples' clock)."""
        return LinearBoundary(t_s=self.t_s - dt_s, T_C=self.T_C, source=self.source)

    def __call__(self, t) -> dict:
        t0, t1 = self.span_s
        tol = 1e-9 * max(t1 - t0, 1.0)
        if not (t0 - tol <= t <= t1 + tol):
            raise InputError(self.source, float(t), f"outside the logged times [{t0:g}, {t1:g}] s: "
                             "a logged boundary is not extrapolated")
        return {n: float(np.interp(t, self.t_s, v)) for n, v in self.T_C.items()}
