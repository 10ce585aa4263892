"""Load distribution with the lubricant film in the contact law (thermobear.loads_film)."""
import numpy as np
import pytest

from thermobear.errors import InputError, NoEquilibrium
from thermobear.film import film_thickness_nvm
from thermobear.geometry import bearing
from thermobear.kinematics import entrainment_speed
from thermobear.loads import axial_contact_angle, load_distribution
from thermobear.loads_film import film_contact_law, film_load_distribution

B7210 = bearing("7210")
B6210 = bearing("6210")
# seed 004 scene at 4800 rpm: entrainment speed at the nominal angle; mineral oil near 50 °C
U = float(entrainment_speed(4800 * np.pi / 30, 0.0, B7210.D, B7210.dm, B7210.alpha0))
OIL = dict(u_i=U, u_o=U, eta=0.0221, alpha_p=2e-8)


def _geometry(brg, ld):
    """Independent re-computation of the ball geometry from the ring displacements (Harris 2001 §7.4)."""
    A, R = brg.A, brg.R_inner_locus
    c = np.cos(ld.psi)
    A1 = np.asarray(ld.delta_a)[..., None] + R * np.asarray(ld.theta)[..., None] * c
    A2 = A * np.cos(brg.alpha0) + np.asarray(ld.delta_r)[..., None] * c
    return np.hypot(A1, A2) - A, np.arctan2(A1, A2)


def _forces(brg, ld):
    s, al = _geometry(brg, ld)
    c = np.cos(ld.psi)
    return ((ld.Q * np.sin(al)).sum(-1), (ld.Q * np.cos(al) * c).sum(-1),
            (ld.Q * np.sin(al) * c).sum(-1) * brg.R_inner_locus)


@pytest.mark.parametrize("brg, Fa, Fr, M", [(B7210, 450.0, 750.0, None), (B7210, 450.0, 325.0, None),
                                            (B6210, 0.0, 1000.0, None), (B7210, 450.0, 300.0, 1.0)])
def test_vanishing_film_gives_the_dry_distribution(brg, Fa, Fr, M):
    """η → 0: films → 0, the law tends to Q = K_n s^1.5 for s > 0 and Q → 0 across a gap."""
    dry = load_distribution(brg, Fa, Fr, M=M)
    ld = film_load_distribution(brg, Fa, Fr, M=M, u_i=U, u_o=U, eta=1e-15, alpha_p=2e-8)
    scale = dry.Q.max()
    assert np.max(np.abs(ld.Q - dry.Q)) <= 1e-6 * scale
    assert ld.delta_a == pytest.approx(dry.delta_a, rel=1e-6, abs=1e-12)
    assert ld.delta_r == pytest.approx(dry.delta_r, rel=1e-6, abs=1e-12)
    assert ld.theta == pytest.approx(dry.theta, rel=1e-6, abs=1e-12)
    loaded = dry.Q > 0
    assert np.allclose(ld.alpha_i[loaded], dry.alpha_i[loaded], rtol=0, atol=1e-8)
    # and the film does make a difference at a real viscosity (the test can fail)
    real = film_load_distribution(brg, Fa, Fr, M=M, **OIL)
    assert np.max(np.abs(real.Q - dry.Q)) > 1e-3 * scale


def test_pure_axial_load_all_balls_equal():
    ld = film_load_distribution(B7210, 450.0, 0.0, **OIL)
    assert np.ptp(ld.Q) <= 1e-12 * ld.Q.max()
    assert np.ptp(ld.alpha_i) <= 1e-12
    Fa, Fr, M = _forces(B7210, ld)
    assert Fa == pytest.approx(450.0, rel=1e-10)
    assert abs(Fr) <= 1e-10 * 450.0
    # one ball: Q sin α = Fa/Z with s(α) = δ_el(Q) − h_i − h_o (hand check of the single-ball law)
    Q = float(ld.Q[0])
    al = float(ld.alpha_i[0])
    assert Q * np.sin(al) == pytest.approx(450.0 / B7210.Z, rel=1e-10)
    s, d_el, hi, ho = film_contact_law(B7210, Q, al, **OIL)
    A = B7210.A
    # the ring moved axially only: A1 = δa, A2 = A cos α0, hence s = A cos α0 / cos α − A
    assert float(s) == pytest.approx(A * np.cos(B7210.alpha0) / np.cos(al) - A, rel=1e-8)
    # the film takes up approach: the contact angle is below the dry one
    assert al < float(axial_contact_angle(B7210, 450.0))


@pytest.mark.parametrize("Fr", [25.0, 325.0, 750.0])
def test_combined_load_equilibrium_and_law(Fr):
    ld = film_load_distribution(B7210, 450.0, Fr, **OIL)
    Fa, Frm, M = _forces(B7210, ld)
    assert Fa == pytest.approx(450.0, rel=1e-10)
    assert Frm == pytest.approx(Fr, rel=1e-10)
    assert np.all(ld.Q > 0)                        # no open contact
    s, al = _geometry(B7210, ld)
    assert np.allclose(ld.alpha_i, al, rtol=0, atol=1e-12)
    law, d_el, hi, ho = film_contact_law(B7210, ld.Q, al, **OIL)
    scale = d_el + hi + ho
    assert np.max(np.abs(law - s) / scale) < 1e-9
    # the films are the NVM central films of each contact at the ball's angle
    assert np.allclose(ld.h_i, film_thickness_nvm(ld.Q, B7210.Rx_i(al), B7210.Ry_i, U, 0.0221, 2e-8,
                                                  B7210.E_prime), rtol=1e-12)
    assert np.allclose(ld.h_o, film_thickness_nvm(ld.Q, B7210.Rx_o(al), B7210.Ry_o, U, 0.0221, 2e-8,
                                                  B7210.E_prime), rtol=1e-12)
    # symmetry about the load line: ball j and ball Z − j carry the same load
    assert np.allclose(ld.Q[1:], ld.Q[1:][::-1], rtol=1e-9)
    if Fr == 750.0:
        dry = load_distribution(B7210, 450.0, Fr)
        assert np.any(dry.Q == 0) and np.any(s < 0)   # gaps exist and carry a film force


def test_tilt_free_and_batch_equilibrium():
    ld = film_load_distribution(B7210, 450.0, [300.0, 600.0], M=[1.0, -2.0], stiffness="per_ball", **OIL)
    Fa, Fr, M = _forces(B7210, ld)
    assert np.allclose(Fa, 450.0, rtol=1e-10)
    assert np.allclose(Fr, [300.0, 600.0], rtol=1e-10)
    assert np.allclose(M, [1.0, -2.0], rtol=1e-9, atol=1e-10 * 450.0 * B7210.R_inner_locus)
    assert np.all(ld.Q > 0)


def test_more_viscosity_evens_the_loads():
    """Thicker films carry the least loaded balls and even the distribution out."""
    etas = [0.005, 0.01, 0.02, 0.04, 0.08]
    for brg, Fa, Fr in ((B6210, 0.0, 1000.0), (B6210, 0.0, 3000.0), (B7210, 450.0, 750.0), (B7210, 450.0, 325.0)):
        lds = [film_load_distribution(brg, Fa, Fr, u_i=U, u_o=U, eta=e, alpha_p=2e-8) for e in etas]
        qmin = np.array([x.Q.min() for x in lds])
        qmax = np.array([x.Q.max() for x in lds])
        assert np.all(np.diff(qmin) > 0)
        assert np.all(np.diff(qmin / qmax) > 0)
        if brg is B6210:
            # radial bearing: the most loaded ball carries less (the films share out the radial load)
            assert np.all(np.diff(qmax) < 0)
    # angular contact under Fa: the films take up approach, the contact angles fall and the
    # most loaded ball's load rises (the film acts as extra preload) — documented, not a defect
    a = film_load_distribution(B7210, 450.0, 750.0, u_i=U, u_o=U, eta=0.005, alpha_p=2e-8)
    b = film_load_distribution(B7210, 450.0, 750.0, u_i=U, u_o=U, eta=0.08, alpha_p=2e-8)
    assert b.alpha_i[0] < a.alpha_i[0] and b.Q.max() > a.Q.max()


def test_film_law_monotone_and_gap_load():
    """dQ/ds > 0 at the solution; a gap carries the IVR load of a film as thick as the gap."""
    ld = film_load_distribution(B7210, 450.0, 750.0, **OIL)
    assert np.all(ld.stiffness_n > 0)
    Q = np.logspace(-6, 4, 400)
    s, *_ = film_contact_law(B7210, Q, B7210.alpha0, **OIL)
    assert np.all(np.diff(s) > 0)
    # IVR limit: h ∝ Q^-2 at very light load (Moes H_RI ∝ M^-2)
    _, _, h1, _ = film_contact_law(B7210, 1e-6, B7210.alpha0, **OIL)
    _, _, h2, _ = film_contact_law(B7210, 2e-6, B7210.alpha0, **OIL)
    assert np.log(h1 / h2) / np.log(2.0) == pytest.approx(2.0, rel=1e-3)


def test_bad_input_and_impossible_loads():
    with pytest.raises(InputError, match="eta"):
        film_load_distribution(B7210, 450.0, 100.0, u_i=U, u_o=U, eta=0.0, alpha_p=2e-8)
    with pytest.raises(InputError, match="u_i"):
        film_load_distribution(B7210, 450.0, 100.0, u_i=-1.0, u_o=U, eta=0.02, alpha_p=2e-8)
    with pytest.raises(InputError, match="alpha_p"):
        film_load_distribution(B7210, 450.0, 100.0, u_i=U, u_o=U, eta=0.02, alpha_p=np.nan)
    with pytest.raises(InputError, match="Fa, Fr, M"):
        film_load_distribution(B6210, 0.0, 0.0, **OIL)
    with pytest.raises(InputError, match="stiffness"):
        film_load_distribution(B7210, 450.0, 0.0, stiffness="soft", **OIL)
    with pytest.raises(InputError, match="u_i"):
        film_load_distribution(B7210, 450.0, 100.0, u_i=np.ones(4), u_o=U, eta=0.02, alpha_p=2e-8)
    with pytest.raises(NoEquilibrium):
        film_load_distribution(B7210, 0.0, 100.0, **OIL)
