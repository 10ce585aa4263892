"""Errors of a bearing table name the table's keys in its units (mm, deg, kN), not the SI attributes the
table becomes, and a scene that changes a catalogue bearing says which of its values it changed: a
ball diameter written in metres (D_mm = 0.0127) was reported as 'bearing[6208].Pd = 1.3e-05 — clearance
must be < 2A = 1.016e-06 m', naming neither the key nor the unit the user wrote."""
from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

import thermobear as tb
from thermobear.app.cli import main
from thermobear.contact.geometry import bearing, bearing_from_dict, bearing_table
from thermobear.errors import InputError
from thermobear.scene.scene import scene_from_dict

BATH = Path(tb.example_path("block_6208_oil_bath.toml"))


def _scene(**bearing_keys):
    d = tomllib.loads(BATH.read_text(encoding="utf-8"))
    d["bearing"].update(bearing_keys)
    return scene_from_dict(d, path=str(BATH))


@pytest.mark.parametrize("keys, message", [
    ({"D_mm": 0.0127}, r"^bearing\.Pd_mm = 0\.013 — clearance must be < 2A = 0\.001016 mm .*; the scene changes "
                       r"6208's D_mm = 0\.0127 \(catalogue: 12\.7\)$"),
    ({"dm_mm": 0.06}, r"^bearing\.D_mm = 12\.7 — .* pitch diameter dm = 0\.06 mm; the scene changes 6208's dm_mm"),
    ({"bore_mm": 0.04}, r"^bearing\.bore_mm = 0\.04 — ISO 5753-1's clearance table holds bores over 6 mm up to "
                        r"100 mm \[mm\]"),
    ({"bore_mm": 55.0}, r"^bearing\.bore_mm = 55(\.0)? — bore must lie in \(0, dm − D = 47\.763 mm\)"),
    ({"outer_diameter_mm": 0.08}, r"^bearing\.outer_diameter_mm = 0\.08 — outer diameter must exceed dm \+ D = "
                                  r"73\.163 mm"),
    ({"alpha0_deg": 0.16}, r"^bearing\.alpha0_deg = 0\.16 — inconsistent with Pd: arccos\(1 - Pd/2A\) = 9\.175\d* deg"),
    ({"Z": 40}, r"^bearing\.Z = 40 — 40 balls of D = 12\.7 mm do not fit"),
])
def test_scene_bearing_errors_in_the_scenes_keys_and_units(keys, message):
    with pytest.raises(InputError, match=message):
        _scene(**keys)


@pytest.mark.parametrize("Z", [0, 1, 2, 201])
def test_number_of_balls_range_is_the_same_in_both_checks(Z):
    """Z = 0 was refused as 'must be in [1, 200]' (the scene key's range) and Z = 2 as 'an integer >= 3' (the
    bearing's): one range, [3, 200], in both messages."""
    with pytest.raises(InputError, match=r"^bearing\.Z = \d+ — must be in \[3, 200\]"):
        _scene(Z=Z)
    with pytest.raises(InputError, match=r"number of balls must be an integer in \[3, 200\]$"):
        tb.bearing("6208").with_(Z=Z)


def test_preload_is_not_a_negative_clearance():
    """Pd_mm was documented '(negative: preload)' and accepted down to -10 by the table check, then refused by the
    bearing: the key's range is now what the bearing accepts."""
    with pytest.raises(InputError, match=r"^bearing\.Pd_mm = -0\.005 — must be in \[0, 10\] \[mm\]"):
        _scene(Pd_mm=-0.005)


def test_catalogue_table_errors_in_its_units():
    t = {k: v for k, v in bearing_table("6208").items() if k != "uncertainty"}
    with pytest.raises(InputError, match=r"^bearings\[6208\]\.D_mm = 127(\.0)? — .* dm = 60\.463 mm$"):
        bearing_from_dict({**t, "D_mm": 127.0}, name="6208", where="bearings[6208]")


def test_cli_names_the_key_the_user_wrote(tmp_path, capsys):
    p = tmp_path / "m.toml"
    p.write_text(BATH.read_text(encoding="utf-8").replace('catalog = "6208"', 'catalog = "6208"\nD_mm = 0.0127'),
                 encoding="utf-8")
    assert main(["run", str(p)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "D_mm = 0.0127 (catalogue: 12.7)" in err and "e-06 m" not in err


def test_unknown_designation_points_to_the_command_that_lists_the_series(capsys):
    assert main(["init", "6204-2XX", "--lubrication", "grease"]) == 2
    err = capsys.readouterr().err
    assert "close: 6204" in err and "thermobear list bearings --series" in err


@pytest.mark.parametrize("kw, field", [
    (dict(Z=float("nan")), "Z"), (dict(Z=None), "Z"), (dict(Z=float("inf")), "Z"), (dict(Pd="x"), "Pd"),
    (dict(alpha0="x"), "alpha0"), (dict(C0=float("inf")), "C0"), (dict(width=float("nan")), "width"),
    (dict(foo=1), "foo"), (dict(K_nominal=(1.0, 1.0, 1.0)), "K_nominal"),
])
def test_bearing_with_refuses_what_is_not_a_finite_number_or_a_field_by_name(kw, field):
    """BallBearing.with_ (and the constructor) answered these with bare ValueError / TypeError /
    OverflowError (Z = NaN, None, inf; Pd or alpha0 text; an unknown keyword), or accepted C0 = inf."""
    with pytest.raises(InputError, match=rf"^bearing\[6208\]\.{field}"):
        bearing("6208").with_(**kw)
