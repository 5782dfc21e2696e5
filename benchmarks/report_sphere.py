"""Numbers quoted in docs/validation.md for the sphere (run: python benchmarks/report_sphere.py).

1. Frictionless error of the paper's scheme at n = 8 ... 64 and of the default method.
2. k(c/a) at nu = 0.3: paper scheme (n = 16, both readings of Eq. 11) beside the
   default method (n = 256), with the consistency flags and the frictional work.
3. Convergence of k for the default method (n = 64 ... 1024) and its observed order.
"""

from __future__ import annotations

import numpy as np

from contactlib import solve
from contactlib.solvers.default_method import solve_default
from contactlib.model.geometry import Geometry
from contactlib.model.theory import hertz_pressure


def frictionless() -> None:
    print("## Frictionless (nu = 0.3): load and pressure error against Hertz")
    print("| method | n | P/P_H - 1 | max abs(p/p0 - sqrt(1-xi^2)) |")
    print("|---|---|---|---|")
    for method, ns in (("paper", (8, 16, 32, 64)), ("default", (64, 128, 256, 512))):
        for n in ns:
            s = solve("sphere", 0.3, stick_ratio=0.0, n=n, method=method)
            perr = np.max(np.abs(s.pressure - hertz_pressure(s.xi)))
            print(f"| {method} | {n} | {s.load_ratio - 1:+.2e} | {perr:.2e} |")


def side_by_side() -> None:
    print("\n## k(c/a), nu = 0.3: paper scheme (n = 16) and default method (n = 256)")
    print("| c/a | k paper | k paper-literal | paper slip ok | paper V | k default | "
          "default consistent | default V |")
    print("|---|---|---|---|---|---|---|---|")
    for m in range(1, 16):
        c = m / 16
        p = solve("sphere", 0.3, stick_ratio=c, n=16, method="paper")
        pl = solve("sphere", 0.3, stick_ratio=c, n=16, method="paper-literal", energy=False)
        d = solve("sphere", 0.3, stick_ratio=c)
        conv = "" if p.converged else " (not converged)"
        print(f"| {c:.4f} | {p.friction_coefficient:.4f}{conv} | {pl.friction_coefficient:.4f} | "
              f"{p.slip_direction_ok} ({p.extra['slip_violation']:.2f}) | "
              f"{p.frictional_work:+.2e} | {d.friction_coefficient:.6f} | {d.consistent} | "
              f"{d.frictional_work:.4e} |")


def convergence() -> None:
    print("\n## Default method: k at nu = 0.3 against n, observed order")
    g = Geometry("sphere", 0.3)
    ns = (64, 128, 256, 512, 1024)
    print("| c/a | " + " | ".join(f"n={n}" for n in ns) + " | orders |")
    print("|---|" + "---|" * (len(ns) + 1))
    for c in (0.02, 0.1, 0.3, 0.5, 0.7, 0.9, 0.98):
        ks = np.array([solve_default(g, c, n).k for n in ns])
        d = np.diff(ks)
        orders = np.log2(np.abs(d[:-1] / d[1:]))
        print(f"| {c} | " + " | ".join(f"{k:.8f}" for k in ks) + " | "
              + ", ".join(f"{o:.2f}" for o in orders) + " |")


if __name__ == "__main__":
    frictionless()
    side_by_side()
    convergence()
