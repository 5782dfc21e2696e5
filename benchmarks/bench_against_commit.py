"""Solve time of this checkout against an earlier commit, measured in one run.

    python benchmarks/bench_against_commit.py REV [--n 256,2048] [--rounds 5]

Clones the repository at REV into a temporary folder, builds its compiled parts there
(``python setup.py build_ext --inplace``; nothing is installed), and times
``contactlib.solve(geometry, nu=0.3, stick_ratio=0.5, n=n)`` for the sphere and the
cylinder in fresh processes, alternating this checkout and REV round by round, so that
the load of a shared machine falls on both alike. Prints the best CPU time (the solve only,
after a warm-up solve at n = 64) of each and their ratio; the k of both must agree.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parents[1]

CHILD = r"""
import json, sys, time
import contactlib
g, n = sys.argv[1], int(sys.argv[2])
contactlib.solve(g, nu=0.3, stick_ratio=0.5, n=64)
t = time.process_time()
sol = contactlib.solve(g, nu=0.3, stick_ratio=0.5, n=n)
cpu = time.process_time() - t
print(json.dumps({"cpu": cpu, "k": float(sol.friction_coefficient)}))
"""


def run(root: Path, geometry: str, n: int) -> dict:
    env = dict(os.environ, PYTHONPATH=str(root), OPENBLAS_NUM_THREADS="1",
               OMP_NUM_THREADS="1")
    out = subprocess.run([sys.executable, "-c", CHILD, geometry, str(n)], env=env, cwd=root,
                         capture_output=True, text=True, check=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("rev")
    ap.add_argument("--n", default="256,2048")
    ap.add_argument("--rounds", type=int, default=5)
    args = ap.parse_args()
    sizes = [int(x) for x in args.n.split(",")]
    with tempfile.TemporaryDirectory() as tmp:
        old = Path(tmp) / "old"
        subprocess.run(["git", "clone", "-q", str(HERE), str(old)], check=True)
        subprocess.run(["git", "checkout", "-q", args.rev], cwd=old, check=True)
        subprocess.run([sys.executable, "setup.py", "-q", "build_ext", "--inplace"], cwd=old,
                       check=True, capture_output=True)
        print(f"this checkout against {args.rev}: best CPU of {args.rounds} rounds, "
              "alternating")
        print(f"{'geometry':>9} {'n':>5} {'now (s)':>9} {'then (s)':>9} {'ratio':>6} "
              f"{'k now - k then':>15}")
        for geometry in ("sphere", "cylinder"):
            for n in sizes:
                now, then = [], []
                for _ in range(args.rounds):
                    now.append(run(HERE, geometry, n))
                    then.append(run(old, geometry, n))
                a = min(r["cpu"] for r in now)
                b = min(r["cpu"] for r in then)
                dk = now[0]["k"] - then[0]["k"]
                print(f"{geometry:>9} {n:>5} {a:9.3f} {b:9.3f} {a / b:6.3f} {dk:15.2e}")


if __name__ == "__main__":
    main()
