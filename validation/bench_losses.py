"""Speed of the local loss model (thermobear.losses): evaluate_losses and bearing_losses.

Cases, on the seed-004 scene (7210 ACBB, 15 balls, oil jet; contacts of
``thermobear.coupled.scene_contacts``):

* ``point``        evaluate_losses, one operating point, full LossResult;
* ``2 states``     the same point at two temperature states (x and x + h of the coupled Newton);
* ``2 x 1000``     two temperature states of 1000 operating points (2 × 1000 × 15 balls × 2 contacts);
* ``batch 1000``   bearing_losses over 1000 operating points (loads, Hertz, kinematics and losses), per point;
* ``prepare 1000`` prepare_contacts over 1000 operating points, per point.

Every case runs the scene's model choices (``choose_models``), including the film physics of
issue 17 (Eyring traction, inlet shear heating, replenishment) where the tree has them.

Run ``python validation/bench_losses.py`` for this tree's numbers, or with ``--against REV`` to time
a git revision as well, in the same run (exported with ``git archive`` to a temporary directory;
the two trees are timed in alternating fresh interpreters, best of ``--rounds``), and print the
ratios (reference time / this tree's time: > 1 is faster).  A revision from before the batched interface (where
temperatures could not carry leading axes) is timed through its own equivalents: the repeated
contacts and the fused 2-state sums (``_repeat_contacts``, ``_contact_powers``), and contacts
prepared for (2, 1000) points.  Nothing is asserted (timings belong here, not in tests/).
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

TARGETS_US = {"point": 150.0, "2 states": 200.0, "2 x 1000": 15000.0, "batch 1000": 50.0}


def _best(fn, repeat=7, min_time=0.2):
    """Best time of one call [s] over ``repeat`` runs of enough calls to last ``min_time`` s."""
    fn()
    n = 1
    while True:
        t0 = time.perf_counter()
        for _ in range(n):
            fn()
        dt = time.perf_counter() - t0
        if dt >= min_time / repeat or n >= 1 << 16:
            break
        n *= 2
    best = dt / n
    for _ in range(repeat - 1):
        t0 = time.perf_counter()
        for _ in range(n):
            fn()
        best = min(best, (time.perf_counter() - t0) / n)
    return best


def measure() -> dict:
    """Timings of this interpreter's ``thermobear`` [µs per call, or per point for the batches]."""
    import thermobear as tb
    try:                                                  # the coupled package before / after its pipeline
        from thermobear.coupled.solver import choose_models, scene_contacts
    except ImportError:
        from thermobear.coupled import scene_contacts
        from thermobear.models import choose_models
    from thermobear.losses import local
    from thermobear.losses.local import bearing_losses, evaluate_losses, prepare_contacts
    warnings.simplefilter("ignore")
    s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml"))
    models = choose_models(s)
    cs = scene_contacts(s, models)
    oil = s.lubricant
    kw = dict(supply=s.supply, oil_flow_m3_s=s.oil_flow, Rq_ball=s.Rq_ball, Rq_ring=s.Rq_ring,
              mu_boundary=s.mu_boundary, mu_full_film=s.mu_full_film, rolling_model=models["rolling"][0])
    try:                                                  # the film choices (traction, inlet heating, replenishment)
        from thermobear.models import film_options
        kw.update(film_options(models))
    except ImportError:                                   # a tree from before issue 17: constant μ, isothermal, flooded
        pass
    old = hasattr(local, "_repeat_contacts")          # before the batched interface
    out = {}
    out["point"] = _best(lambda: evaluate_losses(cs, oil, 45.0, T_inner_C=60.0, T_outer_C=55.0, T_oil_C=45.0, **kw))
    Ti2, To2, Tm2 = np.array([60.0, 60.05]), np.array([55.0, 55.05]), np.array([45.0, 45.05])
    if old:
        cs2 = local._repeat_contacts(cs, 2)
        out["2 states"] = _best(lambda: evaluate_losses(cs2, oil, Tm2, T_inner_C=Ti2, T_outer_C=To2, T_oil_C=Tm2, **kw))
        sums_kw = {k: v for k, v in kw.items() if k != "rolling_model"}
        out["2 states, fused sums"] = _best(lambda: local._contact_powers(cs2, oil, Ti2, To2, Tm2, **sums_kw))
    else:
        out["2 states"] = _best(lambda: evaluate_losses(cs, oil, Tm2, T_inner_C=Ti2, T_outer_C=To2, T_oil_C=Tm2, **kw))
    rng = np.random.default_rng(4)
    B = 1000
    Fa, Fr = rng.uniform(300.0, 700.0, B), rng.uniform(100.0, 900.0, B)
    n = rng.uniform(1000.0, 9000.0, B)
    Ti = rng.uniform(45.0, 75.0, B)
    To, Tm = Ti - 4.0, Ti - 12.0
    Ti2, To2, Tm2 = (np.stack((v, v + 0.05)) for v in (Ti, To, Tm))
    pk = dict(rotating=s.rotating, hertz_method=models["hertz"][0], control=models["kinematics"][0])
    if old:
        csB = prepare_contacts(s.bearing, np.broadcast_to(Fa, (2, B)), np.broadcast_to(Fr, (2, B)),
                               np.broadcast_to(n, (2, B)), **pk)
        sums_kw = {k: v for k, v in kw.items() if k != "rolling_model"}
        out["2 x 1000, fused sums"] = _best(lambda: local._contact_powers(csB, oil, Ti2, To2, Tm2, **sums_kw), repeat=5)
    else:
        csB = prepare_contacts(s.bearing, Fa, Fr, n, **pk)
    out["2 x 1000"] = _best(lambda: evaluate_losses(csB, oil, Tm2, T_inner_C=Ti2, T_outer_C=To2, T_oil_C=Tm2, **kw),
                            repeat=5)
    out["batch 1000"] = _best(lambda: bearing_losses(s.bearing, oil, Fa, Fr, n, Ti, T_oil_C=Tm, **pk, **kw),
                              repeat=3) / B
    out["prepare 1000"] = _best(lambda: prepare_contacts(s.bearing, Fa, Fr, n, **pk), repeat=3) / B
    return {k: v * 1e6 for k, v in out.items()}


def _measure_in(tree: str | None) -> dict:
    """:func:`measure` in a fresh interpreter, on the source tree ``tree`` (None: this one)."""
    env = dict(os.environ, PYTHONPATH=tree) if tree else dict(os.environ)
    res = subprocess.run([sys.executable, str(Path(__file__).resolve()), "--json"], cwd=tree or None, env=env,
                         check=True, capture_output=True, text=True)
    return json.loads(res.stdout.strip().splitlines()[-1])


def measure_against(rev: str, repo: Path, rounds: int = 3) -> tuple[dict, dict]:
    """Timings of this tree and of git revision ``rev`` of ``repo`` (exported to a temporary
    directory), in alternating fresh interpreters, ``rounds`` times; the best of each case."""
    with tempfile.TemporaryDirectory(prefix="tb_bench_") as tmp:
        archive = subprocess.run(["git", "-C", str(repo), "archive", rev], check=True, capture_output=True).stdout
        subprocess.run(["tar", "-x", "-C", tmp], input=archive, check=True)
        now, ref = {}, {}
        for _ in range(rounds):
            for tree, best in ((None, now), (tmp, ref)):
                for k, v in _measure_in(tree).items():
                    best[k] = min(v, best.get(k, v))
    return now, ref


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--against", help="also time this git revision (e.g. main) and print the ratios")
    ap.add_argument("--json", action="store_true", help="print the timings as JSON only")
    ap.add_argument("--rounds", type=int, default=3, help="alternating rounds with --against (best of each)")
    a = ap.parse_args(argv)
    if a.json:
        print(json.dumps(measure()))
        return
    if a.against:
        now, ref = measure_against(a.against, Path(__file__).resolve().parent.parent, a.rounds)
    else:
        now, ref = measure(), {}
    print("local loss model, seed-004 scene (7210, 15 balls); µs per call (batches: µs per point)"
          + (f"; reference: {a.against}" if a.against else ""))
    print(f"{'case':24s} {'this tree':>12s} {'target':>9s}" + (f" {a.against:>12s} {'ratio':>7s}" if ref else ""))
    for k in dict.fromkeys(list(now) + list(ref)):
        v, r = now.get(k), ref.get(k)
        line = f"{k:24s} {v if v is not None else float('nan'):12.1f} {TARGETS_US.get(k, float('nan')):9.0f}"
        if ref:
            line += f" {r if r is not None else float('nan'):12.1f}"
            line += f" {r / v:7.2f}" if (v and r) else f" {'':7s}"
        print(line)


if __name__ == "__main__":
    main()
