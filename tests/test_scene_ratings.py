"""Issue 16 in the scene's answers: five-degree-of-freedom loads from the scene (operation.Fz_N, My_Nm), the
ratings of `thermobear run` (thermobear.coupled.ratings: C0, C, s0, p_max, κ, a_ISO, lives, clearance) and the
static overload refused before any solve (exit 2, one line naming the load, the limit and C0)."""
from __future__ import annotations

import json
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

import thermobear as tb
from thermobear.app.cli import main
from thermobear.contact.fits import operating_clearance
from thermobear.contact.materials import material
from thermobear.coupled.pipeline import scene_load
from thermobear.coupled.ratings import (check_static_safety, operating_lives, rating_samples, scene_clearance,
                                        scene_ratings, scene_ratings_many, typical_fits)
from thermobear.errors import InputError, OutsideValidity
from thermobear.rating import load_ratings
from thermobear.rating.life import stated_ratings
from thermobear.scene.scene import scene_from_dict

EX = Path(__file__).resolve().parents[1] / "examples"
BATH = str(EX / "oil_bath_6208.toml")
S = tb.load_scene(BATH)


def run(capsys, *argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def test_scene_keys_fz_my_are_strict_and_in_si():
    s = S.with_(Fz_N=500.0, My_Nm=2.0)
    assert (s.Fz, s.My) == (500.0, 2.0) and S.Fz == 0.0 and S.My is None
    with pytest.raises(InputError, match="^Fz = '500' — must be a number"):
        S.with_(Fz="500")
    with pytest.raises(InputError, match="contamination"):
        S.with_(contamination="dusty")


def test_a_radial_load_along_z_is_the_radial_load_turned():
    """Fr along z instead of y: the same power within the difference the 9 balls' positions make, the
    displacement along z; Fz = 0 leaves the answer exactly as it was (numbers do not move)."""
    a, b = tb.steady_state(S), tb.steady_state(S.with_(Fr=0.0, Fz=2000.0))
    assert b.P_W == pytest.approx(a.P_W, rel=0.03)
    assert tb.steady_state(S.with_(Fz=0.0)).P_W == a.P_W
    ld = scene_load(S.with_(Fr=0.0, Fz=2000.0))
    assert abs(float(ld.delta_z)) > 10 * abs(float(ld.delta_r))


def test_the_loads_verb_carries_fz_and_my(capsys):
    code, out, _ = run(capsys, "loads", BATH, "--set", "Fz_N=800", "--set", "My_Nm=1.5", "--json")
    d = json.loads(out)
    assert code == 0 and d["Fz_N"] == 800.0 and d["My_Nm"] == 1.5 and d["delta_z_um"] > 0 and d["theta_y_mrad"] != 0


def test_overload_exits_2_before_any_solve_naming_load_limit_and_c0(capsys):
    """6208 at Fr 40 kN (C0 ≈ 19.9 kN): s0 = 0.497 < 0.5, refused in one line, not a thermal runaway."""
    C0 = load_ratings(tb.bearing("6208"))[1]
    for verb in (("run",), ("loads",), ("transient", "--t-end", "100")):
        code, out, err = run(capsys, *verb[:1], BATH, *verb[1:], "--set", "Fr=40000")
        assert code == 2 and out == "" and len(err.strip().splitlines()) == 1, verb
        assert "Fr 40000 N" in err and "must be >= 0.5" in err and f"C0 = {C0:.4g} N of 6208" in err
        assert "ThermalRunaway" not in err
    check_static_safety(S.with_(Fr=0.49 * 2 * C0))           # s0 just above 0.5: accepted


def test_run_answers_ratings_in_text_and_json(capsys):
    code, out, _ = run(capsys, "run", BATH, "--json")
    d = json.loads(out)
    C, C0, _ = stated_ratings(tb.bearing("6208"))          # the catalogue's, else from the geometry
    r = d["ratings"]
    assert code == 0 and r["C_N"] == pytest.approx(C) and r["C0_N"] == pytest.approx(C0)
    assert d["s0"] == pytest.approx(C0 / 2000.0) and {"mounted", "operating"} <= set(d["clearance_um"])
    assert r["L10_h"] == pytest.approx((C / 2000.0) ** 3 * 1e6 / (60 * 3000.0), rel=1e-12)
    assert r["L10m_h"] == pytest.approx(r["a_ISO"] * r["L10_h"]) and r["L10r_h"] > 0
    assert 0 < r["p_max_Pa"]["outer"] < r["p_max_Pa"]["inner"] < 4.2e9
    # κ > 4: ISO 281 takes κ = 4 — stated with the ratings, not a warning (below 0.1 it is one)
    assert r["kappa"] > 4 and not any(w["quantity"] == "kappa" for w in d["warnings"])
    code, out, _ = run(capsys, "run", BATH)
    assert "Ratings (ISO 76, ISO 281, ISO/TS 16281)" in out and "L10m" in out and "k5 (13.5 µm) / H7 (-21.5 µm)" in out
    assert "a_ISO at kappa = 4, ISO 281" in out


def test_life_falls_with_load_as_the_cube():
    r1, r2 = (scene_ratings(s, tb.steady_state(s)) for s in (S.with_(Fr=1000.0), S.with_(Fr=2000.0)))
    assert r1.L10_h / r2.L10_h == pytest.approx(8.0, rel=1e-12)
    assert r2.L10m_h < r1.L10m_h and r2.s0 == pytest.approx(r1.s0 / 2)


def _steady(Ti, To, Q=1000.0):
    """A steady state as scene_ratings reads it: node temperatures, roles and contacts."""
    b = S.bearing
    c = tb.hertz(Q, b.Rx_i(0.0), b.Ry_i, b.E_prime), tb.hertz(Q, b.Rx_o(0.0), b.Ry_o, b.E_prime)
    side = (lambda h: {"Q": np.full(b.Z, Q), "a": np.full(b.Z, float(h.a)), "b": np.full(b.Z, float(h.b))})  # noqa: E731
    return SimpleNamespace(T_C={"inner_ring": Ti, "outer_ring": To, "balls": 0.5 * (Ti + To)},
                           roles={"inner": "inner_ring", "outer": "outer_ring", "ball": "balls"},
                           losses=SimpleNamespace(contacts={"inner": side(c[0]), "outer": side(c[1])}))


def test_kappa_rises_as_the_bearing_cools():
    k = [scene_ratings(S, _steady(T, T)).kappa for T in (90.0, 70.0, 50.0)]
    assert k[0] < k[1] < k[2]
    assert k[2] == pytest.approx(S.lubricant.nu(50.0) * 1e-6 / tb.rating.iso281.reference_viscosity(3000.0, S.bearing.dm))


def test_operating_clearance_falls_as_the_inner_ring_warms_and_is_the_fit_formula():
    cl = [scene_ratings(S, _steady(T, 40.0)).clearance_um for T in (40.0, 60.0, 80.0)]
    assert cl[0]["operating"] > cl[1]["operating"] > cl[2]["operating"]
    # the scene describes its machine: the seats of its network's joints (k5 / H7, probable), its shaft's and
    # housing's materials (the ratings took the load-typical fits of a bare bearing before: j6 or k5)
    m = S.network
    hand = operating_clearance(S.bearing, shaft="k5", housing="H7", T_inner_C=60.0, T_outer_C=40.0, T_ball_C=50.0,
                               T_shaft_C=60.0, T_housing_C=40.0, n_rpm=3000.0, shaft_bore=m.shaft.bore,
                               shaft_material=material(m.shaft.material), housing_material=material(m.housing.material))
    assert cl[1]["operating"] == pytest.approx(float(hand.Pd) * 1e6, abs=1e-9)
    assert cl[1]["shaft_fit"] == "k5 (13.5 µm)" and "network's joints" in cl[1]["fits_from"]
    assert cl[2]["operating"] < 0                                   # C0 6208 (13 µm) consumed by 40 K
    r = scene_ratings(S, _steady(80.0, 40.0))
    assert any(isinstance(w, OutsideValidity) and w.quantity == "operating_clearance" for w in r.warnings)


def test_typical_fits_follow_the_load_and_scene_fits_win():
    b = tb.bearing("6208")
    assert typical_fits(b, 1000.0, 30000.0)[:2] == ("j6", "H7")      # P <= 0.05 C: light
    assert typical_fits(b, 3000.0, 30000.0)[:2] == ("k5", "H7")
    assert typical_fits(b, 3000.0, 30000.0, "outer")[:2] == ("h6", "N7")
    raw = {**S.raw, "bearing": {**S.raw["bearing"], "shaft_fit": "m5", "housing_fit": "J7"}}
    c = scene_ratings(scene_from_dict(raw, path=S.path), _steady(50.0, 50.0)).clearance_um
    assert (c["shaft_fit"], c["housing_fit"], c["fits_from"]) == ("m5", "J7", "the scene")


def _catalogue_ends():
    from thermobear.contact.geometry import bearing_names
    series: dict = {}
    for name in bearing_names():
        b = tb.bearing(name)
        if b.C0 is not None and b.series is not None:
            series.setdefault(b.series, []).append(name)
    return [n for names in series.values() for n in (names[0], names[-1])]


@pytest.mark.parametrize("name", _catalogue_ends())
def test_every_catalogue_series_answers_with_its_ratings(name):
    # the smallest and largest bearing of every series, in an oil-bath block housing at ISO 15312's
    # reference load, 1500 rpm: the run answer carries C0, C, s0, κ, a_ISO and L10m
    b = tb.bearing(name)
    thrust = b.kind == "thrust"
    Fr = 0.0 if thrust else 0.05 * b.C0
    Fa = 0.02 * b.C0 if thrust else (1.25 * Fr * np.tan(b.alpha0) if b.kind == "angular_contact" else 0.0)
    s = scene_from_dict({"bearing": {"catalog": name},
                         "lubricant": {"name": "iso-vg-68-mineral", "supply": "oil_bath", "oil_level_mm": b.D * 500},
                         "operation": {"n_rpm": 1500.0, "Fr_N": Fr, "Fa_N": Fa}, "thermal": {"T_ambient_C": 25.0},
                         "housing": {}})
    d = tb.solve(s).as_dict()                     # what run --json prints
    r = d["ratings"]
    assert r["C0_N"] == pytest.approx(b.C0, rel=1e-3) and r["C_N"] == pytest.approx(b.C, rel=1e-3)   # (catalogue: whole N)
    assert d["s0"] == pytest.approx(r["C0_N"] / r["P0_N"], rel=1e-9) and d["s0"] > 1.0
    assert 0.0 < d["kappa"] and 0.0 < d["a_ISO"] <= 50.0
    assert d["L10m_h"] == pytest.approx(d["a_ISO"] * r["L10_h"], rel=1e-9)


def test_ratings_use_the_c_and_c0_the_bearing_data_state():
    """A stated C / C0 (catalogue or scene C_kN, C0_kN) is the rating the answer uses; the geometry's only where
    the data give none (the life scales with the stated C cubed)."""
    s = S.with_(bearing={"catalog": "6208", "C_kN": 40.0, "C0_kN": 25.0})
    r, r0 = scene_ratings(s, _steady(40.0, 35.0)), scene_ratings(S, _steady(40.0, 35.0))
    assert (r.C_N, r.C0_N) == (40000.0, 25000.0)
    assert r.s0 == pytest.approx(25000.0 / r.P0_N, rel=1e-12)
    assert r.L10_h / r0.L10_h == pytest.approx((40000.0 / r0.C_N) ** 3, rel=1e-9)


def test_an_unloaded_bearing_has_no_fatigue_life_and_no_error(capsys):
    s = S.with_(Fr=0.0, Fa=0.0)
    r = scene_ratings(s, _steady(40.0, 35.0, Q=0.0))
    assert r.P_N == 0.0 and r.L10_h == np.inf and r.L10m_h == np.inf and r.s0 == np.inf and r.a_ISO == 50.0
    assert any("unloaded (P = 0), no fatigue life" in ln for ln in r.lines())
    code, out, _ = run(capsys, "run", BATH, "--set", "Fr=0", "--json")
    assert code == 0 and json.loads(out)["ratings"]["L10_h"] is None          # JSON has no infinity


def test_a_thrust_bearing_reports_no_radial_clearance_or_fits():
    s = tb.load_scene(str(EX / "seed002_grease_thrust_51107.toml"))
    r = scene_ratings(s, tb.steady_state(s))
    assert r.clearance_um["applies"] is False and "operating" not in r.clearance_um
    text = "\n".join(r.lines())
    assert "thrust bearing: no radial clearance" in text and "  fits " not in text and "H7" not in text
    assert not any(w.quantity == "operating_clearance" for w in r.warnings)


def test_operating_lives_fall_as_the_oil_thins():
    """κ = ν/ν1 falls with the operating temperature (the oil thins), and with it a_ISO and L10m (ISO 281
    §9.3.3); L10 does not depend on it; each element of the batch equals the scalar call."""
    T = np.linspace(30.0, 110.0, 9)
    lv = operating_lives(S, T)
    assert np.all(np.diff(lv["kappa"]) < 0) and np.all(np.diff(lv["a_ISO"]) <= 0)
    assert np.all(np.diff(lv["L10m_h"]) <= 0) and lv["L10m_h"][-1] < lv["L10m_h"][0]
    for k, t in enumerate(T):
        one = operating_lives(S, float(t))
        assert isinstance(one["kappa"], float)
        for key in ("kappa", "a_ISO", "L10m_h"):
            assert one[key] == pytest.approx(lv[key][k], rel=1e-12)
    with pytest.raises(InputError, match="n_rpm"):
        operating_lives(S.with_(n_rpm=0.0), 40.0)


def test_rating_samples_equal_each_points_ratings():
    """The batched design answers of many solved points (an uncertainty band's samples) are those of
    scene_ratings point by point: two speeds and two loads (four groups), a failed point NaN."""
    scenes = [S.with_(n_rpm=n, Fr_N=f) for n in (2000.0, 4000.0) for f in (500.0, 3000.0)]
    states = [tb.steady_state(s) for s in scenes]
    out = rating_samples(scenes + scenes[:1], states + [None])
    for i, (s, st) in enumerate(zip(scenes, states)):
        rt = scene_ratings(s, st)
        for key, v in (("T_operating_C", rt.T_operating_C), ("kappa", rt.kappa), ("a_ISO", rt.a_ISO),
                       ("L10m_h", rt.L10m_h), ("clearance_op_um", rt.clearance_um["operating"])):
            assert out[f"ratings.{key}"][i] == pytest.approx(v, rel=1e-12), (i, key)
    assert all(np.isnan(v[-1]) for v in out.values())
    thrust = tb.load_scene(str(EX / "seed002_grease_thrust_51107.toml"))
    got = rating_samples([thrust], [tb.steady_state(thrust)])
    assert "ratings.kappa" in got and "ratings.clearance_op_um" not in got   # no radial clearance


def test_ratings_of_many_points_are_each_points_ratings():
    """A sweep's rows rated together (scene_ratings_many: the clearance once per group of bearing, fits and network)
    answer as each point rated alone: a deep groove bearing's machine at two speeds and two loads, another machine,
    an angular contact bearing on its typical fits and a thrust bearing, mixed and in reverse order."""
    scenes = [S.with_(n_rpm=n, Fr_N=f) for n in (2000.0, 4000.0) for f in (500.0, 3000.0)]
    scenes += [tb.load_scene(str(EX / f)) for f in ("block_6208_oil_jet.toml", "seed004_oil_jet_7210.toml",
                                                   "seed002_grease_thrust_51107.toml")]
    states = [tb.steady_state(s) for s in scenes]
    many = scene_ratings_many(scenes[::-1], states[::-1])[::-1]
    fits = set()
    for s, st, rt in zip(scenes, states, many):
        assert rt.as_dict() == scene_ratings(s, st).as_dict()
        if s.bearing.kind != "thrust":
            alone = scene_clearance(s, st.T_C, st.roles)
            assert rt.clearance_um["operating"] == pytest.approx(alone["operating"], rel=1e-12, abs=1e-9)
            assert rt.clearance_um["shaft_fit"] == alone["shaft_fit"]
            fits.add(alone["shaft_fit"])
    assert len(fits) >= 2                       # (groups of different fits in one call)
    assert many[-1].clearance_um["applies"] is False
    assert scene_ratings_many([], []) == []


def test_a_machines_clearance_takes_the_seats_of_its_network(tmp_path):
    """A scene that describes its machine: its operating clearance takes the seats its network's joints take —
    the [shaft] / [housing] interference_um it gives (init writes them), else the builders' probable fit.  It took
    the load-typical fit of a bare bearing (j6 at the ISO 15312 reference load of a 6208) while the network sat the
    ring on k5, and ignored interference_um."""
    from thermobear.thermal.builders import seat_interferences
    path = tmp_path / "x.toml"
    assert main(["init", "6208", "--lubrication", "oil-bath", "--out", str(path)]) == 0
    s = tb.load_scene(path)
    (I_i, why_i), (I_o, _) = seat_interferences(s.network)
    assert why_i == "[shaft] interference_um" and I_i == pytest.approx(13.5e-6)
    st = tb.steady_state(s)
    c = scene_ratings(s, st).clearance_um
    tight = dict(s.raw["shaft"], interference_um=30.0)
    s2 = scene_from_dict({**s.raw, "shaft": tight}, path=s.path)
    c2 = scene_ratings(s2, st).clearance_um
    assert c["mounted"] > c2["mounted"]                              # a tighter seat takes more clearance
    hand = operating_clearance(s.bearing, I_inner_m=30e-6, I_outer_m=I_o, shaft_bore=s2.network.shaft.bore,
                               shaft_material=material(s2.network.shaft.material),
                               housing_material=material(s2.network.housing.material))
    assert c2["mounted"] == pytest.approx(float(hand.Pd) * 1e6, rel=1e-12)
    assert c2["shaft_fit"] == "30.0 µm" and "interference_um" in c2["fits_from"]
    with pytest.raises(InputError, match="I_inner_m"):
        operating_clearance(s.bearing, I_inner_m=float("nan"))


def test_rating_samples_read_each_samples_lubricant_draws():
    """An uncertainty sample draws the oil's viscosity (lubricant.nu100_cSt): its κ is that of its own oil at its
    own temperature (the bands read the nominal oil's, so κ, a_ISO and L10m moved with the temperature alone)."""
    st = tb.steady_state(S)
    lo, hi = S.with_(samples={"lubricant.nu100_cSt": 8.0}), S.with_(samples={"lubricant.nu100_cSt": 9.6})
    out = rating_samples([lo, hi, S], [st, st, st])
    T = st.T_C
    for k, sc in enumerate((lo, hi)):
        lub = sc.lubricant.sampled({"nu100_cSt": np.array([sc.samples["lubricant.nu100_cSt"]])})
        T_op = 0.5 * (T[st.roles["inner"]] + T[st.roles["outer"]])
        want = operating_lives(sc, T_op, float(np.ravel(lub.nu(T_op))[0]) * 1e-6)["kappa"]
        assert out["ratings.kappa"][k] == pytest.approx(want, rel=1e-12)
    assert out["ratings.kappa"][0] < out["ratings.kappa"][2] < out["ratings.kappa"][1]   # thinner oil, lower κ


def test_a_machine_with_one_fit_stated_keeps_the_other_rings_seat():
    """A machine scene that states the shaft's fit only: the housing sits on its network's seat (it fell back to
    the load-typical housing fit and said the fits came from the load)."""
    raw = {**S.raw, "bearing": {**S.raw["bearing"], "shaft_fit": "m5"}}
    s = scene_from_dict(raw, path=S.path)
    c = scene_ratings(s, _steady(50.0, 50.0)).clearance_um
    assert c["shaft_fit"] == "m5" and c["housing_fit"] == "H7 (-21.5 µm)"
    assert "housing H7 (probable)" in c["fits_from"] and "other ring's fit from the scene" in c["fits_from"]


def test_ratings_at_a_prescribed_temperature():
    """`run` with operation.T_C gave no ratings (an engineer's usual question: the life at a specified 70 °C):
    now κ and the lives are ISO 281's at that temperature, the clearance with every part at it (a uniform
    temperature: the fits alone and the speed), and a hotter specification gives a shorter L10m."""
    from thermobear.coupled import solve
    from thermobear.coupled.ratings import operating_lives
    s = tb.load_scene(tb.example_path("block_6208_oil_bath.toml"))
    r70, r90 = solve(s.with_(T_C=70.0)), solve(s.with_(T_C=90.0))
    lv = operating_lives(s, 70.0)
    assert r70.ratings.T_operating_C == 70.0 and r70.ratings.kappa == pytest.approx(float(lv["kappa"]), rel=1e-12)
    assert r70.ratings.L10m_h == pytest.approx(float(lv["L10m_h"]), rel=1e-12)
    assert r90.ratings.L10m_h < r70.ratings.L10m_h and r90.ratings.L10_h == r70.ratings.L10_h
    c = r70.ratings.clearance_um
    assert abs(c["operating"] - c["mounted"]) < 0.1          # no ring temperature difference: the speed's growth only
    assert "ratings" in r70.as_dict() and r70.ratings.L10r_h > 0


def test_an_angular_contact_bearings_clearance_says_what_it_is():
    """A single 7210 B's 'clearance mounted 229.85 µm' meant nothing to an engineer: the ratings say it is the play
    the contact angle implies, which a pair's axial adjustment overrides; a deep groove bearing's carries no note."""
    from thermobear.coupled import solve
    r = solve(tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")))
    assert "2A(1 − cos α0)" in r.ratings.clearance_um["note"] and r.ratings.lines()[-1].startswith("  (angular contact")
    dg = solve(tb.load_scene(tb.example_path("block_6208_oil_bath.toml")))
    assert "note" not in dg.ratings.clearance_um


def test_a_radial_preload_warning_says_whether_the_next_clearance_group_would_keep_a_clearance():
    """The preload warning names the next ISO 5753-1 group and whether its larger mid clearance would leave a clearance
    at the same temperatures and fits (a designer's first question; `init` scenes on k5 seats ran preloaded in CN)."""
    from thermobear.contact.geometry import radial_clearance
    from thermobear.coupled.ratings import preload_warnings
    b = tb.bearing("6208")
    assert b.clearance_group == "CN"
    gain = sum(radial_clearance(b.bore, "C3")) / 2 - sum(radial_clearance(b.bore, "CN")) / 2
    c = {"mounted": 1.69, "shaft_fit": "k5", "housing_fit": "H7"}
    small = str(preload_warnings(b, -0.5 * gain, c, "warm")[0])
    large = str(preload_warnings(b, -2.0 * gain, c, "warm")[0])
    assert f"a C3 bearing (+{gain * 1e6:.3g} µm mid clearance) would keep a clearance here" in small
    assert "would not keep a clearance here (looser fits, or a larger group)" in large
    c4 = str(preload_warnings(b.with_(clearance_group="C4"), -4e-6, c, "warm")[0])
    assert "clearance here" not in c4 and "bearing (+" not in c4                      # no larger group to offer
