"""Resolution of the frictional work per cycle on a layer (docs/validation.md, Layers).

Run: python benchmarks/report_layer_history.py  (about 8 min on one core)

Sphere, nu = 0.3, k = 0.2, path 0 -> 1 -> 0, h fixed (a_max/h = 1 and 2, both
bases), at (n, steps a segment) = (240, 100), (480, 200), (960, 400): the work,
its error estimate, and the difference of each run to the one refined fourfold
(or twofold) in n and in steps. Printed as Markdown.
"""

from __future__ import annotations

import os
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

from contactlib import history  # noqa: E402

RUNS = ((240, 100), (480, 200), (960, 400))


def main() -> None:
    print("| a_max/h, base | " + " | ".join(f"n = {n}, {s} steps" for n, s in RUNS)
          + " | 240 vs 960 | 480 vs 960 | seconds |")
    print("|---" * (len(RUNS) + 4) + "|")
    for ratio in (1.0, 2.0):
        for base in ("smooth", "bonded"):
            work, cells, secs = [], [], []
            for n, steps in RUNS:
                t = time.perf_counter()
                res = history("sphere", 0.3, 0.2, [0, 1, 0], steps, n=n, slab_ratio=ratio,
                              base=base)
                secs.append(time.perf_counter() - t)
                work.append(res.frictional_work[-1])
                cells.append(f"{work[-1]:.4e} ± {100 * res.work_error_estimate[-1]:.2g} %")
            diffs = [f"{100 * (w / work[-1] - 1):+.2f} %" for w in work[:-1]]
            print(f"| {ratio:g}, {base} | " + " | ".join(cells + diffs)
                  + " | " + ", ".join(f"{s:.0f}" for s in secs) + " |", flush=True)


if __name__ == "__main__":
    main()
