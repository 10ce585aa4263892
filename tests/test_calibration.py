"""thermobear.app.calibration: what a fit says besides its values — warnings of the answer only, and a torque
column it cannot weigh refused by name."""
from __future__ import annotations

import warnings
from pathlib import Path

import pytest

from thermobear.app.calibration import calibrate
from thermobear.app.rig import channel_map, read_log
from thermobear.errors import InputError, OutsideValidity
from thermobear.scene.scene import load_scene

LOGS = Path(__file__).resolve().parents[1] / "examples" / "logs"


def test_trial_values_warn_nothing_the_answer_does_not():
    """Started at G = 1e-6 W/K, the fit's first trials run the bearing at 190 °C (beyond the grease's range);
    the fitted G = 0.85 W/K does not: no warning (there were four, of the trials)."""
    scene = load_scene(LOGS / "synthetic_heatup_scene.toml")
    log = read_log(LOGS / "synthetic_heatup_7210.csv")
    with warnings.catch_warnings(record=True) as got:
        warnings.simplefilter("always")
        cal = calibrate(scene, log, ["bearing_to_ambient.G_W_K=1e-6"], channel_map(scene, log))
    assert cal.values["bearing_to_ambient.G_W_K"] == pytest.approx(0.85, rel=0.01)
    assert not [w for w in got if issubclass(w.category, (OutsideValidity, RuntimeWarning))]


def test_a_torque_column_of_zeros_is_refused_by_name(tmp_path):
    """Torque residuals are weighed in % of the mean torque: a column of zeros made that weight overflow and the
    fit end on 'models.skf_R1 = nan' after four RuntimeWarnings; it is refused naming the column."""
    scene = load_scene(LOGS / "seed002_skf_scene.toml")
    p = tmp_path / "zero.csv"
    p.write_text("n_rpm,torque_Nm,T_III_C\n1000,0,49.8\n2000,0,60\n", encoding="utf-8")
    log = read_log(p)
    with pytest.raises(InputError, match="^torque_Nm = 0.0 — a torque to fit must not be zero"):
        calibrate(scene, log, ["skf_R1"], channel_map(scene, log))


def test_a_parameter_the_models_do_not_read_is_refused_up_front(monkeypatch):
    """``--param mu_full_film`` under the Eyring traction ran 113 s to a 'singular Jacobian' (the models never read
    it): it is refused by name before any model evaluation, and not offered; under models.traction = "constant"
    it is offered.  mu_boundary on the SKF model likewise."""
    import thermobear.app.calibration as calmod
    from thermobear.app.calibration import parameter_names
    monkeypatch.setattr(calmod, "simulate_log", lambda *a, **k: pytest.fail("a model evaluation"))
    scene = load_scene(LOGS / "synthetic_heatup_scene.toml")
    log = read_log(LOGS / "synthetic_heatup_7210.csv")
    with pytest.raises(InputError, match=r"^--param = 'mu_full_film' — the scene's models do not read it.*"
                                         r'models\.traction = "eyring"'):
        calibrate(scene, log, ["mu_full_film"], channel_map(scene, log))
    assert "mu_full_film" not in parameter_names(scene) and "mu_boundary" in parameter_names(scene)
    assert "mu_full_film" in parameter_names(scene.with_(models={"traction": "constant"}))
    skf = load_scene(LOGS / "seed002_skf_scene.toml")
    with pytest.raises(InputError, match=r"^--param = 'mu_boundary' — the scene's models do not read it"):
        calibrate(skf, read_log(LOGS / "seed002_greases.csv"), ["mu_boundary"], {})


def test_a_fit_through_u_0_keeps_its_step_and_finds_the_minimum():
    """K_rs on the synthetic heat-up: the RMS residual falls steadily from SKF's grease 6e-8 (3.00 K) towards 0 (1.45 K
    at 1e-8, 1.33 K at 1e-9).  The fit's ln K_rs passed u = 0 on its first step, where scipy's relative step fell to
    ~1e-9 and the heat-up's tolerance noise made a false minimum at 2.2e-8 (1.72 K) with σ 3e-14.  Now the step is
    absolute in u: the fit goes down to the small values and its σ is of the size of the answer (K_rs undetermined
    near 0: the log does not need starvation); the noisy residuals are named."""
    import numpy as np
    scene = load_scene(LOGS / "synthetic_heatup_scene.toml")
    log = read_log(LOGS / "synthetic_heatup_7210.csv")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        cal = calibrate(scene, log, ["K_rs"], channel_map(scene, log))
    assert cal.rms_residual < 1.40 and cal.values["K_rs"] < 5e-9
    assert cal.std["K_rs"] > 0.1 * cal.values["K_rs"] and np.isfinite(cal.std["K_rs"])
    assert "not smooth" in cal.message and "K_rs runs towards 0" in cal.message


@pytest.mark.parametrize("start", ["0", "1e-6", "-1e-8"])
def test_a_k_rs_start_outside_its_open_range_is_refused_by_name(start):
    """K_rs=0 gave `K_rs = 0.000999…` (a trial value the user never gave: a linear step of 1 on a 3e-8 quantity)
    and 1e-6 stepped past the scene's bound: the start must lie in (0, 1e-6), named before any solve."""
    scene = load_scene(LOGS / "synthetic_heatup_scene.toml")
    log = read_log(LOGS / "synthetic_heatup_7210.csv")
    with pytest.raises(InputError, match=r"--param K_rs = .* start must lie in \(0, 1e-0?6\)"):
        calibrate(scene, log, [f"K_rs={start}"], channel_map(scene, log))


def test_a_zero_start_of_a_quantity_that_cannot_go_negative_is_refused_by_name():
    """An oil bath's flow of 0 L/h (its default) as the start: the fit stepped linearly to −1 L/h and stopped on
    `oil_flow_L_h = -1.0 — must be in [0, 100000]`, a value the user never gave.  A zero start of a quantity bounded
    at 0 (here μ_boundary of the grease scene, whose flow its models do not read) is refused up front, naming the
    parameter (it is fitted in logarithms: start > 0)."""
    scene = load_scene(LOGS / "synthetic_heatup_scene.toml")
    log = read_log(LOGS / "synthetic_heatup_7210.csv")
    with pytest.raises(InputError, match=r"--param mu_boundary = 0.0 — a start of 0 cannot be fitted"):
        calibrate(scene, log, ["mu_boundary=0"], channel_map(scene, log))
