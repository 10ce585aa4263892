"""Regressions for defects found in review (each test failed before its fix)."""
import dataclasses

import numpy as np
import pytest

import thermobear as tb
from thermobear.errors import InputError
from thermobear.contact.hertz import hertz
from thermobear.contact.kinematics import ball_kinematics
from thermobear.coupled import scene_losses
from thermobear.models import choose_models

S004 = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))


def test_two_dimensional_batch_temperatures_follow_the_operating_points():
    b, oil = tb.bearing("51205-3ball"), tb.lubricant("mol-liton-00")
    n, T = np.array([60.0, 120.0, 210.0]), np.array([20.0, 40.0, 60.0])
    r = tb.bearing_losses(b, oil, Fa=[[1.0], [4.0]], n_rpm=n, T_C=T, supply="grease")
    single = [tb.bearing_losses(b, oil, Fa=1.0, n_rpm=nk, T_C=Tk, supply="grease").P_W for nk, Tk in zip(n, T)]
    np.testing.assert_allclose(r.P_W[0], single, rtol=1e-12)


def test_radial_control_at_zero_contact_angle_is_refused():
    with pytest.raises(InputError, match="control"):
        ball_kinematics(500.0, 0.0, 0.0, 0.0, 12.7e-3, 70e-3, control="radial")


@pytest.mark.parametrize("kw, field", [
    (dict(M=float("nan")), "M"), (dict(oil_flow_L_h=-5.0), "oil_flow_L_h"), (dict(Fa="abc"), "Fa"),
    (dict(bearing=42), "bearing"), (dict(models={"film": "x"}), "models.film"),
    (dict(models={"kinematics": "cage"}), "models.kinematics"),
    (dict(network_parameters={"x.G_W_K": "big"}), "thermal.parameters"),
])
def test_with_validates_like_a_scene_file(kw, field):
    with pytest.raises(InputError) as e:
        S004.with_(**kw)
    assert field in str(e.value)


def test_with_accepts_names_and_tables():
    s = S004.with_(lubricant={"name": "seed002-mg1"}, bearing="7210")
    assert s.lubricant.name == "seed002-mg1" and s.bearing.name == "7210"


def test_kinematics_model_key_is_used():
    a = scene_losses(S004.with_(T_C=50.0, models={"high_speed": False}))
    b = scene_losses(S004.with_(T_C=50.0, models={"high_speed": False, "kinematics": "inner"}))
    assert a.P_W != b.P_W and b.models_used["kinematics"][0] == "inner"


def test_closed_form_equals_jones_harris_for_an_unloaded_deep_groove_bearing():
    sc = S004.with_(bearing="6210", Fa=0.0, Fr=0.0, T_C=50.0, models={"high_speed": False})
    assert choose_models(sc)["load_model"][0] == "closed_form"
    a = scene_losses(sc)
    b = scene_losses(sc.with_(models={"load_model": "jones_harris"}))
    assert a.P_W == pytest.approx(b.P_W, rel=1e-12)


def test_outer_ring_rotation_does_not_take_the_inner_ring_high_speed_path():
    sc = dataclasses.replace(S004, rotating="outer").with_(n_rpm=6500.0)
    assert choose_models(sc)["high_speed"][0] == "no"
    with pytest.raises(InputError, match="inner"):
        choose_models(sc.with_(models={"high_speed": True}))


def test_nearly_circular_contact():
    c = hertz(10.0, 5e-3, 5.0000001e-3, 2.3e11)
    assert c.kappa == pytest.approx(1.0 + (2 / 3) * 2e-8, abs=1e-12)


def test_bore_must_leave_a_ring_wall():
    with pytest.raises(InputError, match="bore"):
        tb.bearing("6210").with_(bore=69e-3)
