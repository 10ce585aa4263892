"""Bearings on one rigid shaft (thermobear.loads.sets, issue 16 item 2): duplex sets with position and
spring preload against hand calculations, the thermally induced preload, a shaft on two supports, the
shaft's equilibrium and stiffness, and loads an arrangement cannot carry."""
import numpy as np
import pytest

import thermobear as tb
from thermobear.contact.fits import expanded_bearing, steel_expansion
from thermobear.errors import InputError, NoEquilibrium
from thermobear.loads.sets import Support, bearing_set, shaft_loads, shaft_on_two_supports
from thermobear.loads.static import ring_reaction

B7205 = tb.bearing("7205B")


def axial_preload(brg, d):
    """Hand calculation (Harris & Kotzalas 2007 ch. 7, thrust load; ch. 8, preloading): a ball bearing whose
    inner ring is pushed axially by d beyond first touch, all balls alike.  The groove centres, A apart, move
    from (A sin α0, A cos α0) to (A sin α0 + d, A cos α0), so tan α = tan α0 + d/(A cos α0), the approach is
    A (cos α0/cos α − 1), and F_a = Z K_n [A (cos α0/cos α − 1)]^1.5 sin α.  Returns F_a [N] and the axial
    stiffness dF_a/dd [N/m], by the chain rule dα/dd = cos²α/(A cos α0)."""
    A, a0, Z, Kn = brg.A, brg.alpha0, brg.Z, brg.Kn()
    al = np.arctan(np.tan(a0) + d / (A * np.cos(a0)))
    t = np.cos(a0) / np.cos(al) - 1.0
    Fa = Z * Kn * (A * t) ** 1.5 * np.sin(al)
    dF_dal = Z * Kn * A ** 1.5 * (1.5 * t ** 0.5 * np.cos(a0) * np.sin(al) ** 2 / np.cos(al) ** 2 + t ** 1.5 * np.cos(al))
    return Fa, dF_dal * np.cos(al) ** 2 / (A * np.cos(a0))


@pytest.mark.parametrize("arrangement", ["back_to_back", "face_to_face"])
@pytest.mark.parametrize("offset", [4e-6, 10e-6, 25e-6])
def test_position_preload_and_axial_stiffness_of_a_duplex_pair_by_hand(arrangement, offset):
    """Acceptance: a 7205B pair with a total axial offset d (each bearing d/2 beyond first touch) carries the
    preload F_a(d/2) in both bearings; under an axial load one bearing gains what the other loses, so the pair's
    axial stiffness is twice the single bearing's (1e-9)."""
    s = bearing_set(B7205, arrangement, preload_offset=offset)
    Fa, Ka = axial_preload(B7205, offset / 2)
    assert np.allclose(s.preload, Fa, rtol=1e-9)
    assert s.stiffness[0, 0] == pytest.approx(2 * Ka, rel=1e-9)
    assert np.allclose(s.q, 0.0, atol=1e-15)


def test_back_to_back_pair_carries_moments_stiffer_than_face_to_face():
    """The pressure centres of a back-to-back pair lie outside the pair, of a face-to-face pair inside: the same
    preloaded bearings resist a tilt many times more stiffly back to back (Harris & Kotzalas 2007 ch. 8)."""
    db = bearing_set(B7205, "back_to_back", preload_offset=10e-6)
    df = bearing_set(B7205, "face_to_face", preload_offset=10e-6)
    assert db.stiffness[2, 2] > 5 * df.stiffness[2, 2]
    assert db.stiffness[1, 1] == pytest.approx(df.stiffness[1, 1], rel=1e-9)      # radial: the same bearings
    assert db.stiffness[2, 2] == pytest.approx(db.stiffness[4, 4], rel=1e-9)      # both tilts alike (13 balls)


@pytest.mark.parametrize("dT", [10.0, 30.0])
def test_preload_rise_when_the_inner_rings_run_warmer(dT):
    """Acceptance: inner rings ΔT warmer than the outer rings.  Radially the inner groove centres move out by
    ε c_i (ε = α ΔT; c_i the radius of the inner groove centres, c_o of the outer), the inner groove radius
    grows by ε r_i, so the warm bearing touches at a smaller free angle: A' cos α0' = c_i(1 + ε) − c_o,
    A' = r_i(1 + ε) + r_o − D (balls at the mean rise ΔT/2).  Axially the inner stack grows against the outer
    one by ε B between the raceway planes (B the width): back to back the inner raceways move apart (each
    bearing loses ε B/2), face to face they move in (each gains ε B/2).  Each bearing's offset beyond first
    touch becomes d/2 + A sin α0 ∓ ε B/2 − A' sin α0', and its preload the hand formula at the warm geometry."""
    a = steel_expansion()
    eps, eb = a * dT, a * dT / 2
    b = B7205
    D, ca = b.D, np.cos(b.alpha0)
    ri, ro = b.fi * D, b.fo * D
    ci = (b.dm / 2 + (ri - D / 2) * ca) * (1 + eps)
    co = b.dm / 2 - (ro - D / 2) * ca
    A2 = ri * (1 + eps) + ro - D * (1 + eb)
    a02 = np.arccos((ci - co) / A2)
    warm = expanded_bearing(b, dT, 0.0, dT / 2)
    assert warm.A == pytest.approx(A2, rel=1e-12) and warm.alpha0 == pytest.approx(a02, rel=1e-12)
    cold = axial_preload(b, 5e-6)[0]
    rises = {}
    for arrangement, sign in (("back_to_back", -1), ("face_to_face", +1)):
        d_warm = 5e-6 + b.A * np.sin(b.alpha0) + sign * eps * b.width / 2 - A2 * np.sin(a02)
        hand = axial_preload(warm, d_warm)[0]
        s = bearing_set(b, arrangement, preload_offset=10e-6, dT_inner=dT)
        assert np.allclose(s.preload, hand, rtol=1e-9)
        rises[arrangement] = hand / cold
    # the radial growth raises both, the axial growth takes some of it back to back and adds face to face
    assert 1 < rises["back_to_back"] < rises["face_to_face"]
    assert rises["back_to_back"] == pytest.approx({10.0: 1.600, 30.0: 3.055}[dT], rel=1e-3)
    assert rises["face_to_face"] == pytest.approx({10.0: 2.309, 30.0: 5.816}[dT], rel=1e-3)


def test_spring_preload_holds_its_force_and_leaves_the_axial_stiffness_to_the_other_bearing():
    """Constant-force preload: the spring-held bearing carries its spring force whatever the loads; its outer
    ring slides, so the shaft's axial stiffness is the other bearing's alone."""
    F = 300.0
    s = bearing_set(B7205, "back_to_back", Fa=[0.0, 500.0, 800.0], Fr=[0.0, 300.0, 600.0], Fz=[0.0, 100.0, 0.0],
                    My=[0.0, 0.5, 0.0], preload_force=F)
    assert np.allclose(s.preload[:, 1], F, rtol=1e-10)
    assert np.allclose(s.preload[:, 0] - s.preload[:, 1], [0.0, 500.0, 800.0], rtol=0, atol=1e-7)
    ld = s.loads[0]
    q0 = np.stack([ld.delta_a, ld.delta_r, ld.theta, ld.delta_z, ld.theta_y], axis=-1)
    K0 = ring_reaction(B7205, q0)[1]
    # preload alone (no radial coupling): the set's axial stiffness is bearing 0's
    assert s.stiffness[0, 0, 0] == pytest.approx(K0[0, 0, 0], rel=1e-9)
    assert s.stiffness[0, 0, 0] == pytest.approx(axial_preload(B7205, ld.delta_a[0] - B7205.A * np.sin(B7205.alpha0))[1],
                                                 rel=1e-9)


def test_shaft_equilibrium_in_five_degrees_of_freedom():
    """The bearings' loads, carried back to the shaft (T_kᵀ P_k), balance the external loads (1e-9 of them)."""
    sups = [Support(B7205, -0.05, 1, offset=6e-6), Support(B7205, 0.05, -1, offset=6e-6)]
    loads = dict(Fa=400.0, Fr=-700.0, M=3.0, Fz=900.0, My=-8.0)
    s = shaft_loads(sups, **loads, x_load=0.02)
    P = np.zeros(5)
    for sup, R in zip(sups, s.reactions):
        sg, x = sup.facing, sup.x
        P += [sg * R[0], R[1], -x * R[1] + sg * R[2], R[3], -x * R[3] + sg * R[4]]
    want = [400.0, -700.0, 3.0 - 0.02 * -700.0, 900.0, -8.0 - 0.02 * 900.0]
    assert np.allclose(P, want, rtol=0, atol=1e-9 * 900)


def test_two_deep_groove_supports_share_a_radial_load_by_the_lever_rule():
    """A shaft on two 6208 bearings: the radial reactions sum to the load, and with the bearings' small tilt
    moments their moment balance holds exactly; the lever rule holds to the bearings' tilt stiffness (1e-3)."""
    b = tb.bearing("6208")
    span, x = 0.12, 0.04
    s = shaft_on_two_supports(b, b, span, Fr=2000.0, x_load=x)
    R1, R2 = s.reactions[:, 1]
    assert R1 + R2 == pytest.approx(2000.0, rel=1e-10)
    assert R1 == pytest.approx(2000.0 * (span - x) / span, rel=1e-3)
    dy0, _ = s.displacement_at(0.0)
    dy1, _ = s.displacement_at(span)
    assert dy0 == pytest.approx(s.loads[0].delta_r, rel=1e-9) and dy1 == pytest.approx(s.loads[1].delta_r, rel=1e-9)


def test_batched_sets_equal_their_single_cases():
    Fa = np.array([0.0, 300.0, -250.0])
    Fr = np.array([400.0, 0.0, 800.0])
    batch = bearing_set(B7205, "back_to_back", Fa, Fr, preload_offset=8e-6)
    for k in range(3):
        one = bearing_set(B7205, "back_to_back", Fa[k], Fr[k], preload_offset=8e-6)
        assert np.allclose(batch.reactions[k], one.reactions, rtol=1e-9, atol=1e-9)


def test_loads_an_arrangement_cannot_carry_are_named():
    with pytest.raises(NoEquilibrium, match="axial load towards -1x"):
        bearing_set(B7205, "tandem", Fa=-100.0, Fr=200.0)
    with pytest.raises(NoEquilibrium, match="low shoulder"):          # beyond the spring against it
        bearing_set(B7205, "face_to_face", Fa=500.0, Fr=300.0, preload_force=300.0)
    with pytest.raises(InputError, match=r"^Fa, Fr, M \(shaft loads\) = 'Fa 200000 N, Fr 0 N' — maximum contact pressure"):
        bearing_set(B7205, "back_to_back", Fa=2e5, preload_offset=5e-6)
    with pytest.raises(InputError, match="arrangement"):
        bearing_set(B7205, "side_by_side")
    with pytest.raises(InputError, match="tandem"):
        bearing_set(B7205, "tandem", preload_offset=5e-6)
