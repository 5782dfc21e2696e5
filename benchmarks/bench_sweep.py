"""Where a sweep's time goes, and how it grows with n (issue 7's starting point).

    python benchmarks/bench_sweep.py [cases] [n]

Prints, for a default-method sphere sweep of `cases` stick ratios (default 50)
at n elements (default 256), the wall time of each stage of
contactlib.stages in one run:

* solve: collocation operators at the nodes + Newton on k (+ the n = 64/128
  Richardson warm start for n > 128),
* samples: displacements at the Gauss points of the slip zone (checks, energy),
* profiles: the displacement on the 201-point output grid,

and the ratio of the whole to one LU factorization of the same system size.
Then the cost of a 5-point sweep for n = 64 ... 512 and the fitted exponent.
"""

from __future__ import annotations

import sys
import time

import numpy as np
from scipy import linalg

from contactlib import stages
from contactlib.api import output_grid
from contactlib.default_method import solve_default
from contactlib.geometry import Geometry


def stage_times(geom: Geometry, ratios: np.ndarray, n: int) -> dict[str, float]:
    t = {"solve": 0.0, "samples": 0.0, "profiles": 0.0}
    xi = output_grid()
    for c in ratios:
        t0 = time.perf_counter()
        d = solve_default(geom, float(c), n)
        t1 = time.perf_counter()
        rec = stages._record(geom, d, samples=True)
        t2 = time.perf_counter()
        stages.profiles(geom, rec, xi)
        t3 = time.perf_counter()
        t["solve"] += t1 - t0
        t["samples"] += t2 - t1
        t["profiles"] += t3 - t2
    return t


def lu_time(size: int, repeat: int = 3) -> float:
    a = np.random.default_rng(0).standard_normal((size, size)) + size * np.eye(size)
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        linalg.lu_factor(a, check_finite=False)
        best = min(best, time.perf_counter() - t0)
    return best


def main() -> None:
    cases = int(sys.argv[1]) if len(sys.argv) > 1 else 50
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 256
    geom = Geometry("sphere", 0.3)
    ratios = np.linspace(0.02, 0.98, cases)
    solve_default(geom, 0.5, 32)  # warm-up (imports, caches)
    t = stage_times(geom, ratios, n)
    total = sum(t.values())
    lu = lu_time(n + 1 + int(0.6 * n))  # partial-slip system: p, delta, stick phi, C
    print(f"sphere, nu = 0.3, default method, n = {n}, {cases} stick ratios in 0.02 ... 0.98")
    for k, v in t.items():
        print(f"  {k:9s} {v:7.2f} s  ({v / total:5.1%})")
    print(f"  total     {total:7.2f} s  = {total / cases * 1e3:.0f} ms a case; "
          f"{total / lu:.0f} x one LU of the {n + 1 + int(0.6 * n)}-size system ({lu * 1e3:.1f} ms)")
    print("\nsweep cost vs n (5 stick ratios, all stages):")
    ns, ts = [64, 128, 256, 512], []
    for nn in ns:
        tt = sum(stage_times(geom, np.linspace(0.1, 0.9, 5), nn).values())
        ts.append(tt)
        print(f"  n = {nn:4d}: {tt:6.2f} s")
    slope = np.polyfit(np.log(ns), np.log(ts), 1)[0]
    last = np.log(ts[-1] / ts[-2]) / np.log(2)
    print(f"  fitted exponent {slope:.2f} (last doubling {last:.2f})")


if __name__ == "__main__":
    main()
