"""The sphere under a prescribed rigid shift (``fretting(..., tangential_displacement=True)``):
accuracy against Mindlin's Q(s), Cattaneo's stick ratio and Mindlin–Deresiewicz's cycle
work, the gross-sliding cycle, the round trip through a force-controlled run, and the cost
as a ratio to a normal-load cycle of ``history`` timed in the same run.

    python benchmarks/report_fretting_sphere_displacement.py            # about 20 s
    python benchmarks/report_fretting_sphere_displacement.py --coupled  # about 1 min

Two equal bodies with nu = 0 (beta = gamma = 0: the closed forms are exact), k = 0.3, P to
P_max, then the shift s: 0 -> s_a -> -s_a -> s_a, 4 steps a segment, through ``fretting``
with its estimates (n/2 and, from n = 64, n/4). Units E* = R = 1, lengths over a_max; the
sliding shift s* = 3 k P C/16 = 0.3 (C = 4). Q/(kP) = 1 - (1 - s/s*)^(3/2) below s*; the
cycle's work is Mindlin–Deresiewicz's at x = Q(s_a)/(kP), and past s* the Masing loop with
its sliding plateaus, W_MD(1) + 4 k P (s_a - s*). The round trip prescribes a
force-controlled run's shifts at its points (Q* = 0.5 k P; the beta = 0 pair and the rigid
sphere on nu = 0.3, beta = 0.286) and compares Q and c/a at the points. ``--coupled``: the
rigid sphere on nu = 0.3 under s: 0 -> 0.2 -> -0.2 -> 0.2 (Q* about 0.65-0.71 k P) at
(n, steps) = (16, 4) and (32, 8) with their estimates, against the run refined fourfold
from (16, 4), (64, 16): each estimate over the difference (want 1 to 3).
"""

from __future__ import annotations

import sys
import time

import numpy as np

from contactlib import fretting, history

K = 0.3
P_MAX = 4.0 / 3.0
S_STAR = 3 * K * P_MAX * 4.0 / 16
EXACT = dict(indenter_modulus=1.0, indenter_nu=0.0)


def md_work(x: float) -> float:
    bracket = 1 - (1 - x) ** (5 / 3) - 5 * x / 6 * (1 + (1 - x) ** (2 / 3))
    return 9 * K * K * P_MAX * P_MAX * 4.0 / 10 * bracket


def main() -> None:
    t0 = time.perf_counter()
    history("sphere", 0.3, 0.3, [0, 1, 0], 200)
    ref = time.perf_counter() - t0
    print(f"history reference: {ref:.2f} s")
    print("| s_a/s* | n | Q/kP − Mindlin | est. | c/a − (1−x)^⅓ | est. "
          "| cycle work rel. error | est. | time | × history |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for frac in (0.3, 0.6, 0.9, 1.5):
        amp = frac * S_STAR
        for n in (32, 64):
            t0 = time.perf_counter()
            r = fretting("sphere", 0.0, K, [0, 1, 1, 1, 1], [0, 0, amp, -amp, amp], 4, n=n,
                         tangential_displacement=True, **EXACT)
            dt = time.perf_counter() - t0
            j = r.point_step[2]
            x = 1 - (1 - min(frac, 1.0)) ** 1.5
            c = (1 - x) ** (1 / 3)
            work = md_work(x) + 4 * K * P_MAX * max(amp - S_STAR, 0.0)
            (_, _, w, w_est), = r.cycles
            ok = "" if r.converged.all() else " (not converged)"
            print(f"| {frac} | {n} | {r.force_ratio[j] - x:.1e} | {r.force_ratio_error[2]:.1e} "
                  f"| {r.stick_ratio[j] - c:.1e} | {r.stick_ratio_error[2]:.1e} "
                  f"| {w / work - 1:.1e} | {w_est / work:.1e} | {dt:.1f} s{ok} "
                  f"| {dt / ref:.1f} |")
    print()
    print("round trip (n = 32, 4 steps; Q* = 0.5 k P): max over the points")
    print("| pair | beta | Q/kP difference | est. | c/a difference | est. |")
    print("|---|---|---|---|---|---|")
    load, tang = [0, 1, 1, 1, 1], [0, 0, 0.5, -0.5, 0.5]
    for name, nu, extra in (("equal, nu = 0", 0.0, EXACT), ("rigid on nu = 0.3", 0.3, {})):
        f = fretting("sphere", nu, K, load, tang, 4, n=32, **extra)
        shifts = [0.0, 0.0] + [float(v) for v in f.shift[f.point_step[2:]]]
        d = fretting("sphere", nu, K, load, shifts, 4, n=32, tangential_displacement=True,
                     **extra)
        pts = d.point_step[2:]
        dq = np.abs(d.force_ratio[pts] - np.array(tang[2:]))
        dc = np.abs(d.stick_ratio[pts] - f.stick_ratio[pts])
        print(f"| {name} | {d.beta:.3f} | {dq.max():.1e} | {d.force_ratio_error[2:].min():.1e} "
              f"| {dc.max():.1e} | {d.stick_ratio_error[2:].min():.1e} |")


def coupled() -> None:
    path = [0, 0, 0.2, -0.2, 0.2]
    runs = {}
    for n, steps, est in ((16, 4, True), (32, 8, True), (64, 16, False)):
        t0 = time.perf_counter()
        runs[n] = fretting("sphere", 0.3, K, [0, 1, 1, 1, 1], path, steps, n=n,
                           tangential_displacement=True, error_estimate=est)
        print(f"n = {n}, {steps} steps: {time.perf_counter() - t0:.1f} s, converged "
              f"{runs[n].converged.all()}, Q/kP at the points "
              f"{np.round(runs[n].force_ratio[runs[n].point_step[2:]], 4).tolist()}")
    truth = runs[64]
    tp = truth.point_step[2:]
    print("| n, steps | Q/kP: est./diff. (points 2, 3, 4) | c/a: est./diff. | cycle work: "
          "est./diff. |")
    print("|---|---|---|---|")
    for n, steps in ((16, 4), (32, 8)):
        r = runs[n]
        pts = r.point_step[2:]
        dq = np.abs(r.force_ratio[pts] - truth.force_ratio[tp])
        dc = np.abs(r.stick_ratio[pts] - truth.stick_ratio[tp])
        dw = abs(r.cycles[0][2] - truth.cycles[0][2])
        fmt = ", ".join
        print(f"| {n}, {steps} | {fmt(f'{v:.2g}' for v in r.force_ratio_error[2:] / dq)} "
              f"| {fmt(f'{v:.2g}' for v in r.stick_ratio_error[2:] / dc)} "
              f"| {r.cycles[0][3] / dw:.2g} |")


if __name__ == "__main__":
    if "--coupled" in sys.argv[1:]:
        coupled()
    else:
        main()
