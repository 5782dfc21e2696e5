"""Does the extrapolated method's error estimate cover its error? (issue 18)

    python benchmarks/report_estimate_coverage.py             # the round-off spread, ~1.5 h
    python benchmarks/report_estimate_coverage.py --quick     # n = 1024 only, ~2 min
    python benchmarks/report_estimate_coverage.py --four      # four levels, ~12 min

Default (``--quick``: n = 1024 alone, fewer draws): the five-level k's round-off. Stick
ratios c/a + j 1e-15 (j = 0 ... draws - 1) leave the discretization alone and change the
round-off; with nu = 0.4999999 the closed form is a truth to about 1e-13. For each
geometry, c/a and n the script prints the mean and the standard deviation of the error
over the draws, the standard deviation over the noise bound
(``extrapolated_method.log_noise``) and the largest error over its estimate.

``--four``: the four-level estimate (``extrapolated_method.TRUNCATION_FACTOR``) at
n = 128, 256, 512, 768 against the method's five-level k at n = 2048 (estimates about
3e-10 ... 2e-8 there), nu = 0.4999999, 0.3, 0, -0.5, c/a = 0.1 ... 0.98: the error over
the last correction (the estimate over the factor; not the correction where the level n/8
lies beyond ``LOG_LEVEL_MAX_OFFSET`` and the finest level's estimate was taken) and over
the estimate.

One BLAS thread; run from the repository root.
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")  # before numpy is imported

import sys

import numpy as np

from contactlib.solvers.extrapolated_method import log_noise, solve_extrapolated, truncation_factor
from contactlib.model import contact
from contactlib.model.theory import uncoupled_friction

NU = 0.4999999
RATIOS = (0.005, 0.02, 0.1, 0.3, 0.5, 0.7, 0.9, 0.95, 0.97, 0.98, 0.99)


def spread(ns, draws: int) -> None:
    """The five-level k over stick ratios 1e-15 apart, against the closed form."""
    print("geometry  n     c/a    mean err   std err   std/bound  max err/est")
    worst = 0.0
    for geometry in ("sphere", "cylinder"):
        model = contact(geometry, NU)
        for n in ns:
            for c0 in RATIOS:
                errs, ratios = [], []
                bound = np.nan
                for j in range(draws):
                    c = c0 + j * 1e-15
                    s = solve_extrapolated(model, c, n, work=False)
                    err = s.k / float(uncoupled_friction(geometry, NU, c)) - 1.0
                    errs.append(err)
                    ratios.append(abs(err) / s.error_estimate)
                    bound = log_noise(s.mesh)
                e = np.array(errs)
                worst = max(worst, max(ratios))
                print(f"{geometry:9s} {n:5d} {c0:<6} {e.mean():+.2e}  {e.std(ddof=1):.2e}"
                      f"   {e.std(ddof=1) / bound:8.2f}   {max(ratios):.2f}", flush=True)
    print(f"largest error / estimate: {worst:.2f}")


def four_levels() -> None:
    """The four-level estimate against the five-level k at n = 2048."""
    print("geometry   nu         c/a   n    error     err/correction  err/estimate")
    for geometry in ("sphere", "cylinder"):
        for nu in (NU, 0.3, 0.0, -0.5):
            model = contact(geometry, nu)
            for c in (0.1, 0.3, 0.5, 0.7, 0.9, 0.98):
                ref = solve_extrapolated(model, c, 2048, work=False)
                for n in (128, 256, 512, 768):
                    s = solve_extrapolated(model, c, n, work=False)
                    if not (s.converged and ref.converged):
                        print(f"{geometry:9s} {nu:<10} {c:<5} {n:4d} not converged")
                        continue
                    err = abs(s.k / ref.k - 1.0)
                    est = s.error_estimate
                    print(f"{geometry:9s} {nu:<10} {c:<5} {n:4d} {err:.2e}  "
                          f"{err / (est / truncation_factor(n)):8.2f}  {err / est:12.2f}",
                          flush=True)


def main() -> None:
    if "--four" in sys.argv:
        four_levels()
    elif "--quick" in sys.argv:
        spread((1024,), 5)
    else:
        spread((1024, 1536, 2048, 3072), 8)


if __name__ == "__main__":
    main()
