r"""The scene solver: the least model a scene needs, steady state and transient.

In the spirit of pvlib's ModelChain, :func:`choose_models` infers from what a
scene contains which sub-models serve it, each with the reason, overridable
from the scene's ``[models]`` table:

* **thermal** — no thermal network when the scene prescribes the temperature
  (``operation.T_C``); else the scene's network, coupled to the losses by a
  fixed point (:mod:`thermobear.coupled.fixedpoint`).
* **load_model** — the closed form when the load case is symmetric and the
  closed form is exact (pure axial load, tilt held: all balls equal, Harris
  eq 7.36; thrust bearing: Q = Fa/Z); Jones–Harris otherwise.  Centrifugal and
  gyroscopic terms (``high_speed``, Jones 1960, :mod:`thermobear.loads.highspeed`)
  only where ``needs_high_speed`` says they matter (F_c > 5 % of the ball load);
  otherwise the low-speed form, in which the centrifugal force F_c still loads the
  outer contact (it is what keeps balls outside the load zone on the race).
  ``load_model = "film"``: the lubricant films in each contact's law
  (:mod:`thermobear.loads.film` in the low-speed form, ``film=`` of
  :mod:`thermobear.loads.highspeed` in the high-speed form, chosen as for
  Jones–Harris), films at one temperature — the prescribed T, or in
  ``steady_state`` the mean contact temperature of the solution (a fixed point
  on it); in the transient the loads are re-solved piece by piece as the mean
  contact temperature drifts (≈ 2 K per piece).  Chosen when the dry
  Jones–Harris solution lifts a ball off a race in a flooded bearing (oil jet
  or oil bath; :func:`open_contacts`): the films of those balls carry load and
  a rolling loss the dry law drops (2–50 % of the power on a 7210 / 6210 grid;
  with every ball on both races at most 6 % — validation/report/film_criterion.md).
  Grease and oil–air contacts outside the load zone are taken as starved.
* **drag** — only for jet / oil–air supply, or when n·dm ≥ 1e5 mm·rpm (below,
  churning of a few balls in air is < 0.1 % of the contact losses).
* **rolling** — per-contact regime selection (seed 004) unless named.
* **hertz** — exact (one ellipticity solve per contact; the approximations'
  errors, 1–5 %, would show in p_max and the film).

The same numbers come out whichever path computes them (tests/test_solver.py).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from thermobear.errors import InputError, ThermalRunaway
from thermobear.losses.local import ContactSet, LossResult, evaluate_losses, prepare_contacts
from thermobear.loads.static import LoadDistribution, axial_contact_angle, load_distribution, needs_high_speed
from thermobear.scene.scene import Scene

__all__ = ["choose_models", "open_contacts", "scene_losses", "solve", "steady_state", "transient", "RunResult",
           "SteadyState", "TransientRun", "network_context"]

_ROLES = {"inner": ("inner_race", "shaft_washer", "inner_ring", "bearing"),
          "outer": ("outer_race", "housing_washer", "outer_ring", "bearing"),
          "ball": ("balls", "bearing"),
          "oil": ("oil_air", "balls", "bearing")}


def choose_models(scene: Scene) -> dict:
    """Models a scene needs, each as ``(choice, reason)`` (see the module docstring)."""
    b, m = scene.bearing, dict(scene.models)
    out = {}
    if scene.T_C is not None:
        out["thermal"] = ("none", f"temperature prescribed in the scene ({scene.T_C:g} °C)")
    elif scene.network:
        out["thermal"] = (f"network {scene.network}", "temperatures solved with the losses (fixed point)")
    else:
        raise InputError("thermal.network", None, "give a thermal network or prescribe operation.T_C")
    symmetric = _symmetric(scene)
    if "load_model" in m:
        if m["load_model"] not in ("closed_form", "jones_harris", "film"):
            raise InputError("models.load_model", m["load_model"], "must be 'closed_form', 'jones_harris' or "
                             "'film' (lubricant film in the contact law)")
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
        out["load_model"] = _combined_load_model(scene, out["high_speed"][0] == "yes")
    ndm = scene.n_rpm * b.dm * 1e3
    if "drag" in m:
        out["drag"] = (bool(m["drag"]), "chosen in the scene")
    elif scene.supply in ("oil_jet", "oil_air"):
        out["drag"] = (True, f"{scene.supply}: balls run through an oil–air mixture")
    elif ndm >= 1e5 and scene.supply == "grease":
        out["drag"] = (True, f"n dm = {ndm:.3g} mm rpm >= 1e5")
    else:
        out["drag"] = (False, f"{scene.supply} at n dm = {ndm:.3g} mm rpm: churning negligible")
    lm = m.get("losses", "local")
    if lm not in ("local", "skf"):
        raise InputError("models.losses", lm, "must be 'local' (per-contact model) or 'skf' (SKF 2004 global model)")
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


def _symmetric(scene: Scene) -> bool:
    """Pure axial load, tilt held, nominal stiffness: every ball carries the same load."""
    return scene.Fr == 0.0 and scene.M is None and scene.models.get("stiffness", "nominal") == "nominal"


def _high_speed_choice(scene: Scene) -> tuple:
    """``("yes" | "no", reason)``: the high-speed ball equilibrium, by the scene's choice or F_c/Q."""
    b, m = scene.bearing, scene.models
    Qtyp = max(scene.Fa / (b.Z * max(np.sin(b.alpha0), 1e-3)), scene.Fr * 5.0 / b.Z, 1e-9)
    need, ratio = needs_high_speed(b, scene.n_rpm, Qtyp, rotating=scene.rotating)
    if "high_speed" in m:
        hs = m["high_speed"]
        if not isinstance(hs, bool):
            raise InputError("models.high_speed", hs, "must be true or false")
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


_FLOODED = ("oil_jet", "oil_bath")


def _combined_load_model(scene: Scene, high_speed: bool) -> tuple:
    """Dry Jones–Harris, or the film load model when the dry solution leaves contacts open in a
    flooded bearing (see :func:`open_contacts`)."""
    jh = "combined load: balls differ (Jones–Harris, seed 004 eqs 6–8)"
    if scene.supply not in _FLOODED:
        return "jones_harris", jh + f"; {scene.supply}: contacts outside the load zone taken as starved (no film load)"
    from thermobear.errors import SolverError
    try:
        n_open, Z = open_contacts(scene, high_speed), scene.bearing.Z
    except SolverError as exc:      # the load step itself will say so (and a sweep records it for its point)
        return "jones_harris", jh + f"; the dry solution failed ({type(exc).__name__}), so no film test"
    if n_open == 0:
        return "jones_harris", jh + ("; every ball on both races in the dry solution (the films would change the "
                                     "power by 0.2 % typically, at most 6 % on the validation grid)")
    return ("film", f"combined load: the dry solution lifts {n_open} of {Z} balls off a race in a flooded bearing "
                    f"({scene.supply}); their films carry load and rolling loss (seed 004 §5.3.5, Fig. 19), so the "
                    "films enter each contact law (Jones–Harris with NVM films)")


def open_contacts(scene: Scene, high_speed: bool) -> int:
    r"""Number of balls with an open contact (Q = 0 at the inner or the outer race) in the dry
    Jones–Harris solution of a scene (high-speed form when ``high_speed``).

    The criterion of :func:`choose_models` for the film load model: in a flooded bearing a ball
    that the dry contact law lifts off a race still rolls on a film that carries load and a
    hydrodynamic rolling force nearly independent of the gap (IVR: F_R ∝ η u R_x (R_x/h)^(1/6);
    seed 004 §5.3.5, Fig. 19), which the dry law sets to zero: each lifted ball adds roughly its
    share of the rolling loss.  On the seed 004 7210 (Fa 225–675 N, Fr 25–750 N, 3200 and 8070 rpm,
    30 and 70 °C prescribed) and a 6210 (Fr 250–4000 N) the film law changes the power by 10–50 %
    with 6 or more of 15 balls lifted, 2–8 % with 5 of 10, about 4 % with 2 of 15 (5–7 % at 4800 rpm,
    Fr 750 N, rings imposed: seed 004's radial-load trend), and at most 6 % (median 0.2 %) with
    none (``validation/film_criterion.py``, report ``film_criterion.md``).  The count is a physical
    criterion, not a threshold fitted to that grid: with no ball lifted the films can still change
    the power by up to 6 % (next to a ball about to lift off), more than with 2 of 15 lifted; what
    the dry law gets qualitatively wrong is the lifted ball, whose film and rolling loss it drops.
    The switch is a step: at 4800 rpm, 50 °C, Fa 450 N the power steps by 4 % where the first ball
    lifts off (Fr ≈ 733 N).  The dry solution is cached and reused by :func:`scene_load`.

    >>> import thermobear as tb
    >>> sc = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    >>> open_contacts(sc.with_(Fr=150.0), True), open_contacts(sc.with_(Fr=750.0, n_rpm=4800.0), True) > 0
    (0, True)
    """
    ld = _dry_load(scene, high_speed)
    Qi, Qo = np.asarray(ld.Q_i, float), np.asarray(ld.Q_o, float)
    return int(np.count_nonzero((Qi <= 0.0) | (Qo <= 0.0)))


def _dry_load(scene: Scene, high_speed: bool) -> LoadDistribution:
    stiff = scene.models.get("stiffness", "nominal")
    M = None if scene.M is None else float(scene.M)
    if high_speed:
        return _dry_load_cached(scene.bearing, float(scene.Fa), float(scene.Fr), M, stiff, float(scene.n_rpm))
    return _dry_load_cached(scene.bearing, float(scene.Fa), float(scene.Fr), M, stiff, None)


class _LoadCache:
    """Least-recently-used cache of dry load distributions keyed by operating point, which a batched
    solve can fill (:func:`_prime_dry_loads`); ``cache_clear()`` as for ``functools.lru_cache``.
    Thread-safe (Dask workers run points in threads): the dictionary is touched under a lock, the
    solve itself runs outside it (two threads may solve the same point; both answers are equal)."""

    def __init__(self, fn, maxsize: int):
        import threading
        self.fn, self.maxsize, self._d, self._lock = fn, maxsize, {}, threading.Lock()

    def __call__(self, *key):
        with self._lock:
            ld = self._d.pop(key, None)
            if ld is not None:
                self._d[key] = ld                       # most recently used last
                return ld
        ld = self.fn(*key)                              # an exception is not cached
        self.put(key, ld)
        return ld

    def __contains__(self, key) -> bool:
        with self._lock:
            return key in self._d

    def put(self, key, ld):
        for v in vars(ld).values():
            if isinstance(v, np.ndarray):
                v.setflags(write=False)
        with self._lock:
            self._d[key] = ld
            while len(self._d) > self.maxsize:
                self._d.pop(next(iter(self._d)))

    def cache_clear(self):
        with self._lock:
            self._d.clear()


def _dry_load_solve(brg, Fa, Fr, M, stiffness, n_rpm):
    """Dry Jones–Harris load distribution (high-speed form when ``n_rpm`` is given)."""
    if n_rpm is None:
        return load_distribution(brg, Fa=Fa, Fr=Fr, M=M, stiffness=stiffness)
    from thermobear.loads.highspeed import load_distribution_high_speed
    return load_distribution_high_speed(brg, Fa=Fa, Fr=Fr, M=M, n_rpm=n_rpm, stiffness=stiffness)


# The model choice and the load step of one operating point share the dry solution (a sweep chooses
# the models of all its points first: room for a few thousand, ≈ 2 kB each).  Its arrays are read-only.
_dry_load_cached = _LoadCache(_dry_load_solve, 4096)


def _dry_need(scene: Scene):
    """Key of the dry load distribution :func:`choose_models` and :func:`scene_load` will ask for, or
    None when the scene needs none (closed form, film model chosen in the scene) or is invalid
    (choose_models will say why)."""
    m = scene.models
    if m.get("load_model") in ("closed_form", "film") or (scene.T_C is None and not scene.network):
        return None
    if m.get("losses") == "skf" and scene.supply not in _FLOODED and scene.T_C is not None:
        return None         # prescribed T, SKF losses, no film test: no loads (a network needs the contacts)
    try:
        hs = _high_speed_choice(scene)[0] == "yes"
    except InputError:
        return None
    symmetric = _symmetric(scene)
    if symmetric and not hs and "load_model" not in m:
        return None
    M = None if scene.M is None else float(scene.M)
    return (scene.bearing, float(scene.Fa), float(scene.Fr), M, m.get("stiffness", "nominal"),
            float(scene.n_rpm) if hs else None)


def _prime_dry_loads(scenes) -> int:
    """Solve the dry loads of many operating points in batched calls and cache them.

    Points sharing a bearing, stiffness option, load form and moment convention form one load batch
    (:func:`thermobear.loads.highspeed.load_distribution_high_speed` or
    :func:`thermobear.loads.load_distribution`, vectorised over load cases: each case converges on its
    own, equal to a single solve to round-off).  A cached case carries the batch's largest residual
    and iteration count (upper bounds of its own).  A batch that fails is halved until the points
    without equilibrium stand alone; those are left to their own solves, which report the failure per
    point.  Returns the number of cases solved and cached."""
    from thermobear.errors import SolverError
    groups: dict = {}
    room = _dry_load_cached.maxsize       # more would evict what was primed before it is used
    for sc in scenes:
        key = _dry_need(sc)
        if key is not None and key not in _dry_load_cached:
            g = groups.setdefault((key[0], key[3] is None, key[4], key[5] is None), {})
            if key not in g:
                if room == 0:
                    break
                g[key] = None
                room -= 1

    def batch(brg, no_M, stiff, low, keys) -> int:
        if len(keys) < 2:
            return 0
        Fa = np.array([k[1] for k in keys])
        Fr = np.array([k[2] for k in keys])
        M = None if no_M else np.array([k[3] for k in keys])
        try:
            if low:     # no continuation in a priming batch: a case that needs it is left to its own solve
                ld = load_distribution(brg, Fa=Fa, Fr=Fr, M=M, stiffness=stiff, _cont=False)
            else:
                from thermobear.loads.highspeed import load_distribution_high_speed
                ld = load_distribution_high_speed(brg, Fa=Fa, Fr=Fr, M=M, n_rpm=np.array([k[5] for k in keys]),
                                                  stiffness=stiff)
        except SolverError:         # a point without equilibrium: halve the batch (log2 n more batches)
            h = len(keys) // 2
            return batch(brg, no_M, stiff, low, keys[:h]) + batch(brg, no_M, stiff, low, keys[h:])
        for j, key in enumerate(keys):
            _dry_load_cached.put(key, _load_case(ld, j, len(keys)))
        return len(keys)

    return sum(batch(*g, list(keys)) for g, keys in groups.items())


def _load_case(load, index, nb):
    """A batched load distribution (leading batch axis of size ``nb``) taken at ``index``: every batched
    array indexed along its first axis, the rest (azimuths, scalars) kept."""
    import dataclasses
    out = {}
    for f in dataclasses.fields(load):
        v = getattr(load, f.name)
        out[f.name] = v[index] if isinstance(v, np.ndarray) and v.ndim >= 1 and v.shape[0] == nb \
            and f.name != "psi" else v
    return dataclasses.replace(load, **out)


def _refuse_unloaded_thrust(Fa):
    from thermobear.errors import NoEquilibrium
    raise NoEquilibrium(f"a thrust ball bearing needs an axial load (operation.Fa_N = {Fa:g} N; accepted: > 0): "
                        "without it the balls leave the washers and no contact carries or loses anything "
                        "(in service a minimum axial load keeps them rolling)")


def _closed_form_axial(b, Fa) -> LoadDistribution:
    """Pure axial load, all balls equal: Harris eq 7.36 (radial/angular) or Q = Fa/Z (thrust).

    A thrust bearing without axial load has no contact at all (its washers are not radially located
    and nothing presses the balls): NoEquilibrium, as the high-speed form says."""
    Z = b.Z
    if b.kind == "thrust" and not Fa > 0:
        _refuse_unloaded_thrust(Fa)
    psi = 2.0 * np.pi * np.arange(Z) / Z
    if b.kind == "thrust" and b.alpha0 >= np.pi / 2 - 1e-12:
        al = np.pi / 2
        Q = Fa / Z
        da = b.A + (Q / b.Kn()) ** (2.0 / 3.0) if Fa > 0 else 0.0
    elif Fa <= 0:
        al = 0.0 if b.kind == "deep_groove" else b.alpha0   # unloaded: as the Jones–Harris solver reports
        Q = 0.0
        da = 0.0
    else:
        al = float(axial_contact_angle(b, Fa))
        Q = Fa / (Z * np.sin(al))
        da = b.A * np.cos(b.alpha0) * np.tan(al)
    dn = (Q / b.Kn()) ** (2.0 / 3.0)
    full = np.full(Z, Q)
    return LoadDistribution(delta_a=float(da), delta_r=0.0, theta=0.0, Q_i=full, Q_o=full.copy(),
                            alpha_i=np.full(Z, al), alpha_o=np.full(Z, al), psi=psi, delta_n=np.full(Z, dn),
                            residual=0.0, iterations=0, Fa=np.asarray(Fa), Fr=np.asarray(0.0), M=0.0)


def film_temperature_C(scene: Scene) -> float:
    """Temperature [°C] at which the film load model evaluates the films when the caller gives none:
    the prescribed T_C, else the oil inlet, else the ambient temperature (steady_state iterates it)."""
    for T in (scene.T_C, scene.T_oil_in_C, scene.T_ambient_C):
        if T is not None:
            return float(T)
    return 20.0


def scene_load(scene: Scene, models: dict | None = None, T_film_C=None) -> LoadDistribution:
    """Load distribution by the model :func:`choose_models` picked (``T_film_C`` [°C]: temperature of
    the films for the ``"film"`` load model; default :func:`film_temperature_C`)."""
    models = models or choose_models(scene)
    if models["load_model"][0] == "film":
        return film_scene_load(scene, models, film_temperature_C(scene) if T_film_C is None else float(T_film_C))
    if models["load_model"][0] == "closed_form":
        return _closed_form_axial(scene.bearing, scene.Fa)
    return _dry_load(scene, models["high_speed"][0] == "yes")


def film_scene_load(scene: Scene, models: dict, T_film_C, n_rpm=None) -> LoadDistribution:
    """Film load model of a scene (:mod:`thermobear.loads.film`, or :mod:`thermobear.loads.highspeed`
    with ``film=`` where ``models`` has the high-speed form), films at ``T_film_C`` [°C]; with arrays
    ``n_rpm`` [rpm] and/or ``T_film_C`` one batched solve over the operating points (a load batch)."""
    from thermobear.contact.kinematics import entrainment_speed
    b, lub = scene.bearing, scene.lubricant
    T = np.asarray(T_film_C, float)
    n = np.asarray(scene.n_rpm if n_rpm is None else n_rpm, float)
    batch = T.ndim > 0 or n.ndim > 0
    val = (lambda v: np.asarray(v, float)) if batch else float       # noqa: E731
    eta, ap = val(lub.eta(T)), val(lub.alpha_p_at(T))
    stiff = scene.models.get("stiffness", "nominal")
    Fa, Fr, M = scene.Fa, scene.Fr, scene.M
    from thermobear.units import rpm_to_rad_s
    w = rpm_to_rad_s(n)
    wi, wo = (w, 0.0 * w) if scene.rotating == "inner" else (0.0 * w, w)
    u = np.maximum(np.asarray(entrainment_speed(wi, wo, b.D, b.dm, b.alpha0), float), 1e-6)
    if batch:                                       # one load case per operating point
        n, u, eta, ap = (a.ravel() for a in np.broadcast_arrays(n, u, eta, ap))
        Fa, Fr = np.full(n.size, Fa), np.full(n.size, Fr)
        M = None if M is None else np.full(n.size, M)
        u = u[:, None]
    if models["high_speed"][0] == "yes":
        # high-speed form: per-contact films at the caged kinematics of the solution (one temperature per point)
        from thermobear.loads.highspeed import load_distribution_high_speed
        return load_distribution_high_speed(b, Fa=Fa, Fr=Fr, M=M, n_rpm=n if batch else float(n), stiffness=stiff,
                                            film=dict(eta=eta, alpha_p=ap))
    from thermobear.loads.film import film_load_distribution
    return film_load_distribution(b, Fa=Fa, Fr=Fr, M=M, u_i=u if batch else float(u), u_o=u if batch else float(u),
                                  eta=eta, alpha_p=ap, stiffness=stiff)


def scene_contacts(scene: Scene, models: dict | None = None, load: LoadDistribution | None = None,
                   n_rpm=None, T_film_C=None) -> ContactSet:
    """Temperature-independent contact data of a scene (loads, ellipses, kinematics).

    ``n_rpm`` may override the scene's speed with an array (vectorised sweeps); ``T_film_C``: see
    :func:`scene_load` (the film load model's loads depend on the film temperature)."""
    models = models or choose_models(scene)
    if load is None and models["load_model"][0] == "film" and n_rpm is not None and np.ndim(n_rpm):
        raise InputError("models.load_model", "film", "the film load model takes one speed per call (no speed "
                         "arrays): sweep the scenes one by one")
    load = load if load is not None else scene_load(scene, models, T_film_C=T_film_C)
    n = scene.n_rpm if n_rpm is None else n_rpm
    return prepare_contacts(scene.bearing, scene.Fa, scene.Fr, n, M=scene.M, rotating=scene.rotating,
                            hertz_method=models["hertz"][0], centrifugal=models["high_speed"][0] != "yes", load=load,
                            control=models["kinematics"][0])


def scene_losses(scene: Scene, T_C=None, *, T_inner_C=None, T_outer_C=None, T_oil_C=None,
                 load: LoadDistribution | None = None, models: dict | None = None,
                 contacts: ContactSet | None = None, n_rpm=None) -> LossResult:
    """Losses of a scene at given temperatures (default: the scene's prescribed T_C) [W].

    ``n_rpm`` and the temperatures may be arrays (one operating point each, vectorised)."""
    models = models or choose_models(scene)
    if T_C is None:
        T_C = scene.T_C if scene.T_C is not None else scene.T_ambient_C
    cs = contacts if contacts is not None else scene_contacts(scene, models, load, n_rpm=n_rpm)
    r = evaluate_losses(cs, scene.lubricant, T_C, T_inner_C=T_inner_C, T_outer_C=T_outer_C, T_oil_C=T_oil_C,
                        supply=scene.supply, oil_flow_m3_s=scene.oil_flow, Rq_ball=scene.Rq_ball,
                        Rq_ring=scene.Rq_ring, mu_boundary=scene.mu_boundary, mu_full_film=scene.mu_full_film,
                        rolling_model=models["rolling"][0], drag=bool(models["drag"][0]))
    used = dict(r.models_used)
    used.update({k: v for k, v in models.items()})
    lm, hs = models["load_model"][0], models["high_speed"][0]
    if getattr(contacts, "models_used", {}).get("load_distribution", ("",))[0] == "injected":
        used["load_distribution"] = contacts.models_used["load_distribution"]
    else:
        used["load_distribution"] = (
            "closed form, all balls equal" if lm == "closed_form" else
            "Jones–Harris high-speed (centrifugal, gyroscopic)" if hs == "yes" else "Jones–Harris low-speed, rigid rings",
            models["load_model"][1])
        used["centrifugal"] = (("in the ball equilibrium", "high-speed form") if hs == "yes" else
                               ("F_c/cos α on the outer contact", "balls outside the load zone ride on the outer race")
                               if scene.bearing.kind != "thrust" else ("none", "thrust bearing"))
    object.__setattr__(r, "models_used", used)
    return r


@dataclass
class SKFLosses:
    """Losses of the SKF global model in the shape the solver reports (no per-contact data)."""

    P_W: float
    torque_Nm: float
    breakdown_W: dict
    heat_W: dict
    skf: object
    models_used: dict
    contacts: dict = field(default_factory=dict)


_SKF_MU_EHL = {"mineral": "mineral", "PAO": "synthetic", "ester": "synthetic", "ester+vegetal": "synthetic"}


def skf_scene_losses(scene: Scene, T_C, models: dict | None = None) -> SKFLosses:
    """SKF 2004 global model for a scene at bearing temperature ``T_C`` [°C] (viscosity of the
    (base) oil there).  Calibrated constants from ``[models] skf_R1, skf_S1, skf_mu_EHL``.
    Heat split for the network: ½ to the balls, ¼ to each ring (the equal split of the contact
    losses); drag to the oil."""
    from thermobear.losses.skf import skf_friction
    models = models or choose_models(scene)
    if scene.bearing.kind == "thrust" and not scene.Fa > 0:
        _refuse_unloaded_thrust(scene.Fa)
    m = scene.models
    lub = "grease" if scene.supply == "grease" else scene.supply
    base = _SKF_MU_EHL.get(getattr(scene.lubricant, "base_oil", "mineral"), "mineral")
    nu = scene.lubricant.nu(T_C)
    r = skf_friction(scene.bearing, nu, scene.n_rpm, scene.Fa, scene.Fr, lubrication=lub,
                     R1=m.get("skf_R1"), S1=m.get("skf_S1"), mu_EHL=m.get("skf_mu_EHL"), base_oil=base)
    w = scene.omega
    bd = {"rolling": float(r.M_rr * w), "sliding": float(r.M_sl * w), "drag": float(r.M_drag * w),
          "seal": float(r.M_seal * w)}
    P = float(r.P_W)
    contact = P - bd["drag"]
    heat = {"inner_ring": 0.25 * contact, "outer_ring": 0.25 * contact, "balls": 0.5 * contact, "oil": bd["drag"]}
    used = dict(models)
    used["losses"] = ("skf", f"SKF 2004 global model (R1 {m.get('skf_R1', 'catalogue')}, S1 {m.get('skf_S1', 'catalogue')})")
    return SKFLosses(P_W=P, torque_Nm=float(r.M_total), breakdown_W=bd, heat_W=heat, skf=r, models_used=used)


def network_context(scene: Scene, contacts: dict | None = None) -> dict:
    """Context for :func:`thermobear.thermal.load_network` from a scene."""
    ctx = {"bearing": scene.bearing,
           "scene": {"n_rpm": scene.n_rpm, "T_ambient_C": scene.T_ambient_C,
                     "T_oil_in_C": scene.T_oil_in_C if scene.T_oil_in_C is not None else scene.T_ambient_C,
                     "oil_flow_m3_s": scene.oil_flow,
                     **{k: v for k, v in scene.network_parameters.items() if "." not in k}},
           "oil": scene.lubricant}
    if contacts is not None:
        ctx["contacts"] = contacts
    return ctx


def _impose_temperatures(spec: dict, fixed: dict, name: str) -> None:
    """Turn the nodes of ``fixed`` (node → °C, measured) into fixed-temperature nodes, in place.

    This is how seed 004 (§4.5) uses its network: the inner- and outer-ring thermocouple readings
    are boundary conditions and the network gives the ball and mixture temperatures.  Nodes that
    receive the loss heat (the roles of ``_ROLES``: contact, ball and mixture nodes) cannot be
    imposed — their heat would vanish into the boundary; impose the ring node next to them."""
    if not fixed:
        return
    nodes = spec.get("nodes", {})
    sinks = {next((c for c in cands if c in nodes), None) for cands in _ROLES.values()}
    for node, T in fixed.items():
        if node not in nodes:
            raise InputError(f"thermal.fixed_C.{node}", T, f"no node '{node}' in network {name}; known: "
                             f"{', '.join(nodes)}")
        if node in sinks:
            raise InputError(f"thermal.fixed_C.{node}", T, "this node receives the loss heat and cannot be imposed; "
                             "impose a ring/housing node instead (e.g. inner_ring, outer_ring), or set "
                             "operation.T_C to prescribe the contact temperature")
        nd = nodes[node]
        kept = {k: v for k, v in nd.items() if k in ("description", "measured_by", "source")}
        kept["T_C"] = float(T)
        kept["source"] = "imposed by the scene (thermal.fixed_C)"
        nodes[node] = kept


def network_spec(scene: Scene) -> dict:
    """The scene's thermal network table with ``[thermal.parameters]`` overrides applied.

    A key ``"<element or node name>.<parameter>"`` replaces that parameter (e.g.
    ``"bearing_to_ambient.G_W_K" = 0.8``, ``"oil_stream.beta" = 0.5``); a key without a dot is a
    context value the network reads as ``scene.<key>``.  Nodes named in ``scene.T_fixed_C`` become
    fixed-temperature nodes at the imposed (measured) temperature.  Returns a fresh copy (the caller
    may modify it).
    """
    import copy
    return copy.deepcopy(_network_spec_shared(scene))


_SPECS: dict = {}


def _network_spec_shared(scene: Scene) -> dict:
    """:func:`network_spec`, cached per network file (resolved path and modification time), imposed
    temperatures and parameter overrides; the returned table is shared and never modified (the
    network builder then checks its structure once: ``load_network(..., _frozen=True)``)."""
    from pathlib import Path

    name = str(scene.network)
    if scene.path is None and not Path(name).is_absolute() and name not in _bundled_networks():
        path = Path(name).resolve()            # relative to the working directory: resolved at every call
    else:
        path = _network_path(name, scene.path)
    try:
        stamp = path.stat().st_mtime_ns
    except OSError:
        return _network_spec_new(scene)      # raises the "unknown network" message
    key = (str(path), stamp, repr(sorted(scene.T_fixed_C.items())),
           repr(sorted(scene.network_parameters.items())))
    spec = _SPECS.get(key)
    if spec is None:
        spec = _network_spec_new(scene)
        if len(_SPECS) > 64:
            _SPECS.clear()
        _SPECS[key] = spec
    return spec


@__import__("functools").lru_cache(maxsize=1)
def _bundled_networks() -> frozenset:
    from thermobear.thermal.network import network_names
    return frozenset(network_names())


@__import__("functools").lru_cache(maxsize=64)
def _network_path(name: str, scene_path):
    """Resolved file of a bundled network name or of a path (absolute, or relative to the scene file)."""
    from pathlib import Path

    from thermobear.files import data_dir
    if name in _bundled_networks():
        return (data_dir("networks") / f"{name}.toml").resolve()
    path = Path(name)
    if scene_path and not path.is_absolute():
        path = Path(scene_path).resolve().parent / path
    return path.resolve()


def _network_spec_new(scene: Scene) -> dict:
    import copy
    from pathlib import Path

    from thermobear.files import data_dir, read_toml
    from thermobear.thermal.network import network_names
    name = str(scene.network)
    if name in network_names():
        path = data_dir("networks") / f"{name}.toml"
    else:
        path = Path(name)
        if scene.path and not path.is_absolute():
            path = Path(scene.path).resolve().parent / path
        if not path.is_file():
            raise InputError("thermal.network", name, f"unknown network; known: {', '.join(network_names())} "
                             "or a path to a .toml file")
    spec = copy.deepcopy(read_toml(str(path.resolve())))   # the file as it is now (read_toml re-reads an edited file)
    _impose_temperatures(spec, scene.T_fixed_C, name)
    for key, val in scene.network_parameters.items():
        if "." not in key:
            continue
        target, param = key.rsplit(".", 1)
        hits = [e for e in spec.get("elements", []) if e.get("name") == target]
        if target in spec.get("nodes", {}):
            hits.append(spec["nodes"][target])
        if not hits:
            known = [e.get("name") for e in spec.get("elements", [])] + list(spec.get("nodes", {}))
            raise InputError(f"thermal.parameters.{key}", val, f"no element or node '{target}' in network "
                             f"{name}; known: {', '.join(str(k) for k in known)}")
        for h in hits:
            if param not in h:
                raise InputError(f"thermal.parameters.{key}", val,
                                 f"'{target}' has no parameter '{param}'; it has: {', '.join(sorted(h))}")
            h[param] = val
    return spec


def _roles(net) -> dict:
    roles = {}
    for role, cands in _ROLES.items():
        for c in cands:
            if c in net.index and not net.fixed[net.index[c]]:
                roles[role] = c
                break
        else:
            raise InputError(f"network {net.name}", role, f"has no node for the role '{role}' (tried {', '.join(cands)})")
    return roles


@dataclass
class SteadyState:
    """Coupled steady state of a scene.

    Attributes
    ----------
    T_C : dict                node → temperature [°C]
    T_ball_C : float          ball temperature [°C]
    P_W : float               total power loss [W]
    losses : LossResult       losses at equilibrium
    iterations : int          fixed-point iterations
    residual_K : float        last temperature change [K]
    energy_balance_W : float  Σ sources − Σ heat to fixed nodes [W]
    heat_flows_W : dict       element → heat flow [W]
    models_used : dict        model → (choice, reason)
    history : list            convergence history
    """

    T_C: dict
    T_ball_C: float
    P_W: float
    losses: LossResult
    iterations: int
    residual_K: float
    energy_balance_W: float
    heat_flows_W: dict
    models_used: dict
    history: list = field(default_factory=list)
    roles: dict = field(default_factory=dict)


def _contact_temps(T_C: dict, roles: dict):
    """Contact temperatures = mean of ball and race nodes (seed 004 §4.5), oil = the oil–air node;
    clipped to the lubricant correlations' validity so that an iterate beyond it stays defined
    (an equilibrium there is reported as runaway: ``_T_LIMIT_C``)."""
    from thermobear.lubrication.lubricant import T_VALID_C
    lo, hi = T_VALID_C
    Tb = T_C[roles["ball"]]
    clip = lambda v: min(max(v, lo), hi)  # noqa: E731
    return clip(0.5 * (Tb + T_C[roles["inner"]])), clip(0.5 * (Tb + T_C[roles["outer"]])), clip(T_C[roles["oil"]])


def _setup_thermal(scene: Scene, models: dict, contacts: ContactSet | None = None):
    from thermobear.thermal import load_network
    if contacts is not None:
        import dataclasses
        contacts = dataclasses.replace(contacts, models_used={
            **contacts.models_used, "load_distribution": ("injected", "contacts prepared by the caller")})
    cs = contacts if contacts is not None else scene_contacts(scene, models)
    # contact semi-axes for the contact conductances (temperature independent: rigid rings)
    contacts = {s: {"a_m": np.asarray(cs.sides[s]["a"], float), "b_m": np.asarray(cs.sides[s]["b"], float)}
                for s in ("inner", "outer")}
    net = load_network(_network_spec_shared(scene), network_context(scene, contacts), _frozen=True)
    return net, cs, _roles(net)


def _sources(scene, models, cs, roles, T_C: dict):
    """Heat sources [W] per node and the losses, at node temperatures ``T_C`` [°C]."""
    return _sources_c(scene, models, cs, roles, *_contact_temps(T_C, roles))


def _sources_c(scene, models, cs, roles, Ti, To, Toil):
    """Heat sources [W] per node and the losses, at contact and oil temperatures [°C]."""
    from thermobear.lubrication.lubricant import T_VALID_C
    from thermobear.thermal import split_losses
    Ti, To, Toil = (min(max(float(v), T_VALID_C[0]), T_VALID_C[1]) for v in (Ti, To, Toil))
    if models["losses"][0] == "skf":
        r = skf_scene_losses(scene, 0.5 * (Ti + To), models)
        h = r.heat_W
        src = split_losses(2 * h["inner_ring"], 2 * h["outer_ring"], h["oil"], ball=roles["ball"],
                           inner=roles["inner"], outer=roles["outer"], oil=roles["oil"])
        return src, r
    r = scene_losses(scene, T_inner_C=Ti, T_outer_C=To, T_oil_C=Toil, T_C=Toil, models=models, contacts=cs)
    ci, co = r.contacts["inner"], r.contacts["outer"]
    Pi = ci["P_rolling"] + ci["P_sliding"] + ci["P_pivoting"] + ci["P_hysteresis"]
    Po = co["P_rolling"] + co["P_sliding"] + co["P_pivoting"] + co["P_hysteresis"]
    src = split_losses(Pi, Po, r.breakdown_W["drag"], ball=roles["ball"], inner=roles["inner"],
                       outer=roles["outer"], oil=roles["oil"])
    return src, r


def _sources_batch(scene, models, cs, roles):
    """:func:`_sources` for many node-temperature states at once (the output pass of a transient):
    ``fn(t_s, T_K)`` with ``T_K`` node → array over the states [K] returns (list of source dicts,
    report dict of arrays: P_W and P_<loss family> [W]); one vectorised loss evaluation."""
    from thermobear.lubrication.lubricant import T_VALID_C
    from thermobear.thermal import split_losses

    def fn(t_s, T_K):
        lo, hi = T_VALID_C
        Tb = np.asarray(T_K[roles["ball"]], float) - 273.15
        Ti = np.clip(0.5 * (Tb + (np.asarray(T_K[roles["inner"]], float) - 273.15)), lo, hi)
        To = np.clip(0.5 * (Tb + (np.asarray(T_K[roles["outer"]], float) - 273.15)), lo, hi)
        Toil = np.clip(np.asarray(T_K[roles["oil"]], float) - 273.15, lo, hi)
        # the states as leading temperature axes of the one operating point
        r = scene_losses(scene, T_inner_C=Ti, T_outer_C=To, T_oil_C=Toil, T_C=Toil, models=models, contacts=cs)
        ci, co = r.contacts["inner"], r.contacts["outer"]
        Pi = ci["P_rolling"] + ci["P_sliding"] + ci["P_pivoting"] + ci["P_hysteresis"]
        Po = co["P_rolling"] + co["P_sliding"] + co["P_pivoting"] + co["P_hysteresis"]
        drag = np.broadcast_to(r.breakdown_W["drag"], Tb.shape)
        srcs = [split_losses(Pi[k], Po[k], drag[k], ball=roles["ball"], inner=roles["inner"],
                             outer=roles["outer"], oil=roles["oil"]) for k in range(Tb.size)]
        rep = {"P_W": np.broadcast_to(r.P_W, Tb.shape).astype(float),
               **{f"P_{n}": np.broadcast_to(v, Tb.shape).astype(float) for n, v in r.breakdown_W.items()}}
        return srcs, rep
    return fn


def _coupled_of(T_K, net, roles):
    """(inner contact, outer contact, oil) temperatures [K] from all node temperatures [K]."""
    ix = net.index
    Tb = T_K[ix[roles["ball"]]]
    return np.array([0.5 * (Tb + T_K[ix[roles["inner"]]]), 0.5 * (Tb + T_K[ix[roles["outer"]]]), T_K[ix[roles["oil"]]]])


def _coupling_matrices(net, roles):
    """C (3 × n_free): coupled temperatures (inner contact, outer contact, oil) = C T_free; S (n_free × 3):
    free-node sources = S (P_inner contacts, P_outer contacts, P_drag) (½ ball, ½ race; drag to the oil)."""
    ix, free = net.index, ~net.fixed
    nf = int(free.sum())
    fpos = -np.ones(len(net.nodes), int)
    fpos[free] = np.arange(nf)
    b, i, o, oil = (fpos[ix[roles[k]]] for k in ("ball", "inner", "outer", "oil"))
    C = np.zeros((3, nf))
    C[0, b] += 0.5
    C[0, i] += 0.5
    C[1, b] += 0.5
    C[1, o] += 0.5
    C[2, oil] += 1.0
    S = np.zeros((nf, 3))
    S[b, 0] += 0.5
    S[b, 1] += 0.5
    S[i, 0] += 0.5
    S[o, 1] += 0.5
    S[oil, 2] += 1.0
    return C, S


def _losses_and_slopes(scene, models, cs2, x_K, h=0.05):
    """Losses P = (inner contacts, outer contacts, drag) [W] at the coupled temperatures x [K] and
    ∂P/∂x [W/K] (forward differences, step h [K]).  Each part depends on its own temperature only
    (the inner contacts on x_inner, the outer contacts on x_outer, drag on x_oil), so ∂P/∂x is
    diagonal and one vectorised evaluation at two temperature triplets, x and x + h (all three
    stepped at once: temperatures of shape (2,) in front of the contacts' operating point ``cs2``),
    gives all of it (:func:`thermobear.losses.evaluate_losses` reads T_inner for the inner contacts,
    T_outer for the outer ones and T_oil for drag only; a loss model that couples them needs the
    differences one temperature at a time again — tests/test_thermal_fast_paths.py checks the two agree).
    Temperatures are held in the lubricant's validity range, as :func:`_sources_c` does."""
    from thermobear.lubrication.lubricant import T_VALID_C
    lo, hi = T_VALID_C[0] + 273.15, T_VALID_C[1] + 273.15
    x = np.asarray(x_K, float)
    X = np.clip(np.column_stack((x, x + h)), lo, hi) - 273.15          # 3 × 2 [°C]
    r = scene_losses(scene, T_C=X[2], T_inner_C=X[0], T_outer_C=X[1], T_oil_C=X[2], models=models, contacts=cs2)
    Pm = np.vstack([r.contact_W["inner"], r.contact_W["outer"],
                    np.broadcast_to(r.breakdown_W["drag"], (2,))])                     # 3 × 2 [W]
    return Pm[:, 0], np.diag((Pm[:, 1] - Pm[:, 0]) / h)


def _newton_coupled(scene, models, net, roles, cs2, tol_K, T_limit_K, maxiter=30, h=0.05, T0_K=None):
    """Newton on the free-node temperatures T_f of the network coupled with the losses [K].

    Residual (heat balance of each free node) [W] and its Jacobian:

        R(T_f) = A_ff(T) T_f + A_fb(T) T_b − S P(x),   x = C T_f
        ∂R/∂T_f = A_ff + ∂A/∂T·T − S (∂P/∂x) C

    with x the three coupled temperatures (inner contact, outer contact — each the mean of ball and
    race — and oil), P = (inner contacts, outer contacts, drag) [W] and S their split onto the nodes
    (½ ball, ½ race; drag to the oil).  P and its diagonal ∂P/∂x come from one vectorised loss
    evaluation at x and x + h (:func:`_losses_and_slopes`; ``cs2``: the contacts of the operating point);
    ∂A/∂T·T from forward differences
    of the temperature-dependent conductances (convection with fluid properties, radiation),
    re-evaluated while the steps exceed 1 K and then kept (a small, slowly varying part of the
    Jacobian: the loss slopes and the conductances themselves are fresh at every iterate), so the
    iteration converges quadratically to superlinearly (5–7 iterations from ambient).  Stops when the Newton step max |ΔT_f| ≤ tol_K (the step is
    taken: the remaining error is of the order of the step squared).  The loop gain is the largest
    real eigenvalue of dG/dx = C A_ff⁻¹ S ∂P/∂x (the losses through the network at the current
    conductances, as :func:`thermobear.coupled.fixedpoint.loop_gain` measures it).  Returns (x, T_nodes, iters,
    residual, loop_gain, history) or None when it cannot decide (the caller then uses Anderson)."""
    from thermobear.thermal.solve import _dense_solve, _max_real_eigenvalue, _plan
    plan = _plan(net)
    free, fixed = ~net.fixed, net.fixed
    C, S = _coupling_matrices(net, roles)
    T = net.initial_T_K() if T0_K is None else np.where(net.fixed, net.T_fixed_K, T0_K)
    Tb = T[fixed]
    history = []
    dG, step_prev = None, np.inf
    for it in range(1, maxiter + 1):
        x = C @ T[free]
        P, dP = _losses_and_slopes(scene, models, cs2, x, h)
        if dG is None or step_prev > 1.0:
            G, dG = plan.dconductances(T, nodes=plan.free)  # only ∂/∂T_free enters Jr below
        else:                                           # small steps: the slopes of the last iterate
            G = plan.conductances(T)
        Aff, Afb = plan.blocks(G)
        if not isinstance(Aff, np.ndarray):
            Aff, Afb = Aff.toarray(), Afb.toarray()
        Tf = T[free]
        R = Aff @ Tf + Afb @ Tb - S @ P
        Jr = Aff + plan.dAT_free(T, dG) - S @ dP @ C
        dT = _dense_solve(Jr, -R)
        if dT is None or not np.isfinite(dT).all():
            return None
        step = float(np.abs(dT).max())
        # loop gain (an eigenvalue problem): at the first iterate, whenever the step does not shrink, and at
        # the answer — a converging sequence needs no runaway check in between
        if it == 1 or step >= step_prev or step <= tol_K:
            X = _dense_solve(Aff, S @ dP)
            if X is None:
                return None
            gain = _max_real_eigenvalue(C @ X)
            if not math.isfinite(gain):
                return None
        step_prev = step
        if step > 50.0:
            dT *= 50.0 / step
        dx = C @ dT
        history.append(dict(iteration=it, T_K=x.copy(), residual_K=step,
                            mean_residual_K=float(dx.sum() / dx.size), P_W=float(P.sum()), step="newton"))
        T = T.copy()
        T[free] = Tf + dT
        if step <= tol_K:
            return C @ T[free], T, it, step, gain, history
        if gain >= 1.0 or np.max(C @ T[free]) > T_limit_K:
            return None                                     # runaway suspected: the Anderson path decides
    return None


def _steady_film(scene, models, *, tol_K, method, tol_film_K=0.1, maxiter=10, **kw):
    """Steady state with the film load model: the loads depend on the film temperature, taken as the
    mean contact temperature of the solution — a fixed point on that one temperature (the loads vary
    slowly with it: a few updates), started from the dry solution's mean contact temperature, each
    update's Newton started from the last solution.  Drives :func:`_steady_film_steps`, solving each
    film load distribution it asks for on its own (a sweep batches them over its points)."""
    steps = _steady_film_steps(scene, models, tol_K=tol_K, method=method, tol_film_K=tol_film_K,
                               maxiter=maxiter, **kw)
    T_film = next(steps)
    while True:
        try:
            T_film = steps.send(film_scene_load(scene, models, T_film))
        except StopIteration as done:
            return done.value


def _steady_film_steps(scene, models, *, tol_K, method, tol_film_K=0.1, maxiter=10, **kw):
    """:func:`_steady_film` as a generator: yields each film temperature [°C] at which it needs the film
    load distribution, receives that distribution (``send``), and returns the steady state."""
    from thermobear.errors import NoConvergence
    # start: the dry solution's mean contact temperature (its loads are cached from the model choice;
    # the films change the power by a few to tens of per cent, the contact temperature by a few kelvin)
    from thermobear.errors import SolverError
    dry = {**models, "load_model": ("jones_harris", "start of the film fixed point")}
    try:
        st0 = steady_state(scene, tol_K=max(tol_K, 1e-3), contacts=scene_contacts(scene, dry), method=method,
                           **dict(kw))
        c0 = st0.losses.contacts
        T_ref = float(np.mean(np.concatenate([np.ravel(c0["inner"]["T_C"]), np.ravel(c0["outer"]["T_C"])])))
        start = st0.T_C
    except SolverError:             # no dry equilibrium to start from: the film model decides on its own
        T_ref, start = film_temperature_C(scene), None
    hist = []
    for k in range(1, maxiter + 1):
        load = yield T_ref                  # the film loads at T_ref (film_scene_load)
        cs = scene_contacts(scene, models, load=load)
        st = steady_state(scene, tol_K=tol_K, contacts=cs, method=method, _T_start_C=start, **kw)
        start = st.T_C                      # the next update starts from this solution (the loads moved a little)
        c = st.losses.contacts
        T_new = float(np.mean(np.concatenate([np.ravel(c["inner"]["T_C"]), np.ravel(c["outer"]["T_C"])])))
        hist.append(dict(iteration=k, T_film_C=T_ref, T_contacts_C=T_new, P_W=st.P_W))
        if abs(T_new - T_ref) <= tol_film_K:
            st.models_used["load_distribution"] = (
                "film in the contact law (" + ("high-speed, thermobear.loads.highspeed" if models["high_speed"][0] == "yes"
                                              else "low-speed, thermobear.loads.film") + ")",
                f"films at the mean contact temperature {T_ref:.2f} °C ({k} load updates from "
                f"{hist[0]['T_film_C']:.2f} °C)")
            st.history = list(st.history) + [dict(h, step="film") for h in hist]
            return st
        T_ref = T_new
    raise NoConvergence(f"film load model: the film temperature did not settle within {tol_film_K} K in {maxiter} "
                        f"load updates (last {hist[-2]['T_contacts_C']:.2f} → {hist[-1]['T_contacts_C']:.2f} °C)",
                        iterations=maxiter, residual=abs(hist[-1]["T_contacts_C"] - hist[-1]["T_film_C"]),
                        history=hist)


def steady_state(scene: Scene, *, tol_K: float = 1e-6, contacts: ContactSet | None = None,
                 method: str = "newton", **kw) -> SteadyState:
    """Coupled steady state: losses(T) ↔ thermal network, to a fixed point.

    The losses depend on three temperatures only — inner contact, outer contact (each the mean
    of ball and race, seed 004 §4.5) and oil–air mixture — so the fixed point is solved on those
    three.  ``method="newton"`` (default, local losses): Newton with a Jacobian from one vectorised
    loss evaluation at four temperature triplets and one sparse LU with four right-hand sides per
    iteration; its Jacobian gives the loop gain.  When Newton cannot decide (loop gain ≥ 1, a limit
    passed, divergence) or for the SKF losses, ``"anderson"``: Anderson mixing
    (:func:`thermobear.coupled.fixedpoint.solve_coupled`), each update one loss evaluation and one network solve
    linearised at the last iterate (the temperature-dependent conductances converge with the losses),
    with its runaway logic.  The returned state is a full
    network solve with the converged losses: its energy balance closes to machine precision and its
    coupled temperatures are checked against the fixed point.

    ``contacts`` injects a prepared :class:`~thermobear.losses.ContactSet` (e.g. from the high-speed
    load model) instead of the one the scene's models give.

    Raises ThermalRunaway or NoConvergence (with the history) when no stable equilibrium is found.

    >>> import thermobear as tb
    >>> st = steady_state(tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")))
    >>> bool(abs(st.energy_balance_W) <= 1e-9 * st.P_W), bool(st.T_C["inner_ring"] > 30.0)
    (True, True)
    """
    from thermobear.coupled.fixedpoint import solve_coupled
    from thermobear.errors import NoConvergence
    from thermobear.lubrication.lubricant import T_VALID_C
    from thermobear.thermal import solve_steady
    if method not in ("newton", "anderson"):
        raise InputError("method", method, "'newton' or 'anderson'")
    models = choose_models(scene)
    if scene.T_C is not None:
        raise InputError("operation.T_C", scene.T_C, "the scene prescribes its temperature: use solve() "
                         "or remove operation.T_C to solve the thermal network")
    if contacts is None and models["load_model"][0] == "film":
        return _steady_film(scene, models, tol_K=tol_K, method=method, **kw)
    net, cs, roles = _setup_thermal(scene, models, contacts)
    kw.setdefault("T_limit_K", T_VALID_C[1] + 273.15)      # beyond the lubricant's validity: runaway
    state = {"T": net.initial_T_K()}
    T0_K = kw.pop("_T_start_C", None)
    if T0_K is not None:          # a start: node → °C (e.g. the last film update's solution), nodes matched by name
        init = net.initial_T_K()
        T0_K = np.array([T0_K[nm] + 273.15 if nm in T0_K else init[i] for i, nm in enumerate(net.nodes)])
        state["T"] = np.where(net.fixed, net.T_fixed_K, T0_K)

    def sources_at(x_K):
        return _sources_c(scene, models, cs, roles, *(np.asarray(x_K) - 273.15))

    def update(x_K):
        src, r = sources_at(x_K)
        st = solve_steady(net, src, T_guess_K=state["T"], linearized=True)
        state["T"] = st.T_K
        return _coupled_of(st.T_K, net, roles), float(r.P_W)

    import warnings
    from thermobear.coupled.fixedpoint import CoupledResult
    from thermobear.errors import ExtrapolationWarning
    with warnings.catch_warnings():
        # intermediate iterates may overshoot beyond the correlations' data; only the answer is checked
        warnings.simplefilter("ignore", ExtrapolationWarning)
        nw = None
        if method == "newton" and models["losses"][0] == "local" and cs.batch == ():
            nw = _newton_coupled(scene, models, net, roles, cs, tol_K, kw["T_limit_K"], T0_K=T0_K)
        if nw is not None:
            x, state["T"], its, resid, gain, hist = nw
            res = CoupledResult(T_K=x, P_W=hist[-1]["P_W"], iterations=its, evaluations=its * 2,
                                residual_K=resid, energy_residual_rel=float("nan"), loop_gain=gain,
                                history=hist, method="newton")
        else:
            res = solve_coupled(update, _coupled_of(state["T"], net, roles), tol_K=tol_K, **kw)
    src, r = sources_at(res.T_K)
    st = solve_steady(net, src, T_guess_K=state["T"])
    T_C = dict(st.T_C)
    hot = {k: v for k, v in T_C.items() if v + 273.15 > kw["T_limit_K"]}
    if hot:
        node = max(hot, key=hot.get)
        raise ThermalRunaway(
            f"no equilibrium below {kw['T_limit_K'] - 273.15:g} °C (the lubricant's limit): the network cannot shed "
            f"{r.P_W:.4g} W even at that temperature ({node} would reach "
            f"{hot[node]:.4g} °C); more cooling, less speed or a thinner oil is needed",
            iterations=res.iterations, residual=res.residual_K, last=T_C, history=res.history)
    gap = float(np.max(np.abs(_coupled_of(st.T_K, net, roles) - res.T_K)))
    if gap > max(10 * tol_K, 1e-4):
        raise NoConvergence(f"coupled temperatures of the final network solve differ from the fixed point by "
                            f"{gap:.3g} K", iterations=res.iterations, residual=gap, last=T_C, history=res.history)
    used = dict(r.models_used)
    used["thermal"] = (f"network {net.name}", f"fixed point on 3 coupled temperatures: {res.method}, "
                                              f"{res.iterations} iterations, loop gain {res.loop_gain:.2f}")
    used["node_roles"] = (roles, "contact temperature = mean of ball and race nodes (seed 004 §4.5)")
    return SteadyState(T_C=T_C, T_ball_C=T_C[roles["ball"]], P_W=float(r.P_W), losses=r,
                       iterations=res.iterations, residual_K=max(res.residual_K, gap),
                       energy_balance_W=float(st.balance_W),
                       heat_flows_W={k: f.Q_W for k, f in st.flows.items()},
                       models_used=used, history=res.history, roles=roles)


@dataclass
class TransientRun:
    """Heat-up of a scene.

    Attributes
    ----------
    t_s : ndarray            times [s]
    T_C : dict               node → temperatures [°C] (arrays over t_s)
    P_W : ndarray            total power loss [W]
    breakdown_W : dict       loss family → power [W] over t_s
    models_used : dict       model → (choice, reason) of the first segment; "schedule" lists the choices
                             that later schedule steps change (e.g. the film load model from a radial step)
    """

    t_s: np.ndarray
    T_C: dict
    P_W: np.ndarray
    breakdown_W: dict
    models_used: dict
    roles: dict = field(default_factory=dict)


_FILM_DT0_S = 20.0      # first piece of a film-load-model transient [s]
_FILM_DRIFT_K = 2.0     # film-temperature drift per piece [K] (loads re-solved at each piece's start)


def _film_temperature_of(T_state, roles, scene) -> float:
    """Mean contact temperature [°C] (ball with each race, seed 004 §4.5) of a transient state; a
    scalar state (the start) is that temperature."""
    if not isinstance(T_state, dict) or roles is None:
        return float(T_state) if np.ndim(T_state) == 0 else film_temperature_C(scene)
    Tb = T_state.get(roles["ball"], np.nan)
    Ti, To = T_state.get(roles["inner"], np.nan), T_state.get(roles["outer"], np.nan)
    T = 0.25 * (2.0 * Tb + Ti + To)
    return float(T) if np.isfinite(T) else film_temperature_C(scene)


def transient(scene: Scene, t_end_s: float, *, schedule=None, T0_C=None, t_eval=None, rtol: float = 1e-5,
              atol: float = 1e-3, contacts: ContactSet | None = None, **kw) -> TransientRun:
    """Heat-up of a scene on its thermal network, losses re-evaluated as temperatures change.

    Parameters
    ----------
    scene : Scene
    t_end_s : float          end time [s]
    schedule : list          optional steps ``[(t_s, {"n_rpm": ..., "Fa": ..., ...}), ...]`` applied
                             from t_s on (scene.with_ overrides)
    T0_C : float or dict     start temperature of the free nodes (default: ambient)
    t_eval : array_like      output times [s]
    rtol, atol : float       BDF tolerances (atol in K).  The defaults keep the seed 004 heat-up
                             (3600 s) within 5 mK and the power within 1e-4 of a rtol = 1e-8 solution
                             (measured; tests/test_solver.py pins it) — two orders below a
                             thermocouple's accuracy; tighten them for numerical studies
    contacts : ContactSet    inject prepared contacts (one operating point: no schedule)

    With ``models.load_model = "film"`` the loads depend on the film temperature: each segment is
    run in pieces, the loads re-solved at the start of each at its mean contact temperature, the
    pieces sized for ≈ 2 K of drift (20 s first, then ×½ … ×4).
    """
    from thermobear.thermal import solve_transient
    if not (np.isfinite(t_end_s) and t_end_s > 0):
        raise InputError("t_end_s", t_end_s, "end time must be > 0 [s]")
    steps = sorted(schedule or [], key=lambda s: s[0])
    scenes = [(0.0, scene)]
    for t, ch in steps:
        if not (0 <= t < t_end_s):
            raise InputError("schedule.t_s", t, f"step times must lie in [0, {t_end_s}) s")
        scenes.append((float(t), scenes[-1][1].with_(**ch)))
    if contacts is not None and steps:
        raise InputError("contacts", "ContactSet", "injected contacts hold one operating point: no schedule")
    from thermobear.lubrication.lubricant import T_VALID_C
    T_lim_C = T_VALID_C[1]
    if t_eval is not None:
        t_eval = np.asarray(t_eval, float)
        if t_eval.ndim != 1 or np.any(~np.isfinite(t_eval)) or np.any((t_eval < 0) | (t_eval > t_end_s)) \
                or np.any(np.diff(t_eval) <= 0):
            raise InputError("t_eval", t_eval, f"output times must increase within [0, {t_end_s}] s")
    # one network per segment: a step may change boundary temperatures, oil flow, speed-dependent
    # convection and contact ellipses, not only the losses
    bounds = [t for t, _ in scenes] + [float(t_end_s)]
    T_state = scene.T_ambient_C if T0_C is None else T0_C
    out_t, out_T, out_rep = [], {}, {}
    first = None
    seg_changes: dict = {}          # schedule step time [s] → model choices that differ from the first segment's
    seg_seen: set = set()
    # pieces of the run: one per schedule segment; with the film load model a segment is cut into pieces
    # whose film temperature (the mean contact temperature at the piece's start) drifts by ≈ _FILM_DRIFT_K
    pieces = [(ts, bounds[k + 1], sc, k == len(scenes) - 1) for k, (ts, sc) in enumerate(scenes)
              if bounds[k + 1] > ts]
    film_dt = None
    i = -1
    while i + 1 < len(pieces):
        i += 1
        ts, te, sc, last_seg = pieces[i]
        models = choose_models(sc)
        film = contacts is None and models["load_model"][0] == "film"
        if film:
            T_film = _film_temperature_of(T_state, first[1] if first else None, sc)
            film_dt = min(_FILM_DT0_S, te - ts) if film_dt is None else film_dt
            if ts + film_dt < te - 1e-9 * te:
                pieces.insert(i + 1, (ts + film_dt, te, sc, last_seg))
                te, last_seg = ts + film_dt, False
            cs_film = scene_contacts(sc, models, T_film_C=T_film)
            net, cs, roles = _setup_thermal(sc, models, cs_film)
        else:
            net, cs, roles = _setup_thermal(sc, models, contacts)
        first = first or (models, roles, list(net.nodes))
        changed = {k: v for k, v in models.items() if first[0].get(k, (None,))[0] != v[0]}
        if changed and id(sc) not in seg_seen:         # once per schedule segment (not per film piece)
            seg_seen.add(id(sc))
            seg_changes[ts] = changed
        if list(net.nodes) != first[2]:
            raise InputError("schedule", ts, "a step may not change the thermal network's nodes")

        def sources(t, T_K, sc=sc, models=models, cs=cs, roles=roles):
            T_C = {n: v - 273.15 for n, v in T_K.items()}
            src, r = _sources(sc, models, cs, roles, T_C)
            return src, {"P_W": float(r.P_W), **{f"P_{n}": float(v) for n, v in r.breakdown_W.items()}}

        if contacts is None and models["losses"][0] == "local" and cs.batch == ():
            sources._batch = _sources_batch(sc, models, cs, roles)

        if t_eval is None:
            seg = None
        else:     # points in [ts, te) belong to this segment (right-continuous at steps); te closes it
            want = t_eval[(t_eval >= ts) & ((t_eval < te) | (last_seg & (t_eval <= te)))]
            seg = np.union1d(want - ts, [te - ts])
        tr = solve_transient(net, sources, te - ts, T0_C=T_state, t_eval=seg, rtol=rtol, atol=atol, **kw)
        t_abs = np.asarray(tr.t) + ts
        keep = np.ones(t_abs.size, bool)
        if t_eval is not None:
            keep = np.isin(np.round(t_abs, 9), np.round(t_eval, 9))
        if not last_seg:
            keep &= t_abs < te                    # the step's instant is reported by the next segment
        out_t.append(t_abs[keep])
        for n, v in tr.T_C.items():
            out_T.setdefault(n, []).append(np.asarray(v)[keep])
        for n, v in tr.report.items():
            out_rep.setdefault(n, []).append(np.asarray(v, float)[keep])
        T_state = {n: float(np.asarray(v)[-1]) for n, v in tr.T_C.items() if n in net.free_nodes}
        if film:       # next piece: as long as gives ≈ _FILM_DRIFT_K of film-temperature drift (×½ … ×4)
            drift = abs(_film_temperature_of(T_state, roles, sc) - T_film)
            film_dt = (te - ts) * float(np.clip(_FILM_DRIFT_K / max(drift, 1e-9), 0.5, 4.0))
        hot = {n: v for n, v in T_state.items() if v > T_lim_C}
        if hot:
            node = max(hot, key=hot.get)
            raise ThermalRunaway(f"the heat-up passes the lubricant's limit {T_lim_C:g} °C ({node} at "
                                 f"{hot[node]:.4g} °C by t = {te:g} s): no equilibrium the bearing could run at",
                                 iterations=0, last=T_state)
    cat = lambda parts: np.concatenate(parts) if parts else np.zeros(0)  # noqa: E731
    rep = {n: cat(v) for n, v in out_rep.items()}
    P = rep.get("P_W", np.zeros(0))
    bd = {n[2:]: v for n, v in rep.items() if n.startswith("P_") and n != "P_W"}
    used = dict(first[0])
    if seg_changes:
        used["schedule"] = ("models change with the schedule", "; ".join(
            f"from t = {t:g} s: " + ", ".join(f"{k} {v[0]} ({v[1]})" for k, v in ch.items())
            for t, ch in sorted(seg_changes.items())))
    return TransientRun(t_s=cat(out_t), T_C={n: cat(v) for n, v in out_T.items()}, P_W=P, breakdown_W=bd,
                        models_used=used, roles=first[1])


@dataclass
class RunResult:
    """What ``thermobear run`` reports."""

    scene: Scene
    P_W: float
    torque_Nm: float
    breakdown_W: dict
    T_C: dict
    models_used: dict
    losses: LossResult
    steady: SteadyState | None = None

    def as_dict(self) -> dict:
        r = self.losses
        d = {"scene": self.scene.name, "bearing": self.scene.bearing.name, "n_rpm": self.scene.n_rpm,
             "Fa_N": self.scene.Fa, "Fr_N": self.scene.Fr, "T_C": self.T_C, "P_W": self.P_W,
             "torque_Nm": self.torque_Nm, "breakdown_W": self.breakdown_W,
             "models_used": {k: {"choice": v[0], "reason": v[1]} for k, v in self.models_used.items()},
             }
        if r.contacts:
            d["balls"] = {"Q_inner_N": r.contacts["inner"]["Q"], "Q_outer_N": r.contacts["outer"]["Q"],
                          "alpha_deg": np.rad2deg(r.contacts["inner"]["alpha"]),
                          "regime_inner": r.contacts["inner"]["regime"], "regime_outer": r.contacts["outer"]["regime"]}
        if self.steady is not None:
            d["solver"] = {"iterations": self.steady.iterations, "residual_K": self.steady.residual_K,
                           "energy_balance_W": self.steady.energy_balance_W}
        return d

    def summary(self) -> str:
        s = self.scene
        lines = [f"thermobear — {s.name}: {s.bearing.name}, {s.n_rpm:g} rpm, Fa {s.Fa:g} N, Fr {s.Fr:g} N, "
                 f"{s.lubricant.name} ({s.supply})", "", "Temperatures [°C]"]
        for k, v in self.T_C.items():
            lines.append(f"  {k:18s} {v:8.2f}" + ("   imposed (thermal.fixed_C)" if k in s.T_fixed_C else ""))
        lines += ["", f"Power loss {self.P_W:.3f} W   (friction torque {self.torque_Nm * 1e3:.2f} N mm)"]
        for k, v in self.breakdown_W.items():
            share = 100 * v / self.P_W if self.P_W > 0 else 0.0
            lines.append(f"  {k:12s} {v:10.4f} W  {share:5.1f} %")
        lines += ["", "Models used"]
        for k, v in self.models_used.items():
            if k == "node_roles":
                continue
            lines.append(f"  {k:18s} {str(v[0]):40s} {v[1]}")
        if self.steady is not None:
            lines += ["", f"Fixed point: {self.steady.iterations} iterations, residual {self.steady.residual_K:.1e} K, "
                          f"energy balance {self.steady.energy_balance_W:.1e} W"]
        return "\n".join(lines)


def solve(scene: Scene) -> RunResult:
    """Run a scene with the least model it needs (thermal network only when temperatures are not given)."""
    models = choose_models(scene)
    if scene.T_C is not None:
        r = (skf_scene_losses(scene, scene.T_C, models) if models["losses"][0] == "skf"
             else scene_losses(scene, models=models))
        return RunResult(scene=scene, P_W=float(r.P_W), torque_Nm=float(r.torque_Nm),
                         breakdown_W=dict(r.breakdown_W), T_C={"contacts (prescribed)": scene.T_C},
                         models_used=r.models_used, losses=r)
    st = steady_state(scene)
    return RunResult(scene=scene, P_W=st.P_W, torque_Nm=float(st.losses.torque_Nm),
                     breakdown_W=dict(st.losses.breakdown_W), T_C=st.T_C, models_used=st.models_used,
                     losses=st.losses, steady=st)
