"""run_sweep: the same numbers as single solves, whatever path (vectorised, processes, Dask) computes them."""
from __future__ import annotations

import csv
import warnings

import numpy as np
import pytest

import thermobear as tb
from thermobear.errors import InputError
from thermobear.coupled import solve, steady_state
from thermobear.models import dry_load, plan_many
from thermobear.app.sweep import run_sweep, sweep_points


@pytest.fixture(scope="module")
def seed004():
    return tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))


@pytest.fixture(scope="module")
def seed002():
    return tb.load_scene(tb.example_path("seed002_grease_thrust_51107.toml"))


def test_grid_order_is_cartesian_first_key_slowest():
    pts = sweep_points({"n_rpm": [1, 2], "Fa": [10, 20, 30]})
    assert len(pts) == 6
    assert [p["n_rpm"] for p in pts] == [1, 1, 1, 2, 2, 2]
    assert [p["Fa"] for p in pts] == [10, 20, 30, 10, 20, 30]


def test_prescribed_sweep_equals_single_solves(seed004):
    grid = {"n_rpm": [0.0, 3200.0, 8070.0], "Fr": [50.0, 1500.0], "Fa": [225.0, 675.0], "T_C": [30.0, 70.0]}
    rows = run_sweep(seed004, grid)
    assert len(rows) == 24
    for r in rows:
        single = solve(seed004.with_(n_rpm=r["n_rpm"], Fr=r["Fr"], Fa=r["Fa"], T_C=r["T_C"]))
        assert r["status"] == "ok"
        assert r["P_W"] == pytest.approx(single.P_W, rel=1e-12, abs=1e-15)
        assert r["torque_Nm"] == pytest.approx(single.torque_Nm, rel=1e-12, abs=1e-15)
        for k, v in single.breakdown_W.items():
            assert r["breakdown_W"][k] == pytest.approx(v, rel=1e-12, abs=1e-15)
        assert r["models"]["drag"] == single.models_used["drag"][0]
        assert r["models"]["load_model"] == single.models_used["load_model"][0]
        assert r["warnings"] == [str(w) for w in single.warnings]       # (they were always [] here)
    # Fr 1500 N lifts balls off the races: those points run the film load model, one by one
    assert {r["models"]["load_model"] for r in rows if r["n_rpm"] > 0} == {"jones_harris", "film"}
    # physics of the rows: standstill dissipates nothing; losses fall with temperature (viscosity)
    assert all(r["P_W"] == 0.0 for r in rows if r["n_rpm"] == 0.0)
    by = {(r["n_rpm"], r["Fr"], r["Fa"], r["T_C"]): r["P_W"] for r in rows}
    assert by[(8070.0, 50.0, 225.0, 30.0)] > by[(8070.0, 50.0, 225.0, 70.0)]
    assert by[(8070.0, 50.0, 225.0, 30.0)] > by[(3200.0, 50.0, 225.0, 30.0)]


def test_prescribed_rows_carry_the_warnings_of_a_single_run(seed004):
    """A prescribed point's row states its validity as `run` does (an unloaded bearing at speed, an oil under a
    grease supply); the rows' warnings were always empty."""
    sc = seed004.with_(T_C=50.0, supply="grease")
    rows = run_sweep(sc, {"n_rpm": [3000.0], "Fa": [0.0, 500.0], "Fr": [0.0]})
    for r in rows:
        with pytest.warns(tb.OutsideValidity):
            single = solve(sc.with_(n_rpm=r["n_rpm"], Fa=r["Fa"], Fr=r["Fr"]))
        assert r["warnings"] == [str(w) for w in single.warnings] and r["warnings"]
    assert sum("unloaded" in w for w in rows[0]["warnings"]) == 1 and not any("unloaded" in w for w in rows[1]["warnings"])
    assert all("is an oil, supply = grease" in r["warnings"][0] for r in rows)
    # the jet's flow and inlet temperature the scene keeps are not read under grease: named in each row
    assert all(any(w.startswith("lubricant.T_in_C = 30") for w in r["warnings"]) for r in rows)


def test_prescribed_pure_axial_uses_the_closed_form(seed002):
    rows = run_sweep(seed002, {"n_rpm": [500.0, 1000.0], "T_C": [49.8]})
    assert {r["models"]["load_model"] for r in rows} == {"closed_form"}
    single = solve(seed002.with_(n_rpm=1000.0, T_C=49.8))
    assert rows[1]["P_W"] == pytest.approx(single.P_W, rel=1e-12)


def test_coupled_local_processes_equal_single_solves(seed002):
    rows = run_sweep(seed002, {"n_rpm": [1000.0, 2000.0]}, processes=2)
    for r in rows:
        st = steady_state(seed002.with_(n_rpm=r["n_rpm"]))
        assert r["status"] == "ok"
        assert r["P_W"] == pytest.approx(st.P_W, rel=1e-12)
        assert r["temperatures_C"]["balls"] == pytest.approx(st.T_C["balls"], rel=1e-12)
        assert r["iterations"] == st.iterations
    # the hotter point is the faster one (more heat into the same network)
    assert rows[1]["temperatures_C"]["balls"] > rows[0]["temperatures_C"]["balls"]
    # energy: the row's power equals the breakdown's sum
    for r in rows:
        assert sum(r["breakdown_W"].values()) == pytest.approx(r["P_W"], rel=1e-12)


def test_mixed_grid_and_progress(seed002):
    seen = []
    rows = run_sweep(seed002, {"n_rpm": [1000.0], "T_C": [None, 50.0]}, processes=1,
                     progress=lambda d, t: seen.append((d, t)))
    assert rows[0]["temperatures_C"].get("balls") is not None      # coupled (T_C None)
    assert rows[1]["temperatures_C"] == {"contacts (prescribed)": 50.0}
    assert seen[-1] == (2, 2) and all(t == 2 for _, t in seen)


def test_bad_override_raises_before_running(seed004):
    with pytest.raises(InputError, match="n_rpm"):
        run_sweep(seed004, {"n_rpm": [1000.0, -5.0], "T_C": [40.0]})
    with pytest.raises(InputError, match="unknown override"):
        run_sweep(seed004, {"speed": [1000.0]})
    with pytest.raises(InputError, match="processes"):
        run_sweep(seed004, {"n_rpm": [1000.0], "T_C": [40.0]}, processes=0)


def test_dask_path_identical_to_local(seed002):
    distributed = pytest.importorskip("dask.distributed")
    grid = {"n_rpm": [1000.0, 2000.0], "Fa": [5000.0, 7000.0]}
    local = run_sweep(seed002, grid, processes=1)
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False,
                                  dashboard_address=None) as cluster:
        remote = run_sweep(seed002, grid, scheduler=cluster.scheduler_address)
    assert len(remote) == len(local) == 4
    for a, b in zip(local, remote):
        assert (a["n_rpm"], a["Fa"]) == (b["n_rpm"], b["Fa"])
        assert a["status"] == b["status"] == "ok"
        np.testing.assert_allclose(b["P_W"], a["P_W"], rtol=1e-13)
        for k in a["temperatures_C"]:
            np.testing.assert_allclose(b["temperatures_C"][k], a["temperatures_C"][k], rtol=1e-13)
        assert a["iterations"] == b["iterations"]


def test_planned_dry_loads_equal_single_solves(seed004):
    """The model choice of many points solves their dry loads in batched calls (high-speed and
    low-speed forms apart); every point's dry solution equals its own single solve to round-off."""
    scenes = [seed004.with_(n_rpm=n, Fr=Fr) for n in (1500.0, 2500.0, 5000.0, 8000.0) for Fr in (100.0, 325.0)]
    plans = plan_many(scenes)
    forms = set()
    for sc, alts in zip(scenes, plans):
        assert sum(a.weight for a in alts) == pytest.approx(1.0, rel=1e-14)
        for a in alts:
            hs = a.models["high_speed"][0] == "yes"
            forms.add(hs)
            ref = dry_load(sc, hs)
            for f in ("Q_i", "Q_o", "alpha_i", "alpha_o"):
                assert np.allclose(getattr(a.dry.load(), f), getattr(ref, f), rtol=1e-11, atol=1e-12 * 450.0), f
    assert forms == {True, False}                                   # both forms in the grid


def test_a_failing_load_batch_leaves_each_point_to_its_own_solve(seed004):
    """Fa = 0 under a radial load has no equilibrium in an angular contact bearing: the batch is halved
    around it, and the sweep reports the failure on that point only."""
    pts = [seed004.with_(Fa=Fa, n_rpm=n) for Fa in (0.0, 450.0) for n in (5000.0, 5500.0, 6000.0, 6500.0)]
    plans = plan_many(pts)
    assert all(a.dry is not None for p in plans[4:] for a in p)
    rows = run_sweep(seed004, {"Fa": [0.0, 450.0], "n_rpm": [5000.0, 6000.0]}, processes=1)
    assert [r["status"] for r in rows] == ["NoEquilibrium", "NoEquilibrium", "ok", "ok"]
    for r in rows[2:]:
        st = tb.steady_state(seed004.with_(Fa=450.0, n_rpm=r["n_rpm"]))
        assert r["P_W"] == pytest.approx(st.P_W, rel=1e-12)


@pytest.mark.parametrize("processes", [1, 2])
def test_coupled_film_points_batched_equal_single_solves(seed004, processes):
    """Coupled points on the film load model run their film fixed points together, the film load
    distributions of each round solved in one batched call: every row equals its single solve."""
    grid = {"n_rpm": [2000.0, 2600.0, 3600.0], "Fr": [325.0, 700.0]}
    seen = []
    rows = run_sweep(seed004, grid, processes=processes, progress=lambda d, t: seen.append((d, t)))
    assert [d for d, _ in seen] == list(range(1, 7)) and {t for _, t in seen} == {6}
    kinds = []
    for r in rows:
        st = steady_state(seed004.with_(n_rpm=r["n_rpm"], Fr=r["Fr"]))
        kinds.append(st.models_used["load_model"][0])
        assert r["status"] == "ok"
        assert r["P_W"] == pytest.approx(st.P_W, rel=1e-12)
        assert r["temperatures_C"]["balls"] == pytest.approx(st.T_C["balls"], rel=1e-12)
        assert r["iterations"] == st.iterations and r["models"]["load_model"] == kinds[-1]
    assert kinds.count("film") >= 3 and "jones_harris" in kinds


def test_prescribed_sweep_records_a_point_without_equilibrium_on_its_row(seed002):
    """A thrust bearing at Fa = 0 (no contact) in a prescribed-temperature sweep, local and SKF losses:
    that point's row says NoEquilibrium; the others are computed."""
    for sc in (seed002.with_(T_C=40.0), seed002.with_(T_C=40.0, models={"losses": "skf"})):
        rows = run_sweep(sc, {"Fa": [0.0, 1000.0, 7000.0]})
        assert [r["status"] for r in rows] == ["NoEquilibrium", "ok", "ok"]
        assert rows[0]["P_W"] is None and rows[1]["P_W"] > 0


def test_a_forced_model_no_row_can_take_is_bad_input_before_any_row(tmp_path, capsys):
    """A fitted clearance forced at prescribed temperatures failed every row (exit 3, a CSV of errors): the model
    choice each axis value forces is checked with the values, before computing — exit 2, one line, no file."""
    from thermobear.app.cli import main
    out = tmp_path / "sw.csv"
    rc = main(["sweep", tb.example_path("block_6208_oil_jet.toml"), "--set", "bearing.shaft_fit=p6",
               "--set", "models.clearance=mounted", "--T-C", "40,100", "--csv", str(out)])
    err = capsys.readouterr().err
    assert rc == 2 and not out.exists() and err.strip().splitlines() == [
        "error: models.clearance = 'mounted' — the fitted clearance is applied by the coupled steady state: remove "
        "operation.T_C, or choose 'given'"]


def test_coupled_rows_carry_the_ratings_and_their_warnings_as_run_gives_them(capsys):
    """The 6208 oil bath example on its k5 / H7 seats: `run` names the operating clearance consumed into a radial
    preload (−11 µm at the answer's temperatures, a ratings warning).  A sweep row of the same point said nothing
    (`warnings` held the steady state's only); it now carries the ratings `run` gives — L10m, κ, s0, the operating
    clearance — and their warnings, equal to run's, on every coupled row."""
    from thermobear.app.cli import main
    from thermobear.coupled.ratings import scene_ratings
    s = tb.load_scene(tb.example_path("oil_bath_6208.toml"))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        st = tb.steady_state(s)
        rt = scene_ratings(s, st)
        rows = run_sweep(s, {"n_rpm": [s.n_rpm, 2.0 * s.n_rpm]}, processes=1)
    row = rows[0]
    assert rt.clearance_um["operating"] < 0 and any("operating radial clearance" in str(w) for w in rt.warnings)
    assert row["clearance_operating_um"] == pytest.approx(rt.clearance_um["operating"], rel=1e-9)
    assert row["L10m_h"] == pytest.approx(rt.L10m_h, rel=1e-9) and row["kappa"] == pytest.approx(rt.kappa, rel=1e-9)
    assert row["s0"] == pytest.approx(rt.s0)
    assert all(str(w) in row["warnings"] for w in rt.warnings)
    assert rows[1]["clearance_operating_um"] < row["clearance_operating_um"]      # faster: warmer inner ring, tighter
    assert rows[1]["L10m_h"] < row["L10m_h"]                                       # fewer hours to the same revolutions
    assert main(["sweep", str(tb.example_path("oil_bath_6208.toml")), "--n-rpm", str(s.n_rpm)]) == 0
    header, first = csv.reader(capsys.readouterr().out.strip().splitlines()[-2:])
    cols = dict(zip(header, first))
    assert float(cols["clearance_operating_um"]) == pytest.approx(rt.clearance_um["operating"], rel=1e-6)


def test_prescribed_rows_carry_the_ratings_run_gives_at_that_temperature():
    """A 6310 at a prescribed 20 °C with 8 N (8 kN typed in kN as N): `run` names the load below SKF's minimum load
    (a ratings warning); the prescribed-temperature rows of a sweep carry the same ratings and warnings (they held
    the loss model's warnings only)."""
    s = tb.load_scene(tb.example_path("oil_bath_6208.toml")).with_(bearing="6310", lubricant="iso-vg-150-mineral",
                                                                    n_rpm=1500.0, Fr=8.0, T_C=20.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ref = solve(s)
        rows = run_sweep(s, {"Fr": [8.0, 8000.0]}, processes=1)
    mine = [str(w) for w in ref.ratings.warnings if "minimum load" in str(w)]
    assert mine and mine[0] in rows[0]["warnings"]
    assert not any("minimum load" in w for w in rows[1]["warnings"])
    assert rows[0]["kappa"] == pytest.approx(ref.ratings.kappa, rel=1e-12)
    assert rows[0]["L10m_h"] == pytest.approx(ref.ratings.L10m_h, rel=1e-12)
    assert rows[0]["clearance_operating_um"] == pytest.approx(ref.ratings.clearance_um["operating"], rel=1e-12)
