"""Kernel cost: 2048 x 2048 (x, s) evaluations, slab strips vs half-space discs.

Run: python benchmarks/bench_kernels.py
Prints the wall time of the sphere's disc kernels, the half-plane and slab
(a/h = 1/20) strip kernels, and raw scipy.special ellipk + ellipe on the same
number of points, measured in one run (best of 5), with their ratios.
"""

from __future__ import annotations

import time

import numpy as np
from scipy import special

from contactlib.kernels import disc, strip


def best(f, repeat: int = 5) -> float:
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return min(times)


def main(n: int = 2048) -> None:
    x = np.linspace(0.0, 1.0, n)[:, None]
    s = (np.arange(1, n + 1) / n)[None, :]
    m = np.broadcast_to((np.minimum(x, s) / np.maximum(x, s)) ** 2, (n, n)).copy()
    strip.pressure_strip(x, s, 0.3, 20.0)  # build the slab tables once
    t_ell = best(lambda: (special.ellipk(m), special.ellipe(m)))
    t_disc = best(lambda: (disc.pressure_disc(x, s, 0.3), disc.shear_disc(x, s, 0.3)))
    t_half = best(lambda: (strip.pressure_strip(x, s, 0.3), strip.shear_strip(x, s, 0.3)))
    t_slab = best(lambda: (strip.pressure_strip(x, s, 0.3, 20.0),
                           strip.shear_strip(x, s, 0.3, 20.0)))
    print(f"{n}x{n} points, pressure + shear kernels, best of 5")
    print(f"  ellipk+ellipe      {t_ell:7.3f} s")
    print(f"  sphere discs       {t_disc:7.3f} s")
    print(f"  half-plane strips  {t_half:7.3f} s   ratio to sphere {t_half / t_disc:5.2f}")
    print(f"  slab strips (h=20) {t_slab:7.3f} s   ratio to sphere {t_slab / t_disc:5.2f}")


if __name__ == "__main__":
    main()
