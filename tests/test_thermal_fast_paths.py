"""The thermal half of a coupled steady point: its fast paths give the numbers of the plain ones.

* a network rebuilt from the shared (frozen) table — static values, per-entry templates and
  once-per-build expressions — equals a fresh, fully checked build of the same table, for every
  changed scene value (speed, oil flow, ambient, parameter overrides, bearing): nothing is served stale;
* the graph built on first access holds the nodes and elements of the network;
* the Newton loss slopes from two temperature states (x, x + h) equal the forward differences of
  one temperature at a time;
* the free block of ∂(A T)/∂T, the direct LAPACK solve and eigenvalues equal numpy's.
"""
import copy
import dataclasses
import warnings

import numpy as np
import pytest

import thermobear as tb
from thermobear.errors import ExtrapolationWarning, InputError
from thermobear.losses.local import evaluate_losses
from thermobear.coupled.solver import (_losses_and_slopes, _network_spec_shared, _setup_thermal, choose_models,
                               network_context)
from thermobear.thermal.network import evaluate, load_network
from thermobear.thermal.solve import _dense_solve, _max_real_eigenvalue, _plan

warnings.simplefilter("ignore", ExtrapolationWarning)


def _scene(**kw):
    s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    return s.with_(**kw) if kw else s


def _fresh(scene, cs):
    """The scene's network built from a private copy of its table, every check run (no sharing)."""
    ctx = {s: {"a_m": np.asarray(cs.sides[s]["a"], float), "b_m": np.asarray(cs.sides[s]["b"], float)}
           for s in ("inner", "outer")}
    return load_network(copy.deepcopy(_network_spec_shared(scene)), network_context(scene, ctx))


def _same_network(a, b):
    assert a.nodes == b.nodes and a.name == b.name
    np.testing.assert_array_equal(a.fixed, b.fixed)
    np.testing.assert_array_equal(a.T_fixed_K, b.T_fixed_K)
    np.testing.assert_array_equal(a.C_J_K, b.C_J_K)
    assert [e.name for e in a.elements] == [e.name for e in b.elements]
    for ea, eb in zip(a.elements, b.elements):
        assert type(ea) is type(eb) and (ea.i, ea.j) == (eb.i, eb.j)
        assert list(ea.p) == list(eb.p), ea.name                         # same keys, table order
        for k in ea.p:
            va, vb = ea.p[k], eb.p[k]
            if isinstance(va, np.ndarray):
                np.testing.assert_array_equal(va, vb)
            else:
                assert va == vb, (ea.name, k, va, vb)
    T = a.initial_T_K() + np.where(a.fixed, 0.0, 7.0)
    np.testing.assert_array_equal(a.conductances(T), b.conductances(T))


@pytest.mark.parametrize("kw", [
    {}, {"n_rpm": 3217.5}, {"n_rpm": 8070.0}, {"oil_flow_L_h": 4.0}, {"T_ambient_C": 31.0},
    {"T_oil_in_C": 45.0}, {"Fr": 900.0},
    {"network_parameters": {"oil_stream.beta": 0.55}},                 # a number of the table
    {"network_parameters": {"housing_to_frame.length_m": 0.08}},
    {"network_parameters": {"inner_ring_radial.L_m": 0.015}},          # an expression replaced by a number
    {"T_fixed_C": {"support_block": 33.0}},
    {"bearing": "wider"},                                              # other bearing values: other static values
])
def test_a_shared_table_builds_the_network_a_fresh_table_builds(kw):
    base = _scene()
    if kw.get("bearing") == "wider":
        kw = {"bearing": dataclasses.replace(base.bearing, width=0.022)}
    for n in (3000.0, 3100.0):                  # earlier builds of the shared table (templates filled)
        s0 = base.with_(n_rpm=n)
        _setup_thermal(s0, choose_models(s0))
    s = base.with_(**kw) if kw else base
    net, cs, _ = _setup_thermal(s, choose_models(s))
    _same_network(net, _fresh(s, cs))
    # and again, now that this scene's own values were built once
    net2, cs2, _ = _setup_thermal(s, choose_models(s))
    _same_network(net2, _fresh(s, cs2))


def test_the_speed_reaches_the_convection_elements_of_every_build():
    got = {}
    for n in (2000.0, 4000.0, 2000.0):
        s = _scene(n_rpm=n)
        net = _setup_thermal(s, choose_models(s))[0]
        u = {e.name: e.p["u_m_s"] for e in net.elements if "u_m_s" in e.p}
        assert len(u) == 3
        got.setdefault(n, []).append(u)
    assert got[2000.0][0] == got[2000.0][1]
    for name in got[2000.0][0]:
        assert got[4000.0][0][name] == pytest.approx(2.0 * got[2000.0][0][name], rel=1e-12)


def test_a_failing_value_still_names_its_field_once_values_are_shared():
    s = _scene()
    net, cs, _ = _setup_thermal(s, choose_models(s))           # the shared table is trusted from now on
    ctx = network_context(s, {k: {"a_m": cs.sides[k]["a"], "b_m": cs.sides[k]["b"]} for k in ("inner", "outer")})
    spec = _network_spec_shared(s)
    ctx["scene"] = dict(ctx["scene"], T_ambient_C=-300.0)
    with pytest.raises(InputError, match=r"nodes\.ambient\.T_C"):
        load_network(spec, ctx, _frozen=True)
    ctx["scene"] = dict(ctx["scene"], T_ambient_C=25.0, oil_flow_m3_s=-1e-6)
    with pytest.raises(InputError, match=r"elements\[inner_race_to_oil_air\]\.oil_fraction.*is not a number"):
        load_network(spec, ctx, _frozen=True)


def test_the_graph_is_built_on_first_access():
    s = _scene()
    net = _setup_thermal(s, choose_models(s))[0]
    assert "graph" not in net.__dict__
    g = net.graph
    assert list(g.nodes) == net.nodes and g.number_of_edges() == len(net.elements)
    assert g.nodes["ambient"] == {"fixed": True, "T_C": pytest.approx(s.T_ambient_C, abs=1e-12)}
    assert g.nodes["housing"]["C_J_K"] == net.C_J_K[net.index["housing"]]
    edge = g.edges["oil_air", "oil_inlet", "oil_stream"]
    assert edge["type"] == "advection" and edge["advective"] and edge["beta"] == 0.4
    assert g.edges["inner_race", "inner_ring", "inner_ring_radial"]["material"] == s.bearing.ring_material.name
    assert net.graph is g


def test_evaluate_without_floating_point_guard_for_min_max_abs():
    assert evaluate("min(2.0, max(-1.0, abs(-0.5)))") == 0.5
    assert evaluate("pi / 4") == np.pi / 4
    with pytest.raises(InputError, match="cannot be evaluated"):
        evaluate("sqrt(0 - 1)")
    with pytest.raises(InputError, match="cannot be evaluated"):
        evaluate("max(1.0, x)", {"x": np.ones(2)})


@pytest.mark.parametrize("kw", [{}, {"n_rpm": 8070.0}])
def test_loss_slopes_from_two_states_equal_one_temperature_at_a_time(kw):
    s = _scene(**kw)
    models = choose_models(s)
    cs = _setup_thermal(s, models)[1]
    x = np.array([330.0, 321.5, 309.25])
    h = 0.05
    P, dP = _losses_and_slopes(s, models, cs, x, h)
    X = x[:, None] + h * np.eye(3)[:, [0, 0, 1, 2]] * np.array([0, 1, 1, 1])     # x, then x + h e_k
    Ti, To, Toil = X - 273.15                                                   # 4 states of the one point
    r4 = evaluate_losses(cs, s.lubricant, Toil, T_inner_C=Ti, T_outer_C=To, T_oil_C=Toil, oil_flow_m3_s=s.oil_flow,
                         Rq_ball=s.Rq_ball, Rq_ring=s.Rq_ring, mu_boundary=s.mu_boundary,
                         mu_full_film=s.mu_full_film)
    P4 = np.vstack([r4.contact_W["inner"], r4.contact_W["outer"], r4.breakdown_W["drag"]])
    np.testing.assert_allclose(P, P4[:, 0], rtol=1e-13)
    np.testing.assert_allclose(dP, (P4[:, 1:] - P4[:, [0]]) / h, rtol=1e-9, atol=1e-12)
    assert np.all(np.diag(dP) < 0)              # hotter: thinner oil, less loss


def test_free_block_of_dAT_and_direct_lapack_equal_numpy():
    s = _scene()
    net = _setup_thermal(s, choose_models(s))[0]
    plan = _plan(net)
    T = net.initial_T_K() + np.where(net.fixed, 0.0, np.linspace(3.0, 40.0, net.fixed.size))
    _, dG = plan.dconductances(T, nodes=plan.free)
    free = ~net.fixed
    np.testing.assert_array_equal(plan.dAT_free(T, dG), plan.dAT(T, dG)[np.ix_(free, free)])
    Aff, _ = plan.blocks(plan.conductances(T))
    b = np.arange(1.0, Aff.shape[0] + 1.0)
    np.testing.assert_allclose(_dense_solve(Aff, b), np.linalg.solve(Aff, b), rtol=1e-13)
    assert _dense_solve(np.zeros((3, 3)), np.ones(3)) is None
    M = np.array([[0.2, 0.1, 0.0], [-0.3, 0.1, 0.2], [0.0, 0.4, -0.5]])
    assert _max_real_eigenvalue(M) == pytest.approx(float(np.max(np.linalg.eigvals(M).real)), rel=1e-13)
    assert np.isnan(_max_real_eigenvalue(np.full((3, 3), np.nan)))
