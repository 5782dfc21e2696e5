"""Regenerate ``tests/data/frontier_reference.json``: converged k of the default method.

The independent truth of ``tests/test_extrapolated_method.py`` (issue 18). For each case
(geometry, nu, c/a) the default method (``solve_default``, untouched by the extrapolated
method) is solved at n = 256, 384, 512, 768, 1024, 1536 and 2048, and the converged k is
the least-squares fit of

    k(n) = k + A n^-2 + B n^-3

over those n. The JSON keeps every k(n) (so the fit can be re-examined), the fitted k, and
``uncertainty``: the largest of (i) the change of the fitted k when the finest level is
left out, (ii) the change when the coarsest is left out, (iii) the rms residual of the fit.
At c/a = 0.9 the default method's n = 2048 level carries a round-off/quadrature floor of
a few 1e-7 relative (its k moves against the trend), which this number shows.

Usage (from the repository root; about 10 minutes on one core)::

    OPENBLAS_NUM_THREADS=1 python tests/data/make_frontier_reference.py
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from contactlib.solvers.default_method import solve_default  # noqa: E402
from contactlib.model import contact  # noqa: E402

NS = (256, 384, 512, 768, 1024, 1536, 2048)
RATIOS = (0.1, 0.3, 0.5, 0.7, 0.9)
NUS = (0.0, 0.3, 0.45)
GEOMETRIES = ("sphere", "cylinder")
ORDERS = (2.0, 3.0)
OUT = Path(__file__).with_name("frontier_reference.json")


def fit(ns, ks) -> float:
    """k of the least-squares fit k + A n^-2 + B n^-3."""
    n = np.asarray(ns, dtype=float)
    a = np.column_stack([np.ones(n.size)] + [n ** -p for p in ORDERS])
    return float(np.linalg.lstsq(a, np.asarray(ks), rcond=None)[0][0])


def reference(ns, ks) -> tuple[float, float]:
    """(fitted k, uncertainty) as described in the module docstring."""
    k = fit(ns, ks)
    n = np.asarray(ns, dtype=float)
    a = np.column_stack([np.ones(n.size)] + [n ** -p for p in ORDERS])
    coef = np.linalg.lstsq(a, np.asarray(ks), rcond=None)[0]
    rms = float(np.sqrt(np.mean((a @ coef - np.asarray(ks)) ** 2)))
    spread = max(abs(fit(ns[:-1], ks[:-1]) - k), abs(fit(ns[1:], ks[1:]) - k), rms)
    return k, spread


def main() -> None:
    cases = []
    for geometry in GEOMETRIES:
        for nu in NUS:
            model = contact(geometry, nu)
            for c in RATIOS:
                ks = []
                guess = None
                for n in NS:
                    d = solve_default(model, c, n, k_guess=guess)
                    if not d.converged:
                        raise RuntimeError(f"{geometry} nu={nu} c/a={c} n={n}: {d.message}")
                    ks.append(float(d.k))
                    guess = d.k
                k, unc = reference(NS, ks)
                cases.append({"geometry": geometry, "nu": nu, "stick_ratio": c,
                              "k_by_n": dict(zip(map(str, NS), ks)), "k": k,
                              "uncertainty": unc / k})
                print(f"{geometry:8s} nu={nu:<5g} c/a={c:<4g} k={k:.12f} "
                      f"uncertainty {unc / k:.1e}", flush=True)
    doc = {"about": "converged k of the default method; made by make_frontier_reference.py",
           "fit": "k + A n^-2 + B n^-3, least squares over n", "n": list(NS),
           "cases": cases}
    OUT.write_text(json.dumps(doc, indent=1) + "\n")


if __name__ == "__main__":
    main()
