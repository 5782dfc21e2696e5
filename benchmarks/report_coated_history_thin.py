"""The cylinder's history on thin layers: a coated body and a smooth rigid base (issue 39).

Run: python benchmarks/report_coated_history_thin.py  (about 6 min on one core)

nu = nu2 = 0.3; coated E2/E1 = 0.1, 0.5, 10 at a_max/h = 50 ... 1000, smooth base at
100 ... 500; history at its defaults (n = 240, 200 steps a segment). Per case, in one run:

* mesh: the probe-sized mesh extent (a_max) and the contact a_peak at P_max;
* k = 0: |L a_peak^2 - 1|, L the self-similar frictionless solve's load ratio at
  a/h = a_peak a_max/h (n = 256), against the bound one history element over a_peak
  plus the solve's load estimate;
* k = 0.2, path [0, 1]: the history's c at P_max minus the self-similar solve's c(k)
  at a_peak (in a_max), the history's estimate, and the same difference at a_max/h
  three times smaller (a departure of first order in h/a falls by ~3);
* path [0, 1, 0]: max |external - stored - frictional| over the peak external work;
* n: c and the cycle's work at n = 240, 480 (steps scaled alike) and the n = 240
  estimates against the difference;
* seconds and peak memory (ru_maxrss) of the n = 240 runs.
Printed as Markdown.
"""

from __future__ import annotations

import os
import resource
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

import contactlib  # noqa: E402
from contactlib import history, validate  # noqa: E402

NU, K = 0.3, 0.2
CASES = ([("elastic", m, r) for m in (0.1, 0.5, 10.0) for r in (50.0, 100.0, 300.0, 1000.0)]
         + [("smooth", None, r) for r in (100.0, 200.0, 500.0)])


def _kw(base: str, modulus: float | None) -> dict:
    return {"base": base} | ({"substrate_modulus": modulus} if base == "elastic" else {})


def cycle_work(res) -> np.ndarray:
    """Cumulative frictional work by the trapezoid rule on the result's arrays (cylinder)."""
    lo, hi = res.xi_bounds[:, 0], res.xi_bounds[:, 1]
    q = 0.5 * res.shear
    du = np.diff(res.tangential_displacement, axis=0)
    st = res.state
    moving = (st[1:] >= 2) | ((st[1:] == 0) & (st[:-1] >= 2))
    terms = np.where(moving, -0.5 * (q[1:] + q[:-1]) * du * 2.0 * (hi - lo), 0.0)
    return np.concatenate([[0.0], np.cumsum(terms.sum(axis=1))])


def stick_gap(ratio: float, kw: dict, n: int | None = None, steps: int | None = None):
    """(history, c_history - c_selfsimilar in a_max) on monotonic loading."""
    res = history("cylinder", NU, K, [0, 1], steps, n=n, slab_ratio=ratio, **kw)
    a = float(res.contact_radius[-1])
    try:
        ref = contactlib.solve("cylinder", NU, friction=K, n=256, slab_ratio=ratio * a,
                               energy=False, **kw)
    except validate.SolverLimit:  # k beyond the self-similar solutions: all stuck there
        return res, float("nan")
    return res, (float(res.stick_ratio[-1]) - ref.stick_ratio) * a


def row(base: str, modulus: float | None, ratio: float) -> str:
    kw = _kw(base, modulus)
    name = f"E2/E1 = {modulus:g}" if base == "elastic" else "smooth"
    try:
        t = time.perf_counter()
        res, gap = stick_gap(ratio, kw)
        secs = time.perf_counter() - t
    except validate.InputError as exc:
        return f"| {name} | {ratio:g} | refused: {exc} |"
    a = float(res.contact_radius[-1])
    element = float(res.xi_bounds[0, 1] - res.xi_bounds[0, 0])
    _, gap3 = stick_gap(ratio / 3.0, kw)
    free = history("cylinder", NU, 0.0, [0, 1], None, slab_ratio=ratio, **kw)
    a0 = float(free.contact_radius[-1])
    ref0 = contactlib.solve("cylinder", NU, friction=0.0, n=256, slab_ratio=ratio * a0,
                            energy=False, **kw)
    load_gap = abs(ref0.load_ratio * a0**2 - 1.0)
    load_bound = 2.0 * element / a0 + float(ref0.load_error_estimate)
    cyc = history("cylinder", NU, K, [0, 1, 0], None, slab_ratio=ratio, **kw)
    rest = np.abs(cyc.external_work - cyc.stored_energy - cycle_work(cyc))
    fine = history("cylinder", NU, K, [0, 1, 0], 400, n=480, slab_ratio=ratio, **kw)
    top, top_fine = int(np.argmax(cyc.load_ratio)), int(np.argmax(fine.load_ratio))
    dc = abs(float(fine.stick_ratio[top_fine] * fine.contact_radius[top_fine]
                   - cyc.stick_ratio[top] * cyc.contact_radius[top]))
    dw = abs(fine.frictional_work[-1] / cyc.frictional_work[-1] - 1.0)
    return (f"| {name} | {ratio:g} | {res.mesh_extent:.3f} | {a:.4f} | {load_gap:.1e} "
            f"({load_bound:.1e}) | {gap:+.1e} ({res.stick_radius_error_estimate[-1]:.1e}) "
            f"| {gap3:+.1e} | {rest.max() / cyc.external_work.max():.1e} "
            f"| {dc:.1e} ({cyc.stick_radius_error_estimate[top]:.1e}) "
            f"| {dw:.1e} ({cyc.work_error_estimate[-1]:.1e}) "
            f"| {', '.join(q for q, ok in cyc.resolved_quantities.items() if ok) or 'none'} "
            f"| {secs:.1f} |")


def main() -> None:
    print("| body | a_max/h | mesh | a_peak | k=0: abs(L a^2 - 1) (bound) "
          "| k=0.2: c - c_ss (estimate) | same at a_max/h / 3 | energy rest "
          "| c: 240 vs 480 (estimate) | work: 240 vs 480 (estimate) | resolved (cycle) "
          "| seconds |")
    print("|---" * 12 + "|")
    for case in CASES:
        print(row(*case), flush=True)
    print(f"\npeak memory {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024:.0f} MB")


if __name__ == "__main__":
    main()
