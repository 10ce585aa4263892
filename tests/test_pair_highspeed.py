"""A preloaded pair at speed (thermobear.loads.shaftspeed, thermobear.loads.pair with n_rpm, thermobear.contact.fits
raceway_growth): each bearing's high-speed load–displacement (the balls' centrifugal force and gyroscopic moment,
Jones 1960) and the inner rings' centrifugal growth in the pair's compatibility."""
import numpy as np
import pytest

import thermobear as tb
from thermobear.contact.fits import operating_clearance, raceway_growth
from thermobear.errors import NoEquilibrium
from thermobear.loads.pair import pair_loads, pair_preload_offset
from thermobear.loads.sets import duplex_supports, shaft_loads, warm_supports
from thermobear.loads.shaftspeed import shaft_loads_high_speed

B = tb.bearing("7014C")
PAIRS = ("back_to_back", "face_to_face")


@pytest.mark.parametrize("arrangement", PAIRS)
@pytest.mark.parametrize("n_rpm", [0.0, 1.0])
@pytest.mark.parametrize("Fa, Fr, dT", [(0.0, 0.0, 0.0), (0.0, 2020.0, 0.0), (400.0, 1500.0, 0.0),
                                        (250.0, 800.0, 12.0)])
def test_at_rest_the_pair_at_speed_is_the_static_pair(arrangement, n_rpm, Fa, Fr, dT):
    """n → 0: the high-speed relation is the static one (no centrifugal force, no ring growth), and so is the pair's
    compatibility: the loads of bearing_set's rigid shaft to ~1e-6 relative, warm rings and an external load alike."""
    kw = dict(dT_inner=dT, dT_outer=0.5 * dT, spacer=0.01)
    ref = pair_loads(B, arrangement, 300.0, "position", Fa, Fr, **kw)
    hs = pair_loads(B, arrangement, 300.0, "position", Fa, Fr, n_rpm=n_rpm, **kw)
    for name in ("Fa", "Fr", "Fa_other", "preload"):
        assert getattr(hs, name) == pytest.approx(getattr(ref, name), rel=1e-6, abs=1e-6), name
    assert hs.loaded == ref.loaded and hs.offset == ref.offset


def test_the_shaft_at_rest_moves_as_the_static_shaft():
    """The shaft's displacement (δa, δr, θ) at n = 0 is shaft_loads's, with a radial load off the pair's centre."""
    sups, _ = duplex_supports(B, "back_to_back", preload_offset=pair_preload_offset(B, 300.0))
    st = shaft_loads(sups, 100.0, 1500.0, x_load=0.01)
    hs = shaft_loads_high_speed(sups, 100.0, 1500.0, 0.0, x_load=0.01)
    assert np.allclose(hs.q, st.q[:3], rtol=1e-6, atol=1e-6 * B.A)
    assert np.allclose(hs.reactions, st.reactions, rtol=1e-6, atol=1e-6 * 1500.0)
    assert hs.q[2] != 0.0                               # the off-centre load tilts the shaft


@pytest.mark.parametrize("arrangement", PAIRS)
def test_a_position_preload_rises_with_speed_at_constant_temperature(arrangement):
    """At the mounting temperature the position preload of the pair rises monotonically with speed (SKF's strain
    gauges: 'a marked increase in preload at very high rotational speeds', the centrifugal forces on the balls; Li &
    Shin 2004; Harris & Kotzalas 2007): the balls' centrifugal force alone, and more with the inner rings' growth."""
    speeds = [0.0, 3000.0, 6000.0, 9000.0, 12000.0, 15000.0]
    F = [pair_loads(B, arrangement, 300.0, n_rpm=n).preload for n in speeds]
    assert F[0] == pytest.approx(300.0, rel=1e-9) and np.all(np.diff(F) > 0)
    sups, _ = duplex_supports(B, arrangement, preload_offset=pair_preload_offset(B, 300.0))
    balls = shaft_loads_high_speed(sups, n_rpm=12000.0).preload[0]
    assert 300.0 < balls < F[4]


def test_the_examples_cold_preload_at_12000_rpm():
    """examples/spindle_7014C_pair_oil_air.toml, 7014C back-to-back, 300 N cold (20.78 µm offset), at 12 000 rpm
    (the example runs at 8000): at the static position the balls' centrifugal force alone gives 903 N (902.6 N); the
    free inner rings' centrifugal growth, 2.96 µm on the raceway's radius (the operating clearance's −5.9 µm
    diametral), moves each bearing's groove centres 11.6 µm further into the balls at α0 = 15° and the pair carries 1269 N; with the
    example's 2020 N radial load on the pair its loaded bearing carries 1352 N."""
    s = tb.load_scene(tb.example_path("spindle_7014C_pair_oil_air.toml"))
    d = pair_preload_offset(s.bearing, 300.0)
    assert d * 1e6 == pytest.approx(20.78, abs=0.01)
    sups, _ = duplex_supports(s.bearing, "back_to_back", preload_offset=d)
    assert shaft_loads_high_speed(sups, n_rpm=12000.0).preload[0] == pytest.approx(902.6, abs=0.1)
    u = raceway_growth(s.bearing, 12000.0)
    oc = operating_clearance(s.bearing, n_rpm=12000.0)
    assert u * 1e6 == pytest.approx(2.96, abs=0.01) and float(oc.centrifugal) == pytest.approx(-2.0 * u, rel=1e-12)
    grown = warm_supports(sups, n_rpm=12000.0)
    assert (grown[0].offset - sups[0].offset) * 1e6 == pytest.approx(11.64, abs=0.02)
    p = pair_loads(s.bearing, "back_to_back", 300.0, Fr=s.Fr, n_rpm=12000.0)
    assert p.preload == pytest.approx(1269.0, abs=1.0) and p.Fa == pytest.approx(1352.0, abs=1.0)
    assert p.Fr == pytest.approx(1010.0, rel=1e-9)


@pytest.mark.parametrize("arrangement", PAIRS)
def test_the_loads_balance_the_external_loads_at_speed(arrangement):
    """Fa_A − Fa_B = the external axial load, the radial loads share the external one, at 12 000 rpm, warm."""
    p = pair_loads(B, arrangement, 300.0, "position", 600.0, 2000.0, n_rpm=12000.0, dT_inner=15.0, dT_outer=10.0)
    assert p.Fa - p.Fa_other == pytest.approx(600.0, rel=1e-9)
    sups, _ = duplex_supports(B, arrangement, preload_offset=pair_preload_offset(B, 300.0))
    hs = shaft_loads_high_speed(warm_supports(sups, 15.0, 10.0, n_rpm=12000.0), 600.0, 2000.0, 12000.0, x_load=0.004)
    R, s = hs.reactions, [sp.facing for sp in sups]
    assert s[0] * R[0, 0] + s[1] * R[1, 0] == pytest.approx(600.0, rel=1e-9)
    assert R[0, 1] + R[1, 1] == pytest.approx(2000.0, rel=1e-9)
    x = [sp.x for sp in sups]                           # moments about x = 0: the radial load's at x_load
    assert (-x[0] * R[0, 1] + s[0] * R[0, 2] - x[1] * R[1, 1] + s[1] * R[1, 2]) == pytest.approx(-0.004 * 2000.0,
                                                                                                  rel=1e-8)
    assert hs.residual < 1e-10 and all(ld.residual < 1e-9 for ld in hs.loads)


def test_a_spring_preload_keeps_its_force_at_speed():
    """A spring preload is a force: at 12 000 rpm, warm, the spring-held bearing carries it whatever the speed; an
    external axial load goes to the other bearing; the outer ring slides."""
    for Fa in (0.0, 500.0):
        p = pair_loads(B, "back_to_back", 300.0, "spring", Fa, 1500.0, n_rpm=12000.0, dT_inner=20.0, dT_outer=10.0)
        assert p.preload == pytest.approx(300.0, rel=1e-9) and p.Fa_other == pytest.approx(300.0, rel=1e-9)
        assert p.Fa == pytest.approx(300.0 + Fa, rel=1e-9) and p.offset is None


@pytest.mark.parametrize("arrangement", PAIRS)
def test_without_external_loads_both_bearings_carry_alike(arrangement):
    sups, _ = duplex_supports(B, arrangement, preload_offset=pair_preload_offset(B, 300.0))
    hs = shaft_loads_high_speed(warm_supports(sups, 20.0, 10.0, 30.0, n_rpm=12000.0), n_rpm=12000.0)
    assert hs.reactions[0, 0] == pytest.approx(hs.reactions[1, 0], rel=1e-9)
    assert np.all(np.abs(hs.reactions[:, 1:3]) < 1e-6) and np.all(np.abs(hs.q[1:]) < 1e-12)
    assert np.all(hs.extras[0].Fc > 0.0) and np.all(hs.loads[0].alpha_i > hs.loads[0].alpha_o)   # at speed: α_i > α_o


def test_an_axial_load_that_unloads_a_bearing_at_speed_is_refused_by_name():
    """The high-speed form needs both bearings loaded axially: an external axial load beyond what the preload holds
    is NoEquilibrium naming the shaft loads (not a NaN, not a silent static answer)."""
    with pytest.raises(NoEquilibrium) as e:
        pair_loads(B, "back_to_back", 300.0, "position", 20000.0, 0.0, n_rpm=12000.0)
    assert e.value.field == "Fa, Fr, M (shaft loads)"


@pytest.mark.parametrize("kind", ["position", "spring"])
def test_a_solve_started_from_a_nearby_answer_is_the_same_answer(kind):
    """shaft_loads_high_speed(start=answer) and pair_loads(start=...): the nearby answer's loads and its bearings'
    ball equilibria start the solve (a heat-up's next piece); the answer is the cold start's to the tolerance, in
    fewer Newton steps."""
    pre = dict(preload_offset=pair_preload_offset(B, 300.0)) if kind == "position" else dict(preload_force=300.0)
    sups, _ = duplex_supports(B, "back_to_back", **pre)
    near_sups = warm_supports(sups, 18.0, 10.0, 24.0, n_rpm=12000.0)
    far_sups = warm_supports(sups, 20.0, 10.0, 26.0, n_rpm=12000.0)
    Fa, Fr = [0.0, 0.0], [2020.0, 0.0]
    near = shaft_loads_high_speed(near_sups, Fa, Fr, 12000.0)
    cold = shaft_loads_high_speed(far_sups, Fa, Fr, 12000.0)
    warm = shaft_loads_high_speed(far_sups, Fa, Fr, 12000.0, start=near)
    assert warm.reactions == pytest.approx(cold.reactions, rel=1e-8, abs=1e-6)
    assert warm.q == pytest.approx(cold.q, rel=1e-7, abs=1e-12) and warm.iterations <= cold.iterations
    a = pair_loads(B, "back_to_back", 300.0, kind, Fr=2020.0, dT_inner=18.0, dT_outer=10.0, n_rpm=12000.0)
    b = pair_loads(B, "back_to_back", 300.0, kind, Fr=2020.0, dT_inner=20.0, dT_outer=10.0, n_rpm=12000.0, start=a)
    c = pair_loads(B, "back_to_back", 300.0, kind, Fr=2020.0, dT_inner=20.0, dT_outer=10.0, n_rpm=12000.0)
    assert (b.Fa, b.Fr, b.preload) == pytest.approx((c.Fa, c.Fr, c.preload), rel=1e-8)
