"""Thermal network: elements against hand computations, solver conservation and limits, file checks."""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np
import pytest
from scipy.special import ellipk

import thermobear as tb
from thermobear.files import data_dir, read_toml
from thermobear.errors import InputError, NoConvergence
from thermobear.thermal import (prepare_network, load_network, network_names, solve_steady, solve_transient,
                                split_losses, evaluate)
from thermobear.thermal import elements as el
from thermobear.contact.kinematics import ball_kinematics
from thermobear.losses.drag import oil_volume_fraction_parker
from thermobear.contact.materials import material

C0 = 273.15


# --------------------------------------------------------------------------- stand-ins for the lead's objects
# (the real BallBearing / Lubricant come from geometry.py / lubricant.py; test_coupling imports these)


@dataclass
class StubBearing:
    """Just the attributes a thermal network reads (SI), formulas of Harris 2001 ch. 2."""

    D: float = 12.7e-3
    dm: float = 70e-3
    Z: int = 15
    bore: float = 50e-3
    outer_diameter: float = 90e-3
    width: float = 20e-3
    alpha0: float = math.radians(40.0)
    fi: float = 0.52
    fo: float = 0.52
    E_prime: float = 2.3077e11

    def __post_init__(self):
        self.ball_material = material("aisi-52100")
        self.ring_material = material("aisi-52100")

    def gamma(self, alpha):
        return self.D * math.cos(alpha) / self.dm

    def Rx_i(self, alpha):
        return self.D / 2 * (1 - self.gamma(alpha))

    def Rx_o(self, alpha):
        return self.D / 2 * (1 + self.gamma(alpha))

    @property
    def Ry_i(self):
        return self.fi * self.D / (2 * self.fi - 1)

    @property
    def Ry_o(self):
        return self.fo * self.D / (2 * self.fo - 1)


class StubOil:
    """Mineral oil of seed 004 (ν40 36.6, ν100 7.8 cSt, ρ15 864.6) with Walther ν(T) (ASTM D341)."""

    def __init__(self, nu40=36.6, nu100=7.8, rho15=864.6):
        ll = lambda nu: math.log10(math.log10(nu + 0.7))
        self.B = (ll(nu40) - ll(nu100)) / (math.log10(373.15) - math.log10(313.15))
        self.A = ll(nu40) + self.B * math.log10(313.15)
        self.rho15 = rho15

    def nu(self, T_C):
        return 10 ** (10 ** (self.A - self.B * np.log10(np.asarray(T_C) + 273.15))) - 0.7

    def rho(self, T_C):
        return self.rho15 - 0.6 * (np.asarray(T_C) - 15.0)

    def k_th(self, T_C):
        return 0.13 + 0.0 * np.asarray(T_C)

    def cp(self, T_C):
        return 1950.0


def oil_jet_context(n_rpm=6500.0, T_amb=25.0, T_oil=30.0, flow_L_h=10.0, **extra):
    """The context the coupled solver gives the oil-jet network: scene values and what the physics computed
    for the operating point (``op``: kinematics at the nominal angle, Parker's oil fraction)."""
    b = StubBearing()
    w = n_rpm * math.pi / 30.0
    k = ball_kinematics(w, 0.0, b.alpha0, b.alpha0, b.D, b.dm)
    ctx = {"bearing": b, "oil": StubOil(),
           "scene": {"n_rpm": n_rpm, "T_ambient_C": T_amb, "T_oil_in_C": T_oil, "oil_flow_m3_s": flow_L_h / 3.6e6},
           "op": {"omega_rad_s": w, "omega_inner_rad_s": w, "omega_outer_rad_s": 0.0, "omega_cage_rad_s": float(k.omega_c),
                  "omega_ball_rad_s": abs(float(k.omega_R)),
                  "oil_fraction": float(oil_volume_fraction_parker(flow_L_h / 60.0 * 1e3, n_rpm, b.dm * 1e3))}}
    ctx.update(extra)
    return ctx


def thrust_51107_context(T_amb=25.0, **extra):
    # 51107: bore 35, OD 52, height 12 mm; balls and pitch diameter are stand-ins (the lead's catalog rules)
    b = StubBearing(D=6.35e-3, dm=43.5e-3, Z=18, bore=35e-3, outer_diameter=52e-3, width=12e-3,
                    alpha0=math.radians(90.0), fi=0.54, fo=0.54)
    ctx = {"bearing": b, "scene": {"n_rpm": 1000.0, "T_ambient_C": T_amb}}
    ctx.update(extra)
    return ctx


def net_of(nodes, elements, ctx=None):
    return load_network({"name": "t", "nodes": nodes, "elements": elements}, ctx)


def cond(a, b, G, name=None):
    d = {"type": "conductance", "between": [a, b], "G_W_K": G}
    if name:
        d["name"] = name
    return d


# --------------------------------------------------------------------------- evaluator
def test_evaluate_arithmetic_and_context():
    ctx = {"bearing": StubBearing(), "scene": {"n_rpm": 3000.0}}
    assert evaluate("bearing.bore / 2", ctx) == pytest.approx(0.025)
    assert evaluate("pi * scene.n_rpm / 30", ctx) == pytest.approx(100 * math.pi)
    assert evaluate("sqrt(16) + 2**3 - -1", {}) == 13.0
    assert evaluate(2, {}) == 2.0


@pytest.mark.parametrize("expr", ["__import__('os')", "bearing.__class__", "(lambda: 1)()",
                                  "'a' * 3", "[1, 2]", "scene.n_rpm if 1 else 2", "open('x')",
                                  "bearing.gamma(0.1)", "1 / 0", "10.0**400"])
def test_evaluate_rejects_everything_else(expr):
    ctx = {"bearing": StubBearing(), "scene": {"n_rpm": 1.0}}
    with pytest.raises(InputError) as exc:
        evaluate(expr, ctx, "elements[x].L_m")
    assert exc.value.field == "elements[x].L_m"


def test_evaluate_unknown_name_is_named():
    with pytest.raises(InputError, match="scene.T_oil_in_C"):
        evaluate("scene.T_oil_in_C", {"scene": {}}, "nodes.oil_inlet.T_C")


# --------------------------------------------------------------------------- element physics
def test_shell_conductance_analytic():
    k, L, r1, r2 = 42.7, 0.02, 0.025, 0.02865
    assert el.shell_conductance(k, L, r1, r2) == pytest.approx(2 * math.pi * k * L / math.log(r2 / r1), rel=1e-14)
    # thin shell → planar limit k A / t
    t = 1e-5
    assert el.shell_conductance(k, L, r1, r1 + t) == pytest.approx(k * 2 * math.pi * r1 * L / t, rel=1e-3)
    with pytest.raises(InputError):
        el.shell_conductance(k, L, r2, r1)


def test_constriction_circle_and_ellipse():
    k, a = 40.0, 1e-3
    assert el.constriction_resistance(k, a, a) == pytest.approx(1 / (4 * k * a), rel=1e-14)
    # ellipse, m = 1 - (b/a)^2, independent evaluation
    b = 0.2e-3
    assert el.constriction_resistance(k, a, b) == pytest.approx(ellipk(1 - 0.04) / (2 * math.pi * k * a), rel=1e-14)
    # order of semi-axes does not matter; a more slender contact (same a) conducts less
    assert el.constriction_resistance(k, b, a) == el.constriction_resistance(k, a, b)
    assert el.constriction_resistance(k, a, 0.1e-3) > el.constriction_resistance(k, a, 0.2e-3)


def test_ball_race_contacts_in_parallel_unloaded_excluded():
    a = np.array([5e-4, 5e-4, 5e-4, 0.0])
    b = np.array([1e-4, 1e-4, 1e-4, 0.0])
    one = 1 / (el.constriction_resistance(42.7, 5e-4, 1e-4) + el.constriction_resistance(27.0, 5e-4, 1e-4))
    assert el.ball_race_conductance(42.7, 27.0, a, b) == pytest.approx(3 * one, rel=1e-14)


def test_rolling_contact_exchange_is_the_integral_of_the_semi_infinite_contact_flux():
    # Bergman et al. 2011 §5.7: two semi-infinite solids in contact exchange e_eff ΔT / √(π t); a surface
    # point at y crosses the ellipse's chord 2b√(1 − y²/a²) at u: integrate numerically over the ellipse
    from scipy.integrate import quad
    from thermobear.thermal.conduction import rolling_contact_conductance
    e_eff, a, b, u = 6200.0, 9e-4, 8e-5, 2.9

    def chord(y):
        L = 2 * b * math.sqrt(max(1 - (y / a) ** 2, 0.0))
        return e_eff * 2 * math.sqrt(u * L / math.pi)         # ∫_0^L e/√(π x/u) dx
    G_num = quad(chord, -a, a, limit=200)[0]
    assert rolling_contact_conductance(e_eff, a, b, u) == pytest.approx(G_num, rel=1e-7)
    # scaling: ∝ √u (0 at rest), ∝ a, ∝ √b
    assert rolling_contact_conductance(e_eff, a, b, 0.0) == 0.0
    assert rolling_contact_conductance(e_eff, a, b, 4 * u) == pytest.approx(2 * G_num, rel=1e-12)
    assert rolling_contact_conductance(e_eff, 2 * a, 4 * b, u) == pytest.approx(4 * G_num, rel=1e-12)


def test_rolling_ball_race_conductance_limits():
    from thermobear.thermal.conduction import rolling_contact_conductance, thermal_effusivity
    k, a, b = 42.7, np.array([9e-4, 0.0]), np.array([8e-5, 0.0])
    e = thermal_effusivity(k, 7830.0, 460.0)
    assert e == pytest.approx(math.sqrt(k * 7830.0 * 460.0), rel=1e-14)
    Gs = el.ball_race_conductance(k, k, a, b)
    # at rest: the stationary constriction; fast: the rolling exchange (Pe = u b / 2κ ≈ 40 at 12 m/s)
    assert el.ball_race_conductance(k, k, a, b, u=np.zeros(2), e_ball=e, e_ring=e) == pytest.approx(Gs, rel=1e-14)
    Gr = rolling_contact_conductance(e / 2, a[0], b[0], 12.0)
    G = el.ball_race_conductance(k, k, a, b, u=np.full(2, 12.0), e_ball=e, e_ring=e)
    assert Gr > 10 * Gs and G == pytest.approx(Gr, rel=0.01) and G > max(Gr, Gs)
    # an oil film in series: below both, and the plane layer's resistance h / (k_f π a b) added
    Gf = el.ball_race_conductance(k, k, a, b, u=np.full(2, 12.0), e_ball=e, e_ring=e, h_film=np.full(2, 5e-7),
                                  k_film=0.13)
    assert 1 / Gf == pytest.approx(1 / G + 5e-7 / (0.13 * math.pi * a[0] * b[0]), rel=1e-12)
    with pytest.raises(InputError):
        el.ball_race_conductance(k, k, a, b, u=np.full(2, 12.0))


def test_meniscus_conduction_is_the_gap_integral():
    # k/h over the gap h = h0 + x²/2Rx + y²/2Ry out to where it reaches h_m (an ellipse), numerically
    from scipy.integrate import quad
    from thermobear.thermal.conduction import meniscus_conductance
    k, Rx, Ry, h0, hm = 0.13, 3e-3, 0.1, 1e-6, 3e-5
    # in polar coordinates of the scaled plane (x = √Rx r cos θ, y = √Ry r sin θ): dA = √(Rx Ry) r dr dθ
    r_m = math.sqrt(2 * (hm - h0))
    G_num = 2 * math.pi * math.sqrt(Rx * Ry) * quad(lambda r: k * r / (h0 + r * r / 2), 0.0, r_m)[0]
    assert meniscus_conductance(k, Rx, Ry, h0, hm) == pytest.approx(G_num, rel=1e-10)
    assert meniscus_conductance(k, Rx, Ry, h0, h0) == 0.0 and meniscus_conductance(k, Rx, Ry, h0, 0.5 * h0) == 0.0
    assert meniscus_conductance(k, Rx, Ry, h0, 10 * hm) > meniscus_conductance(k, Rx, Ry, h0, hm)


def test_harris_coefficient_and_scaling():
    k, Pr, u, nu, x = 0.03, 2.0, 12.0, 2e-5, 0.02
    h = el.h_harris(k, Pr, u, nu, x)
    assert h == pytest.approx(0.0332 * k * Pr ** (1 / 3) * math.sqrt(u / (nu * x)), rel=1e-14)
    assert el.h_harris(k, Pr, u, nu, x, "flat_plate_laminar") == pytest.approx(10 * h, rel=1e-12)
    # h ∝ (u/(ν x))^½ (pitfall 11: not (u x/ν)^½)
    assert el.h_harris(k, Pr, 4 * u, nu, x) == pytest.approx(2 * h)
    assert el.h_harris(k, Pr, u, nu, 4 * x) == pytest.approx(h / 2)
    assert el.h_harris(k, Pr, 0.0, nu, x) == 0.0
    with pytest.raises(InputError):
        el.h_harris(k, Pr, u, nu, x, "harris_typo")


def test_air_convection_against_hand_correlations():
    Ts, Ta, D, u = 340.0, 300.0, 0.12, 3.0
    air = el.air_properties(0.5 * (Ts + Ta))
    # Churchill-Chu, horizontal cylinder, free convection (Incropera eq 9.34)
    Gr = 9.80665 / (0.5 * (Ts + Ta)) * (Ts - Ta) * D**3 / air["nu"] ** 2
    Ra = Gr * air["Pr"]
    Nu = (0.60 + 0.387 * Ra ** (1 / 6) / (1 + (0.559 / air["Pr"]) ** (9 / 16)) ** (8 / 27)) ** 2
    assert el.h_natural_horizontal_cylinder(Ts, Ta, D) == pytest.approx(Nu * air["k"] / D, rel=1e-10)
    # Churchill-Bernstein, cylinder in cross-flow (Incropera eq 7.54)
    Re, Pr = u * D / air["nu"], air["Pr"]
    Nu = 0.3 + 0.62 * Re**0.5 * Pr ** (1 / 3) / (1 + (0.4 / Pr) ** (2 / 3)) ** 0.25 * (1 + (Re / 282000) ** 0.625) ** 0.8
    assert el.h_forced_cylinder(u, D, Ts, Ta) == pytest.approx(Nu * air["k"] / D, rel=1e-10)
    # laminar flat plate, mean: 0.664 Re^½ Pr^⅓
    assert el.h_forced_plate(u, D, Ts, Ta) == pytest.approx(0.664 * Re**0.5 * Pr ** (1 / 3) * air["k"] / D, rel=1e-10)
    # free convection grows with ΔT
    assert el.h_natural_horizontal_cylinder(360.0, Ta, D) > el.h_natural_horizontal_cylinder(Ts, Ta, D)


def test_radiation_linearisation_exact():
    h = el.h_radiation(0.8, 360.0, 295.0)
    assert h * 65.0 == pytest.approx(0.8 * el.SIGMA_SB * (360.0**4 - 295.0**4), rel=1e-14)
    Tm = 0.5 * (360 + 295)
    assert h == pytest.approx(4 * 0.8 * el.SIGMA_SB * Tm**3, rel=0.01)


def test_oil_air_mixture_limits():
    oil = StubOil()
    pure = el.oil_air_properties(1.0, oil.rho(50), oil.nu(50), 0.13, 1950.0, 323.15)
    assert pure["nu"] == pytest.approx(oil.nu(50) * 1e-6, rel=1e-12)
    assert pure["Pr"] == pytest.approx(oil.nu(50) * 1e-6 * oil.rho(50) * 1950.0 / 0.13, rel=1e-12)
    air = el.oil_air_properties(0.0, oil.rho(50), oil.nu(50), 0.13, 1950.0, 323.15)
    assert air["rho"] == pytest.approx(el.air_properties(323.15)["rho"])


# --------------------------------------------------------------------------- steady solver
def test_series_and_parallel_against_hand_sums():
    # a --(2 W/K)-- b --(4 W/K || 1 W/K)-- ambient ; 30 W into a
    net = net_of({"a": {}, "b": {}, "amb": {"T_C": 20.0}},
                 [cond("a", "b", 2.0), cond("b", "amb", 4.0, "p1"), cond("b", "amb", 1.0, "p2")])
    r = solve_steady(net, {"a": 30.0})
    R_total = 1 / 2.0 + 1 / (4.0 + 1.0)
    assert r.T_C["a"] == pytest.approx(20.0 + 30.0 * R_total, rel=1e-13)
    assert r.T_C["b"] == pytest.approx(20.0 + 30.0 / 5.0, rel=1e-13)
    assert r.flows_W["p1"] == pytest.approx(24.0) and r.flows_W["p2"] == pytest.approx(6.0)
    assert r.flows_W["a--b"] > 0                      # signed along between: from a to b
    assert abs(r.balance_rel) < 1e-12


def test_cylindrical_shell_in_network():
    net = net_of({"bore": {}, "outside": {"T_C": 40.0}},
                 [{"type": "shell", "between": ["bore", "outside"], "material": "aisi-52100",
                   "r1_m": "bearing.bore / 2", "r2_m": "bearing.outer_diameter / 2", "L_m": "bearing.width"}],
                 {"bearing": StubBearing()})
    r = solve_steady(net, {"bore": 100.0})
    G = 2 * math.pi * 42.7 * 0.02 / math.log(45 / 25)
    assert r.T_C["bore"] - 40.0 == pytest.approx(100.0 / G, rel=1e-12)


def test_advection_is_one_way_and_carries_heat_out():
    nodes = {"inlet": {"T_C": 30.0}, "u": {}, "d": {}, "amb": {"T_C": 20.0}}
    adv = lambda a, b, name: {"name": name, "type": "advection", "between": [a, b], "Q_m3_s": 1e-5,
                              "beta": 0.5, "rho_kg_m3": 800.0, "cp_J_kgK": 2000.0}
    G = 800 * 2000 * 1e-5 * 0.5          # 8 W/K
    net = net_of(nodes, [adv("inlet", "u", "s1"), adv("u", "d", "s2"), cond("u", "amb", 1.0)])
    r0 = solve_steady(net, {})
    r = solve_steady(net, {"d": 40.0})
    # the downstream source does not warm the upstream node (upwind), a symmetric link would
    assert r.T_C["u"] == pytest.approx(r0.T_C["u"], abs=1e-12)
    assert r.T_C["d"] - r.T_C["u"] == pytest.approx(40.0 / G, rel=1e-12)
    # heat carried by the stream out of d: G (T_d − T_u) = 40 W, in the flow direction
    assert r.flows_W["s2"] == pytest.approx(40.0) and r.heat_out_W["stream"] == pytest.approx(40.0 + r.flows_W["s1"])
    assert abs(r.balance_rel) < 1e-12
    # simplest case: T_mix = T_in + P / (ρ c_p Q β)
    net1 = net_of({"inlet": {"T_C": 30.0}, "mix": {}}, [adv("inlet", "mix", "s")])
    assert solve_steady(net1, {"mix": 16.0}).T_C["mix"] == pytest.approx(32.0, rel=1e-13)


def test_energy_balance_random_networks():
    rng = np.random.default_rng(1)
    for _ in range(5):
        n = 8
        nodes = {f"n{i}": {} for i in range(n)}
        nodes["amb"] = {"T_C": 20.0}
        nodes["inlet"] = {"T_C": 35.0}
        els = [cond(f"n{i}", f"n{i + 1}", float(rng.uniform(0.1, 50)), f"c{i}") for i in range(n - 1)]
        els += [cond(f"n{i}", f"n{j}", float(rng.uniform(0.1, 5)), f"x{i}{j}")
                for i, j in rng.integers(0, n, (6, 2)) if i != j]
        els += [cond("n0", "amb", 2.0, "g"), {"type": "advection", "between": ["inlet", "n3"], "Q_m3_s": 2e-6,
                                              "beta": 0.4, "rho_kg_m3": 860.0, "cp_J_kgK": 1950.0}]
        net = net_of(nodes, els)
        src = {f"n{i}": float(rng.uniform(0, 100)) for i in range(n)}
        r = solve_steady(net, src)
        assert abs(r.balance_rel) < 1e-9
        assert math.fsum(r.heat_out_W.values()) == pytest.approx(sum(src.values()), rel=1e-9)


@pytest.mark.parametrize("name,ctx,src", [
    ("oil_jet_ball_bearing", oil_jet_context(), split_losses([8.0] * 15, [8.0] * 15, 20.0)),
    ("grease_thrust_four_ball", thrust_51107_context(),
     split_losses([3.0] * 18, [3.0] * 18, 0.0, inner="shaft_washer", outer="housing_washer", oil="balls")),
    ("one_node", {"bearing": StubBearing(), "scene": {"T_ambient_C": 25.0}}, {"bearing": 200.0}),
])
def test_shipped_networks_load_and_give_sensible_temperatures(name, ctx, src):
    assert name in network_names()
    net = load_network(name, ctx)
    r = solve_steady(net, src)
    assert abs(r.balance_rel) < 1e-9
    free = [r.T_C[n] for n in net.free_nodes]
    assert min(free) > 25.0 - 1e-9                    # heated above the coldest boundary
    assert max(free) < 400.0                          # few hundred W: hot but finite
    hottest = max(net.free_nodes, key=lambda n: r.T_C[n])
    assert hottest in src                             # the maximum sits where heat is injected
    assert net.estimated                              # estimates are declared


def test_oil_jet_network_physics_trends():
    ctx = oil_jet_context()
    net = load_network("oil_jet_ball_bearing", ctx)
    src = split_losses([6.0] * 15, [6.0] * 15, 10.0)
    r = solve_steady(net, src)
    assert r.iterations > 1 and r.residual_K < 1e-8    # temperature-dependent elements iterated
    assert r.heat_out_W["stream"] > 0                   # the oil carries heat away
    # more oil → cooler mixture and bearing
    r2 = solve_steady(load_network("oil_jet_ball_bearing", oil_jet_context(flow_L_h=15.0)), src)
    assert r2.T_C["oil_air"] < r.T_C["oil_air"] and r2.T_C["inner_ring"] < r.T_C["inner_ring"]
    # hotter inlet oil → hotter bearing
    r3 = solve_steady(load_network("oil_jet_ball_bearing", oil_jet_context(T_oil=50.0)), src)
    assert r3.T_C["inner_ring"] > r.T_C["inner_ring"]
    # contact semi-axes from the mechanics replace the fallback; bigger contacts conduct more
    a = np.full(15, 1.0e-3)
    b = np.full(15, 0.2e-3)
    ctx_c = oil_jet_context(contacts={"inner": {"a_m": a, "b_m": b}, "outer": {"a_m": a, "b_m": b}})
    net_c = load_network("oil_jet_ball_bearing", ctx_c)
    contact = next(e for e in net_c.elements if e.name == "inner_contacts")
    assert contact.p["semi_axes_from"] == "context"
    assert solve_steady(net_c, src).T_C["balls"] < r.T_C["balls"]


def test_steady_outer_loop_budget_raises():
    net = load_network("oil_jet_ball_bearing", oil_jet_context())
    with pytest.raises(NoConvergence) as exc:
        solve_steady(net, {"balls": 100.0}, max_iter=2)
    assert exc.value.iterations == 2 and exc.value.residual > 0


def test_sources_into_unknown_or_fixed_nodes_rejected():
    net = net_of({"a": {}, "amb": {"T_C": 20.0}}, [cond("a", "amb", 1.0)])
    with pytest.raises(InputError, match="sources"):
        solve_steady(net, {"nope": 1.0})
    with pytest.raises(InputError, match="sources.amb"):
        solve_steady(net, {"amb": 1.0})


# --------------------------------------------------------------------------- sources
def test_split_losses_conserves_energy():
    Pi, Po = np.array([1.0, 2.0, 0.0, 3.5]), np.array([0.5, 0.25, 0.0, 1.0])     # four operating points
    s = split_losses(Pi, Po, 0.7, extra={"seal": 0.3})
    np.testing.assert_allclose(s["balls"], 0.5 * (Pi + Po))
    np.testing.assert_allclose(s["inner_race"], 0.5 * Pi)
    np.testing.assert_allclose(s["outer_race"], 0.5 * Po)
    np.testing.assert_allclose(sum(s.values()), Pi + Po + 0.7 + 0.3, rtol=1e-15)
    with pytest.raises(InputError):
        split_losses([-1.0], [0.0])


# --------------------------------------------------------------------------- transient
def rc_net(C=500.0, G=2.0, T_amb=20.0):
    return net_of({"b": {"C_J_K": C}, "ambient": {"T_C": T_amb}}, [cond("b", "ambient", G)])


def test_rc_matches_exact_exponential():
    C, G, P = 500.0, 2.0, 80.0
    t = np.linspace(0, 2000, 41)
    r = solve_transient(rc_net(C, G), {"b": P}, 2000.0, t_eval=t)
    exact = P / G * (1 - np.exp(-G * t / C))
    rise = r.T_C["b"] - 20.0
    assert np.allclose(rise[1:], exact[1:], rtol=1e-4, atol=0)
    assert r.t[0] == 0 and rise[0] == 0.0


def test_long_transient_reaches_steady_state():
    net = load_network("oil_jet_ball_bearing", oil_jet_context())
    src = split_losses(75.0, 75.0, 15.0)
    tr = solve_transient(net, src, 3e5, t_eval=[3e5])
    st = solve_steady(net, src)
    for n in net.nodes:
        assert tr.T_C[n][-1] == pytest.approx(st.T_C[n], abs=0.1)


def test_step_schedule_not_smeared_and_report_recorded():
    C, G, P, t1 = 400.0, 4.0, 40.0, 100.0

    def sources(t, T_K):           # T_K (..., B, n); the output pass calls it with all output times at once
        q = np.where(np.asarray(t) >= t1, P, 0.0)
        Pm = np.zeros(np.shape(T_K))
        Pm[..., 0] = q if np.ndim(t) == 0 else q[:, None]
        return Pm, {"P_W": Pm[..., 0], "T_b_K": T_K[..., 0]}

    t = np.array([0.0, 50.0, 100.0, 150.0, 300.0])
    r = solve_transient(rc_net(C, G), sources, 300.0, breakpoints=[t1], t_eval=t)
    assert np.all(np.abs(r.T_C["b"][:3] - 20.0) < 1e-9)          # nothing before the step
    tau = C / G
    exact = 20.0 + P / G * (1 - np.exp(-(t[3:] - t1) / tau))
    assert np.allclose(r.T_C["b"][3:], exact, rtol=1e-5)
    assert list(r.report["P_W"]) == [0.0, 0.0, P, P, P]
    assert np.allclose(r.report["T_b_K"], r.T_K[:, 0, 0])
    # a step in a boundary temperature (fixed_C) at the same breakpoint
    r2 = solve_transient(rc_net(C, G), {}, 300.0, breakpoints=[t1], t_eval=t,
                         fixed_C=lambda tt: {"ambient": 20.0 if tt < t1 else 30.0})
    assert np.allclose(r2.T_C["b"][3:], 20.0 + 10.0 * (1 - np.exp(-(t[3:] - t1) / tau)), rtol=1e-5)


def test_continued_transient_follows_the_exact_exponential():
    # a run continued in pieces (its integrator kept) is the one run: the exact RC heat-up, and a
    # source stepping between the pieces (as film loads re-solved per piece do) is followed exactly
    C, G, P, net = 500.0, 2.0, 80.0, rc_net(500.0, 2.0)
    first = solve_transient(net, {"b": P}, 300.0, t_eval=[300.0])
    second = solve_transient(net, {"b": P}, 700.0, t_eval=[350.0, 700.0], continue_from=first)
    assert list(second.t) == [350.0, 700.0]
    exact = 20.0 + P / G * (1 - np.exp(-G * (300.0 + second.t) / C))
    assert np.allclose(second.T_C["b"], exact, rtol=1e-5)
    third = solve_transient(net, {"b": 2 * P}, 1000.0, t_eval=[1000.0], continue_from=second)
    T1 = exact[-1]
    T_inf = 20.0 + 2 * P / G
    assert third.T_C["b"][-1] == pytest.approx(T_inf + (T1 - T_inf) * np.exp(-G * 1000.0 / C), rel=1e-5)
    with pytest.raises(InputError, match="T0_C"):
        solve_transient(net, {"b": P}, 10.0, continue_from=third, T0_C=30.0)
    with pytest.raises(InputError, match="continue_from"):
        solve_transient(net, {"b": P}, 10.0, continue_from=object())
    with pytest.raises(InputError, match="continued once"):               # its integrator has gone on since
        solve_transient(net, {"b": P}, 10.0, continue_from=first)
    with pytest.raises(InputError, match="rtol"):
        solve_transient(net, {"b": P}, 10.0, continue_from=third, rtol=1e-6)


def test_until_ends_the_run_at_its_step_and_the_next_run_goes_on():
    # a run ended by ``until`` (where the RC node passes 40 °C) stops at that step, its state the last point
    # also with t_eval; the run continued from there is the one exact exponential
    C, G, P, net = 500.0, 2.0, 80.0, rc_net(500.0, 2.0)
    first = solve_transient(net, {"b": P}, 1000.0, t_eval=[100.0, 1000.0], until=lambda t, T_K: T_K[0, 0] > 313.15)
    assert first.completed and first.t[0] == 100.0 and 100.0 < first.t[-1] < 1000.0
    exact = (lambda t: 20.0 + P / G * (1 - np.exp(-G * t / C)))  # noqa: E731
    assert first.T_C["b"][-1] > 40.0 and exact(first.t[-1] * 0.9) < 40.0    # the step that passed 40 °C
    assert first.T_C["b"][-1] == pytest.approx(exact(first.t[-1]), rel=1e-5)
    rest = 1000.0 - first.t[-1]
    second = solve_transient(net, {"b": P}, rest, t_eval=[rest], continue_from=first)
    assert second.T_C["b"][-1] == pytest.approx(exact(1000.0), rel=1e-5)


def test_transient_needs_capacities():
    net = net_of({"a": {}, "amb": {"T_C": 20.0}}, [cond("a", "amb", 1.0)])
    with pytest.raises(InputError, match="nodes.a.C_J_K"):
        solve_transient(net, {"a": 1.0}, 10.0)


# --------------------------------------------------------------------------- bad files
BASE_NODES = {"a": {"C_J_K": 10.0}, "amb": {"T_C": 20.0}}


@pytest.mark.parametrize("nodes,elements,field", [
    (BASE_NODES, [{"type": "conductance", "between": ["a", "amb"], "G_W_K": 1.0, "r3_m": 1.0}], "r3_m"),
    (BASE_NODES, [{"type": "conduction", "between": ["a", "amb"], "G_W_K": 1.0}], ".type"),
    (BASE_NODES, [{"type": "conductance", "between": ["a", "zz"], "G_W_K": 1.0}], ".between"),
    (BASE_NODES, [{"type": "shell", "between": ["a", "amb"], "material": "aisi-52100", "r1_m": 0.01,
                   "L_m": 0.02}], ".r2_m"),
    (BASE_NODES, [{"type": "shell", "between": ["a", "amb"], "material": "aisi-52100", "r1_m": 0.02,
                   "r2_m": 0.01, "L_m": 0.02}], "r2_m"),
    (BASE_NODES, [{"type": "planar", "between": ["a", "amb"], "k_W_mK": 40.0, "A_m2": 1e-3,
                   "length_m": -0.1}], ".length_m"),
    (BASE_NODES, [{"type": "conductance", "between": ["a", "amb"], "G_W_K": 1.0, "estimated": ["R_K_W"]}],
     ".estimated"),
    (BASE_NODES, [{"type": "conductance", "between": ["a", "amb"], "G_W_K": "scene.G"}], ".G_W_K"),
    ({**BASE_NODES, "lonely": {}}, [{"type": "conductance", "between": ["a", "amb"], "G_W_K": 1.0}],
     "nodes.lonely"),
    ({"a": {"C_J_K": 10.0, "T_C": 20.0}, "amb": {"T_C": 20.0}},
     [{"type": "conductance", "between": ["a", "amb"], "G_W_K": 1.0}], "nodes.a.T_C"),
    ({"a": {"C_J_K": 10.0, "colour": "red"}, "amb": {"T_C": 20.0}},
     [{"type": "conductance", "between": ["a", "amb"], "G_W_K": 1.0}], "nodes.a.colour"),
    (BASE_NODES, [{"type": "advection", "between": ["a", "amb"], "Q_m3_s": 1e-6, "beta": 0.4,
                   "rho_kg_m3": 860.0, "cp_J_kgK": 1950.0}], ".between"),
    (BASE_NODES, [{"type": "advection", "between": ["amb", "a"], "Q_m3_s": 1e-6, "beta": 1.4,
                   "rho_kg_m3": 860.0, "cp_J_kgK": 1950.0}], "beta"),
    (BASE_NODES, [{"type": "convection", "between": ["a", "amb"], "correlation": "forced_cylinder",
                   "A_m2": 0.01, "D_m": 0.1}], ".u_air_m_s"),
    (BASE_NODES, [{"type": "convection", "between": ["a", "amb"], "correlation": "harris", "A_m2": 0.01,
                   "u_m_s": 1.0, "x_m": 0.01, "oil_fraction": 0.01}], ".correlation"),
    (BASE_NODES, [{"type": "ball_race_contact", "between": ["a", "amb"], "contact": "inner",
                   "k_ball_W_mK": 40.0, "k_ring_W_mK": 40.0, "n_balls": 3}], "contacts.inner.a_m"),
    (BASE_NODES, [{"type": "shell", "between": ["a", "amb"], "material": "unobtainium", "r1_m": 0.01,
                   "r2_m": 0.02, "L_m": 0.02}], ".material"),
])
def test_bad_network_raises_input_error_naming_the_field(nodes, elements, field):
    with pytest.raises(InputError) as exc:
        net_of(nodes, elements, {"scene": {}})
    assert field in exc.value.field, str(exc.value)


def test_bad_toml_file_named(tmp_path):
    p = tmp_path / "bad.toml"
    p.write_text('[nodes.a]\nC_J_K = 1.0\n[nodes.amb]\nT_C = 20.0\n[[elements]]\ntype = "conductance"\n'
                 'between = ["a", "amb"]\nG_W_K = 1.0\nL_mm = 3.0\n')
    with pytest.raises(InputError) as exc:
        load_network(p, {})
    assert exc.value.field.startswith("bad.toml: elements[a--amb].L_mm")
    with pytest.raises(InputError, match="unknown network"):
        load_network("no_such_network", {})
    with pytest.raises(InputError, match="fixed-temperature node") as exc:
        net_of({"a": {}, "b": {}}, [cond("a", "b", 1.0)])
    assert exc.value.field.endswith("nodes")
    with pytest.raises(InputError, match="elements"):
        net_of({"a": {}, "amb": {"T_C": 20.0}}, [])


def test_a_template_at_many_operating_points_equals_each_point_alone():
    # one check of the table, then the operating-point values as arrays: every point's conductances
    # equal the network built for that point alone, and a bad value in any point is refused by name
    spec = read_toml(str(data_dir("networks") / "oil_jet_ball_bearing.toml"))
    ctxs = [oil_jet_context(), oil_jet_context(n_rpm=3200.0, T_oil=50.0), oil_jet_context(flow_L_h=15.0)]
    template = prepare_network(spec, {"bearing": ctxs[0]["bearing"]})
    scene = {k: np.array([c["scene"][k] for c in ctxs]) for k in ctxs[0]["scene"]}
    op = {k: np.array([c["op"][k] for c in ctxs]) for k in ctxs[0]["op"]}
    many = template.at({**ctxs[0], "scene": scene, "op": op})
    assert many.B == 3
    for b, ctx in enumerate(ctxs):
        one = load_network(spec, ctx)
        T = one.initial_T_K() + 7.0
        np.testing.assert_allclose(many.conductances(np.repeat(T, 3, axis=0))[b], one.conductances(T)[0], rtol=1e-14)
    bad = dict(scene, oil_flow_m3_s=np.array([1e-6, -1e-6, 1e-6]))
    with pytest.raises(InputError, match=r"elements\[oil_stream\]\.Q_m3_s .* must be >= 0"):
        template.at({**ctxs[0], "scene": bad, "op": op})

def test_heat_balance_jacobian_matches_finite_differences():
    """∂(A(T) T)/∂T of the network (the Newton Jacobian's thermal part) against central differences
    of the heat leaving each node, for every operating point of a batch."""
    spec = read_toml(str(data_dir("networks") / "oil_jet_ball_bearing.toml"))
    ctx = oil_jet_context()
    net = prepare_network(spec, {"bearing": ctx["bearing"]}).at({**ctx, "scene": {
        k: np.array([v, v]) for k, v in ctx["scene"].items()}, "op": {k: np.array([v, v]) for k, v in ctx["op"].items()}})
    T = net.initial_T_K() + np.where(net.fixed, 0.0, np.linspace(5.0, 40.0, len(net.nodes)))[None] * np.array([[1.0], [1.5]])

    def flux(T):                                   # A(T) T: heat leaving each node [W]
        return np.einsum("bij,bj->bi", net.matrix(net.conductances(T)), T)

    G, dG = net.dconductances(T)
    free = np.flatnonzero(~net.fixed)
    J = net.matrix(G)[:, free][:, :, free] + net.dAT_free(T, dG)
    for c, m in enumerate(free):
        h = 1e-3
        Tp, Tm = T.copy(), T.copy()
        Tp[:, m] += h
        Tm[:, m] -= h
        col = (flux(Tp) - flux(Tm)) / (2 * h)
        np.testing.assert_allclose(J[:, :, c], col[:, free], rtol=1e-4, atol=1e-6 * np.abs(J).max())
    assert np.abs(net.dAT_free(T, dG)).max() > 1e-3       # the dependence is not negligible here


def test_free_convection_in_oil_at_the_oils_limits_is_finite_and_continuous():
    # a node at the lubricant's refusal temperature (an iterate of a coupled solve may reach it): the
    # expansion coefficient's ±1 K difference stays inside the oil's range instead of refusing it
    from thermobear.lubrication.lubricant import lubricant
    from thermobear.validity import T_LUBRICANT_REFUSE_C
    oil = lubricant("iso-vg-68-mineral")
    e = el.Convection("c", "convection", ("a", "b"), 0, 1, {"correlation": "plate_vertical", "fluid": "oil",
                                                            "L_m": 0.05, "A_m2": 1e-3})
    lo, hi = (t + 273.15 for t in T_LUBRICANT_REFUSE_C)
    for T_wall, T_fluid, T_in in ((hi + 10.0, hi, hi - 0.5), (lo, lo - 10.0, lo + 0.5)):
        G = e.conductance(np.array([T_wall]), np.array([T_fluid]), oil)
        G_in = e.conductance(np.array([T_in + 5.0]), np.array([T_in - 5.0]), oil)
        assert np.isfinite(G).all() and G[0] > 0
        assert G[0] == pytest.approx(G_in[0], rel=0.05)     # no step at the limit


def test_the_output_pass_in_chunks_equals_one_call(monkeypatch):
    """The losses at the output times are evaluated in chunks of times (a 100 000-point heat-up held every
    contact's losses at every time at once: 3.7 GB); the series are those of one call."""
    import thermobear as tb
    import thermobear.thermal.solve as solve
    s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    t = np.linspace(0.0, 600.0, 1201)
    whole = tb.transient(s, 600.0, t_eval=t)
    monkeypatch.setattr(solve, "_OUTPUT_CHUNK", 100)
    chunked = tb.transient(s, 600.0, t_eval=t)
    assert chunked.t_s.size == 1201
    np.testing.assert_allclose(chunked.P_W, whole.P_W, rtol=1e-12)
    for k, v in whole.breakdown_W.items():
        np.testing.assert_allclose(chunked.breakdown_W[k], v, rtol=1e-12, atol=1e-15)


def test_forced_plate_convection_takes_temperatures_per_operating_point():
    """ht's laminar flat-plate law branches on Pr with a scalar `if`: film temperatures of several stacked points (the
    alternatives of a point in a model-switch band) made it raise ValueError, and a built machine with forced air
    stopped with an internal error there.  Elementwise now, equal to the scalar calls."""
    from thermobear.thermal.convection import h_forced_plate
    T = np.array([300.0, 320.0, 360.0])
    got = np.asarray(h_forced_plate(2.0, 0.1, T, 300.0))
    np.testing.assert_allclose(got, [h_forced_plate(2.0, 0.1, float(t), 300.0) for t in T], rtol=1e-15)
    assert np.all(np.diff(got) < 0)                     # warmer film air: a thicker, more viscous boundary layer


def test_a_forced_air_machine_in_a_switch_band_solves(tmp_path):
    from thermobear.app.cli import main
    path = tmp_path / "s.toml"
    assert main(["init", "7014C", "--lubrication", "oil-air", "--speed-rpm", "4000", "--out", str(path)]) == 0
    text = path.read_text(encoding="utf-8").replace('air = "still"', 'air = "forced"\nair_speed_m_s = 30.0')
    path.write_text(text, encoding="utf-8")
    s = tb.load_scene(path).with_(Fa=431.0, Fr=1010.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        st = tb.steady_state(s)
    assert "blend" in st.models_used and st.P_W > 0 and abs(st.residual_K) < 1e-6
