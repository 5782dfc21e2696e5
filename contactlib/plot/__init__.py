"""Figures of contactlib: a shared base with paper, history and convergence figures on top.

* :mod:`contactlib.plot.base`: the style file, colours, markers, panel grids,
  the frozen layout and small label helpers every figure uses;
* :mod:`contactlib.plot.paper`: the paper's figures 2-5 (self-similar datasets
  of :func:`contactlib.io.to_dataset`);
* :mod:`contactlib.plot.history`: loading-history figures (datasets of
  :func:`contactlib.io.history_to_dataset` and :func:`contactlib.io.stack_histories`);
* :mod:`contactlib.plot.convergence`: error against time
  (:func:`contactlib.io.study_to_dataset`);
* :mod:`contactlib.plot.materials`: named material pairs (elastic indenters),
  k against c/a and the frictional work per load cycle;
* :mod:`contactlib.plot.viscoelastic`: viscoelastic bodies, the dissipation
  per cycle against the loading rate and load-indentation loops.
* :mod:`contactlib.plot.layers`: the frictionless load and k against a/h on
  layers (smooth and bonded bases).
* :mod:`contactlib.plot.coatings`: the same against a/h on coatings bonded to
  elastic substrates (a :class:`contactlib.coating_study.CoatingStudy`).
* :mod:`contactlib.plot.stresses`: von Mises and Tresca maps inside the body
  (datasets of :func:`contactlib.stresses.subsurface_stresses`).

Figures take datasets and return a :class:`matplotlib.figure.Figure`; nothing
here touches the disk or imports the numerics' solvers. Save with
``contactlib.io.write_figure(fig, path, style=style_path())``.

Examples
--------
>>> import contactlib
>>> from contactlib import io, plot
>>> ds = io.to_dataset(contactlib.sweep("sphere", 0.3, [0, 0.5], n=32))
>>> fig = plot.fig2_friction(ds)
>>> plot.style_path().name
'contactlib.mplstyle'
"""

from contactlib.plot.base import style_path
from contactlib.plot.coatings import fig_coatings
from contactlib.plot.convergence import fig_convergence
from contactlib.plot.history import (
    hist_displacement_loop,
    hist_energy_per_cycle,
    hist_stick_map,
    hist_stick_radius,
)
from contactlib.plot.fretting import fig_fretting
from contactlib.plot.layers import fig_layers
from contactlib.plot.materials import fig_material_pairs
from contactlib.plot.paper import fig2_friction, fig3_tractions, fig4_displacement, fig5_work
from contactlib.plot.stresses import (fig_stress_maxima, fig_subsurface,
                                      fig_surface_radial_stress, fig_tangential_stresses)
from contactlib.plot.viscoelastic import fig_viscoelastic

__all__ = [
    "style_path",
    "fig2_friction",
    "fig3_tractions",
    "fig4_displacement",
    "fig5_work",
    "fig_convergence",
    "hist_stick_radius",
    "hist_stick_map",
    "hist_displacement_loop",
    "hist_energy_per_cycle",
    "fig_material_pairs",
    "fig_viscoelastic",
    "fig_layers",
    "fig_coatings",
    "fig_fretting",
    "fig_subsurface",
    "fig_stress_maxima",
    "fig_surface_radial_stress",
    "fig_tangential_stresses",
]
