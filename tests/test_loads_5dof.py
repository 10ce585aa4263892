"""Five-degree-of-freedom load distribution (issue 16, item 1): radial loads along y and z, moments in both
planes; equilibrium, symmetry (rotation by a ball pitch and by 90°, mirror), the in-plane restriction, the
high-speed and film forms, and overloads refused naming the loads.

Axes (thermobear.loads.rings): x axial, y radial at ψ = 0 (Fr), z radial at ψ = 90° (Fz); M [N m] loads the
balls at ψ = 0 towards +x (θ > 0 moves that side towards +x), My the right-handed moment about +y (θ_y > 0 moves
the side at ψ = 90° towards +x)."""
import numpy as np
import pytest

import thermobear as tb
from thermobear.contact.geometry import BallBearing, bearing
from thermobear.errors import InputError
from thermobear.loads import film_load_distribution, load_distribution, load_distribution_high_speed
from thermobear.loads.overload import contact_limits
from thermobear.contact.hertz import hertz

STEEL = tb.Material(E=2.1e11, nu=0.3, rho=7850.0)


def ring_forces(brg, ld, arm=None, side="i"):
    """(Fa, Fy, Fz, M, My) the balls' contact loads put on the inner ring (low-speed form, or the high-speed
    form under outer-raceway control, where the inner contacts carry no friction) [N, N m]."""
    R = brg.R_inner_locus if arm is None else arm
    Q, a = (ld.Q_i, ld.alpha_i) if side == "i" else (ld.Q_o, ld.alpha_o)
    c, s = np.cos(ld.psi), np.sin(ld.psi)
    fa, fr = Q * np.sin(a), Q * np.cos(a)
    return np.array([fa.sum(-1), (fr * c).sum(-1), (fr * s).sum(-1), R * (fa * c).sum(-1), R * (fa * s).sum(-1)])


def dgbb(Z, Pd=10e-6):
    return BallBearing(D=11.5e-3, dm=max(43.5e-3, 1.3 * 11.5e-3 / np.sin(np.pi / Z)), Z=Z, fi=0.52, fo=0.53, Pd=Pd,
                       kind="deep_groove", ball_material=STEEL, ring_material=STEEL)


@pytest.mark.parametrize("name, loads", [
    ("iso-dgbb", dict(Fa=300.0, Fr=800.0, Fz=-500.0, M=2.0, My=-3.0)),
    ("6210", dict(Fa=0.0, Fr=-2000.0, Fz=1500.0)),
    ("7210", dict(Fa=1500.0, Fr=400.0, Fz=700.0, My=10.0)),
])
def test_five_loads_are_balanced(name, loads):
    b = bearing(name)
    ld = load_distribution(b, **loads)
    F = ring_forces(b, ld)
    want = [loads.get(k, 0.0) for k in ("Fa", "Fr", "Fz", "M", "My")]
    scale = max(abs(v) for v in want)
    assert np.allclose(F, want, rtol=0, atol=1e-9 * scale)
    assert ld.residual <= 1e-9


@pytest.mark.parametrize("k", [1, 2, 3, 5])
@pytest.mark.parametrize("tilt", [None, "free"])
def test_a_load_turned_by_k_ball_pitches_turns_the_solution(k, tilt):
    """Symmetry (acceptance): a radial load at β = 2πk/Z is the load at 0 turned by β about the axis; the balls
    then carry the loads of the unturned case shifted by k places, displacements and tilts turned by β (1e-9)."""
    b = bearing("iso-dgbb").with_(Pd=10e-6)
    Z, F, m = b.Z, 1000.0, (1.5 if tilt else None)
    beta = 2 * np.pi * k / Z
    c, s = np.cos(beta), np.sin(beta)
    ref = load_distribution(b, Fa=400.0, Fr=F, M=m)
    mz = None if tilt is None else m * c
    my = None if tilt is None else m * s
    rot = load_distribution(b, Fa=400.0, Fr=F * c, Fz=F * s, M=mz, My=my)
    assert np.allclose(rot.Q, np.roll(ref.Q, k), rtol=1e-9, atol=1e-9 * F)
    assert np.allclose(rot.alpha_i, np.roll(ref.alpha_i, k), rtol=0, atol=1e-9)
    assert rot.delta_a == pytest.approx(ref.delta_a, rel=1e-9)
    for (u, v), (u0, v0) in (((rot.delta_r, rot.delta_z), (ref.delta_r, ref.delta_z)),
                             ((rot.theta, rot.theta_y), (ref.theta, ref.theta_y))):
        scale = max(abs(u0), abs(v0), 1e-300)
        assert abs(u - (c * u0 - s * v0)) <= 1e-9 * scale and abs(v - (s * u0 + c * v0)) <= 1e-9 * scale


def test_a_moment_about_y_is_the_moment_in_the_xy_plane_turned_by_90_degrees():
    """With Z = 12 balls a quarter turn maps the balls onto themselves: Fz and My give exactly the solution of
    Fr and M turned by 90° (δz = δr, θ_y = θ, loads shifted by Z/4), to 1e-9 (acceptance)."""
    b = dgbb(12)
    ref = load_distribution(b, Fa=500.0, Fr=900.0, M=4.0)
    rot = load_distribution(b, Fa=500.0, Fz=900.0, My=4.0)
    assert rot.delta_z == pytest.approx(ref.delta_r, rel=1e-9) and abs(rot.delta_r) < 1e-9 * ref.delta_r
    assert rot.theta_y == pytest.approx(ref.theta, rel=1e-9) and abs(rot.theta) < 1e-9 * abs(ref.theta)
    assert np.allclose(rot.Q, np.roll(ref.Q, 3), rtol=1e-9, atol=1e-9 * 900.0)
    # the sign conventions: a positive moment alone, a positive tilt (the side at ψ = 0 / 90° towards +x)
    assert load_distribution(b, Fa=500.0, M=4.0).theta > 0 and load_distribution(b, Fa=500.0, My=4.0).theta_y > 0


def test_mirror_about_the_xy_plane():
    """The balls lie symmetric about the x–y plane (ψ_j and −ψ_j): Fz → −Fz, My → −My mirror δz, θ_y and the
    ball loads (ball j ↔ ball Z − j)."""
    b = bearing("iso-dgbb").with_(Pd=10e-6)
    a = load_distribution(b, Fa=200.0, Fr=700.0, Fz=300.0, My=2.0)
    m = load_distribution(b, Fa=200.0, Fr=700.0, Fz=-300.0, My=-2.0)
    assert m.delta_z == pytest.approx(-a.delta_z, rel=1e-9) and m.theta_y == pytest.approx(-a.theta_y, rel=1e-9)
    assert m.delta_r == pytest.approx(a.delta_r, rel=1e-9) and m.theta == pytest.approx(a.theta, rel=1e-9, abs=1e-15)
    assert np.allclose(m.Q, np.roll(a.Q[::-1], 1), rtol=1e-9, atol=1e-9 * 700.0)


def test_in_plane_cases_solved_with_five_unknowns_equal_the_restricted_solve():
    """One formulation: a batch where one case leaves the x–y plane is solved with five unknowns for every case;
    its in-plane cases then have δz = θ_y = 0 and the solution of the three-unknown solve (the restriction)."""
    b = bearing("7210")
    three = load_distribution(b, Fa=[450.0, 900.0], Fr=[325.0, 200.0], M=[0.0, 3.0])
    five = load_distribution(b, Fa=[450.0, 900.0, 450.0], Fr=[325.0, 200.0, 0.0], Fz=[0.0, 0.0, 325.0],
                             M=[0.0, 3.0, 0.0])
    assert np.allclose(five.Q[:2], three.Q, rtol=1e-10, atol=1e-10)
    assert np.allclose(five.delta_a[:2], three.delta_a, rtol=1e-10)
    assert np.allclose(five.theta[:2], three.theta, rtol=1e-9, atol=1e-15)
    assert np.all(np.abs(five.delta_z[:2]) < 1e-15) and np.all(np.abs(five.theta_y[:2]) < 1e-13)


def test_high_speed_form_in_five_degrees_of_freedom():
    """At speed (outer-raceway control: no friction at the inner contacts) the inner contacts balance all five
    loads; at n = 0 the high-speed form is the static one; a ball-pitch turn of the load turns the solution."""
    b = bearing("7210")
    loads = dict(Fa=900.0, Fr=300.0, Fz=-400.0, M=2.0, My=5.0)
    hs = load_distribution_high_speed(b, n_rpm=8000.0, **loads)
    F = ring_forces(b, hs)
    want = [loads[k] for k in ("Fa", "Fr", "Fz", "M", "My")]
    assert np.allclose(F, want, rtol=0, atol=1e-8 * 900.0)
    assert np.all(hs.Q_o > hs.Q_i)
    rest = load_distribution_high_speed(b, n_rpm=0.0, **loads)
    st = load_distribution(b, **loads)
    assert np.allclose(rest.Q_i, st.Q, rtol=1e-7, atol=1e-8 * 900) and rest.theta_y == pytest.approx(st.theta_y,
                                                                                                     rel=1e-7)
    k, Z = 4, b.Z
    beta = 2 * np.pi * k / Z
    ref = load_distribution_high_speed(b, Fa=900.0, Fr=500.0, n_rpm=8000.0)
    rot = load_distribution_high_speed(b, Fa=900.0, Fr=500.0 * np.cos(beta), Fz=500.0 * np.sin(beta), n_rpm=8000.0)
    assert np.allclose(rot.Q_o, np.roll(ref.Q_o, k), rtol=1e-8, atol=1e-8 * 500)
    assert np.hypot(rot.delta_r, rot.delta_z) == pytest.approx(ref.delta_r, rel=1e-8)


def test_film_form_in_five_degrees_of_freedom():
    b = bearing("7210")
    ld = film_load_distribution(b, 450.0, 500.0, Fz=400.0, My=2.0, u_i=8.6, u_o=8.6, eta=0.0221, alpha_p=2e-8)
    assert ld.residual <= 1e-10 and np.all(ld.Q > 0)
    assert np.allclose(ring_forces(b, ld), [450.0, 500.0, 400.0, 0.0, 2.0], rtol=0, atol=1e-9 * 500)


@pytest.mark.parametrize("name, loads", [
    ("6208", dict(Fa=1e6)),                      # far beyond the pressure limit
    ("6208", dict(Fa=1e3, Fr=1e3, M=1e6)),
    ("iso-dgbb", dict(Fa=0.0, Fr=2e5, Fz=2e5)),
    ("7210", dict(Fa=1e8, Fr=1e5)),
    ("6208", dict(Fa=0.0, Fr=5.3e4)),            # beyond only on the solved contacts (not before the solve)
    ("6208", dict(Fa=0.0, Fr=1e3, Fz=5.3e4)),
])
def test_an_overload_is_an_input_error_naming_the_loads(name, loads):
    """Acceptance: a load the contacts cannot carry is refused by name (never a solver traceback), by the
    limits of thermobear.validity (p_max beyond twice the ISO 76 rating, or the ellipse over the groove edge):
    before the solve where no ball set can carry it, else on the solution."""
    msg = r"^((Fa|Fr|M) = \S+|Fa, Fr, M = 'Fa \S+ N, Fr \S+ N.*') — maximum contact pressure \S+ MPa must lie in \[0, 5292\]"
    with pytest.raises(InputError, match=msg):
        load_distribution(bearing(name), **loads)
    with pytest.raises(InputError, match=msg):
        load_distribution(bearing(name), n_rpm=3000.0, **loads)


def test_the_contact_ellipse_over_the_groove_edge_is_refused_below_the_pressure_limit():
    """Truncation: wide, conforming grooves (f = 0.505) keep p_max low while the ellipse grows; under a heavy
    axial load its far end passes the groove's equator (|α| + a/(f D) > 90°) before p_max reaches its limit."""
    b = BallBearing(D=12.7e-3, dm=65e-3, Z=10, fi=0.505, fo=0.505, Pd=20e-6, kind="deep_groove",
                    ball_material=STEEL, ring_material=STEEL)
    F = np.geomspace(1e3, 3e5, 40)
    ld = load_distribution(b, Fa=F, refuse_overload=False)
    lim = contact_limits(b, ld.Q_i, ld.Q_o, ld.alpha_i, ld.alpha_o)
    p = np.maximum(lim["inner"][0].max(-1), lim["outer"][0].max(-1))
    reach = np.maximum(lim["inner"][1].max(-1), lim["outer"][1].max(-1))
    k = int(np.argmax(reach > np.pi / 2))
    assert reach[k] > np.pi / 2 and p[k] < tb.validity.P_MAX_REFUSE_PA
    with pytest.raises(InputError, match=r"contact angle \+ half the contact ellipse, from the groove bottom 9\d\.\d+ deg"):
        load_distribution(b, Fa=F[k])
    load_distribution(b, Fa=F[k - 1])                               # just inside: solved


def test_contact_limits_are_the_hertz_contacts():
    b = bearing("6208")
    lim = contact_limits(b, [2000.0, 0.0], [2500.0, 0.0], [0.2, 0.0], [0.1, 0.0])
    ci = hertz(2000.0, b.Rx_i(0.2), b.Ry_i, b.E_prime)
    co = hertz(2500.0, b.Rx_o(0.1), b.Ry_o, b.E_prime)
    assert lim["inner"][0][0] == pytest.approx(ci.p_max, rel=1e-12)
    assert lim["outer"][1][0] == pytest.approx(0.1 + co.a / (b.fo * b.D), rel=1e-12)
    assert lim["inner"][0][1] == 0.0 and lim["outer"][1][1] == 0.0


def test_tilts_held_without_a_moment_free_with_either():
    b = bearing("iso-dgbb").with_(Pd=10e-6)
    held = load_distribution(b, Fa=1000.0, Fr=1000.0, Fz=300.0)
    assert held.theta == 0.0 and held.theta_y == 0.0
    free = load_distribution(b, Fa=1000.0, Fr=1000.0, Fz=300.0, My=0.0)
    assert free.theta != 0.0 and free.theta_y != 0.0
    assert np.allclose(ring_forces(b, free)[3:], 0.0, atol=1e-9 * 1000 * b.R_inner_locus)


def test_tilt_arm_pitch_uses_the_pitch_radius():
    """tilt_arm="pitch": A1 = δa + (d_m/2)(θ cos ψ + θ_y sin ψ) and M = (d_m/2) Σ Q sin α cos ψ."""
    b = bearing("iso-dgbb").with_(Pd=10e-6)
    ld = load_distribution(b, Fa=1000.0, Fr=1000.0, M=1.0, tilt_arm="pitch")
    assert np.allclose(ring_forces(b, ld, arm=0.5 * b.dm), [1000.0, 1000.0, 0.0, 1.0, 0.0], atol=1e-9 * 1000)
    A1 = ld.delta_a + 0.5 * b.dm * ld.theta * np.cos(ld.psi)
    A2 = b.A * np.cos(b.alpha0) + ld.delta_r * np.cos(ld.psi)
    assert np.allclose(np.arctan2(A1, A2)[ld.Q > 0], ld.alpha_i[ld.Q > 0], rtol=0, atol=1e-12)
    with pytest.raises(InputError, match="tilt_arm"):
        load_distribution(b, Fa=1.0, tilt_arm="shaft")


@pytest.mark.parametrize("control", ["inner", "both"])
def test_high_speed_friction_rows_turn_with_the_load(control):
    """With gyroscopic friction at the inner contacts (control "inner" / "both") the ring equations carry the
    friction forces and couples in both planes: a load turned by k ball pitches (with its moment) gives the
    turned solution."""
    b = bearing("7210")
    k, Z = 2, b.Z
    beta = 2 * np.pi * k / Z
    c, s = np.cos(beta), np.sin(beta)
    ref = load_distribution_high_speed(b, Fa=1500.0, Fr=400.0, M=3.0, n_rpm=6000.0, control=control)
    rot = load_distribution_high_speed(b, Fa=1500.0, Fr=400.0 * c, Fz=400.0 * s, M=3.0 * c, My=3.0 * s,
                                       n_rpm=6000.0, control=control)
    assert np.allclose(rot.Q_i, np.roll(ref.Q_i, k), rtol=1e-7, atol=1e-8 * 1500)
    assert np.allclose(rot.Q_o, np.roll(ref.Q_o, k), rtol=1e-7, atol=1e-8 * 1500)
    assert rot.theta * c + rot.theta_y * s == pytest.approx(ref.theta, rel=1e-7)
    assert np.hypot(rot.delta_r, rot.delta_z) == pytest.approx(ref.delta_r, rel=1e-7)
