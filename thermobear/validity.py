r"""Where the models hold: one table of limits, checked by every entry point.

Two levels, for every quantity below:

* **refuse** — physically impossible, or outside what the models can represent at all:
  :class:`~thermobear.errors.InputError` naming the field, the value and the accepted range
  (command line: one line, exit code 2);
* **warn** — computable, but outside where the models were validated: an
  :class:`~thermobear.errors.OutsideValidity` warning (quantity, value, validated range, source),
  which the solvers collect into their results (``warnings``) and the command line prints one line
  each.

The limits (the README's table is :func:`limits_table`, with the reasoning and source of each):

>>> print(limits_table(sources=False))
| quantity | unit | refused | warned |
|---|---|---|---|
| osculation | – | outside (0.5, 2] | outside [0.505, 1.4] |
| speed n·dm | mm/min | outside [0, 4e+06] | > 1e+06 |
| maximum contact pressure | MPa | outside [0, 5292] | > 4200 |
| contact angle + half the contact ellipse, from the groove bottom | deg | > 90 | – |
| Hertz contact size / radius of curvature | – | outside [0, 1] | > 0.2 |
| lubricant temperature | °C | outside [-40, 250] | outside [-20, 150] |
| static safety s0 | – | < 0.5 | < 1 |
| viscosity ratio κ = ν/ν1 | – | – | < 0.1 |
| operating radial clearance | µm | – | < 0 |
| warm / cold preload of a position-preloaded pair | – | – | outside [0.5, 2] |
| load (Fa, Fr or M/ℜ_i), when not 0 | N | < 1e-06 | – |
| speed, when not 0 | rpm | < 1e-06 | – |
| load / SKF's minimum load, radial (deep groove) or axial (angular contact, thrust) | – | – | < 1 |
| SKF weighting factor Φ_bl | – | – | > 0.5 |

Reasoning per limit is in :data:`LIMITS`; the sources are [1]_–[9]_.

References
----------
.. [1] Harris, T. A., 2001, *Rolling Bearing Analysis*, 4th ed., Wiley, ch. 2 (osculation
   f = r/D of ball bearings 0.505–0.57) and ch. 6 (contact angle and groove).
.. [2] Bamberger, E. N., Zaretsky, E. V., Signer, H., 1976, "Endurance and failure characteristic
   of main-shaft jet engine bearing at 3 × 10⁶ DN", J. Lubr. Technol. 98(4), 580–585.
.. [3] Harris 2001 ch. 8 (the 218 angular contact bearing, 0–20 000 rpm: n·d_m ≤ 2.5e6, the
   high-speed load model's check case); Darul et al. 2024 (seed 004), 8 070 rpm on d_m 70 mm
   (n·d_m 5.6e5), the highest speed the loss models were scored on.
.. [4] ISO 76:2006, *Rolling bearings — Static load ratings*, §4: a contact stress of 4 200 MPa
   (ball bearings) corresponds to a total permanent deformation of 1e-4 of the ball diameter.
.. [5] Palmgren, A., 1959, *Ball and Roller Bearing Engineering*, 3rd ed., SKF: permanent
   deformation ∝ Q² — twice the rated contact load (p_max × 2^(1/3)) gives four times the
   ISO 76 deformation, where elastic (Hertz) contact no longer describes the contact.
.. [6] Johnson, K. L., 1985, *Contact Mechanics*, Cambridge University Press, §4.1–4.2: Hertz's
   theory assumes contact dimensions small against the radii of curvature.
.. [7] ASTM D341-09: the Walther equation is a two-point fit (here at 40 and 100 °C) and is
   reliable over the range of the data; bearing oils near −40 °C are at or past their pour point
   (mineral oils −9 … −30 °C), above 250 °C past their flash point.
.. [8] SKF, 2004, *The SKF model for calculating the frictional moment of bearings*: Φ_bl is the
   weight of the boundary (mixed) friction term; above 0.5 the contacts are mostly in boundary
   lubrication, where μ_bl is a single estimated constant.
.. [9] SKF, 2018, *Rolling bearings*, PUB BU/P1 17000/1 EN, pp. 106, 254, 398 and 469: the requisite
   minimum load of deep groove ball bearings (radial), of single row angular contact and of thrust ball
   bearings (axial) (:mod:`thermobear.rating.minimum_load`).

Examples
--------
>>> from thermobear import validity
>>> validity.check("osculation", 0.52, "bearing.fi")
[]
>>> try:
...     validity.check("osculation", 10.0, "bearing.fi")
... except Exception as e:
...     print(e)
bearing.fi = 10.0 — osculation must lie in (0.5, 2] [-] (groove radius / ball diameter: > 0.5 or the ball does not fit its groove; beyond 2 the race is flatter than any ball bearing groove and its geometry (A = (f_i + f_o - 1) D) loses its meaning; validated from the catalogue range 0.505-0.57 (Harris 2001 ch. 2) to seed 001's modified races (0.655 and 1.387))
"""
from __future__ import annotations

import contextlib
import math
import warnings
from dataclasses import dataclass

import numpy as np

from thermobear.errors import InputError, OutsideValidity

__all__ = ["Limit", "LIMITS", "check", "collect", "limits_table", "P_MAX_REFUSE_PA", "P_MAX_WARN_PA",
           "T_LUBRICANT_REFUSE_C", "T_LUBRICANT_WARN_C", "warning_lines"]


@dataclass(frozen=True)
class Limit:
    """One quantity's limits: accepted (refuse outside) and validated (warn outside) ranges.

    ``lo_open``: the accepted range excludes its lower end.  ``None`` = no bound.
    """

    quantity: str
    unit: str
    refuse: tuple
    warn: tuple
    source: str
    lo_open: bool = False
    scale: float = 1.0          # SI value × scale = value in ``unit`` (for messages)

    def range_text(self, which: str = "refuse") -> str:
        lo, hi = getattr(self, which)
        f = (lambda v: f"{v * self.scale:.4g}")  # noqa: E731
        if lo is not None and hi is not None:
            return f"{'(' if (self.lo_open and which == 'refuse') else '['}{f(lo)}, {f(hi)}]"
        if lo is not None:
            return f"{'>' if self.lo_open else '>='} {f(lo)}"
        return f"<= {f(hi)}"


P_MAX_WARN_PA = 4200e6                          #: ISO 76:2006 reference contact stress, ball bearings
P_MAX_REFUSE_PA = 4200e6 * 2.0 ** (1.0 / 3.0)   #: twice the rated contact load (p ∝ Q^(1/3))
T_LUBRICANT_REFUSE_C = (-40.0, 250.0)           #: lubricant temperature accepted [°C]
T_LUBRICANT_WARN_C = (-20.0, 150.0)             #: lubricant temperature validated [°C]

#: Every limit, by name (values in SI; ``unit`` and ``scale`` for messages).
LIMITS = {
    "osculation": Limit(
        "osculation", "-", (0.5, 2.0), (0.505, 1.4), lo_open=True,
        source="groove radius / ball diameter: > 0.5 or the ball does not fit its groove; beyond 2 the race is "
               "flatter than any ball bearing groove and its geometry (A = (f_i + f_o - 1) D) loses its meaning; "
               "validated from the catalogue range 0.505-0.57 (Harris 2001 ch. 2) to seed 001's modified races "
               "(0.655 and 1.387)"),
    "n_dm": Limit(
        "speed n·dm", "mm/min", (0.0, 4.0e6), (None, 1.0e6),
        source="refused beyond the fastest ball bearings run (3e6 DN, Bamberger et al. 1976); "
               "warned beyond twice the fastest scored rig (seed 004: 5.6e5)"),
    "p_max": Limit(
        "maximum contact pressure", "MPa", (0.0, P_MAX_REFUSE_PA), (None, P_MAX_WARN_PA), scale=1e-6,
        source="ISO 76:2006 4200 MPa for ball bearings (warn); refused beyond twice the rated contact "
               "load, 4200·2^(1/3) MPa, where the permanent deformation (Palmgren 1959, ∝ Q²) is 4× "
               "ISO 76's and Hertz's elastic contact no longer holds"),
    "contact_angle": Limit(
        "contact angle + half the contact ellipse, from the groove bottom", "deg", (None, math.pi / 2), (None, None), scale=180 / math.pi,
        source="the contact must stay on the race side of the groove (Harris 2001 ch. 2): beyond 90° from the "
               "groove bottom (the radial plane; a thrust bearing's axis) the ellipse, a/(f D) wide on the groove "
               "(Harris 2001 ch. 6), passes the groove's equator, over any shoulder"),
    "hertz_size": Limit(
        "Hertz contact size / radius of curvature", "-", (0.0, 1.0), (None, 0.2),
        source="Hertz's theory assumes contact dimensions small against the radii (Johnson 1985 §4.1)"),
    "lubricant_T": Limit(
        "lubricant temperature", "°C", T_LUBRICANT_REFUSE_C, T_LUBRICANT_WARN_C,
        source="ASTM D341 two-point fit at 40 and 100 °C: warned 60 K below / 50 K above the data, refused "
               "below −40 °C (bearing oils at or past their pour point) and above 250 °C (past their flash point)"),
    "s0": Limit(
        "static safety s0", "-", (0.5, None), (1.0, None),
        source="ISO 76:2006: s0 < 1 means permanent deformation above 1e-4 D; refused below 0.5, a static "
               "equivalent load twice C0: the refused contact pressure (4200·2^(1/3) MPa, p ∝ Q^(1/3)) at the "
               "standard's load distribution, where the deformation (Palmgren 1959, ∝ Q²) is 4× ISO 76's"),
    "kappa": Limit(
        "viscosity ratio κ = ν/ν1", "-", (None, None), (0.1, None),
        source="ISO 281:2007 §9.3.3: a_ISO is defined for 0.1 <= κ <= 4; above 4 the standard takes κ = 4 (a "
               "thicker film adds no life: stated with the ratings, not warned); below 0.1 the film no longer "
               "separates the surfaces and a_ISO does not apply (evaluated at 0.1)"),
    "operating_clearance": Limit(
        "operating radial clearance", "µm", (None, None), (0.0, None), scale=1e6,
        source="clearance consumed by the fits, the temperatures and the speed: a radial preload, each ball "
               "compressed by −P_d/2 between the centred rings (Q0 = K_n (−P_d/2)^1.5; Harris & Kotzalas 2007 ch. 3, "
               "7), whose load and heat grow as the inner ring warms (the models' data are of bearings with a "
               "clearance)"),
    "thermal_preload": Limit(
        "warm / cold preload of a position-preloaded pair", "-", (None, None), (0.5, 2.0),
        source="reasoning: the rings and balls warmer than at mounting, the inner ring above the outer, raise a "
               "position preload (Harris & Kotzalas 2007 ch. 3, 8), as do the balls' centrifugal force and the inner "
               "ring's growth at speed (Jones 1960); beyond twice the mounted one the bearing runs "
               "a preload class heavier than chosen (the makers' light, medium and heavy preloads step by about 2) "
               "and its heat grows with it: the runaway of spindle bearings; below half of it (a shaft growing "
               "axially more than the housing, a cold inner ring) a preload class lighter, at 0 the pair has play: "
               "its balls may skid and the spindle loses stiffness"),
    "load": Limit(
        "load (Fa, Fr or M/ℜ_i), when not 0", "N", (1e-6, None), (None, None),
        source="below 1 µN the Hertz approach of a ball, (Q/K)^(2/3) with K ≈ 1e10 N/m^1.5, is below a tenth of "
               "an atomic spacing, where continuum contact (Hertz; Johnson 1985 §4.2) has no meaning (0: unloaded)"),
    "speed": Limit(
        "speed, when not 0", "rpm", (1e-6, None), (None, None),
        source="below 1e-6 rpm (one turn in 1.9 years) the bearing is at rest for every model here, and their "
               "powers of the speed underflow the floating-point range (0: at rest)"),
    "minimum_load": Limit(
        "load / SKF's minimum load, radial (deep groove) or axial (angular contact, thrust)", "-", (None, None),
        (1.0, None),
        source="SKF 2018 (Rolling bearings, pp. 106, 254, 398, 469): below the requisite minimum load the balls may "
               "skid and smear; the load and loss models assume rolling balls (raceway control, no gross slip). Deep "
               "groove: the larger of the radial and axial load against F_rm = k_r (ν n/1000)^(2/3) (d_m/100)^2 kN at "
               "the operating viscosity (a radial preload meets it); single row angular contact (single or in tandem) "
               "and thrust: the axial load against F_am = A (n/1000)^2 kN, A of the bearing's product table row"),
    "skf_phi_bl": Limit(
        "SKF weighting factor Φ_bl", "-", (None, None), (None, 0.5),
        source="SKF 2004: mostly boundary lubrication, μ_bl an estimated constant"),
}


def _bound_text(lim: Limit, which: str) -> str:
    """A limit's refused or warned values, as a reader of a table reads them."""
    lo, hi = getattr(lim, which)
    f = (lambda v: f"{v * lim.scale:.4g}")  # noqa: E731
    open_lo = lim.lo_open and which == "refuse"
    if lo is None and hi is None:
        return "–"
    if lo is not None and hi is not None:
        return f"outside {'(' if open_lo else '['}{f(lo)}, {f(hi)}]"
    if hi is not None:
        return f"> {f(hi)}"
    return f"{'<=' if open_lo else '<'} {f(lo)}"


def limits_table(sources: bool = True) -> str:
    """:data:`LIMITS` as a Markdown table: quantity, unit, refused and warned values (and the source).

    The README's table of the limits is this table (tests/test_readme.py checks it).
    """
    cols = ["quantity", "unit", "refused", "warned"] + (["source"] if sources else [])
    rows = ["| " + " | ".join(cols) + " |", "|" + "---|" * len(cols)]
    for lim in LIMITS.values():
        cells = [lim.quantity, "–" if lim.unit == "-" else lim.unit, _bound_text(lim, "refuse"), _bound_text(lim, "warn")]
        rows.append("| " + " | ".join(cells + ([lim.source] if sources else [])) + " |")
    return "\n".join(rows)


def _minmax(value):
    if isinstance(value, (float, int)) and not isinstance(value, bool):
        lo = hi = float(value)
    else:
        a = np.asarray(value, dtype=float)
        if a.size == 0:
            return None
        lo, hi = (float(a), float(a)) if a.ndim == 0 else (float(a.min()), float(a.max()))
    if math.isnan(lo) or math.isnan(hi):
        return "nan"
    return lo, hi


def _inside(mm, bounds, lo_open) -> bool:
    lo, hi = bounds
    return ((lo is None or (mm[0] > lo if lo_open else mm[0] >= lo)) and (hi is None or mm[1] <= hi))


def _show(value, scale):
    a = np.asarray(value, dtype=float) * scale
    if a.size == 1:
        return float(a.reshape(-1)[0])
    return f"{float(a.min()):.4g}…{float(a.max()):.4g}"


def check(name: str, value, field: str, *, what: str = "", category=OutsideValidity,
          warn: bool = True, given=None) -> list:
    """Check ``value`` (scalar or array, SI) against limit ``name`` of :data:`LIMITS`.

    Raises InputError(field, value, accepted range + source) when any element is outside the
    accepted range (or not finite); warns :class:`~thermobear.errors.OutsideValidity` (one warning
    for the array) when outside the validated range and returns the warnings issued.

    Parameters
    ----------
    name : str          key of :data:`LIMITS`
    value : array_like  the quantity, SI (p_max [Pa], angles [rad], n·dm [mm/min], T [°C], …)
    field : str         the input the value comes from, as the user wrote it (e.g. ``operation.Fa_N``)
    what : str          optional context for the message (e.g. "inner contact of ball 3")
    category : type     the warning class (an OutsideValidity subclass, e.g. ExtrapolationWarning)
    warn : bool         False: refuse only (e.g. while reading a scene; solvers warn when they run)
    given : optional    the input as the user gave it, shown as the field's value when the quantity is
                        computed from it (e.g. the loads whose contact pressure is refused); the
                        quantity's offending value then goes into the message
    """
    lim = LIMITS[name]
    mm = _minmax(value)
    if mm is None:
        return []
    finite = mm != "nan" and -math.inf < mm[0] and mm[1] < math.inf
    if finite and _inside(mm, lim.refuse, lim.lo_open) and (not warn or _inside(mm, lim.warn, False)):
        return []                                      # the common case, without building messages
    shown = _show(value, lim.scale) if mm != "nan" else value
    ctx = f" ({what})" if what else ""
    if mm == "nan":
        raise InputError(field, shown, f"{lim.quantity} must be finite{ctx}")
    lo, hi = mm
    rlo, rhi = lim.refuse
    below = rlo is not None and (lo < rlo or (lim.lo_open and lo <= rlo))
    if below or (rhi is not None and hi > rhi):
        quantity = lim.quantity
        if given is not None:
            shown, quantity = given, f"{lim.quantity} {(lo if below else hi) * lim.scale:.4g} {lim.unit}"
        verb = "lie in" if rlo is not None and rhi is not None else "be"
        raise InputError(field, shown, f"{quantity} must {verb} {lim.range_text('refuse')} [{lim.unit}]{ctx} "
                                       f"({lim.source})")
    if not finite:                                     # infinite on a side without a bound
        raise InputError(field, shown, f"{lim.quantity} must be finite{ctx}")
    wlo, whi = lim.warn
    out = []
    if not warn:
        return out
    if (wlo is not None and lo < wlo) or (whi is not None and hi > whi):
        v = lo if (wlo is not None and lo < wlo) else hi
        msg = (f"{field}: {lim.quantity} {v * lim.scale:.4g} {lim.unit} outside the validated range "
               f"{lim.range_text('warn')}{ctx} — {lim.source}")
        w = category(msg, quantity=name, value=v * lim.scale, limit=lim.range_text("warn"),
                            source=lim.source, field=field)
        warnings.warn(w, stacklevel=2)
        out.append(w)
    return out


@contextlib.contextmanager
def collect(replay: bool = True):
    """Collect the :class:`~thermobear.errors.OutsideValidity` warnings issued inside the block.

    Yields a list that receives the unique warnings (by message) in order; with ``replay`` they (and
    every other warning of the block) are also passed on to the caller's warning filters.

    >>> import warnings
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore")
    ...     with collect() as got:
    ...         _ = check("n_dm", 2e6, "operation.n_rpm")
    >>> [w.quantity for w in got]
    ['n_dm']
    """
    got: list = []
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        yield got
    seen = set()
    for r in rec:
        if issubclass(r.category, OutsideValidity):
            w = r.message if isinstance(r.message, OutsideValidity) else r.category(str(r.message))
            if str(w) not in seen:
                seen.add(str(w))
                got.append(w)
    if replay:
        for r in rec:                              # pass everything on, once each
            warnings.warn_explicit(r.message, r.category, r.filename, r.lineno)


def warning_lines(ws) -> list:
    """One line per warning: ``warning: <Category>: <message>`` (the command line's form)."""
    return [f"warning: {type(w).__name__}: {' '.join(str(w).split())}" for w in ws]
