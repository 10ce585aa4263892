r"""Answers across a model switch: the weighted blend of the answers of each alternative.

Where a point lies in a switch band (:data:`thermobear.models.BLEND_BANDS`) its model choice has
two alternatives (four where two bands meet), each solved in full; the point's answer is

.. math:: y = \sum_k w_k\, y_k, \qquad \sum_k w_k = 1

for every number of the answer that both alternatives have on the same footing — node
temperatures, power, torque, loss breakdown, heat flows and the energy balance (a sum of flows:
the blend of balanced states is balanced to round-off).  Per-contact data (loads, films, regimes)
belongs to one contact model and is reported from the alternative of the largest weight.  The
``blend`` entry of ``models_used`` gives the weights and how far the alternatives differ at the
point: the size of the switch that the blend removes.

If an alternative fails (a named SolverError) the others carry the answer, renormalised, and an
:class:`~thermobear.errors.OutsideValidity` warning says that the answer may step there.
"""
from __future__ import annotations

import dataclasses

import numpy as np

from thermobear.coupled.pipeline import SWITCHED
from thermobear.errors import OutsideValidity
from thermobear.thermal import ThermalNetwork
from thermobear.units import ZERO_C_K

__all__ = ["blend_states", "blend_losses", "switch_label", "StackedBlend", "FilmNetwork"]


def switch_label(models: dict, others: list) -> str:
    """What distinguishes one alternative's models from the others' (e.g. ``load_model=film``)."""
    keys = [k for k in SWITCHED if any(o.get(k, (None,))[0] != models.get(k, (None,))[0] for o in others)]
    return ", ".join(f"{k}={models[k][0]}" for k in keys) or "same models"


def _ok(parts, kind):
    """The parts that delivered (weights renormalised), and the failures as warnings."""
    ok = [(w, r) for w, r in parts if isinstance(r, kind)]
    bad = [(w, r) for w, r in parts if not isinstance(r, kind)]
    total = sum(w for w, _ in ok)
    ws = []
    if bad and ok:
        names = ", ".join(f"{type(r).__name__} (weight {w:.2f})" for w, r in bad)
        ws.append(OutsideValidity(f"model blend: an alternative across a model switch failed ({names}); the answer "
                                  "is that of the others and may step here", quantity="model_blend",
                                  value=sum(w for w, _ in bad), limit="both alternatives solved",
                                  source="thermobear.models.BLEND_BANDS", field="models"))
    return [(w / total, r) for w, r in ok], ws


def _label(parts, models_of):
    labels = []
    for w, r in parts:
        others = [models_of(o) for v, o in parts if o is not r]
        labels.append(f"{w:.3f} × ({switch_label(models_of(r), others)})")
    return " + ".join(labels)


def _wsum(ws, xs):
    """The blending rule, one place: Σ_k w_k x_k summed in the alternatives' order from 0 (Python floats,
    or float arrays elementwise: the same IEEE operations in the same order)."""
    acc = 0
    for w, x in zip(ws, xs):
        acc = acc + w * x
    return acc


def _weighted(parts, get):
    vals = [get(r) for _, r in parts]
    ws = [w for w, _ in parts]
    if all(isinstance(x, float) for x in vals):      # numbers: the same sum in Python floats
        return float(_wsum(ws, vals))
    v = _wsum(ws, [np.asarray(x, float) for x in vals])
    return float(v) if np.ndim(v) == 0 else v


def blend_states(parts, state_type):
    """The blend of steady states ``[(weight, SteadyState or SolverError), ...]`` (module docstring):
    a SteadyState, or the failure of the alternative of the largest weight when none delivered."""
    if len(parts) == 1:
        return parts[0][1]
    ok, ws = _ok(parts, state_type)
    if not ok:
        return max(parts, key=lambda p: p[0])[1]
    if len(ok) == 1:
        st = ok[0][1]
        return dataclasses.replace(st, warnings=list(st.warnings) + ws)
    dom = max(ok, key=lambda p: p[0])[1]
    nodes = list(dom.T_C)
    keys = list(dict.fromkeys(k for _, s in ok for k in s.breakdown_W))
    flows = list(dom.heat_flows_W)
    sources = {p: list(dict.fromkeys(n for _, s in ok for n in s.heat_sources_W.get(p, {})))
               for p in dict.fromkeys(p for _, s in ok for p in s.heat_sources_W)}
    # every blended number of an alternative in one row (a part or key it lacks: 0), blended at once
    X = np.array([[s.T_C[n] for n in nodes]
                  + [s.T_ball_C, s.P_W, s.torque_Nm, s.energy_balance_W, s.T_contacts_C]
                  + [s.breakdown_W.get(k, 0.0) for k in keys] + [s.heat_flows_W[k] for k in flows]
                  + [s.heat_out_W.get(k, 0.0) for k in dom.heat_out_W]
                  + [s.heat_sources_W.get(p, {}).get(n, 0.0) for p, ns in sources.items() for n in ns]
                  for _, s in ok], float)
    y = iter(_wsum([w for w, _ in ok], X).tolist())
    T = X[:, :len(nodes)]
    dT = float(np.abs(T[:, None, :] - T[None, :, :]).max())
    P = X[:, len(nodes) + 1]
    spread = (P.max() - P.min()) / max(float(np.mean(P)), 1e-300)
    used = dict(dom.models_used)
    used["blend"] = (_label(ok, lambda s: s.models_used),
                     f"across a model switch (thermobear.models.BLEND_BANDS): the alternatives differ here by "
                     f"{spread:.2%} in power and {dT:.3g} K at most in a node temperature")
    seen, warned = set(), []
    for w in [w for _, s in ok for w in s.warnings] + ws:
        if str(w) not in seen:
            seen.add(str(w))
            warned.append(w)

    def fill(names):
        return {k: next(y) for k in names}
    T_C = fill(nodes)
    T_ball, P_W, M, bal, T_cont = (next(y) for _ in range(5))
    return dataclasses.replace(
        dom, T_C=T_C, T_ball_C=T_ball, P_W=P_W, torque_Nm=M, energy_balance_W=bal, T_contacts_C=T_cont,
        breakdown_W=fill(keys), heat_flows_W=fill(flows), heat_out_W=fill(dom.heat_out_W),
        heat_sources_W={p: fill(ns) for p, ns in sources.items()},
        iterations=max(s.iterations for _, s in ok), residual_K=max(s.residual_K for _, s in ok),
        models_used=used, warnings=warned)


def blend_losses(parts):
    """The blend of loss results at prescribed temperatures ``[(weight, LossResult), ...]``: power,
    torque and breakdown weighted; per-contact data and the rest from the largest weight."""
    if len(parts) == 1:
        return parts[0][1]
    dom = max(parts, key=lambda p: p[0])[1]
    keys = list(dict.fromkeys(k for _, r in parts for k in r.breakdown_W))
    P = np.array([np.asarray(r.P_W, float) for _, r in parts])
    spread = float(np.max((P.max(axis=0) - P.min(axis=0)) / np.maximum(np.abs(P.mean(axis=0)), 1e-300)))
    used = dict(dom.models_used)
    used["blend"] = (_label(parts, lambda r: r.models_used),
                     f"across a model switch (thermobear.models.BLEND_BANDS): the alternatives differ here by "
                     f"{spread:.2%} in power")
    return dataclasses.replace(
        dom, P_W=_weighted(parts, lambda r: r.P_W), torque_Nm=_weighted(parts, lambda r: r.torque_Nm),
        breakdown_W={k: _weighted(parts, lambda r: r.breakdown_W.get(k, 0.0)) for k in keys}, models_used=used)


class StackedBlend:
    r"""One operating point's model alternatives as one loss source: ``source`` evaluates the K
    alternatives as K stacked points of one batch (one call: their contact sets differ, their loss
    options do not), and the parts and results are weighted with ``weights`` (K,).  The transient's
    heat sources across a switch band (the steady state blends whole answers).

    ``film``: ``(lower, upper, T_lo, T_hi)`` — rows (masks (K,)) of film-load-model alternatives solved with
    their films at T_lo and T_hi [°C]: a row's weight w becomes w (1 − θ) (lower) or w θ (upper),

    .. math:: \theta = \frac{T_f - T_{lo}}{T_{hi} - T_{lo}}, \qquad T_f = \tfrac12 (x_{inner} + x_{outer}),

    the losses interpolated linearly in the film temperature T_f (the mean contact temperature) between two
    load solutions, so that the film loads follow the temperatures continuously (θ held within
    [−0.5, 1.5]: beyond, the caller moves the pair)."""

    def __init__(self, source, weights, film=None):
        self.source, self.w = source, np.asarray(weights, float)
        self.diagonal = source.diagonal and film is None      # θ reads both contact temperatures
        self.K = self.w.size
        self.film = film

    def _stack(self, x_C):
        x = np.asarray(x_C, float)
        return np.repeat(x[..., None, :], self.K, axis=-2)        # (..., n_x) → (..., K, n_x)

    def weights(self, x_C):
        """The weights (K,) or, with ``film``, (..., K) at coupled temperatures (..., n_x) [°C]."""
        if self.film is None:
            return self.w
        lower, upper, T_lo, T_hi = self.film
        x = np.asarray(x_C, float)
        th = np.clip((0.5 * (x[..., 0] + x[..., 1]) - T_lo) / (T_hi - T_lo), -0.5, 1.5)[..., None]
        return np.where(lower, self.w * (1.0 - th), np.where(upper, self.w * th, self.w))

    def parts(self, x_C):
        """Weighted loss parts (..., n_parts) [W] at coupled temperatures (..., n_x) [°C]."""
        if self.film is None:
            return np.einsum("k,...kp->...p", self.w, self.source.parts(self._stack(x_C)))
        return np.einsum("...k,...kp->...p", self.weights(x_C), self.source.parts(self._stack(x_C)))

    def parts_of(self, r, shape):
        """The weighted loss parts (``shape`` + (n_parts,)) [W] of a result of :meth:`result` (the parts
        are linear in the powers it weights)."""
        return self.source.parts_of(r, shape)

    def result(self, x_C):
        """The alternatives' results with power, torque, breakdown and contact powers weighted (the
        per-contact arrays keep the alternatives' axis)."""
        r = self.source.result(self._stack(x_C))
        w = self.weights(x_C)

        def wsum(v):
            v = np.asarray(v, float)
            if v.shape[-1:] != (self.K,):
                return v
            return np.tensordot(v, w, axes=([-1], [0])) if self.film is None else (v * w).sum(axis=-1)
        return dataclasses.replace(r, P_W=wsum(r.P_W), torque_Nm=wsum(r.torque_Nm),
                                   breakdown_W={k: wsum(v) for k, v in r.breakdown_W.items()},
                                   contact_W={k: wsum(v) for k, v in r.contact_W.items()})


@dataclasses.dataclass(frozen=True)
class FilmNetwork(ThermalNetwork):
    """A network between two: the dominant alternative's network with its loads at the two film temperatures
    T_lo, T_hi [°C] of a heat-up piece's film cell (its contact ellipses and speeds differ), the conductances
    interpolated linearly in the film temperature as the losses are (:class:`StackedBlend`;
    :mod:`thermobear.coupled.transient`)."""

    upper: ThermalNetwork = None
    film: tuple = ()                 # (c (n,): the film temperature c · T [K] of the node temperatures T, T_lo, T_hi)

    @classmethod
    def between(cls, lower: ThermalNetwork, upper: ThermalNetwork, c, T_lo: float, T_hi: float):
        """The network of ``lower`` (at T_lo [°C]) and ``upper`` (at T_hi [°C]); ``c`` (n,) the film temperature's
        weights of the node temperatures."""
        return cls(**{f.name: getattr(lower, f.name) for f in dataclasses.fields(ThermalNetwork)}, upper=upper,
                   film=(np.asarray(c, float), T_lo, T_hi))

    def conductances(self, T_K) -> np.ndarray:
        c, T_lo, T_hi = self.film
        th = np.clip((T_K @ c - ZERO_C_K - T_lo) / (T_hi - T_lo), -0.5, 1.5)[..., None]
        return (1.0 - th) * super().conductances(T_K) + th * self.upper.conductances(T_K)
