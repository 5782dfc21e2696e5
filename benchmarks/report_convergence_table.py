"""The speed-accuracy table of docs/accuracy.md ("The speed-accuracy trade").

    python benchmarks/report_convergence_table.py [n_min] [study ...]

Runs the default-method studies of ``convergence:`` in config/config.yaml
(default both, ``sphere-default`` and ``cylinder-default``: nu = 0.3, the
config's stick ratios, n doubling from ``n_min`` (default 64) to the
config's largest n) with :func:`contactlib.convergence.study`, and prints
per study and n: the median wall time of one :func:`contactlib.solve`
(kernels, Newton, profiles, flags, work and the error estimates), the median
relative k error over the stick ratios and the peak memory. The reference
is the Richardson value of the finest triple whose observed order lies in
[1, 3] (:func:`contactlib.convergence.converged_richardson`; ``snakemake
convergence`` takes order >= 1 with no upper bound), and the table says which.
The k values themselves go to stderr. Runs the same
solves as the workflow's default studies, without the workflow; about 10 min
on an idle core.
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")  # before numpy is imported

import pathlib
import sys

import numpy as np
import yaml

from contactlib.convergence import converged_richardson, study

CONFIG = pathlib.Path(__file__).resolve().parents[1] / "config" / "config.yaml"
STUDIES = ("sphere-default", "cylinder-default")


def reference(k: np.ndarray, ns: list[int]) -> tuple[float, int]:
    """Richardson value of the finest triple (ending at ns[i]) that converges at order
    1 ... 3, and that triple's finest n (NaN, 0 when none does)."""
    ref, order, end = converged_richardson(k, 1.0, 3.0)
    return (ref, ns[end]) if np.isfinite(order) else (float("nan"), 0)


def main() -> None:
    args = sys.argv[1:]
    n_min = int(args.pop(0)) if args and args[0].isdigit() else 64
    names = args or list(STUDIES)
    conf = yaml.safe_load(CONFIG.read_text())["convergence"]
    unknown = [x for x in names if x not in conf["studies"]]
    if unknown:
        sys.exit(f"unknown study {unknown[0]!r}: the studies of config/config.yaml are "
                 + ", ".join(conf["studies"]) + " (usage: python "
                 "benchmarks/report_convergence_table.py [n_min] [study ...])")
    for name in names:
        spec = dict(conf["studies"][name])
        ns = [n for n in spec.pop("n") if n >= n_min]
        st = study(spec["geometry"], spec["nu"], spec["method"], ns, conf["stick_ratios"],
                   slab_ratio=spec.get("slab_ratio", 0.0),
                   progress=lambda s: print("  " + s, file=sys.stderr, flush=True))
        k = st.values[0]  # (n, stick_ratio)
        print(f"{name} k:\n" + "\n".join(f"  n = {n}: " + " ".join(f"{v:.12g}" for v in row)
                                        for n, row in zip(ns, k)), file=sys.stderr)
        refs = [reference(k[:, j], ns) for j in range(k.shape[1])]
        ref = np.array([r for r, _ in refs])
        err = np.abs(k / ref - 1.0)
        print(f"\n{name} (stick ratios {conf['stick_ratios']}; reference: Richardson of the "
              f"triple ending at n = {[e for _, e in refs]})\n")
        print("| n | time a solve (median) | median k error | largest k error | peak memory |")
        print("|---|---|---|---|---|")
        for i, n in enumerate(ns):
            print(f"| {n} | {np.median(st.wall_time[i]):.3g} s | {np.median(err[i]):.1e} | "
                  f"{np.max(err[i]):.1e} | {np.max(st.peak_memory[i]) / 1024:.2f} GiB |",
                  flush=True)


if __name__ == "__main__":
    main()
