r"""Loads the contacts cannot carry: the one place the load solvers and the scene's solvers refuse them.

A rigid-ring solution exists for any load (Hertz's law has no limit), so a load far beyond what a
bearing carries still returns ball loads — with contact angles past the groove edge and pressures no
steel survives.  Two limits of :data:`thermobear.validity.LIMITS` say where the answer stops meaning
anything, checked on every contact of a solution (:func:`check_contacts`):

* ``"p_max"``: the maximum Hertz pressure p_max = 3Q/(2πab) (Harris 2001 [1] eq 6.47) beyond
  :data:`thermobear.validity.P_MAX_REFUSE_PA`, twice the ISO 76 [2] static rating load;
* ``"contact_angle"`` (truncation): the contact ellipse reaches past the groove's equator,
  |α − α_b| + a/(f D) > 90° (:func:`groove_angle`; a the semi-axis across the rolling direction, on the
  groove of radius f D; α_b the direction of the groove bottom: 0 in a radial or angular contact bearing,
  90° in a thrust bearing's washers; Harris 2001 ch. 2 and 6).

:func:`check_loads` refuses, before any solve, loads no ball set can carry (a lower bound of the largest
ball load at the most favourable contact); :func:`refuse_overload` checks a solution: both limits scale with
the load as Q^(1/3), so bounds of p_max and a at 1 N over every contact angle (:func:`contact_bounds`,
:func:`_upper_bounds`) screen the cases, and the contacts of a case the screen does not clear are evaluated
exactly (:func:`thermobear.contact.hertz.hertz` at their own angles).

References
----------
.. [1] Harris, T. A. (2001). *Rolling Bearing Analysis*, 4th ed., Wiley, ch. 2 (groove geometry) and
   ch. 6 (eq 6.47, Hertz pressure; contact ellipse).
.. [2] ISO 76:2006. Rolling bearings — Static load ratings, §4 (4 200 MPa, ball bearings).
"""
from __future__ import annotations

import numpy as np

from thermobear.contact.geometry import BallBearing
from thermobear.contact.hertz import hertz
from thermobear.errors import ContactLimit, InputError
from thermobear.validity import LIMITS, P_MAX_REFUSE_PA, check

__all__ = ["check_loads", "check_contacts", "contact_bounds", "contact_limits", "groove_angle", "loads_text",
           "refuse_overload"]


def _groove_bottom(brg: BallBearing) -> float:
    """Contact angle of the groove bottom [rad]: the radial plane, for a thrust bearing the axis."""
    return 0.5 * np.pi if brg.kind == "thrust" else 0.0


def groove_angle(brg: BallBearing, alpha, a, f):
    r"""Angle from the groove bottom to the far edge of the contact ellipse [rad].

    .. math:: \theta = |\alpha - \alpha_g| + \frac{a}{f D}

    α the contact angle, α_g that of the groove bottom (0; π/2 for a thrust bearing), a the semi-axis
    across the rolling direction [m] (along the groove), f D the groove radius [m]: the arc a on the
    groove seen from its curvature centre (Harris 2001 ch. 2 and 6).  Beyond π/2 the ellipse passes
    the groove's equator (:data:`thermobear.validity.LIMITS` ``contact_angle``).

    >>> from thermobear.contact.geometry import bearing
    >>> round(float(np.degrees(groove_angle(bearing("7210"), np.radians(40.0), 2e-3, 0.52))), 2)
    57.35
    """
    return np.abs(np.asarray(alpha, float) - _groove_bottom(brg)) + np.asarray(a, float) / (f * brg.D)


def check_contacts(brg: BallBearing, sides, field: str, *, warn: bool = False, given=None) -> list:
    """The limits of the contacts of an answer: maximum pressure and the contact ellipse inside its groove.

    ``sides``: ``"inner"`` / ``"outer"`` → mapping with the contacts' Q [N], alpha [rad], a, b [m] (a
    :class:`~thermobear.losses.ContactSet`'s ``sides``, a :class:`~thermobear.losses.LossResult`'s
    ``contacts``).  Raises :class:`~thermobear.errors.ContactLimit` (an InputError) naming ``field`` (showing
    ``given``, e.g. the loads) beyond the refused limits (:data:`thermobear.validity.LIMITS` ``p_max``,
    ``contact_angle``); returns the warnings (``warn``).
    """
    out = []
    for side, f in (("inner", brg.fi), ("outer", brg.fo)):
        c = sides[side]
        Q, a, b = (np.asarray(c[k], float) for k in ("Q", "a", "b"))
        with np.errstate(divide="ignore", invalid="ignore"):
            p = np.where(Q > 0, 1.5 * Q / (np.pi * a * b), 0.0)
        theta = np.where(Q > 0, groove_angle(brg, c["alpha"], a, f), 0.0)
        try:
            out += check("p_max", p, field, what=f"{side} contacts", warn=warn, given=given)
            out += check("contact_angle", theta, field, what=f"{side} contacts", warn=warn, given=given)
        except InputError as exc:            # loads the contacts cannot carry: the named kind of bad input
            raise ContactLimit(exc.field, exc.value, exc.expected) from None
    return out


#: Hamrock–Brewe (1983) against the exact Hertz ellipse over 1 <= Ry/Rx <= 1e10 (tests/test_hertz.py):
#: a_exact <= 1.0046 a_HB and p_exact >= 0.9976 p_HB; the bounds below keep a margin.
_A_OVER_HB, _P_UNDER_HB = 1.01, 0.99


def _rx_range(brg: BallBearing):
    """The least and greatest R_x = D (1 ∓ γ)/2 of any contact of the bearing (|γ| <= D/d_m) [m]."""
    return 0.5 * brg.D * (1.0 - brg.D / brg.dm), 0.5 * brg.D * (1.0 + brg.D / brg.dm)


def contact_bounds(brg: BallBearing) -> tuple:
    """(a, p_max) at Q = 1 N [m, Pa] bounding every contact of the bearing (a ∝ Q^(1/3), p_max ∝ Q^(1/3)): a and
    p_max fall as Rx grows at a given Ry, and Rx = D (1 ∓ γ)/2 with |γ| <= D/dm.  Bounds: a of the inner and
    outer contacts at the smallest Rx (above any contact's a), p_max of the inner contact at the largest Rx
    (below any inner contact's p_max), from the Hamrock–Brewe ellipse with its margins (:data:`_A_OVER_HB`,
    :data:`_P_UNDER_HB`)."""
    lo, hi = _rx_range(brg)
    c = hertz(1.0, np.array([lo, lo, hi]), np.array([brg.Ry_i, brg.Ry_o, brg.Ry_i]), brg.E_prime,
              method="hamrock_brewe")
    return c.a[:2] * _A_OVER_HB, c.p_max[2] * _P_UNDER_HB


def _upper_bounds(brg: BallBearing) -> tuple:
    """Upper bounds at Q = 1 N of p_max [Pa] and of the ellipse's angular half-width a/(f D) [rad] of any contact
    of the bearing: the exact Hertz contacts of both sides at the smallest R_x (:func:`contact_bounds`), +1 %."""
    lo = _rx_range(brg)[0]
    c = hertz(1.0, np.array([lo, lo]), np.array([brg.Ry_i, brg.Ry_o]), brg.E_prime)
    return 1.01 * float(np.max(c.p_max)), 1.01 * float(np.max(c.a / (np.array([brg.fi, brg.fo]) * brg.D)))


def _radial_share(Z: int) -> float:
    r"""An upper bound of Σ_j max(cos(ψ_j − φ), 0) over Z equally spaced balls and any direction φ: Z/π + 1
    (the sum against its integral, Z/(2π) ∫ max(cos, 0) = Z/π, plus one term).  A radial load (or a moment over
    the arm) F needs a largest ball load of at least F over this share: only the balls on its side push."""
    return Z / np.pi + 1.0


def check_loads(brg: BallBearing, Fa, Fr, M=None, n_rpm=0.0, *, Fz=0.0, My=None,
                names=("Fa", "Fr", "M", "n_rpm"), bounds=None):
    """Refuse, before any solve, loads and speeds no answer exists for.

    The inputs must broadcast together; the speed must be finite, >= 0 and inside the accepted n·d_m
    (:data:`thermobear.validity.LIMITS` ``n_dm``, ``speed``); each load 0 or at least the ``load`` limit;
    and the loads must not exceed what the balls can carry at the refused contact pressure: a ball carries
    at most its load Q along the axis, so the largest ball load is at least F_a/Z; only the balls on the side
    of a radial load (√(F_r² + F_z²)) or of a moment (√(M² + M_y²)/ℜ_i) push against it, so it is at least
    that load over their share (:func:`_radial_share`); at that load even the most favourable inner contact
    (the largest R_x) is beyond :data:`thermobear.validity.P_MAX_REFUSE_PA`.  Signs and finiteness of the
    loads are the forms' own checks (:func:`thermobear.loads.rings.batch_loads`).  ``names``: the inputs as the
    caller calls them (Fa, Fr, M, n_rpm); ``bounds``: the bearing's :func:`contact_bounds`, if known.

    >>> from thermobear.contact.geometry import bearing
    >>> check_loads(bearing("7210"), Fa=450.0, Fr=[325.0, 650.0])
    >>> try:
    ...     check_loads(bearing("7210"), Fa=1e5, Fr=1e6)
    ... except InputError as e:
    ...     print(e.field)
    Fr
    """
    arrays = [np.asarray(v, dtype=float) for v in (Fa, Fr, 0.0 if M is None else M, n_rpm, Fz,
                                                   0.0 if My is None else My)]
    try:
        np.broadcast_shapes(*(v.shape for v in arrays))
    except ValueError:
        shown = arrays if any(v.ndim for v in arrays[4:]) else arrays[:4]      # Fz, My where given as arrays
        raise InputError(", ".join(names + ("Fz", "My")[:len(shown) - 4]), "shapes " + ", ".join(str(v.shape) for v in shown),
                         "must broadcast together (numpy rules)") from None
    n = arrays[3]
    if n.size and not (n.min() >= 0 and n.max() < np.inf):                  # NaN fails both
        raise InputError(names[3], n_rpm, "inner-ring speed must be finite and >= 0 [rpm] (outer ring fixed)")
    with np.errstate(over="ignore"):              # beyond the float range: beyond the limit
        check("n_dm", n * brg.dm * 1e3, names[3], warn=False, given=n_rpm)
        share = _radial_share(brg.Z)
        loads = (arrays[0], np.hypot(arrays[1], arrays[4]), np.hypot(arrays[2], arrays[5]) / brg.R_inner_locus)
    check("speed", n[n > 0], names[3], warn=False)
    if not all(np.all(np.isfinite(v)) for v in arrays[:3] + arrays[4:]):
        return                                    # not numbers: the forms name them
    for name, v in zip(names, loads):
        check("load", v[(v > 0) & (v < np.inf)], name, warn=False)      # (overflowed M/ℜ_i: the pressure says)
    peaks = [float(np.max(v)) if v.size else 0.0 for v in loads]
    least = [peaks[0] / brg.Z, peaks[1] / share, peaks[2] / share]        # largest ball load, at least [N]
    if not max(least) > 0:
        return                                    # nothing to carry
    k = int(np.argmax(least))
    p_least = (bounds or contact_bounds(brg))[1] * np.cbrt(least[k])
    if p_least > P_MAX_REFUSE_PA:
        given = (Fa, Fr, M)[k]
        given = np.asarray(given).item() if np.size(given) == 1 else given
        try:
            check("p_max", p_least, names[k], what=f"at least: the largest ball load of {brg.name or 'the bearing'}, "
                                                    f"{least[k]:.4g} N or more", warn=False, given=given)
        except InputError as exc:            # loads the contacts cannot carry (ContactLimit)
            raise ContactLimit(exc.field, exc.value, exc.expected) from None


def contact_limits(brg: BallBearing, Q_i, Q_o, alpha_i, alpha_o):
    r"""Maximum Hertz pressure and reach of the contact ellipse of every contact.

    Parameters
    ----------
    brg : BallBearing
    Q_i, Q_o : array_like        inner / outer contact loads [N], balls on the last axis
    alpha_i, alpha_o : array_like contact angles [rad]

    Returns
    -------
    dict  side → (p_max [Pa], reach [rad]) of the shape of the loads; reach = |α − α_b| + a/(f D), the angle
          from the groove bottom to the far end of the contact ellipse (:func:`groove_angle`; 0 unloaded)

    Examples
    --------
    >>> from thermobear.contact.geometry import bearing
    >>> lim = contact_limits(bearing("6208"), [3000.0], [3000.0], [0.0], [0.0])
    >>> [round(float(lim[s][0][0]) / 1e6) for s in ("inner", "outer")]
    [2591, 2369]
    """
    out = {}
    for side, Q, al, f in (("inner", Q_i, alpha_i, brg.fi), ("outer", Q_o, alpha_o, brg.fo)):
        Q, al = np.broadcast_arrays(np.asarray(Q, float), np.asarray(al, float))
        if side == "inner":
            c = hertz(np.maximum(Q, 0.0), brg.Rx_i(al), brg.Ry_i, brg.E_prime)
        else:
            c = hertz(np.maximum(Q, 0.0), brg.Rx_o(al), brg.Ry_o, brg.E_prime)
        out[side] = (np.asarray(c.p_max, float), np.where(Q > 0, groove_angle(brg, al, c.a, f), 0.0))
    return out


def refuse_overload(brg: BallBearing, ld, field: str = "Fa, Fr, M") -> None:
    """InputError naming the loads of the first case of ``ld`` (a LoadDistribution) whose contacts cannot carry
    them: p_max or the contact ellipse beyond the limits of :func:`check_contacts` (module docstring).  Returns
    None when every contact is inside both.  A contact beyond Hertz's size limit is the loads' fault, named so."""
    Z = brg.Z
    Qi, Qo, ai, ao = (np.asarray(v, dtype=float).reshape(-1, Z) for v in (ld.Q_i, ld.Q_o, ld.alpha_i, ld.alpha_o))
    lim_a, ab = LIMITS["contact_angle"].refuse[1], _groove_bottom(brg)
    p_hi, a_hi = _upper_bounds(brg)
    # per case, both sides at once: the bounds at the largest load and the largest angle from the groove bottom
    q3 = np.cbrt(np.maximum(Qi.max(axis=1), Qo.max(axis=1)))
    reach = np.maximum(np.abs(ai - ab).max(axis=1), np.abs(ao - ab).max(axis=1))
    sus = np.flatnonzero((q3 * p_hi > P_MAX_REFUSE_PA) | (reach + q3 * a_hi > lim_a))
    if not sus.size:
        return
    for k in sus:                                 # exact, the suspects only, in order: the first is named
        one = {"inner": (Qi[k], ai[k], brg.Rx_i, brg.Ry_i), "outer": (Qo[k], ao[k], brg.Rx_o, brg.Ry_o)}
        case = np.array([_case(ld, name, k) for name in ("Fa", "Fr", "M", "Fz", "My")])
        case[np.abs(case) < 1e-9 * np.abs(case).max()] = 0.0            # a solver's round-off is no load
        sides, given = {}, loads_text(*case)
        for side, (Q, al, Rx, Ry) in one.items():
            try:
                c = hertz(np.maximum(Q, 0.0), Rx(al), Ry, brg.E_prime)
            except InputError as e:
                raise InputError(field, given, f"{side} contacts: {e.expected}") from None
            sides[side] = {"Q": Q, "alpha": al, "a": c.a, "b": c.b}
        check_contacts(brg, sides, field, given=given)


def _case(ld, name, k):
    """Load ``name`` of case k (flat index) of a LoadDistribution."""
    v = np.ravel(np.asarray(getattr(ld, name, 0.0), float))
    return float(v[k if v.size > 1 else 0]) if v.size else 0.0


def loads_text(Fa, Fr, M=None, Fz=None, My=None) -> str:
    """The loads as a user reads them in a message: ``"Fa 450 N, Fr 325 N"`` (ranges for arrays; M, Fz, My
    where not 0).

    >>> loads_text(450.0, [325.0, 650.0], 2.0)
    'Fa 450 N, Fr 325…650 N, M 2 N m'
    >>> loads_text(450.0, 325.0, Fz=-100.0)
    'Fa 450 N, Fr 325 N, Fz -100 N'
    """
    def txt(v):
        v = np.asarray(v, dtype=float)
        return f"{float(v.min()):g}…{float(v.max()):g}" if v.size > 1 and v.min() != v.max() else f"{float(v.flat[0]):g}"
    out = f"Fa {txt(Fa)} N, Fr {txt(Fr)} N"
    for name, v, unit in (("M", M, "N m"), ("Fz", Fz, "N"), ("My", My, "N m")):
        if v is not None and np.any(np.asarray(v)):
            out += f", {name} {txt(v)} {unit}"
    return out
