"""Rule fretting_run: a fretting scene's path (contactlib.fretting) ->
results/datasets/<scene>.nc, results/tables/<scene>.csv and results/figures/<scene>.png/pdf."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import fretting, io, summary  # noqa: E402
from contactlib.plot.base import style_path  # noqa: E402
from contactlib.plot.fretting import fig_fretting_path  # noqa: E402

params = snakemake.params.run  # noqa: F821
scene = params["scene"]
res = fretting(**params["run"])  # (seconds: no progress lines)
ds = io.set_provenance(io.fretting_to_dataset(res), scene, params["hash"])
io.write_dataset(ds, snakemake.output.dataset)  # noqa: F821
io.write_table(summary.fretting_path_rows(ds), snakemake.output.table)  # noqa: F821
fig = fig_fretting_path(ds, title=scene)
io.write_figure(fig, snakemake.output.png, style=style_path())  # noqa: F821
io.write_figure(fig, snakemake.output.pdf, style=style_path())  # noqa: F821
print(f"{scene}: c/a at the last point {float(res.stick_ratio[-1]):.6g} "
      f"(estimate {float(res.stick_ratio_error[-1]):.2g}); all resolved: {res.all_resolved}",
      flush=True)
