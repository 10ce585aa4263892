"""Operating clearance from fits, temperatures and speed (thermobear.contact.fits, issue 16 item 3): the
ISO 286 / ISO 492 limits, Lamé's thick cylinders against their limits, the rotating ring, and a 6208 C3 on a
k5 shaft in an H7 housing against a hand calculation."""
import numpy as np
import pytest

import thermobear as tb
from thermobear.contact.fits import (clearance_preload, expanded_bearing, fit_interference, fit_pressure,
                                     lame_displacement, operating_clearance, ring_deviations,
                                     raceway_growth, rotating_ring_displacement, seat_deviations,
                                     seated_raceway_growth, steel_expansion)
from thermobear.contact.geometry import radial_clearance
from thermobear.errors import InputError

UM = 1e-6


@pytest.mark.parametrize("d, zone, lo, hi", [
    (0.040, "k5", 2, 13), (0.040, "k6", 2, 18), (0.040, "m5", 9, 20), (0.040, "n6", 17, 33), (0.040, "j5", -5, 6),
    (0.060, "k5", 2, 15), (0.060, "m6", 11, 30), (0.015, "n6", 12, 23), (0.025, "m5", 8, 17),
    (0.040, "h5", -11, 0), (0.040, "js6", -8, 8),
    (0.080, "H7", 0, 30), (0.080, "J7", -12, 18), (0.080, "K7", -21, 9), (0.080, "M7", -30, 0),
    (0.080, "N7", -39, -9), (0.080, "P7", -51, -21), (0.100, "K7", -25, 10), (0.350, "H7", 0, 57),
    (0.040, "g6", -25, -9), (0.015, "g6", -17, -6), (0.010, "g6", -14, -5), (0.010, "k5", 1, 7), (0.010, "H7", 0, 15),
    (0.005, "k5", 1, 6), (0.005, "g6", -12, -4), (0.005, "N7", -16, -4),
])
def test_iso_286_limits(d, zone, lo, hi):
    """ISO 286-2 limits (the JIS B 0401 = ISO 286-2 shaft table quoted in materials/iso286_fits.toml, and the
    hole rule ES = −ei + Δ for K, M, N to IT8, P to IT7)."""
    got = seat_deviations(d, zone)
    assert got == (pytest.approx(lo * UM, abs=1e-12), pytest.approx(hi * UM, abs=1e-12))


def test_iso_492_normal_class_and_the_fits_of_a_6208():
    assert ring_deviations(0.040, "inner") == (pytest.approx(-12 * UM), 0.0)
    assert ring_deviations(0.080, "outer") == (pytest.approx(-13 * UM), 0.0)
    assert ring_deviations(0.150, "outer")[0] == pytest.approx(-18 * UM)     # the outer ring's own step
    assert np.allclose(fit_interference(0.040, "k5", "inner"), [2 * UM, 13.5 * UM, 25 * UM], rtol=0, atol=1e-12)
    assert np.allclose(fit_interference(0.080, "H7", "outer"), [-43 * UM, -21.5 * UM, 0.0], rtol=0, atol=1e-12)
    assert np.allclose(fit_interference(0.080, "N7", "outer"), [-4 * UM, 17.5 * UM, 39 * UM], rtol=0, atol=1e-12)
    with pytest.raises(InputError, match="nominal size"):
        seat_deviations(0.5, "k5")
    with pytest.raises(InputError, match="shaft"):
        fit_interference(0.040, "K7", "inner")


def test_lame_closes_the_interference_and_reaches_the_textbook_limits():
    """The interface pressure makes the ring's bore grow and the shaft shrink by I/2 together; a solid shaft of
    the ring's steel gives the raceway growth I d/d_i exactly (Harris & Kotzalas 2007 ch. 3); a thick housing
    shrinks the outer raceway by I D/d_o."""
    I, d, di, c = 20 * UM, 0.040, 0.0478, 0.016
    p = fit_pressure(I, d, c, di)
    grow = lame_displacement(d / 2, d / 2, di / 2, p_in=p)
    shrink = lame_displacement(d / 2, c / 2, d / 2, p_out=p)
    assert grow - shrink == pytest.approx(I / 2, rel=1e-12)
    p0 = fit_pressure(I, d, 0.0, di)
    assert 2 * lame_displacement(di / 2, d / 2, di / 2, p_in=p0) == pytest.approx(I * d / di, rel=1e-12)
    D, do = 0.080, 0.0732
    po = fit_pressure(I, D, do, np.inf)
    assert -2 * lame_displacement(do / 2, do / 2, D / 2, p_out=po) == pytest.approx(I * do / D, rel=1e-12)
    assert fit_pressure(-5 * UM, d, 0.0, di) == 0.0                      # a clearance fit carries nothing


def test_rotating_ring_limits():
    """The rotating annular disc tends to the solid disc as its bore closes; at its rim
    u = ρω²b[(3 + ν)a² + (1 − ν)b²]/(4E) (Timoshenko & Goodier 1970 ch. 4); u ∝ ω²."""
    w, a, b = 1000.0, 0.02, 0.024
    rim = 7830.0 * w ** 2 * b * ((3.3) * a * a + 0.7 * b * b) / (4 * 210e9)
    assert rotating_ring_displacement(b, a, b, w) == pytest.approx(rim, rel=1e-12)
    assert rotating_ring_displacement(b, 1e-9, b, w) == pytest.approx(rotating_ring_displacement(b, 0.0, b, w), rel=1e-9)
    assert rotating_ring_displacement(b, a, b, 2 * w) == pytest.approx(4 * rim, rel=1e-12)


def test_operating_clearance_of_a_6208_C3_on_k5_in_H7_by_hand():
    """Acceptance (0.5 µm): a 6208 C3 (ISO 5753 C3 at 40 mm: 15–33 µm, mid 24 µm) on a solid steel k5 shaft
    (mean interference 13.5 µm) in a thick steel H7 housing (a clearance fit: no pressure); inner ring 70 °C,
    shaft 75 °C, outer ring 55 °C, housing 45 °C, balls 62.5 °C, at rest.  By hand: the warmer shaft tightens
    the fit to I = 13.5 + α·40 mm·5 K = 16 µm, which (same steel, solid shaft) grows the inner raceway by
    I d/d_i; the free thermal growth changes the clearance by α[d_o (55 − 20) − d_i (70 − 20) − 2D (62.5 − 20)],
    d_i = d_m − D and d_o = d_m + D the raceway diameters."""
    lo, hi = radial_clearance(0.040, "C3")
    b = tb.bearing("6208").with_(Pd=0.5 * (lo + hi), clearance_group="C3")
    a = steel_expansion()
    oc = operating_clearance(b, shaft="k5", housing="H7", T_inner_C=70.0, T_outer_C=55.0, T_ball_C=62.5,
                             T_shaft_C=75.0, T_housing_C=45.0)
    d, di, do, D = 0.040, b.dm - b.D, b.dm + b.D, b.D
    I = 13.5 * UM + a * d * 5.0
    hand = 24 * UM - I * d / di + a * (do * 35.0 - di * 50.0 - 2 * D * 42.5)
    assert abs(float(oc.Pd) - hand) < 0.5 * UM
    assert float(oc.Pd) == pytest.approx(hand, abs=1e-12)               # the same formula, to round-off
    assert float(oc.interference_inner) == pytest.approx(I, rel=1e-12) and oc.pressure_outer == 0.0


def test_speed_loosens_the_fit_and_grows_the_inner_raceway():
    b = tb.bearing("6208").with_(Pd=24 * UM, clearance_group="C3")
    rest = operating_clearance(b, shaft="k5", T_inner_C=60.0, T_outer_C=50.0)
    fast = operating_clearance(b, shaft="k5", T_inner_C=60.0, T_outer_C=50.0, n_rpm=[5000.0, 20000.0])
    assert np.all(fast.interference_inner < rest.interference_inner)
    assert np.all(fast.centrifugal < 0) and fast.centrifugal[1] == pytest.approx(16 * fast.centrifugal[0], rel=1e-12)
    assert np.all(fast.Pd < rest.Pd)


def test_tighter_fits_and_warmer_inner_rings_take_clearance():
    b = tb.bearing("6208").with_(Pd=24 * UM, clearance_group="C3")
    pd = [float(operating_clearance(b, shaft=z).Pd) for z in ("j5", "k5", "m5", "n6")]
    assert pd == sorted(pd, reverse=True)
    warm = operating_clearance(b, T_inner_C=[20.0, 40.0, 60.0], T_outer_C=20.0).Pd
    assert np.all(np.diff(warm) < 0)
    assert float(operating_clearance(b).Pd) == pytest.approx(24 * UM, abs=1e-15)       # nothing changed


def test_a_negative_operating_clearance_is_a_radial_preload():
    b = tb.bearing("6208")
    assert float(clearance_preload(b, -6 * UM)) == pytest.approx(b.Kn() * (3 * UM) ** 1.5, rel=1e-12)
    assert float(clearance_preload(b, 5 * UM)) == 0.0


def test_uniform_warming_scales_the_bearing():
    """Rings and balls equally warm: every length grows by 1 + ε, the free contact angle stays."""
    b = tb.bearing("7205B")
    eps = steel_expansion() * 40.0
    w = expanded_bearing(b, 40.0, 40.0, 40.0)
    assert w.alpha0 == pytest.approx(b.alpha0, rel=1e-12)
    assert w.D == pytest.approx(b.D * (1 + eps), rel=1e-12) and w.dm == pytest.approx(b.dm * (1 + eps), rel=1e-12)
    assert w.Pd == pytest.approx(b.Pd * (1 + eps), rel=1e-9)
    assert expanded_bearing(b, 30.0, 0.0).alpha0 < b.alpha0 < expanded_bearing(b, 0.0, 30.0).alpha0
    warm = expanded_bearing(tb.bearing("6208"), 60.0, 0.0)      # the clearance closes: a radial preload
    free = tb.operating_clearance("6208", T_inner_C=80.0, T_outer_C=20.0).Pd
    assert warm.Pd < 0 and warm.alpha0 == 0.0 and warm.Pd == pytest.approx(float(free), rel=1e-3)
    assert expanded_bearing(warm, 0.0, 0.0).Pd == pytest.approx(warm.Pd, rel=1e-12)


def test_seat_materials_by_catalogue_name_equal_the_materials():
    b = tb.bearing("6208")
    by_name = tb.operating_clearance("6208", shaft="k5", housing="H7", shaft_material="aluminium-en-ac-42100",
                                     housing_material="cast-iron-gjl-250")
    given = tb.operating_clearance(b, shaft="k5", housing="H7", shaft_material=tb.material("aluminium-en-ac-42100"),
                                   housing_material=tb.material("cast-iron-gjl-250"))
    assert by_name == given
    assert by_name.pressure_inner < tb.operating_clearance(b, shaft="k5", housing="H7").pressure_inner
    with pytest.raises(InputError, match="^shaft_material = 3 — must be a Material"):
        tb.operating_clearance(b, shaft="k5", shaft_material=3)


@pytest.mark.parametrize("n_rpm", [4000.0, 8000.0, 12000.0])
def test_a_ring_on_its_seat_grows_less_at_speed_than_a_free_one(n_rpm):
    """The inner raceway's growth at speed on an interference seat: the free ring's centrifugal growth less the fit's
    relief (the ring's bore grows more than the solid shaft's: the interference and the fit's expansion fall).  A
    loose seat (a clearance) leaves the ring free; a tight one takes back most of the growth, the same at any speed
    (both ∝ ω²); it is operating_clearance's change of the clearance with speed, halved."""
    b = tb.bearing("7014C")
    free = raceway_growth(b, n_rpm)
    assert seated_raceway_growth(b, n_rpm) == free
    assert seated_raceway_growth(b, n_rpm, I_inner_m=-10e-6) == pytest.approx(free, rel=1e-12)
    tight = seated_raceway_growth(b, n_rpm, I_inner_m=16e-6)
    assert 0.0 < tight < 0.3 * free and tight / free == pytest.approx(0.62 / 2.96, rel=0.02)
    oc = operating_clearance(b, shaft="k5", n_rpm=np.array([0.0, n_rpm]))
    assert seated_raceway_growth(b, n_rpm, shaft="k5") == pytest.approx(-0.5 * float(oc.Pd[1] - oc.Pd[0]), rel=1e-12)
