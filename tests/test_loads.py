"""Jones–Harris quasi-static load distribution: ISO/TS 16281 reference cases, analytic limits,
symmetry, robustness and named failures (issue 2 acceptance)."""
import numpy as np
import pytest

import thermobear as tb
from thermobear.errors import InputError, NoEquilibrium
from thermobear.contact.geometry import BallBearing, bearing
from thermobear.loads import axial_contact_angle, load_distribution

STEEL = tb.Material(E=2.1e11, nu=0.3, rho=7850.0)


def iso(Pd):
    return BallBearing(D=11.5e-3, dm=43.5e-3, Z=7, fi=0.52, fo=0.53, Pd=Pd, kind="deep_groove",
                       ball_material=STEEL, ring_material=STEEL)


@pytest.mark.parametrize("Fa, Fr, Pd, field, ref_um", [
    (0.0, 1000.0, 0.0, "delta_r", 15.1101),
    (1000.0, 0.0, 0.0, "delta_a", 133.5381),
    (0.0, 1000.0, 0.01e-3, "delta_r", 21.223),
    (1000.0, 0.0, 0.01e-3, "delta_a", 149.1717),
])
def test_iso_ts_16281_reference_cases(Fa, Fr, Pd, field, ref_um):
    ld = load_distribution(iso(Pd), Fa=Fa, Fr=Fr)
    assert getattr(ld, field) * 1e6 == pytest.approx(ref_um, rel=5e-4)
    assert ld.residual <= 1e-9


def test_pure_axial_contact_angle_equation():
    # Fa/(Z Kn A^1.5) = sin α (cos α0 / cos α − 1)^1.5 with the solver's own α (not the closed form)
    b = bearing("7210")
    for Fa in (10.0, 450.0, 5000.0):
        ld = load_distribution(b, Fa=Fa)
        al = ld.alpha_i
        assert np.ptp(al) < 1e-12 and np.ptp(ld.Q) < 1e-9 * ld.Q.max()      # all balls equal
        lhs = Fa / (b.Z * b.Kn() * b.A**1.5)
        rhs = np.sin(al[0]) * (np.cos(b.alpha0) / np.cos(al[0]) - 1) ** 1.5
        assert lhs == pytest.approx(rhs, rel=1e-9)
        assert al[0] == pytest.approx(axial_contact_angle(b, Fa), rel=1e-10)
        assert ld.Q.sum() * np.sin(al[0]) == pytest.approx(Fa, rel=1e-10)


@pytest.mark.parametrize("Fr", [0.5, 5.0])
@pytest.mark.parametrize("ratio", [0.05, 0.3])
def test_light_combined_load_solved_by_continuation_one_ball_analytic(Fr, ratio):
    """A few newtons on a 7210 with Fa/Fr < 0.5: the closed-form start fails (the solution is almost pure
    geometry); continuation in the load magnitude finds it.  One ball carries everything, so
    Q sin α = Fa and Q cos α = Fr give tan α = Fa/Fr and Q = √(Fa² + Fr²) exactly."""
    b = bearing("7210")
    ld = load_distribution(b, Fa=ratio * Fr, Fr=Fr)
    k = ld.Q > 0
    assert k.sum() == 1 and ld.residual <= 1e-9
    assert np.tan(ld.alpha_i[k][0]) == pytest.approx(ratio, rel=1e-8)
    assert ld.Q[k][0] == pytest.approx(np.hypot(ratio * Fr, Fr), rel=1e-8)
    batch = load_distribution(b, Fa=np.array([ratio * Fr, 450.0]), Fr=np.array([Fr, 325.0]))
    assert np.allclose(batch.Q[0], ld.Q, rtol=1e-9, atol=1e-12)
    assert np.allclose(batch.Q[1], load_distribution(b, Fa=450.0, Fr=325.0).Q, rtol=1e-12)


def test_stribeck_sum_zero_clearance():
    # zero clearance, pure radial: Q_max·Z/Fr → 4.37 (discrete sums 4.385 Z=9, 4.364 Z=12, 4.369 Z=20)
    for Z, ref in ((9, 4.385), (12, 4.364), (20, 4.369)):
        b = BallBearing(D=12.7e-3, dm=65e-3 * Z / 9 if Z > 9 else 65e-3, Z=Z, fi=0.52, fo=0.52, Pd=0.0,
                        ball_material=STEEL, ring_material=STEEL)
        ld = load_distribution(b, Fr=8900.0)
        assert ld.Q.max() * Z / 8900.0 == pytest.approx(ref, abs=0.01)


def test_stribeck_radial_1d_solution_with_clearance():
    # pure radial, α ≈ 0: Q = Kn (δr cos ψ − Pd/2)^1.5, Fr = Σ Q cos ψ  (Harris 2001 §7.4: deep-groove simplification)
    b = iso(0.01e-3)
    ld = load_distribution(b, Fr=1000.0)
    dpsi = ld.delta_r * np.cos(ld.psi) - b.Pd / 2
    Q1 = b.Kn() * np.maximum(dpsi, 0) ** 1.5
    # equal to first order: α of the loaded balls is 0 exactly by symmetry
    np.testing.assert_allclose(ld.alpha_i[ld.loaded], 0.0, atol=1e-12)
    assert (Q1 * np.cos(ld.psi)).sum() == pytest.approx(1000.0, rel=2e-3)


def test_equilibrium_residual_and_force_sums():
    b = bearing("6210")
    ld = load_distribution(b, Fa=300.0, Fr=1500.0)
    assert ld.residual <= 1e-9
    Fa = np.sum(ld.Q * np.sin(ld.alpha_i))
    Fr = np.sum(ld.Q * np.cos(ld.alpha_i) * np.cos(ld.psi))
    assert Fa == pytest.approx(300.0, rel=1e-9) and Fr == pytest.approx(1500.0, rel=1e-9)


def test_symmetric_loads_give_symmetric_distribution():
    b = bearing("7210")
    ld = load_distribution(b, Fa=450.0, Fr=650.0)
    # ball j and ball Z−j are mirror images about ψ = 0
    Q = ld.Q
    np.testing.assert_allclose(Q[1:], Q[1:][::-1], rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(ld.alpha_i[1:], ld.alpha_i[1:][::-1], rtol=1e-10)
    assert np.argmax(Q) == 0


def test_unloaded_balls_are_zero_not_nan():
    b = bearing("6210")
    ld = load_distribution(b, Fr=1000.0)
    assert np.all(np.isfinite(ld.Q)) and np.all(np.isfinite(ld.alpha_i))
    assert np.sum(ld.Q == 0) >= 4 and np.all(ld.Q >= 0)


def test_tiny_and_zero_loads():
    b = bearing("6210")
    ld = load_distribution(b, Fa=1e-3, Fr=1e-3)
    assert ld.residual <= 1e-9 and np.all(np.isfinite(ld.Q))
    ld0 = load_distribution(b, Fa=0.0, Fr=0.0)
    assert np.all(ld0.Q == 0) and ld0.iterations == 0


def test_thrust_bearing_pure_axial_and_moment():
    b = bearing("51107")
    ld = load_distribution(b, Fa=7000.0)
    np.testing.assert_allclose(ld.Q, 7000.0 / b.Z, rtol=1e-12)
    np.testing.assert_allclose(ld.alpha_i, np.pi / 2)
    ldm = load_distribution(b, Fa=7000.0, M=5.0)
    assert ldm.residual <= 1e-9
    assert np.sum(ldm.Q * np.sin(ldm.alpha_i) * b.R_inner_locus * np.cos(ldm.psi)) == pytest.approx(5.0, rel=1e-8)


def test_radial_load_on_thrust_bearing_has_no_equilibrium():
    with pytest.raises(NoEquilibrium, match="thrust"):
        load_distribution(bearing("51107"), Fa=1000.0, Fr=100.0)


def test_radial_only_on_single_angular_contact_has_no_equilibrium():
    with pytest.raises(NoEquilibrium, match="axial"):
        load_distribution(bearing("7210"), Fa=0.0, Fr=100.0)


def test_moment_free_tilt_balances_moment():
    b = iso(0.0)
    ld = load_distribution(b, Fa=500.0, Fr=300.0, M=2.0)
    Mm = np.sum(ld.Q * np.sin(ld.alpha_i) * b.R_inner_locus * np.cos(ld.psi))
    assert Mm == pytest.approx(2.0, rel=1e-9) and ld.theta != 0


def test_batch_equals_single():
    b = bearing("7210")
    Fa = np.array([225.0, 450.0, 675.0, 450.0])
    Fr = np.array([0.0, 650.0, 1500.0, 50.0])
    ldb = load_distribution(b, Fa=Fa, Fr=Fr)
    assert ldb.Q.shape == (4, b.Z) and ldb.delta_a.shape == (4,)
    for k in range(4):
        ld = load_distribution(b, Fa=Fa[k], Fr=Fr[k])
        np.testing.assert_allclose(ldb.Q[k], ld.Q, rtol=1e-9, atol=1e-9)
        assert ldb.delta_r[k] == pytest.approx(ld.delta_r, rel=1e-9, abs=1e-15)


def test_more_load_more_displacement_monotonic():
    b = bearing("6210")
    Fr = np.linspace(100, 5000, 12)
    ld = load_distribution(b, Fa=200.0, Fr=Fr)
    assert np.all(np.diff(ld.delta_r) > 0) and np.all(np.diff(ld.Q.max(axis=1)) > 0)


def test_per_ball_stiffness_close_to_nominal():
    b = bearing("7210")
    a = load_distribution(b, Fa=450.0, Fr=650.0)
    p = load_distribution(b, Fa=450.0, Fr=650.0, stiffness="per_ball")
    assert p.residual <= 1e-9
    np.testing.assert_allclose(p.Q, a.Q, rtol=2e-3, atol=1e-6)


@pytest.mark.parametrize("kw", [dict(Fa=-1.0), dict(Fz=np.nan), dict(Fa=np.nan), dict(M=np.inf), dict(My=np.inf)])
def test_bad_loads(kw):
    with pytest.raises(InputError):
        load_distribution(bearing("6210"), **({"Fa": 10.0} | kw))


def test_bad_stiffness_mode():
    with pytest.raises(InputError, match="stiffness"):
        load_distribution(bearing("6210"), Fa=1.0, stiffness="wobbly")
