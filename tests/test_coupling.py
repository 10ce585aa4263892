"""Coupled losses ↔ temperatures: convergence, acceleration, stability and thermal runaway."""
from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq
from scipy.special import lambertw

sys.path.insert(0, str(Path(__file__).parent))

from thermobear.coupled.fixedpoint import loop_gain, solve_coupled  # noqa: E402
from thermobear.errors import InputError, NoConvergence, ThermalRunaway  # noqa: E402
from thermobear.thermal import split_losses  # noqa: E402

TA = 293.15      # ambient [K]
G = 2.0          # one-node dissipation conductance [W/K]


def one_node(P):
    """Update map of one node with conductance G to ambient: T ← TA + P(T)/G, and the loss."""
    return lambda T: (TA + P(T) / G, float(np.sum(P(T))))


# (i) normal case: losses fall with temperature (viscosity) -------------------------------
def test_viscous_losses_converge_in_few_iterations():
    P = lambda T: 300.0 * np.exp(-(T - TA) / 35.0)
    r = solve_coupled(one_node(P), [TA])
    T_exact = brentq(lambda T: TA + P(T) / G - T, TA, TA + 200)
    assert r.T_K[0] == pytest.approx(T_exact, abs=1e-6)
    assert r.iterations <= 10
    assert r.residual_K <= 1e-6 and r.energy_residual_rel <= 1e-6
    assert r.loop_gain < 0                           # negative feedback: very stable
    assert r.history[0]["T_K"][0] == TA and len(r.history) == r.iterations
    assert r.P_W == pytest.approx(float(P(r.T_K)[0]), rel=1e-12)


def test_positive_feedback_below_threshold_gives_lower_stable_root():
    # P = P0 exp((T−TA)/θ): equilibria s = c e^s (s = (T−TA)/θ, c = P0/(G θ)); two roots when c < 1/e
    P0, theta = 12.0, 20.0
    c = P0 / (G * theta)                             # 0.3 < 1/e
    P = lambda T: P0 * np.exp((T - TA) / theta)
    s_low = float(-lambertw(-c, 0).real)             # stable (lower) root
    s_high = float(-lambertw(-c, -1).real)           # unstable (upper) root
    for method in ("anderson", "picard"):
        r = solve_coupled(one_node(P), [TA], method=method)
        assert r.T_K[0] == pytest.approx(TA + theta * s_low, abs=1e-6)
        assert r.loop_gain == pytest.approx(c * math.exp(s_low), rel=1e-3) and r.loop_gain < 1
    # starting above the unstable root the bearing runs away: no stable state is reachable by heating
    with pytest.raises(ThermalRunaway):
        solve_coupled(one_node(P), [TA + theta * (s_high + 0.5)])


# (ii) runaway: heat generation grows faster than G ΔT ---------------------------------------
@pytest.mark.parametrize("method", ["anderson", "picard"])
def test_runaway_raises_with_reason_history_and_last(method):
    P0, theta = 30.0, 20.0                           # c = 0.75 > 1/e: no equilibrium at all
    P = lambda T: P0 * np.exp((T - TA) / theta)
    with pytest.raises(ThermalRunaway) as exc:
        solve_coupled(one_node(P), [TA], method=method)
    e = exc.value
    assert "faster" in e.reason and e.history and e.last is not None
    assert e.last[0] > TA                            # it was heating


def test_runaway_just_beyond_threshold():
    theta = 20.0
    P0 = 1.02 * G * theta / math.e                   # 2 % beyond the tangency c = 1/e
    with pytest.raises(ThermalRunaway):
        solve_coupled(one_node(lambda T: P0 * np.exp((T - TA) / theta)), [TA], max_iter=400)


# (iii) stiff negative feedback: plain Picard oscillates, Anderson converges ---------------
def test_stiff_case_picard_fails_anderson_converges():
    P = lambda T: 3000.0 * np.exp(-(T - TA) / 8.0)   # loop gain ≈ −4 at the solution
    T_exact = brentq(lambda T: TA + P(T) / G - T, TA, TA + 500)
    gain = -float(P(np.array([T_exact]))[0]) / (G * 8.0)
    assert gain < -2
    with pytest.raises(NoConvergence) as exc:
        solve_coupled(one_node(P), [TA], method="picard", damping=1.0)
    assert "oscillat" in exc.value.reason and exc.value.history
    r = solve_coupled(one_node(P), [TA])
    assert r.T_K[0] == pytest.approx(T_exact, abs=1e-6) and r.method == "anderson"
    assert r.iterations < 30
    # damping below 2/(1 − gain) makes Picard converge too (slowly): the fallback's rule
    r2 = solve_coupled(one_node(P), [TA], method="picard", damping=1.0 / (1.0 - gain), max_iter=400)
    assert r2.T_K[0] == pytest.approx(T_exact, abs=1e-5)


def test_loop_gain_of_linear_map():
    J = np.array([[0.2, 0.1, 0.0], [0.0, 0.5, 0.2], [0.1, 0.0, 0.3]])
    lam = float(np.max(np.linalg.eigvals(J).real))
    assert loop_gain(lambda T: 300.0 + J @ (T - 300.0), np.full(3, 320.0)) == pytest.approx(lam, rel=1e-8)


def test_bad_inputs():
    with pytest.raises(InputError):
        solve_coupled(lambda T: T, [-5.0])
    with pytest.raises(InputError):
        solve_coupled(lambda T: np.array([1.0, 2.0]), [300.0])
    with pytest.raises(InputError):
        solve_coupled(lambda T: T, [300.0], method="newton")


# network + loss model --------------------------------------------------------------------
def viscous_losses(oil, n_rpm=6500.0):
    """Toy loss model: contact losses ∝ (ν n)^⅔ at the contact temperature (mean of ball and race)."""
    def losses(T_K):
        Tci = 0.5 * (T_K["balls"] + T_K["inner_race"]) - 273.15
        Tco = 0.5 * (T_K["balls"] + T_K["outer_race"]) - 273.15
        k = 0.04 * n_rpm ** (2 / 3)
        Pi = np.full(15, k * oil.nu(Tci) ** (2 / 3) / 15)
        Po = np.full(15, k * oil.nu(Tco) ** (2 / 3) / 15)
        drag = 1e-7 * n_rpm**2
        src = split_losses(Pi, Po, drag)
        return src, {"P_inner_W": Pi.sum(), "P_outer_W": Po.sum(), "P_drag_W": drag}
    return losses


def test_picard_does_not_call_a_stable_non_normal_map_runaway():
    # Jordan block with eigenvalues 0.8: increments grow for a few steps, yet the map contracts
    J = np.array([[0.8, 0.0], [1.0, 0.8]])
    c = np.array([6.0, 3.0])                       # equilibrium 330 K and 465 K, below the limit
    r = solve_coupled(lambda T: J @ (T - 300.0) + c + 300.0, [300.0, 300.0], method="picard")
    np.testing.assert_allclose(r.T_K - 300.0, np.linalg.solve(np.eye(2) - J, c), atol=1e-5)


def test_physical_path_settles_a_creeping_heating_path_near_the_fold():
    # one node whose loop gain at the equilibrium is 0.995 (just below the fold where equilibria end):
    # plain Picard from ambient creeps (error × 0.995 per step, 100 steps leave 60 % of it); the path is
    # restarted from Aitken's extrapolation and settles on the equilibrium, not a NoConvergence
    from thermobear.coupled.fixedpoint import _Update, _physical_path
    T_eq, lam = 350.0, 0.995
    G = lambda T: T_eq + lam * (T - T_eq) + 1e-5 * (T - T_eq) ** 2          # noqa: E731
    ev = _Update(lambda T: G(T), 1)
    res = _physical_path(ev, np.array([300.0]), tol_K=1e-6, tol_energy_rel=1e-6, max_iter=100, T_limit_K=573.15)
    assert res.T_K[0] == pytest.approx(T_eq, abs=1e-4) and res.method == "picard-aitken"
    # beyond the fold (no equilibrium: G(T) > T everywhere) the same path is a named runaway
    ev = _Update(lambda T: T + 0.01 + 2e-5 * (T - 300.0), 1)
    with pytest.raises(ThermalRunaway):
        _physical_path(ev, np.array([300.0]), tol_K=1e-6, tol_energy_rel=1e-6, max_iter=100, T_limit_K=573.15)


def test_heating_path_past_a_fold_settles_on_the_hotter_equilibrium_not_runaway():
    # losses that rise in a step with temperature (a logistic: a starved cold state whose replenishment
    # recovers as it warms), one node: just past the fold where the cool equilibrium ends the heating path
    # creeps past its ghost with growing increments and a loop gain ≥ 1 — which alone was called runaway —
    # and goes on to the hot equilibrium, 396 K, far below the limit: the update maps the limit below itself
    b, w, Tm = 120.0, 5.0, 340.0

    def P(T, a):
        return a + b / (1.0 + np.exp(-(np.asarray(T, float) - Tm) / w))

    grid = np.linspace(TA, Tm, 4001)

    def cool_root(a):                                # a cool equilibrium below Tm exists
        return bool(np.min(TA + P(grid, a) / G - grid) <= 0.0)
    lo, hi = 0.0, 120.0                              # cool root at lo, none at hi
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if cool_root(mid) else (lo, mid)
    a = hi + 0.05                                    # just past the fold
    hot = brentq(lambda T: TA + P(T, a) / G - T, Tm, 573.15)
    for method in ("picard", "anderson"):
        r = solve_coupled(lambda T: (TA + P(T, a) / G, float(np.sum(P(T, a)))), [TA], method=method, max_iter=400)
        assert r.T_K[0] == pytest.approx(hot, abs=1e-5) and r.loop_gain < 1.0
    # the same map with losses that outgrow the cooling up to the limit is still a runaway
    with pytest.raises(ThermalRunaway):
        solve_coupled(lambda T: (TA + (P(T, a) + 0.02 * (T - TA) ** 2) / G, 1.0), [TA], method="picard",
                      max_iter=400)


def test_runaway_stays_runaway_where_the_update_is_undefined_at_the_limit():
    # the test of the limit (does the update map it below itself?) cannot be made where the update refuses
    # such temperatures (a lubricant's property range): nothing is proven, the runaway stands (not the InputError)
    theta = 20.0
    P0 = 1.02 * G * theta / math.e                   # 2 % beyond the tangency: the path creeps, then accelerates

    def update(T):
        if np.max(T) > 500.0:
            raise InputError("T_C", float(np.max(T)) - 273.15, "a lubricant temperature up to 226.85 °C")
        P = P0 * np.exp((T - TA) / theta)
        return TA + P / G, float(np.sum(P))
    with pytest.raises(ThermalRunaway):
        solve_coupled(update, [TA], method="picard", max_iter=400)
