r"""Load ratings and rating life of one bearing at one load case: :func:`rating_life`.

Puts the standards' functions together for a :class:`~thermobear.contact.geometry.BallBearing`:
C (ISO 281) and C0 (ISO 76) from the internal geometry, P and P0 from the applied loads,
the static safety s0, the maximum contact pressure of each ring from the load distribution
(Hertz), L10, the ISO/TS 16281 reference life L10r from the ball loads, and — given the
operating viscosity and speed — κ, a_ISO and the modified lives L10m and L10mr.

Quantities outside the standards' domain are returned, not hidden: s0 < 1, p_max above the
4 200 MPa of ISO 76, κ outside 0.1–4, a_ISO at its cap of 50, groove radii above the ISO 281
reference each add a sentence to ``RatingLife.notes``.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from thermobear.errors import InputError, SolverError
from thermobear.schema import Field, check_value
from thermobear.arrays import instance_of
from thermobear.contact.geometry import BallBearing, bearing
from thermobear.loads.static import LoadDistribution, load_distribution
from thermobear.rating.iso76 import (contact_pressures, f0_radial, pressure_ratio, static_equivalent_load,
                                     static_load_rating, static_safety_factor)
from thermobear.rating.iso281 import (A_ISO_MAX, basic_rating_life, contamination_factor,
                                      dynamic_equivalent_load, dynamic_load_rating, fatigue_load_limit,
                                      life_modification_factor, modified_rating_life, radial_load_factors,
                                      reference_viscosity, viscosity_ratio)
from thermobear.rating.iso16281 import ReferenceLife, rating_angle, reference_life

__all__ = ["RatingLife", "rating_life", "load_ratings", "stated_ratings", "equivalent_loads"]


@dataclass(frozen=True)
class RatingLife:
    """Ratings and lives of one bearing at one load case (SI; lives in 10⁶ revolutions and hours).

    Attributes
    ----------
    C_N, C0_N : basic dynamic (ISO 281) and static (ISO 76) load ratings [N]
    P_N, P0_N : dynamic and static equivalent loads [N]
    s0 : static safety factor C0/P0 [-]
    p_max_Pa : {"inner": ..., "outer": ...} largest Hertz pressure of each ring [Pa] (None without
        a load distribution)
    pressure_ratio : max p_max / 4 200 MPa [-] (None without a load distribution)
    L10_Mrev, L10_h : basic rating life [10⁶ rev], [h] (hours need n_rpm)
    L10r_Mrev : ISO/TS 16281 basic reference rating life [10⁶ rev] (None without a load distribution)
    reference : the ISO/TS 16281 parts (raceway ratings, equivalent ball loads, P_ref), or None
    kappa, nu1_m2_s, e_C, C_u_N, a_ISO : viscosity ratio, reference viscosity [m²/s], contamination
        factor, fatigue load limit [N], life modification factor (None without viscosity and speed)
    L10m_Mrev, L10m_h : modified rating life a_ISO L10 [10⁶ rev], [h]
    L10mr_Mrev : modified reference rating life a_ISO(P_ref) L10r [10⁶ rev]
    notes : sentences naming every quantity outside the standards' domain
    """

    C_N: float
    C0_N: float
    P_N: float
    P0_N: float
    s0: float
    L10_Mrev: float
    p_max_Pa: dict | None = None
    pressure_ratio: float | None = None
    L10r_Mrev: float | None = None
    reference: ReferenceLife | None = None
    L10_h: float | None = None
    kappa: float | None = None
    nu1_m2_s: float | None = None
    e_C: float | None = None
    C_u_N: float | None = None
    a_ISO: float | None = None
    L10m_Mrev: float | None = None
    L10m_h: float | None = None
    L10mr_Mrev: float | None = None
    notes: tuple = field(default_factory=tuple)


def load_ratings(brg: BallBearing) -> tuple[float, float]:
    """(C, C0) of a bearing from its internal geometry [N]: ISO 281:2007 and ISO 76:2006.

    >>> from thermobear.contact.geometry import bearing
    >>> [round(x) for x in load_ratings(bearing("iso-dgbb"))]
    [22381, 11491]
    """
    a = rating_angle(brg)
    return (dynamic_load_rating(brg.D, brg.dm, brg.Z, a, brg.kind),
            float(static_load_rating(brg.D, brg.dm, brg.Z, a, brg.kind)))


def stated_ratings(brg: BallBearing) -> tuple[float, float, tuple[str, str]]:
    """(C, C0) of a bearing as its data state them [N] (the catalogue's or a scene's ``C_kN``, ``C0_kN``), each
    one the data lack from its internal geometry (:func:`load_ratings`), and where each comes from.

    >>> from thermobear.contact.geometry import bearing
    >>> C, C0, src = stated_ratings(bearing("6210"))
    >>> round(C), round(C0), src
    (35074, 23200, ('ISO 281 from the geometry', 'stated'))
    """
    C_iso, C0_iso = load_ratings(brg)
    geo = ("ISO 281 from the geometry", "ISO 76 from the geometry")
    return (C_iso if brg.C is None else float(brg.C), C0_iso if brg.C0 is None else float(brg.C0),
            (geo[0] if brg.C is None else "stated", geo[1] if brg.C0 is None else "stated"))


def equivalent_loads(brg: BallBearing, Fr: float, Fa: float, C0: float) -> tuple[float, float]:
    """(P, P0) of a single-row bearing [N]: ISO 281:2007 Table 3 and ISO 76:2006 Table 1.

    Deep groove bearings enter Table 3 with f0 Fa / C0 (f0 of ISO 76 at the bearing's γ), angular
    contact bearings with Fa / C0; thrust bearings (α = 90°) take axial load only, P = Fa.

    >>> from thermobear.contact.geometry import bearing
    >>> [round(x, 1) for x in equivalent_loads(bearing("iso-dgbb"), 1000.0, 500.0, 11490.0)]
    [1475.6, 1000.0]
    """
    a = rating_angle(brg)
    P0 = float(static_equivalent_load(Fr, Fa, a, brg.kind))
    if brg.kind == "thrust":
        if abs(np.cos(a)) > 1e-9 or Fr > 0:
            raise InputError("Fr", Fr, "ISO 281 P of thrust ball bearings is implemented for α = 90° and "
                             "pure axial load only [N]")
        return float(Fa), P0
    rel = f0_radial(brg.D * np.cos(a) / brg.dm) * Fa / C0 if brg.kind == "deep_groove" else Fa / C0
    X, Y, e = radial_load_factors(rel, a, brg.kind)
    return float(dynamic_equivalent_load(Fr, Fa, X, Y, e)), P0


def _loads(ld, Fa, Fr):
    """Applied loads from the arguments or the load distribution (one load case)."""
    if ld is not None:
        if np.ndim(ld.Q_i) != 1:
            raise InputError("ld", np.shape(ld.Q_i), "one load case (per-ball loads of shape (Z,)); "
                             "call rating_life per case")
        for name, given, own in (("Fa", Fa, float(ld.Fa)), ("Fr", Fr, float(ld.Fr))):
            if given is not None and abs(given - own) > 1e-9 * max(1.0, abs(own)):
                raise InputError(name, given, f"differs from the load distribution's {own:g} N; give one")
        return float(ld.Fa), float(ld.Fr)
    Fa = 0.0 if Fa is None else Fa
    Fr = 0.0 if Fr is None else Fr
    for name, v in (("Fa", Fa), ("Fr", Fr)):
        if isinstance(v, bool) or not isinstance(v, (int, float, np.floating)) or not (np.isfinite(v) and v >= 0):
            raise InputError(name, v, "must be one finite load >= 0 [N]")
    if Fa == 0 and Fr == 0:
        raise InputError("Fa, Fr", (Fa, Fr), "no load: an unloaded bearing has no finite rating life")
    return float(Fa), float(Fr)


_RATING = Field.number("N", 0.0, lo_open=True)      #: a load rating given: finite and > 0 [N]


def _osculation_note(brg):
    lim = (0.54, 0.54) if brg.kind == "thrust" else (0.52, 0.53)
    if brg.fi > lim[0] + 1e-12 or brg.fo > lim[1] + 1e-12:
        return (f"groove radii fi = {brg.fi:g}, fo = {brg.fo:g} exceed the ISO 281 reference "
                f"({lim[0]:g} D inner, {lim[1]:g} D outer): the tabulated f_c overstates C")
    return None


def _stated_notes(brg, C_iso, C0_iso) -> list:
    """Notes where the bearing's data state a rating (``C_kN``, ``C0_kN``) more than 0.5 % from the ISO value of its
    geometry that :func:`rating_life` used (``C_iso``, ``C0_iso``; None: a rating the caller gave)."""
    out = []
    for name, iso, stated, arg in (("C", C_iso, brg.C, "C_N"), ("C0", C0_iso, brg.C0, "C0_N")):
        if iso is not None and stated is not None and abs(float(stated) / iso - 1.0) > 5e-3:
            out.append(f"{name} = {iso / 1e3:.4g} kN from the geometry (ISO {'281' if name == 'C' else '76'}); the "
                       f"bearing's data state {float(stated) / 1e3:.4g} kN, which a scene's ratings use: give "
                       f"{arg}={float(stated):.6g} for that")
    return out


def rating_life(brg: BallBearing, ld: LoadDistribution | None = None, *, Fa=None, Fr=None, nu_m2_s=None,
                n_rpm=None, contamination="normal_cleanliness", rotating="inner", C_N=None,
                C0_N=None) -> RatingLife:
    r"""Load ratings, static safety, contact pressures and rating lives of a ball bearing.

    Parameters
    ----------
    brg : BallBearing                 or its catalogue name (:func:`~thermobear.contact.geometry.bearing`)
    ld : LoadDistribution, optional   one load case; computed from Fa, Fr (rigid rings, low speed,
                                      :func:`thermobear.loads.static.load_distribution`) if not given
    Fa, Fr : float                    axial and radial load [N] (default: those of ``ld``)
    nu_m2_s : float, optional         operating kinematic viscosity (base oil of a grease) [m²/s]
    n_rpm : float, optional           speed of the rotating ring [rpm]
    contamination : str or float      ISO 281 cleanliness level (see
                                      :data:`thermobear.rating.iso281.CONTAMINATION_LEVELS`, middle of
                                      the simplified table's range) or e_C in [0, 1]
    rotating : str                    ``"inner"`` or ``"outer"``: the ring rotating relative to the load
                                      (ISO/TS 16281 equivalent ball loads)
    C_N, C0_N : float, optional       ratings to use instead of the ISO values from the geometry
                                      (e.g. a maker's) [N]

    Returns
    -------
    RatingLife

    Notes
    -----
    C, C0: ISO 281:2007 / ISO 76:2006 from D, dm, Z, α (not the catalogue's stored values; where those differ by
    more than 0.5 %, a note says so — a scene's ratings, :func:`stated_ratings`, use the stored ones).
    P = X Fr + Y Fa (ISO 281 Table 3), P0 = max(X0 Fr + Y0 Fa, Fr) (ISO 76 Table 1),
    L10 = (C/P)³, L10r from the ball loads (ISO/TS 16281); with ν and n:
    κ = ν/ν1(n, dm), C_u = C0/22 (dm ≤ 100 mm), a_ISO(κ, e_C C_u/P) ≤ 50, L10m = a_ISO L10 and
    L10mr = a_ISO(κ, e_C C_u/P_ref) L10r.  Hours: L_h = 10⁶ L / (60 n).
    Raises InputError for an unloaded bearing (no finite life), a radial load on a flat thrust
    bearing, or inputs outside the standards' tables; the rest is reported in ``notes``.

    Examples
    --------
    >>> from thermobear.contact.geometry import bearing
    >>> r = rating_life(bearing("iso-dgbb"), Fr=1000.0, nu_m2_s=20e-6, n_rpm=3000.0)
    >>> round(r.C_N), round(r.L10_Mrev), round(r.L10r_Mrev), round(r.s0, 2)
    (22381, 11212, 11518, 11.49)
    """
    brg = instance_of(brg, BallBearing, "brg", bearing)
    Fa, Fr = _loads(None if ld is None else instance_of(ld, LoadDistribution, "ld"), Fa, Fr)
    C_iso, C0_iso = load_ratings(brg)
    C = C_iso if C_N is None else check_value(C_N, _RATING, "C_N")
    C0 = C0_iso if C0_N is None else check_value(C0_N, _RATING, "C0_N")
    P, P0 = equivalent_loads(brg, Fr, Fa, C0)
    s0 = float(static_safety_factor(C0, P0))
    L10 = float(basic_rating_life(C, P))
    notes = []
    if s0 < 1.0:
        notes.append(f"static equivalent load P0 = {P0:.4g} N exceeds C0 = {C0:.4g} N (s0 = {s0:.3g})")
    osc = _osculation_note(brg)
    if osc:
        notes.append(osc)
    notes += _stated_notes(brg, C_iso if C_N is None else None, C0_iso if C0_N is None else None)
    kw = {}
    if ld is None:
        try:
            ld = load_distribution(brg, Fa=Fa, Fr=Fr)
        except SolverError as exc:
            notes.append(f"no load distribution ({type(exc).__name__}: {exc}); p_max and L10r not computed")
    if ld is not None:
        p_i, p_o = contact_pressures(brg, ld.Q_i, ld.Q_o, ld.alpha_i, ld.alpha_o)
        p = {"inner": float(np.max(p_i)), "outer": float(np.max(p_o))}
        ratio = float(pressure_ratio(max(p.values())))
        if ratio > 1.0:
            notes.append(f"maximum contact pressure {max(p.values()) / 1e6:.0f} MPa exceeds the ISO 76 "
                         f"reference of 4200 MPa (ratio {ratio:.3g})")
        ref = reference_life(brg, ld, C, rotating=rotating)
        kw.update(p_max_Pa=p, pressure_ratio=ratio, L10r_Mrev=float(ref.L10r), reference=ref)
    if n_rpm is not None:
        if isinstance(n_rpm, bool) or not isinstance(n_rpm, (int, float, np.floating)) or not (
                np.isfinite(n_rpm) and n_rpm > 0):
            raise InputError("n_rpm", n_rpm, "must be one finite speed > 0 [rpm]")
        kw["L10_h"] = L10 * 1e6 / (60.0 * float(n_rpm))
    if nu_m2_s is not None and n_rpm is not None:
        kw.update(_modified(brg, C0, P, L10, kw.get("reference"), nu_m2_s, n_rpm, contamination, notes))
    return RatingLife(C_N=C, C0_N=C0, P_N=P, P0_N=P0, s0=s0, L10_Mrev=L10, notes=tuple(notes), **kw)


def _modified(brg, C0, P, L10, ref, nu, n_rpm, contamination, notes) -> dict:
    """κ, a_ISO and the modified lives (ISO 281:2007 systems approach; ISO/TS 16281 for L10mr)."""
    nu1 = float(reference_viscosity(n_rpm, brg.dm))
    kappa = float(viscosity_ratio(nu, nu1))
    if not 0.1 <= kappa <= 4.0:
        notes.append(f"kappa = {kappa:.3g} outside ISO 281's 0.1 ... 4: a_ISO evaluated at "
                     f"{min(max(kappa, 0.1), 4.0):g}")
    e_C = contamination_factor(contamination, brg.dm)
    C_u = float(fatigue_load_limit(C0, brg.dm))
    kind = "thrust" if brg.kind == "thrust" else "radial"
    a_iso = float(life_modification_factor(kappa, e_C * C_u / P, kind))
    if a_iso >= A_ISO_MAX:
        notes.append(f"a_ISO capped at {A_ISO_MAX:g} (ISO 281 limit)")
    L10m = float(modified_rating_life(a_iso, L10))
    out = dict(kappa=kappa, nu1_m2_s=nu1, e_C=e_C, C_u_N=C_u, a_ISO=a_iso, L10m_Mrev=L10m,
               L10m_h=L10m * 1e6 / (60.0 * float(n_rpm)))
    if ref is not None:
        a_ref = float(life_modification_factor(kappa, e_C * C_u / float(ref.P_ref), kind))
        out["L10mr_Mrev"] = float(modified_rating_life(a_ref, ref.L10r))
    return out
