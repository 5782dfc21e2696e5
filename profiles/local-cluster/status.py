#!/usr/bin/env python3
"""Stand-in batch scheduler, status side: ``status.py JOBID``.

Snakemake's cluster-generic executor calls this for every running job
(profile key ``cluster-generic-status-cmd``) and expects exactly one line:
``running``, ``success`` or ``failed``. The answer comes from the files
``submit.py`` keeps under ``results/logs/cluster/``:

* ``<id>.exit`` exists: ``success`` when it holds 0, else ``failed``;
* otherwise the job's process (``<id>.pid``) is alive: ``running``;
* otherwise (killed without recording a status, or an unknown id): ``failed``.

Standard library only.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

STATE = Path("results") / "logs" / "cluster"


def recorded_exit(job_id: str) -> int | None:
    try:
        return int((STATE / f"{job_id}.exit").read_text().strip())
    except (FileNotFoundError, ValueError):
        return None


def alive(pid: int) -> bool:
    """Whether ``pid`` runs (a zombie, finished but not yet reaped, does not)."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return True  # no /proc: trust kill(pid, 0)
    return stat.rsplit(")", 1)[1].split()[0] != "Z"


def status(job_id: str) -> str:
    code = recorded_exit(job_id)
    if code is None:
        try:
            pid = int((STATE / f"{job_id}.pid").read_text().strip())
        except (FileNotFoundError, ValueError):
            return "failed"  # not a job of ours
        if alive(pid):
            return "running"
        code = recorded_exit(job_id)  # it may have ended between the two looks
        if code is None:
            return "failed"  # killed before it could record a status
    return "success" if code == 0 else "failed"


def main(argv: list[str]) -> int:
    if len(argv) != 1:
        print("usage: status.py JOBID", file=sys.stderr)
        return 2
    print(status(argv[0]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
