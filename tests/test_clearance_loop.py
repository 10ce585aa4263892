"""The temperature → clearance → loads → losses → temperatures loop (thermobear.coupled.clearance)."""
import dataclasses

import numpy as np
import pytest

import thermobear as tb
from thermobear.app.cli import main
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


def test_normal_clearance_on_k5_runs_into_preload_per_point(jet):
    cn, c3 = fitted(jet, 13.0), fitted(jet, 24.0)
    out = tb.steady_states([cn, c3])
    assert isinstance(out[0], tb.ThermalPreloadRunaway) and isinstance(out[0], tb.SolverError)
    e = out[0]
    assert e.clearance_history_m[-1] <= 0 and len(e.history) >= 2
    assert e.dT_inner_outer_K > 0 and e.mounted_m == pytest.approx(1.694e-6, abs=1e-8)
    assert isinstance(out[1], tb.SteadyState) and out[1].clearance_um["used"] > 0


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


def test_heat_up_stops_when_the_clearance_is_consumed(jet):
    with pytest.raises(tb.ThermalPreloadRunaway) as got:
        tb.transient(fitted(jet, 13.0), 3600.0)
    run = got.value.last
    assert run is not None and not run.completed and run.t_s[-1] < 3600.0
    assert got.value.clearance_history_m[-1] <= 0 < got.value.clearance_history_m[0]


def test_cli_exit_code_3_one_line(tmp_path, jet):
    src = open(tb.example_path("block_6208_oil_jet.toml")).read()
    f = tmp_path / "cn.toml"
    f.write_text(src.replace('catalog = "6208"', 'catalog = "6208"\nshaft_fit = "k5"\nhousing_fit = "H7"', 1))
    assert main(["run", str(f)]) == 3
