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
* **drag** — for jet / oil–air supply (the oil–air mixture) and grease (the cavity air: negligible
  below n·d_m ≈ 1e5 mm/min, ∝ ω², so kept everywhere rather than switched on at a speed).  In an oil
  bath the bath's drag on the balls is **churning** (no oil–air mixture term).
* **churning** — where an oil level reaches the balls (``lubricant.oil_level_mm`` > 0, horizontal shaft;
  an oil bath without a level is not given one: the reason says so): the local model's ball drag in
  oil weighted by the immersed share of the ball path
  (:func:`~thermobear.losses.drag.churning_loss`), or SKF's drag term with V_M at H/dm (SKF 2018).
* **seals** — contact seals (RSL, RSH, RS1, …): SKF 2004's M_seal (:mod:`thermobear.losses.seals`);
  shields and open bearings have none.
* **cage** — a ring-guided cage (``bearing.cage = "inner_ring" | "outer_ring"``): Petroff land friction
  and ball–pocket sliding (:mod:`thermobear.losses.cage`); a ball-centred cage (the default: pressed
  steel and polyamide cages) none.
* **rolling** — per-contact regime selection (seed 004 §4.3) unless named.
* **traction** — the film's own traction law (Eyring stress and limiting shear stress of the base
  oil; :mod:`thermobear.losses.traction`) wherever an oil film carries the contacts; a constant
  full-film μ only for a dry film.  A constant μ_e charges the low-slip spin of thrust and
  angular-contact bearings with plateau traction (+40 % of the seed 002 torque:
  validation/report/seed002_local_diagnosis.md).
* **inlet_heating** — the thermal film reduction of Gupta et al. (1992) wherever an oil film rolls
  (:mod:`thermobear.lubrication.thermal_film`; φ_T → 1 at low speed × viscosity, so no switch).
* **starvation** — SKF's kinematic replenishment factor Φ_rs on the rolling force wherever it is
  defined (grease, oil–air, jet, bath; Φ_rs → 1 when the track refills, so no switch).
* **clearance** — the diametral clearance the load distribution uses (:mod:`thermobear.coupled.clearance`):
  ``operating`` — the mounted clearance (ISO 286 fits, Lamé) less the thermal and centrifugal growth at the
  solution's own ring, ball, shaft and housing temperatures, to a fixed point — by default for a deep groove
  bearing whose scene gives its fits (``bearing.shaft_fit`` / ``housing_fit``: the mounting is known); ``given``
  (the bearing's clearance as stated) otherwise, the operating clearance at the solution still reported with the
  ratings (with the catalogue-typical k5 / H7 fits and the mid CN clearance every shipped 6208 scene consumes its
  clearance, so a default loop would preload them all on guessed fits); ``mounted`` the fits at 20 °C.  A
  negative clearance is a radial preload, solved with a named warning (its runaway refused).  Angular
  contact and thrust bearings: ``given`` (their contact angle is set by the design, not by a radial play).
* **hertz** — exact (one ellipticity solve per contact; the approximations' errors, 1–5 %, would
  show in p_max and the film).
* **preload** — one bearing of a preloaded pair of angular contact bearings (``[bearing] arrangement``,
  ``preload_N``, ``preload``): its loads are the pair's loaded bearing's, at the cold preload with a spring, at
  the fixed point of the warm preload with a position preload (:mod:`thermobear.coupled.preload`, in the coupled
  steady state; the entry states the cold and warm preloads).  A model choice for given loads refuses such a
  scene (:func:`refuse_pair`).

**No step where the model switches.**  Two choices switch on a number: the high-speed form (F_c/Q)
and the film load model (a ball lifting off a race).  Across a band of each criterion
(:data:`BLEND_BANDS`) a point has two alternatives (up to four where the bands meet), each solved in
full, and its answer is their blend with the C¹ weight :func:`smooth_weight` — continuous in speed,
load and temperature (:func:`plan_many` returns the :class:`Alternative` s;
:mod:`thermobear.coupled.blend` combines the answers and reports how far the two models differ there).

The dry load solution the choice needs is returned with it (:func:`plan`, :class:`DryRow`), so that
the load step does not solve it again: no hidden cache.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermobear.arrays import instance_of, smooth_weight, take
from thermobear.errors import InputError, NoEquilibrium, SolverError
from thermobear.loads import LoadDistribution, load_distribution, needs_high_speed
from thermobear.loads.highspeed import load_distribution_high_speed_full
from thermobear.losses.cage import cage_land_estimate
from thermobear.losses.seals import BALL_SEALS, CONTACT_SEALS, seal_counterface_estimate_mm
from thermobear.losses.skf import K_RS, drag_loss_factor_VM, phi_rs, skf_K_z
from thermobear.lubrication.thermal_film import thermal_loading_parameter, thermal_reduction_gupta
from thermobear.scene import Scene

#: Where the model choice switches, both models are solved across a band of the switch's criterion and
#: their answers blended with the C¹ weight :func:`smooth_weight`, so that an answer never steps where
#: the choice changes.  ``high_speed``: F_c/Q from 0.035 to 0.07 (the criterion of
#: :func:`~thermobear.loads.needs_high_speed`, 0.05, at the band's geometric middle); ``film``: the
#: least contact load of the dry solution over its greatest, from 0.1 down to 0 (a ball lifting off a
#: race).  The bands are numerical choices (wide enough that 20 points across one change a blended
#: answer by less than 1 % per step when the two models differ by up to 10 %), not fits to data.
BLEND_BANDS = {"high_speed": (0.035, 0.07), "film": (0.0, 0.1)}
#: An alternative of a smaller weight is left out (the others renormalised): it would move the answer by
#: less than 1e-3 of the difference between the models (≤ 1e-4 of the power for models 10 % apart).
MIN_WEIGHT = 1e-3

__all__ = ["choose_models", "plan", "plan_many", "open_contacts", "dry_load", "is_symmetric", "moments", "FLOODED",
           "BLEND_BANDS", "Alternative", "DryRow", "smooth_weight", "film_options", "added_losses", "oil_level",
           "seal_diameter_mm", "cage_land", "traction_choice", "replenishment_constant"]

FLOODED = ("oil_jet", "oil_bath")


def is_symmetric(scene: Scene) -> bool:
    """Pure axial load, tilt held, nominal stiffness, a clearance (≥ 0): every ball carries the same load at the
    closed form's contact angle (a radial preload, P_d < 0, compresses the balls radially as well: Jones–Harris)."""
    return (scene.Fr == 0.0 and scene.Fz == 0.0 and scene.M is None and scene.My is None and scene.bearing.Pd >= 0.0
            and scene.models.get("stiffness", "nominal") == "nominal")


def _high_speed_choice(scene: Scene) -> tuple:
    """``("yes" | "no", reason)`` of a scene that fixes the choice, or of a thrust bearing."""
    b, m = scene.bearing, scene.models
    if "high_speed" in m:
        hs = m["high_speed"]
        if hs and b.kind == "thrust":
            raise InputError("models.high_speed", True, "the high-speed form is for radial and angular contact "
                             "bearings (a thrust bearing's centrifugal force acts across its grooves)")
        if hs and scene.rotating != "inner":
            raise InputError("models.high_speed", True, "the high-speed form is implemented for a rotating inner "
                             "ring (operation.rotating = 'inner')")
        if hs:
            high_speed_control(scene)
        return ("yes" if hs else "no", "chosen in the scene")
    return ("no", "thrust bearing: centrifugal force acts across the groove; not modelled")


def high_speed_control(scene: Scene) -> str:
    """The raceway control of the high-speed form's ball equilibrium: the scene's kinematics (``models.kinematics``,
    default ``"outer"``), so that the loads (β and the gyroscopic moment's share λ, Jones 1960) and the contacts'
    kinematics rest on one hypothesis.  InputError for ``"radial"``: the high-speed form takes its β from the
    controlling contact (outer or inner)."""
    ctl = scene.models.get("kinematics", "outer")
    if ctl not in ("outer", "inner"):
        raise InputError("models.kinematics", ctl, "the high-speed form needs outer or inner raceway control (β from "
                         "the controlling contact, Jones 1960)")
    return ctl


def refuse_unloaded_thrust(Fa):
    """A thrust bearing without axial load has no contact: NoEquilibrium naming operation.Fa_N."""
    raise NoEquilibrium(f"a thrust ball bearing needs an axial load (operation.Fa_N = {Fa:g} N; accepted: > 0): "
                        "without it the balls leave the washers and no contact carries or loses anything "
                        "(in service a minimum axial load keeps them rolling)", field="operation.Fa_N")


def _dry_key(scene: Scene, hs: bool):
    """The dry load distribution the model choice of ``scene`` needs with the high-speed form ``hs`` —
    (bearing, Fa, Fr, M, stiffness, n_rpm or None, Fz, My, raceway control of the high-speed form or None) —
    or None when it needs none (closed form, film
    chosen in the scene, no choice to make, or an invalid scene: :func:`choose_models` will say why)."""
    m = scene.models
    if m.get("load_model") in ("closed_form", "film") or (scene.T_C is None and not scene.network):
        return None
    if m.get("losses") == "skf":
        return None         # the SKF global model reads F_a, F_r only: no film test, no dry loads needed
    if is_symmetric(scene) and not hs and "load_model" not in m:
        return None
    M, My = moments(scene)
    return (scene.bearing, float(scene.Fa), float(scene.Fr), M, m.get("stiffness", "nominal"),
            float(scene.n_rpm) if hs else None, float(scene.Fz), My, high_speed_control(scene) if hs else None)


def moments(scene: Scene) -> tuple:
    """(M, M_y) of a scene for the load solvers [N m]: both None (tilts held) unless either is given, then the
    other 0 (:func:`thermobear.loads.load_distribution`)."""
    if scene.M is None and scene.My is None:
        return None, None
    return float(scene.M or 0.0), float(scene.My or 0.0)


def _solve_dry(brg, Fa, Fr, M, stiffness, n_rpm, *, continuation=True, Fz=0.0, My=None,
               control="outer") -> LoadDistribution:
    """Dry Jones–Harris load distribution (high-speed form when ``n_rpm`` is given, with raceway ``control``);
    arrays batch."""
    return _solve_dry_full(brg, Fa, Fr, M, stiffness, n_rpm, continuation=continuation, Fz=Fz, My=My,
                           control=control)[0]


def _solve_dry_full(brg, Fa, Fr, M, stiffness, n_rpm, *, continuation=True, Fz=0.0, My=None, control="outer") -> tuple:
    """(:func:`_solve_dry`, the high-speed form's HighSpeedExtras or None)."""
    if n_rpm is None:
        return load_distribution(brg, Fa=Fa, Fr=Fr, M=M, Fz=Fz, My=My, stiffness=stiffness, continuation=continuation,
                                 refuse_overload=False), None    # the contact set refuses overloads per point
    return load_distribution_high_speed_full(brg, Fa=Fa, Fr=Fr, M=M, Fz=Fz, My=My, n_rpm=n_rpm, stiffness=stiffness,
                                             control=control)


def dry_load(scene: Scene, high_speed: bool) -> LoadDistribution:
    """The scene's dry Jones–Harris load distribution (high-speed form when ``high_speed``)."""
    M, My = moments(scene)
    return _solve_dry(scene.bearing, float(scene.Fa), float(scene.Fr), M, scene.models.get("stiffness", "nominal"),
                      float(scene.n_rpm) if high_speed else None, Fz=float(scene.Fz), My=My,
                      control=high_speed_control(scene) if high_speed else "outer")


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


def _high_speed_alternatives(scene: Scene) -> list:
    """``[((choice, reason), weight), ...]``: the high-speed form, the low-speed form, or both blended
    across the switch band of F_c/Q (:data:`BLEND_BANDS`)."""
    b, m = scene.bearing, scene.models
    if "high_speed" in m or b.kind == "thrust":
        return [(_high_speed_choice(scene), 1.0)]
    Qtyp = max(scene.Fa / (b.Z * max(np.sin(b.alpha0), 1e-3)), float(np.hypot(scene.Fr, scene.Fz)) * 5.0 / b.Z, 1e-9)
    ratio = float(needs_high_speed(b, scene.n_rpm, Qtyp, rotating=scene.rotating)[1])
    lo, hi = BLEND_BANDS["high_speed"]
    w = float(smooth_weight(ratio, lo, hi))
    if scene.rotating != "inner" and w > 0.0:
        return [(("no", f"F_c/Q = {ratio:.3g} > {lo:g}, but the high-speed form is implemented for a rotating inner "
                        "ring: low-speed form with F_c on the outer contacts"), 1.0)]
    if w > 0.0:
        high_speed_control(scene)              # the high-speed form takes part: its raceway control must be one it has
    if w >= 1.0:
        return [(("yes", f"F_c/Q = {ratio:.3g} >= {hi:g}: Jones high-speed form (centrifugal force, gyroscopic "
                         "moment, outer-race control) shifts the contact angles"), 1.0)]
    if w <= 0.0:
        return [(("no", f"F_c/Q = {ratio:.3g} <= {lo:g} (F_c still loads the outer contacts of balls outside the "
                        "load zone)"), 1.0)]
    why = (f"F_c/Q = {ratio:.3g} inside the switch band {lo:g}–{hi:g}: the high-speed and low-speed forms "
           f"blended, weight {w:.3f} on the high-speed form")
    return [(("yes", why), w), (("no", why), 1.0 - w)]


def _load_model_alternatives(scene: Scene, dry) -> list:
    """``[((choice, reason), weight), ...]`` of a combined load: dry Jones–Harris, the film load model
    when the dry solution lifts a ball off a race in a flooded bearing (see :func:`open_contacts`), or
    both blended while the least loaded contact carries less than 10 % of the greatest
    (:data:`BLEND_BANDS`)."""
    jh = "combined load: balls differ (Jones–Harris, seed 004 eqs 6–8)"
    if scene.models.get("losses") == "skf":
        return [(("jones_harris", jh + "; SKF global model: its losses read F_a, F_r only (no film test)"), 1.0)]
    if scene.supply not in FLOODED:
        return [(("jones_harris", jh + f"; {scene.supply}: contacts outside the load zone taken as starved (no "
                                       "film load)"), 1.0)]
    if dry is None:                  # no network and no T_C: the model choice (choose_models) says what is missing
        return [(("jones_harris", jh + "; no dry solution to test the films on"), 1.0)]
    if isinstance(dry, (SolverError, InputError)):  # the load step itself will say so (per point)
        return [(("jones_harris", jh + f"; the dry solution failed ({type(dry).__name__}), so no film test"), 1.0)]
    Z = scene.bearing.Z
    lo, hi = BLEND_BANDS["film"]
    w = 1.0 - float(smooth_weight(dry.q, lo, hi))
    film = ("film", f"combined load: the dry solution lifts {dry.n_open} of {Z} balls off a race in a flooded bearing "
                    f"({scene.supply}); their films carry load and rolling loss (seed 004 §5.3.5, Fig. 19), so the films "
                    "enter each contact law (Jones–Harris with NVM films)")
    if w >= 1.0:
        return [(film, 1.0)]
    if w <= 0.0:
        return [(("jones_harris", jh + f"; every ball on both races in the dry solution (least contact load "
                                       f"{dry.q:.0%} of the greatest; the films would change the power by 0.2 % "
                                       "typically, at most 6 % on the validation grid)"), 1.0)]
    why = (f"the least loaded contact carries {dry.q:.1%} of the greatest (switch band {lo:g}–{hi:g} before a ball "
           f"lifts off): the film and dry load models blended, weight {w:.3f} on the film model")
    return [(("film", why), w), (("jones_harris", why), 1.0 - w)]


def film_options(models: dict) -> dict:
    """The keyword arguments of :func:`thermobear.losses.evaluate_losses` for the film choices of a
    :func:`choose_models` answer (``traction``, ``inlet_heating``, ``starvation``; absent → the
    constant-μ, isothermal, flooded model)."""
    return {"traction": models.get("traction", ("constant",))[0],
            "inlet_heating": bool(models.get("inlet_heating", (False,))[0]),
            "starvation": bool(models.get("starvation", (False,))[0])}


def traction_choice(scene: Scene) -> tuple:
    """``(choice, reason)`` of the full-film traction (module docstring): the scene's, else a constant μ for a
    dry film and the base oil's Eyring law wherever an oil film carries the contacts."""
    m, oil = scene.models, scene.lubricant
    if "traction" in m:
        return m["traction"], "chosen in the scene"
    if scene.supply == "dry_film":
        return "constant", "dry film: constant friction coefficient"
    return "eyring", (f"oil film: the base oil's traction (Eyring stress {oil.eyring_stress:.3g} Pa, "
                      f"τ_L/p {oil.limiting_shear:g}) on each contact's slip")


def replenishment_constant(scene: Scene, models: dict | None = None):
    """The replenishment constant K_rs [-] of a scene's starvation factor Φ_rs (:func:`~thermobear.losses.skf.phi_rs`):
    the scene's ``[lubricant] K_rs``, else SKF's for its supply (SKF 2004: 3e-8 oil jet and low-level oil bath,
    6e-8 grease and oil–air; :data:`~thermobear.losses.skf.K_RS`); None for a supply SKF gives none (dry film).
    With the chosen ``models`` whose starvation is off: 0 (Φ_rs = 1, the SKF model's too).

    >>> import thermobear as tb
    >>> s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    >>> replenishment_constant(s), replenishment_constant(s.with_(K_rs=4.5e-8))
    (3e-08, 4.5e-08)
    >>> replenishment_constant(s, {"starvation": (False, "chosen in the scene")})
    0.0
    """
    if models is not None and not models.get("starvation", (True,))[0]:
        return 0.0
    return scene.K_rs if scene.K_rs is not None else K_RS.get(scene.supply)


def _film_choices(scene: Scene, out: dict, K_z: dict | None = None) -> None:
    """``traction``, ``inlet_heating`` and ``starvation``, each with its reason (see the module docstring);
    evaluated at the scene's temperature (prescribed, else the oil inlet or the ambient).  ``K_z``: bearing
    kind → SKF K_z read by this call's caller for its scenes (filled here as kinds come up)."""
    m, b, oil = scene.models, scene.bearing, scene.lubricant
    out["traction"] = traction_choice(scene)
    T = scene.T_C if scene.T_C is not None else (scene.T_oil_in_C if scene.T_oil_in_C is not None
                                                   else scene.T_ambient_C)
    wet = scene.supply != "dry_film" and scene.n_rpm > 0
    # both factors tend to 1 continuously where they do not matter: applied wherever they are defined
    # (no switch at a threshold, so no step), the reason giving their size at the scene's temperature
    if "inlet_heating" in m:
        out["inlet_heating"] = (m["inlet_heating"], "chosen in the scene")
    elif not wet:
        out["inlet_heating"] = (False, "no rolling film")
    else:
        u_sum = scene.omega * b.dm / 2.0 * (1.0 - (b.D / b.dm) ** 2)        # 2u at α = 0: an upper bound
        phi = float(thermal_reduction_gupta(thermal_loading_parameter(oil.beta_at(float(T)), oil.eta(float(T)),
                                                                      u_sum, oil.k_th(float(T)))))
        out["inlet_heating"] = (True, f"Gupta φ_T = {phi:.3f} at {T:g} °C, the inlet's shear heating "
                                      "(→ 1 at low speed × viscosity)")
    if "starvation" in m:
        out["starvation"] = (m["starvation"], "chosen in the scene")
    elif not wet or scene.supply not in K_RS or b.bore is None or b.outer_diameter is None:
        out["starvation"] = (False, "fully flooded (no replenishment factor for this supply or bearing: bore/OD unknown)")
    else:
        K_z = {} if K_z is None else K_z
        if b.kind not in K_z:
            K_z[b.kind] = skf_K_z(b.kind)
        K = replenishment_constant(scene)
        phi = float(phi_rs(scene.n_rpm, oil.nu(float(T)), b.bore * 1e3, b.outer_diameter * 1e3, K_z[b.kind], K))
        given = "the scene's" if scene.K_rs is not None else "SKF's"
        out["starvation"] = (True, f"{scene.supply}: SKF Φ_rs = {phi:.3f} at {T:g} °C on the rolling force "
                                   f"(kinematic replenishment, K_rs {K:.3g} {given}; → 1 when the track refills)")


def _choose(scene: Scene, hs: tuple, lm: tuple | None, film: dict | None = None, K_z: dict | None = None) -> dict:
    """The model choices of a scene, given the high-speed choice ``hs`` and, for a combined load the
    scene does not fix, the load model ``lm`` (each ``(choice, reason)``).  ``film``: the scene's
    :func:`_film_choices` (the same for each alternative of the scene: an empty dict is filled on the first
    call), ``K_z`` as there."""
    b, m = scene.bearing, dict(scene.models)
    out = {}
    if scene.T_C is not None:
        out["thermal"] = ("none", f"temperature prescribed in the scene ({scene.T_C:g} °C)")
    elif scene.network:
        out["thermal"] = (f"network {scene.network}", "temperatures solved with the losses (fixed point)")
    else:
        raise InputError("thermal.network", None, "give a thermal network or prescribe operation.T_C")
    if "load_model" in m:
        if m["load_model"] == "closed_form" and not is_symmetric(scene):
            raise InputError("models.load_model", "closed_form", "the closed form needs Fr = 0, no moment, "
                             "the nominal stiffness and a clearance >= 0 (a radial preload: jones_harris)")
        out["load_model"] = (m["load_model"], "chosen in the scene" if m["load_model"] != "film" else
                             "chosen in the scene: Jones–Harris with the NVM films in each contact law "
                             "(thermobear.loads.film, or thermobear.loads.highspeed with film=...)")
    elif is_symmetric(scene):
        out["load_model"] = ("closed_form", "pure axial load, tilt held: all balls equal (exact closed form)")
    else:
        out["load_model"] = lm
    out["high_speed"] = hs
    if hs[0] == "yes" and out["load_model"][0] == "closed_form":
        out["load_model"] = ("jones_harris", "high-speed form: per-ball equilibrium with centrifugal force")
    ndm = scene.n_rpm * b.dm * 1e3
    if "drag" in m:
        out["drag"] = (m["drag"], "chosen in the scene")
    elif scene.supply in ("oil_jet", "oil_air"):
        out["drag"] = (True, f"{scene.supply}: balls run through an oil–air mixture")
    elif scene.supply == "grease":
        out["drag"] = (True, f"grease: the balls' drag in the cavity air (∝ ω²; n dm = {ndm:.3g} mm rpm here, "
                             "negligible below about 1e5; kept everywhere so that no switch steps the answer)")
    elif scene.supply == "oil_bath":
        out["drag"] = (False, "oil bath: no oil–air mixture term (the bath's drag on the balls is the churning "
                              "term, from lubricant.oil_level_mm)")
    else:
        out["drag"] = (False, f"{scene.supply}: drag of the balls not modelled for this supply")
    lm_ = m.get("losses", "local")
    out["losses"] = (lm_, "chosen in the scene" if "losses" in m else "per-contact local model (default)")
    out.update(added_losses(scene))
    out["rolling"] = (m.get("rolling", "auto"), "chosen in the scene" if "rolling" in m
                      else "per-contact regime (IVR: Houpert, PVR/IVE: Biboulet, EHL: Houpert; seed 004)")
    default_control = "radial" if b.kind == "thrust" else "outer"
    out["kinematics"] = (m.get("kinematics", default_control), "chosen in the scene" if "kinematics" in m else
                         "thrust: symmetric radial ball axis (seed 000)" if b.kind == "thrust"
                         else "Jones outer-raceway control")
    out["hertz"] = (m.get("hertz", "exact"), "chosen in the scene" if "hertz" in m else
                    "exact elliptic integrals (approximations err 1–5 %)")
    film = {} if film is None else film
    if not film:
        _film_choices(scene, film, K_z)
    out.update(film)
    out["clearance"] = clearance_choice(scene)
    return out


def clearance_choice(scene: Scene) -> tuple:
    """``(choice, reason)`` of the clearance of the load distribution (module docstring): ``given``,
    ``mounted`` or ``operating``; InputError where the scene forces a choice its bearing cannot take."""
    b, m = scene.bearing, scene.models.get("clearance")
    pd = f"P_d {b.Pd * 1e6:.3g} µm" + (f" ({b.clearance_group})" if b.clearance_group else "")
    can = b.kind == "deep_groove" and b.bore is not None and b.outer_diameter is not None
    if m in ("mounted", "operating") and not can:
        raise InputError("models.clearance", m, "the fitted clearance needs a deep groove bearing with its bore and "
                         "outside diameter (angular contact and thrust bearings: their contact angle is the design's)")
    if m in ("mounted", "operating") and scene.T_C is not None:
        raise InputError("models.clearance", m, "the fitted clearance is applied by the coupled steady state: "
                         "remove operation.T_C, or choose 'given'")
    if m is not None:
        return m, f"chosen in the scene ({pd} unmounted)"
    if not can:
        return "given", f"{b.kind.replace('_', ' ')} bearing: the contact angle of the design ({pd})"
    if scene.T_C is None and (scene.shaft_fit is not None or scene.housing_fit is not None):
        return "operating", (f"deep groove bearing with fits given ({scene.shaft_fit or '-'} / {scene.housing_fit or '-'}):"
                             f" {pd} unmounted, mounted and warmed to the solution's ring temperatures (fixed point)")
    if scene.T_C is not None:
        return "given", (f"{pd} as given (a prescribed temperature: the operating clearance with every part at it is "
                         "reported with the ratings; the loop needs the solved temperatures)")
    seats = [f"[{k}] interference_um {getattr(scene.network, k).interference * 1e6:.3g} µm" for k in ("shaft", "housing")
             if getattr(getattr(scene.network, k, None), "interference", None) is not None]
    if seats:      # a machine's seats (init writes the usual fits' probable interference): reported, not in the loads
        return "given", (f"{pd} as given; the machine's seats ({', '.join(seats)}) give the operating clearance at "
                         "the solution, reported with the ratings — models.clearance = 'operating' uses it in the loads "
                         "(a fixed point; it neglects the seats' surface smoothing, so it errs tight)")
    return "given", (f"{pd} as given (fits not stated: the operating clearance at the solution is reported with the "
                     "ratings; bearing.shaft_fit / housing_fit or models.clearance = 'operating' close the loop)")


@dataclass(frozen=True)
class DryRow:
    """One point's dry load distribution inside a batched solution (sliced when asked for), with the
    film test's criteria: ``n_open`` balls off a race, ``q`` the least contact load over the greatest;
    ``extras`` the batch's per-ball details of the high-speed form (the film load model starts from them)."""

    batch: LoadDistribution
    row: int
    B: int
    n_open: int
    q: float
    extras: object = None          # the high-speed form's HighSpeedExtras of the batch (None: low-speed form)

    def load(self) -> LoadDistribution:
        return take(self.batch, self.row, self.B)


@dataclass(frozen=True)
class Alternative:
    """One set of model choices of a point, with its weight in the point's answer (1 unless the point
    lies in a switch band, :data:`BLEND_BANDS`)."""

    models: dict
    dry: DryRow | None
    weight: float


def oil_level(scene: Scene) -> tuple:
    """``(H [m] or None, how)``: the oil level above the lowest point of the outer-ring raceway,
    ``lubricant.oil_level_mm`` (None where the scene does not give it: no default — the level of a bath
    is a design value, and the immersion model assumes a horizontal shaft)."""
    if scene.oil_level is not None:
        return scene.oil_level, "given"
    return None, ""


def seal_diameter_mm(scene: Scene) -> tuple:
    """``(d_s [mm], how)``: the seal counterface diameter given or estimated
    (:func:`~thermobear.losses.seals.seal_counterface_estimate_mm`)."""
    if scene.seal_diameter is not None:
        return scene.seal_diameter * 1e3, "given"
    b = scene.bearing
    return seal_counterface_estimate_mm(b.bore * 1e3, b.outer_diameter * 1e3), "estimated d + 0.25 (D − d)"


def cage_land(scene: Scene) -> tuple:
    """``(dict d_land, b_land, c_land [m], estimated keys)`` of a ring-guided cage
    (:func:`~thermobear.losses.cage.cage_land_estimate` for what the scene does not give)."""
    b = scene.bearing
    land = cage_land_estimate(scene.cage, b.bore * 1e3, b.outer_diameter * 1e3, b.width * 1e3)
    est = ["d_land"]
    for key, given in (("b_land", scene.cage_land_width), ("c_land", scene.cage_land_clearance)):
        if given is None:
            est.append(key)
        else:
            land[key] = given
    return land, est


def _forced(m, key, cond, why):
    """``m[key]`` forced True where ``cond`` is False: InputError saying why."""
    if m.get(key) is True and not cond:
        raise InputError(f"models.{key}", True, why)


def added_losses(scene: Scene) -> dict:
    """The choices ``churning``, ``seals`` and ``cage`` (see the module docstring): each ``(choice, reason)``,
    choice False where the scene has no such loss.  Needs no load solve (the coupling of a scene family
    is built from it)."""
    m, b, skf = scene.models, scene.bearing, scene.models.get("losses") == "skf"
    out = {}
    H, how = oil_level(scene)
    _forced(m, "churning", H is not None and H > 0, "churning needs an oil level reaching the balls: give "
            "lubricant.oil_level_mm > 0 with an oil supply")
    if m.get("churning") is False:
        out["churning"] = (False, "chosen in the scene")
    elif H is None and scene.supply == "oil_bath":
        out["churning"] = (False, "oil bath without lubricant.oil_level_mm: churning not modelled (give the level "
                                  "above the lowest point of the outer-ring raceway; SKF's static level is the "
                                  "lowest ball centre, D/2)")
    elif H is None:
        out["churning"] = (False, f"{scene.supply}: no oil bath (no lubricant.oil_level_mm)")
    elif H <= 0:
        out["churning"] = (False, "oil level 0: no ball reaches the bath")
    else:
        lvl = f"oil level H = {H * 1e3:.3g} mm ({how}), H/dm = {H / b.dm:.3g}"
        out["churning"] = (("skf_2018", f"{lvl}: SKF 2018 drag term, V_M = {float(drag_loss_factor_VM(H / b.dm)):.3g} "
                            "(SKF's diagram, digitised)") if skf else
                           ("pouly_immersed", f"{lvl}: the balls cross the bath; Pouly's sphere drag in oil × the "
                            "immersed share of the ball path"))
    contact = scene.seals in CONTACT_SEALS
    _forced(m, "seals", contact, f"seal friction needs a contact seal (bearing.seals one of {', '.join(BALL_SEALS[2:])})")
    if m.get("seals") is False:
        out["seals"] = (False, "chosen in the scene")
    elif not contact:
        out["seals"] = (False, "open bearing" if scene.seals == "none" else
                        f"shields ×{scene.seal_sides}: non-contact, no friction (SKF)")
    else:
        ds, how = seal_diameter_mm(scene)
        out["seals"] = (f"SKF 2004 {scene.seals} ×{scene.seal_sides}",
                        f"M_seal = K_S1 d_s^β + K_S2 (SKF table 4), d_s = {ds:.3g} mm ({how})")
    ring = scene.cage != "balls"
    _forced(m, "cage", ring and scene.supply != "dry_film" and not skf, "the cage loss needs a ring-guided cage "
            "(bearing.cage = 'inner_ring' | 'outer_ring') with an oil or grease film on its land, and the local model")
    if m.get("cage") is False:
        out["cage"] = (False, "chosen in the scene")
    elif not ring:
        out["cage"] = (False, "ball-centred cage: no land; its pocket forces balance only the cage's windage "
                              "(not modelled)")
    elif skf:
        out["cage"] = (False, "SKF model: the cage is inside its empirical constants")
    elif scene.supply == "dry_film":
        out["cage"] = (False, "dry film: no fluid film on the cage land")
    else:
        land, est = cage_land(scene)
        out["cage"] = ("petroff_land+pocket", f"{scene.cage}-centred cage: Petroff land friction (land Ø "
                       f"{land['d_land'] * 1e3:.3g} mm, width {land['b_land'] * 1e3:.3g} mm, clearance "
                       f"{land['c_land'] * 1e3:.3g} mm; estimated: {', '.join(est)}) + ball–pocket sliding")
    return out


def refuse_pair(scene: Scene) -> None:
    """InputError for one bearing of a preloaded pair (``[bearing] arrangement``): its loads come from the pair's
    preload at the solved temperatures — in the coupled steady state (:mod:`thermobear.coupled.preload`: ``run``,
    ``sweep``, ``speed``'s thermally safe speed, ``--uncertainty``) and the heat-up
    (:mod:`thermobear.coupled.transient_pair`: ``transient``, with ``--uncertainty`` too) — which a model choice for
    given loads does not close (a prescribed temperature, a spin-down, injected loads)."""
    if scene.arrangement is not None:
        raise InputError("bearing.arrangement", scene.arrangement, "one bearing of a preloaded pair is solved by the "
                         "coupled steady state and its heat-up (its loads follow the pair's preload at the solved "
                         "temperatures: run, sweep, steady_state, transient), not for given loads (a spin-down, injected "
                         "loads): give the bearing's own loads without arrangement / preload_N")


def plan(scene: Scene) -> tuple:
    """(models, dry load distribution or None) of the scene's dominant alternative (the largest weight,
    :func:`plan_many`): :func:`choose_models` and the dry solution it solved."""
    alts = plan_many([instance_of(scene, Scene, "scene")])[0]
    if isinstance(alts, Exception):
        raise alts
    a = max(alts, key=lambda a: a.weight)
    return a.models, (a.dry.load() if a.dry is not None else None)


def choose_models(scene: Scene) -> dict:
    """Models a scene needs, each as ``(choice, reason)`` (see the module docstring); in a switch band
    the model of the larger weight (its reason says so).

    >>> import thermobear as tb
    >>> m = choose_models(tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")))
    >>> m["high_speed"][0], m["load_model"][0], m["drag"][0]
    ('yes', 'jones_harris', True)
    """
    return plan(scene)[0]


def plan_many(scenes) -> list:
    """The model alternatives of many operating points, their dry loads solved in batched calls.

    Returns, per scene, a list of :class:`Alternative` (one, or two to four inside switch bands,
    weights summing to 1) or the InputError / SolverError that stops its model choice.  Points
    sharing a bearing, stiffness option, load form and moment convention form one load batch (each
    case converges on its own, equal to a single solve to round-off); a batch that fails is halved
    until the points without equilibrium stand alone.
    """
    hs_alts: list = []
    for sc in scenes:
        try:
            refuse_pair(sc)
            hs_alts.append(_high_speed_alternatives(sc))
        except (InputError, SolverError) as exc:
            hs_alts.append(exc)
    groups: dict = {}
    for sc, alts in zip(scenes, hs_alts):
        for hs, _ in ([] if isinstance(alts, Exception) else alts):
            k = _dry_key(sc, hs[0] == "yes")
            if k is not None:
                groups.setdefault((k[0], k[3] is None, k[4], k[8]), {})[k] = None
    dry: dict = {}
    for (brg, no_M, stiff, ctl), members in groups.items():
        _batch_dry(brg, no_M, stiff, ctl, list(members), dry)
    out, K_z = [], {}              # K_z: bearing kind → SKF K_z, read once for these scenes
    for sc, alts in zip(scenes, hs_alts):
        if isinstance(alts, Exception):
            out.append(alts)
            continue
        try:
            out.append(_alternatives(sc, alts, dry, K_z))
        except (InputError, SolverError) as exc:
            out.append(exc)
    return out


def _alternatives(sc: Scene, hs_alts: list, dry: dict, K_z: dict) -> list:
    out = []
    film: dict = {}
    for hs, w in hs_alts:
        k = _dry_key(sc, hs[0] == "yes")
        d = dry.get(k) if k is not None else None
        lms = (_load_model_alternatives(sc, d) if "load_model" not in sc.models and not is_symmetric(sc)
               else [(None, 1.0)])
        for lm, w2 in lms:
            if w * w2 >= MIN_WEIGHT:
                out.append(Alternative(models=_choose(sc, hs, lm, film, K_z), dry=d if isinstance(d, DryRow) else None,
                                       weight=w * w2))
    total = sum(a.weight for a in out)
    return [a if total == 1.0 else Alternative(a.models, a.dry, a.weight / total) for a in out]


def _batch_dry(brg, no_M, stiff, ctl, keys, dry):
    """Solve the dry loads of ``keys`` (one group; ``ctl`` the high-speed form's raceway control, None: low-speed
    form) in batched calls, halving failed batches; each key gets its :class:`DryRow` or the SolverError of its own
    solve."""
    Fa, Fr = np.array([k[1] for k in keys]), np.array([k[2] for k in keys])
    M = None if no_M else np.array([k[3] for k in keys])
    n = None if ctl is None else np.array([k[5] for k in keys])
    Fz, My = np.array([k[6] for k in keys]), None if no_M else np.array([k[7] for k in keys])
    try:               # no continuation inside a batch: a case that needs it is left to its own solve
        ld, ex = _solve_dry_full(brg, Fa, Fr, M, stiff, n, continuation=len(keys) == 1, Fz=Fz, My=My,
                                 control=ctl or "outer")
    except (SolverError, InputError) as exc:     # loads the contacts cannot carry: said by the load step
        if len(keys) == 1:
            dry[keys[0]] = exc
            return
        h = len(keys) // 2
        _batch_dry(brg, no_M, stiff, ctl, keys[:h], dry)
        _batch_dry(brg, no_M, stiff, ctl, keys[h:], dry)
        return
    B = len(keys)
    Qi, Qo = np.asarray(ld.Q_i, float).reshape(B, -1), np.asarray(ld.Q_o, float).reshape(B, -1)
    n_open = np.count_nonzero((Qi <= 0.0) | (Qo <= 0.0), axis=1)
    Qmax = np.maximum(Qi, Qo).max(axis=1)
    q = np.where(Qmax > 0.0, np.minimum(Qi, Qo).min(axis=1) / np.where(Qmax > 0.0, Qmax, 1.0), 0.0)
    for j, k in enumerate(keys):
        dry[k] = DryRow(batch=ld, row=j, B=B, n_open=int(n_open[j]), q=float(max(q[j], 0.0)), extras=ex)
