"""Do the round-off (noise) bounds of the error estimates hold under other BLAS kernels? (issue 42)

    python benchmarks/report_noise_kernels.py             # 3 kernels, 2 draws a case, ~25 min
    python benchmarks/report_noise_kernels.py --quick     # 3 kernels, 1 draw, ~10 min
    python benchmarks/report_noise_kernels.py --kernels Haswell,Sandybridge --draws 3

The estimates at the extremes of c/a carry measured bounds of the round-off the smallest
elements amplify (``extrapolated_method.DIFFERENCE_NOISE``, ``NOISE``, ``BAND_NOISE``,
``LOG_NOISE``; ``accuracy.default_noise``). Round-off is what changes with the BLAS
kernel: OpenBLAS picks its kernels by CPU, and ``OPENBLAS_CORETYPE`` forces another one on
this machine, which simulates another CPU (the bounds had been fitted on one CPU with no
margin; on an AMD EPYC with the Haswell kernels one case came out at 1.01 of its
estimate). The script runs itself once per kernel in a subprocess (the variable must be
set before numpy loads OpenBLAS) and, besides the kernels, draws the round-off again by
moving c/a by a relative 1e-13 per draw (which leaves the discretization alone).

Cases (truth: the uncoupled closed form at nu = 0.4999999, sharp to O(beta^2) ~ 4e-14):

* ``extremes``: the extrapolated method at n = 1024 where the axis or edge difference
  rows apply (the finest level's k, the default method's estimate from the levels n/4,
  n/2, n plus ``quadrature_noise(difference=True)``), sphere c/a = 1e-8, 1e-7, 1e-6;
  cylinder 1 - 1e-5, 0.9999;
* ``default``: the default method through ``contactlib.solve`` at n = 1024 (the same
  rows and mesh, the estimate from the levels plus ``accuracy.default_noise``), sphere
  c/a = 1e-8, 1e-6 and the half-plane c/a = 1e-6.

For each case and kernel the script prints the error, the estimate, its parts (levels,
noise bound) and error / estimate; at the end the largest error / estimate over every
kernel and draw, and the largest error / (levels part) (what the noise bound has to
cover). One BLAS thread; run from the repository root.
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")  # before numpy is imported

import argparse
import json
import subprocess
import sys

NU = 0.4999999
CASES = {
    "extremes": [("sphere", 1e-8), ("sphere", 1e-7), ("sphere", 1e-6),
                 ("cylinder", 1 - 1e-5), ("cylinder", 0.9999)],
    "default": [("sphere", 1e-8), ("sphere", 1e-6), ("cylinder", 1e-6)],
}
N = 1024
KERNELS = ("SkylakeX", "Haswell", "Sandybridge")


def _worker(group: str, draws: int) -> None:
    """One kernel: every case of ``group``, one JSON line each."""
    import threadpoolctl

    import contactlib
    from contactlib.accuracy import default_noise, estimate
    from contactlib.solvers.extrapolated_method import quadrature_noise, solve_extrapolated
    from contactlib.model import contact
    from contactlib.model.theory import uncoupled_friction

    arch = ",".join(str(i.get("architecture")) for i in threadpoolctl.threadpool_info())
    for geometry, c0 in CASES[group]:
        model = contact(geometry, NU)
        for j in range(draws):
            c = c0 * (1.0 + j * 1e-13) if c0 < 0.5 else 1.0 - (1.0 - c0) * (1.0 + j * 1e-13)
            truth = float(uncoupled_friction(geometry, NU, c))
            if group == "extremes":
                s = solve_extrapolated(model, c, N, work=False)
                k, est = s.k, s.error_estimate
                levels = estimate(*s.level_k[-3:])[0]
                noise = quadrature_noise(s.mesh, difference=True)
            else:
                s = contactlib.solve(geometry, NU, n=N, stick_ratio=c, energy=False)
                k, est = s.friction_coefficient, s.error_estimate
                noise = default_noise(model, c, N)
                levels = est - noise  # (plus twice Newton's last step, ~0 here)
            err = abs(k / truth - 1.0)
            print(json.dumps({"kernel": arch, "group": group, "geometry": geometry, "c": c0,
                              "draw": j, "error": err, "estimate": est, "levels": levels,
                              "noise": noise}), flush=True)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true", help="one draw a case")
    ap.add_argument("--draws", type=int, default=2)
    ap.add_argument("--kernels", default=",".join(KERNELS))
    ap.add_argument("--groups", default="extremes,default")
    ap.add_argument("--worker", help=argparse.SUPPRESS)
    args = ap.parse_args()
    draws = 1 if args.quick else args.draws
    if args.worker:
        _worker(args.worker, draws)
        return
    rows = []
    for kernel in args.kernels.split(","):
        for group in args.groups.split(","):
            env = dict(os.environ, OPENBLAS_CORETYPE=kernel)
            out = subprocess.run([sys.executable, __file__, "--worker", group,
                                  "--draws", str(draws)], env=env, capture_output=True,
                                 text=True, check=True).stdout
            for line in out.splitlines():
                r = json.loads(line)
                rows.append(r)
                print(f"{r['kernel']:>11} {r['group']:>8} {r['geometry']:>8} "
                      f"c/a={r['c']:<9.6g} draw {r['draw']}: error {r['error']:.3e} "
                      f"estimate {r['estimate']:.3e} (levels {r['levels']:.2e}, noise "
                      f"{r['noise']:.2e})  err/est {r['error'] / r['estimate']:.3f}",
                      flush=True)
    print()
    for group in args.groups.split(","):
        part = [r for r in rows if r["group"] == group]
        if not part:
            continue
        worst = max(part, key=lambda r: r["error"] / r["estimate"])
        print(f"{group}: largest error / estimate {worst['error'] / worst['estimate']:.3f} "
              f"({worst['geometry']}, c/a = {worst['c']:g}, {worst['kernel']}); largest "
              f"(error - levels) / noise bound "
              f"{max((r['error'] - r['levels']) / r['noise'] for r in part):.3f}")


if __name__ == "__main__":
    main()
