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

One concern a module; :func:`main` is here, and every public name is
re-exported, so ``contactlib.cli.X`` and ``from contactlib.cli import X`` are
the way to use them:

* :mod:`contactlib.cli.inputs`: option values parsed and checked one at a time
  (``parse_nu``, ``parse_load_path``, ...), the exit statuses,
  :class:`UsageError`, :class:`SolverLimitError` and :func:`check_output`;
* :mod:`contactlib.cli.parser`: :func:`build_parser`, every subcommand, option
  and help text;
* :mod:`contactlib.cli.arguments`: a parsed namespace to the checked keyword
  arguments of one entry point (``is_physical`` and the ``validate_*`` functions);
* :mod:`contactlib.cli.report`: the printed summaries (``format_summary``,
  ``format_table``, ``format_history``, ``format_fretting``), progress and error lines;
* :mod:`contactlib.cli.remedies`: the commands that answer a case beyond a
  solver limit (exit status 3);
* :mod:`contactlib.cli.run`: the runners of the subcommands and ``check_config``.

Examples
--------
>>> from contactlib.cli import main
>>> main(["solve", "--geometry", "cone", "--nu", "0.3", "--stick-ratio", "0.5"])
2
"""

from __future__ import annotations

import sys
import traceback
from types import ModuleType

from contactlib.cli.arguments import (is_physical, path_has_units, validate_fretting,
                                      validate_history, validate_physical,
                                      validate_planned_history, validate_solve)
from contactlib.cli.inputs import (EXIT_BAD_INPUT, EXIT_SOLVER_LIMIT, PROG, SolverLimitError,
                                   UsageError, check_output, parse_base, parse_fraction,
                                   parse_friction, parse_history_n, parse_history_path,
                                   parse_indenter, parse_load_path, parse_max_error, parse_n,
                                   parse_nu, parse_relaxation, parse_slab_ratio, parse_steps,
                                   parse_stick_ratios, parse_substrate, parse_tolerance,
                                   parse_viscoelastic)
from contactlib.cli.parser import build_parser, options_taken
from contactlib.cli.remedies import run_limit
from contactlib.cli.report import (fail, format_fretting, format_history, format_summary,
                                   format_table, progress_printer, relative_text, ticker)
from contactlib.cli.run import (check_config, run_check_config, run_fretting, run_history,
                                run_physical, run_physical_fretting, run_solve, run_sweep,
                                silence_stdout, write_solution)

__all__ = ["main", "build_parser", "check_output", "UsageError", "SolverLimitError",
           "EXIT_BAD_INPUT", "EXIT_SOLVER_LIMIT"]
# public before the split, outside __all__ (kept out of `import *` and the reference page)
_ALSO_PUBLIC = (PROG, parse_base, parse_fraction, parse_friction, parse_history_n,
                parse_history_path, parse_indenter, parse_load_path, parse_max_error, parse_n,
                parse_nu, parse_relaxation, parse_slab_ratio, parse_steps, parse_stick_ratios,
                parse_substrate, parse_tolerance, parse_viscoelastic, is_physical,
                format_fretting, format_history, format_summary, format_table, check_config)
# the names the tests read under their names before the split
_progress_printer = progress_printer
_ticker = ticker
_relative_text = relative_text
_validate_planned_history = validate_planned_history
_taken = options_taken
# where main finds the writer of solve and sweep (tests/test_bad_input.py replaces it)
_write = write_solution


def _api() -> ModuleType:
    """Import the library API lazily (so ``--help`` never needs it)."""
    from contactlib import api

    return api


def _history_api() -> ModuleType:
    """Import the history module lazily (so ``--help`` never needs it)."""
    from contactlib import history_api

    return history_api


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
            return run_check_config(args.files)
        if args.command == "history" and args.tolerance is not None and (
                args.tangential_path is not None or is_physical(args)):
            raise UsageError("--tolerance plans a dimensionless history of a normal load path "
                             "(--nu, load levels): give it without --tangential-path and the "
                             "physical options")
        if args.command == "history" and args.tangential_displacement \
                and args.tangential_path is None:
            raise UsageError("--tangential-displacement needs --tangential-path (the shift "
                             "at the points of --load-path)")
        if args.command == "history" and (args.tangential_path is not None
                                          or args.bulk_stress is not None):
            if args.tangential_path is None:
                raise UsageError("--bulk-stress needs --tangential-path (give 0s for none)")
            if is_physical(args) or path_has_units(args.tangential_path):
                check_output(args.output)
                return run_physical_fretting(args)
            fret_kwargs = validate_fretting(args)  # before any numerics
            check_output(args.output)
            return run_fretting(fret_kwargs, args.output)
        if args.command in ("solve", "history") and is_physical(args):
            if getattr(args, "subsurface", False):
                raise UsageError("--subsurface must be given without --body (physical "
                                 "input), got both")
            phys_kwargs = validate_physical(args)  # before any numerics
            check_output(args.output)
            return run_physical(phys_kwargs, args.output, args.command)
        if args.command == "history":
            hist_kwargs = (validate_planned_history(args) if args.tolerance is not None
                           else validate_history(args))  # before importing the numerics
            check_output(args.output)
            return run_history(hist_kwargs, args.output, _history_api())
        kwargs = validate_solve(args)  # before importing the numerics
        api = _api()
        check_output(args.output)
        if args.command == "solve":
            return run_solve(kwargs, args.output, api, args.subsurface, _write)
        return run_sweep(kwargs, args.output, api, _write)
    except UsageError as exc:
        fail(str(exc))
        return EXIT_BAD_INPUT
    except SolverLimitError as exc:
        return run_limit(exc, argv, args)
    except KeyboardInterrupt:
        fail("interrupted")
        return 130
    except BrokenPipeError:  # the reader of stdout went away (`| head`): stop quietly
        silence_stdout()
        return 141  # 128 + SIGPIPE, what a shell reports for a writer killed by it
    except Exception as exc:  # noqa: BLE001 - last-resort, one line
        fail(f"{type(exc).__name__}: {exc}")
        if debug:
            traceback.print_exc()
        return 1
