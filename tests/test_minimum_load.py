"""SKF's requisite minimum load of deep groove ball bearings (thermobear.rating.minimum_load): the equation against
SKF's worked example, its scaling, the series' factors as the product tables give them, and the warning a scene gets
below it (a load typed in kN as N passed without a word)."""
from __future__ import annotations

import warnings

import numpy as np
import pytest

import thermobear as tb
from thermobear.coupled import solve
from thermobear.rating.minimum_load import minimum_load_factor, minimum_radial_load


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
    F_rm = float(minimum_radial_load(0.03, s.lubricant.nu(20.0), 1500.0, s.bearing.dm))
    assert F_rm == pytest.approx(1659.0, rel=2e-3)
    assert bool(got) is warned
    if warned:
        assert f"against F_rm {F_rm:.4g} N" in got[0] and f"{max(Fr, Fa) / F_rm:.4g}" in got[0]
