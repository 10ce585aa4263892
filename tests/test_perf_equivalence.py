"""The fast paths give the numbers of independent, slower computations (no timing here).

* coupled steady state: full Newton on the node temperatures (with the conductances' temperature
  dependence) = Anderson mixing on the three coupled temperatures, to 1e-6 K;
* network assembly from the cached index plan = the element-by-element COO assembly;
  ∂(A(T)T)/∂T of the plan = finite differences of the heat balance;
* transient output pass evaluated in one batch = the losses evaluated point by point;
* cached expression parsing does not leak one context's values into another.
"""
import warnings

import numpy as np
import pytest
import scipy.sparse as sp

import thermobear as tb
from thermobear.errors import ExtrapolationWarning
from thermobear.coupled.solver import _setup_thermal, _sources, choose_models, steady_state, transient
from thermobear.thermal.network import evaluate
from thermobear.thermal.solve import _plan, assemble

warnings.simplefilter("ignore", ExtrapolationWarning)


def _scene(name="seed004_oil_jet_7210.toml", **kw):
    s = tb.load_scene(tb.example_path(name))
    return s.with_(**kw) if kw else s


@pytest.mark.parametrize("name,kw", [("seed004_oil_jet_7210.toml", {}),
                                     ("seed004_oil_jet_7210.toml", {"n_rpm": 8070.0, "Fr": 750.0,
                                                                    "models": {"load_model": "jones_harris"}}),
                                     ("seed002_grease_thrust_51107.toml", {})])
def test_newton_steady_equals_anderson(name, kw):
    s = _scene(name, **kw)
    nw = steady_state(s)
    an = steady_state(s, method="anderson", tol_K=1e-9)
    assert "newton" in nw.models_used["thermal"][1]
    for node, T in an.T_C.items():
        assert nw.T_C[node] == pytest.approx(T, abs=1e-6)
    assert nw.P_W == pytest.approx(an.P_W, rel=1e-7)
    # the conductances' temperature dependence is in the Jacobian: quadratic convergence
    assert nw.iterations <= 7
    res = [h["residual_K"] for h in nw.history]
    assert res[-1] <= 1e-6 and res[-2] <= 1e-2


def _network():
    s = _scene()
    net, cs, roles = _setup_thermal(s, choose_models(s))
    return net, roles


def test_plan_assembly_equals_coo_assembly():
    net, _ = _network()
    rng = np.random.default_rng(3)
    for _ in range(3):
        T = net.initial_T_K() + np.where(net.fixed, 0.0, rng.uniform(0.0, 60.0, len(net.nodes)))
        G = net.conductances(T)                               # element by element
        i = np.array([e.i for e in net.elements])
        j = np.array([e.j for e in net.elements])
        adv = np.array([e.advective for e in net.elements])
        sym = ~adv
        rows = np.concatenate([i[sym], j[sym], i[sym], j[sym], j[adv], j[adv]])
        cols = np.concatenate([i[sym], j[sym], j[sym], i[sym], j[adv], i[adv]])
        vals = np.concatenate([G[sym], G[sym], -G[sym], -G[sym], G[adv], -G[adv]])
        A_ref = sp.coo_matrix((vals, (rows, cols)), shape=(len(net.nodes),) * 2).toarray()
        A, G_plan = assemble(net, T)
        np.testing.assert_allclose(G_plan, G, rtol=1e-14)
        np.testing.assert_allclose(A.toarray(), A_ref, rtol=1e-13, atol=1e-13 * np.abs(A_ref).max())
        Aff, Afb = _plan(net).blocks(G)
        free, fixed = ~net.fixed, net.fixed
        np.testing.assert_allclose(Aff, A_ref[np.ix_(free, free)], rtol=1e-13, atol=1e-13)
        np.testing.assert_allclose(Afb, A_ref[np.ix_(free, fixed)], rtol=1e-13, atol=1e-13)
    # a replaced parameter rebuilds the plan (no stale conductance)
    e = next(e for e in net.elements if e.type == "interface")
    G0 = assemble(net, T)[1][net.elements.index(e)]
    e.p["h_W_m2K"] = 2.0 * e.p["h_W_m2K"]
    assert assemble(net, T)[1][net.elements.index(e)] == pytest.approx(2.0 * G0, rel=1e-14)


def test_plan_heat_balance_jacobian_matches_finite_differences():
    net, _ = _network()
    plan = _plan(net)
    T = net.initial_T_K() + np.where(net.fixed, 0.0, np.linspace(5.0, 40.0, len(net.nodes)))

    def flux(T):                                   # A(T) T: heat leaving each node [W]
        return plan.dense(net.conductances(T)) @ T

    G, dG = plan.dconductances(T)
    J = plan.dense(G) + plan.dAT(T, dG)
    free = np.flatnonzero(~net.fixed)
    for m in free:
        h = 1e-3
        Tp, Tm = T.copy(), T.copy()
        Tp[m] += h
        Tm[m] -= h
        col = (flux(Tp) - flux(Tm)) / (2 * h)
        np.testing.assert_allclose(J[free, m], col[free], rtol=1e-4, atol=1e-6 * np.abs(J).max())
    # the temperature dependence is not negligible here (else the test could not fail)
    assert np.abs(plan.dAT(T, dG)).max() > 1e-3


def test_transient_batched_output_equals_pointwise_losses():
    s = _scene()
    tr = transient(s, 1800.0, t_eval=[0.0, 60.0, 600.0, 1800.0])
    models = choose_models(s)
    net, cs, roles = _setup_thermal(s, models)
    for k in range(tr.t_s.size):
        T_C = {n: float(v[k]) for n, v in tr.T_C.items()}
        src, r = _sources(s, models, cs, roles, T_C)
        assert tr.P_W[k] == pytest.approx(float(r.P_W), rel=1e-12)
        for fam, v in r.breakdown_W.items():
            assert tr.breakdown_W[fam][k] == pytest.approx(float(v), rel=1e-12, abs=1e-15)
    assert tr.P_W[-1] != pytest.approx(tr.P_W[0], rel=1e-3)      # the states differ


def test_cached_parse_keeps_contexts_apart():
    expr = "bearing.bore / 2 + 1e-3"
    assert evaluate(expr, {"bearing": {"bore": 0.05}}) == pytest.approx(0.026)
    assert evaluate(expr, {"bearing": {"bore": 0.03}}) == pytest.approx(0.016)


# --------------------------------------------------------------------------- cached look-ups, fast paths
def test_material_cache_returns_the_same_values_and_errors():
    from thermobear.contact.materials import material, material_names
    m = material("aisi-52100")
    assert material("aisi-52100") is m and m.E == 210e9
    assert "aisi-52100" in material_names()
    with pytest.raises(tb.errors.InputError, match="known: .*aisi-52100"):
        material("unobtainium")


def test_compiled_expressions_give_the_tree_walkers_values_and_messages():
    import ast

    from thermobear.thermal.network import _Evaluator
    ctx = {"bearing": {"bore": 0.05, "D": 0.0127}, "scene": {"n_rpm": 3200.0}, "x": np.array([1.0, 2.0])}
    exprs = ["bearing.bore / 2 + sqrt(4) * 1e-3", "-pi * bearing.D**2 / 4", "max(scene.n_rpm, 1.0) * 2",
             "x * 2", "bearing.nope", "nope + 1", "1 / 0", "log(-1.0)", "bearing._x", "'a' + 1",
             "(lambda: 1)()", "bearing.bore.real", "scene", "[1, 2]", "sqrt(4, k=1)", "True"]
    for e in exprs:
        try:
            want = ("ok", _Evaluator(ctx, "f", e).num(ast.parse(e, mode="eval").body))
        except tb.errors.InputError as exc:
            want = ("err", str(exc))
        try:
            got = ("ok", evaluate(e, ctx, "f"))
        except tb.errors.InputError as exc:
            got = ("err", str(exc))
        assert got[0] == want[0], e
        if got[0] == "ok":
            np.testing.assert_allclose(got[1], want[1], rtol=0, atol=0)
        else:
            assert got[1] == want[1]


def test_dconductances_restricted_to_free_nodes():
    net, _ = _network()
    plan = _plan(net)
    T = net.initial_T_K() + np.where(net.fixed, 0.0, np.linspace(5.0, 40.0, len(net.nodes)))
    G, dG = plan.dconductances(T)
    G2, dG2 = plan.dconductances(T, nodes=plan.free)
    assert np.array_equal(G, G2)
    assert dG2 == [d for d in dG if d[1] in set(plan.free.tolist())]
    assert len(dG2) < len(dG)                       # some elements depend on fixed nodes (ambient)


def test_element_fast_paths_equal_the_public_functions():
    from thermobear.thermal.elements import (advection_conductance, air_properties, h_harris,
                                             h_natural_horizontal_cylinder, h_radiation, oil_air_properties,
                                             planar_conductance, shell_conductance)
    net, _ = _network()
    oil = _scene().lubricant
    T = net.initial_T_K() + np.where(net.fixed, 0.0, np.linspace(5.0, 60.0, len(net.nodes)))
    seen = set()
    for e in net.elements:
        if not e.T_dependent:
            continue
        Ts, Tf = float(T[e.i]), float(T[e.j])
        p = e.p
        if e.type == "convection" and p["correlation"] in ("harris", "flat_plate_laminar"):
            Tc = Tf - 273.15
            pr = oil_air_properties(np.array(p["oil_fraction"]), np.array(oil.rho(Tc)), np.array(oil.nu(Tc)),
                                    np.array(oil.k_th(Tc)), np.array(oil.cp(Tc)), np.array(Tf))     # array path
            ref = h_harris(pr["k"], pr["Pr"], p["u_m_s"], pr["nu"], p["x_m"], p["correlation"]) * p["A_m2"]
        elif e.type == "convection":
            ref = h_natural_horizontal_cylinder(np.array(Ts), np.array(Tf), np.array(p["D_m"])) * p["A_m2"]
        elif e.type == "radiation":
            ref = h_radiation(np.array(p["emissivity"]), np.array(Ts), np.array(Tf)) * p["A_m2"]
        else:
            Tc = Ts - 273.15
            ref = advection_conductance(np.array(oil.rho(Tc)), np.array(oil.cp(Tc)), p["Q_m3_s"], p["beta"])
        seen.add(e.type + p.get("correlation", ""))
        for G in (e.conductance(T), e._conductance_shared(T, {}), e._conductance_shared(T.tolist(), {})):
            assert G == pytest.approx(ref, rel=1e-14, abs=0.0), e.name
    assert seen == {"convectionflat_plate_laminar", "convectionnatural_horizontal_cylinder", "radiation", "advection"}
    a = air_properties(np.array(330.0))
    assert oil_air_properties(0.0, 860.0, 20.0, 0.13, 1950.0, 330.0)["k"] == pytest.approx(float(a["k"]), rel=1e-15)
    assert shell_conductance(42.7, 0.02, 0.025, 0.0286) == pytest.approx(
        float(shell_conductance(np.array(42.7), 0.02, 0.025, 0.0286)), rel=1e-15)
    assert planar_conductance(40.0, 1e-3, 0.1) == float(planar_conductance(np.array(40.0), 1e-3, 0.1))
    with pytest.raises(tb.errors.InputError):                         # the scalar paths keep the checks
        shell_conductance(42.7, 0.02, 0.03, 0.025)
    with pytest.raises(tb.errors.InputError):
        oil_air_properties(1.5, 860.0, 20.0, 0.13, 1950.0, 330.0)
