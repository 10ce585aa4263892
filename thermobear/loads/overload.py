r"""Loads the contacts cannot carry: refused by the load distribution, naming the loads.

A rigid-ring solution exists for any load (Hertz's law has no limit), so a load far beyond what a
bearing carries still returns ball loads — with contact angles past the groove edge and pressures no
steel survives.  Two limits of :data:`thermobear.validity.LIMITS` say where the answer stops meaning
anything, checked on every contact of a solution:

* ``"p_max"``: the maximum Hertz pressure p_max = 3Q/(2πab) (Harris 2001 [1] eq 6.47) beyond
  :data:`thermobear.validity.P_MAX_REFUSE_PA`, twice the ISO 76 [2] static rating load;
* ``"contact_angle"`` (truncation): the contact ellipse reaches past the groove's equator,
  |α − α_b| + a/(f D) > 90° (a the semi-axis across the rolling direction, on the groove of radius f D;
  α_b the direction of the groove bottom: 0 in a radial or angular contact bearing, 90° in a thrust
  bearing's washers; Harris 2001 ch. 2 and 6).

Both scale with the load as Q^(1/3) for a given contact angle; a per-bearing bound of p_max(1 N, α)
and a(1 N, α) over 0 ≤ α ≤ 90° (:func:`_unit_bounds`), at each case's largest load and angle, screens
the cases, and the contacts of a case the screen does not clear are evaluated exactly
(:func:`thermobear.contact.hertz.hertz` at their own angles).

References
----------
.. [1] Harris, T. A. (2001). *Rolling Bearing Analysis*, 4th ed., Wiley, ch. 2 (groove geometry) and
   ch. 6 (eq 6.47, Hertz pressure; contact ellipse).
.. [2] ISO 76:2006. Rolling bearings — Static load ratings, §4 (4 200 MPa, ball bearings).
"""
from __future__ import annotations

from functools import lru_cache

import numpy as np

from thermobear.contact.geometry import BallBearing
from thermobear.contact.hertz import hertz
from thermobear.errors import InputError
from thermobear.validity import LIMITS, P_MAX_REFUSE_PA

__all__ = ["contact_limits", "refuse_overload"]

_GRID = np.linspace(0.0, 0.5 * np.pi, 31)


def _contacts(brg: BallBearing, side: str, Q, alpha):
    """Hertz contacts of one side at loads Q [N] and contact angles α [rad] (arrays of one shape)."""
    if side == "inner":
        return hertz(Q, brg.Rx_i(alpha), brg.Ry_i, brg.E_prime)
    return hertz(Q, brg.Rx_o(alpha), brg.Ry_o, brg.E_prime)


@lru_cache(maxsize=32)
def _unit_bounds(brg: BallBearing):
    """The largest p_max [Pa] and angular half-width a/(f D) of the contact ellipse across the groove [rad] of
    either side's contacts at Q = 1 N, over α ∈ [0, 90°] (+1 % margin)."""
    p, a = [], []
    for side, f in (("inner", brg.fi), ("outer", brg.fo)):
        c = _contacts(brg, side, np.ones_like(_GRID), _GRID)
        p.append(1.01 * float(np.max(c.p_max)))
        a.append(1.01 * float(np.max(c.a)) / (f * brg.D))
    return {"both": (max(p), max(a))}


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
          from the groove bottom to the far end of the contact ellipse (0 for an unloaded contact)

    Examples
    --------
    >>> from thermobear.contact.geometry import bearing
    >>> lim = contact_limits(bearing("6208"), [3000.0], [3000.0], [0.0], [0.0])
    >>> [round(float(lim[s][0][0]) / 1e6) for s in ("inner", "outer")]
    [2591, 2369]
    """
    out, ab = {}, _bottom(brg)
    for side, Q, al, f in (("inner", Q_i, alpha_i, brg.fi), ("outer", Q_o, alpha_o, brg.fo)):
        Q, al = np.broadcast_arrays(np.asarray(Q, float), np.asarray(al, float))
        c = _contacts(brg, side, np.maximum(Q, 0.0), al)
        a = np.asarray(c.a, float)                                # semi-axis across the rolling direction
        out[side] = (np.asarray(c.p_max, float), np.where(Q > 0, np.abs(al - ab) + a / (f * brg.D), 0.0))
    return out


def refuse_overload(brg: BallBearing, ld, field: str = "Fa, Fr, M") -> None:
    """InputError naming the loads of the first case of ``ld`` (a LoadDistribution) whose contacts cannot carry
    them: p_max beyond :data:`thermobear.validity.P_MAX_REFUSE_PA` or an ellipse past the groove edge
    (module docstring).  Returns None when every contact is inside both limits."""
    Z = brg.Z
    Qi, Qo, ai, ao = (np.asarray(v, dtype=float).reshape(-1, Z) for v in (ld.Q_i, ld.Q_o, ld.alpha_i, ld.alpha_o))
    lim_a, ab = LIMITS["contact_angle"].refuse[1], _bottom(brg)
    p_hi, a_hi = _unit_bounds(brg)["both"]
    # per case, both sides at once: the bounds at the largest load and the largest angle from the groove bottom
    q3 = np.cbrt(np.maximum(Qi.max(axis=1), Qo.max(axis=1)))
    reach = np.maximum(np.abs(ai - ab).max(axis=1), np.abs(ao - ab).max(axis=1))
    suspect = (q3 * p_hi > P_MAX_REFUSE_PA) | (reach + q3 * a_hi > lim_a)
    if not suspect.any():
        return
    sus = np.flatnonzero(suspect)
    lim = contact_limits(brg, Qi[sus], Qo[sus], ai[sus], ao[sus])        # exact, the suspects only
    bad = {side: (lim[side][0].max(axis=1) > P_MAX_REFUSE_PA) | (lim[side][1].max(axis=1) > lim_a)
           for side in ("inner", "outer")}
    over = bad["inner"] | bad["outer"]
    if over.any():
        j = int(np.argmax(over))
        side = "inner" if bad["inner"][j] else "outer"
        raise InputError(field, _loads_text(ld, int(sus[j])), _why(side, lim[side][0][j], lim[side][1][j], lim_a))


def _bottom(brg: BallBearing) -> float:
    """Direction of the groove bottom α_b [rad]: 90° for a thrust bearing's washers, 0 otherwise."""
    return 0.5 * np.pi if brg.kind == "thrust" else 0.0


def _why(side, p, reach, lim_a) -> str:
    if p.max() > P_MAX_REFUSE_PA:
        return (f"more than the contacts can carry: maximum contact pressure {p.max() / 1e6:.4g} MPa at the {side} "
                f"contacts > {P_MAX_REFUSE_PA / 1e6:.4g} MPa ({LIMITS['p_max'].source})")
    return (f"more than the contacts can carry: the {side} contact ellipse reaches {np.degrees(reach.max()):.4g}° "
            f"from the groove bottom > {np.degrees(lim_a):.4g}° ({LIMITS['contact_angle'].source})")


def _loads_text(ld, k) -> str:
    """The loads of case k of ``ld`` (flat index) as text."""
    parts = []
    for name, unit in (("Fa", "N"), ("Fr", "N"), ("M", "N m"), ("Fz", "N"), ("My", "N m")):
        v = np.ravel(np.asarray(getattr(ld, name), float))
        if v.size:
            x = float(v[k if v.size > 1 else 0])
            if name in ("Fa", "Fr") or x != 0.0:
                parts.append(f"{name} = {x:g} {unit}")
    return ", ".join(parts)
