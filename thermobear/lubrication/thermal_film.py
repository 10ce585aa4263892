r"""Inlet shear heating: the thermal reduction of EHL film thickness and of the hydrodynamic rolling force.

Part of the oil that reaches the inlet of a rolling contact cannot pass and flows back; its shear
heats the inlet, lowers the viscosity where the film is formed, and so thins the film and lowers
the Poiseuille (rolling) force below their isothermal values.  The reduction grows with the
thermal loading parameter L = β η u_s²/k (the viscous heating of the inlet against the oil's
conduction; Murch & Wilson 1975, Wilson & Sheu 1983) and with sliding.

* :func:`thermal_loading_parameter` — L [-];
* :func:`thermal_reduction_gupta` — the film ratio φ_T = h_thermal/h_isothermal of Gupta et al.
  (1992), → 1 as L → 0;
* :func:`thermal_inlet_viscosity` — the inlet viscosity that gives the thermal film with the
  isothermal formulas, η_T = η φ_T^(1/0.67): one effective viscosity for the film (Hamrock–Dowson,
  h ∝ η^0.67) and the rolling force of the local model (an inlet flow effect of the same viscosity).

The global analogue is the SKF 2004 inlet-shear-heating factor Φ_ish on M_rr
(:func:`thermobear.losses.skf.phi_ish`).

References
----------
.. [1] Murch L. E., Wilson W. R. D. (1975) A thermal elastohydrodynamic inlet zone analysis.
       ASME J. Lubr. Technol. 97, 212–216.
.. [2] Wilson W. R. D., Sheu S. (1983) Effect of inlet shear heating due to sliding on
       elastohydrodynamic film thickness. ASME J. Lubr. Technol. 105, 187–188.
.. [3] Gupta P. K., Cheng H. S., Zhu D., Forster N. H., Schrand J. B. (1992) Viscoelastic effects
       in MIL-L-7808-type lubricant, Part I: analytical formulation. Tribol. Trans. 35, 269–274.
"""
from __future__ import annotations

import numpy as np

from thermobear.arrays import checked as _num, out as _out

__all__ = ["thermal_loading_parameter", "thermal_reduction_gupta", "thermal_inlet_viscosity", "HD_SPEED_EXPONENT"]

#: speed (and viscosity) exponent of the Hamrock–Dowson central film, h ∝ (η u)^0.67
HD_SPEED_EXPONENT = 0.67


def thermal_loading_parameter(beta, eta, u_sum, k_th, *, check=True):
    r"""Thermal loading parameter of an EHL inlet [-].

    Parameters
    ----------
    beta : array_like   temperature–viscosity coefficient −d ln η/dT [1/K]
    eta : array_like    inlet viscosity at the surface temperature [Pa s]
    u_sum : array_like  sum of the surface speeds u1 + u2 = 2 u [m/s]
    k_th : array_like   thermal conductivity of the oil [W/(m K)]
    check : bool        False: inputs already checked by the caller (e.g. the lubricant's values): skip the checks

    Returns
    -------
    float or ndarray  L [-]

    Notes
    -----
    .. math::

        L = \frac{\beta\, \eta\, u_s^2}{k}

    (Murch & Wilson 1975 [1]_; Gupta et al. 1992 [2]_).  The viscous heat of the inlet against
    its conduction: the inlet temperature rise is of order L/β.

    References
    ----------
    .. [1] Murch L. E., Wilson W. R. D. (1975) ASME J. Lubr. Technol. 97, 212–216.
    .. [2] Gupta P. K. et al. (1992) Tribol. Trans. 35, 269–274.

    Examples
    --------
    A mineral oil at 50 °C (β 0.045 1/K, η 0.114 Pa s, k 0.13 W/(m K)) at u_s = 2.28 m/s:

    >>> round(thermal_loading_parameter(0.045, 0.114, 2.28, 0.13), 4)
    0.2051
    """
    if check:
        beta, eta = _num("beta", beta, strict=False, what=" [1/K]"), _num("eta", eta, what=" [Pa s]")
        u_sum, k_th = _num("u_sum", u_sum, strict=False, what=" [m/s]"), _num("k_th", k_th, what=" [W/(m K)]")
    return _out(beta * eta * u_sum ** 2 / k_th)


def thermal_reduction_gupta(L, srr=0.0, *, check=True):
    r"""Thermal reduction of the EHL film thickness by inlet shear heating, φ_T = h_T/h_iso [-].

    Parameters
    ----------
    L : array_like    thermal loading parameter (:func:`thermal_loading_parameter`) [-]
    srr : array_like  slide-to-roll ratio |u1 − u2|/(u1 + u2) [-] (0: pure rolling)
    check : bool      False: inputs already checked by the caller (e.g. the lubricant's values): skip the checks

    Returns
    -------
    float or ndarray  φ_T ∈ (0, 1] [-]

    Notes
    -----
    .. math::

        \phi_T = \left[1 + 0.1\,(1 + 14.8\,S^{0.83})\, L^{0.64}\right]^{-1}

    Gupta et al. (1992) [1]_, a curve fit of the thermal inlet analyses of Murch & Wilson (1975) and
    Wilson & Sheu (1983) [2]_; φ_T → 1 as L → 0 (slow, thin or conductive oil).  The form is the one
    used for rolling-bearing contacts by the group of seed 002 (Porto); recalled, not checked
    against the original in this work.

    References
    ----------
    .. [1] Gupta P. K., Cheng H. S., Zhu D., Forster N. H., Schrand J. B. (1992) Tribol. Trans. 35, 269–274.
    .. [2] Wilson W. R. D., Sheu S. (1983) ASME J. Lubr. Technol. 105, 187–188.

    Examples
    --------
    >>> round(thermal_reduction_gupta(0.2051), 4), thermal_reduction_gupta(0.0), round(thermal_reduction_gupta(1.0, 0.1), 4)
    (0.965, 1.0, 0.7582)
    """
    if check:
        L = _num("L", L, strict=False, what=" (thermal loading parameter)")
        srr = _num("srr", srr, strict=False, what=" (slide-to-roll ratio)")
    return _out(1.0 / (1.0 + 0.1 * (1.0 + 14.8 * srr**0.83) * L**0.64))


def thermal_inlet_viscosity(eta, phi_T, *, check=True):
    r"""Effective inlet viscosity of a thermally reduced film [Pa s].

    Parameters
    ----------
    eta : array_like    isothermal inlet viscosity [Pa s]
    phi_T : array_like  thermal film reduction (:func:`thermal_reduction_gupta`) [-]
    check : bool        False: inputs already checked by the caller (e.g. the lubricant's values): skip the checks

    Returns
    -------
    float or ndarray  η_T [Pa s]

    Notes
    -----
    .. math::

        \eta_T = \eta\, \phi_T^{1/0.67}

    The viscosity with which the isothermal Hamrock–Dowson central film (h ∝ (η u)^0.67) gives the
    thermal film φ_T h — the reading of inlet heating as a lowered inlet viscosity of Murch & Wilson
    (1975) [1]_.  The local model evaluates its rolling force (an inlet Poiseuille effect) at the
    same viscosity.

    References
    ----------
    .. [1] Murch L. E., Wilson W. R. D. (1975) ASME J. Lubr. Technol. 97, 212–216.

    Examples
    --------
    >>> round(thermal_inlet_viscosity(0.114, 0.965), 5), thermal_inlet_viscosity(0.114, 1.0)
    (0.1081, 0.114)
    """
    phi_T = _num("phi_T", phi_T, what=" [-]") if check else phi_T
    return _out(np.asarray(eta, float) * phi_T ** (1.0 / HD_SPEED_EXPONENT))
