"""The compiled kernels of the high-speed ball equilibrium (thermobear.loads._kernels) against the numpy
reference methods they transcribe: every state field, the Newton step, the per-ball start, and whole
solutions.  Skipped without numba (or with THERMOBEAR_NUMBA=0), where only the numpy path runs."""
import numpy as np
import pytest

from thermobear.loads import _kernels as hk
from thermobear.loads import highspeed as hs
from thermobear.contact.geometry import bearing


compiled = pytest.mark.skipif(not hk.ENABLED, reason="numba not installed (or THERMOBEAR_NUMBA=0)")


@pytest.fixture
def numpy_only(monkeypatch):
    """The numpy reference path (kernels off)."""
    monkeypatch.setattr(hs, "_kernels", lambda: None)


def _problem(brg, nb, rng, control):
    lam_i, lam_o, kin = hs.HS_CONTROLS[control]
    Fa = rng.uniform(200.0, 3000.0, nb)
    Fr = rng.uniform(0.0, 2000.0, nb)
    F_app = np.stack([Fa, Fr, rng.uniform(-50.0, 50.0, nb)], axis=1)
    n = rng.uniform(1000.0, 15000.0, nb)
    omega = n * np.pi / 30.0
    scale = np.max(np.abs(F_app), axis=1)
    free_g = np.ones((nb, 3))
    free_g[::3, 2] = 0.0                           # some cases with the tilt held
    pb = hs._Problem(brg, F_app, scale, omega, free_g, "nominal", lam_i, lam_o, kin)
    # iterates around the static solution: loaded balls, balls with an open contact, both open
    ls = hs.load_distribution(brg, Fa, Fr)
    g = np.zeros((nb, 3))
    g[:, 0] = ls.delta_a / pb.A
    g[:, 1] = ls.delta_r / pb.A * rng.uniform(0.5, 2.0, nb)
    g[:, 2] = rng.uniform(-0.01, 0.01, nb) * free_g[:, 2]
    x = hs._static_start(pb, g) * (1.0 + rng.uniform(-0.05, 0.05, (nb, brg.Z, 1)) * pb.A / pb.co0)
    return pb, x, g


def _compiled_state(pb, x, g):
    """The kernels' state and step."""
    nb, Z = x.shape[0], pb.Z
    blk, cblk = np.empty((nb, hk.N_BALL_FIELDS, Z)), np.empty((nb, 3))
    r_b, r_g = np.empty((nb, Z, 2)), np.empty((nb, 3))
    hk.state_kernel(x, g, pb.c[0], pb.omega, pb.scale, pb.F_app, pb.A, pb.A2_0, pb.ci0, pb.co0, pb.Ki0, pb.Ko0,
                    pb.k_eps, pb.gp, pb.dm, pb.D, pb.m, pb.J, float(pb.lam_i), float(pb.lam_o), pb.fi, pb.R,
                    pb.kin_control == "outer", blk, cblk, r_b, r_g)
    dx, dg = np.empty((nb, Z, 2)), np.empty((nb, 3))
    hk.step_kernel(blk, cblk, r_b, r_g, pb.c[0], pb.omega, pb.w_ref, pb.scale, pb.act, pb.A, pb.gp, pb.dm, pb.D,
                   pb.m, pb.J, float(pb.lam_i), float(pb.lam_o), pb.fi, pb.R, pb.kin_control == "outer", dx, dg)
    fields = {name: blk[:, k] for k, name in enumerate(hk.BALL_FIELDS)}
    fields.update(qs=cblk[:, 0:1], W=cblk[:, 1:2], Fc=cblk[:, 2:3], r_b=r_b, r_g=r_g)
    return fields, dx, dg


@compiled
@pytest.mark.parametrize("name", ["7210", "6210"])
@pytest.mark.parametrize("control", ["outer", "inner", "both"])
def test_state_and_step_equal_numpy(name, control, numpy_only):
    rng = np.random.default_rng(7)
    pb, x, g = _problem(bearing(name), 24, rng, control)
    with np.errstate(all="ignore"):                # random iterates: some blocks are singular
        ref = pb.state(x, g)                       # numpy (kernels off)
        dx0, dg0 = pb.newton_step(ref)
    # the batch covers loaded, one-contact-open and both-open balls
    assert (ref.dl_i < 0).any() and (ref.dl_i > 0).any() and (ref.dl_o > 0).any()
    got, dx, dg = _compiled_state(pb, x, g)
    assert set(got) == set(ref.__dict__)
    for k, v in ref.__dict__.items():
        scale = max(np.max(np.abs(v)), 1e-300)
        np.testing.assert_allclose(got[k], v, rtol=1e-12, atol=1e-12 * scale, err_msg=k)
    # A ball with an open contact hangs, in that direction, on the regularising stiffness (1e-12 of
    # K √A): its 2×2 block is ill-conditioned and its step (capped by the solver) up to 1e8 A; through
    # the Schur complement that rounding reaches its whole case.  So the steps are compared per case,
    # against the case's largest component: to 1e-9 where every component is below 10 A, to 1e-6 below
    # 1e6 A; not beyond (a step of 1e9 A or more is the rounding of a singular block in either version;
    # the solver caps any step at 0.1 A).
    # (a random iterate can be singular for both: the same cases give NaN; the solver rejects such a step)
    fin = np.isfinite(dx0).all(axis=(1, 2)) & np.isfinite(dg0).all(axis=1)
    assert np.array_equal(fin, np.isfinite(dx).all(axis=(1, 2)) & np.isfinite(dg).all(axis=1)) and fin.sum() >= 16
    dx, dx0, dg, dg0 = dx[fin], dx0[fin], dg[fin], dg0[fin]
    big = np.maximum(np.abs(dx0).max(axis=(1, 2)), np.abs(dg0).max(axis=1))
    err = np.maximum(np.abs(dx - dx0).max(axis=(1, 2)), np.abs(dg - dg0).max(axis=1))
    sane = big < 10.0
    assert sane.sum() >= 8 and (~sane).any()
    assert np.all(err[sane] <= 1e-9 * big[sane])
    assert np.all(err[big < 1e6] <= 1e-6 * big[big < 1e6])


@compiled
def test_place_equals_numpy(numpy_only):
    """The per-ball start: free, resting and wedged balls end where the numpy iteration puts them."""
    brg = bearing("7210")
    rng = np.random.default_rng(3)
    pb = hs._Problem(brg, np.array([[500.0, 300.0, 0.0]]), np.array([500.0]), np.array([800.0]),
                     np.ones((1, 3)), "nominal", *hs.HS_CONTROLS["outer"])
    n = 200
    a1, a2 = np.full(n, pb.A * np.sin(brg.alpha0)), np.full(n, pb.A2_0)
    th = rng.uniform(-0.3, 1.2, n)
    r = pb.co0 * (1.0 + rng.uniform(-3e-3, 3e-3, n))
    x1, x2 = r * np.sin(th), r * np.cos(th)
    f1, f2 = rng.uniform(-20.0, 20.0, n), rng.uniform(0.0, 60.0, n)
    mu = np.full(n, 1e-9 / pb.A * 500.0)
    tol = 1e-4 * np.hypot(f1, f2)
    args = (a1, a2, f1, f2, pb.Ki0, pb.Ko0, mu, tol, pb.ci0, pb.co0, hs._BALL_CAP * pb.A)
    X1, X2 = hs._place(x1, x2, *args)                          # numpy
    y1, y2 = x1.copy(), x2.copy()
    hk.place_kernel(y1, y2, a1, a2, f1, f2, np.full(n, pb.Ki0), np.full(n, pb.Ko0), mu, tol, pb.ci0, pb.co0,
                    hs._BALL_CAP * pb.A, hs._BALL_MAXIT, hs._BALL_HALVINGS)
    assert np.max(np.abs(X1 - x1)) > 1e-7                     # the balls did move
    np.testing.assert_allclose(y1, X1, rtol=0, atol=1e-12 * pb.A)
    np.testing.assert_allclose(y2, X2, rtol=0, atol=1e-12 * pb.A)


@compiled
@pytest.mark.parametrize("control", ["outer", "inner", "both"])
def test_solutions_equal_numpy(control, monkeypatch):
    """Whole high-speed solutions on a random batch: the same loads, angles, ball speeds and iterations."""
    brg = bearing("7210")
    rng = np.random.default_rng(11)
    Fr = rng.uniform(0.0, 3000.0, 60)
    Fa = 0.9 * Fr + rng.uniform(100.0, 2000.0, 60)
    n = rng.uniform(500.0, 8000.0, 60)
    ld1, ex1 = hs.load_distribution_high_speed_full(brg, Fa=Fa, Fr=Fr, n_rpm=n, control=control)[:2]
    assert hs._kernels() is not None
    monkeypatch.setattr(hs, "_kernels", lambda: None)
    ld0, ex0 = hs.load_distribution_high_speed_full(brg, Fa=Fa, Fr=Fr, n_rpm=n, control=control)[:2]
    assert ld1.iterations == ld0.iterations
    for a, b in ((ld1.Q_i, ld0.Q_i), (ld1.Q_o, ld0.Q_o), (ex1.omega_c, ex0.omega_c), (ex1.Mg, ex0.Mg)):
        np.testing.assert_allclose(a, b, rtol=1e-9, atol=1e-9 * np.max(np.abs(b)))
    np.testing.assert_allclose(ld1.alpha_i, ld0.alpha_i, rtol=0, atol=1e-10)


def test_switch_off_by_environment():
    """THERMOBEAR_NUMBA=0 gives the numpy path (a fresh process: the switch is read at import)."""
    import os
    import subprocess
    import sys
    out = subprocess.run([sys.executable, "-c", "from thermobear.loads import highspeed as h; print(h._kernels())"],
                         env={**os.environ, "THERMOBEAR_NUMBA": "0"}, capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "None"


@compiled
@pytest.mark.parametrize("name", ["7210", "6210", "iso-dgbb", "51107"])
@pytest.mark.parametrize("moment", [False, True])
def test_static_solutions_equal_numpy(name, moment, monkeypatch):
    """The low-speed Newton (thermobear.loads.static) compiled and in numpy: same loads, angles, iterations."""
    from thermobear.loads import static as loads
    brg = bearing(name)
    rng = np.random.default_rng(5)
    n = 200
    if brg.kind == "thrust":
        Fa, Fr = rng.uniform(200.0, 3000.0, n), np.zeros(n)
        M = rng.uniform(-0.5, 0.5, n) if moment else None
    else:
        Fr = rng.uniform(0.0, 3000.0, n)
        Fa = (rng.uniform(300.0, 3000.0, n) + 0.5 * Fr if brg.kind == "angular_contact"
              else rng.uniform(0.0, 3000.0, n))
        M = rng.uniform(-5.0, 5.0, n) if moment else None
    a = loads.load_distribution(brg, Fa=Fa, Fr=Fr, M=M)
    assert loads._kernels() is not None
    monkeypatch.setattr(loads, "_kernels", lambda: None)
    b = loads.load_distribution(brg, Fa=Fa, Fr=Fr, M=M)
    assert a.iterations == b.iterations and a.residual <= 1e-9
    np.testing.assert_allclose(a.Q_i, b.Q_i, rtol=1e-10, atol=1e-10 * np.max(b.Q_i))
    np.testing.assert_allclose(a.alpha_i, b.alpha_i, rtol=0, atol=1e-12)
    np.testing.assert_allclose(a.delta_a, b.delta_a, rtol=1e-10, atol=1e-18)


@compiled
def test_axial_angle_equals_numpy(monkeypatch):
    from thermobear.loads import static as loads
    for name in ("7210", "6210", "iso-dgbb"):
        brg = bearing(name)
        F = np.concatenate([[0.0, 1e-6], np.geomspace(1e-3, 1e6, 200)])
        a = loads.axial_contact_angle(brg, F)
        with monkeypatch.context() as m:
            m.setattr(loads, "_kernels", lambda: None)
            b = loads.axial_contact_angle(brg, F)
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-13)
        assert a[0] == brg.alpha0 and np.all(np.diff(a) > 0)


@compiled
def test_one_compiled_version_per_kernel():
    """numba compiles (and caches) one machine-code version per argument-type signature; a read-only
    or non-contiguous array is another type, and a new version costs seconds at first use.  Every entry
    point — scalar and batched loads, read-only inputs, a tilt-free case, a steady state, a sweep —
    must reach the kernels with one signature each."""
    import warnings

    import thermobear as tb
    from thermobear.loads import static as loads
    from thermobear.app.sweep import run_sweep
    brg = bearing("7210")
    ro = np.broadcast_to(np.array([500.0, 800.0]), (2,))                      # read-only inputs
    loads.load_distribution(brg, Fa=450.0, Fr=300.0)
    loads.load_distribution(brg, Fa=ro, Fr=ro * 0.5, M=np.array([1.0, -2.0]))
    loads.axial_contact_angle(brg, ro)
    hs.load_distribution_high_speed(brg, Fa=450.0, Fr=300.0, n_rpm=6000.0)
    hs.load_distribution_high_speed(brg, Fa=ro, Fr=ro * 0.5, n_rpm=np.array([3000.0, 9000.0]), control="inner")
    hs.load_distribution_high_speed(bearing("51107"), Fa=ro, n_rpm=4000.0)
    scene = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        tb.steady_state(scene.with_(n_rpm=5000.0))
        run_sweep(scene, {"n_rpm": [4000.0, 7000.0]}, processes=1)
    for name in ("state_kernel", "step_kernel", "place_kernel", "static_kernel", "axial_angle_kernel"):
        assert len(getattr(hk, name).signatures) == 1, (name, getattr(hk, name).signatures)


@pytest.mark.parametrize("kernels", [True, False])
@pytest.mark.parametrize("loads_", [dict(Fa=1e300, Fr=1e300), dict(Fa=1e-200, M=1e-200),
                                    dict(Fa=1e-30, Fr=1e-30, M=1e-30)])
def test_absurd_loads_fail_loudly_on_both_paths(kernels, loads_, monkeypatch):
    """Overflowing or vanishing loads: an answer or a named SolverError, never NaN loads, never a raw
    LinAlgError (review finding: a NaN residual read as converged; numpy's singular solve leaked)."""
    from thermobear.loads import static as loads
    from thermobear.errors import SolverError
    if not kernels:
        monkeypatch.setattr(loads, "_kernels", lambda: None)
    elif loads._kernels() is None:
        pytest.skip("numba not installed (or THERMOBEAR_NUMBA=0)")
    try:
        with np.errstate(all="ignore"):             # the numpy path overflows on the way (1e300 N)
            ld = loads.load_distribution(bearing("7210"), **loads_)
    except SolverError:
        return
    assert np.all(np.isfinite(ld.Q_i)) and ld.residual <= 1e-9


def test_uncacheable_location_compiles_in_memory(monkeypatch):
    """Where numba finds no writable cache location it refuses cache=True when decorating (review
    finding): the kernel is then compiled without the cache instead of failing the import."""
    calls = []

    def fake_njit(**kw):
        calls.append(kw)
        if kw.get("cache"):
            raise RuntimeError("cannot cache function 'f': no locator available")
        return lambda f: f

    monkeypatch.setattr(hk, "njit", fake_njit)

    def f(x):
        return x
    assert hk._jit(f)(3) == 3
    assert [c["cache"] for c in calls] == [True, False] and all(c["error_model"] == "numpy" for c in calls)
