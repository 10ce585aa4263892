"""A grease is refused under an oil supply (oil bath, jet, oil–air) wherever a scene gets it: the file,
``Scene.with_`` / ``--set``, a sweep's lubricant list — as ``thermobear init --oil`` refuses it."""
from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

import thermobear as tb
from thermobear.app.cli import main
from thermobear.errors import InputError
from thermobear.scene.scene import scene_from_dict

BATH = Path(tb.example_path("block_6208_oil_bath.toml"))
GREASE = "grease-lithium-mineral-vg100-nlgi2"


def test_grease_in_an_oil_bath_file_is_refused_by_name():
    d = tomllib.loads(BATH.read_text(encoding="utf-8"))
    d["lubricant"]["name"] = GREASE
    with pytest.raises(InputError, match=r"lubricant\.name = 'grease-lithium-mineral-vg100-nlgi2' — is a grease; "
                                         r"supply = 'oil_bath' needs an oil"):
        scene_from_dict(d, path=str(BATH))


@pytest.mark.parametrize("example", ["block_6208_oil_bath.toml", "block_6208_oil_jet.toml", "seed004_oil_jet_7210.toml"])
def test_grease_override_under_an_oil_supply_is_refused(example):
    with pytest.raises(InputError, match="is a grease"):
        tb.load_scene(tb.example_path(example)).with_(lubricant=GREASE)


def test_grease_stays_accepted_with_a_grease_supply():
    s = tb.load_scene(tb.example_path("block_6208_grease.toml")).with_(lubricant="grease-polyurea-mineral-vg100-nlgi2")
    assert s.lubricant.kind == "grease" and s.supply == "grease"


@pytest.mark.parametrize("argv", [["run", str(BATH), "--set", f"lubricant={GREASE}"],
                                  ["sweep", str(BATH), "--n-rpm", "3000", "--lubricant", f"iso-vg-68-mineral,{GREASE}"]])
def test_cli_grease_under_oil_is_bad_input(capsys, argv):
    code = main(argv)
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and err.startswith("error: lubricant.name")


@pytest.mark.parametrize("typo, close", [("iso-vg-68-minral", "iso-vg-68-mineral"), ("seed004-mineal", "seed004-mineral")])
def test_a_typod_lubricant_is_refused_naming_the_closest_names_first(typo, close):
    with pytest.raises(InputError, match=rf"^lubricant = '{typo}' — unknown name; close: {close}"):
        tb.load_scene(BATH).with_(lubricant=typo)
