r"""Ball bearing internal geometry and the bearing catalog.

``BallBearing`` holds the internal geometry in SI and derives what the
mechanics needs: the distance between groove curvature centres A, the free
contact angle, the reduced radii of each contact as functions of the contact
angle, the contact stiffnesses.  The catalog is data: the seed papers'
bearings in ``materials/bearings.toml`` and the common series (deep groove
60, 62, 63, 618, 619, 160; angular contact 72 B, 73 B; spindle 70 C/E,
719 C/E; thrust 511, 512, 513) in ``materials/bearings/<series>.toml``,
written by ``validation/catalogue.py``.  Radial internal clearance groups
(ISO 5753-1) are data too: ``materials/iso5753_clearance.toml``.

Conventions (Harris 2001 ch. 2; seed 004 eqs 1–5): x is the
rolling direction, y the transverse one; osculations f = r/D; diametral
clearance Pd = d_o − d_i − 2D; A = (fi + fo − 1) D; cos α0 = 1 − Pd/(2A) (Pd < 0, a radial preload of a deep groove
bearing: α0 = 0, the groove centres A_r0 = A − Pd/2 apart with the rings centred); γ = D cos α / dm.
"""
from __future__ import annotations

import difflib
import numbers
import re
from dataclasses import dataclass, field, fields, replace

import numpy as np

from thermobear.arrays import instance_of
from thermobear.files import data_dir, read_toml
from thermobear.errors import InputError, NoConvergence
from thermobear.schema import Field, check_table, check_uncertainty, check_value
from thermobear.validity import check as check_limit
from thermobear.contact.hertz import contact_stiffness, series_stiffness
from thermobear.contact.materials import Material, material, reduced_modulus

__all__ = ["BallBearing", "bearing", "bearing_names", "bearing_series", "bearing_table", "bearing_from_dict",
           "bearing_values", "canonical_designation", "radial_clearance", "KINDS", "CLEARANCE_GROUPS"]

KINDS = ("deep_groove", "angular_contact", "thrust")
#: ISO 5753-1 radial internal clearance groups in the data file (normal, larger, larger still).
CLEARANCE_GROUPS = ("CN", "C3", "C4")
#: number of balls a bearing may have: 3 hold the rings (seed 001's three-ball rig), 200 beyond any catalogue bearing
Z_RANGE = (3, 200)


def _default_steel() -> Material:
    return material("aisi-52100")


@dataclass(frozen=True)
class BallBearing:
    r"""Internal geometry of a single-row ball bearing (SI units).

    Parameters
    ----------
    D : float             ball diameter [m]
    dm : float            pitch diameter (ball-centre circle) [m]
    Z : int               number of balls [-]
    fi, fo : float        inner / outer osculation r/D [-], > 0.5
    Pd : float            diametral clearance [m] (deep groove; derived for the others); negative: a radial
                          preload, every ball compressed by −Pd/2 between the centred rings (contact angle 0,
                          :attr:`A_r0`), as the fits and temperatures of a mounted bearing make it
                          (:func:`~thermobear.contact.fits.operating_clearance`); > −2A.  A bearing table
                          (``Pd_mm``: catalogue, scene) states the unmounted clearance, ≥ 0
    alpha0 : float        free contact angle [rad]; required for angular contact,
                          π/2 for thrust; derived from Pd for deep groove if not given
    kind : str            ``"deep_groove"``, ``"angular_contact"`` or ``"thrust"``
    ball_material, ring_material : Material   (default AISI 52100), or a material's catalogue name
    name : str            label
    bore, outer_diameter, width : float   boundary dimensions [m] (optional; the SKF
                          model and thermal networks need them)
    series : str          series key (e.g. "62", "72B", "511"; also the SKF global model's key)
    C0, C : float         static / dynamic load rating [N] (optional; the catalogue stores the ISO 76 /
                          ISO 281 values of the geometry, :mod:`thermobear.rating` computes them)
    clearance_group : str ISO 5753-1 group ("CN", "C3", "C4") whose mid value gave Pd (deep groove), or None
    estimated : tuple     names of fields that are estimates, not published data
    uncertainty : dict    table key (``D_mm``, ``fi`` …) → :class:`~thermobear.schema.Uncertainty` of the
                          estimated values (:func:`bearing_values` applies drawn values)

    Examples
    --------
    The ISO/TS 16281 reference ball bearing:

    >>> from thermobear import Material
    >>> steel = Material(E=2.1e11, nu=0.3, rho=7850.0)
    >>> brg = BallBearing(D=11.5e-3, dm=43.5e-3, Z=7, fi=0.52, fo=0.53, Pd=0.0,
    ...                   kind="deep_groove", ball_material=steel, ring_material=steel)
    >>> round(brg.A * 1e3, 4), round(brg.Ry_i * 1e3, 2), round(float(brg.Rx_i(0.0)) * 1e3, 4)
    (0.575, 149.5, 4.23)
    """

    D: float
    dm: float
    Z: int
    fi: float
    fo: float
    Pd: float | None = None
    alpha0: float | None = None
    kind: str = "deep_groove"
    ball_material: Material = field(default_factory=_default_steel)
    ring_material: Material = field(default_factory=_default_steel)
    name: str = "custom"
    bore: float | None = None
    outer_diameter: float | None = None
    width: float | None = None
    series: str | None = None
    C0: float | None = None
    estimated: tuple = ()
    C: float | None = None
    clearance_group: str | None = None
    uncertainty: dict = field(default_factory=dict, compare=False, hash=False, repr=False)
    #: (K_i, K_o, K_n) at the nominal angle, exact Hertz [N/m^1.5]: derived once when the (immutable)
    #: bearing is built (None where Hertz refuses the geometry: :meth:`Kn` then raises its error)
    K_nominal: tuple | None = field(init=False, default=None, compare=False, hash=False, repr=False)

    def __post_init__(self):
        self._check()
        try:
            an = self.alpha_nominal
            Ki, Ko = float(self.K_i(an)), float(self.K_o(an))
            object.__setattr__(self, "K_nominal", (Ki, Ko, float(series_stiffness(Ki, Ko))))
        except (InputError, NoConvergence):
            pass

    def _check(self):
        """Validate the fields and derive alpha0, Pd (set once, while the object is built)."""
        p = f"bearing[{self.name}]"
        if self.kind not in KINDS:
            raise InputError(f"{p}.kind", self.kind, f"must be one of {', '.join(KINDS)}")
        for fld in ("ball_material", "ring_material"):     # a Material, or its catalogue name
            object.__setattr__(self, fld, instance_of(getattr(self, fld), Material, f"{p}.{fld}", material))
        for fld in ("D", "dm"):
            v = getattr(self, fld)
            if isinstance(v, bool) or not isinstance(v, numbers.Real) or not (np.isfinite(v) and v > 0):
                raise InputError(f"{p}.{fld}", v, "must be a finite length > 0 [m]")
        if self.D >= self.dm:
            raise InputError(f"{p}.D", self.D, f"ball diameter must be smaller than the pitch diameter dm = {self.dm} m")
        for fld, unit in (("Z", "-"), ("alpha0", "rad"), ("Pd", "m"), ("bore", "m"), ("outer_diameter", "m"),
                          ("width", "m"), ("C0", "N"), ("C", "N")):
            v = getattr(self, fld)
            if (v is not None or fld == "Z") and (isinstance(v, bool) or not isinstance(v, numbers.Real)
                                                   or not np.isfinite(v)):
                raise InputError(f"{p}.{fld}", v, f"must be a finite number [{unit}]")
        if int(self.Z) != self.Z or not Z_RANGE[0] <= self.Z <= Z_RANGE[1]:
            raise InputError(f"{p}.Z", self.Z, f"number of balls must be an integer in [{Z_RANGE[0]}, {Z_RANGE[1]}]")
        if self.D > self.dm * np.sin(np.pi / self.Z) * (1 + 1e-9):
            raise InputError(f"{p}.Z", self.Z, f"{self.Z} balls of D = {self.D * 1e3:.4g} mm do not fit on "
                             f"dm = {self.dm * 1e3:.4g} mm (need D <= dm sin(pi/Z))")
        for fld in ("fi", "fo"):
            v = getattr(self, fld)
            if isinstance(v, bool) or not isinstance(v, numbers.Real):
                raise InputError(f"{p}.{fld}", v, "osculation must be a number (groove radius / ball diameter)")
            check_limit("osculation", v, f"{p}.{fld}", warn=False)
        A = (self.fi + self.fo - 1.0) * self.D
        a0, Pd = self.alpha0, self.Pd
        if self.kind == "thrust":
            if a0 is None:
                a0 = np.pi / 2
            if not (np.pi / 4 <= a0 <= np.pi / 2 + 1e-12):
                raise InputError(f"{p}.alpha0", a0, "thrust bearing contact angle must lie in [45°, 90°] [rad]")
            if Pd not in (None, 0.0):
                raise InputError(f"{p}.Pd", Pd, "a thrust bearing has no diametral clearance; leave Pd unset")
            Pd = 2.0 * A * (1.0 - np.cos(a0))
        elif self.kind == "angular_contact":
            if a0 is None:
                raise InputError(f"{p}.alpha0", None, "an angular contact bearing needs its free contact angle alpha0 in (0°, 60°] [rad]")
            if not (0.0 < a0 <= np.pi / 3 + 1e-12):
                raise InputError(f"{p}.alpha0", a0, "free contact angle must lie in (0°, 60°] [rad]")
            implied = 2.0 * A * (1.0 - np.cos(a0))
            if Pd is not None and abs(Pd - implied) > 1e-3 * max(implied, 1e-9):
                raise InputError(f"{p}.Pd", Pd, f"inconsistent with alpha0: Pd = 2A(1 - cos alpha0) = {implied:.4g} m; give one of them")
            Pd = implied
        else:  # deep groove
            if Pd is None:
                Pd = 0.0 if a0 is None else 2.0 * A * (1.0 - np.cos(a0))
            if not np.isfinite(Pd):
                raise InputError(f"{p}.Pd", Pd, "diametral clearance must be finite [m]")
            if Pd >= 2.0 * A:
                raise InputError(f"{p}.Pd", Pd, f"clearance must be < 2A = {2 * A:.4g} m (else the free contact angle exceeds 90°)")
            if Pd <= -2.0 * A:     # a radial preload: every ball compressed by −Pd/2 (< A)
                raise InputError(f"{p}.Pd", Pd, f"a negative clearance (radial preload) must be > −2A = {-2 * A:.4g} m")
            a_from_pd = float(np.arccos(1.0 - Pd / (2.0 * A))) if Pd >= 0 else 0.0
            if a0 is not None and abs(a0 - a_from_pd) > 1e-6:
                raise InputError(f"{p}.alpha0", a0, f"inconsistent with Pd: arccos(1 - Pd/2A) = {a_from_pd:.6g} rad; give one of them")
            a0 = a_from_pd
        object.__setattr__(self, "alpha0", float(a0))
        object.__setattr__(self, "Pd", float(Pd))
        object.__setattr__(self, "Z", int(self.Z))
        if self.bore is not None and not (0 < self.bore < self.dm - self.D):
            raise InputError(f"{p}.bore", self.bore, f"bore must lie in (0, dm − D = {self.dm - self.D:.6g} m) "
                             "(the inner ring needs a wall under the raceway)")
        if self.outer_diameter is not None and not (self.outer_diameter > self.dm + self.D):
            raise InputError(f"{p}.outer_diameter", self.outer_diameter,
                             f"outer diameter must exceed dm + D = {self.dm + self.D:.6g} m")
        if self.width is not None and not (self.width > 0):
            raise InputError(f"{p}.width", self.width, "width must be > 0 [m]")
        if self.C0 is not None and not (self.C0 > 0):
            raise InputError(f"{p}.C0", self.C0, "static load rating must be > 0 [N]")
        if self.C is not None and not (self.C > 0):
            raise InputError(f"{p}.C", self.C, "dynamic load rating must be > 0 [N]")
        if self.clearance_group is not None and self.clearance_group not in CLEARANCE_GROUPS:
            raise InputError(f"{p}.clearance_group", self.clearance_group,
                             f"must be one of {', '.join(CLEARANCE_GROUPS)} (ISO 5753-1)")

    # ---- derived geometry -------------------------------------------------
    @property
    def total_curvature(self) -> float:
        """B = fi + fo − 1 [-] (Harris 2001 eq 2.8)."""
        return self.fi + self.fo - 1.0

    @property
    def A(self) -> float:
        """Distance between the groove curvature centres, unloaded: A = (fi + fo − 1) D [m] (seed 004 eq 2)."""
        return self.total_curvature * self.D

    @property
    def A_r0(self) -> float:
        r"""Radial distance between the groove curvature centres with the rings centred [m].

        .. math:: A_{r0} = A − P_d/2

        the inner raceway's groove centre at d_i/2 + r_i, the outer's at d_o/2 − r_o, so that their distance is
        r_i + r_o − (d_o − d_i)/2 = A − P_d/2 (P_d = d_o − d_i − 2D; Harris & Kotzalas 2007 [1] ch. 2, ball bearings).
        With a clearance (P_d ≥ 0) it is A cos α0 (the free contact angle cos α0 = 1 − P_d/(2A) of [1] ch. 2), evaluated so; with a
        negative clearance (a radial preload) it exceeds A: every ball is compressed by A_r0 − A = −P_d/2
        between the centred rings (:func:`thermobear.contact.fits.clearance_preload`).

        References
        ----------
        .. [1] Harris, T. A., Kotzalas, M. N. (2007), *Essential Concepts of Bearing Technology* (Rolling Bearing
           Analysis, 5th ed., vol. 1), CRC Press, ch. 2 (ball bearings: diametral clearance, free contact angle).

        Examples
        --------
        >>> b = bearing("6208")
        >>> round(b.with_(Pd=-8e-6).A_r0 - b.A, 12), bool(abs(b.A_r0 - b.A * np.cos(b.alpha0)) < 1e-18)
        (4e-06, True)
        """
        if self.Pd < 0:
            return self.A - 0.5 * self.Pd
        return float(self.A * np.cos(self.alpha0))

    @property
    def A_a0(self) -> float:
        r"""Axial distance between the groove curvature centres where the balls first touch both races
        (no load) [m]

        .. math:: A_{a0} = A \sin α_0

        0 with a radial preload (P_d < 0, α0 = 0: the
        rings are centred and already compress the balls, :attr:`A_r0`).  Harris & Kotzalas 2007 ch. 2 (free end play
        P_e = 2 A sin α0).

        >>> round(bearing("7210").A_a0 * 1e6, 3), bearing("6208").with_(Pd=-8e-6).A_a0
        (326.536, 0.0)
        """
        return float(self.A * np.sin(self.alpha0))

    @property
    def alpha_nominal(self) -> float:
        """Nominal contact angle [rad]: 0 for deep groove, alpha0 otherwise.

        The load–deflection constant is evaluated here by default (ISO/TS 16281
        practice; the reference cases in tests/test_loads.py use it)."""
        return 0.0 if self.kind == "deep_groove" else self.alpha0

    @property
    def free_end_play(self) -> float:
        """Pe = 2 A sin α0 [m] (Harris 2001 eq 2.16)."""
        return 2.0 * self.A * np.sin(self.alpha0)

    @property
    def E_prime(self) -> float:
        """Reduced modulus of the ball–ring pair [Pa]."""
        return reduced_modulus(self.ball_material, self.ring_material)

    @property
    def Ry_i(self) -> float:
        """Reduced transverse radius, inner contact: fi D/(2 fi − 1) [m] (seed 004 eq 5)."""
        return self.fi * self.D / (2.0 * self.fi - 1.0)

    @property
    def Ry_o(self) -> float:
        """Reduced transverse radius, outer contact: fo D/(2 fo − 1) [m] (seed 004 eq 5)."""
        return self.fo * self.D / (2.0 * self.fo - 1.0)

    @property
    def R_inner_locus(self) -> float:
        """Radius of the locus of inner groove curvature centres [m]: dm/2 + (fi − ½) D cos α0 (Harris 2001 §7.4)."""
        return 0.5 * self.dm + (self.fi - 0.5) * self.D * np.cos(self.alpha0)

    @property
    def clearance_range(self) -> tuple[float, float] | None:
        """(min, max) radial internal clearance of the bearing's ISO 5753-1 group [m], or None.

        Needs ``clearance_group`` and ``bore`` (see :func:`radial_clearance`); Pd is the mid value."""
        if self.clearance_group is None or self.bore is None:
            return None
        return radial_clearance(self.bore, self.clearance_group)

    @property
    def ball_mass(self) -> float:
        """Mass of one ball [kg]."""
        return self.ball_material.rho * np.pi * self.D**3 / 6.0

    def gamma(self, alpha):
        """γ = D cos α / dm [-] (seed 004 eq 3); α [rad], scalar or array."""
        return self.D * np.cos(alpha) / self.dm

    def Rx_i(self, alpha):
        """Reduced rolling-direction radius, inner contact: D(1 − γ)/2 [m] (seed 004 eq 4)."""
        return 0.5 * self.D * (1.0 - self.gamma(alpha))

    def Rx_o(self, alpha):
        """Reduced rolling-direction radius, outer contact: D(1 + γ)/2 [m] (seed 004 eq 4).

        For a thrust bearing (α = 90°) both are D/2: the race is flat in the rolling direction."""
        return 0.5 * self.D * (1.0 + self.gamma(alpha))

    def K_i(self, alpha, method: str = "exact"):
        """Load–deflection constant of the inner contact, Q = K δ^1.5 [N/m^1.5]."""
        return contact_stiffness(self.Rx_i(alpha), self.Ry_i, self.E_prime, method)

    def K_o(self, alpha, method: str = "exact"):
        """Load–deflection constant of the outer contact [N/m^1.5]."""
        return contact_stiffness(self.Rx_o(alpha), self.Ry_o, self.E_prime, method)

    def Kn(self, alpha=None, method: str = "exact"):
        r"""Ball load–deflection constant, both contacts in series [N/m^1.5].

        K_n = [K_i^(−2/3) + K_o^(−2/3)]^(−3/2) (Harris 2001 eq 7.3), at the contact
        angle α [rad] (default: the nominal angle).

        >>> from thermobear import Material
        >>> s = Material(E=2.1e11, nu=0.3)
        >>> b = BallBearing(D=11.5e-3, dm=43.5e-3, Z=7, fi=0.52, fo=0.53, ball_material=s, ring_material=s)
        >>> round(float(b.Kn()) * 10**-4.5)   # N/mm^1.5 (ISO/TS 16281 reference bearing)
        333592
        """
        if alpha is None:
            if method == "exact" and self.K_nominal is not None:
                return self.K_nominal[2]
            alpha = self.alpha_nominal
        return series_stiffness(self.K_i(alpha, method), self.K_o(alpha, method))

    def with_(self, **changes) -> "BallBearing":
        """Copy with some fields changed (validated again).

        Derived clearance data follow the change: a new ``Pd`` re-derives ``alpha0`` of a
        deep groove bearing, a new ``alpha0`` re-derives ``Pd``; either drops ``clearance_group``
        unless it is given too."""
        unknown = sorted(set(changes) - {f.name for f in fields(self) if f.init})
        if unknown:
            raise InputError(f"bearing[{self.name}].{unknown[0]}", changes[unknown[0]],
                             f"unknown field; accepted: {', '.join(f.name for f in fields(self) if f.init)}")
        kind = changes.get("kind", self.kind)
        if ("Pd" in changes or "alpha0" in changes) and "clearance_group" not in changes:
            changes["clearance_group"] = None # the group no longer names where Pd came from
        if kind == "deep_groove":
            if "alpha0" in changes and "Pd" not in changes:
                changes["Pd"] = None          # re-derive Pd from the new alpha0
            elif "alpha0" not in changes:
                changes["alpha0"] = None      # re-derive alpha0 from Pd (kept or changed)
        elif "Pd" not in changes:
            changes["Pd"] = None              # re-derive Pd from alpha0
        return replace(self, **changes)


# ---- catalog ----------------------------------------------------------------
_MM_KEYS = {"D_mm": "D", "dm_mm": "dm", "Pd_mm": "Pd", "bore_mm": "bore",
            "outer_diameter_mm": "outer_diameter", "width_mm": "width"}
#: The keys of a bearing table (catalogue entries, inline scene tables), with their kinds and units;
#: the physical limits (osculation, balls that fit, contact angle) are checked by BallBearing.
FIELDS = {
    "D_mm": Field.number("mm", 0.0, 1000.0, lo_open=True, doc="ball diameter", required=True),
    "dm_mm": Field.number("mm", 0.0, 5000.0, lo_open=True, doc="pitch diameter", required=True),
    "Z": Field.integer("-", *Z_RANGE, doc="number of balls", required=True),
    "fi": Field.number("-", doc="inner osculation r/D", required=True),
    "fo": Field.number("-", doc="outer osculation r/D", required=True),
    "Pd_mm": Field.number("mm", 0.0, 10.0, doc="unmounted diametral clearance (>= 0; a radial preload arises from "
                          "the fits and temperatures: shaft_fit, housing_fit, models.clearance)"),
    "alpha0_deg": Field.number("deg", 0.0, 90.0, doc="free contact angle"),
    "kind": Field.choice(*KINDS, doc="bearing type"),
    "bore_mm": Field.number("mm", 0.0, 5000.0, lo_open=True, doc="bore diameter"),
    "outer_diameter_mm": Field.number("mm", 0.0, 6000.0, lo_open=True, doc="outer diameter"),
    "width_mm": Field.number("mm", 0.0, 1000.0, lo_open=True, doc="width (height of a thrust bearing)"),
    "ball_material": Field.text("material name (materials/solids)"),
    "ring_material": Field.text("material name (materials/solids)"),
    "series": Field.text("series (e.g. 62, 72B)"),
    "C0_kN": Field.number("kN", 0.0, None, lo_open=True, doc="basic static load rating"),
    "C_kN": Field.number("kN", 0.0, None, lo_open=True, doc="basic dynamic load rating"),
    "clearance_group": Field.text("ISO 5753-1 radial clearance group (CN, C3, C4, ...)"),
    "estimated": Field.names("keys whose values are estimates"),
    "uncertainty": Field.table("ranges of estimated values (thermobear.schema.check_uncertainty)"),
    "aliases": Field.names("other designations"),
    "name": Field.text(), "description": Field.text(), "source": Field.text(),
}


def canonical_designation(name: str) -> str:
    """Canonical form of a catalogue designation: spaces removed, letters upper case.

    "7205 B", "7205b" -> "7205B"; "7014 c" -> "7014C"; "6208" unchanged.  Names with a hyphen or
    lower-case words (the seed bearings "iso-dgbb", "51205-3ball") are returned as given.

    >>> canonical_designation("7205 b"), canonical_designation("iso-dgbb")
    ('7205B', 'iso-dgbb')
    """
    s = str(name).strip()
    if "-" in s or not s[:1].isdigit():
        return s
    return s.replace(" ", "").upper()


def _catalog() -> dict:
    """Every catalogue entry by name: the seed file, then materials/bearings/*.toml (one file per series).

    A name defined twice is a data error (InputError naming both files); aliases of an entry
    (``aliases = [...]``) are not keys here — see :func:`_resolve`."""
    base = data_dir("materials")
    out = dict(read_toml(str(base / "bearings.toml")))
    folder = base / "bearings"
    if folder.is_dir():
        for path in sorted(folder.glob("*.toml")):
            for name, entry in read_toml(str(path)).items():
                if not isinstance(entry, dict):
                    continue
                if name in out:
                    raise InputError(f"bearings/{path.name}[{name}]", name, "designation defined twice in the catalog")
                out[name] = entry
    return out


def _resolve(name, cat: dict) -> str | None:
    """Catalogue key of a designation: exact, canonical, or an alias of an entry (all canonicalised)."""
    if name in cat:
        return name
    c = canonical_designation(name)
    if c in cat:
        return c
    for key, entry in cat.items():
        if c in {canonical_designation(a) for a in entry.get("aliases", ())}:
            return key
    return None


def _series_match(entry_series, query: str) -> bool:
    """A series query matches the entry's series exactly (spaces and case ignored), or its letter-less
    stem: "62" -> "62"; "72 b" -> "72B"; "70" -> "70C" and "70E"."""
    if entry_series is None:
        return False
    e = str(entry_series).replace(" ", "").upper()
    q = str(query).replace(" ", "").upper()
    return e == q or (q.isdigit() and e.rstrip("ABCDEFGHIJKLMNOPQRSTUVWXYZ") == q)


def bearing_names(series: str | None = None) -> list[str]:
    """Names in the bearing catalog, all or those of one series (see :func:`bearing_series`).

    >>> bearing_names(series="62")[:3]
    ['6200', '6201', '6202']
    >>> "7205B" in bearing_names(series="72 B")
    True
    """
    cat = _catalog()
    if series is None:
        return sorted(cat, key=_name_key)
    hits = sorted((n for n, e in cat.items() if _series_match(e.get("series"), series)), key=_name_key)
    if not hits:
        raise InputError("series", series, f"no bearing of this series; known series: {', '.join(bearing_series())}")
    return hits


def _name_key(name: str):
    """Sort designations numerically where they are numbers ("6200" < "6201" < "62000")."""
    digits = "".join(ch for ch in name if ch.isdigit())
    return (len(digits) if digits else 99, name)


def bearing_series() -> list[str]:
    """Series present in the catalog (e.g. "60", "62", "72B", "70C", "511").

    >>> {"62", "72B", "719E", "513"} <= set(bearing_series())
    True
    """
    return sorted({str(e["series"]) for e in _catalog().values() if e.get("series")}, key=lambda s: (len(s), s))


def bearing_table(name: str) -> dict:
    """A copy of the catalogue entry of a designation (unit-suffixed keys, as in the data files).

    Resolves canonical forms and aliases like :func:`bearing`; for merging scene overrides.

    >>> bearing_table("7205 B")["series"]
    '72B'
    """
    cat = _catalog()
    key = _resolve(name, cat)
    if key is None:
        raise InputError("bearing", name, _unknown_message(name, cat))
    return {"name": key, **cat[key]}


def _unknown_message(name, cat) -> str:
    close = difflib.get_close_matches(canonical_designation(name), list(cat), n=5, cutoff=0.6)
    seeds = sorted(read_toml(str(data_dir("materials") / "bearings.toml")))
    hint = f"close: {', '.join(close)}; " if close else ""
    return (f"unknown catalog name; {hint}seed bearings: {', '.join(seeds)}; series: "
            f"{', '.join(bearing_series())} (thermobear list bearings --series S; in Python bearing_names(series=S))")


def radial_clearance(bore, group: str = "CN") -> tuple[float, float]:
    """(min, max) radial internal clearance of a deep groove ball bearing [m] (ISO 5753-1:2009 Table 1).

    Parameters
    ----------
    bore : float   bore diameter [m], over 6 mm up to 100 mm
    group : str    "CN" (normal), "C3" or "C4"

    >>> [round(x * 1e6) for x in radial_clearance(50e-3)]
    [6, 23]
    >>> [round(x * 1e6) for x in radial_clearance(50e-3, "C3")]
    [18, 36]
    """
    if group not in CLEARANCE_GROUPS:
        raise InputError("clearance_group", group, f"must be one of {', '.join(CLEARANCE_GROUPS)} (ISO 5753-1)")
    tab = read_toml(str(data_dir("materials") / "iso5753_clearance.toml"))
    d_mm = float(bore) * 1e3
    for lo_mm, hi_mm, (cmin, cmax) in zip(tab["bore_over_mm"], tab["bore_incl_mm"], tab[f"{group}_um"]):
        if lo_mm < d_mm <= hi_mm + 1e-9:
            return cmin * 1e-6, cmax * 1e-6
    raise InputError("bore", bore, f"ISO 5753-1's clearance table holds bores over {tab['bore_over_mm'][0]:g} mm up to "
                     f"{tab['bore_incl_mm'][-1]:g} mm [m]")


def bearing_from_dict(d: dict, name: str = "custom", where: str = "bearing") -> BallBearing:
    """Build a BallBearing from a catalog/scene table with unit-suffixed keys (mm, deg, kN).

    A deep groove bearing without ``Pd_mm`` but with ``clearance_group`` and ``bore_mm`` takes Pd
    as the mid value of that ISO 5753-1 group; an explicit ``Pd_mm`` wins, and the group is kept only
    if Pd lies in its range.  With none of ``Pd_mm``, ``alpha0_deg``, ``clearance_group`` stated, a deep
    groove bearing with a bore takes the normal group CN (what a bearing is delivered with unless another
    group is ordered, ISO 5753-1:2009 §4), as the catalogue's do; without a bore, Pd = 0.  Unknown keys
    raise InputError naming them; so do missing required keys.
    """
    t = check_table(d, FIELDS, where)
    unc = check_uncertainty(t.get("uncertainty", {}), {k: FIELDS[k] for k in t if FIELDS[k].kind in ("number", "integer")},
                            where)
    kw = _attributes(t)
    for mk in ("ball_material", "ring_material"):
        if mk in t:
            kw[mk] = material(t[mk])
    kind = t.get("kind", "deep_groove")
    try:
        group = t.get("clearance_group")
        if group is None and kind == "deep_groove" and "bore" in kw and not {"Pd_mm", "alpha0_deg"} & set(t):
            group = "CN"                      # the normal group, as delivered (ISO 5753-1)
        if group is not None:
            kw["clearance_group"] = _clearance(kw, group, kind, where)
        return BallBearing(Z=t["Z"], fi=t["fi"], fo=t["fo"], kind=kind, name=t.get("name", name),
                           series=t.get("series"), C0=t["C0_kN"] * 1e3 if "C0_kN" in t else None,
                           C=t["C_kN"] * 1e3 if "C_kN" in t else None, estimated=tuple(t.get("estimated", ())),
                           uncertainty=unc, **kw)
    except InputError as e:
        raise in_table_units(e, where) from None


#: BallBearing attribute → (key of a bearing table, factor from SI to the key's unit)
_TABLE_KEYS = {"D": ("D_mm", 1e3), "dm": ("dm_mm", 1e3), "Pd": ("Pd_mm", 1e3), "bore": ("bore_mm", 1e3),
               "outer_diameter": ("outer_diameter_mm", 1e3), "width": ("width_mm", 1e3),
               "alpha0": ("alpha0_deg", 180.0 / np.pi), "C0": ("C0_kN", 1e-3), "C": ("C_kN", 1e-3)}
_NUMBER = r"(-?\d+(?:\.\d*)?(?:e[+-]?\d+)?)"


def in_table_units(e: InputError, where: str = "bearing") -> InputError:
    """A :class:`BallBearing` error (its SI attributes: m, rad, N) restated in the keys and units of a bearing
    table, as the scene or catalogue wrote them (``D_mm``, ``alpha0_deg``, ``C0_kN``).

    >>> str(in_table_units(InputError("bearing[6208].Pd", 1.3e-05, "clearance must be < 2A = 1.016e-06 m")))
    'bearing.Pd_mm = 0.013 — clearance must be < 2A = 0.001016 mm'
    """
    attr = e.field.rsplit(".", 1)[-1]
    key, f = _TABLE_KEYS.get(attr, (attr, 1.0))
    value = e.value
    if attr in _TABLE_KEYS and isinstance(value, numbers.Real) and not isinstance(value, bool):
        value = float(f"{value * f:.6g}")
    text = re.sub(_NUMBER + r" m\b", lambda m: f"{float(m.group(1)) * 1e3:.6g} mm", e.expected)
    text = re.sub(_NUMBER + r" rad\b", lambda m: f"{np.rad2deg(float(m.group(1))):.6g} deg", text)
    text = text.replace("[m]", "[mm]").replace("[rad]", "[deg]").replace("[N]", "[kN]")
    return InputError(f"{where}.{key}", value, text)


def _attributes(t: dict) -> dict:
    """BallBearing attributes [SI] of the length and angle keys of a table (mm, deg)."""
    kw = {_MM_KEYS[k]: t[k] * 1e-3 for k in t if k in _MM_KEYS}
    if "alpha0_deg" in t:
        kw["alpha0"] = float(np.deg2rad(t["alpha0_deg"]))
    return kw


def bearing_values(brg: BallBearing, values: dict) -> BallBearing:
    """A bearing with some of its table values replaced (``D_mm``, ``dm_mm``, ``Z``, ``fi``, ``fo``,
    ``Pd_mm``, ``alpha0_deg``, ``C0_kN``, ``C_kN``: the keys of :data:`FIELDS`, in their units),
    checked again (e.g. the drawn values of an uncertainty run).

    >>> bearing_values(bearing("7210"), {"D_mm": 12.0, "fi": 0.515}).D
    0.012
    """
    numeric = {k for k, f in FIELDS.items() if f.kind in ("number", "integer")}
    unknown = [k for k in values if k not in numeric]
    if unknown:
        raise InputError(f"bearing[{brg.name}].{unknown[0]}", values[unknown[0]],
                         f"a numeric bearing key: {', '.join(sorted(numeric))}")
    t = {k: check_value(float(v) if FIELDS[k].kind == "number" else int(round(float(v))), FIELDS[k],
                        f"bearing[{brg.name}].{k}") for k, v in values.items()}
    kw = _attributes(t)
    for k, attr in (("Z", "Z"), ("fi", "fi"), ("fo", "fo")):
        if k in t:
            kw[attr] = t[k]
    for k, attr in (("C0_kN", "C0"), ("C_kN", "C")):
        if k in t:
            kw[attr] = t[k] * 1e3
    return brg.with_(**kw)


def _clearance(kw: dict, group: str, kind: str, where: str) -> str | None:
    """Fill kw["Pd"] from an ISO 5753-1 group (deep groove, bore known); return the group label to keep."""
    if group not in CLEARANCE_GROUPS:
        raise InputError(f"{where}.clearance_group", group, f"must be one of {', '.join(CLEARANCE_GROUPS)}")
    if kind != "deep_groove":
        raise InputError(f"{where}.clearance_group", group, "a radial clearance group applies to deep groove "
                         "bearings (angular contact and thrust bearings take alpha0_deg)")
    if "bore" not in kw:
        raise InputError(f"{where}.clearance_group", group, "needs bore_mm to look up the ISO 5753-1 range")
    lo, hi = radial_clearance(kw["bore"], group)
    if "Pd" not in kw:
        kw["Pd"] = 0.5 * (lo + hi)
        return group
    return group if lo - 1e-12 <= kw["Pd"] <= hi + 1e-12 else None


def bearing(name: str) -> BallBearing:
    """Catalog look-up by designation (see :func:`bearing_names`).

    Designations are accepted in canonical form ("7205B", "7014C") or with spaces and lower-case
    suffixes ("7205 B"); the seed bearing "7210" is also "7210B".

    >>> b = bearing("7210")
    >>> b.Z, round(float(np.rad2deg(b.alpha0)), 1), b.kind
    (15, 40.0, 'angular_contact')
    >>> bearing("7205 B").name, bearing("6208").clearance_group
    ('7205B', 'CN')
    """
    cat = _likely_catalog(name)
    key = _resolve(name, cat)
    if key is None:
        cat = _catalog()
        key = _resolve(name, cat)
    if key is None:
        raise InputError("bearing", name, _unknown_message(name, cat))
    return bearing_from_dict(cat[key], name=key, where=f"bearings[{key}]")


def _likely_catalog(name: str) -> dict:
    """The entries of the files that can hold a designation: the seed file and the series files whose
    digits begin the designation's ("6208" → 62.toml, "7014C" → 70C.toml and 70E.toml); a name not
    found there is looked up in the whole catalogue (:func:`_catalog`: aliases, duplicates)."""
    base = data_dir("materials")
    out = dict(read_toml(str(base / "bearings.toml")))
    digits = canonical_designation(name)
    for path in sorted((base / "bearings").glob("*.toml")):
        stem = path.stem.rstrip("ABCDEFGHIJKLMNOPQRSTUVWXYZ")
        if stem and digits.startswith(stem):
            out.update((k, v) for k, v in read_toml(str(path)).items() if isinstance(v, dict))
    return out
