"""Measurements of the incremental stick-slip solver (the numbers in HISTORY_NOTES.md).

Run: python benchmarks/report_history.py [section ...]
Sections: convergence, spence, work, cycles, highk, patterns, slab, onestep,
steady, timing, errors, errors_default, errors_cost (default: all, about 40 min on one
core; errors_default alone about 12 min). Every table is printed as Markdown.

References (all independent of the incremental solver): the self-similar
default method (``contactlib.solve``, n = 256 unless stated), Spence's
published point, the area of the load-indentation loop of a closed cycle.
Lengths are scaled with a_max, the frictionless contact radius at P_max; the
self-similar solution at the same load has a / a_max = load_ratio^(-1/3)
(sphere) or load_ratio^(-1/2) (cylinder), which converts its work V / a^5
(a^4) to the a_max scaling.
"""

from __future__ import annotations

import os
import sys
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

from contactlib.solvers import history_solver as hs  # noqa: E402
from contactlib import solve  # noqa: E402
from contactlib.model.geometry import Geometry  # noqa: E402
from contactlib import history  # noqa: E402

NU = 0.3
P_MAX = {"sphere": 4.0 / 3.0, "cylinder": np.pi / 4.0}
POWER = {"sphere": 5, "cylinder": 4}


def self_similar(geometry: str, nu: float, *, stick_ratio=None, friction=None, slab_ratio=0.0,
                 n: int = 256):
    """Self-similar solution and its contact radius at P_max in units of a_max."""
    sol = solve(geometry, nu, stick_ratio=stick_ratio, friction=friction, n=n,
                slab_ratio=slab_ratio)
    expo = 1 / 3 if geometry == "sphere" else 1 / 2
    a = sol.load_ratio ** (-expo)
    return sol, a


def loop_area(res) -> float:
    load = res.load_ratio * P_MAX[res.geometry]
    return float(np.sum(0.5 * (load[1:] + load[:-1]) * np.diff(res.indentation)))


def runs(geometry: str, state: np.ndarray, xi_edges: np.ndarray, a: float) -> str:
    """Compress an element state row to 'stick 0-0.44, slip-in 0.44-0.80, ...' (r/a)."""
    names = {1: "stick", 2: "slip-in", 3: "slip-out"}
    out, start = [], 0
    m = int(np.count_nonzero(state))
    for i in range(1, m + 1):
        if i == m or state[i] != state[start]:
            lo, hi = xi_edges[start, 0] / a, min(xi_edges[i - 1, 1] / a, 1.0)
            out.append(f"{names[int(state[start])]} {lo:.2f}-{hi:.2f}")
            start = i
    return ", ".join(out)


# ----------------------------------------------------------------------------- sections
def convergence() -> None:
    print("\n## Monotonic loading of the sphere (nu = 0.3): c/a against the self-similar "
          "method\n")
    print("k from the self-similar default method (n = 256) for the target c/a; the "
          "incremental c/a at P_max; deviation in per cent.\n")
    targets = (0.2, 0.3, 0.5, 0.7, 0.9)
    grid = [(120, 50), (120, 200), (120, 800), (240, 50), (240, 200), (240, 800),
            (480, 50), (480, 200), (480, 800)]
    print("| c/a (self-similar) | k | " + " | ".join(f"n={n}, {s} st." for n, s in grid)
          + " |")
    print("|---|---|" + "---|" * len(grid))
    for g in targets:
        sol, a_ss = self_similar("sphere", NU, stick_ratio=g)
        k = sol.friction_coefficient
        cells = []
        for n, steps in grid:
            res = history("sphere", NU, k, [0, 1], steps, n=n)
            flag = "" if res.converged.all() else "*"
            c = res.stick_ratio[-1]
            cells.append(f"{c:.5f} ({100 * (c / g - 1):+.2f}){flag}")
        print(f"| {g} | {k:.6f} | " + " | ".join(cells) + " |")
    print("\nContact radius a/a_max at P_max (self-similar: load_ratio^(-1/3)), n = 240, 200 "
          "steps:\n")
    print("| c/a | a/a_max self-similar | incremental | deviation |")
    print("|---|---|---|---|")
    for g in targets:
        sol, a_ss = self_similar("sphere", NU, stick_ratio=g)
        res = history("sphere", NU, sol.friction_coefficient, [0, 1], 200, n=240)
        a = res.contact_radius[-1]
        print(f"| {g} | {a_ss:.6f} | {a:.6f} | {a / a_ss - 1:+.1e} |")


def spence() -> None:
    print("\n## Spence's point: nu = 0, k = 0.2986 -> c/a = 0.5\n")
    ref, _ = self_similar("sphere", 0.0, friction=0.2986)
    print(f"Self-similar default method (n = 256): c/a = {ref.stick_ratio:.5f}.\n")
    print("| n | steps | c/a incremental | vs 0.5 | vs self-similar |")
    print("|---|---|---|---|---|")
    for n in (120, 240, 480):
        for steps in (50, 200, 800):
            res = history("sphere", 0.0, 0.2986, [0, 1], steps, n=n)
            c = res.stick_ratio[-1]
            print(f"| {n} | {steps} | {c:.5f} | {100 * (c / 0.5 - 1):+.2f} % | "
                  f"{100 * (c / ref.stick_ratio - 1):+.2f} % |")


def work() -> None:
    print("\n## Work of monotonic loading against the self-similar work (sphere, nu = 0.3)\n")
    print("V R^2/(E* a_max^5); deviation of the incremental sum from the self-similar "
          "V (n = 256) in per cent.\n")
    print("| c/a | V self-similar | n | 50 steps | 200 steps | 800 steps | 3200 steps |")
    print("|---|---|---|---|---|---|---|")
    for g in (0.2, 0.5, 0.9):
        sol, a_ss = self_similar("sphere", NU, stick_ratio=g)
        v_ss = sol.frictional_work * a_ss**5
        for n in (120, 240):
            cells = []
            for steps in (50, 200, 800, 3200):
                res = history("sphere", NU, sol.friction_coefficient, [0, 1], steps, n=n)
                cells.append(f"{100 * (res.frictional_work[-1] / v_ss - 1):+.2f}")
            print(f"| {g} | {v_ss:.5e} | {n} | " + " | ".join(cells) + " |")


def cycles() -> None:
    print("\n## Load-unload cycle 0 -> 1 -> 0 (nu = 0.3, n = 240)\n")
    print("V in R^2/(E* a_max^5) (sphere) or R^2/(E* a_max^4) per length (half-plane), "
          "1600 steps a segment. Columns: loading, unloading and cycle work (sums of "
          "|q| |du|), the area of the P-delta loop (the indenter's net work over the "
          "cycle: an independent estimate of the cycle work), the self-similar loading "
          "work (n = 256) at the same load, and the error of the paper's estimate "
          "'cycle = 2 x loading half-cycle', with the incremental and with the "
          "self-similar loading work, against the loop area.\n")
    print("| geometry | k | c/a at P_max | V load | V unload | V cycle | loop area | "
          "V load self-similar | unload/load | 2 V load / cycle - 1 | "
          "2 V_ss / cycle - 1 |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for geometry in ("sphere", "cylinder"):
        for k in (0.05, 0.1, 0.2, 0.3, 0.5):
            res = history(geometry, NU, k, [0, 1, 0], 1600, n=240)
            v_load, v_unload = res.segment_work()
            v_cycle, loop = res.frictional_work[-1], loop_area(res)
            sol, a_ss = self_similar(geometry, NU, friction=k)
            v_ss = sol.frictional_work * a_ss ** POWER[geometry]
            ok = "" if res.converged.all() else " (not converged)"
            print(f"| {geometry if geometry == 'sphere' else 'half-plane'} | {k} | "
                  f"{res.stick_ratio[1600]:.4f} | {v_load:.4e} | {v_unload:.4e} | "
                  f"{v_cycle:.4e} | {loop:.4e} | {v_ss:.4e} | "
                  f"{v_unload / v_load:.3f} | {100 * (2 * v_load / loop - 1):+.1f} % | "
                  f"{100 * (2 * v_ss / loop - 1):+.1f} %{ok} |")
    print("\nConvergence of the cycle work (sphere, k = 0.2) in steps a segment and "
          "elements:\n")
    print("| n | 100 | 200 | 400 | 800 | 1600 | loop area (1600) |")
    print("|---|---|---|---|---|---|---|")
    for n in (120, 240, 480):
        vals, last = [], None
        for steps in (100, 200, 400, 800, 1600):
            last = history("sphere", NU, 0.2, [0, 1, 0], steps, n=n)
            vals.append(f"{last.frictional_work[-1]:.5e}")
        print(f"| {n} | " + " | ".join(vals) + f" | {loop_area(last):.5e} |")


def highk() -> None:
    print("\n## Large k: the thin slip annulus needs more elements and steps (nu = 0.3)\n")
    print("| geometry | k | n | steps a segment | c/a at P_max | V load | V unload | V cycle | "
          "loop area | V load self-similar |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for geometry, k, ns in (("sphere", 0.3, (240, 480)), ("sphere", 0.5, (240, 480, 960)),
                            ("cylinder", 0.5, (240, 480, 960))):
        sol, a_ss = self_similar(geometry, NU, friction=k)
        v_ss = sol.frictional_work * a_ss ** POWER[geometry]
        for n in ns:
            for steps in (400, 1600):
                res = history(geometry, NU, k, [0, 1, 0], steps, n=n)
                v_load, v_unload = res.segment_work()
                print(f"| {geometry if geometry == 'sphere' else 'half-plane'} | {k} | {n} | "
                      f"{steps} | {res.stick_ratio[steps]:.4f} | {v_load:.4e} | "
                      f"{v_unload:.4e} | {res.frictional_work[-1]:.4e} | "
                      f"{loop_area(res):.4e} | {v_ss:.4e} |")


def patterns() -> None:
    print("\n## Stick/slip pattern along a cycle (nu = 0.3, n = 240, 200 steps a segment)\n")
    print("Zones as r/a (x/a) from the axis to the contact edge: stick, slip-in (the body "
          "slips toward the axis, shear = +k p), slip-out (away from it, shear = -k p).\n")
    for geometry, k in (("sphere", 0.1), ("sphere", 0.2), ("sphere", 0.5), ("cylinder", 0.2)):
        res = history(geometry, NU, k, [0, 1, 0], 200, n=240)
        print(f"**{geometry if geometry == 'sphere' else 'half-plane'}, k = {k}**\n")
        print("| P/P_max | phase | a/a_max | c/a | zones |")
        print("|---|---|---|---|---|")
        for i in (100, 200, 202, 210, 240, 300, 360, 390):
            phase = "loading" if i <= 200 else "unloading"
            a = res.contact_radius[i]
            print(f"| {res.load_ratio[i]:.3f} | {phase} | {a:.4f} | {res.stick_ratio[i]:.4f} | "
                  f"{runs(geometry, res.state[i], res.xi_bounds, a)} |")
        print()


def slab() -> None:
    print("\n## Cylinder on a slab, a_max/h = 1/20 (nu = 0.3): incremental against "
          "self-similar\n")
    print("Self-similar at the final a/h = (a/a_max)/20 (n = 256); 'h ~ a' is the "
          "incremental solver with the thickness rebuilt every step as a_H(P)/(a/h) - a "
          "self-similar body - which must and does reproduce the self-similar c/a. "
          "Incremental: n = 240, 200 steps.\n")
    print("| k | c/a half-plane (incremental) | c/a slab self-similar | c/a slab incremental | "
          "difference | c/a slab, h ~ a | a/a_max slab |")
    print("|---|---|---|---|---|---|---|")
    for k in (0.1, 0.15, 0.2, 0.25, 0.3):
        half = history("cylinder", NU, k, [0, 1], 200, n=240)
        res = history("cylinder", NU, k, [0, 1], 200, n=240, slab_ratio=0.05)
        a = res.contact_radius[-1]
        ref = solve("cylinder", NU, friction=k, slab_ratio=0.05 * a, energy=False)
        c_var = _growing_slab(k, 0.05, 200, 240)
        print(f"| {k} | {half.stick_ratio[-1]:.4f} | {ref.stick_ratio:.4f} | "
              f"{res.stick_ratio[-1]:.4f} | "
              f"{100 * (res.stick_ratio[-1] / ref.stick_ratio - 1):+.1f} % | "
              f"{c_var:.4f} | {a:.4f} |")
    print("\nDifference incremental - self-similar against a_max/h (k = 0.2, n = 240, 200 "
          "steps):\n")
    print("| a_max/h | c/a self-similar | c/a incremental | difference | per unit a/h |")
    print("|---|---|---|---|---|")
    for ratio in (0.005, 0.01, 0.02, 0.05, 0.1):
        res = history("cylinder", NU, 0.2, [0, 1], 200, n=240, slab_ratio=ratio)
        a = res.contact_radius[-1]
        ref = solve("cylinder", NU, friction=0.2, slab_ratio=ratio * a, energy=False)
        d = res.stick_ratio[-1] / ref.stick_ratio - 1
        print(f"| {ratio} | {ref.stick_ratio:.4f} | {res.stick_ratio[-1]:.4f} | "
              f"{100 * d:+.2f} % | {d / ratio:.2f} |")
    print("\nConvergence (k = 0.2, a_max/h = 1/20): c/a incremental\n")
    print("| n | 50 steps | 200 steps | 800 steps |")
    print("|---|---|---|---|")
    for n in (120, 240, 480):
        cells = []
        for steps in (50, 200, 800):
            res = history("cylinder", NU, 0.2, [0, 1], steps, n=n, slab_ratio=0.05)
            cells.append(f"{res.stick_ratio[-1]:.5f}")
        print(f"| {n} | " + " | ".join(cells) + " |")


def _growing_slab(k: float, ratio: float, steps: int, n: int) -> float:
    """Incremental loading with h = a_H(P) / ratio rebuilt every step (self-similar body)."""
    state, u_old = np.zeros(n, dtype=np.int8), np.zeros(n)
    step = ops = None
    for level in np.arange(1, steps + 1) / steps:
        a_h = np.sqrt(level)
        ops = hs.build_operators(Geometry("cylinder", NU, ratio / a_h), n)
        guess = state if state.any() else (ops.mid < a_h).astype(np.int8)
        step = hs.solve_step(ops, k, level * ops.p_max, u_old, guess)
        state, u_old = step.state, step.u
    a = hs.contact_radius(ops, step.state, step.gap)
    return hs.stick_radius(ops, k, step.state, step.p, step.q, a) / a


def onestep() -> None:
    print("\n## One-step load against incremental loading (nu = 0.3, n = 240)\n")
    print("| geometry | k | c/a one step | c/a incremental (200 steps) | c/a self-similar | "
          "one-step / incremental |")
    print("|---|---|---|---|---|---|")
    for geometry in ("sphere", "cylinder"):
        for k in (0.05, 0.1, 0.15, 0.2, 0.3, 0.5):
            one = history(geometry, NU, k, [0, 1], 1, n=240)
            inc = history(geometry, NU, k, [0, 1], 200, n=240)
            ref = solve(geometry, NU, friction=k, energy=False)
            c1, ci = one.stick_ratio[-1], inc.stick_ratio[-1]
            ratio = f"{c1 / ci:.3f}" if ci > 0 else "-"
            print(f"| {geometry if geometry == 'sphere' else 'half-plane'} | {k} | "
                  f"{c1:.4f} | {ci:.4f} | {ref.stick_ratio:.4f} | {ratio} |")
    print("\nOne-step c/a against n (sphere, k = 0.15): " + ", ".join(
        f"n={n}: {history('sphere', NU, 0.15, [0, 1], 1, n=n).stick_ratio[-1]:.4f}"
        for n in (120, 240, 480)))


def steady() -> None:
    print("\n## Repeated cycles between P/P_max = 0.5 and 1 (nu = 0.3, n = 240, 200 steps "
          "a segment)\n")
    print("Path 0, 1, then (0.5, 1) x 12. Work per cycle (unload + reload), c/a at the top "
          "and the bottom of each cycle.\n")
    for geometry, k in (("sphere", 0.1), ("sphere", 0.2), ("cylinder", 0.2)):
        path = [0.0, 1.0] + [0.5, 1.0] * 12
        res = history(geometry, NU, k, path, 200, n=240)
        seg = res.segment_work()
        print(f"**{geometry if geometry == 'sphere' else 'half-plane'}, k = {k}** "
              f"(first loading V = {seg[0]:.4e}; converged: {bool(res.converged.all())})\n")
        print("| cycle | V unload | V reload | V cycle | c/a at P = 0.5 | c/a at P = 1 |")
        print("|---|---|---|---|---|---|")
        for j in range(12):
            down, up = seg[1 + 2 * j], seg[2 + 2 * j]
            bottom, top = res.segment_end(2 + 2 * j), res.segment_end(3 + 2 * j)
            print(f"| {j + 1} | {down:.5e} | {up:.5e} | {down + up:.5e} | "
                  f"{res.stick_ratio[bottom]:.4f} | {res.stick_ratio[top]:.4f} |")
        full = history(geometry, NU, k, [0, 1, 0, 1, 0], 200, n=240)
        w = full.segment_work()
        print(f"\nFull cycles 0 -> 1 -> 0 twice: V = {w[0] + w[1]:.5e}, {w[2] + w[3]:.5e} "
              f"(the unloaded body keeps no traction, so every full cycle is the first).\n")


def timing() -> None:
    import bench_history  # benchmarks/ is on sys.path when this file runs as a script

    print("\n## Timing: 200-step load-unload cycle at the default resolution\n")
    print("```")
    bench_history.main(["sphere", "cylinder"])
    print("```")


ERROR_PATHS = {"cycle": (0, 1, 0), "fretting": (0, 1, 0.5, 1, 0.5, 1, 0.5, 1),
               "scene-fretting": (0, 1, 0.5, 1, 0.5, 1, 0.5)}
# (geometry, nu, k, path): the set (nu = 0.3, k = 0.1 ... 0.3, both paths), then
# the default scenes' other k, nu = 0 and k = 0.5 (a slip annulus of few elements)
ERROR_CASES = ([(g, NU, k, p) for g in ("sphere", "cylinder") for k in (0.1, 0.2, 0.3)
                for p in ("cycle", "fretting")]
               + [(g, NU, k, "cycle") for g in ("sphere", "cylinder") for k in (0.05, 0.5)]
               + [(g, 0.0, 0.2, "cycle") for g in ("sphere", "cylinder")]
               + [("sphere", 0.0, 0.3, "fretting")])
# at the default resolution (truth n = 960, 4 x steps: 0.5 ... 2 min a case)
DEFAULT_ERROR_CASES = [("sphere", NU, 0.05, "cycle"), ("sphere", NU, 0.2, "cycle"),
                       ("sphere", NU, 0.3, "cycle"), ("cylinder", NU, 0.2, "cycle"),
                       ("sphere", NU, 0.2, "scene-fretting")]


def error_check(geometry: str, k: float, path: str, n: int, steps: int,
                nu: float = NU) -> dict:
    """Error estimates of one history against the same history refined fourfold.

    The truth is the run with 4n elements and 4 x steps (fine step i = refined
    step 4i). Per quantity: ``under`` the smallest estimate / true error over
    the steps (the estimate covers the error within a factor 3 where it is >=
    1/3), ``inflation`` the largest, over path segments, of the segment's
    largest estimate over its largest true error (<= 10: not inflated), both
    over the steps flagged resolved by the slip-zone criterion (``annulus``)
    and over all steps; ``cost`` the CPU time of the estimate over the run's
    (the same history without estimate, timed in this process).
    """
    levels = ERROR_PATHS[path]
    t0 = time.process_time()
    res = history(geometry, nu, k, levels, steps, n=n)
    t1 = time.process_time()
    history(geometry, nu, k, levels, steps, n=n, error_estimate=False)
    t2 = time.process_time()
    ref = history(geometry, nu, k, levels, 4 * steps, n=4 * n, error_estimate=False)
    c = np.nan_to_num(res.stick_ratio * res.contact_radius)
    c_ref = np.nan_to_num(ref.stick_ratio * ref.contact_radius)[::4]
    w, w_ref = res.frictional_work, ref.frictional_work[::4]
    true = {"c": np.abs(c - c_ref),  # the work relative to the path's total (the estimate's)
            "w": np.abs(w - w_ref) / ref.frictional_work[-1] if ref.frictional_work[-1] > 0
            else np.zeros_like(w)}
    est = {"c": res.stick_radius_error_estimate, "w": res.work_error_estimate}
    annulus = hs.annulus_resolved(k, res.state) & (res.load_ratio > 0)
    out = {"resolved": int(res.resolved[1:].sum()), "steps": res.load_ratio.size - 1,
           "cost": (t1 - t0) / (t2 - t1) - 1.0}
    for q in ("c", "w"):
        for label, mask in (("annulus", annulus), ("all", res.load_ratio > 0)):
            t, e = true[q], est[q]
            m = mask & (t > 0)
            out[f"{q}_under_{label}"] = float(np.min(e[m] / t[m])) if m.any() else np.nan
            infl = [np.max(e[mask & (res.segment == g)]) / np.max(t[mask & (res.segment == g)])
                    for g in np.unique(res.segment[res.segment > 0])
                    if np.any(t[mask & (res.segment == g)] > 0)]
            out[f"{q}_inflation_{label}"] = float(max(infl)) if infl else np.nan
        out[f"{q}_true_end"], out[f"{q}_est_end"] = float(true[q][-1]), float(est[q][-1])
    return out


def errors(n: int = 120, steps: int = 50, cases=None) -> None:
    """Error estimates against runs refined fourfold, and their cost."""
    print(f"\n## Error estimates (n = {n}, {steps} steps a segment; truth 4n, 4 x steps)\n")
    print("| geometry | nu | k | path | resolved | c: min est/true (annulus; all) | "
          "c: max inflation | c true, est (end) | W: min est/true (annulus; all) | "
          "W: max inflation | W true, est (end) | estimate's cost |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for geometry, nu, k, path in cases or ERROR_CASES:
        r = error_check(geometry, k, path, n, steps, nu)
        print(f"| {geometry} | {nu} | {k} | {path} | {r['resolved']}/{r['steps']} | "
              f"{r['c_under_annulus']:.2f}; {r['c_under_all']:.2f} | "
              f"{r['c_inflation_annulus']:.1f}; {r['c_inflation_all']:.1f} | "
              f"{r['c_true_end']:.1e}, {r['c_est_end']:.1e} | "
              f"{r['w_under_annulus']:.2f}; {r['w_under_all']:.2f} | "
              f"{r['w_inflation_annulus']:.1f}; {r['w_inflation_all']:.1f} | "
              f"{r['w_true_end']:.1e}, {r['w_est_end']:.1e} | {r['cost']:.0%} |", flush=True)


def errors_default() -> None:
    """The same at the default resolution (n = 240, the scenes' steps a segment)."""
    for steps, path in ((200, "cycle"), (100, "scene-fretting")):
        errors(240, steps, [c for c in DEFAULT_ERROR_CASES if c[3] == path])


def errors_cost() -> None:
    """CPU time of the default config's history scenes with and without their estimates."""
    print("\nCost of the estimate (CPU time, best of 3 alternating; the history scenes of "
          "config/config.yaml, every k of a scene):\n")
    print("| scene | without (s) | with (s) | extra |")
    print("|---|---|---|---|")
    scenes = {"sphere-cycle": ("sphere", (0.05, 0.1, 0.15, 0.2, 0.3), (0, 1, 0), 200),
              "halfplane-cycle": ("cylinder", (0.05, 0.1, 0.15, 0.2, 0.3), (0, 1, 0), 200),
              "sphere-fretting": ("sphere", (0.2,), (0, 1, 0.5, 1, 0.5, 1, 0.5), 100)}
    for name, (geometry, ks, path, steps) in scenes.items():
        t = {False: np.inf, True: np.inf}
        for _ in range(3):
            for flag in (False, True):
                t0 = time.process_time()  # the machine may be shared: CPU, not wall
                for k in ks:
                    history(geometry, NU, k, path, steps, error_estimate=flag)
                t[flag] = min(t[flag], time.process_time() - t0)
        print(f"| {name} | {t[False]:.2f} | {t[True]:.2f} | {t[True] / t[False] - 1:.0%} |",
              flush=True)


SECTIONS = {"convergence": convergence, "spence": spence, "work": work, "cycles": cycles,
            "highk": highk, "patterns": patterns, "slab": slab, "onestep": onestep,
            "steady": steady, "timing": timing, "errors": errors,
            "errors_default": errors_default, "errors_cost": errors_cost}

if __name__ == "__main__":
    names = sys.argv[1:] or list(SECTIONS)
    for name in names:
        t0 = time.perf_counter()
        SECTIONS[name]()
        print(f"\n({name}: {time.perf_counter() - t0:.0f} s)")
