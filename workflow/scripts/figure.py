"""Rule figures_<family>: the family's figures (PNG and PDF) from the scenes' datasets.

One job draws every figure of its family; the figures run in parallel worker
processes (threads), forked after the imports, each one whole in one process.
"""

import sys
from pathlib import Path

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import io  # noqa: E402
from contactlib.threads import map_cases  # noqa: E402

figures = snakemake.params.figures  # noqa: F821  {figure: [scene, ...]}
DRAW = {}
if any(not name.startswith("history_") for name in figures):
    from contactlib.plot import paper

    DRAW.update(fig2=paper.fig2_friction, fig3=paper.fig3_tractions,
                fig4=paper.fig4_displacement, fig5=paper.fig5_work)
if any(name.startswith("history_") for name in figures):
    from contactlib.plot import history as hist

    DRAW.update(history_stick_radius=hist.hist_stick_radius,
                history_stick_map=lambda datasets: hist.hist_stick_map(datasets[0]),
                history_loop=hist.hist_displacement_loop,
                history_energy=hist.hist_energy_per_cycle)
from contactlib.plot.base import style_path  # noqa: E402

STYLE = style_path()
# the datasets, read once before the workers fork: <scene>.nc -> scene
datasets = {Path(path).stem: io.read_dataset(path) for path in snakemake.input}  # noqa: F821


def draw(name: str) -> None:
    fig = DRAW[name]([datasets[scene] for scene in figures[name]])
    io.write_figure(fig, snakemake.output[f"{name}_png"], style=STYLE)  # noqa: F821
    io.write_figure(fig, snakemake.output[f"{name}_pdf"], style=STYLE)  # noqa: F821
    print(f"{name}: drawn from {', '.join(figures[name])}", flush=True)


# the slowest first (CPU seconds, measured), so that the workers end together
COST = {"fig3": 2.1, "fig5": 1.6, "history_energy": 1.5, "fig2": 1.2, "history_loop": 1.2,
        "history_stick_radius": 0.9, "history_stick_map": 0.9, "fig4": 0.8}
map_cases(draw, sorted(figures, key=lambda name: -COST.get(name, 1.0)),
          snakemake.threads)  # noqa: F821
