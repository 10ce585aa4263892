r"""A rigid shaft on two bearings in the high-speed form: each bearing's loads from its high-speed equilibrium
(the balls' centrifugal force and gyroscopic moment, Jones 1960), the shaft through both inner rings.

:mod:`thermobear.loads.sets` solves the shaft with each bearing's low-speed ring reaction P_k(q_k), a function of
its inner ring's displacement.  The high-speed relation
(:func:`thermobear.loads.highspeed.load_distribution_high_speed`) is force-controlled: it gives the inner ring's
displacement q_k = (δa, δr, θ)_k under the loads P_k = (F_a, F_r, M)_k of bearing k in its own frame (rings rigid,
outer ring fixed, inner ring at n).  With two
bearings the shaft's equilibrium (axes, signs, T_k and c_k of :mod:`thermobear.loads.sets`; loads in the x–y plane)

.. math:: T_0^T P_0 + T_1^T P_1 = P_{ext} \quad\Rightarrow\quad P_1 = T_1^{-T}\,\bigl(P_{ext} − T_0^T P_0\bigr)

leaves bearing 0's loads P_0 as the unknowns, and the rigid shaft through both inner rings — the shaft
displacement q read from bearing 0, q = T_0^{-1} (q_0 − c_0 e_a) — the compatibility

.. math:: r(P_0) = q_1(P_1) − (c_1 + w_1)\, e_a − T_1 T_0^{-1} \bigl(q_0(P_0) − c_0 e_a\bigr) = 0

(three rows: the sum of both bearings' axial displacements equals the mounted offset, c_0 + c_1 — warm and at
speed through the supports' geometry, :func:`thermobear.loads.sets.warm_supports`; equal radial displacement and
tilt of the shaft at both).  A spring-held outer ring (bearing 1's, w_1 its free slide) fixes F_a,1 = F_s and so
F_a,0 by the axial balance; its slide takes up the axial row: two unknowns (F_r,0, M_0), two rows (Harris &
Kotzalas 2007 [2] ch. 8, duplex pairs; Jones 1960 [1], a shaft on several bearings at speed).

Solver: Newton on P_0 (scaled by the force scale S and S·L, L the larger of the bearings' axial distance and
d_m/2), the Jacobian by forward differences (steps 10⁻⁶ of the scale), every case's base point and its
perturbations in one batched high-speed call per bearing; a step whose residual does not fall (or whose loads
the high-speed form cannot solve) is halved, up to 30 times.  Start: the low-speed shaft
(:func:`thermobear.loads.sets.shaft_loads`), each bearing kept at ≥ 10 % of the scale axially (the high-speed form
needs both loaded); where a bearing's axial load falls below 10⁻³ of the scale along the steps, an external axial
load lifts it off: NoEquilibrium.  Converged when the scaled residual (displacements / A, the tilt times L / A) is
below ``tol``.  At n = 0 the high-speed relation is the static one, and so is this shaft
(:func:`thermobear.loads.sets.shaft_loads`, to the tolerances).  Cost: two batched high-speed calls per Newton
step, ~5 steps from the static start; each call's ball equilibria start from the last evaluation's answer of their
case (``start`` of :func:`~thermobear.loads.highspeed.load_distribution_high_speed_full`: nearby loads, a few
iterations instead of the static solve and the placement), and a nearby answer given as ``start`` (a heat-up's
last) starts the first as well.

The speed-induced preload rise of a position-preloaded pair (Harris & Kotzalas 2007 [3] ch. 1–3 high-speed ball
bearings; Li & Shin 2004 [4]; Jorgensen & Shin 1998 [5]; SKF [6] measures it with strain gauges, "a marked increase
in preload at very high rotational speeds", mainly from the balls' centrifugal force): at speed each ball's
centrifugal force pushes it out against the outer race; the inner and outer contact angles part (α_i up, α_o
down) and the inner ring's axial displacement under a given axial load falls (the 7014C under 300 N: 26 µm less
at 12 000 rpm), so at the pair's fixed axial offset the axial load rises with speed at constant temperature; the
inner ring's centrifugal
growth (carried by the supports' geometry: a free ring's, :func:`thermobear.contact.fits.raceway_growth`, or on its
seat, :func:`thermobear.contact.fits.seated_raceway_growth`) adds to it.  The 7014C back-to-back pair of 300 N cold
(α0 = 15°): 903 N at 12 000 rpm from the balls alone, 1269 N with a free ring's growth
(:func:`thermobear.loads.pair.pair_loads`).

References
----------
.. [1] Jones, A. B. (1960). A general theory for elastically constrained ball and radial roller bearings under
   arbitrary load and speed conditions. *J. Basic Eng.* 82(2):309–320.
.. [2] Harris, T. A. & Kotzalas, M. N. (2007). *Essential Concepts of Bearing Technology*, 5th ed., CRC Press,
   ch. 8 (bearing deflection and preloading: duplex pairs, position and spring preload).
.. [3] Harris, T. A. & Kotzalas, M. N. (2007). *Advanced Concepts of Bearing Technology*, 5th ed., CRC Press,
   ch. 1–3 (high-speed ball bearings: centrifugal force, gyroscopic moment, contact angles at speed).
.. [4] Li, H. & Shin, Y. C. (2004). Analysis of bearing configuration effects on high speed spindles using an
   integrated dynamic thermo-mechanical spindle model. *Int. J. Mach. Tools Manuf.* 44(4):347–364.
.. [5] Jorgensen, B. R. & Shin, Y. C. (1998). Dynamics of spindle-bearing systems at high speeds including
   cutting load effects. *J. Manuf. Sci. Eng.* 120(2):387–394.
.. [6] SKF, super-precision angular contact ball bearings, "Bearing preload: effect of rotational speed on preload"
   (skf.com, super-precision bearings; qualitative: no number to compare with).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from thermobear.errors import InputError, NoConvergence, NoEquilibrium, SolverError
from thermobear.arrays import take
from thermobear.loads.highspeed import load_distribution_high_speed_full
from thermobear.loads.overload import refuse_overload as refuse_overload_of
from thermobear.loads.sets import Support, shaft_loads, shaft_transform
from thermobear.loads.sets import _external as external_loads

__all__ = ["HighSpeedShaftLoads", "shaft_loads_high_speed"]

_TOL = 1e-10
_MAXIT = 30
_HALVINGS = 30
_FD = 1e-6              # forward-difference step, of the unknowns' scale
_DOF = [0, 1, 2]        # (δa, δr, θ): loads in the x–y plane


@dataclass(frozen=True)
class HighSpeedShaftLoads:
    """Equilibrium of a shaft on two bearings in the high-speed form (leading axes: the load cases).

    Attributes
    ----------
    q : ndarray (..., 3)        shaft displacement at x = 0: (δa, δr, θ) [m, m, rad]
    loads : tuple               each bearing's high-speed LoadDistribution in its own frame (the cases on one axis)
    extras : tuple              each bearing's :class:`~thermobear.loads.highspeed.HighSpeedExtras` (the same)
    reactions : ndarray (..., 2, 5)  each bearing's loads (F_a, F_r, M, F_z = 0, M_y = 0) in its own frame [N, N m]
    slide : ndarray (..., 2)    axial slide of a spring-held outer ring [m] (0 for the others)
    supports : tuple            the Support of each bearing (warm and at speed, as given)
    n_rpm : ndarray             the inner rings' speed [rpm]
    residual : float            largest scaled compatibility residual (displacements / A) [-]
    iterations : int            Newton iterations
    """

    q: np.ndarray
    loads: tuple
    extras: tuple
    reactions: np.ndarray
    slide: np.ndarray
    supports: tuple = field(repr=False)
    n_rpm: np.ndarray = None
    residual: float = 0.0
    iterations: int = 0

    @property
    def preload(self):
        """Axial load each bearing carries in its own frame [N] (..., 2)."""
        return self.reactions[..., 0]


class _Pair:
    """The compatibility r(P_0) of two supports (module docstring), batched over cases."""

    def __init__(self, sups, P_ext, n_b, control, stiffness, tilt_arm, scale):
        self.sups, self.P, self.n = sups, P_ext, n_b
        self.kw = dict(control=control, stiffness=stiffness, tilt_arm=tilt_arm)
        self.T = [shaft_transform(s)[np.ix_(_DOF, _DOF)] for s in sups]
        self.c = np.array([s.mounted for s in sups])
        self.spring = sups[1].spring
        self.free = [1, 2] if self.spring is not None else [0, 1, 2]
        self.A = min(s.bearing.A for s in sups)
        self.L = max(max(abs(s.x) for s in sups), max(s.bearing.dm for s in sups) / 2)
        self.unit = scale[:, None] * np.array([1.0, 1.0, self.L])[None, :]
        self.T1invT = np.linalg.inv(self.T[1].T)
        self.T1T0inv = self.T[1] @ np.linalg.inv(self.T[0])
        self.last = None        # (cases, each bearing's (ld, ex)): the last evaluation's base points, to start from

    def starts(self, idx, reps: int) -> tuple:
        """Each bearing's start for the cases ``idx`` (sorted), each case repeated ``reps`` times: the answers of the
        last evaluation's base points (the loads of a nearby step), or None where it did not have every case."""
        if self.last is None:
            return None, None
        cases, sols = self.last
        where = np.full(self.P.shape[0], -1)
        where[cases] = np.arange(cases.size)
        pos = where[idx]
        if np.any(pos < 0):
            return None, None
        return tuple(take(sol, np.repeat(pos, reps), cases.size) for sol in sols)

    def loads(self, P0, idx):
        """Bearing 1's loads (nb, 3) from bearing 0's ``P0`` (nb, 3) of the cases ``idx``: the shaft's equilibrium."""
        return (self.P[idx] - P0 @ self.T[0]) @ self.T1invT.T

    def axial0(self, idx):
        """Bearing 0's axial load with a spring on bearing 1 [N] (the axial balance)."""
        return self.T[0][0, 0] * (self.P[idx, 0] - self.T[1][0, 0] * self.spring)

    def unknowns(self, z, idx):
        """P_0 (nb, 3) [N, N, N m] at the scaled unknowns z (nb, m)."""
        P0 = np.zeros((len(idx), 3))
        P0[:, self.free] = z * self.unit[idx][:, self.free]
        if self.spring is not None:
            P0[:, 0] = self.axial0(idx)
        return P0

    @staticmethod
    def loaded(P, k):
        """Bearing k's loads P (nb, 3), checked: NoEquilibrium where it would lose its axial load."""
        if np.any(P[:, 0] <= 0.0) or not np.all(np.isfinite(P)):
            raise NoEquilibrium(f"bearing {k} of the pair would lose its axial load (F_a = {P[:, 0].min():.4g} N): "
                                "the high-speed form needs both bearings loaded axially",
                                field="Fa, Fr, M (shaft loads)")
        return P

    def solve(self, P, k, n, start=None):
        """Bearing k's high-speed (LoadDistribution, HighSpeedExtras) under its loads P (nb, 3) at the speeds n
        (checked: :meth:`loaded`), Newton started from ``start`` where given (:meth:`starts`)."""
        return load_distribution_high_speed_full(self.sups[k].bearing, Fa=self.loaded(P, k)[:, 0], Fr=P[:, 1],
                                                 M=P[:, 2], n_rpm=n, start=start, **self.kw)

    def residual(self, P0, idx, starts=(None, None)):
        """Scaled compatibility (nb, m) of the cases ``idx`` at bearing 0's loads P0 (nb, 3), the slide w_1 and each
        bearing's solution (``starts``: theirs to start from, :meth:`starts`)."""
        n = self.n[idx]
        sols = (self.solve(P0, 0, n, starts[0]), self.solve(self.loads(P0, idx), 1, n, starts[1]))
        q0, q1 = (np.stack([ld.delta_a - c, ld.delta_r, ld.theta], axis=1) for (ld, _), c in zip(sols, self.c))
        r = q1 - q0 @ self.T1T0inv.T
        w = r[:, 0] if self.spring is not None else np.zeros(len(idx))
        r[:, 2] *= self.L
        return r[:, self.free] / self.A, w, sols

    def evaluate(self, z, idx):
        """(residual (nb, m), Jacobian (nb, m, m)) at z (nb, m): the base point and its m forward differences in one
        batched high-speed call per bearing, each started from the last evaluation's answer of its case."""
        nb, m = z.shape
        Z = np.repeat(z[:, None, :], m + 1, axis=1)
        Z[:, 1:, :] += _FD * np.eye(m)[None, :, :]
        idx_all = np.repeat(idx, m + 1)
        R, _, sols = self.residual(self.unknowns(Z.reshape(-1, m), idx_all), idx_all, self.starts(idx, m + 1))
        self.last = (idx, tuple(take(sol, np.arange(nb) * (m + 1), nb * (m + 1)) for sol in sols))
        R = R.reshape(nb, m + 1, m)
        J = np.swapaxes(R[:, 1:, :] - R[:, :1, :], 1, 2) / _FD
        return R[:, 0, :], J


def _external(Fa, Fr, M, x_load, n_rpm):
    """The cases as one flat batch: shape, P_ext (nb, 3) at x = 0 [N, N, N m] (checked and moved to x = 0 by
    :mod:`thermobear.loads.sets`' own) and the speeds (nb,) [rpm]."""
    n = np.asarray(n_rpm, dtype=float)
    shape = np.broadcast_shapes(*(np.shape(v) for v in (Fa, Fr, M, x_load)), n.shape)
    on = (lambda v: np.broadcast_to(np.asarray(v, dtype=float), shape))  # noqa: E731
    _, P = external_loads(on(Fa), on(Fr), on(M), 0.0, 0.0, on(x_load))
    n = on(n).ravel()
    if n.size and not (np.all(np.isfinite(n)) and np.all(n >= 0)):
        raise InputError("n_rpm", n, "the inner rings' speed must be finite and >= 0 [rpm]")
    return shape, P[:, :3], n


def _start(sups, P, stiffness, tilt_arm):
    """Bearing 0's loads (nb, 3) to start from and the cases' force scale (nb,) [N]: the low-speed shaft's, each
    bearing kept at ≥ 10 % of the scale axially (the high-speed form needs both loaded; at speed the balls'
    centrifugal force keeps a bearing loaded that the static pair unloads); where the low-speed shaft has no
    solution (a bearing unloaded completely), the external loads shared."""
    s0, s1 = sups[0].facing, sups[1].facing
    try:
        st = shaft_loads(sups, P[:, 0], P[:, 1], P[:, 2], stiffness=stiffness, tilt_arm=tilt_arm, refuse_overload=False)
        R = st.reactions.reshape(-1, 2, 5)
        R0, scale = R[:, 0, :3].copy(), np.maximum(np.abs(R[:, :, :2]).max(axis=(1, 2)), np.abs(P[:, :2]).max(axis=1))
    except SolverError:
        R0 = np.stack([np.maximum(s0 * P[:, 0], 0.0), 0.5 * P[:, 1], np.zeros(len(P))], axis=1)
        scale = np.abs(P[:, :2]).max(axis=1)
    scale = np.maximum(scale, 1e-3)
    if sups[1].spring is None:
        f = 0.1 * scale
        R0[:, 0] = np.maximum(R0[:, 0], np.maximum(f, f - s1 * P[:, 0]))
    return R0, scale


def _given_start(start, P):
    """Bearing 0's loads (nb, 3) to start from, given (e.g. a nearby solution's), and the cases' force scale (nb,)
    [N]: the larger of those loads and the external ones (as :func:`_start`'s)."""
    R0 = np.broadcast_to(np.asarray(start, float), (P.shape[0], 3)).copy()
    if not np.all(np.isfinite(R0)):
        raise InputError("start", start, "bearing 0's loads (Fa, Fr, M) to start from: finite [N, N, N m]")
    return R0, np.maximum(np.maximum(np.abs(R0[:, :2]).max(axis=1), np.abs(P[:, :2]).max(axis=1)), 1e-3)


def _newton(pb, z, tol, maxiter):
    """Damped Newton on every case: (z, scaled residual norm, iterations); NoConvergence names the first case that
    does not reach ``tol``."""
    nb = z.shape[0]
    idx = np.arange(nb)
    r, J = pb.evaluate(z, idx)
    norm = np.abs(r).max(axis=1)
    its = np.zeros(nb, dtype=int)
    live = np.flatnonzero(norm > tol)
    err = None                          # the last trial's error: what stopped a step that found no descent
    while live.size:
        dz = -np.linalg.solve(J[live], r[live][..., None])[..., 0]
        lam, todo = np.ones(live.size), np.arange(live.size)
        for _ in range(_HALVINGS):
            sel = live[todo]
            try:
                r_t, J_t = pb.evaluate(z[sel] + lam[todo, None] * dz[todo], sel)
                n_t = np.abs(r_t).max(axis=1)
            except SolverError as exc:  # loads the high-speed form cannot solve: shorter steps (all, in the batch)
                n_t, err = np.full(sel.size, np.inf), exc
            ok = n_t < norm[sel]
            if ok.any():
                took = sel[ok]
                z[took] += lam[todo[ok], None] * dz[todo[ok]]
                r[took], J[took], norm[took] = r_t[ok], J_t[ok], n_t[ok]
            lam[todo[~ok]] *= 0.5
            todo = todo[~ok]
            if not todo.size:
                break
        its[live] += 1
        if todo.size:                   # no descent along the Newton step: stop those cases
            its[live[todo]] = maxiter
        live = live[norm[live] > tol]
        P0 = pb.unknowns(z[live], live)    # a bearing unloading (F_a < 10⁻³ of the scale): no equilibrium ahead
        its[live[np.minimum(P0[:, 0], pb.loads(P0, live)[:, 0]) < 1e-3 * pb.unit[live, 0]]] = maxiter
        live = live[its[live] < maxiter]
    if np.any(norm > tol):
        k = int(np.argmax(norm > tol))
        P0 = pb.unknowns(z[k:k + 1], np.array([k]))
        Fa_k = np.array([P0[0, 0], pb.loads(P0, np.array([k]))[0, 0]])
        if Fa_k.min() < 1e-2 * pb.unit[k, 0]:
            err = NoEquilibrium(f"bearing {int(np.argmin(Fa_k))} of the pair unloads axially (F_a {Fa_k.min():.3g} N "
                                "→ 0 along the steps: the other carries the external load alone, its balls lifted "
                                "off the inner race — beyond the high-speed form, which needs both bearings loaded)",
                                field="Fa, Fr, M (shaft loads)")
        if isinstance(err, NoEquilibrium):
            raise NoEquilibrium(
                f"high-speed shaft on two bearings: no equilibrium for Fa = {pb.P[k, 0]:g} N, Fr = {pb.P[k, 1]:g} N, "
                f"M = {pb.P[k, 2]:g} N m at {pb.n[k]:g} rpm — the steps towards it end where {err}",
                field=err.field, iterations=int(its[k]), residual=float(norm[k])) from err
        raise NoConvergence(
            f"high-speed shaft on two bearings: compatibility not reached for Fa = {pb.P[k, 0]:g} N, Fr = "
            f"{pb.P[k, 1]:g} N, M = {pb.P[k, 2]:g} N m at {pb.n[k]:g} rpm (scaled residual {norm[k]:.3g} after "
            f"{its[k]} Newton steps)", iterations=int(its[k]), residual=float(norm[k]))
    return z, norm, its


def shaft_loads_high_speed(supports, Fa=0.0, Fr=0.0, n_rpm=0.0, *, M=0.0, x_load=0.0, control: str = "outer",
                           stiffness: str = "nominal", tilt_arm: str = "groove", tol: float = _TOL,
                           maxiter: int = _MAXIT, refuse_overload: bool = True, start=None) -> HighSpeedShaftLoads:
    r"""Equilibrium of a rigid shaft on two bearings with each bearing's high-speed load–displacement relation.

    Parameters
    ----------
    supports : sequence of two Support   the bearings (position preload by ``offset``; a spring on the second
                        only); their geometry as it runs (warm, at speed: :func:`~thermobear.loads.sets.warm_supports`)
    Fa : array_like     axial load on the shaft, towards +x [N]
    Fr : array_like     radial load along y [N], acting at ``x_load`` [m]
    n_rpm : array_like  speed of the inner rings (with the shaft) [rpm], ≥ 0; the outer rings fixed
    M : array_like      moment in the x–y plane [N m]
    control, stiffness, tilt_arm : as :func:`thermobear.loads.highspeed.load_distribution_high_speed`
    tol, maxiter : Newton tolerance (scaled compatibility residual) and steps
    start : array_like or HighSpeedShaftLoads
                        bearing 0's loads (Fa, Fr, M) [N, N, N m] to start Newton from, one per case (e.g. a nearby
                        answer's ``reactions[..., 0, :3]``), or a nearby answer of the same cases (a heat-up's last):
                        its loads, and its bearings' ball equilibria to start their high-speed solves from; default
                        the low-speed shaft's

    Returns
    -------
    HighSpeedShaftLoads

    Raises
    ------
    InputError       bad input; loads the contacts cannot carry (named ``Fa, Fr, M (shaft loads)``)
    NoEquilibrium    a bearing losing its axial load (the high-speed form needs both loaded), or a loaded ball's
                     contact angle passing 0 (as the low-speed :func:`~thermobear.loads.sets.shaft_loads`)
    NoConvergence    Newton did not reach ``tol``

    Notes
    -----
    .. math::

        P_1 = T_1^{-T}(P_{ext} − T_0^T P_0), \qquad
        q_1(P_1) − (c_1 + w_1) e_a = T_1 T_0^{-1}\bigl(q_0(P_0) − c_0 e_a\bigr)

    (module docstring; Jones 1960; Harris & Kotzalas 2007, *Essential Concepts* ch. 8 and *Advanced Concepts*
    ch. 1–3).  At n = 0 it equals :func:`~thermobear.loads.sets.shaft_loads`.

    Examples
    --------
    A 7014C back-to-back pair with 20.8 µm position preload (300 N cold at rest): the same at n = 0, and about
    three times as much at 12 000 rpm with the rings' geometry at rest (the balls' centrifugal force alone).

    >>> from thermobear.contact.geometry import bearing
    >>> from thermobear.loads.pair import pair_preload_offset
    >>> from thermobear.loads.sets import duplex_supports
    >>> b = bearing("7014C")
    >>> sups, _ = duplex_supports(b, "back_to_back", preload_offset=pair_preload_offset(b, 300.0))
    >>> [round(float(shaft_loads_high_speed(sups, n_rpm=n).preload[0]), 1) for n in (0.0, 12000.0)]
    [300.0, 902.6]
    """
    sups = tuple(supports)
    if len(sups) != 2 or not all(isinstance(s, Support) for s in sups):
        raise InputError("supports", supports, "two Support(bearing, x, facing, offset, spring)")
    if sups[0].spring is not None:
        raise InputError("supports", supports, "a spring-held outer ring on the second support only")
    if any(s.bearing.kind != "angular_contact" for s in sups):
        raise InputError("supports", supports, "two angular contact bearings (a preloaded pair)")
    shape, P, n = _external(Fa, Fr, M, x_load, n_rpm)
    near = start if isinstance(start, HighSpeedShaftLoads) else None
    if near is not None:
        start = near.reactions.reshape(-1, 2, 5)[:, 0, :3]
    R0, scale = _start(sups, P, stiffness, tilt_arm) if start is None else _given_start(start, P)
    pb = _Pair(sups, P, n, control, stiffness, tilt_arm, scale)
    if near is not None and near.reactions.size == 10 * P.shape[0]:     # (its cases: the balls' start too)
        pb.last = (np.arange(P.shape[0]), tuple(zip(near.loads, near.extras)))
    z, norm, its = _newton(pb, R0[:, pb.free] / pb.unit[:, pb.free], tol, maxiter)
    idx = np.arange(P.shape[0])
    P0 = pb.unknowns(z, idx)
    P1 = pb.loads(P0, idx)
    _, w, sols = pb.residual(P0, idx, pb.starts(idx, 1))      # (w: a spring-held outer ring's slide)
    lds, exs = zip(*sols)
    if refuse_overload:
        for s, ld in zip(sups, lds):
            refuse_overload_of(s.bearing, ld, field="Fa, Fr, M (shaft loads)")
    q = np.stack([lds[0].delta_a - pb.c[0], lds[0].delta_r, lds[0].theta], axis=1) @ np.linalg.inv(pb.T[0]).T
    reac = np.zeros((P.shape[0], 2, 5))
    reac[:, 0, :3], reac[:, 1, :3] = P0, P1
    slide = np.zeros((P.shape[0], 2))
    slide[:, 1] = w
    return HighSpeedShaftLoads(q=q.reshape(shape + (3,)), loads=tuple(lds), extras=tuple(exs),
                               reactions=reac.reshape(shape + (2, 5)), slide=slide.reshape(shape + (2,)),
                               supports=sups, n_rpm=n.reshape(shape), residual=float(norm.max()) if norm.size else 0.0,
                               iterations=int(its.max()) if its.size else 0)
