"""Cost of the per-case error estimates, as a share of the default sweep.

    python benchmarks/bench_error_estimate.py [cases] [n]

Prints, from one run (BLAS single-threaded unless OPENBLAS_NUM_THREADS is
set), for the default sweep (``contactlib.sweep("sphere", 0.3, ratios)``, 50
stick ratios in 0.02 ... 0.98 at n = 256, every output) and for the same
sweep of the cylinder:

* the CPU time of the whole public sweep (with the estimates, as users get it);
* the CPU time of the solve stage with and without the estimates
  (:func:`contactlib.stages.solve_cases`, ``estimate=True`` / ``False``:
  the nested n/2 solves of k, load and work);
* the ratio of the difference to the sweep without the estimates (the
  issue's budget: at most 30 %).

CPU time (``time.process_time``) is used because the machine is shared; each
measurement is the best of ``REPEAT`` runs, alternating, so a burst of load
hits both sides alike.
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")  # before numpy is imported

import sys
import time

import numpy as np

import contactlib
from contactlib import stages
from contactlib.model.geometry import Geometry

REPEAT = 3


def cpu(func) -> float:
    c0 = time.process_time()
    func()
    return time.process_time() - c0


def measure(geometry: str, ratios: np.ndarray, n: int) -> dict[str, float]:
    geom = Geometry(geometry, 0.3)
    best = {"sweep": np.inf, "with": np.inf, "without": np.inf}
    for _ in range(REPEAT):
        best["sweep"] = min(best["sweep"], cpu(
            lambda: contactlib.sweep(geometry, 0.3, ratios, n=n)))
        best["with"] = min(best["with"], cpu(
            lambda: stages.solve_cases(geom, "default", n, ratios, estimate=True)))
        best["without"] = min(best["without"], cpu(
            lambda: stages.solve_cases(geom, "default", n, ratios, estimate=False)))
    best["estimate"] = best["with"] - best["without"]
    best["ratio"] = best["estimate"] / (best["sweep"] - best["estimate"])
    return best


def main() -> None:
    cases = int(sys.argv[1]) if len(sys.argv) > 1 else 50
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 256
    ratios = np.linspace(0.02, 0.98, cases)
    contactlib.solve("sphere", 0.3, stick_ratio=0.5, n=32)  # imports, first calls
    print(f"error estimates: nu = 0.3, n = {n}, {cases} stick ratios in 0.02 ... 0.98, best "
          f"CPU time of {REPEAT} (BLAS threads {os.environ['OPENBLAS_NUM_THREADS']}, load "
          f"average {os.getloadavg()[0]:.1f} on {os.cpu_count()} CPUs)")
    for geometry in ("sphere", "cylinder"):
        b = measure(geometry, ratios, n)
        print(f"  {geometry:8s}: sweep {b['sweep']:.2f} s (with estimates); solve stage "
              f"{b['with']:.2f} s with, {b['without']:.2f} s without; estimate "
              f"{b['estimate']:.2f} s = {100 * b['ratio']:.0f} % of the sweep without it")


if __name__ == "__main__":
    main()
