"""Thin coatings under a cylinder (a/h up to 1000 on an elastic substrate): cost in one run.

Run: python benchmarks/bench_thin_coatings_cylinder.py [--quick]

The case: E2/E1 = 0.1, nu = 0.3, nu2 = 0.2 (m = E1*/E2* = 10.5), c/a = 0.5. Prints,
measured in one run:

* the first coated solve at each a/h (it builds the strip tables: the coated table
  to |x +- s|/h = 48 and the far tables to the octave the case reaches), its time;
* then one solve at n = 256 on the coated body and on the bonded rigid base at
  a/h = 20, 100, 1000 (``--quick``: 20, 100), each over the half-plane's solve at
  the same n (after a warm-up solve).

Beyond |x +- s|/h = 48 the coated remainders come from log-spaced tables
(:mod:`contactlib.kernels.strip`, "Coated body"): 46 kB a (nu, substrate), whatever a/h.
Timings on a shared machine are noisy.
"""

from __future__ import annotations

import sys
import time

import contactlib

NU, SUB = 0.3, {"substrate_modulus": 0.1, "substrate_nu": 0.2}


def seconds(ratio: float, n: int, base: str) -> float:
    kw = SUB if base == "elastic" else {}
    t0 = time.perf_counter()
    contactlib.solve("cylinder", NU, stick_ratio=0.5, n=n, slab_ratio=ratio,
                     base=base if ratio else "smooth", energy=False, **kw)
    return time.perf_counter() - t0


def main() -> None:
    ratios = (20.0, 100.0) if "--quick" in sys.argv else (20.0, 100.0, 1000.0)
    seconds(0.0, 256, "smooth")
    for r in ratios:
        first = seconds(r, 256, "elastic")
        print(f"a/h = {r:g}: first coated solve (builds the tables) {first:.2f} s")
    half = min(seconds(0.0, 256, "smooth") for _ in range(3))
    print(f"half-plane, n = 256: {half:.3f} s")
    for r in ratios:
        coated = min(seconds(r, 256, "elastic") for _ in range(3))
        bonded = min(seconds(r, 256, "bonded") for _ in range(3))
        print(f"a/h = {r:g}, n = 256: coated {coated:.3f} s ({coated / half:.2f}x the "
              f"half-plane), bonded {bonded:.3f} s ({bonded / half:.2f}x)")


if __name__ == "__main__":
    main()
