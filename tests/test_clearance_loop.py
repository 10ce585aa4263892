"""The temperature → clearance → loads → losses → temperatures loop (thermobear.coupled.clearance)."""
import dataclasses

import numpy as np
import pytest

import thermobear as tb
from thermobear.app.cli import main
from thermobear.contact.fits import clearance_preload
from thermobear.coupled.ratings import scene_clearance


@pytest.fixture(scope="module")
def jet():
    return tb.load_scene(tb.example_path("block_6208_oil_jet.toml"))


def fitted(scene, Pd_um, shaft="k5", housing="H7"):
    """The scene with a 6208 of clearance Pd_um on the given fits, the loop forced on."""
    s = scene.with_(bearing=scene.bearing.with_(Pd=Pd_um * 1e-6), models={"clearance": "operating"})
    return dataclasses.replace(s, shaft_fit=shaft, housing_fit=housing)


def test_fixed_point_satisfies_its_equation(jet):
    sc = fitted(jet, 24.0)                                   # C3 mid value
    st = tb.steady_state(sc)
    c = st.clearance_um
    again = scene_clearance(sc, st.T_C, st.roles)["operating"]
    assert c["iterations"] >= 2 and c["residual_um"] <= 1e-2
    assert abs(c["used"] - again) <= 1e-2                    # Pd used = operating clearance at the answer's T
    assert 0 < c["used"] < c["mounted"] < c["unmounted"]     # the fit and the warm inner ring both take some
    assert st.models_used["clearance"][0] == "operating"
    assert len(c["history"]) == c["iterations"]


def test_tighter_fit_smaller_clearance_more_balls_share_the_load(jet):
    k5, m5 = (tb.steady_state(fitted(jet, 38.0, shaft)) for shaft in ("k5", "m5"))
    assert m5.clearance_um["used"] < k5.clearance_um["used"] - 3.0
    Q = {k: np.asarray(s.losses.contacts["inner"]["Q"], float).ravel() for k, s in (("k5", k5), ("m5", m5))}
    assert Q["m5"].max() < Q["k5"].max()                     # the smaller clearance spreads the radial load
    assert np.count_nonzero(Q["m5"] > 1.0) >= np.count_nonzero(Q["k5"] > 1.0)


def test_hotter_inner_ring_smaller_operating_clearance(jet):
    sc = fitted(jet, 24.0)
    roles = {"inner": "i", "outer": "o", "ball": "b"}
    c = [scene_clearance(sc, {"i": Ti, "o": 30.0, "b": 0.5 * (Ti + 30.0)}, roles)["operating"] for Ti in (30, 40, 50)]
    assert c[0] > c[1] > c[2]


def test_normal_clearance_on_k5_is_solved_preloaded_per_point(jet):
    """CN (13 µm) on k5 / H7: the fits and the warm inner ring consume the clearance; the loop follows it into
    the preload (before: ThermalPreloadRunaway) to its fixed point, with the named warning of the preload."""
    cn, c3 = fitted(jet, 13.0), fitted(jet, 24.0)
    out = tb.steady_states([cn, c3])
    st = out[0]
    assert isinstance(st, tb.SteadyState) and st.clearance_um["used"] < 0 < st.clearance_um["mounted"]
    again = scene_clearance(cn, st.T_C, st.roles)["operating"]
    assert abs(st.clearance_um["used"] - again) <= 1e-2 and st.clearance_um["residual_um"] <= 1e-2
    assert st.clearance_um["history"][0]["operating_um"] < 0 and st.models_used["clearance"][0] == "operating"
    Q0 = float(clearance_preload(cn.bearing, st.clearance_um["used"] * 1e-6))
    w = [w for w in st.warnings if w.quantity == "operating_clearance"]
    assert len(w) == 1 and f"Q0 = {Q0:.3g} N" in str(w[0]) and "compressed by" in str(w[0])
    Q = np.asarray(st.losses.contacts["inner"]["Q"], float).ravel()
    assert np.all(Q > 0)                                       # the preload keeps every ball loaded
    assert isinstance(out[1], tb.SteadyState) and out[1].clearance_um["used"] > 0
    assert st.P_W > out[1].P_W and not any(w.quantity == "operating_clearance" for w in out[1].warnings)


def runaway_scene(shaft="k5", n_rpm=9000.0):
    """The grease 6208 on a tight fit at high speed, its outer ring held at 20 °C (a cooled housing): the inner
    ring's heat consumes more clearance than the preload took."""
    s = tb.load_scene(tb.example_path("block_6208_grease.toml"))
    s = dataclasses.replace(s, shaft_fit=shaft, housing_fit="H7")
    return s.with_(models={"clearance": "operating"}, n_rpm=n_rpm, T_fixed_C={"outer_ring": 20.0})


def test_a_preload_whose_heat_consumes_more_clearance_runs_away():
    """Runaway criterion (thermobear.coupled.clearance): at a negative clearance the loop's step
    |g(P_k) − P_k| stops shrinking — no fixed point ahead; the error carries the history and residual."""
    e = tb.steady_states([runaway_scene()])[0]
    assert isinstance(e, tb.ThermalPreloadRunaway) and "no fixed point" in str(e)
    h = e.history
    r = [x["operating_um"] - x["used_um"] for x in h]
    assert len(h) >= 3 and all(np.diff(e.clearance_history_m) < 0) and r[-1] < 0 and abs(r[-1]) >= abs(r[-2])
    assert e.residual == pytest.approx(abs(r[-1]) * 1e-6, rel=1e-9) and e.dT_inner_outer_K > 100.0
    assert [x["P_W"] for x in h] == sorted(x["P_W"] for x in h)           # more preload, more heat


def test_a_preload_without_a_steady_state_runs_away_with_its_cause():
    e = tb.steady_states([runaway_scene("p6")])[0]
    assert isinstance(e, tb.ThermalPreloadRunaway) and isinstance(e.__cause__, tb.ThermalRunaway)
    assert e.clearance_history_m[-1] < 0 and "no solution" in str(e)


def test_fits_that_consume_the_clearance_at_mounting_are_a_preload(jet):
    """models.clearance = mounted with a p6 shaft: −20.5 µm at 20 °C, solved preloaded with its warning
    (before: InputError)."""
    st = tb.steady_state(fitted(jet, 13.0, shaft="p6").with_(models={"clearance": "mounted"}))
    c = st.clearance_um
    assert c["mounted"] < 0 and c["used"] == pytest.approx(c["mounted"], abs=1e-9)
    assert any(w.quantity == "operating_clearance" and "at mounting" in str(w) for w in st.warnings)


def test_given_clearance_is_the_old_answer(jet):
    st, given = tb.steady_state(jet), tb.steady_state(jet.with_(models={"clearance": "given"}))
    assert st.models_used["clearance"][0] == "given" and st.clearance_um is None
    assert given.P_W == st.P_W and given.T_C == st.T_C
    assert st.P_W == pytest.approx(29.86175401839089, rel=1e-9)      # main's number for this scene (rolling contacts)


def test_mounted_clearance_uses_the_fits_at_20C(jet):
    sc = fitted(jet, 24.0)
    st = tb.steady_state(sc.with_(models={"clearance": "mounted"}))
    assert st.clearance_um["used"] == pytest.approx(st.clearance_um["mounted"], abs=1e-9)
    assert st.models_used["clearance"][0] == "mounted"


def test_seed_scenes_keep_their_clearance():
    for name in ("seed000_grease_thrust_3ball", "seed002_grease_thrust_51107", "seed004_oil_jet_7210"):
        assert tb.choose_models(tb.load_scene(tb.example_path(name + ".toml")))["clearance"][0] == "given"
    s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    with pytest.raises(tb.InputError, match="models.clearance"):
        tb.choose_models(s.with_(models={"clearance": "operating"}))


def test_heat_up_follows_the_clearance_to_the_fixed_point(jet):
    sc = fitted(jet, 24.0)
    tr = tb.transient(sc, 3600.0)
    st = tb.steady_state(sc)
    assert tr.completed and tr.P_W[-1] == pytest.approx(st.P_W, rel=2e-3)


def test_heat_up_follows_the_clearance_into_the_preload(jet):
    sc = fitted(jet, 13.0)
    tr = tb.transient(sc, 3600.0)
    st = tb.steady_state(sc)
    assert st.clearance_um["used"] < 0
    assert tr.completed and tr.P_W[-1] == pytest.approx(st.P_W, rel=2e-3)
    assert any(w.quantity == "operating_clearance" and "heat-up" in str(w) for w in tr.warnings)


def test_cli_preload_one_warning_and_runaway_exit_code_3_one_line(tmp_path, capsys, jet):
    src = open(tb.example_path("block_6208_oil_jet.toml")).read()
    f = tmp_path / "cn.toml"
    f.write_text(src.replace('catalog = "6208"', 'catalog = "6208"\nshaft_fit = "k5"\nhousing_fit = "H7"', 1))
    assert main(["run", str(f)]) == 0
    err = capsys.readouterr().err
    assert len([ln for ln in err.splitlines() if "operating radial clearance" in ln]) == 1
    src = open(tb.example_path("block_6208_grease.toml")).read()
    g = tmp_path / "hot.toml"
    g.write_text(src.replace('catalog = "6208"', 'catalog = "6208"\nshaft_fit = "k5"\nhousing_fit = "H7"', 1))
    assert main(["run", str(g), "--set", "n_rpm=9000", "--set", "fixed_C.outer_ring=20"]) == 3
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "preload runaway" in err and "no fixed point" in err


def test_a_machine_that_states_its_seats_says_how_they_enter_the_loads():
    """`thermobear init` writes the seats' interference into [shaft] / [housing]: the clearance stays as given by
    default (the usual fits' probable interference without surface smoothing errs tight) and the reason says so —
    it said "fits not stated" beside ratings that named those seats; with models.clearance = 'operating' a seat
    changed in the file changes the loads and the answer."""
    import tomllib
    from thermobear.app.scaffold import scaffold
    from thermobear.models import clearance_choice
    from thermobear.scene import scene_from_dict
    d = tomllib.loads(scaffold("6206", "grease", n_rpm=3000.0, Fr_N=1500.0))
    d["models"] = {"clearance": "operating"}
    s = scene_from_dict(d)
    plain = scene_from_dict({k: v for k, v in d.items() if k != "models"})
    choice, why = clearance_choice(plain)
    assert choice == "given" and "[shaft] interference_um 11.5 µm" in why and "not stated" not in why
    d["shaft"]["interference_um"] = 21.0
    tight = scene_from_dict(d)
    r, rt = tb.steady_state(s), tb.steady_state(tight)
    assert "fixed point" in r.models_used["clearance"][1] and rt.P_W > r.P_W


def test_mounted_fits_warn_of_the_warm_preload_they_leave(jet):
    """models.clearance = 'mounted' with k5 / H7: the loads use the 1.69 µm of the fits at 20 °C while the warm rings
    leave −5.5 µm — the ratings name that preload (the loop's own warning covers only the clearance it used)."""
    s = dataclasses.replace(jet, shaft_fit="k5", housing_fit="H7").with_(models={"clearance": "mounted"})
    with pytest.warns(tb.OutsideValidity):
        r = tb.solve(s)
    c = r.ratings.clearance_um
    assert c["used"] == pytest.approx(c["mounted"]) and c["operating"] < 0
    w = [x for x in r.warnings if x.quantity == "operating_clearance"]
    assert len(w) == 1 and f"the loads used {c['used']:.3g} µm" in str(w[0])


def test_a_preload_that_overloads_the_contacts_is_a_preload_runaway():
    """A loop step whose preloaded steady state overloads the contacts (ContactLimit) is the preload's runaway, the
    overload its cause — not an input error blaming the scene's loads."""
    from thermobear.coupled.clearance import _stopped
    from thermobear.errors import ContactLimit, ThermalPreloadRunaway
    s = tb.load_scene(tb.example_path("block_6208_oil_jet.toml"))
    c = scene_clearance(s, {"ir": 60.0, "or": 30.0, "b": 60.0}, {"inner": "ir", "outer": "or", "ball": "b"})
    err = ContactLimit("operation (Fa_N, Fr_N, M_Nm)", "Fa 0 N", "maximum contact pressure 6528 MPa")
    out = _stopped(s, err, -5e-4, [dict(operating_um=-500.0)], c)
    assert isinstance(out, ThermalPreloadRunaway) and out.__cause__ is err
    assert _stopped(s, err, 1e-6, [], c) is err                  # at a clearance: the error as it is


def test_a_heat_up_takes_the_mounted_clearance_and_names_the_warm_preload(jet):
    """models.clearance = 'mounted' on p6 / N7: the heat-up ran at the clearance as given (29.86 W, `run` 66.22 W) and
    said nothing; now its loads use the fits' clearance and it settles on `run`'s answer, naming the preload the warm
    rings leave at its end — as the clearance as given does (it was silent too)."""
    s = dataclasses.replace(jet, shaft_fit="p6", housing_fit="N7")
    with pytest.warns(tb.OutsideValidity):
        steady = tb.solve(s.with_(models={"clearance": "mounted"}))
        tr = tb.transient(s.with_(models={"clearance": "mounted"}), 7200.0)
        given = tb.transient(s.with_(models={"clearance": "given"}), 7200.0)
    assert tr.P_W[-1] == pytest.approx(steady.P_W, rel=1e-3) and given.P_W[-1] < 0.5 * tr.P_W[-1]
    for r in (tr, given):
        w = [x for x in r.warnings if x.quantity == "operating_clearance"]
        assert len(w) == 1 and "at t = 7200 s" in str(w[0]) and w[0].value < 0
