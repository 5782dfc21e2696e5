"""Cost of a layer: ring kernels, one solve and the tables, against the half-space.

Run: python benchmarks/bench_layer.py [--quick]

Prints, measured in one run (best of ``repeat``):

* kernel evaluation for 2048 rings: the pressure and shear disc kernels on the
  2049 x 2049 grid of (r, s) the solvers' operators evaluate (``r`` = ``s`` =
  the 2049 ring edges on [0, 1]), on a layer (a/h = 1 and 10, smooth and
  bonded, nu = 0.3) over the half-space (target <= 3);
* one default-method solve (``contactlib.solve``, c/a = 0.5, without the
  work integral, with its error estimate) at the same n on a layer over the
  half-space of the same nu (target <= 1.5): a/h = 1 (both bases, nu = 0.3)
  and a/h = 20 where a self-similar k exists (smooth base at nu = 0.3, bonded
  at nu = 0.45; the bonded layer at nu = 0.3 has none there, its Newton run
  ends unconverged, so its time would not be a solve's), with the Newton
  iterations of each (the half-space needs 1-2, these layers 4-5: the start
  comes from the half-space's sign of beta, and there the slip runs outward);
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
    layer.layer_table(0.45, "bonded")
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
    cases = ((nu, "smooth", 1.0), (nu, "bonded", 1.0), (nu, "smooth", 20.0),
             (0.45, "bonded", 20.0))
    print(f"one solve, c/a = 0.5, sphere, best of {repeat} (half-space and layer interleaved)")
    for n in ns:
        def solve(nu_=nu, a_over_h=0.0, base="smooth", n=n):
            return contactlib.solve("sphere", nu_, stick_ratio=0.5, n=n, slab_ratio=a_over_h,
                                    base=base, energy=False)

        for nu_, base, a_over_h in cases:
            times = {0.0: [], a_over_h: []}
            for _ in range(repeat):
                for r in times:
                    t0 = time.perf_counter()
                    sol = solve(nu_, r, base)
                    times[r].append(time.perf_counter() - t0)
                    if r:
                        its, ok = sol.iterations, sol.converged
            t_h, t_l = min(times[0.0]), min(times[a_over_h])
            print(f"  n = {n:4d} nu = {nu_:<4g} layer {base:6s} a/h={a_over_h:<4g} "
                  f"{t_l:7.3f} s, half-space {t_h:7.3f} s   ratio {t_l / t_h:5.2f}   "
                  f"(target <= 1.5; Newton {its}, converged {ok})")

    print("tables (one per (nu, base); the smooth one serves every nu)")
    for base, nbytes in tables.items():
        print(f"  {base:6s} {nbytes / 2**20:6.2f} MiB")
    print(f"  build of one table (bonded, nu = {nu}): {build:.2f} s")


if __name__ == "__main__":
    main(quick="--quick" in sys.argv[1:])
