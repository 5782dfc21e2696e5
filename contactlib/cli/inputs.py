"""Option values of the command line: parsed and checked one at a time.

Every value is parsed here (no argparse ``type=``: the messages are our own)
and checked by the library's rule of :mod:`contactlib.validate`; a refused
value is a :class:`UsageError` of one line naming the option and showing the
value as typed. Also here: the exit statuses (:data:`EXIT_BAD_INPUT`,
:data:`EXIT_SOLVER_LIMIT`), the two exceptions the command line ends with
(:class:`UsageError`, :class:`SolverLimitError`), the load shapes and tables of
a history (:func:`parse_history_path`) and :func:`check_output`, which refuses
an unwritable ``--output`` before any computing.
"""

from __future__ import annotations

import argparse
import re
from collections.abc import Callable
from typing import Any

from contactlib import validate


PROG = "contactlib"


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


def option_of(name: str) -> str:
    """The option of a library argument: ``slab_ratio`` -> ``--slab-ratio``."""
    return "--" + name.replace("_", "-")


def usage(exc: ValueError, text: str | None = None) -> UsageError:
    """A library input error as a one-line usage error naming the option.

    The rule's name and requirement come from the exception's fields
    (:class:`contactlib.validate.InputError`), not from its text; the value
    is shown as the user typed it.
    """
    name = getattr(exc, "name", None)
    if name is None:
        return UsageError(str(exc))
    option = option_of(name)
    shown = exc.value if text is None else text
    if isinstance(shown, str) and len(shown) > 40:
        shown = shown[:37] + "..."
    standard = f"{name} must be {exc.requirement}, got {exc.value!r}"
    if str(exc) == standard:
        return UsageError(f"{option} must be {exc.requirement}, got {shown!r}")
    message = str(exc)
    return UsageError(option + message[len(name):] if message.startswith(name) else message)


def to_float(text: str) -> float | str:
    """The number a string spells, or the string itself (which the rule refuses)."""
    try:
        return float(text)
    except (TypeError, ValueError):
        return text


def to_int(text: str) -> int | str:
    """The integer a string spells (digits only), or the string itself."""
    return int(text) if _INT_RE.match(text) and len(text.strip()) <= 12 else text


def checked(rule: Callable[..., Any], text: str, value: Any, *args: Any) -> Any:
    """``rule(value, *args)``, its :class:`ValueError` as a usage error showing ``text``."""
    try:
        return rule(value, *args)
    except ValueError as exc:
        raise usage(exc, text) from None


def to_list(text: str) -> list[float | str]:
    return [to_float(item) for item in text.split(",")]


def parse_nu(text: str) -> float:
    """Poisson's ratio in (-1, 0.5]."""
    return checked(validate.nu, text, to_float(text))


def parse_max_error(text: str) -> float:
    """Accuracy asked for: a relative error of k in (0, 1)."""
    return checked(validate.max_error, text, to_float(text))


def parse_tolerance(text: str) -> float:
    """A relative error of k to reach, in [1e-9, 0.1] (:func:`validate.planned_tolerance`)."""
    return checked(validate.planned_tolerance, text, to_float(text))


def parse_fraction(option: str, text: str) -> float:
    """A stick ratio c/a in [0, 1] (``option``: ``--stick-ratio``)."""
    return checked(validate.stick_ratio, text, to_float(text), option.lstrip("-").replace("-", "_"))


def parse_friction(text: str) -> float:
    """Friction coefficient k >= 0 (``inf`` allowed: full adhesion)."""
    return checked(validate.friction, text, to_float(text))


def parse_slab_ratio(text: str, geometry: str | None = None, base: str = "smooth",
                     extent: float = 1.0) -> float:
    """Layer ratio a/h, finite, >= 0 (0 = half-space/half-plane), within the supported range."""
    return checked(validate.slab_ratio, text, to_float(text), geometry, base, extent)


def parse_base(text: str, coated: bool = False) -> str:
    """The layer's rigid base: smooth or bonded (``coated``: also elastic, a coated body)."""
    return checked(validate.base, text, text, coated)


def parse_substrate(args: argparse.Namespace, base: str, geometry: str,
                    method: str) -> dict[str, float]:
    """``substrate_modulus`` and ``substrate_nu`` of a coated body (``--base elastic``), checked
    by :func:`validate.substrate`; refused without it; {} on a rigid base."""
    modulus = None if args.substrate_modulus is None else to_float(args.substrate_modulus)
    nu2 = None if args.substrate_nu is None else to_float(args.substrate_nu)
    shown = {"substrate_modulus": args.substrate_modulus, "substrate_nu": args.substrate_nu,
             "method": method}
    try:
        modulus, nu2 = validate.substrate(base, modulus, nu2, geometry, method)
    except validate.InputError as exc:
        raise usage(exc, shown.get(exc.name, base)) from None
    if base != validate.COATED_BASE:
        return {}
    return {"substrate_modulus": modulus} | ({} if nu2 is None else {"substrate_nu": nu2})


def profile_kwargs(args: argparse.Namespace) -> dict[str, Any]:
    """``profile`` (and ``exponent``) keywords, only when not the paraboloid (the default)."""
    if args.profile == "paraboloid" and args.exponent is None and args.flat_ratio is None:
        return {}
    from contactlib.model import profiles

    exponent = None if args.exponent is None else to_float(args.exponent)
    flat = None if args.flat_ratio is None else to_float(args.flat_ratio)
    try:
        shape = profiles.profile(args.profile, exponent, flat)
    except ValueError as exc:  # shown with the option it names
        text = {"exponent": args.exponent, "flat_ratio": args.flat_ratio}.get(
            getattr(exc, "name", ""), args.profile)
        raise usage(exc, text) from None
    return {"profile": shape.name, **({"exponent": shape.exponent}
                                      if shape.name == "power" else {}),
            **({"flat_ratio": shape.flat} if shape.is_rounded else {})}


def parse_n(text: str, method: str = "default") -> int:
    """Number of elements of a self-similar solve, for ``method``."""
    return checked(validate.n, text, to_int(text), method)


def parse_history_n(text: str) -> int:
    """Number of elements of the history solver."""
    return checked(validate.history_n, text, to_int(text))


def parse_stick_ratios(text: str, n: int) -> str | list[float]:
    """``all`` or a comma-separated list of distinct numbers in [0, 1]."""
    if text.strip().lower() == "all":
        return "all"
    labels = [item.strip() for item in text.split(",")]
    return checked(validate.stick_ratios, text, to_list(text), n, labels)


def parse_load_path(text: str | None) -> list[float]:
    """Comma-separated load levels P/P_max in [0, 1], starting at 0 (at least two)."""
    if text is None:
        raise UsageError("--load-path is required here (comma-separated load levels, e.g. "
                         "0,1,0)")
    return list(checked(validate.load_path, text, to_list(text)))


_SHAPE_OPTIONS = ("amplitude", "mean", "frequency", "cycles", "ramp")


def path_source(args: argparse.Namespace) -> str:
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
    of a history, as the mapping of :mod:`contactlib.model.load_paths` (levels) or of
    :func:`contactlib.physical.force_shape` (forces, SI)."""
    from contactlib.model import load_paths

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
                spec[key] = value if physical and key != "cycles" else to_float(value)
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
    return checked(validate.steps, text, to_int(text))


def parse_indenter(modulus: str, nu: str | None) -> tuple[float, float | None]:
    """(E1/E2, nu1) from ``--indenter-modulus`` and ``--indenter-nu`` (nu1 None: the body's)."""
    try:
        return validate.indenter_material(to_float(modulus), None if nu is None else to_float(nu))
    except ValueError as exc:
        name = getattr(exc, "name", None)
        raise usage(exc, modulus if name == "indenter_modulus" else nu) from None


def required_value(value: str | None, option: str) -> str:
    """``value``, or a usage error naming the missing ``option``."""
    if value is None:
        raise UsageError(f"the following arguments are required: {option}")
    return value


def parse_relaxation(text: str) -> tuple[tuple[float, float], ...]:
    """``g1:tau1,g2:tau2`` as Prony pairs (:func:`contactlib.validate.relaxation`)."""
    pairs: list[Any] = []
    for item in text.split(","):
        parts = item.split(":")
        pairs.append([to_float(v) for v in parts] if len(parts) == 2 else item)
    return checked(validate.relaxation, text, pairs)


def parse_viscoelastic(relaxation: str | None, duration: str | None,
                       segments: int) -> dict[str, Any]:
    """``relaxation`` and ``duration`` keywords from ``--relaxation`` and ``--duration``."""
    prony = () if relaxation is None else parse_relaxation(relaxation)
    value: Any = None
    if duration is not None:
        items = to_list(duration)
        value = items[0] if len(items) == 1 else items
    durations = checked(validate.duration, duration, value, segments, bool(prony))
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
