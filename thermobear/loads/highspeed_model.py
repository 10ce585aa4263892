r"""The high-speed ball equilibrium as a problem of the shared Newton: residual, exact Jacobian, path.

Equations and conventions: :mod:`thermobear.loads.highspeed` (Jones 1960 [1]; Harris 2001 [2] ch. 8;
Harris & Kotzalas 2007 [3] ch. 3).  Unknowns of a load case, one row of z (nb, 3 + 2Z):

    z = (δa/A, δr/A, θℜ_i/A,  X1_0/A, X2_0/A,  X1_1/A, X2_1/A, …)

the ring unknowns g first (the lever map of :mod:`thermobear.loads.rings`), then the centre of each
ball from its outer groove curvature centre (axial, radial).  Residual rows in the same order: the
inner ring's (F_a, F_r, M/ℜ_i) balance, then each ball's (axial, radial) force balance, all divided
by the case's force scale.

Arrays are ball-major with the two contacts stacked: (nb, Z, 2 contacts [inner, outer], 2 components
[axial, radial]); both contacts go through one numpy call wherever their formulas agree (a load case
is a few hundred tiny arrays: the number of calls, not the arithmetic, sets the cost).

References
----------
.. [1] Jones, A. B. (1960). A general theory for elastically constrained ball and radial roller
   bearings under arbitrary load and speed conditions. *J. Basic Eng.* 82(2):309–320.
.. [2] Harris, T. A. (2001). *Rolling Bearing Analysis*, 4th ed., Wiley, ch. 8.
.. [3] Harris, T. A. & Kotzalas, M. N. (2007). *Advanced Concepts of Bearing Technology* (Rolling
   Bearing Analysis, 5th ed.), CRC Press, ch. 3.
"""
from __future__ import annotations

from functools import lru_cache

import numpy as np

from thermobear.loads.filmlaw import _FilmAt, _NVMFixed, _carry, _invert
from thermobear.loads.highspeed_start import relax as _relax
from thermobear.loads.rings import azimuths, lever_matrix

_EPS_TENSION = 1e-12    # linear stiffness of an open contact, relative to K √A (numerical regularisation)
_SGN_E = np.array([1.0, -1.0])                  # (sin α, cos α) reversed -> e = (cos α, −sin α)
_SGN_2 = np.array([[1.0, -1.0], [-1.0, 1.0]])   # cofactor signs of a 2×2 inverse
_PM = np.array([1.0, -1.0])                     # inner (+), outer (−) contact on the ball residual
LAG_SKIP = 0.05       # film refresh: keep the iterate when the cage-speed lag is below this fraction of its residual


@lru_cache(maxsize=32)
def _stiffness_constants(brg):
    """K_i, K_o at the nominal contact angle [N/m^1.5] and the open-contact regularising stiffness
    ε K_n √A [N/m] of a bearing (cached: a BallBearing is immutable and hashable)."""
    an = brg.alpha_nominal
    return float(brg.K_i(an)), float(brg.K_o(an)), _EPS_TENSION * float(brg.Kn()) * np.sqrt(brg.A)


class _FilmLaw:
    r"""Film contact law of both contacts of every ball, stacked on a last axis (inner, outer).

    δ_c = (Q_c/K_c)^(2/3) − h_c(Q_c, α_c)   with h_c the NVM central film
    (:func:`thermobear.lubrication.film.film_thickness_nvm`) at R_x,c = (D/2)(1 ∓ γ'cos α_c), R_y,c, the mean
    entrainment speed u_c = v_c (d_m/2)(1 ∓ γ'cos α_c), v = (|ω − ω_cage|, ω_cage) (caged kinematics,
    :func:`thermobear.contact.kinematics.caged_ball_kinematics`, outer ring fixed), one η and α_p per case.
    :meth:`at` gives the law at fixed angles that :func:`thermobear.loads.filmlaw._invert` inverts."""

    def __init__(self, brg, eta, alpha_p, K=None, v=None):
        self.brg, self.eta, self.ap, self.K, self.v = brg, eta, alpha_p, K, v
        self.Ep = brg.E_prime
        self.gp = brg.D / brg.dm
        self.sgn = np.array([-1.0, 1.0])
        self.Ry = np.array([brg.Ry_i, brg.Ry_o])

    def take(self, m):
        """The per-case data of a subset of the batch (eta, alpha_p have shape (nb, 1, 1))."""
        return _FilmLaw(self.brg, self.eta[m], self.ap[m])

    def bind(self, K, v):
        """The law with the contact constants K [N/m^1.5] and orbital speed factors v [rad/s] set."""
        return _FilmLaw(self.brg, self.eta, self.ap, K, v)

    def at(self, alpha):
        r"""The law at contact angles α [rad], shape (nb, Z, 2) (:class:`thermobear.loads.filmlaw._FilmAt`):
        R_x and u both ∝ 1 ∓ γ'cos α, ∂ln R_x/∂α = ∂ln u/∂α = ±γ' sin α / (1 ∓ γ'cos α); K held."""
        gc = self.sgn * (self.gp * np.cos(alpha))
        fac = 1.0 + gc
        dln = -self.sgn * (self.gp * np.sin(alpha)) / fac
        nvm = _NVMFixed(0.5 * self.brg.D * fac, self.Ry, self.v * (0.5 * self.brg.dm) * fac, self.eta, self.ap,
                        self.Ep)
        return _FilmAt(self.K, nvm, False, dln, dln)


class _HSState:
    """Arrays of one Newton iterate, every one with the load cases as leading axis (set by
    :meth:`_HSProblem.evaluate`; None where a field does not apply)."""

    FLAGS = ("allpos", "wpos")      # every contact closed / every ball with a loaded contact (fast paths)

    def take(self, idx):
        new = _HSState.__new__(_HSState)
        new.__dict__ = {k: (v if k in self.FLAGS or v is None else v[idx]) for k, v in self.__dict__.items()}
        return new

    def put(self, idx, other):
        for k, v in self.__dict__.items():
            if k in self.FLAGS:
                self.__dict__[k] = v and other.__dict__[k]
            elif v is not None:
                v[idx] = other.__dict__[k]

    # per-ball views used by the start and the results
    @property
    def Qi(self):
        return self.Q[..., 0]

    @property
    def Qo(self):
        return self.Q[..., 1]

    @property
    def X1(self):
        return self.V[..., 1, 0]

    @property
    def X2(self):
        return self.V[..., 1, 1]


class _HSProblem:
    """Fixed data of one batch of high-speed load cases (bearing constants, loads, speeds, control).

    ``film``: the :class:`_FilmLaw` of the film contact law (None: dry Hertz contacts); ``fz`` the data it
    freezes per Newton step (cage speed "W" (nb, 1), warm-start loads "Q" (nb, Z, 2) and the derivatives
    of the iterate they were taken at, :meth:`refresh`)."""

    def __init__(self, brg, F_app, scale, omega, free_g, stiffness, lam_i, lam_o, kin_control):
        self.brg = brg
        self.Z, self.A, self.R = brg.Z, brg.A, brg.R_inner_locus
        Z, A = brg.Z, brg.A
        self.c = np.cos(azimuths(Z))
        self.c0 = np.array([(brg.fi - 0.5) * brg.D, (brg.fo - 0.5) * brg.D])   # |O_i − C|, |C − O_o| unloaded [m]
        self.A2_0 = A * np.cos(brg.alpha0)
        L = lever_matrix(brg)
        self.Lb = L.reshape(3, 2, Z).transpose(0, 2, 1).reshape(3, 2 * Z)     # ball-major (A1_j, A2_j) [m]
        self.Sg = self.Lb.T / A                                               # ring sums of (f_a, f_r) per ball
        self.off = np.array([0.0, self.A2_0])
        self.Wt = np.zeros((Z, 2, 3))                 # dA_c/dg / A per ball: [[1, 0, c], [0, c, 0]]
        self.Wt[:, 0, 0], self.Wt[:, 0, 2], self.Wt[:, 1, 1] = 1.0, self.c, self.c
        self.WtT = np.ascontiguousarray(self.Wt.swapaxes(-1, -2))
        self.stiffness, self.per_ball = stiffness, stiffness == "per_ball"
        self.lam = np.array([lam_i, lam_o], dtype=float)
        self.lam_i, self.lam_o, self.kin_control = lam_i, lam_o, kin_control
        self.has_lam = bool(lam_i or lam_o)
        Ki, Ko, self.k_eps = _stiffness_constants(brg)
        self.Ki0, self.Ko0 = Ki, Ko
        self.K0 = np.array([Ki, Ko])
        self.K15 = 1.5 * self.K0
        self.D, self.dm, self.fi = brg.D, brg.dm, brg.fi
        gp = brg.D / brg.dm
        self.gp = gp
        self.k = 1 if kin_control == "outer" else 0      # the contact whose zero spin sets β
        sg = 1.0 if kin_control == "outer" else -1.0
        self.rb2_0, self.rb2_1, self.cb_0 = 1.0 + gp * gp, 2.0 * sg * gp, sg * gp
        self.hdm, self.hD = 0.5 * brg.dm, 0.5 * brg.D
        self.Rsg = np.array([-0.5 * brg.dm * gp, 0.5 * brg.dm * gp])          # R_c = dm/2 + Rsg_c cos α_c
        self.ek = np.zeros((2, 2))
        self.ek[:, self.k] = 1.0                       # dβ/dα_m ≠ 0 only for m = k
        self.m = brg.ball_mass
        self.J = self.m * brg.D**2 / 10.0
        self.mdm2 = 0.5 * self.m * brg.dm
        self.lamD = self.lam / brg.D
        self.vsg = self.lamD * _PM                     # ∂r_b/∂M_g = Σ_c vsg_c e_c
        self.mom = lam_i * brg.fi / self.R * self.c    # moment of the inner gyroscopic friction per M_g
        self.film = None
        self.fz = None
        self.set_cases(F_app, scale, omega, free_g)

    def set_cases(self, F_app, scale, omega, free_g):
        """Per-case data (call again after changing any of them)."""
        self.F_app, self.scale, self.omega, self.free_g = F_app, scale, omega, free_g
        nb = scale.size
        self.w = omega[:, None]
        self.w_ref = np.maximum(omega, 1.0)
        self.inv_s = (1.0 / scale)[:, None]
        self.As = (self.A / scale)[:, None, None, None]
        self.wrs = (self.w_ref / scale)[:, None, None]
        self.Aw = (self.A / self.w_ref)[:, None, None]
        self.mask = np.ones((nb, 3 + 2 * self.Z))
        self.mask[:, :3] = free_g
        act = np.ones((nb, 4))
        act[:, :3] = free_g
        self.act, self.act2 = act, act[:, :, None] * act[:, None, :]
        self.eye_fix = np.eye(4)[None] * (1.0 - act)[:, :, None]

    def rows(self, idx):
        new = _HSProblem.__new__(_HSProblem)
        new.__dict__.update(self.__dict__)
        new.set_cases(self.F_app[idx], self.scale[idx], self.omega[idx], self.free_g[idx])
        if self.film is not None:
            new.film = self.film.take(idx)
            new.fz = None if self.fz is None else {k: v[idx] for k, v in self.fz.items()}
        return new

    def centres(self, g):
        """Inner groove-centre offsets (A1, A2) per ball (nb, Z, 2) [m] at the ring unknowns g (nb, 3)."""
        return (g @ self.Lb).reshape(-1, self.Z, 2) + self.off

    # ------------------------------------------------------------------ residual
    def evaluate(self, z):
        r"""Everything at the unknowns z (nb, 3 + 2Z).

        Contacts: n_c = (sin α_c, cos α_c) the unit vectors O_i − C (inner) and C − O_o (outer),
        δ_c = |·| − (f_c − ½)D, Q_c = K_c δ_c^1.5 (an open contact: the tension stiffness k_ε δ).
        Kinematics (:func:`thermobear.contact.kinematics.ball_kinematics` written with sin α, cos α of the
        contact normals, control contact k, σ = +1 outer, −1 inner): tan β = −sin α_k / (cos α_k + σγ'),
        contact radii R_c = (dm/2)(1 ∓ γ' cos α_c), lever arms E_c = (D/2) cos(α_c + β); each ball's own
        no-slip orbital speed ω_c,j = ω R_i E_o / (R_o E_i + R_i E_o); cage speed ω_cage = Σ Q_i ω_c,j / Σ Q_i
        (:func:`thermobear.contact.kinematics.common_cage_speed`); ball spin the load-weighted least-squares
        ω_R = −[Q_o E_o R_o ω_cage + Q_i E_i R_i (ω − ω_cage)] / (Q_o E_o² + Q_i E_i²)
        (:func:`thermobear.contact.kinematics.caged_ball_kinematics`; own no-slip −ω R_o R_i / det when
        both contacts are open); F_c = ½ m dm ω_cage², M_g = J ω_R ω_cage sin β."""
        nb, Z, A = z.shape[0], self.Z, self.A
        st = _HSState.__new__(_HSState)
        V = np.empty((nb, Z, 2, 2))
        x = z[:, 3:].reshape(nb, Z, 2)
        np.multiply(x, A, out=V[:, :, 1])                                     # C − O_o
        np.subtract(self.centres(z[:, :3]), V[:, :, 1], out=V[:, :, 0])       # O_i − C
        sq = V * V
        d = np.sqrt(sq[..., 0] + sq[..., 1])
        n = V / d[..., None]
        dl = d - self.c0
        if self.per_ball:
            al = np.arctan2(V[..., 0], V[..., 1])
            K = np.stack([self.brg.K_i(al[..., 0]), self.brg.K_o(al[..., 1])], axis=-1)
        else:
            K = self.K0
        st.fz_W = st.h = st.d_el = st.f_Ga = st.f_GQ = st.f_hu = st.f_v = st.f_al = st.f_rel = st.codes = None
        if self.film is None:
            pos = dl > 0
            st.allpos = bool(pos.all())
            if st.allpos:
                r = np.sqrt(dl)
                Q, dQ = K * dl * r, (self.K15 if not self.per_ball else 1.5 * K) * r
            else:
                r = np.sqrt(np.where(pos, dl, 0.0))
                Q = np.where(pos, K * dl * r, self.k_eps * dl)
                dQ = np.where(pos, 1.5 * K * r, self.k_eps)
        else:
            Q, dQ = self._film_force(st, V, dl, K)
            st.allpos = True
        self._kinematics(st, n, Q)
        # forces on the ball: the inner ring's Q_i n_i + T_i e_i, the outer ring's −(Q_o n_o + T_o e_o)
        F = Q[..., None] * n
        if self.has_lam:
            e = n[..., ::-1] * _SGN_E
            F += (st.Mg[..., None] * self.lamD)[..., None] * e
        res = np.empty((nb, 3 + 2 * Z))
        r_b = res[:, 3:].reshape(nb, Z, 2)
        np.subtract(F[:, :, 0], F[:, :, 1], out=r_b)
        r_b[..., 1] += st.Fc
        r_g = F[:, :, 0].reshape(nb, 2 * Z) @ self.Sg
        if self.lam_i:
            r_g[:, 2] -= st.Mg @ self.mom
        np.subtract(r_g, self.F_app, out=res[:, :3])
        res *= self.inv_s
        norm = np.abs(res * self.mask).max(axis=1)
        if not np.isfinite(norm).all():              # an overflow: a residual too large to accept (continue)
            norm = np.where(np.isfinite(norm), norm, np.inf)
        if st.codes is not None:                     # the film law could not be inverted: the case stops
            norm = np.where(st.codes.any(axis=(1, 2)), np.nan, norm)
        st.z, st.V, st.d, st.n, st.dl, st.Q, st.dQ, st.res, st.norm = z, V, d, n, dl, Q, dQ, res, norm
        return st

    def _kinematics(self, st, n, Q):
        """β, contact radii, lever arms, own orbital speeds, cage speed, ω_R, F_c, M_g into ``st``."""
        w = self.w
        sk, ck = n[:, :, self.k, 0], n[:, :, self.k, 1]
        rb2 = self.rb2_0 + self.rb2_1 * ck
        irb = 1.0 / np.sqrt(rb2)
        cb, sb = (ck + self.cb_0) * irb, -sk * irb
        cab = n[..., 1] * cb[..., None] - n[..., 0] * sb[..., None]        # cos(α_c + β)
        R = self.hdm + self.Rsg * n[..., 1]
        E = self.hD * cab
        Ri, Ro, Ei, Eo = R[..., 0], R[..., 1], E[..., 0], E[..., 1]
        det = Ro * Ei + Ri * Eo
        w_own = w * Ri * Eo / det
        q = Q if st.allpos else np.maximum(Q, 0.0)
        qs = q[..., 0].sum(1, keepdims=True)
        if (qs > 0).all():
            wgt = q[..., 0] / qs
        else:
            has = qs > 0
            wgt = np.where(has, q[..., 0] / np.where(has, qs, 1.0), 1.0 / self.Z)
        W = (wgt * w_own).sum(1, keepdims=True)
        v = np.empty((W.shape[0], 1, 2))
        np.subtract(w, W, out=v[:, :, 0])
        v[:, :, 1] = W
        qE = q * E
        qER = qE * R
        den = (qE * E).sum(-1)
        num = -(qER * v).sum(-1)
        pos = den > 0
        st.wpos = bool(pos.all())
        if st.wpos:
            wR = num / den
        else:
            wR = np.where(pos, num / np.where(pos, den, 1.0), -w * Ro * Ri / det)
        st.Fc = self.mdm2 * W * W
        st.Mg = self.J * wR * W * sb
        st.q, st.qs, st.wgt, st.W, st.v, st.qE, st.qER, st.den = q, qs, wgt, W, v, qE, qER, den
        st.rb2, st.cb, st.sb, st.cab, st.R, st.E, st.det, st.w_own, st.wR = (
            rb2, cb, sb, cab, R, E, det, w_own, wR)

    def _film_force(self, st, V, dl, K):
        r"""Contact loads and dQ/dδ of both contacts under the film law (:class:`_FilmLaw`).

        The law δ_c = δ_el,c(Q_c) − h_c(Q_c, α_c) is inverted per contact for Q_c > 0 by the bracketed
        Newton iteration in ln Q of :func:`thermobear.loads.filmlaw._invert` (vectorised over the batch, the
        balls and both contacts).  The entrainment speeds use the cage speed frozen in ``self.fz``
        (:meth:`refresh`); dQ/dδ = 1/(dδ_el/dQ − dh/dQ) > 0.  Warm start: the loads of the frozen iterate
        carried to first order, Δln Q = (Δδ − ∂G/∂α Δα + h ∂ln h/∂ln u Δln v) / (∂G/∂ln Q) (only a
        starting value: the inversion is converged from it)."""
        fz = self.fz
        al = np.arctan2(V[..., 0], V[..., 1])
        Kc = np.broadcast_to(K, al.shape) if np.ndim(K) > 1 else K
        W = fz["W"]
        v = np.stack([np.abs(self.w - W), W], axis=-1)                    # (nb, 1, 2)
        Q0 = fz["Q"]
        if "GQ" in fz:
            Q0 = _carry(Q0, fz["GQ"], (dl - fz["dl"]) - fz["Ga"] * (al - fz["al"]) + fz["hu"] * np.log(v / fz["v"]))
        Q, d_el, h, GQ, Ga, h_u, nit, rel, fail = _invert(self.film.bind(Kc, v).at(al), dl, al, Q0)
        st.f_al, st.f_Ga, st.f_GQ, st.f_hu, st.f_v, st.h, st.d_el = al, Ga, GQ, h_u, v, h, d_el
        st.f_rel, st.fz_W, st.codes = np.full(Q.shape[0], rel), W.copy(), fail
        return Q, Q / GQ

    def refresh(self, z, st):
        """Film law: freeze the cage speed and the warm-start loads at the iterate ``st`` and re-evaluate the
        cases whose cage speed has moved (by more than 5 % of the case's residual) with them."""
        if self.film is None:
            return st
        lag = np.abs(st.W - self.fz["W"])[:, 0] / self.w_ref
        self.fz = {"W": st.W.copy(), "Q": st.Q.copy(), "dl": st.dl, "al": st.f_al, "v": st.f_v, "GQ": st.f_GQ,
                   "Ga": st.f_Ga, "hu": st.f_hu}
        redo = np.flatnonzero((lag > 1e-15) & ~(lag <= LAG_SKIP * st.norm))
        if not redo.size:
            return st
        if redo.size == lag.size:
            return self.evaluate(z)
        st.put(redo, self.rows(redo).evaluate(z[redo]))
        return st

    # ------------------------------------------------------------------ Newton direction
    def direction(self, st):
        r"""Exact Newton direction at the iterate ``st``.

        Unknowns: the ball centres, the three ring unknowns g and, as a fourth global, the cage speed
        with the residual r_W = (ω_cage − Σ Q_i ω_c,j / Σ Q_i)/ω_ref, zero at every iterate: its row
        carries the dependence of the cage speed on every ball (a rank-one coupling), so the Newton
        step of the augmented system is that of the reduced one.  The per-ball 2×2 blocks are
        eliminated in closed form (Schur complement; a 4×4 system per case).  All kinematic
        derivatives (of β, the contact radii, ω_c,j, ω_R, F_c and M_g with respect to α_i, α_o, Q_i,
        Q_o and ω_cage) are analytic; dα_i/d(A − X) = e_i/d_i, dα_o/dX = e_o/d_o."""
        Jbb, Jbg, Jgb, S = self._blocks(st)
        nb, Z = st.Q.shape[:2]
        # per-ball 2×2 inverse [[d, −b], [−c, a]] / det
        det2 = Jbb[..., 0, 0] * Jbb[..., 1, 1] - Jbb[..., 0, 1] * Jbb[..., 1, 0]
        big = np.abs(Jbb).max(axis=(-1, -2))
        if (np.abs(det2) < (1e-14 * big) ** 2).any():      # ball exactly at the edge of contact
            tiny = 1e-14 * np.maximum(big, 1e-300)
            bad = np.abs(det2) < tiny ** 2
            Jbb = Jbb - (bad * tiny)[..., None, None] * np.eye(2)
            det2 = Jbb[..., 0, 0] * Jbb[..., 1, 1] - Jbb[..., 0, 1] * Jbb[..., 1, 0]
        Binv = Jbb[..., ::-1, ::-1].swapaxes(-1, -2) * _SGN_2 / det2[..., None, None]
        YB = Binv @ Jbg                                     # (nb, Z, 2, 5): B⁻¹ J_bg and B⁻¹ r_b
        T = (Jgb @ YB).sum(1)                               # (nb, 4, 5)
        S -= T[..., :4]
        rhs = T[..., 4]
        rhs[:, :3] -= st.res[:, :3]
        rhs *= self.act
        S *= self.act2
        S += self.eye_fix
        try:
            dG = np.linalg.solve(S, rhs[..., None])        # (nb, 4, 1)
        except np.linalg.LinAlgError:                       # a singular case: regularise it
            sd = np.abs(np.linalg.det(S))
            S = np.where((sd < 1e-300)[:, None, None], S + 1e-6 * np.eye(4)[None], S)
            dG = np.linalg.solve(S, rhs[..., None])
        ext = np.empty((nb, 1, 5, 1))
        ext[:, 0, :4] = dG
        ext[:, 0, 4] = 1.0
        dz = np.empty((nb, 3 + 2 * Z))
        dz[:, :3] = dG[:, :3, 0]
        np.negative((YB @ ext)[..., 0], out=dz[:, 3:].reshape(nb, Z, 2))
        return dz

    def _blocks(self, st):
        """The blocks of the augmented Jacobian (scaled): per ball ∂r_b/∂X (nb, Z, 2, 2), [∂r_b/∂g,
        ∂r_b/∂ω_cage, r_b] (nb, Z, 2, 5), the balls' part of ∂(r_g, r_W)/∂X (nb, Z, 4, 2), and the
        global block ∂(r_g, r_W)/∂(g, ω_cage) before the elimination (nb, 4, 4)."""
        n, d, Q, dQ = st.n, st.d, st.Q, st.dQ
        W, wR, sb, R, E, den, v = st.W, st.wR, st.sb, st.R, st.E, st.den, st.v
        J, hD = self.J, self.hD
        w = self.w
        Ri, Ro, Ei, Eo = R[..., 0], R[..., 1], E[..., 0], E[..., 1]
        # --- derivatives of the kinematics with respect to α_m (last axis m = inner, outer)
        b = -(1.0 + self.rb2_1 * 0.5 * n[:, :, self.k, 1]) / st.rb2          # dβ/dα_k
        sab = n[..., 0] * st.cb[..., None] + n[..., 1] * sb[..., None]          # sin(α_c + β)
        Ed = (-hD * sab)[..., :, None] * (np.eye(2) + b[..., None, None] * self.ek)   # dE_c/dα_m
        Rd = -self.Rsg * n[..., 0]                                             # dR_c/dα_c
        RdE = Rd * E[..., ::-1]                                                # (Rd_i E_o, Rd_o E_i)
        det_m = Ro[..., None] * Ed[..., 0, :] + Ri[..., None] * Ed[..., 1, :] + RdE
        RdE[..., 1] = 0.0
        wo_m = (w[..., None] * (Ri[..., None] * Ed[..., 1, :] + RdE) - st.w_own[..., None] * det_m) / st.det[..., None]
        qEv = st.qE * v
        wpos = st.wpos
        den1 = den if wpos else np.where(den > 0, den, 1.0)
        coef = (st.q * R) * v + (2.0 * wR)[..., None] * st.qE
        wR_m = -((coef[..., :, None] * Ed).sum(-2) + qEv * Rd) / den1[..., None]
        wR_Q = -E * (R * v + wR[..., None] * E) / den1[..., None] * (Q > 0)
        wR_W = (st.qER[..., 0] - st.qER[..., 1]) / den1
        if not wpos:
            pos = (den > 0)[..., None]
            own = (-w[..., None] * np.stack([Ro * Rd[..., 0], Rd[..., 1] * Ri], axis=-1)
                   + (w * Ro * Ri / st.det)[..., None] * det_m) / st.det[..., None]
            wR_m = np.where(pos, wR_m, own)
            wR_Q = np.where(pos, wR_Q, 0.0)
            wR_W = np.where(pos[..., 0], wR_W, 0.0)
        JW = J * W
        Mg_m = (JW * sb)[..., None] * wR_m
        Mg_m[..., self.k] += JW * wR * st.cb * b
        Mg_Q = (JW * sb)[..., None] * wR_Q
        Mg_W = J * sb * (wR + W * wR_W)
        Fc_W = 2.0 * self.mdm2 * W
        # cage speed: ∂ω_cage/∂Q_i, ∂α_m of each ball
        if (st.qs > 0).all():
            W_Q = ((st.w_own - W) / st.qs) * (Q[..., 0] > 0)
        else:
            has = st.qs > 0
            W_Q = np.where(has & (Q[..., 0] > 0), (st.w_own - W) / np.where(has, st.qs, 1.0), 0.0)
        W_m = st.wgt[..., None] * wo_m
        e = n[..., ::-1] * _SGN_E                                              # (cos α, −sin α)
        if self.film is not None:
            # film law: Q_c(δ_c, α_c), ∂Q/∂α = −(∂G/∂α) dQ/dδ, so dQ/dp = dQ/dδ n + ∂Q/∂α e/d
            Qa = -st.f_Ga * dQ
            Mg_m = Mg_m + Mg_Q * Qa
            W_m[..., 0] += W_Q * Qa[..., 0]
        ed = e / d[..., None]
        mC = Mg_m[..., None] * ed + (Mg_Q * dQ)[..., None] * n                  # dM_g/dp_c
        bC = W_m[..., None] * ed                                               # dω_cage/dp_c
        bC[..., 0, :] += (W_Q * dQ[..., 0])[..., None] * n[..., 0, :]
        # contact stiffness matrices d(Q n + T e)/dp = dQ n nᵀ + (Q e − T n) eᵀ / d (+ film: n (∂Q/∂α) eᵀ/d)
        t = Q[..., None] * e
        if self.has_lam:
            t -= (st.Mg[..., None] * self.lamD)[..., None] * n
        if self.film is not None:
            t += Qa[..., None] * n
        G = dQ[..., None, None] * (n[..., :, None] * n[..., None, :]) + (t / d[..., None])[..., :, None] * e[..., None, :]
        As = self.As
        nb, Z = Q.shape[:2]
        if self.has_lam:
            vM = (self.vsg[:, None] * e).sum(-2)                              # ∂r_b/∂M_g
            H = G * _PM[:, None, None] + vM[..., None, :, None] * mC[..., :, None, :]   # d r_b/dp_c
            a_b = vM * Mg_W[..., None]
        else:
            H = G * _PM[:, None, None]
            a_b = np.zeros((nb, Z, 2))
        Hi = H[:, :, 0]
        Jbb = As * (H[:, :, 1] - Hi)
        Jbg = np.empty((nb, Z, 2, 5))
        np.multiply(As, Hi @ self.Wt, out=Jbg[..., :3])
        a_b[..., 1] += Fc_W
        np.multiply(a_b, self.wrs, out=Jbg[..., 3])
        Jbg[..., 4] = st.res[:, 3:].reshape(nb, Z, 2)
        Jgb = np.empty((nb, Z, 4, 2))
        WGi = self.WtT @ G[:, :, 0]
        if self.lam_i:
            u = self.WtT @ (self.lamD[0] * e[:, :, 0])[..., None]            # (nb, Z, 3, 1)
            u[..., 2, 0] -= self.mom
            Li = WGi + u * mC[:, :, 0, None, :]
            Jgb[..., :3, :] = As * (u * mC[:, :, 1, None, :] - Li)
            Jgg_b = Li @ self.Wt
            S_W = (u[..., 0] * Mg_W[..., None]).sum(1) * (self.w_ref / self.scale)[:, None]
        else:
            np.multiply(-As, WGi, out=Jgb[..., :3, :])
            Jgg_b = WGi @ self.Wt
            S_W = 0.0
        np.multiply(self.Aw, bC[:, :, 0] - bC[:, :, 1], out=Jgb[..., 3, :])
        S = np.empty((nb, 4, 4))
        np.multiply(As[..., 0], Jgg_b.sum(1), out=S[:, :3, :3])
        S[:, :3, 3] = S_W
        S[:, 3, :3] = -self.Aw[..., 0] * (bC[:, :, 0, None, :] @ self.Wt)[..., 0, :].sum(1)
        S[:, 3, 3] = 1.0
        return Jbb, Jbg, Jgb, S

    # ------------------------------------------------------------------ safeguards and path
    def limit(self, st, dz):
        r"""Shorten the step of a ball that would close an open contact.

        An open contact has no stiffness in the linear model, so Newton moves a ball with one open
        contact as if the race were not there; near a wedge (a ball outside the load zone held between
        both races with loads ~F_c) the step then buries the ball deep in that race.  The ball's step is
        shortened so that the predicted approach of an open contact, δ + n·(ΔA − ΔX) (inner) or δ + n·ΔX
        (outer), reaches at most δ_η = (F/K)^(2/3), the approach that carries the ball's force scale
        F = max(F_c, |r_b|) — the next step then sees the contact."""
        if not (st.dl < 0).any():
            return dz
        nb, Z, A = dz.shape[0], self.Z, self.A
        dX = A * dz[:, 3:].reshape(nb, Z, 2)
        dV = np.stack([self.centres(dz[:, :3]) - self.off - dX, dX], axis=2)
        dd = (st.n * dV).sum(-1)                                              # predicted change of δ_c
        rb = st.res[:, 3:].reshape(nb, Z, 2)
        F = np.maximum(st.Fc, np.abs(rb).max(axis=-1) * self.scale[:, None])
        d_eta = (F[..., None] / self.K0) ** (2.0 / 3.0)
        over = (st.dl < 0) & (st.dl + dd > d_eta)
        if not over.any():
            return dz
        kap = np.where(over, (d_eta - st.dl) / np.where(over, dd, 1.0), 1.0).min(axis=-1)
        dz = dz.copy()
        dz[:, 3:] *= np.repeat(kap, 2, axis=1)
        return dz

    def path(self, z, dz):
        """A step in polar form about the outer groove centre for each ball: radius ρ, angle α_o,
        dρ = n_o·dx, dα = e_o·dx/ρ (n_o = (sin α_o, cos α_o), e_o = (cos α_o, −sin α_o)); the rings linear."""
        nb, Z = z.shape[0], self.Z
        x, dx = z[:, 3:].reshape(nb, Z, 2), dz[:, 3:].reshape(nb, Z, 2)
        x1, x2, d1, d2 = x[..., 0], x[..., 1], dx[..., 0], dx[..., 1]
        rho = np.sqrt(x1 * x1 + x2 * x2)
        return z, dz, rho, np.arctan2(x1, x2), (x1 * d1 + x2 * d2) / rho, (x2 * d1 - x1 * d2) / (rho * rho)

    def move(self, path, lam):
        """The point at the fraction lam (nb,) of the step along the path: the ball centres at
        (ρ + λ dρ)(sin, cos)(α + λ dα) — to first order the Newton step itself; a ball resting on the outer
        race keeps its approach δ_o when it rolls along the race (a straight tangential step would push it
        into the race by ≈ step²/2ρ, far more than the δ_o of a lightly loaded ball).  ``lam=None``: the
        full step."""
        z, dz, rho, a, drho, da = path
        nb, Z = z.shape[0], self.Z
        out = np.empty(z.shape)
        if lam is None:
            np.add(z[:, :3], dz[:, :3], out=out[:, :3])
            r, t = rho + drho, a + da
        else:
            np.add(z[:, :3], lam[:, None] * dz[:, :3], out=out[:, :3])
            lc = lam[:, None]
            r, t = rho + lc * drho, a + lc * da
        xo = out[:, 3:].reshape(nb, Z, 2)
        np.multiply(r, np.sin(t), out=xo[..., 0])
        np.multiply(r, np.cos(t), out=xo[..., 1])
        return out

    def relax(self, z, st, todo):
        """After a damped step: re-place stalled light balls (:func:`thermobear.loads.highspeed_start.relax`)."""
        if self.per_ball or self.film is not None:
            return z, st
        return _relax(self, z, st, todo)

