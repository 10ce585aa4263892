"""The model's band over its estimated inputs on a rig log (``thermobear compare --uncertainty N``)."""
from __future__ import annotations

import numpy as np

from thermobear.app.rig import Comparison, RigLog, _log_inputs, _row_scene, special_target
from thermobear.coupled.uncertainty import steady_uncertainty, transient_uncertainty
from thermobear.errors import InputError
from thermobear.scene import Scene

__all__ = ["log_bands", "compare_bands"]


def log_bands(scene: Scene, log: RigLog, mapping: dict, n: int, *, T0_C=None, seed=0, method: str = "lhs",
              groups: int | None = None):
    """The model's 5/50/95 % band of every mapped temperature channel over ``n`` samples of the
    estimated inputs (:mod:`thermobear.coupled.uncertainty`): a transient log by the sampled heat-up
    at the log's times (one operating point: no speed or load steps; its ``impose:<node>`` channels the logged
    boundary of every sample, as :func:`~thermobear.app.rig.simulate_log` runs it), a steady log row by
    row.  Returns (channel → dict(p5, p50, p95) over the rows, design dict)."""
    chans = {ch: nd for ch, nd in mapping.items() if not special_target(nd)}
    if log.kind == "transient":
        sc, steps, bnd = _log_inputs(scene, log, mapping)
        if steps:
            raise InputError("--uncertainty", n, "bands of a transient log need one operating point (this log "
                             "steps its speed or loads)")
        t = np.asarray(log.t_s, float) - float(log.t_s[0])
        if T0_C is None and bnd is not None and "ambient" in bnd.T_C:
            T0_C = float(bnd.T_C["ambient"][0])           # as simulate_log: from the logged room
        r = transient_uncertainty(sc, float(t[-1]), n, t_eval=t, T0_C=T0_C, seed=seed, method=method, groups=groups,
                                  boundary=bnd)
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
