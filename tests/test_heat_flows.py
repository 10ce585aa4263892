"""Heat flows of a steady state (thermobear.coupled.run.heat_flows): where each loss part heats the
network and which path carries it out; conservation (the paths sum to the power loss)."""
import json

import pytest

import thermobear as tb
from thermobear.app.cli import main
from thermobear.coupled import solve
from thermobear.coupled.run import heat_flows, path_group


@pytest.mark.parametrize("example", ["block_6208_grease.toml", "block_6208_oil_jet.toml",
                                     "seed004_oil_jet_7210.toml"])
def test_heat_leaving_sums_to_the_power_and_sources_to_the_loss(example):
    r = solve(tb.load_scene(tb.example_path(example)))
    hf = heat_flows(r.steady)
    out = sum(hf["out_W"].values())
    assert out == pytest.approx(r.P_W, rel=1e-6)                      # energy conservation at the steady state
    assert sum(hf["out_by_group_W"].values()) == pytest.approx(out, rel=1e-12)
    made = sum(w for nodes in hf["sources_W"].values() for w in nodes.values())
    assert made == pytest.approx(r.P_W, rel=1e-9)
    assert set(hf["out_W"]) == set(hf["out_to"])
    if example.startswith("seed004"):
        assert hf["out_W"]["oil_stream"] > 0                          # 30 °C oil carries heat away
    if example == "block_6208_oil_jet.toml":                          # 40 °C oil into a 39.6 °C cavity heats it
        assert hf["out_W"]["oil_stream"] < 0 and r.T_C["oil_air"] < 40.0
    if "grease" in example:
        assert hf["sources_W"]["seal"] and set(hf["sources_W"]["seal"]) == {"seal"}


def test_run_prints_the_heat_flow_table_and_json(capsys):
    path = tb.example_path("block_6208_oil_bath.toml")
    assert main(["run", path]) == 0
    text = capsys.readouterr().out
    assert "Heat leaving" in text and "housing → frame_mounting" in text and "total" in text
    assert main(["run", path, "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert sum(d["heat_flows"]["out_W"].values()) == pytest.approx(d["P_W"], rel=1e-6)
    assert d["heat_flows"]["sources_W"]["churning"] == pytest.approx({"oil_sump": d["breakdown_W"]["churning"]})


def test_path_groups_drop_the_cells_of_the_discretisation():
    assert path_group("housing_seat_1_r5--frame_mounting", "frame") == "housing → frame_mounting"
    assert path_group("shaft_left_6--ambient_end", "ambient") == "shaft_left → ambient_end"
    assert path_group("bearing_to_ambient", "ambient") == "bearing_to_ambient → ambient"
