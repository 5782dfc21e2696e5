"""Layers: the frictionless load, k and the work per cycle against a/h, both bases.

One figure, :func:`fig_layers`, for the ``layers`` target of the workflow,
from a dataset of :func:`contactlib.io.layer_study_to_dataset`: one row per
geometry (sphere, cylinder); left the frictionless load over Hertz's at the
same contact radius, middle the friction coefficient k at one stick ratio,
both against a/h; right, where the study has its load cycles, the
frictional work of a load cycle 0 -> 1 -> 0 against a_max/h (log scale,
bars: the work's error estimate; a cross: not resolved to 1e-2).
Colour: Poisson's ratio; solid: smooth base, dashed: bonded base. A k that
is not resolved (not converged, inconsistent: the slip changes direction
where the layer's outward squeeze balances the half-space's inward pull,
or above the error bound) has no line and a cross at k = 0.

Built on :mod:`contactlib.plot.base` only; nothing here touches the disk.

Examples
--------
>>> from contactlib.io import layer_study_to_dataset
>>> from contactlib.layer_study import layer_study
>>> from contactlib.plot.layers import fig_layers
>>> st = layer_study(geometries=("sphere",), bases=("smooth",), nus=(0.3,),
...                  ratios=(0.0, 1.0), stick_ratios=(0.5,), n=32, history_n=32,
...                  history_steps=8)
>>> len(fig_layers(layer_study_to_dataset(st)).axes)
6
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from contactlib.plot.base import MARKERS, finish, fmt, palette, panel_grid, style_context

__all__ = ["fig_layers"]

_DASHES = {"smooth": None, "bonded": (4.0, 2.0)}


def fig_layers(ds: xr.Dataset, stick_ratio: float = 0.5) -> Figure:
    """Frictionless load ratio and k(c/a = ``stick_ratio``) against a/h.

    Parameters
    ----------
    ds : xarray.Dataset
        From :func:`contactlib.io.layer_study_to_dataset`.
    stick_ratio : float
        The c/a of the right-hand panels (the nearest in the dataset).

    Returns
    -------
    matplotlib.figure.Figure
        Two plot panels a geometry (three with the load cycles) and one
        axis-free legend holder a column.

    Raises
    ------
    ValueError
        If a variable of the layer study is missing.
    """
    for name in ("load_ratio", "friction_coefficient", "resolved"):
        if name not in ds.variables:
            raise ValueError(f"fig_layers: variable {name!r} is absent (not a layer study)")
    cs = np.asarray(ds["stick_ratio"].values, dtype=float)
    ic = int(np.argmin(np.abs(cs - stick_ratio)))
    ratios = np.asarray(ds["slab_ratio"].values, dtype=float)
    geometries = [str(g) for g in ds["geometry"].values]
    bases = [str(b) for b in ds["base"].values]
    nus = np.asarray(ds["poisson_ratio"].values, dtype=float)
    cycles = "cycle_work" in ds.variables
    ncol = 3 if cycles else 2
    with style_context():
        colors = palette()
        fig, axes, holders = panel_grid(ncol, (2.2,) * len(geometries),
                                        -(-(len(bases) * nus.size + 1) // 2),
                                        width=3.4 * ncol + 0.2)
        handles: list[Line2D] = []
        for g, geometry in enumerate(geometries):
            ax_p, ax_k = axes[g, 0], axes[g, 1]
            for b, base in enumerate(bases):
                for v, nu in enumerate(nus):
                    color = colors[v % len(colors)]
                    style: dict[str, object] = {"color": color, "lw": 1.2, "ms": 3.5,
                                                "marker": MARKERS[v % len(MARKERS)],
                                                "mfc": color if b == 0 else "white"}
                    if _DASHES.get(base) is not None:
                        style["dashes"] = _DASHES[base]
                    load = ds["load_ratio"].values[g, b, v]
                    k = ds["friction_coefficient"].values[g, b, v, :, ic]
                    ok = ds["resolved"].values[g, b, v, :, ic].astype(bool)
                    (line,) = ax_p.plot(ratios, load, **style)  # type: ignore[arg-type]
                    # a line through the resolved cases only; the others have no
                    # self-similar k (Newton's root there is not a solution): crossed at 0
                    ax_k.plot(ratios, np.where(ok, k, np.nan), **style)  # type: ignore[arg-type]
                    ax_k.plot(ratios[~ok], np.zeros(int((~ok).sum())), ls="none", marker="x",
                              color=color, ms=5)
                    if cycles:
                        _cycle_work(axes[g, 2], ds, (g, b, v), ratios, style)
                    if g == 0:
                        line.set_label(f"{base} base, ν = {fmt(nu)}")
                        handles.append(line)
            ax_p.set_ylabel(f"{geometry}: $P/P_{{Hertz}}$ (frictionless)")
            ax_k.set_ylabel(f"{geometry}: k at c/a = {fmt(cs[ic])}")
            ax_k.axhline(0.0, color="0.6", lw=0.6, zorder=0)
            if cycles:
                axes[g, 2].set_yscale("log")
                axes[g, 2].set_ylabel(f"{geometry}: work per cycle, "
                                      f"k = {fmt(float(ds.attrs['history_friction']))}")
        for ax in axes[-1, :2]:
            ax.set_xlabel("a/h")
        if cycles:
            axes[-1, 2].set_xlabel("$a_{max}/h$ (history 0 → 1 → 0)")
        handles.append(Line2D([], [], ls="none", marker="x", color="black", ms=5,
                              label="no self-similar k (slip reverses; drawn at 0)"))
        half = -(-len(handles) // 2)
        parts = [handles[:half], handles[half:]]
        if cycles:
            parts.append([Line2D([], [], ls="none", marker="x", color="black", ms=6,
                                 label="over a point: work not resolved to 1e-2\n"
                                       "(bars: its error estimate)")])
        for holder, part in zip(holders, parts):
            if part:
                holder.legend(handles=part, loc="upper left", frameon=False)
        return finish(fig)


def _cycle_work(ax, ds: xr.Dataset, index: tuple[int, int, int], ratios: np.ndarray,
                style: dict[str, object]) -> None:
    """Work per load cycle against a_max/h with its estimated error (bars, cut at 95 %
    below on the log axis); a cross over the points not resolved to 1e-2."""
    work = ds["cycle_work"].values[index]
    err = np.abs(work) * ds["cycle_work_error_estimate"].values[index]
    ok = ds["cycle_work_resolved"].values[index].astype(bool)
    ax.plot(ratios, work, **style)  # type: ignore[arg-type]
    ax.errorbar(ratios, work, yerr=(np.minimum(err, 0.95 * np.abs(work)), err), ls="none",
                color=style["color"], lw=0.8, capsize=2)
    ax.plot(ratios[~ok], work[~ok], ls="none", marker="x", color=style["color"], ms=6)
