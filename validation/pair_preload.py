"""A preloaded spindle pair: the bundled example's preload, stiffness and heat-up, and the checks that pin them.

The example (examples/spindle_7014C_pair_oil_air.toml: a 7014C of a back-to-back pair, 300 N cold position
preload, oil–air, 8000 rpm, 2020 N radial on the pair, the bearing's share of a block housing) has no measured
counterpart: this report holds its numbers so that a change that moves them shows here (validation/CHANGES.md
says why), beside the limits the pair's model is pinned to:

* the pair at rest without external load: its axial stiffness both bearings in parallel, 2 dF_a/dδ_a(F0) of one
  bearing (thermobear.loads.static), a spring pair's one bearing's; back-to-back = face-to-face by mirror symmetry;
* the high-speed form at n = 0 against the static form (loads and stiffness);
* the heat-up's end against the steady answer (within the heat-up's drift bound);
* the answer's cold stiffness against `thermobear loads`' (the same evaluation).

Writes validation/report/pair_preload.md.  Run:  python validation/pair_preload.py   (≈ 30 s)
"""
from __future__ import annotations

import sys
import warnings
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import thermobear as tb  # noqa: E402
from _common import write_report  # noqa: E402
from thermobear.app.sweep import run_sweep  # noqa: E402
from thermobear.coupled.preload import cold_pair  # noqa: E402
from thermobear.loads.pair import pair_loads  # noqa: E402
from thermobear.loads.static import load_distribution_static  # noqa: E402

EXAMPLE = tb.example_path("spindle_7014C_pair_oil_air.toml")
SPEEDS = (2000.0, 4000.0, 6000.0, 8000.0, 10000.0, 12000.0)


def quiet(f, *a, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return f(*a, **kw)


def limits() -> list:
    """The analytic and symmetry checks of the pair's stiffness and its two forms (7014C, 300 N)."""
    b, F0, h = tb.bearing("7014C"), 300.0, 0.01
    d = [float(load_distribution_static(b, Fa=F, Fr=0.0).delta_a) for F in (F0 + h, F0 - h)]
    k1 = 2.0 * h / (d[0] - d[1])
    rows = ["| check | model | limit | relative difference |", "|---|---|---|---|"]

    def row(what, got, ref):
        rows.append(f"| {what} | {got:.6g} | {ref:.6g} | {abs(got / ref - 1.0):.1e} |")
    k = pair_loads(b, "back_to_back", F0, with_stiffness=True).stiffness
    row("axial stiffness at rest, no external load [N/µm] vs 2 dF_a/dδ_a(F0) of one bearing", k[0] * 1e-6, 2 * k1 * 1e-6)
    ks = pair_loads(b, "back_to_back", F0, "spring", with_stiffness=True).stiffness
    row("a spring pair's axial stiffness [N/µm] vs dF_a/dδ_a(F0) of one bearing", ks[0] * 1e-6, k1 * 1e-6)
    kf = pair_loads(b, "face_to_face", F0, with_stiffness=True).stiffness
    row("radial stiffness, face to face vs back to back [N/µm]", kf[1] * 1e-6, k[1] * 1e-6)
    for name, kk, a in (("back to back", k, 0.5 * b.width + 0.5 * b.dm * np.tan(b.alpha0)),
                        ("face to face", kf, abs(0.5 * b.width - 0.5 * b.dm * np.tan(b.alpha0)))):
        row(f"tilt stiffness {name} [N m/mrad] ≥ 2 k_r,1 a², the bearings' radial stiffness at its pressure centres "
            f"(a = {a * 1e3:.2f} mm; a lower bound: the bearings' own moment stiffness adds)", kk[2] * 1e-3,
            k[1] * a ** 2 * 1e-3)
    for Fr in (0.0, 2020.0):
        st = pair_loads(b, "back_to_back", F0, Fr=Fr, with_stiffness=True)
        n0 = pair_loads(b, "back_to_back", F0, Fr=Fr, n_rpm=0.0, with_stiffness=True)
        row(f"high-speed form at n = 0 vs static: loaded bearing's F_a [N], Fr {Fr:g} N", n0.Fa, st.Fa)
        row(f"high-speed form at n = 0 vs static: axial stiffness [N/µm], Fr {Fr:g} N", n0.stiffness[0] * 1e-6,
            st.stiffness[0] * 1e-6)
    return rows


def steady(s) -> tuple:
    """The example's steady answer and its cold states (``thermobear loads``: :func:`cold_pair`)."""
    st = quiet(tb.steady_state, s)
    p, cold = st.preload, cold_pair(s)[0]
    rows = ["| state | preload [N] | loaded bearing F_a [N] | axial stiffness [N/µm] | radial stiffness [N/µm] | "
            "tilt stiffness [N m/mrad] |", "|---|---|---|---|---|---|"]
    for name, c in (("cold at rest", cold["at_rest"]), (f"cold at {s.n_rpm:g} rpm", cold["at_speed"])):
        rows.append(f"| {name} | {c['preload_N']:.1f} | {c['Fa_N']:.1f} | {c['k_axial_N_um']:.2f} | "
                    f"{c['k_radial_N_um']:.1f} | {c['k_tilt_Nm_mrad']:.1f} |")
    rows.append(f"| warm at {s.n_rpm:g} rpm (the answer) | {p['warm_N']:.1f} | {p['Fa_N']:.1f} | "
                f"{p['k_axial_warm_N_um']:.2f} | {p['k_radial_warm_N_um']:.1f} | {p['k_tilt_warm_Nm_mrad']:.1f} |")
    same = (p["k_axial_cold_N_um"] == cold["at_rest"]["k_axial_N_um"]
            and p["k_axial_at_speed_cold_N_um"] == cold["at_speed"]["k_axial_N_um"])
    T = p["temperatures_C"]
    text = [f"Steady answer: P = {st.P_W:.2f} W; inner ring {T['inner ring']:.2f} °C, outer ring {T['outer ring']:.2f} °C, "
            f"balls {T['balls']:.2f} °C; fixed point in {p['iterations']} steps (residual {p['residual_N']:.1e} N); "
            f"with the balls at the rings' mean {p['warm_balls_at_rings_N']:.1f} N.  The answer's cold stiffness "
            f"{'is' if same else 'is NOT'} `thermobear loads`' (the same evaluation)."]
    return st, rows, text


def over_speed(s) -> list:
    rows = quiet(run_sweep, s, {"n_rpm": list(SPEEDS)}, processes=1)
    out = ["| n [rpm] | status | P [W] | warm preload [N] | axial stiffness warm [N/µm] | radial stiffness warm [N/µm] | "
           "tilt stiffness warm [N m/mrad] |", "|---|---|---|---|---|---|---|"]
    for r in rows:
        ok = r["status"] == "ok"
        out.append(f"| {r['n_rpm']:g} | {r['status']} | " + (
            f"{r['P_W']:.1f} | {r['preload_warm_N']:.0f} | {r['k_axial_warm_N_um']:.1f} | {r['k_radial_warm_N_um']:.0f} | "
            f"{r['k_tilt_warm_Nm_mrad']:.0f} |" if ok else "– | – | – | – | – |"))
    return out


def heat_up(s, st) -> list:
    """The example's 3600 s heat-up, its end against the steady answer (within the pieces' drift bound)."""
    r = quiet(tb.transient, s, 3600.0)
    p, k = r.preload, int(np.argmax(r.P_W))
    apart = abs(p["end_N"] / st.preload["warm_N"] - 1.0)
    return [f"3600 s heat-up from 20 °C: {p['start_N']:.1f} N at the start → peak {p['peak_N']:.1f} N at "
            f"{p['peak_t_s']:.0f} s → {p['end_N']:.1f} N at the end ({p['pieces']} pieces of ≤ "
            f"{100 * p['drift_bound_rel']:.0f} % drift; the power peaks at {float(r.P_W[k]):.1f} W at {r.t_s[k]:.0f} s "
            f"over the integrator's steps, {float(r.P_W[-1]):.1f} W at the end); the steady answer "
            f"{st.preload['warm_N']:.1f} N: {apart:.1e} apart, "
            f"{'within' if apart <= p['drift_bound_rel'] else 'OUTSIDE'} the drift bound."]


def main() -> int:
    s = tb.load_scene(EXAMPLE)
    st, table, text = steady(s)
    lines = ["# A preloaded spindle pair: preload, stiffness and heat-up", "",
             "Generated by `validation/pair_preload.py`.  The example `examples/spindle_7014C_pair_oil_air.toml` (a "
             "7014C of a back-to-back pair, 300 N cold position preload, oil–air, 8000 rpm, 2020 N radial on the pair) "
             "has no measurement to compare with: its numbers are here to track.  Stiffness at the pair's centre under "
             "the external loads, the other displacements free (`loads/pair.py`).", "",
             "## Limits the pair's model is pinned to (7014C, 300 N)", "", *limits(), "",
             "## The example's steady answer", "", *text, "", *table, "",
             "## Over speed (`thermobear sweep --n-rpm`)", "", *over_speed(s), "",
             "## Heat-up", "", *heat_up(s, st)]
    print(f"wrote {write_report('pair_preload.md', lines)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
