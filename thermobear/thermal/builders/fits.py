r"""Ring seats as thermal joints: the probable fit of a ring and the joint conductance it gives.

A rotating ring sits with an interference, a stationary ring with a small clearance (the
usual recommendation for ball bearings under a rotating inner-ring load: shaft k5 (m5 above
100 mm), housing H7; with a rotating outer ring: shaft g6, housing N7 — SKF 2018, *Rolling
bearings* catalogue 17000 EN, "Selecting fits").  The probable (mean) diametral interference is
the difference of the mid-tolerances of the seat (ISO 286-2) and of the ring (ISO 492 normal
tolerance class): :func:`thermobear.contact.fits.fit_interference`, the tables the operating clearance uses.  The joint conductance (:func:`seat_conductance`):

* interference δ > 0: Lamé contact pressure (:func:`~thermobear.thermal.conduction.fit_pressure`)
  and the plastic-contact joint conductance with air in the gaps
  (:func:`~thermobear.thermal.conduction.joint_conductance`);
* clearance c ≥ 0: the loaded half of the seat presses with the radial load over its projected area,
  p = F_r/(B D) (estimated distribution), the other half is a gap of c/2: h = ½ h_j(p) + ½ k_air/(c/2 + M).

Surface data (estimated; ``materials/network_builders.toml`` with their ranges,
:mod:`~thermobear.thermal.builders.estimates`): ground shaft and housing seats Ra 0.8 µm (shaft) and
1.6 µm (housing), the guideline values SKF gives for IT6/IT7 seats; ring bore and outside surface
Ra 0.4 µm (ground); RMS σ = 1.25 Ra (a Gaussian profile).  Microhardness of the softer member 3 GPa (an
unhardened C45 shaft or a grey-iron housing: Vickers 200–250 HV ≈ 2–2.5 GPa, the microhardness of
a ground surface about 1.3× that).  Air in the gaps at 60 °C, k = 0.029 W/(m K), rarefaction
parameter M ≈ 0.3 µm (accommodation coefficient ≈ 0.9, Yovanovich 2005).  Thermal expansion of
the parts (which tightens or loosens a fit as they warm) is not modelled.
"""
from __future__ import annotations

import math

from thermobear.contact.fits import fit_interference
from thermobear.contact.materials import Material
from thermobear.errors import InputError
from thermobear.thermal.builders import estimates
from thermobear.thermal.conduction import fit_pressure, joint_conductance

__all__ = ["probable_interference", "seat_conductance", "seat_sigma", "SIGMA_SHAFT_SEAT_M", "SIGMA_HOUSING_SEAT_M",
           "H_MICRO_PA", "K_AIR_GAP_W_MK", "M_AIR_M", "P_MAX_RATIO"]

_RQ = 1.25                                              # RMS / Ra of a Gaussian profile
_EST = estimates.values()


def seat_sigma(Ra_seat_m: float, Ra_ring_m: float) -> float:
    """RMS roughness of a seat and a ring surface [m]: σ = √((1.25 Ra_1)² + (1.25 Ra_2)²) (Gaussian profiles).

    >>> round(seat_sigma(0.8e-6, 0.4e-6) * 1e6, 3)
    1.118
    """
    return math.hypot(_RQ * Ra_seat_m, _RQ * Ra_ring_m)


#: the data's nominal pairs (materials/network_builders.toml): shaft seat + ring bore, housing seat + ring OD
SIGMA_SHAFT_SEAT_M = seat_sigma(_EST["Ra_shaft_seat_m"], _EST["Ra_ring_seat_m"])
SIGMA_HOUSING_SEAT_M = seat_sigma(_EST["Ra_housing_seat_m"], _EST["Ra_ring_seat_m"])
H_MICRO_PA = _EST["H_micro_Pa"]   #: microhardness of the softer member (estimated, see the module docstring)
#: the joint correlation's upper pressure, P/H_c = 2 % (Yovanovich 2005): a tighter seat (a k5 fit on a
#: 10 mm shaft reaches ≈ 65 MPa) is given the conductance at this bound — a lower bound, as more
#: pressure conducts more, of a joint already conducting far better than the rings around it
P_MAX_RATIO = 0.02
K_AIR_GAP_W_MK = 0.029       #: air at 60 °C (materials/air_1atm.toml: 0.0287 W/m K at 333 K)
M_AIR_M = _EST["M_gas_m"]    #: gas rarefaction parameter of air at 1 atm (estimated, Yovanovich 2005)

_RING = {"k5": "inner", "m5": "inner", "g6": "inner", "H7": "outer", "N7": "outer"}


def probable_interference(d_m: float, seat: str) -> float:
    """Mean diametral interference of a ring on its seat [m] (negative: clearance).

    The middle of the fit's range, :func:`thermobear.contact.fits.fit_interference` (ISO 286 limits of the seat,
    ISO 492 normal class of the ring; the tables of ``materials/iso286_fits.toml``).

    Parameters
    ----------
    d_m : float   seat diameter [m] (bearing bore for a shaft seat, outside diameter for a housing), 3–400 mm
    seat : str    shaft ``"k5"``, ``"m5"``, ``"g6"`` or housing ``"H7"``, ``"N7"``

    >>> round(probable_interference(0.040, "k5") * 1e6, 1)     # k5 +2/+13, bore 0/-12
    13.5
    >>> round(probable_interference(0.080, "H7") * 1e6, 1)     # H7 0/+30, OD 0/-13
    -21.5
    """
    ring = _RING.get(seat)
    if ring is None:
        raise InputError("seat", seat, f"one of {', '.join(_RING)}")
    try:
        return float(fit_interference(d_m, seat, ring)[1])
    except InputError:
        field, key = ("bearing.bore_mm", "[shaft]") if ring == "inner" else ("bearing.outer_diameter_mm", "[housing]")
        raise InputError(field, d_m * 1e3, f"the fit tables (ISO 286, ISO 492) cover seats of 3 to 400 mm; give "
                         f"{key} interference_um") from None


def seat_conductance(delta_m: float, d_m: float, d_inner_m: float, d_outer_m: float, inner: Material,
                     outer: Material, sigma_m: float, *, F_r_N: float = 0.0, width_m: float = 0.0,
                     H_micro_Pa: float = H_MICRO_PA, M_gas_m: float = M_AIR_M) -> tuple:
    """Joint conductance of a ring seat [W/(m² K)] and the contact pressure [Pa].

    Parameters
    ----------
    delta_m : float         diametral interference (negative: clearance) [m]
    d_m : float             seat diameter [m]
    d_inner_m, d_outer_m : float  bore of the inner member (0: solid) and outside diameter of the
                            outer member [m]
    inner, outer : Material the inner member (shaft or ring) and the outer (ring or housing)
    sigma_m : float         RMS roughness of the pair [m]
    F_r_N, width_m : float  radial load and seat width (a clearance fit's loaded half) [N], [m]
    H_micro_Pa : float      microhardness of the softer member [Pa] (the correlation's pressure bound
                            is ``P_MAX_RATIO`` of it)
    M_gas_m : float         gas rarefaction parameter of the gaps' air [m]

    Returns
    -------
    (h [W/(m² K)], p [Pa])

    >>> from thermobear.contact.materials import material
    >>> s = material("aisi-52100")
    >>> h, p = seat_conductance(13.5e-6, 0.04, 0.0, 0.0473, material("steel-c45"), s, SIGMA_SHAFT_SEAT_M)
    >>> round(p / 1e6, 1), round(h, -3)
    (10.1, 38000.0)
    """
    p_max = P_MAX_RATIO * H_micro_Pa
    if delta_m > 0:
        p = float(fit_pressure(delta_m, d_m, d_inner_m, d_outer_m, inner.E, inner.nu, outer.E, outer.nu))
        return float(joint_conductance(inner.k, outer.k, min(p, p_max), sigma_m, H_micro_Pa, K_AIR_GAP_W_MK,
                                       M_gas_m)), p
    p = F_r_N / (width_m * d_m) if F_r_N > 0 and width_m > 0 else 0.0
    h_loaded = float(joint_conductance(inner.k, outer.k, min(p, p_max), sigma_m, H_micro_Pa, K_AIR_GAP_W_MK,
                                       M_gas_m))
    h_gap = K_AIR_GAP_W_MK / (0.5 * (-delta_m) + M_gas_m)
    return 0.5 * (h_loaded + h_gap), p
