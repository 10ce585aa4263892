"""Fast paths of the coupled steady point give the numbers of the slow ones (no timing here).

* network build from a checked table: the values that read only the bearing (volumes, areas,
  lengths, materials) are shared between builds with the same bearing values; every build equals a
  fully checked build, a changed bearing (new object or mutated in place) gets its own values, and
  a change to one built network does not leak into the next;
* only expressions over the bearing are taken as static: scene, contacts and oil values are
  evaluated for every build.
"""
import dataclasses
import warnings

import numpy as np
import pytest

import thermobear as tb
from thermobear.errors import ExtrapolationWarning, InputError
from thermobear.coupled.solver import _network_spec_shared, _setup_thermal, choose_models, network_context
from thermobear.thermal import load_network
from thermobear.thermal.network import _leaves

warnings.simplefilter("ignore", ExtrapolationWarning)


def _scene(**kw):
    s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    return s.with_(**kw) if kw else s


def _same(fast, full, T):
    assert fast.nodes == full.nodes and fast.estimated == full.estimated
    np.testing.assert_array_equal(fast.fixed, full.fixed)
    np.testing.assert_array_equal(fast.T_fixed_K, full.T_fixed_K)
    np.testing.assert_array_equal(fast.C_J_K, full.C_J_K)
    np.testing.assert_array_equal(fast.conductances(T), full.conductances(T))
    for a, b in zip(fast.elements, full.elements):
        assert a.p.keys() == b.p.keys()
        for k in a.p:
            np.testing.assert_array_equal(a.p[k], b.p[k])


def test_leaves_of_static_and_operating_point_expressions():
    assert _leaves("pi / 4 * bearing.bore**2 * 0.03") == {("bearing", "bore")}
    assert _leaves("bearing.Z * pi * bearing.D**3 / 6") == {("bearing", "Z"), ("bearing", "D")}
    assert _leaves("450 / (bearing.Z * sin(bearing.alpha0))") == {("bearing", "Z"), ("bearing", "alpha0")}
    assert _leaves("bearing.ring_material") == {("bearing", "ring_material")}
    assert _leaves("0.03") == frozenset()
    # anything that reads the operating point (scene, contacts, oil) is evaluated at every build
    for expr in ("scene.T_ambient_C", "pi * scene.n_rpm / 30 * bearing.dm", "contacts.inner.a_m",
                 "oil.rho_15", "min(scene.oil_flow_m3_s, 1.0)", "not valid ("):
        assert _leaves(expr) is None


@pytest.mark.parametrize("kw", [{}, {"n_rpm": 8070.0}, {"Fr": 750.0, "n_rpm": 4800.0, "T_oil_in_C": 50.0}])
def test_cached_static_values_build_the_fully_checked_network(kw):
    s = _scene(**kw)
    models = choose_models(s)
    spec = _network_spec_shared(s)
    net, cs, _ = _setup_thermal(s, {**models, "load_model": ("jones_harris", "")} if kw.get("Fr") else models)
    ctx = network_context(s, {sd: {"a_m": np.asarray(cs.sides[sd]["a"], float),
                                   "b_m": np.asarray(cs.sides[sd]["b"], float)} for sd in ("inner", "outer")})
    full = load_network(spec, ctx)                       # every check, every value evaluated
    for _ in range(2):                                   # the second build takes the shared values
        fast = load_network(spec, ctx, _frozen=True)
        T = full.initial_T_K() + np.where(full.fixed, 0.0, np.linspace(3.0, 40.0, len(full.nodes)))
        _same(fast, full, T)


def test_another_bearing_gets_its_own_static_values():
    s = _scene()
    spec = _network_spec_shared(s)
    ctx = network_context(s)
    n1 = load_network(spec, ctx, _frozen=True)
    n1 = load_network(spec, ctx, _frozen=True)
    wide = dataclasses.replace(s.bearing, width=2.0 * s.bearing.width)
    ctx2 = {**ctx, "bearing": wide}
    n2 = load_network(spec, ctx2, _frozen=True)
    _same(n2, load_network(spec, ctx2), n2.initial_T_K() + 5.0)
    i = n1.index["inner_ring"]
    assert n2.C_J_K[i] == pytest.approx(2.0 * n1.C_J_K[i], rel=1e-12)
    # and the first bearing's values are still its own
    _same(load_network(spec, ctx, _frozen=True), load_network(spec, ctx), n1.initial_T_K() + 5.0)


def test_a_bearing_mutated_in_place_is_seen():
    # the shared values are keyed on the values the expressions read, not on the object
    class Mutable:
        pass

    s = _scene()
    b = Mutable()
    for k in ("D", "dm", "Z", "bore", "outer_diameter", "width", "alpha0", "ball_material", "ring_material",
              "Rx_i", "Rx_o", "Ry_i", "Ry_o", "E_prime"):
        setattr(b, k, getattr(s.bearing, k))
    spec = _network_spec_shared(s)
    ctx = {**network_context(s), "bearing": b}
    C0 = load_network(spec, ctx, _frozen=True).C_J_K.copy()
    load_network(spec, ctx, _frozen=True)
    b.bore = 0.9 * b.bore
    net = load_network(spec, ctx, _frozen=True)
    _same(net, load_network(spec, ctx), net.initial_T_K() + 5.0)
    assert net.C_J_K[net.index["shaft"]] == pytest.approx(0.81 * C0[net.index["shaft"]], rel=1e-12)
    # bad values are still refused on a trusted build
    b.width = -b.width
    with pytest.raises(InputError):
        load_network(spec, ctx, _frozen=True)


def test_a_changed_network_does_not_leak_into_the_next_build():
    s = _scene()
    spec = _network_spec_shared(s)
    ctx = network_context(s)
    a = load_network(spec, ctx, _frozen=True)
    b = load_network(spec, ctx, _frozen=True)
    e = next(e for e in b.elements if e.type == "shell")
    G0 = e.conductance(b.initial_T_K())
    e.p["L_m"] = 2.0 * e.p["L_m"]                        # the caller edits one built network
    assert e.conductance(b.initial_T_K()) == pytest.approx(2.0 * G0, rel=1e-14)
    c = load_network(spec, ctx, _frozen=True)
    k = b.elements.index(e)
    assert c.elements[k].p["L_m"] == a.elements[k].p["L_m"]
    assert c.elements[k].conductance(c.initial_T_K()) == pytest.approx(G0, rel=1e-14)


def test_operating_point_values_are_evaluated_per_build():
    s = _scene()
    spec = _network_spec_shared(s)
    nets = [load_network(spec, network_context(s.with_(n_rpm=n, T_ambient_C=T)), _frozen=True)
            for n, T in ((3200.0, 25.0), (6400.0, 35.0))]
    u = [next(e for e in n.elements if e.name == "balls_to_oil_air").p["u_m_s"] for n in nets]
    assert u[1] == pytest.approx(2.0 * u[0], rel=1e-12)
    amb = [n.T_fixed_K[n.index["ambient"]] for n in nets]
    assert amb[1] - amb[0] == pytest.approx(10.0, abs=1e-12)


def test_steady_point_unchanged_by_shared_values():
    # a point solved after another point (bearing values shared) equals the same point solved with
    # nothing shared
    from thermobear.coupled import solver
    from thermobear.thermal import network
    s = _scene(n_rpm=3200.32)
    solver.steady_state(_scene(n_rpm=5000.0))
    warm = solver.steady_state(s)
    network._STATIC.clear()
    cold = solver.steady_state(s)
    assert warm.P_W == cold.P_W
    assert warm.T_C == cold.T_C
