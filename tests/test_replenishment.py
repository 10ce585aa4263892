"""Kinematic replenishment (SKF's Φ_rs) with the scene's constant K_rs: read by both loss models, per point in a
batch, sampled and calibrated where the models read it, named where they do not; the factors at the solution."""
import re

import numpy as np
import pytest

import thermobear as tb
from thermobear.errors import InputError
from thermobear.losses import bearing_losses
from thermobear.losses.skf import K_RS, phi_rs, skf_friction
from thermobear.model_inputs import unread_inputs, unread_settings
from thermobear.models import replenishment_constant

SEED004 = "seed004_oil_jet_7210.toml"


@pytest.fixture(scope="module")
def s004():
    return tb.load_scene(tb.example_path(SEED004))


def test_the_constant_is_the_scenes_else_skfs_of_the_supply(s004):
    assert replenishment_constant(s004.with_(K_rs=None)) == K_RS["oil_jet"] == 3e-8
    assert replenishment_constant(s004.with_(K_rs=4.5e-8)) == 4.5e-8
    assert replenishment_constant(s004.with_(K_rs=None, supply="oil_air")) == K_RS["oil_air"] == 6e-8
    with pytest.raises(InputError, match="K_rs"):
        s004.with_(K_rs=-1e-8)


def test_a_zero_constant_is_a_flooded_contact_and_power_falls_as_it_grows():
    """K_rs = 0: Φ_rs = 1 exactly, the same losses as without starvation; then monotonic in K_rs."""
    s = tb.load_scene(tb.example_path("seed002_grease_thrust_51107.toml"))
    kw = dict(Fa=7000.0, n_rpm=1000.0, T_C=49.8, supply="grease", drag=False)
    flooded = bearing_losses(s.bearing, s.lubricant, **kw).P_W
    assert bearing_losses(s.bearing, s.lubricant, starvation=True, K_rs=0.0, **kw).P_W == flooded
    P = [bearing_losses(s.bearing, s.lubricant, starvation=True, K_rs=k, **kw).P_W for k in (1e-8, 3e-8, 6e-8, 1.2e-7)]
    assert all(a > b for a, b in zip([flooded] + P, P))
    # the default is SKF's grease constant; one value per operating point equals each point alone
    assert bearing_losses(s.bearing, s.lubricant, starvation=True, **kw).P_W == P[2]
    batch = bearing_losses(s.bearing, s.lubricant, starvation=True, K_rs=np.array([1e-8, 6e-8]), **kw).P_W
    assert batch == pytest.approx([P[0], P[2]], rel=1e-12)


def test_skf_model_reads_the_constant(s004):
    b = s004.bearing
    r = skf_friction(b, 20.0, 3000.0, 450.0, 325.0, lubrication="oil_jet", K_rs=6e-8)
    assert r.phi_rs == pytest.approx(float(phi_rs(3000.0, 20.0, b.bore * 1e3, b.outer_diameter * 1e3, 4.4, 6e-8)),
                                     rel=1e-12)
    assert skf_friction(b, 20.0, 3000.0, 450.0, 325.0, lubrication="oil_jet").phi_rs > r.phi_rs
    skf = s004.with_(models={"losses": "skf"})
    assert tb.steady_state(skf.with_(K_rs=6e-8)).P_W < tb.steady_state(skf.with_(K_rs=3e-8)).P_W


def test_steady_states_batch_the_constant_per_point(s004):
    """Points differing only in K_rs solve together as they do alone (the constant per point in the batch)."""
    pts = [s004.with_(K_rs=k) for k in (1.5e-8, 3e-8, 6e-8)]
    together = [r.P_W for r in tb.steady_states(pts)]
    alone = [tb.steady_state(p).P_W for p in pts]
    assert together == pytest.approx(alone, rel=1e-9)
    assert alone[0] > alone[1] > alone[2]


def test_unread_where_no_starvation_and_refused_by_calibration(s004):
    off = s004.with_(models={"starvation": False})
    assert "lubricant.K_rs" in unread_inputs(off) and "lubricant.K_rs" not in unread_inputs(s004)
    assert [f for f, _, _ in unread_settings(off.with_(K_rs=4e-8))] == ["lubricant.K_rs"]
    from thermobear.app.calibration import parameter_names
    assert "K_rs" in parameter_names(s004) and "K_rs" not in parameter_names(off)


def test_sampled_where_read(s004):
    from thermobear.coupled.uncertainty import uncertain_inputs
    assert "lubricant.K_rs" in [i.address for i in uncertain_inputs(s004)]
    off = s004.with_(models={"starvation": False})
    assert "lubricant.K_rs" not in [i.address for i in uncertain_inputs(off)]


def test_models_used_state_the_factors_at_the_solution(s004):
    """The model choice states Φ_rs and φ_T at the inlet's 30 °C; the solution's contacts run warmer, so their
    oil is thinner: a larger Φ_rs (less starvation) and the shown ranges lie in (0, 1]."""
    r = tb.steady_state(s004)
    for key, sym in (("starvation", "Φ_rs"), ("inlet_heating", "φ_T")):
        reason = r.models_used[key][1]
        inlet = float(re.search(sym + r" = ([0-9.]+) at", reason).group(1))
        lo, hi = map(float, re.search(r"at the solution " + sym + r" ([0-9.]+)–([0-9.]+)", reason).groups())
        assert 0.0 < lo <= hi <= 1.0
        if key == "starvation":
            assert lo > inlet


def test_the_skf_model_honours_starvation_off():
    """models.starvation = false on the SKF model kept its Φ_rs (25.56 W, and K_rs still moved it); now Φ_rs = 1
    there too (more rolling loss), and a K_rs set beside it is named as unread."""
    from thermobear.model_inputs import unread_settings
    s = tb.load_scene(tb.example_path("block_6208_oil_jet.toml")).with_(models={"losses": "skf"})
    off = s.with_(models={"starvation": False})
    P_on, P_off = tb.steady_state(s).P_W, tb.steady_state(off).P_W
    assert P_off > P_on and tb.steady_state(off.with_(K_rs=5e-7)).P_W == pytest.approx(P_off, rel=1e-12)
    assert [f for f, _, _ in unread_settings(off.with_(K_rs=5e-7))] == ["lubricant.K_rs"]
