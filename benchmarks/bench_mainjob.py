"""The main job against a dense LU, measured in the same run.

    python benchmarks/bench_mainjob.py [--repeat R] [--cores C] [--working-tree] [--keep DIR]
                                       [--compare REV]

For each of R repeats (default 1) this

1. runs the reference twice: a fresh Python process that imports numpy and
   scipy, draws a dense 4097 x 4097 matrix and LU-factorizes it with
   ``scipy.linalg.lu_factor`` (imports included, wall time of the process);
2. runs the main job, ``python -m snakemake --cores C`` (default 2), in a fresh
   temporary copy of the repository (``git archive HEAD``; with
   ``--working-tree`` the tracked files as they are now, uncommitted edits
   included), with ``PYTHONPATH`` pointing at that copy so that its
   ``contactlib`` is the one imported (its compiled parts built there first, untimed,
   where the copy has a ``setup.py``);
3. runs the reference twice again,

and prints the times and the ratio main job / fastest of the four references,
and the same ratio of CPU time (user + system, over every process of the
main job; the least of the four references'): a second view, less tied to
how much of the machine other jobs leave (the acceptance is on wall time).
The fastest, because the reference swings most with the load (it uses the
BLAS's default threads, 1.0 - 1.9 s for the same factorization here) and
its best time is the machine's speed; the main job varies far less.
With ``--compare REV`` each repeat also runs the main job of the commit REV
(``git archive REV``) between the same references, right after this one, and
prints its line too: before and after a change, measured under the same load.
With ``--keep DIR`` the last run's ``results`` folder is copied to DIR (to
compare its datasets and figures byte for byte with another version's).
Acceptance (issue 17): ratio at most 20. The BLAS thread variables are left
as the caller set them, for both processes alike; the copy is removed
afterwards. On a shared machine the ratio swings with the load: repeat and
read the range.
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
SIZE = 4097
REFERENCE = (
    "import numpy as np\n"
    "from scipy import linalg\n"
    f"a = np.random.default_rng(0).standard_normal(({SIZE}, {SIZE}))\n"
    "linalg.lu_factor(a, overwrite_a=True, check_finite=False)\n"
)


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def wall(cmd: list[str], cwd: Path, env: dict, cpu: list[float] | None = None) -> float:
    """Wall time of one process in seconds; raise with its output if it fails.

    With ``cpu`` given, the CPU time (user + system) of the process and every
    descendant it waited for is appended to it.
    """
    c0, t0 = _children_cpu(), time.perf_counter()
    proc = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True)
    t = time.perf_counter() - t0
    if cpu is not None:
        cpu.append(_children_cpu() - c0)
    if proc.returncode != 0:
        raise SystemExit(f"{' '.join(cmd)} failed:\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}")
    return t


def fresh_copy(dest: Path, working_tree: bool, rev: str = "HEAD") -> None:
    """The repository's tracked files in dest: rev (HEAD), or the working tree's versions."""
    if working_tree:
        names = subprocess.run(["git", "ls-files", "-z"], cwd=REPO, check=True,
                               capture_output=True).stdout.decode().split("\0")
        for name in filter(None, names):
            src = REPO / name
            if src.is_file():
                (dest / name).parent.mkdir(parents=True, exist_ok=True)
                shutil.copy2(src, dest / name)
    else:
        archive = subprocess.run(["git", "archive", rev], cwd=REPO, check=True,
                                 capture_output=True).stdout
        subprocess.run(["tar", "-x", "-C", str(dest)], input=archive, check=True)
    if (dest / "setup.py").exists():  # the compiled parts, as pip install builds them
        # (untimed; without them the copy runs the numpy routes: the same numbers, slower)
        subprocess.run([sys.executable, "setup.py", "-q", "build_ext", "--inplace"], cwd=dest,
                       check=True, capture_output=True)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--cores", type=int, default=2)
    parser.add_argument("--working-tree", action="store_true")
    parser.add_argument("--keep", type=Path, default=None)
    parser.add_argument("--compare", default=None, metavar="REV")
    args = parser.parse_args()
    print(f"machine: {os.cpu_count()} CPUs, Python {sys.version.split()[0]}, BLAS threads "
          f"{os.environ.get('OPENBLAS_NUM_THREADS', 'default')}", flush=True)
    ratios, cpu_ratios = [], []
    for i in range(args.repeat):
        with tempfile.TemporaryDirectory(prefix="contactlib-mainjob-") as tmp:
            work = Path(tmp) / "this"
            copies = {"this": work}
            if args.compare:
                copies[args.compare] = Path(tmp) / "compare"
            for name, dest in copies.items():
                dest.mkdir()
                if name == "this":
                    fresh_copy(dest, args.working_tree)
                else:
                    fresh_copy(dest, False, args.compare)
            ref = [sys.executable, "-c", REFERENCE]
            env = dict(os.environ, PYTHONPATH=str(work))
            load = os.getloadavg()[0]
            ref_cpu: list[float] = []
            before = [wall(ref, work, env, ref_cpu) for _ in range(2)]
            jobs = {}
            for name, dest in copies.items():
                cpu: list[float] = []
                t = wall([sys.executable, "-m", "snakemake", "--cores", str(args.cores)],
                         dest, dict(os.environ, PYTHONPATH=str(dest)), cpu)
                jobs[name] = (t, cpu[0], len(list((dest / "results" / "logs").rglob("*.log"))))
            after = [wall(ref, work, env, ref_cpu) for _ in range(2)]
            if args.keep is not None:
                shutil.rmtree(args.keep, ignore_errors=True)
                shutil.copytree(work / "results", args.keep)
        refs = " ".join(f"{t:.2f}" for t in before + after)
        for name, (job, cpu_job, logs) in jobs.items():
            ratio = job / min(before + after)
            cpu_ratio = cpu_job / min(ref_cpu)
            if name == "this":
                ratios.append(ratio)
                cpu_ratios.append(cpu_ratio)
            label = f"run {i + 1}" if name == "this" else f"  {name} (--compare)"
            print(f"{label}: main job {job:.1f} s ({logs} job logs), LU {SIZE} reference "
                  f"{refs} s, ratio {ratio:.1f} (load average before {load:.1f}); CPU time: "
                  f"main job {cpu_job:.1f} s, reference {min(ref_cpu):.2f} - "
                  f"{max(ref_cpu):.2f} s, ratio {cpu_ratio:.1f}", flush=True)
    if len(ratios) > 1:
        print(f"ratio range {min(ratios):.1f} - {max(ratios):.1f} over {len(ratios)} runs; "
              f"CPU-time ratio {min(cpu_ratios):.1f} - {max(cpu_ratios):.1f}")

if __name__ == "__main__":
    main()
