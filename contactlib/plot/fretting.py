"""Figure of the fretting amplitude study: Q-s loops and the work per cycle.

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

from contactlib.theory import cylinder_cycle_work
from contactlib.plot.base import finish, palette, style_context

__all__ = ["fig_fretting", "fig_fretting_path"]

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
