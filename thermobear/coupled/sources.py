r"""The losses as heat sources of the thermal network, and the network at a family's operating points.

The losses of a bearing depend on three temperatures only — the inner and the outer contact
temperature, each the mean of the ball and race nodes (seed 004 §4.5), and the oil–air mixture
temperature (drag).  A loss source gives, at these coupled temperatures x [°C] of B operating
points, the three parts P = (inner contacts, outer contacts, drag) [W]; the network receives ½ of
each contact loss at the ball node and ½ at the race node (Pouly et al. 2010), drag at the
mixture node (:func:`thermobear.thermal.split_losses`).  Two sources:

* :class:`LocalSources` — the local contact model (:func:`thermobear.losses.evaluate_losses`);
  each part depends on its own temperature only (the inner contacts on x_inner, …), so ∂P/∂x is
  diagonal;
* :class:`SKFSources` — the SKF 2004 global model at the mean bearing temperature ½(x_inner +
  x_outer) (¼ of the contact losses to each race, ½ to the balls), drag to the mixture.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import numpy as np

from thermobear.errors import InputError
from thermobear.losses import ContactSet, LossResult, evaluate_losses
from thermobear.losses.drag import oil_volume_fraction_parker
from thermobear.losses.skf import skf_friction
from thermobear.models import plan, refuse_unloaded_thrust
from thermobear.coupled.limits import overloads
from thermobear.coupled.pipeline import Family, scene_contacts
from thermobear.scene import Scene
from thermobear.scene.network import network_spec
from thermobear.thermal import ROLES, NetworkTemplate, ThermalNetwork, prepare_network
from thermobear.validity import T_LUBRICANT_REFUSE_C

__all__ = ["LocalSources", "SKFSources", "SKFLosses", "Coupling", "PARTS", "TEMPERATURES", "DEFAULT_PARTS", "loss_sources", "network_template",
           "family_network", "network_context", "scene_losses", "skf_losses", "Prepared", "prepare",
           "prepared_for"]

_SKF_MU_EHL = {"mineral": "mineral", "PAO": "synthetic", "ester": "synthetic", "ester+vegetal": "synthetic"}


def _clip(x_C):
    """Coupled temperatures [°C] held inside the lubricant's accepted range: an iterate may overshoot;
    an equilibrium beyond the limit is reported as runaway by the solver."""
    return np.clip(x_C, *T_LUBRICANT_REFUSE_C)


class LocalSources:
    """The local contact model as the network's heat sources (see the module docstring)."""

    diagonal = True

    def __init__(self, fam: Family, contacts: ContactSet):
        self.fam, self.contacts, self.lubricant = fam, contacts, fam.lubricant
        sc = fam.scene
        flow = fam.values("oil_flow")
        flow = float(flow[0]) if np.all(flow == flow[0]) else flow      # one value when the points share it
        per = {k: fam.values(k) for k in ("Rq_ball", "Rq_ring", "mu_boundary", "mu_full_film")}
        per = {k: float(v[0]) if np.all(v == v[0]) else v[:, None, None] for k, v in per.items()}  # per contact
        self.kw = dict(supply=sc.supply, oil_flow_m3_s=flow, **per,
                       rolling_model=fam.models["rolling"][0], drag=bool(fam.models["drag"][0]))

    def result(self, x_C) -> LossResult:
        """Losses at coupled temperatures x (B, 3) [°C] (inner contact, outer contact, oil)."""
        x = _clip(np.asarray(x_C, float))
        return evaluate_losses(self.contacts, self.lubricant, x[..., 2], T_inner_C=x[..., 0],
                               T_outer_C=x[..., 1], T_oil_C=x[..., 2], **self.kw)

    def parts(self, x_C) -> np.ndarray:
        """(..., B, 3) inner contacts, outer contacts, drag [W] at coupled temperatures (..., B, 3) [°C]
        (every leading state in one evaluation)."""
        r = self.result(x_C)
        shape = np.shape(x_C)[:-1]
        return np.stack([np.broadcast_to(r.contact_W["inner"], shape), np.broadcast_to(r.contact_W["outer"], shape),
                         np.broadcast_to(r.breakdown_W["drag"], shape)], axis=-1)


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


class SKFSources:
    """The SKF 2004 global model as the network's heat sources (see the module docstring)."""

    diagonal = False

    def __init__(self, fam: Family, contacts=None):
        self.fam, self.lubricant = fam, fam.lubricant
        sc = fam.scene
        if sc.bearing.kind == "thrust" and not np.all(fam.values("Fa") > 0):
            refuse_unloaded_thrust(float(np.min(fam.values("Fa"))))

    def result(self, x_C) -> SKFLosses:
        """Losses at coupled temperatures x (B, 3) [°C]: the model at ½(x_inner + x_outer)."""
        x = _clip(np.asarray(x_C, float))
        return skf_losses(self.fam.scene, 0.5 * (x[..., 0] + x[..., 1]), self.fam.models,
                          n_rpm=self.fam.values("n_rpm"), Fa=self.fam.values("Fa"), Fr=self.fam.values("Fr"),
                          lubricant=self.lubricant)

    def parts(self, x_C) -> np.ndarray:
        x = np.asarray(x_C, float)
        if x.ndim == 2:
            r = self.result(x)
            c = np.asarray(r.P_W, float) - np.asarray(r.breakdown_W["drag"], float)
            return np.stack([0.5 * c, 0.5 * c, np.asarray(r.breakdown_W["drag"], float) + 0.0 * c], axis=-1)
        return np.stack([self.parts(xk) for xk in x])


def skf_losses(scene: Scene, T_C, models: dict, *, n_rpm=None, Fa=None, Fr=None, lubricant=None) -> SKFLosses:
    """SKF 2004 global model for a scene at bearing temperature ``T_C`` [°C] (viscosity of the (base)
    oil there); ``n_rpm``, ``Fa``, ``Fr`` may override the scene's with arrays, ``lubricant`` its
    lubricant (values per point: :attr:`~thermobear.coupled.pipeline.Family.lubricant`).  Calibrated constants
    from ``[models] skf_R1, skf_S1, skf_mu_EHL``.  Heat split for the network: ½ to the balls, ¼ to
    each ring (the equal split of the contact losses); drag to the oil."""
    m = scene.models
    n = scene.n_rpm if n_rpm is None else n_rpm
    Fa, Fr = (scene.Fa if Fa is None else Fa), (scene.Fr if Fr is None else Fr)
    if scene.bearing.kind == "thrust" and not np.all(np.asarray(Fa) > 0):
        refuse_unloaded_thrust(float(np.min(Fa)))
    lub = "grease" if scene.supply == "grease" else scene.supply
    base = _SKF_MU_EHL.get(getattr(scene.lubricant, "base_oil", "mineral"), "mineral")
    oil = scene.lubricant if lubricant is None else lubricant
    r = skf_friction(scene.bearing, oil.nu(T_C), n, Fa, Fr, lubrication=lub, R1=m.get("skf_R1"),
                     S1=m.get("skf_S1"), mu_EHL=m.get("skf_mu_EHL"), base_oil=base)
    w = np.asarray(n, float) * np.pi / 30.0
    bd = {"rolling": r.M_rr * w, "sliding": r.M_sl * w, "drag": r.M_drag * w, "seal": r.M_seal * w}
    P = r.P_W
    contact = P - bd["drag"]
    heat = {"inner_ring": 0.25 * contact, "outer_ring": 0.25 * contact, "balls": 0.5 * contact, "oil": bd["drag"]}
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
    :func:`thermobear.losses.drag.oil_volume_fraction_parker`, as the drag model uses it)."""
    sc = fam.scene
    n = fam.values("n_rpm")
    T_in = fam.values("T_oil_in_C")
    scene = {"n_rpm": n, "T_ambient_C": fam.values("T_ambient_C"),
             "T_oil_in_C": np.where(np.isnan(T_in), fam.values("T_ambient_C"), T_in),
             "oil_flow_m3_s": fam.values("oil_flow")}
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
                               "b_m": np.asarray(contacts.sides[s]["b"], float)} for s in ("inner", "outer")}
        op["omega_cage_rad_s"] = np.asarray(contacts.omega_cage, float)
        op["omega_ball_rad_s"] = np.asarray(contacts.omega_ball, float).mean(axis=-1)
    ctx["op"] = op
    return ctx


def _oil_fraction(fam: Family, n_rpm) -> np.ndarray:
    """Oil volume fraction of the oil–air mixture per point: Parker's for oil jets, 1 % for oil–air,
    0 otherwise (the drag model's choices, :func:`thermobear.losses.evaluate_losses`)."""
    sc = fam.scene
    if sc.supply == "oil_jet":
        W = fam.values("oil_flow") * 1e6 * 60.0
        run = n_rpm > 0
        X = np.zeros(n_rpm.shape)
        if run.any():
            X[run] = oil_volume_fraction_parker(W[run], n_rpm[run], sc.bearing.dm * 1e3)
        return X
    return np.full(n_rpm.shape, 0.01 if sc.supply == "oil_air" else 0.0)


def family_network(fam: Family, template: NetworkTemplate, contacts: ContactSet | None) -> ThermalNetwork:
    """The family's network at its B operating points."""
    ctx = network_context(fam, contacts)
    return template.at(ctx, oil=ctx["oil"], batch=fam.B)


#: The coupled temperatures the loss models read, each the mean of role nodes (role → weight): a contact
#: reads the mean of its ball and race nodes (seed 004 §4.5), drag the oil–air mixture.  A new loss
#: part that reads another temperature adds its entry here (after these three: their order is fixed).
TEMPERATURES = {"inner": {"ball": 0.5, "inner": 0.5},
                "outer": {"ball": 0.5, "outer": 0.5},
                "oil": {"oil": 1.0}}

#: The loss parts a source reports: part → (heat split, role → fraction summing to 1; the coupled
#: temperature it reads).  Each contact loss goes ½ to the ball and ½ to its race (Pouly et al.
#: 2010), drag to the oil–air mixture.
PARTS = {"inner": ({"ball": 0.5, "inner": 0.5}, "inner"),
         "outer": ({"ball": 0.5, "outer": 0.5}, "outer"),
         "drag": ({"oil": 1.0}, "oil")}

#: The parts every source reports, in this order.
DEFAULT_PARTS = ("inner", "outer", "drag")


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
        temps = tuple(TEMPERATURES)[:3] + tuple(dict.fromkeys(PARTS[p][1] for p in parts
                                                               if PARTS[p][1] not in tuple(TEMPERATURES)[:3]))
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
                 models: dict | None = None, contacts: ContactSet | None = None, n_rpm=None):
    """Losses of a scene at given temperatures [W] (default: the scene's prescribed T_C): the local
    model (:func:`thermobear.losses.evaluate_losses`) or the SKF model, as the scene's models say.

    ``n_rpm`` and the temperatures may be arrays (one operating point each, vectorised; the loads
    of the scene); ``load`` / ``contacts`` inject a load distribution / prepared contacts.

    >>> import thermobear as tb
    >>> s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    >>> r = scene_losses(s, T_C=50.0)
    >>> max(r.breakdown_W, key=r.breakdown_W.get), r.models_used["load_distribution"][0]
    ('rolling', 'Jones–Harris high-speed (centrifugal, gyroscopic)')
    """
    dry = None
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
                        supply=scene.supply, oil_flow_m3_s=scene.oil_flow, Rq_ball=scene.Rq_ball,
                        Rq_ring=scene.Rq_ring, mu_boundary=scene.mu_boundary, mu_full_film=scene.mu_full_film,
                        rolling_model=models["rolling"][0], drag=bool(models["drag"][0]))
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
    bearing-level values, and the coupling of losses and nodes.

    It serves the scenes that share its network file, parameter overrides, imposed node names and
    bearing (:meth:`serves`); the solvers refuse it for another scene.
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
            tuple(sorted(scene.T_fixed_C)))


def prepare(scene: Scene) -> Prepared:
    """The network template and coupling of a scene's family, computed once (see :class:`Prepared`).

    >>> import thermobear as tb
    >>> s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    >>> p = prepare(s)
    >>> p.serves(s.with_(n_rpm=6500.0)), p.serves(s.with_(bearing="6210"))
    (True, False)
    """
    if scene.network is None:
        raise InputError("thermal.network", None, "a scene with a thermal network (no network: nothing to prepare)")
    template = network_template(scene, fixed_placeholders=True)
    return Prepared(key=_prepared_key(scene), bearing=scene.bearing, template=template, coupling=Coupling.of(template))


def prepared_for(scene: Scene, prepared=None) -> Prepared:
    """``prepared`` when it serves ``scene`` (InputError when it does not), else :func:`prepare`."""
    if prepared is None:
        return prepare(scene)
    if not isinstance(prepared, Prepared) or not prepared.serves(scene):
        raise InputError("prepared", type(prepared).__name__, "the prepare(scene) of this scene's family (same network, "
                         "overrides, imposed nodes and bearing)")
    return prepared
