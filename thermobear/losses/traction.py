r"""Full-film traction of EHL contacts: the oil's shear rheology instead of a constant μ.

A constant full-film friction coefficient μ_e charges every point of a contact with μ_e p however
slowly it slips.  In the spinning contacts of thrust and angular-contact bearings most of the
ellipse slips at a few tenths of a percent of the rolling speed, where a real film carries much
less than its plateau traction.  The models here give the shear stress of the film from its
viscosity at the local pressure, the local shear rate and two properties of the oil:

* pressure–viscosity: Roelands (1966) with the pressure index Z that has the oil's α_p as its
  initial slope (:func:`roelands_viscosity`);
* shear stress: the Eyring sinh law of the non-linear viscous (isothermal) regime of Johnson &
  Tevaarwerk (1977), capped by the limiting shear stress τ_L = Λ_L p of Bair & Winer (1979)
  (:func:`eyring_shear_stress`); → Newtonian τ = η γ̇ at low shear stress, → τ_L at high slip;
* the slip-weighted traction coefficient of a contact whose slip varies along the major axis
  (spin, Heathcote micro-slip) on the Hertz strip load (:func:`strip_traction_coefficient`), and the
  nodes the local model prepares once per contact set (:data:`STRIP_NODES`).

The elastic (Maxwell) term of Johnson & Tevaarwerk is left out: at the film thicknesses and
pressures of rolling bearings it matters below slide-to-roll ratios of ~1e-4 only (the elastic
strain G γ reaches the Eyring stress within a few µm of the inlet).  Heating of the film by its
own shear (the thermal regime of Evans & Johnson 1986) is left out as well: the slip speeds of spin
and micro-slip are millimetres to centimetres per second.

The node arrays of a batch are large (stacked evaluations × points × contacts × balls × slip
components × nodes: ~10⁵ values for a 125-point family), so :func:`eyring_shear_stress` and
:func:`strip_traction_coefficient` work in place on one array instead of allocating a temporary
per operation: the same arithmetic (equal to the allocating form within 1e-15), about half the time.

References
----------
.. [1] Roelands C. J. A. (1966) Correlational aspects of the viscosity–temperature–pressure
       relationship of lubricating oils. PhD thesis, TU Delft.
.. [2] Johnson K. L., Tevaarwerk J. L. (1977) Shear behaviour of elastohydrodynamic oil films.
       Proc. R. Soc. Lond. A 356, 215–236.
.. [3] Bair S., Winer W. O. (1979) A rheological model for elastohydrodynamic contacts based on
       primary laboratory data. ASME J. Lubr. Technol. 101, 258–265.
.. [4] Evans C. R., Johnson K. L. (1986) Regimes of traction in elastohydrodynamic lubrication.
       Proc. IMechE C 200, 313–324.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermobear.arrays import checked as _num, out as _out
from thermobear.losses.sliding import XI0_HEATHCOTE

__all__ = ["ROELANDS_P0_PA", "roelands_pressure_index", "roelands_viscosity", "eyring_shear_stress",
           "strip_traction_coefficient", "strip_contacts", "StripContacts", "check_film_viscosity", "STRIP_NODES"]

#: Roelands' reference pressure p0 = 1.96e8 Pa (Roelands 1966 [1]_)
ROELANDS_P0_PA = 1.96e8
_LN_ETA_INF = 9.67          # −ln η∞, η∞ = 6.31e-5 Pa s (Roelands 1966)
_ETA_INF = float(np.exp(-_LN_ETA_INF))


def roelands_pressure_index(eta0, alpha_p):
    r"""Roelands pressure index Z whose initial slope d ln η/dp is α_p [-].

    Parameters
    ----------
    eta0 : array_like     viscosity at ambient pressure [Pa s] (> 6.31e-5)
    alpha_p : array_like  pressure–viscosity coefficient [1/Pa]

    Returns
    -------
    float or ndarray  Z [-]

    Notes
    -----
    .. math::

        Z = \frac{\alpha_p\, p_0}{\ln \eta_0 + 9.67}

    (the derivative of :func:`roelands_viscosity` at p = 0; Roelands 1966 [1]_, as used e.g. by
    Hamrock 1994).  Mineral oils give Z ≈ 0.5–0.7.

    References
    ----------
    .. [1] Roelands C. J. A. (1966) PhD thesis, TU Delft.

    Examples
    --------
    >>> round(roelands_pressure_index(0.114, 19.5e-9), 3)
    0.51
    """
    eta0 = _num("eta0", eta0, lo=np.exp(-_LN_ETA_INF), what=" [Pa s]")
    return _out(_num("alpha_p", alpha_p, what=" [1/Pa]") * ROELANDS_P0_PA / (np.log(eta0) + _LN_ETA_INF))


def roelands_viscosity(eta0, alpha_p, p):
    r"""Viscosity at pressure, Roelands (1966) with the index of :func:`roelands_pressure_index` [Pa s].

    Parameters
    ----------
    eta0 : array_like     viscosity at ambient pressure [Pa s]
    alpha_p : array_like  pressure–viscosity coefficient [1/Pa] (sets Z)
    p : array_like        pressure [Pa], ≥ 0

    Returns
    -------
    float or ndarray  η(p) [Pa s]

    Notes
    -----
    .. math::

        \eta = \eta_0 \exp\left\{(\ln\eta_0 + 9.67)\left[(1 + p/p_0)^Z - 1\right]\right\},
        \qquad p_0 = 1.96\times 10^8\ \mathrm{Pa}

    Equal to Barus' η0 e^{α_p p} to first order in p; far below it at EHL pressures (Barus over-predicts
    by orders of magnitude above ~1 GPa).

    References
    ----------
    .. [1] Roelands C. J. A. (1966) PhD thesis, TU Delft.

    Examples
    --------
    A mineral oil (η0 0.114 Pa s, α 19.5 GPa⁻¹) at 1 GPa, and the Barus limit at 1 kPa:

    >>> round(roelands_viscosity(0.114, 19.5e-9, 1e9) / 1e3, 2)
    9.71
    >>> round(float(roelands_viscosity(0.114, 19.5e-9, 1e3) / (0.114 * np.exp(19.5e-9 * 1e3))), 8)
    1.0
    """
    eta0 = check_film_viscosity(eta0)
    alpha_p = _num("alpha_p", alpha_p, what=" [1/Pa]")
    return _out(_roelands(eta0, alpha_p, np.log1p(_num("p", p, strict=False, what=" [Pa]") / ROELANDS_P0_PA)))


def check_film_viscosity(eta0):
    """``eta0`` as a float array, each value finite and above Roelands' η∞ = 6.31e-5 Pa s (the pressure
    index of :func:`roelands_pressure_index` needs ln η0 + 9.67 > 0); else an InputError."""
    return _num("eta0", eta0, lo=_ETA_INF, what=" [Pa s]")


def _roelands(eta0, alpha_p, ln_p):
    """:func:`roelands_viscosity` of checked arrays, the pressure given as ln(1 + p/p0) (a contact's
    pressures do not change with its temperature: :class:`StripContacts` forms them once)."""
    lg = np.log(eta0) + _LN_ETA_INF
    e = np.asarray(np.multiply(alpha_p * ROELANDS_P0_PA / lg, ln_p))      # Z ln(1 + p/p0)
    np.expm1(e, out=e)                                           # (1 + p/p0)^Z − 1
    e *= lg
    np.exp(e, out=e)
    e *= eta0
    return e


def eyring_shear_stress(eta, shear_rate, tau0, tau_L=np.inf):
    r"""Shear stress of an EHL film: Eyring sinh law capped by the limiting shear stress [Pa].

    Parameters
    ----------
    eta : array_like         viscosity at the local pressure and temperature [Pa s]
    shear_rate : array_like  shear rate |Δu|/h [1/s], ≥ 0
    tau0 : array_like        Eyring stress [Pa]
    tau_L : array_like       limiting shear stress [Pa] (e.g. Λ_L p); default no limit

    Returns
    -------
    float or ndarray  τ [Pa], ≥ 0

    Notes
    -----
    .. math::

        \tau = \min\left(\tau_0\, \mathrm{asinh}\frac{\eta\dot\gamma}{\tau_0},\ \tau_L\right)

    The non-linear viscous flow of Johnson & Tevaarwerk (1977) [1]_ (their eq 6 without the elastic
    term) and the limiting shear stress of Bair & Winer (1979) [2]_.  Limits: Newtonian τ → η γ̇
    as η γ̇/τ0 → 0; τ0 ln(2 η γ̇/τ0) for η γ̇ ≫ τ0; τ_L at high slip.

    References
    ----------
    .. [1] Johnson K. L., Tevaarwerk J. L. (1977) Proc. R. Soc. Lond. A 356, 215–236.
    .. [2] Bair S., Winer W. O. (1979) ASME J. Lubr. Technol. 101, 258–265.

    Examples
    --------
    >>> round(eyring_shear_stress(1.0, 1e3, 5e6), 3)             # Newtonian: η γ̇ = 1 kPa
    1000.0
    >>> round(eyring_shear_stress(1e6, 1e4, 5e6) / 1e6, 2), eyring_shear_stress(1e12, 1e4, 5e6, 1e8)
    (41.47, 100000000.0)
    """
    tau0 = _num("tau0", tau0, what=" (Eyring stress) [Pa]")
    x = np.asarray(np.multiply(eta, _num("shear_rate", shear_rate, strict=False, what=" [1/s]"), dtype=float))
    x /= tau0                                    # in place: batched arrays are large (module notes)
    r = _eyring_reduced(x, np.asarray(tau_L, float) / tau0)
    r *= tau0
    return _out(r)


def _eyring_reduced(x, cap):
    """τ/τ0 of :func:`eyring_shear_stress` from x = η γ̇/τ0 (a float array, turned into the result in
    place where the shapes allow) and the cap τ_L/τ0."""
    np.arcsinh(x, out=x)
    if np.broadcast_shapes(x.shape, np.shape(cap)) != x.shape:
        return np.minimum(x, cap)
    return np.minimum(x, cap, out=x)


def _strip_nodes():
    """Gauss–Legendre nodes on (0, 1) split at the Heathcote rolling point ξ0 = 0.3473 (the kink of
    the micro-slip integrand, :data:`thermobear.losses.sliding.XI0_HEATHCOTE`), and the weights of the half-strip integral of the Hertz strip load,
    w (1 − ξ²): 4 nodes on (0, ξ0), 6 on (ξ0, 1)."""
    parts = []
    for lo, hi, n in ((0.0, XI0_HEATHCOTE, 4), (XI0_HEATHCOTE, 1.0, 6)):
        t, w = np.polynomial.legendre.leggauss(n)
        parts.append(((hi - lo) / 2 * t + (hi + lo) / 2, (hi - lo) / 2 * w))
    xi = np.concatenate([p[0] for p in parts])
    w = np.concatenate([p[1] for p in parts])
    return xi, w * (1.0 - xi**2)


#: (ξ, W): nodes ξ on (0, 1) along the major semi-axis and weights W = w (1 − ξ²) of the half-strip
#: integral of the Hertz strip load (split at the Heathcote rolling point; :func:`strip_traction_coefficient`)
STRIP_NODES = _strip_nodes()


def strip_traction_coefficient(slip, p_mean, h, eta0, alpha_p, tau0, Lambda_L, *, weights=None):
    r"""Slip-weighted full-film traction coefficient of a contact whose slip varies along its major
    axis [-].

    Parameters
    ----------
    slip : array_like      |slip speed| at the nodes ξ_k of :data:`STRIP_NODES`, node axis last [m/s]
                           (e.g. spin |ω_s| a ξ_k)
    p_mean : array_like    mean pressure across the rolling direction at ξ_k, (π/4) p_max √(1 − ξ_k²) [Pa]
                           (node axis last)
    h : array_like         central film thickness [m] (one per contact: broadcast against slip[..., 0])
    eta0 : array_like      viscosity at ambient pressure, contact temperature [Pa s] (per contact)
    alpha_p : array_like   pressure–viscosity coefficient [1/Pa] (per contact)
    tau0 : array_like      Eyring stress [Pa] (per contact)
    Lambda_L : array_like  limiting shear stress–pressure coefficient τ_L/p [-] (per contact)
    weights : array_like, optional  quadrature weights W_k of the Hertz strip load; default those of
                           :data:`STRIP_NODES`

    Returns
    -------
    float or ndarray  μ_f [-] per contact: the ratio of the contact's sliding power to that at μ = 1;
    0 where nothing slips

    Notes
    -----
    On slices across the rolling direction (the strip of seed 000 eqs 31–32, Hertz strip load
    q = (3Q/4a)(1 − ξ²), whose slice mean pressure is p̄ = (π/4) p_max √(1 − ξ²)), the film shears at
    γ̇ = |v|/h with the viscosity η(p̄) of :func:`roelands_viscosity`; its local traction coefficient
    is τ(p̄, γ̇)/p̄ (:func:`eyring_shear_stress`, τ_L = Λ_L p̄), and

    .. math::

        \mu_f = \frac{\int_0^1 (1-\xi^2)\,|v(\xi)|\,\tau/\bar p\; d\xi}{\int_0^1 (1-\xi^2)\,|v(\xi)|\; d\xi}

    so that P = μ_f P(μ = 1), with P(μ = 1) the power of the constant-μ model (pivoting, Heathcote).
    A constant τ/p̄ = μ gives μ_f = μ exactly.  Isothermal; the elastic term of Johnson & Tevaarwerk
    (1977) omitted (module notes).

    Examples
    --------
    Spin of a seed 002 thrust contact (MG1 at 50 °C, 1000 rpm: a = 0.744 mm, b = 0.116 mm,
    Q = 389 N, ω_s = 52.4 rad/s, h_c = 0.36 µm), Eyring stress 5 MPa, Λ_L = 0.075:

    >>> xi = STRIP_NODES[0]
    >>> pm = np.pi / 4 * 2.152e9 * np.sqrt(1 - xi**2)
    >>> round(strip_traction_coefficient(52.4 * 0.744e-3 * xi, pm, 0.36e-6, 0.114, 19.5e-9, 5e6, 0.075), 4)
    0.0288
    """
    st = strip_contacts(slip, p_mean, weights=weights)
    tau0 = _num("tau0", tau0, what=" (Eyring stress) [Pa]")
    eta0 = check_film_viscosity(eta0)
    return _out(st.traction(np.asarray(h, float), eta0, _num("alpha_p", alpha_p, what=" [1/Pa]"), tau0, Lambda_L))


@dataclass(frozen=True, eq=False)
class StripContacts:
    """The temperature-independent part of :func:`strip_traction_coefficient` for a set of contacts
    (:func:`strip_contacts`; the local model's :class:`~thermobear.losses.local.ContactSet` holds one):
    slip speeds ``v`` (…, k) [m/s], slice mean pressures ``pm`` (…, k) [Pa] and ln(1 + p̄/p0) ``ln_p``
    (Roelands), and ``G`` = W_k |v_k| [p̄_k > 0] / (p̄_k Σ_k W_k |v_k|) (…, k) [1/Pa] with the quadrature
    weights W_k: μ_f = Σ_k G_k τ_k."""

    v: np.ndarray
    pm: np.ndarray
    ln_p: np.ndarray
    G: np.ndarray

    def traction(self, h, eta0, alpha_p, tau0, Lambda_L):
        """μ_f of :func:`strip_traction_coefficient` at central films ``h`` [m], viscosities ``eta0``
        [Pa s] and α_p [1/Pa], Eyring stresses ``tau0`` [Pa] and Λ_L [-] (each per contact: broadcast
        against ``v[..., 0]``; checked by the caller)."""
        tau0 = np.asarray(tau0, float)
        eta = _roelands(eta0[..., None], alpha_p[..., None], self.ln_p)    # η(p̄) at the nodes
        eta *= (1.0 / (tau0 * np.maximum(h, 1e-12)))[..., None]           # η/(τ0 h)
        r = _eyring_reduced(eta * self.v, (np.asarray(Lambda_L, float) / tau0)[..., None] * self.pm)
        return tau0 * np.einsum("...k,...k->...", r, self.G)                 # Σ_k G_k τ_k, τ = τ0 r


def strip_contacts(slip, p_mean, *, weights=None, check=True) -> StripContacts:
    """The :class:`StripContacts` of slips and slice mean pressures at the strip nodes (see
    :func:`strip_traction_coefficient`; ``weights`` default those of :data:`STRIP_NODES`; ``check``
    False: ``slip`` already |slip| ≥ 0 and ``p_mean`` ≥ 0, float arrays, e.g. of a Hertz contact).

    >>> xi = STRIP_NODES[0]
    >>> st = strip_contacts(0.01 * xi, 1e9 * np.sqrt(1 - xi**2))
    >>> round(float(st.traction(np.array(1e-7), np.array(1e3), np.array(30e-9), 5e6, 0.06)), 4)
    0.06
    """
    W = STRIP_NODES[1] if weights is None else np.asarray(weights, float)
    if check:
        v, pm = np.abs(np.asarray(slip, float)), _num("p_mean", p_mean, strict=False, what=" [Pa]")
    else:
        v, pm = slip, p_mean
    den = v @ W                                  # Σ_k W_k |v_k|
    loaded = pm > 0
    G = v * (W * (loaded / np.where(loaded, pm, 1.0)))                 # W_k |v_k| / p̄_k (0 where p̄_k = 0)
    G *= np.where(den > 0, 1.0 / np.where(den > 0, den, 1.0), 0.0)[..., None]
    return StripContacts(v=v, pm=pm, ln_p=np.log1p(pm * (1.0 / ROELANDS_P0_PA)), G=G)
