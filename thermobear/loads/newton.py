r"""Damped Newton's method and continuation, batched over load cases.

One iteration for the three forms of the load distribution (:mod:`thermobear.loads.static`,
:mod:`thermobear.loads.highspeed`, :mod:`thermobear.loads.film`).  Each form keeps its physics —
unknowns, residual, Jacobian, start — in its own module and hands this module a *problem*:

``problem.evaluate(z)``
    the state at the unknowns ``z`` (nb, n) (one row per load case); ``state.norm`` (nb,) is the
    max-norm of the case's scaled residual, NaN where it is not finite.
``problem.direction(state)``
    the Newton direction dz (nb, n), J dz = −r (each form solves its own structure).
``problem.rows(idx)``
    the same problem for the cases ``idx`` (a subset of the batch);
    ``state.take(idx)`` and ``state.put(idx, other)`` read and write rows of a state.

and optionally ``problem.limit(state, dz)`` (a form's own safeguard on a step, e.g. an open contact
that would close too far), ``problem.path(z, dz)`` with ``problem.move(path, lam)`` (trial points
along a curved path; default z + λ dz), ``problem.refresh(z, state)`` (called before every step:
data the form freezes per step) and ``problem.relax(z, state, todo)`` (called after a damped step).

The iteration, per case (a case's iterates never depend on the other cases of the batch):

* stop when the residual is ≤ ``tol``, or, with ``polish`` > 0, after up to ``polish`` more steps
  towards ``tol · polish_factor`` (Newton converges quadratically: they cost little and settle
  ill-conditioned unknowns), or when the residual is below ``floor`` and no longer halves (the
  floating-point floor);
* the step is scaled so that no component moves more than ``step_cap``;
* backtracking line search: the largest λ ∈ {1, ½, ¼, …} (``halvings`` tries) whose residual
  satisfies n(λ) < (1 − 10⁻⁴ λ) n_ref (Armijo-type sufficient decrease on the max-norm), n_ref the
  largest of the last ``window`` residuals (non-monotone for ``window`` > 1: a step may raise the
  residual for a while, e.g. a lightly loaded ball changing between its contact states); a case
  that finds none takes the smallest step anyway (it leaves a flat region);
* a non-finite residual or step ends the case (not converged).

:func:`continuation` follows a path of parameters (a load factor, a speed, a viscosity), one
Newton solve per stage from the last solution, per case; it stops a case at its first failure.

References
----------
.. [1] Dennis, J. E. & Schnabel, R. B. (1996). *Numerical Methods for Unconstrained Optimization
   and Nonlinear Equations*, SIAM, §6.3 (backtracking line search, Armijo condition).
.. [2] Grippo, L., Lampariello, F. & Lucidi, S. (1986). A nonmonotone line search technique for
   Newton's method. *SIAM J. Numer. Anal.* 23(4):707–716.
.. [3] Allgower, E. L. & Georg, K. (2003). *Introduction to Numerical Continuation Methods*,
   SIAM (natural-parameter continuation, ch. 1).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["NewtonOptions", "NewtonResult", "newton", "ContinuationResult", "continuation", "RowState"]


class RowState:
    """A problem state whose arrays (named in ``FIELDS``) all have the load cases as leading axis: ``take`` and
    ``put`` read and write rows of them (the state protocol of :func:`newton`)."""

    FIELDS: tuple = ()

    def take(self, idx):
        new = type(self).__new__(type(self))
        for k in self.FIELDS:
            setattr(new, k, getattr(self, k)[idx])
        return new

    def put(self, idx, other):
        for k in self.FIELDS:
            getattr(self, k)[idx] = getattr(other, k)


@dataclass(frozen=True)
class NewtonOptions:
    """Stopping rules and safeguards of :func:`newton` (see the module docstring).

    Attributes
    ----------
    tol : float            residual (max-norm, scaled by the form) at which a case has converged [-]
    maxiter : int          Newton steps at most
    step_cap : float       largest move of any unknown per step (scaled units; ``inf``: none)
    window : int           residuals remembered by the non-monotone line search (1: monotone)
    polish : int           steps allowed after ``tol`` is met, towards ``tol · polish_factor``
    polish_factor : float  target of the polish steps, relative to ``tol``
    halvings : int         line-search trials per step (λ = 1, ½, … , 2^(1 − halvings))
    armijo : float         sufficient-decrease constant of the line search
    floor : float          residual below which a case that stops improving has converged
    """

    tol: float
    maxiter: int
    step_cap: float = np.inf
    window: int = 1
    polish: int = 0
    polish_factor: float = 1e-3
    halvings: int = 30
    armijo: float = 1e-4
    floor: float = 1e-9


@dataclass
class NewtonResult:
    """Outcome of :func:`newton`, per case.

    Attributes
    ----------
    z : ndarray (nb, n)         unknowns at the last iterate
    state : object              the problem's state at ``z``
    norm : ndarray (nb,)        residual at ``z`` (NaN: not finite)
    iterations : ndarray (nb,)  Newton steps taken by each case
    converged : ndarray (nb,)   residual ≤ tol, or ≤ floor and no longer improving
    """

    z: np.ndarray
    state: object
    norm: np.ndarray
    iterations: np.ndarray
    converged: np.ndarray


def _linear_move(path, lam):
    z, dz = path
    return z + dz if lam is None else z + lam[:, None] * dz


def _line_search(sub, z_new, dz, st_try, ref, path, move, opt):
    """Backtracking from the rejected full step ``z_new`` (state ``st_try``): the unknowns, the state and
    the step fraction λ each case took.  Only the cases still searching are evaluated again."""
    ok = st_try.norm < (1.0 - opt.armijo) * ref
    lam = np.where(ok, 1.0, 0.5)
    pend = np.flatnonzero(~ok)
    for _ in range(opt.halvings - 1):
        if not pend.size:
            break
        sp = sub.rows(pend)
        zt = move(_take_path(path, pend), lam[pend])
        st = sp.evaluate(zt)
        good = st.norm < (1.0 - opt.armijo * lam[pend]) * ref[pend]
        if good.any():
            k = pend[good]
            z_new[k] = zt[good]
            st_try.put(k, st.take(np.flatnonzero(good)))
        lam[pend[~good]] *= 0.5
        pend = pend[~good]
    if pend.size:                   # no decrease found: the smallest step anyway (leaves flat regions)
        zt = move(_take_path(path, pend), lam[pend])
        z_new[pend] = zt
        st_try.put(pend, sub.rows(pend).evaluate(zt))
    return z_new, st_try, lam


def _take_path(path, idx):
    return tuple(p[idx] for p in path)


def newton(problem, z, opt: NewtonOptions, state=None) -> NewtonResult:
    """Damped Newton iteration on every case of ``problem`` from the unknowns ``z`` (nb, n).

    ``state``: the problem's state at ``z`` when the caller has it.  Returns a :class:`NewtonResult`;
    a case that does not converge is reported, never raised (the form decides: continuation, or
    NoConvergence / NoEquilibrium with the residual and the iterations).

    The iteration runs on the active cases only: a case that has stopped (converged, at its floor or
    failed) is written to the result once and dropped from the arrays the next steps work on."""
    st_all = problem.evaluate(z) if state is None else state
    nb = st_all.norm.size
    z_all = np.array(z, dtype=float)
    its = np.zeros(nb, int)
    floor_all = np.zeros(nb, bool)
    act = np.arange(nb)                      # the active cases (indices into the batch)
    sub, st, zz = problem, st_all, z_all     # the problem, state and unknowns of the active cases
    norm = st.norm
    floor = np.zeros(nb, bool)
    floored = False                          # any active case at its floor (then ``todo`` excludes it)
    npol = np.zeros(nb, int)
    hist = np.repeat(norm[:, None], opt.window, axis=1) if opt.window > 1 else None
    has_refresh, has_relax = hasattr(problem, "refresh"), hasattr(problem, "relax")
    has_limit, curved = hasattr(problem, "limit"), hasattr(problem, "path")
    tol, target, accept = opt.tol, opt.tol * opt.polish_factor, 1.0 - opt.armijo
    capped = opt.step_cap < np.inf
    for it in range(1, opt.maxiter + 1):
        if has_refresh:
            st = sub.refresh(zz, st)
            norm = st.norm
        todo = norm > tol
        if opt.polish:
            todo |= (norm > target) & (npol < opt.polish)
        if floored:
            todo &= ~floor
        n_todo = np.count_nonzero(todo)
        if n_todo == 0 and act.size == nb:    # every case stopped before any retired: the arrays are the batch
            break
        if n_todo < todo.size:                # retire the cases that have stopped
            if act.size == nb:                # the first retirement: the batch results are the current arrays
                z_all, st_all = zz.copy(), st
            _retire(act, ~todo, zz, st, floor, z_all, st_all, floor_all)
            if n_todo == 0:
                act = act[:0]
                break
            keep = np.flatnonzero(todo)
            act, zz, st, norm = act[keep], zz[keep], st.take(keep), norm[keep]
            sub = sub.rows(keep)
            floor, npol = floor[keep], npol[keep]
            hist = None if hist is None else hist[keep]
            floored = bool(floor.any())
        dz = sub.direction(st)
        if has_limit:
            dz = sub.limit(st, dz)
        if capped:
            big = np.abs(dz).max(axis=1)
            if np.fmax.reduce(big) > opt.step_cap:
                dz *= np.minimum(1.0, opt.step_cap / big)[:, None]
        ref = norm if hist is None else hist.max(axis=1)
        path = sub.path(zz, dz) if curved else (zz, dz)
        move = sub.move if curved else _linear_move
        z_new = move(path, None)
        st_new = sub.evaluate(z_new)
        prev = norm
        zz, st = z_new, st_new
        if not (st.norm < accept * ref).all():
            zz, st, lam = _line_search(sub, zz, dz, st, ref, path, move, opt)
            damped = lam < 1.0
            if has_relax and damped.any():
                zz, st = sub.relax(zz, st, damped)      # the cases that took a damped step
        norm = st.norm
        if np.fmin.reduce(norm) <= opt.floor:     # (fmin: a NaN case does not hide the others)
            floor |= (norm <= opt.floor) & (norm > 0.5 * prev)
            floored = bool(floor.any())
        if hist is not None:
            hist[:, it % opt.window] = norm
        if opt.polish and np.fmin.reduce(prev) <= tol:
            npol += prev <= tol
        its[act] += 1
    if act.size == nb:                        # no case retired: the active arrays are the batch
        z_all, st_all, floor_all = zz, st, floor
    elif act.size:
        _retire(act, np.ones(act.size, bool), zz, st, floor, z_all, st_all, floor_all)
    norm = st_all.norm
    conv = (norm <= tol) | (floor_all & (norm <= opt.floor))
    return NewtonResult(z_all, st_all, norm, its, conv)


def _retire(act, mask, zz, st, floor, z_all, st_all, floor_all):
    """Write the active cases ``mask`` (their unknowns, state and floor flag) into the batch results."""
    loc = np.flatnonzero(mask)
    g = act[loc]
    z_all[g] = zz[loc]
    st_all.put(g, st.take(loc))
    floor_all[g] = floor[loc]


@dataclass
class ContinuationResult:
    """Outcome of :func:`continuation`, per case.

    Attributes
    ----------
    z : ndarray (nb, n)         unknowns at the last stage each case solved (its start where none)
    reached : ndarray (nb,)     index of that stage (−1: none)
    norm : ndarray (nb,)        residual of the last solve of each case (NaN: never solved)
    iterations : ndarray (nb,)  Newton steps over all stages
    ok : ndarray (nb,)          the case solved its last stage
    states : dict               the problem state of the last solve, by stage: ``{stage: (idx, state)}``
    """

    z: np.ndarray
    reached: np.ndarray
    norm: np.ndarray
    iterations: np.ndarray
    ok: np.ndarray
    states: dict


def continuation(solve, z0, path) -> ContinuationResult:
    """Natural-parameter continuation, batched: each case follows its own path of parameters.

    ``path`` (nb, T): the parameter of each case at each stage, NaN after its last stage.
    ``solve(idx, z, p, stage)`` solves the cases ``idx`` at parameters ``p`` from the unknowns ``z``
    (the last solution of each, ``z0`` at the first stage) and returns a :class:`NewtonResult`.
    A case that fails a stage stops there (``reached`` says how far it got)."""
    path = np.asarray(path, dtype=float)
    nb, T = path.shape
    z = np.array(z0, dtype=float)
    alive = np.ones(nb, bool)
    reached = np.full(nb, -1)
    norm = np.full(nb, np.nan)
    its = np.zeros(nb, int)
    last = np.isfinite(path).sum(axis=1) - 1
    states = {}
    for t in range(T):
        act = alive & np.isfinite(path[:, t])
        if not act.any():
            continue
        idx = np.flatnonzero(act)
        r = solve(idx, z[idx], path[idx, t], t)
        its[idx] += r.iterations
        norm[idx] = r.norm
        good = r.converged
        z[idx[good]] = r.z[good]
        reached[idx[good]] = t
        alive[idx[~good]] = False
        states[t] = (idx, r.state)
    return ContinuationResult(z, reached, norm, its, alive & (reached == last), states)
