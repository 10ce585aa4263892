r"""The engineering answers of a solved scene: ratings, static safety, contact pressure, κ, a_ISO, lives, clearance.

:func:`check_static_safety` refuses, before any solve, a scene whose static equivalent load is beyond the
refused static safety (:data:`thermobear.validity.LIMITS` ``s0``: s0 < 0.5, twice the ISO 76 rating — the same
limit as the refused contact pressure, 4200·2^(1/3) MPa, since p_max ∝ Q^(1/3)).  :func:`scene_ratings` gives the
answers at the steady state's temperatures (:class:`Ratings`):

* C0 (ISO 76:2006 [1]) and C (ISO 281:2007 [2]) as the bearing's data state them (catalogue or scene), else from
  the internal geometry; P0 and P (F_r the resultant
  √(F_r² + F_z²); the moments have no term in the standards' equivalent loads), s0 = C0/P0 (unloaded: s0 and the
  lives infinite, a_ISO at its cap);
* the largest Hertz pressure of each ring from the solved contacts (Harris 2001 eq 6.47);
* κ = ν/ν1 (ISO 281 ν1 at the speed and d_m) with ν at the operating temperature — the mean of the inner and outer
  raceway temperatures of the steady state — e_C of the scene's contamination level (ISO 281 simplified table,
  :data:`thermobear.rating.iso281.CONTAMINATION_LEVELS`), a_ISO, L10 and L10m in hours, and the ISO/TS 16281 [3] reference life
  L10r of the solved ball loads (hours);
* the operating clearance (:func:`thermobear.contact.fits.operating_clearance`) of the mounted radial bearing at the ring,
  ball, shaft and housing temperatures, with the scene's fits or the catalogue-typical fit for the load
  (:func:`typical_fits`), stated.

Outside the standards' domain the answer says so as named OutsideValidity warnings: s0 < 1, κ outside
0.1 … 4, the clearance consumed (a radial preload: :func:`preload_warnings`, its compression and ball load), a
load below SKF's requisite minimum load (:mod:`thermobear.rating.minimum_load`: radial of a deep groove bearing,
axial of an angular contact or thrust one).

References
----------
.. [1] ISO 76:2006, Rolling bearings — Static load ratings.
.. [2] ISO 281:2007, Rolling bearings — Dynamic load ratings and rating life (§9.3.3 κ, ν1; Table 11 e_C).
.. [3] ISO/TS 16281:2008, Rolling bearings — Methods for calculating the modified reference rating life.
.. [4] SKF Group (2018), *Rolling bearings* (catalogue PUB BU/P1 17000/1 EN), "Tolerances and resultant fits":
   fits for solid steel shafts (radial ball bearings) and for cast iron and steel housings.
"""
from __future__ import annotations

from dataclasses import asdict, dataclass, field

import numpy as np

from thermobear.contact.fits import T_REF_C, clearance_preload, operating_clearance
from thermobear.contact.geometry import BallBearing, radial_clearance
from thermobear.contact.materials import material
from thermobear.coupled.pipeline import sampled_lubricant
from thermobear.errors import InputError
from thermobear.loads import loads_text
from thermobear.rating.iso16281 import rating_angle, reference_life
from thermobear.rating.iso76 import static_equivalent_load
from thermobear.rating.iso281 import (A_ISO_MAX, basic_rating_life, contamination_factor, fatigue_load_limit,
                                      life_modification_factor, reference_viscosity, viscosity_ratio)
from thermobear.rating.life import equivalent_loads, stated_ratings
from thermobear.rating.minimum_load import (AXIAL_KINDS, minimum_axial_load, minimum_axial_load_factor,
                                            minimum_load_factor, minimum_radial_load)
from thermobear.thermal.builders import Machine, seat_interferences
from thermobear.validity import LIMITS, check, collect

__all__ = ["PRELOAD_OUTPUTS", "RATING_OUTPUTS", "Ratings", "check_static_safety", "inner_seat", "operating_lives", "operating_temperature_C",
           "preload_warnings", "rating_samples", "scene_clearance", "scene_ratings", "scene_ratings_many",
           "typical_fits"]

_LOAD_FIELDS = "operation (Fa_N, Fr_N, Fz_N)"


def _static(scene):
    """(C, C0, P, P0) of a scene's bearing and loads [N] (F_r the radial resultant); C and C0 as the bearing's data
    state them (the catalogue's or the scene's ``C_kN`` / ``C0_kN``), else from its geometry
    (:func:`~thermobear.rating.life.stated_ratings`)."""
    C, C0 = stated_ratings(scene.bearing)[:2]
    P, P0 = equivalent_loads(scene.bearing, float(np.hypot(scene.Fr, scene.Fz)), float(scene.Fa), C0)
    return C, C0, P, P0


def check_static_safety(scene, C0=None) -> None:
    """Refuse (InputError, before any solve) a scene whose static safety s0 = C0/P0 is below the refused limit
    (:data:`thermobear.validity.LIMITS` ``s0``), naming the loads, the limit and the bearing's C0 (``C0`` [N]: its
    stated or ISO 76 rating, :func:`~thermobear.rating.life.stated_ratings`, where the caller has it, e.g. once for the scenes of one bearing).

    >>> import thermobear as tb
    >>> s = tb.load_scene(tb.example_path("oil_bath_6208.toml"))
    >>> check_static_safety(s)
    >>> try:
    ...     check_static_safety(s.with_(Fr=40000.0))
    ... except InputError as e:
    ...     print(str(e)[:94])
    operation (Fa_N, Fr_N, Fz_N) = 'Fa 0 N, Fr 40000 N' — static safety s0 0.4971 - must be >= 0.5

    One bearing of a preloaded pair (``arrangement``) is checked under its own loads where the pair's are solved
    (its cold loads at speed before a heat-up's or a steady loop's first thermal solve, each step and piece after,
    ``thermobear loads``): the pair's external loads are not one bearing's.
    """
    b = scene.bearing
    if b.kind == "thrust" and (scene.Fr or scene.Fz) or getattr(scene, "arrangement", None) is not None:
        return                                    # (thrust: no ISO P0 for it, the load solvers say what is wrong)
    C0 = stated_ratings(b)[1] if C0 is None else C0
    P0 = float(static_equivalent_load(float(np.hypot(scene.Fr, scene.Fz)), float(scene.Fa), rating_angle(b), b.kind))
    if P0 > 0:
        check("s0", C0 / P0, _LOAD_FIELDS, warn=False, given=loads_text(scene.Fa, scene.Fr, None, scene.Fz),
              what=f"P0 = {P0:.4g} N against C0 = {C0:.4g} N of {b.name or 'the bearing'}, ISO 76")


def typical_fits(brg: BallBearing, P, C, rotating: str = "inner") -> tuple:
    """(shaft, housing, why): the catalogue-typical ISO 286 fits of a radial ball bearing for its load [4].

    Rotating inner ring load: the shaft by bore and load (P ≤ 0.05 C light: js5 to 17 mm, j6 to 100 mm, k6 to
    140 mm; P > 0.05 C normal and heavy: js5 to 10 mm, j5 to 17, k5 to 100, m5 to 140, m6 to 200 mm), the housing
    H7 (stationary outer ring load, loads of all kinds).  Rotating outer ring load: the shaft h6 (the classes
    tabulated here have no g6), the housing M7 (light), N7 (P > 0.05 C) or P7 (P > 0.1 C).

    >>> from thermobear.contact.geometry import bearing
    >>> typical_fits(bearing("6208"), 2000.0, 30000.0)[:2]
    ('k5', 'H7')
    """
    d = float(brg.bore or 0.0) * 1e3
    light = P <= 0.05 * C
    if rotating == "outer":
        housing = "M7" if light else ("P7" if P > 0.1 * C else "N7")
        return "h6", housing, f"rotating outer ring load, P/C = {P / C:.3g}: h6 / {housing} (SKF 2018 fit tables)"
    steps = ((17, "js5"), (100, "j6"), (140, "k6")) if light else ((10, "js5"), (17, "j5"), (100, "k5"),
                                                                   (140, "m5"), (200, "m6"))
    shaft = next((z for top, z in steps if d <= top), steps[-1][1])
    return shaft, "H7", (f"rotating inner ring load, P/C = {P / C:.3g} ({'light' if light else 'normal/heavy'}), "
                         f"d = {d:g} mm: {shaft} / H7 (SKF 2018 fit tables)")


@dataclass(frozen=True)
class Ratings:
    """Ratings, safety, pressures, lives and clearance of one solved operating point (SI; lives in hours).

    Attributes
    ----------
    C_N, C0_N, P_N, P0_N, s0 : ratings, equivalent loads [N] and static safety [-]
    p_max_Pa : ring → largest Hertz pressure [Pa]
    T_operating_C, nu_m2_s, nu1_m2_s, kappa : the temperature of κ [°C], ν and ν1 [m²/s], κ [-]
    contamination, e_C, a_ISO : cleanliness level, e_C and the life modification factor [-]
    L10_h, L10m_h, L10r_h : basic, modified and ISO/TS 16281 reference rating lives [h]
    clearance_um : unmounted, mounted, operating diametral clearance and the one the loads used [µm], the fits and
                   the temperatures (:func:`scene_clearance`; with ``models.clearance`` = operating the fixed point's)
    warnings : the named OutsideValidity warnings of these answers
    """

    C_N: float
    C0_N: float
    P_N: float
    P0_N: float
    s0: float
    p_max_Pa: dict
    T_operating_C: float
    nu_m2_s: float
    nu1_m2_s: float
    kappa: float
    contamination: str
    e_C: float
    a_ISO: float
    L10_h: float
    L10m_h: float
    L10r_h: float | None
    clearance_um: dict
    warnings: list = field(default_factory=list)

    def as_dict(self) -> dict:
        d = asdict(self)
        d["warnings"] = [w.as_dict() for w in self.warnings]
        return d

    def lines(self) -> list:
        """A short table for the text answer."""
        p = self.p_max_Pa
        return ["Ratings (ISO 76, ISO 281, ISO/TS 16281)",
                f"  C0 {self.C0_N:9.0f} N   P0 {self.P0_N:9.0f} N   "
                + (f"s0 {self.s0:7.3g}" if np.isfinite(self.s0) else "s0 — (no static load)"),
                f"  C  {self.C_N:9.0f} N   P  {self.P_N:9.0f} N   p_max inner {p['inner'] / 1e6:6.0f} MPa, "
                f"outer {p['outer'] / 1e6:6.0f} MPa",
                f"  kappa {self.kappa:.3g} (nu {self.nu_m2_s * 1e6:.3g} cSt at {self.T_operating_C:.1f} °C, "
                f"nu1 {self.nu1_m2_s * 1e6:.3g} cSt{'; a_ISO at kappa = 4, ISO 281' if self.kappa > 4.0 else ''})   "
                f"e_C {self.e_C:g} ({self.contamination})   a_ISO {self.a_ISO:.3g}",
                ("  L10, L10m: unloaded (P = 0), no fatigue life" + ("" if self.L10r_h is None else
                 f"   L10r {self.L10r_h:.4g} h (ISO/TS 16281, the solved ball loads: a preload)")
                 if not self.P_N > 0 else
                 f"  L10 {self.L10_h:.4g} h   L10m {self.L10m_h:.4g} h (ISO 281 × a_ISO)" +
                 ("" if self.L10r_h is None else f"   L10r {self.L10r_h:.4g} h (ISO/TS 16281, the solved ball loads)")),
                *self._clearance_lines()]

    def _clearance_lines(self) -> list:
        c = self.clearance_um
        if "operating" not in c:
            return [f"  clearance: {c.get('why', 'not applicable')}"]
        return [f"  clearance mounted {c['mounted']:.2f} µm, operating {c['operating']:.2f} µm, in the loads "
                f"{c['used']:.2f} µm" + (f" (fixed point, {c['iterations']} iterations, residual "
                                         f"{c['residual_um']:.1e} µm)" if "iterations" in c else " (as given)"),
                f"  fits {c['shaft_fit']} / {c['housing_fit']}: {c['fits_from']}"] + (
                    [f"  ({c['note']})"] if c.get("note") else [])


def _num(v):
    """A float, or an array of one per operating point."""
    return float(v) if np.ndim(v) == 0 else np.asarray(v, float)


def _node_T(T, roles, names, role):
    """Temperature [°C] (a float, or an array over operating points) of the first node of ``names`` the network
    has, else of the node of ``role``."""
    for n in names:
        if n in T:
            return _num(T[n]), n
    node = roles.get(role)
    return _num(T[node]), node


def _fits(scene, static=None) -> tuple:
    """(shaft class or None, housing class or None, the machine's seats as :func:`operating_clearance` keywords, the
    answer's fit labels) of a scene's bearing (:func:`scene_clearance`)."""
    b = scene.bearing
    C, _, P, _ = _static(scene) if static is None else static        # (static: the caller's _static(scene))
    typ = typical_fits(b, P, C, scene.rotating)
    shaft, housing = scene.shaft_fit or typ[0], scene.housing_fit or typ[1]
    given = scene.shaft_fit is not None and scene.housing_fit is not None
    out = {"shaft_fit": shaft, "housing_fit": housing, "fits_from": "the scene" if given else typ[2]}
    seats = {}
    if isinstance(scene.network, Machine) and not given:
        # a machine described by its dimensions: a ring whose fit the scene does not state sits on the seat of its
        # network's joint (its interference or the usual fit, thermobear.thermal.builders.seat_interferences)
        m = scene.network
        (I_i, why_i), (I_o, why_o) = seat_interferences(m)
        seats = dict(shaft_bore=m.shaft.bore, shaft_material=material(m.shaft.material),
                     housing_material=material(m.housing.material))
        label = (lambda I, why: f"{why.split(' ')[0]} ({I * 1e6:.1f} µm)" if "probable" in why  # noqa: E731
                 else f"{I * 1e6:.1f} µm")
        whys = []
        if scene.shaft_fit is None:
            shaft, seats["I_inner_m"], out["shaft_fit"] = None, I_i, label(I_i, why_i)
            whys.append(f"shaft {why_i}")
        if scene.housing_fit is None:
            housing, seats["I_outer_m"], out["housing_fit"] = None, I_o, label(I_o, why_o)
            whys.append(f"housing {why_o}")
        out["fits_from"] = ("the machine's seats, as its network's joints: " + ", ".join(whys)
                            + ("" if len(whys) == 2 else "; the other ring's fit from the scene"))
    if b.bore is None or b.outer_diameter is None:
        out["fits_from"] = "no fit: the bearing has no bore / outside diameter"
        shaft = housing = None
        seats = {}
    return shaft, housing, seats, out


def inner_seat(scene) -> dict:
    """The inner ring's seat of a scene as :func:`~thermobear.contact.fits.operating_clearance` keywords (``shaft``
    class or ``I_inner_m``, ``shaft_bore``, ``shaft_material``), as :func:`scene_clearance` takes it: the scene's
    fit, else its machine's seat, else the typical fit for its loads; an empty dict where the ring has no fit."""
    shaft, _, seats, _ = _fits(scene)
    out = {k: seats[k] for k in ("I_inner_m", "shaft_bore", "shaft_material") if k in seats}
    if shaft is not None:
        out["shaft"] = shaft
    return out if ("shaft" in out or "I_inner_m" in out) else {}


def scene_clearance(scene, T_C: dict, roles: dict, *, static=None) -> dict:
    """Unmounted, mounted (fits at 20 °C) and operating diametral clearance [µm] of a scene's bearing at the node
    temperatures ``T_C`` (node → °C, or → an array of one per operating point: then the operating clearance and the
    temperatures are arrays too; ``roles``: role → node), with the scene's fits (``shaft_fit``, ``housing_fit``), else —
    a scene that describes its machine — the seats of its network's joints
    (:func:`thermobear.thermal.builders.seat_interferences`: its ``interference_um`` or the usual fit, with its shaft's
    and housing's materials), else the typical fits for its load (:func:`typical_fits`), as
    :func:`~thermobear.contact.fits.operating_clearance` gives them: the ring
    temperatures from the nodes ``inner_ring`` / ``outer_ring`` (else the inner / outer role), the balls', the
    shaft's and housing's (else the ring's), the inner ring's speed when it rotates (:func:`_clearance_at`, which
    :func:`scene_ratings_many` calls for groups of points).

    >>> import thermobear as tb
    >>> s = tb.load_scene(tb.example_path("oil_bath_6208.toml"))
    >>> c = scene_clearance(s, {"ball": 20.0, "ir": 20.0, "or": 20.0}, {"ball": "ball", "inner": "ir", "outer": "or"})
    >>> round(c["mounted"], 2), c["shaft_fit"]
    (1.69, 'k5 (13.5 µm)')
    """
    shaft, housing, seats, out = _fits(scene, static)
    return {**out, **_clearance_at(scene.bearing, shaft, housing, seats, T_C, roles,
                                   scene.n_rpm if scene.rotating == "inner" else 0.0)}


def _clearance_at(b, shaft, housing, seats: dict, T_C: dict, roles: dict, n_in) -> dict:
    """The clearance values of :func:`scene_clearance` [µm] for its fits (:func:`_fits`) at the node temperatures
    ``T_C`` and inner-ring speeds ``n_in`` [rpm] (floats, or arrays of one per operating point)."""
    (Ti, ni), (To, no) = _node_T(T_C, roles, ("inner_ring",), "inner"), _node_T(T_C, roles, ("outer_ring",), "outer")
    Tb, nb = _node_T(T_C, roles, (), "ball")
    (Ts, ns), (Th, nh) = _node_T(T_C, roles, ("shaft",), "inner"), _node_T(T_C, roles, ("housing",), "outer")
    # mounted (20 °C, at rest) and operating in one call: a leading axis of two states
    T2 = [np.stack([np.full_like(v, T_REF_C), v]) for v in np.broadcast_arrays(*(np.asarray(v, float)
                                                                               for v in (Ti, To, Tb, Ts, Th, n_in)))]
    n2 = np.stack([np.zeros_like(T2[5][1]), T2[5][1]])
    Pd = operating_clearance(b, shaft=shaft, housing=housing, T_inner_C=T2[0], T_outer_C=T2[1], T_ball_C=T2[2],
                             T_shaft_C=T2[3], T_housing_C=T2[4], n_rpm=n2, **seats).Pd
    return dict(unmounted=b.Pd * 1e6, mounted=float(np.ravel(Pd[0])[0]) * 1e6, operating=_num(Pd[1]) * 1e6,
                used=b.Pd * 1e6,
                temperatures_C={"inner ring": Ti, "outer ring": To, "balls": Tb, "shaft": Ts, "housing": Th},
                nodes={"inner ring": ni, "outer ring": no, "balls": nb, "shaft": ns, "housing": nh})


def scene_ratings(scene, steady, losses=None) -> Ratings:
    """The ratings of a scene at its solved steady state (:class:`~thermobear.coupled.steady.SteadyState`;
    ``losses``: its loss result, default ``steady.losses``), with the named warnings (module docstring): one point of
    :func:`scene_ratings_many`.

    >>> import thermobear as tb
    >>> s = tb.load_scene(tb.example_path("oil_bath_6208.toml"))
    >>> r = scene_ratings(s, tb.steady_state(s))
    >>> round(r.C0_N), round(r.s0, 2), r.clearance_um["shaft_fit"]
    (19886, 9.94, 'k5 (13.5 µm)')
    """
    return scene_ratings_many([scene], [steady], None if losses is None else [losses])[0]


def scene_ratings_many(scenes, states, losses=None) -> list:
    """The ratings (:class:`Ratings`) of many solved operating points, e.g. the rows of a sweep: per scene at its
    steady state (``losses``: their loss results, default each state's ``losses``).  The bearing's ratings and
    minimum load factor are looked up once per bearing, the equivalent loads once per load case, and the operating
    clearance once per group of points that share bearing, fits and network, for the arrays of their temperatures
    and speeds (:func:`scene_clearance`); the rest per point.

    >>> import thermobear as tb
    >>> s = tb.load_scene(tb.example_path("oil_bath_6208.toml"))
    >>> sc = [s.with_(n_rpm=n) for n in (2000.0, 4000.0)]
    >>> st = [tb.steady_state(x) for x in sc]
    >>> rt = scene_ratings_many(sc, st)
    >>> [round(r.kappa, 2) for r in rt], rt[1].as_dict() == scene_ratings(sc[1], st[1]).as_dict()
    ([5.81, 5.11], True)
    """
    scenes, states = list(scenes), list(states)
    losses = [None] * len(states) if losses is None else list(losses)
    statics: dict = {}
    for sc in scenes:
        if (k := (sc.bearing, sc.Fa, sc.Fr, sc.Fz)) not in statics:
            statics[k] = _static(sc)
    static = [statics[sc.bearing, sc.Fa, sc.Fr, sc.Fz] for sc in scenes]
    clears = _clearances(scenes, states, static)
    factors: dict = {}
    for sc in scenes:
        if sc.bearing not in factors:
            factors[sc.bearing] = _load_factor(sc.bearing)
    return [_ratings(sc, st, r, stc, clear, factors[sc.bearing])
            for sc, st, r, stc, clear in zip(scenes, states, losses, static, clears)]


def _clearances(scenes, states, static) -> list:
    """Per point, its clearance dict (:func:`scene_clearance` at its state's temperatures; a state's own where the
    loads were solved at it; the thrust bearing's reason none applies), evaluated once per group of points of one
    bearing, fit and network."""
    out: list = [None] * len(scenes)
    groups: dict = {}
    for i, (sc, st) in enumerate(zip(scenes, states)):
        if sc.bearing.kind == "thrust":
            out[i] = {"applies": False, "why": "thrust bearing: no radial clearance or radial fits (its axial play is "
                                               "set by the mounting)"}
        elif getattr(st, "clearance_um", None):
            out[i] = st.clearance_um
        else:
            shaft, housing, seats, fit = _fits(sc, static[i])
            key = (sc.bearing, sc.rotating == "inner", shaft, housing, tuple(sorted(seats.items())),
                   tuple(sorted(st.roles.items())), tuple(st.T_C))
            groups.setdefault(key, (shaft, housing, seats, []))[3].append((i, fit))
    for (b, inner, *_), (shaft, housing, seats, members) in groups.items():
        idx = [i for i, _ in members]
        T = {k: np.array([float(states[i].T_C[k]) for i in idx]) for k in states[idx[0]].T_C}
        n = np.array([float(scenes[i].n_rpm) if inner else 0.0 for i in idx])
        c = _clearance_at(b, shaft, housing, seats, T, states[idx[0]].roles, n)
        for k, (i, fit) in enumerate(members):
            out[i] = {**fit, **c, "operating": float(c["operating"][k]),
                      "temperatures_C": {w: float(v[k]) for w, v in c["temperatures_C"].items()}}
    for i, (sc, c) in enumerate(zip(scenes, out)):
        if sc.bearing.kind == "angular_contact":
            out[i] = {**c, "note": "angular contact bearing: the diametral play its contact angle implies, "
                                   "P_d = 2A(1 − cos α0); in a pair the axial adjustment sets the contacts, not this play"}
    return out


def _ratings(scene, steady, r, static, clear: dict, factor) -> Ratings:
    """One point's :class:`Ratings` (:func:`scene_ratings_many`): its loss result ``r`` (None: the steady state's,
    its contacts' loads and ellipses alone), ``static`` = (C, C0, P, P0), its clearance dict and its bearing's minimum
    load factor (:func:`_load_factor`)."""
    b = scene.bearing
    C, C0, P, P0 = static
    if r is None and hasattr(steady, "contact_values"):     # (a SteadyState; any other state: its ``losses``)
        c = steady.contact_values("Q", "a", "b")
    else:
        c = getattr(steady.losses if r is None else r, "contacts", None)
    p = {}
    if c:
        for side in ("inner", "outer"):
            Q, a, bb = (np.asarray(c[side][k], float) for k in ("Q", "a", "b"))
            with np.errstate(divide="ignore", invalid="ignore"):
                p[side] = float(np.max(np.where(Q > 0, 1.5 * Q / (np.pi * a * bb), 0.0)))
    T_op = operating_temperature_C(steady.T_C, steady.roles)
    lv = operating_lives(scene, T_op, static=static)
    nu, nu1, kappa, e_C, a_iso = (float(lv[k]) for k in ("nu_m2_s", "nu1_m2_s", "kappa", "e_C", "a_ISO"))
    hours = 1e6 / (60.0 * float(scene.n_rpm))
    L10r = None
    if c and np.max(np.asarray(c["inner"]["Q"], float), initial=0.0) > 0:      # external loads or a preload
        ld = type("Balls", (), {"Q_i": np.ravel(c["inner"]["Q"]), "Q_o": np.ravel(c["outer"]["Q"])})
        L10r = float(reference_life(b, ld, C, rotating=scene.rotating).L10r) * hours
    s0 = C0 / P0 if P0 > 0 else np.inf
    with collect(replay=False) as got:
        if P0 > 0:
            check("s0", s0, _LOAD_FIELDS, what=f"P0 = {P0:.4g} N, C0 = {C0:.4g} N")
        check("kappa", kappa, "lubricant viscosity at the operating temperature",
              what=f"nu {nu * 1e6:.3g} cSt at {T_op:.1f} °C, nu1 {nu1 * 1e6:.3g} cSt")
        _minimum_load_check(scene, nu, clear, factor)
    looped = clear.get("choice") == "operating"           # the loads at the operating clearance: its own warning
    if "operating" in clear and not looped:
        advice = ("" if b.kind != "deep_groove" else
                  "; models.clearance = 'operating' without operation.T_C solves the preload" if scene.T_C is not None
                  else "; models.clearance = 'operating' solves the preload")
        got += preload_warnings(b, clear["operating"] * 1e-6, clear, f"at the answer's temperatures; the loads used "
                                f"{clear.get('used', b.Pd * 1e6):.3g} µm{advice}")
    return Ratings(C_N=C, C0_N=C0, P_N=P, P0_N=P0, s0=s0, p_max_Pa=p or {"inner": 0.0, "outer": 0.0},
                   T_operating_C=T_op, nu_m2_s=nu, nu1_m2_s=nu1, kappa=kappa, contamination=str(scene.contamination),
                   e_C=e_C, a_ISO=a_iso, L10_h=float(lv["L10_h"]), L10m_h=float(lv["L10m_h"]), L10r_h=L10r,
                   clearance_um=clear, warnings=list(got))


def preload_warnings(brg: BallBearing, Pd, c: dict, why: str) -> list:
    r"""The named warning of a radial preload: the operating clearance ``Pd`` [m] negative (``c`` the clearance
    dict of :func:`scene_clearance`, ``why`` where it arises), with the compression and ball load of the rings
    centred

    .. math:: δ_0 = −P_d/2, \qquad Q_0 = K_n δ_0^{1.5}

    (:func:`~thermobear.contact.fits.clearance_preload`; Harris & Kotzalas 2007 ch. 3 and 7): an
    :class:`~thermobear.errors.OutsideValidity` of :data:`thermobear.validity.LIMITS` ``operating_clearance``, or
    none with a clearance.

    Parameters
    ----------
    brg : BallBearing   the (radial) bearing
    Pd : float          operating diametral clearance [m]
    c : dict            ``mounted`` [µm], ``shaft_fit``, ``housing_fit`` (:func:`scene_clearance`)
    why : str           where the preload arises (in the warning's text)

    Returns
    -------
    list                the warning, or empty

    Examples
    --------
    >>> import thermobear as tb
    >>> c = {"mounted": 1.69, "shaft_fit": "k5", "housing_fit": "H7"}
    >>> w = preload_warnings(tb.bearing("6208"), -4e-6, c, "warm")
    >>> w[0].quantity, "compressed by 2 µm, Q0 = 34 N" in str(w[0])
    ('operating_clearance', True)
    """
    if not Pd < 0:
        return []
    Q0 = float(clearance_preload(brg, Pd))
    with collect(replay=False) as got:
        check("operating_clearance", Pd, "bearing clearance",
              what=f"{why}: mounted {c['mounted']:.2f} µm, fits {c['shaft_fit']} / {c['housing_fit']}; a radial "
                   f"preload, each ball compressed by {-0.5 * Pd * 1e6:.3g} µm, Q0 = {Q0:.3g} N between the centred "
                   f"rings{_looser_group(brg, Pd)}")
    return list(got)


def _looser_group(brg: BallBearing, Pd: float) -> str:
    """Advice where a preload arises: the next ISO 5753-1 clearance group's larger mid clearance, and whether it would
    leave a clearance at the same temperatures and fits (the groups' mid values: :func:`~thermobear.contact.geometry.
    radial_clearance`); '' where the bearing has no group or no larger one."""
    nxt = {"CN": "C3", "C3": "C4"}.get(brg.clearance_group or "")
    if brg.kind != "deep_groove" or nxt is None or brg.bore is None:
        return ""
    try:
        gain = sum(radial_clearance(brg.bore, nxt)) / 2.0 - sum(radial_clearance(brg.bore, brg.clearance_group)) / 2.0
    except InputError:                                  # (a bore outside ISO 5753-1's table)
        return ""
    keeps = Pd + gain > 0.0
    return (f"; a {nxt} bearing (+{gain * 1e6:.3g} µm mid clearance) would {'keep' if keeps else 'not keep'} a clearance "
            "here" + ("" if keeps else " (looser fits, or a larger group)"))


def _load_factor(brg: BallBearing):
    """A bearing's SKF minimum load factor as on file: ``minimum_axial_load_factor``'s row (angular contact and
    thrust bearings), else the radial k_r (:func:`~thermobear.rating.minimum_load.minimum_load_factor`); None where
    none is."""
    if brg.kind in AXIAL_KINDS:
        return minimum_axial_load_factor(brg)
    return minimum_load_factor(brg.kind, brg.series)


def _minimum_load_check(scene, nu_m2_s: float, clear: dict, factor) -> None:
    """Warn (:data:`thermobear.validity.LIMITS` ``minimum_load``) where the larger of a deep groove bearing's radial
    and axial load lies below SKF's requisite minimum load at the operating viscosity ``nu_m2_s``
    (:func:`~thermobear.rating.minimum_load.minimum_radial_load`, d_m = (d + D)/2 as SKF's; none where the loads were
    solved with a radial preload — ``clear``'s choice ``operating`` at a negative clearance —, nor where no k_r is on
    file; an estimated negative clearance is named beside), or an angular contact or thrust bearing's axial load below its
    minimum axial load (:func:`_minimum_axial_load_check`); ``factor``: the bearing's (:func:`_load_factor`)."""
    b = scene.bearing
    if b.kind in AXIAL_KINDS:
        _minimum_axial_load_check(scene, factor)
        return
    k_r = factor
    if k_r is None or not scene.n_rpm > 0 or (clear.get("choice") == "operating" and clear.get("used", 0.0) < 0.0):
        return                         # (the loads solved with a radial preload: SKF's "consider preloading")
    dm = 0.5 * (b.bore + b.outer_diameter) if b.bore is not None and b.outer_diameter is not None else b.dm
    F_rm = float(minimum_radial_load(k_r, nu_m2_s * 1e6, scene.n_rpm, dm))
    F = max(float(np.hypot(scene.Fr, scene.Fz)), abs(float(scene.Fa)))
    if F == 0.0:                       # (unloaded at speed: named as such, limits.point_warnings)
        return
    pre = ("; the operating clearance estimated at the answer's temperatures is negative: the radial preload it "
           "implies may meet F_rm (models.clearance = 'operating' solves the loads with it)"
           if clear.get("operating", 0.0) < 0.0 else "")
    check("minimum_load", F / F_rm, _LOAD_FIELDS,
          what=f"Fr {np.hypot(scene.Fr, scene.Fz):.4g} N, Fa {scene.Fa:.4g} N against F_rm {F_rm:.4g} N = k_r {k_r:g} "
               f"(ν n/1000)^(2/3) (d_m/100 mm)^2 kN at ν {nu_m2_s * 1e6:.3g} mm²/s, {scene.n_rpm:.6g} rpm, d_m = (d + D)/2 "
               f"(SKF 2018): the balls may skid — raise the load, preload the bearing, or check the load's unit{pre}")


def _minimum_axial_load_check(scene, got) -> None:
    """Warn (:data:`thermobear.validity.LIMITS` ``minimum_load``) where an angular contact bearing's (taken single) or a
    thrust bearing's axial load |Fa| lies below SKF's minimum axial load F_am = A (n/1000)² kN
    (:func:`~thermobear.rating.minimum_load.minimum_axial_load`; none where no A is on file: ``got`` the bearing's
    row, :func:`_load_factor`)."""
    if got is None or not scene.n_rpm > 0:
        return
    A, _, source = got                                   # (source names SKF's designation of the row)
    F_am = float(minimum_axial_load(A, scene.n_rpm))
    Fa = abs(float(scene.Fa))
    if Fa == 0.0 and scene.Fr == 0.0 and scene.Fz == 0.0:  # (unloaded at speed: named as such, limits.point_warnings)
        return
    angular = scene.bearing.kind == "angular_contact"
    single = ("; for a single bearing or a tandem pair: back-to-back and face-to-face pairs take a minimum radial "
              "load instead" if angular else "")
    check("minimum_load", Fa / F_am, _LOAD_FIELDS,
          what=f"Fa {Fa:.4g} N against F_am {F_am:.4g} N = A {A:g} (n/1000)^2 kN at {scene.n_rpm:.6g} rpm (SKF 2018 "
               f"p. {398 if angular else 469}{single}; A: {source}): the balls may skid — raise the "
               "axial load or preload, or check the load's unit")


def operating_temperature_C(T_C: dict, roles: dict):
    """The operating temperature of ISO 281's viscosity ratio [°C]: the mean of the inner and outer raceway
    (role) nodes of ``T_C`` (node → °C, or → arrays of one per operating point)."""
    return 0.5 * (_node_T(T_C, roles, (), "inner")[0] + _node_T(T_C, roles, (), "outer")[0])


def operating_lives(scene, T_op_C, nu_m2_s=None, *, static=None) -> dict:
    r"""ISO 281 [2] viscosity ratio, life modification factor and lives of a scene's bearing and loads at operating
    temperatures ``T_op_C`` [°C] (a float, or an array of one per operating point, e.g. the samples of an
    uncertainty band; :func:`operating_temperature_C`); ``nu_m2_s``: the lubricant's kinematic viscosity there
    [m²/s] (default: the scene's lubricant at ``T_op_C``).

    .. math:: \kappa = \nu / \nu_1, \qquad L_{10m} = a_{ISO}(\kappa, e_C C_u / P)\, (C/P)^3 \frac{10^6}{60 n}\ \mathrm{h}

    Returns a dict of ``nu_m2_s``, ``nu1_m2_s`` [m²/s], ``kappa``, ``e_C``, ``a_ISO`` [-], ``L10_h``, ``L10m_h`` [h]
    (unloaded, P = 0: a_ISO at its cap, the lives infinite).

    >>> import thermobear as tb
    >>> lv = operating_lives(tb.load_scene(tb.example_path("oil_bath_6208.toml")), np.array([40.0, 80.0]))
    >>> [round(float(k), 2) for k in lv["kappa"]], bool(lv["L10m_h"][0] > lv["L10m_h"][1])
    ([6.44, 1.4], True)
    """
    b = scene.bearing
    C, C0, P, _ = _static(scene) if static is None else static      # (static: the caller's _static(scene))
    n = float(scene.n_rpm)
    if not n > 0:
        raise InputError("operation.n_rpm", n, "ratings in hours need a speed > 0 [rpm]")
    T = np.asarray(T_op_C, float)
    nu = np.asarray(scene.lubricant.nu(T), float) * 1e-6 if nu_m2_s is None else np.asarray(nu_m2_s, float)
    nu1 = float(reference_viscosity(n, b.dm))
    kappa = np.asarray(viscosity_ratio(nu, nu1), float)
    e_C = float(contamination_factor(scene.contamination, b.dm))
    hours = 1e6 / (60.0 * n)
    if P > 0:
        kind = "thrust" if b.kind == "thrust" else "radial"
        a_iso = np.asarray(life_modification_factor(kappa, e_C * float(fatigue_load_limit(C0, b.dm)) / P, kind), float)
        L10 = float(basic_rating_life(C, P))
    else:                              # unloaded: no fatigue (ISO 281's a_ISO at its cap, the lives infinite)
        a_iso, L10 = np.full(kappa.shape, A_ISO_MAX), np.inf
    return {"nu_m2_s": _num(nu), "nu1_m2_s": nu1, "kappa": _num(kappa), "e_C": e_C, "a_ISO": _num(a_iso),
            "L10_h": L10 * hours, "L10m_h": _num(a_iso * (L10 * hours))}


#: the design answers an uncertainty band gives (:func:`rating_samples`): output name → unit
RATING_OUTPUTS = {"ratings.T_operating_C": "°C", "ratings.kappa": "-", "ratings.a_ISO": "-", "ratings.L10m_h": "h",
                  "ratings.clearance_op_um": "µm"}

#: a preloaded pair's answers an uncertainty band gives (:mod:`thermobear.coupled.preload`): the warm preload, the
#: loaded bearing's axial load and the warm pair's axial, radial and tilt stiffness → unit
PRELOAD_OUTPUTS = {"preload.warm_N": "N", "preload.Fa_N": "N", "preload.k_axial_warm_N_um": "N/µm",
                   "preload.k_radial_warm_N_um": "N/µm", "preload.k_tilt_warm_Nm_mrad": "N m/mrad"}


def rating_samples(scenes, states) -> dict:
    """The design answers of many solved operating points, e.g. the samples of an uncertainty band: output name
    (:data:`RATING_OUTPUTS`) → (n,) values, one per scene and its steady state (``states``: SteadyStates, or None
    where a point did not solve: NaN there).  The operating temperature, κ, a_ISO and L10m of :func:`operating_lives`
    and the operating clearance of :func:`scene_clearance` (radial bearings; with ``models.clearance`` =
    operating the fixed point's), each evaluated once per bearing and operating point for the arrays of
    temperatures of its samples — the same functions :func:`scene_ratings` evaluates for one point.

    >>> import thermobear as tb
    >>> s = tb.load_scene(tb.example_path("oil_bath_6208.toml"))
    >>> st = tb.steady_state(s)
    >>> out = rating_samples([s, s], [st, None])
    >>> round(float(out["ratings.kappa"][0]), 3) == round(scene_ratings(s, st).kappa, 3), bool(np.isnan(out["ratings.kappa"][1]))
    (True, True)
    """
    n = len(scenes)
    out = {k: np.full(n, np.nan) for k in RATING_OUTPUTS}
    groups: dict = {}
    for i, (sc, st) in enumerate(zip(scenes, states)):
        if st is not None and sc.n_rpm > 0:
            groups.setdefault((sc.bearing, sc.Fa, sc.Fr, sc.Fz, sc.n_rpm, sc.rotating, sc.contamination, sc.shaft_fit,
                               sc.housing_fit, tuple(sorted(st.roles.items())),
                               tuple(sorted(k for k in sc.samples if k.startswith("lubricant.")))), []).append(i)
    for idx in groups.values():
        sc, st0 = scenes[idx[0]], states[idx[0]]
        T = {k: np.array([states[i].T_C[k] for i in idx]) for k in st0.T_C}
        T_op = operating_temperature_C(T, st0.roles)
        lv = operating_lives(sc, T_op, sampled_lubricant([scenes[i] for i in idx]).nu(T_op) * 1e-6)  # cSt → m²/s
        for key, v in (("T_operating_C", T_op), ("kappa", lv["kappa"]), ("a_ISO", lv["a_ISO"]), ("L10m_h", lv["L10m_h"])):
            out[f"ratings.{key}"][idx] = v
        if sc.bearing.kind == "thrust":
            continue
        given = [getattr(states[i], "clearance_um", None) for i in idx]
        if all(g and "operating" in g for g in given):
            out["ratings.clearance_op_um"][idx] = [g["operating"] for g in given]
        else:
            out["ratings.clearance_op_um"][idx] = scene_clearance(sc, T, st0.roles)["operating"]
    return {k: v for k, v in out.items() if np.isfinite(v).any()}
