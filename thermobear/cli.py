"""Command-line interface: ``thermobear <verb> ...``.

Every bad input ends with a one-line message naming the field, the value and
what is expected, exit code 2 and no traceback (``--debug`` shows it).
Nothing is written before the inputs have been validated.
"""
from __future__ import annotations

import argparse
import json
import sys
import warnings

import numpy as np

from .errors import InputError, NoEquilibrium, SolverError, ThermobearError

EXIT_BAD_INPUT = 2
EXIT_SOLVER = 3


def _jsonable(x):
    if isinstance(x, dict):
        return {str(k): _jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_jsonable(v) for v in x]
    if isinstance(x, np.ndarray):
        return _jsonable(x.tolist())
    if isinstance(x, (np.floating, float)):
        return None if not np.isfinite(x) else float(x)
    if isinstance(x, (np.integer,)):
        return int(x)
    return x


def _overrides(items):
    out = {}
    for it in items or []:
        if "=" not in it:
            raise InputError("--set", it, "expected key=value, e.g. --set n_rpm=6500")
        k, v = it.split("=", 1)
        try:
            out[k.strip()] = float(v)
        except ValueError:
            out[k.strip()] = v.strip()
    return out


def _cmd_run(args):
    from .scene import load_scene
    from .solver import solve
    scene = load_scene(args.scene)
    if args.set:
        scene = scene.with_(**_overrides(args.set))
    res = solve(scene)
    if args.json:
        print(json.dumps(_jsonable(res.as_dict()), indent=2))
    else:
        print(res.summary())
    if args.plot:
        from .plots import plot_result
        for p in plot_result(res, args.plot):
            print(f"wrote {p}", file=sys.stderr)
    return 0


def _cmd_loads(args):
    from .loads import load_distribution
    from .scene import load_scene
    scene = load_scene(args.scene)
    ld = load_distribution(scene.bearing, Fa=scene.Fa, Fr=scene.Fr, M=scene.M)
    d = {"bearing": scene.bearing.name, "Fa_N": scene.Fa, "Fr_N": scene.Fr,
         "delta_a_um": ld.delta_a * 1e6, "delta_r_um": ld.delta_r * 1e6, "theta_mrad": ld.theta * 1e3,
         "Q_N": ld.Q, "alpha_deg": np.rad2deg(ld.alpha_i), "psi_deg": np.rad2deg(ld.psi),
         "residual": ld.residual, "iterations": ld.iterations}
    if args.json:
        print(json.dumps(_jsonable(d), indent=2))
    else:
        print(f"{scene.bearing.name}: Fa = {scene.Fa:g} N, Fr = {scene.Fr:g} N -> "
              f"delta_a = {d['delta_a_um']:.3f} um, delta_r = {d['delta_r_um']:.3f} um "
              f"(residual {ld.residual:.1e}, {ld.iterations} iterations)")
        print(f"{'ball':>4s} {'psi [deg]':>10s} {'Q [N]':>10s} {'alpha [deg]':>12s}")
        for j in range(scene.bearing.Z):
            print(f"{j:4d} {d['psi_deg'][j]:10.1f} {ld.Q[j]:10.2f} {d['alpha_deg'][j]:12.2f}")
    return 0


def _cmd_list(args):
    from .geometry import bearing_names
    from .lubricant import lubricant_names
    from .materials import material_names
    from ._data import data_dir, names_in
    what = {"bearings": bearing_names(), "lubricants": lubricant_names(), "materials": material_names(),
            "networks": names_in(data_dir("networks")),
            "examples": sorted(p.name for p in data_dir("examples").glob("*.toml"))}
    if args.json:
        print(json.dumps(what, indent=2))
    else:
        for k, v in what.items():
            print(f"{k}: {', '.join(v)}")
    return 0


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="thermobear", description="Power loss and temperatures of rolling bearings.")
    p.add_argument("--version", action="version", version=f"thermobear {_version()}")
    p.add_argument("--debug", action="store_true", help="show tracebacks")
    sub = p.add_subparsers(dest="verb", required=True)

    r = sub.add_parser("run", help="coupled steady state of a scene (temperatures, power, models used)")
    r.add_argument("scene", help="scene file (TOML), e.g. examples/seed004_oil_jet_7210.toml")
    r.add_argument("--json", action="store_true", help="print JSON")
    r.add_argument("--set", action="append", metavar="KEY=VALUE", help="override n_rpm, Fa, Fr, T_C, ...")
    r.add_argument("--plot", metavar="DIR", help="write PNG plots to DIR")
    r.set_defaults(func=_cmd_run)

    lo = sub.add_parser("loads", help="load distribution of a scene's bearing (per ball loads and angles)")
    lo.add_argument("scene")
    lo.add_argument("--json", action="store_true")
    lo.set_defaults(func=_cmd_loads)

    li = sub.add_parser("list", help="list bundled bearings, lubricants, materials, networks, examples")
    li.add_argument("--json", action="store_true")
    li.set_defaults(func=_cmd_list)
    return p


def _version():
    from . import __version__
    return __version__


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    debug = getattr(args, "debug", False)
    try:
        with warnings.catch_warnings():
            if not debug:
                warnings.simplefilter("default")
            return int(args.func(args) or 0)
    except (InputError, NoEquilibrium) as e:   # bad input, incl. loads the bearing cannot carry
        if debug:
            raise
        print(f"error: {e}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except SolverError as e:
        if debug:
            raise
        print(f"error: {type(e).__name__}: {e}", file=sys.stderr)
        return EXIT_SOLVER
    except ThermobearError as e:
        if debug:
            raise
        print(f"error: {e}", file=sys.stderr)
        return EXIT_BAD_INPUT


if __name__ == "__main__":
    sys.exit(main())
