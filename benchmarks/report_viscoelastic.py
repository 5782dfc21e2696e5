"""Numbers of docs/validation.md, "Viscoelastic bodies" (the checks of tests/test_viscoelastic.py).

Run: python benchmarks/report_viscoelastic.py   (about a minute)

Prints, for a sphere at nu = 0.3:

* Lee-Radok: the largest relative error of the contact radius over every
  step of a frictionless ramp (T/tau = 1, SLS g = 0.5; and a two-term series
  over T = 3) and of a step-and-hold (ramp in 0.01, hold 10), at the default
  n = 240 and at n = 480 with twice the steps;
* Ting: the largest relative error of the contact radius while it shrinks
  (0 -> 1 -> 0, T/tau = 1 a segment, loads above 0.05 P_max);
* the energy balance |external - stored - viscous - frictional| / external,
  largest over the steps, for two cycles 0 -> 1 -> 0 and the default
  config's fretting path at T/tau from 1e-3 to 1e3.

The truths are computed as in the tests (creep compliance by partial
fractions, Ting's load integral by quadrature).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np
from scipy import integrate, optimize

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
from test_viscoelastic import SLS, TWO, creep_compliance, lee_radok_radius  # noqa: E402

from contactlib import history  # noqa: E402


def lee_radok() -> None:
    cases = [("ramp", SLS, [1.0], [0, 1]), ("ramp", TWO, [3.0], [0, 1]),
             ("step-and-hold", SLS, [0.01, 10.0], [0, 1, 1]),
             ("step-and-hold", TWO, [0.01, 10.0], [0, 1, 1])]
    for name, prony, durations, path in cases:
        row = []
        for n, steps in ((None, 100 // (len(path) - 1)), (480, 200 // (len(path) - 1))):
            res = history("sphere", 0.3, 0.0, path, steps, n=n, relaxation=prony,
                          duration=durations, error_estimate=False)
            a = lee_radok_radius(prony, durations, path, res.time)
            row.append(np.max(np.abs(res.contact_radius[1:] / a[1:] - 1.0)))
        print(f"Lee-Radok {name:<14s} {str(prony):<28s} T = {durations}: "
              f"max |da/a| {row[0]:.2%} (n = 240), {row[1]:.2%} (n = 480, 2x steps)")


def ting() -> None:
    g, tau = SLS[0]
    J, _ = creep_compliance(SLS)
    psi = lambda u: (1.0 - g) + g * np.exp(-u / tau)  # noqa: E731
    for n, steps in ((None, 100), (480, 200)):
        res = history("sphere", 0.3, 0.0, [0, 1, 0], steps, n=n, relaxation=SLS, duration=2.0,
                      error_estimate=False)
        worst = 0.0
        for t, load, a in zip(res.time, res.load_ratio, res.contact_radius):
            if t <= 1.0 + 1e-9 or load < 0.05:
                continue
            p = lambda t1: integrate.quad(lambda s: psi(t - s) * J(s), 0.0, t1)[0]  # noqa: E731
            t1 = optimize.brentq(lambda x: p(x) - load, 1e-9, 1.0)
            a_ting = integrate.quad(J, 0.0, t1)[0] ** (1 / 3)
            worst = max(worst, abs(a / a_ting - 1.0))
        print(f"Ting unloading (SLS, T/tau = 1 a segment), n = {n or 240}, {steps} steps a "
              f"segment: max |da/a| {worst:.3%}")


def balance() -> None:
    for label, path, prony, n in (("two cycles 0-1-0, two terms", [0, 1, 0, 1, 0], TWO, 160),
                                  ("default fretting path, SLS", [0, 1, 0.5, 1, 0.5, 1, 0.5],
                                   SLS, 240)):
        for duration in (1e-3, 1e-1, 1.0, 10.0, 1e3):
            res = history("sphere", 0.3, 0.2, path, 100, n=n, relaxation=prony,
                          duration=duration, error_estimate=False)
            ext = res.external_work
            bal = ext - res.stored_energy - res.viscous_work - res.frictional_work
            rel = np.abs(bal[1:]) / ext[1:]
            print(f"balance {label:<28s} T = {duration:7.0e} (k = 0.2, n = {n}): max "
                  f"{rel.max():.1e} (step {int(rel.argmax()) + 1} of {rel.size}); viscous "
                  f"{res.viscous_work[-1] / ext[-1]:.3f}, frictional "
                  f"{res.frictional_work[-1] / ext[-1]:.3f} of the external work")


if __name__ == "__main__":
    lee_radok()
    ting()
    balance()
