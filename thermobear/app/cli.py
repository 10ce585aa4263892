"""Command-line interface: ``thermobear <verb> ...``.

Verbs: ``run`` (steady state), ``transient`` (heat-up, optional speed/load
schedule), ``sweep`` (grid over speed, load, temperature, lubricant),
``compare`` (a rig log against a simulation), ``calibrate`` (fit uncertain
parameters to a rig log), ``spin-down`` (seed 001 coast-down rig), ``loads``
and ``list``.  ``--json`` prints JSON, ``--plot DIR`` writes PNGs.

Every bad input ends with a one-line message naming the field, the value and
what is expected, exit code 2 and no traceback (``--debug`` shows it); a
solver that cannot deliver (thermal runaway, no convergence) exits with 3.
All inputs and output paths are validated before anything is computed, and
files are written whole (temporary file, then renamed) or not at all.
"""
from __future__ import annotations

import argparse
import csv
import io
import json
import os
import sys
import warnings
from pathlib import Path

import numpy as np

from thermobear.errors import InputError, NoEquilibrium, SolverError, ThermobearError

EXIT_BAD_INPUT = 2
EXIT_SOLVER = 3


# --------------------------------------------------------------------------- helpers
def _jsonable(x):
    if isinstance(x, dict):
        return {str(k): _jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_jsonable(v) for v in x]
    if isinstance(x, np.ndarray):
        return _jsonable(x.tolist())
    if isinstance(x, (np.floating, float)):
        return None if not np.isfinite(x) else float(x)
    if isinstance(x, (np.integer,)):
        return int(x)
    if isinstance(x, (np.bool_,)):
        return bool(x)
    if isinstance(x, np.str_):
        return str(x)
    return x


def _print_json(d):
    print(json.dumps(_jsonable(d), indent=2, ensure_ascii=False))


def _overrides(items):
    out = {}
    for it in items or []:
        if "=" not in it:
            raise InputError("--set", it, "expected key=value, e.g. --set n_rpm=6500")
        k, v = it.split("=", 1)
        k = k.strip()
        try:
            val = float(v)
        except ValueError:
            val = v.strip()
        if k.startswith("fixed_C."):           # --set fixed_C.inner_ring=52: a measured node temperature
            out.setdefault("T_fixed_C", {})[k.split(".", 1)[1]] = val
        else:
            out[k] = val
    return out


def _load_scene(path, sets=None):
    from thermobear.app.rig import resolve_scene_paths
    from thermobear.scene.scene import load_scene
    scene = resolve_scene_paths(load_scene(path))
    if sets:
        ov = _overrides(sets)
        if "T_fixed_C" in ov:
            ov["T_fixed_C"] = {**scene.T_fixed_C, **ov["T_fixed_C"]}
        scene = scene.with_(**ov)
    return scene


def _check_out_file(path, field):
    """An output file must be creatable: its folder exists and is writable, it is not a folder."""
    if path is None:
        return None
    p = Path(path)
    if p.is_dir():
        raise InputError(field, str(path), "is a folder; give a file name")
    parent = p.parent if str(p.parent) else Path(".")
    if not parent.is_dir():
        raise InputError(field, str(path), f"folder {parent} does not exist")
    if not os.access(parent, os.W_OK) or (p.exists() and not os.access(p, os.W_OK)):
        raise InputError(field, str(path), "not writable")
    return p


def _check_out_dir(path, field="--plot"):
    """A plot folder must exist or be creatable in a writable parent (created only when writing)."""
    if path is None:
        return None
    p = Path(path)
    if p.exists() and not p.is_dir():
        raise InputError(field, str(path), "exists and is not a folder")
    base = p if p.exists() else p.parent if str(p.parent) else Path(".")
    if not base.is_dir():
        raise InputError(field, str(path), f"parent folder {base} does not exist")
    if not os.access(base, os.W_OK):
        raise InputError(field, str(path), "not writable")
    return p


def _write_text(path: Path, text: str):
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, path)


def _csv_text(header, rows, comments=()):
    buf = io.StringIO()
    for c in comments:
        buf.write(f"# {c}\n")
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(header)
    for r in rows:
        w.writerow(["" if v is None else (f"{v:.10g}" if isinstance(v, (float, np.floating)) else v) for v in r])
    return buf.getvalue()


def _flatten(d, pre=""):
    out = {}
    for k, v in d.items():
        if isinstance(v, dict):
            out.update(_flatten(v, f"{pre}{k}."))
        elif isinstance(v, (list, tuple, np.ndarray)) and np.ndim(v) > 0:
            continue                                     # per-ball arrays do not fit a CSV row
        else:
            out[f"{pre}{k}"] = v.item() if isinstance(v, np.generic) else v
    return out


def _parse_values(text, field, *, allow_str=False):
    """``"a:b:n"`` → n values from a to b (inclusive); ``"a,b,c"`` → the list; ``"a"`` → [a]."""
    s = str(text).strip()
    if ":" in s:
        parts = s.split(":")
        if len(parts) != 3:
            raise InputError(field, text, "expected start:stop:count, e.g. 1000:8000:8")
        try:
            a, b, n = float(parts[0]), float(parts[1]), int(parts[2])
        except ValueError:
            raise InputError(field, text, "expected numbers start:stop:count (count an integer)") from None
        if n < 1 or n > 100000 or not (np.isfinite(a) and np.isfinite(b)):
            raise InputError(field, text, "count must lie in 1..100000 and start, stop be finite")
        return np.linspace(a, b, n).tolist()
    items = [v.strip() for v in s.split(",") if v.strip()]
    if not items:
        raise InputError(field, text, "expected a value, a list a,b,c or a range start:stop:count")
    if allow_str:
        return items
    try:
        vals = [float(v) for v in items]
    except ValueError:
        raise InputError(field, text, "expected numbers a,b,c or a range start:stop:count") from None
    if not all(np.isfinite(vals)):
        raise InputError(field, text, "values must be finite")
    return vals


class _Progress:
    """Progress bar on stderr: ``progress(done, total)``."""

    def __init__(self, enabled=True, stream=None, label="sweep"):
        self.enabled, self.stream, self.label = enabled, stream or sys.stderr, label

    def __call__(self, done, total=None, *args, **kw):
        if not self.enabled:
            return
        total = total or 1
        k = int(30 * done / total)
        self.stream.write(f"\r{self.label} [{'#' * k}{'.' * (30 - k)}] {done}/{total}")
        if done >= total:
            self.stream.write("\n")
        self.stream.flush()


def _wrote(paths):
    for p in paths:
        print(f"wrote {p}", file=sys.stderr)


# --------------------------------------------------------------------------- run / loads / list
def _cmd_run(args):
    from thermobear.coupled.solver import solve
    _check_out_dir(args.plot)
    scene = _load_scene(args.scene, args.set)
    res = solve(scene)
    if args.json:
        _print_json(res.as_dict())
    else:
        print(res.summary())
    if args.plot:
        from thermobear.app.plots import plot_result
        _wrote(plot_result(res, args.plot))
    return 0


def _cmd_loads(args):
    from thermobear.loads.static import load_distribution
    scene = _load_scene(args.scene)
    ld = load_distribution(scene.bearing, Fa=scene.Fa, Fr=scene.Fr, M=scene.M)
    d = {"bearing": scene.bearing.name, "Fa_N": scene.Fa, "Fr_N": scene.Fr,
         "delta_a_um": ld.delta_a * 1e6, "delta_r_um": ld.delta_r * 1e6, "theta_mrad": ld.theta * 1e3,
         "Q_N": ld.Q, "alpha_deg": np.rad2deg(ld.alpha_i), "psi_deg": np.rad2deg(ld.psi),
         "residual": ld.residual, "iterations": ld.iterations}
    if args.json:
        _print_json(d)
    else:
        print(f"{scene.bearing.name}: Fa = {scene.Fa:g} N, Fr = {scene.Fr:g} N -> "
              f"delta_a = {d['delta_a_um']:.3f} um, delta_r = {d['delta_r_um']:.3f} um "
              f"(residual {ld.residual:.1e}, {ld.iterations} iterations)")
        print(f"{'ball':>4s} {'psi [deg]':>10s} {'Q [N]':>10s} {'alpha [deg]':>12s}")
        for j in range(scene.bearing.Z):
            print(f"{j:4d} {d['psi_deg'][j]:10.1f} {ld.Q[j]:10.2f} {d['alpha_deg'][j]:12.2f}")
    return 0


def _cmd_list(args):
    from thermobear.contact.geometry import bearing_names
    from thermobear.lubrication.lubricant import lubricant_names
    from thermobear.contact.materials import material_names
    from thermobear.files import data_dir, names_in
    what = {"bearings": bearing_names(), "lubricants": lubricant_names(), "materials": material_names(),
            "networks": names_in(data_dir("networks")),
            "examples": sorted(p.name for p in data_dir("examples").glob("*.toml"))}
    if args.json:
        _print_json(what)
    else:
        for k, v in what.items():
            print(f"{k}: {', '.join(v)}")
    return 0


# --------------------------------------------------------------------------- transient
_SCHEDULE_KEYS = {"t_s", "n_rpm", "Fa_N", "Fr_N", "M_Nm", "T_oil_in_C", "T_ambient_C", "oil_flow_L_h", "lubricant"}


def read_schedule(path, scene=None, t_end_s=None) -> list:
    """Read a schedule TOML (``[[step]]`` tables with ``t_s`` and scene overrides) → [(t_s, {...}), ...].

    Each step is checked against the scene (``Scene.with_``) when one is given.
    """
    from thermobear.files import read_toml
    p = Path(path)
    if not p.is_file():
        raise InputError("--schedule", str(path), "file not found")
    d = read_toml(str(p.resolve()))
    if set(d) - {"step"} or not isinstance(d.get("step"), list) or not d["step"]:
        raise InputError(f"{p.name}", ", ".join(sorted(d)) or None,
                         "expected [[step]] tables, e.g. [[step]] t_s = 600.0  n_rpm = 4800.0")
    out, sc = [], scene
    for i, st in enumerate(d["step"]):
        where = f"{p.name}: step[{i}]"
        if not isinstance(st, dict):
            raise InputError(where, st, "must be a table")
        for k in st:
            if k not in _SCHEDULE_KEYS:
                raise InputError(f"{where}.{k}", st[k], f"unknown key; accepted: {', '.join(sorted(_SCHEDULE_KEYS))}")
        t = st.get("t_s")
        if isinstance(t, bool) or not isinstance(t, (int, float)) or not np.isfinite(t) or t < 0:
            raise InputError(f"{where}.t_s", t, "step time must be a number >= 0 [s]")
        if t_end_s is not None and t >= t_end_s:
            raise InputError(f"{where}.t_s", t, f"must be < --t-end ({t_end_s:g} s)")
        if out and t <= out[-1][0]:
            raise InputError(f"{where}.t_s", t, "step times must increase")
        ch = {k: v for k, v in st.items() if k != "t_s"}
        if sc is not None:
            sc = sc.with_(**ch)
        out.append((float(t), ch))
    return out


def _cmd_transient(args):
    from thermobear.coupled.solver import transient
    if not (np.isfinite(args.t_end) and args.t_end > 0):
        raise InputError("--t-end", args.t_end, "end time must be > 0 [s]")
    if args.points < 2 or args.points > 100000:
        raise InputError("--points", args.points, "number of output times must lie in 2..100000")
    out_csv = _check_out_file(args.csv, "--csv")
    _check_out_dir(args.plot)
    scene = _load_scene(args.scene, args.set)
    if scene.T_C is not None:
        raise InputError("operation.T_C", scene.T_C, "a transient solves the thermal network: remove the prescribed "
                         "temperature (and give [thermal] network)")
    schedule = read_schedule(args.schedule, scene, args.t_end) if args.schedule else []
    t_eval = np.linspace(0.0, args.t_end, args.points)
    run = transient(scene, args.t_end, schedule=schedule, T0_C=args.T0_C, t_eval=t_eval)
    nodes = list(run.T_C)
    header = ["t_s"] + [f"T_{n}_C" for n in nodes] + ["P_W"] + [f"P_{k}_W" for k in run.breakdown_W]
    cols = [run.t_s] + [run.T_C[n] for n in nodes] + [run.P_W] + list(run.breakdown_W.values())
    rows = list(zip(*[np.asarray(c, float) for c in cols]))
    final = {n: float(run.T_C[n][-1]) for n in nodes}
    if out_csv:
        _write_text(out_csv, _csv_text(header, rows, [f"thermobear transient of {scene.name} ({args.scene}), "
                                                       f"t_end {args.t_end:g} s"]))
        print(f"wrote {out_csv}", file=sys.stderr)
    if args.json:
        _print_json({"scene": scene.name, "t_s": run.t_s, "T_C": run.T_C, "P_W": run.P_W,
                     "breakdown_W": run.breakdown_W, "schedule": schedule, "final_T_C": final})
    else:
        from thermobear.app.rig import metrics
        print(f"thermobear transient — {scene.name}: {args.t_end:g} s, {len(schedule)} schedule steps")
        print(f"\n{'node':18s} {'start [°C]':>11s} {'end [°C]':>10s} {'t90 [s]':>9s}")
        for n in nodes:
            T = np.asarray(run.T_C[n], float)
            t90 = metrics(T, T, run.t_s)["t90_simulated_s"]
            print(f"{n:18s} {T[0]:11.2f} {T[-1]:10.2f} " + (f"{t90:9.0f}" if t90 is not None else f"{'-':>9s}"))
        print(f"\nPower loss at the end {run.P_W[-1]:.3f} W (start {run.P_W[0]:.3f} W)")
        for k, v in run.breakdown_W.items():
            print(f"  {k:12s} {float(v[-1]):10.4f} W")
    if args.plot:
        from thermobear.app.plots import plot_heatup
        d = Path(args.plot)
        d.mkdir(parents=True, exist_ok=True)
        free = {n: run.T_C[n] for n in nodes if np.ptp(run.T_C[n]) > 0}
        _wrote([plot_heatup(run.t_s, free, d / "heatup.png", title=f"Heat-up — {scene.name}")])
    return 0


# --------------------------------------------------------------------------- sweep
def _cmd_sweep(args):
    out_csv = _check_out_file(args.csv, "--csv")
    _check_out_dir(args.plot)
    if args.processes is not None and args.processes < 1:
        raise InputError("--processes", args.processes, "must be >= 1")
    scene = _load_scene(args.scene, args.set)
    grid = {}
    if args.n_rpm is not None:
        grid["n_rpm"] = _parse_values(args.n_rpm, "--n-rpm")
    if args.Fa is not None:
        grid["Fa_N"] = _parse_values(args.Fa, "--Fa")
    if args.Fr is not None:
        grid["Fr_N"] = _parse_values(args.Fr, "--Fr")
    if args.T_C is not None:
        grid["T_C"] = _parse_values(args.T_C, "--T-C")
    if args.lubricant is not None:
        grid["lubricant"] = _parse_values(args.lubricant, "--lubricant", allow_str=True)
    if not grid:
        raise InputError("sweep", None, "give at least one of --n-rpm, --Fa, --Fr, --T-C, --lubricant")
    # validate every value of every axis on the scene before computing anything
    for k, vals in grid.items():
        for v in vals:
            scene.with_(**{k: v})
    try:
        from thermobear.app.sweep import run_sweep
    except ImportError:
        raise InputError("sweep", None, "thermobear.app.sweep is not installed in this version") from None
    rows = run_sweep(scene, grid, scheduler=args.scheduler, processes=args.processes,
                     progress=_Progress(enabled=not args.quiet))
    flat = [_flatten(r) for r in rows]
    header = []
    for r in flat:
        header += [k for k in r if k not in header]
    if out_csv:
        _write_text(out_csv, _csv_text(header, [[r.get(k) for k in header] for r in flat],
                                       [f"thermobear sweep of {scene.name} ({args.scene}): "
                                        + ", ".join(f"{k} x{len(v)}" for k, v in grid.items())]))
        print(f"wrote {out_csv}", file=sys.stderr)
    if args.json:
        _print_json(rows)
    elif not out_csv:
        print(_csv_text(header, [[r.get(k) for k in header] for r in flat]), end="")
    else:
        print(f"{len(rows)} operating points, columns: {', '.join(header)}")
    if args.plot and "n_rpm" in grid:
        from thermobear.app.plots import plot_vs_speed
        d = Path(args.plot)
        d.mkdir(parents=True, exist_ok=True)
        key = "torque_Nm" if "torque_Nm" in header else "P_W"
        if key in header:
            others = [k for k in grid if k != "n_rpm"]
            series = {}
            for r in flat:
                lab = ", ".join(f"{k}={r.get(k, r.get(k.replace('_N', '')))}" for k in others) or key
                series.setdefault(lab, ([], []))
                series[lab][0].append(r.get("n_rpm")), series[lab][1].append(r.get(key))
            import matplotlib.pyplot as plt
            from thermobear.app.plots import _save
            fig, ax = plt.subplots(figsize=(7, 4.5))
            for lab, (x, y) in series.items():
                o = np.argsort(x)
                ax.plot(np.asarray(x, float)[o], np.asarray(y, float)[o] * (1e3 if key == "torque_Nm" else 1), "-o",
                        ms=3, label=lab)
            ax.set_xlabel("speed n [rpm]"), ax.set_ylabel("friction torque [N mm]" if key == "torque_Nm" else "P [W]")
            ax.legend(fontsize=7), ax.grid(alpha=0.3), ax.set_title(f"Sweep — {scene.name}")
            paths = [_save(fig, d / f"sweep_{key}.png")]
            bkeys = [k for k in header if k.startswith("breakdown_W.")]
            from thermobear.app.plots import plot_losses_vs_speed
            groups = {}
            for r in flat:
                if r.get("status", "ok") != "ok":
                    continue
                lab = ", ".join(f"{k}={r.get(k)}" for k in others)
                groups.setdefault(lab, []).append(r)
            for i, (lab, rs) in enumerate(list(groups.items())[:6]):
                bd = {k.split(".", 1)[1]: [r.get(k) for r in rs] for k in bkeys}
                paths.append(plot_losses_vs_speed([r["n_rpm"] for r in rs], bd, d / f"sweep_losses_{i + 1}.png",
                                                  f"Loss breakdown vs speed — {scene.name}" + (f" ({lab})" if lab else "")))
            _wrote(paths)
    return 0


# --------------------------------------------------------------------------- compare / calibrate
def _rig_inputs(args):
    from thermobear.app.rig import channel_map, parse_map, read_log
    scene = _load_scene(args.scene, getattr(args, "set", None))
    log = read_log(args.log)
    mapping = channel_map(scene, log, parse_map(args.map))
    return scene, log, mapping


def _plot_comparison(comp, outdir, title, prefix="compare"):
    from thermobear.app.plots import plot_heatup, plot_vs_speed
    d = Path(outdir)
    d.mkdir(parents=True, exist_ok=True)
    paths = []
    temps = {k: v for k, v in comp.simulated.items() if k != "torque_Nm"}
    if comp.kind == "transient":
        if temps:
            meas = {k: (comp.x, comp.measured[k]) for k in temps}
            paths.append(plot_heatup(comp.x, temps, d / f"{prefix}_heatup.png", meas, title=title,
                                     mapping=comp.mapping))
        if "torque_Nm" in comp.simulated:
            paths.append(plot_vs_speed(comp.x, {"torque": comp.simulated["torque_Nm"]}, d / f"{prefix}_torque.png",
                                       {"torque": comp.measured["torque_Nm"]}, "friction torque [N mm]", title, 1e3))
    else:
        labels = comp.log.columns.get("lubricant")
        if "torque_Nm" in comp.simulated:
            paths.append(plot_vs_speed(comp.x, {"torque": comp.simulated["torque_Nm"]}, d / f"{prefix}_torque.png",
                                       {"torque": comp.measured["torque_Nm"]}, "friction torque [N mm]",
                                       f"Torque vs speed — {title}", 1e3, labels=labels))
        if temps:
            paths.append(plot_vs_speed(comp.x, temps, d / f"{prefix}_temperature.png",
                                       {k: comp.measured[k] for k in temps}, "temperature [°C]",
                                       f"Temperature vs speed — {title}", labels=labels))
    return paths


def _cmd_compare(args):
    from thermobear.app.rig import compare
    _check_out_dir(args.plot)
    out_csv = _check_out_file(args.csv, "--csv")
    scene, log, mapping = _rig_inputs(args)
    comp = compare(scene, log, mapping, T0_C=args.T0_C)
    if out_csv:
        chans = list(comp.measured)
        header = ["t_s" if comp.kind == "transient" else "n_rpm"] + [f"{c}{s}" for c in chans for s in ("", "_model")]
        rows = [[comp.x[i]] + [v for c in chans for v in (comp.measured[c][i], comp.simulated[c][i])]
                for i in range(comp.x.size)]
        _write_text(out_csv, _csv_text(header, rows, [f"thermobear compare: {args.log} vs {scene.name}"]))
        print(f"wrote {out_csv}", file=sys.stderr)
    if args.json:
        _print_json(comp.as_dict())
    else:
        print(comp.summary())
    if args.plot:
        _wrote(_plot_comparison(comp, args.plot, f"{Path(args.log).name} vs {scene.name}"))
    return 0


def _cmd_calibrate(args):
    from thermobear.app.rig import calibrate
    _check_out_dir(args.plot)
    if args.max_nfev < 1:
        raise InputError("--max-nfev", args.max_nfev, "must be >= 1")
    scene, log, mapping = _rig_inputs(args)
    cal = calibrate(scene, log, args.param, mapping, T0_C=args.T0_C, max_nfev=args.max_nfev)
    if args.json:
        _print_json(cal.as_dict())
    else:
        print(cal.summary())
    if args.plot and cal.comparison is not None:
        _wrote(_plot_comparison(cal.comparison, args.plot, f"{Path(args.log).name}, calibrated", prefix="calibrate"))
    return 0


# --------------------------------------------------------------------------- spin-down
def spin_down_runs(scene, J, rpms, *, n_table=80):
    r"""Coast-downs of the scene's rotor from each initial speed, fitted as seed 001 does.

    The friction torque T(ω) of the scene (prescribed temperature) is tabulated
    on a log grid of speeds (one vectorised loss evaluation), interpolated
    log-log (power law below the grid), and J dω/dt = −T(ω) is integrated until
    the rotor stops (:func:`thermobear.app.spindown.integrate_spin_down`).  From the
    stop time t_max and the angle φ_max, K* and n follow as in seed 001 eqs 20–21
    (:func:`thermobear.app.spindown.fit_from_stop`).  K* and n do not depend on J
    (t_max ∝ J); J sets only the time scale.
    """
    import dataclasses
    from thermobear.coupled.solver import choose_models, scene_losses
    from thermobear.app.spindown import fit_from_stop, integrate_spin_down
    out = []
    for rpm in rpms:
        sc = scene.with_(n_rpm=rpm)
        models = choose_models(sc)
        w0 = rpm * np.pi / 30.0
        wg = w0 * np.logspace(-5, 0, n_table)
        r = scene_losses(dataclasses.replace(sc, n_rpm=wg * 30.0 / np.pi), models=models)
        Tg = np.asarray(r.torque_Nm, float)
        if np.any(~np.isfinite(Tg)) or np.any(Tg <= 0):
            raise InputError("spin-down", rpm, "the model torque must be > 0 at every speed below the initial one")
        lw, lT = np.log(wg), np.log(Tg)
        n_low = (lT[1] - lT[0]) / (lw[1] - lw[0])

        def torque(w, lw=lw, lT=lT, n_low=n_low, Tg=Tg, wg=wg):
            if w <= 0:
                return 0.0
            if w < wg[0]:
                return float(Tg[0] * (w / wg[0]) ** max(n_low, 0.0))
            return float(np.exp(np.interp(np.log(w), lw, lT)))

        t_guess = J * w0 / Tg[-1] * 50.0
        sd = integrate_spin_down(J, torque, w0, t_guess, rtol=1e-9)
        if not np.isfinite(sd.t_stop):
            raise InputError("spin-down", rpm, f"the rotor does not stop within {t_guess:.3g} s (torque exponent >= 1)")
        fit = fit_from_stop(w0, sd.t_stop, float(sd.phi[-1]), J)
        out.append({"n0_rpm": rpm, "omega0_rad_s": w0, "T0_Nm": float(Tg[-1]), "t_stop_s": sd.t_stop,
                    "phi_max_rad": float(sd.phi[-1]), "K_star": fit.K, "n": fit.n,
                    "T_fit_at_omega0_Nm": fit.K * w0 ** fit.n, "_sd": sd})
    return out


def _cmd_spin_down(args):
    from thermobear.app.rig import read_log
    _check_out_dir(args.plot)
    scene = _load_scene(args.scene, args.set)
    if scene.T_C is None:
        raise InputError("operation.T_C", None, "the spin-down rig model needs a prescribed temperature (seed 001: 26.5 °C)")
    J = args.J
    if J is None:
        rig = scene.raw.get("rig", {}) if isinstance(scene.raw, dict) else {}
        J = rig.get("J_kg_m2") if isinstance(rig, dict) else None
    if J is None:
        raise InputError("rig.J_kg_m2", None, "the spin-down needs the rotating inertia J [kg m²]: give --J or "
                         "[rig] J_kg_m2 in the scene")
    if isinstance(J, bool) or not isinstance(J, (int, float)) or not (np.isfinite(J) and J > 0):
        raise InputError("rig.J_kg_m2", J, "inertia must be > 0 [kg m²]")
    log = read_log(args.log) if args.log else None
    if log is not None and not ({"n_rpm", "torque_Nm"} <= set(log.columns)) or (log is not None and log.kind != "steady"):
        raise InputError("--log", args.log, "a spin-down log has n_rpm and torque_Nm columns and no t_s")
    rpms = _parse_values(args.rpm, "--rpm") if args.rpm else (list(log["n_rpm"]) if log is not None else [scene.n_rpm])
    for r in rpms:
        if not r > 0:
            raise InputError("--rpm", r, "initial speeds must be > 0 [rpm]")
    if log is not None and "Fa_N" in log.columns and np.any(np.abs(log["Fa_N"] - scene.Fa) > 1e-6 * max(scene.Fa, 1)):
        raise InputError("--log", args.log, f"its Fa_N differs from the scene's Fa = {scene.Fa:g} N (another rig set-up)")
    runs = spin_down_runs(scene, float(J), rpms)
    if log is not None:
        for r in runs:
            k = np.flatnonzero(np.isclose(log["n_rpm"], r["n0_rpm"]))
            r["T_log_Nm"] = float(log["torque_Nm"][k[0]]) if k.size else None
            r["T_error"] = r["T0_Nm"] / r["T_log_Nm"] - 1 if r["T_log_Nm"] else None
    pub = [{k: v for k, v in r.items() if not k.startswith("_")} for r in runs]
    if args.json:
        _print_json({"scene": scene.name, "J_kg_m2": J, "T_C": scene.T_C, "runs": pub})
    else:
        print(f"thermobear spin-down — {scene.name}: J = {J:g} kg m², T = {scene.T_C:g} °C; "
              "K*, n from t_max and φ_max (seed 001 eqs 20–21)")
        head = f"{'n0 [rpm]':>8s} {'t_stop [s]':>10s} {'phi [rad]':>10s} {'K* [N m s^n]':>13s} {'n':>6s} {'T(w0) [N m]':>12s}"
        if log is not None:
            head += f" {'log [N m]':>10s} {'error':>7s}"
        print(head)
        for r in pub:
            line = (f"{r['n0_rpm']:8.0f} {r['t_stop_s']:10.2f} {r['phi_max_rad']:10.2f} {r['K_star']:13.4e} "
                    f"{r['n']:6.3f} {r['T0_Nm']:12.4e}")
            if log is not None:
                line += (f" {r['T_log_Nm']:10.4e} {100 * r['T_error']:+6.1f}%" if r.get("T_log_Nm") else "")
            print(line)
    if args.plot:
        from thermobear.app.plots import plot_spin_down, plot_vs_speed
        d = Path(args.plot)
        d.mkdir(parents=True, exist_ok=True)
        paths = [plot_spin_down([(f"{r['n0_rpm']:g} rpm", r["_sd"].t, r["_sd"].omega) for r in runs],
                                d / "spin_down.png", f"Spin-down — {scene.name}, J = {J:g} kg m²")]
        n0 = np.array([r["n0_rpm"] for r in runs])
        sim = {"torque at the initial speed": np.array([r["T0_Nm"] for r in runs])}
        meas = ({"torque at the initial speed": np.array([r.get("T_log_Nm") or np.nan for r in runs])}
                if log is not None else None)
        paths.append(plot_vs_speed(n0, sim, d / "spin_down_torque.png", meas, "friction torque [N mm]",
                                   f"Torque vs speed — {scene.name}", 1e3))
        _wrote(paths)
    return 0


# --------------------------------------------------------------------------- parser
def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="thermobear", description="Power loss and temperatures of rolling bearings.")
    p.add_argument("--version", action="version", version=f"thermobear {_version()}")
    p.add_argument("--debug", action="store_true", help="show tracebacks")
    sub = p.add_subparsers(dest="verb", required=True)

    def common(sp, plot=True, sets=True):
        sp.add_argument("--json", action="store_true", help="print JSON")
        if plot:
            sp.add_argument("--plot", metavar="DIR", help="write PNG plots to DIR")
        if sets:
            sp.add_argument("--set", action="append", metavar="KEY=VALUE",
                            help="override n_rpm, Fa, Fr, T_C, T_ambient_C, lubricant, ...; "
                                 "fixed_C.<node>=T imposes a measured node temperature [°C]")
        sp.add_argument("--debug", action="store_true", default=argparse.SUPPRESS, help="show tracebacks")

    r = sub.add_parser("run", help="coupled steady state of a scene (temperatures, power, models used)")
    r.add_argument("scene", help="scene file (TOML), e.g. examples/seed004_oil_jet_7210.toml")
    common(r)
    r.set_defaults(func=_cmd_run)

    tr = sub.add_parser("transient", help="heat-up of a scene: every node and the loss breakdown vs time")
    tr.add_argument("scene")
    tr.add_argument("--t-end", type=float, required=True, metavar="S", help="end time [s]")
    tr.add_argument("--schedule", metavar="FILE.toml", help="[[step]] tables: t_s and n_rpm, Fa_N, Fr_N, ...")
    tr.add_argument("--csv", metavar="OUT", help="write the time series as CSV")
    tr.add_argument("--points", type=int, default=201, help="number of output times (default 201)")
    tr.add_argument("--T0-C", dest="T0_C", type=float, default=None, help="start temperature [°C] (default ambient)")
    common(tr)
    tr.set_defaults(func=_cmd_transient)

    sw = sub.add_parser("sweep", help="grid over speed, load, temperature and lubricant (CSV out)")
    sw.add_argument("scene")
    sw.add_argument("--n-rpm", dest="n_rpm", metavar="A:B:N|a,b", help="speeds [rpm]")
    sw.add_argument("--Fa", metavar="A:B:N|a,b", help="axial loads [N]")
    sw.add_argument("--Fr", metavar="A:B:N|a,b", help="radial loads [N]")
    sw.add_argument("--T-C", dest="T_C", metavar="A:B:N|a,b", help="prescribed temperatures [°C]")
    sw.add_argument("--lubricant", metavar="NAME,...", help="lubricant names")
    sw.add_argument("--csv", metavar="OUT", help="write the results as CSV")
    sw.add_argument("--scheduler", metavar="tcp://host:port", help="dask scheduler address")
    sw.add_argument("--processes", type=int, default=None, help="local worker processes")
    sw.add_argument("--quiet", action="store_true", help="no progress bar")
    common(sw)
    sw.set_defaults(func=_cmd_sweep)

    def rig_args(sp):
        sp.add_argument("scene")
        sp.add_argument("log", help="rig log CSV (t_s / n_rpm, T_<name>_C, torque_Nm, ...)")
        sp.add_argument("--map", action="append", metavar="CHANNEL=NODE",
                        help="map a log channel to a network node (or 'input' / 'ignore')")
        sp.add_argument("--T0-C", dest="T0_C", type=float, default=None,
                        help="start temperature of a transient log [°C] (default ambient)")

    c = sub.add_parser("compare", help="a rig log against a simulation: RMSE, max error, steady-state error, t90")
    rig_args(c)
    c.add_argument("--csv", metavar="OUT", help="write measured and simulated values as CSV")
    common(c)
    c.set_defaults(func=_cmd_compare)

    ca = sub.add_parser("calibrate", help="fit uncertain parameters to a rig log (least squares, with uncertainty)")
    rig_args(ca)
    ca.add_argument("--param", action="append", required=True, metavar="NAME[=START]",
                    help="parameter to fit: a [thermal.parameters] name, T_ambient_C, mu_boundary, skf.R1, ...")
    ca.add_argument("--max-nfev", type=int, default=60, help="budget of model evaluations (default 60)")
    common(ca)
    ca.set_defaults(func=_cmd_calibrate)

    sd = sub.add_parser("spin-down", help="seed 001 coast-down rig: integrate J dω/dt = -T(ω), fit K*, n")
    sd.add_argument("scene")
    sd.add_argument("--J", type=float, default=None, metavar="KG_M2", help="rotating inertia [kg m²] "
                    "(default: [rig] J_kg_m2 of the scene)")
    sd.add_argument("--rpm", metavar="a,b|A:B:N", help="initial speeds [rpm] (default: the log's, else the scene's)")
    sd.add_argument("--log", metavar="LOG.csv", help="torque log (n_rpm, torque_Nm) to compare at the initial speeds")
    common(sd)
    sd.set_defaults(func=_cmd_spin_down)

    lo = sub.add_parser("loads", help="load distribution of a scene's bearing (per ball loads and angles)")
    lo.add_argument("scene")
    common(lo, plot=False, sets=False)
    lo.set_defaults(func=_cmd_loads)

    li = sub.add_parser("list", help="list bundled bearings, lubricants, materials, networks, examples")
    li.add_argument("--json", action="store_true")
    li.set_defaults(func=_cmd_list)
    return p


def _version():
    from thermobear import __version__
    return __version__


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    debug = getattr(args, "debug", False)
    try:
        with warnings.catch_warnings():
            if not debug:
                warnings.simplefilter("default")
            return int(args.func(args) or 0)
    except (InputError, NoEquilibrium) as e:   # bad input, incl. loads the bearing cannot carry
        if debug:
            raise
        print(f"error: {_one_line(e)}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except SolverError as e:
        if debug:
            raise
        print(f"error: {type(e).__name__}: {_one_line(e)}", file=sys.stderr)
        return EXIT_SOLVER
    except ThermobearError as e:
        if debug:
            raise
        print(f"error: {_one_line(e)}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except BrokenPipeError:                      # e.g. `thermobear run ... | head`
        try:
            sys.stdout = open(os.devnull, "w")
        except OSError:
            pass
        return 0


def _one_line(e) -> str:
    return " ".join(str(e).split())


if __name__ == "__main__":
    sys.exit(main())
