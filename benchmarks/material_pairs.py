"""Table of named material pairs: Dundurs' beta and k at c/a = 0.5 (docs/theory.md).

Usage::

    PYTHONPATH=. python benchmarks/material_pairs.py [--n 256]

For each pair (indenter on body, from ``contactlib/data/materials.yaml``) prints E1/E2,
nu1, nu2, beta (> 0: inward slip, q = k p; < 0: outward, q = -k p), and the
friction coefficient k of the self-similar loading at c/a = 0.5 for the sphere
on a half-space and the cylinder on a half-plane (default method), with the
frictional work of the sphere. Prints a Markdown table.
"""

from __future__ import annotations

import argparse

from contactlib import solve
from contactlib.model.materials import pair

PAIRS = [
    ("steel", "aluminium"), ("aluminium", "steel"),
    ("tungsten", "steel"), ("steel", "brass"),
    ("alumina", "soda_lime_glass"), ("soda_lime_glass", "steel"),
    ("fused_silica", "steel"), ("steel", "pmma"), ("pmma", "steel"),
    ("steel", "natural_rubber"), ("natural_rubber", "steel"), ("steel", "steel"),
]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=256)
    n = parser.parse_args().n
    print("| indenter on body | E1/E2 | nu1 | nu2 | beta | k sphere | k cylinder "
          "| V sphere |")
    print("|---|---|---|---|---|---|---|---|")
    for ind, body in PAIRS:
        ratio, nu1, nu2 = pair(ind, body)
        kw = dict(stick_ratio=0.5, n=n, indenter_modulus=ratio, indenter_nu=nu1)
        s = solve("sphere", nu2, **kw)
        c = solve("cylinder", nu2, energy=False, **kw)
        flag = "" if (s.consistent and c.consistent and s.converged and c.converged) else " (!)"
        print(f"| {ind} on {body} | {ratio:.4g} | {nu1:g} | {nu2:g} | {s.dundurs_beta:+.4g} "
              f"| {s.friction_coefficient:.4g} | {c.friction_coefficient:.4g} "
              f"| {s.frictional_work:.3e}{flag} |")


if __name__ == "__main__":
    main()
