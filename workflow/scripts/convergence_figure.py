"""Rule convergence_figure: error against time, every study (PNG and PDF)."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import figures, io  # noqa: E402

fig = figures.fig_convergence([io.read_dataset(p) for p in snakemake.input])  # noqa: F821
io.write_figure(fig, snakemake.output.png)  # noqa: F821
io.write_figure(fig, snakemake.output.pdf)  # noqa: F821
