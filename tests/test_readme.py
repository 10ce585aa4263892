"""The README says what the code does: its Python example runs as written (from the repository root, as
the README shows it), its table of limits is thermobear.validity.LIMITS, its exit codes the command line's."""
from __future__ import annotations

import re
from pathlib import Path

from thermobear.app.cli import EXIT_BAD_INPUT, EXIT_INTERRUPTED, EXIT_SOLVER
from thermobear.validity import limits_table

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text(encoding="utf-8")


def test_readme_python_example_runs(monkeypatch):
    blocks = re.findall(r"```python\n(.*?)```", README, re.S)
    assert blocks, "README has no python example"
    monkeypatch.chdir(ROOT)                       # its paths are relative to the repository root
    ns: dict = {}
    for code in blocks:
        exec(compile(code, "README.md", "exec"), ns)
    tb = ns["tb"]
    assert ns["st"].P_W > 0 and ns["tr"].P_W.size > 1
    assert ns["rig"].T_C["inner_ring"] == 52.0                      # imposed ring temperatures hold
    assert tb.choose_models(ns["lifted"])["load_model"][0] == "film"
    assert ns["dry"].models_used["load_model"][0] == "jones_harris"


def test_readme_table_of_limits_is_the_limits_the_code_checks():
    got = re.search(r"<!-- limits: [^\n]*-->\n(.*?)\n<!-- /limits -->", README, re.S)
    assert got, "README has no generated table of limits"
    assert got.group(1) == limits_table(), ("the README's table of limits differs from thermobear.validity.LIMITS: "
                                           "paste thermobear.validity.limits_table() between the markers")


def test_readme_exit_codes_are_the_command_lines():
    section = README.split("## Command line: exit codes", 1)[1].split("\n## ", 1)[0]
    codes = [int(c) for c in re.findall(r"^\| (\d+) \|", section, re.M)]
    assert codes == sorted({0, 1, EXIT_BAD_INPUT, EXIT_SOLVER, EXIT_INTERRUPTED})


def test_readme_bundled_data_counts_the_catalogue():
    """The "Bundled data" table listed 6 bearings and 10 lubricants while the catalogue holds 308 bearings and 36
    lubricants (ISO VG oils, greases): its counts and names are the catalogue's."""
    from thermobear.contact.geometry import bearing, bearing_names
    from thermobear.lubrication.lubricant import lubricant, lubricant_names
    section = README.split("## Bundled data", 1)[1].split("\n## ", 1)[0]
    rows = {m[0]: m[1] for m in re.findall(r"^\| ([a-z ]+?) \| (.*?) \|", section, re.M)}
    names = bearing_names()
    assert rows["bearings"].startswith(f"{len(names)} ")
    series = {bearing(n).series for n in names} - {None}
    listed = {s.replace(" ", "") for s in re.findall(r"\b(\d{2,3}(?: [BCE])?)\b(?!°)", rows["bearings"].split(" — ")[1])}
    assert listed == series
    assert {n for n in names if bearing(n).series is None} <= set(re.findall(r"`([^`]+)`", rows["bearings"]))
    lubs = lubricant_names()
    greases = [n for n in lubs if n.startswith("grease-")]
    vg = [n for n in lubs if n.startswith("iso-vg-")]
    assert all(lubricant(n).kind == "grease" for n in greases) and all(lubricant(n).kind == "oil" for n in vg)
    head = rows["lubricants"]
    assert head.startswith(f"{len(lubs)} ") and f"{len(vg)} ISO VG oils" in head and f"{len(greases)} greases" in head
    assert all(f"`{g}`" in head for g in greases)
    seeds = [n for n in lubs if n not in greases + vg]
    assert f"{len(seeds)} of the seed papers" in head
    assert all(f"`{n}`" in head or f"`-{n.rsplit('-', 1)[1]}`" in head for n in seeds)
    assert rows["scenes"].startswith(f"{len(list((ROOT / 'examples').glob('*.toml')))} ")
