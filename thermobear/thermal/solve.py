r"""Steady and transient solution of a thermal network at B operating points, and the loss split.

Heat balance of the free nodes f, with the fixed nodes b as boundaries (Pouly et al. 2010):

.. math:: A_{ff}(T)\, T_f + A_{fb}(T)\, T_b = P_f

with conductive elements symmetric (A_ii += G, A_jj += G, A_ij = A_ji −= G) and advective ones
one-way (upwind: only the downstream row d gets A_dd += G, A_du −= G).  Every operating point of
a :class:`~thermobear.thermal.network.ThermalNetwork` is solved at once: stacked matrices
(B, n_f, n_f), one batched LAPACK solve per iteration.

* :func:`solve_steady` — Newton on T_f for the temperature-dependent conductances (free and
  forced convection, radiation, fluid properties), ∂(A T)/∂T by forward differences of the
  conductances; one linear solve for a linear network.  The energy balance of the result closes
  to machine precision (the flows use the conductances of the final solve).
* :func:`solve_transient` — C_f dT_f/dt = P_f(t, T) − A_ff(T) T_f − A_fb(T) T_b(t), integrated
  with scipy's BDF and the block-diagonal Jacobian −C⁻¹ A_ff, restarted at every breakpoint so
  that steps in the inputs are not smeared; a run may continue another one's integration
  (``continue_from``: sources changing a little between runs, the step history kept).
* :func:`split_losses` — the bearing losses onto the nodes (½ of each contact loss to the ball,
  ½ to its race; drag to the oil–air mixture), energy conserved exactly.

References
----------
.. [1] Pouly, F., Changenet, C., Ville, F., Velex, P., Damiens, B., 2010, "Power loss predictions
   in high-speed rolling element bearings using thermal networks", Tribology Transactions 53,
   957–967.
.. [2] Shampine, L. F., Reichelt, M. W., 1997, "The MATLAB ODE suite", SIAM J. Sci. Comput. 18,
   1–22 (the BDF/NDF method of ``scipy.integrate.solve_ivp``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np
import scipy.sparse as sp

from thermobear.errors import InputError, NoConvergence
from thermobear.lazy import lazy_module
from thermobear.thermal.boundary import LinearBoundary  # noqa: F401  (re-exported: the transient's fixed_C)
from thermobear.thermal.network import ThermalNetwork
from thermobear.units import ZERO_C_K

integrate = lazy_module("scipy.integrate")  # BDF, Radau: loaded by the first transient

__all__ = ["SteadyResult", "TransientResult", "solve_steady", "solve_linear", "solve_transient", "split_losses",
           "sources_matrix", "batched_solve", "heat_out", "heat_paths", "isolated_nodes", "LinearBoundary"]

_C0 = ZERO_C_K                 # [K] at 0 °C (thermobear.units)


def batched_solve(A, b):
    """x with A x = b for stacked matrices A (B, n, n) and right-hand sides b (B, n) or (B, n, k);
    rows of a singular A come back as NaN (the caller names the failure)."""
    try:
        return np.linalg.solve(A, b[..., None])[..., 0] if b.ndim == A.ndim - 1 else np.linalg.solve(A, b)
    except np.linalg.LinAlgError:
        out = np.full(b.shape, np.nan)
        for k in range(A.shape[0]):
            try:
                out[k] = np.linalg.solve(A[k], b[k])
            except np.linalg.LinAlgError:
                pass
        return out


def sources_matrix(net: ThermalNetwork, sources_W) -> np.ndarray:
    """Heat sources (B, n) [W] from a dict node → W (numbers, arrays over the B points, or per-ball
    arrays (B, Z) summed over the last axis); unknown or fixed nodes → InputError."""
    P = np.zeros((net.B, len(net.nodes)))
    for name, q in (sources_W or {}).items():
        k = net.index.get(name)
        if k is None:
            raise InputError("sources", name, f"unknown node; nodes: {', '.join(net.nodes)}")
        if net.fixed[k]:
            raise InputError(f"sources.{name}", q, "heat cannot be injected into a fixed-temperature node")
        q = np.asarray(q, dtype=float)
        if q.ndim == 2 or (q.ndim == 1 and net.B == 1 and q.size > 1):
            q = q.sum(axis=-1)
        if not np.all(np.isfinite(q)):
            raise InputError(f"sources.{name}", q, "must be a finite heat flow [W]")
        P[:, k] += q
    return P


def heat_paths(net: ThermalNetwork, Q) -> dict:
    """Heat leaving the free part of the network per path [W]: element name → (boundary, (B,) flow)
    for each element between a free and a fixed node (positive: into the fixed node) and each
    advective element draining a free node (boundary ``"stream"``: carried away by the oil), from
    element flows Q (B, n_el)."""
    out: dict = {}
    fixed = net.fixed
    for k, e in enumerate(net.elements):
        fi, fj = fixed[e.i], fixed[e.j]
        if e.advective:
            if not fj:
                out[e.name] = ("stream", Q[:, k])
        elif fi != fj:
            out[e.name] = (e.nodes[1], Q[:, k]) if fj else (e.nodes[0], -Q[:, k])
    return out


def heat_out(net: ThermalNetwork, Q) -> dict:
    """Heat leaving the free part of the network [W] per point (B,): into each fixed node, and
    into the oil stream (``"stream"``): the paths of :func:`heat_paths` summed per boundary."""
    out: dict = {}
    for node, q in heat_paths(net, Q).values():
        out[node] = out.get(node, 0.0) + q
    return out


def _scalar(v, B):
    """Per-point values: a float for one operating point, else the (B,) array."""
    return float(v[0]) if B == 1 else np.asarray(v)


@dataclass
class SteadyResult:
    """Steady temperatures, flows and energy balance at B operating points.

    Per-point quantities are floats when the network has one operating point, (B,) arrays otherwise.

    Attributes
    ----------
    T_C : dict              node → temperature [°C]
    T_K : ndarray           (B, n) temperatures of all nodes in ``network.nodes`` order [K]
    G_W_K : ndarray         (B, n_el) element conductances of the final solve [W/K]
    flows_W : dict          element name → heat flow [W], signed along the element's ``between``
                            (advection: carried away from the downstream node)
    sources_W : dict        node → heat injected [W]
    balance_W : float       Σ sources − Σ heat leaving to fixed nodes and the oil stream [W]
    balance_rel : float     |balance_W| / Σ |sources| (or / Σ |flows| without sources)
    iterations : int        Newton iterations (1 for a linear network)
    residual_K : float      last max |ΔT| [K]
    network : ThermalNetwork
    """

    T_C: dict
    T_K: np.ndarray
    G_W_K: np.ndarray
    flows_W: dict
    sources_W: dict
    balance_W: object
    balance_rel: object
    iterations: int
    residual_K: float
    network: ThermalNetwork = field(repr=False)

    @property
    def heat_out_W(self) -> dict:
        """Heat leaving into each fixed node and into the oil stream [W]."""
        Q = np.column_stack([np.atleast_1d(self.flows_W[e.name]) for e in self.network.elements])
        return {k: _scalar(np.broadcast_to(v, (self.network.B,)), self.network.B)
                for k, v in heat_out(self.network, Q).items()}


def _result(net, T, G, P, it, res) -> SteadyResult:
    B = net.B
    Q = net.flows(T, G)
    Pf = P[:, ~net.fixed]
    out = heat_out(net, Q)
    total_out = sum(np.broadcast_to(v, (B,)) for v in out.values()) if out else np.zeros(B)
    bal = Pf.sum(axis=1) - total_out
    scale = np.abs(Pf).sum(axis=1)
    scale = np.where(scale > 0, scale, np.maximum(np.abs(Q).sum(axis=1), 1.0))
    return SteadyResult(
        T_C={n: _scalar(T[:, k] - _C0, B) for k, n in enumerate(net.nodes)}, T_K=T, G_W_K=G,
        flows_W={e.name: _scalar(Q[:, k], B) for k, e in enumerate(net.elements)},
        sources_W={n: _scalar(P[:, k], B) for k, n in enumerate(net.nodes) if np.any(P[:, k])},
        balance_W=_scalar(bal, B), balance_rel=_scalar(np.abs(bal) / scale, B), iterations=it, residual_K=res,
        network=net)


def solve_steady(net: ThermalNetwork, sources_W=None, *, T_guess_K=None, tol_K: float = 1e-8,
                 max_iter: int = 50) -> SteadyResult:
    r"""Steady temperatures of a thermal network at its operating points.

    Parameters
    ----------
    net : ThermalNetwork
    sources_W : dict or ndarray   free node → injected heat [W] (numbers or (B,) arrays), or a
                                  (B, n) matrix (:func:`sources_matrix`)
    T_guess_K : array_like        (B, n) start (default: free nodes at the mean fixed temperature)
    tol_K : float                 Newton tolerance on max |ΔT| [K]
    max_iter : int                iteration budget

    Returns
    -------
    SteadyResult   (energy balance closes to machine precision)

    Raises
    ------
    NoConvergence  when an operating point does not reach tol_K, or its matrix is singular

    Notes
    -----
    Newton on the free temperatures:

    .. math:: \left(A_{ff} + \frac{\partial (A T)}{\partial T_f}\right) \Delta T_f
              = P_f - A_{ff} T_f - A_{fb} T_b

    Examples
    --------
    >>> from thermobear.thermal.network import load_network
    >>> net = load_network({"nodes": {"a": {}, "amb": {"T_C": 20.0}},
    ...     "elements": [{"type": "conductance", "between": ["a", "amb"], "G_W_K": 2.0}]})
    >>> r = solve_steady(net, {"a": 100.0})
    >>> round(r.T_C["a"], 9), r.flows_W["a--amb"], r.balance_rel < 1e-12
    (70.0, 100.0, True)
    """
    P = np.asarray(sources_W, float) if isinstance(sources_W, np.ndarray) else sources_matrix(net, sources_W)
    free, fixed = ~net.fixed, net.fixed
    T = net.initial_T_K() if T_guess_K is None else np.array(np.broadcast_to(T_guess_K, (net.B, len(net.nodes))))
    T[:, fixed] = net.T_fixed_K[:, fixed]
    res, it = math.inf, 0
    for it in range(1, max_iter + 1):
        if net.T_dependent:
            G, dG = net.dconductances(T)
        else:
            G, dG = net.structure.G0, []
        Aff, Afb = net.blocks(G)
        R = np.einsum("bij,bj->bi", Aff, T[:, free]) + np.einsum("bij,bj->bi", Afb, T[:, fixed]) - P[:, free]
        J = Aff + net.dAT_free(T, dG) if dG else Aff
        dT = batched_solve(J, -R)
        if not np.all(np.isfinite(dT)):
            bad = np.flatnonzero(~np.isfinite(dT).all(axis=1))
            raise NoConvergence(f"singular conductance matrix at operating point(s) {bad.tolist()} "
                                "(a node without conductance?)", iterations=it, last=T.copy())
        T[:, free] += dT
        res = float(np.max(np.abs(dT))) if dT.size else 0.0
        if not net.T_dependent or res <= tol_K:
            break
    else:
        raise NoConvergence(f"steady network: max |ΔT| = {res:.3g} K after {max_iter} Newton iterations "
                            f"(tolerance {tol_K:g} K)", iterations=max_iter, residual=res, last=T.copy())
    G = net.conductances(T)
    if net.T_dependent:                # the flows and the temperatures from the same conductances
        Aff, Afb = net.blocks(G)
        T[:, free] = batched_solve(Aff, P[:, free] - np.einsum("bij,bj->bi", Afb, T[:, fixed]))
    return _result(net, T, G, P, it, res)


def solve_linear(net: ThermalNetwork, sources_W, T_K, *, singular: str = "raise") -> SteadyResult:
    """Temperatures of the free nodes for sources (B, n) [W] with the conductances at ``T_K`` (B, n)
    [K] held (one linear solve): the last step of a coupled solution, whose flows and temperatures
    then come from the same conductances (the energy balance closes to machine precision).

    An operating point whose conductance matrix is singular (a free node that exchanges no heat, e.g. the
    balls of a bearing at rest and unloaded): ``singular="raise"`` a NoConvergence naming the nodes
    (:func:`isolated_nodes`), ``"nan"`` its row of temperatures NaN (the others solved)."""
    if singular not in ("raise", "nan"):
        raise InputError("singular", singular, "'raise' or 'nan'")
    free, fixed = ~net.fixed, net.fixed
    T = np.array(T_K, dtype=float)
    T[:, fixed] = net.T_fixed_K[:, fixed]
    G = net.conductances(T)
    Aff, Afb = net.blocks(G)
    P = np.asarray(sources_W, float)
    T[:, free] = batched_solve(Aff, P[:, free] - np.einsum("bij,bj->bi", Afb, T[:, fixed]))
    if singular == "raise" and not np.all(np.isfinite(T)):
        bad = int(np.argmax(~np.isfinite(T).all(axis=1)))
        raise NoConvergence(f"singular conductance matrix: {isolated_nodes(net, G)[bad] or 'a group of nodes'} "
                            "exchange no heat with the rest of the network", iterations=1)
    return _result(net, T, G, P, 1, 0.0)


def isolated_nodes(net: ThermalNetwork, G) -> list:
    """Per operating point, the free nodes without any conductance [-] at the conductances G (B, n_el) [W/K]:
    the nodes whose temperature no steady state determines (a singular conductance matrix), joined by ", "."""
    Aff, Afb = net.blocks(G)
    none = (np.abs(Aff).sum(axis=2) + np.abs(Afb).sum(axis=2)) == 0.0
    names = [n for n, f in zip(net.nodes, ~net.fixed) if f]
    return [", ".join(n for n, z in zip(names, row) if z) for row in none]


@dataclass
class TransientResult:
    """Time series of a transient run at B operating points.

    Attributes
    ----------
    t : ndarray          output times [s]
    T_K : ndarray        node temperatures, shape (n_t, B, n) [K]
    T_C : dict           node → temperatures [°C]: (n_t,) for one operating point, (n_t, B) otherwise
    report : dict        name → series of what the sources callback reported, (n_t,) or (n_t, B)
    nfev : int           right-hand-side evaluations
    completed : bool     False when the run was interrupted (``t`` ends where it stopped)
    network : ThermalNetwork
    integrator : object  the integrator at the run's end (``continue_from`` of a following run)
    """

    t: np.ndarray
    T_K: np.ndarray
    T_C: dict
    report: dict
    nfev: int
    completed: bool = True
    network: ThermalNetwork = field(default=None, repr=False)
    integrator: object = field(default=None, repr=False)

    def end_rate_K_s(self) -> np.ndarray:
        """dT/dt of every node at the end of the run, (B, n) [K/s] (fixed nodes 0): the slope of the
        integrator's interpolant over its last step (no balance evaluated); zeros for a run without a step."""
        out = np.zeros(self.T_K.shape[1:])
        sv = None if self.integrator is None else self.integrator.solver
        if sv is not None and sv.t_old is not None:
            dense, eps = sv.dense_output(), 1e-3 * (sv.t - sv.t_old)
            out[:, ~self.network.fixed] = ((dense(sv.t) - dense(sv.t - eps)) / eps).reshape(out.shape[0], -1)
        return out


@dataclass(frozen=True)
class _Boundary:
    """The fixed nodes of a network at time t [K]: their own temperatures, those named by a
    ``fixed_C(t)`` callable replaced by its values."""

    net: ThermalNetwork
    fixed_C: Callable | None
    names: tuple
    index: np.ndarray

    @classmethod
    def of(cls, net, fixed_C):
        if fixed_C is None:
            return cls(net, None, (), np.zeros(0, int))
        names = tuple(fixed_C(0.0))
        for name in names:
            if name not in net.index or not net.fixed[net.index[name]]:
                raise InputError("fixed_C", name, f"a fixed node name ({', '.join(np.asarray(net.nodes)[net.fixed])})")
        return cls(net, fixed_C, names, np.array([net.index[n] for n in names], int))

    def values_K(self, t) -> np.ndarray:
        """(B, k) temperatures [K] of the nodes named by fixed_C at time t [s]."""
        d = self.fixed_C(t)
        return np.stack([np.broadcast_to(np.asarray(d[n], float), (self.net.B,)) for n in self.names], axis=-1) + _C0

    def T_K(self, t) -> np.ndarray:
        """(B, n) temperatures [K] with the fixed nodes at their values at t (free nodes: undefined)."""
        T = self.net.T_fixed_K.copy()
        if self.fixed_C is not None:
            T[:, self.index] = self.values_K(t)
        return T


def _start(net, T0_C, bnd=None):
    """(B, n) start temperatures: fixed nodes at theirs (at t = 0), free nodes at ``T0_C`` (°C, a
    number, a (B,) array, or node → °C), default (and the nodes a dict leaves out) the fixed node
    ``ambient`` (else the mean fixed T)."""
    free, fixed = ~net.fixed, net.fixed
    T = net.T_fixed_K.copy() if bnd is None else bnd.T_K(0.0)
    a = net.index.get("ambient")
    if T0_C is None or isinstance(T0_C, dict):
        T[:, free] = (T[:, [a]] if a is not None and fixed[a] else T[:, fixed].mean(axis=1, keepdims=True))
    if isinstance(T0_C, dict):
        for name, v in T0_C.items():
            if name not in net.index or fixed[net.index[name]]:
                raise InputError("T0_C", name, "a free node name")
            T[:, net.index[name]] = np.asarray(v, float) + _C0
    elif T0_C is not None:
        T[:, free] = np.asarray(T0_C, float).reshape(-1, 1) + _C0
    if not np.all(np.isfinite(T)):
        raise InputError("T0_C", T0_C, "start temperatures must be finite [°C]")
    return T


def solve_transient(net: ThermalNetwork, sources: Callable, t_end: float, *, T0_C=None, breakpoints=(),
                    fixed_C: Callable | None = None, t_eval=None, rtol: float = 1e-8, atol: float = 1e-8,
                    method: str = "BDF", max_step: float = np.inf, stop: Callable | None = None,
                    continue_from: TransientResult | None = None, until: Callable | None = None) -> TransientResult:
    r"""Transient temperatures of a thermal network at its operating points.

    Parameters
    ----------
    net : ThermalNetwork        every free node needs a heat capacity C [J/K]
    sources : callable          ``sources(t, T_K) -> (P, report)``: T_K node temperatures
                                (..., B, n) [K] (the output pass calls it once with a leading time
                                axis), P the injected heat of the same shape [W], report a dict of
                                arrays (..., B) to record (e.g. the loss breakdown); or a (B, n)
                                matrix / dict of constant sources.  A callable may carry
                                ``sources.jacobian(t, T_K)``: ∂P/∂T of the free nodes (B, n_free,
                                n_free) [W/K], which the integrator's Jacobian adds to the network's
                                (without it: the network's alone, the sources' feedback left to the
                                corrector's iterations)
    t_end : float               end time [s]
    T0_C : float, array, dict   initial temperature of the free nodes [°C] (default: ambient)
    breakpoints : sequence      times [s] where inputs step: the integration restarts there; inside a
                                segment [a, b) the callbacks see t < b; reported series are
                                right-continuous
    fixed_C : callable          optional ``fixed_C(t) -> dict`` fixed node → °C (numbers or (B,)
                                arrays): time-varying boundary temperatures, evaluated wherever the
                                integrator evaluates the balance (inside a segment [a, b), like the
                                sources).  One mechanism for steps (a function stepping at
                                breakpoints) and for continuous boundaries (a logged temperature,
                                linear between its samples: :class:`LinearBoundary`); the fixed nodes
                                of the result hold its values at the output times
    t_eval : array_like         output times [s] (default: the integrator's steps)
    rtol, atol : float          integrator tolerances (atol in K)
    method : str                ``"BDF"`` or ``"Radau"``
    stop : callable             optional ``stop() -> bool`` checked between steps: True ends the run
                                early, keeping what was integrated (``completed`` False)
    until : callable            optional ``until(t, T_K) -> bool`` of the run's time [s] and node temperatures
                                (B, n) [K] after each step: True ends the run at that step (completed, its last time — reported
                                also with ``t_eval`` — before ``t_end``; e.g. where a temperature leaves the
                                range its sources hold for)
    continue_from : TransientResult
                                a completed run this one continues: from its end state (``T0_C``
                                None), its clock starting at 0 there, the integrator keeping its step
                                history (order, step size, Jacobian) instead of starting afresh — for
                                sources that change a little between runs (the film pieces of
                                :func:`thermobear.coupled.transient`); same nodes, points, method,
                                tolerances and max_step

    Returns
    -------
    TransientResult

    Notes
    -----
    .. math:: C_f \frac{dT_f}{dt} = P_f(t, T) - A_{ff}(T) T_f - A_{fb}(T) T_b(t)

    Jacobian −C⁻¹ A_ff, block diagonal over the operating points (dP/dT and dG/dT left out of it:
    they only change the Newton iterations of the implicit scheme, not the solution).

    Examples
    --------
    >>> from thermobear.thermal.network import load_network
    >>> net = load_network({"nodes": {"a": {"C_J_K": 100.0}, "amb": {"T_C": 20.0}},
    ...     "elements": [{"type": "conductance", "between": ["a", "amb"], "G_W_K": 2.0}]})
    >>> r = solve_transient(net, {"a": 100.0}, 50.0, t_eval=[50.0])
    >>> round(float(r.T_C["a"][-1]), 4), round(20 + 50 * (1 - math.exp(-1.0)), 4)
    (51.606, 51.606)
    """
    if method not in ("BDF", "Radau"):
        raise InputError("method", method, "a stiff integrator: BDF or Radau")
    if not (math.isfinite(t_end) and t_end > 0):
        raise InputError("t_end", t_end, "must be > 0 [s]")
    free = ~net.fixed
    C = net.C_J_K[..., free]                      # (nf,), or (B, nf) when the capacities differ per point
    if np.any(~np.isfinite(C) | (C <= 0)):
        bad = [n for n, c in zip(net.free_nodes, np.atleast_2d(C).min(axis=0)) if not (np.isfinite(c) and c > 0)]
        raise InputError(f"{net.source}: nodes.{bad[0]}.C_J_K", None,
                         "the transient needs a heat capacity (C_J_K, or mass_kg/volume_m3 with a material)")
    if not callable(sources):
        const = sources if isinstance(sources, np.ndarray) else sources_matrix(net, sources)
        sources = (lambda t, T_K: (np.broadcast_to(const, np.shape(T_K)), {}))  # noqa: E731
    B, nf = net.B, int(free.sum())
    edges = [0.0, *sorted({float(b) for b in breakpoints if 0 < float(b) < t_end}), float(t_end)]
    bnd = _Boundary.of(net, fixed_C)
    T = _start(net, T0_C, bnd)
    t_eval = None if t_eval is None else np.asarray(t_eval, dtype=float)
    pieces, completed = [], True
    y = T[:, free].ravel()
    if continue_from is None:
        integ = _Integrator(method, rtol, atol, max_step)
    else:
        integ = _continued(continue_from, net, T0_C, B, nf, (method, rtol, atol, max_step))
        y = integ.solver.y.copy()
    nfev0 = integ.nfev
    for a, b in zip(edges[:-1], edges[1:]):
        sol, ok = integ.segment(net, sources, C, bnd, a, b, y, t_eval, stop, fresh=not (a == 0.0 and continue_from),
                                until=until)
        y = sol.y[:, -1].copy()
        pieces.append((sol, a, b))
        if not ok:
            completed = False
            break
        if sol.until:
            break
    t_all, T_all = _collect(pieces, net, t_eval, B, nf, bnd)
    report = _output_pass(sources, t_all, T_all)
    squeeze = (lambda v: v[:, 0] if B == 1 else v)  # noqa: E731
    integ.last = TransientResult(t=t_all, T_K=T_all, T_C={n: squeeze(T_all[..., k] - _C0) for k, n in enumerate(net.nodes)},
                                 report={k: squeeze(np.asarray(v, float)) for k, v in report.items()},
                                 nfev=integ.nfev - nfev0, completed=completed, network=net, integrator=integ)
    return integ.last


def _continued(run, net, T0_C, B, nf, settings):
    """The integrator of a completed run, checked to continue on ``net`` with the same ``settings``
    (method, rtol, atol, max_step)."""
    integ = getattr(run, "integrator", None)
    if integ is None or integ.solver is None or not run.completed:
        raise InputError("continue_from", type(run).__name__, "a completed TransientResult of solve_transient")
    if integ.last is not run:
        raise InputError("continue_from", "TransientResult", "the latest run of its integrator (a run is continued once)")
    if T0_C is not None:
        raise InputError("T0_C", T0_C, "a continued run starts from the state its predecessor ended in (T0_C None)")
    if (B, nf) != (integ.B, integ.nf) or list(net.nodes) != list(integ.net.nodes):
        raise InputError("continue_from", net.name, "the same nodes and operating points as the run it continues")
    if settings != (integ.method, integ.rtol, integ.atol, integ.max_step):
        raise InputError("continue_from", settings, f"the integrator's method, rtol, atol and max_step "
                         f"{(integ.method, integ.rtol, integ.atol, integ.max_step)}")
    return integ


class _Integrator:
    """The stiff integrator of a transient and the problem it integrates now.

    The problem (network, sources, capacities, boundary, the segment [a, b) on its run's clock) can be
    replaced while the integrator keeps its step history (order, step size, Jacobian): a run that
    continues another (``solve_transient(..., continue_from=...)``) goes on from the same state with
    the same integrator, its clock starting at the integrator's time ``offset``.  A fresh segment (a
    breakpoint, a new run) starts a new integrator."""

    def __init__(self, method, rtol, atol, max_step):
        self.method, self.rtol, self.atol, self.max_step = method, rtol, atol, max_step
        self.solver, self.nfev, self.last = None, 0, None

    def _set(self, net, sources, C, bnd, a, b, offset):
        self.net, self.sources, self.bnd, self.a, self.b, self.offset = net, sources, bnd, a, b, offset
        self.free, self.fixed = ~net.fixed, net.fixed
        self.B, self.nf = net.B, C.shape[-1]
        self.t_hi = np.nextafter(b, a)      # inputs of [a, b): the step at b belongs to the next segment
        self.Tfull = bnd.T_K(a)
        self.Cb = np.broadcast_to(C, (self.B, self.nf))
        self.Cinv = (1.0 / self.Cb).ravel()

    def _state(self, tau, yf):
        """Node temperatures (B, n) [K] at integrator time tau, free nodes from yf; the run's time."""
        t = min(max(tau - self.offset, self.a), self.t_hi)
        self.Tfull[:, self.free] = yf.reshape(self.B, self.nf)
        if self.bnd.fixed_C is not None:
            self.Tfull[:, self.bnd.index] = self.bnd.values_K(t)
        return t, self.Tfull

    def rhs(self, tau, yf):
        self.nfev += 1
        t, T = self._state(tau, yf)
        Aff, Afb = self.net.blocks(self.net.conductances(T))
        P, _ = self.sources(t, T)
        q = (P[:, self.free] - np.einsum("bij,bj->bi", Aff, T[:, self.free])
             - np.einsum("bij,bj->bi", Afb, T[:, self.fixed]))
        return q.ravel() * self.Cinv

    def jac(self, tau, yf):
        t, T = self._state(tau, yf)
        Aff, _ = self.net.blocks(self.net.conductances(T))
        dP = getattr(self.sources, "jacobian", None)          # the sources' own feedback, where they give it
        Jb = (-Aff if dP is None else dP(t, T) - Aff) / self.Cb[:, :, None]
        return Jb[0] if self.B == 1 else sp.block_diag(list(Jb), format="csc")

    def _kink_within_tolerance(self, net, sources, C, bnd, a, b) -> bool:
        r"""Set the new problem; True when the step in dT/dt it makes at the integrator's state is
        small enough to continue: a multistep method whose history predates a kink Δf in the
        derivative makes an error of order h Δf in its next step h, kept within the tolerances'
        scale (the integrator's RMS error norm),

        .. math:: h \left\| \frac{f_{new}(y) - f_{old}(y)}{atol + rtol |y|} \right\|_{rms} \le 1,

        else the integration restarts there (order 1, history discarded), as at a breakpoint."""
        sv = self.solver
        if net is self.net and sources is self.sources and bnd.fixed_C is None and self.bnd.fixed_C is None:
            self._set(net, sources, C, bnd, a, b, sv.t - a)      # the same problem goes on: no kink
            return True
        f_old = self.rhs(sv.t, sv.y)
        self._set(net, sources, C, bnd, a, b, sv.t - a)
        f_new = self.rhs(sv.t, sv.y)
        scale = self.atol + self.rtol * np.abs(sv.y)
        return sv.step_size * np.linalg.norm((f_new - f_old) / scale) / math.sqrt(scale.size) <= 1.0

    def segment(self, net, sources, C, bnd, a, b, y0, t_eval, stop, fresh=True, until=None):
        """Integrate [a, b] of a run: (solution, finished).  ``fresh`` False: continue the integrator from
        its last state (``y0`` is that state) with this problem, its clock going on.  ``until(t, T_K)`` True after
        a step ends the segment there (its state the solution's last point)."""
        if not (fresh or self.solver is None) and self._kink_within_tolerance(net, sources, C, bnd, a, b):
            # the bound of the integration moved on: the one change of scipy's OdeSolver state a
            # continuation needs (history, step size and Jacobian are kept)
            self.solver.t_bound, self.solver.status = self.offset + b, "running"
        else:
            self._set(net, sources, C, bnd, a, b, 0.0)
            self.solver = getattr(integrate, self.method)(self.rhs, a, y0, b, jac=self.jac, rtol=self.rtol, atol=self.atol,
                                                max_step=self.max_step)
        solver = self.solver
        te = None if t_eval is None else np.union1d(t_eval[(t_eval >= a) & (t_eval <= b)], [b])
        ts, ys = [a], [np.asarray(y0, float).copy()]
        k = 1 if te is not None and te.size and te[0] == a else 0      # the next requested time to report
        while solver.status == "running":
            if stop is not None and stop():           # stopped by the caller: keep what was integrated
                return _Segment(np.array(ts), np.array(ys).T), False
            msg = solver.step()
            if solver.status == "failed":
                raise NoConvergence(f"transient integration failed at t = {solver.t - self.offset:.6g} s (segment "
                                    f"{a:g}–{b:g} s): {msg}", iterations=solver.nfev, last=solver.y)
            t_now = b if solver.status == "finished" else solver.t - self.offset
            if te is None:
                ts.append(t_now)
                ys.append(solver.y.copy())
            else:
                hi = np.searchsorted(te, t_now, side="right")
                if hi > k:                            # requested times inside the step: dense output
                    dense = solver.dense_output()
                    for t in te[k:hi]:
                        ts.append(float(t))
                        ys.append(solver.y.copy() if t == t_now else dense(t + self.offset))
                    k = hi
            if until is not None and solver.status == "running" and until(t_now, self._state(solver.t, solver.y)[1]):
                if ts[-1] != t_now:                   # the run ends at this step: its state is the last point
                    ts.append(t_now)
                    ys.append(solver.y.copy())
                return _Segment(np.array(ts), np.array(ys).T, until=True), True
        return _Segment(np.array(ts), np.array(ys).T), True


@dataclass
class _Segment:
    """Times and states (n_free·B, n_t) of one integrated segment (``until``: ended early by the run's
    ``until``, its last state kept in the output)."""

    t: np.ndarray
    y: np.ndarray
    until: bool = False


_OUTPUT_CHUNK = 512    #: output times whose sources are evaluated in one call (their losses: tens of kB per time)


def _output_pass(sources, t_all, T_all) -> dict:
    """What ``sources`` reports at the output times (name → (n_t, ...) arrays), evaluated in chunks of
    ``_OUTPUT_CHUNK`` times, so that a long log's heat-up does not hold every contact's losses at every
    output time at once."""
    if not t_all.size:
        return {}
    got = [sources(t_all[k:k + _OUTPUT_CHUNK], T_all[k:k + _OUTPUT_CHUNK])[1]
           for k in range(0, t_all.size, _OUTPUT_CHUNK)]
    return {name: np.concatenate([np.asarray(g[name], float) for g in got], axis=0) for name in got[0]}


def _collect(pieces, net, t_eval, B, nf, bnd):
    """Output times and (n_t, B, n) temperatures of the segments (each step reported once; the
    fixed nodes at their values at the output times, as the segment's integration saw them)."""
    free = ~net.fixed
    ts, Ts = [], []
    for sol, a, b in pieces:
        keep = np.ones(sol.t.size, bool) if t_eval is None else np.isin(sol.t, t_eval)
        keep[-1] |= sol.until                         # a run ended by ``until``: its last state
        tt, ys = sol.t[keep], sol.y[:, keep]
        if ts and ts[-1].size and tt.size and tt[0] == ts[-1][-1]:
            tt, ys = tt[1:], ys[:, 1:]
        T = np.broadcast_to(net.T_fixed_K, (tt.size, B, len(net.nodes))).copy()
        if bnd.fixed_C is not None:
            t_hi = np.nextafter(b, a)
            for k, t in enumerate(tt):
                T[k][:, bnd.index] = bnd.values_K(min(max(float(t), a), t_hi))
        T[:, :, free] = ys.T.reshape(tt.size, B, nf)
        ts.append(tt)
        Ts.append(T)
    n = len(net.nodes)
    if not ts:
        return np.zeros(0), np.zeros((0, B, n))
    return np.concatenate(ts), np.concatenate(Ts, axis=0)


def split_losses(P_inner_W=0.0, P_outer_W=0.0, P_drag_W=0.0, *, ball="balls", inner="inner_race",
                 outer="outer_race", oil="oil_air", extra=None) -> dict:
    r"""Map bearing losses to network nodes, conserving energy exactly.

    Parameters
    ----------
    P_inner_W, P_outer_W : array_like  loss of all inner / outer ball–race contacts [W] (a number,
                                       or one per operating point)
    P_drag_W : array_like              drag (churning) loss [W]
    ball, inner, outer, oil : str      node names receiving them
    extra : dict                       further node → loss [W] (e.g. seals, cage)

    Returns
    -------
    dict node → W: ½ of each contact loss to the ball node and ½ to its raceway node (Pouly et al.
    2010 [1]_), drag to the oil–air node; Σ sources = Σ losses.

    Examples
    --------
    >>> s = split_losses(3.0, 1.0, 0.3)
    >>> s["balls"], s["inner_race"], s["outer_race"], s["oil_air"]
    (2.0, 1.5, 0.5, 0.3)
    """
    def checked(name, v):
        a = np.asarray(v, dtype=float)
        if a.size and not (a.min() >= 0.0 and a.max() < math.inf):         # NaN fails both
            raise InputError(name, v, "losses must be finite and >= 0 [W]")
        return float(a) if a.ndim == 0 else a

    Pi, Po, Pd = checked("P_inner_W", P_inner_W), checked("P_outer_W", P_outer_W), checked("P_drag_W", P_drag_W)
    out: dict = {}

    def add(node, q):
        out[node] = out.get(node, 0.0) + q

    add(ball, 0.5 * Pi + 0.5 * Po)
    add(inner, 0.5 * Pi)
    add(outer, 0.5 * Po)
    add(oil, Pd)
    for k, v in (extra or {}).items():
        add(k, checked(f"extra.{k}", v))
    return out
