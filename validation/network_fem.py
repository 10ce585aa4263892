"""Built thermal networks against an axisymmetric finite-element reference of the same geometry.

For three deep-groove bearings (6205, 6208, 6216) in their default block housings on free-ended
shafts (thermobear.thermal.builders defaults; grease, 3000 rpm, Fr = 0.1 C), the lumped network the
builders make (shaft and housing cut by the Biot/Fourier rule of thermobear.thermal.builders.axisym) is
compared with a fine solution of the same problem:

* geometry: the shaft, the two rings (bore to raceway diameter, outer raceway to outside diameter,
  over the width) and the housing's equivalent annulus, meshed in (r, z) with bilinear quadrilaterals
  (scikit-fem; ∇·(k∇T) = 0 weighted by 2πr); the seats as thin layers (0.05 mm, k = h t) with the
  joint conductance h the network uses;
* what the network does not resolve is shared: the balls and the cavity's mixture are unknowns of
  their own, joined to the raceway faces by the same contact, convection and conduction elements
  (the network's element objects, evaluated at the finite-element face temperatures, Picard
  iterations to 1e-6 K); the outside faces of the shaft and housing exchange with the room and the
  frame through the same elements, their conductance spread over the annulus's face;
* heat: the loss of the coupled thermobear solution of the scene, ½ into the balls, ¼ as a uniform
  flux into each raceway (the network puts it on the race nodes).

Compared: the rings (bore face, raceway faces, outside face: the nodes stand for these faces'
temperatures), the housing's seat cell and the housing's volume mean, the shaft under the bearing,
the balls and the mixture; the same with the rule refined (Bi ≤ 0.01); the finite-element mesh at
1 mm and 0.5 mm (its own error).
What the comparison does not test: that a block housing behaves as the annulus of its cross-section
(both models make that idealisation), the convection correlations themselves.

Run:  python validation/network_fem.py   (needs scikit-fem: pip install "thermobear[validation]"; ≈ 1–2 min)
"""
from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import spsolve

try:                                    # the validation extra: pip install "thermobear[validation]"
    from skfem import (Basis, BilinearForm, ElementQuad1, FacetBasis, LinearForm, MeshQuad, asm,
                       condense)
except ImportError:                     # pragma: no cover - reported by main()
    MeshQuad = None

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _common import write_report  # noqa: E402

import thermobear as tb  # noqa: E402
from thermobear.coupled.steady import steady_state  # noqa: E402
from thermobear.scene.scene import scene_from_dict  # noqa: E402
from thermobear.thermal import prepare_network, solve_steady  # noqa: E402
from thermobear.thermal.builders import build_network  # noqa: E402
from thermobear.thermal.builders.layout import layout  # noqa: E402

SIZES = ("6205", "6208", "6216")
N_RPM = 3000.0
LAYER_M = 0.05e-3
RING_FACES = ("inner_ring", "inner_race", "outer_race", "outer_ring")


def scene_of(size: str, Bi_max: float | None = None):
    d = {"scene": {"name": f"{size}-block-grease"}, "bearing": {"catalog": size},
         "lubricant": {"name": "grease-lithium-mineral-vg100-nlgi2", "supply": "grease"},
         "operation": {"n_rpm": N_RPM, "Fr_N": 0.1 * tb.bearing(size).C},
         "thermal": {"T_ambient_C": 20.0}, "housing": {"type": "block"}}
    s = scene_from_dict(d)
    return s if Bi_max is None else s.with_(network="parametric")


def context(scene):
    """The network's context at the scene's point (kinematics of an unloaded-angle deep-groove bearing)."""
    b, w = scene.bearing, scene.omega
    g = b.D / b.dm
    op = {"omega_rad_s": w, "omega_inner_rad_s": w, "omega_outer_rad_s": 0.0, "omega_cage_rad_s": 0.5 * w * (1 - g),
          "omega_ball_rad_s": 0.5 * w / g * (1 - g * g), "oil_fraction": 0.0}
    return {"bearing": b, "oil": scene.lubricant, "op": op,
            "scene": {"T_ambient_C": scene.T_ambient_C, "T_oil_in_C": scene.T_ambient_C, "oil_flow_m3_s": 0.0,
                      "n_rpm": scene.n_rpm}}


# --------------------------------------------------------------------------- the finite-element model
class Fem:
    """Axisymmetric conduction in shaft, rings and housing, with the network's lumped parts attached."""

    def __init__(self, built, net, lay, h_max):
        self.built, self.net, self.lay = built, net, lay
        cells = built.cells
        mat = {c.body: tb.material(c.material).k for c in cells}
        self.k_ring = _ring_k(net)
        joints = {s.to: s.h_W_m2K for s in built.surfaces if s.kind == "joint" and s.to in ("inner_ring", "outer_ring")}
        self.h_in, self.h_out = joints["inner_ring"], joints["outer_ring"]
        r_ir, r_or = (lay.dm - lay.D) / 2, (lay.dm + lay.D) / 2
        self.r_faces = {"inner_ring": lay.r_s + LAYER_M, "inner_race": r_ir, "outer_race": r_or,
                        "outer_ring": lay.R_seat - LAYER_M}
        rs = {0.0, lay.r_si, lay.r_s, lay.r_s + LAYER_M, r_ir, r_or, lay.R_seat - LAYER_M, lay.R_seat, lay.R_h}
        zs = {-lay.B / 2, lay.B / 2}
        for c in cells:
            rs |= {c.r0, c.r1}
            zs |= {c.z0, c.z1}
        self.mesh = MeshQuad.init_tensor(_refine(sorted(rs), h_max), _refine(sorted(zs), h_max))
        mid = self.mesh.p[:, self.mesh.t].mean(axis=1)
        kk = self._conductivity(mid, mat["shaft"], mat["housing"], self.k_ring)
        keep = np.flatnonzero(kk > 0)
        self.mesh = self.mesh.restrict(keep)
        self.k_el = kk[keep]
        self.e = ElementQuad1()
        self.basis = Basis(self.mesh, self.e)
        kq = np.repeat(self.k_el[:, None], self.basis.X.shape[1], axis=1)

        @BilinearForm
        def cond(u, v, w):
            return w.kk * (u.grad[0] * v.grad[0] + u.grad[1] * v.grad[1]) * 2 * np.pi * w.x[0]
        self.K0 = asm(cond, self.basis, kk=kq)
        self.n = self.basis.N

    def _conductivity(self, mid, k_shaft, k_housing, k_ring):
        lay, r, z = self.lay, mid[0], mid[1]
        inb = np.abs(z) < lay.B / 2
        k = np.zeros(r.size)
        k[(r > lay.r_si) & (r < lay.r_s) & (z > lay.z_s0) & (z < lay.z_s1)] = k_shaft
        k[inb & (r > lay.r_s) & (r < lay.r_s + LAYER_M)] = self.h_in * LAYER_M
        k[inb & (r > lay.r_s + LAYER_M) & (r < (lay.dm - lay.D) / 2)] = k_ring
        k[inb & (r > (lay.dm + lay.D) / 2) & (r < lay.R_seat - LAYER_M)] = k_ring
        k[inb & (r > lay.R_seat - LAYER_M) & (r < lay.R_seat)] = self.h_out * LAYER_M
        k[(r > lay.R_seat) & (r < lay.R_h) & (z > lay.z_h0) & (z < lay.z_h1)] = k_housing
        return k

    def face(self, face, r, z, boundary=True):
        """(mass matrix ∫uv dS, load vector ∫v dS, area) of a boundary face: radial at r over z, or axial at z over r."""
        eps = 1e-9
        if face in ("outer", "inner"):
            sel = lambda x: np.isclose(x[0], r[0], atol=eps) & (x[1] > z[0] - eps) & (x[1] < z[1] + eps)  # noqa
        else:
            sel = lambda x: np.isclose(x[1], z[0], atol=eps) & (x[0] > r[0] - eps) & (x[0] < r[1] + eps)  # noqa
        facets = self.mesh.facets_satisfying(sel, boundaries_only=boundary)
        if facets.size == 0:
            raise RuntimeError(f"no boundary facets on {face} r={r} z={z}")
        fb = FacetBasis(self.mesh, self.e, facets=facets)
        M = asm(BilinearForm(lambda u, v, w: u * v * 2 * np.pi * w.x[0]), fb)
        b = asm(LinearForm(lambda v, w: v * 2 * np.pi * w.x[0]), fb)
        return M, b, float(b.sum())

    def volume_weights(self, r0, r1, z0, z1):
        """Weights w (length n) with w·T the volume mean of T over the box (r0..r1, z0..z1)."""
        mid = self.mesh.p[:, self.mesh.t].mean(axis=1)
        el = np.flatnonzero((mid[0] > r0) & (mid[0] < r1) & (mid[1] > z0) & (mid[1] < z1))
        sb = Basis(self.mesh, self.e, elements=el)
        w = asm(LinearForm(lambda v, w_: v * 2 * np.pi * w_.x[0]), sb)
        return w / w.sum()


def _refine(pts, h):
    out = [pts[0]]
    for a, b in zip(pts[:-1], pts[1:]):
        if b - a < 1e-12:
            continue
        n = max(1, math.ceil((b - a) / h - 1e-9))
        out += list(np.linspace(a, b, n + 1)[1:])
    return np.array(out)


def _ring_k(net):
    for e in net.elements:
        if e.name == "inner_ring_radial":
            return e.p["material"].k
    raise RuntimeError("no inner_ring_radial element")


def solve_fem(built, net, lay, sources, h_max, T_start):
    """Steady temperatures of the finite-element model: (face means, cell means, scalar values)."""
    fem = Fem(built, net, lay, h_max)
    idx = net.index
    fixed = {n: float(net.T_fixed_K[0, idx[n]]) for n in net.fixed_nodes}
    cells = {c.name: c for c in built.cells}
    scalars = [n for n in net.free_nodes if n not in cells and n not in RING_FACES]
    spos = {n: fem.n + q for q, n in enumerate(scalars)}
    N = fem.n + len(scalars)
    faces, dirichlet = [], []          # (element, face key, M, b, A, side node, other node)
    by_name = {e.name: e for e in net.elements}
    for s in built.surfaces:
        if s.to in RING_FACES or s.to in ("shaft_washer", "housing_washer"):
            continue                    # the seats: the thin layers
        M, b, A = fem.face(s.face, s.r, s.z)
        if s.kind == "fixed":
            dirichlet.append((b, fixed[s.to]))
            continue
        cell = by_name[s.element].nodes[0]
        faces.append((by_name[s.element], s, M, b, A, cell, s.to))
    ring_face = {n: fem.face("outer" if n in ("inner_race", "outer_ring") else "inner",
                             (fem.r_faces[n], fem.r_faces[n]), (-lay.B / 2, lay.B / 2),
                             boundary=n in ("inner_race", "outer_race")) for n in RING_FACES}
    links, lumped = [], []             # ring face ↔ lumped node; lumped ↔ lumped
    for e in net.elements:
        a, b_ = e.nodes
        if (a in cells or a in RING_FACES) and (b_ in cells or b_ in RING_FACES):
            continue                    # resolved by the mesh (shells, cells, seats)
        if a in cells or b_ in cells:
            continue                    # on a body's face: in built.surfaces
        if a in RING_FACES or b_ in RING_FACES:
            ring, other = (a, b_) if a in RING_FACES else (b_, a)
            links.append((e, ring, other))
        else:
            lumped.append(e)
    T = {n: T_start[n] for n in net.nodes}        # the lumped nodes' values; faces: their own means
    xf = None

    def face_T(b, A, node):
        return T[node] if xf is None else float(b @ xf[:fem.n] / A)
    ns = len(scalars)
    weights = {c.name: fem.volume_weights(c.r0, c.r1, c.z0, c.z1) for c in built.cells}
    for it in range(60):
        acc = _Acc(fem.K0.copy(), np.zeros((fem.n, ns)), np.zeros((ns, ns)), np.zeros(fem.n), np.zeros(ns), fem.n)
        for e, s, M, b, A, cell, other in faces:
            G = _G(e, face_T(b, A, cell), T[other], net.oil)
            acc.couple(M, b, G / A, G, other, spos, fixed)
        for e, ring, other in links:
            M, b, A = ring_face[ring]
            Tr = face_T(b, A, ring)
            G = _G(e, *((Tr, T[other]) if e.nodes[0] == ring else (T[other], Tr)), net.oil)
            acc.couple(M, b, G / A, G, other, spos, fixed)
        for e in lumped:
            acc.lumped(e, _G(e, T[e.nodes[0]], T[e.nodes[1]], net.oil), spos, fixed)
        for node, q in sources.items():
            if node in RING_FACES:
                M, b, A = ring_face[node]
                acc.rf += q / A * b
            else:
                acc.rs[spos[node] - fem.n] += q
        K, rhs = acc.system()
        xn = np.zeros(N)
        if dirichlet:
            D = np.unique(np.concatenate([np.flatnonzero(b) for b, _ in dirichlet]))
            for b, Tv in dirichlet:
                xn[np.flatnonzero(b)] = Tv
            I = np.setdiff1d(np.arange(N), D)
            A_, b_ = condense(K, rhs, x=xn, D=D)[:2]
            xn[I] = spsolve(A_, b_)
        else:
            xn = spsolve(K, rhs)
        Tn = _means(fem, xn, built, ring_face, scalars, spos, weights)
        step = max(abs(Tn[k] - T[k]) for k in Tn) if xf is not None else math.inf
        T.update(Tn)
        xf = xn
        if step < 1e-6:
            break
    return T, fem, it + 1


class _Acc:
    """The linear system being assembled: FEM block, FEM–lumped columns, lumped block, right-hand sides."""

    def __init__(self, Kff, Kfs, Kss, rf, rs, n):
        self.Kff, self.Kfs, self.Kss, self.rf, self.rs, self.n = Kff, Kfs, Kss, rf, rs, n

    def couple(self, M, b, g, G, other, spos, fixed):
        """A face exchanging g [W/(m² K)] (G in all) with a fixed or a lumped node."""
        self.Kff = self.Kff + g * M
        if other in fixed:
            self.rf += g * fixed[other] * b
        else:
            j = spos[other] - self.n
            self.Kfs[:, j] -= g * b
            self.Kss[j, j] += G

    def lumped(self, e, G, spos, fixed):
        a, b = e.nodes
        ia = None if a in fixed else spos[a] - self.n
        ib = None if b in fixed else spos[b] - self.n
        if e.advective:                # one-way: only the downstream balance
            self.Kss[ib, ib] += G
            if ia is None:
                self.rs[ib] += G * fixed[a]
            else:
                self.Kss[ib, ia] -= G
            return
        for p, q, ip, iq in ((a, b, ia, ib), (b, a, ib, ia)):
            if ip is None:
                continue
            self.Kss[ip, ip] += G
            if iq is None:
                self.rs[ip] += G * fixed[q]
            else:
                self.Kss[ip, iq] -= G

    def system(self):
        Kfs = sp.csr_matrix(self.Kfs)
        K = sp.bmat([[self.Kff, Kfs], [Kfs.T, sp.csr_matrix(self.Kss)]], format="csr")
        return K, np.concatenate([self.rf, self.rs])


def _G(e, Ti, Tj, oil):
    return float(np.asarray(e.conductance(np.array([Ti]), np.array([Tj]), oil, {})).ravel()[0])


def _means(fem, x, built, ring_face, scalars, spos, weights):
    out = {n: float(x[spos[n]]) for n in scalars}
    for n, (M, b, A) in ring_face.items():
        out[n] = float(b @ x[:fem.n] / A)
    for c in built.cells:
        out[c.name] = float(weights[c.name] @ x[:fem.n])
    return out


# --------------------------------------------------------------------------- comparison
def compare(size: str, h_max: float, Bi_max: float = 0.1):
    """Lumped and finite-element temperatures of one size: (rows, segments, mesh size, iterations)."""
    s = scene_of(size)
    st = steady_state(s)
    m = s.network if Bi_max == 0.1 else s.network.with_(Bi_max=Bi_max)
    built = build_network(m)
    lay = layout(m)
    net = prepare_network(built.spec, {"bearing": s.bearing}).at(context(s), oil=s.lubricant)
    P = st.P_W
    sources = {"balls": 0.5 * P, "inner_race": 0.25 * P, "outer_race": 0.25 * P}
    lumped = solve_steady(net, sources)
    T_l = {k: float(v) for k, v in lumped.T_C.items()}
    T_K0 = {k: v + 273.15 for k, v in T_l.items()}
    T_f, fem, its = solve_fem(built, net, lay, sources, h_max, T_K0)
    T_f = {k: v - 273.15 for k, v in T_f.items()}
    return s, P, built, T_l, T_f, fem, its


COMPARED = ("inner_ring", "inner_race", "outer_race", "outer_ring", "balls", "oil_air", "shaft", "housing")


def _errors(built, T_l, T_f):
    """Per compared node the lumped − reference difference [K]; the housing's volume mean too."""
    out = {k: T_l[k] - T_f[k] for k in COMPARED}
    cells = [c for c in built.cells if c.body == "housing"]
    vol = [math.pi * (c.r1**2 - c.r0**2) * (c.z1 - c.z0) for c in cells]
    mean = lambda T: sum(v * T[c.name] for c, v in zip(cells, vol)) / sum(vol)  # noqa: E731
    out["housing (volume mean)"] = mean(T_l) - mean(T_f)
    out["max over every node"] = max((T_l[k] - T_f[k] for k in T_f if k in T_l), key=abs)
    return out


def _counts(built) -> str:
    seg = built.segments
    sh = "+".join(str(v.n) for k, v in seg.items() if k.startswith("shaft") and "radial" not in k)
    ho = "+".join(str(v.n) for k, v in seg.items() if k.startswith("housing") and "radial" not in k)
    return f"shaft {sh} × {seg['shaft radial'].n}, housing {ho} × {seg['housing radial'].n}"


def main() -> int:
    if MeshQuad is None:
        print("network_fem.py needs scikit-fem: pip install \"thermobear[validation]\"")
        write_report("network_fem.md", ["# Built thermal networks against a finite-element reference", "",
                                        "Not run: scikit-fem is not installed (`pip install \"thermobear[validation]\"`)."])
        return 0
    L = ["# Built thermal networks against an axisymmetric finite-element reference", "",
         "Generated by `python validation/network_fem.py` (do not edit; the method is in its docstring).", "",
         f"Three deep-groove bearings in their default block housings (`thermobear.thermal.builders` defaults: grey-iron "
         f"block 2 D × 2 D × 2 B bolted to a steel frame at 20 °C, C45 shafts 2.5 d long each side with free ends, "
         f"probable k5/H7 seats), grease, {N_RPM:g} rpm, Fr = 0.1 C.  The same geometry, seats (thin layers), balls, "
         "mixture and exchange elements in both models; the finite elements resolve the conduction in the shaft, the "
         "rings and the housing's annulus.  Heat: the coupled solution's loss, ½ to the balls, ¼ into each raceway.",
         ""]
    rows, mesh_rows, refine_rows = [], [], []
    worst = 0.0
    for size in SIZES:
        s, P, built, T_l, T_f, fem, its = compare(size, 1.0e-3)
        _, _, _, _, T_f2, fem2, _ = compare(size, 0.5e-3)
        e = _errors(built, T_l, T_f)
        mesh_rows.append((size, fem.n, fem2.n, max(abs(T_f[k] - T_f2[k]) for k in T_f if k in T_f2)))
        worst = max(worst, max(abs(e[k]) for k in ("inner_ring", "inner_race", "outer_race", "outer_ring", "housing",
                                                   "housing (volume mean)")))
        rows.append((size, P, len(built.spec["nodes"]), _counts(built), e, its))
        _, _, builtf, T_lf, T_ff, _, _ = compare(size, 1.0e-3, Bi_max=0.01)
        refine_rows.append((size, len(builtf.spec["nodes"]), _counts(builtf), _errors(builtf, T_lf, T_ff)))
    L += ["## Lumped network (default rule: Bi ≤ 0.1, Fo ≥ 1 at 100 s) − finite elements [K]", "",
          "| bearing | loss [W] | nodes | cells (axial pieces × radial) | " + " | ".join(COMPARED)
          + " | housing mean | max, any node |", "|---" * (len(COMPARED) + 6) + "|"]
    for size, P, n, counts, e, its in rows:
        L.append(f"| {size} | {P:.1f} | {n} | {counts} | " + " | ".join(f"{e[k]:+.2f}" for k in COMPARED)
                 + f" | {e['housing (volume mean)']:+.2f} | {e['max over every node']:+.2f} |")
    L += ["", f"Largest difference on the rings and the housing: **{worst:.2f} K** (acceptance: 2 K).", "",
          "## The rule refined (Bi ≤ 0.01)", "",
          "| bearing | nodes | cells | " + " | ".join(COMPARED) + " | max, any node |", "|---" * (len(COMPARED) + 4) + "|"]
    for size, n, counts, e in refine_rows:
        L.append(f"| {size} | {n} | {counts} | " + " | ".join(f"{e[k]:+.2f}" for k in COMPARED)
                 + f" | {e['max over every node']:+.2f} |")
    L += ["", "## The reference's own mesh error", "",
          "| bearing | nodes (1 mm) | nodes (0.5 mm) | largest change [K] |", "|---|---|---|---|"]
    for size, n1, n2, d in mesh_rows:
        L.append(f"| {size} | {n1} | {n2} | {d:.3f} |")
    L += ["", "Cell counts: the axial pieces of each body (left of the bearing outside and inside the housing, "
          "under the bearing, right inside and outside) × the radial cells; `thermobear.thermal.builders.axisym` "
          "states the rule.  The nodes stand for the faces' temperatures for the rings (bore, raceways, "
          "outside) and for the volume means of the cells; the balls and the mixture are unknowns of both models."]
    write_report("network_fem.md", L)
    print("\n".join(L))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
