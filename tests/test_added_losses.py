"""Churning, seals and cage in a scene: keys, the model choice and why, the coupling parts, the solvers, the CLI."""
import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest

import thermobear as tb
from thermobear.app.cli import main
from thermobear.coupled import scene_losses, steady_state, transient
from thermobear.coupled.sources import loss_parts, prepare
from thermobear.models import choose_models

EX = Path(__file__).resolve().parents[1] / "examples"
BATH = tb.load_scene(EX / "oil_bath_6208.toml")
JET = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))


def test_the_oil_bath_example_reads_its_keys():
    assert BATH.oil_level == pytest.approx(8e-3) and BATH.seals == "RS1" and BATH.seal_sides == 1
    assert BATH.seal_diameter == pytest.approx(52.6e-3) and BATH.cage == "balls"
    assert JET.seals == "none" and JET.seal_sides == 0 and JET.oil_level is None


def test_model_choice_says_why():
    m = choose_models(BATH)
    assert m["churning"][0] == "pouly_immersed" and "H = 8 mm" in m["churning"][1]
    assert m["seals"][0] == "SKF 2004 RS1 ×1" and m["cage"][0] is False and "ball-centred" in m["cage"][1]
    assert m["drag"][0] is False
    assert choose_models(BATH.with_(models={"losses": "skf"}))["churning"][0] == "skf_2018"
    bare = dataclasses.replace(BATH, network=None).with_(T_C=50.0)   # no network: the level alone decides
    assert choose_models(bare.with_(oil_level_mm=0.0))["churning"] == (False, "oil level 0: no ball reaches the bath")
    missing = choose_models(bare.with_(oil_level_mm=None))["churning"]
    assert missing[0] is False and "oil_level_mm" in missing[1]
    for level in (0.0, None):           # the bath of a parametric housing needs its level, as in the file
        with pytest.raises(tb.InputError, match=r"lubricant\.oil_level_mm"):
            BATH.with_(oil_level_mm=level)
    no_level = scene_losses(bare.with_(oil_level_mm=None, models={"losses": "skf"}))
    assert no_level.breakdown_W["churning"] == 0.0 and no_level.P_W > 0      # the SKF model runs, without drag
    jet = choose_models(JET)
    assert not jet["churning"][0] and not jet["seals"][0] and not jet["cage"][0]
    assert choose_models(BATH.with_(seals="shield"))["seals"][0] is False
    assert choose_models(BATH.with_(cage="outer_ring"))["cage"][0] == "petroff_land+pocket"


def test_every_added_model_can_be_forced_off_and_refuses_to_be_forced_on_without_its_source():
    m = choose_models(BATH.with_(models={"churning": False, "seals": False}))
    assert m["churning"] == (False, "chosen in the scene") and m["seals"] == (False, "chosen in the scene")
    for key, scene in (("churning", JET), ("seals", JET), ("cage", BATH)):
        with pytest.raises(tb.InputError) as e:
            choose_models(scene.with_(models={key: True}))
        assert e.value.field == f"models.{key}"


@pytest.mark.parametrize("section, key, value, field", [
    ("bearing", "seals", "felt", "bearing.seals"),
    ("bearing", "seals", "LS", "bearing.seals"),              # a roller-bearing seal on a ball bearing
    ("bearing", "seal_sides", 3, "bearing.seal_sides"),
    ("bearing", "cage", "rollers", "bearing.cage"),
    ("lubricant", "oil_level_mm", -1.0, "lubricant.oil_level_mm"),
])
def test_bad_keys_name_the_field(tmp_path, section, key, value, field):
    d = tb.files.read_toml(str(EX / "oil_bath_6208.toml"))
    d = {k: dict(v) if isinstance(v, dict) else v for k, v in d.items()}
    d[section][key] = value
    with pytest.raises(tb.InputError) as e:
        tb.scene.scene_from_dict(d)
    assert e.value.field.startswith(field)


def test_inconsistent_keys_are_refused():
    with pytest.raises(tb.InputError) as e:
        JET.with_(seals="none", seal_sides=2)
    assert e.value.field == "bearing.seal_sides"
    with pytest.raises(tb.InputError) as e:
        BATH.with_(supply="grease")
    assert e.value.field == "lubricant.oil_level_mm"


def test_losses_of_the_oil_bath_limits_and_level_trend():
    """Prescribed temperature: churning 0 at level 0, rising with the level; the seal loss is SKF's moment × ω;
    no seal → none; every loss family sums to the total and the heat sources conserve it."""
    base = dataclasses.replace(BATH, network=None).with_(T_C=50.0)   # a parametric bath refuses level 0, as its file
    P = [scene_losses(base.with_(oil_level_mm=h)).breakdown_W["churning"] for h in (0.0, 4.0, 8.0, 20.0, 40.0)]
    assert P[0] == 0.0 and np.all(np.diff(P) > 0)
    r = scene_losses(base)
    # one RS1 seal, D 80 mm (SKF row 62 < D <= 80: K_S1 0.018, K_S2 20, β 2.25): half the two-seal moment
    assert r.breakdown_W["seal"] == pytest.approx(0.5 * (0.018 * 52.6 ** 2.25 + 20.0) * 1e-3 * 3000 * np.pi / 30)
    assert scene_losses(base.with_(seals="none")).breakdown_W["seal"] == 0.0
    assert sum(r.breakdown_W.values()) == pytest.approx(r.P_W, rel=1e-12)
    assert sum(r.heat_W.values()) == pytest.approx(r.P_W, rel=1e-12)
    skf = scene_losses(base.with_(models={"losses": "skf"}))
    assert skf.breakdown_W["churning"] > 0 and skf.breakdown_W["seal"] == pytest.approx(r.breakdown_W["seal"])
    assert sum(skf.breakdown_W.values()) == pytest.approx(skf.P_W, rel=1e-12)


def test_cage_loss_of_a_ring_guided_cage_vanishes_at_standstill():
    s = BATH.with_(T_C=50.0, cage="outer_ring", seals="none")
    P = [float(scene_losses(s.with_(n_rpm=n)).breakdown_W["cage"]) for n in (0.0, 1000.0, 2000.0)]
    assert P[0] == 0.0 and 0 < P[1] < P[2]


def test_coupling_parts_follow_the_scene():
    cp = prepare(BATH).coupling
    assert cp.parts == ("inner", "outer", "drag", "churning", "seal") == loss_parts(choose_models(BATH))
    assert np.allclose(cp.S.sum(axis=0), 1.0) and "bath" in cp.temperatures
    assert prepare(JET).coupling.parts == ("inner", "outer", "drag")
    assert not prepare(BATH).serves(BATH.with_(seals="none"))        # other parts: another family


@pytest.mark.parametrize("losses", ["local", "skf"])
def test_steady_oil_bath_conserves_energy_and_reports_churning(losses):
    st = steady_state(BATH.with_(models={"losses": losses}))
    bd = st.losses.breakdown_W
    assert np.isfinite(st.P_W) and st.P_W > 0 and bd["churning"] > 0 and bd["seal"] > 0
    assert sum(float(v) for v in bd.values()) == pytest.approx(st.P_W, rel=1e-9)
    assert abs(st.energy_balance_W) < 1e-6 * st.P_W
    assert st.models_used["churning"][0] and "4 coupled temperatures" in st.models_used["thermal"][1]


def test_transient_of_the_oil_bath_heats_up_towards_the_steady_state():
    tr = transient(BATH, 7200.0, t_eval=np.linspace(0.0, 7200.0, 13))
    T = tr.T_C["inner_ring"]
    assert np.all(np.diff(T[:4]) > 0) and np.all(tr.breakdown_W["churning"] > 0)
    assert T[-1] == pytest.approx(steady_state(BATH).T_C["inner_ring"], abs=0.01)


@pytest.mark.parametrize("extra", [[], ["--set", "models.losses=skf"]])
def test_cli_run_json_on_the_oil_bath(capsys, extra):
    code = main(["run", str(EX / "oil_bath_6208.toml"), "--json", *extra])
    d = json.loads(capsys.readouterr().out)
    assert code == 0 and d["P_W"] > 0 and d["breakdown_W"]["churning"] > 0
    assert all(np.isfinite(v) and v >= 0 for v in d["breakdown_W"].values())
    for key in ("churning", "seals", "cage", "drag"):
        assert d["models_used"][key]["reason"]


#: a value every [models] key accepts on the oil-bath example (a new key must be added here)
_FORCEABLE = {"rolling": "auto", "hertz": "exact", "load_model": "jones_harris", "drag": "false",
              "kinematics": "outer", "stiffness": "nominal", "high_speed": "false", "losses": "local",
              "skf_R1": "1e-6", "skf_S1": "0.01", "skf_mu_EHL": "0.05", "churning": "false", "seals": "false",
              "cage": "false", "traction": "constant", "inlet_heating": "false", "starvation": "false",
              "clearance": "given"}


def test_every_models_key_can_be_forced_with_set(capsys):
    from thermobear.scene.scene import MODEL_FIELDS
    assert set(_FORCEABLE) == set(MODEL_FIELDS)
    for key, value in _FORCEABLE.items():
        code = main(["run", str(EX / "oil_bath_6208.toml"), "--json", "--set", "T_C=50", "--set",
                     f"models.{key}={value}"])
        out = capsys.readouterr().out
        assert code == 0, (key, out)
        assert json.loads(out)["P_W"] > 0
