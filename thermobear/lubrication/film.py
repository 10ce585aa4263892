r"""EHL film thickness, Moes parameters, lubrication regime and specific film thickness.

Conventions (Hamrock & Dowson 1977; Moes 1992): x is the rolling direction; ``Rx``, ``Ry`` the
reduced radii in the rolling / transverse direction (Ry ≥ Rx for ball–race
contacts); ``u`` is the MEAN entrainment speed u = (u1 + u2)/2 [m/s] (Hamrock
convention) at every public function — the Moes / NVM groups use the sum speed
2u internally; ``eta`` the inlet dynamic viscosity [Pa s]; ``alpha_p`` the
pressure–viscosity coefficient [1/Pa]; ``E_prime`` the reduced modulus
2/E' = (1−ν1²)/E1 + (1−ν2²)/E2 [Pa].  All functions broadcast numpy arrays
(e.g. a leading batch axis of temperature states against the contacts).

Limits, defined so that no NaN and no floating-point warning is produced:

* zero speed (u = 0): every film is 0; the Moes regime is the u → 0 limit
  (iso-viscous elastic, "IVE", for a loaded contact);
* zero load (Q = 0): there is no contact, and the film is reported as 0 **by
  convention** (the rigid-isoviscous film grows without bound, h ∝ Q^-2, as
  Q → 0); the regime is "IVR".

Regimes (Nijenbanning, Venner & Moes 1994; seed 004 §3): "IVR" iso-viscous rigid, "IVE"
iso-viscous elastic, "PVR" piezo-viscous rigid, "EHL" piezo-viscous elastic.

References
----------
Hamrock B. J., Dowson D. (1977) Isothermal elastohydrodynamic lubrication of point contacts,
Part III — fully flooded results. J. Lubr. Technol. 99, 264–276.
Nijenbanning G., Venner C. H., Moes H. (1994) Film thickness in elastohydrodynamically lubricated
elliptic contacts. Wear 176, 217–229.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermobear.errors import InputError
from thermobear.lubrication.nvm import (EXP_MAX, REGIMES, TINY, MoesMapBoundaries, Regime, _arr, _clip,
                                        _ln_branches, _out, _regime_from_ln, ln_asymptote_consts,
                                        moes_map_boundaries, moes_N, moes_regime, nvm_asymptotes, nvm_H)

__all__ = [
    "hamrock_dowson_groups", "film_thickness", "moes_parameters", "moes_N",
    "nvm_asymptotes", "nvm_H", "film_thickness_nvm", "composite_roughness",
    "specific_film_thickness", "Regime", "moes_regime", "lubrication_regime",
    "MoesMapBoundaries", "moes_map_boundaries", "REGIMES", "ln_asymptote_consts", "TINY", "EXP_MAX",
    "EHLContacts", "ehl_contacts",
]

_TINY, _EXP_MAX = TINY, EXP_MAX          # former private names (thermobear.loads.film imports them)
_ln_asymptote_consts = ln_asymptote_consts


# ---------------------------------------------------------------------------
# input checks
# ---------------------------------------------------------------------------
def _geometry(Q, Rx, Ry, u, E_prime):
    """Checked contact geometry (Q, Rx, Ry/Rx, u, E_prime), each array checked once (not broadcast);
    Ry > 0 follows from Rx > 0 and Ry/Rx ≥ 1."""
    Q = _arr("Q", Q, nonneg=True)
    Rx = _arr("Rx", Rx, positive=True)
    ratio = Ry / Rx if type(Ry) is float else np.asarray(Ry, dtype=float) / Rx
    if not (ratio if type(ratio) is float else ratio.min()) >= 1.0 - 1e-12:     # NaN fails too
        raise InputError("Ry/Rx", ratio, "must be >= 1 (Ry transverse, Rx rolling direction; "
                         "these formulas were fitted for Ry >= Rx)")
    return Q, Rx, ratio, _arr("u", u, nonneg=True), _arr("E_prime", E_prime, positive=True)


def _contact(Q, Rx, Ry, u, eta, alpha_p, E_prime, alpha_positive):
    """Checked contact inputs (Q, Rx, Ry/Rx, u, eta, alpha_p, E_prime), not broadcast."""
    Q, Rx, ratio, u, E_prime = _geometry(Q, Rx, Ry, u, E_prime)
    eta = _arr("eta", eta, positive=True)
    alpha_p = _arr("alpha_p", alpha_p, positive=alpha_positive, nonneg=True)
    return Q, Rx, ratio, u, eta, alpha_p, E_prime


def _scalar(*inputs):
    return all(np.ndim(v) == 0 for v in inputs)


_FILM_KINDS = ("min", "central")


# ---------------------------------------------------------------------------
# Contacts prepared for the film and regime formulas
# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class EHLContacts:
    r"""Point contacts prepared for the film and regime formulas (inputs checked once).

    The temperature-independent factors of :func:`film_thickness` (Hamrock & Dowson 1977) and
    :func:`lubrication_regime` (Nijenbanning, Venner & Moes 1994) for contacts of given load,
    radii, entrainment speed and modulus; :meth:`film_thickness` and :meth:`regime` evaluate them
    at the lubricant's η and α_p, which broadcast against the contacts (leading axes: temperature
    states).  Built by :func:`ehl_contacts`; the module functions are these two steps.

    Attributes
    ----------
    Rx, ratio : ndarray   rolling-direction radius [m] and Ry/Rx [-]
    W : ndarray           load parameter Q/(E' Rx²) [-]
    U_eta : ndarray       speed parameter per unit viscosity, U/η = u/(E' Rx) [1/(Pa s)]
    E_prime : ndarray     reduced modulus [Pa]
    loaded : ndarray      Q > 0
    C_min, C_c : ndarray  h_min, h_c at U = G = 1 (Notes of :func:`film_thickness`) [m]; 0 where Q = 0
    lnW : ndarray         ln W, floored at ln 1e-300 [-]
    D : ndarray           Rx/Ry [-]
    consts : tuple        :func:`~thermobear.lubrication.nvm.ln_asymptote_consts` of D
    """

    Rx: np.ndarray
    ratio: np.ndarray
    W: np.ndarray
    U_eta: np.ndarray
    E_prime: np.ndarray
    loaded: np.ndarray
    C_min: np.ndarray
    C_c: np.ndarray
    lnW: np.ndarray
    D: np.ndarray
    consts: tuple

    def film_thickness(self, eta, alpha_p, kind="min", method="hamrock_dowson", check=True):
        """Film thickness [m] at viscosity ``eta`` [Pa s] and pressure–viscosity coefficient
        ``alpha_p`` [1/Pa] (arrays; see :func:`film_thickness` for ``kind`` and ``method``; ``check``
        False: η and α_p already checked, e.g. a lubricant's values)."""
        kinds = kind if isinstance(kind, tuple) else (kind,)
        if not kinds or any(k not in _FILM_KINDS for k in kinds):
            raise InputError("film_thickness kind", kind, 'must be "min" or "central" (or a tuple of them)')
        if method not in ("hamrock_dowson", "seed000_eq15") or (method == "seed000_eq15" and kinds != ("min",)):
            raise InputError("film_thickness method", method, '"hamrock_dowson", or "seed000_eq15" (kind="min")')
        if check:
            eta, alpha_p = _arr("eta", eta, positive=True), _arr("alpha_p", alpha_p, positive=True)
        U, G = eta * self.U_eta, alpha_p * self.E_prime
        out = []
        for k in kinds:
            if method == "seed000_eq15":
                C = np.where(self.loaded, 3.63 * self.W**-0.073 * (1.0 - 0.61 * np.exp(-0.68 * self.ratio))
                             * self.Rx, 0.0)
                out.append(C * U**0.68 * G**0.49)
            elif k == "central":
                out.append(self.C_c * U**0.67 * G**0.53)
            else:
                out.append(self.C_min * U**0.68 * G**0.49)
        return tuple(out) if isinstance(kind, tuple) else out[0]

    def regime(self, eta, alpha_p, check=True) -> Regime:
        """:class:`Regime` of the contacts at ``eta`` [Pa s] and ``alpha_p`` [1/Pa] (≥ 0; ``check`` False:
        already checked)."""
        if check:
            eta, alpha_p = _arr("eta", eta, positive=True), _arr("alpha_p", alpha_p, nonneg=True)
        lnU2 = np.log(np.maximum(eta * (2.0 * self.U_eta), TINY))
        lnM = self.lnW - 0.75 * lnU2
        lnL = np.log(np.maximum(alpha_p * self.E_prime, TINY)) + 0.25 * lnU2
        return _regime_from_ln(lnM, lnL, self.D, self.loaded, False, self.consts)


def ehl_contacts(Q, Rx, Ry, u, E_prime) -> EHLContacts:
    r"""Point contacts prepared for :func:`film_thickness` and :func:`lubrication_regime`.

    Parameters
    ----------
    Q : array_like        normal load [N], >= 0
    Rx, Ry : array_like   reduced radii, rolling / transverse direction [m], Ry >= Rx
    u : array_like        mean entrainment speed (u1+u2)/2 [m/s], >= 0
    E_prime : array_like  reduced modulus E' [Pa]

    Returns
    -------
    EHLContacts  evaluate with ``.film_thickness(eta, alpha_p, kind)`` and ``.regime(eta, alpha_p)``

    Notes
    -----
    For contacts evaluated at many temperatures (coupled and transient solvers): the
    temperature-independent factors are computed once, e.g.

    .. math::

        h_{min} = C_{min}\, U^{0.68} G^{0.49},\qquad
        C_{min} = 3.63\, R_x W^{-0.073} (1 - e^{-0.68\kappa})

    (Hamrock & Dowson 1977), and ln W and the D-terms of the NVM asymptotes (Nijenbanning, Venner
    & Moes 1994) for the regime.

    Examples
    --------
    >>> c = ehl_contacts([4527.0, 0.0], 5.109e-3, 165.1e-3, 6.25, 228e9)
    >>> h = c.film_thickness(0.04, 2.3e-8, kind="central")
    >>> [round(float(v) * 1e6, 2) for v in h], c.regime(0.04, 2.3e-8).code.tolist()
    ([0.69, 0.0], ['EHL', 'IVR'])
    """
    Q, Rx, ratio, u, E_prime = _geometry(Q, Rx, Ry, u, E_prime)
    loaded = Q > 0
    ERx = E_prime * Rx
    W = Q / (E_prime * Rx**2)
    Ws = np.where(loaded, W, 1.0)
    kappa = 1.0339 * ratio**0.636
    C_min = np.where(loaded, 3.63 * Ws**-0.073 * (1.0 - np.exp(-0.68 * kappa)) * Rx, 0.0)
    C_c = np.where(loaded, 2.69 * Ws**-0.067 * (1.0 - 0.61 * np.exp(-0.73 * kappa)) * Rx, 0.0)
    D = 1.0 / ratio
    return EHLContacts(Rx=Rx, ratio=ratio, W=W, U_eta=u / ERx, E_prime=E_prime, loaded=loaded, C_min=C_min,
                       C_c=C_c, lnW=np.log(np.maximum(W, TINY)), D=D, consts=ln_asymptote_consts(D))


# ---------------------------------------------------------------------------
# Hamrock–Dowson
# ---------------------------------------------------------------------------
def hamrock_dowson_groups(Q, Rx, Ry, u, eta, alpha_p, E_prime):
    r"""Dimensionless groups of Hamrock & Dowson (mean-velocity convention).

    Parameters
    ----------
    Q : array_like        normal load [N]
    Rx, Ry : array_like   reduced radii, rolling / transverse direction [m]
    u : array_like        mean entrainment speed (u1+u2)/2 [m/s]
    eta : array_like      inlet dynamic viscosity [Pa s]
    alpha_p : array_like  pressure–viscosity coefficient [1/Pa]
    E_prime : array_like  reduced modulus E' [Pa]

    Returns
    -------
    (U, G, W, kappa) : tuple of float or ndarray
        the speed, material, load parameters and the ellipticity [-]

    Notes
    -----
    .. math::

        U = \frac{\eta u}{E' R_x},\quad G = \alpha_p E',\quad W = \frac{Q}{E' R_x^2},\quad
        \kappa = 1.0339 \left(\frac{R_y}{R_x}\right)^{0.636}

    (Hamrock & Dowson 1977 [1]_; κ of Hamrock & Brewe 1983 [2]_; seed 000 eq 16 and seed 004
    eq 10 write the same U*, G*, W*).

    References
    ----------
    .. [1] Hamrock B. J., Dowson D. (1977) J. Lubr. Technol. 99, 264–276.
    .. [2] Hamrock B. J., Brewe D. E. (1983) J. Lubr. Technol. 105, 171–177.

    Examples
    --------
    >>> U, G, W, k = hamrock_dowson_groups(4527., 5.109e-3, 165.1e-3, 6.25, 0.04, 2.3e-8, 228e9)
    >>> f"{U:.3g} {G:.4g} {W:.3g} {k:.3g}"
    '2.15e-10 5244 0.000761 9.43'
    """
    Qa, Rxa, ratio, ua, etaa, alphaa, Ea = _contact(Q, Rx, Ry, u, eta, alpha_p, E_prime, False)
    U = etaa * ua / (Ea * Rxa)
    G = alphaa * Ea
    W = Qa / (Ea * Rxa**2)
    kappa = 1.0339 * ratio**0.636
    shape = np.broadcast_shapes(*(np.shape(v) for v in (Qa, Rxa, ratio, ua, etaa, alphaa, Ea)))
    return tuple(_out(np.broadcast_to(x, shape), Q) for x in (U, G, W, kappa))


def film_thickness(Q, Rx, Ry, u, eta, alpha_p, E_prime, kind="min", method="hamrock_dowson"):
    r"""EHL film thickness of a point contact [m].

    Parameters
    ----------
    Q : array_like        normal load [N], >= 0
    Rx, Ry : array_like   reduced radii, rolling / transverse direction [m], Ry >= Rx
    u : array_like        mean entrainment speed (u1+u2)/2 [m/s], >= 0
    eta : array_like      inlet dynamic viscosity [Pa s]
    alpha_p : array_like  pressure–viscosity coefficient [1/Pa]
    E_prime : array_like  reduced modulus E' [Pa]
    kind : {"min", "central"} or a tuple of them
        a tuple gives a tuple of films, in that order, from one pass over the inputs
    method : {"hamrock_dowson", "nvm", "seed000_eq15"}
        "hamrock_dowson" (default) — Hamrock & Dowson (1977) [1]_, see Notes;
        "nvm" (central only) — Nijenbanning, Venner & Moes (1994), see :func:`film_thickness_nvm`;
        "seed000_eq15" (min only) — the form PRINTED in seed 000 eq 15 (Ianuș et al.):
        3.63 Rx U^0.68 G^0.49 W^-0.073 (1 − 0.61 e^(−0.68 k)), k = Ry/Rx.  Its ellipticity
        factor differs from Hamrock–Dowson's (1 − e^(−0.68 κ)); for seed 000's k ≈ 17.7
        both are 1 within 1.3 %.  Offered only to reproduce that paper.

    Returns
    -------
    float or ndarray  film thickness [m]; 0 where u = 0 and, by convention, where Q = 0

    Notes
    -----
    With the groups U, G, W, κ of :func:`hamrock_dowson_groups` (Hamrock & Dowson 1977 [1]_, their
    central and minimum film formulas):

    .. math::

        h_c = 2.69\, R_x U^{0.67} G^{0.53} W^{-0.067} (1 - 0.61 e^{-0.73\kappa}),\qquad
        h_{min} = 3.63\, R_x U^{0.68} G^{0.49} W^{-0.073} (1 - e^{-0.68\kappa})

    Fitted for κ ≈ 1–8, isothermal, Newtonian, fully flooded, smooth surfaces [1]_.
    Requires alpha_p > 0 (G = 0 would give a zero film, which is not the
    iso-viscous answer — use method="nvm").

    References
    ----------
    .. [1] Hamrock B. J., Dowson D. (1977) Isothermal elastohydrodynamic lubrication of point
           contacts, Part III. J. Lubr. Technol. 99, 264–276.

    Examples
    --------
    Inner contact of a 209 bearing (Hamrock & Dowson's example inputs, 400 rad/s):

    >>> h = film_thickness(4527., 5.109e-3, 165.1e-3, 6.25, 0.04, 2.3e-8, 228e9, kind="central")
    >>> round(h * 1e6, 2)
    0.69
    >>> [round(v * 1e6, 2) for v in film_thickness(4527., 5.109e-3, 165.1e-3, 6.25, 0.04, 2.3e-8, 228e9,
    ...                                            kind=("min", "central"))]
    [0.55, 0.69]
    """
    kinds = kind if isinstance(kind, tuple) else (kind,)
    if not kinds or any(k not in _FILM_KINDS for k in kinds):
        raise InputError("film_thickness kind", kind, 'must be "min" or "central" (or a tuple of them)')
    if method == "nvm":
        if kinds != ("central",):
            raise InputError("film_thickness method", method, 'NVM gives the central film only: use kind="central"')
        return film_thickness_nvm(Q, Rx, Ry, u, eta, alpha_p, E_prime)
    if method not in ("hamrock_dowson", "seed000_eq15"):
        raise InputError("film_thickness method", method, 'must be "hamrock_dowson", "nvm" or "seed000_eq15"')
    if method == "seed000_eq15" and kinds != ("min",):
        raise InputError("film_thickness method", method, 'seed 000 eq 15 is a minimum film: use kind="min"')
    h = ehl_contacts(Q, Rx, Ry, u, E_prime).film_thickness(eta, alpha_p, kind, method)
    if not _scalar(Q, Rx, Ry, u, eta, alpha_p, E_prime):
        return h
    return tuple(float(v) for v in h) if isinstance(kind, tuple) else float(h)


# ---------------------------------------------------------------------------
# Moes parameters and NVM
# ---------------------------------------------------------------------------
def moes_parameters(Q, Rx, Ry, u, eta, alpha_p, E_prime):
    r"""Moes dimensionless parameters M, L and the radius ratio D.

    Parameters
    ----------
    Q, Rx, Ry, u, eta, alpha_p, E_prime : array_like
        as in :func:`film_thickness` (u is the MEAN entrainment speed [m/s])

    Returns
    -------
    (M, L, D)  M = W (2U)^(-3/4), L = G (2U)^(1/4), D = Rx/Ry ≤ 1 [-]

    Notes
    -----
    Moes (1992); Nijenbanning, Venner & Moes, Wear 176 (1994) 217; seed 004
    eq 9 (with 2U*).  U, G, W are the Hamrock groups of
    :func:`hamrock_dowson_groups`, so 2U is the sum-velocity group.  M = inf
    where u = 0, M = 0 where Q = 0.

    Examples
    --------
    >>> M, L, D = moes_parameters(4527., 5.109e-3, 165.1e-3, 6.25, 0.04, 2.3e-8, 228e9)
    >>> round(M), round(L, 1), round(D, 4)
    (8066, 23.9, 0.0309)
    """
    Qa, Rxa, ratio, ua, etaa, alphaa, Ea = _contact(Q, Rx, Ry, u, eta, alpha_p, E_prime, False)
    Qa, Rxa, ratio, ua, etaa, alphaa, Ea = np.broadcast_arrays(Qa, Rxa, ratio, ua, etaa, alphaa, Ea)
    U2 = 2.0 * etaa * ua / (Ea * Rxa)
    W = Qa / (Ea * Rxa**2)
    moving = U2 > 0
    M = np.where(moving, W * np.where(moving, U2, 1.0) ** -0.75, np.where(Qa > 0, np.inf, 0.0))
    L = alphaa * Ea * U2**0.25
    D = 1.0 / ratio
    return tuple(_out(x, Q, Rx, Ry, u, eta, alpha_p, E_prime) for x in (M, L, D))


def film_thickness_nvm(Q, Rx, Ry, u, eta, alpha_p, E_prime):
    r"""Central film thickness by Nijenbanning, Venner & Moes (1994) [m].

    Parameters
    ----------
    Q, Rx, Ry, u, eta, alpha_p, E_prime : array_like
        as in :func:`film_thickness` (u is the MEAN entrainment speed [m/s];
        alpha_p >= 0 — NVM covers the iso-viscous regimes)

    Returns
    -------
    ndarray  h_c = H Rx (2U)^(1/2) [m]; 0 where u = 0 and (by convention) where Q = 0

    Notes
    -----
    Valid over all four regimes (IVR, IVE, PVR, EHL), unlike Hamrock–Dowson.
    For narrow ellipses (D ≈ 0.03) NVM gives 20–30 % more than Hamrock–Dowson
    (209 inner contact, Hamrock & Dowson's example inputs: 0.92 vs 0.69 µm).

    Examples
    --------
    >>> h = film_thickness_nvm(4527., 5.109e-3, 165.1e-3, 6.25, 0.04, 2.3e-8, 228e9)
    >>> round(h * 1e6, 2)
    0.92
    """
    Qa, Rxa, ratio, ua, etaa, alphaa, Ea = _contact(Q, Rx, Ry, u, eta, alpha_p, E_prime, False)
    U2 = 2.0 * etaa * ua / (Ea * Rxa)
    W = Qa / (Ea * Rxa**2)
    ok = (U2 > 0) & (Qa > 0)
    lnU2 = np.log(np.where(ok, U2, 1.0))
    lnM = np.log(np.where(ok, W, 1.0)) - 0.75 * lnU2
    lnL = np.log(np.maximum(alphaa * Ea, TINY)) + 0.25 * lnU2
    ln_H = _ln_branches(lnM, lnL, 1.0 / ratio)[0]
    ln_h = np.where(ok, ln_H + np.log(Rxa) + 0.5 * lnU2, 0.0)
    return _out(np.where(ok, np.exp(_clip(ln_h, -EXP_MAX, EXP_MAX)), 0.0),
                Q, Rx, Ry, u, eta, alpha_p, E_prime)


# ---------------------------------------------------------------------------
# Specific film thickness
# ---------------------------------------------------------------------------
def composite_roughness(Rq1, Rq2):
    r"""Composite RMS roughness σ = √(Rq1² + Rq2²) [m].

    Examples
    --------
    >>> round(composite_roughness(0.06e-6, 0.03e-6) * 1e6, 5)
    0.06708
    """
    a = _arr("Rq1", Rq1, nonneg=True)
    b = _arr("Rq2", Rq2, nonneg=True)
    return np.hypot(a, b).item() if type(a) is float and type(b) is float else _out(np.hypot(a, b), Rq1, Rq2)


def specific_film_thickness(h, Rq1, Rq2):
    r"""Specific film thickness Λ = h / √(Rq1² + Rq2²) [-].

    Parameters
    ----------
    h : array_like         film thickness, usually h_min [m]
    Rq1, Rq2 : array_like  RMS roughness of the two surfaces [m] (Rq, not Ra)

    Returns
    -------
    ndarray  Λ [-]; rough guide: < 1 boundary, 1–3 mixed, > 3 full film

    Notes
    -----
    Seed 000 eq 19 (Λ with the RMS roughness Rq, not Ra).  Both roughnesses zero raises InputError
    (Λ undefined for ideally smooth surfaces).

    Examples
    --------
    >>> round(specific_film_thickness(0.0953e-6, 0.06e-6, 0.03e-6), 2)
    1.42
    """
    h = _arr("h", h, nonneg=True)
    sigma = composite_roughness(Rq1, Rq2)
    if not (np.min(sigma) if np.ndim(sigma) else sigma) > 0:
        raise InputError("Rq1, Rq2", (Rq1, Rq2), "composite roughness must be > 0 [m] (Lambda undefined for smooth surfaces)")
    return h / sigma if isinstance(h, np.ndarray) and h.ndim else _out(h / sigma, Rq1, Rq2)


# ---------------------------------------------------------------------------
# Regime
# ---------------------------------------------------------------------------
def lubrication_regime(Q, Rx, Ry, u, eta, alpha_p, E_prime):
    r"""Lubrication regime of each contact ("IVR" | "IVE" | "PVR" | "EHL").

    Parameters
    ----------
    Q, Rx, Ry, u, eta, alpha_p, E_prime : array_like
        as in :func:`film_thickness` (u is the MEAN entrainment speed [m/s])

    Returns
    -------
    Regime  codes (str array, or str for scalar input), dominant-term ratios,
            M, L, D and H (see :class:`Regime`, :func:`moes_regime`)

    Notes
    -----
    Q = 0 → "IVR" (no load: rigid, iso-viscous); u = 0 with Q > 0 → the u → 0
    limit ("IVE": iso ∝ U^0.1 beats piezo ∝ U^0.25).

    Examples
    --------
    >>> lubrication_regime([4527., 1e-3], 5.109e-3, 165.1e-3, 6.25, 0.04, 2.3e-8, 228e9).code.tolist()
    ['EHL', 'IVR']
    """
    r = ehl_contacts(Q, Rx, Ry, u, E_prime).regime(eta, alpha_p)
    if not _scalar(Q, Rx, Ry, u, eta, alpha_p, E_prime):
        return r
    return Regime(str(r.code), *(float(getattr(r, f)) for f in ("ln_iso_over_piezo", "ln_RI_over_EI",
                                                                "ln_EP_over_RP", "M", "L", "D")), int(r.index))
