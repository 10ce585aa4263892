"""``thermobear speed``: ISO 15312's thermal reference speed (the model's losses at the standard's
reference conditions), the thermally safe speed of the scene's own cooling (the coupled model), the speed at which
the model's equilibria end (a thermal runaway, a preloaded pair's preload running away:
:func:`thermobear.coupled.speeds.runaway_speed`) and DIN 732's thermally safe speed (the standard's method), each
with the temperature of the node the limit is on at that speed: the hotter race (``inner_race`` or ``outer_race``, the rings' raceway layers — not the ring
bodies ``inner_ring`` / ``outer_ring``; :func:`thermobear.coupled.speeds.hottest_race`), or ``--node``.

Beside them the maker's reference speed (of the open bearing, ISO 15312's; of a thrust ball bearing, which ISO
15312 excludes, SKF's own) and limiting speed (of the scene's variant: its seals;
:func:`thermobear.rating.maker_speeds.maker_speeds`), where the data file has them: a thermally safe speed above
the limiting speed keeps its number, flagged, and the limiting speed governs."""
from __future__ import annotations

import sys
import warnings

from thermobear.app.output import print_json
from thermobear.app.overrides import load_scene_with
from thermobear.coupled.limits import emit
from thermobear.coupled.ratings import scene_ratings
from thermobear.coupled.sources import prepare
from thermobear.coupled.speeds import (HOTTER_RACE, check_node, din732_safe_speed, hottest_race, runaway_speed,
                                      thermal_reference_speed, thermally_safe_speed)
from thermobear.coupled.steady import steady_state, steady_states
from thermobear.errors import InputError, NoSpeedRoot, OutsideValidity, SolverError
from thermobear.losses.seals import CONTACT_SEALS
from thermobear.rating.maker_speeds import limiting_speed_text, maker_speeds
from thermobear.scene import Scene
from thermobear.validity import T_LUBRICANT_REFUSE_C

__all__ = ["speed_report", "cmd_speed", "EXIT_SOLVER", "JUMP_K"]

EXIT_SOLVER = 3
#: |limit − temperature| at the model's root beyond which the root is a jump across the limit [K] (the search
#: stops within 1 rpm: a continuous rise misses the limit by hundredths of a kelvin there)
JUMP_K = 0.1
LIMITING = "maker's limiting speed"
#: what a thrust ball bearing's ISO 15312 row and maker's reference speed say (ISO 15312:2018 scope)
THRUST_EXCLUDED = "ISO 15312 excludes thrust ball bearings"


def _at_speeds(scene: Scene, speeds: dict, node) -> dict:
    """(node, temperature [°C]) of the hotter race (or ``node``) in the scene's steady state at each named speed,
    or the exception that says why there is none (each speed on its own: one past the lubricant's limit does not take the others)."""
    names = [k for k, v in speeds.items() if v is not None]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OutsideValidity)
        try:
            res = steady_states([scene.with_(n_rpm=speeds[k]) for k in names])
        except InputError:                  # a speed the models refuse, or a point past the lubricant's limit,
            res = [_one(scene, speeds[k]) for k in names]        # stops the batch: one by one
    return {k: r if isinstance(r, Exception) else hottest_race(r, node) for k, r in zip(names, res)}


def _one(scene: Scene, n_rpm: float):
    try:
        return steady_state(scene.with_(n_rpm=n_rpm))
    except (SolverError, InputError) as exc:
        return exc


def _why_not(exc: Exception) -> str:
    """Why a speed has no temperature of the scene, one line."""
    what = "no equilibrium" if isinstance(exc, SolverError) or "lubricant temperature" in str(exc) else "not modelled"
    return f"{what} ({type(exc).__name__}: {' '.join(str(exc).split())})"


def _across(scene: Scene, n_rpm: float, node, residual_K: float) -> str:
    """What lies on the other side of a speed at which the temperature steps past its limit (2 rpm away: the
    search's tolerance is 1 rpm): above it where the root lies below the limit, below it where it lies above."""
    where = "just above it" if residual_K < 0 else "just below it"
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", OutsideValidity)
            st = steady_state(scene.with_(n_rpm=n_rpm + (2.0 if residual_K < 0 else -2.0)))
    except (SolverError, InputError) as exc:
        return f"no equilibrium {where} ({type(exc).__name__}: the losses outgrow the cooling)"
    at, T = hottest_race(st, node)
    return f"{at} {T:.2f} °C {where} (a step of the model)"


def speed_report(scene: Scene, *, limit_C: float = 70.0, node: str | None = None) -> dict:
    """The three speeds of a scene as plain data (what ``thermobear speed --json`` prints).

    Each part that has no answer carries ``error`` (its one-line reason) instead of its numbers.  A model
    speed at which the temperature jumps past the limit (|residual| > :data:`JUMP_K`: a runaway, or a step to a
    hotter equilibrium where a cooler one ends, sets in before the limit is reached) carries ``jump``, what lies
    on the other side of it.
    """
    return _report(scene, limit_C, node)[0]


def _report(scene: Scene, limit_C: float, node, node_field: str = "node") -> tuple[dict, list]:
    """:func:`speed_report` and the warnings of its answers (OutsideValidity objects); InputError naming
    ``node_field`` for a node that is not a free node of the scene's network."""
    if node is not None and scene.network is not None:
        check_node(scene, node, field=node_field)
    hi = T_LUBRICANT_REFUSE_C[1]
    if not scene.T_ambient_C < limit_C < hi:          # (NaN fails)
        raise InputError("--limit-C", limit_C, f"must be above the ambient {scene.T_ambient_C:g} °C (no speed heats "
                         f"the bearing to a temperature below its surroundings) and below {hi:g} °C (the lubricant "
                         "data's limit)")
    ws: list = []
    rep = {"scene": scene.name, "bearing": scene.bearing.name, "limit_C": limit_C,
           "node": node or HOTTER_RACE, "T_ambient_C": scene.T_ambient_C, "contact_seals": scene.seals in CONTACT_SEALS}
    if node is None and scene.network is not None:      # the nodes the hotter race is the hotter of
        roles = prepare(scene).coupling.roles
        rep["race_nodes"] = [roles["inner"], roles["outer"]]
    try:
        r = thermal_reference_speed(scene.bearing)
        ws += r.warnings
        rep["iso15312"] = {"n_rpm": r.n_rpm, "P_W": r.P_W, "Phi_r_W": r.Phi_r_W, "A_r_mm2": r.A_r_m2 * 1e6,
                           "q_r_W_m2": r.q_r_W_m2, "load_N": r.load_N, "lubricant": r.lubricant,
                           "residual_W": r.residual_W, "iterations": r.iterations,
                           "warnings": [w.as_dict() for w in r.warnings]}
    except (SolverError, InputError) as exc:
        rep["iso15312"] = {"error": " ".join(str(exc).split())}
    s = None
    try:
        s = thermally_safe_speed(scene, limit_C=limit_C, node=node)
        with warnings.catch_warnings():      # the state's ratings at that speed: a consumed clearance, a preload
            warnings.simplefilter("ignore", OutsideValidity)
            rated = scene_ratings(scene.with_(n_rpm=s.n_rpm), s.steady).warnings
        sw = s.warnings + [w for w in rated if str(w) not in map(str, s.warnings)]
        ws += sw
        rep["model"] = {"n_rpm": s.n_rpm, "T_C": s.T_C, "T_node": s.T_node, "residual_K": s.residual_K, "iterations": s.iterations,
                        "bracket_rpm": list(s.bracket_rpm), "monotonic": s.monotonic, "P_W": s.steady.P_W,
                        "warnings": [w.as_dict() for w in sw]}
        if abs(s.residual_K) > JUMP_K:
            rep["model"]["jump"] = _across(scene, s.n_rpm, node, s.residual_K)
    except SolverError as exc:                          # (a probe speed's failure: the other answers stand)
        rep["model"] = {"error": " ".join(str(exc).split()) if isinstance(exc, NoSpeedRoot) else
                        f"{type(exc).__name__}: " + " ".join(str(exc).split())}
        if hasattr(exc, "contact_limit_rpm"):          # the search ended where the contacts stop carrying the loads
            rep["model"].update(contact_limit_rpm=exc.contact_limit_rpm, T_C_at_contact_limit=exc.T_C)
    rep["runaway"] = _runaway(scene, s.ladder if s is not None else None)
    try:
        d = din732_safe_speed(scene, limit_C=limit_C)
        rep["din732"] = {"n_rpm": d.n_rpm, "f_n": d.f_n, "K_L": d.K_L, "K_P": d.K_P,
                         "n_theta_r_rpm": d.n_theta_r_rpm, "Phi_W": d.Phi_W, "nu_cSt": d.nu_cSt, "P1_N": d.P1_N,
                         "f0": d.f0, "f1": d.f1, "f_n_balance": d.f_n_balance}
    except (SolverError, InputError) as exc:
        rep["din732"] = {"error": " ".join(str(exc).split())}
    rep["maker"] = _maker(scene, rep)
    temps = _at_speeds(scene, {"iso15312": rep["iso15312"].get("n_rpm"), "din732": rep["din732"].get("n_rpm")}, node)
    for k, T in temps.items():
        if isinstance(T, Exception):        # a number field holds a number or null; the reason beside it
            rep[k].update(T_C=None, T_node=None, T_C_error=_why_not(T))
        else:
            rep[k]["T_node"], rep[k]["T_C"] = T
    return rep, ws


def _runaway(scene: Scene, ladder) -> dict:
    """The speed at which the model's equilibria end (:func:`~thermobear.coupled.speeds.runaway_speed`, on the
    thermally safe speed's ladder where it has one), or ``error`` saying why there is none."""
    try:
        r = runaway_speed(scene, ladder=ladder)
    except (SolverError, InputError) as exc:
        return {"error": " ".join(str(exc).split()) if isinstance(exc, NoSpeedRoot) else
                f"{type(exc).__name__}: " + " ".join(str(exc).split())}
    return {"n_rpm": r.n_rpm, "settled_rpm": r.settled_rpm, "kind": r.kind, "why": r.why, "T_C": r.T_C,
            "T_node": r.T_node, "P_W": r.P_W, "preload_warm_N": r.preload_warm_N, "iterations": r.iterations,
            "again_rpm": list(r.again_rpm)}


def _maker(scene: Scene, rep: dict) -> dict:
    """The maker's speeds beside the thermal ones (rpm, null where none is on file), and the speed that governs:
    the lower of the model's thermally safe speed and the limiting speed; each thermally safe speed above the
    limiting speed is flagged (``above_limiting_speed``) in its own part."""
    lim, ref = maker_speeds(scene.bearing, scene.seals), maker_speeds(scene.bearing, "none")
    out = {"limiting_rpm": None if lim is None else lim.limiting_rpm,
           "reference_rpm": None if ref is None else ref.reference_rpm,
           "designation": None if lim is None else lim.designation,
           "reference_designation": None if ref is None else ref.designation,
           "source": None if lim is None else lim.source, "note": None if lim is None else lim.note or None,
           "text": limiting_speed_text(scene.bearing, scene.seals),
           "reference_basis": None if ref is None else "ISO 15312" if scene.bearing.kind != "thrust" else
           f"SKF's own rating: its friction model at ISO 15312's conditions ({THRUST_EXCLUDED})"}
    for k in ("model", "din732"):
        if rep[k].get("n_rpm") is not None and lim is not None:
            rep[k]["above_limiting_speed"] = rep[k]["n_rpm"] > lim.limiting_rpm
    n = rep["model"].get("n_rpm")
    if n is not None:
        past = lim is not None and n > lim.limiting_rpm
        out["governing_rpm"] = lim.limiting_rpm if past else n
        out["governed_by"] = ("maker's limiting speed" if past else "thermally safe speed (model)" if lim is not None
                              else "thermally safe speed (model); no maker's limiting speed on file")
    return out


def _maker_lines(rep: dict) -> list:
    """The maker's rows of the table, and what governs where a thermally safe speed passes the limiting speed."""
    m = rep["maker"]
    if m["limiting_rpm"] is None:
        lines = [f"  {LIMITING:58s} —  {m['text']}"]
    else:
        note = f"; {m['note']}" if m["note"] else ""
        label = f"{LIMITING} ({m['designation']}, kinematic)"
        lines = [f"  {label:58s} {m['limiting_rpm']:9.0f} rpm   SKF: {m['source']}{note}"]
    if m["reference_rpm"] is not None:
        iso = m.get("reference_basis") == "ISO 15312"
        label = f"maker's reference speed ({m['reference_designation']}, {'ISO 15312' if iso else 'SKF'})"
        lines.insert(0, f"  {label:58s} {m['reference_rpm']:9.0f} rpm" + ("" if iso else f"   {m['reference_basis']}"))
    for k, what in (("model", "thermally safe speed of this scene's cooling"),
                    ("din732", "DIN 732 thermally safe speed")):
        if rep[k].get("above_limiting_speed"):
            lines.append(f"    {what} {rep[k]['n_rpm']:.0f} rpm exceeds the maker's limiting speed "
                         f"{m['limiting_rpm']:.0f} rpm: the limiting speed governs (the kinematic limit of the bearing, "
                         "its cage or its seals, whatever the cooling)")
    return lines


def _line(label: str, part: dict, note: str = "") -> str:
    """A speed and the temperature of the node the limit is on there (which node: the hotter race is either)."""
    if "error" in part:
        return f"  {label:58s} —  {part['error']}"
    T = part.get("T_C")
    T = f"{part['T_node']} {T:.2f} °C{note}" if T is not None else f"—  {part.get('T_C_error', 'not evaluated')}"
    return f"  {label:58s} {part['n_rpm']:9.0f} rpm   {T}"


def _runaway_line(part: dict) -> str:
    """The row of the speed at which the model's equilibria end."""
    label = "equilibria end (model: runaway speed)"
    if "error" in part:
        return f"  {label:58s} —  {part['error']}"
    pre = "" if part["preload_warm_N"] is None else f", warm preload {part['preload_warm_N']:.0f} N"
    again = ("" if not part["again_rpm"] else "; equilibria again at " + ", ".join(f"{n:.0f}" for n in
                                                                               part["again_rpm"]) + " rpm (the first end)")
    return (f"  {label:58s} {part['n_rpm']:9.0f} rpm   {part['kind']}; at {part['settled_rpm']:.0f} rpm still "
            f"{part['T_node']} {part['T_C']:.2f} °C, {part['P_W']:.1f} W{pre}{again}")


def summary(rep: dict) -> str:
    """The text table of :func:`speed_report`."""
    races = rep.get("race_nodes")
    on = rep["node"]
    if races:
        on = (f"the hotter of {races[0]} and {races[1]}" if races[0] != races[1] else races[0]) + \
            " (the inner and outer contact nodes; --node NAME limits another node)"
    lines = [f"thermobear speed — {rep['scene']}: {rep['bearing']}, ambient {rep['T_ambient_C']:g} °C, "
             f"limit {rep['limit_C']:g} °C on {on}", ""]
    iso, mod, din = rep["iso15312"], rep["model"], rep["din732"]
    hot = {k: f"; above the {rep['limit_C']:g} °C limit" if (p.get("T_C") or -1e9) > rep["limit_C"] + JUMP_K else ""
           for k, p in (("iso15312", iso), ("din732", din))}
    open_ = " (of the open bearing: ISO 15312 has none for contact seals)" if rep.get("contact_seals") else ""
    if any(w.get("quantity") == "iso15312_scope" for w in iso.get("warnings", ())):
        open_ += f"; {THRUST_EXCLUDED}: a model comparison"
    lines.append(_line("ISO 15312 thermal reference speed (model, reference cond.)", iso,
                       " in this scene" + hot["iso15312"] + open_))
    past = {k: "; above the maker's limiting speed" if p.get("above_limiting_speed") else "" for k, p in
            (("model", mod), ("din732", din))}
    bound = "" if "jump" not in mod or "error" in mod else (
        f"; the equilibria end here, {-mod['residual_K']:.1f} K below the limit" if mod["residual_K"] < 0
        else f"; a step of the model passes the limit here (+{mod['residual_K']:.1f} K)")
    lines.append(_line("thermally safe speed, this scene's cooling (model)", mod, bound + past["model"]))
    lines.append(_line("DIN 732 thermally safe speed (standard's method)", din, " (model)" + hot["din732"] + past["din732"]))
    lines.append(_runaway_line(rep["runaway"]))
    lines += _maker_lines(rep)
    if "error" not in iso:
        lines.append(f"    ISO 15312: q_r A_r = {iso['Phi_r_W']:.2f} W (A_r {iso['A_r_mm2']:.0f} mm²), load "
                     f"{iso['load_N']:.0f} N, {iso['lubricant']}; residual {iso['residual_W']:.1e} W, "
                     f"{iso['iterations']} iterations")
    if "error" not in mod:
        lines.append(f"    model: residual {mod['residual_K']:.1e} K, {mod['iterations']} iterations, power "
                     f"{mod['P_W']:.2f} W" + ("" if mod["monotonic"] else ", temperature not monotonic in speed "
                                                "below the bracket (first crossing taken)"))
        if "jump" in mod:
            lines.append(f"    model: the limit is {'not reached' if mod['residual_K'] < 0 else 'passed by a step'} at "
                         f"this speed — {mod['T_node']} {mod['T_C']:.2f} °C here, {mod['jump']}: the speed bounds the "
                         "equilibria, not the limit temperature")
    if "error" not in din:
        lines.append(f"    DIN 732: f_n = {din['f_n']:.3f} × n_θr {din['n_theta_r_rpm']:.0f} rpm (ISO 15312's "
                     f"equations); lubricant parameter K_L {din['K_L']:.3f}, load parameter K_P {din['K_P']:.3f}; "
                     f"heat dissipated {din['Phi_W']:.2f} W")
        inside = all(0.01 <= din[k] <= 10.0 for k in ("K_L", "K_P"))
        lines.append(f"    DIN 732: the root of the balance K_L f_n^(5/3) + K_P f_n = 1 that f_n approximates is "
                     f"{din['f_n_balance']:.3f} ({din['f_n_balance'] * din['n_theta_r_rpm']:.0f} rpm); K_L, K_P "
                     + ("inside" if inside else "outside") + " the approximation's range 0.01 … 10")
    return "\n".join(lines)


def cmd_speed(args):
    rep, ws = _report(load_scene_with(args.scene, args.set), args.limit_C, args.node, "--node")
    emit(ws)                                   # one line each on stderr, as every verb's answers
    if args.json:
        print_json(rep)
    else:
        print(summary(rep))
    if "error" in rep["model"]:                # the answer the verb is for: exit 3 with its reason on stderr
        err = rep["model"]["error"]
        print(f"error: thermally safe speed (model): {err}", file=sys.stderr)
        return EXIT_SOLVER
    return 0
