"""Rule history_run: one load path for one friction coefficient -> results/history/<scene>/k<i>.nc."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import history, io  # noqa: E402

spec = dict(snakemake.params.run)  # noqa: F821
scene, config_hash = spec.pop("scene"), spec.pop("hash")
total = spec["steps"] * (len(spec["load_path"]) - 1)


def progress(i, n):
    if i == n or i % max(1, n // 10) == 0:
        print(f"{scene} k = {spec['friction']:g}: step {i}/{n}", flush=True)


res = history(progress=progress, **spec)
ds = io.set_provenance(io.history_to_dataset(res), scene, config_hash)
if res.message:
    print(f"{scene} k = {spec['friction']:g}: {res.message}", flush=True)
io.write_dataset(ds, snakemake.output[0])  # noqa: F821
