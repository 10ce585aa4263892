r"""Bearing losses: per contact → per ball → bearing totals (local model).

For each ball j and each contact (inner ``i``, outer ``o``) this module chains
load distribution → Hertz ellipse → kinematics → film and regime → losses:

* hydrodynamic rolling  P = 2 u F_R   (F_R by regime: Houpert IVR / Biboulet PVR /
  Houpert EHL, or a named model; seed 004 eqs 17–20, seed 000 eqs 20–23)
* sliding (Heathcote micro-slip across the major axis, pure rolling at the two
  points ξ0 = ±0.347 a that balance the traction of the Hertz strip load)
  P = ∫ μ q(x) |ω_roll (B(x0) − B(x))| dx, B(x) after seed 000 eqs 7–8
* pivoting (spin)  P = MP |ω_s|, MP = (3/8) μ Q a  (seed 000 eq 28 = the slice
  integral of μ q |ω_s x| for the Hertz strip load)
* hysteresis  P = MER |ω_roll|  (seed 000 eq 25)
* drag of the balls in the oil–air mixture (Pouly 2010, seed 004 eq 21)

with μ from the film parameter Λ (seed 000 eq 18) and the viscosity at the
contact temperature.  Sliding and pivoting are superposed (each with its own
slip field); the combined slip integral differs by a few percent of these
small terms.

Balls outside the load zone still touch the outer race under their centrifugal
force in the low-speed load model: the outer contact load is
Q_o = Q + F_c / cos α (F_c = ½ m dm ω_c², Harris 2001 eq 8.9) for contact angles
below 80°.  This is what makes lightly loaded balls dissipate in the IVR
regime (seed 004 §6.2).

Heat sources (for the thermal network): each contact's loss goes ½ to the
ball and ½ to the ring (Pouly 2010 convention; PHYSICS.md §8), drag to the
oil–air mixture.  The split conserves energy exactly (tested).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ._arrays import out as _as

from .errors import InputError
from .film import film_thickness, lubrication_regime
from .friction.drag import drag_loss, oil_volume_fraction_parker
from .friction.rolling import rolling_force
from .friction.sliding import deformed_radius, hysteresis_moment, mixed_friction_ianus
from .geometry import BallBearing
from .hertz import hertz
from .kinematics import ball_kinematics, caged_ball_kinematics, common_cage_speed
from .loads import LoadDistribution, load_distribution

__all__ = ["LossResult", "ContactSet", "bearing_losses", "prepare_contacts", "evaluate_losses",
           "BREAKDOWN_KEYS", "ROLLING_MODELS"]

BREAKDOWN_KEYS = ("sliding", "rolling", "pivoting", "hysteresis", "drag")
ROLLING_MODELS = ("auto", "auto_sharp", "biboulet_ivr", "biboulet_ehl", "biboulet_transition", "houpert_ivr",
                  "houpert_ehl", "biboulet_pvr")
_SWITCH_WIDTH = 0.05   # ln-ratio width of the smooth regime switch (±5 % around a boundary)
_XI0 = 0.3473   # root of ξ − ξ³/3 = 1/3: pure-rolling points of the Hertz strip load (Heathcote)
_GL_X, _GL_W = np.polynomial.legendre.leggauss(32)


@dataclass(frozen=True)
class LossResult:
    """Power loss of a bearing at one or many operating points.

    Attributes
    ----------
    P_W : float or ndarray              total power loss [W]
    torque_Nm : float or ndarray        friction torque on the rotating ring, P/ω [N m]
    breakdown_W : dict                  sliding, rolling, pivoting, hysteresis, drag [W]
    contacts : dict                     per contact arrays, keys ``"inner"``/``"outer"`` → dict of
                                        Q [N], alpha [rad], a, b [m], u [m/s], T_C, eta [Pa s],
                                        h_min, h_c [m], Lambda, regime (str), mu, F_R [N],
                                        P_rolling, P_sliding, P_pivoting, P_hysteresis [W], spin [rad/s]
    heat_W : dict                       heat sources: ``inner_ring``, ``outer_ring``, ``balls``, ``oil`` [W]
    load : LoadDistribution
    omega_c : cage speed [rad/s]
    models_used : dict                  model per sub-problem with the reason
    """

    P_W: np.ndarray
    torque_Nm: np.ndarray
    breakdown_W: dict
    contacts: dict
    heat_W: dict
    load: LoadDistribution
    omega_c: np.ndarray
    models_used: dict = field(default_factory=dict)


def _sigmoid(x):
    return 0.5 * (1.0 + np.tanh(0.5 * x))


def _rolling_auto_smooth(Q, Rx, Ry, u, eta, Ep, alpha_p, a, b, reg):
    r"""Regime-selected hydrodynamic rolling force, switched smoothly across the Moes boundaries [N].

    Seed 004 §4.3 picks Houpert IVR, Biboulet PVR or Houpert EHL by regime (IVE → Biboulet PVR,
    thermobear.friction.rolling.REGIME_MODEL).  The formulas do not meet at the boundaries (jumps of
    ×0.5–0.9, tests/test_rolling.py), and a force that jumps with temperature stalls implicit time
    integration.  Here each choice is weighted by logistic functions of the NVM dominance ratios,
    w = 1/(1 + r^(−1/0.05)): 1 % of the way from the boundary in ln r the selection is 60/40, 15 %
    away it is 95/5; away from boundaries the result equals the sharp selection (``"auto_sharp"``)."""
    F_ivr = np.asarray(rolling_force(Q, Rx, Ry, u, eta, Ep, model="houpert_ivr"))
    F_pvr = np.asarray(rolling_force(Q, Rx, Ry, u, eta, Ep, model="biboulet_pvr", a=a, b=b))
    F_ehl = np.asarray(rolling_force(Q, Rx, Ry, u, eta, Ep, model="houpert_ehl", alpha_p=alpha_p, a=a, b=b))
    w = _SWITCH_WIDTH
    with np.errstate(divide="ignore", over="ignore"):
        s_piezo = _sigmoid(-np.log(np.maximum(reg.iso_over_piezo, 1e-300)) / w)
        s_rigid_iso = _sigmoid(np.log(np.maximum(reg.RI_over_EI, 1e-300)) / w)
        s_rigid_piezo = _sigmoid(np.log(np.maximum(reg.EP_over_RP, 1e-300)) / w)
    iso = s_rigid_iso * F_ivr + (1.0 - s_rigid_iso) * F_pvr
    piezo = s_rigid_piezo * F_pvr + (1.0 - s_rigid_piezo) * F_ehl
    return (1.0 - s_piezo) * iso + s_piezo * piezo


def _heathcote_power(mu, Q, a, Ra, omega_roll):
    """Sliding power of Heathcote micro-slip: ∫ μ q(x) |ω_roll (B(x0) − B(x))| dx over (−a, a) [W].

    B(x0) − B(x) = √(Ra² − x²) − √(Ra² − x0²) with x0 = ξ0 a; the Hertz strip load
    q = (3Q/4a)(1 − ξ²) (seed 000 eq 32 with the Hertz profile).  Vectorised Gauss–Legendre
    on each side of the pure-rolling points is unnecessary: the integrand's kinks are
    mild and 32 nodes give < 1e-4 relative error."""
    a = np.asarray(a, float)
    xi = _GL_X.reshape((-1,) + (1,) * a.ndim)
    w = _GL_W.reshape(xi.shape)
    x = xi * a
    x0 = _XI0 * a
    dB = np.sqrt(np.maximum(Ra**2 - x**2, 0.0)) - np.sqrt(np.maximum(Ra**2 - x0**2, 0.0))
    integrand = w * 0.75 * (1.0 - xi**2) * np.abs(dB)
    return mu * Q * np.abs(omega_roll) * integrand.sum(axis=0)


@dataclass(frozen=True)
class ContactSet:
    """Temperature-independent part of the local model (rigid rings: the mechanics does not
    depend on temperature).  Built by :func:`prepare_contacts`, evaluated by :func:`evaluate_losses`.

    Attributes
    ----------
    brg : BallBearing
    batch : tuple                batch shape of the operating points
    n_rpm : ndarray              speed [rpm] (batch)
    omega : ndarray              rotating-ring speed [rad/s] (batch)
    load : LoadDistribution
    omega_c : ndarray            cage speed per ball [rad/s] (batch + (Z,))
    sides : dict                 "inner"/"outer" → dict of Q, alpha, Rx, Ry, a, b, u, spin,
                                 omega_roll, I_sl (Heathcote slip integral per unit μ [W]),
                                 I_piv (pivoting power per unit μ [W]), P_hysteresis [W]
    models_used : dict
    """

    brg: BallBearing
    batch: tuple
    n_rpm: np.ndarray
    omega: np.ndarray
    load: LoadDistribution
    omega_c: np.ndarray
    sides: dict
    models_used: dict


def prepare_contacts(brg: BallBearing, Fa=0.0, Fr=0.0, n_rpm=0.0, *, M=None, rotating: str = "inner",
                     hertz_method: str = "exact", control: str | None = None, centrifugal: bool = True,
                     load: LoadDistribution | None = None, batch_extra: tuple = ()) -> ContactSet:
    """Load distribution, Hertz ellipses, kinematics and every temperature-independent loss
    factor of each contact (see :func:`bearing_losses` for the parameters)."""
    if rotating not in ("inner", "outer"):
        raise InputError("rotating", rotating, "must be 'inner' or 'outer'")
    n = np.asarray(n_rpm, dtype=float)
    if np.any(~np.isfinite(n)) or np.any(n < 0):
        raise InputError("n_rpm", n_rpm, "speed must be finite and >= 0 [rpm]")
    Fa_a, Fr_a = np.asarray(Fa, float), np.asarray(Fr, float)
    batch = np.broadcast_shapes(Fa_a.shape, Fr_a.shape, n.shape, tuple(batch_extra))
    Z = brg.Z
    ld = load if load is not None else load_distribution(brg, Fa=np.broadcast_to(Fa_a, batch),
                                                          Fr=np.broadcast_to(Fr_a, batch), M=M)
    ex = (...,) + (None,)                         # batch → batch + (Z,)
    nb = np.broadcast_to(n, batch)
    omega = nb * np.pi / 30.0
    w_i = omega if rotating == "inner" else np.zeros_like(omega)
    w_o = omega if rotating == "outer" else np.zeros_like(omega)
    ai = np.broadcast_to(ld.alpha_i, batch + (Z,))
    ao = np.broadcast_to(ld.alpha_o, batch + (Z,))
    if control is None:
        control = "radial" if brg.kind == "thrust" else "outer"
    Qi = np.broadcast_to(ld.Q_i, batch + (Z,)).astype(float)
    Qo = np.broadcast_to(ld.Q_o, batch + (Z,)).astype(float)
    # one rigid cage: every ball orbits at the load-weighted mean of the balls' no-slip orbital
    # speeds (they differ when the contact angles do: combined and high-speed loads); a ball
    # outside the load zone follows the cage and rolls on the race that carries it
    free = ball_kinematics(w_i[ex], w_o[ex], ai, ao, brg.D, brg.dm, control=control)
    w_cage = common_cage_speed(np.broadcast_to(np.asarray(free.omega_c), batch + (Z,)), Qi)
    omega_c = np.broadcast_to(np.asarray(w_cage)[ex], batch + (Z,))
    if centrifugal and brg.kind != "thrust":
        Fc = 0.5 * brg.ball_mass * brg.dm * omega_c**2
        ca = np.cos(ao)
        Qo = Qo + np.where(ca > np.cos(np.deg2rad(80.0)), Fc / np.maximum(ca, 1e-3), 0.0)
    kin = caged_ball_kinematics(w_i[ex], w_o[ex], ai, ao, brg.D, brg.dm, omega_c, Qi, Qo, control=control)
    Ep = brg.E_prime
    sides = {}
    for side, Q, al, u, spin, f in (("inner", Qi, ai, kin.u_i, kin.spin_i, brg.fi),
                                    ("outer", Qo, ao, kin.u_o, kin.spin_o, brg.fo)):
        Rx = brg.Rx_i(al) if side == "inner" else brg.Rx_o(al)
        Ry = brg.Ry_i if side == "inner" else brg.Ry_o
        u = np.broadcast_to(np.asarray(u, float), batch + (Z,))
        c = hertz(Q, Rx, Ry, Ep, method=hertz_method)
        a, b = np.asarray(c.a), np.asarray(c.b)
        omega_roll = np.broadcast_to(np.asarray(kin.omega_R) * np.cos(al + np.asarray(kin.beta)), batch + (Z,))
        Ra = deformed_radius(brg.D, f)
        I_sl = np.where(Q > 0, _heathcote_power(1.0, Q, a, Ra, omega_roll), 0.0)
        I_piv = 0.375 * Q * a * np.abs(np.broadcast_to(np.asarray(spin, float), batch + (Z,)))
        MER = np.asarray(hysteresis_moment(Q, brg.D, np.maximum(Ry / Rx, 1.0)))
        sides[side] = dict(Q=Q, alpha=al, Rx=np.broadcast_to(Rx, batch + (Z,)), Ry=Ry, a=a, b=b, u=u,
                           spin=np.broadcast_to(np.asarray(spin, float), batch + (Z,)), omega_roll=omega_roll,
                           I_sl=I_sl, I_piv=I_piv, P_hysteresis=MER * np.abs(omega_roll))
    models = {
        "load_distribution": ("Jones–Harris low-speed, rigid rings" + (", tilt free" if M is not None else ""),
                              "quasi-static ball loads and angles (seed 004 eqs 6–8)"),
        "hertz": (hertz_method, "exact elliptic integrals" if hertz_method == "exact" else "approximation chosen"),
        "kinematics": (f"no-slip at contact centres, {control} control, one cage speed",
                       "thrust: symmetric radial ball axis (seed 000)" if control == "radial" else "Jones outer-race control"),
        "centrifugal": ("F_c/cos α on the outer contact" if centrifugal and brg.kind != "thrust" else "none",
                        "balls outside the load zone ride on the outer race"),
    }
    return ContactSet(brg=brg, batch=batch, n_rpm=nb, omega=omega, load=ld, omega_c=omega_c, sides=sides,
                      models_used=models)


def evaluate_losses(cs: ContactSet, oil, T_C=40.0, *, T_inner_C=None, T_outer_C=None, T_oil_C=None,
                    supply: str = "oil_jet", oil_flow_m3_s: float = 0.0, Rq_ball: float = 0.05e-6,
                    Rq_ring: float = 0.1e-6, mu_boundary: float = 0.11, mu_full_film: float = 0.05,
                    rolling_model: str = "auto", drag: bool = True) -> LossResult:
    """Temperature-dependent part of the local model on a prepared :class:`ContactSet`
    (see :func:`bearing_losses` for the parameters)."""
    if rolling_model not in ROLLING_MODELS:
        raise InputError("rolling_model", rolling_model, f"must be one of {', '.join(ROLLING_MODELS)}")
    if supply not in ("oil_jet", "grease", "oil_bath", "oil_air", "dry_film"):
        raise InputError("supply", supply, "must be oil_jet, grease, oil_bath, oil_air or dry_film")
    brg, batch, Z = cs.brg, cs.batch, cs.brg.Z
    shape = batch + (Z,)
    T_C_a = np.asarray(T_C, float)
    Ti = T_C_a if T_inner_C is None else np.asarray(T_inner_C, float)
    To = T_C_a if T_outer_C is None else np.asarray(T_outer_C, float)
    Toil = np.asarray(T_C if T_oil_C is None else T_oil_C, float)
    for nm, v in (("T_C", T_C_a), ("T_oil_C", Toil)):
        try:
            np.broadcast_to(v, batch)
        except ValueError:
            raise InputError(nm, v, f"must broadcast to the operating points {batch}") from None
    Ep = brg.E_prime
    out_c = {}
    totals = {k: 0.0 for k in BREAKDOWN_KEYS}
    per_contact_heat = {}
    regimes_seen = set()
    for side, T_side in (("inner", Ti), ("outer", To)):
        sd = cs.sides[side]
        Q, Rx, Ry, u, a, b = sd["Q"], sd["Rx"], sd["Ry"], sd["u"], sd["a"], sd["b"]
        if T_side.shape == shape:
            Ts = T_side                                         # one temperature per ball
        else:                                                   # one per operating point
            try:
                Ts = np.broadcast_to(np.broadcast_to(T_side, batch)[..., None], shape)
            except ValueError:
                name = "T_C" if (T_side is T_C_a) else f"T_{side}_C"
                raise InputError(name, T_side, f"must broadcast to the operating points {batch} "
                                 f"(or be per ball, {shape})") from None
        eta = np.asarray(oil.eta(Ts), float)
        alpha_p = np.asarray(oil.alpha_p_at(Ts), float)
        h_min = np.asarray(film_thickness(Q, Rx, Ry, u, eta, alpha_p, Ep, kind="min"))
        h_c = np.asarray(film_thickness(Q, Rx, Ry, u, eta, alpha_p, Ep, kind="central"))
        Lam = h_min / np.hypot(Rq_ball, Rq_ring) if (Rq_ball or Rq_ring) else np.full_like(h_min, np.inf)
        reg = lubrication_regime(Q, Rx, Ry, u, eta, alpha_p, Ep)
        code = np.asarray(reg.code)
        regimes_seen |= set(np.unique(code).tolist())
        mu = np.asarray(mixed_friction_ianus(np.where(np.isfinite(Lam), Lam, 1e6), mu_full_film, mu_boundary))
        if rolling_model == "auto":
            F_R = _rolling_auto_smooth(Q, Rx, Ry, u, eta, Ep, alpha_p, a, b, reg)
        elif rolling_model == "auto_sharp":
            F_R = np.asarray(rolling_force(Q, Rx, Ry, u, eta, Ep, model="auto", alpha_p=alpha_p, a=a, b=b,
                                           regime=code))
        else:
            F_R = np.asarray(rolling_force(Q, Rx, Ry, u, eta, Ep, model=rolling_model, alpha_p=alpha_p, a=a, b=b))
        F_R = np.where(Q > 0, F_R, 0.0)
        P_roll = 2.0 * u * F_R
        P_sl = mu * sd["I_sl"]
        P_piv = mu * sd["I_piv"]
        P_hys = sd["P_hysteresis"]
        out_c[side] = dict(Q=Q, alpha=sd["alpha"], a=a, b=b, u=u, T_C=Ts, eta=eta, h_min=h_min, h_c=h_c,
                           Lambda=Lam, regime=code, mu=mu, F_R=F_R, spin=sd["spin"], P_rolling=P_roll,
                           P_sliding=P_sl, P_pivoting=P_piv, P_hysteresis=P_hys, M=reg.M, L=reg.L)
        totals["rolling"] = totals["rolling"] + P_roll.sum(-1)
        totals["sliding"] = totals["sliding"] + P_sl.sum(-1)
        totals["pivoting"] = totals["pivoting"] + P_piv.sum(-1)
        totals["hysteresis"] = totals["hysteresis"] + P_hys.sum(-1)
        per_contact_heat[side] = (P_roll + P_sl + P_piv + P_hys).sum(-1)

    # drag of the balls in the oil–air mixture
    nb = cs.n_rpm
    # cage speed: the balls' pure-rolling orbital speeds differ when their contact angles do (high-speed
    # form); the cage runs at the speed the loaded balls impose — their load-weighted mean
    Qw = cs.sides["inner"]["Q"]
    Qs = Qw.sum(-1)
    wc_mean = np.where(Qs > 0, (Qw * cs.omega_c).sum(-1) / np.where(Qs > 0, Qs, 1.0), cs.omega_c.mean(-1))
    if drag and supply not in ("oil_bath", "dry_film") and np.any(nb > 0):
        if supply == "oil_jet":
            W_cm3_min = oil_flow_m3_s * 1e6 * 60.0
            X = np.zeros(batch)
            run = np.broadcast_to(nb > 0, batch)
            X[run] = oil_volume_fraction_parker(W_cm3_min, np.broadcast_to(nb, batch)[run], brg.dm * 1e3)
        elif supply == "oil_air":
            X = np.full(batch, 0.01)
        else:
            X = np.zeros(batch)
        Tm = np.broadcast_to(Toil, batch)
        dr = drag_loss(Z, brg.D, brg.dm, np.maximum(wc_mean, 1e-12), X, oil.rho(Tm), oil.eta(Tm), Tm + 273.15)
        P_drag = np.where(nb > 0, np.asarray(dr.P_W), 0.0)
    else:
        P_drag = np.zeros(batch)
    totals["drag"] = P_drag
    breakdown = {k: _as(np.broadcast_to(v, batch)) for k, v in totals.items()}
    P = sum(np.broadcast_to(v, batch) for v in totals.values())
    omega = cs.omega
    with np.errstate(divide="ignore", invalid="ignore"):
        torque = np.where(omega > 0, P / np.where(omega > 0, omega, 1.0), 0.0)
    heat = {"inner_ring": _as(0.5 * per_contact_heat["inner"]), "outer_ring": _as(0.5 * per_contact_heat["outer"]),
            "balls": _as(0.5 * (per_contact_heat["inner"] + per_contact_heat["outer"])), "oil": _as(P_drag)}
    models = dict(cs.models_used)
    models.update({
        "rolling": (rolling_model, "per-contact regime: " + ", ".join(sorted(regimes_seen))
                    if rolling_model == "auto" else "chosen explicitly"),
        "film": ("Hamrock–Dowson h_min, h_c; regime by NVM dominant terms", "seed 000 eq 15, seed 004 §3"),
        "friction": ("mixed μ(Λ) seed 000 eq 18", f"μ_e {mu_full_film}, μ_a {mu_boundary}"),
        "drag": ("Pouly 2010 sphere drag" if drag and supply not in ("oil_bath", "dry_film") else "none",
                 {"oil_jet": "Parker oil fraction", "oil_air": "oil fraction 1 %", "grease": "air only"}.get(
                     supply, "not modelled for this supply")),
    })
    return LossResult(P_W=_as(P), torque_Nm=_as(torque), breakdown_W=breakdown, contacts=out_c, heat_W=heat,
                      load=cs.load, omega_c=_as(wc_mean), models_used=models)


def bearing_losses(brg: BallBearing, oil, Fa=0.0, Fr=0.0, n_rpm=0.0, T_C=40.0, *, M=None,
                   T_inner_C=None, T_outer_C=None, T_oil_C=None, rotating: str = "inner",
                   supply: str = "oil_jet", oil_flow_m3_s: float = 0.0, Rq_ball: float = 0.05e-6,
                   Rq_ring: float = 0.1e-6, mu_boundary: float = 0.11, mu_full_film: float = 0.05,
                   rolling_model: str = "auto", hertz_method: str = "exact", control: str | None = None,
                   centrifugal: bool = True, drag: bool = True, load: LoadDistribution | None = None
                   ) -> LossResult:
    r"""Power loss of a ball bearing by the local contact model.

    Parameters
    ----------
    brg : BallBearing
    oil : Lubricant                 (grease: its base oil)
    Fa, Fr : array_like             axial / radial load [N]
    n_rpm : array_like              speed of the rotating ring [rpm]
    T_C : array_like                temperature of contacts and oil where the next three are not given [°C]
    M : float, optional             tilting moment [N m] (tilt free); None holds the tilt
    T_inner_C, T_outer_C : array_like, optional
                                    inner / outer contact temperature [°C] (e.g. the mean of ball and
                                    ring temperatures, seed 004 §4.5); broadcast against the balls
    T_oil_C : array_like, optional  oil–air mixture temperature for drag [°C]
    rotating : str                  ``"inner"`` or ``"outer"`` ring rotating
    supply : str                    ``"oil_jet"`` (drag with Parker's oil fraction), ``"oil_air"``,
                                    ``"grease"`` (drag in air), ``"oil_bath"`` or ``"dry_film"`` (no drag term)
    oil_flow_m3_s : float           oil flow through the bearing [m³/s] (oil jet)
    Rq_ball, Rq_ring : float        RMS roughness [m]
    mu_boundary, mu_full_film : float  μ_a and μ_e of seed 000 eq 18 [-]
    rolling_model : str             ``"auto"`` (by regime, seed 004, smooth across boundaries),
                                    ``"auto_sharp"`` (the paper's sharp selection) or one of ``ROLLING_MODELS``
    hertz_method : str              ``"exact"`` or an approximation (``thermobear.hertz.METHODS``)
    control : str                   ball spin control (``"outer"``, ``"inner"``, ``"radial"``);
                                    default ``"radial"`` for thrust bearings, ``"outer"`` otherwise
    centrifugal : bool              add F_c/cos α to the outer contact load
    drag : bool                     include the drag term
    load : LoadDistribution         reuse a load distribution (must match Fa, Fr, M)

    Returns
    -------
    LossResult

    Examples
    --------
    Seed 004 7210 at 4800 rpm, bearing at 50 °C (hydrodynamic rolling is the largest term):

    >>> from thermobear.geometry import bearing
    >>> from thermobear.lubricant import lubricant
    >>> r = bearing_losses(bearing("7210"), lubricant("seed004-mineral"), Fa=450.0, Fr=650.0,
    ...                    n_rpm=4800.0, T_C=50.0, oil_flow_m3_s=10e-3 / 3600)
    >>> max(r.breakdown_W, key=r.breakdown_W.get), bool(abs(r.torque_Nm * 4800 * np.pi / 30 / r.P_W - 1) < 1e-12)
    ('rolling', True)
    """
    T_extra = np.broadcast_shapes(np.shape(T_C), np.shape(T_oil_C) if T_oil_C is not None else ())
    cs = prepare_contacts(brg, Fa, Fr, n_rpm, M=M, rotating=rotating, hertz_method=hertz_method, control=control,
                          centrifugal=centrifugal, load=load, batch_extra=T_extra)
    return evaluate_losses(cs, oil, T_C, T_inner_C=T_inner_C, T_outer_C=T_outer_C, T_oil_C=T_oil_C, supply=supply,
                           oil_flow_m3_s=oil_flow_m3_s, Rq_ball=Rq_ball, Rq_ring=Rq_ring, mu_boundary=mu_boundary,
                           mu_full_film=mu_full_film, rolling_model=rolling_model, drag=drag)
