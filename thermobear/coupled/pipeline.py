r"""Scene → loads → contacts, for one operating point or a family of them.

A **family** is a set of operating points (scenes) that share everything but numbers: the bearing,
lubricant, supply, network and model choices are the same, while speed, loads, moment, inlet and
ambient temperatures, oil flow, roughness, friction coefficients, imposed node temperatures, network
context values and drawn values (``Scene.samples``: the lubricant's and the network's estimated
values moved per point, :mod:`thermobear.coupled.uncertainty`) may differ.
A family is solved together: one batched load distribution, one batched contact set, one network
at B operating points (:mod:`thermobear.coupled.steady`).

The load step follows :func:`thermobear.models.choose_models`: the closed form (pure axial load,
Harris 2001 eq 7.36), the dry Jones–Harris distribution (low- or high-speed form, reusing the dry
solution the model choice computed), or the film load model at a film temperature.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from thermobear.arrays import take
from thermobear.contact.kinematics import entrainment_speed
from thermobear.errors import InputError, SolverError
from thermobear.loads import LoadDistribution, axial_contact_angle, load_distribution
from thermobear.loads.film import film_load_distribution
from thermobear.loads.highspeed import load_distribution_high_speed, load_distribution_high_speed_full
from thermobear.losses import ContactSet, prepare_contacts
from thermobear.models import DryRow, moments, plan, refuse_unloaded_thrust
from thermobear.scene import Scene

__all__ = ["Family", "families", "dry_loads", "film_temperature_C", "sampled_lubricant", "closed_form_axial", "stack_loads", "family_loads",
           "family_film_loads", "family_contacts", "stack_key", "stack_families", "concat_loads", "SWITCHED", "scene_load",
           "scene_contacts", "film_scene_load"]


def film_temperature_C(scene: Scene) -> float:
    """Temperature [°C] at which the film load model evaluates the films when the caller gives none:
    the prescribed T_C, else the oil inlet, else the ambient temperature (the steady state iterates it)."""
    for T in (scene.T_C, scene.T_oil_in_C, scene.T_ambient_C):
        if T is not None:
            return float(T)
    return 20.0


def closed_form_axial(brg, Fa) -> LoadDistribution:
    """Pure axial load, all balls equal: Harris 2001 eq 7.36 (radial/angular) or Q = Fa/Z (thrust);
    ``Fa`` [N] a number or an array (one load case each).

    A thrust bearing without axial load has no contact at all (its washers are not radially located
    and nothing presses the balls): NoEquilibrium, as the high-speed form says."""
    Fa_a = np.asarray(Fa, dtype=float)
    Z = brg.Z
    if brg.kind == "thrust" and not np.all(Fa_a > 0):
        refuse_unloaded_thrust(float(np.min(Fa_a)))
    psi = 2.0 * np.pi * np.arange(Z) / Z
    if brg.kind == "thrust" and brg.alpha0 >= np.pi / 2 - 1e-12:
        al = np.full(Fa_a.shape, np.pi / 2)
        Q = Fa_a / Z
        da = brg.A + (Q / brg.Kn()) ** (2.0 / 3.0)
    else:
        loaded = Fa_a > 0
        al = np.where(loaded, axial_contact_angle(brg, np.where(loaded, Fa_a, 1.0)),
                      0.0 if brg.kind == "deep_groove" else brg.alpha0)   # unloaded: as Jones–Harris reports
        Q = np.where(loaded, Fa_a / (Z * np.sin(np.where(loaded, al, 1.0))), 0.0)
        da = np.where(loaded, brg.A * np.cos(brg.alpha0) * np.tan(al), 0.0)
    dn = (Q / brg.Kn()) ** (2.0 / 3.0)
    full = np.multiply.outer(Q, np.ones(Z))
    per = (lambda v: np.multiply.outer(v, np.ones(Z)))  # noqa: E731
    sc = (lambda v: float(v) if np.ndim(v) == 0 else v)  # noqa: E731
    return LoadDistribution(delta_a=sc(da), delta_r=sc(0.0 * da), theta=sc(0.0 * da), Q_i=full, Q_o=full.copy(),
                            alpha_i=per(al), alpha_o=per(al), psi=psi, delta_n=per(dn), residual=0.0, iterations=0,
                            Fa=Fa_a, Fr=np.zeros_like(Fa_a), M=0.0)


def stack_loads(loads) -> LoadDistribution:
    """One batched load distribution (leading axis) from single-point ones of the same bearing."""
    first = loads[0]
    fields = {}
    for name in ("delta_a", "delta_r", "theta", "Q_i", "Q_o", "alpha_i", "alpha_o", "delta_n", "Fa", "Fr", "M",
                 "delta_z", "theta_y", "Fz", "My"):
        fields[name] = np.stack([np.asarray(getattr(ld, name), float) for ld in loads])
    fields["residual"] = max(float(np.max(ld.residual)) for ld in loads)
    fields["iterations"] = max(int(np.max(ld.iterations)) for ld in loads)
    fields["psi"] = first.psi
    return LoadDistribution(**fields)


def dry_loads(dry) -> LoadDistribution:
    """The batched dry load distribution of points whose model choice solved it (:class:`DryRow` s
    of one batch: one slice; otherwise stacked point by point)."""
    if all(isinstance(d, DryRow) for d in dry) and len({id(d.batch) for d in dry}) == 1:
        return take(dry[0].batch, np.array([d.row for d in dry]), dry[0].B)
    return stack_loads([d.load() if isinstance(d, DryRow) else d for d in dry])


def _dry_start(fam) -> tuple | None:
    """(LoadDistribution, HighSpeedExtras) of the family's points from the dry high-speed solutions their model
    choice solved (one batch), or None."""
    d = fam.dry
    if not (all(isinstance(r, DryRow) and r.extras is not None for r in d) and len({id(r.batch) for r in d}) == 1):
        return None
    rows = np.array([r.row for r in d])
    return take(d[0].batch, rows, d[0].B), take(d[0].extras, rows, d[0].B)


@dataclass(frozen=True)
class Family:
    """Operating points that share everything but numbers (see the module docstring).

    Attributes
    ----------
    scenes : tuple           the B scenes
    index : tuple            their positions in the caller's list
    models : dict            the shared model choices (model → (choice, reason) of the first point)
    dry : tuple              per point, the dry load distribution the model choice solved
                             (:class:`~thermobear.models.DryRow`, a LoadDistribution or None)
    """

    scenes: tuple
    index: tuple
    models: dict
    dry: tuple

    @property
    def B(self) -> int:
        return len(self.scenes)

    @property
    def scene(self) -> Scene:
        """The first point (everything shared is read from it)."""
        return self.scenes[0]

    def values(self, attr) -> np.ndarray:
        """(B,) array of a per-point scene value (None → NaN)."""
        return np.array([np.nan if getattr(s, attr) is None else getattr(s, attr) for s in self.scenes], float)

    def samples(self, prefix: str = "") -> dict:
        """Drawn values per point (:attr:`Scene.samples`) whose address starts with ``prefix``: address →
        (B,) array (the points of a family share the addresses)."""
        return {k: np.array([s.samples[k] for s in self.scenes], float)
                for k in self.scene.samples if k.startswith(prefix)}

    @property
    def lubricant(self):
        """The family's lubricant: the scenes' own, with its drawn values (``lubricant.<key>``) per point
        (:meth:`thermobear.lubrication.lubricant.Lubricant.sampled`)."""
        return sampled_lubricant(self.scenes)

    def loads(self) -> dict:
        """The points' loads as the load solvers take them: Fa, Fr, M, Fz, My, (B,) arrays (M, My: None when
        the tilts are held, :func:`thermobear.models.moments`)."""
        out = {k: self.values(k) for k in ("Fa", "Fr", "Fz")}
        held = moments(self.scene)[0] is None
        for i, k in enumerate(("M", "My")):
            out[k] = None if held else np.array([moments(s)[i] for s in self.scenes], float)
        return out


def sampled_lubricant(scenes):
    """The lubricant of scenes that draw the same keys (a family, a group of uncertainty samples): the first
    one's, with each scene's drawn values (``lubricant.<key>`` of :attr:`Scene.samples`) per point
    (:meth:`thermobear.lubrication.lubricant.Lubricant.sampled`); the scenes' own where nothing is drawn."""
    keys = [k for k in scenes[0].samples if k.startswith("lubricant.")]
    if not keys:
        return scenes[0].lubricant
    return scenes[0].lubricant.sampled({k[len("lubricant."):]: np.array([s.samples[k] for s in scenes], float)
                                        for k in keys})


def _key(scene: Scene, models: dict):
    """What a family shares: every choice, the bearing and lubricant objects, the network, the names
    of imposed nodes and context values, the element overrides and every non-numeric scene value."""
    params = scene.network_parameters
    return (id(scene.bearing), id(scene.lubricant), scene.supply, scene.network, scene.path, scene.rotating,
            moments(scene)[0] is None, scene.T_C is None, scene.T_oil_in_C is None, tuple(sorted(scene.samples)),
            tuple(sorted(scene.T_fixed_C)),
            tuple(sorted((k, v if "." in k else None) for k, v in params.items())),
            tuple(sorted((k, repr(v)) for k, v in scene.models.items())),
            tuple(sorted((k, repr(v[0])) for k, v in models.items())))


def families(scenes, plans=None) -> tuple:
    """Group operating points into families.

    Parameters
    ----------
    scenes : list of Scene
    plans : list            per scene ``(models, dry)`` (:func:`thermobear.models.plan_many`) or an
                            exception; default: planned one by one

    Returns
    -------
    (list of Family, dict index → exception)  the points whose model choice failed apart
    """
    plans = plans if plans is not None else [plan(s) for s in scenes]
    groups: dict = {}
    failed = {}
    for i, (sc, p) in enumerate(zip(scenes, plans)):
        if isinstance(p, Exception):
            failed[i] = p
            continue
        groups.setdefault(_key(sc, p[0]), []).append((i, sc, p))
    fams = [Family(scenes=tuple(m[1] for m in members), index=tuple(m[0] for m in members),
                   models=members[0][2][0], dry=tuple(m[2][1] for m in members)) for members in groups.values()]
    return fams, failed


def _film_inputs(scene: Scene, n_rpm, T_film_C, lubricant=None):
    """Entrainment speed [m/s] (at the nominal angle), viscosity [Pa s] and α_p [1/Pa] of the films
    (of ``lubricant``, default the scene's)."""
    b, lub = scene.bearing, scene.lubricant if lubricant is None else lubricant
    w = np.asarray(n_rpm, float) * np.pi / 30.0
    wi, wo = (w, 0.0 * w) if scene.rotating == "inner" else (0.0 * w, w)
    u = np.maximum(np.asarray(entrainment_speed(wi, wo, b.D, b.dm, b.alpha0), float), 1e-6)
    T = np.asarray(T_film_C, float)
    return u, np.asarray(lub.eta(T), float), np.asarray(lub.alpha_p_at(T), float)


def film_loads(scene: Scene, models: dict, Fa, Fr, M, n_rpm, T_film_C, Fz=0.0, My=None, lubricant=None,
               start=None) -> LoadDistribution:
    """Film load model (:mod:`thermobear.loads.film`, or :mod:`thermobear.loads.highspeed` with
    ``film=`` in the high-speed form), films at ``T_film_C`` [°C]; arrays: one load case each
    (``lubricant`` per point: :attr:`Family.lubricant`; ``start``: a solution of these cases to start from,
    where the caller has one: the high-speed form's ``(LoadDistribution, HighSpeedExtras)``, the low-speed
    form's LoadDistribution, dry or with the film)."""
    return _film_loads(scene, models, Fa, Fr, M, n_rpm, T_film_C, Fz, My, lubricant, start)[0]


def _film_loads(scene, models, Fa, Fr, M, n_rpm, T_film_C, Fz, My, lubricant, start) -> tuple:
    """(:func:`film_loads`, the solution as ``start`` takes it)."""
    stiff = scene.models.get("stiffness", "nominal")
    u, eta, ap = _film_inputs(scene, n_rpm, T_film_C, lubricant)
    batch = np.ndim(Fa) > 0
    val = (lambda v: np.asarray(v, float)) if batch else float     # noqa: E731
    if models["high_speed"][0] == "yes":
        r = load_distribution_high_speed_full(scene.bearing, Fa=Fa, Fr=Fr, M=M, Fz=Fz, My=My, n_rpm=val(n_rpm),
                                              stiffness=stiff, film=dict(eta=val(eta), alpha_p=val(ap)), start=start,
                                              control=models["kinematics"][0])
        return r[0], r
    uu = u[:, None] if batch else float(u)
    ld = film_load_distribution(scene.bearing, Fa=Fa, Fr=Fr, M=M, Fz=Fz, My=My, u_i=uu, u_o=uu, eta=val(eta),
                                alpha_p=val(ap), stiffness=stiff, start=start)
    return ld, ld


def family_film_loads(fam: Family, T_film_C=None, start=None) -> tuple:
    """(the film load model's batched load distribution of a family, the solution as ``start`` takes it): films
    at ``T_film_C`` (B,) [°C] (default :func:`film_temperature_C`), from ``start`` (a batched solution of the same
    loads, e.g. at the last film temperatures; :func:`film_loads`), else from the dry solutions the model choice
    solved."""
    sc, m, F = fam.scene, fam.models, fam.loads()
    T = np.array([film_temperature_C(s) for s in fam.scenes]) if T_film_C is None else np.asarray(T_film_C, float)
    if start is None and m["high_speed"][0] == "yes":
        start = _dry_start(fam)
    elif start is None and all(isinstance(d, DryRow) for d in fam.dry):
        start = dry_loads(fam.dry)
    return _film_loads(sc, m, F["Fa"], F["Fr"], F["M"], fam.values("n_rpm"), T, F["Fz"], F["My"], fam.lubricant, start)


def family_loads(fam: Family, T_film_C=None) -> LoadDistribution:
    """The batched load distribution of a family (leading axis B) by its load model; ``T_film_C``
    (B,) [°C] the film temperatures of the film load model (:func:`family_film_loads`)."""
    sc, m = fam.scene, fam.models
    F = fam.loads()
    Fa, Fr, M, F5 = F["Fa"], F["Fr"], F["M"], dict(Fz=F["Fz"], My=F["My"])
    lm = m["load_model"][0]
    if lm == "closed_form":
        return closed_form_axial(sc.bearing, Fa)
    if lm == "film":
        return family_film_loads(fam, T_film_C)[0]
    if all(d is not None for d in fam.dry):
        return dry_loads(fam.dry)
    stiff = sc.models.get("stiffness", "nominal")
    if m["high_speed"][0] == "yes":
        return load_distribution_high_speed(sc.bearing, Fa=Fa, Fr=Fr, M=M, n_rpm=fam.values("n_rpm"), stiffness=stiff,
                                            control=m["kinematics"][0], **F5)
    # overloads are refused per point by coupled/limits.py (on the contact set), not for the whole batch
    return load_distribution(sc.bearing, Fa=Fa, Fr=Fr, M=M, stiffness=stiff, refuse_overload=False, **F5)


def family_contacts(fam: Family, load: LoadDistribution, centrifugal=None) -> ContactSet:
    """Temperature-independent contact data of a family (ellipses, kinematics), batch (B,); ``centrifugal``:
    one flag per point where the points' loads come from different forms (:func:`stack_families`), default
    the family's (F_c on the outer contacts unless the high-speed form put it in the ball equilibrium)."""
    sc, m = fam.scene, fam.models
    cf = m["high_speed"][0] != "yes" if centrifugal is None else centrifugal
    return prepare_contacts(sc.bearing, fam.values("Fa"), fam.values("Fr"), fam.values("n_rpm"),
                            M=None if sc.M is None else fam.values("M"), rotating=sc.rotating,
                            hertz_method=m["hertz"][0], centrifugal=cf, load=load, control=m["kinematics"][0])


#: The model choices in which the alternatives of a point across a switch band differ (:data:`~thermobear.models.
#: BLEND_BANDS`): families that differ only in these share contact model, losses and network, and are solved
#: stacked on the batch axis (:func:`stack_families`).
SWITCHED = ("high_speed", "load_model")


def stack_key(fam: Family):
    """What the families of one stacked solve share: everything of a family but the switched choices."""
    return _key(fam.scene, {k: v for k, v in fam.models.items() if k not in SWITCHED})


def stack_families(fams) -> tuple:
    """(one Family over the points of ``fams`` in order, (B,) flags of F_c on the outer contact): families of
    one :func:`stack_key`, each with its own loads, solved as one batch.  The stack's ``models`` are the
    first family's (the choices the families share are read from it; the switched ones are per family)."""
    if len(fams) == 1:
        f = fams[0]
        return f, f.models["high_speed"][0] != "yes"
    cf = np.concatenate([np.full(f.B, f.models["high_speed"][0] != "yes") for f in fams])
    return Family(scenes=sum((f.scenes for f in fams), ()), index=sum((f.index for f in fams), ()),
                  models=fams[0].models, dry=sum((f.dry for f in fams), ())), (bool(cf[0]) if cf.all() or not cf.any()
                                                                               else cf)


def concat_loads(loads, sizes) -> LoadDistribution:
    """One batched load distribution from batched ones (``sizes``: their batch sizes), along the batch axis; a
    field that is one number in a part (e.g. no moment) is repeated over its points."""
    if len(loads) == 1:
        return loads[0]
    out = {}
    for f in dataclasses.fields(LoadDistribution):
        vals = [getattr(ld, f.name) for ld in loads]
        if f.name == "psi":
            out[f.name] = vals[0]
        elif f.name in ("residual", "iterations"):
            out[f.name] = max(vals)
        elif all(v is None for v in vals):
            out[f.name] = None
        elif all(np.ndim(v) == 0 for v in vals) and len({float(v) for v in vals}) == 1:
            out[f.name] = vals[0]
        else:
            tail = next(np.shape(v)[1:] for v in vals if np.ndim(v) > 0)
            out[f.name] = np.concatenate([np.broadcast_to(np.asarray(v, float), (B,) + tail)
                                          for v, B in zip(vals, sizes)])
    return LoadDistribution(**out)


def _one(scene: Scene, models=None):
    """A one-point family of ``scene`` (models chosen unless given)."""
    if models is None:
        models, dry = plan(scene)
    else:
        dry = None
    return Family(scenes=(scene,), index=(0,), models=models, dry=(dry,))


def scene_load(scene: Scene, models: dict | None = None, T_film_C=None) -> LoadDistribution:
    """Load distribution of one scene by the model :func:`~thermobear.models.choose_models` picked
    (``T_film_C`` [°C]: temperature of the films for the ``"film"`` load model)."""
    fam = _one(scene, models)
    T = None if T_film_C is None else [float(T_film_C)]
    return take(family_loads(fam, T), 0, 1)


def film_scene_load(scene: Scene, models: dict, T_film_C, n_rpm=None) -> LoadDistribution:
    """Film load model of a scene, films at ``T_film_C`` [°C]; with arrays ``n_rpm`` [rpm] and/or
    ``T_film_C`` one batched solve over those operating points (loads of the scene)."""
    T = np.asarray(T_film_C, float)
    n = np.asarray(scene.n_rpm if n_rpm is None else n_rpm, float)
    M, My = moments(scene)
    if T.ndim == 0 and n.ndim == 0:
        return film_loads(scene, models, scene.Fa, scene.Fr, M, float(n), float(T), Fz=scene.Fz, My=My)
    n, T = (a.ravel() for a in np.broadcast_arrays(n, T))
    full = (lambda v: None if v is None else np.full(n.size, v))  # noqa: E731
    return film_loads(scene, models, full(scene.Fa), full(scene.Fr), full(M), n, T, Fz=full(scene.Fz), My=full(My))


def scene_contacts(scene: Scene, models: dict | None = None, load: LoadDistribution | None = None,
                   n_rpm=None, T_film_C=None) -> ContactSet:
    """Temperature-independent contact data of a scene (loads, ellipses, kinematics).

    ``n_rpm`` may override the scene's speed with an array (one operating point each, the loads of
    the scene: a prescribed-temperature sweep); ``T_film_C``: see :func:`scene_load`."""
    models = models if models is not None else plan(scene)[0]
    if load is None and models["load_model"][0] == "film" and n_rpm is not None and np.ndim(n_rpm):
        raise InputError("models.load_model", "film", "the film load model takes one speed per call (no speed "
                         "arrays): sweep the scenes one by one")
    load = load if load is not None else scene_load(scene, models, T_film_C=T_film_C)
    n = scene.n_rpm if n_rpm is None else n_rpm
    return prepare_contacts(scene.bearing, scene.Fa, scene.Fr, n, M=scene.M, rotating=scene.rotating,
                            hertz_method=models["hertz"][0], centrifugal=models["high_speed"][0] != "yes", load=load,
                            control=models["kinematics"][0])


def split_failures(fn, fam: Family, *args):
    """``fn(fam, *args)`` for a family; when it raises a SolverError / InputError for the whole batch,
    the family is halved until the failing points stand alone (arrays with a leading axis B and batched
    load distributions among ``args`` halved with it).  Returns [(sub-family, result or exception)]."""
    try:
        return [(fam, fn(fam, *args))]
    except (SolverError, InputError) as exc:
        if fam.B == 1:
            return [(fam, exc)]
    h = fam.B // 2
    out = []
    for part in (slice(0, h), slice(h, fam.B)):
        sub = Family(scenes=fam.scenes[part], index=fam.index[part], models=fam.models, dry=fam.dry[part])
        sub_args = [a[part] if isinstance(a, np.ndarray) and a.shape[:1] == (fam.B,) else
                    take(a, np.arange(fam.B)[part], fam.B) if isinstance(a, (LoadDistribution, tuple)) else a
                    for a in args]
        out += split_failures(fn, sub, *sub_args)
    return out
