"""The located stick edge of a history against a run refined fourfold, step by step.

Run: python benchmarks/report_stick_edge.py   (about 2 min on one core)

For a 0 -> 1 -> 0 cycle (n = 120, 50 steps a segment; truth n = 480, 200 steps) on the
sphere (nu = 0.3, k = 0.2), the half-plane (nu = 0.3, k = 0.3) and the sphere on a layer
(a_max/h = 1 on a smooth base, k = 0.2) it prints the error of the stick radius in
elements (a_max/100) at every fourth step of the unloading, and the largest over the last
20 steps of the loading. The stick edge is located from the traction deficit with the law
of an advancing edge under increasing load and of a receding one under decreasing load
(``history_solver.stick_radius``); at the first step after the turn it is an element
edge. The last unloading step (P = 0.02 P_max) moves the contact edge over several
elements, which equal steps do not resolve. Then the same for reloading below the previous
peak (0 -> 1 -> 0.4 -> 1): the median and largest error over the reload, and every fourth
step. The reload takes the advancing edge's law: the receding law there was measured
worse (median 0.07 -> 0.25 elements on the half-plane, 0.20 -> 0.25 on the layer; the
sphere's fits are rejected either way, 0.25, so its reload is quantized by the mesh).
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

    # reloading below the previous peak: 0 -> 1 -> 0.4 -> 1
    path = [0, 1, 0.4, 1]
    for geometry, nu, k, kwargs in CASES:
        run = history(geometry, nu, k, path, STEPS, n=N, error_estimate=False, **kwargs)
        ref = history(geometry, nu, k, path, 4 * STEPS, n=4 * N, error_estimate=False,
                      **kwargs)
        h = float(run.xi_bounds[0, 1])
        err = (stick(run) - stick(ref)[::4]) / h
        reload = err[2 * STEPS + 2:3 * STEPS + 1]  # after the turn's first step
        print(f"{geometry}, nu = {nu}, k = {k} {kwargs or ''}: reload 0.4 -> 1, median "
              f"|error| {np.median(np.abs(reload)):.2f} elements, max "
              f"{np.abs(reload).max():.2f}; every 4th step: "
              + " ".join(f"{e:+.2f}" for e in reload[::4]))


if __name__ == "__main__":
    main()
