"""Where the models hold (thermobear.validity): every limit refuses beyond its accepted range with
the field, the value, the range and the source, and warns beyond its validated range; the solvers
and the entry points apply the same limits."""
import math
import warnings

import numpy as np
import pytest

import thermobear as tb
from thermobear import validity
from thermobear.errors import InputError, OutsideValidity

S004 = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))


@pytest.mark.parametrize("name", sorted(validity.LIMITS))
def test_every_limit_refuses_and_warns_with_its_source(name):
    lim = validity.LIMITS[name]
    lo, hi = lim.refuse
    if hi is not None:
        with pytest.raises(InputError) as e:
            validity.check(name, hi * 1.01 + 1e-12, "field.x")
        msg = str(e.value)
        assert msg.startswith("field.x = ") and lim.quantity in msg and lim.source in msg
    if lo is not None:
        with pytest.raises(InputError):
            validity.check(name, lo - 1.0 if lo > 0 else -1.0 if lo == 0 else lo * 1.01, "field.x")
    wlo, whi = lim.warn
    inside = [v for v in (wlo, whi) if v is not None]
    if inside:
        v = (whi * 1.01 if whi is not None and (hi is None or whi * 1.01 < hi) else wlo * 0.99 if wlo else -1e-9)
        with pytest.warns(OutsideValidity) as rec:
            got = validity.check(name, v, "field.y")
        assert got and got[0].quantity == name and got[0].source == lim.source and "field.y" in str(rec[0].message)
    with pytest.raises(InputError, match="finite"):
        validity.check(name, math.nan, "field.z")


def test_inside_every_range_nothing_is_said():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert validity.check("n_dm", 3e5, "x") == [] and validity.check("p_max", 2e9, "x") == []
        assert validity.check("lubricant_T", np.array([20.0, 80.0]), "x") == []


def test_the_solvers_and_the_scene_share_the_speed_limit():
    # a scene refuses 1e6 rpm on a 7210 (n dm = 7e7 mm/min), as every solver entry point does
    with pytest.raises(InputError, match="speed n·dm"):
        S004.with_(n_rpm=1e6)
    with pytest.raises(InputError, match=r"^n_rpm = 1000000.0 — speed n·dm 7e\+07 mm/min must lie in \[0, 4e\+06\]"):
        tb.bearing_losses(S004.bearing, S004.lubricant, 450.0, 325.0, n_rpm=1e6, T_C=50.0)
    with pytest.raises(InputError, match=r"^n_rpm = 1000000.0 — speed n·dm"):
        tb.load_distribution(S004.bearing, 450.0, 325.0, n_rpm=1e6)
    with pytest.warns(OutsideValidity, match="speed n·dm"):
        st = tb.steady_state(S004.with_(n_rpm=16000.0))          # 1.1e6: computed, but outside the validated
    assert any(w.quantity == "n_dm" for w in st.warnings)


def test_a_load_the_contacts_cannot_carry_is_refused_naming_the_loads():
    # far beyond (even shared by all balls): refused before any solve, naming the scene's key
    with pytest.raises(InputError, match=r"^operation\.Fa_N = 1000000.0 — maximum contact pressure \d+ MPa must lie "
                                         r"in \[0, 5292\] \[MPa\]"):
        tb.steady_state(S004.with_(Fa=1e6))
    with pytest.raises(InputError, match=r"^operation\.Fa_N = 1000000.0 — .*twice the rated contact load"):
        tb.solve(S004.with_(Fa=1e6, T_C=50.0))
    # beyond at the most loaded ball only: refused before any solve by the static safety (P0 > 2 C0, ISO 76)
    with pytest.raises(InputError) as e:
        tb.solve(S004.with_(Fa=5000.0, Fr=70000.0, T_C=50.0))
    assert str(e.value).startswith("operation (Fa_N, Fr_N, Fz_N) = 'Fa 5000 N, Fr 70000 N' — static safety s0 0.3643 - "
                                   "must be >= 0.5 [-] (P0 = 7e+04 N against C0 = 2.55e+04 N of 7210, ISO 76)")


def test_osculation_outside_its_range_is_refused():
    with pytest.raises(InputError, match=r"bearing\[x\]\.fi = 10.0 — osculation must lie in \(0.5, 2\]"):
        tb.BallBearing(D=11.5e-3, dm=43.5e-3, Z=7, fi=10.0, fo=0.53, name="x")
    with pytest.raises(InputError, match="fo"):
        tb.BallBearing(D=11.5e-3, dm=43.5e-3, Z=7, fi=0.52, fo=0.49, name="x")


def test_a_start_below_the_lubricants_range_is_refused():
    with pytest.raises(InputError, match="T0_C|T_ambient_C"):
        tb.transient(S004, 100.0, T0_C=-60.0)


def test_the_answers_warnings_are_its_own():
    """A point inside every range carries no warning, although intermediate iterates may lie
    beyond the lubricant's data; one outside carries each warning once."""
    assert tb.steady_state(S004).warnings == []
    hot = tb.steady_state(S004.with_(n_rpm=16000.0))
    names = [w.quantity for w in hot.warnings]
    assert len(names) == len(set(map(str, hot.warnings)))


def test_a_bearing_at_speed_without_load_is_warned():
    """The rings of an unloaded bearing are held centred, which is not the limit of a small load (seed 004's 7210
    at 40 °C: 19 W unloaded, 45 W under 1 µN axial): the answer says so; a loaded one, or one at rest, does not."""
    import thermobear as tb
    s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    unloaded = tb.steady_state(s.with_(Fa=0.0, Fr=0.0))
    assert [w for w in unloaded.warnings if w.quantity == "unloaded"]
    assert not [w for w in tb.steady_state(s).warnings if w.quantity == "unloaded"]
    from thermobear.coupled.limits import point_warnings
    assert not [w for w in point_warnings(s.with_(Fa=0.0, Fr=0.0, n_rpm=0.0), None, [20.0]) if w.quantity == "unloaded"]
    bath = tb.load_scene(tb.example_path("oil_bath_6208.toml")).with_(Fr=0.0)      # a radial preload centres
    pre = tb.steady_state(bath.with_(bearing=bath.bearing.with_(Pd=-5e-6)))      # the rings: a state of its own
    assert not [w for w in pre.warnings if w.quantity == "unloaded"]


def test_a_friction_input_the_models_do_not_read_is_named():
    """lubricant.mu_full_film under the default Eyring traction was accepted and changed nothing, silently
    (0.01 and 0.1: the same seed-004 answer).  The answer now names it (UnreadInput: the field, the value, why);
    under models.traction = "constant" it is read — it moves the answer and nothing is said; the nominal scene
    says nothing."""
    from thermobear.errors import UnreadInput
    with pytest.warns(UnreadInput, match=r"^lubricant\.mu_full_film = 0\.01 is not read by the chosen models: "
                                         r'models\.traction = "eyring"'):
        lo = tb.steady_state(S004.with_(mu_full_film=0.01))
    with pytest.warns(UnreadInput, match=r"^lubricant\.mu_full_film = 0\.1 "):
        hi = tb.steady_state(S004.with_(mu_full_film=0.1))
    assert lo.P_W == pytest.approx(hi.P_W, rel=1e-12)                      # what the warning is about
    w = [w for w in lo.warnings if isinstance(w, UnreadInput)]
    assert len(w) == 1 and w[0].field == "lubricant.mu_full_film" and w[0].value == 0.01
    assert not [w for w in tb.steady_state(S004).warnings if isinstance(w, UnreadInput)]
    const = {"traction": "constant"}
    c_lo = tb.steady_state(S004.with_(mu_full_film=0.01, models=const))
    c_hi = tb.steady_state(S004.with_(mu_full_film=0.1, models=const))
    assert c_hi.P_W > c_lo.P_W * 1.05
    assert not [w for w in c_lo.warnings + c_hi.warnings if isinstance(w, UnreadInput)]


@pytest.mark.parametrize("kw,field", [
    (dict(mu_boundary=0.3, models={"losses": "skf"}), "lubricant.mu_boundary"),
    (dict(Rq_ball_um=0.5, models={"losses": "skf"}), "lubricant.Rq_ball_um"),
    (dict(models={"skf_R1": 2e-7}), "models.skf_R1"),
    (dict(Rq_ball_um=0.0, Rq_ring_um=0.0, mu_boundary=0.2), "lubricant.mu_boundary"),
])
def test_the_siblings_the_models_do_not_read_are_named(kw, field):
    """The same for the friction law's other inputs: μ_a and the roughnesses on the SKF model, an SKF constant on
    the local model, μ_a on smooth surfaces (Λ = ∞)."""
    from thermobear.errors import UnreadInput
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OutsideValidity)
        r = tb.solve(S004.with_(T_C=60.0, **kw))
    names = [w.field for w in r.warnings if isinstance(w, UnreadInput)]
    # (at a prescribed temperature seed 004's inlet and room temperatures are named too: no network reads them)
    assert field in names and set(names) - {field} == {"lubricant.T_in_C", "thermal.T_ambient_C"}


def test_a_ring_guided_cage_reads_mu_full_film():
    """A ring-guided cage's pocket friction is mu_full_film's: read under the Eyring traction too."""
    from thermobear.model_inputs import unread_inputs
    assert "lubricant.mu_full_film" in unread_inputs(S004)
    assert "lubricant.mu_full_film" not in unread_inputs(S004.with_(cage="outer_ring"))
