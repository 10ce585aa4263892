"""A thermal network at B operating points: conductances, matrices and their derivatives as arrays.

Built by :meth:`thermobear.thermal.network.NetworkTemplate.at`; every per-point quantity has a
leading axis of length B, so that the steady and transient solvers treat many operating points
with stacked matrices.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from thermobear.errors import InputError

__all__ = ["ThermalNetwork", "Structure"]


@dataclass(frozen=True)
class ThermalNetwork:
    """A network at B operating points (build it with :meth:`NetworkTemplate.at` or :func:`load_network`).

    Attributes
    ----------
    template : NetworkTemplate
    B : int                   number of operating points (leading axis of every per-point array)
    T_fixed_K : ndarray       (B, n) fixed-node temperatures [K] (free entries 0)
    elements : tuple          the elements, parameters numbers or arrays over the B points
    oil : Lubricant or None   the lubricant (fluid properties of convection and advection)
    structure : Structure    matrix pattern, temperature dependence, the constant conductances
    C_points : ndarray        (B, n) heat capacities [J/K] when they differ per point (drawn values of an
                              uncertainty run), else None: the template's
    """

    template: object
    B: int
    T_fixed_K: np.ndarray
    elements: tuple
    oil: object = None
    structure: "Structure" = None
    C_points: np.ndarray = None

    # -- the template's structure -------------------------------------------------------------
    name = property(lambda self: self.template.name)
    nodes = property(lambda self: list(self.template.nodes))
    index = property(lambda self: self.template.index)
    fixed = property(lambda self: self.template.fixed)
    C_J_K = property(lambda self: self.template.C_J_K if self.C_points is None else self.C_points,
                     doc="heat capacities [J/K]: (n,), or (B, n) when they differ per operating point")
    estimated = property(lambda self: self.template.estimated)
    source = property(lambda self: self.template.source)
    free_nodes = property(lambda self: self.template.free_nodes)
    fixed_nodes = property(lambda self: self.template.fixed_nodes)

    @property
    def T_dependent(self) -> bool:
        """True when some element conductance depends on a free node's temperature."""
        return bool(self.structure.dep)

    def initial_T_K(self) -> np.ndarray:
        """(B, n) node temperatures with every free node at its point's mean fixed temperature [K]."""
        T = self.T_fixed_K.copy()
        T[:, ~self.fixed] = self.T_fixed_K[:, self.fixed].mean(axis=1, keepdims=True)
        return T

    def conductances(self, T_K) -> np.ndarray:
        """(B, n_elements) conductances [W/K] at node temperatures ``T_K`` (B, n) [K]."""
        s = self.structure
        G = s.G0.copy()
        shared: dict = {}
        for k in s.dep:
            e = self.elements[k]
            G[:, k] = e.conductance(T_K[:, e.i], T_K[:, e.j], self.oil, shared)
        return G

    def dconductances(self, T_K, h_K: float = 1e-3):
        """Conductances G (B, n_el) [W/K] and their forward-difference derivatives by the free nodes
        each temperature-dependent element depends on: list of (element, node, dG/dT (B,) [W/K²])."""
        s = self.structure
        G = self.conductances(T_K)
        out = []
        for m, users in s.users.items():
            Tp = T_K.copy()
            Tp[:, m] += h_K
            shared: dict = {}
            for k in users:
                e = self.elements[k]
                out.append((k, m, (e.conductance(Tp[:, e.i], Tp[:, e.j], self.oil, shared) - G[:, k]) / h_K))
        return G, out

    def matrix(self, G) -> np.ndarray:
        """(B, n, n) conductance matrices: node r's balance Σ_c A_rc T_c = P_r [W/K]."""
        n = len(self.template.nodes)
        return (G @ self.structure.pattern).reshape(self.B, n, n)

    def blocks(self, G):
        """(A_ff, A_fb): the free × free (B, nf, nf) and free × fixed (B, nf, nb) blocks [W/K]."""
        s = self.structure
        return (G @ s.pattern_ff).reshape(self.B, s.nf, s.nf), (G @ s.pattern_fb).reshape(self.B, s.nf, s.nb)

    def dAT_free(self, T_K, dG) -> np.ndarray:
        """Free × free block of ∂(A(T) T)/∂T from the conductances' temperature dependence (B, nf, nf)."""
        s = self.structure
        D = np.zeros((self.B, s.nf, s.nf))
        for k, m, d in dG:
            e, c = self.elements[k], s.fpos[m]
            if e.advective:
                if s.fpos[e.j] >= 0:
                    D[:, s.fpos[e.j], c] += d * (T_K[:, e.j] - T_K[:, e.i])
            else:
                if s.fpos[e.i] >= 0:
                    D[:, s.fpos[e.i], c] += d * (T_K[:, e.i] - T_K[:, e.j])
                if s.fpos[e.j] >= 0:
                    D[:, s.fpos[e.j], c] += d * (T_K[:, e.j] - T_K[:, e.i])
        return D

    def flows(self, T_K, G) -> np.ndarray:
        """(B, n_el) heat flow through each element [W], signed along ``nodes`` (conduction,
        convection, radiation: from nodes[0] to nodes[1]; advection: carried away from the
        downstream node, G (T_down − T_up))."""
        s = self.structure
        return G * np.where(s.adv, T_K[:, s.j] - T_K[:, s.i], T_K[:, s.i] - T_K[:, s.j])

    def take(self, idx) -> "ThermalNetwork":
        """The network at a subset of its operating points (index array or mask)."""
        idx = np.arange(self.B)[idx]

        def sub(v):
            return v[idx] if isinstance(v, np.ndarray) and v.ndim >= 1 and v.shape[0] == self.B else v
        els = tuple(replace(e, p={k: sub(v) for k, v in e.p.items()}) for e in self.elements)
        return ThermalNetwork(template=self.template, B=idx.size, T_fixed_K=self.T_fixed_K[idx], elements=els,
                              oil=self.oil, structure=replace(self.structure, G0=self.structure.G0[idx]),
                              C_points=None if self.C_points is None else self.C_points[idx])

    @property
    def graph(self):
        """The topology (see :attr:`NetworkTemplate.graph`)."""
        return self.template.graph


@dataclass(frozen=True)
class Structure:
    """Matrix pattern and temperature dependence of a network at its operating points."""

    pattern: np.ndarray       # (n_el, n*n): A.ravel() = G @ pattern
    ff: np.ndarray
    fb: np.ndarray
    nf: int
    nb: int
    fpos: tuple               # node → position among the free nodes (−1: fixed)
    dep: tuple                # elements whose conductance depends on a free node's temperature
    users: dict               # free node → elements depending on it
    G0: np.ndarray            # (B, n_el) conductances of the other elements (dep columns 0)

    pattern_ff: np.ndarray = None   # (n_el, nf*nf): the free × free block of the pattern
    pattern_fb: np.ndarray = None   # (n_el, nf*nb): the free × fixed block
    i: np.ndarray = None      # element → its first node (flows)
    j: np.ndarray = None      # element → its second node
    adv: np.ndarray = None    # element → advective

    @classmethod
    def topology(cls, fixed, elements) -> "Structure":
        """The part that depends only on the network's topology (computed once, by its template):
        matrix pattern, positions of the free and fixed blocks, temperature dependence."""
        n = fixed.size
        pattern = np.zeros((len(elements), n * n))
        for k, e in enumerate(elements):
            i, j = e.i, e.j
            if e.advective:
                pattern[k, j * n + j] += 1.0
                pattern[k, j * n + i] -= 1.0
            else:
                pattern[k, [i * n + i, j * n + j]] += 1.0
                pattern[k, [i * n + j, j * n + i]] -= 1.0
        free_i, fixed_i = np.flatnonzero(~fixed), np.flatnonzero(fixed)
        fpos = -np.ones(n, int)
        fpos[free_i] = np.arange(free_i.size)
        dep = tuple(k for k, e in enumerate(elements) if any(not fixed[m] for m in e.depends_on()))
        users: dict = {}
        for k in dep:
            for m in elements[k].depends_on():
                if not fixed[m]:
                    users.setdefault(m, []).append(k)
        ff, fb = (free_i[:, None] * n + free_i[None, :]).ravel(), (free_i[:, None] * n + fixed_i[None, :]).ravel()
        p_ff, p_fb = np.ascontiguousarray(pattern[:, ff]), np.ascontiguousarray(pattern[:, fb])
        for a in (pattern, p_ff, p_fb):
            a.setflags(write=False)
        return cls(pattern=pattern, ff=ff, fb=fb, nf=free_i.size, nb=fixed_i.size, pattern_ff=p_ff, pattern_fb=p_fb,
                   fpos=tuple(fpos.tolist()), dep=dep, users=users, G0=None,
                   i=np.array([e.i for e in elements]), j=np.array([e.j for e in elements]),
                   adv=np.array([e.advective for e in elements]))

    def at(self, template, elements, T_fixed_K, oil) -> "Structure":
        """This topology at operating points: every element evaluated once at a probe state (free nodes
        10 K above the mean fixed temperature), naming the element when its conductance is not finite
        and ≥ 0; the constant ones kept (those reading only the bearing from the template)."""
        fixed = template.fixed
        T = T_fixed_K.copy()
        T[:, ~fixed] = T_fixed_K[:, fixed].mean(axis=1, keepdims=True) + 10.0
        G0 = np.zeros((T.shape[0], len(elements)))
        shared: dict = {}
        for k, e in enumerate(elements):
            G_static = template.elements[k].G_static
            if G_static is not None:
                G0[:, k] = G_static
                continue
            try:
                G = np.asarray(e.conductance(T[:, e.i], T[:, e.j], oil, shared), float)
            except InputError as exc:
                raise InputError(f"{template.source}: elements[{e.name}].{exc.field}", exc.value, exc.expected) from None
            if not (np.all(np.isfinite(G)) and np.all(G >= 0)):
                raise InputError(f"{template.source}: elements[{e.name}]", G, "conductance must be finite and >= 0 [W/K]")
            if k not in self.dep:
                G0[:, k] = G
        return replace(self, G0=G0)
