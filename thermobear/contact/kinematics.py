r"""Ball kinematics: cage and ball speeds, entrainment (rolling) speed, spin.

Rigid-body rolling without slip at the two contact centres (Jones 1959; Harris
2001 ch. 8).  Work in the cage frame: x̂ bearing axis, r̂ radial
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

β (here β = −β_Harris: Harris's sign convention reversed): ``control="outer"`` (Jones
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

from thermobear.arrays import finite_range
from thermobear.arrays import out as _f

from thermobear.errors import InputError

__all__ = ["BallKinematics", "ball_kinematics", "caged_ball_kinematics", "common_cage_speed", "free_orbital_speed",
           "cage_speed", "entrainment_speed", "CONTROLS"]

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

    u = (dm/4)(1 − γ²)|ω_i − ω_o|, γ = D cos α / dm (Harris 2001 ch. 8).
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
    conditions of the module docstring (re-derived from the no-slip conditions; the β here is
    the negative of Harris's).  With α_i = α_o = β = α the results reduce exactly to
    ω_c = ω_i (1 − γ)/2 and ω_R = −(dm/2D)(1 − γ²) ω_i.

    Examples
    --------
    Seed 000 thrust bearing at 100 rpm (Table 1: ω_b 23.74, ω_c 5.23 rad/s):

    >>> k = ball_kinematics(100 * np.pi / 30, 0.0, np.pi / 2, np.pi / 2, 7.938e-3, 36e-3, control="radial")
    >>> round(float(abs(k.omega_R)), 2), round(float(k.omega_c), 2), round(float(abs(k.spin_i)), 2)
    (23.75, 5.24, 5.24)
    """
    _check_control(control)
    wi, wo, ai, ao, D, dm = _inputs(omega_i, omega_o, alpha_i, alpha_o, D, dm)
    if beta is not None and not np.all(np.isfinite(np.asarray(beta, dtype=float))):
        raise InputError("beta", beta, "the imposed pitch angle must be finite [rad]")
    omega_c, omega_R, beta, co, ci = _cage_spin(wi, wo, ai, ao, D, dm, control, beta)
    return _speeds(wi, wo, ai, ao, beta, omega_c, omega_R, co, ci)


def _inputs(omega_i, omega_o, alpha_i, alpha_o, D, dm) -> tuple:
    """The ring speeds and contact angles as float arrays (finite, broadcasting together), D and dm as floats
    (0 < D < dm); else an InputError naming the argument."""
    arrs = []
    for name, v, unit in (("omega_i", omega_i, "rad/s"), ("omega_o", omega_o, "rad/s"), ("alpha_i", alpha_i, "rad"),
                          ("alpha_o", alpha_o, "rad")):
        a = np.asarray(v, dtype=float)
        if a.size and finite_range(a) is None:
            raise InputError(name, v, f"must be finite [{unit}]")
        arrs.append(a)
    try:
        np.broadcast_shapes(*(a.shape for a in arrs))
    except ValueError:
        raise InputError("omega_i, omega_o, alpha_i, alpha_o", [a.shape for a in arrs],
                         "must broadcast together (numpy rules)") from None
    D, dm = (float(np.asarray(v, dtype=float)) for v in (D, dm))
    if not (np.isfinite(dm) and dm > 0.0):
        raise InputError("dm", dm, "the pitch diameter must be finite and > 0 [m]")
    if not (np.isfinite(D) and 0.0 < D < dm):
        raise InputError("D", D, f"the ball diameter must lie in (0, dm = {dm:g}) [m]")
    return (*arrs, D, dm)


def free_orbital_speed(omega_i, omega_o, alpha_i, alpha_o, D, dm, control: str = "outer", *, check: bool = True):
    """No-slip orbital speed of each ball [rad/s]: ``ball_kinematics(...).omega_c`` without the contact
    speeds (the input of :func:`common_cage_speed`); ``check`` False: the inputs are a solved bearing's, already
    checked (the loss evaluation's hot path).

    >>> bool(np.isclose(free_orbital_speed(300.0, 0.0, 0.7, 0.7, 0.0127, 0.07),
    ...                 ball_kinematics(300.0, 0.0, 0.7, 0.7, 0.0127, 0.07).omega_c))
    True
    """
    _check_control(control)
    if check:
        wi, wo, ai, ao, D, dm = _inputs(omega_i, omega_o, alpha_i, alpha_o, D, dm)
    else:
        wi, wo, ai, ao = (np.asarray(v, dtype=float) for v in (omega_i, omega_o, alpha_i, alpha_o))
    return _cage_spin(wi, wo, ai, ao, D, dm, control)[0]


def _speeds(wi, wo, ai, ao, beta, omega_c, omega_R, co, ci) -> BallKinematics:
    """Entrainment, spin and spin-to-roll at both contacts from the cage speed ω_c and ball speed
    ω_R [rad/s] (module docstring; c_o, c_i the contact radii [m])."""
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



def common_cage_speed(omega_c, Q):
    r"""Speed of a rigid cage carrying balls whose free rolling speeds differ [rad/s].

    ω_cage = Σ Q_j ω_c,j / Σ Q_j over the balls (last axis), the load-weighted mean of the
    balls' no-slip orbital speeds: the loaded balls drive the cage, a ball with no load
    follows it.  All weights zero → plain mean.  In a symmetric load case all ω_c,j are
    equal and ω_cage is that value.

    Parameters
    ----------
    omega_c : array_like (..., Z)   no-slip orbital speed of each ball [rad/s]
    Q : array_like (..., Z)         driving contact load of each ball [N]

    Returns
    -------
    ndarray (...)                   cage speed [rad/s]

    >>> float(common_cage_speed([100.0, 110.0, 300.0], [10.0, 10.0, 0.0]))
    105.0
    """
    w, q = np.asarray(omega_c, float), np.asarray(Q, float)
    qs = q.sum(-1)
    return np.where(qs > 0, (q * w).sum(-1) / np.where(qs > 0, qs, 1.0), w.mean(-1))


def caged_ball_kinematics(omega_i, omega_o, alpha_i, alpha_o, D, dm, omega_cage, Q_i, Q_o,
                          control: str = "outer") -> BallKinematics:
    r"""Ball kinematics with the orbital speed imposed by a common cage [rad/s, m/s].

    When the contact angles differ from ball to ball (combined or high-speed loads), the
    no-slip orbital speeds of :func:`ball_kinematics` differ too; a rigid cage makes every
    ball orbit at one speed ω_cage (:func:`common_cage_speed`).  With ω_c = ω_cage imposed,
    the two no-slip conditions of the module docstring cannot both hold; the ball speed ω_R
    is the load-weighted least-squares solution of the two,

        ω_R = [Q_o e_o c_o (ω_o − ω_c) − Q_i e_i c_i (ω_i − ω_c)] / (Q_o e_o² + Q_i e_i²),

    c_o = (dm/2)(1 + γ' cos α_o), c_i = (dm/2)(1 − γ' cos α_i), e = (D/2) cos(α + β), so a
    ball rolls without slip on the race that carries it (Q_i = 0: the outer race) and a ball
    whose own no-slip orbital speed equals ω_cage gets exactly :func:`ball_kinematics`'
    result.  Entrainment speeds follow from ω_c alone: u_o = |ω_o − ω_c| c_o, u_i = |ω_i − ω_c| c_i.
    This keeps balls outside the load zone — whose inner "contact angle" is the geometry of
    a gap, not of a contact — from orbiting at the speed that angle would imply.

    Parameters
    ----------
    omega_i, omega_o : array_like   ring speeds [rad/s]
    alpha_i, alpha_o : array_like   contact angles [rad] (per ball)
    D, dm : float                   ball and pitch diameter [m]
    omega_cage : array_like         cage speed, broadcast against the balls [rad/s]
    Q_i, Q_o : array_like           contact loads [N] (weights of the two no-slip conditions)
    control : str                   ball-axis hypothesis for β (as :func:`ball_kinematics`)

    Returns
    -------
    BallKinematics

    Examples
    --------
    Equal angles: the cage speed is every ball's own, and the result is Jones' (Harris 2001 ch. 8).

    >>> k0 = ball_kinematics(300.0, 0.0, 0.7, 0.7, 0.0127, 0.07)
    >>> k = caged_ball_kinematics(300.0, 0.0, 0.7, 0.7, 0.0127, 0.07, k0.omega_c, 50.0, 60.0)
    >>> bool(np.isclose(k.omega_R, k0.omega_R) and np.isclose(k.u_i, k0.u_i))
    True
    """
    _check_control(control)
    wi, wo = np.asarray(omega_i, float), np.asarray(omega_o, float)
    ai, ao = np.asarray(alpha_i, float), np.asarray(alpha_o, float)
    w_free, wR_free, beta, co, ci = _cage_spin(wi, wo, ai, ao, D, dm, control)
    wc = np.broadcast_to(np.asarray(omega_cage, float), np.broadcast(ai, ao, wi, wo).shape)
    eo = 0.5 * D * np.cos(ao + beta)
    ei = 0.5 * D * np.cos(ai + beta)
    qi, qo = np.asarray(Q_i, float), np.asarray(Q_o, float)
    den = qo * eo * eo + qi * ei * ei
    num = qo * eo * co * (wo - wc) - qi * ei * ci * (wi - wc)
    omega_R = np.where(den > 0, num / np.where(den > 0, den, 1.0), wR_free)
    return _speeds(wi, wo, ai, ao, beta, wc, omega_R, co, ci)


def _check_control(control):
    """Raise InputError unless ``control`` names a raceway-control hypothesis (:data:`CONTROLS`)."""
    if control not in CONTROLS:
        raise InputError("control", control, f"must be one of {', '.join(CONTROLS)}")


def _cage_spin(wi, wo, ai, ao, D, dm, control, beta=None):
    """Cage speed ω_c, ball spin ω_R [rad/s], pitch β [rad] and the contact radii co, ci [m] of
    :func:`ball_kinematics` (float arrays in, no input checks: the inner loop of the high-speed
    load distribution calls it with validated arrays)."""
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
    return omega_c, omega_R, beta, co, ci
