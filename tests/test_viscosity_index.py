"""ASTM D2270 viscosity index (thermobear.lubrication.viscosity_index): the standard's worked examples, its inverse,
continuity where Procedure A meets B and the table meets the formulas, and the sampled grade tolerance of an ISO VG
oil keeping the viscosity index its ν100 range was derived for."""
from __future__ import annotations

import numpy as np
import pytest

import thermobear as tb
from thermobear.lubrication.viscosity_index import astm_d2270_LH, nu100_from_vi, viscosity_index


def test_astm_d2270_worked_examples():
    """Procedure A: ν40 73.30 / ν100 8.86 mm²/s → L 119.94, H 69.48, VI 92.43; Procedure B: 22.83 / 5.05 → VI 156."""
    L, H = astm_d2270_LH(8.86)
    assert (float(L), float(H)) == (pytest.approx(119.94, abs=0.005), pytest.approx(69.48, abs=0.005))
    assert float(viscosity_index(73.30, 8.86)) == pytest.approx(92.43, abs=0.01)
    assert float(viscosity_index(22.83, 5.05)) == pytest.approx(156.0, abs=0.5)


def test_inverse_and_continuity():
    U = np.array([10.0, 32.0, 46.0, 100.0, 460.0])
    for vi in (80.0, 100.0, 140.0):
        np.testing.assert_allclose(viscosity_index(U, nu100_from_vi(U, vi)), vi, atol=1e-6)
    assert float(nu100_from_vi(40.0, 100.0)) == pytest.approx(6.185, abs=0.002)      # mol-liton-00's estimate
    Y = 8.0                                                  # Procedures A and B meet at U = H (VI 100)
    H = float(astm_d2270_LH(Y)[1])
    assert float(viscosity_index(H * (1 + 1e-9), Y)) == pytest.approx(100.0, abs=1e-5)
    assert float(viscosity_index(H * (1 - 1e-9), Y)) == pytest.approx(100.0, abs=1e-5)
    L70, H70 = (float(v) for v in astm_d2270_LH(70.0))   # the table's end against the formulas above it
    L_, H_ = (float(v) for v in astm_d2270_LH(70.0 + 1e-9))
    assert L_ == pytest.approx(L70, rel=2e-3) and H_ == pytest.approx(H70, rel=2e-3)
    with pytest.raises(tb.InputError, match="nu100_cSt"):
        astm_d2270_LH(1.0)


@pytest.mark.parametrize("name", ["iso-vg-10-mineral", "iso-vg-46-mineral", "iso-vg-46-pao", "iso-vg-460-mineral"])
def test_a_sampled_grade_tolerance_keeps_the_viscosity_index(name):
    """ISO 3448's ±10 % on ν40, drawn with ν100's range (set by the viscosity index of the family at the nominal
    ν40): the sampled oils keep viscosity indices inside that range (drawn apart, VG 46 mineral spanned 60–141 for
    the sources' 80–120), and an oil at the grade's upper end is more viscous at every temperature."""
    oil = tb.lubricant(name)
    u40, u100 = oil.uncertainty["nu40_cSt"], oil.uncertainty["nu100_cSt"]
    vi_lo, vi_hi = (float(viscosity_index(oil.table["nu40_cSt"], y)) for y in (u100.lo, u100.hi))
    f = np.array([u40.lo, u40.lo, u40.hi, u40.hi])
    y = np.array([u100.lo, u100.hi, u100.lo, u100.hi])
    s = oil.sampled({"nu40_cSt": f, "nu100_cSt": y})
    vi = np.asarray(viscosity_index(s.table["nu40_cSt"], s.table["nu100_cSt"]))
    assert np.all(vi >= min(vi_lo, vi_hi) - 1e-6) and np.all(vi <= max(vi_lo, vi_hi) + 1e-6)
    nominal = oil.sampled({"nu40_cSt": np.array([u40.lo, 1.0, u40.hi])})
    T = np.array([[0.0], [40.0], [100.0]])
    nu = np.asarray(nominal.nu(np.broadcast_to(T, (3, 3))))
    assert np.all(np.diff(nu, axis=1) > 0)                                 # higher ν40 factor: more viscous at each T
    assert nu[1, 1] == pytest.approx(oil.nu(40.0), rel=1e-9)
