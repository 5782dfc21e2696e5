"""Figures of fretting: the amplitude study (Q-s loops, work per cycle), a path, and the
sphere's stick-zone map.

Drawn from the dataset of :func:`contactlib.io.fretting_study_to_dataset`. As every figure
of :mod:`contactlib.plot`, built with :class:`matplotlib.figure.Figure` inside the
contactlib style, never touching the disk (save with
``contactlib.io.write_figure(fig, path, style=style_path())``). Steps that did not
converge are NaN in the dataset's loops and are not drawn; a cycle with such a step is
not drawn either.
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from contactlib.model.theory import cylinder_cycle_work
from contactlib.plot.base import finish, palette, style_context

__all__ = ["fig_fretting", "fig_fretting_path", "fig_stick_zone_map"]

# convention: the amplitudes the fretting figure draws loops for
_LOOP_AMPLITUDES = (0.25, 0.5, 0.9)


def fig_fretting(ds: xr.Dataset) -> Figure:
    """Q-s loops of the uncoupled cases and the cycle work against Mindlin–Deresiewicz.

    Parameters
    ----------
    ds : xarray.Dataset
        From :func:`contactlib.io.fretting_study_to_dataset`.

    Returns
    -------
    matplotlib.figure.Figure
        Left: Q/(kP) against the shift change (s - s0)/(k p0 a_max^2/R) over the last
        cycle, beta = 0, Q*/kP = 0.25, 0.5, 0.9 where present. Right: the work of the
        last cycle over k^2 p0 P_max a_max^2/R against Q*/kP, log axes, one marker per
        beta, error bars the estimates, with the closed form of the cylinder.
    """
    for name in ("amplitude", "cycle_work", "loop_shift", "dundurs_beta"):
        if name not in ds.variables:
            raise ValueError(f"fig_fretting: the dataset has no variable {name!r} (expected "
                             "one of contactlib.io.fretting_study_to_dataset)")
    k = float(ds.attrs["friction_coefficient"])
    p0, p_max = 0.5, np.pi / 4  # Hertz's cylinder at a_max = 1
    unit = k**2 * p0 * p_max
    amp = ds["amplitude"].values
    beta = ds["dundurs_beta"].values
    with style_context():
        fig = Figure(figsize=(7.2, 3.2))
        left, right = fig.subplots(1, 2)
        colors = palette()
        shown = 0
        for c in np.flatnonzero(beta == 0.0):
            if not any(np.isclose(amp[c], a) for a in _LOOP_AMPLITUDES):
                continue
            left.plot(ds["loop_shift"].values[c], ds["loop_tangential_load"].values[c],
                      color=colors[shown % len(colors)], gid="fretting-loop",
                      label=f"$Q^*/kP$ = {amp[c]:g}")
            shown += 1
        left.set_xlabel(r"shift change $(s - s_0)\,/\,(k p_0 a_{max}^2/R)$")
        left.set_ylabel(r"$Q / kP$")
        if shown:
            left.legend(loc="lower right")
        grid = np.linspace(0.02, 0.999, 200)
        right.loglog(grid, cylinder_cycle_work(grid, 1.0, 1.0, 1.0), color="0.4",
                     gid="mindlin-deresiewicz", label="Mindlin–Deresiewicz, β = 0")
        for idx, b in enumerate(sorted(set(beta.tolist()))):
            sel = np.flatnonzero(beta == b)
            ok = ds["cycle_converged"].values[sel, -1].astype(bool)
            w = ds["cycle_work"].values[sel, -1] / unit
            e = ds["cycle_work_error_estimate"].values[sel, -1] / unit
            right.errorbar(amp[sel][ok], w[ok], yerr=e[ok], fmt="os"[idx % 2], mfc="none"
                           if idx else None, color=colors[idx % len(colors)],
                           gid="cycle-work", label=f"contactlib, β = {b:.3g}")
        right.set_xlabel(r"$Q^*/kP$")
        right.set_ylabel(r"work per cycle $/\,(k^2 p_0 P\,a_{max}^2/R)$")
        right.legend(loc="lower right")
        return finish(fig)


def fig_fretting_path(ds: xr.Dataset, title: str = "") -> Figure:
    """A fretting path's Q-s curve and its stick ratio, step by step.

    Parameters
    ----------
    ds : xarray.Dataset
        From :func:`contactlib.io.fretting_to_dataset` (one path).
    title : str
        Drawn above the panels (e.g. the scene's name).

    Returns
    -------
    matplotlib.figure.Figure
        Left: Q/(k P_max) against the shift change (s - s_0)/(k p0 a_max^2/R) from the
        path's first step. Right: the stick ratio c/a against the load step, the path
        points marked with their error estimates. Steps that did not converge are not
        drawn.
    """
    for name in ("tangential_load_ratio", "tangential_shift", "stick_ratio", "point_step"):
        if name not in ds.variables:
            raise ValueError(f"fig_fretting_path: the dataset has no variable {name!r} "
                             "(expected one of contactlib.io.fretting_to_dataset)")
    k = float(ds.attrs["friction_coefficient"])
    p0 = float(ds.attrs.get("p0", 0.5))  # the run's pressure unit (older files: the cylinder's)
    ok = np.cumprod(ds["converged"].values.astype(bool)).astype(bool)
    q = np.where(ok, ds["tangential_load_ratio"].values, np.nan)
    s = np.where(ok, ds["tangential_shift"].values - ds["tangential_shift"].values[0], np.nan)
    c = np.where(ok, ds["stick_ratio"].values, np.nan)
    pts = ds["point_step"].values
    with style_context():
        fig = Figure(figsize=(7.2, 3.2))
        left, right = fig.subplots(1, 2)
        colors = palette()
        left.plot(s / (k * p0), q, color=colors[0], gid="fretting-path-loop")
        left.set_xlabel(r"shift change $(s - s_0)\,/\,(k p_0 a_{max}^2/R)$")
        left.set_ylabel(r"$Q / k P_{max}$")
        steps = np.arange(c.size)
        right.plot(steps, c, color=colors[0], gid="fretting-path-stick-ratio")
        right.errorbar(pts, c[pts], yerr=ds["stick_ratio_error_estimate"].values, fmt="o",
                       mfc="none", color=colors[0], gid="fretting-path-points",
                       label="path points (error estimate)")
        right.set_xlabel("load step")
        right.set_ylabel(r"stick ratio $c/a$")
        right.set_ylim(-0.02, 1.02)
        right.legend(loc="lower left")
        if title:
            fig.suptitle(title)
        return finish(fig)


def _map_steps(ds: xr.Dataset, steps) -> list[int]:
    """The steps to draw: those asked, or the path points with a tangential load."""
    if steps is not None:
        return [int(j) for j in steps]
    pts = ds["point_step"].values
    q = ds["tangential_load_ratio"].values[pts]
    return [int(j) for j in pts[(q != 0.0) & np.isfinite(q)]]


def _estimate_marks(ax, ds: xr.Dataset, step: int, r: np.ndarray, centre, ring,
                    color) -> None:
    """A step's band of +- the radii's estimates and its markers (filled: resolved to the
    dataset's max_error; open: not); markers alone where the step is no path point."""
    cos, sin = ring
    hit = np.flatnonzero(ds["point_step"].values == step)
    name = "stick_radius_directions_error_estimate"
    x, y = centre[0] + r * cos, centre[1] + r * sin
    if not hit.size or name not in ds:
        ax.plot(x, y, "o", color=color, markersize=3, gid="stick-direction")
        return
    e = ds[name].values[hit[0]]
    e = np.append(e, e[0])
    if np.all(np.isfinite(r) & np.isfinite(e)):
        outer, inner = r + e, np.maximum(r - e, 0.0)
        ax.fill(np.concatenate([centre[0] + outer * cos, (centre[0] + inner * cos)[::-1]]),
                np.concatenate([centre[1] + outer * sin, (centre[1] + inner * sin)[::-1]]),
                color=color, alpha=0.2, lw=0, gid="stick-estimate")
    ok = e[:-1] <= float(ds.attrs.get("max_error", np.nan))
    ax.plot(x[:-1][ok], y[:-1][ok], "o", color=color, markersize=3.5, gid="stick-resolved")
    ax.plot(x[:-1][~ok], y[:-1][~ok], "o", color=color, mfc="white", markersize=3.5,
            gid="stick-unresolved")


def fig_stick_zone_map(datasets, steps=None, titles=None) -> Figure:
    """The sphere's stick zone per direction at several steps: one panel per path.

    Parameters
    ----------
    datasets : xarray.Dataset or sequence of them
        From :func:`contactlib.io.fretting_to_dataset` of sphere paths (with the variables
        ``stick_radius_directions``, ``contact_radius_directions`` and their centres);
        one panel each.
    steps : sequence of int, optional
        The steps drawn in every panel (default: the path points with Q != 0).
    titles : sequence of str, optional
        One per panel (default: Dundurs' beta and n).

    Returns
    -------
    matplotlib.figure.Figure
        In each panel, in units a_max with equal aspect: the stick zone's outline (its
        radius per direction from its centroid, a closed polygon) at each step,
        labelled with Q/kP, with a band of +- its estimate where the step is a path point
        (the estimates are per path point) and a marker per direction: filled where the
        radius is resolved (its estimate within the dataset's ``max_error``), open where it
        is not; the contact's outline at the last step (grey); and, dashed,
        Cattaneo–Mindlin's circle c = a (1 - Q/kP)^(1/3) at the same Q/kP (exact for
        beta = gamma = 0), a the contact's mean radius. The arrow shows Q's direction.
        Directions that have no radius (NaN) break the outline and get no band.
    """
    if isinstance(datasets, xr.Dataset):
        datasets = [datasets]
    for ds in datasets:
        for name in ("stick_radius_directions", "contact_radius_directions", "direction",
                     "stick_centre", "contact_centre"):
            if name not in ds.variables:
                raise ValueError(f"fig_stick_zone_map: the dataset has no variable {name!r} "
                                 "(expected a sphere's contactlib.io.fretting_to_dataset)")
    with style_context():
        fig = Figure(figsize=(3.4 * len(datasets) + 1.4, 3.4))
        axes = np.atleast_1d(fig.subplots(1, len(datasets), squeeze=False)[0])
        colors = palette()
        for idx_ds, (ax, ds) in enumerate(zip(axes, datasets)):
            theta = ds["direction"].values
            ring = np.append(theta, theta[0] + 2 * np.pi)
            cos, sin = np.cos(ring), np.sin(ring)
            ok = np.cumprod(ds["converged"].values.astype(bool)).astype(bool)
            chosen = [j for j in _map_steps(ds, steps) if ok[j]]
            with np.errstate(invalid="ignore", divide="ignore"):
                x = ds["tangential_load_ratio"].values / ds["load_ratio"].values
            circle = np.linspace(0.0, 2 * np.pi, 181)
            for idx, j in enumerate(chosen):
                r = ds["stick_radius_directions"].values[j]
                r = np.append(r, r[0])
                cx, cy = ds["stick_centre"].values[j]
                color = colors[idx % len(colors)]
                ax.plot(cx + r * cos, cy + r * sin, color=color, lw=1.2, gid="stick-outline",
                        label=f"$Q/kP$ = {x[j]:.2g}")
                _estimate_marks(ax, ds, j, r, (cx, cy), (cos, sin), color)
                a = float(np.nanmean(ds["contact_radius_directions"].values[j]))
                c = a * (1.0 - abs(x[j])) ** (1.0 / 3.0)
                ax.plot(c * np.cos(circle), c * np.sin(circle), color=color, lw=0.8,
                        ls="--", gid="cattaneo-mindlin")
            if chosen:
                a_dir = ds["contact_radius_directions"].values[chosen[-1]]
                a_dir = np.append(a_dir, a_dir[0])
                ax_, ay_ = ds["contact_centre"].values[chosen[-1]]
                ax.plot(ax_ + a_dir * cos, ay_ + a_dir * sin, color="0.45", lw=1.2,
                        gid="contact-outline",
                        label="contact")
            ax.plot([], [], color="0.3", lw=0.8, ls="--", label="Cattaneo–Mindlin")
            asked = float(ds.attrs.get("max_error", np.nan))
            ax.plot([], [], "o", color="0.3", markersize=3.5,
                    label=f"resolved to {asked:g} $a_{{max}}$")
            ax.plot([], [], "o", color="0.3", mfc="white", markersize=3.5,
                    label="not resolved")
            ax.fill([], [], color="0.3", alpha=0.2, lw=0, label="± estimate")
            ax.annotate("", xy=(1.15, -1.12), xytext=(0.75, -1.12),
                        arrowprops={"arrowstyle": "->", "color": "0.3"})
            ax.text(0.95, -1.06, "$Q$", ha="center", va="bottom", color="0.3")
            ax.set_aspect("equal")
            ax.set_xlim(-1.2, 1.2)
            ax.set_ylim(-1.2, 1.2)
            ax.set_xlabel(r"$x / a_{max}$")
            ax.set_ylabel(r"$y / a_{max}$")
            ax.set_title(titles[idx_ds] if titles is not None else
                         f"β = {float(ds.attrs['dundurs_beta']):.3g}, "
                         f"n = {int(ds.attrs['elements'])}", fontsize="medium")
        axes[-1].legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize="small")
        return finish(fig)
