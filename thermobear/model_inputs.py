"""Which scene inputs the chosen models read: a value set for a model that does not read it is named, not
silently ignored (the warning ``UnreadInput`` of :mod:`thermobear.coupled.limits`); uncertainty sampling and
calibration leave such inputs out (:mod:`thermobear.coupled.uncertainty`, :mod:`thermobear.app.calibration`).
The model choice itself: :mod:`thermobear.models`.
"""
from __future__ import annotations

import dataclasses
import math

from thermobear.losses.skf import K_RS
from thermobear.models import added_losses, traction_choice
from thermobear.scene import Scene

__all__ = ["unread_inputs", "unread_settings", "FRICTION_INPUTS", "SKF_CONSTANTS"]

#: scene inputs of the local model's mixed friction (seed 000 eq 18): Scene attribute → (the scene file's field,
#: scale from the attribute's unit to the field's)
FRICTION_INPUTS = {"mu_full_film": ("lubricant.mu_full_film", 1.0), "mu_boundary": ("lubricant.mu_boundary", 1.0),
                   "Rq_ball": ("lubricant.Rq_ball_um", 1e6), "Rq_ring": ("lubricant.Rq_ring_um", 1e6)}
#: the SKF model's calibrated constants (``[models]``), read by ``losses = "skf"`` only
SKF_CONSTANTS = ("skf_R1", "skf_S1", "skf_mu_EHL")
_DEFAULTS = {f.name: f.default for f in dataclasses.fields(Scene) if f.name in FRICTION_INPUTS}
_T_AMBIENT = next(f.default for f in dataclasses.fields(Scene) if f.name == "T_ambient_C")


def unread_inputs(scene: Scene) -> dict:
    """The scene inputs its chosen models do not read, whatever their value: field → why (one phrase).

    * ``lubricant.mu_full_film`` (μ_e of seed 000 eq 18): read by the constant full-film traction
      (``models.traction = "constant"``, the default of a dry film) and by a ring-guided cage's ball–pocket
      friction; not by the Eyring traction (the default wherever an oil film carries the contacts: its
      full-film μ is the oil's own traction law) nor by the SKF model.
    * ``lubricant.mu_boundary`` (μ_a): read by the local model's mixed friction where the surfaces are
      rough; not on smooth surfaces (``Rq_ball_um = Rq_ring_um = 0``: Λ = ∞, full film) nor by the SKF
      model.  (Read, it still acts only where Λ < 2.03: beyond, the film carries the whole load.)
    * ``lubricant.Rq_ball_um``, ``Rq_ring_um``: not read by the SKF model.
    * ``models.skf_R1``, ``skf_S1``, ``skf_mu_EHL``: read by the SKF model only (``models.losses = "skf"``).
    * ``lubricant.flow_L_h``, ``T_in_C``: not under grease or a dry film; ``T_in_C`` not without a flow; at a
      prescribed temperature (``operation.T_C``: no network) neither ``T_in_C`` nor ``thermal.T_ambient_C`` (named
      when away from its default 20 °C), nor a bath's flow (a jet's still sets the drag's oil fraction).
    * ``lubricant.K_rs``: read by the starvation factor Φ_rs (:func:`~thermobear.models.replenishment_constant`):
      by both loss models unless ``models.starvation = false`` (then Φ_rs = 1 in the SKF model too), a dry film, or
      (local model) a bearing without bore and outside diameter.

    >>> import thermobear as tb
    >>> s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    >>> sorted(unread_inputs(s)), "lubricant.mu_full_film" in unread_inputs(s.with_(models={"traction": "constant"}))
    (['lubricant.mu_full_film', 'models.skf_R1', 'models.skf_S1', 'models.skf_mu_EHL'], False)
    """
    if scene.models.get("losses") == "skf":
        why = ('models.losses = "skf": the SKF 2004 model has its own friction coefficients (μ_bl 0.15, μ_EHL: '
               'models.skf_mu_EHL) and no roughness')
        return {**{field: why for field, _ in FRICTION_INPUTS.values()}, **_supply_unread(scene), **_fits_unread(scene),
                **_K_rs_unread(scene, skf=True)}
    why = 'read by the SKF model only (models.losses = "skf"); this scene runs the local model'
    out = {**{f"models.{k}": why for k in SKF_CONSTANTS}, **_supply_unread(scene), **_fits_unread(scene)}
    traction, reason = traction_choice(scene)
    if traction != "constant" and not added_losses(scene)["cage"][0]:
        out["lubricant.mu_full_film"] = (f'models.traction = "{traction}" ({reason.partition(":")[0]}) takes the '
                                         "full-film friction from the oil's traction law; mu_full_film is read with "
                                         "models.traction = \"constant\" or by a ring-guided cage's pocket friction")
    if not scene.Rq_ball and not scene.Rq_ring:
        out["lubricant.mu_boundary"] = ("smooth surfaces (Rq_ball_um = Rq_ring_um = 0): Λ = ∞, the full-film "
                                        "friction alone")
    return {**out, **_K_rs_unread(scene, skf=False)}


def _K_rs_unread(scene: Scene, skf: bool) -> dict:
    """``lubricant.K_rs`` where no replenishment factor is applied: starvation off (both models), or — the local
    model's — a supply without one or a bearing without bore and outside diameter."""
    b = scene.bearing
    if not scene.models.get("starvation", True):
        return {"lubricant.K_rs": "models.starvation = false: no replenishment factor on the rolling force"
                                  + (" (Φ_rs = 1 in the SKF model too)" if skf else "")}
    if not skf and (scene.supply not in K_RS or b.bore is None or b.outer_diameter is None):
        return {"lubricant.K_rs": f"no replenishment factor (supply {scene.supply!r}, or the bearing's bore and outside "
                                  "diameter unknown)"}
    return {}


def _fits_unread(scene: Scene) -> dict:
    """A thrust bearing's seat fits: no radial clearance for them to change (its axial play is the mounting's)."""
    if scene.bearing.kind != "thrust":
        return {}
    why = "a thrust bearing has no radial clearance for the fits to change (its axial play is set by the mounting)"
    return {"bearing.shaft_fit": why, "bearing.housing_fit": why}


def _supply_unread(scene: Scene) -> dict:
    """The oil supply's inputs a supply without an oil flow does not read: ``lubricant.flow_L_h`` and ``T_in_C``
    under grease or a dry film; ``T_in_C`` where no oil flows (``flow_L_h`` = 0: a bath that does not circulate)."""
    if scene.supply in ("grease", "dry_film"):
        why = f"supply {scene.supply!r}: no oil flows through the bearing"
        return {"lubricant.flow_L_h": why, "lubricant.T_in_C": why}
    if scene.T_C is not None:          # no network: the inlet and the room have nothing to heat; a bath's flow neither
        why = f"operation.T_C = {scene.T_C:g} °C prescribes the temperatures (no thermal network)"
        return {"lubricant.T_in_C": why, "thermal.T_ambient_C": why} | (
            {"lubricant.flow_L_h": why} if scene.supply == "oil_bath" else {})
    if not scene.oil_flow > 0:
        return {"lubricant.T_in_C": "no oil flows in (lubricant.flow_L_h = 0): the inlet temperature has nothing to carry"}
    return {}


def unread_settings(scene: Scene) -> list:
    """``[(field, value, why)]``: the inputs of :func:`unread_inputs` the scene sets — a friction input away from
    its default, an SKF constant given at all — each in its file's unit (no model choice for a scene that sets
    none of them)."""
    if not (any(not math.isclose(getattr(scene, a), d, rel_tol=1e-9) for a, d in _DEFAULTS.items())
            or any(k in scene.models for k in SKF_CONSTANTS) or scene.K_rs is not None
            or (scene.T_oil_in_C is not None or scene.oil_flow > 0) and scene.supply in ("grease", "dry_film")
            or scene.T_oil_in_C is not None and not scene.oil_flow > 0
            or scene.T_C is not None and (scene.T_oil_in_C is not None or scene.T_ambient_C != _T_AMBIENT
                                          or scene.oil_flow > 0)
            or scene.bearing.kind == "thrust" and (scene.shaft_fit or scene.housing_fit)):
        return []
    unread = unread_inputs(scene)
    out = []
    for attr, (fld, scale) in FRICTION_INPUTS.items():
        v = getattr(scene, attr)
        if fld in unread and not math.isclose(v, _DEFAULTS[attr], rel_tol=1e-9):
            out.append((fld, v * scale, unread[fld]))
    for k in SKF_CONSTANTS:
        if f"models.{k}" in unread and scene.models.get(k) is not None:
            out.append((f"models.{k}", scene.models[k], unread[f"models.{k}"]))
    for fld, v in (("lubricant.K_rs", scene.K_rs), ("lubricant.T_in_C", scene.T_oil_in_C),
                   ("lubricant.flow_L_h", round(scene.oil_flow * 3.6e6, 9) or None),
                   ("thermal.T_ambient_C", None if scene.T_ambient_C == _T_AMBIENT else scene.T_ambient_C),
                   ("bearing.shaft_fit", scene.shaft_fit), ("bearing.housing_fit", scene.housing_fit)):
        if fld in unread and v is not None:
            out.append((fld, v, unread[fld]))
    return out
