"""Tabulated air properties against CoolProp's PropsSI."""
import numpy as np
import pytest
from CoolProp.CoolProp import PropsSI

from thermobear.air import air_properties
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
