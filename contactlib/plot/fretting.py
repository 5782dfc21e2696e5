"""Figures of fretting paths (:func:`contactlib.fretting`): Q-s loops and the work per cycle.

As every figure of :mod:`contactlib.plot`, built with :class:`matplotlib.figure.Figure`
inside the contactlib style, never touching the disk (save with
``contactlib.io.write_figure(fig, path, style=style_path())``). Only converged steps are
drawn; a step that did not converge is left out of the loops and named in the legend.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from matplotlib.figure import Figure

from contactlib.fretting_api import cylinder_cycle_work
from contactlib.plot.base import finish, palette, style_context

__all__ = ["plot_cycles"]


def plot_cycles(results: Sequence[Any], friction: float) -> Figure:
    """Q-s loops of several amplitudes and their cycle work against Mindlin–Deresiewicz.

    Parameters
    ----------
    results : sequence of FrettingResult
        Paths cycling Q between +-Q* at constant P (beta = 0 for the closed form
        to apply), each with at least one closed cycle.
    friction : float
        Their friction coefficient k.

    Returns
    -------
    matplotlib.figure.Figure
        Left: the tangential load Q/(k P) against the shift change (s - s0)/(k p0 a_max)
        over the last cycle; right: the work of the last cycle over k^2 p0 P a_max
        against Q*/(kP) with the closed form of the cylinder, log axes.
    """
    with style_context():
        fig = Figure(figsize=(7.2, 3.2))
        left, right = fig.subplots(1, 2)
        colors = palette()
        xs, ws, es = [], [], []
        for idx, r in enumerate(results):
            if not r.cycles:
                raise ValueError("plot_cycles: a result has no closed cycle (repeat a point "
                                 "of the path)")
            i, j, w, est = r.cycles[-1]
            a, b = r.point_step[i], r.point_step[j]
            ok = r.converged[a:b + 1]
            s = r.shift[a:b + 1]
            q = r.force_ratio[a:b + 1] / r.load_ratio[a:b + 1]
            scale = friction * r.p0
            x_amp = float(np.max(np.abs(r.force_ratio[a:b + 1])) / r.load_ratio[b])
            left.plot(((s - s[0]) / scale)[ok], q[ok], color=colors[idx % len(colors)],
                      gid="fretting-loop", label=f"$Q^*/kP$ = {x_amp:g}")
            xs.append(x_amp)
            ws.append(w / (friction**2 * r.p0 * r.p_max))
            es.append(est / (friction**2 * r.p0 * r.p_max))
        left.set_xlabel(r"shift change $(s - s_0)\,/\,(k p_0 a_{max}^2/R)$")
        left.set_ylabel(r"$Q / kP$")
        left.legend(loc="lower right")
        grid = np.linspace(0.02, 0.999, 200)
        right.loglog(grid, cylinder_cycle_work(grid, 1.0, 1.0, 1.0), color="0.4",
                     gid="mindlin-deresiewicz", label="Mindlin–Deresiewicz (closed form)")
        right.errorbar(xs, ws, yerr=es, fmt="o", color=colors[0], gid="cycle-work",
                       label="contactlib (estimate as bar)")
        right.set_xlabel(r"$Q^*/kP$")
        right.set_ylabel(r"work per cycle $/\,(k^2 p_0 P\,a_{max}^2/R)$")
        right.legend(loc="lower right")
        return finish(fig)
