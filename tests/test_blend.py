"""Blending answers across a model switch (thermobear.coupled.blend): every number the alternatives share
is the weighted sum of theirs, the blend of balanced states is balanced, a failed alternative leaves the
others renormalised with a warning."""
from __future__ import annotations

import warnings

import numpy as np
import pytest

import thermobear as tb
from thermobear.coupled.blend import StackedBlend, blend_states
from thermobear.errors import NoConvergence, OutsideValidity
from thermobear.coupled.steady import SteadyState


@pytest.fixture(scope="module")
def two():
    """Seed 004's point solved with the low-speed and the high-speed form of the dry load law."""
    warnings.simplefilter("ignore", OutsideValidity)
    s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    return [tb.steady_state(s.with_(models={"load_model": "jones_harris", "high_speed": hs})) for hs in (False, True)]


def test_blend_weights_every_shared_number(two):
    a, b = two
    st = blend_states([(0.25, a), (0.75, b)], SteadyState)
    assert st.P_W == pytest.approx(0.25 * a.P_W + 0.75 * b.P_W, rel=1e-14)
    assert st.torque_Nm == pytest.approx(0.25 * a.torque_Nm + 0.75 * b.torque_Nm, rel=1e-14)
    for n in a.T_C:
        assert st.T_C[n] == pytest.approx(0.25 * a.T_C[n] + 0.75 * b.T_C[n], rel=1e-14)
    for k in set(a.breakdown_W) | set(b.breakdown_W):                 # a key one lacks counts 0
        assert st.breakdown_W[k] == pytest.approx(0.25 * a.breakdown_W.get(k, 0.0) + 0.75 * b.breakdown_W.get(k, 0.0),
                                                  rel=1e-14, abs=1e-300)
    for e in a.heat_flows_W:
        assert st.heat_flows_W[e] == pytest.approx(0.25 * a.heat_flows_W[e] + 0.75 * b.heat_flows_W[e], rel=1e-12,
                                                   abs=1e-12)
    # conservation: the blend of balanced states is balanced; its sources and its outflows carry its power
    assert abs(st.energy_balance_W) <= 1e-9 * st.P_W
    assert sum(sum(q.values()) for q in st.heat_sources_W.values()) == pytest.approx(st.P_W, rel=1e-9)
    assert sum(st.heat_out_W.values()) == pytest.approx(st.P_W, rel=1e-9)
    # per-contact data from the alternative of the largest weight; the weights said in models_used
    assert st.batch_losses is b.batch_losses and st.row == b.row
    assert "0.250 ×" in st.models_used["blend"][0] and "0.750 ×" in st.models_used["blend"][0]


def test_blend_limits(two):
    a, b = two
    same = blend_states([(0.5, a), (0.5, a)], SteadyState)          # the blend of one answer is that answer
    assert same.P_W == pytest.approx(a.P_W, rel=1e-15) and same.T_C == pytest.approx(a.T_C, rel=1e-15)
    fail = NoConvergence("did not converge", iterations=3, residual=1.0)
    alone = blend_states([(0.4, a), (0.6, fail)], SteadyState)      # the other carries the answer, with a warning
    assert alone.P_W == a.P_W and alone.T_C == a.T_C
    assert any("model blend" in str(w) for w in alone.warnings)
    assert blend_states([(0.4, fail), (0.6, fail)], SteadyState) is fail


def test_stacked_blend_interpolates_the_film_rows_in_the_film_temperature():
    """A film-load-model alternative solved at two film temperatures: its rows weighted (1 − θ) and θ,
    θ = (T_f − T_lo)/(T_hi − T_lo) with T_f = ½ (x_inner + x_outer); the other rows keep their weight."""
    class Rows:                 # parts of K = 3 rows: row k gives k + 1 W on each part
        diagonal = True

        def parts(self, x):
            return np.broadcast_to(np.arange(1.0, 4.0)[:, None], np.shape(x)[:-1] + (2,)).copy()

    lower, upper = np.array([False, True, False]), np.array([False, False, True])
    sb = StackedBlend(Rows(), [0.4, 0.6, 0.6], film=(lower, upper, 40.0, 43.0))
    for T_f, th in ((40.0, 0.0), (41.5, 0.5), (43.0, 1.0), (43.3, 1.1)):
        x = np.array([[T_f - 1.0, T_f + 1.0, 30.0]])
        assert sb.parts(x)[0] == pytest.approx([0.4 + 0.6 * ((1 - th) * 2 + th * 3)] * 2)
    assert not sb.diagonal                                     # θ reads both contact temperatures
