"""Rule fretting_stick_map: the sphere's stick-zone map (PNG, PDF) and its radii per
direction with their estimates (CSV)."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import io, plot, summary  # noqa: E402
from contactlib.fretting_api import STICK_MAP_CASES  # noqa: E402
from contactlib.plot.fretting import fig_stick_zone_map  # noqa: E402

datasets = [io.read_dataset(snakemake.input[name]) for name in STICK_MAP_CASES]  # noqa: F821
fig = fig_stick_zone_map(datasets, titles=[title for title, _ in STICK_MAP_CASES.values()])
io.write_figure(fig, snakemake.output.png, style=plot.style_path())  # noqa: F821
io.write_figure(fig, snakemake.output.pdf, style=plot.style_path())  # noqa: F821
io.write_table(summary.stick_direction_rows(datasets, list(STICK_MAP_CASES)),
               snakemake.output.csv)  # noqa: F821
