r"""The least model a scene needs: which sub-model serves each step, and why.

In the spirit of pvlib's ModelChain, :func:`choose_models` infers from what a scene contains which
sub-models serve it, each with the reason, overridable from the scene's ``[models]`` table:

* **thermal** — no thermal network when the scene prescribes the temperature (``operation.T_C``);
  else the scene's network, coupled to the losses (:mod:`thermobear.coupled.steady`).
* **load_model** — the closed form when the load case is symmetric and the closed form is exact
  (pure axial load, tilt held: all balls equal, Harris 2001 eq 7.36; thrust bearing: Q = Fa/Z);
  Jones–Harris otherwise.  Centrifugal and gyroscopic terms (``high_speed``, Jones 1960,
  :mod:`thermobear.loads.highspeed`) only where :func:`~thermobear.loads.needs_high_speed` says they
  matter (F_c > 5 % of the ball load); otherwise the low-speed form, in which the centrifugal force
  still loads the outer contact (it keeps balls outside the load zone on the race).
  ``load_model = "film"``: the lubricant films in each contact's law (:mod:`thermobear.loads.film`,
  or the high-speed form with films), chosen when the dry Jones–Harris solution lifts a ball off a
  race in a flooded bearing (oil jet or oil bath; :func:`open_contacts`): the films of those balls
  carry load and a rolling loss the dry law drops (2–50 % of the power on a 7210 / 6210 grid; with
  every ball on both races at most 6 % — validation/report/film_criterion.md).  Grease and oil–air
  contacts outside the load zone are taken as starved.
* **drag** — only for jet / oil–air supply, or grease at n·d_m ≥ 1e5 mm/min (below, churning of a
  few balls in air is < 0.1 % of the contact losses).
* **rolling** — per-contact regime selection (seed 004 §4.3) unless named.
* **hertz** — exact (one ellipticity solve per contact; the approximations' errors, 1–5 %, would
  show in p_max and the film).

The dry load solution the choice needs is returned with it (:func:`plan`), so that the load step
does not solve it again: no hidden cache.
"""
from __future__ import annotations

import numpy as np

from thermobear.arrays import take
from thermobear.errors import InputError, NoEquilibrium, SolverError
from thermobear.loads import LoadDistribution, load_distribution, needs_high_speed
from thermobear.loads.highspeed import load_distribution_high_speed
from thermobear.scene import Scene

__all__ = ["choose_models", "plan", "plan_many", "open_contacts", "dry_load", "is_symmetric", "FLOODED"]

FLOODED = ("oil_jet", "oil_bath")


def is_symmetric(scene: Scene) -> bool:
    """Pure axial load, tilt held, nominal stiffness: every ball carries the same load."""
    return scene.Fr == 0.0 and scene.M is None and scene.models.get("stiffness", "nominal") == "nominal"


def _high_speed_choice(scene: Scene) -> tuple:
    """``("yes" | "no", reason)``: the high-speed ball equilibrium, by the scene's choice or F_c/Q."""
    b, m = scene.bearing, scene.models
    Qtyp = max(scene.Fa / (b.Z * max(np.sin(b.alpha0), 1e-3)), scene.Fr * 5.0 / b.Z, 1e-9)
    need, ratio = needs_high_speed(b, scene.n_rpm, Qtyp, rotating=scene.rotating)
    if "high_speed" in m:
        hs = m["high_speed"]
        if hs and b.kind == "thrust":
            raise InputError("models.high_speed", True, "the high-speed form is for radial and angular contact "
                             "bearings (a thrust bearing's centrifugal force acts across its grooves)")
        if hs and scene.rotating != "inner":
            raise InputError("models.high_speed", True, "the high-speed form is implemented for a rotating inner "
                             "ring (operation.rotating = 'inner')")
        return ("yes" if hs else "no", "chosen in the scene")
    if b.kind == "thrust":
        return ("no", "thrust bearing: centrifugal force acts across the groove; not modelled")
    if bool(need) and scene.rotating != "inner":
        return ("no", f"F_c/Q = {float(ratio):.2f} > 0.05, but the high-speed form is implemented for "
                      "a rotating inner ring: low-speed form with F_c on the outer contacts")
    if bool(need):
        return ("yes", f"F_c/Q = {float(ratio):.2f} > 0.05: Jones high-speed form (centrifugal force, "
                       "gyroscopic moment, outer-race control) shifts the contact angles")
    return ("no", f"F_c/Q = {float(ratio):.3f} <= 0.05 (F_c still loads the outer contacts "
                  "of balls outside the load zone)")


def refuse_unloaded_thrust(Fa):
    """A thrust bearing without axial load has no contact: NoEquilibrium naming operation.Fa_N."""
    raise NoEquilibrium(f"a thrust ball bearing needs an axial load (operation.Fa_N = {Fa:g} N; accepted: > 0): "
                        "without it the balls leave the washers and no contact carries or loses anything "
                        "(in service a minimum axial load keeps them rolling)", field="operation.Fa_N")


def _dry_key(scene: Scene):
    """The dry load distribution the model choice of ``scene`` needs — (bearing, Fa, Fr, M, stiffness,
    n_rpm or None) — or None when it needs none (closed form, film chosen in the scene, no choice to
    make, or an invalid scene: :func:`choose_models` will say why)."""
    m = scene.models
    if m.get("load_model") in ("closed_form", "film") or (scene.T_C is None and not scene.network):
        return None
    if m.get("losses") == "skf" and scene.supply not in FLOODED and scene.T_C is not None:
        return None         # prescribed T, SKF losses, no film test: no loads needed
    try:
        hs = _high_speed_choice(scene)[0] == "yes"
    except InputError:
        return None
    if is_symmetric(scene) and not hs and "load_model" not in m:
        return None
    return (scene.bearing, float(scene.Fa), float(scene.Fr), None if scene.M is None else float(scene.M),
            m.get("stiffness", "nominal"), float(scene.n_rpm) if hs else None)


def _solve_dry(brg, Fa, Fr, M, stiffness, n_rpm, *, continuation=True) -> LoadDistribution:
    """Dry Jones–Harris load distribution (high-speed form when ``n_rpm`` is given); arrays batch."""
    if n_rpm is None:
        return load_distribution(brg, Fa=Fa, Fr=Fr, M=M, stiffness=stiffness, continuation=continuation,
                                 refuse_overload=False)      # the contact set refuses overloads per point
    return load_distribution_high_speed(brg, Fa=Fa, Fr=Fr, M=M, n_rpm=n_rpm, stiffness=stiffness)


def dry_load(scene: Scene, high_speed: bool) -> LoadDistribution:
    """The scene's dry Jones–Harris load distribution (high-speed form when ``high_speed``)."""
    M = None if scene.M is None else float(scene.M)
    return _solve_dry(scene.bearing, float(scene.Fa), float(scene.Fr), M, scene.models.get("stiffness", "nominal"),
                      float(scene.n_rpm) if high_speed else None)


def open_contacts(scene: Scene, high_speed: bool, dry: LoadDistribution | None = None) -> int:
    r"""Number of balls with an open contact (Q = 0 at the inner or the outer race) in the dry
    Jones–Harris solution of a scene (high-speed form when ``high_speed``; ``dry``: that solution
    when the caller has it).

    The criterion of :func:`choose_models` for the film load model: in a flooded bearing a ball that
    the dry contact law lifts off a race still rolls on a film that carries load and a
    hydrodynamic rolling force nearly independent of the gap (IVR: F_R ∝ η u R_x (R_x/h)^(1/6);
    seed 004 §5.3.5, Fig. 19), which the dry law sets to zero.  On the seed 004 7210 and a 6210 the
    film law changes the power by 10–50 % with 6 or more of 15 balls lifted, 2–8 % with 5 of 10,
    about 4 % with 2 of 15, and at most 6 % (median 0.2 %) with none
    (validation/report/film_criterion.md).  The count is a physical criterion, not a threshold
    fitted to that grid.  The switch is a step: at 4800 rpm, 50 °C, Fa 450 N the power steps by
    4 % where the first ball lifts off (Fr ≈ 733 N).

    >>> import thermobear as tb
    >>> sc = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    >>> open_contacts(sc.with_(Fr=150.0), True), open_contacts(sc.with_(Fr=750.0, n_rpm=4800.0), True) > 0
    (0, True)
    """
    ld = dry if dry is not None else dry_load(scene, high_speed)
    return int(np.count_nonzero((np.asarray(ld.Q_i) <= 0.0) | (np.asarray(ld.Q_o) <= 0.0)))


def _combined_load_model(scene: Scene, high_speed: bool, dry) -> tuple:
    """Dry Jones–Harris, or the film load model when the dry solution leaves contacts open in a
    flooded bearing (see :func:`open_contacts`)."""
    jh = "combined load: balls differ (Jones–Harris, seed 004 eqs 6–8)"
    if scene.supply not in FLOODED:
        return "jones_harris", jh + f"; {scene.supply}: contacts outside the load zone taken as starved (no film load)"
    if isinstance(dry, SolverError):    # the load step itself will say so (a sweep records it for its point)
        return "jones_harris", jh + f"; the dry solution failed ({type(dry).__name__}), so no film test"
    n_open, Z = open_contacts(scene, high_speed, dry), scene.bearing.Z
    if n_open == 0:
        return "jones_harris", jh + ("; every ball on both races in the dry solution (the films would change the "
                                     "power by 0.2 % typically, at most 6 % on the validation grid)")
    return ("film", f"combined load: the dry solution lifts {n_open} of {Z} balls off a race in a flooded bearing "
                    f"({scene.supply}); their films carry load and rolling loss (seed 004 §5.3.5, Fig. 19), so the "
                    "films enter each contact law (Jones–Harris with NVM films)")


def _choose(scene: Scene, dry) -> dict:
    b, m = scene.bearing, dict(scene.models)
    out = {}
    if scene.T_C is not None:
        out["thermal"] = ("none", f"temperature prescribed in the scene ({scene.T_C:g} °C)")
    elif scene.network:
        out["thermal"] = (f"network {scene.network}", "temperatures solved with the losses (fixed point)")
    else:
        raise InputError("thermal.network", None, "give a thermal network or prescribe operation.T_C")
    symmetric = is_symmetric(scene)
    if "load_model" in m:
        if m["load_model"] == "closed_form" and not symmetric:
            raise InputError("models.load_model", "closed_form", "the closed form needs Fr = 0, no moment and "
                             "the nominal stiffness")
        out["load_model"] = (m["load_model"], "chosen in the scene" if m["load_model"] != "film" else
                             "chosen in the scene: Jones–Harris with the NVM films in each contact law "
                             "(thermobear.loads.film, or thermobear.loads.highspeed with film=...)")
    elif symmetric:
        out["load_model"] = ("closed_form", "pure axial load, tilt held: all balls equal (exact closed form)")
    else:
        out["load_model"] = ("jones_harris", "")         # dry or film: decided below, once high_speed is known
    out["high_speed"] = _high_speed_choice(scene)
    if out["high_speed"][0] == "yes" and out["load_model"][0] == "closed_form":
        out["load_model"] = ("jones_harris", "high-speed form: per-ball equilibrium with centrifugal force")
    if out["load_model"] == ("jones_harris", ""):
        out["load_model"] = _combined_load_model(scene, out["high_speed"][0] == "yes", dry)
    ndm = scene.n_rpm * b.dm * 1e3
    if "drag" in m:
        out["drag"] = (m["drag"], "chosen in the scene")
    elif scene.supply in ("oil_jet", "oil_air"):
        out["drag"] = (True, f"{scene.supply}: balls run through an oil–air mixture")
    elif ndm >= 1e5 and scene.supply == "grease":
        out["drag"] = (True, f"n dm = {ndm:.3g} mm rpm >= 1e5")
    else:
        out["drag"] = (False, f"{scene.supply} at n dm = {ndm:.3g} mm rpm: churning negligible")
    lm = m.get("losses", "local")
    out["losses"] = (lm, "chosen in the scene" if "losses" in m else "per-contact local model (default)")
    out["rolling"] = (m.get("rolling", "auto"), "chosen in the scene" if "rolling" in m
                      else "per-contact regime (IVR: Houpert, PVR/IVE: Biboulet, EHL: Houpert; seed 004)")
    default_control = "radial" if b.kind == "thrust" else "outer"
    out["kinematics"] = (m.get("kinematics", default_control), "chosen in the scene" if "kinematics" in m else
                         "thrust: symmetric radial ball axis (seed 000)" if b.kind == "thrust"
                         else "Jones outer-raceway control")
    out["hertz"] = (m.get("hertz", "exact"), "chosen in the scene" if "hertz" in m else
                    "exact elliptic integrals (approximations err 1–5 %)")
    return out


def plan(scene: Scene) -> tuple:
    """(models, dry load distribution or None): :func:`choose_models` and the dry solution it solved."""
    key = _dry_key(scene)
    dry = None
    if key is not None:
        try:
            dry = _solve_dry(*key)
        except SolverError as exc:
            dry = exc
    models = _choose(scene, dry)
    return models, (dry if isinstance(dry, LoadDistribution) else None)


def choose_models(scene: Scene) -> dict:
    """Models a scene needs, each as ``(choice, reason)`` (see the module docstring).

    >>> import thermobear as tb
    >>> m = choose_models(tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")))
    >>> m["high_speed"][0], m["load_model"][0], m["drag"][0]
    ('yes', 'jones_harris', True)
    """
    return plan(scene)[0]


def plan_many(scenes) -> list:
    """:func:`plan` of many operating points, their dry loads solved in batched calls.

    Points sharing a bearing, stiffness option, load form and moment convention form one load
    batch (each case converges on its own, equal to a single solve to round-off).  A batch that
    fails is halved until the points without equilibrium stand alone.  Returns, per scene,
    ``(models, dry)`` or the InputError / SolverError that stops its model choice.
    """
    keys = [_dry_key(sc) for sc in scenes]
    dry: dict = {}
    groups: dict = {}
    for k in keys:
        if k is not None and k not in groups.setdefault((k[0], k[3] is None, k[4], k[5] is None), {}):
            groups[(k[0], k[3] is None, k[4], k[5] is None)][k] = None
    for (brg, no_M, stiff, low), members in groups.items():
        _batch_dry(brg, no_M, stiff, low, list(members), dry)
    out = []
    for sc, k in zip(scenes, keys):
        d = dry.get(k) if k is not None else None
        try:
            out.append((_choose(sc, d), d if isinstance(d, LoadDistribution) else None))
        except (InputError, SolverError) as exc:
            out.append(exc)
    return out


def _batch_dry(brg, no_M, stiff, low, keys, dry):
    """Solve the dry loads of ``keys`` (one group) in batched calls, halving failed batches."""
    if len(keys) == 1:
        try:
            dry[keys[0]] = _solve_dry(*keys[0])
        except SolverError as exc:
            dry[keys[0]] = exc
        return
    Fa, Fr = np.array([k[1] for k in keys]), np.array([k[2] for k in keys])
    M = None if no_M else np.array([k[3] for k in keys])
    n = None if low else np.array([k[5] for k in keys])
    try:               # no continuation inside a batch: a case that needs it is left to its own solve
        ld = _solve_dry(brg, Fa, Fr, M, stiff, n, continuation=False) if low else _solve_dry(brg, Fa, Fr, M, stiff, n)
    except SolverError:
        h = len(keys) // 2
        _batch_dry(brg, no_M, stiff, low, keys[:h], dry)
        _batch_dry(brg, no_M, stiff, low, keys[h:], dry)
        return
    for j, k in enumerate(keys):
        dry[k] = take(ld, j, len(keys))
