"""No step where the model switches: fine sweeps across every switch of the model choice.

Each switch (film ↔ dry load law, high-speed ↔ low-speed form) is blended across a band of its
criterion (thermobear.models.BLEND_BANDS); a sweep across it must show no step: the change between
neighbouring points may differ from the one before by at most 1 % of the power and 0.5 K (a step
of s shows as a jump of s in these differences; before the blend they reached 3.9–5.0 % and
1.3–1.9 K on the same sweeps).  Drag (grease) and the regime boundaries of the rolling force are
continuous by construction; their sweeps are checked the same way.
"""
from __future__ import annotations

import warnings

import numpy as np
import pytest

import thermobear as tb
from thermobear.app.sweep import run_sweep
from thermobear.models import BLEND_BANDS, plan_many


@pytest.fixture(scope="module")
def s004():
    warnings.simplefilter("ignore", tb.OutsideValidity)
    return tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))


def _jumps(y):
    """Largest change of the increment between neighbouring points (second difference)."""
    y = np.asarray(y, float)
    return np.abs(y[2:] - 2.0 * y[1:-1] + y[:-2])


def _check(states, n_blended_min=1):
    assert all(isinstance(st, tb.SteadyState) for st in states), [type(st).__name__ for st in states]
    P = np.array([st.P_W for st in states])
    T = np.array([st.T_C["inner_ring"] for st in states])
    assert np.max(_jumps(P) / P[1:-1]) <= 0.01, np.max(_jumps(P) / P[1:-1])
    assert np.max(_jumps(T)) <= 0.5, np.max(_jumps(T))
    blended = [st for st in states if "blend" in st.models_used]
    assert len(blended) >= n_blended_min                       # the sweep does cross a switch band
    for st in blended:                                          # the reason states the switch's size here
        assert "differ here by" in st.models_used["blend"][1]
    return blended


@pytest.mark.parametrize("what,points", [
    ("axial load across the film/dry switch (5500 rpm, Fr 325 N)", [dict(Fa=f, n_rpm=5500.0)
                                                                   for f in np.arange(200.0, 601.0, 10.0)]),
    ("speed across the high-speed switch (Fa 225 N)", [dict(Fa=225.0, n_rpm=n) for n in np.arange(2000.0, 4501.0, 50.0)]),
    ("radial load across both switches (4800 rpm)", [dict(Fr=f, n_rpm=4800.0) for f in np.arange(200.0, 1301.0, 10.0)]),
])
def test_a_fine_sweep_across_a_switch_has_no_step(s004, what, points):
    _check(tb.steady_states([s004.with_(**p) for p in points]))


def test_the_sweeps_cross_the_bands_they_test(s004):
    """The weights of the swept points cover the whole band (0 → 1) of each switch."""
    def weights(points, key, value):
        return [sum(a.weight for a in p if a.models[key][0] == value) for p in plan_many([s004.with_(**q)
                                                                                          for q in points])]
    film = weights([dict(Fa=f, n_rpm=5500.0) for f in np.arange(200.0, 601.0, 10.0)], "load_model", "film")
    assert min(film) == 0.0 and max(film) == 1.0
    hs = weights([dict(Fa=225.0, n_rpm=n) for n in np.arange(2000.0, 4501.0, 50.0)], "high_speed", "yes")
    assert min(hs) == 0.0 and max(hs) == 1.0
    hs = weights([dict(Fr=f, n_rpm=4800.0) for f in np.arange(200.0, 1301.0, 10.0)], "high_speed", "yes")
    film = weights([dict(Fr=f, n_rpm=4800.0) for f in np.arange(200.0, 1301.0, 10.0)], "load_model", "film")
    assert min(hs) == 0.0 and max(hs) == 1.0 and min(film) == 0.0 and max(film) == 1.0
    assert BLEND_BANDS["high_speed"][0] < 0.05 < BLEND_BANDS["high_speed"][1]


def test_prescribed_temperature_sweep_across_the_film_switch_has_no_step(s004):
    rows = run_sweep(s004.with_(T_C=50.0), {"Fa": list(np.arange(200.0, 601.0, 5.0)), "n_rpm": [5500.0]},
                     processes=1)
    P = np.array([r["P_W"] for r in rows])
    assert np.max(_jumps(P) / P[1:-1]) <= 0.01
    assert any(r["reason"].startswith("blend of") for r in rows)


def test_grease_drag_has_no_switch_in_speed():
    """Grease: the balls' drag in air is kept at every speed (∝ ω²: negligible below n dm ≈ 1e5)."""
    s = tb.load_scene(tb.example_path("seed002_grease_thrust_51107.toml"))
    dm_mm = s.bearing.dm * 1e3
    n = np.linspace(0.5e5, 1.5e5, 21) / dm_mm
    states = tb.steady_states([s.with_(n_rpm=x) for x in n])
    assert all(st.models_used["drag"][0] is True for st in states)
    P = np.array([st.P_W for st in states])
    assert np.max(_jumps(P) / P[1:-1]) <= 0.01


def test_rolling_regime_boundaries_have_no_step(s004):
    """Prescribed temperature, speed sweep from IVR-dominated to EHL contacts: the rolling force is
    weighted smoothly across the regime boundaries (losses.rolling), so the power has no step (on
    log scales, where a power law is a line: a step of s shows as a jump of ≈ s in ln P)."""
    sc = s004.with_(T_C=60.0, Fr=0.0)
    r = tb.scene_losses(sc, T_C=60.0, n_rpm=np.geomspace(50.0, 8000.0, 200))
    assert len(set(np.ravel(r.contacts["inner"]["regime"]))) >= 2          # the sweep crosses regimes
    assert np.max(_jumps(np.log(np.asarray(r.P_W, float)))) <= 0.01
