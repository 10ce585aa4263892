"""Inlet shear heating (thermobear.lubrication.thermal_film) and the lubricant's β, and their use in
the local model."""
from __future__ import annotations

import numpy as np
import pytest

import thermobear as tb
from thermobear.losses import bearing_losses
from thermobear.lubrication.lubricant import lubricant
from thermobear.lubrication.thermal_film import (thermal_inlet_viscosity, thermal_loading_parameter,
                                                 thermal_reduction_gupta)


def test_thermal_reduction_is_one_at_low_speed_and_falls_with_loading_and_sliding():
    assert thermal_reduction_gupta(0.0) == 1.0
    assert thermal_reduction_gupta(1e-8) == pytest.approx(1.0, abs=1e-5)
    phis = thermal_reduction_gupta(np.array([0.1, 1.0, 10.0]))
    assert np.all(np.diff(phis) < 0)
    assert thermal_reduction_gupta(1.0, 0.2) < thermal_reduction_gupta(1.0, 0.0)
    # hand value of Gupta et al. (1992): L = 1, pure rolling: 1/(1 + 0.1) ; L = 10: 1/(1 + 0.1 * 10^0.64)
    assert thermal_reduction_gupta(1.0) == pytest.approx(1 / 1.1, rel=1e-12)
    assert thermal_reduction_gupta(10.0) == pytest.approx(1 / (1 + 0.1 * 10**0.64), rel=1e-12)


def test_loading_parameter_and_effective_viscosity():
    assert thermal_loading_parameter(0.04, 0.1, 2.0, 0.13) == pytest.approx(0.04 * 0.1 * 4 / 0.13)
    # the isothermal Hamrock-Dowson film at eta_T is the thermal film: (eta_T/eta)^0.67 = phi
    assert (thermal_inlet_viscosity(0.1, 0.9) / 0.1) ** 0.67 == pytest.approx(0.9, rel=1e-12)


def test_beta_is_the_temperature_derivative_of_ln_eta():
    oil = lubricant("seed004-mineral")
    for T in (30.0, 60.0, 100.0):
        fd = -(np.log(oil.eta(T + 0.01)) - np.log(oil.eta(T - 0.01))) / 0.02
        assert oil.beta_at(T) == pytest.approx(fd, rel=1e-5)
    assert np.allclose(oil.beta_at(np.array([30.0, 60.0])), [oil.beta_at(30.0), oil.beta_at(60.0)])


def test_traction_properties_come_from_the_family_or_the_file():
    assert lubricant("seed002-pg1").eyring_stress == 5e6
    custom = tb.Lubricant.from_dict({"nu40_cSt": 36.6, "nu100_cSt": 7.8, "rho15_kg_m3": 864.6,
                                     "alpha_p_1_Pa": 20e-9, "eyring_stress_Pa": 8e6,
                                     "limiting_shear_coefficient": 0.06})
    assert (custom.eyring_stress, custom.limiting_shear) == (8e6, 0.06)


def test_inlet_heating_thins_the_film_and_lowers_the_rolling_force_at_speed():
    s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    kw = dict(Fa=450.0, Fr=650.0, T_C=50.0, oil_flow_m3_s=10e-3 / 3600, drag=False)
    slow = [bearing_losses(s.bearing, s.lubricant, n_rpm=10.0, inlet_heating=h, **kw) for h in (False, True)]
    fast = [bearing_losses(s.bearing, s.lubricant, n_rpm=8000.0, inlet_heating=h, **kw) for h in (False, True)]
    assert slow[1].breakdown_W["rolling"] / slow[0].breakdown_W["rolling"] == pytest.approx(1.0, abs=1e-3)
    assert fast[1].breakdown_W["rolling"] / fast[0].breakdown_W["rolling"] < 0.95
    hT, h0 = fast[1].contacts["inner"]["h_c"], fast[0].contacts["inner"]["h_c"]
    assert np.all(hT[h0 > 0] < h0[h0 > 0])


def test_starvation_takes_the_replenishment_factor_of_the_supply():
    from thermobear.losses.skf import phi_rs
    s = tb.load_scene(tb.example_path("seed002_grease_thrust_51107.toml"))
    kw = dict(Fa=7000.0, n_rpm=1000.0, T_C=49.8, supply="grease", drag=False)
    r0 = bearing_losses(s.bearing, s.lubricant, **kw)
    r1 = bearing_losses(s.bearing, s.lubricant, starvation=True, **kw)
    b = s.bearing
    phi = phi_rs(1000.0, s.lubricant.nu(49.8), b.bore * 1e3, b.outer_diameter * 1e3, 3.8, 6e-8)
    assert r1.breakdown_W["rolling"] / r0.breakdown_W["rolling"] == pytest.approx(float(phi), rel=1e-9)
    assert r1.breakdown_W["pivoting"] == r0.breakdown_W["pivoting"]


def test_models_choose_the_film_physics_and_say_why():
    from thermobear.models import choose_models
    s = tb.load_scene(tb.example_path("seed002_grease_thrust_51107.toml"))
    m = choose_models(s)
    assert m["traction"][0] == "eyring" and m["starvation"][0] is True and "Φ_rs" in m["starvation"][1]
    forced = choose_models(s.with_(models={"traction": "constant", "inlet_heating": False, "starvation": False}))
    assert (forced["traction"][0], forced["inlet_heating"][0], forced["starvation"][0]) == ("constant", False, False)
    slow = choose_models(s.with_(n_rpm=1.0, T_C=80.0))            # applied everywhere (no switch), ≈ 1 here
    assert slow["inlet_heating"][0] is True and "φ_T = 1.000" in slow["inlet_heating"][1]
