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
* ``torque_Nm``  friction torque [N m]; ``Fa_N``, ``Fr_N`` loads [N];
  ``lubricant``  a lubricant name per row (steady logs).

Empty cells are missing values (skipped by the metrics).  Each temperature
channel is mapped to a thermal-network node in the scene's ``[rig.map]`` table
(``T_IR_C = "inner_ring"``) or on the command line (``--map T_IR_C=inner_ring``).
Two special targets: ``"input"`` makes the channel the operating temperature
of its row (``operation.T_C``: the losses are evaluated at the measured
temperature, no network needed — the way seed 002 evaluates its models) and
``"ignore"`` skips it.  ``"impose:<node>"`` imposes the channel's value on that node in its row
(``thermal.fixed_C``): with the ring thermocouples imposed, the balls and the
mixture are solved and the torque is compared at the measured bearing temperature
— how seed 004 (§4.5) runs its model against its rig.  In a transient log this
makes every row a quasi-steady point (balls and mixture at equilibrium with the
measured rings), the way to compare a heat-up's torque without modelling the rig.

Metrics per channel (:func:`metrics`): RMSE, maximum absolute error, bias,
steady-state error (mean error over the last 10 % of a transient log) and the
time to 90 % of the rise, measured and simulated.

Calibration (:func:`calibrate`) fits named parameters by
:func:`scipy.optimize.least_squares` and reports each with its standard
uncertainty from the Jacobian, covariance = s² (JᵀJ)⁻¹ with
s² = Σ r²/(m − p) (m residuals, p parameters; Bates & Watts 1988, §2.3).
Residuals are weighted so that 1 unit ≈ 1 K for a temperature channel and
1 % of the mean measured torque for the torque channel.
"""
from __future__ import annotations

import csv
import dataclasses
import io
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from scipy.optimize import least_squares

from thermobear.coupled import solve, transient
from thermobear.errors import InputError, NoConvergence
from thermobear.losses.skf import skf_constants
from thermobear.scene import Scene
from thermobear.scene.network import network_nodes as scene_network_nodes
from thermobear.scene.network import network_spec

__all__ = ["RigLog", "read_log", "channel_map", "metrics", "simulate_log", "compare", "Comparison",
           "calibrate", "Calibration", "network_nodes", "parameter_names",
           "parse_map", "SPECIAL_TARGETS"]

SPECIAL_TARGETS = ("input", "ignore")
IMPOSE = "impose:"


def _special(target: str) -> bool:
    """A target that is not a simulated node (an input of the model, or skipped)."""
    return target in SPECIAL_TARGETS or target.startswith(IMPOSE)
_T_RE = re.compile(r"^T_[A-Za-z0-9_]+_C$")
_NUMERIC = ("t_s", "n_rpm", "torque_Nm", "Fa_N", "Fr_N")
_SCENE_SCALARS = ("T_ambient_C", "T_oil_in_C", "oil_flow_L_h", "mu_boundary", "mu_full_film")
_SKF = ("skf_R1", "skf_S1", "skf_mu_EHL")


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
        raise InputError("log", str(path), "file not found")
    try:
        text = p.read_text(encoding="utf-8")
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
        raise InputError(f"rig.map.{inputs[0]}", "input", "an input temperature needs a steady log (no t_s)")
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


def _schedule_from_log(log: RigLog):
    if "n_rpm" not in log.columns:
        return [], None
    n, t = log["n_rpm"], log.t_s
    if np.any(np.isnan(n)):
        raise InputError(f"{Path(log.path).name}: column n_rpm", None, "speed missing in some rows")
    steps = [(float(t[k]), {"n_rpm": float(n[k])}) for k in range(1, n.size) if n[k] != n[k - 1]]
    return steps, float(n[0])


def simulate_log(scene: Scene, log: RigLog, mapping: dict, *, rtol: float = 1e-6, T0_C=None) -> dict:
    """Simulate what the log measured: channel → simulated array (and ``torque_Nm``).

    Transient logs run :func:`thermobear.coupled.transient` at the log's times
    (speed steps in ``n_rpm`` become the schedule; start at ``T0_C``, default the
    scene's ambient temperature); steady logs run :func:`thermobear.coupled.solve`
    once per row (speed, loads, lubricant and input temperature of that row).  A transient
    log with ``"impose:<node>"`` channels is run row by row the same way, quasi-steadily: the
    imposed (measured) temperatures of the row are boundaries and the remaining nodes — balls,
    mixture, with time constants of seconds — are taken at equilibrium with them.
    """
    out = {}
    if log.kind == "transient" and not any(n.startswith(IMPOSE) for n in mapping.values()):
        steps, n0 = _schedule_from_log(log)
        sc = scene.with_(n_rpm=n0) if n0 is not None else scene
        t = log.t_s
        run = transient(sc, float(t[-1]), schedule=steps, t_eval=t, T0_C=T0_C, rtol=rtol, atol=rtol * 10)
        for ch, node in mapping.items():
            if not _special(node):
                out[ch] = np.asarray(run.T_C[node], float)
        if "torque_Nm" in log.columns:
            n_rpm = _speed_at(log, run.t_s)
            w = n_rpm * np.pi / 30.0
            out["torque_Nm"] = np.where(w > 0, run.P_W / np.where(w > 0, w, 1.0), 0.0)
        out["_run"] = run
        return out
    res = [solve(_row_scene(scene, log, i, mapping)) for i in range(log.n_rows)]
    for ch, node in mapping.items():
        if not _special(node):
            out[ch] = np.array([r.T_C[node] for r in res])
    out["torque_Nm"] = np.array([r.torque_Nm for r in res])
    out["P_W"] = np.array([r.P_W for r in res])
    out["_runs"] = res
    return out


def _speed_at(log: RigLog, t):
    return np.asarray(log["n_rpm"], float)[np.searchsorted(log.t_s, t, side="right") - 1]


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
    bands: dict = field(default_factory=dict)
    inside: dict = field(default_factory=dict)
    uncertainty: dict = field(default_factory=dict)

    def as_dict(self) -> dict:
        return {"kind": self.kind, "log": self.log.path, "mapping": self.mapping, "metrics": self.metrics,
                "x": self.x, "measured": self.measured, "simulated": self.simulated,
                **({"bands": self.bands, "inside_band": self.inside, "uncertainty": self.uncertainty} if self.bands else {})}

    def summary(self) -> str:
        unit = {"torque_Nm": "N m"}
        lines = [f"compare {Path(self.log.path).name} ({self.kind}, {self.log.n_rows} rows)", "",
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
                row += f" {m['steady_state_error']:+9.3g} {f(m['t90_measured_s'])} {f(m['t90_simulated_s'])}"
            lines.append(row)
        if self.kind == "transient":
            lines.append("\nSS err: mean error over the last 10 % of the log; t90: time to 90 % of the rise [s].")
        if self.bands:
            u = self.uncertainty
            lines += ["", f"Model band over the estimated inputs ({u['n']} samples, seed {u['seed']}, {u['failed']} "
                      "failed): measured points inside the 5-95 % band"] + [
                f"  {ch:14s} {k:4d} of {m:4d}" for ch, (k, m) in self.inside.items()]
        return "\n".join(lines)


def compare(scene: Scene, log: RigLog, mapping: dict, *, T0_C=None) -> Comparison:
    """Simulate a rig log and measure the agreement of every mapped channel (and torque) (the model's
    band over the estimated inputs: :func:`thermobear.app.bands.compare_bands`)."""
    sim = simulate_log(scene, log, mapping, T0_C=T0_C)
    x = log.t_s if log.kind == "transient" else log["n_rpm"]
    meas, simd, met = {}, {}, {}
    for ch, node in mapping.items():
        if _special(node):
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
                      mapping=mapping, log=log)


# --------------------------------------------------------------------------- calibration
def _network_numeric_parameters(scene: Scene) -> dict:
    """``"<element or node>.<parameter>"`` → numeric value, for every number in the scene's network."""
    if not scene.network:
        return {}
    spec = network_spec(scene.network, scene.path, parameters=scene.network_parameters, fixed_C=scene.T_fixed_C)
    out = {}
    tables = [(e.get("name"), e) for e in spec.get("elements", [])] + list(spec.get("nodes", {}).items())
    for name, tbl in tables:
        if not name or not isinstance(tbl, dict):
            continue
        for k, v in tbl.items():
            if isinstance(v, (int, float)) and not isinstance(v, bool):
                out[f"{name}.{k}"] = float(v)
    return out


def parameter_names(scene: Scene) -> list:
    """Parameters :func:`calibrate` can fit for this scene.

    Network parameters (``[thermal.parameters]`` keys and every numeric
    ``<element or node>.<parameter>`` of the network), the scene scalars
    T_ambient_C, T_oil_in_C, oil_flow_L_h, mu_boundary, mu_full_film, and —
    for scenes on the SKF global model (``[models] losses = "skf"``) — skf_R1,
    skf_S1, skf_mu_EHL.
    """
    names = list(scene.network_parameters)
    names += [k for k in _network_numeric_parameters(scene) if k not in names]
    names += list(_SCENE_SCALARS)
    if scene.models.get("losses") == "skf":
        names += list(_SKF)
    return names


def _parse_param(scene: Scene, spec: str):
    name, _, start = spec.partition("=")
    name = name.strip()
    if name in _SKF and scene.models.get("losses") != "skf":
        raise InputError("--param", name, 'SKF constants need a scene on the SKF model: [models] losses = "skf"')
    known = parameter_names(scene)
    if name not in known:
        raise InputError("--param", name, f"unknown parameter; this scene offers: {', '.join(known)}")
    if start.strip():
        try:
            x0 = float(start)
        except ValueError:
            raise InputError(f"--param {name}", start, "start value must be a number") from None
    elif name in scene.network_parameters:
        x0 = scene.network_parameters[name]
    elif "." in name:
        x0 = _network_numeric_parameters(scene)[name]
    elif name in _SKF:
        x0 = scene.models.get(name)
        if x0 is None:
            x0 = 0.05 if name == "skf_mu_EHL" else _skf_table(scene)[name.split("_")[1]]
    elif name == "oil_flow_L_h":
        x0 = scene.oil_flow * 3.6e6
    else:
        x0 = getattr(scene, name)
    if x0 is None or isinstance(x0, bool) or not isinstance(x0, (int, float)) or not math.isfinite(x0):
        raise InputError(f"--param {name}", x0, "needs a finite numeric start value (give NAME=START)")
    return name, float(x0)


def _skf_table(scene):
    b = scene.bearing
    return skf_constants(b.kind, b.series)


def _apply(scene: Scene, values: dict) -> Scene:
    net = {k: v for k, v in values.items() if k in scene.network_parameters or "." in k}
    sc = scene.with_(network_parameters=net) if net else scene
    skf = {k: v for k, v in values.items() if k in _SKF}
    if skf:
        sc = sc.with_(models=skf)
    w = {k: v for k, v in values.items() if k in ("T_ambient_C", "T_oil_in_C", "oil_flow_L_h")}
    if w:
        sc = sc.with_(**w)
    rep = {k: v for k, v in values.items() if k in ("mu_boundary", "mu_full_film")}
    for k, v in rep.items():
        if not 0.0 <= v <= 1.0:
            raise InputError(k, v, "friction coefficient must lie in [0, 1]")
    if rep:
        sc = dataclasses.replace(sc, **rep)
    return sc


@dataclass
class Calibration:
    """Fitted parameters with standard uncertainties.

    Attributes
    ----------
    values : dict          name → fitted value
    std : dict             name → standard uncertainty (None if the data do not determine it)
    start : dict           name → start value
    cov : ndarray          covariance of the parameters (in the order of ``values``)
    rms_residual : float   RMS weighted residual (≈ K for temperatures) at the optimum
    dof : int              residuals − parameters
    nfev : int             model evaluations
    comparison : Comparison  the log against the calibrated scene
    scene : Scene          the calibrated scene
    """

    values: dict
    std: dict
    start: dict
    cov: np.ndarray
    rms_residual: float
    dof: int
    nfev: int
    comparison: Comparison | None = None
    scene: Scene | None = field(default=None, repr=False)
    message: str = ""

    def as_dict(self) -> dict:
        return {"values": self.values, "std": self.std, "start": self.start, "cov": self.cov,
                "rms_residual": self.rms_residual, "dof": self.dof, "nfev": self.nfev, "message": self.message,
                "metrics": self.comparison.metrics if self.comparison else None}

    def summary(self) -> str:
        w = max([18] + [len(k) for k in self.values])
        lines = [f"calibration: {self.nfev} model evaluations, RMS residual {self.rms_residual:.4g} "
                 f"(K, or % of torque), {self.dof} degrees of freedom", "",
                 f"{'parameter':{w}s} {'start':>12s} {'fitted':>12s} {'std':>12s}"]
        for k, v in self.values.items():
            s = self.std[k]
            lines.append(f"{k:{w}s} {self.start[k]:12.5g} {v:12.5g} " + (f"{s:12.3g}" if s is not None else f"{'n/a':>12s}"))
        if self.message:
            lines += ["", self.message]
        if self.comparison is not None:
            lines += ["", self.comparison.summary()]
        return "\n".join(lines)


def calibrate(scene: Scene, log: RigLog, params: list, mapping: dict, *, T0_C=None, max_nfev: int = 60,
              diff_step: float = 1e-3) -> Calibration:
    r"""Fit named parameters of a scene to a rig log (nonlinear least squares).

    Parameters
    ----------
    scene : Scene
    log : RigLog
    params : list[str]     names (``NAME`` or ``NAME=START``, see :func:`parameter_names`): network
                           parameters (``"bearing_to_ambient.G_W_K"``, ``"oil_stream.beta"``, or a
                           ``[thermal.parameters]`` key), T_ambient_C, T_oil_in_C, oil_flow_L_h,
                           mu_boundary, mu_full_film, or on an SKF scene skf_R1, skf_S1, skf_mu_EHL
                           (seed 002 re-calibrates R1, S1 for the 51107 this way)
    mapping : dict         channel → node (:func:`channel_map`)
    T0_C : float           start temperature of transient logs [°C] (default ambient)
    max_nfev : int         budget of model evaluations
    diff_step : float      relative finite-difference step of the Jacobian

    Returns
    -------
    Calibration

    Notes
    -----
    Positive parameters are fitted as ln p (p stays positive; the standard
    uncertainty is σ_p = p σ_ln p).  Covariance = s² (JᵀJ)⁻¹, s² = Σ r²/(m − p);
    with m = p (no degrees of freedom) the uncertainty is not determined (None).
    """
    if not params:
        raise InputError("--param", None, "name at least one parameter to fit")
    specs = [_parse_param(scene, p) for p in params]
    names = [n for n, _ in specs]
    if len(set(names)) != len(names):
        raise InputError("--param", ", ".join(names), "each parameter once")
    x0 = np.array([v for _, v in specs])
    logsp = np.array([v > 0 and not n.endswith("_C") for n, v in specs])

    def values_of(x):
        return {n: float(np.exp(xi) if lg else xi) for n, xi, lg in zip(names, x, logsp)}

    weights = {}
    if "torque_Nm" in log.columns:
        tq = log["torque_Nm"]
        if np.any(~np.isnan(tq)):
            weights["torque_Nm"] = 100.0 / max(float(np.nanmean(np.abs(tq))), 1e-300)
    fit_channels = [c for c, n in mapping.items() if not _special(n)]
    nfev = [0]

    def resid(x):
        nfev[0] += 1
        sim = simulate_log(_apply(scene, values_of(x)), log, mapping, T0_C=T0_C)
        chans = fit_channels + (["torque_Nm"] if "torque_Nm" in weights else [])
        r = []
        for c in chans:
            y = log[c]
            ok = ~np.isnan(y)
            r.append((sim[c][ok] - y[ok]) * weights.get(c, 1.0))
        return np.concatenate(r) if r else np.zeros(0)

    xs0 = np.where(logsp, np.log(np.where(logsp, x0, 1.0)), x0)
    r0 = resid(xs0)
    m, p = r0.size, len(names)
    if m < p:
        raise InputError("--param", ", ".join(names), f"{p} parameters but only {m} measured values")
    res = least_squares(resid, xs0, method="trf", diff_step=diff_step, max_nfev=max_nfev, x_scale=1.0)
    rms = float(np.sqrt(np.mean(res.fun**2))) if m else 0.0
    if res.status <= 0:
        raise NoConvergence(f"calibration did not converge: {res.message}", iterations=int(res.nfev),
                            residual=rms, last=values_of(res.x))
    J = res.jac
    dof = m - p
    JTJ = J.T @ J
    vals = values_of(res.x)
    std = {n: None for n in names}
    cov = np.full((p, p), np.nan)
    msg = ""
    if np.linalg.cond(JTJ) > 1e14:
        msg = "the data do not determine these parameters independently (singular Jacobian): no uncertainty"
    elif dof == 0:
        msg = "as many parameters as measured values: exact fit, uncertainty not determined"
    else:
        s2 = float(res.fun @ res.fun) / dof
        cov_x = s2 * np.linalg.inv(JTJ)
        scale = np.array([vals[n] if lg else 1.0 for n, lg in zip(names, logsp)])
        cov = cov_x * np.outer(scale, scale)
        std = {n: float(np.sqrt(cov[i, i])) for i, n in enumerate(names)}
    cal_scene = _apply(scene, vals)
    comp = compare(cal_scene, log, mapping, T0_C=T0_C)
    return Calibration(values=vals, std=std, start=dict(zip(names, x0.tolist())), cov=cov, rms_residual=rms,
                       dof=dof, nfev=nfev[0], comparison=comp, scene=cal_scene, message=msg)
