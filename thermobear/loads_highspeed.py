r"""High-speed quasi-static load distribution of a ball bearing (Jones 1960; Harris 2001 ch. 8).

At speed each ball carries a centrifugal force F_c and a gyroscopic moment M_g,
so the inner and outer contacts no longer share one line of action: α_o falls,
α_i rises and Q_o > Q_i.  Rigid rings, outer ring fixed, inner ring rotating at
n [rpm] and displaced by (δa, δr, θ) exactly as in :mod:`thermobear.loads`
(ISO/TS 16281 convention: δa measured from the centred position).

Geometry of ball j (PHYSICS.md §3.3).  x axial (the direction in which F_a
pushes the inner ring), r radial outward through the ball centre; O_o and O_i
the outer and inner groove curvature centres, C the ball centre:

    O_i − O_o = (A1_j, A2_j) = (δa + ℜ_i θ cos ψ_j,  A cos α0 + δr cos ψ_j)
    C − O_o   = (X1_j, X2_j) = ((f_o − ½)D + δo_j)(sin αo_j, cos αo_j)
    O_i − C   = (A1_j − X1_j, A2_j − X2_j) = ((f_i − ½)D + δi_j)(sin αi_j, cos αi_j)

The two distance equations (PHYSICS.md §3.3 eqs 1–2) are explicit in δi, δo,

    δo = |C − O_o| − (f_o − ½)D,     δi = |O_i − C| − (f_i − ½)D,

so they are satisfied identically and the unknowns left per ball are X1, X2;
α_i, α_o are the directions of those two vectors.  Q_i = K_i δi^1.5,
Q_o = K_o δo^1.5.

Free-body diagram of the ball (re-derived here; unit normal n = (sin α, cos α)
pointing from the inner towards the outer contact, tangent e = (cos α, −sin α),
cage frame x̂, r̂, t̂ = x̂ × r̂ of :mod:`thermobear.kinematics`):

* inner ring on ball: +Q_i n_i (pushes outward/forward), outer ring: −Q_o n_o;
* centrifugal force +F_c r̂, F_c = ½ m dm ω_c² (Harris 2001 eq 8.9);
* gyroscopic moment.  The ball spins at ω_b = ω_R (cos β x̂ + sin β r̂) in a frame
  turning at ω_c x̂, so dH/dt = ω_c x̂ × J ω_b = J ω_R ω_c sin β t̂: the contacts must
  apply the couple M_g t̂ with M_g = J ω_R ω_c sin β, J = m D²/10, in the β and
  ω_R convention of :func:`thermobear.kinematics.ball_kinematics` (β = −β_Harris,
  hence M_g = −M_g,Harris).  A tangential friction force T e at the outer contact
  point C + (D/2) n_o gives the couple −(D/2) T t̂, at the inner contact point
  C − (D/2) n_i it gives +(D/2) T t̂.  With the share λ_i + λ_o = 2 (outer-raceway
  control λ_o = 2, λ_i = 0) the friction forces on the ball are
  +λ_i (M_g/D) e_i at the inner and −λ_o (M_g/D) e_o at the outer contact.

Ball equilibrium (axial, radial):

    Q_i sin αi − Q_o sin αo + (M_g/D)(λ_i cos αi − λ_o cos αo)      = 0
    Q_i cos αi − Q_o cos αo − (M_g/D)(λ_i sin αi − λ_o sin αo) + F_c = 0

identical to PHYSICS.md §3.3 eqs 3–4 written with M_g,Harris = −M_g (the public
code PHYSICS.md warns about swaps X1/X2 in the radial equation; not copied).
Inner-ring equilibrium (the inner ring receives −(Q_i n_i + λ_i (M_g/D) e_i) from
each ball; the friction force acts at the contact point, a distance f_i D from
O_i, hence the couple term):

    F_a   = Σ (Q_i sin αi + λ_i (M_g/D) cos αi)
    F_r   = Σ (Q_i cos αi − λ_i (M_g/D) sin αi) cos ψ
    M     = Σ [(Q_i sin αi + λ_i (M_g/D) cos αi) ℜ_i − λ_i f_i M_g] cos ψ

(Harris 2001 §8; PHYSICS.md §3.3 global equations with M_g,Harris = −M_g).  With
outer-raceway control every M_g term leaves the global equations.

Kinematics: one rigid cage.  Every ball orbits at the cage speed ω_c, the Q_i-weighted mean of
the balls' own no-slip orbital speeds (:func:`thermobear.kinematics.ball_kinematics` at each
ball's current α_i, α_o; :func:`thermobear.kinematics.common_cage_speed`), and spins at the
load-weighted least-squares ω_R of :func:`thermobear.kinematics.caged_ball_kinematics`.  Harris's
model lets each ball orbit at its own speed; under combined load at speed those differ by 50 %
and more, and a ball outside the load zone would orbit at the speed its gap's "contact angle"
implies (with a centrifugal force to match).  Every residual is evaluated with the kinematics
recomputed at the iterate, so a converged residual is the fixed point of the coupled problem.

Solver: Newton on the 2Z + 3 unknowns (X per ball, δa, δr, θ) — the 4Z + 3 of Harris with
δi, δo eliminated exactly — vectorised over the balls and a batch of load cases; the
per-ball 2×2 blocks are eliminated in closed form (Schur complement) so only a 3×3 global
system is solved per case.  The Jacobian includes the dependence of F_c and M_g on the
contact angles (finite differences in α_i, α_o) and, through the cage speed, on every ball (a
rank-one term added by Sherman–Morrison), so convergence is quadratic; steps are
capped at 0.1 A and damped by a backtracking line search; starting values from
:func:`thermobear.loads.load_distribution` with each ball pushed out by its F_c.  A case
that fails is re-solved by continuation in speed; if equilibria exist up to some speed
and not beyond (the branch ends: e.g. outer-raceway control in a thrust bearing, where the
cage speed runs away as α_i passes 90°), NoEquilibrium says so.  For a thrust bearing δr is
held at 0 (the shaft locates the shaft washer radially).  α_o may fall to ≤ 0 at light
load and high speed (contact at the groove bottom) and is returned as such; only a loaded
inner contact at α_i ≤ 0 of an angular contact bearing is refused (NoEquilibrium).  A ball out of contact gets a
vanishing linear "tension" stiffness ε K √A (ε = 1e-12) so that its position stays
defined at n = 0; its contact force is reported as 0 (the force it could carry,
< 1e-9 of the applied load, is below every tolerance).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .errors import InputError, NoConvergence, NoEquilibrium
from .geometry import BallBearing
from .kinematics import _cage_spin, common_cage_speed
from .loads import STIFFNESS_MODES, LoadDistribution, load_distribution

__all__ = ["HighSpeedExtras", "load_distribution_high_speed", "load_distribution_high_speed_full",
           "HS_CONTROLS"]

#: raceway-control hypotheses: name -> (λ_i, λ_o, control passed to ball_kinematics for β)
HS_CONTROLS = {"outer": (0.0, 2.0, "outer"), "inner": (2.0, 0.0, "inner"), "both": (1.0, 1.0, "outer")}
_ALIASES = {"none": "both"}
_EPS_TENSION = 1e-12    # linear stiffness of an open contact, relative to K √A (numerical regularisation)
_MAXIT = 100
_STEP_CAP = 0.1         # largest Newton move of a ball centre or ring per step, in units of A


@dataclass(frozen=True)
class HighSpeedExtras:
    """Per-ball quantities of the high-speed solution (leading batch axis as the loads, last axis Z).

    Attributes
    ----------
    Fc : ball centrifugal force ½ m dm ω_c² [N]
    Mg : gyroscopic moment J ω_R ω_c sin β [N m] (β, ω_R in the kinematics convention; = −M_g,Harris)
    omega_c : cage (orbital) speed [rad/s]
    omega_R : ball spin speed relative to the cage [rad/s] (signed)
    beta : pitch angle of the ball axis [rad] (β = −β_Harris)
    X1, X2 : axial / radial position of the ball centre from the outer groove curvature centre [m]
    delta_i, delta_o : elastic approach at the inner / outer contact [m]; negative = gap
    lambda_i, lambda_o : share of the gyroscopic moment taken by each raceway [-]
    control : raceway-control hypothesis ("outer", "inner" or "both")
    n_rpm : inner-ring speed [rpm]
    """

    Fc: np.ndarray
    Mg: np.ndarray
    omega_c: np.ndarray
    omega_R: np.ndarray
    beta: np.ndarray
    X1: np.ndarray
    X2: np.ndarray
    delta_i: np.ndarray
    delta_o: np.ndarray
    lambda_i: float
    lambda_o: float
    control: str
    n_rpm: np.ndarray


_P = np.array([[0.0, 1.0], [-1.0, 0.0]])       # e = P n  (tangent from normal)


class _Problem:
    """Fixed data of one batch: bearing constants, loads, weights.  Arrays have shape (nb, Z[, ...])."""

    def __init__(self, brg, F_app, scale, omega, free_g, stiffness, lam_i, lam_o, kin_control):
        self.brg = brg
        self.Z, self.A, self.R = brg.Z, brg.A, brg.R_inner_locus
        self.psi = 2.0 * np.pi * np.arange(brg.Z) / brg.Z
        self.c = np.cos(self.psi)[None, :]
        self.ci0 = (brg.fi - 0.5) * brg.D          # |O_i − C| unloaded [m]
        self.co0 = (brg.fo - 0.5) * brg.D          # |C − O_o| unloaded [m]
        self.F_app, self.scale, self.free_g = F_app, scale, free_g
        self.omega = omega                          # (nb,) inner-ring speed [rad/s]
        self.stiffness = stiffness
        self.lam_i, self.lam_o, self.kin_control = lam_i, lam_o, kin_control
        an = brg.alpha_nominal
        self.Ki0, self.Ko0 = float(brg.K_i(an)), float(brg.K_o(an))
        self.k_eps = _EPS_TENSION * float(brg.Kn()) * np.sqrt(self.A)
        self.m = brg.ball_mass
        self.J = self.m * brg.D**2 / 10.0

    def centres(self, g):
        """Inner groove-centre offsets A1, A2 [m] from scaled globals g = (δa/A, δr/A, θℜ/A)."""
        A, c = self.A, self.c
        A1 = A * (g[:, 0:1] + g[:, 2:3] * c)
        A2 = A * np.cos(self.brg.alpha0) + A * g[:, 1:2] * c
        return A1, A2

    def _contact_force(self, delta, K):
        pos = delta > 0
        dp = np.where(pos, delta, 0.0)
        Q = np.where(pos, K * dp**1.5, self.k_eps * delta)
        dQ = np.where(pos, 1.5 * K * np.sqrt(dp), self.k_eps)
        return Q, dQ

    def free_speeds(self, a_i, a_o):
        """Each ball's own no-slip orbital speed ω_c [rad/s], ball speed ω_R, pitch β and the contact
        radii c_o, c_i (thermobear.kinematics.ball_kinematics), broadcast to the balls."""
        brg = self.brg
        w_c, w_R, beta, co, ci = _cage_spin(self.omega[:, None], np.float64(0.0), a_i, a_o, brg.D, brg.dm,
                                            self.kin_control)
        one = np.ones_like(a_i)
        return w_c * one, w_R * one, beta * one, co * one, ci * one

    def inertia(self, a_i, a_o, Qi, Qo, w_cage=None):
        """Centrifugal force F_c [N] and gyroscopic moment M_g [N m] of each ball from its
        contact angles and loads (Harris 2001 eqs 8.9, 8.34; kinematics of thermobear.kinematics).

        One rigid cage: every ball orbits at the cage speed, the Q_i-weighted mean of the balls'
        own no-slip orbital speeds (:func:`thermobear.kinematics.common_cage_speed`), and spins at
        the load-weighted least-squares ω_R of :func:`thermobear.kinematics.caged_ball_kinematics`
        (Harris's model lets each ball orbit at its own speed; with combined loads at speed those
        differ by 50 % and more between the loaded and the lightly loaded balls).  ``w_cage`` (nb,)
        freezes the cage speed (finite differences at fixed cage speed; the cage's own dependence
        on the balls enters the Newton step as a rank-one term, :meth:`newton_step`)."""
        brg = self.brg
        w_c, w_R, beta, co, ci = self.free_speeds(a_i, a_o)
        qi, qo = np.maximum(Qi, 0.0), np.maximum(Qo, 0.0)
        if w_cage is None:
            w_cage = common_cage_speed(w_c, qi)
        wc = np.asarray(w_cage)[:, None] * np.ones_like(a_i)
        eo = 0.5 * brg.D * np.cos(a_o + beta)
        ei = 0.5 * brg.D * np.cos(a_i + beta)
        den = qo * eo * eo + qi * ei * ei
        num = -qo * eo * co * wc - qi * ei * ci * (self.omega[:, None] - wc)
        w_R = np.where(den > 0, num / np.where(den > 0, den, 1.0), w_R)
        Fc = 0.5 * self.m * brg.dm * wc**2
        Mg = self.J * w_R * wc * np.sin(beta)
        return Fc, Mg, wc, w_R, beta

    def state(self, x, g):
        """Everything at scaled unknowns x = X/A (nb, Z, 2) and g (nb, 3)."""
        brg, A = self.brg, self.A
        A1, A2 = self.centres(g)
        X1, X2 = A * x[..., 0], A * x[..., 1]
        p, q = A1 - X1, A2 - X2
        d_i, d_o = np.hypot(p, q), np.hypot(X1, X2)
        n_i = np.stack([p / d_i, q / d_i], axis=-1)
        n_o = np.stack([X1 / d_o, X2 / d_o], axis=-1)
        a_i, a_o = np.arctan2(p, q), np.arctan2(X1, X2)
        dl_i, dl_o = d_i - self.ci0, d_o - self.co0
        if self.stiffness == "per_ball":
            Ki, Ko = brg.K_i(a_i), brg.K_o(a_o)
        else:
            Ki, Ko = self.Ki0, self.Ko0
        Qi, dQi = self._contact_force(dl_i, Ki)
        Qo, dQo = self._contact_force(dl_o, Ko)
        Fc, Mg, w_c, w_R, beta = self.inertia(a_i, a_o, Qi, Qo)
        w_cage = w_c[:, 0].copy()
        Ti, To = self.lam_i * Mg / brg.D, self.lam_o * Mg / brg.D
        e_i = n_i @ _P.T
        e_o = n_o @ _P.T
        F_i = Qi[..., None] * n_i + Ti[..., None] * e_i                 # inner ring on ball
        F_o = -(Qo[..., None] * n_o + To[..., None] * e_o)              # outer ring on ball
        r_b = F_i + F_o
        r_b[..., 1] += Fc
        c = self.c
        Fg = np.stack([F_i[..., 0].sum(1), (F_i[..., 1] * c).sum(1),
                       ((F_i[..., 0] - self.lam_i * brg.fi * Mg / self.R) * c).sum(1)], axis=1)
        r_g = Fg - self.F_app
        s = self.scale
        return dict(A1=A1, A2=A2, X1=X1, X2=X2, d_i=d_i, d_o=d_o, n_i=n_i, n_o=n_o, a_i=a_i, a_o=a_o,
                    dl_i=dl_i, dl_o=dl_o, Qi=Qi, Qo=Qo, dQi=dQi, dQo=dQo, Ti=Ti, To=To, Fc=Fc, Mg=Mg,
                    w_c=w_c, w_R=w_R, beta=beta, w_cage=w_cage, r_b=r_b / s[:, None, None], r_g=r_g / s[:, None])

    def norm(self, st):
        nb = np.max(np.abs(st["r_b"]), axis=(1, 2))
        ng = np.max(np.abs(st["r_g"]) * self.free_g, axis=1)
        return np.maximum(nb, ng)

    def newton_step(self, st):
        """Newton direction at frozen F_c, M_g (Schur complement over the per-ball 2×2 blocks)."""
        A, s = self.A, self.scale[:, None, None, None]
        eye = np.eye(2)

        def G(Q, dQ, T, n, d):
            nn = n[..., :, None] * n[..., None, :]
            tang = (Q[..., None, None] * eye + T[..., None, None] * _P) @ (eye - nn) / d[..., None, None]
            return dQ[..., None, None] * nn + tang

        Gi = G(st["Qi"], st["dQi"], st["Ti"], st["n_i"], st["d_i"]) * A / s
        Go = G(st["Qo"], st["dQo"], st["To"], st["n_o"], st["d_o"]) * A / s
        nb, Z = Gi.shape[:2]
        Wt = np.zeros((nb, Z, 2, 3))                       # dA/dg / A = [[1, 0, c], [0, c, 0]]
        Wt[..., 0, 0] = 1.0
        Wt[..., 0, 2] = self.c
        Wt[..., 1, 1] = self.c
        W = np.swapaxes(Wt, -1, -2)
        Jbb = -(Gi + Go)
        Jbg = Gi @ Wt                                       # (nb, Z, 2, 3)
        Jgb = -(W @ Gi)                                     # (nb, Z, 3, 2)
        Jgg = (W @ Gi @ Wt).sum(1)                          # (nb, 3, 3)
        # kinematic coupling: F_c and M_g depend on α_i, α_o (finite differences in the angles);
        # dα_i/dX = −e_i/d_i, dα_i/d(A1, A2) = e_i/d_i, dα_o/dX = e_o/d_o
        h = 1e-7
        a_i, a_o = st["a_i"], st["a_o"]
        wcg = st["w_cage"]
        Fc_i, Mg_i = self.inertia(a_i + h, a_o, st["Qi"], st["Qo"], wcg)[:2]
        Fc_o, Mg_o = self.inertia(a_i, a_o + h, st["Qi"], st["Qo"], wcg)[:2]
        e_i, e_o = st["n_i"] @ _P.T, st["n_o"] @ _P.T
        D = self.brg.D
        drb_dMg = (self.lam_i * e_i - self.lam_o * e_o) / D                       # (nb, Z, 2)
        drg_dMg = (W @ (self.lam_i * e_i / D)[..., None])[..., 0]                 # (nb, Z, 3)
        drg_dMg[..., 2] -= self.lam_i * self.brg.fi * self.c / self.R
        sc = A / self.scale[:, None, None]
        vb, ub, vg, ug = [], [], [], []
        for dFc, dMg in (((Fc_i - st["Fc"]) / h, (Mg_i - st["Mg"]) / h), ((Fc_o - st["Fc"]) / h, (Mg_o - st["Mg"]) / h)):
            b = drb_dMg * dMg[..., None]
            b[..., 1] += dFc
            (vb if not vb else ub).append(b * sc)
            (vg if not vg else ug).append(drg_dMg * dMg[..., None] * sc)
        vb, ub, vg, ug = vb[0], ub[0], vg[0], ug[0]
        gi = e_i / st["d_i"][..., None]                    # dα_i/dA
        go = e_o / st["d_o"][..., None]                    # dα_o/dX
        Jbb = Jbb - vb[..., :, None] * gi[..., None, :] + ub[..., :, None] * go[..., None, :]
        Jbg = Jbg + vb[..., :, None] * (gi[..., None, :] @ Wt)
        Jgb = Jgb - vg[..., :, None] * gi[..., None, :] + ug[..., :, None] * go[..., None, :]
        Jgg = Jgg + (vg[..., :, None] * (gi[..., None, :] @ Wt)).sum(1)
        det = Jbb[..., 0, 0] * Jbb[..., 1, 1] - Jbb[..., 0, 1] * Jbb[..., 1, 0]
        tiny = 1e-14 * np.maximum(np.abs(Jbb).max(axis=(-1, -2)), 1e-300)
        bad = np.abs(det) < tiny ** 2
        if np.any(bad):                                     # ball exactly at the edge of contact
            Jbb = Jbb - (bad * tiny)[..., None, None] * eye
            det = Jbb[..., 0, 0] * Jbb[..., 1, 1] - Jbb[..., 0, 1] * Jbb[..., 1, 0]
        Binv = np.empty_like(Jbb)
        Binv[..., 0, 0], Binv[..., 1, 1] = Jbb[..., 1, 1] / det, Jbb[..., 0, 0] / det
        Binv[..., 0, 1], Binv[..., 1, 0] = -Jbb[..., 0, 1] / det, -Jbb[..., 1, 0] / det
        JgbB = Jgb @ Binv
        S = Jgg - (JgbB @ Jbg).sum(1)
        act = self.free_g
        S = S * (act[:, :, None] * act[:, None, :]) + np.eye(3)[None] * (1.0 - act)[:, :, None]
        sd = np.abs(np.linalg.det(S))
        S = np.where((sd < 1e-300)[:, None, None], S + 1e-6 * np.eye(3)[None], S)

        def solve(r_b, r_g):                                # (dx, dg) = −J_block⁻¹ (r_b, r_g)
            rhs = (-r_g + (JgbB @ r_b[..., None])[..., 0].sum(1)) * act
            dg = np.linalg.solve(S, rhs[..., None])[..., 0]
            dx = (Binv @ (-r_b - (Jbg @ dg[:, None, :, None])[..., 0])[..., None])[..., 0]
            return dx, dg

        dx, dg = solve(st["r_b"], st["r_g"])
        # the cage: every ball's F_c and M_g depend on the cage speed, a weighted mean over all balls —
        # a rank-one term a bᵀ of the Jacobian (a = ∂r/∂ω_cage, b = ∂ω_cage/∂(x, g)), added by
        # Sherman–Morrison: dz = dz0 − w (b·dz0)/(1 + b·w), w = J_block⁻¹ a
        hw = 1e-7 * np.maximum(wcg, 1.0)
        Fc_w, Mg_w = self.inertia(a_i, a_o, st["Qi"], st["Qo"], wcg + hw)[:2]
        dFw, dMw = (Fc_w - st["Fc"]) / hw[:, None], (Mg_w - st["Mg"]) / hw[:, None]
        s1 = self.scale[:, None, None]
        a_b = drb_dMg * dMw[..., None] / s1
        a_b[..., 1] += dFw / self.scale[:, None]
        a_g = (drg_dMg * dMw[..., None]).sum(1) / self.scale[:, None] * act
        w_own = self.free_speeds(a_i, a_o)[0]
        dw_ai = (self.free_speeds(a_i + h, a_o)[0] - w_own) / h
        dw_ao = (self.free_speeds(a_i, a_o + h)[0] - w_own) / h
        q = np.maximum(st["Qi"], 0.0)
        qs = q.sum(1, keepdims=True)
        has = qs > 0
        wgt = np.where(has, q / np.where(has, qs, 1.0), 1.0 / q.shape[1])
        c_q = np.where(has & (st["Qi"] > 0), (w_own - wcg[:, None]) / np.where(has, qs, 1.0), 0.0)
        c_ai, c_ao = wgt * dw_ai, wgt * dw_ao
        dQn = (c_q * st["dQi"])[..., None] * st["n_i"]                          # via Q_i: dQ_i/dA = dQ_i n_i
        b_x = A * (-c_ai[..., None] * gi + c_ao[..., None] * go - dQn)           # per scaled x
        b_g = A * ((c_ai[..., None] * gi + dQn)[..., None, :] @ Wt)[..., 0, :].sum(1) * act
        wx, wg = solve(-a_b, -a_g)
        bz = (b_x * dx).sum((1, 2)) + (b_g * dg).sum(1)
        bw = (b_x * wx).sum((1, 2)) + (b_g * wg).sum(1)
        den = 1.0 + bw
        f = np.where(np.abs(den) > 1e-12, bz / np.where(np.abs(den) > 1e-12, den, 1.0), 0.0)
        return dx - f[:, None, None] * wx, dg - f[:, None] * wg


def _newton(pb, x, g, tol, maxiter):
    """Damped Newton with frozen kinematics per step.  Returns x, g, norm, iterations, done mask."""
    st = pb.state(x, g)
    norm = pb.norm(st)
    floor = np.zeros(norm.shape, bool)
    it = 0
    for it in range(1, maxiter + 1):
        todo = (norm > tol) & ~floor
        if not np.any(todo):
            it -= 1
            break
        sub = _Sub(pb, todo)
        st_t = {k: v[todo] for k, v in st.items()}
        dx, dg = sub.newton_step(st_t)
        # cap the step (a Hertz contact has zero stiffness where it opens: an unlimited
        # Newton step from there can throw a ball through its groove centre)
        big = np.maximum(np.max(np.abs(dx), axis=(1, 2)), np.max(np.abs(dg), axis=1))
        cap = np.minimum(1.0, _STEP_CAP / np.maximum(big, 1e-300))
        dx, dg = dx * cap[:, None, None], dg * cap[:, None]
        x_t, g_t, n_t = x[todo], g[todo], norm[todo]
        lam = np.ones(n_t.shape)
        acc = np.zeros(n_t.shape, bool)
        best_x, best_g = x_t.copy(), g_t.copy()
        best_st = None                              # states at the accepted trial points (reused below)
        for _ in range(30):
            tx = x_t + lam[:, None, None] * dx
            tg = g_t + lam[:, None] * dg
            st_try = sub.state(tx, tg)
            nt = sub.norm(st_try)
            ok = (nt < (1.0 - 1e-4 * lam) * n_t) & ~acc & np.isfinite(nt)
            best_x[ok], best_g[ok] = tx[ok], tg[ok]
            if best_st is None:
                best_st = st_try
            elif ok.any():
                for k, v in best_st.items():
                    v[ok] = st_try[k][ok]
            acc |= ok
            if acc.all():
                break
            lam = np.where(acc, lam, 0.5 * lam)
        stuck = ~acc                                # take the smallest step anyway (leave flat regions)
        best_x[stuck] = x_t[stuck] + lam[stuck, None, None] * dx[stuck]
        best_g[stuck] = g_t[stuck] + lam[stuck, None] * dg[stuck]
        x, g = x.copy(), g.copy()
        x[todo], g[todo] = best_x, best_g
        prev = norm.copy()
        if acc.all() and todo.all():
            st = best_st                            # every case took an evaluated trial point
        else:
            st = pb.state(x, g)
        norm = pb.norm(st)
        norm = np.where(np.isfinite(norm), norm, np.inf)
        floor |= todo & (norm <= 1e-9) & (norm > 0.5 * prev)
    else:
        it = maxiter
    return x, g, norm, it, norm <= np.maximum(tol, np.where(floor, 1e-9, tol))


class _Sub(_Problem):
    """View of a _Problem restricted to a subset of the batch."""

    def __init__(self, pb, mask):            # noqa: D107  (no super().__init__: copy and slice)
        self.__dict__.update(pb.__dict__)
        self.F_app, self.scale = pb.F_app[mask], pb.scale[mask]
        self.free_g, self.omega = pb.free_g[mask], pb.omega[mask]


def _check_options(control, stiffness, tol, maxiter):
    if not isinstance(control, str) or _ALIASES.get(control, control) not in HS_CONTROLS:
        raise InputError("control", control, f"must be one of {', '.join(HS_CONTROLS)} (or 'none' = 'both')")
    if stiffness not in STIFFNESS_MODES:
        raise InputError("stiffness", stiffness, f"must be one of {', '.join(STIFFNESS_MODES)}")
    if not (isinstance(tol, (int, float)) and 0.0 < tol < 1e-3):
        raise InputError("tol", tol, "relative residual tolerance must lie in (0, 1e-3)")
    if not (isinstance(maxiter, (int, np.integer)) and maxiter >= 1):
        raise InputError("maxiter", maxiter, "must be an integer >= 1")


def load_distribution_high_speed_full(brg: BallBearing, Fa=0.0, Fr=0.0, M=None, n_rpm=0.0, *,
                                      control: str = "outer", stiffness: str = "nominal",
                                      tol: float = 1e-10, maxiter: int = _MAXIT):
    r"""High-speed quasi-static load distribution with the per-ball details.

    Parameters
    ----------
    brg : BallBearing
    Fa : array_like      axial load on the inner ring [N], ≥ 0
    Fr : array_like      radial load on the inner ring [N], ≥ 0, towards ψ = 0
    M : array_like       tilting moment [N m]; ``None`` holds the tilt at θ = 0
    n_rpm : array_like   inner-ring speed [rpm], ≥ 0 (outer ring fixed); broadcast with the loads
    control : str       raceway control of the gyroscopic moment: ``"outer"`` (Jones: λ_o = 2,
                        λ_i = 0, β from zero spin at the outer contact), ``"inner"`` (λ_i = 2,
                        λ_o = 0, β from the inner contact) or ``"both"`` (alias ``"none"``:
                        λ_i = λ_o = 1; β taken from the outer-control formula — a choice: the
                        split leaves β undetermined without a friction model)
    stiffness : str     ``"nominal"`` (K_i, K_o at the nominal contact angle, as the low-speed
                        default) or ``"per_ball"`` (K_i(α_i), K_o(α_o) at each ball's angles)
    tol : float         relative residual (forces / largest applied load) at which Newton stops
    maxiter : int       Newton iterations per attempt

    Returns
    -------
    (LoadDistribution, HighSpeedExtras)
        ``Q_i ≠ Q_o`` and ``alpha_i ≠ alpha_o`` at speed; ``residual`` is the largest relative
        force residual of all ball and ring equations, ``iterations`` the Newton iterations.

    Raises
    ------
    InputError       bad option or negative / non-finite speed or load
    NoEquilibrium    loads the bearing cannot carry (from the low-speed check), or a loaded
                     angular-contact ball whose contact angle would fall to ≤ 0
    NoConvergence    Newton (with continuation in speed) did not reach the tolerance

    Notes
    -----
    Jones (1960); Harris (2001) §8.2–8.3 (eqs 8.9 F_c, 8.34 M_g, 8.60–8.66 equilibrium);
    PHYSICS.md §3.3 and §4.  Equations, sign derivation and solver: module docstring.
    At n = 0 the solution equals :func:`thermobear.loads.load_distribution`.

    Examples
    --------
    7210 (α0 = 40°) under 450 N axial load at 20 000 rpm: the centrifugal force (443 N) exceeds
    the static ball load (≈ 45 N); α_o falls to 2.7°, α_i rises to 59°, Q_o ≫ Q_i.

    >>> from thermobear.geometry import bearing
    >>> ld, ex = load_distribution_high_speed_full(bearing("7210"), Fa=450.0, n_rpm=20000.0)
    >>> [round(float(np.rad2deg(a[0])), 1) for a in (ld.alpha_i, ld.alpha_o)]
    [59.4, 2.7]
    >>> round(float(ld.Q_i[0]), 1), round(float(ld.Q_o[0]), 1), round(float(ex.Fc[0]), 1)
    (34.8, 461.5, 442.8)
    """
    _check_options(control, stiffness, tol, maxiter)
    control = _ALIASES.get(control, control)
    lam_i, lam_o, kin_control = HS_CONTROLS[control]
    Fa_in, Fr_in = np.asarray(Fa, dtype=float), np.asarray(Fr, dtype=float)
    n_in = np.asarray(n_rpm, dtype=float)
    if np.any(~np.isfinite(n_in)) or np.any(n_in < 0):
        raise InputError("n_rpm", n_rpm, "inner-ring speed must be finite and >= 0 [rpm] (outer ring fixed)")
    M_in = None if M is None else np.asarray(M, dtype=float)
    shape = np.broadcast_shapes(Fa_in.shape, Fr_in.shape, n_in.shape, () if M_in is None else M_in.shape)
    Fa_b = np.broadcast_to(Fa_in, shape).ravel().copy()
    Fr_b = np.broadcast_to(Fr_in, shape).ravel().copy()
    n_b = np.broadcast_to(n_in, shape).ravel().copy()
    M_b = None if M_in is None else np.broadcast_to(M_in, shape).ravel().copy()

    # low-speed solution: input checks, NoEquilibrium cases, starting values
    ls = load_distribution(brg, Fa_b, Fr_b, M_b, stiffness=stiffness)
    Z, A, R = brg.Z, brg.A, brg.R_inner_locus
    nb = Fa_b.size
    Mv = np.zeros(nb) if M_b is None else M_b
    F_app = np.stack([Fa_b, Fr_b, Mv / R], axis=1)
    omega = n_b * np.pi / 30.0
    w_c0 = 0.5 * omega * (1.0 - brg.gamma(brg.alpha0))
    Fc0 = 0.5 * brg.ball_mass * brg.dm * w_c0**2
    load_max = np.max(np.abs(F_app), axis=1)
    zero = load_max == 0.0
    scale = np.maximum(np.maximum(load_max, Fc0), 1e-300)
    free_g = np.ones((nb, 3))
    if M_b is None:
        free_g[:, 2] = 0.0
    if brg.kind == "thrust":
        # the shaft washer is located radially by the shaft (Fr = 0 is enforced): hold δr = 0.
        # At speed the balls thrown outwards give the washer a negative radial stiffness, so a
        # free δr would only find the symmetric solution by accident.
        free_g[:, 1] = 0.0
    free_g[zero] = 0.0                       # no load: the rings stay centred, only the balls move
    pb = _Problem(brg, F_app, scale, omega, free_g, stiffness, lam_i, lam_o, kin_control)

    if brg.kind == "thrust" and np.any(zero & (n_b > 0)):
        k = int(np.argmax(zero & (n_b > 0)))
        raise NoEquilibrium(
            f"a thrust ball bearing at n = {n_b[k]:g} rpm needs an axial load (minimum load): with Fa = 0 the "
            "centrifugal force throws the balls outwards and nothing holds them between the washers")
    g0 = np.zeros((nb, 3))
    g0[:, 0] = np.reshape(ls.delta_a, nb) / A
    if brg.kind == "thrust":
        # unloaded thrust bearing: washers just touching the balls (the centred position
        # would put both groove centres on one point)
        g0[zero, 0] = np.sin(brg.alpha0)
    g0[:, 1] = np.reshape(ls.delta_r, nb) / A
    g0[:, 2] = np.reshape(ls.theta, nb) * R / A
    x0 = _static_start(pb, g0)
    xs0 = _spinning_start(pb, x0, g0)

    x, g, norm, it, done = _newton(pb, xs0, g0.copy(), tol, maxiter)
    its = np.full(nb, it)
    if not np.all(done):
        _diagnose(pb, x, g, done, Fa_b, Fr_b, n_b, its, norm)
    if not np.all(done) and np.any(n_b[~done] > 0):
        # continuation in speed for the failed cases, warm-started from the static solution;
        # a case that fails at some speed fraction stops there (its branch of equilibria ends)
        idx = np.flatnonzero(~done)
        xs, gs = x0[idx].copy(), g0[idx].copy()
        alive = np.ones(idx.size, bool)
        reached = np.zeros(idx.size)             # largest speed fraction with an equilibrium
        ns = np.full(idx.size, np.inf)
        tot = np.zeros(idx.size, int)
        for frac in np.linspace(0.0, 1.0, 11)[1:]:
            if not alive.any():
                break
            m = np.zeros(nb, bool)
            m[idx[alive]] = True
            sub = _Sub(pb, m)
            sub.omega = omega[m] * frac
            xa, ga, na, k, da_ = _newton(sub, xs[alive].copy(), gs[alive].copy(), tol, maxiter)
            tot[alive] += k
            ok = np.flatnonzero(alive)[da_]
            xs[ok], gs[ok], reached[ok], ns[ok] = xa[da_], ga[da_], frac, na[da_]
            bad = np.flatnonzero(alive)[~da_]
            ns[bad] = na[~da_]
            alive[bad] = False
        fin = alive & (reached == 1.0)
        x[idx[fin]], g[idx[fin]], norm[idx[fin]], done[idx[fin]] = xs[fin], gs[fin], ns[fin], True
        norm[idx[~fin]] = ns[~fin]
        its[idx] = it + tot
        fold = ~fin & (reached > 0)
        if np.any(fold):
            j = int(np.flatnonzero(fold)[0])
            k = int(idx[j])
            raise NoEquilibrium(
                f"no high-speed equilibrium at n = {n_b[k]:g} rpm for Fa = {Fa_b[k]:g} N, Fr = {Fr_b[k]:g} N, "
                f"M = {Mv[k]:g} N m (control = '{control}'): continuation in speed found equilibria up to "
                f"{reached[j] * n_b[k]:.4g} rpm, then none — the centrifugal and gyroscopic loads outgrow what the "
                "contacts can balance (e.g. the cage speed runs away when a raceway-control hypothesis no longer "
                "fits the contact angles); raise the axial load or preload, or check the control hypothesis",
                iterations=int(its[k]), residual=float(ns[j]), last=np.concatenate([gs[j] * A, xs[j].ravel() * A]))
    st = pb.state(x, g)
    if not np.all(done):
        _diagnose(pb, x, g, done, Fa_b, Fr_b, n_b, its, norm)
        k = int(np.argmax(np.where(done, -np.inf, norm)))
        raise NoConvergence(
            f"high-speed load distribution did not reach equilibrium for Fa = {Fa_b[k]:g} N, Fr = {Fr_b[k]:g} N, "
            f"M = {Mv[k]:g} N m, n = {n_b[k]:g} rpm: relative residual {norm[k]:.3g} after {its[k]} Newton "
            "iterations (direct and with continuation in speed)",
            iterations=int(its[k]), residual=float(norm[k]), last=np.concatenate([g[k] * A, x[k].ravel() * A]))

    Qi = np.where(st["dl_i"] > 0, st["Qi"], 0.0)
    Qo = np.where(st["dl_o"] > 0, st["Qo"], 0.0)
    a_i, a_o = st["a_i"], st["a_o"]
    if brg.kind == "angular_contact" and np.any((Qi > 0) & (a_i <= 0)):
        k = int(np.argmax(np.any((Qi > 0) & (a_i <= 0), axis=1)))
        raise NoEquilibrium(
            f"angular contact bearing at Fa = {Fa_b[k]:g} N, Fr = {Fr_b[k]:g} N, n = {n_b[k]:g} rpm: a loaded "
            "ball's inner contact angle would be <= 0 (contact over the low shoulder); raise the axial load "
            "or preload", iterations=int(its[k]), residual=float(norm[k]))
    free = (Qi == 0) & (Qo == 0)
    if brg.kind != "deep_groove":
        a_i, a_o = np.where(free, brg.alpha0, a_i), np.where(free, brg.alpha0, a_o)
    else:
        a_i, a_o = np.where(zero[:, None] & free, 0.0, a_i), np.where(zero[:, None] & free, 0.0, a_o)
    dn = np.maximum(st["dl_i"], 0.0) + np.maximum(st["dl_o"], 0.0)
    da = np.where(zero, 0.0, g[:, 0] * A)
    dr = np.where(zero, 0.0, g[:, 1] * A)
    th = np.where(zero, 0.0, g[:, 2] * A / R)

    def sh(v):
        return v.reshape(shape) if shape else float(v[0])

    def shz(v):
        return v.reshape(shape + (Z,)) if shape else v[0]

    ld = LoadDistribution(
        delta_a=sh(da), delta_r=sh(dr), theta=sh(th), Q_i=shz(Qi), Q_o=shz(Qo), alpha_i=shz(a_i),
        alpha_o=shz(a_o), psi=pb.psi, delta_n=shz(dn), residual=float(norm.max()) if norm.size else 0.0,
        iterations=int(its.max()) if its.size else 0, Fa=Fa_in, Fr=Fr_in, M=sh(Mv))
    ex = HighSpeedExtras(
        Fc=shz(st["Fc"]), Mg=shz(st["Mg"]), omega_c=shz(st["w_c"]), omega_R=shz(st["w_R"]),
        beta=shz(st["beta"]), X1=shz(st["X1"]), X2=shz(st["X2"]), delta_i=shz(st["dl_i"]),
        delta_o=shz(st["dl_o"]), lambda_i=lam_i, lambda_o=lam_o, control=control,
        n_rpm=sh(n_b) if shape else float(n_b[0]))
    return ld, ex


def _static_start(pb, g):
    """Ball centres of the static solution: on the line of groove centres, the approach
    A_j − A split between the contacts so that K_i δi^1.5 = K_o δo^1.5 (equal split for
    an open contact, where the regularising stiffness is the same on both sides)."""
    A1, A2 = pb.centres(g)
    Aj = np.hypot(A1, A2)
    s = Aj - pb.A
    Ki, Ko = pb.Ki0, pb.Ko0
    if pb.stiffness == "per_ball":
        al = np.arctan2(A1, A2)
        Ki, Ko = pb.brg.K_i(al), pb.brg.K_o(al)
    share_o = np.where(s > 0, Ki ** (2.0 / 3.0) / (Ki ** (2.0 / 3.0) + Ko ** (2.0 / 3.0)), 0.5)
    r_o = pb.co0 + share_o * s
    x = np.stack([r_o * A1 / Aj, r_o * A2 / Aj], axis=-1) / pb.A
    return x


def _diagnose(pb, x, g, done, Fa_b, Fr_b, n_b, its, norm):
    """Raise NoEquilibrium for an unconverged case whose load cannot balance the friction the
    control hypothesis demands from the inner raceway: the inner ring receives Σ λ_i (M_g/D) cos α_i
    axially from the gyroscopic friction; when that reaches F_a, Q_i sin α_i would have to be < 0."""
    st = pb.state(x, g)
    if pb.brg.kind == "angular_contact":
        bad = ~done & np.any((st["dl_i"] > 0) & (st["a_i"] <= 0), axis=1)
        if np.any(bad):
            k = int(np.argmax(bad))
            raise NoEquilibrium(
                f"angular contact bearing at Fa = {Fa_b[k]:g} N, Fr = {Fr_b[k]:g} N, n = {n_b[k]:g} rpm: no "
                "equilibrium with positive inner contact angles (the balls would run over the low shoulder); "
                "raise the axial load or preload", iterations=int(its[k]), residual=float(norm[k]))
    if pb.lam_i == 0.0:
        return
    gyro = (pb.lam_i * st["Mg"] / pb.brg.D * np.cos(st["a_i"])).sum(1)
    bad = ~done & (gyro >= np.maximum(Fa_b, 0.0)) & (n_b > 0)
    if np.any(bad):
        k = int(np.argmax(bad))
        raise NoEquilibrium(
            f"control = '{'inner' if pb.lam_o == 0 else 'both'}' at Fa = {Fa_b[k]:g} N, Fr = {Fr_b[k]:g} N, "
            f"n = {n_b[k]:g} rpm: the gyroscopic friction the inner raceway must supply pushes the inner ring "
            f"axially with {gyro[k]:.4g} N >= Fa; no positive contact loads balance it. Use control = 'outer' "
            "or a larger axial load", iterations=int(its[k]), residual=float(norm[k]))


def _spinning_start(pb, x_static, g):
    """Static start with each ball pushed out by its centrifugal force: the outer contact takes
    the static ball load plus F_c r̂ (kinematics at the static angles), the globals are kept."""
    st = pb.state(x_static, g)
    Qs = np.maximum(st["Qi"], 0.0)
    f1 = Qs * st["n_i"][..., 0]
    f2 = Qs * st["n_i"][..., 1] + st["Fc"]
    Qo = np.hypot(f1, f2)
    Ko = pb.Ko0 if pb.stiffness == "nominal" else pb.brg.K_o(st["a_o"])
    r_o = pb.co0 + (Qo / Ko) ** (2.0 / 3.0)
    x = np.stack([r_o * f1, r_o * f2], axis=-1) / np.where(Qo > 0, Qo, 1.0)[..., None] / pb.A
    moved = (st["Fc"] > 0)[..., None]
    return np.where(moved, x, x_static)


def load_distribution_high_speed(brg: BallBearing, Fa=0.0, Fr=0.0, M=None, n_rpm=0.0, *,
                                 control: str = "outer", stiffness: str = "nominal",
                                 tol: float = 1e-10, maxiter: int = _MAXIT) -> LoadDistribution:
    r"""High-speed quasi-static load distribution (Jones 1960; Harris 2001 ch. 8).

    Same parameters as :func:`load_distribution_high_speed_full`; returns only the
    :class:`thermobear.loads.LoadDistribution` (centrifugal forces, gyroscopic moments,
    ball speeds and positions are in the ``_full`` variant).

    Examples
    --------
    At n = 0 it is the low-speed solution:

    >>> from thermobear.geometry import bearing
    >>> from thermobear.loads import load_distribution
    >>> b = bearing("7210")
    >>> hs, ls = load_distribution_high_speed(b, Fa=450.0, Fr=300.0), load_distribution(b, Fa=450.0, Fr=300.0)
    >>> bool(np.allclose(hs.Q_o, ls.Q, rtol=1e-8, atol=1e-9 * 450) and np.allclose(hs.Q_i, hs.Q_o, rtol=1e-8))
    True
    """
    return load_distribution_high_speed_full(brg, Fa, Fr, M, n_rpm, control=control, stiffness=stiffness,
                                             tol=tol, maxiter=maxiter)[0]
