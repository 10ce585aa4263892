"""Hertz point contact: exact solution against published/tabulated values and the
approximations' error over Ry/Rx = 1…50 (issue 2 acceptance)."""
import warnings

import numpy as np
import pytest
from scipy.special import ellipe, ellipk

from thermobear.errors import InputError
from thermobear.contact.hertz import ellipticity, hertz, series_stiffness


def test_circular_contact_is_classical_hertz():
    # sphere on sphere, Rx = Ry = R0: a = b = (3 Q R / (2 E'))^(1/3) with R = R0/2, p = 3Q/(2 pi a^2)
    Q, R0, Ep = 100.0, 5e-3, 2.3e11
    c = hertz(Q, R0, R0, Ep)
    # Rx = Ry = R0 are the reduced radii (two spheres of radius 2 R0)
    a = (3 * Q * R0 / (2 * Ep)) ** (1 / 3)
    assert c.kappa == pytest.approx(1.0, abs=1e-12)
    assert c.a == pytest.approx(a, rel=1e-12) and c.b == pytest.approx(a, rel=1e-12)
    assert c.delta == pytest.approx(a**2 / R0, rel=1e-12)            # δ = a²/R for a circle
    assert c.p_max == pytest.approx(1.5 * Q / (np.pi * a * a), rel=1e-12)


def test_exact_matches_harris_209_table():
    # exact solution (Hertz 1881; Harris 2001 ch. 6) of the 209 bearing at Q = 4527 N (independent script)
    inner = hertz(4527.0, 5.109e-3, 165.1e-3, 228e9)
    outer = hertz(4527.0, 7.591e-3, 165.1e-3, 228e9)
    assert inner.kappa == pytest.approx(9.285, abs=2e-3)
    assert (inner.a, inner.b) == (pytest.approx(2.545e-3, rel=5e-4), pytest.approx(0.2742e-3, rel=5e-4))
    assert inner.delta == pytest.approx(26.98e-6, rel=5e-4)
    assert inner.p_max == pytest.approx(3.097e9, rel=5e-4)
    assert outer.kappa == pytest.approx(7.295, abs=2e-3)
    assert outer.delta == pytest.approx(26.00e-6, rel=5e-4)
    assert outer.p_max == pytest.approx(2.588e9, rel=5e-4)


def test_ellipticity_satisfies_curvature_difference():
    r = np.geomspace(1.0001, 200.0, 300)
    k = ellipticity(r)
    m = 1 - 1 / k**2
    F = ((k**2 + 1) * ellipe(m) - 2 * ellipk(m)) / ((k**2 - 1) * ellipe(m))
    np.testing.assert_allclose(F, (r - 1) / (r + 1), rtol=0, atol=1e-11)
    assert np.all(np.diff(k) > 0)


def test_ellipticity_root_over_the_whole_range_from_near_circular_to_1e5():
    from thermobear.contact.hertz import _f_rho
    r = np.concatenate([np.exp(np.linspace(0.0, np.log(1e5), 400)), [1.0, 1.00005, 1.0002, 5.0, 32.3]])
    k = ellipticity(r)
    circ = r < 1.0001                  # leading-order root (Ry/Rx)^(2/3) where F(ρ) cancels 0/0
    res = np.where(circ, 0.0, _f_rho(np.where(circ, 2.0, k)) - (r - 1.0) / (r + 1.0))
    assert np.max(np.abs(res)) <= 1e-10
    np.testing.assert_allclose(k[circ], r[circ] ** (2.0 / 3.0), rtol=1e-12)
    assert np.all(k >= 1.0) and np.all(np.diff(k[:400]) > 0)


def test_load_deflection_consistency():
    Q = np.array([1.0, 10.0, 1000.0])
    c = hertz(Q, 4e-3, 80e-3, 2.3e11)
    np.testing.assert_allclose(c.K * c.delta**1.5, Q, rtol=1e-12)
    np.testing.assert_allclose(c.p_max * 2 * np.pi * c.a * c.b / 3, Q, rtol=1e-12)


def test_swapped_axes_are_symmetric():
    c1 = hertz(50.0, 4e-3, 40e-3, 2.3e11)
    c2 = hertz(50.0, 40e-3, 4e-3, 2.3e11)
    assert c2.a == pytest.approx(c1.b, rel=1e-12) and c2.b == pytest.approx(c1.a, rel=1e-12)
    assert c2.delta == pytest.approx(c1.delta, rel=1e-12)


def test_zero_load_gives_zero_contact_without_nan():
    c = hertz(np.array([0.0, 1.0]), 4e-3, 40e-3, 2.3e11)
    assert c.a[0] == 0 and c.b[0] == 0 and c.delta[0] == 0 and c.p_max[0] == 0
    assert np.all(np.isfinite([c.a, c.b, c.delta, c.p_max]))


APPROX_TOL = {  # max |relative error| over Ry/Rx = 1…50: measured maxima (printed table) + ~10 %
    "hamrock_brewe": {"a": 0.031, "b": 0.011, "delta": 0.060, "p_max": 0.024},
    "brewe_hamrock": {"a": 0.030, "b": 0.013, "delta": 0.030, "p_max": 0.018},
    "houpert": {"a": 0.16, "b": 0.026, "delta": 0.060, "p_max": 0.14},
}


def test_hamrock_brewe_within_1_5_percent_in_ball_bearing_range():
    # Hamrock & Brewe 1983: within about 1.5 % for ball–race contacts (Ry/Rx ≈ 8–40); measured max 1.52 %
    ratio = np.linspace(8, 40, 30)
    ex = hertz(500.0, 5e-3, 5e-3 * ratio, 2.31e11)
    ap = hertz(500.0, 5e-3, 5e-3 * ratio, 2.31e11, method="hamrock_brewe")
    for q in ("a", "b", "delta", "p_max"):
        assert np.max(np.abs(getattr(ap, q) / getattr(ex, q) - 1)) < 0.016, q


@pytest.mark.parametrize("method", list(APPROX_TOL))
def test_approximation_error_table(method, capsys):
    """Tabulate each approximation's error against the exact solution over Ry/Rx = 1…50."""
    ratio = np.array([1.0, 1.5, 2, 3, 5, 7, 10, 15, 20, 30, 40, 50])
    Rx = 5e-3
    ex = hertz(100.0, Rx, Rx * ratio, 2.31e11)
    ap = hertz(100.0, Rx, Rx * ratio, 2.31e11, method=method)
    rows = []
    for q, tol in APPROX_TOL[method].items():
        err = getattr(ap, q) / getattr(ex, q) - 1.0
        rows.append((q, err))
        assert np.max(np.abs(err)) < tol, (method, q, err)
    with capsys.disabled():
        print(f"\n{method}: relative error vs exact, Ry/Rx = {ratio.tolist()}")
        for q, err in rows:
            print(f"  {q:6s} " + " ".join(f"{e:+.4f}" for e in err))


def test_houpert_close_at_seed000_contact():
    # Houpert's a, b (seed 000 eqs 9–10) at seed 000's contact (k = 17.7): a within 0.4 %, b within 1.3 %
    Rx = 7.938e-3 / 2
    Ry = 0.53 * 7.938e-3 / (2 * 0.53 - 1)
    ex, ho = hertz(1.42, Rx, Ry, 2.3e11), hertz(1.42, Rx, Ry, 2.3e11, method="houpert")
    assert abs(ho.a / ex.a - 1) < 0.0045 and abs(ho.b / ex.b - 1) < 0.013


def test_series_stiffness_209():
    assert series_stiffness(3.231e10, 3.416e10) == pytest.approx(1.174e10, rel=1e-3)


@pytest.mark.parametrize("kw", [dict(Q=-1.0), dict(Rx=0.0), dict(Ry=-1e-3), dict(E_prime=np.nan)])
def test_bad_input(kw):
    args = dict(Q=1.0, Rx=1e-3, Ry=1e-2, E_prime=2e11) | kw
    with pytest.raises(InputError) as e:
        hertz(**args)
    assert list(kw)[0] in str(e.value)


def test_unknown_method():
    with pytest.raises(InputError, match="method"):
        hertz(1.0, 1e-3, 1e-2, 2e11, method="magic")


def test_nearly_circular_contact_takes_the_leading_order_ellipticity():
    # Ry/Rx − 1 = 2e-8: F(ρ) cancels 0/0 in floating point; κ = (Ry/Rx)^(2/3) to O((Ry/Rx − 1)²)
    c = hertz(10.0, 5e-3, 5.0000001e-3, 2.3e11)
    assert c.kappa == pytest.approx(1.0 + (2 / 3) * 2e-8, abs=1e-12)


def test_a_contact_beyond_its_radii_or_the_float_range_is_refused_by_name():
    # hertz(100, 1e-300, 1e-2, 228e9) returned a = inf (with overflow warnings)
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        with pytest.raises(InputError, match=r"^Rx, Ry = 1e\+298 — the larger over the smaller radius must be <= 1e\+10"):
            hertz(100.0, 1e-300, 1e-2, 228e9)
        with pytest.raises(InputError, match=r"Hertz contact size / radius of curvature must lie in \[0, 1\]"):
            hertz(58605.0, 0.015625, 0.0078125, 1e9)            # a soft, heavily loaded contact: a > Ry
        with pytest.raises(InputError, match="Hertz contact size"):
            hertz(1.7e308, 1e-30, 1e-30, 1.7e308)               # beyond the float range
        with pytest.raises(InputError, match=r"^Q, Rx, Ry, E_prime = 'shapes \(4,\), \(3,\), \(\), \(\)' — must broadcast"):
            hertz(np.ones(4), np.full(3, 1e-3), 1e-2, 2e11)


def test_a_vanishing_load_gives_a_vanishing_contact_not_zero_times_infinity():
    # a = c Q^(1/3): a subnormal load keeps the ellipse's shape and a finite pressure
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        tiny, one = hertz(5e-324, 1e-3, 1e-2, 2e11), hertz(1.0, 1e-3, 1e-2, 2e11)
    assert tiny.a / one.a == pytest.approx(np.cbrt(5e-324), rel=1e-12)
    assert tiny.p_max / one.p_max == pytest.approx(np.cbrt(5e-324), rel=1e-12) and tiny.p_max > 0
