"""The command line's verbs: each checks its inputs and output paths first, then computes, then writes.

Every verb returns its exit code: 0 done, 2 bad input (raised as InputError and turned into one
line by :func:`thermobear.app.cli.main`), 3 a solver that could not deliver (or a sweep with failed
points, unless ``--allow-failures``), 130 interrupted (Ctrl-C or SIGTERM; what was finished is
kept and said where).
"""
from __future__ import annotations

import math
import signal
import sys
import warnings
from pathlib import Path

import numpy as np

from thermobear.app.output import (Progress, RowWriter, check_out_dir, check_out_file, csv_text, flatten,
                                   print_json, write_text, wrote)
from thermobear.app.bands import compare_bands
from thermobear.app.calibration import calibrate
from thermobear.app.overrides import load_scene_with, overrides  # noqa: F401  (overrides: its former home)
from thermobear.app.scaffold import scaffold
from thermobear.app.rig import channel_map, compare, parse_map, read_log
from thermobear.app.spindown import spin_down_runs
from thermobear.app.sweep import PAIR_STIFFNESS_COLUMNS, run_sweep, sweep_points
from thermobear.contact.geometry import bearing, bearing_names
from thermobear.contact.materials import material_names
from thermobear.coupled import solve, transient
from thermobear.coupled.limits import emit
from thermobear.parallel import check_processes
from thermobear.coupled.preload import cold_pair
from thermobear.coupled.transient_pair import preload_line
from thermobear.coupled.uncertainty import steady_uncertainty, transient_uncertainty
from thermobear.errors import InputError, ThermalPreloadRunaway
from thermobear.files import data_dir, names_in, read_toml
from thermobear.loads import load_distribution
from thermobear.losses import BREAKDOWN_KEYS
from thermobear.losses.skf import SKF_BREAKDOWN_KEYS
from thermobear.lubrication.lubricant import lubricant_names
from thermobear.coupled.clearance import scene_at_clearance
from thermobear.coupled.ratings import check_static_safety, scene_clearance
from thermobear.models import clearance_choice, moments, plan
from thermobear.rating.life import stated_ratings
from thermobear.scene.network import network_nodes
from thermobear.validity import T_LUBRICANT_REFUSE_C

__all__ = ["cmd_run", "cmd_loads", "cmd_list", "cmd_init", "cmd_transient", "cmd_sweep", "cmd_compare", "cmd_calibrate",
           "cmd_spin_down", "read_schedule", "EXIT_INTERRUPTED"]

EXIT_SOLVER = 3
EXIT_INTERRUPTED = 130


def _plot_dir(path):
    """The --plot folder, checked (creatable) with the plot module importable, before computing."""
    out = check_out_dir(path)
    if out is not None:
        _plots()
    return out


def _plots():
    """The plot module (matplotlib is the optional "plot" extra: a run without --plot never imports it)."""
    try:
        from thermobear.app import plots
    except ImportError as exc:
        raise InputError("--plot", None, f"plots need matplotlib: pip install 'thermobear[plot]' ({exc})") from None
    return plots


# --------------------------------------------------------------------------- inputs
def _T0(value, field="--T0-C"):
    """A start temperature [°C]: finite and in the lubricant's accepted range."""
    if value is None:
        return None
    lo, hi = T_LUBRICANT_REFUSE_C
    if not (np.isfinite(value) and lo <= value <= hi):
        raise InputError(field, value, f"start temperature must lie in [{lo:g}, {hi:g}] °C")
    return float(value)


def parse_values(text, field, *, allow_str=False):
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


def _uncertainty_kw(args) -> dict:
    """The sample design of ``--uncertainty N`` (``--seed``, ``--design``, ``--groups``, ``--sensitivity``)."""
    if args.uncertainty is not None and args.uncertainty < 1:
        raise InputError("--uncertainty", args.uncertainty, "a number of samples >= 1")
    if args.groups is not None and args.groups < 1:
        raise InputError("--groups", args.groups, "a number of bearing-geometry families >= 1")
    if args.sensitivity == "sobol":
        try:
            import SALib  # noqa: F401, PLC0415  (optional dependency: checked before computing)
        except ImportError:
            raise InputError("--sensitivity", "sobol", "needs SALib: pip install 'thermobear[sensitivity]'") from None
    return dict(seed=args.seed, method=args.design, groups=args.groups, sensitivity=args.sensitivity)


def _sample_warnings(unc):
    """On stderr: the samples that failed, and the caveat of the inputs' ranking (the draws do not determine
    its regression: :func:`~thermobear.coupled.sensitivity.regression_check`), once."""
    if unc.failed:
        print(f"warning: {len(unc.failed)} of {unc.n} samples failed (" + ", ".join(
            f"{k} {v}" for k, v in sorted(unc.failed_count.items())) + "): the bands are those of the others",
            file=sys.stderr)
    caveat = next((r["caveat"] for r in unc.sensitivity.values() if r.get("caveat")), None)
    if caveat:
        print(f"warning: {caveat['name']}: {caveat['message']}", file=sys.stderr)


# --------------------------------------------------------------------------- run / loads / list
def cmd_run(args):
    out = _plot_dir(args.plot)
    kw = _uncertainty_kw(args)
    scene = load_scene_with(args.scene, args.set)
    if args.uncertainty is not None and scene.T_C is not None:
        raise InputError("--uncertainty", args.uncertainty, "bands of the coupled solution: a scene with a thermal "
                         "network and no prescribed temperature (operation.T_C)")
    res = solve(scene)
    unc = None if args.uncertainty is None else steady_uncertainty(scene, args.uncertainty, nominal=res.steady, **kw)
    if args.json:
        print_json({**res.as_dict(), "uncertainty": unc.as_dict()} if unc else res.as_dict())
    else:
        print(res.summary())
        if unc:
            print("\n" + unc.summary())
    if unc:
        _sample_warnings(unc)
    if out is not None:
        plots = _plots()
        wrote(plots.plot_result(res, out))
        if unc:
            wrote(plots.plot_bands(unc, out, title=f"Bands over the estimated inputs — {scene.name}"))
    return 0


def cmd_loads(args):
    """``thermobear loads``: the scene bearing's load distribution — which form (static or high-speed), the ring
    displacements with the axial one split into the free travel through the clearance and the elastic part,
    per-ball loads and angles; ``--plot DIR`` draws the ball loads around the bearing."""
    scene = load_scene_with(args.scene, args.set)
    out = _plot_dir(getattr(args, "plot", None))
    check_static_safety(scene)                              # before any solve (a pair: its loaded bearing's, below)
    pair = None
    if scene.arrangement is not None:      # one bearing of a preloaded pair: the pair cold, the loaded bearing at speed
        pair, pair_text, scene, pair_warned = cold_pair(scene)
        emit(pair_warned)
    models = plan(scene)[0]
    fitted = models["clearance"][0] in ("mounted", "operating")
    if fitted:                     # the fits' clearance at 20 °C (the operating one needs the solved temperatures)
        scene = scene_at_clearance(scene, scene_clearance(scene, {"x": 20.0}, dict.fromkeys(("inner", "outer", "ball"),
                                                                                          "x"))["mounted"] * 1e-6)
        models = {**plan(scene)[0], "clearance": models["clearance"]}   # its model choice (film, high speed) there
    hs = models["high_speed"][0] == "yes"
    brg, stiff = scene.bearing, scene.models.get("stiffness", "nominal")
    M, My = moments(scene)
    ld = load_distribution(brg, Fa=scene.Fa, Fr=scene.Fr, M=M, Fz=scene.Fz, My=My, n_rpm=scene.n_rpm if hs else 0.0,
                           form="high_speed" if hs else "static", stiffness=stiff)
    form = (f"high-speed solution (Jones 1960: ball centrifugal force and gyroscopic moment at {scene.n_rpm:g} rpm, "
            "inner and outer contacts apart)" if hs else
            "static solution (low-speed Jones–Harris, rigid rings: no centrifugal force, one load per ball)")
    # the axial displacement from the centred rings: the rigid-body travel through the clearance to first contact
    # (A sin alpha0, taken when the bearing carries an axial load), then the rest — the elastic approach of the
    # contacts (and at speed the balls' outward shift)
    free = brg.A * np.sin(brg.alpha0) * np.sign(ld.delta_a) if (scene.Fa > 0 or brg.kind != "deep_groove") else 0.0
    free_txt = ("free axial play taken up through the clearance" if brg.kind == "deep_groove" else
                "rigid-body travel to first contact")
    rest_txt = "elastic approach and the balls' outward shift at speed" if hs else "elastic approach"
    d = {"bearing": brg.name, "form": form, "high_speed": hs, "Fa_N": scene.Fa, "Fr_N": scene.Fr, "M_Nm": scene.M,
         "Fz_N": scene.Fz, "My_Nm": scene.My,
         "n_rpm": scene.n_rpm, "delta_a_um": ld.delta_a * 1e6, "delta_a_free_um": free * 1e6,
         "delta_a_elastic_um": (ld.delta_a - free) * 1e6,
         "axial_end_play_um": brg.free_end_play * 1e6 if brg.kind == "deep_groove" else None,
         "delta_r_um": ld.delta_r * 1e6, "delta_z_um": ld.delta_z * 1e6, "theta_mrad": ld.theta * 1e3,
         "theta_y_mrad": ld.theta_y * 1e3, "Q_inner_N": ld.Q_i, "Q_outer_N": ld.Q_o,
         "alpha_inner_deg": np.rad2deg(ld.alpha_i), "alpha_outer_deg": np.rad2deg(ld.alpha_o),
         "psi_deg": np.rad2deg(ld.psi), "residual": ld.residual, "iterations": ld.iterations,
         "load_model": models["load_model"][0]}
    # the loads shown are dry; where `run` solves the scene with the films in the contact laws, say so
    note = (f"note: run solves this scene with the film load model ({models['load_model'][1]}): its ball loads "
            "depend on the films and their temperature; these are the dry loads (as models.load_model = jones_harris)"
            if models["load_model"][0] == "film" else None)
    if fitted:
        note = "; ".join(filter(None, [note, f"note: the loads at the mounted clearance {brg.Pd * 1e6:.3g} µm (the fits "
                                       f"at 20 °C; models.clearance = {models['clearance'][0]}"
                                       + ("; `run` solves the operating one" if models["clearance"][0] == "operating"
                                          else "") + ")"]))
    d["note"] = note
    if pair:
        d["pair"] = pair
    if args.json:
        print_json(d)
    else:
        if pair:
            print("\n".join(pair_text) + ("\nthe loaded bearing at speed:" if "at_speed" in pair else
                                          "\nthe loaded bearing (the static form: its outer ring rotates):"))
        m = "" if scene.M is None else f", M = {scene.M:g} N m"
        m += "" if not scene.Fz else f", Fz = {scene.Fz:g} N"
        m += "" if scene.My is None else f", My = {scene.My:g} N m"
        print(f"{brg.name}: Fa = {scene.Fa:g} N, Fr = {scene.Fr:g} N{m} — {form}")
        print(f"  delta_a = {d['delta_a_um']:.3f} um from the centred rings = {d['delta_a_free_um']:.3f} um {free_txt} "
              f"(A sin alpha0) {'+' if d['delta_a_elastic_um'] >= 0 else '-'} {abs(d['delta_a_elastic_um']):.3f} um "
              f"{rest_txt}" + (f"; the bearing's axial end play 2 A sin alpha0 = {d['axial_end_play_um']:.3f} um"
                                 if brg.kind == "deep_groove" else ""))
        print(f"  delta_r = {d['delta_r_um']:.3f} um, theta = {d['theta_mrad']:.4f} mrad (residual {ld.residual:.1e}, "
              f"{ld.iterations} iterations)")
        print(f"{'ball':>4s} {'psi [deg]':>10s} {'Q_i [N]':>10s} {'Q_o [N]':>10s} {'alpha_i [deg]':>14s} "
              f"{'alpha_o [deg]':>14s}")
        for j in range(brg.Z):
            print(f"{j:4d} {d['psi_deg'][j]:10.1f} {ld.Q_i[j]:10.2f} {ld.Q_o[j]:10.2f} {d['alpha_inner_deg'][j]:14.2f} "
                  f"{d['alpha_outer_deg'][j]:14.2f}")
        if note:
            print(note)
    if out is not None:
        wrote([_plots().plot_load_distribution(ld, out / "load_distribution.png",
                                               f"{brg.name}: {'high-speed' if hs else 'static'} solution")])
    return 0


def cmd_init(args):
    out = check_out_file(args.out, "--out")
    if out is not None and out.exists():              # a scene the user may have edited: never overwritten
        raise InputError("--out", str(out), "exists: init does not overwrite a scene (remove it or name another file)")
    cmd = " ".join(["thermobear init", args.bearing, "--lubrication", args.lubrication]
                   + [f"{flag} {v:g}" if isinstance(v, float) else f"{flag} {v}" for flag, v in
                      (("--oil", args.oil), ("--housing", args.housing), ("--speed-rpm", args.speed_rpm),
                       ("--Fr-N", args.Fr_N), ("--Fa-N", args.Fa_N), ("--pair", args.pair),
                       ("--preload-N", args.preload_N)) if v is not None])
    text = scaffold(args.bearing, args.lubrication, oil=args.oil, housing=args.housing, n_rpm=args.speed_rpm,
                    Fr_N=args.Fr_N, Fa_N=args.Fa_N, pair=args.pair, preload_N=args.preload_N, command=cmd)
    if out is None:
        print(text, end="")
    else:
        write_text(out, text)
        wrote([out])
    return 0


def bearing_rows(series: str) -> list:
    """One row per catalogue bearing of a series: designation, boundary dimensions [mm], Z, D_w [mm],
    alpha0 [deg], C and C0 [kN] (the catalogue's; one it lacks from the geometry, ``C_from``/``C0_from``
    saying which), the estimated values."""
    rows = []
    for name in bearing_names(series=series):
        b = bearing(name)
        C, C0, (C_from, C0_from) = stated_ratings(b)
        rows.append({"designation": name, "kind": b.kind, "d_mm": round(b.bore * 1e3, 6),
                     "D_mm": round(b.outer_diameter * 1e3, 6), "B_mm": round(b.width * 1e3, 6), "Z": b.Z,
                     "Dw_mm": round(b.D * 1e3, 6), "alpha0_deg": round(float(np.rad2deg(b.alpha0)), 6),
                     "C_kN": C / 1e3, "C0_kN": C0 / 1e3, "C_from": C_from, "C0_from": C0_from,
                     "estimated": list(b.estimated)})
    return rows


def _print_bearing_rows(series, rows):
    alpha0 = {"deep_groove": "alpha0 of a deep groove bearing: its free contact angle from the mid clearance; ",
              "angular_contact": "alpha0: the nominal contact angle (C 15°, E 25°, B 40°); ",
              "thrust": ""}.get(rows[0]["kind"] if rows else "", "")
    print(f"series {series}: {len(rows)} bearings ({alpha0}C, C0 from the catalogue, whose generated series compute "
          "them by ISO 281 / ISO 76 from the estimated geometry; * computed here, not in the catalogue)")
    print(f"{'designation':12s} {'d x D x B [mm]':>18s} {'Z':>3s} {'D_w [mm]':>9s} {'alpha0':>7s} {'C [kN]':>8s} "
          f"{'C0 [kN]':>8s}  estimated")
    for r in rows:
        dims = f"{r['d_mm']:g} x {r['D_mm']:g} x {r['B_mm']:g}"
        C, C0 = (f"{v:7.2f}{' ' if how == 'stated' else '*'}" for v, how in ((r["C_kN"], r["C_from"]),
                                                                           (r["C0_kN"], r["C0_from"])))
        print(f"{r['designation']:12s} {dims:>18s} {r['Z']:3d} {r['Dw_mm']:9.4f} {r['alpha0_deg']:7.2f} {C} {C0}  "
              f"{', '.join(r['estimated']) or '-'}")


def cmd_list(args):
    if args.series is not None:
        if args.what not in (None, "bearings"):
            raise InputError("--series", args.series, "applies to thermobear list bearings")
        rows = bearing_rows(args.series)
        print_json(rows) if args.json else _print_bearing_rows(args.series, rows)
        return 0
    what = {"bearings": bearing_names, "lubricants": lubricant_names, "materials": material_names,
            "networks": lambda: names_in(data_dir("networks")),
            "examples": lambda: sorted(p.name for p in data_dir("examples").glob("*.toml"))}
    what = {k: f() for k, f in what.items() if args.what in (None, k)}
    if args.json:
        print_json(what)
    else:
        for k, v in what.items():
            print(f"{k}: {', '.join(v)}")
    if args.what is None and not args.json:
        print("(thermobear list bearings --series 62: a series as a table)")
    return 0


# --------------------------------------------------------------------------- transient
_SCHEDULE_KEYS = {"t_s", "n_rpm", "Fa_N", "Fr_N", "M_Nm", "T_oil_in_C", "T_ambient_C", "oil_flow_L_h", "lubricant"}


def read_schedule(path, scene=None, t_end_s=None) -> list:
    """Read a schedule TOML (``[[step]]`` tables with ``t_s`` and scene overrides) → [(t_s, {...}), ...];
    each step is checked against the scene (:meth:`Scene.with_`) when one is given."""
    p = Path(path)
    if not p.is_file():
        raise InputError("--schedule", str(path), "is a folder, not a schedule file (TOML)" if p.is_dir()
                         else "file not found")
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


def t90_s(t, T):
    """Time [s] at which T first reaches 90 % of its rise from T[0] to T[-1], interpolated between
    output times (None without a rise)."""
    t, T = np.asarray(t, float), np.asarray(T, float)
    rise = T[-1] - T[0]
    if T.size < 2 or abs(rise) < 1e-9:
        return None
    s = np.sign(rise) * (T - (T[0] + 0.9 * rise))
    k = int(np.flatnonzero(s >= 0)[0])
    if k == 0:
        return float(t[0])
    return float(t[k - 1] + (t[k] - t[k - 1]) * (-s[k - 1]) / (s[k] - s[k - 1]))


def cmd_transient(args):
    if not (np.isfinite(args.t_end) and args.t_end > 0):
        raise InputError("--t-end", args.t_end, "end time must be > 0 [s]")
    if args.points < 2 or args.points > 100000:
        raise InputError("--points", args.points, "number of output times must lie in 2..100000")
    T0 = _T0(args.T0_C)
    out_csv = check_out_file(args.csv, "--csv")
    out_dir = _plot_dir(args.plot)
    scene = load_scene_with(args.scene, args.set)
    if scene.T_C is not None:
        raise InputError("operation.T_C", scene.T_C, "a transient solves the thermal network: remove the prescribed "
                         "temperature (and give [thermal] network)")
    schedule = read_schedule(args.schedule, scene, args.t_end) if args.schedule else []
    if args.uncertainty is not None:
        return _transient_bands(args, scene, schedule, T0, out_csv, out_dir)
    if args.processes is not None:
        raise InputError("--processes", args.processes, "worker processes run the heat-ups of --uncertainty N: give it, "
                         "or leave --processes out (one heat-up runs in this process)")
    stop = {"flag": False}

    def halt(signum, frame):
        stop["flag"] = True
    previous = {s: signal.signal(s, halt) for s in (signal.SIGINT, signal.SIGTERM)}
    try:
        run = transient(scene, args.t_end, schedule=schedule, T0_C=T0, t_eval=np.linspace(0.0, args.t_end, args.points),
                        stop=lambda: stop["flag"])
    except ThermalPreloadRunaway as e:       # a pair's preload ran away: what was integrated to --csv, then exit 3
        if out_csv and getattr(e.last, "t_s", np.zeros(0)).size:
            what = "the pair's preload" if getattr(e.last, "preload", None) else "the radial preload"
            _transient_csv(e.last, scene, args, out_csv, f", {what} ran away after {e.last.t_s[-1]:g} s")
        raise
    finally:
        for s, h in previous.items():
            signal.signal(s, h)
    nodes = list(run.T_C)
    if out_csv:
        _transient_csv(run, scene, args, out_csv, "" if run.completed else
                       f", interrupted at {run.t_s[-1] if run.t_s.size else 0:g} s")
    if not run.completed:
        t = float(run.t_s[-1]) if run.t_s.size else 0.0
        print(f"interrupted at t = {t:g} s: kept {run.t_s.size} output times" + (f" in {out_csv}" if out_csv else
              " (no --csv: nothing written)"), file=sys.stderr)
        return EXIT_INTERRUPTED
    if args.json:
        print_json({"scene": scene.name, "t_s": run.t_s, "T_C": run.T_C, "P_W": run.P_W,
                    "breakdown_W": run.breakdown_W, "schedule": schedule,
                    "final_T_C": {n: float(run.T_C[n][-1]) for n in nodes},
                    "t90_s": {n: t90_s(run.t_s, run.T_C[n]) for n in nodes},
                    **({"preload": run.preload} if run.preload else {}),
                    "warnings": [w.as_dict() for w in run.warnings]})
    else:
        print(f"thermobear transient — {scene.name}: {args.t_end:g} s, {len(schedule)} schedule steps")
        print(f"\n{'node':18s} {'start [°C]':>11s} {'end [°C]':>10s} {'t90 [s]':>9s}")
        for n in nodes:
            T = np.asarray(run.T_C[n], float)
            t90 = t90_s(run.t_s, T)
            print(f"{n:18s} {T[0]:11.2f} {T[-1]:10.2f} " + (f"{t90:9.0f}" if t90 is not None else f"{'-':>9s}"))
        print(f"\nPower loss at the end {run.P_W[-1]:.3f} W (start {run.P_W[0]:.3f} W)")
        for k, v in run.breakdown_W.items():
            print(f"  {k:12s} {float(v[-1]):10.4f} W")
        if run.preload:                      # one bearing of a preloaded pair: its preload through the heat-up
            print(f"\n{preload_line(run.preload)}")
    if out_dir is not None:
        plots = _plots()
        out_dir.mkdir(parents=True, exist_ok=True)
        free = {n: run.T_C[n] for n in nodes if np.ptp(run.T_C[n]) > 0}
        wrote([plots.plot_heatup(run.t_s, free, out_dir / "heatup.png", title=f"Heat-up — {scene.name}",
                                 power_W=run.P_W, preload_N=(run.preload or {}).get("series", {}).get("preload_N"))])
    return 0


def _transient_csv(run, scene, args, path, note: str = "") -> None:
    """The heat-up's ``--csv``: times [s], node temperatures [°C], power and its breakdown [W]; of a preloaded pair's
    bearing the pair's preload and the loaded bearing's loads [N] at the output times."""
    p = (run.preload or {}).get("series")
    header = (["t_s"] + [f"T_{n}_C" for n in run.T_C] + ["P_W"] + [f"P_{k}_W" for k in run.breakdown_W] +
              (["preload_N", "Fa_loaded_N", "Fr_loaded_N"] if p else []))
    cols = ([run.t_s] + list(run.T_C.values()) + [run.P_W] + list(run.breakdown_W.values()) +
            ([p["preload_N"], p["Fa_N"], p["Fr_N"]] if p else []))
    rows = list(zip(*[np.asarray(c, float) for c in cols]))
    write_text(path, csv_text(header, rows, [f"thermobear transient of {scene.name} ({args.scene}), t_end "
                                             f"{args.t_end:g} s{note}"]))
    wrote([path])


def _transient_bands(args, scene, schedule, T0, out_csv, out_dir):
    """``thermobear transient --uncertainty N``: the heat-up's bands over the estimated inputs."""
    kw = _uncertainty_kw(args)
    if schedule:
        raise InputError("--schedule", args.schedule, "a heat-up with --uncertainty runs one operating point")
    t = np.linspace(0.0, args.t_end, args.points)
    procs = 1 if args.processes is None else check_processes(args.processes, "--processes")
    unc = transient_uncertainty(scene, args.t_end, args.uncertainty, t_eval=t, T0_C=T0, processes=procs, **kw)
    if out_csv:
        keys = list(unc.bands)
        header = ["t_s"] + [f"{k}_{q}" for k in keys for q in ("p5", "p50", "p95")]
        rows = list(zip(t, *[np.asarray(unc.bands[k][q], float) for k in keys for q in ("p5", "p50", "p95")]))
        write_text(out_csv, csv_text(header, rows, [f"thermobear transient --uncertainty {args.uncertainty} of "
                                                     f"{scene.name} ({args.scene}), seed {args.seed}"]))
        wrote([out_csv])
    if args.json:
        print_json({"scene": scene.name, "nominal": {"t_s": unc.nominal.t_s, "T_C": unc.nominal.T_C,
                                                     "P_W": unc.nominal.P_W}, "uncertainty": unc.as_dict()})
    else:
        print(f"thermobear transient — {scene.name}: {args.t_end:g} s\n\n{unc.summary()}")
    _sample_warnings(unc)
    if out_dir is not None:
        wrote(_plots().plot_bands(unc, out_dir, title=f"Heat-up bands over the estimated inputs — {scene.name}"))
    return 0


# --------------------------------------------------------------------------- sweep
_MODEL_COLUMNS = ("thermal", "load_model", "high_speed", "drag", "churning", "seals", "cage", "losses", "rolling",
                  "kinematics", "hertz")


def _sweep_header(scene, grid) -> list:
    """Columns of a sweep's rows, known before the first row (rows stream out as they finish)."""
    scenes = {str(v): scene.with_(**{k: v}) for k, vals in grid.items() for v in vals if k == "T_C"} or {"": scene}
    nodes, coupled, prescribed = [], False, False
    for sc in scenes.values():
        if sc.T_C is None and scene.network:
            coupled = True
        else:
            prescribed = True
    if coupled:
        nodes += network_nodes(scene.network, scene.path)
    if prescribed:
        nodes.append("contacts (prescribed)")
    bd = SKF_BREAKDOWN_KEYS if scene.models.get("losses") == "skf" else BREAKDOWN_KEYS
    rated = ["L10m_h", "kappa", "s0", "clearance_operating_um"] + (
        ["preload_cold_N", "preload_warm_N", *PAIR_STIFFNESS_COLUMNS] if coupled and getattr(scene, "arrangement", None)
        else [])
    return (list(grid) + ["status", "reason", "P_W", "torque_Nm", "T_ball_C"] + rated + ["iterations", "residual_K"]
            + [f"breakdown_W.{k}" for k in bd] + [f"temperatures_C.{n}" for n in nodes]
            + [f"models.{k}" for k in _MODEL_COLUMNS] + ["warnings"])


def _grid(args) -> dict:
    grid = {}
    for attr, key, field in (("n_rpm", "n_rpm", "--n-rpm"), ("Fa", "Fa_N", "--Fa"), ("Fr", "Fr_N", "--Fr"),
                             ("T_C", "T_C", "--T-C"), ("preload_N", "preload_N", "--preload-N")):
        if getattr(args, attr) is not None:
            grid[key] = parse_values(getattr(args, attr), field)
    if args.lubricant is not None:
        grid["lubricant"] = parse_values(args.lubricant, "--lubricant", allow_str=True)
    if not grid:
        raise InputError("sweep", None, "give at least one of --n-rpm, --Fa, --Fr, --T-C, --lubricant, --preload-N")
    return grid


def cmd_sweep(args):
    out_csv, out_jsonl = check_out_file(args.csv, "--csv"), check_out_file(args.jsonl, "--jsonl")
    out_dir = _plot_dir(args.plot)
    if args.processes is not None:
        check_processes(args.processes, "--processes")
    scene = load_scene_with(args.scene, args.set)
    grid = _grid(args)
    for k, vals in grid.items():                 # every value of every axis checked before computing (and the
        for v in vals:                           # model choice it forces: a fitted clearance at a prescribed T)
            clearance_choice(scene.with_(**{k: v}))
    total = len(sweep_points(grid))
    writer = RowWriter(_sweep_header(scene, grid), out_csv, out_jsonl,
                       f"thermobear sweep of {scene.name} ({args.scene}): " + ", ".join(f"{k} x{len(v)}" for k, v in grid.items()))
    try:
        rows = run_sweep(scene, grid, scheduler=args.scheduler, processes=args.processes,
                         progress=Progress(enabled=not args.quiet), on_row=writer.write)
    except KeyboardInterrupt:
        writer.close()
        if not writer.count:
            print(f"interrupted before the first of {total} rows finished: nothing written", file=sys.stderr)
        else:
            where = ", ".join(writer.paths) if writer.paths else "nowhere (give --csv or --jsonl to keep rows)"
            print(f"interrupted: kept {writer.count} of {total} rows in {where}", file=sys.stderr)
        return EXIT_INTERRUPTED
    writer.close()
    wrote(writer.paths)
    failed = [r for r in rows if r["status"] != "ok"]
    if args.json:
        print_json(rows)
    elif not writer.paths:
        print(csv_text(writer.header, [[i] + [_flat_get(r, k) for k in writer.header[1:]] for i, r in enumerate(rows)]),
              end="")
    else:
        print(f"{len(rows)} operating points ({len(failed)} failed), columns: {', '.join(writer.header)}")
    if out_dir is not None and "n_rpm" in grid:
        plots = _plots()
        wrote(plots.plot_sweep(rows, grid, out_dir, scene.name))
    if failed and not args.allow_failures:
        print(f"error: {len(failed)} of {len(rows)} points failed ({', '.join(sorted({r['status'] for r in failed}))}); "
              "their rows say why (--allow-failures exits 0)", file=sys.stderr)
        return EXIT_SOLVER
    return 0


def _flat_get(row, key):
    return flatten(row).get(key)


# --------------------------------------------------------------------------- compare / calibrate
def _rig_inputs(args):
    scene = load_scene_with(args.scene, getattr(args, "set", None))
    log = read_log(args.log)
    return scene, log, channel_map(scene, log, parse_map(args.map))


def cmd_compare(args):
    out_dir = _plot_dir(args.plot)
    out_csv = check_out_file(args.csv, "--csv")
    T0 = _T0(args.T0_C)
    kw = _uncertainty_kw(args)
    scene, log, mapping = _rig_inputs(args)
    comp = compare(scene, log, mapping, T0_C=T0)
    if args.uncertainty is not None:
        compare_bands(comp, scene, args.uncertainty, T0_C=T0, **{k: v for k, v in kw.items() if k != "sensitivity"})
    if out_csv:
        chans = list(comp.measured)
        q = ("_p5", "_p95")
        header = (["t_s" if comp.kind == "transient" else "n_rpm"] + [f"{c}{s}" for c in chans for s in ("", "_model")]
                  + [f"{c}_model{s}" for c in comp.bands for s in q])
        rows = [[comp.x[i]] + [v for c in chans for v in (comp.measured[c][i], comp.simulated[c][i])]
                + [comp.bands[c][s[1:]][i] for c in comp.bands for s in q] for i in range(comp.x.size)]
        note = f"thermobear compare: {args.log} vs {scene.name}; mode: {comp.mode}"
        write_text(out_csv, csv_text(header, rows, [note]))
        wrote([out_csv])
    print_json(comp.as_dict()) if args.json else print(comp.summary())
    if out_dir is not None:
        plots = _plots()
        wrote(plots.plot_comparison(comp, out_dir, f"{Path(args.log).name} vs {scene.name}"))
    return 0


def cmd_calibrate(args):
    out_dir = _plot_dir(args.plot)
    if args.max_nfev < 1:
        raise InputError("--max-nfev", args.max_nfev, "must be >= 1")
    T0 = _T0(args.T0_C)
    scene, log, mapping = _rig_inputs(args)
    cal = calibrate(scene, log, args.param, mapping, T0_C=T0, max_nfev=args.max_nfev)
    print_json(cal.as_dict()) if args.json else print(cal.summary())
    if out_dir is not None and cal.comparison is not None:
        plots = _plots()
        wrote(plots.plot_comparison(cal.comparison, out_dir, f"{Path(args.log).name}, calibrated", prefix="calibrate"))
    return 0


# --------------------------------------------------------------------------- spin-down
def cmd_spin_down(args):
    out_dir = _plot_dir(args.plot)
    scene = load_scene_with(args.scene, args.set)
    if scene.T_C is None:
        raise InputError("operation.T_C", None, "the spin-down rig model needs a prescribed temperature (seed 001: 26.5 °C)")
    J = args.J if args.J is not None else scene.rig_J_kg_m2
    if J is None:
        raise InputError("rig.J_kg_m2", None, "the spin-down needs the rotating inertia J [kg m²]: give --J or "
                         "[rig] J_kg_m2 in the scene")
    if not (np.isfinite(J) and J > 0):
        raise InputError("--J", J, "inertia must be > 0 [kg m²]")
    log = read_log(args.log) if args.log else None
    if log is not None and (not ({"n_rpm", "torque_Nm"} <= set(log.columns)) or log.kind != "steady"):
        raise InputError("--log", args.log, "a spin-down log has n_rpm and torque_Nm columns and no t_s")
    rpms = parse_values(args.rpm, "--rpm") if args.rpm else (list(log["n_rpm"]) if log is not None else [scene.n_rpm])
    for r in rpms:
        if not r > 0:
            raise InputError("--rpm", r, "initial speeds must be > 0 [rpm]")
    if log is not None:
        _check_spin_down_log(scene, log, args.log)
    runs = spin_down_runs(scene, float(J), rpms)
    if log is not None:
        for r in runs:
            k = np.flatnonzero(np.isclose(log["n_rpm"], r["n0_rpm"]))
            T = float(log["torque_Nm"][k[0]]) if k.size else math.nan
            r["T_log_Nm"] = T if math.isfinite(T) else None              # an empty cell: not measured
            r["T_error"] = r["T0_Nm"] / r["T_log_Nm"] - 1 if r["T_log_Nm"] else None
    pub = [{k: v for k, v in r.items() if not k.startswith("_")} for r in runs]
    if args.json:
        print_json({"scene": scene.name, "J_kg_m2": J, "T_C": scene.T_C, "runs": pub})
    else:
        _print_spin_down(scene, J, pub, log is not None)
    if out_dir is not None:
        plots = _plots()
        out_dir.mkdir(parents=True, exist_ok=True)
        paths = [plots.plot_spin_down([(f"{r['n0_rpm']:g} rpm", r["_sd"].t, r["_sd"].omega) for r in runs],
                                out_dir / "spin_down.png", f"Spin-down — {scene.name}, J = {J:g} kg m²")]
        n0 = np.array([r["n0_rpm"] for r in runs])
        sim = {"torque at the initial speed": np.array([r["T0_Nm"] for r in runs])}
        meas = ({"torque at the initial speed": np.array([r.get("T_log_Nm") or np.nan for r in runs])}
                if log is not None else None)
        paths.append(plots.plot_vs_speed(n0, sim, out_dir / "spin_down_torque.png", meas, "friction torque [N mm]",
                                   f"Torque vs speed — {scene.name}", 1e3))
        wrote(paths)
    return 0


def _check_spin_down_log(scene, log, path):
    """A spin-down log is one rig set-up, the scene's: its loads must be the scene's, and a lubricant per row
    (which the runs would not apply) is refused."""
    name = Path(path).name
    unused = [c for c in log.columns if c not in ("n_rpm", "torque_Nm", "Fa_N", "Fr_N", "lubricant")]
    if unused:                          # never silently: the runs compare the torque only
        warnings.warn(f"{name}: column{'s' * (len(unused) > 1)} {', '.join(unused)} not used: a spin-down run "
                      f"compares the torque at the initial speed, its contacts at operation.T_C = {scene.T_C:g} °C",
                      UserWarning, stacklevel=3)
    if "lubricant" in log.columns:
        raise InputError(f"{name}: column", "lubricant", "a spin-down log runs the scene's lubricant: one log per "
                         "lubricant (--set lubricant=NAME), without the column")
    for col, F in (("Fa_N", scene.Fa), ("Fr_N", scene.Fr)):
        if col in log.columns and np.any(np.abs(log[col] - F) > 1e-6 * max(F, 1)):
            raise InputError("--log", path, f"its {col} differs from the scene's {col[:2]} = {F:g} N (another rig "
                             "set-up)")


def _print_spin_down(scene, J, pub, with_log):
    print(f"thermobear spin-down — {scene.name}: J = {J:g} kg m², T = {scene.T_C:g} °C; "
          "K*, n from t_max and φ_max (seed 001 eqs 20–21)")
    head = f"{'n0 [rpm]':>8s} {'t_stop [s]':>10s} {'phi [rad]':>10s} {'K* [N m s^n]':>13s} {'n':>6s} {'T(w0) [N m]':>12s}"
    print(head + (f" {'log [N m]':>10s} {'error':>7s}" if with_log else ""))
    for r in pub:
        line = (f"{r['n0_rpm']:8.0f} {r['t_stop_s']:10.2f} {r['phi_max_rad']:10.2f} {r['K_star']:13.4e} "
                f"{r['n']:6.3f} {r['T0_Nm']:12.4e}")
        if with_log:
            line += (f" {r['T_log_Nm']:10.4e}" if r["T_log_Nm"] is not None else f" {'-':>10s}")
            line += f" {100 * r['T_error']:+6.1f}%" if r["T_error"] is not None else f" {'-':>7s}"
        print(line)

