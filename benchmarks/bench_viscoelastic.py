"""Cost of a viscoelastic history step: independent of the step count, and against an elastic step.

The hereditary integral is updated recursively (contactlib.solvers.history_solver,
``run_history``): a step keeps 2 (N + 1) traction-sized arrays for N Prony
terms, whatever the number of steps before it. This script measures that.

Run: python benchmarks/bench_viscoelastic.py [--n N] [--segments M] [--n-ratio N2] [--part 1|2]

1. Step count. A fretting path 0 -> 1, then M cycles 1 -> 0.5 -> 1 (100 steps
   a segment, sphere, nu = 0.3, k = 0.2, two Prony terms, T/tau = 1 a
   segment) at ``--n`` elements (default 60), so 100 (2 M + 1) steps
   (default M = 500: 100 100 steps). The time of every step is taken from
   the progress callback; the script prints the median time per step over
   windows of 1000 steps early, in the middle and at the end of the run
   (and the mean, which includes the turning points of the path and any
   time the shared machine took away), and their ratios to the first
   window (independent of the step count: ratios near 1).
2. Viscoelastic against elastic. The same path with M = 5 at ``--n-ratio``
   elements (default 240, the default resolution) and the same mesh: elastic,
   viscoelastic with T/tau ~ 1 and viscoelastic with T/tau = 1e-4 (the contact
   of the elastic run, so the difference is the recursion's own cost), run
   alternately five times each; prints the best CPU time per step of each
   (process time: what other processes on a shared machine take is not
   counted) and the ratios to the elastic one (target <= 2).

BLAS runs single-threaded unless the caller sets OPENBLAS_NUM_THREADS /
OMP_NUM_THREADS. The machine may be shared: read the ratios, which are
measured in one process, rather than the absolute times.
"""

from __future__ import annotations

import argparse
import os
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np

from contactlib.solvers import history_solver as hs
from contactlib.history_api import creep_extent, load_levels, step_times
from contactlib.model import contact

PRONY = ((0.3, 0.5), (0.3, 5.0))
STEPS = 100  # steps a segment


def fretting(cycles: int) -> list[float]:
    return [0.0, 1.0] + [0.5, 1.0] * cycles


def run(n: int, cycles: int, viscous: bool, stamps: list[float] | None = None,
        segment: float = 1.0) -> float:
    """Wall time per step of ``run_history`` (operators excluded)."""
    model = contact("sphere", 0.3, relaxation=PRONY if viscous else ())
    ops = hs.build_operators(model, n, creep_extent(contact("sphere", 0.3, relaxation=PRONY)))
    path = fretting(cycles)
    levels, _ = load_levels(path, STEPS)
    times = step_times([segment] * (len(path) - 1), STEPS) if viscous else None
    progress = None
    if stamps is not None:
        def progress(i: int, total: int) -> None:
            stamps.append(time.perf_counter())
    t0 = time.process_time()  # CPU time of this process: not the time others took away
    hs.run_history(ops, 0.2, levels, progress=progress, times=times)
    return (time.process_time() - t0) / (levels.size - 1)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=60)
    parser.add_argument("--segments", type=int, default=500, help="cycles M of part 1")
    parser.add_argument("--n-ratio", type=int, default=240)
    parser.add_argument("--part", type=int, choices=(1, 2), default=None,
                        help="run only part 1 or part 2")
    args = parser.parse_args()
    if args.part != 2:
        step_count(args)
    if args.part != 1:
        against_elastic(args)


def step_count(args: argparse.Namespace) -> None:
    """Part 1: time per step (wall clock, per step) along a long path."""
    stamps: list[float] = []
    start = time.perf_counter()
    run(args.n, args.segments, True, stamps)
    dt = np.diff(np.concatenate([[start], stamps]))
    total = dt.size
    window = min(1000, total // 4)
    starts = sorted({window, total // 10, total // 2, total - window})
    print(f"1. viscoelastic fretting path, n = {args.n}, {total} steps "
          f"({2 * args.segments + 1} segments of {STEPS}), {len(PRONY)} Prony terms; "
          f"{time.perf_counter() - start:.1f} s")
    first = None
    for s in starts:
        med = float(np.median(dt[s:s + window]))
        mean = float(np.mean(dt[s:s + window]))
        first = (med, mean) if first is None else first
        print(f"   steps {s:>7d} ... {s + window:>7d}: median {1e3 * med:7.3f} ms a step "
              f"(ratio to the first window {med / first[0]:5.2f}), mean {1e3 * mean:7.3f} ms "
              f"(ratio {mean / first[1]:5.2f})")



def against_elastic(args: argparse.Namespace) -> None:
    """Part 2: CPU time per step, viscoelastic against elastic, same path and mesh."""
    cases = {"elastic": (False, 1.0), "viscoelastic, T/tau_i = 2 and 0.2 a segment": (True, 1.0),
             "viscoelastic, fast (1e-4 of tau a segment)": (True, 1e-4)}
    best = {name: np.inf for name in cases}
    for _ in range(5):
        for name, (viscous, segment) in cases.items():
            best[name] = min(best[name], run(args.n_ratio, 5, viscous, segment=segment))
    print(f"2. same path (11 segments of {STEPS} steps), n = {args.n_ratio}, CPU time, best of 5 "
          f"(target: viscoelastic <= 2 x elastic):")
    for name, value in best.items():
        print(f"   {name:<45s} {1e3 * value:7.3f} ms a step, ratio to elastic "
              f"{value / best['elastic']:5.2f}")
    print("   (at T/tau ~ 1 creep enlarges the contact, so the linear systems are larger "
          "than the elastic ones; the fast case has the elastic contact and shows the cost "
          "of the recursion itself)")


if __name__ == "__main__":
    main()
