"""Bearing geometry: derived radii, clearance ↔ free contact angle, catalog, bad input."""
import numpy as np
import pytest

import thermobear as tb
from thermobear.errors import InputError
from thermobear.contact.geometry import BallBearing, bearing, bearing_from_dict, bearing_names, bearing_table

STEEL = tb.Material(E=2.1e11, nu=0.3, rho=7850.0)


def make(**kw):
    args = dict(D=11.5e-3, dm=43.5e-3, Z=7, fi=0.52, fo=0.53, Pd=0.0, kind="deep_groove",
                ball_material=STEEL, ring_material=STEEL) | kw
    return BallBearing(**args)


def test_209_radii_match_physics_reference():
    # 209 bearing (Harris 2001 ch. 2), D 12.7, f 0.52, dm 64.9985 mm: Rx,i 5.109, Rx,o 7.591, Ry 165.1 mm
    b = make(D=12.7e-3, dm=64.9985e-3, Z=9, fi=0.52, fo=0.52, Pd=15e-6)
    assert b.gamma(0.0) == pytest.approx(0.1954, abs=1e-4)
    assert b.Rx_i(0.0) == pytest.approx(5.109e-3, rel=2e-4)
    assert b.Rx_o(0.0) == pytest.approx(7.591e-3, rel=2e-4)
    assert b.Ry_i == pytest.approx(165.1e-3, rel=2e-4)


def test_free_contact_angle_from_clearance_seed004_eq1():
    b = make(Pd=0.01e-3)
    A = (0.52 + 0.53 - 1) * 11.5e-3
    assert b.A == pytest.approx(A)
    assert b.alpha0 == pytest.approx(np.arccos(1 - 0.01e-3 / (2 * A)), rel=1e-12)
    assert np.rad2deg(b.alpha0) == pytest.approx(7.56, abs=0.01)
    assert b.free_end_play == pytest.approx(2 * A * np.sin(b.alpha0))


def test_angular_contact_clearance_follows_alpha0():
    b = bearing("7210")
    assert b.Pd == pytest.approx(2 * b.A * (1 - np.cos(np.deg2rad(40))), rel=1e-12)
    b2 = b.with_(fi=0.53)
    assert b2.Pd == pytest.approx(2 * b2.A * (1 - np.cos(np.deg2rad(40))), rel=1e-12)


def test_thrust_radii_flat_race():
    b = bearing("51205-3ball")
    assert b.Rx_i(b.alpha0) == pytest.approx(b.D / 2, rel=1e-12)   # race flat in rolling direction
    assert b.Rx_o(b.alpha0) == pytest.approx(b.D / 2, rel=1e-12)
    assert b.Ry_i / b.Rx_i(b.alpha0) == pytest.approx(2 * 0.53 / (2 * 0.53 - 1), rel=1e-12)  # seed 000 eq 12


def test_reduced_modulus_steel():
    assert make().E_prime == pytest.approx(2.3077e11, rel=1e-4)


def test_catalog_lists_seed_bearings_with_estimates_marked():
    names = bearing_names()
    for n in ("51205", "51205-3ball", "51107", "7210", "6210", "iso-dgbb"):
        assert n in names
    b = bearing("7210")
    assert b.Z == 15 and b.dm == pytest.approx(70e-3) and "D_mm" in b.estimated
    b = bearing("51205-3ball")
    assert b.Z == 3 and b.D == pytest.approx(7.938e-3) and b.fi == 0.53 and b.estimated == ()


@pytest.mark.parametrize("kw, field", [
    (dict(D=50e-3), "D"),                 # D >= dm
    (dict(D=-1e-3), "D"),
    (dict(fi=0.5), "fi"),                 # osculation <= 0.5
    (dict(fo=0.45), "fo"),
    (dict(Z=2), "Z"),                     # Z < 3
    (dict(Z=7.5), "Z"),
    (dict(Z=40), "Z"),                    # balls do not fit
    (dict(Pd=-2e-3), "Pd"),               # a radial preload of a ball compressed by more than A
    (dict(Pd=5e-3), "Pd"),                # clearance beyond 2A
    (dict(kind="tapered"), "kind"),
    (dict(kind="angular_contact", Pd=None), "alpha0"),
])
def test_bad_geometry_names_the_field(kw, field):
    with pytest.raises(InputError) as e:
        make(**kw)
    assert f".{field}" in str(e.value)
    assert "—" in str(e.value)            # message carries what is expected


def test_unknown_catalog_name_lists_known():
    with pytest.raises(InputError) as e:
        bearing("6299X")
    assert "6299X" in str(e.value) and "7210" in str(e.value)


def test_an_edited_material_file_is_read_again(tmp_path, monkeypatch):
    """material() builds from the file as it is now (a user editing materials/solids in a session gets
    the new values, as read_toml gives for every other data file)."""
    import shutil
    import time

    from thermobear import files as _data
    from thermobear.contact import materials as mats
    root = tmp_path / "materials"
    shutil.copytree(_data.data_dir("materials") / "solids", root / "solids")
    monkeypatch.setattr(_data, "data_dir", lambda kind: root if kind == "materials" else None)
    monkeypatch.setattr(mats, "data_dir", lambda kind: root)
    E0 = mats.material("aisi-52100").E
    f = root / "solids" / "aisi-52100.toml"
    text = f.read_text()
    key = next(ln for ln in text.splitlines() if ln.strip().startswith("E_Pa"))
    time.sleep(0.01)
    f.write_text(text.replace(key, "E_Pa = 1.5e11"))
    assert mats.material("aisi-52100").E == 1.5e11 != E0


def test_a_bore_that_leaves_no_ring_wall_is_refused():
    with pytest.raises(InputError, match="bore"):
        tb.bearing("6210").with_(bore=69e-3)


def test_custom_deep_groove_bearing_without_a_clearance_takes_iso_5753_normal_group():
    """A bearing table with its geometry and a bore but no Pd_mm, alpha0_deg or clearance_group took Pd = 0
    silently (and the fits then consumed it); it takes ISO 5753-1's normal group, as the catalogue's do."""
    from thermobear.contact.geometry import bearing_from_dict, radial_clearance
    geo = dict(kind="deep_groove", D_mm=12.7, dm_mm=60.0, Z=9, fi=0.515, fo=0.525, bore_mm=40.0)
    b = bearing_from_dict(geo)
    lo, hi = radial_clearance(40e-3, "CN")
    assert b.clearance_group == "CN" and b.Pd == pytest.approx(0.5 * (lo + hi))
    assert b.Pd == bearing("6208").Pd                                   # the catalogue's 40 mm bore, CN
    assert bearing_from_dict({**geo, "clearance_group": "C3"}).Pd > b.Pd
    assert bearing_from_dict({**geo, "Pd_mm": 0.0}).Pd == 0.0           # a stated clearance wins
    no_bore = {k: v for k, v in geo.items() if k != "bore_mm"}
    assert bearing_from_dict(no_bore).Pd == 0.0 and bearing_from_dict(no_bore).clearance_group is None


def test_materials_by_catalogue_name_in_with_and_the_constructor():
    b = bearing("6208").with_(ball_material="si3n4")
    assert b.ball_material == tb.material("si3n4") and b.E_prime == bearing("6208").with_(
        ball_material=tb.material("si3n4")).E_prime
    assert BallBearing(D=11.5e-3, dm=43.5e-3, Z=7, fi=0.52, fo=0.53, ring_material="m50").ring_material == tb.material("m50")
    with pytest.raises(InputError, match=r"ball_material = 7 — must be a Material"):
        bearing("6208").with_(ball_material=7)
    with pytest.raises(InputError, match=r"^bearing\[6208\]\.ring_material = 'x' — unknown name"):
        bearing("6208").with_(ring_material="x")


def test_a_negative_clearance_is_a_radial_preload_with_the_rings_centred():
    """P_d < 0 (the operating clearance the fits and temperatures leave): contact angle 0, the groove centres
    A − P_d/2 apart radially (each ball compressed by −P_d/2); with a clearance A_r0 is A cos α0 exactly."""
    b = make(Pd=-6e-6)
    assert b.alpha0 == 0.0 and b.A_a0 == 0.0 and b.free_end_play == 0.0
    assert b.A_r0 - b.A == pytest.approx(3e-6, rel=1e-9)
    for Pd in (0.0, 1e-6, 20e-6):
        c = make(Pd=Pd)
        assert c.A_r0 == c.A * np.cos(c.alpha0) and c.A_a0 == c.A * np.sin(c.alpha0)
        assert c.A_r0 == pytest.approx(c.A - Pd / 2, rel=1e-12)
    assert make(Pd=-6e-6, alpha0=0.0).Pd == -6e-6
    with pytest.raises(InputError, match="alpha0"):
        make(Pd=-6e-6, alpha0=0.1)
    with pytest.raises(InputError, match="Pd_mm"):          # a bearing table states the unmounted clearance
        bearing_from_dict({**{k: v for k, v in bearing_table("6208").items() if k != "name"},
                              "Pd_mm": -0.006})
