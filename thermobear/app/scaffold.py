r"""``thermobear init``: a commented scene for a catalogue bearing in a machine built from its dimensions.

The scene names every key it uses, with its unit and where its value comes from:

* the bearing: the catalogue (``materials/bearings/*.toml``; estimated internal geometry marked there);
* the operating point, when not given: the reference conditions of ISO 15312:2003 (thermal speed
  rating) — a radial load of 0.05 C0 for a radial bearing (an angular contact bearing with the axial
  reaction of a half load zone, 1.25 Fr tan α0: alone it carries a radial load only against an axial
  one), an axial load of 0.02 C0 for a thrust bearing, ambient 20 °C — and half of the
  bearing's thermal reference speed (:func:`thermobear.coupled.speeds.thermal_reference_speed`: the speed at
  which thermobear's loss at the reference conditions equals the reference heat flow q_r A_r);
* the lubrication: ISO 15312's reference lubrication (oil bath to the middle of the lowest ball,
  ISO VG 32 for radial and VG 68 for thrust bearings; a lithium / mineral-oil grease of 100–200 mm²/s
  at 40 °C filling 30 % of the free space), an oil-jet flow that carries the bearing's reference heat
  flow with a 10 K rise, an oil–air feed (estimated);
* the shaft and housing: the parametric builders' defaults (:mod:`thermobear.thermal.builders.machine`),
  resolved into numbers by :func:`thermobear.thermal.builders.layout.layout`.

References
----------
.. [1] ISO 15312:2003, Rolling bearings — Thermal speed rating — Calculation (reference conditions:
   bearing at 70 °C over 20 °C ambient, loads 0.05 C0 radial / 0.02 C0 thrust, oil bath to the middle of
   the lowest rolling element, ISO VG 32 radial / VG 68 thrust; Annex C grease: lithium soap, mineral
   base oil 100–200 mm²/s at 40 °C, 30 % of the free space).  The same conditions are restated in SKF,
   Rolling bearings (catalogue 17000/1 EN, 2018), "Reference speed".
"""
from __future__ import annotations

import difflib
import math
import re

from thermobear import __version__
from thermobear.contact.geometry import BallBearing, bearing
from thermobear.coupled.ratings import check_static_safety
from thermobear.coupled.sources import scene_losses
from thermobear.coupled.speeds import ReferenceSpeed, reference_loads, thermal_reference_speed
from thermobear.errors import InputError, NoSpeedRoot, SolverError
from thermobear.losses.seals import BALL_SEALS, seal_constants
from thermobear.losses.skf import K_RS
from thermobear.lubrication.lubricant import lubricant, lubricant_names
from thermobear.rating.life import load_ratings, stated_ratings
from thermobear.loads.pair import PAIR_ARRANGEMENTS
from thermobear.scene import Scene, scene_from_dict
from thermobear.thermal.builders.layout import H_MOUNT_W_M2K, layout

__all__ = ["METHODS", "HOUSINGS", "scaffold"]

#: ``--lubrication`` choices → the scene's ``supply``.
METHODS = {"oil-bath": "oil_bath", "grease": "grease", "oil-jet": "oil_jet", "oil-air": "oil_air"}
HOUSINGS = ("block", "pillow", "flange")

T_AMBIENT_REF_C = 20.0    #: ISO 15312 reference ambient [°C]
SPEED_FRACTION = 0.5      #: default speed / thermal reference speed [-]
JET_RISE_K = 10.0         #: oil-jet default: rise of the oil carrying the reference heat flow [K] (estimated)
T_JET_IN_C = 40.0         #: oil-jet / oil-air default inlet temperature [°C] (estimated)
OIL_AIR_FLOW_L_H = 0.005  #: oil–air default oil feed [L/h] (estimated)
OIL_AIR_AIR_L_MIN = 20.0  #: oil–air default carrier air [L/min] (estimated)
GREASE_FILL = 0.3         #: ISO 15312 Annex C grease quantity: 30 % of the free space [-]
DEFAULT_GREASE = "grease-lithium-mineral-vg100-nlgi2"


# --------------------------------------------------------------------------- choices
#: a designation's closure suffix (SKF: -2RS1 two contact seals, -RSH one, -2Z two shields, -RZ a non-contact seal)
_CLOSURE = re.compile(r"^(?P<base>.+?)[- ]?(?P<two>2?)(?P<kind>RS1|RSH|RSL|RZ|Z)$", re.IGNORECASE)


def _bearing(name: str) -> tuple[BallBearing, list]:
    """The catalogue bearing of a designation, with the ``[bearing]`` rows of its closure suffix
    (``6204-2RS1``: two RS1 contact seals; ``6204-Z``: one shield); InputError with close names when unknown."""
    try:
        return bearing(name), []
    except InputError as exc:
        m = _CLOSURE.match(str(name).strip())
        if m is None:
            raise
        try:
            brg = bearing(m["base"])
        except InputError:
            raise exc from None
    if brg.kind == "thrust":
        raise InputError("bearing", name, f"a thrust ball bearing has no seals or shields: {brg.name} without "
                                          f"-{m['two']}{m['kind'].upper()}")
    kind, sides = m["kind"].upper(), 2 if m["two"] else 1
    seals = "shield" if kind in ("Z", "RZ") else kind
    what = {"shield": "non-contact, the cavity closed; no friction in SKF 2004's seal model",
            "RSL": "low-friction contact seal (SKF 2004 seal model)", "RSH": "contact seal (SKF 2004 seal model)",
            "RS1": "contact seal (SKF 2004 seal model)"}[seals]
    return brg, [("seals", seals, f"from the designation's -{m['two']}{kind}: {what}"),
                 ("seal_sides", sides, f"{'two' if sides == 2 else 'one'} (the designation's "
                                       f"{'2' if sides == 2 else 'single '}{kind})")]


def _lubricant(name: str | None, supply: str, brg: BallBearing) -> tuple[str, str]:
    """(lubricant name, where it comes from); a grease only for grease lubrication, an oil for the rest."""
    if name is None:
        if supply == "grease":
            return DEFAULT_GREASE, ("ISO 15312 Annex C reference grease: lithium soap, mineral base oil "
                                    "100-200 mm2/s at 40 °C (this one: VG 100, NLGI 2)")
        vg = "68" if brg.kind == "thrust" else "32"
        return f"iso-vg-{vg}-mineral", f"ISO 15312 reference oil for {'thrust' if vg == '68' else 'radial'} bearings"
    names = lubricant_names()
    if name not in names:
        close = difflib.get_close_matches(name, names, n=4, cutoff=0.5)
        raise InputError("--oil", name, "unknown lubricant; " + (f"close: {', '.join(close)}; " if close else "")
                         + "thermobear list lubricants shows them all")
    kind = lubricant(name).kind
    if (kind == "grease") != (supply == "grease"):
        want = "a grease" if supply == "grease" else "an oil"
        raise InputError("--oil", name, f"is {'a grease' if kind == 'grease' else 'an oil'}; "
                         f"lubrication {supply.replace('_', '-')} needs {want}")
    return name, "given (--oil)"


def _sig(x: float, digits: int = 2) -> float:
    """x rounded to a number of significant digits."""
    return float(f"{x:.{digits}g}") if x > 0 else 0.0


def _pair_rows(brg: BallBearing, pair, preload_N) -> list:
    """The [bearing] rows of a preloaded pair (``--pair``, ``--preload-N``), or none; refused naming the option."""
    if pair is None:
        if preload_N is not None:
            raise InputError("--preload-N", preload_N, "a preload needs its pair: give --pair back_to_back or face_to_face")
        return []
    if pair not in PAIR_ARRANGEMENTS:
        raise InputError("--pair", pair, f"one of {', '.join(PAIR_ARRANGEMENTS)}")
    if brg.kind != "angular_contact":
        raise InputError("--pair", pair, f"a preloaded pair of angular contact bearings; {brg.name} is {brg.kind}")
    _check_number("--preload-N", preload_N, True)
    if preload_N is None:
        raise InputError("--preload-N", None, "a pair needs its cold mounted preload, > 0 [N] (as mounted: a maker's "
                         "light, medium or heavy preload is the unmounted set's)")
    try:                                 # the preload alone: each bearing's axial load, the static safety run checks
        check_static_safety(Scene(name=brg.name, bearing=brg, lubricant=lubricant("iso-vg-32-mineral"),
                                  supply="oil_air", n_rpm=1.0, Fa=float(preload_N), Fr=0.0))
    except InputError as exc:
        raise InputError("--preload-N", preload_N, exc.expected) from None
    return [("arrangement", pair, "one bearing of a symmetric pair (--pair); the loaded one of the two is solved, both at "
             "the same temperatures (thermobear.scene.pair); the network below is this bearing's share of the "
             "pair's machine, cut at the symmetry plane between the two ([shaft] and [housing] end_right)"),
            ("preload_N", float(preload_N), "N: the pair's cold preload as mounted (--preload-N; a maker's class is the "
             "unmounted set's, the seats' fits add to it), a position preload: it follows the temperatures"),
            ("preload", "position", "position (rigid: ground faces or spacers) | spring (a constant force)")]


def _operation(brg, ref: ReferenceSpeed | None, n_rpm, Fr_N, Fa_N, pair: bool = False) -> list:
    rows = []
    if n_rpm is None:
        n = _sig(SPEED_FRACTION * ref.n_rpm)
        rows.append(("n_rpm", n, f"r/min: {SPEED_FRACTION:g} × the thermal reference speed {ref.n_rpm:.0f} r/min "
                     f"(ISO 15312 heat balance q_r A_r = {ref.Phi_r_W:.1f} W at 70 °C with thermobear's losses; "
                     "thermobear speed SCENE)"))
    else:
        rows.append(("n_rpm", float(n_rpm), "r/min: given (--speed-rpm)"))
    if Fr_N is None and Fa_N is None:
        loads = reference_loads(brg)
        fa, fr = loads.get("Fa", 0.0), loads.get("Fr", 0.0)
        C0, how = stated_ratings(brg)[1:]
        if how[1] == "stated":             # the catalogue's: ISO 76 of its (estimated) geometry, or a maker's value
            how = ("", "catalogue: ISO 76 from its internal geometry" if abs(C0 / load_ratings(brg)[1] - 1.0) < 5e-3
                   else "stated in the catalogue")
        C0 = f"C0 = {C0 / 1e3:.2f} kN ({how[1]})"
        src_fr = f"N: 0.05 C0, ISO 15312 reference load of radial bearings, {C0}"
        src_fa = {"thrust": f"N: 0.02 C0, ISO 15312 reference load of thrust bearings, {C0}",
                  "angular_contact": "N: 1.25 Fr tan(alpha0), the axial reaction of a half load zone (Sjövall; Harris "
                                     "& Kotzalas 2007): a single angular contact bearing needs it"}.get(brg.kind)
        if pair:                          # the preload, not an external axial load, sets a pair's contacts
            fa, src_fa = 0.0, None
        rows.append(("Fa_N", _sig(fa, 3), src_fa if fa > 0 else "N: none (radial reference load)" if not pair else
                     "N: no external axial load on the pair (its preload sets the contacts)"))
        rows.append(("Fr_N", _sig(fr, 3), src_fr if fr > 0 else "N: none (axial reference load)"))
    else:
        if brg.kind == "thrust" and (Fr_N or not Fa_N):
            raise InputError("--Fr-N" if Fr_N else "--Fa-N", Fr_N or Fa_N, "a thrust ball bearing carries an axial load "
                             "only: give --Fa-N > 0 and no --Fr-N")
        if brg.kind == "angular_contact" and not Fa_N and not pair:
            raise InputError("--Fa-N", Fa_N, "a single angular contact bearing needs an axial load against its "
                             "shoulder: give --Fa-N (the axial reaction or preload of the arrangement)")
        rows.append(("Fa_N", float(Fa_N or 0.0), "N: given (--Fa-N)" if Fa_N is not None else "N: 0 (only --Fr-N given)"))
        rows.append(("Fr_N", float(Fr_N or 0.0), "N: given (--Fr-N)" if Fr_N is not None else "N: 0 (only --Fa-N given)"))
    rows.append(("rotating", "inner", "the inner ring turns with the shaft"))
    return rows


def _lubrication(brg, supply, oil, oil_src, ref: ReferenceSpeed | None) -> list:
    rows = [("name", oil, oil_src), ("supply", supply, f"--lubrication {supply.replace('_', '-')}")]
    if supply == "oil_bath":
        rows.append(("oil_level_mm", round(0.5 * brg.D * 1e3, 3), "mm above the lowest point of the outer-ring "
                     f"raceway (SKF's H): the middle of the lowest ball, D_w/2 (ISO 15312 reference oil bath; SKF)"))
    elif supply == "grease":
        rows.append(("grease_fill", GREASE_FILL, "- of the bearing's free volume (ISO 15312 Annex C; SKF: ~30 %)"))
    elif supply == "oil_jet":
        lub = lubricant(oil)
        rho_cp = float(lub.rho(T_JET_IN_C) * lub.cp(T_JET_IN_C))
        Q = ref.Phi_r_W / (rho_cp * JET_RISE_K) * 3.6e6
        q = _sig(Q, 2)
        rows += [("flow_L_h", q, f"L/h: carries the reference heat flow {ref.Phi_r_W:.1f} W (ISO 15312 q_r A_r) "
                  f"with a {JET_RISE_K:g} K rise, Q = N / (rho c_p dT), rho c_p = {rho_cp / 1e6:.2f} MJ/(m3 K) at "
                  f"{T_JET_IN_C:g} °C (rise estimated: 5-15 K is usual for circulating oil)"),
                 _range("flow_L_h", [_sig(q * JET_RISE_K / 15.0, 2), _sig(q * JET_RISE_K / 5.0, 2)], "the flow that "
                        "carries the reference heat with the usual 5-15 K rise (Q ∝ 1/dT)", lognormal=True),
                 ("T_in_C", T_JET_IN_C, "°C: estimated (a tempered supply above a 20 °C room)"),
                 _T_in_range(),
                 ("oil_feed", "jet", "a jet: 0.4 of the flow passes the bearing (Brossier et al. 2021; builders' "
                  "default); \"circulating\": all of it")]
    elif supply == "oil_air":
        rows += [("flow_L_h", OIL_AIR_FLOW_L_H, "L/h: estimated (minimal-quantity feed, a few mL/h; no rule cited: "
                  "take the supplier's value)"),
                 _range("flow_L_h", [OIL_AIR_FLOW_L_H / 2.0, OIL_AIR_FLOW_L_H * 2.0], "a minimal-quantity feed of a "
                        "few mL/h, a factor 2 either way of the estimate", lognormal=True),
                 ("T_in_C", T_JET_IN_C, "°C: estimated"), _T_in_range(),
                 ("air_flow_L_min", OIL_AIR_AIR_L_MIN, "L/min at 20 °C, 1 atm: estimated (take the supplier's value)")]
    K = K_RS[supply]
    return rows + [("K_rs", K, f"SKF 2004 replenishment constant of {supply.replace('_', ' ')} (starvation factor "
                    "Phi_rs); a rig's own: thermobear calibrate --param K_rs"),
                   _range("K_rs", [K / 2.0, K * 2.0], "SKF 2004 gives K_rs for two supply classes only, 3e-8 and "
                          "6e-8, with no tolerance; their factor 2 taken either way of the class value", lognormal=True)]


def _contact_seals(brg: BallBearing) -> list:
    """SKF's contact seals whose constants cover this bearing (kind and outside diameter; none for a thrust bearing)."""
    out = []
    for t in BALL_SEALS[2:]:
        try:
            seal_constants(t, brg.kind, brg.outer_diameter * 1e3)
        except InputError:
            continue
        out.append(t)
    return out


def _table(rows) -> dict:
    """A table's rows as the scene file reads them (``uncertainty.<key>`` rows nested under ``uncertainty``)."""
    out: dict = {}
    for key, v, _ in rows:
        head, _, rest = key.partition(".")
        if rest:
            out.setdefault(head, {})[rest] = v
        else:
            out[key] = v
    return out


def _range(key: str, rng: list, why: str, lognormal: bool = False) -> tuple:
    """An ``uncertainty.<key>`` row of the scene file: the estimate's range (the support of a uniform draw, or the
    5-95 % quantiles of a lognormal one) and its reasoning."""
    u = {"range": rng} | ({"distribution": "lognormal"} if lognormal else {}) | {"source": f"reasoning: {why}"}
    return f"uncertainty.{key}", u, None


def _T_in_range() -> tuple:
    return "uncertainty.T_in_C", {"offset": [-10.0, 10.0], "source": "reasoning: a tempered oil supply is held at "
                                  "30-50 °C, the estimate the middle"}, None


_MACHINE_SRC = "builders' default (thermobear/thermal/builders/machine.py)"


#: where a pair's bearing's share of the machine ends (``init --pair``): the symmetry plane between the two
#: bearings, adjacent (no spacer), through which no heat flows
_PAIR_CUT = ("the pair's symmetry plane (--pair): the bearing's share of the machine ends at its face toward the other "
             "bearing")


def _shaft_rows(m, lay, pair: bool = False) -> list:
    s = m.shaft
    L_right = round(1e3 * (lay.z_s1 - lay.B / 2), 3)
    right = ([("length_right_mm", L_right, f"mm: 0, {_PAIR_CUT} (with a spacer, [bearing] spacer_mm: half its length)")]
             if pair else [("length_right_mm", L_right, "mm: 2.5 d, as the left")])
    return [
        ("diameter_mm", round(2e3 * lay.r_s, 3), "mm: the bearing bore (catalogue)"),
        ("length_left_mm", round(1e3 * (-lay.B / 2 - lay.z_s0), 3), f"mm: 2.5 d, {_MACHINE_SRC}: DIN 748-1 shaft ends "
         "are 2.1-2.8 d long"),
        *right,
        ("material", s.material, f"{_MACHINE_SRC} (steel C45)"),
        ("end_left", s.end_left, "free: convection from the end face; fixed (with T_end_left_C): a coupling, a motor"),
        ("end_right", s.end_right, "adiabatic: the symmetry plane (free | fixed | adiabatic)" if pair else
         "free | fixed | adiabatic"),
        ("surface", s.surface, "air: the shaft outside the housing in the room's air"),
        ("interference_um", round(1e6 * lay.delta_inner, 2), "µm diametral: probable interference of a k5 seat "
         "(m5 above 100 mm), ISO 286 / ISO 492 (materials/iso286_fits.toml)"),
    ]


def _housing_rows(m, lay, housing: str, pair: bool = False) -> list:
    h = m.housing
    rows = [("type", housing, "--housing: block | pillow | flange"),
            ("material", h.material, f"{_MACHINE_SRC}: grey cast iron EN-GJL-250, the material of plummer blocks")]
    if pair:
        rows += [("axial_length_mm", round(1e3 * lay.L_h, 3), f"mm: 1.5 B, room for a cover on the left ({_MACHINE_SRC}: "
                  f"B/2 either side of a single bearing), {_PAIR_CUT}"),
                 ("offset_mm", round(1e3 * h.offset, 3), "mm: the housing's centre from the bearing's (its right end at "
                  "the bearing's right face; with a spacer, [bearing] spacer_mm, half its length further)")]
    else:
        rows.append(("axial_length_mm", round(1e3 * lay.L_h, 3), f"mm: 2 B, {_MACHINE_SRC} (room for a cover either side)"))
    if lay.shape == "block":
        rows += [("height_mm", round(1e3 * lay.height, 3), f"mm: 2 D, {_MACHINE_SRC} (a wall of D/2 around the seat)"),
                 ("depth_mm", round(1e3 * lay.depth, 3), "mm: 2 D, as the height"),
                 ("centre_height_mm", round(1e3 * lay.centre_height, 3), "mm: half the height")]
    else:
        rows.append(("outer_diameter_mm", round(1e3 * lay.height, 3), f"mm: 2 D, {_MACHINE_SRC}"))
        if lay.foot:
            rows += [("centre_height_mm", round(1e3 * lay.centre_height, 3), "mm: 0.7 × body diameter (the foot)"),
                     ("base_length_mm", round(1e3 * lay.base_length, 3), "mm: 2.5 × body diameter (the foot)")]
    rows += [("end_left", lay.end_left, "air | mounted | adiabatic" + (" (a flange is bolted by its left face)"
                                                                        if housing == "flange" else "")),
             ("end_right", lay.end_right, "adiabatic: the symmetry plane (air | mounted | adiabatic)" if pair else
              "air | mounted | adiabatic"),
             ("mounting", h.mounting, "bolted to a frame at ambient (a half-space); none: free-standing"),
             ("mounting_h_W_m2K", round(H_MOUNT_W_M2K, 1), "W/(m2 K): bolted joint in air at 0.1 MPa (Bergman et al. "
              "2011 Table 3.2)"),
             ("frame_material", h.frame_material, f"{_MACHINE_SRC}"),
             ("air", h.air, "still | forced (then air_speed_m_s)"),
             ("emissivity", h.emissivity, "- painted cast iron 0.8-0.95 (Bergman et al. 2011 Table A.11)"),
             ("interference_um", round(1e6 * lay.delta_outer, 2), "µm diametral (negative: clearance): probable H7 "
              "seat, ISO 286 / ISO 492 (materials/iso286_fits.toml)")]
    return rows


def _fmt(v) -> str:
    if isinstance(v, dict):                   # an inline table: an uncertainty entry
        return "{ " + ", ".join(f"{k} = {_fmt(x)}" for k, x in v.items()) + " }"
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_fmt(x) for x in v) + "]"
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(v, int):
        return str(v)
    return repr(float(v))


def _section(name: str, rows, lines: list, notes=()):
    """A table of the scene file: its rows ``(key, value, source)``, then ``notes`` ``(key = value, what it does)``
    as commented lines inside the table (uncommented, each is a valid key of it)."""
    lines.append("")
    lines.append(f"[{name}]")
    for key, value, src in rows:
        kv = f"{key} = {_fmt(value)}"
        lines.append(f"{kv:32s} # {src}" if src else kv)
    for kv, what in notes:
        lines.append(f"{'# ' + kv:32s} # uncomment: {what}")


def _reference_speed(brg: BallBearing) -> ReferenceSpeed:
    """The thermal reference speed, or InputError asking for the speed when the model has none."""
    try:
        return thermal_reference_speed(brg)
    except NoSpeedRoot as exc:
        raise InputError("--speed-rpm", None, f"no default speed: {' '.join(str(exc).split())}; give --speed-rpm "
                         "(and for an oil jet --oil's flow in the scene)") from None


def _check_number(field: str, v, positive: bool):
    if v is None:
        return
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v) or v < 0 or (positive and v == 0):
        raise InputError(field, v, "must be a finite number " + ("> 0" if positive else ">= 0"))


def _check_loads(brg: BallBearing, oil: str, supply: str, Fa_N, Fr_N):
    """Given loads the bearing cannot carry refused naming the options, before anything is computed: the static
    safety ``run`` checks (:func:`thermobear.coupled.ratings.check_static_safety`, ISO 76)."""
    if Fa_N is None and Fr_N is None:
        return                                          # ISO 15312's reference loads: 0.05 C0 / 0.02 C0
    sc = Scene(name=brg.name, bearing=brg, lubricant=lubricant(oil), supply=supply, n_rpm=1.0, Fa=float(Fa_N or 0.0),
               Fr=float(Fr_N or 0.0))
    try:
        check_static_safety(sc)
    except InputError as exc:
        given = [(f, v) for f, v in (("--Fa-N", Fa_N), ("--Fr-N", Fr_N)) if v]
        field, value = given[0] if len(given) == 1 else (", ".join(f for f, _ in given), exc.value)
        raise InputError(field, value, exc.expected) from None


def _suffix(closure: list) -> str:
    """The closure suffix of a designation from its rows ("-2RS1", "-Z"; "" without seals)."""
    if not closure:
        return ""
    seals, sides = closure[0][1], closure[1][1]
    return f"-{'2' if sides == 2 else ''}{'Z' if seals == 'shield' else seals}"


def _bearing_rows(brg: BallBearing) -> list:
    est = ", ".join(brg.estimated) if brg.estimated else "none"
    dims = f"{brg.bore * 1e3:g} x {brg.outer_diameter * 1e3:g} x {brg.width * 1e3:g} mm"
    C, C0, src = stated_ratings(brg)
    computed = [f"{k} {how}" for k, how in zip(("C", "C0"), src) if how != "stated"]
    geo = (f"Z {brg.Z}, D_w {brg.D * 1e3:.4g} mm, dm {brg.dm * 1e3:.4g} mm, alpha0 {math.degrees(brg.alpha0):.3g} deg, "
           f"C {C / 1e3:.3g} kN, C0 {C0 / 1e3:.3g} kN" + (f" ({', '.join(computed)})" if computed else ""))
    return [("catalog", brg.name, f"{brg.kind.replace('_', ' ')}, {dims}; {geo}; estimated: {est} "
             "(thermobear list bearings --series ...); any geometry key overrides, e.g. D_mm = ...")]


def _skf_hint(scene) -> str:
    """The header's word on the SKF 2004 model: ``--set models.losses=skf`` where the model evaluates this scene
    (its series has SKF's constants: not the 70 C/E, 719 C/E series), else why it does not."""
    try:
        scene_losses(scene, T_C=70.0, models={"losses": "skf"})
    except (InputError, SolverError) as exc:
        return f"--json). No SKF 2004 model (models.losses = \"skf\") for it: {' '.join(str(exc).split())}"
    return "--json; --set models.losses=skf for the SKF 2004 model)."


def scaffold(name: str, lubrication: str, *, oil: str | None = None, housing: str = "block", n_rpm=None, Fr_N=None,
             Fa_N=None, pair: str | None = None, preload_N=None, command: str | None = None) -> str:
    """The commented scene TOML of a catalogue bearing in a parametric machine (see the module docstring).

    Parameters
    ----------
    name : str            catalogue designation ("6208", "7205 B", "51107")
    lubrication : str     ``oil-bath``, ``grease``, ``oil-jet`` or ``oil-air``
    oil : str             lubricant name (default: ISO 15312's reference oil or grease)
    housing : str         ``block``, ``pillow`` or ``flange``
    n_rpm : float         speed [r/min] (default: half the thermal reference speed)
    Fr_N, Fa_N : float    loads [N] (default: ISO 15312's reference load; a pair: no external axial load)
    pair : str            an angular contact bearing as one of a preloaded pair, ``back_to_back`` or ``face_to_face``
                          (:mod:`thermobear.scene.pair`), with ``preload_N`` its cold mounted preload [N]
    command : str         the command line, recorded in the header

    Returns
    -------
    str   the scene file's text; ``thermobear run`` solves it as written

    Examples
    --------
    >>> text = scaffold("6208", "grease")
    >>> "grease_fill = 0.3" in text and "[housing]" in text
    True
    """
    if lubrication not in METHODS:
        raise InputError("--lubrication", lubrication, f"one of {', '.join(METHODS)}")
    if housing not in HOUSINGS:
        raise InputError("--housing", housing, f"one of {', '.join(HOUSINGS)}")
    _check_number("--speed-rpm", n_rpm, True)
    _check_number("--Fr-N", Fr_N, False)
    _check_number("--Fa-N", Fa_N, False)
    brg, closure = _bearing(name)
    pair_rows = _pair_rows(brg, pair, preload_N)
    missing = [f"{k}_mm" for k in ("bore", "outer_diameter", "width") if getattr(brg, k) is None]
    if missing:
        raise InputError("bearing", name, f"a bundled bearing without boundary dimensions ({', '.join(missing)}): a "
                         "parametric network needs the bearing's boundary dimensions; a catalogue bearing with "
                         "d x D x B (thermobear list bearings)")
    supply = METHODS[lubrication]
    oil, oil_src = _lubricant(oil, supply, brg)
    _check_loads(brg, oil, supply, Fa_N, Fr_N)
    ref = _reference_speed(brg) if (n_rpm is None or supply == "oil_jet") else None
    rows = {"bearing": _bearing_rows(brg) + closure + pair_rows,
            "lubricant": _lubrication(brg, supply, oil, oil_src, ref),
            "operation": _operation(brg, ref, n_rpm, Fr_N, Fa_N, bool(pair_rows)),
            "thermal": [("T_ambient_C", T_AMBIENT_REF_C, "°C: ISO 15312 reference ambient; network = \"parametric\" "
                         "is implied by [shaft] / [housing]"),
                        ("uncertainty.T_ambient_C", {"offset": [-5.0, 5.0], "source": "reasoning: the machine's room is "
                         "not known; 15-25 °C about the reference"}, None)]}
    title = f"{brg.name}{_suffix(closure)}-{lubrication}-{housing}"
    rows["scene"] = [("name", title, None),
                     ("description", f"{brg.name} on a steel shaft in a {housing} housing, {lubrication}", None),
                     ("source", f"thermobear init (thermobear {__version__}): catalogue, ISO 15312 reference "
                      "conditions, builders' defaults; no measurement", None)]
    d = {k: _table(r) for k, r in rows.items()}
    d["housing"] = {"type": housing}
    pair = bool(pair_rows)
    if pair:                     # the bearing's share of the pair's machine: cut at the symmetry plane (_PAIR_CUT)
        B_mm = 1e3 * brg.width
        d["shaft"] = {"length_right_mm": 0.0, "end_right": "adiabatic"}
        d["housing"].update(axial_length_mm=1.5 * B_mm, offset_mm=-0.25 * B_mm, end_right="adiabatic")
    sc = scene_from_dict(d)
    lay = layout(sc.network)
    rows["shaft"], rows["housing"] = _shaft_rows(sc.network, lay, pair), _housing_rows(sc.network, lay, housing, pair)
    d = {k: _table(r) for k, r in rows.items()}
    sc = scene_from_dict(d)                                  # the scene as written is a valid scene
    lines = [f"# A {brg.name}{_suffix(closure)} in a {housing} housing, {lubrication}: written by "
             f"`{command or 'thermobear init ' + brg.name + ' --lubrication ' + lubrication}`.",
             "# Every key is used; units are in the key names; each comment says where the value comes from.",
             f"# Solve it: thermobear run THIS_FILE  ({_skf_hint(sc)}",
             "# The network is built from [shaft] and [housing] (examples/README.md, \"Machine keys\")."]
    seals = _contact_seals(brg)
    notes = {"bearing": ([] if closure or not seals else [(f'seals = "{seals[-1]}"', "contact seals and their losses "
                                                           f"(none | shield | {' | '.join(seals)})")])
             + [('cage = "outer_ring"', "a ring-guided cage and its losses")],
             "operation": [("T_C = 70.0", "prescribe the contacts' temperature (no thermal network)")]}
    for sec in ("scene", "bearing", "lubricant", "operation", "thermal", "shaft", "housing"):
        _section(sec, rows[sec], lines, notes.get(sec, ()))
    return "\n".join(lines) + "\n"
