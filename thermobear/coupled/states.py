r"""The answers of the coupled steady state: :class:`SteadyState`, and the converged points of a batched solve
made into them (:func:`finish`).

A batched solve (:mod:`thermobear.coupled.newton`) ends at the fixed point x of its points; the answer of each
point is a full network solve with the losses at x: its energy balance closes to machine precision, and its
coupled temperatures are checked against x (a gap beyond 10 tol_K, at least 1e-4 K: NoConvergence; a node beyond
the lubricant's limit: ThermalRunaway).  The points' numbers are kept as arrays (:class:`Solved`) and a point's
SteadyState, with its dicts of temperatures, breakdown, flows and heat paths, is made when its answer is final
(:class:`Answer`: a dry start or an unsettled film round reads only its contact temperature, power and nodes).
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass, field

import numpy as np

from thermobear.arrays import take
from thermobear.coupled.limits import family_warnings
from thermobear.coupled.newton import _C0, T_LIMIT_K, _Newton, _sources_matrix, no_exchange
from thermobear.coupled.pipeline import Family
from thermobear.coupled.sources import Coupling
from thermobear.errors import ExtrapolationWarning, NoConvergence, ThermalRunaway
from thermobear.thermal.solve import heat_paths, isolated_nodes, solve_linear

__all__ = ["SteadyState"]


@dataclass
class SteadyState:
    """Coupled steady state of one operating point.

    Attributes
    ----------
    T_C : dict                node → temperature [°C]
    T_ball_C : float          ball temperature [°C]
    P_W : float               total power loss [W]
    losses : LossResult       losses at equilibrium (the SKF model: its result), a property
    torque_Nm : float         friction torque on the rotating ring [N m]
    breakdown_W : dict        loss family → power [W]
    T_contacts_C : float      mean contact temperature [°C] (ball with each race)
    iterations : int          fixed-point iterations
    residual_K : float        last temperature change [K]
    energy_balance_W : float  Σ sources − Σ heat to fixed nodes and the oil stream [W]
    heat_flows_W : dict       element → heat flow [W] (signed along the element's ``between``)
    heat_sources_W : dict     loss part → {node: W}: where each part of the loss heats the network
    heat_out_W : dict         path (element) → W leaving the network through it into a fixed-temperature
                              node or the oil stream (positive: out); sums to the heat of the sources
    heat_out_to : dict        path → the boundary it leads to (a fixed node, or ``"stream"``)
    models_used : dict        model → (choice, reason)
    history : list            convergence history
    clearance_um : dict       with ``models.clearance`` mounted / operating: the clearances [µm] (unmounted,
                              mounted, operating at these temperatures, ``used`` by the loads), the fits, the
                              fixed point's iterations, residual and history (:mod:`thermobear.coupled.clearance`);
                              None: the bearing's own clearance (the ratings report its operating value)
    preload : dict            of a preloaded pair's bearing (``[bearing] arrangement``): the kind, the cold and warm
                              preload [N], the loaded bearing's loads, the fixed point's iterations, residual [N],
                              temperatures and history (:mod:`thermobear.coupled.preload`); None: no pair
    roles : dict              role → node (ball, inner, outer, oil)
    warnings : list           OutsideValidity warnings of this point's answer
    """

    T_C: dict
    T_ball_C: float
    P_W: float
    iterations: int
    residual_K: float
    energy_balance_W: float
    heat_flows_W: dict
    models_used: dict
    history: list = field(default_factory=list)
    roles: dict = field(default_factory=dict)
    warnings: list = field(default_factory=list)
    torque_Nm: float = 0.0
    breakdown_W: dict = field(default_factory=dict)
    T_contacts_C: float = 0.0
    heat_sources_W: dict = field(default_factory=dict)
    heat_out_W: dict = field(default_factory=dict)
    heat_out_to: dict = field(default_factory=dict)
    batch_losses: object = field(default=None, repr=False)
    row: int | None = None
    clearance_um: dict | None = None
    preload: dict | None = None

    @property
    def losses(self):
        """The losses at equilibrium (:class:`~thermobear.losses.LossResult`; the SKF model: its
        result): this point's slice of its family's batched result, taken when asked for."""
        if self.row is None:
            return self.batch_losses
        return take(self.batch_losses, self.row, np.shape(self.batch_losses.P_W)[0])

    def contact_values(self, *keys) -> dict:
        """Fields ``keys`` of :attr:`losses`' contacts at equilibrium, ``{"inner": {key: array}, "outer": ...}``,
        sliced alone from the family's batch (the ratings need a few; the whole result is not taken); {} for a
        result without contacts (the SKF model)."""
        r = self.batch_losses
        c = getattr(r, "contacts", None)
        if not c:
            return {}
        if self.row is None:
            return {side: {k: c[side][k] for k in keys} for side in ("inner", "outer")}
        B = np.shape(r.P_W)[0]
        return {side: {k: take(c[side][k], self.row, B) for k in keys} for side in ("inner", "outer")}


def _models_used(fam: Family, r, template, cp: Coupling) -> dict:
    """The models a family's answers used (shared by its points; the thermal entry per point:
    :func:`_point_models_used`)."""
    used = dict(getattr(r, "models_used", {}))
    used.update(fam.models)
    lm, hs = fam.models["load_model"][0], fam.models["high_speed"][0]
    used["load_distribution"] = (
        "closed form, all balls equal" if lm == "closed_form" else
        "Jones–Harris high-speed (centrifugal, gyroscopic)" if hs == "yes" else "Jones–Harris low-speed, rigid rings",
        fam.models["load_model"][1])
    if fam.scene.bearing.kind != "thrust":
        used["centrifugal"] = (("in the ball equilibrium", "high-speed form") if hs == "yes" else
                               ("F_c/cos α on the outer contact", "balls outside the load zone ride on the outer race"))
    else:
        used["centrifugal"] = ("none", "thrust bearing")
    used["thermal"] = (f"network {template.name}", "")
    used["node_roles"] = (cp.roles, "contact temperature = mean of ball and race nodes (seed 004 §4.5)")
    return used


#: the film factors the model choice states at the inlet temperature, stated at the solution too
_FACTORS = (("starvation", "phi_rs", "Φ_rs"), ("inlet_heating", "phi_T", "φ_T"))


def _factor_ranges(r, B: int) -> dict:
    """Per factor of :data:`_FACTORS` the (B,) least and greatest value over a point's contacts in the loss result
    ``r`` (none for a result without contacts: the SKF model)."""
    contacts = getattr(r, "contacts", None)
    if not contacts or "phi_rs" not in contacts["inner"]:
        return {}
    out = {}
    for _, arr, _ in _FACTORS:
        v = np.concatenate([np.reshape(np.asarray(contacts[k][arr], float), (B, -1)) for k in ("inner", "outer")],
                           axis=1)
        out[arr] = (v.min(axis=1).tolist(), v.max(axis=1).tolist())
    return out


def _point_models_used(used: dict, nw: _Newton, b: int, factors: dict | None = None) -> dict:
    """A point's models used: its fixed point's iterations, and the film factors the model choice stated at the
    inlet temperature also at the solution (``factors``: :func:`_factor_ranges` of the point's batch)."""
    out = dict(used)
    out["thermal"] = (used["thermal"][0], f"fixed point on {nw.x.shape[1]} coupled temperatures: {nw.method[b]}, "
                                          f"{int(nw.its[b])} iterations, loop gain {nw.gain[b]:.2f}")
    for key, arr, sym in _FACTORS:
        if arr in (factors or {}) and out.get(key, (False,))[0]:
            lo, hi = factors[arr][0][b], factors[arr][1][b]
            out[key] = (out[key][0], f"{out[key][1]}; at the solution {sym} {lo:.3f}–{hi:.3f} over the contacts")
    return out


def finish(fam: Family, net, src, cp: Coupling, template, nw: _Newton, tol_K, fams=None) -> list:
    """Per point: an :class:`Answer` of a full network solve with the converged losses (its SteadyState built
    when asked for: a dry start or an unsettled film round needs only a few of its numbers), a SolverError,
    or None (not converged: the caller decides it on the heating path); ``fams``: the families stacked in
    ``fam`` (:func:`thermobear.coupled.steady._solve_rows`), whose model choices their points report."""
    solved = Solved(fam, net, src, cp, template, nw, fams)
    B, tol = fam.B, np.broadcast_to(np.asarray(tol_K, float), (fam.B,)).tolist()
    out = []
    for b in range(B):
        if not nw.done[b]:
            out.append(None)
            continue
        if solved.singular[b]:
            out.append(no_exchange(solved.isolated[b], iterations=int(nw.its[b]), history=nw.history[b]))
            continue
        T_C = dict(zip(net.nodes, solved.T_all[b]))
        hot = {k: v for k, v in T_C.items() if v + _C0 > T_LIMIT_K}
        if hot:
            node = max(hot, key=hot.get)
            out.append(ThermalRunaway(
                f"no equilibrium below {T_LIMIT_K - _C0:g} °C (the lubricant's limit): the network cannot shed "
                f"{solved.parts[b].sum():.4g} W even at that temperature ({node} would reach {hot[node]:.4g} °C); "
                "more cooling, less speed or a thinner oil is needed", iterations=int(nw.its[b]),
                residual=float(nw.step[b]), last=T_C, history=nw.history[b]))
            continue
        if solved.gap[b] > max(10 * tol[b], 1e-4):
            out.append(NoConvergence(f"coupled temperatures of the final network solve differ from the fixed point "
                                     f"by {solved.gap[b]:.3g} K", iterations=int(nw.its[b]),
                                     residual=float(solved.gap[b]), last=T_C, history=nw.history[b]))
            continue
        out.append(Answer(solved, b))
    return out


class Solved:
    """The converged points of one batched solve as arrays (:func:`finish`): the losses at the fixed point,
    the network solved with them, the flows and paths; a point's SteadyState made from them when asked for."""

    def __init__(self, fam: Family, net, src, cp: Coupling, template, nw: _Newton, fams=None):
        free, B = ~net.fixed, fam.B
        x_C = nw.x - _C0
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ExtrapolationWarning)
            r = src.result(x_C)
        self.r, self.nw, self.cp, self.nodes = r, nw, cp, list(net.nodes)
        self.parts = src.parts_of(r, x_C.shape[:-1])
        st = solve_linear(net, _sources_matrix(net, cp, self.parts), nw.T, singular="nan")
        self.singular = ~np.isfinite(st.T_K).all(axis=1)       # (a point whose nodes exchange no heat: named)
        self.isolated = isolated_nodes(net, st.G_W_K) if self.singular.any() else [""] * B
        self.gap = np.abs(st.T_K[:, free] @ cp.C.T - nw.x).max(axis=1)
        flows = {k: np.atleast_1d(v) for k, v in st.flows_W.items()}
        self.paths = heat_paths(net, np.column_stack([np.broadcast_to(flows[e.name], (B,)) for e in net.elements]))
        dry = [d if f.models["load_model"][0] == "film" else None for f in (fams or [fam]) for d in f.dry]
        seal = list(net.nodes).index("seal") if "seal" in net.nodes else None
        self.warned = family_warnings(fam.scenes, r, x_C, nw.done & (nw.x.max(axis=1) <= T_LIMIT_K),
                                      dry=dry if any(d is not None for d in dry) else None,
                                      T_seal_C=None if seal is None else st.T_K[:, seal] - _C0)
        self.used = [u for f in (fams or [fam]) for u in [_models_used(f, r, template, cp)] * f.B]
        self.factors = _factor_ranges(r, B)
        contacts = getattr(r, "contacts", None)
        T_cont = (0.5 * (np.asarray(contacts["inner"]["T_C"], float).mean(axis=-1)
                         + np.asarray(contacts["outer"]["T_C"], float).mean(axis=-1)) if contacts else
                  0.5 * (x_C[:, 0] + x_C[:, 1]))
        self.T_all = (st.T_K - _C0).tolist()

        def cols(d):              # {key: (B,) or scalar} → (keys, (B, k) array)
            return list(d), np.reshape([np.broadcast_to(np.asarray(v, float), (B,)) for v in d.values()], (len(d), B)).T
        self.bd, self.flows = cols(r.breakdown_W), cols(flows)
        self.out = cols({k: q for k, (_, q) in self.paths.items()})
        self.free_nodes = [n for n, f in zip(net.nodes, free) if f]
        self.P, self.M, self.T_cont, self.bal = (np.broadcast_to(np.asarray(v, float), (B,)).tolist()
                                                 for v in (r.P_W, r.torque_Nm, T_cont, np.atleast_1d(st.balance_W)))

    def state(self, b: int) -> SteadyState:
        """Point ``b``'s SteadyState."""
        nw, cp = self.nw, self.cp
        T_C = dict(zip(self.nodes, self.T_all[b]))
        row = (lambda c: dict(zip(c[0], c[1][b].tolist())))  # noqa: E731
        return SteadyState(
            T_C=T_C, T_ball_C=T_C[cp.roles["ball"]], P_W=self.P[b], iterations=int(nw.its[b]),
            residual_K=max(float(nw.step[b]), float(self.gap[b])), energy_balance_W=self.bal[b],
            heat_flows_W=row(self.flows), models_used=_point_models_used(self.used[b], nw, b, self.factors),
            history=nw.history[b],
            roles=dict(cp.roles), warnings=self.warned[b], torque_Nm=self.M[b], breakdown_W=row(self.bd),
            T_contacts_C=self.T_cont[b], batch_losses=self.r, row=b, heat_sources_W=_part_sources(cp, self.parts[b],
                                                                                                  self.free_nodes),
            heat_out_W=row(self.out), heat_out_to={k: to for k, (to, _) in self.paths.items()})


class Answer:
    """One converged point of a batched solve (:class:`Solved`): its contact temperature, power and node
    temperatures at once, its SteadyState when asked for."""

    __slots__ = ("solved", "row")

    def __init__(self, solved: Solved, row: int):
        self.solved, self.row = solved, row

    T_contacts_C = property(lambda self: self.solved.T_cont[self.row])
    P_W = property(lambda self: self.solved.P[self.row])

    def node_T(self) -> np.ndarray:
        """Node temperatures [K] (as the state's T_C gives them)."""
        return np.array([t + _C0 for t in self.solved.T_all[self.row]])

    def state(self) -> SteadyState:
        return self.solved.state(self.row)


def _part_sources(cp: Coupling, parts, free_nodes) -> dict:
    """Loss part → {node: W}: the split of each part of a point (parts (n_parts,) [W]) over the network's free
    nodes."""
    out = {}
    for j, name in enumerate(cp.parts):
        nz = np.flatnonzero(cp.S[:, j])
        out[name] = dict(zip([free_nodes[i] for i in nz], (cp.S[nz, j] * parts[j]).tolist()))
    return out
