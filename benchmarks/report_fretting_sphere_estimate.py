"""The sphere's frictional work per cycle: its error (the mesh's lattice part, the steps'
part) and the estimate ``fretting("sphere", ...)`` gives it, against independent truths.

    python benchmarks/report_fretting_sphere_estimate.py          # about 4 CPU min
    python benchmarks/report_fretting_sphere_estimate.py --fine   # + the coupled (32, 8)
                                                                  # against (128, 32): +10 min

Measured (this script, LU(1024) = 0.027 CPU s): at beta = 0 the estimate over the error
against Mindlin–Deresiewicz is 3.11, 1.23, 1.03 at n = 32 (Q*/kP = 0.25, 0.5, 0.9) and
5.39, 2.75, 2.05 at n = 64 (the former estimate: 21, 1.2, 6.8 and 3.3, 8.0, 1.0); at
beta = 0.286, (16, 4) against (64, 16): 3.78 (former 0.7, not covered); with ``--fine``,
(32, 8) against (128, 32): 3.3 (error 7.2e-5, estimate 2.38e-4; (128, 32) took 553 CPU s).
The run with its estimates costs 1.8 to 3.9 times the run alone.

Paths: k = 0.3, P: 0 -> P_max, then Q: 0 -> Q* -> -Q* -> Q*; the cycle is the last two
segments. beta = 0: two equal bodies with nu = 0 (beta = gamma = 0), where
Mindlin–Deresiewicz is exact. beta = 0.286: a rigid sphere on nu = 0.3, whose truth is the
run refined fourfold in n and in steps (``error_estimate=False``). CPU seconds are
``time.process_time`` and, in brackets, in units of one dense LU factorization of order
1024 measured in the same run.

1. The lattice error: the centred grid's work against Mindlin–Deresiewicz at n = 16 to 64
   (not smooth in n: sign changes), the grid moved by i/4, j/4 of a cell, and the mean over
   those 4 x 4 placements (free of it).
2. The steps' error of the coupled cycle at n = 16, 32, 64 and 4, 8, 16 steps, and its
   order (and none at beta = 0: 4 and 8 steps give the same work).
3. The estimate against the truth: ratio estimate / |error| (want 1 to 3), with the former
   estimate (Richardson from (n/2, S/2) and (n/4, S/4) at the order they show, at most 2)
   for comparison, and the CPU of the run with and without its estimate.
"""

from __future__ import annotations

import argparse
import os
import sys
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

from contactlib import fretting  # noqa: E402
from contactlib import fretting_api as fa  # noqa: E402
from contactlib.model import contact  # noqa: E402
from contactlib.solvers.history_solver import measured_order  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from report_history_tolerance import lu_unit  # noqa: E402

K = 0.3
LOAD = np.array([0, 1, 1, 1, 1.0])
EQUAL = {"indenter_modulus": 1.0, "indenter_nu": 0.0}  # equal bodies (nu = 0 given)


def tang(x: float) -> np.ndarray:
    return np.array([0, 0, x, -x, x])


def md(x: float, big_p: float = 4 / 3, c: float = 4.0) -> float:
    """Mindlin–Deresiewicz's cycle work (a = R = E* = 1; C = 4 for equal bodies, nu = 0)."""
    bracket = 1 - (1 - x) ** (5 / 3) - 5 * x / 6 * (1 + (1 - x) ** (2 / 3))
    return 9 * K * K * big_p * big_p * c / 10 * bracket


def raw_work(model, n: int, steps: int, x: float, offset=(0.0, 0.0)) -> tuple[float, float]:
    """The cycle's work of one grid placement and its CPU seconds."""
    t0 = time.process_time()
    _, raw = fa._sphere_run(model, n, steps, K, LOAD, tang(x), False, offset=offset)
    w = float(raw.dissipation[4 * steps] - raw.dissipation[2 * steps])
    return w, time.process_time() - t0


def timed(*args, **kw):
    t0 = time.process_time()
    r = fretting(*args, **kw)
    return r, time.process_time() - t0


def lattice(unit: float) -> None:
    print("\n1. beta = 0, Q*/kP = 0.5: the centred grid and the placements' mean, relative "
          "error against Mindlin-Deresiewicz (1 step a segment: at beta = 0 and constant P "
          "the steps do not matter)")
    model, exact = contact("sphere", 0.0, **EQUAL), md(0.5)
    print("| n | centred | moved (1/2, 0) | moved (1/2, 1/2) | spread of 4 x 4 | mean 2 x 2 "
          "| mean 4 x 4 | CPU 4 x 4 |")
    print("|---|---|---|---|---|---|---|---|")
    for n in (16, 32, 64):
        t0 = time.process_time()
        m = fa.SPHERE_OFFSETS
        works = {(i, j): raw_work(model, n, 1, 0.5, (i / m, j / m))[0] / exact - 1
                 for i in range(m) for j in range(m // 2 + 1)}
        cpu = time.process_time() - t0
        full = [works[i, min(j, m - j)] for i in range(m) for j in range(m)]
        two = [works[i, j] for i in (0, m // 2) for j in (0, m // 2)]
        print(f"| {n} | {works[0, 0]:+.2e} | {works[m // 2, 0]:+.2e} | "
              f"{works[m // 2, m // 2]:+.2e} | {min(full):+.1e} .. {max(full):+.1e} | "
              f"{np.mean(two):+.2e} | {np.mean(full):+.2e} | {cpu:.1f} s "
              f"({cpu / unit:.0f}) |", flush=True)


def steps_error(unit: float) -> dict:
    print("\n2. The steps' error of the cycle's work, beta = 0.286 (rigid on nu = 0.3), "
          "Q*/kP = 0.5, centred grid")
    model = contact("sphere", 0.3)
    print("| n | W(4 steps) | W(8) | W(16) | W(4) - W(8) | W(8) - W(16) | order | CPU (16) |")
    print("|---|---|---|---|---|---|---|---|")
    out = {}
    for n in (16, 32, 64):
        ws = [raw_work(model, n, s, 0.5) for s in (4, 8, 16)]
        w = [v for v, _ in ws]
        out[n] = w
        order = np.log2(abs(w[0] - w[1]) / abs(w[1] - w[2]))
        print(f"| {n} | {w[0]:.6e} | {w[1]:.6e} | {w[2]:.6e} | {w[0] - w[1]:.2e} | "
              f"{w[1] - w[2]:.2e} | {order:.2f} | {ws[2][1]:.1f} s ({ws[2][1] / unit:.0f}) |",
              flush=True)
    eq = contact("sphere", 0.0, **EQUAL)
    a, b = raw_work(eq, 32, 4, 0.9)[0], raw_work(eq, 32, 8, 0.9)[0]
    print(f"beta = 0, Q*/kP = 0.9, n = 32: 4 and 8 steps differ by {abs(a / b - 1):.1e} "
          "(relative)")
    return out


def former(model, n: int, steps: int, x: float, fine: float) -> float:
    """The former estimate: Richardson from (n/2, S/2) and (n/4, S/4) at the measured order
    (at most 2), the order over the one cycle."""
    w2 = raw_work(model, n // 2, steps // 2, x)[0]
    w4 = raw_work(model, n // 4, steps // 4, x)[0]
    order = min(measured_order(np.array([fine]), np.array([w2]), np.array([w4])), 2.0)
    return abs(fine - w2) / (2.0**order - 1.0)


def estimates(unit: float, fine: bool) -> None:
    print("\n3. The cycle work's estimate against the truth (ratio = estimate / |error|)")
    print("| case | n, steps | work | error (rel.) | estimate (rel.) | ratio | former ratio | "
          "CPU run | CPU with estimate |")
    print("|---|---|---|---|---|---|---|---|---|")
    ratios = []
    eq = contact("sphere", 0.0, **EQUAL)
    for x in (0.25, 0.5, 0.9):
        for n, s in ((32, 4), (64, 8)):
            r, cpu = timed("sphere", 0.0, K, LOAD, tang(x), s, n=n, **EQUAL)
            _, cpu0 = timed("sphere", 0.0, K, LOAD, tang(x), s, n=n, error_estimate=False,
                            **EQUAL)
            (_, _, w, e), = r.cycles
            err = w - md(x)
            old = former(eq, n, s, x, w)
            ratios.append(e / abs(err))
            print(f"| beta = 0, Q*/kP = {x} (truth: M-D) | {n}, {s} | {w:.5e} | "
                  f"{err / md(x):+.1e} | {e / md(x):.1e} | {e / abs(err):.2f} | "
                  f"{old / abs(err):.1f} | {cpu0:.1f} s ({cpu0 / unit:.0f}) | {cpu:.1f} s "
                  f"({cpu / unit:.0f}) |", flush=True)
    model = contact("sphere", 0.3)
    plan = [((16, 4), (64, 16))] + ([((32, 8), (128, 32))] if fine else [])
    for (n, s), (nf, sf) in plan:
        r, cpu = timed("sphere", 0.3, K, LOAD, tang(0.5), s, n=n)
        _, cpu0 = timed("sphere", 0.3, K, LOAD, tang(0.5), s, n=n, error_estimate=False)
        truth = raw_work(model, nf, sf, 0.5)[0]  # n = 128 is beyond fretting's coupled limit
        (_, _, w, e), = r.cycles
        err = w - truth
        old = former(model, n, s, 0.5, w)
        ratios.append(e / abs(err))
        print(f"| beta = 0.286, Q*/kP = 0.5 (truth: ({nf}, {sf})) | {n}, {s} | {w:.5e} | "
              f"{err / truth:+.1e} | {e / truth:.1e} | {e / abs(err):.2f} | "
              f"{old / abs(err):.1f} | {cpu0:.1f} s ({cpu0 / unit:.0f}) | {cpu:.1f} s "
              f"({cpu / unit:.0f}) |", flush=True)
    arr = np.array(ratios)
    print(f"\n{arr.size} estimates: ratio from {arr.min():.2f} to {arr.max():.2f}; under 1: "
          f"{int(np.sum(arr < 1))}; above 3: {int(np.sum(arr > 3))}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--fine", action="store_true",
                    help="the coupled (32, 8) against (128, 32) (about 8 CPU min more)")
    args = ap.parse_args()
    t0 = time.process_time()
    unit = lu_unit()
    print(f"unit: dense LU of order 1024 = {unit:.3f} CPU s")
    lattice(unit)
    steps_error(unit)
    estimates(unit, args.fine)
    print(f"\ntotal CPU {time.process_time() - t0:.0f} s")


if __name__ == "__main__":
    main()
