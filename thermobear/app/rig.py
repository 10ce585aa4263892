r"""Rig logs: read them, simulate them, compare, and calibrate uncertain parameters.

A rig log is a CSV file (``#`` lines are comments: name the source there) with
named columns, units in the names::

    # heat-up of a 7210 on rig X, 2024-05-03
    t_s,T_IR_C,T_OR_C,n_rpm
    0,22.1,22.0,3000
    30,25.4,24.2,3000

* ``t_s``        time [s] — a *transient* log (heat-up, speed steps); without it
  the rows are *steady* operating points (e.g. torque and temperature vs speed);
* ``T_<name>_C`` a temperature channel [°C];
* ``n_rpm``      speed [rpm] (transient: steps become a schedule; steady: one
  operating point per row);
* ``torque_Nm``  friction torque [N m]; ``Fa_N``, ``Fr_N`` loads [N] (transient: steps become a
  schedule, as ``n_rpm``; steady: the row's loads, an empty cell the scene's);
  ``lubricant``  a lubricant name per row (steady logs).

Empty cells are missing values (skipped by the metrics).  Each temperature
channel is mapped to a thermal-network node in the scene's ``[rig.map]`` table
(``T_IR_C = "inner_ring"``) or on the command line (``--map T_IR_C=inner_ring``).
Two special targets: ``"input"`` makes the channel the operating temperature
of its row (``operation.T_C``: the losses are evaluated at the measured
temperature, no network needed — the way seed 002 evaluates its models) and
``"ignore"`` skips it.  ``"impose:<node>"`` imposes the logged temperature on that node
(``thermal.fixed_C``): the room on ``ambient``, the oil inlet on ``oil_inlet``, the ring
thermocouples on ``inner_ring``/``outer_ring`` (then the balls and the mixture are solved and
the torque is compared at the measured bearing temperature — how seed 004 (§4.5) runs its model
against its rig).  A steady log imposes each row's value on its equilibrium.  A transient log
runs the heat-up with the channel as a *time-varying boundary*: linear between the logged rows
(an empty cell is bridged linearly from its neighbours; the first and last rows must be given),
never extrapolated — the run covers the log's rows only.  The speed and load steps of ``n_rpm``,
``Fa_N`` and ``Fr_N`` (a change at a row applies from that row on, one on the last row has no time
to act and is ignored, though a load there that the bearing cannot carry is refused; every row must give them) and the imposed channels reach the integrator
the same way (:func:`thermobear.coupled.transient`, ``schedule`` and ``boundary``).  The run starts at the log's first row, at ``T0_C`` (default:
the logged value of an imposed ``ambient`` node at that row, else the scene's ambient
temperature).  A node can be imposed by one channel only, and an imposed node is not compared.

Metrics per channel (:func:`metrics`): RMSE, maximum absolute error, bias,
steady-state error (mean error over the last 10 % of a transient log) and the
time to 90 % of the rise, measured and simulated.

Calibration of uncertain parameters on a log: :mod:`thermobear.app.calibration`.
"""
from __future__ import annotations

import csv
import io
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from thermobear.coupled import solve, transient
from thermobear.coupled.ratings import check_static_safety
from thermobear.errors import InputError
from thermobear.scene import Scene
from thermobear.scene.network import network_nodes as scene_network_nodes
from thermobear.thermal.solve import LinearBoundary

__all__ = ["RigLog", "read_log", "channel_map", "metrics", "simulate_log", "compare", "Comparison",
           "network_nodes", "parse_map", "special_target", "SPECIAL_TARGETS"]

SPECIAL_TARGETS = ("input", "ignore")
IMPOSE = "impose:"


def special_target(target: str) -> bool:
    """A target that is not a simulated node (an input of the model, or skipped)."""
    return target in SPECIAL_TARGETS or target.startswith(IMPOSE)


_T_RE = re.compile(r"^T_[A-Za-z0-9_]+_C$")
_NUMERIC = ("t_s", "n_rpm", "torque_Nm", "Fa_N", "Fr_N")


# --------------------------------------------------------------------------- reading
@dataclass(frozen=True)
class RigLog:
    """A parsed rig log.

    Attributes
    ----------
    path : str              file read
    comments : list[str]    header comment lines (without ``#``)
    columns : dict          column name → ndarray (float, NaN where empty) or list[str] (lubricant)
    kind : str              ``"transient"`` (has ``t_s``) or ``"steady"``
    """

    path: str
    comments: list
    columns: dict
    kind: str

    @property
    def t_s(self):
        """Times [s] (transient logs) or None."""
        return self.columns.get("t_s")

    @property
    def temperature_channels(self) -> list:
        """Names of the ``T_<name>_C`` columns, in file order."""
        return [c for c in self.columns if _T_RE.match(c)]

    @property
    def n_rows(self) -> int:
        """Number of data rows."""
        return len(next(iter(self.columns.values())))

    def __getitem__(self, name):
        return self.columns[name]


def read_log(path) -> RigLog:
    """Read and check a rig log (CSV, see the module docstring).

    Raises InputError naming the file, line and column of any malformed value,
    an unknown column, a log without ``t_s`` or ``n_rpm``, or times that do not
    increase.

    >>> import io, tempfile, os
    >>> p = os.path.join(tempfile.mkdtemp(), "log.csv")
    >>> _ = open(p, "w").write("# demo\\nt_s,T_IR_C\\n0,20\\n60,25.5\\n")
    >>> log = read_log(p)
    >>> log.kind, log.temperature_channels, float(log["T_IR_C"][1])
    ('transient', ['T_IR_C'], 25.5)
    """
    p = Path(path)
    if not p.is_file():
        raise InputError("log", str(path), "is a folder, not a log file (CSV)" if p.is_dir() else "file not found")
    try:
        text = p.read_text(encoding="utf-8-sig")         # Excel's "CSV UTF-8" starts with a BOM
    except UnicodeDecodeError:
        raise InputError("log", str(path), "not a UTF-8 text (CSV) file") from None
    comments, body = [], []
    for k, line in enumerate(text.splitlines(), start=1):
        s = line.strip()
        if s.startswith("#"):
            comments.append(s[1:].strip())
        elif s:
            body.append((k, line))
    if not body:
        raise InputError(f"{p.name}", None, "no header and no data rows (expected e.g. 't_s,T_IR_C')")
    rows = list(csv.reader(io.StringIO("\n".join(l for _, l in body))))
    header = [h.strip() for h in rows[0]]
    for h in header:
        if not (h in _NUMERIC or h == "lubricant" or _T_RE.match(h)):
            raise InputError(f"{p.name}: column", h, "unknown column; accepted: t_s, n_rpm, torque_Nm, Fa_N, Fr_N, "
                             "lubricant, T_<name>_C")
    if len(set(header)) != len(header):
        dup = sorted({h for h in header if header.count(h) > 1})[0]
        raise InputError(f"{p.name}: column", dup, "appears twice")
    if "t_s" not in header and "n_rpm" not in header:
        raise InputError(f"{p.name}: columns", ",".join(header),
                         "a log needs t_s (transient) or n_rpm (steady operating points)")
    data = rows[1:]
    if not data:
        raise InputError(f"{p.name}", None, "header but no data rows")
    cols = {h: [] for h in header}
    for (lineno, _), row in zip(body[1:], data):
        if len(row) != len(header):
            raise InputError(f"{p.name}: line {lineno}", ",".join(row),
                             f"expected {len(header)} comma-separated values ({','.join(header)})")
        for h, v in zip(header, row):
            v = v.strip()
            if h == "lubricant":
                cols[h].append(v)
                continue
            if v == "":
                cols[h].append(math.nan)
                continue
            try:
                x = float(v)
            except ValueError:
                raise InputError(f"{p.name}: line {lineno}, column {h}", v, "must be a number") from None
            if not math.isfinite(x):
                raise InputError(f"{p.name}: line {lineno}, column {h}", v, "must be finite (leave the cell empty "
                                 "for a missing value)")
            cols[h].append(x)
    out = {h: (v if h == "lubricant" else np.asarray(v, float)) for h, v in cols.items()}
    kind = "transient" if "t_s" in out else "steady"
    if kind == "transient":
        t = out["t_s"]
        if np.any(np.isnan(t)) or np.any(t < 0) or np.any(np.diff(t) <= 0):
            raise InputError(f"{p.name}: column t_s", None, "times must be given, >= 0 and strictly increasing [s]")
        if "lubricant" in out:
            raise InputError(f"{p.name}: column", "lubricant", "a lubricant per row belongs in a steady log (no t_s)")
    else:
        n = out["n_rpm"]
        if np.any(np.isnan(n)) or np.any(n < 0):
            raise InputError(f"{p.name}: column n_rpm", None, "every steady row needs a speed >= 0 [rpm]")
    for h in ("torque_Nm", "Fa_N", "Fr_N"):
        if h in out and np.any(out[h][~np.isnan(out[h])] < 0):
            raise InputError(f"{p.name}: column {h}", None, "values must be >= 0")
    for h in out:
        if _T_RE.match(h) and np.any(~np.isnan(out[h]) & ((out[h] < -60) | (out[h] > 250))):
            raise InputError(f"{p.name}: column {h}", None, "temperatures must lie in [-60, 250] °C")
    if kind == "transient" and len(out["t_s"]) < 2:     # a run from t_s to itself: nothing to compare
        raise InputError(f"{p.name}", f"1 row (t_s = {out['t_s'][0]:g} s)", "a transient log needs at least two rows "
                         "at increasing times t_s [s]; a steady operating point is a row of a log with n_rpm and no t_s")
    return RigLog(path=str(p), comments=comments, columns=out, kind=kind)


# --------------------------------------------------------------------------- scene helpers
def network_nodes(scene: Scene) -> list:
    """Node names of the scene's thermal network (read from its file, nothing evaluated); [] without one."""
    return scene_network_nodes(scene.network, scene.path) if scene.network else []


def parse_map(items) -> dict:
    """``["T_IR_C=inner_ring", ...]`` → dict; InputError for a malformed item."""
    out = {}
    for it in items or []:
        if "=" not in it:
            raise InputError("--map", it, "expected channel=node, e.g. --map T_IR_C=inner_ring")
        k, v = (s.strip() for s in it.split("=", 1))
        out[k] = v
    return out


def channel_map(scene: Scene, log: RigLog, overrides: dict | None = None) -> dict:
    """Channel → node (or ``"input"``/``"ignore"``) from ``[rig.map]`` and command-line overrides.

    Every temperature channel of the log must be mapped; every mapped channel
    must exist in the log; every node must exist in the scene's network.
    """
    m = {**scene.rig_map, **(overrides or {})}
    chans = log.temperature_channels
    for ch, node in m.items():
        if ch not in chans:
            src = "--map" if overrides and ch in overrides else "rig.map"
            raise InputError(f"{src}.{ch}", node, f"unknown channel; the log has: {', '.join(chans) or 'none'}")
    for ch in chans:
        if ch not in m:
            raise InputError(f"rig.map.{ch}", None, "channel not mapped: add [rig.map] "
                             f'{ch} = "<node>" (or "input"/"ignore"/"impose:<node>") to the scene or --map {ch}=<node>')
    nodes = network_nodes(scene)
    inputs = [c for c, n in m.items() if n == "input"]
    if len(inputs) > 1:
        raise InputError("rig.map", ", ".join(inputs), "only one channel can be the operating temperature (input)")
    if inputs and log.kind == "transient":
        raise InputError(f"rig.map.{inputs[0]}", "input", "an input temperature needs a steady log (no t_s); "
                         'a heat-up log imposes a logged temperature on a node: "impose:<node>"')
    imposed = {}
    for ch, node in m.items():
        if node.startswith(IMPOSE):
            if node[len(IMPOSE):] in imposed:
                raise InputError(f"rig.map.{ch}", node, f"the node is imposed by {imposed[node[len(IMPOSE):]]} already")
            imposed[node[len(IMPOSE):]] = ch
    for ch, node in m.items():
        if node in imposed:
            raise InputError(f"rig.map.{ch}", node, f"the node is imposed by {imposed[node]}: nothing to compare")
    for ch, node in m.items():
        if node in SPECIAL_TARGETS:
            continue
        if node.startswith(IMPOSE):
            node = node[len(IMPOSE):]
        if not nodes:
            raise InputError(f"rig.map.{ch}", node, "the scene has no thermal network (temperature prescribed); "
                             'map the channel to "input" or "ignore"')
        if node not in nodes:
            raise InputError(f"rig.map.{ch}", node, f"unknown node; the network has: {', '.join(nodes)}")
    return m


# --------------------------------------------------------------------------- metrics
def _t90(t, y):
    """Time to 90 % of the rise from the first value to the final (mean of the last 10 %) value [s]."""
    ok = ~np.isnan(y)
    t, y = t[ok], y[ok]
    if t.size < 3:
        return None
    n_end = max(1, int(round(0.1 * t.size)))
    y0, y1 = y[0], float(np.mean(y[-n_end:]))
    rise = y1 - y0
    if abs(rise) < 1e-9:
        return None
    target = y0 + 0.9 * rise
    s = np.sign(rise) * (y - target)
    k = np.flatnonzero(s >= 0)
    if k.size == 0:
        return None
    k = int(k[0])
    if k == 0:
        return float(t[0])
    f = (target - y[k - 1]) / (y[k] - y[k - 1])
    return float(t[k - 1] + f * (t[k] - t[k - 1]))


def metrics(measured, simulated, t_s=None) -> dict:
    r"""Agreement of a simulated channel with its measurement.

    Parameters
    ----------
    measured, simulated : array_like   same shape; NaN in ``measured`` = missing
    t_s : array_like, optional         times [s] (transient logs)

    Returns
    -------
    dict  n, rmse, max_abs_error, bias (mean of simulated − measured), and for
          transient logs steady_state_error (mean error over the last 10 % of
          the duration), t90_measured_s, t90_simulated_s (time to 90 % of the rise)

    Examples
    --------
    >>> m = metrics([1.0, 2.0, 3.0], [1.0, 2.0, 5.0])
    >>> m["n"], round(m["rmse"], 6), m["max_abs_error"], round(m["bias"], 6)
    (3, 1.154701, 2.0, 0.666667)
    """
    y = np.asarray(measured, float)
    s = np.asarray(simulated, float)
    ok = ~np.isnan(y)
    e = (s - y)[ok]
    if e.size == 0:
        return {"n": 0, "rmse": None, "max_abs_error": None, "bias": None}
    out = {"n": int(e.size), "rmse": float(np.sqrt(np.mean(e**2))), "max_abs_error": float(np.max(np.abs(e))),
           "bias": float(np.mean(e))}
    if t_s is not None:
        t = np.asarray(t_s, float)
        late = ok & (t >= t[0] + 0.9 * (t[-1] - t[0]))
        out["steady_state_error"] = float(np.mean((s - y)[late])) if late.any() else float(e[-1])
        out["t90_measured_s"] = _t90(t, y)
        out["t90_simulated_s"] = _t90(t, s)
    return out


# --------------------------------------------------------------------------- simulation
def _row_scene(scene: Scene, log: RigLog, i: int, mapping: dict) -> Scene:
    ch = {}
    c = log.columns
    if "n_rpm" in c:
        ch["n_rpm"] = float(c["n_rpm"][i])
    for k in ("Fa_N", "Fr_N"):
        if k in c and not np.isnan(c[k][i]):
            ch[k] = float(c[k][i])
    if "lubricant" in c and c["lubricant"][i]:
        ch["lubricant"] = c["lubricant"][i]
    for chn, node in mapping.items():
        if node == "input":
            v = c[chn][i]
            if np.isnan(v):
                raise InputError(f"{Path(log.path).name}: row {i + 1}, column {chn}", None,
                                 "the input temperature is missing")
            ch["T_C"] = float(v)
        elif node.startswith(IMPOSE):
            v = c[chn][i]
            if np.isnan(v):
                raise InputError(f"{Path(log.path).name}: row {i + 1}, column {chn}", None,
                                 "the imposed temperature is missing")
            ch.setdefault("T_fixed_C", dict(scene.T_fixed_C))[node[len(IMPOSE):]] = float(v)
    return scene.with_(**ch)


def _imposed(mapping: dict) -> dict:
    """Channel → node of the ``"impose:<node>"`` channels."""
    return {ch: n[len(IMPOSE):] for ch, n in mapping.items() if n.startswith(IMPOSE)}


_DRIVES = ("n_rpm", "Fa_N", "Fr_N")          # transient-log columns that drive the operating point (scene keys)


def _log_inputs(scene: Scene, log: RigLog, mapping: dict):
    """What a transient log drives, on the run's clock (0 at the log's first row): the scene at the
    first row, the schedule of its speed and load steps (``n_rpm``, ``Fa_N``, ``Fr_N``), the logged
    boundary (None without imposed channels)."""
    name, t = Path(log.path).name, log.t_s
    t0 = float(t[0])
    drives = [c for c in _DRIVES if c in log.columns]
    for c in drives:
        if np.any(np.isnan(log[c])):
            raise InputError(f"{name}: column {c}", None, f"{'speed' if c == 'n_rpm' else 'load'} missing in some "
                             "rows (a transient log's operating point is stepped from every row)")
    steps = []
    for k in range(1, t.size - 1):         # a change on the last row has no time to act: ignored
        ch = {c: float(log[c][k]) for c in drives if log[c][k] != log[c][k - 1]}
        if ch:
            steps.append((float(t[k]) - t0, ch))
    sc = scene.with_(**{c: float(log[c][0]) for c in drives}) if drives else scene
    loads = [c for c in drives if c != "n_rpm"]
    if loads and t.size > 1 and any(log[c][-1] != log[c][-2] for c in loads):
        try:                                # not run, but a load no bearing carries is a wrong log: refused
            check_static_safety(sc.with_(**{c: float(log[c][-1]) for c in loads}))
        except InputError as exc:
            raise InputError(f"{name}: last row (t = {float(t[-1]):g} s): {exc.field}", exc.value,
                             exc.expected) from None
    imposed = _imposed(mapping)
    if not imposed:
        return sc, steps, None
    values = {}
    for ch, node in imposed.items():
        y = log[ch]
        ok = ~np.isnan(y)
        if not (ok[0] and ok[-1]):
            raise InputError(f"{name}: column {ch}", None, "an imposed (boundary) temperature needs its first and "
                             "last rows: the run covers the logged times, a boundary is not extrapolated")
        values[node] = np.interp(t, t[ok], y[ok])          # empty cells bridged linearly
    src = f"{name}: imposed {', '.join(imposed)}"
    return sc, steps, LinearBoundary.of(t - t0, values, source=src)


def _mode(log: RigLog, mapping: dict, steps=()) -> str:
    """How the log is simulated, in words (shown by ``compare`` and ``calibrate``)."""
    imposed = _imposed(mapping)
    arrows = ", ".join(f"{ch} → {node}" for ch, node in imposed.items())
    inputs = [ch for ch, n in mapping.items() if n == "input"]
    if log.kind == "steady":
        out = "steady points (one equilibrium per row)"
        if inputs:
            out += f"; operating temperature per row: {inputs[0]}"
        return out + (f"; imposed per row: {arrows}" if arrows else "")
    out = (f"transient with logged boundary {arrows} (linear between rows)" if arrows
           else "transient (heat-up from the start temperature)")
    stepped = [c for c in _DRIVES if any(c in ch for _, ch in steps)]
    if stepped:
        what = "speed step" if stepped == ["n_rpm"] else "step"
        out += f"; {len(steps)} {what}{'s' * (len(steps) != 1)} from {', '.join(stepped)}"
    held = [f"{c} {float(log[c][0]):g} N" for c in ("Fa_N", "Fr_N") if c in log.columns and c not in stepped]
    out += f"; logged load held: {', '.join(held)}" if held else ""
    last = [c for c in _DRIVES if c in log.columns and log.n_rows > 1 and log[c][-1] != log[c][-2]]
    return out + (f"; the change of {', '.join(last)} on the last row (t = {float(log.t_s[-1]):g} s) has no time to "
                  "act: ignored" if last else "")


def simulate_log(scene: Scene, log: RigLog, mapping: dict, *, rtol: float = 1e-6, T0_C=None, dense: int = 0) -> dict:
    """Simulate what the log measured: channel → simulated array (and ``torque_Nm``).

    Transient logs run :func:`thermobear.coupled.transient` from the log's first row to its last,
    the speed and load steps of ``n_rpm``, ``Fa_N``, ``Fr_N`` as its schedule and the ``"impose:<node>"`` channels as its
    logged boundary (time-varying, linear between rows; see the module docstring); the start
    temperature ``T0_C`` [°C] defaults to the logged ambient (an imposed ``ambient`` node), else
    the scene's ambient temperature.  Steady logs run :func:`thermobear.coupled.solve` once per
    row (speed, loads, lubricant, input and imposed temperatures of that row).

    ``dense`` > 0 (transient logs) adds the integrated trajectory at that many evenly spaced times
    besides the log's: ``"_model_t"`` [s] and ``"_model"`` (channel → values), to draw the model
    continuously.  ``"_mode"`` says how the log was simulated.
    """
    out = {}
    if log.kind == "transient":
        sc, steps, bnd = _log_inputs(scene, log, mapping)
        t = log.t_s
        t0 = float(t[0])
        if T0_C is None and bnd is not None and "ambient" in bnd.T_C:
            T0_C = float(bnd.T_C["ambient"][0])
        t_run = _output_times(t, dense)
        run = transient(sc, float(t[-1]) - t0, schedule=steps, t_eval=t_run - t0, T0_C=T0_C, rtol=rtol,
                        atol=rtol * 10, boundary=bnd)
        at_log = np.searchsorted(t_run, t)
        tm = run.t_s + t0
        curves = {}
        for ch, node in mapping.items():
            if not special_target(node):
                curves[ch] = np.asarray(run.T_C[node], float)
        if "torque_Nm" in log.columns:
            w = (_speed_at(log, tm) if "n_rpm" in log.columns else np.full(tm.shape, sc.n_rpm)) * np.pi / 30.0
            curves["torque_Nm"] = np.where(w > 0, run.P_W / np.where(w > 0, w, 1.0), 0.0)
        out.update({ch: v[at_log] for ch, v in curves.items()})
        if dense:
            out["_model_t"], out["_model"] = tm, curves
        out["_run"], out["_mode"] = run, _mode(log, mapping, steps)
        return out
    res = [solve(_row_scene(scene, log, i, mapping)) for i in range(log.n_rows)]
    for ch, node in mapping.items():
        if not special_target(node):
            out[ch] = np.array([r.T_C[node] for r in res])
    out["torque_Nm"] = np.array([r.torque_Nm for r in res])
    out["P_W"] = np.array([r.P_W for r in res])
    out["_runs"], out["_mode"] = res, _mode(log, mapping)
    return out


def _output_times(t, dense: int):
    """The log's times and ``dense`` evenly spaced ones between its first and last (none closer to a
    log time than 1e-6 of the span)."""
    if dense <= 0:
        return np.asarray(t, float)
    t = np.asarray(t, float)
    grid = np.linspace(t[0], t[-1], int(dense))
    k = np.clip(np.searchsorted(t, grid), 1, t.size - 1)
    near = np.minimum(np.abs(grid - t[k - 1]), np.abs(grid - t[k])) < 1e-6 * float(t[-1] - t[0])
    return np.union1d(t, grid[~near])


def _speed_at(log: RigLog, t):
    """The logged speed in effect at the times ``t`` [s] (a change on the last row is not run)."""
    k = np.searchsorted(log.t_s, t, side="right") - 1
    return np.asarray(log["n_rpm"], float)[np.clip(k, 0, max(log.n_rows - 2, 0))]


@dataclass
class Comparison:
    """A rig log against its simulation.

    Attributes
    ----------
    kind : str            ``"transient"`` or ``"steady"``
    x : ndarray           times [s] (transient) or speeds [rpm] (steady)
    measured : dict       channel → measured array
    simulated : dict      channel → simulated array
    metrics : dict        channel → :func:`metrics` dict
    mapping : dict        channel → node
    mode : str            how the log was simulated (steady points; transient; transient with a logged
                          boundary, naming its channels and nodes)
    model_x : ndarray     times [s] of the integrated trajectory (transient logs; else None)
    model : dict          channel → the model along ``model_x`` (continuous curve)
    imposed : dict        channel → logged values imposed on a node (the boundary)
    bands, inside         channel → the model's band over the estimated inputs, dict(p5, p50, p95) over x,
                          and (measured points inside it, their number) (:mod:`thermobear.app.bands`)
    uncertainty : dict    the sample design and failed samples of the bands
    """

    kind: str
    x: np.ndarray
    measured: dict
    simulated: dict
    metrics: dict
    mapping: dict
    log: RigLog = field(repr=False)
    mode: str = ""
    model_x: np.ndarray | None = None
    model: dict = field(default_factory=dict)
    imposed: dict = field(default_factory=dict)
    bands: dict = field(default_factory=dict)
    inside: dict = field(default_factory=dict)
    uncertainty: dict = field(default_factory=dict)

    def as_dict(self) -> dict:
        out = {"kind": self.kind, "mode": self.mode, "log": self.log.path, "mapping": self.mapping,
               "metrics": self.metrics, "x": self.x, "measured": self.measured, "simulated": self.simulated}
        if self.model_x is not None:
            out["model"] = {"t_s": self.model_x, **self.model}
        if self.bands:
            out.update(bands=self.bands, inside_band=self.inside, uncertainty=self.uncertainty)
        return out

    def summary(self) -> str:
        unit = {"torque_Nm": "N m"}
        lines = [f"compare {Path(self.log.path).name} ({self.kind}, {self.log.n_rows} rows)",
                 f"mode: {self.mode}", "",
                 f"{'channel':14s} {'node':14s} {'n':>4s} {'RMSE':>10s} {'max err':>10s} {'bias':>10s}"
                 + (f" {'SS err':>9s} {'t90 meas':>9s} {'t90 sim':>9s}" if self.kind == "transient" else "")]
        for ch, m in self.metrics.items():
            if m["n"] == 0:
                lines.append(f"{ch:14s} {self.mapping.get(ch, '-'):14s} {0:4d}   (no measured values)")
                continue
            u = unit.get(ch, "K")
            row = (f"{ch:14s} {self.mapping.get(ch, 'torque'):14s} {m['n']:4d} {m['rmse']:8.3g} {u:1s} "
                   f"{m['max_abs_error']:8.3g} {u:1s} {m['bias']:+8.3g} {u:1s}")
            if self.kind == "transient":
                f = (lambda v: f"{v:9.0f}" if v is not None else f"{'-':>9s}")
                row += f" {m['steady_state_error']:+7.3g} {u:1s} {f(m['t90_measured_s'])} {f(m['t90_simulated_s'])}"
            lines.append(row)
        if self.kind == "transient":
            lines.append("\nSS err: mean error (model − measured) over the last 10 % of the log; t90: time to 90 % "
                         "of the rise [s].")
        if self.bands:
            u = self.uncertainty
            lines += ["", f"Model band over the estimated inputs ({u['n']} samples, seed {u['seed']}, {u['failed']} "
                      "failed): measured points inside the 5-95 % band"] + [
                f"  {ch:14s} {k:4d} of {m:4d}" for ch, (k, m) in self.inside.items()]
        return "\n".join(lines)


def compare(scene: Scene, log: RigLog, mapping: dict, *, T0_C=None, dense: int = 400) -> Comparison:
    """Simulate a rig log (:func:`simulate_log`) and measure the agreement of every mapped channel
    (and torque) at the logged rows; a transient log also keeps the integrated trajectory at
    ``dense`` evenly spaced times (``model_x``, ``model``) to draw the model continuously (the model's
    band over the estimated inputs: :func:`thermobear.app.bands.compare_bands`)."""
    sim = simulate_log(scene, log, mapping, T0_C=T0_C, dense=dense if log.kind == "transient" else 0)
    x = log.t_s if log.kind == "transient" else log["n_rpm"]
    meas, simd, met = {}, {}, {}
    for ch, node in mapping.items():
        if special_target(node):
            continue
        meas[ch], simd[ch] = log[ch], sim[ch]
        met[ch] = metrics(log[ch], sim[ch], log.t_s)
    if "torque_Nm" in log.columns:
        meas["torque_Nm"], simd["torque_Nm"] = log["torque_Nm"], sim["torque_Nm"]
        met["torque_Nm"] = metrics(log["torque_Nm"], sim["torque_Nm"], log.t_s)
    if not met:
        raise InputError(f"{Path(log.path).name}", None, "nothing to compare: no mapped temperature channel "
                         "and no torque_Nm column")
    return Comparison(kind=log.kind, x=np.asarray(x, float), measured=meas, simulated=simd, metrics=met,
                      mapping=mapping, log=log, mode=sim["_mode"], model_x=sim.get("_model_t"),
                      model=sim.get("_model", {}), imposed={ch: log[ch] for ch in _imposed(mapping)})
