"""Thin layers on a rigid base (sphere, a/h up to 1000): cost, memory and accuracy in one run.

Run: python benchmarks/bench_thin_layers.py [--quick]

Prints, measured in one run:

* one frictionless solve (``contactlib.solve``, n = 256, with its error
  estimate) on a bonded layer (nu = 0.3) at a/h = 10, 30, 100, 300, 1000
  (``--quick``: up to 100), its time over the half-space's solve at the same n,
  (both under ``tracemalloc``, after a warm-up solve),
  and the peak memory traced during it (the kernels hold at
  most ``thin_layer.MEMORY_BYTES`` of Bessel values at once);
* its load against Winkler's thin-layer limit 3 pi M a/(16 E* h)
  (M/E* = (1 - nu)^2/(1 - 2 nu)): the departure and departure x a/h (first
  order in h/a: about constant);
* at the largest a/h, the same solve at n = 64: its load error estimate
  against the difference to n = 256 (the estimate must cover it).

Beyond a/h = 20 the ring remainders are transform-domain sums
(:mod:`contactlib.kernels.thin_layer`), whose node count grows like a/h: the
cost ratio grows with a/h. Timings on a shared machine are noisy.
"""

from __future__ import annotations

import sys
import time
import tracemalloc

import numpy as np

import contactlib

NU = 0.3
M_OVER_ESTAR = (1.0 - NU) ** 2 / (1.0 - 2.0 * NU)


def solve(ratio: float, n: int) -> tuple[contactlib.Solution, float, float]:
    tracemalloc.start()
    t0 = time.perf_counter()
    sol = contactlib.solve("sphere", NU, stick_ratio=0.0, n=n, slab_ratio=ratio,
                           base="bonded", energy=False)
    elapsed = time.perf_counter() - t0
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    return sol, elapsed, peak


def main(quick: bool = False) -> None:
    ratios = (10.0, 30.0, 100.0) if quick else (10.0, 30.0, 100.0, 300.0, 1000.0)
    solve(0.0, 256)  # warm-up (imports, caches)
    _, t_half, peak_half = solve(0.0, 256)
    print(f"half-space, n = 256: {t_half:.2f} s, peak traced memory {peak_half / 1e6:.0f} MB")
    print(" a/h    load/Hertz   estimate  Winkler dep.  dep. x a/h   time ratio  peak MB")
    sols = {}
    for ratio in ratios:
        sol, t, peak = solve(ratio, 256)
        sols[ratio] = sol
        dep = sol.load_ratio / (3.0 * np.pi * M_OVER_ESTAR * ratio / 16.0) - 1.0
        print(f"{ratio:5g}  {sol.load_ratio:11.6f}  {sol.load_error_estimate:8.1e}  "
              f"{dep:11.3e}  {dep * ratio:10.3f}  {t / t_half:10.1f}  {peak / 1e6:7.0f}"
              f"{'' if sol.resolved else '   (not resolved)'}")
    top = ratios[-1]
    coarse, _, _ = solve(top, 64)
    diff = abs(coarse.load_ratio / sols[top].load_ratio - 1.0)
    print(f"a/h = {top:g}, n = 64 against n = 256: load difference {diff:.2e}, "
          f"estimate at n = 64 {coarse.load_error_estimate:.2e} "
          f"({'covers' if coarse.load_error_estimate >= diff else 'DOES NOT cover'})")


if __name__ == "__main__":
    main("--quick" in sys.argv[1:])
