"""Command-line interface: ``thermobear <verb> ...``.

``--uncertainty N`` (run, transient, compare): bands over N samples of the estimated inputs
(:mod:`thermobear.coupled.uncertainty`), with ``--seed``, ``--design``, ``--groups``, ``--sensitivity``.

Verbs: ``run`` (steady state), ``transient`` (heat-up, optional speed/load schedule), ``sweep``
(grid over speed, load, temperature, lubricant), ``compare`` (a rig log against a simulation),
``calibrate`` (fit uncertain parameters to a rig log), ``spin-down`` (seed 001 coast-down rig),
``loads``, ``init`` (a commented scene for a catalogue bearing) and ``list``.  ``--json`` prints JSON, ``--plot DIR`` writes PNGs.

Exit codes:

==== =====================================================================================
0    done
2    bad input: one line ``error: <field> = <value> — <what is accepted>``, nothing written
     (also loads the bearing cannot carry)
3    a solver could not deliver (thermal runaway, no convergence), or a sweep had failed
     points (their rows say why; ``--allow-failures`` exits 0)
130  interrupted (Ctrl-C, SIGTERM): what was finished is kept, one line says where
==== =====================================================================================

No traceback (``--debug`` shows it); warnings (outside a model's validated range, extrapolated
correlations) are one line each on stderr.  All inputs and output paths are checked before
anything is computed.
"""
from __future__ import annotations

import argparse
import os
import re
import signal
import sys
import warnings

from thermobear.app.scaffold import HOUSINGS, METHODS
from thermobear.app.speed import cmd_speed
from thermobear.app.verbs import (EXIT_INTERRUPTED, cmd_calibrate, cmd_compare, cmd_init, cmd_list, cmd_loads, cmd_run,
                                  cmd_spin_down, cmd_sweep, cmd_transient)
from thermobear import __version__
from thermobear.app.output import jsonable, print_json
from thermobear.loads.pair import PAIR_ARRANGEMENTS
from thermobear.errors import InputError, NoEquilibrium, OutsideValidity, SolverError, ThermobearError

__all__ = ["main", "build_parser", "solver_error_data", "EXIT_BAD_INPUT", "EXIT_SOLVER", "EXIT_INTERRUPTED"]

EXIT_BAD_INPUT = 2
EXIT_SOLVER = 3

_NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
#: a negative number, list (-10,0,10) or range (-10:100:12): argparse took it for an option
_NEGATIVE = re.compile(rf"-(?:\d|\.\d)[^\s]*")
_NUMBERS = re.compile(rf"{_NUM}(?:\s*[,:]\s*{_NUM})*")


def valued_options(parser: argparse.ArgumentParser) -> frozenset:
    """The option strings of ``parser`` and its sub-commands (their argument groups too) that take one value."""
    out = set()
    for a in parser._actions:                       # (argparse's list of a parser's actions, groups' included)
        if a.option_strings and a.nargs is None:
            out.update(a.option_strings)
        if isinstance(getattr(a, "choices", None), dict):                       # the sub-commands
            for sub in a.choices.values():
                if isinstance(sub, argparse.ArgumentParser):
                    out |= valued_options(sub)
    return frozenset(out)


def attach_negative_values(argv: list, valued) -> list:
    """``--T-C -10:100:12`` as ``--T-C=-10:100:12``: a value after an option that takes one (``valued``,
    :func:`valued_options`), starting with '-' and reading as a number, a list a,b,c or a range start:stop:count,
    attached to its option (argparse took it for an option and refused "expected one argument"); everything after
    ``--`` is left as it is.

    >>> attach_negative_values(["sweep", "s.toml", "--T-C", "-10:100:12", "--Fa", "-x", "--quiet"], {"--T-C", "--Fa"})
    ['sweep', 's.toml', '--T-C=-10:100:12', '--Fa', '-x', '--quiet']
    """
    out, args, i = [], list(argv), 0
    while i < len(args):
        tok = args[i]
        if tok == "--":
            return out + args[i:]
        if (tok in valued and i + 1 < len(args) and _NEGATIVE.match(args[i + 1])
                and _NUMBERS.fullmatch(args[i + 1].strip())):
            out.append(f"{tok}={args[i + 1]}")
            i += 2
            continue
        out.append(tok)
        i += 1
    return out


class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors (exit 2)."""

    def error(self, message):
        print(f"error: {self.prog}: {' '.join(message.split())} (see {self.prog} --help)", file=sys.stderr)
        sys.exit(EXIT_BAD_INPUT)


def _common(sp, plot=True, sets=True):
    sp.add_argument("--json", action="store_true", help="print JSON")
    if plot:
        sp.add_argument("--plot", metavar="DIR", help="write PNG plots to DIR (needs the 'plot' extra)")
    if sets:
        sp.add_argument("--set", action="append", metavar="KEY=VALUE",
                        help="override n_rpm, Fa, Fr, T_C, T_ambient_C, lubricant, ...; models.<key>=<value> "
                             "forces a model; fixed_C.<node>=T imposes a measured node temperature [°C]; "
                             "bearing.<key>=<value> sets a key of the [bearing] table (clearance_group=C3 too)")
    sp.add_argument("--debug", action="store_true", default=argparse.SUPPRESS, help="show tracebacks")


def _uncertainty_args(sp):
    g = sp.add_argument_group("uncertainty (bands over the estimated inputs of the scene's data)")
    g.add_argument("--uncertainty", type=int, default=None, metavar="N",
                   help="sample the estimated inputs N times (their ranges: uncertainty.<key> in the data files) "
                        "and report the 5/50/95 %% bands and the inputs ranked")
    g.add_argument("--seed", type=int, default=0, help="seed of the sample design (default 0: runs repeat)")
    g.add_argument("--design", choices=("lhs", "sobol"), default="lhs",
                   help="Latin hypercube (default) or scrambled Sobol' sequence")
    g.add_argument("--groups", type=int, default=None, metavar="G",
                   help="bearing-geometry (and built-network estimate) families (default min(N, max(8, 2 (d + 1)))"
                        " for d family-level inputs): they are drawn at G levels")
    g.add_argument("--sensitivity", choices=("src", "sobol"), default="src",
                   help="ranking: standardised regression coefficients (default) or first-order Sobol indices "
                        "(RBD-FAST, needs the 'sensitivity' extra: SALib)")


def _transient_parser(sub):
    tr = sub.add_parser("transient", help="heat-up of a scene: every node and the loss breakdown vs time")
    tr.add_argument("scene")
    tr.add_argument("--t-end", type=float, required=True, metavar="S", help="end time [s]")
    tr.add_argument("--schedule", metavar="FILE.toml", help="[[step]] tables: t_s and n_rpm, Fa_N, Fr_N, ...")
    tr.add_argument("--csv", metavar="OUT", help="write the time series as CSV")
    tr.add_argument("--points", type=int, default=201, help="number of output times (default 201)")
    tr.add_argument("--T0-C", dest="T0_C", type=float, default=None, help="start temperature [°C] (default ambient)")
    _common(tr)
    tr.add_argument("--processes", type=int, default=None,
                    help="local worker processes for --uncertainty's heat-ups (default 1)")
    _uncertainty_args(tr)
    tr.set_defaults(func=cmd_transient)


def _rig_args(sp):
    sp.add_argument("scene")
    sp.add_argument("log", help="rig log CSV (t_s / n_rpm, T_<name>_C, torque_Nm, ...)")
    sp.add_argument("--map", action="append", metavar="CHANNEL=NODE",
                    help="map a log channel to a network node, or 'impose:<node>' (the logged temperature imposed "
                    "on the node; in a transient log a time-varying boundary, linear between rows), 'input' (the "
                    "operating temperature of a steady row) or 'ignore'")
    sp.add_argument("--T0-C", dest="T0_C", type=float, default=None,
                    help="start temperature of a transient log [°C] (default: the logged ambient of an imposed "
                    "'ambient' node, else the scene's ambient)")


def build_parser() -> argparse.ArgumentParser:
    p = _Parser(prog="thermobear", description="Power loss and temperatures of rolling bearings.")
    p.add_argument("--version", action="version", version=f"thermobear {__version__}")
    p.add_argument("--debug", action="store_true", help="show tracebacks")
    sub = p.add_subparsers(dest="verb", required=True, parser_class=_Parser)

    r = sub.add_parser("run", help="coupled steady state of a scene (temperatures, power, models used)")
    r.add_argument("scene", help="scene file (TOML), e.g. examples/seed004_oil_jet_7210.toml")
    _common(r)
    _uncertainty_args(r)
    r.set_defaults(func=cmd_run)

    _transient_parser(sub)

    sw = sub.add_parser("sweep", help="grid over speed, load, temperature, lubricant and a pair's preload (rows written as "
                        "they finish)",
                        epilog="A:B:N is N values from A to B (inclusive), a,b a list. A range or list may start "
                        "with a negative number as it is: --T-C -10:100:12, --T-C -20,0,20 (--T-C=-10:100:12 too).")
    sw.add_argument("scene")
    sw.add_argument("--n-rpm", dest="n_rpm", metavar="A:B:N|a,b", help="speeds [rpm]")
    sw.add_argument("--Fa", metavar="A:B:N|a,b", help="axial loads [N]")
    sw.add_argument("--Fr", metavar="A:B:N|a,b", help="radial loads [N]")
    sw.add_argument("--T-C", dest="T_C", metavar="A:B:N|a,b", help="prescribed temperatures [°C], e.g. -10:100:12")
    sw.add_argument("--lubricant", metavar="NAME,...", help="lubricant names")
    sw.add_argument("--preload-N", dest="preload_N", metavar="A:B:N|a,b",
                    help="cold mounted preloads of a preloaded pair [N] (a pair scene: [bearing] arrangement)")
    sw.add_argument("--csv", metavar="OUT", help="write the rows as CSV (index column first), each row as it finishes")
    sw.add_argument("--jsonl", metavar="OUT", help="write the rows as JSON lines, each row as it finishes")
    sw.add_argument("--scheduler", metavar="tcp://host:port", help="dask scheduler address")
    sw.add_argument("--processes", type=int, default=None, help="local worker processes (default 1)")
    sw.add_argument("--allow-failures", action="store_true", help="exit 0 even when some points failed")
    sw.add_argument("--quiet", action="store_true", help="no progress")
    _common(sw)
    sw.set_defaults(func=cmd_sweep)

    c = sub.add_parser("compare", help="a rig log against a simulation: RMSE, max error, steady-state error, t90")
    _rig_args(c)
    c.add_argument("--csv", metavar="OUT", help="write measured and simulated values as CSV")
    _common(c)
    _uncertainty_args(c)
    c.set_defaults(func=cmd_compare)

    ca = sub.add_parser("calibrate", help="fit uncertain parameters to a rig log (least squares, with uncertainty)")
    _rig_args(ca)
    ca.add_argument("--param", action="append", required=True, metavar="NAME[=START]",
                    help="parameter to fit: a machine's builder estimate (builder.R_mount_m2K_W, builder.emissivity, "
                    "...), a network value (<element or node>.<param>), a [thermal.parameters] name, T_ambient_C, "
                    "mu_boundary, skf_R1, ... (--param x lists the scene's)")
    ca.add_argument("--max-nfev", type=int, default=60, help="budget of model evaluations (default 60)")
    _common(ca)
    ca.set_defaults(func=cmd_calibrate)

    sd = sub.add_parser("spin-down", help="seed 001 coast-down rig: integrate J dω/dt = -T(ω), fit K*, n")
    sd.add_argument("scene")
    sd.add_argument("--J", type=float, default=None, metavar="KG_M2", help="rotating inertia [kg m²] "
                    "(default: [rig] J_kg_m2 of the scene)")
    sd.add_argument("--rpm", metavar="a,b|A:B:N", help="initial speeds [rpm] (default: the log's, else the scene's)")
    sd.add_argument("--log", metavar="LOG.csv", help="torque log (n_rpm, torque_Nm) to compare at the initial speeds")
    _common(sd)
    sd.set_defaults(func=cmd_spin_down)

    lo = sub.add_parser("loads", help="load distribution of a scene's bearing (static or high-speed; per ball loads "
                                      "and angles; --plot: the ball loads around the bearing)")
    lo.add_argument("scene")
    _common(lo)
    lo.set_defaults(func=cmd_loads)

    spd = sub.add_parser("speed", help="thermal reference speed (ISO 15312, model), thermally safe speed of the "
                         "scene's cooling (model) and DIN 732's, each with the temperature of the limited node there "
                         "(the hotter race, or --node)")
    spd.add_argument("scene")
    spd.add_argument("--limit-C", dest="limit_C", type=float, default=70.0, metavar="T",
                     help="limit temperature [°C] (default 70) of the hotter race — the hotter of the inner and outer "
                     "contact nodes, inner_race / outer_race in a network built from [shaft] / [housing] (the "
                     "raceway layers, not the ring bodies inner_ring / outer_ring) — or of --node")
    spd.add_argument("--node", default=None, help="limit this free network node instead of the hotter race (e.g. "
                     "outer_ring: the stationary outer ring, where ISO 15312 / DIN 732 take the bearing's temperature)")
    _common(spd, plot=False)
    spd.set_defaults(func=cmd_speed)
    it = sub.add_parser("init", help="write a commented scene for a catalogue bearing in a shaft and housing "
                        "(every default named with its source); thermobear run solves it")
    it.add_argument("bearing", help='catalogue designation, e.g. 6208, "7205 B", 51107 (thermobear list bearings); '
                    'a closure suffix sets the seals: 6204-2RS1, 6204-RSH, 6205-2Z')
    it.add_argument("--lubrication", required=True, choices=list(METHODS), help="lubrication method")
    it.add_argument("--oil", metavar="NAME", help="lubricant (default: ISO 15312's reference oil or grease)")
    it.add_argument("--housing", choices=list(HOUSINGS), default="block", help="housing type (default block)")
    it.add_argument("--speed-rpm", dest="speed_rpm", type=float, metavar="N",
                    help="speed [r/min] (default: half the thermal reference speed, ISO 15312)")
    it.add_argument("--Fr-N", dest="Fr_N", type=float, metavar="F", help="radial load [N] (default, with neither "
                    "load given: ISO 15312's reference load 0.05 C0 of a radial bearing, 0 for a thrust bearing; "
                    "with --Fa-N alone: 0)")
    it.add_argument("--Fa-N", dest="Fa_N", type=float, metavar="F", help="axial load [N] (default, with neither "
                    "load given: 0 for a deep groove bearing, the axial reaction 1.25 Fr tan(alpha0) of an angular "
                    "contact bearing's half load zone, ISO 15312's 0.02 C0 for a thrust bearing; with --Fr-N alone: "
                    "0, refused for an angular contact bearing)")
    it.add_argument("--pair", choices=list(PAIR_ARRANGEMENTS), help="an angular contact bearing as one of a "
                    "preloaded pair (a spindle's set): its thermal preload is solved with the temperatures")
    it.add_argument("--preload-N", dest="preload_N", type=float, metavar="F", help="the pair's cold mounted preload "
                    "[N] (with --pair; as mounted: a maker's light, medium or heavy preload is the unmounted set's, "
                    "its seats' fits add to it)")
    it.add_argument("--out", metavar="FILE", help="write the scene to FILE (default: print it)")
    it.set_defaults(func=cmd_init)

    li = sub.add_parser("list", help="list bundled bearings, lubricants, materials, networks, examples")
    li.add_argument("what", nargs="?", choices=["bearings", "lubricants", "materials", "networks", "examples"],
                    help="one category (default: all, names only)")
    li.add_argument("--series", metavar="S", help='bearings of one series as a table (d x D x B, Z, D_w, alpha0, C, '
                    'C0, estimated values), e.g. 62, "72 B", 70')
    li.add_argument("--json", action="store_true")
    li.set_defaults(func=cmd_list)
    return p


def _one_line(e) -> str:
    return " ".join(str(e).split())


def _show_warning(seen):
    """One line per warning on stderr (no source lines), each fact once: a message once, and an
    OutsideValidity of the same quantity, value and range as one already shown (e.g. a lubricant temperature
    beyond its data, met by each property of the lubricant in turn) not again."""
    def show(message, category, filename, lineno, file=None, line=None):
        text = f"warning: {category.__name__}: {_one_line(message)}"
        fact = ((getattr(message, "quantity", ""), repr(getattr(message, "value", None)), getattr(message, "limit", ""))
                if isinstance(message, OutsideValidity) and getattr(message, "quantity", "") else text)
        if text not in seen and fact not in seen:
            seen.update((text, fact))
            print(text, file=sys.stderr)
    return show


def _terminate(signum, frame):
    raise KeyboardInterrupt


def solver_error_data(e: SolverError, message: str) -> dict:
    """A solver's failure as JSON-safe data (``--json`` of a verb that exits 3).

    Parameters
    ----------
    e : SolverError    the failure
    message : str      its one-line message

    Returns
    -------
    dict   ``error`` (class), ``message``, ``iterations``, ``residual`` (its unit in the message; null where not
           finite), ``history`` (the solver's, where kept), and a runaway's ``clearance_history_m`` [m],
           ``preload_history_N`` [N], ``dT_inner_outer_K`` [K] and ``mounted_m`` [m] where it has them

    >>> from thermobear.errors import ThermalPreloadRunaway
    >>> d = solver_error_data(ThermalPreloadRunaway("x", iterations=3, preload_history_N=[500.0, 900.0]), "x")
    >>> d["error"], d["iterations"], d["preload_history_N"], d["residual"]
    ('ThermalPreloadRunaway', 3, [500.0, 900.0], None)
    """
    out = {"error": type(e).__name__, "message": message, "iterations": e.iterations, "residual": e.residual,
           "history": list(e.history or [])}
    for k in ("clearance_history_m", "preload_history_N", "dT_inner_outer_K", "mounted_m"):
        v = getattr(e, k, None)
        if v is not None and not (isinstance(v, list) and not v) and not (isinstance(v, float) and v != v):
            out[k] = v                                    # (a NaN default: the runaway does not have it)
    return jsonable(out)


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(attach_negative_values(sys.argv[1:] if argv is None else argv, valued_options(parser)))
    debug = getattr(args, "debug", False)
    signal.signal(signal.SIGTERM, _terminate)          # SIGTERM ends a run as Ctrl-C does
    try:
        with warnings.catch_warnings():
            if not debug:
                warnings.simplefilter("default")
                warnings.simplefilter("ignore", ResourceWarning)   # housekeeping (a file an interrupt left open)
                warnings.showwarning = _show_warning(set())
            return int(args.func(args) or 0)
    except (InputError, NoEquilibrium) as e:   # bad input, incl. loads the bearing cannot carry
        if debug:
            raise
        text = _one_line(e) if isinstance(e, InputError) else f"{e.field} — {_one_line(e)}"
        print(f"error: {text}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except SolverError as e:
        if debug:
            raise
        print(f"error: {type(e).__name__}: {_one_line(e)}", file=sys.stderr)
        if getattr(args, "json", False):         # --json: what the solver did, for the caller (stdout)
            print_json(solver_error_data(e, _one_line(e)))
        return EXIT_SOLVER
    except ThermobearError as e:
        if debug:
            raise
        print(f"error: {_one_line(e)}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except KeyboardInterrupt:
        print("interrupted: nothing finished was lost (no output had been written yet)", file=sys.stderr)
        return EXIT_INTERRUPTED
    except BrokenPipeError:                      # e.g. `thermobear run ... | head`
        try:
            sys.stdout = open(os.devnull, "w")
        except OSError:
            pass
        return 0
    except Exception as e:  # noqa: BLE001 - the last line of defence: no traceback for a user
        if debug:
            raise
        print(f"error: internal error ({type(e).__name__}: {_one_line(e)}); please report it with the command "
              "line (--debug shows the traceback)", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
