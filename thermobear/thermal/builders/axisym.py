r"""One discretisation rule for the bodies of revolution of a thermal network (shafts, housings).

A body of revolution — a solid or hollow cylinder: a shaft, the equivalent annulus of a housing —
is cut into pieces along its axis (the part under the bearing, the parts either side of it) and
each piece into an n_r × n_z grid of annular cells, one network node per cell.  The counts come
from one rule, applied to each direction of each piece (:func:`segment_count`):

* **Biot.**  A piece of conduction resistance R along a direction, exchanging a conductance G
  with its surroundings through faces spread along that direction (the lateral surface of a
  shaft along its axis, the end faces of a housing along its radius), has the Biot number
  Bi = R G.  Cut into n cells, each cell has R/n and G/n: Bi_cell = Bi/n².  The cells are lumped
  when Bi_cell ≤ Bi_max = 0.1, the lumped-capacitance criterion (Bergman et al. 2011 §5.1:
  the temperature differences inside stay below ≈ 5 % of those to the surroundings):

  .. math:: n_{Bi} = \left\lceil \sqrt{Bi / Bi_{max}} \right\rceil

  For a shaft this is the fin parameter: Bi = (mL)², m = √(hP/(kA)).
* **Fourier.**  A heat-up resolved from t_res on needs cells through which heat diffuses within
  t_res: a t_res/ℓ² ≥ Fo_min = 1 (Bergman et al. 2011 §5.10), a = k/(ρ c_p):

  .. math:: n_{Fo} = \left\lceil L \sqrt{Fo_{min} / (a\, t_{res})} \right\rceil

  t_res = 100 s by default: the hand-written seed-004 network (networks/oil_jet_ball_bearing.toml)
  cut its 150 mm shaft path into five 30 mm segments by this criterion (Fo ≥ 1.28 from 100 s on);
  the rule gives the same five.
* n = min(max(n_Bi, n_Fo, 1), 24).  The steady state needs only the Biot part
  (``t_resolve_s=None``).

Inside a body, cells are joined radially by the cylindrical shell between their node radii and
axially by the plane wall between their centres (finite volumes).  A cell's node stands for its
volume-mean temperature: for an annular cell of radii r0 < r1 at the radius r_c with

.. math:: \ln r_c = \frac{r_1^2 \ln r_1 - r_0^2 \ln r_0}{r_1^2 - r_0^2} - \frac12

(the volume mean of ln r: exact for radial conduction through the cell; neighbouring cells are joined
by the shell between their node radii), for a solid core at its mean.  Exchanges through a face
(convection, radiation) act on the cell's node; stiff joints (fits, a mounting face) are put in
series with the conduction between the node and the face (:func:`face_conductance`: the heat
crossing the face spreads through the cell's volume, 1/(8πkL) for a solid core).

References
----------
.. [1] Bergman, T. L., Lavine, A. S., Incropera, F. P., DeWitt, D. P., 2011, *Fundamentals of Heat
   and Mass Transfer*, 7th ed., Wiley: §5.1 (lumped capacitance, Bi < 0.1), §5.10 (finite
   differences and the Fourier number of a cell), eq 3.33 (cylindrical shell), eq 3.6 (plane
   wall), §3.6.4 (fins: m = √(hP/(kA))).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from thermobear.contact.materials import material as material_of
from thermobear.errors import InputError
from thermobear.thermal.builders.spec import Cell, NetworkSpec
from thermobear.thermal.conduction import shell_conductance, solid_cylinder_conductance

__all__ = ["BI_MAX", "FO_MIN", "T_RESOLVE_S", "N_MAX", "Segmentation", "segment_count", "node_radius",
           "face_conductance", "Body", "revolution_body"]

BI_MAX = 0.1          #: Biot number of a lumped cell (Bergman et al. 2011 §5.1)
FO_MIN = 1.0          #: Fourier number of a cell at the resolved time (Bergman et al. 2011 §5.10)
T_RESOLVE_S = 100.0   #: heat-up resolved from this time on [s] (the seed-004 hand network's choice)
N_MAX = 24            #: cells per piece and direction at most


@dataclass(frozen=True)
class Segmentation:
    """The cells of one piece in one direction and why.

    n : int       cells;  n_Bi, n_Fo : what each criterion asks;  Bi : Biot number of the whole piece
    [-];  Fo : its Fourier number a t_res / L² [-] (inf for the steady state)
    """

    n: int
    n_Bi: int
    n_Fo: int
    Bi: float
    Fo: float


def segment_count(length, R_cond, G_ext, diffusivity, *, Bi_max=BI_MAX, t_resolve_s=T_RESOLVE_S,
                  Fo_min=FO_MIN, n_max=N_MAX) -> Segmentation:
    r"""Number of cells of a piece of a body in one direction (see the module docstring).

    Parameters
    ----------
    length : float       extent of the piece in that direction [m]
    R_cond : float       conduction resistance of the whole piece in that direction [K/W]
    G_ext : float        conductance to its surroundings through faces spread along it [W/K]
    diffusivity : float  thermal diffusivity k/(ρ c_p) [m²/s]
    Bi_max : float       Biot number of a lumped cell [-]
    t_resolve_s : float  time from which a heat-up is resolved [s]; None: the steady state only
    Fo_min : float       Fourier number of a cell at t_resolve_s [-]
    n_max : int          cap

    Returns
    -------
    Segmentation

    Notes
    -----
    .. math:: n = \min\left(\max\left(\left\lceil\sqrt{R G / Bi_{max}}\right\rceil,
              \left\lceil L\sqrt{Fo_{min}/(a\, t_{res})}\right\rceil, 1\right), n_{max}\right)

    Examples
    --------
    The 150 mm, 50 mm shaft path of the seed-004 rig (52100 steel), no lateral exchange:

    >>> s = segment_count(0.15, 1.0, 0.0, 42.7 / (7830.0 * 475.0))
    >>> s.n, s.n_Fo, round(s.Fo, 2)
    (5, 5, 0.05)
    """
    for name, v in (("length_m", length), ("diffusivity_m2_s", diffusivity)):
        if not (np.isfinite(v) and v > 0):
            raise InputError(name, v, "must be finite and > 0")
    if not (np.isfinite(R_cond) and R_cond >= 0 and np.isfinite(G_ext) and G_ext >= 0):
        raise InputError("R_cond_K_W", (R_cond, G_ext), "resistance and conductance must be finite and >= 0")
    Bi = float(R_cond * G_ext)
    n_Bi = max(1, math.ceil(math.sqrt(Bi / Bi_max) - 1e-12))
    if t_resolve_s is None:
        Fo, n_Fo = math.inf, 1
    else:
        Fo = float(diffusivity * t_resolve_s / length**2)
        n_Fo = max(1, math.ceil(math.sqrt(Fo_min / Fo) - 1e-12))
    return Segmentation(n=int(min(max(n_Bi, n_Fo), n_max)), n_Bi=n_Bi, n_Fo=n_Fo, Bi=Bi, Fo=Fo)


def node_radius(r0, r1):
    r"""Radius of the node of an annular cell: its volume-mean temperature under radial conduction [m].

    .. math:: \ln r_c = \frac{r_1^2 \ln r_1 - r_0^2 \ln r_0}{r_1^2 - r_0^2} - \frac12

    >>> round(node_radius(0.04, 0.08), 4)         # above the arithmetic mid-radius 0.06: more volume outside
    0.0611
    """
    if r0 <= 0:
        return 0.0
    return math.exp((r1**2 * math.log(r1) - r0**2 * math.log(r0)) / (r1**2 - r0**2) - 0.5)


class Body:
    """A body of revolution cut into cells: ``slices`` ordered by z, each a list of cells by r."""

    def __init__(self, name: str, material: str, slices: list):
        self.name, self.material, self.slices = name, material, slices
        self.k = material_of(material).k

    @property
    def cells(self) -> list:
        return [c for s in self.slices for c in s]

    def face(self, face: str, z_range=None) -> list:
        """Cells on a face with the part of the face each holds: ``outer`` / ``inner``: (cell, z0, z1)
        (within ``z_range``); ``left`` / ``right``: (cell, r0, r1)."""
        if face in ("left", "right"):
            s = self.slices[0] if face == "left" else self.slices[-1]
            return [(c, c.r0, c.r1) for c in s]
        out = []
        lo, hi = z_range if z_range is not None else (-math.inf, math.inf)
        for s in self.slices:
            c = s[-1] if face == "outer" else s[0]
            if face == "inner" and c.r0 <= 0:
                continue
            z0, z1 = max(c.z0, lo), min(c.z1, hi)
            if z1 - z0 > 1e-12:
                out.append((c, z0, z1))
        return out

    def half_conductance(self, cell: Cell, face: str, extent) -> float:
        """Conduction between a cell's node and the part ``extent`` of its face [W/K]: (z0, z1) of a
        radial face, (r0, r1) of an end face (see :func:`face_conductance`)."""
        if face in ("outer", "inner"):
            return face_conductance(self.k, extent[1] - extent[0], cell.r0, cell.r1, face)
        A = math.pi * (extent[1] ** 2 - extent[0] ** 2)
        return self.k * A / (0.5 * (cell.z1 - cell.z0))


def face_conductance(k, L, r0, r1, face="outer") -> float:
    r"""Conductance between the mean temperature of an annular cell and its outer (or inner) face [W/K].

    Parameters
    ----------
    k : float        conductivity [W/(m K)]
    L : float        length of the face [m]
    r0, r1 : float   inner (0: a solid core) and outer radius [m]
    face : str       ``"outer"`` or ``"inner"``

    Notes
    -----
    Heat crossing the face spreads through the cell's volume (a uniform sink, the opposite face
    adiabatic): T(r) from (1/r)(r T')' = s/k, its volume mean against the face.  Outer face:

    .. math:: G = rac{\pi (r_1^2 - r_0^2) L k}{(r_1^2 - r_0^2)/8 - (r_0^2/2) \ln(r_1 / r_c)}

    inner face: :math:`G = \pi (r_1^2 - r_0^2) L k / [(r_1^2/2)\ln(r_c/r_0) - (r_1^2 - r_0^2)/8]`, with
    r_c the node radius (:func:`node_radius`).  A solid core gives 8πkL
    (:func:`~thermobear.thermal.conduction.solid_cylinder_conductance`).

    Examples
    --------
    >>> round(face_conductance(48.0, 0.01, 0.0, 0.02) / (8 * math.pi * 48.0 * 0.01), 12)
    1.0
    """
    if r0 <= 0:
        if face != "outer":
            raise InputError("face", face, "a solid core has only an outer face")
        return float(solid_cylinder_conductance(k, L))
    rc = node_radius(r0, r1)
    area = r1**2 - r0**2
    den = area / 8 - 0.5 * r0**2 * math.log(r1 / rc) if face == "outer" else 0.5 * r1**2 * math.log(rc / r0) - area / 8
    return math.pi * area * L * k / den


def _edges(z0, z1, n, towards_start):
    """n equal cells on [z0, z1]; listed from the end nearest the bearing."""
    e = list(np.linspace(z0, z1, n + 1))
    pairs = list(zip(e[:-1], e[1:]))
    return pairs if towards_start else pairs[::-1]


def revolution_body(spec: NetworkSpec, name: str, r_in: float, r_out: float, pieces, material: str, n_r: int,
                    *, cell_name, radial_from: str = "inner", description: str = "", estimated=()) -> Body:
    """Cut a body of revolution into cells, add their nodes and the conduction between them.

    Parameters
    ----------
    spec : NetworkSpec
    name : str            body name
    r_in, r_out : float   inner radius (0: solid) and outer radius [m]
    pieces : list         (label, z0, z1, n_z, from_start, j0): axial pieces in z order; cells are
                          numbered j0 + 1, j0 + 2, … from z0 when ``from_start`` (else from z1)
    material : str        material name (``materials/solids``)
    n_r : int             radial cells
    cell_name : callable  (label, j, i) → node name; j the axial index (1 nearest the bearing), i
                          the radial index (0 at the bearing's side)
    radial_from : str     ``"inner"`` (a housing: index 0 at r_in) or ``"outer"`` (a shaft)

    Returns
    -------
    Body
    """
    m = material_of(material)
    r_edges = np.linspace(r_in, r_out, n_r + 1)
    slices = []
    for label, z0, z1, n_z, from_start, j0 in pieces:
        zs = _edges(z0, z1, n_z, from_start)
        order = sorted(range(n_z), key=lambda j: zs[j][0])
        for j in order:
            za, zb = zs[j]
            row = []
            for q in range(n_r):
                i = q if radial_from == "inner" else n_r - 1 - q
                c = Cell(cell_name(label, j0 + j + 1, i), name, float(r_edges[q]), float(r_edges[q + 1]), float(za),
                         float(zb), material)
                spec.node(c.name, volume_m3=math.pi * (c.r1**2 - c.r0**2) * (c.z1 - c.z0), material=material,
                          description=f"{description} cell r {1e3 * c.r0:.1f}–{1e3 * c.r1:.1f} mm, "
                                      f"z {1e3 * c.z0:.1f}–{1e3 * c.z1:.1f} mm".strip(),
                          estimated=estimated)
                spec.cells.append(c)
                row.append(c)
            slices.append(row)
    body = Body(name, material, slices)
    _internal_links(spec, body, m)
    return body


def _internal_links(spec: NetworkSpec, body: Body, m) -> None:
    k = m.k
    for row in body.slices:                               # radial: shells between node radii
        for a, b in zip(row[:-1], row[1:]):
            L = a.z1 - a.z0
            if a.r0 <= 0:
                G = 1.0 / (1.0 / float(solid_cylinder_conductance(k, L))
                           + math.log(node_radius(b.r0, b.r1) / a.r1) / (2 * math.pi * k * L))
                spec.element(f"{a.name}--{b.name}", "conductance", (a.name, b.name), G_W_K=G,
                             description=f"solid core mean to its surface (8πkL) in series with the shell to the "
                                         f"next node, {m.name}")
            else:
                spec.element(f"{a.name}--{b.name}", "shell", (a.name, b.name), material=m.name,
                             r1_m=node_radius(a.r0, a.r1), r2_m=node_radius(b.r0, b.r1), L_m=L,
                             description="radial conduction between the cells' node radii")
    for s0, s1 in zip(body.slices[:-1], body.slices[1:]):  # axial: plane walls between centres
        for a, b in zip(s0, s1):
            spec.element(f"{a.name}--{b.name}", "planar", (a.name, b.name), material=m.name,
                         A_m2=math.pi * (a.r1**2 - a.r0**2), length_m=0.5 * (b.z1 - a.z0),
                         description="axial conduction between the cells' centres")
