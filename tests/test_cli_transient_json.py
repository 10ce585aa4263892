"""``thermobear transient --json`` carries what the text prints: the end temperatures and each node's t90
(the text's t90 column was missing from the JSON)."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from thermobear.app.cli import main

SYNTH = str(Path(__file__).resolve().parents[1] / "examples" / "logs" / "synthetic_heatup_scene.toml")


def test_transient_json_has_the_texts_t90(capsys):
    argv = ["transient", SYNTH, "--t-end", "1200", "--points", "41"]
    assert main(argv) == 0
    rows = [ln.split() for ln in capsys.readouterr().out.splitlines() if ln.startswith("bearing ")]
    assert main(argv + ["--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    (row,) = rows
    assert float(row[2]) == pytest.approx(d["final_T_C"]["bearing"], abs=0.006)
    assert d["t90_s"]["bearing"] == pytest.approx(float(row[3]), abs=0.5) and 0 < d["t90_s"]["bearing"] < 1200
    assert d["t90_s"]["ambient"] is None                   # a boundary: no rise, '-' in the text
