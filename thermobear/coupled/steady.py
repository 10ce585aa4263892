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

The model alternatives of the points (two to four inside a switch band, :mod:`thermobear.coupled.blend`) form
families that differ only in the load model and the high-speed form: they share the contact model, the losses
and the network, and are solved **stacked** on the batch axis (:func:`~thermobear.coupled.pipeline.stack_key`;
Newton method: :mod:`thermobear.coupled.newton`): the dry families with the film families' dry starts in one
batched Newton iteration, then each round of the film fixed points of every film family in one more — loads
solved per family, contact sets, networks and iterations shared.  A point's iterates are its own, so the
stacked answers are those of each family solved alone.

The returned states are full network solves with the converged losses: their energy balance
closes to machine precision, and their coupled temperatures are checked against the fixed point.
"""
from __future__ import annotations

import dataclasses
import warnings
from typing import NamedTuple

import numpy as np

from thermobear.arrays import instance_of, take
from thermobear.coupled.blend import blend_states
from thermobear.coupled.clearance import clearance_loop
from thermobear.coupled.preload import preload_loop
from thermobear.coupled.newton import _C0, T_LIMIT_K, _newton, _physical_path, _slopes  # noqa: F401
from thermobear.coupled.pipeline import (Family, concat_loads, families, family_contacts, family_film_loads,
                                        family_loads, film_temperature_C, split_failures, stack_families, stack_key)
from thermobear.coupled.limits import emit, overloads
from thermobear.coupled.ratings import check_static_safety
from thermobear.coupled.sources import Coupling, family_network, loss_sources, prepare, prepared_for
from thermobear.coupled.states import Answer, SteadyState, finish
from thermobear.errors import (ExtrapolationWarning, InputError, NoConvergence, OutsideValidity, SolverError,
                               ThermalRunaway)
from thermobear.loads.api import check_loads, contact_bounds
from thermobear.models import plan_many
from thermobear.rating.life import stated_ratings
from thermobear.scene import Scene
from thermobear.schema import Field, check_value

__all__ = ["SteadyState", "steady_state", "steady_states", "T_LIMIT_K"]

_FILM_TOL_K = 0.1                              #: film temperature fixed point tolerance [K]
_FILM_MAXITER = 20
_FILM_JUMP_K = 1e-3                            #: a bracket this narrow with answers apart by > the tolerance: a jump [K]
_FILM_HOT_C = T_LIMIT_K - _C0 - 1.0             #: the answer taken for loads whose equilibrium runs away [°C]
_TOL_K = Field.number("K", 0.0, lo_open=True)  #: what tol_K accepts: a finite tolerance > 0 [K]
SCENE_LOADS = ("operation.Fa_N", "operation.Fr_N", "operation.M_Nm", "operation.n_rpm")


class _Part(NamedTuple):
    """The points of one family in a stacked solve (:func:`_solve_rows`)."""

    fam: Family
    load: object                   # their (batched) LoadDistribution
    T0: object = None              # (B, n) Newton starts [K] (rows of NaN: the network's), or None
    tol_K: float | None = None     # their Newton tolerance [K] (None: the solve's)


def _solve_rows(parts, template, cp: Coupling, tol_K, lazy: bool = False) -> list:
    """Steady states of families with given (batched) loads, stacked on the batch axis: ``parts``
    :class:`_Part` s (or their tuples) of one :func:`~thermobear.coupled.pipeline.stack_key`
    (e.g. the alternatives of points across a model switch: their own loads, the same contact model, losses and
    network).  One contact set, one network and one Newton iteration for all their points (each point's
    iterates its own, as solved alone), the heating path for the points it cannot decide.  Per part, per
    point a SteadyState (``lazy``: its :class:`~thermobear.coupled.states.Answer`) or a SolverError."""
    parts = [_Part(*p) for p in parts]
    fams, sizes = [p.fam for p in parts], [p.fam.B for p in parts]
    fam, cf = stack_families(fams)
    load = concat_loads([p.load for p in parts], sizes)
    T0 = None if all(p.T0 is None for p in parts) else np.concatenate(
        [np.full((p.fam.B, len(template.nodes)), np.nan) if p.T0 is None else np.asarray(p.T0, float) for p in parts])
    tol = np.concatenate([np.full(p.fam.B, tol_K if p.tol_K is None else p.tol_K) for p in parts])
    contacts = family_contacts(fam, load, cf)
    over = overloads(fam.scenes, contacts)
    cut = np.cumsum([0] + sizes)
    if over:                        # refused points apart; the others solved as a stack of their own
        out, kept = [[over.get(a + b) for b in range(B)] for a, B in zip(cut, sizes)], []
        for k, ((f, ld, t, tk), a, B) in enumerate(zip(parts, cut, sizes)):
            keep = [b for b in range(B) if a + b not in over]
            if keep:
                sub = Family(scenes=tuple(f.scenes[b] for b in keep), index=tuple(f.index[b] for b in keep),
                             models=f.models, dry=tuple(f.dry[b] for b in keep))
                kept.append((k, keep, _Part(sub, take(ld, np.array(keep), B),
                                            None if t is None else np.asarray(t)[keep], tk)))
        for (k, keep, _), res in zip(kept, _solve_rows([p for _, _, p in kept], template, cp, tol_K, lazy) if kept
                                     else ()):
            for b, r in zip(keep, res):
                out[k][b] = r
        return out
    net = family_network(fam, template, contacts)
    src = loss_sources(fam, contacts)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)
        nw = _newton(net, src, cp, tol if tol.min() < tol.max() else float(tol[0]), T0)
    out = finish(fam, net, src, cp, template, nw, tol, fams)
    for row in [r for r, o in enumerate(out) if o is None]:
        k = int(np.searchsorted(cut, row, side="right")) - 1
        (f, ld, _, _), b = parts[k], row - cut[k]
        sub = Family(scenes=(f.scenes[b],), index=(f.index[b],), models=f.models, dry=(f.dry[b],))
        cs_b = family_contacts(sub, _batched(take(ld, b, f.B) if f.B > 1 else ld))
        net_b, src_b = family_network(sub, template, cs_b), loss_sources(sub, cs_b)
        try:
            nw_b = _physical_path(net_b, src_b, cp, float(tol[row]))
        except SolverError as exc:
            out[row] = exc
            continue
        out[row] = finish(sub, net_b, src_b, cp, template, nw_b, tol[row:row + 1])[0]
    if not lazy:
        out = [o.state() if isinstance(o, Answer) else o for o in out]
    return [out[a:a + B] for a, B in zip(cut, sizes)]


def _solve_loaded(fam: Family, load, template, cp: Coupling, tol_K, T0=None) -> list:
    """:func:`_solve_rows` of one family."""
    return _solve_rows([(fam, load, T0)], template, cp, tol_K)[0]


def _batched(load):
    """A one-point load distribution with a leading batch axis of 1 (the family form)."""
    return take(load, np.array([0]), 1) if np.ndim(load.delta_a) == 0 else load


def _node_T(st, template) -> np.ndarray:
    """Node temperatures [K] of a SteadyState or an :class:`~thermobear.coupled.states.Answer`."""
    return st.node_T() if isinstance(st, Answer) else np.array([st.T_C[n] + _C0 for n in template.nodes])


def _is_film(fam: Family) -> bool:
    return fam.models["load_model"][0] == "film"


def next_film_temperature(history) -> float:
    r"""The next film temperature [°C] of a point's film fixed point, from its load updates so far
    (``history``: dicts with ``T_film_C``, the film temperature of the loads, and ``T_contacts_C``, the
    mean contact temperature of the answer on them).

    Plain substitution, :math:`T_{k+1} = T_c(T_k)`, while it contracts.  Once the residual
    :math:`r(T) = T_c(T) - T` changes sign without halving (the loads' response to the film
    temperature is a loop gain ≤ −1: a cold start, where the films at the cold temperature lift the
    balls into a loss that heats them past it, and back), the root of r between the last two film
    temperatures of opposite residual by regula falsi with the Illinois modification (Dowell &
    Jarratt 1971), which keeps the bracket and converges superlinearly:

    .. math:: T_{k+1} = T_k - r_k \frac{T_k - T_j}{r_k - w\,r_j}, \qquad w = 2^{-(m-1)}

    with j the last update of opposite residual and m the number of the latest updates on r_k's side.

    References
    ----------
    .. [1] Dowell, M. & Jarratt, P. (1971). A modified regula falsi method for computing the root of an
       equation. BIT 11, 168–174.

    Examples
    --------
    >>> h = [dict(T_film_C=-11.0, T_contacts_C=47.8), dict(T_film_C=47.8, T_contacts_C=-10.9)]
    >>> round(next_film_temperature(h), 2)
    18.43
    >>> next_film_temperature(h[:1])          # substitution
    47.8
    """
    T, r, j = _bracket(history)
    if j is None:
        return history[-1]["T_contacts_C"]
    m = len(r) - 1 - j                          # the latest updates on r[-1]'s side (since j)
    w = 0.5 ** (m - 1)
    return T[-1] - r[-1] * (T[-1] - T[j]) / (r[-1] - w * r[j])


def _bracket(history):
    """(film temperatures, residuals, j): j the last update whose residual is opposite to the last one's
    once the substitution oscillates without halving (None: substitution goes on)."""
    T = [e["T_film_C"] for e in history]
    r = [e["T_contacts_C"] - e["T_film_C"] for e in history]
    oscillates = any(a * b < 0 and abs(b) > 0.5 * abs(a) for a, b in zip(r[:-1], r[1:]))
    opposite = [k for k in range(len(r) - 1) if r[k] * r[-1] < 0]
    return T, r, opposite[-1] if oscillates and opposite else None


def _film_jump(history) -> NoConvergence | None:
    """The named failure of a film fixed point whose bracket has closed (to ``_FILM_JUMP_K``) on a jump
    of the answer (answers on both sides still apart by more than the tolerance), else None."""
    T, r, j = _bracket(history)
    if j is None or abs(T[-1] - T[j]) > _FILM_JUMP_K:
        return None
    a, b = history[j], history[-1]

    def answer(e):
        return (f"no equilibrium below {_FILM_HOT_C + 1.0:g} °C" if e.get("runaway") else
                f"{e['T_contacts_C']:.2f} °C ({e['P_W']:.4g} W)")
    return NoConvergence(
        f"film load model: no film temperature fixed point — at film temperatures {a['T_film_C']:.2f} and "
        f"{b['T_film_C']:.2f} °C the answers are {answer(a)} and {answer(b)}: the loads or the thermal equilibrium "
        "jump there (a ball lifting off, or two equilibria of losses that rise with temperature, e.g. a starved cold "
        "start); the heat-up from ambient (thermobear transient) shows where the bearing settles",
        iterations=len(history), residual=abs(r[-1]), history=history)


class _FilmRows:
    """The film load model's fixed point on the film temperature for the points of a family (module
    docstring): a dry start, then film load updates, each followed by a steady state started from the last,
    until the film temperature moves by ≤ ``_FILM_TOL_K``.  Driven round by round (:func:`_solve_stack`), so
    that the rounds of several families share one stacked solve."""

    def __init__(self, fam: Family, template):
        self.fam, self.template = fam, template
        self.pos = {i: k for k, i in enumerate(fam.index)}
        self.T_ref = np.array([film_temperature_C(s) for s in fam.scenes])
        self.start = np.full((fam.B, len(template.nodes)), np.nan)
        self.out, self.hist, self.film = [None] * fam.B, [[] for _ in range(fam.B)], {}
        self.live, self.k, self.results = np.arange(fam.B), 0, {}

    def started(self, i, st: SteadyState):
        """Point ``i``'s dry start: the answer of its dry twin or of its own dry start."""
        self.T_ref[self.pos[i]], self.start[self.pos[i]] = st.T_contacts_C, _node_T(st, self.template)

    def dry(self, index) -> Family:
        """The family of the dry starts of points ``index`` (the dry Jones–Harris loads of the model choice)."""
        f, rows = self.fam, [self.pos[i] for i in index]
        return Family(scenes=tuple(f.scenes[b] for b in rows), index=tuple(index), dry=tuple(f.dry[b] for b in rows),
                      models={**f.models, "load_model": ("jones_harris", "start of the film fixed point")})

    def round(self) -> list:
        """The next load update: ``[(sub-family, film loads, Newton starts), ...]`` of the live points (a
        sub-family whose loads failed goes to :attr:`results`); the loads start from the last ones."""
        self.k += 1
        f, live, film = self.fam, self.live, self.film
        sub = Family(scenes=tuple(f.scenes[j] for j in live), index=tuple(f.index[j] for j in live),
                     models=f.models, dry=tuple(f.dry[j] for j in live))
        last = (take(film[live[0]][0], np.array([film[j][1] for j in live]), film[live[0]][2])
                if self.k > 1 and len({id(film[j][0]) for j in live}) == 1 else None)
        out, self.results = [], {}
        for part, ld in split_failures(family_film_loads, sub, self.T_ref[live], last):
            idx = [self.pos[i] for i in part.index]
            if isinstance(ld, Exception):
                self.results.update((j, ld) for j in idx)
                continue
            ld, solution = ld
            film.update({j: (solution, r, part.B) for r, j in enumerate(idx)})
            out.append((part, ld, self.start[idx]))
        return out

    def update(self):
        """The load update's answers (:attr:`results`, point → SteadyState or exception): the points whose
        film temperature settled are done, the others go on from their answer."""
        nxt, k, hs = [], self.k, self.fam.models["high_speed"][0] == "yes"
        for j in self.live:
            st, h = self.results[j], self.hist[j]
            if isinstance(st, ThermalRunaway) and self.T_ref[j] < _FILM_HOT_C:
                # the loads of films colder than the limit run away: the answer lies beyond the limit, where the
                # films are thinner: a residual toward it (not the point's verdict: loads at hot films decide)
                h.append(dict(iteration=k, T_film_C=float(self.T_ref[j]), T_contacts_C=_FILM_HOT_C,
                              P_W=float(st.history[-1]["P_W"]) if st.history else 0.0, runaway=True))
                self.out[j] = _film_jump(h)
                if self.out[j] is None:
                    self.T_ref[j], self.start[j] = next_film_temperature(h), np.nan
                    nxt.append(j)
                continue
            if not isinstance(st, Answer):
                self.out[j] = st
                continue
            T_new = st.T_contacts_C
            h.append(dict(iteration=k, T_film_C=float(self.T_ref[j]), T_contacts_C=T_new, P_W=st.P_W))
            if abs(T_new - self.T_ref[j]) <= _FILM_TOL_K:
                st = st.state()
                st.models_used["load_distribution"] = (
                    "film in the contact law (" + ("high-speed, thermobear.loads.highspeed" if hs
                                                   else "low-speed, thermobear.loads.film") + ")",
                    f"films at the mean contact temperature {self.T_ref[j]:.2f} °C ({k} load updates from "
                    f"{h[0]['T_film_C']:.2f} °C)")
                st.history = list(st.history) + [dict(e, step="film") for e in h]
                self.out[j] = st
                continue
            jump = _film_jump(h)
            if jump is not None:
                self.out[j] = jump
                continue
            self.T_ref[j], self.start[j] = next_film_temperature(h), _node_T(st, self.template)
            nxt.append(j)
        self.live = np.array(nxt, int)
        if k < _FILM_MAXITER:
            return
        for j in self.live:
            h = self.hist[j]
            self.out[j] = NoConvergence(
                f"film load model: the film temperature did not settle within {_FILM_TOL_K} K in {_FILM_MAXITER} "
                f"load updates (last {h[-2]['T_contacts_C']:.2f} → {h[-1]['T_contacts_C']:.2f} °C)",
                iterations=_FILM_MAXITER, residual=abs(h[-1]["T_contacts_C"] - h[-1]["T_film_C"]), history=h)
        self.live = self.live[:0]


def _solve_stack(fams, tol_K, template, cp: Coupling, res: list, starts_of, twin_of: dict):
    """The families of one stack key (:func:`~thermobear.coupled.pipeline.stack_key`), solved together into
    ``res`` (job → answer): the dry families and the film families' dry starts in one stacked solve, then the
    film fixed points' load updates, each round one stacked solve of every film family's live points.

    ``starts_of(fam)``: point → ``(state, twin)`` of the answers solved so far (:func:`_starts`): with ``twin``
    the point's dry start (its models on the dry Jones–Harris loads, to this tolerance), otherwise another
    alternative of the point, whose node temperatures start its dry start's Newton iteration (the same
    equilibrium, reached in fewer steps); ``twin_of``: job → its dry twin's job.  A dry start is solved to
    1e-3 K (or ``tol_K`` if larger), from the network's start where no other alternative is solved yet."""
    films = [_FilmRows(f, template) for f in fams if _is_film(f)]
    here = {i for f in fams if not _is_film(f) for i in f.index}      # solved in the first stacked solve
    tried: set = set()
    for first in (True, False):
        parts, who = [], []
        for f in [f for f in fams if not _is_film(f)] if first else ():
            for sub, ld in split_failures(family_loads, f):
                if isinstance(ld, Exception):
                    for i in sub.index:
                        res[i] = ld
                    continue
                parts.append((sub, ld, None))
                who.append(None)
        for fs in films:
            given, cold = starts_of(fs.fam), {}
            for i in [i for i in fs.fam.index if i not in tried]:
                got = given.get(i)
                if got is not None and got[1]:
                    fs.started(i, got[0])
                elif not (first and twin_of.get(i) in here):      # (else: its twin's answer, after this solve)
                    cold[i] = np.full(len(template.nodes), np.nan) if got is None else _node_T(got[0], template)
                else:
                    continue
                tried.add(i)
            for sub, ld in split_failures(family_loads, fs.dry(list(cold))) if cold else ():
                if not isinstance(ld, Exception):   # (no dry equilibrium to start from: the film model decides alone)
                    parts.append(_Part(sub, ld, np.array([cold[i] for i in sub.index]), max(tol_K, 1e-3)))
                    who.append(fs)
        for p, fs, out in zip(parts, who, _solve_rows(parts, template, cp, tol_K, lazy=True) if parts else ()):
            for i, r in zip(p[0].index, out):
                if fs is None:
                    res[i] = r.state() if isinstance(r, Answer) else r
                elif isinstance(r, Answer):
                    fs.started(i, r)
    while active := [fs for fs in films if fs.live.size]:
        parts, who = [], []
        for fs in active:
            for p in fs.round():
                parts.append(p)
                who.append(fs)
        for p, fs, out in zip(parts, who, _solve_rows(parts, template, cp, tol_K, lazy=True) if parts else ()):
            fs.results.update(zip((fs.pos[i] for i in p[0].index), out))
        for fs in active:
            fs.update()
    for fs in films:
        for i, r in zip(fs.fam.index, fs.out):
            res[i] = r


def _solve_family(fam: Family, tol_K, load=None, prepared=None, ctx=None) -> list:
    """Per point of a family: a SteadyState or the exception that stopped it (``ctx``: ``(res, starts_of,
    twin_of)`` of :func:`_solve_stack`; with injected ``load`` none)."""
    try:
        pre = prepared_for(fam.scene, prepared if prepared is not None and prepared.serves(fam.scene) else None)
    except InputError as exc:
        return [exc] * fam.B
    if load is not None:
        return _solve_loaded(fam, load, pre.template, pre.coupling, tol_K)
    _solve_stack([fam], tol_K, pre.template, pre.coupling, *ctx)
    return [ctx[0][i] for i in fam.index]


def _points_apart(fam: Family, tol_K, load, prepared, ctx=None) -> list:
    """:func:`_solve_family`; when a point's iterate leaves what the models can represent (an
    InputError, e.g. a lubricant past its refusal temperature), each point again on its own, so
    that the error is that point's and the others are solved."""
    try:
        return _solve_family(fam, tol_K, load, prepared, ctx)
    except InputError as exc:
        if fam.B == 1:
            return [exc]
    out = []
    for b in range(fam.B):
        one = Family(scenes=(fam.scenes[b],), index=(fam.index[b],), models=fam.models, dry=(fam.dry[b],))
        out += _points_apart(one, tol_K, None if load is None else _batched(take(load, b, fam.B)), prepared, ctx)
    return out


def _solve_group(fams, tol_K, load, prepared, ctx):
    """The families of one stack key into ``ctx[0]`` (job → answer): stacked (:func:`_solve_stack`); where an
    InputError stops the stack, family by family (the dry ones first), then point by point."""
    if load is None and len(fams) > 1:
        try:
            pre = prepared_for(fams[0].scene, prepared if prepared is not None and prepared.serves(fams[0].scene)
                               else None)
            _solve_stack(fams, tol_K, pre.template, pre.coupling, *ctx)
            return
        except InputError:
            pass
    for fam in sorted(fams, key=_is_film):
        for i, r in zip(fam.index, _points_apart(fam, tol_K, None if load is None else _batched(load), prepared, ctx)):
            ctx[0][i] = r


def steady_states(scenes, *, tol_K: float = 1e-6, load=None, prepared=None) -> list:
    """Coupled steady states of many operating points, solved together.

    Parameters
    ----------
    scenes : list of Scene     the operating points (any mix: they are grouped into families that
                               share bearing, lubricant, network and model choices, each family
                               solved in batched calls)
    tol_K : float              Newton tolerance on the node temperatures [K]
    load : LoadDistribution    optional loads to use instead of the model's (one scene, or a batch
                               matching a single family; the clearance and preload loops do not apply: the
                               loads are given)
    prepared : Prepared        :func:`~thermobear.coupled.sources.prepare` of a family, reused for the
                               points it serves (the others are prepared here)

    Returns
    -------
    list   per scene, its :class:`SteadyState`, or the InputError / SolverError that stopped it
           (a failing point never stops the others); points with ``models.clearance`` mounted or
           operating at their clearance's fixed point (:func:`~thermobear.coupled.clearance.clearance_loop`;
           a negative one is a radial preload; one that runs away: :class:`~thermobear.errors.ThermalPreloadRunaway`);
           one bearing of a preloaded pair (``[bearing] arrangement``) at its preload's fixed point
           (:func:`~thermobear.coupled.preload.preload_loop`; a runaway: ThermalPreloadRunaway)
    """
    if isinstance(scenes, Scene) or not hasattr(scenes, "__iter__"):
        raise InputError("scenes", type(scenes).__name__, "a list of Scene (steady_state solves one scene)")
    scenes, tol_K = list(scenes), check_value(tol_K, _TOL_K, "tol_K")

    def solve(scs):                      # at the clearance's fixed point (the points whose clearance is fitted)
        return clearance_loop(scs, _steady_states(scs, tol_K=tol_K, prepared=prepared),
                              lambda again: _steady_states(again, tol_K=tol_K, prepared=prepared))
    out = (_steady_states(scenes, tol_K=tol_K, load=load, prepared=prepared) if load is not None else
           preload_loop(scenes, solve))
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
        ctx = (res, lambda fam: _starts(fam, twins, owner, alts_of, plans, res), twins)
        groups: dict = {}       # the alternatives of a point share a stack key: each group solved on its own
        for fam in fams:
            groups.setdefault(stack_key(fam), []).append(fam)
        for group in groups.values():
            pre = next((p for p in shared if p.serves(group[0].scene)), None)
            if pre is None and group[0].scene.network is not None:
                try:
                    pre = prepare(group[0].scene)
                    shared.append(pre)
                except InputError:
                    pre = None              # the family's own solve names the error per point
            _solve_group(group, tol_K, load, pre, ctx)
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
        bounds, checked, C0 = contact_bounds(brg), False, None
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
                if C0 is None and not (brg.kind == "thrust" and (sc.Fr or sc.Fz)):
                    C0 = stated_ratings(brg)[1]            # (the one bearing's C0, for its scenes)
                check_static_safety(sc, C0)
            except InputError as exc:
                out[k] = exc
    return out


def _dry_twins(owner, plans) -> dict:
    """Job → job: for a film-load-model alternative of a point, its alternative with the same model
    choices but the dry Jones–Harris loads (the film fixed point's dry start), where the point has one (the
    alternatives of a point differ only in the switched choices, :data:`~thermobear.coupled.pipeline.SWITCHED`:
    the same high-speed form)."""
    dry = {(i, m["high_speed"][0]): j for j, ((i, _), (m, _)) in enumerate(zip(owner, plans))
           if m["load_model"][0] == "jones_harris"}
    out = {}
    for j, ((i, _), (m, _)) in enumerate(zip(owner, plans)):
        if m["load_model"][0] == "film" and (i, m["high_speed"][0]) in dry:
            out[j] = dry[(i, m["high_speed"][0])]
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
    r = steady_states([instance_of(scene, Scene, "scene")], tol_K=tol_K, load=load, prepared=prepared)[0]
    if isinstance(r, Exception):
        raise r
    return r
