"""Rule figure: one figure from the scenes' datasets (PNG and PDF)."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import figures, history_figures, io  # noqa: E402

name = snakemake.params.fig  # noqa: F821
datasets = [io.read_dataset(path) for path in snakemake.input]  # noqa: F821
if name == "history_stick_map":  # the map of one history scene
    fig = history_figures.hist_stick_map(datasets[0])
else:
    draw = {
        "fig2": figures.fig2_friction,
        "fig3": figures.fig3_tractions,
        "fig4": figures.fig4_displacement,
        "fig5": figures.fig5_work,
        "history_stick_radius": history_figures.hist_stick_radius,
        "history_loop": history_figures.hist_displacement_loop,
        "history_energy": history_figures.hist_energy_per_cycle,
    }[name]
    fig = draw(datasets)
io.write_figure(fig, snakemake.output.png)  # noqa: F821
io.write_figure(fig, snakemake.output.pdf)  # noqa: F821
