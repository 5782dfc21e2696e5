"""Coated bodies: does the error estimate cover the fourfold-refined difference? (issue 39)

    python benchmarks/report_coated_estimates.py          # cylinder, c/a = 0.5, ~3 min
    python benchmarks/report_coated_estimates.py --full   # + c/a = 0, 0.1, 0.9 and the sphere

For each coated body (nu = 0.3, nu2 = 0.2, E2/E1 = 0.01, 0.1, 10, 100, 1e3; a/h = 1, 10,
100, 1000) the self-similar solve at n = 64, 128, 256 and at 4n: the estimate of k and of
the load ratio (``error_estimate``, ``load_error_estimate``) over the truth |v(n)/v(4n) - 1|
(an independent reference: the same case refined fourfold). ``edge`` tells whether the
coarsest nested level (n/4) has its contact-edge element below the coating's thickness h
(contactlib.estimates.edge_zone_resolved): there the estimate is Richardson's with the order
capped at contactlib.estimates.COATED_ORDER; before it the change over the last two
refinements (contactlib.estimates.coated_estimate). At the end: the smallest and largest
coverage in each regime, and the ratios of successive differences of k and of the load at
the finest levels, n = 256, 512, 1024 (the evidence for COATED_ORDER: 2^1.6 = 3.03).
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import argparse
import itertools
import warnings

import numpy as np

import contactlib
from contactlib.discretization.elements import graded_mesh
from contactlib.estimates import COATED_ORDER, edge_zone_resolved

NU, NU2 = 0.3, 0.2
MODULI = (1e-2, 0.1, 10.0, 100.0, 1e3)
RATIOS = (1.0, 10.0, 100.0, 1000.0)
NS = (64, 128, 256)
# --full: the sphere at the points where the cylinder's estimate fell short before
SPHERE_POINTS = ((0.1, 100.0), (0.01, 1000.0), (10.0, 1000.0), (1e3, 1000.0))


def _solve(geometry: str, c: float, modulus: float, ratio: float, n: int):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return contactlib.solve(geometry, NU, stick_ratio=c, n=n, energy=False,
                                slab_ratio=ratio, base="elastic", substrate_modulus=modulus,
                                substrate_nu=NU2)


def _case(geometry: str, c: float, modulus: float, ratio: float, rows: list, ratios: list):
    sols = {n: _solve(geometry, c, modulus, ratio, n) for n in sorted({*NS, *(4 * m for m in NS),
                                                                       16, 32})}
    values = {"k": {n: s.friction_coefficient for n, s in sols.items()},
              "load": {n: s.load_ratio for n, s in sols.items()}}
    for what, v in values.items():  # the ratio of successive differences at the finest levels
        if np.isfinite(v[256]) and v[512] != v[1024]:
            ratios.append((what, (v[256] - v[512]) / (v[512] - v[1024]), geometry, c, modulus,
                           ratio, 256))
    for n in NS:
        edge = edge_zone_resolved(graded_mesh(n // 4, c).nodes, 1.0 / ratio)
        cover = {}
        for what, est in (("k", sols[n].error_estimate), ("load", sols[n].load_error_estimate)):
            v = values[what]
            true = abs(v[n] / v[4 * n] - 1.0) if np.isfinite(v[n]) and v[n] != 0 else np.nan
            cover[what] = (est / true if true > 0 else np.nan, true)
        rows.append((geometry, c, modulus, ratio, n, edge, cover, bool(sols[n].resolved)))
        k, p = cover["k"], cover["load"]
        print(f"{geometry:8s} c/a={c:<4g} E2/E1={modulus:<6g} a/h={ratio:<5g} n={n:<4d} "
              f"edge={'yes' if edge else 'no ':3s} k {k[0]:7.2f}x ({k[1]:.1e})  "
              f"load {p[0]:7.2f}x ({p[1]:.1e})  resolved={sols[n].resolved}", flush=True)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--full", action="store_true")
    args = ap.parse_args()
    rows: list = []
    ratios: list = []
    cases = [("cylinder", 0.5, m, r) for m, r in itertools.product(MODULI, RATIOS)]
    if args.full:
        cases += [("cylinder", c, m, r) for c in (0.0, 0.1, 0.9)
                  for m, r in itertools.product((1e-2, 1e3), (100.0, 1000.0))]
        cases += [("sphere", 0.5, m, r) for m, r in SPHERE_POINTS]
    for case in cases:
        _case(*case, rows, ratios)
    print("\ncoverage (estimate / |v(n)/v(4n) - 1|), by regime of the coarsest level n/4:")
    for what in ("k", "load"):
        for edge in (True, False):
            got = [(r[6][what][0], r) for r in rows if r[5] == edge
                   and np.isfinite(r[6][what][0])]
            if not got:
                continue
            lo, hi = min(got, key=lambda t: t[0]), max(got, key=lambda t: t[0])
            print(f"  {what:4s} edge {'resolved' if edge else 'not resolved':12s}: "
                  f"{len(got)} cases, min {lo[0]:.2f}x ({lo[1][0]}, c/a {lo[1][1]:g}, "
                  f"E2/E1 {lo[1][2]:g}, a/h {lo[1][3]:g}, n {lo[1][4]}), max {hi[0]:.2f}x, "
                  f"{sum(t[0] > 3.0 for t in got)} above 3x")
    print(f"ratios of successive differences at n = 256, 512, 1024 (COATED_ORDER "
          f"{COATED_ORDER} takes {2.0 ** COATED_ORDER:.2f}):")
    for what in ("k", "load"):
        got = sorted((t for t in ratios if t[0] == what), key=lambda t: t[1])
        print(f"  {what:4s}: " + ", ".join(f"{t[1]:.2f}" for t in got))
        for t in got[:3]:
            print(f"        {t[1]:.2f}: {t[2]}, c/a {t[3]:g}, E2/E1 {t[4]:g}, a/h {t[5]:g}")


if __name__ == "__main__":
    main()
