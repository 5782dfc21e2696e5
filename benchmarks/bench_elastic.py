"""Cost of an elastic indenter against a rigid one at the same n (issue 14).

Run: PYTHONPATH=. python benchmarks/bench_elastic.py [n ...]   (default n = 256 1024)

For the sphere on a half-space and the cylinder on a slab (a/h = 0.2), times
one cold ``solve`` at c/a = 0.5 (stick-block store emptied before each, best
of 3) with a rigid indenter and with an elastic one (E1/E2 = 0.5, nu1 = 0.2:
the indenter's kernels are evaluated and summed with the body's), and prints
the ratio elastic/rigid. Targets: <= 1.2 on the half-space, <= 2 on the slab.
"""

from __future__ import annotations

import math
import sys
import time

from contactlib import solve

CASES = [("sphere", 0.0, 1.2), ("cylinder", 0.2, 2.0)]


def _best(geometry: str, slab: float, n: int, ratio: float, repeat: int = 3) -> float:
    kw = {} if math.isinf(ratio) else {"indenter_modulus": ratio, "indenter_nu": 0.2}
    best = math.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        solve(geometry, 0.3, stick_ratio=0.5, n=n, slab_ratio=slab, **kw)
        best = min(best, time.perf_counter() - t0)
    return best


def main(ns: list[int]) -> None:
    for n in ns:
        for geometry, slab, target in CASES:
            rigid = _best(geometry, slab, n, math.inf)
            elastic = _best(geometry, slab, n, 0.5)
            print(f"{geometry:8s} a/h={slab:<4g} n={n:5d}  rigid={rigid:7.3f}s  "
                  f"elastic={elastic:7.3f}s  ratio={elastic / rigid:5.2f}  (target <= {target})")


if __name__ == "__main__":
    main([int(a) for a in sys.argv[1:]] or [256, 1024])
