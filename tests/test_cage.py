"""Cage losses (thermobear.losses.cage): Petroff land friction, the cage equilibrium, limits."""
import numpy as np
import pytest

from thermobear.errors import InputError
from thermobear.losses.cage import (cage_land_estimate, cage_land_torque_petroff, cage_loss, pocket_force,
                                     pocket_sliding_power)

ETA, DL, BL, CL = 0.024, 68e-3, 4.5e-3, 0.34e-3


def test_petroff_hand_value():
    """T = shear stress η ω r / c × land surface π d b × radius d/2 (Petroff 1883), by hand."""
    w = 130.0
    tau = ETA * w * (DL / 2) / CL
    T = tau * np.pi * DL * BL * DL / 2
    assert float(cage_land_torque_petroff(ETA, DL, BL, CL, w)) == pytest.approx(T, rel=1e-12)


def test_cage_equilibrium_pocket_forces_carry_the_land_torque():
    T, Z, dm = 0.0123, 9, 60e-3
    assert pocket_force(T, Z, dm) * Z * dm / 2 == pytest.approx(T, rel=1e-14)


def test_pocket_sliding_hand_value():
    wb = np.full(9, 800.0)
    assert float(pocket_sliding_power(0.05, 0.04, 11.9e-3, wb)) == pytest.approx(0.05 * 0.04 * 11.9e-3 / 2 * 800 * 9)


def test_cage_loss_vanishes_at_standstill_and_grows_as_speed_squared():
    w = np.array([0.0, 50.0, 100.0])
    wb = np.outer(w / 50.0 * 300.0, np.ones(9))           # ball spin ∝ speed
    r = cage_loss(ETA, 9, 11.9e-3, 60e-3, w, wb, 0.05, DL, BL, CL)
    assert r.P_W[0] == 0.0 and r.P_land_W[0] == 0.0 and r.P_pocket_W[0] == 0.0
    assert r.P_land_W[2] / r.P_land_W[1] == pytest.approx(4.0, rel=1e-12)
    assert r.P_pocket_W[2] / r.P_pocket_W[1] == pytest.approx(4.0, rel=1e-12)
    assert np.allclose(r.P_W, r.P_land_W + r.P_pocket_W, rtol=1e-14)


def test_land_estimate_and_refusal_for_a_ball_centred_cage():
    e = cage_land_estimate("inner_ring", 40.0, 80.0, 18.0)
    assert e["d_land"] == pytest.approx(52e-3) and e["b_land"] == pytest.approx(4.5e-3)
    with pytest.raises(InputError) as exc:
        cage_land_estimate("balls", 40.0, 80.0, 18.0)
    assert exc.value.field == "bearing.cage"
