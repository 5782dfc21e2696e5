"""What the command line prints: summaries, tables, progress and error lines.

:func:`format_summary` (one solution), :func:`format_table` (a sweep),
:func:`format_history` and :func:`format_fretting` turn results into text;
:func:`ticker` and :func:`progress_printer` show progress on a terminal (and
nothing elsewhere); :func:`fail` writes the one ``contactlib: error:`` line.
"""

from __future__ import annotations

from contextlib import contextmanager
import math
import sys
from collections.abc import Callable, Sequence
from typing import Any, TextIO

from contactlib.result import Solution, substrate_text
from contactlib.cli.inputs import PROG


def _indenter_text(sol: Any) -> str:
    """``, E1/E2 = .., nu1 = .., beta = ..`` of an elastic indenter; empty when rigid."""
    ratio = getattr(sol, "indenter_modulus_ratio", float("inf"))
    if ratio == float("inf"):
        return ""
    return (f", E1/E2 = {ratio:g}, nu1 = {sol.indenter_poisson_ratio:g}, "
            f"beta = {sol.dundurs_beta:.4g}")


def format_fretting(res: Any) -> str:
    """Summary of a fretting path: the state at every path point, and the cycles' work."""
    shifted = getattr(res, "tangential_displacement", False)
    lines = [f"fretting of the {res.geometry}: nu = {res.nu:g}, k = {res.friction:g}, "
             f"beta = {res.beta:.4g}, n = {res.n}, {res.steps} steps a segment"
             + (", the shift prescribed" if shifted else ""),
             "point  P/P_max  " + ("sR/a_max^2  Q/(kP_max) (estimate)  " if shifted
                                   else "Q/(kP_max)  ")
             + "c/a (estimate)       e/a_max   frictional work (estimate)  resolved"]
    for i, j in enumerate(res.point_step):
        tangential = (f"{res.shift[j]:10.4g}  {res.force_ratio[j]:10.6f} "
                      f"({res.force_ratio_error[i]:.1e})" if shifted
                      else f"{res.force_ratio[j]:10.4g}")
        lines.append(
            f"{i:5d}  {res.load_ratio[j]:7.4g}  {tangential}  "
            f"{res.stick_ratio[j]:8.5f} ({res.stick_ratio_error[i]:.1e})  "
            f"{res.stick_offset[j]:9.2e}  {res.dissipation[j]:12.5e} "
            f"({res.dissipation_error[i]:.1e})  {'yes' if res.resolved[i] else 'NO'}")
    for i, j, work, err in res.cycles:
        lines.append(f"cycle from point {i} to {j}: frictional work {work:.5e} "
                     f"(estimate {err:.1e}; units "
                     + ("E* a_max^5/R^2)" if res.geometry == "sphere"
                        else "E* a_max^4/R^2 per unit length)"))
    from contactlib.fretting_api import stick_shape

    shape = stick_shape(res)  # the sphere: its stick zone per direction at the largest |Q|/kP
    if shape is not None:
        lines.append(shape.describe())
    failed = int(res.converged.size - res.converged.sum())
    if failed:
        lines.append(f"{failed} steps did not converge; their values "
                     "are not data")
    if not res.all_resolved:
        from contactlib.fretting_api import finer_run

        n, steps = finer_run(res)  # a run the command accepts
        at_limit = "" if n > res.n else f" (n = {n} is the largest accepted for this case)"
        lines.append(f"not every point is resolved to max_error = {res.max_error:g}: refine "
                     f"with --n {n} --steps {steps}{at_limit}")
    return "\n".join(lines)


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
    from contactlib.model.indenter import indenter

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
    if getattr(res, "load_shape", None):  # a shape or table (contactlib.model.load_paths)
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
                    + (f" {relative_text(float(errors[j]), res.frictional_work[j], zero_below)}"
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


def relative_text(error: float, value: float, zero_below: float = 0.0) -> str:
    """An 8-character relative error, or ``(zero)`` for a value that is zero at its scale
    (no relative error is printed for it)."""
    if abs(float(value)) <= zero_below:
        return f"{'(zero)':>8}"
    return f"{error:8.1e}"


@contextmanager
def ticker(stream: TextIO, label: str, after: float = 2.0, every: float = 1.0):
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


def progress_printer(stream: TextIO, label: str = "sweep") -> Callable[[int, int], None] | None:
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


def fail(message: str) -> None:
    print(f"{PROG}: error: {' '.join(str(message).split())}", file=sys.stderr)
