r"""The terms of :func:`thermobear.losses.local.evaluate_losses` around the contacts' films and
friction: the temperatures stacked per raceway and oil–air mixture, the lubricant's properties at them
(one float at a time for a few, values per operating point broadcast), the drag of the balls in the
mixture, the inlet-heating and replenishment factors of the films, and churning, seal and cage powers.
Each composes the public physics functions of its family (drag, seals, cage, thermal_film, skf).
"""
from __future__ import annotations

import numpy as np

from thermobear.errors import InputError
from thermobear.losses.cage import cage_loss
from thermobear.losses.drag import cavity_oil_fraction, churning_loss, drag_loss, immersed_fraction
from thermobear.losses.skf import K_RS, phi_rs
from thermobear.lubrication.thermal_film import (thermal_inlet_viscosity, thermal_loading_parameter,
                                                 thermal_reduction_gupta)
from thermobear.units import ZERO_C_K

__all__ = ["temperature_stack", "property_at", "drag_power", "inlet_viscosity", "replenishment", "added_powers"]


# --------------------------------------------------------------------------- temperatures
def _lead(T, name, batch, Z):
    """(leading shape, per_ball) of a temperature array: ``lead + batch' (+ (Z,))`` with ``batch'``
    broadcasting to ``batch``; a trailing ball axis (Z,) right after the batch axes is per ball."""
    nb = len(batch)
    if T.ndim > nb and T.shape[T.ndim - nb - 1:] == batch + (Z,):
        return T.shape[:T.ndim - nb - 1], True
    k = max(T.ndim - nb, 0)
    tail = T.shape[k:]
    if any(t != 1 and t != b for t, b in zip(tail, batch[nb - len(tail):])):
        raise InputError(name, T, f"must broadcast to the operating points {batch} (with leading axes "
                         f"for more temperature states) or be per ball, {batch + (Z,)}")
    return T.shape[:k], False


def temperature_stack(cs, T_C, T_inner_C, T_outer_C, T_oil_C, dragged):
    """The contact temperatures of both raceways and (when ``dragged``) the oil–air mixture,
    stacked on one axis after the operating points: (*lead, *batch, 2 or 3, Z or 1) [°C]; the
    leading shape; and whether a raceway's temperature is per ball."""
    batch, Z = cs.batch, cs.brg.Z
    Ts = [T_C if v is None else v for v in (T_inner_C, T_outer_C, T_oil_C)]
    n = 3 if dragged else 2
    if all(isinstance(v, (float, int)) for v in Ts):     # one temperature each: no shapes to work out
        Tall = np.empty(batch + (n, 1))
        for k in range(n):
            Tall[..., k, :] = Ts[k]
        return Tall, (), False
    Ts = [np.asarray(v, float) for v in Ts]
    names = [n if v is not None else "T_C" for n, v in zip(("T_inner_C", "T_outer_C", "T_oil_C"),
                                                          (T_inner_C, T_outer_C, T_oil_C))]
    shapes = [_lead(v, nm, batch, Z) for v, nm in zip(Ts, names)]
    if shapes[2][1]:
        raise InputError(names[2], Ts[2], f"the oil temperature is one per operating point {batch}, not per ball")
    leads = [sh[0] for sh in shapes]
    lead = leads[0] if leads[0] == leads[1] == leads[2] else np.broadcast_shapes(*leads)
    per_ball = shapes[0][1] or shapes[1][1]
    Tall = np.empty(lead + batch + (n, Z if per_ball else 1))
    for k in range(n):
        Tall[..., k, :] = Ts[k] if shapes[k][1] else Ts[k][..., None]
    return Tall, lead, per_ball


_FEW = 8        # up to this many temperatures, properties are asked one Python float at a time


def property_at(prop, T, per_point=False):
    """``prop(T)`` on a temperature array [°C]: one Python float at a time when there are a few
    (the lubricant's and drag's formulas on floats: no array overhead), else one array call (always
    for a lubricant with values per operating point)."""
    if T.size > _FEW or per_point:
        return prop(T)
    return np.array([prop(t) for t in T.ravel().tolist()]).reshape(T.shape)


def drag_power(cs, oil, T_oil, eta_oil, supply, oil_flow_m3_s):
    """Drag power of the balls [W] at oil–air mixture temperatures ``T_oil`` [°C] (*lead, *batch),
    where the oil's viscosity is ``eta_oil`` [Pa s]:
    :func:`~thermobear.losses.drag.drag_loss` with the cavity's oil fraction
    (:func:`~thermobear.losses.drag.cavity_oil_fraction`: Parker's for oil jets and oil–air, air alone otherwise);
    0 where the bearing stands still."""
    brg, batch = cs.brg, cs.batch
    run = cs.omega_cage > 0                       # (a subnormal speed: a cage speed of 0)
    all_run = bool(run.all())
    X = cavity_oil_fraction(supply, oil_flow_m3_s, np.where(run, cs.n_rpm, 0.0), brg.dm)
    wc = cs.omega_cage if all_run else np.where(run, cs.omega_cage, 1.0)
    if T_oil.size <= _FEW and oil.points is None:  # a few states: the formulas on Python floats
        each = (np.broadcast_to(v, T_oil.shape).ravel().tolist() for v in (T_oil, eta_oil, wc, X))
        P = np.array([drag_loss(brg.Z, brg.D, brg.dm, w, x, oil.rho(t), e, t + ZERO_C_K, check=False).P_W
                      for t, e, w, x in zip(*each)]).reshape(T_oil.shape)
    else:
        P = drag_loss(brg.Z, brg.D, brg.dm, wc, X, oil.rho(T_oil), eta_oil, T_oil + ZERO_C_K, check=False).P_W
    return P if all_run else np.where(run, P, 0.0)


def inlet_viscosity(cs, oil, T2, eta2, per_point=False):
    """(Inlet viscosity lowered by inlet shear heating [Pa s], φ_T [-]): Gupta et al. (1992) φ_T at the contacts'
    thermal loading (pure rolling at the centre, u_s = 2u), read as the viscosity of the thermal film
    (:mod:`thermobear.lubrication.thermal_film`)."""
    L = thermal_loading_parameter(property_at(oil.beta_at, T2, per_point), eta2, 2.0 * cs.u,
                                  property_at(oil.k_th, T2, per_point), check=False)       # the lubricant's values
    phi = thermal_reduction_gupta(L, check=False)
    return thermal_inlet_viscosity(eta2, phi, check=False), phi


def replenishment(cs, oil, T2, supply, per_point=False, K_rs=None):
    """SKF's kinematic replenishment factor Φ_rs (:func:`~thermobear.losses.skf.phi_rs`) of the
    bearing at each contact's viscosity [-] (bore, OD in mm; K_z of the bearing kind; ``K_rs`` [-] scalar or
    per point (``cs.batch + (1, 1)``), None: SKF's of the supply)."""
    brg = cs.brg
    if cs.K_z is None or supply not in K_RS:
        raise InputError("models.starvation", True, "the replenishment factor needs the bearing's bore and outside "
                         "diameter, an SKF bearing kind and an oil or grease supply (" + ", ".join(K_RS) + ")")
    n = np.asarray(cs.n_rpm, float)[(...,) + (None,) * 2]
    K = K_RS[supply] if K_rs is None else K_rs
    return phi_rs(n, property_at(oil.nu, T2, per_point), brg.bore * 1e3, brg.outer_diameter * 1e3, cs.K_z, K)


def added_powers(cs, oil, lead, T_bath_C, T_cage_C, oil_level_m, seal_torque_Nm, cage, per_point=False):
    """Churning, seal and cage powers [W] (each (*lead, *batch)) of :func:`~thermobear.losses.local.evaluate_losses` (``oil`` with
    values per point against the batch axis last: ``per_point``)."""
    brg, shape = cs.brg, lead + cs.batch
    zero = np.zeros(shape)
    out = {"churning": zero, "seal": zero + np.asarray(seal_torque_Nm, float) * cs.omega, "cage": zero}
    if oil_level_m is not None:
        T = np.broadcast_to(np.asarray(T_bath_C, float), shape)
        w = immersed_fraction(np.broadcast_to(np.asarray(oil_level_m, float), cs.batch), brg.dm, brg.D)
        out["churning"] = zero + churning_loss(brg.Z, brg.D, brg.dm, cs.omega_cage, w, property_at(oil.rho, T, per_point),
                                               property_at(oil.eta, T, per_point)).P_W
    if cage is not None:
        T = np.broadcast_to(np.asarray(T_cage_C, float), shape)
        w_rel = (cs.omega if cage.guide_rotates else 0.0) - cs.omega_cage
        out["cage"] = zero + cage_loss(property_at(oil.eta, T, per_point), brg.Z, brg.D, brg.dm, w_rel, cs.omega_ball,
                                       cage.mu_pocket, cage.d_land, cage.b_land, cage.c_land).P_W
    return out
