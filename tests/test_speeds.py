"""Speeds: ISO 15312 reference conditions and heat flow, DIN 732's speed ratio, the model's thermal
reference speed and the thermally safe speed of a scene's cooling (root meets its condition, trends,
failures named)."""
import dataclasses
import json
import warnings

import numpy as np
import pytest
from scipy.optimize import brentq

import thermobear as tb
import thermobear.app.speed as app_speed
from thermobear.app.cli import main
from thermobear.coupled.speeds import (ENDS, _ends, din732_safe_speed, hottest_ring_C, reference_loads,
                                       reference_lubricant, runaway_speed, thermal_reference_speed,
                                       thermally_safe_speed)
from thermobear.errors import ContactLimit, InputError, NoSpeedRoot
from thermobear.rating.speeds import (din732_parameters, din732_speed_ratio, palmgren_moments, reference_conditions,
                                      reference_heat_flow_density, reference_surface, standard_reference_speed)


@pytest.fixture(scope="module")
def block():
    return tb.load_scene(tb.example_path("block_6208_oil_bath.toml"))


@pytest.fixture(scope="module")
def safe70(block):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return thermally_safe_speed(block, limit_C=70.0, xtol_rpm=20.0, n_min_rpm=3000.0, n_max_rpm=24000.0, points=4)


def test_reference_conditions_radial_and_thrust():
    r, t = reference_conditions("deep_groove"), reference_conditions("thrust")
    assert (r.T_C, r.T_ambient_C, r.load_fraction, r.nu_cSt, r.load) == (70.0, 20.0, 0.05, 12.0, "Fr")
    assert (t.load_fraction, t.nu_cSt, t.load, t.in_scope) == (0.02, 24.0, "Fa", False)
    assert reference_lubricant("angular_contact").nu(70.0) == pytest.approx(12.0, rel=1e-12)
    assert reference_lubricant("thrust").nu(70.0) == pytest.approx(24.0, rel=1e-12)


def test_reference_surface_radial_and_thrust_by_hand():
    assert reference_surface(0.040, 0.080, 0.018, "deep_groove") == pytest.approx(np.pi * 0.018 * 0.120)
    assert reference_surface(0.035, 0.052, 0.012, "thrust") == pytest.approx(np.pi / 2 * (0.052 ** 2 - 0.035 ** 2))


def test_heat_flow_density_at_the_standards_knee():
    knee = 50_000e-6
    A = np.array([0.5 * knee, knee, knee * (1 + 1e-9), 2 * knee])
    q = reference_heat_flow_density(A)
    assert q[0] == q[1] == 16e3                                  # flat up to 50 000 mm²
    assert q[2] == pytest.approx(16e3, rel=1e-9)                 # continuous at the knee
    assert q[3] == pytest.approx(16e3 * 2 ** -0.34, rel=1e-12)   # falling beyond
    assert np.all(np.diff(q * A) > 0)                            # the reference heat flow still grows
    qt = reference_heat_flow_density(A, "thrust")                # thrust bearings: 20 kW/m², exponent -0.16
    assert qt[0] == qt[1] == 20e3 and qt[2] == pytest.approx(20e3, rel=1e-9)
    assert qt[3] == pytest.approx(20e3 * 2 ** -0.16, rel=1e-12)


def test_din732_ratio_approximates_the_heat_balance():
    # K_L f^(5/3) + K_P f = 1 at n = f n_θr (K_L the lubricant parameter, M0's share; K_P the load parameter):
    # the approximation quoted by Schaeffler HR 1 (2006) p. 63 holds to 5.7 % (median 0.7 %) on its stated range
    # 0.01–10 of both; with the parameters exchanged (this module's reading before) it errs by up to 150 %
    def exact(K_L, K_P):
        return brentq(lambda f: K_L * f ** (5 / 3) + K_P * f - 1.0, 1e-9, 1e6)
    grid = [0.01, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0]
    err = np.array([din732_speed_ratio(a, b) / exact(a, b) - 1.0 for a in grid for b in grid])
    assert np.abs(err).max() < 0.058 and np.median(np.abs(err)) < 0.008
    swapped = np.array([din732_speed_ratio(a, b) / exact(b, a) - 1.0 for a in grid for b in grid])
    assert np.abs(swapped).max() > 1.0                           # the orientation of the parameters matters
    for K_L, K_P in [(0.5, 0.5), (0.3, 0.7), (0.7, 0.3), (0.1, 0.9), (0.9, 0.1), (1.0, 1.0), (2.0, 2.0)]:
        assert din732_speed_ratio(K_L, K_P) == pytest.approx(exact(K_L, K_P), rel=0.021)
    assert din732_speed_ratio(1.421, 0.303) / exact(1.421, 0.303) == pytest.approx(1.004, abs=0.002)  # 6208 block


def test_standard_reference_speed_meets_its_balance():
    n, res, it = standard_reference_speed(6785.8e-6, 0.060, 950.0, 2.0, 0.000179)
    M0, M1 = palmgren_moments(n, 12.0, 950.0, 0.060, 2.0, 0.000179)
    assert np.pi / 30 * n * (M0 + M1) == pytest.approx(16e3 * 6785.8e-6, rel=1e-10)
    K_L, K_P = din732_parameters(n, M0, M1, 16e3 * 6785.8e-6)
    assert K_L + K_P == pytest.approx(1.0, rel=1e-10)            # reference conditions: f_n = 1 exactly


def test_model_reference_speed_residual_and_trends():
    b = tb.bearing("6208")
    r = thermal_reference_speed(b)
    assert abs(r.residual_W) <= 1e-6 * r.Phi_r_W and r.monotonic
    assert r.P_W == pytest.approx(r.Phi_r_W, rel=1e-6)
    assert r.load_N == pytest.approx(0.05 * b.C0)
    thick = thermal_reference_speed(b, lubricant=tb.lubricant("iso-vg-68-mineral"))
    assert thick.n_rpm < r.n_rpm                                 # more viscous oil: more friction, lower n_θr


def test_thrust_reference_conditions_and_scope_warning():
    r = thermal_reference_speed(tb.bearing("51107"))
    assert r.load_N == pytest.approx(0.02 * tb.bearing("51107").C0)
    assert r.lubricant.startswith("iso15312-reference-24")
    assert [w.quantity for w in r.warnings] == ["iso15312_scope"]


def test_safe_speed_meets_the_limit(safe70):
    assert abs(safe70.residual_K) < 0.05 and safe70.T_C == pytest.approx(70.0, abs=0.05)
    lo, hi = safe70.bracket_rpm
    assert lo < safe70.n_rpm < hi


def test_safe_speed_trends(block, safe70):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        higher = thermally_safe_speed(block, limit_C=80.0, xtol_rpm=20.0, n_min_rpm=3000.0, n_max_rpm=24000.0, points=4)
        cooler = thermally_safe_speed(block.with_(T_ambient_C=15.0), limit_C=70.0, xtol_rpm=20.0, n_min_rpm=3000.0, n_max_rpm=24000.0, points=4)
    assert higher.n_rpm > safe70.n_rpm                           # higher limit → higher speed
    assert cooler.n_rpm > safe70.n_rpm                           # colder surroundings → higher speed


def test_safe_speed_failures_are_named(block):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(NoSpeedRoot, match="exceeded already at"):
            thermally_safe_speed(block, limit_C=30.0, points=3)
        with pytest.raises(NoSpeedRoot, match="at no speed up to"):
            thermally_safe_speed(block, limit_C=70.0, n_max_rpm=2000.0, points=3)
        with pytest.raises(InputError, match="node"):
            thermally_safe_speed(block, node="no_such_node", points=3)


def test_din732_of_the_block_scene(block):
    d = din732_safe_speed(block)
    assert d.n_rpm == pytest.approx(d.f_n * d.n_theta_r_rpm)
    assert d.P1_N == block.Fr and d.nu_cSt == pytest.approx(block.lubricant.nu(70.0))
    assert din732_safe_speed(block, limit_C=80.0).n_rpm > d.n_rpm
    with pytest.raises(InputError, match="thrust"):
        din732_safe_speed(block.with_(bearing="51107", Fa=1000.0, Fr=0.0))
    with pytest.raises(InputError, match="ambient"):
        din732_safe_speed(block, limit_C=20.0)


def test_cli_speed_json(capsys, block):
    assert main(["speed", tb.example_path("block_6208_oil_bath.toml"), "--json", "--limit-C", "70"]) == 0
    rep = json.loads(capsys.readouterr().out)
    assert abs(rep["model"]["T_C"] - 70.0) < 0.01 and "jump" not in rep["model"]
    assert {"n_rpm", "T_C"} <= set(rep["iso15312"]) and {"n_rpm", "f_n", "T_C"} <= set(rep["din732"])
    run = rep["runaway"]            # the equilibria end well above the speed at which the race reaches 70 °C
    assert run["kind"] == "thermal runaway" and run["settled_rpm"] < run["n_rpm"] <= 1.01 * run["settled_rpm"]
    assert run["n_rpm"] > rep["model"]["n_rpm"] and run["T_C"] > 70.0 and run["preload_warm_N"] is None


def test_cli_speed_says_when_the_limit_is_jumped_and_prints_the_answers_warnings(capsys, tmp_path):
    """A greased 6205 of `thermobear init`: its replenishment-starved losses keep the rings below 70 °C up to near
    5e4 rpm (n·dm 1.9e6, beyond the validated 1e6), where that cool equilibrium ends and the rings step to a
    hotter one, past the limit (the heating path crosses to it: the update maps 250 °C below itself, so it is no
    runaway).  The text names the step (the answer passes the limit by 4 K, the cool side lies below it) and, as
    every verb, prints the answer's warnings on stderr (they were kept in the JSON only)."""
    scene = tmp_path / "g6205.toml"
    assert main(["init", "6205", "--lubrication", "grease", "--speed-rpm", "10000", "--out", str(scene)]) == 0
    capsys.readouterr()
    assert main(["speed", str(scene)]) == 0
    out, err = capsys.readouterr()
    assert "the limit is passed by a step at this speed" in out and "°C just below it (a step of the model)" in out
    row = next(ln for ln in out.splitlines() if "this scene's cooling (model)" in ln)
    assert "a step of the model passes the limit here (+" in row              # the table's row says it too
    assert "warning: OutsideValidity: operation.n_rpm: speed n·dm" in err
    assert main(["speed", str(scene), "--json"]) == 0
    rep = json.loads(capsys.readouterr().out)["model"]
    node, below = rep["jump"].split(" °C just below")[0].split()            # "<node> <T> °C just below it ..."
    below = float(below)
    assert node in ("inner_race", "outer_race")
    assert rep["residual_K"] > 1.0 and below < 70.0 < rep["T_C"]                 # the step across the limit


def test_cli_speed_row_says_when_the_equilibria_end_below_the_limit(capsys):
    """The greased 6208 block, limit 240 °C: the steady states end (runaway just above) with the inner race
    some kelvin below the limit.  The speed is the answer (it bounds the equilibria), and the table's row says
    so beside the number, not only the note under the table (it read as a root of the limit)."""
    assert main(["speed", str(tb.example_path("block_6208_grease.toml")), "--limit-C", "240"]) == 0
    out = capsys.readouterr().out
    row = next(ln for ln in out.splitlines() if "this scene's cooling (model)" in ln)
    T = float(row.split("inner_race ")[1].split(" °C")[0])
    below = float(row.split("the equilibria end here, ")[1].split(" K below")[0])
    assert T < 240.0 and below == pytest.approx(240.0 - T, abs=0.051)
    assert "the limit is not reached at this speed" in out


def test_safe_speed_ends_where_the_contacts_cannot_carry_the_loads(tmp_path, capsys):
    # a 7311 B under its init loads (Fa 2710 N, Fr 2580 N): with speed the balls' centrifugal force turns
    # the inner contacts of the lightly loaded balls towards the groove's edge; the ellipse passes it near
    # 8300 rpm, before the hottest ring reaches 70 °C (it is 59 °C at 7100 rpm)
    path = tmp_path / "a7311.toml"
    assert main(["init", "7311B", "--lubrication", "oil-air", "--out", str(path)]) == 0
    sc = tb.load_scene(path)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        # 9 rungs: the one at 18 050 rpm is refused (ContactLimit); 5 rungs: the top one, 45 714 rpm, runs away
        # (no equilibrium), and Brent's search between 7127 rpm and it meets the contacts' limit
        for points in (9, 5):
            with pytest.raises(NoSpeedRoot, match="highest speed at which the contacts carry the loads") as e:
                thermally_safe_speed(sc, limit_C=70.0, points=points)
            n_c, T_c = e.value.contact_limit_rpm, e.value.T_C
            assert f"no speed up to {n_c:.6g} rpm" in str(e.value) and f"({T_c:.2f} °C there)" in str(e.value)
            assert 7127.0 < n_c < 18050.0 and 59.46 < T_c < 70.0
        assert tb.steady_state(sc.with_(n_rpm=n_c)).P_W > 0.0           # carried at the speed named …
        with pytest.raises(ContactLimit, match="groove bottom"):        # … and not 0.5 % above it
            tb.steady_state(sc.with_(n_rpm=1.005 * n_c))
        # a limit the hottest ring passes below the contacts' limit, between its last rung and it: found there
        for points in (9, 5):
            r = thermally_safe_speed(sc, limit_C=T_c - 0.5, points=points, xtol_rpm=0.5)
            assert 7127.0 < r.n_rpm < n_c and abs(r.T_C - (T_c - 0.5)) < 0.01
            assert points == 5 or r.bracket_rpm[1] == pytest.approx(n_c, rel=3e-3)    # (9: from the contacts' limit)
        assert thermally_safe_speed(sc, limit_C=50.0, points=5).n_rpm < 7127.0   # a crossing on the ladder
    assert main(["speed", str(path), "--json"]) == 3                   # the model part has no answer: exit 3
    rep = json.loads(capsys.readouterr().out)["model"]
    assert rep["contact_limit_rpm"] == pytest.approx(n_c, rel=3e-3) and "error" in rep


def test_din732_of_a_bearing_without_a_catalogue_c0_takes_iso_76s(block):
    """A bearing whose data state no C0 (a scene's own geometry) was an internal error (None × float) in DIN 732;
    it takes ISO 76's C0 from the geometry, as the ratings and ISO 15312's reference load do."""
    from thermobear.rating.life import load_ratings
    bare = block.with_(bearing=block.bearing.with_(C0=None))
    C0 = load_ratings(block.bearing)[1]
    stated = block.with_(bearing=block.bearing.with_(C0=C0))
    assert din732_safe_speed(bare).n_rpm == pytest.approx(din732_safe_speed(stated).n_rpm, rel=1e-12)
    assert reference_loads(bare.bearing)["Fr"] == pytest.approx(0.05 * C0)


class _State:
    """A steady state as the safe-speed search reads it (hottest ring, warnings)."""

    def __init__(self, T):
        self.T_C, self.roles, self.warnings = {"i": T, "o": T - 1.0}, {"inner": "i", "outer": "o"}, []


def _fold(n):
    """A machine whose equilibria end at 20 000 rpm (runaway above) with the ring at 40 °C, whose heating path
    no longer settles in the last 5 % below that fold (loop gain near 1)."""
    if n >= 20000.0:
        raise tb.ThermalRunaway("runaway")
    if n >= 19000.0:
        raise tb.NoConvergence("the heating path creeps near the fold")
    return _State(20.0 + n / 1000.0)


def test_safe_speed_closing_on_the_runaway_edge_takes_an_unsettled_path_as_beyond(block, monkeypatch):
    # the limit 50 °C is never reached: Brent closes on the fold between the last equilibrium and the runaway
    # rung, where the heating path may not settle (a NoConvergence): that is the edge, not the search's failure
    import thermobear.coupled.speeds as sp

    def many(scenes, prepared=None):
        out = []
        for sc in scenes:
            try:
                out.append(_fold(sc.n_rpm))
            except tb.SolverError as e:
                out.append(e)
        return out
    monkeypatch.setattr(sp, "steady_states", many)
    monkeypatch.setattr(sp, "steady_state", lambda sc, prepared=None: _fold(sc.n_rpm))
    monkeypatch.setattr(sp, "prepare", lambda sc: None)
    r = thermally_safe_speed(block, limit_C=50.0, n_min_rpm=1000.0, n_max_rpm=40000.0, points=5, xtol_rpm=1.0)
    assert 18990.0 < r.n_rpm < 19000.0 and r.T_C < 50.0 and r.bracket_rpm[1] > 20000.0
    # below a rung with an equilibrium (no runaway above the bracket) a NoConvergence is the search's failure
    monkeypatch.setattr(sp, "steady_state", lambda sc, prepared=None: (_ for _ in ()).throw(tb.NoConvergence("x")))
    with pytest.raises(tb.NoConvergence):
        thermally_safe_speed(block, limit_C=30.0, n_min_rpm=1000.0, n_max_rpm=40000.0, points=5, xtol_rpm=1.0)


def test_cli_speed_reports_a_solver_failure_of_the_model_and_keeps_the_standards(block, monkeypatch, capsys):
    import thermobear.app.speed as app_speed

    def fails(*a, **k):
        raise tb.NoConvergence("high-speed load distribution did not reach equilibrium at a probe speed")
    monkeypatch.setattr(app_speed, "thermally_safe_speed", fails)
    assert main(["speed", tb.example_path("block_6208_oil_bath.toml"), "--json"]) == 3
    rep = json.loads(capsys.readouterr().out)
    assert rep["model"]["error"].startswith("NoConvergence: high-speed") and "n_rpm" in rep["iso15312"]
    assert "n_rpm" in rep["din732"]


@pytest.mark.parametrize("limit", ["25", "10", "250", "nan"])
def test_cli_speed_limit_not_above_the_ambient_is_bad_input(block, capsys, limit):
    """A limit at or below the ambient (25 °C here) is an input no speed can meet: exit 2 with one line naming
    --limit-C, its value and the accepted range, nothing on stdout (it ran the searches, wrote a partial table and
    exited 3 as if the model had failed)."""
    assert main(["speed", tb.example_path("block_6208_oil_bath.toml"), "--limit-C", limit]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.strip().splitlines() == [
        f"error: --limit-C = {float(limit)} — must be above the ambient 25 °C (no speed heats the bearing to a "
        "temperature below its surroundings) and below 250 °C (the lubricant data's limit)"]


def test_speed_rows_say_which_speeds_pass_the_limit_and_carry_the_states_ratings(capsys, tmp_path):
    """The 6206-2RS1 motor bearing as `init` writes it: DIN 732's and ISO 15312's speeds heat the race past the 70 °C
    limit in this scene (now flagged), ISO 15312's is the open bearing's (none for contact seals), and the model's
    speed carries its state's ratings warnings (a consumed clearance, which `run` at that speed names)."""
    path = tmp_path / "m.toml"
    assert main(["init", "6206-2RS1", "--lubrication", "grease", "--speed-rpm", "3000", "--Fr-N", "1500",
                 "--out", str(path)]) == 0
    capsys.readouterr()
    assert main(["speed", str(path), "--json"]) == 0
    rep = json.loads(capsys.readouterr().out)
    assert rep["din732"]["T_C"] > 70.0 and rep["contact_seals"] is True
    assert any(w["quantity"] == "operating_clearance" for w in rep["model"]["warnings"])
    text = app_speed.summary(rep)
    assert "DIN 732 thermally safe speed" in text and "; above the 70 °C limit" in text
    assert "ISO 15312 has none for contact seals" in text


def test_speed_refuses_a_node_that_is_not_free(block, capsys):
    """A fixed-temperature node does not follow the speed: `--node ambient` reported a 'safe speed' at the
    ambient's 25.00 °C; it is refused naming --node (exit 2, nothing printed), and by the library naming node."""
    with pytest.raises(InputError, match="fixed-temperature") as e:
        thermally_safe_speed(block, node="ambient", points=3)
    assert e.value.field == "node"
    assert main(["speed", tb.example_path("block_6208_oil_bath.toml"), "--node", "ambient"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.startswith("error: --node = 'ambient' — a fixed-temperature (boundary) node")
    assert len(err.splitlines()) == 1


def test_cli_speed_temperature_at_a_speed_does_not_depend_on_the_other_speeds(block, monkeypatch, capsys):
    """The scene's temperatures at the ISO 15312 and DIN 732 speeds were one batch: a DIN speed the models refuse
    (n·dm beyond 4e6 mm/min, as --limit-C 240 gives a 6208) made the ISO row 'no equilibrium (InputError)' too,
    and --json put that string in the numeric T_C.  Each speed is its own: T_C a number or null with T_C_error."""
    monkeypatch.setattr(app_speed, "din732_safe_speed",
                        lambda scene, limit_C: dataclasses.replace(din732_safe_speed(scene, limit_C=limit_C),
                                                                   n_rpm=80000.0))
    assert main(["speed", tb.example_path("block_6208_oil_bath.toml"), "--json"]) == 0
    rep = json.loads(capsys.readouterr().out)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        T_iso = hottest_ring_C(tb.steady_state(block.with_(n_rpm=rep["iso15312"]["n_rpm"])))
    assert rep["iso15312"]["T_C"] == pytest.approx(T_iso, abs=1e-3) and "T_C_error" not in rep["iso15312"]
    at = rep["iso15312"]["T_node"]
    assert rep["din732"]["T_C"] is None and rep["din732"]["T_C_error"].startswith("not modelled (InputError: "
                                                                                  "operation.n_rpm = 80000.0")
    assert main(["speed", tb.example_path("block_6208_oil_bath.toml")]) == 0
    out = capsys.readouterr().out
    assert f"{at} {T_iso:.2f} °C in this scene" in out and "—  not modelled (InputError: operation.n_rpm" in out


def test_cli_speed_names_the_node_it_limits(tmp_path, capsys):
    """`speed` said "hottest ring 70.00 °C" where the node at 70 °C was outer_race (the raceway layer; the ring
    body outer_ring was at 67.2 °C): the label names the node limited at each speed, the header the nodes the
    hotter race is taken from, and the temperature is that node's in `run` at that speed."""
    scene = tmp_path / "spindle.toml"
    assert main(["init", "7014C", "--lubrication", "oil-air", "--speed-rpm", "12000", "--Fa-N", "600",
                 "--out", str(scene)]) == 0
    capsys.readouterr()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert main(["speed", str(scene), "--json"]) == 0
        rep = json.loads(capsys.readouterr().out)
        st = tb.steady_state(tb.load_scene(scene).with_(n_rpm=rep["model"]["n_rpm"]))
    assert rep["node"] == "hotter race" and rep["race_nodes"] == ["inner_race", "outer_race"]
    mod = rep["model"]
    assert mod["T_node"] == "outer_race" and st.T_C["outer_race"] == pytest.approx(70.0, abs=0.05)
    assert st.T_C["outer_ring"] < 69.0                        # the ring body is not what is limited
    out = app_speed.summary(rep)
    assert "hottest ring" not in out and "limit 70 °C on the hotter of inner_race and outer_race" in out
    assert f"{mod['n_rpm']:9.0f} rpm   outer_race 70.00 °C" in out
    for part in ("iso15312", "din732"):
        assert f"{rep[part]['T_node']} {rep[part]['T_C']:.2f} °C" in out


def test_din732_balance_root_meets_its_balance_and_its_limits():
    """The root of K_L f^(5/3) + K_P f = 1 (what DIN 732's f_n approximates): the balance holds to 1e-12 on a grid,
    one term alone gives K_L^(−3/5) or 1/K_P, K_L = K_P = 1/2 gives 1, none gives ∞; the speed verb's DIN 732 row
    states it beside the approximation (0.702 against 0.705 on the bundled 6208 block)."""
    from thermobear.coupled.speeds import din732_safe_speed
    from thermobear.rating.speeds import din732_balance_ratio
    KL, KP = np.meshgrid([0.0, 0.01, 0.3, 1.0, 5.0], [0.0, 0.02, 0.5, 1.4, 8.0])
    f = np.asarray(din732_balance_ratio(KL, KP))
    ok = (KL > 0) | (KP > 0)
    np.testing.assert_allclose(f[ok] ** (5 / 3) * KL[ok] + f[ok] * KP[ok], 1.0, rtol=1e-12)
    assert np.isinf(f[~ok]).all()
    assert din732_balance_ratio(0.0, 0.25) == pytest.approx(4.0) and din732_balance_ratio(32.0, 0.0) == pytest.approx(0.125)
    assert din732_balance_ratio(0.5, 0.5) == pytest.approx(1.0, rel=1e-12)
    d = din732_safe_speed(tb.load_scene(tb.example_path("block_6208_oil_bath.toml")))
    assert d.f_n_balance == pytest.approx(float(din732_balance_ratio(d.K_L, d.K_P)))
    assert d.K_L == pytest.approx(1.421, abs=5e-4) and d.K_P == pytest.approx(0.303, abs=5e-4)   # M0's share the larger
    assert d.f_n / d.f_n_balance == pytest.approx(1.004, abs=0.002)


def _pair(preload_N: float):
    """Seed 004's 7210 on its oil jet as one bearing of a back-to-back pair (the block's 650 N on the pair)."""
    return tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")).with_(arrangement="back_to_back",
                                                                           preload_N=preload_N, Fa=0.0, Fr=650.0)


def test_runaway_speed_brackets_where_a_pairs_preload_runs_away():
    """The speed at which the equilibria end: at its lower end the pair settles (its warm preload the answer's), at
    its upper end the preload runs away (ThermalPreloadRunaway, named), the two within rtol; a pair preloaded twice
    as hard runs away at a lower speed (more preload, more heat, more preload)."""
    r = runaway_speed(_pair(450.0), n_min_rpm=2000.0, n_max_rpm=6500.0, points=2, rtol=0.03)
    assert r.kind == "preload runaway" and r.why.startswith("ThermalPreloadRunaway")
    assert r.settled_rpm < r.n_rpm <= 1.03 * r.settled_rpm
    assert r.preload_warm_N == pytest.approx(r.steady.preload["warm_N"]) and r.preload_warm_N > 2 * 450.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(tb.ThermalPreloadRunaway):
            tb.steady_state(_pair(450.0).with_(n_rpm=r.n_rpm))
    heavy = runaway_speed(_pair(900.0), n_min_rpm=2000.0, n_max_rpm=6500.0, points=2, rtol=0.03)
    assert heavy.n_rpm < r.settled_rpm


def test_runaway_speed_says_when_there_is_none_in_the_range():
    s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    with pytest.raises(NoSpeedRoot, match="an equilibrium at every speed up to 8000 rpm"):
        runaway_speed(s, n_min_rpm=2000.0, n_max_rpm=8000.0, points=3)
    with pytest.raises(NoSpeedRoot, match="no equilibrium already at 6500 rpm"):
        runaway_speed(_pair(450.0), n_min_rpm=6500.0, n_max_rpm=8000.0, points=2)
    with pytest.raises(InputError, match="rtol"):
        runaway_speed(s, rtol=0.0)


def test_what_ends_the_equilibria_is_named_including_the_contacts_limit():
    """The errors that end the equilibria each have their name (a ContactLimit is an InputError, but not the
    lubricant's); another InputError is not an end (it is raised)."""
    assert _ends(ContactLimit("operation (Fa_N, Fr_N, M_Nm)", "Fa 0 N", "maximum contact pressure 6528 MPa")) == \
        ENDS[ContactLimit]
    assert _ends(tb.ThermalPreloadRunaway("x")) == "preload runaway" and _ends(tb.ThermalRunaway("x")) == "thermal runaway"
    assert _ends(InputError("operation.n_rpm", -1.0, "must be >= 0")) is None
