"""Rig logs: parsing, channel maps, metrics, the shipped seed logs, and calibration recovering known parameters."""
from __future__ import annotations

import csv
import io
import math
from pathlib import Path

import numpy as np
import pytest

from thermobear.errors import InputError
from thermobear.app.calibration import calibrate
from thermobear.app.rig import channel_map, compare, metrics, read_log
from thermobear.coupled import transient
from thermobear.scene.scene import load_scene

ROOT = Path(__file__).resolve().parents[1]
LOGS = ROOT / "examples" / "logs"


def _write(tmp_path, text, name="log.csv"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def _table(name):
    text = (ROOT / "validation" / "data" / name).read_text(encoding="utf-8")
    return list(csv.DictReader(io.StringIO("\n".join(l for l in text.splitlines() if not l.startswith("#")))))


# ------------------------------------------------------------------ reading
def test_read_transient_and_steady(tmp_path):
    log = read_log(_write(tmp_path, "# rig X\nt_s,T_IR_C,T_OR_C\n0,20,20\n10,22.5,\n20,24,21\n"))
    assert log.kind == "transient" and log.temperature_channels == ["T_IR_C", "T_OR_C"]
    assert log.comments == ["rig X"]
    assert np.isnan(log["T_OR_C"][1]) and log["T_IR_C"][2] == 24.0
    st = read_log(_write(tmp_path, "n_rpm,lubricant,torque_Nm\n1000,seed002-mg1,0.17\n", "s.csv"))
    assert st.kind == "steady" and st["lubricant"] == ["seed002-mg1"]


@pytest.mark.parametrize("text, field", [
    ("t_s,T_IR_C\n0,20\n10,abc\n", "line 3, column T_IR_C"),
    ("t_s,T_IR\n0,20\n", "column"),                          # unknown column (no _C suffix)
    ("T_IR_C\n20\n", "columns"),                             # neither t_s nor n_rpm
    ("t_s,T_IR_C\n0,20\n0,21\n", "column t_s"),              # times must increase
    ("t_s,T_IR_C\n0,20,5\n", "line 2"),                      # wrong number of fields
    ("t_s,T_IR_C\n0,nan\n", "line 2, column T_IR_C"),         # NaN is not a missing value
    ("t_s,T_IR_C\n0,900\n", "column T_IR_C"),                # outside [-60, 250] °C
    ("# only a comment\n", "log.csv"),
])
def test_malformed_logs_name_the_field(tmp_path, text, field):
    with pytest.raises(InputError) as e:
        read_log(_write(tmp_path, text))
    assert field in str(e.value)


def test_log_with_a_utf8_bom_reads_as_without(tmp_path):
    """Excel's "CSV UTF-8" starts with a byte-order mark; it was read into the first column's name
    ('\\ufefft_s' — unknown column)."""
    text = "t_s,T_IR_C\n0,20\n60,25.5\n"
    p = tmp_path / "bom.csv"
    p.write_bytes(b"\xef\xbb\xbf" + text.encode("utf-8"))
    log = read_log(p)
    assert list(log.columns) == ["t_s", "T_IR_C"] and log.kind == "transient"
    np.testing.assert_array_equal(log["T_IR_C"], read_log(_write(tmp_path, text))["T_IR_C"])


def test_missing_log_file():
    with pytest.raises(InputError, match="file not found"):
        read_log("/nonexistent/log.csv")


# ------------------------------------------------------------------ mapping
@pytest.fixture(scope="module")
def synthetic_scene():
    return load_scene(LOGS / "synthetic_heatup_scene.toml")


def test_channel_map_from_scene_and_errors(tmp_path, synthetic_scene):
    log = read_log(_write(tmp_path, "t_s,T_bearing_C,T_room_C,T_X_C\n0,20,20,20\n10,21,20,21\n"))
    with pytest.raises(InputError, match="rig.map.T_X_C"):            # unmapped channel
        channel_map(synthetic_scene, log)
    assert channel_map(synthetic_scene, log, {"T_X_C": "ignore"}) == {"T_bearing_C": "bearing",
                                                                      "T_room_C": "impose:ambient", "T_X_C": "ignore"}
    with pytest.raises(InputError, match="rig.map.T_room_C"):         # the scene maps a channel the log lacks
        channel_map(synthetic_scene, read_log(_write(tmp_path, "t_s,T_bearing_C\n0,20\n10,21\n", "b.csv")))
    with pytest.raises(InputError, match="imposed by T_room_C already"):
        channel_map(synthetic_scene, log, {"T_X_C": "impose:ambient"})
    with pytest.raises(InputError, match="nothing to compare"):       # an imposed node is not compared
        channel_map(synthetic_scene, log, {"T_X_C": "ambient"})
    with pytest.raises(InputError, match="--map.T_Y_C"):              # unknown channel
        channel_map(synthetic_scene, log, {"T_X_C": "ignore", "T_Y_C": "bearing"})
    with pytest.raises(InputError, match="unknown node"):
        channel_map(synthetic_scene, log, {"T_X_C": "housing"})
    with pytest.raises(InputError, match="steady log"):               # input temperature needs a steady log
        channel_map(synthetic_scene, log, {"T_X_C": "input"})


# ------------------------------------------------------------------ metrics
def test_metrics_hand_computed():
    m = metrics([1.0, np.nan, 3.0, 4.0], [2.0, 9.0, 3.0, 2.0])
    assert m["n"] == 3
    assert m["rmse"] == pytest.approx(math.sqrt((1 + 0 + 4) / 3))
    assert m["max_abs_error"] == 2.0 and m["bias"] == pytest.approx(-1 / 3)


def test_t90_of_first_order_response_is_tau_ln10():
    tau = 120.0
    t = np.linspace(0.0, 20 * tau, 20001)
    y = 20.0 + 40.0 * (1.0 - np.exp(-t / tau))
    m = metrics(y, y + 0.5, t)
    assert m["t90_measured_s"] == pytest.approx(tau * math.log(10.0), rel=1e-3)
    assert m["t90_simulated_s"] == pytest.approx(m["t90_measured_s"], rel=1e-6)   # an offset does not shift t90
    assert m["steady_state_error"] == pytest.approx(0.5) and m["rmse"] == pytest.approx(0.5)


# ------------------------------------------------------------------ shipped logs hold the published numbers
def test_seed002_logs_are_table3_sums_and_text_values():
    rows = {r["grease"]: r for r in _table("seed002_greases.csv")}
    log = read_log(LOGS / "seed002_greases.csv")
    for n, lub, M, T in zip(log["n_rpm"], log["lubricant"], log["torque_Nm"], log["T_III_C"]):
        if n == 1000:
            r = rows[lub.split("-")[1].upper()]
            assert M * 1e3 == pytest.approx(float(r["Mrr_Nmm"]) + float(r["Msl_Nmm"]), abs=1e-9)
            assert T == float(r["T_1000rpm_C"])
    at2000 = {lub: (M, T) for n, lub, M, T in zip(log["n_rpm"], log["lubricant"], log["torque_Nm"], log["T_III_C"])
              if n == 2000}
    assert at2000 == {"seed002-mg1": (0.155, 65.0), "seed002-pg2": (0.110, 53.0)}     # seed 002 sec. 4.2
    mg1 = read_log(LOGS / "seed002_mg1.csv")
    assert mg1["torque_Nm"].tolist() == [0.1753, 0.155] and mg1["T_III_C"].tolist() == [49.8, 65.0]


@pytest.mark.parametrize("table", ["1", "2"])
def test_seed001_logs_are_K_omega_n(table):
    log = read_log(LOGS / f"seed001_table{table}_torque.csv")
    rows = [r for r in _table("seed001_spin_down.csv") if r["table"] == table]
    for r, n, M in zip(rows, log["n_rpm"], log["torque_Nm"]):
        w = float(r["initial_rpm"]) * math.pi / 30
        assert n == float(r["initial_rpm"])
        assert M == pytest.approx(float(r["K"]) * w ** float(r["n"]), rel=1e-4)


def _make_synthetic():
    import importlib.util
    spec = importlib.util.spec_from_file_location("make_synthetic", LOGS / "make_synthetic.py")
    mk = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mk)
    return mk


def test_synthetic_log_is_labelled_synthetic():
    p = LOGS / "synthetic_heatup_7210.csv"
    assert "synthetic" in p.name
    assert read_log(p).comments[0].startswith("SYNTHETIC")


def test_shipped_synthetic_log_is_what_the_current_code_makes(tmp_path):
    """make_synthetic.py run now writes the shipped file again (same header, values within the
    1 mK rounding): a model change that moves the heat-up fails here until the log is regenerated."""
    mk = _make_synthetic()
    shipped, fresh = LOGS / "synthetic_heatup_7210.csv", read_log(mk.make(tmp_path / "synthetic.csv"))
    log = read_log(shipped)
    assert log.comments == fresh.comments and list(log.columns) == list(fresh.columns) == \
        ["t_s", "T_bearing_C", "T_room_C"]
    assert f"default_rng({mk.SEED})" in " ".join(log.comments) and f"bearing {mk.NOISE_K} K" in " ".join(log.comments)
    for c in log.columns:
        np.testing.assert_allclose(log[c], fresh[c], rtol=0, atol=1.5e-3)


def test_calibrate_on_the_shipped_synthetic_log_recovers_the_truth(synthetic_scene):
    """The shipped log (G = 0.85 W/K, 0.3 K noise, the logged room imposed on ambient as a time-varying
    boundary): the fit returns 0.85 within 2 standard uncertainties, with a residual of the added noise;
    holding the room at the scene's constant 22 °C instead biases the fit by many uncertainties."""
    mk = _make_synthetic()
    log = read_log(LOGS / "synthetic_heatup_7210.csv")
    m = channel_map(synthetic_scene, log)
    assert m == {"T_bearing_C": "bearing", "T_room_C": "impose:ambient"}
    cal = calibrate(synthetic_scene, log, [mk.PARAM], m)
    g, s = cal.values[mk.PARAM], cal.std[mk.PARAM]
    assert cal.start[mk.PARAM] == 1.0 and mk.G_TRUE_W_K == 0.85
    assert 0 < s < 0.01
    assert abs(g - mk.G_TRUE_W_K) < 2 * s
    assert cal.rms_residual == pytest.approx(mk.NOISE_K, rel=0.2)
    assert cal.comparison.mode.startswith("transient with logged boundary T_room_C → ambient")
    fixed_room = calibrate(synthetic_scene, log, [mk.PARAM], channel_map(synthetic_scene, log, {"T_room_C": "ignore"}))
    assert abs(fixed_room.values[mk.PARAM] - mk.G_TRUE_W_K) > 4 * fixed_room.std[mk.PARAM]


# ------------------------------------------------------------------ compare / calibrate
def _skf_scene():
    return load_scene(LOGS / "seed002_skf_scene.toml")


def test_compare_steady_skf_metrics_match_the_arrays():
    scene = _skf_scene()
    log = read_log(LOGS / "seed002_greases.csv")
    comp = compare(scene, log, channel_map(scene, log))
    e = comp.simulated["torque_Nm"] - log["torque_Nm"]
    assert comp.metrics["torque_Nm"]["rmse"] == pytest.approx(float(np.sqrt(np.mean(e**2))))
    # the model sees each row's lubricant and measured temperature: MG1 (230 cSt at 40 °C) above PG2 (32.5 cSt)
    assert comp.simulated["torque_Nm"][0] > comp.simulated["torque_Nm"][4]


def test_calibrate_skf_recovers_constants_of_model_generated_data(tmp_path):
    """Torques generated by the SKF model with R1 = 8e-7, S1 = 1.2e-2 (no noise): the fit returns them."""
    scene = _skf_scene()
    rows = [(n, T) for n in (500.0, 1000.0, 1500.0, 2000.0) for T in (40.0, 60.0)]
    from thermobear.coupled import solve
    sc = scene.with_(models={"skf_R1": 8e-7, "skf_S1": 1.2e-2})
    M = [solve(sc.with_(n_rpm=n, T_C=T)).torque_Nm for n, T in rows]
    text = "n_rpm,torque_Nm,T_III_C\n" + "\n".join(f"{n},{m!r},{T}" for (n, T), m in zip(rows, M)) + "\n"
    log = read_log(_write(tmp_path, text))
    cal = calibrate(scene, log, ["skf_R1", "skf_S1"], channel_map(scene, log))
    assert cal.values["skf_R1"] == pytest.approx(8e-7, rel=1e-5)
    assert cal.values["skf_S1"] == pytest.approx(1.2e-2, rel=1e-5)
    assert cal.dof == len(rows) - 2 and cal.std["skf_R1"] < 1e-3 * 8e-7


def test_calibrate_bad_parameters(synthetic_scene):
    log = read_log(LOGS / "synthetic_heatup_7210.csv")
    m = channel_map(synthetic_scene, log)
    with pytest.raises(InputError, match="--param"):
        calibrate(synthetic_scene, log, ["no_such_parameter"], m)
    with pytest.raises(InputError, match="SKF"):
        calibrate(synthetic_scene, log, ["skf_R1"], m)
    with pytest.raises(InputError, match="start value"):
        calibrate(synthetic_scene, log, ["bearing_to_ambient.G_W_K=abc"], m)


def test_compare_with_imposed_ring_temperatures_reproduces_the_free_solution(tmp_path):
    """Rows whose logged IR/OR temperatures are the model's own free steady state: imposing them
    ("impose:<node>", seed 004 §4.5) gives back the same torque and ball temperature."""
    import warnings

    import thermobear as tb
    from thermobear.coupled import steady_state
    warnings.simplefilter("ignore", tb.ExtrapolationWarning)
    # models pinned: the test is about imposing temperatures (a point inside a switch band blends two
    # models' answers, and the blend of two solutions is the solution of neither to ~1e-5 K)
    sc = tb.load_scene(ROOT / "examples" / "seed004_oil_jet_7210.toml").with_(
        models={"high_speed": True, "load_model": "jones_harris"})
    rows = []
    for n in (3200.0, 4800.0):
        st = steady_state(sc.with_(n_rpm=n))
        rows.append(f"{n},{st.T_C['inner_ring']!r},{st.T_C['outer_ring']!r},{st.T_C['balls']!r},"
                    f"{st.P_W / (n * np.pi / 30)!r}")
    log = read_log(_write(tmp_path, "n_rpm,T_IR_C,T_OR_C,T_ball_C,torque_Nm\n" + "\n".join(rows) + "\n"))
    m = channel_map(sc, log, {"T_IR_C": "impose:inner_ring", "T_OR_C": "impose:outer_ring", "T_ball_C": "balls"})
    c = compare(sc, log, m)
    assert set(c.metrics) == {"T_ball_C", "torque_Nm"}          # imposed channels are inputs, not compared
    assert c.metrics["T_ball_C"]["rmse"] < 1e-3
    assert c.metrics["torque_Nm"]["rmse"] < 1e-6 * np.mean(log["torque_Nm"])


def test_transient_log_with_imposed_rings_runs_the_transient(tmp_path):
    """A heat-up log whose ring channels are imposed runs the transient with the logged rings as
    time-varying boundaries (not one equilibrium per row): the balls and the mixture start cold (more
    torque: viscous oil), reach the equilibrium with the rings within seconds, so rows logged at the free
    steady state give back its torque; a ring temperature rising later gives less torque (viscosity)."""
    import warnings

    import thermobear as tb
    from thermobear.coupled import steady_state
    warnings.simplefilter("ignore", tb.ExtrapolationWarning)
    sc = tb.load_scene(ROOT / "examples" / "seed004_oil_jet_7210.toml").with_(
        models={"high_speed": True, "load_model": "jones_harris"})          # one model (no switch-band blend)
    st = steady_state(sc)
    Ti, To = st.T_C["inner_ring"], st.T_C["outer_ring"]
    text = "t_s,T_IR_C,T_OR_C,torque_Nm\n" + "".join(
        f"{t},{Ti + dT!r},{To + dT!r},0.1\n" for t, dT in ((0, 0.0), (600, 0.0), (1200, 0.0), (1800, 15.0)))
    log = read_log(_write(tmp_path, text))
    m = channel_map(sc, log, {"T_IR_C": "impose:inner_ring", "T_OR_C": "impose:outer_ring"})
    c = compare(sc, log, m)
    assert c.mode.startswith("transient with logged boundary T_IR_C → inner_ring, T_OR_C → outer_ring")
    tq = c.simulated["torque_Nm"]
    M_eq = st.P_W / sc.omega
    assert tq[0] > 1.2 * M_eq                                  # cold balls and mixture at the start
    np.testing.assert_allclose(tq[1:3], M_eq, rtol=1e-4)     # ≈ 2 mK of the integrator tolerance
    assert tq[3] < 0.95 * tq[2]
    # the trajectory is continuous: it passes through the logged rows and the rings follow the log linearly
    assert c.model_x.size > 300 and np.all(np.isin(log.t_s, c.model_x))
    run_T = c.model["torque_Nm"]
    assert np.all(np.isfinite(run_T)) and run_T[np.searchsorted(c.model_x, 1500.0)] < M_eq


def test_impose_needs_a_known_node(tmp_path, synthetic_scene):
    log = read_log(_write(tmp_path, "t_s,T_bearing_C,T_room_C\n0,20,20\n10,21,20\n"))
    with pytest.raises(InputError) as e:
        channel_map(synthetic_scene, log, {"T_bearing_C": "impose:spindle"})
    assert e.value.field == "rig.map.T_bearing_C"


def _with_column(tmp_path, name, values_of_t, out="loads.csv"):
    """The shipped synthetic heat-up log with one more column, its value a function of t [s]."""
    lines = (LOGS / "synthetic_heatup_7210.csv").read_text(encoding="utf-8").splitlines()
    rows = [l if l.startswith("#") else (f"{l},{name}" if l.startswith("t_s") else f"{l},{values_of_t(float(l.split(',')[0]))}")
            for l in lines]
    return read_log(_write(tmp_path, "\n".join(rows) + "\n", out))


def test_transient_log_load_columns_step_the_operating_point(tmp_path, synthetic_scene):
    """Fa_N / Fr_N columns of a transient log drive the run as n_rpm does: the first row's loads start
    it, a change steps the schedule at that row (they used to be ignored: metrics equal to the plain log)."""
    plain = read_log(LOGS / "synthetic_heatup_7210.csv")
    m = channel_map(synthetic_scene, plain)
    base = compare(synthetic_scene, plain, m).simulated["T_bearing_C"]
    t = plain.t_s
    bnd = (t, {"ambient": plain["T_room_C"]})
    step = _with_column(tmp_path, "Fa_N", lambda x: 1000 if x < 900 else 6000)
    c = compare(synthetic_scene, step, m)
    assert c.mode.endswith("; 1 step from Fa_N")
    direct = transient(synthetic_scene.with_(Fa=1000.0), float(t[-1]), schedule=[(900.0, {"Fa_N": 6000.0})],
                       t_eval=t, T0_C=float(plain["T_room_C"][0]), rtol=1e-6, atol=1e-5, boundary=bnd)
    np.testing.assert_allclose(c.simulated["T_bearing_C"], direct.T_C["bearing"], rtol=1e-9)
    assert c.simulated["T_bearing_C"][-1] > base[-1] + 10.0            # 6 kN axial: far more heat
    np.testing.assert_allclose(c.simulated["T_bearing_C"][t < 900], base[t < 900], rtol=1e-9)
    const = _with_column(tmp_path, "Fr_N", lambda x: 3000, "fr.csv")
    c = compare(synthetic_scene, const, m)
    assert c.mode.endswith("; logged load held: Fr_N 3000 N")
    direct = transient(synthetic_scene.with_(Fr=3000.0), float(t[-1]), t_eval=t, T0_C=float(plain["T_room_C"][0]),
                       rtol=1e-6, atol=1e-5, boundary=bnd)
    np.testing.assert_allclose(c.simulated["T_bearing_C"], direct.T_C["bearing"], rtol=1e-9)
    assert abs(c.simulated["T_bearing_C"][-1] - base[-1]) > 1.0
    gap = _with_column(tmp_path, "Fr_N", lambda x: "" if x == 600 else 3000, "gap.csv")
    with pytest.raises(InputError) as e:
        compare(synthetic_scene, gap, m)
    assert e.value.field == "gap.csv: column Fr_N"


def test_transient_log_change_on_the_last_row_is_ignored(tmp_path, synthetic_scene):
    """A speed or load change on the log's last row (t = t_end) has no time to act: the run is the
    log's without it, the mode line says so (it used to be refused naming 'schedule[0].t_s', a
    schedule the user never wrote); the last row's torque is at the speed still running."""
    plain = read_log(LOGS / "synthetic_heatup_7210.csv")
    m = channel_map(synthetic_scene, plain)
    base = compare(synthetic_scene, plain, m).simulated["T_bearing_C"]
    for col, before, after in (("n_rpm", 3000, 4000), ("Fa_N", 1000, 6000)):
        log = _with_column(tmp_path, col, lambda x: before if x < 1800 else after, f"{col}.csv")
        c = compare(synthetic_scene, log, m)
        np.testing.assert_allclose(c.simulated["T_bearing_C"], base, rtol=1e-9)
        assert c.mode.endswith(f"; the change of {col} on the last row (t = 1800 s) has no time to act: ignored")
    lines = (tmp_path / "n_rpm.csv").read_text(encoding="utf-8").splitlines()
    log = read_log(_write(tmp_path, "\n".join(l if l.startswith("#") else l + (",torque_Nm" if l.startswith("t_s")
                                                                              else ",0.1") for l in lines) + "\n"))
    c = compare(synthetic_scene, log, m)
    tq = c.simulated["torque_Nm"]
    assert tq[-1] == pytest.approx(tq[-2], rel=0.02)             # at 3000 rpm, not the P_W(3000) / ω(4000)
    huge = _with_column(tmp_path, "Fr_N", lambda x: 1000 if x < 1800 else 1e7, "huge.csv")
    with pytest.raises(InputError, match="static safety") as e:       # not run, yet no bearing carries it
        compare(synthetic_scene, huge, m)
    assert e.value.field.startswith("huge.csv: last row (t = 1800 s): operation")


def test_compare_refuses_a_one_row_transient_log_naming_it_and_states_the_units(tmp_path, capsys):
    """A one-row transient log ran a heat-up from t_s to itself: `error: t_end_s = 0.0 — must be > 0`, naming no
    file.  It is refused naming the CSV (a transient log needs two rows at increasing times), by compare and
    calibrate alike, nothing written; and the compare table's "SS err" column carries its unit as the others do."""
    from thermobear.app.cli import main
    scene, out = tmp_path / "s.toml", tmp_path / "cmp.csv"
    assert main(["init", "6208", "--lubrication", "oil-bath", "--out", str(scene)]) == 0
    one = _write(tmp_path, "t_s,T_outer_ring_C\n0,20\n", "one_row.csv")
    for verb in (["compare", "--csv", str(out)], ["calibrate", "--param", "T_ambient_C"]):
        capsys.readouterr()
        assert main([verb[0], str(scene), str(one), "--map", "T_outer_ring_C=outer_ring", *verb[1:]]) == 2
        err = capsys.readouterr().err
        assert err.startswith("error: one_row.csv = '1 row (t_s = 0 s)' — a transient log needs at least two rows")
        assert len(err.splitlines()) == 1 and not out.exists()
    three = _write(tmp_path, "t_s,T_outer_ring_C\n0,20\n600,30\n1200,35\n", "three.csv")
    assert main(["compare", str(scene), str(three), "--map", "T_outer_ring_C=outer_ring"]) == 0
    text = capsys.readouterr().out
    row = next(ln for ln in text.splitlines() if ln.startswith("T_outer_ring_C"))
    assert [t for t in row.split() if t in ("K",)] == ["K"] * 4                  # RMSE, max err, bias, SS err
