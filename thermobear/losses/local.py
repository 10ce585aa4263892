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

import warnings
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from thermobear.arrays import out as _as

from thermobear.errors import InputError
from thermobear.losses.drag import oil_volume_fraction_parker
from thermobear.losses.rolling import rolling_force
from thermobear.losses.sliding import deformed_radius, hysteresis_moment
from thermobear.contact.geometry import BallBearing
from thermobear.contact.hertz import hertz
from thermobear.contact.kinematics import _cage_spin, _check_control, caged_ball_kinematics, common_cage_speed
from thermobear.loads.static import LoadDistribution, load_distribution

__all__ = ["LossResult", "ContactSet", "bearing_losses", "prepare_contacts", "evaluate_losses",
           "BREAKDOWN_KEYS", "ROLLING_MODELS"]

BREAKDOWN_KEYS = ("sliding", "rolling", "pivoting", "hysteresis", "drag")
ROLLING_MODELS = ("auto", "auto_sharp", "biboulet_ivr", "biboulet_ehl", "biboulet_transition", "houpert_ivr",
                  "houpert_ehl", "biboulet_pvr")
_SWITCH_WIDTH = 0.05   # ln-ratio width of the smooth regime switch (±5 % around a boundary)
_XI0 = 0.3473   # root of ξ − ξ³/3 = 1/3: pure-rolling points of the Hertz strip load (Heathcote)
_GL_X, _GL_W = np.polynomial.legendre.leggauss(32)
_CLIFT_GAUVIN_RE_MAX = 2e5     # range of fluids.drag.drag_sphere_correlations["Clift_Gauvin"]


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
    thermobear.losses.rolling.REGIME_MODEL).  The formulas do not meet at the boundaries (jumps of
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


def _view(v, shape):
    """A read-only view of ``v`` broadcast to ``shape`` (``np.broadcast_to`` without its overhead when
    ``v`` has that shape already)."""
    a = np.asarray(v)
    if a.shape != shape:
        return np.broadcast_to(a, shape)
    a = a.view()
    a.flags.writeable = False
    return a


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
    ld = load if load is not None else load_distribution(brg, Fa=_view(Fa_a, batch),
                                                          Fr=_view(Fr_a, batch), M=M)
    ex = (...,) + (None,)                         # batch → batch + (Z,)
    nb = _view(n, batch)
    omega = nb * np.pi / 30.0
    w_i = omega if rotating == "inner" else np.zeros_like(omega)
    w_o = omega if rotating == "outer" else np.zeros_like(omega)
    ai = _view(ld.alpha_i, batch + (Z,))
    ao = _view(ld.alpha_o, batch + (Z,))
    if control is None:
        control = "radial" if brg.kind == "thrust" else "outer"
    Qi = _view(ld.Q_i, batch + (Z,)).astype(float)
    Qo = _view(ld.Q_o, batch + (Z,)).astype(float)
    # one rigid cage: every ball orbits at the load-weighted mean of the balls' no-slip orbital
    # speeds (they differ when the contact angles do: combined and high-speed loads); a ball
    # outside the load zone follows the cage and rolls on the race that carries it
    _check_control(control)
    # the balls' free orbital speeds: ball_kinematics(...).omega_c, without the rest of its output
    free_wc = _cage_spin(np.asarray(w_i[ex], float), np.asarray(w_o[ex], float), np.asarray(ai, float),
                         np.asarray(ao, float), brg.D, brg.dm, control)[0]
    w_cage = common_cage_speed(_view(free_wc, batch + (Z,)), Qi)
    omega_c = _view(np.asarray(w_cage)[ex], batch + (Z,))
    if centrifugal and brg.kind != "thrust":
        Fc = 0.5 * brg.ball_mass * brg.dm * omega_c**2
        ca = np.cos(ao)
        Qo = Qo + np.where(ca > np.cos(np.deg2rad(80.0)), Fc / np.maximum(ca, 1e-3), 0.0)
    kin = caged_ball_kinematics(w_i[ex], w_o[ex], ai, ao, brg.D, brg.dm, omega_c, Qi, Qo, control=control)
    Ep = brg.E_prime
    # both raceways at once, stacked on a leading axis (inner, outer): one vectorised Hertz ellipticity
    # iteration and one pass of each loss factor
    sh = batch + (Z,)
    col = (2,) + (1,) * (len(batch) + 1)                        # per-raceway constants against (2, *sh)
    Q2 = np.stack((Qi, Qo))
    al2 = np.stack((ai, ao))
    Rx2 = np.stack((_view(brg.Rx_i(ai), sh), _view(brg.Rx_o(ao), sh)))
    Ry2 = np.array((brg.Ry_i, brg.Ry_o)).reshape(col)
    c2 = hertz(Q2, Rx2, Ry2, Ep, method=hertz_method)
    a2, b2 = np.asarray(c2.a), np.asarray(c2.b)
    u2 = np.empty((2,) + sh)
    u2[0], u2[1] = kin.u_i, kin.u_o
    spin2 = np.empty((2,) + sh)
    spin2[0], spin2[1] = kin.spin_i, kin.spin_o
    omega_roll2 = np.empty((2,) + sh)
    omega_roll2[...] = np.asarray(kin.omega_R) * np.cos(al2 + np.asarray(kin.beta))
    Ra2 = np.array((deformed_radius(brg.D, brg.fi), deformed_radius(brg.D, brg.fo))).reshape(col)
    I_sl2 = np.where(Q2 > 0, _heathcote_power(1.0, Q2, a2, Ra2, omega_roll2), 0.0)
    I_piv2 = 0.375 * Q2 * a2 * np.abs(spin2)
    P_hys2 = np.asarray(hysteresis_moment(Q2, brg.D, np.maximum(Ry2 / Rx2, 1.0))) * np.abs(omega_roll2)
    for arr in (u2, spin2, omega_roll2):
        arr.flags.writeable = False
    sides = {side: dict(Q=Q2[k], alpha=al2[k], Rx=Rx2[k], Ry=(brg.Ry_i, brg.Ry_o)[k], a=a2[k], b=b2[k], u=u2[k],
                        spin=spin2[k], omega_roll=omega_roll2[k], I_sl=I_sl2[k], I_piv=I_piv2[k],
                        P_hysteresis=P_hys2[k])
             for k, side in enumerate(("inner", "outer"))}
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


# --------------------------------------------------------------------------- fused kernel
# evaluate_losses runs many times on one ContactSet (coupled Newton, transient right-hand side):
# everything that does not depend on temperature is computed once per ContactSet (``_kernel_pre``,
# inputs validated there as the public functions validate them), the rest in one pass over both
# raceways stacked on a leading axis (``_kernel``).  The formulas are those of the public functions
# named in the comments; tests/test_perf_equivalence.py pins the two paths together (≤ 1e-12).
_LN_TINY = float(np.log(1e-300))      # film._TINY: floor of the Moes groups and dominance ratios
_LN2 = float(np.log(2.0))
_REGIME_CODES = np.array(["IVR", "IVE", "PVR", "EHL"], dtype="<U3")


# The temperature enters a contact through ln U2 = ln η + ln(2u/(E'Rx)) and ln G = ln(α_p E') only, so
# every power law of the film, friction and rolling formulas is exp(k_U ln η + k_G ln G + c) with c a
# per-contact constant: the kernel evaluates them as one stacked exp (rows below) and the NVM
# dominance ratios as affine functions of ln U2 and ln G — fewer, larger numpy calls (the contact
# arrays are small: the calls' overhead, not the arithmetic, is the cost).
# Rows (exponents of η and G; the rows that depend on G first): h_min, h_min^0.28 (Λ^0.28 σ^0.28),
# F_ehl, h_c, F_ivr, c_pvr f_ivr, c_pvr f_ehl (Biboulet PVR, c_pvr = E' Rx 2a), r = 6.6/M_B,
# 4.72 M_B^-0.39 and M_B^0.165 (the c_Bib truncation, M_B = den U2^-3/4).
_ROW_KU = np.array([0.68, 0.28 * 0.68, 0.656, 0.67, 0.636, 2.0 / 3.0, 0.75, 0.75, 0.39 * 0.75, -0.165 * 0.75])
_ROW_KG = np.array([0.49, 0.28 * 0.49, 0.022, 0.53])
# NVM ratios (film._ln_asymptotes_from, ._ln_blend_ratios) with ln M = ln W − ¾ u, ln L = g + ¼ u
# (u = ln U2, g = ln G, both floored at ln 1e-300): rows d_ri = ln H_RI − ln H_EI, d_ep = ln H_EP − ln H_RP,
# −4 ln H_EI, 1.5 ln H_RI, −8 ln H_RP, −8 ln H_EP
_NVM_KU = np.array([1.4, 1.0 / 12.0, -0.4, 2.25, -4.0 / 3.0, -2.0])
_NVM_KG = np.array([0.0, 1.0 / 12.0, 0.0, 0.0, -16.0 / 3.0, -6.0])
_SIG_K = np.array([-0.5, 0.5, 0.5]) / _SWITCH_WIDTH          # logistic weights 0.5 (1 + tanh(x/2)), x = ±d/w


@lru_cache(maxsize=8)
def _row_consts(nd: int) -> tuple:
    """The row constants above shaped (rows, 1, …, 1) against arrays of ``nd`` dimensions."""
    sh = (-1,) + (1,) * nd
    return tuple(v.reshape(sh) for v in (_ROW_KU, _ROW_KG, _NVM_KU, _NVM_KG, _SIG_K))


def _kernel_pre(cs: ContactSet) -> dict:
    """Temperature-independent factors of :func:`_kernel` for both raceways, stacked (2, *batch, Z)
    (row constants (rows, 2, *batch, Z)); inputs checked once as :func:`thermobear.lubrication.film.film_thickness`
    and :func:`thermobear.losses.rolling.biboulet_parameters` check them.  Cached on ``cs``."""
    pre = cs.__dict__.get("_tb_kernel")
    if pre is not None:
        return pre
    from scipy.special import ellipe

    from thermobear.lubrication.film import _arr, _ln_asymptote_consts
    shape = cs.batch + (cs.brg.Z,)
    Ep = float(cs.brg.E_prime)
    sd = [cs.sides["inner"], cs.sides["outer"]]

    def st(key):                      # both raceways stacked, each broadcast to (*batch, Z)
        out = np.empty((2,) + shape)
        out[0], out[1] = sd[0][key], sd[1][key]
        return out

    Q, Rx, Ry, u, a, b = (st(k) for k in ("Q", "Rx", "Ry", "u", "a", "b"))
    # the checks of film_thickness (thermobear.lubrication.film._contact, geometry part; η and α_p are checked per call)
    _arr("Q", Q, nonneg=True)
    _arr("Rx", Rx, positive=True)
    _arr("Ry", Ry, positive=True)
    if np.any(Ry < Rx * (1.0 - 1e-12)):
        raise InputError("Ry/Rx", Ry / Rx, "must be >= 1 (Ry transverse, Rx rolling direction; "
                         "these formulas were fitted for Ry >= Rx)")
    _arr("u", u, nonneg=True)
    _arr("E_prime", Ep, positive=True)
    loaded = Q > 0
    W = Q / (Ep * Rx**2)
    with np.errstate(divide="ignore", invalid="ignore"):
        lnU2fac = np.log(2.0 * u / (Ep * Rx))                  # ln(2U/η); −inf at u = 0
        kappa = np.where(a > 0, b / np.where(a > 0, a, 1.0), 1.0)
    if np.any(kappa > 1.0 + 1e-12):
        raise InputError("b/a", kappa, "must be <= 1 (b along rolling is the short semi-axis; "
                         "formulas fitted for Ry >= Rx)")
    ratio = Ry / Rx
    k_hd = 1.0339 * ratio**0.636                               # Hamrock–Dowson ellipticity
    Wl = np.where(loaded, Q, 1.0) / (Ep * Rx**2)
    beta = (4.0 / np.pi) * ellipe(1.0 - kappa**2) / (1.0 + Rx / Ry)
    den = beta**0.25 * kappa * W                               # M_B U2^(3/4) (biboulet_parameters)
    lnW = np.log(np.clip(W, 1e-300, None))
    pvr_ok = (W > 0) & (lnU2fac > -np.inf)                     # Biboulet PVR defined (loaded, rolling)
    with np.errstate(divide="ignore", invalid="ignore"):
        # film_thickness (Hamrock–Dowson): h = C U^n G^m, C = c W^w (ellipticity factor) Rx, U = U2/2
        ln_hmin = np.where(loaded, np.log(3.63 * Wl**-0.073 * (1.0 - np.exp(-0.68 * k_hd)) * Rx) - 0.68 * _LN2
                           + 0.68 * lnU2fac, -np.inf)
        ln_hc = np.where(loaded, np.log(2.69 * Wl**-0.067 * (1.0 - 0.61 * np.exp(-0.73 * k_hd)) * Rx) - 0.67 * _LN2
                         + 0.67 * lnU2fac, -np.inf)
        # rolling_force_houpert_ivr: 0.835 λ^-0.358 W^0.364 E' Rx² × U2^0.636
        ln_ivr = np.log(0.835 * (Rx / Ry) ** -0.358 * W**0.364 * Ep * Rx**2) + 0.636 * lnU2fac
        # rolling_force_biboulet_pvr (c_Bib truncation): E' Rx 2a × (f_ivr r + f_ehl)/(1 + r) × C(M_B, κ),
        # f_ivr = 0.77 β^-1/3 κ^0.12 U2^2/3, f_ehl = 1.8 β^-1/4 U2^3/4, r = 6.6/M_B, M_B = den U2^-3/4
        ln_pvr = np.log(Ep * Rx * 2.0 * a)
        ln_f_ivr = ln_pvr + np.log(0.77 * beta ** (-1.0 / 3.0) * kappa**0.12) + (2.0 / 3.0) * lnU2fac
        ln_f_ehl = ln_pvr + np.log(1.8 * beta**-0.25) + 0.75 * lnU2fac
        ln_den = np.log(den)
        ln_r = np.where(pvr_ok, np.log(6.6) - ln_den + 0.75 * lnU2fac, -np.inf)
        ln_m1 = np.where(pvr_ok, np.log(4.72) - 0.39 * ln_den + 0.39 * 0.75 * lnU2fac, 0.0)
        ln_m2 = np.where(pvr_ok, 0.165 * ln_den - 0.165 * 0.75 * lnU2fac, 0.0)
        # rolling_force_houpert_ehl: 0.674 κ^-0.043 (2a/Rx) (κW)^0.133 E' Rx² × G^0.022 U2^0.656
        ln_ehl = np.log(0.674 * kappa**-0.043 * (2.0 * a / Rx) * (kappa * W) ** 0.133 * Ep * Rx**2) + 0.656 * lnU2fac
    c_RI, c_EI, c_RP, c_EP, ln_h00 = _ln_asymptote_consts(Rx / Ry)
    A_RI, A_EI, A_EP = c_RI - 2.0 * lnW, c_EI - (2.0 / 15.0) * lnW, c_EP - lnW / 12.0
    I_sl, I_piv, P_hys = st("I_sl"), st("I_piv"), st("P_hysteresis")
    pre = dict(
        u=u, loaded=loaded, lnU2fac=lnU2fac, lnW=lnW,
        rows=np.stack([ln_hmin, 0.28 * ln_hmin, ln_ehl, ln_hc, ln_ivr, ln_f_ivr, ln_f_ehl, ln_r, ln_m1, ln_m2]),
        nvm=np.stack([A_RI - A_EI, A_EP - c_RP, -4.0 * A_EI, 1.5 * A_RI, -8.0 * c_RP, -8.0 * A_EP]),
        nvm_h00=-4.0 * ln_h00, k_kappa=0.484 * np.log(kappa),
        # per unit μ, and hysteresis (temperature independent: prepare_contacts)
        I_sl=I_sl, I_piv=I_piv, I_sp=I_sl + I_piv, P_hys=P_hys, two_u=2.0 * u,
    )
    cs.__dict__["_tb_kernel"] = pre
    return pre


def _kernel(pre, eta, alpha_p, Ep, sigma, mu_e, mu_a, *, rolling=True, full=False, sums=False):
    """Temperature-dependent part of the local model on both raceways at once [SI].

    ``eta`` [Pa s], ``alpha_p`` [1/Pa] broadcast against the stacked contacts (2, *batch, Z) of
    ``pre`` (:func:`_kernel_pre`); ``sigma`` composite roughness [m] (0: smooth, Λ = ∞).  Returns a
    dict: mu, h_min [m], Lambda, P_rolling (``rolling``), P_sliding, P_pivoting [W] and, with ``full``, h_c
    [m], F_R [N], regime codes, Moes M, L; with ``sums`` only the contact power summed over the balls
    (2, *batch) [W] (rolling + sliding + pivoting + hysteresis).  Same formulas as film_thickness
    (Hamrock–Dowson), lubrication_regime (NVM dominance), mixed_friction_ianus (seed 000 eq 18) and the
    smooth regime-weighted rolling force of :func:`_rolling_auto_smooth` (seed 004 eqs 17–19), written
    in logarithms of U2 = 2ηu/(E'Rx) and G = α_p E' so that one exp gives each power."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        le = np.log(eta)
        lnG = np.log(alpha_p * Ep)
        lnU2 = le + pre["lnU2fac"]                                              # −inf at u = 0
        loaded = pre["loaded"]
        row_ku, row_kg, nvm_ku, nvm_kg, sig_k = _row_consts(le.ndim)
        arg = row_ku * le
        arg[:4] += row_kg * lnG
        E = np.exp(arg + pre["rows"])
        h_min = E[0]                                                            # film_thickness, kind="min"
        if sigma > 0:                                                           # mixed_friction_ianus
            mu = mu_a + (np.asarray(mu_e) - mu_a) * np.minimum(E[1] * (0.82 * sigma**-0.28), 1.0)
        else:                                                                   # smooth: Λ = ∞, φ = 1
            mu = np.broadcast_to(np.asarray(mu_e, float), h_min.shape)
        if not (rolling or full):
            Lam = h_min / sigma if sigma > 0 else np.full_like(h_min, np.inf)
            return dict(mu=mu, h_min=h_min, Lambda=Lam, P_sliding=mu * pre["I_sl"], P_pivoting=mu * pre["I_piv"])
        # regime (lubrication_regime): dominance ratios of the NVM blend
        u = np.maximum(lnU2, _LN_TINY)
        g = np.maximum(lnG, _LN_TINY)
        nvm = nvm_ku * u + (nvm_kg * g + pre["nvm"])
        ln_EIc15 = -0.375 * np.logaddexp(nvm[2], pre["nvm_h00"])               # 1.5 ln H_EI' (h00 cap)
        d_ip = ((2.0 / 3.0) * np.logaddexp(nvm[3], ln_EIc15)                  # ln iso − ln piezo
                + 0.125 * np.logaddexp(nvm[4], nvm[5]))
        # smooth selection (_rolling_auto_smooth): logistic weights of the ln ratios
        x = np.empty((3,) + d_ip.shape)
        x[0], x[1:] = d_ip, nvm[:2]
        np.minimum(np.maximum(x, _LN_TINY, out=x), 700.0, out=x)               # (np.clip)
        s_piezo, s_ri, s_rp = 0.5 + 0.5 * np.tanh(x * sig_k)
        if rolling:
            # the three rolling forces (rolling_force_houpert_ivr / _biboulet_pvr / _houpert_ehl)
            F_ivr, F_ehl, r = E[4], E[2], E[7]
            C = 0.85 / (1.0 + E[8] * np.exp(pre["k_kappa"] * E[9]))                 # c_Bib(M_B, κ)
            # (the row constants are −inf where a force is undefined or zero — unloaded, u = 0 —, so
            # these forces, and F_R, are exactly 0 there without masks)
            F_pvr = (E[5] * r + E[6]) / (1.0 + r) * C
            iso = F_pvr + s_ri * (F_ivr - F_pvr)
            piezo = F_ehl + s_rp * (F_pvr - F_ehl)
            F_R = iso + s_piezo * (piezo - iso)
            if sums:
                return (F_R * pre["two_u"] + mu * pre["I_sp"] + pre["P_hys"]).sum(-1)
        Lam = h_min / sigma if sigma > 0 else np.full_like(h_min, np.inf)
        out = dict(mu=mu, h_min=h_min, Lambda=Lam, P_sliding=mu * pre["I_sl"], P_pivoting=mu * pre["I_piv"])
        if rolling:
            out.update(F_R=F_R, P_rolling=pre["two_u"] * F_R)
        if full:
            out["h_c"] = E[3]
            idx = np.where(d_ip >= 0, np.where(nvm[0] >= 0, 0, 1), np.where(nvm[1] >= 0, 2, 3))
            out["regime"] = _REGIME_CODES[np.where(loaded, idx, 0)]
            lnM = pre["lnW"] - 0.75 * u
            out["M"] = np.where(loaded, np.exp(np.clip(lnM, -700.0, 700.0)), 0.0)
            out["L"] = np.exp(np.clip(g + 0.25 * u, -700.0, 700.0))
    return out


def _drag_pre(cs: ContactSet, supply: str, oil_flow_m3_s: float, dragged: bool) -> dict:
    """Temperature-independent part of the drag term: mean cage speed [rad/s] and, when the balls
    are dragged, Parker's oil fraction [-] and the pitch-line speed [m/s]; cached on ``cs``."""
    cache = cs.__dict__.setdefault("_tb_drag", {})
    key = (supply, float(oil_flow_m3_s), dragged)
    if key in cache:
        return cache[key]
    rep = cs.__dict__.get("_tb_repeat_of")
    if rep is not None:                  # a repeated operating point: its factors, repeated
        base, n = rep
        d = {k: (v[None].repeat(n, axis=0) if isinstance(v, np.ndarray) else v)
             for k, v in _drag_pre(base, supply, oil_flow_m3_s, dragged).items()}
        cache[key] = d
        return d
    brg, batch, nb = cs.brg, cs.batch, cs.n_rpm
    # cage speed: prepare_contacts already puts every ball at the one cage speed (common_cage_speed)
    wc_mean = np.asarray(cs.omega_c)[..., 0]
    d = dict(wc_mean=wc_mean)
    if dragged:
        if supply == "oil_jet":
            W_cm3_min = oil_flow_m3_s * 1e6 * 60.0
            X = np.zeros(batch)
            run = _bc(nb > 0, batch)
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                X[run] = oil_volume_fraction_parker(W_cm3_min, _bc(nb, batch)[run], brg.dm * 1e3)
            d["warn"] = [(str(w.message), w.category) for w in caught]
        elif supply == "oil_air":
            X = np.full(batch, 0.01)
        else:
            X = np.zeros(batch)
        wc = np.maximum(wc_mean, 1e-12)
        if np.any(~np.isfinite(wc) | (wc <= 0)):
            raise InputError("omega_c", wc, "must be finite and > 0")
        v = wc * brg.dm / 2.0
        # Re = ρ v D / μ, P = ρ C_d Z (π D²/4)/2 |v|³ (drag_loss)
        d.update(X=X, X1=1.0 - X, v=v, vD=v * brg.D, K=brg.Z * ((np.pi * brg.D ** 2 / 4.0) / 2.0) * np.abs(v) ** 3,
                 run=nb > 0)
    cache[key] = d
    return d


def _drag_kernel(cs, dp, oil, Tm, rho_oil, mu_oil):
    """Drag power of the balls [W] (:func:`thermobear.losses.drag.drag_loss` with the default
    Clift–Gauvin sphere drag, Pouly 2010, seed 004 eq 21) at mixture temperatures ``Tm`` [°C] with the
    oil's density and viscosity there."""
    from thermobear.lubrication.air import air_properties
    for w in dp.get("warn", ()):
        warnings.warn(w[0], w[1], stacklevel=3)
    Tm = np.asarray(Tm, float)
    if Tm.size <= 8:                  # a few states: the table's scalar path (same values, no spline call)
        air = {}
        for t in Tm.ravel().tolist():
            if t not in air:
                air[t] = air_properties(t + 273.15)
        rho_a = np.array([air[t]["rho"] for t in Tm.ravel().tolist()]).reshape(Tm.shape)
        mu_a = np.array([air[t]["mu"] for t in Tm.ravel().tolist()]).reshape(Tm.shape)
    else:
        air = air_properties(Tm + 273.15)
        rho_a, mu_a = air["rho"], air["mu"]
    X, X1 = dp["X"], dp["X1"]
    rho_mix = X * rho_oil + X1 * rho_a
    mu_mix = X * mu_oil + X1 * mu_a
    Re = rho_mix * dp["vD"] / mu_mix
    if Re.min() > 0.0 and Re.max() <= _CLIFT_GAUVIN_RE_MAX:
        # fluids.drag.Clift_Gauvin (Clift & Gauvin 1970), as drag_coefficient_sphere evaluates it
        c_d = 24. / Re * (1 + 0.152 * Re**0.677) + 0.417 / (1 + 5070 * Re**-0.94)
    else:                                   # outside its range (or invalid): its warning or error
        from thermobear.losses.drag import drag_coefficient_sphere
        c_d = np.asarray(drag_coefficient_sphere(Re), float)
    return np.where(dp["run"], rho_mix * c_d * dp["K"], 0.0)


def _repeat_contacts(cs: ContactSet, n: int) -> ContactSet:
    """``cs`` (one operating point, batch ()) repeated ``n`` times as a batch (n,): the contacts of
    :func:`prepare_contacts` with ``n_rpm = np.full(n, ...)`` and the same load, without recomputing
    them (repeated copies; the kernel and drag factors are those of ``cs``, repeated)."""
    if cs.batch != ():
        raise InputError("contacts", cs.batch, "must hold one operating point to be repeated")

    def rep(v):
        return np.asarray(v)[None].repeat(n, axis=0)

    sides = {side: {k: (v if k == "Ry" else rep(v)) for k, v in sd.items()} for side, sd in cs.sides.items()}
    out = ContactSet(brg=cs.brg, batch=(n,), n_rpm=rep(cs.n_rpm), omega=rep(cs.omega), load=cs.load,
                     omega_c=rep(cs.omega_c), sides=sides, models_used=cs.models_used)
    pre = _kernel_pre(cs)          # (…, Z) → (…, 1, Z): the batch axis before the balls
    out.__dict__["_tb_kernel"] = {k: v[..., None, :] for k, v in pre.items()}
    out.__dict__["_tb_repeat_of"] = (cs, n)
    return out


def _contact_powers(cs: ContactSet, oil, T_inner_C, T_outer_C, T_oil_C, *, supply: str = "oil_jet",
                    oil_flow_m3_s: float = 0.0, Rq_ball: float = 0.05e-6, Rq_ring: float = 0.1e-6,
                    mu_boundary: float = 0.11, mu_full_film: float = 0.05, drag: bool = True) -> np.ndarray:
    """Inner-contact, outer-contact and drag power [W], shape (3, *batch), of the ``"auto"`` rolling
    model at operating-point temperatures [°C] (each of shape ``cs.batch``): the sums
    :func:`evaluate_losses` reports, without the per-contact detail (the coupled solvers' inner loop)."""
    batch = cs.batch
    pre = _kernel_pre(cs)
    dragged = drag and supply not in ("oil_bath", "dry_film") and _running(cs)
    T = np.empty((3 if dragged else 2,) + batch)          # the temperatures broadcast to the batch
    T[0], T[1] = T_inner_C, T_outer_C
    if dragged:
        T[2] = T_oil_C
    eta_b, alpha_b, rho_b = _oil_props(oil, T)
    alpha_p = alpha_b[:2][..., None]
    eta = eta_b[:2][..., None]
    from thermobear.lubrication.film import _arr
    _arr("eta", eta, positive=True)
    _arr("alpha_p", alpha_p, positive=True, nonneg=True)
    sigma = float(np.hypot(Rq_ball, Rq_ring)) if (Rq_ball or Rq_ring) else 0.0
    Pc = _kernel(pre, eta, alpha_p, cs.brg.E_prime, sigma, mu_full_film, mu_boundary, sums=True)
    dp = _drag_pre(cs, supply, oil_flow_m3_s, dragged)
    out = np.empty((3,) + batch)
    out[:2] = Pc
    out[2] = _drag_kernel(cs, dp, oil, T[2], rho_b[2], eta_b[2]) if dragged else 0.0
    return out


def _oil_props(oil, T):
    """η [Pa s], α_p [1/Pa], ρ [kg/m³] of the lubricant at temperatures ``T`` [°C] (an array): one
    look-up for a :class:`~thermobear.lubrication.lubricant.Lubricant`, else its three public methods."""
    f = getattr(oil, "_eta_alpha_rho", None)
    if f is not None:
        return f(T)
    return (np.asarray(oil.eta(T), float), np.asarray(oil.alpha_p_at(T), float), np.asarray(oil.rho(T), float))


def _running(cs: ContactSet) -> bool:
    """Any operating point of ``cs`` turning (n > 0); cached on ``cs``."""
    run = cs.__dict__.get("_tb_running")
    if run is None:
        run = cs.__dict__["_tb_running"] = bool(np.any(cs.n_rpm > 0))
    return run


def _bc(v, shape):
    """``np.broadcast_to(v, shape)``, or ``v`` itself (as an array) when it has that shape already."""
    a = np.asarray(v)
    return a if a.shape == shape else np.broadcast_to(a, shape)


def _filled(v, shape):
    """A new array of ``shape`` filled with (broadcast) ``v``."""
    out = np.empty(shape)
    out[...] = v
    return out


def evaluate_losses(cs: ContactSet, oil, T_C=40.0, *, T_inner_C=None, T_outer_C=None, T_oil_C=None,
                    supply: str = "oil_jet", oil_flow_m3_s: float = 0.0, Rq_ball: float = 0.05e-6,
                    Rq_ring: float = 0.1e-6, mu_boundary: float = 0.11, mu_full_film: float = 0.05,
                    rolling_model: str = "auto", drag: bool = True) -> LossResult:
    """Temperature-dependent part of the local model on a prepared :class:`ContactSet`
    (see :func:`bearing_losses` for the parameters).

    The temperature-independent factors are computed (and the contact geometry checked) on the
    first call and kept on ``cs`` for the next ones — treat a ContactSet as immutable; the
    per-contact formulas run in one fused pass over both raceways (``_kernel``), the same
    formulas as the public film / regime / friction / rolling functions (tests pin them together)."""
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
            _bc(v, batch)
        except ValueError:
            raise InputError(nm, v, f"must broadcast to the operating points {batch}") from None
    Ep = brg.E_prime
    Ts = {}
    for side, T_side in (("inner", Ti), ("outer", To)):
        if T_side.shape == shape:
            Ts[side] = T_side                                   # one temperature per ball
        else:                                                   # one per operating point
            try:
                Ts[side] = _filled(_bc(T_side, batch)[..., None], shape)
            except ValueError:
                name = "T_C" if (T_side is T_C_a) else f"T_{side}_C"
                raise InputError(name, T_side, f"must broadcast to the operating points {batch} "
                                 f"(or be per ball, {shape})") from None
    pre = _kernel_pre(cs)
    dragged = drag and supply not in ("oil_bath", "dry_film") and _running(cs)
    # lubricant properties: one call per property for both raceways (and the mixture, for drag)
    per_ball = Ti.shape == shape or To.shape == shape
    if per_ball:
        eta = np.stack([np.asarray(oil.eta(Ts[k]), float) for k in ("inner", "outer")])
        alpha_p = np.stack([np.asarray(oil.alpha_p_at(Ts[k]), float) for k in ("inner", "outer")])
    else:
        Tb = [_bc(Ti, batch), _bc(To, batch)]
        if dragged:
            Tb.append(_bc(Toil, batch))
        eta_b, alpha_b, rho_b = _oil_props(oil, np.stack(Tb))
        alpha_p = alpha_b[:2][..., None]
        eta = eta_b[:2][..., None]
    from thermobear.lubrication.film import _arr
    _arr("eta", eta, positive=True)                      # the checks of film_thickness (temperature part)
    _arr("alpha_p", alpha_p, positive=True, nonneg=True)
    sigma = float(np.hypot(Rq_ball, Rq_ring)) if (Rq_ball or Rq_ring) else 0.0
    k = _kernel(pre, eta, alpha_p, Ep, sigma, mu_full_film, mu_boundary, rolling=rolling_model == "auto",
                full=True)
    code = k["regime"]
    if rolling_model == "auto":
        F_R = k["F_R"]
    else:
        F_R = []
        for i, side in enumerate(("inner", "outer")):
            sd = cs.sides[side]
            e_i, a_i = np.broadcast_to(eta[i], shape), np.broadcast_to(alpha_p[i], shape)
            if rolling_model == "auto_sharp":
                f = rolling_force(sd["Q"], sd["Rx"], sd["Ry"], sd["u"], e_i, Ep, model="auto", alpha_p=a_i,
                                  a=sd["a"], b=sd["b"], regime=code[i])
            else:
                f = rolling_force(sd["Q"], sd["Rx"], sd["Ry"], sd["u"], e_i, Ep, model=rolling_model,
                                  alpha_p=a_i, a=sd["a"], b=sd["b"])
            F_R.append(np.where(sd["Q"] > 0, np.asarray(f), 0.0))
        F_R = np.stack(F_R)
        k["P_rolling"] = 2.0 * pre["u"] * F_R
    regimes_seen = set(code.ravel().tolist())
    P_roll, P_sl, P_piv, P_hys = k["P_rolling"], k["P_sliding"], k["P_pivoting"], pre["P_hys"]
    heat_c = (P_roll + P_sl + P_piv + P_hys).sum(-1)
    out_c = {}
    for i, side in enumerate(("inner", "outer")):
        sd = cs.sides[side]
        out_c[side] = dict(Q=sd["Q"], alpha=sd["alpha"], a=sd["a"], b=sd["b"], u=sd["u"], T_C=Ts[side],
                           eta=_filled(eta[i], shape), h_min=k["h_min"][i], h_c=k["h_c"][i],
                           Lambda=k["Lambda"][i], regime=code[i], mu=k["mu"][i], F_R=F_R[i], spin=sd["spin"],
                           P_rolling=P_roll[i], P_sliding=P_sl[i], P_pivoting=P_piv[i], P_hysteresis=sd["P_hysteresis"],
                           M=k["M"][i], L=k["L"][i])
    per_contact_heat = {"inner": heat_c[0], "outer": heat_c[1]}
    totals = {"sliding": P_sl.sum(-1).sum(0), "rolling": P_roll.sum(-1).sum(0), "pivoting": P_piv.sum(-1).sum(0),
              "hysteresis": P_hys.sum(-1).sum(0)}

    # drag of the balls in the oil–air mixture
    dp = _drag_pre(cs, supply, oil_flow_m3_s, dragged)
    wc_mean = dp["wc_mean"]
    if dragged:
        Tm = _bc(Toil, batch)
        if per_ball:
            eta_m, rho_m = np.asarray(oil.eta(Tm), float), np.asarray(oil.rho(Tm), float)
        else:
            eta_m, rho_m = eta_b[2], rho_b[2]
        P_drag = _drag_kernel(cs, dp, oil, Tm, rho_m, eta_m)
    else:
        P_drag = np.zeros(batch)
    totals["drag"] = P_drag
    breakdown = {k: _as(_bc(v, batch)) for k, v in totals.items()}
    P = sum(_bc(v, batch) for v in totals.values())
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
    hertz_method : str              ``"exact"`` or an approximation (``thermobear.contact.hertz.METHODS``)
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

    >>> from thermobear.contact.geometry import bearing
    >>> from thermobear.lubrication.lubricant import lubricant
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
