"""Cost of the difference rows of the extremes, as a ratio in one run.

``contactlib.solvers.default_method`` writes the normal rows of a tiny stick zone as
w(r_i) - w(0) when c/a <= AXIS_ROWS_BELOW (1e-4), and the normal and stick rows
of a thin slip annulus relative to a node a few widths inside when 1 - c/a <=
EDGE_ROWS_BELOW (5e-4), and at high n (the elements next to c below
NEAR_ROWS_BELOW min(c, a - c)) the rows within 0.1 min(c, a - c) of c; elsewhere
nothing changes. This times one
default-method solve (n = 256, nu = 0.499, both geometries) with those rows and
with the plain rows (both thresholds disabled) in the same process, best of 3,
one BLAS thread, and prints the ratio and k against the closed form.

Run: ``PYTHONPATH=. OPENBLAS_NUM_THREADS=1 python benchmarks/bench_axis_rows.py``
"""

from __future__ import annotations

import math
import time

from scipy import special

from contactlib.solvers import default_method
from contactlib.model import contact
from contactlib.model.theory import beta_of_nu


def closed_form(geometry: str, nu: float, c: float) -> float:
    """The uncoupled closed form (K' = K(1 - c^2) without rounding 1 - c^2)."""
    kp = special.ellipkm1(c * c)
    if geometry == "sphere":
        return beta_of_nu(nu) * math.atanh(c) / c / kp
    return beta_of_nu(nu) * special.ellipk(c * c) / kp


def best(fn, repeat: int = 3):
    times, out = [], None
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t)
    return min(times), out


def _set(axis: float, edge: float, near: float) -> None:
    default_method.AXIS_ROWS_BELOW = axis
    default_method.EDGE_ROWS_BELOW = edge
    default_method.NEAR_ROWS_BELOW = near


def main() -> None:
    nu, n = 0.499, 256
    threshold = (default_method.AXIS_ROWS_BELOW, default_method.EDGE_ROWS_BELOW,
                 default_method.NEAR_ROWS_BELOW)
    print(f"{'case':22s} {'plain (s)':>10s} {'axis (s)':>10s} {'ratio':>6s} "
          f"{'k err plain':>12s} {'k err axis':>12s}")
    for geometry in ("sphere", "cylinder"):
        model = contact(geometry, nu)
        for c in (1e-8, 1e-6, 1e-4, 1 - 1e-4, 1 - 1e-5):
            truth = closed_form(geometry, nu, c)
            _set(-1.0, -1.0, -1.0)
            t_plain, s_plain = best(lambda: default_method.solve_default(model, c, n))
            _set(*threshold)
            t_axis, s_axis = best(lambda: default_method.solve_default(model, c, n))
            print(f"{geometry + ', c/a = ' + format(c, '.6g'):22s} {t_plain:10.3f} {t_axis:10.3f} "
                  f"{t_axis / t_plain:6.2f} {s_plain.k / truth - 1:12.2e} "
                  f"{s_axis.k / truth - 1:12.2e}")


    # high n at c/a = 0.5: the rows within 0.1 min(c, a - c) of c (NEAR_ROWS_BELOW)
    model = contact("sphere", 0.3)
    for n_high in (2048,):
        _set(-1.0, -1.0, -1.0)
        t_plain, _ = best(lambda: default_method.solve_default(model, 0.5, n_high), 1)
        _set(*threshold)
        t_near, _ = best(lambda: default_method.solve_default(model, 0.5, n_high), 1)
        print(f"{'sphere, nu = 0.3, c/a = 0.5, n = ' + str(n_high):34s} plain {t_plain:.2f} s, "
              f"near-c rows {t_near:.2f} s, ratio {t_near / t_plain:.2f}")


if __name__ == "__main__":
    main()
