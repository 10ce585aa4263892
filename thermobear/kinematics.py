r"""Ball kinematics: cage and ball speeds, entrainment (rolling) speed, spin.

Rigid-body rolling without slip at the two contact centres (Jones 1959; Harris
2001 ch. 8; PHYSICS.md §4).  Work in the cage frame: x̂ bearing axis, r̂ radial
through the ball centre, t̂ = x̂ × r̂.  Ring speeds ω_i, ω_o [rad/s] (any may
rotate), contact angles α_i, α_o [rad] (equal in the low-speed form), ball
spin axis ω_b = ω_R (cos β x̂ + sin β r̂) with pitch angle β.  No slip at the
contact centres:

    (D/2) ω_R cos(α_o + β) = (ω_o − ω_c)(dm/2)(1 + γ' cos α_o)
   −(D/2) ω_R cos(α_i + β) = (ω_i − ω_c)(dm/2)(1 − γ' cos α_i),    γ' = D/dm

a linear system in (ω_c, ω_R) solved in closed form.  Spin (pivoting) speed at
each contact is the normal component of the relative angular velocity:

    ω_s,o = ω_R sin(α_o + β) − (ω_o − ω_c) sin α_o
    ω_s,i = ω_R sin(α_i + β) − (ω_i − ω_c) sin α_i

β (here β = −β_Harris, PHYSICS.md §4 and pitfall 15): ``control="outer"`` (Jones
outer-raceway control, zero spin at the outer contact: tan(−β) = sin α_o / (cos α_o + γ')),
``"inner"`` (zero spin at the inner contact: tan(−β) = sin α_i / (cos α_i − γ')),
or ``"radial"`` (β = −π/2, the ball axis radial: the symmetric choice
of a thrust ball bearing, seed 000 eqs 1–2 and 13, pivoting speed = ω_c).
At α = 0 outer and inner control give β = 0 and zero spin; radial control has no
rolling solution there (the ball axis would be normal to the contacts) and is refused.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ._arrays import out as _f

from .errors import InputError

__all__ = ["BallKinematics", "ball_kinematics", "cage_speed", "entrainment_speed", "CONTROLS"]

CONTROLS = ("outer", "inner", "radial")


@dataclass(frozen=True)
class BallKinematics:
    """Kinematics of the balls (arrays broadcast from the inputs).

    Attributes
    ----------
    omega_c : cage (orbital) speed [rad/s]
    omega_R : ball spin speed about its own axis, relative to the cage [rad/s] (signed)
    beta : pitch angle of the ball axis from the bearing axis [rad]
    u_i, u_o : entrainment (mean rolling) speed at the inner / outer contact [m/s], ≥ 0
    spin_i, spin_o : spin (pivoting) speed at the inner / outer contact [rad/s] (signed)
    spin_roll_i, spin_roll_o : spin-to-roll ratio ω_s / (ω_R cos(α + β)) [-]
    """

    omega_c: np.ndarray
    omega_R: np.ndarray
    beta: np.ndarray
    u_i: np.ndarray
    u_o: np.ndarray
    spin_i: np.ndarray
    spin_o: np.ndarray
    spin_roll_i: np.ndarray
    spin_roll_o: np.ndarray


def cage_speed(omega_i, omega_o, gamma):
    r"""Cage speed at equal contact angles, pure rolling [rad/s].

    ω_c = ½ [ω_i (1 − γ) + ω_o (1 + γ)],  γ = D cos α / dm  (Harris 2001 eq 8.20;
    thrust (γ = 0): ω_c = ω/2, seed 000 eq 2).

    >>> round(float(cage_speed(100.0, 0.0, 0.2)), 6)
    40.0
    """
    return 0.5 * (np.asarray(omega_i) * (1.0 - gamma) + np.asarray(omega_o) * (1.0 + gamma))


def entrainment_speed(omega_i, omega_o, D, dm, alpha):
    r"""Entrainment (mean rolling) speed at equal contact angles [m/s].

    u = (dm/4)(1 − γ²)|ω_i − ω_o|, γ = D cos α / dm (Harris 2001 ch. 8; PHYSICS.md §4).
    It is the same at both contacts and equals seed 004 eq 11 with the
    contact radius dm/2 − (D/2) cos α in place of dm/2 − D/2 (identical at α = 0).
    Thrust bearing (α = 90°): u = ω dm / 4 = π n dm / 120 (seed 000 eq 17).

    >>> round(float(entrainment_speed(2 * np.pi * 100 / 60, 0.0, 7.938e-3, 36e-3, np.pi / 2)), 6)
    0.094248
    """
    g = D * np.cos(alpha) / dm
    return 0.25 * dm * (1.0 - g * g) * np.abs(np.asarray(omega_i) - np.asarray(omega_o))


def ball_kinematics(omega_i, omega_o, alpha_i, alpha_o, D, dm, control: str = "outer",
                    beta=None) -> BallKinematics:
    r"""Cage, ball and contact speeds for given ring speeds and contact angles.

    Parameters
    ----------
    omega_i, omega_o : array_like   inner / outer ring speed [rad/s]
    alpha_i, alpha_o : array_like   inner / outer contact angle [rad]
    D, dm : float                   ball and pitch diameter [m]
    control : str                   ``"outer"``, ``"inner"`` or ``"radial"`` (see module docstring)
    beta : array_like, optional     impose the pitch angle β [rad] instead

    Returns
    -------
    BallKinematics

    Notes
    -----
    Jones (1959); Harris (2001) eqs 8.30–8.40 rewritten as the cage-frame no-slip
    conditions of the module docstring (re-derived in PHYSICS.md §4, whose β is the
    negative of Harris's).  With α_i = α_o = β = α the results reduce exactly to
    ω_c = ω_i (1 − γ)/2 and ω_R = −(dm/2D)(1 − γ²) ω_i.

    Examples
    --------
    Seed 000 thrust bearing at 100 rpm (Table 1: ω_b 23.74, ω_c 5.23 rad/s):

    >>> k = ball_kinematics(100 * np.pi / 30, 0.0, np.pi / 2, np.pi / 2, 7.938e-3, 36e-3, control="radial")
    >>> round(float(abs(k.omega_R)), 2), round(float(k.omega_c), 2), round(float(abs(k.spin_i)), 2)
    (23.75, 5.24, 5.24)
    """
    if control not in CONTROLS:
        raise InputError("control", control, f"must be one of {', '.join(CONTROLS)}")
    wi, wo = np.asarray(omega_i, dtype=float), np.asarray(omega_o, dtype=float)
    ai, ao = np.asarray(alpha_i, dtype=float), np.asarray(alpha_o, dtype=float)
    gp = D / dm
    beta_given = beta
    if beta is None:
        if control == "outer":
            beta = -np.arctan2(np.sin(ao), np.cos(ao) + gp)
        elif control == "inner":
            beta = -np.arctan2(np.sin(ai), np.cos(ai) - gp)
        else:
            beta = np.full(np.broadcast(ai, ao).shape, -np.pi / 2)
    beta = np.asarray(beta, dtype=float)
    # linear system  [ co   , (D/2) cos(ao+β) ] [ω_c]   [ co ω_o ]       co = (dm/2)(1 + γ' cos ao)
    #                [ -ci  , (D/2) cos(ai+β) ] [ω_R] = [ -ci ω_i ]      ci = (dm/2)(1 − γ' cos ai)
    co = 0.5 * dm * (1.0 + gp * np.cos(ao))
    ci = 0.5 * dm * (1.0 - gp * np.cos(ai))
    eo = 0.5 * D * np.cos(ao + beta)
    ei = 0.5 * D * np.cos(ai + beta)
    det = co * ei + ci * eo
    if np.any(np.abs(det) < 1e-9 * dm * D):
        raise InputError("control" if beta_given is None else "beta", control if beta_given is None else beta,
                         "the ball axis is normal to both contacts (e.g. 'radial' control at a contact angle "
                         "near 0): no rolling solution; use 'outer' or 'inner'")
    omega_c = (co * wo * ei + ci * wi * eo) / det
    omega_R = co * ci * (wo - wi) / det
    u_o = np.abs((wo - omega_c) * co)
    u_i = np.abs((wi - omega_c) * ci)
    spin_o = omega_R * np.sin(ao + beta) - (wo - omega_c) * np.sin(ao)
    spin_i = omega_R * np.sin(ai + beta) - (wi - omega_c) * np.sin(ai)
    roll_o = omega_R * np.cos(ao + beta)
    roll_i = omega_R * np.cos(ai + beta)
    with np.errstate(divide="ignore", invalid="ignore"):
        sr_o = np.where(roll_o != 0, spin_o / np.where(roll_o != 0, roll_o, 1.0), 0.0)
        sr_i = np.where(roll_i != 0, spin_i / np.where(roll_i != 0, roll_i, 1.0), 0.0)
    f = _f
    return BallKinematics(omega_c=f(omega_c), omega_R=f(omega_R), beta=f(beta), u_i=f(u_i), u_o=f(u_o),
                          spin_i=f(spin_i), spin_o=f(spin_o), spin_roll_i=f(sr_i), spin_roll_o=f(sr_o))

