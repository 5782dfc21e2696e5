"""The speed-accuracy table of docs/accuracy.md ("The speed-accuracy trade").

    python benchmarks/report_convergence_table.py [n_min]

Runs the default-method studies of ``convergence:`` in config/config.yaml
(``sphere-default`` and ``cylinder-default``: nu = 0.3, the config's stick
ratios, n doubling from ``n_min`` (default 64) to the config's largest n)
with :func:`contactlib.convergence.study`, and prints the table: per n the
median wall time of one solve (kernels, Newton, profiles, flags, work and
the error estimates of :func:`contactlib.solve`) and the median relative k
error against the Richardson value of the three finest n, plus the peak
memory at the largest n. Runs the same solves as ``snakemake convergence``'s
default studies, without the workflow; about 10 min on one core.
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")  # before numpy is imported

import pathlib
import sys

import yaml

from contactlib import io
from contactlib.convergence import study, trade_table

CONFIG = pathlib.Path(__file__).resolve().parents[1] / "config" / "config.yaml"
STUDIES = ("sphere-default", "cylinder-default")


def main() -> None:
    n_min = int(sys.argv[1]) if len(sys.argv) > 1 else 64
    conf = yaml.safe_load(CONFIG.read_text())["convergence"]
    rows = {}
    for name in STUDIES:
        spec = dict(conf["studies"][name])
        ns = [n for n in spec.pop("n") if n >= n_min]
        st = study(spec["geometry"], spec["nu"], spec["method"], ns, conf["stick_ratios"],
                   slab_ratio=spec.get("slab_ratio", 0.0),
                   progress=lambda s: print("  " + s, file=sys.stderr, flush=True))
        rows[name] = trade_table([io.study_to_dataset(st)])
    print("| n | sphere: time a solve | median k error | cylinder a/h = 1/20: time "
          "| median k error |")
    print("|---|---|---|---|---|")
    for s, c in zip(*(rows[name] for name in STUDIES)):
        mem = ""
        if s is rows[STUDIES[0]][-1]:
            mem = f", {s['peak_memory_MiB'] / 1024:.1f} GiB"
        cmem = f", {c['peak_memory_MiB'] / 1024:.1f} GiB" if mem else ""
        print(f"| {s['n']} | {s['time_s']:.3g} s{mem} | {s['median_error']:.1e} | "
              f"{c['time_s']:.3g} s{cmem} | {c['median_error']:.1e} |")


if __name__ == "__main__":
    main()
