r"""Bearing losses: per contact → per ball → bearing totals (local model).

For each ball j and each contact (inner ``i``, outer ``o``) this module chains
load distribution → Hertz ellipse → kinematics → film and regime → losses, each
step by the public function of its module:

* hydrodynamic rolling  P = 2 u F_R (:func:`~thermobear.losses.rolling.rolling_force`: Houpert IVR /
  Biboulet PVR / Houpert EHL by regime, weighted smoothly across the boundaries, or a named model;
  seed 004 eqs 17–20, seed 000 eqs 20–23)
* sliding (Heathcote micro-slip across the major axis, pure rolling at the two points
  ξ0 = ±0.347 a that balance the traction of the Hertz strip load;
  :func:`~thermobear.losses.sliding.sliding_power_heathcote`, seed 000 eqs 7–8, 31–33)
* pivoting (spin)  P = MP |ω_s|, MP = (3/8) μ Q a  (seed 000 eq 28 = the slice
  integral of μ q |ω_s x| for the Hertz strip load)
* hysteresis  P = MER |ω_roll|  (seed 000 eq 25)
* drag of the balls in the oil–air mixture (Pouly et al. 2010, seed 004 eq 21)
* churning of the balls through an oil bath: the same drag in oil, weighted by the immersed share of
  the ball path at the oil level (:func:`~thermobear.losses.drag.churning_loss`)
* seal friction, SKF 2004 (:func:`~thermobear.losses.seals.seal_friction`, given as a torque)
* cage: Petroff land friction of a ring-guided cage and ball–pocket sliding
  (:func:`~thermobear.losses.cage.cage_loss`)

with μ from the film parameter Λ (seed 000 eq 18), the Hamrock–Dowson film (1977) and the
Nijenbanning–Venner–Moes regime (1994) at the viscosity of the contact temperature.  Sliding
and pivoting are superposed (each with its own slip field); the combined slip integral differs
by a few percent of these small terms.  Both are linear in μ: :func:`prepare_contacts` evaluates
them once at μ = 1, :func:`evaluate_losses` multiplies by μ(T).

Balls outside the load zone still touch the outer race under their centrifugal
force in the low-speed load model: the outer contact load is
Q_o = Q + F_c / cos α (F_c = ½ m dm ω_c², Harris 2001 eq 8.9) for contact angles
below 80°.  This is what makes lightly loaded balls dissipate in the IVR
regime (seed 004 §6.2).

Heat sources (for the thermal network): each contact's loss goes ½ to the
ball and ½ to the ring (the convention of Pouly et al. 2010), drag to the
oil–air mixture, churning to the bath, seal friction to the seal, cage losses to the cage.
The split conserves energy exactly (tested).

Shapes: a :class:`ContactSet` holds ``batch`` operating points (per-contact arrays
``(*batch, 2, Z)``, inner then outer raceway); temperatures broadcast to the batch, or carry extra
leading axes (e.g. ``(2, *batch)``: two temperature states per operating point), and every result
then carries those axes in front.
"""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from thermobear.arrays import checked, instance_of, within
from thermobear.contact.geometry import BallBearing, bearing
from thermobear.contact.hertz import hertz
from thermobear.contact.kinematics import caged_ball_kinematics, common_cage_speed, free_orbital_speed
from thermobear.errors import InputError
from thermobear.loads.api import check_contacts, check_loads, loads_text
from thermobear.loads.static import LoadDistribution, load_distribution
from thermobear.losses.cage import CageLand
from thermobear.losses.rolling import RollingContacts, rolling_contacts, rolling_power
from thermobear.losses.skf import K_RS, skf_K_z
from thermobear.losses.sliding import (XI0_HEATHCOTE, deformed_radius, hysteresis_moment, mixed_friction_ianus,
                                       pivoting_moment, sliding_power_heathcote)
from thermobear.losses.terms import (added_powers, drag_power, inlet_viscosity, property_at, replenishment,
                                     temperature_stack)
from thermobear.losses.traction import STRIP_NODES, StripContacts, check_film_viscosity, strip_contacts
from thermobear.lubrication.film import REGIMES, EHLContacts, ehl_contacts, specific_film_thickness
from thermobear.lubrication.lubricant import Lubricant, lubricant
from thermobear.validity import check as check_limit

__all__ = ["LossResult", "ContactSet", "ContactArrays", "bearing_losses", "prepare_contacts", "evaluate_losses",
           "BREAKDOWN_KEYS", "ROLLING_MODELS", "TRACTION_MODELS"]

_OIL = ("eta", "alpha_p_at", "rho")      # what evaluate_losses reads of a lubricant
BREAKDOWN_KEYS = ("sliding", "rolling", "pivoting", "hysteresis", "drag", "churning", "seal", "cage")
ROLLING_MODELS = ("auto", "auto_sharp", "biboulet_ivr", "biboulet_ehl", "biboulet_transition", "biboulet_dominant",
                  "houpert_ivr", "houpert_ehl", "biboulet_pvr")
#: full-film traction: a constant μ_e (seed 000 eq 18), or the oil's Eyring / limiting-shear-stress law
TRACTION_MODELS = ("constant", "eyring")
#: rolling_model of this module → model of :func:`~thermobear.losses.rolling.rolling_force`
_ROLLING_FORCE_MODEL = {"auto": "auto_smooth", "auto_sharp": "auto"}
SUPPLIES = ("oil_jet", "grease", "oil_bath", "oil_air", "dry_film")
_SIDES = ("inner", "outer")


@dataclass(frozen=True)
class LossResult:
    """Power loss of a bearing at one or many operating points.

    Attributes
    ----------
    P_W : float or ndarray              total power loss [W]
    torque_Nm : float or ndarray        friction torque on the rotating ring, P/ω [N m]
    breakdown_W : dict                  sliding, rolling, pivoting, hysteresis, drag, churning, seal, cage [W]
    contacts : ContactArrays            per contact arrays (a mapping), ``"inner"``/``"outer"`` → dict of
                                        Q [N], alpha [rad], a, b [m], u [m/s], T_C, eta [Pa s],
                                        h_min, h_c [m], Lambda, regime (str), mu, F_R [N] (with Φ_rs),
                                        phi_rs, phi_T [-] (the starvation factor Φ_rs and the thermal film
                                        reduction φ_T: 1 where the models leave them out),
                                        P_rolling, P_sliding, P_pivoting, P_hysteresis [W], spin [rad/s],
                                        M, L (Moes parameters) [-]
    heat_W : dict                       heat sources: ``inner_ring``, ``outer_ring``, ``balls``, ``oil``
                                        (drag), ``bath`` (churning), ``seal``, ``cage`` [W]
    load : LoadDistribution
    omega_c : cage speed [rad/s]
    models_used : dict                  model per sub-problem with the reason
    contact_W : dict                    ``"inner"``/``"outer"`` → power of all inner / outer contacts
                                        (rolling + sliding + pivoting + hysteresis, summed over the balls) [W]

    Every array has the shape of the operating points (with the temperatures' leading axes in
    front); per-contact arrays end with the ball axis (Z,).
    """

    P_W: np.ndarray
    torque_Nm: np.ndarray
    breakdown_W: dict
    contacts: Mapping
    heat_W: dict
    load: LoadDistribution
    omega_c: np.ndarray
    models_used: dict = field(default_factory=dict)
    contact_W: dict = field(default_factory=dict)


@dataclass(frozen=True)
class ContactSet:
    """Temperature-independent part of the local model (rigid rings: the mechanics does not
    depend on temperature).  Built by :func:`prepare_contacts`, evaluated by :func:`evaluate_losses`;
    its arrays are read-only.

    Attributes
    ----------
    brg : BallBearing
    n_rpm : ndarray               speed [rpm] (batch); ``batch`` is its shape
    batch : tuple                 shape of the operating points (property)
    omega : ndarray               rotating-ring speed [rad/s] (batch)
    inv_omega : ndarray           1/ω where the ring turns, else 0 [s/rad] (torque = power × inv_omega)
    load : LoadDistribution
    omega_c : ndarray             cage speed per ball [rad/s] (batch + (Z,)); all balls at the one cage speed
    omega_cage : ndarray          cage speed [rad/s] (batch)
    omega_ball : ndarray          ball spin speed about its own axis, relative to the cage, |ω_R| [rad/s]
                                  (batch + (Z,))
    models_used : dict
    Q, alpha : ndarray            contact load [N] and angle [rad], (*batch, 2, Z): inner, outer raceway
    Rx, Ry : ndarray              reduced radii, rolling / transverse direction [m] (broadcast to (*batch, 2, Z))
    a, b : ndarray                Hertz semi-axes across / along rolling [m]
    u : ndarray                   mean entrainment speed [m/s]
    spin : ndarray                spin (pivoting) speed [rad/s], signed
    omega_roll : ndarray          ball rolling speed about the contact's major axis [rad/s]
    P_sliding_mu : ndarray        Heathcote sliding power per unit friction coefficient [W]
    P_pivoting_mu : ndarray       pivoting power per unit friction coefficient [W]
    P_hysteresis : ndarray        hysteresis power [W]
    slips : ndarray               |slip speed| of Heathcote micro-slip and of pivoting at the strip nodes
                                  ξ_k of :data:`thermobear.losses.traction.STRIP_NODES` [m/s], (*batch, 2, Z, 2, k)
    p_strip : ndarray             mean pressure across the rolling direction there, (π/4) p_max √(1 − ξ_k²) [Pa],
                                  (*batch, 2, Z, 1, k)
    strip : StripContacts         the slips and pressures prepared for the traction formulas
                                  (:func:`thermobear.losses.traction.strip_contacts`)
    K_z : float or None           SKF bearing-type constant of the replenishment factor (None: bore/OD or kind unknown)
    ehl : EHLContacts             the contacts prepared for the film and regime formulas
                                  (:func:`thermobear.lubrication.film.ehl_contacts`)
    rolling : RollingContacts     the contacts prepared for the rolling-force formulas
                                  (:func:`thermobear.losses.rolling.rolling_contacts`)

    ``sides`` gives the per-raceway views (``cs.sides["inner"]["a"]``).
    """

    brg: BallBearing
    n_rpm: np.ndarray
    omega: np.ndarray
    inv_omega: np.ndarray
    load: LoadDistribution
    omega_c: np.ndarray
    omega_cage: np.ndarray
    omega_ball: np.ndarray
    models_used: dict
    Q: np.ndarray
    alpha: np.ndarray
    Rx: np.ndarray
    Ry: np.ndarray
    a: np.ndarray
    b: np.ndarray
    u: np.ndarray
    spin: np.ndarray
    omega_roll: np.ndarray
    P_sliding_mu: np.ndarray
    P_pivoting_mu: np.ndarray
    P_hysteresis: np.ndarray
    slips: np.ndarray
    p_strip: np.ndarray
    strip: StripContacts
    K_z: float | None
    ehl: EHLContacts
    rolling: RollingContacts

    @property
    def batch(self) -> tuple:
        """Shape of the operating points (that of ``n_rpm``)."""
        return self.n_rpm.shape

    @property
    def sides(self) -> dict:
        """``"inner"``/``"outer"`` → dict of that raceway's contact arrays (views, (*batch, Z))."""
        keys = ("Q", "alpha", "Rx", "Ry", "a", "b", "u", "spin", "omega_roll", "P_hysteresis")
        return {side: {k: getattr(self, k)[..., i, :] for k in keys} for i, side in enumerate(_SIDES)}


def _frozen(a):
    a = np.asarray(a, dtype=float)
    a.flags.writeable = False
    return a


def prepare_contacts(brg: BallBearing, Fa=0.0, Fr=0.0, n_rpm=0.0, *, M=None, rotating: str = "inner",
                     hertz_method: str = "exact", control: str | None = None, centrifugal: bool = True,
                     load: LoadDistribution | None = None) -> ContactSet:
    r"""Temperature-independent part of the local model: loads, Hertz ellipses, kinematics and the
    loss factors of every contact, held in a frozen :class:`ContactSet`.

    Parameters
    ----------
    brg : BallBearing
    Fa, Fr : array_like          axial / radial load [N]
    n_rpm : array_like           speed of the rotating ring [rpm]
    M : float, optional          tilting moment [N m] (tilt free); None holds the tilt
    rotating : str               ``"inner"`` or ``"outer"``
    hertz_method : str           ``"exact"`` or an approximation (``thermobear.contact.hertz.METHODS``)
    control : str, optional      ball spin control; default ``"radial"`` (thrust), ``"outer"`` otherwise
    centrifugal : bool           add F_c/cos α to the outer contact load (or one flag per operating point)
    load : LoadDistribution, optional
                                 a solved load distribution (must match Fa, Fr, M); with a leading
                                 batch axis B when solved for array loads

    Returns
    -------
    ContactSet   operating points ``batch`` = the broadcast of Fa, Fr, n_rpm and the load's batch
                 (e.g. ``n_rpm`` of shape (B,) with a batched load: one speed per point)

    Notes
    -----
    Per contact: Hertz (:func:`~thermobear.contact.hertz.hertz`), rolling without slip at the
    contact centres with one rigid cage (:func:`~thermobear.contact.kinematics.caged_ball_kinematics`),
    the outer load raised by the centrifugal force F_c = ½ m dm ω_c² / cos α (Harris 2001 eq 8.9),
    and the μ-free losses: Heathcote sliding and pivoting powers at μ = 1
    (:func:`~thermobear.losses.sliding.sliding_power_heathcote`,
    :func:`~thermobear.losses.sliding.pivoting_moment` × |ω_s|) and the hysteresis power
    :func:`~thermobear.losses.sliding.hysteresis_moment` × |ω_roll|; the contacts prepared for the film,
    regime (:func:`~thermobear.lubrication.film.ehl_contacts`) and rolling-force formulas
    (:func:`~thermobear.losses.rolling.rolling_contacts`).

    Examples
    --------
    >>> from thermobear.contact.geometry import bearing
    >>> cs = prepare_contacts(bearing("7210"), Fa=[300.0, 450.0], Fr=650.0, n_rpm=[3200.0, 4800.0])
    >>> cs.batch, cs.Q.shape
    ((2,), (2, 2, 15))
    """
    if rotating not in ("inner", "outer"):
        raise InputError("rotating", rotating, "must be 'inner' or 'outer'")
    n = np.asarray(n_rpm, dtype=float)
    if n.size and not (n.min() >= 0 and n.max() < np.inf):                  # NaN fails both
        raise InputError("n_rpm", n_rpm, "speed must be finite and >= 0 [rpm]")
    Fa_a, Fr_a = np.asarray(Fa, float), np.asarray(Fr, float)
    Z = brg.Z
    if load is None:
        shape = np.broadcast_shapes(Fa_a.shape, Fr_a.shape, np.shape(M) if M is not None else ())
        load = load_distribution(brg, Fa=np.broadcast_to(Fa_a, shape), Fr=np.broadcast_to(Fr_a, shape), M=M)
    batch = np.broadcast_shapes(Fa_a.shape, Fr_a.shape, n.shape, np.shape(load.Q_i)[:-1])
    sh = batch + (Z,)
    ex = (...,) + (None,)                         # batch → batch + (Z,)
    nb = np.broadcast_to(n, batch)
    omega = nb * np.pi / 30.0
    zero = np.zeros_like(omega)
    w_i, w_o = (omega, zero) if rotating == "inner" else (zero, omega)
    ai = np.broadcast_to(load.alpha_i, sh)
    ao = np.broadcast_to(load.alpha_o, sh)
    if control is None:
        control = "radial" if brg.kind == "thrust" else "outer"
    Qi = np.broadcast_to(load.Q_i, sh).astype(float)
    Qo = np.broadcast_to(load.Q_o, sh).astype(float)
    # one rigid cage: every ball orbits at the load-weighted mean of the balls' no-slip orbital
    # speeds (they differ when the contact angles do: combined and high-speed loads); a ball
    # outside the load zone follows the cage and rolls on the race that carries it
    free = free_orbital_speed(w_i[ex], w_o[ex], ai, ao, brg.D, brg.dm, control=control, check=False)
    w_cage = np.asarray(common_cage_speed(np.broadcast_to(free, sh), Qi), float)
    omega_c = np.broadcast_to(w_cage[ex], sh)
    cf = np.asarray(centrifugal, bool)
    if cf.any() and brg.kind != "thrust":
        Fc = 0.5 * brg.ball_mass * brg.dm * omega_c**2
        ca = np.cos(ao)
        Qo = Qo + np.where(cf[..., None] & (ca > np.cos(np.deg2rad(80.0))), Fc / np.maximum(ca, 1e-3), 0.0)
    kin = caged_ball_kinematics(w_i[ex], w_o[ex], ai, ao, brg.D, brg.dm, omega_c, Qi, Qo, control=control)
    # both raceways at once, stacked on an axis before the balls (inner, outer): (*batch, 2, Z)
    col = (2, 1)                                                # per-raceway constants against (*batch, 2, Z)
    Q2 = np.stack((Qi, Qo), axis=-2)
    al2 = np.stack((ai, ao), axis=-2)
    Rx2 = np.stack((np.broadcast_to(brg.Rx_i(ai), sh), np.broadcast_to(brg.Rx_o(ao), sh)), axis=-2)
    Ry2 = np.broadcast_to(np.array((brg.Ry_i, brg.Ry_o)).reshape(col), Q2.shape)
    c2 = hertz(Q2, Rx2, Ry2, brg.E_prime, method=hertz_method)
    a2, b2 = np.asarray(c2.a), np.asarray(c2.b)
    u2 = np.stack(np.broadcast_arrays(kin.u_i, kin.u_o), axis=-2)
    spin2 = np.stack(np.broadcast_arrays(kin.spin_i, kin.spin_o), axis=-2)
    omega_roll2 = np.asarray(kin.omega_R)[..., None, :] * np.cos(al2 + np.asarray(kin.beta)[..., None, :])
    Ra2 = np.array((deformed_radius(brg.D, brg.fi), deformed_radius(brg.D, brg.fo))).reshape(col)
    # sliding and pivoting are linear in μ: their powers at μ = 1
    P_sl = sliding_power_heathcote(1.0, Q2, a2, Ra2, omega_roll2)
    P_piv = np.asarray(pivoting_moment(1.0, Q2, a2)) * np.abs(spin2)
    P_hys = np.asarray(hysteresis_moment(Q2, brg.D, np.maximum(Ry2 / Rx2, 1.0))) * np.abs(omega_roll2)
    slips, p_strip = _strip_slips(Q2, a2, b2, Ra2, spin2, omega_roll2)
    try:
        K_z = skf_K_z(brg.kind) if brg.bore is not None and brg.outer_diameter is not None else None
    except InputError:
        K_z = None
    models = {
        "load_distribution": ("Jones–Harris low-speed, rigid rings" + (", tilt free" if M is not None else ""),
                              "quasi-static ball loads and angles (seed 004 eqs 6–8)"),
        "hertz": (hertz_method, "exact elliptic integrals" if hertz_method == "exact" else "approximation chosen"),
        "kinematics": (f"no-slip at contact centres, {control} control, one cage speed",
                       "thrust: symmetric radial ball axis (seed 000)" if control == "radial" else "Jones outer-race control"),
        "centrifugal": ("F_c/cos α on the outer contact" if cf.all() and brg.kind != "thrust" else
                        "F_c/cos α on the outer contact of some points" if cf.any() and brg.kind != "thrust" else "none",
                        "balls outside the load zone ride on the outer race"),
    }
    f = _frozen
    Q2, Rx2, Ry2, u2, a2, b2 = (f(v) for v in (Q2, Rx2, Ry2, u2, a2, b2))
    inv_omega = np.where(omega > 0, 1.0 / np.maximum(omega, np.finfo(float).tiny), 0.0)     # (subnormal ω: finite)
    return ContactSet(brg=brg, n_rpm=f(nb), omega=f(omega), inv_omega=f(inv_omega), load=load, omega_c=f(omega_c),
                      omega_cage=f(w_cage), omega_ball=f(np.abs(np.broadcast_to(kin.omega_R, omega_c.shape))),
                      models_used=models, Q=f(Q2), alpha=f(al2), Rx=f(Rx2), Ry=f(Ry2),
                      a=f(a2), b=f(b2), u=f(u2), spin=f(spin2), omega_roll=f(omega_roll2), P_sliding_mu=f(P_sl),
                      P_pivoting_mu=f(P_piv), P_hysteresis=f(P_hys), slips=f(slips), p_strip=f(p_strip), K_z=K_z,
                      strip=strip_contacts(slips, p_strip, check=False), ehl=ehl_contacts(Q2, Rx2, Ry2, u2, brg.E_prime),
                      rolling=rolling_contacts(Q2, Rx2, Ry2, u2, brg.E_prime, a2, b2))


def _strip_slips(Q, a, b, Ra, spin, omega_roll):
    """Slip speeds of Heathcote micro-slip (|ω_roll| |B(ξ0 a) − B(ξ a)|, seed 000 eq 7) and pivoting
    (|ω_s| a ξ) at the strip nodes ξ of :data:`~thermobear.losses.traction.STRIP_NODES`, stacked
    (*contacts, 2, nodes) [m/s], and the slice mean pressure (π/4) p_max √(1 − ξ²) of the Hertz contact
    there, (*contacts, 1, nodes) [Pa]."""
    xi = STRIP_NODES[0]
    a_ = a[..., None]
    x = xi * a_
    slip_spin = np.abs(spin)[..., None] * x
    Ra2 = np.broadcast_to(Ra, a.shape)[..., None] ** 2
    dB = np.sqrt(np.maximum(Ra2 - x * x, 0.0)) - np.sqrt(np.maximum(Ra2 - (XI0_HEATHCOTE * a_) ** 2, 0.0))
    slip_heath = np.abs(omega_roll)[..., None] * np.abs(dB)
    ab = a * b
    p_max = np.where(ab > 0, 1.5 * Q / (np.pi * np.where(ab > 0, ab, 1.0)), 0.0)
    p_strip = (0.25 * np.pi) * p_max[..., None] * np.sqrt(1.0 - xi**2)
    return np.stack((slip_heath, slip_spin), axis=-2), p_strip[..., None, :]


def evaluate_losses(cs: ContactSet, oil, T_C=40.0, *, T_inner_C=None, T_outer_C=None, T_oil_C=None,
                    supply: str = "oil_jet", oil_flow_m3_s=0.0, Rq_ball: float = 0.05e-6,
                    Rq_ring: float = 0.1e-6, mu_boundary: float = 0.11, mu_full_film: float = 0.05,
                    rolling_model: str = "auto", drag: bool = True, traction: str = "constant",
                    inlet_heating: bool = False, starvation: bool = False, oil_level_m=None, T_bath_C=None,
                    seal_torque_Nm=0.0, cage: CageLand | None = None, T_cage_C=None, K_rs=None) -> LossResult:
    r"""Temperature-dependent part of the local model on prepared contacts [W].

    Parameters
    ----------
    cs : ContactSet               from :func:`prepare_contacts` (operating points ``cs.batch``)
    oil : Lubricant               any object with ``eta``, ``alpha_p_at`` and ``rho`` methods of T [°C]; a
                                  lubricant with values per operating point (``Lubricant.per_point``, B =
                                  ``cs.batch``) gives each point its own properties
    T_C : array_like              temperature of contacts and oil where the next three are not given [°C]
    T_inner_C, T_outer_C : array_like, optional
                                  inner / outer contact temperatures [°C]: broadcast to ``cs.batch``,
                                  per ball (``cs.batch + (Z,)``), or with extra leading axes
    T_oil_C : array_like, optional  oil–air mixture temperature for drag [°C] (per operating point)
    supply, oil_flow_m3_s, Rq_ball, Rq_ring, mu_boundary, mu_full_film, rolling_model, drag
                                  as :func:`bearing_losses`; ``oil_flow_m3_s`` [m³/s] may have the shape
                                  of ``cs.batch``, the roughnesses and friction coefficients the shape
                                  ``cs.batch + (1, 1)`` (one value per operating point)
    traction : str                ``"constant"``: full-film μ = ``mu_full_film`` (seed 000 eq 18);
                                  ``"eyring"``: the film's Eyring / limiting-shear-stress traction on the slip
                                  of each contact (:func:`~thermobear.losses.traction.strip_traction_coefficient`,
                                  the oil's ``eyring_stress`` and ``limiting_shear``)
    inlet_heating : bool          thermal reduction of film and rolling force by inlet shear heating
                                  (Gupta et al. 1992, :mod:`thermobear.lubrication.thermal_film`)
    starvation, K_rs : bool, array_like   kinematic replenishment: the rolling force times SKF's Φ_rs
                                  (:func:`~thermobear.losses.skf.phi_rs`; needs the bearing's bore and OD) of constant
                                  K_rs [-] (one, or ``cs.batch + (1, 1)``; None: SKF's of the supply)
    oil_level_m : array_like, optional  oil-bath level above the lowest point of the outer-ring raceway
                                  [m] (``cs.batch``): churning of the balls through the bath; None: none
    T_bath_C : array_like, optional  bath temperature [°C] (default T_oil_C, else T_C)
    seal_torque_Nm : array_like   friction torque of the seals [N m] (``cs.batch``; SKF's model is
                                  temperature independent: :func:`~thermobear.losses.seals.seal_friction`)
    cage : CageLand, optional     a ring-guided cage (:class:`~thermobear.losses.cage.CageLand`): land
                                  friction and ball–pocket sliding; None: no cage loss
    T_cage_C : array_like, optional  temperature of the oil at the cage land [°C] (default T_oil_C, else T_C)

    Returns
    -------
    LossResult   every array has the temperatures' leading axes, then ``cs.batch``
                 (then (Z,) per contact)

    Notes
    -----
    Per contact, with η, α_p of the lubricant at the contact temperature: the Hamrock–Dowson films
    (:func:`~thermobear.lubrication.film.film_thickness`), the regime of the NVM blend
    (:func:`~thermobear.lubrication.film.lubrication_regime`), the rolling force of the chosen
    model (:func:`~thermobear.losses.rolling.rolling_force`; ``"auto"`` is the regime-weighted
    choice of seed 004 §4.3), Λ and μ (seed 000 eqs 18–19), and

    .. math::

        P = 2 u F_R + \mu\,(P_{sl}/\mu + P_{piv}/\mu) + P_{hys}

    with the μ = 1 sliding and pivoting powers and the hysteresis power of the ContactSet; the drag
    of the balls is :func:`~thermobear.losses.drag.drag_loss` (Pouly et al. 2010), their churning in
    a bath :func:`~thermobear.losses.drag.churning_loss`, the seal power the seal torque × ω, the cage
    loss :func:`~thermobear.losses.cage.cage_loss`.  Temperatures
    with leading axes (e.g. shape (2, *batch): two states per operating point, for finite
    differences) evaluate every state in one pass.

    Examples
    --------
    Two temperature states of one operating point (seed 004, 7210 at 4800 rpm):

    >>> from thermobear.contact.geometry import bearing
    >>> from thermobear.lubrication.lubricant import lubricant
    >>> cs = prepare_contacts(bearing("7210"), Fa=450.0, Fr=650.0, n_rpm=4800.0)
    >>> r = evaluate_losses(cs, lubricant("seed004-mineral"), [50.0, 60.0], oil_flow_m3_s=10e-3 / 3600)
    >>> r.P_W.shape, r.contacts["inner"]["P_rolling"].shape, bool(r.P_W[1] < r.P_W[0])
    ((2,), (2, 15), True)
    """
    _check_choices(rolling_model, supply, traction)
    dragged = drag and supply not in ("oil_bath", "dry_film") and bool(cs.omega_cage.any())
    Tall, lead, per_ball = temperature_stack(cs, T_C, T_inner_C, T_outer_C, T_oil_C, dragged)
    T2 = Tall[..., :2, :]                           # the raceways' contact temperatures
    pp = getattr(oil, "points", None) is not None   # values per operating point: against (…, B, 2|3, Z|1)
    oil_c = oil.aligned(2) if pp else oil
    eta_all = property_at(oil_c.eta, Tall, pp)      # contacts and (drag) the oil–air mixture in one call
    eta2, alpha2 = eta_all[..., :2, :], property_at(oil_c.alpha_p_at, T2, pp)
    eta_in, phi_T = inlet_viscosity(cs, oil_c, T2, eta2, pp) if inlet_heating else (eta2, 1.0)
    h_min, h_c = cs.ehl.film_thickness(eta_in, alpha2, kind=("min", "central"), check=False)  # η, α_p: the lubricant's
    reg = cs.ehl.regime(eta_in, alpha2, check=False)
    phi_rs = replenishment(cs, oil_c, T2, supply, pp, K_rs) if starvation else 1.0     # (1: shown as such per contact)
    F_R = cs.rolling.force(eta_in, _ROLLING_FORCE_MODEL.get(rolling_model, rolling_model), alpha2, reg,
                           check=False) * phi_rs
    if np.any(Rq_ball) or np.any(Rq_ring):
        Lam = specific_film_thickness(h_min, Rq_ball, Rq_ring)
    else:                                           # smooth surfaces: Λ = ∞, full-film friction
        Lam = np.full(h_min.shape, np.inf)
    if traction == "eyring":
        oil_s = oil.aligned(3) if pp else oil       # per point against (…, B, 2, Z, 2): per contact
        check_film_viscosity(eta2)
        mu_f = cs.strip.traction(h_c[..., None], eta2[..., None], alpha2[..., None], oil_s.eyring_stress,
                                 oil_s.limiting_shear)             # (..., 2, Z, 2): micro-slip, spin
        mus = mixed_friction_ianus(Lam[..., None], mu_f, np.asarray(mu_boundary, float)[..., None], check=False)
        mu, mu_piv = mus[..., 0], mus[..., 1]                           # Λ ≥ 0: films over roughnesses
    else:
        mu = mu_piv = mixed_friction_ianus(Lam, mu_full_film, mu_boundary, check=False)
    P = np.empty((4,) + h_min.shape)                # rolling, sliding, pivoting, hysteresis per contact
    P[0] = rolling_power(cs.u, F_R)
    np.multiply(mu, cs.P_sliding_mu, out=P[1])
    np.multiply(mu_piv, cs.P_pivoting_mu, out=P[2])
    P[3] = cs.P_hysteresis
    P_drag = (drag_power(cs, oil, Tall[..., 2, 0], eta_all[..., 2, 0], supply, oil_flow_m3_s) if dragged
              else np.zeros(lead + cs.batch))
    T_aux = T_C if T_oil_C is None else T_oil_C
    added = added_powers(cs, oil, lead, T_aux if T_bath_C is None else T_bath_C, T_aux if T_cage_C is None else T_cage_C,
                         oil_level_m, seal_torque_Nm, cage, pp)
    per_contact = dict(T_C=T2, eta=eta2, h_min=h_min, h_c=h_c, Lambda=Lam, regime=reg.code, mu=mu, F_R=F_R,
                       **{k: np.broadcast_to(v, h_min.shape) for k, v in (("mu_pivoting", mu_piv), ("phi_rs", phi_rs),
                                                                         ("phi_T", phi_T))},
                       P_rolling=P[0], P_sliding=P[1], P_pivoting=P[2], P_hysteresis=P[3], M=reg.M, L=reg.L)
    models = _reasons(cs.models_used, reg, oil, rolling_model, traction, mu_full_film, mu_boundary, inlet_heating,
                      starvation, supply, drag, oil_level_m, cage, K_rs)
    return _result(cs, P, P_drag, per_contact, models, added)


def _check_choices(rolling_model, supply, traction):
    """The named choices of :func:`evaluate_losses`, each among its accepted values."""
    if rolling_model not in ROLLING_MODELS:
        raise InputError("rolling_model", rolling_model, f"must be one of {', '.join(ROLLING_MODELS)}")
    if supply not in SUPPLIES:
        raise InputError("supply", supply, "must be " + ", ".join(SUPPLIES[:-1]) + " or " + SUPPLIES[-1])
    if traction not in TRACTION_MODELS:
        raise InputError("traction", traction, f"must be one of {', '.join(TRACTION_MODELS)}")


def _reasons(used, reg, oil, rolling_model, traction, mu_full_film, mu_boundary, inlet_heating, starvation, supply,
             drag, oil_level_m, cage, K_rs=None) -> dict:
    """The models an :func:`evaluate_losses` answer used, with their reasons (``used``: the contact set's)."""
    models = dict(used)
    seen = ", ".join(REGIMES[i] for i in np.flatnonzero(np.bincount(reg.index.ravel(), minlength=4)))
    models.update({
        "rolling": (rolling_model, "per-contact regime: " + seen if rolling_model == "auto" else "chosen explicitly"),
        "film": ("Hamrock–Dowson h_min, h_c; regime by NVM dominant terms", "seed 000 eq 15, seed 004 §3"),
        "friction": ("mixed μ(Λ) seed 000 eq 18", f"μ_e {_shown(mu_full_film)}, μ_a {_shown(mu_boundary)}"
                     if traction != "eyring" else
                     f"μ_e from the film's traction (Eyring τ0 {_shown(oil.eyring_stress, '.3g')} Pa, Λ_L "
                     f"{_shown(oil.limiting_shear)}; Johnson & Tevaarwerk 1977, Bair & Winer 1979), "
                     f"μ_a {_shown(mu_boundary)}"),
        "inlet_heating": ("Gupta et al. 1992 φ_T on the inlet viscosity" if inlet_heating else "isothermal inlet", ""),
        "starvation": (f"SKF Φ_rs (K_rs {_shown(K_RS.get(supply, 0) if K_rs is None else K_rs)}) on the rolling force"
                       if starvation
                       else "fully flooded", ""),
        "drag": ("Pouly 2010 sphere drag" if drag and supply not in ("oil_bath", "dry_film") else "none",
                 {"oil_jet": "Parker oil fraction", "oil_air": "Parker oil fraction of the oil–air feed", "grease": "air only"}.get(
                     supply, "not modelled for this supply")),
    })
    if oil_level_m is not None:
        models["churning"] = ("Pouly drag in oil × immersed share of the ball path", "oil level given")
    if cage is not None:
        models["cage"] = ("Petroff land + ball–pocket sliding", "ring-guided cage")
    return models


def _shown(v, fmt="g") -> str:
    """A model parameter as the reasons show it: its value, or "per point" (values per operating point)."""
    return format(float(v), fmt) if np.ndim(v) == 0 else "per point"


def _as(x):
    """A 0-d array as a Python float, any other array unchanged."""
    return x if x.ndim else float(x)


@dataclass(frozen=True, eq=False)
class ContactArrays(Mapping):
    """Per-contact arrays of a :class:`LossResult`, by raceway: ``["inner"]`` / ``["outer"]`` → mapping of
    arrays (*lead, *batch, Z).

    Holds the arrays of both raceways stacked, (*lead, *batch, 2, Z) (``arrays``); a raceway's arrays
    are views made on access, key by key, so a solver that reads only the sums (or one key) does not pay
    for the rest.  A dataclass: :func:`thermobear.arrays.take` picks operating points from it like from a dict."""

    arrays: dict

    def __getitem__(self, side: str) -> Mapping:
        if side not in _SIDES:
            raise KeyError(side)
        return _Raceway(self.arrays, _SIDES.index(side))

    def __iter__(self):
        return iter(_SIDES)

    def __len__(self) -> int:
        return len(_SIDES)


class _Raceway(Mapping):
    """One raceway's per-contact arrays of a :class:`ContactArrays` (views, made on access)."""

    __slots__ = ("arrays", "k")

    def __init__(self, arrays: dict, k: int):
        self.arrays, self.k = arrays, k

    def __getitem__(self, key):
        v = self.arrays[key]
        full = self.arrays["h_min"].shape           # T_C, eta: one per operating point, shown per contact
        return (v if v.shape == full else np.broadcast_to(v, full))[..., self.k, :]

    def __iter__(self):
        return iter(self.arrays)

    def __len__(self) -> int:
        return len(self.arrays)

    def __repr__(self):
        return repr(dict(self))


def _result(cs, P, P_drag, per_contact, models, added):
    """The LossResult of the per-contact powers ``P`` (4, *lead, *batch, 2, Z), the drag (*lead, *batch) and
    the churning, seal and cage powers ``added`` (each (*lead, *batch))."""
    S = P.sum(-1)                                   # (4, *lead, *batch, 2): summed over the balls
    fam = S.sum(-1)                                 # each family summed over both raceways
    per_side = S.sum(0)                             # contact power of each raceway
    P_in, P_out = per_side[..., 0], per_side[..., 1]
    per_contact.update(Q=cs.Q, alpha=cs.alpha, a=cs.a, b=cs.b, u=cs.u, spin=cs.spin)
    breakdown = {"sliding": _as(fam[1]), "rolling": _as(fam[0]), "pivoting": _as(fam[2]),
                 "hysteresis": _as(fam[3]), "drag": _as(P_drag), "churning": _as(added["churning"]),
                 "seal": _as(added["seal"]), "cage": _as(added["cage"])}
    total = fam[1] + fam[0] + fam[2] + fam[3] + P_drag + added["churning"] + added["seal"] + added["cage"]
    heat = {"inner_ring": _as(0.5 * P_in), "outer_ring": _as(0.5 * P_out), "balls": _as(0.5 * (P_in + P_out)),
            "oil": _as(P_drag), "bath": _as(added["churning"]), "seal": _as(added["seal"]), "cage": _as(added["cage"])}
    return LossResult(P_W=_as(total), torque_Nm=_as(total * cs.inv_omega), breakdown_W=breakdown,
                      contacts=ContactArrays(per_contact), heat_W=heat, load=cs.load,
                      omega_c=_as(cs.omega_cage), models_used=models, contact_W={"inner": _as(P_in), "outer": _as(P_out)})


def bearing_losses(brg: BallBearing, oil, Fa=0.0, Fr=0.0, n_rpm=0.0, T_C=40.0, *, M=None,
                   T_inner_C=None, T_outer_C=None, T_oil_C=None, rotating: str = "inner",
                   supply: str = "oil_jet", oil_flow_m3_s=0.0, Rq_ball: float = 0.05e-6,
                   Rq_ring: float = 0.1e-6, mu_boundary: float = 0.11, mu_full_film: float = 0.05,
                   rolling_model: str = "auto", hertz_method: str = "exact", control: str | None = None,
                   centrifugal: bool = True, drag: bool = True, load: LoadDistribution | None = None,
                   traction: str = "constant", inlet_heating: bool = False, starvation: bool = False,
                   oil_level_m=None, seal_torque_Nm=0.0, cage: CageLand | None = None, K_rs=None) -> LossResult:
    r"""Power loss of a ball bearing by the local contact model.

    Parameters
    ----------
    brg : BallBearing               or its catalogue name (:func:`~thermobear.contact.geometry.bearing`)
    oil : Lubricant                 (grease: its base oil), or its catalogue name
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
    oil_flow_m3_s : array_like      oil flow through the bearing [m³/s] (oil jet)
    Rq_ball, Rq_ring : array_like   RMS roughness [m]
    mu_boundary, mu_full_film : array_like  μ_a and μ_e of seed 000 eq 18 [-]
                                    (these, the flow, the oil level and the seal torque: one value, or one per
                                    operating point, broadcast with the loads, speeds and temperatures)
    rolling_model : str             ``"auto"`` (by regime, seed 004, smooth across boundaries),
                                    ``"auto_sharp"`` (the paper's sharp selection) or one of ``ROLLING_MODELS``
    hertz_method : str              ``"exact"`` or an approximation (``thermobear.contact.hertz.METHODS``)
    control : str                   ball spin control (``"outer"``, ``"inner"``, ``"radial"``);
                                    default ``"radial"`` for thrust bearings, ``"outer"`` otherwise
    centrifugal : bool              add F_c/cos α to the outer contact load
    drag : bool                     include the drag term
    load : LoadDistribution         reuse a load distribution (must match Fa, Fr, M)
    traction, inlet_heating, starvation
                                    full-film traction law, inlet shear heating, kinematic replenishment
                                    (see :func:`evaluate_losses`)
    K_rs : array_like, optional     replenishment constant of the starvation factor [-] (one, or one per
                                    operating point); None: SKF's of the supply
    oil_level_m, seal_torque_Nm, cage  churning, seal and cage terms, as :func:`evaluate_losses`

    Returns
    -------
    LossResult   arrays over the operating points: the broadcast of Fa, Fr, n_rpm, T_C and T_oil_C

    Notes
    -----
    :func:`prepare_contacts` (loads, Hertz, kinematics: temperature independent) followed by
    :func:`evaluate_losses` (film, regime, friction, rolling, drag at the temperatures).

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
    brg, oil = instance_of(brg, BallBearing, "brg", bearing), instance_of(oil, Lubricant, "oil", lubricant, needs=_OIL)
    shapes = [np.shape(v) for v in (Fa, Fr, n_rpm, T_C)] + [np.shape(T_oil_C) if T_oil_C is not None else ()]
    try:
        batch = np.broadcast_shapes(*shapes)
    except ValueError:
        raise InputError("Fa, Fr, n_rpm, T_C, T_oil_C", "shapes " + ", ".join(map(str, shapes)),
                         "must broadcast together (numpy rules)") from None
    batch, pp = _per_point(batch, dict(oil_flow_m3_s=oil_flow_m3_s, Rq_ball=Rq_ball, Rq_ring=Rq_ring,
                                       mu_boundary=mu_boundary, mu_full_film=mu_full_film,
                                       seal_torque_Nm=seal_torque_Nm, oil_level_m=oil_level_m, K_rs=K_rs))
    check_loads(brg, Fa, Fr, M, n_rpm)                    # before any solve: what no answer exists for
    check_limit("n_dm", np.asarray(n_rpm, float) * brg.dm * 1e3, "n_rpm")    # warns beyond the validated speed
    cs = prepare_contacts(brg, Fa, Fr, np.broadcast_to(np.asarray(n_rpm, float), batch), M=M, rotating=rotating,
                          hertz_method=hertz_method, control=control, centrifugal=centrifugal, load=load)
    check_contacts(brg, cs.sides, "Fa, Fr, M", warn=True, given=loads_text(Fa, Fr, M))
    return evaluate_losses(cs, oil, T_C, T_inner_C=T_inner_C, T_outer_C=T_outer_C, T_oil_C=T_oil_C, supply=supply,
                           rolling_model=rolling_model, drag=drag, traction=traction, inlet_heating=inlet_heating,
                           starvation=starvation, cage=cage, **pp)


def _per_point(batch: tuple, params: dict):
    """(batch, params) of :func:`bearing_losses`: the operating points' shape extended by the parameters given one
    per operating point (numpy broadcasting; each point then equals the call with its values), and the parameters as
    :func:`evaluate_losses` takes them (roughnesses and friction coefficients with two axes for the contacts).
    Each is checked as a scene's: finite and >= 0, the friction coefficients in [0, 1]."""
    loads = batch
    for name, v in params.items():
        if v is None:
            continue
        try:
            a = np.asarray(v, dtype=float)
        except (TypeError, ValueError):
            raise InputError(name, v, "must be a number, or an array of numbers") from None
        if name.startswith("mu_") and not within(a, 0.0, 1.0):                 # NaN fails
            raise InputError(name, v, "friction coefficient must lie in [0, 1] [-] (as a scene's [lubricant] key)")
        checked(name, a, lo=0.0, strict=False, what=f" [{_UNITS.get(name, '-')}]")
        try:
            batch = np.broadcast_shapes(batch, a.shape)
        except ValueError:
            raise InputError(name, f"shape {a.shape}", f"one value, or one per operating point: a shape "
                             f"broadcasting with {loads}, the shape of the loads, speed and temperatures") from None
    return batch, {k: np.broadcast_to(np.asarray(v, float), batch)[..., None, None]
                   if k in _PER_CONTACT and np.ndim(v) else v for k, v in params.items()}


_PER_CONTACT = ("Rq_ball", "Rq_ring", "mu_boundary", "mu_full_film", "K_rs")   # against the contacts (…, 2, Z)
_UNITS = {"oil_flow_m3_s": "m³/s", "Rq_ball": "m", "Rq_ring": "m", "seal_torque_Nm": "N m", "oil_level_m": "m"}
