r"""SKF 2004 global friction model of ball bearings (rolling, sliding, drag, seals).

The model (SKF General Catalogue 6000 EN, 2005, "The SKF model for calculating
the frictional moment"; restated in seed 002, Cousseau et al., Appendix A) is

    M = Φ_ish Φ_rs G_rr (ν n)^0.6  +  G_sl μ_sl  +  M_drag  +  M_seal      [N mm]

with G_rr, G_sl functions of bearing type, series constants and loads.  M_drag is the drag of an
oil bath: with the oil level H known, the two-term form of SKF's 2018 edition (Rolling bearings 17000 EN)
with V_M read off SKF's diagram (:func:`drag_loss_factor_VM`, digitised in ``materials/skf_constants.toml``);
M_seal the seal moment of :mod:`thermobear.losses.seals`.  It is defined in SKF's units: M in N mm, n in r/min, ν in mm²/s (cSt) at the operating
temperature (grease: base-oil viscosity), loads in N, d, D, dm = (d + D)/2 in mm.

Everything in this module up to :func:`skf_moment` works in those units (every
argument name carries its unit); :func:`skf_moment` converts its result to SI once
(N m, W) and :func:`skf_friction` takes a :class:`thermobear.contact.geometry.BallBearing`
(SI) and converts its dimensions to mm once.

Series constants (R1..R3, S1..S3, K_z) are data: ``materials/skf_constants.toml``
with a status tag per row.  Calibrated R1, S1 (e.g. from a rig) override the table.

Honest reporting: the back-calculated full-film friction coefficient
(:func:`mu_EHL_from_torque`, seed 002 eqs A.12–A.13) is returned as computed,
negative values included — seed 002 §3 reports that the catalogue constants give
negative μ_EHD for the 51107 at high speed.
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from thermobear.files import data_dir, read_toml
from thermobear.errors import ExtrapolationWarning, InputError
from thermobear.losses.seals import seal_moment_Nmm
from thermobear.units import NMM, MM

__all__ = [
    "SKFFriction", "skf_friction", "skf_moment", "skf_constants",
    "skf_K_z", "phi_ish", "phi_rs", "phi_bl", "mu_sl", "alpha_F_deg", "G_rr_G_sl",
    "drag_moment_skf_Nmm", "drag_moment_skf2018_Nmm", "drag_loss_factor_VM", "seal_moment_Nmm",
    "mu_EHL_from_torque", "K_RS", "MU_EHL", "SKF_BREAKDOWN_KEYS",
]

KINDS = ("deep_groove", "angular_contact", "thrust")

#: Loss families of the SKF model as the solvers report them (``breakdown_W``): the oil-bath drag of
#: the model is the ``churning`` of the bath; ``drag`` (balls in an oil–air mixture) is 0 in it.
SKF_BREAKDOWN_KEYS = ("rolling", "sliding", "drag", "churning", "seal")

#: Replenishment/starvation constant K_rs of Φ_rs [-] by lubrication method
#: (SKF 2004, General Catalogue 6000 EN; seed 002 eq A.5 gives 6e-8 for grease): SKF's defaults, which a
#: scene may replace (``[lubricant] K_rs``, e.g. calibrated on a rig:
#: :func:`thermobear.models.replenishment_constant`).
K_RS = {"grease": 6e-8, "oil_air": 6e-8, "oil_jet": 3e-8, "oil_bath": 3e-8}

#: SKF's full-film friction coefficient μ_EHL by base-oil family [-]
#: (SKF 2004, General Catalogue 6000 EN; recalled, not checked against the catalogue).
MU_EHL = {"mineral": 0.05, "synthetic": 0.04, "transmission": 0.1}


# --------------------------------------------------------------------------- data
def skf_constants(kind: str, series: str) -> dict:
    """Series constants of the SKF model from ``materials/skf_constants.toml``.

    Returns a dict with R1, S1 (all kinds), R2, S2 (deep groove, angular contact),
    R3, S3 (angular contact), K_z and status.  Unknown kind/series raise InputError
    listing the known names.

    >>> c = skf_constants("thrust", "511")
    >>> c["R1"], c["S1"], c["K_z"]
    (1.03e-06, 0.016, 3.8)
    """
    table = read_toml(str(data_dir("materials") / "skf_constants.toml"))
    if kind not in KINDS:
        raise InputError("bearing.kind", kind, f"SKF constants exist for {', '.join(sorted(KINDS))}")
    sub = table[kind]
    series_tab = sub["series"]
    if series is None or str(series) not in series_tab:
        raise InputError("bearing.series", series,
                         f"no SKF constants for this {kind} series; known: {', '.join(series_tab)}"
                         + (" (or pass calibrated R1, S1)" if kind == "thrust" else ""))   # _brg_args: thrust only
    out = {"K_z": sub["K_z"]}
    out.update(series_tab[str(series)])
    return out


# ------------------------------------------------------------ reduction factors
def phi_ish(n_rpm, dm_mm, nu_cSt):
    r"""Inlet shear heating reduction factor Φ_ish of the rolling moment [-].

    Parameters
    ----------
    n_rpm : array_like   rotational speed [r/min]
    dm_mm : array_like   bearing mean diameter (d + D)/2 [mm]
    nu_cSt : array_like  kinematic viscosity at operating temperature [mm²/s]

    Notes
    -----
    Φ_ish = 1 / (1 + 1.84e-9 (n dm)^1.28 ν^0.64)
    (SKF 6000 EN; seed 002 eq A.4).  Φ_ish → 1 as n → 0.

    Examples
    --------
    Seed 002, 51107, 1000 r/min, MG1 grease (ν = 129.8 mm²/s):

    >>> round(float(phi_ish(1000, 43.5, 129.8)), 4)
    0.9654
    """
    n, dm, nu = (np.asarray(x, dtype=float) for x in (n_rpm, dm_mm, nu_cSt))
    return 1.0 / (1.0 + 1.84e-9 * (n * dm) ** 1.28 * nu ** 0.64)


def phi_rs(n_rpm, nu_cSt, d_mm, D_mm, K_z, K_rs):
    r"""Kinematic replenishment/starvation reduction factor Φ_rs [-].

    Parameters
    ----------
    n_rpm : array_like   rotational speed [r/min]
    nu_cSt : array_like  kinematic viscosity [mm²/s]
    d_mm, D_mm : float   bearing bore and outside diameter [mm] (not raceway diameters)
    K_z : float          bearing-type geometry constant [-] (3.1 DGBB, 4.4 ACBB, 3.8 thrust)
    K_rs : float         replenishment constant [-]: 6e-8 grease / oil–air, 3e-8 oil jet / bath

    Notes
    -----
    Φ_rs = exp[−K_rs ν n (d + D) √(K_z / (2 (D − d)))]
    (SKF 6000 EN; seed 002 eq A.5, which writes 1/e^(...)).

    Examples
    --------
    >>> round(float(phi_rs(1000, 129.8, 35, 52, 3.8, 6e-8)), 4)
    0.7973
    """
    n, nu = np.asarray(n_rpm, dtype=float), np.asarray(nu_cSt, dtype=float)
    return np.exp(-K_rs * nu * n * (d_mm + D_mm) * np.sqrt(K_z / (2.0 * (D_mm - d_mm))))


def phi_bl(n_rpm, nu_cSt, dm_mm):
    r"""Weighting factor Φ_bl between boundary and full-film sliding friction [-].

    Parameters
    ----------
    n_rpm : array_like   rotational speed [r/min]
    nu_cSt : array_like  kinematic viscosity [mm²/s]
    dm_mm : array_like   bearing mean diameter [mm]

    Notes
    -----
    Φ_bl = exp[−2.6e-8 (n ν)^1.4 dm]   (SKF 6000 EN; seed 002 eq A.10).
    Φ_bl = 1 at standstill (pure boundary friction), → 0 at high n ν.

    Examples
    --------
    >>> round(float(phi_bl(1000, 33.0, 43.5)), 4)
    0.0911
    """
    n, nu = np.asarray(n_rpm, dtype=float), np.asarray(nu_cSt, dtype=float)
    return np.exp(-2.6e-8 * (n * nu) ** 1.4 * np.asarray(dm_mm, dtype=float))


def mu_sl(phi_bl_, mu_bl=0.15, mu_EHL=0.05):
    r"""Sliding friction coefficient μ_sl = Φ_bl μ_bl + (1 − Φ_bl) μ_EHL [-].

    Parameters
    ----------
    phi_bl_ : array_like  weighting factor Φ_bl [-]
    mu_bl : float         boundary (asperity) friction coefficient [-]; SKF default 0.15
    mu_EHL : float        full-film friction coefficient [-]; SKF 0.05 mineral oil

    Notes
    -----
    SKF 6000 EN; seed 002 eq A.9.

    Examples
    --------
    >>> round(float(mu_sl(0.5, 0.15, 0.05)), 3)
    0.1
    """
    p = np.asarray(phi_bl_, dtype=float)
    return p * mu_bl + (1.0 - p) * mu_EHL


def alpha_F_deg(Fa, C0):
    r"""Load angle α_F of a deep groove ball bearing under combined load [deg].

    Parameters
    ----------
    Fa : array_like  axial load [N]
    C0 : float       basic static load rating [N]

    Notes
    -----
    α_F = 24.6 (F_a / C0)^0.24 degrees (SKF 6000 EN, table 2a note).

    Examples
    --------
    >>> round(float(alpha_F_deg(1000.0, 23200.0)), 2)
    11.57
    """
    return 24.6 * (np.asarray(Fa, dtype=float) / C0) ** 0.24


# --------------------------------------------------------------- load functions
def G_rr_G_sl(kind, dm_mm, Fa, Fr, n_rpm=0.0, *, R1, S1, R2=None, R3=None, S2=None, S3=None, C0=None):
    r"""Rolling and sliding load variables G_rr, G_sl of the SKF model (SKF units).

    Parameters
    ----------
    kind : str           "deep_groove", "angular_contact" (also four-point) or "thrust"
    dm_mm : float        bearing mean diameter (d + D)/2 [mm]
    Fa, Fr : array_like  axial and radial load [N]
    n_rpm : array_like   speed [r/min] (angular contact: centrifugal term F_g)
    R1..R3, S1..S3 : float  series constants (SKF table 3)
    C0 : float           static load rating [N] (deep groove with Fa > 0)

    Returns
    -------
    (G_rr, G_sl) : tuple of ndarray   such that M_rr [N mm] = Φ_ish Φ_rs G_rr (ν n)^0.6
                                      and M_sl [N mm] = G_sl μ_sl

    Notes
    -----
    Deep groove, F_a = 0:  G_rr = R1 dm^1.96 F_r^0.54,  G_sl = S1 dm^−0.26 F_r^(5/3).
    Deep groove, F_a > 0:  G_rr = R1 dm^1.96 (F_r + R2/sin α_F F_a)^0.54,
                           G_sl = S1 dm^−0.145 (F_r^5 + S2 dm^1.5/sin α_F F_a^4)^(1/3).
    Angular contact:       G_rr = R1 dm^1.97 (F_r + F_g + R2 F_a)^0.54, F_g = R3 dm^4 n^2,
                           G_sl = S1 dm^0.26 ((F_r + F_g)^(4/3) + S2 F_a^(4/3)), F_g = S3 dm^4 n^2.
    Thrust:                G_rr = R1 dm^1.83 F_a^0.54,  G_sl = S1 dm^0.05 F_a^(4/3)
                           (seed 002 eqs A.3, A.7).
    SKF 2004 (General Catalogue 6000 EN), table 2a.  The deep-groove combined form is used
    whenever F_a > 0: adding F_a to F_r, as some public code does, misreads both terms.

    Examples
    --------
    51107 thrust, F_a = 7000 N, catalogue constants:

    >>> Grr, Gsl = G_rr_G_sl("thrust", 43.5, 7000.0, 0.0, R1=1.03e-6, S1=1.6e-2)
    >>> round(float(Grr), 4), round(float(Gsl), 0)
    (0.1224, 2587.0)
    """
    dm = float(dm_mm)
    Fa, Fr, n = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (Fa, Fr, n_rpm)))
    if kind == "thrust":
        return R1 * dm ** 1.83 * Fa ** 0.54, S1 * dm ** 0.05 * Fa ** (4.0 / 3.0)
    if kind == "angular_contact":
        Fg_r = R3 * dm ** 4 * n ** 2
        Fg_s = S3 * dm ** 4 * n ** 2
        G_rr = R1 * dm ** 1.97 * (Fr + Fg_r + R2 * Fa) ** 0.54
        G_sl = S1 * dm ** 0.26 * ((Fr + Fg_s) ** (4.0 / 3.0) + S2 * Fa ** (4.0 / 3.0))
        return G_rr, G_sl
    if kind == "deep_groove":
        has_Fa = Fa > 0
        if np.any(has_Fa) and C0 is None:
            raise InputError("bearing.C0", None, "a deep groove bearing under axial load needs its static "
                             "load rating C0 [N] (SKF load angle alpha_F)")
        sin_aF = np.sin(np.deg2rad(alpha_F_deg(np.where(has_Fa, Fa, 1.0), C0 if C0 else 1.0)))
        G_rr = np.where(has_Fa, R1 * dm ** 1.96 * (Fr + R2 / sin_aF * Fa) ** 0.54,
                        R1 * dm ** 1.96 * Fr ** 0.54)
        G_sl = np.where(has_Fa, S1 * dm ** -0.145 * (Fr ** 5 + S2 * dm ** 1.5 / sin_aF * Fa ** 4) ** (1.0 / 3.0),
                        S1 * dm ** -0.26 * Fr ** (5.0 / 3.0))
        return G_rr, G_sl
    raise InputError("kind", kind, f"must be one of {', '.join(KINDS)}")


def drag_moment_skf_Nmm(V_M, K_z, d_mm, D_mm, n_rpm, i_rw=1):
    r"""SKF 2004 drag moment of a ball bearing in an oil bath [N mm].

    Parameters
    ----------
    V_M : float          drag loss factor from SKF's diagram (oil level H/dm); no closed form
    K_z : float          bearing-type geometry constant [-]
    d_mm, D_mm : float   bore and outside diameter [mm]
    n_rpm : array_like   speed [r/min]
    i_rw : int           number of ball rows

    Notes
    -----
    M_drag = V_M K_ball dm^5 n^2,  K_ball = i_rw K_z (d + D)/(D − d) 1e-12
    (SKF 2004, General Catalogue 6000 EN; seed 002 eq A.1).  The 2018 edition scales this term by
    0.4 and adds a viscous term (:func:`drag_moment_skf2018_Nmm`, used when the oil level is known).

    Examples
    --------
    >>> round(float(drag_moment_skf_Nmm(1.2e-3, 3.1, 50, 90, 3000)), 2)
    196.94
    """
    dm = 0.5 * (d_mm + D_mm)
    return V_M * _K_ball(K_z, d_mm, D_mm, i_rw) * dm ** 5 * np.asarray(n_rpm, dtype=float) ** 2


def _K_ball(K_z, d_mm, D_mm, i_rw):
    """SKF's rolling-element constant of ball bearings K_ball = i_rw K_z (d + D)/(D − d) 1e-12."""
    return i_rw * K_z * (d_mm + D_mm) / (D_mm - d_mm) * 1e-12


def drag_loss_factor_VM(H_over_dm):
    r"""SKF drag loss factor V_M of ball bearings at an oil level H/dm [-] (SKF's diagram, digitised).

    Parameters
    ----------
    H_over_dm : array_like   oil level H (above the lowest point of the outer-ring raceway) over the
                             bearing mean diameter dm = (d + D)/2 [-], >= 0; SKF caps H at 1.2 dm

    Returns
    -------
    ndarray   V_M [-], linear between the points of ``materials/skf_constants.toml``
              ``[drag_loss_factor.ball]`` (SKF 6000 EN p. 98 / 17000 EN diagram, digitised; 0 at H = 0)

    Examples
    --------
    >>> round(float(drag_loss_factor_VM(0.1)), 7), float(drag_loss_factor_VM(0.0))
    (7.31e-05, 0.0)
    """
    tab = read_toml(str(data_dir("materials") / "skf_constants.toml"))["drag_loss_factor"]["ball"]
    x = np.asarray(H_over_dm, dtype=float)
    if x.size and not (x.min() >= 0 and x.max() < np.inf):          # NaN fails too
        raise InputError("H_over_dm", H_over_dm, "oil level over dm must be finite and >= 0")
    x = np.minimum(x, tab["H_cap_over_dm"])
    return np.interp(x, tab["H_over_dm"], tab["V_M"])


def drag_moment_skf2018_Nmm(H_mm, nu_cSt, K_z, d_mm, D_mm, n_rpm, i_rw=1, V_M=None):
    r"""SKF drag moment of a ball bearing in an oil bath at oil level H, 2018 form [N mm].

    Parameters
    ----------
    H_mm : array_like     oil level above the lowest point of the outer-ring raceway [mm], >= 0
                          (SKF: H >= 1.2 dm counts as 1.2 dm)
    nu_cSt : array_like   kinematic viscosity at the operating temperature [mm²/s]
    K_z : float           bearing-type geometry constant [-]
    d_mm, D_mm : float    bore and outside diameter [mm]
    n_rpm : array_like    speed [r/min]
    i_rw : int            number of ball rows
    V_M : array_like      drag loss factor; default :func:`drag_loss_factor_VM` at H/dm

    Notes
    -----
    .. math::

        M_{drag} = 0.4\,V_M K_{ball} d_m^5 n^2
                   + 1.093\cdot 10^{-7}\, n^2 d_m^3 \left(\frac{n d_m^2 f_t}{\nu}\right)^{-1.379} R_s

    with K_ball = i_rw K_z (d + D)/(D − d) 1e-12, f_A = 0.05 K_z (D + d)/(D − d),
    R_s = 0.36 dm² (t − sin t) f_A, t = 2 arccos[(0.6 dm − H)/(0.6 dm)], f_t = sin(t/2) for t <= π,
    1 for π < t < 2π (SKF Rolling bearings 17000 EN (2018), "Drag losses"; the 2004 catalogue 6000 EN
    has the first term alone with factor 1, :func:`drag_moment_skf_Nmm`).  H = 0 → 0 (no ball reaches
    the bath: V_M = 0 and R_s ∝ t³ → 0 faster than the viscous factor grows).  Status: the form as
    printed by SKF, confirmed in three public implementations of the 2018 model; V_M digitised.

    Examples
    --------
    6208 (40 × 80 mm, dm 60 mm), H = 6 mm (H/dm 0.1), 3000 r/min, ν 30 mm²/s:

    >>> round(float(drag_moment_skf2018_Nmm(6.0, 30.0, 3.1, 40.0, 80.0, 3000.0)), 3)
    3.483
    """
    dm = 0.5 * (d_mm + D_mm)
    H = np.asarray(H_mm, dtype=float)
    if H.size and not (H.min() >= 0 and H.max() < np.inf):
        raise InputError("oil_level_mm", H_mm, "oil level must be finite and >= 0 [mm]")
    H = np.minimum(H, 1.2 * dm)
    VM = drag_loss_factor_VM(H / dm) if V_M is None else np.asarray(V_M, dtype=float)
    n, nu = np.asarray(n_rpm, dtype=float), np.asarray(nu_cSt, dtype=float)
    t = 2.0 * np.arccos(np.clip((0.6 * dm - H) / (0.6 * dm), -1.0, 1.0))
    f_t = np.where(t <= np.pi, np.sin(0.5 * t), 1.0)
    f_A = 0.05 * K_z * (D_mm + d_mm) / (D_mm - d_mm)
    R_s = 0.36 * dm ** 2 * (t - np.sin(t)) * f_A
    wet = (t > 0) & (n > 0)
    Re = np.where(wet, n * dm ** 2 * f_t / nu, 1.0)
    viscous = np.where(wet, 1.093e-7 * n ** 2 * dm ** 3 * Re ** -1.379 * R_s, 0.0)
    return 0.4 * VM * _K_ball(K_z, d_mm, D_mm, i_rw) * dm ** 5 * n ** 2 + viscous


# ------------------------------------------------------------------- the model
@dataclass(frozen=True)
class SKFFriction:
    """Result of the SKF model (moments in N m, power in W; arrays broadcast over operating points).

    Attributes
    ----------
    M_rr : rolling moment Φ_ish Φ_rs G_rr (ν n)^0.6 [N m]
    M_sl : sliding moment G_sl μ_sl [N m]
    M_drag, M_seal : drag and seal moments [N m]
    M_total : sum of the four [N m]
    phi_ish, phi_rs, phi_bl, mu_sl, mu_EHL, mu_bl : factors and coefficients [-]
    G_rr, G_sl : load variables in SKF units (N mm with the (ν n)^0.6 and μ factors)
    P_W : friction power M_total ω [W]
    """

    M_rr: np.ndarray
    M_sl: np.ndarray
    M_drag: np.ndarray
    M_seal: np.ndarray
    M_total: np.ndarray
    phi_ish: np.ndarray
    phi_rs: np.ndarray
    phi_bl: np.ndarray
    mu_sl: np.ndarray
    mu_EHL: np.ndarray
    mu_bl: np.ndarray
    G_rr: np.ndarray
    G_sl: np.ndarray
    P_W: np.ndarray


def _out(x):
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x


def _check_positive(name, x, allow_zero=False):
    a = np.asarray(x, dtype=float)
    bad = ~np.isfinite(a) | ((a < 0) if allow_zero else (a <= 0))
    if np.any(bad):
        raise InputError(name, x, "must be finite and " + (">= 0" if allow_zero else "> 0"))


def skf_moment(d_mm, D_mm, kind, nu_cSt, n_rpm, Fa, Fr, *, R1, S1, R2=None, R3=None, S2=None, S3=None,
               K_z, lubrication="grease", mu_bl=0.15, mu_EHL=0.05, C0=None, V_M=None, i_rw=1,
               M_seal_Nmm=0.0, H_mm=None, K_rs=None):
    r"""SKF 2004 frictional moment of a ball bearing from plain numbers, vectorised.

    Parameters
    ----------
    d_mm, D_mm : float     bore and outside diameter [mm]; dm = (d + D)/2
    kind : str             "deep_groove", "angular_contact" or "thrust"
    nu_cSt : array_like    kinematic viscosity at operating temperature [mm²/s] (grease: base oil)
    n_rpm : array_like     speed [r/min]
    Fa, Fr : array_like    axial and radial load [N]
    R1, S1, R2, R3, S2, S3 : float   series constants (see :func:`skf_constants`)
    K_z : float            bearing-type geometry constant [-]
    lubrication : str      "grease", "oil_air" (K_rs 6e-8), "oil_jet", "oil_bath" (K_rs 3e-8)
    mu_bl, mu_EHL : float  boundary and full-film friction coefficients [-]
    K_rs : array_like      replenishment constant of Φ_rs [-] (:func:`phi_rs`); None: SKF's for
                           ``lubrication`` (:data:`K_RS`)
    C0 : float             static load rating [N] (deep groove with Fa > 0)
    V_M : float            SKF drag factor (oil bath, read from SKF's diagram); alone: the 2004 drag
                           term V_M K_ball dm^5 n^2 (:func:`drag_moment_skf_Nmm`)
    i_rw : int             ball rows (drag term)
    M_seal_Nmm : array_like  seal moment [N mm] (see :func:`thermobear.losses.seals.seal_friction`)
    H_mm : array_like      oil level above the lowest point of the outer-ring raceway [mm]: the 2018
                           drag form with V_M from SKF's diagram (:func:`drag_moment_skf2018_Nmm`);
                           an oil bath needs H_mm or V_M

    Returns
    -------
    SKFFriction   moments in N m (converted once, here), power in W

    Notes
    -----
    M = Φ_ish Φ_rs G_rr (ν n)^0.6 + G_sl μ_sl + M_drag + M_seal  [N mm]
    (SKF 6000 EN; seed 002 eqs A.1–A.10; M_drag of the 2018 edition when H_mm is given).
    Power P = M ω = M π n / 30, which is
    SKF's N_R = 1.05e-4 M n with M in N mm.

    Examples
    --------
    Seed 002, 51107, F_a = 7000 N, 1000 r/min, MG1 grease (ν 129.8 mm²/s), with the
    R1, S1 that Table 3 implies and the paper's μ_EHD = 0.044, μ_bl = 0.09:

    >>> r = skf_moment(35, 52, "thrust", 129.8, 1000, 7000, 0, R1=8.12e-7, S1=1.244e-2,
    ...                K_z=3.8, mu_bl=0.09, mu_EHL=0.044)
    >>> round(r.M_rr * 1e3, 1), round(r.M_sl * 1e3, 1)    # Table 3: 86.8, 88.5 N mm
    (86.8, 88.5)
    """
    if kind not in KINDS:
        raise InputError("kind", kind, f"must be one of {', '.join(KINDS)}")
    if lubrication not in K_RS:
        raise InputError("lubrication", lubrication, f"must be one of {', '.join(K_RS)}")
    if not (np.isfinite(d_mm) and np.isfinite(D_mm) and 0 < d_mm < D_mm):
        raise InputError("D_mm", D_mm, f"outside diameter must exceed the bore d = {d_mm} mm > 0")
    _check_positive("nu_cSt", nu_cSt)
    _check_positive("n_rpm", n_rpm, allow_zero=True)
    _check_positive("Fa", Fa, allow_zero=True)
    _check_positive("Fr", Fr, allow_zero=True)
    for name, val in (("R1", R1), ("S1", S1), ("K_z", K_z)):
        if val is None or not (np.isfinite(val) and val > 0):
            raise InputError(name, val, "SKF constant must be > 0 (see materials/skf_constants.toml)")
    mb, me = np.asarray(mu_bl, dtype=float), np.asarray(mu_EHL, dtype=float)
    if np.any(~np.isfinite(mb) | (mb < 0) | (mb >= 1)):
        raise InputError("mu_bl", mu_bl, "boundary friction coefficient must lie in [0, 1)")
    if np.any(~np.isfinite(me) | (me >= 1)):
        raise InputError("mu_EHL", mu_EHL, "full-film friction coefficient must be finite and < 1")
    if kind == "thrust" and np.any(np.asarray(Fr, dtype=float) > 0):
        raise InputError("Fr", Fr, "a thrust ball bearing carries no radial load; Fr must be 0 [N]")
    if kind in ("deep_groove", "angular_contact"):
        for name, val in (("R2", R2), ("S2", S2)) + ((("R3", R3), ("S3", S3)) if kind == "angular_contact" else ()):
            if val is None:
                raise InputError(name, None, f"SKF constant required for a {kind} bearing")
    _check_positive("M_seal_Nmm", M_seal_Nmm, allow_zero=True)
    K_rs = K_RS[lubrication] if K_rs is None else K_rs
    _check_positive("K_rs", K_rs, allow_zero=True)
    for name, val in (("V_M", V_M), ("H_mm", H_mm)):
        if val is not None:
            _check_positive(name, val, allow_zero=True)
    if lubrication == "oil_bath" and V_M is None and H_mm is None:
        raise InputError("oil_level_mm", None, "oil-bath lubrication needs the oil level H above the lowest "
                         "point of the outer-ring raceway [mm] (or SKF's drag factor V_M)")

    nu, n, Fa_, Fr_ = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (nu_cSt, n_rpm, Fa, Fr)))
    dm = 0.5 * (d_mm + D_mm)
    G_rr, G_sl = G_rr_G_sl(kind, dm, Fa_, Fr_, n, R1=R1, S1=S1, R2=R2, R3=R3, S2=S2, S3=S3, C0=C0)
    p_ish = phi_ish(n, dm, nu)
    p_rs = phi_rs(n, nu, d_mm, D_mm, K_z, K_rs)
    p_bl = phi_bl(n, nu, dm)
    m_sl = mu_sl(p_bl, mu_bl, mu_EHL)
    M_rr = p_ish * p_rs * G_rr * (nu * n) ** 0.6
    M_sl = G_sl * m_sl
    if H_mm is not None:
        M_drag = drag_moment_skf2018_Nmm(H_mm, nu, K_z, d_mm, D_mm, n, i_rw, V_M)
    else:
        M_drag = np.zeros_like(n) if V_M is None else drag_moment_skf_Nmm(V_M, K_z, d_mm, D_mm, n, i_rw)
    M_seal = np.asarray(M_seal_Nmm, dtype=float) + 0.0 * n
    M_tot = M_rr + M_sl + M_drag + M_seal
    omega = n * np.pi / 30.0
    # --- the one conversion to SI: N mm -> N m
    return SKFFriction(M_rr=_out(M_rr * NMM), M_sl=_out(M_sl * NMM), M_drag=_out(M_drag * NMM),
                       M_seal=_out(M_seal * NMM), M_total=_out(M_tot * NMM), phi_ish=_out(p_ish),
                       phi_rs=_out(p_rs), phi_bl=_out(p_bl), mu_sl=_out(m_sl), mu_EHL=_out(me),
                       mu_bl=_out(mb), G_rr=_out(G_rr), G_sl=_out(G_sl), P_W=_out(M_tot * NMM * omega))


def _brg_args(brg, R1, S1, constants):
    """SKF plain-number arguments (mm) from a BallBearing (m): the one mm conversion."""
    for fld in ("bore", "outer_diameter"):
        if getattr(brg, fld, None) is None:
            raise InputError(f"bearing[{getattr(brg, 'name', '?')}].{fld}", None,
                             "the SKF model needs the bore and outside diameter [m]")
    d_mm, D_mm = brg.bore / MM, brg.outer_diameter / MM
    if constants is None:
        try:
            constants = skf_constants(brg.kind, brg.series)
        except InputError:
            if not (R1 is not None and S1 is not None and brg.kind == "thrust"):
                raise
            constants = {"K_z": skf_K_z("thrust")}   # thrust needs only R1, S1, K_z
    c = dict(constants)
    c.pop("status", None)
    if R1 is not None:
        c["R1"] = R1
    if S1 is not None:
        c["S1"] = S1
    return d_mm, D_mm, c


def skf_K_z(kind: str) -> float:
    """K_z of a bearing kind from ``materials/skf_constants.toml``.

    >>> skf_K_z("deep_groove")
    3.1
    """
    table = read_toml(str(data_dir("materials") / "skf_constants.toml"))
    if kind not in KINDS:
        raise InputError("bearing.kind", kind, f"SKF constants exist for {', '.join(sorted(KINDS))}")
    return table[kind]["K_z"]


def skf_friction(brg, nu_cSt, n_rpm, Fa, Fr, lubrication="grease", R1=None, S1=None, mu_bl=0.15,
                 mu_EHL=None, *, base_oil="mineral", V_M=None, M_seal_Nmm=0.0, constants=None, H_mm=None,
                 K_rs=None):
    r"""SKF 2004 frictional moment and power of a ball bearing (public entry point).

    Parameters
    ----------
    brg : thermobear.contact.geometry.BallBearing   needs kind, series, bore, outer_diameter [m]
                           (and C0 [N] for a deep groove bearing under axial load)
    nu_cSt : array_like    kinematic viscosity at operating temperature [mm²/s]
                           (grease: base oil at the bearing temperature)
    n_rpm : array_like     speed [r/min]
    Fa, Fr : array_like    axial and radial load [N]
    lubrication : str      "grease" | "oil_jet" | "oil_bath" | "oil_air"
    R1, S1 : float         calibrated constants overriding the series table
    mu_bl : float          boundary friction coefficient [-] (SKF 0.15)
    mu_EHL : float         full-film friction coefficient [-]; None → SKF value for ``base_oil``
    base_oil : str         "mineral" (0.05), "synthetic" (0.04), "transmission" (0.1)
    V_M : float            SKF oil-bath drag factor (2004 drag term; or give H_mm)
    M_seal_Nmm : array_like  seal moment [N mm]
    H_mm : array_like      oil level [mm] (oil bath: the 2018 drag term, V_M from SKF's diagram)
    constants : dict       full set of series constants (R1.., S1.., K_z) instead of the table
    K_rs : array_like      replenishment constant [-]; None: SKF's for ``lubrication`` (:data:`K_RS`)

    Returns
    -------
    SKFFriction   r.M_rr, r.M_sl, r.M_drag, r.M_seal, r.M_total [N m], r.phi_ish, r.phi_rs,
                  r.phi_bl, r.mu_sl, r.P_W [W]

    Notes
    -----
    dm of the SKF model is (bore + OD)/2, not the ball pitch diameter brg.dm.
    See :func:`skf_moment` for the equations (SKF 6000 EN; seed 002 Appendix A).

    Examples
    --------
    >>> from thermobear.contact.geometry import bearing
    >>> r = skf_friction(bearing("6210"), 20.0, 3000, 0.0, 1000.0, lubrication="oil_jet")
    >>> round(r.M_total * 1e3, 1), round(r.P_W, 1)     # N mm, W
    (48.9, 15.4)
    """
    if mu_EHL is None:
        if base_oil not in MU_EHL:
            raise InputError("base_oil", base_oil, f"must be one of {', '.join(MU_EHL)} (or give mu_EHL)")
        mu_EHL = MU_EHL[base_oil]
    d_mm, D_mm, c = _brg_args(brg, R1, S1, constants)
    return skf_moment(d_mm, D_mm, brg.kind, nu_cSt, n_rpm, Fa, Fr, lubrication=lubrication, mu_bl=mu_bl,
                      mu_EHL=mu_EHL, C0=brg.C0, V_M=V_M, M_seal_Nmm=M_seal_Nmm, H_mm=H_mm, K_rs=K_rs, **c)


def mu_EHL_from_torque(M_exp_Nm, d_mm, D_mm, kind, nu_cSt, n_rpm, Fa, Fr, *, mu_bl, **constants):
    r"""Full-film friction coefficient implied by a measured total moment (seed 002 eqs A.12–A.13).

    Parameters
    ----------
    M_exp_Nm : array_like  measured total frictional moment [N m]
    d_mm, D_mm, kind, nu_cSt, n_rpm, Fa, Fr : as :func:`skf_moment`
    mu_bl : float          boundary friction coefficient assumed [-]
    **constants            R1, S1, (R2, R3, S2, S3), K_z, lubrication, C0, V_M, M_seal_Nmm, K_rs (None: SKF's
                           of the lubrication)

    Returns
    -------
    ndarray   μ_EHL = (M_sl / G_sl − Φ_bl μ_bl) / (1 − Φ_bl), with
              M_sl = M_exp − M_rr − M_drag − M_seal.  Returned as computed: a negative
              value means the model's rolling moment already exceeds the measurement
              (seed 002 §3: catalogue R1, S1 give negative μ_EHD for the 51107 at high speed).

    Examples
    --------
    Seed 002 Table 3, MG1 at 1000 r/min: M_exp = M_rr + M_sl = 175.3 N mm.

    >>> round(float(mu_EHL_from_torque(0.1753, 35, 52, "thrust", 129.8, 1000, 7000, 0,
    ...       mu_bl=0.09, R1=8.12e-7, S1=1.244e-2, K_z=3.8)), 4)
    0.044
    """
    r = skf_moment(d_mm, D_mm, kind, nu_cSt, n_rpm, Fa, Fr, mu_bl=mu_bl, mu_EHL=0.0, **constants)
    M_sl_Nmm = (np.asarray(M_exp_Nm, dtype=float) - r.M_rr - r.M_drag - r.M_seal) / NMM
    p_bl = np.asarray(r.phi_bl)
    if np.any(p_bl > 0.5):
        warnings.warn("mu_EHL_from_torque: Φ_bl > 0.5 — the back-calculation divides by 1 − Φ_bl → 0 and its sign "
                      "is not meaningful there", ExtrapolationWarning, stacklevel=2)
    return _out((M_sl_Nmm / r.G_sl - p_bl * mu_bl) / (1.0 - p_bl))
