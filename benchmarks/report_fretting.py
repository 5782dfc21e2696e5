"""Fretting of the cylinder: accuracy against closed forms, cost against a history cycle
(docs/fretting.md).

    python benchmarks/report_fretting.py                    # about 5 min
    python benchmarks/report_fretting.py --figure out.png   # and the figure of the page

1. Cycle work between +-Q* at constant P (beta = 0, rigid on nu = 0.5) against the
   Mindlin-Deresiewicz closed form of the cylinder, at the default n = 120, 40 steps a
   segment: relative error, estimate, and the stick ratio at Q* against Cattaneo (the
   located stick edge, whose fit ``fretting_solver.EDGE_SKIP``/``EDGE_FIT`` set).
2. Coupled (rigid on nu = 0.3, beta = 0.286): the work of successive cycles (shakedown of
   the coupling) and its estimate against a run refined fourfold in n and steps.
3. Cost: the wall time of the default fretting path (load, then two cycles) over that of
   the default normal-load cycle of ``contactlib.history`` (0, 1, 0; n = 240, 200 steps),
   measured in the same run.
"""

from __future__ import annotations

import argparse
import os
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

from contactlib import fretting, history  # noqa: E402
from contactlib.solvers.fretting_solver import EDGE_FIT, EDGE_SKIP  # noqa: E402
from contactlib.model.theory import cylinder_cycle_work  # noqa: E402

K = 0.3
PATH = [0, 1, 1, 1, 1, 1]


def _cycle(x: float) -> list[float]:
    return [0, 0, x, -x, x, -x]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--figure", default=None, help="write the page's figure to this PNG")
    args = ap.parse_args()
    xs = (0.1, 0.25, 0.5, 0.75, 0.9)
    print("1. beta = 0: cycle work W against Mindlin-Deresiewicz (cylinder), c/a against "
          "Cattaneo")
    print(f"  (the stick edge: f^2 fitted over EDGE_FIT = {EDGE_FIT} elements, the "
          f"EDGE_SKIP = {EDGE_SKIP} next to it left out)")
    print("  Q*/kP   W/W_MD - 1   estimate/W_MD   c/a - sqrt(1 - x)   its estimate")
    for x in xs:
        r = fretting("cylinder", 0.5, K, PATH, _cycle(x), 40)
        exact = float(cylinder_cycle_work(x, K, r.p_max, r.p0))
        i, j, w, est = r.cycles[-1]
        print(f"  {x:5.2f}  {w / exact - 1:+.2e}     {est / exact:.2e}       "
              f"{r.stick_ratio[r.point_step[2]] - np.sqrt(1 - x):+.2e}         "
              f"{r.stick_ratio_error[2]:.1e}")
    print("\n2. beta = 0.286 (rigid on nu = 0.3), Q* = 0.5 k P: work of successive cycles")
    path = [0] + [1] * 9
    tang = [0, 0] + [0.5, -0.5] * 4
    r = fretting("cylinder", 0.3, K, path, tang, 40)
    fine = fretting("cylinder", 0.3, K, path, tang, 160, n=480, error_estimate=False)
    print("  cycle (points)  work          estimate   |work - 4x refined|   c/a at its end")
    for (i, j, w, est), (_, _, wf, _) in zip(r.cycles, fine.cycles):
        print(f"  {i}->{j:<12d} {w:.6e}  {est:.1e}    {abs(w - wf):.1e}              "
              f"{r.stick_ratio[r.point_step[j]]:.4f}")
    print("\n3. cost, wall time in one run (ratio to a default normal-load history cycle)")
    t0 = time.perf_counter()
    history("cylinder", 0.3, K, [0, 1, 0], 200)
    t_hist = time.perf_counter() - t0
    t0 = time.perf_counter()
    fretting("cylinder", 0.3, K, PATH, _cycle(0.5), 40)
    t_fret = time.perf_counter() - t0
    print(f"  history 0,1,0 (n = 240, 200 steps, estimates): {t_hist:.2f} s")
    print(f"  fretting load + 2 cycles (n = 120, 40 steps, estimates): {t_fret:.2f} s, "
          f"ratio {t_fret / t_hist:.2f}")
    if args.figure:
        from contactlib import io, plot
        from contactlib.fretting_api import amplitude_study

        ds = io.fretting_study_to_dataset(amplitude_study())
        io.write_figure(plot.fig_fretting(ds), args.figure, style=plot.style_path())
        print(f"wrote {args.figure}")

if __name__ == "__main__":
    main()
