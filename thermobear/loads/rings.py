r"""Rigid rings: the loads on the inner ring, the positions of the groove curvature centres, the result.

Shared by the three forms of the load distribution.  Ball j sits at the azimuth ψ_j = 2πj/Z
(ψ = 0 in the direction of the radial load).  The inner ring is displaced from the centred
position by δa (axial), δr (radial, towards ψ = 0) and tilted by θ; the inner groove curvature
centre of ball j is then offset from the outer one by (Jones 1960 [1]; Harris 2001 [2] ch. 7;
ISO/TS 16281 [3], rigid rings)

.. math::

    A_{1j} = δ_a + ℜ_i θ \cos ψ_j, \qquad A_{2j} = A \cos α_0 + δ_r \cos ψ_j

(axial, radial), A = (f_i + f_o − 1) D the unloaded distance of the groove centres, α0 the free
contact angle and ℜ_i the radius of the locus of inner groove centres (the arm conjugate to θ).
The map is linear in the scaled ring unknowns g = (δa/A, δr/A, θℜ_i/A): (A1, A2) = A0 + g·L with
the lever matrix L (:func:`lever_matrix`), and by virtual work the inner ring's equilibrium sums
the ball forces with the same matrix, (F_a, F_r, M/ℜ_i) = Σ_j L_j f_j.  A second radial plane
(δz, θy: five ring unknowns) adds two rows to L and the out-of-plane force components; every form
takes the map from here.

References
----------
.. [1] Jones, A. B. (1960). A general theory for elastically constrained ball and radial roller
   bearings under arbitrary load and speed conditions. *J. Basic Eng.* 82(2):309–320.
.. [2] Harris, T. A. (2001). *Rolling Bearing Analysis*, 4th ed., Wiley, ch. 7.
.. [3] ISO/TS 16281:2008. Rolling bearings — Methods for calculating the modified reference
   rating life for universally loaded bearings.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermobear.contact.geometry import BallBearing
from thermobear.errors import InputError, NoEquilibrium

__all__ = ["LoadDistribution", "STIFFNESS_MODES", "check_stiffness", "batch_loads", "lever_matrix", "azimuths",
           "unbatch"]

STIFFNESS_MODES = ("nominal", "per_ball")


@dataclass(frozen=True)
class LoadDistribution:
    """Result of a quasi-static load distribution (every form).

    Scalars (or arrays with a leading batch axis when the loads are arrays).

    Attributes
    ----------
    delta_a, delta_r : inner-ring axial / radial displacement from the centred position [m]
    theta : tilt [rad] (0 when held)
    Q_i, Q_o : ball–inner / ball–outer contact loads, per ball [N] (equal in the low-speed form)
    alpha_i, alpha_o : contact angles per ball [rad]
    psi : ball azimuths [rad], shape (Z,)
    delta_n : total elastic approach per ball [m]
    residual : max relative equilibrium residual [-]
    iterations : Newton iterations used (the largest over the batch, continuation included)
    Fa, Fr, M : the applied loads [N], [N], [N m]
    """

    delta_a: np.ndarray
    delta_r: np.ndarray
    theta: np.ndarray
    Q_i: np.ndarray
    Q_o: np.ndarray
    alpha_i: np.ndarray
    alpha_o: np.ndarray
    psi: np.ndarray
    delta_n: np.ndarray
    residual: float
    iterations: int
    Fa: np.ndarray
    Fr: np.ndarray
    M: np.ndarray

    @property
    def Q(self):
        """Ball load [N] (= Q_i = Q_o in the low-speed form)."""
        return self.Q_i

    @property
    def loaded(self):
        """Boolean mask of balls in contact."""
        return self.Q_i > 0


def check_stiffness(stiffness):
    """InputError unless ``stiffness`` is one of :data:`STIFFNESS_MODES`."""
    if stiffness not in STIFFNESS_MODES:
        raise InputError("stiffness", stiffness, f"must be one of {', '.join(STIFFNESS_MODES)}")


def _bad(v):
    """Any load negative or not finite (NaN fails both comparisons)."""
    return v.size > 0 and not (v.min() >= 0.0 and v.max() < np.inf)


def _check_loads(brg, Fa, Fr, M):
    for nm, v in (("Fa", Fa), ("Fr", Fr)):
        if _bad(v):
            raise InputError(nm, v, "load must be finite and >= 0 [N] (Fa pushes the inner ring along +x; "
                             "Fr acts at psi = 0)")
    if M is not None and M.size and not np.isfinite(M).all():
        raise InputError("M", M, "moment must be finite [N m]")
    if brg.kind == "thrust" and np.any(Fr > 0):
        raise NoEquilibrium(
            f"a thrust ball bearing carries no radial load (its washers are not radially located): Fr = "
            f"{np.max(Fr):g} N; carry Fr with a radial bearing")
    if brg.kind == "thrust" and np.any((Fa <= 0) & ((np.abs(M) if M is not None else 0) > 0)):
        raise NoEquilibrium("a thrust ball bearing cannot carry a moment without an axial load (balls would lift off)")
    if brg.kind == "angular_contact" and np.any((Fa <= 0) & (Fr > 0)):
        raise NoEquilibrium(
            "a single angular contact bearing under radial load needs an axial load to hold it against its "
            f"shoulder (Fa = 0, Fr = {np.max(Fr):g} N): give the axial reaction or preload of the arrangement")


def batch_loads(brg: BallBearing, Fa, Fr, M, *extra):
    """Loads (and ``extra`` per-case inputs, e.g. a speed) broadcast to one batch axis and checked.

    Returns (shape, Fa, Fr, M or None, M or 0, *extra), each flat (nb,) [N, N m]; raises InputError for
    negative or non-finite loads and NoEquilibrium for loads the bearing cannot carry at all."""
    Fa_in, Fr_in = np.asarray(Fa, dtype=float), np.asarray(Fr, dtype=float)
    M_in = None if M is None else np.asarray(M, dtype=float)
    ex = [np.asarray(v, dtype=float) for v in extra]
    shape = np.broadcast_shapes(Fa_in.shape, Fr_in.shape, () if M_in is None else M_in.shape, *(v.shape for v in ex))
    Fa_b = np.broadcast_to(Fa_in, shape).ravel()
    Fr_b = np.broadcast_to(Fr_in, shape).ravel()
    M_b = None if M_in is None else np.broadcast_to(M_in, shape).ravel()
    _check_loads(brg, Fa_b, Fr_b, M_b)
    ex_b = [np.broadcast_to(v, shape).ravel() for v in ex]
    return (shape, Fa_b, Fr_b, M_b, M_b if M_b is not None else np.zeros(Fa_b.size), *ex_b)


def azimuths(Z: int):
    """Ball azimuths ψ_j = 2πj/Z [rad], j = 0 … Z − 1."""
    return 2.0 * np.pi * np.arange(Z) / Z


def lever_matrix(brg: BallBearing):
    """The lever matrix L (3, 2Z) of the groove-centre map [m]: row k holds ∂A1_j/∂g_k (first Z
    columns) and ∂A2_j/∂g_k (last Z) for g = (δa/A, δr/A, θℜ_i/A), i.e. A (1, 0), A (0, cos ψ_j),
    A (cos ψ_j, 0).  Its transpose, divided by A, sums per-ball forces (f_a | f_r) into the ring loads
    (F_a, F_r, M/ℜ_i)."""
    Z, A = brg.Z, brg.A
    c = np.cos(azimuths(Z))
    L = np.zeros((3, 2 * Z))
    L[0, :Z] = A
    L[1, Z:] = A * c
    L[2, :Z] = A * c
    return L


def unbatch(shape, v, per_ball: bool = False):
    """A flat batch (nb,) or (nb, Z) back to the loads' shape (a float / (Z,) array for scalar loads)."""
    if shape:
        return v.reshape(shape + v.shape[1:]) if per_ball else v.reshape(shape)
    return v[0] if per_ball else float(v[0])
