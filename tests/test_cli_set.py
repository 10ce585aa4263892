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
