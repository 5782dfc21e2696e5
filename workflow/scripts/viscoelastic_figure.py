"""Rule viscoelastic_figure: dissipation per cycle against T/tau, and three loops."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import io, plot  # noqa: E402

fig = plot.fig_viscoelastic([io.read_dataset(p) for p in snakemake.input])  # noqa: F821
io.write_figure(fig, snakemake.output.png, style=plot.style_path())  # noqa: F821
io.write_figure(fig, snakemake.output.pdf, style=plot.style_path())  # noqa: F821
print(f"viscoelastic: drawn from {len(snakemake.input)} cycle durations")  # noqa: F821
