r"""Sweeps: one scene over a grid of operating points, vectorised or in parallel.

:func:`run_sweep` takes a scene and a grid ``{override: [values, ...]}`` whose
keys are :meth:`thermobear.scene.scene.Scene.with_` overrides (``n_rpm``, ``Fa``,
``Fr``, ``M``, ``T_C``, ``T_oil_in_C``, ``T_ambient_C``, ``oil_flow_L_h``,
``lubricant``, ...).  It runs the Cartesian product of the values (first key
slowest) and returns one row per point, in grid order.

Two kinds of points, as :func:`thermobear.coupled.solver.choose_models` decides:

* **prescribed temperature** (the point has ``T_C``): no thermal network.  The
  points that share everything but speed and temperature — same lubricant,
  loads and model choices, a "group" — are computed in **one** vectorised
  :func:`thermobear.coupled.solver.scene_losses` call with the group's single load
  distribution (the loads do not depend on speed or temperature in the
  low-speed model; the high-speed and the film load models solve the group's
  loads in one batched call, one case per speed and temperature).  Scenes on the
  SKF global model (``models.losses = "skf"``) are evaluated point by point.
* **coupled** (no ``T_C``): the thermal fixed point
  (:func:`thermobear.coupled.solver.steady_state`) per point, run in local processes
  (:class:`concurrent.futures.ProcessPoolExecutor`, ``processes`` workers,
  default ``os.cpu_count()``; ``processes=1`` runs in this process) or on an
  existing Dask distributed cluster (``scheduler="tcp://host:port"``; needs the
  optional dependency ``dask[distributed]``).

A point whose coupled solution fails (:class:`~thermobear.errors.ThermalRunaway`,
:class:`~thermobear.errors.NoConvergence`, ...) does not stop the sweep: its
row says so (``status`` = the error class, ``reason``, ``iterations``) and
carries no power — never a silent or NaN result.  Bad overrides raise
:class:`~thermobear.errors.InputError` before anything runs.

Each row holds the grid values and ``P_W`` [W], ``torque_Nm`` [N m],
``breakdown_W`` (loss family → W), ``temperatures_C`` (node → °C; prescribed
points: ``{"contacts (prescribed)": T}``), ``T_ball_C`` (coupled points), ``models`` (sub-model → choice),
``status`` ("ok" or the error class), ``reason`` (how the fixed point converged, or why it
failed), ``iterations`` and ``residual_K`` (coupled points).
"""
from __future__ import annotations

import itertools
import os
from concurrent.futures import ProcessPoolExecutor, as_completed

import numpy as np

from thermobear.errors import InputError, SolverError
from thermobear.scene.scene import Scene
from thermobear.coupled.solver import _load_case, _prime_dry_loads, choose_models, scene_load, scene_losses, solve, steady_state

__all__ = ["run_sweep", "sweep_points"]

_VECTOR_KEYS = ("n_rpm", "T_C")          # vectorised inside one scene_losses call


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


def _solve_point(scene: Scene, point: dict) -> dict:
    """Coupled steady state of one point (runs in a worker process or on a Dask worker)."""
    sc = scene.with_(**point)
    try:
        st = steady_state(sc)
    except (SolverError, InputError) as exc:   # inputs were validated up front: a model range left mid-solve
        return _row(point, sc, exc=exc)
    return _row(point, sc, st=st)


def _row(point: dict, sc: Scene, st=None, exc=None) -> dict:
    """A coupled point's row from its steady state, or from the error that stopped it."""
    row = _base_row(point)
    if exc is not None:
        row.update(P_W=None, torque_Nm=None, breakdown_W={}, temperatures_C={}, models=_choices(choose_models(sc)),
                   status=type(exc).__name__, reason=str(exc.reason if hasattr(exc, "reason") else exc),
                   iterations=getattr(exc, "iterations", None), residual_K=getattr(exc, "residual", None))
        return row
    row.update(P_W=float(st.P_W), torque_Nm=float(st.losses.torque_Nm),
               breakdown_W={k: float(v) for k, v in st.losses.breakdown_W.items()},
               temperatures_C={k: float(v) for k, v in st.T_C.items()}, T_ball_C=float(st.T_ball_C),
               models=_choices(st.models_used), status="ok", reason=str(st.models_used["thermal"][1]),
               iterations=int(st.iterations),
               residual_K=float(st.residual_K))
    return row


def _film_points(scene: Scene, points: list, progress=None) -> list:
    """Rows of coupled points on the film load model (worker side, or in this process).

    Each point runs the film fixed point of :func:`thermobear.coupled.solver.steady_state`
    (:func:`thermobear.coupled.solver._steady_film_steps`: a dry start, then film load updates, each followed by
    a network solve).  The film load distributions the points ask for in the same round are solved in
    one batched call per group of points that differ only in speed and film temperature
    (:func:`thermobear.coupled.solver.film_scene_load`, each case equal to its single solve to round-off); a
    batch that fails is solved point by point, so a failure stays with its point."""
    from thermobear.coupled.solver import _steady_film_steps, film_scene_load
    rows: list = [None] * len(points)
    live = {}
    for j, p in enumerate(points):
        sc = scene.with_(**p)
        models = choose_models(sc)
        steps = _steady_film_steps(sc, models, tol_K=1e-6, method="newton")
        try:
            live[j] = (steps, sc, models, next(steps))
        except (SolverError, InputError) as exc:
            rows[j] = _row(p, sc, exc=exc)
            if progress:
                progress()
    while live:
        groups: dict = {}
        for j, (_, sc, models, _) in live.items():
            key = (sc.bearing, id(sc.lubricant), sc.Fa, sc.Fr, sc.M, sc.rotating, sc.models.get("stiffness"),
                   models["high_speed"][0])
            groups.setdefault(key, []).append(j)
        nxt = {}
        for members in groups.values():
            loads = {}
            if len(members) > 1:
                sc0, models0 = live[members[0]][1], live[members[0]][2]
                try:
                    ld = film_scene_load(sc0, models0, np.array([live[j][3] for j in members]),
                                         n_rpm=np.array([live[j][1].n_rpm for j in members]))
                    loads = {j: _load_case(ld, k, len(members)) for k, j in enumerate(members)}
                except (SolverError, InputError):       # each point on its own: a failure stays on its row
                    loads = {}
            for j in members:
                steps, sc, models, T_film = live[j]
                try:
                    load = loads[j] if j in loads else film_scene_load(sc, models, T_film)
                    nxt[j] = (steps, sc, models, steps.send(load))
                except StopIteration as done:
                    rows[j] = _row(points[j], sc, st=done.value)
                except (SolverError, InputError) as exc:
                    rows[j] = _row(points[j], sc, exc=exc)
                if rows[j] is not None and progress:
                    progress()
        live = nxt
    return rows


def _losses_batch(sc: Scene, n_rpm, T_C, models: dict, load=None):
    """Local losses of one group, vectorised over speed and temperature [W].

    Goes through :func:`thermobear.coupled.solver.scene_losses` (the same argument mapping as a single
    solve) with the group's speed array; ``load``: a load distribution instead of the one the
    solver picks."""
    return scene_losses(sc, T_C=np.asarray(T_C, float), models=models, n_rpm=np.asarray(n_rpm, float),
                        load=scene_load(sc, models) if load is None else load)


def _prescribed(scenes, points, idx, rows):
    groups: dict = {}
    for i in idx:
        models = choose_models(scenes[i])
        key = (tuple((k, repr(v)) for k, v in points[i].items() if k not in _VECTOR_KEYS),
               tuple(sorted((k, repr(v[0])) for k, v in models.items() if k != "thermal")))
        groups.setdefault(key, (models, []))[1].append(i)
    for models, members in groups.values():
        try:
            _prescribed_group(scenes, points, rows, models, members)
        except SolverError:         # a point without equilibrium: each point alone, the failure on its own row
            for i in members:
                try:
                    _prescribed_group(scenes, points, rows, models, [i])
                except SolverError as exc:
                    rows[i] = _row(points[i], scenes[i], exc=exc)


def _prescribed_group(scenes, points, rows, models, members):
    """Rows of one group of prescribed-temperature points (one vectorised loss evaluation)."""
    sc = scenes[members[0]]
    n = np.array([scenes[i].n_rpm for i in members], float)
    T = np.array([scenes[i].T_C for i in members], float)
    if models.get("losses", ("local",))[0] != "local":         # SKF global model: per point
        rs = [solve(scenes[i]) for i in members]
        P = np.array([x.P_W for x in rs])
        M = np.array([x.torque_Nm for x in rs])
        bd = {k: np.array([x.breakdown_W[k] for x in rs]) for k in rs[0].breakdown_W}
    else:
        load = None
        if models["load_model"][0] == "film":   # loads depend on speed and film temperature: one batched solve
            from thermobear.coupled.solver import film_scene_load
            load = film_scene_load(sc, models, T, n_rpm=n)
        elif models["high_speed"][0] == "yes":   # high-speed ball loads depend on speed only: one batched
            from thermobear.loads.highspeed import load_distribution_high_speed    # solve over the distinct speeds
            n_u, back = np.unique(n, return_inverse=True)
            load = _load_case(load_distribution_high_speed(sc.bearing, Fa=sc.Fa, Fr=sc.Fr, M=sc.M, n_rpm=n_u,
                                                           stiffness=sc.models.get("stiffness", "nominal")),
                              back, n_u.size)
        r = _losses_batch(sc, n, T, models, load=load)
        P, M = np.atleast_1d(r.P_W), np.atleast_1d(r.torque_Nm)
        bd = {k: np.broadcast_to(np.atleast_1d(v), P.shape) for k, v in r.breakdown_W.items()}
    for j, i in enumerate(members):
        row = _base_row(points[i])
        row.update(P_W=float(P[j]), torque_Nm=float(M[j]), breakdown_W={k: float(v[j]) for k, v in bd.items()},
                   temperatures_C={"contacts (prescribed)": float(T[j])}, models=_choices(models), status="ok",
                   reason="", iterations=0, residual_K=0.0)
        rows[i] = row


def _film_chunk(scene, points):
    return _film_points(scene, points)


def _coupled_local(scene, points, idx, rows, processes, progress, done, total, scenes=None):
    # points on the film load model run together (their film load distributions batched per round)
    film = [i for i in idx if scenes is not None and choose_models(scenes[i])["load_model"][0] == "film"]
    in_film = set(film)
    rest = [i for i in idx if i not in in_film]
    count = [done]

    def tick():
        count[0] += 1
        if progress:
            progress(count[0], total)
    if processes == 1 or len(idx) == 1:
        if film:
            for i, row in zip(film, _film_points(scene, [points[i] for i in film], progress=tick)):
                rows[i] = row
        for i in rest:
            rows[i] = _solve_point(scene, points[i])
            tick()
        return count[0]
    with ProcessPoolExecutor(max_workers=min(processes, len(idx))) as ex:
        futs = {ex.submit(_solve_point, scene, points[i]): [i] for i in rest}
        n_chunks = min(processes, len(film))
        for c in range(n_chunks):                   # contiguous chunks: neighbouring speeds batch together
            part = film[c * len(film) // n_chunks:(c + 1) * len(film) // n_chunks]
            futs[ex.submit(_film_chunk, scene, [points[i] for i in part])] = part
        for f in as_completed(futs):
            part = futs[f]
            out = f.result()
            for i, row in zip(part, out if isinstance(out, list) else [out]):
                rows[i] = row
                tick()
    return count[0]


def _coupled_dask(scene, points, idx, rows, scheduler, progress, done, total):
    try:
        from dask.distributed import Client, as_completed as das_completed
    except ImportError:   # pragma: no cover - exercised only without dask
        raise InputError("scheduler", scheduler, "the Dask path needs the optional dependency: "
                         "pip install 'thermobear[dask]' (dask[distributed])") from None
    own = not isinstance(scheduler, Client)
    client = Client(scheduler) if own else scheduler
    try:
        futs = client.map(_solve_point, [scene] * len(idx), [points[i] for i in idx], pure=False)
        where = {f.key: i for f, i in zip(futs, idx)}
        for f in das_completed(futs):
            rows[where[f.key]] = f.result()
            done += 1
            if progress:
                progress(done, total)
    finally:
        if own:
            client.close()
    return done


def run_sweep(scene: Scene, grid: dict, *, scheduler=None, processes: int | None = None,
              progress=None) -> list[dict]:
    """Run a scene over a grid of operating points (see the module docstring).

    Parameters
    ----------
    scene : Scene               the base scene
    grid : dict                 ``{override: [values]}``; keys are :meth:`Scene.with_` overrides
                                (n_rpm [rpm], Fa, Fr [N], T_C, T_oil_in_C [°C], lubricant, ...)
    scheduler : str or Client   Dask scheduler address ``"tcp://host:port"`` (or a
                                ``dask.distributed.Client``) for the coupled points; None: local
    processes : int             local worker processes for the coupled points (default
                                ``os.cpu_count()``; 1 runs them in this process)
    progress : callable         ``progress(done, total)`` after each point

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
        raise InputError("scene", type(scene).__name__, "a thermobear.scene.scene.Scene")
    if processes is not None and (not isinstance(processes, (int, np.integer)) or processes < 1):
        raise InputError("processes", processes, "an integer >= 1")
    points = sweep_points(grid)
    scenes = [scene.with_(**p) for p in points]          # validates every override first
    _prime_dry_loads(scenes)                             # the dry loads of all points in batched solves
    for sc in scenes:
        choose_models(sc)                                # InputError (e.g. no network) before running
    total = len(points)
    rows: list = [None] * total
    fixed = [i for i, sc in enumerate(scenes) if sc.T_C is not None]
    coupled = [i for i, sc in enumerate(scenes) if sc.T_C is None]
    _prescribed(scenes, points, fixed, rows)
    done = len(fixed)
    if progress and fixed:
        progress(done, total)
    if coupled:
        if scheduler is not None:
            _coupled_dask(scene, points, coupled, rows, scheduler, progress, done, total)
        else:
            _coupled_local(scene, points, coupled, rows, processes or os.cpu_count() or 1, progress, done, total,
                           scenes=scenes)
    return rows
