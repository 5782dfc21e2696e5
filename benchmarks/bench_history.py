"""Speed of the history solver, as a ratio to one dense LU factorization in the same process.

Run: python benchmarks/bench_history.py [--compare REV] [--lu SIZE] [geometry ...]

Two measurements, BLAS single-threaded (the library pins one thread itself):

* **scenes**: the CPU time of the history scenes of ``config/config.yaml``
  (sphere-cycle and halfplane-cycle: k = 0.05, 0.1, 0.15, 0.2, 0.3, 0 -> 1 -> 0,
  200 steps a segment; sphere-fretting: k = 0.2, 100 steps a segment; n = 240,
  with the error estimates, as the main job computes them) over the CPU time
  of one ``scipy.linalg.lu_factor`` of a random dense SIZE x SIZE matrix
  (default 1024, median of 7), measured in the same process. The ratio is
  what the README quotes; it does not depend on the machine's speed.
* **cycle** (for each geometry, default sphere and cylinder): the wall time
  of one load-unload cycle (nu = 0.3, k = 0.15, 100 steps a segment, the
  default n), best of 3, per step in units of one LU as large as the
  largest system the run solved, and the active-set iterations.

``--compare REV`` measures the scenes ratio of the package as it was at git
revision REV (``git archive REV contactlib``, run in a subprocess) and of
this tree (also in a subprocess), alternating, twice each, and prints both
ratios (the smaller of the two runs each) and their quotient: before vs
after in one run, e.g. ``--compare 7e7dca5`` (before the solver's
speed-up of issue 17).
"""

from __future__ import annotations

import os
import sys
import time

# One BLAS thread unless the caller chose otherwise: on a shared two-core machine
# a second BLAS thread that waits for a busy core makes small factorizations
# erratically slow (measured: 0.8 ms to 18 ms for the same 300 x 300 LU).
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import json  # noqa: E402
import subprocess  # noqa: E402
import tempfile  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
from scipy import linalg  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
SCENES = {"sphere-cycle": ("sphere", (0.05, 0.1, 0.15, 0.2, 0.3), (0, 1, 0), 200),
          "halfplane-cycle": ("cylinder", (0.05, 0.1, 0.15, 0.2, 0.3), (0, 1, 0), 200),
          "sphere-fretting": ("sphere", (0.2,), (0, 1, 0.5, 1, 0.5, 1, 0.5), 100)}


def lu_time(size: int, repeats: int = 7, clock=time.perf_counter) -> float:
    a = np.random.default_rng(0).standard_normal((size, size))
    linalg.lu_factor(a, check_finite=False)  # warm-up
    times = []
    for _ in range(repeats):
        t0 = clock()
        linalg.lu_factor(a, check_finite=False)
        times.append(clock() - t0)
    return float(np.median(times))


def scenes_ratio(lu_size: int) -> dict:
    """CPU time of the config's history scenes over one LU of ``lu_size`` (same process)."""
    from contactlib.history_api import history

    history("sphere", 0.3, 0.15, [0, 1], 2, n=16)  # imports and kernel tables
    cpu = {}
    for name, (geometry, ks, path, steps) in SCENES.items():
        t0 = time.process_time()
        for k in ks:
            history(geometry, 0.3, k, path, steps)
        cpu[name] = time.process_time() - t0
    t_lu = lu_time(lu_size, clock=time.process_time)
    total = sum(cpu.values())
    return {"cpu": cpu, "total": total, "lu": t_lu, "ratio": total / t_lu}


def print_scenes(label: str, r: dict, lu_size: int) -> None:
    parts = ", ".join(f"{name} {t:.2f}" for name, t in r["cpu"].items())
    print(f"{label}: history scenes {r['total']:.2f} s CPU ({parts}); LU {lu_size} = "
          f"{r['lu'] * 1e3:.1f} ms; ratio = {r['ratio']:.0f} LU")


def compare(rev: str, lu_size: int) -> None:
    """Scenes ratio of revision ``rev`` against this tree, alternating in subprocesses."""
    with tempfile.TemporaryDirectory() as tmp:
        archive = subprocess.run(["git", "-C", str(ROOT), "archive", rev, "contactlib"],
                                 check=True, capture_output=True).stdout
        subprocess.run(["tar", "-x", "-C", tmp], input=archive, check=True)
        trees = {rev: tmp, "this tree": str(ROOT)}
        best: dict[str, dict] = {}
        for _ in range(2):
            for label, path in trees.items():
                env = dict(os.environ, PYTHONPATH=path)
                out = subprocess.run([sys.executable, __file__, "--json", "--lu", str(lu_size)],
                                     check=True, capture_output=True, text=True, env=env,
                                     cwd=tmp).stdout
                r = json.loads(out.strip().splitlines()[-1])
                if label not in best or r["ratio"] < best[label]["ratio"]:
                    best[label] = r
    for label, r in best.items():
        print_scenes(f"{label:>10s}", r, lu_size)
    print(f"speed-up: {best[rev]['ratio'] / best['this tree']['ratio']:.2f} x "
          f"(history CPU in units of one LU {lu_size}, best of 2 runs each)")


def cycles(geometries: list[str]) -> None:
    from contactlib.history_api import DEFAULT_N, history

    for geometry in geometries:
        history(geometry, 0.3, 0.15, [0, 1], 2, n=16)  # imports and kernel tables
        runs = []
        for _ in range(3):
            t0 = time.perf_counter()
            res = history(geometry, 0.3, 0.15, [0, 1, 0], 100)
            runs.append(time.perf_counter() - t0)
        t_run = min(runs)
        steps = res.load_ratio.size - 1
        # largest system: contact pressures + stick shears + delta (final sets of a step)
        size = int(np.max(np.count_nonzero(res.state > 0, axis=1)
                          + np.count_nonzero(res.state == 1, axis=1)) + 1)
        t_lu = lu_time(size)
        per_step = t_run / steps
        print(f"cycle {geometry:8s} n={DEFAULT_N} steps={steps} {t_run:6.2f}s "
              f"(best of 3; slowest {max(runs):.2f}s)  largest system={size}  "
              f"LU={t_lu * 1e3:6.2f} ms  per step={per_step * 1e3:6.2f} ms "
              f"= {per_step / t_lu:5.1f} LU  iterations/step={res.iterations[1:].mean():.2f} "
              f"(max {res.iterations.max()})  converged={bool(res.converged.all())}")


def main(argv: list[str]) -> None:
    lu_size = 1024
    if "--lu" in argv:
        i = argv.index("--lu")
        lu_size = int(argv[i + 1])
        del argv[i:i + 2]
    if "--json" in argv:  # one measurement for --compare
        print(json.dumps(scenes_ratio(lu_size)))
        return
    if "--compare" in argv:
        i = argv.index("--compare")
        compare(argv[i + 1], lu_size)
        return
    print(f"BLAS threads={os.environ['OPENBLAS_NUM_THREADS']}")
    print_scenes("scenes", scenes_ratio(lu_size), lu_size)
    cycles(argv or ["sphere", "cylinder"])


if __name__ == "__main__":
    main(sys.argv[1:])
