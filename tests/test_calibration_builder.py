"""calibrate on a machine built from its dimensions (a scene of ``thermobear init``): the builders' estimates
it reads (``builder.<key>``: the mounting joint, the emissivity, …) are parameters of the fit.  Before, such a
scene offered only the values of its ~400 cells and elements (areas, volumes, one cell's conductance), none of
them a machine's unknown."""
from __future__ import annotations

import dataclasses

import pytest

import thermobear as tb
from thermobear.app.calibration import calibrate, parameter_names
from thermobear.app.cli import main
from thermobear.app.rig import channel_map, read_log
from thermobear.thermal.builders import build_network, estimates

BATH = tb.example_path("block_6208_oil_bath.toml")


def test_a_built_machine_offers_its_builders_estimates_first():
    s = tb.load_scene(BATH)
    names = parameter_names(s)
    keys = ["builder." + k for k in estimates.sampled_keys(s.network)]
    assert "builder.R_mount_m2K_W" in keys and names[:len(keys)] == keys
    assert not any(n.startswith("builder.") for n in parameter_names(tb.load_scene(tb.example_path(
        "seed004_oil_jet_7210.toml"))))                   # a network file has no builder


def test_calibration_recovers_a_mounting_joint_from_model_made_ring_temperatures(tmp_path):
    """Outer-ring and shaft temperatures made by the model with the mounting joint's resistance at 3× the
    builders' estimate: the fit from the estimate finds 3× back (to the solver's tolerance)."""
    s = tb.load_scene(BATH)
    R0 = estimates.machine_value(s.network, "R_mount_m2K_W")
    cells = {k: g.n for k, g in build_network(s.network).segments.items()}
    truth = dataclasses.replace(s, network=estimates.drawn(s.network, {"R_mount_m2K_W": 3.0 * R0}, cells))
    rows = []
    for n in (1500.0, 3000.0, 4500.0):
        st = tb.steady_state(truth.with_(n_rpm=n))
        rows.append(f"{n:g},{st.T_C['outer_ring']:.4f},{st.T_C['shaft']:.4f}")
    log_path = tmp_path / "rig.csv"
    log_path.write_text("n_rpm,T_outer_C,T_shaft_C\n" + "\n".join(rows) + "\n", encoding="utf-8")
    log = read_log(log_path)
    mapping = channel_map(s, log, {"T_outer_C": "outer_ring", "T_shaft_C": "shaft"})
    cal = calibrate(s, log, ["builder.R_mount_m2K_W"], mapping)
    assert cal.start["builder.R_mount_m2K_W"] == pytest.approx(R0)
    assert cal.values["builder.R_mount_m2K_W"] == pytest.approx(3.0 * R0, rel=1e-3)
    assert cal.rms_residual < 1e-3
    assert main(["calibrate", BATH, str(log_path), "--map", "T_outer_C=outer_ring", "--map", "T_shaft_C=shaft",
                 "--param", "builder.emissivity", "--json"]) == 0


def test_calibrate_help_spells_the_parameters_as_calibrate_accepts_them(capsys):
    with pytest.raises(SystemExit):
        main(["calibrate", "--help"])
    helptext = " ".join(capsys.readouterr().out.split())
    assert "skf_R1" in helptext and "skf.R1" not in helptext and "builder.R_mount_m2K_W" in helptext


def test_a_fit_outside_the_range_the_scene_states_is_named(tmp_path):
    """Ring temperatures made with the mounting joint at 10× the builders' estimate, whose stated range is a factor
    3 either way (5–95 %): the fit finds 10× back, and its message says the value lies outside the stated range
    (a fit that lands far outside what the scene holds likely was reported as plainly as one inside it)."""
    s = tb.load_scene(BATH)
    R0 = estimates.machine_value(s.network, "R_mount_m2K_W")
    cells = {k: g.n for k, g in build_network(s.network).segments.items()}
    truth = dataclasses.replace(s, network=estimates.drawn(s.network, {"R_mount_m2K_W": 10.0 * R0}, cells))
    rows = []
    for n in (1500.0, 4500.0):
        st = tb.steady_state(truth.with_(n_rpm=n))
        rows.append(f"{n:g},{st.T_C['outer_ring']:.4f},{st.T_C['shaft']:.4f}")
    log_path = tmp_path / "rig.csv"
    log_path.write_text("n_rpm,T_outer_C,T_shaft_C\n" + "\n".join(rows) + "\n", encoding="utf-8")
    log = read_log(log_path)
    cal = calibrate(s, log, ["builder.R_mount_m2K_W"], channel_map(s, log, {"T_outer_C": "outer_ring",
                                                                            "T_shaft_C": "shaft"}))
    assert cal.values["builder.R_mount_m2K_W"] == pytest.approx(10.0 * R0, rel=1e-3)
    u = estimates.uncertainty()["R_mount_m2K_W"]
    assert u.kind == "factor" and u.hi < 10.0
    assert (f"builder.R_mount_m2K_W = {10.0 * R0:.3g} lies outside the range the scene states for it, "
            f"{u.lo * R0:.3g} … {u.hi * R0:.3g}") in cal.message
    assert "not determined" not in cal.message                 # determined: model-made, noiseless temperatures
