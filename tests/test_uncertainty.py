"""Uncertainty of predictions (thermobear.coupled.uncertainty, .sensitivity; the uncertainty syntax of
thermobear.schema): reproducible samples, bands around the nominal answer, zero-width ranges, a known
linear sensitivity, failed samples counted, unknown keys refused, every estimated value ranged."""
from __future__ import annotations

import dataclasses
import json
import warnings

import numpy as np
import pytest

import thermobear as tb
from thermobear.app.cli import main
from thermobear.coupled import uncertainty as unc
from thermobear.coupled.ratings import scene_ratings
from thermobear.coupled.uncertainty import (Input, sample_scenes, steady_uncertainty, transient_uncertainty,
                                            uncertain_inputs)
from thermobear.errors import InputError
from thermobear.files import data_dir, read_toml
from thermobear.schema import Field, Uncertainty, check_uncertainty
from thermobear.thermal import prepare_network

SEED004 = tb.example_path("seed004_oil_jet_7210.toml")
SEED002 = tb.example_path("seed002_grease_thrust_51107.toml")


@pytest.fixture(scope="module")
def s004():
    return tb.load_scene(SEED004)


def _narrow(inputs, rel):
    """The inputs with symmetric ranges of relative half-width ``rel`` about their nominal draws
    (rel = 0: zero-width ranges at the nominal)."""
    out = []
    for i in inputs:
        u = i.uncertainty
        if u.kind == "factor":
            lo, hi = 1.0 - rel, 1.0 + rel
        elif u.kind == "offset":
            lo, hi = -10 * rel, 10 * rel
        elif i.nominal is not None and not u.integer:
            lo, hi = i.nominal * (1.0 - rel), i.nominal * (1.0 + rel)
        else:
            continue
        out.append(dataclasses.replace(i, uncertainty=Uncertainty(u.kind, lo, hi, "uniform", "test")))
    return out


# --------------------------------------------------------------------------- the data
def test_every_estimated_number_has_a_range():
    """Every estimated numeric value of the bundled materials, lubricants, seed bearings, networks and
    example scenes carries an uncertainty entry (non-numeric estimates — a material's name — excepted)."""
    missing = []
    for name in tb.material_names():
        m = tb.material(name)
        missing += [f"materials/{name}.{k}" for k in read_toml(str(data_dir("materials") / "solids" / f"{name}.toml"))
                    .get("estimated", []) if k not in m.uncertainty]
    for name in tb.lubricant_names():
        lub = tb.lubricant(name)
        missing += [f"lubricants/{name}.{k}" for k in lub.estimated if k not in lub.uncertainty]
    for name in ("6210", "7210", "51107", "51205", *tb.bearing_names()):
        b = tb.bearing(name)
        missing += [f"bearings[{name}].{k}" for k in b.estimated if k not in b.uncertainty]
    for net in ("oil_jet_ball_bearing", "grease_thrust_four_ball", "one_node"):
        spec = read_toml(str(data_dir("networks") / f"{net}.toml"))
        tables = [(f"nodes.{n}", t) for n, t in spec["nodes"].items()] + [(f"elements.{e['name']}", e)
                                                                          for e in spec["elements"]]
        for addr, t in tables:
            missing += [f"{net}: {addr}.{k}" for k in t.get("estimated", [])
                        if k not in ("material",) and k not in t.get("uncertainty", {})]
    for ex in ("seed004_oil_jet_7210.toml", "seed002_grease_thrust_51107.toml", "seed001_spin_down_3ball.toml"):
        sc = tb.load_scene(tb.example_path(ex))
        raw = {k for sec in sc.raw.values() if isinstance(sec, dict) for k in sec.get("uncertainty", {})}
        assert raw, ex
    assert missing == []


def test_unknown_keys_in_ranges_are_refused():
    num = {"k_W_mK": Field.number("W/(m K)", 0.0)}
    with pytest.raises(InputError, match="names no numeric value"):
        check_uncertainty({"k_W_mk": {"range": [40, 46], "source": "x"}}, num, "m")
    with pytest.raises(InputError, match="unknown key"):
        check_uncertainty({"k_W_mK": {"rang": [40, 46], "source": "x"}}, num, "m")
    with pytest.raises(InputError, match="exactly one of"):
        check_uncertainty({"k_W_mK": {"range": [40, 46], "factor": [0.9, 1.1], "source": "x"}}, num, "m")
    with pytest.raises(InputError, match="missing required key"):
        check_uncertainty({"k_W_mK": {"range": [40, 46]}}, num, "m")
    with pytest.raises(InputError, match="lo <= hi"):
        check_uncertainty({"k_W_mK": {"range": [46, 40], "source": "x"}}, num, "m")
    with pytest.raises(InputError, match="must be >"):
        check_uncertainty({"k_W_mK": {"range": [-1, 40], "source": "x"}}, num, "m")
    with pytest.raises(InputError, match="> 0"):
        check_uncertainty({"k_W_mK": {"factor": [0.0, 1.1], "source": "x"}}, num, "m")
    net = {"name": "n", "nodes": {"a": {"C_J_K": 10.0, "uncertainty": {"C_J_k": {"factor": [0.9, 1.1], "source": "x"}}},
                                  "amb": {"T_C": 20.0}},
           "elements": [{"type": "conductance", "between": ["a", "amb"], "G_W_K": 1.0}]}
    with pytest.raises(InputError, match="nodes.a.uncertainty.C_J_k"):
        prepare_network(net)
    net["nodes"]["a"]["uncertainty"] = {}
    net["elements"][0]["uncertainty"] = {"type": {"factor": [0.9, 1.1], "source": "x"}}
    with pytest.raises(InputError, match="names no numeric value"):
        prepare_network(net)
    with pytest.raises(InputError, match="unknown key"):
        tb.Lubricant.from_dict({"nu40_cSt": 36.6, "nu100_cSt": 7.8, "rho15_kg_m3": 864.6, "alpha_p_1_Pa": 2e-8,
                                "uncertainty": {"rho15_kg_m3": {"range": [850, 880], "sorce": "x"}}})


def test_a_network_sample_at_an_unknown_address_is_refused(s004):
    pre = tb.prepare(s004)
    with pytest.raises(InputError, match="no uncertain value"):
        pre.template.at({"scene": {"T_ambient_C": 25.0, "T_oil_in_C": 30.0, "oil_flow_m3_s": 1e-6, "n_rpm": 3200.0},
                         "op": {"oil_fraction": 0.01, "omega_inner_rad_s": 300.0, "omega_outer_rad_s": 0.0,
                                "omega_cage_rad_s": 130.0, "omega_ball_rad_s": 700.0},
                         "sample": {"nodes.shaft.volume_m4": 1.0}}, oil=s004.lubricant)


# --------------------------------------------------------------------------- sampling
def test_sampling_is_reproducible_with_a_seed(s004):
    a = sample_scenes(s004, 12, seed=7)
    b = sample_scenes(s004, 12, seed=7)
    c = sample_scenes(s004, 12, seed=8)
    assert np.array_equal(a.X, b.X) and np.array_equal(a.group, b.group)
    assert not np.allclose(a.X, c.X)
    assert [s.samples for s in a.scenes] == [s.samples for s in b.scenes]
    assert [s.bearing.D for s in a.scenes] == [s.bearing.D for s in b.scenes]
    s1 = sample_scenes(s004, 16, seed=7, method="sobol")
    assert np.array_equal(s1.X, sample_scenes(s004, 16, seed=7, method="sobol").X)


def test_latin_hypercube_strata_and_bearing_families(s004):
    sm = sample_scenes(s004, 40, seed=3, groups=4)
    ins = sm.inputs
    k = next(j for j, i in enumerate(ins) if i.address == "thermal.T_ambient_C")
    strata = np.floor((sm.X[:, k] - ins[k].uncertainty.lo) / (ins[k].uncertainty.hi - ins[k].uncertainty.lo) * 40)
    assert sorted(strata.astype(int)) == list(range(40))            # one sample per stratum
    assert sorted(np.bincount(sm.group).tolist()) == [10, 10, 10, 10]  # balanced families
    assert len({id(s.bearing) for s in sm.scenes}) == 4
    fam = [j for j, i in enumerate(ins) if i.level == "family"]
    for g in range(4):                                               # one geometry per family
        assert np.ptp(sm.X[sm.group == g][:, fam], axis=0).max() == 0.0


# --------------------------------------------------------------------------- bands
def test_zero_width_ranges_give_zero_width_bands_at_the_nominal(s004):
    ins = _narrow(uncertain_inputs(s004), 0.0)
    r = steady_uncertainty(s004, 12, seed=1, inputs=ins)
    assert not r.failed
    rt = scene_ratings(s004, r.nominal)          # the one point's design answers, scalar path
    answers = {"ratings.T_operating_C": rt.T_operating_C, "ratings.kappa": rt.kappa, "ratings.a_ISO": rt.a_ISO,
               "ratings.L10m_h": rt.L10m_h, "ratings.clearance_op_um": rt.clearance_um["operating"]}
    assert set(answers) <= set(r.bands)
    for key, b in r.bands.items():
        nom = r.nominal.T_C[key[4:]] if key.startswith("T_C.") else (
            r.nominal.P_W if key == "P_W" else answers[key] if key in answers
            else float(r.nominal.breakdown_W[key.split(".")[1]]))
        assert b["p5"] == pytest.approx(nom, rel=1e-9, abs=1e-9), key
        assert b["p95"] == pytest.approx(nom, rel=1e-9, abs=1e-9), key
    assert r.nominal_values == pytest.approx(answers, rel=1e-12)


def test_bands_contain_the_nominal_neighbourhood(s004):
    r = steady_uncertainty(s004, 48, seed=2, inputs=_narrow(uncertain_inputs(s004), 0.01))
    nom = r.nominal
    for node in ("inner_ring", "outer_ring", "balls", "housing", "oil_air"):
        b = r.bands[f"T_C.{node}"]
        assert b["p5"] < nom.T_C[node] < b["p95"]
        assert b["p95"] - b["p5"] < 0.2 * (nom.T_C[node] - 25.0)   # ±1 % inputs: a small part of the rise
    assert r.bands["P_W"]["p5"] < nom.P_W < r.bands["P_W"]["p95"]


def test_each_samples_breakdown_adds_up_to_its_power(s004):
    """The seed-004 point is blended across model switches: its breakdown is the blend, like its power
    (not the breakdown of the alternative of the largest weight)."""
    r = steady_uncertainty(s004, 24, seed=4)
    parts = np.nansum([v for k, v in r.outputs.items() if k.startswith("breakdown_W.")], axis=0)
    assert not r.failed
    np.testing.assert_allclose(parts, r.outputs["P_W"], rtol=1e-9)
    assert sum(r.nominal.breakdown_W.values()) == pytest.approx(r.nominal.P_W, rel=1e-9)


def test_a_range_the_models_do_not_read_is_not_sampled(s004):
    """Seed 004 ranges the balls' roughness; on the SKF model (which reads no roughness) it is not sampled: its
    draws would change nothing and take a coefficient of the ranking."""
    assert "lubricant.Rq_ball_um" in [i.address for i in uncertain_inputs(s004)]
    assert "lubricant.Rq_ball_um" not in [i.address for i in uncertain_inputs(s004.with_(models={"losses": "skf"}))]


def test_lubricant_draws_per_point_equal_one_lubricant_each():
    """A family of points with drawn lubricant densities (seed 002, MG1) gives each point the answer of
    a lubricant built with that density."""
    s = tb.load_scene(SEED002)
    rho = [880.0, 905.0]
    res = tb.steady_states([s.with_(samples={"lubricant.rho15_kg_m3": v}) for v in rho])
    for v, r in zip(rho, res):
        lub = tb.lubricant("seed002-mg1").per_point({"rho15_kg_m3": v})        # one number: a plain lubricant
        assert lub.points is None
        alone = tb.steady_state(s.with_(lubricant=lub))
        assert r.P_W == pytest.approx(alone.P_W, rel=1e-9)
        assert r.T_C["balls"] == pytest.approx(alone.T_C["balls"], rel=1e-9)


def test_a_known_linear_sensitivity_is_recovered(s004):
    """Only the support block's temperature drawn (offset ±1 K): the block node moves by exactly the
    draw (slope 1), and the inner ring's regression slope equals the finite difference of two nominal
    solves with the block imposed 1 K colder and warmer."""
    u = Uncertainty("offset", -1.0, 1.0, "uniform", "test")
    r = steady_uncertainty(s004, 24, seed=4, inputs=[Input("nodes.support_block.T_C", u, 0.0)])
    blk = r.sensitivity["T_C.support_block"]["inputs"][0]
    assert blk["slope"] == pytest.approx(1.0, rel=1e-9) and blk["src"] == pytest.approx(1.0, rel=1e-9)
    lo = tb.steady_state(s004.with_(T_fixed_C={"support_block": 24.0})).T_C["inner_ring"]
    hi = tb.steady_state(s004.with_(T_fixed_C={"support_block": 26.0})).T_C["inner_ring"]
    ir = r.sensitivity["T_C.inner_ring"]
    assert ir["inputs"][0]["slope"] == pytest.approx((hi - lo) / 2.0, rel=2e-3)
    assert ir["r2"] > 0.999


def test_failed_samples_are_counted_never_dropped(s004):
    """A conductance drawn negative (refused by the network: InputError) and a support block drawn
    far above the lubricant's limit (no equilibrium below it) are counted by error name; the bands
    are those of the samples that solved."""
    ins = [Input("elements.shaft_to_inner_ring_fit.h_W_m2K", Uncertainty("range", -4000.0, 8000.0), 5000.0),
           Input("nodes.support_block.T_C", Uncertainty("offset", 0.0, 900.0), 0.0)]
    r = steady_uncertainty(s004, 24, seed=5, inputs=ins)
    neg = r.X[:, 0] <= 0
    assert neg.any() and r.failed_count.get("InputError", 0) == int(neg.sum())
    assert len(r.failed) > int(neg.sum())                           # the hot blocks fail too
    assert set(r.failed_count) <= {"InputError", "ThermalRunaway", "NoConvergence"}
    ok = np.isfinite(r.outputs["P_W"])
    assert ok.sum() + len(r.failed) == r.n == 24
    assert r.bands["P_W"]["n"] == ok.sum()
    d = r.as_dict()
    assert d["failed"]["count"] == len(r.failed) and d["failed"]["by_error"] == r.failed_count


def test_transient_bands_over_time(s004):
    ins = _narrow([i for i in uncertain_inputs(s004) if i.level == "point"], 0.1)
    r = transient_uncertainty(s004, 600.0, 8, t_eval=[100.0, 300.0, 600.0], seed=1, inputs=ins)
    b = r.bands["T_C.inner_ring"]
    assert np.shape(b["p5"]) == (3,) and np.all(b["p5"] <= b["p95"])
    assert np.all(np.diff(b["p50"]) > 0)                             # heating up
    nom = np.interp([100.0, 300.0, 600.0], r.nominal.t_s, r.nominal.T_C["inner_ring"])
    assert np.all(np.abs(b["p50"] - nom) < 2.0)


def test_batched_heat_up_samples_equal_their_own_heat_ups(monkeypatch):
    """Seed 002 (one model alternative): sampled points integrated as one batch (one family, one
    block-diagonal system) each follow the heat-up they have alone; the seed-004 point, inside two
    model-switch bands, runs point by point through transient() (its blended alternatives)."""
    calls = []
    for name in ("_family_heatup", "_point_heatup"):
        f = getattr(unc, name)
        monkeypatch.setattr(unc, name, lambda *a, f=f, name=name, **k: calls.append(name) or f(*a, **k))
    s = tb.load_scene(SEED002)
    sm = sample_scenes(s, 4, seed=2, groups=1)
    t = np.array([60.0, 300.0])
    batch, failed = unc._heatups(sm.scenes, 300.0, t, None, 1e-8, 1e-6, None, None)
    assert not failed and calls == ["_family_heatup"]
    for k, sc in enumerate(sm.scenes):
        alone = tb.transient(sc, 300.0, t_eval=t, rtol=1e-8, atol=1e-6)
        assert batch["T_C.balls"][k] == pytest.approx(alone.T_C["balls"], abs=1e-3)
        assert batch["P_W"][k] == pytest.approx(alone.P_W, rel=1e-5)
    calls.clear()
    unc._heatups(sample_scenes(tb.load_scene(SEED004), 2, seed=2).scenes, 10.0, np.array([10.0]), None, 1e-5, 1e-3,
                 None, None)
    assert calls == ["_point_heatup", "_point_heatup"]


def test_given_inputs_keep_the_data_kind(s004):
    with pytest.raises(InputError, match="same kind"):
        sample_scenes(s004, 4, inputs=[Input("nodes.support_block.T_C", Uncertainty("factor", 0.9, 1.1), 1.0)])
    with pytest.raises(InputError, match="no estimated value"):
        sample_scenes(s004, 4, inputs=[Input("nodes.shaft.mass_kg", Uncertainty("factor", 0.9, 1.1), 1.0)])


def test_per_point_capacities_enter_the_heat_up(s004):
    """A drawn oil-air capacity (×2) slows the mixture's heat-up: per-point capacities in the batch."""
    u = Uncertainty("factor", 0.5, 2.0)
    pre = tb.prepare(s004)
    assert "nodes.oil_air.C_J_K" in pre.template.uncertainty
    r = transient_uncertainty(s004, 2.0, 8, t_eval=[2.0], seed=1, inputs=[Input("nodes.oil_air.C_J_K", u, 1.0)])
    rho = r.sensitivity["T_C.oil_air"]["inputs"][0]["spearman"]
    assert rho < -0.9


# --------------------------------------------------------------------------- API and CLI
def test_api_steady_state_with_uncertainty(s004):
    r = tb.steady_state(s004, uncertainty=8, seed=3)
    assert isinstance(r, tb.UncertaintyResult) and r.n == 8 and r.seed == 3
    assert isinstance(r.nominal, tb.SteadyState)
    assert isinstance(tb.steady_state(s004), tb.SteadyState)
    with pytest.raises(InputError):
        tb.steady_state(s004, uncertainty=0)
    with pytest.raises(InputError):
        tb.steady_state(s004.with_(T_C=50.0), uncertainty=4)


def test_a_pairs_band_carries_its_warm_preload(s004):
    """Seed 004's 7210 as one bearing of a back-to-back pair preloaded to 450 N (the block's 650 N on the pair): the
    warm preload, the design answer of a pair, gets its band and its ranking like a temperature.  Each solved sample's
    loaded bearing carries at least the pair's preload (a radial load on a preloaded pair adds axial load to the
    loaded bearing), the nominal value is the nominal answer's, and a scene without a pair has no such output."""
    pair = s004.with_(arrangement="back_to_back", preload_N=450.0, Fa=0.0, Fr=650.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = tb.steady_state(pair, uncertainty=8, seed=1)
    warm, Fa = r.outputs["preload.warm_N"], r.outputs["preload.Fa_N"]
    ok = np.isfinite(warm)
    assert ok.sum() >= 6 and np.all(Fa[ok] > warm[ok]) and np.all(warm[ok] > 450.0)
    assert r.nominal_values["preload.warm_N"] == pytest.approx(r.nominal.preload["warm_N"], rel=1e-12)
    b = r.bands["preload.warm_N"]
    assert b["p5"] < b["p50"] < b["p95"] and "preload.warm_N" in r.sensitivity
    assert "preload.warm_N [N]" in r.summary() and "Inputs ranked for preload.warm_N" in r.summary()
    assert not any(k.startswith("preload.") for k in tb.steady_state(s004, uncertainty=4, seed=1).outputs)


def test_a_pairs_heat_up_bands_carry_its_preload_over_time(s004):
    """The heat-up of one bearing of a preloaded pair with uncertainty: each sample's heat-up on its own (its preload's
    pieces), equal to the heat-up of the sample's scene alone; bands over its preload at the temperatures and the loaded
    bearing's axial load at each output time.  Early in the heat-up the preload rises (the
    inner ring and balls warm before the housing), and the loaded bearing carries at least the preload (the pair's
    radial load adds axial load to it)."""
    pair = s004.with_(arrangement="back_to_back", preload_N=450.0, Fa=0.0, Fr=650.0)
    t = np.array([20.0, 60.0])                   # (the first minute: ~40 pieces of ≤ 2 % drift, 2 s a heat-up)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = tb.transient(pair, 60.0, uncertainty=2, seed=1, t_eval=t)
        alone = [tb.transient(sc, 60.0, t_eval=t) for sc in sample_scenes(pair, 2, seed=1).scenes]
    assert not r.failed and r.nominal.preload is not None
    warm, Fa = r.outputs["preload.warm_N"], r.outputs["preload.Fa_N"]
    for k, run in enumerate(alone):
        assert warm[k] == pytest.approx(run.preload["series"]["preload_N"], rel=1e-9)
        assert r.outputs["T_C.balls"][k] == pytest.approx(run.T_C["balls"], rel=1e-9)
    assert np.all(np.diff(warm, axis=1) > 0) and np.all(Fa >= warm) and np.all(warm > 450.0)
    b = r.bands["preload.warm_N"]
    assert np.shape(b["p5"]) == (2,) and np.all(b["p5"] <= b["p95"]) and "preload.Fa_N" in r.bands
    nominal = r.nominal.preload["series"]
    assert r.nominal_values["preload.warm_N"] == pytest.approx(float(np.interp(60.0, nominal["t_s"],
                                                                               nominal["preload_N"])), rel=1e-12)
    assert "preload.warm_N [N]" in r.summary()


def test_cli_run_uncertainty_json_and_table(capsys):
    assert main(["run", SEED004, "--uncertainty", "8", "--seed", "2", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    u = d["uncertainty"]
    assert u["design"] == {"n": 8, "seed": 2, "method": "lhs", "groups": 8, "sensitivity": "src"}
    assert set(u["bands"]["T_C.inner_ring"]) == {"p5", "p50", "p95", "n"}
    assert u["failed"]["count"] == 0 and u["sensitivity"]["P_W"]["inputs"]
    life = u["bands"]["ratings.L10m_h"]                      # the design answers carry their bands too
    assert 0 < life["p5"] <= life["p50"] <= life["p95"] and u["nominal_values"]["ratings.L10m_h"] > 0
    assert main(["run", SEED004, "--uncertainty", "8"]) == 0
    out = capsys.readouterr().out
    assert "p95" in out and "Failed samples: 0 of 8" in out and "Inputs ranked for P_W" in out
    assert "L10m_h [h]" in out and "kappa [-]" in out and "clearance_op_um [µm]" in out
    assert main(["run", SEED004, "--uncertainty", "0"]) == 2


def test_cli_compare_shows_the_measured_points_against_the_band(capsys):
    logs = tb.example_path("seed004_oil_jet_7210.toml").rsplit("/", 1)[0] + "/logs/"
    assert main(["compare", logs + "synthetic_heatup_scene.toml", logs + "synthetic_heatup_7210.csv",
                 "--uncertainty", "8", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    b = d["bands"]["T_bearing_C"]
    assert len(b["p5"]) == len(d["x"]) and all(lo <= hi for lo, hi in zip(b["p5"], b["p95"]))
    k, m = d["inside_band"]["T_bearing_C"]
    assert 0 <= k <= m == len(d["x"]) and d["uncertainty"]["n"] == 8


def test_cli_withholds_a_ranking_the_family_draws_do_not_determine(tmp_path, capsys):
    """The engineer's 7014C spindle (``thermobear init``): 16 family-level inputs (bearing geometry, the
    built network's estimates), which the default would draw on 2 (16 + 1) = 34 families (it drew them on 18,
    d + 2, and ranked by noise: SRC −2.04, seat roughness the #2 driver of the power).  20 samples make at most 20
    families: the regression on them is withheld — no SRC beyond 1 or of a sign against the rank correlation —
    with the caveat UnreliableRegression in the JSON, naming the counts, and one warning line on stderr."""
    scene = tmp_path / "spindle.toml"
    assert main(["init", "7014C", "--lubrication", "oil-air", "--housing", "block", "--speed-rpm", "12000",
                 "--Fa-N", "600", "--out", str(scene)]) == 0
    capsys.readouterr()
    assert main(["run", str(scene), "--uncertainty", "20", "--seed", "1", "--json"]) == 0
    out, err = capsys.readouterr()
    u = json.loads(out)["uncertainty"]
    assert u["design"]["groups"] == 20                    # min(n, 34)
    for key in ("P_W", "T_C.balls"):
        r = u["sensitivity"][key]
        c = r["caveat"]
        assert c["name"] == "UnreliableRegression" and "too_few_draws" in c["reasons"]
        assert c["levels"]["family"]["inputs"] == 16 and c["levels"]["family"]["needed"] == 34
        assert c["levels"]["family"]["draws"] <= 20
        assert r["ranked_by"] == "spearman" and r["r2"] is None
        assert all(e["src"] is None and e["slope"] is None for e in r["inputs"])
    assert sum(line.startswith("warning: UnreliableRegression: ") for line in err.splitlines()) == 1


def test_cli_table_names_the_caveat_once(capsys):
    """Seed 004 with 8 samples for its 47 inputs: too few for the regression; the table says so in one
    named line and ranks by rank correlation."""
    assert main(["run", SEED004, "--uncertainty", "8", "--seed", "2"]) == 0
    out, err = capsys.readouterr()
    lines = out.splitlines()
    cav = [line for line in lines if line.startswith("caveat: UnreliableRegression: ")]
    assert len(cav) == 1 and "48 coefficients" in cav[0] and "on 8 samples" in cav[0]
    assert "Inputs ranked for P_W (by rank correlation; regression withheld: caveat above)" in lines
    assert "SRC " not in out.split(cav[0])[1]
    assert "warning: UnreliableRegression: " in err


def test_a_negative_seed_is_refused_by_name(capsys):
    """`--seed -1` ended in an internal ValueError of numpy (exit 1)."""
    from thermobear.coupled.uncertainty import design
    with pytest.raises(tb.InputError) as e:
        design(8, 2, seed=-1)
    assert e.value.field == "uncertainty.seed"
    assert main(["run", SEED004, "--uncertainty", "8", "--seed", "-1"]) == 2
    assert "error: uncertainty.seed = -1" in capsys.readouterr().err


def test_cli_run_uncertainty_plots_the_bands_beside_its_design_answers(capsys, tmp_path):
    """`run --uncertainty N --plot DIR` draws the temperature and power bands; the design answers' bands (κ, life,
    clearance, a pair's preload and stiffness, in their own units) stay in the text's table, not on a power axis."""
    assert main(["run", SEED004, "--uncertainty", "8", "--seed", "2", "--plot", str(tmp_path / "p")]) == 0
    out = capsys.readouterr().out
    assert (tmp_path / "p" / "bands_T.png").is_file() and (tmp_path / "p" / "bands_P.png").is_file()
    assert "kappa [-]" in out and "L10m_h [h]" in out


def test_heat_up_bands_in_worker_processes_are_the_same_bands(s004, capsys, monkeypatch):
    """transient(..., uncertainty=N, processes=2): the geometry groups' heat-ups in worker processes give the outputs
    of the samples run here, to the bit; bad counts are refused by name, and --processes without --uncertainty on
    the command line (it would run nothing in a worker)."""
    kw = dict(uncertainty=4, seed=1, t_eval=[30.0, 120.0])
    here = tb.transient(s004, 120.0, **kw)
    pools = []
    real = unc.imap_unordered
    monkeypatch.setattr(unc, "imap_unordered", lambda fn, jobs, n: pools.append(len(jobs)) or real(fn, jobs, n))
    there = tb.transient(s004, 120.0, processes=2, **kw)
    assert pools and pools[0] > 1                       # (the groups' heat-ups went to the workers)
    assert set(here.outputs) == set(there.outputs) and here.failed == there.failed
    for k, v in here.outputs.items():
        assert np.array_equal(v, there.outputs[k], equal_nan=True), k
    for bad in (0, 1.5, True):
        with pytest.raises(InputError, match="processes"):
            transient_uncertainty(s004, 10.0, 2, processes=bad)
    assert main(["transient", SEED004, "--t-end", "10", "--processes", "2"]) == 2
    assert "error: --processes" in capsys.readouterr().err


def test_stop_with_worker_processes_ends_the_band_between_groups(s004):
    """stop() with processes > 1 acts between the geometry groups: the first group answered, every later one counted
    as stopped samples (as a heat-up stopped in this process), the workers ended."""
    r = transient_uncertainty(s004, 60.0, 4, seed=1, t_eval=[60.0], processes=2, stop=lambda: True)
    stopped = [k for k, v in r.failed.items() if "stopped" in v["message"]]
    assert 0 < len(stopped) < 4 and len(r.failed) == len(stopped)
    assert np.isfinite(r.outputs["P_W"]).sum() == 4 - len(stopped)


def test_worker_processes_are_counted_as_they_must_be(s004):
    from thermobear.parallel import check_processes, imap_unordered
    assert check_processes(np.int64(2)) == 2
    for bad in (0, -1, 1.0, True, "2"):
        with pytest.raises(InputError, match="processes"):
            check_processes(bad)
    with pytest.raises(InputError, match="processes"):
        list(imap_unordered(abs, [1, 2], 0))
    with pytest.raises(InputError, match="uncertainty=N"):          # one heat-up: no worker to run it
        tb.transient(s004, 10.0, processes=2)
