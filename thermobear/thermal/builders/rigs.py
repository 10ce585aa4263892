"""The seed rigs expressed with the builders: the estimates of the hand-written networks, as machines.

The hand-written tables (``networks/oil_jet_ball_bearing.toml``, ``networks/grease_thrust_four_ball.toml``)
stay the networks of the seed scenes and the general mechanism for rigs nobody can parametrise;
these machines carry the same estimates (dimensions, materials, given joint conductances, the
mounting) so that the builders can be checked against them (tests/test_builders.py).  What the
builders add or do differently, and how much it moves the steady temperatures, is listed in
:data:`DIFFERENCES`.
"""
from __future__ import annotations

from thermobear.contact.geometry import BallBearing
from thermobear.thermal.builders.machine import Housing, Lubrication, Machine, Shaft

__all__ = ["seed004_machine", "seed002_machine", "DIFFERENCES"]

#: What the built networks model differently from the hand-written ones.
DIFFERENCES = {
    "both": ("the ball–race contacts as the hand networks' (Hertz constriction alone: the rigs' machines say "
             "contact_exchange = 'stationary'; a machine's default adds the rolling exchange, the film and the "
             "lubricant around the contacts); "
             "the shaft and housing are cut by the discretisation rule (the hand housing is one node); the seats "
             "are in series with the half cells of the shaft and housing (the hand networks join the nodes "
             "directly); the still mixture conducts between the races (or washers) and the oil–air node"),
    "seed004": ("the shaft inside the housing and the housing's bore exchange with the cavity's mixture; the "
                "housing's end face is a vertical plate (the hand network uses the cylinder's law for it)"),
    "seed002": ("an oil_air node for the grease and air (the hand network has none: the 'oil' role falls back to "
                "the balls) with conduction through the grease; the housing's top is a plate in the fans' flow "
                "(the hand network uses the cylinder's law); the washer seat spans the bearing's height"),
}


def seed004_machine(bearing: BallBearing, n_rpm: float = 3200.0, T_ambient_C: float = 25.0) -> Machine:
    """The seed-004 rig (Darul et al. 2024 §5.1): one 7210 of the two in the measurement block.

    The hand network's estimates: a 50 mm steel shaft from the block's mid-plane (10 mm beyond the
    bearing, a symmetry plane) 150 mm to a support block at ambient, no convection from it; half the
    block, a steel cylinder 160 mm across and 60 mm long from the mid-plane, free convection and
    radiation (ε 0.8) from its side and outer end, 0.854 W/K to the bed (1000 mm² of steel, 50 mm);
    seats 5000 and 2000 W/(m² K); the mixture 4 J/K; the jet's penetration 0.4.
    """
    B = bearing.width
    shaft = Shaft(diameter=bearing.bore, length_left=0.010, length_right=0.150, material="aisi-52100",
                  end_left="adiabatic", end_right="fixed", surface="enclosed", fit_h_W_m2K=5000.0,
                  end_right_node="support_block")
    housing = Housing(type="round", material="aisi-52100", outer_diameter=0.16, axial_length=0.06,
                      offset=-B / 2 - 0.010 + 0.03, end_left="adiabatic", end_right="air", mounting="frame",
                      mounting_G_W_K=42.7 * 1e-3 / 0.05, emissivity=0.8, fit_h_W_m2K=2000.0)
    lub = Lubrication(supply="oil_jet", feed="jet", beta=0.4, oil_air_C_J_K=4.0, contact_exchange="stationary")
    return Machine(bearing=bearing, shaft=shaft, housing=housing, lubrication=lub, rotating="inner", n_rpm=n_rpm,
                   T_ambient_C=T_ambient_C, Fa=450.0, Fr=325.0, name="seed004_built",
                   description="seed 004 rig built from its dimensions (thermobear.thermal.builders.rigs)")


def seed002_machine(bearing: BallBearing, n_rpm: float = 1000.0, T_ambient_C: float = 25.0,
                    rho_cp: float = 1.8e6, k: float = 0.14) -> Machine:
    """The seed-002 rig (Cousseau et al. §2.1): the 51107 in its housing on the four-ball machine.

    The hand network's estimates: the 35 mm shaft 100 mm into the machine's spindle, held at ambient
    there, no convection from it; a steel housing 90 mm across and 50 mm high in the fans' air at
    2 m/s (forced cross flow), no radiation, seated on the machine through 300 W/(m² K) over a 50 mm
    seat; the washers' seats 3000 W/(m² K).  ``rho_cp``, ``k``: the grease's (the network's oil_air node).
    """
    shaft = Shaft(diameter=bearing.bore, length_left=0.100, length_right=0.0, material="aisi-52100",
                  end_left="fixed", end_right="adiabatic", surface="enclosed", fit_h_W_m2K=3000.0)
    housing = Housing(type="round", material="aisi-52100", outer_diameter=0.09, axial_length=0.05,
                      end_left="mounted", end_right="air", mounting="frame",
                      mounting_G_W_K=300.0 * 3.141592653589793 / 4 * 0.05**2, air="forced", air_speed=2.0,
                      shape_convection="forced_cylinder", emissivity=0.0, fit_h_W_m2K=3000.0)
    lub = Lubrication(supply="grease", rho_cp=rho_cp, k=k, contact_exchange="stationary")
    m = Machine(bearing=bearing, shaft=shaft, housing=housing, lubrication=lub, rotating="inner", n_rpm=n_rpm,
                T_ambient_C=T_ambient_C, Fa=7000.0, name="seed002_built",
                description="seed 002 rig built from its dimensions (thermobear.thermal.builders.rigs)")
    return m
