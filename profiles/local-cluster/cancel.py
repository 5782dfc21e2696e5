#!/usr/bin/env python3
"""Stand-in batch scheduler, cancel side: ``cancel.py JOBID [JOBID ...]``.

Snakemake's cluster-generic executor calls this (profile key
``cluster-generic-cancel-cmd``) with the ids of the jobs still running when it
is interrupted (Ctrl-C). Each job was started in its own process group by
``submit.py``; the whole group gets SIGTERM. Unknown or finished jobs are
skipped. Standard library only.
"""

from __future__ import annotations

import os
import signal
import sys
from pathlib import Path

STATE = Path("results") / "logs" / "cluster"


def main(argv: list[str]) -> int:
    for job_id in argv:
        if (STATE / f"{job_id}.exit").exists():
            continue
        try:
            pid = int((STATE / f"{job_id}.pid").read_text().strip())
            os.killpg(pid, signal.SIGTERM)
        except (FileNotFoundError, ValueError, ProcessLookupError, PermissionError):
            continue
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
