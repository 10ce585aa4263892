"""Hydrodynamic rolling force: hand computations, published values, limits.

Hand computations use plain ``math`` arithmetic from the printed formulas
(seed 000 eqs 20-23, seed 004 eqs 17-19, Biboulet & Houpert 2010 eqs 28-36),
not the library's code path.
"""
import math
import warnings

import numpy as np
import pytest
from scipy.integrate import quad

from thermobear.errors import InputError
from thermobear.losses import rolling as R
from thermobear.lubrication.film import lubrication_regime

E = 2.3e11
D = 7.938e-3
RX = D / 2                                  # thrust race: flat in the rolling direction
RY = 0.53 * D / (2 * 0.53 - 1)              # 70.12 mm
K_RATIO = RY / RX                           # 17.67 = 2f/(2f-1), seed 000 eq 12
Q = 1.42
ETA = 0.089                                 # reproduces seed 000 Table 1 (validation/report/seed000_table1.md, E5)
DM = 0.036


def u_mean(n_rpm):
    return math.pi * n_rpm * DM / 120.0     # seed 000 eq 17


def hand_biboulet(Qv, u, eta=ETA, Rx=RX, Ry=RY):
    W = Qv / (E * Rx * Rx)
    U = eta * u / (E * Rx)
    k = Ry / Rx
    f_ivr = 2.9766 * E * Rx**2 * k**0.3316 * W ** (1 / 3) * U ** (2 / 3)
    f_ehl = 7.5826 * E * Rx**2 * k**0.4055 * W ** (1 / 3) * U**0.75
    M = 0.5549 * k**-0.6029 * W * U**-0.75
    return f_ivr, f_ehl, M, f_ivr / (1 + M / 6.6) + (M / 6.6) / (1 + M / 6.6) * f_ehl


def hand_ellipe(kappa):
    return quad(lambda p: math.sqrt(1 - (1 - kappa**2) * math.sin(p) ** 2), 0, math.pi / 2)[0]


def houpert_ab(Qv, Rx=RX, Ry=RY):
    """Houpert's approximate semi-axes (seed 000 eqs 9-10), a different path from exact Hertz."""
    k, W = Ry / Rx, Qv / (E * Rx * Rx)
    return 1.3085 * Rx * k**0.4091 * W ** (1 / 3), 1.1502 * Rx * k**-0.1876 * W ** (1 / 3)


# ------------------------------------------------------------------ Biboulet (seeds 000/001)
@pytest.mark.parametrize("n", [100, 200, 300, 400])
def test_biboulet_forms_match_hand_computation(n):
    u = u_mean(n)
    f_ivr, f_ehl, M, f_tr = hand_biboulet(Q, u)
    assert R.rolling_force_biboulet_ivr(Q, RX, RY, u, ETA, E) == pytest.approx(f_ivr, rel=1e-12)
    assert R.rolling_force_biboulet_ehl(Q, RX, RY, u, ETA, E) == pytest.approx(f_ehl, rel=1e-12)
    assert R.transition_parameter(Q, RX, RY, u, ETA, E) == pytest.approx(M, rel=1e-12)
    assert R.rolling_force_biboulet_transition(Q, RX, RY, u, ETA, E) == pytest.approx(f_tr, rel=1e-12)
    assert R.rolling_force(Q, RX, RY, u, ETA, E) == pytest.approx(f_tr, rel=1e-12)


@pytest.mark.parametrize("n, fr_paper", [(100, 0.59e-2), (200, 1.1e-2), (300, 1.5e-2), (400, 1.9e-2)])
def test_seed000_table1_FR(n, fr_paper):
    """Published F_R of seed 000 Table 1 (two significant digits) with η = 0.089 Pa s."""
    f = R.rolling_force_biboulet_transition(Q, RX, RY, u_mean(n), ETA, E)
    assert f == pytest.approx(fr_paper, rel=0.03)


def test_seed001_ehl_partition_41_to_21_percent():
    """Seed 001 §4.4: d 6.35 mm, Q 0.125 N, η 0.05 Pa s, r 18 mm, v = ω r/2: 41 % at 60 rpm, 21 % at 210 rpm."""
    d, rg = 6.35e-3, 4.16e-3
    Rx, Ry = d / 2, rg * (d / 2) / (rg - d / 2)
    w = np.array([60.0, 210.0]) * math.pi / 30
    p = R.ehl_partition(0.125, Rx, Ry, w * 0.018 / 2, 0.05, E)
    assert np.round(p * 100).tolist() == [41.0, 21.0]


def test_dominant_regime_force_is_ivr_where_ivr_dominates_and_transition_where_ehl_does():
    """Bălan et al. 2015 §5: Biboulet's IVR equation when IVR dominates (EHL partition below the band), his
    transition equation when EHL dominates (above it); in between a C¹ blend, hand-computed here."""
    d, rg = 6.35e-3, 4.16e-3
    Rx, Ry = d / 2, rg * (d / 2) / (rg - d / 2)
    lo, hi = R.DOMINANT_BAND
    assert lo < 0.5 < hi                                        # the paper's line lies inside the band
    for Qv in np.geomspace(0.01, 10.0, 25):
        for rpm in (20.0, 60.0, 210.0, 2000.0):
            u = rpm * math.pi / 30 * 0.018 / 2
            f_ivr, _, M, f_tr = hand_biboulet(Qv, u, eta=0.05, Rx=Rx, Ry=Ry)
            p = (M / 6.6) / (1 + M / 6.6)
            t = min(1.0, max(0.0, (p - lo) / (hi - lo)))
            w = t * t * (3 - 2 * t)
            f = R.rolling_force_biboulet_dominant(Qv, Rx, Ry, u, 0.05, E)
            assert f == pytest.approx(f_ivr + w * (f_tr - f_ivr), rel=1e-12)
            if p <= lo:
                assert f == pytest.approx(f_ivr, rel=1e-12)
            if p >= hi:
                assert f == pytest.approx(f_tr, rel=1e-12)


def test_dominant_regime_force_has_no_step_across_its_band():
    """A fine load sweep across the band: the force is a smooth power law in Q (no jump in ln F)."""
    d, rg = 6.35e-3, 4.16e-3
    Rx, Ry = d / 2, rg * (d / 2) / (rg - d / 2)
    u = 120 * math.pi / 30 * 0.018 / 2
    Qs = np.geomspace(0.02, 5.0, 4000)
    p = R.ehl_partition(Qs, Rx, Ry, u, 0.05, E)
    assert p.min() < R.DOMINANT_BAND[0] and p.max() > R.DOMINANT_BAND[1]        # the sweep crosses the band
    lnF = np.log(R.rolling_force_biboulet_dominant(Qs, Rx, Ry, u, 0.05, E))
    slope = np.diff(lnF) / np.diff(np.log(Qs))
    assert np.all(np.abs(np.diff(slope)) < 0.05)                  # d ln F / d ln Q changes gradually
    assert np.all(np.abs(slope) < 1.0)


# ------------------------------------------------------------------ Houpert / B&H 2010 (seed 004)
def test_houpert_ivr_hand():
    u = u_mean(200)
    W, U2 = Q / (E * RX**2), 2 * ETA * u / (E * RX)
    hand = 0.835 * (RX / RY) ** -0.358 * W**0.364 * U2**0.636 * E * RX**2
    assert R.rolling_force_houpert_ivr(Q, RX, RY, u, ETA, E) == pytest.approx(hand, rel=1e-12)
    # B&H 2010 §3.4: Houpert's IVR is ~0.6 of their fully flooded IVR
    ratio = hand / R.rolling_force_biboulet_ivr(Q, RX, RY, u, ETA, E)
    assert 0.55 < ratio < 0.75


def test_houpert_ehl_hand_with_given_semi_axes():
    u, ap = u_mean(300), 2.5e-8
    a, b = houpert_ab(Q)
    kap, W, U2, G = b / a, Q / (E * RX**2), 2 * ETA * u / (E * RX), ap * E
    hand = 0.674 * kap**-0.043 * (2 * a / RX) * G**0.022 * (kap * W) ** 0.133 * U2**0.656 * E * RX**2
    got = R.rolling_force_houpert_ehl(Q, RX, RY, u, ETA, E, ap, a=a, b=b)
    assert got == pytest.approx(hand, rel=1e-12)
    # exact Hertz semi-axes (default) within ~1.5 % of Houpert's approximation (seed 000 eqs 9–10)
    assert R.rolling_force_houpert_ehl(Q, RX, RY, u, ETA, E, ap) == pytest.approx(hand, rel=0.015)
    with pytest.raises(InputError, match="alpha_p"):
        R.rolling_force(Q, RX, RY, u, ETA, E, model="houpert_ehl")


def hand_pvr(Qv, u, a, b, c_bib):
    kap = b / a
    beta = 4 / math.pi * hand_ellipe(kap) / (1 + RX / RY)
    U2, W = 2 * ETA * u / (E * RX), Qv / (E * RX**2)
    M = beta**0.25 * kap * W / U2**0.75
    inner = (0.77 * beta ** (-1 / 3) * kap**0.12 * U2 ** (-1 / 12) - 1.8 * beta**-0.25) / (1 + M / 6.6) \
        + 1.8 * beta**-0.25
    c = 0.85 / (1 + 4.72 * M**-0.39 * kap ** (0.484 * M**0.165)) if c_bib else 1.0
    return c * E * RX**2 * (2 * a / RX) * inner * U2**0.75, M, beta


@pytest.mark.parametrize("trunc", ["seed004", None])
def test_biboulet_pvr_hand(trunc):
    u = u_mean(100)
    a, b = houpert_ab(Q)
    hand, M, beta = hand_pvr(Q, u, a, b, trunc == "seed004")
    got = R.rolling_force_biboulet_pvr(Q, RX, RY, u, ETA, E, a=a, b=b, truncation=trunc)
    assert got == pytest.approx(hand, rel=1e-10)
    assert 1.0 < beta < 4 / math.pi      # B&H 2010: β between circle (1) and wide ellipse (4/π)


def test_biboulet_pvr_untruncated_equals_seed000_transition():
    """B&H eq 32 (exact κ, β) and its seed 000 re-fit (k = Ry/Rx) agree within 2 % over 100-400 rpm."""
    for n in (100, 200, 300, 400):
        u = u_mean(n)
        full = R.rolling_force_biboulet_pvr(Q, RX, RY, u, ETA, E, truncation=None)
        assert full == pytest.approx(R.rolling_force_biboulet_transition(Q, RX, RY, u, ETA, E), rel=0.02)


def test_pvr_limits_tend_to_ivr_and_ehl_asymptotes():
    """Untruncated eq 32 -> B&H IVR asymptote (M -> 0) and EHL asymptote (M -> inf), eq 31."""
    def asymptotes(Qv, u):
        a, b = R.biboulet_parameters(Qv, RX, RY, u, ETA, E)["a"], R.biboulet_parameters(Qv, RX, RY, u, ETA, E)["b"]
        kap = b / a
        beta = 4 / math.pi * hand_ellipe(kap) / (1 + RX / RY)
        U2 = 2 * ETA * u / (E * RX)
        ivr = 0.77 * beta ** (-1 / 3) * kap**0.12 * (2 * a / RX) * U2 ** (2 / 3) * E * RX**2
        ehl = 1.8 * beta**-0.25 * (2 * a / RX) * U2**0.75 * E * RX**2
        return ivr, ehl
    # M -> 0: tiny load, high speed
    q_lo, u_hi = 1e-6, 50.0
    M_lo = R.biboulet_parameters(q_lo, RX, RY, u_hi, ETA, E)["M"]
    assert M_lo < 1e-3
    ivr, _ = asymptotes(q_lo, u_hi)
    assert R.rolling_force_biboulet_pvr(q_lo, RX, RY, u_hi, ETA, E, truncation=None) == pytest.approx(ivr, rel=1e-3)
    # M -> inf: heavy load, slow
    q_hi, u_lo = 1e4, 1e-6
    assert R.biboulet_parameters(q_hi, RX, RY, u_lo, ETA, E)["M"] > 1e7
    _, ehl = asymptotes(q_hi, u_lo)
    f_ehl = R.rolling_force_biboulet_pvr(q_hi, RX, RY, u_lo, ETA, E, truncation=None)
    assert f_ehl == pytest.approx(ehl, rel=2e-3)
    # seed 004's c_Bib version: 0.85 x EHL asymptote at large M, -> 0 at small M (documented: no IVR limit)
    f_c = R.rolling_force_biboulet_pvr(q_hi, RX, RY, u_lo, ETA, E)
    assert f_c / f_ehl == pytest.approx(0.85, rel=0.02)
    assert R.rolling_force_biboulet_pvr(q_lo, RX, RY, u_hi, ETA, E) / ivr < 0.02


def test_transition_limits():
    """Transition -> IVR as M -> 0, -> EHL as M -> inf (seed 000 eq 20)."""
    f_ivr, _, M, _ = hand_biboulet(1e-8, 30.0)
    assert M < 1e-4
    assert R.rolling_force_biboulet_transition(1e-8, RX, RY, 30.0, ETA, E) == pytest.approx(f_ivr, rel=1e-4)
    _, f_ehl, M, _ = hand_biboulet(1e3, 1e-7)
    assert M > 1e6
    assert R.rolling_force_biboulet_transition(1e3, RX, RY, 1e-7, ETA, E) == pytest.approx(f_ehl, rel=1e-5)


MODELS = ["biboulet_ivr", "biboulet_ehl", "biboulet_transition", "biboulet_dominant", "houpert_ivr", "houpert_ehl",
          "biboulet_pvr"]


@pytest.mark.parametrize("model", MODELS)
def test_zero_speed_and_zero_load_give_zero_without_warnings(model):
    u = np.array([0.0, 1e-12, 1e-9, 1e-6, 1e-3, 0.1])
    with warnings.catch_warnings(), np.errstate(all="raise"):
        warnings.simplefilter("error")
        f = np.asarray(R.rolling_force(Q, RX, RY, u, ETA, E, model=model, alpha_p=2.5e-8))
        f0 = np.asarray(R.rolling_force(np.array([0.0, 0.0]), RX, RY, np.array([0.0, 0.1]), ETA, E,
                                        model=model, alpha_p=2.5e-8))
    assert np.all(np.isfinite(f)) and f[0] == 0.0
    assert np.all(np.diff(f) > 0)                 # increases with speed
    assert f[1] < 1e-6 * f[-1]                    # -> 0 as u -> 0
    assert np.all(f0 == 0.0)


@pytest.mark.parametrize("model", MODELS)
def test_broadcasting_matches_scalar_calls(model):
    Qs = np.array([[0.5], [1.42], [3.0]])
    us = np.array([0.05, 0.1, 0.4, 1.0])
    grid = R.rolling_force(Qs, RX, RY, us, ETA, E, model=model, alpha_p=2.5e-8)
    assert grid.shape == (3, 4)
    for i, q in enumerate(Qs[:, 0]):
        for j, u in enumerate(us):
            assert grid[i, j] == pytest.approx(R.rolling_force(q, RX, RY, u, ETA, E, model=model, alpha_p=2.5e-8),
                                               rel=1e-12)


def test_bad_input_names_field():
    with pytest.raises(InputError, match="^Q = "):
        R.rolling_force(-1.0, RX, RY, 0.1, ETA, E)
    with pytest.raises(InputError, match="^eta = "):
        R.rolling_force(1.0, RX, RY, 0.1, 0.0, E)
    with pytest.raises(InputError, match="model"):
        R.rolling_force(1.0, RX, RY, 0.1, ETA, E, model="palmgren")
    with pytest.raises(InputError, match="regime"):
        R.rolling_force(1.0, RX, RY, 0.1, ETA, E, model="auto", regime="XYZ")


# ------------------------------------------------------------------ auto and its continuity
def test_auto_mapping_and_ive_choice():
    regimes = np.array(["IVR", "PVR", "IVE", "EHL"])
    f = R.rolling_force(Q, RX, RY, 0.1, ETA, E, model="auto", alpha_p=2.5e-8, regime=regimes)
    assert f[0] == pytest.approx(R.rolling_force_houpert_ivr(Q, RX, RY, 0.1, ETA, E))
    assert f[1] == f[2] == pytest.approx(R.rolling_force_biboulet_pvr(Q, RX, RY, 0.1, ETA, E))
    assert f[3] == pytest.approx(R.rolling_force_houpert_ehl(Q, RX, RY, 0.1, ETA, E, 2.5e-8))


def test_auto_regime_jumps_are_quantified():
    """The seed 004 switching scheme is discontinuous; pin the jumps along a load sweep.

    Seed 000 contact, u = 0.0942 m/s, η 0.089, α_p 2.5e-8: F drops by ~47 % entering
    PVR (c_Bib ≈ 0.5 there) and by ~16 % entering EHL (values in the seed 001 report).
    """
    q = np.logspace(-4, 4, 20001)
    reg = lubrication_regime(q, RX, RY, 0.0942, ETA, 2.5e-8, E).code
    f = R.rolling_force(q, RX, RY, 0.0942, ETA, E, model="auto", alpha_p=2.5e-8)
    edges = np.nonzero(reg[1:] != reg[:-1])[0]
    jumps = {f"{reg[i]}->{reg[i + 1]}": f[i + 1] / f[i] for i in edges}
    assert set(jumps) == {"IVR->PVR", "PVR->EHL"}
    assert 0.45 < jumps["IVR->PVR"] < 0.65
    assert 0.75 < jumps["PVR->EHL"] < 0.92
    # away from the edges the curve is smooth (neighbouring points within 0.2 %)
    smooth = np.ones(q.size - 1, bool)
    smooth[edges] = False
    assert np.max(np.abs(f[1:][smooth] / f[:-1][smooth] - 1)) < 2e-3


def test_pressure_force_and_power():
    f = R.rolling_force(Q, RX, RY, u_mean(400), ETA, E)
    assert R.pressure_force(f) == 2 * f
    # seed 000 eq 34: (FR_l + FR_u) d_b ω_b with d_b ω_b = 2 u, ω_b = ω_c dm/d_b
    omega_c = math.pi * 400 / 60
    omega_b = omega_c * DM / D
    assert 2 * R.rolling_power(u_mean(400), f) == pytest.approx(2 * f * D * omega_b, rel=1e-12)


# ------------------------------------------------------------------ prepared contacts, smooth selection
def test_prepared_contacts_at_several_viscosities_equal_the_module_functions():
    q = np.array([0.0, 0.01, 1.42, 50.0])
    u = np.array([0.0942, 0.0942, 0.0, 0.2])
    c = R.rolling_contacts(q, RX, RY, u, E)
    eta = np.array([[0.089], [0.03]])                                      # 2 states in front
    for model in ("houpert_ivr", "biboulet_pvr", "houpert_ehl", "auto", "auto_smooth", "biboulet_transition"):
        F = c.force(eta, model, alpha_p=2.5e-8)
        assert np.shape(F) == (2, 4)
        for k in range(2):
            ref = R.rolling_force(q, RX, RY, u, float(eta[k, 0]), E, model=model, alpha_p=2.5e-8)
            np.testing.assert_allclose(F[k], ref, rtol=1e-13, atol=0.0, err_msg=model)
        assert np.all(F[:, 0] == 0) and np.all(F[:, 2] == 0)             # Q = 0, u = 0


def test_smooth_selection_equals_the_sharp_one_away_from_boundaries_and_is_continuous():
    q = np.logspace(-4, 4, 4001)
    reg = lubrication_regime(q, RX, RY, 0.0942, ETA, 2.5e-8, E)
    smooth = R.rolling_force(q, RX, RY, 0.0942, ETA, E, model="auto_smooth", alpha_p=2.5e-8, regime=reg)
    sharp = R.rolling_force(q, RX, RY, 0.0942, ETA, E, model="auto", alpha_p=2.5e-8, regime=reg)
    far = np.minimum.reduce([np.abs(reg.ln_iso_over_piezo), np.abs(reg.ln_RI_over_EI) + (reg.ln_iso_over_piezo < 0) * 9,
                             np.abs(reg.ln_EP_over_RP) + (reg.ln_iso_over_piezo > 0) * 9]) > 0.5
    np.testing.assert_allclose(smooth[far], sharp[far], rtol=1e-4)
    step = np.max(np.abs(np.diff(np.log(smooth))))                          # Δ ln q = 0.0046 per step
    assert step < 0.05 and np.max(np.abs(np.diff(np.log(sharp)))) > 0.3     # the sharp selection jumps


# ----------------------------------------------------------------------------- mixed lubrication (load sharing)
# Seed 001 Table 1 contact: 3 mm ball on the 4.16 mm groove, 0.633 N, η 0.05 Pa s, v = ω r/2 at r = 18 mm.
_MIXED = (0.633, 1.5e-3, 4.16e-3 * 1.5e-3 / (4.16e-3 - 1.5e-3), 2 * math.pi * 0.018 / 2, 0.05, 2.3e11)


@pytest.mark.parametrize("model", ["biboulet_ivr", "biboulet_transition", "houpert_ivr", "biboulet_pvr"])
def test_mixed_rolling_force_is_the_film_force_at_the_film_borne_load(model):
    # seed 001 App. A share at Λ = 0.5: Q_a/Q = 1 - 1.21·0.5^0.64/(1 + 0.37·0.5^1.26) = 0.327
    Q = _MIXED[0]
    s = 1.0 - 1.21 * 0.5**0.64 / (1.0 + 0.37 * 0.5**1.26)
    assert s == pytest.approx(0.327, abs=5e-4)
    film = R.rolling_force((1 - s) * Q, *_MIXED[1:], model=model)
    assert R.rolling_force_mixed(*_MIXED, 0.5, model=model) == pytest.approx(film, rel=1e-12)
    assert R.rolling_force_mixed(*_MIXED, 0.5, model=model, c_rr_asperity=1e-3) == pytest.approx(
        film + 1e-3 * s * Q, rel=1e-12)


def test_mixed_rolling_force_limits_full_film_and_boundary():
    full = R.rolling_force(*_MIXED)
    # Λ ≥ 2.258 (and the smooth limit Λ = ∞): the full-film force, exactly
    for lam in (2.2582, 3.0, 10.0, math.inf):
        assert float(R.rolling_force_mixed(*_MIXED, lam)) == full
    # Λ = 0: every newton on asperities, no film force; only the asperity rolling resistance remains
    assert float(R.rolling_force_mixed(*_MIXED, 0.0)) == 0.0
    assert float(R.rolling_force_mixed(*_MIXED, 0.0, c_rr_asperity=2e-4)) == pytest.approx(2e-4 * _MIXED[0])


def test_mixed_rolling_force_is_continuous_and_monotonic_in_lambda():
    lam = np.linspace(0.0, 4.0, 4001)
    F = R.rolling_force_mixed(*_MIXED, lam)
    assert np.all(np.diff(F) >= 0.0)                               # more film, more film force
    # no step (dΛ = 1e-3); near Λ = 0 the film force rises as ((1 - s) Q)^(1/3) ∝ Λ^0.21, steep but continuous
    assert np.max(np.abs(np.diff(F[50:]))) < 2e-3 * R.rolling_force(*_MIXED)
    assert float(R.rolling_force_mixed(*_MIXED, 1e-12)) < 0.01 * R.rolling_force(*_MIXED)
    # a large asperity coefficient makes it fall with Λ instead, still without a step
    G = R.rolling_force_mixed(*_MIXED, lam, c_rr_asperity=0.02)
    assert np.all(np.diff(G) <= 0.0)


def test_mixed_rolling_force_vectorised_and_checked():
    lam = np.array([[0.3, 0.6], [1.0, np.inf]])
    F = R.rolling_force_mixed(*_MIXED, lam)
    assert F.shape == (2, 2)
    for i, j in np.ndindex(2, 2):
        assert F[i, j] == pytest.approx(float(R.rolling_force_mixed(*_MIXED, lam[i, j])), rel=1e-13)
    with pytest.raises(InputError):
        R.rolling_force_mixed(*_MIXED, -0.1)
    with pytest.raises(InputError):
        R.rolling_force_mixed(*_MIXED, float("nan"))
