"""Time-varying (logged) boundary temperatures: the thermal solver against the analytic first-order
response, the coupled transient against its fixed-boundary form, and rig logs driving both."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from thermobear.app.rig import channel_map, compare, read_log, simulate_log
from thermobear.coupled import transient
from thermobear.errors import InputError
from thermobear.scene.scene import load_scene
from thermobear.thermal.network import load_network
from thermobear.thermal.solve import LinearBoundary, solve_transient

ROOT = Path(__file__).resolve().parents[1]
LOGS = ROOT / "examples" / "logs"


def one_node(C=500.0, G=2.0):
    return load_network({"nodes": {"b": {"C_J_K": C}, "ambient": {"T_C": 20.0}},
                         "elements": [{"type": "conductance", "between": ["b", "ambient"], "G_W_K": G}]})


@pytest.fixture(scope="module")
def scene():
    return load_scene(LOGS / "synthetic_heatup_scene.toml")


def _write(tmp_path, text, name="log.csv"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


# ------------------------------------------------------------------ the thermal solver
@pytest.mark.parametrize("P_W", [0.0, 40.0])
def test_ramp_on_one_node_is_the_first_order_response(P_W):
    """C dT/dt = P − G (T − T_a(t)), T_a = T0 + r t, T(0) = T0:
    T = T_a + P/G − r τ + (r τ − P/G) e^{−t/τ}, τ = C/G (a ramp lags by r τ)."""
    C, G, r, T0, t_end = 500.0, 2.0, 0.01, 20.0, 2000.0
    tau = C / G
    bnd = LinearBoundary.of([0.0, t_end], {"ambient": [T0, T0 + r * t_end]})
    t = np.linspace(0.0, t_end, 41)
    res = solve_transient(one_node(C, G), {"b": P_W}, t_end, t_eval=t, fixed_C=bnd, T0_C=T0)
    exact = T0 + r * t + P_W / G - r * tau + (r * tau - P_W / G) * np.exp(-t / tau)
    np.testing.assert_allclose(res.T_C["b"][1:] - T0, exact[1:] - T0, rtol=1e-3)
    np.testing.assert_allclose(res.T_C["ambient"], T0 + r * t, rtol=1e-12)        # the boundary as imposed


def test_linear_boundary_interpolates_and_refuses_extrapolation():
    b = LinearBoundary.of([0.0, 10.0, 30.0], {"ambient": [20.0, 25.0, 15.0]}, source="log.csv: T_room_C")
    assert b(5.0) == {"ambient": 22.5} and b(20.0) == {"ambient": 20.0} and b(30.0) == {"ambient": 15.0}
    with pytest.raises(InputError, match="not extrapolated") as e:
        b(30.5)
    assert e.value.field == "log.csv: T_room_C"
    with pytest.raises(InputError):
        LinearBoundary.of([0.0, 0.0], {"ambient": [20.0, 21.0]})                 # times must increase
    with pytest.raises(InputError):
        LinearBoundary.of([0.0, 1.0], {"ambient": [20.0, np.nan]})


def test_boundary_on_a_free_node_is_refused():
    with pytest.raises(InputError, match="a fixed node name"):
        solve_transient(one_node(), {}, 10.0, fixed_C=LinearBoundary.of([0, 10], {"b": [20, 21]}))


# ------------------------------------------------------------------ the coupled transient
def test_constant_boundary_equals_the_fixed_boundary_transient_exactly(scene):
    t = np.linspace(0.0, 900.0, 31)
    fixed = transient(scene.with_(T_fixed_C={"ambient": 25.0}), 900.0, t_eval=t)
    logged = transient(scene, 900.0, t_eval=t, boundary=([0.0, 300.0, 900.0], {"ambient": [25.0, 25.0, 25.0]}))
    assert np.array_equal(fixed.t_s, logged.t_s)
    for n in fixed.T_C:
        assert np.array_equal(fixed.T_C[n], logged.T_C[n])
    assert np.array_equal(fixed.P_W, logged.P_W)


def test_a_room_ramp_ends_at_the_steady_state_of_the_warmer_room(scene):
    """A room ramp of 3 K over the first 600 s, then held: long after (50 time constants) the bearing
    sits at the steady state of a 25 °C room, less than 3 K above the 22 °C one (warmer grease, less
    friction)."""
    from thermobear.coupled import steady_state
    t = np.array([0.0, 600.0, 6000.0])
    ref = transient(scene, 6000.0, t_eval=t)
    warm = transient(scene, 6000.0, t_eval=t, boundary=([0.0, 600.0, 6000.0], {"ambient": [22.0, 25.0, 25.0]}))
    assert warm.T_C["ambient"].tolist() == [22.0, 25.0, 25.0]
    st = steady_state(scene.with_(T_fixed_C={"ambient": 25.0}))
    assert warm.T_C["bearing"][-1] == pytest.approx(st.T_C["bearing"], abs=2e-3)
    assert 0 < warm.T_C["bearing"][-1] - ref.T_C["bearing"][-1] < 3.0 and warm.P_W[-1] < ref.P_W[-1]


def test_boundary_must_cover_the_run_and_spare_the_heated_nodes(scene):
    with pytest.raises(InputError, match="must cover the run"):
        transient(scene, 900.0, boundary=([0.0, 600.0], {"ambient": [22.0, 23.0]}))
    with pytest.raises(InputError, match="must cover the run"):
        transient(scene, 900.0, boundary=([10.0, 900.0], {"ambient": [22.0, 23.0]}))
    with pytest.raises(InputError, match="receives the loss heat"):
        transient(scene, 900.0, boundary=([0.0, 900.0], {"bearing": [22.0, 23.0]}))


# ------------------------------------------------------------------ rig logs
def test_logged_room_at_the_scene_ambient_changes_nothing(tmp_path, scene):
    rows = "".join(f"{t},{30 + t / 100:.3f},22.0\n" for t in range(0, 901, 60))
    log = read_log(_write(tmp_path, "t_s,T_bearing_C,T_room_C\n" + rows))
    with_room = compare(scene, log, channel_map(scene, log))
    without = compare(scene, log, channel_map(scene, log, {"T_room_C": "ignore"}))
    assert with_room.mode == "transient with logged boundary T_room_C → ambient (linear between rows)"
    assert without.mode == "transient (heat-up from the start temperature)"
    assert np.array_equal(with_room.simulated["T_bearing_C"], without.simulated["T_bearing_C"])
    assert with_room.imposed["T_room_C"].tolist() == [22.0] * 16
    d = with_room.as_dict()
    assert d["mode"] == with_room.mode and d["model"]["t_s"].size > 300
    assert "mode: transient with logged boundary T_room_C → ambient" in with_room.summary()


def test_log_is_run_from_its_first_row(tmp_path, scene):
    """A log whose clock starts at 1000 s is the same run as the log starting at 0 (the run starts at
    the first row); a speed step and the room both drive it."""
    def text(t0):
        return "t_s,T_bearing_C,T_room_C,n_rpm\n" + "".join(
            f"{t0 + t},{30.0},{22 + t / 300:.3f},{3000 if t < 300 else 4000}\n" for t in range(0, 601, 60))
    a = simulate_log(scene, read_log(_write(tmp_path, text(0.0), "a.csv")), channel_map(scene, read_log(
        _write(tmp_path, text(0.0), "a.csv"))))
    log_b = read_log(_write(tmp_path, text(1000.0), "b.csv"))
    b = simulate_log(scene, log_b, channel_map(scene, log_b))
    np.testing.assert_allclose(a["T_bearing_C"], b["T_bearing_C"], rtol=1e-9)
    assert a["_mode"] == "transient with logged boundary T_room_C → ambient (linear between rows); 1 speed step from n_rpm"
    direct = transient(scene.with_(n_rpm=3000.0), 600.0, schedule=[(300.0, {"n_rpm": 4000.0})],
                       t_eval=np.arange(0.0, 601.0, 60.0), rtol=1e-6, atol=1e-5, T0_C=22.0,
                       boundary=(np.arange(0.0, 601.0, 60.0), {"ambient": 22 + np.arange(0.0, 601.0, 60.0) / 300}))
    np.testing.assert_allclose(a["T_bearing_C"], direct.T_C["bearing"], rtol=1e-12)


def test_imposed_channel_gaps(tmp_path, scene):
    """Empty cells inside an imposed channel are bridged linearly; an empty first or last row is refused
    (the boundary would have to be extrapolated)."""
    gap = read_log(_write(tmp_path, "t_s,T_bearing_C,T_room_C\n0,22,22\n60,30,\n120,35,24\n", "g.csv"))
    full = read_log(_write(tmp_path, "t_s,T_bearing_C,T_room_C\n0,22,22\n60,30,23\n120,35,24\n", "f.csv"))
    np.testing.assert_array_equal(simulate_log(scene, gap, channel_map(scene, gap))["T_bearing_C"],
                                  simulate_log(scene, full, channel_map(scene, full))["T_bearing_C"])
    bad = read_log(_write(tmp_path, "t_s,T_bearing_C,T_room_C\n0,22,\n60,30,23\n120,35,24\n", "b.csv"))
    with pytest.raises(InputError, match="first and last rows") as e:
        simulate_log(scene, bad, channel_map(scene, bad))
    assert e.value.field == "b.csv: column T_room_C"


def test_comparison_plot_has_a_residual_panel(tmp_path, scene):
    pytest.importorskip("matplotlib")
    from thermobear.app.plots import plot_comparison
    log = read_log(LOGS / "synthetic_heatup_7210.csv")
    c = compare(scene, log, channel_map(scene, log))
    paths = plot_comparison(c, tmp_path, "synthetic")
    assert [Path(p).name for p in paths] == ["compare_heatup.png"] and Path(paths[0]).stat().st_size > 0
    # the model is drawn on its own dense trajectory, of which the logged rows are a subset
    assert c.model_x.size > log.n_rows and np.allclose(np.interp(log.t_s, c.model_x, c.model["T_bearing_C"]),
                                                       c.simulated["T_bearing_C"], rtol=0, atol=1e-12)
