r"""The estimated inputs of a scene and their sample design: what :mod:`thermobear.coupled.uncertainty` samples.

:func:`uncertain_inputs` collects every estimated value a scene's data carry with its range (the addresses and
levels of :mod:`thermobear.coupled.uncertainty`'s table), :func:`design` draws the unit design (Latin hypercube or
scrambled Sobol', :mod:`scipy.stats.qmc`), :func:`sample_scenes` the scenes of a design: the per-point draws in
each scene's ``samples``, the family-level draws (bearing geometry, a built network's estimates) at ``groups``
levels, one family each.
"""
from __future__ import annotations
import dataclasses
import warnings
from dataclasses import dataclass

import numpy as np

from thermobear.contact.geometry import bearing_values
from thermobear.contact.materials import PROPERTIES, material
from thermobear.coupled.sources import prepared_for
from thermobear.errors import InputError
from thermobear.lazy import lazy_module
from thermobear.model_inputs import FRICTION_INPUTS, unread_inputs
from thermobear.scene import Scene
from thermobear.scene.scene import SECTIONS
from thermobear.schema import Uncertainty, check_value
from thermobear.thermal.builders import Machine, build_network, estimates

stats = lazy_module("scipy.stats")          # qmc samplers: loaded when the first design is drawn

__all__ = ["Input", "Samples", "uncertain_inputs", "design", "sample_scenes", "METHODS"]

METHODS = ("lhs", "sobol")
_GROUPS = 8

#: scene address → (Scene.with_ key, scale from the file's unit to the scene attribute's, attribute)
_SCENE_KEYS = {
    "operation.n_rpm": ("n_rpm", 1.0, "n_rpm"), "operation.Fa_N": ("Fa", 1.0, "Fa"),
    "operation.Fr_N": ("Fr", 1.0, "Fr"), "operation.M_Nm": ("M", 1.0, "M"), "operation.Fz_N": ("Fz", 1.0, "Fz"),
    "operation.My_Nm": ("My", 1.0, "My"), "operation.T_C": ("T_C", 1.0, "T_C"),
    "lubricant.flow_L_h": ("oil_flow_L_h", 3.6e6, "oil_flow"), "lubricant.T_in_C": ("T_oil_in_C", 1.0, "T_oil_in_C"),
    "lubricant.Rq_ball_um": ("Rq_ball_um", 1e6, "Rq_ball"), "lubricant.Rq_ring_um": ("Rq_ring_um", 1e6, "Rq_ring"),
    "lubricant.mu_boundary": ("mu_boundary", 1.0, "mu_boundary"),
    "lubricant.mu_full_film": ("mu_full_film", 1.0, "mu_full_film"),
    "lubricant.K_rs": ("K_rs", 1.0, "K_rs"),
    "lubricant.jet_penetration": ("jet_penetration", 1.0, "jet_penetration"),
    "thermal.T_ambient_C": ("T_ambient_C", 1.0, "T_ambient_C"),
}
_FRICTION = ([f for f, _ in FRICTION_INPUTS.values()] + ["lubricant.K_rs", "lubricant.flow_L_h", "lubricant.T_in_C",
                                                          "thermal.T_ambient_C"])
#: (the inputs above are sampled only where the models read them)
_RATINGS = ("C0_kN", "C_kN")
#: bearing table key → (BallBearing attribute, scale to the key's unit)
_BEARING_KEYS = {"D_mm": ("D", 1e3), "dm_mm": ("dm", 1e3), "Pd_mm": ("Pd", 1e3), "Z": ("Z", 1.0), "fi": ("fi", 1.0),
                 "fo": ("fo", 1.0), "C0_kN": ("C0", 1e-3), "C_kN": ("C", 1e-3), "bore_mm": ("bore", 1e3),
                 "outer_diameter_mm": ("outer_diameter", 1e3), "width_mm": ("width", 1e3)}


@dataclass(frozen=True)
class Input:
    """One uncertain input of a scene.

    Attributes
    ----------
    address : str              where it lives (module docstring)
    uncertainty : Uncertainty  its range, distribution and source
    nominal : float | None     the draw that gives the nominal value: 1 for a factor, 0 for an offset,
                               the nominal value for a range (None when the nominal is an expression)
    level : str                ``"point"`` (varies within a family) or ``"family"`` (the bearing)
    """

    address: str
    uncertainty: Uncertainty
    nominal: float | None
    level: str = "point"

    @property
    def label(self) -> str:
        """The address with what a draw is (``× …`` factor, ``+ …`` offset)."""
        return self.address + {"factor": " [×]", "offset": " [+]"}.get(self.uncertainty.kind, "")

    def as_dict(self) -> dict:
        return {"address": self.address, **self.uncertainty.as_dict(), "nominal_draw": self.nominal,
                "level": self.level}


def _nominal_draw(u: Uncertainty, value) -> float | None:
    if u.kind == "factor":
        return 1.0
    if u.kind == "offset":
        return 0.0
    return None if value is None or isinstance(value, str) else float(value)


def _network_nominal(template, address):
    """The static nominal value of a network address (None for an expression)."""
    kind, name, key = address.split(".", 2)
    if kind == "materials":
        return getattr(material(name), PROPERTIES[key])
    if kind == "elements":
        e = next(e for e in template.elements if e.name == name)
        v = e.static.get(key)
        return v if isinstance(v, float) else None
    for k, fld, v in template.T_fixed:
        if template.nodes[k] == name and key == "T_C" and isinstance(v, float):
            return v
    for k, kk, v, _ in template.capacity:
        if template.nodes[k] == name and kk == key:
            return v
    return None


def uncertain_inputs(scene: Scene, prepared=None) -> list:
    """The uncertain inputs of a scene (module docstring), in a fixed order: the scene's numbers, the
    lubricant's, the network's and its materials', then (per family) a built network's builder estimates
    and the bearing's.

    >>> import thermobear as tb
    >>> ins = uncertain_inputs(tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")))
    >>> ins[0].address, ins[-1].address, ins[-1].level
    ('lubricant.Rq_ball_um', 'bearing.fo', 'family')
    """
    out = []
    unread = unread_inputs(scene) if any(a in _FRICTION for a in scene.uncertainty) else {}
    for addr, u in scene.uncertainty.items():
        if addr not in _SCENE_KEYS or addr in unread:
            continue                        # e.g. rig.J_kg_m2: an input of the spin-down, not of the thermal solve
        _, scale, attr = _SCENE_KEYS[addr]
        v = getattr(scene, attr)
        out.append(Input(addr, u, _nominal_draw(u, None if v is None else v * scale)))
    lub = scene.lubricant
    for key, u in getattr(lub, "uncertainty", {}).items():
        out.append(Input(f"lubricant.{key}", u, _nominal_draw(u, lub.table.get(key))))
    if scene.network is not None:
        template = prepared_for(scene, prepared).template
        for addr, u in template.uncertainty.items():
            out.append(Input(addr, u, _nominal_draw(u, _network_nominal(template, addr))))
    if isinstance(scene.network, Machine):
        unc = estimates.uncertainty()
        for key in estimates.sampled_keys(scene.network):
            nominal = estimates.machine_value(scene.network, key)
            out.append(Input(f"builder.{key}", unc[key], _nominal_draw(unc[key], nominal), level="family"))
    brg = scene.bearing
    for key, u in brg.uncertainty.items():
        if key in _RATINGS:
            continue                        # load ratings: read by the life and safety checks, not by the solve
        attr, scale = _BEARING_KEYS.get(key, (None, 1.0))
        v = getattr(brg, attr) if attr else None
        out.append(Input(f"bearing.{key}", u, _nominal_draw(u, None if v is None else v * scale), level="family"))
    return out


def design(n: int, d: int, seed=None, method: str = "lhs") -> np.ndarray:
    """(n, d) probabilities in (0, 1): a Latin hypercube (``"lhs"``) or a scrambled Sobol' sequence
    (``"sobol"``, n a power of 2 for its balance) of :mod:`scipy.stats.qmc`, seeded.

    >>> u = design(8, 2, seed=1)
    >>> u.shape, bool(np.all(np.sort(np.floor(u[:, 0] * 8)) == np.arange(8)))
    ((8, 2), True)
    """
    if method not in METHODS:
        raise InputError("uncertainty.method", method, f"one of {', '.join(METHODS)}")
    n, d = _count(n, "uncertainty.n"), int(d)
    if seed is not None and (isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0):
        raise InputError("uncertainty.seed", seed, "a whole number >= 0 (or None: a fresh design)")
    if d == 0:
        return np.zeros((n, 0))
    rng = np.random.default_rng(seed)
    if method == "lhs":
        return stats.qmc.LatinHypercube(d=d, rng=rng).random(n)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)     # "balance properties … n a power of 2": said in the doc
        return stats.qmc.Sobol(d=d, scramble=True, rng=rng).random(n)


def _count(n, field):
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
        raise InputError(field, n, "a whole number of samples >= 1")
    return int(n)


@dataclass
class Samples:
    """The sampled operating points of a scene (:func:`sample_scenes`)."""

    scenes: list             # per sample, its Scene (or the InputError its draws raised)
    inputs: list             # the Inputs, columns of X
    X: np.ndarray            # (n, d) draws (factor, offset or value, as each input says)
    group: np.ndarray        # (n,) family group of each sample
    seed: object
    method: str
    groups: int


def sample_scenes(scene: Scene, n: int, *, seed=None, method: str = "lhs", groups: int | None = None,
                  inputs=None, prepared=None) -> Samples:
    """``n`` sampled operating points of a scene: every uncertain input drawn (module docstring).

    ``inputs``: the inputs to sample (default :func:`uncertain_inputs`; given ones may narrow, widen
    or reshape the data's ranges, each at an address the data ranges, with its kind of draw);
    ``groups``: the number of bearing-geometry (and builder-estimate) families (default min(n, max(8, 2 (d + 1)))
    for d family-level inputs; 1 with none)."""
    n = _count(n, "uncertainty.n")
    data = uncertain_inputs(scene, prepared)
    ins = list(data if inputs is None else _checked(inputs, data))
    pts = [k for k, i in enumerate(ins) if i.level == "point"]
    fams = [k for k, i in enumerate(ins) if i.level == "family"]
    G = 1 if not fams else min(n, max(_GROUPS, 2 * (len(fams) + 1)) if groups is None
                               else _count(groups, "uncertainty.groups"))
    U = design(n, len(pts) + (1 if G > 1 else 0), seed, method)
    X = np.zeros((n, len(ins)))
    for c, k in enumerate(pts):
        X[:, k] = ins[k].uncertainty.quantile(U[:, c])
    group = np.minimum((U[:, -1] * G).astype(int), G - 1) if G > 1 else np.zeros(n, int)
    brgs = [(scene.bearing, scene.network)] * G
    if fams:
        Ug = design(G, len(fams), None if seed is None else np.random.default_rng(seed).integers(2**32), method)
        Xg = np.column_stack([ins[k].uncertainty.quantile(Ug[:, c]) for c, k in enumerate(fams)])
        X[:, fams] = Xg[group]
        cells = ({k: g.n for k, g in build_network(scene.network).segments.items()}   # the nominal's cells, hence
                 if isinstance(scene.network, Machine) else None)                    # its nodes, in every group
        brgs = [_family_at(scene, [ins[k] for k in fams], Xg[g], cells) for g in range(G)]
    scenes = [_scene_at(scene, ins, pts, X[i], *brgs[group[i]]) for i in range(n)]
    return Samples(scenes=scenes, inputs=ins, X=X, group=group, seed=seed, method=method, groups=G)


def _checked(inputs, data) -> list:
    """Given inputs, each at an address the scene's data range, with the data's kind of draw (the
    solver moves a value by its data entry: factor, offset or value)."""
    known = {i.address: i for i in data}
    for i in inputs:
        d = known.get(i.address)
        if d is None:
            raise InputError("uncertainty.inputs", i.address, "no estimated value with a range at this address; the "
                             f"scene has: {', '.join(known)}")
        if d.uncertainty.kind != i.uncertainty.kind or d.level != i.level:
            raise InputError(f"uncertainty.inputs.{i.address}", i.uncertainty.kind, f"its data draws a "
                             f"{d.uncertainty.kind} ({d.level} level): give the same kind")
    return list(inputs)


def _family_at(scene: Scene, ins, draws, cells=None) -> tuple:
    """The scene's bearing and network with one group's drawn values: (bearing or the InputError the
    draws raise, network).  A network built from dimensions takes the drawn builder estimates and the
    drawn bearing, cut into the nominal's ``cells`` (:func:`thermobear.thermal.builders.estimates.drawn`)."""
    brg, net = scene.bearing, scene.network
    vals, built = {}, {}
    for i, x in zip(ins, draws):
        kind, key = i.address.split(".", 1)
        if kind == "builder":
            built[key] = float(i.uncertainty.apply(estimates.machine_value(net, key), x))
            continue
        attr, scale = _BEARING_KEYS[key]
        vals[key] = i.uncertainty.apply(getattr(brg, attr) * scale, x)
    try:
        brg = bearing_values(brg, vals) if vals else brg
    except InputError as exc:
        return exc, net
    if isinstance(net, Machine) and (built or brg is not scene.bearing):
        net = estimates.drawn(net if brg is scene.bearing else dataclasses.replace(net, bearing=brg), built, cells)
    return brg, net


def _scene_at(scene: Scene, ins, pts, x, brg, network=None):
    """One sampled operating point: scene numbers set, other draws in ``samples``, the group's bearing
    and network (or the InputError).

    A scene number is checked by its section's field (as :meth:`Scene.with_` does) and set on a copy;
    a drawn speed goes through :meth:`Scene.with_` (its n·dm limit is a check across keys)."""
    if isinstance(brg, InputError):
        return brg
    attrs, samples, slow = {}, {}, {}
    try:
        for k in pts:
            i = ins[k]
            if i.address not in _SCENE_KEYS:
                samples[i.address] = float(x[k])
                continue
            key, scale, attr = _SCENE_KEYS[i.address]
            sec, name = i.address.split(".")
            v = check_value(float(i.uncertainty.apply(getattr(scene, attr) * scale, x[k])), SECTIONS[sec][name],
                            f"{i.address} (drawn)")
            if i.address == "operation.n_rpm":
                slow[key] = v
            else:
                attrs[attr] = v / scale
        if brg is not scene.bearing:
            attrs["bearing"] = brg
        if network is not None and network is not scene.network:
            attrs["network"] = network
        out = dataclasses.replace(scene, samples=samples, **attrs)
        return out.with_(**slow) if slow else out
    except InputError as exc:
        return exc
