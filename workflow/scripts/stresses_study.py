"""Rule stresses_study: the stress fields (netCDF), four figures and the maxima table."""

import sys
from pathlib import Path

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import io, plot, stress_study  # noqa: E402

out = snakemake.output  # noqa: F821
groups = stress_study.study()
folder = Path(out.fields)
folder.mkdir(parents=True, exist_ok=True)
for group, items in groups.items():
    for i, ds in enumerate(items):
        io.write_dataset(ds, folder / f"{group.replace('_', '-')}-{i}.nc")
figures = {"maps": plot.fig_subsurface(groups["partial_slip"][::2]),
           "maxima": plot.fig_stress_maxima(groups["partial_slip"]),
           "edge": plot.fig_surface_radial_stress(groups["edge"]),
           "tangential": plot.fig_tangential_stresses(groups["tangential"])}
for name, fig in figures.items():
    io.write_figure(fig, out[name], style=plot.style_path())
io.write_table(stress_study.maxima_rows(groups["partial_slip"], groups["tangential"]), out.csv)
print(f"stresses: {sum(len(v) for v in groups.values())} fields")
