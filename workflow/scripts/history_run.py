"""Rule history_run: a history scene's load path, one run a friction coefficient (in
parallel worker processes, threads), stacked along k -> results/datasets/<scene>.nc."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import history, io  # noqa: E402
from contactlib.threads import map_cases  # noqa: E402

params = snakemake.params.run  # noqa: F821
scene, config_hash = params["scene"], params["hash"]


def run(index: int):
    spec = dict(params["runs"][index])
    k = spec["friction"]

    def progress(i, n):
        if i == n or i % max(1, n // 10) == 0:
            print(f"{scene} k = {k:g}: step {i}/{n}", flush=True)

    res = history(progress=progress, **spec)
    if res.message:
        print(f"{scene} k = {k:g}: {res.message}", flush=True)
    return io.set_provenance(io.history_to_dataset(res), scene, config_hash)


ds = io.stack_histories(map_cases(run, range(len(params["runs"])), snakemake.threads))  # noqa: F821
io.set_provenance(ds, scene, config_hash)
io.write_dataset(ds, snakemake.output[0])  # noqa: F821
print(f"{scene}: {ds.sizes['friction_coefficient']} histories written", flush=True)
