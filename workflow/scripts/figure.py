"""Rule figure: one of the paper's figures from the scenes' datasets (PNG and PDF)."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import figures, io  # noqa: E402

draw = {
    "fig2": figures.fig2_friction,
    "fig3": figures.fig3_tractions,
    "fig4": figures.fig4_displacement,
    "fig5": figures.fig5_work,
}[snakemake.params.fig]  # noqa: F821
fig = draw([io.read_dataset(path) for path in snakemake.input])  # noqa: F821
io.write_figure(fig, snakemake.output.png)  # noqa: F821
io.write_figure(fig, snakemake.output.pdf)  # noqa: F821
