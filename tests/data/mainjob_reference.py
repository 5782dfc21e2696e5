"""Regenerate ``tests/data/mainjob_reference.json``: a fingerprint of the main job's outputs.

The main job is the README Quickstart's ``snakemake --cores 2`` with the repository's
``config/config.yaml``. ``tests/test_mainjob.py`` runs it in a temporary copy of the
workflow and compares its outputs with the stored fingerprint:

* the list of final files (datasets, figures, tables);
* each dataset's dimensions, variables, their dtypes and attributes (the package
  version left out);
* the numbers of each variable: every value of a variable with at most 64 of them,
  otherwise its sum, the sum of its absolute values and 9 values at evenly spaced
  flat positions (NaNs counted apart), compared for meaning (converged values within
  their estimates or round-off, estimates within a factor: ``tests/test_mainjob.py``);
* every cell of the key-numbers table (numbers within one unit of the last quoted
  digit, text exactly);
* the SHA-256 of every figure (for reference: figures are compared byte for byte only
  against a second drawing on the same machine).

**A change of any stored number must be a named bug fix**: regenerate the reference
only in the commit that fixes the bug, and name the bug and the numbers it moves in
that commit's message. A restructuring that moves a number is a bug in the
restructuring, not a reason to regenerate.

Usage (from the repository root)::

    python tests/data/mainjob_reference.py            # runs the main job in a temporary copy
    python tests/data/mainjob_reference.py WORKDIR    # fingerprints WORKDIR/results as it is
"""

from __future__ import annotations

import csv
import hashlib
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[2]
OUT = Path(__file__).resolve().with_name("mainjob_reference.json")
FINAL = ("datasets/*.nc", "figures/*.png", "figures/*.pdf", "tables/*.csv")
SMALL = 64  # variables with at most this many values are stored in full
SAMPLES = 9
VOLATILE_ATTRS = ("contactlib_version",)


def _number(v: float) -> float | str | None:
    """JSON-safe float: NaN as None, infinities as strings."""
    v = float(v)
    if math.isnan(v):
        return None
    if math.isinf(v):
        return "inf" if v > 0 else "-inf"
    return v


def _attr(v):
    if isinstance(v, np.ndarray):
        return [_attr(x) for x in v.tolist()]
    if isinstance(v, (list, tuple)):
        return [_attr(x) for x in v]
    if isinstance(v, (np.integer, int)) and not isinstance(v, bool):
        return int(v)
    if isinstance(v, (np.floating, float)):
        return _number(v)
    return str(v)


def fingerprint_array(values: np.ndarray) -> dict:
    """Every value (small arrays), or sums and evenly spaced samples."""
    a = np.asarray(values)
    out: dict = {"dtype": str(a.dtype), "shape": list(a.shape)}
    if a.dtype.kind not in "biuf":
        out["text"] = [str(x) for x in a.ravel().tolist()] if a.size <= SMALL else \
            hashlib.sha256("\n".join(map(str, a.ravel().tolist())).encode()).hexdigest()
        return out
    flat = a.astype(float).ravel()
    if flat.size <= SMALL:
        out["values"] = [_number(v) for v in flat]
        return out
    nan = np.isnan(flat)
    out["nan_count"] = int(nan.sum())
    out["sum"] = _number(np.sum(flat[~nan]))
    out["abs_sum"] = _number(np.sum(np.abs(flat[~nan])))
    idx = np.linspace(0, flat.size - 1, SAMPLES).round().astype(int)
    out["samples"] = {str(i): _number(flat[i]) for i in idx}
    return out


def fingerprint_dataset(path: Path) -> dict:
    from contactlib.io import read_dataset

    ds = read_dataset(path)
    return {
        "sizes": {k: int(v) for k, v in sorted(ds.sizes.items())},
        "attrs": {k: _attr(v) for k, v in sorted(ds.attrs.items())
                  if k not in VOLATILE_ATTRS},
        "variables": {name: dict(fingerprint_array(ds[name].values),
                                 dims=list(ds[name].dims),
                                 attrs={k: _attr(v) for k, v in sorted(ds[name].attrs.items())})
                      for name in sorted(ds.variables)},
    }


def fingerprint_table(path: Path) -> list[list]:
    rows = []
    with open(path, newline="") as fh:
        for row in csv.reader(fh):
            cells = []
            for cell in row:
                try:
                    cells.append(_number(float(cell)) if cell.strip() else cell)
                except ValueError:
                    cells.append(cell)
            rows.append(cells)
    return rows


def final_files(results: Path) -> list[str]:
    return sorted(str(p.relative_to(results)) for pattern in FINAL
                  for p in results.glob(pattern) if not p.name.startswith("."))


def fingerprint(results: Path) -> dict:
    """The fingerprint of a results folder of the main job."""
    import matplotlib

    files = final_files(results)
    return {
        "files": files,
        "datasets": {f: fingerprint_dataset(results / f) for f in files if f.endswith(".nc")},
        "tables": {f: fingerprint_table(results / f) for f in files if f.endswith(".csv")},
        "figures": {"matplotlib": matplotlib.__version__,
                    "sha256": {f: hashlib.sha256((results / f).read_bytes()).hexdigest()
                               for f in files if f.startswith("figures/")}},
    }


def run_main_job(workdir: Path) -> None:
    """The README's main command in a copy of the workflow."""
    shutil.copy(REPO / "Snakefile", workdir / "Snakefile")
    for folder in ("workflow", "config"):
        shutil.copytree(REPO / folder, workdir / folder,
                        ignore=shutil.ignore_patterns("__pycache__"))
    env = dict(os.environ, PYTHONHASHSEED="0", PYTHONPATH=os.pathsep.join(
        p for p in (str(REPO), os.environ.get("PYTHONPATH", "")) if p))
    subprocess.run([sys.executable, "-m", "snakemake", "--cores", "2"], cwd=workdir, env=env,
                   check=True)


def main(argv: list[str]) -> None:
    sys.path.insert(0, str(REPO))  # this checkout's contactlib
    if argv:
        results = Path(argv[0]) / "results"
        ref = fingerprint(results)
    else:
        with tempfile.TemporaryDirectory() as tmp:
            run_main_job(Path(tmp))
            ref = fingerprint(Path(tmp) / "results")
    OUT.write_text(json.dumps(ref, indent=1, sort_keys=True) + "\n")
    print(f"wrote {OUT} ({len(ref['files'])} files)")


if __name__ == "__main__":
    main(sys.argv[1:])
