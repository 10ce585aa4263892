"""The command line: every verb, JSON output, plots, and bad input (exit 2, one line, nothing written)."""
from __future__ import annotations

import json
import math
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from thermobear.app.cli import main

ROOT = Path(__file__).resolve().parents[1]
EX = ROOT / "examples"
LOGS = EX / "logs"
SEED000 = str(EX / "seed000_grease_thrust_3ball.toml")        # prescribed temperature: fast
SEED001 = str(EX / "seed001_spin_down_3ball.toml")
SYNTH = str(LOGS / "synthetic_heatup_scene.toml")              # one-node network: fast transient
SKF = str(LOGS / "seed002_skf_scene.toml")


def run(capsys, *argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def assert_bad_input(code, err, field):
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("error: ") and field in lines[0]
    assert "Traceback" not in err


def bad_scene(tmp_path):
    text = Path(SEED000).read_text(encoding="utf-8").replace('catalog = "51205-3ball"',
                                                             'catalog = "51205-3ball"\nfi = 0.49')
    p = tmp_path / "bad.toml"
    p.write_text(text, encoding="utf-8")
    return p


# ------------------------------------------------------------------ run / list / loads
def test_run_json_prescribed_temperature(capsys):
    code, out, _ = run(capsys, "run", SEED000, "--json")
    assert code == 0
    d = json.loads(out)
    assert d["P_W"] == pytest.approx(sum(d["breakdown_W"].values()), rel=1e-12)
    assert d["torque_Nm"] == pytest.approx(d["P_W"] / (200 * math.pi / 30), rel=1e-12)


def test_run_set_override_changes_speed(capsys):
    _, out1, _ = run(capsys, "run", SEED000, "--json")
    _, out2, _ = run(capsys, "run", SEED000, "--json", "--set", "n_rpm=400")
    assert json.loads(out2)["n_rpm"] == 400.0
    assert json.loads(out2)["P_W"] > json.loads(out1)["P_W"]


def test_run_plots(capsys, tmp_path):
    code, _, err = run(capsys, "run", SEED000, "--plot", tmp_path / "plots")
    assert code == 0
    names = sorted(p.name for p in (tmp_path / "plots").glob("*.png"))
    assert names == ["ball_loads.png", "loss_breakdown.png", "regime_map.png"]
    assert all((tmp_path / "plots" / n).stat().st_size > 10_000 for n in names)


def test_run_bad_scene_exit_2_no_plot(capsys, tmp_path):
    code, out, err = run(capsys, "run", bad_scene(tmp_path), "--plot", tmp_path / "plots")
    assert_bad_input(code, err, "fi")
    assert not (tmp_path / "plots").exists()


def test_thrust_bearing_without_axial_load_exit_2(capsys, tmp_path):
    code, out, err = run(capsys, "run", str(EX / "seed002_grease_thrust_51107.toml"), "--set", "Fa=0",
                         "--plot", tmp_path / "plots")
    assert_bad_input(code, err, "Fa_N")
    assert out == "" and not (tmp_path / "plots").exists()


@pytest.mark.parametrize("where", ["under_a_file", "/proc/thermobear-test"])
def test_run_plot_folder_that_cannot_be_made_is_refused_before_computing(capsys, tmp_path, where):
    if where == "under_a_file":
        (tmp_path / "file").write_text("x")
        where = tmp_path / "file" / "plots"
    code, out, err = run(capsys, "run", SEED000, "--plot", where)
    assert_bad_input(code, err, "--plot")
    assert out == "" and not Path(where).exists()


def test_list_and_loads(capsys):
    code, out, _ = run(capsys, "list", "--json")
    assert code == 0 and "7210" in json.loads(out)["bearings"]
    code, out, _ = run(capsys, "loads", str(EX / "seed004_oil_jet_7210.toml"), "--json")
    d = json.loads(out)
    assert code == 0 and len(d["Q_inner_N"]) == len(d["psi_deg"]) and d["form"].startswith("high-speed")


def test_list_bearings_of_a_series(capsys):
    code, out, _ = run(capsys, "list", "bearings", "--series", "62", "--json")
    rows = json.loads(out)
    assert code == 0 and [r["designation"] for r in rows][:3] == ["6200", "6201", "6202"]
    r = next(r for r in rows if r["designation"] == "6208")
    assert (r["d_mm"], r["D_mm"], r["B_mm"]) == (40.0, 80.0, 18.0) and "D_mm" in r["estimated"] and r["C0_kN"] > 0
    code, out, _ = run(capsys, "list", "bearings", "--series", "72 B")
    assert code == 0 and "7205B" in out and "40.00" in out
    code, _, err = run(capsys, "list", "bearings", "--series", "99")
    assert code == 2 and "known series" in err


def test_solver_error_exit_3(capsys, monkeypatch):
    import thermobear.app.verbs as verbs
    from thermobear.errors import ThermalRunaway

    def boom(scene):
        raise ThermalRunaway("losses grow faster than dissipation above 180 °C", iterations=7, residual=3.0)
    monkeypatch.setattr(verbs, "solve", boom)
    code, _, err = run(capsys, "run", SEED000)
    assert code == 3 and err.strip() == "error: ThermalRunaway: losses grow faster than dissipation above 180 °C"


def test_runaway_of_a_built_oil_bath_network_is_exit_3_not_bad_input(capsys):
    # 6208 in an oil bath at 30 000 rpm: the heating path passes the oil's 250 °C limit; a bath node
    # beyond it on the way is the runaway's (exit 3, named, 250 °C in the reason), not bad input (exit 2)
    code, out, err = run(capsys, "run", EX / "oil_bath_6208.toml", "--set", "n_rpm=30000", "--json")
    assert code == 3 and err.startswith("error: ThermalRunaway:") and "250 °C" in err and "nan" not in err
    got = json.loads(out)              # --json: the failure as data on stdout (it printed nothing; a caller lost it)
    assert got["error"] == "ThermalRunaway" and got["iterations"] >= 1 and "250 °C" in got["message"]
    assert isinstance(got["history"], list) and "NaN" not in out


def test_console_script_bad_input_no_traceback(tmp_path):
    exe = shutil.which("thermobear", path=str(Path(sys.executable).parent))
    cmd = [exe] if exe else [sys.executable, "-m", "thermobear.app.cli"]
    r = subprocess.run(cmd + ["run", str(bad_scene(tmp_path))], capture_output=True, text=True, timeout=120)
    assert r.returncode == 2
    assert "Traceback" not in r.stderr
    assert len(r.stderr.strip().splitlines()) == 1 and ".fi = 0.49 — " in r.stderr


# ------------------------------------------------------------------ transient
def test_transient_csv_and_json(capsys, tmp_path):
    out_csv = tmp_path / "tr.csv"
    code, out, _ = run(capsys, "transient", SYNTH, "--t-end", 600, "--points", 7, "--csv", out_csv, "--json")
    assert code == 0
    d = json.loads(out)
    T = np.array(d["T_C"]["bearing"])
    assert T[0] == pytest.approx(22.0) and np.all(np.diff(T) > 0)        # heats up from ambient
    lines = [l for l in out_csv.read_text().splitlines() if not l.startswith("#")]
    assert lines[0].split(",")[:3] == ["t_s", "T_bearing_C", "T_ambient_C"] and len(lines) == 8
    assert float(lines[-1].split(",")[1]) == pytest.approx(T[-1], rel=1e-9)
    P = np.array(d["P_W"])
    assert P[-1] == pytest.approx(sum(np.array(v)[-1] for v in d["breakdown_W"].values()), rel=1e-9)


def test_transient_schedule_speed_step(capsys, tmp_path):
    sch = tmp_path / "s.toml"
    sch.write_text("[[step]]\nt_s = 300.0\nn_rpm = 1000.0\n", encoding="utf-8")
    code, out, _ = run(capsys, "transient", SYNTH, "--t-end", 600, "--points", 61, "--schedule", sch, "--json")
    d = json.loads(out)
    t, P = np.array(d["t_s"]), np.array(d["P_W"])
    assert code == 0 and P[t > 300].max() < 0.5 * P[(t > 250) & (t < 300)].min()   # 3000 → 1000 rpm: less loss


@pytest.mark.parametrize("args, field", [
    (["--t-end", "-5"], "--t-end"),
    (["--t-end", "60", "--schedule", "SCHED"], "step[0].speed"),
    (["--t-end", "60", "--csv", "NOFOLDER/x.csv"], "--csv"),
])
def test_transient_bad_input_writes_nothing(capsys, tmp_path, args, field):
    sch = tmp_path / "bad_schedule.toml"
    sch.write_text("[[step]]\nt_s = 10.0\nspeed = 1000.0\n", encoding="utf-8")
    args = [a.replace("SCHED", str(sch)).replace("NOFOLDER", str(tmp_path / "nofolder")) for a in args]
    out_csv = tmp_path / "out.csv"
    extra = [] if "--csv" in args else ["--csv", out_csv]
    code, _, err = run(capsys, "transient", SYNTH, *args, *extra)
    assert_bad_input(code, err, field)
    assert not out_csv.exists() and not (tmp_path / "nofolder").exists()


def test_schedule_or_log_that_is_a_folder_says_so(capsys, tmp_path):
    """`--schedule /tmp` said 'file not found' for a folder that exists (so did a log path)."""
    code, _, err = run(capsys, "transient", SYNTH, "--t-end", 60, "--schedule", tmp_path)
    assert_bad_input(code, err, "--schedule")
    assert err.strip().endswith("— is a folder, not a schedule file (TOML)")
    code, _, err = run(capsys, "transient", SYNTH, "--t-end", 60, "--schedule", tmp_path / "none.toml")
    assert err.strip().endswith("— file not found")
    code, _, err = run(capsys, "compare", SYNTH, tmp_path)
    assert_bad_input(code, err, "log")
    assert err.strip().endswith("— is a folder, not a log file (CSV)")


def test_transient_refuses_prescribed_temperature(capsys):
    code, _, err = run(capsys, "transient", SEED000, "--t-end", 10)
    assert_bad_input(code, err, "operation.T_C")


# ------------------------------------------------------------------ sweep
def test_sweep_csv(capsys, tmp_path):
    out_csv = tmp_path / "sw.csv"
    code, _, err = run(capsys, "sweep", SEED000, "--n-rpm", "100:300:3", "--T-C", "23.5,40", "--csv", out_csv,
                       "--processes", 1)
    assert code == 0 and "6/6" in err                     # progress bar on stderr
    rows = [l.split(",") for l in out_csv.read_text().splitlines() if not l.startswith("#")]
    head = rows[0]
    assert head[:3] == ["index", "n_rpm", "T_C"] and len(rows) == 1 + 6
    assert sorted(int(r[0]) for r in rows[1:]) == list(range(6))
    P = {(float(r[1]), float(r[2])): float(r[head.index("P_W")]) for r in rows[1:]}
    assert P[(300.0, 23.5)] > P[(200.0, 23.5)] > P[(100.0, 23.5)]      # more speed, more loss
    assert P[(200.0, 40.0)] < P[(200.0, 23.5)]                          # thinner oil, less rolling loss
    code, out, _ = run(capsys, "run", SEED000, "--json", "--set", "n_rpm=200")
    assert P[(200.0, 23.5)] == pytest.approx(json.loads(out)["P_W"], rel=1e-9)   # same number as a single run


@pytest.mark.parametrize("args, field", [
    (["--n-rpm", "1000:x:3"], "--n-rpm"),
    (["--n-rpm", "100,-5"], "n_rpm"),
    (["--lubricant", "no-such-oil"], "lubricant"),
    ([], "sweep"),
])
def test_sweep_bad_input_writes_nothing(capsys, tmp_path, args, field):
    out_csv = tmp_path / "sw.csv"
    code, _, err = run(capsys, "sweep", SEED000, *args, "--csv", out_csv, "--quiet")
    assert_bad_input(code, err, field)
    assert not out_csv.exists()


# ------------------------------------------------------------------ compare / calibrate
def test_compare_transient_json_and_plot(capsys, tmp_path):
    code, out, err = run(capsys, "compare", SYNTH, LOGS / "synthetic_heatup_7210.csv", "--json",
                         "--plot", tmp_path / "p", "--csv", tmp_path / "c.csv")
    assert code == 0
    m = json.loads(out)["metrics"]["T_bearing_C"]
    assert m["n"] == 61 and m["rmse"] > 0 and {"steady_state_error", "t90_measured_s", "t90_simulated_s"} <= set(m)
    assert (tmp_path / "p" / "compare_heatup.png").is_file()
    head = (tmp_path / "c.csv").read_text().splitlines()[1]
    assert head == "t_s,T_bearing_C,T_bearing_C_model"


def test_compare_steady_with_input_temperature(capsys):
    code, out, _ = run(capsys, "compare", SKF, LOGS / "seed002_mg1.csv", "--json")
    d = json.loads(out)
    assert code == 0 and list(d["metrics"]) == ["torque_Nm"] and d["metrics"]["torque_Nm"]["n"] == 2


@pytest.mark.parametrize("extra, field", [
    (["--map", "T_nope_C=bearing"], "--map.T_nope_C"),
    (["--map", "T_bearing_C=housing"], "rig.map.T_bearing_C"),
    (["--map", "T_bearing_C"], "--map"),
])
def test_compare_bad_map(capsys, tmp_path, extra, field):
    code, _, err = run(capsys, "compare", SYNTH, LOGS / "synthetic_heatup_7210.csv", *extra,
                       "--plot", tmp_path / "p")
    assert_bad_input(code, err, field)
    assert not (tmp_path / "p").exists()


def test_compare_malformed_log(capsys, tmp_path):
    log = tmp_path / "log.csv"
    log.write_text("t_s,T_bearing_C\n0,22\n30,hot\n", encoding="utf-8")
    code, _, err = run(capsys, "compare", SYNTH, log)
    assert_bad_input(code, err, "line 3, column T_bearing_C")


def test_calibrate_skf_cli(capsys):
    code, out, _ = run(capsys, "calibrate", SKF, LOGS / "seed002_greases.csv", "--param", "skf_R1",
                       "--param", "skf_S1", "--json")
    d = json.loads(out)
    assert code == 0 and d["dof"] == 7 - 2
    assert d["std"]["skf_R1"] > 0 and d["metrics"]["torque_Nm"]["rmse"] < 0.02     # fitted: within 20 N mm


def test_calibrate_unknown_parameter(capsys):
    code, _, err = run(capsys, "calibrate", SYNTH, LOGS / "synthetic_heatup_7210.csv", "--param", "G_nope")
    assert_bad_input(code, err, "--param")


# ------------------------------------------------------------------ spin-down
def test_spin_down_fit_is_independent_of_inertia(capsys):
    code, out, _ = run(capsys, "spin-down", SEED001, "--J", "1e-4", "--rpm", "120", "--json")
    a = json.loads(out)["runs"][0]
    _, out, _ = run(capsys, "spin-down", SEED001, "--J", "2e-4", "--rpm", "120", "--json")
    b = json.loads(out)["runs"][0]
    assert code == 0 and 0 < a["n"] < 1
    assert b["t_stop_s"] == pytest.approx(2 * a["t_stop_s"], rel=1e-4)       # t_max ∝ J
    assert b["K_star"] == pytest.approx(a["K_star"], rel=1e-4) and b["n"] == pytest.approx(a["n"], abs=1e-5)
    # the fitted power law passes near the model torque at the initial speed
    assert a["T_fit_at_omega0_Nm"] == pytest.approx(a["T0_Nm"], rel=0.1)


def test_spin_down_against_seed001_log(capsys, tmp_path):
    code, out, _ = run(capsys, "spin-down", SEED001, "--J", "1e-4", "--log", LOGS / "seed001_table2_torque.csv",
                       "--json", "--plot", tmp_path / "p")
    runs = json.loads(out)["runs"]
    assert code == 0 and [r["n0_rpm"] for r in runs] == [60, 90, 120, 150, 180, 210]
    assert all(r["T_error"] == pytest.approx(r["T0_Nm"] / r["T_log_Nm"] - 1) for r in runs)
    assert sorted(p.name for p in (tmp_path / "p").glob("*.png")) == ["spin_down.png", "spin_down_torque.png"]


def test_a_spin_down_log_column_it_does_not_use_is_named(capsys, tmp_path):
    """A temperature column of a spin-down log was ignored silently: the runs are at the scene's T_C."""
    rows = [l for l in (LOGS / "seed001_table2_torque.csv").read_text(encoding="utf-8").splitlines()
            if l and not l.startswith("#")]
    log = tmp_path / "with_T.csv"
    log.write_text("\n".join([rows[0] + ",T_race_C"] + [r + ",40" for r in rows[1:]]) + "\n", encoding="utf-8")
    code, out, err = run(capsys, "spin-down", SEED001, "--J", "1e-4", "--log", log, "--json")
    assert code == 0 and len(json.loads(out)["runs"]) == len(rows) - 1
    assert "with_T.csv: column T_race_C not used" in err and "operation.T_C = 26.5 °C" in err
    _, _, err = run(capsys, "spin-down", SEED001, "--J", "1e-4", "--log", LOGS / "seed001_table2_torque.csv", "--json")
    assert "not used" not in err


def test_spin_down_needs_inertia(capsys, tmp_path):
    # a copy of the seed 001 scene without its [rig] table: the inertia is missing
    text = open(SEED001).read().split("\n[rig]")[0]
    bare = tmp_path / "no_rig.toml"
    bare.write_text(text)
    code, _, err = run(capsys, "spin-down", str(bare), "--rpm", "120")
    assert_bad_input(code, err, "rig.J_kg_m2")


# ------------------------------------------------------------------ bad input named by its field
@pytest.mark.parametrize("T0", ["nan", "-300", "1000", "inf"])
def test_transient_start_temperature_is_refused_by_its_own_name(capsys, tmp_path, T0):
    """--T0-C nan ended in a scipy ValueError, -300 reported "T1_K = -26.85", 1000 exited with 3."""
    out_csv = tmp_path / "t.csv"
    code, _, err = run(capsys, "transient", SYNTH, "--t-end", 10, "--T0-C", T0, "--csv", out_csv)
    assert_bad_input(code, err, "--T0-C")
    assert not out_csv.exists()


def test_a_sweep_with_failed_points_exits_3_after_writing_every_row_unless_allowed(capsys, tmp_path):
    out_csv = tmp_path / "s.csv"
    s004 = str(EX / "seed004_oil_jet_7210.toml")
    code, _, err = run(capsys, "sweep", s004, "--Fa", "0,450", "--n-rpm", "3000", "--csv", out_csv, "--quiet")
    lines = [r for r in out_csv.read_text().splitlines() if not r.startswith("#")]
    assert code == 3 and len(lines) == 3 and "1 of 2 points failed (NoEquilibrium)" in err
    code, _, _ = run(capsys, "sweep", s004, "--Fa", "0,450", "--n-rpm", "3000", "--csv", out_csv, "--quiet",
                     "--allow-failures")
    assert code == 0


def test_transient_t90_is_interpolated_between_output_times():
    from thermobear.app.verbs import t90_s
    t = np.linspace(0.0, 100.0, 11)
    T = 20.0 + 10.0 * (1.0 - np.exp(-t / 20.0))
    exact = -20.0 * np.log(1.0 - 0.9 * (1.0 - np.exp(-5.0)))      # where T reaches 90 % of its rise to T(100)
    assert t90_s(t, T) == pytest.approx(exact, rel=0.02) and t90_s(t, T) % 10.0 != 0.0
    assert t90_s(t, np.full(11, 20.0)) is None


def test_progress_on_a_pipe_is_a_line_every_few_seconds():
    import io
    from thermobear.app.output import Progress
    buf = io.StringIO()
    p = Progress(stream=buf, every_s=3600.0)
    for k in range(1, 501):
        p(k, 500)
    assert "\r" not in buf.getvalue() and buf.getvalue().count("\n") <= 2 and "500/500" in buf.getvalue()


def test_warnings_are_one_line_each_without_source_lines(capsys):
    code, _, err = run(capsys, "run", str(EX / "seed004_oil_jet_7210.toml"), "--set", "n_rpm=16000")
    lines = [line for line in err.splitlines() if line.strip()]
    assert code == 0 and lines and all(line.startswith("warning: ") for line in lines)
    assert len(lines) == len(set(lines)) and not any(".py" in line for line in lines)


def test_every_models_key_can_be_forced_on_the_command_line(capsys):
    s004 = str(EX / "seed004_oil_jet_7210.toml")
    code, out, _ = run(capsys, "run", s004, "--json", "--set", "models.drag=false", "--set", "models.hertz=houpert",
                       "--set", "T_C=50")
    d = json.loads(out)
    assert code == 0 and d["models_used"]["drag"]["choice"] is False and d["models_used"]["hertz"]["choice"] == "houpert"
    code, _, err = run(capsys, "run", s004, "--set", 'models.drag="false"')
    assert_bad_input(code, err, "models.drag")


def test_run_and_transient_plots_of_a_machine_show_its_network_and_power(capsys, tmp_path):
    scene = str(Path(__file__).parents[1] / "examples" / "block_6208_oil_bath.toml")
    code, _, _ = run(capsys, "run", scene, "--plot", tmp_path / "run")
    assert code == 0 and (tmp_path / "run" / "network.png").stat().st_size > 50_000
    code, _, _ = run(capsys, "transient", scene, "--t-end", "600", "--plot", tmp_path / "tr")
    assert code == 0 and (tmp_path / "tr" / "heatup.png").stat().st_size > 20_000


def test_node_families_group_a_machines_parts():
    from thermobear.app.plots import node_family
    assert [node_family(n) for n in ("inner_race", "shaft_seat_3_r2", "housing_foot", "balls", "oil_sump", "frame")] \
        == ["inner", "shaft", "housing", "ball", "oil", ""]


def test_one_warning_line_per_fact(capsys):
    """A lubricant temperature beyond its data is met by each of its properties in turn (β, η, k, ν) and by
    the contact temperature check: one fact, one warning line (there were five)."""
    assert main(["run", str(EX / "seed004_oil_jet_7210.toml"), "--set", "T_C=200"]) == 0
    err = capsys.readouterr().err.strip().splitlines()
    temp = [ln for ln in err if "lubricant temperature 200 °C" in ln]
    assert len(temp) == 1 and temp[0].startswith("warning: ExtrapolationWarning: ")


def test_negative_ranges_and_values_follow_their_option_as_they_are(capsys, tmp_path):
    """`sweep --T-C -10:100:12` failed in argparse ("expected one argument": a value starting with '-' taken for an
    option); only --T-C=-10:100:12 worked.  A number, list or range after an option that takes a value is its value,
    in every verb (--T0-C -1e3 reaches its own check); the sweep's help says so."""
    scene = tmp_path / "s.toml"
    assert main(["init", "6208", "--lubrication", "oil-bath", "--out", str(scene)]) == 0
    capsys.readouterr()
    for T in (["--T-C", "-10:100:3"], ["--T-C=-10:100:3"], ["--T-C", "-10,45,1e2"]):
        code, out, err = run(capsys, "sweep", scene, *T, "--n-rpm", "1000", "--quiet")
        assert code == 0, err
        rows = [ln.split(",") for ln in out.splitlines() if not ln.startswith("#")]
        assert [float(r[rows[0].index("T_C")]) for r in rows[1:]] == [-10.0, 45.0, 100.0]
    code, _, err = run(capsys, "sweep", scene, "--Fa", "-5:10:2", "--quiet")
    assert_bad_input(code, err, "Fa")                                # the sweep's own check, not argparse's
    code, _, err = run(capsys, "transient", scene, "--t-end", "10", "--T0-C", "-1e3")
    assert_bad_input(code, err, "--T0-C = -1000.0 — start temperature")
    with pytest.raises(SystemExit):
        main(["sweep", "--help"])
    assert "--T-C -10:100:12" in " ".join(capsys.readouterr().out.split())
    from thermobear.app.cli import build_parser, valued_options
    v = valued_options(build_parser())           # read off the parser, argument groups' options too
    assert {"--T-C", "--T0-C", "--seed", "--groups", "--set", "--uncertainty"} <= v and "--json" not in v


def test_a_scene_input_the_models_do_not_read_is_named(capsys):
    """``--set mu_full_film=0.01`` under the default Eyring traction: one named warning line; ``calibrate --param
    mu_full_film`` is refused up front (exit 2, one line naming it)."""
    s004 = str(EX / "seed004_oil_jet_7210.toml")
    code, _, err = run(capsys, "run", s004, "--set", "mu_full_film=0.01", "--set", "T_C=60")
    assert code == 0
    assert [line for line in err.splitlines() if "UnreadInput: lubricant.mu_full_film" in line] == [
        'warning: UnreadInput: lubricant.mu_full_film = 0.01 is not read by the chosen models: models.traction = '
        '"eyring" (oil film) takes the full-film friction from the oil\'s traction law; mu_full_film is read with '
        'models.traction = "constant" or by a ring-guided cage\'s pocket friction — it changes nothing here']
    code, _, err = run(capsys, "run", s004, "--set", "mu_full_film=0.01", "--set", "T_C=60",
                       "--set", "models.traction=constant")
    assert code == 0 and "UnreadInput: lubricant.mu_full_film" not in err
    code, _, err = run(capsys, "calibrate", SYNTH, LOGS / "synthetic_heatup_7210.csv", "--param", "mu_full_film")
    assert_bad_input(code, err, "--param = 'mu_full_film' — the scene's models do not read it")


def test_loads_says_when_run_solves_the_scene_with_the_film_load_model(capsys):
    """`loads` prints the dry distribution; where `run` puts the films in the contact laws (a 6208 oil bath, 3 of
    9 balls loaded dry) its loads differ (×4 and more when cold): one note line and the JSON's `note` say so."""
    bath = str(EX / "oil_bath_6208.toml")
    code, out, _ = run(capsys, "loads", bath, "--set", "Fr_N=2000")
    assert code == 0 and out.splitlines()[-1].startswith("note: run solves this scene with the film load model")
    code, out, _ = run(capsys, "loads", bath, "--set", "Fr_N=2000", "--json")
    d = json.loads(out)
    assert d["load_model"] == "film" and d["note"].startswith("note: run solves")
    code, out, _ = run(capsys, "loads", bath, "--set", "Fr_N=2000", "--set", "models.load_model=jones_harris", "--json")
    assert json.loads(out)["note"] is None
