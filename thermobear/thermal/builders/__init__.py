"""Thermal networks built from a machine's dimensions: shaft, housing, fits, lubrication.

:func:`build_network` turns a :class:`Machine` (a bearing with its :class:`Shaft`,
:class:`Housing` and :class:`Lubrication`, SI) into the same network table a ``networks/*.toml``
file holds, so that :func:`thermobear.thermal.prepare_network` and the solvers run it unchanged.
Modules: ``machine`` (the description and its defaults), ``layout`` (the defaults resolved),
``axisym`` (the one discretisation rule of bodies of revolution), ``bodies`` / ``faces`` (shaft and
housing), ``bearing`` (rings, balls, seats, seals, cage), ``fits`` (ring seats as joints),
``lubrication`` (mixture, jets, circulating oil, oil–air, bath, grease), ``rigs`` (the seed-004
and seed-002 rigs expressed with these builders), ``spec`` (the table being written).
"""
from thermobear.thermal.builders.assemble import build_network
from thermobear.thermal.builders.axisym import segment_count
from thermobear.thermal.builders.layout import seat_interferences
from thermobear.thermal.builders.machine import Housing, Lubrication, Machine, Shaft
from thermobear.thermal.builders.spec import BuiltNetwork, Cell, Surface

__all__ = ["build_network", "segment_count", "seat_interferences", "Machine", "Shaft", "Housing", "Lubrication",
           "BuiltNetwork", "Cell", "Surface"]
