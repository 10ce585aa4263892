"""Stability map of the coupled fixed point against the analytic runaway threshold.

One node, conductance G to ambient, losses P = P0 exp((T − Ta)/θ) (heat generation growing with
temperature).  Equilibria solve s = c e^s with s = (T − Ta)/θ and c = P0/(G θ): a stable one exists
iff c ≤ 1/e (tangency), at s = −W0(−c) (Lambert W).  The solver must converge below the threshold
and raise ThermalRunaway above it.  Run: python validation/stability_map_coupling.py
"""
from __future__ import annotations

import math

import numpy as np
from scipy.special import lambertw

from thermobear.coupled.fixedpoint import solve_coupled
from thermobear.errors import NoConvergence, ThermalRunaway

TA, G, THETA = 293.15, 2.0, 20.0


def outcome(c, method):
    P0 = c * G * THETA
    update = lambda T: (TA + P0 * np.exp((T - TA) / THETA) / G, float(P0 * np.exp((T[0] - TA) / THETA)))
    try:
        r = solve_coupled(update, [TA], method=method, max_iter=400)
        return "converged", r.T_K[0], r.iterations
    except ThermalRunaway as e:
        return "runaway", float(np.max(e.last)), e.iterations
    except NoConvergence as e:
        return "no-convergence", float(np.max(e.last)), e.iterations


def main():
    print(f"threshold c* = 1/e = {1 / math.e:.4f}")
    print(f"{'c':>7} {'analytic':>10} {'method':>9} {'outcome':>15} {'T [K]':>9} {'exact T':>9} {'it':>4}")
    bad = 0
    for c in [0.05, 0.2, 0.3, 0.35, 0.36, 0.3750, 0.38, 0.5, 1.0, 2.0]:
        expected = "converged" if c <= 1 / math.e else "runaway"
        T_exact = TA + THETA * float(-lambertw(-c, 0).real) if c <= 1 / math.e else float("nan")
        for method in ("anderson", "picard"):
            out, T, it = outcome(c, method)
            ok = out == expected and (out != "converged" or abs(T - T_exact) < 1e-5)
            bad += not ok
            print(f"{c:7.4f} {expected:>10} {method:>9} {out:>15} {T:9.2f} {T_exact:9.2f} {it:4d}"
                  + ("" if ok else "   <-- MISMATCH"))
    print("all outcomes match the analytic threshold" if not bad else f"{bad} mismatches")
    return bad


if __name__ == "__main__":
    raise SystemExit(main())
