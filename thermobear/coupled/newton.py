r"""The batched Newton iteration of the coupled steady state, and the heating path it falls back on.

For the free node temperatures T_f of B operating points at once (stacked matrices, one batched solve per
iteration; the points may be the model alternatives of several families stacked on the batch axis):

.. math:: R(T_f) = A_{ff}(T) T_f + A_{fb}(T) T_b - S\, P(C T_f) = 0,
          \qquad J = A_{ff} + \frac{\partial (A T)}{\partial T_f} - S \frac{\partial P}{\partial x} C

with C the coupled-temperature map and S the split of the loss parts onto the nodes
(:class:`~thermobear.coupled.sources.Coupling`).  ∂P/∂x comes from one loss evaluation at stacked
temperature states (x and x + h; four states for a source whose parts share temperatures), ∂(AT)/∂T
from forward differences of the temperature-dependent conductances (re-evaluated while the steps
exceed 1 K).  Each point stops on its own (max |ΔT_f| ≤ tol_K): a point's iterates do not depend on
the other points of the batch.  The loop gain, the largest real eigenvalue of C A_ff⁻¹ S ∂P/∂x, must be
< 1 at an equilibrium; a point the iteration cannot decide is decided on the physical heating path
(:func:`thermobear.coupled.fixedpoint.solve_coupled`).
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from thermobear.coupled.fixedpoint import solve_coupled
from thermobear.coupled.sources import Coupling
from thermobear.errors import ExtrapolationWarning, NoConvergence
from thermobear.thermal.solve import batched_solve, isolated_nodes
from thermobear.units import ZERO_C_K
from thermobear.validity import T_LUBRICANT_REFUSE_C

__all__ = ["T_LIMIT_K"]

_C0 = ZERO_C_K                 # [K] at 0 °C (thermobear.units)
T_LIMIT_K = T_LUBRICANT_REFUSE_C[1] + _C0     #: an equilibrium beyond the lubricant's limit is runaway


class _Histories:
    """Per-point convergence histories of the batched Newton iteration, kept as arrays per iteration
    and turned into a point's list of dicts only when asked for (most points never are)."""

    def __init__(self, B: int):
        self.records: list = []            # per iteration: (iteration, points, x [K], step, mean step, P [W])
        self.explicit: dict = {}           # point → a history given whole (the heating path)
        self.B = B

    def add(self, it, idx, x, s, mean, P):
        pos = np.full(self.B, -1)
        pos[idx] = np.arange(idx.size)
        self.records.append((it, pos.tolist(), x, s.tolist(), mean.tolist(), P.tolist()))

    def __getitem__(self, b: int) -> list:
        if b in self.explicit:
            return self.explicit[b]
        return [dict(iteration=it, T_K=x[pos[b]].copy(), residual_K=s[pos[b]], mean_residual_K=mean[pos[b]],
                     P_W=P[pos[b]], step="newton") for it, pos, x, s, mean, P in self.records if pos[b] >= 0]


@dataclass
class _Newton:
    """Per-point outcome of the batched Newton iteration."""

    T: np.ndarray            # (B, n) node temperatures [K]
    x: np.ndarray            # (B, n_x) coupled temperatures [K]
    done: np.ndarray         # (B,) converged to a stable equilibrium
    its: np.ndarray          # (B,) iterations
    step: np.ndarray         # (B,) last step [K]
    gain: np.ndarray         # (B,) loop gain
    history: object          # per point (indexable), list of dicts
    method: tuple = ()       # per point, how it converged


def _slopes(src, cp: Coupling, x_C, h=0.05):
    """Loss parts P (B, n_parts) [W] at x [°C] and ∂P/∂x (B, n_parts, n_x) [W/K] by forward differences."""
    if src.diagonal:       # each part reads its own temperature: x and x + h in one evaluation
        Pm = src.parts(np.stack([x_C, x_C + h]))
        return Pm[0], (Pm[1] - Pm[0])[:, :, None] * cp.incidence()[None] / h
    n = x_C.shape[-1]
    X = np.repeat(x_C[None], n + 1, axis=0)
    for k in range(n):
        X[k + 1, :, k] += h
    Pm = src.parts(X)
    return Pm[0], np.stack([(Pm[k + 1] - Pm[0]) / h for k in range(n)], axis=-1)


def _loop_gain(Aff, SdP, C):
    """Largest real eigenvalue of C A_ff⁻¹ S ∂P/∂x per point (B,) (``SdP`` = S ∂P/∂x, (B, n_free, n_x));
    NaN where it is not defined."""
    M = C @ batched_solve(Aff, SdP)
    ok = np.isfinite(M).all(axis=(1, 2))
    out = np.full(M.shape[0], np.nan)
    if ok.any():
        out[ok] = np.linalg.eigvals(M[ok]).real.max(axis=1)
    return out


def _newton(net, src, cp: Coupling, tol_K, T0=None, maxiter: int = 30, h: float = 0.05) -> _Newton:
    """Batched Newton on the free node temperatures (see the module docstring)."""
    B, free, fixed = net.B, ~net.fixed, net.fixed
    T = net.initial_T_K()
    if T0 is not None:              # a start per point (rows of NaN: the default start)
        T0 = np.asarray(T0, float)
        T = np.where(np.isfinite(T0).all(axis=1, keepdims=True) & ~fixed, T0, T)
    Tb = T[:, fixed]
    done, bad = np.zeros(B, bool), np.zeros(B, bool)
    its, step, gain = np.zeros(B, int), np.full(B, np.inf), np.full(B, np.nan)
    hist = _Histories(B)
    dG = None
    for it in range(1, maxiter + 1):
        live = ~(done | bad)
        if not live.any():
            break
        x = T[:, free] @ cp.C.T
        P, dP = _slopes(src, cp, x - _C0, h)
        fresh = live & (step > 1.0)
        if dG is None or fresh.any():  # the slopes of the conductances re-evaluated while a point's step > 1 K;
            G, dG_new = net.dconductances(T)     # below, each point keeps its last ones (same as alone)
            dG = dG_new if dG is None else [(k, m, np.where(fresh, dn, do)) for (k, m, dn), (_, _, do) in zip(dG_new, dG)]
        else:
            G = net.conductances(T)
        Aff, Afb = net.blocks(G)
        Tf = T[:, free]
        SdP = cp.S @ dP                                          # (B, n_free, n_x)
        R = (Aff @ Tf[..., None] + Afb @ Tb[..., None])[..., 0] - P @ cp.S.T
        J = Aff + net.dAT_free(T, dG) - SdP @ cp.C
        dT = batched_solve(J, -R)
        finite = np.isfinite(dT).all(axis=1)
        bad |= live & ~finite
        live &= finite
        dT = np.where(live[:, None], dT, 0.0)
        s = np.where(live, np.abs(dT).max(axis=1, initial=0.0), np.inf)
        # the loop gain at the first iterate, whenever the step does not shrink, and at the answer
        check = live & ((it == 1) | (s >= step) | (s <= tol_K))
        if check.any():
            gain = np.where(check, _loop_gain(Aff, SdP, cp.C), gain)
        step = np.where(live, s, step)
        dT *= np.minimum(1.0, 50.0 / np.maximum(np.abs(dT).max(axis=1, initial=0.0), 1e-300))[:, None]
        idx = np.flatnonzero(live)
        hist.add(it, idx, x[idx], s[idx], (dT[idx] @ cp.C.T).mean(axis=1), P[idx].sum(axis=1))
        T[:, free] = Tf + dT
        its = np.where(live, it, its)
        conv = live & (s <= tol_K)
        done |= conv
        bad |= live & ~conv & ((gain >= 1.0) | (~np.isfinite(gain)) | ((T[:, free] @ cp.C.T).max(axis=1) > T_LIMIT_K))
    done &= np.isfinite(gain) & (gain < 1.0)
    return _Newton(T=T, x=T[:, free] @ cp.C.T, done=done, its=its, step=step, gain=gain, history=hist,
                   method=("newton",) * B)


def no_exchange(names: str, **kw) -> NoConvergence:
    """The failure of an operating point whose network leaves nodes without any conductance (``names``,
    :func:`~thermobear.thermal.solve.isolated_nodes`): their temperatures are not determined."""
    return NoConvergence(
        f"no steady state: {names or 'a group of nodes'} exchange no heat with the rest of the network at this "
        "operating point (e.g. the balls of a bearing at rest and unloaded: their contacts carry no load and the "
        "lubricant around them is still), so that no temperature is determined for them", **kw)


def _sources_matrix(net, cp: Coupling, parts) -> np.ndarray:
    """(B, n) node sources [W] of the loss parts (B, n_parts)."""
    P = np.zeros((net.B, len(net.nodes)))
    P[:, ~net.fixed] = parts @ cp.S.T
    return P


_NETWORK_MAXITER = 50     #: passes of the network's conductances to its own temperatures in one heating-path update


def _physical_path(net, src, cp: Coupling, tol_K) -> _Newton:
    """One point (B = 1) decided on the heating path (:func:`~thermobear.coupled.fixedpoint.solve_coupled`:
    Anderson mixing, then Picard from ambient); raises ThermalRunaway or NoConvergence.  Each update is
    the network's steady state with the losses at the coupled temperatures, its temperature-dependent
    conductances iterated to its own temperatures (else the update would depend on the last iterate's,
    and a fixed point in the coupled temperatures need not be the network's)."""
    free, fixed = ~net.fixed, net.fixed
    state = {"T": net.initial_T_K()}
    Tb = state["T"][:, fixed]

    def update(x_K):
        parts = src.parts((np.asarray(x_K) - _C0)[None])
        P = _sources_matrix(net, cp, parts)[:, free]
        for _ in range(_NETWORK_MAXITER):     # the network with these sources, its conductances at its own temperatures
            T_was = state["T"][:, free]
            G = net.conductances(state["T"])
            Aff, Afb = net.blocks(G)
            Tf = batched_solve(Aff, P - np.einsum("bij,bj->bi", Afb, Tb))
            if not np.isfinite(Tf).all():
                raise no_exchange(isolated_nodes(net, G)[0], iterations=0)
            state["T"] = np.where(fixed, state["T"], 0.0)
            state["T"][:, free] = Tf
            if np.max(np.abs(Tf - T_was)) <= 1e-3 * tol_K:
                break
        return (Tf @ cp.C.T)[0], float(parts.sum())

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)
        res = solve_coupled(update, (state["T"][:, free] @ cp.C.T)[0], tol_K=tol_K, T_limit_K=T_LIMIT_K)
        update(res.T_K)             # the network at the answer (the loop gain's probes moved it)
    x = res.T_K[None]
    T = state["T"]
    hist = _Histories(1)
    hist.explicit[0] = res.history
    return _Newton(T=T, x=x, done=np.array([True]), its=np.array([res.iterations]), step=np.array([res.residual_K]),
                   gain=np.array([res.loop_gain]), history=hist, method=(res.method,))
