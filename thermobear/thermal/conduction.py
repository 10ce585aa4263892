r"""Conduction in the solids of a thermal network: shells, plane walls, constrictions, joints.

Pure functions (scalars or numpy arrays, broadcast) giving a conductance G [W/K], a resistance
R [K/W] or a joint conductance h [W/(m² K)]:

==============================  ==============================================  ==================================
element                         model                                           function
==============================  ==============================================  ==================================
radial conduction               G = 2π k L / ln(r2/r1)                          :func:`shell_conductance`
mean of a solid cylinder        G = 8π k L (mean temperature ↔ lateral surface)  :func:`solid_cylinder_conductance`
planar conduction               G = k A / ℓ                                     :func:`planar_conductance`
ball–race contact               R = 𝔎(e)/(2π k a) per body per contact          :func:`ball_race_conductance`
rolling ball–race contact       G_r = 2√(2/π) I e a √(b u) (Pe ≫ 1)              :func:`rolling_contact_conductance`
lubricant around a contact      G_m = 2π k √(R_x R_y) ln(h_m/h_0)                :func:`meniscus_conductance`
disk on a large body            G = 4 k a (isothermal disk, a = √(A/π))        :func:`spreading_conductance`
fitted / clamped joint          h = h_contact + h_gap (Mikic; Yovanovich)       :func:`joint_conductance`
press-fit pressure              Lamé thick cylinders                            :func:`fit_pressure`
==============================  ==============================================  ==================================

References
----------
.. [1] Pouly, F., Changenet, C., Ville, F., Velex, P., Damiens, B., 2010, "Power loss predictions
   in high-speed rolling element bearings using thermal networks", Tribology Transactions 53,
   957–967.
.. [2] Bergman, T. L., Lavine, A. S., Incropera, F. P., DeWitt, D. P., 2011, *Fundamentals of Heat
   and Mass Transfer*, 7th ed., Wiley: eq 3.33 (cylindrical shell), eq 3.6 (plane wall), eq 3.53
   (solid cylinder with uniform generation), Table 4.1 case 10 (disk on a semi-infinite medium,
   S = 2D).
.. [3] Yovanovich, M. M., 1971, "Thermal constriction resistance between contacting metallic
   paraboloids", AIAA Progress in Astronautics 24, 337–358; Muzychka, Y. S., Yovanovich, M. M.,
   2001, "Thermal resistance models for non-circular moving heat sources", J. Heat Transfer 123,
   1028–1034 (the elliptical isothermal contact, R = 𝔎(e)/(2π k a)).
.. [4] Mikic, B. B., 1974, "Thermal contact conductance; theoretical considerations", Int. J. Heat
   Mass Transfer 17, 205–214 (plastic contacts, h_c = 1.25 k_s (m/σ)(P/H_c)^0.95, as correlated by
   Yovanovich 1982).
.. [5] Yovanovich, M. M., 2005, "Four decades of research on thermal contact, gap, and joint
   resistance in microelectronics", IEEE Trans. Components and Packaging Technologies 28, 182–206:
   eq 11 (plastic contact conductance), eq 23 (mean plane separation Y of plastic contacts),
   eq 19 (gap conductance h_g = k_g/(Y + M)); Antonetti, V. W., Whittle, T. D., Simons, R. E., 1991,
   "An approximate thermal contact conductance correlation", ASME HTD 170, 35–42 (asperity slope
   m = 0.125 (σ/1 µm)^0.402, 0.216 ≤ σ ≤ 9.6 µm).
.. [6] Budynas, R. G., Nisbett, J. K., 2011, *Shigley's Mechanical Engineering Design*, 9th ed.,
   McGraw-Hill, §3-16 eqs 3-56, 3-57 (pressure of a shrink or press fit, Lamé thick cylinders).
.. [7] Churchill, S. W., Usagi, R., 1972, "A general expression for the correlation of rates of
   transfer and other phenomena", AIChE Journal 18, 1121–1128.
"""
from __future__ import annotations

import numpy as np
from scipy.special import ellipk, gammaln

from thermobear.arrays import checked, out as _out
from thermobear.errors import InputError

__all__ = ["shell_conductance", "solid_cylinder_conductance", "planar_conductance", "constriction_resistance",
           "ball_race_conductance", "rolling_contact_conductance", "thermal_effusivity", "meniscus_conductance", "spreading_conductance", "asperity_slope", "joint_conductance",
           "fit_pressure"]


def shell_conductance(k, L, r1, r2):
    r"""Conductance of radial conduction through a cylindrical shell [W/K].

    Parameters
    ----------
    k : array_like       thermal conductivity [W/(m K)]
    L : array_like       axial length (ring width) [m]
    r1, r2 : array_like  inner and outer radius, 0 < r1 < r2 [m]

    Returns
    -------
    float or ndarray  G [W/K]

    Notes
    -----
    .. math:: G = \frac{2 \pi k L}{\ln(r_2 / r_1)}

    (Bergman et al. 2011 eq 3.33 [2]).

    Examples
    --------
    >>> round(shell_conductance(42.7, 0.02, 0.025, 0.0286), 2)
    39.9
    """
    k, L, r1, r2 = (checked(n, v) for n, v in (("k_W_mK", k), ("L_m", L), ("r1_m", r1), ("r2_m", r2)))
    if np.any(r2 <= r1):
        raise InputError("r2_m", _out(r2), f"outer radius must exceed the inner radius r1_m = {_out(r1)}")
    return _out(2.0 * np.pi * k * L / np.log(r2 / r1))


def planar_conductance(k, A, length):
    r"""Conductance of one-dimensional planar (or axial) conduction [W/K].

    Parameters
    ----------
    k : array_like       thermal conductivity [W/(m K)]
    A : array_like       cross-section normal to the heat flow [m²]
    length : array_like  conduction length ℓ [m]

    Returns
    -------
    float or ndarray  G [W/K]

    Notes
    -----
    .. math:: G = \frac{k A}{\ell}

    (Bergman et al. 2011 eq 3.6 [2]).

    Examples
    --------
    >>> planar_conductance(40.0, 1e-3, 0.1)
    0.4
    """
    return _out(checked("k_W_mK", k) * checked("A_m2", A) / checked("length_m", length))


def constriction_resistance(k, a, b):
    r"""Constriction resistance of one body at an elliptical isothermal contact [K/W].

    Parameters
    ----------
    k : array_like    thermal conductivity of the body [W/(m K)]
    a, b : array_like semi-axes of the Hertz ellipse [m] (either order; the
                      larger one is the major semi-axis)

    Returns
    -------
    float or ndarray  R [K/W]

    Notes
    -----
    .. math:: R = \frac{\mathfrak{K}(m)}{2 \pi k a_{major}}, \quad m = 1 - (a_{minor}/a_{major})^2

    (Yovanovich 1971; Muzychka & Yovanovich 2001 [3]); 𝔎 is the complete elliptic integral of
    the first kind with *parameter* m = e² (``scipy.special.ellipk``).  For a circle 𝔎(0) = π/2
    and R = 1/(4 k a).  Stationary, isothermal contact: at Péclet numbers u b/(2κ) ≫ 1 the moving
    heat source lowers R (a ×2–5 uncertainty, not modelled).

    Examples
    --------
    >>> r = constriction_resistance(40.0, 1e-3, 1e-3)     # circle: 1/(4 k a)
    >>> round(r, 6), round(1 / (4 * 40.0 * 1e-3), 6)
    (6.25, 6.25)
    """
    k, a, b = checked("k_W_mK", k), checked("a_m", a), checked("b_m", b)
    major, minor = np.maximum(a, b), np.minimum(a, b)
    return _out(ellipk(1.0 - (minor / major) ** 2) / (2.0 * np.pi * k * major))


def ball_race_conductance(k_ball, k_ring, a, b, u=None, e_ball=None, e_ring=None, h_film=None, k_film=None):
    r"""Total conductance of the ball–race contacts of one raceway [W/K].

    Parameters
    ----------
    k_ball, k_ring : array_like  conductivities of ball and ring [W/(m K)] (broadcast against
                                 the leading axes of ``a``)
    a, b : array_like            per-ball Hertz semi-axes [m], shape (..., Z), ``a`` across and ``b``
                                 along the rolling direction; a ball with a = 0 or b = 0 is unloaded and
                                 conducts nothing
    u : array_like, optional     per-ball rolling (entrainment) speed [m/s], shape of ``a``: adds the
                                 exchange of the rolling surfaces (:func:`rolling_contact_conductance`);
                                 None: stationary contacts
    e_ball, e_ring : array_like  thermal effusivities √(k ρ c_p) of ball and ring [W s^½/(m² K)]
                                 (needed with ``u``)
    h_film, k_film : array_like, optional  lubricant film in the contacts: thickness [m] (shape of
                                 ``a``) and conductivity [W/(m K)], a plane layer over the ellipse in series

    Returns
    -------
    float or ndarray  G [W/K], summed over the last axis

    Notes
    -----
    One constriction per body (:func:`constriction_resistance`), the two bodies in series, the
    contacts in parallel [1]_, [3]_.  Rolling contacts (``u`` given): the constriction and the rolling
    exchange G_r (the two asymptotes, Péclet number → 0 and ≫ 1) combined as Churchill & Usagi (1972)
    [7]_ combine asymptotes (exponent 2, estimated: at Pe = u b/(2κ) ≥ 10, where G_r ≥ 7 G_s, within 1 %
    of G_r), then the film layer in series:

    .. math:: G = \sum_{balls} \left[\left(G_s^2 + G_r^2\right)^{-1/2}
              + \frac{h}{k_f\,\pi a b}\right]^{-1},
              \qquad G_s = \frac{1}{R_{ball} + R_{ring}}

    Examples
    --------
    >>> G = ball_race_conductance(42.7, 42.7, [1e-3, 1e-3, 0.0], [2e-4, 2e-4, 0.0])
    >>> G1 = 1 / (2 * constriction_resistance(42.7, 1e-3, 2e-4))
    >>> round(G / G1, 12)
    2.0

    A rolling contact (6205 inner race, Fr 400 N, 3000 rpm): ×7 the stationary one, halved by a
    0.3 µm oil film:

    >>> e = thermal_effusivity(42.7, 7830.0, 460.0)
    >>> G0 = ball_race_conductance(42.7, 42.7, 9.06e-4, 8.19e-5)
    >>> G = ball_race_conductance(42.7, 42.7, 9.06e-4, 8.19e-5, u=2.9, e_ball=e, e_ring=e)
    >>> Gf = ball_race_conductance(42.7, 42.7, 9.06e-4, 8.19e-5, u=2.9, e_ball=e, e_ring=e, h_film=3e-7, k_film=0.13)
    >>> round(float(G0), 4), round(float(G), 4), round(float(Gf), 4)
    (0.032, 0.2436, 0.0714)
    """
    a, b = np.broadcast_arrays(np.asarray(a, dtype=float), np.asarray(b, dtype=float))
    checked("contacts.a_m", a, strict=False)
    checked("contacts.b_m", b, strict=False)
    kb = checked("k_W_mK", k_ball)[..., None]
    kr = checked("k_W_mK", k_ring)[..., None]
    loaded = (a > 0) & (b > 0)
    aa, bb = np.where(loaded, a, 1.0), np.where(loaded, b, 1.0)
    G = 1.0 / (constriction_resistance(kb, aa, bb) + constriction_resistance(kr, aa, bb))
    if u is not None:
        if e_ball is None or e_ring is None:
            raise InputError("e_ball, e_ring", None, "the effusivities of ball and ring are needed with a rolling speed u")
        eb, er = (checked("effusivity", e)[..., None] for e in (e_ball, e_ring))
        G = np.hypot(G, rolling_contact_conductance(eb * er / (eb + er), aa, bb, np.abs(np.asarray(u, float))))
    if h_film is not None:
        h = checked("h_film_m", h_film, strict=False)
        G = 1.0 / (1.0 / G + h / (checked("k_film_W_mK", k_film) * np.pi * aa * bb))
    return _out(np.sum(np.where(loaded, G, 0.0), axis=-1))


def meniscus_conductance(k_fluid, Rx, Ry, h0, h_m):
    r"""Conduction through the lubricant filling the gap around a ball–race contact [W/K].

    Parameters
    ----------
    k_fluid : array_like   conductivity of the lubricant [W/(m K)]
    Rx, Ry : array_like    reduced radii of the contact along and across the rolling direction [m]
    h0 : array_like        gap at the contact: its film [m], > 0
    h_m : array_like       gap at which the lubricant meniscus ends [m]; none where h_m ≤ h0

    Returns
    -------
    float or ndarray  G_m [W/K] per contact

    Notes
    -----
    Outside the contact the gap opens as the two surfaces' paraboloid, h = h0 + x²/(2R_x) + y²/(2R_y);
    where it is filled, the heat crosses it by conduction normal to the surfaces (a thin layer, the
    plane wall of Bergman et al. 2011 eq 3.6 [2]_ with the local thickness; the gap's slope is small).
    With x = √R_x ρ cos θ, y = √R_y ρ sin θ the integral of k/h over the filled area is

    .. math::

        G_m = \int \frac{k}{h}\,dA = 2\pi k \sqrt{R_x R_y}\,\ln\frac{h_m}{h_0}

    (the area of the contact itself, where the gap is the film, taken as the annulus's inner edge: the
    rigid paraboloid shifted by the flattened ellipse gives the same integral).  The conforming groove
    (R_y ≫ R_x) makes the filled gap long across the race: it carries more heat than the Hertz contact.
    Where the meniscus ends (h_m) is a property of the lubrication (flooded or starved inlet).  The
    paraboloid holds while the filled region stays inside the groove, √(2 R_y h_m) below the ball's
    radius (a 6205: h_m up to ≈ 58 µm on the inner race, 94 µm on the outer); beyond, the groove's
    shoulders end the region and this overestimates G_m by the logarithm's excess (14 % at 100 µm on
    that inner race, from a 1 µm film).

    Examples
    --------
    A 6205 inner contact (R_x 3 mm, R_y 102 mm) through oil (0.13 W/(m K)) from a 0.9 µm film out
    to a 30 µm gap:

    >>> round(meniscus_conductance(0.13, 3e-3, 0.102, 0.9e-6, 30e-6), 4)
    0.0501
    """
    k, Rx, Ry = checked("k_W_mK", k_fluid), checked("Rx_m", Rx), checked("Ry_m", Ry)
    h0, h_m = checked("h0_m", h0), checked("h_m_m", h_m)
    return _out(2.0 * np.pi * k * np.sqrt(Rx * Ry) * np.log(np.maximum(h_m / h0, 1.0)))


#: ∫₋₁¹ (1 − η²)^¼ dη = √π Γ(5/4)/Γ(7/4): the ellipse's mean of the square root of its chord
_CHORD_QUARTER = float(np.sqrt(np.pi) * np.exp(gammaln(1.25) - gammaln(1.75)))


def thermal_effusivity(k, rho, cp):
    r"""Thermal effusivity √(k ρ c_p) of a solid [W s^½/(m² K)].

    Parameters
    ----------
    k : array_like     thermal conductivity [W/(m K)]
    rho : array_like   density [kg/m³]
    cp : array_like    specific heat [J/(kg K)]

    Returns
    -------
    float or ndarray  e [W s^½/(m² K)]

    Notes
    -----
    .. math:: e = \sqrt{k \rho c_p}

    the property that sets the heat a suddenly heated surface takes up (Bergman et al. 2011 §5.7 [2]_).

    Examples
    --------
    >>> round(thermal_effusivity(42.7, 7830.0, 460.0))
    12401
    """
    return _out(np.sqrt(checked("k_W_mK", k) * checked("rho_kg_m3", rho) * checked("cp_J_kgK", cp)))


def rolling_contact_conductance(e_eff, a, b, u):
    r"""Heat exchange of two surfaces rolling through an elliptical contact, per contact [W/K].

    Parameters
    ----------
    e_eff : array_like  e₁e₂/(e₁ + e₂) of the two bodies' effusivities [W s^½/(m² K)]
                        (:func:`thermal_effusivity`)
    a, b : array_like   semi-axes of the contact across and along the rolling direction [m], > 0
    u : array_like      rolling speed of both surfaces through the contact [m/s], ≥ 0

    Returns
    -------
    float or ndarray  G_r [W/K]

    Notes
    -----
    At Péclet numbers Pe = u b/(2κ) ≫ 1 a surface point crosses the contact in t = L/u, too short
    for the heat to penetrate more than √(κ t) ≪ b: each body is a semi-infinite solid entering the
    contact at its own temperature, and two such solids in contact exchange, from the moment of
    contact t, the flux q = e_eff ΔT/√(π t) at a constant interface temperature (Bergman et al. 2011
    §5.7 [2]_: the surface flux of a semi-infinite solid at a suddenly changed surface temperature,
    and the interface temperature of two semi-infinite solids in contact).  Integrated over the
    passage of each chord L(y) = 2b √(1 − y²/a²) of the ellipse:

    .. math::

        G_r = \int_{-a}^{a} \int_0^{L(y)} \frac{e_{eff}}{\sqrt{\pi x / u}}\,dx\,dy
            = 2 \sqrt{\frac{2}{\pi}}\, I\, e_{eff}\, a \sqrt{b u},
        \qquad I = \int_{-1}^{1} (1 - \eta^2)^{1/4} d\eta = \frac{\sqrt{\pi}\,\Gamma(5/4)}{\Gamma(7/4)}

    The surfaces are taken to enter at their bodies' node temperatures: the track's own periodic heating
    between passes is not modelled, so this is the upper bound of the exchange (the stationary
    constriction, :func:`constriction_resistance`, the lower one).  It vanishes as √u at rest, where
    the stationary constriction takes over (:func:`ball_race_conductance`).

    Examples
    --------
    Steel on steel (e = 12 401), a 1.8 mm × 0.16 mm contact at 2.9 m/s (Pe ≈ 10):

    >>> round(rolling_contact_conductance(12401.0 / 2, 9.06e-4, 8.19e-5, 2.9), 4)
    0.2415
    """
    e_eff, a, b = checked("e_eff", e_eff), checked("a_m", a), checked("b_m", b)
    u = checked("u_m_s", u, strict=False)
    return _out(2.0 * np.sqrt(2.0 / np.pi) * _CHORD_QUARTER * e_eff * a * np.sqrt(b * u))


def solid_cylinder_conductance(k, L):
    r"""Conductance between the mean temperature of a solid cylinder and its lateral surface [W/K].

    Parameters
    ----------
    k : array_like   thermal conductivity [W/(m K)]
    L : array_like   length [m]

    Returns
    -------
    float or ndarray  G [W/K]

    Notes
    -----
    Heat crossing the lateral surface and spreading through the volume (entering at the surface
    and leaving axially, or stored) gives the parabolic profile of uniform generation,
    T(r) = T_s + q̇ (r_o² − r²)/(4k) (Bergman et al. 2011 eq 3.53 [2]_); its area mean lies
    q̇ r_o²/(8k) above the surface, and with the heat Q = q̇ π r_o² L:

    .. math:: G = \frac{Q}{\bar T - T_s} = 8 \pi k L

    independent of the radius.

    Examples
    --------
    >>> round(solid_cylinder_conductance(42.7, 0.02), 4)      # 8 pi k L
    21.4634
    """
    return _out(8.0 * np.pi * checked("k_W_mK", k) * checked("L_m", L))


def spreading_conductance(k, A):
    r"""Conductance from an isothermal disk on the surface of a large body into its far field [W/K].

    Parameters
    ----------
    k : array_like   conductivity of the body [W/(m K)]
    A : array_like   contact area (taken as a disk of the same area) [m²]

    Returns
    -------
    float or ndarray  G [W/K]

    Notes
    -----
    Shape factor S = 2D of a disk of diameter D on a semi-infinite medium (Bergman et al. 2011
    Table 4.1 case 10 [2]_), with the disk of the same area, a = √(A/π):

    .. math:: G = k S = 4 k a = 4 k \sqrt{A/\pi}

    A housing foot bolted to a machine frame: the frame far from the foot at its own temperature.

    Examples
    --------
    >>> round(spreading_conductance(50.0, np.pi * 0.05**2), 6)    # 4 k a, a = 50 mm
    10.0
    """
    return _out(4.0 * checked("k_W_mK", k) * np.sqrt(checked("A_m2", A) / np.pi))


def asperity_slope(sigma):
    r"""Mean absolute asperity slope of a bead-blasted or ground metal surface pair [-].

    Parameters
    ----------
    sigma : array_like   RMS roughness of the pair, σ = √(σ1² + σ2²) [m] (0.216–9.6 µm)

    Returns
    -------
    float or ndarray  m [-]

    Notes
    -----
    Antonetti et al. 1991 (as used by Yovanovich 2005 [5]_):

    .. math:: m = 0.125 \left(\frac{\sigma}{1\,\mu m}\right)^{0.402}

    Examples
    --------
    >>> round(asperity_slope(1e-6), 3)
    0.125
    """
    return _out(0.125 * (checked("sigma_m", sigma) * 1e6) ** 0.402)


def joint_conductance(k1, k2, P, sigma, H_c, k_gap, M=0.0):
    r"""Conductance of a metallic joint with a gas or liquid in its gaps [W/(m² K)].

    Parameters
    ----------
    k1, k2 : array_like  conductivities of the two solids [W/(m K)]
    P : array_like       apparent contact pressure, ≥ 0 [Pa] (0: the gap alone)
    sigma : array_like   RMS roughness of the pair √(σ1² + σ2²) [m]
    H_c : array_like     microhardness of the softer solid [Pa]
    k_gap : array_like   conductivity of the substance in the gaps [W/(m K)]
    M : array_like       gas rarefaction parameter [m] (0 for a liquid; ≈ 0.3 µm for air at 1 atm)

    Returns
    -------
    float or ndarray  h_j = h_c + h_g [W/(m² K)]

    Notes
    -----
    Plastically deformed Gaussian asperities (Mikic 1974 [4]_; Yovanovich 2005 eqs 11, 19, 23
    [5]_), the gaps in parallel:

    .. math:: h_c = 1.25\, k_s \frac{m}{\sigma} \left(\frac{P}{H_c}\right)^{0.95}, \quad
              k_s = \frac{2 k_1 k_2}{k_1 + k_2}, \quad m = 0.125 (\sigma / 1\mu m)^{0.402}

    .. math:: h_g = \frac{k_g}{Y + M}, \quad Y = 1.184\, \sigma \left[-\ln\left(3.132 \frac{P}{H_c}
              \right)\right]^{0.547}

    At P → 0 the surfaces separate: Y is held at its value at P/H_c = 1e-6 (Y ≈ 4.7 σ), the
    limit of the correlation's range (10⁻⁶ ≤ P/H_c ≤ 2·10⁻²).

    Examples
    --------
    >>> h = joint_conductance(45.0, 45.0, 10e6, 1e-6, 3e9, 0.026, 0.3e-6)
    >>> round(h, -2)
    39800.0
    """
    k1, k2, sigma, H_c = (checked(n, v) for n, v in (("k1_W_mK", k1), ("k2_W_mK", k2), ("sigma_m", sigma),
                                                       ("H_c_Pa", H_c)))
    P, k_gap, M = checked("P_Pa", P, strict=False), checked("k_gap_W_mK", k_gap), checked("M_m", M, strict=False)
    ratio = np.clip(P / H_c, 1e-6, 2e-2)
    if np.any(P / H_c > 2e-2):
        raise InputError("P_Pa", _out(P), f"contact pressure above 2 % of the microhardness {_out(H_c)} Pa "
                         "(outside the plastic-contact correlation)")
    ks = 2.0 * k1 * k2 / (k1 + k2)
    m = 0.125 * (sigma * 1e6) ** 0.402
    h_c = np.where(P > 0, 1.25 * ks * m / sigma * (P / H_c) ** 0.95, 0.0)
    Y = 1.184 * sigma * (-np.log(3.132 * ratio)) ** 0.547
    return _out(h_c + k_gap / (Y + M))


def fit_pressure(delta, d, d_inner, d_outer, E_shaft, nu_shaft, E_hub, nu_hub):
    r"""Contact pressure of an interference fit of a shaft (or ring) in a hub [Pa].

    Parameters
    ----------
    delta : array_like             diametral interference, ≥ 0 [m]
    d : array_like                 nominal diameter of the fit [m]
    d_inner : array_like           bore of the inner member, 0 ≤ d_inner < d (0: solid shaft) [m]
    d_outer : array_like           outside diameter of the outer member, > d [m]
    E_shaft, nu_shaft : array_like Young's modulus [Pa] and Poisson's ratio of the inner member
    E_hub, nu_hub : array_like     the same of the outer member

    Returns
    -------
    float or ndarray  p [Pa]

    Notes
    -----
    Lamé thick cylinders (Budynas & Nisbett 2011 eq 3-56 [6]_):

    .. math:: p = \frac{\delta}{d \left[\frac{1}{E_o}\left(\frac{d_o^2 + d^2}{d_o^2 - d^2} + \nu_o\right)
              + \frac{1}{E_i}\left(\frac{d^2 + d_i^2}{d^2 - d_i^2} - \nu_i\right)\right]}

    which for one material and a solid shaft is p = E δ (d_o² − d²)/(2 d d_o²) (eq 3-57).

    Examples
    --------
    >>> p = fit_pressure(13.5e-6, 0.040, 0.0, 0.0473, 210e9, 0.3, 210e9, 0.3)
    >>> round(p / 1e6, 2)
    10.09
    """
    delta = checked("delta_m", delta, strict=False)
    d, d_o = checked("d_m", d), checked("d_outer_m", d_outer)
    d_i = checked("d_inner_m", d_inner, strict=False)
    if np.any(d_o <= d):
        raise InputError("d_outer_m", _out(d_o), f"must exceed the fit diameter {_out(d)} m")
    if np.any(d_i >= d):
        raise InputError("d_inner_m", _out(d_i), f"must be below the fit diameter {_out(d)} m")
    Eo, no, Ei, ni = (checked(n, v) for n, v in (("E_hub_Pa", E_hub), ("nu_hub", nu_hub), ("E_shaft_Pa", E_shaft),
                                                   ("nu_shaft", nu_shaft)))
    return _out(delta / (d * ((d_o**2 + d**2) / (d_o**2 - d**2) + no) / Eo
                         + d * ((d**2 + d_i**2) / (d**2 - d_i**2) - ni) / Ei))
