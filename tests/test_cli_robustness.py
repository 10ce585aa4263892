"""The command line under random bad input (property-based, hypothesis): mutated bundled scenes —
wrong types, unknown keys, NaN/inf, negative, huge and tiny values, bad encodings — through ``run``,
``loads``, ``transient`` and ``sweep``.  Every outcome is one of: exit 0 with finite JSON output,
exit 2 with one line naming a field, exit 3 with one line naming a solver error; never a traceback,
never NaN/inf in an output, never a file half-written.

A few hundred examples run in CI (``THERMOBEAR_FUZZ`` unset); ``THERMOBEAR_FUZZ=long`` runs thousands.
"""
import csv as _csv
import json
import math
import os
import tomllib
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import thermobear as tb
from thermobear.app.cli import main

LONG = os.environ.get("THERMOBEAR_FUZZ") == "long"
SCENES = ["seed004_oil_jet_7210.toml", "seed002_grease_thrust_51107.toml", "seed000_grease_thrust_3ball.toml"]
BASE = {name: tomllib.loads(open(tb.example_path(name), encoding="utf-8").read()) for name in SCENES}


def _toml_value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        return "nan" if math.isnan(v) else ("inf" if v == math.inf else "-inf" if v == -math.inf else repr(v))
    if isinstance(v, int):
        return str(v)
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, list):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f'"{k}" = {_toml_value(x)}' for k, x in v.items()) + " }"
    raise TypeError(v)


def dumps(d: dict) -> str:
    """A minimal TOML writer for scene tables (sections of key = value, inline sub-tables)."""
    out = []
    for sec, tbl in d.items():
        if not isinstance(tbl, dict):
            out.append(f'"{sec}" = {_toml_value(tbl)}')
            continue
        out.append(f'["{sec}"]')
        out += [f'"{k}" = {_toml_value(v)}' for k, v in tbl.items()]
    return "\n".join(out) + "\n"


BAD_VALUES = st.one_of(
    st.sampled_from([math.nan, math.inf, -math.inf, -1.0, 0.0, 1e-300, 1e30, -1e30, 1e6, 1e-9, 3, -7]),
    st.sampled_from(["", "68", "false", "maybe", "7210", "one_node", "é"]),
    st.sampled_from([True, False, [], [1.0, 2.0], {}, {"x": 1.0}]),
    st.floats(allow_nan=True, allow_infinity=True, width=64),
)


@st.composite
def mutated_scene(draw):
    name = draw(st.sampled_from(SCENES))
    d = json.loads(json.dumps(BASE[name]))           # a deep copy
    for _ in range(draw(st.integers(1, 3))):
        sec = draw(st.sampled_from(sorted(d)))
        tbl = d[sec]
        kind = draw(st.sampled_from(["replace", "replace", "replace", "unknown", "delete", "section"]))
        if kind == "section":
            d[draw(st.sampled_from(["bogus", "operation", "models"]))] = draw(st.sampled_from([{}, {"x": 1.0}, 3]))
        elif not isinstance(tbl, dict) or not tbl:
            continue
        elif kind == "unknown":
            tbl[draw(st.sampled_from(["flow_L_min", "nu40", "Fa", "drag_on", "x"]))] = draw(BAD_VALUES)
        elif kind == "delete":
            del tbl[draw(st.sampled_from(sorted(tbl)))]
        else:
            tbl[draw(st.sampled_from(sorted(tbl)))] = draw(BAD_VALUES)
    return d


def _finite(x) -> bool:
    if isinstance(x, dict):
        return all(_finite(v) for v in x.values())
    if isinstance(x, list):
        return all(_finite(v) for v in x)
    if isinstance(x, float):
        return math.isfinite(x)
    return True


def _check(code, out, err, json_out=True):
    assert "Traceback" not in err and "Traceback" not in out, err
    lines = [line for line in err.splitlines() if line.strip()]
    errors = [line for line in lines if not line.startswith(("warning: ", "wrote "))]
    assert code in (0, 2, 3), (code, err)
    if code == 0:
        assert not errors, err
        if json_out:
            assert _finite(json.loads(out)), "NaN or inf in the output"
    else:
        assert len(errors) == 1 and errors[0] == lines[-1], err
        if code == 2:
            assert errors[0].startswith("error: ") and " — " in errors[0], err
        else:                     # a named solver error, or a sweep whose failed points say why in their rows
            name = errors[0].split(":")[1].strip()
            assert name.endswith(("Runaway", "Convergence", "Equilibrium")) or " points failed (" in name, err


FUZZ = settings(max_examples=2000 if LONG else 150, deadline=None, derandomize=not LONG,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])


@FUZZ
@given(scene=mutated_scene(), verb=st.sampled_from(["run", "loads", "transient", "sweep"]))
def test_mutated_scenes_exit_0_2_or_3_and_never_a_traceback(tmp_path, capsys, scene, verb):
    path = tmp_path / "scene.toml"
    path.write_text(dumps(scene), encoding="utf-8")
    out_csv = tmp_path / "out.csv"
    out_csv.unlink(missing_ok=True)
    args = {"run": ["run", path, "--json"], "loads": ["loads", path, "--json"],
            "transient": ["transient", path, "--t-end", "200", "--points", "5", "--json", "--csv", out_csv],
            "sweep": ["sweep", path, "--n-rpm", "1000,3000", "--json", "--csv", out_csv, "--quiet"]}[verb]
    code = main([str(a) for a in args])
    out, err = capsys.readouterr()
    _check(code, out, err)
    if out_csv.exists():                              # written whole, or row by row: every row complete
        with open(out_csv, newline="", encoding="utf-8") as fh:
            rows = list(_csv.reader(line for line in fh if not line.startswith("#")))
        assert rows and all(len(r) == len(rows[0]) for r in rows)
        assert not any(c.strip().lower() in ("nan", "inf", "-inf") for r in rows for c in r)


@FUZZ
@given(data=st.binary(min_size=1, max_size=300), verb=st.sampled_from(["run", "loads"]))
def test_any_bytes_as_a_scene_file_are_refused_by_name(tmp_path, capsys, data, verb):
    path = tmp_path / "scene.toml"
    path.write_bytes(data)
    code = main([verb, str(path)])
    out, err = capsys.readouterr()
    _check(code, out, err, json_out=False)
    assert code == 2                              # unreadable, not TOML, or a TOML without what a scene needs


@pytest.mark.parametrize("text", ["[operation]\nn_rpm = 1000\n".encode("latin-1") + b"\xe9\xff",
                                  b"\xff\xfe[scene]\n", "[bearing]\ncatalog = \"7210\"\n".encode("utf-16")])
def test_a_non_utf8_scene_names_the_file(tmp_path, capsys, text):
    path = tmp_path / "scene.toml"
    path.write_bytes(text)
    code = main(["run", str(path)])
    _, err = capsys.readouterr()
    assert code == 2 and "not UTF-8" in err and str(path) in err and len(err.strip().splitlines()) == 1




def test_a_scene_with_a_utf8_byte_order_mark_runs_as_without(tmp_path, capsys):
    """Some editors write a byte-order mark before UTF-8 text; tomllib read it as an invalid character (exit 2)."""
    src = Path(tb.example_path("seed004_oil_jet_7210.toml"))
    path = tmp_path / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + src.read_bytes())
    assert main(["run", str(path), "--json"]) == 0
    bom = json.loads(capsys.readouterr().out)
    assert main(["run", str(src), "--json"]) == 0
    assert bom["P_W"] == json.loads(capsys.readouterr().out)["P_W"]
