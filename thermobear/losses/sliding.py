r"""Local sliding, pivoting and hysteresis losses of ball–race contacts.

The local model of seed 000 (Ianuș et al.; after Harris 1991 and Houpert 1999)
and seed 001 (Bălan et al. 2015, Appendices A–B), with seed 004's simple form:

* friction coefficient in mixed lubrication from Λ (seed 000 eq 18; seed 001
  App. A load sharing);
* sliding speed on slices across the contact ellipse (seed 000 eqs 3–8, 13–14);
* sliding power with the Hertz traction distribution (seed 000 eqs 31–33),
  vectorised Gauss–Legendre over all contacts at once;
* pivoting moment MP (seed 000 eq 28, seed 001 eq 11), hysteresis moment MER
  (seed 000 eq 25), ball inertia force (eq 24);
* ball force/moment balance, traction forces and race torque of a thrust ball
  bearing (seed 000 eqs 26–30; seed 001 App. B) and the power both ways
  (eqs 34–36).

x is the coordinate along the major semi-axis a of the contact ellipse
(across the rolling direction; for a thrust race it is radial, positive away
from the bearing axis).  SI throughout.

Two errata of seed 000 are handled here (evidence in
validation/report/seed000_table1.md):

1. Eq 32 prints the traction per unit length as (3/4)(μQ/a)√(1-(x/a)²), which
   integrates to (3π/8) μQ, not μQ, and eq 31 carries an extra 1/a (W/m).  The
   Hertz strip load (3Q/4a)(1-(x/a)²) integrates to Q and reproduces eq 28,
   MP = (3/8) μ Q a, exactly for a pure pivoting slip ω_p x — so it is the
   default (``profile="hertz"``); the printed form is ``profile="seed000"``.
2. Eq 14 adds ω_p x to the slip of eq 3, but eq 3 is written in the cage frame
   where the race speed (dm/2 + x) ω_c already contains the pivoting ω_c x, so
   eq 14 counts it twice.  With eq 3 alone the power method equals the torque
   method (eqs 35–36) to 1e-6; with eq 14 it exceeds it by one pivoting power
   per contact.  Table 1's P_s matches eq 3 alone.
"""
from __future__ import annotations

import numpy as np

from thermobear.arrays import checked as _num, out as _out

from thermobear.errors import InputError

__all__ = [
    "mixed_friction_ianus", "asperity_load_share", "mixed_friction_balan",
    "deformed_radius", "ball_radius_to_contact", "sliding_speed", "sliding_speed_thrust",
    "total_sliding_speed", "hertz_strip_load", "sliding_power", "sliding_power_simple",
    "sliding_power_heathcote", "pivoting_moment", "hysteresis_moment", "ball_mass", "ball_inertia_force",
    "traction_forces", "tangential_force_upper", "thrust_race_torque", "ball_rolling_power",
    "LAMBDA_FULL_FILM_BALAN",
]


# ----------------------------------------------------------------------------- friction coefficient
def mixed_friction_ianus(Lambda, mu_e=0.05, mu_a=0.11, *, check=True):
    r"""Friction coefficient in mixed lubrication from the film parameter (seed 000 eq 18) [-].

    Parameters
    ----------
    Lambda : array_like   film parameter h_min/√(Rq1² + Rq2²) [-], ≥ 0; +inf (smooth
                          surfaces) gives the full-film value μ_e
    mu_e : array_like     full-film (EHL) coefficient [-]
    mu_a : array_like     boundary (asperity) coefficient [-]
    check : bool          False: Λ already known to be ≥ 0 (e.g. films over roughnesses): skip the check

    Returns
    -------
    float or ndarray  μ [-]

    Notes
    -----
    .. math::

        \mu = \mu_e \varphi + \mu_a (1 - \varphi),\qquad \varphi = \min(0.82\,\Lambda^{0.28}, 1)

    (seed 000 eq 18, after Bălan et al. 2015).  The cap: unclipped, φ > 1 for Λ > 2.03 and μ would
    fall below μ_e (0.048, 0.043, 0.039 at Λ = 2.26, 2.96, 3.6), whereas seed 000 Table 1 lists
    μ = 0.05 there — so φ is the film-borne load share, ≤ 1.

    Examples
    --------
    >>> round(mixed_friction_ianus(1.42), 4), mixed_friction_ianus(3.6), mixed_friction_ianus(float("inf"))
    (0.0557, 0.05, 0.05)
    """
    L = np.asarray(Lambda, dtype=float)
    if check and L.size and not L.min() >= 0.0:        # NaN fails too; +inf is the smooth limit
        raise InputError("Lambda", Lambda, "must be >= 0 (film parameter)")
    phi = np.minimum(0.82 * L**0.28, 1.0)
    return _out(np.asarray(mu_e) * phi + np.asarray(mu_a) * (1.0 - phi))


#: Film parameter beyond which :func:`asperity_load_share` is held at zero:
#: the minimum of 1 - 1.21 Λ^0.64/(1 + 0.37 Λ^1.26), Λ = (0.64/(0.37·0.62))^(1/1.26).
LAMBDA_FULL_FILM_BALAN = (0.64 / (0.37 * 0.62)) ** (1.0 / 1.26)


def asperity_load_share(Lambda):
    r"""Share Q_a/Q of the normal load carried by asperities (seed 001 App. A) [-].

    Parameters
    ----------
    Lambda : array_like   film parameter [-]

    Notes
    -----
    Q_a/Q = 1 - 1.21 Λ^0.64/(1 + 0.37 Λ^1.26)  (seed 001 App. A; its OCR lost
    the minus sign; Λ = 0 gives 1).  The fit reaches its minimum (-0.0025) at
    Λ = 2.258 and rises again beyond (0.11 at Λ = 5, 0.32 at 10), which is an
    artefact: asperity load cannot grow with film thickness.  We clip to
    [0, 1] and hold 0 for Λ ≥ :data:`LAMBDA_FULL_FILM_BALAN` (seed 001 tested
    0.3 ≤ Λ ≤ 3.2).

    Examples
    --------
    >>> round(asperity_load_share(0.5), 3), asperity_load_share(0.0), asperity_load_share(5.0)
    (0.327, 1.0, 0.0)
    """
    L = _num("Lambda", Lambda, strict=False, what=" (film parameter)")
    share = 1.0 - 1.21 * L**0.64 / (1.0 + 0.37 * L**1.26)
    return _out(np.where(L >= LAMBDA_FULL_FILM_BALAN, 0.0, np.clip(share, 0.0, 1.0)))


def mixed_friction_balan(Lambda, mu_ehl=0.03, mu_a=0.11):
    r"""Friction coefficient from the asperity load share (seed 001 App. A) [-].

    Notes
    -----
    μ = μ_EHL (1 - Q_a/Q) + μ_a Q_a/Q with :func:`asperity_load_share`;
    seed 001 uses μ_EHL = 0.03, μ_a = 0.11.

    >>> round(mixed_friction_balan(0.5), 4), mixed_friction_balan(3.0)
    (0.0562, 0.03)
    """
    s = np.asarray(asperity_load_share(Lambda))
    return _out(np.asarray(mu_ehl) * (1.0 - s) + np.asarray(mu_a) * s)


# ----------------------------------------------------------------------------- speeds across the ellipse
def deformed_radius(D, f):
    r"""Radius of the deformed contact surface across the groove, R_a (seed 000 eq 8) [m].

    Parameters
    ----------
    D : array_like   ball diameter [m]
    f : array_like   race osculation r_groove/D (> 0.5) [-]

    Notes
    -----
    R_a = D 2f/(2f + 1) = 2 r D/(2r + D), r = f D  (Harris 1991; seed 000 eq 8):
    the harmonic mean of groove radius and ball radius.

    >>> round(deformed_radius(7.938e-3, 0.53) * 1e3, 4)
    4.0847
    """
    D = _num("D", D, what=" (ball diameter) [m]")
    f = _num("f", f, lo=0.5, what=" (osculation r/D)")
    return _out(D * 2.0 * f / (2.0 * f + 1.0))


def ball_radius_to_contact(x, D, f, a):
    r"""Distance from the ball rotation axis to the deformed contact surface, B(x) [m].

    Parameters
    ----------
    x : array_like   position along the major semi-axis, |x| ≤ a [m]
    D : array_like   ball diameter [m]
    f : array_like   race osculation [-]
    a : array_like   major semi-axis of the contact ellipse [m]

    Notes
    -----
    B(x) = √(R_a² - x²) - √(R_a² - a²) + √((D/2)² - a²)  (Harris 1991;
    seed 000 eq 7), R_a from :func:`deformed_radius`; valid when the ball axis
    is parallel to the major axis (thrust ball, or radial contact at α = 0).

    >>> round(ball_radius_to_contact(0.0, 7.938e-3, 0.53, 0.1235e-3) * 1e3, 5)
    3.96895
    """
    x = np.asarray(x, dtype=float)
    a = _num("a", a, strict=False, what=" [m]")
    D = _num("D", D, what=" [m]")
    if np.any(np.abs(x) > a * (1 + 1e-12) + 1e-15):
        raise InputError("x", x, "must lie within the contact, |x| <= a")
    if np.any(a >= D / 2):
        raise InputError("a", a, "semi-axis must be smaller than the ball radius D/2")
    Ra = np.asarray(deformed_radius(D, f))
    return _out(np.sqrt(Ra**2 - x**2) - np.sqrt(Ra**2 - a**2) + np.sqrt((D / 2) ** 2 - a**2))


def sliding_speed(r_race, omega_race, B, omega_ball):
    r"""Slip speed in the rolling direction on a slice, race minus ball (seed 000 eqs 3, 6) [m/s].

    Parameters
    ----------
    r_race : array_like      distance of the race surface point from the race's rotation axis [m]
    omega_race : array_like  race angular speed relative to the cage [rad/s]
    B : array_like           distance of the ball surface point from the ball's axis [m]
    omega_ball : array_like  ball angular speed about its own axis (cage frame) [rad/s]

    Notes
    -----
    v_s = r_race ω_race - B ω_ball.  In the cage frame the race term already
    contains the race's spin about the contact normal (pivoting).

    >>> round(sliding_speed(0.018, 20.944, 3.969e-3, 94.98), 5)   # race 0.37699, ball 0.37698 m/s
    1e-05
    """
    return _out(np.asarray(r_race, float) * np.asarray(omega_race, float)
                - np.asarray(B, float) * np.asarray(omega_ball, float))


def sliding_speed_thrust(x, dm, omega_race, omega_ball, D, f, a):
    r"""Slip speed across the contact of a thrust ball bearing (seed 000 eqs 3–8) [m/s].

    Parameters
    ----------
    x : array_like           radial position in the contact, |x| ≤ a, + outward [m]
    dm : array_like          pitch diameter [m]
    omega_race : array_like  race speed relative to the cage: ω_c for a fixed race,
                             ω_race - ω_c for a rotating one [rad/s]
    omega_ball : array_like  ball speed about its radial axis [rad/s]
    D, f, a : array_like     ball diameter [m], osculation [-], major semi-axis [m]

    Notes
    -----
    v_s(x) = (dm/2 + x) ω_race - ω_ball B(x)  (seed 000 eqs 3–7).  It contains
    the pivoting slip ω_c x; do not add eq 14's ω_p x again (module notes).

    Examples
    --------
    400 rpm in seed 000 (ω_c = 20.944, ω_b = ω_c dm/D rad/s): slip ≈ ω_c x at the
    edges (± 2.588 mm/s), plus the curvature term ω_b x²/(2 R_a):

    >>> wc = 20.944; v = sliding_speed_thrust([-1.2355e-4, 0.0, 1.2355e-4], 0.036, wc, wc * 36 / 7.938,
    ...                                        7.938e-3, 0.53, 1.2355e-4)
    >>> [round(float(s) * 1e3, 3) for s in v]
    [-2.405, 0.005, 2.77]
    """
    x = np.asarray(x, dtype=float)
    B = ball_radius_to_contact(x, D, f, a)
    return sliding_speed(np.asarray(dm, float) / 2 + x, omega_race, B, omega_ball)


def total_sliding_speed(v_s, omega_p, x):
    r"""Seed 000 eq 14 as printed: v_t = v_s + ω_p x [m/s].

    Kept for reproduction only: with v_s from eq 3 in the cage frame this counts
    the pivoting twice (module notes); :func:`sliding_power` should get v_s.

    >>> total_sliding_speed(0.001, 20.0, 1e-4)
    0.003
    """
    return _out(np.asarray(v_s, float) + np.asarray(omega_p, float) * np.asarray(x, float))


# ----------------------------------------------------------------------------- sliding power
def hertz_strip_load(x, Q, a):
    r"""Normal load per unit length across the contact (Hertz strip) [N/m].

    q(x) = (3Q/4a)(1 - (x/a)²), the Hertz pressure integrated along the
    rolling direction; ∫ q dx over (-a, a) = Q.  Multiply by μ for traction
    (Houpert 1999; seed 000 eq 32 corrected — module notes).

    >>> round(hertz_strip_load(0.0, 1.42, 1.2355e-4), 1)
    8620.0
    """
    x, Q = np.asarray(x, float), _num("Q", Q, strict=False, what=" [N]")
    a = _num("a", a, what=" [m]")
    return _out(np.where(np.abs(x) <= a, 0.75 * Q / a * (1.0 - (x / a) ** 2), 0.0))


def _gl_halves(n):
    """Gauss–Legendre nodes on [-1, 0] ∪ [0, 1] (n per half): the |v| kink sits at x ≈ 0."""
    t, w = np.polynomial.legendre.leggauss(n)
    return np.concatenate([(t - 1.0) / 2.0, (t + 1.0) / 2.0]), np.concatenate([w, w]) / 2.0


def sliding_power(speed, mu, Q, a, *, n=24, profile="hertz"):
    r"""Sliding power of contacts, slip integrated across the ellipse (seed 000 eqs 31–32) [W].

    Parameters
    ----------
    speed : callable or array_like
        slip speed v(x) [m/s]: a function of the positions ``x`` (array of
        shape ``(2n, *contacts)``) returning the same shape, or a constant
        (pure rigid slip).
    mu : array_like   friction coefficient per contact [-]
    Q : array_like    normal load per contact [N]
    a : array_like    major semi-axis per contact [m]
    n : int           Gauss–Legendre nodes on each half of the contact
    profile : str     ``"hertz"`` (q = (3Q/4a)(1 - ξ²), ∫ = Q) or ``"seed000"``
                      (eq 32 as printed, (3Q/4a)√(1 - ξ²), ∫ = 3πQ/8)

    Returns
    -------
    ndarray  P = ∫ |v(x)| μ q(x) dx over (-a, a), one value per contact [W]

    Notes
    -----
    Eq 31 of seed 000 carries a prefactor 1/a that makes it W/m; it is dropped
    here (module notes).  For pure pivoting v = ω_p x, P = MP ω_p with
    MP = (3/8) μ Q a (eq 28) exactly.  Split rule: the integrand's kink at the
    contact centre falls on a node boundary.

    Examples
    --------
    >>> round(sliding_power(lambda x: 20.944 * x, 0.05, 1.42, 1.2355e-4), 10)   # = MP ω_p
    6.88e-05
    """
    if profile not in ("hertz", "seed000"):
        raise InputError("profile", profile, "must be 'hertz' or 'seed000'")
    mu = _num("mu", mu, strict=False, what=" (friction coefficient)")
    Q = _num("Q", Q, strict=False, what=" [N]")
    a = _num("a", a, strict=False, what=" [m]")
    shape = np.broadcast_shapes(mu.shape, Q.shape, a.shape)
    xi, w = _gl_halves(int(n))
    ex = (slice(None),) + (None,) * len(shape)
    x = xi[ex] * np.broadcast_to(a, shape)[None]
    v = speed(x) if callable(speed) else np.broadcast_to(np.asarray(speed, float), shape)[None]
    v = np.broadcast_to(v, x.shape)
    shape_fn = (1.0 - xi**2) if profile == "hertz" else np.sqrt(1.0 - xi**2)
    integral = np.sum((w * 0.75 * shape_fn)[ex] * np.abs(v), axis=0)   # ∫ |v| (3/4) s(ξ) dξ
    return _out(mu * Q * integral)


def sliding_power_simple(mu, Q, v_sl):
    r"""Sliding power of a contact with a uniform slip, P = μ Q |v_sl| (seed 004 eqs 15–16) [W].

    >>> sliding_power_simple(0.05, 100.0, 0.2)
    1.0
    """
    return _out(np.asarray(mu, float) * _num("Q", Q, strict=False) * np.abs(np.asarray(v_sl, float)))


#: ξ0: root of ξ − ξ³/3 = 1/3, the pure-rolling points x = ±ξ0 a of the Hertz strip load (Heathcote slip)
XI0_HEATHCOTE = 0.3473
_GL32_X, _GL32_W = np.polynomial.legendre.leggauss(32)
_GL32_HALF = _GL32_X > 0                # the integrand is even in x: the 16 positive nodes, twice
_HEATHCOTE_XI2 = _GL32_X[_GL32_HALF] ** 2
_HEATHCOTE_W = 2.0 * _GL32_W[_GL32_HALF] * 0.75 * (1.0 - _HEATHCOTE_XI2)


def sliding_power_heathcote(mu, Q, a, Ra, omega_roll):
    r"""Sliding power of Heathcote micro-slip across the major axis of a ball–race contact [W].

    Parameters
    ----------
    mu : array_like          friction coefficient [-]
    Q : array_like           normal load [N]
    a : array_like           major semi-axis of the contact ellipse (across rolling) [m]
    Ra : array_like          radius of the deformed contact surface across the groove [m]
                             (:func:`deformed_radius`)
    omega_roll : array_like  ball rolling speed about the axis parallel to the major axis [rad/s]

    Returns
    -------
    float or ndarray  P [W]

    Notes
    -----
    The rolling radius of the ball varies across the groove-shaped contact, B(x) (seed 000
    eqs 7–8, after Harris 1991), so only two lines roll without slip (Heathcote 1921 [1]_);
    elsewhere the surfaces slip at ω_roll (B(x0) − B(x)).  With the Hertz strip load
    q = (3Q/4a)(1 − ξ²) (seed 000 eq 32 corrected, module notes) and friction balance of the
    traction, the pure-rolling points are ξ0 = ±0.3473 (root of ξ − ξ³/3 = 1/3):

    .. math::

        P = \int_{-a}^{a} \mu\, q(x)\, \left|\omega_{roll}\,
        \left(\sqrt{R_a^2 - x^2} - \sqrt{R_a^2 - x_0^2}\right)\right| dx,\qquad x_0 = \xi_0 a

    evaluated with 32-point Gauss–Legendre over the whole width (the kinks at ±x0 are mild: error
    < 1e-4 relative).  P is linear in μ.

    References
    ----------
    .. [1] Heathcote H. L. (1921) The ball bearing: in the making, under test and on service.
           Proc. Inst. Automobile Engineers 15, 569–702 (reference recalled, not checked here).

    Examples
    --------
    Seed 000 contact (a 0.1235 mm, R_a 4.085 mm) rolling at 24 rad/s, μ = 0.05: half a µW.

    >>> round(sliding_power_heathcote(0.05, 1.42, 1.2355e-4, 4.0847e-3, 23.74) * 1e6, 3)
    0.507
    """
    mu = _num("mu", mu, strict=False, what=" (friction coefficient)")
    Q = _num("Q", Q, strict=False, what=" [N]")
    a = _num("a", a, strict=False, what=" [m]")
    Ra = _num("Ra", Ra, what=" [m]")
    nd = max(mu.ndim, Q.ndim, a.ndim, Ra.ndim, np.ndim(omega_roll))
    col = (-1,) + (1,) * nd
    a2, Ra2 = a * a, Ra * Ra
    dB = np.sqrt(np.maximum(Ra2 - _HEATHCOTE_XI2.reshape(col) * a2, 0.0))
    dB -= np.sqrt(np.maximum(Ra2 - XI0_HEATHCOTE**2 * a2, 0.0))
    # Σ w 0.75 (1 − ξ²) |dB| (einsum: no BLAS threads, which spin against other work on a busy machine)
    integral = np.einsum("k,k...->...", _HEATHCOTE_W, np.abs(dB, out=dB))
    return _out(mu * Q * np.abs(omega_roll) * integral)


# ----------------------------------------------------------------------------- moments
def pivoting_moment(mu, Q, a, ratio_RyRx=None):
    r"""Pivoting (spin) friction moment about the contact normal, MP [N m].

    Parameters
    ----------
    mu : array_like          friction coefficient [-]
    Q : array_like           normal load [N]
    a : array_like           major semi-axis [m]
    ratio_RyRx : array_like, optional   k = Ry/Rx; if given, seed 001's k-dependent form

    Notes
    -----
    Large k (seed 000 eq 28; Houpert 1999): MP = (3/8) μ Q a.
    Any k (seed 001 eq 11, signs restored):
    MP = [3/8 + (3π/16 - 3/8) k^(-0.945 - 0.016 ln k)] μ Q a,
    3π/16 μ Q a for a circle (k = 1).  The exact ∬ μ p r dA over the Hertz
    ellipse (slip ∝ distance from the centre) is (3/8) E(1 - b²/a²) μ Q a, E the
    complete elliptic integral; eq 11 is within 0.3 % of it for k = 1–50
    (tests/test_sliding.py); at k = 17.7 the large-k value 3/8 is 3.3 % low.

    Examples
    --------
    >>> round(pivoting_moment(0.05, 1.42, 1.2355e-4) * 1e6, 3)
    3.289
    >>> round(pivoting_moment(0.05, 1.42, 1.2355e-4, 17.667) * 1e6, 3)
    3.399
    """
    mu = _num("mu", mu, strict=False)
    Q = _num("Q", Q, strict=False, what=" [N]")
    a = _num("a", a, strict=False, what=" [m]")
    if ratio_RyRx is None:
        c = 0.375
    else:
        k = _num("ratio_RyRx", ratio_RyRx, lo=1.0, strict=False, what=" (Ry/Rx)")
        c = 0.375 + (3.0 * np.pi / 16.0 - 0.375) * k ** (-0.945 - 0.016 * np.log(k))
    return _out(c * mu * Q * a)


def hysteresis_moment(Q, D, ratio_RyRx):
    r"""Rolling resistance moment from elastic hysteresis, MER [N m].

    Parameters
    ----------
    Q : array_like           normal load [N]
    D : array_like           ball diameter [m]
    ratio_RyRx : array_like  k = Ry/Rx ≥ 1 [-]

    Notes
    -----
    MER = 7.48e-7 (D/2)^0.33 Q^1.33 [1 - 3.519e-3 (k - 1)^0.8063] with D/2 in m,
    Q in N, MER in N m — a dimensional fit for steel (Houpert 1999; seed 000
    eq 25, seed 001 eq 9).  Independent of speed and lubricant.

    >>> round(hysteresis_moment(1.42, 7.938e-3, 17.667) * 1e7, 3)
    1.858
    """
    Q = _num("Q", Q, strict=False, what=" [N]")
    D = _num("D", D, what=" [m]")
    k = _num("ratio_RyRx", ratio_RyRx, lo=1.0, strict=False, what=" (Ry/Rx)")
    return _out(7.48e-7 * (D / 2) ** 0.33 * Q**1.33 * (1.0 - 3.519e-3 * (k - 1.0) ** 0.8063))


def ball_mass(D, rho=7850.0):
    r"""Mass of a solid ball, m = ρ π D³/6 [kg] (ρ [kg/m³], default bearing steel).

    >>> round(ball_mass(7.938e-3) * 1e3, 4)
    2.0559
    """
    return _out(_num("rho", rho) * np.pi * _num("D", D) ** 3 / 6.0)


def ball_inertia_force(m_b, dm, domega_c_dt):
    r"""Inertia force on the ball centre in a decelerating rig, F_ib [N].

    Parameters
    ----------
    m_b : array_like          ball mass [kg]
    dm : array_like           pitch diameter [m]
    domega_c_dt : array_like  orbital (cage) angular acceleration [rad/s²] (< 0 when decelerating)

    Notes
    -----
    F_ib = -m_b (dm/2) dω_c/dt  (seed 000 eq 24; seed 001 eq 8 with r = dm/2,
    ω_c = ω_2/2).  Positive (forward) while the rig decelerates.

    >>> round(ball_inertia_force(2.0561e-3, 0.036, -3.68) * 1e4, 3)
    1.362
    """
    return _out(-np.asarray(m_b, float) * np.asarray(dm, float) / 2.0 * np.asarray(domega_c_dt, float))


# ----------------------------------------------------------------------------- thrust ball balance
def traction_forces(MER_l, MER_u, FR_l, FR_u, F_ib, D):
    r"""Traction forces FS_l, FS_u at the lower (fixed) and upper (driving) race [N].

    Notes
    -----
    From the force and moment balance of the ball (seed 000 eq 26; seed 001
    App. B with 1 = lower, 2 = upper):
    FS_l = (MER_l + MER_u)/D + F_ib/2 + FR_u,
    FS_u = (MER_l + MER_u)/D - F_ib/2 + FR_l.

    >>> [round(f * 1e3, 4) for f in traction_forces(1.75e-7, 1.75e-7, 5.9e-3, 5.9e-3, 1.36e-4, 7.938e-3)]
    [6.0121, 5.8761]
    """
    s = (np.asarray(MER_l, float) + np.asarray(MER_u, float)) / _num("D", D)
    half = np.asarray(F_ib, float) / 2.0
    return _out(s + half + np.asarray(FR_u, float)), _out(s - half + np.asarray(FR_l, float))


def tangential_force_upper(MER_l, MER_u, FR_l, FR_u, F_ib, D):
    r"""Total tangential force of one ball on the upper race, F_t = FS_u + FR_u [N].

    Notes
    -----
    F_t = (MER_l + MER_u)/D + FR_u + FR_l - F_ib/2  (seed 000 eq 27; seed 001 App. B).

    >>> round(tangential_force_upper(1.75e-7, 1.75e-7, 5.9e-3, 5.9e-3, 1.36e-4, 7.938e-3) * 1e2, 3)
    1.178
    """
    _, fs_u = traction_forces(MER_l, MER_u, FR_l, FR_u, F_ib, D)
    return _out(np.asarray(fs_u) + np.asarray(FR_u, float))


def thrust_race_torque(F_t, MP_u, dm, Z=3):
    r"""Friction torque on the rotating race of a thrust ball bearing, T_z [N m].

    Parameters
    ----------
    F_t : array_like   tangential force per ball on the race [N]
    MP_u : array_like  pivoting moment at the race contact [N m]
    dm : array_like    pitch diameter [m]
    Z : int            number of (equally loaded) balls

    Notes
    -----
    T_z = Z (F_t dm/2 + MP_u)  (seed 000 eqs 29–30; seed 001 eq 13).

    >>> round(thrust_race_torque(1.178e-2, 3.26e-6, 0.036) * 1e3, 4)
    0.646
    """
    return _out(Z * (np.asarray(F_t, float) * np.asarray(dm, float) / 2.0 + np.asarray(MP_u, float)))


def ball_rolling_power(MER_l, MER_u, FR_l, FR_u, F_ib, D, dm, omega_b, omega_c):
    r"""Rolling power of one thrust ball: hysteresis, hydrodynamic, inertia (seed 000 eq 34) [W].

    Notes
    -----
    P_R = (MER_l + MER_u) ω_b + (FR_l + FR_u) D ω_b - F_ib (dm/2) ω_c, D ω_b = 2u
    for each contact.  P_t = Z (P_S + P_R) (eq 35) must equal T_z ω_race (eq 36)
    with ω_race = 2 ω_c when P_S is the pivoting slip power.

    >>> round(ball_rolling_power(1.75e-7, 1.75e-7, 5.9e-3, 5.9e-3, 1.36e-4, 7.938e-3, 0.036, 23.74, 5.23) * 1e3, 4)
    2.2192
    """
    return _out((np.asarray(MER_l, float) + np.asarray(MER_u, float)) * np.asarray(omega_b, float)
                + (np.asarray(FR_l, float) + np.asarray(FR_u, float)) * np.asarray(D, float)
                * np.asarray(omega_b, float)
                - np.asarray(F_ib, float) * np.asarray(dm, float) / 2.0 * np.asarray(omega_c, float))
