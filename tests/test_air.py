"""Tabulated air properties against CoolProp's PropsSI."""
import numpy as np
import pytest
from CoolProp.CoolProp import PropsSI

from thermobear.lubrication.air import air_properties
from thermobear.errors import InputError


def test_table_matches_coolprop():
    T = np.array([210.3, 273.15, 300.0, 333.7, 401.9, 512.25, 599.5])
    p = air_properties(T)
    for key, code in (("rho", "D"), ("mu", "V"), ("k", "L"), ("cp", "C")):
        ref = PropsSI(code, "T", T, "P", 101325.0, "Air")
        np.testing.assert_allclose(p[key], ref, rtol=1e-6)


def test_other_pressure_goes_direct():
    p = air_properties(320.0, 2e5)
    assert p["rho"] == pytest.approx(PropsSI("D", "T", 320.0, "P", 2e5, "Air"), rel=1e-12)


def test_range():
    with pytest.raises(InputError, match="T_K"):
        air_properties(700.0)


def test_shipped_table_is_coolprop_at_every_node():
    """materials/air_1atm.toml (written by validation/air_table.py from CoolProp 8.0.0) against the installed
    CoolProp: equal with 8.0.0; another release may move the air model slightly, so 1e-4 — beyond that the
    table is stale and must be regenerated."""
    from thermobear.files import data_dir, read_toml
    d = read_toml(str(data_dir("materials") / "air_1atm.toml"))
    T = np.asarray(d["T_K"], float)
    assert T[0] == 200.0 and T[-1] == 600.0 and np.all(np.diff(T) == 1.0) and d["p_Pa"] == 101325.0
    for key, code in (("rho_kg_m3", "D"), ("mu_Pa_s", "V"), ("k_W_mK", "L"), ("cp_J_kgK", "C")):
        np.testing.assert_allclose(d[key], PropsSI(code, "T", T, "P", 101325.0, "Air"), rtol=1e-4)


def test_shipped_spline_pieces_are_scipys_not_a_knot_spline():
    """The pieces the module evaluates are scipy's CubicSpline through the shipped values (to round-off)."""
    from scipy.interpolate import CubicSpline
    from thermobear.files import data_dir, read_toml
    d = read_toml(str(data_dir("materials") / "air_1atm.toml"))
    T = np.asarray(d["T_K"], float)
    for key in ("rho_kg_m3", "mu_Pa_s", "k_W_mK", "cp_J_kgK"):
        np.testing.assert_allclose(np.asarray(d["spline_" + key]).reshape(-1, 4), CubicSpline(T, d[key]).c.T,
                                   rtol=1e-12, atol=1e-15 * np.max(d[key]))


def test_a_steady_state_does_not_import_coolprop():
    """The 1 atm table is data: a coupled solve in a fresh process never pays CoolProp's import (≈ 1.7 s)."""
    import subprocess
    import sys
    code = ("import sys, thermobear as tb; "
            "st = tb.steady_state(tb.load_scene(tb.example_path('seed004_oil_jet_7210.toml'))); "
            "print('CoolProp' in sys.modules, st.P_W > 0)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split()
    assert out == ["False", "True"]


@pytest.mark.parametrize("broken", [{"T_K": [200.0]}, "short", "nan", "pieces"])
def test_a_broken_table_is_a_named_input_error(monkeypatch, broken):
    import thermobear.files as data
    import thermobear.lubrication.air as air
    good = data.read_toml(str(data.data_dir("materials") / "air_1atm.toml"))
    if broken == "short":
        bad = {**good, "k_W_mK": good["k_W_mK"][:-1]}
    elif broken == "pieces":                       # pieces that miss the tabulated values
        bad = {**good, "spline_rho_kg_m3": [1.0] * len(good["spline_rho_kg_m3"])}
    elif broken == "nan":
        bad = {**good, "cp_J_kgK": [float("nan")] * len(good["cp_J_kgK"])}
    else:
        bad = broken
    monkeypatch.setattr(air, "read_toml", lambda path: bad)
    with pytest.raises(InputError, match="air_1atm.toml"):
        air.air_table()


def test_one_temperature_equals_the_array_path():
    """One Python float takes the table's cubic pieces without arrays: the same values."""
    T = np.concatenate([np.random.default_rng(5).uniform(200.0, 600.0, 300), [200.0, 273.15, 599.5, 600.0]])
    arr = air_properties(T)
    for k, t in enumerate(T):
        p = air_properties(float(t))
        for key in ("rho", "mu", "k", "cp", "nu", "Pr"):
            assert p[key] == pytest.approx(arr[key][k], rel=1e-14, abs=0.0)
    assert air_properties(np.float64(T[0]))["Pr"] == pytest.approx(arr["Pr"][0], rel=1e-14)
    assert isinstance(air_properties(np.array(300.0))["rho"], float)
    with pytest.raises(InputError, match="T_K"):
        air_properties(650.0)
    with pytest.raises(InputError, match="T_K"):
        air_properties(np.array([300.0, np.nan]))
