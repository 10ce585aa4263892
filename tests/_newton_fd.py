"""Shared check: a solver's Newton direction against central finite differences of its residual."""
import numpy as np


def assert_newton_matches_fd(pb, z, rtol=1e-5):
    """The problem ``pb``'s Newton direction at the unknowns z (1, n) equals −J⁻¹ r with J from central
    differences of ``pb.evaluate`` (held unknowns — rows of ``pb.mask`` that are 0 — fixed), to ``rtol``
    of the largest component.  Works for every problem of thermobear.loads.newton with a ``mask``."""
    mask = pb.mask[0]

    def res(v):
        return pb.evaluate(v[None]).res[0] * mask

    z0 = np.asarray(z, dtype=float)[0]
    J = np.zeros((z0.size, z0.size))
    for k in range(z0.size):
        h = 1e-7 * max(abs(z0[k]), 1e-3)
        zp, zm = z0.copy(), z0.copy()
        zp[k] += h
        zm[k] -= h
        J[:, k] = (res(zp) - res(zm)) / (2 * h)
    held = np.flatnonzero(mask == 0)
    J[held, :] = 0.0
    J[:, held] = 0.0
    J[held, held] = 1.0
    d_fd = np.linalg.solve(J, -res(z0))
    d = pb.direction(pb.evaluate(z0[None]))[0]
    assert np.max(np.abs(d - d_fd)) <= rtol * np.max(np.abs(d_fd))
