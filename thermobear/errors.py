"""Named exceptions and warnings of thermobear.

Every bad input raises :class:`InputError` naming the field, the value and
what is accepted; every iterative solver that cannot deliver raises a
:class:`SolverError` subclass carrying its last iterate, residual and
iteration count.  Nothing returns NaN or a silently unconverged result.
"""
from __future__ import annotations

import numpy as np

__all__ = [
    "ThermobearError", "InputError", "ContactLimit", "SolverError", "NoEquilibrium",
    "NoConvergence", "ThermalRunaway", "ThermalPreloadRunaway", "NoSpeedRoot", "OutsideValidity",
    "ExtrapolationWarning", "UnreadInput",
]


class ThermobearError(Exception):
    """Base class of every error thermobear raises on purpose."""


class InputError(ThermobearError, ValueError):
    """A bad input value: names the field, the value and what is expected.

    >>> str(InputError("bearing.fi", 0.49, "osculation must be > 0.5 (groove radius / ball diameter)"))
    'bearing.fi = 0.49 — osculation must be > 0.5 (groove radius / ball diameter)'
    """

    def __init__(self, field: str, value=None, expected: str = ""):
        self.field, self.value, self.expected = field, value, expected
        if value is None:
            msg = f"{field} — {expected}" if expected else field
        else:
            msg = f"{field} = {_short(value)} — {expected}"
        super().__init__(msg)


class ContactLimit(InputError):
    """An operating point's loads that its contacts cannot carry: the maximum contact pressure beyond the
    refused limit, or a contact ellipse past its groove's equator (over the shoulder).  An InputError of
    the loads; a speed search meets it at a speed the bearing cannot run under those loads (e.g. the
    centrifugal force turning the inner contacts towards the groove's edge) and ends its range there."""


class SolverError(ThermobearError, RuntimeError):
    """An iterative solver could not deliver a converged answer.

    Attributes
    ----------
    reason : str          why it stopped
    iterations : int      iterations done
    residual : float      last residual (units in the message)
    last : object         last iterate (solver specific)
    history : list        convergence history where kept
    """

    def __init__(self, reason: str, *, iterations: int = 0, residual: float = float("nan"),
                 last=None, history=None):
        self.reason, self.iterations, self.residual = reason, iterations, residual
        self.last, self.history = last, history if history is not None else []
        super().__init__(reason)


class NoEquilibrium(SolverError):
    """No static equilibrium exists for the applied loads (e.g. radial load on a thrust bearing).

    ``field`` names the input that has no equilibrium (default: the scene's loads); the command line
    reports it as bad input (exit code 2).
    """

    def __init__(self, reason: str, *, field: str = "operation (Fa_N, Fr_N, M_Nm)", **kw):
        super().__init__(reason, **kw)
        self.field = field


class NoConvergence(SolverError):
    """The iteration did not converge within its budget, or diverged."""


class ThermalRunaway(SolverError):
    """Heat generation grows faster with temperature than dissipation: no thermal equilibrium."""


class ThermalPreloadRunaway(SolverError):
    """A preload that runs away: its heat warms the inner ring (and the balls) more than the outer ring, which
    adds more preload than it took, so the loop around the steady state (or the heat-up) finds no fixed point.
    Either a radial preload — the clearance the fits and ring temperatures leave is negative
    (:mod:`thermobear.coupled.clearance`: the loop's steps not shrinking at a negative clearance, or no steady
    state at the preload reached) — or the position preload of an angular contact pair
    (:mod:`thermobear.coupled.preload`: the pair's preload rising without shrinking steps, or no steady state at
    it).  A preload with a fixed point is solved, not refused.

    Attributes (besides :class:`SolverError`'s): ``clearance_history_m`` the clearances of the loop or the
    heat-up [m] (used → operating), ``dT_inner_outer_K`` the inner- minus outer-ring temperature difference
    at the last state [K], ``mounted_m`` the mounted clearance at 20 °C [m]; ``residual`` the last step's
    operating − used clearance [m] — or, of a pair, ``preload_history_N`` the pair's warm preloads of the loop's
    steps [N] (each bearing's axial load without external load) and ``residual`` the last step's change of the
    loaded bearing's axial load [N].
    """

    def __init__(self, reason: str, *, clearance_history_m=(), dT_inner_outer_K: float = float("nan"),
                 mounted_m: float = float("nan"), preload_history_N=(), **kw):
        super().__init__(reason, **kw)
        self.clearance_history_m = list(clearance_history_m)
        self.preload_history_N = list(preload_history_N)
        self.dT_inner_outer_K, self.mounted_m = dT_inner_outer_K, mounted_m


class NoSpeedRoot(SolverError):
    """A speed search found no speed that meets its condition in the speeds it may search: the
    message says which ("the limit is reached at no speed up to …", "exceeded already at …")."""


class OutsideValidity(UserWarning):
    """Computable, but outside where a model was validated (see :mod:`thermobear.validity`).

    Structured: ``quantity`` (what), ``value``, ``limit`` (the validated range, as text),
    ``source`` (where the range comes from) and ``field`` (the input it concerns).  Solvers collect
    these into their results (``warnings``); the command line prints one line each.

    >>> w = OutsideValidity("n dm = 1.2e+06 mm/min beyond 1e+06", quantity="n_dm", value=1.2e6)
    >>> str(w), w.quantity
    ('n dm = 1.2e+06 mm/min beyond 1e+06', 'n_dm')
    """

    def __init__(self, message: str = "", *, quantity: str = "", value=None, limit: str = "",
                 source: str = "", field: str = ""):
        super().__init__(message)
        self.message, self.quantity, self.value = message, quantity, value
        self.limit, self.source, self.field = limit, source, field

    def as_dict(self) -> dict:
        """The warning as plain data (JSON output)."""
        return {"category": type(self).__name__, "quantity": self.quantity, "field": self.field,
                "value": self.value, "limit": self.limit, "source": self.source, "message": self.message}


class ExtrapolationWarning(OutsideValidity):
    """An input lies beyond the data a correlation was fitted to (result still computed)."""


class UnreadInput(OutsideValidity):
    """A scene input set that the chosen models do not read: its value changes nothing
    (:func:`thermobear.model_inputs.unread_inputs`).  ``field`` names it, ``value`` is the value set and ``limit``
    says which models would read it."""


def _short(value) -> str:
    try:
        arr = np.asarray(value)
        if arr.ndim and arr.size > 4:
            return f"array(min={arr.min():.6g}, max={arr.max():.6g})"
    except Exception:  # noqa: BLE001 - any non-numeric value is printed as is
        pass
    return f"{value!r}" if isinstance(value, str) else f"{value}"
