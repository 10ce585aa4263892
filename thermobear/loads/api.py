r"""One entry point to the quasi-static load distribution: :func:`load_distribution` chooses the form.

* ``"static"`` — :func:`thermobear.loads.static.load_distribution_static`: low speed, equal inner and
  outer contact angles (Jones 1960; Harris 2001 ch. 7; seed 004 eqs 6–8; ISO/TS 16281 rigid rings);
* ``"high_speed"`` — :func:`thermobear.loads.highspeed.load_distribution_high_speed`: centrifugal force,
  gyroscopic moment and one cage (Jones 1960; Harris 2001 ch. 8), inner ring rotating;
* with ``film=...`` the lubricant film enters each contact law (:mod:`thermobear.loads.film` in the static
  form, ``film=`` of the high-speed form).

Every form solves the five ring unknowns (δa, δr, θ, δz, θ_y; axes and signs in :mod:`thermobear.loads.rings`)
and, for in-plane loads (F_z = M_y = 0), their first three (exact by symmetry).  A solution whose contacts
cannot carry the loads is refused (:func:`thermobear.loads.overload.refuse_overload`).
"""
from __future__ import annotations

from dataclasses import fields

import numpy as np

from thermobear.arrays import instance_of
from thermobear.contact.fits import clearance_preload
from thermobear.contact.geometry import BallBearing, bearing
from thermobear.contact.kinematics import entrainment_speed
from thermobear.errors import InputError
from thermobear.loads.film import film_load_distribution
from thermobear.loads.highspeed import FilmInputs, load_distribution_high_speed
from thermobear.loads.overload import (check_contacts, check_loads, contact_bounds, groove_angle,  # noqa: F401
                                       loads_text, refuse_overload as refuse_overload_of)
from thermobear.loads.rings import LoadDistribution
from thermobear.loads.static import load_distribution_static, needs_high_speed

__all__ = ["load_distribution", "FORMS", "high_speed_cases", "check_loads", "check_contacts", "groove_angle",
           "loads_text", "contact_bounds"]

FORMS = ("auto", "static", "high_speed")


def high_speed_cases(brg: BallBearing, Fa, Fr, n_rpm, rotating: str = "inner", threshold: float = 0.05, Fz=0.0):
    """Which load cases the ``"auto"`` form solves in the high-speed form (boolean, broadcast shape).

    High speed where :func:`thermobear.loads.needs_high_speed` says so — the ball centrifugal force above
    ``threshold`` of the typical ball load Q = max(F_a / (Z sin α0), 5 F_r / Z, Q_0) (the axial share,
    Stribeck's most loaded ball, or a radial preload's ball load Q_0 = K_n (−P_d/2)^1.5,
    :func:`~thermobear.contact.fits.clearance_preload`; F_r the radial load √(F_r² + F_z²)) — and the form
    applies: a radial or angular contact bearing with its inner ring rotating.  A thrust bearing's centrifugal force acts across its grooves (not modelled).

    >>> from thermobear.contact.geometry import bearing
    >>> high_speed_cases(bearing("7210"), 450.0, 325.0, [0.0, 1000.0, 3200.0]).tolist()
    [False, False, True]
    """
    Fa, Fr, n, Fz = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (Fa, Fr, n_rpm, Fz)))
    if brg.kind == "thrust" or rotating != "inner":
        return np.zeros(Fa.shape, bool)
    Fr = np.hypot(Fr, Fz)
    Qtyp = np.maximum(np.maximum(Fa / (brg.Z * max(np.sin(brg.alpha0), 1e-3)), Fr * 5.0 / brg.Z), 1e-9)
    if brg.Pd < 0:                          # a radial preload loads every ball by Q_0 at least
        Qtyp = np.maximum(Qtyp, float(clearance_preload(brg, brg.Pd)))
    return needs_high_speed(brg, n, Qtyp, threshold=threshold, rotating=rotating)[0] & (n > 0)


def load_distribution(brg: BallBearing, Fa=0.0, Fr=0.0, M=None, n_rpm=0.0, *, Fz=0.0, My=None, form: str = "auto",
                      film=None, stiffness: str = "nominal", control: str = "outer", tol=None, maxiter=None,
                      start=None, continuation: bool = True, tilt_arm: str = "groove",
                      refuse_overload: bool = True) -> LoadDistribution:
    r"""Quasi-static load distribution of a ball bearing with rigid rings (five degrees of freedom), in the
    form the case needs.

    Parameters
    ----------
    brg : BallBearing   or its catalogue name (:func:`~thermobear.contact.geometry.bearing`)
    Fa : array_like     axial load on the inner ring [N], ≥ 0 (along +x)
    Fr : array_like     radial load on the inner ring along y, towards ψ = 0 [N]
    M : array_like      moment in the x–y plane [N m]: it loads the balls at ψ = 0 towards +x (= −M_z);
                        ``M`` and ``My`` ``None`` hold both tilts at 0 (a shaft located by two bearings),
                        either given frees both (the other moment 0)
    n_rpm : array_like  inner-ring speed [rpm], ≥ 0 (outer ring fixed); broadcast with the loads
    Fz : array_like     radial load along z, towards ψ = 90° [N]
    My : array_like     moment about +y [N m] (right-handed: loads the balls at ψ = 90° towards +x)
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
    tilt_arm : str      the arm ℜ of the tilts and moments (:data:`thermobear.loads.rings.TILT_ARMS`):
                        ``"groove"`` (default, ℜ_i of the inner groove centres) or ``"pitch"`` (d_m/2, the
                        ISO/TS 16281 reference examples)
    refuse_overload : bool
                        refuse loads the contacts cannot carry (default True; ``False`` for callers that check
                        the contacts themselves, per operating point)

    Returns
    -------
    LoadDistribution    (:class:`thermobear.loads.film.FilmLoadDistribution` for the static film law);
                        the per-ball details of the high-speed form are in
                        :func:`thermobear.loads.highspeed.load_distribution_high_speed_full`; ``delta_z``,
                        ``theta_y`` the out-of-plane displacement and tilt (0 for in-plane loads)

    Raises
    ------
    InputError          bad input; loads the contacts cannot carry (field ``"Fa, Fr, M"``: p_max beyond twice
                        the ISO 76 rating or the contact ellipse past the groove edge,
                        :mod:`thermobear.loads.overload`)
    NoEquilibrium, NoConvergence   as the form's function

    Examples
    --------
    Seed 004 7210 under Fa 450 N, Fr 325 N: static at rest, high speed at 3200 rpm (F_c/Q ≈ 0.13), where
    the outer contacts carry the centrifugal force.

    >>> from thermobear.contact.geometry import bearing
    >>> b = bearing("7210")
    >>> rest, run = load_distribution(b, 450.0, 325.0), load_distribution(b, 450.0, 325.0, n_rpm=3200.0)
    >>> bool(np.allclose(rest.Q_i, rest.Q_o)), bool(np.all(run.Q_o > run.Q_i))
    (True, True)

    The same radial load and moment turned by 90° about the axis (along z, about y): δz and θ_y take the
    place of δr and θ, within the difference the 15 balls' positions make (the balls do not turn with it).

    >>> side = load_distribution(b, 450.0, 0.0, Fz=325.0, My=5.0)
    >>> inplane = load_distribution(b, 450.0, 325.0, M=5.0)
    >>> [round(v * 1e6, 1) for v in (side.delta_z, inplane.delta_r, side.delta_r)]
    [51.6, 51.5, 0.1]
    >>> [round(v * 1e3, 2) for v in (side.theta_y, inplane.theta)]
    [-1.69, -1.69]
    """
    brg = instance_of(brg, BallBearing, "brg", bearing)
    ld = _load_distribution(brg, Fa, Fr, M, n_rpm, Fz, My, form, film, stiffness, control, tol, maxiter, start,
                            continuation, tilt_arm)
    if refuse_overload:
        refuse_overload_of(brg, ld)
    return ld


def _load_distribution(brg, Fa, Fr, M, n_rpm, Fz, My, form, film, stiffness, control, tol, maxiter, start,
                       continuation, tilt_arm):
    """:func:`load_distribution` without the overload check."""
    if form not in FORMS:
        raise InputError("form", form, f"must be one of {', '.join(FORMS)}")
    check_loads(brg, Fa, Fr, M, n_rpm, Fz=Fz, My=My)
    n = np.asarray(n_rpm, dtype=float)
    if isinstance(film, FilmInputs):
        film = {"eta": film.eta, "alpha_p": film.alpha_p}
    if film is not None and not hasattr(film, "keys"):
        raise InputError("film", film, "None or a dict with 'eta' [Pa s], 'alpha_p' [1/Pa] (static form: also "
                         "'u_i', 'u_o' [m/s])")
    opts = {k: v for k, v in (("tol", tol), ("maxiter", maxiter)) if v is not None}
    opts.update(Fz=Fz, My=My, tilt_arm=tilt_arm)
    return _solve(brg, Fa, Fr, M, n, form, film, stiffness, control, opts, start, continuation)


def _solve(brg, Fa, Fr, M, n, form, film, stiffness, control, opts, start, continuation):
    """The load distribution in the form asked for (``"auto"``: by :func:`high_speed_cases`)."""
    if form == "auto":
        hs = high_speed_cases(brg, Fa, Fr, n, Fz=opts["Fz"])
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
        shape = np.broadcast_shapes(np.shape(Fa), np.shape(Fr), np.shape(M) if M is not None else (), n.shape,
                                    np.shape(opts["Fz"]), np.shape(opts["My"]) if opts["My"] is not None else ())
        u_i = u_o = np.broadcast_to(u, shape)[..., None]
    return film_load_distribution(brg, Fa, Fr, M, u_i=u_i, u_o=u_o, eta=film["eta"], alpha_p=film["alpha_p"],
                                  stiffness=stiffness, **opts)


def _mixed(brg, Fa, Fr, M, n, hs, film, stiffness, control, opts, start, continuation):
    """A batch whose cases need different forms: each form on its cases, merged into one LoadDistribution."""
    shape = hs.shape
    flat_of = (lambda v: None if v is None else np.broadcast_to(np.asarray(v, dtype=float), shape).ravel())  # noqa: E731
    Fa_b, Fr_b, n_b, M_b, Fz_b, My_b = (flat_of(v) for v in (Fa, Fr, n, M, opts["Fz"], opts["My"]))
    flat = hs.ravel()
    parts = []
    for form, sel in (("high_speed", flat), ("static", ~flat)):
        idx = np.flatnonzero(sel)
        f = None if film is None else {k: _rows(v, shape, brg.Z, idx) for k, v in film.items()}
        st = None if start is None or form == "high_speed" else _rows_of_start(start, shape, idx)
        o = dict(opts, Fz=Fz_b[idx], My=None if My_b is None else My_b[idx])
        ld = _solve(brg, Fa_b[idx], Fr_b[idx], None if M_b is None else M_b[idx], n_b[idx], form, f, stiffness,
                    control, o, st, continuation)
        parts.append((idx, ld))
    nb, Z = flat.size, brg.Z
    out = {}
    for fld in fields(LoadDistribution):
        k = fld.name
        if k in ("psi", "residual", "iterations", "Fa", "Fr"):
            continue
        v = np.empty((nb, Z) if np.ndim(getattr(parts[0][1], k)) == 2 else nb)
        for idx, ld in parts:
            v[idx] = getattr(ld, k)
        out[k] = v.reshape(shape + v.shape[1:])
    return LoadDistribution(psi=parts[0][1].psi, residual=max(ld.residual for _, ld in parts),
                            iterations=max(ld.iterations for _, ld in parts), Fa=np.asarray(Fa, dtype=float),
                            Fr=np.asarray(Fr, dtype=float), **out)


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
                                           for k in ("delta_a", "delta_r", "theta", "delta_z", "theta_y"))), axis=-1)
    else:
        v = np.asarray(start, dtype=float)
    n = v.shape[-1]
    return np.broadcast_to(v, shape + (n,)).reshape(-1, n)[idx]
