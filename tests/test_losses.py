"""Bearing totals of the local loss model: conservation, limits and the seed 004 trends."""
import numpy as np
import pytest

import thermobear as tb
from thermobear.errors import InputError
from thermobear.losses.local import BREAKDOWN_KEYS, bearing_losses

B7210 = tb.bearing("7210")
OIL = tb.lubricant("seed004-mineral")
JET = dict(oil_flow_m3_s=10e-3 / 3600, supply="oil_jet")


def losses(**kw):
    args = dict(Fa=450.0, Fr=650.0, n_rpm=4800.0, T_C=50.0) | JET | kw
    return bearing_losses(B7210, OIL, **args)


def test_breakdown_sums_to_total_and_torque_times_speed_is_power():
    r = losses()
    assert set(r.breakdown_W) == set(BREAKDOWN_KEYS)
    assert sum(r.breakdown_W.values()) == pytest.approx(r.P_W, rel=1e-12)
    assert r.torque_Nm * 4800 * np.pi / 30 == pytest.approx(r.P_W, rel=1e-12)
    # per-contact sums equal the breakdown
    c = r.contacts
    assert (c["inner"]["P_rolling"].sum() + c["outer"]["P_rolling"].sum()) == pytest.approx(r.breakdown_W["rolling"])


def test_heat_split_conserves_energy_exactly():
    r = losses()
    h = r.heat_W
    assert h["inner_ring"] + h["outer_ring"] + h["balls"] + h["oil"] == pytest.approx(r.P_W, rel=1e-13)
    assert h["oil"] == r.breakdown_W["drag"]


def test_rolling_power_is_2uF():
    r = losses()
    for side in ("inner", "outer"):
        c = r.contacts[side]
        np.testing.assert_allclose(c["P_rolling"], 2 * c["u"] * c["F_R"], rtol=1e-14)


def test_zero_load_contacts_lose_nothing_drag_remains():
    r = losses(Fr=0.0, Fa=1e-9, centrifugal=False)
    assert r.breakdown_W["rolling"] < 1e-3 * r.breakdown_W["drag"]
    assert r.breakdown_W["sliding"] < 1e-6 and r.breakdown_W["hysteresis"] < 1e-6
    assert r.breakdown_W["drag"] > 1.0


def test_unloaded_inner_contacts_zero_outer_carry_centrifugal_load():
    r = losses(Fr=1500.0)
    ci, co = r.contacts["inner"], r.contacts["outer"]
    unloaded = ci["Q"] == 0
    assert unloaded.any()
    assert np.all(ci["P_rolling"][unloaded] == 0) and np.all(ci["P_sliding"][unloaded] == 0)
    assert np.all(co["Q"][unloaded] > 0) and np.all(co["P_rolling"][unloaded] > 0)   # F_c keeps them on the race


def test_zero_speed_zero_loss_without_nan():
    r = losses(n_rpm=0.0)
    assert r.P_W == 0.0 and r.torque_Nm == 0.0
    for side in ("inner", "outer"):
        for k, v in r.contacts[side].items():
            if np.asarray(v).dtype.kind == "f":
                assert np.all(np.isfinite(v)), (side, k)


def test_power_falls_as_the_bearing_heats():
    P = losses(T_C=np.array([30.0, 50.0, 70.0, 90.0])).P_W
    assert np.all(np.diff(P) < 0)


def test_speed_x2_at_equal_temperature_about_x3():
    # seed 004 §5.3.1: at equal OR–IR mean temperature, power "x3" when speed x2 (25–70 °C, read
    # from figures).  Physics bound: rolling P = 2uF_R ∝ n^1.6–1.75 (F_R ∝ U^0.64–0.75), drag ∝ n^3,
    # so the ratio lies between 2^1.6 = 3.0 and 2^2 = 4 while drag is a minor term; measured 3.1–3.7.
    for T in (30.0, 50.0, 70.0):
        P = losses(n_rpm=np.array([3200.0, 6400.0]), T_C=T).P_W
        assert 2.9 < P[1] / P[0] < 4.0, (T, P)


def test_axial_preload_raises_power():
    # seed 004 §5.3.4 / Fig. 12: Fa 225 → 675 N raises the losses (Fr 0, 4800 rpm)
    Pa = losses(Fa=np.array([225.0, 450.0, 675.0]), Fr=0.0).P_W
    assert np.all(np.diff(Pa) > 0)


def test_radial_load_shrinks_the_load_zone():
    # more radial load at fixed Fa: fewer loaded inner contacts, the most loaded ball carries more.
    # (Seed 004's "radial load has almost no effect" is compared in validation/seed004_trends.py.)
    r = losses(Fr=np.array([25.0, 325.0, 750.0]))
    nload = (r.contacts["inner"]["Q"] > 0).sum(-1)
    assert np.all(np.diff(nload) <= 0) and nload[0] == B7210.Z and nload[-1] < B7210.Z
    assert np.all(np.diff(r.contacts["inner"]["Q"].max(-1)) > 0)


def test_one_cage_speed_for_all_balls():
    # a rigid cage: balls in and out of the load zone orbit at one speed, and the unloaded balls'
    # outer entrainment speed stays that of a ball rolling on the outer race (within the spread
    # of the contact angles), not the 1.7x that a no-slip solution with a gap's "contact angle" gives
    from thermobear.losses.local import prepare_contacts
    cs = prepare_contacts(B7210, Fa=450.0, Fr=750.0, n_rpm=4800.0)
    assert np.ptp(cs.omega_c) <= 1e-12 * np.max(cs.omega_c)
    r = losses(Fr=750.0)
    ci, co = r.contacts["inner"], r.contacts["outer"]
    unloaded, loaded = ci["Q"] == 0, ci["Q"] > 0
    assert unloaded.any() and loaded.any()
    assert co["u"][unloaded].max() < 1.05 * co["u"][loaded].max()


def test_batch_equals_single():
    n = np.array([3200.0, 4800.0, 6500.0, 8070.0])
    rb = losses(n_rpm=n)
    for k, nk in enumerate(n):
        assert losses(n_rpm=nk).P_W == pytest.approx(rb.P_W[k], rel=1e-10)


def test_regimes_acbb_pvr():
    # seed 004 §3.2: ACBB Fa 400 N, 6500 rpm, 30–80 °C: loaded contacts PVR
    for T in (30.0, 55.0, 80.0):
        r = losses(Fa=400.0, Fr=0.0, n_rpm=6500.0, T_C=T)
        assert set(r.contacts["inner"]["regime"].tolist()) == {"PVR"}


def test_bad_inputs():
    with pytest.raises(InputError, match="rolling_model"):
        losses(rolling_model="magic")
    with pytest.raises(InputError, match="n_rpm"):
        losses(n_rpm=-1.0)
    with pytest.raises(InputError, match="supply"):
        losses(supply="mist")


def test_oil_injection_temperature_barely_matters_at_equal_bearing_temperature():
    # seed 004 §5.3.2 / Fig. 10: the controlling viscosity is the contacts' (bearing) temperature;
    # the oil–air temperature only enters through drag
    a = losses(n_rpm=6500.0, T_C=50.0, T_oil_C=30.0)
    b = losses(n_rpm=6500.0, T_C=50.0, T_oil_C=55.0)
    assert abs(b.P_W / a.P_W - 1) < 0.02
    assert b.breakdown_W["rolling"] == a.breakdown_W["rolling"]
