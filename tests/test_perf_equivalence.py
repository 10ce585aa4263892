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


# --------------------------------------------------------------------------- fused loss kernel
from thermobear.lubrication.film import film_thickness, lubrication_regime                    # noqa: E402
from thermobear.losses.rolling import rolling_force                              # noqa: E402
from thermobear.losses.sliding import mixed_friction_ianus                       # noqa: E402
from thermobear.losses.local import (_contact_powers, _repeat_contacts, _rolling_auto_smooth,  # noqa: E402
                               evaluate_losses, prepare_contacts)


def _contacts_spread():
    """7210 contacts over loads (balls outside the load zone: Q_i = 0), speeds (down to 0) and a
    temperature spread that crosses the IVR / PVR / EHL boundaries."""
    s = _scene()
    n = np.array([0.0, 30.0, 400.0, 3200.0, 8070.0, 12000.0])
    cs = prepare_contacts(s.bearing, Fa=np.array([450.0, 60.0, 450.0, 100.0, 900.0, 300.0]),
                          Fr=np.array([325.0, 750.0, 0.0, 900.0, 25.0, 1500.0]), n_rpm=n)
    return s, cs


def _public_path(cs, oil, Ts, sigma, mu_e=0.05, mu_a=0.11):
    """The per-contact quantities computed with the checked public functions, side by side."""
    Ep = cs.brg.E_prime
    out = {}
    for side in ("inner", "outer"):
        sd = cs.sides[side]
        eta, alpha_p = oil.eta(Ts[side]), oil.alpha_p_at(Ts[side])
        args = (sd["Q"], sd["Rx"], sd["Ry"], sd["u"], eta, alpha_p, Ep)
        h_min = film_thickness(*args, kind="min")
        reg = lubrication_regime(*args)
        F = _rolling_auto_smooth(sd["Q"], sd["Rx"], sd["Ry"], sd["u"], eta, Ep, alpha_p, sd["a"], sd["b"], reg)
        out[side] = dict(h_min=h_min, h_c=film_thickness(*args, kind="central"), regime=reg.code, M=reg.M,
                         L=reg.L, mu=mixed_friction_ianus(h_min / sigma, mu_e, mu_a),
                         F_R=np.where(sd["Q"] > 0, F, 0.0))
    return out


@pytest.mark.filterwarnings("ignore::thermobear.errors.ExtrapolationWarning")
@pytest.mark.parametrize("per_ball", [False, True])
def test_fused_loss_kernel_equals_public_functions(per_ball):
    s, cs = _contacts_spread()
    oil = s.lubricant
    shape = cs.batch + (cs.brg.Z,)
    rng = np.random.default_rng(11)
    if per_ball:
        Ti, To = rng.uniform(20.0, 140.0, shape), rng.uniform(20.0, 140.0, shape)
    else:
        Ti, To = np.linspace(20.0, 140.0, cs.batch[0]), np.linspace(140.0, 25.0, cs.batch[0])
    r = evaluate_losses(cs, oil, 60.0, T_inner_C=Ti, T_outer_C=To, T_oil_C=45.0, oil_flow_m3_s=s.oil_flow)
    sigma = np.hypot(0.05e-6, 0.1e-6)
    Ts = {k: np.broadcast_to(np.asarray(v)[..., None] if not per_ball else v, shape)
          for k, v in (("inner", Ti), ("outer", To))}
    ref = _public_path(cs, oil, Ts, sigma)
    codes = set()
    for side in ("inner", "outer"):
        got, exp = r.contacts[side], ref[side]
        np.testing.assert_array_equal(got["regime"], exp["regime"])
        codes |= set(np.unique(exp["regime"]).tolist())
        for key in ("h_min", "h_c", "M", "L", "mu", "F_R"):
            np.testing.assert_allclose(got[key], exp[key], rtol=1e-12, atol=0.0, err_msg=f"{side} {key}")
        assert np.all(got["eta"] == oil.eta(Ts[side]))
    # the spread reaches the regimes whose formulas the kernel blends, and the limits u = 0, Q = 0
    assert {"IVR", "PVR", "EHL"} <= codes
    assert np.any(cs.sides["inner"]["u"] == 0) and np.any(cs.sides["inner"]["Q"] == 0)
    assert np.all(r.contacts["inner"]["F_R"][0] == 0) and np.all(r.contacts["inner"]["h_min"][0] == 0)


@pytest.mark.filterwarnings("ignore::thermobear.errors.ExtrapolationWarning")
@pytest.mark.parametrize("model", ["auto_sharp", "houpert_ivr", "biboulet_pvr", "houpert_ehl", "biboulet_transition"])
def test_named_rolling_models_use_the_public_functions(model):
    s, cs = _contacts_spread()
    r = evaluate_losses(cs, s.lubricant, 70.0, oil_flow_m3_s=s.oil_flow, rolling_model=model)
    sd, c = cs.sides["outer"], r.contacts["outer"]
    kw = dict(regime=c["regime"]) if model == "auto_sharp" else {}
    F = rolling_force(sd["Q"], sd["Rx"], sd["Ry"], sd["u"], c["eta"], cs.brg.E_prime,
                      model="auto" if model == "auto_sharp" else model, alpha_p=s.lubricant.alpha_p_at(70.0),
                      a=sd["a"], b=sd["b"], **kw)
    np.testing.assert_allclose(c["F_R"], np.where(sd["Q"] > 0, F, 0.0), rtol=1e-13, atol=0.0)


@pytest.mark.filterwarnings("ignore::thermobear.errors.ExtrapolationWarning")
def test_contact_powers_and_repeated_contacts_equal_the_full_path():
    s = _scene(n_rpm=6500.0, Fr=750.0)
    models = choose_models(s)
    cs = _setup_thermal(s, models)[1]
    cs4 = _repeat_contacts(cs, 4)
    ref4 = prepare_contacts(s.bearing, s.Fa, s.Fr, np.full(4, s.n_rpm), M=s.M, rotating=s.rotating,
                            hertz_method=models["hertz"][0], centrifugal=models["high_speed"][0] != "yes",
                            load=cs.load, control=models["kinematics"][0])
    for side in ("inner", "outer"):
        for key, v in ref4.sides[side].items():
            np.testing.assert_allclose(np.broadcast_to(cs4.sides[side][key], np.shape(v)), v, rtol=1e-12,
                                       atol=1e-12 * np.max(np.abs(v)))      # batch-4 vs batch-() round-off
    Ti, To, Toil = np.array([40.0, 55.0, 70.0, 90.0]), np.array([35.0, 50.0, 60.0, 80.0]), np.array([30.0, 45.0, 50.0, 75.0])
    P = _contact_powers(cs4, s.lubricant, Ti, To, Toil, oil_flow_m3_s=s.oil_flow)
    r = evaluate_losses(ref4, s.lubricant, Toil, T_inner_C=Ti, T_outer_C=To, T_oil_C=Toil, oil_flow_m3_s=s.oil_flow)
    np.testing.assert_allclose(P[0], 2.0 * r.heat_W["inner_ring"], rtol=1e-12)
    np.testing.assert_allclose(P[1], 2.0 * r.heat_W["outer_ring"], rtol=1e-12)
    np.testing.assert_allclose(P[2], r.breakdown_W["drag"], rtol=1e-12)
    assert np.all(np.diff(P[0]) < 0) and np.all(np.diff(P[1]) < 0)   # hotter contacts, thinner oil: less loss
    assert np.ptp(P[2]) > 1e-3 * P[2].max()                          # the mixture temperature enters the drag


# --------------------------------------------------------------------------- cached look-ups, fast paths
def test_air_scalar_path_equals_the_spline():
    from thermobear.lubrication.air import _table, air_properties
    T = np.concatenate([np.random.default_rng(5).uniform(200.0, 600.0, 300), [200.0, 273.15, 599.5, 600.0]])
    tab = _table()(T)
    for k, t in enumerate(T):
        p = air_properties(float(t))
        assert (p["rho"], p["mu"], p["k"], p["cp"]) == tuple(tab[k])      # same bits
    arr = air_properties(T)
    assert air_properties(np.float64(T[0]))["Pr"] == arr["Pr"][0]
    with pytest.raises(tb.errors.InputError, match="T_K"):
        air_properties(650.0)


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


def test_cached_drag_factors_still_warn_at_every_evaluation():
    s, cs = _contacts_spread()                       # 30 rpm: Parker's fraction > 1, clipped with a warning
    for _ in range(2):                               # the second call runs on the cached factors
        with pytest.warns(ExtrapolationWarning, match="Parker"):
            evaluate_losses(cs, s.lubricant, 50.0, oil_flow_m3_s=s.oil_flow)


# --------------------------------------------------------------------------- scalar fast paths, fused drag
@pytest.mark.filterwarnings("ignore::thermobear.errors.ExtrapolationWarning")
def test_fused_drag_equals_the_public_drag_loss():
    from thermobear.losses.drag import drag_loss
    s, cs = _contacts_spread()                       # 0 … 12000 rpm (Parker's fraction clipped at 30 rpm)
    oil, T_oil = s.lubricant, np.array([25.0, 40.0, 60.0, 80.0, 110.0, 140.0])
    r = evaluate_losses(cs, oil, 60.0, T_oil_C=T_oil, oil_flow_m3_s=s.oil_flow)
    dp = cs.__dict__["_tb_drag"][("oil_jet", float(s.oil_flow), True)]
    run = cs.n_rpm > 0
    ref = drag_loss(cs.brg.Z, cs.brg.D, cs.brg.dm, np.asarray(cs.omega_c)[run, 0], dp["X"][run],
                    oil.rho(T_oil[run]), oil.eta(T_oil[run]), T_oil[run] + 273.15)
    np.testing.assert_allclose(r.breakdown_W["drag"][run], ref.P_W, rtol=1e-12, atol=0.0)
    assert np.all(r.breakdown_W["drag"][~run] == 0.0)
    # the repeated operating point (coupled Newton) takes the same factors, repeated
    cs1 = prepare_contacts(s.bearing, s.Fa, s.Fr, 8070.0)
    P4 = _contact_powers(_repeat_contacts(cs1, 4), oil, 50.0, 50.0, T_oil[:4], oil_flow_m3_s=s.oil_flow)
    r1 = [evaluate_losses(cs1, oil, 50.0, T_oil_C=t, oil_flow_m3_s=s.oil_flow).breakdown_W["drag"] for t in T_oil[:4]]
    np.testing.assert_allclose(P4[2], r1, rtol=1e-12, atol=0.0)


@pytest.mark.filterwarnings("ignore::thermobear.errors.ExtrapolationWarning")
def test_fused_kernel_smooth_surfaces_and_sums():
    s, cs = _contacts_spread()
    oil, Ti, To = s.lubricant, np.linspace(20.0, 140.0, 6), np.linspace(140.0, 25.0, 6)
    kw = dict(T_inner_C=Ti, T_outer_C=To, T_oil_C=45.0, oil_flow_m3_s=s.oil_flow)
    rough = evaluate_losses(cs, oil, 60.0, **kw)
    smooth = evaluate_losses(cs, oil, 60.0, Rq_ball=0.0, Rq_ring=0.0, **kw)
    for side in ("inner", "outer"):                  # Λ = ∞: full-film friction, the same rolling forces
        assert np.all(smooth.contacts[side]["mu"] == 0.05) and np.all(np.isinf(smooth.contacts[side]["Lambda"]))
        np.testing.assert_array_equal(smooth.contacts[side]["F_R"], rough.contacts[side]["F_R"])
    for r, rq in ((rough, 0.05e-6), (smooth, 0.0)):   # the sums of the Newton path = the per-contact path
        P = _contact_powers(cs, oil, Ti, To, 45.0, oil_flow_m3_s=s.oil_flow, Rq_ball=rq, Rq_ring=2 * rq)
        np.testing.assert_allclose(P[0], 2.0 * r.heat_W["inner_ring"], rtol=1e-12, atol=1e-300)
        np.testing.assert_allclose(P[1], 2.0 * r.heat_W["outer_ring"], rtol=1e-12, atol=1e-300)


def test_lubricant_scalar_path_equals_the_array_path():
    from thermobear.errors import OutsideValidity
    from thermobear.lubrication.lubricant import lubricant
    T = [-20.0, -3.7, 0.0, 23.5, 40.0, 77.7, 100.0, 149.9, 150.0]
    for name in ("seed004-mineral", "seed002-mg1", "seed002-pg2", "mol-liton-00"):
        oil = lubricant(name)
        for prop in ("nu", "rho", "eta", "k_th", "cp"):
            f = getattr(oil, prop)
            arr = f(np.array(T))
            got = np.array([f(t) for t in T])
            np.testing.assert_allclose(got, arr, rtol=1e-14, atol=0.0, err_msg=f"{name} {prop}")
            assert f(np.float64(50.0)) == f(50.0)
        eta, alpha, rho = oil._eta_alpha_rho(np.array(T))             # the kernels' combined look-up
        assert np.array_equal(eta, oil.eta(np.array(T))) and np.array_equal(rho, oil.rho(np.array(T)))
        assert np.array_equal(alpha, oil.alpha_p_at(np.array(T)))
    oil = lubricant("seed004-mineral")
    with pytest.warns(ExtrapolationWarning):                          # outside T_WARN_C: the array path's warning
        oil.eta(180.0)
    with pytest.raises(tb.errors.InputError):
        oil.rho(300.0)
    with pytest.raises(tb.errors.InputError):
        oil.nu(float("nan"))


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


def test_ellipticity_start_table_gives_the_root_of_the_plain_iteration():
    import sys
    H = sys.modules["thermobear.contact.hertz"]
    r = np.concatenate([np.exp(np.linspace(0.0, np.log(1e5), 400)), [1.0, 1.00005, 1.0002, 5.0, 32.3]])
    k = H.ellipticity(r)
    k_hb = H._ellipticity_newton(r, 1.0339 * r**0.6360, 1e-13, 50)        # started at Hamrock–Brewe
    inside = (r > 1.01) & (r < 300.0)          # near 1 and beyond 300 F(κ) is flat: the root is known to ~1e-12
    np.testing.assert_allclose(k[inside], k_hb[inside], rtol=1e-13)
    np.testing.assert_allclose(k, k_hb, rtol=2e-12)
    kk = np.where(r < 1.0001, 2.0, k)                                      # the residual of the defining equation
    res = np.where(r < 1.0001, 0.0, H._f_rho(kk) - (r - 1.0) / (r + 1.0))
    assert np.max(np.abs(res)) <= 1e-10
