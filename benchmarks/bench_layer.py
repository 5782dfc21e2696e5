"""Cost of a layer: ring kernels, one solve and the tables, against the half-space.

Run: python benchmarks/bench_layer.py [--quick]

Prints, measured in one run (best of ``repeat``):

* kernel evaluation for 2048 rings: the pressure and shear disc kernels on the
  2049 x 2049 grid of (r, s) the solvers' operators evaluate (``r`` = ``s`` =
  the 2049 ring edges on [0, 1]), on a layer (a/h = 1 and 10, smooth and
  bonded, nu = 0.3) over the half-space (target <= 3);
* one default-method solve (``contactlib.solve``, c/a = 0.5, without the
  work integral, with its error estimate) at the same n on a layer (a/h = 1
  and 20) over the half-space (target <= 1.5);
* the memory of the layer's interpolation tables (one per (nu, base)) and the
  time to build one.

Timings on a shared machine are noisy: the ratios of one run are what to read.
"""

from __future__ import annotations

import sys
import time

import numpy as np

import contactlib
from contactlib.kernels import disc, layer


def best(f, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return min(times)


def main(quick: bool = False) -> None:
    nu, rings = 0.3, 2048
    repeat = 2 if quick else 3
    edges = np.linspace(0.0, 1.0, rings + 1)
    r, s = edges[:, None], edges[None, :]

    t0 = time.perf_counter()
    layer.layer_table(nu, "bonded")
    build = time.perf_counter() - t0
    layer.layer_table(nu, "smooth")
    tables = {b: layer.layer_table(nu, b).nbytes for b in layer.BASES}

    def half_space():
        disc.pressure_disc(r, s, nu)
        disc.shear_disc(r, s, nu)

    t_half = best(half_space, repeat)
    print(f"kernels, {rings} rings ({rings + 1}^2 points, pressure + shear), best of {repeat}")
    print(f"  half-space             {t_half:7.3f} s")
    for base in layer.BASES:
        for a_over_h in (1.0, 10.0):
            h = 1.0 / a_over_h

            def on_layer(h=h, base=base):
                layer.pressure_disc(r, s, nu, h, base)
                layer.shear_disc(r, s, nu, h, base)

            t = best(on_layer, repeat)
            print(f"  layer {base:6s} a/h={a_over_h:<4g} {t:7.3f} s   ratio {t / t_half:5.2f}"
                  f"   (target <= 3)")

    ns = (256,) if quick else (256, 1024)
    print(f"one solve, c/a = 0.5, sphere, best of {repeat}")
    for n in ns:
        def solve(a_over_h=0.0, base="smooth", n=n):
            contactlib.solve("sphere", nu, stick_ratio=0.5, n=n, slab_ratio=a_over_h,
                             base=base, energy=False)

        t_h = best(solve, repeat)
        print(f"  n = {n:4d} half-space             {t_h:7.3f} s")
        for base in layer.BASES:
            for a_over_h in (1.0, 20.0):
                t_l = best(lambda base=base, a_over_h=a_over_h: solve(a_over_h, base), repeat)
                print(f"  n = {n:4d} layer {base:6s} a/h={a_over_h:<4g} {t_l:7.3f} s   ratio "
                      f"{t_l / t_h:5.2f}   (target <= 1.5)")

    print("tables (one per (nu, base); the smooth one serves every nu)")
    for base, nbytes in tables.items():
        print(f"  {base:6s} {nbytes / 2**20:6.2f} MiB")
    print(f"  build of one table (bonded, nu = {nu}): {build:.2f} s")


if __name__ == "__main__":
    main(quick="--quick" in sys.argv[1:])
