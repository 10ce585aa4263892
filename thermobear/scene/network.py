"""The scene's thermal network: which file, with the scene's overrides and imposed temperatures.

A scene names a bundled network (``networks/<name>.toml``) or a path (absolute, relative to the
scene file, or — for a scene built in code — to the working directory).  :func:`network_spec`
returns its table with ``[thermal.parameters]`` applied and the ``[thermal] fixed_C`` nodes
turned into fixed-temperature boundaries; every name the scene uses (parameters, imposed nodes,
``[rig.map]`` targets) is checked against the network here, when the scene is read.
"""
from __future__ import annotations

import copy
from pathlib import Path

from thermobear.errors import InputError
from thermobear.files import data_dir, names_in, read_toml
from thermobear.thermal.network import ROLES

__all__ = ["network_path", "network_spec", "network_nodes", "heat_receiving_nodes"]

_KEEP_ON_IMPOSE = ("description", "measured_by", "source")


def network_path(name: str, scene_path: str | None = None) -> Path:
    """File of a bundled network name or of a path (absolute, relative to the scene file, else to
    the working directory); InputError naming ``thermal.network`` when there is none."""
    names = names_in(data_dir("networks"))
    if name in names:
        return (data_dir("networks") / f"{name}.toml").resolve()
    path = Path(name)
    if scene_path and not path.is_absolute():
        path = Path(scene_path).resolve().parent / path
    if not path.is_file():
        raise InputError("thermal.network", name, f"unknown network; known: {', '.join(names)} "
                         "or a path to a .toml file")
    return path.resolve()


def heat_receiving_nodes(nodes) -> set:
    """Nodes that receive the loss heat (contact, ball and mixture roles, :data:`ROLES`)."""
    return {next((c for c in cands if c in nodes), None) for cands in ROLES.values()} - {None}


def _impose(spec: dict, fixed: dict, name: str) -> None:
    """Turn the nodes of ``fixed`` (node → °C, measured) into fixed-temperature nodes, in place.

    This is how seed 004 (Darul et al. 2024, §4.5) uses its network: the inner- and outer-ring
    thermocouple readings are boundary conditions and the network gives the ball and mixture
    temperatures.  Nodes that receive the loss heat cannot be imposed — their heat would vanish
    into the boundary; impose the ring node next to them."""
    nodes = spec.get("nodes", {})
    sinks = heat_receiving_nodes(nodes)
    for node, T in fixed.items():
        if node not in nodes:
            raise InputError(f"thermal.fixed_C.{node}", T, f"no node '{node}' in network {name}; known: "
                             f"{', '.join(nodes)}")
        if node in sinks:
            raise InputError(f"thermal.fixed_C.{node}", T, "this node receives the loss heat and cannot be imposed; "
                             "impose a ring/housing node instead (e.g. inner_ring, outer_ring), or set "
                             "operation.T_C to prescribe the contact temperature")
        kept = {k: v for k, v in nodes[node].items() if k in _KEEP_ON_IMPOSE}
        kept["T_C"] = T if isinstance(T, str) else float(T)     # a number, or an expression of the context
        kept["source"] = "imposed by the scene (thermal.fixed_C)"
        nodes[node] = kept


def _override(spec: dict, parameters: dict, name: str) -> None:
    """Apply ``"<element or node>.<parameter>" = value`` overrides, in place."""
    elements = spec.get("elements", [])
    nodes = spec.get("nodes", {})
    for key, val in parameters.items():
        if "." not in key:
            continue                      # a context value the network reads as scene.<key>
        target, param = key.rsplit(".", 1)
        hits = [e for e in elements if e.get("name") == target]
        if target in nodes:
            hits.append(nodes[target])
        if not hits:
            known = [e.get("name") for e in elements] + list(nodes)
            raise InputError(f"thermal.parameters.{key}", val, f"no element or node '{target}' in network "
                             f"{name}; known: {', '.join(str(k) for k in known)}")
        for h in hits:
            if param not in h:
                raise InputError(f"thermal.parameters.{key}", val,
                                 f"'{target}' has no parameter '{param}'; it has: {', '.join(sorted(h))}")
            h[param] = val
            if isinstance(h.get("uncertainty"), dict):      # the scene's value replaces the estimate and its range
                h["uncertainty"] = {k: v for k, v in h["uncertainty"].items() if k != param}


def network_spec(network: str, scene_path: str | None = None, *, parameters: dict | None = None,
                 fixed_C: dict | None = None) -> dict:
    """A network's table with parameter overrides applied and measured temperatures imposed.

    Parameters
    ----------
    network : str       bundled network name or path (see :func:`network_path`)
    scene_path : str    the scene file, for relative paths
    parameters : dict   ``"<element or node>.<parameter>" = value`` (``[thermal.parameters]``)
    fixed_C : dict      node → imposed temperature [°C] (``[thermal] fixed_C``)

    Returns
    -------
    dict   a fresh copy (the caller may change it)

    >>> spec = network_spec("one_node", parameters={"bearing_to_ambient.G_W_K": 0.8})
    >>> spec["elements"][0]["G_W_K"]
    0.8
    """
    path = network_path(str(network), scene_path)
    spec = copy.deepcopy(read_toml(str(path)))
    _impose(spec, dict(fixed_C or {}), str(network))
    _override(spec, dict(parameters or {}), str(network))
    return spec


def network_nodes(network: str, scene_path: str | None = None) -> list:
    """Node names of a network (no overrides applied)."""
    return list(read_toml(str(network_path(str(network), scene_path))).get("nodes", {}))
