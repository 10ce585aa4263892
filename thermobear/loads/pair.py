r"""A preloaded pair of equal angular contact bearings: its position preload from the cold preload force, and the
loads of its loaded bearing with warm rings and balls.

Spindle bearings are mounted in pairs, back to back or face to face, and preloaded cold (Harris & Kotzalas 2007
[1] ch. 8): by position (ground faces or spacers push each inner ring δ/2 beyond first touch) or by a spring (a
constant force F_s).  Catalogues state the preload as a force F_0, the axial load each bearing carries at mounting
without external load.  By symmetry the shaft of an unloaded pair stays where it was mounted, so each bearing is
a bearing under the pure axial load F_0, and the pair's offset is

.. math:: δ = 2\,\bigl(δ_a(F_0) − A \sin α_0\bigr)

with δ_a(F_0) the axial displacement of the inner ring from the centred position under F_0
(:func:`thermobear.loads.static.load_distribution_static`) and A sin α0 its axial travel to first touch: the
exact inverse of :func:`thermobear.loads.sets.bearing_set`'s ``preload_offset`` for the force.  Warm, the inner
ring (with the shaft) ΔT_i, the outer ring (with the housing) ΔT_o and the balls ΔT_b above the mounting
temperature, the rings and balls grow ([1] ch. 3), the groove centres move and the position preload follows
(:func:`thermobear.loads.sets.warm_supports`); a spring keeps its force.

At speed (``n_rpm`` given) each bearing's load–displacement is the high-speed form's
(:func:`thermobear.loads.highspeed.load_distribution_high_speed`: the balls' centrifugal force and gyroscopic
moment, Jones 1960 [2]) and the inner rings (with the shaft) grow by their centrifugal growth as well
(:func:`thermobear.contact.fits.raceway_growth`, in :func:`~thermobear.loads.sets.warm_supports`): the pair's
compatibility — the sum of both bearings' axial displacements the warm offset, the shaft's radial displacement
and tilt alike at both, the shaft in equilibrium — is solved by
:func:`thermobear.loads.shaftspeed.shaft_loads_high_speed`.  The position preload δ stays the one mounted cold at
rest; at speed a position-preloaded pair's load rises (Harris & Kotzalas 2007 [3] ch. 1–3; Li & Shin 2004 [4]):
the 7014C back-to-back pair of 300 N cold carries 903 N at 12 000 rpm from the balls' centrifugal force alone, and
1269 N with the free inner rings' centrifugal growth (3.0 µm on the raceway's radius, 11.6 µm more axial
interference per bearing at α0 = 15°); on an interference seat the fit's relief takes back most of that growth
(``u_inner``: :func:`thermobear.contact.fits.seated_raceway_growth`, 0.62 µm on a 16 µm seat).  A spring keeps its force at any speed; only the split of the loads changes.  Without
a speed (``n_rpm=None``) the pair is the low-speed (static) form: :func:`~thermobear.loads.sets.bearing_set`,
rigid rings, no centrifugal terms.

Stiffness (``with_stiffness``): of the pair at its centre under the external loads, the outer rings held (a rigid
housing), each stiffness with the shaft's other displacements free — the compliance's diagonal

.. math:: k_a = 1 / C_{aa}, \quad k_r = 1 / C_{rr}, \quad k_θ = 1 / C_{θθ}, \qquad C = K^{-1},
          \quad K = \partial P_{ext} / \partial q

(the static form's K the shaft's own, :class:`~thermobear.loads.sets.ShaftLoads` ``stiffness``; at speed the same
by central differences of the shaft's displacement over Fa ± h, Fr ± h, M ± h d_m/2, h = 10⁻³ of the larger of
the preload and the loads).  The tilt (moment) stiffness is what the arrangement sets: a back-to-back pair's
pressure centres lie a = B/2 + (d_m/2) tan α0 either side of its centre, k_θ ≈ 2 k_r,1 a² with k_r,1 one bearing's
radial stiffness; a face-to-face pair's at |B/2 − (d_m/2) tan α0|, for a 15° bearing nearly at its centre: the
7014C pair at 300 N 288 against 10 N m/mrad (Harris & Kotzalas 2007 [1] ch. 8, duplex sets).  Without external load a position-preloaded pair's axial stiffness is both bearings in parallel,
k_a = 2 dF_a/dδ_a(F_0), a spring-preloaded pair's the held bearing's alone (its partner's ring slides), and both
arrangements are alike by mirror symmetry; a radial load couples the axial displacement to the tilt, which a
back-to-back pair resists less than a face-to-face one here (Harris & Kotzalas 2007 [1] ch. 8: the axial
stiffness of duplex sets; the load–deflection of ch. 7).  At speed the balls' centrifugal force softens a spring
pair and the preload's rise stiffens a position pair (Jones 1960 [2]).

References
----------
.. [1] Harris, T. A. & Kotzalas, M. N. (2007). *Essential Concepts of Bearing Technology*, 5th ed., CRC Press,
   ch. 3 (thermal expansion), ch. 7 (the load–deflection of a ball bearing under axial load) and ch. 8 (bearing
   deflection and preloading: duplex pairs, position and spring preload).
.. [2] Jones, A. B. (1960). A general theory for elastically constrained ball and radial roller bearings under
   arbitrary load and speed conditions. *J. Basic Eng.* 82(2):309–320.
.. [3] Harris, T. A. & Kotzalas, M. N. (2007). *Advanced Concepts of Bearing Technology*, 5th ed., CRC Press,
   ch. 1–3 (high-speed ball bearings).
.. [4] Li, H. & Shin, Y. C. (2004). Analysis of bearing configuration effects on high speed spindles using an
   integrated dynamic thermo-mechanical spindle model. *Int. J. Mach. Tools Manuf.* 44(4):347–364.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from thermobear.contact.geometry import BallBearing
from thermobear.errors import InputError
from thermobear.loads.sets import ARRANGEMENTS, bearing_set, duplex_supports, warm_supports
from thermobear.loads.shaftspeed import HighSpeedShaftLoads, shaft_loads_high_speed
from thermobear.loads.static import load_distribution_static

__all__ = ["PAIR_ARRANGEMENTS", "PRELOAD_KINDS", "PairLoads", "pair_preload_offset", "pair_loads"]

#: The arrangements of a preloaded pair (:data:`~thermobear.loads.sets.ARRANGEMENTS` less the tandem, which has no
#: position preload of its own) and the kinds of its preload.
PAIR_ARRANGEMENTS = tuple(a for a in ARRANGEMENTS if a != "tandem")
PRELOAD_KINDS = ("position", "spring")
#: The load step of the high-speed form's stiffness by central differences, of the larger of the preload and the
#: external loads (the load–displacement is smooth: the differences' error ~ step², far below 1e-6)
_STIFFNESS_STEP = 1e-3


@dataclass(frozen=True)
class PairLoads:
    """The loads of a preloaded pair at given ring and ball temperatures.

    Attributes
    ----------
    Fa, Fr : float      axial and radial load of the loaded bearing (the larger axial load) [N]
    loaded : int        which bearing of :func:`~thermobear.loads.sets.bearing_set` it is (0 at −B/2, 1 at +B/2)
    Fa_other : float    the other bearing's axial load [N]
    preload : float     the pair's preload at these temperatures without external load: each bearing's axial
                        load [N] (the two alike by symmetry)
    offset : float | None  the position preload δ [m] (None: a spring preload)
    start : HighSpeedShaftLoads | None  the high-speed form's answer of its two load cases (the external loads,
                        none): where a nearby solve starts (``pair_loads(start=…)``); None in the static form
    stiffness : tuple | None  ``(axial [N/m], radial [N/m], tilt [N m/rad])`` stiffness of the pair under the
                        external loads (``pair_loads(with_stiffness=True)``; module docstring), else None
    """

    Fa: float
    Fr: float
    loaded: int
    Fa_other: float
    preload: float
    offset: float | None
    start: HighSpeedShaftLoads | None = field(default=None, repr=False, compare=False)
    stiffness: tuple | None = None


def pair_preload_offset(brg: BallBearing, preload, *, stiffness: str = "nominal") -> float:
    r"""The position preload δ [m] of a pair whose bearings each carry ``preload`` [N] cold, without external load
    (module docstring: δ = 2 (δ_a(F_0) − A sin α0)).

    Parameters
    ----------
    brg : BallBearing   the bearing of both rows (angular contact)
    preload : float     the cold preload F_0, each bearing's axial load [N], > 0
    stiffness : str     as :func:`thermobear.loads.load_distribution`

    Returns
    -------
    float               the total axial offset of the pair beyond first touch [m]

    Examples
    --------
    A 7205B pair preloaded to 470 N: about the 10 µm of :func:`~thermobear.loads.sets.bearing_set`'s example (whose
    preload, 469.5 N, is rounded there); set back, the offset gives the force.

    >>> from thermobear.contact.geometry import bearing
    >>> from thermobear.loads.sets import bearing_set
    >>> d = pair_preload_offset(bearing("7205B"), 470.0)
    >>> round(d * 1e6, 2), [round(float(F), 9) for F in bearing_set(bearing("7205B"), preload_offset=d).preload]
    (10.01, [470.0, 470.0])
    """
    if brg.kind != "angular_contact":
        raise InputError("bearing.arrangement", brg.kind, "a preloaded pair needs angular contact bearings")
    F0 = float(preload)
    if not (np.isfinite(F0) and F0 > 0):
        raise InputError("bearing.preload_N", preload, "the cold preload must be finite and > 0 [N]")
    ld = load_distribution_static(brg, Fa=F0, Fr=0.0, stiffness=stiffness)
    return float(2.0 * (float(ld.delta_a) - brg.A * np.sin(brg.alpha0)))


def pair_loads(brg: BallBearing, arrangement: str, preload, kind: str = "position", Fa=0.0, Fr=0.0, *,
               dT_inner: float = 0.0, dT_outer: float = 0.0, dT_ball: float | None = None,
               offset: float | None = None, stiffness: str = "nominal", spacer: float = 0.0,
               n_rpm: float | None = None, control: str = "outer", start: "PairLoads | None" = None,
               u_inner: float | None = None, with_stiffness: bool = False) -> PairLoads:
    r"""The loads of a preloaded pair's loaded bearing, and the pair's preload, with warm rings and balls.

    Parameters
    ----------
    brg : BallBearing   the bearing of both rows (angular contact, with its width)
    arrangement : str   ``"back_to_back"`` or ``"face_to_face"``
    preload : float     the cold preload F_0 [N] (each bearing's axial load at mounting, no external load)
    kind : str          ``"position"`` (ground faces or spacers) or ``"spring"`` (constant force)
    Fa, Fr : float      external axial load on the shaft and radial load at the pair's centre [N] (≥ 0; the
                        axial load towards the bearing whose outer ring is held: the spring yields to none)
    dT_inner, dT_outer, dT_ball : float  rises of the inner rings (with the shaft), outer rings (with the housing)
                        and balls above the mounting temperature [K] (dT_ball default: the rings' mean)
    offset : float      the position preload δ [m] (default :func:`pair_preload_offset` of ``preload``)
    stiffness : str     as :func:`thermobear.loads.load_distribution`
    spacer : float      length of equal inner and outer spacers between the bearings [m] (0: adjacent): the
                        bearings sit at ∓(B + spacer)/2, where the shaft's and housing's axial growth moves them
                        (:func:`~thermobear.loads.sets.warm_supports`; the cold offset does not depend on it)
    n_rpm : float       speed of the inner rings (with the shaft) [rpm], ≥ 0: the high-speed form (module docstring;
                        the offset stays the one mounted at rest); ``None`` (default): the static form
    control : str       the high-speed form's raceway control
                        (:func:`~thermobear.loads.highspeed.load_distribution_high_speed`)
    u_inner : float     the inner raceways' growth at ``n_rpm`` [m] (default: a free ring's,
                        :func:`~thermobear.contact.fits.raceway_growth`; on an interference seat
                        :func:`~thermobear.contact.fits.seated_raceway_growth`, less)
    start : PairLoads   a nearby answer of the high-speed form (e.g. a heat-up's last) whose loads, and its
                        bearings' ball equilibria, start the solve (default: the low-speed pair's loads); the answer is
                        the same to the solver's tolerance
    with_stiffness : bool  also the pair's axial, radial and tilt stiffness under the external loads
                        (``PairLoads.stiffness``: the static form's from the shaft's stiffness matrix, the high-speed
                        form's by central differences over six more load cases in the same call)

    Returns
    -------
    PairLoads

    Raises
    ------
    InputError     bad input; loads the warm contacts cannot carry (named ``Fa, Fr, M (shaft loads)``); a warm
                   bearing with no clearance left (``dT_inner``: its contact angle would pass 0)
    NoEquilibrium, NoConvergence   as :func:`~thermobear.loads.sets.shaft_loads`, at speed as
                   :func:`~thermobear.loads.shaftspeed.shaft_loads_high_speed`

    Notes
    -----
    One :func:`~thermobear.loads.sets.bearing_set` call on two load cases, the external loads and none (rigid rings,
    low speed: the centrifugal effects are not in the preload); with ``n_rpm`` one
    :func:`~thermobear.loads.shaftspeed.shaft_loads_high_speed` call on the same two cases, the supports warm and at
    speed.  At n → 0 the two agree (to ~10⁻⁸ relative).  The loaded bearing's tilting moment in the pair is not
    returned: a single-bearing scene holds its tilt.

    Examples
    --------
    A 7014C back-to-back pair preloaded to 300 N cold: the inner rings 10 K warmer than the outer rings raise the
    preload (the balls at the rings' mean).

    >>> from thermobear.contact.geometry import bearing
    >>> b = bearing("7014C")
    >>> cold = pair_loads(b, "back_to_back", 300.0, Fr=2020.0)
    >>> warm = pair_loads(b, "back_to_back", 300.0, Fr=2020.0, dT_inner=20.0, dT_outer=10.0)
    >>> round(cold.preload, 6), round(cold.Fa), round(cold.Fr), round(warm.preload)
    (300.0, 431, 1010, 1381)

    At 12 000 rpm, cold: the balls' centrifugal force and the inner rings' centrifugal growth raise the preload.

    >>> fast = pair_loads(b, "back_to_back", 300.0, Fr=2020.0, n_rpm=12000.0)
    >>> round(fast.preload), round(fast.Fa), round(fast.Fr)
    (1269, 1352, 1010)

    The pair's axial and radial stiffness at rest under its preload alone [N/µm] (twice a bearing's axial one), and
    its tilt stiffness [N m/mrad]: back to back, then face to face.

    >>> [round(k * 1e-6, 1) for k in pair_loads(b, "back_to_back", 300.0, with_stiffness=True).stiffness[:2]]
    [94.2, 530.2]
    >>> [round(pair_loads(b, a, 300.0, with_stiffness=True).stiffness[2] * 1e-3) for a in PAIR_ARRANGEMENTS]
    [288, 10]
    """
    if arrangement not in PAIR_ARRANGEMENTS:
        raise InputError("bearing.arrangement", arrangement, " or ".join(PAIR_ARRANGEMENTS))
    if kind not in PRELOAD_KINDS:
        raise InputError("bearing.preload", kind, " or ".join(PRELOAD_KINDS))
    for name, v in (("Fa", Fa), ("Fr", Fr)):
        if not (np.isfinite(v) and v >= 0):
            raise InputError(name, v, "must be finite and >= 0 [N]")
    if kind == "spring":
        pre = dict(preload_force=float(preload))
        offset = None
        if not (np.isfinite(pre["preload_force"]) and pre["preload_force"] > 0):
            raise InputError("bearing.preload_N", preload, "the spring force must be finite and > 0 [N]")
    else:
        offset = pair_preload_offset(brg, preload, stiffness=stiffness) if offset is None else float(offset)
        pre = dict(preload_offset=offset)
    towards = ARRANGEMENTS[arrangement][0]          # the axial load on the first (held) bearing
    h = _STIFFNESS_STEP * max(float(preload), float(Fa), float(Fr), 1.0) if with_stiffness else 0.0
    hM = h * 0.5 * brg.dm                           # (the moment's step: h at the pitch radius)
    Fa2, Fr2, M2 = _cases(towards, float(Fa), float(Fr), 0.0 if n_rpm is None else h, hM)   # (stiffness: 6 more)
    start = None if with_stiffness else start       # (its cases are the two of the loads alone)
    if n_rpm is None:
        s = bearing_set(brg, arrangement, Fa2, Fr2, **pre, dT_inner=dT_inner, dT_outer=dT_outer, dT_ball=dT_ball,
                        stiffness=stiffness, spacer=float(spacer))
    else:
        n = float(n_rpm)
        if not (np.isfinite(n) and n >= 0):
            raise InputError("n_rpm", n_rpm, "the inner rings' speed must be finite and >= 0 [rpm]")
        sups, _ = duplex_supports(brg, arrangement, **pre, spacer=float(spacer))
        if dT_inner or dT_outer or dT_ball or n > 0:
            sups = warm_supports(sups, dT_inner, dT_outer, dT_ball, n_rpm=n, u_inner=u_inner)
        s = shaft_loads_high_speed(sups, Fa2, Fr2, n, M=M2, control=control, stiffness=stiffness,
                                   start=None if start is None or start.start is None else start.start)
    R, k = s.reactions, int(np.argmax(s.reactions[0, :, 0]))     # (cases, 2 bearings, 5); the loaded bearing
    # without an external radial load the bearings' radial reactions are the solver's residual (≈ 1e-14 N): 0
    Fr_k = float(np.hypot(R[0, k, 1], R[0, k, 3])) if float(Fr) > 0.0 else 0.0
    return PairLoads(Fa=float(R[0, k, 0]), Fr=Fr_k, loaded=k,
                     Fa_other=float(R[0, 1 - k, 0]), preload=float(R[1, :, 0].mean()), offset=offset,
                     start=None if n_rpm is None or with_stiffness else s,
                     stiffness=_stiffness(s, n_rpm is None, towards * h, h, hM) if with_stiffness else None)


def _cases(towards: float, Fa: float, Fr: float, h: float, hM: float) -> tuple:
    """(Fa, Fr, M) of the shaft's load cases [N, N, N m]: the external loads and none; with a step ``h`` > 0 six more,
    Fa ± h, Fr ± h, M ± hM (the high-speed stiffness's central differences); the axial loads ``towards`` the held
    bearing."""
    A, R, M = [towards * Fa, 0.0], [Fr, 0.0], [0.0, 0.0]
    if h:
        A += [towards * (Fa + h), towards * (Fa - h)] + [towards * Fa] * 4
        R += [Fr, Fr, Fr + h, Fr - h, Fr, Fr]
        M += [0.0] * 4 + [hM, -hM]
    return A, R, M


def _stiffness(s, static: bool, dFa: float, dFr: float, dM: float) -> tuple:
    """(axial [N/m], radial [N/m], tilt [N m/rad]) stiffness of a solved pair ``s`` under its first load case: the
    static form's from the inverse of its stiffness matrix at the pair's centre (the other displacements free), the
    high-speed form's from the shaft displacements of its cases 2–7 (the external loads Fa ± dFa, Fr ± dFr [N] and
    the moment ± dM [N m] on the shaft)."""
    if static:
        C = np.linalg.inv(np.asarray(s.stiffness)[0])
        return float(1.0 / C[0, 0]), float(1.0 / C[1, 1]), float(1.0 / C[2, 2])
    q = np.asarray(s.q)
    return (float(2.0 * dFa / (q[2, 0] - q[3, 0])), float(2.0 * dFr / (q[4, 1] - q[5, 1])),
            float(2.0 * dM / (q[6, 2] - q[7, 2])))
