r"""Low-speed quasi-static load distribution of a ball bearing with rigid rings.

Equal inner and outer contact angles, no centrifugal force or gyroscopic moment: Jones (1960) [1]
at low speed, Harris (2001) [2] §7.4, seed 004 eqs 6–8 [3] (there without tilt), generalised to radial loads in both directions, tilts
and moments about both radial axes: the five-degree-of-freedom rigid-ring model of ISO/TS 16281 [4].

With the groove-centre offsets A1_j, A2_j of :mod:`thermobear.loads.rings` (five ring unknowns: δa, δr, θ
in the x–y plane, δz, θ_y in the x–z plane), ball j carries

.. math::

    A_j = \sqrt{A_{1j}^2 + A_{2j}^2}, \quad \tan α_j = A_{1j}/A_{2j}, \quad
    Q_j = K_n \max(A_j − A, 0)^{1.5}

(K_n the ball's inner and outer Hertz contacts in series, Harris 2001 eq 7.3 form), and the inner
ring is in equilibrium when

.. math::

    F_a = Σ_j Q_j \sin α_j, \quad F_r = Σ_j Q_j \cos α_j \cos ψ_j, \quad F_z = Σ_j Q_j \cos α_j \sin ψ_j,

    M = Σ_j Q_j \sin α_j ℜ \cos ψ_j, \quad M_y = Σ_j Q_j \sin α_j ℜ \sin ψ_j .

Unknowns y = (δa'/A, δr/A, θℜ/A, δz/A, θ_yℜ/A), δa' the axial displacement from the position where
the balls just touch at α0 (δa = δa' + A sin α0); in-plane loads (F_z = M_y = 0) solve the first three
(δz = θ_y = 0 by symmetry).  The approach A_j − A is formed without cancellation,
s = [2A(sin α0 d1 + cos α0 d2) + d1² + d2²]/(A_j + A) with (d1, d2) = y·L, so that tiny loads
(|s| ≪ A) keep full relative precision.  The Jacobian is the stiffness matrix, exact and symmetric:
per ball dQ n nᵀ + (Q/A_j) e eᵀ (n = (sin α, cos α), e = (cos α, −sin α)), summed with the lever
arms of L.  Solved by the shared damped Newton (:mod:`thermobear.loads.newton`) from the pure-axial
closed form (:func:`axial_contact_angle`) and Stribeck's radial estimate; a case that fails is
solved again by continuation in the load magnitude (:func:`load_distribution_static`, Notes).

References
----------
.. [1] Jones, A. B. (1960). A general theory for elastically constrained ball and radial roller
   bearings under arbitrary load and speed conditions. *J. Basic Eng.* 82(2):309–320.
.. [2] Harris, T. A. (2001). *Rolling Bearing Analysis*, 4th ed., Wiley, ch. 7 (§7.4; eq 7.36 pure
   axial load) and ch. 8 (eq 8.9, centrifugal force).
.. [3] Darul, Ł. et al. (2024). Power losses in an oil-jet lubricated angular contact ball bearing:
   rolling, sliding and drag (seed 004), *Lubricants* 12:14, §2.2 eqs 6–8.
.. [4] ISO/TS 16281:2008. Rolling bearings — Methods for calculating the modified reference rating
   life for universally loaded bearings (rigid rings; reference cases of the validation).
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from thermobear.contact.geometry import BallBearing
from thermobear.errors import InputError, NoConvergence, NoEquilibrium
from thermobear.loads.newton import NewtonOptions, RowState, continuation, newton
from thermobear.loads.rings import (STIFFNESS_MODES, LoadDistribution, RingLoads, arm_length, azimuths,
                                    check_stiffness, force_scale, groove_offsets, lever_matrix, ring_direction,
                                    ring_loads, ring_sums, unbatch)

__all__ = ["load_distribution_static", "ring_reaction", "reaction_problem", "reaction_of", "axial_contact_angle", "needs_high_speed", "LoadDistribution",
           "STIFFNESS_MODES"]

_TOL = 1e-12          # relative equilibrium residual at which Newton stops
_MAXIT = 60
_HALVINGS = 30        # line-search halvings per Newton step


def axial_contact_angle(brg: BallBearing, Fa, Kn=None, tol: float = 1e-14):
    r"""Contact angle under a pure axial load, all balls equal [rad].

    Solves

    .. math::

        \frac{F_a}{Z K_n A^{1.5}} = \sin α \left(\frac{\cos α_0}{\cos α} − 1\right)^{1.5}

    (Harris 2001 eq 7.36, written with A = (fi + fo − 1) D so that no B^1.5 factor is lost).  With
    t = cos α0 / cos α − 1 the equation reads t^1.5 · √(t (t + 2) + sin² α0) / (1 + t) = F_a / (Z K_n A^1.5),
    whose logarithm is close to linear in s = ln t (slope between 1.5 and 2); a vectorised Newton
    iteration on s converges in 2–4 steps from s = ln(F_a / (Z K_n A^1.5) / sin α0) / 1.5, and
    α = atan2(√(t (t + 2) + sin² α0), cos α0) keeps the small angles of a deep groove bearing accurate.

    Parameters
    ----------
    brg : BallBearing
    Fa : array_like   axial load [N], ≥ 0
    Kn : float        ball stiffness [N/m^1.5] (default: ``brg.Kn()`` at the nominal angle)

    Returns
    -------
    ndarray  contact angle α [rad]; α0 where Fa = 0

    Examples
    --------
    >>> from thermobear.contact.geometry import bearing
    >>> b = bearing("iso-dgbb")
    >>> a = axial_contact_angle(b, 1000.0)
    >>> Kn, A = b.Kn(), b.A
    >>> lhs = 1000.0 / (b.Z * Kn * A**1.5)
    >>> rhs = np.sin(a) * (1.0 / np.cos(a) - 1.0) ** 1.5
    >>> bool(abs(lhs / rhs - 1) < 1e-12)
    True
    """
    Fa = np.asarray(Fa, dtype=float)
    Kn = brg.Kn() if Kn is None else Kn
    a0 = brg.alpha0
    if brg.kind == "thrust" and a0 >= np.pi / 2 - 1e-12:
        # α stays 90°: the approach is Fa/(Z Kn) ^ (2/3) along the axis
        return np.full_like(Fa, np.pi / 2)
    c2, s2 = np.cos(a0) ** 2, np.sin(a0) ** 2
    ln_target = np.log(np.where(Fa > 0, Fa, 1.0) / (brg.Z * Kn * brg.A**1.5))
    # start: the small-deflection limits t^1.5 sin α0 = target, or for α0 = 0, √2 t² = target
    s = (ln_target - 0.5 * np.log(s2)) / 1.5 if s2 > 1e-12 else 0.5 * (ln_target - 0.5 * np.log(2.0))
    for _ in range(100):
        t = np.exp(s)
        w = 1.0 + t
        q = t * (t + 2.0) + s2                       # (1 + t)² − cos² α0 without cancellation
        ds = (1.5 * s + 0.5 * np.log(q / (w * w)) - ln_target) / (1.5 + c2 * t / (w * q))
        s = s - ds
        if (np.abs(ds) <= tol).all():
            break
    t = np.exp(s)
    al = np.clip(np.arctan2(np.sqrt(t * (t + 2.0) + s2), np.sqrt(c2)), a0 + 1e-12, np.pi / 2 - 1e-9)
    return np.where(Fa > 0, al, a0)


def needs_high_speed(brg: BallBearing, n_rpm, Q_typical, threshold: float = 0.05, rotating: str = "inner"):
    r"""Does the centrifugal ball force matter against the contact load?

    Criterion (documented choice): the low-speed form is used when the ball
    centrifugal force F_c = ½ m dm ω_c² (Harris 2001 eq 8.9, ω_c = ½ω(1 ∓ γ) the cage
    speed with the inner / outer ring rotating) is below ``threshold`` (5 %) of the typical
    ball load.  At the threshold the high-speed solution
    (:mod:`thermobear.loads.highspeed`) has |Q_o − Q_i|/Q ≈ 0.04 and contact angles
    moved by 1.3–1.4° (218 at two loads, 7210 at 450 and 2000 N; tests/test_loads_highspeed.py).
    Returns a boolean (array) and the ratio F_c / Q.

    The seed 004 7210 at 6500 rpm under Fa = 450 N (ball load ≈ 47 N): F_c ≈ 25 N, so
    the criterion asks for the high-speed form although seed 004 neglects it (N dm < 1e6
    was its argument); at 1000 rpm it does not:

    >>> from thermobear.contact.geometry import bearing
    >>> need, ratio = needs_high_speed(bearing("7210"), [1000.0, 6500.0], 450.0 / (15 * np.sin(0.698)))
    >>> need.tolist(), np.round(ratio, 3).tolist()
    ([False, True], [0.013, 0.541])
    """
    omega = np.asarray(n_rpm, dtype=float) * np.pi / 30.0
    gamma = brg.gamma(brg.alpha0)
    omega_c = 0.5 * omega * (1.0 - gamma if rotating == "inner" else 1.0 + gamma)
    Fc = 0.5 * brg.ball_mass * brg.dm * omega_c**2
    ratio = Fc / np.maximum(np.asarray(Q_typical, dtype=float), 1e-300)
    return ratio > threshold, ratio


def _constants(brg, ndof):
    """Fixed arrays of a bearing (formed with each problem, ≈ 20 µs): the lever matrix L (ndof, 2Z) [m], the
    groove-centre offsets at first touch (A_a0 | A_r0) (2Z,) and twice them, the sum matrix
    (5 Z, ndof² + ndof) turning per-ball rows (g_aa, g_ar, g_rr, Q sin α, Q cos α) into the Jacobian and the
    ring forces (:func:`thermobear.loads.rings.ring_sums`), K_n at the nominal angle [N/m^1.5]
    (:attr:`~thermobear.contact.geometry.BallBearing.K_nominal`) and the constant c of the approach [m²] (0, or
    the radial preload's: :func:`thermobear.loads.rings.groove_offsets`)."""
    Z = brg.Z
    L = lever_matrix(brg, ndof)
    sums = ring_sums(Z, ndof)
    a0, r0, c = groove_offsets(brg)
    A0 = np.concatenate([np.full(Z, a0), np.full(Z, r0)])
    return L, A0, 2.0 * A0, sums, float(brg.Kn()), c


class _StaticState(RowState):
    """Residual, Jacobian and ball geometry at one iterate (leading axis: the load cases)."""

    FIELDS = ("y", "AA", "Aj", "s", "res", "J", "norm")


class _StaticProblem:
    """The low-speed equilibrium of a batch of load cases as a problem of :func:`thermobear.loads.newton.newton`.

    Unknowns y (nb, ndof) (module docstring); the unknowns with ``free`` 0 (the tilts when no moment is given)
    are held."""

    def __init__(self, brg, F_app, scale, free, stiffness):
        self.brg, self.F_app, self.scale = brg, F_app, scale
        self.ndof = F_app.shape[1]
        self.inv_scale = 1.0 / scale[:, None]
        self.J_scale = (brg.A / scale)[:, None, None]
        self.zero = np.max(np.abs(F_app), axis=1) == 0.0
        self.any_zero = bool(self.zero.any())
        self.free, self.per_ball = free, stiffness == "per_ball"
        fi = np.flatnonzero(free)
        self.all_free = fi.size == free.size
        self.free_idx = slice(0, fi.size) if fi.size and fi[-1] == fi.size - 1 else fi    # a prefix: a view
        self.Z, self.A = brg.Z, brg.A
        self.L, self.A0, self.A0x2, self.sums, self.Kn0, self.c0 = _constants(brg, self.ndof)

    def rows(self, idx):
        new = _StaticProblem.__new__(_StaticProblem)
        new.__dict__.update(self.__dict__)
        new.F_app, new.scale, new.zero = self.F_app[idx], self.scale[idx], self.zero[idx]
        new.inv_scale, new.J_scale = self.inv_scale[idx], self.J_scale[idx]
        new.any_zero = bool(new.zero.any())
        return new

    def geometry(self, y):
        """Groove-centre offsets (A1 | A2) (nb, 2Z), their distance A_j and the signed approach s = A_j − A
        (nb, Z) [m] (negative: a gap), formed without cancellation (a radial preload's constant c included,
        :func:`thermobear.loads.rings.groove_offsets`)."""
        Z = self.Z
        d = y @ self.L
        AA = d + self.A0
        sq = AA * AA
        Aj = np.sqrt(sq[:, :Z] + sq[:, Z:])
        t = d * (self.A0x2 + d)
        t = t[:, :Z] + t[:, Z:]
        if self.c0:
            t += self.c0
        s = t / (Aj + self.A)
        return AA, Aj, s

    def evaluate(self, y):
        Z, nb, nd = self.Z, y.shape[0], self.ndof
        AA, Aj, s = self.geometry(y)
        sp = np.maximum(s, 0.0)
        if self.per_ball:
            Kn = self.brg.Kn(np.arctan2(AA[:, :Z], AA[:, Z:]))
            dQ = 1.5 * Kn * np.sqrt(sp)
        else:
            Kn = self.Kn0
            dQ = np.sqrt(sp)
            dQ *= 1.5 * Kn
        Q = sp * dQ
        Q *= 1.0 / 1.5                                            # K_n s^1.5
        n = AA.reshape(nb, 2, Z) / Aj[:, None, :]                 # (sin α, cos α)
        if Aj.min() > 0:
            Qa = Q / Aj
        else:                                                     # groove centres on one point (unloaded thrust)
            Qa = np.divide(Q, Aj, out=np.zeros_like(Q), where=Aj > 0)
        nn = n * n
        sa, ca = n[:, 0], n[:, 1]
        P = np.empty((nb, 5, Z))
        # per-ball stiffness g = dQ n nᵀ + (Q/A_j) e eᵀ and forces Q n, summed over the balls by one
        # product with the lever arms (see _constants)
        np.add(dQ * nn[:, 0], Qa * nn[:, 1], out=P[:, 0])
        np.multiply((dQ - Qa) * sa, ca, out=P[:, 1])
        np.add(dQ * nn[:, 1], Qa * nn[:, 0], out=P[:, 2])
        np.multiply(Q[:, None, :], n, out=P[:, 3:])
        out = P.reshape(nb, 5 * Z) @ self.sums
        st = _StaticState.__new__(_StaticState)
        st.y, st.AA, st.Aj, st.s = y, AA, Aj, s
        n2 = nd * nd
        st.res = (out[:, n2:] - self.F_app) * self.inv_scale
        st.J = out[:, :n2].reshape(nb, nd, nd) * self.J_scale
        norm = np.abs(st.res if self.all_free else st.res[:, self.free_idx]).max(axis=1)
        st.norm = np.where(self.zero, 0.0, norm) if self.any_zero else norm
        return st

    def direction(self, st):
        return ring_direction(st.J, st.res, self.free)


def _start(brg, F, ndof, tilt_free, arm, Kn0):
    """Scaled unknowns y (nb, ndof) to start from, the loads F (nb, 5) [N, N m]: the pure-axial closed form for
    F_a (plus a share of the radial load for an angular contact bearing), Stribeck's Q_max ≈ 5 F_r/(Z cos α)
    along the radial load, and a tilt carrying a moment larger than the other loads at the balls on its plane."""
    Z, A = brg.Z, brg.A
    Fa, Fy, Mv, Fz, My = F.T
    nb = Fa.size
    y = np.zeros((nb, ndof))
    Fr = np.hypot(Fy, Fz)
    if brg.kind == "thrust":
        y[:, 0] = (Fa / Z / Kn0) ** (2.0 / 3.0) / A
    else:
        Fa_eff = Fa + (1.25 * Fr * np.tan(brg.alpha0) if brg.kind == "angular_contact" else 0.0)
        al = axial_contact_angle(brg, Fa_eff, Kn0)
        y[:, 0] = np.where(Fa_eff > 0, np.cos(brg.alpha0) * np.tan(al) - np.sin(brg.alpha0), -np.sin(brg.alpha0))
        ca0 = np.cos(np.where(Fa_eff > 0, al, brg.alpha0))
        Qmax = 5.0 * Fr / (Z * np.maximum(ca0, 0.2))
        # the clearance is taken up radially only when no axial load has taken it up already
        dr0 = (Qmax / Kn0) ** (2.0 / 3.0) / np.maximum(ca0, 0.2) + np.where(Fa_eff > 0, 0.0, brg.Pd / 2.0)
        if brg.Pd < 0:       # a radial preload: at most the ring's travel under its preloaded stiffness
            dr0 = np.minimum(np.maximum(dr0, 0.0), Fr / (0.75 * Z * Kn0 * np.sqrt(-0.5 * brg.Pd)))
        nr = np.where(Fr > 0, Fr, 1.0)
        y[:, 1] = np.where(Fr > 0, dr0 / A * (Fy / nr), 0.0)
        if ndof == 5:
            y[:, 3] = np.where(Fr > 0, dr0 / A * (Fz / nr), 0.0)
    if tilt_free:
        Mabs = np.hypot(Mv, My) if ndof == 5 else np.abs(Mv)
        Fm_eq = 4.0 * Mabs / (arm * Z) * Z              # rough axial load of the most loaded balls
        mdom = Mabs / arm > np.maximum(Fa, Fr)
        if np.any(mdom) and brg.kind != "thrust":
            t = np.cos(brg.alpha0) * np.tan(axial_contact_angle(brg, Fm_eq[mdom], Kn0))
            if ndof == 5:
                y[mdom, 2] = t * Mv[mdom] / Mabs[mdom]
                y[mdom, 4] = t * My[mdom] / Mabs[mdom]
            else:
                y[mdom, 2] = np.sign(Mv[mdom]) * t
    return y


def _over_shoulder(pb, y):
    """Per case: a loaded ball of an angular contact bearing has its groove centres at A1 ≤ 0 (its contact
    would run over the low shoulder)."""
    if pb.brg.kind != "angular_contact":
        return np.zeros(y.shape[0], bool)
    AA, Aj, s = pb.geometry(y)
    return np.any((s > 0) & (AA[:, :pb.Z] <= 0), axis=1)


def _solve(brg, loads, stiffness, tol, maxiter, arm, y0=None, factor=1.0):
    """Newton from the closed-form start (or ``y0``) on a batch of load cases (:class:`RingLoads`, scaled by
    ``factor``): NewtonResult and the problem."""
    F_app = loads.applied(arm, factor)                                   # moments as forces at the arm ℜ
    scale = np.maximum(force_scale(brg, F_app), 1e-300)
    pb = _StaticProblem(brg, F_app, scale, loads.free(), stiffness)
    if y0 is None:
        y0 = _start(brg, loads.F if factor == 1.0 else factor * loads.F, loads.ndof, loads.tilt_free, arm, pb.Kn0)
    return newton(pb, np.array(y0, dtype=float), NewtonOptions(tol=tol, maxiter=maxiter, halvings=_HALVINGS)), pb


def _continue_in_load(brg, loads, stiffness, tol, maxiter, arm):
    """Continuation in the load magnitude for the cases ``loads`` that failed from the closed-form start: the
    same load ratios ×10, ×100, … ×1e6 from the closed-form start until one converges (for each case its first
    k), then back down in steps of √10 to the given loads, each from the last solution.  Returns a
    ContinuationResult (unknowns y, ``ok`` per case, iterations)."""
    thr = max(tol, 1e-9)
    nc = loads.nb
    k_up = np.zeros(nc, int)
    y_up = np.zeros((nc, loads.ndof))
    its = np.zeros(nc, int)
    for k in range(1, 7):
        todo = np.flatnonzero(k_up == 0)
        if not todo.size:
            break
        r, _ = _solve(brg, loads.rows(todo), stiffness, tol, maxiter, arm, factor=10.0 ** k)
        its[todo] += r.iterations
        good = r.norm <= thr
        k_up[todo[good]] = k
        y_up[todo[good]] = r.z[good]
    path = np.full((nc, 12), np.nan)
    for j in range(nc):
        if k_up[j]:
            e = np.arange(2 * k_up[j] - 1, -1, -1) / 2.0
            path[j, :e.size] = 10.0 ** e

    def solve(idx, y, f, stage):
        sub = loads.rows(idx)
        sub = RingLoads(sub.shape, f[:, None] * sub.F, sub.tilt_free, sub.ndof)
        r, _ = _solve(brg, sub, stiffness, tol, maxiter, arm, y0=y)
        r.converged = r.norm <= thr
        return r

    res = continuation(solve, y_up, path)
    res.iterations += its
    res.ok &= k_up > 0
    return res


def load_distribution_static(brg: BallBearing, Fa=0.0, Fr=0.0, M=None, *, Fz=0.0, My=None,
                             stiffness: str = "nominal", tol: float = _TOL, maxiter: int = _MAXIT, start=None,
                             continuation: bool = True, tilt_arm: str = "groove") -> LoadDistribution:
    r"""Quasi-static (low-speed) load distribution, rigid rings, five degrees of freedom.

    Parameters
    ----------
    brg : BallBearing
    Fa : array_like    axial load on the inner ring [N], ≥ 0
    Fr : array_like    radial load on the inner ring along y (towards ψ = 0) [N]
    M : array_like     moment in the x–y plane [N m] (loads the balls at ψ = 0 towards +x; = −M_z)
    Fz : array_like    radial load along z (towards ψ = 90°) [N]
    My : array_like    moment about +y [N m] (loads the balls at ψ = 90° towards +x); ``M`` and ``My``
                       ``None`` hold both tilts at 0 (shaft held by two bearings), either given frees both
    stiffness : str    ``"nominal"`` (K_n at the nominal contact angle: ISO/TS 16281 practice, default)
                       or ``"per_ball"`` (K_n re-evaluated at each ball's contact angle)
    tol : float        relative equilibrium residual (forces / largest applied load) at which Newton stops
    maxiter : int      Newton iterations per attempt
    start : LoadDistribution or array_like, optional
                       ring displacements to start Newton from — a nearby solution, or (δa, δr, θ) or
                       (δa, δr, θ, δz, θ_y) [m, m, rad, m, rad] per case on a last axis; default: the
                       closed-form start (module docstring)
    continuation : bool
                       solve a case that fails from the start again by continuation in the load
                       magnitude (Notes); ``False``: report it (NoConvergence) at once
    tilt_arm : str     the tilt arm ℜ (:data:`thermobear.loads.rings.TILT_ARMS`): ``"groove"`` (ℜ_i, default) or
                       ``"pitch"`` (d_m/2, the ISO/TS 16281 reference examples)

    Returns
    -------
    LoadDistribution   fields gain a leading batch axis when the loads are arrays

    Raises
    ------
    NoEquilibrium      loads the bearing cannot carry (radial load on a thrust bearing,
                       radial load without axial on a single angular contact bearing)
    NoConvergence      Newton did not reach the tolerance (carries the residual and iterations)

    Notes
    -----
    Seed 004 eqs 6–8; Harris 2001 §7.4; Jones 1960; the module docstring has the equations and
    conventions.  Loads with F_z = 0 and M_y = 0 are solved with δz = θ_y = 0 (the three in-plane
    unknowns; exact by symmetry, :mod:`thermobear.loads.rings`).  A case whose Newton iteration fails
    from the closed-form start is solved again by continuation in the load magnitude: the same load
    ratios ×10, ×100, ... until it converges, then back down to the given loads in steps of √10, each
    step started from the last solution (at very light loads the solution is almost pure geometry — the
    contact angles of the few loaded balls set by Fa/Fr — and the Hertz approach too small to guide
    Newton there).

    Examples
    --------
    ISO/TS 16281 reference case (Fr = 1000 N, no clearance: δr = 15.1101 µm); the same load along z, between
    the balls of this 7-ball bearing, moves the ring a little further and a little off its line:

    >>> from thermobear.contact.geometry import bearing
    >>> ld = load_distribution_static(bearing("iso-dgbb"), Fa=0.0, Fr=1000.0)
    >>> round(ld.delta_r * 1e6, 3), ld.residual < 1e-9
    (15.11, True)
    >>> lz = load_distribution_static(bearing("iso-dgbb"), Fr=0.0, Fz=1000.0)
    >>> round(lz.delta_z * 1e6, 3), round(lz.delta_r * 1e6, 3)
    (15.187, 0.4)
    """
    check_stiffness(stiffness)
    loads = ring_loads(brg, Fa, Fr, M, Fz, My)
    arm = arm_length(brg, tilt_arm)
    A = brg.A
    y0 = None if start is None else _start_unknowns(brg, start, loads.nb, loads.ndof, arm)
    r, pb = _solve(brg, loads, stiffness, tol, maxiter, arm, y0)
    y, norm, its = r.z, r.norm, r.iterations
    thr = max(tol, 1e-9)                # (a NaN residual — a singular step, an overflow — counts as failed)
    bad = ~(norm <= thr)
    if continuation and brg.kind != "thrust" and bad.any():
        k = np.flatnonzero(bad & ~_over_shoulder(pb, y))      # over the shoulder: no equilibrium (below)
        if k.size:
            c = _continue_in_load(brg, loads.rows(k), stiffness, tol, maxiter, arm)
            its[k] += c.iterations
            ok = k[c.ok]
            y[ok], norm[ok] = c.z[c.ok], c.norm[c.ok]
    bad = ~(norm <= thr)
    if bad.any():
        k = int(np.argmax(np.where(bad, np.nan_to_num(norm, nan=np.inf), -1.0)))
        last = y[k] * np.array([A, A, A / arm, A, A / arm])[:loads.ndof]
        if _over_shoulder(pb, y[k:k + 1])[0]:
            raise NoEquilibrium(
                f"angular contact bearing: Fa = {loads.Fa[k]:g} N is too small for the radial load and moment "
                f"({loads.case(k)}) — the balls would have to run over the low shoulder (contact angle <= 0)",
                iterations=int(its[k]), residual=float(norm[k]), last=last)
        raise NoConvergence(
            f"load distribution did not reach equilibrium for {loads.case(k)}: relative residual {norm[k]:.3g} "
            f"after {its[k]} Newton iterations", iterations=int(its[k]), residual=float(norm[k]), last=last)
    return _result(brg, pb, y, norm, its, loads, arm, Fa, Fr)


def _start_unknowns(brg, start, nb, ndof, arm):
    """Scaled unknowns y (nb, ndof) from a LoadDistribution or (δa, δr, θ[, δz, θ_y]) [m, m, rad, m, rad] on a
    last axis."""
    A = brg.A
    if isinstance(start, LoadDistribution):
        v = np.stack(np.broadcast_arrays(*(np.asarray(getattr(start, k), float)
                                           for k in ("delta_a", "delta_r", "theta", "delta_z", "theta_y"))), axis=-1)
    else:
        v = np.asarray(start, dtype=float)
    n = v.shape[-1] if v.ndim else 0
    ok = n in (3, 5) and v.size in (n, n * nb) and np.all(np.isfinite(v))
    if not ok:
        raise InputError("start", start, "a LoadDistribution of the same batch or finite (delta_a, delta_r, theta"
                         "[, delta_z, theta_y]) [m, m, rad, m, rad] per case on a last axis")
    v = np.broadcast_to(v.reshape(-1, n), (nb, n))
    if n < ndof:
        v = np.concatenate([v, np.zeros((nb, ndof - n))], axis=1)
    y = np.stack([(v[:, 0] - brg.A_a0) / A, v[:, 1] / A, v[:, 2] * arm / A], axis=1)
    if ndof == 5:
        y = np.concatenate([y, np.stack([v[:, 3] / A, v[:, 4] * arm / A], axis=1)], axis=1)
    return y


def _result(brg, pb, y, norm, its, loads, arm, Fa, Fr):
    """The LoadDistribution at the solution y (nb, ndof)."""
    A, Z, shape = brg.A, brg.Z, loads.shape
    zero = pb.zero
    AA, Aj, s = pb.geometry(y)
    sp = np.maximum(s, 0.0)
    A1, A2 = AA[:, :Z], AA[:, Z:]
    al = np.arctan2(A1, A2)
    Kn = brg.Kn(al) if pb.per_ball else pb.Kn0
    Q = Kn * sp ** 1.5
    if zero.any() and brg.Pd >= 0:     # unloaded (a radial preload loads every ball: Q_0, rings centred)
        Q = np.where(zero[:, None], 0.0, Q)
        sp = np.where(zero[:, None], 0.0, sp)
    alpha = al if brg.kind == "deep_groove" else np.where(Q > 0, al, brg.alpha0)
    if brg.kind == "angular_contact" and np.any((Q > 0) & (alpha <= 0)):
        raise NoEquilibrium("angular contact bearing: a loaded ball would need a contact angle <= 0 "
                            "(contact over the low shoulder); the axial load is too small for the radial load")
    if brg.kind == "deep_groove" and zero.any():
        alpha = np.where(zero[:, None], 0.0, alpha)
    out5 = np.zeros((y.shape[0], 5))
    out5[:, 0] = np.where(zero, 0.0, y[:, 0] * A + brg.A_a0)     # from the centred position
    for k in range(1, y.shape[1]):
        out5[:, k] = np.where(zero, 0.0, y[:, k] * A if k % 2 else y[:, k] * A / arm)
    return LoadDistribution(
        delta_a=unbatch(shape, out5[:, 0]), delta_r=unbatch(shape, out5[:, 1]), theta=unbatch(shape, out5[:, 2]),
        Q_i=unbatch(shape, Q, True), Q_o=unbatch(shape, Q.copy(), True), alpha_i=unbatch(shape, alpha, True),
        alpha_o=unbatch(shape, alpha.copy(), True), psi=azimuths(Z), delta_n=unbatch(shape, sp, True),
        residual=float(norm.max()) if norm.size else 0.0, iterations=int(its.max()) if its.size else 0,
        delta_z=unbatch(shape, out5[:, 3]), theta_y=unbatch(shape, out5[:, 4]), **loads.result_fields(Fa, Fr))


def ring_reaction(brg: BallBearing, q, *, stiffness: str = "nominal", tilt_arm: str = "groove"):
    r"""The loads that hold the inner ring at a given displacement, the ring's stiffness matrix there and the
    load distribution.

    The displacement-controlled static form: one evaluation of the equilibrium of
    :func:`load_distribution_static` at the ring displacement q instead of a solve for it.

    Parameters
    ----------
    brg : BallBearing
    q : array_like     (δa, δr, θ, δz, θ_y) [m, m, rad, m, rad] on the last axis (leading axes: cases); δa from
                       the centred position, axes and signs of :mod:`thermobear.loads.rings`
    stiffness, tilt_arm : as :func:`load_distribution_static`

    Returns
    -------
    (P, K, ld)  P (..., 5): the loads (F_a, F_r, M, F_z, M_y) on the inner ring that the balls balance
                [N, N, N m, N, N m]; K (..., 5, 5): the stiffness dP/dq [N/m, N/rad, N m/m, N m/rad];
                ld: the LoadDistribution at q (its applied loads are P)

    Raises
    ------
    NoEquilibrium   a loaded ball of an angular contact bearing over its low shoulder (contact angle ≤ 0)

    Notes
    -----
    K is the exact Jacobian of the equilibrium (symmetric): per ball dQ n nᵀ + (Q/A_j) e eᵀ summed with the
    levers of :func:`thermobear.loads.rings.lever_matrix` (module docstring), in the physical units of q and P.

    Examples
    --------
    At the solution of a load case the reaction is the load itself:

    >>> from thermobear.contact.geometry import bearing
    >>> b = bearing("7210")
    >>> ld = load_distribution_static(b, Fa=450.0, Fr=325.0, M=2.0)
    >>> P, K, at = ring_reaction(b, [ld.delta_a, ld.delta_r, ld.theta, 0.0, 0.0])
    >>> [round(float(v), 6) + 0.0 for v in P], bool(np.allclose(at.Q, ld.Q, rtol=1e-9))
    ([450.0, 325.0, 2.0, 0.0, 0.0], True)
    """
    check_stiffness(stiffness)
    arm = arm_length(brg, tilt_arm)
    q = np.asarray(q, dtype=float)
    if q.shape[-1:] != (5,) or not np.all(np.isfinite(q)):
        raise InputError("q", q, "finite (delta_a, delta_r, theta, delta_z, theta_y) [m, m, rad, m, rad] on a last axis")
    shape = q.shape[:-1]
    qf = q.reshape(-1, 5)
    pb = reaction_problem(brg, qf.shape[0], stiffness)
    P, K, y = reaction_of(pb, qf, arm)
    loads = RingLoads(shape, P, True, 5)
    ld = _result(brg, pb, y, np.zeros(qf.shape[0]), np.zeros(qf.shape[0], int), loads, arm, P[:, 0], P[:, 1])
    if not shape:
        ld = replace(ld, Fa=np.asarray(float(P[0, 0])), Fr=np.asarray(float(P[0, 1])))
    else:
        ld = replace(ld, Fa=P[:, 0].reshape(shape), Fr=P[:, 1].reshape(shape))
    return P.reshape(shape + (5,)), K.reshape(shape + (5, 5)), ld


def reaction_problem(brg: BallBearing, nb: int, stiffness: str = "nominal"):
    """The five-unknown static problem of ``nb`` cases at prescribed ring displacements (applied loads 0, force
    scale 1 N, every case loaded): the ring reaction is its residual, the stiffness its Jacobian."""
    pb = _StaticProblem(brg, np.zeros((nb, 5)), np.ones(nb), np.ones(5), stiffness)
    pb.zero[:] = False
    pb.any_zero = False
    return pb


def reaction_of(pb, q, arm):
    """Loads P (nb, 5) and stiffness K (nb, 5, 5) of the five-unknown problem ``pb`` (applied loads 0, scale 1)
    at the ring displacements q (nb, 5) [m, rad], and the scaled unknowns y (:func:`ring_reaction`)."""
    A, brg = pb.A, pb.brg
    to_y = np.array([1.0 / A, 1.0 / A, arm / A, 1.0 / A, arm / A])
    y = (q - np.array([brg.A_a0, 0.0, 0.0, 0.0, 0.0])) * to_y
    st = pb.evaluate(y)
    to_P = np.array([1.0, 1.0, arm, 1.0, arm])
    return st.res * to_P, st.J * to_P[:, None] * to_y[None, :], y


#: the static form under its former name (``thermobear.loads.static.load_distribution``, imported by
#: modules outside this package); the entry point that chooses the form is :func:`thermobear.loads.load_distribution`
load_distribution = load_distribution_static
