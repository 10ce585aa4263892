"""Heavy optional-path modules, loaded on their first use.

``thermobear run`` on one scene needs neither :mod:`scipy.stats` (uncertainty sampling, rank
sensitivities) nor :mod:`scipy.integrate` (transients, spin-downs); importing them costs about a
third of a second per process.  :func:`lazy_module` returns such a module at the top of the modules
that use it, as their other imports are, and executes it on its first attribute access, with the
standard library's :class:`importlib.util.LazyLoader` (the recipe of the :mod:`importlib`
documentation, "Implementing lazy imports"; the same mechanism as the Scientific Python
SPEC 1 ``lazy_loader.load``).
"""
from __future__ import annotations

import importlib.util
import sys
from types import ModuleType

__all__ = ["lazy_module"]


def lazy_module(name: str) -> ModuleType:
    """The module ``name``: the loaded one if it is loaded, else one executed on first attribute use.

    A missing module fails here, at the import of the module asking for it, as an import would.

    >>> lazy_module("json").dumps([1])
    '[1]'
    """
    if name in sys.modules:
        return sys.modules[name]
    spec = importlib.util.find_spec(name)
    if spec is None:
        raise ModuleNotFoundError(f"No module named {name!r}", name=name)
    loader = importlib.util.LazyLoader(spec.loader)
    spec.loader = loader
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    loader.exec_module(module)
    return module
