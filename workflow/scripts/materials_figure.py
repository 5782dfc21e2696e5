"""Rule materials_figure: k against c/a and the work per load cycle of the material pairs."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import io, plot  # noqa: E402

inputs = snakemake.input  # noqa: F821
fig = plot.fig_material_pairs([io.read_dataset(p) for p in inputs.self_similar],
                              [io.read_dataset(p) for p in inputs.cycles],
                              labels=snakemake.params.labels)  # noqa: F821
io.write_figure(fig, snakemake.output.png, style=plot.style_path())  # noqa: F821
io.write_figure(fig, snakemake.output.pdf, style=plot.style_path())  # noqa: F821
print(f"materials: drawn from {', '.join(snakemake.params.labels)}")  # noqa: F821
