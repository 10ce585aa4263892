r"""Steady and transient solution of a thermal network, and the loss → node split.

Steady state (PHYSICS.md §8 "Solving"): the conductance matrix A (sparse) of
the free nodes f and fixed nodes b gives

    A_ff T_f = P_f − A_fb T_b,

with conductive elements symmetric (A_ii += G, A_jj += G, A_ij = A_ji −= G)
and advective ones one-way (upwind: only the downstream row d gets
A_dd += G, A_du −= G).  Temperature-dependent elements (free and forced
convection, radiation, fluid properties) are updated in an outer Picard loop
until max |ΔT| < tol_K.

Transient: C_f dT_f/dt = P_f(t, T) − A_ff(T) T_f − A_fb(T) T_b(t), integrated
with scipy's BDF (stiff) with the sparse Jacobian −C⁻¹A_ff, restarted at
every schedule breakpoint so that steps in the inputs are not smeared.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np
import scipy.sparse as sp
from scipy.integrate import solve_ivp
from scipy.sparse.linalg import spsolve

from ..errors import InputError, NoConvergence
from .network import ThermalNetwork

__all__ = ["SteadyResult", "TransientResult", "Flow", "solve_steady", "solve_transient",
           "assemble", "split_losses", "sources_vector"]

_C0 = 273.15


@dataclass(frozen=True)
class Flow:
    """Heat flow through one element.

    Q_W is signed along the element's ``between`` order: for conduction,
    convection and radiation the heat going from ``nodes[0]`` to ``nodes[1]``;
    for advection (``nodes = (upstream, downstream)``) the heat the stream
    carries away from the downstream node, G (T_down − T_up).  ``from_node`` /
    ``to_node`` give the physical direction with ``abs(Q_W)``.
    """

    element: str
    type: str
    nodes: tuple
    Q_W: float
    G_W_K: float

    @property
    def from_node(self) -> str:
        """Node the heat leaves."""
        if self.type == "advection":
            return self.nodes[1] if self.Q_W >= 0 else "stream"
        return self.nodes[0] if self.Q_W >= 0 else self.nodes[1]

    @property
    def to_node(self) -> str:
        """Node the heat enters (``"stream"``: carried away by the oil)."""
        if self.type == "advection":
            return "stream" if self.Q_W >= 0 else self.nodes[1]
        return self.nodes[1] if self.Q_W >= 0 else self.nodes[0]


@dataclass
class SteadyResult:
    """Steady temperatures, flows and energy balance.

    Attributes
    ----------
    T_C : dict              node → temperature [°C]
    T_K : ndarray           temperatures of all nodes in ``network.nodes`` order [K]
    flows : dict            element name → :class:`Flow`
    sources_W : dict        node → heat injected [W]
    balance_W : float       Σ sources − Σ heat leaving to fixed nodes and the oil stream [W]
    balance_rel : float     |balance_W| / Σ|sources| (or / Σ|flows| without sources)
    iterations : int        outer-loop iterations (1 for a linear network)
    residual_K : float      last max |ΔT| of the outer loop [K]
    network : ThermalNetwork
    """

    T_C: dict
    T_K: np.ndarray
    flows: dict
    sources_W: dict
    balance_W: float
    balance_rel: float
    iterations: int
    residual_K: float
    network: ThermalNetwork = field(repr=False)

    @property
    def heat_out_W(self) -> dict:
        """Heat leaving into each fixed node and into the oil stream [W]."""
        return _heat_out(self.network, self.flows)


@dataclass
class TransientResult:
    """Time series of a transient run.

    Attributes
    ----------
    t : ndarray        output times [s]
    T_K : ndarray      node temperatures, shape (n_nodes, n_t) [K]
    T_C : dict         node → temperatures [°C]
    sources_W : dict   node → injected heat [W] at the output times
    report : dict      name → series of whatever the sources callback reported
    nfev : int         right-hand-side evaluations
    network : ThermalNetwork
    """

    t: np.ndarray
    T_K: np.ndarray
    T_C: dict
    sources_W: dict
    report: dict
    nfev: int
    network: ThermalNetwork = field(repr=False)


def sources_vector(net: ThermalNetwork, sources_W) -> np.ndarray:
    """Heat sources as a vector over ``net.nodes`` [W] (unknown or fixed nodes → InputError)."""
    P = np.zeros(len(net.nodes))
    for name, q in (sources_W or {}).items():
        if name not in net.index:
            raise InputError("sources", name, f"unknown node; nodes: {', '.join(net.nodes)}")
        if net.fixed[net.index[name]]:
            raise InputError(f"sources.{name}", q, "heat cannot be injected into a fixed-temperature node")
        q = float(np.sum(q))
        if not math.isfinite(q):
            raise InputError(f"sources.{name}", q, "must be a finite heat flow [W]")
        P[net.index[name]] += q
    return P


def assemble(net: ThermalNetwork, T_K, G=None):
    """Sparse conductance matrix A (n×n, CSR) and element conductances G [W/K].

    Heat balance of node r: Σ_c A_rc T_c = P_r (net injected heat).

    >>> import numpy as np
    >>> from thermobear.thermal.network import load_network
    >>> net = load_network({"nodes": {"a": {"C_J_K": 1.0}, "amb": {"T_C": 20.0}},
    ...     "elements": [{"type": "conductance", "between": ["a", "amb"], "G_W_K": 2.0}]})
    >>> A, G = assemble(net, net.initial_T_K())
    >>> A.toarray()
    array([[ 2., -2.],
           [-2.,  2.]])
    """
    G = net.conductances(T_K) if G is None else G
    i = np.array([e.i for e in net.elements])
    j = np.array([e.j for e in net.elements])
    adv = np.array([e.advective for e in net.elements])
    sym = ~adv
    rows = np.concatenate([i[sym], j[sym], i[sym], j[sym], j[adv], j[adv]])
    cols = np.concatenate([i[sym], j[sym], j[sym], i[sym], j[adv], i[adv]])
    vals = np.concatenate([G[sym], G[sym], -G[sym], -G[sym], G[adv], -G[adv]])
    n = len(net.nodes)
    return sp.csr_matrix((vals, (rows, cols)), shape=(n, n)), G


def _flows(net, T, G):
    out = {}
    for e, g in zip(net.elements, G):
        Q = g * (T[e.j] - T[e.i]) if e.advective else g * (T[e.i] - T[e.j])
        out[e.name] = Flow(e.name, e.type, e.nodes, float(Q), float(g))
    return out


def _heat_out(net, flows):
    """Heat leaving the free part of the network: into each fixed node, and into the stream."""
    out = {}
    for e in net.elements:
        f = flows[e.name]
        fi, fj = net.fixed[e.i], net.fixed[e.j]
        if e.advective:
            if not fj:
                out["stream"] = out.get("stream", 0.0) + f.Q_W
        elif fi != fj:
            fixed_node = e.nodes[1] if fj else e.nodes[0]
            q = f.Q_W if fj else -f.Q_W
            out[fixed_node] = out.get(fixed_node, 0.0) + q
    return out


def _balance(net, P, flows):
    out = _heat_out(net, flows)
    total_out = math.fsum(out.values())
    bal = math.fsum(P) - total_out
    scale = math.fsum(np.abs(P)) or math.fsum(abs(f.Q_W) for f in flows.values()) or 1.0
    return bal, abs(bal) / scale


def solve_steady(net: ThermalNetwork, sources_W=None, *, T_guess_K=None, tol_K: float = 1e-8,
                 max_iter: int = 200, relax: float = 1.0, linearized: bool = False) -> SteadyResult:
    r"""Steady temperatures of a thermal network.

    Parameters
    ----------
    net : ThermalNetwork
    sources_W : dict            free node → injected heat [W] (arrays are summed)
    T_guess_K : array_like      start of the outer loop (default: free nodes at the
                                mean fixed temperature)
    tol_K : float               outer-loop tolerance on max |ΔT| [K]
    max_iter : int              outer-loop budget
    relax : float               under-relaxation of the outer loop, 0 < relax ≤ 1
    linearized : bool           one linear solve with the conductances at ``T_guess_K`` (no outer
                                loop): for callers that iterate anyway (the coupled fixed point
                                converges conductances and losses together); the energy balance
                                still closes exactly with those conductances

    Returns
    -------
    SteadyResult  (energy balance closes to machine precision: the flows are
    computed with the conductances of the final linear solve)

    Raises
    ------
    NoConvergence  when the outer loop (temperature-dependent elements) does
                   not reach tol_K within max_iter

    Notes
    -----
    A_ff T_f = P_f − A_fb T_b (PHYSICS.md §8 "Solving"); sparse LU (scipy).

    Examples
    --------
    >>> from thermobear.thermal.network import load_network
    >>> net = load_network({"nodes": {"a": {}, "amb": {"T_C": 20.0}},
    ...     "elements": [{"type": "conductance", "between": ["a", "amb"], "G_W_K": 2.0}]})
    >>> r = solve_steady(net, {"a": 100.0})
    >>> round(r.T_C["a"], 9), r.flows["a--amb"].Q_W, r.balance_rel < 1e-12
    (70.0, 100.0, True)
    """
    if not 0 < relax <= 1:
        raise InputError("relax", relax, "under-relaxation must lie in (0, 1]")
    P = sources_vector(net, sources_W)
    free, fixed = ~net.fixed, net.fixed
    T = net.initial_T_K() if T_guess_K is None else np.array(T_guess_K, dtype=float)
    T[fixed] = net.T_fixed_K[fixed]
    history = []
    it, res = 0, float("inf")
    for it in range(1, max_iter + 1):
        A, G = assemble(net, T)
        Aff = A[free][:, free].tocsc()
        rhs = P[free] - A[free][:, fixed] @ T[fixed]
        Tf = np.atleast_1d(spsolve(Aff, rhs))
        if not np.all(np.isfinite(Tf)):
            raise NoConvergence("singular conductance matrix (a node without conductance?)",
                                iterations=it, last=T.copy(), history=history)
        Tnew = T.copy()
        Tnew[free] = T[free] + relax * (Tf - T[free])
        res = float(np.max(np.abs(Tnew[free] - T[free]))) if free.any() else 0.0
        history.append(res)
        T = Tnew
        if not net.T_dependent or linearized:
            res = 0.0 if not net.T_dependent else res   # linear network: one exact solve
            break
        if res < tol_K:
            break
    else:
        raise NoConvergence(f"steady outer loop: max |ΔT| = {res:.3g} K after {max_iter} iterations "
                            f"(tolerance {tol_K:g} K)", iterations=max_iter, residual=res,
                            last=T.copy(), history=history)
    if (relax < 1 or net.T_dependent) and not linearized:
        # final consistent linear solve with the converged conductances
        A, G = assemble(net, T)
        T = T.copy()
        T[free] = np.atleast_1d(spsolve(A[free][:, free].tocsc(), P[free] - A[free][:, fixed] @ T[fixed]))
    flows = _flows(net, T, G)
    bal, rel = _balance(net, P[free], flows)
    return SteadyResult(T_C={n: float(T[k] - _C0) for k, n in enumerate(net.nodes)}, T_K=T,
                        flows=flows, sources_W={n: float(P[k]) for k, n in enumerate(net.nodes) if P[k]},
                        balance_W=bal, balance_rel=rel, iterations=it, residual_K=res, network=net)


def _call_sources(sources, t, T, net):
    out = sources(t, {n: float(T[k]) for k, n in enumerate(net.nodes)}) if callable(sources) else sources
    if isinstance(out, tuple):
        src, rep = out
    else:
        src, rep = out, {}
    return sources_vector(net, src), rep


def solve_transient(net: ThermalNetwork, sources, t_end: float, *, T0_C=None,
                    breakpoints=(), fixed_C: Callable | None = None, t_eval=None,
                    rtol: float = 1e-8, atol: float = 1e-8, method: str = "BDF",
                    max_step: float = np.inf) -> TransientResult:
    r"""Transient temperatures of a thermal network.

    Parameters
    ----------
    net : ThermalNetwork        every free node needs a heat capacity C [J/K]
    sources : dict or callable  node → W, or ``sources(t, T_K) -> dict`` or
                                ``-> (dict, report)`` with ``T_K`` a dict node → K
                                and ``report`` a dict of numbers to record
                                (e.g. the loss breakdown)
    t_end : float               end time [s]
    T0_C : float, dict or None  initial temperature of the free nodes [°C]; None:
                                the fixed node ``ambient`` (else the mean fixed T)
    breakpoints : sequence      times [s] where inputs step (integration restarts there;
                                inside a segment [a, b) the callbacks see t < b, so a step
                                at b never leaks into the segment before it; reported
                                series are right-continuous: at t = b they show the new inputs)
    fixed_C : callable          optional ``fixed_C(t) -> dict`` fixed node → °C
                                (piecewise constant between breakpoints)
    t_eval : array_like         output times [s] (default: the integrator's steps)
    rtol, atol : float          integrator tolerances (atol in K)
    method : str                ``"BDF"`` or ``"Radau"``

    Returns
    -------
    TransientResult

    Notes
    -----
    C_f dT_f/dt = P_f(t,T) − A_ff(T) T_f − A_fb(T) T_b(t) (PHYSICS.md §8);
    Jacobian −C⁻¹A_ff (sparse; dP/dT and dG/dT neglected in it, which only
    affects the Newton iterations of the implicit scheme, not the solution).

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
    free, fixed = ~net.fixed, net.fixed
    C = net.C_J_K[free]
    if np.any(~np.isfinite(C) | (C <= 0)):
        bad = [n for n, c in zip(net.free_nodes, C) if not (np.isfinite(c) and c > 0)]
        raise InputError(f"{net.source}: nodes.{bad[0]}.C_J_K", None,
                         "the transient needs a heat capacity (C_J_K, or mass_kg/volume_m3 with a material)")
    bps = sorted({float(b) for b in breakpoints if 0 < float(b) < t_end})
    edges = [0.0, *bps, float(t_end)]

    T = net.T_fixed_K.copy()
    if T0_C is None:
        T0 = T[net.index["ambient"]] if "ambient" in net.index and fixed[net.index["ambient"]] \
            else net.T_fixed_K[fixed].mean()
        T[free] = T0
    elif isinstance(T0_C, dict):
        T[free] = net.T_fixed_K[fixed].mean()
        for name, v in T0_C.items():
            if name not in net.index or fixed[net.index[name]]:
                raise InputError("T0_C", name, "a free node name")
            T[net.index[name]] = float(v) + _C0
    else:
        T[free] = float(T0_C) + _C0

    def fixed_at(t):
        Tb = net.T_fixed_K.copy()
        if fixed_C is not None:
            for name, v in fixed_C(t).items():
                if name not in net.index or not fixed[net.index[name]]:
                    raise InputError("fixed_C", name, "a fixed node name")
                Tb[net.index[name]] = float(v) + _C0
        return Tb

    nfev = [0]
    t_eval = None if t_eval is None else np.asarray(t_eval, dtype=float)
    ts, Ys = [], []
    y = T[free].copy()
    for a, b in zip(edges[:-1], edges[1:]):
        Tb = fixed_at(0.5 * (a + b))          # piecewise constant over the segment
        Tfull = Tb.copy()
        t_hi = np.nextafter(b, a)             # inputs of [a, b): the step at b belongs to the next segment

        def rhs(t, yf, Tfull=Tfull, a=a, t_hi=t_hi):
            nfev[0] += 1
            Tfull[free] = yf
            A, _ = assemble(net, Tfull)
            P, _ = _call_sources(sources, min(max(t, a), t_hi), Tfull, net)
            return (P[free] - A[free] @ Tfull) / C

        def jac(t, yf, Tfull=Tfull):
            Tfull[free] = yf
            A, _ = assemble(net, Tfull)
            return sp.diags(1.0 / C) @ (-A[free][:, free])

        te_req = None if t_eval is None else t_eval[(t_eval >= a) & (t_eval <= b)]
        te = None if te_req is None else np.union1d(te_req, [b])
        sol = solve_ivp(rhs, (a, b), y, method=method, jac=jac, rtol=rtol, atol=atol,
                        t_eval=te, max_step=max_step)
        if not sol.success:
            t_fail = sol.t[-1] if sol.t.size else a
            raise NoConvergence(f"transient integration failed at t = {t_fail:.6g} s (segment {a:g}–{b:g} s): "
                                f"{sol.message}",
                                iterations=sol.nfev, last=sol.y[:, -1] if sol.y.size else y)
        y = sol.y[:, -1].copy()
        keep = np.ones(sol.t.size, bool) if te_req is None else np.isin(sol.t, te_req)
        tt, ys = sol.t[keep], sol.y[:, keep]
        if ts and ts[-1].size and tt.size and tt[0] == ts[-1][-1]:
            tt, ys = tt[1:], ys[:, 1:]
        ts.append(tt)
        Ys.append((ys, Tb))

    t_all = np.concatenate(ts) if ts else np.array([])
    T_all = np.concatenate([np.where(free[:, None], np.zeros((len(net.nodes), y_.shape[1])), Tb[:, None])
                            for y_, Tb in Ys], axis=1)
    T_all[free] = np.concatenate([y_ for y_, _ in Ys], axis=1)
    src_series = {n: np.zeros(t_all.size) for n in net.free_nodes}
    report: dict = {}
    for k, t in enumerate(t_all):
        P, rep = _call_sources(sources, t, T_all[:, k], net)
        for n in net.free_nodes:
            src_series[n][k] = P[net.index[n]]
        for key, v in rep.items():
            report.setdefault(key, np.full(t_all.size, np.nan))[k] = v
    return TransientResult(t=t_all, T_K=T_all, T_C={n: T_all[k] - _C0 for k, n in enumerate(net.nodes)},
                           sources_W=src_series, report=report, nfev=nfev[0], network=net)


def split_losses(P_inner_W=0.0, P_outer_W=0.0, P_drag_W=0.0, *, ball="balls", inner="inner_race",
                 outer="outer_race", oil="oil_air", extra=None) -> dict:
    r"""Map bearing losses to network nodes, conserving energy exactly.

    Parameters
    ----------
    P_inner_W, P_outer_W : array_like  loss at each inner / outer ball–race contact
                                       (any shape, e.g. per ball) [W]
    P_drag_W : array_like              drag (churning) loss [W]
    ball, inner, outer, oil : str      node names receiving them
    extra : dict                       further node → loss [W] (e.g. seals, cage)

    Returns
    -------
    dict node → W: ½ of each contact loss to the ball node and ½ to its
    raceway node (Pouly 2010 convention, PHYSICS.md §8 "Heat sources"), drag
    to the oil–air node.  Σ sources = Σ losses is checked (pitfall 13).

    Examples
    --------
    >>> s = split_losses([1.0, 2.0], [0.5, 0.5], 0.3)
    >>> s["balls"], s["inner_race"], s["outer_race"], s["oil_air"]
    (2.0, 1.5, 0.5, 0.3)
    """
    parts = {"P_inner_W": P_inner_W, "P_outer_W": P_outer_W, "P_drag_W": P_drag_W}
    parts.update({f"extra.{k}": v for k, v in (extra or {}).items()})
    arr = {}
    for k, v in parts.items():
        a = np.asarray(v, dtype=float)
        if np.any(~np.isfinite(a) | (a < 0)):
            raise InputError(k, v, "losses must be finite and >= 0 [W]")
        arr[k] = a
    Pi, Po = math.fsum(arr["P_inner_W"].ravel()), math.fsum(arr["P_outer_W"].ravel())
    out: dict = {}

    def add(node, q):
        out[node] = out.get(node, 0.0) + q

    add(ball, 0.5 * Pi + 0.5 * Po)
    add(inner, 0.5 * Pi)
    add(outer, 0.5 * Po)
    add(oil, math.fsum(arr["P_drag_W"].ravel()))
    for k, v in (extra or {}).items():
        add(k, math.fsum(arr[f"extra.{k}"].ravel()))
    total_losses = math.fsum(math.fsum(a.ravel()) for a in arr.values())
    total_sources = math.fsum(out.values())
    if abs(total_sources - total_losses) > 1e-12 * max(total_losses, 1e-300):
        raise RuntimeError(f"heat split does not conserve energy: sources {total_sources!r} W "
                           f"≠ losses {total_losses!r} W")
    return out
