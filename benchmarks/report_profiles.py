"""k(c/a) against the profile's exponent d, and the frictionless limits (docs/profiles.md).

    python benchmarks/report_profiles.py            # about 1 min

For each geometry and stick ratio, the friction coefficient of the paraboloid (d = 2),
the cone (d = 1) and the power laws d = 1.5 and 3 at the default n = 256, with each
estimate, and the relative difference to the paraboloid over the sum of the two
estimates (below 1: equal within the estimates). Then the frictionless load over the
profile's own closed-form load (Galin) at n = 128 and 256 and its convergence ratio.
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

from contactlib import api  # noqa: E402

PROFILES = [("cone", None), ("power", 1.5), ("power", 3.0)]


def main() -> None:
    print("geometry  nu   c/a   k paraboloid (est)     "
          + "   ".join(f"{p if e is None else 'd=' + format(e, 'g'):>6}: k, |dk|/est"
                       for p, e in PROFILES))
    for geometry in ("sphere", "cylinder"):
        for nu in (0.3, 0.0):
            for c in (0.2, 0.5, 0.8):
                ref = api.solve(geometry, nu, stick_ratio=c, energy=False)
                row = [f"{geometry:8s} {nu:4.1f} {c:4.1f}  {ref.friction_coefficient:.7f} "
                       f"({ref.error_estimate:.1e})"]
                for name, d in PROFILES:
                    s = api.solve(geometry, nu, stick_ratio=c, profile=name, exponent=d)
                    diff = abs(s.friction_coefficient / ref.friction_coefficient - 1.0)
                    row.append(f"{s.friction_coefficient:.7f} {diff / (s.error_estimate + ref.error_estimate):5.2f}"
                               + ("" if s.resolved else " (not resolved)"))
                print("   ".join(row), flush=True)
    print("\nfrictionless load / Galin's load - 1 at n = 128, 256 (ratio: 4 is second order)")
    for geometry in ("sphere", "cylinder"):
        for name, d in PROFILES:
            e = [api.solve(geometry, 0.3, stick_ratio=0.0, n=n, profile=name,
                           exponent=d).load_ratio - 1.0 for n in (128, 256)]
            label = name if d is None else f"d = {d:g}"
            print(f"{geometry:8s} {label:8s} {e[0]:+.2e} {e[1]:+.2e}  ratio {e[0] / e[1]:.2f}")


if __name__ == "__main__":
    main()
