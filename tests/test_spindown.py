"""Spin-down: ODE integration vs closed forms, the two fits, energy balance, named errors."""
import math

import json

import numpy as np
import pytest

import thermobear as tb
from thermobear.app.cli import main
from thermobear.errors import InputError, NoConvergence
from thermobear.losses import rolling as R
from thermobear.app import spindown as SD

J = 2.0e-4


@pytest.mark.parametrize("K, n", [(3.354e-5, 0.649), (3.213e-5, 0.339), (1e-4, 0.0), (2e-5, 1.0), (1e-6, 1.5)])
def test_integration_matches_closed_form(K, n):
    w0 = 210 * math.pi / 30
    t_end = SD.stop_time(w0, K, n, J) * 1.2 if n < 1 else 60.0
    t = np.linspace(0, t_end, 60)
    r = SD.integrate_spin_down(J, lambda w: K * w**n, w0, t_end, t_eval=t)
    assert r.omega == pytest.approx(SD.omega_power_law(t, w0, K, n, J), rel=1e-6, abs=1e-7 * w0)
    assert r.phi == pytest.approx(SD.angle_power_law(t, w0, K, n, J), rel=1e-6, abs=1e-7)
    if n < 1:
        # the rotor touches ω = 0 tangentially (ω ∝ (t_s - t)^(1/(1-n))): the event is located to ~1e-5
        assert r.t_stop == pytest.approx(J * w0 ** (1 - n) / ((1 - n) * K), rel=1e-4)
        assert r.phi[-1] == pytest.approx(J * w0 ** (2 - n) / ((2 - n) * K), rel=1e-7)
    else:
        assert r.t_stop == math.inf


def test_energy_balance_of_a_rig_model():
    """½ J ω0² = ∫ T(ω) ω dt for the seed 001 rig torque T = 6 r F_R(ω r/2) (no closed form)."""
    d, rg, r = 6.35e-3, 4.16e-3, 0.018
    Rx, Ry = d / 2, rg * d / 2 / (rg - d / 2)
    T = lambda w: 6 * r * R.rolling_force(0.125, Rx, Ry, w * r / 2, 0.05, 2.3e11)
    w0 = 210 * math.pi / 30
    res = SD.integrate_spin_down(J, T, w0, 500.0)
    assert math.isfinite(res.t_stop)
    t = np.linspace(0, res.t_stop, 4001)
    s = SD.integrate_spin_down(J, T, w0, 500.0, t_eval=t)
    P = np.array([T(w) * w for w in s.omega])
    work = np.sum((P[1:] + P[:-1]) / 2 * np.diff(t))
    assert work == pytest.approx(0.5 * J * w0**2, rel=1e-3)


def test_fit_from_stop_closed_form_round_trip_and_dry_case():
    w0 = 120 * math.pi / 30
    for K, n in [(3.943e-5, 0.620), (2.864e-5, 0.318), (1e-4, 0.0)]:
        tm, ph = SD.stop_time(w0, K, n, J), SD.total_angle(w0, K, n, J)
        f = SD.fit_from_stop(w0, tm, ph, J)
        assert (f.K, f.n) == (pytest.approx(K, rel=1e-10), pytest.approx(n, abs=1e-10))
    # hand: n = 0 -> T = J ω0 / t_max, φ = ω0 t/2 ; seed 001 eq 18
    assert SD.dry_torque_from_stop(w0, 10.0, w0 * 5.0, J) == pytest.approx(J * w0 / 10.0, rel=1e-12)
    with pytest.raises(InputError, match="phi_max"):
        SD.fit_from_stop(w0, 10.0, 0.6 * w0 * 10.0, J)     # would need n < 0
    with pytest.raises(InputError, match="phi_max"):
        SD.dry_torque_from_stop(w0, 10.0, 1.1 * w0 * 10.0, J)


def test_least_squares_fit_recovers_parameters_from_noisy_data():
    rng = np.random.default_rng(1)
    w0, K, n = 150 * math.pi / 30, 3.779e-5, 0.654
    t = np.linspace(0, 0.9 * SD.stop_time(w0, K, n, J), 200)
    w = SD.omega_power_law(t, w0, K, n, J) + rng.normal(0, 0.01, t.size)
    f = SD.fit_power_law(t, np.clip(w, 0, None), J)
    sK, sn = np.sqrt(np.diag(f.cov))
    assert abs(math.log(f.K / K)) < 4 * sK + 1e-3
    assert abs(f.n - n) < 4 * sn + 1e-3
    assert f.residual == pytest.approx(0.01, rel=0.2)
    assert f.iterations > 0 and f.method == "least_squares"


def test_least_squares_fit_raises_named_error_when_ill_posed():
    t = np.linspace(0, 10, 30)
    with pytest.raises(NoConvergence):
        SD.fit_power_law(t, np.full(t.size, 5.0), J, omega0=5.0)     # no deceleration: K, n not fixed
    with pytest.raises(InputError):
        SD.fit_power_law(t, -np.ones(t.size), J)


def test_bad_inputs():
    with pytest.raises(InputError, match="^n = "):
        SD.omega_power_law(1.0, 10.0, 1e-4, 2.5, J)
    with pytest.raises(InputError, match="^J = "):
        SD.stop_time(10.0, 1e-4, 0.5, 0.0)
    with pytest.raises(InputError, match="torque"):
        SD.integrate_spin_down(J, lambda w: -1.0, 10.0, 1.0)


def test_spin_down_of_a_scene_whose_model_choice_is_the_film_load_model():
    """A flooded, radially loaded 6208 lifts balls off the races: the model choice takes the film load model,
    whose loads are solved one speed at a time — the coast-down tabulates its torque speed by speed (it was
    refused as 'models.load_model = film', a key the scene never set) and starts from the scene's own torque."""
    import thermobear as tb
    from thermobear.coupled import scene_losses
    from thermobear.models import plan
    sc = tb.load_scene(tb.example_path("block_6208_oil_bath.toml")).with_(T_C=40.0)
    models = plan(sc)[0]
    assert models["load_model"][0] == "film"
    (run,) = SD.spin_down_runs(sc, 0.01, [3000.0], n_table=24)
    assert run["T0_Nm"] == pytest.approx(float(scene_losses(sc, models=models).torque_Nm), rel=1e-9)
    assert np.isfinite(run["t_stop_s"]) and 0.0 < run["n"] < 1.0


def _cli_spin_down(tmp_path, capsys, text, *extra):
    log = tmp_path / "sd.csv"
    log.write_text(text, encoding="utf-8")
    code = main(["spin-down", tb.example_path("seed001_spin_down_3ball.toml"), "--J", "1e-4", "--log", str(log), *extra])
    return code, *capsys.readouterr()


def test_cli_spin_down_log_with_an_empty_torque_cell(tmp_path, capsys):
    """An empty torque cell (not measured) printed 'nan   +nan%' in the table; it prints '-' (JSON: null)."""
    text = "n_rpm,Fa_N,torque_Nm\n60,0.375,1.3947e-04\n90,0.375,\n"
    code, out, err = _cli_spin_down(tmp_path, capsys, text)
    assert code == 0 and "nan" not in out.lower()
    row = next(ln for ln in out.splitlines() if ln.split() and ln.split()[0] == "90")
    assert row.split()[-2:] == ["-", "-"]
    row = next(ln for ln in out.splitlines() if ln.split() and ln.split()[0] == "60")
    assert row.split()[-2] == "1.3947e-04" and row.endswith("%")
    code, out, err = _cli_spin_down(tmp_path, capsys, text, "--json")
    runs = json.loads(out)["runs"]
    assert code == 0 and runs[1]["T_log_Nm"] is None and runs[1]["T_error"] is None and runs[0]["T_log_Nm"] > 0


def test_cli_spin_down_log_refuses_a_lubricant_column(tmp_path, capsys):
    """A lubricant per row was silently ignored (rows naming different greases gave identical answers): a
    spin-down runs the scene's lubricant, so the column is refused, naming it (exit 2, nothing printed)."""
    text = "n_rpm,Fa_N,torque_Nm,lubricant\n60,0.375,1.39e-04,seed002-mg1\n90,0.375,1.64e-04,seed002-pg2\n"
    code, out, err = _cli_spin_down(tmp_path, capsys, text)
    assert code == 2 and out == ""
    assert err.startswith("error: sd.csv: column = 'lubricant' — a spin-down log runs the scene's lubricant")
    assert len(err.splitlines()) == 1
    code, out, err = _cli_spin_down(tmp_path, capsys, "n_rpm,Fr_N,torque_Nm\n60,5,1.39e-04\n")   # Fr_N as Fa_N
    assert code == 2 and "its Fr_N differs from the scene's Fr = 0 N" in err
