r"""Cage losses: hydrodynamic friction of a ring-guided cage on its land, and ball–pocket sliding.

A cage centred on a ring land runs on a thin oil film between its bore (or rim) and the land; the
concentric limit of the short journal bearing that Harris & Kotzalas use for the cage land [2]_ is
Petroff's law [1]_:

.. math::

    T_{land} = \frac{\pi\, \eta\, \omega_{rel}\, b\, d_l^3}{4\, c},\qquad P_{land} = T_{land}\, \omega_{rel}

(land diameter d_l, axial land width b, radial land clearance c, ω_rel the speed of the cage
relative to its guiding ring).  The balls drive the cage against that torque: in equilibrium the
pocket forces Q_c satisfy Σ_j Q_c,j d_m/2 = T_land (the cage equilibrium of the quasi-dynamic
ball-bearing analysis [2]_), taken equal for the Z balls, and each ball's surface slides in its
pocket at its spin speed about its own axis, ω_R D/2:

.. math::

    P_{pocket} = \mu_c \sum_j Q_{c,j}\, \frac{D}{2}\, |\omega_{R,j}|,\qquad Q_{c,j} = \frac{2\,T_{land}}{Z\, d_m}

A ball-centred cage (pressed steel, polyamide window cages: SKF suffixes J, P, Y, M [3]_) has no
land: in this model its pocket forces only balance the cage's own windage, which is not modelled,
so its loss is taken as zero.

References
----------
.. [1] Petroff, N. P., 1883, "Friction in machines and the effect of the lubricant", Inzhenernii
   Zhurnal, St. Petersburg (the concentric journal bearing).
.. [2] Harris, T. A., Kotzalas, M. N., 2007, Advanced Concepts of Bearing Technology (Rolling Bearing
   Analysis, 5th ed.), CRC Press: cage–land hydrodynamic force (short journal bearing) and the cage
   equilibrium under the ball–pocket forces of the high-speed ball-bearing analysis.
.. [3] SKF Rolling bearings 17000 EN (2018), cage designations (J, Y pressed steel/brass; P, TN9
   polyamide; M machined brass: ball centred; MA, MB: outer / inner ring centred).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermobear.errors import InputError

__all__ = ["GUIDANCE", "CageLand", "CageLoss", "cage_land_torque_petroff", "pocket_force", "pocket_sliding_power", "cage_loss",
           "cage_land_estimate"]

#: How a cage is centred: on the balls (no land), on an inner-ring or an outer-ring land.
GUIDANCE = ("balls", "inner_ring", "outer_ring")


def _nonneg(name, x):
    a = np.asarray(x, dtype=float)
    if a.size and not (a.min() >= 0 and a.max() < np.inf):
        raise InputError(name, x, "must be finite and >= 0")
    return a


def _positive(name, x):
    a = np.asarray(x, dtype=float)
    if a.size and not (a.min() > 0 and a.max() < np.inf):
        raise InputError(name, x, "must be finite and > 0")
    return a


def _out(x):
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x


def cage_land_torque_petroff(eta, d_land, b_land, c_land, omega_rel):
    r"""Viscous torque of a cage on its guiding land, Petroff's concentric journal [N m].

    Parameters
    ----------
    eta : array_like        dynamic viscosity of the oil in the land gap [Pa s]
    d_land : float          land diameter [m]
    b_land : float          axial width of the guiding land(s), summed [m]
    c_land : float          radial clearance between cage and land [m]
    omega_rel : array_like  speed of the cage relative to the guiding ring [rad/s]

    Returns
    -------
    ndarray   torque [N m] (its power is T |ω_rel|)

    Notes
    -----
    .. math:: T = \frac{\pi\, \eta\, |\omega_{rel}|\, b\, d_l^3}{4\, c}

    (Petroff 1883 [1]_: shear stress η ω r/c on the land surface π d_l b at radius d_l/2; the concentric
    limit of the cage-land short bearing [2]_).  Laminar, flooded land; → 0 as ω_rel → 0.

    Examples
    --------
    Outer-ring land of a 6208 (d_l 68 mm, b 4.5 mm, c 0.34 mm), ISO VG 68 oil at 60 °C (η 0.024 Pa s),
    cage at 130 rad/s:

    >>> round(float(cage_land_torque_petroff(0.024, 68e-3, 4.5e-3, 0.34e-3, 130.0)), 5)
    0.0102
    """
    e = _positive("eta", eta)
    w = np.abs(np.asarray(omega_rel, dtype=float))
    for name, v in (("d_land", d_land), ("b_land", b_land), ("c_land", c_land)):
        _positive(name, v)
    return _out(np.pi * e * w * b_land * d_land ** 3 / (4.0 * c_land))


def pocket_force(T_cage, Z, dm):
    r"""Ball–pocket normal force that drives a cage against a torque T, shared by the Z balls [N].

    .. math:: Q_c = \frac{2\, T}{Z\, d_m}

    (cage equilibrium Σ_j Q_c,j d_m/2 = T [2]_, equal shares).

    >>> pocket_force(0.01, 9, 0.06)
    0.037037037037037035
    """
    if int(Z) != Z or Z < 1:
        raise InputError("Z", Z, "number of balls must be an integer >= 1")
    _positive("dm", dm)
    return _out(2.0 * _nonneg("T_cage", T_cage) / (Z * dm))


def pocket_sliding_power(mu, Q_c, D, omega_ball):
    r"""Sliding power of the balls in their cage pockets [W].

    Parameters
    ----------
    mu : array_like          friction coefficient of the pocket contact [-]
    Q_c : array_like         pocket normal force per ball [N] (operating points)
    D : float                ball diameter [m]
    omega_ball : array_like  each ball's spin speed about its own axis, relative to the cage [rad/s]
                             (operating points + (Z,))

    Notes
    -----
    .. math:: P = \mu \sum_j Q_{c,j}\, \frac{D}{2}\, |\omega_{R,j}|

    The pocket contact lies on the ball's equator with respect to its spin axis (which lies in the
    radial–axial plane), so its surface slides past the pocket at ω_R D/2.

    >>> round(float(pocket_sliding_power(0.05, 0.037, 11.9e-3, [800.0] * 9)), 5)
    0.0792
    """
    w = np.abs(np.asarray(omega_ball, dtype=float))
    Q = _nonneg("Q_c", Q_c)
    return _out(np.asarray(mu, dtype=float) * Q * 0.5 * D * w.sum(axis=-1))


@dataclass(frozen=True)
class CageLand:
    """A ring-guided cage as the loss model needs it: land diameter ``d_land``, summed land width
    ``b_land`` and radial clearance ``c_land`` [m], the pocket friction coefficient ``mu_pocket`` [-]
    and whether the guiding ring is the rotating one (``guide_rotates``)."""

    d_land: float
    b_land: float
    c_land: float
    mu_pocket: float
    guide_rotates: bool


@dataclass(frozen=True)
class CageLoss:
    """Cage loss (arrays over operating points): P_W [W] total, P_land_W and P_pocket_W [W], T_land_Nm
    [N m] land torque, Q_pocket_N [N] pocket force per ball."""

    P_W: object
    P_land_W: object
    P_pocket_W: object
    T_land_Nm: object
    Q_pocket_N: object


def cage_loss(eta, Z, D, dm, omega_rel, omega_ball, mu_pocket, d_land, b_land, c_land) -> CageLoss:
    r"""Loss of a ring-guided cage: land friction plus ball–pocket sliding [W].

    Parameters
    ----------
    eta : array_like         oil viscosity in the land gap [Pa s] (operating points)
    Z : int                  number of balls
    D, dm : float            ball and pitch diameter [m]
    omega_rel : array_like   cage speed relative to the guiding ring [rad/s] (operating points)
    omega_ball : array_like  ball spin speeds about their axes [rad/s] (operating points + (Z,))
    mu_pocket : float        pocket friction coefficient [-]
    d_land, b_land, c_land : float  land diameter, width and radial clearance [m]

    Returns
    -------
    CageLoss

    Notes
    -----
    T = π η |ω_rel| b d_l³/(4c) (:func:`cage_land_torque_petroff`), P_land = T |ω_rel|,
    Q_c = 2T/(Z dm) (:func:`pocket_force`), P_pocket = μ Σ Q_c (D/2)|ω_R| (:func:`pocket_sliding_power`).
    Both vanish at standstill (P_land ∝ ω², P_pocket ∝ ω²).

    Examples
    --------
    >>> r = cage_loss(0.024, 9, 11.9e-3, 60e-3, 130.0, [800.0] * 9, 0.05, 68e-3, 4.5e-3, 0.34e-3)
    >>> round(float(r.P_land_W), 3), round(float(r.P_pocket_W), 5)
    (1.33, 0.0809)
    """
    T = cage_land_torque_petroff(eta, d_land, b_land, c_land, omega_rel)
    P_land = np.asarray(T) * np.abs(np.asarray(omega_rel, dtype=float))
    Q = pocket_force(T, Z, dm)
    P_pocket = pocket_sliding_power(mu_pocket, Q, D, omega_ball)
    return CageLoss(P_W=_out(P_land + P_pocket), P_land_W=_out(P_land), P_pocket_W=_out(P_pocket), T_land_Nm=T,
                    Q_pocket_N=Q)


def cage_land_estimate(guidance: str, d_mm: float, D_mm: float, width_mm: float) -> dict:
    r"""Estimated land diameter, width and clearance of a ring-guided cage [m] (no drawing at hand).

    * land diameter: the ring shoulder, d + 0.3 (D − d) (inner) or D − 0.3 (D − d) (outer): the inner-ring
      shoulder of SKF's 6208 is d1 = 52.6 mm = d + 0.32 (D − d) (SKF product table); outer symmetric;
    * land width: two lands of B/8 each (B the bearing width), 0.25 B in all;
    * radial clearance: 0.5 % of the land diameter.

    All three are estimates (flagged as such by the scene): give ``bearing.cage_land_width_mm`` and
    ``bearing.cage_land_clearance_mm`` from the drawing where known.

    >>> e = cage_land_estimate("outer_ring", 40.0, 80.0, 18.0)
    >>> round(e["d_land"] * 1e3, 1), round(e["b_land"] * 1e3, 2), round(e["c_land"] * 1e3, 3)
    (68.0, 4.5, 0.34)
    """
    if guidance not in GUIDANCE[1:]:
        raise InputError("bearing.cage", guidance, "a ring-guided cage ('inner_ring' or 'outer_ring') has a land")
    d_l = (d_mm + 0.3 * (D_mm - d_mm)) if guidance == "inner_ring" else (D_mm - 0.3 * (D_mm - d_mm))
    return {"d_land": d_l * 1e-3, "b_land": 0.25 * width_mm * 1e-3, "c_land": 0.005 * d_l * 1e-3}
