"""The cylinder on a thin layer on a smooth rigid base (a/h to 1000): what n = 256 resolves.

Run: python benchmarks/report_thin_layers_cylinder_smooth.py [--ratios 100,1000] [--nu 0.3]

For each a/h and c/a = 0.05, 0.1, 0.2, ..., 0.9, 0.95 it prints the default method's k
at n = 256 with its error estimate and verdict, the same case at n = 1024 (refined
fourfold), the difference between them relative to k, and whether the estimate covers
it (``cover`` = estimate / difference, >= 1 where it does). Then the frictionless load
over the thin-layer limit 8 (a/h) / (3 pi) (Winkler's ``w = p h`` on a smooth base,
E* = 1). Minutes at a/h = 1000 (22 solves an a/h).
"""

from __future__ import annotations

import argparse
import math

import contactlib

STICK_RATIOS = (0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ratios", default="100,200,500,1000")
    ap.add_argument("--nu", type=float, default=0.3)
    args = ap.parse_args()
    for s in (float(v) for v in args.ratios.split(",")):
        worst = math.inf
        for c in STICK_RATIOS:
            kw = dict(stick_ratio=c, slab_ratio=s, base="smooth", energy=False)
            r = contactlib.solve("cylinder", args.nu, n=256, **kw)
            f = contactlib.solve("cylinder", args.nu, n=1024, **kw)
            diff = abs(r.friction_coefficient - f.friction_coefficient) / f.friction_coefficient
            cover = r.error_estimate / diff if diff > 0 else math.inf
            if r.resolved:
                worst = min(worst, cover)
            print(f"a/h = {s:g}  c/a = {c:<4g} k256 = {r.friction_coefficient:.8g}  "
                  f"est = {r.error_estimate:.1e}  resolved = {r.resolved!s:5}  "
                  f"k1024 = {f.friction_coefficient:.8g} ({f.resolved})  diff = {diff:.1e}  "
                  f"cover = {cover:.2f}", flush=True)
        p = contactlib.solve("cylinder", args.nu, stick_ratio=0.0, n=256, slab_ratio=s,
                             base="smooth", energy=False)
        thin = 8.0 * s / (3.0 * math.pi)
        print(f"a/h = {s:g}  frictionless load / thin limit = {p.load_ratio / thin:.6f}  "
              f"(est {p.load_error_estimate:.1e}); smallest cover of a resolved k: {worst:.2f}",
              flush=True)


if __name__ == "__main__":
    main()
