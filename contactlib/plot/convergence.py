"""Convergence figure: error against wall time (the speed-accuracy trade) of studies.

Drawn from the datasets of :func:`contactlib.io.study_to_dataset`, on the
shared base :mod:`contactlib.plot.base`; save with
``contactlib.io.write_figure(fig, path, style=style_path())``.

Examples
--------
>>> from contactlib import convergence, io
>>> st = convergence.study("sphere", 0.3, "default", [16, 32, 64], [0.5])
>>> fig = fig_convergence(io.study_to_dataset(st))
>>> [ax.get_title() for ax in fig.axes]
['error against time (labels: n)', 'order of convergence']
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from contactlib.plot.base import MARKERS, as_list, finish, palette, style_context

__all__ = ["fig_convergence"]


def fig_convergence(datasets: xr.Dataset | Sequence[xr.Dataset],
                    quantity: str = "friction_coefficient") -> Figure:
    """Error against wall time (the speed-accuracy trade), one curve a study.

    Parameters
    ----------
    datasets : Dataset or sequence of Dataset
        From :func:`contactlib.io.study_to_dataset` of
        :func:`contactlib.convergence.study` (one geometry and method each).
    quantity : str
        Which error to draw (``friction_coefficient``, ``load_ratio``,
        ``frictional_work`` or ``peak_shear``).

    Returns
    -------
    matplotlib.figure.Figure
        Left: median relative error over the stick ratios against the median
        wall time of one solve, each point one n (labelled); log-log. Right:
        the observed order of convergence of each study per stick ratio.
    """
    items = as_list(datasets)
    for i, ds in enumerate(items):
        for name in ("error", "wall_time", "observed_order"):
            if name not in ds:
                raise ValueError(f"convergence dataset {i} has no variable {name!r}")
    with style_context():
        fig = Figure(figsize=(9.0, 3.8))
        ax, ax2 = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1.6, 1.0]})
        for i, ds in enumerate(items):
            label = f"{ds.attrs['geometry']}, {ds.attrs['method']}"
            err = ds["error"].sel(quantity=quantity).median("stick_ratio").values
            t = ds["wall_time"].median("stick_ratio").values
            ok = np.isfinite(err) & (err > 0)
            color = palette()[i % len(palette())]
            ax.loglog(t[ok], err[ok], marker=MARKERS[i % len(MARKERS)], color=color,
                      label=label)
            for n, x, y in zip(ds["n"].values[ok], t[ok], err[ok]):
                ax.annotate(f"{n}", (x, y), textcoords="offset points", xytext=(3, 3),
                            fontsize=7, color=color)
            order = ds["observed_order"].sel(quantity=quantity)
            ax2.plot(ds["stick_ratio"].values, order.values, marker=MARKERS[i % len(MARKERS)],
                     color=color, label=label)
        ax.set_xlabel("wall time of one solve (s)")
        ax.set_ylabel(f"relative error in {quantity.replace('_', ' ')}")
        ax.set_title("error against time (labels: n)")
        ax.legend(fontsize=8)
        ax2.set_xlabel("stick ratio c/a")
        ax2.set_ylabel("observed order")
        ax2.set_title("order of convergence")
        return finish(fig)
