"""The largest stick ratio c* of one slip zone near full stick, and why.

    python benchmarks/report_stick_limit.py [geometry[:a/h]] [nu ...]

(``cylinder:1`` is the cylinder on a slab of a/h = 1 on a smooth base.)

For each nu (default -0.99, -0.5, 0) prints, at n = 128, 256, 512 (environment
variable STICK_LIMIT_NS, e.g. "128"):

* c*: the stick ratio at which k of the default method grows without bound
  (1/k -> 0). Found by bisection between the last stick ratio with a
  converged inward root and the first past it (where ``solve_default``
  reports the root that came back through k = inf, with tensile pressure,
  as NaN), and by the zero of 1/k fitted (quadratic in c) through the
  converged roots at 1 - c/a = 1.6, 1.3, 1.1 (1 - c*) (both printed; the
  bisection's bound is low where Newton loses the root next to the pole);
* r0: the first node, counted from the axis, where the pressure of the
  full-stick (c/a = 1) self-similar solution turns tensile (printed as
  1 - r0/a), and its ratio to 1 - c*: the full-stick solution is not
  admissible, so c/a does not tend to 1 as k grows.

Slow (a few minutes a geometry on one core).
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")  # before numpy is imported

import sys

import numpy as np

from contactlib.solvers.default_method import solve_default
from contactlib.model import contact


NS = [int(v) for v in os.environ.get("STICK_LIMIT_NS", "128,256,512").split(",")]


def inward_k(model, c: float, n: int, guess: float | None) -> float:
    """k of the inward (single-zone) root at c, NaN when there is none."""
    d = solve_default(model, c, n, k_guess=guess)
    if guess is not None and not (d.converged and np.isfinite(d.k)):
        d = solve_default(model, c, n)  # a poor guess: Newton from the coarse levels
    return d.k if d.converged and np.isfinite(d.k) else np.nan


def stick_limit(model, n: int, c0: float = 0.5) -> tuple[float, float]:
    """(c* by bisection, c* from 1/k extrapolated to 0)."""
    lo, k_lo = c0, inward_k(model, c0, n, None)
    hi = 1.0 - 0.3 * (1.0 - lo)
    while True:  # step toward 1 until the inward root is lost
        k = inward_k(model, hi, n, k_lo)
        if not (np.isfinite(k) and k > k_lo):
            break
        lo, k_lo, hi = hi, k, 1.0 - 0.3 * (1.0 - hi)
        if hi > 1.0 - 1e-7:
            return np.nan, np.nan
    while hi - lo > 1e-4 * (1.0 - lo):
        mid = 0.5 * (lo + hi)
        k = inward_k(model, mid, n, k_lo)
        if np.isfinite(k) and k > k_lo:
            lo, k_lo = mid, k
        else:
            hi = mid
    w = 1.0 - lo
    cs = [1.0 - f * w for f in (1.6, 1.3, 1.1)]  # three roots inside, far to near
    ks, guess = [], None
    for c in cs:
        ks.append(inward_k(model, c, n, guess))
        guess = ks[-1] if np.isfinite(ks[-1]) else None
    ok = np.isfinite(ks)  # (Newton may lose a root near the pole from a poor start)
    if ok.sum() < 2:
        return 0.5 * (lo + hi), np.nan
    coef = np.polyfit(np.array(cs)[ok] - lo, 1.0 / np.array(ks)[ok], min(2, ok.sum() - 1))
    roots = np.roots(coef)
    roots = roots[np.isreal(roots)].real
    extrap = lo + float(roots[np.argmin(np.abs(roots))]) if roots.size else np.nan
    return 0.5 * (lo + hi), extrap


def tensile_edge(model, n: int) -> float:
    """1 - r0: the outermost point inside which the full-stick pressure stays >= 0."""
    d = solve_default(model, 1.0, n)
    r, p = d.mesh.nodes[:-1], d.p[:-1]
    neg = np.nonzero(p < 0)[0]
    return float(1.0 - r[neg[0]]) if neg.size else np.nan


def main() -> None:
    geometry, _, slab = (sys.argv[1] if len(sys.argv) > 1 else "sphere").partition(":")
    slab_ratio = float(slab or 0.0)
    nus = [float(v) for v in sys.argv[2:]] or [-0.99, -0.5, 0.0]
    print(f"{geometry}, a/h = {slab_ratio:g}: | nu | n | c* (bisection) | c* (1/k -> 0) "
          "| 1 - r0 (full stick tensile) | (1 - r0)/(1 - c*) |")
    for nu in nus:
        model = contact(geometry, nu, slab_ratio)
        for n in NS:
            cb, ce = stick_limit(model, n)
            r0 = tensile_edge(model, n)
            print(f"| {nu:g} | {n} | {cb:.6f} | {ce:.6f} | {r0:.3g} | "
                  f"{r0 / (1 - ce):.3g} |", flush=True)


if __name__ == "__main__":
    main()
