"""``--set key=value``: values read as TOML, names kept as names (a designation such as 6308 is not a number)."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from thermobear.app.cli import main
from thermobear.app.verbs import overrides

BATH = str(Path(__file__).resolve().parents[1] / "examples" / "block_6208_oil_bath.toml")


@pytest.mark.parametrize("item, expected", [
    ("bearing=6308", {"bearing": "6308"}),
    ('bearing="6308"', {"bearing": "6308"}),
    ("bearing=51110", {"bearing": "51110"}),
    ('bearing={catalog = "6308"}', {"bearing": {"catalog": "6308"}}),
    ("lubricant=iso-vg-68-mineral", {"lubricant": "iso-vg-68-mineral"}),
    ("n_rpm=6500", {"n_rpm": 6500}),
    ("models.losses=skf", {"models": {"losses": "skf"}}),
])
def test_overrides_read_values_and_keep_names(item, expected):
    assert overrides([item]) == expected


def test_set_bearing_by_designation_runs_that_bearing(capsys):
    code = main(["run", BATH, "--json", "--set", "bearing=6308", "--set", "T_C=60"])
    out, err = capsys.readouterr()
    assert code == 0, err
    assert json.loads(out)["bearing"] == "6308"


def test_set_unknown_designation_is_bad_input(capsys):
    code = main(["run", BATH, "--set", "bearing=9999", "--set", "T_C=60"])
    err = capsys.readouterr().err
    assert code == 2 and err.startswith("error: bearing = '9999' — unknown catalog name")


def test_set_clearance_group_rebuilds_the_scenes_bearing(tmp_path, capsys):
    """`--set clearance_group=C3` was refused citing the Python API (`scene.with_(clearance_group)`): it is the
    scene's [bearing] key, set as `bearing.clearance_group` (or alone) — the bearing rebuilt from the file's
    [bearing] table with it (6208: P_d 13 µm CN → 24 µm C3) — and an unknown key names `--set <key>`."""
    scene = tmp_path / "s.toml"
    assert main(["init", "6208", "--lubrication", "oil-bath", "--out", str(scene)]) == 0
    capsys.readouterr()
    from thermobear.app.verbs import load_scene_with
    cn = load_scene_with(scene).bearing
    for item in ("clearance_group=C3", "bearing.clearance_group=C3", 'bearing.clearance_group="C3"'):
        b = load_scene_with(scene, [item]).bearing
        assert b.clearance_group == "C3" and b.Pd == pytest.approx(24e-6) and b.name == cn.name and cn.Pd == 13e-6
    c4 = load_scene_with(scene, ["bearing=6308", "clearance_group=C4"]).bearing
    assert c4.name == "6308" and c4.clearance_group == "C4"
    # a bearing whose data state its clearance (seed 004's 6210: Pd_mm 14.5 µm) takes the group given instead (it
    # kept 14.5 µm and dropped the group silently): bore 50 mm, C3 18–36 µm
    import thermobear as tb
    bath = tb.example_path("oil_bath_6208.toml")                  # a hand-written network: any bore fits
    b = load_scene_with(bath, ["bearing=6210", "clearance_group=C3"]).bearing
    assert b.clearance_group == "C3" and b.Pd == pytest.approx(27e-6)
    assert load_scene_with(bath, ["bearing.catalog=6210"]).bearing.name == "6210"    # a number-like name: text
    code = main(["run", str(scene), "--json", "--set", "clearance_group=C3", "--set", "T_C=60"])
    out, err = capsys.readouterr()
    assert code == 0, err
    assert "P_d 24 µm (C3)" in json.loads(out)["models_used"]["clearance"]["reason"]
    code = main(["run", str(scene), "--set", "clearance_grp=C3"])
    err = capsys.readouterr().err
    assert code == 2 and err.startswith("error: --set clearance_grp = 'C3' — unknown key; accepted: n_rpm")
    assert "scene.with_" not in err and "bearing.<key>" in err and len(err.splitlines()) == 1
    code = main(["run", str(scene), "--set", "bearing.clearance_group=C9"])
    err = capsys.readouterr().err
    assert code == 2 and err.startswith("error: bearing.clearance_group = 'C9' — must be one of CN, C3, C4")


def test_set_takes_a_scene_files_number_as_written():
    """`--set flow_L_h=5` was unknown (the with_ key is oil_flow_L_h): a scene file's number is taken as written, with
    or without its section, and lands on the same scene value."""
    from thermobear.app.overrides import overrides
    assert overrides(["flow_L_h=5", "lubricant.T_in_C=40", "operation.n_rpm=100", "lubricant.K_rs=4e-8"]) == \
        {"oil_flow_L_h": 5, "T_oil_in_C": 40, "n_rpm": 100, "K_rs": 4e-8}
    assert overrides(["flow_L_h=5"]) == overrides(["oil_flow_L_h=5"])


def test_set_takes_the_seat_fits(capsys):
    """`--set bearing.shaft_fit=k5` was refused (the fits could only be given in the file): stated fits close the
    clearance loop of a deep groove bearing; an unknown class is refused by name."""
    scene = str(Path(__file__).resolve().parents[1] / "examples" / "block_6208_oil_jet.toml")
    assert main(["run", scene, "--json", "--set", "bearing.shaft_fit=k5", "--set", "bearing.housing_fit=H7"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["models_used"]["clearance"]["choice"] == "operating"
    assert main(["run", scene, "--set", "bearing.shaft_fit=k9"]) == 2
    assert "shaft_fit = 'k9' — must be one of" in capsys.readouterr().err


@pytest.mark.parametrize("item, line", [
    ("flow_L_h=-1", "error: flow_L_h = -1 — must be in [0, 100000] [L/h]"),
    ("lubricant.T_in_C=900", "error: lubricant.T_in_C = 900 — must be in [-40, 250] [°C]")])
def test_a_file_keys_error_names_the_key_as_given(capsys, item, line):
    """`--set flow_L_h=-1` was refused as `oil_flow_L_h = -1`, a name the user never wrote."""
    scene = str(Path(__file__).resolve().parents[1] / "examples" / "block_6208_oil_jet.toml")
    assert main(["run", scene, "--set", item]) == 2
    assert capsys.readouterr().err.strip() == line
