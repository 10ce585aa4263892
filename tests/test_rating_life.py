"""rating_life: ISO 76 / ISO 281 / ISO/TS 16281 put together for one bearing and load case."""
import numpy as np
import pytest

import thermobear as tb
from thermobear.contact.geometry import bearing
from thermobear.errors import InputError
from thermobear.loads.static import load_distribution
from thermobear.rating.iso281 import (dynamic_load_rating, fatigue_load_limit, life_modification_factor,
                                      reference_viscosity)
from thermobear.rating.life import RatingLife, equivalent_loads, load_ratings, rating_life


def test_public_name_and_frozen_result():
    r = tb.rating_life(bearing("iso-dgbb"), Fr=1000.0)
    assert isinstance(r, tb.RatingLife)
    with pytest.raises(AttributeError):
        r.C_N = 1.0                                          # frozen


def test_ratings_and_life_agree_with_the_standard_functions():
    b = bearing("7210")
    r = rating_life(b, Fa=2000.0, Fr=1000.0, nu_m2_s=30e-6, n_rpm=3000.0, contamination="high_cleanliness")
    C, C0 = load_ratings(b)
    assert r.C_N == C == pytest.approx(dynamic_load_rating(b.D, b.dm, b.Z, b.alpha0, "angular_contact"))
    # 40°: Fa/Fr = 2 > e = 1.14 -> P = 0.35 Fr + 0.57 Fa; P0 = 0.5 Fr + 0.26 Fa (ISO 281, ISO 76)
    assert r.P_N == pytest.approx(0.35 * 1000 + 0.57 * 2000)
    assert r.P0_N == pytest.approx(0.5 * 1000 + 0.26 * 2000)
    assert r.s0 == pytest.approx(C0 / r.P0_N)
    assert r.L10_Mrev == pytest.approx((C / r.P_N) ** 3)
    assert r.L10_h == pytest.approx(r.L10_Mrev * 1e6 / (60 * 3000.0))
    nu1 = reference_viscosity(3000.0, b.dm)
    assert r.kappa == pytest.approx(30e-6 / nu1)
    assert r.e_C == pytest.approx(0.7) and r.C_u_N == pytest.approx(fatigue_load_limit(C0, b.dm))
    assert r.a_ISO == pytest.approx(life_modification_factor(r.kappa, r.e_C * r.C_u_N / r.P_N))
    assert r.L10m_Mrev == pytest.approx(r.a_ISO * r.L10_Mrev)
    assert r.L10m_h == pytest.approx(r.L10m_Mrev * 1e6 / (60 * 3000.0))
    assert set(r.p_max_Pa) == {"inner", "outer"} and r.L10r_Mrev > 0 and r.L10mr_Mrev > 0


def test_given_load_distribution_is_used_and_checked():
    b = bearing("iso-dgbb")
    ld = load_distribution(b, Fa=300.0, Fr=1000.0)
    r = rating_life(b, ld)
    assert r.P_N == pytest.approx(equivalent_loads(b, 1000.0, 300.0, r.C0_N)[0])
    assert r.L10r_Mrev == pytest.approx(rating_life(b, Fa=300.0, Fr=1000.0).L10r_Mrev, rel=1e-9)
    with pytest.raises(InputError):
        rating_life(b, ld, Fr=2000.0)                        # conflicting loads
    with pytest.raises(InputError):
        rating_life(b, load_distribution(b, Fr=np.array([500.0, 1000.0])))   # one case at a time


def test_light_load_limit_is_finite_and_unloaded_is_refused():
    b = bearing("iso-dgbb")
    lives = [rating_life(b, Fr=F, nu_m2_s=50e-6, n_rpm=1500.0) for F in (1000.0, 100.0, 1.0)]
    L = [x.L10_Mrev for x in lives]
    assert L[0] < L[1] < L[2] and all(np.isfinite(L))
    assert lives[2].a_ISO == 50.0 and any("a_ISO capped" in n for n in lives[2].notes)
    with pytest.raises(InputError):
        rating_life(b, Fr=0.0)
    with pytest.raises(InputError):
        rating_life(b, Fr=1000.0, n_rpm=0.0)


def test_overload_is_named_not_hidden():
    b = bearing("iso-dgbb")
    C0 = load_ratings(b)[1]
    r = rating_life(b, Fr=1.5 * C0)
    assert r.s0 < 1 and r.pressure_ratio > 1
    assert any("exceeds C0" in n for n in r.notes) and any("4200 MPa" in n for n in r.notes)
    r = rating_life(b, Fr=0.1 * C0, nu_m2_s=1e-6, n_rpm=100.0)
    assert r.kappa < 0.1 and any("kappa" in n for n in r.notes)


def test_thrust_bearing_axial_only_and_single_acbb_radial_note():
    t = bearing("51107")
    r = rating_life(t, Fa=7000.0, nu_m2_s=50e-6, n_rpm=1000.0)
    assert r.P_N == 7000.0 and r.P0_N == 7000.0
    assert r.L10r_Mrev == pytest.approx(r.L10_Mrev, rel=1e-9)                # equal balls: same life
    with pytest.raises(InputError):
        rating_life(t, Fa=7000.0, Fr=100.0)
    r = rating_life(bearing("7210"), Fr=1000.0)               # no axial reaction: no equilibrium
    assert r.L10r_Mrev is None and any("no load distribution" in n for n in r.notes)


def test_maker_ratings_can_replace_the_iso_values():
    b = bearing("iso-dgbb")
    r = rating_life(b, Fr=1000.0, C_N=23400.0, C0_N=11600.0)
    assert r.C_N == 23400.0 and r.L10_Mrev == pytest.approx(23.4**3)
    assert isinstance(r, RatingLife)


def test_a_stated_rating_the_geometry_does_not_give_is_named():
    """The 7210 states C0 = 25.5 kN (seed 004), its geometry gives 28.6 kN under ISO 76: rating_life uses the
    geometry's and says so (a scene's ratings use the stated: s0 12.75 there, 14.29 here); given, no note."""
    r = rating_life(bearing("7210"), Fr=2000.0, Fa=1000.0)
    assert [n for n in r.notes if n.startswith("C0 = 28.58 kN from the geometry")] and r.s0 == pytest.approx(14.29, abs=0.01)
    assert not [n for n in r.notes if n.startswith("C = ")]
    given = rating_life(bearing("7210"), Fr=2000.0, Fa=1000.0, C0_N=25500.0)
    assert not [n for n in given.notes if "from the geometry" in n] and given.s0 == pytest.approx(12.75)
    assert not [n for n in rating_life(bearing("6208"), Fr=2000.0).notes if "from the geometry" in n]


def test_rating_life_takes_a_bearing_name_and_refuses_a_load_distribution_that_is_not_one():
    kw = dict(Fr=2000.0, nu_m2_s=30e-6, n_rpm=3000.0)
    assert rating_life("6208", **kw).L10m_Mrev == rating_life(bearing("6208"), **kw).L10m_Mrev
    with pytest.raises(InputError, match="^ld = 'x' — must be a LoadDistribution"):
        rating_life(bearing("6208"), "x")


@pytest.mark.parametrize("kw, message", [(dict(C0_N=0.0), r"^C0_N = 0.0 — must be > 0 \[N\]"),
                                         (dict(C_N=-1.0), r"^C_N = -1.0 — must be > 0 \[N\]"),
                                         (dict(C_N=np.nan), r"^C_N = nan — must be finite"),
                                         (dict(C0_N="x"), r"^C0_N = 'x' — must be a number")])
def test_stated_load_ratings_must_be_finite_and_positive(kw, message):
    with pytest.raises(InputError, match=message):
        rating_life(bearing("6208"), Fa=0.0, Fr=2000.0, nu_m2_s=30e-6, n_rpm=3000.0, **kw)
