"""Cost of an elastic indenter against a rigid one at the same n (issue 14).

Run: PYTHONPATH=. python benchmarks/bench_elastic.py [n ...]   (default n = 256 1024)

For the sphere on a half-space, the cylinder on the half-plane and the
cylinder on a slab (a/h = 0.2), times one cold ``solve`` at c/a = 0.5 with a
rigid indenter and with an elastic one (E1/E2 = 0.5, nu1 = 0.2), the two
alternating, best of 5 each (each ``solve`` owns its stick-block store), and
prints the ratio elastic/rigid, with Newton's iterations of each (the two
are different physical problems, so their iterations may differ). Targets:
<= 1.2 on the half-space and half-plane, <= 2 on the slab.

Over an unbounded body the summed kernels are evaluated once
(:attr:`contactlib.model.Contact.merged_half_space`): the ratio is 1 within
the timing noise. Over a slab both bodies' kernels are evaluated and summed.
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")  # before numpy is imported

import math
import sys
import time

from contactlib import solve

CASES = [("sphere", 0.0, 1.2), ("cylinder", 0.0, 1.2), ("cylinder", 0.2, 2.0)]
ELASTIC = {"indenter_modulus": 0.5, "indenter_nu": 0.2}


def _time(geometry: str, slab: float, n: int, kw: dict) -> tuple[float, int]:
    t0 = time.perf_counter()
    s = solve(geometry, 0.3, stick_ratio=0.5, n=n, slab_ratio=slab, **kw)
    return time.perf_counter() - t0, s.iterations


def main(ns: list[int], repeat: int = 5) -> None:
    for n in ns:
        for geometry, slab, target in CASES:
            rigid = elastic = math.inf
            for _ in range(repeat):  # alternating: both see the same load of the machine
                t, it_r = _time(geometry, slab, n, {})
                rigid = min(rigid, t)
                t, it_e = _time(geometry, slab, n, ELASTIC)
                elastic = min(elastic, t)
            print(f"{geometry:8s} a/h={slab:<4g} n={n:5d}  rigid={rigid:7.3f}s ({it_r} it)  "
                  f"elastic={elastic:7.3f}s ({it_e} it)  ratio={elastic / rigid:5.2f}  "
                  f"(target <= {target})", flush=True)


if __name__ == "__main__":
    main([int(a) for a in sys.argv[1:]] or [256, 1024])
