"""Does the default method's estimate collapse at isolated stick ratios? (issue 42, item 9)

    python benchmarks/report_estimate_collapse.py                # n = 16, cylinder, ~2 min
    python benchmarks/report_estimate_collapse.py --n 16,32 --geometry sphere

The default method estimates k's error from the same case on nested coarser meshes (two
levels n/2, n below n = 32, three from there: contactlib.accuracy.estimate). Where the
coarse levels' errors cancel, the estimate comes out accidentally small. The script scans
c/a and prints, for each case, k's error against the extrapolated method at n = 256 (its
own estimate ~1e-7 ... 1e-6, far below the errors scanned), the estimate, error /
estimate and ``resolved``; at the end the largest error / estimate and the resolved cases
whose error exceeds max_error (the defect: a resolved case off by more than max_error).
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import argparse

import numpy as np

import contactlib


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", default="16")
    ap.add_argument("--geometry", default="cylinder")
    ap.add_argument("--slab-ratios", default="0,0.05")
    ap.add_argument("--ratios", default=None, help="comma-separated c/a (default: a scan)")
    args = ap.parse_args()
    ratios = ([float(x) for x in args.ratios.split(",")] if args.ratios else
              list(np.round(np.r_[np.arange(0.02, 0.2, 0.01), np.arange(0.2, 0.99, 0.05)], 4)))
    bad = []
    worst = 0.0
    for slab in (float(x) for x in args.slab_ratios.split(",")):
        if args.geometry == "sphere" and slab:
            continue
        for n in (int(x) for x in args.n.split(",")):
            print(f"{args.geometry}, a/h = {slab:g}, n = {n}")
            for c in ratios:
                truth = contactlib.solve(args.geometry, 0.3, stick_ratio=c, n=256,
                                         method="extrapolated", slab_ratio=slab,
                                         energy=False).friction_coefficient
                s = contactlib.solve(args.geometry, 0.3, stick_ratio=c, n=n,
                                     slab_ratio=slab, energy=False)
                err = abs(s.friction_coefficient / truth - 1.0)
                ratio = err / s.error_estimate if s.error_estimate > 0 else np.inf
                worst = max(worst, ratio)
                flag = ""
                if s.resolved and err > s.max_error:
                    flag = "  <-- resolved, error > max_error"
                    bad.append((slab, n, c, err, s.error_estimate))
                print(f"  c/a = {c:<6g} error {err:.2e}  estimate {s.error_estimate:.2e}  "
                      f"err/est {ratio:6.2f}  resolved {s.resolved}{flag}", flush=True)
    print(f"largest error / estimate: {worst:.2f}; resolved with error > max_error: "
          f"{len(bad)}")
    for b in bad:
        print("  a/h = %g, n = %d, c/a = %g: error %.2e, estimate %.2e" % b)


if __name__ == "__main__":
    main()
