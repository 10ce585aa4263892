r"""Hydrodynamic rolling force of a lubricated ball–race (point) contact.

The pressure field of a lubricated rolling contact is not symmetric (the
outlet cavitates), so the Poiseuille shear pulls each surface against the
rolling direction with a force F_R [N], and the pressure pushes the ball centre
with FP = 2 F_R (seed 000 §2.3; seed 001 §2).  The power dissipated by one
contact is 2 u F_R, u the *mean* entrainment speed (seed 000 eq 34, seed 004 eq 20).

Models (one function each, pure and vectorised; scalars or broadcastable arrays):

=====================  =========================================================
``biboulet_ivr``       Biboulet & Houpert 2010, IVR curve fit (seed 000 eq 21)
``biboulet_ehl``       Biboulet & Houpert 2010, EHL curve fit (seed 000 eq 22)
``biboulet_transition``  blend of the two with M (seed 000 eqs 20, 23)
``biboulet_dominant``  IVR or transition by the dominant regime (Bălan et al. 2015, seed 001 §5)
``houpert_ivr``        Houpert 1987 IVR re-fitted (seed 004 eq 17; B&H 2010 eq 28)
``houpert_ehl``        Houpert EHL (seed 004 eq 18; B&H 2010 eq 29)
``biboulet_pvr``       Biboulet's full IVR→EHL fit (seed 004 eq 19; B&H 2010 eqs 32, 36)
``auto``               per contact by lubrication regime (seed 004 §4.3)
``auto_smooth``        the same choice, weighted smoothly across the regime boundaries
=====================  =========================================================

The formulas themselves are in :mod:`thermobear.losses.rolling_forms` (re-exported here);
this module adds the dispatcher :func:`rolling_force`, the regime selection and
:class:`RollingContacts`: contacts prepared once (checked, speed-free coefficients) and evaluated
at any number of viscosities (temperature states), as the local loss model does.

Zero load.  Every formula here is *load controlled*: the gap follows from Q, so
F_R → 0 as Q → 0 (W^(1/3) for Biboulet, W^0.364 for Houpert IVR, a ∝ Q^(1/3)
for the EHL/PVR forms) and is exactly 0 at Q = 0.  A ball in the unloaded zone
of a radial bearing is not at zero load in reality: its outer contact carries
the centrifugal force and its gap is set by the clearance, so it still brakes
(seed 004 finds those IVR contacts matter).  Pass the actual small load (e.g.
centrifugal force) of such contacts; do not rely on Q = 0 to model them.

References
----------
Biboulet N., Houpert L. (2010) Hydrodynamic force and moment in pure rolling
lubricated contacts. Part 2: point contacts. Proc. IMechE J 224, 777–787.
Seeds 000 (Ianuș et al.), 001 (Bălan et al. 2015), 004 (Darul et al. 2024).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermobear.arrays import out as _out
from thermobear.errors import InputError
from thermobear.losses.rolling_forms import (  # noqa: F401  (re-exported)
    _M_SPLIT, _biboulet_pvr, _biboulet_pvr_coeffs, _checked_geometry, _houpert_ehl, _houpert_ehl_coeff,
    _houpert_ivr, _houpert_ivr_coeff, DOMINANT_BAND, _num, biboulet_parameters, ehl_partition, rolling_force_biboulet_dominant,
    rolling_force_biboulet_ehl, rolling_force_biboulet_ivr, rolling_force_biboulet_pvr, rolling_force_biboulet_transition,
    rolling_force_houpert_ehl, rolling_force_houpert_ivr, transition_parameter, truncation_coefficient)
from thermobear.losses.sliding import LAMBDA_FULL_FILM_BALAN, asperity_load_share
from thermobear.lubrication.film import Regime, lubrication_regime

__all__ = [
    "MODELS", "REGIME_MODEL", "SWITCH_WIDTH", "DOMINANT_BAND",
    "transition_parameter", "ehl_partition",
    "rolling_force_biboulet_ivr", "rolling_force_biboulet_ehl",
    "rolling_force_biboulet_transition", "rolling_force_biboulet_dominant",
    "biboulet_parameters", "truncation_coefficient",
    "rolling_force_houpert_ivr", "rolling_force_houpert_ehl", "rolling_force_biboulet_pvr",
    "RollingContacts", "rolling_contacts",
    "rolling_force_regime_weighted", "rolling_force", "rolling_force_mixed", "pressure_force", "rolling_power",
]

MODELS = ("biboulet_ivr", "biboulet_ehl", "biboulet_transition", "biboulet_dominant", "houpert_ivr",
          "houpert_ehl", "biboulet_pvr", "auto", "auto_smooth")

#: Model used per lubrication regime by ``model="auto"`` (seed 004 §4.3).  IVE
#: (iso-viscous elastic) has no dedicated formula in the seeds; it goes to the
#: Biboulet IVR→EHL blend because that blend depends on the elastic parameter M
#: only and its elastic asymptote is independent of piezo-viscosity
#: (B&H 2010 found G^0.022), which is exactly the iso-viscous *elastic* case;
#: Houpert's EHL fit assumes a piezo-viscous film.
REGIME_MODEL = {"IVR": "houpert_ivr", "PVR": "biboulet_pvr", "IVE": "biboulet_pvr",
                "EHL": "houpert_ehl"}

#: ln-ratio width of the smooth regime switch of :func:`rolling_force_regime_weighted` (±5 %)
SWITCH_WIDTH = 0.05



# ----------------------------------------------------------------------------- prepared contacts
@dataclass(frozen=True)
class RollingContacts:
    r"""Point contacts prepared for the rolling-force formulas (inputs checked once).

    The speed-free coefficients of the Biboulet & Houpert / seed 004 forms for contacts of given
    load, radii, entrainment speed, modulus and Hertz semi-axes; :meth:`force` evaluates a model at
    the lubricant's η (and α_p), which broadcast against the contacts (leading axes: temperature
    states).  Built by :func:`rolling_contacts`.

    Attributes
    ----------
    Q, Rx, Ry, u, E_prime : ndarray   the checked inputs [N, m, m, m/s, Pa]
    kappa : ndarray                   ellipse ratio b/a [-]
    U2_eta : ndarray                  2u/(E' Rx): B&H's speed parameter per unit viscosity [1/(Pa s)]
    C_ivr : ndarray                   Houpert's IVR force at U2 = 1 [N]
    C_ehl : ndarray                   Houpert's EHL force at G = U2 = 1 [N]
    pvr : tuple                       speed-free factors of Biboulet's PVR force
    """

    Q: np.ndarray
    Rx: np.ndarray
    Ry: np.ndarray
    u: np.ndarray
    E_prime: np.ndarray
    kappa: np.ndarray
    U2_eta: np.ndarray
    C_ivr: np.ndarray
    C_ehl: np.ndarray
    pvr: tuple

    def force(self, eta, model="auto_smooth", alpha_p=None, regime=None, check=True):
        """Rolling force [N] of ``model`` (one of :data:`MODELS`) at the inlet viscosity ``eta``
        [Pa s] and pressure–viscosity coefficient ``alpha_p`` [1/Pa] (houpert_ehl, auto, auto_smooth);
        ``regime``: see :func:`rolling_force`; ``check`` False: η and α_p already checked."""
        if model not in MODELS:
            raise InputError("model", model, f"must be one of {', '.join(MODELS)}")
        if model in ("biboulet_ivr", "biboulet_ehl", "biboulet_transition", "biboulet_dominant"):
            return rolling_force(self.Q, self.Rx, self.Ry, self.u, eta, self.E_prime, model=model)
        eta = _num("eta", eta, what=" [Pa s]") if check else eta
        U2 = eta * self.U2_eta
        if model == "houpert_ivr":
            return _houpert_ivr(self.C_ivr, U2)
        if model == "biboulet_pvr":
            return _biboulet_pvr(self.pvr, U2)
        if model == "auto" and regime is not None:
            return self._sharp(regime, U2, alpha_p)
        if alpha_p is None:
            raise InputError("alpha_p", None, f"pressure-viscosity coefficient [1/Pa] is required by {model}")
        alpha_p = _num("alpha_p", alpha_p, what=" [1/Pa]") if check else alpha_p
        if model == "houpert_ehl":
            return _houpert_ehl(self.C_ehl, alpha_p * self.E_prime, U2)
        if regime is None:
            regime = lubrication_regime(self.Q, self.Rx, self.Ry, self.u, eta, alpha_p, self.E_prime)
        if model == "auto":
            return self._sharp(regime, U2, alpha_p)
        F_ivr = _houpert_ivr(self.C_ivr, U2)
        F_pvr = _biboulet_pvr(self.pvr, U2)
        F_ehl = _houpert_ehl(self.C_ehl, alpha_p * self.E_prime, U2)
        k = 0.5 / SWITCH_WIDTH                        # logistic 1/(1 + e^(−x/w)) = ½ + ½ tanh(x/2w)
        s_piezo = 0.5 - 0.5 * np.tanh(k * regime.ln_iso_over_piezo)
        s_rigid_iso = 0.5 + 0.5 * np.tanh(k * regime.ln_RI_over_EI)
        s_rigid_piezo = 0.5 + 0.5 * np.tanh(k * regime.ln_EP_over_RP)
        iso = F_pvr + s_rigid_iso * (F_ivr - F_pvr)
        piezo = F_ehl + s_rigid_piezo * (F_pvr - F_ehl)
        return iso + s_piezo * (piezo - iso)

    def _sharp(self, regime, U2, alpha_p):
        """Seed 004's sharp selection by regime code (:data:`REGIME_MODEL`)."""
        code = np.asarray(regime.code if isinstance(regime, Regime) else regime)
        unknown = set(np.unique(code).tolist()) - set(REGIME_MODEL)
        if unknown:
            raise InputError("regime", sorted(unknown), f"must be one of {', '.join(REGIME_MODEL)}")
        def ehl():
            if alpha_p is None:
                raise InputError("alpha_p", None, "pressure-viscosity coefficient [1/Pa] is required by houpert_ehl")
            return _houpert_ehl(self.C_ehl, _num("alpha_p", alpha_p, what=" [1/Pa]") * self.E_prime, U2)

        forces = {"houpert_ivr": lambda: _houpert_ivr(self.C_ivr, U2),
                  "biboulet_pvr": lambda: _biboulet_pvr(self.pvr, U2), "houpert_ehl": ehl}
        shape = np.broadcast_shapes(np.shape(U2), np.shape(self.C_ivr), code.shape)
        out = np.zeros(shape)
        code = np.broadcast_to(code, shape)
        for name in sorted(set(REGIME_MODEL[r] for r in np.unique(code).tolist())):
            mask = np.isin(code, [r for r, m in REGIME_MODEL.items() if m == name])
            out = np.where(mask, forces[name](), out)
        return out


def rolling_contacts(Q, Rx, Ry, u, E_prime, a=None, b=None) -> RollingContacts:
    r"""Point contacts prepared for :meth:`RollingContacts.force` (the formulas of this module).

    Parameters
    ----------
    Q : array_like        normal load [N]
    Rx, Ry : array_like   reduced radii in / across the rolling direction [m]
    u : array_like        mean entrainment speed (u1 + u2)/2 [m/s]
    E_prime : array_like  reduced modulus E' [Pa]
    a, b : array_like, optional   Hertz semi-axes across / along rolling [m] (exact Hertz if omitted)

    Returns
    -------
    RollingContacts

    Notes
    -----
    The speed-free coefficients are computed once, e.g. for Houpert's IVR force (seed 004 eq 17)

    .. math::

        F = C_{IVR}\, U^{0.636},\qquad C_{IVR} = 0.835\, \lambda^{-0.358} W^{0.364} E' R_x^2

    with U = 2 η u/(E' Rx); each formula is written once (:mod:`thermobear.losses.rolling_forms`).

    Examples
    --------
    >>> c = rolling_contacts(1.42, 3.969e-3, 70.12e-3, 0.0942, 2.3e11)
    >>> round(float(c.force(0.089, "houpert_ivr")), 5), round(float(c.force([0.089, 0.178], "houpert_ivr")[1]), 5)
    (0.00585, 0.00909)
    """
    Q, Rx, Ry, u, E_prime, a, kappa, beta = _checked_geometry(Q, Rx, Ry, u, E_prime, a, b)
    W = Q / (E_prime * Rx**2)
    return RollingContacts(Q=Q, Rx=Rx, Ry=Ry, u=u, E_prime=E_prime, kappa=kappa, U2_eta=2.0 * u / (E_prime * Rx),
                           C_ivr=_houpert_ivr_coeff(W, Rx, Ry, E_prime),
                           C_ehl=_houpert_ehl_coeff(W, Rx, E_prime, a, kappa),
                           pvr=_biboulet_pvr_coeffs(W, Rx, E_prime, a, kappa, beta, u > 0))


# ----------------------------------------------------------------------------- regime selection
def rolling_force_regime_weighted(Q, Rx, Ry, u, eta, E_prime, alpha_p, a=None, b=None, regime=None):
    r"""Regime-selected hydrodynamic rolling force, switched smoothly across the Moes boundaries [N].

    Parameters
    ----------
    Q, Rx, Ry, u, eta, E_prime : as :func:`rolling_force_biboulet_ivr`
    alpha_p : array_like           pressure–viscosity coefficient [1/Pa]
    a, b : array_like, optional    Hertz semi-axes across / along rolling [m] (exact Hertz if omitted)
    regime : Regime, optional      the contacts' regime (:func:`thermobear.lubrication.film.lubrication_regime`
                                   of the same inputs; computed if omitted)

    Returns
    -------
    ndarray  force opposing rolling on each surface [N]

    Notes
    -----
    Seed 004 §4.3 picks Houpert IVR, Biboulet PVR or Houpert EHL by regime (IVE → Biboulet PVR,
    :data:`REGIME_MODEL`).  The formulas do not meet at the boundaries (jumps of ×0.5–0.9,
    tests/test_rolling.py), and a force that jumps with temperature stalls implicit time
    integration.  Here each choice is weighted by logistic functions of the dominance ratios of
    the Nijenbanning–Venner–Moes blend (:class:`~thermobear.lubrication.film.Regime`),

    .. math::

        F = (1 - s_p) [s_{ri} F_{IVR} + (1 - s_{ri}) F_{PVR}] + s_p [s_{rp} F_{PVR} + (1 - s_{rp}) F_{EHL}],

        s(r) = \frac{1}{1 + r^{-1/w}},\quad s_p = s(1/r_{iso/piezo}),\ s_{ri} = s(r_{RI/EI}),\
        s_{rp} = s(r_{EP/RP}),\quad w = 0.05

    1 % of the way from a boundary in ln r the selection is 60/40, 15 % away it is 95/5; away
    from the boundaries the result equals the sharp selection (``rolling_force(model="auto")``).
    The weighting is this library's (not published); the three forces are seed 004 eqs 17–19
    (Biboulet & Houpert 2010 [1]_).

    References
    ----------
    .. [1] Biboulet N., Houpert L. (2010) Proc. IMechE J 224, 777–787.

    Examples
    --------
    Seed 000 contact geometry (thrust race, 100 rpm) at 0.1 N, deep in the IVR regime
    (Houpert's IVR force), and at 1.42 N, PVR near the EHL boundary (ln H_EP/H_RP = 0.14: 94 % PVR):

    >>> args = (3.969e-3, 70.12e-3, 0.0942, 0.089, 2.3e11)
    >>> round(float(rolling_force_regime_weighted(0.1, *args, 2.5e-8)), 6), round(rolling_force_houpert_ivr(0.1, *args), 6)
    (0.002227, 0.002227)
    >>> round(float(rolling_force_regime_weighted(1.42, *args, 2.5e-8)), 5), round(rolling_force_biboulet_pvr(1.42, *args), 5)
    (0.0031, 0.00317)
    """
    if alpha_p is None:
        raise InputError("alpha_p", None, "pressure-viscosity coefficient [1/Pa] is required by auto_smooth")
    return _out(rolling_contacts(Q, Rx, Ry, u, E_prime, a, b).force(eta, "auto_smooth", alpha_p, regime))


def rolling_force(Q, Rx, Ry, u, eta, E_prime, model="biboulet_transition", alpha_p=None,
                  a=None, b=None, regime=None):
    r"""Hydrodynamic rolling force of point contacts by the chosen model [N].

    Parameters
    ----------
    Q : array_like        normal load [N]
    Rx, Ry : array_like   reduced radii in / across the rolling direction [m]
    u : array_like        mean entrainment speed (u1 + u2)/2 [m/s]
    eta : array_like      inlet dynamic viscosity [Pa s]
    E_prime : array_like  reduced modulus [Pa]
    model : str           one of :data:`MODELS`
    alpha_p : array_like  pressure–viscosity coefficient [1/Pa] (houpert_ehl, auto, auto_smooth)
    a, b : array_like     Hertz semi-axes across / along rolling [m] (optional)
    regime : Regime or array_like of str, optional
        for ``model="auto"``: "IVR", "PVR", "IVE" or "EHL" per contact (or a
        :class:`~thermobear.lubrication.film.Regime`); for ``"auto_smooth"`` a Regime;
        computed with :func:`thermobear.lubrication.film.lubrication_regime` if omitted.
        Mapping :data:`REGIME_MODEL` (seed 004 §4.3; IVE → biboulet_pvr, see there).

    Returns
    -------
    Force opposing rolling on each surface [N]; the contact dissipates
    :func:`rolling_power` = 2 u F.

    Notes
    -----
    ``auto`` switches formulas at regime boundaries and so is discontinuous
    there; the jumps are quantified in tests/test_rolling.py and in
    validation/report/seed001_spin_down.md.  ``auto_smooth`` is
    :func:`rolling_force_regime_weighted`.

    Examples
    --------
    >>> args = (1.42, 3.969e-3, 70.12e-3, 0.094248, 0.089, 2.3e11)
    >>> round(rolling_force(*args), 5), round(rolling_force(*args, model="houpert_ivr"), 5)
    (0.00605, 0.00585)
    >>> rolling_force(*args, model="auto", regime=["IVR", "PVR"]).round(5)
    array([0.00585, 0.00317])
    """
    if model not in MODELS:
        raise InputError("model", model, f"must be one of {', '.join(MODELS)}")
    if model == "biboulet_ivr":
        return rolling_force_biboulet_ivr(Q, Rx, Ry, u, eta, E_prime)
    if model == "biboulet_ehl":
        return rolling_force_biboulet_ehl(Q, Rx, Ry, u, eta, E_prime)
    if model == "biboulet_transition":
        return rolling_force_biboulet_transition(Q, Rx, Ry, u, eta, E_prime)
    if model == "biboulet_dominant":
        return rolling_force_biboulet_dominant(Q, Rx, Ry, u, eta, E_prime)
    if model == "houpert_ivr":
        return rolling_force_houpert_ivr(Q, Rx, Ry, u, eta, E_prime)
    if model == "houpert_ehl":
        return rolling_force_houpert_ehl(Q, Rx, Ry, u, eta, E_prime, alpha_p, a, b)
    if model == "biboulet_pvr":
        return rolling_force_biboulet_pvr(Q, Rx, Ry, u, eta, E_prime, a, b)
    if model == "auto_smooth":
        return rolling_force_regime_weighted(Q, Rx, Ry, u, eta, E_prime, alpha_p, a, b, regime)
    # auto: seed 004's sharp selection
    if regime is None and alpha_p is None:
        raise InputError("alpha_p", None, "model='auto' without a regime array needs alpha_p [1/Pa]")
    return _out(rolling_contacts(Q, Rx, Ry, u, E_prime, a, b).force(eta, "auto", alpha_p, regime))


def rolling_force_mixed(Q, Rx, Ry, u, eta, E_prime, Lambda, model="biboulet_transition", *,
                        c_rr_asperity=0.0, alpha_p=None):
    r"""Rolling resistance of a point contact in mixed lubrication, by load sharing [N].

    Parameters
    ----------
    Q, Rx, Ry, u, eta, E_prime : as :func:`rolling_force` [N, m, m, m/s, Pa s, Pa]
    Lambda : array_like       film parameter h_min/√(Rq1² + Rq2²) of the smooth film [-], ≥ 0;
                              +inf (smooth surfaces) gives the full-film force
    model : str               hydrodynamic model of the film share (one of :data:`MODELS`)
    c_rr_asperity : array_like  rolling-resistance coefficient of the asperity contacts [-]
                              (force / asperity load); 0 by default, see Notes
    alpha_p : array_like      pressure–viscosity coefficient [1/Pa] (models that need it)

    Returns
    -------
    float or ndarray  force opposing rolling on each surface [N]

    Notes
    -----
    Load sharing (Johnson, Greenwood & Poon 1972 [1]_): the film and the asperities carry
    Q_f + Q_a = Q, and each part is evaluated with its own model at its own load; seed 001
    (Bălan et al. 2015 [2]_, App. A) applies it to the friction coefficient,
    μ_S = μ_EHL (1 − Q_a/Q) + μ_a Q_a/Q, with the share Q_a/Q(Λ) of
    :func:`~thermobear.losses.sliding.asperity_load_share` (fit of Bălan et al. 2014 [3]_).
    Applied to the rolling resistance:

    .. math::

        F = F_R\big((1 - s)\,Q\big) + c_{rr,a}\, s\, Q,\qquad s = Q_a/Q(\Lambda)

    with F_R the hydrodynamic force of ``model`` (Biboulet & Houpert 2010 [4]_) at the film-borne load.
    The share is 0 for Λ ≥ 2.258 (:data:`~thermobear.losses.sliding.LAMBDA_FULL_FILM_BALAN`), so F
    is the full-film force there, continuously; F_R grows with load (W^(1/3) in IVR and EHL), so with
    c_rr,a = 0 F grows monotonically with Λ.  Every hydrodynamic force here is load controlled
    (F_R ∝ Q^(1/3)): carrying part of the load on asperities *lowers* the film's rolling force
    (×0.79 on the IVR force at s = 0.51, Λ ≈ 0.27).

    The asperity term: in pure rolling, asperity contacts dissipate by hysteresis and micro-slip
    only.  The local model carries the hysteresis moment (Houpert 1999, seed 001 eq 9) at the
    whole load and the micro-slip (pivoting, Heathcote slip) at the mixed μ(Λ), so the default
    c_rr,a = 0 avoids counting them twice.  Seed 001 §4.3 bounds the rest: its dry torque (no
    film: every contact on asperities) is 2–12 % of the lubricated torque.

    References
    ----------
    .. [1] Johnson K.L., Greenwood J.A., Poon S.Y. (1972) A simple theory of asperity contact in
       elastohydrodynamic lubrication. Wear 19, 91–108.
    .. [2] Bălan M.R.D., Houpert L., Tufescu A., Olaru D.N. (2015) Rolling friction torque in
       ball-race contacts operating in mixed lubrication conditions. Lubricants 3, 222–243, App. A.
    .. [3] Bălan M.R., Stamate V.C., Houpert L., Olaru D. (2014) The influence of the lubricant
       viscosity on the rolling friction torque. Tribol. Int. 72, 1–12.
    .. [4] Biboulet N., Houpert L. (2010) Proc. IMechE J 224, 777–787.

    Examples
    --------
    Seed 001, 3 mm ball on the 4.16 mm groove, 0.633 N, 60 rpm (u = 0.0565 m/s), η 0.05 Pa s:
    at Λ = 0.27 the asperities carry 51 %, and the film's force falls by 13 % (less than
    (0.49)^(1/3) = 0.79: the lighter film leans towards the larger IVR force):

    >>> args = (0.633, 1.5e-3, 2.3459e-3, 0.056549, 0.05, 2.3e11)
    >>> round(rolling_force(*args) * 1e6, 2), round(float(rolling_force_mixed(*args, 0.27)) * 1e6, 2)
    (274.65, 238.99)
    >>> float(rolling_force_mixed(*args, float("inf"))) == rolling_force(*args)
    True
    """
    L = np.asarray(Lambda, dtype=float)
    if L.size and not L.min() >= 0.0:                  # NaN fails too; +inf is the smooth limit
        raise InputError("Lambda", Lambda, "must be >= 0 (film parameter)")
    share = np.asarray(asperity_load_share(np.minimum(L, LAMBDA_FULL_FILM_BALAN)))   # 0 from there on
    Q = _num("Q", Q, what=" [N]")
    F_film = rolling_force((1.0 - share) * Q, Rx, Ry, u, eta, E_prime, model=model, alpha_p=alpha_p)
    return _out(np.asarray(F_film) + np.asarray(c_rr_asperity, dtype=float) * share * Q)


def pressure_force(F_R):
    r"""Pressure force on the ball centre, FP = 2 F_R, opposite to F_R [N].

    Integrating p dh/dx by parts with p = 0 at both menisci gives FP = 2 F_R
    (seed 001 §2, eq 7; seed 000 §2.3) — for a race flat in the rolling direction.

    >>> pressure_force(0.006)
    0.012
    """
    return _out(2.0 * np.asarray(F_R, dtype=float))


def rolling_power(u, F_R):
    r"""Power dissipated by hydrodynamic rolling in one contact, P = 2 u F_R [W].

    Parameters
    ----------
    u : array_like    mean entrainment speed [m/s]
    F_R : array_like  hydrodynamic rolling force [N]

    Returns
    -------
    float or ndarray  power [W]

    Notes
    -----
    .. math::

        P = 2 u F_R

    Sum velocity times force: seed 000 eq 34 (F_R d_b ω_b, d_b ω_b = 2u) and seed 004 eq 20.

    >>> round(rolling_power(0.37699, 0.01896), 6)
    0.014295
    """
    return _out(2.0 * np.asarray(u, dtype=float) * np.asarray(F_R, dtype=float))
