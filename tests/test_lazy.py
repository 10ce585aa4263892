"""thermobear.lazy: heavy modules of optional paths are loaded on first use, not by `thermobear run`."""
import subprocess
import sys

import pytest

from thermobear.lazy import lazy_module

#: modules only uncertainty, sensitivity, transients, spin-downs, speeds and calibration use
DEFERRED = ("scipy.stats", "scipy.integrate", "scipy.optimize")


def _loaded_after(code: str) -> dict:
    probe = ("import sys, json\n" + code + "\n"
             "print(json.dumps({m: (m in sys.modules and type(sys.modules[m]).__name__ != '_LazyModule')"
             f" for m in {DEFERRED!r}}}))")
    out = subprocess.run([sys.executable, "-c", probe], check=True, capture_output=True, text=True)
    return __import__("json").loads(out.stdout.strip().splitlines()[-1])


def test_cli_import_defers_the_optional_path_modules():
    assert _loaded_after("import thermobear.app.cli, thermobear") == {m: False for m in DEFERRED}


def test_a_steady_run_does_not_load_them():
    code = ("import thermobear as tb\n"
            "s = tb.load_scene(tb.example_path('seed004_oil_jet_7210.toml'))\n"
            "tb.steady_state(s)")
    assert _loaded_after(code) == {m: False for m in DEFERRED}


def test_first_use_loads_the_module():
    code = ("import thermobear as tb\n"
            "from thermobear.coupled import sampling\n"
            "sampling.stats.qmc.LatinHypercube(d=2, rng=1).random(4)")
    assert _loaded_after(code)["scipy.stats"] is True


def test_a_loaded_module_is_returned_as_it_is():
    import json
    assert lazy_module("json") is json


def test_a_missing_module_fails_at_once():
    with pytest.raises(ModuleNotFoundError, match="no_such_module_xyz"):
        lazy_module("no_such_module_xyz")
