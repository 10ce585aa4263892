"""The shared damped Newton and continuation driver of the load distributions (thermobear.loads.newton):
convergence on a problem with a known root, per-case independence in a batch, loud failures with the
residual and the iteration count, continuation where a direct solve fails."""
import numpy as np
import pytest

from thermobear.contact.geometry import bearing
from thermobear.errors import NoConvergence, NoEquilibrium
from thermobear.loads import load_distribution, load_distribution_high_speed, load_distribution_static
from thermobear.loads.newton import NewtonOptions, continuation, newton


class _State:
    def __init__(self, z, res):
        self.z, self.res = z, res
        self.norm = np.abs(res).max(axis=1)

    def take(self, idx):
        return _State(self.z[idx], self.res[idx])

    def put(self, idx, other):
        self.z[idx], self.res[idx], self.norm[idx] = other.z, other.res, other.norm


class _Cubic:
    """r(z) = z³ − a per case (root a^(1/3)); a ≤ 0 rows have a Jacobian that vanishes at the start z = 0
    and a NaN residual for a < 0 (a case that must fail without disturbing the others)."""

    def __init__(self, a):
        self.a = np.asarray(a, dtype=float)

    def rows(self, idx):
        return _Cubic(self.a[idx])

    def evaluate(self, z):
        res = z ** 3 - self.a[:, None]
        res = np.where(self.a[:, None] < 0, np.nan, res)
        return _State(z, res)

    def direction(self, st):
        with np.errstate(divide="ignore", invalid="ignore"):
            return -st.res / (3.0 * st.z ** 2)


def test_newton_converges_quadratically_to_the_root():
    r = newton(_Cubic([8.0, 27.0, 1e-3]), np.array([[1.0], [1.0], [1.0]]), NewtonOptions(tol=1e-14, maxiter=60))
    assert r.converged.all()
    np.testing.assert_allclose(r.z[:, 0], [2.0, 3.0, 0.1], rtol=1e-14)
    assert r.iterations.max() < 40


def test_a_failing_case_does_not_change_the_others():
    opt = NewtonOptions(tol=1e-14, maxiter=60)
    alone = newton(_Cubic([8.0, 27.0]), np.ones((2, 1)), opt)
    mixed = newton(_Cubic([8.0, -1.0, 27.0]), np.ones((3, 1)), opt)
    assert mixed.converged.tolist() == [True, False, True]
    assert np.isnan(mixed.norm[1])
    assert np.array_equal(mixed.z[[0, 2]], alone.z) and np.array_equal(mixed.iterations[[0, 2]], alone.iterations)


def test_continuation_follows_the_path_and_stops_a_case_at_its_first_failure():
    opt = NewtonOptions(tol=1e-14, maxiter=60)

    def solve(idx, z, p, stage):
        return newton(_Cubic(p), z, opt)

    path = np.array([[1.0, 8.0, 64.0], [1.0, -1.0, 8.0], [1.0, 27.0, np.nan]])
    c = continuation(solve, np.ones((3, 1)), path)
    assert c.ok.tolist() == [True, False, True] and c.reached.tolist() == [2, 0, 1]
    np.testing.assert_allclose(c.z[:, 0], [4.0, 1.0, 3.0], rtol=1e-14)


@pytest.mark.parametrize("Fr", [0.5, 5.0])
def test_light_load_needs_continuation_and_converges(Fr):
    # a few newtons with Fa/Fr = 0.05 on a 7210: Newton from the closed-form start fails, continuation in
    # the load magnitude converges (one ball carries everything: tan α = Fa/Fr)
    b = bearing("7210")
    with pytest.raises(NoConvergence) as e:
        load_distribution_static(b, Fa=0.05 * Fr, Fr=Fr, continuation=False)
    assert e.value.iterations > 0 and e.value.residual > 1e-9
    ld = load_distribution_static(b, Fa=0.05 * Fr, Fr=Fr)
    assert ld.residual <= 1e-9 and ld.iterations > e.value.iterations
    k = ld.Q > 0
    assert np.tan(ld.alpha_i[k][0]) == pytest.approx(0.05, rel=1e-8)


def test_failures_carry_the_residual_and_the_iterations():
    with pytest.raises(NoConvergence) as e:
        load_distribution_static(bearing("7210"), Fa=450.0, Fr=325.0, maxiter=2, continuation=False)
    assert e.value.iterations == 2 and e.value.residual > 1e-12 and e.value.last is not None
    with pytest.raises(NoConvergence) as e:         # with continuation: its iterations count too
        load_distribution_static(bearing("7210"), Fa=450.0, Fr=325.0, maxiter=2)
    assert e.value.iterations > 2
    with pytest.raises(NoEquilibrium) as e:
        load_distribution_high_speed(bearing("7210"), Fa=10.0, n_rpm=20000.0, control="inner")
    assert e.value.iterations > 0


def test_batch_with_a_case_that_needs_continuation_equals_single_solves():
    b = bearing("7210")
    Fa, Fr = np.array([0.025, 450.0, 1.5]), np.array([0.5, 325.0, 5.0])
    batch = load_distribution(b, Fa, Fr)
    for k in range(3):
        one = load_distribution(b, Fa[k], Fr[k])
        np.testing.assert_allclose(batch.Q[k], one.Q, rtol=1e-12, atol=1e-15)


def test_high_speed_batch_cases_are_independent():
    # the same case alone and inside a batch with very different ones (no load at speed, heavy radial
    # load at crawl speed): the same Newton path, the same numbers
    b = bearing("7210")
    alone = load_distribution_high_speed(b, 450.0, 750.0, n_rpm=4800.0)
    batch = load_distribution_high_speed(b, np.array([450.0, 450.0, 450.0]), np.array([1500.0, 750.0, 0.0]),
                                         n_rpm=np.array([50.0, 4800.0, 20000.0]))
    # (to the solution's own accuracy: residual 1e-10 of the load scale; the path is the same, only sums over
    # the batch may round differently)
    np.testing.assert_allclose(batch.Q_i[1], alone.Q_i, rtol=1e-10, atol=1e-10 * 450.0)
    np.testing.assert_allclose(batch.alpha_o[1], alone.alpha_o, rtol=1e-10, atol=1e-12)


def test_start_from_a_nearby_solution():
    b = bearing("6210")
    ld = load_distribution_static(b, Fa=300.0, Fr=1500.0)
    near = load_distribution_static(b, Fa=310.0, Fr=1500.0)
    again = load_distribution_static(b, Fa=300.0, Fr=1500.0, start=near)
    assert again.iterations < ld.iterations
    np.testing.assert_allclose(again.Q, ld.Q, rtol=1e-10, atol=1e-9)
    with pytest.raises(Exception):
        load_distribution_static(b, Fa=300.0, Fr=1500.0, start=[1.0, 2.0])
