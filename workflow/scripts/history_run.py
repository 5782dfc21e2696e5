"""Rule history_run: a history scene's load path, one run a friction coefficient
-> results/history/<scene>/k<i>.nc, the runs in parallel worker processes (threads)."""

import sys
from pathlib import Path

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import history, io  # noqa: E402
from contactlib.threads import map_cases  # noqa: E402

params = snakemake.params.run  # noqa: F821
scene, config_hash = params["scene"], params["hash"]
folder = Path(snakemake.output[0])  # noqa: F821
folder.mkdir(parents=True, exist_ok=True)


def run(index: int) -> None:
    spec = dict(params["runs"][index])
    k = spec["friction"]

    def progress(i, n):
        if i == n or i % max(1, n // 10) == 0:
            print(f"{scene} k = {k:g}: step {i}/{n}", flush=True)

    res = history(progress=progress, **spec)
    ds = io.set_provenance(io.history_to_dataset(res), scene, config_hash)
    if res.message:
        print(f"{scene} k = {k:g}: {res.message}", flush=True)
    io.write_dataset(ds, folder / f"k{index}.nc")


map_cases(run, range(len(params["runs"])), snakemake.threads)  # noqa: F821
