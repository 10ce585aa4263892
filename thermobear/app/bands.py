"""The model's band over its estimated inputs on a rig log (``thermobear compare --uncertainty N``)."""
from __future__ import annotations

import numpy as np

from thermobear.app.rig import IMPOSE, Comparison, RigLog, _row_scene, _schedule_from_log, _special
from thermobear.coupled.uncertainty import steady_uncertainty, transient_uncertainty
from thermobear.errors import InputError
from thermobear.scene import Scene

__all__ = ["log_bands", "compare_bands"]


def log_bands(scene: Scene, log: RigLog, mapping: dict, n: int, *, T0_C=None, seed=0, method: str = "lhs",
              groups: int | None = None):
    """The model's 5/50/95 % band of every mapped temperature channel over ``n`` samples of the
    estimated inputs (:mod:`thermobear.coupled.uncertainty`): a transient log by the sampled heat-up
    at the log's times (one operating point: no speed steps), a steady log (or a quasi-steady one with
    imposed channels) row by row.  Returns (channel → dict(p5, p50, p95) over the rows, design dict)."""
    quasi = any(nd.startswith(IMPOSE) for nd in mapping.values())
    chans = {ch: nd for ch, nd in mapping.items() if not _special(nd)}
    if log.kind == "transient" and not quasi:
        steps, n0 = _schedule_from_log(log)
        if steps:
            raise InputError("--uncertainty", n, "bands of a transient log need one operating point (this log "
                             "steps its speed)")
        sc = scene.with_(n_rpm=n0) if n0 is not None else scene
        r = transient_uncertainty(sc, float(log.t_s[-1]), n, t_eval=log.t_s, T0_C=T0_C, seed=seed, method=method,
                                  groups=groups)
        out = {ch: {q: r.bands[f"T_C.{nd}"][q] for q in ("p5", "p50", "p95")} for ch, nd in chans.items()}
        return out, {"n": n, "seed": seed, "method": method, "failed": len(r.failed), "by_error": r.failed_count}
    out = {ch: {q: np.full(log.n_rows, np.nan) for q in ("p5", "p50", "p95")} for ch in chans}
    failed, by = 0, {}
    for i in range(log.n_rows):
        r = steady_uncertainty(_row_scene(scene, log, i, mapping), n, seed=seed, method=method, groups=groups)
        failed += len(r.failed)
        for k, v in r.failed_count.items():
            by[k] = by.get(k, 0) + v
        for ch, nd in chans.items():
            for q in ("p5", "p50", "p95"):
                out[ch][q][i] = r.bands[f"T_C.{nd}"][q] if f"T_C.{nd}" in r.bands else np.nan
    return out, {"n": n, "seed": seed, "method": method, "failed": failed, "by_error": by}


def compare_bands(comp: Comparison, scene: Scene, n: int, *, T0_C=None, seed=0, method: str = "lhs",
                  groups: int | None = None) -> Comparison:
    """A comparison with the model's 5–95 % band of every mapped temperature channel over ``n``
    samples of the estimated inputs (:func:`log_bands`) and how many measured points lie inside it."""
    comp.bands, comp.uncertainty = log_bands(scene, comp.log, comp.mapping, n, T0_C=T0_C, seed=seed, method=method,
                                             groups=groups)
    for ch, b in comp.bands.items():
        m = np.asarray(comp.measured[ch], float)
        ok = np.isfinite(m) & np.isfinite(b["p5"])
        comp.inside[ch] = (int(np.sum(ok & (m >= b["p5"]) & (m <= b["p95"]))), int(ok.sum()))
    return comp
