"""Cost of the stress field under a sphere's fretting step against the step's solve (issue 38).

Run: python benchmarks/bench_stresses_grid.py [n]   (default n = 64)
     python benchmarks/bench_stresses_grid.py --accuracy   (the tables of docs/stresses.md)

The run: a sphere on a body of the same material (nu = 0.3: Dundurs beta = 0), friction
0.3, pressed to P_max in 8 steps and then pushed to Q = 0.5 mu P_max in 8 more
(:func:`contactlib.solvers.fretting_sphere.run_sphere_fretting`, n x n cells over [-1.2, 1.2]^2
a_max). One step's solve is the median wall time of the 8 tangential steps (timed
through the run's progress callback). Then, in the same process, the field of the last
step (:func:`contactlib.stresses.grid.fretting_step_stresses`, the stresses and the
derived measures, no estimate; the median of 3):

* a 100 x 100 (x, z) plane at y = 0 (x in [-1.5, 1.5], z in [0.015, 1.5] a_max), by the
  direct sum over the corners at any points;
* the 3-D field on the lattice of the cell corners, (n + 1)^2 points at 100 depths, by
  the FFT convolution at each depth;
* that 3-D field with its estimate (the fields of the runs with n/2 and n/4 cells; their
  solves, about 1/8 and 1/64 of the run's, are not counted).

Each is printed as seconds and as the ratio to one step's solve, with the peak memory the
field allocates (``tracemalloc``).

``--accuracy`` prints instead (about 2 min of CPU): the largest error of the field of a
Hertz pressure on n x n cells against Huber's axis, and of Cattaneo-Mindlin tractions
against the Hankel field of :mod:`contactlib.stresses.tangential` (x in {-0.8, 0, 0.5},
y in {0, 0.3}, z in {0.3, 0.5, 0.8}), each with the measured order; the maxima of the
fretting field of equal nu = 0 bodies (where Cattaneo-Mindlin is exact) at n = 16 ... 128
with their estimates, the change to 2n and the error against the exact field, and where
on the plane the estimate covers that error; and the
maxima of equal nu = 0.3 bodies (gamma = 0.43: the shear turns off x) at n = 64 against
the Cattaneo-Mindlin approximation's field; and the field after a reversal (Q to
-0.25 mu P) against Mindlin and Deresiewicz's tractions' Hankel field.
"""

from __future__ import annotations

import statistics
import sys
import time
import tracemalloc

import numpy as np

from contactlib.solvers.fretting_sphere import grid_operators, run_sphere_fretting
from contactlib.history_api import load_levels
from contactlib.model import contact
from contactlib.stresses.grid import fretting_step_stresses, grid_stresses
from contactlib.stresses.tangential import (CARTESIAN, cartesian_stresses,
                                            mindlin_deresiewicz_tractions,
                                            mindlin_sphere_stresses)

NU, FRICTION, STEPS = 0.3, 0.3, 8


def _run(n: int, steps: int = STEPS, nu: float = NU, tangential=(0, 0, 0.5)):
    model = contact("sphere", nu, indenter_modulus=1.0, indenter_nu=nu)  # beta = 0
    ops = grid_operators(model, n)
    load = [0] + [1] * (len(tangential) - 1)
    big_p = load_levels(load, steps)[0][1:] * ops.p_max
    big_q = load_levels(tangential, steps)[0][1:] * FRICTION * ops.p_max
    stamps = [time.perf_counter()]
    raw = run_sphere_fretting(ops, FRICTION, big_p, big_q, keep_fields=True,
                              progress=lambda i, m: stamps.append(time.perf_counter()))
    return ops, raw, np.diff(stamps)


def _timed(f, repeat: int = 3):
    times, out = [], None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t0)
    tracemalloc.start()
    f()
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    return statistics.median(times), peak, out


def main(n: int) -> None:
    ops, raw, step_times = _run(n)
    c_ops, c_raw, _ = _run(n // 2, STEPS // 2)
    f_ops, f_raw, _ = _run(n // 4, STEPS // 4)
    t_step = float(np.median(step_times[STEPS:]))
    last = 2 * STEPS
    x, z = np.linspace(-1.5, 1.5, 100), np.linspace(0.015, 1.5, 100)
    cases = [
        ("plane 100 x 100, direct", lambda: fretting_step_stresses(
            ops, raw, last, x, [0.0], z, nu=NU)),
        (f"3-D {n + 1}^2 x 100, lattice FFT", lambda: fretting_step_stresses(
            ops, raw, last, None, None, z, nu=NU)),
        (f"3-D {n + 1}^2 x 100 + estimate", lambda: fretting_step_stresses(
            ops, raw, last, None, None, z, nu=NU, coarse=(c_ops, c_raw, last // 2),
            coarser=(f_ops, f_raw, last // 4))),
    ]
    print(f"n = {n}: one tangential step's solve {t_step:.3f} s (median of {STEPS}; the "
          f"whole run of {2 * STEPS} steps {step_times.sum():.2f} s)")
    for label, f in cases:
        t, peak, ds = _timed(f)
        print(f"{label:34s} {t:7.3f} s = {t / t_step:7.1f} steps' solves   "
              f"peak memory {peak / 2**20:6.1f} MiB   max von Mises "
              f"{ds.attrs['max_von_mises']:.5f}")


def _cells(n: int, friction: float, ratio: float):
    """Hertz pressure and the Cattaneo-Mindlin shear at the centres of n x n cells."""
    h = 2.4 / n
    c = -1.2 + h * (np.arange(n) + 0.5)
    r2 = c[:, None] ** 2 + c[None, :] ** 2
    p = np.sqrt(np.clip(1 - r2, 0, None))
    q = np.zeros((2, n, n))
    stick = (1 - ratio) ** (1 / 3)
    q[0] = friction * (p - np.sqrt(np.clip(stick**2 - r2, 0, None)))
    return p, q, h


def _orders(errors):
    e = np.array(errors)
    return " ".join(f"{o:.2f}" for o in np.log2(e[:-1] / e[1:]))


def accuracy() -> None:
    z = np.array([0.2, 0.48, 1.0, 2.0])
    huber_zz = -1 / (1 + z * z)
    huber_rr = -(1 + NU) * (1 - z * np.arctan(1 / z)) + 1 / (2 * (1 + z * z))
    errors = []
    for n in (32, 64, 128):
        p, _, h = _cells(n, 0.0, 0.0)
        s = grid_stresses(p, None, h, (-1.2, -1.2), [0.0], [0.0], z, NU)
        errors.append(max(np.abs(s["sigma_zz"][:, 0, 0] - huber_zz).max(),
                          np.abs(s["sigma_xx"][:, 0, 0] - huber_rr).max()))
        print(f"Huber axis, Hertz pressure on {n}^2 cells: largest error {errors[-1]:.2e} p0")
    print(f"  orders {_orders(errors)}")
    x, y, zc = np.array([-0.8, 0.0, 0.5]), np.array([0.0, 0.3]), np.array([0.3, 0.5, 0.8])
    ref = mindlin_sphere_stresses(0.3, 0.5, x, y, zc, NU, points=1601)
    errors = []
    for n in (24, 48, 96, 192):
        p, q, h = _cells(n, 0.3, 0.5)
        s = grid_stresses(p, q, h, (-1.2, -1.2), x, y, zc, NU)
        errors.append(max(np.abs(s[k] - ref[k].values).max() for k in CARTESIAN))
        print(f"Cattaneo-Mindlin (mu = 0.3, Q/mu P = 0.5) on {n}^2 cells: largest error "
              f"{errors[-1]:.2e} p0")
    print(f"  orders {_orders(errors)}")
    fx, fz = np.linspace(-1.2, 1.2, 25), np.linspace(0.1, 1.0, 10)
    for nu, sizes in ((0.0, (16, 32, 64, 128)), (0.3, (16, 32, 64))):
        runs = {n: _run(n, 4, nu)[:2] for n in sizes}
        exact = mindlin_sphere_stresses(0.3, 0.5, fx, [0.0], fz, nu)
        ds = {n: fretting_step_stresses(
            *runs[n], 8, fx, [0.0], fz, nu=nu,
            coarse=(*runs[n // 2], 8) if n // 2 in runs else None,
            coarser=(*runs[n // 4], 8) if n // 4 in runs else None) for n in sizes}
        for name in ("von_mises", "tresca"):
            top = float(exact[name].max())
            print(f"fretting, equal nu = {nu} bodies, mu = 0.3, Q/mu P = 0.5, {name}: "
                  f"Cattaneo-Mindlin {top:.6f}")
            for n in sizes:
                a = ds[n].attrs
                err = a.get(f"max_{name}_error", float("nan"))
                nxt = (f"{abs(a[f'max_{name}'] - ds[2 * n].attrs[f'max_{name}']):.1e}"
                       if 2 * n in ds else "  -    ")
                print(f"  n = {n:3d}: max {a[f'max_{name}']:.6f} at (x, z) = "
                      f"({a[f'max_{name}_x']:+.2f}, {a[f'max_{name}_z']:.2f})  estimate "
                      f"{err:.1e}  change to 2n {nxt}  off Cattaneo-Mindlin "
                      f"{abs(a[f'max_{name}'] - top):.1e}")
        if nu == 0.0:  # Cattaneo-Mindlin exact: where on the plane the estimate covers
            for n in sizes[1:]:
                for name in ("von_mises", "sigma_xx", "sigma_xz"):
                    err = np.abs(ds[n][name].values - exact[name].values)
                    est = ds[n][f"{name}_error"].values
                    big = err > 1e-6
                    print(f"  n = {n:3d}, {name}: the estimate covers the error at "
                          f"{100 * np.mean(est >= err):.1f} % of the plane's points, at "
                          f"least {np.min(est[big] / err[big]):.2f} of it")
        fine = ds[sizes[-1]]
        print(f"  n = {sizes[-1]}: largest difference of von Mises to Cattaneo-Mindlin on "
              f"the plane {float(np.abs(fine.von_mises - exact.von_mises).max()):.1e} "
              f"(estimate there at most {float(fine.von_mises_error.max()):.1e})")
    reversal(fx, fz)


def reversal(fx: np.ndarray, fz: np.ndarray) -> None:
    """Q: 0 -> 0.5 mu P -> -0.25 mu P, equal nu = 0 bodies, against Mindlin-Deresiewicz."""
    xi, p, q, _, _ = mindlin_deresiewicz_tractions(FRICTION, 0.5, -0.25, 1001)
    ref = cartesian_stresses(xi, p, fx, [0.0], fz, 0.0, shear_x=q)
    for n in (32, 64, 128):
        ops, raw, _ = _run(n, 4, 0.0, (0, 0, 0.5, -0.25))
        ds = fretting_step_stresses(ops, raw, 12, fx, [0.0], fz, nu=0.0)
        err = max(float(np.abs(ds[k].values - ref[k]).max()) for k in CARTESIAN)
        print(f"after a reversal (Mindlin-Deresiewicz), n = {n}: largest error {err:.1e} p0")


if __name__ == "__main__":
    if "--accuracy" in sys.argv[1:]:
        accuracy()
    else:
        main(int(sys.argv[1]) if len(sys.argv) > 1 else 64)
