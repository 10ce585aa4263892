"""High-speed Jones–Harris load distribution (issue 2, item 5): the n = 0 limit, symmetry,
ball and ring equilibrium, an independent solution of Jones's (1960) ball equations written with
Harris's (2001, §8.2) sign convention, speed trends, batching, and named failures."""
import dataclasses

import numpy as np
import pytest
from scipy.optimize import fsolve

import thermobear as tb
from thermobear.errors import InputError, NoEquilibrium
from thermobear.contact.geometry import BallBearing, bearing
from thermobear.loads import load_distribution
from thermobear.loads.highspeed import load_distribution_high_speed, load_distribution_high_speed_full

from _highspeed_checks import assert_ball_centres
from _newton_fd import assert_newton_matches_fd

STEEL = tb.Material(E=2.075e11, nu=0.3, rho=7850.0)


def b218():
    """Harris's 218 angular contact example (Harris 2001 worked example; inputs as recalled, not confirmed
    against the book)."""
    return BallBearing(D=22.23e-3, dm=125.3e-3, Z=16, fi=0.5232, fo=0.5232, alpha0=np.deg2rad(40.0),
                       kind="angular_contact", ball_material=STEEL, ring_material=STEEL, name="218")


def rel(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    return np.max(np.abs(a - b)) / max(np.max(np.abs(b)), 1e-300)


@pytest.mark.parametrize("name, Fa, Fr, M", [
    ("7210", 450.0, 0.0, None),
    ("7210", 450.0, 300.0, None),
    ("7210", 2000.0, 1000.0, 20.0),
    ("6210", 0.0, 2000.0, None),          # deep groove with clearance: half the balls unloaded
    ("6210", 500.0, 2000.0, None),
    ("51107", 7000.0, 0.0, None),
    ("51107", 7000.0, 0.0, 30.0),
])
@pytest.mark.parametrize("stiffness", ["nominal", "per_ball"])
def test_zero_speed_is_the_low_speed_solution(name, Fa, Fr, M, stiffness):
    b = bearing(name)
    ls = load_distribution(b, Fa=Fa, Fr=Fr, M=M, stiffness=stiffness)
    hs = load_distribution_high_speed(b, Fa=Fa, Fr=Fr, M=M, n_rpm=0.0, stiffness=stiffness)
    Qs = ls.Q.max()
    assert np.max(np.abs(hs.Q_i - ls.Q)) <= 1e-8 * Qs
    assert np.max(np.abs(hs.Q_o - ls.Q)) <= 1e-8 * Qs
    loaded = ls.Q > 1e-6 * Qs
    assert rel(hs.alpha_i[loaded], ls.alpha_i[loaded]) < 1e-8
    assert rel(hs.alpha_o[loaded], ls.alpha_i[loaded]) < 1e-8
    assert hs.delta_a == pytest.approx(ls.delta_a, rel=1e-8, abs=1e-8 * b.A)
    assert hs.delta_r == pytest.approx(ls.delta_r, rel=1e-8, abs=1e-8 * b.A)
    assert hs.theta == pytest.approx(ls.theta, rel=1e-8, abs=1e-12)
    # and the limit is continuous: a crawl speed moves the loads by a tiny amount only
    crawl = load_distribution_high_speed(b, Fa=Fa, Fr=Fr, M=M, n_rpm=1.0, stiffness=stiffness)
    assert np.max(np.abs(crawl.Q_o - ls.Q)) <= 1e-5 * Qs
    assert crawl.residual <= 1e-9


def test_pure_axial_load_gives_identical_balls():
    ld, ex = load_distribution_high_speed_full(b218(), Fa=17800.0, n_rpm=15000.0)
    for v in (ld.Q_i, ld.Q_o, ld.alpha_i, ld.alpha_o, ex.Fc, ex.Mg, ex.X1, ex.X2):
        assert np.ptp(v) <= 1e-9 * np.max(np.abs(v))
    assert abs(ld.delta_r) < 1e-12 and ld.theta == 0.0


def _pure_axial_reference(brg, Fa, n_rpm):
    """Jones (1960) / Harris (2001) §8.2 ball and ring equations for identical balls (Harris's β and M_g signs,
    squared distances, cos/sin from X and δ) with Harris's kinematic formulas of §4, solved by
    scipy's fsolve: an independent route to the same answer (outer-raceway control)."""
    D, dm, Z, A = brg.D, brg.dm, brg.Z, brg.A
    fi, fo = brg.fi, brg.fo
    Ki, Ko = float(brg.K_i(brg.alpha0)), float(brg.K_o(brg.alpha0))
    m = brg.ball_mass
    J = m * D**2 / 10.0
    w = n_rpm * np.pi / 30.0
    gp = D / dm
    A2 = A * np.cos(brg.alpha0)

    def eqs(u):
        X1, X2, di, do, da = u[0] * A, u[1] * A, u[2] * A, u[3] * A, u[4] * A
        A1 = da
        ri, ro = (fi - 0.5) * D + di, (fo - 0.5) * D + do
        co, so = X2 / ro, X1 / ro
        ci, si = (A2 - X2) / ri, (A1 - X1) / ri
        ao, ai = np.arctan2(so, co), np.arctan2(si, ci)
        tb_ = np.sin(ao) / (np.cos(ao) + gp)                  # tan β_Harris, outer control
        bH = np.arctan(tb_)
        num = (1 - gp * np.cos(ai)) * (np.cos(ao) + tb_ * np.sin(ao))
        den = (1 + gp * np.cos(ao)) * (np.cos(ai) + tb_ * np.sin(ai)) + num
        wm = w * num / den
        wR = -w / (gp * np.cos(bH) * ((np.cos(ao) + tb_ * np.sin(ao)) / (1 + gp * np.cos(ao))
                                      + (np.cos(ai) + tb_ * np.sin(ai)) / (1 - gp * np.cos(ai))))
        Fc = 0.5 * m * dm * wm**2
        MgH = J * wR * wm * np.sin(bH)
        Qi, Qo = Ki * max(di, 0) ** 1.5, Ko * max(do, 0) ** 1.5
        li, lo = 0.0, 2.0
        s = Fa / Z
        return [((A1 - X1) ** 2 + (A2 - X2) ** 2 - ri**2) / A**2,
                (X1**2 + X2**2 - ro**2) / A**2,
                (Qi * si - Qo * so - MgH / D * (li * ci - lo * co)) / s,
                (Qi * ci - Qo * co + MgH / D * (li * si - lo * so) + Fc) / s,
                (Z * (Qi * si - li * MgH / D * ci) - Fa) / Fa]

    ls = load_distribution(brg, Fa=Fa)
    a, dn = ls.alpha_i[0], ls.delta_n[0]
    ro = (fo - 0.5) * D + dn / 2
    u0 = [ro * np.sin(a) / A, ro * np.cos(a) / A, dn / 2 / A, dn / 2 / A, ls.delta_a / A]
    u, info, ier, msg = fsolve(eqs, u0, full_output=True, xtol=1e-13)
    assert ier == 1, msg
    X1, X2, di, do = u[0] * A, u[1] * A, u[2] * A, u[3] * A
    ai = np.arctan2(u[4] * A - X1, A2 - X2)
    ao = np.arctan2(X1, X2)
    return ai, ao, Ki * di**1.5, Ko * do**1.5, u[4] * A


@pytest.mark.parametrize("n_rpm", [5000.0, 12000.0, 20000.0])
def test_pure_axial_matches_independent_harris_form(n_rpm):
    b = b218()
    ai, ao, Qi, Qo, da = _pure_axial_reference(b, 17800.0, n_rpm)
    ld = load_distribution_high_speed(b, Fa=17800.0, n_rpm=n_rpm)
    assert ld.alpha_i[0] == pytest.approx(ai, rel=1e-7)
    assert ld.alpha_o[0] == pytest.approx(ao, rel=1e-7)
    assert ld.Q_i[0] == pytest.approx(Qi, rel=1e-7)
    assert ld.Q_o[0] == pytest.approx(Qo, rel=1e-7)
    assert ld.delta_a == pytest.approx(da, rel=1e-7)


@pytest.mark.parametrize("control", ["outer", "inner", "both"])
def test_ball_and_ring_equilibrium_from_returned_fields(control):
    b = b218()
    Fa, Fr, M = 17800.0, 6000.0, 150.0
    ld, ex = load_distribution_high_speed_full(b, Fa=Fa, Fr=Fr, M=M, n_rpm=9000.0, control=control)
    assert ld.residual <= 1e-10 and ld.iterations > 0
    ai, ao, Qi, Qo = ld.alpha_i, ld.alpha_o, ld.Q_i, ld.Q_o
    li, lo, D = ex.lambda_i, ex.lambda_o, b.D
    G = ex.Mg / D
    # ball: forces of both rings, friction that carries the gyroscopic couple, centrifugal force
    fx = Qi * np.sin(ai) - Qo * np.sin(ao) + G * (li * np.cos(ai) - lo * np.cos(ao))
    fr = Qi * np.cos(ai) - Qo * np.cos(ao) - G * (li * np.sin(ai) - lo * np.sin(ao)) + ex.Fc
    assert np.max(np.abs(fx)) < 1e-8 * Fa and np.max(np.abs(fr)) < 1e-8 * Fa
    # inner ring
    c, R = np.cos(ld.psi), b.R_inner_locus
    fa_j = Qi * np.sin(ai) + li * G * np.cos(ai)
    assert fa_j.sum() == pytest.approx(Fa, rel=1e-9)
    assert ((Qi * np.cos(ai) - li * G * np.sin(ai)) * c).sum() == pytest.approx(Fr, rel=1e-9)
    assert ((fa_j * R - li * b.fi * ex.Mg) * c).sum() == pytest.approx(M, rel=1e-8)
    # geometry: ball centre on both contact normals
    assert_ball_centres(b, ld, ex)
    # Hertz
    assert np.allclose(Qi, b.K_i(b.alpha0) * np.maximum(ex.delta_i, 0) ** 1.5, rtol=1e-12)


def test_friction_couple_equals_gyroscopic_moment():
    # 3-D check of the sign derivation: the friction forces the model applies at the contact
    # points give, about the ball centre, the moment dH/dt = ω_c x̂ × J ω_b of the spinning ball.
    b = b218()
    ld, ex = load_distribution_high_speed_full(b, Fa=17800.0, n_rpm=15000.0, control="both")
    ai, ao, D, G = ld.alpha_i[0], ld.alpha_o[0], b.D, ex.Mg[0] / b.D
    x, r = np.array([1.0, 0, 0]), np.array([0, 1.0, 0])          # t̂ = x̂ × r̂ = ẑ
    n_i, n_o = np.sin(ai) * x + np.cos(ai) * r, np.sin(ao) * x + np.cos(ao) * r
    e_i, e_o = np.cos(ai) * x - np.sin(ai) * r, np.cos(ao) * x - np.sin(ao) * r
    F_i, F_o = ex.lambda_i * G * e_i, -ex.lambda_o * G * e_o          # friction on the ball
    couple = np.cross(-D / 2 * n_i, F_i) + np.cross(D / 2 * n_o, F_o)
    w_b = ex.omega_R[0] * (np.cos(ex.beta[0]) * x + np.sin(ex.beta[0]) * r)
    dHdt = np.cross(ex.omega_c[0] * x, b.ball_mass * D**2 / 10 * w_b)
    assert np.allclose(couple, dHdt, rtol=1e-12, atol=1e-12 * abs(ex.Mg[0]))
    assert abs(ex.Mg[0]) > 0.1


def test_trends_with_speed():
    b = b218()
    n = np.array([0.0, 2500.0, 5000.0, 10000.0, 15000.0, 20000.0])
    ld, ex = load_distribution_high_speed_full(b, Fa=17800.0, n_rpm=n)
    ai, ao, Qi, Qo = ld.alpha_i[:, 0], ld.alpha_o[:, 0], ld.Q_i[:, 0], ld.Q_o[:, 0]
    assert np.all(np.diff(ao) < 0) and np.all(np.diff(ai) > 0)        # α_o falls, α_i rises
    assert np.all(np.diff(Qo - Qi) > 0) and np.all((Qo > Qi)[1:])
    assert np.all(np.diff(ex.Fc[:, 0]) > 0)
    assert ai[-1] - ao[-1] > np.deg2rad(20)                          # strongly split at n dm = 2.5e6
    # Fc ∝ ω_c²: at fixed angles it would scale with n²; the actual ratio stays close to it
    assert ex.Fc[2, 0] / ex.Fc[1, 0] == pytest.approx(4.0, rel=0.05)


def test_batch_equals_single():
    b = bearing("7210")
    Fa = np.array([300.0, 800.0, 2000.0])
    Fr = np.array([[0.0], [400.0]])
    n = 12000.0
    batch = load_distribution_high_speed(b, Fa=Fa, Fr=Fr, n_rpm=n)
    assert batch.Q_i.shape == (2, 3, b.Z)
    for i in range(2):
        for j in range(3):
            one = load_distribution_high_speed(b, Fa=Fa[j], Fr=Fr[i, 0], n_rpm=n)
            assert np.allclose(batch.Q_i[i, j], one.Q_i, rtol=1e-8, atol=1e-9 * Fa[j])
            assert np.allclose(batch.alpha_o[i, j], one.alpha_o, rtol=1e-8)
            assert batch.delta_a[i, j] == pytest.approx(one.delta_a, rel=1e-9)


def test_a_dry_solve_started_from_a_nearby_answer_is_the_same_answer_in_fewer_steps():
    """start= without the film: Newton from the answer of nearby loads (an outer iteration's last step) reaches the
    answer of the static start, to the tolerance, in fewer iterations; a start it cannot bring to the tolerance in
    the allowed iterations leaves the batch to the static start, the same answer."""
    b = bearing("7014C")
    Fa, Fr, n = np.array([800.0, 2500.0]), np.array([300.0, 1000.0]), 12000.0
    near = load_distribution_high_speed_full(b, Fa=Fa * 1.01, Fr=Fr * 0.99, n_rpm=n)
    cold = load_distribution_high_speed_full(b, Fa=Fa, Fr=Fr, n_rpm=n)
    warm = load_distribution_high_speed_full(b, Fa=Fa, Fr=Fr, n_rpm=n, start=near)
    for k in ("Q_i", "Q_o", "alpha_i", "alpha_o", "delta_a", "delta_r"):
        assert rel(getattr(warm[0], k), getattr(cold[0], k)) < 1e-8, k
    assert rel(warm[1].omega_c, cold[1].omega_c) < 1e-10
    assert warm[0].iterations < cold[0].iterations and warm[0].residual < 1e-10
    # the rings 50 times as far in as the nearby answer's: Newton fails from there; the static start's answer
    far = (dataclasses.replace(near[0], delta_a=near[0].delta_a * 50.0), near[1])
    fell_back = load_distribution_high_speed_full(b, Fa=Fa, Fr=Fr, n_rpm=n, start=far)
    assert np.array_equal(fell_back[0].Q_i, cold[0].Q_i) and fell_back[0].iterations == cold[0].iterations


@pytest.mark.parametrize("kw, field", [
    (dict(control="cage"), "control"),
    (dict(stiffness="soft"), "stiffness"),
    (dict(n_rpm=-100.0), "n_rpm"),
    (dict(n_rpm=np.nan), "n_rpm"),
    (dict(tol=0.0), "tol"),
    (dict(maxiter=0), "maxiter"),
    (dict(Fa=-5.0), "Fa"),
])
def test_bad_input_raises_input_error(kw, field):
    args = dict(Fa=450.0, n_rpm=1000.0)
    args.update(kw)
    with pytest.raises(InputError) as e:
        load_distribution_high_speed(bearing("7210"), **args)
    assert e.value.field == field


def test_radial_load_on_thrust_bearing_raises_no_equilibrium():
    with pytest.raises(NoEquilibrium):
        load_distribution_high_speed(bearing("51107"), Fa=7000.0, Fr=100.0, n_rpm=1000.0)
    with pytest.raises(NoEquilibrium):
        load_distribution_high_speed(bearing("51107"), Fa=0.0, n_rpm=1000.0)   # no minimum load


def test_inner_control_friction_beyond_axial_load_raises_no_equilibrium():
    # λ_i = 2 puts Z·2(M_g/D)cos α_i on the inner ring axially; above F_a no positive Q_i balances it
    with pytest.raises(NoEquilibrium, match="gyroscopic"):
        load_distribution_high_speed(bearing("7210"), Fa=10.0, n_rpm=20000.0, control="inner")
    ld = load_distribution_high_speed(bearing("7210"), Fa=10.0, n_rpm=20000.0, control="outer")
    assert ld.residual <= 1e-10 and np.all(ld.Q_i > 0)


def test_no_load_at_speed_presses_balls_on_the_outer_race():
    b = bearing("6210")
    ld, ex = load_distribution_high_speed_full(b, Fa=0.0, Fr=0.0, n_rpm=6000.0)
    assert np.all(ld.Q_i == 0.0)
    assert np.allclose(ld.Q_o, ex.Fc, rtol=1e-9)
    assert ld.delta_a == 0.0 and ld.delta_r == 0.0


def test_one_cage_speed_and_unloaded_balls_pressed_by_their_centrifugal_force():
    # combined load at speed: the balls' own no-slip orbital speeds differ by > 50 % between the
    # loaded and the lightly loaded balls; a rigid cage makes them orbit together, and a ball with
    # an open inner contact rests on the outer race with its centrifugal force at the cage speed
    b = tb.bearing("7210")
    ld, ex = load_distribution_high_speed_full(b, Fa=450.0, Fr=750.0, n_rpm=4800.0)
    assert np.ptp(ex.omega_c) <= 1e-12 * np.max(ex.omega_c)
    free = ld.Q_i == 0
    assert free.any()
    Fc = 0.5 * b.ball_mass * b.dm * ex.omega_c[free] ** 2
    np.testing.assert_allclose(ld.Q_o[free] * np.cos(ld.alpha_o[free]), Fc, rtol=0.02)
    # the cage speed is the load-weighted mean of the loaded balls' own speeds: between their extremes
    from thermobear.contact.kinematics import ball_kinematics
    own = ball_kinematics(4800 * np.pi / 30, 0.0, ld.alpha_i, ld.alpha_o, b.D, b.dm).omega_c
    assert own[~free].min() <= ex.omega_c[0] <= own[~free].max()


# --- robustness and exactness of the solver (one cage, analytic Jacobian) ---------------------------

def _assert_equilibrium(b, ld, ex, Fa, Fr, M=0.0, rtol=1e-8):
    """Every ball and ring equation, re-evaluated from the returned fields (forces in N)."""
    ai, ao, Qi, Qo = ld.alpha_i, ld.alpha_o, ld.Q_i, ld.Q_o
    li, lo, D = ex.lambda_i, ex.lambda_o, b.D
    G = ex.Mg / D
    scale = max(Fa, Fr, float(np.max(ex.Fc)))
    fx = Qi * np.sin(ai) - Qo * np.sin(ao) + G * (li * np.cos(ai) - lo * np.cos(ao))
    fr = Qi * np.cos(ai) - Qo * np.cos(ao) - G * (li * np.sin(ai) - lo * np.sin(ao)) + ex.Fc
    assert np.max(np.abs(fx)) < rtol * scale and np.max(np.abs(fr)) < rtol * scale
    c = np.cos(ld.psi)
    fa_j = Qi * np.sin(ai) + li * G * np.cos(ai)
    assert abs(fa_j.sum() - Fa) < rtol * scale
    assert abs(((Qi * np.cos(ai) - li * G * np.sin(ai)) * c).sum() - Fr) < rtol * scale
    # the geometry the loads come from: ball centre on both contact normals, Hertz at both contacts
    A1 = ld.delta_a + b.R_inner_locus * ld.theta * c
    A2 = b.A * np.cos(b.alpha0) + ld.delta_r * c
    ri, ro = (b.fi - 0.5) * D + ex.delta_i, (b.fo - 0.5) * D + ex.delta_o
    loaded = (Qi > 0) & (Qo > 0)
    assert np.allclose((A1 - ex.X1)[loaded], (ri * np.sin(ai))[loaded], rtol=1e-9, atol=1e-15)
    assert np.allclose((A2 - ex.X2)[loaded], (ri * np.cos(ai))[loaded], rtol=1e-9, atol=1e-15)
    assert np.allclose(ex.X1, ro * np.sin(ao), rtol=1e-9, atol=1e-15)
    an = b.alpha_nominal
    assert np.allclose(Qi, b.K_i(an) * np.maximum(ex.delta_i, 0) ** 1.5, rtol=1e-12)
    assert np.allclose(Qo, b.K_o(an) * np.maximum(ex.delta_o, 0) ** 1.5, rtol=1e-12)


@pytest.mark.parametrize("name, Fa, Frs", [
    ("7210", 450.0, [0.0, 25.0, 100.0, 300.0, 325.0, 450.0, 540.0, 650.0, 750.0, 1000.0, 1500.0]),
    ("7210", 225.0, [0.0, 300.0, 650.0, 1500.0]),
    ("6210", 0.0, [100.0, 1000.0, 3000.0]),
    ("6210", 300.0, [100.0, 1000.0, 3000.0]),
])
def test_load_speed_grid_converges(name, Fa, Frs):
    # combined loads from no to heavy radial load, 50 … 20 000 rpm, one batched call: balls leave the
    # load zone, rest on the outer race or wedge between both races (before the polar step, the
    # contact-closing limit and the placed start, 5 of these cases raised NoConvergence)
    b = bearing(name)
    Fr = np.array(Frs)[:, None]
    n = np.array([50.0, 1000.0, 3200.0, 4800.0, 6500.0, 8070.0, 12000.0, 20000.0])
    ld, ex = load_distribution_high_speed_full(b, Fa=Fa, Fr=Fr, n_rpm=n)
    assert ld.residual <= 1e-10
    assert np.all(ld.Q_o > 0)                     # at n > 0 every ball is pressed on the outer race
    assert np.ptp(ex.omega_c, axis=-1).max() <= 1e-12 * ex.omega_c.max()


@pytest.mark.parametrize("Fa, Fr, n", [(450.0, 450.0, 50.0), (450.0, 540.0, 50.0), (450.0, 650.0, 50.0),
                                       (450.0, 650.0, 1000.0), (225.0, 300.0, 50.0)])
def test_formerly_failing_cases_satisfy_every_equation(Fa, Fr, n):
    b = bearing("7210")
    ld, ex = load_distribution_high_speed_full(b, Fa=Fa, Fr=Fr, n_rpm=n)
    _assert_equilibrium(b, ld, ex, Fa, Fr)
    # the load zone is where it belongs: the heaviest ball at ψ = 0, symmetric about it
    assert np.argmax(ld.Q_i) == 0
    assert np.allclose(ld.Q_i[1:], ld.Q_i[1:][::-1], rtol=1e-6, atol=1e-9 * Fa)


def test_out_of_zone_balls_wedged_with_loads_of_the_order_of_their_centrifugal_force():
    # 50 rpm: F_c ≈ 1.5 mN.  A ball outside the load zone cannot rest on the outer race alone (it
    # would sit in the axially offset inner groove); it is wedged between both races with loads
    # of the order of F_c — not the kN loads of a ball pushed straight out by F_c
    b = bearing("7210")
    ld, ex = load_distribution_high_speed_full(b, Fa=450.0, Fr=650.0, n_rpm=50.0)
    out = ld.Q_o < 1e-3 * ld.Q_o.max()
    assert out.sum() >= 6
    assert np.all(ld.Q_i[out] > 0)
    ratio = ld.Q_o[out] / ex.Fc[out]
    assert np.all((ratio > 1.0) & (ratio < 10.0))
    assert np.all(ld.alpha_i[out] - ld.alpha_o[out] > np.deg2rad(5))   # two distinct contact normals
    _assert_equilibrium(b, ld, ex, 450.0, 650.0)


@pytest.mark.parametrize("control", ["outer", "inner", "both"])
def test_kinematics_agree_with_the_kinematics_module(control):
    # the solver evaluates β, the own orbital speeds, ω_R with sin/cos of the contact normals and
    # analytic derivatives; thermobear.contact.kinematics computes them from the angles
    from thermobear.contact.kinematics import ball_kinematics, caged_ball_kinematics, common_cage_speed
    b = bearing("7210")
    ld, ex = load_distribution_high_speed_full(b, Fa=450.0, Fr=540.0, n_rpm=6500.0, control=control)
    w = 6500.0 * np.pi / 30
    kc = "inner" if control == "inner" else "outer"
    own = ball_kinematics(w, 0.0, ld.alpha_i, ld.alpha_o, b.D, b.dm, control=kc)
    wc = common_cage_speed(own.omega_c, ld.Q_i)
    np.testing.assert_allclose(ex.omega_c, wc, rtol=1e-12)
    caged = caged_ball_kinematics(w, 0.0, ld.alpha_i, ld.alpha_o, b.D, b.dm, wc, ld.Q_i, ld.Q_o, control=kc)
    np.testing.assert_allclose(ex.omega_R, caged.omega_R, rtol=1e-10)
    np.testing.assert_allclose(ex.beta, own.beta, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(ex.Fc, 0.5 * b.ball_mass * b.dm * wc**2, rtol=1e-12)
    np.testing.assert_allclose(ex.Mg, b.ball_mass * b.D**2 / 10 * ex.omega_R * wc * np.sin(ex.beta), rtol=1e-12)


@pytest.mark.parametrize("control, Fr, n", [("outer", 325.0, 3200.0), ("inner", 325.0, 3200.0),
                                            ("both", 325.0, 8000.0), ("outer", 1500.0, 1000.0)])
def test_newton_direction_is_exact(control, Fr, n, monkeypatch):
    # the analytic Jacobian (contacts, kinematics, the cage as a rank-one coupling) gives the same
    # Newton direction as central finite differences of the residual, at the start of the solve
    import thermobear.loads.highspeed as lh
    b = bearing("7210")
    seen = {}
    orig = lh.newton

    def spy(pb, z, opt, state=None):
        seen.setdefault("args", (pb, z.copy()))
        return orig(pb, z, opt, state)

    monkeypatch.setattr(lh, "newton", spy)
    load_distribution_high_speed_full(b, Fa=450.0, Fr=Fr, n_rpm=n, control=control)
    pb, z = seen["args"]
    assert_newton_matches_fd(pb, z, rtol=1e-5)


def test_seed004_point_converges_quadratically():
    # Fa 450 N, Fr 325 N, 3200 rpm (seed 004): exact Newton from the placed start
    ld = load_distribution_high_speed(bearing("7210"), Fa=450.0, Fr=325.0, n_rpm=3200.0)
    assert ld.residual <= 1e-13
    assert ld.iterations <= 10


@pytest.mark.parametrize("control", ["outer", "inner"])
@pytest.mark.parametrize("load_model", ["jones_harris", "film"])
def test_scene_loads_and_kinematics_share_the_raceway_control(control, load_model):
    # Jones (1960): the raceway control sets β and the gyroscopic moment's share in the ball equilibrium *and*
    # the ball's kinematics; a scene's models.kinematics must reach the high-speed loads as well as the contacts
    # (before: the loads always took outer control, inconsistent with models.kinematics = "inner")
    from thermobear.coupled import scene_contacts, solve
    from thermobear.models import plan_many
    sc = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")).with_(
        n_rpm=6500.0, T_C=50.0, models={"high_speed": True, "kinematics": control, "load_model": load_model})
    (alt,) = plan_many([sc])[0]
    cs = scene_contacts(sc, alt.models)
    ref, ex = load_distribution_high_speed_full(sc.bearing, Fa=sc.Fa, Fr=sc.Fr, n_rpm=6500.0, control=control)
    other = "inner" if control == "outer" else "outer"
    _, ex_other = load_distribution_high_speed_full(sc.bearing, Fa=sc.Fa, Fr=sc.Fr, n_rpm=6500.0, control=other)
    w, w_same, w_other = (float(np.mean(x)) for x in (cs.omega_cage, ex.omega_c, ex_other.omega_c))
    assert abs(w_other / w_same - 1) > 0.05                      # the two hypotheses' cages differ: the test can tell
    if load_model == "jones_harris":
        assert rel(cs.load.Q_i, ref.Q_i) < 1e-8 and rel(cs.load.alpha_o, ref.alpha_o) < 1e-8
        assert w == pytest.approx(w_same, rel=1e-9)
    else:                                                        # the films move the cage a little, not across
        assert abs(w - w_same) < 0.1 * abs(w_other - w_same)
    assert solve(sc).P_W > 0


def test_high_speed_form_refuses_a_raceway_control_it_has_not():
    sc = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")).with_(
        n_rpm=6500.0, T_C=50.0, models={"high_speed": True, "kinematics": "radial"})
    with pytest.raises(InputError, match="models.kinematics"):
        tb.choose_models(sc)
