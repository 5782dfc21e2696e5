"""Subsurface stresses: von Mises and Tresca maps, frictionless beside partial slip.

Three figures from datasets of
:func:`contactlib.stresses.subsurface_stresses` (or a solve's dataset with the field,
:func:`contactlib.stresses.with_subsurface`): one column a dataset (e.g. c/a = 0, 0.5,
0.9), the von Mises stress above and the maximum shear (Tresca) below, in units of p0
on one colour scale a row, depth downward, the field mirrored to negative x (both
measures are even in x). A white cross marks each map's maximum (grid maximum refined
by a parabola, :func:`contactlib.stresses.field_maximum`), the dashed line the contact
(|x| <= a on the surface). :func:`fig_stress_maxima` draws the largest von Mises and
Tresca stresses and their depth against c/a; :func:`fig_surface_radial_stress` the
surface radial stress near the contact edge (the cone-crack driver), one panel an
indenter (rigid or elastic, E1/E2) and body (the body or the elastic indenter).

Built on :mod:`contactlib.plot.base` only; nothing here touches the disk.

Examples
--------
>>> import numpy as np
>>> from contactlib import solve
>>> from contactlib.stresses import subsurface_stresses
>>> from contactlib.plot.stresses import fig_subsurface
>>> g = np.linspace(0.0, 1.5, 16)
>>> ds = [subsurface_stresses(solve("sphere", 0.3, stick_ratio=c, n=32), g, g)
...       for c in (0.0, 0.5)]
>>> len(fig_subsurface(ds).axes)
6
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import xarray as xr
from matplotlib.colors import Normalize
from matplotlib.figure import Figure

from contactlib.plot.base import (MARKERS, as_list, finish, fmt, k_text, palette, panel_grid,
                                  style_context)

__all__ = ["fig_subsurface", "fig_stress_maxima", "fig_surface_radial_stress",
           "fig_tangential_stresses"]

_ROWS = (("von_mises", "von Mises / $p_0$"), ("tresca", "max. shear (Tresca) / $p_0$"))


def _mirrored(ds: xr.Dataset, name: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """x, z and the field on -x ... x (an even field; x = 0 kept once)."""
    x = np.asarray(ds["x"].values, dtype=float)
    z = np.asarray(ds["z"].values, dtype=float)
    v = np.asarray(ds[name].values, dtype=float)
    if x[0] == 0.0 and np.all(x >= 0):
        x = np.concatenate([-x[:0:-1], x])
        v = np.concatenate([v[:, :0:-1], v], axis=1)
    return x, z, v


def _case(ds: xr.Dataset) -> tuple[float, float]:
    """(c/a, k) of a field: its attributes, or a solve dataset's variables."""
    c = float(ds.attrs.get("stick_ratio", np.nan))
    k = float(ds.attrs.get("friction_coefficient", np.nan))
    if "stick_ratio" in ds.variables:
        c = float(ds["stick_ratio"].values)
    if "friction_coefficient" in ds.variables:
        k = float(ds["friction_coefficient"].values)
    return c, k


def _peak(ds: xr.Dataset, name: str) -> tuple[float, float, float]:
    """(value, x, z) of the largest value on the grid, refined by a parabola per axis."""
    from contactlib.stresses import field_maximum  # numerics-free helper

    top = field_maximum(ds, name)
    return top["value"], top["x"], top["z"]


def fig_subsurface(datasets: xr.Dataset | Sequence[xr.Dataset]) -> Figure:
    """von Mises (top) and Tresca (bottom) maps, one column a dataset.

    Parameters
    ----------
    datasets : xarray.Dataset or sequence of them
        Fields of :func:`contactlib.stresses.subsurface_stresses` on grids x >= 0, z >= 0
        (units of a); their ``stick_ratio`` and ``friction_coefficient`` attributes (or
        variables) title the columns.

    Returns
    -------
    matplotlib.figure.Figure
        2 rows of maps and one colour bar a row.

    Raises
    ------
    ValueError
        If a dataset lacks ``von_mises`` or ``tresca``.
    """
    items = as_list(datasets)
    for i, ds in enumerate(items):
        for name, _ in _ROWS:
            if name not in ds.variables:
                raise ValueError(f"fig_subsurface: dataset {i} has no {name!r} "
                                 "(make it with contactlib.stresses.subsurface_stresses)")
    ncol = len(items)
    with style_context():
        fig = Figure(figsize=(0.6 + 2.6 * ncol, 4.6), layout="constrained")
        axes = fig.subplots(2, ncol, squeeze=False, sharex=True, sharey=True)
        for row, (name, label) in enumerate(_ROWS):
            top = max(float(np.nanmax(ds[name].values)) for ds in items)
            norm = Normalize(0.0, top)
            mesh = None
            for col, ds in enumerate(items):
                ax = axes[row, col]
                x, z, v = _mirrored(ds, name)
                mesh = ax.pcolormesh(x, z, v, norm=norm, cmap="viridis", shading="gouraud",
                                     rasterized=True)
                ax.contour(x, z, v, levels=np.linspace(0.1, 0.9, 9) * top, colors="white",
                           linewidths=0.4, alpha=0.6)
                value, px, pz = _peak(ds, name)
                for sx in ((px, -px) if px > 0 else (px,)):
                    ax.plot(sx, pz, marker="x", color="white", ms=6, mew=1.5)
                ax.plot([-1, 1], [0, 0], color="white", lw=2.0, ls=(0, (3, 2)))
                ax.text(0.03, 0.04, f"max {value:.3f} at z/a = {pz:.2f}",
                        transform=ax.transAxes, color="white", fontsize="small")
                ax.set_ylim(float(z.max()), float(z.min()))
                if row == 0:
                    c, k = _case(ds)
                    ax.set_title(f"c/a = {fmt(c)}, k = {k_text(k)}")
                if row == 1:
                    geometry = str(ds.attrs.get("geometry", "sphere"))
                    ax.set_xlabel("r/a" if geometry == "sphere" else "x/a")
                if col == 0:
                    ax.set_ylabel("depth z/a")
            fig.colorbar(mesh, ax=list(axes[row, :]), label=label, shrink=0.9)
        return finish(fig)


def fig_stress_maxima(datasets: xr.Dataset | Sequence[xr.Dataset]) -> Figure:
    """The largest von Mises and Tresca stresses (left) and their depth (right) against c/a.

    Parameters
    ----------
    datasets : xarray.Dataset or sequence of them
        Fields of :func:`contactlib.stresses.subsurface_stresses` of one geometry and
        body at several c/a (the ``stick_ratio`` attribute); the maxima are those of each
        grid, refined by a parabola (:func:`contactlib.stresses.field_maximum`).

    Returns
    -------
    matplotlib.figure.Figure
        Two panels and a legend row.
    """
    items = sorted(as_list(datasets), key=lambda d: _case(d)[0])
    cs = np.array([_case(d)[0] for d in items])
    with style_context():
        colors = palette()
        fig, axes, holders = panel_grid(2, (2.4,), 2)
        handles = []
        for i, (name, label) in enumerate(_ROWS):
            peaks = np.array([_peak(d, name) for d in items])
            style = {"color": colors[i], "marker": MARKERS[i], "ms": 4, "lw": 1.2}
            (line,) = axes[0, 0].plot(cs, peaks[:, 0], label=label.replace(" / $p_0$", ""),
                                      **style)
            axes[0, 1].plot(cs, peaks[:, 2], **style)
            handles.append(line)
        axes[0, 0].set_ylabel("largest value / $p_0$")
        axes[0, 1].set_ylabel("its depth z/a (0: surface)")
        for ax in axes[0]:
            ax.set_xlabel("stick ratio c/a")
        holders[0].legend(handles=handles, loc="upper left", frameon=False)
        return finish(fig)


def fig_surface_radial_stress(datasets: xr.Dataset | Sequence[xr.Dataset],
                              x_range: tuple[float, float] = (0.5, 2.5)) -> Figure:
    """Surface radial stress (sigma_rr, or sigma_xx for the cylinder) near the contact edge.

    Parameters
    ----------
    datasets : xarray.Dataset or sequence of them
        Fields of :func:`contactlib.stresses.subsurface_stresses` whose ``z`` holds 0; one
        panel a distinct (``indenter_modulus_ratio``, ``body``) pair, one line a c/a.
    x_range : tuple of float
        The r/a (x/a) shown.

    Returns
    -------
    matplotlib.figure.Figure
        One panel a pair, side by side, and a legend row.

    Raises
    ------
    ValueError
        If a dataset has no surface row (z = 0).
    """
    items = as_list(datasets)
    groups: dict[tuple[float, str], list[xr.Dataset]] = {}
    for i, ds in enumerate(items):
        if not np.any(np.asarray(ds["z"].values) == 0.0):
            raise ValueError(f"fig_surface_radial_stress: dataset {i} has no surface row "
                             "(z = 0)")
        key = (float(ds.attrs.get("indenter_modulus_ratio", np.inf)),
               str(ds.attrs.get("body", "body")))
        groups.setdefault(key, []).append(ds)
    with style_context():
        colors = palette()
        entries = max(len(g) for g in groups.values())
        fig, axes, holders = panel_grid(len(groups), (2.6,), entries,
                                        width=0.7 + 3.0 * len(groups))
        for j, ((ratio, body), group) in enumerate(groups.items()):
            ax = axes[0, j]
            for i, ds in enumerate(sorted(group, key=lambda d: _case(d)[0])):
                geometry = str(ds.attrs.get("geometry", "sphere"))
                name = "sigma_rr" if geometry == "sphere" else "sigma_xx"
                x = np.asarray(ds["x"].values, dtype=float)
                iz = int(np.flatnonzero(np.asarray(ds["z"].values) == 0.0)[0])
                keep = (x >= x_range[0]) & (x <= x_range[1])
                c, k = _case(ds)
                ax.plot(x[keep], ds[name].values[iz, keep], color=colors[i % len(colors)],
                        lw=1.2, label=f"c/a = {fmt(c)}, k = {k_text(k)}")
            ax.axvline(1.0, color="0.6", lw=0.6, ls=(0, (3, 2)), zorder=0)
            ax.axhline(0.0, color="0.6", lw=0.6, zorder=0)
            who = "rigid indenter" if np.isinf(ratio) else f"$E_1/E_2$ = {fmt(ratio)}"
            beta = float(group[0].attrs.get("dundurs_beta", np.nan))
            ax.set_title(f"{who}, {body}" + ("" if np.isnan(beta) else f", β = {beta:+.3f}"),
                         fontsize="medium")
            ax.set_xlabel("r/a on the surface")
            if j == 0:
                ax.set_ylabel("surface radial stress / $p_0$ (tension > 0)")
            holders[j].legend(handles=ax.get_lines()[:len(group)], loc="upper left",
                              frameon=False)
        return finish(fig)


def fig_tangential_stresses(datasets: xr.Dataset | Sequence[xr.Dataset]) -> Figure:
    """von Mises maps in the plane of the load (top) and the surface sigma_xx (bottom).

    Parameters
    ----------
    datasets : xarray.Dataset or sequence of them
        Fields on (z, x) in the plane y = 0 of
        :func:`contactlib.stresses.tangential.mindlin_sphere_stresses` (``.isel(y=0)``),
        x along the tangential load, with a surface row (z = 0); their
        ``friction_coefficient``, ``load_ratio`` and ``stick_ratio`` attributes title the
        columns.

    Returns
    -------
    matplotlib.figure.Figure
        One column a dataset: the map on one colour scale with its grid maximum (white
        cross), the contact (dashed) and the stick zone (solid), and below it sigma_xx / p0
        on the surface (tension > 0).

    Raises
    ------
    ValueError
        If a dataset lacks ``von_mises``, ``sigma_xx`` or a surface row.
    """
    items = as_list(datasets)
    for i, ds in enumerate(items):
        if not {"von_mises", "sigma_xx"} <= set(ds.variables) or ds["von_mises"].ndim != 2:
            raise ValueError(f"fig_tangential_stresses: dataset {i} is not a (z, x) field of "
                             "mindlin_sphere_stresses(...).isel(y=0)")
        if not np.any(np.asarray(ds["z"].values) == 0.0):
            raise ValueError(f"fig_tangential_stresses: dataset {i} has no surface row (z = 0)")
    ncol = len(items)
    with style_context():
        colors = palette()
        fig = Figure(figsize=(0.6 + 2.6 * ncol, 4.4), layout="constrained")
        axes = fig.subplots(2, ncol, squeeze=False, sharex=True, height_ratios=(1.6, 1.0))
        top = max(float(np.nanmax(ds["von_mises"].values)) for ds in items)
        norm = Normalize(0.0, top)
        mesh = None
        for col, ds in enumerate(items):
            ax = axes[0, col]
            x = np.asarray(ds["x"].values, dtype=float)
            z = np.asarray(ds["z"].values, dtype=float)
            v = np.asarray(ds["von_mises"].values, dtype=float)
            mesh = ax.pcolormesh(x, z, v, norm=norm, cmap="viridis", shading="gouraud",
                                 rasterized=True)
            ax.contour(x, z, v, levels=np.linspace(0.1, 0.9, 9) * top, colors="white",
                       linewidths=0.4, alpha=0.6)
            i, j = np.unravel_index(int(np.argmax(v)), v.shape)
            ax.plot(x[j], z[i], marker="x", color="white", ms=6, mew=1.5)
            ax.text(0.03, 0.05, f"max {v[i, j]:.3f} at ({x[j]:.2f}, {z[i]:.2f})",
                    transform=ax.transAxes, color="white", fontsize="small")
            ax.plot([-1, 1], [0, 0], color="white", lw=2.0, ls=(0, (3, 2)))
            c = float(ds.attrs.get("stick_ratio", 0.0))
            if c > 0:
                ax.plot([-c, c], [0, 0], color="white", lw=2.5)
            ax.set_ylim(float(z.max()), float(z.min()))
            mu = float(ds.attrs.get("friction_coefficient", np.nan))
            ratio = float(ds.attrs.get("load_ratio", np.nan))
            case = ("frictionless" if mu == 0 else "sliding" if ratio == 1.0
                    else f"Q/μP = {fmt(ratio)}, c/a = {c:.2f}")
            ax.set_title(f"μ = {fmt(mu)}, {case}", fontsize="medium")
            if col == 0:
                ax.set_ylabel("depth z/a")
            low = axes[1, col]
            iz = int(np.flatnonzero(z == 0.0)[0])
            low.plot(x, np.asarray(ds["sigma_xx"].values)[iz], color=colors[0], lw=1.2)
            low.axhline(0.0, color="0.6", lw=0.6, zorder=0)
            for edge in (-1.0, 1.0):
                low.axvline(edge, color="0.6", lw=0.6, ls=(0, (3, 2)), zorder=0)
            low.set_xlabel("x/a (load along +x)")
            if col == 0:
                low.set_ylabel("surface $\\sigma_{xx}$ / $p_0$")
        fig.colorbar(mesh, ax=list(axes[0, :]), label="von Mises / $p_0$", shrink=0.9)
        return finish(fig)
