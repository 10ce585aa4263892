"""Bearing catalogue: the common series (materials/bearings/<series>.toml), names, series filter,
clearance groups (ISO 5753-1), physical plausibility, and ratings against makers' published values."""
import importlib.util
import sys
from pathlib import Path

import numpy as np
import pytest

from thermobear.contact.geometry import (CLEARANCE_GROUPS, bearing, bearing_from_dict, bearing_names,
                                         bearing_series, bearing_table, canonical_designation, radial_clearance)
from thermobear.errors import InputError
from thermobear.rating.life import load_ratings

ALL = bearing_names()


def test_catalogue_holds_the_series_and_the_names_the_next_issues_need():
    assert len(ALL) > 300
    for s in ("60", "62", "63", "618", "619", "160", "72B", "73B", "70C", "70E", "719C", "719E",
              "511", "512", "513"):
        assert s in bearing_series()
    for name in ("6208", "6305", "7205 B", "7205B", "7014 C", "7014C", "61806", "51107"):
        bearing(name)
    assert bearing("7205 B").name == bearing("7205b").name == "7205B"
    assert bearing("7210B").name == "7210"                       # seed 004 bearing, alias of its designation
    assert canonical_designation("719 14 e") == "71914E"


def test_series_filter():
    n62 = bearing_names(series="62")
    assert n62 == [f"62{c}" for c in ("00", "01", "02", "03")] + [f"62{i:02d}" for i in range(4, 21)]
    assert set(bearing_names(series="70")) == set(bearing_names(series="70C")) | set(bearing_names(series="70E"))
    assert "7210" in bearing_names(series="72 B")                # seed bearing listed with its series
    assert all(bearing(n).series == "513" for n in bearing_names(series="513"))
    with pytest.raises(InputError):
        bearing_names(series="64")


@pytest.mark.parametrize("name", ALL)
def test_every_bearing_loads_and_is_physically_possible(name):
    b = bearing(name)
    assert b.D <= b.dm * np.sin(np.pi / b.Z) * (1 + 1e-9)       # balls fit on the pitch circle
    assert 0.5 < b.fi <= 0.6 and 0.5 < b.fo <= 0.6
    if b.bore is not None and b.outer_diameter is not None:
        assert b.D < 0.5 * (b.outer_diameter - b.bore)           # ball inside the ring section
        if b.kind == "thrust":
            assert b.D < b.width                                 # and inside the height
    C, C0 = load_ratings(b)
    assert C > 0 and C0 > 0
    if b.C is not None:                                         # stored values are the ISO values of the geometry
        assert b.C == pytest.approx(C, abs=0.6) and b.C0 == pytest.approx(C0, abs=0.6)   # stored to 1 N


# Makers' published ratings [kN] and the tolerance of the comparison (sanity check of geometry + ISO 281/76):
#   Japanese maker table, gist nagae/8756dc2de16082219e1ae6a80a73dfb3 (rows without "&"): within 3 %;
#   SKF, gumyr/bd_warehouse single_row_{deep_groove,angular_contact}_ball_bearing_parameters.csv: within 15 %
#   (Explorer ratings, bore 10 mm deep groove and 72/73 B); 6210 C0 23.2 kN SKF (materials/bearings.toml):
#   within 2 %; 6305 C 23.4 kN (minzhun/ISO16281): within 15 %.
MAKERS = [("6203", 9.55, 4.8, 0.03), ("6204", 12.8, 6.6, 0.03), ("6205", 14.0, 7.85, 0.03),
          ("6206", 19.5, 11.3, 0.03), ("61800", 1.72, 0.83, 0.15), ("61900", 2.7, 1.27, 0.15),
          ("6000", 4.75, 1.96, 0.15), ("6200", 5.4, 2.36, 0.15), ("6300", 8.52, 3.4, 0.15),
          ("7200B", 7.02, 3.35, 0.15), ("7202B", 8.8, 4.65, 0.15), ("7203B", 11.0, 5.85, 0.15),
          ("7303B", 15.9, 8.3, 0.15), ("7304B", 19.0, 10.0, 0.15), ("7305B", 26.5, 15.3, 0.15),
          ("6210", None, 23.2, 0.02), ("6305", 23.4, None, 0.15)]


@pytest.mark.parametrize("name, C_kN, C0_kN, tol", MAKERS)
def test_ratings_of_the_right_order_against_makers(name, C_kN, C0_kN, tol):
    C, C0 = load_ratings(bearing(name))
    if C_kN:
        assert C / 1e3 == pytest.approx(C_kN, rel=tol)
    if C0_kN:
        assert C0 / 1e3 == pytest.approx(C0_kN, rel=tol)


@pytest.mark.parametrize("name, dims", [   # d, D, B [mm]; source: gumyr/bd_warehouse CSVs (SKF designations)
    ("61800", (10, 19, 5)), ("61900", (10, 22, 6)), ("6000", (10, 26, 8)), ("6200", (10, 30, 9)),
    ("6300", (10, 35, 11)), ("7200B", (10, 30, 9)), ("7201B", (12, 32, 10)), ("7202B", (15, 35, 11)),
    ("7203B", (17, 40, 12)), ("7302B", (15, 42, 13)), ("7303B", (17, 47, 14)), ("7304B", (20, 52, 15)),
    ("7305B", (25, 62, 17)), ("6205", (25, 52, 15)), ("6206", (30, 62, 16)),   # 6205/6206 also gist nagae
    ("61806", (30, 42, 7)), ("51107", (35, 52, 12)), ("51205", (25, 47, 15))])
def test_boundary_dimensions_spot_checks(name, dims):
    b = bearing(name)
    assert (b.bore * 1e3, b.outer_diameter * 1e3, b.width * 1e3) == pytest.approx(dims)


def test_seed_bearings_unchanged():
    b = bearing("6210")
    assert (b.Z, b.D, b.dm, b.Pd, b.C0) == (10, pytest.approx(12.7e-3), pytest.approx(70e-3),
                                             pytest.approx(0.0145e-3), pytest.approx(23.2e3))
    assert bearing("51107").Z == 18 and bearing("51205").Z == 12 and bearing("iso-dgbb").Z == 7
    assert bearing("7210").C0 == pytest.approx(25.5e3) and bearing("51205-3ball").Z == 3


def test_generated_files_are_what_the_script_writes_now():
    """materials/bearings/*.toml are the output of validation/catalogue.py on the current code and data."""
    path = Path(__file__).resolve().parents[1] / "validation" / "catalogue.py"
    sys.path.insert(0, str(path.parent))
    try:
        spec = importlib.util.spec_from_file_location("catalogue_script", path)
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        cat = mod.build()
    finally:
        sys.path.remove(str(path.parent))
    n = 0
    for _series, (_src, rows) in cat.items():
        for name, e, _info, seed in rows:
            if seed:
                continue
            t = bearing_table(name)
            for k in ("D_mm", "dm_mm", "Z", "fi", "fo", "bore_mm", "outer_diameter_mm", "width_mm", "C_kN", "C0_kN"):
                assert t[k] == pytest.approx(e[k]), (name, k)
            n += 1
    assert n == sum(1 for x in ALL if bearing_table(x).get("source", "").startswith("dimensions:"))


def test_radial_clearance_groups_iso5753():
    assert [round(x * 1e6) for x in radial_clearance(40e-3, "CN")] == [6, 20]
    assert [round(x * 1e6) for x in radial_clearance(40.001e-3, "CN")] == [6, 23]      # next row: over 40
    assert [round(x * 1e6) for x in radial_clearance(100e-3, "C4")] == [53, 84]
    for d in (10e-3, 30e-3, 70e-3):                                                   # groups grow CN < C3 < C4
        mids = [sum(radial_clearance(d, g)) for g in CLEARANCE_GROUPS]
        assert mids == sorted(mids)
    with pytest.raises(InputError):
        radial_clearance(150e-3)
    with pytest.raises(InputError):
        radial_clearance(40e-3, "C5")


def test_bearing_clearance_is_the_mid_of_its_group_and_follows_a_change():
    b = bearing("6208")
    assert b.clearance_group == "CN" and b.Pd == pytest.approx(13e-6)                # CN 6-20 um at 40 mm
    assert b.clearance_range == pytest.approx((6e-6, 20e-6))
    t = bearing_table("6208")
    c3 = bearing_from_dict({**t, "clearance_group": "C3"}, name="6208")
    assert c3.Pd == pytest.approx(24e-6) and c3.clearance_group == "C3"                # C3 15-33 um
    mine = bearing_from_dict({**t, "Pd_mm": 0.0}, name="6208")                         # explicit Pd wins
    assert mine.Pd == 0.0 and mine.clearance_group is None
    assert b.with_(Pd=0.0).clearance_group is None
    with pytest.raises(InputError):
        bearing_from_dict({**bearing_table("7205B"), "clearance_group": "C3"})        # angular contact: no group


def test_unknown_name_suggests_and_lists_seeds_and_series():
    with pytest.raises(InputError) as e:
        bearing("6299X")
    msg = str(e.value)
    assert "6299X" in msg and "7210" in msg and "62" in msg
