"""The commands that answer a case beyond a solver limit (exit status 3).

:func:`run_limit` reports a :class:`~contactlib.cli.inputs.SolverLimitError`:
its reason, then one line ``contactlib: answer it with: contactlib ...`` for
each remedy of the library's :class:`contactlib.validate.SolverLimit`, built
from the user's own arguments and shown only if our input rules accept it.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from typing import Any

from contactlib.cli.inputs import EXIT_SOLVER_LIMIT, PROG, SolverLimitError, UsageError, option_of
from contactlib.cli.parser import build_parser, options_taken
from contactlib.cli.arguments import (is_physical, validate_history, validate_physical,
                                      validate_planned_history, validate_solve)
from contactlib.cli.report import fail


_FLAGS = ("--no-energy", "--subsurface", "--debug")


# options both commands take with another meaning: history's n counts elements over
# 1.2 a_max, not across the contact
_OTHER_MEANING = ("--n",)


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
    taken = options_taken(command)
    given = _options(argv[start:])
    opts = [(o, v) for o, v in given if o not in drop and o in taken]
    physical = is_physical(args)
    for name, value in changes.items():
        option = option_of(name)
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
            validate_physical(new)
        elif command == "history" and new.tolerance is not None:
            validate_planned_history(new)
        elif command == "history":
            validate_history(new)
        else:
            validate_solve(new)
    except UsageError:
        return None
    return " ".join([PROG] + [shlex.quote(t) for t in tokens])


def run_limit(exc: SolverLimitError, argv: Sequence[str], args: Any) -> int:
    """Report a solver limit: the reason, then the commands that answer the case."""
    fail(str(exc))
    if args is not None:
        for command, changes in getattr(exc.limit, "remedies", ()):
            line = _remedy_command(argv, args, command, changes)
            if line is not None:
                print(f"{PROG}: answer it with: {line}", file=sys.stderr)
    return EXIT_SOLVER_LIMIT
