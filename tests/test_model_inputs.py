"""Which scene inputs the chosen models read (thermobear.model_inputs): the oil supply's flow and inlet temperature."""
import warnings

import thermobear as tb
from thermobear.app.calibration import parameter_names
from thermobear.errors import UnreadInput
from thermobear.model_inputs import unread_inputs, unread_settings


def test_a_grease_scene_names_an_oil_flow_and_inlet_temperature_it_does_not_read():
    """A grease 6208 gave the same 69.92 W with an 80 °C inlet and 50 L/h as without, without a word, and calibrate
    offered T_oil_in_C and oil_flow_L_h for it; now both are unread inputs, named when set, not offered."""
    s = tb.load_scene(tb.example_path("block_6208_grease.toml"))
    set_ = s.with_(T_oil_in_C=80.0, oil_flow_L_h=50.0)
    assert [f for f, _, _ in unread_settings(set_)] == ["lubricant.T_in_C", "lubricant.flow_L_h"]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r0, r1 = tb.steady_state(s), tb.steady_state(set_)
    assert r1.P_W == r0.P_W
    assert sorted(w.field for w in r1.warnings if isinstance(w, UnreadInput)) == ["lubricant.T_in_C",
                                                                               "lubricant.flow_L_h"]
    assert not {"T_oil_in_C", "oil_flow_L_h"} & set(parameter_names(s))


def test_an_inlet_temperature_without_a_flow_is_not_read_and_a_bath_flow_is():
    """An oil bath that does not circulate (flow 0): its inlet temperature carries nothing; a flow circulates
    through the bath and moves the answer, so it stays a read input (and a calibratable one)."""
    s = tb.load_scene(tb.example_path("block_6208_oil_bath.toml"))
    assert "lubricant.T_in_C" in unread_inputs(s) and "lubricant.flow_L_h" not in unread_inputs(s)
    assert "lubricant.T_in_C" not in unread_inputs(s.with_(oil_flow_L_h=50.0))
    assert tb.steady_state(s.with_(oil_flow_L_h=50.0)).P_W != tb.steady_state(s).P_W
    assert "oil_flow_L_h" in parameter_names(s) and "T_oil_in_C" not in parameter_names(s)
    jet = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    assert not {"lubricant.T_in_C", "lubricant.flow_L_h"} & set(unread_inputs(jet))


def test_a_prescribed_temperature_names_the_network_inputs_it_does_not_read():
    """At operation.T_C no network runs: the oil-bath 6208 gave 21.179 W with an 80 °C inlet, 5 L/h and any room
    temperature, without a word; now the inlet, the bath's flow and a room away from 20 °C are named.  A jet's flow
    still sets the drag's oil fraction there, so it stays read."""
    bath = tb.load_scene(tb.example_path("block_6208_oil_bath.toml")).with_(T_C=70.0)
    set_ = bath.with_(T_oil_in_C=80.0, oil_flow_L_h=5.0)
    assert [f for f, _, _ in unread_settings(set_)] == ["lubricant.T_in_C", "lubricant.flow_L_h", "thermal.T_ambient_C"]
    jet = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")).with_(T_C=50.0)
    assert "lubricant.flow_L_h" not in unread_inputs(jet) and "lubricant.T_in_C" in unread_inputs(jet)
    assert tb.solve(jet.with_(oil_flow_L_h=30.0)).P_W != tb.solve(jet).P_W
    assert "thermal.T_ambient_C" not in unread_inputs(jet.with_(T_C=None))


def test_a_thrust_bearings_fits_are_named_unread():
    """p6 / N7 on the 51107 gave the plain answer without a word: a thrust bearing has no radial clearance for them."""
    s = tb.load_scene(tb.example_path("seed002_grease_thrust_51107.toml"))
    fitted = s.with_(shaft_fit="p6", housing_fit="N7")
    assert [f for f, _, _ in unread_settings(fitted)] == ["bearing.shaft_fit", "bearing.housing_fit"]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = tb.steady_state(fitted)
    assert r.P_W == tb.steady_state(s).P_W
    assert ["bearing.shaft_fit = p6" in str(w) for w in r.warnings if isinstance(w, UnreadInput)] == [True, False]
