"""``thermobear loads`` (issue 16 item 7): it names the solution (static or high-speed), splits the axial
displacement into the free travel through the clearance and the elastic approach, refuses an overload as bad
input (exit 2, one line), and draws the ball loads around the bearing with --plot."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import thermobear as tb
from thermobear.app.cli import main

EX = Path(__file__).resolve().parents[1] / "examples"
SEED004 = str(EX / "seed004_oil_jet_7210.toml")


def run(capsys, *argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.mark.parametrize("n_rpm, form", [(3200.0, "high-speed"), (300.0, "static")])
def test_the_verb_names_its_solution_and_splits_the_axial_displacement(capsys, n_rpm, form):
    code, out, _ = run(capsys, "loads", SEED004, "--set", f"n_rpm={n_rpm}", "--json")
    d = json.loads(out)
    assert code == 0 and d["form"].startswith(form) and d["high_speed"] == (form == "high-speed")
    b = tb.bearing("7210")
    assert d["delta_a_free_um"] == pytest.approx(b.A * np.sin(b.alpha0) * 1e6, rel=1e-12)
    assert d["delta_a_free_um"] + d["delta_a_elastic_um"] == pytest.approx(d["delta_a_um"], rel=1e-12)
    assert d["delta_z_um"] == 0.0 and d["theta_y_mrad"] == 0.0
    code, text, _ = run(capsys, "loads", SEED004, "--set", f"n_rpm={n_rpm}")
    assert f"{form} solution" in text and "rigid-body travel to first contact" in text


def test_static_elastic_part_is_the_pure_axial_approach(capsys):
    """Pure axial load, low speed: the elastic part is the closed form A cos α0 (tan α − tan α0) of the
    load distribution's contact angle (Harris 2001 eq 7.36)."""
    code, out, _ = run(capsys, "loads", SEED004, "--set", "n_rpm=100", "--set", "Fr=0", "--json")
    d = json.loads(out)
    b = tb.bearing("7210")
    al = np.radians(d["alpha_inner_deg"][0])
    assert d["delta_a_elastic_um"] == pytest.approx(b.A * np.cos(b.alpha0) * (np.tan(al) - np.tan(b.alpha0)) * 1e6,
                                                    rel=1e-9)


def test_an_overload_is_bad_input_naming_the_loads(capsys):
    code, out, err = run(capsys, "loads", SEED004, "--set", "Fa=2e6", "--set", "n_rpm=100")
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1
    assert "Fa 2e+06 N" in err and "static safety s0" in err and "C0 = " in err and "Traceback" not in err


def test_plot_of_the_ball_loads(capsys, tmp_path):
    pytest.importorskip("matplotlib")
    code, out, _ = run(capsys, "loads", SEED004, "--plot", tmp_path / "p")
    assert code == 0 and (tmp_path / "p" / "load_distribution.png").is_file()
    from thermobear.app.plots import plot_load_distribution
    ld = tb.load_distribution(tb.bearing("6208"), Fa=300.0, Fr=1500.0, Fz=-900.0)
    assert Path(plot_load_distribution(ld, tmp_path / "q" / "ld.png")).is_file()


def test_loads_take_the_mounted_clearance_of_stated_fits(capsys):
    """`loads` with p6 / N7 fits and models.clearance = mounted showed the unmounted bearing (3 of 9 balls loaded)
    while `run` preloaded every ball: the loads are now at the fits' clearance at 20 °C, and the output says so."""
    import json
    from thermobear.app.cli import main
    import thermobear as tb
    path = tb.example_path("block_6208_oil_jet.toml")
    fits = ["--set", "bearing.shaft_fit=p6", "--set", "bearing.housing_fit=N7"]
    assert main(["loads", path, "--json", *fits, "--set", "models.clearance=mounted"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert min(d["Q_inner_N"]) > 0 and "the loads at the mounted clearance -36.5 µm" in d["note"]
    assert "film load model" not in d["note"]     # its model choice at that clearance: no ball lifts off
    assert main(["loads", path, "--json"]) == 0
    assert min(json.loads(capsys.readouterr().out)["Q_inner_N"]) == 0
