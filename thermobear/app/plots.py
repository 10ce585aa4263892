r"""Plots of results (matplotlib, Agg backend: files only, no display needed).

Every function writes one PNG and returns its path:

* :func:`plot_ball_loads`         per-ball contact load and lubrication regime (polar)
* :func:`plot_load_distribution`  per-ball inner / outer loads of a load distribution, both radial directions (polar)
* :func:`plot_regime_map`         the Moes (M, L) map with its regime boundaries and every contact
* :func:`plot_loss_breakdown`     loss families of one operating point (bar)
* :func:`plot_losses_vs_speed`    loss breakdown vs speed (stacked)
* :func:`plot_heatup`             node temperatures vs time (a colour family per machine part), with measured
                                  points, and the power loss in a second panel
* :func:`plot_network`            the thermal network: node temperatures and heat flows over its graph
* :func:`plot_vs_speed`           torque or temperature vs speed, with measured points
* :func:`plot_spin_down`          coast-down speed vs time

:func:`plot_result` writes the plots of ``thermobear run``.
"""
from __future__ import annotations

import math
import os
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import networkx as nx  # noqa: E402
import numpy as np  # noqa: E402

from thermobear.coupled.sources import prepare  # noqa: E402
from thermobear.lubrication.film import moes_map_boundaries  # noqa: E402

__all__ = ["plot_result", "plot_ball_loads", "plot_load_distribution", "plot_regime_map", "plot_loss_breakdown", "plot_losses_vs_speed",
           "plot_sweep", "plot_comparison",
           "plot_heatup", "plot_network", "plot_vs_speed", "plot_spin_down", "REGIME_COLORS", "node_family"]

REGIME_COLORS = {"IVR": "tab:blue", "IVE": "tab:cyan", "PVR": "tab:orange", "EHL": "tab:red",
                 "unloaded": "lightgrey", "none": "lightgrey"}
#: one colour per loss family of the breakdowns (local and SKF): churning, seal and cage were all grey
FAMILY_COLORS = {"rolling": "tab:blue", "sliding": "tab:orange", "pivoting": "tab:green",
                 "hysteresis": "tab:purple", "drag": "tab:brown", "churning": "tab:olive", "seal": "tab:pink",
                 "cage": "tab:cyan"}
#: machine part of a node (first matching prefix) → colour map of its family in heat-up plots
NODE_FAMILIES = (("inner", "Reds"), ("shaft", "Oranges"), ("ball", "Purples"), ("cage", "Purples"),
                 ("seal", "Greys"), ("outer", "Blues"), ("housing", "Greens"), ("oil", "YlOrBr"),
                 ("sump", "YlOrBr"), ("", "Greys"))


def node_family(name: str) -> str:
    """The machine part a node belongs to, by its name's prefix (``shaft_left_3`` → ``shaft``;
    ``inner_race`` → ``inner``; anything else → ``""``).

    >>> node_family("housing_seat_1_r2"), node_family("oil_sump"), node_family("frame")
    ('housing', 'oil', '')
    """
    return next(f for f, _ in NODE_FAMILIES if name.startswith(f))


def _save(fig, path) -> str:
    path = Path(path)
    tmp = path.with_name(path.name + ".tmp.png")
    fig.savefig(tmp, dpi=110, bbox_inches="tight")
    plt.close(fig)
    os.replace(tmp, path)
    return str(path)


def _regime_str(code):
    return np.asarray(code).astype(str)


def plot_ball_loads(losses, path, title: str = "") -> str:
    """Per-ball inner-contact load (bar length [N]) at its azimuth, coloured by the contact's regime.

    Parameters
    ----------
    losses : LossResult   one operating point (contacts per ball)
    path : str            PNG to write
    """
    ld = losses.load
    psi = np.asarray(ld.psi, float)
    fig, axs = plt.subplots(1, 2, subplot_kw={"projection": "polar"}, figsize=(10, 5))
    width = 2 * np.pi / max(psi.size, 1) * 0.7
    for ax, side in zip(axs, ("inner", "outer")):
        c = losses.contacts[side]
        Q = np.asarray(c["Q"], float).reshape(-1)
        reg = _regime_str(c["regime"]).reshape(-1)
        cols = [REGIME_COLORS.get(r, "black") for r in reg]
        ax.bar(psi, Q, width=width, color=cols, edgecolor="k", linewidth=0.5)
        ax.set_theta_zero_location("N")
        ax.set_title(f"{side} contacts: Q [N] at azimuth ψ", fontsize=10)
        for r in sorted(set(reg)):
            ax.bar([0], [0], color=REGIME_COLORS.get(r, "black"), label=r)
        ax.legend(loc="lower left", bbox_to_anchor=(-0.15, -0.15), fontsize=8, title="regime")
    fig.suptitle(title or "Ball loads and lubrication regimes")
    return _save(fig, path)


def plot_load_distribution(ld, path, title: str = "") -> str:
    """Ball loads around the bearing (polar): inner and outer contact load [N] at each ball's azimuth ψ, with the
    radial load (F_r along y at ψ = 0, F_z along z at ψ = 90°) and the ring's radial displacement (δr, δz) as
    arrows in the same plane, so a load in either radial direction shows where it loads the balls.

    Parameters
    ----------
    ld : LoadDistribution   one load case (per-ball arrays of shape (Z,))
    path : str              PNG to write
    """
    psi = np.asarray(ld.psi, float)
    Qi, Qo = np.asarray(ld.Q_i, float).reshape(-1), np.asarray(ld.Q_o, float).reshape(-1)
    if Qi.size != psi.size:
        raise ValueError("plot_load_distribution draws one load case")
    fig, ax = plt.subplots(subplot_kw={"projection": "polar"}, figsize=(6, 6))
    width = 2 * np.pi / max(psi.size, 1) * 0.35
    ax.bar(psi - width / 2, Qi, width=width, color="tab:blue", edgecolor="k", linewidth=0.5, label="inner Q_i [N]")
    ax.bar(psi + width / 2, Qo, width=width, color="tab:orange", edgecolor="k", linewidth=0.5, label="outer Q_o [N]")
    top = max(float(np.max(Qo)), float(np.max(Qi)), 1e-12)
    for (u, v), style, name in (((float(ld.Fr), float(ld.Fz)), "-", "radial load (Fr, Fz)"),
                                ((float(ld.delta_r), float(ld.delta_z)), "--", "ring displacement (δr, δz)")):
        if np.hypot(u, v) > 0:
            ax.annotate("", xy=(np.arctan2(v, u), 0.9 * top), xytext=(0.0, 0.0),
                        arrowprops=dict(arrowstyle="->", linestyle=style, color="k", lw=1.5))
            ax.plot([], [], style, color="k", label=name)
    ax.set_theta_zero_location("N")
    ax.set_theta_direction(-1)
    ax.set_title("ψ from y (ψ = 0) towards z (ψ = 90°)", fontsize=9)
    ax.legend(loc="lower left", bbox_to_anchor=(-0.15, -0.15), fontsize=8)
    fig.suptitle(title or "Ball loads")
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    return _save(fig, path)


def plot_regime_map(losses, brg, path, title: str = "") -> str:
    r"""Every contact on the Moes (M, L) map, with the regime boundaries of :func:`thermobear.lubrication.film.moes_map_boundaries`.

    The boundaries depend on D = Rx/Ry; they are drawn for the mean D of the
    plotted contacts (the spread of D between contacts is printed in the legend).
    """
    fig, ax = plt.subplots(figsize=(7, 5.5))
    Ms, Ls, Ds = [], [], []
    for side, mk in (("inner", "o"), ("outer", "s")):
        c = losses.contacts[side]
        M, L = np.asarray(c["M"], float).reshape(-1), np.asarray(c["L"], float).reshape(-1)
        reg = _regime_str(c["regime"]).reshape(-1)
        al = np.asarray(c["alpha"], float).reshape(-1)
        Rx = brg.Rx_i(al) if side == "inner" else brg.Rx_o(al)
        Ry = brg.Ry_i if side == "inner" else brg.Ry_o
        ok = np.isfinite(M) & np.isfinite(L) & (M > 0) & (L > 0)
        for r in sorted(set(reg[ok])):
            sel = ok & (reg == r)
            ax.scatter(M[sel], L[sel], marker=mk, color=REGIME_COLORS.get(r, "k"), edgecolor="k", s=40,
                       label=f"{side} contacts, {r} ({int(sel.sum())})", zorder=3)
        Ms.append(M[ok]), Ls.append(L[ok]), Ds.append(np.broadcast_to(np.asarray(Rx / Ry, float), M.shape)[ok])
    M_all, L_all, D_all = (np.concatenate(v) if v else np.array([]) for v in (Ms, Ls, Ds))
    D = float(np.clip(np.mean(D_all), 1e-6, 1.0)) if D_all.size else 1.0
    lo = min(0.1, float(M_all.min()) / 3) if M_all.size else 0.1
    hi = max(1e4, float(M_all.max()) * 3) if M_all.size else 1e4
    Mg = np.logspace(np.log10(lo), np.log10(hi), 300)
    b = moes_map_boundaries(D, M=Mg)
    ax.plot(Mg, b.L_iso_piezo, "k-", lw=1.5, label="iso-viscous | piezo-viscous")
    piezo = b.L_rigid_elastic_piezo >= b.L_iso_piezo
    ax.plot(Mg[piezo], b.L_rigid_elastic_piezo[piezo], "k--", lw=1.5, label="PVR | EHL")
    Liso = b.L_iso_piezo[np.argmin(np.abs(Mg - b.M_rigid_elastic_iso))]
    ax.plot([b.M_rigid_elastic_iso] * 2, [1e-3, Liso], "k:", lw=1.5, label="IVR | IVE")
    ax.set_xscale("log"), ax.set_yscale("log")
    Lmin = min(0.1, float(L_all.min()) / 3) if L_all.size else 0.1
    Lmax = max(1e2, float(L_all.max()) * 3) if L_all.size else 1e2
    ax.set_xlim(lo, hi), ax.set_ylim(Lmin, Lmax)
    ax.set_xlabel("Moes load parameter M [-]"), ax.set_ylabel("Moes material parameter L [-]")
    def at(M):                                   # boundaries at one M
        return (float(np.interp(np.log(M), np.log(Mg), b.L_iso_piezo)),
                float(np.interp(np.log(M), np.log(Mg), b.L_rigid_elastic_piezo)))
    Mre = b.M_rigid_elastic_iso
    M_ivr, M_ive, M_ehl = Mre / 10, Mre * 30, Mre * 30
    labels = (("IVR", M_ivr, min(at(M_ivr)[0], Lmax) / 10), ("IVE", M_ive, at(M_ive)[0] / 10),
              ("PVR", 2 * Mre, 4 * max(at(2 * Mre))), ("EHL", M_ehl, math.sqrt(at(M_ehl)[0] * max(at(M_ehl)))))
    for txt, x, y in labels:
        if lo < x < hi and Lmin < y < Lmax:
            ax.text(x, y, txt, fontsize=11, color="grey", ha="center", va="center")
    spread = f", D spread {D_all.min():.3g}–{D_all.max():.3g}" if D_all.size else ""
    ax.set_title(title or f"Moes regime map (boundaries at D = Rx/Ry = {D:.3g}{spread})", fontsize=10)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax.grid(True, which="both", alpha=0.2)
    return _save(fig, path)


def plot_loss_breakdown(breakdown_W: dict, path, title: str = "") -> str:
    """Bar chart of the loss families of one operating point [W]."""
    fig, ax = plt.subplots(figsize=(6, 4))
    keys = list(breakdown_W)
    vals = [float(np.asarray(breakdown_W[k]).sum()) for k in keys]
    ax.bar(keys, vals, color=[FAMILY_COLORS.get(k, "grey") for k in keys])
    tot = sum(vals)
    for i, v in enumerate(vals):
        ax.text(i, v, f"{v:.3g} W\n{100 * v / tot:.0f} %" if tot > 0 else f"{v:.3g}", ha="center", va="bottom", fontsize=8)
    if vals and max(vals) > 0:
        ax.set_ylim(0, 1.15 * max(vals))          # headroom for the labels of the tallest bar
    ax.set_ylabel("power loss [W]")
    ax.set_title(title or f"Loss breakdown (total {tot:.3g} W)")
    return _save(fig, path)


def plot_losses_vs_speed(n_rpm, breakdown_W: dict, path, title: str = "", measured=None) -> str:
    """Stacked loss families vs speed [W]; optional measured total power ``(n_rpm, P_W)``."""
    n = np.asarray(n_rpm, float)
    order = np.argsort(n)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    keys = list(breakdown_W)
    ax.stackplot(n[order], *[np.asarray(breakdown_W[k], float)[order] for k in keys], labels=keys,
                 colors=[FAMILY_COLORS.get(k, "grey") for k in keys], alpha=0.85)
    if measured is not None:
        ax.plot(*measured, "ko", label="measured total")
    ax.set_xlabel("speed n [rpm]"), ax.set_ylabel("power loss [W]")
    ax.legend(loc="upper left", fontsize=8)
    ax.set_title(title or "Loss breakdown vs speed")
    ax.grid(alpha=0.3)
    return _save(fig, path)


def _family_colours(names) -> dict:
    """A colour per node: the family's colour map, members spread over its darker two thirds."""
    cmaps = dict(NODE_FAMILIES)
    groups: dict = {}
    for n in names:
        groups.setdefault(node_family(n), []).append(n)
    out = {}
    for fam, members in groups.items():
        cmap = plt.get_cmap(cmaps[fam])
        for k, n in enumerate(members):
            out[n] = cmap(0.9 - 0.55 * k / max(len(members) - 1, 1))
    return out


def plot_heatup(t_s, simulated: dict, path, measured: dict | None = None, title: str = "",
                mapping: dict | None = None, power_W=None, bands: dict | None = None, preload_N=None) -> str:
    """Temperatures vs time [°C]: simulated lines (one colour family per machine part:
    :func:`node_family`), measured points in the same colour; the power loss [W] in a second panel
    when ``power_W`` is given, with a preloaded pair's preload [N] on its right axis (``preload_N``).

    Parameters
    ----------
    t_s : array_like       simulation times [s]
    simulated : dict       name → temperatures [°C] (same length as t_s)
    measured : dict        name → (t_s, T_C) measured points, keyed like ``simulated``
    mapping : dict         optional name → label suffix (e.g. channel → node)
    power_W : array_like   optional total power loss over t_s [W]
    bands : dict           optional name → (low, high) temperatures [°C] at t_s, shaded (the 5–95 %
                           band over the estimated inputs)
    preload_N : array_like optional preload of a preloaded pair over t_s [N] (with ``power_W``)
    """
    t = np.asarray(t_s, float)
    if power_W is None:
        fig, ax = plt.subplots(figsize=(7.5, 4.5))
    else:
        fig, (ax, axp) = plt.subplots(2, 1, figsize=(7.5, 6.0), sharex=True, height_ratios=(3, 1))
    unit, scale = ("min", 60.0) if t.max() > 600 else ("s", 1.0)
    colours = _family_colours([mapping.get(k, k) if mapping else k for k in simulated])
    for k, T in simulated.items():
        col = colours[mapping.get(k, k) if mapping else k]
        lab = k + (f" → {mapping[k]}" if mapping and k in mapping else "")
        ax.plot(t / scale, np.asarray(T, float), "-", color=col, label=f"{lab} (model)")
        if bands and k in bands:
            ax.fill_between(t / scale, np.asarray(bands[k][0], float), np.asarray(bands[k][1], float), color=col,
                            alpha=0.2, lw=0, label=f"{k} 5–95 % band")
        if measured and k in measured:
            tm, Tm = measured[k]
            ax.plot(np.asarray(tm, float) / scale, np.asarray(Tm, float), "o", ms=3.5, color=col, alpha=0.7,
                    label=f"{k} (measured)")
    ax.set_ylabel("temperature [°C]")
    if len(simulated) > 12:                     # many nodes: the legend beside the axes
        ax.legend(fontsize=6, ncol=2, loc="upper left", bbox_to_anchor=(1.01 if preload_N is None else 1.12, 1.0))
    else:
        ax.legend(fontsize=7, ncol=2)
    ax.grid(alpha=0.3)
    ax.set_title(title or "Heat-up")
    if power_W is not None:
        axp.plot(t / scale, np.asarray(power_W, float), "k-")
        axp.set_ylabel("power loss [W]")
        axp.grid(alpha=0.3)
        if preload_N is not None:               # a preloaded pair: its preload beside the power it drives
            axf = axp.twinx()
            axf.plot(t / scale, np.asarray(preload_N, float), "-", color="tab:red")
            axf.set_ylabel("preload [N]", color="tab:red")
    (axp if power_W is not None else ax).set_xlabel(f"time [{unit}]")
    return _save(fig, path)


def plot_network(template, steady, path, title: str = "", label_share: float = 0.02) -> str:
    """The thermal network at a steady state: nodes coloured by temperature [°C] (imposed nodes
    square), edges as wide as the heat they carry, the flows above ``label_share`` of the power
    labelled [W] with an arrow from the warmer node, heat sources [W] next to their nodes.

    Parameters
    ----------
    template : NetworkTemplate     the network (its graph: :meth:`NetworkTemplate.graph`)
    steady : SteadyState           temperatures ``T_C``, element flows ``heat_flows_W``, ``heat_sources_W``
    """
    g = nx.Graph()
    g.add_nodes_from(template.nodes)
    flows = steady.heat_flows_W
    for e in template.elements:
        a, b = e.nodes
        w = abs(flows.get(e.name, 0.0))
        g.add_edge(a, b, weight=g.edges[a, b]["weight"] + w if g.has_edge(a, b) else w)
    pos = nx.kamada_kawai_layout(g, weight=None)          # graph distances (the flows only draw the edges)
    T = {n: steady.T_C.get(n, np.nan) for n in template.nodes}
    fig, ax = plt.subplots(figsize=(11, 8.5))
    P = max(steady.P_W, 1e-12)
    for a, b, d in g.edges(data=True):
        (xa, ya), (xb, yb) = pos[a], pos[b]
        ax.plot([xa, xb], [ya, yb], "-", color="0.55", lw=0.6 + 8.0 * d["weight"] / P, zorder=1)
        if d["weight"] >= label_share * P:
            hot, cold = (a, b) if T[a] >= T[b] else (b, a)
            (xh, yh), (xc, yc) = pos[hot], pos[cold]
            ax.annotate("", xy=(0.45 * xh + 0.55 * xc, 0.45 * yh + 0.55 * yc), xytext=(0.55 * xh + 0.45 * xc,
                        0.55 * yh + 0.45 * yc), arrowprops=dict(arrowstyle="-|>", color="0.2", lw=0.8), zorder=3)
            ax.text(0.5 * (xa + xb), 0.5 * (ya + yb), f"{d['weight']:.2g} W", fontsize=6, color="0.15",
                    ha="center", va="bottom", zorder=4)
    free = [n for n, f in zip(template.nodes, template.fixed) if not f]
    fixed = [n for n, f in zip(template.nodes, template.fixed) if f]
    vals = [T[n] for n in template.nodes]
    norm = plt.Normalize(np.nanmin(vals), np.nanmax(vals))
    for nodes, marker in ((free, "o"), (fixed, "s")):
        if nodes:
            sc = ax.scatter([pos[n][0] for n in nodes], [pos[n][1] for n in nodes], c=[T[n] for n in nodes],
                            cmap="inferno", norm=norm, marker=marker, s=160, edgecolors="k", zorder=5)
    heat: dict = {}
    for part in (steady.heat_sources_W or {}).values():
        for n, w in part.items():
            heat[n] = heat.get(n, 0.0) + w
    for n in template.nodes:
        src = heat.get(n, 0.0)
        ax.text(pos[n][0], pos[n][1] + 0.035, f"{n}\n{T[n]:.1f} °C" + (f"  +{src:.2g} W" if src > 0 else ""),
                fontsize=6, ha="center", va="bottom", zorder=6)
    fig.colorbar(sc, ax=ax, label="temperature [°C]", shrink=0.7)
    ax.set_axis_off()
    ax.set_title(title or f"Thermal network — {template.name} (total loss {steady.P_W:.3g} W; squares: imposed)")
    return _save(fig, path)


def plot_vs_speed(n_rpm, simulated: dict, path, measured: dict | None = None, ylabel: str = "",
                  title: str = "", yscale: float = 1.0, labels=None, bands: dict | None = None) -> str:
    """Quantities vs speed: model lines (or markers) and measured points.

    Parameters
    ----------
    n_rpm : array_like    speeds [rpm]
    simulated : dict      name → values at n_rpm
    measured : dict       name → values at n_rpm (NaN = not measured)
    ylabel : str          axis label with unit
    yscale : float        factor applied to every value (e.g. 1e3 for N m → N mm)
    labels : list[str]    optional per-point text (e.g. the lubricant of each row)
    bands : dict          optional name → (low, high) at n_rpm, drawn as intervals (5–95 % bands)
    """
    n = np.asarray(n_rpm, float)
    order = np.argsort(n, kind="stable")
    fig, ax = plt.subplots(figsize=(7, 4.5))
    if labels is not None:                      # one point per labelled row: spread rows sharing a speed
        span = max(float(np.ptp(n)), float(np.max(n)) * 0.5, 1.0)
        x = n.copy()
        for v in np.unique(n):
            idx = np.flatnonzero(n == v)
            x[idx] = v + (np.arange(idx.size) - (idx.size - 1) / 2) * 0.025 * span
    for i, (k, v) in enumerate(simulated.items()):
        col = f"C{i % 10}"
        v = np.asarray(v, float) * yscale
        m = np.asarray(measured[k], float) * yscale if measured and k in measured else None
        if bands and k in bands:
            lo, hi = (np.asarray(b, float) * yscale for b in bands[k])
            ax.errorbar(n if labels is None else x, 0.5 * (lo + hi), yerr=0.5 * (hi - lo), fmt="none", ecolor=col,
                        elinewidth=4, alpha=0.3, label=f"{k} 5–95 % band")
        if labels is None:
            ax.plot(n[order], v[order], "-x", color=col, label=f"{k} (model)")
            if m is not None:
                ax.plot(n, m, "o", color=col, mfc="none", ms=7, label=f"{k} (measured)")
            continue
        ax.plot(x, v, "x", color=col, ms=7, label=f"{k} (model)")
        if m is not None:
            ax.plot(x, m, "o", color=col, mfc="none", ms=7, label=f"{k} (measured)")
            ax.vlines(x, np.fmin(v, m), np.fmax(v, m), color=col, lw=0.6, alpha=0.5)
        for xi, yi, s in zip(x, v if m is None else np.where(np.isnan(m), v, np.fmax(v, m)), labels):
            ax.annotate(s, (xi, yi), fontsize=6, rotation=90, xytext=(0, 5), textcoords="offset points",
                        ha="center", va="bottom")
        lo, hi = ax.get_ylim()
        ax.set_ylim(lo, hi + 0.25 * (hi - lo))
    ax.set_xlabel("speed n [rpm]"), ax.set_ylabel(ylabel)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    ax.set_title(title)
    return _save(fig, path)


def plot_spin_down(runs: list, path, title: str = "") -> str:
    """Coast-down speed vs time, one curve per initial speed; ``runs`` = [(label, t_s, omega_rad_s), ...]."""
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for lab, t, w in runs:
        ax.plot(t, np.asarray(w) * 30 / np.pi, label=lab)
    ax.set_xlabel("time [s]"), ax.set_ylabel("speed [rpm]")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    ax.set_title(title or "Spin-down")
    return _save(fig, path)


def plot_result(res, outdir) -> list:
    """Plots of a ``thermobear run`` result: ball loads, regime map, loss breakdown and, for a
    coupled steady state, the thermal network with its temperatures and heat flows. Returns the paths."""
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    s = res.scene
    tag = f"{s.bearing.name}, {s.n_rpm:g} rpm, Fa {s.Fa:g} N, Fr {s.Fr:g} N"
    paths = [plot_ball_loads(res.losses, out / "ball_loads.png", f"Ball loads and regimes — {tag}"),
             plot_regime_map(res.losses, s.bearing, out / "regime_map.png"),
             plot_loss_breakdown(res.breakdown_W, out / "loss_breakdown.png",
                                 f"Loss breakdown — {tag} (total {res.P_W:.3g} W)")]
    if res.steady is not None:
        paths.append(plot_network(prepare(s).template, res.steady, out / "network.png",
                                  f"Thermal network — {s.name}: {tag}, total loss {res.P_W:.3g} W (squares: imposed)"))
    return paths


def plot_sweep(rows: list, grid: dict, outdir, title: str = "") -> list:
    """Plots of a sweep over speed: torque (or power) vs speed per combination of the other grid
    values, and the loss breakdown vs speed of the first six combinations.  Returns the paths."""
    d = Path(outdir)
    d.mkdir(parents=True, exist_ok=True)
    ok = [r for r in rows if r.get("status") == "ok"]
    key = "torque_Nm" if any(r.get("torque_Nm") is not None for r in ok) else "P_W"
    others = [k for k in grid if k != "n_rpm"]
    groups: dict = {}
    for r in ok:
        groups.setdefault(", ".join(f"{k}={r.get(k)}" for k in others), []).append(r)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    scale = 1e3 if key == "torque_Nm" else 1.0
    for lab, rs in groups.items():
        x = np.array([r["n_rpm"] for r in rs], float)
        y = np.array([r[key] for r in rs], float) * scale
        o = np.argsort(x)
        ax.plot(x[o], y[o], "-o", ms=3, label=lab or key)
    ax.set_xlabel("speed n [rpm]"), ax.set_ylabel("friction torque [N mm]" if key == "torque_Nm" else "P [W]")
    ax.legend(fontsize=7), ax.grid(alpha=0.3), ax.set_title(f"Sweep — {title}")
    paths = [_save(fig, d / f"sweep_{key}.png")]
    for i, (lab, rs) in enumerate(list(groups.items())[:6]):
        keys = list(rs[0]["breakdown_W"])
        bd = {k: [r["breakdown_W"].get(k) for r in rs] for k in keys}
        paths.append(plot_losses_vs_speed([r["n_rpm"] for r in rs], bd, d / f"sweep_losses_{i + 1}.png",
                                          f"Loss breakdown vs speed — {title}" + (f" ({lab})" if lab else "")))
    return paths


def plot_comparison(comp, outdir, title, prefix="compare") -> list:
    """Plots of a rig-log comparison (:class:`thermobear.app.rig.Comparison`).

    Transient logs: the temperatures (and the torque) vs time, the model drawn continuously along
    its integrated trajectory, the measurements as points, the imposed (boundary) channels dashed,
    and below a residual panel (model − measured at the logged rows, per channel); the mode in the
    title.  Steady logs: torque and temperatures vs speed."""
    d = Path(outdir)
    d.mkdir(parents=True, exist_ok=True)
    paths = []
    temps = [k for k in comp.simulated if k != "torque_Nm"]
    if comp.kind == "transient":
        mx = comp.model_x if comp.model_x is not None else comp.x
        model = comp.model or comp.simulated
        sub = f"{title}\n{comp.mode}" if comp.mode else title
        if temps or comp.imposed:
            paths.append(_log_vs_time(mx, {k: model[k] for k in temps}, comp, temps, d / f"{prefix}_heatup.png",
                                      "temperature [°C]", sub, imposed=comp.imposed, bands=_band_pairs(comp)))
        if "torque_Nm" in comp.simulated:
            paths.append(_log_vs_time(mx, {"torque_Nm": model["torque_Nm"]}, comp, ["torque_Nm"],
                                      d / f"{prefix}_torque.png", "friction torque [N mm]", sub, yscale=1e3))
        return paths
    labels = comp.log.columns.get("lubricant")
    if "torque_Nm" in comp.simulated:
        paths.append(plot_vs_speed(comp.x, {"torque": comp.simulated["torque_Nm"]}, d / f"{prefix}_torque.png",
                                   {"torque": comp.measured["torque_Nm"]}, "friction torque [N mm]",
                                   f"Torque vs speed — {title}", 1e3, labels=labels))
    if temps:
        paths.append(plot_vs_speed(comp.x, {k: comp.simulated[k] for k in temps}, d / f"{prefix}_temperature.png",
                                   {k: comp.measured[k] for k in temps}, "temperature [°C]",
                                   f"Temperature vs speed — {title}", labels=labels, bands=_band_pairs(comp)))
    return paths


def _band_pairs(comp) -> dict:
    """channel → (p5, p95) of a comparison with bands."""
    return {k: (b["p5"], b["p95"]) for k, b in getattr(comp, "bands", {}).items()}


def plot_bands(unc, outdir, title: str = "") -> list:
    """The bands of an :class:`~thermobear.coupled.uncertainty.UncertaintyResult`.

    Steady state: one interval per node (5–95 % bar, median tick, nominal dot), and the power with
    its breakdown (``bands_T.png``, ``bands_P.png``).  Heat-up: shaded 5–95 % bands over time around
    the nominal heat-up of the rig's measured nodes (``unc.focus``) and the balls, mixture and housing,
    and of the power (``bands_heatup.png``, ``bands_P_heatup.png``)."""
    d = Path(outdir)
    d.mkdir(parents=True, exist_ok=True)
    Tk = [k for k in unc.bands if k.startswith("T_C.")]
    Pk = [k for k in unc.bands if k == "P_W" or k.startswith("breakdown_W.")]   # (design answers: the text's table)
    nom = unc.nominal
    if unc.t_s is not None:
        t = np.asarray(unc.t_s, float)
        shown = tuple(unc.focus) + ("balls", "oil_air", "housing", "bearing")   # the rig's nodes and the loss nodes
        free = [k for k in Tk if k[4:] in shown and np.ptp(np.asarray(unc.bands[k]["p95"], float)) > 0]
        sim = {k[4:]: np.interp(t, nom.t_s, nom.T_C[k[4:]]) for k in free}
        paths = [plot_heatup(t, sim, d / "bands_heatup.png", title=title,
                             bands={k[4:]: (unc.bands[k]["p5"], unc.bands[k]["p95"]) for k in free})]
        P = {"P_W": np.interp(t, nom.t_s, nom.P_W)}
        fig, ax = plt.subplots(figsize=(7.5, 4.0))
        ax.plot(t, P["P_W"], "-", color="C0", label="power (nominal)")
        ax.fill_between(t, unc.bands["P_W"]["p5"], unc.bands["P_W"]["p95"], color="C0", alpha=0.2, lw=0,
                        label="5–95 % band")
        ax.set_xlabel("time [s]"), ax.set_ylabel("power loss [W]"), ax.grid(alpha=0.3), ax.legend(fontsize=8)
        ax.set_title(title)
        return paths + [_save(fig, d / "bands_P_heatup.png")]
    paths = []
    for keys, name, unit in ((Tk, "bands_T.png", "temperature [°C]"), (Pk, "bands_P.png", "power [W]")):
        if not keys:
            continue
        fig, ax = plt.subplots(figsize=(7, 0.35 * len(keys) + 1.5))
        y = np.arange(len(keys))[::-1]
        lo = [unc.bands[k]["p5"] for k in keys]
        hi = [unc.bands[k]["p95"] for k in keys]
        ax.hlines(y, lo, hi, color="C0", lw=6, alpha=0.35, label="5–95 % band")
        ax.plot([unc.bands[k]["p50"] for k in keys], y, "|", color="C0", ms=12, mew=2, label="median")
        nv = [_nominal_of(nom, k) for k in keys]
        ax.plot(nv, y, "o", color="k", ms=4, label="nominal")
        ax.set_yticks(y, [k.split(".", 1)[-1] for k in keys])
        ax.set_xlabel(unit), ax.grid(alpha=0.3, axis="x"), ax.legend(fontsize=7, loc="best")
        ax.set_title(title or "Bands over the estimated inputs")
        paths.append(_save(fig, d / name))
    return paths


def _nominal_of(nom, key):
    kind, _, name = key.partition(".")
    if kind == "T_C":
        return nom.T_C[name]
    if kind == "P_W":
        return nom.P_W
    return float(nom.losses.breakdown_W[name])
def _log_vs_time(t_model, model: dict, comp, channels, path, ylabel, title, yscale=1.0, imposed=None,
                 bands=None) -> str:
    """Model (continuous) and measured points vs time, with the residual panel below; ``bands``: channel →
    (low, high) at the logged rows, shaded (the 5–95 % band over the estimated inputs)."""
    fig, (ax, axr) = plt.subplots(2, 1, figsize=(8, 6), sharex=True, gridspec_kw={"height_ratios": [3, 1.3]})
    tm, t = np.asarray(t_model, float), np.asarray(comp.x, float)
    unit, scale = ("min", 60.0) if t.max() > 600 else ("s", 1.0)
    for i, k in enumerate(channels):
        col = f"C{i % 10}"
        lab = k + (f" → {comp.mapping[k]}" if k in comp.mapping else "")
        ax.plot(tm / scale, np.asarray(model[k], float) * yscale, "-", color=col, lw=1.4, label=f"{lab} (model)")
        if bands and k in bands:
            ax.fill_between(t / scale, np.asarray(bands[k][0], float) * yscale, np.asarray(bands[k][1], float) * yscale,
                            color=col, alpha=0.2, lw=0, label=f"{k} 5–95 % band")
        m = np.asarray(comp.measured[k], float) * yscale
        ax.plot(t / scale, m, "o", ms=3.5, color=col, alpha=0.7, label=f"{k} (measured)")
        r = np.asarray(comp.simulated[k], float) * yscale - m
        axr.plot(t / scale, r, "o-", ms=3, lw=0.6, color=col, label=k)
    for j, (k, v) in enumerate((imposed or {}).items()):
        ax.plot(t / scale, np.asarray(v, float) * yscale, "--", lw=1.0, color=f"C{(len(channels) + j) % 10}",
                label=f"{k} → {comp.mapping[k][len('impose:'):]} (logged, imposed)")
    axr.axhline(0.0, color="k", lw=0.8)
    ax.set_ylabel(ylabel), ax.grid(alpha=0.3), ax.legend(fontsize=7, ncol=2)
    axr.set_ylabel("model − measured" + (" [K]" if ylabel.startswith("temp") else " [N mm]"), fontsize=8)
    axr.set_xlabel(f"time [{unit}]"), axr.grid(alpha=0.3)
    ax.set_title(title, fontsize=9)
    return _save(fig, path)
