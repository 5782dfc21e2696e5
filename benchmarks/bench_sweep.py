"""The default sweep: 50 stick ratios of the sphere at the default resolution.

    python benchmarks/bench_sweep.py [cases] [n]

Prints, in one run (BLAS single-threaded unless OPENBLAS_NUM_THREADS is set,
as on a busy 2-core machine extra threads only add CPU time):

* the wall and CPU time of ``contactlib.sweep("sphere", 0.3, ratios, n=n)``
  for ``cases`` stick ratios in 0.02 ... 0.98 (default 50, n = 256 the
  default resolution): every output (k, load, checks, work, the stress profiles; the
  displacement profile is computed when a caller first reads it), after
  a warm-up solve that pays for imports; three repeats, the first with a
  cold cache of stick-zone blocks (:func:`contactlib.solvers.default_method.
  nodal_operator_part`), and the ratio to one LU factorization of the
  partial-slip system (size about 1.6 n);
* where the time goes (cProfile of one sweep, cumulative, by stage);
* the cost of a 5-point sweep for n = 64 ... 1024 and its fitted exponent.
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")  # before numpy is imported

import cProfile
import pstats
import sys
import time

import numpy as np
from scipy import linalg

import contactlib


def lu_time(size: int, repeat: int = 5) -> float:
    a = np.random.default_rng(0).standard_normal((size, size)) + size * np.eye(size)
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        linalg.lu_factor(a, check_finite=False)
        best = min(best, time.perf_counter() - t0)
    return best


def timed_sweep(ratios, n: int) -> tuple[float, float, list]:
    t0, c0 = time.perf_counter(), time.process_time()
    sols = contactlib.sweep("sphere", 0.3, ratios, n=n)
    return time.perf_counter() - t0, time.process_time() - c0, sols


def stage_split(ratios, n: int) -> dict[str, float]:
    prof = cProfile.Profile()
    prof.enable()
    contactlib.sweep("sphere", 0.3, ratios, n=n)
    prof.disable()
    stats = pstats.Stats(prof).stats
    # (the displacement profile is computed when first read: not in a sweep's time)
    wanted = {"nodal operators": "nodal_operators", "Newton (LU etc.)": "newton_on_k",
              "slip samples": "_slip_samples", "profiles": "profiles"}
    out = {}
    for label, func in wanted.items():  # cumulative time over every call of the function
        out[label] = sum(v[3] for k, v in stats.items() if k[2] == func)
    total = max(v[3] for k, v in stats.items() if k[2] == "sweep")
    out["total"] = total
    return out


def main() -> None:
    cases = int(sys.argv[1]) if len(sys.argv) > 1 else 50
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 256
    ratios = np.linspace(0.02, 0.98, cases)
    contactlib.solve("sphere", 0.3, stick_ratio=0.5, n=32)  # imports, first calls
    size = n + 1 + int(0.6 * n)
    lu = lu_time(size)
    print(f"contactlib.sweep: sphere, nu = 0.3, n = {n}, {cases} stick ratios in 0.02 ... 0.98 "
          f"(BLAS threads {os.environ['OPENBLAS_NUM_THREADS']}, load average "
          f"{os.getloadavg()[0]:.1f} on {os.cpu_count()} CPUs)")
    for i in range(3):
        wall, cpu, sols = timed_sweep(ratios, n)
        ok = sum(s.converged and s.consistent for s in sols)
        print(f"  run {i + 1}{' (cold cache)' if i == 0 else '             '}: wall {wall:5.2f} s, "
              f"CPU {cpu:5.2f} s = {wall / cases * 1e3:4.0f} ms a case = "
              f"{wall / cases / lu:4.1f} x one LU of size {size} ({lu * 1e3:.2f} ms); "
              f"{ok}/{cases} converged and consistent")
    print("  where the time goes (cProfile, one sweep; profiling adds overhead):")
    split = stage_split(ratios, n)
    for label, v in split.items():
        print(f"    {label:18s} {v:6.2f} s ({v / split['total']:5.1%})")
    print("\nsweep cost vs n (5 stick ratios 0.1 ... 0.9, all outputs):")
    ns, ts = [64, 128, 256, 512, 1024], []
    for nn in ns:
        tt = timed_sweep(np.linspace(0.1, 0.9, 5), nn)[0]
        ts.append(tt)
        print(f"  n = {nn:4d}: {tt:6.2f} s")
    slope = np.polyfit(np.log(ns), np.log(ts), 1)[0]
    last = np.log(ts[-1] / ts[-2]) / np.log(2)
    print(f"  fitted exponent {slope:.2f} (last doubling {last:.2f})")


if __name__ == "__main__":
    main()
