"""The thermal preload of a position-preloaded pair of angular contact bearings (thermobear.scene.pair,
thermobear.loads.pair, thermobear.coupled.preload): the cold offset, the warm pair's loads, the fixed point of the
coupled steady state, its runaway, bad input and the command line."""
import json
import tomllib
import warnings
from pathlib import Path

import numpy as np
import pytest

import thermobear as tb
from thermobear.app.cli import main
from thermobear.app.sweep import run_sweep
from thermobear.contact.fits import T_REF_C, seated_raceway_growth
from thermobear.coupled.preload import (PRELOAD_TOL_N, pair_scene, preload_step_runs_away, scene_pair_loads,
                                        thermal_preload_warnings)
from thermobear.coupled.ratings import inner_seat
from thermobear.coupled.speeds import din732_safe_speed
from thermobear.errors import InputError, ThermalPreloadRunaway
from thermobear.loads.pair import pair_loads, pair_preload_offset
from thermobear.loads.sets import bearing_set
from thermobear.scene.scene import scene_from_dict

SEED004 = tb.example_path("seed004_oil_jet_7210.toml")
PAIRS = ("back_to_back", "face_to_face")


def hand_preload(brg, d):
    """Harris & Kotzalas 2007 ch. 7: a ball bearing whose inner ring is pushed axially by d beyond first touch, all
    balls alike: tan α = tan α0 + d/(A cos α0), F_a = Z K_n [A (cos α0/cos α − 1)]^1.5 sin α [N]."""
    A, a0 = brg.A, brg.alpha0
    al = np.arctan(np.tan(a0) + d / (A * np.cos(a0)))
    return brg.Z * brg.Kn() * (A * (np.cos(a0) / np.cos(al) - 1.0)) ** 1.5 * np.sin(al)


def seed004_pair(**kw):
    """Seed 004's 7210 on its oil jet as one bearing of a back-to-back pair preloaded to 450 N (seed 004's axial
    load), the block's 650 N radial load on the pair."""
    return tb.load_scene(SEED004).with_(arrangement="back_to_back", preload_N=450.0, Fa=0.0, Fr=650.0, **kw)


@pytest.fixture(scope="module")
def spindle(tmp_path_factory):
    """`thermobear init 7014C --lubrication oil-air --speed-rpm 12000`, made one bearing of a back-to-back pair
    preloaded to 300 N (a light spindle preload), the init scene's 2020 N radial load on the pair, no axial load."""
    path = tmp_path_factory.mktemp("pair") / "spindle_7014C.toml"
    assert main(["init", "7014C", "--lubrication", "oil-air", "--speed-rpm", "12000", "--out", str(path)]) == 0
    return tb.load_scene(path).with_(arrangement="back_to_back", preload_N=300.0, Fa=0.0)


@pytest.fixture(scope="module")
def spindle_state(spindle):
    with pytest.warns(tb.OutsideValidity):
        return tb.steady_state(spindle)


# --------------------------------------------------------------------------- (a) the cold offset
@pytest.mark.parametrize("name", ["7014C", "7205B", "7210"])
@pytest.mark.parametrize("F0", [50.0, 300.0, 1500.0])
def test_cold_offset_gives_the_preload_back(name, F0):
    """The offset of a cold preload F0, set back into bearing_set, gives F0 in both bearings (1e-6), and F0 is the
    hand formula's axial load at half the offset beyond first touch."""
    b = tb.bearing(name)
    off = pair_preload_offset(b, F0)
    for arrangement in PAIRS:
        assert np.allclose(bearing_set(b, arrangement, preload_offset=off).preload, F0, rtol=1e-6, atol=0)
    assert hand_preload(b, off / 2) == pytest.approx(F0, rel=1e-6)


# --------------------------------------------------------------------------- (b) symmetry
@pytest.mark.parametrize("arrangement", PAIRS)
@pytest.mark.parametrize("dT", [0.0, 15.0, 40.0])
def test_equal_temperatures_load_both_bearings_alike(arrangement, dT):
    """Without external load and with rings and balls at one temperature both bearings carry the same warm preload;
    at the mounting temperature it is the cold one."""
    b = tb.bearing("7014C")
    off = pair_preload_offset(b, 300.0)
    s = bearing_set(b, arrangement, preload_offset=off, dT_inner=dT, dT_outer=dT, dT_ball=dT)
    assert s.preload[0] == pytest.approx(s.preload[1], rel=1e-9)
    p = pair_loads(b, arrangement, 300.0, dT_inner=dT, dT_outer=dT, dT_ball=dT)
    assert p.Fa == pytest.approx(p.Fa_other, rel=1e-9) and p.preload == pytest.approx(s.preload[0], rel=1e-9)
    if dT == 0.0:
        assert p.preload == pytest.approx(300.0, rel=1e-9) and p.Fa == pytest.approx(300.0, rel=1e-9)


# --------------------------------------------------------------------------- (c) monotonic
@pytest.mark.parametrize("name", ["7014C", "7210"])
def test_warm_preload_rises_with_the_inner_ring_above_the_outer(name):
    """The outer ring 10 K above the mounting temperature, the balls at the rings' mean: the warm preload rises
    strictly with ΔT_i − ΔT_o, face to face faster than back to back (the shaft's axial growth adds to the
    face-to-face pair's preload and takes from the back-to-back pair's)."""
    b = tb.bearing(name)
    diffs = [-4.0, 0.0, 4.0, 8.0, 16.0]
    warm = {a: [pair_loads(b, a, 300.0, dT_inner=10.0 + d, dT_outer=10.0).preload for d in diffs] for a in PAIRS}
    for a in PAIRS:
        assert np.all(np.diff(warm[a]) > 0), warm[a]
    assert all(f > d for f, d in zip(warm["face_to_face"][2:], warm["back_to_back"][2:]))


def test_spring_preload_keeps_its_force_warm():
    b = tb.bearing("7014C")
    p = pair_loads(b, "back_to_back", 300.0, "spring", Fr=2020.0, dT_inner=30.0, dT_outer=10.0)
    assert p.preload == pytest.approx(300.0, rel=1e-9) and p.offset is None


def test_the_external_axial_load_goes_to_the_loaded_bearing():
    """With the shaft's axial load the scene's bearing is the one that carries more, the two axial loads apart by
    the external one (the shaft's axial equilibrium); a spring-held bearing keeps its force, the other takes the
    external load on top of it."""
    b = tb.bearing("7014C")
    for a in PAIRS:
        p = pair_loads(b, a, 300.0, "position", 1000.0, 2020.0)
        assert p.Fa > p.Fa_other and p.Fa - p.Fa_other == pytest.approx(1000.0, rel=1e-9)
        s = pair_loads(b, a, 300.0, "spring", 200.0, 0.0)
        assert s.Fa == pytest.approx(500.0, rel=1e-9) and s.Fa_other == pytest.approx(300.0, rel=1e-9)


# --------------------------------------------------------------------------- (d) the fixed point of a scene
def test_spindle_pair_solves_to_a_warm_preload_above_the_cold_one(spindle, spindle_state):
    """A 7014C pair at 12000 rpm on oil-air: the speed (the balls' centrifugal force, the inner rings' growth) and
    the warm rings and balls raise the 300 N preload; the answer's loads are the warm pair's at its own temperatures
    and speed (the fixed point, to tolerance), the power above the power at the cold preload (at speed), the warning
    named (warm > 2 × cold)."""
    st = spindle_state
    p = st.preload
    assert p["kind"] == "position" and p["cold_N"] == 300.0 and p["warm_N"] > 2 * 300.0
    assert p["residual_N"] <= PRELOAD_TOL_N and p["iterations"] == len(p["history"]) >= 3
    assert st.models_used["preload"][0] == "position" and "300 N cold" in st.models_used["preload"][1]
    T = p["temperatures_C"]
    assert T["inner ring"] == pytest.approx(st.T_C["inner_ring"]) and T["balls"] == pytest.approx(st.T_ball_C)
    u = seated_raceway_growth(spindle.bearing, spindle.n_rpm, **inner_seat(spindle))   # the ring on its seat
    again = pair_loads(spindle.bearing, "back_to_back", 300.0, "position", 0.0, spindle.Fr,
                       dT_inner=T["inner ring"] - T_REF_C, dT_outer=T["outer ring"] - T_REF_C,
                       dT_ball=T["balls"] - T_REF_C, n_rpm=spindle.n_rpm, u_inner=u)
    assert abs(again.Fa - p["Fa_N"]) <= PRELOAD_TOL_N and again.preload == pytest.approx(p["warm_N"], rel=1e-9)
    pre = [h["preload_N"] for h in p["history"]]
    assert pre == sorted(pre)                                    # the heat-up's way: rising to the answer
    at_speed = pair_loads(spindle.bearing, "back_to_back", 300.0, Fr=spindle.Fr, n_rpm=spindle.n_rpm,
                          u_inner=seated_raceway_growth(spindle.bearing, spindle.n_rpm, **inner_seat(spindle)))
    assert p["form"] == "high_speed" and p["at_speed_cold_N"] == pytest.approx(at_speed.preload, rel=1e-9)
    assert 300.0 < p["at_speed_cold_N"] < p["warm_N"]
    cold = tb.steady_state(pair_scene(spindle, at_speed))
    assert st.P_W > cold.P_W and st.T_C["inner_ring"] > cold.T_C["inner_ring"]
    assert any(w.quantity == "thermal_preload" for w in st.warnings)


def test_spring_preload_is_one_solve_at_the_cold_force(spindle, spindle_state):
    st = tb.steady_state(spindle.with_(preload="spring"))
    p = st.preload
    assert p["kind"] == "spring" and p["warm_N"] == 300.0 and p["iterations"] == 1 and p["history"] == []
    assert p["Fa_N"] == pytest.approx(300.0, rel=1e-9)
    assert st.P_W < spindle_state.P_W
    assert not any(w.quantity == "thermal_preload" for w in st.warnings)


def test_a_scene_without_a_pair_is_solved_as_before():
    """Seed 004 (one bearing, no arrangement): the answer of the code before the pair loop, to the last bit."""
    st = tb.steady_state(tb.load_scene(SEED004))
    assert st.preload is None and "preload" not in st.models_used
    assert st.P_W == 39.49342415993864


# --------------------------------------------------------------------------- (e) runaway
def test_seed004_pair_runs_away_at_6500_rpm():
    """Seed 004's 7210 as a back-to-back pair preloaded to 450 N: at 3200 rpm its preload settles (about three
    times the cold one), at 6500 rpm each step adds more than the last — a thermal preload runaway, named with the
    history of rising preloads; with a spring preload of the same force the point solves."""
    with pytest.warns(tb.OutsideValidity):
        ok = tb.steady_state(seed004_pair())
    assert 2 * 450.0 < ok.preload["warm_N"] < 5 * 450.0
    with pytest.raises(ThermalPreloadRunaway, match="thermal preload runaway of a back-to-back pair") as e:
        tb.steady_state(seed004_pair(n_rpm=6500.0))
    pre = e.value.preload_history_N
    assert len(pre) >= 3 and pre[0] > 450.0 and all(b > a for a, b in zip(pre, pre[1:]))
    assert preload_step_runs_away(e.value.history) and e.value.dT_inner_outer_K > 0
    spring = tb.steady_state(seed004_pair(n_rpm=6500.0, preload="spring"))
    assert spring.preload["warm_N"] == 450.0


def test_the_step_criterion_needs_growth_that_does_not_slow():
    """Synthetic histories of the loaded bearing's axial load (used → warm): the loop's steps r = g(F) − F.  Steps
    that grow and grow faster: a runaway.  Steps that grow for a while from a light preload, then slow and
    shrink (the 7014C pair at 16000 rpm: 13, 63, 136, 267, 101 N, settling at 1080 N): never called a runaway,
    though the secant slope passes 1 on the way."""
    def history(steps, F=431.0):
        out = []
        for r in steps:
            out.append(dict(Fa_used_N=F, Fa_N=F + r))
            F += r
        return out
    assert preload_step_runs_away(history([1398.0, 1278.0, 1470.0]))           # seed 004 at 6500 rpm
    settling = history([13.2, 62.8, 136.3, 267.2, 101.3, 41.9, 16.1])
    assert not any(preload_step_runs_away(settling[:k]) for k in range(1, len(settling) + 1))
    assert not preload_step_runs_away(history([100.0, 200.0]))                 # two steps decide nothing
    assert not preload_step_runs_away(history([-50.0, -80.0, -150.0]))         # falling: losing preload


# --------------------------------------------------------------------------- (f) bad input
def _pair_file(tmp_path, **bearing) -> Path:
    """Seed 004's scene file with keys added to its [bearing] table."""
    text = Path(SEED004).read_text(encoding="utf-8")
    keys = "".join(f"{k} = {json.dumps(v)}\n" for k, v in bearing.items())
    path = tmp_path / "pair.toml"
    path.write_text(text.replace('catalog = "7210"', 'catalog = "7210"\n' + keys, 1), encoding="utf-8")
    return path


@pytest.mark.parametrize("keys, field", [
    (dict(arrangement="back_to_back", preload_N=0.0), "bearing.preload_N"),
    (dict(arrangement="back_to_back", preload_N=-100.0), "bearing.preload_N"),
    (dict(arrangement="back_to_back", preload_N=300.0, preload="soft"), "bearing.preload"),
    (dict(arrangement="tandem", preload_N=300.0), "bearing.arrangement"),
    (dict(preload_N=300.0), "bearing.preload_N"),
    (dict(arrangement="face_to_face"), "bearing.preload_N"),
])
def test_bad_pair_keys_are_refused_naming_the_field(tmp_path, keys, field):
    with pytest.raises(InputError) as e:
        tb.load_scene(_pair_file(tmp_path, **keys))
    assert e.value.field == field


@pytest.mark.parametrize("name, kind", [("6208", "deep groove"), ("51205", "thrust")])
def test_a_pair_needs_angular_contact_bearings(name, kind):
    s = tb.load_scene(SEED004)
    with pytest.raises(InputError, match=f"only for angular contact bearings.*{kind}") as e:
        s.with_(bearing=name, arrangement="back_to_back", preload_N=300.0, Fr=0.0 if kind == "thrust" else 325.0)
    assert e.value.field == "bearing.arrangement" and e.value.value == "back_to_back"


def test_a_pair_refuses_loads_and_paths_it_does_not_model():
    s = seed004_pair()
    for kw, field in ((dict(M=2.0), "operation.M_Nm"), (dict(Fz=100.0), "operation.Fz_N"),
                      (dict(T_C=50.0), "operation.T_C")):
        with pytest.raises(InputError) as e:
            s.with_(**kw)
        assert e.value.field == field
    ld = tb.load_distribution(s.bearing, Fa=450.0, Fr=325.0)
    with pytest.raises(InputError, match="solved by the coupled steady state and its heat-up") as e:
        tb.transient(s, 10.0, load=ld)     # given loads do not close the pair's preload (a heat-up does:
    assert e.value.field == "bearing.arrangement"     # tests/test_pair_heatup.py)


def test_a_deep_groove_pair_on_the_command_line_is_one_line_exit_2(tmp_path, capsys):
    path = tmp_path / "dg.toml"
    text = Path(tb.example_path("oil_bath_6208.toml")).read_text(encoding="utf-8")
    d = tomllib.loads(text)
    assert "catalog" in d["bearing"]
    path.write_text(text.replace(f'catalog = "{d["bearing"]["catalog"]}"',
                                 f'catalog = "{d["bearing"]["catalog"]}"\narrangement = "back_to_back"\n'
                                 'preload_N = 300.0', 1), encoding="utf-8")
    assert main(["run", str(path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: bearing.arrangement = 'back_to_back'")


# --------------------------------------------------------------------------- (g) the command line
def test_run_prints_the_pair_preload(tmp_path, capsys):
    path = _pair_file(tmp_path, arrangement="back_to_back", preload_N=450.0)
    assert main(["run", str(path), "--set", "Fa_N=0", "--set", "Fr_N=650"]) == 0
    out, err = capsys.readouterr()
    assert "Preload of the pair" in out
    assert "preload (back-to-back pair, position): cold 450 N, warm " in out and "fixed point in " in out
    assert "warning: OutsideValidity: bearing.preload_N: warm / cold preload of a position-preloaded pair" in err
    assert main(["run", str(path), "--set", "Fa_N=0", "--set", "Fr_N=650", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["preload"]["cold_N"] == 450.0 and d["preload"]["warm_N"] > 450.0
    assert d["models_used"]["preload"]["choice"] == "position"
    assert len(d["preload"]["history"]) == d["preload"]["iterations"]


def test_run_names_the_runaway_exit_3(tmp_path, capsys):
    path = _pair_file(tmp_path, arrangement="back_to_back", preload_N=450.0)
    assert main(["run", str(path), "--set", "n_rpm=6500"]) == 3
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: ThermalPreloadRunaway: thermal preload runaway")
    assert main(["run", str(path), "--set", "n_rpm=6500", "--json"]) == 3     # --json: the history as data
    d = json.loads(capsys.readouterr().out)
    assert d["error"] == "ThermalPreloadRunaway" and len(d["preload_history_N"]) == d["iterations"] >= 3
    assert all(b > a for a, b in zip(d["preload_history_N"], d["preload_history_N"][1:]))


def test_init_writes_a_pair_scene_that_run_solves_to_the_examples_answer(tmp_path, capsys):
    """`thermobear init 7014C --lubrication oil-air --speed-rpm 8000 --pair back_to_back --preload-N 300` writes the
    pair's keys and no external axial load (the preload sets the contacts); it is the bundled example scene, and
    `run` solves its thermal preload.  Bad options are refused naming them."""
    out = tmp_path / "pair.toml"
    assert main(["init", "7014C", "--lubrication", "oil-air", "--speed-rpm", "8000", "--pair", "back_to_back",
                 "--preload-N", "300", "--out", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    assert 'arrangement = "back_to_back"' in text and "preload_N = 300.0" in text and "Fa_N = 0.0" in text
    example = tb.example_path("spindle_7014C_pair_oil_air.toml")
    assert text.split("\n", 1)[1] == open(example, encoding="utf-8").read().split("\n", 1)[1]   # (header: command)
    capsys.readouterr()
    for bad, field in ((["6208", "--pair", "back_to_back", "--preload-N", "300"], "--pair"),
                       (["7014C", "--preload-N", "300"], "--preload-N"),
                       (["7014C", "--pair", "back_to_back"], "--preload-N"),
                       (["7014C", "--pair", "back_to_back", "--preload-N", "-5"], "--preload-N")):
        assert main(["init", *bad, "--lubrication", "oil-air"]) == 2
        assert f"error: {field}" in capsys.readouterr().err


def test_sweep_rows_of_a_pair_carry_its_warm_preload():
    s = tb.load_scene(tb.example_path("spindle_7014C_pair_oil_air.toml"))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        st = tb.steady_state(s)
        row = run_sweep(s, {"n_rpm": [s.n_rpm]}, processes=1)[0]
    assert row["preload_cold_N"] == 300.0 and row["preload_warm_N"] == pytest.approx(st.preload["warm_N"], rel=1e-9)
    assert row["preload_warm_N"] > 2 * row["preload_cold_N"] and any("warm / cold preload" in w for w in row["warnings"])
    assert row["k_axial_warm_N_um"] == pytest.approx(st.preload["k_axial_warm_N_um"], rel=1e-6)
    assert row["k_radial_warm_N_um"] == pytest.approx(st.preload["k_radial_warm_N_um"], rel=1e-6)
    assert row["k_tilt_warm_Nm_mrad"] == pytest.approx(st.preload["k_tilt_warm_Nm_mrad"], rel=1e-6)


def test_a_lost_preload_is_named_and_at_20000_rpm_the_speed_keeps_the_pair_preloaded(spindle):
    """A warm preload of 0 N is named (warm / cold below 0.5, 'the pair has play').  With the static form the
    uncut machine's pair lost its preload at 20 000 rpm (its outer ring 23 K above its inner ring); with the pair at
    speed (the balls' centrifugal force, the inner rings' growth on their seats) it carries more than twice its cold
    preload at 20 000 rpm before any heat, and settles warm above that, no play.  No warning says the pair's preload
    is the static form's."""
    s = spindle
    T = {"inner ring": 40.0, "outer ring": 63.0, "balls": 51.5}
    texts = [str(w) for w in thermal_preload_warnings(s, 0.0, T)]
    assert len(texts) == 1 and "the pair has play" in texts[0] and "bearing.preload_N" in texts[0]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fast = tb.steady_state(s.with_(n_rpm=20000.0))
    p = fast.preload
    assert p["at_speed_cold_N"] > 2 * 300.0 and p["warm_N"] > p["at_speed_cold_N"]
    assert not any("no preload left" in str(w) or "static form" in str(w) for w in fast.warnings)


def test_din732_refuses_a_pair_scene_by_name():
    with pytest.raises(InputError, match="bearing.arrangement"):
        din732_safe_speed(tb.load_scene(tb.example_path("spindle_7014C_pair_oil_air.toml")))


@pytest.mark.parametrize("cut, second", [(False, False), (True, None)])
def test_the_fixed_point_is_probed_for_a_second_equilibrium_above_it(spindle, cut, second):
    """With the static pair at 17 000 rpm the uncut machine's loop settled at a light preload (≈ 400 N) below a second,
    unstable one (a reviewer evaluated g(700 N) = 787 N): which one the loop found depended on its first step only.
    The loop starts once more at twice the fixed point's axial load; where g does not fall back there, a named
    warning says the preload has a second, unstable equilibrium above it; where the models cannot evaluate it, that
    the stability is not established.  At 12 000 rpm the uncut machine's probe falls back: no warning; the example
    (cut at the symmetry plane) settles at 12 000 rpm near 3800 N, and at twice that the warm rings close the radial
    play: not established."""
    s = (tb.load_scene(tb.example_path("spindle_7014C_pair_oil_air.toml")) if cut else spindle).with_(n_rpm=12000.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        st = tb.steady_state(s)
    probe = st.preload["probe"]
    assert probe["Fa_N"] == pytest.approx(2.0 * st.preload["Fa_N"]) and probe["rises"] is second
    assert any("second equilibrium above the fixed point" in str(w) for w in st.warnings) is bool(second)
    assert any("stability above the fixed point is not established" in str(w) for w in st.warnings) is (second is None)


def test_a_pair_without_external_radial_load_runs(tmp_path):
    """`init 7014C --pair face_to_face --preload-N 200 --Fa-N 500` writes Fr_N = 0: the pair's loaded bearing took the
    solver's radial residual (≈ 1e-14 N) as its Fr, and `run` refused it as a load below 1e-6 N (a value the user
    never gave).  Its Fr is 0 now, and the scene solves."""
    out = tmp_path / "fa.toml"
    assert main(["init", "7014C", "--lubrication", "oil-air", "--pair", "face_to_face", "--preload-N", "200",
                 "--Fa-N", "500", "--out", str(out)]) == 0
    s = tb.load_scene(out)
    assert s.Fr == 0.0 and pair_loads(s.bearing, "face_to_face", 200.0, "position", 500.0, 0.0).Fr == 0.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        st = tb.steady_state(s)
    assert st.preload["Fr_N"] == 0.0 and st.preload["Fa_N"] > 500.0 and st.preload["warm_N"] > 200.0


def test_the_cut_pair_runs_away_at_14000_rpm():
    """The example is the bearing's share of the pair's machine, cut at the pair's middle (no right shaft end, both
    right ends adiabatic).  With the static pair, cut so, it settled at 12 000 rpm at 4378 N (its probe not evaluated:
    at twice that load the warm rings closed the radial play).  With the pair at speed (on its seat) the
    less-cooled bearing's loop closes the radial play itself at 14 000 rpm (`thermobear speed`: the equilibria end near
    13 760 rpm): a thermal preload runaway naming it."""
    s = tb.load_scene(tb.example_path("spindle_7014C_pair_oil_air.toml")).with_(n_rpm=14000.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(ThermalPreloadRunaway, match="close the bearing's radial play") as e:
            tb.steady_state(s)
    assert e.value.preload_history_N[0] > 2000.0 and e.value.dT_inner_outer_K > 0


def test_init_pair_cuts_the_machine_at_the_symmetry_plane(spindle):
    """`init --pair` builds the bearing's share of the pair's machine: the shaft and housing end at the bearing's face
    toward the other bearing, adiabatic (no heat crosses the symmetry plane).  With half the cooling paths of one
    bearing's machine (a shaft end either side, a housing around it alone: the `spindle` fixture, the same bearing,
    loads, preload and speed), the share runs hotter and its preload higher."""
    ex = tb.load_scene(tb.example_path("spindle_7014C_pair_oil_air.toml"))
    sh, ho = ex.network.shaft, ex.network.housing
    assert sh.length_right == 0.0 and sh.end_right == "adiabatic" and ho.end_right == "adiabatic"
    B = ex.bearing.width
    assert ho.offset + 0.5 * ho.axial_length == pytest.approx(0.5 * B)        # the housing ends at the bearing's face
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        cut, whole = tb.steady_state(ex), tb.steady_state(spindle.with_(n_rpm=ex.n_rpm))
    assert cut.T_C["inner_ring"] > whole.T_C["inner_ring"] + 10.0 and cut.preload["warm_N"] > whole.preload["warm_N"]


@pytest.mark.parametrize("arrangement, sign", [("back_to_back", -1), ("face_to_face", +1)])
def test_a_spacer_lets_the_shaft_and_housing_grow_apart_over_it(arrangement, sign):
    """Equal spacers between the bearings (`[bearing] spacer_mm`): with the inner ring (and shaft) 10 K above the outer
    ring (and housing), the shaft grows axially more than the housing over the spacer — relieving a back-to-back
    pair's preload, adding to a face-to-face one's (Harris & Kotzalas 2007 ch. 8) — more so the longer the spacer; the
    cold preload does not depend on it, and spacer 0 is the adjacent pair."""
    b = tb.bearing("7014C")
    warm = [pair_loads(b, arrangement, 300.0, dT_inner=20.0, dT_outer=10.0, dT_ball=15.0, spacer=L).preload
            for L in (0.0, 0.02, 0.04)]
    assert warm[0] == pytest.approx(pair_loads(b, arrangement, 300.0, dT_inner=20.0, dT_outer=10.0, dT_ball=15.0).preload)
    assert np.all(sign * np.diff(warm) > 0)
    assert pair_loads(b, arrangement, 300.0, spacer=0.04).preload == pytest.approx(300.0, rel=1e-6)


def test_a_spacer_is_read_from_the_scene_and_needs_its_pair(tmp_path):
    s = tb.load_scene(tb.example_path("spindle_7014C_pair_oil_air.toml"))
    assert s.pair_spacer is None and s.with_(spacer_mm=40.0).pair_spacer == pytest.approx(0.04)
    text = open(tb.example_path("spindle_7014C_pair_oil_air.toml"), encoding="utf-8").read()
    path = tmp_path / "lone.toml"
    lines = [ln for ln in text.splitlines() if not ln.startswith(("preload_N", "preload ="))]
    path.write_text("\n".join(lines).replace('arrangement = "back_to_back"', 'spacer_mm = 40.0'), encoding="utf-8")
    with pytest.raises(InputError, match="bearing.spacer_mm"):
        tb.load_scene(path)


def test_the_answer_brackets_the_balls_share_of_the_preload_rise(spindle):
    """The balls run 28 K above the rings' mean in the uncut machine and their growth drives most of the thermal rise;
    their temperature rests on the estimated ball–race conductance.  The answer gives the warm preload at the same
    ring temperatures and speed with the balls at the rings' mean beside its own (1695 N against 2806 N; 1269 N at
    speed cold), and `run` prints it; a spring keeps its force either way."""
    s = spindle
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        st = tb.steady_state(s)
        spring = tb.steady_state(s.with_(preload="spring"))
    p, T = st.preload, st.preload["temperatures_C"]
    lo = pair_loads(s.bearing, "back_to_back", 300.0, dT_inner=T["inner ring"] - T_REF_C,
                    dT_outer=T["outer ring"] - T_REF_C, dT_ball=0.5 * (T["inner ring"] + T["outer ring"]) - T_REF_C,
                    n_rpm=s.n_rpm, u_inner=seated_raceway_growth(s.bearing, s.n_rpm, **inner_seat(s))).preload
    assert p["warm_balls_at_rings_N"] == pytest.approx(lo, rel=1e-9)
    rise = p["warm_N"] - p["at_speed_cold_N"]
    assert p["at_speed_cold_N"] < p["warm_balls_at_rings_N"] < p["warm_N"] - 0.5 * rise
    assert spring.preload["warm_balls_at_rings_N"] == 300.0


def test_a_sweep_over_the_cold_preload_of_a_pair(tmp_path, capsys):
    """`thermobear sweep --preload-N` compares preload classes: seed 004's 7210 as a back-to-back pair at 3200 rpm,
    150 / 450 / 900 N cold — a heavier cold preload gives a heavier warm one and more heat (each row the steady
    answer at that preload); a scene without a pair refuses the axis by the field it needs."""
    text = Path(SEED004).read_text(encoding="utf-8")
    path = tmp_path / "pair.toml"
    path.write_text(text.replace('catalog = "7210"', 'catalog = "7210"\narrangement = "back_to_back"\n'
                                 'preload_N = 450.0\n', 1), encoding="utf-8")
    out = tmp_path / "rows.jsonl"
    assert main(["sweep", str(path), "--set", "Fa_N=0", "--set", "Fr_N=650", "--preload-N", "150,450,900",
                 "--jsonl", str(out), "--quiet"]) == 0
    rows = [json.loads(ln) for ln in out.read_text(encoding="utf-8").splitlines()]
    rows = sorted(rows, key=lambda r: r["preload_N"])
    assert [r["preload_cold_N"] for r in rows] == [150.0, 450.0, 900.0] and all(r["status"] == "ok" for r in rows)
    assert np.all(np.diff([r["preload_warm_N"] for r in rows]) > 0) and np.all(np.diff([r["P_W"] for r in rows]) > 0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        st = tb.steady_state(seed004_pair())
    assert rows[1]["preload_warm_N"] == pytest.approx(st.preload["warm_N"], rel=1e-6)
    capsys.readouterr()
    assert main(["sweep", SEED004, "--preload-N", "300,600", "--quiet"]) == 2
    assert "error: bearing.preload_N" in capsys.readouterr().err


def test_the_loads_verb_gives_a_pairs_cold_loads_and_stiffness(capsys):
    """`thermobear loads` on a pair scene (was refused): the pair at the mounting temperature, at rest (its cold
    preload) and at the scene's speed, with the loaded bearing's loads and the pair's stiffness, and the loaded
    bearing's ball loads at speed (the scene_pair_loads of run's first step)."""
    ex = tb.example_path("spindle_7014C_pair_oil_air.toml")
    assert main(["loads", ex, "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    s = tb.load_scene(ex)
    fast = scene_pair_loads(s, None, with_stiffness=True)
    assert d["pair"]["at_rest"]["preload_N"] == pytest.approx(300.0, rel=1e-9)
    assert d["pair"]["at_speed"]["preload_N"] == pytest.approx(fast.preload, rel=1e-12)
    assert d["pair"]["at_speed"]["k_axial_N_um"] == pytest.approx(fast.stiffness[0] * 1e-6, rel=1e-12)
    assert d["pair"]["at_speed"]["k_tilt_Nm_mrad"] == pytest.approx(fast.stiffness[2] * 1e-3, rel=1e-12)
    assert d["Fa_N"] == pytest.approx(fast.Fa, rel=1e-12) and d["Fr_N"] == pytest.approx(fast.Fr, rel=1e-12)
    assert d["high_speed"] and d["pair"]["at_speed"]["Fa_N"] > d["pair"]["at_rest"]["Fa_N"]
    assert main(["loads", ex]) == 0
    text = capsys.readouterr().out
    assert "back-to-back pair, position preload 300 N cold" in text and "at 8000 rpm: preload 605.9 N" in text


def test_a_pairs_static_safety_is_its_loaded_bearings(capsys):
    """The refused static safety (s0 < 0.5) of one bearing of a pair is checked on the loaded bearing's own loads,
    not on the pair's external ones: a 200 kN preload is refused before any thermal solve (loads, transient), a
    60 kN radial load on the pair — 30 kN on each bearing — is not."""
    ex = tb.example_path("spindle_7014C_pair_oil_air.toml")
    assert main(["loads", ex, "--set", "preload_N=200000"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("error: bearing.preload_N, operation (Fa_N, Fr_N)") and "cold at rest" in err
    assert main(["loads", ex, "--set", "Fr_N=60000", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["pair"]["at_rest"]["Fr_N"] == pytest.approx(30000.0) and d["Fr_N"] == pytest.approx(30000.0)
    with pytest.raises(InputError, match="the pair's loaded bearing cold at speed") as e:
        tb.transient(tb.load_scene(ex).with_(preload_N=200000.0), 10.0)
    assert e.value.field == "bearing.preload_N, operation (Fa_N, Fr_N)"
