"""The sphere's stick-zone map (docs/img/fretting-stick-map.png) and its shape numbers.

The workflow's map (``snakemake --cores 1 fretting_stick_map``) from the same library call,
contactlib.fretting_api.stick_map_study: a rigid sphere on nu = 0.3 (Dundurs beta = 0.286,
a coupled pair) and, for comparison, two equal bodies with nu = 0 (beta = gamma = 0,
Cattaneo–Mindlin exact); k = 0.3, P to P_max, then Q/kP: 0 -> 0.3 -> 0.5 -> 0.7 -> 0.9 at
constant P, n = 64, 4 steps a segment, with the estimate runs. Prints per path point the
stick zone's radius along +x and -x (from the stick zone's centroid), their ratio, max/min
over the directions, the mean estimate, and for the beta = 0 pair the largest miss of
Cattaneo–Mindlin's c = (1 - Q/kP)^(1/3) a_max over the directions with its estimate; then
the cost of the radii per direction a step against the step's solve. About 1 min.

    python benchmarks/figure_fretting_stick_map.py [OUTPUT.png]

``--accuracy`` instead: the largest error over the 24 directions, in cells, of the stick
radius (and the contact's) against Cattaneo–Mindlin (equal bodies, nu = 0, Q/kP = 0.5 and
0.9, 4 steps a segment) at n = 16, 32, 64, 128, and against Spence's 0.8831 a_max (rigid
on nu = 0.3, Q = 0, 16 steps; history at 960 rings, docs/fretting.md) at n = 32, 64;
the raw solver, no estimate runs. About 1 min.

    python benchmarks/figure_fretting_stick_map.py --accuracy
"""

from __future__ import annotations

import sys
import time

import numpy as np

from contactlib import io, plot
from contactlib.fretting_api import STICK_MAP_CASES, STICK_MAP_PATH, stick_map_study
from contactlib.history_api import load_levels
from contactlib.model import contact
from contactlib.solvers import fretting_sphere as fs
from contactlib.plot.fretting import fig_stick_zone_map

OUTPUT = sys.argv[1] if len(sys.argv) > 1 else "docs/img/fretting-stick-map.png"
K = 0.3


def _raw(model, n: int, load, tang, steps: int, keep: bool = False):
    """The raw solver's run (no estimate runs) and its operators."""
    ops = fs.grid_operators(model, n)
    big_p = load_levels(np.array(load, float), steps)[0][1:] * ops.p_max
    big_q = load_levels(np.array(tang, float), steps)[0][1:] * K * ops.p_max
    return ops, fs.run_sphere_fretting(ops, K, big_p, big_q, keep_fields=keep)


if OUTPUT == "--accuracy":
    exact = contact("sphere", 0.0, indenter_modulus=1.0, indenter_nu=0.0)
    print("Cattaneo-Mindlin: largest error over the directions, in cells")
    for n in (16, 32, 64, 128):
        ops, raw = _raw(exact, n, [0, 1, 1, 1], [0, 0, 0.5, 0.9], 4)
        for j, x in ((8, 0.5), (12, 0.9)):
            c = raw.stick_directions[j, 0]
            a = raw.contact_directions[j, 0]
            miss = np.max(np.abs(c - (1 - x) ** (1 / 3))) / ops.h
            print(f"  n = {n:3d}, Q/kP = {x}: stick {miss:.2f}"
                  f", contact {np.max(np.abs(a - 1.0)) / ops.h:.2f}")
    print("Spence (Q = 0, beta = 0.286) against 0.8831 a_max: largest error, in cells")
    for n in (32, 64):
        ops, raw = _raw(contact("sphere", 0.3), n, [0, 1], [0, 0], 16)
        c = raw.stick_directions[-1, 0]
        print(f"  n = {n:3d}: stick {np.max(np.abs(c - 0.8831)) / ops.h:.2f}")
    sys.exit(0)
LOAD, TANG = (list(v) for v in STICK_MAP_PATH)
t = time.perf_counter()
results = stick_map_study()  # the workflow's rule fretting_stick_map_study computes the same
print(f"stick_map_study: {time.perf_counter() - t:.1f} s")
datasets = []
for name, r in results.items():
    N, STEPS = r.n, r.steps
    print(f"{STICK_MAP_CASES[name][0]}: beta = {r.beta:.3f}, n = {N}, {STEPS} steps a "
          f"segment, all converged: {bool(r.converged.all())}")
    d = r.direction_angles.size
    back, up, down = d // 2, d // 4, 3 * d // 4  # the directions -x, +y, -y
    print("  Q/kP   r(0)    r(pi)   r(0)/r(pi)  x/y width  max/min  est.(mean)  area c  centroid x"
          + ("  max |r - CM|  est. there" if r.beta == 0 else ""))
    for i in range(2, len(TANG)):
        j = r.point_step[i]
        c = r.stick_radius_directions[j]
        e = r.stick_radius_directions_error[i]
        a = r.contact_edges[j, 1]
        wide = (c[0] + c[back]) / (c[up] + c[down])
        line = (f"  {TANG[i]:.1f}   {c[0]:.4f}  {c[back]:.4f}  {c[0] / c[back]:.3f}       "
                f"{wide:.3f}      "
                f"{np.nanmax(c) / np.nanmin(c):.3f}    {np.nanmean(e):.1e}     "
                f"{r.stick_ratio[j] * a:.4f}  {r.stick_centre[j, 0]:+.4f}")
        if r.beta == 0:
            miss = np.abs(c - (1 - TANG[i]) ** (1 / 3))
            m = int(np.nanargmax(miss))
            line += f"  {miss[m]:.1e}      {e[m]:.1e}"
        print(line)
    datasets.append(io.fretting_to_dataset(r))

# the cost of the radii per direction: their two calls a step against the step's solve
# (the coupled pair's path above at n = 64, without the estimate runs)
t = time.perf_counter()
ops, raw = _raw(contact("sphere", 0.3), N, LOAD, TANG, STEPS, keep=True)  # with the radii
solve = (time.perf_counter() - t) / len(raw.p)
t = time.perf_counter()
for i, (p, q, st) in enumerate(zip(raw.p, raw.q, raw.stick), start=1):
    d = np.clip(1.0 - np.hypot(*q) / np.where(p > 0, K * p, 1.0), 0.0, 1.0)
    fs.direction_radii(ops, p**2, p > 0, raw.angles, tuple(raw.contact_centre[i]))
    fs.direction_radii(ops, d**2, st & (p > 0), raw.angles, tuple(raw.stick_centre[i]))
rays = (time.perf_counter() - t) / len(raw.p)
print(f"cost a step at n = {N}: the radii per direction {1e3 * rays:.2f} ms, the step "
      f"{solve:.3f} s (ratio {rays / solve:.1e})")

fig = fig_stick_zone_map(datasets, titles=[title for title, _ in STICK_MAP_CASES.values()])
io.write_figure(fig, OUTPUT, style=plot.style_path())
print(f"wrote {OUTPUT}")
