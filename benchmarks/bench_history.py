"""Speed of a full load-unload cycle of 200 steps at the default resolution.

The cycle is timed three times after a small warm-up run (imports, kernel
tables); the best time is reported with the slowest (the machine is shared).
BLAS runs single-threaded unless OPENBLAS_NUM_THREADS / OMP_NUM_THREADS are
set by the caller.

Run: python benchmarks/bench_history.py [geometry ...]   (default: sphere cylinder)

For each geometry (nu = 0.3, k = 0.15, path 0 -> 1 -> 0 with 100 steps a
segment, n = contactlib.history_api.DEFAULT_N) prints the wall time of
``contactlib.history`` (operators, every step, post-processing), the
time of one ``scipy.linalg.lu_factor`` of a random dense matrix as large as
the largest linear system the run solved (contact pressures + stick shears +
indentation), measured in the same run (median of 7), the per-step cost in
units of that factorization, and the active-set iterations. Acceptance: the
cycle under 10 s.
"""

from __future__ import annotations

import os
import sys
import time

# One BLAS thread unless the caller chose otherwise: on a shared two-core machine
# a second BLAS thread that waits for a busy core makes small factorizations
# erratically slow (measured: 0.8 ms to 18 ms for the same 300 x 300 LU).
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np
from scipy import linalg

from contactlib.history_api import DEFAULT_N, history


def lu_time(size: int, repeats: int = 7) -> float:
    a = np.random.default_rng(0).standard_normal((size, size))
    linalg.lu_factor(a, check_finite=False)  # warm-up
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        linalg.lu_factor(a, check_finite=False)
        times.append(time.perf_counter() - t0)
    return float(np.median(times))


def main(geometries: list[str]) -> None:
    for geometry in geometries:
        history(geometry, 0.3, 0.15, [0, 1], 2, n=16)  # imports and kernel tables
        runs = []
        for _ in range(3):
            t0 = time.perf_counter()
            res = history(geometry, 0.3, 0.15, [0, 1, 0], 100)
            runs.append(time.perf_counter() - t0)
        t_run = min(runs)
        steps = res.load_ratio.size - 1
        # largest system: contact pressures + stick shears + delta (final sets of a step)
        size = int(np.max(np.count_nonzero(res.state > 0, axis=1)
                          + np.count_nonzero(res.state == 1, axis=1)) + 1)
        t_lu = lu_time(size)
        per_step = t_run / steps
        threads = os.environ["OPENBLAS_NUM_THREADS"]
        print(f"{geometry:8s} BLAS threads={threads} n={DEFAULT_N} steps={steps} "
              f"cycle={t_run:6.2f}s "
              f"(best of 3; slowest {max(runs):.2f}s) "
              f"({'OK' if t_run < 10 else 'SLOW'}, limit 10 s)  largest system={size}  "
              f"LU={t_lu * 1e3:6.2f} ms  per step={per_step * 1e3:6.2f} ms "
              f"= {per_step / t_lu:5.1f} LU  iterations/step={res.iterations[1:].mean():.2f} "
              f"(max {res.iterations.max()})  converged={bool(res.converged.all())}")


if __name__ == "__main__":
    main(sys.argv[1:] or ["sphere", "cylinder"])
