"""Full-film traction (thermobear.losses.traction): Roelands viscosity, Eyring / limiting shear stress,
the slip-weighted traction coefficient of a contact strip, and its use in the local model."""
from __future__ import annotations

import numpy as np
import pytest

import thermobear as tb
from thermobear.errors import InputError
from thermobear.losses import bearing_losses
from thermobear.losses.traction import (STRIP_NODES, eyring_shear_stress, roelands_pressure_index,
                                        roelands_viscosity, strip_traction_coefficient)


def test_roelands_has_the_barus_slope_at_ambient_pressure():
    # d ln eta / dp at p = 0 equals alpha_p (Roelands 1966 with Z = alpha p0 / (ln eta0 + 9.67))
    eta0, alpha = 0.05, 20e-9
    dp = 1e3
    slope = np.log(roelands_viscosity(eta0, alpha, dp) / eta0) / dp
    assert slope == pytest.approx(alpha, rel=1e-5)


def test_roelands_index_of_a_mineral_oil_and_below_barus_at_ehl_pressure():
    assert 0.4 < roelands_pressure_index(0.114, 19.5e-9) < 0.7         # mineral oils: Z = 0.5-0.7
    assert roelands_viscosity(0.114, 19.5e-9, 1e9) < 1e-3 * 0.114 * np.exp(19.5e-9 * 1e9)


def test_eyring_is_newtonian_at_low_stress_and_limited_at_high_slip():
    # Johnson & Tevaarwerk 1977: tau -> eta gamma' as eta gamma'/tau0 -> 0
    assert eyring_shear_stress(10.0, 1e2, 5e6) == pytest.approx(1e3, rel=1e-7)
    # logarithmic above tau0: tau0 ln(2 eta gamma'/tau0)
    x = 1e6
    assert eyring_shear_stress(x * 5e6, 1.0, 5e6) == pytest.approx(5e6 * np.log(2 * x), rel=1e-9)
    # Bair & Winer 1979: capped by the limiting shear stress
    assert eyring_shear_stress(1e12, 1e6, 5e6, 1e8) == 1e8
    with pytest.raises(InputError):
        eyring_shear_stress(1.0, 1.0, 0.0)


def test_strip_traction_is_the_constant_mu_when_the_film_is_at_its_limit():
    # tau/p = Lambda_L everywhere (huge viscosity): mu_f = Lambda_L exactly, the constant-mu model
    xi = STRIP_NODES[0]
    pm = np.pi / 4 * 2e9 * np.sqrt(1 - xi**2)
    mu = strip_traction_coefficient(0.01 * xi, pm, 1e-7, 1e3, 30e-9, 5e6, 0.06)
    assert mu == pytest.approx(0.06, rel=1e-12)
    # nothing slips: 0
    assert strip_traction_coefficient(0.0 * xi, pm, 1e-7, 0.1, 20e-9, 5e6, 0.06) == 0.0


def test_strip_weights_integrate_the_hertz_strip_load():
    # 2 * int_0^1 (3/4)(1 - xi^2) d xi = 1 (the strip load integrates to Q); the spin moment (3/8) mu Q a
    xi, W = STRIP_NODES
    assert 2 * 0.75 * W.sum() == pytest.approx(1.0, rel=1e-12)
    assert 2 * 0.75 * (W * xi).sum() == pytest.approx(0.375, rel=1e-12)


def test_traction_grows_with_slip_and_stays_below_the_limit():
    xi = STRIP_NODES[0]
    pm = np.pi / 4 * 2.15e9 * np.sqrt(1 - xi**2)
    mus = [strip_traction_coefficient(w * 0.744e-3 * xi, pm, 0.36e-6, 0.114, 19.5e-9, 5e6, 0.075)
           for w in (1.0, 10.0, 52.4, 500.0)]
    assert np.all(np.diff(mus) > 0) and max(mus) <= 0.075


def test_local_model_spin_loss_falls_with_eyring_traction():
    # seed 002 51107 at 7000 N: the spin of the heavily loaded thrust contacts slips at < 4 % of the
    # rolling speed, where the film carries ~0.03, not the plateau 0.05
    s = tb.load_scene(tb.example_path("seed002_grease_thrust_51107.toml"))
    kw = dict(Fa=7000.0, n_rpm=1000.0, T_C=49.8, supply="grease", drag=False)
    c = bearing_losses(s.bearing, s.lubricant, **kw)
    e = bearing_losses(s.bearing, s.lubricant, traction="eyring", **kw)
    assert 0.4 < e.breakdown_W["pivoting"] / c.breakdown_W["pivoting"] < 0.8
    assert e.breakdown_W["rolling"] == c.breakdown_W["rolling"]
    assert np.all(e.contacts["inner"]["mu_pivoting"] < 0.05)
    with pytest.raises(InputError):
        bearing_losses(s.bearing, s.lubricant, traction="coulomb", **kw)
