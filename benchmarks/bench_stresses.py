"""Cost of the subsurface stress field against one solve (issue 38).

Run: python benchmarks/bench_stresses.py [n]   (default n = 256)

Prints, for the sphere and the cylinder at c/a = 0.5, nu = 0.3: the wall time of one
``contactlib.solve`` (the median of 5), of :func:`contactlib.stresses.subsurface_stresses`
on a 100 x 100 grid (x = r/a and z = depth/a on [0, 2], the surface row included; the
median of 3), their ratio (also without the surface row z = 0, whose shear part needs
the longest xi range), and the peak of the memory the field allocates
(``tracemalloc``). Both are timed in the same run. The field is computed from the
solution's tractions on its 201 output points, whatever n is.
"""

from __future__ import annotations

import statistics
import sys
import time
import tracemalloc

import numpy as np

from contactlib import solve
from contactlib.stresses import subsurface_stresses


def _median_time(f, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main(n: int) -> None:
    x, z = np.linspace(0.0, 2.0, 100), np.linspace(0.0, 2.0, 100)
    for geometry in ("sphere", "cylinder"):
        sol = solve(geometry, 0.3, stick_ratio=0.5, n=n)
        t_solve = _median_time(lambda: solve(geometry, 0.3, stick_ratio=0.5, n=n), 5)
        t_field = _median_time(lambda: subsurface_stresses(sol, x, z), 3)
        t_inside = _median_time(lambda: subsurface_stresses(sol, x, z[1:]), 3)
        tracemalloc.start()
        subsurface_stresses(sol, x, z)
        peak = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        print(f"{geometry:8s} n={n}  solve={t_solve:6.3f}s  field 100x100={t_field:6.3f}s  "
              f"ratio={t_field / t_solve:6.1f} solves  without the surface row "
              f"{t_inside / t_solve:5.1f} solves  peak memory={peak / 2**20:6.1f} MiB")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 256)
