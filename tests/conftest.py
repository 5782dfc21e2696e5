"""Shared test helpers: copies of the workflow in a temporary folder, snakemake runs.

Markers (registered in ``pyproject.toml``):

``slow``
    more than about 10 s on a loaded 2-core machine, or a snakemake run that repeats
    a check the fast tier makes in the library. ``python -m pytest -m "not slow"``
    is the fast tier for development; every property checked by a slow test keeps a
    cheaper check (smaller n, a tiny configuration, one of several refusals) in the
    fast tier.
``workflow``
    runs snakemake as a subprocess (dry runs, tiny end-to-end runs, the main job).
``cluster``
    goes through a batch profile (the local stand-in scheduler, SLURM).

Test modules import the helpers below with ``from conftest import ...``.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import yaml

REPO = Path(__file__).resolve().parents[1]
DATA = Path(__file__).resolve().parent / "data"
SNAKEMAKE = [sys.executable, "-m", "snakemake"]
# the checked-out library first, whatever else is installed; a fixed hash seed
ENV = dict(os.environ, PYTHONHASHSEED="0", PYTHONPATH=os.pathsep.join(
    p for p in (str(REPO), os.environ.get("PYTHONPATH", "")) if p))


def has_snakemake() -> bool:
    return subprocess.run(SNAKEMAKE + ["--version"], capture_output=True,
                          env=ENV).returncode == 0


needs_snakemake = pytest.mark.skipif(not has_snakemake(), reason="snakemake is not installed")


def make_workdir(tmp: Path, config: dict | str | None = None, *,
                 folders: tuple[str, ...] = ("workflow", "config")) -> Path:
    """A copy of the workflow (Snakefile and ``folders``) in tmp.

    ``config`` replaces ``config/config.yaml``: a dict (dumped as YAML), the text of
    the file, or None to keep the repository's (``config/`` is then copied, so the
    material and other files it names come along).
    """
    shutil.copy(REPO / "Snakefile", tmp / "Snakefile")
    for folder in folders:
        shutil.copytree(REPO / folder, tmp / folder, ignore=shutil.ignore_patterns("__pycache__"))
    if config is not None:
        (tmp / "config").mkdir(exist_ok=True)
        text = config if isinstance(config, str) else yaml.safe_dump(config, sort_keys=False)
        (tmp / "config" / "config.yaml").write_text(text)
    return tmp


def snakemake(workdir: Path, *args: str, cores: int | None = 2, check: bool = True,
              timeout: float = 900) -> subprocess.CompletedProcess:
    """Run snakemake in workdir (``--cores`` unless None, e.g. with a profile)."""
    cmd = SNAKEMAKE + (["--cores", str(cores)] if cores is not None else []) + list(args)
    proc = subprocess.run(cmd, cwd=workdir, env=ENV, capture_output=True, text=True,
                          timeout=timeout)
    if check and proc.returncode != 0:
        raise AssertionError(f"snakemake {' '.join(args)} failed:\n{proc.stdout}\n{proc.stderr}")
    return proc


def dry_run(workdir: Path) -> tuple[int, str]:
    """Exit status and output of ``snakemake --cores 1 --dry-run``."""
    proc = snakemake(workdir, "--dry-run", cores=1, check=False, timeout=300)
    return proc.returncode, proc.stdout + proc.stderr


def job_counts(workdir: Path, *args: str) -> dict[str, int]:
    """Jobs a dry run would execute, by rule."""
    out = snakemake(workdir, "--dry-run", *args)
    text = out.stdout + out.stderr
    table = text[text.index("Job stats:"):]
    counts = {}
    for line in table.splitlines()[3:]:
        parts = line.split()
        if len(parts) != 2 or not parts[1].isdigit() or parts[0] == "total":
            if parts and parts[0] == "total":
                break
            continue
        counts[parts[0]] = int(parts[1])
    return counts


def nothing_to_do(workdir: Path) -> bool:
    out = snakemake(workdir, "--dry-run")
    return "Nothing to be done" in out.stdout + out.stderr


@pytest.fixture
def factorizations(monkeypatch):
    """A counter (a one-item list) of the solvers' LU factorizations, one per Newton
    iteration and level, counted from the test's start."""
    from contactlib.solvers import default_method
    count = [0]
    lu_factor = default_method.linalg.lu_factor

    def counted(*args, **kwargs):
        count[0] += 1
        return lu_factor(*args, **kwargs)

    monkeypatch.setattr(default_method.linalg, "lu_factor", counted)
    return count


def trapezoid_work(res) -> np.ndarray:
    """Cumulative frictional work by the plain trapezoid rule, from the result's arrays.

    Minus the shear's work on the surface, ``-sum As_j (q_old + q_new)_j / 2 du_j`` over
    the elements slipping at the end of a step and those slipping before it that
    separate in it, summed over the steps (0 at step 0); ``As_j`` the shear-weighted
    element area. The history reports its lower monotone envelope.
    """
    lo, hi = res.xi_bounds[:, 0], res.xi_bounds[:, 1]
    mid = 0.5 * (lo + hi)
    shear_area = (2.0 * np.pi / 3.0 * (hi**3 - lo**3) / mid if res.geometry == "sphere"
                  else 2.0 * (hi - lo))  # int (r / r_j) 2 pi r dr, or 2 dx
    q = res.shear * (2.0 / np.pi if res.geometry == "sphere" else 0.5)  # p0 (history_api)
    du = np.diff(res.tangential_displacement, axis=0)
    st = res.state
    moving = (st[1:] >= 2) | ((st[1:] == 0) & (st[:-1] >= 2))
    terms = np.where(moving, -0.5 * (q[1:] + q[:-1]) * du * shear_area, 0.0)
    return np.concatenate([[0.0], np.cumsum(terms.sum(axis=1))])
