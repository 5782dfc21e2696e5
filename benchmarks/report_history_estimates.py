"""Coverage of the history's error estimates against runs refined fourfold, in one run.

Run: python benchmarks/report_history_estimates.py [n steps]   (default n = 120, 50 steps
a segment; the truth is 4n elements and 4 x steps; about 1 min on one core)

For each path it prints estimate / true error of

* the cycle's work (the cumulative frictional work at the end of the path,
  ``work_error_estimate[-1] * work_scale`` against |W - W_ref|);
* the stick radius at the top of the first loading (``stick_radius_error_estimate``
  against |c - c_ref|, units a_max);
* the stick radius along the path: the smallest estimate / error over the steps
  (coverage; the steps that move the contact edge over an element, which the verdict
  leaves out, are left out), and the largest, over path segments, of the segment's
  largest estimate over its largest error (inflation);
* the stick radius's typical tightness: the median over the steps of the estimate over
  the largest true error within two steps either side (the estimate's own window: the
  located edge's error changes sign from step to step, so one step's error may be near 0);
* the external work at the top (``energy_error_estimate`` is the largest of the
  energies' estimates: against the external work's error, relative to the peak
  external work).

An estimate covers its error within a factor 3 and is not inflated if every ratio is
in [1/3, 3]. The order of convergence that the work's estimate measured
(``history_solver.measured_order``) is printed with it.
"""

from __future__ import annotations

import os
import sys
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

from contactlib import history  # noqa: E402
from contactlib.solvers import history_solver as hs  # noqa: E402

NU = 0.3
SLS = [(0.5, 1.0)]  # standard linear solid, g = 0.5, tau = 1
CASES = [  # (label, geometry, nu, k, path, extra keyword arguments)
    ("sphere cycle", "sphere", NU, 0.2, (0, 1, 0), {}),
    ("cylinder cycle", "cylinder", NU, 0.3, (0, 1, 0), {}),
    ("sphere k=0.05 cycle", "sphere", NU, 0.05, (0, 1, 0), {}),
    ("sphere fretting", "sphere", NU, 0.2, (0, 1, 0.5, 1, 0.5), {}),
    ("cylinder fretting nu=0", "cylinder", 0.0, 0.2, (0, 1, 0.5, 1, 0.5), {}),
    ("sphere layer a/h=1", "sphere", NU, 0.2, (0, 1, 0), {"slab_ratio": 1.0}),
    ("sphere viscoelastic T=tau", "sphere", NU, 0.2, (0, 1, 0),
     {"relaxation": SLS, "duration": 1.0}),
]


def _orders() -> list[float]:
    """Record the work's measured order of every estimate made (wraps error_estimates)."""
    seen: list[float] = []
    original = hs.error_estimates

    def recording(*args, **kwargs):
        out = original(*args, **kwargs)
        seen.append(out[2]["work"])
        return out

    hs.error_estimates = recording
    return seen


def stick(res) -> np.ndarray:
    return np.nan_to_num(res.stick_ratio * res.contact_radius)


def check(label, geometry, nu, k, path, kwargs, n, steps, orders) -> str:
    t0 = time.process_time()
    res = history(geometry, nu, k, path, steps, n=n, **kwargs)
    ref = history(geometry, nu, k, path, 4 * steps, n=4 * n, error_estimate=False, **kwargs)
    cpu = time.process_time() - t0
    w_true = abs(res.frictional_work[-1] - ref.frictional_work[-1])
    w_est = res.work_error_estimate[-1] * res.work_scale
    c, c_ref = stick(res), stick(ref)[::4]
    top = res.segment_end(1)
    c_true = np.abs(c - c_ref)
    c_est = res.stick_radius_error_estimate
    regular = np.concatenate([[False], np.abs(np.diff(res.contact_radius))
                              <= res.xi_bounds[0, 1]]) & (res.load_ratio > 0)
    m = regular & (c_true > 0)
    cover = float(np.min(c_est[m] / c_true[m])) if m.any() else np.nan
    infl = [np.max(c_est[regular & (res.segment == g)])
            / np.max(c_true[regular & (res.segment == g)])
            for g in range(1, len(path)) if np.any(c_true[regular & (res.segment == g)] > 0)]
    window = np.array([np.max(c_true[max(i - 2, 0):i + 3][res.segment[max(i - 2, 0):i + 3]
                                                          == res.segment[i]])
                       for i in range(c_true.size)])  # within two steps, same segment
    w = regular & (window > 0)
    typical = float(np.median(c_est[w] / window[w])) if w.any() else np.nan
    e_true = abs(res.external_work[top] - ref.external_work[4 * top]) / res.energy_scale
    e_est = res.energy_error_estimate[top]
    w_rel = w_true / ref.frictional_work[-1]
    return (f"| {label} | {orders[-1]:.2f} | {w_est / w_true:.2f} ({w_rel:.1e}) | "
            f"{c_est[top] / c_true[top]:.2f} ({c_true[top]:.1e}) | {cover:.2f} | "
            f"{max(infl) if infl else np.nan:.2f} | {typical:.2f} | "
            f"{e_est / e_true:.2f} ({e_true:.1e}) | {cpu:.0f} |")


def main(argv: list[str]) -> None:
    n, steps = (int(argv[0]), int(argv[1])) if len(argv) >= 2 else (120, 50)
    orders = _orders()
    print(f"## Estimate / true error, n = {n}, {steps} steps a segment (truth {4 * n}, "
          f"{4 * steps})\n")
    print("| path | work order p | cycle work (true rel.) | stick radius at top (true, a_max) | "
          "stick radius: min over steps | stick radius: max segment inflation | "
          "stick radius: median over its window's largest error | "
          "external work at top (true rel.) | CPU s |")
    print("|---|---|---|---|---|---|---|---|---|")
    for case in CASES:
        print(check(*case, n, steps, orders), flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
