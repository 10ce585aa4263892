"""The entry point thermobear.loads.load_distribution: the form it chooses, equal to the form's own
function, the film law, mixed batches and loud input errors."""
import warnings

import numpy as np
import pytest

import thermobear as tb
from thermobear.contact.geometry import bearing
from thermobear.contact.kinematics import entrainment_speed
from thermobear.errors import InputError
from thermobear.loads import (film_load_distribution, high_speed_cases, load_distribution,
                              load_distribution_high_speed, load_distribution_static)

B = bearing("7210")
OIL50 = dict(eta=0.0221, alpha_p=2e-8)


def same(a, b, rtol=1e-13):
    for k in ("Q_i", "Q_o", "alpha_i", "alpha_o", "delta_a", "delta_r", "theta", "delta_n"):
        np.testing.assert_allclose(getattr(a, k), getattr(b, k), rtol=rtol, atol=1e-15, err_msg=k)


def test_top_level_name_is_the_entry_point():
    assert tb.load_distribution is load_distribution


@pytest.mark.parametrize("name, Fa, Fr, M", [("iso-dgbb", 0.0, 1000.0, None), ("7210", 450.0, 325.0, None),
                                              ("6210", 300.0, 1500.0, 2.0), ("51107", 7000.0, 0.0, 5.0)])
def test_at_rest_it_is_the_static_form(name, Fa, Fr, M):
    b = bearing(name)
    same(load_distribution(b, Fa, Fr, M), load_distribution_static(b, Fa, Fr, M))
    same(load_distribution(b, Fa, Fr, M, n_rpm=0.0, form="auto"), load_distribution_static(b, Fa, Fr, M))


def test_auto_takes_the_high_speed_form_where_the_centrifugal_force_matters():
    # F_c/Q > 5 % (needs_high_speed) for the 7210 under Fa 450 N, Fr 325 N above ≈ 2000 rpm
    n = np.array([500.0, 1000.0, 3200.0, 6500.0])
    hs = high_speed_cases(B, 450.0, 325.0, n)
    assert hs.tolist() == [False, False, True, True]
    same(load_distribution(B, 450.0, 325.0, n_rpm=3200.0), load_distribution_high_speed(B, 450.0, 325.0, n_rpm=3200.0))
    same(load_distribution(B, 450.0, 325.0, n_rpm=1000.0), load_distribution_static(B, 450.0, 325.0))
    # a thrust bearing stays static at any speed (its centrifugal force acts across the grooves)
    assert not high_speed_cases(bearing("51107"), 7000.0, 0.0, 20000.0)


def test_forms_on_request():
    same(load_distribution(B, 450.0, 325.0, n_rpm=3200.0, form="static"), load_distribution_static(B, 450.0, 325.0))
    same(load_distribution(B, 450.0, 325.0, n_rpm=500.0, form="high_speed"),
         load_distribution_high_speed(B, 450.0, 325.0, n_rpm=500.0))


def test_mixed_batch_is_solved_form_by_form():
    n = np.array([500.0, 3200.0, 0.0, 6500.0])
    Fr = np.array([325.0, 325.0, 750.0, 100.0])
    ld = load_distribution(B, 450.0, Fr, n_rpm=n)
    for k in range(4):
        one = load_distribution(B, 450.0, Fr[k], n_rpm=n[k])
        np.testing.assert_allclose(ld.Q_i[k], one.Q_i, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(ld.alpha_o[k], one.alpha_o, rtol=1e-12, atol=1e-14)
    assert np.allclose(ld.Q_i[0], ld.Q_o[0]) and not np.allclose(ld.Q_i[1], ld.Q_o[1])


def test_film_law_in_both_forms():
    # static form: the entrainment speeds given, or from n_rpm at the nominal contact angle
    u = float(entrainment_speed(4800.0 * np.pi / 30.0, 0.0, B.D, B.dm, B.alpha0))
    ref = film_load_distribution(B, 450.0, 750.0, u_i=u, u_o=u, **OIL50)
    same(load_distribution(B, 450.0, 750.0, film=dict(u_i=u, u_o=u, **OIL50)), ref, rtol=1e-12)
    same(load_distribution(B, 450.0, 750.0, n_rpm=4800.0, form="static", film=OIL50), ref, rtol=1e-12)
    # high-speed form: its own caged entrainment speeds
    same(load_distribution(B, 450.0, 750.0, n_rpm=4800.0, film=OIL50),
         load_distribution_high_speed(B, 450.0, 750.0, n_rpm=4800.0, film=OIL50), rtol=1e-12)


@pytest.mark.parametrize("kw, field", [
    (dict(form="fast"), "form"),
    (dict(n_rpm=-1.0), "n_rpm"),
    (dict(film=dict(eta=0.02, alpha_p=2e-8, u_i=3.0)), "film"),
    (dict(film=dict(eta=0.02, alpha_p=2e-8)), "n_rpm"),                 # static film law needs speeds
    (dict(film=dict(eta=0.02, alpha_p=2e-8, u_i=3.0, u_o=3.0), n_rpm=6500.0), "film"),   # high-speed: own speeds
    (dict(film=0.02), "film"),
])
def test_bad_input(kw, field):
    with pytest.raises(InputError) as e:
        load_distribution(B, 450.0, 325.0, **kw)
    assert e.value.field == field


def test_loads_no_set_of_balls_can_carry_are_refused_before_solving():
    # load_distribution(7210, Fa=1e5, Fr=1e6) returned ball loads of 300 kN at contact angles of 170°
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        with pytest.raises(InputError, match=r"^Fr = 1000000.0 — maximum contact pressure \d{4} MPa must lie in "
                                             r"\[0, 5292\] \[MPa\] \(at least: the largest ball load of 7210"):
            load_distribution(B, Fa=1e5, Fr=1e6)
        with pytest.raises(InputError, match="^Fa = 1e\\+30 — maximum contact pressure"):
            load_distribution(B, Fa=1e30)                       # solved before, through overflows
        with pytest.raises(InputError, match="^M = 1.7e\\+308 — maximum contact pressure inf MPa"):
            load_distribution(B, 450.0, 325.0, M=1.7e308)


def test_a_contact_ellipse_past_its_groove_equator_is_refused_naming_the_loads():
    with pytest.raises(InputError, match=r"^Fa, Fr, M = 'Fa 61379.7 N, Fr 0 N, M 0.182 N m' — contact angle \+ half the "
                                         r"contact ellipse, from the groove bottom 95.\d+ deg must be <= 90 \[deg\] "
                                         r"\(inner contacts\)"):
        load_distribution(bearing("7302B"), 61379.7, 0.0, 0.182)


def test_sub_physical_loads_and_speeds_are_refused_and_zero_is_not():
    with pytest.raises(InputError, match=r"^Fa = 1e-09 — load .* must be >= 1e-06 \[N\]"):
        load_distribution(B, Fa=1e-9)
    with pytest.raises(InputError, match=r"^n_rpm = 1e-09 — speed, when not 0 must be >= 1e-06 \[rpm\]"):
        load_distribution(B, 450.0, 325.0, n_rpm=1e-9)
    assert load_distribution(bearing("6210"), Fa=0.0, Fr=1e-6).Q_i.max() == pytest.approx(1e-6, rel=1e-6)


def test_inputs_that_do_not_broadcast_are_refused_by_name():
    with pytest.raises(InputError, match=r"^Fa, Fr, M, n_rpm = 'shapes \(2,\), \(3,\), \(\), \(\)' — must broadcast"):
        load_distribution(B, [450.0, 500.0], [100.0, 200.0, 300.0])


def test_load_distribution_takes_a_catalogue_name_and_refuses_other_objects():
    assert np.array_equal(load_distribution("7210", 450.0, 650.0).Q_i, load_distribution(B, 450.0, 650.0).Q_i)
    with pytest.raises(InputError, match="^brg = 7210 — must be a BallBearing"):
        load_distribution(7210, 450.0, 650.0)
