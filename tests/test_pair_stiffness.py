"""The stiffness of a preloaded pair (thermobear.loads.pair.pair_loads ``with_stiffness``; a steady answer's
``preload["k_..."]``): at the pair's centre under the external loads, the other displacements free.  Pinned to the
analytic limit at rest (each bearing's own dF_a/dδ_a, the two in parallel; a spring's bearing alone), the mirror
symmetry of back-to-back and face-to-face pairs, the high-speed form at n = 0 against the static form's stiffness
matrix, Hertz's F^(1/3) trend with the preload, and the steady answer's three states."""
import warnings

import numpy as np
import pytest

import thermobear as tb
from thermobear.contact.geometry import bearing
from thermobear.coupled.preload import preload_lines
from thermobear.coupled.ratings import PRELOAD_OUTPUTS
from thermobear.loads.highspeed import load_distribution_high_speed
from thermobear.loads.pair import pair_loads
from thermobear.loads.static import load_distribution_static

B = bearing("7014C")


def k_axial_single(brg, F0, h=0.01):
    """One bearing's axial stiffness dF_a/dδ_a under the pure axial load F0 [N/m] (central differences of the
    static load distribution)."""
    d = [float(load_distribution_static(brg, Fa=F, Fr=0.0).delta_a) for F in (F0 + h, F0 - h)]
    return 2.0 * h / (d[0] - d[1])


@pytest.mark.parametrize("name, F0", [("7014C", 300.0), ("7210", 450.0), ("7205B", 1000.0)])
def test_at_rest_a_position_pair_is_both_bearings_in_parallel(name, F0):
    """No external load: the shaft moved axially compresses one bearing and relieves the other, each at the preload,
    k = 2 dF_a/dδ_a(F0); a spring preload's outer ring slides, its bearing holds nothing: k = dF_a/dδ_a(F0)."""
    b = bearing(name)
    k1 = k_axial_single(b, F0)
    assert pair_loads(b, "back_to_back", F0, with_stiffness=True).stiffness[0] == pytest.approx(2 * k1, rel=1e-6)
    assert pair_loads(b, "back_to_back", F0, "spring", with_stiffness=True).stiffness[0] == pytest.approx(k1, rel=1e-6)


@pytest.mark.parametrize("n_rpm", [None, 8000.0])
def test_back_to_back_and_face_to_face_are_alike_without_external_load(n_rpm):
    """Mirror symmetry at the pair's centre: with the preload alone the two arrangements have the same axial and
    radial stiffness (they differ in tilt, and under a radial load through the axial–tilt coupling, which the
    back-to-back pair's wider spread of contact lines leaves freer to tilt here: less axial stiffness)."""
    db = pair_loads(B, "back_to_back", 300.0, n_rpm=n_rpm, with_stiffness=True).stiffness
    df = pair_loads(B, "face_to_face", 300.0, n_rpm=n_rpm, with_stiffness=True).stiffness
    assert db[:2] == pytest.approx(df[:2], rel=1e-5)
    under = [pair_loads(B, a, 300.0, Fr=2020.0, with_stiffness=True).stiffness for a in ("back_to_back", "face_to_face")]
    assert under[0][1] == pytest.approx(under[1][1], rel=1e-9) and under[0][0] < 0.9 * under[1][0]


@pytest.mark.parametrize("n_rpm", [8000.0, 12000.0])
def test_at_speed_the_pair_is_its_bearings_high_speed_stiffness(n_rpm):
    """At speed without external load, the inner rings held at their size (``u_inner=0``: the bearing's own
    geometry): a position pair's axial stiffness is twice one bearing's high-speed dF_a/dδ_a at the pair's preload at
    that speed (the balls' centrifugal force in it), a spring pair's that of its held bearing at the spring force."""
    def k_single(F, h=0.05):
        d = [float(load_distribution_high_speed(B, Fa=x, Fr=0.0, n_rpm=n_rpm).delta_a) for x in (F + h, F - h)]
        return 2.0 * h / (d[0] - d[1])
    pos = pair_loads(B, "back_to_back", 300.0, n_rpm=n_rpm, with_stiffness=True, u_inner=0.0)
    assert pos.stiffness[0] == pytest.approx(2.0 * k_single(pos.preload), rel=1e-4)
    spring = pair_loads(B, "back_to_back", 300.0, "spring", n_rpm=n_rpm, with_stiffness=True, u_inner=0.0)
    assert spring.stiffness[0] == pytest.approx(k_single(300.0), rel=1e-4)


@pytest.mark.parametrize("name", ["7014C", "7210"])
def test_the_tilt_stiffness_is_the_arrangements_pressure_centres(name):
    """A back-to-back pair's pressure centres lie a = B/2 + (d_m/2) tan α0 either side of its centre: its tilt
    stiffness is about the two bearings' radial stiffness at that arm, 2 k_r,1 a² (the bearings' own moment stiffness
    adds a little); a face-to-face pair's at |B/2 − (d_m/2) tan α0|: less, and for a 15° bearing, whose face-to-face
    pressure centres nearly meet at the pair's centre, far less (Harris & Kotzalas 2007 ch. 8)."""
    b = bearing(name)
    db = pair_loads(b, "back_to_back", 300.0, with_stiffness=True).stiffness
    df = pair_loads(b, "face_to_face", 300.0, with_stiffness=True).stiffness
    k_r1 = 0.5 * db[1]                                    # (db[1]: both bearings' radial stiffness in parallel)
    for k, a in ((db[2], 0.5 * b.width + 0.5 * b.dm * np.tan(b.alpha0)),
                 (df[2], abs(0.5 * b.width - 0.5 * b.dm * np.tan(b.alpha0)))):
        assert 2.0 * k_r1 * a ** 2 < k < 2.0 * k_r1 * a ** 2 + 0.25 * db[2]
    assert db[2] > (10.0 if name == "7014C" else 2.0) * df[2]


@pytest.mark.parametrize("Fa, Fr", [(0.0, 0.0), (0.0, 2020.0), (500.0, 800.0)])
def test_the_high_speed_form_at_rest_is_the_static_forms_matrix(Fa, Fr):
    """Central differences of the high-speed shaft at n = 0 against the inverse of the static shaft's stiffness
    matrix: the same stiffness to the differences' error."""
    static = pair_loads(B, "back_to_back", 300.0, Fa=Fa, Fr=Fr, with_stiffness=True).stiffness
    rest = pair_loads(B, "back_to_back", 300.0, Fa=Fa, Fr=Fr, n_rpm=0.0, with_stiffness=True).stiffness
    assert rest == pytest.approx(static, rel=2e-4)


def test_stiffness_rises_about_as_the_cube_root_of_the_preload():
    """Hertz: δ ∝ Q^(2/3), so k ∝ F^(1/3): doubling the preload stiffens the pair by about 2^(1/3) = 1.26; the
    contact angle's growth under load adds to the axial stiffness, little at α0 = 40° (7210), much at 15° (7014C)."""
    r = {}
    for name in ("7210", "7014C"):
        k = [pair_loads(bearing(name), "back_to_back", F, with_stiffness=True).stiffness for F in (300.0, 600.0)]
        r[name] = (k[1][0] / k[0][0], k[1][1] / k[0][1])
    assert 1.26 < r["7210"][0] < 1.29 and 1.22 < r["7210"][1] < 1.27 and 1.22 < r["7014C"][1] < 1.27
    assert r["7014C"][0] > r["7210"][0] + 0.05


def test_the_loads_are_those_without_the_stiffness():
    """Asking for the stiffness adds load cases to the same call; the pair's loads stay the same to the solver's
    tolerance (static: the same call)."""
    for n in (None, 12000.0):
        a = pair_loads(B, "back_to_back", 300.0, Fr=2020.0, n_rpm=n)
        b = pair_loads(B, "back_to_back", 300.0, Fr=2020.0, n_rpm=n, with_stiffness=True)
        assert (b.Fa, b.Fr, b.preload) == pytest.approx((a.Fa, a.Fr, a.preload), rel=1e-9)
        assert a.stiffness is None and min(b.stiffness) > 0


def test_a_pairs_steady_answer_gives_its_stiffness_cold_at_speed_and_warm():
    """Seed 004's 7210 as a back-to-back pair at 450 N, the block's 650 N radial load: the warm pair carries more
    preload and is stiffer than cold; the answer's cold-at-rest stiffness is pair_loads' at rest; the text names all
    three; the warm stiffness is an uncertainty output."""
    s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")).with_(arrangement="back_to_back", preload_N=450.0,
                                                                           Fa=0.0, Fr=650.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        p = tb.steady_state(s).preload
    cold = pair_loads(s.bearing, "back_to_back", 450.0, Fr=650.0, with_stiffness=True).stiffness
    assert (p["k_axial_cold_N_um"], p["k_radial_cold_N_um"], p["k_tilt_cold_Nm_mrad"]) == pytest.approx(
        (cold[0] * 1e-6, cold[1] * 1e-6, cold[2] * 1e-3), rel=1e-12)
    assert p["warm_N"] > p["at_speed_cold_N"] and p["k_axial_warm_N_um"] > p["k_axial_at_speed_cold_N_um"]
    assert p["k_radial_warm_N_um"] > p["k_radial_at_speed_cold_N_um"]
    assert {"preload.k_axial_warm_N_um", "preload.k_radial_warm_N_um", "preload.k_tilt_warm_Nm_mrad"} <= set(PRELOAD_OUTPUTS)
    assert p["k_tilt_warm_Nm_mrad"] > p["k_tilt_at_speed_cold_Nm_mrad"] > 0
    line = [x for x in preload_lines(p) if "stiffness" in x]
    assert len(line) == 1 and f"{p['k_axial_warm_N_um']:.4g}" in line[0] and "at speed" in line[0]


def test_a_stiffness_without_a_solution_is_named_not_nan(monkeypatch):
    """Where the pair's loads with the stiffness's load steps have no solution (here the warm state, forced), the
    answer names it (an OutsideValidity warning) and leaves that state out: no NaN in the answer or its text."""
    from thermobear.coupled import preload as pl
    from thermobear.errors import NoConvergence
    real = pl.scene_pair_loads

    def failing(scene, T, offset=None, start=None, *, with_stiffness=False, at_rest=False):
        if with_stiffness and T is not None:
            raise NoConvergence("forced for the test", iterations=1, residual=1.0)
        return real(scene, T, offset, start, with_stiffness=with_stiffness, at_rest=at_rest)
    monkeypatch.setattr(pl, "scene_pair_loads", failing)
    s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")).with_(arrangement="back_to_back", preload_N=450.0,
                                                                           Fa=0.0, Fr=650.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        st = tb.steady_state(s)
    p = st.preload
    assert "k_axial_warm_N_um" not in p and p["k_axial_cold_N_um"] > 0 and p["k_axial_at_speed_cold_N_um"] > 0
    named = [w for w in st.warnings if w.quantity == "pair stiffness"]
    assert len(named) == 1 and "warm" in str(named[0]) and "forced for the test" in str(named[0])
    text = "\n".join(preload_lines(p))
    assert "nan" not in text and "cold at rest" in text and "warm at speed" not in text
