"""The coupled steady state (thermobear.coupled.steady): the batched Newton iteration reaches the
fixed point an independent iteration reaches, converges quadratically, and its loss slopes are
those of one temperature at a time; the transient's loss report equals the losses at its states."""
import numpy as np
import pytest

import thermobear as tb
from thermobear.coupled import steady_state, transient
from thermobear.coupled.fixedpoint import solve_coupled
from thermobear.coupled.pipeline import families, family_loads
from thermobear.coupled.sources import prepare
from thermobear.coupled.steady import _C0, _slopes, _solve_rows
from thermobear.coupled.transient import point_model
from thermobear.models import choose_models, plan_many


def _scene(name="seed004_oil_jet_7210.toml", **kw):
    s = tb.load_scene(tb.example_path(name))
    return s.with_(**kw) if kw else s


def _picard_path(pm, T_limit_K=523.15):
    """The fixed point by damped Picard on the coupled temperatures (an independent iteration):
    losses at x → one linear network solve at the last state's conductances → new x."""
    net, src, cp = pm.network, pm.source, pm.coupling
    free, fixed = ~net.fixed, net.fixed
    state = {"T": net.initial_T_K()}

    def update(x_K):
        parts = src.parts((np.asarray(x_K) - _C0)[None])
        Aff, Afb = net.blocks(net.conductances(state["T"]))
        rhs = parts @ cp.S.T - np.einsum("bij,bj->bi", Afb, state["T"][:, fixed])
        Tf = np.linalg.solve(Aff[0], rhs[0])
        state["T"] = state["T"].copy()
        state["T"][0, free] = Tf
        return cp.C @ Tf, float(parts.sum())
    x0 = (state["T"][:, free] @ cp.C.T)[0]
    return solve_coupled(update, x0, method="picard", damping=0.7, tol_K=1e-9, max_iter=2000, T_limit_K=T_limit_K)


@pytest.mark.parametrize("name,kw", [("seed004_oil_jet_7210.toml", {"models": {"high_speed": True,
                                                                               "load_model": "jones_harris"}}),
                                     ("seed004_oil_jet_7210.toml", {"n_rpm": 8070.0, "Fr": 750.0,
                                                                    "models": {"load_model": "jones_harris"}}),
                                     ("seed002_grease_thrust_51107.toml", {})])
def test_newton_reaches_the_fixed_point_of_an_independent_iteration(name, kw):
    s = _scene(name, **kw)
    st = steady_state(s)
    ref = _picard_path(point_model(s, choose_models(s)))
    x = np.array([0.5 * (st.T_C[st.roles["ball"]] + st.T_C[st.roles[r]]) for r in ("inner", "outer")]
                 + [st.T_C[st.roles["oil"]]]) + _C0
    np.testing.assert_allclose(x, ref.T_K, atol=1e-5)
    assert st.P_W == pytest.approx(ref.P_W, rel=1e-7)
    # the conductances' temperature dependence is in the Jacobian: quadratic convergence
    assert st.iterations <= 7
    res = [h["residual_K"] for h in st.history]
    assert res[-1] <= 1e-6 and res[-2] <= 1e-2
    assert abs(st.energy_balance_W) <= 1e-9 * st.P_W


@pytest.mark.parametrize("kw", [{}, {"models": {"rolling": "houpert_ivr"}}, {"n_rpm": 8070.0}])
def test_loss_slopes_are_those_of_one_temperature_at_a_time(kw):
    """Each loss part reads only its own temperature (inner contacts the inner contact temperature,
    outer the outer, drag the mixture): the diagonal slopes from x and x + h equal forward differences
    taken one temperature at a time — the assumption the Newton Jacobian rests on."""
    pm = point_model(_scene(**kw))
    x = np.array([[47.0, 41.0, 43.0]])
    P, dP = _slopes(pm.source, pm.coupling, x, h=0.05)
    for k in range(3):
        xk = x.copy()
        xk[0, k] += 0.05
        col = (pm.source.parts(xk) - P) / 0.05
        np.testing.assert_allclose(dP[0, :, k], col[0], rtol=1e-9, atol=1e-12)
    assert np.all(np.diag(dP[0])[:2] < 0)      # thinner oil, less contact loss: the slopes are not trivially zero


def test_transient_report_equals_the_losses_at_its_states():
    s = _scene(models={"high_speed": True, "load_model": "jones_harris"})      # one model: its point model
    tr = transient(s, 1800.0, t_eval=[0.0, 60.0, 600.0, 1800.0])
    pm = point_model(s)
    ro = tr.roles
    for k in range(tr.t_s.size):
        T = {n: float(v[k]) for n, v in tr.T_C.items()}
        x = np.array([[0.5 * (T[ro["ball"]] + T[ro["inner"]]), 0.5 * (T[ro["ball"]] + T[ro["outer"]]), T[ro["oil"]]]])
        r = pm.source.result(x)
        assert tr.P_W[k] == pytest.approx(float(np.asarray(r.P_W).ravel()[0]), rel=1e-12)
        for fam, v in r.breakdown_W.items():
            assert tr.breakdown_W[fam][k] == pytest.approx(float(np.asarray(v).ravel()[0]), rel=1e-12, abs=1e-15)
    assert tr.P_W[-1] != pytest.approx(tr.P_W[0], rel=1e-3)      # the states differ


def test_a_failing_point_does_not_stop_the_others():
    s = _scene()
    good, bad = s.with_(n_rpm=3000.0), s.with_(Fa=0.0, Fr=300.0)          # no equilibrium without axial load
    out = tb.steady_states([good, bad, s])
    assert isinstance(out[0], tb.SteadyState) and isinstance(out[2], tb.SteadyState)
    assert isinstance(out[1], tb.NoEquilibrium)
    assert out[2].P_W == pytest.approx(steady_state(s).P_W, rel=1e-12)


@pytest.mark.parametrize("name", ["seed004_oil_jet_7210.toml", "block_6208_oil_bath.toml"])
def test_a_point_at_rest_and_unloaded_names_its_isolated_balls_and_stops_no_other(name):
    """At rest and unloaded the balls exchange no heat (contacts without load, the mixture still): their
    temperature is not determined.  It was a batch-wide 'singular conductance matrix' (or, on the heating
    path, a lubricant evaluated at NaN: an InputError) that stopped every point solved with it (a whole sweep)."""
    s = tb.load_scene(tb.example_path(name))
    idle, loaded = s.with_(n_rpm=0.0, Fa=0.0, Fr=0.0), s.with_(n_rpm=0.0)
    out = tb.steady_states([s, idle, loaded])
    assert isinstance(out[1], tb.NoConvergence) and "balls exchange no heat" in str(out[1])
    assert isinstance(out[0], tb.SteadyState) and isinstance(out[2], tb.SteadyState)
    assert out[0].T_C["balls"] == pytest.approx(steady_state(s).T_C["balls"], abs=1e-6)
    assert out[2].P_W == pytest.approx(0.0, abs=1e-9)                     # loaded at rest: no losses
    with pytest.raises(tb.NoConvergence, match="balls exchange no heat"):
        steady_state(idle)


def test_coupling_conserves_each_loss_part_and_matches_the_pouly_split():
    """Every loss part's heat goes somewhere whole (columns of S sum to 1); the three default parts split
    as split_losses does (½ ball, ½ race; drag to the mixture); contact temperatures are ball/race means."""
    from thermobear.coupled.sources import Coupling, prepare
    from thermobear.thermal import split_losses
    s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    cp = prepare(s).coupling
    assert np.allclose(cp.S.sum(axis=0), 1.0)
    assert np.allclose(cp.C.sum(axis=1), 1.0)
    t = prepare(s).template
    free = np.flatnonzero(~t.fixed)
    for col, unit in enumerate(np.eye(3)):
        want = {k: v for k, v in split_losses(*unit).items() if v}
        got = {t.nodes[free[i]]: q for i, q in enumerate(cp.S[:, col]) if q}
        assert got == pytest.approx(want)
    assert list(cp.reads) == [0, 1, 2] and cp.parts == ("inner", "outer", "drag")
    with pytest.raises(tb.InputError, match="loss parts"):
        Coupling.of(t, parts=("inner", "brakes"))


def test_a_point_past_the_lubricants_limit_fails_alone_in_its_batch():
    # a point whose heating path runs past the oil's refusal temperature stopped the whole batch; it is
    # that point's runaway (the bath's free convection evaluated inside the oil's range on the way)
    s = tb.load_scene(tb.example_path("oil_bath_6208.toml"))
    ok, hot = tb.steady_states([s, s.with_(n_rpm=28000.0)])
    assert isinstance(hot, tb.ThermalRunaway) and "250 °C" in str(hot)
    assert ok.T_C["balls"] == pytest.approx(tb.steady_state(s).T_C["balls"], abs=1e-6)


def test_alternatives_stacked_in_one_solve_equal_each_solved_alone():
    """The model alternatives of a point across both switch bands (three families: the high-speed form dry and
    with the film law, the low-speed form with the film law) solved as one stacked batch give each family's
    answer solved alone: the same equilibrium to round-off (each point's Newton iterates are its own)."""
    s = _scene()
    alts = plan_many([s])[0]
    assert {(a.models["high_speed"][0], a.models["load_model"][0]) for a in alts} == {
        ("yes", "film"), ("yes", "jones_harris"), ("no", "film")}
    fams, _ = families([s] * len(alts), [(a.models, a.dry) for a in alts])
    pre = prepare(s)
    parts = [(f, family_loads(f, [45.0] * f.B)) for f in fams]
    stacked = _solve_rows(parts, pre.template, pre.coupling, 1e-6)
    for p, st in zip(parts, stacked):
        alone = _solve_rows([p], pre.template, pre.coupling, 1e-6)[0][0]
        assert isinstance(st[0], tb.SteadyState) and isinstance(alone, tb.SteadyState)
        assert max(abs(st[0].T_C[n] - alone.T_C[n]) for n in alone.T_C) <= 1e-9
        assert st[0].P_W == pytest.approx(alone.P_W, rel=1e-12)
        assert st[0].iterations == alone.iterations
        assert st[0].models_used["load_distribution"] == alone.models_used["load_distribution"]
    assert len({round(st[0].P_W, 6) for st in stacked}) == 3          # three different answers


_S004 = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))


@pytest.mark.parametrize("tol, message", [(0, r"^tol_K = 0 — must be > 0 \[K\]"), (-1.0, r"^tol_K = -1.0 — must be > 0"),
                                          (np.nan, r"^tol_K = nan — must be finite"), ("x", r"^tol_K = 'x' — must be a number")])
def test_steady_state_refuses_a_tolerance_that_is_not_finite_and_positive(tol, message):
    with pytest.raises(tb.InputError, match=message):
        steady_state(_S004, tol_K=tol)


def test_steady_states_refuses_a_scene_for_the_list_and_steady_state_a_non_scene():
    with pytest.raises(tb.InputError, match=r"^scenes = 'Scene' — a list of Scene"):
        tb.steady_states(_S004)
    with pytest.raises(tb.InputError, match=r"^scene = 'x' — must be a Scene"):
        steady_state("x")
    assert tb.steady_states((_S004,), tol_K=np.float32(1e-6))[0].P_W == steady_state(_S004).P_W
