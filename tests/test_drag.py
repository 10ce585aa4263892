"""Pouly (2010) ball drag, seed 004 eq 21: analytic limits, scaling, seed 004 hand computation."""
import warnings

import numpy as np
import pytest

from thermobear.errors import ExtrapolationWarning, InputError
from thermobear.losses.drag import (air_properties, drag_coefficient_sphere, drag_loss, drag_power_pouly,
                                      mixture_density, mixture_viscosity, oil_volume_fraction_parker)

# seed 004: 7210, Z 15, dm 70 mm, 40°, D 12.7 mm (estimated, bearings.toml), 10 L/h
Z, D, DM, ALPHA = 15, 12.7e-3, 70e-3, np.radians(40.0)


def omega_cage(n_rpm):
    """Outer ring fixed: ω_c = ω_i (1 − γ)/2, γ = D cos α / dm (Harris 2001 eq 8.20)."""
    return n_rpm * np.pi / 30 * (1 - D / DM * np.cos(ALPHA)) / 2


def seed004_oil(T_C):
    """Seed 004 oil by hand: ASTM D341 through ν40 = 36.6, ν100 = 7.8 cSt; ρ15 864.6 kg/m³, −0.65 kg/m³/K."""
    A = lambda nu: np.log10(np.log10(nu + 0.7))       # noqa: E731
    B = (A(36.6) - A(7.8)) / (np.log10(373.15) - np.log10(313.15))
    nu = 10 ** (10 ** (A(36.6) - B * (np.log10(T_C + 273.15) - np.log10(313.15)))) - 0.7
    rho = 864.6 - 0.65 * (T_C - 15)
    return rho, nu * 1e-6 * rho


def test_stokes_limit_closed_form():
    """C_d = 24/Re ⇒ F = 3π μ D v per ball (Stokes) ⇒ P = Z 3π μ D v² exactly."""
    wc = np.array([0.5, 2.0])                       # Re <= 0.08: inside the Stokes range
    r = drag_loss(Z, D, DM, wc, 1.0, 870.0, 10.0, 303.15, cd_method="Stokes")
    assert np.all(r.Re < 0.3)
    v = wc * DM / 2
    np.testing.assert_allclose(r.P_W, Z * 3 * np.pi * 10.0 * D * v ** 2, rtol=1e-12)


def test_clift_gauvin_tends_to_stokes():
    Re = np.array([1e-4, 1e-3])
    np.testing.assert_allclose(drag_coefficient_sphere(Re), 24 / Re, rtol=3e-3)
    # and the Newton plateau 0.4-0.5 for 1e3 < Re < 1e5
    assert np.all((drag_coefficient_sphere(np.array([2e3, 2e4, 1e5])) > 0.38)
                  & (drag_coefficient_sphere(np.array([2e3, 2e4, 1e5])) < 0.5))


def test_power_scales_with_omega_cubed_at_constant_cd():
    P = drag_power_pouly(60.0, 0.44, Z, D, np.array([100.0, 200.0, 400.0]), DM)
    np.testing.assert_allclose(P[1:] / P[:-1], 8.0, rtol=1e-12)


def test_mixture_limits():
    assert mixture_density(0.0, 860.0, 1.16) == pytest.approx(1.16)
    assert mixture_density(1.0, 860.0, 1.16) == pytest.approx(860.0)
    assert mixture_viscosity(0.0, 0.05, 1.9e-5) == pytest.approx(1.9e-5)
    assert mixture_viscosity(1.0, 0.05, 1.9e-5) == pytest.approx(0.05)
    with pytest.raises(InputError):
        mixture_density(1.2, 860.0, 1.16)


def test_air_properties_against_ideal_gas_and_tables():
    rho, mu = air_properties(np.array([300.0, 350.0]))
    np.testing.assert_allclose(rho, 101325 / (287.05 * np.array([300.0, 350.0])), rtol=3e-3)
    assert mu[0] == pytest.approx(184.6e-7, rel=0.02)       # Incropera Table A.4, 300 K
    assert mu[1] > mu[0]


def test_parker_fraction_scaling_and_clip():
    X = oil_volume_fraction_parker(np.array([100.0, 200.0]), 5000, 70.0)
    assert X[1] / X[0] == pytest.approx(2 ** 0.37, rel=1e-12)
    assert oil_volume_fraction_parker(100.0, 5000, 70.0, "percent") == pytest.approx(X[0] / 100)
    with pytest.warns(ExtrapolationWarning):
        assert oil_volume_fraction_parker(1000.0, 10.0, 20.0) == 1.0


def test_seed004_7210_6500rpm_hand_computation():
    """7210, 6500 r/min, 10 L/h, 30 °C: independent hand computation of eq 21 (Clift–Gauvin C_d)."""
    rho_o, mu_o = seed004_oil(30.0)
    X = 1e5 * (10 * 1000 / 60) ** 0.37 / (6500 * 70 ** 1.7)
    rho_a, mu_a = 1.1644, 1.869e-5                            # air at 30 °C, 1 atm
    rho_m, mu_m = X * rho_o + (1 - X) * rho_a, X * mu_o + (1 - X) * mu_a
    v = omega_cage(6500) * DM / 2
    Re = rho_m * v * D / mu_m
    cd = 24 / Re * (1 + 0.152 * Re ** 0.677) + 0.417 / (1 + 5070 * Re ** -0.94)
    P_hand = 0.5 * rho_m * cd * (np.pi * D ** 2 / 4) * v ** 3 * Z
    r = drag_loss(Z, D, DM, omega_cage(6500), oil_volume_fraction_parker(10 * 1000 / 60, 6500, 70.0),
                  rho_o, mu_o, 303.15)
    assert r.P_W == pytest.approx(P_hand, rel=2e-3)
    # order of magnitude seed 004 implies: drag ≈ 5 % of a total of a few hundred W
    assert 10.0 < r.P_W < 60.0


def test_seed004_flow_x1p5_gives_plus16_percent():
    """Seed 004 §6: 'multiplying the oil flow rate by 1.5 leads to an increase of drag losses equal to 16 %'
    (8070 r/min). Reproduced with Parker's number read as a fraction, not as a percent."""
    for T_C in (30.0, 90.0):
        rho_o, mu_o = seed004_oil(T_C)

        def P(q_L_h, conv):
            X = oil_volume_fraction_parker(q_L_h * 1000 / 60, 8070, 70.0, conv)
            return drag_loss(Z, D, DM, omega_cage(8070), X, rho_o, mu_o, T_C + 273.15).P_W

        assert P(15, "fraction") / P(10, "fraction") == pytest.approx(1.16, abs=0.01)
        assert P(15, "percent") / P(10, "percent") < 1.08


def test_vectorised_over_operating_points():
    rho_o, mu_o = seed004_oil(50.0)
    n = np.array([3200.0, 4800.0, 6500.0, 8070.0])
    X = oil_volume_fraction_parker(10 * 1000 / 60, n, 70.0)
    vec = drag_loss(Z, D, DM, omega_cage(n), X, rho_o, mu_o, 323.15)
    for k in range(4):
        assert vec.P_W[k] == pytest.approx(drag_loss(Z, D, DM, omega_cage(n[k]), X[k], rho_o, mu_o, 323.15).P_W,
                                           rel=1e-12)
    assert np.all(np.diff(vec.P_W) > 0)


def test_bad_input():
    with pytest.raises(InputError) as e:
        drag_loss(Z, D, DM, -1.0, 0.05, 860.0, 0.03, 303.15)
    assert e.value.field == "omega_c"
    with pytest.raises(InputError):
        drag_coefficient_sphere(100.0, "NoSuchMethod")
    with pytest.raises(InputError):
        air_properties(50.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(ExtrapolationWarning):
            drag_coefficient_sphere(5e5)


def test_cavity_oil_fraction_by_supply():
    # oil jets and oil–air: Parker's fraction of the oil flow through the bearing (an oil–air feed of a few mL/h
    # gives ≈ 1 % at moderate speed, falling as 1/n); grease, bath, dry film: air; at standstill: none
    from thermobear.losses.drag import cavity_oil_fraction, oil_volume_fraction_parker
    W, n, dm = 0.005e-3 / 3600, np.array([3700.0, 7400.0, 0.0]), 0.06
    for supply in ("oil_jet", "oil_air"):
        X = cavity_oil_fraction(supply, W, n, dm)
        assert X[:2] == pytest.approx(oil_volume_fraction_parker(W * 6e7, n[:2], 60.0), rel=1e-14) and X[2] == 0.0
        assert X[1] == pytest.approx(X[0] / 2, rel=1e-12)
    for supply in ("grease", "oil_bath", "dry_film"):
        assert not cavity_oil_fraction(supply, W, n, dm).any()


@pytest.mark.parametrize("key, value", [("D", np.inf), ("dm", np.inf), ("omega_c", np.inf), ("rho_oil", np.inf),
                                        ("mu_oil", np.inf), ("Z", np.nan), ("A_c", np.nan), ("A_c", -1e-4)])
def test_drag_refuses_infinite_or_undefined_inputs_by_name(key, value):
    """An infinite diameter, speed, density or viscosity has no finite drag: they passed the check ("the formulas
    take it as their limit") and came back NaN (or a ZeroDivisionError, or a bare ValueError for Z = NaN)."""
    args = dict(Z=15, D=12.7e-3, dm=70e-3, omega_c=300.0, X=0.01, rho_oil=857.0, mu_oil=0.0494, T_K=303.15)
    args[key] = value
    with pytest.raises(InputError, match=f"^{key} = "):
        drag_loss(**args)
