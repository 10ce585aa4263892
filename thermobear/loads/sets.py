r"""Bearings on one rigid shaft: duplex sets and a shaft on two supports, with preload.

The shaft (with the inner rings) is a rigid body; the housing (with the outer rings) is fixed.  Its
displacement at the axial position x = 0 is q = (δa, δr, θ, δz, θ_y) in the axes and signs of
:mod:`thermobear.loads.rings` (x axial; θ moves the shaft's side at +y towards +x, a rotation about −z;
θ_y the side at +z, about +y).  Bearing k sits at the axial position x_k and faces σ_k = ±1: σ = +1 carries a
load towards +x on its inner ring (the single-bearing convention), σ = −1 is the mirrored bearing.  In its
own frame (x mirrored for σ = −1) its inner ring is displaced by

.. math::

    q_k = T_k q + (c_k + w_k) e_a, \qquad
    T_k q = (σ_k δa,\; δr − x_k θ,\; σ_k θ,\; δz − x_k θ_y,\; σ_k θ_y)

(rigid-body motion to first order; e_a the axial unit vector), with c_k its mounted axial position (the
position preload: A sin α0 + offset, offset beyond first touch) and w_k the axial slide of an outer ring
held by a spring (constant-force preload; w_k = 0 otherwise).  Its ring reaction P_k(q_k) and stiffness K_k
are those of :func:`thermobear.loads.static.ring_reaction` (rigid rings, low speed; two bearings in the
high-speed form: :mod:`thermobear.loads.shaftspeed`).  By virtual work the
shaft is in equilibrium when

.. math::

    \sum_k T_k^T P_k(q_k) = P_{ext}, \qquad P_{k,a} = F_{s,k} \text{ for each spring-loaded bearing},

P_ext = (F_a, F_r, M − x_F F_r, F_z, M_y − x_F F_z) the external loads acting at x_F moved to x = 0.  The
Jacobian Σ T_kᵀ K_k T_k (with the spring rows) is exact; the unknowns are solved by the shared damped Newton
(:mod:`thermobear.loads.newton`), three of them (δa, δr, θ) when every load lies in the x–y plane, five
otherwise (exact by the symmetry of :mod:`thermobear.loads.rings`).  Start: the shaft at rest on its mounted
bearings when they are preloaded; otherwise each bearing solved alone under a statically determinate share
of the loads (lever rule between the two outermost supports, the axial load to the bearings facing it) and
the shaft placed through the results (least squares).

Duplex arrangements (Harris & Kotzalas 2007 [1] ch. 8; adjacent bearings of width B at x = ∓B/2):
back-to-back (σ = +1, −1: the load lines diverge, pressure centres outside the pair), face-to-face
(σ = −1, +1: they converge), tandem (+1, +1: both carry +x).

References
----------
.. [1] Harris, T. A. & Kotzalas, M. N. (2007). *Essential Concepts of Bearing Technology*, 5th ed., CRC Press,
   ch. 7 (internal load distribution, thrust load: the load–deflection of a ball bearing under axial load) and
   ch. 8 (bearing deflection and preloading: duplex pairs, position and spring preload).
.. [2] Jones, A. B. (1960). A general theory for elastically constrained ball and radial roller bearings under
   arbitrary load and speed conditions. *J. Basic Eng.* 82(2):309–320 (a shaft on several bearings).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from thermobear.contact.fits import expanded_bearing, raceway_growth, steel_expansion
from thermobear.contact.geometry import BallBearing
from thermobear.errors import InputError, NoConvergence, NoEquilibrium
from thermobear.loads.newton import NewtonOptions, RowState, newton
from thermobear.loads.overload import refuse_overload as refuse_overload_of
from thermobear.loads.rings import arm_length, check_stiffness, ring_direction
from thermobear.loads.static import load_distribution_static, reaction_of, reaction_problem, ring_reaction

__all__ = ["Support", "ShaftLoads", "ARRANGEMENTS", "shaft_loads", "bearing_set", "shaft_on_two_supports",
           "warm_supports", "duplex_supports", "shaft_transform"]

#: duplex arrangements: facing of the bearing at −B/2 and at +B/2
ARRANGEMENTS = {"back_to_back": (1, -1), "face_to_face": (-1, 1), "tandem": (1, 1)}
_TOL = 1e-10
_MAXIT = 80


@dataclass(frozen=True)
class Support:
    """A bearing on the shaft.

    Attributes
    ----------
    bearing : BallBearing
    x : float           axial position of its centre plane on the shaft [m]
    facing : int        +1: it carries loads towards +x on its inner ring; −1: the mirrored bearing (deep groove:
                        either)
    offset : float      position preload [m]: the axial displacement of its inner ring against its outer ring,
                        towards its balls, beyond first touch, with the shaft at q = 0 (negative: axial play).
                        ``None``: an angular contact bearing at first touch, a deep groove bearing centred
    spring : float      constant-force preload [N]: its outer ring slides axially in the housing, pushed against
                        its balls by this force (``None``: the outer ring is held)
    """

    bearing: BallBearing
    x: float = 0.0
    facing: int = 1
    offset: float | None = None
    spring: float | None = None

    def __post_init__(self):
        if self.facing not in (1, -1):
            raise InputError("facing", self.facing, "+1 (carries +x loads on its inner ring) or -1 (mirrored)")
        if not np.isfinite(self.x):
            raise InputError("x", self.x, "axial position must be finite [m]")
        if self.offset is not None and not np.isfinite(self.offset):
            raise InputError("offset", self.offset, "position preload offset must be finite [m]")
        if self.spring is not None and not (np.isfinite(self.spring) and self.spring > 0):
            raise InputError("spring", self.spring, "constant preload force must be finite and > 0 [N]")
        if self.spring is not None and self.offset is not None:
            raise InputError("offset", self.offset, "give a position preload (offset) or a spring force, not both")

    @property
    def mounted(self) -> float:
        """c_k: the axial position of its inner ring against its outer ring at q = 0, from the centred position [m]."""
        b = self.bearing
        if self.offset is None:
            return 0.0 if b.kind == "deep_groove" else b.A * np.sin(b.alpha0)
        return b.A * np.sin(b.alpha0) + self.offset


@dataclass(frozen=True)
class ShaftLoads:
    """Equilibrium of a shaft on its bearings (leading axes: the load cases).

    Attributes
    ----------
    q : ndarray (..., 5)       shaft displacement at x = 0: (δa, δr, θ, δz, θ_y) [m, m, rad, m, rad]
    loads : tuple              each bearing's LoadDistribution in its own frame (its Fa, Fr, M, Fz, My are the
                               loads it carries)
    reactions : ndarray (..., n, 5)  each bearing's loads (F_a, F_r, M, F_z, M_y) in its own frame [N, N m]
    stiffness : ndarray (..., 5, 5)  the shaft's stiffness matrix at x = 0, dP_ext/dq [N/m, N/rad, N m/m, N m/rad]
                               (the spring-held outer rings sliding; rows/columns δz, θ_y included)
    slide : ndarray (..., n)   axial slide w_k of each spring-held outer ring [m] (0 for the others)
    supports : tuple           the Support of each bearing
    residual : float           largest scaled equilibrium residual [-]
    iterations : int           Newton iterations
    """

    q: np.ndarray
    loads: tuple
    reactions: np.ndarray
    stiffness: np.ndarray
    slide: np.ndarray
    supports: tuple = field(repr=False)
    residual: float = 0.0
    iterations: int = 0

    @property
    def preload(self):
        """Axial load each bearing carries in its own frame [N] (..., n)."""
        return self.reactions[..., 0]

    def displacement_at(self, x):
        """The shaft's radial displacement (along y, along z) at the axial position x [m]: δr − x θ, δz − x θ_y."""
        q = self.q
        return q[..., 1] - x * q[..., 2], q[..., 3] - x * q[..., 4]


def shaft_transform(sup: Support):
    """T_k (5, 5) of the module docstring: the bearing's local ring displacement per shaft displacement at x = 0
    (its transpose: the shaft's loads per local ring reaction)."""
    s, x = float(sup.facing), float(sup.x)
    T = np.zeros((5, 5))
    T[0, 0] = s
    T[1, 1], T[1, 2] = 1.0, -x
    T[2, 2] = s
    T[3, 3], T[3, 4] = 1.0, -x
    T[4, 4] = s
    return T


class _ShaftProblem:
    """The shaft equilibrium as a problem of :func:`thermobear.loads.newton.newton`: unknowns z (nb, m) = the
    shaft's free unknowns (scaled: translations / A_ref, tilts · L_ref / A_ref), then one axial slide per
    spring-held bearing (/ A_ref); residual rows in the same order, / the case's force scale."""

    def __init__(self, sups, P_ext, dofs, scale, stiffness, tilt_arm):
        self.sups, self.dofs, self.stiffness = sups, np.asarray(dofs), stiffness
        self.P_ext, self.scale = P_ext, scale
        self.arms = [arm_length(s.bearing, tilt_arm) for s in sups]
        self.pbs = [reaction_problem(s.bearing, P_ext.shape[0], stiffness) for s in sups]
        self.T = [shaft_transform(s) for s in sups]
        self.c = np.array([s.mounted for s in sups])
        self.springs = [k for k, s in enumerate(sups) if s.spring is not None]
        self.A_ref = min(s.bearing.A for s in sups)
        span = max(abs(s.x) for s in sups)
        self.L_ref = max(span, max(s.bearing.dm for s in sups) / 2)
        unit = np.array([self.A_ref, self.A_ref, self.A_ref / self.L_ref, self.A_ref, self.A_ref / self.L_ref])
        self.unit = unit[self.dofs]                    # q = z · unit (free unknowns)
        self.force_unit = np.array([1.0, 1.0, self.L_ref, 1.0, self.L_ref])[self.dofs]
        self.n = len(self.dofs) + len(self.springs)

    def rows(self, idx):
        new = _ShaftProblem.__new__(_ShaftProblem)
        new.__dict__.update(self.__dict__)
        new.P_ext, new.scale = self.P_ext[idx], self.scale[idx]
        new.pbs = [reaction_problem(s.bearing, len(idx), self.stiffness) for s in self.sups]
        return new

    def shaft(self, z):
        """Shaft displacement q (nb, 5) and slides w (nb, n_bearings) [m, rad] at the unknowns z."""
        nb, nd = z.shape[0], len(self.dofs)
        q = np.zeros((nb, 5))
        q[:, self.dofs] = z[:, :nd] * self.unit
        w = np.zeros((nb, len(self.sups)))
        for j, k in enumerate(self.springs):
            w[:, k] = z[:, nd + j] * self.A_ref
        return q, w

    def local(self, z):
        """Each bearing's local ring displacement (nb, 5) at z."""
        q, w = self.shaft(z)
        out = []
        for k, T in enumerate(self.T):
            qk = q @ T.T
            qk[:, 0] += self.c[k] + w[:, k]
            out.append(qk)
        return out

    def evaluate(self, z):
        nb, nd = z.shape[0], len(self.dofs)
        R = -self.P_ext.copy()
        J = np.zeros((nb, self.n, self.n))
        P_all, K_all = [], []
        for k, (pb, T, qk) in enumerate(zip(self.pbs, self.T, self.local(z))):
            P, K, _ = reaction_of(pb, qk, self.arms[k])
            P_all.append(P)
            K_all.append(K)
            R += P @ T
            J[:, :nd, :nd] += (T.T @ K @ T)[:, self.dofs][:, :, self.dofs]
        for j, k in enumerate(self.springs):
            T, K = self.T[k], K_all[k]
            col = (T.T @ K[:, :, 0:1])[:, self.dofs, 0]             # dR/dw_k
            J[:, :nd, nd + j] = col * self.A_ref
            J[:, nd + j, :nd] = (K[:, 0:1, :] @ T)[:, 0, self.dofs] * self.unit
            J[:, nd + j, nd + j] = K[:, 0, 0] * self.A_ref
        J[:, :nd, :nd] *= self.unit[None, None, :]
        res = np.empty((nb, self.n))
        res[:, :nd] = R[:, self.dofs] / self.force_unit
        for j, k in enumerate(self.springs):
            res[:, nd + j] = P_all[k][:, 0] - self.sups[k].spring
        J[:, :nd, :] /= self.force_unit[None, :, None]
        inv = (1.0 / self.scale)[:, None]
        st = _ShaftState()
        st.z, st.res, st.J = z, res * inv, J * inv[:, :, None]
        st.norm = np.abs(st.res).max(axis=1)
        st.norm = np.where(np.isfinite(st.norm), st.norm, np.nan)
        return st

    def direction(self, st):
        return ring_direction(st.J, st.res, np.ones(self.n))


class _ShaftState(RowState):
    FIELDS = ("z", "res", "J", "norm")


def _position_preload(sup: Support, stiffness, tilt_arm) -> float:
    """The axial force [N] a position-preloaded bearing carries with the shaft at rest (q = 0): the force scale of
    a preloaded set's equilibrium, whatever the external loads (0 without a position preload)."""
    if sup.offset is None or not sup.offset > 0:
        return 0.0
    P = ring_reaction(sup.bearing, [sup.mounted, 0.0, 0.0, 0.0, 0.0], stiffness=stiffness, tilt_arm=tilt_arm)[0]
    return abs(float(P[0]))


def _external(Fa, Fr, M, Fz, My, x_load):
    """The external loads as one flat batch: shape and P_ext (nb, 5) at x = 0 [N, N m]."""
    vals = [np.asarray(v, dtype=float) for v in (Fa, Fr, M, Fz, My, x_load)]
    shape = np.broadcast_shapes(*(v.shape for v in vals))
    Fa, Fr, M, Fz, My, xF = (np.broadcast_to(v, shape).ravel() for v in vals)
    for name, v in (("Fa", Fa), ("Fr", Fr), ("M", M), ("Fz", Fz), ("My", My), ("x_load", xF)):
        if v.size and not np.all(np.isfinite(v)):
            raise InputError(name, v, "must be finite [N], [N m] or [m]")
    P = np.stack([Fa, Fr, M - xF * Fr, Fz, My - xF * Fz], axis=1)
    return shape, P


def _start(sups, P, dofs, stiffness, tilt_arm):
    """Shaft displacement q (nb, 5) to start from: each bearing alone under a statically determinate share of
    the loads, the shaft placed through their displacements (least squares); see the module docstring."""
    nb, n = P.shape[0], len(sups)
    xs = np.array([s.x for s in sups])
    i1, i2 = int(np.argmin(xs)), int(np.argmax(xs))
    share = np.zeros((nb, n, 5))
    if xs[i2] > xs[i1]:
        for r, t in ((1, 2), (3, 4)):                          # lever rule: R1 + R2 = F, x1 R1 + x2 R2 = −P_θ
            R2 = (-P[:, t] - xs[i1] * P[:, r]) / (xs[i2] - xs[i1])
            share[:, i2, r], share[:, i1, r] = R2, P[:, r] - R2
    else:
        share[:, :, 1], share[:, :, 3] = P[:, None, 1] / n, P[:, None, 3] / n
    for sgn in (1.0, -1.0):
        carriers = [k for k, s in enumerate(sups) if s.facing == sgn or s.bearing.kind == "deep_groove"]
        on = sgn * P[:, 0] > 0
        for k in carriers:
            share[on, k, 0] = sups[k].facing * P[on, 0] / len(carriers)
    rows, rhs = [], []
    for k, s in enumerate(sups):
        loc = share[:, k]
        Fa = np.abs(loc[:, 0]) + (s.spring or 0.0)
        try:
            ld = load_distribution_static(s.bearing, Fa=Fa, Fr=np.hypot(loc[:, 1], loc[:, 3]), stiffness=stiffness,
                                          tilt_arm=tilt_arm)
        except (NoEquilibrium, NoConvergence):
            continue
        Fr = np.hypot(loc[:, 1], loc[:, 3])
        cy = np.where(Fr > 0, loc[:, 1] / np.where(Fr > 0, Fr, 1.0), 0.0)
        cz = np.where(Fr > 0, loc[:, 3] / np.where(Fr > 0, Fr, 1.0), 0.0)
        da = np.sign(np.where(loc[:, 0] == 0, 1.0, loc[:, 0])) * np.asarray(ld.delta_a).reshape(nb)
        T = shaft_transform(s)
        rows.append(T)
        rhs.append(np.stack([np.where(Fa > 0, da - s.mounted, 0.0), np.asarray(ld.delta_r).reshape(nb) * cy, np.zeros(nb),
                             np.asarray(ld.delta_r).reshape(nb) * cz, np.zeros(nb)], axis=1))
    q = np.zeros((nb, 5))
    if rows:
        Tm = np.concatenate([T[[0, 1, 3]] for T in rows])[:, dofs]
        b = np.concatenate([r[:, [0, 1, 3]] for r in rhs], axis=1)
        q[:, dofs] = np.linalg.lstsq(Tm, b.T, rcond=None)[0].T
    return q


def shaft_loads(supports, Fa=0.0, Fr=0.0, M=0.0, Fz=0.0, My=0.0, *, x_load=0.0, stiffness: str = "nominal",
                tilt_arm: str = "groove", tol: float = _TOL, maxiter: int = _MAXIT,
                refuse_overload: bool = True) -> ShaftLoads:
    r"""Equilibrium of a rigid shaft on several bearings under external loads (rigid rings, low speed).

    Parameters
    ----------
    supports : sequence of Support   the bearings (at least two, or one duplex set's two)
    Fa : array_like     axial load on the shaft, towards +x [N]
    Fr, Fz : array_like radial loads along y and z [N], acting at the axial position ``x_load``
    M, My : array_like  moments in the x–y plane (loads the shaft's +y side towards +x) and about +y [N m]
    x_load : array_like axial position where Fr and Fz act [m]
    stiffness, tilt_arm : as :func:`thermobear.loads.load_distribution`
    tol, maxiter : Newton tolerance (scaled residual) and iterations

    Returns
    -------
    ShaftLoads

    Raises
    ------
    InputError       bad input; loads the contacts cannot carry (:mod:`thermobear.loads.overload`)
    NoEquilibrium    a load the arrangement cannot carry (e.g. an axial load against a tandem pair)
    NoConvergence    Newton did not reach the tolerance

    Notes
    -----
    Equations in the module docstring (Jones 1960; Harris & Kotzalas 2007 ch. 8).

    Examples
    --------
    A shaft on two 6208 bearings 120 mm apart, 2 kN radial load 40 mm from the first: the lever rule.

    >>> from thermobear.contact.geometry import bearing
    >>> b = bearing("6208")
    >>> res = shaft_loads([Support(b, 0.0), Support(b, 0.12)], Fr=2000.0, x_load=0.04)
    >>> [round(float(v), 1) for v in res.reactions[:, 1]]
    [1333.3, 666.7]
    """
    sups = tuple(supports)
    if len(sups) < 2 or not all(isinstance(s, Support) for s in sups):
        raise InputError("supports", supports, "two or more Support(bearing, x, facing, offset, spring)")
    check_stiffness(stiffness)
    shape, P = _external(Fa, Fr, M, Fz, My, x_load)
    nb = P.shape[0]
    if not any(s.spring for s in sups):
        for sgn in (1, -1):
            if np.any(sgn * P[:, 0] > 0) and not any(s.facing == sgn or s.bearing.kind == "deep_groove" for s in sups):
                raise NoEquilibrium(f"no bearing of the arrangement carries an axial load towards {sgn:+d}x (every "
                                    f"angular contact bearing faces {-sgn:+d}): Fa = {P[np.argmax(sgn * P[:, 0]), 0]:g} N",
                                    field="Fa (shaft loads)")
    dofs = [0, 1, 2, 3, 4] if np.any(P[:, 3:] != 0.0) else [0, 1, 2]
    preload = [s.spring or 0.0 for s in sups] + [_position_preload(s, stiffness, tilt_arm) for s in sups]
    scale = np.maximum.reduce([np.abs(P[:, :2]).max(axis=1), np.abs(P[:, 3]),
                               np.abs(P[:, [2, 4]]).max(axis=1) / max(max(abs(s.x) for s in sups),
                                                                     max(s.bearing.dm for s in sups) / 2),
                               np.full(nb, max(preload + [1e-3]))])
    pb = _ShaftProblem(sups, P, dofs, scale, stiffness, tilt_arm)
    has_pre = any(s.spring is not None or (s.offset is not None and s.offset > 0) for s in sups)
    q0 = np.zeros((nb, 5)) if has_pre else _start(sups, P, dofs, stiffness, tilt_arm)
    z0 = np.zeros((nb, pb.n))
    z0[:, :len(dofs)] = q0[:, dofs] / pb.unit
    r = newton(pb, z0, NewtonOptions(tol=tol, maxiter=maxiter, halvings=30, polish=2))
    if has_pre and not r.converged.all():                   # from the statics estimate as well
        bad = np.flatnonzero(~r.converged)
        sub = pb.rows(bad)
        z1 = np.zeros((bad.size, pb.n))
        z1[:, :len(dofs)] = _start(sups, P[bad], dofs, stiffness, tilt_arm)[:, dofs] / pb.unit
        r2 = newton(sub, z1, NewtonOptions(tol=tol, maxiter=maxiter, halvings=30, polish=2))
        r.z[bad[r2.converged]] = r2.z[r2.converged]
        r.norm[bad] = np.where(r2.converged, r2.norm, r.norm[bad])
        r.iterations[bad] += r2.iterations
        r.converged[bad] |= r2.converged
    if not r.converged.all():
        k = int(np.argmax(~r.converged))
        raise NoConvergence(
            f"shaft equilibrium not reached for Fa = {P[k, 0]:g} N, Fr = {P[k, 1]:g} N, Fz = {P[k, 3]:g} N "
            f"(moments at x = 0: {P[k, 2]:g}, {P[k, 4]:g} N m): scaled residual {r.norm[k]:.3g} after "
            f"{r.iterations[k]} Newton iterations — the bearings may not locate the shaft in every direction "
            "(e.g. an axial load against a tandem pair, or no bearing facing it)",
            iterations=int(r.iterations[k]), residual=float(r.norm[k]))
    return _result(pb, r, shape, stiffness, tilt_arm, refuse_overload)


def _result(pb, r, shape, stiffness, tilt_arm, check):
    """ShaftLoads at the solution."""
    q, w = pb.shaft(r.z)
    lds, reac, Ks = [], [], np.zeros((q.shape[0], 5, 5))
    for k, (s, T, qk) in enumerate(zip(pb.sups, pb.T, pb.local(r.z))):
        try:
            P, K, ld = ring_reaction(s.bearing, qk.reshape(shape + (5,)), stiffness=stiffness, tilt_arm=tilt_arm)
        except NoEquilibrium:
            raise NoEquilibrium(
                f"bearing {k} ({s.bearing.name}, facing {s.facing:+d} at x = {s.x:g} m) would carry its share over "
                "its low shoulder (contact angle <= 0): the arrangement cannot carry these loads (e.g. an axial "
                "load against a bearing beyond the preload, or a spring preload, that holds it)",
                field="Fa, Fr, M (shaft loads)") from None
        if check:
            refuse_overload_of(s.bearing, ld, field="Fa, Fr, M (shaft loads)")
        lds.append(ld)
        reac.append(P.reshape(-1, 5))
        Ks += T.T @ K.reshape(-1, 5, 5) @ T
    for k in pb.springs:                               # a sliding outer ring: eliminate its slide (Schur)
        T, K = pb.T[k], ring_reaction(pb.sups[k].bearing, pb.local(r.z)[k], stiffness=stiffness,
                                      tilt_arm=tilt_arm)[1]
        col = T.T @ K[:, :, 0:1]
        Ks -= col @ np.swapaxes(col, 1, 2) / K[:, 0, 0][:, None, None]
    reac = np.stack(reac, axis=1)
    return ShaftLoads(q=q.reshape(shape + (5,)), loads=tuple(lds), reactions=reac.reshape(shape + reac.shape[1:]),
                      stiffness=Ks.reshape(shape + (5, 5)), slide=w.reshape(shape + w.shape[1:]), supports=pb.sups,
                      residual=float(np.nanmax(r.norm)) if r.norm.size else 0.0,
                      iterations=int(r.iterations.max()) if r.iterations.size else 0)


def warm_supports(supports, dT_inner=0.0, dT_outer=0.0, dT_ball=None, *, alpha_ring=None, alpha_ball=None,
                  n_rpm: float = 0.0, u_inner: float | None = None):
    r"""The supports of a shaft whose inner rings (and shaft) run ``dT_inner`` and outer rings (and housing)
    ``dT_outer`` warmer than at mounting [K]: each bearing grown (:func:`thermobear.contact.fits.expanded_bearing`:
    groove radii, pitch diameter, free contact angle) and its position preload moved by the axial growth.

    Radially, the inner ring's groove centres move out against the outer ring's and the balls touch earlier
    (a smaller free contact angle, a smaller first-touch offset A' sin α0'); axially, the shaft (inner stack)
    grows about x = 0 by ε_i x_k and the housing (outer stack) by ε_o x_k (ε = α ΔT), which moves bearing k's
    inner raceway against its outer one by σ_k (ε_i − ε_o) x_k in its own frame (Harris & Kotzalas 2007 ch. 3,
    differential expansion; ch. 8, preloading).  Position preloads become
    offset' = A sin α0 + offset + σ_k (ε_i − ε_o) x_k − A' sin α0'; a spring keeps its force (its outer ring
    slides), a deep groove bearing without a preload stays centred.  At speed (``n_rpm`` > 0, the inner rings
    rotating) each inner raceway also grows by its centrifugal growth u_i (:func:`thermobear.contact.fits.raceway_growth`,
    Timoshenko & Goodier 1970 ch. 4: a free rotating ring; ``u_inner`` given: e.g. on its seat,
    :func:`thermobear.contact.fits.seated_raceway_growth`), radially, like its thermal growth; the shaft's axial
    (Poisson) contraction at speed is left out.

    Parameters
    ----------
    supports : sequence of Support
    dT_inner, dT_outer : float  temperature rises of the inner rings with the shaft and of the outer rings with
                                the housing since mounting [K]
    dT_ball : float             of the balls [K] (default: the mean)
    alpha_ring, alpha_ball : float  expansion coefficients [1/K] (default AISI 52100, shaft and housing alike)
    n_rpm : float               speed of the inner rings [rpm] (0: at rest, no centrifugal growth)
    u_inner : float             the inner raceways' growth at that speed [m] (default: a free ring's, raceway_growth)

    Returns
    -------
    tuple of Support

    Examples
    --------
    A 7014C with 10 µm position preload, inner rings 10 K warmer than the outer: the free contact angle falls, the
    offset beyond first touch grows; at 12 000 rpm the inner ring's centrifugal growth adds to it.

    >>> from thermobear.contact.geometry import bearing
    >>> cold = Support(bearing("7014C"), offset=10e-6)
    >>> [round(float(s.offset) * 1e6, 2) for s in (warm_supports([cold], 10.0, 0.0)[0],
    ...                                     warm_supports([cold], 10.0, 0.0, n_rpm=12000.0)[0])]
    [33.42, 48.59]
    """
    a_r = steel_expansion() if alpha_ring is None else float(alpha_ring)
    de = a_r * (float(dT_inner) - float(dT_outer))
    out = []
    for s in supports:
        b = s.bearing
        u = (raceway_growth(b, n_rpm) if u_inner is None else float(u_inner)) if n_rpm else 0.0
        warm = expanded_bearing(b, dT_inner, dT_outer, dT_ball, alpha_ring=a_r, alpha_ball=alpha_ball, u_inner=u)
        if s.spring is not None or (s.offset is None and b.kind == "deep_groove"):
            out.append(Support(warm, s.x, s.facing, s.offset, s.spring))
            continue
        c = s.mounted + s.facing * de * s.x
        out.append(Support(warm, s.x, s.facing, c - warm.A * np.sin(warm.alpha0)))
    return tuple(out)


def bearing_set(brg: BallBearing, arrangement: str = "back_to_back", Fa=0.0, Fr=0.0, M=0.0, Fz=0.0, My=0.0, *,
                preload_offset: float | None = None, preload_force: float | None = None, spacer: float = 0.0,
                dT_inner: float = 0.0, dT_outer: float = 0.0, dT_ball: float | None = None,
                stiffness: str = "nominal", tilt_arm: str = "groove") -> ShaftLoads:
    r"""A duplex set of two equal angular contact bearings on a rigid shaft, preloaded, under external loads.

    Parameters
    ----------
    brg : BallBearing   the bearing of both rows (its ``width`` B places them at x = ∓(B + spacer)/2)
    arrangement : str   ``"back_to_back"``, ``"face_to_face"`` or ``"tandem"`` (:data:`ARRANGEMENTS`)
    Fa, Fr, M, Fz, My : array_like  loads on the shaft at the set's centre (x = 0) [N, N m]
    preload_offset : float   position preload [m]: the total axial interference of the pair (ground faces or
                        spacers of unequal length) — each bearing's inner ring pushed by half of it beyond first
                        touch (back-to-back, face-to-face); ``None`` and no force: zero preload, zero play
    preload_force : float    constant-force preload [N] (springs): the second bearing's outer ring slides axially
                        under this force (back-to-back, face-to-face); for a tandem pair an axial force on the
                        shaft towards the pair's facing (+x), shared by both
    spacer : float      length of equal inner and outer spacers between the bearings [m]
    dT_inner, dT_outer : float  the inner rings (with the shaft and inner spacer) and the outer rings (with the
                        housing and outer spacer) run this much warmer than at mounting [K] (:func:`warm_supports`)
    dT_ball : float     the balls run this much warmer than at mounting [K] (default: the mean of the rings')
    stiffness, tilt_arm : as :func:`thermobear.loads.load_distribution`

    Returns
    -------
    ShaftLoads          bearing 0 at −(B + spacer)/2, bearing 1 at +(B + spacer)/2

    Examples
    --------
    A back-to-back 7205B pair with 10 µm position preload: each bearing carries the same preload.

    >>> from thermobear.contact.geometry import bearing
    >>> s = bearing_set(bearing("7205B"), "back_to_back", preload_offset=10e-6)
    >>> [round(float(v)) for v in s.preload]
    [470, 470]
    """
    sups, Fa = duplex_supports(brg, arrangement, Fa, preload_offset=preload_offset, preload_force=preload_force,
                               spacer=spacer)
    if dT_inner or dT_outer or dT_ball:
        sups = warm_supports(sups, dT_inner, dT_outer, dT_ball)
    return shaft_loads(sups, Fa, Fr, M, Fz, My, stiffness=stiffness, tilt_arm=tilt_arm)


def duplex_supports(brg: BallBearing, arrangement: str = "back_to_back", Fa=0.0, *,
                    preload_offset: float | None = None, preload_force: float | None = None,
                    spacer: float = 0.0) -> tuple:
    r"""The two supports of :func:`bearing_set` (cold, as mounted) and the axial load on the shaft [N].

    Parameters
    ----------
    brg, arrangement, Fa, preload_offset, preload_force, spacer : as :func:`bearing_set`

    Returns
    -------
    (tuple of Support, array_like)   bearing 0 at −(B + spacer)/2, bearing 1 at +(B + spacer)/2; the shaft's axial
                        load (a tandem pair's spring force added to ``Fa``)

    Examples
    --------
    >>> from thermobear.contact.geometry import bearing
    >>> sups, Fa = duplex_supports(bearing("7205B"), "back_to_back", preload_offset=10e-6)
    >>> [(round(s.x * 1e3, 1), s.facing, round(s.offset * 1e6, 1)) for s in sups], float(Fa)
    ([(-7.5, 1, 5.0), (7.5, -1, 5.0)], 0.0)
    """
    if arrangement not in ARRANGEMENTS:
        raise InputError("arrangement", arrangement, f"must be one of {', '.join(ARRANGEMENTS)}")
    if brg.width is None:
        raise InputError("bearing.width", None, "a duplex set needs the bearings' width B [m] (their spacing)")
    if preload_offset is not None and preload_force is not None:
        raise InputError("preload_offset", preload_offset, "give a position preload or a preload force, not both")
    half = 0.5 * (brg.width + spacer)
    s1, s2 = ARRANGEMENTS[arrangement]
    if arrangement == "tandem":
        if preload_offset is not None:
            raise InputError("preload_offset", preload_offset, "a tandem pair has no position preload of its own "
                             "(both rows face the same way): give preload_force, or mount a counter bearing")
        sups = (Support(brg, -half, s1), Support(brg, half, s2))
        Fa = np.asarray(Fa, dtype=float) + (preload_force or 0.0)
    else:
        off = None if preload_offset is None else 0.5 * preload_offset
        sups = (Support(brg, -half, s1, offset=off if preload_force is None else None),
                Support(brg, half, s2, offset=off if preload_force is None else None, spring=preload_force))
    return sups, Fa


def shaft_on_two_supports(first: BallBearing | Support, second: BallBearing | Support, span: float, Fa=0.0, Fr=0.0,
                          M=0.0, Fz=0.0, My=0.0, *, x_load=None, stiffness: str = "nominal",
                          tilt_arm: str = "groove") -> ShaftLoads:
    r"""A rigid shaft on two bearings ``span`` apart, with loads between (or outside) them.

    Parameters
    ----------
    first, second : BallBearing or Support   the bearings at x = 0 and x = span (a Support's own x is replaced);
                        a bare BallBearing faces +x (the first) and −x (the second): an angular contact pair in
                        back-to-back ("O", indirect) mounting, or two deep groove bearings
    span : float        distance between the bearings' centre planes [m], > 0
    Fa, Fr, M, Fz, My : array_like  loads on the shaft [N, N m]; Fr and Fz act at ``x_load``
    x_load : array_like axial position of the radial loads from the first bearing [m] (default: mid-span)

    Returns
    -------
    ShaftLoads          displacements at the first bearing (x = 0); ``displacement_at(x)`` elsewhere

    Examples
    --------
    A 7210 pair 0.2 m apart, back-to-back ("O"), 500 N spring preload on the second, 1 kN radial load at a third of
    the span: the pressure centres lie (d_m/2) tan α0 = 29 mm outside the bearings, so the nearer bearing takes
    less than the 2/3 of the lever rule between the bearings' planes.

    >>> from thermobear.contact.geometry import bearing
    >>> b = bearing("7210")
    >>> res = shaft_on_two_supports(b, Support(b, facing=-1, spring=500.0), 0.2, Fr=1000.0, x_load=0.2 / 3)
    >>> [round(float(v)) for v in res.reactions[:, 1]], round(float(res.preload[1]))
    ([637, 363], 500)
    """
    if not (np.isfinite(span) and span > 0):
        raise InputError("span", span, "distance between the bearings must be finite and > 0 [m]")
    sups = []
    for x, s, facing in ((0.0, first, 1), (float(span), second, -1)):
        if isinstance(s, BallBearing):
            s = Support(s, x, facing)
        elif isinstance(s, Support):
            s = Support(s.bearing, x, s.facing, s.offset, s.spring)
        else:
            raise InputError("support", s, "a BallBearing or a Support")
        sups.append(s)
    xl = 0.5 * span if x_load is None else x_load
    return shaft_loads(sups, Fa, Fr, M, Fz, My, x_load=xl, stiffness=stiffness, tilt_arm=tilt_arm)
