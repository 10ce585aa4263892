"""ISO/TS 16281 reference rating life from the ball loads (thermobear.rating.iso16281).

Reference numbers: the ISO/TS 16281 example bearing (Z 7, D 11.5 mm, dm 43.5 mm, fi 0.52, fo 0.53,
steel E 210 GPa, nu 0.3, C = 23 400 N, inner ring rotating) and its displacements, tilts and L10r for the
seven example load cases as listed in minzhun/ISO16281, Test_BallBearing.py (Examples 1-7).

Conventions of the reference cases (read from that file and its Head.py): axes x, y radial (the first ball on
x, phi0 = 0), z axial; Load(Fx, Fy, Fz, Mx, My, Mz) in N and N mm.  Their (x, y, z) are our (y, z, x) — a
cyclic permutation, so a moment Mx about their x is our My (about the radial axis through ball 0: it tilts
the ring in the plane of the balls at psi = 90 deg).  Example 6 is Mx = 1000 N mm alone (our My = 1 N m),
example 7 Fx = 1000 N, Fz = 1000 N, Mx = 1000 N mm (our Fr = 1000 N, Fa = 1000 N, My = 1 N m), example 5 the
same forces with the tilt free and no moment.  The reference reports the radial displacement
|(dr, dz)|, the axial displacement from the centred position and the total misalignment |(theta, theta_y)|;
its tilts are those of the pitch radius dm/2 as the arm of tilts and moments (tilt_arm="pitch": they are
reproduced to 4e-5, with the groove-centre radius they are 1 % off and the pure-moment life 2.4 %).
"""
import numpy as np
import pytest

import thermobear as tb
from thermobear.contact.geometry import BallBearing, bearing
from thermobear.errors import InputError
from thermobear.loads.static import load_distribution
from thermobear.rating.iso16281 import (equivalent_ball_loads, iso16281_life, raceway_load_ratings, reference_life,
                                        reference_rating_life, system_life)
from thermobear.rating.life import load_ratings

STEEL = tb.Material(E=2.1e11, nu=0.3, rho=7850.0)
C_REF = 23400.0          # minzhun/ISO16281 Test_BallBearing.py: BasicCapacity(23400)


def iso(Pd):
    return BallBearing(D=11.5e-3, dm=43.5e-3, Z=7, fi=0.52, fo=0.53, Pd=Pd, kind="deep_groove",
                       ball_material=STEEL, ring_material=STEEL, name="iso-dgbb")


def l10r(brg, C, kind="deep_groove", alpha=0.0, rotating="inner", **loads):
    ld = load_distribution(brg, **loads)
    g = brg.D * np.cos(alpha) / brg.dm
    Qc = raceway_load_ratings(C, brg.Z, alpha, g, brg.fi, brg.fo, kind)
    return reference_rating_life(C, *Qc, *equivalent_ball_loads(ld.Q_i, ld.Q_o, rotating))


@pytest.mark.parametrize("case, Fa, Fr, Pd, ref", [
    (1, 0.0, 1000.0, 0.0, 13163.019),       # radial, zero clearance
    (2, 1000.0, 0.0, 0.0, 2222.7318),       # axial, zero clearance
    (3, 0.0, 1000.0, 0.01e-3, 10795.7948),  # radial, 10 um clearance
    (4, 1000.0, 0.0, 0.01e-3, 3115.8781),   # axial, 10 um clearance
    (5, 1000.0, 1000.0, 0.01e-3, 1630.5367),  # combined, clearance, tilt free without moment
])
def test_L10r_reproduces_the_iso_ts_16281_examples(case, Fa, Fr, Pd, ref):
    """Within 0.1 % (the brief asks 1 %); source of ref: minzhun/ISO16281 Test_BallBearing.py."""
    M = 0.0 if case == 5 else None
    r = l10r(iso(Pd), C_REF, Fa=Fa, Fr=Fr, M=M)
    assert float(r.L10r) == pytest.approx(ref, rel=1e-3)
    assert float(r.P_ref) == pytest.approx(C_REF * float(r.L10r) ** (-1 / 3), rel=1e-12)


def test_raceway_ratings_of_the_example_by_hand():
    """x = 1.044 ((1-γ)/(1+γ))^1.72 (0.52*0.06/(0.53*0.04))^0.41 = 0.48218 for γ = 11.5/43.5;
    Q_ci = C/(0.407 Z) (1 + x^(10/3))^0.3, Q_ce = C/(0.389 Z) (1 + x^(-10/3))^0.3 (hand computation)."""
    g = 11.5 / 43.5
    x = 1.044 * ((1 - g) / (1 + g)) ** 1.72 * (0.52 * 0.06 / (0.53 * 0.04)) ** 0.41
    qi, qe = raceway_load_ratings(C_REF, 7, 0.0, g, 0.52, 0.53, "deep_groove")
    assert qi == pytest.approx(C_REF / (0.407 * 7) * (1 + x ** (10 / 3)) ** 0.3, rel=1e-12)
    assert qe == pytest.approx(C_REF / (0.389 * 7) * (1 + x ** (-10 / 3)) ** 0.3, rel=1e-12)


def test_L10r_is_one_at_Fr_equal_C_for_many_balls():
    """The constants 0.407 / 0.389 are Lundberg–Palmgren load-zone ratios of a half-circle load zone:
    with zero clearance and F_r = C the reference life tends to 10^6 rev as Z grows (7 balls: +2.7 %)."""
    b7 = iso(0.0)
    C7 = load_ratings(b7)[0]
    assert float(l10r(b7, C7, Fr=C7).L10r) == pytest.approx(1.0, abs=0.03)
    b25 = BallBearing(D=10e-3, dm=100e-3, Z=25, fi=0.52, fo=0.53, ball_material=STEEL, ring_material=STEEL)
    C25 = load_ratings(b25)[0]
    assert float(l10r(b25, C25, Fr=C25).L10r) == pytest.approx(1.0, abs=1e-3)


def test_thrust_bearing_at_Fa_equal_C_lives_one_million_revolutions():
    """Centric axial load: every ball carries Fa/Z, the ring lives combine to exactly 1 at Fa = C_a."""
    b = bearing("51205")
    C = load_ratings(b)[0]
    r = l10r(b, C, kind="thrust", alpha=np.pi / 2, Fa=C)
    assert float(r.L10r) == pytest.approx(1.0, rel=1e-9)
    r2 = l10r(b, C, kind="thrust", alpha=np.pi / 2, Fa=C / 2)
    assert float(r2.L10r) == pytest.approx(8.0, rel=1e-9)                     # (C/P)^3


def test_rotating_outer_ring_swaps_the_equivalent_loads():
    Q = np.array([300.0, 100.0, 0.0, 0.0, 0.0, 100.0, 0.0])
    qi, qe = equivalent_ball_loads(Q, Q, "inner")
    qi2, qe2 = equivalent_ball_loads(Q, Q, "outer")
    assert (qi2, qe2) == (pytest.approx(qe), pytest.approx(qi))
    assert qe > qi                                                             # 10/3 mean > cubic mean
    with pytest.raises(InputError):
        equivalent_ball_loads(Q, Q, "cage")


def test_life_falls_with_load_and_unloaded_bearing_is_refused():
    b = iso(0.0)
    lives = [float(l10r(b, C_REF, Fr=F).L10r) for F in (500.0, 1000.0, 2000.0)]
    assert lives[0] > lives[1] > lives[2]
    Qc = raceway_load_ratings(C_REF, 7, 0.0, 11.5 / 43.5, 0.52, 0.53, "deep_groove")
    with pytest.raises(InputError):
        reference_rating_life(C_REF, *Qc, 0.0, 0.0)


#: (example, loads [N, N m], Pd [m], reference: radial |δ| [µm], axial δa [µm], tilt [mrad], L10r [10^6 rev])
EXAMPLES = [
    (1, dict(Fr=1000.0), 0.0, dict(dr=15.1101, L=13163.019)),
    (2, dict(Fa=1000.0), 0.0, dict(da=133.5381, L=2222.7318)),
    (3, dict(Fr=1000.0), 0.01e-3, dict(dr=21.223, L=10795.7948)),
    (4, dict(Fa=1000.0), 0.01e-3, dict(da=149.1717, L=3115.8781)),
    (5, dict(Fa=1000.0, Fr=1000.0, My=0.0), 0.01e-3, dict(dr=19.5923, da=146.4603, th=2.6872, L=1630.5367)),
    (6, dict(My=1.0), 0.0, dict(th=3.6957, L=785144.7521)),
    (7, dict(Fa=1000.0, Fr=1000.0, My=1.0), 0.01e-3, dict(dr=19.7144, da=146.3084, th=2.7239, L=1627.7479)),
]


@pytest.mark.parametrize("case, loads, Pd, ref", EXAMPLES, ids=[f"example{e[0]}" for e in EXAMPLES])
def test_the_seven_iso_ts_16281_examples_in_five_degrees_of_freedom(case, loads, Pd, ref):
    """Acceptance: displacements within 0.05 %, tilts and lives within 1 % (achieved: 3e-5, 4e-5, 2.2e-4)."""
    life, ld = iso16281_life(iso(Pd), C_REF, **loads)
    got = dict(dr=ld.radial_displacement * 1e6, da=ld.delta_a * 1e6, th=ld.tilt * 1e3, L=float(life.L10r))
    tol = dict(dr=5e-4, da=5e-4, th=1e-2, L=1e-2)
    for k, v in ref.items():
        assert got[k] == pytest.approx(v, rel=tol[k]), k
    assert ld.residual <= 1e-9


def test_the_moment_of_example_7_is_perpendicular_to_its_radial_load():
    """Example 7 read as a moment in the plane of the radial load (our M) misses the reference by 10 % in the
    radial displacement (validation/report/iso_ts_16281.md before the five-degree-of-freedom model); about the
    radial load's axis (our My, as Mx of the reference is) it is reproduced to 1e-5."""
    inplane = iso16281_life(iso(0.01e-3), C_REF, Fa=1000.0, Fr=1000.0, M=1.0)[1]
    across = iso16281_life(iso(0.01e-3), C_REF, Fa=1000.0, Fr=1000.0, My=1.0)[1]
    assert abs(inplane.radial_displacement * 1e6 / 19.7144 - 1) > 0.05
    assert across.radial_displacement * 1e6 == pytest.approx(19.7144, rel=5e-5)


def test_reference_life_is_batched_and_follows_the_ball_loads():
    b = iso(0.01e-3)
    ld = tb.load_distribution(b, Fa=[0.0, 1000.0], Fr=[1000.0, 1000.0], Fz=[0.0, 300.0])
    lives = reference_life(b, ld, C_REF).L10r
    assert lives.shape == (2,)
    one = reference_life(b, tb.load_distribution(b, Fr=1000.0), C_REF).L10r
    assert lives[0] == pytest.approx(one, rel=1e-12) and lives[1] < lives[0]


def test_system_life_of_equal_members_and_of_one_member():
    """L = (Σ L_k^-e)^(-1/e), e = 10/9: n equal members live n^(-9/10) as long; one member is itself."""
    assert float(system_life([500.0])) == pytest.approx(500.0, rel=1e-12)
    assert float(system_life([500.0, 500.0, 500.0])) == pytest.approx(500.0 * 3 ** -0.9, rel=1e-12)
    assert float(system_life([500.0, 1e12])) == pytest.approx(500.0, rel=1e-9)
