r"""Starting ball positions of the high-speed solve and the re-placing of stalled light balls.

A ball in the high-speed form carries its centrifugal force and a gyroscopic friction besides its
contact loads (:mod:`thermobear.loads.highspeed`).  Newton's method needs the balls near their
equilibrium: a ball outside the load zone has open contacts (no stiffness in the linear model) and a
step from the static positions throws it through its groove.  This module places the balls with the
rings held: the loaded ones pushed out by their centrifugal force (Jones 1960 [1], Harris 2001 [2]
§8.2 start), the light ones at the minimum of their potential energy (:func:`place`).

All functions take the problem ``pb`` and states of :mod:`thermobear.loads.highspeed_model`; unknowns
z (nb, ndof + 2Z) as there (ndof = ``pb.ng`` ring unknowns).

References
----------
.. [1] Jones, A. B. (1960). *J. Basic Eng.* 82(2):309–320.
.. [2] Harris, T. A. (2001). *Rolling Bearing Analysis*, 4th ed., Wiley, ch. 8.
"""
from __future__ import annotations

import numpy as np

__all__ = ["static_start", "start", "place", "relax"]

_BALL_CAP = 0.05        # largest move of a ball centre per step of the per-ball start, in units of A
_BALL_MAXIT = 40        # Newton steps of the per-ball start
_BALL_HALVINGS = 12     # line-search halvings of the per-ball start
_RELAX = 1e-2           # a light ball is re-placed when its residual exceeds this share of its F_c + friction
_BALL_TOL = 1e-4        # re-placing a stalled ball: force residual relative to the ball's external force
_START_TOL = 0.3        # the start places a ball to this share of its external force (Newton does the rest)


def static_start(pb, g):
    """Unknowns z (nb, ndof + 2Z) with the rings at g (nb, ndof) and the balls of the static solution: on the
    line of groove centres, the approach A_j − A split between the contacts so that K_i δi^1.5 = K_o δo^1.5
    (equal split for an open contact, where the regularising stiffness is the same on both sides)."""
    nb, Z, ng = g.shape[0], pb.Z, pb.ng
    Ac = pb.centres(g)
    A1, A2 = Ac[:, :Z], Ac[:, Z:]
    Aj = np.sqrt(A1 * A1 + A2 * A2)
    s = Aj - pb.A
    Ki, Ko = pb.Ki0, pb.Ko0
    if pb.per_ball:
        al = np.arctan2(A1, A2)
        Ki, Ko = pb.brg.K_i(al), pb.brg.K_o(al)
    share_o = np.where(s > 0, Ki ** (2.0 / 3.0) / (Ki ** (2.0 / 3.0) + Ko ** (2.0 / 3.0)), 0.5)
    r = (pb.c0[0, Z] + share_o * s) / Aj / pb.A
    z = np.empty((nb, ng + 2 * Z))
    z[:, :ng] = g
    np.multiply(A1, r, out=z[:, ng:ng + Z])
    np.multiply(A2, r, out=z[:, ng + Z:])
    return z


def _external(pb, st):
    """The force on each ball besides its contact loads (centrifugal force and gyroscopic friction) at the
    state ``st``: (f1, f2) axial, radial (nb, Z) [N], r_b·scale − (Q_i n_i − Q_o n_o)."""
    Z = pb.Z
    rb = st.res[:, pb.ng:] * pb.scale[:, None]
    F = np.concatenate((st.Q, st.Q), axis=1) * st.n                 # [Q sin α | Q cos α] of both contacts
    return rb[:, :Z] - (F[:, :Z] - F[:, Z:2 * Z]), rb[:, Z:] - (F[:, 2 * Z:3 * Z] - F[:, 3 * Z:])


def start(pb, z):
    r"""Starting ball positions at speed, the rings held at the static solution in ``z``.

    With the kinematics of the static positions each ball carries a centrifugal force and a
    gyroscopic friction, frozen here as one external force f (F_c r̂ included).

    * A ball whose static load exceeds |f| is pushed out: its outer contact takes the static
      inner-contact force plus F_c r̂ (Jones's usual start).
    * A lighter ball, or one outside the load zone, is placed where it is in equilibrium under f
      with the rings held: the minimum of its convex potential energy

          U(X) = ⅖ K_i δ_i₊^2.5 + ⅖ K_o δ_o₊^2.5 − f·X,
          δ_i = |O_i − X| − (f_i − ½)D,  δ_o = |X| − (f_o − ½)D,

      (−∇U = Q_i n_i − Q_o n_o + f is its force residual, the Hessian the sum of the contact
      stiffness matrices), by Newton's method with a step cap and an Armijo line search on U,
      on all such balls at once (:func:`place`).  A ball with both contacts open moves along f until
      it touches a race and ends on the outer race or wedged between both races with loads of the
      order of its centrifugal force — not, as a push by F_c alone would put it, deep in the axially
      offset inner groove with kN contact loads.

    Only a start: the shared Newton then solves the coupled problem.  Returns the unknowns z."""
    st = pb.evaluate(z)
    nb, Z, A = z.shape[0], pb.Z, pb.A
    f1, f2 = _external(pb, st)
    fn = np.hypot(f1, f2)
    Ki, Ko = pb.Ki0, pb.Ko0
    if pb.per_ball:
        Z2 = 2 * Z
        al = np.arctan2(st.V[:, :Z2], st.V[:, Z2:])
        Ki, Ko = pb.brg.K_i(al[:, :Z]), pb.brg.K_o(al[:, Z:])
    # loaded balls: pushed out
    Qs = np.maximum(st.Qi, 0.0)
    g1, g2 = Qs * st.n[:, :Z], Qs * st.n[:, 2 * Z:3 * Z] + st.Fc
    Qo = np.hypot(g1, g2)
    r_o = (pb.c0[0, Z] + (Qo / Ko) ** (2.0 / 3.0)) / np.where(Qo > 0, Qo, 1.0)
    X1 = np.where(st.Fc > 0, r_o * g1, st.X1)
    X2 = np.where(st.Fc > 0, r_o * g2, st.X2)
    # light and unloaded balls: placed (flattened over the batch)
    k = np.flatnonzero((Qs <= fn) & (fn > 0))
    if k.size:
        Ac = pb.centres(z[:, :pb.ng])
        X1, X2 = X1.ravel(), X2.ravel()
        ki = Ki if np.ndim(Ki) == 0 else Ki.ravel()[k]
        ko = Ko if np.ndim(Ko) == 0 else Ko.ravel()[k]
        mu = (1e-9 / A) * np.repeat(pb.scale, Z)[k]                 # keeps a free ball's Hessian invertible
        X1[k], X2[k] = place(st.X1.ravel()[k], st.X2.ravel()[k], Ac[:, :Z].ravel()[k], Ac[:, Z:].ravel()[k],
                             f1.ravel()[k], f2.ravel()[k], ki, ko, mu, _START_TOL * fn.ravel()[k],
                             pb.c0[0, 0], pb.c0[0, Z], _BALL_CAP * A)
    out = z.copy()
    out[:, pb.ng:pb.ng + Z] = X1.reshape(nb, Z) / A
    out[:, pb.ng + Z:] = X2.reshape(nb, Z) / A
    return out


def place(x1, x2, a1, a2, f1, f2, Ki, Ko, mu, tol, ci0, co0, cap):
    """Newton minimisation of each ball's potential energy (see :func:`start`) on flat arrays of balls
    (centre x, inner groove centre a, external force f, stiffnesses, regularisation mu, force tolerance);
    a ball leaves the active set when its force residual is below ``tol`` or its line search fails (a
    start needs no more).  Returns the ball centres X1, X2 [m]."""
    x1, x2 = x1.copy(), x2.copy()
    act = np.arange(x1.size)
    fabs = np.hypot(f1, f2)
    per_ball = np.ndim(Ki) != 0

    def sub(v, m):
        return v[m] if per_ball else v

    for _ in range(_BALL_MAXIT):
        X1, X2, A1, A2, h1, h2 = x1[act], x2[act], a1[act], a2[act], f1[act], f2[act]
        ki, ko, fa = sub(Ki, act), sub(Ko, act), fabs[act]
        p, q = A1 - X1, A2 - X2
        d_i, d_o = np.hypot(p, q), np.hypot(X1, X2)
        di, do = np.maximum(d_i - ci0, 0.0), np.maximum(d_o - co0, 0.0)
        sqi, sqo = np.sqrt(di), np.sqrt(do)
        Qi, Qo = ki * di * sqi, ko * do * sqo
        si, ci, so, co = p / d_i, q / d_i, X1 / d_o, X2 / d_o
        r1 = Qi * si - Qo * so + h1
        r2 = Qi * ci - Qo * co + h2
        go = np.hypot(r1, r2) > tol[act]
        if not go.any():
            break
        if not go.all():
            act = act[go]
            X1, X2, A1, A2, h1, h2, r1, r2 = X1[go], X2[go], A1[go], A2[go], h1[go], h2[go], r1[go], r2[go]
            Qi, Qo, d_i, d_o, si, ci, so, co = Qi[go], Qo[go], d_i[go], d_o[go], si[go], ci[go], so[go], co[go]
            di, do, sqi, sqo, ki, ko, fa = di[go], do[go], sqi[go], sqo[go], sub(ki, go), sub(ko, go), fa[go]
        # Hessian of U: dQ n nᵀ + (Q/d) e eᵀ per contact, e = (cos α, −sin α)
        ti, to = Qi / d_i, Qo / d_o
        kki, kko = 1.5 * ki * sqi, 1.5 * ko * sqo
        m = mu[act]
        h11 = kki * si * si + ti * ci * ci + kko * so * so + to * co * co + m
        h22 = kki * ci * ci + ti * si * si + kko * co * co + to * so * so + m
        h12 = (kki - ti) * si * ci + (kko - to) * so * co
        dt = h11 * h22 - h12 * h12
        d1, d2 = (h22 * r1 - h12 * r2) / dt, (h11 * r2 - h12 * r1) / dt
        c = np.minimum(1.0, cap / np.maximum(np.hypot(d1, d2), 1e-300))
        # an open contact closes to at most the approach that carries the ball's force |f|
        for gap, dd, K in ((d_i - ci0, -(si * d1 + ci * d2), ki), (d_o - co0, so * d1 + co * d2, ko)):
            shut = gap < 0
            if not shut.any():
                continue
            eta = (fa / K) ** (2.0 / 3.0)
            over = shut & (gap + c * dd > eta)
            if over.any():
                c = np.where(over, (eta - gap) / np.where(over, dd, 1.0), c)
        d1, d2 = d1 * c, d2 * c
        slope = r1 * d1 + r2 * d2                                   # −∇U·dX > 0
        U0 = 0.4 * (ki * di * di * sqi + ko * do * do * sqo)
        lam = np.ones(X1.shape)
        acc = np.zeros(X1.shape, bool)
        for _ in range(_BALL_HALVINGS):
            t1, t2 = X1 + lam * d1, X2 + lam * d2
            ui = np.maximum(np.hypot(A1 - t1, A2 - t2) - ci0, 0.0)
            uo = np.maximum(np.hypot(t1, t2) - co0, 0.0)
            dU = 0.4 * (ki * ui * ui * np.sqrt(ui) + ko * uo * uo * np.sqrt(uo)) - U0 - lam * (h1 * d1 + h2 * d2)
            acc |= dU <= -1e-4 * lam * slope
            if acc.all():
                break
            lam = np.where(acc, lam, 0.5 * lam)
        if acc.all():
            x1[act], x2[act] = X1 + lam * d1, X2 + lam * d2
            continue
        x1[act] = np.where(acc, X1 + lam * d1, X1)
        x2[act] = np.where(acc, X2 + lam * d2, X2)
        act = act[acc]
        if not act.size:
            break
    return x1, x2


def relax(pb, z, st, todo):
    r"""Re-place the light balls whose force residual is large against their own loads.

    A ball outside the load zone carries loads ~F_c, tiny against the ring loads; near the
    transitions between resting on the outer race, wedging between both races and (at n → 0)
    floating, the Newton model of its contacts is poor, and the line search on the largest
    residual of the case then stalls on that one ball.  Such a ball (static-type load Q_i ≤ |f|,
    residual > 1 % of |f|, among the largest residuals of its case; f its centrifugal force plus
    gyroscopic friction at the iterate, frozen) is placed again by :func:`place` with the rings
    held; the case keeps the new positions if its residual falls.  Near the solution no ball
    qualifies, so the quadratic convergence of Newton is untouched.  Returns (z, st)."""
    Z, A, ng = pb.Z, pb.A, pb.ng
    s = pb.scale[:, None]
    ar = np.abs(st.res[:, ng:])
    rb = np.maximum(ar[:, :Z], ar[:, Z:])
    f1, f2 = _external(pb, st)
    fn = np.hypot(f1, f2)
    light = ((np.maximum(st.Qi, 0.0) <= fn) & (rb * s > _RELAX * fn) & (rb >= 0.1 * st.norm[:, None])
             & (fn > 0) & todo[:, None])
    if not light.any():
        return z, st
    k = np.flatnonzero(light)
    Ac = pb.centres(z[:, :ng])
    X1, X2 = place(st.X1.ravel()[k], st.X2.ravel()[k], Ac[:, :Z].ravel()[k], Ac[:, Z:].ravel()[k],
                   f1.ravel()[k], f2.ravel()[k], pb.Ki0, pb.Ko0, (1e-9 / A) * np.repeat(pb.scale, Z)[k],
                   _BALL_TOL * fn.ravel()[k], pb.c0[0, 0], pb.c0[0, Z], _BALL_CAP * A)
    zn = z.copy()
    i, j = np.divmod(k, Z)
    zn[i, ng + j], zn[i, ng + Z + j] = X1 / A, X2 / A
    cases = np.flatnonzero(light.any(axis=1))
    st2 = pb.rows(cases).evaluate(zn[cases])
    better = st2.norm < st.norm[cases]
    if not better.any():
        return z, st
    idx = cases[better]
    z = z.copy()
    z[idx] = zn[idx]
    st.put(idx, st2.take(np.flatnonzero(better)))
    return z, st
