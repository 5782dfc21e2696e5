"""The runners of the subcommands: one function a kind of run.

:func:`run_solve`, :func:`run_sweep`, :func:`run_history`,
:func:`run_fretting`, :func:`run_physical_fretting`, :func:`run_physical` and
:func:`run_check_config` take checked keyword arguments, call the library,
write the dataset (``--output``, after success) and print the summary. The
library's input errors become usage errors (status 2), its
:class:`contactlib.validate.SolverLimit` a
:class:`~contactlib.cli.inputs.SolverLimitError` (status 3).
:func:`check_config` checks workflow configuration files.
"""

from __future__ import annotations

import argparse
from contextlib import contextmanager
import os
import sys
from collections.abc import Callable, Sequence
from types import ModuleType
from typing import Any

from contactlib import validate
from contactlib.result import Solution
from contactlib.cli.inputs import (PROG, SolverLimitError, UsageError, parse_friction,
                                   parse_max_error, parse_steps, required_value, to_int, usage)
from contactlib.cli.report import (fail, format_fretting, format_history, format_summary,
                                   format_table, progress_printer, ticker)


def run_physical_fretting(args: argparse.Namespace) -> int:
    """``history --tangential-path`` with forces in N, or with ``--tangential-displacement``
    shifts in m (:mod:`contactlib.physical_fretting`)."""
    from contactlib import io, physical_fretting

    for option, given in (("--nu", args.nu is not None),
                          ("--indenter-modulus", args.indenter_modulus != "inf"),
                          ("--indenter-nu", args.indenter_nu is not None),
                          ("--slab-ratio", args.slab_ratio not in (None, "0")),
                          ("--thickness", args.thickness is not None),
                          ("--relaxation", args.relaxation is not None),
                          ("--profile", getattr(args, "profile", "paraboloid") != "paraboloid"),
                          ("--half-angle", getattr(args, "half_angle", None) is not None)):
        if given:
            raise UsageError(f"{option} is not used with a fretting path in newtons (--radius, "
                             f"--length, --indenter, --body give the problem, a paraboloid), "
                             f"got {option}")
    cylinder = args.geometry == "cylinder"
    if not cylinder and args.length is not None:
        raise UsageError(f"--length is for a cylinder only, got --length {args.length!r} "
                         "with --geometry sphere")
    kwargs: dict[str, Any] = {
        "radius": required_value(args.radius, "--radius"),
        "length": required_value(args.length, "--length") if cylinder else None,
        "load_path": args.load_path, "tangential_path": args.tangential_path,
        "indenter": "rigid" if args.indenter is None else args.indenter,
        "body": required_value(args.body, "--body"),
        "friction": parse_friction(args.friction),
        "geometry": args.geometry,
        "steps": None if args.steps is None else parse_steps(args.steps),
        "max_error": parse_max_error(args.max_error)}
    if args.n is not None:
        kwargs["n"] = to_int(args.n)
    if args.bulk_stress is not None:
        kwargs["bulk_stress"] = args.bulk_stress
    if args.tangential_displacement:
        kwargs["tangential_displacement"] = True
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


def run_fretting(kwargs: dict[str, Any], output: str | None) -> int:
    from contactlib import fretting_api, io

    with _progress("fretting") as progress:
        res = fretting_api.fretting(progress=progress, **kwargs)
    if output is not None:
        io.write_dataset(io.fretting_to_dataset(res), output)
    print(format_fretting(res))
    _wrote(output)
    return 0


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


def run_physical(kwargs: dict[str, Any], output: str | None, command: str) -> int:
    from contactlib import physical

    if command == "history":
        with _progress("history") as progress:
            res = _warned(lambda: physical.physical_history(progress=progress, **kwargs))
    else:
        try:
            with ticker(sys.stderr, "solve"):
                res = _warned(lambda: physical.physical_solve(**kwargs))
        except validate.SolverLimit as exc:  # valid input beyond the method: status 3
            raise SolverLimitError(exc) from exc
        except ValueError as exc:
            raise usage(exc) from exc
    if output is not None:
        from contactlib import io

        io.write_dataset(io.physical_to_dataset(res), output)
    print(res.summary())
    if output is not None:
        print(f"  wrote {output}")
    return 0


def write_solution(obj: Solution | Sequence[Solution], output: str) -> None:
    """Write the dataset of a solution or a sweep (:func:`contactlib.io.to_dataset`)."""
    from contactlib import io

    io.write_dataset(io.to_dataset(obj), output)


def silence_stdout() -> None:
    """Point stdout at /dev/null, so that the interpreter's last flush cannot fail again."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):  # no real file descriptor (e.g. captured in a test)
        pass


def run_solve(kwargs: dict[str, Any], output: str | None, api: ModuleType,
               subsurface: bool = False,
               write: Callable[[Any, str], None] = write_solution) -> int:
    try:
        if subsurface:  # before any numerics: refuses a missing --output
            from contactlib.stresses import check_subsurface_request
            check_subsurface_request(output, kwargs.get("slab_ratio", 0.0),
                                     kwargs.get("base", "smooth"))
        with ticker(sys.stderr, "solve"):
            sol = api.solve(**kwargs)
    except validate.SolverLimit as exc:  # valid input beyond the method: status 3
        raise SolverLimitError(exc) from exc
    except ValueError as exc:  # the library's own input validation
        raise usage(exc) from exc
    if output is not None and subsurface:  # the solve's dataset and the stress field
        from contactlib import io, stresses
        io.write_dataset(stresses.with_subsurface(io.to_dataset(sol), sol), output)
    elif output is not None:  # the file first: a closed pipe on stdout must not lose it
        write(sol, output)
    print(format_summary(sol))
    if output is not None:
        print(f"  wrote {output}")
    return 0


@contextmanager
def _progress(label: str):
    """A progress printer on a terminal (else None); library ValueErrors become usage errors.

    The progress line is cleared on the way out, whatever happens.
    """
    progress = progress_printer(sys.stderr, label)
    try:
        yield progress
    except validate.SolverLimit as exc:  # valid input beyond the method: status 3
        raise SolverLimitError(exc) from exc
    except ValueError as exc:  # the library's own input validation
        raise usage(exc) from exc
    finally:
        if progress is not None:
            sys.stderr.write("\r\033[K")
            sys.stderr.flush()


def run_sweep(kwargs: dict[str, Any], output: str, api: ModuleType,
              write: Callable[[Any, str], None] = write_solution) -> int:
    ratios = kwargs.pop("stick_ratios")
    with _progress("sweep") as progress:
        sols = api.sweep(kwargs.pop("geometry"), kwargs.pop("nu"), ratios,
                         progress=progress, **kwargs)
    write(sols, output)
    print(format_table(sols))
    print(f"wrote {output}")
    return 0


def run_history(kwargs: dict[str, Any], output: str | None, module: ModuleType) -> int:
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


def run_check_config(paths: Sequence[str]) -> int:
    problems = check_config(paths)
    for line in problems:
        fail(line)
    if not problems:
        print(f"{', '.join(paths)}: no problems found")
    return 2 if problems else 0
