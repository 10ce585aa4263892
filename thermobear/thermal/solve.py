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
from functools import lru_cache
from typing import Callable

import numpy as np
import scipy.sparse as sp
from scipy.integrate import solve_ivp
from scipy.linalg.lapack import dgeev, dgesv
from scipy.sparse.linalg import spsolve

from thermobear.errors import InputError, NoConvergence
from thermobear.thermal.network import ThermalNetwork

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
        k = net.index.get(name)
        if k is None:
            raise InputError("sources", name, f"unknown node; nodes: {', '.join(net.nodes)}")
        if net.fixed[k]:
            raise InputError(f"sources.{name}", q, "heat cannot be injected into a fixed-temperature node")
        q = q if type(q) is float else float(np.sum(q))
        if not math.isfinite(q):
            raise InputError(f"sources.{name}", q, "must be a finite heat flow [W]")
        P[k] += q
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
    plan = _plan(net)
    G = plan.conductances(T_K) if G is None else np.asarray(G, dtype=float)
    return plan.csr(G), G


_DENSE_MAX = 400      # networks up to this many nodes are solved with dense LU (faster than sparse there)


class _Plan:
    """Index structure of a network's conductance matrix and its temperature-independent
    conductances, computed once per network (private; :func:`_plan` rebuilds it when the
    elements or their parameters are replaced).

    A = Σ_e G_e B_e with fixed 0/±1 patterns B_e (conductive elements symmetric, advective ones
    upwind), so assembling is one weighted ``bincount`` over precomputed positions.  Elements
    whose conductance depends on temperature are re-evaluated only when the temperatures of the
    nodes they depend on change (``Element._T_nodes``); the harris-type convections sharing a fluid
    node share one evaluation of the fluid properties (``Convection._harris_props``).
    """

    def __init__(self, net: ThermalNetwork):
        els = net.elements
        n = len(net.nodes)
        self.n, self.elements = n, els
        self.key = _plan_key(net)
        (self.eidx, self.sign, self.flat, self.inv, self.nnz, self.indices, self.indptr, self.free,
         self.fixed) = _pattern(n, tuple((e.i, e.j, bool(e.advective)) for e in els), net.fixed.tobytes())
        self.dep = [k for k, e in enumerate(els) if e.T_dependent]
        self.nodes_of = {k: tuple(els[k]._T_nodes()) for k in self.dep}
        self._dep_items = [(k, els[k], self.nodes_of[k]) for k in self.dep]
        # node → the temperature-dependent elements whose conductance it changes (dconductances)
        self._users = {m: [k for k in self.dep if m in self.nodes_of[k]]
                       for m in sorted({m for k in self.dep for m in self.nodes_of[k]})}
        # positions of the free × free and free × fixed blocks in the flattened dense matrix
        self._ff = (self.free[:, None] * n + self.free[None, :]).ravel()
        self._fb = (self.free[:, None] * n + self.fixed[None, :]).ravel()
        self._fpos = [-1] * n                   # node → position among the free nodes (−1: fixed)
        for q, m in enumerate(self.free.tolist()):
            self._fpos[m] = q
        T0 = net.initial_T_K()
        self.G0 = np.array([0.0 if k in self.dep else e.conductance(T0) for k, e in enumerate(els)], dtype=float)
        self.memo: dict = {}

    def conductances(self, T_K) -> np.ndarray:
        """Conductance of every element [W/K] at node temperatures ``T_K`` [K] (as
        ``net.conductances``)."""
        if not self.dep:
            return self.G0.copy()
        T = np.asarray(T_K, dtype=float).tolist()      # the elements read single temperatures: floats
        G = self.G0.copy()
        shared: dict = {}
        memo = self.memo
        for k, e, nodes in self._dep_items:
            key = tuple([T[m] for m in nodes])
            hit = memo.get(k)
            if hit is not None and hit[0] == key:
                G[k] = hit[1]
                continue
            g = float(e._conductance_shared(T, shared))
            memo[k] = (key, g)
            G[k] = g
        return G

    def dconductances(self, T_K, h_K: float = 1e-3, nodes=None):
        """Conductances G [W/K] and their forward-difference derivatives with respect to the
        temperatures of the nodes each element depends on: list of (element, node, dG/dT [W/K²]);
        ``nodes`` (indices) restricts the derivatives to those nodes (e.g. the free ones: a Newton
        step on the free temperatures needs no derivative by a fixed one)."""
        T = np.asarray(T_K, dtype=float).tolist()
        G = self.conductances(T)
        out = []
        want = None if nodes is None else {int(m) for m in nodes}
        els = self.elements
        for m, users in self._users.items():
            if want is not None and m not in want:
                continue
            Tp = list(T)
            Tp[m] += h_K
            shared: dict = {}                     # one property evaluation per perturbed node
            for k in users:
                g = float(els[k]._conductance_shared(Tp, shared))
                out.append((k, m, (g - G[k]) / h_K))
        return G, out

    def dAT(self, T_K, dG) -> np.ndarray:
        """∂(A(T) T)/∂T from the conductances' temperature dependence (n×n, dense) [W/K]:
        ``dG`` as returned by :meth:`dconductances`."""
        T = np.asarray(T_K, dtype=float)
        D = np.zeros((self.n, self.n))
        for k, m, d in dG:
            e = self.elements[k]
            if e.advective:
                D[e.j, m] += d * (T[e.j] - T[e.i])
            else:
                D[e.i, m] += d * (T[e.i] - T[e.j])
                D[e.j, m] += d * (T[e.j] - T[e.i])
        return D

    def dAT_free(self, T_K, dG) -> np.ndarray:
        """The free × free block of :meth:`dAT` (``dG`` with derivatives by free nodes only, as
        ``dconductances(..., nodes=self.free)`` gives them), built directly [W/K]."""
        T = np.asarray(T_K, dtype=float).tolist()
        fpos = self._fpos
        nf = self.free.size
        D = np.zeros((nf, nf))
        els = self.elements
        for k, m, d in dG:
            e = els[k]
            c = fpos[m]
            if c < 0:                           # a derivative by a fixed node: not in this block
                continue
            if e.advective:
                r = fpos[e.j]
                if r >= 0:
                    D[r, c] += d * (T[e.j] - T[e.i])
            else:
                r = fpos[e.i]
                if r >= 0:
                    D[r, c] += d * (T[e.i] - T[e.j])
                r = fpos[e.j]
                if r >= 0:
                    D[r, c] += d * (T[e.j] - T[e.i])
        return D

    def values(self, G):
        """Contributions of the elements to the matrix entries (pattern ``self.flat``)."""
        return self.sign * G[self.eidx]

    def dense(self, G) -> np.ndarray:
        """Full conductance matrix A (n×n, dense) for conductances G."""
        n = self.n
        return np.bincount(self.flat, self.values(G), minlength=n * n).reshape(n, n)

    def csr(self, G):
        """Full conductance matrix A (n×n, CSR) for conductances G."""
        data = np.bincount(self.inv, self.values(G), minlength=self.nnz)
        return sp.csr_matrix((data, self.indices.copy(), self.indptr.copy()), shape=(self.n, self.n))

    def blocks(self, G):
        """(A_ff, A_fb) blocks, free × free and free × fixed: dense arrays for networks up to
        ``_DENSE_MAX`` nodes, else sparse (CSC / CSR)."""
        if self.n <= _DENSE_MAX:
            A = np.bincount(self.flat, self.values(G), minlength=self.n * self.n)
            nf = self.free.size
            return A[self._ff].reshape(nf, nf), A[self._fb].reshape(nf, self.fixed.size)
        A = self.csr(G)
        return A[self.free][:, self.free].tocsc(), A[self.free][:, self.fixed]


@lru_cache(maxsize=64)
def _pattern(n, ija, fixed_bytes):
    """Index structure of the conductance matrix of a topology (n nodes; elements (i, j, advective);
    the fixed-node mask): cached, because networks are rebuilt for every operating point."""
    i = np.array([t[0] for t in ija], dtype=int)
    j = np.array([t[1] for t in ija], dtype=int)
    adv = np.array([t[2] for t in ija], dtype=bool)
    ks, ka = np.flatnonzero(~adv), np.flatnonzero(adv)
    rows = np.concatenate([i[ks], j[ks], i[ks], j[ks], j[ka], j[ka]])
    cols = np.concatenate([i[ks], j[ks], j[ks], i[ks], j[ka], i[ka]])
    eidx = np.concatenate([ks, ks, ks, ks, ka, ka])
    sign = np.concatenate([np.ones(2 * ks.size), -np.ones(2 * ks.size), np.ones(ka.size), -np.ones(ka.size)])
    flat = rows * n + cols
    uniq, inv = np.unique(flat, return_inverse=True)
    ur, uc = np.divmod(uniq, n)
    indptr = np.searchsorted(ur, np.arange(n + 1)).astype(np.int32)
    fixed = np.frombuffer(fixed_bytes, dtype=bool)
    out = (eidx, sign, flat, inv, uniq.size, uc.astype(np.int32), indptr, np.flatnonzero(~fixed),
           np.flatnonzero(fixed))
    for a in out:
        if isinstance(a, np.ndarray):
            a.setflags(write=False)          # shared between networks of one topology
    return out


def _plan_key(net):
    els = net.elements
    return (id(els), len(els), len(net.nodes), net.fixed.tobytes(),
            tuple((id(e), e.i, e.j, id(e.p), tuple(map(id, e.p.values()))) for e in els))


def _plan(net) -> _Plan:
    """The cached :class:`_Plan` of a network (rebuilt when its elements changed)."""
    plan = net.__dict__.get("_tb_plan")
    if plan is None or plan.key != _plan_key(net):
        plan = _Plan(net)
        net.__dict__["_tb_plan"] = plan
    return plan


def _dense_solve(A, b):
    """x with A x = b (LAPACK gesv: LU with partial pivoting, as ``numpy.linalg.solve``, called
    directly: the networks' matrices are small and the wrapper's overhead is most of the cost);
    None when A is singular."""
    lu, piv, x, info = dgesv(A, b)
    return None if info else x


def _max_real_eigenvalue(M) -> float:
    """Largest real part of the eigenvalues of a small dense matrix (LAPACK geev, as
    ``numpy.linalg.eigvals``); NaN when M is not finite or the eigenvalues do not converge."""
    if not np.isfinite(M).all():
        return math.nan
    wr, wi, vl, vr, info = dgeev(M, compute_vl=0, compute_vr=0)
    return math.nan if info else float(wr.max())


def _lin_solve(Aff, rhs):
    """Solve A_ff x = rhs (dense LU or sparse LU); non-finite result when A_ff is singular."""
    if isinstance(Aff, np.ndarray):
        x = _dense_solve(Aff, rhs)
        return np.full(np.shape(rhs), np.nan) if x is None else x
    return spsolve(Aff, rhs)


def _flows(net, T, G):
    out = {}
    T = T.tolist()
    for e, g in zip(net.elements, G.tolist()):
        Q = g * (T[e.j] - T[e.i]) if e.advective else g * (T[e.i] - T[e.j])
        out[e.name] = Flow(e.name, e.type, e.nodes, Q, g)
    return out


def _heat_out(net, flows):
    """Heat leaving the free part of the network: into each fixed node, and into the stream."""
    out = {}
    fixed = net.fixed.tolist()
    for e in net.elements:
        f = flows[e.name]
        fi, fj = fixed[e.i], fixed[e.j]
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
    P = np.asarray(P, dtype=float).tolist()
    bal = math.fsum(P) - total_out
    scale = math.fsum([abs(q) for q in P]) or math.fsum(abs(f.Q_W) for f in flows.values()) or 1.0
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
    plan = _plan(net)
    for it in range(1, max_iter + 1):
        G = plan.conductances(T)
        Aff, Afb = plan.blocks(G)
        rhs = P[free] - Afb @ T[fixed]
        Tf = np.atleast_1d(_lin_solve(Aff, rhs))
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
        G = plan.conductances(T)
        Aff, Afb = plan.blocks(G)
        T = T.copy()
        T[free] = np.atleast_1d(_lin_solve(Aff, P[free] - Afb @ T[fixed]))
    flows = _flows(net, T, G)
    bal, rel = _balance(net, P[free], flows)
    Tl, Pl = (T - _C0).tolist(), P.tolist()
    return SteadyResult(T_C=dict(zip(net.nodes, Tl)), T_K=T,
                        flows=flows, sources_W={n: q for n, q in zip(net.nodes, Pl) if q},
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
                                (e.g. the loss breakdown).  A callable may carry an
                                attribute ``_batch(t_array, T_K_arrays) -> (list of dicts,
                                dict of arrays)`` giving the same for all output times at
                                once; the output pass then calls it instead of the loop
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
    Jacobian −C⁻¹A_ff (dense up to 400 nodes, else sparse; dP/dT and dG/dT neglected
    in it, which only affects the Newton iterations of the implicit scheme, not the
    solution: including them was tried and saved only 6 % of the evaluations).

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
    plan = _plan(net)
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
            Aff, Afb = plan.blocks(plan.conductances(Tfull))
            P, _ = _call_sources(sources, min(max(t, a), t_hi), Tfull, net)
            return (P[free] - Aff @ yf - Afb @ Tfull[fixed]) / C

        def jac(t, yf, Tfull=Tfull):
            Tfull[free] = yf
            Aff, _ = plan.blocks(plan.conductances(Tfull))
            if isinstance(Aff, np.ndarray):
                return -Aff / C[:, None]
            return sp.diags(1.0 / C) @ (-Aff)

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
    batch = getattr(sources, "_batch", None) if callable(sources) else None
    if batch is not None and t_all.size:
        # the callback can evaluate all output times at once (one vectorised loss evaluation)
        srcs, reps = batch(t_all, {n: T_all[k] for k, n in enumerate(net.nodes)})
        for k, src in enumerate(srcs):
            P = sources_vector(net, src)
            for n in net.free_nodes:
                src_series[n][k] = P[net.index[n]]
        report = {key: np.asarray(v, dtype=float) for key, v in reps.items()}
    else:
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
        if a.size and not (a.min() >= 0.0 and a.max() < math.inf):         # NaN fails both
            raise InputError(k, v, "losses must be finite and >= 0 [W]")
        arr[k] = a.ravel().tolist()
    Pi, Po = math.fsum(arr["P_inner_W"]), math.fsum(arr["P_outer_W"])
    out: dict = {}

    def add(node, q):
        out[node] = out.get(node, 0.0) + q

    add(ball, 0.5 * Pi + 0.5 * Po)
    add(inner, 0.5 * Pi)
    add(outer, 0.5 * Po)
    add(oil, math.fsum(arr["P_drag_W"]))
    for k, v in (extra or {}).items():
        add(k, math.fsum(arr[f"extra.{k}"]))
    total_losses = math.fsum(math.fsum(a) for a in arr.values())
    total_sources = math.fsum(out.values())
    if abs(total_sources - total_losses) > 1e-12 * max(total_losses, 1e-300):
        raise RuntimeError(f"heat split does not conserve energy: sources {total_sources!r} W "
                           f"≠ losses {total_losses!r} W")
    return out
