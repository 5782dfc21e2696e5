"""Coatings: the frictionless load, k and the work per cycle against a/h, four substrates.

One figure, :func:`fig_coatings`, for the ``coatings`` target of the
workflow, from a :class:`contactlib.coating_study.CoatingStudy` (read by its
attributes; nothing is imported from the numerics): one row per geometry;
left the frictionless load over the coating's Hertz load at the same contact
radius, middle k at one stick ratio, both against a/h; right the frictional
work of a load cycle 0 -> 1 -> 0 against a_max/h (log scale, bars: its error
estimate). Colour: the substrate (E1/E2). Only resolved numbers are drawn;
an unresolved k or load is a cross at the bottom of its panel, an unresolved
or refused cycle has no point. The a/h beyond the study's grid, up to the
1000 issue 39 asks for, is shaded and labelled as not covered.

Built on :mod:`contactlib.plot.base` only; nothing here touches the disk.

Examples
--------
>>> from contactlib.coating_study import coating_study
>>> from contactlib.plot.coatings import fig_coatings
>>> st = coating_study(geometries=("sphere",), substrate_moduli=(0.1,), ratios=(0.01, 1.0),
...                    stick_ratios=(0.5,), n=32, history_ratios=(1.0,), history_n=32,
...                    history_steps=8)
>>> len(fig_coatings(st).axes)
6
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

from contactlib.plot.base import (
    MARKERS,
    finish,
    fmt,
    palette,
    panel_grid,
    style_context,
)

__all__ = ["fig_coatings"]

# convention: the a/h issue 39 asks for
_ISSUE_MAX = 1000.0  # the a/h issue 39 asks for (the x axes reach it, shaded beyond the data)


def fig_coatings(study: Any, stick_ratio: float = 0.5) -> Figure:
    """Frictionless load ratio, k(c/a = ``stick_ratio``) and cycle work against a/h.

    Parameters
    ----------
    study : CoatingStudy
        From :func:`contactlib.coating_study.coating_study`.
    stick_ratio : float
        The c/a of the middle panels (the nearest in the study).

    Returns
    -------
    matplotlib.figure.Figure
        Three plot panels a geometry and one axis-free legend holder a column.

    Raises
    ------
    ValueError
        If ``study`` lacks an attribute of a coating study.
    """
    for name in ("load_ratio", "friction", "resolved", "cycle_work", "substrate_moduli"):
        if not hasattr(study, name):
            raise ValueError(f"fig_coatings: attribute {name!r} is absent (not a coating study)")
    cs = np.asarray(study.stick_ratios, dtype=float)
    ic = int(np.argmin(np.abs(cs - stick_ratio)))
    ratios = np.asarray(study.ratios, dtype=float)
    hratios = np.asarray(study.history_ratios, dtype=float)
    covered = np.asarray(getattr(study, "covered", np.ones((len(study.geometries), ratios.size))),
                         dtype=bool)
    top_h = float(hratios.max()) if hratios.size else float(ratios.max())
    with style_context():
        colors = palette()
        fig, axes, holders = panel_grid(3, (2.3,) * len(study.geometries), 4, width=10.4)
        handles: list[Any] = []
        for g, geometry in enumerate(study.geometries):
            ax_p, ax_k, ax_w = axes[g]
            top = float(ratios[covered[g]].max()) if covered[g].any() else float(ratios.min())
            tops = (top, top, top_h)
            for j, m in enumerate(study.substrate_moduli):
                color = colors[j % len(colors)]
                style = {"color": color, "lw": 1.2, "ms": 3.5, "marker": MARKERS[j % len(MARKERS)]}
                kind = "hard" if m < 1.0 else "soft"
                load_ok = np.asarray(study.load_resolved[g, j], dtype=bool)
                (line,) = ax_p.plot(ratios, np.where(load_ok, study.load_ratio[g, j], np.nan),
                                    **style)
                _crosses(ax_p, ratios[covered[g] & ~load_ok], color)
                k_ok = np.asarray(study.resolved[g, j, :, ic], dtype=bool)
                ax_k.plot(ratios, np.where(k_ok, study.friction[g, j, :, ic], np.nan), **style)
                _crosses(ax_k, ratios[covered[g] & ~k_ok], color)
                if hratios.size:
                    _cycle_work(ax_w, study, (g, j), hratios, style)
                if g == 0:
                    line.set_label(f"E1/E2 = {fmt(1.0 / m)}: {kind} coating")
                    handles.append(line)
            ax_p.axhline(1.0, color="0.6", lw=0.6, zorder=0)
            ax_p.set_yscale("log")
            ax_p.set_ylabel("$P/P_{Hertz}$, frictionless")
            ax_k.set_ylabel(f"k at c/a = {fmt(cs[ic])}")
            ax_k.set_title(f"{geometry}, ν = ν2 = {fmt(study.nu)}", fontsize="medium")
            ax_w.set_yscale("log")
            ax_w.set_ylabel(f"work per cycle (k = {fmt(study.history_friction)})")
            for ax, top in zip((ax_p, ax_k, ax_w), tops):
                ax.set_xscale("log")
                ax.set_xlim(0.7 * min(ratios.min(), hratios.min() if hratios.size else 1.0),
                            1.4 * _ISSUE_MAX)
                if top < _ISSUE_MAX:  # the rest of the issue's range: shaded, not drawn
                    ax.axvspan(top, 1.4 * _ISSUE_MAX, color="0.88", lw=0, zorder=0)
                    ax.text(np.sqrt(top * _ISSUE_MAX), 0.5, "not\ncovered",
                            transform=ax.get_xaxis_transform(), ha="center", va="center",
                            fontsize="x-small", color="0.35")
        for ax in axes[-1, :2]:
            ax.set_xlabel("a/h (held fixed)")
        axes[-1, 2].set_xlabel("$a_{max}/h$ (history 0 → 1 → 0)")
        handles_k = [Line2D([], [], ls="none", marker="x", color="black", ms=5,
                            label="not resolved to 1e-3 (not drawn)")]
        if not covered.all() or ratios.max() < _ISSUE_MAX:
            handles_k.append(Patch(color="0.88", label="a/h not covered (up to 1000)"))
        handles_w = [Line2D([], [], color="black", marker="o", ms=3.5,
                            label="resolved to 1e-2 (bars: estimate)"),
                     Line2D([], [], ls="none", label="no point: unresolved or refused"),
                     Patch(color="0.88", label=f"a_max/h > {fmt(top_h)}: not covered")]
        for holder, part in zip(holders, (handles, handles_k, handles_w)):
            holder.legend(handles=part, loc="upper left", frameon=False)
        return finish(fig)


def _crosses(ax, xs: np.ndarray, color: str) -> None:
    """Crosses near the bottom of a panel over the a/h whose number is not resolved."""
    ax.plot(xs, np.full(xs.size, 0.04), ls="none", marker="x", color=color, ms=5,
            transform=ax.get_xaxis_transform(), scalex=False, scaley=False)


def _cycle_work(ax, study: Any, index: tuple[int, int], hratios: np.ndarray,
                style: dict[str, object]) -> None:
    """Resolved work per load cycle against a_max/h with its estimated error (bars)."""
    ok = np.asarray(study.cycle_resolved[index], dtype=bool)
    work = np.where(ok, study.cycle_work[index], np.nan)
    err = np.abs(work) * study.cycle_work_error_estimate[index]
    ax.plot(hratios, work, **style)  # type: ignore[arg-type]
    ax.errorbar(hratios, work, yerr=err, ls="none", color=style["color"], lw=0.8, capsize=2)
