"""Cluster-style batch execution: profiles/local-cluster and profiles/slurm.

* The stand-in scheduler's scripts (submit, status, cancel) on their own:
  job ids, one submission line a job, running / success / failed, cancel.
* The default target end to end through Snakemake's cluster-generic executor
  with ``--profile profiles/local-cluster``: every job submitted (one line
  each in results/logs/cluster-submissions.log) and the datasets equal the
  library's.
* profiles/slurm names the slurm executor and leaves account and partition
  to the user; every rule declares threads, mem_mb and runtime.
"""

from __future__ import annotations

import collections
import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
import yaml

import contactlib
from conftest import REPO, make_workdir, needs_snakemake, snakemake
from contactlib.io import read_dataset

LOCAL = REPO / "profiles" / "local-cluster"
SLURM = REPO / "profiles" / "slurm"
pytestmark = pytest.mark.cluster


# ----------------------------------------------------------------------------- the stand-in scheduler
def _script(name: str, *args: str, cwd: Path) -> str:
    proc = subprocess.run([str(LOCAL / name), *args], cwd=cwd, capture_output=True, text=True,
                          timeout=60)
    assert proc.returncode == 0, proc.stderr
    return proc.stdout


def _jobscript(tmp: Path, name: str, body: str) -> Path:
    path = tmp / name
    path.write_text(f'#!/bin/sh\n# properties = {{"rule": "{name}", "jobid": 7, "threads": 1, '
                    f'"resources": {{"mem_mb": 500, "runtime": 5}}, "output": ["out/{name}"]}}\n'
                    f"{body}\n")
    return path


def _wait_status(job: str, cwd: Path, want: str, timeout: float = 30) -> None:
    deadline = time.monotonic() + timeout
    while (got := _script("status.py", job, cwd=cwd).strip()) != want:
        assert got == "running", (job, got)
        assert time.monotonic() < deadline, f"{job} still {got}"
        time.sleep(0.05)


def test_scripts_are_executable_and_standard_library_only():
    for name in ("submit.py", "status.py", "cancel.py"):
        path = LOCAL / name
        assert os.access(path, os.X_OK), f"{path} must be executable (git update-index --chmod=+x)"
        text = path.read_text()
        assert text.startswith("#!/usr/bin/env python3\n")
        imported = set(re.findall(r"^(?:from|import) (\w+)", text, flags=re.M))
        assert imported <= set(sys.stdlib_module_names), imported


def test_stand_in_scheduler_submit_status_cancel(tmp_path):
    ok = _jobscript(tmp_path, "ok", "echo hello")
    bad = _jobscript(tmp_path, "bad", "echo oops >&2; exit 3")
    slow = _jobscript(tmp_path, "slow", "sleep 60")
    ids = [_script("submit.py", str(p), cwd=tmp_path) for p in (ok, bad, slow)]
    # submit prints exactly one line: the job id
    assert [i.count("\n") for i in ids] == [1, 1, 1]
    ids = [i.strip() for i in ids]
    assert ids == ["local-000001", "local-000002", "local-000003"]
    lines = (tmp_path / "results/logs/cluster-submissions.log").read_text().splitlines()
    assert [line.split("\t")[0] for line in lines] == ids
    assert lines[0].split("\t")[1:] == ["rule=ok", "jobid=7", "threads=1", "mem_mb=500",
                                        "runtime=5", "output=out/ok"]
    _wait_status(ids[0], tmp_path, "success")
    _wait_status(ids[1], tmp_path, "failed")
    assert _script("status.py", ids[2], cwd=tmp_path).strip() == "running"
    state = tmp_path / "results/logs/cluster"
    assert (state / f"{ids[0]}.log").read_text() == "hello\n"
    assert (state / f"{ids[1]}.log").read_text() == "oops\n"
    assert (state / f"{ids[1]}.exit").read_text().strip() == "3"
    # each job is its own process group; cancel ends the whole group
    pid = int((state / f"{ids[2]}.pid").read_text())
    assert os.getpgid(pid) == pid
    _script("cancel.py", ids[2], "local-999999", cwd=tmp_path)
    _wait_status(ids[2], tmp_path, "failed")
    # a job killed from outside (no exit status recorded) is failed, an unknown id too
    killed = _script("submit.py", str(slow), cwd=tmp_path).strip()
    os.killpg(int((state / f"{killed}.pid").read_text()), signal.SIGKILL)
    _wait_status(killed, tmp_path, "failed")
    assert _script("status.py", "local-424242", cwd=tmp_path).strip() == "failed"
    assert len((tmp_path / "results/logs/cluster-submissions.log").read_text().splitlines()) == 4


# ----------------------------------------------------------------------------- end to end
CLUSTER_CONFIG = {
    "scenes": {
        "s": {"geometry": "sphere", "nu": 0.3, "method": "default", "n": 32,
              "stick_ratios": [0.0, 0.5, 1.0], "outputs": ["k_curve", "stresses"]},
    },
    "figures": {"fig2": ["s"], "fig3": ["s"]},
}
EXPECTED_JOBS = {"influence": 1, "solve": 1, "check": 1, "assemble": 1, "figures_paper": 1,
                 "key_numbers": 1}


@pytest.fixture(scope="module")
def cluster_run(tmp_path_factory):
    wd = make_workdir(tmp_path_factory.mktemp("cluster"), CLUSTER_CONFIG,
                      folders=("workflow", "profiles"))
    proc = snakemake(wd, "--profile", "profiles/local-cluster", cores=None)
    return wd, proc.stdout + proc.stderr


@needs_snakemake
@pytest.mark.workflow
@pytest.mark.slow
def test_local_cluster_profile_runs_the_default_target(cluster_run):
    wd, text = cluster_run
    assert "cluster-generic" in text or "external jobid" in text
    for fig in ("fig2", "fig3"):
        for ext in ("png", "pdf"):
            assert (wd / f"results/figures/{fig}.{ext}").stat().st_size > 1000
    assert (wd / "results/tables/key-numbers.csv").exists()
    # one submission line a job, every job through the scheduler, each one succeeded
    lines = (wd / "results/logs/cluster-submissions.log").read_text().splitlines()
    fields = [dict(f.split("=", 1) for f in line.split("\t")[1:]) for line in lines]
    assert collections.Counter(f["rule"] for f in fields) == EXPECTED_JOBS
    ids = [line.split("\t")[0] for line in lines]
    assert len(set(ids)) == len(ids)
    for job, f in zip(ids, fields):
        assert re.search(rf"Submitted job \d+ with external jobid '{job}'", text), job
        assert (wd / "results/logs/cluster" / f"{job}.exit").read_text().strip() == "0"
        # every output is there, but the influence matrices: temporary, removed once read
        assert (wd / f["output"]).exists() != (f["rule"] == "influence"), f["output"]
        # the declared resources reach the scheduler
        # (a figure family's job draws its two figures in two worker processes)
        assert f["threads"] == ("2" if f["rule"] == "figures_paper" else "1")
        assert int(f["mem_mb"]) > 0 and int(f["runtime"]) > 0
    # the numbers are the library's
    ds = read_dataset(wd / "results/datasets/s.nc")
    ref = contactlib.sweep("sphere", 0.3, [0.0, 0.5, 1.0], n=32, energy=False)
    np.testing.assert_array_equal(ds["friction_coefficient"].values,
                                  [s.friction_coefficient for s in ref])
    np.testing.assert_allclose(ds["pressure"].values, np.stack([s.pressure for s in ref]),
                               rtol=1e-13, atol=1e-15)
    # a second invocation finds nothing to do and submits nothing
    again = snakemake(wd, "--profile", "profiles/local-cluster", cores=None, timeout=300)
    assert "Nothing to be done" in again.stdout + again.stderr
    assert len((wd / "results/logs/cluster-submissions.log").read_text().splitlines()) == \
        len(lines)


# ----------------------------------------------------------------------------- slurm
def _rule_blocks() -> dict[str, str]:
    """Text of every rule in workflow/rules/*.smk, by name (figure rules by their f-string)."""
    blocks = {}
    for path in sorted((REPO / "workflow" / "rules").glob("*.smk")):
        text = path.read_text()
        starts = [m for m in re.finditer(r"^(\s*)rule\s*(\w*)\s*:", text, flags=re.M)]
        for i, m in enumerate(starts):
            end = starts[i + 1].start() if i + 1 < len(starts) else len(text)
            body = text[m.end():end]
            name = m.group(2) or re.search(r"name:\s*\n\s*(\S+)", body).group(1)
            blocks[f"{path.name}:{name}"] = body
    return blocks


def test_every_rule_declares_threads_memory_and_runtime():
    blocks = _rule_blocks()
    assert len(blocks) >= 8  # influence, solve, check, energy, assemble, history_run, ...
    for name, body in blocks.items():
        if not re.search(r"^\s*(script|shell|run|wrapper|notebook):", body, flags=re.M):
            continue  # a target that only collects inputs: runs locally, nothing to size
        assert re.search(r"^\s*threads:\s*\S", body, flags=re.M), f"{name}: no threads"
        resources = re.search(r"^\s*resources:\s*\n((?:\s{8,}.*\n)+)", body, flags=re.M)
        assert resources, f"{name}: no resources"
        assert re.search(r"^\s*mem_mb\s*=", resources.group(1), flags=re.M), f"{name}: no mem_mb"
        assert re.search(r"^\s*runtime\s*=", resources.group(1), flags=re.M), \
            f"{name}: no runtime"


def test_slurm_profile_names_the_executor_and_leaves_account_to_the_user():
    cfg = yaml.safe_load((SLURM / "config.yaml").read_text())
    assert cfg["executor"] == "slurm"
    text = yaml.safe_dump(cfg)
    assert "slurm_account" not in text and "slurm_partition" not in text
    assert "default-resources" not in cfg  # a user's profile may set account/partition there
    assert cfg.get("retries", 0) >= 1  # memory and runtime grow with the attempt
    pyproject = (REPO / "pyproject.toml").read_text()
    assert "snakemake-executor-plugin-slurm" in pyproject
    assert "snakemake-executor-plugin-cluster-generic" in pyproject


@needs_snakemake
@pytest.mark.workflow
@pytest.mark.slow
def test_slurm_profile_dry_run(tmp_path):
    """With the optional plugin installed (``pip install -e '.[slurm]'``) the profile loads."""
    pytest.importorskip("snakemake_executor_plugin_slurm")
    wd = make_workdir(tmp_path, folders=("workflow", "profiles", "config"))
    proc = snakemake(wd, "--profile", "profiles/slurm", "--dry-run", cores=None, check=False,
                     timeout=300)
    text = proc.stdout + proc.stderr
    assert proc.returncode == 0, text
    assert "influence" in text and "solve" in text
