r"""Bands and sensitivity ranking of sampled predictions (:mod:`thermobear.coupled.uncertainty`).

Bands: the 5, 50 and 95 % quantiles of each output over the samples that solved.

Ranking of the inputs, for each output y over the draws X (n samples × d inputs):

* ``"src"`` (default, numpy / scipy): the standardised regression coefficients of the linear
  least-squares fit of y on X,

  .. math:: \frac{y - \bar y}{s_y} = \sum_j \mathrm{SRC}_j \frac{x_j - \bar x_j}{s_{x_j}} + \varepsilon,

  with its R²; when R² is near 1, SRC_j² is input j's share of the variance of y (Saltelli et al.
  2008, *Global Sensitivity Analysis: The Primer*, §1.2.5).  Each entry also has the slope
  ∂y/∂x_j = SRC_j s_y / s_{x_j} (output unit per draw unit: per factor, per K of offset …) and
  Spearman's rank correlation (monotonic, not only linear, dependence).
* ``"sobol"``: first-order Sobol' indices S1 estimated on the same samples by RBD-FAST (Tarantola,
  Gatelli & Mara 2006; Plischke 2010), from the optional SALib (``pip install thermobear[sensitivity]``);
  the SRC entries are kept beside them.

The regression is trusted only where the draws determine it (:func:`regression_check`); otherwise its
coefficients are withheld (``src``, ``slope`` and ``r2`` None), the inputs are ranked by |rank
correlation| (or S1) and every output's ranking carries the named caveat ``UnreliableRegression`` with
its reasons (``caveat``; None for a trusted regression).  Inputs whose draws do not vary (a zero-width
range) get zero.
"""
from __future__ import annotations

import numpy as np

from thermobear.coupled.ratings import PRELOAD_OUTPUTS, RATING_OUTPUTS
from thermobear.errors import InputError
from thermobear.lazy import lazy_module

stats = lazy_module("scipy.stats")          # rankdata: loaded by the first ranking

__all__ = ["bands", "ranking", "regression_check", "SENSITIVITY", "CAVEAT", "DRAWS_PER_COEFFICIENT", "VIF_MAX"]

SENSITIVITY = ("src", "sobol")
#: the name of the caveat of a ranking whose regression the draws do not determine
CAVEAT = "UnreliableRegression"
#: distinct draws a regression needs per coefficient (intercept included; Austin & Steyerberg 2015)
DRAWS_PER_COEFFICIENT = 2
#: the largest variance inflation factor of a trusted regression (Marquardt 1970; Kutner et al. 2005 §10.5)
VIF_MAX = 10.0


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


def regression_check(levels, X, names=None) -> dict | None:
    r"""Whether the draws determine the regression of the ranking: None when they do, else the caveat.

    Two criteria, both on the draws X alone (the same for every output):

    * **Distinct draws per coefficient.**  An input drawn per family (``level = "family"``: the bearing
      geometry, a built network's estimates) takes only as many distinct values as there are families;
      its coefficients are fitted to those m distinct rows, with the intercept p + 1 coefficients for p
      such inputs (the point-level regression: all d inputs and the intercept on the n samples).  Each
      level needs at least :data:`DRAWS_PER_COEFFICIENT` = 2 distinct draws per coefficient,
      m >= 2 (p + 1): the fewest with which least-squares coefficients are estimated without material
      bias (Austin & Steyerberg 2015).  Fewer leave about one residual degree of freedom: the fit
      passes through the family means, noise included (R² near 1, coefficients of either sign).
    * **Collinearity.**  The variance inflation factors of the standardised draws,
      :math:`\mathrm{VIF}_j = [R^{-1}]_{jj}` with R their correlation matrix, the factor by which
      collinearity inflates the variance of coefficient j; the largest must not exceed :data:`VIF_MAX` = 10
      (Marquardt 1970; Kutner et al. 2005 §10.5).  A rank-deficient R (an input a combination of others)
      determines no coefficient at all.

    A sign of SRC opposite to the rank correlation's, or |SRC| > 1, are the symptoms of these causes, not
    criteria of their own (a small coefficient of either measure is noise; an output not monotonic in an
    input may have them legitimately).  Under the caveat the inputs are ranked by Spearman's rank
    correlation, a marginal measure that needs no regression; on m distinct draws it has (without ties)
    the null standard deviation :math:`1/\sqrt{m-1}`, so |ρ| < 1.96 / √(m − 1) is not distinguishable from
    zero at 95 % (Kendall & Gibbons 1990).

    Parameters
    ----------
    levels : sequence of str   each varying input's level (``"point"`` or ``"family"``)
    X : ndarray                (n, p) draws of the varying inputs (units of each input's draw)
    names : sequence of str    the inputs' addresses (default their column numbers)

    Returns
    -------
    dict or None
        ``name`` (:data:`CAVEAT`), ``reasons`` (codes: ``too_few_draws``, ``rank_deficient``,
        ``collinear``), ``message`` (one line), ``levels`` (level → ``inputs``, ``coefficients`` fitted
        on its draws, distinct ``draws``, ``needed`` draws), ``max_vif`` (None when rank-deficient),
        ``max_vif_input`` (its name), ``rho_zero`` (the |ρ| not distinguishable from 0 on the fewest
        draws), ``rho_draws`` and ``rho_level`` (those draws and their level).

    References
    ----------
    Austin P. C., Steyerberg E. W. (2015) The number of subjects per variable required in linear
    regression analyses. *J. Clin. Epidemiol.* 68(6), 627–636.
    Marquardt D. W. (1970) Generalized inverses, ridge regression, biased linear estimation, and
    nonlinear estimation. *Technometrics* 12(3), 591–612.
    Kutner M. H., Nachtsheim C. J., Neter J., Li W. (2005) *Applied Linear Statistical Models*, 5th ed.,
    McGraw-Hill.
    Kendall M. G., Gibbons J. D. (1990) *Rank Correlation Methods*, 5th ed., Edward Arnold.

    >>> rng = np.random.default_rng(0)
    >>> regression_check(["point"] * 2, rng.random((50, 2))) is None
    True
    >>> fam = rng.random((6, 4))[rng.integers(0, 6, 50)]           # 4 inputs drawn per family, 6 families
    >>> c = regression_check(["family"] * 4, fam)
    >>> c["reasons"], c["levels"]["family"]
    (['too_few_draws', 'collinear'], {'inputs': 4, 'coefficients': 5, 'draws': 6, 'needed': 10})
    """
    X = np.asarray(X, float)
    n, p = X.shape
    if p == 0:
        return None
    names = [str(k) for k in range(p)] if names is None else list(names)
    lv = np.asarray(levels, dtype=object)
    found, why = {}, []
    for level in dict.fromkeys(lv):
        cols = lv == level
        k = p if level == "point" else int(cols.sum())         # the point-level fit holds every coefficient
        m = n if level == "point" else len(np.unique(X[:, cols], axis=0))
        found[level] = {"inputs": int(cols.sum()), "coefficients": k + 1, "draws": m,
                        "needed": DRAWS_PER_COEFFICIENT * (k + 1)}
        if m < found[level]["needed"]:
            whose = (f"{k} inputs and the intercept) on {n} samples" if level == "point" else
                     f"{k} {level}-level inputs and the intercept) on their {m} distinct draws")
            why.append(f"{k + 1} coefficients ({whose}, fewer than {DRAWS_PER_COEFFICIENT} per coefficient "
                       f"({found[level]['needed']})")
    reasons = ["too_few_draws"] if why else []
    Z, _ = _std(X)
    R = Z.T @ Z / max(n, 1)
    ev = np.linalg.eigvalsh(R)
    vif = name = None
    if p >= n or ev.min() <= 1e-10 * ev.max():
        reasons.append("rank_deficient")
        why.append(f"the draws' correlation matrix is rank-deficient (rank {np.linalg.matrix_rank(R)} of {p})")
    else:
        v = np.diag(np.linalg.inv(R))
        vif, name = float(v.max()), names[int(np.argmax(v))]
        if vif > VIF_MAX:
            reasons.append("collinear")
            why.append(f"largest variance inflation factor {vif:.3g} ({name}) > {VIF_MAX:g}")
    if not reasons:
        return None
    fewest = min(found, key=lambda k: found[k]["draws"])
    m = found[fewest]["draws"]
    rho0 = 1.96 / np.sqrt(m - 1) if m > 1 else None
    return {"name": CAVEAT, "reasons": reasons, "message": "; ".join(why), "levels": found, "max_vif": vif,
            "max_vif_input": name, "rho_zero": None if rho0 is None else float(rho0), "rho_draws": m,
            "rho_level": fewest}


def _caveat(check, method):
    """The caveat of :func:`regression_check` worded for a ranking: what is withheld, what ranks instead."""
    if check is None:
        return None
    fam = check["levels"].get("family")
    hint = (f"; {fam['needed']} groups (and at least as many samples) would determine the family level"
            if fam and fam["draws"] < fam["needed"] else "")
    rank = "ranked by rank correlation" if method == "src" else "ranked by S1"
    band = (f"; a {check['rho_level']}-level |rho| < {check['rho_zero']:.2f} is not distinguishable from 0 at 95 % "
            f"({check['rho_draws']} draws)" if check["rho_zero"] is not None else "")
    return {**check, "message": f"{check['message']}: SRCs withheld, {rank}{band}{hint}"}


def ranking(inputs, X, outputs: dict, method: str = "src") -> dict:
    """Output → ``{"method", "r2", "ranked_by", "caveat", "inputs": [{"address", "src", "slope", "spearman"[, "S1"]},
    ...]}``, the inputs sorted by importance (module docstring); outputs given per sample (n,), NaN where a
    sample failed (those samples are left out).  One least-squares solve for all outputs, when
    :func:`regression_check` trusts it; else ``src``, ``slope`` and ``r2`` are None, the inputs ranked by
    |rank correlation| (or S1) and ``caveat`` says why (the same for every output: the draws decide).

    >>> rng = np.random.default_rng(0)
    >>> X = rng.random((200, 2))
    >>> r = ranking([type("I", (), {"address": a})() for a in "ab"], X, {"y": 3 * X[:, 1] + 0.1 * X[:, 0]})
    >>> [e["address"] for e in r["y"]["inputs"]], round(r["y"]["inputs"][0]["slope"], 6), round(r["y"]["r2"], 6)
    (['b', 'a'], 3.0, 1.0)
    >>> r["y"]["caveat"] is None
    True
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
    idx = np.flatnonzero(live)
    caveat = _caveat(regression_check([getattr(inputs[k], "level", "point") for k in idx], Xk[:, live],
                                      [names[k] for k in idx]), method)
    SRC = np.zeros((len(names), len(keys)))
    r2 = [None] * len(keys)
    if caveat is None:
        beta = np.linalg.lstsq(Zx[:, live], Zy, rcond=None)[0]
        SRC[live] = beta
        res = np.sum((Zy - Zx[:, live] @ beta) ** 2, axis=0)
        r2 = [float(1.0 - r / n) if s > 0 else None for r, s in zip(res, sy)]
    Rx, _ = _std(np.column_stack([stats.rankdata(c) for c in Xk.T]) if Xk.shape[1] else Xk)
    Ry, _ = _std(np.column_stack([stats.rankdata(c) for c in Yk.T]))
    RHO = np.where(live[:, None], Rx.T @ Ry / n, 0.0)
    SLOPE = np.where(live[:, None], SRC * sy[None, :] / np.where(live, sx, 1.0)[:, None], 0.0)
    reg = (lambda v: float(v) if caveat is None else None)  # noqa: E731   (withheld: None, never a false 0)
    out = {}
    for j, key in enumerate(keys):
        if sy[j] == 0:
            continue                      # a fixed output (e.g. an imposed node): nothing to rank
        rows = [{"address": a, "src": reg(SRC[k, j]), "slope": reg(SLOPE[k, j]), "spearman": float(RHO[k, j])}
                for k, a in enumerate(names)]
        if method == "sobol":
            for row, s1 in zip(rows, _rbd_fast(names, Xk, Yk[:, j], live)):
                row["S1"] = float(s1)
        order = "S1" if method == "sobol" else ("src" if caveat is None else "spearman")
        rows.sort(key=lambda e: -abs(e[order]))
        out[key] = {"method": method, "r2": r2[j], "ranked_by": order, "caveat": caveat, "inputs": rows}
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
             ""]
    rows, outside = [], 0
    for key, b in res.bands.items():
        kind, _, name = key.partition(".")
        design = RATING_OUTPUTS.get(key) or PRELOAD_OUTPUTS.get(key)
        unit = design or ("°C" if kind == "T_C" else "W")
        v = res.nominal_values.get(key, _nominal_value(nom, key) if not design else None)
        f = ".4g" if design else ".2f"
        lo, hi = last(b["p5"]), last(b["p95"])
        out = v is not None and bool(np.isfinite(lo) and np.isfinite(hi)) and not lo <= v <= hi
        outside += out
        label = key if key in PRELOAD_OUTPUTS else (name or key)
        rows.append((f"{label} [{unit}]", f"{'' if v is None else f'{v:9{f}}':>9s} "
                     f"{last(b['p5']):9{f}} {last(b['p50']):9{f}} {last(b['p95']):9{f}}" + ("  *" if out else "")))
    w = max([26] + [len(a) for a, _ in rows])
    lines[-1] = f"  {'':{w}s} {'nominal':>9s} {'p5':>9s} {'p50':>9s} {'p95':>9s}"
    lines += [f"  {a:{w}s} {b}" for a, b in rows]
    if outside:
        lines += ["", "  * nominal outside its 5-95 % band: the nominal inputs are not the middle of their ranges "
                  "(a one-sided range, e.g. an estimate at its range's end), or the output is not monotonic in them"]
    fc = res.failed_count
    lines += ["", f"Failed samples: {len(res.failed)} of {res.n}" + (
        " (" + ", ".join(f"{k} {v}" for k, v in sorted(fc.items())) + ")" if fc else "")]
    if any("Runaway" in k for k in fc):      # the hottest draws are the ones missing from the bands
        lines.append("  (samples that run away are not in the bands: their p95 understates those draws — a runaway "
                     "is the answer's upper end)")
    shown = [k for k in ("P_W", *(f"T_C.{n}" for n in res.focus), "preload.warm_N") if k in res.sensitivity]
    caveat = next((res.sensitivity[k]["caveat"] for k in shown if res.sensitivity[k].get("caveat")), None)
    if caveat:
        lines += ["", f"caveat: {caveat['name']}: {caveat['message']}"]
    for key in shown:
        r = res.sensitivity[key]
        how = {"src": "standardised regression coefficient", "spearman": "rank correlation",
               "S1": "first-order Sobol index"}[r["ranked_by"]]
        r2 = "" if r["r2"] is None else f", R² {r['r2']:.2f}"
        tail = "; slope per draw unit)" if r2 else ("; regression withheld: caveat above)" if r.get("caveat") else ")")
        lines += ["", f"Inputs ranked for {key} (by {how}{r2}" + tail]
        for e in r["inputs"][:top]:
            s1 = f"  S1 {e['S1']:6.3f}" if "S1" in e else ""
            reg = "" if r["r2"] is None else f"SRC {e['src']:+6.3f}  "
            slope = "" if r["r2"] is None else f"  slope {e['slope']:+.4g}"
            lines.append(f"  {e['address']:44s} {reg}rho {e['spearman']:+6.3f}{slope}{s1}")
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
