"""Ball kinematics: analytic limits (α = 0, thrust), no-slip identities, seed 000 Table 1 speeds."""
import numpy as np
import pytest

from thermobear.errors import InputError
from thermobear.contact.kinematics import (ball_kinematics, cage_speed, caged_ball_kinematics, common_cage_speed,
                                           entrainment_speed, free_orbital_speed)

D, DM = 12.7e-3, 70e-3


def test_alpha_zero_reduces_to_textbook():
    w = 600.0
    g = D / DM
    for control in ("outer", "inner", "radial"):
        beta = None if control != "radial" else 0.0
        k = ball_kinematics(w, 0.0, 0.0, 0.0, D, DM, control=control, beta=beta)
        assert k.omega_c == pytest.approx(0.5 * w * (1 - g), rel=1e-12)
        assert k.omega_R == pytest.approx(-(DM / (2 * D)) * (1 - g * g) * w, rel=1e-12)
        assert k.spin_i == pytest.approx(0.0, abs=1e-9) and k.spin_o == pytest.approx(0.0, abs=1e-9)
        assert k.u_i == pytest.approx(entrainment_speed(w, 0.0, D, DM, 0.0), rel=1e-12)
        assert k.u_o == pytest.approx(k.u_i, rel=1e-12)


def test_equal_angles_beta_equal_alpha_identity():
    # Harris 2001 ch. 8: with αi = αo = β = α, ω_m = ω(1 − γ)/2 and ω_R = −(dm/2D)(1 − γ²) ω
    a = np.deg2rad(40.0)
    g = D * np.cos(a) / DM
    k = ball_kinematics(500.0, 0.0, a, a, D, DM, beta=a)
    assert k.omega_c == pytest.approx(500.0 * (1 - g) / 2, rel=1e-12)
    assert k.omega_c == pytest.approx(cage_speed(500.0, 0.0, g), rel=1e-12)


def test_outer_control_zero_outer_spin_and_inner_spin_present():
    a = np.deg2rad(np.array([15.0, 25.0, 40.0]))
    k = ball_kinematics(680.0, 0.0, a, a, D, DM, control="outer")
    np.testing.assert_allclose(k.spin_o, 0.0, atol=1e-9)
    assert np.all(np.abs(k.spin_roll_i) > 0.05) and np.all(np.diff(np.abs(k.spin_roll_i)) > 0)


def test_outer_ring_rotating_symmetry():
    # rotating the outer ring instead: same entrainment magnitude formula, cage = ω_o(1+γ)/2
    g = D / DM
    k = ball_kinematics(0.0, 300.0, 0.0, 0.0, D, DM)
    assert k.omega_c == pytest.approx(0.5 * 300.0 * (1 + g), rel=1e-12)
    assert k.u_o == pytest.approx(entrainment_speed(0.0, 300.0, D, DM, 0.0), rel=1e-12)


def test_no_slip_surface_speeds_match():
    a_i, a_o = np.deg2rad(42.0), np.deg2rad(37.0)
    k = ball_kinematics(900.0, 0.0, a_i, a_o, D, DM)
    # ball surface speed at each contact equals the ring's (cage frame)
    assert abs(0.5 * D * k.omega_R * np.cos(a_o + k.beta)) == pytest.approx(k.u_o, rel=1e-12)
    assert abs(0.5 * D * k.omega_R * np.cos(a_i + k.beta)) == pytest.approx(k.u_i, rel=1e-12)


def test_seed000_table1_speeds():
    # seed 000 Table 1: ω_b = 23.74, 47.49, 71.24, 94.98 rad/s; ω_c = 5.23 … 20.94 rad/s (eqs 1–2, 13, 17)
    n = np.array([100.0, 200.0, 300.0, 400.0])
    k = ball_kinematics(n * np.pi / 30, 0.0, np.pi / 2, np.pi / 2, 7.938e-3, 36e-3, control="radial")
    np.testing.assert_allclose(np.abs(k.omega_R), [23.74, 47.49, 71.24, 94.98], rtol=6e-4)
    np.testing.assert_allclose(k.omega_c, [5.23, 10.47, 15.70, 20.94], rtol=1.2e-3)
    np.testing.assert_allclose(np.abs(k.spin_i), k.omega_c, rtol=1e-12)        # pivoting = ω_c (eq 13)
    np.testing.assert_allclose(k.u_i, np.pi * n * 36e-3 / 120, rtol=1e-12)       # eq 17


def test_bad_control():
    with pytest.raises(InputError, match="control"):
        ball_kinematics(1.0, 0.0, 0.0, 0.0, D, DM, control="cage")


def test_radial_control_at_zero_contact_angle_is_refused():
    # a radial ball axis at α = 0 is normal to both contacts: no rolling solution
    with pytest.raises(InputError, match="control"):
        ball_kinematics(500.0, 0.0, 0.0, 0.0, D, DM, control="radial")


def test_caged_ball_without_inner_load_rolls_on_the_outer_race():
    # a ball outside the load zone (Q_i = 0): orbits at the cage speed, no slip on the outer race
    a_i, a_o = np.deg2rad(75.0), np.deg2rad(0.5)          # a gap's geometry, not a contact
    wc = 0.42 * 500.0
    k = caged_ball_kinematics(500.0, 0.0, a_i, a_o, D, DM, wc, 0.0, 40.0)
    assert k.omega_c == pytest.approx(wc, rel=1e-12)
    assert abs(0.5 * D * k.omega_R * np.cos(a_o + k.beta)) == pytest.approx(k.u_o, rel=1e-12)
    assert k.u_o == pytest.approx(wc * 0.5 * DM * (1 + D / DM * np.cos(a_o)), rel=1e-12)
    # the free (two-contact no-slip) solution would make this ball orbit far faster than the cage
    assert ball_kinematics(500.0, 0.0, a_i, a_o, D, DM).omega_c > 1.5 * wc


def test_caged_equals_free_when_the_cage_runs_at_the_balls_own_speed():
    a_i, a_o = np.deg2rad([42.0, 45.0]), np.deg2rad([37.0, 36.0])
    k0 = ball_kinematics(900.0, 0.0, a_i, a_o, D, DM)
    k = caged_ball_kinematics(900.0, 0.0, a_i, a_o, D, DM, k0.omega_c, [100.0, 50.0], [120.0, 70.0])
    for name in ("omega_R", "u_i", "u_o", "spin_i", "spin_o"):
        np.testing.assert_allclose(getattr(k, name), getattr(k0, name), rtol=1e-10, atol=1e-12)


def test_common_cage_speed_weights_and_limits():
    assert common_cage_speed([[10.0, 20.0], [5.0, 7.0]], [[1.0, 3.0], [0.0, 0.0]]).tolist() == [17.5, 6.0]


@pytest.mark.parametrize("args, field", [
    ((np.nan, 0.0, 0.3, 0.28, 0.0127, 0.07), "omega_i"), ((500.0, np.inf, 0.3, 0.28, 0.0127, 0.07), "omega_o"),
    ((500.0, 0.0, np.nan, 0.28, 0.0127, 0.07), "alpha_i"), ((500.0, 0.0, 0.3, 0.28, 0.0, 0.07), "D"),
    ((500.0, 0.0, 0.3, 0.28, 0.1, 0.07), "D"), ((500.0, 0.0, 0.3, 0.28, 0.0127, 0.0), "dm"),
    (([1.0, 2.0, 3.0], [1.0, 2.0], 0.3, 0.28, 0.0127, 0.07), "omega_i, omega_o"),
])
def test_ball_kinematics_refuse_what_has_no_kinematics_by_name(args, field):
    """NaN speeds or angles, a ball of zero size or larger than the pitch circle, a pitch circle of zero: the
    kinematics came back NaN or ±inf (or a ZeroDivisionError); refused naming the argument, as is a batch
    whose arrays do not broadcast."""
    for f in (ball_kinematics, free_orbital_speed):
        with pytest.raises(InputError, match=f"^{field}"):
            f(*args)
    with pytest.raises(InputError, match="^beta"):
        ball_kinematics(500.0, 0.0, 0.3, 0.28, 0.0127, 0.07, beta=np.nan)
