"""A history to a tolerance: reached where it says so? Its cost in dense LU(1024) units.

Run: python benchmarks/report_history_tolerance.py [T ...] [--cap N] [--only G:K,...]
(default T = 1e-2; the fourfold-refined truth is run where 4n <= N, default 960; --only
runs the listed cases, e.g. ``--only cylinder:0.2,sphere:0.05``)

For the sphere and the cylinder at nu = 0.3, k = 0.05, 0.2, 0.5, path 0, 1, 0, it runs
``contactlib.history(..., tolerance=T)`` (n and steps planned, refined where the
estimates fall short: :mod:`contactlib.history_plan`) and prints

* the n and steps it ended with and whether it says the tolerance is met;
* the cycle work's true relative error against a run refined fourfold (4n elements,
  4 x steps, no estimate) and its estimate (``work_error_estimate[-1]``);
* the stick radius at the peak: its true error (units a_max) against the refined run
  and its estimate (``stick_radius_error_estimate`` at the peak);
* the CPU time of the planned call (every run it made, estimates included) in units
  of one dense LU factorization of order 1024 (``scipy.linalg.lu_factor``, float64),
  measured in the same run (the median of 5), and in seconds.

"honest" is yes where a case that says it met T is within T against the refined run in
both quantities, "NO" where it is not, "-" where it does not say it met T (then the
dataset is flagged and the command line exits with status 3) or where the refined run
was not made (4n above the cap: about n^3 a step, 4n = 1920 takes an hour).
"""

from __future__ import annotations

import os
import sys
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402
from scipy import linalg  # noqa: E402

from contactlib import history  # noqa: E402
from contactlib.history_plan import peak_step  # noqa: E402

NU = 0.3
PATH = (0, 1, 0)
CASES = [(g, k) for g in ("sphere", "cylinder") for k in (0.05, 0.2, 0.5)]


def lu_unit() -> float:
    """CPU seconds of one dense LU factorization of order 1024 (median of 5)."""
    rng = np.random.default_rng(0)
    a = rng.standard_normal((1024, 1024))
    times = []
    for _ in range(5):
        t0 = time.process_time()
        linalg.lu_factor(a)
        times.append(time.process_time() - t0)
    return float(np.median(times))


def stick(res, i: int) -> float:
    return float(np.nan_to_num(res.stick_ratio[i] * res.contact_radius[i]))


def row(geometry: str, k: float, tol: float, cap: int, unit: float) -> str:
    t0 = time.process_time()
    try:
        res = history(geometry, NU, k, PATH, None, tolerance=tol)
    except ValueError as exc:  # SolverLimit: planned beyond the largest n
        return f"| {geometry} | {k:g} | {tol:g} | refused: {exc} |||||||"
    cpu = time.process_time() - t0
    top = peak_step(res.load_ratio)
    w_est = float(res.work_error_estimate[-1])
    c_est = float(res.stick_radius_error_estimate[top])
    met = "yes" if res.tolerance_met else "no"
    if 4 * res.n > cap:
        truth = f"(4n = {4 * res.n} > {cap}: not run)"
        return (f"| {geometry} | {k:g} | {tol:g} | {res.n}, {res.steps} | {met} | {truth} | "
                f"{w_est:.1e} | - | {c_est:.1e} | {cpu / unit:.0f} ({cpu:.2f} s) | - |")
    ref = history(geometry, NU, k, PATH, 4 * res.steps, n=4 * res.n, error_estimate=False)
    w_true = abs(res.frictional_work[-1] - ref.frictional_work[-1]) / ref.frictional_work[-1]
    c_true = abs(stick(res, top) - stick(ref, peak_step(ref.load_ratio)))
    honest = "-" if not res.tolerance_met else (
        "yes" if w_true <= tol and c_true <= tol else "NO")
    return (f"| {geometry} | {k:g} | {tol:g} | {res.n}, {res.steps} | {met} | {w_true:.1e} | "
            f"{w_est:.1e} | {c_true:.1e} | {c_est:.1e} | {cpu / unit:.0f} ({cpu:.2f} s) | "
            f"{honest} |")


def main(argv: list[str]) -> None:
    cap = 960
    if "--cap" in argv:
        i = argv.index("--cap")
        cap = int(argv[i + 1])
        argv = argv[:i] + argv[i + 2:]
    cases = CASES
    if "--only" in argv:
        i = argv.index("--only")
        cases = [(g, float(k)) for g, k in (c.split(":") for c in argv[i + 1].split(","))]
        argv = argv[:i] + argv[i + 2:]
    tols = [float(a) for a in argv] or [1e-2]
    unit = lu_unit()
    print(f"## History to a tolerance (nu = {NU}, path {PATH}); LU(1024) = {unit * 1e3:.1f} ms "
          f"CPU\n")
    print("| geometry | k | T | n, steps | met (says) | work: true rel. error | estimate | "
          "stick radius at peak: true (a_max) | estimate | CPU in LU(1024) | honest |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for tol in tols:
        for geometry, k in cases:
            print(row(geometry, k, tol, cap, unit), flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
