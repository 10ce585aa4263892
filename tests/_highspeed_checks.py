"""Checks shared by the high-speed load-distribution tests (dry and film contact laws)."""
from __future__ import annotations

import numpy as np


def assert_ball_centres(brg, ld, ex):
    """Each ball centre lies on both contact normals, at the (signed) approaches δ_i, δ_o the solver
    returns: C − O_o = ((f_o − ½)D + δ_o)(sin α_o, cos α_o), O_i − C = ((f_i − ½)D + δ_i)(sin α_i, cos α_i)
    (loads_highspeed module docstring)."""
    D, c, R = brg.D, np.cos(ld.psi), brg.R_inner_locus
    ai, ao = ld.alpha_i, ld.alpha_o
    assert np.allclose(ex.X1, ((brg.fo - 0.5) * D + ex.delta_o) * np.sin(ao), rtol=1e-12, atol=1e-15)
    assert np.allclose(ex.X2, ((brg.fo - 0.5) * D + ex.delta_o) * np.cos(ao), rtol=1e-12, atol=1e-15)
    A1 = ld.delta_a + R * ld.theta * c
    A2 = brg.A * np.cos(brg.alpha0) + ld.delta_r * c
    assert np.allclose(A1 - ex.X1, ((brg.fi - 0.5) * D + ex.delta_i) * np.sin(ai), rtol=1e-10, atol=1e-15)
    assert np.allclose(A2 - ex.X2, ((brg.fi - 0.5) * D + ex.delta_i) * np.cos(ai), rtol=1e-10, atol=1e-15)
