"""The README's Python example runs as written (from the repository root, as the README shows it)."""
from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_readme_python_example_runs(monkeypatch):
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
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
