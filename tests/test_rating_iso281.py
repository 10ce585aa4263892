"""ISO 281:2007 dynamic load rating, equivalent load, L10, ν1, κ, e_C, C_u, a_ISO (thermobear.rating.iso281)."""
import numpy as np
import pytest

from thermobear.errors import InputError
from thermobear.rating.iso281 import (CONTAMINATION_LEVELS, FC_GAMMA_RADIAL, FC_RADIAL, FC_THRUST,
                                      basic_rating_life, contamination_factor, dynamic_equivalent_load,
                                      dynamic_load_rating, fatigue_load_limit, fc_radial, fc_thrust,
                                      life_modification_factor, modified_rating_life, radial_load_factors,
                                      reference_viscosity, viscosity_ratio)


def _lp_shape(g, ratio=1.0):
    """Lundberg–Palmgren γ-dependence of a raceway pair with equal groove radii (Harris 2001
    ch. 18): γ^0.3 (1-γ)^1.39 (1+γ)^(-1/3) [1 + (ratio ((1-γ)/(1+γ))^1.72)^(10/3)]^(-0.3); ratio is
    the inner/outer rating ratio of the load-zone integrals, 1.04 radial (0.407/0.389), 1 thrust."""
    s = g**0.3 * (1 - g) ** 1.39 / (1 + g) ** (1 / 3)
    return s * (1 + (ratio * ((1 - g) / (1 + g)) ** 1.72) ** (10 / 3)) ** -0.3


def test_fc_tables_follow_one_smooth_lundberg_palmgren_curve():
    """Transcription check of ISO 281 Tables 2 and 4: every entry equals one constant times the
    Lundberg–Palmgren γ-shape to within the table's rounding (±0.06 plus 0.1 %).  A typo of one digit
    fails this.  (The constant is fitted here; it is not claimed to be the standard's.)"""
    cols = [(FC_GAMMA_RADIAL, FC_RADIAL, _lp_shape(FC_GAMMA_RADIAL, 1.04))]
    for a in (45.0, 60.0, 75.0):
        g, f = FC_THRUST[a]
        cols.append((g, f, _lp_shape(g)))
    g, f = FC_THRUST[90.0]
    cols.append((g, f, g**0.3))                                   # α = 90°: both washers alike
    for g, f, shape in cols:
        k = np.median(f / shape)
        assert np.all(np.abs(f - k * shape) <= 0.06 + 1e-3 * f), np.abs(f - k * shape).max()


def test_C_of_the_iso_ts_16281_bearing_by_hand():
    """C_r = b_m f_c Z^(2/3) D^1.8: gamma 0.264368 -> f_c = 58.2 - 0.4368*0.5 = 57.9816;
    1.3 * 57.9816 * 7^(2/3) * 11.5^1.8 = 22381.5 N (hand computation)."""
    fc = 58.2 - (11.5 / 43.5 - 0.26) / 0.01 * 0.5
    hand = 1.3 * fc * 7 ** (2 / 3) * 11.5**1.8
    assert dynamic_load_rating(11.5e-3, 43.5e-3, 7, 0.0, "deep_groove") == pytest.approx(hand, rel=1e-12)
    assert hand == pytest.approx(22381.5, abs=0.5)


def test_C_large_ball_branch_is_continuous_at_25_4_mm():
    """D^1.8 and 3.647 D^1.4 meet at D = 25.4 mm (25.4^0.4 = 3.647)."""
    lo = dynamic_load_rating(25.4e-3 * (1 - 1e-9), 200e-3, 12, 0.0, "deep_groove")
    hi = dynamic_load_rating(25.4e-3 * (1 + 1e-9), 200e-3, 12, 0.0, "deep_groove")
    assert hi == pytest.approx(lo, rel=2e-4)


def test_C_angular_and_thrust_forms_by_hand():
    a = np.deg2rad(40.0)
    g = 12.7 * np.cos(a) / 70.0                                # 0.138985
    fc = np.interp(g, [0.13, 0.14], [58.2, 58.8])
    hand = 1.3 * fc * np.cos(a) ** 0.7 * 15 ** (2 / 3) * 12.7**1.8
    assert dynamic_load_rating(12.7e-3, 70e-3, 15, a, "angular_contact") == pytest.approx(hand, rel=1e-12)
    # thrust 90°: C_a = b_m f_c(D/dm) Z^(2/3) D^1.8
    g = 7.938 / 36.0
    hand = 1.3 * np.interp(g, [0.22, 0.23], [92.8, 94.1]) * 12 ** (2 / 3) * 7.938**1.8
    assert dynamic_load_rating(7.938e-3, 36e-3, 12, np.pi / 2, "thrust") == pytest.approx(hand, rel=1e-12)
    # thrust 60°: C_a = b_m f_c (cos α)^0.7 tan α Z^(2/3) D^1.8, f_c between the 45° and 75° columns
    a = np.deg2rad(60.0)
    g = 10.0 * np.cos(a) / 60.0
    hand = 1.3 * fc_thrust(g, a) * np.cos(a) ** 0.7 * np.tan(a) * 20 ** (2 / 3) * 10.0**1.8
    assert dynamic_load_rating(10e-3, 60e-3, 20, a, "thrust") == pytest.approx(hand, rel=1e-12)
    with pytest.raises(InputError):
        fc_thrust(0.05, np.deg2rad(80.0))                     # no ISO column between 75° and 90°


def test_fc_radial_refuses_outside_the_table():
    assert fc_radial(0.01) == 29.1 and fc_radial(0.40) == 48.4
    with pytest.raises(InputError):
        fc_radial(0.005)


def test_radial_load_factors_table_3():
    # deep groove nodes and interpolation (f0 Fa/C0r)
    assert radial_load_factors(0.172, 0.0, "deep_groove") == (0.56, 2.30, 0.19)
    X, Y, e = radial_load_factors(0.5 * (2.07 + 3.45), 0.0, "deep_groove")
    assert (Y, e) == (pytest.approx(1.23), pytest.approx(0.36))
    assert radial_load_factors(0.01, 0.0, "deep_groove")[1] == 2.30           # below the table: first row
    # angular contact
    assert radial_load_factors(0.0, np.deg2rad(25.0), "angular_contact") == (0.41, 0.87, 0.68)
    assert radial_load_factors(0.058, np.deg2rad(15.0), "angular_contact") == (0.44, 1.30, 0.43)
    X, Y, e = radial_load_factors(0.0, np.deg2rad(27.5), "angular_contact")
    assert (X, Y, e) == (pytest.approx(0.40), pytest.approx(0.815), pytest.approx(0.74))
    with pytest.raises(InputError):
        radial_load_factors(0.1, np.deg2rad(50.0), "angular_contact")


def test_dynamic_equivalent_load_switches_at_e():
    X, Y, e = 0.56, 1.55, 0.28
    assert dynamic_equivalent_load(1000.0, 280.0, X, Y, e) == 1000.0       # Fa/Fr = e: P = Fr
    assert dynamic_equivalent_load(1000.0, 500.0, X, Y, e) == pytest.approx(560.0 + 775.0)
    assert dynamic_equivalent_load(0.0, 500.0, X, Y, e) == pytest.approx(775.0)


def test_L10_and_its_zero_load_limit():
    assert basic_rating_life(30000.0, 3000.0) == pytest.approx(1000.0)
    L = basic_rating_life(30000.0, np.array([3000.0, 1500.0, 750.0]))
    assert np.all(np.isfinite(L)) and L[2] / L[0] == pytest.approx(64.0)
    for P in (0.0, 1e-300):                                  # unloaded: refused, never inf
        with pytest.raises(InputError):
            basic_rating_life(30000.0, P)


def test_reference_viscosity_iso281_formula_by_hand():
    """ν1 = 45000 n^-0.83 dm^-0.5 (n < 1000), 4500 n^-0.5 dm^-0.5 (n >= 1000), mm²/s, mm."""
    assert reference_viscosity(500.0, 70e-3) == pytest.approx(45000 * 500**-0.83 * 70**-0.5 * 1e-6, rel=1e-12)
    assert reference_viscosity(3000.0, 70e-3) == pytest.approx(4500 / np.sqrt(3000 * 70) * 1e-6, rel=1e-12)
    n = np.array([100.0, 999.0, 1000.0, 10000.0])
    nu1 = reference_viscosity(n, 50e-3)
    assert np.all(np.diff(nu1) < 0)                                           # falls with speed
    assert nu1[1] / nu1[2] == pytest.approx(1.02, abs=0.01)                  # the standard's 2 % step
    with pytest.raises(InputError):
        reference_viscosity(0.0, 50e-3)


def test_kappa_monotone_and_a_iso_monotone_capped_continuous():
    nu = np.linspace(2e-6, 200e-6, 50)
    kappa = viscosity_ratio(nu, 10e-6)
    assert np.all(np.diff(kappa) > 0)
    k = np.linspace(0.1, 4.0, 400)
    for load in (0.01, 0.05, 0.1):
        a = life_modification_factor(k, load)
        assert np.all(np.diff(a) >= -1e-12)                                 # better film, longer life
        assert a.min() >= 0.1 - 1e-12 and a.max() <= 50.0
    # branches meet at kappa = 0.4 and 1 (ISO 281's five-digit exponents 0.054381 / 0.19087 / 0.071739 leave a
    # 0.05 % step at 0.4; rounded to 0.054 / 0.19 / 0.071, as they were here, a 1 % step)
    for kb in (0.4, 1.0):
        for load in (0.05, 0.2, 0.5):
            assert life_modification_factor(kb * (1 - 1e-9), load) == pytest.approx(
                life_modification_factor(kb, load), rel=1e-3)
    # more load (smaller e_C Cu/P) -> smaller a_ISO; a light load reaches the cap of 50
    x = np.linspace(0.0, 5.0, 200)
    a = life_modification_factor(2.0, x)
    assert np.all(np.diff(a) >= 0) and a[-1] == 50.0 and np.all(np.isfinite(a))
    assert life_modification_factor(0.05, 0.1) == life_modification_factor(0.1, 0.1)   # κ < 0.1 -> 0.1
    assert life_modification_factor(0.1, 0.1) == pytest.approx(0.1, rel=0.05)
    assert life_modification_factor(10.0, 0.1) == life_modification_factor(4.0, 0.1)   # κ > 4 -> 4


def test_a_iso_by_hand_radial_and_thrust():
    """κ = 1, e_C C_u/P = 0.25: 0.1 [1 - (2.5671 - 1.9987)^0.83 0.25^(1/3)]^-9.3 = 10.57 (hand);
    thrust ball bearings use e_C C_u / (3 P)."""
    hand = 0.1 * (1 - (2.5671 - 1.9987) ** 0.83 * 0.25 ** (1 / 3)) ** -9.3
    assert hand == pytest.approx(10.57, abs=0.01)
    assert life_modification_factor(1.0, 0.25) == pytest.approx(hand, rel=1e-12)
    assert life_modification_factor(1.0, 0.75, "thrust") == pytest.approx(hand, rel=1e-12)
    assert modified_rating_life(hand, 100.0) == pytest.approx(100 * hand)
    # the lower branches by hand with the standard's exponents: κ = 0.2 (x 2.2649, y 0.054381), κ = 0.6 (1.9987,
    # 0.19087), κ = 2 (1.9987, 0.071739)
    for k, x, y in ((0.2, 2.2649, 0.054381), (0.6, 1.9987, 0.19087), (2.0, 1.9987, 0.071739)):
        hand = 0.1 * (1 - (2.5671 - x / k ** y) ** 0.83 * 0.25 ** (1 / 3)) ** -9.3
        assert life_modification_factor(k, 0.25) == pytest.approx(hand, rel=1e-12)


def test_contamination_levels_and_fatigue_load_limit():
    assert list(CONTAMINATION_LEVELS)[0] == "extreme_cleanliness" and len(CONTAMINATION_LEVELS) == 7
    assert contamination_factor("extreme_cleanliness", 0.05) == 1.0
    assert contamination_factor("normal_cleanliness", 0.05) == pytest.approx(0.55)
    assert contamination_factor("normal_cleanliness", 0.15) == pytest.approx(0.70)
    assert contamination_factor("typical_contamination", 0.05, bound="low") == pytest.approx(0.1)
    assert contamination_factor("very_severe_contamination", 0.05) == 0.0
    mids = [contamination_factor(k, 0.05) for k in CONTAMINATION_LEVELS]
    assert mids == sorted(mids, reverse=True)                                  # cleaner -> larger e_C
    assert contamination_factor(0.42, 0.05) == 0.42
    for bad in ("clean", 1.5):
        with pytest.raises(InputError):
            contamination_factor(bad, 0.05)
    assert fatigue_load_limit(22000.0, 0.07) == pytest.approx(1000.0)
    assert fatigue_load_limit(22000.0, 0.1) == pytest.approx(1000.0)
    assert fatigue_load_limit(22000.0, 0.4) == pytest.approx(500.0)          # (100/400)^0.5
