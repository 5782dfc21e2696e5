"""Named material pairs (elastic indenters): k against c/a and the work per load cycle.

One figure, :func:`fig_material_pairs`, for the ``materials`` target of the
workflow: for each pair of an indenter material pressed into a body material
(``contactlib/data/materials.yaml``), the self-similar friction coefficient k against
the stick ratio c/a (a dataset of :func:`contactlib.io.to_dataset`) and the
frictional work of one load cycle 0 -> 1 -> 0 against k (a stack of
histories, :func:`contactlib.io.stack_histories`). Every label carries the
pair's Dundurs parameter beta (the ``dundurs_beta`` attribute): on a
half-space k(c/a) and the work depend on |beta| only, so mirror pairs (steel
on aluminium, aluminium on steel) coincide, while the sign of beta gives the
direction of slip (beta > 0: inward, q = k p; beta < 0: outward, q = -k p).

Built on :mod:`contactlib.plot.base` only; nothing here touches the disk.

Examples
--------
>>> import contactlib
>>> from contactlib.io import history_to_dataset, stack_histories, to_dataset
>>> from contactlib.plot.materials import fig_material_pairs
>>> kw = dict(indenter_modulus=3.0, indenter_nu=0.3)
>>> ss = to_dataset(contactlib.sweep("sphere", 0.33, [0.0, 0.5], n=16, **kw))
>>> hs = stack_histories([history_to_dataset(contactlib.history(
...     "sphere", 0.33, k, [0, 1, 0], 4, n=40, **kw)) for k in (0.05, 0.1)])
>>> fig = fig_material_pairs([ss], [hs], labels=["steel on aluminium"])
>>> len(fig.axes)
4
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import xarray as xr
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.ticker import FixedLocator, FuncFormatter, NullLocator

from contactlib.plot.base import MARKERS, as_list, finish, label_of, palette, panel_grid, \
    style_context

__all__ = ["fig_material_pairs", "cycle_work", "pair_label"]

_DASHES = (None, (4.0, 2.0), (1.5, 1.5), (6.0, 2.0, 1.5, 2.0))
_WORK_LABEL = {
    "sphere": r"work per cycle $V R^2/(E^* a_{max}^5)$",
    "cylinder": r"work per cycle $V R^2/(E^* a_{max}^4)$ per unit length",
}


def pair_label(ds: xr.Dataset, name: str) -> str:
    """``name`` and the dataset's Dundurs parameter: ``"steel on aluminium (β = +0.117)"``.

    Raises
    ------
    ValueError
        If the dataset lacks the ``dundurs_beta`` attribute.
    """
    if "dundurs_beta" not in ds.attrs:
        raise ValueError(f"fig_material_pairs: {name!r} lacks the attribute 'dundurs_beta'")
    beta = float(ds.attrs["dundurs_beta"])
    return f"{name} (β = {beta:+.3f})" if beta != 0.0 else f"{name} (β = 0)"


def cycle_work(ds: xr.Dataset) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Friction coefficients, frictional work of the last load cycle, and whether it converged.

    The last cycle is the last two path segments, a loading and an unloading
    one (for the path 0 -> 1 -> 0 the whole path): the cumulative
    ``frictional_work`` at the last step minus its value at the start of the
    second-to-last segment.

    Parameters
    ----------
    ds : xarray.Dataset
        A history or a stack of histories (``friction_coefficient`` dimension)
        with ``frictional_work``, ``segment`` and ``converged`` and the
        ``load_path`` attribute.

    Returns
    -------
    tuple of ndarray
        ``(k, work, converged)``, one entry a friction coefficient.

    Raises
    ------
    ValueError
        If a variable or the ``load_path`` attribute is missing, or the path
        does not end in a loading and an unloading segment.
    """
    for name in ("frictional_work", "segment", "converged"):
        if name not in ds.variables:
            raise ValueError(f"cycle_work: variable {name!r} is absent from the history")
    if "load_path" not in ds.attrs:
        raise ValueError("cycle_work: the history lacks the attribute 'load_path'")
    path = np.atleast_1d(np.asarray(ds.attrs["load_path"], dtype=float))
    if path.size < 3 or not (path[-2] > path[-3] and path[-1] < path[-2]):
        raise ValueError(f"cycle_work: the load path {path.tolist()} does not end in one "
                         "loading and one unloading segment")
    if "friction_coefficient" not in ds.dims:
        k = np.atleast_1d(float(ds.attrs.get("friction_coefficient", math.nan)))
        ds = ds.expand_dims("friction_coefficient")
    else:
        k = np.asarray(ds["friction_coefficient"].values, dtype=float)
    segment = np.asarray(ds["segment"].values)
    segment = segment[0] if segment.ndim == 2 else segment
    start = int(np.flatnonzero(segment == path.size - 2)[0]) - 1  # the step before the segment
    work = np.asarray(ds["frictional_work"].values, dtype=float)
    cycle = work[:, -1] - work[:, start]
    ok = np.asarray(ds["converged"].values).astype(bool)[:, start:].all(axis=1)
    return k, cycle, ok


def fig_material_pairs(self_similar: xr.Dataset | Sequence[xr.Dataset],
                       cycles: xr.Dataset | Sequence[xr.Dataset],
                       labels: Sequence[str] | None = None) -> Figure:
    """k against c/a, and the frictional work per load cycle, for named material pairs.

    Left: the friction coefficient k of the self-similar loading against the
    stick ratio c/a, one line a pair (c/a = 1, k = inf, is left out; a case
    that did not converge, or whose ``resolved`` flag is false, is crossed).
    Right: the frictional work of the last load cycle of each pair's histories (:func:`cycle_work`) against k,
    log-log, crossed where a step of the cycle did not converge (the
    histories' ``resolved`` flags are not drawn); a pair without positive
    work (beta = 0: no shear) is named in a note instead.

    Parameters
    ----------
    self_similar : xarray.Dataset or sequence of xarray.Dataset
        One self-similar sweep a pair, with ``friction_coefficient`` and the
        ``dundurs_beta`` attribute.
    cycles : xarray.Dataset or sequence of xarray.Dataset
        One history (or stack of histories over k) a pair, in the same order,
        on a path ending in a loading and an unloading segment.
    labels : sequence of str, optional
        The pairs' names (e.g. ``"steel on aluminium"``); default: each
        self-similar dataset's ``scene`` attribute.

    Returns
    -------
    matplotlib.figure.Figure
        Two plot panels and two axis-free legend holders.

    Raises
    ------
    ValueError
        If the two sequences or ``labels`` differ in length, a dataset lacks
        ``friction_coefficient``, ``stick_ratio`` or ``dundurs_beta``, or a
        history's path is not a load cycle (see :func:`cycle_work`).
    """
    sims, hists = as_list(self_similar), as_list(cycles)
    if len(sims) != len(hists):
        raise ValueError(f"fig_material_pairs: {len(sims)} self-similar datasets but "
                         f"{len(hists)} histories; give one of each a pair")
    if labels is None:
        labels = [label_of(ds, i, f"pair {i}")[0] for i, ds in enumerate(sims)]
    labels = list(labels)
    if len(labels) != len(sims):
        raise ValueError(f"fig_material_pairs: {len(labels)} labels for {len(sims)} pairs")
    for i, ds in enumerate(sims):
        for name in ("friction_coefficient", "stick_ratio"):
            if name not in ds.variables:
                raise ValueError(f"fig_material_pairs: variable {name!r} is absent from "
                                 f"dataset {i} ({labels[i]!r})")
    names = [pair_label(ds, name) for ds, name in zip(sims, labels)]
    geometry = str(sims[0].attrs.get("geometry", "sphere"))
    with style_context():
        colors = palette()
        fig, axes, holders = panel_grid(2, (2.6,), -(-(len(sims) + 1) // 2), width=7.0)
        ax_k, ax_w = axes[0, 0], axes[0, 1]
        handles: list[Line2D] = []
        notes: list[str] = []
        any_failed = False
        for i, (ss, hs, name) in enumerate(zip(sims, hists, names)):
            color, marker = colors[i % len(colors)], MARKERS[i % len(MARKERS)]
            dashes = _DASHES[i % len(_DASHES)]
            style: dict[str, object] = {"color": color, "marker": marker, "ms": 3.5,
                                        "lw": 1.2, "mfc": color if i % 2 == 0 else "white"}
            if dashes is not None:
                style["dashes"] = dashes
            ss = ss.sortby("stick_ratio") if "stick_ratio" in ss.dims else ss
            c = np.atleast_1d(np.asarray(ss["stick_ratio"].values, dtype=float))
            k = np.atleast_1d(np.asarray(ss["friction_coefficient"].values, dtype=float))
            conv = np.ones(c.shape, bool)
            for flag in ("converged", "resolved"):  # not resolved: a failure, as in fig 2
                if flag in ss:
                    conv &= np.atleast_1d(np.asarray(ss[flag].values).astype(bool))
            shown = np.isfinite(k)
            ax_k.plot(c[shown], k[shown], **style)  # type: ignore[arg-type]
            bad = shown & ~conv
            any_failed |= bool(bad.any())
            ax_k.plot(c[bad], k[bad], ls="none", marker="x", color="black", ms=5)
            kc, work, ok = cycle_work(hs)
            positive = np.isfinite(work) & (work > 0) & np.isfinite(kc) & (kc > 0)
            if positive.any():
                ax_w.plot(kc[positive], work[positive], **style)  # type: ignore[arg-type]
                ax_w.plot(kc[positive & ~ok], work[positive & ~ok], ls="none", marker="x",
                          color="black", ms=5)
                any_failed |= bool((positive & ~ok).any())
            if not positive.all():
                notes.append(f"{name}: no positive work at "
                             f"{int(np.count_nonzero(~positive))} of {kc.size} k")
            handles.append(Line2D([], [], label=name, **style))  # type: ignore[arg-type]
        if any_failed:
            handles.append(Line2D([], [], ls="none", marker="x", color="black", ms=5,
                                  label="not converged or not resolved"))
        ax_k.set_xlim(0.0, 1.0)
        ax_k.set_ylim(bottom=0.0)
        ax_k.set_xlabel("stick ratio c/a")
        ax_k.set_ylabel("friction coefficient k")
        ax_k.set_title(f"{geometry}: self-similar loading\n"
                       "(|β| sets k; sign of β: slip direction)")
        ax_w.set_xscale("log")
        ax_w.set_yscale("log")
        ax_w.set_xlabel("friction coefficient k")
        ax_w.set_ylabel(_WORK_LABEL.get(geometry, "work per cycle"))
        path = " → ".join(f"{v:g}" for v in np.atleast_1d(hists[0].attrs.get("load_path", [])))
        ax_w.set_title(f"frictional work of the last load cycle\n(incremental history, P/P_max "
                       f"{path})")
        if notes:
            box = ax_w.text(0.02, 0.02, "\n".join(notes), transform=ax_w.transAxes,
                            ha="left", va="bottom", fontsize=5.6,
                            bbox={"boxstyle": "square,pad=0.3", "fc": "white", "ec": "0.8"})
            box.set_in_layout(False)
        ticks = sorted({float(v) for line in ax_w.get_lines() for v in line.get_xdata()})
        if ticks:  # a tick and label at every k drawn
            ax_w.xaxis.set_major_locator(FixedLocator(ticks))
            ax_w.xaxis.set_major_formatter(FuncFormatter(lambda v, _pos: f"{v:g}"))
            ax_w.xaxis.set_minor_locator(NullLocator())
            ax_w.set_xlim(ticks[0] / 1.3, ticks[-1] * 1.3)
        half = -(-len(handles) // 2)  # the pairs' legend split over the two columns
        for holder, part in zip(holders, (handles[:half], handles[half:])):
            if part:
                holder.legend(handles=part, loc="upper left", frameon=False)
        return finish(fig)
