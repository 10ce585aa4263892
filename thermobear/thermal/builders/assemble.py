"""Assemble a machine's thermal network from its parts (see :mod:`thermobear.thermal.builders`)."""
from __future__ import annotations

from thermobear.thermal.builders.bearing import add_cage, add_closures, add_rings, add_seats, add_thrust_washers
from thermobear.thermal.builders.bodies import add_housing, add_shaft
from thermobear.thermal.builders.layout import layout
from thermobear.thermal.builders.lubrication import add_mixture, add_supply
from thermobear.thermal.builders.machine import Machine, check_machine
from thermobear.thermal.builders.spec import BuiltNetwork, NetworkSpec

__all__ = ["build_network"]

SOURCE = ("built from dimensions by thermobear.thermal.builders (the discretisation rule of "
          "thermobear.thermal.builders.axisym; each element's law and source in its description)")


def build_network(m: Machine) -> BuiltNetwork:
    """The thermal network of a machine.

    Parameters
    ----------
    m : Machine   bearing, shaft, housing, lubrication (SI; ``None`` fields take the documented
                  defaults of :mod:`thermobear.thermal.builders.machine`)

    Returns
    -------
    BuiltNetwork   ``.spec`` the network table for :func:`thermobear.thermal.prepare_network`,
                   ``.cells`` / ``.surfaces`` the geometry, ``.segments`` the discretisation

    Examples
    --------
    >>> from thermobear.contact.geometry import bearing
    >>> from thermobear.thermal.builders import Lubrication
    >>> net = build_network(Machine(bearing("6208"), n_rpm=3000.0, Fr=2000.0,
    ...                             lubrication=Lubrication(supply="grease")))
    >>> {"inner_race", "balls", "outer_race", "oil_air", "shaft", "housing"} <= set(net.nodes)
    True
    """
    check_machine(m)
    lay = layout(m)
    b = m.bearing
    spec = NetworkSpec(m.name, description=m.description or f"{b.name} on its shaft in a {m.housing.type} housing "
                       f"({m.lubrication.supply})", source=m.source or SOURCE, notes=m.notes)
    spec.fixed("ambient", "scene.T_ambient_C", description="room air and surroundings")
    fluid, sump = add_mixture(spec, m, lay)
    if b.kind == "thrust":
        add_thrust_washers(spec, m, lay, fluid, sump)
        cavity = "oil_air"
    else:
        add_rings(spec, m, lay, fluid, sump)
        cavity = add_closures(spec, m, lay)
    if m.cage:
        add_cage(spec, m, lay)
    shaft = add_shaft(spec, m, lay, cavity)
    housing = add_housing(spec, m, lay, cavity)
    add_seats(spec, m, lay, shaft, housing)
    add_supply(spec, m, lay, housing, sump)
    return spec.built()
