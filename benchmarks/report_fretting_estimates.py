"""Fretting: do the error estimates cover the true error without inflating it?
(docs/fretting.md, "How good are the estimates")

    python benchmarks/report_fretting_estimates.py            # about 4 min on 2 cores
    python benchmarks/report_fretting_estimates.py --cylinder-n 120 --cylinder-steps 40
                                                  # the cylinder's defaults: about 15 min

For each path, ``contactlib.fretting`` runs with its estimates, and the truth is the same
path refined fourfold in n and in steps a segment (``error_estimate=False``), both timed
in CPU seconds in this run. Printed per quantity: the value, its estimate, the true error
(the run minus the refined one), the ratio estimate / |true error| (want 1 to 3; below 1
the estimate under-covers), and whether the point is flagged (estimate above
``max_error`` = 1e-3 at the quantity's scale: absolute for the stick ratio, units a_max
for the offset, relative to the cycle's work for the work) and whether it truly is off
by more than that.

Paths (k = 0.3): P to P_max, then Q: 0 -> Q* -> -Q* -> Q* at Q*/kP = 0.3, 0.6, 0.9;
and a varying P: (P, Q/kP_max) = (1, 0.3) -> (0.6, -0.3) -> (1, 0.3) -> (0.6, -0.3).
Cylinder: rigid on nu = 0.5 (beta = 0) and rigid on nu = 0.3 (beta = 0.286, coupled),
default here n = 64 and 16 steps (the truth n = 256, 64 steps). Sphere: two equal bodies
with nu = 0 (beta = gamma = 0), at its defaults n = 64 and 8 steps; a fourfold refined
sphere (n = 256) takes about 8 CPU minutes a path, so there the truth is Cattaneo-Mindlin
and Mindlin-Deresiewicz, exact for this pair (``--sphere-refined`` uses the n = 256 run
instead). The sphere's varying-P path runs at n = 16, 4 steps, against n = 64, 16 steps.
"""

from __future__ import annotations

import argparse
import os
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

from contactlib import fretting  # noqa: E402

K = 0.3
MAX_ERROR = 1e-3
SPHERE_PAIR = {"indenter_modulus": 1.0, "indenter_nu": 0.0}  # equal bodies, nu = 0


def _cycle(x: float) -> tuple[list[float], list[float]]:
    return [0, 1, 1, 1, 1], [0, 0, x, -x, x]


VARYING = ([0, 1, 0.6, 1, 0.6], [0, 0.3, -0.3, 0.3, -0.3])


def _timed(*args, **kw):
    t0 = time.process_time()
    r = fretting(*args, **kw)
    return r, time.process_time() - t0


def _exact_sphere(r, x: float) -> dict[str, float]:
    """Cattaneo-Mindlin's c/a and Mindlin-Deresiewicz's cycle work (beta = gamma = 0)."""
    bracket = 1 - (1 - x) ** (5 / 3) - 5 * x / 6 * (1 + (1 - x) ** (2 / 3))
    c_mind = 4.0  # (2 - nu1)/G1 + (2 - nu2)/G2 in units 1/E* for equal bodies with nu = 0
    return {"ratio": (1 - x) ** (1 / 3), "work": 9 * K**2 * r.p_max**2 * c_mind / 10 * bracket}


def _rows(r, truth: dict[str, np.ndarray], offset: bool) -> list[tuple]:
    """(quantity, value, estimate, true error, scale) for the stick ratio at Q* (point 2)
    and at the path's end, the stick offset there (cylinder), and each cycle's work."""
    out = []
    for j in (2, r.point_step.size - 1):
        out.append((f"c/a at point {j}", r.stick_ratio[r.point_step[j]],
                    r.stick_ratio_error[j], r.stick_ratio[r.point_step[j]] - truth["ratio"][j],
                    1.0))
    if offset and r.beta != 0.0:  # beta = 0: the offset is 0 by symmetry
        for j in (2, r.point_step.size - 1):
            out.append((f"offset at point {j}", r.stick_offset[r.point_step[j]],
                        r.stick_offset_error[j],
                        r.stick_offset[r.point_step[j]] - truth["offset"][j], 1.0))
    for (i, j, w, e), wt in zip(r.cycles, truth["work"]):
        out.append((f"work {i}->{j}", w, e, w - wt, abs(w)))
    return out


def _truth_of(r) -> dict[str, np.ndarray]:
    return {"ratio": r.stick_ratio[r.point_step], "offset": r.stick_offset[r.point_step],
            "work": np.array([w for _, _, w, _ in r.cycles])}


def _print(name: str, rows: list[tuple], cpu: float, cpu_truth: float, ratios: list) -> None:
    print(f"\n{name}   (CPU {cpu:.1f} s with estimates; truth {cpu_truth:.1f} s)")
    print("  quantity          value         estimate   true error   est/|err|  flagged  "
          "truly off")
    for q, v, e, d, scale in rows:
        ratio = e / abs(d) if d != 0 else np.inf
        if abs(d) > 1e-12 * max(scale, 1e-300):
            ratios.append((name, q, ratio))
        print(f"  {q:16s}  {v:+.6e}  {e:.2e}   {d:+.2e}    {ratio:8.2f}   "
              f"{str(bool(e > MAX_ERROR * scale)):5s}    {bool(abs(d) > MAX_ERROR * scale)}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cylinder-n", type=int, default=64)
    ap.add_argument("--cylinder-steps", type=int, default=16)
    ap.add_argument("--sphere-refined", action="store_true",
                    help="the sphere's truth from n = 256 (about 8 CPU min a path)")
    args = ap.parse_args()
    n, st = args.cylinder_n, args.cylinder_steps
    ratios: list = []
    t_start = time.process_time()
    cyl = [(f"cylinder beta = 0, Q*/kP = {x}", 0.5, *_cycle(x)) for x in (0.3, 0.6, 0.9)]
    cyl += [(f"cylinder beta = 0.286, Q*/kP = {x}", 0.3, *_cycle(x)) for x in (0.3, 0.6)]
    cyl += [(f"cylinder beta = {b}, varying P", nu, *VARYING) for b, nu in (("0", 0.5),
                                                                          ("0.286", 0.3))]
    print(f"Cylinder: n = {n}, {st} steps a segment; truth n = {4 * n}, {4 * st} steps")
    for name, nu, lp, tp in cyl:
        r, cpu = _timed("cylinder", nu, K, lp, tp, st, n=n)
        t, cpu_t = _timed("cylinder", nu, K, lp, tp, 4 * st, n=4 * n, error_estimate=False)
        _print(name, _rows(r, _truth_of(t), True), cpu, cpu_t, ratios)
    print("\nSphere: equal bodies, nu = 0, n = 64, 8 steps a segment")
    for x in (0.3, 0.6, 0.9):
        lp, tp = _cycle(x)
        r, cpu = _timed("sphere", 0.0, K, lp, tp, 8, n=64, **SPHERE_PAIR)
        if args.sphere_refined:
            t, cpu_t = _timed("sphere", 0.0, K, lp, tp, 32, n=256, error_estimate=False,
                              **SPHERE_PAIR)
            truth = _truth_of(t)
        else:
            ex = _exact_sphere(r, x)
            truth = {"ratio": np.full(5, ex["ratio"]), "work": np.array([ex["work"]])}
            cpu_t = 0.0
        _print(f"sphere beta = 0, Q*/kP = {x}", _rows(r, truth, False), cpu, cpu_t, ratios)
    r, cpu = _timed("sphere", 0.0, K, *VARYING, 4, n=16, **SPHERE_PAIR)
    t, cpu_t = _timed("sphere", 0.0, K, *VARYING, 16, n=64, error_estimate=False, **SPHERE_PAIR)
    _print("sphere beta = 0, varying P (n = 16, 4 steps; truth n = 64, 16 steps)",
           _rows(r, _truth_of(t), False), cpu, cpu_t, ratios)
    arr = np.array([x for _, _, x in ratios])
    print(f"\n{arr.size} quantities: est/|err| from {arr.min():.2f} to {arr.max():.2f}; "
          f"within [1/3, 3]: {int(np.sum((arr >= 1 / 3) & (arr <= 3)))}; "
          f"under 1 (not covered): {int(np.sum(arr < 1))}")
    for name, q, x in ratios:
        if x < 1 / 3 or x > 3:
            print(f"  outside [1/3, 3]: {name}, {q}: {x:.2f}")
    print(f"total CPU {time.process_time() - t_start:.0f} s")


if __name__ == "__main__":
    main()
