"""Machine-independent cost ratios of the default method, measured in one run.

    python benchmarks/bench_ratios.py

Takes about 2-3 minutes. This machine is shared and noisy, so every time is
the best of 3 repeats, and the printed quantities are ratios of two times
measured moments apart in the same process. Read them as "how many of the
reference operation one of ours costs". Absolute times are printed only for
context.

a. Kernels vs raw scipy. Time of ``contactlib.kernels.disc.pressure_disc``
   and ``shear_disc`` (sphere), and of the half-plane ``pressure_strip`` and
   ``shear_strip`` (cylinder), on N (r, s) pairs, divided by the time of one
   ``scipy.special.ellipk`` + ``ellipe`` pass over the same N parameters
   m = (min(r, s) / max(r, s))^2. "disc pressure = 2.1 x" means one
   evaluation of the pressure disc kernel (w, u, du/dx at once) costs 2.1
   elliptic-integral passes. The strip kernels use no elliptic integrals;
   their ratio puts them on the same scale.
b. One solve vs one LU. ``solve_default(Geometry("sphere", 0.3), 0.5, n)``,
   (i) as called by the API (builds both collocation operators), (ii) with
   the operators given through ``ops=``, and (iii) with operators and the
   converged k given (only the Newton iterations on the fine system remain),
   divided by one ``scipy.linalg.lu_factor`` of a dense matrix of the partial
   slip system's size n + 1 + (M - 1) + 1 (M = stick nodes of the mesh). For
   n > 128, (i) and (ii) also include the n = 64 and 128 solves of the
   Richardson warm start of k. "ops" is the cost of building the operators.
c. Sweep cost vs n. ``contactlib.sweep("sphere", 0.3, 5 stick ratios 0.1 ...
   0.9, n=n)`` (whole public API: solve, checks, energy, profiles) for n = 64
   ... 1024, with the log-log slope fitted over all n and the exponent of the
   last doubling (2 means cost ~ n^2, 3 means ~ n^3).

BLAS runs single-threaded (OPENBLAS_NUM_THREADS, OMP_NUM_THREADS and
MKL_NUM_THREADS default to 1 here; set them to override): on a shared machine
a multi-threaded LU swings by 10x with the load, which would make the
reference of (b) meaningless.
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")  # before numpy is imported

import time

import numpy as np
from scipy import linalg, special

import contactlib
from contactlib.solvers.default_method import operator_part, solve_default
from contactlib.discretization.elements import graded_mesh
from contactlib.model.geometry import Geometry
from contactlib.kernels import disc, strip

REPEAT = 3
NU = 0.3


def best(f, repeat: int = REPEAT):
    """(best wall time, result of the last call)."""
    t, out = np.inf, None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = f()
        t = min(t, time.perf_counter() - t0)
    return t, out


def lu_time(size: int) -> float:
    a = np.random.default_rng(0).standard_normal((size, size)) + size * np.eye(size)
    return best(lambda: linalg.lu_factor(a, check_finite=False))[0]


def kernels(side: int = 1000) -> None:
    r = np.linspace(0.0, 1.2, side)[:, None]  # inside and outside the loaded disc
    s = (np.arange(1, side + 1) / side)[None, :]
    m = ((np.minimum(r, s) / np.maximum(r, s)) ** 2).copy()  # (side, side), materialized
    t_ell = best(lambda: (special.ellipk(m), special.ellipe(m)))[0]
    rows = [("disc pressure (sphere)", lambda: disc.pressure_disc(r, s, NU)),
            ("disc shear (sphere)", lambda: disc.shear_disc(r, s, NU)),
            ("strip pressure (half-plane)", lambda: strip.pressure_strip(r, s, NU)),
            ("strip shear (half-plane)", lambda: strip.shear_strip(r, s, NU))]
    print(f"a. kernels on N = {m.size:,} (r, s) pairs (w, u, du/dx at once), best of {REPEAT}")
    print(f"   {'ellipk + ellipe (scipy)':30s} {t_ell * 1e3:8.1f} ms   = 1 pass")
    for name, f in rows:
        t = best(f)[0]
        print(f"   {name:30s} {t * 1e3:8.1f} ms   = {t / t_ell:5.2f} x one ellipk+ellipe pass")


def solve_vs_lu(ns=(128, 256, 512, 1024), c: float = 0.5) -> None:
    geom = Geometry("sphere", NU)
    print(f"\nb. one solve (sphere, nu = {NU}, c/a = {c}) vs one LU of the system size, "
          f"best of {REPEAT}")
    print(f"   {'n':>5s} {'size':>5s} {'LU ms':>7s} {'ops ms':>8s} | {'solve':>8s} {'x LU':>6s} | "
          f"{'+ops':>8s} {'x LU':>6s} | {'+ops+k':>8s} {'x LU':>6s} | Newton its")
    for n in ns:
        r = graded_mesh(n, c).nodes
        size = n + 1 + (graded_mesh(n, c).stick_index - 1) + 1
        t_lu = lu_time(size)
        t_ops, ops = best(lambda r=r: (operator_part(geom, r, r, "normal"),
                                       operator_part(geom, r, r, "shear")))
        t_plain, d = best(lambda n=n: solve_default(geom, c, n))
        t_ops_given = best(lambda n=n, ops=ops: solve_default(geom, c, n, ops=ops))[0]
        t_k, d_k = best(lambda n=n, ops=ops, k=d.k: solve_default(geom, c, n, ops=ops,
                                                                   k_guess=k))
        print(f"   {n:5d} {size:5d} {t_lu * 1e3:7.2f} {t_ops * 1e3:8.1f} | "
              f"{t_plain * 1e3:8.1f} {t_plain / t_lu:6.0f} | "
              f"{t_ops_given * 1e3:8.1f} {t_ops_given / t_lu:6.0f} | "
              f"{t_k * 1e3:8.1f} {t_k / t_lu:6.1f} | {d.iterations} / {d_k.iterations}")
    print("   (ms: wall time; x LU: that time / one lu_factor of size x size; '+ops': operators "
          "given;\n    '+ops+k': operators and the converged k given; Newton its: cold / warm)")


def sweep_cost(ns=(64, 128, 256, 512, 1024)) -> None:
    ratios = list(np.linspace(0.1, 0.9, 5))
    print(f"\nc. contactlib.sweep of 5 stick ratios 0.1 ... 0.9 (sphere, nu = {NU}), "
          f"best of {REPEAT}")
    ts = []
    for n in ns:
        t = best(lambda n=n: contactlib.sweep("sphere", NU, ratios, n=n))[0]
        ts.append(t)
        grow = f"   x {t / ts[-2]:5.2f} for 2 x n" if len(ts) > 1 else ""
        print(f"   n = {n:5d}: {t:7.3f} s{grow}")
    slope = np.polyfit(np.log(ns), np.log(ts), 1)[0]
    last = np.log(ts[-1] / ts[-2]) / np.log(ns[-1] / ns[-2])
    print(f"   fitted exponent {slope:.2f} (n = {ns[0]} ... {ns[-1]}); "
          f"last doubling {last:.2f}")


def main() -> None:
    t0 = time.perf_counter()
    solve_default(Geometry("sphere", NU), 0.5, 32)  # warm-up: imports, caches
    strip.pressure_strip(0.5, 1.0, NU)
    kernels()
    solve_vs_lu()
    sweep_cost()
    threads = os.environ["OPENBLAS_NUM_THREADS"]
    print(f"\n(total {time.perf_counter() - t0:.0f} s; BLAS threads {threads}; "
          f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} CPUs)")


if __name__ == "__main__":
    main()
