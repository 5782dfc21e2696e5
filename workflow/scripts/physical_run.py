"""Rule physical_run: a physical scene's path of forces (contactlib.physical_history) ->
results/datasets/<scene>.nc, results/tables/<scene>.csv and results/figures/<scene>.png/pdf."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import io  # noqa: E402
from contactlib.physical import physical_history  # noqa: E402
from contactlib.plot.base import style_path  # noqa: E402
from contactlib.plot.physical import physical_history_figure, physical_table  # noqa: E402

params = snakemake.params.run  # noqa: F821
scene = params["scene"]


def progress(i, n):
    if i == n or i % max(1, n // 10) == 0:
        print(f"{scene}: step {i}/{n}", flush=True)


res = physical_history(progress=progress, **params["run"])
print(res.summary(), flush=True)
io.write_dataset(io.set_provenance(io.physical_to_dataset(res), scene, params["hash"]),
                 snakemake.output.dataset)  # noqa: F821
io.write_table(physical_table(res), snakemake.output.table)  # noqa: F821
fig = physical_history_figure(res, title=scene)
io.write_figure(fig, snakemake.output.png, style=style_path())  # noqa: F821
io.write_figure(fig, snakemake.output.pdf, style=style_path())  # noqa: F821
