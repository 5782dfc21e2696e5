"""Viscoelastic bodies: dissipation per load cycle against the loading rate, and loops.

One figure, :func:`fig_viscoelastic`, for the ``viscoelastic`` target of the
workflow: histories of one load cycle 0 -> 1 -> 0 on a viscoelastic body
(datasets of :func:`contactlib.io.history_to_dataset`, stacked over k by
:func:`contactlib.io.stack_histories`), one a cycle duration T.

* Left: the energy dissipated in the cycle against T/tau (tau the first
  relaxation time), split into the body's viscous work (solid, one line:
  it hardly depends on k, its spread over k is in the legend) and the
  frictional work (dashed, one colour a friction coefficient).
* Right: the load against the indentation (P/P_max against delta R/a_max^2)
  at three durations, for one k: the loop's area is the dissipated energy.

Built on :mod:`contactlib.plot.base` only; nothing here touches the disk.

Examples
--------
>>> import contactlib
>>> from contactlib.io import history_to_dataset, stack_histories
>>> from contactlib.plot.viscoelastic import fig_viscoelastic
>>> runs = [stack_histories([history_to_dataset(contactlib.history(
...     "sphere", 0.3, k, [0, 1, 0], 4, n=40, relaxation=[[0.5, 1.0]], duration=t,
...     error_estimate=False)) for k in (0.1, 0.2)]) for t in (0.1, 1.0, 10.0)]
>>> fig = fig_viscoelastic(runs)
>>> len(fig.axes)
4
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import xarray as xr
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from contactlib.plot.base import as_list, finish, k_text, palette, panel_grid, style_context

__all__ = ["fig_viscoelastic", "cycle_dissipation"]

_WORK_LABEL = {
    "sphere": r"dissipated per cycle $W R^2/(E_0^* a_{max}^5)$",
    "cylinder": r"dissipated per cycle $W R^2/(E_0^* a_{max}^4)$ per unit length",
}


def _stacked(ds: xr.Dataset) -> xr.Dataset:
    return ds if "friction_coefficient" in ds.dims else ds.expand_dims(
        friction_coefficient=[float(ds.attrs["friction_coefficient"])])


def cycle_dissipation(ds: xr.Dataset) -> dict[str, np.ndarray | float]:
    """The cycle's duration over tau_1 and its viscous and frictional work, per k.

    Parameters
    ----------
    ds : xarray.Dataset
        A viscoelastic history (or a stack over k) of the cycle 0 -> 1 -> 0,
        with ``time``, ``viscous_work``, ``frictional_work``, ``external_work``
        and ``stored_energy`` and the ``relaxation_times`` attribute.

    Returns
    -------
    dict
        ``rate`` (T/tau_1), ``k``, ``viscous``, ``frictional``, ``external``
        and ``stored`` (each an array over k, at the end of the cycle), and
        ``converged`` (every step, per k).

    Raises
    ------
    ValueError
        If a variable or the attribute is missing (an elastic history).
    """
    for name in ("time", "viscous_work", "frictional_work", "external_work", "stored_energy"):
        if name not in ds.variables:
            raise ValueError(f"cycle_dissipation: variable {name!r} is absent (the history "
                             "must be of a viscoelastic body)")
    if "relaxation_times" not in ds.attrs:
        raise ValueError("cycle_dissipation: the history lacks the attribute 'relaxation_times'")
    ds = _stacked(ds)
    tau = float(np.atleast_1d(ds.attrs["relaxation_times"])[0])
    time = np.asarray(ds["time"].values, dtype=float)
    end = lambda name: np.asarray(ds[name].values, dtype=float)[:, -1]  # noqa: E731
    return {"rate": float(time.reshape(-1)[-1]) / tau,
            "k": np.asarray(ds["friction_coefficient"].values, dtype=float),
            "viscous": end("viscous_work"), "frictional": end("frictional_work"),
            "external": end("external_work"), "stored": end("stored_energy"),
            "converged": np.asarray(ds["converged"].values).astype(bool).all(axis=-1)}


def fig_viscoelastic(histories: xr.Dataset | Sequence[xr.Dataset],
                     loops: Sequence[int] | None = None, loop_k: int | None = None) -> Figure:
    """Dissipation per cycle against T/tau (viscous and frictional), and three loops.

    Parameters
    ----------
    histories : xarray.Dataset or sequence of xarray.Dataset
        One stack of viscoelastic histories (over k) a cycle duration, same
        body, path 0 -> 1 -> 0 and friction coefficients.
    loops : sequence of int, optional
        Indices (into the histories sorted by T) of the loops drawn on the
        right (default: the first, the middle and the last).
    loop_k : int, optional
        Index of the friction coefficient of the loops (default: the middle one).

    Returns
    -------
    matplotlib.figure.Figure
        The dissipation panel and the loops panel, a legend holder under each.

    Raises
    ------
    ValueError
        If a history is not viscoelastic (see :func:`cycle_dissipation`) or
        the histories differ in their friction coefficients.
    """
    items = [_stacked(ds) for ds in as_list(histories)]
    cycles = [cycle_dissipation(ds) for ds in items]
    order = np.argsort([c["rate"] for c in cycles])
    items, cycles = [items[i] for i in order], [cycles[i] for i in order]
    ks = cycles[0]["k"]
    for c in cycles[1:]:
        if not np.array_equal(c["k"], ks):
            raise ValueError(f"fig_viscoelastic: the histories differ in k: {ks.tolist()} vs "
                             f"{c['k'].tolist()}")
    rate = np.array([c["rate"] for c in cycles])
    viscous = np.array([c["viscous"] for c in cycles])  # (rates, k)
    frictional = np.array([c["frictional"] for c in cycles])
    ok = np.array([c["converged"] for c in cycles])
    loops = [0, len(items) // 2, len(items) - 1] if loops is None else list(loops)
    jk = ks.size // 2 if loop_k is None else int(loop_k)
    attrs = items[0].attrs
    geometry = str(attrs.get("geometry", "sphere"))
    g = np.atleast_1d(np.asarray(attrs.get("relaxation_weights", []), dtype=float))
    tau = np.atleast_1d(np.asarray(attrs.get("relaxation_times", []), dtype=float))
    body = ", ".join(f"g = {a:g}, τ = {b:g}" for a, b in zip(g, tau))
    with style_context():
        colors = palette()
        fig, axes, holders = panel_grid(2, (2.8,), max(ks.size + 3, len(loops)), width=7.0)
        ax_w, ax_l = axes[0, 0], axes[0, 1]
        handles: list[Line2D] = []
        # the viscous work hardly depends on k: one line (the loops' k), its spread in the label
        with np.errstate(invalid="ignore", divide="ignore"):
            spread = float(np.nanmax(np.abs(viscous / viscous[:, [jk]] - 1.0)))
        ax_w.plot(rate, viscous[:, jk], color="black", marker="o", ms=3, lw=1.2)
        for j, k in enumerate(ks):
            color = colors[j % len(colors)]
            fr = frictional[:, j]
            shown = fr > 0
            ax_w.plot(rate[shown], fr[shown], color=color, marker="s", ms=3, lw=1.0,
                      dashes=(4.0, 2.0), mfc="white")
            bad = ~ok[:, j]
            ax_w.plot(rate[bad], viscous[bad, j], ls="none", marker="x", color="black", ms=5)
            handles.append(Line2D([], [], color=color, marker="s", ms=3, lw=1.0,
                                  dashes=(4.0, 2.0), mfc="white", label=f"k = {k_text(k)}"))
        handles += [Line2D([], [], color="black", marker="o", ms=3, lw=1.2,
                           label=f"viscous work of the body, k = {k_text(ks[jk])} (other k: "
                                 f"within {spread:.1%})"),
                    Line2D([], [], color="0.3", marker="s", ms=3, lw=1.0, dashes=(4.0, 2.0),
                           mfc="white", label="frictional work (colour: k)")]
        if not ok.all():
            handles.append(Line2D([], [], ls="none", marker="x", color="black", ms=5,
                                  label="a step did not converge"))
        ax_w.set_xscale("log")
        ax_w.set_yscale("log")
        ax_w.set_xlabel(r"cycle duration over relaxation time $T/\tau$")
        ax_w.set_ylabel(_WORK_LABEL.get(geometry, "dissipated per cycle"))
        i_max = int(np.argmax(viscous[:, jk]))
        ax_w.set_title(f"{geometry}, {body}: one cycle 0 → P_max → 0\n"
                       f"viscous peak {viscous[i_max, jk]:.3g} at T/τ = {rate[i_max]:g}; "
                       f"frictional {frictional[:, jk].min():.2g} … "
                       f"{frictional[:, jk].max():.2g} (k = {k_text(ks[jk])})", fontsize=7)
        loop_handles: list[Line2D] = []
        for m, i in enumerate(loops):
            ds = items[i].isel(friction_coefficient=jk)
            color = colors[(m + 3) % len(colors)]
            ax_l.plot(np.asarray(ds["indentation"].values), np.asarray(ds["load_ratio"].values),
                      color=color, lw=1.2)
            loop_handles.append(Line2D([], [], color=color, lw=1.2,
                                       label=f"T/τ = {rate[i]:g}: dissipated "
                                             f"{viscous[i, jk] + frictional[i, jk]:.3g}"))
        ax_l.set_xlabel(r"indentation $\delta R / a_{max}^2$")
        ax_l.set_ylabel(r"load $P / P_{max}$")
        ax_l.set_xlim(left=0.0)
        ax_l.set_ylim(0.0, 1.05)
        ax_l.set_title(f"load–indentation loops, k = {k_text(ks[jk])}\n"
                       "(E* = E*(0): a_max, P_max at the instantaneous modulus)", fontsize=7)
        holders[0].legend(handles=handles, loc="upper left", frameon=False)
        holders[1].legend(handles=loop_handles, loc="upper left", frameon=False)
        return finish(fig)
