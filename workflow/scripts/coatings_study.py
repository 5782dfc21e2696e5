"""Rule coatings_study: the coatings figure (PNG, PDF) and table (CSV, with estimates)."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import coating_study, io, plot  # noqa: E402

out = snakemake.output  # noqa: F821
study = coating_study.coating_study()
fig = plot.fig_coatings(study)
io.write_figure(fig, out.png, style=plot.style_path())
io.write_figure(fig, out.pdf, style=plot.style_path())
io.write_table(coating_study.coating_rows(study), out.csv)
print(f"coatings: {study.friction.size} k, {study.cycle_work.size} cycles at n = {study.n}")
