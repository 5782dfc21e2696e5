"""Thin layers on a rigid base: does the self-similar estimate cover the refined solve?

    python benchmarks/report_layer_estimates.py cylinder bonded 10,100,1000
    python benchmarks/report_layer_estimates.py cylinder smooth 10,100,500

For each a/h, the solve at c/a = 0.5, nu = 0.3 on n = 16 ... 1024; at n = 64, 128, 256 the
true error |v(n)/v(4n) - 1| of k and of the load ratio (an independent reference: the same
case refined fourfold) and two estimates from the nested levels n/4, n/2, n: ``old``, the
Richardson estimate the solve reports on a rigid base (contactlib.estimates.estimate), and
``coated``, the rule a coated body uses (contactlib.estimates.coated_estimate, with the
edge-zone check edge_zone_resolved of the coarsest level), each over the true error. NaN
where the case has no k (the slip reverses on a bonded thin layer). About 10 s a line of
a/h on one core.
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import sys
import warnings

import contactlib
from contactlib.discretization.elements import graded_mesh
from contactlib.estimates import coated_estimate, edge_zone_resolved, estimate

STICK_RATIO = 0.5


def main() -> None:
    geometry, base = sys.argv[1], sys.argv[2]
    ratios = [float(x) for x in sys.argv[3].split(",")]
    warnings.simplefilter("ignore")
    print(f"{geometry}, {base} base, c/a = {STICK_RATIO}: estimate / true error")
    print(f"{'a/h':>6} {'n':>5} {'quantity':>8} {'true':>9} {'old':>7} {'coated':>7} edge")
    for ratio in ratios:
        vals = {}
        for n in (16, 32, 64, 128, 256, 512, 1024):
            s = contactlib.solve(geometry, nu=0.3, stick_ratio=STICK_RATIO, n=n,
                                 slab_ratio=ratio, base=base)
            vals[n] = (float(s.friction_coefficient), float(s.load_ratio))
        for n in (64, 128, 256):
            edge = edge_zone_resolved(graded_mesh(n // 4, STICK_RATIO).nodes, 1.0 / ratio)
            for q, name in ((0, "k"), (1, "load")):
                v = [vals[n // 4][q], vals[n // 2][q], vals[n][q]]
                true = abs(vals[n][q] / vals[4 * n][q] - 1.0)
                old = estimate(*v)[0] / true
                new = coated_estimate(*v, edge) / true
                print(f"{ratio:6g} {n:5d} {name:>8} {true:9.2e} {old:7.2f} {new:7.2f} {edge}")


if __name__ == "__main__":
    main()
