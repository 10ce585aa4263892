"""The heat-up of one bearing of a preloaded pair (thermobear.coupled.transient_pair): the loaded bearing's loads follow
the pair's preload at the ring and ball temperatures of each piece's start; the warm-up overshoot of a position
preload, its runaway, a spring's constant loads, the drift bound's convergence and the command line.

The scene is seed 004's 7210 on its oil jet as one bearing of a back-to-back pair preloaded to 450 N, its block's
650 N radial load on the pair (as tests/test_preload_pair.py): its heat-ups cost a few seconds (the 7014C example's
machine network ten times more; its numbers are in README.md)."""
import json
import warnings
from pathlib import Path

import numpy as np
import pytest

import thermobear as tb
from thermobear.app.cli import main
from thermobear.coupled import transient_pair
from thermobear.coupled.preload import pair_scene, scene_pair_loads
from thermobear.errors import ThermalPreloadRunaway

SEED004 = tb.example_path("seed004_oil_jet_7210.toml")


def seed004_pair(**kw):
    return tb.load_scene(SEED004).with_(**{**dict(arrangement="back_to_back", preload_N=450.0, Fa=0.0, Fr=650.0),
                                            **kw})


def quiet(f, *a, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return f(*a, **kw)


@pytest.fixture(scope="module")
def long_heatup():
    """A 20000 s heat-up of the seed 004 pair (settled: its preload moves by < 1 N over the last 2000 s) and the
    steady state of the same scene."""
    s = seed004_pair()
    return quiet(tb.transient, s, 20000.0), quiet(tb.steady_state, s)


def test_the_heat_up_ends_at_the_steady_warm_preload(long_heatup):
    """Tolerance: a piece holds the loads of its start, within the drift bound Δ = 2 % of the loaded bearing's axial
    load of the loads at its temperatures; a settled heat-up is the steady state of loads within Δ of the fixed
    point's (the loop's gain below 1/2 there: its steps in the steady loop shrink by more than half), so its preload
    lies within Δ of the steady warm one, its heat within ≈ 2 % and its temperature rises above the ambient within
    2 % (here < 1 N of Δ = 29 N, 0.01 K)."""
    run, st = long_heatup
    p, q = run.preload, st.preload
    delta = transient_pair.PRELOAD_DRIFT_REL * max(p["Fa_N"], p["cold_N"])
    assert p["end_t_s"] == 20000.0 and p["cold_N"] == 450.0
    assert p["end_N"] == pytest.approx(q["warm_N"], abs=delta)
    assert p["Fa_N"] == pytest.approx(q["Fa_N"], abs=delta)
    T_amb = st.T_C["ambient"]
    for key, node in (("inner ring", "inner_ring"), ("outer ring", "outer_ring"), ("balls", "balls")):
        T_steady = q["temperatures_C"][key]
        assert float(run.T_C[node][-1]) == pytest.approx(T_steady, abs=0.02 * (T_steady - T_amb)), key
    h = q["history"]                         # the gain assumed above: the steady loop's steps shrink by > half
    r = [x["Fa_N"] - x["Fa_used_N"] for x in h]
    assert abs(r[-2]) < 0.5 * abs(r[-3])


def test_the_preload_overshoots_while_the_inner_ring_and_balls_lead(long_heatup):
    """The warm-up: the inner ring and balls warm ahead of the outer ring and housing, the position preload peaks
    well above its end value; at the peak the inner ring leads the outer ring by more than at the end."""
    run, _ = long_heatup
    p = run.preload
    assert p["peak_N"] > 1.3 * p["end_N"] and 0.0 < p["peak_t_s"] < 0.2 * p["end_t_s"]
    peak = min(p["history"], key=lambda r: abs(r["t_s"] - p["peak_t_s"]))
    end = p["history"][-1]
    assert peak["dT_inner_outer_K"] > end["dT_inner_outer_K"] + 1.0
    assert peak["T_balls_C"] - peak["T_outer_ring_C"] > end["T_balls_C"] - end["T_outer_ring_C"]
    # the series at the output times: the preload at the start is the cold one (the run starts at the ambient,
    # 25 °C: a little below), the peak's value is reached, the history's times increase
    s = p["series"]
    assert s["t_s"].shape == run.t_s.shape and s["preload_N"].max() == pytest.approx(p["peak_N"], rel=0.02)
    assert abs(s["preload_N"][0] - p["start_N"]) < 0.05 * p["start_N"]      # the pair at speed, still cold
    assert p["start_N"] > p["cold_N"]                # (the balls' centrifugal force, the inner rings' growth)
    assert np.all(np.diff([r["t_s"] for r in p["history"]]) > 0) and p["pieces"] == len(p["history"]) - 1
    assert any("during the heat-up, at t = " in str(w) and "warm / cold preload" in str(w) for w in run.warnings)


def test_a_larger_cold_preload_peaks_higher():
    peaks = [quiet(tb.transient, seed004_pair(preload_N=F0), 1000.0).preload["peak_N"] for F0 in (300.0, 600.0)]
    assert peaks[1] > peaks[0] + 100.0


def test_a_spring_preload_keeps_its_loads():
    """A spring keeps its force: the loads once, the heat-up that of the bearing alone under them (bit-identical)."""
    s = seed004_pair(preload="spring")
    run = quiet(tb.transient, s, 600.0)
    p = run.preload
    g = scene_pair_loads(s, None)                     # the spring's loads at speed, as the steady loop's
    assert p["kind"] == "spring" and p["pieces"] == 1                 # one piece: the loads once
    for k in ("preload_N", "Fa_N", "Fr_N"):
        assert np.ptp(p["series"][k]) == 0.0 and np.ptp([r[k] for r in p["history"]]) == 0.0
    assert p["Fa_N"] == g.Fa and p["Fr_N"] == g.Fr and p["peak_N"] == p["end_N"] == g.preload
    alone = quiet(tb.transient, pair_scene(s, g), 600.0)
    assert all(np.array_equal(run.T_C[n], alone.T_C[n]) for n in alone.T_C)
    assert transient_pair.preload_line(p).startswith("preload 450 N (spring: a constant force)")


def test_halving_the_drift_bound_converges(monkeypatch):
    """The loads held at each piece's start are a first-order update: halving the drift bound shrinks the change of
    the peak preload of a 1200 s heat-up past its peak; the end preload and temperatures, which the piece boundaries
    move about (measured over r = 0.08 … 0.0025: 2348–2368 N, 50.64–50.75 °C past r = 0.04), stay within 1 % and
    0.15 K between r = 0.02 and 0.01."""
    out = []
    for rel in (0.04, 0.02, 0.01):
        monkeypatch.setattr(transient_pair, "PRELOAD_DRIFT_REL", rel)
        r = quiet(tb.transient, seed004_pair(), 1200.0)
        assert r.preload["drift_bound_rel"] == rel
        out.append(np.array([r.preload["peak_N"], r.preload["end_N"], r.T_C["inner_ring"][-1], r.T_C["balls"][-1]]))
    d1, d2 = np.abs(out[1] - out[0]), np.abs(out[2] - out[1])
    assert d2[0] < 0.6 * d1[0] and d2[0] < 0.005 * out[2][0], (d1, d2)
    assert d2[1] < 0.01 * out[2][1] and np.all(d2[2:] < 0.15), (d1, d2)


def test_a_heat_up_without_a_pair_is_unchanged():
    """Seed 004's heat-up as before the pair's heat-up (its end temperatures as the code gave them then: the same
    floats on this machine)."""
    run = tb.transient(tb.load_scene(SEED004), 3600.0)
    before = {'shaft': 40.682407008329335, 'inner_ring': 41.196768453784216, 'inner_race': 41.4020547846477,
              'balls': 46.136667173000546, 'outer_race': 36.60981708777962, 'outer_ring': 36.37683583420329,
              'housing': 35.07167103817778, 'oil_air': 39.25104061152484, 'shaft_5': 26.416689737039746}
    for n, v in before.items():
        assert float(run.T_C[n][-1]) == pytest.approx(v, abs=1e-9), n
    assert run.t_s.size == 74 and float(run.P_W[-1]) == pytest.approx(39.776517156941566, abs=1e-9)
    assert run.preload is None


def test_a_runaway_keeps_what_was_integrated():
    """At 6500 rpm the pair's steady preload runs away (tests/test_preload_pair.py); its heat-up names it, keeping
    what it integrated with the preload's history."""
    with pytest.raises(ThermalPreloadRunaway, match="during the heat-up at t = ") as e:
        quiet(tb.transient, seed004_pair(n_rpm=6500.0), 1200.0, t_eval=np.linspace(0.0, 1200.0, 25))
    last = e.value.last
    assert last is not None and not last.completed and 0.0 < last.t_s[-1] < 1200.0
    assert last.preload["peak_N"] > 10 * 450.0 and e.value.preload_history_N[-1] > 10 * 450.0
    assert np.all(np.diff(e.value.preload_history_N[-5:]) > 0)          # rising to the end


def test_the_command_line_prints_the_preload_line(tmp_path, capsys):
    text = Path(SEED004).read_text(encoding="utf-8")
    path = tmp_path / "pair.toml"
    path.write_text(text.replace('catalog = "7210"', 'catalog = "7210"\narrangement = "back_to_back"\n'
                                 'preload_N = 450.0\n', 1), encoding="utf-8")
    base = ["transient", str(path), "--set", "Fa_N=0", "--set", "Fr_N=650", "--t-end", "900", "--points", "13"]
    csv = tmp_path / "h.csv"
    assert main(base + ["--csv", str(csv), "--plot", str(tmp_path / "pics")]) == 0
    out = capsys.readouterr().out
    assert (tmp_path / "pics" / "heatup.png").stat().st_size > 0         # its power panel carries the preload
    line = [ln for ln in out.splitlines() if ln.startswith("preload 450 N cold")]
    assert len(line) == 1 and " → peak " in line[0] and " N at the end (900 s)" in line[0]
    rows = [ln for ln in csv.read_text(encoding="utf-8").splitlines() if not ln.startswith("#")]
    header = rows[0].split(",")
    assert header[-3:] == ["preload_N", "Fa_loaded_N", "Fr_loaded_N"] and len(rows) == 14
    assert main(base + ["--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    p = d["preload"]
    assert p["cold_N"] == 450.0 and p["peak_N"] > p["end_N"] > 450.0 and len(p["series"]["preload_N"]) == 13
    assert float(rows[-1].split(",")[header.index("preload_N")]) == pytest.approx(p["end_N"], rel=1e-6)
    assert main(base + ["--set", "n_rpm=6500", "--csv", str(csv), "--json"]) == 3     # the runaway: exit 3
    cap = capsys.readouterr()
    assert "ThermalPreloadRunaway" in cap.err and json.loads(cap.out)["preload_history_N"]
    assert "the pair's preload ran away after" in csv.read_text(encoding="utf-8")


def test_an_interrupted_heat_up_keeps_its_preload():
    calls = {"n": 0}

    def stop():
        calls["n"] += 1
        return calls["n"] > 200
    run = quiet(tb.transient, seed004_pair(), 1200.0, stop=stop)
    p = run.preload
    assert not run.completed and 0.0 < run.t_s[-1] < 1200.0 and p["end_t_s"] == pytest.approx(run.t_s[-1])
    assert p["end_N"] > 450.0 and p["series"]["preload_N"].shape == run.t_s.shape
