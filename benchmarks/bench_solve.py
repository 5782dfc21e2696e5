"""Speed of one default solve against one dense LU factorization of its system's size.

Run: python benchmarks/bench_solve.py [n ...]   (default n = 2048)

Prints, for each n, the wall time of ``contactlib.solve`` (kernels, matrices,
Newton on k, profiles, flags and frictional work), the time of one
``scipy.linalg.lu_factor`` of a random dense matrix of the same size as the
solver's linear system, their ratio (acceptance: <= 10 at n = 2048), and the
memory of the dense influence operators. Both are timed in the same run.
"""

from __future__ import annotations

import sys
import time

import numpy as np
from scipy import linalg

from contactlib import solve
from contactlib.discretization.elements import graded_mesh


def main(ns: list[int]) -> None:
    for n in ns:
        c = 0.5
        mesh = graded_mesh(n, c)
        size = n + mesh.stick_index + 1  # p, delta, stick shears, C
        a = np.random.default_rng(0).standard_normal((size, size))
        t0 = time.perf_counter()
        linalg.lu_factor(a, check_finite=False)
        t_lu = time.perf_counter() - t0
        t0 = time.perf_counter()
        sol = solve("sphere", 0.3, stick_ratio=c, n=n)
        t_solve = time.perf_counter() - t0
        mem = 2 * 3 * (n + 1) ** 2 * 8 / 2**20
        print(f"n={n:5d} system={size:5d}  solve={t_solve:7.3f}s  LU={t_lu:6.3f}s  "
              f"ratio={t_solve / t_lu:5.1f}  Newton iterations={sol.iterations}  "
              f"operators={mem:6.0f} MiB  k={sol.friction_coefficient:.8f}")


if __name__ == "__main__":
    main([int(a) for a in sys.argv[1:]] or [2048])
