"""Cost of a coated body (a layer bonded to an elastic half-space) against the bonded base.

Run: python benchmarks/bench_coatings.py [--quick]

Prints, measured in one run:

* the time to build one coated table (per (nu, E2/E1, nu2); the rigid bases build
  theirs the same way, with fewer quadrature nodes near t = 0) and its memory;
* one default-method solve (c/a = 0.5, no work integral, tables already built) on
  the coated body against the bonded rigid base at the same a/h and n (the same
  operators: the ratio should be ~1);
* the largest supported case's kernel memory: one table per (kind) in the
  ``lru_cache`` of :mod:`contactlib.kernels.layer` (8 entries at most).

Timings on a shared machine are noisy: the ratios of one run are what to read.
"""

from __future__ import annotations

import sys
import time

import contactlib
from contactlib.kernels import layer


def timed(f) -> tuple[float, object]:
    t0 = time.perf_counter()
    out = f()
    return time.perf_counter() - t0, out


def main(quick: bool = False) -> None:
    n = 128 if quick else 256
    nu = 0.3
    for modulus in ((0.1,) if quick else (0.01, 0.1, 10.0, 1e6)):
        sub = layer.Substrate(modulus, 0.3)
        t_build, tab = timed(lambda sub=sub: layer.layer_table(nu, sub))
        print(f"table E2/E1 = {modulus:g}: built in {t_build:.2f} s, "
              f"{tab.nbytes / 2**20:.1f} MiB")
    layer.layer_table(nu, "bonded")
    for slab in (1.0, 20.0):
        t_b, sb = timed(lambda s=slab: contactlib.solve(
            "sphere", nu, stick_ratio=0.5, n=n, slab_ratio=s, base="bonded", energy=False))
        t_c, sc = timed(lambda s=slab: contactlib.solve(
            "sphere", nu, stick_ratio=0.5, n=n, slab_ratio=s, base="elastic",
            substrate_modulus=0.1, energy=False))
        print(f"solve n = {n}, a/h = {slab:g}: bonded {t_b:.2f} s, coated (E2/E1 = 0.1) "
              f"{t_c:.2f} s, ratio {t_c / t_b:.2f} (k {sb.friction_coefficient:.6g}, "
              f"{sc.friction_coefficient:.6g})")


if __name__ == "__main__":
    main("--quick" in sys.argv[1:])
