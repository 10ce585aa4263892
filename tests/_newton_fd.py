"""Shared check: a solver's Newton direction against central finite differences of its residual."""
import numpy as np


def assert_newton_matches_fd(pb, x, g, rtol=1e-5):
    """The high-speed problem ``pb``'s Newton step at scaled unknowns (x, g) equals −J⁻¹ r with J from
    central differences of ``pb.state`` (held globals fixed), to ``rtol`` of the largest component."""
    Z = pb.Z

    def res(z):
        st = pb.state(z[:2 * Z].reshape(1, Z, 2), z[2 * Z:].reshape(1, 3))
        return np.concatenate([st.r_b[0].ravel(), st.r_g[0] * pb.free_g[0]])

    z0 = np.concatenate([x[0].ravel(), g[0]])
    J = np.zeros((z0.size, z0.size))
    for k in range(z0.size):
        h = 1e-7 * max(abs(z0[k]), 1e-3)
        zp, zm = z0.copy(), z0.copy()
        zp[k] += h
        zm[k] -= h
        J[:, k] = (res(zp) - res(zm)) / (2 * h)
    held = np.flatnonzero(pb.free_g[0] == 0) + 2 * Z
    J[held, :] = 0.0
    J[:, held] = 0.0
    J[held, held] = 1.0
    d_fd = np.linalg.solve(J, -res(z0))
    dx, dg = pb.newton_step(pb.state(x, g))
    d = np.concatenate([dx[0].ravel(), dg[0]])
    assert np.max(np.abs(d - d_fd)) <= rtol * np.max(np.abs(d_fd))
