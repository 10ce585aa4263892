"""Where the methods fail: stability maps of every iterative part of thermobear.

Run ``python validation/stability.py`` (``run_all.py`` calls :func:`run` and puts the text in
``validation/report/report.md``; the figure is ``validation/report/stability_map.png``).

A. Jones–Harris Newton (low speed, :func:`thermobear.loads.load_distribution`): load magnitude
   from 1e-6 N to 1e5 N × diametral clearance, deep groove 6210 under radial load and 7210 under
   axial load.  Outcome per case: converged (with iterations, residual) / NoEquilibrium /
   NoConvergence / other error.
B. Jones–Harris high speed (:func:`thermobear.loads.highspeed.load_distribution_high_speed`):
   7210, Fa = 450 N, speed × radial load.
C. Coupled fixed point (:func:`thermobear.coupled.steady_state` through
   :func:`thermobear.app.sweep.run_sweep`): the seed 004 7210 on the ``one_node`` network with a low
   conductance to ambient (``thermal.parameters`` override ``bearing_to_ambient.G_W_K``), speed ×
   oil viscosity × conductance → converged (Anderson) / damped (Picard fallback) / no equilibrium
   (ThermalRunaway) / failed.
D. SKF 2004 full-film friction backed out of a torque (seed 002 eqs A.12–A.13,
   :func:`thermobear.losses.skf.mu_EHL_from_torque`) with the catalogue constants, when the
   torque follows the constants calibrated on seed 002 MG1: the region of ν·n where μ_EHL < 0,
   with the measured seed 002 points.
E. Explicit vs implicit time stepping of the transient: the seed 004 network linearised at the
   start, explicit Euler at fractions of its stability limit Δt* = 2/λ_max(C⁻¹A) against the
   BDF solver that :func:`thermobear.thermal.solve_transient` uses.
"""
from __future__ import annotations

import dataclasses
import math
import sys
import time
import warnings
from pathlib import Path

import numpy as np

import thermobear as tb
from thermobear.errors import ExtrapolationWarning, InputError, NoConvergence, NoEquilibrium, SolverError
from thermobear.losses.skf import mu_EHL_from_torque, skf_constants, skf_friction
from thermobear.loads import load_distribution
from thermobear.coupled.transient import point_model
from thermobear.thermal import solve_transient

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
OUTCOMES = ("converged", "damped", "no equilibrium", "no convergence", "failed")
COLORS = {"converged": "#2ca02c", "damped": "#bcbd22", "no equilibrium": "#d62728",
          "no convergence": "#9467bd", "failed": "#7f7f7f"}


def _classify(exc) -> str:
    if isinstance(exc, (NoEquilibrium, tb.ThermalRunaway)):
        return "no equilibrium"
    if isinstance(exc, NoConvergence):
        return "no convergence"
    return "failed"


# ------------------------------------------------------------------------------------------- A
def jones_harris_low_speed():
    loads = np.logspace(-6, 5, 23)
    out = []
    for name, kind in (("6210", "Fr"), ("7210", "Fa")):
        b0 = tb.bearing(name)
        for Pd_um in (0.0, 10.0, 50.0):
            b = b0
            if name == "6210":    # free contact angle from the clearance: cos α0 = 1 − Pd/(2A)
                b = dataclasses.replace(b0, Pd=Pd_um * 1e-6, alpha0=math.acos(1 - Pd_um * 1e-6 / (2 * b0.A)))
            for F in loads:
                kw = {"Fr": F, "Fa": 0.0} if kind == "Fr" else {"Fa": F}
                try:
                    ld = load_distribution(b, **kw)
                    res = "converged" if ld.residual < 1e-8 else "no convergence"
                    out.append((name, kind, Pd_um if name == "6210" else b0.Pd * 1e6, F, res, int(ld.iterations),
                                float(ld.residual), ""))
                except (SolverError, InputError) as exc:
                    out.append((name, kind, Pd_um, F, _classify(exc), getattr(exc, "iterations", None),
                                getattr(exc, "residual", None), f"{type(exc).__name__}: {str(exc)[:100]}"))
            if name == "7210":
                break
    return out


# ------------------------------------------------------------------------------------------- B
def jones_harris_high_speed():
    from thermobear.loads.highspeed import load_distribution_high_speed
    b = tb.bearing("7210")
    speeds = np.array([0.0, 1000, 3200, 4800, 6500, 8070, 12000, 16000, 20000])
    Frs = np.array([0.0, 100.0, 300.0, 450.0, 540.0, 650.0, 1000.0])
    out = []
    with np.errstate(all="ignore"):
        for n in speeds:
            for Fr in Frs:
                t0 = time.perf_counter()
                try:
                    ld = load_distribution_high_speed(b, Fa=450.0, Fr=Fr, n_rpm=n)
                    out.append((n, Fr, "converged", int(ld.iterations), float(ld.residual), "",
                                time.perf_counter() - t0))
                except (SolverError, InputError) as exc:
                    out.append((n, Fr, _classify(exc), getattr(exc, "iterations", None), None,
                                f"{type(exc).__name__}: {str(exc)[:90]}", time.perf_counter() - t0))
    return out


# ------------------------------------------------------------------------------------------- C
COUPLED_G = (0.3, 1.0)
#: oils spanning the viscosities of seed 002's base oils (PG2 32.5, MG1 230 cSt at 40 °C) around seed 004's; under the
#: scene's oil jet (a grease is refused under an oil supply)
COUPLED_LUBS = ("iso-vg-32-pao", "seed004-mineral", "iso-vg-220-mineral")
COUPLED_N = (1000.0, 2000.0, 4000.0, 6000.0, 8000.0, 12000.0, 16000.0)


def coupled_map(processes=None):
    from thermobear.app.sweep import run_sweep
    s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    s = dataclasses.replace(s, network="one_node", rig_map={})
    grid = {"network_parameters": [{"bearing_to_ambient.G_W_K": g} for g in COUPLED_G],
            "lubricant": list(COUPLED_LUBS), "n_rpm": list(COUPLED_N)}
    t0 = time.perf_counter()
    rows = run_sweep(s, grid, processes=processes)
    wall = time.perf_counter() - t0
    out = []
    for r in rows:
        if r["status"] == "ok":
            res = "damped" if "picard-damped" in r["reason"] else "converged"     # newton, anderson or picard
        elif r["status"] == "ThermalRunaway":
            res = "no equilibrium"
        elif r["status"] == "NoConvergence":
            res = "no convergence"
        else:
            res = "failed"
        out.append(dict(G=r["network_parameters"]["bearing_to_ambient.G_W_K"], lub=r["lubricant"],
                        n=r["n_rpm"], outcome=res, T=r["temperatures_C"].get("bearing"), P=r["P_W"],
                        it=r["iterations"], why=r["reason"]))
    return out, wall


# ------------------------------------------------------------------------------------------- D
def skf_negative_mu():
    from fidelity import MU_BL_SEED002, calibrate_L0_seed002, seed002_cases
    cases = seed002_cases()
    cal = next(c for c in cases if not c.held_out)
    R1c, S1c = calibrate_L0_seed002(cal)
    brg = cal.scene.bearing
    d_mm, D_mm = brg.bore * 1e3, brg.outer_diameter * 1e3
    cat = skf_constants("thrust", brg.series)
    n = np.logspace(np.log10(200), np.log10(12000), 60)
    nu = np.logspace(np.log10(5), np.log10(300), 60)
    N, NU = np.meshgrid(n, nu)
    mu_bl = MU_BL_SEED002["mineral"]
    M = skf_friction(brg, NU, N, 7000.0, 0.0, R1=R1c, S1=S1c, mu_bl=mu_bl, mu_EHL=0.05).M_total
    mu = mu_EHL_from_torque(M, d_mm, D_mm, "thrust", NU, N, 7000.0, 0.0, mu_bl=mu_bl, R1=cat["R1"],
                            S1=cat["S1"], K_z=cat["K_z"])
    pts = []
    for c in cases:
        nu_c = float(c.scene.lubricant.nu(c.T_C))
        mb = MU_BL_SEED002[c.extra["base_oil"]]
        m = float(mu_EHL_from_torque(c.torque_Nm, d_mm, D_mm, "thrust", nu_c, c.scene.n_rpm, 7000.0, 0.0,
                                     mu_bl=mb, R1=cat["R1"], S1=cat["S1"], K_z=cat["K_z"]))
        pts.append((c.name, c.scene.n_rpm, nu_c, m))
    return N, NU, np.asarray(mu), pts


# ------------------------------------------------------------------------------------------- E
def explicit_vs_implicit(t_end_s=600.0):
    s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    net = point_model(s).network
    free = ~net.fixed
    T0 = net.T_fixed_K[0].copy()
    T0[free] = s.T_ambient_C + 273.15
    A = net.matrix(net.conductances(T0[None]))[0]
    C = net.C_J_K[free]
    J = -(A[free][:, free]) / C[:, None]
    lam = np.linalg.eigvals(J)
    lam_max = float(np.max(-lam.real))
    dt_star = 2.0 / lam_max
    stiff_node = net.free_nodes[int(np.argmin(C / np.diag(A)[free]))]
    P = np.zeros(len(net.nodes))
    P[net.index["balls"]] = 20.0
    P[net.index["inner_race"]] = 5.0
    P[net.index["outer_race"]] = 5.0
    b = P[free] - A[free][:, ~free] @ T0[~free]
    t0 = time.perf_counter()
    ref = solve_transient(net, {"balls": 20.0, "inner_race": 5.0, "outer_race": 5.0}, t_end_s,
                          T0_C=s.T_ambient_C, t_eval=[t_end_s])
    t_bdf = time.perf_counter() - t0
    T_ref = np.array([ref.T_K[-1, 0, net.index[nm]] for nm in net.free_nodes])
    # the BDF run uses temperature-dependent conductances; the explicit runs the frozen matrix:
    # compare both with the exact solution of the frozen linear system as well
    Aff = A[free][:, free]
    Tss = np.linalg.solve(Aff, b)
    w, V = np.linalg.eig(J)
    c0 = np.linalg.solve(V, T0[free] - Tss)
    T_lin = (Tss + (V @ (c0 * np.exp(w * t_end_s))).real)
    runs = []
    for frac in (0.5, 0.95, 1.05, 1.5):
        dt = frac * dt_star
        steps = int(math.ceil(t_end_s / dt))
        dt = t_end_s / steps
        y = T0[free].copy()
        hist = np.empty(steps + 1)
        hist[0] = y.max()
        t0 = time.perf_counter()
        with np.errstate(all="ignore"):
            for k in range(steps):
                y = y + dt * (b - Aff @ y) / C
                hist[k + 1] = np.max(np.abs(y))
                if not np.all(np.isfinite(y)) or hist[k + 1] > 1e6:
                    hist[k + 2:] = np.nan
                    break
        wall = time.perf_counter() - t0
        err = float(np.max(np.abs(y - T_lin))) if np.all(np.isfinite(y)) else float("inf")
        runs.append(dict(frac=frac, dt=dt, steps=steps, err=err, wall=wall, hist=hist, blew=err > 1e3))
    return dict(dt_star=dt_star, lam=lam, stiff_node=stiff_node, C=dict(zip(net.free_nodes, C)),
                runs=runs, t_bdf=t_bdf, nfev=ref.nfev, bdf_vs_lin=float(np.max(np.abs(T_ref - T_lin))),
                t_end=t_end_s)


# ------------------------------------------------------------------------------------------- report
def plot(A, B, C, D, E, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 3, figsize=(16, 9.5))
    # A
    a = ax[0, 0]
    ys = {}
    for name, kind, Pd, F, res, *_ in A:
        lab = f"{name} {kind}, Pd {Pd:.0f} µm"
        y = ys.setdefault(lab, len(ys))
        a.scatter(F, y, c=COLORS[res], s=30)
    a.set_xscale("log")
    a.set_yticks(list(ys.values()), list(ys.keys()))
    a.set_xlabel("load [N]")
    a.set_title("A. Jones–Harris (low speed)")
    # B
    a = ax[0, 1]
    for n, Fr, res, *_ in B:
        a.scatter(n, Fr, c=COLORS[res], s=60)
    a.axhline(450 / math.tan(math.radians(40)), ls=":", c="k")
    a.text(0, 450 / math.tan(math.radians(40)) + 15, "Fr = Fa / tan α0", fontsize=8)
    a.set_xlabel("n [rpm]")
    a.set_ylabel("Fr [N] (Fa = 450 N)")
    a.set_title("B. Jones–Harris high speed, 7210")
    # C
    a = ax[0, 2]
    for r in C:
        y = COUPLED_LUBS.index(r["lub"]) + (0.15 if r["G"] == COUPLED_G[0] else -0.15)
        a.scatter(r["n"], y, c=COLORS[r["outcome"]], marker="o" if r["G"] == COUPLED_G[0] else "s", s=60)
    a.set_yticks(range(len(COUPLED_LUBS)), [f"{l}" for l in COUPLED_LUBS])
    a.set_xscale("log")
    a.set_xlabel("n [rpm]")
    a.set_title(f"C. coupled fixed point, one node (o G = {COUPLED_G[0]}, □ G = {COUPLED_G[1]} W/K)")
    # D
    N, NU, mu, pts = D
    a = ax[1, 0]
    cf = a.contourf(N, NU, mu, levels=np.linspace(-0.15, 0.1, 11), cmap="RdBu", extend="both")
    a.contour(N, NU, mu, levels=[0.0], colors="k")
    for name, n, nu, m in pts:
        a.scatter(n, nu, c="k" if m >= 0 else "r", marker="x")
        a.annotate(f"{name.split()[0]} {m:+.3f}", (n, nu), fontsize=7)
    a.set_xscale("log")
    a.set_yscale("log")
    a.set_xlabel("n [rpm]")
    a.set_ylabel("ν [mm²/s]")
    a.set_title("D. μ_EHL backed out with SKF catalogue R1, S1 (51107)")
    fig.colorbar(cf, ax=a)
    # E
    a = ax[1, 1]
    for r in E["runs"]:
        t = np.linspace(0, r["dt"] * (len(r["hist"]) - 1), len(r["hist"]))
        a.plot(t, r["hist"] - 273.15, label=f"explicit Δt = {r['frac']:.2f} Δt*")
    a.set_yscale("symlog")
    a.set_ylim(0, 1e6)
    a.set_xlabel("t [s]")
    a.set_ylabel("max |T| [°C]")
    a.set_title(f"E. explicit Euler, Δt* = {E['dt_star']:.3g} s (node {E['stiff_node']})")
    a.legend(fontsize=8)
    # legend panel
    a = ax[1, 2]
    a.axis("off")
    for k, (o, c) in enumerate(COLORS.items()):
        a.scatter([0.1], [0.9 - 0.1 * k], c=c, s=80)
        a.text(0.15, 0.9 - 0.1 * k, o, va="center")
    a.set_xlim(0, 1)
    a.set_ylim(0, 1)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def run(png=HERE / "report" / "stability_map.png", processes=None) -> str:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)
        warnings.simplefilter("ignore", RuntimeWarning)
        A = jones_harris_low_speed()
        B = jones_harris_high_speed()
        C, wall_C = coupled_map(processes)
        D = skf_negative_mu()
        E = explicit_vs_implicit()
    png.parent.mkdir(parents=True, exist_ok=True)
    plot(A, B, C, D, E, png)
    L = []
    w = L.append
    w("### A. Jones–Harris Newton, low speed\n")
    bad = [r for r in A if r[4] != "converged"]
    its = [r[5] for r in A if r[4] == "converged"]
    w(f"{len(A)} cases (6210 radial with Pd 0/10/50 µm, 7210 axial; loads 1e-6–1e5 N): "
      f"{len(A) - len(bad)} converged (iterations {min(its)}–{max(its)}, residual ≤ "
      f"{max(r[6] for r in A if r[4] == 'converged'):.1e}), {len(bad)} not.")
    for r in bad:
        w(f"* {r[0]} {r[1]} = {r[3]:.3g} N, Pd {r[2]:.0f} µm: **{r[4]}** — {r[7]}")
    w("\nDetection: `load_distribution` raises NoEquilibrium for loads the bearing cannot carry "
      "and NoConvergence (with residual) when Newton stalls; zero load returns the unloaded state.\n")
    w("### B. Jones–Harris high speed (7210, Fa = 450 N)\n")
    w("| n [rpm] | " + " | ".join(f"Fr {f:g}" for f in sorted({r[1] for r in B})) + " |")
    w("|---|" + "---|" * len({r[1] for r in B}))
    for n in sorted({r[0] for r in B}):
        cells = [r for r in B if r[0] == n]
        w(f"| {n:g} | " + " | ".join((f"{r[2]} ({r[3]} it)" if r[2] == "converged" else f"**{r[2]}**")
                                     for r in sorted(cells, key=lambda r: r[1])) + " |")
    import re
    kinds: dict = {}
    for r in B:
        if r[2] != "converged":
            msg = re.sub(r"array\([^)]*\)", "[…]", r[5])
            msg = re.sub(r"n = [0-9.]+.*", "n = …", msg)
            kinds[msg] = kinds.get(msg, 0) + 1
    w("\nFailures by message: " + ("; ".join(f"{k} (×{v})" for k, v in sorted(kinds.items())) or "none") + ".")
    first = {}
    for n in sorted({r[0] for r in B}):
        bad = [r[1] for r in B if r[0] == n and r[2] != "converged"]
        if bad:
            first[n] = min(bad)
    w("Region (smallest failing Fr per speed): " + (", ".join(f"{n:g} rpm: Fr ≥ {f:g} N" for n, f in first.items())
                                                    or "none") + ".")
    s004 = [r for r in B if r[1] == 650.0 and r[0] in (3200.0, 4800.0, 6500.0, 8070.0)]
    w("Seed 004 test load (Fa 450, Fr 650 N): " + ", ".join(f"{r[0]:g} rpm {r[2]}" for r in s004) + ".")
    lo = [r for r in B if r[0] == 0.0 and r[2] == "converged"]
    susp = [r for r in B if 0 < r[0] <= 1000.0 and r[2] != "converged" and any(x[1] == r[1] for x in lo)]
    if susp:
        w("Continuity check: at n = 0 every case converges (the low-speed solution); at 1000 rpm, where the "
          "centrifugal force is ≈ 0.5 N per ball, " + ", ".join(f"Fr {r[1]:g} N → {r[2]}" for r in susp)
          + " — physically the solution barely moves, so these are solver failures (start/continuation), "
          "not a loss of equilibrium.")
    w("Detection: `load_distribution_high_speed` raises NoEquilibrium (loads it cannot carry), "
      "NoConvergence (Newton budget) — any InputError raised from inside the iteration (e.g. "
      "`ball_kinematics` on a trial step) would be a misleading class for a solver failure.  Fidelity "
      "L4 records these as failures and scores nothing for them.\n")
    w("### C. Coupled fixed point: speed × viscosity × conductance (one node)\n")
    w(f"{len(C)} points via `run_sweep` ({wall_C:.1f} s wall).  T = bearing node [°C].\n")
    w("| G [W/K] | lubricant | " + " | ".join(f"{n:g} rpm" for n in COUPLED_N) + " |")
    w("|---|---|" + "---|" * len(COUPLED_N))
    for G in COUPLED_G:
        for lub in COUPLED_LUBS:
            cells = [r for r in C if r["G"] == G and r["lub"] == lub]
            cells.sort(key=lambda r: r["n"])
            w(f"| {G:g} | {lub} | " + " | ".join(
                (f"{r['T']:.0f} °C ({r['it']} it)" if r["outcome"] in ("converged", "damped")
                 else f"**{r['outcome']}**") + (" damped" if r["outcome"] == "damped" else "") for r in cells) + " |")
    failed = [r for r in C if r["outcome"] not in ("converged", "damped")]
    if failed:
        w(f"\n{len(failed)} failures, e.g. ({failed[0]['lub']}, {failed[0]['n']:g} rpm, G {failed[0]['G']:g} W/K): "
          f"\"{failed[0]['why'][:220]}\"")
    else:
        w("\nNo failures.")
    w("\nDetection: `solve_coupled` (Anderson, Picard fallback) raises ThermalRunaway when the heating "
      "path passes the lubricant's temperature limit or accelerates, NoConvergence on oscillation; "
      "`run_sweep` records the class and reason in the row and carries on.  Viscous losses fall "
      "with temperature, so every failure here is 'no equilibrium below the limit' (power too large "
      "for the conductance), not a numerical breakdown.\n")
    w("### D. SKF model: sign of the μ_EHL backed out of a torque\n")
    N, NU, mu, pts = D
    neg = mu < 0
    from thermobear.losses.skf import phi_bl
    pbl = phi_bl(N, NU, 43.5)
    ill = pbl > 0.5
    w("Stand-in measurement: the SKF torque with R1, S1 calibrated on seed 002 MG1 (μ_EHL 0.05).  μ_EHL "
      "backed out of it with the catalogue constants (R1 1.03e-6, S1 1.6e-2), seed 002 eq A.13, over "
      "n 200–12000 rpm × ν 5–300 mm²/s (panel D; black line μ = 0).")
    hi = neg & ~ill
    w(f"* μ_EHL < 0 on {100 * neg.mean():.0f} % of the map; {100 * (neg & ill).sum() / max(neg.sum(), 1):.0f} % of "
      f"those cells have Φ_bl > 0.5 (ν·n ≤ {np.max((N * NU)[ill]):.3g} rpm·mm²/s), where eq A.13 divides by "
      "1 − Φ_bl → 0: boundary friction dominates, the backed-out μ_EHL is ill-conditioned and its sign "
      "carries no information.")
    w("* At high ν·n (Φ_bl ≤ 0.5): " + (f"negative from ν·n ≥ {np.min((N * NU)[hi]):.3g} rpm·mm²/s." if hi.any()
      else "μ_EHL stays positive (the catalogue M_rr, 27 % above the calibrated one, does not exceed the total) — "
      "seed 002's statement (negative μ_EHD at high speed with catalogue constants) is NOT reproduced "
      "with a torque that follows the calibrated model; it needs a measured torque that rises more slowly "
      "with speed than (ν n)^0.6."))
    w("* Measured seed 002 torques backed out the same way: " + ", ".join(
        f"{nm} {m:+.4f}" for nm, _, _, m in pts) + " (all positive, about half the calibrated value).")
    w("* Detection: `mu_EHL_from_torque` returns the value unclipped and never raises; a negative μ_EHL "
      "means the constants (or Φ_bl → 1), not the lubricant, are wrong.  Suggested: warn when "
      "Φ_bl > 0.5 (OutsideValidity).\n")
    w("### E. Explicit vs implicit time stepping (seed 004 network)\n")
    w(f"Largest eigenvalue of C⁻¹A: {max(-E['lam'].real):.3g} 1/s (stiffest node: {E['stiff_node']}, "
      f"C = {E['C'][E['stiff_node']]:.3g} J/K); slowest {min(-E['lam'].real):.3g} 1/s: stiffness ratio "
      f"{max(-E['lam'].real) / min(-E['lam'].real):.3g}.  Explicit Euler is stable only for "
      f"Δt < Δt* = 2/λ_max = {E['dt_star']:.3g} s.\n")
    w(f"| Δt / Δt* | Δt [s] | steps for {E['t_end']:g} s | max error vs exact linear [K] | wall [s] |")
    w("|---|---|---|---|---|")
    for r in E["runs"]:
        w(f"| {r['frac']:.2f} | {r['dt']:.3g} | {r['steps']} | "
          + ("**blows up**" if r["blew"] else f"{r['err']:.2e}") + f" | {r['wall']:.3f} |")
    w(f"\nBDF (`solve_transient`, rtol 1e-8): {E['nfev']} right-hand-side evaluations, {E['t_bdf']:.2f} s, "
      f"{E['bdf_vs_lin']:.2e} K from the frozen-matrix solution (the network's conductances vary with T).  "
      "Detection: none needed — the implicit solver is unconditionally stable; an explicit scheme "
      "would need the Δt* check; the smallest C/G node sets it.\n")
    return "\n".join(L)


if __name__ == "__main__":
    print(run())
