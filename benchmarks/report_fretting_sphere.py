"""Fretting of the sphere (contactlib.solvers.fretting_sphere): accuracy against
Cattaneo–Mindlin and Mindlin–Deresiewicz, the coupled normal loading against the
self-similar solution, coupled cycles against a fourfold refined run, and the cost as a
ratio to a normal-load cycle of ``history`` timed in the same run.

    python benchmarks/report_fretting_sphere.py            # about 10 min on 2 cores
    python benchmarks/report_fretting_sphere.py --n128     # the coupled cycle to n = 128 only
    python benchmarks/report_fretting_sphere.py --edge     # the stick edge inside its cell

Cases: two equal bodies with nu = 0 (beta = 0, gamma = 0: Cattaneo–Mindlin exact), k = 0.3,
P: 0 -> P_max, then Q: 0 -> Q* -> -Q* -> Q*, 4 steps a segment (at beta = 0 and constant P
the grid's solution does not depend on the steps of a monotonic branch), n = 32 and 64
cells a side over [-1.2, 1.2]^2 a_max. The estimate of a fine run is its difference to the
run at twice the cell size. Then a rigid sphere on nu = 0.5 (beta = 0, gamma = 1: Mindlin
approximate) in the same cycles; and the coupled normal loading (rigid on nu = 0.3,
beta = 0.286, Q = 0, 10 steps) against the self-similar stick ratio, and its cycle at
Q* = 0.5 k P through ``fretting`` at n = 16, 32 and 64. The coupled cycles (rigid on
nu = 0.3 and 0: beta = 0.286 and 0.5; Q* = 0.5 and 0.9 k P) at (n, steps) = (16, 4) and
(32, 8) with their estimates, against (64, 16). Last, the public door
``contactlib.fretting("sphere", ...)`` at its defaults (n = 64, 8 steps, with its estimate
run at n = 32): the cycle above and CONTACT's shipped "cattaneo" example (equal bodies,
G = 200 N/mm^2, nu = 0.42, a = 1 mm, Fn = 9.1954 N, k = 0.4, Fx = -0.875 k Fn; 4 steps, then
8 and 16, and n = 128) in mm, against Mindlin's closed forms (c/a = 0.500, shift 8.172e-3 mm).
"""

from __future__ import annotations

import sys
import time

import numpy as np

from contactlib.solvers import fretting_sphere as fs
from contactlib import fretting, history, solve
from contactlib.model import contact

K = 0.3
STEPS = 4


def cycle(model, n: int, x: float):
    ops = fs.grid_operators(model, n)
    big_p = ops.p_max
    t = np.arange(1, STEPS + 1) / STEPS
    load = np.concatenate([big_p * t, np.full(3 * STEPS, big_p)])
    force = K * big_p * np.concatenate([0 * t, x * t, x - 2 * x * t, -x + 2 * x * t])
    t0 = time.perf_counter()
    raw = fs.run_sphere_fretting(ops, K, load, force)
    return ops, raw, time.perf_counter() - t0


def against_mindlin(model, n: int, x: float):
    """c/a, delta and the cycle's work at Q*, Mindlin's values, the run's time, converged."""
    ops, raw, dt = cycle(model, n, x)
    c_mind = fs.mindlin_compliance(model)
    i = 2 * STEPS
    big_p = ops.p_max
    bracket = 1 - (1 - x) ** (5 / 3) - 5 * x / 6 * (1 + (1 - x) ** (2 / 3))
    exact = np.array([(1 - x) ** (1 / 3),
                      3 * K * big_p / 16 * c_mind * (1 - (1 - x) ** (2 / 3)),
                      9 * K * K * big_p * big_p * c_mind / 10 * bracket])
    got = np.array([raw.stick_radius[i] / raw.contact_radius[i], raw.shift[i, 0],
                    raw.dissipation[-1] - raw.dissipation[i]])
    return got, exact, dt, bool(raw.converged.all())


def main() -> None:
    t0 = time.perf_counter()
    history("sphere", 0.3, 0.3, [0, 1, 0], 200)
    t_hist = time.perf_counter() - t0
    print(f"reference: history('sphere', 0.3, 0.3, [0, 1, 0], 200): {t_hist:.2f} s\n")

    cases = [(contact("sphere", 0.0, indenter_modulus=1.0, indenter_nu=0.0),
              ("equal bodies, nu = 0 (beta = gamma = 0), k = 0.3: errors against the closed "
               "forms")),
             (contact("sphere", 0.5),
              ("\nrigid on nu = 0.5 (beta = 0, gamma = 1), k = 0.3: Mindlin's miss (run minus "
               "closed form)"))]
    for model, title in cases:
        print(title)
        print("| Q*/kP | n | c/a minus (1-x)^(1/3) | est. | delta rel. | est. | cycle work "
              "rel. | est. | time s | x history |")
        print("|---|---|---|---|---|---|---|---|---|---|")
        for x in (0.25, 0.5, 0.9):
            out = {n: against_mindlin(model, n, x) for n in (32, 64)}
            for n in (32, 64):
                got, exact, dt, ok = out[n]
                est = np.abs(got - out[n // 2][0]) if n // 2 in out else np.full(3, np.nan)
                flag = "" if ok else " (NOT CONVERGED)"
                print(f"| {x} | {n} | {got[0] - exact[0]:.1e} | {est[0]:.1e} | "
                      f"{got[1] / exact[1] - 1:.1e} | {est[1] / exact[1]:.1e} | "
                      f"{got[2] / exact[2] - 1:.1e} | {est[2] / exact[2]:.1e} | {dt:.1f} | "
                      f"{dt / t_hist:.1f}{flag} |")

    print("\nrigid on nu = 0.3 (beta = 0.286), k = 0.3, Q = 0, 10 steps: stick ratio at peak")
    ref = solve("sphere", 0.3, friction=K).stick_ratio
    model = contact("sphere", 0.3)
    prev = None
    for n in (16, 32):
        ops = fs.grid_operators(model, n)
        t = np.arange(1, 11) / 10
        t0 = time.perf_counter()
        raw = fs.run_sphere_fretting(ops, K, ops.p_max * t, 0 * t)
        dt = time.perf_counter() - t0
        c = raw.stick_radius[-1] / raw.contact_radius[-1]
        est = abs(c - prev) if prev is not None else float("nan")
        print(f"n = {n}: c/a = {c:.5f} (self-similar {ref:.5f}, error {c - ref:.1e}, "
              f"estimate {est:.1e}), converged {bool(raw.converged.all())}, {dt:.1f} s "
              f"= {dt / t_hist:.1f} x history")
        prev = c

    print("\nrigid on nu = 0.3 (beta = 0.286), k = 0.3, Q: 0 -> 0.5 -> -0.5 -> 0.5 k P, "
          "4 steps a segment: fretting('sphere', ..., n=n) with its estimates")
    for n in (16, 32, 64):
        t0 = time.perf_counter()
        r = fretting("sphere", 0.3, K, [0, 1, 1, 1, 1], [0, 0, 0.5, -0.5, 0.5], 4, n=n)
        dt = time.perf_counter() - t0
        j = r.point_step[2]
        _, _, work, est = r.cycles[0]
        print(f"n = {n}: c/a = {r.stick_ratio[j]:.4f} (estimate {r.stick_ratio_error[2]:.1e}), "
              f"shift {r.shift[j]:.5f}, cycle work {work:.4e} (estimate {est:.1e}), "
              f"converged {bool(r.converged.all())}, {dt:.1f} s = {dt / t_hist:.1f} x history")
    coupled_fourfold(t_hist)
    print("\ncontactlib.fretting('sphere', ...) at its defaults (n = 64, steps = 8)")
    t0 = time.perf_counter()
    r = fretting("sphere", 0.5, K, [0, 1, 1, 1, 1], [0, 0, 0.5, -0.5, 0.5])
    dt = time.perf_counter() - t0
    _, _, work, est = r.cycles[0]
    exact = against_mindlin_exact(r.p_max, 0.5, 6.0)
    print(f"rigid on nu = 0.5, Q* = 0.5 k P: cycle work {work:.5e} (estimate {est:.1e}; "
          f"Mindlin-Deresiewicz {exact:.5e}), converged {bool(r.converged.all())}, "
          f"{dt:.1f} s = {dt / t_hist:.1f} x history")
    nu, g_mod, a, fn, k, x = 0.42, 200.0, 1.0, 9.1954, 0.4, 0.875
    radius = 4 * (g_mod * (1 + nu) / (1 - nu**2)) * a**3 / (3 * fn)  # mm
    t0 = time.perf_counter()
    r = fretting("sphere", nu, k, [0, 1, 1], [0, 0, -x], 4, indenter_modulus=1.0,
                 indenter_nu=nu)
    dt = time.perf_counter() - t0
    coarse = fretting("sphere", nu, k, [0, 1, 1], [0, 0, -x], 4, n=32, indenter_modulus=1.0,
                      indenter_nu=nu, error_estimate=False)
    j = r.point_step[2]
    shift, shift_c = (-res.shift[-1] * a * a / radius for res in (r, coarse))
    mindlin = 3 * k * fn / (16 * a) * 2 * (2 - nu) / g_mod * (1 - (1 - x) ** (2 / 3))
    print(f"CONTACT cattaneo (R = {radius:.4f} mm): c/a = {r.stick_ratio[j]:.4f} "
          f"(estimate {r.stick_ratio_error[2]:.1e}; Mindlin {(1 - x) ** (1 / 3):.4f}), shift "
          f"{shift:.5e} mm (estimate {abs(shift - shift_c):.1e}; Mindlin {mindlin:.5e}, "
          f"ours minus Mindlin {shift / mindlin - 1:.1e}), converged "
          f"{bool(r.converged.all())}, {dt:.1f} s = {dt / t_hist:.1f} x history")
    for n, steps in ((64, 8), (64, 16), (128, 4)):  # near gross slip at gamma != 0
        t0 = time.perf_counter()
        r = fretting("sphere", nu, k, [0, 1, 1], [0, 0, -x], steps, n=n, indenter_modulus=1.0,
                     indenter_nu=nu, error_estimate=False)
        dt = time.perf_counter() - t0
        print(f"  n = {n}, {steps} steps: c/a = {r.stick_ratio[-1]:.4f}, shift "
              f"{-r.shift[-1] * a * a / radius:.5e} mm, converged {bool(r.converged.all())}, "
              f"{dt:.1f} s")


def coupled_fourfold(t_hist: float) -> None:
    """Coupled cycles (rigid sphere on nu = 0.3 and 0: beta = 0.286 and 0.5) at (n, steps) =
    (16, 4) and (32, 8) with their estimates, against the run refined fourfold from
    (16, 4), (64, 16): the estimate over the difference (want 1 to 3)."""
    print("\ncoupled cycles, k = 0.3, Q: 0 -> Q* -> -Q* -> Q*: fretting('sphere', ...) with its "
          "estimates against (n, steps) = (64, 16); ratio = estimate / |difference|")
    print("| beta | Q*/kP | n, steps | c/a | est. | ratio | cycle work | est. | ratio | "
          "time s | x history |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for nu, x in ((0.3, 0.5), (0.3, 0.9), (0.0, 0.9)):
        path = ([0, 1, 1, 1, 1], [0, 0, x, -x, x])
        runs = []
        for n, steps in ((16, 4), (32, 8)):
            t0 = time.perf_counter()
            runs.append((fretting("sphere", nu, K, *path, steps, n=n),
                         time.perf_counter() - t0))
        t0 = time.perf_counter()
        fine = fretting("sphere", nu, K, *path, 16, n=64, error_estimate=False)
        runs.append((fine, time.perf_counter() - t0))
        jf = fine.point_step[2]
        for r, dt in runs:
            j = r.point_step[2]
            _, _, work, est = r.cycles[0]
            flag = "" if r.converged.all() else " (NOT CONVERGED)"
            if r is fine:
                cols = f"{r.stick_ratio[j]:.4f} | | | {work:.4e} | | "
            else:
                d_c = abs(r.stick_ratio[j] - fine.stick_ratio[jf])
                d_w = abs(work - fine.cycles[0][2])
                cols = (f"{r.stick_ratio[j]:.4f} | {r.stick_ratio_error[2]:.1e} | "
                        f"{r.stick_ratio_error[2] / d_c:.2g} | {work:.4e} | {est:.1e} | "
                        f"{est / d_w:.2g}")
            print(f"| {r.beta:.3f} | {x} | {r.n}, {r.steps} | {cols} | {dt:.1f} | "
                  f"{dt / t_hist:.1f}{flag} |")


def coupled_to_n128() -> None:
    """Rigid sphere on nu = 0 (beta = 0.5), Q*/kP = 0.9, 4 steps a segment: every step
    converged and the cycle's work at n = 16, 32, 64 and 128 (about 5 min)."""
    model = contact("sphere", 0.0)
    print("rigid on nu = 0 (beta = 0.5), k = 0.3, Q: 0 -> 0.9 -> -0.9 -> 0.9 k P, 4 steps a "
          "segment")
    for n in (16, 32, 64, 128):
        ops, raw, dt = cycle(model, n, 0.9)
        work = raw.dissipation[-1] - raw.dissipation[2 * STEPS]
        print(f"n = {n}: cycle work {work:.5e}, converged {bool(raw.converged.all())}, "
              f"{dt:.1f} s", flush=True)


def edge_along_x() -> None:
    """Where the stick edge lies inside its cell, along +x (the row next to the axis): the
    last stick cell's centre plus the zero of d^e extrapolated from the last two stick cells
    (d = 1 - |q|/(k p), the traction deficit), e = 2/3 (an advancing edge: d ~ (c - r)^(3/2))
    and e = 2 (a receding one: d ~ (c - r)^(1/2)), against the area-equivalent radius and the
    independent truth (units a_max): Spence's problem (rigid on nu = 0.3, Q = 0; history at
    960 rings, 160 steps: c = 0.8960 a, a = 0.9857) and Cattaneo (equal bodies nu = 0,
    Q*/kP = 0.5: c = (1 - x)^(1/3)). About 1 min."""
    spence = history("sphere", 0.3, K, [0, 1], 160, n=960)
    cases = [("Spence, beta = 0.286, Q = 0", contact("sphere", 0.3), 0.0,
              float(spence.stick_ratio[-1] * spence.contact_radius[-1])),
             ("Cattaneo, beta = 0, Q*/kP = 0.5",
              contact("sphere", 0.0, indenter_modulus=1.0, indenter_nu=0.0), 0.5,
              0.5 ** (1 / 3))]
    print("| case | n | truth c | area c | edge e = 2/3 | edge e = 2 | h |")
    print("|---|---|---|---|---|---|---|")
    for name, model, x, truth in cases:
        for n in (32, 64):
            ops = fs.grid_operators(model, n)
            # Spence: n/4 load steps (as tests/test_fretting_sphere_coupled.py); Cattaneo: 4
            # steps of P, then 4 of Q (the edge recedes as Q grows)
            steps = n // 4 if x == 0 else STEPS
            t = np.arange(1, steps + 1) / steps
            big_p = ops.p_max * (t if x == 0 else np.concatenate([t, np.ones(steps)]))
            big_q = np.zeros(steps) if x == 0 else K * ops.p_max * x * np.concatenate(
                [0 * t, t])
            raw = fs.run_sphere_fretting(ops, K, big_p, big_q, keep_fields=True)
            p, q, stick = raw.p[-1], raw.q[-1], raw.stick[-1]
            deficit = 1 - np.hypot(*q) / (K * np.where(p > 0, p, np.inf))
            row = n // 2
            i = int(np.nonzero(stick[:, row] & (ops.x > 0))[0].max())
            edges = []
            for e in (2 / 3, 2.0):
                f1, f0 = deficit[i, row] ** e, deficit[i - 1, row] ** e
                edges.append(ops.x[i] + f1 / (f0 - f1) * ops.h)
            print(f"| {name} | {n} | {truth:.4f} | "
                  f"{raw.stick_radius[-1]:.4f} | {edges[0]:.4f} | "
                  f"{edges[1]:.4f} | {ops.h:.4f} |", flush=True)


def against_mindlin_exact(big_p: float, x: float, c_mind: float) -> float:
    """Mindlin–Deresiewicz's cycle work (a = R = 1, compliance ``c_mind`` in 1/E*)."""
    bracket = 1 - (1 - x) ** (5 / 3) - 5 * x / 6 * (1 + (1 - x) ** (2 / 3))
    return 9 * K * K * big_p * big_p * c_mind / 10 * bracket


if __name__ == "__main__":
    if "--n128" in sys.argv[1:]:
        coupled_to_n128()
    elif "--edge" in sys.argv[1:]:
        edge_along_x()
    else:
        main()
