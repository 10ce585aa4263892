r"""Bands and sensitivity ranking of sampled predictions (:mod:`thermobear.coupled.uncertainty`).

Bands: the 5, 50 and 95 % quantiles of each output over the samples that solved.

Ranking of the inputs, for each output y over the draws X (n samples × d inputs):

* ``"src"`` (default, numpy / scipy): the standardised regression coefficients of the linear
  least-squares fit of y on X,

  .. math:: \frac{y - \bar y}{s_y} = \sum_j \mathrm{SRC}_j \frac{x_j - \bar x_j}{s_{x_j}} + \varepsilon,

  with its R²; when R² is near 1, SRC_j² is input j's share of the variance of y (Saltelli et al.
  2008, *Global Sensitivity Analysis: The Primer*, §1.2.5).  Each entry also has the slope
  ∂y/∂x_j = SRC_j s_y / s_{x_j} (output unit per draw unit: per factor, per K of offset …) and
  Spearman's rank correlation (monotonic, not only linear, dependence).  With fewer samples than
  2 (d + 1) (two per coefficient) the regression is not trusted and the inputs are ranked by
  |rank correlation|.
* ``"sobol"``: first-order Sobol' indices S1 estimated on the same samples by RBD-FAST (Tarantola,
  Gatelli & Mara 2006; Plischke 2010), from the optional SALib (``pip install thermobear[sensitivity]``);
  the SRC entries are kept beside them.

Inputs whose draws do not vary (a zero-width range) get zero.
"""
from __future__ import annotations

import numpy as np

from thermobear.coupled.ratings import RATING_OUTPUTS
from thermobear.errors import InputError
from thermobear.lazy import lazy_module

stats = lazy_module("scipy.stats")          # rankdata: loaded by the first ranking

__all__ = ["bands", "ranking", "SENSITIVITY"]

SENSITIVITY = ("src", "sobol")


def bands(outputs: dict) -> dict:
    """Output → dict(p5, p50, p95, n): quantiles over the samples (axis 0) that are finite.

    >>> b = bands({"y": np.arange(101.0)})["y"]
    >>> b["p5"], b["p50"], b["p95"], b["n"]
    (5.0, 50.0, 95.0, 101)
    """
    out = {}
    for k, v in outputs.items():
        v = np.asarray(v, float)
        ok = np.isfinite(v).all(axis=tuple(range(1, v.ndim)))
        if not ok.any():
            continue
        q = np.percentile(v[ok], [5.0, 50.0, 95.0], axis=0)
        sc = (lambda a: float(a) if np.ndim(a) == 0 else a)  # noqa: E731
        out[k] = {"p5": sc(q[0]), "p50": sc(q[1]), "p95": sc(q[2]), "n": int(ok.sum())}
    return out


def _std(a):
    s = a.std(axis=0)
    return (a - a.mean(axis=0)) / np.where(s > 0, s, 1.0), s


def ranking(inputs, X, outputs: dict, method: str = "src") -> dict:
    """Output → ``{"method", "r2", "ranked_by", "inputs": [{"address", "src", "slope", "spearman"[, "S1"]}, ...]}``,
    the inputs sorted by importance (module docstring); outputs given per sample (n,), NaN where a
    sample failed (those samples are left out).  One least-squares solve for all outputs.

    >>> rng = np.random.default_rng(0)
    >>> X = rng.random((200, 2))
    >>> r = ranking([type("I", (), {"address": a})() for a in "ab"], X, {"y": 3 * X[:, 1] + 0.1 * X[:, 0]})
    >>> [e["address"] for e in r["y"]["inputs"]], round(r["y"]["inputs"][0]["slope"], 6), round(r["y"]["r2"], 6)
    (['b', 'a'], 3.0, 1.0)
    """
    if method not in SENSITIVITY:
        raise InputError("uncertainty.sensitivity", method, f"one of {', '.join(SENSITIVITY)}")
    keys = list(outputs)
    if not keys:
        return {}
    names = [i.address for i in inputs]
    Y = np.column_stack([np.asarray(outputs[k], float) for k in keys])
    ok = np.isfinite(Y).all(axis=1)
    if ok.sum() < 3:
        return {}
    Xk, Yk = np.asarray(X, float)[ok], Y[ok]
    n = Xk.shape[0]
    Zx, sx = _std(Xk)
    Zy, sy = _std(Yk)
    live = sx > 0
    SRC = np.zeros((len(names), len(keys)))
    r2 = [None] * len(keys)
    if n >= 2 * (live.sum() + 1):           # at least two samples per coefficient
        beta = np.linalg.lstsq(Zx[:, live], Zy, rcond=None)[0]
        SRC[live] = beta
        res = np.sum((Zy - Zx[:, live] @ beta) ** 2, axis=0)
        r2 = [float(1.0 - r / n) if s > 0 else None for r, s in zip(res, sy)]
    Rx, _ = _std(np.column_stack([stats.rankdata(c) for c in Xk.T]) if Xk.shape[1] else Xk)
    Ry, _ = _std(np.column_stack([stats.rankdata(c) for c in Yk.T]))
    RHO = np.where(live[:, None], Rx.T @ Ry / n, 0.0)
    SLOPE = np.where(live[:, None], SRC * sy[None, :] / np.where(live, sx, 1.0)[:, None], 0.0)
    out = {}
    for j, key in enumerate(keys):
        if sy[j] == 0:
            continue                      # a fixed output (e.g. an imposed node): nothing to rank
        rows = [{"address": a, "src": float(SRC[k, j]), "slope": float(SLOPE[k, j]), "spearman": float(RHO[k, j])}
                for k, a in enumerate(names)]
        if method == "sobol":
            for row, s1 in zip(rows, _rbd_fast(names, Xk, Yk[:, j], live)):
                row["S1"] = float(s1)
        order = "S1" if method == "sobol" else ("src" if r2[j] is not None else "spearman")
        rows.sort(key=lambda e: -abs(e[order]))
        out[key] = {"method": method, "r2": r2[j], "ranked_by": order, "inputs": rows}
    return out


def _rbd_fast(names, X, y, live):
    """First-order Sobol' indices by RBD-FAST on given samples (SALib, optional)."""
    try:
        from SALib.analyze import rbd_fast          # noqa: PLC0415  (optional dependency)
    except ImportError:
        raise InputError("uncertainty.sensitivity", "sobol", "needs SALib (pip install thermobear[sensitivity]); "
                         "or use the default \"src\"") from None
    S1 = np.zeros(len(names))
    idx = np.flatnonzero(live)
    if idx.size and np.ptp(y) > 0:
        problem = {"num_vars": idx.size, "names": [names[k] for k in idx],
                   "bounds": [[float(X[:, k].min()), float(X[:, k].max())] for k in idx]}
        S1[idx] = np.asarray(rbd_fast.analyze(problem, X[:, idx], y, print_to_console=False)["S1"], float)
    return S1


def summary_lines(res, top: int = 8) -> list:
    """The text table of an :class:`~thermobear.coupled.uncertainty.UncertaintyResult`: the bands of
    every node temperature, the power and its breakdown (at the last output time of a heat-up), the
    failed samples, and the inputs ranked for the power and the result's ``focus`` nodes."""
    last = (lambda v: v if np.ndim(v) == 0 else v[-1])  # noqa: E731
    nom = res.nominal
    t = "" if res.t_s is None else f" at t = {res.t_s[-1]:g} s"
    grouped = "bearing geometry" + (" and network-builder estimates" if any(
        i.address.startswith("builder.") for i in res.inputs) else "")
    lines = [f"Uncertainty: {res.n} samples ({'Latin hypercube' if res.method == 'lhs' else 'scrambled Sobol'}, "
             f"seed {res.seed}; {len(res.inputs)} estimated inputs; {grouped} in {res.groups} "
             f"famil{'y' if res.groups == 1 else 'ies'}){t}", "",
             f"  {'':26s} {'nominal':>9s} {'p5':>9s} {'p50':>9s} {'p95':>9s}"]
    for key, b in res.bands.items():
        kind, _, name = key.partition(".")
        unit = RATING_OUTPUTS.get(key) or ("°C" if kind == "T_C" else "W")
        v = res.nominal_values.get(key, _nominal_value(nom, key) if kind != "ratings" else None)
        f = ".4g" if key in RATING_OUTPUTS else ".2f"
        lines.append(f"  {(name or key) + ' [' + unit + ']':26s} {'' if v is None else f'{v:9{f}}':>9s} "
                     f"{last(b['p5']):9{f}} {last(b['p50']):9{f}} {last(b['p95']):9{f}}")
    fc = res.failed_count
    lines += ["", f"Failed samples: {len(res.failed)} of {res.n}" + (
        " (" + ", ".join(f"{k} {v}" for k, v in sorted(fc.items())) + ")" if fc else "")]
    for key in [k for k in ("P_W", *(f"T_C.{n}" for n in res.focus)) if k in res.sensitivity]:
        r = res.sensitivity[key]
        how = {"src": "standardised regression coefficient", "spearman": "rank correlation",
               "S1": "first-order Sobol index"}[r["ranked_by"]]
        r2 = "" if r["r2"] is None else f", R² {r['r2']:.2f}"
        lines += ["", f"Inputs ranked for {key} (by {how}{r2}" + ("; slope per draw unit)" if r2 else ")")]
        for e in r["inputs"][:top]:
            s1 = f"  S1 {e['S1']:6.3f}" if "S1" in e else ""
            reg = "" if r["r2"] is None else f"SRC {e['src']:+6.3f}  "
            slope = "" if r["r2"] is None else f"  slope {e['slope']:+.4g}"
            lines.append(f"  {e['address']:44s} {reg}rho {e['spearman']:+6.3f}{slope}{s1}")
        if r["r2"] is None:
            lines.append(f"  (fewer than two samples per input: ranked by rank correlation, no regression)")
    return lines


def _nominal_value(nom, key):
    """The nominal answer's value of an output (the last time of a heat-up)."""
    kind, _, name = key.partition(".")
    if kind == "T_C":
        v = nom.T_C.get(name)
    elif kind == "P_W":
        v = nom.P_W
    else:
        v = nom.breakdown_W.get(name)          # the answer's own breakdown (blended where the answer is)
    if v is None:
        return None
    return float(np.ravel(v)[-1])
