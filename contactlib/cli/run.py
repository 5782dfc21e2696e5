"""Command line interface: ``contactlib solve``, ``contactlib sweep`` and ``contactlib history``.

Every option value is parsed and range-checked here, before any numerics run,
so that bad input ends with exit status 2 and exactly one line on stderr::

    contactlib: error: --nu must be a number in (-1, 0.5], got 'abc'

Errors raised by the library as :class:`ValueError` are reported the same way
(status 2), except valid input that the solver cannot answer
(:class:`contactlib.validate.SolverLimit`, e.g. a friction so large that the
contact is most likely fully stuck): status 3, its reason on one line and then
one line ``contactlib: answer it with: contactlib ...`` for each command that
answers the case, with the arguments filled in. Any other exception gives one
line and status 1 (``--debug`` adds the traceback). ``--output`` is checked
before any computing (missing parent folders are created; an unwritable place,
a path through a file or a name too long is bad input), and the file is written
only after success.
Negative numbers, also in exponent form (``--nu -1e-3``), are option values,
never taken for options.

Examples
--------
>>> from contactlib.cli import main
>>> main(["solve", "--geometry", "cone", "--nu", "0.3", "--stick-ratio", "0.5"])
2
"""

from __future__ import annotations

import argparse
import math
from contextlib import contextmanager
import os
import re
import sys
import traceback
from collections.abc import Callable, Sequence
from types import ModuleType
from typing import Any, NoReturn, TextIO

from contactlib import __version__
from contactlib import validate
from contactlib.result import Solution, substrate_text

__all__ = ["main", "build_parser", "check_output", "UsageError", "SolverLimitError",
           "EXIT_BAD_INPUT", "EXIT_SOLVER_LIMIT"]

PROG = "contactlib"
# argument strings that are values, not options: a negative number in any form
# (-1, -.5, -1e-3, -inf, -nan) or a list starting with one (-0.1,0.2)
_NEGATIVE_NUMBER = re.compile(r"^-(\.?[0-9]|inf|nan)", re.IGNORECASE)
_INT_RE = re.compile(r"^\s*\+?[0-9]+\s*$")


# convention: exit status of bad input (the project's rule; tests/test_solver_limit.py)
EXIT_BAD_INPUT = 2
"""Exit status of bad input (one line on stderr naming the option)."""
# convention: exit status of valid input beyond a solver limit (the project's rule;
# tests/test_solver_limit.py)
EXIT_SOLVER_LIMIT = 3
"""Exit status of valid input the solver cannot answer (:class:`SolverLimitError`)."""


class UsageError(Exception):
    """Bad command-line input; the message is one line naming the option."""


class SolverLimitError(Exception):
    """Valid input the solver cannot answer (exit status 3).

    ``limit`` is the library's :class:`contactlib.validate.SolverLimit`, whose
    ``remedies`` :func:`main` turns into commands.
    """

    def __init__(self, limit: ValueError) -> None:
        self.limit = limit
        super().__init__(str(limit))


# --------------------------------------------------------------------------
# value parsing (no argparse ``type=``: we want our own one-line messages)
# --------------------------------------------------------------------------


def _option(name: str) -> str:
    """The option of a library argument: ``slab_ratio`` -> ``--slab-ratio``."""
    return "--" + name.replace("_", "-")


def _usage(exc: ValueError, text: str | None = None) -> UsageError:
    """A library input error as a one-line usage error naming the option.

    The rule's name and requirement come from the exception's fields
    (:class:`contactlib.validate.InputError`), not from its text; the value
    is shown as the user typed it.
    """
    name = getattr(exc, "name", None)
    if name is None:
        return UsageError(str(exc))
    option = _option(name)
    shown = exc.value if text is None else text
    if isinstance(shown, str) and len(shown) > 40:
        shown = shown[:37] + "..."
    standard = f"{name} must be {exc.requirement}, got {exc.value!r}"
    if str(exc) == standard:
        return UsageError(f"{option} must be {exc.requirement}, got {shown!r}")
    message = str(exc)
    return UsageError(option + message[len(name):] if message.startswith(name) else message)


def _float(text: str) -> float | str:
    """The number a string spells, or the string itself (which the rule refuses)."""
    try:
        return float(text)
    except (TypeError, ValueError):
        return text


def _int(text: str) -> int | str:
    """The integer a string spells (digits only), or the string itself."""
    return int(text) if _INT_RE.match(text) and len(text.strip()) <= 12 else text


def _check(rule: Callable[..., Any], text: str, value: Any, *args: Any) -> Any:
    """``rule(value, *args)``, its :class:`ValueError` as a usage error showing ``text``."""
    try:
        return rule(value, *args)
    except ValueError as exc:
        raise _usage(exc, text) from None


def _list(text: str) -> list[float | str]:
    return [_float(item) for item in text.split(",")]


def parse_nu(text: str) -> float:
    """Poisson's ratio in (-1, 0.5]."""
    return _check(validate.nu, text, _float(text))


def parse_max_error(text: str) -> float:
    """Accuracy asked for: a relative error of k in (0, 1)."""
    return _check(validate.max_error, text, _float(text))


def parse_tolerance(text: str) -> float:
    """A relative error of k to reach, in [1e-9, 0.1] (:func:`validate.planned_tolerance`)."""
    return _check(validate.planned_tolerance, text, _float(text))


def parse_fraction(option: str, text: str) -> float:
    """A stick ratio c/a in [0, 1] (``option``: ``--stick-ratio``)."""
    return _check(validate.stick_ratio, text, _float(text), option.lstrip("-").replace("-", "_"))


def parse_friction(text: str) -> float:
    """Friction coefficient k >= 0 (``inf`` allowed: full adhesion)."""
    return _check(validate.friction, text, _float(text))


def parse_slab_ratio(text: str, geometry: str | None = None, base: str = "smooth",
                     extent: float = 1.0) -> float:
    """Layer ratio a/h, finite, >= 0 (0 = half-space/half-plane), within the supported range."""
    return _check(validate.slab_ratio, text, _float(text), geometry, base, extent)


def parse_base(text: str, coated: bool = False) -> str:
    """The layer's rigid base: smooth or bonded (``coated``: also elastic, a coated body)."""
    return _check(validate.base, text, text, coated)


def parse_substrate(args: argparse.Namespace, base: str, geometry: str,
                    method: str) -> dict[str, float]:
    """``substrate_modulus`` and ``substrate_nu`` of a coated body (``--base elastic``), checked
    by :func:`validate.substrate`; refused without it; {} on a rigid base."""
    modulus = None if args.substrate_modulus is None else _float(args.substrate_modulus)
    nu2 = None if args.substrate_nu is None else _float(args.substrate_nu)
    shown = {"substrate_modulus": args.substrate_modulus, "substrate_nu": args.substrate_nu,
             "method": method}
    try:
        modulus, nu2 = validate.substrate(base, modulus, nu2, geometry, method)
    except validate.InputError as exc:
        raise _usage(exc, shown.get(exc.name, base)) from None
    if base != validate.COATED_BASE:
        return {}
    return {"substrate_modulus": modulus} | ({} if nu2 is None else {"substrate_nu": nu2})


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


def _profile_kwargs(args: argparse.Namespace) -> dict[str, Any]:
    """``profile`` (and ``exponent``) keywords, only when not the paraboloid (the default)."""
    if args.profile == "paraboloid" and args.exponent is None and args.flat_ratio is None:
        return {}
    from contactlib import profiles

    exponent = None if args.exponent is None else _float(args.exponent)
    flat = None if args.flat_ratio is None else _float(args.flat_ratio)
    try:
        shape = profiles.profile(args.profile, exponent, flat)
    except ValueError as exc:  # shown with the option it names
        text = {"exponent": args.exponent, "flat_ratio": args.flat_ratio}.get(
            getattr(exc, "name", ""), args.profile)
        raise _usage(exc, text) from None
    return {"profile": shape.name, **({"exponent": shape.exponent}
                                      if shape.name == "power" else {}),
            **({"flat_ratio": shape.flat} if shape.is_rounded else {})}


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


def parse_n(text: str, method: str = "default") -> int:
    """Number of elements of a self-similar solve, for ``method``."""
    return _check(validate.n, text, _int(text), method)


def parse_history_n(text: str) -> int:
    """Number of elements of the history solver."""
    return _check(validate.history_n, text, _int(text))


def parse_stick_ratios(text: str, n: int) -> str | list[float]:
    """``all`` or a comma-separated list of distinct numbers in [0, 1]."""
    if text.strip().lower() == "all":
        return "all"
    labels = [item.strip() for item in text.split(",")]
    return _check(validate.stick_ratios, text, _list(text), n, labels)


def parse_load_path(text: str | None) -> list[float]:
    """Comma-separated load levels P/P_max in [0, 1], starting at 0 (at least two)."""
    if text is None:
        raise UsageError("--load-path is required here (comma-separated load levels, e.g. "
                         "0,1,0)")
    return list(_check(validate.load_path, text, _list(text)))


_SHAPE_OPTIONS = ("amplitude", "mean", "frequency", "cycles", "ramp")


def _path_source(args: argparse.Namespace) -> str:
    """Which of ``--load-path``, ``--load-shape``, ``--load-table`` gives the path (one)."""
    given = [opt for opt, value in (("--load-path", args.load_path),
                                    ("--load-shape", args.load_shape),
                                    ("--load-table", args.load_table)) if value is not None]
    if len(given) != 1:
        raise UsageError("give one of --load-path, --load-shape and --load-table"
                         + (f", got {' and '.join(given)}" if given else ""))
    stray = [f"--{key}" for key in _SHAPE_OPTIONS if getattr(args, key) is not None]
    if given[0] != "--load-shape" and stray:
        raise UsageError(f"{stray[0]} goes with --load-shape, got it with {given[0]}")
    return given[0]


def _shape_usage(exc: ValueError, source: str) -> UsageError:
    """A shape's or table's input error, naming its option (``load_path.mean`` -> --mean;
    ``load_path`` -> ``source``, --load-shape or --load-table)."""
    text = str(exc)
    name = getattr(exc, "name", "") or ""
    key = name.split(".", 1)[1] if name.startswith("load_path.") else ""
    option = ("--load-shape" if key == "shape" else f"--{key}" if key in _SHAPE_OPTIONS
              else "--load-table" if key else "")
    for prefix in filter(None, (name, "load_path")):
        if text.startswith(prefix):
            return UsageError((option or source) + text[len(prefix):])
    return UsageError(text)


def parse_history_path(args: argparse.Namespace, physical: bool) -> dict[str, Any]:
    """The shape (``--load-shape`` and its options) or table (``--load-table``, read here)
    of a history, as the mapping of :mod:`contactlib.load_paths` (levels) or of
    :func:`contactlib.physical.force_shape` (forces, SI)."""
    from contactlib import load_paths

    if args.load_table is not None:
        from contactlib import io

        try:
            spec: dict[str, Any] = io.read_load_table(args.load_table, physical=physical)
        except ValueError as exc:
            raise UsageError(f"--load-table: {exc}") from None
    else:
        missing = [f"--{key}" for key in ("amplitude", "mean", "cycles")
                   if getattr(args, key) is None]
        if missing:
            raise UsageError(f"--load-shape needs --amplitude, --mean and --cycles, missing "
                             f"{' and '.join(missing)}")
        spec = {"shape": args.load_shape}
        for key in _SHAPE_OPTIONS:
            value = getattr(args, key)
            if value is not None:
                spec[key] = value if physical and key != "cycles" else _float(value)
        if args.relaxation is not None and args.frequency is None:
            raise UsageError("--frequency is required with --load-shape and --relaxation")
    try:
        if physical:
            from contactlib.physical import force_shape

            force_shape(spec)
        else:
            load_paths.load_path(spec)
    except ValueError as exc:
        raise _shape_usage(exc, "--load-shape" if args.load_table is None
                           else "--load-table") from None
    return spec


def parse_steps(text: str) -> int:
    """Load steps per path segment, a positive integer."""
    return _check(validate.steps, text, _int(text))


# --------------------------------------------------------------------------
# parser
# --------------------------------------------------------------------------


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
                "q_i = k p_i); default: %(default)s")


def _indenter_text(sol: Any) -> str:
    """``, E1/E2 = .., nu1 = .., beta = ..`` of an elastic indenter; empty when rigid."""
    ratio = getattr(sol, "indenter_modulus_ratio", float("inf"))
    if ratio == float("inf"):
        return ""
    return (f", E1/E2 = {ratio:g}, nu1 = {sol.indenter_poisson_ratio:g}, "
            f"beta = {sol.dundurs_beta:.4g}")


def _indenter_options(sub: argparse.ArgumentParser) -> None:
    sub.add_argument("--indenter-modulus", metavar="E1_OVER_E2", default="inf",
                     help="Young's modulus of the indenter over that of the body, > 0 "
                          "(inf = rigid); scalings use the composite modulus E*; "
                          "default: inf")
    sub.add_argument("--indenter-nu", metavar="NU1", default=None,
                     help="Poisson's ratio of an elastic indenter, in (-1, 0.5] "
                          "(needs --indenter-modulus; default: the body's)")


def parse_indenter(modulus: str, nu: str | None) -> tuple[float, float | None]:
    """(E1/E2, nu1) from ``--indenter-modulus`` and ``--indenter-nu`` (nu1 None: the body's)."""
    try:
        return validate.indenter_material(_float(modulus), None if nu is None else _float(nu))
    except ValueError as exc:
        name = getattr(exc, "name", None)
        raise _usage(exc, modulus if name == "indenter_modulus" else nu) from None


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
    sub.add_argument("--method", metavar="NAME", default="default", help=_METHOD_HELP)
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
                      help="fretting (cylinder; sphere for Dundurs beta = 0 pairs): "
                           "comma-separated tangential loads "
                           "Q/(k P_max) at the points of --load-path (same length, starting "
                           "at 0, |Q| < k P at every point); switches to the fretting solver "
                           "(n counts elements over 1.2 a_max each side of the axis, a "
                           "multiple of 4; steps a multiple of 4, default 40; the sphere: "
                           "n cells a side, default 64, steps default 8)")
    hist.add_argument("--bulk-stress", metavar="LIST", default=None,
                      help="with --tangential-path: the body's bulk stress along x over p0 "
                           "at the points of --load-path (fretting fatigue specimen)")
    hist.add_argument("--output", metavar="FILE.nc", default=None,
                      help=_OUTPUT_HELP + " (optional: without it the summary is printed "
                           "and nothing is written)")
    hist.add_argument("--max-error", metavar="E",
                      default=f"{validate.DEFAULT_MAX_ERROR:g}",
                      help="accuracy a step must reach, in (0, 1): a step whose estimated "
                           "error of the stick radius (in a_max) or relative error of the "
                           "frictional work exceeds it is flagged not resolved; "
                           "default: %(default)s, as for solve and sweep (the default n and "
                           "steps reach about 1 %%, so ask for 1e-2 or refine: 1e-3 needs "
                           "about 4 n and 4 x steps)")
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


# --------------------------------------------------------------------------
# validation of a parsed namespace
# --------------------------------------------------------------------------


def _validate(args: argparse.Namespace) -> dict[str, Any]:
    """Turn raw option strings into checked keyword arguments of solve/sweep."""
    geometry = _check(validate.geometry, args.geometry, args.geometry)
    method = _check(validate.method, args.method, args.method)
    n = None if args.n is None else parse_n(args.n, method)
    base = parse_base(args.base, coated=True)
    kwargs: dict[str, Any] = {
        "geometry": geometry,
        "nu": parse_nu(_required(args.nu, "--nu")),
        "n": n,
        "method": method,
        "slab_ratio": parse_slab_ratio(args.slab_ratio, geometry, base),
        "energy": not args.no_energy,
        "max_error": parse_max_error(args.max_error),
    }
    if args.tolerance is not None:
        kwargs["tolerance"] = parse_tolerance(args.tolerance)
        if args.n is not None or args.method != "default":
            raise UsageError("--tolerance must be given without --n and --method (the plan "
                             f"picks them), got --tolerance {args.tolerance!r} with them")
    ratio, nu1 = parse_indenter(args.indenter_modulus, args.indenter_nu)
    if ratio != float("inf"):  # the rigid default is the library's: keywords only when elastic
        kwargs["indenter_modulus"], kwargs["indenter_nu"] = ratio, nu1
    if base != "smooth":  # likewise: the keyword only when not the default
        kwargs["base"] = base
    kwargs.update(parse_substrate(args, base, geometry, method))
    kwargs.update(_profile_kwargs(args))  # likewise
    if args.command == "solve":
        if args.stick_ratio is not None:
            kwargs["stick_ratio"] = parse_fraction("--stick-ratio", args.stick_ratio)
        else:
            kwargs["friction"] = parse_friction(args.friction)
    else:
        kwargs["stick_ratios"] = parse_stick_ratios(args.stick_ratios,
                                                    validate.n(n, method))
    return kwargs


def _validate_history(args: argparse.Namespace) -> dict[str, Any]:
    """Checked keyword arguments of :func:`contactlib.history`."""
    geometry = _check(validate.geometry, args.geometry, args.geometry)
    base = parse_base(args.base, coated=True)
    shaped = _path_source(args) != "--load-path"
    kwargs = {
        "geometry": geometry,
        "nu": parse_nu(_required(args.nu, "--nu")),
        "friction": parse_friction(args.friction),
        "load_path": (parse_history_path(args, physical=False) if shaped
                      else parse_load_path(args.load_path)),
        "steps": None if args.steps is None else parse_steps(args.steps),
        "n": None if args.n is None else parse_history_n(args.n),
        "slab_ratio": parse_slab_ratio(args.slab_ratio, geometry, base,
                                       validate.HISTORY_MESH_EXTENT),
        "max_error": parse_max_error(args.max_error),
    }
    ratio, nu1 = parse_indenter(args.indenter_modulus, args.indenter_nu)
    if ratio != float("inf"):  # as for solve/sweep: keywords only when elastic
        kwargs["indenter_modulus"], kwargs["indenter_nu"] = ratio, nu1
    if shaped and args.duration is not None:
        raise UsageError("--duration is not used with --load-shape or --load-table: the "
                         f"path gives its times, got --duration {args.duration!r}")
    if shaped and args.relaxation is not None:  # the shape's or table's own times
        kwargs["relaxation"] = [list(p) for p in parse_relaxation(args.relaxation)]
    elif args.relaxation is not None or args.duration is not None:  # a viscoelastic body
        kwargs.update(parse_viscoelastic(args.relaxation, args.duration,
                                         len(kwargs["load_path"]) - 1))
        if ratio != float("inf"):
            raise UsageError("--relaxation needs a rigid indenter (no --indenter-modulus)")
    if base != "smooth":
        kwargs["base"] = base
    kwargs.update(parse_substrate(args, base, geometry, "default"))
    kwargs.update(_profile_kwargs(args))
    return kwargs


def _validate_planned_history(args: argparse.Namespace) -> dict[str, Any]:
    """Checked keyword arguments of :func:`contactlib.history` with ``--tolerance`` (the
    plan picks n and steps: :mod:`contactlib.history_plan`)."""
    from contactlib.history_plan import MAX_TOLERANCE, MIN_TOLERANCE

    tol = _check(lambda v: validate.number("tolerance", v, MIN_TOLERANCE, MAX_TOLERANCE),
                 args.tolerance, _float(args.tolerance))
    given = [o for o, v in (("--steps", args.steps), ("--n", args.n)) if v is not None]
    if args.max_error != f"{validate.DEFAULT_MAX_ERROR:g}":
        given.append("--max-error")
    if given:
        raise UsageError(f"--tolerance must be given without {', '.join(given)} (the plan "
                         f"picks n and steps, and T is the accuracy asked for), got "
                         f"--tolerance {args.tolerance!r} with them")
    kwargs = _validate_history(argparse.Namespace(**{**vars(args), "steps": "1"}))
    kwargs.pop("max_error")
    kwargs.update(steps=None, n=None, tolerance=tol)
    return kwargs


def _validate_fretting(args: argparse.Namespace) -> dict[str, Any]:
    """Checked keyword arguments of :func:`contactlib.fretting` (``--tangential-path``)."""
    from contactlib import fretting_api

    for option, given in (("--slab-ratio", args.slab_ratio not in (None, "0")),
                          ("--base", args.base != "smooth"),
                          ("--relaxation", args.relaxation is not None),
                          ("--duration", args.duration is not None),
                          ("--substrate-modulus", getattr(args, "substrate_modulus", None)
                           is not None),
                          ("--substrate-nu", getattr(args, "substrate_nu", None) is not None)):
        if given:
            raise UsageError(f"{option} must be given without --tangential-path: fretting "
                             "is solved for a half-plane (no layer, no viscoelasticity)")
    geometry = _check(validate.geometry, args.geometry, args.geometry)
    kwargs: dict[str, Any] = {
        "geometry": geometry,
        "nu": parse_nu(_required(args.nu, "--nu")),
        "friction": parse_friction(args.friction),
        "load_path": parse_load_path(args.load_path),
        "tangential_path": _list(args.tangential_path),
        "steps": fretting_api.defaults(geometry)[1] if args.steps is None
        else parse_steps(args.steps),
        "n": fretting_api.defaults(geometry)[0] if args.n is None else _int(args.n),
        "max_error": parse_max_error(args.max_error),
    }
    if args.bulk_stress is not None:
        kwargs["bulk_stress"] = _list(args.bulk_stress)
    ratio, nu1 = parse_indenter(args.indenter_modulus, args.indenter_nu)
    if ratio != float("inf"):
        kwargs["indenter_modulus"], kwargs["indenter_nu"] = ratio, nu1
    kwargs.update(_profile_kwargs(args))
    try:
        fretting_api.check_input(kwargs["geometry"], kwargs["friction"], kwargs["load_path"],
                                 kwargs["tangential_path"], kwargs["steps"], kwargs["n"],
                                 kwargs.get("bulk_stress"), kwargs["max_error"],
                                 nu=kwargs["nu"], indenter_modulus=ratio, indenter_nu=nu1)
    except validate.SolverLimit as exc:  # the sphere's coupled tangential load: status 3
        raise SolverLimitError(exc) from exc
    except ValueError as exc:
        raise UsageError(str(exc)) from None
    return kwargs


def format_fretting(res: Any) -> str:
    """Summary of a fretting path: the state at every path point, and the cycles' work."""
    lines = [f"fretting of the {res.geometry}: nu = {res.nu:g}, k = {res.friction:g}, "
             f"beta = {res.beta:.4g}, n = {res.n}, {res.steps} steps a segment",
             "point  P/P_max  Q/(kP_max)  c/a (estimate)       e/a_max   "
             "frictional work (estimate)  resolved"]
    for i, j in enumerate(res.point_step):
        lines.append(
            f"{i:5d}  {res.load_ratio[j]:7.4g}  {res.force_ratio[j]:10.4g}  "
            f"{res.stick_ratio[j]:8.5f} ({res.stick_ratio_error[i]:.1e})  "
            f"{res.stick_offset[j]:9.2e}  {res.dissipation[j]:12.5e} "
            f"({res.dissipation_error[i]:.1e})  {'yes' if res.resolved[i] else 'NO'}")
    for i, j, work, err in res.cycles:
        lines.append(f"cycle from point {i} to {j}: frictional work {work:.5e} "
                     f"(estimate {err:.1e}; units "
                     + ("E* a_max^5/R^2)" if res.geometry == "sphere"
                        else "E* a_max^4/R^2 per unit length)"))
    failed = int(res.converged.size - res.converged.sum())
    if failed:
        lines.append(f"{failed} steps did not converge; their values "
                     "are not data")
    if not res.all_resolved:
        lines.append(f"not every point is resolved to max_error = {res.max_error:g}: refine "
                     f"with --n {2 * res.n} --steps {2 * res.steps}")
    return "\n".join(lines)


def _run_physical_fretting(args: argparse.Namespace) -> int:
    """``history --tangential-path`` with forces in N (:mod:`contactlib.physical_fretting`)."""
    from contactlib import io, physical_fretting

    for option, given in (("--nu", args.nu is not None),
                          ("--indenter-modulus", args.indenter_modulus != "inf"),
                          ("--indenter-nu", args.indenter_nu is not None),
                          ("--slab-ratio", args.slab_ratio not in (None, "0")),
                          ("--thickness", args.thickness is not None),
                          ("--relaxation", args.relaxation is not None)):
        if given:
            raise UsageError(f"{option} is not used with a fretting path in newtons (--radius, "
                             f"--length, --indenter, --body give the problem), got {option}")
    if args.geometry != "cylinder":
        raise UsageError(f"--tangential-path is solved for the cylinder only, got --geometry "
                         f"{args.geometry}")
    kwargs: dict[str, Any] = {
        "radius": _required(args.radius, "--radius"),
        "length": _required(args.length, "--length"),
        "load_path": args.load_path, "tangential_path": args.tangential_path,
        "indenter": "rigid" if args.indenter is None else args.indenter,
        "body": _required(args.body, "--body"),
        "friction": parse_friction(args.friction),
        "steps": 40 if args.steps is None else parse_steps(args.steps),
        "max_error": parse_max_error(args.max_error)}
    if args.n is not None:
        kwargs["n"] = _int(args.n)
    if args.bulk_stress is not None:
        kwargs["bulk_stress"] = args.bulk_stress
    with _progress("fretting") as progress:
        res = physical_fretting.physical_fretting(progress=progress, **kwargs)
    if args.output is not None:
        io.write_dataset(io.physical_fretting_to_dataset(res), args.output)
    print(res.summary())
    _wrote(args.output)
    return 0


def _wrote(output: str | None) -> None:
    """The line that says where the dataset went (or that none was asked for)."""
    print(f"wrote {output}" if output is not None else "(no --output: nothing written)")


def _run_fretting(kwargs: dict[str, Any], output: str | None) -> int:
    from contactlib import fretting_api, io

    with _progress("fretting") as progress:
        res = fretting_api.fretting(progress=progress, **kwargs)
    if output is not None:
        io.write_dataset(io.fretting_to_dataset(res), output)
    print(format_fretting(res))
    _wrote(output)
    return 0


def _required(value: str | None, option: str) -> str:
    """``value``, or a usage error naming the missing ``option``."""
    if value is None:
        raise UsageError(f"the following arguments are required: {option}")
    return value


# --------------------------------------------------------------------------
# physical units (contactlib.physical)
# --------------------------------------------------------------------------

_PHYSICAL = ("radius", "load", "indenter", "body", "length", "thickness", "times",
             "substrate")
_UNIT_RE = re.compile(r"^\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?\s*[A-Za-zµμ]+\s*$")


def _path_has_units(text: str) -> bool:
    """A load path with a number and a unit anywhere (``0N,100N,0N``): forces, not levels
    (``0,x`` is a bad list of levels, not a force path)."""
    return any(_UNIT_RE.match(item) for item in text.split(","))


def is_physical(args: argparse.Namespace) -> bool:
    """True when any physical option is given, or a history's load path has units."""
    if any(getattr(args, name, None) is not None for name in _PHYSICAL):
        return True
    if args.command != "history":
        return False
    return any(text is not None and _path_has_units(text)
               for text in (args.load_path, args.amplitude, args.mean))


def _physical_check(rule: Callable[..., Any], *args: Any) -> Any:
    """``rule(*args)`` of :mod:`contactlib.physical`, its errors as usage errors."""
    try:
        return rule(*args)
    except ValueError as exc:
        raise _usage(exc) from None


def _validate_physical(args: argparse.Namespace) -> dict[str, Any]:
    """Checked keyword arguments of :func:`contactlib.physical.physical_solve` or
    :func:`~contactlib.physical.physical_history` (the physical options replace --nu,
    --indenter-modulus, --indenter-nu and --slab-ratio)."""
    from contactlib import physical

    geometry = _check(validate.geometry, args.geometry, args.geometry)
    for option, given in (("--nu", args.nu is not None),
                          ("--indenter-modulus", args.indenter_modulus != "inf"),
                          ("--indenter-nu", args.indenter_nu is not None),
                          ("--slab-ratio", args.slab_ratio != "0"),
                          ("--substrate-modulus",
                           getattr(args, "substrate_modulus", None) is not None),
                          ("--substrate-nu", getattr(args, "substrate_nu", None) is not None),
                          ("--profile", getattr(args, "profile", "paraboloid") != "paraboloid"
                           or getattr(args, "exponent", None) is not None)):
        if given:
            raise UsageError(f"{option} is not used with physical units (--radius, --body, "
                             f"--indenter, --thickness give the problem), got {option} with "
                             "them")
    radius = _physical_check(physical.parse_quantity, _required(args.radius, "--radius"),
                             "length", "radius")
    body = _physical_check(physical.material, _required(args.body, "--body"), "body")
    indenter = _physical_check(physical.material,
                               "rigid" if args.indenter is None else args.indenter, "indenter")
    kwargs: dict[str, Any] = {"geometry": geometry, "radius": radius, "indenter": indenter,
                              "body": body, "base": parse_base(args.base, coated=True),
                              "max_error": parse_max_error(args.max_error)}
    if geometry == "cylinder":
        kwargs["length"] = _physical_check(physical.parse_quantity,
                                           _required(args.length, "--length"), "length",
                                           "length")
    elif args.length is not None:
        raise UsageError(f"--length is for a cylinder only, got --length {args.length!r} "
                         "with --geometry sphere")
    if args.thickness is not None:
        kwargs["thickness"] = _physical_check(physical.parse_quantity, args.thickness,
                                              "length", "thickness")
    if args.substrate is not None:
        kwargs["substrate"] = _physical_check(physical.material, args.substrate, "substrate")
    if args.command == "solve":
        kwargs["load"] = _physical_check(physical.parse_quantity,
                                         _required(args.load, "--load"), "force", "load")
        method = _check(validate.method, args.method, args.method)
        kwargs.update(method=method, n=None if args.n is None else parse_n(args.n, method),
                      energy=not args.no_energy)
        if args.tolerance is not None:
            kwargs["tolerance"] = parse_tolerance(args.tolerance)
        if args.stick_ratio is not None:
            kwargs["stick_ratio"] = parse_fraction("--stick-ratio", args.stick_ratio)
        else:
            kwargs["friction"] = parse_friction(args.friction)
        return kwargs
    shaped = _path_source(args) != "--load-path"
    if shaped:
        forces: Any = parse_history_path(args, physical=True)
    elif not _path_has_units(args.load_path):
        raise UsageError(f"--load-path must be forces with a unit (0N,100N,0N) with physical "
                         f"units, got {args.load_path!r}")
    elif any(not _path_has_units(item) and item.strip() not in ("0",)
             for item in args.load_path.split(",")):
        raise UsageError(f"--load-path must give every force with its unit (0N,100N,0N), "
                         f"got {args.load_path!r}")
    else:
        forces = _physical_check(physical.parse_force_path, args.load_path)
    kwargs.update(load_path=forces, friction=parse_friction(args.friction),
                  steps=parse_steps(args.steps) if args.steps is not None
                  else physical.DEFAULT_HISTORY_STEPS,
                  n=None if args.n is None else parse_history_n(args.n))
    if args.duration is not None:
        raise UsageError(f"--duration is not used with physical units: give --times (s), got "
                         f"--duration {args.duration!r}")
    if shaped and args.times is not None:
        raise UsageError("--times is not used with --load-shape or --load-table: the path "
                         f"gives its times, got --times {args.times!r}")
    if not shaped and (args.relaxation is None) != (args.times is None):
        missing = "--times" if args.times is None else "--relaxation"
        raise UsageError(f"--relaxation and --times go together with physical units: "
                         f"{missing} is missing")
    if args.relaxation is not None:
        pairs: list[Any] = []
        for item in args.relaxation.split(","):
            parts = item.split(":")
            if len(parts) != 2:
                raise UsageError(f"--relaxation must be G1:TAU1[,G2:TAU2...], got "
                                 f"{args.relaxation!r}")
            tau = _physical_check(physical.parse_quantity, parts[1].strip(), "time",
                                  "relaxation")
            pairs.append([_float(parts[0]), tau])
        kwargs["relaxation"] = _check(validate.relaxation, args.relaxation, pairs)
        if shaped:
            return kwargs

        def when(text: str) -> float:
            return physical.parse_quantity(text.strip(), "time", "times", positive=False)

        times = [_physical_check(when, t) for t in args.times.split(",")]
        if len(times) != len(forces) or any(b <= a for a, b in zip(times, times[1:])):
            raise UsageError(f"--times must give {len(forces)} increasing times, one a "
                             f"--load-path point, got {args.times!r}")
        kwargs["times"] = times
    return kwargs


def _warned(run: Callable[[], Any]) -> Any:
    """``run()``, its validity warnings as one line each on stderr (``contactlib: warning:``)."""
    import warnings

    from contactlib.physical import SmallStrainWarning

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", SmallStrainWarning)
        result = run()
    for w in caught:
        if issubclass(w.category, SmallStrainWarning):
            print(f"{PROG}: warning: {' '.join(str(w.message).split())}", file=sys.stderr)
        else:
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    return result


def _run_physical(kwargs: dict[str, Any], output: str | None, command: str) -> int:
    from contactlib import physical

    if command == "history":
        with _progress("history") as progress:
            res = _warned(lambda: physical.physical_history(progress=progress, **kwargs))
    else:
        try:
            with _ticker(sys.stderr, "solve"):
                res = _warned(lambda: physical.physical_solve(**kwargs))
        except validate.SolverLimit as exc:  # valid input beyond the method: status 3
            raise SolverLimitError(exc) from exc
        except ValueError as exc:
            raise _usage(exc) from exc
    if output is not None:
        from contactlib import io

        io.write_dataset(io.physical_to_dataset(res), output)
    print(res.summary())
    if output is not None:
        print(f"  wrote {output}")
    return 0


def parse_relaxation(text: str) -> tuple[tuple[float, float], ...]:
    """``g1:tau1,g2:tau2`` as Prony pairs (:func:`contactlib.validate.relaxation`)."""
    pairs: list[Any] = []
    for item in text.split(","):
        parts = item.split(":")
        pairs.append([_float(v) for v in parts] if len(parts) == 2 else item)
    return _check(validate.relaxation, text, pairs)


def parse_viscoelastic(relaxation: str | None, duration: str | None,
                       segments: int) -> dict[str, Any]:
    """``relaxation`` and ``duration`` keywords from ``--relaxation`` and ``--duration``."""
    prony = () if relaxation is None else parse_relaxation(relaxation)
    value: Any = None
    if duration is not None:
        items = _list(duration)
        value = items[0] if len(items) == 1 else items
    durations = _check(validate.duration, duration, value, segments, bool(prony))
    return {"relaxation": [list(p) for p in prony], "duration": list(durations)}


def _shorten(text: str, limit: int = 80) -> str:
    return text if len(text) <= limit else text[:limit // 2 - 2] + "..." + text[-(limit // 2 - 1):]


def check_output(text: str | None) -> None:
    """Refuse an ``--output`` that could not be written, before any computing.

    Missing parent folders are allowed (the writer creates them); an
    unwritable place, a path through a file, a folder, an existing path that
    is not a regular file (a symbolic link, a named pipe, a device such as
    ``/dev/null``, which the write would replace), or a name too long
    (:func:`contactlib.io.check_writable`) is a :class:`UsageError` naming
    ``--output``. Nothing is left on the disk.
    """
    if text is None:
        return
    if text.strip() == "":
        raise UsageError(f"--output must be a file path, got {text!r}")
    from contactlib.io import check_writable

    try:
        check_writable(text)
    except OSError as exc:
        raise UsageError(f"--output: {str(exc).replace(text, _shorten(text))}") from None


# --------------------------------------------------------------------------
# output formatting
# --------------------------------------------------------------------------


def _count(number: int, noun: str) -> str:
    """``1 iteration``, ``2 iterations``."""
    return f"{number} {noun}" + ("" if number == 1 else "s")


def _yes(flag: bool) -> str:
    return "yes" if flag else "no"


def _g(value: float, digits: int = 6) -> str:
    return "inf" if math.isinf(value) else f"{value:.{digits}g}"


def _k_digits(error: float) -> int:
    """Significant digits of k worth printing: 6, more where its error estimate is smaller."""
    if not (math.isfinite(error) and error > 0.0):
        return 6
    return int(min(12, max(6, math.ceil(-math.log10(error)) + 1)))


def _indenter(geometry: str) -> Any:
    from contactlib.indenter import indenter

    return indenter(geometry)


def _head(sol: Solution, n_text: str | None = None) -> str:
    """``sphere, nu = 0.3, method = default, n = 256`` (and a/h where a layer is possible;
    ``n_text`` in place of ``n = 256``)."""
    n_text = f"n = {sol.n}" if n_text is None else n_text
    head = f"{sol.geometry}, nu = {sol.nu:.10g}, method = {sol.method}, {n_text}"
    if _indenter(sol.geometry).reports_layer(sol.slab_ratio):
        head += f", a/h = {sol.slab_ratio:g}"
    if sol.slab_ratio > 0:
        head += f" ({getattr(sol, 'base', 'smooth')} base{substrate_text(sol)})"
    if getattr(sol, "profile", "paraboloid") != "paraboloid":
        head += f", profile = {sol.profile} (d = {sol.exponent:g})"
    return head + _indenter_text(sol)


def format_summary(sol: Solution) -> str:
    """Human-readable summary of one solution (several lines)."""
    work_scale = f"V R^2/(E* a^{_indenter(sol.geometry).work_exponent})"
    if getattr(sol, "profile", "paraboloid") != "paraboloid":  # h = A r^d
        power = 2.0 * sol.exponent + (1.0 if sol.geometry == "sphere" else 0.0)
        work_scale = f"V/(E* (A d)^2 a^{power:g}), h = A r^d"
    lines = [
        _head(sol),
        f"  c/a    = {_g(sol.stick_ratio)}",
        f"  k      = {_g(sol.friction_coefficient, _k_digits(sol.error_estimate))}   "
        "(estimated relative error "
        f"{sol.error_estimate:.1e}; resolved: {_yes(sol.resolved)}, max error "
        f"{sol.max_error:g})",
        f"  P/P_H  = {_g(sol.load_ratio)}",
        f"  V      = {_g(sol.frictional_work)}   ({work_scale})",
        f"  slip direction ok: {_yes(sol.slip_direction_ok)}, "
        f"stick admissible: {_yes(sol.stick_admissible)}, "
        f"consistent: {_yes(sol.consistent)}",
        f"  converged: {_yes(sol.converged)} "
        f"(residual {sol.residual_norm:.3g}, {_count(sol.iterations, 'iteration')})",
    ]
    if sol.message:
        lines.append(f"  message: {sol.message}")
    return "\n".join(lines)


def format_table(solutions: Sequence[Solution]) -> str:
    """Compact table of a sweep, one row per stick ratio."""
    if not solutions:
        return "(no points)"
    by_case = len({s.n for s in solutions}) > 1  # a sweep to a tolerance, n by stick ratio
    head = _head(solutions[0], "n by stick ratio" if by_case else None)
    ks = [_g(s.friction_coefficient, _k_digits(s.error_estimate)) for s in solutions]
    wide = max(11, *(len(k) for k in ks))  # k to the digits its estimate supports
    cols = (f"{'c/a':>8}" + (f" {'n':>5}" if by_case else "")
            + f" {'k':>{wide}} {'P/P_H':>11} {'V':>11} "
            f"{'slip':>4} {'stick':>5} {'cons':>4} {'conv':>4} {'residual':>9} "
            f"{'k error':>8} {'res':>3}")
    rows = [head, cols]
    for s, k in zip(solutions, ks):
        row = (f"{s.stick_ratio:8.4f}" + (f" {s.n:5d}" if by_case else "")
               + f" {k:>{wide}} "
               f"{_g(s.load_ratio):>11} {_g(s.frictional_work):>11} "
               f"{_yes(s.slip_direction_ok):>4} {_yes(s.stick_admissible):>5} "
               f"{_yes(s.consistent):>4} {_yes(s.converged):>4} "
               f"{s.residual_norm:9.2e} {s.error_estimate:8.1e} {_yes(s.resolved):>3}")
        if s.message:
            row += f"  {s.message}"
        rows.append(row)
    return "\n".join(rows)


def format_history(res: Any) -> str:
    """Summary of a history: the state at the end of every path segment, and the work."""
    ind = _indenter(res.geometry)
    work_scale = f"V R^2/(E* a_max^{ind.work_exponent})"
    head = (f"{res.geometry}, nu = {res.nu:.10g}, k = {_g(res.friction)}, n = {res.n}, "
            f"{res.steps} steps per "
            f"{'load travel of P_max' if getattr(res, 'segment_steps', ()) else 'segment'}")
    if getattr(res, "load_shape", None):  # a shape or table (contactlib.load_paths)
        head += ", path " + ", ".join(f"{k} {_g(v) if not isinstance(v, str) else v}"
                                      for k, v in res.load_shape.items())
    if getattr(res, "profile", "paraboloid") != "paraboloid":  # h = A r^d, or the flat punch
        shape = res.profile_shape()
        work_scale = shape.work_unit(res.geometry == "sphere")
        head += f", profile = {res.profile}" + shape.label()
    if ind.reports_layer(res.slab_ratio):
        head += f", a_max/h = {res.slab_ratio:g}"
    if res.slab_ratio > 0:
        head += f" ({getattr(res, 'base', 'smooth')} base{substrate_text(res)})"
    head += _indenter_text(res)
    errors = getattr(res, "work_error_estimate", None)
    shown = errors is not None and any(math.isfinite(float(e)) for e in errors)
    zero_below = _zero_work(res)
    zeros = shown and any(abs(float(res.frictional_work[res.segment_end(i)])) <= zero_below
                          for i in range(1, len(res.load_path)))
    rows = [head, f"{'segment':>7} {'P/P_max':>9} {'a/a_max':>9} {'c/a':>8} "
                  f"{'V segment':>11} {'V total':>11}" + (f" {'V error':>8}" if shown else "")]
    seg_work = res.segment_work()
    for i in range(1, len(res.load_path)):
        j = res.segment_end(i)
        rows.append(f"{i:7d} {res.load_ratio[j]:9.4f} {res.contact_radius[j]:9.5f} "
                    f"{_g(float(res.stick_ratio[j]), 5):>8} {seg_work[i - 1]:11.5g} "
                    f"{res.frictional_work[j]:11.5g}"
                    + (f" {_relative_text(float(errors[j]), res.frictional_work[j], zero_below)}"
                       if shown else ""))
    total = res.converged.size - 1
    rows.append(f"  work in {work_scale}" + ("; V error: estimated error of V total relative to "
                                             "the path's total work" if shown else "")
                + ("; (zero): V total is zero at its scale" if zeros else "")
                + "; converged steps: "
                f"{int(res.converged[1:].sum())}/{total} "
                f"(at most {_count(int(res.iterations.max()), 'iteration')})")
    if getattr(res, "relaxation", ()):  # a viscoelastic body: its time and energies
        rows.append(f"  viscoelastic: relaxation {list(map(list, res.relaxation))}, duration "
                    f"{res.time[-1]:g}; at the end, in {work_scale}: external "
                    f"{res.external_work[-1]:.5g} = stored {res.stored_energy[-1]:.5g} + "
                    f"viscous {res.viscous_work[-1]:.5g} + frictional "
                    f"{res.frictional_work[-1]:.5g}")
    if res.resolved is not None:
        rows.append(f"  resolved steps (max error {res.max_error:g}): "
                    f"{int(res.resolved[1:].sum())}/{total}")
    verdicts = getattr(res, "resolved_quantities", None)
    if verdicts:
        rows.append("  resolved quantities: " + ", ".join(
            f"{name.replace('_', ' ')} {_yes(ok)}" for name, ok in verdicts.items()))
    if res.message:
        rows.append(f"  message: {res.message}")
    return "\n".join(rows)


def _zero_work(res: Any) -> float:
    """The frictional work of a history at or below which it is zero at its scale: a
    fraction ``WORK_FLOOR`` of the path's largest external work (0 where unknown)."""
    from contactlib.history_api import WORK_FLOOR

    scale = float(getattr(res, "energy_scale", math.nan))
    return WORK_FLOOR * scale if math.isfinite(scale) else 0.0


def _relative_text(error: float, value: float, zero_below: float = 0.0) -> str:
    """An 8-character relative error, or ``(zero)`` for a value that is zero at its scale
    (no relative error is printed for it)."""
    if abs(float(value)) <= zero_below:
        return f"{'(zero)':>8}"
    return f"{error:8.1e}"


@contextmanager
def _ticker(stream: TextIO, label: str, after: float = 2.0, every: float = 1.0):
    """On a terminal, a line ``label: N s`` updated every ``every`` seconds once the work
    has taken ``after`` seconds, cleared on the way out; nothing when not a terminal.

    For the one-case commands (``solve``), whose inverse search (``--friction``) runs
    for up to about 15 s with no count to show.
    """
    import threading
    import time

    try:
        tty = stream.isatty()
    except (AttributeError, ValueError):
        tty = False
    if not tty:
        yield
        return
    done = threading.Event()
    start = time.monotonic()
    shown = threading.Event()

    def tick() -> None:
        while not done.wait(after if not shown.is_set() else every):
            stream.write(f"\r{label}: {time.monotonic() - start:.0f} s")
            stream.flush()
            shown.set()

    thread = threading.Thread(target=tick, daemon=True)
    thread.start()
    try:
        yield
    finally:
        done.set()
        thread.join()
        if shown.is_set():
            stream.write("\r\033[K")
            stream.flush()


def _progress_printer(stream: TextIO, label: str = "sweep") -> Callable[[int, int], None] | None:
    """A ``progress(i, total)`` callback with ``\\r`` updates, TTY only."""
    try:
        tty = stream.isatty()
    except (AttributeError, ValueError):
        tty = False
    if not tty:
        return None

    def progress(i: int, total: int) -> None:
        stream.write(f"\r{label}: {i}/{total}")
        stream.flush()

    return progress


# --------------------------------------------------------------------------
# commands
# --------------------------------------------------------------------------


def _api() -> ModuleType:
    """Import the library API lazily (so ``--help`` never needs it)."""
    from contactlib import api

    return api


def _write(obj: Solution | Sequence[Solution], output: str) -> None:
    from contactlib import io

    io.write_dataset(io.to_dataset(obj), output)


def _silence_stdout() -> None:
    """Point stdout at /dev/null, so that the interpreter's last flush cannot fail again."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):  # no real file descriptor (e.g. captured in a test)
        pass


def _run_solve(kwargs: dict[str, Any], output: str | None, api: ModuleType,
               subsurface: bool = False) -> int:
    try:
        if subsurface:  # before any numerics: refuses a missing --output
            from contactlib.stresses import check_subsurface_request
            check_subsurface_request(output, kwargs.get("slab_ratio", 0.0),
                                     kwargs.get("base", "smooth"))
        with _ticker(sys.stderr, "solve"):
            sol = api.solve(**kwargs)
    except validate.SolverLimit as exc:  # valid input beyond the method: status 3
        raise SolverLimitError(exc) from exc
    except ValueError as exc:  # the library's own input validation
        raise _usage(exc) from exc
    if output is not None and subsurface:  # the solve's dataset and the stress field
        from contactlib import io, stresses
        io.write_dataset(stresses.with_subsurface(io.to_dataset(sol), sol), output)
    elif output is not None:  # the file first: a closed pipe on stdout must not lose it
        _write(sol, output)
    print(format_summary(sol))
    if output is not None:
        print(f"  wrote {output}")
    return 0


@contextmanager
def _progress(label: str):
    """A progress printer on a terminal (else None); library ValueErrors become usage errors.

    The progress line is cleared on the way out, whatever happens.
    """
    progress = _progress_printer(sys.stderr, label)
    try:
        yield progress
    except validate.SolverLimit as exc:  # valid input beyond the method: status 3
        raise SolverLimitError(exc) from exc
    except ValueError as exc:  # the library's own input validation
        raise _usage(exc) from exc
    finally:
        if progress is not None:
            sys.stderr.write("\r\033[K")
            sys.stderr.flush()


def _run_sweep(kwargs: dict[str, Any], output: str, api: ModuleType) -> int:
    ratios = kwargs.pop("stick_ratios")
    with _progress("sweep") as progress:
        sols = api.sweep(kwargs.pop("geometry"), kwargs.pop("nu"), ratios,
                         progress=progress, **kwargs)
    _write(sols, output)
    print(format_table(sols))
    print(f"wrote {output}")
    return 0


def _history_api() -> ModuleType:
    """Import the history module lazily (so ``--help`` never needs it)."""
    from contactlib import history_api

    return history_api


def _run_history(kwargs: dict[str, Any], output: str | None, module: ModuleType) -> int:
    try:
        with _progress("history") as progress:
            res = module.history(progress=progress, **kwargs)
    except validate.SolverLimit as exc:  # a tolerance planned beyond the largest n: status 3
        raise SolverLimitError(exc) from exc
    from contactlib import io

    if output is not None:
        io.write_dataset(io.history_to_dataset(res), output)
    print(format_history(res))
    _wrote(output)
    if getattr(res, "tolerance_met", None) is False:  # written, flagged, and status 3
        from contactlib.history_plan import reached_tolerance

        reach = reached_tolerance(res)
        written = (f"the dataset {output} is written with its steps flagged"
                   if output is not None else "its steps are flagged")
        raise SolverLimitError(validate.SolverLimit(
            f"{res.message.split('; ')[0]}; {written}",
            remedies=[("history", {"friction": res.friction, "tolerance": reach})]
            if reach is not None else []))
    return 0


def _merge(base: dict, extra: dict) -> dict:
    """``extra`` over ``base``, mappings merged key by key (as Snakemake merges configs)."""
    out = dict(base)
    for key, value in extra.items():
        if isinstance(value, dict) and isinstance(out.get(key), dict):
            out[key] = _merge(out[key], value)
        else:
            out[key] = value
    return out


def check_config(paths: Sequence[str]) -> list[str]:
    """Problems of workflow configuration files, one line each (empty: all good).

    Each file's YAML syntax is checked on its own; the files are then merged
    in the given order, mappings key by key as ``snakemake --configfile``
    merges them, and the scenes of the result are checked by the library's
    rules. To check a file meant to be merged with the workflow's own
    configuration, give ``config/config.yaml`` first.

    Parameters
    ----------
    paths : sequence of str
        YAML files.

    Returns
    -------
    list of str
        ``<file>, line L, column C: YAML syntax error: ...``, a missing file, a
        top level that is not a mapping, a bad ``results_dir``, or
        ``scenes.<name>.<key>: ...`` for each problem of a scene
        (:func:`contactlib.scene.parse_scenes`).
    """
    from pathlib import Path

    from contactlib.io import check_yaml
    from contactlib.scene import parse_scenes

    problems: list[str] = []
    merged: dict = {}
    for path in paths:
        try:
            doc = check_yaml(path)
        except ValueError as exc:
            problems.append(str(exc))
            continue
        if doc is None and not Path(path).is_file():
            problems.append(f"{path}: no such file")
        elif not isinstance(doc, dict):
            problems.append(f"{path}: the top level must be a mapping (scenes:, figures:, ...)")
        else:
            merged = _merge(merged, doc)
    if not problems and "results_dir" in merged:  # the folder of every output
        try:
            validate.results_dir(merged["results_dir"])
        except ValueError as exc:
            problems.append(f"results_dir: {exc}")
    if not problems and merged.get("scenes") is not None:
        try:
            parse_scenes(merged["scenes"])
        except ValueError as exc:
            problems += list(getattr(exc, "problems", [str(exc)]))
    return problems


def _run_check_config(paths: Sequence[str]) -> int:
    problems = check_config(paths)
    for line in problems:
        _fail(line)
    if not problems:
        print(f"{', '.join(paths)}: no problems found")
    return 2 if problems else 0


def _fail(message: str) -> None:
    print(f"{PROG}: error: {' '.join(str(message).split())}", file=sys.stderr)


_FLAGS = ("--no-energy", "--subsurface", "--debug")
# options both commands take with another meaning: history's n counts elements over
# 1.2 a_max, not across the contact
_OTHER_MEANING = ("--n",)


def _taken(command: str) -> set[str]:
    """The options ``contactlib <command>`` takes (read from the parser)."""
    parser = build_parser()
    subparsers = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return {o for a in subparsers.choices[command]._actions for o in a.option_strings}


def _options(tokens: Sequence[str]) -> list[tuple[str, str | None]]:
    """A command's arguments as ``(option, value)`` pairs (value None for a flag)."""
    out: list[tuple[str, str | None]] = []
    i = 0
    while i < len(tokens):
        tok = tokens[i]
        if tok.startswith("--") and "=" in tok:
            out.append(tuple(tok.split("=", 1)))  # type: ignore[arg-type]
        elif tok in _FLAGS or not tok.startswith("--") or i + 1 == len(tokens):
            out.append((tok, None))
        else:
            out.append((tok, tokens[i + 1]))
            i += 1
        i += 1
    return out


def _text(value: Any) -> str:
    """An argument's value as a command line writes it (0.5, 1, 0,1)."""
    if isinstance(value, (list, tuple)):
        return ",".join(_text(v) for v in value)
    text = repr(float(value)) if isinstance(value, float) else str(value)
    return text[:-2] if text.endswith(".0") else text


def _remedy_command(argv: Sequence[str], args: argparse.Namespace, command: str,
                    changes: dict[str, Any]) -> str | None:
    """The command line of a remedy of :class:`~contactlib.validate.SolverLimit`: the
    user's arguments with ``changes`` (library names), or None if our own input
    rules would refuse it."""
    import shlex

    start = list(argv).index(args.command) + 1
    drop = {"--friction", "--stick-ratio", "--output", "--debug"}
    if command != args.command:
        drop.update(_OTHER_MEANING)
    taken = _taken(command)
    given = _options(argv[start:])
    opts = [(o, v) for o, v in given if o not in drop and o in taken]
    physical = is_physical(args)
    for name, value in changes.items():
        option = _option(name)
        opts = [(o, v) for o, v in opts if o != option]
        text = _text(value)
        if name == "load_path" and physical:  # a path in newtons up to the given load
            load = dict(given).get("--load") or ""
            opts = [(o, v) for o, v in opts if o != "--load"]
            unit = "" if load and not load[-1].isdigit() and load[-1] != "." else "N"
            text = ",".join(("0N" if v == 0 else f"{load}{unit}") for v in value)
        opts.append((option, text))
    if command == "history":  # steps, unless the tolerance plans them
        if not physical and "tolerance" not in changes and "--tolerance" not in dict(opts):
            opts.append(("--steps", "200"))
        opts.append(("--output", "history.nc"))
    elif args.output is not None:
        opts.append(("--output", args.output))
    tokens = [command] + [t for o, v in opts for t in ((o,) if v is None else (o, v))]
    try:  # only a command that our own input rules accept
        new = build_parser().parse_args(tokens)
        if is_physical(new):
            _validate_physical(new)
        elif command == "history" and new.tolerance is not None:
            _validate_planned_history(new)
        elif command == "history":
            _validate_history(new)
        else:
            _validate(new)
    except UsageError:
        return None
    return " ".join([PROG] + [shlex.quote(t) for t in tokens])


def _run_limit(exc: SolverLimitError, argv: Sequence[str], args: Any) -> int:
    """Report a solver limit: the reason, then the commands that answer the case."""
    _fail(str(exc))
    if args is not None:
        for command, changes in getattr(exc.limit, "remedies", ()):
            line = _remedy_command(argv, args, command, changes)
            if line is not None:
                print(f"{PROG}: answer it with: {line}", file=sys.stderr)
    return EXIT_SOLVER_LIMIT


def main(argv: list[str] | None = None) -> int:
    """Run the command line.

    Parameters
    ----------
    argv : list of str, optional
        Arguments without the program name; ``sys.argv[1:]`` by default.

    Returns
    -------
    int
        0 on success; 2 (:data:`EXIT_BAD_INPUT`) on bad input (one line on
        stderr); 3 (:data:`EXIT_SOLVER_LIMIT`) on valid input the solver
        cannot answer (:class:`contactlib.validate.SolverLimit`: its reason,
        then a line ``contactlib: answer it with: contactlib ...`` for each
        command that answers it); 1 on an unexpected error; 130 when
        interrupted; 141 when stdout's reader went away.
    """
    argv = list(sys.argv[1:] if argv is None else argv)
    debug = "--debug" in argv
    args = None
    try:
        try:
            args = build_parser().parse_args(argv)
        except SystemExit as exc:  # --help
            return int(exc.code or 0) if not isinstance(exc.code, str) else 2
        debug = bool(getattr(args, "debug", False))
        if args.command == "check-config":
            return _run_check_config(args.files)
        if args.command == "history" and args.tolerance is not None and (
                args.tangential_path is not None or is_physical(args)):
            raise UsageError("--tolerance plans a dimensionless history of a normal load path "
                             "(--nu, load levels): give it without --tangential-path and the "
                             "physical options")
        if args.command == "history" and (args.tangential_path is not None
                                          or args.bulk_stress is not None):
            if args.tangential_path is None:
                raise UsageError("--bulk-stress needs --tangential-path (give 0s for none)")
            if is_physical(args) or _path_has_units(args.tangential_path):
                check_output(args.output)
                return _run_physical_fretting(args)
            fret_kwargs = _validate_fretting(args)  # before any numerics
            check_output(args.output)
            return _run_fretting(fret_kwargs, args.output)
        if args.command in ("solve", "history") and is_physical(args):
            if getattr(args, "subsurface", False):
                raise UsageError("--subsurface must be given without --body (physical "
                                 "input), got both")
            phys_kwargs = _validate_physical(args)  # before any numerics
            check_output(args.output)
            return _run_physical(phys_kwargs, args.output, args.command)
        if args.command == "history":
            hist_kwargs = (_validate_planned_history(args) if args.tolerance is not None
                           else _validate_history(args))  # before importing the numerics
            check_output(args.output)
            return _run_history(hist_kwargs, args.output, _history_api())
        kwargs = _validate(args)  # before importing the numerics
        api = _api()
        check_output(args.output)
        if args.command == "solve":
            return _run_solve(kwargs, args.output, api, args.subsurface)
        return _run_sweep(kwargs, args.output, api)
    except UsageError as exc:
        _fail(str(exc))
        return EXIT_BAD_INPUT
    except SolverLimitError as exc:
        return _run_limit(exc, argv, args)
    except KeyboardInterrupt:
        _fail("interrupted")
        return 130
    except BrokenPipeError:  # the reader of stdout went away (`| head`): stop quietly
        _silence_stdout()
        return 141  # 128 + SIGPIPE, what a shell reports for a writer killed by it
    except Exception as exc:  # noqa: BLE001 - last-resort, one line
        _fail(f"{type(exc).__name__}: {exc}")
        if debug:
            traceback.print_exc()
        return 1
