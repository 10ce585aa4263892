r"""The high-speed ball equilibrium as a problem of the shared Newton: residual, exact Jacobian, path.

Equations and conventions: :mod:`thermobear.loads.highspeed` (Jones 1960 [1]; Harris 2001 [2] ch. 8;
Harris & Kotzalas 2007 [3] ch. 3).  Unknowns of a load case, one row of z (nb, ndof + 2Z):

    z = (g_0 … g_{ndof−1},  X1_0/A … X1_{Z−1}/A,  X2_0/A … X2_{Z−1}/A)

the ring unknowns g = (δa/A, δr/A, θℜ/A[, δz/A, θ_yℜ/A]) first (the lever map of
:mod:`thermobear.loads.rings`: ndof = 3 for in-plane loads, 5 otherwise), then the ball centres from their
outer groove curvature centres, axial components of every ball, then radial ones.  Residual rows in the
same order: the inner ring's (F_a, F_r, M/ℜ[, F_z, M_y/ℜ]) balance, then each ball's axial and radial
force balance, all divided by the case's force scale.  Each ball's equations live in its own radial
plane (the plane of the axis and ψ_j), so the ring's second radial direction only adds lever rows.

Layout.  A load case is a few hundred numpy operations on Z-element rows: their call overhead, not the
arithmetic, sets the cost.  So every per-ball quantity is a flat row, the two contacts of a ball side by
side — (nb, 2Z) arrays [inner | outer] — and one call serves both contacts wherever their formulas
agree; the contact vectors are (nb, 4Z) [axial inner | axial outer | radial inner | radial outer];
sums over the balls are products with constant matrices.

References
----------
.. [1] Jones, A. B. (1960). A general theory for elastically constrained ball and radial roller
   bearings under arbitrary load and speed conditions. *J. Basic Eng.* 82(2):309–320.
.. [2] Harris, T. A. (2001). *Rolling Bearing Analysis*, 4th ed., Wiley, ch. 8.
.. [3] Harris, T. A. & Kotzalas, M. N. (2007). *Advanced Concepts of Bearing Technology* (Rolling
   Bearing Analysis, 5th ed.), CRC Press, ch. 3.
"""
from __future__ import annotations

import numpy as np

from thermobear.loads.filmlaw import _carry, _invert
from thermobear.loads.highspeed_start import relax as _relax
from thermobear.loads.rings import COMPONENT, lever_matrix, levers

_EPS_TENSION = 1e-12    # linear stiffness of an open contact, relative to K √A (numerical regularisation)
LAG_SKIP = 0.05         # film refresh: keep the iterate when the cage-speed lag is below this fraction of its residual


def _stiffness_constants(brg):
    """K_i, K_o at the nominal contact angle [N/m^1.5] and the open-contact regularising stiffness
    ε K_n √A [N/m] of a bearing (:attr:`~thermobear.contact.geometry.BallBearing.K_nominal`, derived when the
    bearing was built)."""
    if brg.K_nominal is None:                # a geometry Hertz refuses: its error
        brg.Kn(brg.alpha_nominal)
    Ki, Ko, Kn = brg.K_nominal
    return Ki, Ko, _EPS_TENSION * Kn * np.sqrt(brg.A)


def _constants(brg, ndof):
    """Fixed arrays of a bearing (formed with each problem, ≈ 15 µs): the lever matrix (ndof, 2Z) [m], the ring sums of the ball forces
    (4Z, ndof), the sums of the Jacobian's per-ball terms ((2 ndof + 2) Z, ndof² + ndof), and each ring row's
    contact component comp_k (0 axial, 1 radial) and lever w_k ∈ {1, cos ψ, sin ψ} (ndof, Z): the ring sums
    S[m, k] = Σ_j P[m, comp_k] w_k of the per-ball rows P[m] = d r_g,m/dp and the cage row in one product."""
    Z = brg.Z
    L = lever_matrix(brg, ndof)
    W = levers(Z, ndof)                                        # (2, ndof, Z)
    comp = np.array(COMPONENT[:ndof])
    lev = np.stack([W[comp[k], k] for k in range(ndof)])
    Sg = np.zeros((4 * Z, ndof))              # (f_i,a | f_o,a | f_i,r | f_o,r) -> (F_a, F_r, M/ℜ, F_z, M_y/ℜ)
    Sg[:Z], Sg[2 * Z:3 * Z] = W[0].T, W[1].T
    M = np.zeros((2 * ndof + 2, Z, ndof * ndof + ndof))
    m, k = np.arange(ndof + 1)[:, None], np.arange(ndof)[None, :]
    M[2 * m + comp[k], :, m * ndof + k] = lev[k]     # ring rows m, then the cage row (columns ndof² …)
    return L, Sg, M.reshape((2 * ndof + 2) * Z, ndof * ndof + ndof), comp, lev


def _fixed(brg, lam_i, lam_o, kin_control, ndof, arm):
    """The fixed attributes of a :class:`_HSProblem` (formed with each problem, ≈ 40 µs: per bearing, raceway
    control, ring unknowns and tilt arm ℜ [m])."""
    Z, A = brg.Z, brg.A
    L, Sg, Msum, comp, lev = _constants(brg, ndof)
    Ki, Ko, k_eps = _stiffness_constants(brg)
    gp = brg.D / brg.dm
    outer = kin_control == "outer"          # the contact whose zero spin sets β
    sg = 1.0 if outer else -1.0

    m = brg.ball_mass
    hdm, hD = 0.5 * brg.dm, 0.5 * brg.D
    # rows (1, Z) of one value and (1, 2Z) of an inner and an outer value, each value repeated Z times
    ones = dict(RB0=1.0 + gp * gp, RB1=2.0 * sg * gp, CB0=sg * gp, SGP=sg * gp, ONE=1.0, HD=hD)
    pairs = dict(off=(0.0, brg.A_r0), c0=((brg.fi - 0.5) * brg.D, (brg.fo - 0.5) * brg.D),
                 K0=(Ki, Ko), K15=(1.5 * Ki, 1.5 * Ko), ONE2=(1.0, 1.0), HDM=(hdm, hdm),
                 RSG=(-hdm * gp, hdm * gp), NRSG=(hdm * gp, -hdm * gp), HD2=(hD, hD), NHD2=(-hD, -hD),
                 LAMD=(lam_i / brg.D, lam_o / brg.D), LP=(lam_i / brg.D, -lam_o / brg.D), PM=(1.0, -1.0))
    r1 = np.repeat(np.array([[v] for v in ones.values()]), Z, axis=1)
    r2 = np.repeat(np.array(list(pairs.values())), Z, axis=1)
    f = dict(
        brg=brg, Z=Z, A=A, R=arm, L=L, Sg=Sg, Msum=Msum, ng=ndof, comp=comp, lev=lev,
        rows_k=tuple((k, int(comp[k]), lev[k][None, :]) for k in range(1, ndof)),   # rows after δa, levers (1, Z)
        lam_i=lam_i, lam_o=lam_o, kin_control=kin_control, Ki0=Ki, Ko0=Ko, k_eps=k_eps,
        D=brg.D, dm=brg.dm, fi=brg.fi, gp=gp, outer=outer,
        m=m, J=m * brg.D**2 / 10.0, mdm2=0.5 * m * brg.dm, has_lam=bool(lam_i or lam_o),
        # the couple of the inner friction per M_g, in the tilt rows (M/ℜ, M_y/ℜ): −λ_i f_i M_g w / ℜ
        mom=tuple((k, lam_i * brg.fi / arm * lev[k]) for k in range(2, ndof, 2)),
        onesZ=np.ones((Z, 1)))
    f.update({k: r1[i:i + 1] for i, k in enumerate(ones)})
    f.update({k: r2[i:i + 1] for i, k in enumerate(pairs)})
    # c0: |O_i − C|, |C − O_o| unloaded [m]; RSG: R_c = dm/2 + RSG_c cos α_c; LP: ∂r_b/∂M_g = Σ_c LP_c e_c;
    # PM: the inner contact pushes the ball, the outer holds it
    return f


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

    # per-ball views (nb, Z)
    @property
    def Qi(self):
        return self.Q[:, :self.Q.shape[1] // 2]

    @property
    def X1(self):
        Z = self.d.shape[1] // 2
        return self.V[:, Z:2 * Z]

    @property
    def X2(self):
        Z = self.d.shape[1] // 2
        return self.V[:, 3 * Z:]


class _HSProblem:
    """Fixed data of one batch of high-speed load cases (bearing constants, loads, speeds, control).

    ``film``: the :class:`_FilmLaw` of the film contact law (None: dry Hertz contacts); ``fz`` the data it
    freezes per Newton step (cage speed "W" (nb, 1), warm-start loads "Q" (nb, 2Z) and the derivatives
    of the iterate they were taken at, :meth:`refresh`).

    Constants are held as (1, n) rows: numpy's fast path for operands of one shape then serves a single
    load case, and a batch broadcasts them."""

    def __init__(self, brg, F_app, scale, omega, free_g, stiffness, lam_i, lam_o, kin_control, arm):
        self.__dict__.update(_fixed(brg, lam_i, lam_o, kin_control, F_app.shape[1], arm))
        self.stiffness, self.per_ball = stiffness, stiffness == "per_ball"
        self.film = None
        self.fz = None
        self.set_cases(F_app, scale, omega, free_g)

    def set_cases(self, F_app, scale, omega, free_g):
        """Per-case data (call again after changing any of them)."""
        self.F_app, self.scale, self.omega, self.free_g = F_app, scale, omega, free_g
        nb, Z = scale.size, self.Z
        self.w = omega[:, None]
        self.wZ = np.repeat(self.w, Z, axis=1)
        self.w2Z = np.repeat(self.w, 2 * Z, axis=1)
        self.w_ref = np.maximum(omega, 1.0)
        self.inv_s = (1.0 / scale)[:, None]
        self.As = (self.A / scale)[:, None]
        self.AsZ = np.repeat(self.As, Z, axis=1)
        self.wrsZ = np.repeat((self.w_ref / scale)[:, None], Z, axis=1)
        self.Aw = (self.A / self.w_ref)[:, None]
        self.AwZ = np.repeat(self.Aw, Z, axis=1)
        ng = self.ng
        self.mask = np.ones((nb, ng + 2 * Z))
        self.mask[:, :ng] = free_g
        act = np.ones((nb, ng + 1))
        act[:, :ng] = free_g
        self.act, self.act2 = act, act[:, :, None] * act[:, None, :]
        self.eye_fix = np.eye(ng + 1)[None] * (1.0 - act)[:, :, None]

    def rows(self, idx):
        new = _HSProblem.__new__(_HSProblem)
        new.__dict__.update(self.__dict__)
        new.set_cases(self.F_app[idx], self.scale[idx], self.omega[idx], self.free_g[idx])
        if self.film is not None:
            new.film = self.film.take(idx)
            new.fz = None if self.fz is None else {k: v[idx] for k, v in self.fz.items()}
        return new

    def centres(self, g):
        """Inner groove-centre offsets (A1 | A2) per ball (nb, 2Z) [m] at the ring unknowns g (nb, ndof)."""
        return g @ self.L + self.off

    # ------------------------------------------------------------------ residual
    def evaluate(self, z):
        r"""Everything at the unknowns z (nb, ndof + 2Z).

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
        nb, Z, A, ng = z.shape[0], self.Z, self.A, self.ng
        Z2, Z3 = 2 * Z, 3 * Z
        st = _HSState.__new__(_HSState)
        V = np.empty((nb, 4 * Z))                          # [p | X1 | q | X2]: O_i − C and C − O_o
        np.multiply(z[:, ng:ng + Z], A, out=V[:, Z:Z2])
        np.multiply(z[:, ng + Z:], A, out=V[:, Z3:])
        Ac = self.centres(z[:, :ng])
        np.subtract(Ac[:, :Z], V[:, Z:Z2], out=V[:, :Z])
        np.subtract(Ac[:, Z:], V[:, Z3:], out=V[:, Z2:Z3])
        sq = V * V
        d = np.sqrt(sq[:, :Z2] + sq[:, Z2:])               # [d_i | d_o]
        n = np.empty((nb, 4 * Z))                          # [sin α_i | sin α_o | cos α_i | cos α_o]
        np.divide(V[:, :Z2], d, out=n[:, :Z2])
        np.divide(V[:, Z2:], d, out=n[:, Z2:])
        dl = d - self.c0
        if self.per_ball:
            al = np.arctan2(V[:, :Z2], V[:, Z2:])
            K = np.concatenate((self.brg.K_i(al[:, :Z]), self.brg.K_o(al[:, Z:])), axis=1)
        else:
            K = self.K0
        st.fz_W = st.h = st.d_el = st.f_Ga = st.f_GQ = st.f_hu = st.f_v = st.f_al = st.f_rel = st.codes = None
        if self.film is not None:
            Q, dQ = self._film_force(st, V, dl, K)
            st.allpos = True
        elif dl.min() > 0:
            st.allpos = True
            r = np.sqrt(dl)
            dQ = (self.K15 if not self.per_ball else 1.5 * K) * r
            Q = K * dl * r
        else:
            st.allpos = False
            pos = dl > 0
            r = np.sqrt(np.where(pos, dl, 0.0))
            Q = np.where(pos, K * dl * r, self.k_eps * dl)
            dQ = np.where(pos, 1.5 * K * r, self.k_eps)
        self._kinematics(st, n, Q)
        # forces on the ball: the inner ring's Q_i n_i + T_i e_i, the outer ring's −(Q_o n_o + T_o e_o),
        # e = (cos α, −sin α), T_c = λ_c M_g/D
        F = np.empty((nb, 4 * Z))                          # [Q sin α | Q cos α] of both contacts
        np.multiply(Q, n[:, :Z2], out=F[:, :Z2])
        np.multiply(Q, n[:, Z2:], out=F[:, Z2:])
        if self.has_lam:
            T = np.concatenate((st.Mg, st.Mg), axis=1) * self.LAMD
            F[:, :Z2] += T * n[:, Z2:]
            F[:, Z2:] -= T * n[:, :Z2]
        res = np.empty((nb, ng + Z2))
        np.subtract(F[:, :Z], F[:, Z:Z2], out=res[:, ng:ng + Z])
        np.subtract(F[:, Z2:Z3], F[:, Z3:], out=res[:, ng + Z:])
        res[:, ng + Z:] += st.Fc
        r_g = F @ self.Sg
        if self.lam_i:
            for k, mom in self.mom:
                r_g[:, k] -= st.Mg @ mom
        np.subtract(r_g, self.F_app, out=res[:, :ng])
        res *= self.inv_s
        norm = np.abs(res * self.mask).max(axis=1)
        if not norm.max() < np.inf:                  # an overflow: a residual too large to accept (continue)
            norm = np.where(np.isfinite(norm), norm, np.inf)
        if st.codes is not None:                     # the film law could not be inverted: the case stops
            norm = np.where(st.codes.any(axis=1), np.nan, norm)
        st.z, st.V, st.d, st.n, st.dl, st.Q, st.dQ, st.res, st.norm = z, V, d, n, dl, Q, dQ, res, norm
        return st

    def _kinematics(self, st, n, Q):
        """β, contact radii, lever arms, own orbital speeds, cage speed, ω_R, F_c, M_g into ``st``."""
        Z = self.Z
        Z2 = 2 * Z
        nb = Q.shape[0]
        sn, cs = n[:, :Z2], n[:, Z2:]
        ck, sk = (cs[:, Z:], sn[:, Z:]) if self.outer else (cs[:, :Z], sn[:, :Z])
        rb2 = ck * self.RB1
        rb2 += self.RB0
        irb = self.ONE / np.sqrt(rb2)
        cb = (ck + self.CB0) * irb
        msb = sk * irb                                         # −sin β
        cbsb = np.empty((nb, 2 * Z2))                          # [−sin β | −sin β | cos β | cos β]
        cbsb[:, :Z], cbsb[:, Z:Z2], cbsb[:, Z2:3 * Z], cbsb[:, 3 * Z:] = msb, msb, cb, cb
        tt = n * cbsb
        E = tt[:, :Z2] + tt[:, Z2:]
        E *= self.HD2                                          # (D/2) cos(α_c + β)
        R = cs * self.RSG
        R += self.HDM
        Ri, Ro, Ei, Eo = R[:, :Z], R[:, Z:], E[:, :Z], E[:, Z:]
        det = Ro * Ei
        det += Ri * Eo
        w_own = self.wZ * Ri
        w_own *= Eo
        w_own /= det
        q = Q if st.allpos else np.maximum(Q, 0.0)
        qi = q[:, :Z]
        qs = np.dot(qi, self.onesZ)
        if qs.min() > 0:
            wgt = qi / qs
        else:
            has = qs > 0
            wgt = np.where(has, qi / np.where(has, qs, 1.0), 1.0 / Z)
        W = np.dot(wgt * w_own, self.onesZ)
        WZ = np.repeat(W, Z, axis=1)
        wmW = self.wZ - WZ
        qE = q * E
        qER = qE * R
        den = qE[:, :Z] * Ei
        den += qE[:, Z:] * Eo
        num = qER[:, :Z] * wmW
        num += qER[:, Z:] * WZ
        st.wpos = den.min() > 0
        if st.wpos:
            wR = num / den
            np.negative(wR, out=wR)
        else:
            pos = den > 0
            wR = np.where(pos, -num / np.where(pos, den, 1.0), -self.wZ * Ro * Ri / det)
        st.Fc = self.mdm2 * W * W
        JWZ = self.J * WZ
        st.Mg = JWZ * wR
        st.Mg *= msb
        np.negative(st.Mg, out=st.Mg)
        st.q, st.qs, st.wgt, st.W, st.WZ, st.wmW, st.qE, st.qER, st.den = q, qs, wgt, W, WZ, wmW, qE, qER, den
        st.rb2, st.cb, st.msb, st.cbsb, st.R, st.E, st.det, st.w_own, st.wR, st.JWZ = (
            rb2, cb, msb, cbsb, R, E, det, w_own, wR, JWZ)

    def _film_force(self, st, V, dl, K):
        r"""Contact loads and dQ/dδ of both contacts under the film law (:class:`_FilmLaw`).

        The law δ_c = δ_el,c(Q_c) − h_c(Q_c, α_c) is inverted per contact for Q_c > 0 by the bracketed
        Newton iteration in ln Q of :func:`thermobear.loads.filmlaw._invert` (vectorised over the batch, the
        balls and both contacts).  The entrainment speeds use the cage speed frozen in ``self.fz``
        (:meth:`refresh`); dQ/dδ = 1/(dδ_el/dQ − dh/dQ) > 0.  Warm start: the loads of the frozen iterate
        carried to first order, Δln Q = (Δδ − ∂G/∂α Δα + h ∂ln h/∂ln u Δln v) / (∂G/∂ln Q) (only a
        starting value: the inversion is converged from it)."""
        fz, Z2 = self.fz, 2 * self.Z
        al = np.arctan2(V[:, :Z2], V[:, Z2:])
        W = fz["W"]
        v = np.repeat(np.concatenate((np.abs(self.w - W), W), axis=1), self.Z, axis=1)     # (nb, 2Z)
        Q0 = fz["Q"]
        if "GQ" in fz:
            Q0 = _carry(Q0, fz["GQ"], (dl - fz["dl"]) - fz["Ga"] * (al - fz["al"]) + fz["hu"] * np.log(v / fz["v"]))
        Q, d_el, h, GQ, Ga, h_u, nit, rel, fail = _invert(self.film.bind(K, v).at(al), dl, al, Q0)
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
        eliminated in closed form (Schur complement; an (ndof + 1)² system per case).  All kinematic
        derivatives (of β, the contact radii, ω_c,j, ω_R, F_c and M_g with respect to α_i, α_o, Q_i,
        Q_o and ω_cage) are analytic; dα_i/d(A − X) = e_i/d_i, dα_o/dX = e_o/d_o."""
        B, C, Rr, S = self._blocks(st)
        nb, Z, ng = st.res.shape[0], self.Z, self.ng
        # per-ball 2×2 inverse [[d, −b], [−c, a]] / det of B = [[B00, B01], [B10, B11]] (rows of B (nb, 4, Z))
        B00, B01, B10, B11 = B[:, 0], B[:, 1], B[:, 2], B[:, 3]
        det2 = B00 * B11 - B01 * B10
        big = np.abs(B).max(axis=1)
        if (np.abs(det2) < (1e-14 * big) ** 2).any():      # ball exactly at the edge of contact
            tiny = 1e-14 * np.maximum(big, 1e-300)
            bad = (np.abs(det2) < tiny ** 2) * tiny
            B00, B11 = B00 - bad, B11 - bad
            det2 = B00 * B11 - B01 * B10
        idet = 1.0 / det2
        # Y = B⁻¹ [∂r_b/∂(g, ω_cage) | r_b]: rows (nb, ndof + 2, Z) of its two components
        Y0 = (B11 * idet)[:, None] * C[:, 0] - (B01 * idet)[:, None] * C[:, 1]
        Y1 = (B00 * idet)[:, None] * C[:, 1] - (B10 * idet)[:, None] * C[:, 0]
        T = Rr[:, 0] @ Y0.transpose(0, 2, 1) + Rr[:, 1] @ Y1.transpose(0, 2, 1)       # (nb, ndof + 1, ndof + 2)
        S -= T[..., :ng + 1]
        rhs = T[..., ng + 1]
        rhs[:, :ng] -= st.res[:, :ng]
        rhs *= self.act
        S *= self.act2
        S += self.eye_fix
        try:
            dG = np.linalg.solve(S, rhs[..., None])        # (nb, ndof + 1, 1)
        except np.linalg.LinAlgError:                       # a singular case: regularise it
            sd = np.abs(np.linalg.det(S))
            S = np.where((sd < 1e-300)[:, None, None], S + 1e-6 * np.eye(ng + 1)[None], S)
            dG = np.linalg.solve(S, rhs[..., None])
        ext = np.empty((nb, 1, ng + 2))
        ext[:, 0, :ng + 1] = dG[:, :, 0]
        ext[:, 0, ng + 1] = 1.0
        dz = np.empty((nb, ng + 2 * Z))
        dz[:, :ng] = dG[:, :ng, 0]
        np.negative((ext @ Y0)[:, 0], out=dz[:, ng:ng + Z])
        np.negative((ext @ Y1)[:, 0], out=dz[:, ng + Z:])
        return dz

    def _pair(self, a, b):
        """[a | b] (nb, 2Z) from two (nb, Z) rows."""
        out = np.empty((a.shape[0], 2 * self.Z))
        out[:, :self.Z], out[:, self.Z:] = a, b
        return out

    def _kinematic_derivatives(self, st):
        """Derivatives of the gyroscopic moment and the cage speed: (Mg_m, Mg_Q, W_m) (nb, 2Z) with respect
        to the contact angle / load of each contact (of M_g; of Σ Q_i ω_c,j / Σ Q_i through ball j),
        Mg_W = ∂M_g/∂ω_cage and W_Q = ∂ω_cage/∂Q_i (nb, Z)."""
        Z = self.Z
        Z2 = 2 * Z
        K, KN = (slice(Z, Z2), slice(0, Z)) if self.outer else (slice(0, Z), slice(Z, Z2))
        n, R, E, pair = st.n, st.R, st.E, self._pair
        sn, cs = n[:, :Z2], n[:, Z2:]
        Ri, Ro, Ei, Eo = R[:, :Z], R[:, Z:], E[:, :Z], E[:, Z:]
        mb = (cs[:, K] * self.SGP + self.ONE) / st.rb2                         # −dβ/dα_k
        cb, msb = st.cb, st.msb
        sab = n * np.concatenate((cb, cb, msb, msb), axis=1)
        hsab = (sab[:, :Z2] - sab[:, Z2:]) * self.NHD2                         # −(D/2) sin(α_c + β)
        Ed = hsab.copy()                                                       # dE_c/dα_c
        Ed[:, K] *= self.ONE - mb
        Ex = hsab[:, KN] * mb
        np.negative(Ex, out=Ex)                                                # dE_other/dα_k
        Rd = sn * self.NRSG                                                    # dR_c/dα_c
        det_m = pair(Ro, Ri) * Ed + Rd * pair(Eo, Ei)                          # d det/dα_m
        det_m[:, K] += R[:, K] * Ex
        N = pair(Rd[:, :Z] * Eo, Ri * Ed[:, Z:])                               # d(R_i E_o)/dα_m
        if not self.outer:                                                     # inner control: E_o moves with α_i
            N[:, :Z] += Ri * Ex
        det2 = pair(st.det, st.det)
        wo_m = (self.w2Z * N - pair(st.w_own, st.w_own) * det_m) / det2
        vv = pair(st.wmW, st.WZ)                                               # (ω − ω_cage | ω_cage)
        den = st.den
        wpos = st.wpos
        iden = self.ONE / (den if wpos else np.where(den > 0, den, 1.0))
        iden2 = pair(iden, iden)
        Rv = R * vv
        wE = pair(st.wR, st.wR) * E
        a = wE + wE
        a += Rv
        a *= st.q                                                              # coefficient of dE_c/dα_m
        Am = a * Ed
        Am[:, K] += a[:, KN] * Ex
        wR_m = st.qE * vv
        wR_m *= Rd
        wR_m += Am
        wR_m *= iden2
        np.negative(wR_m, out=wR_m)
        wR_Q = Rv + wE
        wR_Q *= E
        wR_Q *= iden2
        np.negative(wR_Q, out=wR_Q)
        wR_W = (st.qER[:, :Z] - st.qER[:, Z:]) * iden
        if not st.allpos:
            wR_Q *= st.Q > 0
        if not wpos:
            pos = den > 0
            pos2 = pair(pos, pos).astype(bool)
            own = (-self.w2Z * (pair(Ro, Ri) * Rd) + pair(self.wZ * Ro * Ri / st.det, self.wZ * Ro * Ri / st.det)
                   * det_m) / det2
            wR_m = np.where(pos2, wR_m, own)
            wR_Q = np.where(pos2, wR_Q, 0.0)
            wR_W = np.where(pos, wR_W, 0.0)
        JWmsb = st.JWZ * msb
        JWmsb2 = pair(JWmsb, JWmsb)
        Mg_m = JWmsb2 * wR_m                                                   # M_g = −J ω_cage ω_R (−sin β)
        Mg_m[:, K] += (st.JWZ * st.wR) * (cb * mb)
        np.negative(Mg_m, out=Mg_m)
        Mg_Q = JWmsb2 * wR_Q
        np.negative(Mg_Q, out=Mg_Q)
        Mg_W = st.WZ * wR_W
        Mg_W += st.wR
        Mg_W *= msb
        Mg_W *= -self.J
        if st.allpos and st.qs.min() > 0:
            W_Q = (st.w_own - st.WZ) / st.qs
        else:
            has = st.qs > 0
            W_Q = np.where(has & (st.Q[:, :Z] > 0), (st.w_own - st.WZ) / np.where(has, st.qs, 1.0), 0.0)
        W_m = pair(st.wgt, st.wgt) * wo_m
        return Mg_m, Mg_Q, Mg_W, W_m, W_Q

    def _blocks(self, st):
        """The scaled blocks of the augmented Jacobian: per ball B = ∂r_b/∂X (nb, 4, Z) (entries aa, ar, ra, rr:
        r_b axial, radial × X axial, radial), C = [∂r_b/∂g, ∂r_b/∂ω_cage, r_b] (nb, 2, ndof + 2, Z), R = the
        balls' part of ∂(r_g, r_W)/∂X (nb, 2, ndof + 1, Z) (by component of X), and the global block
        ∂(r_g, r_W)/∂(g, ω_cage) before the elimination (nb, ndof + 1, ndof + 1)."""
        Mg_m, Mg_Q, Mg_W, W_m, W_Q = self._kinematic_derivatives(st)
        nb, Z = st.res.shape[0], self.Z
        Z2 = 2 * Z
        n, d, Q, dQ = st.n, st.d, st.Q, st.dQ
        sn, cs = n[:, :Z2], n[:, Z2:]
        if self.film is not None:
            # film law: Q_c(δ_c, α_c), ∂Q/∂α = −(∂G/∂α) dQ/dδ, so dQ/dp = dQ/dδ n + ∂Q/∂α e/d
            Qa = -st.f_Ga * dQ
            Mg_m = Mg_m + Mg_Q * Qa
            W_m[:, :Z] += W_Q * Qa[:, :Z]
        idd = self.ONE2 / d
        ea, ner = cs * idd, sn * idd                                 # e/d = (ea, −ner), e = (cos α, −sin α)
        MgQ = Mg_Q * dQ
        mA = Mg_m * ea
        mA += MgQ * sn                                               # dM_g/dp_c (axial)
        mR = MgQ * cs
        mR -= Mg_m * ner                                             # (radial)
        bA = W_m * ea                                                # dω_cage/dp_c
        bR = W_m * ner
        np.negative(bR, out=bR)
        WQ = W_Q * dQ[:, :Z]
        bA[:, :Z] += WQ * sn[:, :Z]
        bR[:, :Z] += WQ * cs[:, :Z]
        # contact stiffness d(Q n + T e)/dp = dQ n nᵀ + (Q e − T n) eᵀ / d (+ film: n (∂Q/∂α) eᵀ / d)
        ta = Q * cs
        tr = Q * sn
        np.negative(tr, out=tr)
        if self.has_lam:
            T = self._pair(st.Mg, st.Mg) * self.LAMD
            ta -= T * sn
            tr -= T * cs
        if self.film is not None:
            ta += Qa * sn
            tr += Qa * cs
        dQs, dQc = dQ * sn, dQ * cs
        Gaa = dQs * sn
        Gaa += ta * ea
        Gar = dQs * cs
        Gar -= ta * ner
        Gra = dQc * sn
        Gra += tr * ea
        Grr = dQc * cs
        Grr -= tr * ner
        # as seen by the ball (inner +, outer −), with the friction's share ∂r_b/∂M_g dM_g/dp_c
        H = [Gaa * self.PM, Gar * self.PM, Gra * self.PM, Grr * self.PM]
        if self.has_lam:
            LPcs, LPsn = self.LP * cs, self.LP * sn
            vA = LPcs[:, :Z] + LPcs[:, Z:]
            vR = LPsn[:, :Z] + LPsn[:, Z:]
            np.negative(vR, out=vR)
            vA2, vR2 = self._pair(vA, vA), self._pair(vR, vR)
            H[0] += vA2 * mA
            H[1] += vA2 * mR
            H[2] += vR2 * mA
            H[3] += vR2 * mR
        As = self.AsZ
        B = np.empty((nb, 4, Z))
        for e in range(4):
            np.subtract(H[e][:, Z:], H[e][:, :Z], out=B[:, e])
        B *= As[:, None]
        ng, rows_k = self.ng, self.rows_k
        C = np.empty((nb, 2, ng + 2, Z))
        for row in range(2):
            h = (H[2 * row][:, :Z] * As, H[2 * row + 1][:, :Z] * As)
            C[:, row, 0] = h[0]
            for k, ck, wk in rows_k:
                np.multiply(h[ck], wk, out=C[:, row, k])
        wrs = self.wrsZ
        FcW = st.WZ * (2.0 * self.mdm2)
        if self.has_lam:
            np.multiply(vA * Mg_W, wrs, out=C[:, 0, ng])
            np.multiply(vR * Mg_W + FcW, wrs, out=C[:, 1, ng])
        else:
            C[:, 0, ng] = 0.0
            np.multiply(FcW, wrs, out=C[:, 1, ng])
        C[:, 0, ng + 1] = st.res[:, ng:ng + Z]
        C[:, 1, ng + 1] = st.res[:, ng + Z:]
        # ring rows: d r_g/dp_i = L = W_tᵀ G_i + u m_iᵀ per ball, u = W_tᵀ (λ_i/D) e_i − (λ_i f_i/ℜ) w (tilt
        # rows), W_tᵀ the levers (row k: w_k in component comp_k); by X (p_i = A_c − X, p_o = X through M_g):
        # u m_oᵀ − L
        P = np.empty((nb, 2 * ng + 2, Z))             # L rows (F_a, F_r, M/ℜ[, F_z, M_y/ℜ]) × (axial, radial), b_i
        G = ((Gaa[:, :Z], Gar[:, :Z]), (Gra[:, :Z], Grr[:, :Z]))
        P[:, 0], P[:, 1] = G[0]
        for k, ck, wk in rows_k:
            np.multiply(G[ck][0], wk, out=P[:, 2 * k])
            np.multiply(G[ck][1], wk, out=P[:, 2 * k + 1])
        P[:, 2 * ng], P[:, 2 * ng + 1] = bA[:, :Z], bR[:, :Z]
        Rr = np.empty((nb, 2, ng + 1, Z))
        if self.lam_i:
            li = self.LAMD[0, 0]
            u = [li * cs[:, :Z]] + [li * cs[:, :Z] * wk if ck == 0 else li * -sn[:, :Z] * wk for _, ck, wk in rows_k]
            for k, mom in self.mom:
                u[k] = u[k] - mom
            for m in range(ng):
                P[:, 2 * m] += u[m] * mA[:, :Z]
                P[:, 2 * m + 1] += u[m] * mR[:, :Z]
                np.multiply(u[m] * mA[:, Z:] - P[:, 2 * m], As, out=Rr[:, 0, m])
                np.multiply(u[m] * mR[:, Z:] - P[:, 2 * m + 1], As, out=Rr[:, 1, m])
            S_W = np.stack([(um * Mg_W).sum(1) for um in u], axis=1) * (self.w_ref / self.scale)[:, None]
        else:
            np.multiply(P[:, :2 * ng].reshape(nb, ng, 2, Z).transpose(0, 2, 1, 3), -As[:, None, None],
                        out=Rr[:, :, :ng])
            S_W = 0.0
        np.multiply(bA[:, :Z] - bA[:, Z:], self.AwZ, out=Rr[:, 0, ng])
        np.multiply(bR[:, :Z] - bR[:, Z:], self.AwZ, out=Rr[:, 1, ng])
        # global block: Σ_j L W_t, and the cage row −Σ b_i W_t A/ω_ref
        sums = P.reshape(nb, (2 * ng + 2) * Z) @ self.Msum         # (nb, ndof² + ndof)
        n2 = ng * ng
        S = np.empty((nb, ng + 1, ng + 1))
        np.multiply(sums[:, :n2].reshape(nb, ng, ng), self.As[:, :, None], out=S[:, :ng, :ng])
        S[:, :ng, ng] = S_W
        np.multiply(sums[:, n2:], -self.Aw, out=S[:, ng, :ng])
        S[:, ng, ng] = 1.0
        return B, C, Rr, S

    # ------------------------------------------------------------------ safeguards and path
    def limit(self, st, dz):
        r"""Shorten the step of a ball that would close an open contact.

        An open contact has no stiffness in the linear model, so Newton moves a ball with one open
        contact as if the race were not there; near a wedge (a ball outside the load zone held between
        both races with loads ~F_c) the step then buries the ball deep in that race.  The ball's step is
        shortened so that the predicted approach of an open contact, δ + n·(ΔA − ΔX) (inner) or δ + n·ΔX
        (outer), reaches at most δ_η = (F/K)^(2/3), the approach that carries the ball's force scale
        F = max(F_c, |r_b|) — the next step then sees the contact."""
        if st.allpos:
            return dz
        nb, Z, A, ng = dz.shape[0], self.Z, self.A, self.ng
        Z2, Z3 = 2 * Z, 3 * Z
        dV = np.empty((nb, 4 * Z))
        np.multiply(dz[:, ng:ng + Z], A, out=dV[:, Z:Z2])
        np.multiply(dz[:, ng + Z:], A, out=dV[:, Z3:])
        dAc = dz[:, :ng] @ self.L
        np.subtract(dAc[:, :Z], dV[:, Z:Z2], out=dV[:, :Z])
        np.subtract(dAc[:, Z:], dV[:, Z3:], out=dV[:, Z2:Z3])
        nd = st.n * dV
        dd = nd[:, :Z2] + nd[:, Z2:]                                         # predicted change of δ_c
        rb = np.abs(st.res[:, ng:])
        F = np.maximum(st.Fc, np.maximum(rb[:, :Z], rb[:, Z:]) * self.scale[:, None])
        d_eta = (self._pair(F, F) / self.K0) ** (2.0 / 3.0)
        over = (st.dl < 0) & (st.dl + dd > d_eta)
        if not over.any():
            return dz
        kap = np.where(over, (d_eta - st.dl) / np.where(over, dd, 1.0), 1.0)
        kap = np.minimum(kap[:, :Z], kap[:, Z:])
        dz = dz.copy()
        dz[:, ng:ng + Z] *= kap
        dz[:, ng + Z:] *= kap
        return dz

    def path(self, z, dz):
        """A step in polar form about the outer groove centre for each ball: radius ρ, angle α_o,
        dρ = n_o·dx, dα = e_o·dx/ρ (n_o = (sin α_o, cos α_o), e_o = (cos α_o, −sin α_o)); the rings linear."""
        Z, ng = self.Z, self.ng
        x1, x2, d1, d2 = z[:, ng:ng + Z], z[:, ng + Z:], dz[:, ng:ng + Z], dz[:, ng + Z:]
        r2 = x1 * x1
        r2 += x2 * x2
        rho = np.sqrt(r2)
        drho = x1 * d1
        drho += x2 * d2
        drho /= rho
        da = x2 * d1
        da -= x1 * d2
        da /= r2
        return z, dz, rho, np.arctan2(x1, x2), drho, da

    def move(self, path, lam):
        """The point at the fraction lam (nb,) of the step along the path: the ball centres at
        (ρ + λ dρ)(sin, cos)(α + λ dα) — to first order the Newton step itself; a ball resting on the outer
        race keeps its approach δ_o when it rolls along the race (a straight tangential step would push it
        into the race by ≈ step²/2ρ, far more than the δ_o of a lightly loaded ball).  ``lam=None``: the
        full step."""
        z, dz, rho, a, drho, da = path
        Z, ng = self.Z, self.ng
        out = np.empty(z.shape)
        if lam is None:
            np.add(z[:, :ng], dz[:, :ng], out=out[:, :ng])
            r, t = rho + drho, a + da
        else:
            lc = lam[:, None]
            np.add(z[:, :ng], lc * dz[:, :ng], out=out[:, :ng])
            r, t = rho + lc * drho, a + lc * da
        np.multiply(r, np.sin(t), out=out[:, ng:ng + Z])
        np.multiply(r, np.cos(t), out=out[:, ng + Z:])
        return out

    def relax(self, z, st, todo):
        """After a damped step: re-place stalled light balls (:func:`thermobear.loads.highspeed_start.relax`)."""
        if self.per_ball or self.film is not None:
            return z, st
        return _relax(self, z, st, todo)
