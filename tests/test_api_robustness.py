"""The Python API under random input (property-based, hypothesis): ``tb.hertz``, ``tb.load_distribution``,
``tb.bearing_losses`` and ``tb.steady_state`` over random arrays — NaN, ±inf, negative, zero, subnormal and
huge values, shapes that do not broadcast — and random bearings of the catalogue.

Every outcome is one of: an :class:`~thermobear.errors.InputError` naming the argument at fault; a named
:class:`~thermobear.errors.SolverError` (no equilibrium, no convergence, thermal runaway) for the solvers;
or a finite, physical answer (no NaN/inf, non-negative loads and powers, contacts inside the groove).
Never a bare ``ValueError`` / ``TypeError`` / ``LinAlgError`` / ``ZeroDivisionError``, and never an answer
computed through a floating-point RuntimeWarning (overflow, invalid value, division by zero).

A bounded number of examples runs in CI (``THERMOBEAR_FUZZ`` unset, derandomised); ``THERMOBEAR_FUZZ=long``
runs many more with fresh random seeds.
"""
import math
import os
import warnings

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import thermobear as tb
from thermobear.errors import InputError, SolverError

LONG = os.environ.get("THERMOBEAR_FUZZ") == "long"


def fuzz(ci: int, long: int):
    return settings(max_examples=long if LONG else ci, deadline=None, derandomize=not LONG,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])


SPECIAL = [math.nan, math.inf, -math.inf, -1.0, 0.0, -0.0, 5e-324, 1e-300, 1e-30, 1e30, 1e300, 1.7e308]
SHAPES = [(), (), (), (1,), (3,), (2, 3), (4,), (2, 1)]


def values(lo: float, hi: float, special: bool = True):
    """Numbers of the physical range [lo, hi]; with ``special``, often a special value or any float."""
    if not special:
        return st.floats(lo, hi)
    return st.one_of(st.floats(lo, hi), st.sampled_from(SPECIAL), st.floats(allow_nan=True, allow_infinity=True))


@st.composite
def arrays(draw, lo: float, hi: float):
    """A scalar (float or int) or an array of a random shape; one argument in four carries bad values."""
    shape = draw(st.sampled_from(SHAPES))
    elements = values(lo, hi, special=draw(st.integers(0, 3)) == 0)
    if shape == ():
        v = draw(elements)
        return int(v) if draw(st.booleans()) and math.isfinite(v) and abs(v) < 1e15 else v
    n = int(np.prod(shape))
    return np.array(draw(st.lists(elements, min_size=n, max_size=n)), dtype=float).reshape(shape)


def call(f, *args, **kw):
    """f(*args, **kw): (answer, None) or (None, the InputError / SolverError it raised).  An answer must not
    have passed through a floating-point warning (overflow, invalid value, division by zero) on its way."""
    with warnings.catch_warnings(record=True) as rec, np.errstate(over="warn", divide="warn", invalid="warn"):
        warnings.simplefilter("always", RuntimeWarning)
        warnings.simplefilter("ignore", tb.OutsideValidity)
        try:
            out = f(*args, **kw)
        except (InputError, SolverError) as exc:
            return None, exc
    fp = [str(w.message) for w in rec if issubclass(w.category, RuntimeWarning)]
    assert not fp, f"an answer computed through floating-point warnings: {fp}"
    return out, None


def names_an_argument(exc: InputError, names) -> bool:
    return any(n in exc.field for n in names)


def finite(*xs) -> bool:
    return all(np.all(np.isfinite(np.asarray(x, dtype=float))) for x in xs)


def groove_angle(brg, Q, alpha, a, f):
    """How far the edge of a loaded contact's ellipse lies from the groove bottom [rad] (<= π/2: inside)."""
    bottom = math.pi / 2 if brg.kind == "thrust" else 0.0
    return np.where(np.asarray(Q) > 0, np.abs(np.asarray(alpha) - bottom) + np.asarray(a) / (f * brg.D), 0.0)


BEARINGS = st.sampled_from(tb.bearing_names())


# --------------------------------------------------------------------------- hertz
@fuzz(200, 3000)
@given(Q=arrays(0.0, 1e5), Rx=arrays(1e-4, 1e-1), Ry=arrays(1e-4, 1.0), E=arrays(1e9, 5e11),
       method=st.sampled_from(tb.contact.hertz.METHODS))
def test_hertz_refuses_by_name_or_gives_a_finite_contact_inside_its_radii(Q, Rx, Ry, E, method):
    c, exc = call(tb.hertz, Q, Rx, Ry, E, method=method)
    if exc is not None:
        assert isinstance(exc, InputError) and names_an_argument(exc, ("Q", "Rx", "Ry", "E_prime")), repr(exc)
        return
    assert finite(c.a, c.b, c.delta, c.p_max, c.kappa, c.K), c
    assert np.all(c.a >= 0) and np.all(c.b >= 0) and np.all(c.delta >= 0) and np.all(c.p_max >= 0)
    Rx_b, Ry_b = np.broadcast_arrays(np.asarray(Rx, float), np.asarray(Ry, float))
    assert np.all(c.a <= Ry_b * (1 + 1e-12)) and np.all(c.b <= Rx_b * (1 + 1e-12))     # hertz_size limit


# --------------------------------------------------------------------------- load distribution
@fuzz(120, 2000)
@given(name=BEARINGS, Fa=arrays(0.0, 2e4), Fr=arrays(0.0, 2e4), M=st.one_of(st.none(), arrays(-200.0, 200.0)),
       n=st.one_of(st.just(0.0), arrays(0.0, 3e4)))
def test_load_distribution_refuses_by_name_or_balances_the_loads_inside_the_grooves(name, Fa, Fr, M, n):
    brg = tb.bearing(name)
    ld, exc = call(tb.load_distribution, brg, Fa, Fr, M, n)
    if exc is not None:
        assert not isinstance(exc, InputError) or names_an_argument(exc, ("Fa", "Fr", "M", "n_rpm")), repr(exc)
        return
    assert finite(ld.Q_i, ld.Q_o, ld.alpha_i, ld.alpha_o, ld.delta_a, ld.delta_r, ld.theta), ld
    assert np.all(ld.Q_i >= 0) and np.all(ld.Q_o >= 0) and ld.residual <= 1e-6
    for Q, al, Rx, Ry, f in ((ld.Q_i, ld.alpha_i, brg.Rx_i, brg.Ry_i, brg.fi), (ld.Q_o, ld.alpha_o, brg.Rx_o, brg.Ry_o, brg.fo)):
        a = tb.hertz(Q, Rx(al), Ry, brg.E_prime).a
        assert np.all(groove_angle(brg, Q, al, a, f) <= math.pi / 2 + 1e-9), (name, np.rad2deg(al).max())


# --------------------------------------------------------------------------- bearing losses
@fuzz(80, 1000)
@given(name=BEARINGS, oil=st.sampled_from(tb.lubricant_names()), Fa=arrays(0.0, 5e3), Fr=arrays(0.0, 5e3),
       n=arrays(0.0, 6e3), T=arrays(-20.0, 140.0),
       supply=st.sampled_from(["oil_jet", "grease", "oil_bath", "oil_air", "dry_film"]))
def test_bearing_losses_refuse_by_name_or_give_finite_non_negative_powers(name, oil, Fa, Fr, n, T, supply):
    brg = tb.bearing(name)
    r, exc = call(tb.bearing_losses, brg, tb.lubricant(oil), Fa, Fr, n, T, supply=supply, oil_flow_m3_s=1e-6)
    if exc is not None:
        assert not isinstance(exc, InputError) or names_an_argument(exc, ("Fa", "Fr", "n_rpm", "T_C")), repr(exc)
        return
    assert finite(r.P_W, r.torque_Nm, *r.breakdown_W.values(), *r.heat_W.values()), r.breakdown_W
    assert np.all(np.asarray(r.P_W) >= 0) and all(np.all(np.asarray(v) >= 0) for v in r.breakdown_W.values())
    assert np.allclose(sum(np.asarray(v) for v in r.heat_W.values()), r.P_W, rtol=1e-9, atol=1e-12)


# --------------------------------------------------------------------------- coupled steady state
SCENES = {n: tb.load_scene(tb.example_path(n)) for n in ("seed004_oil_jet_7210.toml",
                                                         "seed002_grease_thrust_51107.toml")}


def scalars(lo, hi):
    """A number of [lo, hi], one in eight a special value."""
    return st.integers(0, 7).flatmap(lambda k: st.sampled_from(SPECIAL) if k == 0 else st.floats(lo, hi))


@fuzz(40, 400)
@given(scene=st.sampled_from(sorted(SCENES)), Fa=scalars(0.0, 1e4), Fr=scalars(0.0, 3e3), n=scalars(0.0, 2e4),
       T_amb=scalars(-20.0, 60.0), name=st.one_of(st.none(), BEARINGS))
def test_steady_state_refuses_by_name_or_gives_finite_temperatures(scene, Fa, Fr, n, T_amb, name):
    sc = SCENES[scene]
    kw = dict(Fa=Fa, Fr=Fr, n_rpm=n, T_ambient_C=T_amb, **({} if name is None else {"bearing": name}))
    s, exc = call(sc.with_, **kw)
    if exc is None:
        s, exc = call(tb.steady_state, s)
    if exc is not None:
        assert not isinstance(exc, InputError) or names_an_argument(
            exc, ("Fa", "Fr", "n_rpm", "T_ambient_C", "bearing", "operation", "network")), repr(exc)
        return
    assert finite(list(s.T_C.values()), s.P_W, s.energy_balance_W) and s.P_W >= 0
    assert abs(s.energy_balance_W) <= 1e-6 * max(s.P_W, 1.0)
