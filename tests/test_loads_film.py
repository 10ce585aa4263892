"""Load distribution with the lubricant film in the contact law (thermobear.loads.film)."""
import numpy as np
import pytest

from thermobear.errors import InputError, NoEquilibrium
from thermobear.lubrication.film import film_thickness_nvm
from thermobear.contact.geometry import bearing
from thermobear.contact.kinematics import entrainment_speed
from thermobear.loads import axial_contact_angle, load_distribution
from thermobear.loads.film import film_contact_law, film_load_distribution

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


# --- the fast path: analytic derivatives of the NVM film and the per-ball inversion -----------------------

# contacts spanning the four Moes regimes (IVR, IVE, PVR, EHL) and the blends between them:
# loads 1e-6–1e4 N, speeds 0.01–50 m/s, thin and viscous oils, α_p = 0 (iso-viscous) to 3e-8 1/Pa,
# narrow and wide ellipses (D = Rx/Ry 0.02–1)
_GRID = [dict(Q=Q, u=u, eta=eta, ap=ap, Rx=Rx, Ry=Ry)
         for Q in (1e-6, 1e-3, 1.0, 100.0, 1e4) for u in (0.01, 1.0, 50.0)
         for eta, ap in ((0.002, 1e-8), (0.0456, 2.2e-8), (0.5, 3e-8), (0.02, 0.0))
         for Rx, Ry in ((4.23e-3, 0.1495), (6.5e-3, 6.6e-3), (3e-3, 0.02))]


def _ln_h_public(Q, Rx, Ry, u, eta, ap):
    return np.log(film_thickness_nvm(Q, Rx, Ry, u, eta, ap, B7210.E_prime))


def test_nvm_log_derivatives_match_central_differences():
    """∂ln h/∂ln Q, ∂ln h/∂ln R_x (R_y fixed: D moves too) and ∂ln h/∂ln u of the NVM central film, from
    the chain rule through the blend (thermobear.loads.film._NVMFixed), against central differences of
    the public film_thickness_nvm (step 1e-4 in the logs: truncation ~1e-8 × the third derivative)."""
    from thermobear.loads.filmlaw import _NVMFixed
    c = {k: np.array([g[k] for g in _GRID]) for k in _GRID[0]}
    nvm = _NVMFixed(c["Rx"], c["Ry"], c["u"], c["eta"], c["ap"], B7210.E_prime)
    ln_h, H_Q, shares = nvm.ln_h(c["Q"])
    H_Rx, H_u = nvm.grad(shares)
    # the same numbers as the public function, bit for bit
    assert np.array_equal(np.exp(ln_h), film_thickness_nvm(c["Q"], c["Rx"], c["Ry"], c["u"], c["eta"], c["ap"],
                                                           B7210.E_prime))
    e = np.exp(1e-4)

    def fd(**kw):
        up = {**c, **{k: c[k] * e for k in kw}}
        dn = {**c, **{k: c[k] / e for k in kw}}
        return (_ln_h_public(up["Q"], up["Rx"], up["Ry"], up["u"], up["eta"], up["ap"])
                - _ln_h_public(dn["Q"], dn["Rx"], dn["Ry"], dn["u"], dn["eta"], dn["ap"])) / 2e-4

    for got, want in ((H_Q, fd(Q=1)), (H_Rx, fd(Rx=1)), (H_u, fd(u=1))):
        assert np.allclose(got, want, rtol=1e-6, atol=1e-8)
    # the grid does reach every regime, and the slope in ln Q spans the asymptotes' −2 … 0
    assert H_Q.min() < -1.9 and H_Q.max() > -0.02
    assert np.all(H_Q < 0)                         # h falls with the load everywhere on the grid


@pytest.mark.parametrize("stiffness", ["nominal", "per_ball"])
def test_law_alpha_derivative_matches_central_difference(stiffness):
    """∂G/∂α at fixed Q of the low-speed law (films through R_x(α); K_n(α) with per_ball) and of the
    high-speed law (R_x and u through 1 ∓ γ'cos α), against central differences of the public functions."""
    from thermobear.loads.film import _Film
    from thermobear.loads.filmlaw import _FilmLaw, _invert
    al = np.linspace(0.3, 0.9, 7)[None, :]
    Q = np.array([[0.01, 0.3, 2.0, 15.0, 120.0, 800.0, 3000.0]])
    law = _Film(B7210, np.full((1, 7), U), np.full((1, 7), 1.3 * U), np.array([[0.0221]]), np.array([[2e-8]]),
                stiffness)
    s = law.parts(Q, al)
    s = s[0] - s[1] - s[2]
    at = law.at(al)
    Qn, d_el, h, GQ, Ga, _, it, rel, fail = _invert(at, s, al, Q * 1.7)
    assert not fail.any()
    assert np.allclose(Qn, Q, rtol=1e-12) and rel < 1e-13
    eps = 1e-6
    Gp = law.parts(Q, al + eps)
    Gm = law.parts(Q, al - eps)
    fd = ((Gp[0] - Gp[1] - Gp[2]) - (Gm[0] - Gm[1] - Gm[2])) / (2 * eps)
    assert np.allclose(Ga, fd, rtol=1e-6, atol=1e-9 * np.abs(fd).max())
    # dG/d ln Q at the solution against a central difference in ln Q
    Gq = [law.parts(Q * f, al) for f in (np.exp(1e-5), np.exp(-1e-5))]
    fdq = ((Gq[0][0] - Gq[0][1] - Gq[0][2]) - (Gq[1][0] - Gq[1][1] - Gq[1][2])) / 2e-5
    assert np.allclose(GQ, fdq, rtol=1e-6)
    # high-speed form: one film per contact, the two contacts of a ball side by side, (nb, 2Z) [inner | outer]
    Z = B7210.Z
    al15, Q15 = np.linspace(0.3, 0.9, Z)[None, :], np.geomspace(0.01, 3000.0, Z)[None, :]
    K = np.repeat([B7210.K_i(B7210.alpha0), B7210.K_o(B7210.alpha0)], Z)
    v = np.repeat([[180.0, 150.0]], Z, axis=1)       # orbital speed factors |ω − ω_c|, ω_c [rad/s]
    hs = _FilmLaw(B7210, np.array([[0.0221]]), np.array([[2e-8]])).bind(K, v)
    a2 = np.concatenate([al15, al15 - 0.05], axis=1)
    Q2 = np.concatenate([Q15, 1.2 * Q15], axis=1)
    gp, sg = B7210.D / B7210.dm, np.repeat([-1.0, 1.0], Z)

    def G_hs(a):
        fac = 1.0 + sg * gp * np.cos(a)
        h = film_thickness_nvm(Q2, 0.5 * B7210.D * fac, np.repeat([B7210.Ry_i, B7210.Ry_o], Z),
                               v * 0.5 * B7210.dm * fac, 0.0221, 2e-8, B7210.E_prime)
        return (Q2 / K) ** (2 / 3) - h

    s2 = G_hs(a2)
    Qn2, _, _, _, Ga2, _, _, rel2, fail2 = _invert(hs.at(a2), s2, a2, Q2 * 0.3)
    assert not fail2.any()
    assert np.allclose(Qn2, Q2, rtol=1e-12) and rel2 < 1e-13
    fd2 = (G_hs(a2 + eps) - G_hs(a2 - eps)) / (2 * eps)
    assert np.allclose(Ga2, fd2, rtol=1e-6, atol=1e-9 * np.abs(fd2).max())


def test_inversion_from_any_warm_start_and_out_of_range():
    """The per-ball inversion converges from warm starts 1e-250 N to 1e16 N to the same load (gaps and
    heavy contacts alike), and says so when no load in [e^-600, e^40] N gives the approach."""
    from thermobear.errors import NoConvergence
    from thermobear.loads.film import _Film
    from thermobear.loads.filmlaw import _invert, invert_error
    law = _Film(B7210, np.full((1, 5), U), np.full((1, 5), U), np.array([[0.0221]]), np.array([[2e-8]]),
                "nominal")
    al = np.full((1, 5), B7210.alpha0)
    s = np.array([[-3e-6, -5e-7, 0.0, 2e-6, 3e-5]])      # gaps, touching, loaded [m]
    ref = None
    for Q0 in (1e-250, 1e-6, 1.0, 1e4, 1e16):
        Q, d_el, h, GQ, Ga, _, it, rel, fail = _invert(law.at(al), s, al, np.full((1, 5), Q0))
        assert rel < 1e-13 and not fail.any() and np.all(GQ > 0) and it < 40
        assert np.allclose(d_el - h.sum(-1), s, rtol=0, atol=1e-13 * np.abs(s).max())
        ref = Q if ref is None else ref
        assert np.allclose(Q, ref, rtol=1e-12)
    for s_bad in (1e6, -1e305):     # 1000 km of approach (Q > e^40 N); a gap wider than the largest film
        s = np.array([[s_bad, 0.0, 0.0, 0.0, 0.0]])
        *_, it, rel, fail = _invert(law.at(al), s, al, np.ones((1, 5)))
        assert fail.tolist() == [[1, 0, 0, 0, 0]]           # only that contact fails; the others are solved
        assert isinstance(invert_error(fail, s, al, it), NoConvergence)
        assert "no load in" in str(invert_error(fail, s, al, it))


def test_start_from_another_solution_gives_the_same_equilibrium():
    # start=: Newton from a given solution of the same loads — the dry one (what it solves itself), or the film
    # loads at another viscosity (the film-temperature iteration) — reaches the same equilibrium
    b = bearing("7210")
    Fa, Fr, kw = np.array([300.0, 450.0]), np.array([750.0, 300.0]), dict(u_i=8.63, u_o=8.63, alpha_p=2e-8)
    own = film_load_distribution(b, Fa, Fr, eta=0.0221, **kw)
    from_dry = film_load_distribution(b, Fa, Fr, eta=0.0221, start=load_distribution(b, Fa, Fr), **kw)
    from_film = film_load_distribution(b, Fa, Fr, eta=0.0221,
                                       start=film_load_distribution(b, Fa, Fr, eta=0.03, **kw), **kw)
    for ld in (from_dry, from_film):
        assert np.max(np.abs(ld.Q_i - own.Q_i)) <= 1e-9 * np.max(own.Q_i) and ld.residual < 1e-10
    assert from_film.iterations <= own.iterations
