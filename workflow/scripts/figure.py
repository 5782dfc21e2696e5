"""Rule figure: one figure from the scenes' datasets (PNG and PDF)."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import io, plot  # noqa: E402

name = snakemake.params.fig  # noqa: F821
datasets = [io.read_dataset(path) for path in snakemake.input]  # noqa: F821
if name == "history_stick_map":  # the map of one history scene
    fig = plot.hist_stick_map(datasets[0])
else:
    draw = {
        "fig2": plot.fig2_friction,
        "fig3": plot.fig3_tractions,
        "fig4": plot.fig4_displacement,
        "fig5": plot.fig5_work,
        "history_stick_radius": plot.hist_stick_radius,
        "history_loop": plot.hist_displacement_loop,
        "history_energy": plot.hist_energy_per_cycle,
    }[name]
    fig = draw(datasets)
io.write_figure(fig, snakemake.output.png, style=plot.style_path())  # noqa: F821
io.write_figure(fig, snakemake.output.pdf, style=plot.style_path())  # noqa: F821
