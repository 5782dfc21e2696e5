"""The located stick edge of a history against a run refined fourfold, step by step.

Run: python benchmarks/report_stick_edge.py   (about 1 min on one core)

For a 0 -> 1 -> 0 cycle (n = 120, 50 steps a segment; truth n = 480, 200 steps) on the
sphere (nu = 0.3, k = 0.2), the half-plane (nu = 0.3, k = 0.3) and the sphere on a layer
(a_max/h = 1 on a smooth base, k = 0.2) it prints the error of the stick radius in
elements (a_max/100) at every fourth step of the unloading, and the largest over the last
20 steps of the loading. The stick edge is located from the traction deficit with the law
of an advancing edge under increasing load and of a receding one under decreasing load
(``history_solver.stick_radius``); at the first step after the turn it is an element
edge. The last unloading step (P = 0.02 P_max) moves the contact edge over several
elements, which equal steps do not resolve.
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

from contactlib import history  # noqa: E402

CASES = [("sphere", 0.3, 0.2, {}), ("cylinder", 0.3, 0.3, {}),
         ("sphere", 0.3, 0.2, {"slab_ratio": 1.0})]
N, STEPS = 120, 50


def stick(res) -> np.ndarray:
    return np.nan_to_num(res.stick_ratio * res.contact_radius)


def main() -> None:
    for geometry, nu, k, kwargs in CASES:
        run = history(geometry, nu, k, [0, 1, 0], STEPS, n=N, error_estimate=False, **kwargs)
        ref = history(geometry, nu, k, [0, 1, 0], 4 * STEPS, n=4 * N, error_estimate=False,
                      **kwargs)
        h = float(run.xi_bounds[0, 1])
        err = (stick(run) - stick(ref)[::4]) / h
        loading = np.abs(err[STEPS - 20:STEPS + 1]).max()
        print(f"{geometry}, nu = {nu}, k = {k} {kwargs or ''}: loading max |error| "
              f"{loading:.2f} elements; unloading, every 4th step: "
              + " ".join(f"{e:+.2f}" for e in err[STEPS + 1:2 * STEPS + 1:4]))


if __name__ == "__main__":
    main()
