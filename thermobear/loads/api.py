r"""One entry point to the quasi-static load distribution: :func:`load_distribution` chooses the form.

* ``"static"`` — :func:`thermobear.loads.static.load_distribution_static`: low speed, equal inner and
  outer contact angles (Jones 1960; Harris 2001 ch. 7; seed 004 eqs 6–8; ISO/TS 16281 rigid rings);
* ``"high_speed"`` — :func:`thermobear.loads.highspeed.load_distribution_high_speed`: centrifugal force,
  gyroscopic moment and one cage (Jones 1960; Harris 2001 ch. 8), inner ring rotating;
* with ``film=...`` the lubricant film enters each contact law (:mod:`thermobear.loads.film` in the static
  form, ``film=`` of the high-speed form).
"""
from __future__ import annotations

from dataclasses import fields

import numpy as np

from thermobear.contact.geometry import BallBearing
from thermobear.contact.hertz import hertz
from thermobear.contact.kinematics import entrainment_speed
from thermobear.errors import InputError
from thermobear.loads.film import film_load_distribution
from thermobear.loads.highspeed import FilmInputs, load_distribution_high_speed
from thermobear.loads.rings import LoadDistribution
from thermobear.loads.static import load_distribution_static, needs_high_speed
from thermobear.validity import P_MAX_REFUSE_PA, check

__all__ = ["load_distribution", "FORMS", "high_speed_cases", "check_loads", "check_contacts", "groove_angle",
           "loads_text", "contact_bounds"]

FORMS = ("auto", "static", "high_speed")


def high_speed_cases(brg: BallBearing, Fa, Fr, n_rpm, rotating: str = "inner", threshold: float = 0.05):
    """Which load cases the ``"auto"`` form solves in the high-speed form (boolean, broadcast shape).

    High speed where :func:`thermobear.loads.needs_high_speed` says so — the ball centrifugal force above
    ``threshold`` of the typical ball load Q = max(F_a / (Z sin α0), 5 F_r / Z) (the axial share, or
    Stribeck's most loaded ball) — and the form applies: a radial or angular contact bearing with its
    inner ring rotating.  A thrust bearing's centrifugal force acts across its grooves (not modelled).

    >>> from thermobear.contact.geometry import bearing
    >>> high_speed_cases(bearing("7210"), 450.0, 325.0, [0.0, 1000.0, 3200.0]).tolist()
    [False, False, True]
    """
    Fa, Fr, n = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (Fa, Fr, n_rpm)))
    if brg.kind == "thrust" or rotating != "inner":
        return np.zeros(Fa.shape, bool)
    Qtyp = np.maximum(np.maximum(Fa / (brg.Z * max(np.sin(brg.alpha0), 1e-3)), Fr * 5.0 / brg.Z), 1e-9)
    return needs_high_speed(brg, n, Qtyp, threshold=threshold, rotating=rotating)[0] & (n > 0)


def load_distribution(brg: BallBearing, Fa=0.0, Fr=0.0, M=None, n_rpm=0.0, *, form: str = "auto", film=None,
                      stiffness: str = "nominal", control: str = "outer", tol=None, maxiter=None, start=None,
                      continuation: bool = True) -> LoadDistribution:
    r"""Quasi-static load distribution of a ball bearing with rigid rings, in the form the case needs.

    Parameters
    ----------
    brg : BallBearing
    Fa : array_like     axial load on the inner ring [N], ≥ 0
    Fr : array_like     radial load on the inner ring [N], ≥ 0, acting towards ψ = 0
    M : array_like      tilting moment [N m]; ``None`` holds the tilt at θ = 0
    n_rpm : array_like  inner-ring speed [rpm], ≥ 0 (outer ring fixed); broadcast with the loads
    form : str          ``"auto"`` (default), ``"static"`` or ``"high_speed"``.  ``"auto"`` takes the
                        high-speed form for the cases :func:`high_speed_cases` selects (F_c above 5 % of the
                        typical ball load, radial or angular contact bearing) and the static form for the
                        others (n_rpm = 0 is always static); a batch mixing both is solved form by form
                        and returned as one :class:`~thermobear.loads.LoadDistribution`.
    film : dict, optional
                        the lubricant film in each contact law: ``dict(eta=..., alpha_p=...)`` [Pa s, 1/Pa]
                        (scalars or one per load case).  The static form also takes the mean entrainment
                        speeds ``u_i``, ``u_o`` [m/s] (per ball or case); without them it uses
                        :func:`thermobear.contact.kinematics.entrainment_speed` at the nominal contact angle,
                        inner ring at n_rpm (then n_rpm > 0).  The high-speed form computes its own
                        (caged kinematics).  ``None``: dry Hertz contacts.
    stiffness : str     ``"nominal"`` or ``"per_ball"`` (K_n at each ball's contact angle)
    control : str       raceway control of the high-speed form (``"outer"``, ``"inner"``, ``"both"``)
    tol, maxiter        Newton tolerance and iterations (default: the form's)
    start : LoadDistribution or array_like, optional
                        static form: ring displacements to start from (a nearby solution)
    continuation : bool static form: solve a case that fails from the closed-form start again by
                        continuation in the load magnitude (default True)

    Returns
    -------
    LoadDistribution    (:class:`thermobear.loads.film.FilmLoadDistribution` for the static film law);
                        the per-ball details of the high-speed form are in
                        :func:`thermobear.loads.highspeed.load_distribution_high_speed_full`

    Raises
    ------
    InputError, NoEquilibrium, NoConvergence   as the form's function

    Examples
    --------
    Seed 004 7210 under Fa 450 N, Fr 325 N: static at rest, high speed at 3200 rpm (F_c/Q ≈ 0.13), where
    the outer contacts carry the centrifugal force.

    >>> from thermobear.contact.geometry import bearing
    >>> b = bearing("7210")
    >>> rest, run = load_distribution(b, 450.0, 325.0), load_distribution(b, 450.0, 325.0, n_rpm=3200.0)
    >>> bool(np.allclose(rest.Q_i, rest.Q_o)), bool(np.all(run.Q_o > run.Q_i))
    (True, True)
    """
    if form not in FORMS:
        raise InputError("form", form, f"must be one of {', '.join(FORMS)}")
    bounds = contact_bounds(brg)
    check_loads(brg, Fa, Fr, M, n_rpm, bounds=bounds)
    n = np.asarray(n_rpm, dtype=float)
    if isinstance(film, FilmInputs):
        film = {"eta": film.eta, "alpha_p": film.alpha_p}
    if film is not None and not hasattr(film, "keys"):
        raise InputError("film", film, "None or a dict with 'eta' [Pa s], 'alpha_p' [1/Pa] (static form: also "
                         "'u_i', 'u_o' [m/s])")
    opts = {k: v for k, v in (("tol", tol), ("maxiter", maxiter)) if v is not None}
    ld = _solve(brg, Fa, Fr, M, n, form, film, stiffness, control, opts, start, continuation)
    _check_answer(brg, ld, bounds[0])
    return ld


def _solve(brg, Fa, Fr, M, n, form, film, stiffness, control, opts, start, continuation):
    """The load distribution in the form asked for (``"auto"``: by :func:`high_speed_cases`)."""
    if form == "auto":
        hs = high_speed_cases(brg, Fa, Fr, n)
        if np.all(hs) and hs.size:
            form = "high_speed"
        elif not np.any(hs):
            form = "static"
        else:
            return _mixed(brg, Fa, Fr, M, n, hs, film, stiffness, control, opts, start, continuation)
    if form == "high_speed":
        hs_film = None
        if film is not None:
            extra = set(film.keys()) - {"eta", "alpha_p"}
            if extra:
                raise InputError("film", film, f"the high-speed form computes the entrainment speeds itself; drop "
                                 f"{', '.join(sorted(extra))}")
            hs_film = dict(film)
        return load_distribution_high_speed(brg, Fa, Fr, M, n, control=control, stiffness=stiffness,
                                            film=hs_film, **opts)
    if film is None:
        return load_distribution_static(brg, Fa, Fr, M, stiffness=stiffness, start=start,
                                        continuation=continuation, **opts)
    return _static_film(brg, Fa, Fr, M, n, film, stiffness, opts)


def _groove_bottom(brg: BallBearing) -> float:
    """Contact angle of the groove bottom [rad]: the radial plane, for a thrust bearing the axis."""
    return 0.5 * np.pi if brg.kind == "thrust" else 0.0


def groove_angle(brg: BallBearing, alpha, a, f):
    r"""Angle from the groove bottom to the far edge of the contact ellipse [rad].

    .. math:: \theta = |\alpha - \alpha_g| + \frac{a}{f D}

    α the contact angle, α_g that of the groove bottom (0; π/2 for a thrust bearing), a the semi-axis
    across the rolling direction [m] (along the groove), f D the groove radius [m]: the arc a on the
    groove seen from its curvature centre (Harris 2001 ch. 2 and 6).  Beyond π/2 the ellipse passes
    the groove's equator (:data:`thermobear.validity.LIMITS` ``contact_angle``).

    >>> from thermobear.contact.geometry import bearing
    >>> round(float(np.degrees(groove_angle(bearing("7210"), np.radians(40.0), 2e-3, 0.52))), 2)
    57.35
    """
    return np.abs(np.asarray(alpha, float) - _groove_bottom(brg)) + np.asarray(a, float) / (f * brg.D)


def check_contacts(brg: BallBearing, sides, field: str, *, warn: bool = False, given=None) -> list:
    """The limits of the contacts of an answer: maximum pressure and the contact ellipse inside its groove.

    ``sides``: ``"inner"`` / ``"outer"`` → mapping with the contacts' Q [N], alpha [rad], a, b [m] (a
    :class:`~thermobear.losses.ContactSet`'s ``sides``, a :class:`~thermobear.losses.LossResult`'s
    ``contacts``).  Raises InputError naming ``field`` (showing ``given``, e.g. the loads) beyond the refused
    limits (:data:`thermobear.validity.LIMITS` ``p_max``, ``contact_angle``); returns the warnings (``warn``).
    """
    out = []
    for side, f in (("inner", brg.fi), ("outer", brg.fo)):
        c = sides[side]
        Q, a, b = (np.asarray(c[k], float) for k in ("Q", "a", "b"))
        with np.errstate(divide="ignore", invalid="ignore"):
            p = np.where(Q > 0, 1.5 * Q / (np.pi * a * b), 0.0)
        out += check("p_max", p, field, what=f"{side} contacts", warn=warn, given=given)
        theta = np.where(Q > 0, groove_angle(brg, c["alpha"], a, f), 0.0)
        out += check("contact_angle", theta, field, what=f"{side} contacts", warn=warn, given=given)
    return out


#: Hamrock–Brewe (1983) against the exact Hertz ellipse over 1 <= Ry/Rx <= 1e10 (tests/test_hertz.py):
#: a_exact <= 1.0046 a_HB and p_exact >= 0.9976 p_HB; the bounds below keep a margin.
_A_OVER_HB, _P_UNDER_HB = 1.01, 0.99


def contact_bounds(brg: BallBearing) -> tuple:
    """(a, p_max) at Q = 1 N [m, Pa] bounding every contact of the bearing (a ∝ Q^(1/3), p_max ∝ Q^(1/3)): a and p_max fall as Rx grows
    at a given Ry, and Rx = D (1 ∓ γ)/2 with |γ| <= D/dm.  Bounds: a of the inner and outer contacts at
    the smallest Rx (above any contact's a), p_max of the inner contact at the largest Rx (below any inner
    contact's p_max), from the Hamrock–Brewe ellipse with its margins (:data:`_A_OVER_HB`, :data:`_P_UNDER_HB`)."""
    lo, hi = 0.5 * brg.D * (1.0 - brg.D / brg.dm), 0.5 * brg.D * (1.0 + brg.D / brg.dm)
    c = hertz(1.0, np.array([lo, lo, hi]), np.array([brg.Ry_i, brg.Ry_o, brg.Ry_i]), brg.E_prime,
              method="hamrock_brewe")
    return c.a[:2] * _A_OVER_HB, c.p_max[2] * _P_UNDER_HB


def check_loads(brg: BallBearing, Fa, Fr, M=None, n_rpm=0.0, *, names=("Fa", "Fr", "M", "n_rpm"), bounds=None):
    """Refuse, before any solve, loads and speeds no answer exists for.

    The inputs must broadcast together; the speed must be finite, >= 0 and inside the accepted n·d_m
    (:data:`thermobear.validity.LIMITS` ``n_dm``, ``speed``); each load 0 or at least the ``load`` limit;
    and the loads must not exceed what the balls can carry
    at the refused contact pressure: a ball carries at most its load Q along each of F_a, F_r and
    M/ℜ_i, so the largest ball load is at least max(F_a, F_r, |M|/ℜ_i)/Z, and at that load even the
    most favourable inner contact (the largest R_x) is beyond :data:`thermobear.validity.P_MAX_REFUSE_PA`.
    Signs and finiteness of the loads are the forms' own checks (:func:`thermobear.loads.rings.batch_loads`).
    ``names``: the inputs as the caller calls them; ``bounds``: the bearing's :func:`contact_bounds`, if known.

    >>> from thermobear.contact.geometry import bearing
    >>> check_loads(bearing("7210"), Fa=450.0, Fr=[325.0, 650.0])
    >>> try:
    ...     check_loads(bearing("7210"), Fa=1e5, Fr=1e6)
    ... except InputError as e:
    ...     print(e.field)
    Fr
    """
    arrays = [np.asarray(v, dtype=float) for v in (Fa, Fr, 0.0 if M is None else M, n_rpm)]
    try:
        np.broadcast_shapes(*(v.shape for v in arrays))
    except ValueError:
        raise InputError(", ".join(names), "shapes " + ", ".join(str(v.shape) for v in arrays),
                         "must broadcast together (numpy rules)") from None
    n = arrays[3]
    if n.size and not (n.min() >= 0 and n.max() < np.inf):                  # NaN fails both
        raise InputError(names[3], n_rpm, "inner-ring speed must be finite and >= 0 [rpm] (outer ring fixed)")
    with np.errstate(over="ignore"):              # beyond the float range: beyond the limit
        check("n_dm", n * brg.dm * 1e3, names[3], warn=False, given=n_rpm)
        loads = (arrays[0], arrays[1], np.abs(arrays[2]) / brg.R_inner_locus)
    check("speed", n[n > 0], names[3], warn=False)
    if not all(np.all(np.isfinite(v)) for v in arrays[:3]):
        return                                    # not numbers: the forms name them
    for name, v in zip(names, loads):
        check("load", v[(v > 0) & (v < np.inf)], name, warn=False)      # (overflowed M/ℜ_i: the pressure says)
    peaks = [float(np.max(v)) if v.size else 0.0 for v in loads]
    if not max(peaks) > 0:
        return                                    # nothing to carry
    k = int(np.argmax(peaks))
    p_least = (bounds or contact_bounds(brg))[1] * np.cbrt(peaks[k] / brg.Z)
    if p_least > P_MAX_REFUSE_PA:
        given = arrays[k] if k < 2 else M
        given = np.asarray(given).item() if np.size(given) == 1 else given
        check("p_max", p_least, names[k], what=f"at least: the load shared by all {brg.Z} balls of "
                                                f"{brg.name or 'the bearing'}", warn=False, given=given)


def _check_answer(brg: BallBearing, ld: LoadDistribution, a1) -> None:
    """The contact ellipses of a load distribution inside their grooves (:func:`check_contacts`): bounded first
    by the reference contacts (:func:`contact_bounds`, a ∝ Q^(1/3)); the exact ellipses only where a
    bound passes the groove's equator.  (Contact pressures: :func:`check_loads` before, the loss models on
    the exact contacts after.)  ``a1``: the bounds of a at 1 N, inner and outer [m]."""
    sides = {"inner": (ld.Q_i, ld.alpha_i, brg.Rx_i, brg.Ry_i, brg.fi, a1[0]),
             "outer": (ld.Q_o, ld.alpha_o, brg.Rx_o, brg.Ry_o, brg.fo, a1[1])}
    if all(np.all(groove_angle(brg, np.where(Q > 0, al, _groove_bottom(brg)), a * np.cbrt(Q), f) <= 0.5 * np.pi)
           for Q, al, _, _, f, a in sides.values()):
        return
    exact = {}
    for side, (Q, al, Rx, Ry, _, _) in sides.items():
        try:
            c = hertz(Q, Rx(al), Ry, brg.E_prime)
        except InputError as e:                   # a contact beyond Hertz's size limit: the loads' fault
            raise InputError("Fa, Fr, M", loads_text(ld.Fa, ld.Fr, ld.M), f"{side} contacts: {e.expected}") from None
        exact[side] = {"Q": Q, "alpha": al, "a": c.a, "b": c.b}
    check_contacts(brg, exact, "Fa, Fr, M", given=loads_text(ld.Fa, ld.Fr, ld.M))


def loads_text(Fa, Fr, M=None) -> str:
    """The loads as a user reads them in a message: ``"Fa 450 N, Fr 325 N"`` (ranges for arrays).

    >>> loads_text(450.0, [325.0, 650.0], 2.0)
    'Fa 450 N, Fr 325…650 N, M 2 N m'
    """
    def txt(v):
        v = np.asarray(v, dtype=float)
        return f"{float(v.min()):g}…{float(v.max()):g}" if v.size > 1 and v.min() != v.max() else f"{float(v.flat[0]):g}"
    return f"Fa {txt(Fa)} N, Fr {txt(Fr)} N" + ("" if M is None or not np.any(np.asarray(M)) else f", M {txt(M)} N m")


def _static_film(brg, Fa, Fr, M, n, film, stiffness, opts):
    """The static form with the film law; entrainment speeds from the film dict or from n_rpm."""
    keys = set(film.keys())
    if not {"eta", "alpha_p"} <= keys or not keys <= {"eta", "alpha_p", "u_i", "u_o"}:
        raise InputError("film", film, "a dict with 'eta' [Pa s], 'alpha_p' [1/Pa] and optionally 'u_i', 'u_o' [m/s]")
    if "u_i" in film or "u_o" in film:
        if not {"u_i", "u_o"} <= keys:
            raise InputError("film", film, "give both 'u_i' and 'u_o' [m/s], or neither (then from n_rpm)")
        u_i, u_o = film["u_i"], film["u_o"]
    else:
        if np.any(n <= 0):
            raise InputError("n_rpm", n, "must be > 0 for the film law without entrainment speeds 'u_i', 'u_o'")
        w = n * np.pi / 30.0
        u = np.asarray(entrainment_speed(w, 0.0 * w, brg.D, brg.dm, brg.alpha0), dtype=float)
        shape = np.broadcast_shapes(np.shape(Fa), np.shape(Fr), np.shape(M) if M is not None else (), n.shape)
        u_i = u_o = np.broadcast_to(u, shape)[..., None]
    return film_load_distribution(brg, Fa, Fr, M, u_i=u_i, u_o=u_o, eta=film["eta"], alpha_p=film["alpha_p"],
                                  stiffness=stiffness, **opts)


def _mixed(brg, Fa, Fr, M, n, hs, film, stiffness, control, opts, start, continuation):
    """A batch whose cases need different forms: each form on its cases, merged into one LoadDistribution."""
    shape = hs.shape
    Fa_b, Fr_b, n_b = (np.broadcast_to(np.asarray(v, dtype=float), shape).ravel() for v in (Fa, Fr, n))
    M_b = None if M is None else np.broadcast_to(np.asarray(M, dtype=float), shape).ravel()
    flat = hs.ravel()
    parts = []
    for form, sel in (("high_speed", flat), ("static", ~flat)):
        idx = np.flatnonzero(sel)
        f = None if film is None else {k: _rows(v, shape, brg.Z, idx) for k, v in film.items()}
        st = None if start is None or form == "high_speed" else _rows_of_start(start, shape, idx)
        ld = _solve(brg, Fa_b[idx], Fr_b[idx], None if M_b is None else M_b[idx], n_b[idx], form, f, stiffness,
                    control, opts, st, continuation)
        parts.append((idx, ld))
    nb, Z = flat.size, brg.Z
    out = {}
    for fld in fields(LoadDistribution):
        k = fld.name
        if k in ("psi", "residual", "iterations", "Fa", "Fr", "M"):
            continue
        v = np.empty((nb, Z) if np.ndim(getattr(parts[0][1], k)) == 2 else nb)
        for idx, ld in parts:
            v[idx] = getattr(ld, k)
        out[k] = v.reshape(shape + v.shape[1:])
    Mv = np.zeros(shape) if M is None else np.broadcast_to(np.asarray(M, dtype=float), shape).copy()
    return LoadDistribution(psi=parts[0][1].psi, residual=max(ld.residual for _, ld in parts),
                            iterations=max(ld.iterations for _, ld in parts), Fa=np.asarray(Fa, dtype=float),
                            Fr=np.asarray(Fr, dtype=float), M=Mv, **out)


def _rows(v, shape, Z, idx):
    """The cases ``idx`` of a film input given per case (batch shape) or per case and ball (+ (Z,))."""
    a = np.asarray(v, dtype=float)
    if a.ndim == 0:
        return a
    try:
        return np.broadcast_to(a, shape).ravel()[idx]
    except ValueError:
        return np.broadcast_to(a, shape + (Z,)).reshape(-1, Z)[idx]


def _rows_of_start(start, shape, idx):
    """The rows ``idx`` of a start given for the whole batch."""
    if isinstance(start, LoadDistribution):
        v = np.stack(np.broadcast_arrays(*(np.asarray(getattr(start, k), float)
                                           for k in ("delta_a", "delta_r", "theta"))), axis=-1)
    else:
        v = np.asarray(start, dtype=float)
    return np.broadcast_to(v, shape + (3,)).reshape(-1, 3)[idx]
