"""Oil-bath churning: the immersed share of the ball path, Pouly's drag in oil, SKF's 2018 drag term with V_M."""
import numpy as np
import pytest

from thermobear.errors import InputError
from thermobear.losses.drag import churning_loss, drag_loss, immersed_fraction
from thermobear.losses.skf import drag_loss_factor_VM, drag_moment_skf2018_Nmm, skf_moment

DM, D, Z = 60e-3, 11.9e-3, 9


def test_immersed_fraction_limits_and_symmetry():
    H = np.array([0.0, D / 2, (DM + D) / 2, DM + D, 0.2])
    w = immersed_fraction(H, DM, D)
    assert w[0] == 0.0 and w[3] == pytest.approx(1.0) and w[4] == 1.0
    assert w[2] == pytest.approx(0.5, abs=1e-3)             # oil up to the shaft axis: half the path
    assert 0 < w[1] < 0.1                                     # up to the lowest ball centre
    levels = np.linspace(0.0, DM + D, 40)
    assert np.all(np.diff(immersed_fraction(levels, DM, D)) >= 0)


def test_churning_is_pouly_in_pure_oil_times_the_immersion():
    """w = 1 is seed 004 eq 21 with X = 1 (the mixture is the oil); w scales it linearly."""
    wc, rho, mu = 130.0, 860.0, 0.032
    full = drag_loss(Z, D, DM, wc, 1.0, rho, mu, 313.15).P_W
    assert float(churning_loss(Z, D, DM, wc, 1.0, rho, mu).P_W) == pytest.approx(full, rel=1e-12)
    assert float(churning_loss(Z, D, DM, wc, 0.3, rho, mu).P_W) == pytest.approx(0.3 * full, rel=1e-12)


def test_churning_limits_and_level_trend():
    r = churning_loss(Z, D, DM, np.array([0.0, 100.0]), 0.2, 860.0, 0.032)
    assert r.P_W[0] == 0.0 and r.P_W[1] > 0
    assert float(churning_loss(Z, D, DM, 100.0, 0.0, 860.0, 0.032).P_W) == 0.0      # empty bath
    w = immersed_fraction(np.array([2e-3, 8e-3, 20e-3, 40e-3]), DM, D)
    P = churning_loss(Z, D, DM, 100.0, w, 860.0, 0.032).P_W
    assert np.all(np.diff(P) > 0)


def test_churning_stokes_limit():
    """Creeping flow: C_d = 24/Re ⇒ P = w Z 3π μ D v²."""
    wc = np.array([0.05, 0.1])
    r = churning_loss(Z, D, DM, wc, 0.4, 860.0, 5.0, cd_method="Stokes")
    v = wc * DM / 2
    np.testing.assert_allclose(r.P_W, 0.4 * Z * 3 * np.pi * 5.0 * D * v ** 2, rtol=1e-12)


def test_skf_2018_drag_hand_value_of_the_printed_equation():
    """6208 (40 × 80 mm), H = 6 mm, 3000 r/min, ν 30 mm²/s, every factor written out (SKF 17000 EN)."""
    d, Dout, H, n, nu, Kz = 40.0, 80.0, 6.0, 3000.0, 30.0, 3.1
    dm = 0.5 * (d + Dout)
    VM = float(drag_loss_factor_VM(H / dm))
    K_ball = Kz * (d + Dout) / (Dout - d) * 1e-12
    t = 2 * np.arccos((0.6 * dm - H) / (0.6 * dm))
    f_t = np.sin(t / 2)
    R_s = 0.36 * dm ** 2 * (t - np.sin(t)) * 0.05 * Kz * (Dout + d) / (Dout - d)
    M = 0.4 * VM * K_ball * dm ** 5 * n ** 2 + 1.093e-7 * n ** 2 * dm ** 3 * (n * dm ** 2 * f_t / nu) ** -1.379 * R_s
    assert float(drag_moment_skf2018_Nmm(H, nu, Kz, d, Dout, n)) == pytest.approx(M, rel=1e-12)


def test_skf_drag_factor_digitised_curve():
    """0 at H = 0; rising; SKF caps H at 1.2 dm; full immersion ≈ 1.2e-3 (the value public code hard-codes)."""
    x = np.linspace(0.0, 1.2, 50)
    V = drag_loss_factor_VM(x)
    assert V[0] == 0.0 and np.all(np.diff(V) > 0)
    assert float(drag_loss_factor_VM(1.2)) == pytest.approx(1.2e-3, rel=0.05)
    assert float(drag_loss_factor_VM(3.0)) == float(drag_loss_factor_VM(1.2))
    with pytest.raises(InputError):
        drag_loss_factor_VM(-0.1)


def test_skf_drag_limits_and_level_trend():
    H = np.array([0.0, 3.0, 8.0, 30.0, 72.0, 200.0])
    M = drag_moment_skf2018_Nmm(H, 30.0, 3.1, 40.0, 80.0, 3000.0)
    assert M[0] == 0.0 and np.all(np.diff(M[:5]) > 0) and M[5] == M[4]      # 72 mm = 1.2 dm: capped
    assert float(drag_moment_skf2018_Nmm(8.0, 30.0, 3.1, 40.0, 80.0, 0.0)) == 0.0


def test_skf_moment_oil_bath_from_the_level():
    kw = dict(R1=3.9e-7, S1=3.23e-3, R2=1.7, S2=36.5, K_z=3.1, lubrication="oil_bath")
    r = skf_moment(40, 80, "deep_groove", 30.0, 3000.0, 0.0, 2000.0, H_mm=8.0, **kw)
    assert r.M_drag == pytest.approx(float(drag_moment_skf2018_Nmm(8.0, 30.0, 3.1, 40, 80, 3000.0)) * 1e-3, rel=1e-12)
    assert r.M_total == pytest.approx(r.M_rr + r.M_sl + r.M_drag, rel=1e-12)
