r"""The losses as heat sources of the thermal network, and the network at a family's operating points.

The losses of a bearing depend on a few temperatures only — the inner and the outer contact
temperature, each the mean of the ball and race nodes (seed 004 §4.5), the oil–air mixture
temperature (drag) and, where a scene has them, the bath (churning) and the cage (land friction)
temperatures.  A loss source gives, at these coupled temperatures x [°C] of B operating points, its
loss **parts** [W] — (inner contacts, outer contacts, drag) and, where chosen, churning, seal and cage
(:data:`PARTS`, :func:`loss_parts`); the network receives ½ of each contact loss at the ball node and
½ at the race node (Pouly et al. 2010), drag at the mixture node, churning at the bath, seal friction
at the seal (or the inner ring), cage losses at the cage (or the mixture) (:class:`Coupling`).  Two
sources:

* :class:`LocalSources` — the local contact model (:func:`thermobear.losses.evaluate_losses`);
  each part depends on its own temperature only (the inner contacts on x_inner, …; the seal on
  none), so ∂P/∂x is diagonal;
* :class:`SKFSources` — the SKF 2004 global model at the mean bearing temperature ½(x_inner +
  x_outer) (¼ of the contact losses to each race, ½ to the balls), its oil-bath drag (SKF 2018 form)
  as churning, its seal moment as the seal part.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import numpy as np

from thermobear.arrays import instance_of
from thermobear.errors import InputError
from thermobear.losses import ContactSet, LossResult, evaluate_losses
from thermobear.losses.cage import CageLand
from thermobear.losses.drag import cavity_oil_fraction
from thermobear.losses.seals import seal_friction
from thermobear.losses.skf import SKF_BREAKDOWN_KEYS, skf_friction
from thermobear.models import (added_losses, cage_land, film_options, oil_level, plan, refuse_unloaded_thrust,
                               replenishment_constant, seal_diameter_mm)
from thermobear.coupled.limits import overloads
from thermobear.coupled.pipeline import Family, scene_contacts
from thermobear.scene import Scene
from thermobear.scene.network import network_spec
from thermobear.thermal import ROLES, NetworkTemplate, ThermalNetwork, prepare_network
from thermobear.validity import T_LUBRICANT_REFUSE_C

__all__ = ["LocalSources", "SKFSources", "SKFLosses", "Coupling", "PARTS", "TEMPERATURES", "DEFAULT_PARTS",
           "loss_parts", "coupled_temperatures", "loss_sources", "network_template", "family_network",
           "network_context", "scene_losses", "skf_losses", "Prepared", "prepare", "prepared_for"]

_SKF_MU_EHL = {"mineral": "mineral", "PAO": "synthetic", "ester": "synthetic", "ester+vegetal": "synthetic"}
#: part → the loss family (``breakdown_W`` key) that a source reports for it (contact parts aside)
_PART_FAMILY = {"drag": "drag", "churning": "churning", "seal": "seal", "cage": "cage"}


def _clip(x_C):
    """Coupled temperatures [°C] held inside the lubricant's accepted range: an iterate may overshoot;
    an equilibrium beyond the limit is reported as runaway by the solver."""
    return np.clip(x_C, *T_LUBRICANT_REFUSE_C)


def _through_flow(fam: Family) -> np.ndarray:
    """(B,) oil flow through the bearing [m³/s]: the supplied jet flow × the share that enters it
    (``lubricant.jet_penetration``, seed 004 §4.5's β) — the W of Parker's oil fraction
    (:func:`thermobear.losses.drag.oil_volume_fraction_parker`)."""
    return fam.values("oil_flow") * fam.values("jet_penetration")


def _one(values: np.ndarray):
    """One float when every point shares the value, else the (B,) array."""
    return float(values[0]) if np.all(values == values[0]) else values


def _K_rs(fam: Family):
    """The family's replenishment constants [-] (:func:`~thermobear.models.replenishment_constant`: one float, or
    (B,) where the points differ; NaN for a supply without one, whose models do not read it)."""
    return _one(np.array([np.nan if k is None else k for k in (replenishment_constant(sc, fam.models)
                                                               for sc in fam.scenes)], float))


def _chosen(models: dict, key: str) -> bool:
    return bool(models.get(key, (False,))[0])


def _added_local(scenes, models: dict) -> dict:
    """:func:`~thermobear.losses.evaluate_losses` keywords of the churning, seal and cage terms the models
    chose, per point of ``scenes`` (one value when they share it)."""
    sc, kw = scenes[0], {}
    if _chosen(models, "churning"):
        kw["oil_level_m"] = _one(np.array([oil_level(s)[0] for s in scenes], float))
    if _chosen(models, "seals"):
        kw["seal_torque_Nm"] = _one(np.array([_seal(s).M_Nm for s in scenes], float))
    if _chosen(models, "cage"):
        land = cage_land(sc)[0]
        kw["cage"] = CageLand(mu_pocket=_one(np.array([s.mu_full_film for s in scenes], float)),
                              guide_rotates=sc.cage == f"{sc.rotating}_ring", **land)
    return kw


def _seal(scene: Scene):
    """The scene's seal friction (SKF 2004; :func:`thermobear.losses.seals.seal_friction`) at 1 rpm (its moment)."""
    b = scene.bearing
    return seal_friction(scene.seals, b.kind, b.outer_diameter * 1e3, seal_diameter_mm(scene)[0], 1.0, scene.seal_sides)


class LocalSources:
    """The local contact model as the network's heat sources (see the module docstring)."""

    diagonal = True

    def __init__(self, fam: Family, contacts: ContactSet):
        self.fam, self.contacts, self.lubricant = fam, contacts, fam.lubricant
        sc = fam.scene
        per = {k: _one(fam.values(k)) for k in ("Rq_ball", "Rq_ring", "mu_boundary", "mu_full_film")}
        per["K_rs"] = _K_rs(fam)
        per = {k: v if np.ndim(v) == 0 else v[:, None, None] for k, v in per.items()}   # per point: (B, 1, 1)
        self.kw = dict(supply=sc.supply, oil_flow_m3_s=_one(_through_flow(fam)), **per,
                       rolling_model=fam.models["rolling"][0], drag=bool(fam.models["drag"][0]),
                       **film_options(fam.models), **_added_local(fam.scenes, fam.models))
        self.parts_ = loss_parts(fam.models)
        temps = coupled_temperatures(self.parts_)
        self.k_bath = temps.index("bath") if "bath" in temps else 2
        self.k_cage = temps.index("cage") if "cage" in temps else 2

    def result(self, x_C) -> LossResult:
        """Losses at coupled temperatures x (B, n_x) [°C] (inner contact, outer contact, oil, then bath
        and cage where the parts read them)."""
        x = _clip(np.asarray(x_C, float))
        return evaluate_losses(self.contacts, self.lubricant, x[..., 2], T_inner_C=x[..., 0],
                               T_outer_C=x[..., 1], T_oil_C=x[..., 2], T_bath_C=x[..., self.k_bath],
                               T_cage_C=x[..., self.k_cage], **self.kw)

    def parts(self, x_C) -> np.ndarray:
        """(..., B, n_parts) loss parts [W] (:func:`loss_parts`, in that order) at coupled temperatures
        (..., B, n_x) [°C] (every leading state in one evaluation)."""
        return self.parts_of(self.result(x_C), np.shape(x_C)[:-1])

    def parts_of(self, r: LossResult, shape) -> np.ndarray:
        """The loss parts (``shape`` + (n_parts,)) [W] of a result of :meth:`result`."""
        cols = [r.contact_W[p] if p in ("inner", "outer") else r.breakdown_W[_PART_FAMILY[p]] for p in self.parts_]
        return np.stack([np.broadcast_to(c, shape) for c in cols], axis=-1)


@dataclass
class SKFLosses:
    """Losses of the SKF global model in the shape the solvers report (no per-contact data)."""

    P_W: object
    torque_Nm: object
    breakdown_W: dict
    heat_W: dict
    skf: object
    models_used: dict
    contacts: dict = field(default_factory=dict)


def _added_skf(scenes, models: dict) -> dict:
    """:func:`skf_losses` keywords: the oil level [mm] (churning chosen) and the seal moment [N mm]."""
    kw = {}
    if _chosen(models, "churning"):
        kw["H_mm"] = _one(np.array([oil_level(s)[0] * 1e3 for s in scenes], float))
    elif scenes[0].supply == "oil_bath":          # level 0, not given or churning switched off: no drag term
        kw["H_mm"] = 0.0
    if _chosen(models, "seals"):
        kw["M_seal_Nmm"] = _one(np.array([_seal(s).M_Nm * 1e3 for s in scenes], float))
    return kw


class SKFSources:
    """The SKF 2004 global model as the network's heat sources (see the module docstring)."""

    diagonal = False

    def __init__(self, fam: Family, contacts=None):
        self.fam, self.lubricant = fam, fam.lubricant
        sc = fam.scene
        if sc.bearing.kind == "thrust" and not np.all(fam.values("Fa") > 0):
            refuse_unloaded_thrust(float(np.min(fam.values("Fa"))))
        self.parts_ = loss_parts(fam.models)
        self.added = _added_skf(fam.scenes, fam.models)

    def result(self, x_C) -> SKFLosses:
        """Losses at coupled temperatures x (B, n_x) [°C]: the model at ½(x_inner + x_outer)."""
        x = _clip(np.asarray(x_C, float))
        return skf_losses(self.fam.scene, 0.5 * (x[..., 0] + x[..., 1]), self.fam.models,
                          n_rpm=self.fam.values("n_rpm"), Fa=self.fam.values("Fa"),
                          Fr=np.hypot(self.fam.values("Fr"), self.fam.values("Fz")),
                          lubricant=self.lubricant, K_rs=_K_rs(self.fam), **self.added)

    def parts(self, x_C) -> np.ndarray:
        x = np.asarray(x_C, float)
        if x.ndim == 2:
            return self.parts_of(self.result(x), x.shape[:-1])
        return np.stack([self.parts(xk) for xk in x])

    def parts_of(self, r: SKFLosses, shape) -> np.ndarray:
        """The loss parts (``shape`` + (n_parts,)) [W] of a result of :meth:`result`: ½ of the rolling and
        sliding moments' power to each contact side, the other terms to their parts."""
        bd = {k: np.asarray(v, float) for k, v in r.breakdown_W.items()}
        c = bd["rolling"] + bd["sliding"]
        cols = [0.5 * c if p in ("inner", "outer") else bd[_PART_FAMILY[p]] + 0.0 * c for p in self.parts_]
        return np.stack([np.broadcast_to(v, shape) for v in cols], axis=-1)


def skf_losses(scene: Scene, T_C, models: dict, *, n_rpm=None, Fa=None, Fr=None, H_mm=None, M_seal_Nmm=None,
               lubricant=None, K_rs=None) -> SKFLosses:
    """SKF 2004 global model for a scene at bearing temperature ``T_C`` [°C] (viscosity of the (base)
    oil there); ``n_rpm``, ``Fa``, ``Fr`` may override the scene's with arrays, ``H_mm`` [mm] and
    ``M_seal_Nmm`` [N mm] the oil level and seal moment (default: the scene's, as the models chose),
    ``lubricant`` its lubricant (values per point: :attr:`~thermobear.coupled.pipeline.Family.lubricant`), ``K_rs``
    the replenishment constant [-] (default the scene's, :func:`~thermobear.models.replenishment_constant`).
    Calibrated constants from ``[models] skf_R1, skf_S1, skf_mu_EHL``.  Breakdown: rolling, sliding,
    drag (0: no oil–air term in the model), churning (its oil-bath drag, SKF 2018 form with V_M at
    H/dm), seal.  Heat split for the network: ½ of rolling + sliding to the balls, ¼ to each ring;
    churning to the bath, seal friction to the seal."""
    m = scene.models
    n = scene.n_rpm if n_rpm is None else n_rpm
    Fa, Fr = (scene.Fa if Fa is None else Fa), (float(np.hypot(scene.Fr, scene.Fz)) if Fr is None else Fr)
    if scene.bearing.kind == "thrust" and not np.all(np.asarray(Fa) > 0):
        refuse_unloaded_thrust(float(np.min(Fa)))
    if H_mm is None and M_seal_Nmm is None:
        added = _added_skf([scene], models)
        H_mm, M_seal_Nmm = added.get("H_mm"), added.get("M_seal_Nmm")
    lub = "grease" if scene.supply == "grease" else scene.supply
    base = _SKF_MU_EHL.get(getattr(scene.lubricant, "base_oil", "mineral"), "mineral")
    oil = scene.lubricant if lubricant is None else lubricant
    r = skf_friction(scene.bearing, oil.nu(T_C), n, Fa, Fr, lubrication=lub, R1=m.get("skf_R1"),
                     S1=m.get("skf_S1"), mu_EHL=m.get("skf_mu_EHL"), base_oil=base, H_mm=H_mm,
                     M_seal_Nmm=0.0 if M_seal_Nmm is None else M_seal_Nmm,
                     K_rs=replenishment_constant(scene, models) if K_rs is None else K_rs)
    w = np.asarray(n, float) * np.pi / 30.0
    bd = {"rolling": r.M_rr * w, "sliding": r.M_sl * w, "drag": 0.0 * r.M_drag * w, "churning": r.M_drag * w,
          "seal": r.M_seal * w}
    P = r.P_W
    contact = bd["rolling"] + bd["sliding"]
    heat = {"inner_ring": 0.25 * contact, "outer_ring": 0.25 * contact, "balls": 0.5 * contact, "oil": bd["drag"],
            "bath": bd["churning"], "seal": bd["seal"]}
    used = dict(models)
    used["losses"] = ("skf", f"SKF 2004 global model (R1 {m.get('skf_R1', 'catalogue')}, S1 {m.get('skf_S1', 'catalogue')})")
    return SKFLosses(P_W=P, torque_Nm=r.M_total, breakdown_W=bd, heat_W=heat, skf=r, models_used=used)


def loss_sources(fam: Family, contacts):
    """The family's loss source (:class:`LocalSources` or :class:`SKFSources`)."""
    return SKFSources(fam, contacts) if fam.models["losses"][0] == "skf" else LocalSources(fam, contacts)


# --------------------------------------------------------------------------- the network side
def network_template(scene: Scene, fixed_placeholders: bool = False) -> NetworkTemplate:
    """The scene's network, checked, with what reads only the bearing evaluated.

    ``fixed_placeholders``: imposed nodes read their temperature from the context
    (``fixed.n<k>``, the k-th imposed node in sorted order) so that the points of a family may
    impose different values."""
    fixed = scene.T_fixed_C
    if fixed_placeholders:
        fixed = {node: f"fixed.n{k}" for k, node in enumerate(sorted(fixed))}
    spec = network_spec(scene.network, scene.path, parameters=scene.network_parameters, fixed_C=fixed)
    return prepare_network(spec, {"bearing": scene.bearing})


def network_context(fam: Family, contacts: ContactSet | None = None) -> dict:
    """Context of the network at a family's B operating points (arrays (B,), contacts (B, Z)).

    ``op`` holds what the physics computed for each point [rad/s]: the ring speeds (``omega_rad_s``
    the rotating one, ``omega_inner_rad_s``, ``omega_outer_rad_s``), the cage speed
    ``omega_cage_rad_s`` and the balls' spin speed about their own axes ``omega_ball_rad_s`` (the
    kinematics of the contacts, :func:`thermobear.contact.kinematics.caged_ball_kinematics`), and the
    oil volume fraction ``oil_fraction`` of the oil–air mixture (Parker 1984,
    :func:`thermobear.losses.drag.cavity_oil_fraction`, as the drag model uses it)."""
    sc = fam.scene
    n = fam.values("n_rpm")
    T_in = fam.values("T_oil_in_C")
    scene = {"n_rpm": n, "T_ambient_C": fam.values("T_ambient_C"),
             "T_oil_in_C": np.where(np.isnan(T_in), fam.values("T_ambient_C"), T_in),
             "oil_flow_m3_s": fam.values("oil_flow"), "jet_penetration": fam.values("jet_penetration")}
    for key in sc.network_parameters:
        if "." not in key:
            scene[key] = np.array([s.network_parameters[key] for s in fam.scenes], float)
    ctx = {"bearing": sc.bearing, "scene": scene, "oil": fam.lubricant,
           "fixed": {f"n{k}": np.array([s.T_fixed_C[node] for s in fam.scenes], float)
                     for k, node in enumerate(sorted(sc.T_fixed_C))},
           "sample": {k: v for k, v in fam.samples().items() if not k.startswith("lubricant.")}}
    omega = n * np.pi / 30.0
    inner = sc.rotating == "inner"
    op = {"omega_rad_s": omega, "omega_inner_rad_s": omega if inner else 0.0 * omega,
          "omega_outer_rad_s": 0.0 * omega if inner else omega, "oil_fraction": _oil_fraction(fam, n)}
    if contacts is not None:
        ctx["contacts"] = {s: {"a_m": np.asarray(contacts.sides[s]["a"], float),
                               "b_m": np.asarray(contacts.sides[s]["b"], float),
                               "u_m_s": np.asarray(contacts.sides[s]["u"], float),
                               "Q_N": np.asarray(contacts.sides[s]["Q"], float),
                               "Rx_m": np.asarray(contacts.sides[s]["Rx"], float),
                               "Ry_m": np.asarray(contacts.sides[s]["Ry"], float)} for s in ("inner", "outer")}
        op["omega_cage_rad_s"] = np.asarray(contacts.omega_cage, float)
        op["omega_ball_rad_s"] = np.asarray(contacts.omega_ball, float).mean(axis=-1)
    ctx["op"] = op
    return ctx


def _oil_fraction(fam: Family, n_rpm) -> np.ndarray:
    """Oil volume fraction of the oil–air mixture per point (:func:`~thermobear.losses.drag.cavity_oil_fraction`,
    as the drag model takes it)."""
    return cavity_oil_fraction(fam.scene.supply, _through_flow(fam), n_rpm, fam.scene.bearing.dm)


def family_network(fam: Family, template: NetworkTemplate, contacts: ContactSet | None) -> ThermalNetwork:
    """The family's network at its B operating points."""
    ctx = network_context(fam, contacts)
    return template.at(ctx, oil=ctx["oil"], batch=fam.B)


#: The coupled temperatures the loss models read, each the mean of role nodes (role → weight): a contact
#: reads the mean of its ball and race nodes (seed 004 §4.5), drag the oil–air mixture, churning the
#: bath, the cage's land friction the cage.  A new loss part that reads another temperature adds its
#: entry here (after the first three: their order is fixed).
TEMPERATURES = {"inner": {"ball": 0.5, "inner": 0.5},
                "outer": {"ball": 0.5, "outer": 0.5},
                "oil": {"oil": 1.0},
                "bath": {"bath": 1.0},
                "cage": {"cage": 1.0}}

#: The loss parts a source reports: part → (heat split, role → fraction summing to 1; the coupled
#: temperature it reads).  Each contact loss goes ½ to the ball and ½ to its race (Pouly et al.
#: 2010), drag to the oil–air mixture, churning to the bath, seal friction to the seal (SKF's moment
#: is temperature independent: it "reads" the inner contact temperature, with a zero slope), the cage
#: loss to the cage.
PARTS = {"inner": ({"ball": 0.5, "inner": 0.5}, "inner"),
         "outer": ({"ball": 0.5, "outer": 0.5}, "outer"),
         "drag": ({"oil": 1.0}, "oil"),
         "churning": ({"bath": 1.0}, "bath"),
         "seal": ({"seal": 1.0}, "inner"),
         "cage": ({"cage": 1.0}, "cage")}

#: The parts every source reports, in this order.
DEFAULT_PARTS = ("inner", "outer", "drag")
#: The parts a scene may add (its model choice → part), in this order.
_ADDED_PARTS = (("churning", "churning"), ("seals", "seal"), ("cage", "cage"))


def loss_parts(models: dict) -> tuple:
    """The loss parts of a scene family: :data:`DEFAULT_PARTS`, then churning, seal and cage where
    :func:`thermobear.models.choose_models` chose them (``models[...]`` truthy).

    >>> loss_parts({"churning": ("pouly_immersed", ""), "seals": (False, ""), "cage": (False, "")})
    ('inner', 'outer', 'drag', 'churning')
    """
    return DEFAULT_PARTS + tuple(part for key, part in _ADDED_PARTS if _chosen(models, key))


def coupled_temperatures(parts: tuple) -> tuple:
    """The coupled temperatures that ``parts`` read, in the order of x: the first three of
    :data:`TEMPERATURES`, then the others in the order the parts need them."""
    first = tuple(TEMPERATURES)[:3]
    return first + tuple(dict.fromkeys(PARTS[p][1] for p in parts if PARTS[p][1] not in first))


@dataclass(frozen=True)
class Coupling:
    """Which network nodes the losses heat and whose temperatures they read.

    Attributes
    ----------
    roles : dict          role → node name (``ball``, ``inner``, ``outer``, ``oil``, …; :data:`ROLES`)
    parts : tuple         the loss parts, in the order of the sources' columns (:data:`PARTS`)
    temperatures : tuple  the coupled temperatures, in the order of x (:data:`TEMPERATURES`)
    C : ndarray           (n_x, n_free): coupled temperatures x = C T_free
    S : ndarray           (n_free, n_parts): free-node sources = S P (the split of the loss parts)
    reads : ndarray       (n_parts,): the coupled temperature each part reads (index into x)
    """

    roles: dict
    C: np.ndarray
    S: np.ndarray
    parts: tuple = DEFAULT_PARTS
    temperatures: tuple = tuple(TEMPERATURES)
    reads: np.ndarray = field(default_factory=lambda: np.arange(3))

    @classmethod
    def of(cls, template: NetworkTemplate, parts: tuple = DEFAULT_PARTS) -> "Coupling":
        unknown = [p for p in parts if p not in PARTS]
        if unknown:
            raise InputError("parts", unknown, f"loss parts among {', '.join(PARTS)}")
        temps = coupled_temperatures(tuple(parts))
        needed = dict.fromkeys(r for t in temps for r in TEMPERATURES[t])
        needed.update(dict.fromkeys(r for p in parts for r in PARTS[p][0]))
        free = ~template.fixed
        roles = {}
        for role in needed:
            cands = ROLES[role]
            hit = next((c for c in cands if c in template.index and free[template.index[c]]), None)
            if hit is None:
                raise InputError(f"network {template.name}", role, f"has no node for the role '{role}' "
                                 f"(tried {', '.join(cands)})")
            roles[role] = hit
        fpos = -np.ones(len(template.nodes), int)
        fpos[free] = np.arange(int(free.sum()))
        pos = {r: fpos[template.index[n]] for r, n in roles.items()}
        C = np.zeros((len(temps), int(free.sum())))
        for row, t in enumerate(temps):
            for role, w in TEMPERATURES[t].items():
                C[row, pos[role]] += w
        S = np.zeros((int(free.sum()), len(parts)))
        for col, p in enumerate(parts):
            for role, w in PARTS[p][0].items():
                S[pos[role], col] += w
        reads = np.array([temps.index(PARTS[p][1]) for p in parts], int)
        return cls(roles=roles, C=C, S=S, parts=tuple(parts), temperatures=temps, reads=reads)

    def incidence(self) -> np.ndarray:
        """(n_parts, n_x): 1 where a part reads a coupled temperature (the pattern of ∂P/∂x of a source
        whose parts each read their own temperature)."""
        R = np.zeros((len(self.parts), len(self.temperatures)))
        R[np.arange(len(self.parts)), self.reads] = 1.0
        return R


def scene_losses(scene: Scene, T_C=None, *, T_inner_C=None, T_outer_C=None, T_oil_C=None, load=None,
                 models: dict | None = None, contacts: ContactSet | None = None, n_rpm=None, dry=None):
    """Losses of a scene at given temperatures [W] (default: the scene's prescribed T_C): the local
    model (:func:`thermobear.losses.evaluate_losses`) or the SKF model, as the scene's models say.

    ``n_rpm`` and the temperatures may be arrays (one operating point each, vectorised; the loads
    of the scene); ``load`` / ``contacts`` inject a load distribution / prepared contacts; ``models`` the model
    choice (name → (choice, reason), :func:`~thermobear.models.plan_many`), or keys of the scene's ``[models]``
    table (``{"load_model": "film"}``, as :meth:`Scene.with_`); ``dry`` the dry load distribution the model
    choice solved.

    >>> import thermobear as tb
    >>> s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    >>> r = scene_losses(s, T_C=50.0)
    >>> max(r.breakdown_W, key=r.breakdown_W.get), r.models_used["load_distribution"][0]
    ('rolling', 'Jones–Harris high-speed (centrifugal, gyroscopic)')
    """
    if models is not None and not (models and isinstance(models, dict) and all(type(v) is tuple for v in models.values())):
        scene, models = scene.with_(models=models), None  # the scene's [models] keys: checked as Scene.with_ does
    if models is None:
        models, dry = plan(scene)
    if T_C is None:
        T_C = scene.T_C if scene.T_C is not None else scene.T_ambient_C
    if models["losses"][0] == "skf":
        T = T_C if T_inner_C is None else 0.5 * (np.asarray(T_inner_C) + np.asarray(T_outer_C))
        return skf_losses(scene, T, models, n_rpm=n_rpm)
    if load is None and dry is not None and models["load_model"][0] == "jones_harris":
        load = dry                        # the model choice solved the dry loads already
        injected = False
    else:
        injected = contacts is not None or load is not None
    cs = contacts if contacts is not None else scene_contacts(scene, models, load, n_rpm=n_rpm)
    if np.ndim(cs.n_rpm) == 0:
        over = overloads([scene], cs)
        if over:
            raise over[0]
    r = evaluate_losses(cs, scene.lubricant, T_C, T_inner_C=T_inner_C, T_outer_C=T_outer_C, T_oil_C=T_oil_C,
                        supply=scene.supply, oil_flow_m3_s=scene.oil_flow * scene.jet_penetration, Rq_ball=scene.Rq_ball,
                        Rq_ring=scene.Rq_ring, mu_boundary=scene.mu_boundary, mu_full_film=scene.mu_full_film,
                        K_rs=replenishment_constant(scene, models), rolling_model=models["rolling"][0],
                        drag=bool(models["drag"][0]), **film_options(models), **_added_local([scene], models))
    used = dict(r.models_used)
    used.update(models)
    lm, hs = models["load_model"][0], models["high_speed"][0]
    if injected:
        used["load_distribution"] = ("injected", "loads given by the caller")
    else:
        used["load_distribution"] = (
            "closed form, all balls equal" if lm == "closed_form" else
            "Jones–Harris high-speed (centrifugal, gyroscopic)" if hs == "yes" else
            "Jones–Harris low-speed, rigid rings", models["load_model"][1])
    return dataclasses.replace(r, models_used=used)


@dataclass(frozen=True)
class Prepared:
    """What the thermal solution of a scene family computes once, prepared explicitly and reused for
    any number of operating points (:func:`prepare`): the checked network template with its
    bearing-level values, and the coupling of losses and nodes (with the loss parts the scene's models
    add: churning, seal, cage; :func:`loss_parts`).

    It serves the scenes that share its network file, parameter overrides, imposed node names, loss
    parts and bearing (:meth:`serves`); the solvers refuse it for another scene.
    """

    key: tuple
    bearing: object
    template: NetworkTemplate
    coupling: "Coupling"

    def serves(self, scene: Scene) -> bool:
        """True when ``scene`` belongs to the family this was prepared for."""
        return _prepared_key(scene) == self.key and scene.bearing == self.bearing


def _prepared_key(scene: Scene) -> tuple:
    return (scene.network, scene.path, tuple(sorted((k, v) for k, v in scene.network_parameters.items() if "." in k)),
            tuple(sorted(scene.T_fixed_C)), loss_parts(added_losses(scene)))


def prepare(scene: Scene) -> Prepared:
    """The network template and coupling of a scene's family, computed once (see :class:`Prepared`).

    >>> import thermobear as tb
    >>> s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    >>> p = prepare(s)
    >>> p.serves(s.with_(n_rpm=6500.0)), p.serves(s.with_(bearing="6210"))
    (True, False)
    """
    scene = instance_of(scene, Scene, "scene")
    if scene.network is None:
        raise InputError("thermal.network", None, "a scene with a thermal network (no network: nothing to prepare)")
    template = network_template(scene, fixed_placeholders=True)
    return Prepared(key=_prepared_key(scene), bearing=scene.bearing, template=template,
                    coupling=Coupling.of(template, parts=loss_parts(added_losses(scene))))


def prepared_for(scene: Scene, prepared=None) -> Prepared:
    """``prepared`` when it serves ``scene`` (InputError when it does not), else :func:`prepare`."""
    if prepared is None:
        return prepare(scene)
    if not isinstance(prepared, Prepared) or not prepared.serves(scene):
        raise InputError("prepared", type(prepared).__name__, "the prepare(scene) of this scene's family (same network, "
                         "overrides, imposed nodes and bearing)")
    return prepared
