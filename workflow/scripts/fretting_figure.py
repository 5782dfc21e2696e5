"""Rule fretting_figure: the fretting figure (PNG, PDF) and table (CSV)."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import io, plot, summary  # noqa: E402

ds = io.read_dataset(snakemake.input[0])  # noqa: F821
fig = plot.fig_fretting(ds)
io.write_figure(fig, snakemake.output.png, style=plot.style_path())  # noqa: F821
io.write_figure(fig, snakemake.output.pdf, style=plot.style_path())  # noqa: F821
io.write_table(summary.fretting_rows(ds), snakemake.output.csv)  # noqa: F821
