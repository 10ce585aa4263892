"""Scene solver: least model per scene, same numbers on every path, steady energy balance,
transient → steady, runaway and convergence behaviour (issues 4 and 5)."""
import dataclasses

import numpy as np
import pytest

import thermobear as tb
from thermobear.errors import InputError, ThermalRunaway
from thermobear.coupled import scene_load, scene_losses, solve, steady_state, steady_states, transient
from thermobear.coupled.transient import _film_of, point_model
from thermobear.models import choose_models, film_options, open_contacts
from thermobear.scene.network import network_spec
from thermobear.scene.scene import scene_from_dict

S004 = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
S001 = tb.load_scene(tb.example_path("seed001_spin_down_3ball.toml"))
S002 = tb.load_scene(tb.example_path("seed002_grease_thrust_51107.toml"))


def test_seed001_rig_gets_a_smaller_model_than_seed004():
    m1, m4 = choose_models(S001), choose_models(S004)
    assert m1["thermal"][0] == "none" and "prescribed" in m1["thermal"][1]
    assert m1["load_model"][0] == "closed_form" and m1["drag"][0] is False
    assert m4["thermal"][0].startswith("network") and m4["load_model"][0] == "jones_harris"
    assert m4["drag"][0] is True
    for k, (choice, reason) in m1.items():
        assert reason, k


def test_film_load_model_where_the_dry_solution_opens_contacts_in_a_flooded_bearing():
    loaded, lifted = S004.with_(Fr=150.0, n_rpm=4800.0), S004.with_(Fr=750.0, n_rpm=4800.0)
    assert open_contacts(loaded, True) == 0 and open_contacts(lifted, True) > 0
    assert choose_models(loaded)["load_model"][0] == "jones_harris"
    m = choose_models(lifted)
    assert m["load_model"][0] == "film" and "off a race" in m["load_model"][1]
    # a greased bearing's unloaded contacts are starved: the dry law stays
    d = _scene_dict()
    d["lubricant"] = {k: v for k, v in d["lubricant"].items() if k not in ("flow_L_h", "T_in_C")} | {"supply": "grease"}
    from thermobear.scene.scene import scene_from_dict
    greased = scene_from_dict(d)
    g = choose_models(greased.with_(Fr=750.0, n_rpm=4800.0))
    assert g["load_model"][0] == "jones_harris" and "starved" in g["load_model"][1]
    # the scene's own choice wins
    forced = lifted.with_(models={"load_model": "jones_harris"})
    assert choose_models(forced)["load_model"] == ("jones_harris", "chosen in the scene")
    # and the film changes the power where contacts open, barely where they do not
    for sc, lo, hi in ((loaded, 0.0, 0.03), (lifted, 0.05, 0.5)):
        Pd = solve(sc.with_(T_C=50.0, models={"load_model": "jones_harris"})).P_W
        Pf = solve(sc.with_(T_C=50.0)).P_W
        assert lo <= abs(Pf / Pd - 1.0) < hi, (Pd, Pf)


def _scene_dict():
    import tomllib
    with open(tb.example_path("seed004_oil_jet_7210.toml"), "rb") as fh:
        return tomllib.load(fh)


@pytest.mark.parametrize("scene", [S001, S004.with_(Fr=0.0, T_C=50.0, n_rpm=1000.0), S002.with_(T_C=50.0),
                                   S004.with_(bearing="6210", Fa=0.0, Fr=0.0, T_C=50.0, models={"high_speed": False})],
                         ids=["seed001", "seed004-axial", "seed002", "unloaded-deep-groove"])
def test_closed_form_and_jones_harris_paths_agree(scene):
    a = scene_losses(scene)
    assert choose_models(scene)["load_model"][0] == "closed_form"
    b = scene_losses(scene.with_(models={"load_model": "jones_harris"}))
    assert b.P_W == pytest.approx(a.P_W, rel=1e-9)
    np.testing.assert_allclose(b.contacts["inner"]["Q"], a.contacts["inner"]["Q"], rtol=1e-9)


def test_prescribed_temperature_equals_bearing_losses():
    # low-speed path: bearing_losses adds F_c to the outer contacts itself
    sc = S004.with_(T_C=50.0, models={"high_speed": False, "load_model": "jones_harris"})
    r = solve(sc)
    ref = tb.bearing_losses(S004.bearing, S004.lubricant, Fa=450.0, Fr=325.0, n_rpm=3200.0, T_C=50.0,
                            oil_flow_m3_s=S004.oil_flow * S004.jet_penetration, Rq_ball=S004.Rq_ball,
                            Rq_ring=S004.Rq_ring, **film_options(choose_models(sc)))
    assert r.P_W == pytest.approx(ref.P_W, rel=1e-12)


def test_high_speed_path_when_centrifugal_force_matters():
    from thermobear.loads.highspeed import load_distribution_high_speed
    sc = S004.with_(T_C=50.0, n_rpm=6500.0)
    m = choose_models(sc)
    assert m["high_speed"][0] == "yes" and "F_c/Q" in m["high_speed"][1]
    assert choose_models(S004.with_(n_rpm=500.0))["high_speed"][0] == "no"
    r = solve(sc.with_(models={"load_model": "jones_harris"}))        # the dry law alone (no film blend)
    ld = load_distribution_high_speed(S004.bearing, Fa=450.0, Fr=325.0, n_rpm=6500.0)
    ref = tb.bearing_losses(S004.bearing, S004.lubricant, Fa=450.0, Fr=325.0, n_rpm=6500.0, T_C=50.0,
                            oil_flow_m3_s=S004.oil_flow * S004.jet_penetration, Rq_ball=S004.Rq_ball,
                            Rq_ring=S004.Rq_ring, load=ld, centrifugal=False, **film_options(m))
    assert r.P_W == pytest.approx(ref.P_W, rel=1e-12)
    assert np.all(r.losses.contacts["outer"]["alpha"] < r.losses.contacts["inner"]["alpha"])


def test_steady_energy_balance_and_few_iterations():
    st = steady_state(S004.with_(models={"high_speed": True, "load_model": "jones_harris"}))    # one model
    assert abs(st.energy_balance_W) <= 1e-9 * st.P_W
    assert st.iterations <= 30 and st.residual_K < 1e-5
    assert st.T_C["balls"] > st.T_C["oil_inlet"] and st.T_C["inner_ring"] > st.T_C["ambient"]
    # losses at equilibrium are those at the equilibrium temperatures
    assert st.P_W == pytest.approx(st.losses.P_W)


def test_long_transient_ends_at_the_steady_state():
    st = steady_state(S002)
    tr = transient(S002, 4.0e5, t_eval=[0.0, 4.0e5])
    for node in ("balls", "housing", "shaft_washer"):
        assert tr.T_C[node][-1] == pytest.approx(st.T_C[node], abs=0.1)
    assert tr.P_W[-1] == pytest.approx(st.P_W, rel=1e-3)


def test_power_falls_as_the_bearing_heats_up():
    tr = transient(S004, 600.0, t_eval=np.linspace(0, 600.0, 7))
    assert np.all(np.diff(tr.P_W) < 0)
    assert np.all(np.diff(tr.T_C["inner_ring"]) > 0)


def test_schedule_step_raises_power():
    tr = transient(S004.with_(T_oil_in_C=30.0), 400.0, schedule=[(200.0, {"n_rpm": 6500.0})],
                   t_eval=[199.0, 201.0])
    assert tr.P_W[1] > 1.5 * tr.P_W[0]


def test_runaway_case_is_named():
    # very high speed, very viscous oil, poor cooling: no equilibrium below the lubricant's limit
    one = tb.scene.scene_from_dict({**{k: v for k, v in S004.raw.items() if k != "rig"}, "thermal": {"network": "one_node", "T_ambient_C": 25.0,
                                    "parameters": {"bearing_to_ambient.G_W_K": 0.05}},
                                    "lubricant": {"name": "iso-vg-220-mineral", "supply": "oil_jet", "flow_L_h": 10.0,
                                                  "T_in_C": 30.0},
                                    "operation": {"n_rpm": 20000.0, "Fa_N": 2000.0}})
    with pytest.raises(ThermalRunaway) as e:          # iterates beyond the oil's data warn nothing: no answer
        steady_state(one)
    assert "no equilibrium below 250" in e.value.reason and e.value.history


def test_network_parameter_override_and_bad_name():
    a = steady_state(S002)
    b = steady_state(S002.with_(network_parameters={"housing_forced_convection.u_air_m_s": 6.0}))
    assert b.T_C["housing"] < a.T_C["housing"]
    with pytest.raises(InputError, match="no element or node"):
        steady_state(S002.with_(network_parameters={"nonexistent.h_W_m2K": 1.0}))


def test_skf_loss_path():
    r = solve(S002.with_(T_C=49.8, models={"losses": "skf", "skf_R1": 8.117e-7, "skf_S1": 1.246e-2}))
    skf = tb.skf_friction(S002.bearing, S002.lubricant.nu(49.8), 1000.0, 7000.0, 0.0, lubrication="grease",
                          R1=8.117e-7, S1=1.246e-2)
    assert r.P_W == pytest.approx(skf.P_W, rel=1e-12)
    st = steady_state(S002.with_(models={"losses": "skf"}))
    assert abs(st.energy_balance_W) <= 1e-9 * st.P_W


def test_schedule_steps_reach_the_network():
    # a step of the oil inlet temperature changes the fixed node and the end state equals the steady state
    # (models pinned: inside a switch band the steady state blends alternatives, the transient runs the
    # dominant one)
    s = S004.with_(models={"high_speed": True, "load_model": "jones_harris"})
    tr = transient(s, 1.0e6, schedule=[(1000.0, {"T_oil_in_C": 70.0})], t_eval=[999.0, 1000.0, 1.0e6])
    assert tr.t_s.tolist() == [999.0, 1000.0, 1.0e6]
    assert tr.T_C["oil_inlet"].tolist() == [30.0, 70.0, 70.0]
    st = steady_state(s.with_(T_oil_in_C=70.0))
    assert tr.T_C["balls"][-1] == pytest.approx(st.T_C["balls"], abs=0.05)


def test_steady_state_above_the_first_iterates_limit():
    # the first update puts the oil–air node far above 250 °C; the equilibrium is at ~110 °C
    st = steady_state(S004.with_(n_rpm=11000.0))
    assert st.T_C["oil_air"] < 150.0 and abs(st.energy_balance_W) < 1e-9 * st.P_W


@pytest.mark.parametrize("scene", [S004, S004.with_(n_rpm=8070.0), S002])
def test_many_points_solved_together_equal_each_solved_alone(scene):
    scenes = [scene.with_(n_rpm=scene.n_rpm * f) for f in (0.5, 1.0, 1.5)]
    together = steady_states(scenes)
    for sc, st in zip(scenes, together):
        alone = steady_state(sc)
        # 7210 at 12 105 rpm with inlet heating and replenishment (issue 17): the cold start's loop gain is 1.47,
        # the batched Newton hands the point to the fallback path, alone and together alike
        assert st.models_used["thermal"][1].startswith("fixed point on 3 coupled temperatures: ")
        for node, T in alone.T_C.items():
            assert st.T_C[node] == pytest.approx(T, abs=1e-6)
        assert st.P_W == pytest.approx(alone.P_W, rel=1e-9)


def test_transient_default_tolerances_are_accurate():
    t = np.linspace(0.0, 3600.0, 13)
    ref = transient(S004, 3600.0, t_eval=t, rtol=1e-8, atol=1e-6)
    run = transient(S004, 3600.0, t_eval=t)
    for node in ref.T_C:
        np.testing.assert_allclose(run.T_C[node], ref.T_C[node], atol=0.01)
    np.testing.assert_allclose(run.P_W, ref.P_W, rtol=5e-4)


def test_transient_reports_model_changes_along_the_schedule():
    # a radial step that lifts balls off the races switches the load model mid-run
    s = S004.with_(n_rpm=4800.0)
    tr = transient(s, 400.0, schedule=[(200.0, {"Fr": 750.0})], t_eval=[0.0, 199.0, 400.0])
    assert tr.models_used["load_model"][0] == "jones_harris"
    assert tr.models_used["schedule"][1].startswith("from t = 200 s: load_model film")
    assert np.all(np.isfinite(tr.P_W)) and tr.t_s[-1] == 400.0


def test_film_steady_state_is_the_fixed_point_of_its_film_temperature():
    import re
    assert choose_models(S004.with_(n_rpm=4800.0, Fr=750.0))["load_model"][0] == "film"
    s = S004.with_(n_rpm=4800.0, Fr=750.0, models={"load_model": "film", "high_speed": True})    # one model
    st = steady_state(s)
    T_film = float(re.search(r"temperature ([\d.]+) °C", st.models_used["load_distribution"][1]).group(1))
    c = st.losses.contacts
    T_contacts = float(np.mean(np.concatenate([np.ravel(c["inner"]["T_C"]), np.ravel(c["outer"]["T_C"])])))
    assert abs(T_contacts - T_film) <= 0.1 + 0.005          # tolerance of the film update, print rounding
    # the same loads solved from scratch (ambient start) give the same state
    ref = steady_state(s, load=scene_load(s, choose_models(s), T_film_C=T_film))
    assert ref.P_W == pytest.approx(st.P_W, rel=1e-4)
    assert abs(ref.T_C["inner_ring"] - st.T_C["inner_ring"]) < 0.01
    assert abs(st.energy_balance_W) <= 1e-9 * st.P_W


def test_a_load_the_bearing_cannot_carry_is_reported_per_point_not_by_the_model_choice():
    from thermobear.errors import NoEquilibrium
    from thermobear.app.sweep import run_sweep
    bad = S004.with_(Fa=0.0, Fr=300.0)              # an angular contact bearing with no axial load
    m = choose_models(bad)                           # choosing models does not solve the loads' failure
    assert m["load_model"][0] == "jones_harris" and "failed" in m["load_model"][1]
    with pytest.raises(NoEquilibrium):
        steady_state(bad)
    rows = run_sweep(S004, {"Fa": [0.0, 500.0], "Fr": [300.0]}, processes=1)
    assert [r["status"] for r in rows] == ["NoEquilibrium", "ok"]


def test_thrust_bearing_without_axial_load_is_refused_not_a_singular_network():
    """A thrust bearing at Fa = 0 has no contact: NoEquilibrium naming the field (CLI exit 2), in solve,
    steady state and per sweep point — not P = 0 W, nor a 'singular conductance matrix'."""
    from thermobear.errors import NoEquilibrium
    from thermobear.app.sweep import run_sweep
    for f in (lambda: solve(S002.with_(Fa=0.0, T_C=50.0)), lambda: steady_state(S002.with_(Fa=0.0))):
        with pytest.raises(NoEquilibrium, match="Fa_N"):
            f()
    rows = run_sweep(S002, {"Fa": [0.0, 100.0]}, processes=1)
    assert [r["status"] for r in rows] == ["NoEquilibrium", "ok"]


def test_network_reading_a_dimension_the_bearing_lacks_names_network_field_and_fix():
    """The ISO/TS 16281 reference bearing has no envelope dimensions; the rig network reads its bore."""
    from thermobear.errors import InputError
    with pytest.raises(InputError) as e:
        steady_state(S004.with_(bearing="iso-dgbb"))
    msg = str(e.value)
    assert "network oil_jet_ball_bearing" in msg and "bearing.bore" in msg and "bore_mm" in msg


def test_schedule_change_reported_once_per_segment_with_film_pieces():
    tr = transient(S004.with_(n_rpm=4800.0, Fr=150.0), 3000.0, schedule=[(200.0, {"Fr": 750.0})], t_eval=[3000.0])
    assert tr.models_used["schedule"][1].count("from t =") == 1


def test_relative_network_path_follows_the_working_directory(tmp_path, monkeypatch):
    import dataclasses
    from thermobear.files import data_dir
    text = (data_dir("networks") / "one_node.toml").read_text(encoding="utf-8")
    for sub, tag in (("a", "variant-a"), ("b", "variant-b")):
        (tmp_path / sub).mkdir()
        (tmp_path / sub / "net.toml").write_text(text.replace('name = "one_node"', f'name = "{tag}"'),
                                                  encoding="utf-8")
    sc = dataclasses.replace(S002, network="net.toml", path=None)
    monkeypatch.chdir(tmp_path / "a")
    assert network_spec(sc.network, sc.path)["name"] == "variant-a"
    monkeypatch.chdir(tmp_path / "b")
    assert network_spec(sc.network, sc.path)["name"] == "variant-b"
    # an edited file is read again (the file catalogue is keyed on the content)
    p = tmp_path / "b" / "net.toml"
    p.write_text(text.replace('name = "one_node"', 'name = "variant-b2"'), encoding="utf-8")
    assert network_spec(sc.network, sc.path)["name"] == "variant-b2"


def test_two_schedule_steps_at_one_time_are_refused_not_merged():
    with pytest.raises(InputError, match=r"schedule\[1\]\.t_s = 100.0 — step times must increase"):
        transient(S004, 300.0, schedule=[(100.0, {"n_rpm": 4000.0}), (100.0, {"n_rpm": 5000.0})])
    with pytest.raises(InputError, match="step times must increase"):
        transient(S004, 300.0, schedule=[(200.0, {"n_rpm": 4000.0}), (100.0, {"n_rpm": 5000.0})])


def test_the_kinematics_model_of_the_scene_is_the_one_used():
    a = scene_losses(S004.with_(T_C=50.0, models={"high_speed": False}))
    b = scene_losses(S004.with_(T_C=50.0, models={"high_speed": False, "kinematics": "inner"}))
    assert a.P_W != b.P_W and b.models_used["kinematics"][0] == "inner"


def test_outer_ring_rotation_does_not_take_the_inner_ring_high_speed_path():
    sc = dataclasses.replace(S004, rotating="outer").with_(n_rpm=6500.0)
    assert choose_models(sc)["high_speed"][0] == "no"
    with pytest.raises(InputError, match="inner"):
        choose_models(sc.with_(models={"high_speed": True}))


@pytest.mark.parametrize("supply, name", [("oil_bath", "iso-vg-68-mineral"), ("oil_jet", "iso-vg-68-mineral"),
                                          ("grease", "grease-lithium-mineral-vg100-nlgi2")])
def test_a_scene_without_network_or_temperature_is_refused_by_name_whatever_its_supply(supply, name):
    """A flooded supply has a film test in its model choice; without a dry solution (no network, no T_C) that
    test must not run: the scene is refused as a grease scene is (thermal.network, exit 2), not an internal error."""
    lub = {"name": name, "supply": supply, **({"oil_level_mm": 6.0} if supply == "oil_bath" else {}),
           **({"flow_L_h": 10.0} if supply == "oil_jet" else {})}
    s = scene_from_dict({"bearing": {"catalog": "6208"}, "lubricant": lub,
                         "operation": {"n_rpm": 3000.0, "Fr_N": 2000.0}})
    with pytest.raises(InputError, match="^thermal.network"):
        tb.choose_models(s)


@pytest.mark.parametrize("name", ["seed004_oil_jet_7210.toml", "oil_bath_6208.toml"])
def test_transient_starts_from_a_dict_of_node_temperatures(name):
    """A dict start (node → °C) runs where the film loads need its film temperature: every free node at
    40 °C is the uniform start at 40 °C; a start giving one node starts that node there."""
    s = tb.load_scene(tb.example_path(name))
    free = point_model(s).network.free_nodes
    uniform, given = transient(s, 100.0, T0_C=40.0), transient(s, 100.0, T0_C={n: 40.0 for n in free})
    assert np.array_equal(uniform.P_W, given.P_W)
    one = transient(s, 100.0, T0_C={"inner_ring": 40.0})
    assert one.T_C["inner_ring"][0] == 40.0 and one.completed and np.all(np.isfinite(one.P_W))


def test_film_temperature_of_a_dict_start_is_the_mean_of_the_contact_nodes_where_the_integrator_starts_them():
    """The nodes a dict start leaves out start at the ambient (as solve_transient starts them): the film
    temperature, the first cell and the first operating clearance are those of the state integrated."""
    roles = {"ball": "balls", "inner": "inner_race", "outer": "outer_race", "oil": "oil_air"}
    assert _film_of({"balls": 30.0, "inner_race": 36.0, "outer_race": 26.0}, roles, S004) == 30.5
    assert _film_of({"balls": 30.0, "inner_race": 36.0}, roles, S004) == (60.0 + 36.0 + S004.T_ambient_C) / 4
    assert _film_of({"inner_ring": 40.0}, roles, S004) == S004.T_ambient_C
    tr = transient(S004, 1.0, T0_C={"balls": 60.0}, t_eval=[0.0, 1.0])
    assert [tr.T_C[n][0] for n in ("balls", "inner_race", "outer_race")] == [60.0, S004.T_ambient_C, S004.T_ambient_C]


def test_dict_start_at_the_operating_clearance_is_the_uniform_start():
    """The clearance of a dict start's first piece: the nodes it leaves out at the scene's temperature."""
    s = tb.load_scene(tb.example_path("oil_bath_6208.toml")).with_(models={"clearance": "operating"})
    runs = [transient(s, 100.0, T0_C=T0) for T0 in (s.T_ambient_C, {"inner_ring": s.T_ambient_C})]
    assert runs[0].completed and np.array_equal(runs[0].P_W, runs[1].P_W)


@pytest.mark.parametrize("call", [choose_models, tb.prepare, solve, lambda s: transient(s, 100.0)],
                         ids=["choose_models", "prepare", "solve", "transient"])
def test_scene_functions_refuse_what_is_not_a_scene_by_name(call):
    with pytest.raises(InputError, match="^scene = 'x' — must be a Scene"):
        call("x")


def test_scene_losses_takes_the_scenes_model_keys_checked_as_scene_with():
    assert scene_losses(S004, T_C=50.0, models={}).P_W == scene_losses(S004, T_C=50.0).P_W
    film = scene_losses(S004, T_C=50.0, models={"load_model": "film"})
    assert film.P_W == scene_losses(S004.with_(models={"load_model": "film"}), T_C=50.0).P_W
    with pytest.raises(InputError, match=r"^models.load_model = 'x' — must be one of"):
        scene_losses(S004, T_C=50.0, models={"load_model": "x"})
    with pytest.raises(InputError, match=r"^models = 'x' — must be a table"):
        scene_losses(S004, T_C=50.0, models="x")


@pytest.mark.parametrize("kw, message", [
    (dict(rtol=-1.0), r"^rtol = -1.0 — must be > 0"),
    (dict(rtol=np.nan), r"^rtol = nan — must be finite"),
    (dict(atol=0.0), r"^atol = 0.0 — must be > 0 \[K\]"),
    (dict(schedule="x"), r"^schedule = 'str' — a list of steps"),
    (dict(schedule=[(10.0,)]), r"^schedule\[0\] = \(10.0,\) — a step \(t_s, \{override"),
    (dict(schedule=[("x", {"n_rpm": 100.0})]), r"^schedule\[0\]\.t_s = 'x' — step times must lie in \[0, 100\)"),
    (dict(stop="x"), r"^stop = 'str' — a callable"),
    (dict(T0_C=300.0), r"^T0_C = 300.0 — must be in \[-40, 250\] \[°C\]"),
    (dict(T0_C={"inner_ring": np.nan}), r"^T0_C\['inner_ring'\] = nan — must be finite"),
    (dict(t_end_s="x"), r"^t_end_s = 'x' — must be a number > 0 \[s\]"),
    (dict(t_end_s=-1.0), r"^t_end_s = -1.0 — must be > 0 \[s\]"),
])
def test_transient_refuses_bad_arguments_at_its_entry_by_the_name_given(kw, message):
    kw = {"t_end_s": 100.0, **kw}
    with pytest.raises(InputError, match=message):
        transient(S004, kw.pop("t_end_s"), **kw)
