r"""Sweeps: one scene over a grid of operating points, solved in batches.

:func:`run_sweep` takes a scene and a grid ``{override: [values, ...]}`` whose keys are
:meth:`thermobear.scene.Scene.with_` overrides (``n_rpm``, ``Fa``, ``Fr``, ``M``, ``T_C``,
``T_oil_in_C``, ``T_ambient_C``, ``oil_flow_L_h``, ``lubricant``, ...).  It runs the Cartesian
product of the values (first key slowest) and returns one row per point, in grid order.

Two kinds of points:

* **prescribed temperature** (the point has ``T_C``): no thermal network; the points that share
  everything but speed and temperature are computed in one vectorised loss evaluation
  (:func:`thermobear.coupled.scene_losses`) with their loads solved in one batched call.
* **coupled** (no ``T_C``): :func:`thermobear.coupled.steady_states` in chunks — each chunk's points
  grouped into families and solved together (stacked Newton, batched loads, one network at all of
  a family's points) — in this process, in local worker processes (``processes``), or on a Dask
  cluster (``scheduler``).

Rows are handed to ``on_row(index, row)`` as their chunk finishes (the command line writes them
then, flushed), so an interrupted sweep keeps every finished row.  A point whose solution fails
(:class:`~thermobear.errors.ThermalRunaway`, :class:`~thermobear.errors.NoConvergence`, a load the
contacts cannot carry, ...) does not stop the sweep: its row says so (``status`` = the error class,
``reason``, ``iterations``) and carries no power — never a silent or NaN result.  Bad overrides
raise :class:`~thermobear.errors.InputError` before anything runs.

Each row holds the grid values and ``P_W`` [W], ``torque_Nm`` [N m], ``breakdown_W`` (loss family
→ W), ``temperatures_C`` (node → °C; prescribed points: ``{"contacts (prescribed)": T}``),
``T_ball_C`` (coupled points), ``models`` (sub-model → choice), ``status`` ("ok" or the error
class), ``reason``, ``iterations``, ``residual_K`` and ``warnings`` (the OutsideValidity messages);
and the ratings `run` gives at their temperatures, ``L10m_h`` [h], ``kappa`` [-], ``s0`` [-] and
``clearance_operating_um`` [µm], with the ratings' warnings (a clearance consumed into a preload, a low κ, a load
below the minimum); a preloaded pair's coupled rows ``preload_cold_N`` and ``preload_warm_N`` [N] and the warm pair's
stiffness ``k_axial_warm_N_um``, ``k_radial_warm_N_um`` [N/µm], ``k_tilt_warm_Nm_mrad`` [N m/mrad]
(:data:`PAIR_STIFFNESS_COLUMNS`).
"""
from __future__ import annotations

import itertools

import numpy as np

from thermobear.coupled import prepare, scene_losses, steady_states
from thermobear.coupled.pipeline import scene_load
from thermobear.errors import InputError, SolverError
from thermobear.loads.highspeed import load_distribution_high_speed
from thermobear.arrays import take
from thermobear.coupled.limits import family_warnings
from thermobear.coupled.pipeline import film_scene_load
from thermobear.coupled.preload import loaded_scene
from thermobear.coupled.ratings import scene_ratings_many
from thermobear.coupled.run import Prescribed
from thermobear.models import moments, plan, plan_many
from thermobear.parallel import check_processes, imap_unordered
from thermobear.scene import Scene

__all__ = ["run_sweep", "sweep_points", "CHUNK", "PAIR_STIFFNESS_COLUMNS"]

_VECTOR_KEYS = ("n_rpm", "T_C")          # vectorised inside one scene_losses call
#: a preloaded pair's stiffness columns (its answer's ``preload`` keys: warm, at the point's speed) [N/µm, N m/mrad]
PAIR_STIFFNESS_COLUMNS = ("k_axial_warm_N_um", "k_radial_warm_N_um", "k_tilt_warm_Nm_mrad")
CHUNK = 256                              #: most coupled points solved together (rows stream out per chunk)


def sweep_points(grid: dict) -> list[dict]:
    """The Cartesian product of a grid as a list of override dicts (first key slowest).

    >>> sweep_points({"n_rpm": [1000, 2000], "T_C": [40.0, 60.0]})[1]
    {'n_rpm': 1000, 'T_C': 60.0}
    """
    if not isinstance(grid, dict) or not grid:
        raise InputError("grid", grid, "a non-empty dict {override: [values, ...]}")
    vals = []
    for k, v in grid.items():
        v = list(v) if isinstance(v, (list, tuple, np.ndarray, range)) else [v]
        if not v:
            raise InputError(f"grid.{k}", v, "at least one value")
        vals.append(v)
    return [dict(zip(grid, combo)) for combo in itertools.product(*vals)]


def _choices(models: dict) -> dict:
    return {k: v[0] for k, v in models.items() if k != "node_roles"}


def _base_row(point: dict) -> dict:
    return {k: (float(v) if isinstance(v, (int, float, np.number)) and not isinstance(v, bool) else v)
            for k, v in point.items()}


def _row(point: dict, sc: Scene, st=None, exc=None, rated=None) -> dict:
    """A coupled point's row from its steady state and its ratings (``rated``: :func:`_ratings_of`'s), or from the
    error that stopped it."""
    row = _base_row(point)
    if exc is not None:
        try:
            models = _choices(plan(sc)[0])
        except (InputError, SolverError):
            models = {}
        row.update(P_W=None, torque_Nm=None, breakdown_W={}, temperatures_C={}, models=models,
                   status=type(exc).__name__, reason=" ".join(str(getattr(exc, "reason", exc)).split()),
                   iterations=getattr(exc, "iterations", None), residual_K=_finite_or_none(getattr(exc, "residual", None)),
                   warnings=[])
        return row
    row.update(P_W=float(st.P_W), torque_Nm=float(st.torque_Nm), breakdown_W=dict(st.breakdown_W),
               temperatures_C={k: float(v) for k, v in st.T_C.items()}, T_ball_C=float(st.T_ball_C),
               models=_choices(st.models_used), status="ok", reason=str(st.models_used["thermal"][1]),
               iterations=int(st.iterations), residual_K=float(st.residual_K),
               warnings=[str(w) for w in st.warnings])
    row.update(_ratings_columns(sc, rated, row["warnings"]))
    pre = getattr(st, "preload", None)                  # a preloaded pair: its warm preload at the point
    if pre:
        row.update(preload_cold_N=float(pre["cold_N"]), preload_warm_N=float(pre["warm_N"]),
                   **{k: _finite_or_none(pre.get(k)) for k in PAIR_STIFFNESS_COLUMNS})
    return row


def _ratings_of(scenes, states, losses=None) -> list:
    """The ratings of points as `run` gives them (:func:`~thermobear.coupled.ratings.scene_ratings_many` of the
    loaded scenes: a pair's loaded bearing under its loads; ``states``: SteadyStates, or
    :class:`~thermobear.coupled.run.Prescribed` temperatures with their ``losses``), or None for a point that has
    none (at rest): such a point is found alone, the others keep their batch."""
    try:
        return scene_ratings_many([loaded_scene(sc, st) for sc, st in zip(scenes, states)], states, losses)
    except InputError:
        if len(scenes) == 1:
            return [None]
    return [_ratings_of([sc], [st], None if losses is None else [losses[k]])[0]
            for k, (sc, st) in enumerate(zip(scenes, states))]


def _ratings_columns(sc: Scene, rt, warned: list) -> dict:
    """A row's ratings columns from its :class:`~thermobear.coupled.ratings.Ratings` ``rt`` (:func:`_ratings_of`;
    None: no ratings at rest, the row's answer stands without them): L10m [h], κ [-], s0 [-] and the operating
    clearance [µm] (None where they do not apply), and ``warnings`` with the ratings' own (viscosity ratio, static
    safety, minimum load, a clearance consumed into a radial preload) added."""
    if rt is None:
        return {"L10m_h": None, "kappa": None, "s0": None, "clearance_operating_um": None}
    c = rt.clearance_um
    return {"L10m_h": _finite_or_none(rt.L10m_h), "kappa": _finite_or_none(rt.kappa), "s0": _finite_or_none(rt.s0),
            "clearance_operating_um": (_finite_or_none(c.get("operating")) if c.get("applies", True)
                                       and sc.bearing.kind == "deep_groove" else None),   # (an angular contact
            # bearing's "clearance" is the play its contact angle implies: run's note says so, a column would not)
            "warnings": list(dict.fromkeys(warned + [str(w) for w in rt.warnings]))}


def _finite_or_none(v):
    return float(v) if isinstance(v, (int, float, np.floating)) and np.isfinite(v) else None


def _solve_chunk(scene: Scene, points: list, scenes: list | None = None, prepared=None) -> list:
    """Rows of a chunk of coupled points (runs in this process, a worker process or on Dask); ``scenes``:
    the points' scenes when this process has built them already; ``prepared``: the base scene's
    :func:`~thermobear.coupled.prepare`, for the points it serves."""
    if scenes is None:
        scenes = [scene.with_(**p) for p in points]
    res = steady_states(scenes, prepared=prepared)
    ok = [k for k, r in enumerate(res) if not isinstance(r, Exception)]
    rated = dict(zip(ok, _ratings_of([scenes[k] for k in ok], [res[k] for k in ok])))
    return [_row(p, sc, exc=r) if isinstance(r, Exception) else _row(p, sc, st=r, rated=rated[k])
            for k, (p, sc, r) in enumerate(zip(points, scenes, res))]


def _prepared(scene: Scene):
    """The base scene's network template and coupling, prepared once for every chunk this process solves (None
    where the scene cannot be prepared: each point then says why)."""
    try:
        return prepare(scene)
    except InputError:
        return None


def _losses_batch(sc: Scene, n_rpm, T_C, models: dict, load=None):
    """Local losses of one group of prescribed points, vectorised over speed and temperature [W]."""
    return scene_losses(sc, T_C=np.asarray(T_C, float), models=models, n_rpm=np.asarray(n_rpm, float),
                        load=scene_load(sc, models) if load is None else load)


def _prescribed_group(scenes, points, models, members, dry=None):
    """Rows of one group of prescribed-temperature points (one vectorised loss evaluation); ``dry``: point → its dry
    load distribution (a preload by the films of the film load model is named)."""
    sc = scenes[members[0]]
    n = np.array([scenes[i].n_rpm for i in members], float)
    T = np.array([scenes[i].T_C for i in members], float)
    if models["losses"][0] != "local":                    # SKF global model: vectorised over the points
        r = scene_losses(sc, T_C=T, models=models, n_rpm=n)
    else:
        load = None
        if models["load_model"][0] == "film":   # loads depend on speed and film temperature: one batched solve
            load = film_scene_load(sc, models, T, n_rpm=n)
        elif models["high_speed"][0] == "yes":   # high-speed ball loads depend on speed: one batched solve
            n_u, back = np.unique(n, return_inverse=True)
            M, My = moments(sc)
            load = take(load_distribution_high_speed(sc.bearing, Fa=sc.Fa, Fr=sc.Fr, M=M, Fz=sc.Fz, My=My, n_rpm=n_u,
                                                     stiffness=sc.models.get("stiffness", "nominal"),
                                                     control=models["kinematics"][0]),
                        back, n_u.size)
        r = _losses_batch(sc, n, T, models, load=load)
    P, M = np.atleast_1d(r.P_W), np.atleast_1d(r.torque_Nm)
    bd = {k: np.broadcast_to(np.atleast_1d(v), P.shape) for k, v in r.breakdown_W.items()}
    # each point's validity, as `run` states it for a prescribed temperature (coupled.limits.point_warnings)
    film = models["load_model"][0] == "film" and dry is not None and models["losses"][0] == "local"
    warned = family_warnings([scenes[i] for i in members], r, np.repeat(T[:, None], 3, axis=1),
                             dry=[dry.get(i) for i in members] if film else None)
    rows = {}
    rated = _ratings_of([scenes[i] for i in members], [Prescribed(float(t)) for t in T],
                        [take(r, j, len(members)) if P.size == len(members) else r for j in range(len(members))])
    for j, i in enumerate(members):
        row = _base_row(points[i])
        row.update(P_W=float(P[j]), torque_Nm=float(M[j]), breakdown_W={k: float(v[j]) for k, v in bd.items()},
                   temperatures_C={"contacts (prescribed)": float(T[j])}, models=_choices(models), status="ok",
                   reason="", iterations=0, residual_K=0.0, warnings=[str(w) for w in warned[j]])
        row.update(_ratings_columns(scenes[i], rated[j], row["warnings"]))
        rows[i] = row
    return rows


def _prescribed(scenes, points, idx, emit):
    """Rows of the prescribed-temperature points, by groups of one vectorised evaluation; a point in a
    switch band (:data:`thermobear.models.BLEND_BANDS`) is evaluated with each alternative and its row
    is their blend."""
    groups: dict = {}
    for i, alts in zip(idx, plan_many([scenes[i] for i in idx])):
        if isinstance(alts, Exception):
            emit(i, _row(points[i], scenes[i], exc=alts))
            continue
        for a in alts:
            key = (tuple((k, repr(v)) for k, v in points[i].items() if k not in _VECTOR_KEYS),
                   tuple(sorted((k, repr(v[0])) for k, v in a.models.items() if k != "thermal")))
            groups.setdefault(key, (a.models, []))[1].append((i, a.weight, a.dry))
    parts: dict = {}
    for models, members in groups.values():
        ids = [i for i, _, _ in members]
        dry = {i: d for i, _, d in members}
        try:
            rows = _prescribed_group(scenes, points, models, ids, dry)
        except (SolverError, InputError):     # each point alone: a failure stays on its own row
            rows = {}
            for i in ids:
                try:
                    rows.update(_prescribed_group(scenes, points, models, [i], dry))
                except (SolverError, InputError) as exc:
                    rows[i] = _row(points[i], scenes[i], exc=exc)
        for i, w, _ in members:
            parts.setdefault(i, []).append((w, rows[i]))
    for i in sorted(parts):
        emit(i, _blend_rows(parts[i]))


def _blend_rows(parts) -> dict:
    """One row from the rows of a point's model alternatives (weights sum to 1): power, torque and
    breakdown weighted (:mod:`thermobear.coupled.blend`); a failed alternative leaves the others."""
    if len(parts) == 1:
        return parts[0][1]
    ok = [(w, r) for w, r in parts if r["status"] == "ok"]
    if not ok:
        return max(parts, key=lambda p: p[0])[1]
    total = sum(w for w, _ in ok)
    ok = [(w / total, r) for w, r in ok]
    row = dict(max(ok, key=lambda p: p[0])[1])
    row["warnings"] = list(dict.fromkeys(w for _, r in ok for w in r["warnings"]))   # every alternative's, as steady
    keys = list(dict.fromkeys(k for _, r in ok for k in r["breakdown_W"]))
    row.update(P_W=sum(w * r["P_W"] for w, r in ok), torque_Nm=sum(w * r["torque_Nm"] for w, r in ok),
               breakdown_W={k: sum(w * r["breakdown_W"].get(k, 0.0) for w, r in ok) for k in keys},
               reason="blend of " + " + ".join(f"{w:.3f} × ({r['models'].get('high_speed')}, "
                                               f"{r['models'].get('load_model')})" for w, r in ok))
    if len(ok) < len(parts):
        row["warnings"] = list(row["warnings"]) + ["model blend: an alternative across a model switch failed; "
                                                   "the answer is that of the others and may step here"]
    return row


def _chunk_job(args):
    scene, idx, points = args
    return idx, _solve_chunk(scene, points)


def _chunks(idx, processes):
    """Chunks of points solved together: large enough to batch well (≥ 16 points; a chunk's load solves,
    Newton iterations and film rounds cost per call: 4 chunks of a 1000-point sweep take 0.87 × the time of 8),
    at least 4 per sweep (4 per process where several share it) so that rows stream out and an interrupted
    sweep keeps most of its work."""
    size = max(16, min(CHUNK, -(-len(idx) // (4 * processes))))
    return [idx[k:k + size] for k in range(0, len(idx), size)]


def _coupled_local(scene, points, idx, processes, emit, scenes):
    chunks = _chunks(idx, processes)
    if processes == 1 or len(chunks) == 1:
        pre = _prepared(scene)
        for part in chunks:
            for i, row in zip(part, _solve_chunk(scene, [points[i] for i in part], [scenes[i] for i in part], pre)):
                emit(i, row)
        return
    for part, rows in imap_unordered(_chunk_job, [(scene, part, [points[i] for i in part]) for part in chunks],
                                     processes):          # (no worker outlives the sweep)
        for i, row in zip(part, rows):
            emit(i, row)


def _coupled_dask(scene, points, idx, scheduler, emit):
    try:
        from dask.distributed import Client, as_completed as das_completed
    except ImportError:   # pragma: no cover - exercised only without dask
        raise InputError("scheduler", scheduler, "the Dask path needs the optional dependency: "
                         "pip install 'thermobear[dask]' (dask[distributed])") from None
    own = not isinstance(scheduler, Client)
    client = Client(scheduler) if own else scheduler
    try:
        chunks = _chunks(idx, 8)
        futs = client.map(_chunk_job, [(scene, part, [points[i] for i in part]) for part in chunks], pure=False)
        for f in das_completed(futs):
            part, rows = f.result()
            for i, row in zip(part, rows):
                emit(i, row)
    finally:
        if own:
            client.close()


def run_sweep(scene: Scene, grid: dict, *, scheduler=None, processes: int | None = None, progress=None,
              on_row=None) -> list[dict]:
    """Run a scene over a grid of operating points (see the module docstring).

    Parameters
    ----------
    scene : Scene               the base scene
    grid : dict                 ``{override: [values]}``; keys are :meth:`Scene.with_` overrides
                                (n_rpm [rpm], Fa, Fr [N], T_C, T_oil_in_C [°C], lubricant, ...)
    scheduler : str or Client   Dask scheduler address ``"tcp://host:port"`` (or a
                                ``dask.distributed.Client``) for the coupled points; None: local
    processes : int             local worker processes for the coupled points (default 1: this
                                process; each worker solves chunks of points together)
    progress : callable         ``progress(done, total)`` as rows finish
    on_row : callable           ``on_row(index, row)`` as each row finishes (index in grid order)

    Returns
    -------
    list of dict   one row per point in grid order (first key slowest)

    Examples
    --------
    Prescribed temperatures: one vectorised loss evaluation for the 4 points.

    >>> import thermobear as tb
    >>> s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    >>> rows = run_sweep(s, {"n_rpm": [3200, 6500], "T_C": [40.0, 60.0]})
    >>> [r["status"] for r in rows], rows[0]["P_W"] > rows[1]["P_W"], rows[2]["P_W"] > rows[0]["P_W"]
    (['ok', 'ok', 'ok', 'ok'], True, True)
    """
    if not isinstance(scene, Scene):
        raise InputError("scene", type(scene).__name__, "a thermobear.scene.Scene")
    processes = None if processes is None else check_processes(processes)
    points = sweep_points(grid)
    scenes = [scene.with_(**p) for p in points]          # validates every override first
    total = len(points)
    rows: list = [None] * total
    done = [0]

    def emit(i, row):
        rows[i] = row
        done[0] += 1
        if on_row is not None:
            on_row(i, row)
        if progress is not None:
            progress(done[0], total)

    fixed = [i for i, sc in enumerate(scenes) if sc.T_C is not None]
    coupled = [i for i, sc in enumerate(scenes) if sc.T_C is None]
    for i in coupled:
        if scenes[i].network is None:
            raise InputError("thermal.network", None, "give a thermal network or prescribe operation.T_C")
    _prescribed(scenes, points, fixed, emit)
    if coupled:
        if scheduler is not None:
            _coupled_dask(scene, points, coupled, scheduler, emit)
        else:
            _coupled_local(scene, points, coupled, processes or 1, emit, scenes)
    return rows


