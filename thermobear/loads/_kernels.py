"""Compiled kernels of the ball equilibria (optional: numba).

The Newton iterations of :mod:`thermobear.loads.static` (low speed) and :mod:`thermobear.loads.highspeed`
evaluate, at every iterate, the forces, kinematics and residuals of every ball and an exact
Newton step.  Written with numpy, one load case is a few hundred calls on Z-element arrays: their
call overhead, not the arithmetic, sets the cost (≈ 0.3 ms per high-speed Newton step).  This
module holds the same computations written ball by ball and case by case, compiled with numba
when it is installed (``pip install thermobear[fast]``):

* :func:`state_kernel`, :func:`step_kernel` — the high-speed state and exact Newton step
  (:meth:`thermobear.loads.highspeed._Problem.state`, ``newton_step``);
* :func:`place_kernel` — the per-ball start of the high-speed solve (``_place``);
* :func:`static_kernel` — the damped Newton of :func:`thermobear.loads.load_distribution`;
* :func:`axial_angle_kernel` — :func:`thermobear.loads.axial_contact_angle`.

The numpy code stays the reference and serves every case these kernels do not cover (the film
contact law; per-ball stiffness, except in the per-ball start, whose kernel takes one stiffness per
ball).  The kernels transcribe it line for line — same equations, same
iteration logic (line searches, caps, stopping rules) — so the two agree to rounding:
tests/test_kernels.py compares every state field, the Newton steps and whole solutions, and CI
runs the load-distribution tests on both paths.  The equations and their references are in the
docstrings of the numpy functions.

``THERMOBEAR_NUMBA=0`` in the environment turns the kernels off (numpy only); :data:`ENABLED`
says whether they are in use.
"""
from __future__ import annotations

import math
import os

import numpy as np

try:                                    # optional dependency
    if os.environ.get("THERMOBEAR_NUMBA", "1").strip().lower() in ("0", "false", "no", "off"):
        raise ImportError("disabled by THERMOBEAR_NUMBA")
    from numba import njit
    ENABLED = True
except ImportError:
    ENABLED = False

    def njit(*args, **kwargs):          # plain Python functions, never called (ENABLED is False)
        if args and callable(args[0]):
            return args[0]
        return lambda f: f



def _jit(f):
    """numba's njit with IEEE float semantics (a division by zero gives inf/NaN as in numpy, no
    exception) and an on-disk cache.  Where numba finds no writable cache location (package folder
    and user cache both read-only) it refuses ``cache=True`` when decorating: the kernels are then
    compiled in memory, once per process (≈ 5 s)."""
    try:
        return njit(cache=True, error_model="numpy")(f)
    except RuntimeError:
        return njit(cache=False, error_model="numpy")(f)


__all__ = ["ENABLED", "N_BALL_FIELDS", "BALL_FIELDS", "state_kernel", "step_kernel", "place_kernel", "static_kernel",
           "axial_angle_kernel"]

#: per-ball fields of the state, in the order of the kernel's output array (nb, n_fields, Z)
BALL_FIELDS = ("X1", "X2", "p", "q", "d_i", "d_o", "si", "ci", "so", "co", "dl_i", "dl_o",
               "Qi", "Qo", "dQi", "dQo", "rb2", "cb", "sb", "seo", "sei", "Ro", "Ri", "Eo", "Ei",
               "det", "w_own", "wR_own", "wgt", "den", "wR", "Mg", "Fi1", "Fi2", "Fo1", "Fo2")
N_BALL_FIELDS = len(BALL_FIELDS)
(_X1, _X2, _P, _Q, _DI, _DO, _SI, _CI, _SO, _CO, _DLI, _DLO, _QI, _QO, _DQI, _DQO, _RB2, _CB, _SB,
 _SEO, _SEI, _RO, _RI, _EO, _EI, _DET, _WOWN, _WROWN, _WGT, _DEN, _WR, _MG, _FI1, _FI2, _FO1,
 _FO2) = range(N_BALL_FIELDS)


@_jit
def state_kernel(x, g, c, omega, scale, F_app, A, A2_0, ci0, co0, Ki, Ko, k_eps, gp, dm, D, m, J,
                 lam_i, lam_o, fi, R, outer, out, case_out, r_b, r_g):  # pragma: no cover (compiled)
    """State of every ball of every case (dry Hertz contacts, one stiffness per race).

    x (nb, Z, 2) and g (nb, 3) the scaled unknowns; c (Z,) cos ψ; omega, scale (nb,); F_app (nb, 3);
    ``outer`` True for outer-race kinematic control.  Writes ``out`` (nb, N_BALL_FIELDS, Z),
    ``case_out`` (nb, 3): Σ Q_i, ω_cage, F_c; ``r_b`` (nb, Z, 2), ``r_g`` (nb, 3).
    """
    nb, Z = x.shape[0], x.shape[1]
    hdm, hD = 0.5 * dm, 0.5 * D
    for b in range(nb):
        w = omega[b]
        g0, g1, g2 = g[b, 0], g[b, 1], g[b, 2]
        qs = 0.0
        for j in range(Z):
            A1 = A * (g0 + g2 * c[j])
            A2 = A2_0 + (A * g1) * c[j]
            X1 = A * x[b, j, 0]
            X2 = A * x[b, j, 1]
            p = A1 - X1
            q = A2 - X2
            d_i = math.hypot(p, q)
            d_o = math.hypot(X1, X2)
            si, ci, so, co = p / d_i, q / d_i, X1 / d_o, X2 / d_o
            dl_i, dl_o = d_i - ci0, d_o - co0
            if dl_i > 0:
                sq = math.sqrt(dl_i)
                Qi, dQi = Ki * dl_i * sq, 1.5 * Ki * sq
            else:
                Qi, dQi = k_eps * dl_i, k_eps
            if dl_o > 0:
                sq = math.sqrt(dl_o)
                Qo, dQo = Ko * dl_o * sq, 1.5 * Ko * sq
            else:
                Qo, dQo = k_eps * dl_o, k_eps
            if outer:
                rb2 = 1.0 + 2.0 * gp * co + gp * gp
                rb = math.sqrt(rb2)
                cb, sb = (co + gp) / rb, -so / rb
                ceo, seo = (1.0 + gp * co) / rb, gp * so / rb
                cei, sei = ci * cb - si * sb, si * cb + ci * sb
            else:
                rb2 = 1.0 - 2.0 * gp * ci + gp * gp
                rb = math.sqrt(rb2)
                cb, sb = (ci - gp) / rb, -si / rb
                cei, sei = (1.0 - gp * ci) / rb, -gp * si / rb
                ceo, seo = co * cb - so * sb, so * cb + co * sb
            Ro, Ri = hdm * (1.0 + gp * co), hdm * (1.0 - gp * ci)
            Eo, Ei = hD * ceo, hD * cei
            det = Ro * Ei + Ri * Eo
            o = out[b, :, j]
            o[_X1], o[_X2], o[_P], o[_Q], o[_DI], o[_DO] = X1, X2, p, q, d_i, d_o
            o[_SI], o[_CI], o[_SO], o[_CO], o[_DLI], o[_DLO] = si, ci, so, co, dl_i, dl_o
            o[_QI], o[_QO], o[_DQI], o[_DQO] = Qi, Qo, dQi, dQo
            o[_RB2], o[_CB], o[_SB], o[_SEO], o[_SEI] = rb2, cb, sb, seo, sei
            o[_RO], o[_RI], o[_EO], o[_EI], o[_DET] = Ro, Ri, Eo, Ei, det
            o[_WOWN] = w * Ri * Eo / det
            o[_WROWN] = -w * Ro * Ri / det
            qs += max(Qi, 0.0)
        # one cage: ω_cage = Σ Q_i ω_c,j / Σ Q_i
        W = 0.0
        for j in range(Z):
            o = out[b, :, j]
            wgt = max(o[_QI], 0.0) / qs if qs > 0 else 1.0 / Z
            o[_WGT] = wgt
            W += wgt * o[_WOWN]
        Fc = 0.5 * m * dm * W * W
        s = scale[b]
        sf1 = sf2 = sfx = 0.0
        for j in range(Z):
            o = out[b, :, j]
            Qi, Qo = o[_QI], o[_QO]
            qi, qo = max(Qi, 0.0), max(Qo, 0.0)
            Ro, Ri, Eo, Ei = o[_RO], o[_RI], o[_EO], o[_EI]
            den = qo * Eo * Eo + qi * Ei * Ei
            if den > 0:
                wR = -(qo * Eo * Ro * W + qi * Ei * Ri * (w - W)) / den
            else:
                wR = o[_WROWN]
            Mg = J * wR * W * o[_SB]
            si, ci, so, co = o[_SI], o[_CI], o[_SO], o[_CO]
            if lam_i != 0.0:
                Ti = lam_i / D * Mg
                Fi1, Fi2 = Qi * si + Ti * ci, Qi * ci - Ti * si
            else:
                Fi1, Fi2 = Qi * si, Qi * ci
            if lam_o != 0.0:
                To = lam_o / D * Mg
                Fo1, Fo2 = Qo * so + To * co, Qo * co - To * so
            else:
                Fo1, Fo2 = Qo * so, Qo * co
            o[_DEN], o[_WR], o[_MG] = den, wR, Mg
            o[_FI1], o[_FI2], o[_FO1], o[_FO2] = Fi1, Fi2, Fo1, Fo2
            r_b[b, j, 0] = (Fi1 - Fo1) / s
            r_b[b, j, 1] = (Fi2 - Fo2 + Fc) / s
            Fx = Fi1 - (lam_i * fi / R) * Mg if lam_i != 0.0 else Fi1
            sf1 += Fi1
            sf2 += Fi2 * c[j]
            sfx += Fx * c[j]
        r_g[b, 0] = (sf1 - F_app[b, 0]) / s
        r_g[b, 1] = (sf2 - F_app[b, 1]) / s
        r_g[b, 2] = (sfx - F_app[b, 2]) / s
        case_out[b, 0], case_out[b, 1], case_out[b, 2] = qs, W, Fc


@_jit
def _solve4(S, r):  # pragma: no cover (compiled)
    """Solve the n×n system S y = r in place by Gaussian elimination with partial pivoting;
    False when a pivot is exactly zero (singular)."""
    n = S.shape[0]
    for k in range(n):
        piv, big = k, abs(S[k, k])
        for i in range(k + 1, n):
            if abs(S[i, k]) > big:
                piv, big = i, abs(S[i, k])
        if big == 0.0:
            return False
        if piv != k:
            for jj in range(n):
                S[k, jj], S[piv, jj] = S[piv, jj], S[k, jj]
            r[k], r[piv] = r[piv], r[k]
        for i in range(k + 1, n):
            f = S[i, k] / S[k, k]
            for jj in range(k, n):
                S[i, jj] -= f * S[k, jj]
            r[i] -= f * r[k]
    for k in range(n - 1, -1, -1):
        acc = r[k]
        for jj in range(k + 1, n):
            acc -= S[k, jj] * r[jj]
        r[k] = acc / S[k, k]
    return True


@_jit
def step_kernel(out, case_out, r_b, r_g, c, omega, w_ref, scale, act, A, gp, dm, D, m, J, lam_i, lam_o,
                fi, R, outer, dx, dg):  # pragma: no cover (compiled)
    """Exact Newton step of every case from its state (the outputs of :func:`state_kernel`).

    Per-ball 2×2 blocks eliminated in closed form (Schur complement), a 4×4 system per case in the
    ring globals and the cage speed; ``act`` (nb, 4) is 1 for a free global, 0 for a held one.
    Writes ``dx`` (nb, Z, 2) and ``dg`` (nb, 3)."""
    nb, Z = out.shape[0], out.shape[2]
    hdm, hD = 0.5 * dm, 0.5 * D
    S = np.empty((4, 4))
    rhs = np.empty(4)
    YB = np.empty((Z, 2, 5))
    Jgb = np.empty((Z, 4, 2))
    for b in range(nb):
        w = omega[b]
        qs, W = case_out[b, 0], case_out[b, 1]
        s = scale[b]
        As = A / s
        wrs = w_ref[b] / s
        Aw = A / w_ref[b]
        wmW = w - W
        JW = J * W
        Fc_W = m * dm * W
        for ii in range(4):
            for jj in range(4):
                S[ii, jj] = 0.0
        sb3 = np.zeros(3)            # Σ_j bi Wt (the cage row)
        for j in range(Z):
            o = out[b, :, j]
            cj = c[j]
            si, ci, so, co = o[_SI], o[_CI], o[_SO], o[_CO]
            Qi, Qo, dQi, dQo = o[_QI], o[_QO], o[_DQI], o[_DQO]
            Ro, Ri, Eo, Ei, det = o[_RO], o[_RI], o[_EO], o[_EI], o[_DET]
            wR, sb, cb = o[_WR], o[_SB], o[_CB]
            if outer:
                b_o, b_i = -(1.0 + gp * co) / o[_RB2], 0.0
                Eo_o, Eo_i = -hD * o[_SEO] * (1.0 + b_o), 0.0
                Ei_i, Ei_o = -hD * o[_SEI], -hD * o[_SEI] * b_o
            else:
                b_i, b_o = -(1.0 - gp * ci) / o[_RB2], 0.0
                Ei_i, Ei_o = -hD * o[_SEI] * (1.0 + b_i), 0.0
                Eo_o, Eo_i = -hD * o[_SEO], -hD * o[_SEO] * b_i
            Ro_o, Ri_i = -hdm * gp * so, hdm * gp * si
            det_i = Ro * Ei_i + Ri_i * Eo + Ri * Eo_i
            det_o = Ro_o * Ei + Ro * Ei_o + Ri * Eo_o
            w_own = o[_WOWN]
            wo_i = (w * (Ri_i * Eo + Ri * Eo_i) - w_own * det_i) / det
            wo_o = (w * Ri * Eo_o - w_own * det_o) / det
            qi, qo = max(Qi, 0.0), max(Qo, 0.0)
            den = o[_DEN]
            JWsb = JW * sb
            if den > 0:
                wR_i = (-qo * W * Eo_i * Ro - qi * wmW * (Ei_i * Ri + Ei * Ri_i)
                        - 2.0 * wR * (qo * Eo * Eo_i + qi * Ei * Ei_i)) / den
                wR_o = (-qo * W * (Eo_o * Ro + Eo * Ro_o) - qi * wmW * Ei_o * Ri
                        - 2.0 * wR * (qo * Eo * Eo_o + qi * Ei * Ei_o)) / den
                Mg_W = J * sb * (wR + W * ((qi * Ei * Ri - qo * Eo * Ro) / den))
                Mg_Qi = JWsb * (-Ei * Ri * wmW - wR * Ei * Ei) / den if Qi > 0 else 0.0
                Mg_Qo = JWsb * (-Eo * Ro * W - wR * Eo * Eo) / den if Qo > 0 else 0.0
            else:
                wR_i = (-w * Ro * Ri_i - o[_WROWN] * det_i) / det
                wR_o = (-w * Ro_o * Ri - o[_WROWN] * det_o) / det
                Mg_W = J * sb * (wR + W * 0.0)
                Mg_Qi = 0.0
                Mg_Qo = 0.0
            Mg_i = JW * (wR_i * sb + wR * cb * b_i)
            Mg_o = JW * (wR_o * sb + wR * cb * b_o)
            W_Q = (w_own - W) / qs if (qs > 0 and Qi > 0) else 0.0
            wgt = o[_WGT]
            W_i, W_o = wgt * wo_i, wgt * wo_o
            # n = (sin α, cos α), e = (cos α, −sin α)
            n_i0, n_i1, n_o0, n_o1 = si, ci, so, co
            e_i0, e_i1, e_o0, e_o1 = ci, -si, co, -so
            d_i, d_o = o[_DI], o[_DO]
            gi0, gi1, go0, go1 = e_i0 / d_i, e_i1 / d_i, e_o0 / d_o, e_o1 / d_o
            a_i, a_o = Mg_Qi * dQi, Mg_Qo * dQo
            mi0, mi1 = Mg_i * gi0 + a_i * n_i0, Mg_i * gi1 + a_i * n_i1
            mo0, mo1 = Mg_o * go0 + a_o * n_o0, Mg_o * go1 + a_o * n_o1
            wq = W_Q * dQi
            bi0, bi1 = W_i * gi0 + wq * n_i0, W_i * gi1 + wq * n_i1
            bo0, bo1 = W_o * go0, W_o * go1
            Mg = o[_MG]
            if lam_i != 0.0:
                Ti = lam_i / D * Mg
                ti0, ti1 = Qi * e_i0 - Ti * n_i0, Qi * e_i1 - Ti * n_i1
            else:
                ti0, ti1 = Qi * e_i0, Qi * e_i1
            if lam_o != 0.0:
                To = lam_o / D * Mg
                to0, to1 = Qo * e_o0 - To * n_o0, Qo * e_o1 - To * n_o1
            else:
                to0, to1 = Qo * e_o0, Qo * e_o1
            # contact stiffness matrices d(Q n + T e)/dp = dQ n nᵀ + (Q e − T n) eᵀ / d
            tdi0, tdi1, tdo0, tdo1 = ti0 / d_i, ti1 / d_i, to0 / d_o, to1 / d_o
            Gi00 = dQi * n_i0 * n_i0 + tdi0 * e_i0
            Gi01 = dQi * n_i0 * n_i1 + tdi0 * e_i1
            Gi10 = dQi * n_i1 * n_i0 + tdi1 * e_i0
            Gi11 = dQi * n_i1 * n_i1 + tdi1 * e_i1
            Go00 = dQo * n_o0 * n_o0 + tdo0 * e_o0
            Go01 = dQo * n_o0 * n_o1 + tdo0 * e_o1
            Go10 = dQo * n_o1 * n_o0 + tdo1 * e_o0
            Go11 = dQo * n_o1 * n_o1 + tdo1 * e_o1
            v0 = (lam_i * e_i0 - lam_o * e_o0) / D                      # ∂r_b/∂M_g
            v1 = (lam_i * e_i1 - lam_o * e_o1) / D
            Hi00, Hi01 = Gi00 + v0 * mi0, Gi01 + v0 * mi1                # d r_b / dp
            Hi10, Hi11 = Gi10 + v1 * mi0, Gi11 + v1 * mi1
            Ho00, Ho01 = v0 * mo0 - Go00, v0 * mo1 - Go01                # d r_b / dX
            Ho10, Ho11 = v1 * mo0 - Go10, v1 * mo1 - Go11
            a = As * (Ho00 - Hi00)
            bb = As * (Ho01 - Hi01)
            cc = As * (Ho10 - Hi10)
            d = As * (Ho11 - Hi11)
            # right-hand sides [∂r_b/∂g (Hi Wt, Wt = [[1, 0, c], [0, c, 0]]), ∂r_b/∂ω_cage, r_b]
            J0 = (As * Hi00, As * (Hi01 * cj), As * (Hi00 * cj), v0 * Mg_W * wrs, r_b[b, j, 0])
            J1 = (As * Hi10, As * (Hi11 * cj), As * (Hi10 * cj), (v1 * Mg_W + Fc_W) * wrs, r_b[b, j, 1])
            # per-ball 2×2 inverse [[d, −b], [−c, a]] / det
            det2 = a * d - bb * cc
            big = max(max(abs(a), abs(bb)), max(abs(cc), abs(d)))
            tiny = 1e-14 * big
            if abs(det2) < tiny * tiny:            # ball exactly at the edge of contact
                a -= tiny
                d -= tiny
                det2 = a * d - bb * cc
            for k in range(5):
                YB[j, 0, k] = (d * J0[k] - bb * J1[k]) / det2
                YB[j, 1, k] = (-cc * J0[k] + a * J1[k]) / det2
            # ring rows: W Gi (W = Wtᵀ: rows [1, 0], [0, c], [c, 0])
            WG00, WG01 = Gi00, Gi01
            WG10, WG11 = cj * Gi10, cj * Gi11
            WG20, WG21 = cj * Gi00, cj * Gi01
            if lam_i != 0.0:
                li = lam_i / D
                u0, u1, u2 = li * e_i0, cj * (li * e_i1), cj * (li * e_i0)
                u2 -= lam_i * fi / R * cj
                L00, L01 = WG00 + u0 * mi0, WG01 + u0 * mi1
                L10, L11 = WG10 + u1 * mi0, WG11 + u1 * mi1
                L20, L21 = WG20 + u2 * mi0, WG21 + u2 * mi1
                Jgb[j, 0, 0], Jgb[j, 0, 1] = As * (u0 * mo0 - L00), As * (u0 * mo1 - L01)
                Jgb[j, 1, 0], Jgb[j, 1, 1] = As * (u1 * mo0 - L10), As * (u1 * mo1 - L11)
                Jgb[j, 2, 0], Jgb[j, 2, 1] = As * (u2 * mo0 - L20), As * (u2 * mo1 - L21)
                S[0, 3] += u0 * Mg_W
                S[1, 3] += u1 * Mg_W
                S[2, 3] += u2 * Mg_W
            else:
                L00, L01, L10, L11, L20, L21 = WG00, WG01, WG10, WG11, WG20, WG21
                Jgb[j, 0, 0], Jgb[j, 0, 1] = -As * WG00, -As * WG01
                Jgb[j, 1, 0], Jgb[j, 1, 1] = -As * WG10, -As * WG11
                Jgb[j, 2, 0], Jgb[j, 2, 1] = -As * WG20, -As * WG21
            Jgb[j, 3, 0], Jgb[j, 3, 1] = Aw * (bi0 - bo0), Aw * (bi1 - bo1)
            # Σ_j L Wt (3×3), Wt = [[1, 0, c], [0, c, 0]]
            S[0, 0] += L00
            S[0, 1] += L01 * cj
            S[0, 2] += L00 * cj
            S[1, 0] += L10
            S[1, 1] += L11 * cj
            S[1, 2] += L10 * cj
            S[2, 0] += L20
            S[2, 1] += L21 * cj
            S[2, 2] += L20 * cj
            sb3[0] += bi0
            sb3[1] += bi1 * cj
            sb3[2] += bi0 * cj
        for ii in range(3):
            for jj in range(3):
                S[ii, jj] *= As
            S[ii, 3] *= wrs
            S[3, ii] = -Aw * sb3[ii]
        S[3, 3] = 1.0
        # Schur complement: S −= Σ_j Jgb B⁻¹ Jbg, rhs = Σ_j Jgb B⁻¹ r_b
        for ii in range(4):
            t4 = 0.0
            for j in range(Z):
                t4 += Jgb[j, ii, 0] * YB[j, 0, 4] + Jgb[j, ii, 1] * YB[j, 1, 4]
            rhs[ii] = t4
            for k in range(4):
                t = 0.0
                for j in range(Z):
                    t += Jgb[j, ii, 0] * YB[j, 0, k] + Jgb[j, ii, 1] * YB[j, 1, k]
                S[ii, k] -= t
        for ii in range(3):
            rhs[ii] -= r_g[b, ii]
        for ii in range(4):
            rhs[ii] *= act[b, ii]
            for k in range(4):
                S[ii, k] *= act[b, ii] * act[b, k]
            S[ii, ii] += 1.0 - act[b, ii]
        S0 = S.copy()
        r0 = rhs.copy()
        if not _solve4(S, rhs):                    # a singular case: regularise it
            for ii in range(4):
                S0[ii, ii] += 1e-6
            if not _solve4(S0, r0):                # still singular: no step (NaN, rejected by the caller)
                r0[:] = math.nan
            rhs[:] = r0
        for k in range(3):
            dg[b, k] = rhs[k]
        for j in range(Z):
            for i2 in range(2):
                t = YB[j, i2, 4]
                for k in range(4):
                    t += YB[j, i2, k] * rhs[k]
                dx[b, j, i2] = -t


@_jit
def place_kernel(x1, x2, a1, a2, f1, f2, Ki, Ko, mu, tol, ci0, co0, cap, maxit, halvings):  # pragma: no cover
    """Per-ball Newton minimisation of the potential energy of :func:`thermobear.loads.highspeed._place`
    (same steps, step cap, closing limit and Armijo line search), ball by ball.  ``Ki``, ``Ko``
    [N/m^1.5] one per ball; updates ``x1``, ``x2`` [m] in place."""
    for k in range(x1.size):
        X1, X2, A1, A2, h1, h2 = x1[k], x2[k], a1[k], a2[k], f1[k], f2[k]
        ki, ko = Ki[k], Ko[k]
        fa = math.hypot(h1, h2)
        for _ in range(maxit):
            p, q = A1 - X1, A2 - X2
            d_i, d_o = math.hypot(p, q), math.hypot(X1, X2)
            di, do = max(d_i - ci0, 0.0), max(d_o - co0, 0.0)
            sqi, sqo = math.sqrt(di), math.sqrt(do)
            Qi, Qo = ki * di * sqi, ko * do * sqo
            si, ci, so, co = p / d_i, q / d_i, X1 / d_o, X2 / d_o
            r1 = Qi * si - Qo * so + h1
            r2 = Qi * ci - Qo * co + h2
            if not math.hypot(r1, r2) > tol[k]:
                break
            ti, to = Qi / d_i, Qo / d_o
            kki, kko = 1.5 * ki * sqi, 1.5 * ko * sqo
            m = mu[k]
            h11 = kki * si * si + ti * ci * ci + kko * so * so + to * co * co + m
            h22 = kki * ci * ci + ti * si * si + kko * co * co + to * so * so + m
            h12 = (kki - ti) * si * ci + (kko - to) * so * co
            dt = h11 * h22 - h12 * h12
            d1, d2 = (h22 * r1 - h12 * r2) / dt, (h11 * r2 - h12 * r1) / dt
            c = min(1.0, cap / max(math.hypot(d1, d2), 1e-300))
            gi, ddi = d_i - ci0, -(si * d1 + ci * d2)
            go, ddo = d_o - co0, so * d1 + co * d2
            if gi < 0:
                eta = (fa / ki) ** (2.0 / 3.0)
                if gi + c * ddi > eta:
                    c = (eta - gi) / ddi
            if go < 0:
                eta = (fa / ko) ** (2.0 / 3.0)
                if go + c * ddo > eta:
                    c = (eta - go) / ddo
            d1, d2 = d1 * c, d2 * c
            slope = r1 * d1 + r2 * d2
            U0 = 0.4 * (ki * di * di * sqi + ko * do * do * sqo)
            lam = 1.0
            acc = False
            for _h in range(halvings):
                t1, t2 = X1 + lam * d1, X2 + lam * d2
                ui = max(math.hypot(A1 - t1, A2 - t2) - ci0, 0.0)
                uo = max(math.hypot(t1, t2) - co0, 0.0)
                dU = 0.4 * (ki * ui * ui * math.sqrt(ui) + ko * uo * uo * math.sqrt(uo)) - U0 - lam * (h1 * d1 + h2 * d2)
                if dU <= -1e-4 * lam * slope:
                    acc = True
                    break
                lam = 0.5 * lam
            if not acc:
                break
            X1, X2 = X1 + lam * d1, X2 + lam * d2
        x1[k], x2[k] = X1, X2


@_jit
def _nanmax(a, b):  # pragma: no cover (compiled)
    """max(a, b) that keeps a NaN (as numpy's max does; Python's max drops one in its second argument)."""
    if a != a or b != b:
        return math.nan
    return a if a >= b else b


@_jit
def _static_rj(y0, y1, y2, c, A, sa0, ca0, Kn, F_app, s, res, J):  # pragma: no cover (compiled)
    """Residual res (3,) and Jacobian J (3, 3) of the low-speed equilibrium at scaled unknowns
    (y0, y1, y2) (:func:`thermobear.loads.load_distribution`'s ``residual_and_jac`` for one case)."""
    s0 = s1 = s2 = s3 = s4 = s5 = 0.0
    f0 = f1 = f2 = 0.0
    for j in range(c.size):
        cj = c[j]
        d1 = A * (y0 + y2 * cj)
        d2 = A * (y1 * cj)
        A1 = A * sa0 + d1
        A2 = A * ca0 + d2
        Aj = math.hypot(A1, A2)
        sp = max((2.0 * A * (sa0 * d1 + ca0 * d2) + d1 * d1 + d2 * d2) / (Aj + A), 0.0)
        sa, ca = A1 / Aj, A2 / Aj
        Q = Kn * sp ** 1.5
        dQ = 1.5 * Kn * math.sqrt(sp)
        Qa = Q / Aj if Aj > 0 else 0.0
        g11 = dQ * sa * sa + Qa * ca * ca
        g12 = (dQ * sa - Qa * sa) * ca
        g22 = dQ * ca * ca + Qa * sa * sa
        c2 = cj * cj
        s0 += g11
        s1 += g12 * cj
        s2 += g11 * cj
        s3 += g22 * c2
        s4 += g12 * c2
        s5 += g11 * c2
        f0 += Q * sa
        f1 += Q * ca * cj
        f2 += Q * sa * cj
    res[0], res[1], res[2] = (f0 - F_app[0]) / s, (f1 - F_app[1]) / s, (f2 - F_app[2]) / s
    k = A / s
    J[0, 0], J[0, 1], J[0, 2] = s0 * k, s1 * k, s2 * k
    J[1, 0], J[1, 1], J[1, 2] = s1 * k, s3 * k, s4 * k
    J[2, 0], J[2, 1], J[2, 2] = s2 * k, s4 * k, s5 * k


@_jit
def static_kernel(y, F_app, scale, zero, na, c, A, sa0, ca0, Kn, tol, maxiter, halvings, norm_out,
                  it_out):  # pragma: no cover (compiled)
    """Damped Newton of the low-speed load distribution, case by case (the iteration of
    :func:`thermobear.loads.load_distribution`: full step first, then halvings until the residual
    norm falls by the Armijo factor 1 − 10⁻⁴ λ, the smallest step taken when none does; a singular
    Jacobian regularised by 10⁻³ on its diagonal; stops at ``tol`` or at the floating-point floor).
    ``na`` = 2 (tilt held) or 3 active unknowns.  Updates y (nb, 3); writes the final residual norm
    and the Newton steps taken per case."""
    res = np.empty(3)
    J = np.empty((3, 3))
    rt = np.empty(3)
    Jt = np.empty((3, 3))
    M = np.empty((na, na))
    dy = np.empty(na)
    for b in range(y.shape[0]):
        if zero[b]:
            norm_out[b], it_out[b] = 0.0, 0
            continue
        s = scale[b]
        Fb = F_app[b]
        _static_rj(y[b, 0], y[b, 1], y[b, 2], c, A, sa0, ca0, Kn, Fb, s, res, J)
        norm = 0.0
        for i in range(na):
            norm = _nanmax(norm, abs(res[i]))
        floor = False
        it = 0
        for step in range(1, maxiter + 1):
            if not (norm > tol) or floor:
                break
            it = step
            prev = norm
            for i in range(na):
                dy[i] = -res[i]
                for k in range(na):
                    M[i, k] = J[i, k]
            det = M[0, 0] * M[1, 1] - M[0, 1] * M[1, 0] if na == 2 else (
                M[0, 0] * (M[1, 1] * M[2, 2] - M[1, 2] * M[2, 1]) - M[0, 1] * (M[1, 0] * M[2, 2] - M[1, 2] * M[2, 0])
                + M[0, 2] * (M[1, 0] * M[2, 1] - M[1, 1] * M[2, 0]))
            if not abs(det) > 1e-300:          # no ball in contact: push towards contact
                for i in range(na):
                    M[i, i] += 1e-3
            if not _solve4(M, dy):             # singular even regularised: the case fails (NaN norm)
                norm = math.nan
                break
            lam = 1.0
            t0, t1, t2 = y[b, 0], y[b, 1], y[b, 2]
            for _h in range(halvings):
                t0 = y[b, 0] + lam * dy[0]
                t1 = y[b, 1] + lam * dy[1]
                t2 = y[b, 2] + lam * dy[2] if na == 3 else y[b, 2]
                _static_rj(t0, t1, t2, c, A, sa0, ca0, Kn, Fb, s, rt, Jt)
                nt = 0.0
                for i in range(na):
                    nt = _nanmax(nt, abs(rt[i]))
                if nt < (1.0 - 1e-4 * lam) * norm:
                    break
                lam = 0.5 * lam
            else:                               # none accepted: the smallest step anyway
                t0 = y[b, 0] + lam * dy[0]
                t1 = y[b, 1] + lam * dy[1]
                t2 = y[b, 2] + lam * dy[2] if na == 3 else y[b, 2]
            y[b, 0], y[b, 1], y[b, 2] = t0, t1, t2
            _static_rj(t0, t1, t2, c, A, sa0, ca0, Kn, Fb, s, res, J)
            norm = 0.0
            for i in range(na):
                norm = _nanmax(norm, abs(res[i]))
            floor = floor or (norm <= 1e-9 and norm > 0.5 * prev)
        else:
            it = maxiter
        norm_out[b], it_out[b] = norm, it


@_jit
def axial_angle_kernel(target, a0, c0, tol, maxit, out):  # pragma: no cover (compiled)
    """Contact angle under pure axial load, element by element: the bracketed Newton iteration of
    :func:`thermobear.loads.axial_contact_angle` on sin α (cos α0 / cos α − 1)^1.5 = target."""
    hi0 = 0.5 * math.pi - 1e-9
    for k in range(target.size):
        tk = target[k]
        lo, hi = a0, hi0
        if a0 > 1e-6:
            al = math.acos(min(max(c0 / (1.0 + (tk / max(math.sin(a0), 1e-12)) ** (2 / 3)), -1.0), 1.0))
        else:
            al = math.acos(1.0 / (1.0 + math.sqrt(max(2.0 * tk, 0.0)) ** (2 / 3)))
        al = min(max(al, a0 + 1e-12), hi0)
        for _ in range(maxit):
            t = max(c0 / math.cos(al) - 1.0, 0.0)
            f = math.sin(al) * t ** 1.5 - tk
            if f < 0:
                lo = al
            if f > 0:
                hi = al
            dfd = math.cos(al) * t ** 1.5 + 1.5 * math.tan(al) ** 2 * math.sqrt(t) * c0
            new = al - (f / dfd if dfd > 0 else 0.0)
            if new <= lo or new >= hi or not math.isfinite(new):
                new = 0.5 * (lo + hi)
            done = abs(new - al) <= tol * max(1.0, abs(al))
            al = new
            if done:
                break
        out[k] = al
