"""Seal friction, SKF 2004 (thermobear.losses.seals): the printed equation and table rows, one/two seals, limits."""
import numpy as np
import pytest

from thermobear.errors import InputError
from thermobear.losses.seals import seal_constants, seal_counterface_estimate_mm, seal_friction, seal_moment_Nmm


def test_rs1_deep_groove_hand_value_of_the_printed_equation():
    """6208-2RS1: D 80 mm (row 62 < D <= 80: K_S1 0.018, K_S2 20, β 2.25), d_s = d1 = 52.6 mm."""
    M_Nmm = 0.018 * 52.6 ** 2.25 + 20.0                 # SKF 6000 EN table 4, by hand
    r = seal_friction("RS1", "deep_groove", 80.0, 52.6, 3000.0)
    assert r.M_Nm == pytest.approx(M_Nmm * 1e-3, rel=1e-12)
    assert r.P_W == pytest.approx(M_Nmm * 1e-3 * 3000 * np.pi / 30, rel=1e-12)
    assert float(seal_moment_Nmm(52.6, 0.018, 20.0, 2.25)) == pytest.approx(M_Nmm, rel=1e-12)


@pytest.mark.parametrize("seal, kind, D, row", [
    ("RSL", "deep_groove", 52.0, (0.0018, 0.0, 2.25)), ("RSL", "deep_groove", 22.0, (0.0, 0.0, 0.0)),
    ("RSH", "deep_groove", 47.0, (0.028, 2.0, 2.25)), ("RS1", "deep_groove", 62.0, (0.023, 2.0, 2.25)),
    ("RS1", "deep_groove", 90.0, (0.018, 15.0, 2.25)), ("RS1", "deep_groove", 150.0, (0.018, 0.0, 2.25)),
    ("RS1", "angular_contact", 90.0, (0.014, 10.0, 2.0)),
])
def test_table_rows_by_outside_diameter(seal, kind, D, row):
    c = seal_constants(seal, kind, D)
    assert (c["K_S1"], c["K_S2"], c["beta"]) == row


def test_one_seal_is_half_except_rsl_above_25_mm():
    two = seal_friction("RS1", "deep_groove", 80.0, 52.6, 1000.0, n_seals=2)
    one = seal_friction("RS1", "deep_groove", 80.0, 52.6, 1000.0, n_seals=1)
    assert one.M_Nm == pytest.approx(0.5 * two.M_Nm, rel=1e-14)
    rsl2 = seal_friction("RSL", "deep_groove", 52.0, 30.0, 1000.0, n_seals=2)
    rsl1 = seal_friction("RSL", "deep_groove", 52.0, 30.0, 1000.0, n_seals=1)
    assert rsl1.M_Nm == rsl2.M_Nm == pytest.approx(0.0018 * 30.0 ** 2.25 * 1e-3, rel=1e-12)


def test_no_seal_no_loss_and_standstill():
    for seal, n in (("none", 2), ("shield", 2), ("RS1", 0)):
        r = seal_friction(seal, "deep_groove", 80.0, 52.6, np.array([0.0, 3000.0]), n_seals=n)
        assert np.all(r.P_W == 0.0) and r.M_Nm == 0.0
    r = seal_friction("RS1", "deep_groove", 80.0, 52.6, np.array([0.0, 1000.0, 2000.0]))
    assert r.P_W[0] == 0.0 and r.P_W[2] == pytest.approx(2 * r.P_W[1], rel=1e-14)   # constant moment: P ∝ n


def test_counterface_estimate_near_the_catalogue_values():
    """6208: d2 = 49.1 (-2RSH), d1 = 52.6; 6210: d1 = 62.5 mm (SKF product tables): within 5 %."""
    assert seal_counterface_estimate_mm(40.0, 80.0) == pytest.approx(np.mean([49.1, 52.6]), rel=0.02)
    assert seal_counterface_estimate_mm(50.0, 90.0) == pytest.approx(62.5, rel=0.05)


@pytest.mark.parametrize("args, field", [
    (("LS", "deep_groove", 80.0), "bearing.seals"),          # a roller-bearing seal
    (("RSH", "deep_groove", 62.0), "bearing.seals"),         # outside SKF's RSH rows (D <= 52)
    (("felt", "deep_groove", 80.0), "bearing.seals"),
])
def test_bad_seal_names_the_field(args, field):
    with pytest.raises(InputError) as e:
        seal_friction(*args, 52.6, 1000.0)
    assert e.value.field == field


def test_contact_seals_past_their_lip_materials_limit_are_warned():
    """A 6208-2RS1 (NBR lips: −40 … +100 °C, SKF 2018) with its contacts at 110 °C: named (quantity seal_T; it
    passed without a word while the grease's own limit, 120 °C, held); at 90 °C, or without seals, nothing."""
    import warnings

    import thermobear as tb
    from thermobear.losses.seals import seal_material
    assert seal_material()["name"] == "NBR" and seal_material()["T_max_C"] == 100.0
    s = tb.load_scene(tb.example_path("block_6208_grease.toml")).with_(T_C=110.0)       # a 6208-2RS1
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        hot, cool, open_ = (tb.solve(x) for x in (s, s.with_(T_C=90.0), s.with_(seals="none", seal_sides=0)))
    hot_w = [w for w in hot.warnings if w.quantity == "seal_T"]
    assert len(hot_w) == 1 and hot_w[0].value == pytest.approx(110.0) and hot_w[0].field == "bearing.seals"
    assert not [w for r in (cool, open_) for w in r.warnings if w.quantity == "seal_T"]


def test_a_built_networks_seal_node_is_the_temperature_the_seal_check_reads():
    """The 6208-2RS1 in its block at 9000 rpm: the seal node (heated by the lips' own friction) runs at ≈ 120 °C,
    15 K above the contacts and cavity; the warning reads the node, and names it."""
    import warnings

    import thermobear as tb
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        st = tb.steady_state(tb.load_scene(tb.example_path("block_6208_grease.toml")).with_(n_rpm=9000.0))
    w = [w for w in st.warnings if w.quantity == "seal_T"]
    assert len(w) == 1 and w[0].value == pytest.approx(st.T_C["seal"], abs=1e-9) and "seal node" in str(w[0])
    assert st.T_C["seal"] > max(st.T_C["inner_race"], st.T_C["outer_race"]) > 100.0


def test_a_heat_up_reads_the_seal_node_too():
    """The same block at 7000 rpm heats its seal node to 103 °C while the races stay below 100 °C: the heat-up
    named nothing (it read the contacts), the steady state did."""
    import warnings

    import thermobear as tb
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        tr = tb.transient(tb.load_scene(tb.example_path("block_6208_grease.toml")).with_(n_rpm=7000.0), 2e5)
    assert tr.T_C["seal"].max() > 100.0 > max(tr.T_C["inner_race"].max(), tr.T_C["outer_race"].max())
    assert [w.quantity for w in tr.warnings].count("seal_T") == 1


def test_a_scene_offers_only_the_seals_of_ball_bearings():
    """LS and CS are SKF's roller-bearing seals: the scene's choice no longer lists them (it listed them and the
    seal model then refused them for a ball bearing)."""
    import thermobear as tb
    from thermobear.errors import InputError
    s = tb.load_scene(tb.example_path("block_6208_grease.toml"))
    with pytest.raises(InputError, match="none, shield, RSL, RSH, RS1$"):
        s.with_(seals="LS")
    assert s.with_(seals="RS1").seals == "RS1"
