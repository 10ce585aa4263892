r"""Coupled steady state: losses(T) ↔ thermal network, for one operating point or many at once.

The losses depend on three coupled temperatures x (inner contact, outer contact — each the mean of
ball and race nodes, seed 004 §4.5 — and oil–air mixture); the network turns them into node
temperatures.  The steady operating point solves, for the free node temperatures T_f of every
operating point of a family at once (stacked matrices, one batched solve per iteration):

.. math:: R(T_f) = A_{ff}(T) T_f + A_{fb}(T) T_b - S\, P(C T_f) = 0,
          \qquad J = A_{ff} + \frac{\partial (A T)}{\partial T_f} - S \frac{\partial P}{\partial x} C

with C the coupled-temperature map and S the split of the three loss parts onto the nodes
(:class:`~thermobear.coupled.sources.Coupling`).  ∂P/∂x comes from one loss evaluation at stacked
temperature states (x and x + h; four states for a source whose parts share temperatures), ∂(AT)/∂T
from forward differences of the temperature-dependent conductances (re-evaluated while the steps
exceed 1 K).  Convergence is quadratic to superlinear (5–7 iterations from ambient); each point
stops on its own (max |ΔT_f| ≤ tol_K), and a point that fails does not stop the others.

Stability: the loop gain, the largest real eigenvalue of dG/dx = C A_ff⁻¹ S ∂P/∂x (the losses
through the network), must be < 1 at an equilibrium.  A point whose Newton iteration cannot decide
(gain ≥ 1, a temperature beyond the lubricant's limit, divergence) is decided on the physical
heating path (:func:`thermobear.coupled.fixedpoint.solve_coupled`: Anderson mixing, then Picard from
ambient, which names thermal runaway).

With the film load model the loads depend on the film temperature, taken as the mean contact
temperature of the solution: an outer fixed point on that temperature (a few load updates; each
round's film load distributions solved for the family's points in one batched call, from the last ones, first the
dry loads of the model choice).  Its dry start: the point's dry alternative where that is solved too.

The returned states are full network solves with the converged losses: their energy balance
closes to machine precision, and their coupled temperatures are checked against the fixed point.
"""
from __future__ import annotations

import dataclasses
import warnings
from dataclasses import dataclass, field

import numpy as np

from thermobear.arrays import take
from thermobear.coupled.blend import blend_states
from thermobear.coupled.clearance import clearance_loop
from thermobear.coupled.fixedpoint import solve_coupled
from thermobear.coupled.pipeline import (Family, families, family_contacts, family_film_loads, family_loads,
                                        film_temperature_C, split_failures)
from thermobear.coupled.limits import emit, family_warnings, overloads
from thermobear.coupled.ratings import check_static_safety
from thermobear.coupled.sources import Coupling, family_network, loss_sources, prepare, prepared_for
from thermobear.errors import (ExtrapolationWarning, InputError, NoConvergence, OutsideValidity, SolverError,
                               ThermalRunaway)
from thermobear.loads.api import check_loads, contact_bounds
from thermobear.models import plan_many
from thermobear.scene import Scene
from thermobear.thermal.solve import batched_solve, heat_paths, solve_linear
from thermobear.validity import T_LUBRICANT_REFUSE_C

__all__ = ["SteadyState", "steady_state", "steady_states", "T_LIMIT_K"]

_C0 = 273.15
T_LIMIT_K = T_LUBRICANT_REFUSE_C[1] + _C0     #: an equilibrium beyond the lubricant's limit is runaway
_FILM_TOL_K = 0.1                              #: film temperature fixed point tolerance [K]
_FILM_MAXITER = 10
SCENE_LOADS = ("operation.Fa_N", "operation.Fr_N", "operation.M_Nm", "operation.n_rpm")


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

    @property
    def losses(self):
        """The losses at equilibrium (:class:`~thermobear.losses.LossResult`; the SKF model: its
        result): this point's slice of its family's batched result, taken when asked for."""
        if self.row is None:
            return self.batch_losses
        return take(self.batch_losses, self.row, np.shape(self.batch_losses.P_W)[0])


class _Histories:
    """Per-point convergence histories of the batched Newton iteration, kept as arrays per iteration
    and turned into a point's list of dicts only when asked for (most points never are)."""

    def __init__(self, B: int):
        self.records: list = []            # per iteration: (iteration, points, x [K], step, mean step, P [W])
        self.explicit: dict = {}           # point → a history given whole (the heating path)
        self.B = B

    def add(self, it, idx, x, s, mean, P):
        pos = np.full(self.B, -1)
        pos[idx] = np.arange(idx.size)
        self.records.append((it, pos.tolist(), x, s.tolist(), mean.tolist(), P.tolist()))

    def __getitem__(self, b: int) -> list:
        if b in self.explicit:
            return self.explicit[b]
        return [dict(iteration=it, T_K=x[pos[b]].copy(), residual_K=s[pos[b]], mean_residual_K=mean[pos[b]],
                     P_W=P[pos[b]], step="newton") for it, pos, x, s, mean, P in self.records if pos[b] >= 0]


@dataclass
class _Newton:
    """Per-point outcome of the batched Newton iteration."""

    T: np.ndarray            # (B, n) node temperatures [K]
    x: np.ndarray            # (B, n_x) coupled temperatures [K]
    done: np.ndarray         # (B,) converged to a stable equilibrium
    its: np.ndarray          # (B,) iterations
    step: np.ndarray         # (B,) last step [K]
    gain: np.ndarray         # (B,) loop gain
    history: object          # per point (indexable), list of dicts
    method: tuple = ()       # per point, how it converged


def _slopes(src, cp: Coupling, x_C, h=0.05):
    """Loss parts P (B, n_parts) [W] at x [°C] and ∂P/∂x (B, n_parts, n_x) [W/K] by forward differences."""
    if src.diagonal:       # each part reads its own temperature: x and x + h in one evaluation
        Pm = src.parts(np.stack([x_C, x_C + h]))
        return Pm[0], (Pm[1] - Pm[0])[:, :, None] * cp.incidence()[None] / h
    n = x_C.shape[-1]
    X = np.repeat(x_C[None], n + 1, axis=0)
    for k in range(n):
        X[k + 1, :, k] += h
    Pm = src.parts(X)
    return Pm[0], np.stack([(Pm[k + 1] - Pm[0]) / h for k in range(n)], axis=-1)


def _loop_gain(Aff, SdP, C):
    """Largest real eigenvalue of C A_ff⁻¹ S ∂P/∂x per point (B,) (``SdP`` = S ∂P/∂x, (B, n_free, n_x));
    NaN where it is not defined."""
    M = C @ batched_solve(Aff, SdP)
    ok = np.isfinite(M).all(axis=(1, 2))
    out = np.full(M.shape[0], np.nan)
    if ok.any():
        out[ok] = np.linalg.eigvals(M[ok]).real.max(axis=1)
    return out


def _newton(net, src, cp: Coupling, tol_K, T0=None, maxiter: int = 30, h: float = 0.05) -> _Newton:
    """Batched Newton on the free node temperatures (see the module docstring)."""
    B, free, fixed = net.B, ~net.fixed, net.fixed
    T = net.initial_T_K()
    if T0 is not None:              # a start per point (rows of NaN: the default start)
        T0 = np.asarray(T0, float)
        T = np.where(np.isfinite(T0).all(axis=1, keepdims=True) & ~fixed, T0, T)
    Tb = T[:, fixed]
    done, bad = np.zeros(B, bool), np.zeros(B, bool)
    its, step, gain = np.zeros(B, int), np.full(B, np.inf), np.full(B, np.nan)
    hist = _Histories(B)
    dG = None
    for it in range(1, maxiter + 1):
        live = ~(done | bad)
        if not live.any():
            break
        x = T[:, free] @ cp.C.T
        P, dP = _slopes(src, cp, x - _C0, h)
        fresh = live & (step > 1.0)
        if dG is None or fresh.any():  # the slopes of the conductances re-evaluated while a point's step > 1 K;
            G, dG_new = net.dconductances(T)     # below, each point keeps its last ones (same as alone)
            dG = dG_new if dG is None else [(k, m, np.where(fresh, dn, do)) for (k, m, dn), (_, _, do) in zip(dG_new, dG)]
        else:
            G = net.conductances(T)
        Aff, Afb = net.blocks(G)
        Tf = T[:, free]
        SdP = cp.S @ dP                                          # (B, n_free, n_x)
        R = (Aff @ Tf[..., None] + Afb @ Tb[..., None])[..., 0] - P @ cp.S.T
        J = Aff + net.dAT_free(T, dG) - SdP @ cp.C
        dT = batched_solve(J, -R)
        finite = np.isfinite(dT).all(axis=1)
        bad |= live & ~finite
        live &= finite
        dT = np.where(live[:, None], dT, 0.0)
        s = np.where(live, np.abs(dT).max(axis=1, initial=0.0), np.inf)
        # the loop gain at the first iterate, whenever the step does not shrink, and at the answer
        check = live & ((it == 1) | (s >= step) | (s <= tol_K))
        if check.any():
            gain = np.where(check, _loop_gain(Aff, SdP, cp.C), gain)
        step = np.where(live, s, step)
        dT *= np.minimum(1.0, 50.0 / np.maximum(np.abs(dT).max(axis=1, initial=0.0), 1e-300))[:, None]
        idx = np.flatnonzero(live)
        hist.add(it, idx, x[idx], s[idx], (dT[idx] @ cp.C.T).mean(axis=1), P[idx].sum(axis=1))
        T[:, free] = Tf + dT
        its = np.where(live, it, its)
        conv = live & (s <= tol_K)
        done |= conv
        bad |= live & ~conv & ((gain >= 1.0) | (~np.isfinite(gain)) | ((T[:, free] @ cp.C.T).max(axis=1) > T_LIMIT_K))
    done &= np.isfinite(gain) & (gain < 1.0)
    return _Newton(T=T, x=T[:, free] @ cp.C.T, done=done, its=its, step=step, gain=gain, history=hist,
                   method=("newton",) * B)


def _sources_matrix(net, cp: Coupling, parts) -> np.ndarray:
    """(B, n) node sources [W] of the loss parts (B, n_parts)."""
    P = np.zeros((net.B, len(net.nodes)))
    P[:, ~net.fixed] = parts @ cp.S.T
    return P


def _physical_path(net, src, cp: Coupling, tol_K) -> _Newton:
    """One point (B = 1) decided on the heating path (:func:`~thermobear.coupled.fixedpoint.solve_coupled`:
    Anderson mixing, then Picard from ambient); raises ThermalRunaway or NoConvergence."""
    free, fixed = ~net.fixed, net.fixed
    state = {"T": net.initial_T_K()}
    Tb = state["T"][:, fixed]

    def update(x_K):
        parts = src.parts((np.asarray(x_K) - _C0)[None])
        P = _sources_matrix(net, cp, parts)
        Aff, Afb = net.blocks(net.conductances(state["T"]))   # linearised at the last iterate
        Tf = batched_solve(Aff, P[:, free] - np.einsum("bij,bj->bi", Afb, Tb))
        state["T"] = np.where(fixed, state["T"], 0.0)
        state["T"][:, free] = Tf
        return (Tf @ cp.C.T)[0], float(parts.sum())

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)
        res = solve_coupled(update, (state["T"][:, free] @ cp.C.T)[0], tol_K=tol_K, T_limit_K=T_LIMIT_K)
    x = res.T_K[None]
    T = state["T"]
    hist = _Histories(1)
    hist.explicit[0] = res.history
    return _Newton(T=T, x=x, done=np.array([True]), its=np.array([res.iterations]), step=np.array([res.residual_K]),
                   gain=np.array([res.loop_gain]), history=hist, method=(res.method,))


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


def _point_models_used(used: dict, nw: _Newton, b: int) -> dict:
    out = dict(used)
    out["thermal"] = (used["thermal"][0], f"fixed point on {nw.x.shape[1]} coupled temperatures: {nw.method[b]}, "
                                          f"{int(nw.its[b])} iterations, loop gain {nw.gain[b]:.2f}")
    return out


def _finish(fam: Family, net, src, cp: Coupling, template, nw: _Newton, tol_K) -> list:
    """Per point: a SteadyState from a full network solve with the converged losses, a SolverError,
    or None (not converged: the caller decides it on the heating path)."""
    free = ~net.fixed
    x_C = nw.x - _C0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)
        r = src.result(x_C)
    parts = src.parts_of(r, x_C.shape[:-1])
    st = solve_linear(net, _sources_matrix(net, cp, parts), nw.T)
    gap = np.abs(st.T_K[:, free] @ cp.C.T - nw.x).max(axis=1)
    bal = np.atleast_1d(st.balance_W)
    flows = {k: np.atleast_1d(v) for k, v in st.flows_W.items()}
    paths = heat_paths(net, np.column_stack([np.broadcast_to(flows[e.name], (fam.B,)) for e in net.elements]))
    warned = family_warnings(fam.scenes, r, x_C, nw.done & (nw.x.max(axis=1) <= T_LIMIT_K))
    B = fam.B
    used = _models_used(fam, r, template, cp)
    contacts = getattr(r, "contacts", None)
    T_cont = (0.5 * (np.asarray(contacts["inner"]["T_C"], float).mean(axis=-1)
                     + np.asarray(contacts["outer"]["T_C"], float).mean(axis=-1)) if contacts else
              0.5 * (x_C[:, 0] + x_C[:, 1]))

    def rows(d):              # {key: (B,) or scalar} → per point, its {key: float}
        cols = np.reshape([np.broadcast_to(np.asarray(v, float), (B,)) for v in d.values()], (len(d), B)).T
        return [dict(zip(d, c)) for c in cols.tolist()]
    T_all, bd_all, flows_all = (st.T_K - _C0).tolist(), rows(r.breakdown_W), rows(flows)
    out_all = rows({k: q for k, (_, q) in paths.items()})
    sources_all = _part_sources(cp, parts, [n for n, f in zip(net.nodes, free) if f])
    P_all, M_all, T_cont_all, bal_all = (np.broadcast_to(np.asarray(v, float), (B,)).tolist()
                                         for v in (r.P_W, r.torque_Nm, T_cont, bal))
    out = []
    for b in range(B):
        if not nw.done[b]:
            out.append(None)
            continue
        T_C = dict(zip(net.nodes, T_all[b]))
        hot = {k: v for k, v in T_C.items() if v + _C0 > T_LIMIT_K}
        if hot:
            node = max(hot, key=hot.get)
            out.append(ThermalRunaway(
                f"no equilibrium below {T_LIMIT_K - _C0:g} °C (the lubricant's limit): the network cannot shed "
                f"{parts[b].sum():.4g} W even at that temperature ({node} would reach {hot[node]:.4g} °C); more "
                "cooling, less speed or a thinner oil is needed", iterations=int(nw.its[b]),
                residual=float(nw.step[b]), last=T_C, history=nw.history[b]))
            continue
        if gap[b] > max(10 * tol_K, 1e-4):
            out.append(NoConvergence(f"coupled temperatures of the final network solve differ from the fixed point "
                                     f"by {gap[b]:.3g} K", iterations=int(nw.its[b]), residual=float(gap[b]),
                                     last=T_C, history=nw.history[b]))
            continue
        out.append(SteadyState(
            T_C=T_C, T_ball_C=T_C[cp.roles["ball"]], P_W=P_all[b], iterations=int(nw.its[b]),
            residual_K=max(float(nw.step[b]), float(gap[b])), energy_balance_W=bal_all[b],
            heat_flows_W=flows_all[b], models_used=_point_models_used(used, nw, b), history=nw.history[b],
            roles=dict(cp.roles), warnings=warned[b], torque_Nm=M_all[b], breakdown_W=bd_all[b],
            T_contacts_C=T_cont_all[b], batch_losses=r, row=b, heat_sources_W=sources_all[b],
            heat_out_W=out_all[b], heat_out_to={k: to for k, (to, _) in paths.items()}))
    return out


def _part_sources(cp: Coupling, parts, free_nodes) -> list:
    """Per point, loss part → {node: W}: the split of each part (parts (B, n_parts) [W]) over the
    network's free nodes."""
    per_part = []
    for j, name in enumerate(cp.parts):
        nz = np.flatnonzero(cp.S[:, j])
        q = (cp.S[nz, j][None, :] * parts[:, j][:, None]).tolist()
        per_part.append((name, [free_nodes[i] for i in nz], q))
    return [{name: dict(zip(nodes, q[b])) for name, nodes, q in per_part} for b in range(parts.shape[0])]


def _solve_loaded(fam: Family, load, template, cp: Coupling, tol_K, T0=None) -> list:
    """Steady states of a family with given (batched) loads: Newton for all points, the heating
    path for the points it cannot decide.  Per point a SteadyState or a SolverError."""
    contacts = family_contacts(fam, load)
    over = overloads(fam.scenes, contacts)
    if over:                        # refused points apart; the others solved as a family of their own
        keep = [b for b in range(fam.B) if b not in over]
        out = [over.get(b) for b in range(fam.B)]
        if keep:
            sub = Family(scenes=tuple(fam.scenes[b] for b in keep), index=tuple(fam.index[b] for b in keep),
                         models=fam.models, dry=tuple(fam.dry[b] for b in keep))
            T0k = None if T0 is None else np.asarray(T0)[keep]
            for b, r in zip(keep, _solve_loaded(sub, take(load, np.array(keep), fam.B), template, cp, tol_K, T0k)):
                out[b] = r
        return out
    net = family_network(fam, template, contacts)
    src = loss_sources(fam, contacts)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)
        nw = _newton(net, src, cp, tol_K, T0)
    out = _finish(fam, net, src, cp, template, nw, tol_K)
    for b in [b for b, o in enumerate(out) if o is None]:
        sub = Family(scenes=(fam.scenes[b],), index=(fam.index[b],), models=fam.models, dry=(fam.dry[b],))
        load_b = take(load, b, fam.B) if fam.B > 1 else load
        cs_b = family_contacts(sub, _batched(load_b))
        net_b, src_b = family_network(sub, template, cs_b), loss_sources(sub, cs_b)
        try:
            nw_b = _physical_path(net_b, src_b, cp, tol_K)
        except SolverError as exc:
            out[b] = exc
            continue
        out[b] = _finish(sub, net_b, src_b, cp, template, nw_b, tol_K)[0]
    return out


def _batched(load):
    """A one-point load distribution with a leading batch axis of 1 (the family form)."""
    return take(load, np.array([0]), 1) if np.ndim(load.delta_a) == 0 else load


def _solve_family(fam: Family, tol_K, load=None, prepared=None, starts=None) -> list:
    """Per point of a family: a SteadyState or the exception that stopped it (``starts``: the film
    load model's dry starts already solved, :func:`_film_family`)."""
    try:
        pre = prepared_for(fam.scene, prepared if prepared is not None and prepared.serves(fam.scene) else None)
    except InputError as exc:
        return [exc] * fam.B
    template, cp = pre.template, pre.coupling
    if load is not None:
        return _solve_loaded(fam, load, template, cp, tol_K)
    if fam.models["load_model"][0] == "film":
        return _film_family(fam, template, cp, tol_K, starts)
    out = [None] * fam.B
    pos = {i: k for k, i in enumerate(fam.index)}
    for sub, ld in split_failures(family_loads, fam):
        res = [ld] * sub.B if isinstance(ld, Exception) else _solve_loaded(sub, ld, template, cp, tol_K)
        for i, r in zip(sub.index, res):
            out[pos[i]] = r
    return out


def _points_apart(fam: Family, tol_K, load, prepared, starts=None) -> list:
    """:func:`_solve_family`; when a point's iterate leaves what the models can represent (an
    InputError, e.g. a lubricant past its refusal temperature), each point again on its own, so
    that the error is that point's and the others are solved."""
    try:
        return _solve_family(fam, tol_K, load, prepared, starts)
    except InputError as exc:
        if fam.B == 1:
            return [exc]
    out = []
    for b in range(fam.B):
        one = Family(scenes=(fam.scenes[b],), index=(fam.index[b],), models=fam.models, dry=(fam.dry[b],))
        out += _points_apart(one, tol_K, None if load is None else _batched(take(load, b, fam.B)), prepared, starts)
    return out


def _node_T(st: SteadyState, template) -> np.ndarray:
    return np.array([st.T_C[n] + _C0 for n in template.nodes])


def _film_family(fam: Family, template, cp: Coupling, tol_K, starts=None) -> list:
    """The film load model's fixed point on the film temperature for a family (module docstring):
    a dry start, then film load updates, each followed by a steady state started from the last.

    ``starts``: point (``fam.index``) → ``(state, twin)``, a steady state of the same operating point the
    caller solved already: with ``twin`` the same models but the dry Jones–Harris loads, to a tolerance at
    least as tight as the start's (that point's dry start, not solved again); otherwise another model
    alternative of the point, whose node temperatures start the Newton iteration of its dry start (the
    same equilibrium, reached in fewer steps)."""
    B = fam.B
    pos = {i: k for k, i in enumerate(fam.index)}
    starts = {i: v for i, v in (starts or {}).items() if i in pos}
    T_ref = np.array([film_temperature_C(s) for s in fam.scenes])
    start = np.full((B, len(template.nodes)), np.nan)
    near = start.copy()                   # the dry start's Newton start (NaN: the network's own)
    for i, (st, twin) in starts.items():
        if twin:
            T_ref[pos[i]], start[pos[i]] = st.T_contacts_C, _node_T(st, template)
        else:
            near[pos[i]] = _node_T(st, template)
    cold = [b for b, i in enumerate(fam.index) if not (i in starts and starts[i][1])]
    dry = Family(scenes=tuple(fam.scenes[b] for b in cold), index=tuple(fam.index[b] for b in cold),
                 dry=tuple(fam.dry[b] for b in cold),
                 models={**fam.models, "load_model": ("jones_harris", "start of the film fixed point")})
    for sub, ld in split_failures(family_loads, dry) if cold else ():
        if isinstance(ld, Exception):
            continue          # no dry equilibrium to start from: the film model decides on its own
        rows = [pos[i] for i in sub.index]
        for i, st in zip(sub.index, _solve_loaded(sub, ld, template, cp, max(tol_K, 1e-3), near[rows])):
            if isinstance(st, SteadyState):
                T_ref[pos[i]], start[pos[i]] = st.T_contacts_C, _node_T(st, template)
    out, hist, film = [None] * B, [[] for _ in range(B)], {}
    live = np.arange(B)
    for k in range(1, _FILM_MAXITER + 1):
        if live.size == 0:
            break
        sub = Family(scenes=tuple(fam.scenes[j] for j in live), index=tuple(fam.index[j] for j in live),
                     models=fam.models, dry=tuple(fam.dry[j] for j in live))
        results = {}           # (the film loads start from the last ones: the same loads, other films)
        last = (take(film[live[0]][0], np.array([film[j][1] for j in live]), film[live[0]][2])
                if k > 1 and len({id(film[j][0]) for j in live}) == 1 else None)
        for part, ld in split_failures(family_film_loads, sub, T_ref[live], last):
            idx = [pos[i] for i in part.index]
            if not isinstance(ld, Exception):
                ld, solution = ld
                film.update({j: (solution, r, part.B) for r, j in enumerate(idx)})
            res = [ld] * part.B if isinstance(ld, Exception) else _solve_loaded(part, ld, template, cp, tol_K,
                                                                                start[idx])
            results.update(zip(idx, res))
        nxt = []
        for j in live:
            st = results[j]
            if not isinstance(st, SteadyState):
                out[j] = st
                continue
            T_new = st.T_contacts_C
            hist[j].append(dict(iteration=k, T_film_C=float(T_ref[j]), T_contacts_C=T_new, P_W=st.P_W))
            if abs(T_new - T_ref[j]) <= _FILM_TOL_K:
                st.models_used["load_distribution"] = (
                    "film in the contact law (" + ("high-speed, thermobear.loads.highspeed"
                                                   if fam.models["high_speed"][0] == "yes"
                                                   else "low-speed, thermobear.loads.film") + ")",
                    f"films at the mean contact temperature {T_ref[j]:.2f} °C ({k} load updates from "
                    f"{hist[j][0]['T_film_C']:.2f} °C)")
                st.history = list(st.history) + [dict(h, step="film") for h in hist[j]]
                out[j] = st
                continue
            T_ref[j], start[j] = T_new, _node_T(st, template)
            nxt.append(j)
        live = np.array(nxt, int)
    for j in live:
        h = hist[j]
        out[j] = NoConvergence(f"film load model: the film temperature did not settle within {_FILM_TOL_K} K in "
                               f"{_FILM_MAXITER} load updates (last {h[-2]['T_contacts_C']:.2f} → "
                               f"{h[-1]['T_contacts_C']:.2f} °C)", iterations=_FILM_MAXITER,
                               residual=abs(h[-1]["T_contacts_C"] - h[-1]["T_film_C"]), history=h)
    return out


def steady_states(scenes, *, tol_K: float = 1e-6, load=None, prepared=None) -> list:
    """Coupled steady states of many operating points, solved together.

    Parameters
    ----------
    scenes : list of Scene     the operating points (any mix: they are grouped into families that
                               share bearing, lubricant, network and model choices, each family
                               solved in batched calls)
    tol_K : float              Newton tolerance on the node temperatures [K]
    load : LoadDistribution    optional loads to use instead of the model's (one scene, or a batch
                               matching a single family; the clearance loop does not apply: the loads
                               are given)
    prepared : Prepared        :func:`~thermobear.coupled.sources.prepare` of a family, reused for the
                               points it serves (the others are prepared here)

    Returns
    -------
    list   per scene, its :class:`SteadyState`, or the InputError / SolverError that stopped it
           (a failing point never stops the others); points with ``models.clearance`` mounted or
           operating at their clearance's fixed point (:func:`~thermobear.coupled.clearance.clearance_loop`;
           a consumed clearance: :class:`~thermobear.errors.ThermalPreloadRunaway`)
    """
    scenes = list(scenes)
    out = _steady_states(scenes, tol_K=tol_K, load=load, prepared=prepared)
    if load is None:
        out = clearance_loop(scenes, out, lambda scs: _steady_states(scs, tol_K=tol_K, prepared=prepared))
    seen: set = set()
    emit([w for r in out if isinstance(r, SteadyState) for w in r.warnings if not (str(w) in seen or seen.add(str(w)))])
    return out


def _steady_states(scenes, *, tol_K: float = 1e-6, load=None, prepared=None) -> list:
    """:func:`steady_states` at each bearing's own clearance (no clearance loop, warnings not emitted)."""
    scenes = list(scenes)
    for k, sc in enumerate(scenes):
        if not isinstance(sc, Scene):
            raise InputError(f"scenes[{k}]", type(sc).__name__, "a thermobear Scene")
        if sc.T_C is not None:
            raise InputError("operation.T_C", sc.T_C, "the scene prescribes its temperature: use solve() "
                             "or remove operation.T_C to solve the thermal network")
    out: list = [None] * len(scenes)
    alternatives: list = _refused(scenes)
    todo = [k for k, a in enumerate(alternatives) if a is None]
    for k, alts in zip(todo, plan_many([scenes[k] for k in todo])):
        alternatives[k] = alts
    jobs, plans, owner, alts_of = [], [], [], {}       # one job per model alternative of a point
    for i, (sc, alts) in enumerate(zip(scenes, alternatives)):
        if isinstance(alts, Exception):
            out[i] = alts
            continue
        if load is not None:                  # injected loads: one model, the dominant one
            alts = [dataclasses.replace(max(alts, key=lambda a: a.weight), weight=1.0)]
        for a in alts:
            jobs.append(sc)
            plans.append((a.models, a.dry))
            owner.append((i, a.weight))
            alts_of.setdefault(i, []).append(len(jobs) - 1)
    fams, _ = families(jobs, plans)
    if load is not None and len(fams) != 1:
        raise InputError("load", "LoadDistribution", "injected loads need the scenes of one family")
    res: list = [None] * len(jobs)
    with warnings.catch_warnings():
        # property calls at intermediate iterates may lie beyond a correlation's data: only the answer
        # counts, and its validity is checked on its own (SteadyState.warnings, limits.point_warnings)
        warnings.simplefilter("ignore", OutsideValidity)
        shared: list = [prepared] if prepared is not None else []   # one prepare per machine of this call
        twins = _dry_twins(owner, plans)
        # the dry families first: their answers are the dry starts of the film load model's fixed points
        for fam in sorted(fams, key=lambda f: f.models["load_model"][0] == "film"):
            pre = next((p for p in shared if p.serves(fam.scene)), None)
            if pre is None and fam.scene.network is not None:
                try:
                    pre = prepare(fam.scene)
                    shared.append(pre)
                except InputError:
                    pre = None              # the family's own solve names the error per point
            starts = _starts(fam, twins, owner, alts_of, plans, res)
            for j, r in zip(fam.index, _points_apart(fam, tol_K, None if load is None else _batched(load), pre,
                                                     starts)):
                res[j] = r
    for i, ks in alts_of.items():
        out[i] = blend_states([(owner[k][1], res[k]) for k in ks], SteadyState)
    return out


def _refused(scenes) -> list:
    """Per scene, before any solve: the InputError of loads no answer exists for
    (:func:`~thermobear.loads.api.check_loads`, named as the scene does, then the static safety), or None.
    The loads of the scenes of one bearing are checked in one call; where it refuses, scene by scene."""
    out: list = [None] * len(scenes)
    groups: dict = {}
    for k, sc in enumerate(scenes):
        groups.setdefault((sc.bearing, sc.M is None, sc.My is None), []).append(k)
    for (brg, no_M, no_My), ks in groups.items():
        bounds, checked = contact_bounds(brg), False
        if len(ks) > 1:
            def col(attr):
                return np.array([getattr(scenes[k], attr) for k in ks], float)
            F = [col("Fa"), col("Fr"), None if no_M else col("M"), col("n_rpm"), col("Fz"), None if no_My else col("My")]
            try:             # (a value that is not a number skips the other checks: then scene by scene)
                check_loads(brg, *F[:4], Fz=F[4], My=F[5], names=SCENE_LOADS, bounds=bounds)
                checked = all(np.isfinite(v).all() for v in F if v is not None)
            except InputError:
                pass                          # said scene by scene below
        for k in ks:
            sc = scenes[k]
            try:
                if not checked:
                    check_loads(brg, sc.Fa, sc.Fr, sc.M, sc.n_rpm, Fz=sc.Fz, My=sc.My, names=SCENE_LOADS, bounds=bounds)
                check_static_safety(sc)
            except InputError as exc:
                out[k] = exc
    return out


def _dry_twins(owner, plans) -> dict:
    """Job → job: for a film-load-model alternative of a point, its alternative with the same model
    choices but the dry Jones–Harris loads (the film fixed point's dry start), where the point has one."""
    def sig(models):
        return tuple(sorted((k, repr(v[0])) for k, v in models.items() if k != "load_model"))
    dry = {(i, sig(m)): j for j, ((i, _), (m, _)) in enumerate(zip(owner, plans))
           if m["load_model"][0] == "jones_harris"}
    out = {}
    for j, ((i, _), (m, _)) in enumerate(zip(owner, plans)):
        if m["load_model"][0] == "film" and (i, sig(m)) in dry:
            out[j] = dry[(i, sig(m))]
    return out


def _starts(fam: Family, twins: dict, owner, alts_of, plans, res) -> dict:
    """Job → (steady state, twin) for the points of a film family (:func:`_film_family`): its dry twin's
    answer, else the answer of another alternative of the same point (``alts_of``: point → its jobs) already
    solved (dry loads first)."""
    if fam.models["load_model"][0] != "film":
        return {}
    out = {}
    for j in fam.index:
        if j in twins and isinstance(res[twins[j]], SteadyState):
            out[j] = (res[twins[j]], True)
            continue
        same = [k for k in alts_of[owner[j][0]] if isinstance(res[k], SteadyState)]
        if same:
            k = min(same, key=lambda k: plans[k][0]["load_model"][0] != "jones_harris")
            out[j] = (res[k], False)
    return out


def steady_state(scene: Scene, *, tol_K: float = 1e-6, load=None, prepared=None) -> SteadyState:
    """Coupled steady state of a scene: losses(T) ↔ thermal network, to a fixed point.

    See the module docstring for the method.  ``load`` uses the given load distribution instead of
    the one the scene's models give; ``prepared`` the :func:`~thermobear.coupled.sources.prepare` of
    its family, reused (many operating points of one machine).

    Raises
    ------
    ThermalRunaway, NoConvergence   no stable equilibrium (with the history)
    InputError                      a scene the models cannot represent

    >>> import thermobear as tb
    >>> st = steady_state(tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")))
    >>> bool(abs(st.energy_balance_W) <= 1e-9 * st.P_W), bool(st.T_C["inner_ring"] > 30.0)
    (True, True)
    """
    if prepared is not None:
        prepared_for(scene, prepared)                    # refuse one prepared for another family
    r = steady_states([scene], tol_K=tol_K, load=load, prepared=prepared)[0]
    if isinstance(r, Exception):
        raise r
    return r
