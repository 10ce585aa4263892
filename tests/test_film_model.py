"""The film load model as a scene option (``[models] load_model = "film"``): selection (high-speed form
where the dry model would use it, low-speed form on request), consistency with thermobear.loads.film and
thermobear.loads.highspeed(film=...), the steady-state fixed point on the film temperature, loud refusals."""
from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

import thermobear as tb
from thermobear.errors import InputError
from thermobear.contact.kinematics import entrainment_speed
from thermobear.loads.film import film_load_distribution
from thermobear.loads.highspeed import load_distribution_high_speed
from thermobear.coupled import scene_contacts, scene_losses, steady_state
from thermobear.models import choose_models
import importlib

transient_module = importlib.import_module("thermobear.coupled.transient")

ROOT = Path(__file__).resolve().parents[1]
FILM = {"load_model": "film"}


@pytest.fixture(scope="module")
def scene():
    warnings.simplefilter("ignore", tb.ExtrapolationWarning)
    return tb.load_scene(ROOT / "examples" / "seed004_oil_jet_7210.toml").with_(n_rpm=4800.0, Fr=750.0, models=FILM)


def test_selection_and_refusals(scene):
    # the film model takes the high-speed form where the dry model does (F_c/Q > 0.05 at 4800 rpm)...
    m = choose_models(scene)
    dry = choose_models(scene.with_(models={"load_model": "jones_harris"}))
    assert m["load_model"][0] == "film" and m["high_speed"][0] == "yes" == dry["high_speed"][0]
    # ...the low-speed form at crawl speed or on request
    assert choose_models(scene.with_(n_rpm=300.0))["high_speed"][0] == "no"
    assert choose_models(scene.with_(models={"high_speed": False}))["high_speed"][0] == "no"
    with pytest.raises(InputError) as e:
        choose_models(scene.with_(models={"load_model": "films"}))
    assert e.value.field == "models.load_model" and "film" in e.value.expected


def test_prescribed_temperature_equals_the_film_distribution_injected(scene):
    T = 50.0
    s = scene.with_(T_C=T, models={"high_speed": False})
    b, lub = s.bearing, s.lubricant
    u = float(entrainment_speed(s.omega, 0.0, b.D, b.dm, b.alpha0))
    ld = film_load_distribution(b, Fa=s.Fa, Fr=s.Fr, u_i=u, u_o=u, eta=float(lub.eta(T)),
                                alpha_p=float(lub.alpha_p_at(T)))
    a = scene_losses(s)
    ref = scene_losses(s.with_(models={"load_model": "jones_harris", "high_speed": False}), load=ld)
    assert a.P_W == pytest.approx(ref.P_W, rel=1e-12)
    # every ball carries load: no open contact in the film law
    assert np.all(a.contacts["inner"]["Q"] > 0)


def test_high_speed_form_equals_the_high_speed_film_distribution_injected(scene):
    T = 50.0
    s = scene.with_(T_C=T)
    b, lub = s.bearing, s.lubricant
    ld = load_distribution_high_speed(b, Fa=s.Fa, Fr=s.Fr, n_rpm=s.n_rpm,
                                      film=dict(eta=float(lub.eta(T)), alpha_p=float(lub.alpha_p_at(T))))
    a = scene_losses(s)
    ref = scene_losses(s.with_(models={"load_model": "jones_harris", "high_speed": True}), load=ld)
    assert a.P_W == pytest.approx(ref.P_W, rel=1e-12)
    assert np.all(a.contacts["inner"]["Q"] > 0)
    # the dry high-speed model opens contacts at this load; the film model loads them (a little power more)
    dry = scene_losses(s.with_(models={"load_model": "jones_harris"}))
    assert np.any(dry.contacts["inner"]["Q"] == 0)
    assert a.P_W > dry.P_W


def test_film_loads_depend_on_the_film_temperature(scene):
    m = choose_models(scene)
    cold, hot = (scene_contacts(scene, m, T_film_C=T).sides["inner"]["Q"] for T in (30.0, 80.0))
    # thicker (cold) films carry more of the load on the lightly loaded balls
    assert cold.min() > hot.min() > 0


@pytest.mark.parametrize("high_speed", [False, True])
def test_steady_state_settles_the_film_temperature(scene, high_speed):
    st = steady_state(scene.with_(models={"high_speed": high_speed}))
    c = st.losses.contacts
    T_contacts = np.mean(np.concatenate([c["inner"]["T_C"], c["outer"]["T_C"]]))
    film_steps = [h for h in st.history if h.get("step") == "film"]
    assert 1 <= len(film_steps) <= 10
    assert film_steps[-1]["T_film_C"] == pytest.approx(T_contacts, abs=0.1)
    assert abs(st.energy_balance_W) <= 1e-9 * st.P_W
    assert "film" in st.models_used["load_distribution"][0]


def test_long_transient_ends_at_the_film_steady_state(scene):
    """The transient re-solves the film loads piece by piece (film temperature drifting ≈ 2 K per
    piece); run long enough it reaches the steady state of the same model."""
    s = scene.with_(n_rpm=3200.0, Fr=325.0, models={"load_model": "film", "high_speed": True})   # one model
    tr = tb.transient(s, t_end_s=30000.0, t_eval=[0.0, 1000.0, 30000.0])
    st = steady_state(s)
    assert tr.T_C["inner_ring"][-1] == pytest.approx(st.T_C["inner_ring"], abs=0.05)
    assert tr.P_W[-1] == pytest.approx(st.P_W, rel=1e-3)
    assert np.all(np.diff(tr.T_C["inner_ring"]) > 0) and np.all(np.diff(tr.P_W) < 0)


def test_film_cells_of_a_heat_up_converge(scene, monkeypatch):
    """The film loads of a heat-up solved on a grid of film temperatures (3 K apart), the losses and the
    network interpolated between the nodes: a grid four times finer moves the heat-up by less than 10 mK
    and 3e-4 of the power (at the solver's tight tolerances: the grid's error alone)."""
    s = scene.with_(Fr=1300.0)
    t = np.linspace(0.0, 900.0, 10)
    kw = dict(t_eval=t, rtol=1e-8, atol=1e-8)
    coarse = tb.transient(s, 900.0, **kw)
    monkeypatch.setattr(transient_module, "_FILM_CELL_K", 0.75)
    fine = tb.transient(s, 900.0, **kw)
    assert max(np.abs(coarse.T_C[n] - fine.T_C[n]).max() for n in fine.T_C) < 0.01
    assert np.abs(coarse.P_W / fine.P_W - 1.0).max() < 3e-4
    assert fine.T_C["inner_ring"][-1] - fine.T_C["inner_ring"][0] > 5.0           # the film temperature moves


def test_film_cells_batched_ahead_equal_one_by_one_and_fall_back_alone(scene, monkeypatch):
    """The grid nodes a heat-up moves towards are solved in one batched call with the node it meets; their loads
    are those solved node by node (to the load solver's tolerance), and a batch that fails leaves the node met
    solved alone (here every batch of more than one node is made to fail)."""
    s = scene.with_(Fr=1300.0)
    t = np.linspace(0.0, 1800.0, 7)
    batched = tb.transient(s, 1800.0, t_eval=t)
    monkeypatch.setattr(transient_module, "_FILM_AHEAD", 1)
    alone = tb.transient(s, 1800.0, t_eval=t)
    real, failed = transient_module.family_film_loads, []

    def fails_in_batches(fam, T, last):
        if len(T) > 1:
            failed.append(len(T))
            raise tb.NoConvergence("a batch that fails")
        return real(fam, T, last)
    monkeypatch.setattr(transient_module, "_FILM_AHEAD", 8)
    monkeypatch.setattr(transient_module, "family_film_loads", fails_in_batches)
    fallback = tb.transient(s, 1800.0, t_eval=t)
    for other in (alone, fallback):
        assert max(np.abs(batched.T_C[n] - other.T_C[n]).max() for n in other.T_C) < 1e-8
    assert failed and max(failed) == 8
    assert batched.T_C["inner_ring"][-1] - batched.T_C["inner_ring"][0] > 9.0      # 3+ grid nodes crossed


def test_transient_outputs_are_ordered_and_unique(scene):
    tr = tb.transient(scene.with_(n_rpm=3200.0), t_end_s=500.0)
    assert np.all(np.diff(tr.t_s) > 0) and tr.t_s[0] == 0.0 and tr.t_s[-1] == 500.0


def test_speed_arrays_are_refused(scene):
    with pytest.raises(InputError) as e:
        scene_losses(scene.with_(T_C=50.0), n_rpm=np.array([3200.0, 4800.0]))
    assert e.value.field == "models.load_model"


def _iterate_film(T_contacts, T0, n=20):
    """The film fixed point's updates on a model answer ``T_contacts(T_film)`` [°C] from ``T0``."""
    from thermobear.coupled.steady import _FILM_TOL_K, _film_jump, next_film_temperature
    h, T = [], T0
    for k in range(n):
        h.append(dict(iteration=k + 1, T_film_C=T, T_contacts_C=T_contacts(T), P_W=1.0))
        if abs(h[-1]["T_contacts_C"] - T) <= _FILM_TOL_K:
            return T, h, None
        jump = _film_jump(h)
        if jump is not None:
            return T, h, jump
        T = next_film_temperature(h)
    return T, h, None


def test_film_fixed_point_is_substitution_while_it_contracts():
    # gain −0.3: the plain substitution's own sequence, converged to the tolerance
    T, h, jump = _iterate_film(lambda T: 50.0 - 0.3 * (T - 40.0), 20.0)
    assert jump is None and abs(T - (50.0 + 12.0) / 1.3) < 0.1
    assert all(b["T_film_C"] == a["T_contacts_C"] for a, b in zip(h[:-1], h[1:]))


@pytest.mark.parametrize("gain", [-1.0, -1.5, -4.0])
def test_film_fixed_point_converges_where_substitution_cannot(gain):
    # a loop gain ≤ −1 (a 2-cycle or a divergence under substitution): the bracketed secant finds the root
    root = 30.0
    T, h, jump = _iterate_film(lambda T: root + gain * (T - root) + 0.02 * (T - root) ** 2, -10.0)
    assert jump is None and abs(T - root) < 0.1 and len(h) <= 12


def test_film_fixed_point_names_a_jump_of_the_answer():
    # no root: the answer jumps across the film temperature 1.2 °C (two equilibria on either side)
    T, h, jump = _iterate_film(lambda T: 10.0 if T < 1.2 else -9.0, -11.0)
    assert jump is not None and "no film temperature fixed point" in jump.reason and jump.history


def test_cold_started_oil_bath_settles_where_substitution_would_cycle():
    # 6208 in a bath at −30 °C: films at the cold start lift the loss (176 W) and heat the contacts to +31 °C,
    # whose films give 44 W and −8 °C — plain substitution cycles between the two (loop gain ≈ −1; SKF's
    # replenishment Φ_rs ≈ 0.003 makes the losses rise with temperature); the bracketed secant settles
    s = tb.load_scene(tb.example_path("oil_bath_6208.toml")).with_(T_ambient_C=-30.0, T_oil_in_C=-30.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        st = steady_state(s)
    film = [h for h in st.history if h.get("step") == "film"]
    r = [h["T_contacts_C"] - h["T_film_C"] for h in film]
    assert r[0] > 20.0 and r[1] < -20.0                              # the substitution's swing
    assert abs(r[-1]) <= 0.1 and len(film) <= 10
    assert st.T_contacts_C == pytest.approx(film[-1]["T_film_C"], abs=0.1)


def test_loads_of_cold_films_that_run_away_are_not_the_verdict(tmp_path):
    """A 16002 in an oil bath at −30 °C (init defaults, 12 000 rpm): with the films of the cold start the balls'
    losses run away (425 W) — this was the point's ThermalRunaway, though the films thin as the bearing warms
    and its heat-up settles near −10 °C.  Such a runaway is now a residual toward the limit; the point ends on the
    film fixed point's own verdict (here the jump between a starved cold equilibrium and a warm one)."""
    from thermobear.app.cli import main
    path = tmp_path / "b.toml"
    assert main(["init", "16002", "--lubrication", "oil-bath", "--out", str(path)]) == 0
    s = tb.load_scene(path).with_(T_ambient_C=-30.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(tb.NoConvergence, match="no film temperature fixed point") as e:
            steady_state(s.with_(models=FILM))
        assert e.value.history[0].get("runaway") and e.value.history[1]["T_film_C"] > 240.0
        assert "heat-up from ambient" in str(e.value)
        tr = tb.transient(s, 1800.0, t_eval=[0.0, 1800.0])
    assert max(T[-1] for T in tr.T_C.values()) < 0.0                 # the heat-up settles cold


def test_a_heat_up_settled_at_a_jump_of_the_loads_stays_there_and_says_so(tmp_path):
    """A 16002 in an oil bath at −20 °C, film load model in the low-speed form: the film temperature has no fixed
    point, the loads jump near −5.6 °C (steady_state names it).  The heat-up's film cell interpolates the loads
    across the jump and settles inside it; the loads solved at that film temperature change the losses by a few %
    and move it away.  Before, one held piece then ran to the end with its loads 4 K off the film temperature, and
    the end state depended on the run's length (−12.0 °C inner ring at 1e4 s, −6.9 °C at 1e5 s).  Now a held piece
    ends after 2 K of drift, the heat-up goes back to the cell's loads and stays at the jump however long it runs,
    and a named warning says so, also where the run ends inside the cell (1e5 s); a heat-up that settles where the
    loads are smooth has none."""
    from thermobear.app.cli import main
    path = tmp_path / "c.toml"
    assert main(["init", "16002", "--lubrication", "oil-bath", "--out", str(path)]) == 0
    s = tb.load_scene(path).with_(T_ambient_C=-20.0, models={"load_model": "film", "high_speed": False})
    ends, said = [], []
    for t_end in (1e4, 1e5):
        with warnings.catch_warnings(record=True) as got:
            warnings.simplefilter("always")
            tr = tb.transient(s, t_end, t_eval=np.linspace(0.0, t_end, 201))
        ends.append((tr.T_C["inner_ring"][-1], tr.P_W[-1]))
        said.append([w for w in tr.warnings if w.quantity == "film load jump"])
        assert [str(w.message) for w in got if getattr(w.message, "quantity", "") == "film load jump"]
        late = tr.t_s > 0.5 * t_end
        assert np.ptp(tr.T_C["balls"][late]) < 0.01              # settled at the jump, not cycling across it
    assert all(len(w) == 1 and "no fixed point" in str(w[0]) for w in said)
    assert abs(ends[0][0] - ends[1][0]) < 0.05 and ends[0][1] == pytest.approx(ends[1][1], rel=1e-3)
    smooth = tb.transient(s.with_(T_ambient_C=20.0), 1e5, t_eval=[0.0, 1e5])
    assert not [w for w in smooth.warnings if w.quantity == "film load jump"]


def test_a_settled_heat_up_ends_at_one_state_however_long_it_runs(tmp_path):
    """A 16002 in an oil bath at −10 °C, film load model in the low-speed form: the loads are smooth (a film
    temperature fixed point at 7.1 °C) but vary enough across a 3 K film cell that the cell's interpolated loads
    settle 0.17 K off it.  Before, the end state depended on the run's length (inner ring 6.49 °C at 1e4 s, ending
    inside the cell; 6.23 °C at 1e5 s, ending on loads held at the settled film temperature, which were not the
    fixed point either).  A settled heat-up now goes on in cells eight times finer: every length past settling ends
    at one state (to the integrator's tolerance), the steady state's."""
    from thermobear.app.cli import main
    path = tmp_path / "c.toml"
    assert main(["init", "16002", "--lubrication", "oil-bath", "--out", str(path)]) == 0
    s = tb.load_scene(path).with_(T_ambient_C=-10.0, models={"load_model": "film", "high_speed": False})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        runs = [tb.transient(s, t_end, t_eval=[0.0, t_end]) for t_end in (1e4, 1e5, 2e5)]
        st = steady_state(s)
    for tr in runs[1:]:
        assert max(abs(tr.T_C[n][-1] - runs[0].T_C[n][-1]) for n in tr.T_C) < 0.003
        assert tr.P_W[-1] == pytest.approx(runs[0].P_W[-1], rel=1e-4)
    assert runs[0].T_C["inner_ring"][-1] == pytest.approx(st.T_C["inner_ring"], abs=0.03)
    assert not [w for tr in runs for w in tr.warnings if w.quantity == "film load jump"]


def test_a_heat_up_started_near_the_lubricants_limit_cools_without_asking_past_it():
    """Seed 004 started at 249 °C: the film cell around it reached 252 °C, past the oil's refusal temperature
    (250 °C), and the heat-up was refused as bad input (exit 2) before it could cool; the film grid now ends at
    the lubricant's limit, and the jet cools the bearing."""
    s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    for T0 in (249.0, 250.0, -40.0):              # (at the range's ends themselves: a cell of zero width, NaN)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            tr = tb.transient(s, 600.0, T0_C=T0, t_eval=[0.0, 600.0])
        assert tr.T_C["inner_ring"][0] == pytest.approx(T0) and -40.0 < tr.T_C["inner_ring"][-1] < 200.0


def test_the_end_of_run_jump_check_never_costs_the_run(tmp_path, monkeypatch):
    """The check after a run that ends settled inside a film cell solves the loads once more; if that fails, the
    finished heat-up is still the answer (without the warning).  (The run is kept in its grid cells to the end, as
    one that settles only at its end: settled earlier, it goes on in the fine cells, whose loads are checked then.)"""
    from thermobear.app.cli import main
    tr_mod = importlib.import_module("thermobear.coupled.transient")
    path = tmp_path / "c.toml"
    assert main(["init", "16002", "--lubrication", "oil-bath", "--out", str(path)]) == 0
    s = tb.load_scene(path).with_(T_ambient_C=-20.0, models={"load_model": "film", "high_speed": False})
    piece = tr_mod._piece_model

    def failing(sc, alts, load, prepared, cells, nodes, dominant=None):
        if len(nodes) == 1:
            raise tb.NoConvergence("film loads: no solution here", iterations=1)
        return piece(sc, alts, load, prepared, cells, nodes, dominant)
    monkeypatch.setattr(tr_mod, "_piece_model", failing)
    monkeypatch.setattr(tr_mod._Settling, "cell", lambda self, fc, T_film, ts, te, sc, last: (fc.cell(T_film), np.inf,
                                                                                              False))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        tr = tb.transient(s, 1e5, t_eval=[0.0, 1e5])
    assert tr.completed and tr.T_C["inner_ring"][-1] == pytest.approx(-6.9, abs=0.1)    # at the jump
    assert not [w for w in tr.warnings if w.quantity == "film load jump"]


def test_a_heat_up_passing_the_limit_between_piece_ends_is_a_runaway():
    """A grease block started at 249.9 °C: its contacts pass 250 °C within seconds, then the housing cools them;
    the series was refused as bad input (exit 2, 'contact / oil temperature = … 252.9') — it is the heat-up's
    ThermalRunaway, as at a piece's end."""
    s = tb.load_scene(tb.example_path("block_6208_grease.toml"))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(tb.ThermalRunaway, match="passes the lubricant's limit 250 °C"):
            tb.transient(s, 600.0, T0_C=249.9)


def test_a_schedule_step_to_loads_the_bearing_cannot_carry_is_refused_before_the_run():
    """A step (or a rig log's load column) to 1e6 N on the 7210 ran into a 1.2e5 °C runaway (exit 3); its static
    safety is checked with the first operating point's, before any solve, naming the step."""
    s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    with pytest.raises(InputError, match=r"^schedule step at t = 900 s: operation \(Fa_N, Fr_N, Fz_N\)"):
        tb.transient(s, 1800.0, schedule=[(900.0, {"Fa_N": 1e6})])


@pytest.mark.parametrize("example, T_start_C", [("seed004_oil_jet_7210.toml", 40.0), ("seed004_oil_jet_7210.toml", -15.0)])
def test_the_heat_ups_jacobian_carries_the_losses_feedback(example, T_start_C):
    """The heat sources' ``jacobian`` (which the integrator adds to the network's) is ∂P/∂T of the free nodes: a
    central difference of the sources themselves agrees (warm and cold: the losses move most with temperature when
    the oil is cold).  Without this term a cold heat-up's corrector iterated on it step by step (the 16002 oil bath
    at −20 °C to 1e6 s: 6384 source evaluations, 244 with it)."""
    s = tb.load_scene(tb.example_path(example))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        pm = transient_module.point_model(s)
        src = transient_module.heat_sources(pm)
        free = ~pm.network.fixed
        T = np.where(free, T_start_C + 273.15, pm.network.initial_T_K())
        J = src.jacobian(0.0, T)[0]
        h, cols = 0.01, []
        for j in np.flatnonzero(free):
            up, dn = T.copy(), T.copy()
            up[..., j] += h
            dn[..., j] -= h
            cols.append((src(0.0, up)[0][..., free] - src(0.0, dn)[0][..., free])[0] / (2 * h))
    fd = np.column_stack(cols)
    assert np.abs(fd).max() > 0.05                        # the feedback is there to be carried: ≥ 0.05 W/K
    np.testing.assert_allclose(J, fd, rtol=0, atol=0.02 * np.abs(fd).max())


def test_films_thicker_than_the_clearance_are_named_as_a_preload():
    """A 6208 in a bath of ISO VG 220 at −10 °C, 1500 rpm, Fr 2 kN: the flooded films take up more than the
    clearance, and the film load model loads every ball — Σ Q 74 kN on the inner race for the dry solution's 2.3 kN,
    647 W — which `run` and `sweep` gave without a word.  Named now (quantity "film preload"); a light load that the
    films of the unloaded balls merely double (Fr 50 N: ×2–3.7, adding < 0.05 C0) and the warm bath are not."""
    from thermobear.app.sweep import run_sweep
    s = tb.load_scene(tb.example_path("oil_bath_6208.toml")).with_(n_rpm=1500.0, Fr=2000.0, Fa=0.0,
                                                                   lubricant="iso-vg-220-mineral")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        cold = tb.solve(s.with_(T_C=-10.0))
        warm = tb.solve(s.with_(T_C=20.0))
        light = tb.solve(s.with_(T_C=40.0, n_rpm=8000.0, Fr=50.0, lubricant="iso-vg-32-mineral"))
        rows = run_sweep(s, {"T_C": [-10.0, 20.0]})
    pre = [w for w in cold.warnings if w.quantity == "film preload"]
    assert cold.models_used["load_model"][0] == "film" and len(pre) == 1 and pre[0].value > 20
    # the rolling force of the same contacts takes the track as starved (SKF's Φ_rs ≈ 0): the warning says the two
    # disagree and that the answer lies between this one and the dry loads'
    phi = min(float(np.min(cold.losses.contacts[k]["phi_rs"])) for k in ("inner", "outer"))
    assert phi < 1e-2 and f"SKF's Φ_rs down to {phi:.3g}" in str(pre[0]) and "between this one and the dry" in str(pre[0])
    assert not [w for r in (warm, light) for w in r.warnings if w.quantity == "film preload"]
    assert light.models_used["load_model"][0] == "film"
    assert [any("film-induced preload" in w for w in r["warnings"]) for r in rows] == [True, False]
    # in a model-switch band (Fa 1 kN: 0.43 film + 0.57 Jones–Harris) the film alternative preloads as much
    # (74.5 kN for 4.0 kN dry) but the blend keeps the dominant alternative's contacts: each alternative is checked
    band = s.with_(T_C=-10.0, Fa=1000.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = tb.solve(band)
        rows = run_sweep(band, {"Fa": [900.0, 1000.0]})
    assert "blend" in r.models_used and [w.quantity for w in r.warnings].count("film preload") == 1
    assert all(any("film-induced preload" in w for w in row["warnings"]) for row in rows)


def test_a_cold_heat_up_names_the_film_preload_it_passes():
    """The same 6208 heated up from a −10 °C bath: the heat-up's film loads at its start carry Σ Q ≈ 74 kN, 32 × the
    dry 2.3 kN — named once, at the film temperature of the largest preload (before, a heat-up checked its validity
    without its loads and said nothing); a warm heat-up of light films is not."""
    s = tb.load_scene(tb.example_path("oil_bath_6208.toml")).with_(n_rpm=1500.0, Fr=2000.0, Fa=0.0,
                                                                   lubricant="iso-vg-220-mineral", T_ambient_C=-10.0)
    warm = s.with_(T_ambient_C=40.0, lubricant="iso-vg-32-mineral", n_rpm=8000.0, Fr=50.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        cold, hot = tb.transient(s, 3600.0), tb.transient(warm, 600.0)
    pre = [w for w in cold.warnings if w.quantity == "film preload"]
    assert len(pre) == 1 and pre[0].value > 20 and "at -10 °C film temperature in the heat-up" in str(pre[0])
    assert not [w for w in hot.warnings if w.quantity == "film preload"]
