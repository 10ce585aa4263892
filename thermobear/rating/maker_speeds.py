r"""The makers' reference and limiting speeds of the catalogue bearings (``materials/maker_speeds.toml``).

A maker's product table gives two speeds per bearing [1]_:

* the **reference speed**, SKF's thermal speed rating under ISO 15312's reference conditions (what
  :func:`thermobear.coupled.speeds.thermal_reference_speed` computes with thermobear's own losses) — for a
  thrust ball bearing, which ISO 15312 excludes [2]_ ("as kinematic effects do not allow the thermal speed rating
  to be applied"), SKF's own rating (SKF 2018, 'Operating temperature and speed', p. 130: the SKF friction model at ISO 15312's
  reference conditions), not the standard's;
* the **limiting speed**, the kinematic limit of the bearing — its cage, the stability of its balls, and for a
  capped bearing its seals' lip speed — which SKF advises not to exceed whatever the cooling
  (its value is for grease as well as oil: one value per bearing in the sources, which do not distinguish
  the lubrication).  Contact-sealed bearings have a limiting speed only: their friction is the seals'.

The data file holds SKF's values as transcribed in public repositories (a source row per entry; how they
were read, cross-checked and which rows were not used: ``validation/maker_speeds.py``): deep groove and
angular contact ball bearings from two transcriptions of SKF's product tables, thrust ball bearings (511, 512,
513, open) from two SKF catalogue editions (2018, 2006).  A bearing or variant the sources do not list has no
value: the spindle series 70 C/E, 719 C/E, most of 72 B / 73 B, 51205-3ball (no SKF designation).

A scene's ``[bearing] seals`` selects the variant: ``none`` the open bearing, ``shield`` the lower of the
shielded variants on file (2Z, 2RZ), a contact seal (RSL, RSH, RS1) its own variant (2RSL, 2RSH, 2RS1) — or,
where the source lists another contact-sealed variant of the bearing but not that one, the lowest limiting
speed of the contact-sealed variants listed (SKF's RSH replaced RS1 on many sizes: the 6208 is listed as
2RSH only), and where it lists no variant with such a closure, the open bearing's, an upper bound of the
capped one's (named so in :attr:`MakerSpeeds.note`).  A bearing capped on one side (-Z, -RSH) has the
values of the one capped on both (SKF lists them on one row [1]_).

References
----------
.. [1] SKF Group, *Rolling bearings* (SKF General Catalogue 10000 EN / 17000 EN), "Speeds" (reference
   and limiting speed) and the product tables of deep groove and angular contact ball bearings, as transcribed
   in github.com/JRaposo-m/SKF-Bearing-Selection-Tool and github.com/gumyr/bd_warehouse; SKF *Rolling
   bearings* PUB BU/P1 17000/1 EN (2018) table 5.1 and the SKF General Catalogue (Russian edition, 2006 data),
   single direction thrust ball bearings, as transcribed in github.com/ArtemFilin1990/Mar.
.. [2] ISO 15312:2018, Rolling bearings — Thermal speed rating — Calculation, scope: thrust ball bearings
   excluded.

Examples
--------
>>> m = maker_speeds("6208")
>>> m.designation, m.reference_rpm, m.limiting_rpm
('6208', 18000.0, 11000.0)
>>> maker_speeds("6208", seals="RS1").designation, maker_speeds("6208", seals="RS1").limiting_rpm
('6208-2RSH', 5600.0)
>>> m = maker_speeds("51208")                 # a thrust ball bearing: SKF's 2018 table 5.1
>>> m.designation, m.reference_rpm, m.limiting_rpm
('51208', 3800.0, 5300.0)
>>> limiting_speed_text("7210")
"no maker's limiting speed on file for 7210"
"""
from __future__ import annotations

from dataclasses import dataclass

from thermobear.errors import InputError
from thermobear.files import data_dir, read_toml
from thermobear.schema import Field, check_table
from thermobear.units import rad_s_to_rpm, rpm_to_rad_s

__all__ = ["MakerSpeeds", "maker_speeds", "maker_speeds_table", "limiting_speed_text", "VARIANTS", "SEAL_VARIANTS"]

#: The variants of a bearing in the data file: open, shields (2Z, 2RZ), contact seals (2RSL, 2RSH, 2RS1).
VARIANTS = ("open", "2Z", "2RZ", "2RSL", "2RSH", "2RS1")
_SHIELDS = ("2Z", "2RZ")
_CONTACT = ("2RSL", "2RSH", "2RS1")
#: A scene's ``[bearing] seals`` -> the variant it names (contact seals of roller bearings have none here).
SEAL_VARIANTS = {"none": "open", "shield": _SHIELDS, "RSL": "2RSL", "RSH": "2RSH", "RS1": "2RS1"}

_ENTRY = {
    "designation": Field.text("the maker's designation of the row", required=True),
    "reference_rpm": Field.number("rpm", 0.0, None, lo_open=True, doc="reference speed (thermal speed rating)"),
    "limiting_rpm": Field.number("rpm", 0.0, None, lo_open=True, doc="limiting speed (kinematic)", required=True),
    "source": Field.text("the source row", required=True),
    "cross_check": Field.text("the other source's row, where it has one"),
    "note": Field.text("duplicates, the cage of the row"),
}
_FILE = "maker_speeds.toml"


@dataclass(frozen=True)
class MakerSpeeds:
    """A bearing's speeds from its maker's product table.

    Attributes
    ----------
    bearing : str          catalogue designation (e.g. ``"6208"``)
    variant : str          the data file's variant the values are of (``open``, ``2Z``, ``2RSH``, …)
    designation : str      the maker's designation of that row (``"6208-2RSH"``, ``"7200 BECBP"``)
    reference : float | None  reference speed [rad/s] (None: the maker gives none, e.g. contact seals; of a
                           thrust ball bearing SKF's own rating, ISO 15312 excluding them)
    limiting : float       limiting speed [rad/s]
    source : str           the source row
    note : str             how the variant was chosen where it is not the scene's own ("" where it is)
    """

    bearing: str
    variant: str
    designation: str
    reference: float | None
    limiting: float
    source: str
    note: str = ""

    @property
    def reference_rpm(self) -> float | None:
        """Reference speed [rpm]."""
        return None if self.reference is None else round(float(rad_s_to_rpm(self.reference)), 6)

    @property
    def limiting_rpm(self) -> float:
        """Limiting speed [rpm]."""
        return round(float(rad_s_to_rpm(self.limiting)), 6)


def _raw() -> dict:
    return read_toml(str(data_dir("materials") / _FILE))


def _checked(name: str, variants) -> dict:
    """One designation's entries, checked: variant -> typed entry; InputError naming the entry and key for an
    unknown variant or key, or a value of the wrong kind."""
    if not isinstance(variants, dict):
        raise InputError(f"{_FILE}: {name}", variants, "must be a table of variants, e.g. [\"6208\".open]")
    out = {}
    for variant, entry in variants.items():
        where = f"{_FILE}: {name}.{variant}"
        if variant not in VARIANTS:
            raise InputError(where, variant, f"unknown variant; accepted: {', '.join(VARIANTS)}")
        out[variant] = check_table(entry, _ENTRY, where)
    return out


def maker_speeds_table() -> dict:
    """Every entry of ``materials/maker_speeds.toml``, checked: designation -> variant -> typed entry.

    Raises InputError naming the entry and key for an unknown key, variant or a value of the wrong kind
    (:func:`maker_speeds` checks the entries of the bearing it looks up, this function all of them).

    >>> t = maker_speeds_table()
    >>> sorted(t["6208"]), t["6208"]["2Z"]["limiting_rpm"]
    (['2RSH', '2RZ', '2Z', 'open'], 9000.0)
    """
    return {name: _checked(name, variants) for name, variants in _raw().items()}


def _choose(entries: dict, seals: str) -> tuple[str, str] | None:
    """(variant, note) of a bearing's entries for a scene's ``seals``; None where none applies."""
    want = SEAL_VARIANTS.get(seals, _CONTACT)
    if isinstance(want, str) and want in entries:
        return want, ""
    group = _SHIELDS if seals == "shield" else _CONTACT
    have = [v for v in group if v in entries]
    if seals != "none" and have:
        v = min(have, key=lambda k: entries[k]["limiting_rpm"])
        if seals == "shield":
            alike = len({entries[k]["limiting_rpm"] for k in have}) == 1
            return v, "" if alike else f"the lower of the shielded variants on file ({', '.join(have)})"
        return v, (f"no {want if isinstance(want, str) else seals} row on file: the lowest limiting speed of the "
                   f"contact-sealed variants listed ({', '.join(have)})")
    if seals != "none" and "open" in entries:
        return "open", (f"no variant with {seals} seals on file: the open bearing's, an upper bound of the capped "
                        "one's")
    return None


def maker_speeds(bearing, seals: str = "none") -> MakerSpeeds | None:
    """The maker's reference and limiting speeds of a catalogue bearing with its seals, or None.

    Parameters
    ----------
    bearing : str or BallBearing   catalogue designation (``"6208"``, ``"7205 B"``, the seed ``"7210"``) or a
                                   bearing whose ``name`` is one (a scene's ``scene.bearing``)
    seals : str                    a scene's ``[bearing] seals``: ``none``, ``shield``, ``RSL``, ``RSH``, ``RS1``
                                   (others: the contact-sealed variants)

    Returns
    -------
    MakerSpeeds or None
        the speeds in rad/s (``reference_rpm``, ``limiting_rpm`` in rpm) and their source row; None where the
        data file has no value for the bearing (no source lists it: most angular contact bearings, the spindle
        series, bearings not in the catalogue) — never an estimate.

    The limiting speed is SKF's for grease and oil alike: the sources give one value (see the module).

    References
    ----------
    SKF Group, *Rolling bearings*, product tables (see :mod:`thermobear.rating.maker_speeds`).

    Examples
    --------
    >>> m = maker_speeds("6208", seals="shield")
    >>> m.designation, m.limiting_rpm, round(m.limiting, 2)
    ('6208-2Z', 9000.0, 942.48)
    >>> maker_speeds("7210") is None        # 7210 B: neither source lists it
    True
    """
    name = str(getattr(bearing, "name", bearing))
    raw = _raw()
    key = _catalogue_key(name, raw)
    if key is None:
        return None
    entries = _checked(key, raw[key])
    picked = _choose(entries, seals)
    if picked is None:
        return None
    variant, note = picked
    e = entries[variant]
    ref = e.get("reference_rpm")
    return MakerSpeeds(bearing=key, variant=variant, designation=e["designation"],
                       reference=None if ref is None else float(rpm_to_rad_s(ref)),
                       limiting=float(rpm_to_rad_s(e["limiting_rpm"])), source=e["source"], note=note)


def _catalogue_key(name: str, table: dict) -> str | None:
    """The data file's key of a designation: as given, without spaces in upper case ("7205 b" -> "7205B")."""
    if name in table:
        return name
    c = name.replace(" ", "").upper()
    return c if c in table else None


def limiting_speed_text(bearing, seals: str = "none") -> str:
    """One line: the maker's limiting speed of a bearing with its seals and its source, or that there is none.

    >>> limiting_speed_text("6208", "RS1")
    "maker's limiting speed 5600 rpm (6208-2RSH; reference speed none given; jraposo deep_groove_ball.csv line 297; no 2RS1 row on file: the lowest limiting speed of the contact-sealed variants listed (2RSH))"
    """
    m = maker_speeds(bearing, seals)
    name = str(getattr(bearing, "name", bearing))
    if m is None:
        return f"no maker's limiting speed on file for {name}" + ("" if seals == "none" else f" ({seals} seals)")
    ref = "none given" if m.reference_rpm is None else f"{m.reference_rpm:.0f} rpm"
    return (f"maker's limiting speed {m.limiting_rpm:.0f} rpm ({m.designation}; reference speed {ref}; "
            f"{m.source}" + (f"; {m.note}" if m.note else "") + ")")
