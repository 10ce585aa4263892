"""A grease run above its stated upper operating temperature (grease_T_max_C of its data file) is a named
OutsideValidity warning of the answer (thermobear.coupled.limits.grease_limit); an oil has no such limit."""
from __future__ import annotations

import pytest

import thermobear as tb
from thermobear.coupled.limits import grease_limit


def _grease_scene(T_ambient_C):
    return tb.load_scene(tb.example_path("block_6208_grease.toml")).with_(T_ambient_C=T_ambient_C)


def test_the_limit_is_the_grease_data_files():
    s = _grease_scene(25.0)
    assert grease_limit(s) == pytest.approx(float(s.lubricant.table["grease_T_max_C"]))
    assert grease_limit(tb.load_scene(tb.example_path("oil_bath_6208.toml"))) is None


def test_a_grease_past_its_limit_is_warned_and_within_it_is_not():
    cool = tb.steady_state(_grease_scene(25.0))
    assert not any(w.quantity == "grease_T" for w in cool.warnings)
    T_max = grease_limit(_grease_scene(25.0))
    hot_scene = _grease_scene(T_max + 5.0)                       # a machine in a room above the limit
    with pytest.warns(tb.OutsideValidity, match="above the grease's upper operating temperature"):
        hot = tb.steady_state(hot_scene)
    w = [w for w in hot.warnings if w.quantity == "grease_T"]
    assert len(w) == 1 and w[0].value > T_max and w[0].field == "lubricant.name"
