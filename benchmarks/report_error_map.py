"""Where the default resolution is resolved: error estimates over (c/a, nu).

    python benchmarks/report_error_map.py [n] [geometry ...]

Prints, for each geometry (default: sphere and cylinder, half-plane), a
markdown table over c/a in {1e-8, 1e-6, 1e-4, 1e-2, 0.5, 0.99, 0.999, 0.9999,
0.99999} and nu in {-0.99, -0.5, 0, 0.3, 0.499}: the estimated relative error
of k (``error_estimate``) of ``contactlib.sweep`` at resolution n (default
256), marked ``*`` where the case is not resolved at the default max_error
(1e-3) and ``!`` where it did not converge; at nu = 0.499 also the error
against the uncoupled closed form. nu = 0.5 is exact (k = 0) everywhere.
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")  # before numpy is imported

import sys

import contactlib
from contactlib.model.theory import uncoupled_friction

RATIOS = [1e-8, 1e-6, 1e-4, 1e-2, 0.5, 0.99, 0.999, 0.9999, 0.99999]
NUS = [-0.99, -0.5, 0.0, 0.3, 0.499]


def cell(sol) -> str:
    mark = "!" if not sol.converged else "" if sol.resolved else "*"
    return f"{sol.error_estimate:.1e}{mark}"


def main() -> None:
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 256
    geometries = sys.argv[2:] or ["sphere", "cylinder"]
    for geometry in geometries:
        print(f"\n{geometry}, n = {n}: error_estimate of k (* not resolved at 1e-3, "
              "! not converged)\n")
        print("| nu \\ c/a | " + " | ".join(f"{c:g}" for c in RATIOS) + " |")
        print("|---" * (len(RATIOS) + 1) + "|")
        closed = None
        for nu in NUS:
            sols = contactlib.sweep(geometry, nu, RATIOS, n=n, energy=False)
            print(f"| {nu:g} | " + " | ".join(cell(s) for s in sols) + " |", flush=True)
            if nu == 0.499:
                closed = [abs(s.friction_coefficient / float(uncoupled_friction(
                    geometry, nu, c)) - 1) for c, s in zip(RATIOS, sols)]
        if closed is not None:
            print("| 0.499, error vs closed form | "
                  + " | ".join(f"{e:.1e}" for e in closed) + " |")


if __name__ == "__main__":
    main()
