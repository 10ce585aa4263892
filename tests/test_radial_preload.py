"""A radial preload: a deep groove bearing with a negative operating clearance in every load-solver form
(BallBearing.A_r0 = A − P_d/2 in thermobear.loads.static, .film, .highspeed), its limits and its power."""
import numpy as np
import pytest

import thermobear as tb
from thermobear.contact.fits import clearance_preload
from thermobear.loads import load_distribution
from thermobear.loads.highspeed import load_distribution_high_speed_full
from thermobear.loads.static import ring_reaction

B = tb.bearing("6208")
UM = 1e-6
FILM = dict(eta=0.02, alpha_p=2e-8)


def preloaded(Pd):
    return B.with_(Pd=Pd)


@pytest.mark.parametrize("form", ["static", "high_speed"])
@pytest.mark.parametrize("Pd_um", [-0.5, -8.0, -30.0])
def test_unloaded_every_ball_carries_the_clearance_preload(form, Pd_um):
    """No load, rings centred: each ball compressed by −P_d/2, Q_0 = K_n (−P_d/2)^1.5 (analytic limit; the
    high-speed form at rest splits the approach between its two contacts, K_i δ_i^1.5 = K_o δ_o^1.5)."""
    ld = load_distribution(preloaded(Pd_um * UM), 0.0, 0.0, form=form)
    Q0 = float(clearance_preload(B, Pd_um * UM))
    assert Q0 == pytest.approx(B.Kn() * (-Pd_um * UM / 2) ** 1.5, rel=1e-12)
    for Q in (ld.Q_i, ld.Q_o):
        assert np.allclose(Q, Q0, rtol=1e-9, atol=0)                     # every ball the same (symmetry)
    assert np.all(np.abs(ld.alpha_i) < 1e-9) and float(ld.delta_r) == 0.0 and float(ld.delta_a) == 0.0
    assert np.allclose(ld.delta_n, -Pd_um * UM / 2, rtol=1e-9)


def test_at_speed_the_outer_contacts_carry_the_centrifugal_force_on_the_preload():
    """At 8000 rpm without load the balls stay equal; the approaches of the two contacts still add up to the
    compression −P_d/2 (contact angle 0) and the outer contact carries F_c = ½ m d_m ω_c² more."""
    b = preloaded(-8 * UM)
    ld, ex = load_distribution_high_speed_full(b, 0.0, 0.0, n_rpm=8000.0)
    Ki, Ko, _ = B.K_nominal
    approach = (ld.Q_i / Ki) ** (2 / 3) + (ld.Q_o / Ko) ** (2 / 3)
    assert np.allclose(approach, 4 * UM, rtol=1e-8)
    Fc = 0.5 * B.ball_mass * B.dm * np.asarray(ex.omega_c) ** 2
    assert np.allclose(ld.Q_o - ld.Q_i, Fc, rtol=1e-8)
    assert np.ptp(ld.Q_i) < 1e-9 * ld.Q_i.max() and ld.Q_i.min() < float(clearance_preload(B, -8 * UM))


@pytest.mark.parametrize("Pd_um", [-8.0, -2.0, 0.0, 10.0])
def test_radial_load_is_harris_sum_of_the_ball_approaches(Pd_um):
    """Harris & Kotzalas 2007 ch. 7: under a radial load the ball at ψ is compressed by δ_r cos ψ − P_d/2, and
    F_r = Σ K_n (δ_r cos ψ − P_d/2)₊^1.5 cos ψ (small displacements against A: 2e-3 here)."""
    b = preloaded(Pd_um * UM)
    ld = load_distribution(b, 0.0, 2000.0, form="static")
    approach = np.maximum(ld.delta_r * np.cos(ld.psi) - Pd_um * UM / 2, 0.0)
    assert np.sum(B.Kn() * approach ** 1.5 * np.cos(ld.psi)) == pytest.approx(2000.0, rel=2e-3)
    assert np.allclose(ld.Q_i, ld.Q_i[(-np.arange(B.Z)) % B.Z], rtol=1e-10)   # symmetric about the load line


def test_light_load_on_a_preload_meets_the_linear_radial_stiffness():
    """A light radial load moves the preloaded ring by F_r / K_r, K_r = ¾ Z K_n √δ0 (δ0 = −P_d/2: every ball
    loaded, Σ cos² ψ = Z/2); the ring reaction at the centred position is the same stiffness, and the axial one
    is the balls' preload over the groove-centre distance, Z Q_0 / A_r0."""
    b = preloaded(-8 * UM)
    Kr = 0.75 * B.Z * B.Kn() * np.sqrt(4 * UM)
    ld = load_distribution(b, 0.0, 1.0, form="static")
    assert ld.delta_r * Kr == pytest.approx(1.0, rel=1e-4) and np.all(ld.Q_i > 0)
    P, K, at = ring_reaction(b, np.zeros(5))
    assert np.allclose(P, 0.0, atol=1e-9 * B.Z * float(clearance_preload(B, -8 * UM)))
    assert K[1, 1] == pytest.approx(Kr, rel=1e-9) and K[3, 3] == pytest.approx(Kr, rel=1e-9)
    assert K[0, 0] == pytest.approx(B.Z * float(clearance_preload(B, -8 * UM)) / b.A_r0, rel=1e-9)


@pytest.mark.parametrize("form, n, film", [("static", 0.0, None), ("high_speed", 6000.0, None),
                                           ("static", 3000.0, FILM)])
def test_ball_loads_are_continuous_across_zero_clearance(form, n, film):
    a, c = (load_distribution(preloaded(Pd), 300.0, 2000.0, n_rpm=n, form=form, film=film) for Pd in (1e-9, -1e-9))
    assert np.allclose(a.Q_i, c.Q_i, rtol=0, atol=1e-4 * a.Q_i.max())
    assert np.allclose(a.Q_o, c.Q_o, rtol=0, atol=1e-4 * a.Q_o.max())
    assert c.delta_r == pytest.approx(a.delta_r, rel=1e-3) and c.delta_a == pytest.approx(a.delta_a, rel=1e-3)


def test_film_law_carries_the_load_on_a_preload():
    """With the films in the contact law the preload is solved too; without load the balls stay equal and carry
    more than the dry Q_0 (the films take up part of the clearance as well)."""
    ld = load_distribution(preloaded(-8 * UM), 0.0, 2000.0, n_rpm=3000.0, form="static", film=FILM)
    assert ld.residual < 1e-9 and np.all(ld.Q_i > 0)
    assert np.sum(ld.Q_i * np.cos(ld.alpha_i) * np.cos(ld.psi)) == pytest.approx(2000.0, rel=1e-9)
    free = load_distribution(preloaded(-8 * UM), 0.0, 0.0, n_rpm=3000.0, form="static", film=FILM)
    assert np.ptp(free.Q_i) <= 1e-9 * free.Q_i.max() and free.Q_i.min() > float(clearance_preload(B, -8 * UM))
    with pytest.raises(tb.InputError, match="needs a load or a radial preload"):
        load_distribution(B, 0.0, 0.0, n_rpm=3000.0, form="static", film=FILM)


@pytest.mark.parametrize("form, n", [("static", 0.0), ("high_speed", 6000.0)])
def test_more_preload_loads_the_balls_more_and_stiffens_the_ring(form, n):
    """Under 2 kN the preload first spreads the load zone — the largest ball load falls (a slight preload is
    the best distribution, Harris & Kotzalas 2007 ch. 7) — then every ball load grows with it; the ring only
    stiffens and the balls' total load only grows.  Under a light load (20 N) the largest ball load rises
    with the preload from the least one on."""
    Pds = (0.0, -2.0, -5.0, -10.0, -20.0, -40.0)
    lds = [load_distribution(preloaded(Pd * UM), 0.0, 2000.0, n_rpm=n, form=form) for Pd in Pds]
    qmax, qsum = ([float(f(ld.Q_i)) for ld in lds] for f in (np.max, np.sum))
    dr = [float(ld.delta_r) for ld in lds]
    loaded = [int(np.count_nonzero(ld.Q_i > 0)) for ld in lds]
    assert all(np.diff(qsum) > 0) and all(np.diff(dr) < 0) and all(np.diff(loaded) >= 0)
    assert qmax[1] < qmax[0] and qmax[2] < qmax[1] and qmax[-1] > qmax[-2] > qmax[-3]
    assert loaded[-1] > loaded[0]
    light = [float(np.max(load_distribution(preloaded(Pd * UM), 0.0, 20.0, n_rpm=n, form=form).Q_i)) for Pd in Pds]
    assert all(np.diff(light[1:]) > 0)


def test_power_rises_with_the_preload_and_is_continuous_across_zero():
    """The oil-bath 6208 at a given clearance: the coupled steady state's power grows with the preload and
    does not jump where the clearance changes sign."""
    s = tb.load_scene(tb.example_path("oil_bath_6208.toml"))
    P = [tb.steady_state(s.with_(bearing=s.bearing.with_(Pd=Pd), models={"clearance": "given"})).P_W
         for Pd in (1e-9, -1e-9, -5 * UM, -11 * UM, -20 * UM)]
    assert P[1] == pytest.approx(P[0], rel=1e-4)
    assert all(np.diff(P[1:]) > 0)


def test_scene_tables_state_the_unmounted_clearance():
    """A negative clearance is what the mounting makes: a bearing table (catalogue, scene) keeps Pd_mm >= 0."""
    with pytest.raises(tb.InputError, match="Pd_mm"):
        tb.load_scene(tb.example_path("oil_bath_6208.toml")).with_(bearing={"Pd_mm": -0.005})


def test_a_pure_axial_load_on_a_preload_is_not_the_closed_form():
    """Fr = 0 on a radially preloaded 6208: the closed form (all balls at the axial contact angle) knew no preload and
    gave the answer of P_d = 0 (64.50 W, Q 305 N); the balls are compressed radially as well, so the model choice
    takes Jones–Harris (all balls still equal, each carrying more than without the preload), and a forced closed
    form is refused by name."""
    import warnings
    from thermobear.errors import InputError
    bath = tb.load_scene(tb.example_path("oil_bath_6208.toml"))
    s = bath.with_(Fr=0.0, Fa=500.0, models={"clearance": "given"})
    pre = s.with_(bearing=s.bearing.with_(Pd=-8e-6))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r0, r1 = tb.steady_state(s), tb.steady_state(pre)
    Q0, Q1 = (np.asarray(r.losses.contacts["inner"]["Q"], float).ravel() for r in (r0, r1))
    assert r0.models_used["load_model"][0] == "closed_form" and r1.models_used["load_model"][0] == "jones_harris"
    assert np.ptp(Q1) < 1e-9 * Q1.max() and Q1.min() > Q0.max() and r1.P_W > r0.P_W
    with pytest.raises(InputError, match="clearance >= 0"):
        tb.steady_state(pre.with_(models={"load_model": "closed_form"}))
