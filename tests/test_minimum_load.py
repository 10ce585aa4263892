"""SKF's requisite minimum load (thermobear.rating.minimum_load): of deep groove ball bearings, the equation against
SKF's worked example, its scaling, the series' factors as the product tables give them, and the warning a scene gets
below it (a load typed in kN as N passed without a word); of angular contact and thrust ball bearings, the minimum
axial load factors A as SKF's tables print them (validation/minimum_load.py), F_am ∝ n², and the warning below it."""
from __future__ import annotations

import csv
import importlib.util
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import thermobear as tb
from thermobear.coupled import solve
from thermobear.rating.minimum_load import (minimum_axial_load, minimum_axial_load_factor, minimum_load_factor,
                                            minimum_radial_load)

ROOT = Path(__file__).resolve().parents[1]


def test_skf_worked_example_and_scaling():
    # SKF 2018 section C.2 (rope sheave): 6207, k_r 0.025, ν 210 mm²/s, d_m 53.5 mm, 2450 r/min: printed 0.44 kN,
    # its equation 0.459 kN (the implementation is the equation; 4 % above the printed value)
    F = float(minimum_radial_load(0.025, 210.0, 2450.0, 0.0535))
    assert F == pytest.approx(1e3 * 0.025 * (210.0 * 2450.0 / 1000.0) ** (2 / 3) * 0.535 ** 2, rel=1e-12)
    assert F == pytest.approx(440.0, rel=0.05)
    nu, n = np.array([10.0, 80.0]), np.array([1000.0, 8000.0])
    ratio = minimum_radial_load(0.025, nu, 3000.0, 0.06) / minimum_radial_load(0.025, 10.0, 3000.0, 0.06)
    np.testing.assert_allclose(ratio, (nu / 10.0) ** (2 / 3), rtol=1e-12)            # ∝ (ν n)^(2/3)
    np.testing.assert_allclose(minimum_radial_load(0.025, 30.0, n, 0.06) / minimum_radial_load(0.025, 30.0, 1000.0, 0.06),
                               (n / 1000.0) ** (2 / 3), rtol=1e-12)
    assert minimum_radial_load(0.03, 30.0, 2000.0, 0.08) / minimum_radial_load(0.03, 30.0, 2000.0, 0.04) == pytest.approx(4.0)
    assert float(minimum_radial_load(0.025, 30.0, 0.0, 0.06)) == 0.0                  # at rest: no skidding


def test_minimum_load_factors_of_the_product_tables():
    got = {s: minimum_load_factor("deep_groove", s) for s in ("618", "619", "160", "60", "62", "63")}
    assert got == {"618": 0.015, "619": 0.02, "160": 0.02, "60": 0.025, "62": 0.025, "63": 0.03}
    assert minimum_load_factor("deep_groove", "64") is None                  # not read: no factor, no warning
    assert minimum_load_factor("thrust", "511") is None
    assert tb.bearing("6310").series == "63" and tb.bearing("6208").series == "62"


def _warned(scene):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = solve(scene)
    return [str(w) for w in r.ratings.warnings if "minimum load" in str(w)], r


@pytest.mark.parametrize("Fr, Fa, warned", [(8.0, 0.0, True), (800.0, 0.0, True), (8000.0, 0.0, False),
                                             (8.0, 2000.0, False)])
def test_a_scene_below_the_minimum_load_is_warned(Fr, Fa, warned):
    """6310 in ISO VG 150 at 1500 rpm, 20 °C (535 mm²/s): F_rm = 1.66 kN.  8 N (8 kN typed in kN) and 800 N are
    below it, 8 kN is not; an axial load above it meets it (SKF: 'consider preloading')."""
    s = tb.load_scene(tb.example_path("oil_bath_6208.toml")).with_(bearing="6310", lubricant="iso-vg-150-mineral",
                                                                    n_rpm=1500.0, Fr=Fr, Fa=Fa, T_C=20.0)
    got, r = _warned(s)
    F_rm = float(minimum_radial_load(0.03, s.lubricant.nu(20.0), 1500.0, 0.5 * (0.050 + 0.110)))   # d_m = (d + D)/2
    assert F_rm == pytest.approx(1659.0, rel=2e-3)
    assert bool(got) is warned
    if warned:
        assert f"against F_rm {F_rm:.4g} N" in got[0] and f"{max(Fr, Fa) / F_rm:.4g}" in got[0]


# -- minimum axial load of angular contact and thrust ball bearings (SKF 2018 pp. 398, 469; tables 3.1, 5.1)

@pytest.mark.parametrize("bearing, A, row, line", [
    ("7210", 0.014, "7210 BECBP", 78880), ("7210 B", 0.014, "7210 BECBP", 78880),       # the seed's 7210 is a 7210 B
    ("7209B", 0.012, "7209 BECBP", 78656), ("7200B", 0.000224, "7200 BECBP", 75988),    # printed "0,000 224"
    ("7301B", 0.000537, "7301 BEP", 76035),                                              # no BECBP row: the steel cage
    ("7311B", 0.0574, "7311 BECBP", 79573), ("7320B", 0.63, "7320 BECBP", 82589),
    ("51208", 0.058, "51208", 94958), ("51107", 0.013, "51107", 94598), ("51320", 1.9, "51320", 95772)])
def test_minimum_axial_load_factors_are_the_tables_printed_values(bearing, A, row, line):
    """A of SKF 2018 tables 3.1 ("Calculation factors" page, the row's position) and 5.1, as printed at the line of
    the transcription (github.com/ArtemFilin1990/Mar Rolling_bearings_1.md, commit 68b9707)."""
    got = minimum_axial_load_factor(bearing)
    assert got is not None and got[:2] == (A, row) and f"A at line {line}," in got[2]
    assert minimum_axial_load_factor(tb.bearing(bearing)) == got                 # a scene's bearing: by its name


def test_the_cage_chosen_and_the_bearings_without_a_factor():
    """A differs by cage and variant in SKF's table (7209: 0.012 polyamide, 0.0128 BECBY, 0.00496 the 25° AC): the
    catalogue's 40° B takes the BECBP (else BEP) row.  No factor where SKF lists none, and none of deep groove."""
    with open(ROOT / "validation" / "data" / "minimum_load_skf2018.csv", encoding="utf-8") as f:
        rows = {r["designation"]: r for r in csv.DictReader(line for line in f if not line.startswith("#"))}
    assert [(rows[d]["A"], rows[d]["A_line"]) for d in ("7209 BECBP", "7209 BECBY", "7209 ACCBM")] == [
        ("0.012", "78656"), ("0.0128", "78704"), ("0.00496", "78720")]
    for name in ("7300B", "51205-3ball", "6208", "7014C", "71910E", "not-a-bearing"):
        assert minimum_axial_load_factor(name) is None, name
    assert minimum_load_factor("angular_contact", "72B") is None                 # (the radial factor k_r: deep groove)


def test_minimum_axial_load_scales_with_the_square_of_the_speed():
    n = np.array([500.0, 1000.0, 3200.0, 8070.0])
    F = minimum_axial_load(0.014, n)
    np.testing.assert_allclose(F, 1e3 * 0.014 * (n / 1000.0) ** 2, rtol=1e-12)      # A (n/1000)^2 kN, in N
    np.testing.assert_allclose(F / F[1], (n / 1000.0) ** 2, rtol=1e-12)
    assert float(minimum_axial_load(0.058, 2000.0)) == pytest.approx(232.0) and float(minimum_axial_load(0.014, 0.0)) == 0.0


@pytest.mark.parametrize("n_rpm, Fa, warned", [(8070.0, 450.0, True), (8070.0, 1000.0, False), (3200.0, 100.0, True),
                                               (3200.0, 450.0, False)])
def test_a_7210_scene_below_its_minimum_axial_load_is_warned(n_rpm, Fa, warned):
    """Seed 004's 7210 (A 0.014): F_am 143 N at 3200 rpm, 912 N at 8070 rpm — its 450 N preload meets the first, not
    the second (for a single bearing or a tandem pair; seed 004's block holds two)."""
    s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")).with_(Fa=Fa, n_rpm=n_rpm)
    got, r = _warned(s)
    F_am = float(minimum_axial_load(0.014, n_rpm))
    assert bool(got) is warned
    if warned:
        w = [w for w in r.ratings.warnings if w.quantity == "minimum_load"][0]
        assert w.value == pytest.approx(Fa / F_am) and f"Fa {Fa:.4g} N against F_am {F_am:.4g} N = A 0.014" in got[0]
        assert f"{n_rpm:.6g} rpm" in got[0] and "7210 BECBP: A at line 78880" in got[0] and "SKF 2018 p. 398" in got[0]


def test_a_thrust_scene_below_its_minimum_axial_load_is_warned():
    """Seed 002's 51107 (A 0.013): F_am 117 N at 3000 rpm; 50 N is below it, its own 7 kN far above."""
    s = tb.load_scene(tb.example_path("seed002_grease_thrust_51107.toml")).with_(n_rpm=3000.0)
    got, _ = _warned(s.with_(Fa=50.0))
    assert len(got) == 1 and "Fa 50 N against F_am 117 N = A 0.013" in got[0] and "SKF 2018 p. 469" in got[0]
    assert not _warned(s)[0]


def _generator():
    """validation/minimum_load.py as a module."""
    path = ROOT / "validation" / "minimum_load.py"
    spec = importlib.util.spec_from_file_location("minimum_load_script", path)
    mod = importlib.util.module_from_spec(spec)
    sys.path.insert(0, str(path.parent))
    try:
        spec.loader.exec_module(mod)
    finally:
        sys.path.remove(str(path.parent))
    return mod


def test_data_file_is_what_the_generator_writes_now():
    """materials/minimum_load.toml is the output of validation/minimum_load.py on the extracted rows: every catalogue
    72B / 73B and 511-513 designation but the two SKF does not list, each row's d x D x B (H) the catalogue's."""
    text, entries, notes = _generator().build()
    assert (ROOT / "materials" / "minimum_load.toml").read_text(encoding="utf-8") == text
    assert len(entries["angular_contact"]) == 41 and len(entries["thrust"]) == 55
    assert notes == ["7300B: no row in table 3.1", "51205-3ball: no row in table 5.1"]


def test_an_estimated_negative_clearance_does_not_silence_the_minimum_load():
    """The 6208 oil bath example runs with its clearance as given (13 µm) while the ratings estimate −10 µm at the
    answer's temperatures: 2 N (2 kN typed in kN) was not warned, the check skipping every negative estimate.  It is
    warned now, the estimated preload named beside; only loads solved with the preload (models.clearance =
    'operating') meet it, as SKF's 'consider preloading'."""
    s = tb.load_scene(tb.example_path("oil_bath_6208.toml")).with_(Fr=2.0)
    got, r = _warned(s)
    assert r.ratings.clearance_um["operating"] < 0 and len(got) == 1
    assert "the radial preload it implies may meet F_rm" in got[0]
    looped, _ = _warned(s.with_(models={**s.models, "clearance": "operating"}))
    assert not looped
