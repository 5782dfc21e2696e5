#!/usr/bin/env python3
"""Stand-in batch scheduler, submit side: ``submit.py JOBSCRIPT``.

Snakemake's cluster-generic executor calls this once per job (profile key
``cluster-generic-submit-cmd``) with the path of the job's script appended.
Like ``sbatch`` it queues the job and prints a job id, and nothing else, on
stdout; here "queueing" means starting the script at once in the background,
in its own session and process group, on this machine.

Per job, under ``results/logs/cluster/`` (relative to the directory Snakemake
runs in, the workflow's root):

* ``<id>.sh``    a copy of the job script (Snakemake deletes its own copy at exit),
* ``<id>.log``   the job's stdout and stderr,
* ``<id>.pid``   the process id of the job (also its process-group id),
* ``<id>.exit``  the job's exit status, written (atomically) when it ends.

and one line per submission is appended to
``results/logs/cluster-submissions.log``::

    <id>  rule=<rule>  jobid=<snakemake job id>  threads=<n>  mem_mb=<m>  runtime=<min>  output=<first output>

Job ids are ``local-000001``, ``local-000002``, ... (the line number in the
submissions log, taken under a file lock, so they are unique across runs).
``status.py`` and ``cancel.py`` read the files above. Standard library only.
"""

from __future__ import annotations

import fcntl
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

STATE = Path("results") / "logs" / "cluster"
SUBMISSIONS = Path("results") / "logs" / "cluster-submissions.log"

# run the job, then record its exit status atomically (status.py reads it)
WRAPPER = 'sh "$1"; code=$?; echo $code > "$2.tmp"; mv "$2.tmp" "$2"; exit $code'


def job_properties(jobscript: Path) -> dict:
    """The ``# properties = {...}`` line Snakemake writes into every job script."""
    with open(jobscript, encoding="utf-8") as fh:
        for line in fh:
            if line.startswith("# properties = "):
                return json.loads(line[len("# properties = "):])
    return {}


def main(argv: list[str]) -> int:
    if len(argv) != 1:
        print("usage: submit.py JOBSCRIPT", file=sys.stderr)
        return 2
    jobscript = Path(argv[0])
    props = job_properties(jobscript)
    resources = props.get("resources", {})
    STATE.mkdir(parents=True, exist_ok=True)
    with open(SUBMISSIONS, "a+", encoding="utf-8") as log:
        fcntl.flock(log, fcntl.LOCK_EX)  # one submitter at a time: unique, ordered ids
        log.seek(0)
        number = sum(1 for _ in log) + 1
        job_id = f"local-{number:06d}"
        script = STATE / f"{job_id}.sh"
        shutil.copyfile(jobscript, script)
        exit_file = STATE / f"{job_id}.exit"
        with open(STATE / f"{job_id}.log", "wb") as out:
            proc = subprocess.Popen(
                ["/bin/sh", "-c", WRAPPER, "local-cluster-job", str(script), str(exit_file)],
                stdin=subprocess.DEVNULL, stdout=out, stderr=subprocess.STDOUT,
                start_new_session=True, close_fds=True,
            )
        pid_file = STATE / f"{job_id}.pid"
        pid_file.with_suffix(".pid.tmp").write_text(f"{proc.pid}\n")
        os.replace(pid_file.with_suffix(".pid.tmp"), pid_file)
        outputs = props.get("output") or ["-"]
        fields = [
            job_id,
            f"rule={props.get('rule', '?')}",
            f"jobid={props.get('jobid', '?')}",
            f"threads={props.get('threads', '?')}",
            f"mem_mb={resources.get('mem_mb', '?')}",
            f"runtime={resources.get('runtime', '?')}",
            f"output={outputs[0]}",
        ]
        log.seek(0, os.SEEK_END)
        log.write("\t".join(fields) + "\n")
        log.flush()
        os.fsync(log.fileno())
    print(job_id)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
