"""Interruption and determinism of the workflow's default target.

* Kill the whole workflow (SIGKILL to its process group) while jobs run,
  check that no half-written file sits under a final name, unlock, rerun with
  ``--rerun-incomplete``: every dataset, figure and table is byte-identical to
  an uninterrupted run, and the temporary files of the killed writers are gone
  (the rerun's writers remove them).
* Two clean runs of the default target give byte-identical datasets, figures
  and tables.

Each run works in its own copy of the workflow (Snakefile, workflow/, config/)
with a small config: one default-method scene at n = 32 and one paper scene
at n = 8, all four figures.
"""

from __future__ import annotations

import os
import signal
import subprocess
import time
from pathlib import Path

import numpy as np
import pytest

from conftest import ENV, SNAKEMAKE, make_workdir, needs_snakemake, snakemake
from contactlib.io import read_arrays, read_dataset

pytestmark = [needs_snakemake, pytest.mark.workflow, pytest.mark.slow]


SMALL = {
    "scenes": {
        "sph": {"geometry": "sphere", "nu": 0.3, "method": "default", "n": 32,
                "stick_ratios": [0.0, 0.3, 0.6, 1.0],
                "outputs": ["k_curve", "stresses", "displacements", "energy"]},
        "pap": {"geometry": "cylinder", "nu": 0.3, "method": "paper", "n": 8,
                "slab_ratio": 0.05, "stick_ratios": "all", "outputs": ["k_curve", "energy"]},
    },
    "figures": {"fig2": ["sph", "pap"], "fig3": ["sph"], "fig4": ["sph"],
                "fig5": ["sph", "pap"]},
}

FINAL = ("datasets/*.nc", "figures/*.png", "figures/*.pdf", "tables/*")


def final_files(workdir: Path) -> dict[str, bytes]:
    """Every final output of the default target (datasets, figures, tables), by path."""
    out = {}
    for pattern in FINAL:
        for path in sorted((workdir / "results").glob(pattern)):
            if not path.name.startswith("."):
                out[str(path.relative_to(workdir))] = path.read_bytes()
    return out


def assert_same_outputs(a: Path, b: Path) -> None:
    fa, fb = final_files(a), final_files(b)
    assert sorted(fa) == sorted(fb)
    assert len([f for f in fa if f.endswith(".nc")]) == len(SMALL["scenes"])
    assert len([f for f in fa if f.startswith("results/figures/")]) == 8
    for name in fa:
        if name.endswith(".nc"):  # values first, for a readable failure
            da, db = read_dataset(a / name), read_dataset(b / name)
            assert da.identical(db), name
        assert fa[name] == fb[name], f"{name} differs"


@pytest.fixture(scope="module")
def reference(tmp_path_factory) -> Path:
    """An uninterrupted run of the default target."""
    wd = make_workdir(tmp_path_factory.mktemp("reference"), SMALL)
    snakemake(wd)
    return wd


# ----------------------------------------------------------------------------- determinism
def test_two_runs_give_identical_datasets_and_figures(reference, tmp_path):
    wd = make_workdir(tmp_path, SMALL)
    snakemake(wd)
    assert_same_outputs(reference, wd)


# ----------------------------------------------------------------------------- interruption
def _group_alive(pgid: int) -> bool:
    """Whether any process of the group still runs (zombies do not count)."""
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[2]) == pgid and fields[0] != "Z":
            return True
    return False


def _running_jobs(workdir: Path) -> int:
    """Jobs Snakemake has marked as started and not finished."""
    marks = workdir / ".snakemake" / "incomplete"
    return sum(1 for _ in marks.iterdir()) if marks.is_dir() else 0


def _kill_mid_run(workdir: Path) -> str:
    """Start the workflow in its own process group; SIGKILL the group mid-run.

    The kill comes the moment a dataset is being written (its temporary file
    exists), or else once one dataset is final while other jobs still run.
    Returns which of the two it was.
    """
    log = open(workdir / "killed-run.log", "w")
    proc = subprocess.Popen(SNAKEMAKE + ["--cores", "2"], cwd=workdir, env=ENV,
                            stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    datasets = workdir / "results" / "datasets"
    when = None
    deadline = time.monotonic() + 600
    try:
        while when is None:
            assert proc.poll() is None, "the workflow ended before it could be interrupted"
            assert time.monotonic() < deadline, "no job finished in time"
            if datasets.is_dir():
                names = [p.name for p in datasets.iterdir()]
                if any(n.startswith(".") and n.endswith(".tmp") for n in names):
                    when = "while a dataset was being written"
                elif any(n.endswith(".nc") and not n.startswith(".") for n in names) \
                        and _running_jobs(workdir) > 0:
                    when = "after one dataset, with other jobs running"
            time.sleep(0.005)
        os.killpg(proc.pid, signal.SIGKILL)
    finally:
        if proc.poll() is None and when is None:
            os.killpg(proc.pid, signal.SIGKILL)
        proc.wait(timeout=60)
        log.close()
    deadline = time.monotonic() + 30
    while _group_alive(proc.pid):
        assert time.monotonic() < deadline, "processes of the killed workflow survive"
        time.sleep(0.1)
    assert proc.returncode == -signal.SIGKILL
    return when


def _no_half_written_files(workdir: Path) -> list[Path]:
    """Every file under a final name is complete; returns the leftover temporary files."""
    results = workdir / "results"
    leftovers = []
    for path in results.rglob("*"):
        if not path.is_file() or path.parent.name == "logs" or "logs" in path.parts:
            continue
        name = path.name
        if name.startswith(".") and name.endswith(".tmp"):
            leftovers.append(path)  # io._atomic_target's temporary: never a final name
        elif name.endswith(".nc"):
            read_dataset(path, require_checksum=True)  # whole, and as written
        elif name.endswith(".npz"):
            read_arrays(path)  # (its content check is required)
        elif name.endswith(".png"):
            data = path.read_bytes()
            assert data.startswith(b"\x89PNG") and data.endswith(b"IEND\xaeB`\x82"), path
        elif name.endswith(".pdf"):
            assert path.read_bytes().rstrip().endswith(b"%%EOF"), path
        elif name.endswith(".csv"):
            assert path.read_text().endswith("\n"), path
        elif name.endswith(".html"):
            assert path.read_text().rstrip().endswith("</html>"), path
    return leftovers


def test_kill_and_resume_gives_the_uninterrupted_results(reference, tmp_path):
    wd = make_workdir(tmp_path, SMALL)
    when = _kill_mid_run(wd)
    datasets = sorted(p.name for p in (wd / "results" / "datasets").glob("*.nc"))
    # influence matrices are temp(): a finished job shows as any final npz
    finished = [p for p in (wd / "results").rglob("*.npz") if not p.name.startswith(".")]
    assert finished, "the kill came before any job had finished"
    leftovers = _no_half_written_files(wd)
    print(f"killed {when}; final datasets then: {datasets}; "
          f"temporary files left: {[p.name for p in leftovers]}")

    # a plain rerun refuses (the killed run's lock and incomplete outputs are
    # on record); --unlock clears the lock, --rerun-incomplete redoes those jobs
    refused = subprocess.run(SNAKEMAKE + ["--cores", "2"], cwd=wd, env=ENV,
                             capture_output=True, text=True, timeout=300)
    assert refused.returncode != 0
    reason = (refused.stdout + refused.stderr).lower()
    assert "lock" in reason or "incomplete" in reason, reason
    snakemake(wd, "--unlock")
    resumed = snakemake(wd, "--rerun-incomplete")
    assert "Finished" in resumed.stdout + resumed.stderr

    assert_same_outputs(reference, wd)
    # the rerun's own writes left nothing behind, and its writers removed the temporary
    # files the killed ones left (a stale one stayed for good before)
    assert _no_half_written_files(wd) == []
    dry = snakemake(wd, "--dry-run")
    assert "Nothing to be done" in dry.stdout + dry.stderr


def test_reference_datasets_are_sound(reference):
    """The reference itself: the datasets hold the physics (frictionless = Hertz)."""
    ds = read_dataset(reference / "results/datasets/sph.nc")
    assert abs(float(ds["load_ratio"].values[0]) - 1.0) < 2e-3
    assert np.isinf(ds["friction_coefficient"].values[-1])
    assert ds["consistent"].values.all()
