"""Toward k to 1e-9 (issue 18): an n^-3 ln n term in the levels' expansion.

    python benchmarks/report_log_extrapolation.py            # about 3 minutes
    python benchmarks/report_log_extrapolation.py --self     # nu = 0.3 and 0: no truth
    python benchmarks/report_log_extrapolation.py --estimate # the method's k and estimate

The extrapolated method eliminates n^-2, n^-3 and n^-4 from the default method's
roots on four nested meshes. This script solves the levels n = 32 ... 2048 (two
extrapolated solves, n = 256 and 2048, whose levels are nested and share the meshes
they have in common) and extrapolates every run of consecutive levels two ways:

* ``2+3+4``: four levels, k + A n^-2 + B n^-3 + C n^-4 (the method's own);
* ``2+3L+3+4``: five levels, with a term n^-3 ln n added.

With nu = 0.4999999 the closed form of the uncoupled problem is a truth to about
1e-13 (the coupling enters at beta^2), so the printed numbers are errors. ``--self``
prints, at nu = 0.3 and 0 (c/a = 0.5, levels up to n = 4096), each value relative to
the last one of its own kind, i.e. how far the extrapolations move as n grows.

``--estimate`` (about 4 minutes) prints, for the method's own solve at n = 1024, 1536 and
2048 (nu = 0.4999999, both geometries, c/a = 0.003 ... 0.995), the error of its k against
the closed form, its error estimate and their ratio, and whether the five-level k was taken.

The method itself does the five-level extrapolation from n = 1024
(``extrapolated_method.LOG_LEVEL_FROM_N``, its ``k`` against ``k_four_levels``); this
script shows both kinds level by level, below that n as well.
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")  # before numpy is imported

import sys

import numpy as np

from contactlib.solvers.extrapolated_method import (extrapolate, extrapolate_with_log,
                                                   solve_extrapolated)
from contactlib.model import contact
from contactlib.model.theory import uncoupled_friction

# the method's own extrapolations, by the number of consecutive levels they take
KINDS = {"2+3+4": (4, lambda v: extrapolate(v)[0]), "2+3L+3+4": (5, extrapolate_with_log)}


def levels(geometry: str, nu: float, c: float, finest: tuple[int, ...]) -> dict[int, float]:
    """Every level's k of extrapolated solves at the given finest n (levels in common:
    their mean; they agree to about 1e-11)."""
    model = contact(geometry, nu)
    found: dict[int, list[float]] = {}
    for n in finest:
        s = solve_extrapolated(model, c, n, work=False)
        if not s.converged or "not nested" in (s.message or ""):
            raise SystemExit(f"{geometry}, nu = {nu}, c/a = {c}, n = {n}: {s.message}")
        for level, k in zip(s.levels, s.level_k):
            found.setdefault(level, []).append(k)
    return {n: float(np.mean(v)) for n, v in sorted(found.items())}


def extrapolations(by_n: dict[int, float], kind: str) -> list[tuple[int, float]]:
    """(finest n, k) of every run of consecutive levels that ``kind`` takes."""
    ns = sorted(by_n)
    size, extrapolated = KINDS[kind]
    return [(ns[last], float(extrapolated([by_n[n] for n in ns[last - size + 1:last + 1]])))
            for last in range(size - 1, len(ns))]


ESTIMATE_RATIOS = (0.003, 0.01, 0.02, 0.05, 0.1, 0.3, 0.5, 0.7, 0.9, 0.95, 0.98, 0.99, 0.995)


def estimates() -> None:
    """The method's k error against the closed form and its estimate (nu = 0.4999999)."""
    nu = 0.4999999
    print(f"the method's k against the closed form, nu = {nu}: error, estimate, ratio")
    worst = 0.0
    for geometry in ("sphere", "cylinder"):
        model = contact(geometry, nu)
        for c in ESTIMATE_RATIOS:
            exact = float(uncoupled_friction(geometry, nu, c))
            row = []
            for n in (1024, 1536, 2048):
                s = solve_extrapolated(model, c, n, work=False)
                err = abs(s.k / exact - 1.0)
                worst = max(worst, err / s.error_estimate)
                five = "5" if s.k != s.k_four_levels else "4"
                row.append(f"n={n}: {err:.1e} / {s.error_estimate:.1e} "
                           f"({err / s.error_estimate:.2f}, {five})")
            print(f"  {geometry:8s} c/a = {c:<6} " + "  ".join(row), flush=True)
    print(f"largest error / estimate: {worst:.2f}")


def main() -> None:
    if "--estimate" in sys.argv[1:]:
        estimates()
        return
    if "--self" in sys.argv[1:]:
        print("k of each extrapolation relative to the last of its kind (c/a = 0.5; no truth)")
        for geometry, nu in (("sphere", 0.3), ("cylinder", 0.3), ("sphere", 0.0)):
            by_n = levels(geometry, nu, 0.5, (512, 4096))
            for name in KINDS:
                ex = extrapolations(by_n, name)
                last = ex[-1][1]
                print(f"  {geometry:8s} nu = {nu:<4} {name:9s} "
                      + "  ".join(f"n={n}: {k / last - 1:+.1e}" for n, k in ex))
        return
    nu = 0.4999999
    print(f"error of k against the closed form, nu = {nu}, by the finest level used")
    for geometry in ("sphere", "cylinder"):
        for c in (0.1, 0.5, 0.9):
            by_n = levels(geometry, nu, c, (256, 2048))
            exact = float(uncoupled_friction(geometry, nu, c))
            for name in KINDS:
                ex = extrapolations(by_n, name)
                print(f"  {geometry:8s} c/a = {c}  {name:9s} "
                      + "  ".join(f"n={n}: {k / exact - 1:+.1e}" for n, k in ex if n >= 256))


if __name__ == "__main__":
    main()
