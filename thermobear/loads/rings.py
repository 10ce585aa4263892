r"""Rigid rings: the loads on the inner ring, the positions of the groove curvature centres, the result.

Shared by the three forms of the load distribution.  Axes: x axial,
the direction in which F_a pushes the inner ring; y radial towards ψ = 0 (the direction of F_r); z radial
at ψ = 90°.  Ball j sits at the azimuth ψ_j = 2πj/Z.  The inner ring is displaced from the centred
position by δa (axial), δr (along y), δz (along z) and tilted by θ (in the x–y plane: the side at ψ = 0
moves towards +x, a rotation about −z) and θ_y (in the x–z plane: the side at ψ = 90° moves towards +x, a
right-handed rotation about +y).  The inner groove curvature centre of ball j is then offset from the
outer one by (Jones 1960 [1]; Harris 2001 [2] ch. 7; ISO/TS 16281 [3], rigid rings)

.. math::

    A_{1j} = δ_a + ℜ (θ \cos ψ_j + θ_y \sin ψ_j), \qquad
    A_{2j} = A_{r0} + δ_r \cos ψ_j + δ_z \sin ψ_j, \qquad A_{r0} = A − P_d/2

(axial, radial in the ball's own radial plane), A = (f_i + f_o − 1) D the unloaded distance of the
groove centres, A_r0 their radial distance with the rings centred (A cos α0 with a clearance P_d ≥ 0, α0 the
free contact angle; A − P_d/2 > A with a negative clearance, a radial preload that compresses every ball by
−P_d/2: :attr:`~thermobear.contact.geometry.BallBearing.A_r0`, Harris & Kotzalas 2007 [4] ch. 2) and ℜ the
tilt arm (:data:`TILT_ARMS`): by default the radius
ℜ_i = d_m/2 + (f_i − ½) D cos α0 of the locus of inner groove centres (exact for a rigid ring turning
about its centre, Harris 2001 §7.4), or the pitch radius d_m/2 (the convention the ISO/TS 16281
reference examples are computed with, :mod:`thermobear.rating.iso16281`).  The ring displacement across
the ball's plane (tangential) moves no groove centre to first order and is left out, as in [1–3].
The map is linear in the scaled ring unknowns

    g = (δa/A, δr/A, θℜ/A, δz/A, θ_yℜ/A):

(A1, A2) = A0 + g·L with the lever matrix L (:func:`lever_matrix`), and by virtual work the inner ring's
equilibrium sums the ball forces with the same matrix, (F_a, F_r, M/ℜ, F_z, M_y/ℜ) = Σ_j L_j f_j / A,
M [N m] the moment in the x–y plane (it loads the balls at ψ = 0 towards +x: M = −M_z) and M_y the
right-handed moment about +y.  The first three unknowns are the in-plane problem: loads with F_z = 0 and
M_y = 0 have a solution with δz = θ_y = 0 exactly (the balls lie symmetric about the x–y plane), so every
form solves the five-unknown problem restricted to its first three rows (``ndof = 3``) for them, and all
five otherwise — one formulation, one Newton (:mod:`thermobear.loads.newton`).

References
----------
.. [1] Jones, A. B. (1960). A general theory for elastically constrained ball and radial roller
   bearings under arbitrary load and speed conditions. *J. Basic Eng.* 82(2):309–320.
.. [2] Harris, T. A. (2001). *Rolling Bearing Analysis*, 4th ed., Wiley, ch. 7.
.. [3] ISO/TS 16281:2008. Rolling bearings — Methods for calculating the modified reference
   rating life for universally loaded bearings.
.. [4] Harris, T. A., Kotzalas, M. N. (2007), *Essential Concepts of Bearing Technology* (Rolling Bearing
   Analysis, 5th ed., vol. 1), CRC Press, ch. 2 (diametral clearance, free contact angle) and ch. 7
   (load distribution under radial load, δ_ψ = δ_r cos ψ − P_d/2).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermobear.contact.fits import clearance_preload
from thermobear.contact.geometry import BallBearing
from thermobear.errors import InputError, NoEquilibrium

__all__ = ["LoadDistribution", "STIFFNESS_MODES", "TILT_ARMS", "RingLoads", "check_stiffness", "ring_loads",
           "arm_length", "levers", "COMPONENT", "lever_matrix", "ring_sums", "azimuths", "unbatch", "ring_direction",
           "force_scale", "groove_offsets"]

STIFFNESS_MODES = ("nominal", "per_ball")
#: tilt arm ℜ of the groove-centre map: "groove" the inner groove-centre radius ℜ_i (Harris 2001 §7.4, default),
#: "pitch" the pitch radius d_m/2 (the convention of the ISO/TS 16281 reference examples)
TILT_ARMS = ("groove", "pitch")
_NAMES = ("Fa", "Fr", "M", "Fz", "My")


@dataclass(frozen=True)
class LoadDistribution:
    """Result of a quasi-static load distribution (every form).

    Scalars (or arrays with a leading batch axis when the loads are arrays).

    Attributes
    ----------
    delta_a, delta_r : inner-ring axial / radial (along y, ψ = 0) displacement from the centred position [m]
    theta : tilt in the x–y plane [rad] (0 when held)
    Q_i, Q_o : ball–inner / ball–outer contact loads, per ball [N] (equal in the low-speed form)
    alpha_i, alpha_o : contact angles per ball [rad]
    psi : ball azimuths [rad], shape (Z,)
    delta_n : total elastic approach per ball [m]
    residual : max relative equilibrium residual [-]
    iterations : Newton iterations used (the largest over the batch, continuation included)
    Fa, Fr, M : the applied loads [N], [N], [N m]
    delta_z : radial displacement along z (ψ = 90°) [m]
    theta_y : tilt in the x–z plane (right-handed about +y) [rad]
    Fz, My : the applied radial load along z [N] and moment about +y [N m]

    The axes and sign conventions are those of :mod:`thermobear.loads.rings`.
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
    delta_z: np.ndarray = 0.0
    theta_y: np.ndarray = 0.0
    Fz: np.ndarray = 0.0
    My: np.ndarray = 0.0

    @property
    def Q(self):
        """Ball load [N] (= Q_i = Q_o in the low-speed form)."""
        return self.Q_i

    @property
    def loaded(self):
        """Boolean mask of balls in contact."""
        return self.Q_i > 0

    @property
    def radial_displacement(self):
        """Magnitude of the radial displacement √(δr² + δz²) [m]."""
        return np.hypot(self.delta_r, self.delta_z)

    @property
    def tilt(self):
        """Magnitude of the tilt √(θ² + θ_y²) [rad] (the total misalignment of the inner ring)."""
        return np.hypot(self.theta, self.theta_y)


def check_stiffness(stiffness):
    """InputError unless ``stiffness`` is one of :data:`STIFFNESS_MODES`."""
    if stiffness not in STIFFNESS_MODES:
        raise InputError("stiffness", stiffness, f"must be one of {', '.join(STIFFNESS_MODES)}")


def arm_length(brg: BallBearing, arm: str = "groove") -> float:
    """The tilt arm ℜ [m] of :data:`TILT_ARMS` ``arm``: ℜ_i (``"groove"``) or d_m/2 (``"pitch"``).

    >>> from thermobear.contact.geometry import bearing
    >>> b = bearing("iso-dgbb")
    >>> round(arm_length(b) * 1e3, 3), round(arm_length(b, "pitch") * 1e3, 3)
    (21.98, 21.75)
    """
    if arm == "groove":
        return float(brg.R_inner_locus)
    if arm == "pitch":
        return 0.5 * float(brg.dm)
    raise InputError("tilt_arm", arm, f"must be one of {', '.join(TILT_ARMS)}")


@dataclass(frozen=True)
class RingLoads:
    """The loads of a batch of cases, flat and checked (:func:`ring_loads`).

    Attributes
    ----------
    shape : tuple          broadcast shape of the loads (the result's batch shape)
    F : ndarray (nb, 5)    (F_a, F_r, M, F_z, M_y) per case [N, N, N m, N, N m]
    tilt_free : bool       tilts free (a moment given); held at 0 otherwise
    ndof : int             ring unknowns solved: 3 (in-plane loads) or 5
    extra : tuple          the extra per-case inputs, flat (nb,)
    """

    shape: tuple
    F: np.ndarray
    tilt_free: bool
    ndof: int
    extra: tuple = ()

    @property
    def nb(self) -> int:
        return self.F.shape[0]

    @property
    def Fa(self):
        return self.F[:, 0]

    @property
    def Fr(self):
        return self.F[:, 1]

    @property
    def M(self):
        return self.F[:, 2]

    def applied(self, arm: float, factor: float = 1.0):
        """The loads (× ``factor``) as the ring rows: (F_a, F_r, M/ℜ, F_z, M_y/ℜ)[:ndof] (nb, ndof) [N]."""
        F = self.F[:, :self.ndof] if factor == 1.0 else factor * self.F[:, :self.ndof]
        return F / np.array([1.0, 1.0, arm, 1.0, arm])[:self.ndof]

    def free(self):
        """Which ring unknowns are solved (ndof,) (1.0) and which held at 0 (the tilts without a moment)."""
        f = np.ones(self.ndof)
        if not self.tilt_free:
            f[2::2] = 0.0                                   # θ and θ_y
        return f

    def case(self, k) -> str:
        """The loads of case ``k`` as text (for messages)."""
        parts = [f"Fa = {self.F[k, 0]:g} N", f"Fr = {self.F[k, 1]:g} N", f"M = {self.F[k, 2]:g} N m"]
        if self.ndof == 5:
            parts += [f"Fz = {self.F[k, 3]:g} N", f"My = {self.F[k, 4]:g} N m"]
        return ", ".join(parts)

    def rows(self, idx):
        """The cases ``idx`` (flat), as a RingLoads of shape (len(idx),)."""
        return RingLoads((len(idx),), self.F[idx], self.tilt_free, self.ndof, tuple(e[idx] for e in self.extra))

    def result_fields(self, Fa_in, Fr_in) -> dict:
        """The applied-load fields of a :class:`LoadDistribution` (Fa, Fr as given, M, Fz, My in the batch shape)."""
        return dict(Fa=np.asarray(Fa_in, dtype=float), Fr=np.asarray(Fr_in, dtype=float),
                    M=unbatch(self.shape, self.F[:, 2]), Fz=unbatch(self.shape, self.F[:, 3]),
                    My=unbatch(self.shape, self.F[:, 4]))


def _bad(v):
    """Any load negative or not finite (NaN fails both comparisons)."""
    return v.size > 0 and not (v.min() >= 0.0 and v.max() < np.inf)


def _check_loads(brg, F):
    Fa = F[:, 0]
    if _bad(Fa):
        raise InputError("Fa", Fa, "load must be finite and >= 0 [N] (Fa pushes the inner ring along +x)")
    if F.size and not np.isfinite(F.sum()):                    # (one reduction in the common case)
        k = next((k for k in (1, 2, 3, 4) if not np.isfinite(F[:, k]).all()), None)
        if k is not None:
            raise InputError(_NAMES[k], F[:, k], "must be finite [N] or [N m]")
    if brg.kind == "deep_groove":
        return
    Frad = np.hypot(F[:, 1], F[:, 3])
    Mabs = np.hypot(F[:, 2], F[:, 4])
    if brg.kind == "thrust" and np.any(Frad > 0):
        raise NoEquilibrium(
            f"a thrust ball bearing carries no radial load (its washers are not radially located): Fr = "
            f"{np.max(Frad):g} N; carry Fr with a radial bearing")
    if brg.kind == "thrust" and np.any((Fa <= 0) & (Mabs > 0)):
        raise NoEquilibrium("a thrust ball bearing cannot carry a moment without an axial load (balls would lift off)")
    if brg.kind == "angular_contact" and np.any((Fa <= 0) & (Frad > 0)):
        raise NoEquilibrium(
            "a single angular contact bearing under radial load needs an axial load to hold it against its "
            f"shoulder (Fa = 0, Fr = {np.max(Frad):g} N): give the axial reaction or preload of the arrangement")


def ring_loads(brg: BallBearing, Fa, Fr, M, Fz=0.0, My=None, extra=()) -> RingLoads:
    """Loads (and ``extra`` per-case inputs, e.g. a speed) broadcast to one batch axis and checked.

    ``M`` and ``My`` ``None``: the tilts are held at 0; either given: both tilts free (the other moment 0).
    Raises InputError for a negative axial or a non-finite load and NoEquilibrium for loads the bearing cannot
    carry at all.  Five ring unknowns are solved when F_z or M_y is not 0 in some case, three otherwise."""
    raw = (Fa, Fr, 0.0 if M is None else M, Fz, 0.0 if My is None else My)
    if not extra and all(isinstance(v, (float, int)) for v in raw):        # one case given as numbers
        shape, F = (), np.array([raw], dtype=float)
    else:
        vals = [np.asarray(v, dtype=float) for v in raw]
        shape = np.broadcast_shapes(*(v.shape for v in vals), *(np.shape(v) for v in extra))
        F = np.empty(shape + (5,))
        for k, v in enumerate(vals):
            F[..., k] = v                                   # (broadcast by the assignment)
        F = F.reshape(-1, 5)
    _check_loads(brg, F)
    ndof = 5 if F.size and np.any(F[:, 3:] != 0.0) else 3
    return RingLoads(shape, F, M is not None or My is not None, ndof,
                     tuple(np.broadcast_to(np.asarray(v, dtype=float), shape).ravel() for v in extra))


def groove_offsets(brg: BallBearing):
    r"""Offsets of the inner groove curvature centres from the outer ones where the balls first touch, rings
    unloaded, and the constant of the cancellation-free approach [m, m, m²].

    .. math::

        (A_{a0}, A_{r0}), \qquad c = A_{a0}^2 + A_{r0}^2 − A^2 = \tfrac{−P_d}{2}\left(2A − \tfrac{P_d}{2}\right)

    (:attr:`~thermobear.contact.geometry.BallBearing.A_a0`, :attr:`~thermobear.contact.geometry.BallBearing.A_r0`;
    c = 0 with a clearance, the balls just touching; with a negative clearance P_d the rings centred, each ball
    compressed by −P_d/2).  A ball's approach at offsets A0 + d is then s = A_j − A = (c + Σ d (2 A0 + d)) / (A_j + A)
    (Harris & Kotzalas 2007 [4] ch. 7).

    Parameters
    ----------
    brg : BallBearing

    Returns
    -------
    (A_a0, A_r0, c) : float   axial and radial offsets [m], the approach's constant [m²]

    Examples
    --------
    >>> from thermobear.contact.geometry import bearing
    >>> b = bearing("6208").with_(Pd=-8e-6)
    >>> a0, r0, c = groove_offsets(b)
    >>> a0, bool(abs(c / (r0 + b.A) - 4e-6) < 1e-18)
    (0.0, True)
    """
    c = 0.0 if brg.Pd >= 0 else -0.5 * brg.Pd * (2.0 * brg.A - 0.5 * brg.Pd)
    return brg.A_a0, brg.A_r0, c


def force_scale(brg: BallBearing, F_app):
    r"""The force scale of each load case's equilibrium residuals [N]: its largest applied load (forces, moments
    over their arm), at least the balls' radial preload

    .. math:: F_s = \max\left(\max_k |F_k|,\; Z Q_0\right), \qquad Q_0 = K_n (−P_d/2)^{1.5}

    (:func:`~thermobear.contact.fits.clearance_preload`; Q_0 = 0 with a clearance), so that a light load on a
    preloaded bearing is solved to the precision its ball forces allow.

    Parameters
    ----------
    brg : BallBearing
    F_app : ndarray    applied loads (nb, ndof) [N] (moments over their arm ℜ)

    Returns
    -------
    ndarray            (nb,) force scale [N]

    Examples
    --------
    >>> from thermobear.contact.geometry import bearing
    >>> b = bearing("6208")
    >>> F = np.array([[0.0, 10.0, 0.0]])
    >>> float(force_scale(b, F)[0]), round(float(force_scale(b.with_(Pd=-4e-6), F)[0]), 1)
    (10.0, 306.2)
    """
    s = np.max(np.abs(F_app), axis=1)
    if brg.Pd < 0:
        s = np.maximum(s, brg.Z * float(clearance_preload(brg, brg.Pd)))
    return s


def azimuths(Z: int):
    """Ball azimuths ψ_j = 2πj/Z [rad], j = 0 … Z − 1."""
    return 2.0 * np.pi * np.arange(Z) / Z


def levers(Z: int, ndof: int = 3):
    """The levers W (2, ndof, Z) of the ring unknowns on each ball's groove-centre offsets [-]: W[0] axial, W[1]
    radial; rows δa (1, 0), δr (0, cos ψ), θ (cos ψ, 0), δz (0, sin ψ), θ_y (sin ψ, 0) (:data:`COMPONENT`: the
    one non-zero component of each row).

    >>> levers(4, 5)[:, :, 1].round(12).tolist()
    [[1.0, 0.0, 0.0, 0.0, 1.0], [0.0, 0.0, 0.0, 1.0, 0.0]]
    """
    if ndof not in (3, 5):
        raise InputError("ndof", ndof, "ring unknowns: 3 (in-plane) or 5")
    psi = azimuths(Z)
    c, s = np.cos(psi), np.sin(psi)
    W = np.zeros((2, ndof, Z))
    W[0, 0], W[1, 1], W[0, 2] = 1.0, c, c
    if ndof == 5:
        W[1, 3], W[0, 4] = s, s
    return W


#: the component (0 axial, 1 radial) each ring unknown moves: δa, δr, θ, δz, θ_y
COMPONENT = (0, 1, 0, 1, 0)


def lever_matrix(brg: BallBearing, ndof: int = 3):
    """The lever matrix L (ndof, 2Z) of the groove-centre map [m]: row k holds ∂A1_j/∂g_k (first Z
    columns) and ∂A2_j/∂g_k (last Z) for g = (δa/A, δr/A, θℜ/A, δz/A, θ_yℜ/A)[:ndof], i.e. A (1, 0),
    A (0, cos ψ_j), A (cos ψ_j, 0), A (0, sin ψ_j), A (sin ψ_j, 0) (A times :func:`levers`).  Its transpose,
    divided by A, sums per-ball forces (f_a | f_r) into the ring loads (F_a, F_r, M/ℜ, F_z, M_y/ℜ)."""
    W = levers(brg.Z, ndof)
    return brg.A * np.concatenate([W[0], W[1]], axis=1)


def ring_sums(Z: int, ndof: int = 3):
    """The constant matrix that sums per-ball terms into ring quantities: per-ball rows (g_aa, g_ar, g_rr, f_a, f_r)
    (nb, 5Z) @ G (5Z, ndof² + ndof) → the ring stiffness Σ_j W_jᵀ g_j W_j (symmetric per-ball g; the first ndof²
    columns, row-major) and the ring forces Σ_j W_jᵀ f_j (the last ndof), W_j (2, ndof) the ball's levers
    (:func:`levers`)."""
    W0, W1 = levers(Z, ndof)
    n2 = ndof * ndof
    G = np.zeros((5, Z, n2 + ndof))
    G[0, :, :n2] = (W0[:, None] * W0[None, :]).reshape(n2, Z).T          # column k ndof + m: W_k W_m
    G[1, :, :n2] = (W0[:, None] * W1[None, :] + W1[:, None] * W0[None, :]).reshape(n2, Z).T
    G[2, :, :n2] = (W1[:, None] * W1[None, :]).reshape(n2, Z).T
    G[3, :, n2:] = W0.T
    G[4, :, n2:] = W1.T
    return G.reshape(5 * Z, -1)


def ring_direction(J, r, free):
    """Newton direction −J⁻¹ r of the ring unknowns (nb, ndof), the unknowns with ``free`` 0 held (their rows
    and columns dropped).  A singular case (no ball in contact) is regularised (+1e-3 on the diagonal: a push
    towards contact); one singular even then gets NaN (it fails)."""
    n = J.shape[1]
    fi = np.flatnonzero(free)
    held = fi.size < n
    if held:
        out = np.zeros(r.shape)
        k = fi.size
        if fi[-1] == k - 1:                    # the free unknowns first (e.g. the tilt of an in-plane case held)
            J, r, fi = J[:, :k, :k], r[:, :k], slice(0, k)
        else:
            J, r = J[:, fi[:, None], fi], r[:, fi]
    try:
        d = -np.linalg.solve(J, r[..., None])[..., 0]
    except np.linalg.LinAlgError:
        J = J + (np.abs(np.linalg.det(J)) <= 1e-300)[:, None, None] * (1e-3 * np.eye(J.shape[1]))
        try:
            d = -np.linalg.solve(J, r[..., None])[..., 0]
        except np.linalg.LinAlgError:
            d = np.full(r.shape, np.nan)
            for k in range(r.shape[0]):
                try:
                    d[k] = -np.linalg.solve(J[k], r[k])
                except np.linalg.LinAlgError:
                    pass
    if held:
        out[:, fi] = d
        return out
    return d


def unbatch(shape, v, per_ball: bool = False):
    """A flat batch (nb,) or (nb, Z) back to the loads' shape (a float / (Z,) array for scalar loads)."""
    if shape:
        return v.reshape(shape + v.shape[1:]) if per_ball else v.reshape(shape)
    return v[0] if per_ball else float(v[0])
