r"""Lubricants: viscosity–temperature (ASTM D341), density, pressure–viscosity, thermal properties.

A :class:`Lubricant` is an oil, or a grease described by its base oil (every
film, rolling-force and SKF formula uses the base-oil properties: seed 000 §3,
seed 002 §4.3; SKF 2004).  Temperatures at the interface are in °C
(names end in ``_C``); everything else is SI except the kinematic viscosity,
returned in cSt (= mm²/s) because every correlation that uses it (Walther,
Gold, SKF) is written in cSt.

Models (one function each, all vectorised):

* kinematic viscosity  — ASTM D341 (Walther) with the exp correction term,
  fitted through ν40 and ν100 or through one point and a slope;
* density              — API MPMS 11.1 / ASTM D1250 thermal expansion of
  lubricating oils, ρ(T) = ρ15 exp[−a ΔT (1 + 0.8 a ΔT)], a = K1/ρ15;
* pressure–viscosity   — constant α_p, or Gold et al. (2001) α = s ν^t;
* thermal conductivity and specific heat — Cragoe (1929) petroleum-oil
  correlations, or constants from the data file.

Data: ``materials/lubricants/<name>.toml`` (see :func:`lubricant_names`); estimated values carry
their range in ``uncertainty`` (:func:`thermobear.schema.check_uncertainty`).

Per operating point: :meth:`Lubricant.per_point` gives the same lubricant with some data values as
arrays (B,) — one per operating point of a family, e.g. the draws of an uncertainty run — and every
property then broadcasts those values against the temperatures (the same formulas; a leading
batch axis B in the temperatures' last place, or :meth:`Lubricant.aligned` for trailing axes).

>>> oil = lubricant("seed004-mineral")
>>> round(oil.nu(40.0), 6), round(oil.nu(100.0), 6)
(36.6, 7.8)
>>> round(oil.eta(60.0), 4)
0.0163
"""
from __future__ import annotations

import copy
import functools

import numpy as np


from thermobear.arrays import within
from thermobear.files import data_dir, lookup, names_in, read_toml
from thermobear.errors import ExtrapolationWarning, InputError
from thermobear.schema import Field, check_table, check_uncertainty
from thermobear.validity import T_LUBRICANT_REFUSE_C, T_LUBRICANT_WARN_C, check as check_limit
from thermobear.units import ZERO_C_K
from thermobear.lubrication.viscosity_index import nu100_from_vi, viscosity_index
from thermobear.lubrication.walther import (_num, _scalar, _xp, walther_fit, walther_nu, walther_nu_from_Z,  # noqa: F401
                                            walther_temperature_coefficient, walther_Z, NU_MIN_CST)

__all__ = [
    "Lubricant", "lubricant", "lubricant_names",
    "walther_Z", "walther_nu_from_Z", "walther_fit", "walther_nu",
    "density_api", "gold_alpha_p", "cragoe_k_th", "cragoe_cp", "walther_temperature_coefficient",
    "traction_defaults",
    "T_WARN_C", "T_VALID_C",
]

#: Temperatures [°C] outside which a lubricant property is an extrapolation (ExtrapolationWarning)
#: and outside which thermobear refuses (InputError): :data:`thermobear.validity.LIMITS` ["lubricant_T"].
T_WARN_C = T_LUBRICANT_WARN_C
T_VALID_C = T_LUBRICANT_REFUSE_C

_T40_K = 40.0 + ZERO_C_K
_T100_K = 100.0 + ZERO_C_K
_RHO_WATER_15_KG_M3 = 999.0   # water at 60 °F (15.56 °C), for the specific gravity d in Cragoe's forms
_K1_API_LUBE = 0.34878 * 1.8  # kg/(m^3 K): API MPMS 11.1 lubricating-oil K1 = 0.34878 (per °F), x 1.8 per K


# ---------------------------------------------------------------------------
# Density, pressure-viscosity, thermal properties
# ---------------------------------------------------------------------------
def density_api(rho15, T_C, K1=_K1_API_LUBE):
    r"""Density of a lubricating oil at temperature, API MPMS 11.1 (ASTM D1250) form.

    Parameters
    ----------
    rho15 : array_like  density at 15 °C [kg/m³]
    T_C : array_like    temperature [°C]
    K1 : float          expansion constant [kg/(m³ K)]; 0.627804 for the
                        lubricating-oil group (API MPMS 11.1: K0 = 0,
                        K1 = 0.34878 with ΔT in °F, ×1.8 for °C)

    Returns
    -------
    ndarray  ρ = ρ15 exp[−a ΔT (1 + 0.8 a ΔT)],  a = K1/ρ15,  ΔT = T − 15 °C  [kg/m³]

    Notes
    -----
    API MPMS ch. 11.1 (2004) / ASTM D1250-04, lubricating-oil commodity group;
    the standard's base is 60 °F = 15.56 °C, taken here as 15 °C (0.04 %
    density difference).  a ≈ 7.3e-4 1/K at 865 kg/m³, inside the 6.5–7.5e-4 1/K typical of
    mineral oils.  Used also for synthetic base oils
    (estimated; esters and PAO have similar volumetric expansion).

    Examples
    --------
    >>> round(float(density_api(864.6, 40.0)), 1)
    848.8
    """
    rho15 = _num(rho15)
    a = K1 / rho15
    dT = _num(T_C) - 15.0
    x = -a * dT * (1.0 + 0.8 * a * dT)
    return rho15 * _xp(x).exp(x)


def gold_alpha_p(nu_cSt, s, t):
    r"""Pressure–viscosity coefficient of Gold et al. (2001) [1/Pa].

    Parameters
    ----------
    nu_cSt : array_like  kinematic viscosity at the operating temperature [cSt]
    s : float            coefficient [1/GPa] (seed 002 Table 1: 9.90 mineral, 7.38 PAO, 6.61 ester)
    t : float            exponent [-] (seed 002 Table 1: 0.13–0.14)

    Returns
    -------
    ndarray  α_p = s ν^t × 1e-9 [1/Pa]

    Notes
    -----
    Gold, Schmidt, Dicke, Loos & Assmann, J. Synthetic Lubrication 18 (2001) 51;
    quoted by seed 002 Table 1 as α(0.2 GPa) = s ν^t with α in 1/GPa and ν in
    mm²/s.  Seed 002's own α at 40 °C are reproduced within 2 % (MG1: 9.90·230^0.14
    = 21.2 vs 21.09 printed).

    Examples
    --------
    >>> round(float(gold_alpha_p(230.0, 9.90, 0.14)) * 1e9, 2)
    21.2
    """
    return s * _num(nu_cSt) ** t * 1e-9


def cragoe_k_th(rho15, T_C):
    r"""Thermal conductivity of a petroleum oil, Cragoe (1929) [W/(m K)].

    Parameters
    ----------
    rho15 : array_like  density at 15 °C [kg/m³]
    T_C : array_like    temperature [°C]

    Returns
    -------
    ndarray  k = 0.11726/d · (1 − 0.00054 T_C),  d = ρ15/999 kg/m³ [W/(m K)]

    Notes
    -----
    Cragoe, Thermal properties of petroleum products, US Bureau of Standards
    Misc. Publ. 97 (1929): k = 0.813/d [1 − 0.0003 (t − 32)] Btu·in/(h ft² °F),
    t in °F, converted to SI (1 Btu·in/(h ft² °F) = 0.144228 W/(m K)).
    Stated accuracy ≈ ±10 %.  [unconfirmed – recalled; SI conversion done here]

    Examples
    --------
    >>> round(float(cragoe_k_th(864.6, 40.0)), 4)
    0.1325
    """
    d = _num(rho15) / _RHO_WATER_15_KG_M3
    return 0.117257 / d * (1.0 - 0.00054 * _num(T_C))


def cragoe_cp(rho15, T_C):
    r"""Specific heat of a petroleum oil, Cragoe (1929) [J/(kg K)].

    Parameters
    ----------
    rho15 : array_like  density at 15 °C [kg/m³]
    T_C : array_like    temperature [°C]

    Returns
    -------
    ndarray  cp = (1684.8 + 3.391 T_C)/√d,  d = ρ15/999 kg/m³ [J/(kg K)]

    Notes
    -----
    Cragoe (1929, US Bureau of Standards Misc. Publ. 97):
    c = (0.388 + 0.00045 t)/√d Btu/(lb °F), t in °F, converted to SI.  The
    Btu form is quoted in public engineering forums; it gives the 1.9–2.1 kJ/(kg K) typical of
    mineral oils at 20–90 °C.

    Examples
    --------
    >>> round(float(cragoe_cp(864.6, 40.0)))
    1957
    """
    d = _num(rho15) / _RHO_WATER_15_KG_M3
    return (1684.8 + 3.391 * _num(T_C)) / _xp(d).sqrt(d)


_TRACTION_KEYS = ("eyring_stress_Pa", "limiting_shear_coefficient")


def traction_defaults(base_oil: str) -> dict:
    """Eyring stress [Pa] and limiting shear stress–pressure coefficient [-] of a base-oil family
    (``materials/lubricant_traction.toml``, sources there): keys ``eyring_stress_Pa``,
    ``limiting_shear_coefficient``, and ``uncertainty`` (key → :class:`~thermobear.schema.Uncertainty`,
    their ranges).

    >>> d = traction_defaults("mineral")
    >>> d["eyring_stress_Pa"], d["uncertainty"]["eyring_stress_Pa"].lo
    (5000000.0, 2000000.0)
    """
    table = read_toml(str(data_dir("materials") / "lubricant_traction.toml"))
    if base_oil not in table or not isinstance(table[base_oil], dict):
        raise InputError("lubricant.base_oil", base_oil, "traction data exist for "
                         + ", ".join(k for k, v in table.items() if isinstance(v, dict)))
    out = dict(table[base_oil])
    out["uncertainty"] = check_uncertainty(out.get("uncertainty", {}), {k: FIELDS[k] for k in _TRACTION_KEYS},
                                           f"lubricant_traction.{base_oil}")
    return out


# ---------------------------------------------------------------------------
# Lubricant
# ---------------------------------------------------------------------------
def _out(x, like):
    """Return a float for scalar input (and scalar properties), else an ndarray."""
    if type(x) is float:
        return x
    return float(x) if np.ndim(like) == 0 and np.ndim(x) == 0 else np.asarray(x, dtype=float)


def _plain(T_C) -> bool:
    """True for one temperature [°C] as a Python or numpy float inside T_WARN_C (no check, warning or
    error to give: :class:`Lubricant` evaluates its formulas on the Python float)."""
    return type(T_C) in (float, np.float64) and T_WARN_C[0] <= T_C <= T_WARN_C[1]


def _per_value(method):
    """A property evaluated on the Python float of a one-value array (a thermal element, or a batch of one
    operating point): the same formula without array overhead, the result shaped like the array."""
    @functools.wraps(method)
    def prop(self, T_C):
        if type(T_C) is np.ndarray and T_C.ndim and T_C.size == 1 and self.points is None:
            return np.full(T_C.shape, method(self, T_C.item()))
        return method(self, T_C)
    return prop


def _positive(field, v):
    """A finite positive value (or array of them, one per operating point)."""
    if v is None or not (np.all(np.isfinite(v)) and np.all(np.asarray(v) > 0)):
        raise InputError(field, v, "must be finite and > 0")
    return _scalar(v)


def _viscosity(field, nu, given=None):
    """A kinematic viscosity [cSt] the D341 form represents (:data:`~thermobear.lubrication.walther.NU_MIN_CST`);
    ``given``: the input it comes from, shown as the field's value."""
    if not np.all(walther_Z(nu) > 1.0):
        raise InputError(field, nu if given is None else given, f"kinematic viscosity must be > {NU_MIN_CST:.4g} cSt: "
                         "ASTM D341's log10 log10 Z (Z = ν + 0.7 + exp(…)) needs Z > 1")
    return nu


def _one_length(name, values):
    """The values given per operating point (arrays) share one length B, else InputError."""
    sizes = sorted({np.size(v) for v in values if v is not None and np.ndim(v)})
    if len(sizes) > 1:
        raise InputError(f"lubricant[{name}]", sizes, "per-point values must share one length B")


class Lubricant:
    r"""An oil, or a grease through its base oil.

    Parameters
    ----------
    nu40_cSt, nu100_cSt : float  kinematic viscosity at 40 / 100 °C [cSt]; ν100 < ν40
    rho15 : float                density at 15 °C [kg/m³]
    alpha_p : float, optional    constant pressure–viscosity coefficient [1/Pa]
    gold_s, gold_t : float, optional
                                 Gold et al. α_p = s ν^t (s in 1/GPa); used instead of
                                 alpha_p when given (temperature dependent)
    k_th, cp : float, optional   constant thermal conductivity [W/(m K)] and specific
                                 heat [J/(kg K)]; default: Cragoe (1929) correlations
    name, kind, base_oil, thickener, description : str
                                 labels; kind is "oil" or "grease"
    uncertainty : dict           data-file key → :class:`~thermobear.schema.Uncertainty` of its
                                 estimated values

    Every number may also be an array (B,), one value per operating point (:meth:`per_point`).

    Methods (T_C scalar or array [°C]; scalar in → float out)
    -------
    nu(T_C) [cSt], eta(T_C) [Pa s], rho(T_C) [kg/m³], alpha_p_at(T_C) [1/Pa],
    k_th(T_C) [W/(m K)], cp(T_C) [J/(kg K)], beta_at(T_C) [1/K]

    Attributes ``eyring_stress`` [Pa] and ``limiting_shear`` [-]: the base oil's traction properties
    (arguments ``eyring_stress``, ``limiting_shear``; default :func:`traction_defaults` of ``base_oil``).

    Notes
    -----
    Temperatures outside T_WARN_C = (-20, 150) °C give an ExtrapolationWarning,
    outside T_VALID_C = (-40, 250) °C an InputError.

    Examples
    --------
    >>> oil = Lubricant(nu40_cSt=36.6, nu100_cSt=7.8, rho15=864.6, alpha_p=20e-9)
    >>> round(oil.nu(40.0), 6), round(oil.alpha_p_at(80.0) * 1e9, 3)
    (36.6, 20.0)
    """

    def __init__(self, nu40_cSt, nu100_cSt, rho15, alpha_p=None, *, gold_s=None, gold_t=None,
                 k_th=None, cp=None, name="custom", kind="oil", base_oil="mineral",
                 thickener=None, description="", estimated=(), eyring_stress=None, limiting_shear=None,
                 uncertainty=None):
        _one_length(name, (nu40_cSt, nu100_cSt, rho15, alpha_p, gold_s, gold_t, k_th, cp, eyring_stress, limiting_shear))
        nu40 = _viscosity(f"lubricant[{name}].nu40_cSt", _positive(f"lubricant[{name}].nu40_cSt", nu40_cSt))
        nu100 = _viscosity(f"lubricant[{name}].nu100_cSt", _positive(f"lubricant[{name}].nu100_cSt", nu100_cSt))
        if not np.all(nu100 < nu40):
            raise InputError(f"lubricant[{name}].nu100_cSt", nu100_cSt,
                             f"must be < nu40_cSt = {nu40_cSt} (viscosity falls with temperature)")
        A, B = walther_fit(nu40, _T40_K, nu100, _T100_K)
        if not np.all(A - B * np.log10(T_VALID_C[0] + ZERO_C_K) < np.log10(308.0)):      # log10 log10 Z at -40 °C
            raise InputError(f"lubricant[{name}].nu100_cSt", nu100_cSt, f"with nu40_cSt = {nu40_cSt} the D341 line is so "
                             f"steep that ν overflows (beyond 1e308 cSt) at {T_VALID_C[0]:g} °C, an accepted temperature")
        self._setup(A, B, rho15, alpha_p, gold_s, gold_t, k_th, cp, name, kind, base_oil,
                    thickener, description, estimated, eyring_stress, limiting_shear, uncertainty)

    # shared by __init__ and from_single_point
    def _setup(self, A, B, rho15, alpha_p, gold_s, gold_t, k_th, cp, name, kind, base_oil,
               thickener, description, estimated, eyring_stress=None, limiting_shear=None, uncertainty=None):
        self.name, self.description = str(name), str(description)
        if kind not in ("oil", "grease"):
            raise InputError(f"lubricant[{name}].kind", kind, 'must be "oil" or "grease"')
        self.kind, self.base_oil, self.thickener = kind, base_oil, thickener
        self.walther_A, self.walther_B = _scalar(A), _scalar(B)
        self.rho15 = _positive(f"lubricant[{name}].rho15", rho15)
        if not np.all((500.0 < self.rho15) & (self.rho15 < 2500.0)):
            raise InputError(f"lubricant[{name}].rho15", rho15, "density at 15 °C must lie in 500-2500 kg/m^3")
        self.alpha_p = None if alpha_p is None else _positive(f"lubricant[{name}].alpha_p", alpha_p)
        if (gold_s is None) != (gold_t is None):
            raise InputError(f"lubricant[{name}].gold_s/gold_t", (gold_s, gold_t),
                             "give both Gold coefficients s [1/GPa] and t [-], or neither")
        self.gold_s = None if gold_s is None else _positive(f"lubricant[{name}].gold_s", gold_s)
        self.gold_t = None if gold_t is None else _positive(f"lubricant[{name}].gold_t", gold_t)
        self._k_th = None if k_th is None else _positive(f"lubricant[{name}].k_th", k_th)
        self._cp = None if cp is None else _positive(f"lubricant[{name}].cp", cp)
        self.estimated = tuple(estimated)
        fam = traction_defaults(base_oil) if eyring_stress is None or limiting_shear is None else {}
        self.eyring_stress = _positive(f"lubricant[{name}].eyring_stress_Pa",
                                       fam["eyring_stress_Pa"] if eyring_stress is None else eyring_stress)
        self.limiting_shear = _positive(f"lubricant[{name}].limiting_shear_coefficient",
                                        fam["limiting_shear_coefficient"] if limiting_shear is None else limiting_shear)
        self.uncertainty = dict(uncertainty or {})
        _one_length(name, self._numbers().values())
        sizes = {np.size(v) for v in self._numbers().values() if np.ndim(v)}
        self.points = sizes.pop() if sizes else None     # B when values are given per operating point
        self.table = {}                                   # the data-file values it was built from (from_dict)

    def _numbers(self) -> dict:
        return {"walther_A": self.walther_A, "walther_B": self.walther_B, "rho15": self.rho15, "alpha_p": self.alpha_p,
                "gold_s": self.gold_s, "gold_t": self.gold_t, "_k_th": self._k_th, "_cp": self._cp,
                "eyring_stress": self.eyring_stress, "limiting_shear": self.limiting_shear}

    def per_point(self, values: dict) -> "Lubricant":
        """This lubricant with data-file values given per operating point.

        Parameters
        ----------
        values : dict   data-file key (``rho15_kg_m3``, ``nu40_cSt``, ``k_W_mK``, ``walther_B``, …; a
                        numeric key of :data:`FIELDS` the lubricant was built from) → array (B,)

        Returns
        -------
        Lubricant   built by the same constructor from its data values with ``values`` replaced: every
                    property broadcasts those arrays against temperatures whose last axis is B (or
                    use :meth:`aligned`)

        >>> oil = lubricant("seed002-mg1").per_point({"rho15_kg_m3": np.array([880.0, 900.0, 920.0])})
        >>> oil.points, np.round(oil.rho(np.array([40.0, 40.0, 40.0])), 1).tolist()
        (3, [864.2, 884.2, 904.2])
        """
        if not values:
            return self
        if not self.table:
            raise InputError(f"lubricant[{self.name}]", None, "per-point values need a lubricant built from data "
                             "values (lubricant(name) or Lubricant.from_dict)")
        for key, v in values.items():
            if key not in self.table or FIELDS[key].kind != "number":
                raise InputError(f"lubricant[{self.name}].{key}", None, "a numeric value of this lubricant; it has: "
                                 + ", ".join(k for k in self.table if FIELDS[k].kind == "number"))
        t = {**self.table, **{k: np.asarray(v, dtype=float) for k, v in values.items()}}
        return _build(t, f"lubricant[{self.name}]")

    def sampled(self, draws: dict) -> "Lubricant":
        """This lubricant with drawn values per operating point: data-file key → draws (B,), each moved
        by the key's :class:`~thermobear.schema.Uncertainty` (factor × value, value + offset, or the
        drawn value) — :meth:`per_point` of the moved values.

        A drawn ν40 moves the whole viscosity curve at the viscosity index the nominal ν40 and ν100 (its own
        draw, or the nominal) give (ASTM D2270, :mod:`thermobear.lubrication.viscosity_index`): an oil at the upper
        end of its grade (ISO 3448: ±10 %) is more viscous at every temperature, and ν100's range keeps setting the
        viscosity index it was derived for (drawn apart, the two gave indices outside their sources' range).

        >>> oil = lubricant("iso-vg-46-mineral")
        >>> s = oil.sampled({"nu40_cSt": np.array([0.9, 1.1])})
        >>> np.round(viscosity_index(s.table["nu40_cSt"], s.table["nu100_cSt"]), 6).tolist()
        [100.0, 100.0]
        """
        for key in draws:
            if key not in self.uncertainty:
                raise InputError(f"sample.lubricant.{key}", None, f"lubricant {self.name} gives no uncertainty for "
                                 f"it; it has: {', '.join(self.uncertainty) or 'none'}")
        moved = {k: self.uncertainty[k].apply(self.table[k], np.asarray(v, float)) for k, v in draws.items()}
        if "nu40_cSt" in moved and "nu100_cSt" in self.table:
            vi = viscosity_index(self.table["nu40_cSt"], moved.get("nu100_cSt", self.table["nu100_cSt"]))
            moved["nu100_cSt"] = nu100_from_vi(moved["nu40_cSt"], vi)
        return self.per_point(moved)

    def aligned(self, trailing: int) -> "Lubricant":
        """The same lubricant with its per-point values shaped (B, 1, …) with ``trailing`` unit axes,
        for temperatures whose operating-point axis has ``trailing`` axes after it (e.g. (…, B, 2, Z)
        per contact: ``aligned(2)``); itself when its values are not per point."""
        if self.points is None or trailing == 0:
            return self
        obj = copy.copy(self)
        shape = (self.points,) + (1,) * trailing
        for k, v in self._numbers().items():
            if np.ndim(v):
                setattr(obj, k, np.reshape(v, shape))
        return obj

    @classmethod
    def from_single_point(cls, eta_Pa_s, T_C, rho15, walther_B=3.7, alpha_p=None, **kw):
        r"""Oil known by one dynamic viscosity at one temperature.

        Parameters
        ----------
        eta_Pa_s : float   dynamic viscosity at T_C [Pa s]
        T_C : float        temperature of that measurement [°C]
        rho15 : float      density at 15 °C [kg/m³] (estimated if unknown: 870 for mineral oil)
        walther_B : float  ASTM D341 slope B [-] (T in K).  Default 3.7 is an
                           ESTIMATE: the slope of VI = 100 mineral oils of
                           30–50 cSt at 40 °C (ASTM D2270; 3.70–3.77 for the
                           seed 001 oils).  walther_B = 0 gives a viscosity
                           constant in temperature (kinematic; η then follows
                           the density only, −0.07 %/K).
        alpha_p : float    pressure–viscosity coefficient [1/Pa], optional
        **kw               as for :class:`Lubricant` (name, k_th, cp, gold_s, ...)

        Notes
        -----
        The D341 line through (T, ν = η/ρ(T)) with slope B:
        A = log10 log10 Z(ν) + B log10 T_K.

        Examples
        --------
        >>> oil = Lubricant.from_single_point(eta_Pa_s=0.05, T_C=26.5, rho15=870.0, alpha_p=2.5e-8)
        >>> round(oil.eta(26.5), 6)
        0.05
        >>> oil.nu(40.0) < oil.nu(26.5)
        True
        """
        name = kw.get("name", "custom")
        _one_length(name, (eta_Pa_s, T_C, rho15, walther_B, alpha_p))
        eta = _positive(f"lubricant[{name}].eta_Pa_s", eta_Pa_s)
        if not (np.all(np.isfinite(T_C)) and np.all((T_VALID_C[0] <= np.asarray(T_C)) & (np.asarray(T_C) <= T_VALID_C[1]))):
            raise InputError(f"lubricant[{name}].T_C", T_C,
                                  f"reference temperature must lie in {T_VALID_C[0]}...{T_VALID_C[1]} °C")
        if walther_B is None or not (np.all(np.isfinite(walther_B))
                                     and np.all((0.0 <= np.asarray(walther_B)) & (np.asarray(walther_B) <= 10.0))):
            raise InputError(f"lubricant[{name}].walther_B", walther_B,
                             "D341 slope must lie in 0...10 (typical mineral oils 3-4)")
        rho15 = _positive(f"lubricant[{name}].rho15", rho15)
        nu_ref = _viscosity(f"lubricant[{name}].eta_Pa_s", eta / (_scalar(density_api(rho15, T_C)) * 1e-6), eta_Pa_s)
        A = _scalar(np.log10(np.log10(walther_Z(nu_ref)))) + walther_B * np.log10(T_C + ZERO_C_K)
        obj = cls.__new__(cls)
        obj._setup(A, walther_B, rho15, alpha_p, kw.get("gold_s"), kw.get("gold_t"), kw.get("k_th"),
                   kw.get("cp"), name, kw.get("kind", "oil"), kw.get("base_oil", "mineral"),
                   kw.get("thickener"), kw.get("description", ""), kw.get("estimated", ()),
                   kw.get("eyring_stress"), kw.get("limiting_shear"), kw.get("uncertainty"))
        return obj

    @classmethod
    def from_dict(cls, d: dict, where: str = "lubricant") -> "Lubricant":
        """Lubricant from a mapping with the data-file keys (scene files, inline definitions).

        Keys: nu40_cSt, nu100_cSt, rho15_kg_m3, alpha_p_1_Pa or gold_s_1_GPa + gold_t,
        k_W_mK, cp_J_kgK, or one point eta_ref_Pa_s (alias eta_Pa_s) at T_ref_C
        (alias T_C) with walther_B (default 3.7, estimated); labels name, kind, ...
        Errors name ``where`` (e.g. the scene section).

        >>> Lubricant.from_dict({"nu40_cSt": 36.6, "nu100_cSt": 7.8, "rho15_kg_m3": 864.6,
        ...                      "alpha_p_1_Pa": 20e-9}).nu(40.0)
        36.6
        """
        return _from_mapping(d, where)

    # -- derived reference values ------------------------------------------
    @property
    def nu40_cSt(self) -> float:
        """Kinematic viscosity at 40 °C [cSt] (input, or derived from a single point)."""
        return _scalar(walther_nu(self.walther_A, self.walther_B, _T40_K))

    @property
    def nu100_cSt(self) -> float:
        """Kinematic viscosity at 100 °C [cSt]."""
        return _scalar(walther_nu(self.walther_A, self.walther_B, _T100_K))

    def __repr__(self):
        if self.points is not None:
            return f"Lubricant(name={self.name!r}, kind={self.kind!r}, values per point: {self.points})"
        return (f"Lubricant(name={self.name!r}, kind={self.kind!r}, nu40_cSt={self.nu40_cSt:.4g}, "
                f"nu100_cSt={self.nu100_cSt:.4g}, rho15={self.rho15:.5g})")

    # -- temperature checks --------------------------------------------------
    def _T(self, T_C, what):
        T = np.asarray(T_C, dtype=float)
        if not within(T, *T_WARN_C):                                           # NaN fails too
            check_limit("lubricant_T", T, f"{self.name}.{what}(T_C)", category=ExtrapolationWarning)
        return T

    # -- properties -----------------------------------------------------------
    # One temperature as a Python float inside T_WARN_C (the thermal elements ask for one at a time)
    # needs no check: the formulas run on the float (with ``math``); anything else is checked first.
    @_per_value
    def nu(self, T_C):
        """Kinematic viscosity [cSt] at T_C [°C], ASTM D341 (see :func:`walther_nu`)."""
        if _plain(T_C) and self.points is None:
            return walther_nu(self.walther_A, self.walther_B, float(T_C) + ZERO_C_K)
        T = self._T(T_C, "nu")
        return _out(walther_nu(self.walther_A, self.walther_B, T + ZERO_C_K), T_C)

    @_per_value
    def rho(self, T_C):
        """Density [kg/m³] at T_C [°C] (see :func:`density_api`)."""
        if _plain(T_C) and self.points is None:
            return density_api(self.rho15, float(T_C))
        T = self._T(T_C, "rho")
        return _out(density_api(self.rho15, T), T_C)

    @_per_value
    def eta(self, T_C):
        """Dynamic viscosity [Pa s] at T_C [°C]: η = ν [cSt] × 1e-6 × ρ [kg/m³]."""
        if _plain(T_C):
            T = float(T_C)
        else:
            T = self._T(T_C, "eta")
        nu = walther_nu(self.walther_A, self.walther_B, T + ZERO_C_K)
        return _out(nu * 1e-6 * density_api(self.rho15, T), T_C)

    @_per_value
    def beta_at(self, T_C):
        """Temperature–viscosity coefficient −d ln η/dT [1/K] at T_C [°C]: ASTM D341
        (:func:`walther_temperature_coefficient`) plus the density's thermal expansion (:func:`density_api`)."""
        T = float(T_C) if _plain(T_C) else self._T(T_C, "beta_at")
        a = _K1_API_LUBE / self.rho15
        dT = T - 15.0
        return _out(walther_temperature_coefficient(self.walther_A, self.walther_B, T + ZERO_C_K)
                    + a * (1.0 + 1.6 * a * dT), T_C)

    def _const(self, v, T, T_C):
        """A constant property ``v`` shaped like the temperatures."""
        return v if type(T) is float else _out(np.broadcast_to(v, np.broadcast_shapes(np.shape(T), np.shape(v))) * 1.0, T_C)

    @_per_value
    def alpha_p_at(self, T_C):
        """Pressure–viscosity coefficient [1/Pa] at T_C [°C].

        Gold et al. s ν(T)^t when s, t are given (see :func:`gold_alpha_p`), else
        the constant alpha_p.  Raises InputError when neither is known.
        """
        T = float(T_C) if _plain(T_C) else self._T(T_C, "alpha_p_at")
        if self.gold_s is not None:
            nu = walther_nu(self.walther_A, self.walther_B, T + ZERO_C_K)
            return _out(gold_alpha_p(nu, self.gold_s, self.gold_t), T_C)
        if self.alpha_p is None:
            raise InputError(f"lubricant[{self.name}].alpha_p", None,
                             "unknown: give alpha_p [1/Pa] or Gold coefficients gold_s, gold_t")
        return self._const(self.alpha_p, T, T_C)

    @_per_value
    def k_th(self, T_C):
        """Thermal conductivity [W/(m K)] at T_C [°C]: constant, or Cragoe (1929) (:func:`cragoe_k_th`)."""
        T = float(T_C) if _plain(T_C) else self._T(T_C, "k_th")
        if self._k_th is not None:
            return self._const(self._k_th, T, T_C)
        return _out(cragoe_k_th(self.rho15, T), T_C)

    @_per_value
    def cp(self, T_C):
        """Specific heat [J/(kg K)] at T_C [°C]: constant, or Cragoe (1929) (:func:`cragoe_cp`)."""
        T = float(T_C) if _plain(T_C) else self._T(T_C, "cp")
        if self._cp is not None:
            return self._const(self._cp, T, T_C)
        return _out(cragoe_cp(self.rho15, T), T_C)


# ---------------------------------------------------------------------------
# Data files
# ---------------------------------------------------------------------------
def lubricant_names() -> list[str]:
    """Names of the bundled lubricants (``materials/lubricants/*.toml``).

    >>> "seed004-mineral" in lubricant_names()
    True
    """
    return names_in(data_dir("materials") / "lubricants")


#: The keys of a lubricant table (data files, inline scene tables), with their kinds and units.
FIELDS = {
    "name": Field.text("label"),
    "kind": Field.choice("oil", "grease", doc="oil, or grease (the models use its base oil)"),
    "description": Field.text(),
    "base_oil": Field.choice("mineral", "PAO", "ester", "ester+vegetal", "glycol", "silicone",
                             doc="base oil family"),
    "thickener": Field.text("grease thickener"),
    "nu40_cSt": Field.number("cSt", 0.0, None, lo_open=True, doc="kinematic viscosity at 40 °C"),
    "nu100_cSt": Field.number("cSt", 0.0, None, lo_open=True, doc="kinematic viscosity at 100 °C"),
    "rho15_kg_m3": Field.number("kg/m^3", 500.0, 2500.0, doc="density at 15 °C"),
    "alpha_p_1_Pa": Field.number("1/Pa", 0.0, 1e-7, lo_open=True, doc="pressure-viscosity coefficient"),
    "gold_s_1_GPa": Field.number("1/GPa", 0.0, None, lo_open=True, doc="Gold et al. 2001 alpha = s nu^t"),
    "gold_t": Field.number("-", 0.0, 1.0, doc="Gold et al. 2001 exponent"),
    "alpha40_1_GPa": Field.number("1/GPa", 0.0, None, lo_open=True, doc="reference only"),
    "thermal": Field.choice("cragoe", "given", doc="thermal properties: Cragoe 1929, or k_W_mK and cp_J_kgK"),
    "k_W_mK": Field.number("W/(m K)", 0.0, 10.0, lo_open=True, doc="thermal conductivity"),
    "cp_J_kgK": Field.number("J/(kg K)", 0.0, 1e4, lo_open=True, doc="specific heat"),
    "eta_ref_Pa_s": Field.number("Pa s", 0.0, None, lo_open=True, doc="one viscosity point (with T_ref_C)"),
    "T_ref_C": Field.number("°C", -60.0, 250.0, doc="temperature of eta_ref_Pa_s"),
    "walther_B": Field.number("-", 0.0, 10.0, lo_open=True, doc="ASTM D341 slope (one-point lubricants)"),
    "estimated": Field.names("keys whose values are estimates"),
    "uncertainty": Field.table("ranges of estimated values (thermobear.schema.check_uncertainty)"),
    "grease_T_min_C": Field.number("°C", -100.0, 300.0, doc="grease operating range (maker)"),
    "grease_T_max_C": Field.number("°C", -100.0, 300.0, doc="grease operating range (maker)"),
    "eyring_stress_Pa": Field.number("Pa", 0.0, None, lo_open=True,
                                     doc="Eyring stress of the base oil (traction; default by base_oil family)"),
    "limiting_shear_coefficient": Field.number("-", 0.0, 1.0, lo_open=True,
                                               doc="limiting shear stress / pressure (traction; default by family)"),
}
_ALIASES = {"eta_Pa_s": "eta_ref_Pa_s", "T_C": "T_ref_C"}


def _from_mapping(d: dict, where: str) -> Lubricant:
    """Build a Lubricant from data-file keys (units in the key names), naming ``where`` in errors."""
    d = {_ALIASES.get(k, k): v for k, v in d.items()}
    d = check_table(d, FIELDS, where)
    if d.get("thermal", "cragoe") != "cragoe" and ("k_W_mK" not in d or "cp_J_kgK" not in d):
        raise InputError(f"{where}.thermal", d.get("thermal"), '"cragoe", or give k_W_mK and cp_J_kgK')
    d["uncertainty"] = check_uncertainty(d.get("uncertainty", {}),
                                         {k: FIELDS[k] for k in d if FIELDS[k].kind == "number"}, where)
    return _build(_with_traction_defaults(d), where)


def _with_traction_defaults(d: dict) -> dict:
    """The data values with the base-oil family's traction values (:func:`traction_defaults`) where the
    lubricant gives none: listed as estimated, with the family's ranges (so that they are sampled)."""
    missing = [k for k in _TRACTION_KEYS if k not in d]
    if not missing:
        return d
    fam = traction_defaults(d.get("base_oil", "mineral"))
    return {**d, **{k: fam[k] for k in missing}, "estimated": tuple(d.get("estimated", ())) + tuple(missing),
            "uncertainty": {**{k: fam["uncertainty"][k] for k in missing if k in fam["uncertainty"]},
                            **d["uncertainty"]}}


def _build(d: dict, where: str) -> Lubricant:
    """The Lubricant of typed data-file values (numbers, or arrays (B,) per operating point)."""
    common = dict(alpha_p=d.get("alpha_p_1_Pa"), gold_s=d.get("gold_s_1_GPa"), gold_t=d.get("gold_t"),
                  k_th=d.get("k_W_mK"), cp=d.get("cp_J_kgK"), name=d.get("name", "custom"),
                  kind=d.get("kind", "oil"), base_oil=d.get("base_oil", "mineral"),
                  thickener=d.get("thickener"), description=d.get("description", ""),
                  estimated=d.get("estimated", ()), eyring_stress=d.get("eyring_stress_Pa"),
                  limiting_shear=d.get("limiting_shear_coefficient"), uncertainty=d.get("uncertainty"))
    lub = _construct(d, where, common)
    lub.table = {k: v for k, v in d.items() if k != "uncertainty"}
    return lub


def _construct(d: dict, where: str, common: dict) -> Lubricant:
    if "eta_ref_Pa_s" in d:
        for key in ("T_ref_C", "rho15_kg_m3"):
            if key not in d:
                raise InputError(f"{where}.{key}", None, "missing (needed with eta_ref_Pa_s)")
        return Lubricant.from_single_point(eta_Pa_s=d["eta_ref_Pa_s"], T_C=d["T_ref_C"],
                                           rho15=d["rho15_kg_m3"], walther_B=d.get("walther_B", 3.7),
                                           **common)
    for key in ("nu40_cSt", "nu100_cSt", "rho15_kg_m3"):
        if key not in d:
            raise InputError(f"{where}.{key}", None, "missing required field")
    return Lubricant(d["nu40_cSt"], d["nu100_cSt"], d["rho15_kg_m3"], **common)


def lubricant(name) -> Lubricant:
    """Bundled lubricant by name (a :class:`Lubricant` is returned unchanged).

    Files give either ``nu40_cSt`` and ``nu100_cSt``, or one point
    ``eta_ref_Pa_s`` at ``T_ref_C`` with an (estimated) ``walther_B``.

    >>> lubricant("mol-liton-00").kind
    'grease'
    """
    if isinstance(name, Lubricant):
        return name
    d = lookup("materials", "lubricants", str(name), "lubricant")
    return _from_mapping({"name": str(name), **d}, f"lubricants/{name}.toml")
