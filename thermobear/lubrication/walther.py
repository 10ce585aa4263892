r"""ASTM D341 (Walther): the viscosity–temperature relation of petroleum and synthetic oils,
log10 log10 Z = A − B log10 T, fitted through two points (ν40, ν100) or through one point and a
slope; its temperature–viscosity coefficient.  Used by :class:`thermobear.lubrication.lubricant.Lubricant`
(and re-exported there).
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["walther_Z", "walther_nu_from_Z", "walther_fit", "walther_nu", "walther_temperature_coefficient",
           "NU_MIN_CST"]

#: The smallest kinematic viscosity the D341 form represents [cSt]: log10 log10 Z needs Z > 1, and
#: :func:`walther_Z` (ν) = 1 at ν = 0.11527 cSt (below it ν(T) is NaN).
#:
#: >>> abs(float(walther_Z(NU_MIN_CST)) - 1.0) < 1e-6
#: True
NU_MIN_CST = 0.1152738


def _xp(x):
    """The module whose exp/log10 the formulas below use: ``math`` for one Python float (the thermal
    elements ask for one temperature at a time), numpy otherwise — one formula for both."""
    return math if type(x) is float else np


def _num(x):
    """``x`` unchanged if a Python float, else as a float array."""
    return x if type(x) is float else np.asarray(x, dtype=float)


def _scalar(x):
    """A 0-d value as a Python float, an array unchanged."""
    return float(x) if np.ndim(x) == 0 else np.asarray(x, dtype=float)


def walther_Z(nu_cSt):
    r"""ASTM D341 Z of a kinematic viscosity.

    Parameters
    ----------
    nu_cSt : array_like  kinematic viscosity [cSt = mm²/s], > 0

    Returns
    -------
    ndarray  Z = ν + 0.7 + exp(−1.47 − 1.84 ν − 0.51 ν²) [cSt]

    Notes
    -----
    ASTM D341-09 eq (2).  The exponential correction matters only below about 2 cSt.

    Examples
    --------
    >>> round(float(walther_Z(10.0)), 12)
    10.7
    """
    nu = _num(nu_cSt)
    return nu + 0.7 + _xp(nu).exp(-1.47 - 1.84 * nu - 0.51 * nu**2)


def walther_nu_from_Z(Z):
    r"""Inverse of :func:`walther_Z` (ASTM D341-09 eq (4)).

    Parameters
    ----------
    Z : array_like  D341 Z [cSt], > 0.7

    Returns
    -------
    ndarray  ν = (Z − 0.7) − exp(−0.7487 − 3.295 (Z−0.7) + 0.6119 (Z−0.7)² − 0.3193 (Z−0.7)³) [cSt]

    Examples
    --------
    >>> round(float(walther_nu_from_Z(walther_Z(1.5))), 3)
    1.5
    """
    x = _num(Z) - 0.7
    return x - _xp(x).exp(-0.7487 - 3.295 * x + 0.6119 * x**2 - 0.3193 * x**3)


def walther_fit(nu1_cSt, T1_K, nu2_cSt, T2_K):
    r"""Walther constants A, B through two points (T1 < T2, ν1 > ν2).

    Parameters
    ----------
    nu1_cSt, nu2_cSt : array_like  kinematic viscosities [cSt] at T1_K, T2_K
    T1_K, T2_K : float             absolute temperatures [K]

    Returns
    -------
    (A, B)  constants of log10 log10 Z = A − B log10 T  (T in K) [-]: floats, or arrays for array input

    Notes
    -----
    B = [log log Z1 − log log Z2] / [log T2 − log T1],  A = log log Z1 + B log T1
    (ASTM D341-09).  Typical B ≈ 3–4 for mineral oils.

    Examples
    --------
    >>> A, B = walther_fit(36.6, 313.15, 7.8, 373.15)
    >>> round(B, 4)
    2.9969
    """
    ll1 = np.log10(np.log10(walther_Z(nu1_cSt)))
    ll2 = np.log10(np.log10(walther_Z(nu2_cSt)))
    B = (ll1 - ll2) / (np.log10(T2_K) - np.log10(T1_K))
    A = ll1 + B * np.log10(T1_K)
    return _scalar(A), _scalar(B)


def walther_nu(A, B, T_K):
    r"""Kinematic viscosity from Walther constants (ASTM D341).

    Parameters
    ----------
    A, B : float       Walther constants (see :func:`walther_fit`) [-]
    T_K : array_like   absolute temperature [K]

    Returns
    -------
    ndarray  ν [cSt] with Z = 10^(10^(A − B log10 T)), ν = :func:`walther_nu_from_Z` (Z)

    Examples
    --------
    >>> A, B = walther_fit(36.6, 313.15, 7.8, 373.15)
    >>> round(float(walther_nu(A, B, 333.15)), 2)
    19.51
    """
    return walther_nu_from_Z(_walther_Z_at(A, B, T_K))


def _walther_Z_at(A, B, T_K):
    """D341 Z = 10^(10^(A − B log10 T)) at T_K [K]."""
    T = _num(T_K)
    return 10.0 ** (10.0 ** (A - B * _xp(T).log10(T)))


def walther_temperature_coefficient(A, B, T_K):
    r"""Temperature–viscosity coefficient of the kinematic viscosity, −d ln ν/dT, from ASTM D341 [1/K].

    Parameters
    ----------
    A, B : float       Walther constants (see :func:`walther_fit`) [-]
    T_K : array_like   absolute temperature [K]

    Returns
    -------
    ndarray  −d ln ν/dT [1/K]

    Notes
    -----
    Differentiating log10 log10 Z = A − B log10 T:

    .. math::

        -\frac{d\ln\nu}{dT} = \frac{B\, Z \ln Z}{\nu\, T},\qquad Z = 10^{10^{A - B\log_{10}T}}

    with dν/dZ = 1 (the exponential correction of :func:`walther_Z` matters below 2 cSt only).

    Examples
    --------
    >>> A, B = walther_fit(36.6, 313.15, 7.8, 373.15)
    >>> round(float(walther_temperature_coefficient(A, B, 333.15)), 4)
    0.028
    """
    Z = _walther_Z_at(A, B, T_K)
    return B * Z * _xp(Z).log(Z) / (walther_nu_from_Z(Z) * _num(T_K))
