"""The ``contactlib`` argument parser: every subcommand, option and help text.

:func:`build_parser` keeps numeric options as strings (checked later by
:mod:`contactlib.cli.inputs`); its errors are one line, raised as
:class:`~contactlib.cli.inputs.UsageError`, and any argument that starts like a
negative number (``-1e-3``, ``-inf``, ``-0.1,0.2``) is an option's value.
:func:`options_taken` reads the options a subcommand takes from the parser.
"""

from __future__ import annotations

import argparse
import re
from typing import Any, NoReturn

from contactlib import __version__
from contactlib import validate
from contactlib.cli.inputs import PROG, UsageError


# argument strings that are values, not options: a negative number in any form
# (-1, -.5, -1e-3, -inf, -nan) or a list starting with one (-0.1,0.2)
_NEGATIVE_NUMBER = re.compile(r"^-(\.?[0-9]|inf|nan)", re.IGNORECASE)


def _profile_options(sub: argparse.ArgumentParser) -> None:
    """``--profile`` and ``--exponent`` (the indenter's shape)."""
    sub.add_argument("--profile", metavar="{paraboloid,cone,power,flat,rounded}",
                     default="paraboloid",
                     help="the indenter's shape h ~ r^d: paraboloid (Hertz, d = 2), cone "
                          "(d = 1; a wedge for the cylinder), power (d = --exponent), "
                          "flat (the flat punch, a = its radius) or rounded (flat to "
                          "--flat-ratio, a paraboloid beyond); flat and rounded for "
                          "history only; for solve and sweep other than paraboloid with "
                          "the default method only; default: paraboloid")
    sub.add_argument("--exponent", metavar="D", default=None,
                     help="d of --profile power, in [0.5, 8]")
    sub.add_argument("--flat-ratio", metavar="B", default=None,
                     help="b/a_max of --profile rounded: its flat radius over the "
                          "frictionless contact radius at P_max, in [0, 0.9]")


def _layer_options(sub: argparse.ArgumentParser, length: str, coated: bool = False) -> None:
    """``--slab-ratio`` and ``--base`` (``length``: "a" or "a_max"); with ``coated`` also
    ``--substrate-modulus`` and ``--substrate-nu`` (solve, sweep, history)."""
    most = dict(validate.LAYER_RATIO_MAX)
    if length == "a_max":  # history: the cylinder on a smooth base keeps its own range
        most[("cylinder", "smooth")] = validate.HISTORY_CYLINDER_SMOOTH_RATIO_MAX
    sub.add_argument("--slab-ratio", metavar="A_OVER_H", default="0",
                     help=f"{length}/h of an elastic layer of thickness h on a rigid base, "
                          f">= 0 (0 = half-space / half-plane); at most "
                          f"{most[('sphere', 'bonded')]:g} for the sphere, "
                          f"{most[('cylinder', 'smooth')]:g} for the cylinder on a smooth "
                          f"base, {most[('cylinder', 'bonded')]:g} on a bonded one; default: 0")
    if not coated:
        sub.add_argument("--base", metavar="{smooth,bonded}", default="smooth",
                         help="the layer's rigid base: smooth (frictionless) or bonded; "
                              "default: smooth")
        return
    sub.add_argument("--base", metavar="{smooth,bonded,elastic}", default="smooth",
                     help="the layer's base: rigid and smooth (frictionless) or bonded, or "
                          "elastic (a coated body: the layer bonded to an elastic half-space; "
                          f"a/h <= {most[('sphere', 'elastic')]:g} for the sphere, "
                          f"{most[('cylinder', 'elastic')]:g} for the cylinder, a_max/h <= "
                          f"{validate.HISTORY_CYLINDER_COATED_RATIO_MAX:g} for the cylinder "
                          "in history); default: smooth")
    sub.add_argument("--substrate-modulus", metavar="E2_OVER_E1", default=None,
                     help="with --base elastic: the substrate's Young's modulus over the "
                          "layer's, in [1e-2, 1e6] (required there)")
    sub.add_argument("--substrate-nu", metavar="NU2", default=None,
                     help="with --base elastic: the substrate's Poisson's ratio, in (-1, 0.5]; "
                          "default: the layer's --nu")


class _Parser(argparse.ArgumentParser):
    """ArgumentParser whose errors are one line, raised as UsageError.

    Any argument that starts like a negative number (``-1e-3``, ``-inf``,
    ``-0.1,0.2``) is an option's value, so that it reaches the validator and
    is accepted or refused by value (argparse alone reads ``-1e-3`` as an
    option).
    """

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = _NEGATIVE_NUMBER

    def error(self, message: str) -> NoReturn:
        raise UsageError(" ".join(message.split()))


_OUTPUT_HELP = ("write the netCDF dataset here (checked before any computing; missing "
                "parent folders are created; an existing file is replaced)")


_METHOD_HELP = ("discretization: 'default' (ours), 'extrapolated' (ours on the nested "
                "meshes n/8 ... n, k extrapolated in n: about 1e-6 at n = 256; n a multiple "
                "of 128), 'paper' (the paper's scheme as printed, "
                "Coulomb's law on each ring's resultant) or 'paper-literal' (the printed "
                "q_i = k p_i); default: 'default', or planned with --tolerance")


def _indenter_options(sub: argparse.ArgumentParser) -> None:
    sub.add_argument("--indenter-modulus", metavar="E1_OVER_E2", default="inf",
                     help="Young's modulus of the indenter over that of the body, > 0 "
                          "(inf = rigid); scalings use the composite modulus E*; "
                          "default: inf")
    sub.add_argument("--indenter-nu", metavar="NU1", default=None,
                     help="Poisson's ratio of an elastic indenter, in (-1, 0.5] "
                          "(needs --indenter-modulus; default: the body's)")


_UNITS_HELP = ("an SI number or a number with a unit suffix")


def _physical_options(sub: argparse.ArgumentParser, *, load: bool) -> None:
    """The options of a problem in physical units (docs/physical.md)."""
    group = sub.add_argument_group(
        "physical units", "give the problem in SI (numbers, or with a unit: 5mm, 100N, "
        "210GPa, 2um): the summary and the dataset then report a, c, pressures, approach and "
        "energies in m, Pa, N and J beside the dimensionless values")
    group.add_argument("--radius", metavar="R", default=None,
                       help=f"indenter radius R in m ({_UNITS_HELP}: 5mm)")
    if load:
        group.add_argument("--load", metavar="P", default=None,
                           help=f"normal force P in N ({_UNITS_HELP}: 100N; a cylinder's over "
                                "its --length)")
    group.add_argument("--half-angle", metavar="DEG", default=None,
                       help="with --profile cone: the cone's (wedge's) half-angle in degrees, "
                            "0 < DEG < 90 (70.3: the cone of a Berkovich tip's area); "
                            "replaces --radius")
    group.add_argument("--indenter", metavar="NAME|E,NU", default=None,
                       help="indenter material: a name of the package's table "
                            "(contactlib/data/materials.yaml), rigid, or E,nu (210GPa,0.3); "
                            "default: rigid")
    group.add_argument("--body", metavar="NAME|E,NU", default=None,
                       help="elastic body (the layer's material on a layer): a name of the "
                            "table or E,nu")
    group.add_argument("--length", metavar="L", default=None,
                       help="the cylinder's length in m (required for a cylinder)")
    group.add_argument("--thickness", metavar="H", default=None,
                       help="thickness of an elastic layer on a rigid base, in m (default: "
                            "half-space / half-plane); --base chooses the base (elastic: "
                            "a coating on --substrate)")
    group.add_argument("--substrate", metavar="NAME|E,NU", default=None,
                       help="with --base elastic and --thickness: the substrate the coating "
                            "(--body) is bonded to, a name of the table or E,nu; its E over "
                            "the coating's in [1e-2, 1e6]")
    if not load:
        group.add_argument("--times", metavar="LIST", default=None,
                           help="with --relaxation: the time of each load-path point, in s "
                                "or with a unit (0s,0.5s,1s); relaxation times then in s "
                                "too (G1:TAU1 with TAU1 in s or with a unit)")


def _common(sub: argparse.ArgumentParser, *, output_required: bool) -> None:
    sub.add_argument("--geometry", required=True, metavar="{sphere,cylinder}",
                     help="rigid indenter: sphere (axisymmetric) or cylinder "
                          "(plane strain)")
    sub.add_argument("--nu", default=None, metavar="NU",
                     help="Poisson's ratio of the elastic body, in (-1, 0.5] (required, "
                          "unless the body is given physically with --body)")
    sub.add_argument("--n", metavar="N", default=None,
                     help="number of elements across the half-contact "
                          "(integer >= 2; library default if omitted)")
    sub.add_argument("--method", metavar="NAME", default=None, help=_METHOD_HELP)
    _profile_options(sub)
    _layer_options(sub, "a", coated=True)
    _indenter_options(sub)
    sub.add_argument("--output", metavar="FILE.nc", required=output_required,
                     default=None, help=_OUTPUT_HELP)
    sub.add_argument("--max-error", metavar="E", default="1e-3",
                     help="accuracy a case must reach, as relative error of k in (0, 1): a "
                          "case whose error estimate exceeds it is reported as not resolved; "
                          "default: %(default)s")
    sub.add_argument("--tolerance", metavar="T", default=None,
                     help="relative error of k to reach instead of --n/--method, in "
                          "[1e-9, 0.1]: the cheapest method and n predicted to meet it are "
                          "planned (the extrapolated method from about 1e-5 down), n is "
                          "doubled where a case's estimate falls short, and --max-error "
                          "becomes T; refused where no method is predicted to meet it "
                          "(e.g. 1e-6 at c/a = 0.9999); with --stick-ratio(s) only")
    sub.add_argument("--no-energy", action="store_true",
                     help="skip the frictional-work integration "
                          "(frictional_work is NaN)")
    sub.add_argument("--debug", action="store_true",
                     help="print a traceback on unexpected errors")


def build_parser() -> argparse.ArgumentParser:
    """Build the ``contactlib`` argument parser.

    Returns
    -------
    argparse.ArgumentParser
        Numeric options are kept as strings; :func:`main` validates them.
    """
    parser = _Parser(
        prog=PROG,
        allow_abbrev=False,
        description="Adhesion and partial slip of a rigid sphere or cylinder pressed "
                    "into an elastic body with Coulomb friction: self-similar loading "
                    "(solve, sweep) or any normal load path (history).",
    )
    parser.add_argument("--version", action="version", version=f"{PROG} {__version__}")
    subs = parser.add_subparsers(dest="command", metavar="{solve,sweep,history,check-config}",
                                 parser_class=_Parser)
    subs.required = True

    solve = subs.add_parser(
        "solve", help="solve one case", allow_abbrev=False,
        description="Solve one case for a given stick ratio c/a or friction "
                    "coefficient k; print a summary, optionally write a dataset.")
    _common(solve, output_required=False)
    _physical_options(solve, load=True)
    which = solve.add_mutually_exclusive_group(required=True)
    which.add_argument("--stick-ratio", metavar="G",
                       help="stick ratio c/a in [0, 1] (0 frictionless, "
                            "1 full adhesion)")
    which.add_argument("--friction", metavar="K",
                       help="friction coefficient k >= 0; solve for c/a")
    solve.add_argument("--subsurface", action="store_true",
                       help="add the stress field inside the body to --output (variables "
                            "sigma_*, von_mises, tresca, ... in units of p0 on x = r/a "
                            "(x/a) and z = depth/a, 0 ... 2; docs/stresses.md); half-space, "
                            "half-plane, a layer on a rigid base or a coated body (z > h: "
                            "the substrate)")

    sweep = subs.add_parser(
        "sweep", help="solve a sweep over c/a", allow_abbrev=False,
        description="Solve a sweep over stick ratios c/a and write one dataset.")
    _common(sweep, output_required=True)
    sweep.add_argument("--stick-ratios", metavar="LIST|all", default="all",
                       help="comma-separated c/a values, or 'all' for m/n, "
                            "m = 1 ... n-1; default: all")

    hist = subs.add_parser(
        "history", help="follow a load path (incremental stick-slip)", allow_abbrev=False,
        description="Follow a normal load path in steps with incremental Coulomb "
                    "stick-slip (no self-similarity, any number of stick zones) and "
                    "write one dataset with a step dimension.")
    hist.add_argument("--geometry", required=True, metavar="{sphere,cylinder}",
                      help="rigid indenter: sphere (axisymmetric) or cylinder "
                           "(plane strain)")
    hist.add_argument("--nu", default=None, metavar="NU",
                      help="Poisson's ratio of the elastic body, in (-1, 0.5] (required, "
                           "unless the body is given physically with --body)")
    hist.add_argument("--friction", required=True, metavar="K",
                      help="friction coefficient k >= 0 (inf: no slip)")
    hist.add_argument("--load-path", default=None, metavar="LIST",
                      help="comma-separated load levels P/P_max in [0, 1] starting at 0, "
                           "e.g. 0,1,0; or forces with a unit, e.g. 0N,100N,0N (a physical "
                           "problem: needs --radius and --body). One of --load-path, "
                           "--load-shape and --load-table is required")
    hist.add_argument("--load-shape", default=None, metavar="{sinusoidal,haversine}",
                      help="a periodic load path: sinusoidal, mean + amplitude sin(2 pi f t), "
                           "or haversine, mean - amplitude cos(2 pi f t); with --amplitude, "
                           "--mean, --cycles and (with --relaxation) --frequency; a ramp from "
                           "0 precedes it if it starts above 0")
    hist.add_argument("--amplitude", default=None, metavar="A",
                      help="with --load-shape: the amplitude, a level (P/P_max) or a force "
                           "with a unit (40N)")
    hist.add_argument("--mean", default=None, metavar="M",
                      help="with --load-shape: the mean, a level or a force with a unit; "
                           "mean >= amplitude (no pull), mean + amplitude <= 1 as levels")
    hist.add_argument("--frequency", default=None, metavar="F",
                      help="with --load-shape: the frequency, in 1/(unit of tau), or in Hz "
                           "(1Hz) for a physical problem; needed with --relaxation only (an "
                           "elastic body's answer does not depend on it)")
    hist.add_argument("--cycles", default=None, metavar="N",
                      help="with --load-shape: the number of periods (> 0)")
    hist.add_argument("--ramp", default=None, metavar="T",
                      help="with --load-shape: duration of the ramp from 0 to the shape's "
                           "start (unit of tau, or s); default a quarter period")
    hist.add_argument("--load-table", default=None, metavar="FILE.csv",
                      help="a load path sampled in time: a CSV file with a header "
                           "'time,load' (levels, time in the unit of tau) or, for a "
                           "physical problem, 'time,force' (s, N; or units in brackets, "
                           "'time [ms],force [kN]'); linear between its rows, from load 0")
    hist.add_argument("--steps", default=None, metavar="N",
                      help="equal load steps per path segment (positive integer; default "
                           f"{validate.HISTORY_DEFAULT_STEPS}); "
                           "with --load-shape or --load-table: steps a load travel of "
                           "P_max, each monotone piece getting its share (a multiple of 4)")
    hist.add_argument("--n", metavar="N", default=None,
                      help="elements over 1.2 a_max (integer; library default if omitted)")
    _profile_options(hist)
    _layer_options(hist, "a_max", coated=True)
    _indenter_options(hist)
    _physical_options(hist, load=False)
    hist.add_argument("--relaxation", metavar="G1:TAU1[,G2:TAU2...]", default=None,
                      help="a viscoelastic body: Prony terms of E(t)/E(0) = 1 - sum g_i "
                           "(1 - exp(-t/tau_i)), g_i > 0, sum g_i < 1, tau_i > 0 (constant "
                           "Poisson's ratio; scalings use E(0)); needs --duration")
    hist.add_argument("--duration", metavar="T[,T2...]", default=None,
                      help="with --relaxation: duration of the load path (segments equally "
                           "long), or one a segment, in the unit of tau")
    hist.add_argument("--tangential-path", metavar="LIST", default=None,
                      help="fretting (cylinder; sphere, coupled pairs in the verified "
                           "range of docs/fretting.md): comma-separated tangential loads "
                           "Q/(k P_max) at the points of --load-path (same length, starting "
                           "at 0, |Q| < k P at every point), or forces with units (0N,0N,10N) "
                           "with the physical options (--radius, --body; the cylinder also "
                           "--length); switches to the fretting solver "
                           "(n counts elements over 1.2 a_max each side of the axis, a "
                           "multiple of 4; steps a multiple of 4, default 40; the sphere: "
                           "n cells a side, default 64, steps default 8)")
    hist.add_argument("--tangential-displacement", action="store_true",
                      help="with --tangential-path (the sphere): its values are the "
                           "indenter's rigid shift s R/a_max^2 (or lengths with units, "
                           "0um,2um, with the physical options) and Q is the answer; gross "
                           "sliding is allowed. The cylinder refuses it (its shift has a "
                           "logarithmic datum)")
    hist.add_argument("--bulk-stress", metavar="LIST", default=None,
                      help="with --tangential-path: the body's bulk stress along x over p0 "
                           "at the points of --load-path (fretting fatigue specimen)")
    hist.add_argument("--output", metavar="FILE.nc", default=None,
                      help=_OUTPUT_HELP + " (optional: without it the summary is printed "
                           "and nothing is written)")
    hist.add_argument("--max-error", metavar="E",
                      default=f"{validate.PATH_DEFAULT_MAX_ERROR:g}",
                      help="accuracy a step must reach, in (0, 1): a step whose estimated "
                           "error of the stick radius (in a_max) or relative error of the "
                           "frictional work exceeds it is flagged not resolved; "
                           "default: %(default)s, what the default n and steps reach (1e-3 "
                           "needs about 4 n and 4 x steps: --tolerance 1e-3 plans them)")
    hist.add_argument("--tolerance", metavar="T", default=None,
                      help="accuracy to reach instead of --n/--steps/--max-error, in "
                           "[1e-5, 1e-2]: the path's frictional work relative to its total "
                           "and the stick radius at the peak load in a_max; n and steps "
                           "are planned from measured convergence, refined where the run's "
                           "estimates fall short, and --max-error becomes T; exit status 3 "
                           "(the dataset written, flagged) where the run does not get there")
    hist.add_argument("--debug", action="store_true",
                      help="print a traceback on unexpected errors")

    check = subs.add_parser(
        "check-config", help="check workflow configuration files", allow_abbrev=False,
        description="Check YAML files meant for the workflow (config/config.yaml, or "
                    "your own for 'snakemake --configfile FILE'): YAML syntax, reported "
                    "with the file and line, and every scene by the library's rules, "
                    "all problems at once. Snakemake reads a --configfile itself before "
                    "the workflow starts, and its message for a YAML syntax error names "
                    "neither file nor line: run this first.")
    check.add_argument("files", nargs="+", metavar="FILE", help="a YAML configuration file")
    return parser


def options_taken(command: str) -> set[str]:
    """The options ``contactlib <command>`` takes (read from the parser)."""
    parser = build_parser()
    subparsers = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return {o for a in subparsers.choices[command]._actions for o in a.option_strings}
