r"""Uncertainty of a prediction: the estimated inputs sampled, solved in batches, reported as bands.

Every estimated value of the data a scene uses carries its range (``uncertainty.<key>``, one syntax:
:func:`thermobear.schema.check_uncertainty`).  :func:`uncertain_inputs` collects them by address:

========================  ===========================================  =====================
address                   where the range lives                        how it varies
========================  ===========================================  =====================
``thermal.T_ambient_C``   the scene's sections ([operation],           per point (a scene number)
``lubricant.Rq_ball_um``  [lubricant] supply keys, [thermal])
``lubricant.<key>``       the lubricant's file (or inline table)       per point (:attr:`Family.lubricant`)
``nodes.<n>.<key>``,      the network file, next to the value          per point (the network's
``elements.<e>.<key>``                                                 ``sample`` context)
``materials.<m>.<key>``   the material file (k, ρ, c_p the network     per point (idem)
                          reads)
``builder.<key>``         ``materials/network_builders.toml`` (a       per **family** (see below)
                          network built from the scene's dimensions)
``bearing.<key>``         the bearing catalogue (or [bearing] table)   per **family** (see below)
========================  ===========================================  =====================

Ranges the thermal solution does not read are not sampled: a rig's inertia (``rig.J_kg_m2``, the
spin-down's), a bearing's load ratings (``C0_kN``, ``C_kN``: life and static safety), a friction input the
scene's models do not read (:func:`thermobear.model_inputs.unread_inputs`: ``mu_full_film`` under the Eyring
traction; the friction inputs and roughnesses on the SKF model).  The design answers of
a steady state vary with each sample's temperatures (and its bearing geometry, where C comes from it): their
bands (``ratings.*``: operating temperature, κ, a_ISO, L10m, operating clearance) come from
:func:`~thermobear.coupled.ratings.rating_samples`, the functions of the point's own ratings.

The samples are a Latin hypercube (default) or a scrambled Sobol' sequence of
:mod:`scipy.stats.qmc`, seeded: the same seed gives the same draws.  Each draw u ∈ (0, 1) becomes a
value by its input's distribution (:meth:`~thermobear.schema.Uncertainty.quantile`).  The sampled
operating points go through the batched solver (:func:`thermobear.coupled.steady.steady_states`) as
points of one family: the scene numbers as per-point scene values, the lubricant's and the network's
values as per-point draws (:attr:`Scene.samples`) that the lubricant (per-point properties) and the
network template (per-point conductances, capacities, fixed temperatures) apply.

The bearing's internal geometry (ball diameter, osculations, number of balls, clearance) cannot vary
within a family: the loads, contact ellipses and kinematics are solved for one bearing.  Nor can the
estimated constants of a network built from dimensions (:mod:`thermobear.thermal.builders.estimates`:
the seats' roughness, the microhardness and gas parameter of their joint conductance, the housing's
emissivity, the mounting joint, the rings' and cavity's fills): the builder computes the seats' joints
from them, spreads them over every cell of a face, and its discretisation rule reads them, so a draw
is a machine of its own, its network built again (a built network's one-element estimates — the
seal's rubber, the cage's pocket film — are element values and vary per point).  These inputs
are drawn at ``groups`` levels (a Latin hypercube of their own; default 8 groups, or 2 (d + 1) for d
family-level inputs when they are more than 3), and every sample is assigned to one group by a further
balanced column of the design: the samples form ``groups`` families of about n / groups points each.
Their sensitivities rest on those ``groups`` distinct geometries (more groups resolve them better, at one
load solve and one network template per group): the default 2 (d + 1) groups give each coefficient of the
ranking's regression two distinct draws, the least that determines it
(:func:`~thermobear.coupled.sensitivity.regression_check`); fewer given ``groups`` leave it undetermined, and
the ranking then withholds its coefficients with the caveat ``UnreliableRegression``.  (The default was d + 2,
one residual degree of freedom: a built network's 16 estimates ranked by noise.)

A sample whose solve fails (no equilibrium, thermal runaway, an input the models refuse) is counted
with its error's name (:attr:`UncertaintyResult.failed`), never dropped silently; the bands are those
of the samples that solved.  Bands and sensitivities: :mod:`thermobear.coupled.sensitivity`.
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass, field

import numpy as np

from thermobear.coupled.pipeline import Family, families, family_contacts, family_loads
from thermobear.coupled.preload import loaded_scene
from thermobear.coupled.ratings import PRELOAD_OUTPUTS, rating_samples
from thermobear.coupled.sampling import METHODS, Input, Samples, design, sample_scenes, uncertain_inputs
from thermobear.coupled.sensitivity import SENSITIVITY, bands, ranking, summary_lines
from thermobear.coupled.sources import family_network, loss_sources, prepared_for
from thermobear.coupled import steady as _steady
from thermobear.coupled import transient as _transient
from thermobear.coupled.steady import SteadyState, steady_states
from thermobear.coupled.transient import PointModel, heat_sources
from thermobear.errors import InputError, OutsideValidity, SolverError
from thermobear.parallel import check_processes, imap_unordered
from thermobear.models import plan_many
from thermobear.scene import Scene
from thermobear.thermal import solve_transient

__all__ = ["Input", "UncertaintyResult", "uncertain_inputs", "design", "sample_scenes", "steady_uncertainty",
           "transient_uncertainty", "steady_state", "transient", "steady_outputs", "METHODS"]

@dataclass
class UncertaintyResult:
    """Bands of a scene's prediction over its sampled uncertain inputs.

    Attributes
    ----------
    nominal : SteadyState or TransientRun   the nominal answer (inputs at their nominal values)
    inputs : list of Input                  the sampled inputs (columns of X)
    X : ndarray                             (n, d) draws
    outputs : dict                          output name (``T_C.<node>``, ``P_W``, ``breakdown_W.<k>``) →
                                            (n,) values of the samples (NaN where a sample failed), or
                                            (n, n_t) over the times ``t_s`` of a transient
    bands : dict                            output → dict(p5, p50, p95) (arrays over t_s for a transient)
    sensitivity : dict                      output → ranking of the inputs (:func:`~thermobear.coupled.sensitivity.ranking`)
    failed : dict                           sample index → error name and message
    n, seed, method, groups                 the sample design
    t_s : ndarray                           output times of a transient [s] (None for a steady state)
    focus : tuple                           nodes the text table ranks the inputs for (the rig's
                                            measured nodes, else the balls)
    nominal_values : dict                   output → the nominal answer's value, for the outputs the
                                            nominal answer does not hold itself (``ratings.*``)
    """

    nominal: object
    inputs: list
    X: np.ndarray
    outputs: dict
    bands: dict
    sensitivity: dict
    failed: dict
    n: int
    seed: object
    method: str
    groups: int
    sensitivity_method: str = "src"
    t_s: np.ndarray | None = None
    group: np.ndarray = field(default=None, repr=False)
    focus: tuple = ()
    nominal_values: dict = field(default_factory=dict)

    def summary(self, top: int = 8) -> str:
        """A text table: bands, failed samples, inputs ranked (:func:`~thermobear.coupled.sensitivity.summary_lines`)."""
        return "\n".join(summary_lines(self, top))

    @property
    def failed_count(self) -> dict:
        """Error name → number of samples it stopped."""
        out: dict = {}
        for v in self.failed.values():
            out[v["error"]] = out.get(v["error"], 0) + 1
        return out

    def as_dict(self) -> dict:
        """JSON-ready: the design, the inputs, the bands, the rankings and the failed samples."""
        arr = (lambda v: v.tolist() if isinstance(v, np.ndarray) else v)  # noqa: E731
        return {"design": {"n": self.n, "seed": self.seed, "method": self.method, "groups": self.groups,
                           "sensitivity": self.sensitivity_method},
                "inputs": [i.as_dict() for i in self.inputs],
                "bands": {k: {q: arr(v) for q, v in b.items()} for k, b in self.bands.items()},
                "nominal_values": dict(self.nominal_values),
                "t_s": arr(self.t_s),
                "sensitivity": self.sensitivity,
                "failed": {"count": len(self.failed), "by_error": self.failed_count,
                           "samples": {str(k): v for k, v in sorted(self.failed.items())}}}


def _focus(scene: Scene, nodes) -> tuple:
    """The rig's measured nodes (``[rig] map``), else the ball node."""
    mapped = tuple(dict.fromkeys(t for t in scene.rig_map.values() if t in nodes))
    return mapped or tuple(n for n in ("balls", "bearing") if n in nodes)[:1]


def _fail(exc) -> dict:
    """A failed sample's entry: its error's name and message (an entry already: as it is)."""
    return exc if isinstance(exc, dict) else {"error": type(exc).__name__, "message": str(exc)}


def steady_outputs(results, scenes=None) -> dict:
    """Output name → (n,) values of the samples' SteadyStates (NaN for a failed sample); with the samples'
    ``scenes`` also their design answers (:func:`~thermobear.coupled.ratings.rating_samples`: ``ratings.kappa``,
    ``ratings.L10m_h``, ``ratings.clearance_op_um``, …)."""
    ok = {i: r for i, r in enumerate(results) if isinstance(r, SteadyState)}
    if not ok:
        return {}
    loss = {i: r.breakdown_W for i, r in ok.items()}       # blended with P_W where a point is blended
    names = list(dict.fromkeys([f"T_C.{k}" for r in ok.values() for k in r.T_C] + ["P_W"]
                               + [f"breakdown_W.{k}" for b in loss.values() for k in b]))
    out = {k: np.full(len(results), np.nan) for k in names}
    for i, r in ok.items():
        for k, v in r.T_C.items():
            out[f"T_C.{k}"][i] = v
        out["P_W"][i] = r.P_W
        for k, v in loss[i].items():
            out[f"breakdown_W.{k}"][i] = float(v)
    if any(getattr(r, "preload", None) for r in ok.values()):   # a preloaded pair: its warm preload, a design answer
        out.update({k: np.full(len(results), np.nan) for k in PRELOAD_OUTPUTS})
        for i, r in ok.items():
            for k, v in preload_values(r).items():
                out[k][i] = v
    if scenes is not None:
        states = [r if isinstance(r, SteadyState) else None for r in results]
        out.update(rating_samples([loaded_scene(sc, r) for sc, r in zip(scenes, states)], states))
    return out


def preload_values(st: SteadyState) -> dict:
    """A preloaded pair's answers of :data:`PRELOAD_OUTPUTS` (output name → value in its unit: N, N/µm) of a solved
    point (none without a pair; NaN for a stiffness not evaluated)."""
    p = getattr(st, "preload", None)
    return {k: float(p.get(k.split(".", 1)[1], float("nan"))) for k in PRELOAD_OUTPUTS} if p else {}


def steady_uncertainty(scene: Scene, n: int, *, seed=None, method: str = "lhs", groups: int | None = None,
                       sensitivity: str = "src", tol_K: float = 1e-6, prepared=None, inputs=None,
                       nominal: SteadyState | None = None) -> UncertaintyResult:
    """The coupled steady state of a scene over ``n`` samples of its uncertain inputs.

    Parameters
    ----------
    scene : Scene           a scene with a thermal network (no prescribed temperature)
    n : int                 number of samples
    seed : int              seed of the design (the same seed gives the same samples)
    method : str            ``"lhs"`` (Latin hypercube) or ``"sobol"`` (scrambled Sobol')
    groups : int            bearing-geometry families (module docstring; default min(n, max(8, 2 (d + 1))),
                            d family-level inputs)
    sensitivity : str       ``"src"`` (standardised regression coefficients and rank correlations,
                            numpy / scipy) or ``"sobol"`` (first-order Sobol' indices by RBD-FAST on the
                            same samples; needs the optional SALib: ``pip install thermobear[sensitivity]``)
    tol_K, prepared         as :func:`~thermobear.coupled.steady.steady_states`
    inputs : list           the inputs to sample (default :func:`uncertain_inputs`)
    nominal : SteadyState   the nominal answer when already solved

    Returns
    -------
    UncertaintyResult

    >>> import thermobear as tb
    >>> r = steady_uncertainty(tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")), 16, seed=1)
    >>> b = r.bands["T_C.balls"]
    >>> bool(b["p5"] < r.nominal.T_C["balls"] < b["p95"]), len(r.failed)
    (True, 0)
    """
    nominal = nominal if nominal is not None else _steady.steady_state(scene, tol_K=tol_K, prepared=prepared)
    sm = _samples(scene, n, seed, method, groups, inputs, prepared, sensitivity)
    runnable = [k for k, s in enumerate(sm.scenes) if isinstance(s, Scene)]
    results: list = list(sm.scenes)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OutsideValidity)    # the samples' validity is the nominal's question
        for k, r in zip(runnable, _solve_split([sm.scenes[k] for k in runnable], tol_K, prepared)):
            results[k] = r
    failed = {k: _fail(r) for k, r in enumerate(results) if isinstance(r, Exception)}
    outputs = steady_outputs(results, sm.scenes)
    return UncertaintyResult(nominal=nominal, inputs=sm.inputs, X=sm.X, outputs=outputs, bands=bands(outputs),
                             sensitivity=ranking(sm.inputs, sm.X, outputs, sensitivity), failed=failed, n=sm.X.shape[0],
                             seed=seed, method=method, groups=sm.groups, sensitivity_method=sensitivity, group=sm.group,
                             focus=_focus(scene, nominal.T_C),
                             nominal_values={**{k: float(v[0]) for k, v in rating_samples([loaded_scene(scene, nominal)],
                                                                                         [nominal]).items()},
                                             **preload_values(nominal)})


def _solve_split(scenes, tol_K, prepared) -> list:
    """:func:`steady_states` of the samples; a drawn value the network refuses (e.g. a conductance
    drawn negative) stops its whole batch, so a refused batch is halved until that sample stands alone
    with its InputError."""
    try:
        return steady_states(scenes, tol_K=tol_K, prepared=prepared)
    except InputError as exc:
        if len(scenes) == 1:
            return [exc]
    h = len(scenes) // 2
    return _solve_split(scenes[:h], tol_K, prepared) + _solve_split(scenes[h:], tol_K, prepared)


def _samples(scene, n, seed, method, groups, inputs, prepared, sensitivity) -> Samples:
    if sensitivity not in SENSITIVITY:
        raise InputError("uncertainty.sensitivity", sensitivity, f"one of {', '.join(SENSITIVITY)}")
    if not isinstance(scene, Scene):
        raise InputError("scene", type(scene).__name__, "a thermobear Scene")
    if scene.network is None or scene.T_C is not None:
        raise InputError("uncertainty", n, "a scene solved on its thermal network (no operation.T_C): the bands are "
                         "those of the coupled steady state or heat-up")
    return sample_scenes(scene, n, seed=seed, method=method, groups=groups, inputs=inputs, prepared=prepared)


# --------------------------------------------------------------------------- heat-up
def _series(run) -> dict:
    """Output name → values over the run's times of a heat-up (a TransientRun): with a preloaded pair's
    (:mod:`thermobear.coupled.transient_pair`) its preload at the temperatures and the loaded bearing's axial load
    (:data:`~thermobear.coupled.ratings.PRELOAD_OUTPUTS`)."""
    pre = (getattr(run, "preload", None) or {}).get("series")
    return {**{f"T_C.{n}": v for n, v in run.T_C.items()}, "P_W": run.P_W,
            **{f"breakdown_W.{k}": v for k, v in run.breakdown_W.items()},
            **({"preload.warm_N": pre["preload_N"], "preload.Fa_N": pre["Fa_N"]} if pre else {})}


def _point_heatup(scene, t_end_s, t_eval, T0_C, rtol, atol, stop, boundary) -> dict:
    """One sampled point's heat-up (:func:`thermobear.coupled.transient.transient`, whose one-point family
    applies the draws; a point across a model switch blends its alternatives there, the film load model
    follows the film temperature, a preloaded pair's loads its preload): output name → (1, n_t)."""
    run = _transient.transient(scene, t_end_s, t_eval=t_eval, T0_C=T0_C, rtol=rtol, atol=atol, stop=stop,
                               boundary=boundary)
    if not run.completed:
        raise SolverError("the heat-up was stopped before its end")
    return {k: np.interp(t_eval, run.t_s, v)[None] for k, v in _series(run).items()}


def _family_heatup(fam: Family, t_end_s, t_eval, T0_C, rtol, atol, stop, boundary) -> dict:
    """One batched heat-up of the sampled points of a family (one model choice each): output name →
    (B, n_t)."""
    pre = prepared_for(fam.scene)
    contacts = family_contacts(fam, family_loads(fam))
    pm = PointModel(family=fam, network=family_network(fam, pre.template, contacts),
                    source=loss_sources(fam, contacts), coupling=pre.coupling)
    T0 = fam.values("T_ambient_C") if T0_C is None else T0_C       # each sample from its own ambient
    tr = solve_transient(pm.network, heat_sources(pm), t_end_s, T0_C=T0, t_eval=t_eval, rtol=rtol, atol=atol, stop=stop,
                         fixed_C=None if boundary is None else boundary.shifted(0.0))
    if not tr.completed:
        raise SolverError("the heat-up was stopped before its end")
    two = (lambda v: np.asarray(v, float).reshape(len(tr.t), -1).T)  # noqa: E731   (n_t[, B]) → (B, n_t)
    return {**{f"T_C.{n}": two(v) for n, v in tr.T_C.items()}, "P_W": two(tr.report["P_W"]),
            **{f"breakdown_W.{k[2:]}": two(v) for k, v in tr.report.items() if k.startswith("P_") and k != "P_W"}}


def _heatups(scenes, t_end_s, t_eval, T0_C, rtol, atol, stop, boundary):
    """The heat-ups of sampled points: (output name → (B, n_t), NaN where a point failed; point → its
    exception).  The points whose model choice has one alternative are integrated in batches, one per
    family of model choices (:func:`thermobear.thermal.solve_transient`, block-diagonal Jacobian); a
    point inside a model-switch band (its alternatives blended as stacked points of one source,
    :func:`~thermobear.coupled.transient.transient`) or on the film load model (its loads follow the film
    temperature along the run) or one bearing of a preloaded pair (its loads follow the pair's preload:
    :mod:`thermobear.coupled.transient_pair`) is integrated on its own.  A failing batch fails its points."""
    single, plans = [k for k, sc in enumerate(scenes) if sc.arrangement is None], [None] * len(scenes)
    for k, p in zip(single, plan_many([scenes[k] for k in single])):   # (a pair's bearing: no model choice for
        plans[k] = p                                                    # given loads, its heat-up alone)
    out, failed = {}, {}
    one = [k for k, a in enumerate(plans) if not (a is None or isinstance(a, Exception)) and len(a) == 1
           and a[0].models["load_model"][0] != "film"]
    failed.update({k: a for k, a in enumerate(plans) if isinstance(a, Exception)})
    fams, _ = families([scenes[k] for k in one], [(plans[k][0].models, plans[k][0].dry) for k in one])
    runs = [([one[j] for j in f.index], lambda f=f: _family_heatup(f, t_end_s, t_eval, T0_C, rtol, atol, stop,
                                                                   boundary)) for f in fams]
    runs += [([k], lambda k=k: _point_heatup(scenes[k], t_end_s, t_eval, T0_C, rtol, atol, stop, boundary))
             for k in range(len(scenes)) if k not in failed and k not in one]
    for idx, run in runs:
        try:
            series = run()
        except (InputError, SolverError) as exc:
            failed.update({k: exc for k in idx})
            continue
        for name, v in series.items():
            out.setdefault(name, np.full((len(scenes), t_eval.size), np.nan))[idx] = v
    return out, failed


def _group_heatups(job, stop=None) -> tuple:
    """One geometry group's heat-ups (:func:`_heatups`; in a worker process, or here with ``stop``): ``(group,
    series, failed entries)``."""
    g, scenes, t_end_s, t_eval, T0_C, rtol, atol, boundary = job
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OutsideValidity)
        series, bad = _heatups(scenes, t_end_s, t_eval, T0_C, rtol, atol, stop, boundary)
    return g, series, {j: _fail(e) for j, e in bad.items()}


def transient_uncertainty(scene: Scene, t_end_s: float, n: int, *, t_eval=None, seed=None, method: str = "lhs",
                          groups: int | None = None, sensitivity: str = "src", T0_C=None, rtol: float = 1e-5,
                          atol: float = 1e-3, stop=None, inputs=None, nominal=None, boundary=None,
                          processes: int = 1) -> UncertaintyResult:
    """The heat-up of a scene over ``n`` samples of its uncertain inputs: the samples integrated in
    batches (:func:`_heatups`: one per bearing-geometry group and model choice), bands over the output
    times.

    ``t_eval`` [s] the output times (default 50 points over [0, t_end_s]); ``boundary`` a logged boundary
    (:class:`~thermobear.thermal.solve.LinearBoundary`, measured: the same for every sample); the other
    parameters as :func:`steady_uncertainty` and :func:`thermobear.coupled.transient.transient` (no
    schedule: one operating point).  A batch whose integration fails counts all its samples as failed.  One
    bearing of a preloaded pair: each sample's heat-up on its own (the pieces of its preload,
    :mod:`thermobear.coupled.transient_pair`), with bands over its preload at the temperatures (``preload.warm_N``)
    and the loaded bearing's axial load (``preload.Fa_N``); a sample whose preload runs away counts as failed,
    named (ThermalPreloadRunaway).  ``processes`` > 1: the geometry groups' heat-ups in that many worker processes
    (:func:`thermobear.parallel.imap_unordered`; the same answers; a scene without family-level inputs has one group:
    one process); ``stop`` then acts between groups (the groups not run count as stopped samples; Ctrl-C ends the
    workers).
    """
    processes = check_processes(processes)
    t_eval = np.linspace(0.0, t_end_s, 51)[1:] if t_eval is None else np.asarray(t_eval, float)
    nominal = nominal if nominal is not None else _transient.transient(scene, t_end_s, t_eval=t_eval, T0_C=T0_C,
                                                                       rtol=rtol, atol=atol, stop=stop, boundary=boundary)
    if boundary is not None:            # the samples of the scene with the logged nodes imposed
        boundary, scene = _transient._imposed(boundary, scene, t_end_s)
    sm = _samples(scene, n, seed, method, groups, inputs, None, sensitivity)
    failed = {k: _fail(s) for k, s in enumerate(sm.scenes) if not isinstance(s, Scene)}
    outputs: dict = {}
    members = {g: idx for g in range(sm.groups)
               if (idx := [k for k in range(len(sm.scenes)) if sm.group[k] == g and k not in failed])}
    jobs = [(g, [sm.scenes[k] for k in idx], t_end_s, t_eval, T0_C, rtol, atol, boundary) for g, idx in members.items()]
    pending = set(members)
    for g, series, bad in (imap_unordered(_group_heatups, jobs, processes) if processes > 1 and len(jobs) > 1
                           else (_group_heatups(job, stop) for job in jobs)):     # (here: stop inside each run)
        pending.discard(g)
        idx = members[g]
        failed.update({idx[j]: _fail(e) for j, e in bad.items()})
        for name, v in series.items():
            outputs.setdefault(name, np.full((len(sm.scenes), t_eval.size), np.nan))[idx] = v
        if stop is not None and processes > 1 and pending and stop():      # (the workers end with the loop)
            failed.update({k: {"error": "SolverError", "message": "the heat-up was stopped before its end"}
                           for h in pending for k in members[h]})
            break
    return UncertaintyResult(nominal=nominal, inputs=sm.inputs, X=sm.X, outputs=outputs, bands=bands(outputs),
                             sensitivity=ranking(sm.inputs, sm.X, {k: v[:, -1] for k, v in outputs.items()}, sensitivity),
                             failed=failed, n=sm.X.shape[0], seed=seed, method=method, groups=sm.groups,
                             sensitivity_method=sensitivity, t_s=t_eval, group=sm.group, focus=_focus(scene, nominal.T_C),
                             nominal_values={k: float(np.interp(t_eval[-1], nominal.t_s, v))     # (a pair's preload)
                                             for k, v in _series(nominal).items() if k.startswith("preload.")})


# --------------------------------------------------------------------------- the public entry points
def steady_state(scene: Scene, *, uncertainty: int | None = None, seed=0, method: str = "lhs",
                 groups: int | None = None, sensitivity: str = "src", tol_K: float = 1e-6, load=None, prepared=None):
    """Coupled steady state of a scene (:func:`thermobear.coupled.steady.steady_state`); with
    ``uncertainty=N`` its bands over N samples of the estimated inputs (:func:`steady_uncertainty`,
    design ``method``, ``seed`` — default 0, so a run repeats —, ``groups``, ``sensitivity``).

    Returns a :class:`~thermobear.coupled.steady.SteadyState`, or with ``uncertainty`` an
    :class:`UncertaintyResult` whose ``nominal`` is the steady state.

    >>> import thermobear as tb
    >>> r = tb.steady_state(tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")), uncertainty=16)
    >>> r.n, r.seed, sorted(r.bands["P_W"])
    (16, 0, ['n', 'p5', 'p50', 'p95'])
    """
    if uncertainty is None:
        return _steady.steady_state(scene, tol_K=tol_K, load=load, prepared=prepared)
    if load is not None:
        raise InputError("load", "LoadDistribution", "injected loads hold one bearing: not with uncertainty (its "
                         "geometry is sampled)")
    return steady_uncertainty(scene, uncertainty, seed=seed, method=method, groups=groups, sensitivity=sensitivity,
                              tol_K=tol_K, prepared=prepared)


def transient(scene: Scene, t_end_s: float, *, uncertainty: int | None = None, seed=0, method: str = "lhs",
              groups: int | None = None, sensitivity: str = "src", schedule=None, T0_C=None, t_eval=None,
              rtol: float = 1e-5, atol: float = 1e-3, load=None, stop=None, prepared=None, boundary=None,
              processes: int = 1):
    """Heat-up of a scene (:func:`thermobear.coupled.transient.transient`); with ``uncertainty=N`` its
    bands over N samples of the estimated inputs (:func:`transient_uncertainty`; one operating point:
    no schedule, no injected loads; a logged ``boundary`` the same for every sample; ``processes`` worker processes
    for the samples' heat-ups).

    Returns a :class:`~thermobear.coupled.transient.TransientRun`, or with ``uncertainty`` an
    :class:`UncertaintyResult` whose ``nominal`` is the heat-up and whose bands run over ``t_s``.
    """
    if uncertainty is None:
        if check_processes(processes) != 1:
            raise InputError("processes", processes, "worker processes run the heat-ups of an uncertainty band: give "
                             "uncertainty=N, or processes=1 (one heat-up runs in this process)")
        return _transient.transient(scene, t_end_s, schedule=schedule, T0_C=T0_C, t_eval=t_eval, rtol=rtol, atol=atol,
                                    load=load, stop=stop, prepared=prepared, boundary=boundary)
    if schedule or load is not None:
        raise InputError("schedule" if schedule else "load", "given", "a heat-up with uncertainty runs one operating "
                         "point: no schedule, no injected loads")
    return transient_uncertainty(scene, t_end_s, uncertainty, t_eval=t_eval, seed=seed, method=method, groups=groups,
                                 sensitivity=sensitivity, T0_C=T0_C, rtol=rtol, atol=atol, stop=stop, boundary=boundary,
                                 processes=processes)
