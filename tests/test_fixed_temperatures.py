"""Measured node temperatures imposed on the network (``[thermal] fixed_C``, seed 004 §4.5 "rig mode")."""
from __future__ import annotations

import json
import warnings
from pathlib import Path

import numpy as np
import pytest

import thermobear as tb
from thermobear.app.cli import main
from thermobear.errors import InputError
from thermobear.scene.scene import scene_from_dict
from thermobear.coupled import steady_state
from thermobear.models import choose_models

ROOT = Path(__file__).resolve().parents[1]
SEED004 = ROOT / "examples" / "seed004_oil_jet_7210.toml"


@pytest.fixture(scope="module")
def scene():
    warnings.simplefilter("ignore", tb.ExtrapolationWarning)
    return tb.load_scene(SEED004)


@pytest.fixture(scope="module")
def free(scene):
    return steady_state(scene)


@pytest.mark.parametrize("models", [{"high_speed": True, "load_model": "jones_harris"}, {}])
def test_imposing_the_free_solution_reproduces_it(scene, models):
    """The free steady state is also the solution when its own ring temperatures are imposed:
    same balls, mixture and power (one fixed point, two ways of reaching it).  With one model to the
    solver's tolerance; the shipped scene lies in a switch band (three alternatives blended): the
    blend of solutions is the solution of no single model, to within 1e-3 K here."""
    sc = scene.with_(models=models) if models else scene
    free = steady_state(sc)
    fixed = {"inner_ring": free.T_C["inner_ring"], "outer_ring": free.T_C["outer_ring"]}
    st = steady_state(sc.with_(T_fixed_C=fixed))
    tol = 1e-4 if models else 1e-3
    for node in ("balls", "oil_air", "inner_race", "outer_race"):
        assert st.T_C[node] == pytest.approx(free.T_C[node], abs=tol)
    assert st.P_W == pytest.approx(free.P_W, rel=1e-6 if models else 1e-4)


def test_imposed_nodes_hold_and_energy_closes(scene):
    st = steady_state(scene.with_(n_rpm=6400.0, T_fixed_C={"inner_ring": 50.0, "outer_ring": 50.0}))
    assert st.T_C["inner_ring"] == 50.0 and st.T_C["outer_ring"] == 50.0
    assert abs(st.energy_balance_W) <= 1e-9 * st.P_W
    # heat is generated in the contacts: the balls run above both rings
    assert st.T_C["balls"] > st.T_C["inner_race"] > 50.0 and st.T_C["balls"] > st.T_C["outer_race"] > 50.0


def test_hotter_rings_lower_the_power(scene):
    """Viscosity falls with the imposed ring temperature: power falls (seed 004 Fig. 9b)."""
    P = [steady_state(scene.with_(T_fixed_C={"inner_ring": T, "outer_ring": T})).P_W for T in (30.0, 50.0, 70.0)]
    assert np.all(np.diff(P) < 0)


def test_transient_keeps_imposed_nodes(scene):
    tr = tb.transient(scene.with_(T_fixed_C={"inner_ring": 45.0, "outer_ring": 40.0}), t_end_s=50.0)
    assert np.all(tr.T_C["inner_ring"] == 45.0) and np.all(tr.T_C["outer_ring"] == 40.0)
    assert tr.T_C["balls"][-1] > tr.T_C["balls"][0]


@pytest.mark.parametrize("fixed, field", [
    ({"balls": 50.0}, "thermal.fixed_C.balls"),          # receives the contact heat
    ({"oil_air": 50.0}, "thermal.fixed_C.oil_air"),      # receives the drag heat
    ({"spindle": 50.0}, "thermal.fixed_C.spindle"),      # unknown node
])
def test_bad_nodes_are_named(scene, fixed, field):
    with pytest.raises(InputError) as e:
        steady_state(scene.with_(T_fixed_C=fixed))
    assert e.value.field == field


@pytest.mark.parametrize("value", [300.0, float("nan"), "hot", True])
def test_bad_temperatures_are_refused(scene, value):
    with pytest.raises(InputError) as e:
        scene.with_(T_fixed_C={"inner_ring": value})
    assert "inner_ring" in e.value.field


def test_scene_file_key_is_read_and_checked(scene):
    raw = {k: dict(v) for k, v in scene.raw.items()}
    raw["thermal"]["fixed_C"] = {"inner_ring": 52.0}
    assert scene_from_dict(raw).T_fixed_C == {"inner_ring": 52.0}
    raw["thermal"]["fixed_C"] = 52.0
    with pytest.raises(InputError) as e:
        scene_from_dict(raw)
    assert e.value.field == "thermal.fixed_C"


def test_cli_set_fixed(capsys):
    code = main(["run", str(SEED004), "--json", "--set", "fixed_C.inner_ring=55", "--set", "fixed_C.outer_ring=50"])
    out, _ = capsys.readouterr()
    assert code == 0
    d = json.loads(out)
    assert d["T_C"]["inner_ring"] == 55.0 and d["T_C"]["outer_ring"] == 50.0
    code = main(["run", str(SEED004), "--set", "fixed_C.balls=55"])
    _, err = capsys.readouterr()
    assert code == 2 and err.startswith("error: thermal.fixed_C.balls") and "Traceback" not in err


def test_radial_load_barely_changes_power_at_equal_ring_temperature(scene):
    """Seed 004 §5.3.5, Figs 13a and 18: Fa 450 N, 4800 rpm, block radial load 50 → 1500 N (two
    bearings: 25 → 750 N each) leaves the power almost unchanged (< 10 %) at equal OR–IR mean
    temperature; compared the paper's way, rings imposed and balls from the network, with the models
    the solver chooses: dry Jones–Harris while every contact is loaded, the film load model once the
    dry solution lifts balls off a race (750 N)."""
    scenes = [scene.with_(n_rpm=4800.0, Fr=Fr) for Fr in (25.0, 325.0, 750.0)]
    assert [choose_models(s)["load_model"][0] for s in scenes] == ["jones_harris", "jones_harris", "film"]
    for T in (30.0, 50.0, 70.0):
        P = [steady_state(s.with_(T_fixed_C={"inner_ring": T, "outer_ring": T})).P_W for s in scenes]
        assert np.ptp(P) / P[0] < 0.10, (T, P)


def test_speed_x2_about_x3_at_equal_ring_temperature(scene):
    """Seed 004 §5.3.1, Fig. 9b: at equal OR–IR mean temperature (25–70 °C) power ×3 for speed ×2;
    rings imposed, balls from the network (their temperature rises with speed, as on the rig)."""
    r = []
    for T in (30.0, 50.0, 70.0):
        P = [steady_state(scene.with_(n_rpm=n, T_fixed_C={"inner_ring": T, "outer_ring": T})).P_W
             for n in (3200.0, 6400.0)]
        r.append(P[1] / P[0])
    assert all(2.5 < x < 3.5 for x in r), r


def test_oil_injection_temperature_barely_changes_power_at_equal_ring_temperature(scene):
    """Seed 004 §5.3.2, Fig. 10: oil injected at 25 or 50 °C (6500 rpm), power at equal OR–IR mean
    temperature unchanged; rings imposed at 50 °C, balls and mixture from the network."""
    P = [steady_state(scene.with_(n_rpm=6500.0, T_oil_in_C=Ti, T_fixed_C={"inner_ring": 50.0, "outer_ring": 50.0})).P_W
         for Ti in (25.0, 50.0)]
    assert abs(P[1] / P[0] - 1.0) < 0.05, P


_COOL_3200 = pytest.mark.xfail(strict=True, raises=AssertionError, reason=(
    "known gap (issue 4): at 3200 rpm the rig network runs cool (39 °C against ≈ 55 °C, rise 53 % low in "
    "validation/report/report.md; its steady state is below the rig's 1000 s reading, so the heat balance, not the inertia, is off); the support "
    "blocks as heat sources add 1.2 K (validation/report/seed004_support_heat.md); every estimate at its warm "
    "bound reaches 52 °C (seed004_heatup_sensitivity.md): needs a logged heat-up of the rig"))


_COOL_8070 = pytest.mark.xfail(strict=True, raises=AssertionError, reason=(
    "known gap (issue 4) at 8070 rpm too since issue 17: inlet shear heating (Gupta φ_T) and oil-jet "
    "replenishment (SKF Φ_rs) lower the high-speed losses — which brings seed 004's measured P(6500)/P(3200) "
    "≈ 3 within reach (validation/report/seed002_local_diagnosis.md) — and the same cool network then gives "
    "62 °C against ≈ 90 °C (rise 43 % low; it was 29 % low with the isothermal, flooded films)"))


@pytest.mark.parametrize("n, ref", [pytest.param(3200.0, 55.0, marks=_COOL_3200),
                                    pytest.param(8070.0, 90.0, marks=_COOL_8070)])
def test_inner_ring_heat_up_of_the_right_order(scene, n, ref):
    """Seed 004 §5.3.1, Fig. 8: inner ring ≈ 55 °C at 3200 rpm and ≈ 90 °C at 8070 rpm after 1000 s
    (oil 10 L/h at 30 °C); 'of the right order' read as within 30 % of the rise above ambient."""
    tr = tb.transient(scene.with_(n_rpm=n), 1000.0, t_eval=[1000.0])
    rise, ref_rise = tr.T_C["inner_ring"][-1] - scene.T_ambient_C, ref - scene.T_ambient_C
    assert abs(rise / ref_rise - 1.0) < 0.3, (n, tr.T_C["inner_ring"][-1])


def test_shaft_path_discretisation_is_converged_and_conserves_conductance(scene, tmp_path):
    """The shipped network splits the 150 mm shaft path into 5 segments (Fo = a t / L² ≈ 0.51 over
    the whole path at 1000 s: one lumped node is not valid).  Refining to 12 segments moves the inner
    ring at 1000 s by < 0.2 K; the steady state depends only on the path's total conductance, so it
    moves by < 0.05 K; one lumped node for the whole shaft share heats the inner ring slower."""
    import dataclasses
    import sys

    from thermobear.files import data_dir
    sys.path.insert(0, str(ROOT / "validation"))
    from seed004_trends import shaft_variant              # the report's own variants (validation/)
    text = (data_dir("networks") / "oil_jet_ball_bearing.toml").read_text(encoding="utf-8")
    s = scene.with_(n_rpm=8070.0)
    fine, coarse = tmp_path / "fine.toml", tmp_path / "coarse.toml"
    fine.write_text(shaft_variant(text, 12), encoding="utf-8")
    coarse.write_text(shaft_variant(text, 0), encoding="utf-8")
    T = {}
    for key, sc in (("shipped", s), ("fine", dataclasses.replace(s, network=str(fine))),
                    ("coarse", dataclasses.replace(s, network=str(coarse)))):
        T[key] = (float(tb.transient(sc, 1000.0, t_eval=[1000.0]).T_C["inner_ring"][-1]),
                  tb.steady_state(sc).T_C["inner_ring"])
    assert abs(T["fine"][0] - T["shipped"][0]) < 0.2, T
    assert abs(T["fine"][1] - T["shipped"][1]) < 0.05, T
    assert T["shipped"][0] > T["coarse"][0] + 5.0, T     # lumped: the whole share heats at once (10 K here)


def test_radial_load_effect_of_the_dry_load_model_is_moderate_and_falls(scene):
    """The dry contact law forced (rings imposed at 50 °C): more radial load concentrates the load on
    fewer balls; the inner contacts it opens lose nothing, so the power falls, by less than 15 %."""
    P = [steady_state(scene.with_(n_rpm=4800.0, Fr=Fr, T_fixed_C={"inner_ring": 50.0, "outer_ring": 50.0},
                                  models={"load_model": "jones_harris", "high_speed": True})).P_W
         for Fr in (25.0, 325.0, 750.0)]
    assert np.all(np.diff(P) < 0) and (P[0] - P[-1]) / P[0] < 0.15, P


def test_radial_load_barely_changes_power_with_the_film_load_model(scene):
    """The same comparison with the films in the contact law (models.load_model = "film"): balls outside
    the load zone carry the hydrodynamic load of their gap's film and keep a rolling force (seed 004
    Fig. 19's IVR balls), and the power stays within the paper's 10 %."""
    for T in (30.0, 50.0, 70.0):
        P = [steady_state(scene.with_(n_rpm=4800.0, Fr=Fr, T_fixed_C={"inner_ring": T, "outer_ring": T},
                                      models={"load_model": "film"})).P_W for Fr in (25.0, 325.0, 750.0)]
        assert np.ptp(P) / P[0] < 0.10, (T, P)
