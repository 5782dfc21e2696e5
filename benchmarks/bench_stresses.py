"""Cost of the subsurface stress field against one solve, and its method error (issue 38).

Run: python benchmarks/bench_stresses.py [n]   (default n = 256)

Prints, for the sphere and the cylinder at c/a = 0.5, nu = 0.3: the wall time of one
``contactlib.solve`` (the median of 5), of :func:`contactlib.stresses.subsurface_stresses`
on a 100 x 100 grid (x = r/a and z = depth/a on [0, 2], the surface row included; the
median of 5), their ratio (also without the surface row z = 0), and the peak of the memory
the field allocates (``tracemalloc``). All are timed in the same run. The field is computed
from the solution's tractions on its 201 output points, whatever n is.

Then the sphere's method error on the same grid, against the same field computed with
finer rules (the tractions' own discretization is not part of it; docs/stresses.md):

* z > 0: the xi quadrature with its panels halved (``PANEL`` / 2, so the 8-point head
  panels and the 32-point tail panels of ``TAIL_PERIODS`` periods are both halved);
* z = 0: the shear's ring integrals with rules of twice the density (tanh-sinh step 1/12
  up to |s| = 4, 20-point Gauss-Legendre), on a grid of spacing 0.001 that passes
  through every node of the tractions; and the surface row of q = r on r < a (40
  pieces) against the closed form of ``contactlib.kernels.disc.shear_disc``.

The cylinder's field is in closed form (exact for the piecewise-linear tractions).
"""

from __future__ import annotations

import statistics
import sys
import time
import tracemalloc

import numpy as np

import contactlib.stresses as st
from contactlib import solve
from contactlib.kernels.disc import shear_disc
from contactlib.stresses import subsurface_stresses

NU = 0.3


def _median_time(f, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def cost(n: int) -> None:
    x, z = np.linspace(0.0, 2.0, 100), np.linspace(0.0, 2.0, 100)
    for geometry in ("sphere", "cylinder"):
        sol = solve(geometry, NU, stick_ratio=0.5, n=n)
        t_solve = _median_time(lambda: solve(geometry, NU, stick_ratio=0.5, n=n), 5)
        t_field = _median_time(lambda: subsurface_stresses(sol, x, z), 5)
        t_inside = _median_time(lambda: subsurface_stresses(sol, x, z[1:]), 5)
        tracemalloc.start()
        subsurface_stresses(sol, x, z)
        peak = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        print(f"{geometry:8s} n={n}  solve={t_solve:6.3f}s  field 100x100={t_field:6.3f}s  "
              f"ratio={t_field / t_solve:5.1f} solves  without the surface row "
              f"{t_inside / t_solve:5.1f} solves  peak memory={peak / 2**20:6.1f} MiB")


def _largest(a: dict, b: dict, rows: slice = slice(None)) -> float:
    return max(float(np.max(np.abs(a[k][rows] - b[k][rows]))) for k in a)


def method_error(n: int) -> None:
    sol = solve("sphere", NU, stick_ratio=0.5, n=n)
    xi, p, q = st.traction_samples(sol)
    x = z = np.linspace(0.0, 2.0, 100)
    base = st.halfspace_stresses(xi, p, q, x, z[1:], NU)
    panel = st.quadrature.PANEL
    try:
        st.quadrature.PANEL = panel / 2
        fine = st.halfspace_stresses(xi, p, q, x, z[1:], NU)
    finally:
        st.quadrature.PANEL = panel
    print(f"sphere z > 0: xi quadrature against halved panels {_largest(base, fine):.1e} p0")
    xs = np.linspace(0.0, 2.0, 2001)
    base = st.halfspace_stresses(xi, p, q, xs, [0.0], NU)
    rules = st.surface.RING_TANH_SINH, st.surface.RING_GAUSS
    try:
        st.surface.RING_TANH_SINH, st.surface.RING_GAUSS = (1.0 / 12.0, 4.0), 20
        fine = st.halfspace_stresses(xi, p, q, xs, [0.0], NU)
    finally:
        st.surface.RING_TANH_SINH, st.surface.RING_GAUSS = rules
    print(f"sphere z = 0: ring integrals against rules of twice the density "
          f"{_largest(base, fine):.1e} p0")
    t = np.linspace(0.0, 1.0, 41)
    r = np.linspace(0.01, 2.0, 200)
    r = r[np.abs(r - 1.0) > 1e-9]  # the jump of q at r = a is log-singular
    f = st.halfspace_stresses(t, 0 * t, t, r, [0.0], NU)
    _, u, du = shear_disc(r, 1.0, NU)
    e = max(np.max(np.abs(f["sigma_rr"][0] - (du + NU * u / r))),
            np.max(np.abs(f["sigma_tt"][0] - (u / r + NU * du))))
    print(f"sphere z = 0: q = r on r < a against shear_disc's closed form {e:.1e} (unit of q)")


if __name__ == "__main__":
    size = int(sys.argv[1]) if len(sys.argv) > 1 else 256
    cost(size)
    method_error(size)
