"""Is the main job the same on another machine? Runs it under several set-ups and compares.

Each set-up is ``KERNEL:PYTHON``: an OpenBLAS kernel (``OPENBLAS_CORETYPE``; ``default``
leaves the machine's own) and the Python of a virtual environment (today's packages, or
the oldest supported ones of ``.ci/oldest.txt``). The first set-up is the reference; each
other one's main job (``snakemake --cores 2`` in a fresh copy of the workflow) is compared
with it the way ``tests/test_mainjob.py`` compares with the stored fingerprint (values
within their estimates or round-off, estimates within a factor 2), and reports:

* the largest difference of k, load and work relative to the case's own estimate;
* whether the key-numbers table is identical, cell for cell;
* the figures: byte-identical or not, and how many pixels differ and by how much.

Usage (from the repository root)::

    python benchmarks/report_reproducibility.py \\
        default:/work/venv/bin/python Sandybridge:/work/venv/bin/python \\
        default:/work/venv-low/bin/python

Prints one block a set-up; takes about a minute a set-up on 2 cores.
"""

from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "tests"))

import test_mainjob as tm  # noqa: E402  (the comparison the tests use)


def run_main_job(workdir: Path, kernel: str, python: str) -> Path:
    """The README's main command in a copy of the workflow; the results folder."""
    shutil.copy(REPO / "Snakefile", workdir / "Snakefile")
    for folder in ("workflow", "config"):
        shutil.copytree(REPO / folder, workdir / folder,
                        ignore=shutil.ignore_patterns("__pycache__"))
    env = dict(os.environ, PYTHONPATH=str(REPO))
    env.pop("OPENBLAS_CORETYPE", None)
    if kernel != "default":
        env["OPENBLAS_CORETYPE"] = kernel
    subprocess.run([python, "-m", "snakemake", "--cores", "2", "-q"], cwd=workdir, env=env,
                   check=True, capture_output=True)
    return workdir / "results"


def versions(python: str, kernel: str) -> str:
    env = dict(os.environ)
    env.pop("OPENBLAS_CORETYPE", None)
    if kernel != "default":
        env["OPENBLAS_CORETYPE"] = kernel
    code = ("import numpy, scipy, threadpoolctl; info = threadpoolctl.threadpool_info(); "
            "print(f'numpy {numpy.__version__}, scipy {scipy.__version__}, OpenBLAS kernel "
            "' + ', '.join(str(i.get('architecture')) for i in info if "
            "i.get('internal_api') == 'openblas'))")
    return subprocess.run([python, "-c", code], env=env, capture_output=True, text=True,
                          check=True).stdout.strip()


def worst_over_estimate(a: Path, b: Path) -> float:
    """Largest |difference| / (estimate |value|) of k, load and work over the default scenes."""
    import xarray as xr

    worst = 0.0
    for path in sorted((a / "datasets").glob("*-default.nc")):
        with xr.open_dataset(path) as x, xr.open_dataset(b / "datasets" / path.name) as y:
            for name, est in tm.ESTIMATE_OF.items():
                u, v = x[name].values, y[name].values
                e = np.maximum(x[est].values, tm.ROUNDOFF) * np.abs(u)
                ok = np.isfinite(u) & np.isfinite(v) & (e > 0)
                if ok.any():
                    worst = max(worst, float(np.max(np.abs(u[ok] - v[ok]) / e[ok])))
    return worst


def pixels(a: Path, b: Path) -> tuple[int, float]:
    import matplotlib.image as mpimg

    x, y = mpimg.imread(a), mpimg.imread(b)
    if x.shape != y.shape:
        return -1, float("inf")
    d = np.abs(x - y).max(axis=-1)
    return int((d > 0).sum()), float(d.max())


def main(setups: list[str]) -> None:
    if len(setups) < 2:
        raise SystemExit(__doc__)
    with tempfile.TemporaryDirectory() as tmp:
        runs = []
        for i, setup in enumerate(setups):
            kernel, python = setup.split(":", 1)
            wd = Path(tmp) / f"run{i}"
            wd.mkdir()
            runs.append((setup, run_main_job(wd, kernel, python), versions(python, kernel)))
        ref_setup, ref, ref_versions = runs[0]
        print(f"reference: {ref_setup} ({ref_versions})")
        fp_ref = tm._script().fingerprint(ref)
        for setup, res, ver in runs[1:]:
            print(f"\n{setup} ({ver})")
            fp = tm._script().fingerprint(res)
            bad = []
            for name, want in fp_ref["datasets"].items():
                try:
                    tm.assert_same_dataset(fp["datasets"][name], want, name)
                except AssertionError as exc:
                    bad.append(f"{name}: {str(exc)[:160]}")
            print(f"  datasets equal in content: {'yes' if not bad else 'NO'}")
            for line in bad:
                print(f"    {line}")
            print(f"  largest k/load/work difference over its estimate: "
                  f"{worst_over_estimate(ref, res):.3g}")
            same_table = (ref / "tables/key-numbers.csv").read_bytes() == \
                (res / "tables/key-numbers.csv").read_bytes()
            print(f"  key numbers identical: {'yes' if same_table else 'NO'}")
            for fig in sorted((ref / "figures").glob("*.png")):
                other = res / "figures" / fig.name
                same = hashlib.sha256(fig.read_bytes()).digest() == \
                    hashlib.sha256(other.read_bytes()).digest()
                count, most = (0, 0.0) if same else pixels(fig, other)
                print(f"  {fig.name}: " + ("byte-identical" if same else
                                          f"{count} pixels differ, by at most {most * 255:.0f}/255"))


if __name__ == "__main__":
    main(sys.argv[1:])
