"""Overrides of a scene (``Scene.with_``, the command line's ``--set``, a schedule step) give the scene the
same file with those values would be: a parametric machine is built again from the values that shape
its network (seals, oil level, …), at the operating point it was built at (no cell count changes)."""
from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

import thermobear as tb
from thermobear.scene.scene import scene_from_dict
from thermobear.thermal.builders import build_network

BATH = Path(tb.example_path("block_6208_oil_bath.toml"))
GREASE = Path(tb.example_path("block_6208_grease.toml"))


def _file(path: Path, **sections) -> tb.Scene:
    """The scene of ``path`` with some keys of its sections changed (as a user would edit the file)."""
    d = tomllib.loads(path.read_text(encoding="utf-8"))
    for sec, kv in sections.items():
        d.setdefault(sec, {}).update(kv)
    return scene_from_dict(d, path=str(path))


@pytest.mark.parametrize("seals, closure, node", [("shield", "shields", "housing_air"), ("RS1", "contact", "seal")])
def test_seals_override_closes_the_cavity_as_the_file_does(seals, closure, node):
    base = _file(GREASE, bearing={"seals": "none", "seal_sides": 0})
    over, edited = base.with_(seals=seals), _file(GREASE, bearing={"seals": seals, "seal_sides": 2})
    assert over.network.housing.seals == closure
    assert over.network == edited.network
    assert node in build_network(over.network).nodes and node not in build_network(base.network).nodes


def test_seals_override_gives_the_files_temperatures():
    base = _file(GREASE, bearing={"seals": "none", "seal_sides": 0})
    a, b = tb.steady_state(base.with_(seals="RS1")), tb.steady_state(_file(GREASE, bearing={"seals": "RS1"}))
    assert a.P_W == pytest.approx(b.P_W, rel=1e-9)
    assert a.T_C == pytest.approx(b.T_C, rel=1e-9)
    assert a.heat_sources_W["seal"] == pytest.approx({"seal": b.heat_sources_W["seal"]["seal"]})


def test_oil_level_override_sets_the_sump_of_the_network():
    s = tb.load_scene(BATH)
    over, edited = s.with_(oil_level_mm=30.0), _file(BATH, lubricant={"oil_level_mm": 30.0})
    assert over.network.lubrication.oil_level == pytest.approx(0.03)
    assert over.network == edited.network
    a, b = tb.steady_state(over), tb.steady_state(edited)
    assert a.P_W == pytest.approx(b.P_W, rel=1e-9) and a.T_C["balls"] == pytest.approx(b.T_C["balls"], rel=1e-9)


def test_rebuilt_machine_keeps_its_operating_point_and_nodes():
    """A lubricant change together with a load change (a schedule step) keeps the discretisation of the
    scene's own operating point: the same nodes (it was refused as a change of the network's nodes)."""
    s = tb.load_scene(BATH)
    moved = s.with_(Fr=6000.0, n_rpm=500.0, lubricant="iso-vg-32-mineral")
    assert (moved.network.Fr, moved.network.n_rpm) == (s.network.Fr, s.network.n_rpm)
    assert list(build_network(moved.network).nodes) == list(build_network(s.network).nodes)


def test_schedule_with_load_and_lubricant_step_runs(tmp_path):
    steps = tmp_path / "steps.toml"
    steps.write_text('[[step]]\nt_s = 300.0\nFr_N = 6000.0\nlubricant = "iso-vg-32-mineral"\n', encoding="utf-8")
    from thermobear.app.cli import main
    assert main(["transient", str(BATH), "--t-end", "600", "--points", "5", "--schedule", str(steps), "--json"]) == 0
