"""One operating point's thermal model: its family, network, loss source and coupling
(:func:`point_model`), and the heat sources of :func:`thermobear.thermal.solve_transient` on it
(:func:`heat_sources`) — the pieces of a heat-up (:func:`thermobear.coupled.transient.transient`)
and the what-if studies on one point."""
from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from thermobear.coupled.newton import _C0, _slopes
from thermobear.coupled.pipeline import Family, family_contacts, family_loads
from thermobear.coupled.sources import Coupling, family_network, loss_parts, loss_sources, prepared_for
from thermobear.coupled.steady import _batched
from thermobear.errors import ExtrapolationWarning
from thermobear.models import plan
from thermobear.scene import Scene

__all__ = ["PointModel", "point_model", "heat_sources"]


@dataclass(frozen=True)
class PointModel:
    """Everything the thermal solution of one operating point needs: its family (one point), the
    network at that point, the loss source and the coupling of losses and nodes."""

    family: Family
    network: object
    source: object
    coupling: Coupling


def point_model(scene: Scene, models: dict | None = None, *, T_film_C=None, load=None, template=None,
                prepared=None, dry=None) -> PointModel:
    """Loads, contacts, network and loss source of one operating point.

    ``models`` default :func:`~thermobear.models.choose_models`; ``T_film_C`` [°C] the film
    temperature of the film load model; ``load`` loads to use instead of the model's; ``template`` a
    network template instead of the scene's (what-if studies); ``prepared`` the :func:`prepare` of its
    family; ``dry`` the dry load distribution its model choice solved (:class:`~thermobear.models.DryRow`)."""
    if models is None:
        models, dry = plan(scene)
    fam = Family(scenes=(scene,), index=(0,), models=models, dry=(dry,))
    if load is None:
        load = family_loads(fam, None if T_film_C is None else [T_film_C])
    cs = family_contacts(fam, _batched(load))
    if template is not None:
        cp = Coupling.of(template, parts=loss_parts(models))
    else:
        pre = prepared_for(scene, prepared)
        template, cp = pre.template, pre.coupling
    return PointModel(family=fam, network=family_network(fam, template, cs), source=loss_sources(fam, cs), coupling=cp)


def heat_sources(pm: PointModel):
    """``sources(t, T_K)`` of :func:`thermobear.thermal.solve_transient` for a point model: the node
    sources of the losses at the node temperatures, and (with a leading time axis, the output pass)
    the report P_W and P_<loss family> [W]; its ``jacobian(t, T_K)``, ∂P/∂T of the free nodes, completes the
    integrator's Jacobian with the losses' feedback (viscosity falls as the contacts warm)."""
    net, src, cp = pm.network, pm.source, pm.coupling
    free = ~net.fixed

    def sources(t, T_K):
        x = T_K[..., free] @ cp.C.T - _C0
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ExtrapolationWarning)
            if np.ndim(t):                          # the output pass: parts and report of one evaluation
                r = src.result(x)
                parts, rep = src.parts_of(r, x.shape[:-1]), _report(r, x.shape[:-1])
            else:
                parts, rep = src.parts(x), {}
        P = np.zeros(T_K.shape)
        P[..., free] = parts @ cp.S.T
        return P, rep

    def jacobian(t, T_K):
        """∂P/∂T of the free nodes (B, n_free, n_free) [W/K] at node temperatures (B, n) [K]: S ∂P/∂x C, the
        loss parts' slopes by forward differences in one stacked evaluation (as the steady Newton's)."""
        x = T_K[..., free] @ cp.C.T - _C0
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ExtrapolationWarning)
            _, dP = _slopes(src, cp, x)
        return cp.S @ dP @ cp.C

    sources.jacobian = jacobian
    return sources


def _report(r, shape):
    """P_W and P_<loss family> [W] (``shape``) of a loss result."""
    return {"P_W": np.broadcast_to(np.asarray(r.P_W, float), shape),
            **{f"P_{n}": np.broadcast_to(np.asarray(v, float), shape) for n, v in r.breakdown_W.items()}}
