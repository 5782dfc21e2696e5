"""The paper's figures 2-5, drawn from contactlib datasets.

Every function takes one :class:`xarray.Dataset` or a sequence of them, as
produced by :func:`contactlib.io.to_dataset` or read back by
:func:`contactlib.io.read_dataset` (variables and scalings of docs/conventions.md
section 2), and returns a new :class:`matplotlib.figure.Figure`. Nothing here
touches the disk; save with ``contactlib.io.write_figure(fig, path,
style=style_path())``.

Style, colours, panels and the frozen layout come from
:mod:`contactlib.plot.base`: figures are built with
:class:`matplotlib.figure.Figure` directly, never with :mod:`matplotlib.pyplot`,
so no backend is selected or needed (saving uses Agg for PNG and the PDF
backend for PDF), and each function draws inside the contactlib style; the
caller's ``rcParams`` are left as they were.

Conventions common to all figures:

* a dataset is labelled by its ``scene`` attribute when present, otherwise
  by its method, element count, Poisson's ratio and (cylinder) a/h;
* a case with ``converged`` false, or (default method) ``resolved`` false
  (its error estimate above the accuracy asked for), is always drawn,
  marked by a black cross (k and work curves) or a dotted line with crosses
  (profiles), and "not converged" in its legend label: a case that is not
  resolved is treated as a failure. A case with no value (NaN: a solver that
  did not converge reports none) is a cross on the bottom edge of a k plot,
  is left out of profiles and work plots, and is named in the legend or a
  note; no number of it is drawn or written. The paper's scheme is a reproduction
  whose k is not the physical one (its ``error_estimate`` against our method
  is large by design); its cases keep their consistency markers;
* filled markers are consistent cases, open markers inconsistent ones;
* the paper's scheme (``method`` ``"paper"`` or ``"paper-literal"``) is drawn
  as markers joined by a thin line, the default method as a solid line;
* a variable a figure needs but a dataset lacks raises :class:`ValueError`
  naming the variable and the dataset.

Examples
--------
>>> import contactlib
>>> from contactlib.io import to_dataset
>>> from contactlib.plot import fig2_friction
>>> ds = to_dataset(contactlib.sweep("sphere", 0.3, [0, 0.1, 0.5, 1], n=32))
>>> fig = fig2_friction(ds)
>>> [ax.get_title() for ax in fig.axes if ax.get_title()]
['sphere on an elastic half-space']
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from numbers import Real
from typing import NamedTuple

import matplotlib
import numpy as np
import xarray as xr
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

from contactlib.plot.base import (
    MARKERS,
    NOT_CONVERGED_GID,
    as_list,
    describe,
    finish,
    fmt,
    k_text,
    label_of,
    legend_height,
    palette,
    panel_grid,
    style_context,
)
from contactlib.model.indenter import indenter
from contactlib.model.theory import hertz_pressure, uncoupled_friction
from contactlib.validate import GEOMETRIES, estimates

__all__ = [
    "fig2_friction",
    "fig3_tractions",
    "fig4_displacement",
    "fig5_work",
]

# convention: the stick ratios of the paper's figures
DEFAULT_STICK_RATIOS: tuple[float, ...] = (0.1, 0.3, 0.5, 0.7, 0.9)
# fig 3 compares the paper's scheme with ours at the same c/a: values m/16 (the
# paper's) that the default scenes also hold
# convention: multiples of 1/16 that the paper's scheme resolves at n = 16
FIG3_STICK_RATIOS: tuple[float, ...] = (1 / 16, 4 / 16, 8 / 16, 12 / 16)
# exact: 1/16, the paper's scheme's smallest c/a at its n = 16
PAPER_SMALLEST_STICK_RATIO = 1.0 / 16.0

_GEOMETRIES = GEOMETRIES
_TITLES = {
    "sphere": "sphere on an elastic half-space",
    "cylinder": "cylinder on an elastic slab (plane strain)",
}
_WORK_LABEL = {
    "sphere": r"frictional work $V R^2/(E^* a^5)$",
    "cylinder": r"frictional work $V R^2/(E^* a^4)$ per unit length",
}
# convention: the line styles of the paper's figures (points on, off)
_DASHES = ((5.0, 2.5), (1.5, 1.5), (6.0, 2.0, 1.5, 2.0), (3.0, 1.0))


# ----------------------------------------------------------------------------- datasets
@dataclass(frozen=True)
class _Case:
    """One dataset, validated and put on a sorted 1-D ``stick_ratio``."""

    index: int
    ds: xr.Dataset
    geometry: str
    nu: float
    method: str
    slab_ratio: float
    label: str
    description: str
    stick: np.ndarray

    @property
    def paper(self) -> bool:
        return self.method.startswith("paper")

    def values(self, name: str) -> np.ndarray:
        return np.asarray(self.ds[name].values, dtype=float)

    def flag(self, name: str, default: bool | None = None) -> np.ndarray:
        if name == "converged" and "resolved" in self.ds and \
                estimates(self.ds.attrs.get("method")):  # not resolved: a failure too
            return (np.asarray(self.ds["converged"].values).astype(bool)
                    & np.asarray(self.ds["resolved"].values).astype(bool))
        if name not in self.ds:
            if default is None:  # pragma: no cover - guarded by _prepare
                raise KeyError(name)
            return np.full(self.stick.shape, default, dtype=bool)
        return np.asarray(self.ds[name].values).astype(bool)


def _prepare(ds: xr.Dataset, index: int, figure: str, required: Sequence[str],
             *, profiles: bool = False) -> _Case:
    """Validate one dataset for ``figure`` and return it as a :class:`_Case`."""
    description = describe(ds, "method")
    label, where = label_of(ds, index, description)
    geometry = ds.attrs.get("geometry")
    if geometry not in _GEOMETRIES:
        raise ValueError(
            f"{figure}: {where} has geometry attribute {geometry!r}, "
            f"expected one of {_GEOMETRIES}"
        )
    if "poisson_ratio" not in ds.attrs:
        raise ValueError(f"{figure}: {where} lacks the attribute 'poisson_ratio'")
    needed = list(required)
    if profiles:
        needed.append("xi")
    if "stick_ratio" not in ds.coords and "stick_ratio" not in ds.dims:
        needed.insert(0, "stick_ratio")
    for name in needed:
        if name not in ds.variables:
            raise ValueError(
                f"{figure}: variable {name!r} is absent from {where}; "
                f"the scene that produced it did not compute {name!r}"
            )
    if "stick_ratio" not in ds.dims:
        ds = ds.expand_dims("stick_ratio")
    ds = ds.sortby("stick_ratio")
    return _Case(
        index=index,
        ds=ds,
        geometry=str(geometry),
        nu=float(ds.attrs["poisson_ratio"]),
        method=str(ds.attrs.get("method", "default")),
        slab_ratio=float(ds.attrs.get("slab_ratio", 0.0)),
        label=label,
        description=description,
        stick=np.asarray(ds["stick_ratio"].values, dtype=float),
    )


def _cases(datasets: xr.Dataset | Sequence[xr.Dataset], figure: str,
           required: Sequence[str], **kw: object) -> list[_Case]:
    return [_prepare(ds, i, figure, required, **kw)  # type: ignore[arg-type]
            for i, ds in enumerate(as_list(datasets))]


def _ratios(stick_ratios: Sequence[float], figure: str) -> list[float]:
    try:
        values = list(stick_ratios)
    except TypeError:
        raise ValueError(f"{figure}: stick_ratios must be a sequence of numbers, "
                         f"got {stick_ratios!r}") from None
    if not values:
        raise ValueError(f"{figure}: stick_ratios must not be empty")
    out = []
    for v in values:
        if isinstance(v, bool) or not isinstance(v, Real) or not 0.0 <= float(v) <= 1.0:
            raise ValueError(f"{figure}: stick_ratios must be numbers in [0, 1], got {v!r}")
        out.append(float(v))
    return out


def _nearest(stick: np.ndarray, requested: Sequence[float], allowed: np.ndarray) -> list[int]:
    """Indices of the allowed stick ratios nearest to each requested one.

    Duplicates are removed; the result is sorted by stick ratio.
    """
    candidates = np.flatnonzero(allowed)
    if candidates.size == 0:
        return []
    chosen = {int(candidates[np.argmin(np.abs(stick[candidates] - r))]) for r in requested}
    return sorted(chosen, key=lambda i: (stick[i], i))


# ----------------------------------------------------------------------------- drawing helpers


def _ratio_color(c: float) -> tuple[float, float, float, float]:
    """Colour of a stick ratio on profile plots (viridis, yellow end left out)."""
    return matplotlib.colormaps["viridis"](0.02 + 0.86 * float(np.clip(c, 0.0, 1.0)))


def _status(converged: bool, consistent: bool | None) -> str:
    notes = []
    if consistent is False:
        notes.append("inconsistent")
    if not converged:
        notes.append("NOT CONVERGED")
    return f" [{', '.join(notes)}]" if notes else ""


def _line_style(case: _Case) -> dict[str, object]:
    """Connecting line: thin for the paper's scheme, solid for ours."""
    return {"lw": 0.7 if case.paper else 1.4, "ls": "-"}


def _marker_size(case: _Case) -> float:
    return 4.5 if case.paper else 3.2


def _by_geometry(cases: Sequence[_Case]) -> list[tuple[str, list[_Case]]]:
    """The geometries the cases cover (sphere first), each with its cases in order."""
    return [(g, [c for c in cases if c.geometry == g]) for g in _GEOMETRIES
            if any(c.geometry == g for c in cases)]


class _Series(NamedTuple):
    """One case's curve over c/a: its look and its values."""

    color: str
    marker: str
    size: float
    x: np.ndarray  # stick ratios c/a
    y: np.ndarray  # the variable drawn
    consistent: np.ndarray
    converged: np.ndarray  # converged and (default method) resolved


def _series(case: _Case, name: str, colors: Sequence[str]) -> _Series:
    """The colour, marker, size, c/a, values of ``name`` and flags of one case."""
    return _Series(colors[case.index % len(colors)], MARKERS[case.index % len(MARKERS)],
                   _marker_size(case), case.stick, case.values(name),
                   case.flag("consistent"), case.flag("converged"))


def _draw_points(ax: Axes, x: np.ndarray, y: np.ndarray, consistent: np.ndarray,
                 *, marker: str, color: str, size: float, clip_on: bool = True) -> None:
    """Filled markers for consistent points, open ones for inconsistent points."""
    for ok, face in ((True, color), (False, "white")):
        sel = consistent == ok
        if np.any(sel):
            ax.plot(x[sel], y[sel], ls="none", marker=marker, ms=size, mfc=face,
                    mec=color, color=color, zorder=3, clip_on=clip_on)


def _draw_not_converged(ax: Axes, x: np.ndarray, y: np.ndarray) -> None:
    """Black crosses over failed cases (gid ``not-converged``)."""
    if x.size:
        ax.plot(x, y, ls="none", marker="x", ms=7, mew=1.3, color="black", zorder=5,
                clip_on=False, gid=NOT_CONVERGED_GID)


def _runs(mask: np.ndarray) -> list[tuple[int, int]]:
    """Maximal runs of consecutive true entries, as (first, last) index pairs."""
    runs: list[tuple[int, int]] = []
    start = None
    for i, m in enumerate(mask):
        if m and start is None:
            start = i
        if not m and start is not None:
            runs.append((start, i - 1))
            start = None
    if start is not None:
        runs.append((start, len(mask) - 1))
    return runs


def _legend_below(holder: Axes, handles: Sequence[object]) -> None:
    """Legend at the top of an axis-free holder panel under the plots."""
    holder.legend(handles=handles, loc="upper center", borderaxespad=0.0)


def _column_title(case: _Case) -> str:
    if case.label != case.description:
        return f"{case.label}\n{case.geometry}, {case.description}"
    return f"{case.geometry}, {case.description}"


# ----------------------------------------------------------------------------- fig 2
def fig2_friction(datasets: xr.Dataset | Sequence[xr.Dataset], *,
                  k_max: float = 1.0) -> Figure:
    """Friction coefficient k against stick ratio c/a (the paper's Fig. 2).

    One panel per geometry present (sphere, then cylinder), one curve per
    dataset. Below each panel a strip shows, for each dataset, the c/a
    ranges over which consecutive sampled cases are all consistent and
    converged (a bar; a lone such case is a tick). The uncoupled closed form
    :func:`contactlib.model.theory.uncoupled_friction` is drawn dashed for every
    Poisson's ratio present, in the colour of the curve of that ratio (of the
    default method's where the paper's scheme shares it): for the sphere, and
    for the cylinder only when a half-plane dataset (``slab_ratio`` 0) is
    present (the closed form is for the half-plane).

    Parameters
    ----------
    datasets : xarray.Dataset or sequence of xarray.Dataset
        Sweeps (or single solves) with ``friction_coefficient``,
        ``consistent`` and ``converged``.
    k_max : float, optional
        The k axis is linear and cut at ``k_max`` (k grows without bound as
        c/a -> 1; k = inf at c/a = 1). Cases above it are drawn as triangles
        on the top edge; the axis reaches below zero by at most 0.1 k_max,
        and cases below it are drawn on the bottom edge, labelled with their
        k. A dataset's legend marker is open when none of its cases is
        consistent.

    Returns
    -------
    matplotlib.figure.Figure
        k (dimensionless) against c/a (dimensionless, 0...1).

    Raises
    ------
    ValueError
        If a dataset lacks a needed variable (the message names it and the
        dataset), has an unknown geometry, or ``k_max`` is not positive.

    Examples
    --------
    >>> import contactlib
    >>> from contactlib.io import to_dataset
    >>> ds = to_dataset(contactlib.sweep("cylinder", 0.3, [0.2, 0.5, 1], n=32))
    >>> fig = fig2_friction([ds], k_max=0.8)
    >>> float(fig.axes[0].get_ylim()[1])
    0.8
    """
    if not (isinstance(k_max, Real) and math.isfinite(k_max) and k_max > 0):
        raise ValueError(f"fig2_friction: k_max must be a positive number, got {k_max!r}")
    k_max = float(k_max)
    cases = _cases(datasets, "fig2_friction",
                   ("friction_coefficient", "consistent", "converged"))
    groups = _by_geometry(cases)
    rows = max(len(members) for _, members in groups)
    entries = max(len(members) + _reference_count(g, cases) for g, members in groups)
    with style_context():
        colors = palette()
        ncol = len(groups)
        main_in, strip_in, legend_in = 2.3, 0.1 + 0.13 * rows, legend_height(entries)
        fig = Figure(figsize=(7.0 if ncol == 2 else 5.2,
                              main_in + strip_in + legend_in + 1.15),
                     layout="constrained")
        grid = fig.add_gridspec(3, ncol, height_ratios=[main_in, strip_in, legend_in])
        any_high = any_low = any_nan = False
        for j, (geometry, members) in enumerate(groups):
            ax = fig.add_subplot(grid[0, j])
            strip = fig.add_subplot(grid[1, j], sharex=ax)
            handles: list[Line2D] = []
            bottom = _k_axis_bottom(members, k_max)
            for row, case in enumerate(members):
                color, marker, size, x, k, consistent, converged = _series(
                    case, "friction_coefficient", colors)
                # the line breaks where a case has no value (NaN: no root)
                ax.plot(x, np.where(np.isinf(k), np.nan, k), color=color, zorder=2,
                        **_line_style(case))
                nan = np.isnan(k)
                high = ~nan & (k > k_max)
                low = ~nan & (k < bottom)
                on = ~(high | low | nan)
                _draw_points(ax, x[on], k[on], consistent[on], marker=marker,
                             color=color, size=size)
                _draw_points(ax, x[high], np.full(int(high.sum()), k_max), consistent[high],
                             marker="^", color=color, size=size + 1, clip_on=False)
                _draw_points(ax, x[low], np.full(int(low.sum()), bottom), consistent[low],
                             marker="v", color=color, size=size + 1, clip_on=False)
                any_high |= bool(np.any(high))
                any_low |= bool(np.any(low))
                any_nan |= bool(np.any(nan))
                # failed cases: crosses wherever their marker went; a case with no
                # value (no root) only a cross on the bottom edge
                y_marks = np.where(high, k_max, np.where(low | nan, bottom, k))
                _draw_not_converged(ax, x[~converged], y_marks[~converged])
                for xv, kv in zip(x[low], k[low]):  # the value of a case below the axis
                    ax.annotate(f"k = {k_text(float(kv))}", (xv, bottom), xytext=(4, 3),
                                textcoords="offset points", fontsize=5.8, color=color,
                                annotation_clip=False)
                handles.append(_series_key(case, color, marker, size, consistent))
                # the consistent-range strip: one row per dataset, top row first
                y = len(members) - 1 - row
                good = consistent & converged
                for first, last in _runs(good):
                    strip.plot([x[first], x[last]], [y, y], color=color, lw=2.6,
                               solid_capstyle="butt", marker="|", ms=7, mew=1.4,
                               clip_on=False)
                if not np.any(good):
                    strip.text(0.5, y, "no consistent converged case", color=color,
                               ha="center", va="center", fontsize=6,
                               transform=strip.get_yaxis_transform())
            handles += _uncoupled_references(ax, geometry, members, colors)
            ax.set_xlim(-0.02, 1.02)
            ax.set_ylim(bottom, k_max)
            ax.set_title(_TITLES[geometry], pad=9)  # clear of the markers on the top edge
            ax.set_ylabel(f"friction coefficient k (axis cut at {fmt(k_max)})")
            ax.tick_params(labelbottom=False)
            holder = fig.add_subplot(grid[2, j])
            holder.set_axis_off()
            _legend_below(holder, handles)
            strip.set_ylim(-0.6, len(members) - 0.4)
            strip.set_yticks([])
            strip.tick_params(right=False, left=False)
            strip.grid(False, axis="y")
            strip.set_ylabel("consistent\nrange", rotation=0, ha="right", va="center",
                             fontsize=6.5)
            strip.set_xlabel("stick ratio c/a")
        key = [
            Line2D([], [], ls="none", marker="o", color="0.35", label="consistent case"),
            Line2D([], [], ls="none", marker="o", color="0.35", mfc="white",
                   label="inconsistent case"),
            Line2D([], [], ls="none", marker="x", ms=7, mew=1.3, color="black",
                   label="not converged or not resolved"),
            Line2D([], [], ls="none", marker="^", color="0.35",
                   label=f"k > {fmt(k_max)} (or k = ∞): on the top edge"),
            Line2D([], [], color="0.35", lw=1.4, label="default method: solid line"),
            Line2D([], [], color="0.35", lw=0.7, marker="o", ms=4,
                   label="paper scheme: markers, thin line"),
            Line2D([], [], color="0.35", lw=2.6, marker="|", ms=7, mew=1.4,
                   label="bar: c/a range of consistent, converged cases"),
        ]
        if any_low:
            key.append(Line2D([], [], ls="none", marker="v", color="0.35",
                              label="k below the axis (value given): on the bottom edge"))
        if any_nan:
            key.append(Line2D([], [], ls="none", marker="x", ms=7, mew=1.3, color="black",
                              label="no root (not converged): cross on the bottom edge, "
                                    "no value"))
        fig.legend(handles=key, loc="outside lower center", ncols=3 if ncol == 2 else 2,
                   fontsize=6.3)
        return finish(fig)


# convention: how far below zero the k axis may reach, as a fraction of k_max
_K_AXIS_FLOOR = 0.1  # the k axis reaches below zero by at most this fraction of k_max


def _k_axis_bottom(members: list[_Case], k_max: float) -> float:
    """Lower end of the k axis: below the lowest k, never below -0.1 k_max.

    A negative k (an inconsistent scheme's) would otherwise squeeze the
    physical curves; cases below the axis go on its bottom edge, labelled
    with their value.
    """
    lowest = 0.0
    for case in members:
        k = case.values("friction_coefficient")
        k = k[np.isfinite(k)]
        if k.size:
            lowest = min(lowest, float(np.min(k)))
    lowest = max(lowest, -_K_AXIS_FLOOR * k_max)
    return lowest - 0.04 * (k_max - lowest)


def _series_key(case: _Case, color: str, marker: str, size: float,
                consistent: np.ndarray) -> Line2D:
    """Legend entry of a dataset: open marker when none of its cases is consistent."""
    face = color if np.any(consistent) else "white"
    return Line2D([], [], color=color, marker=marker, ms=size, mfc=face,
                  label=case.label, **_line_style(case))  # type: ignore[arg-type]


def _uncoupled_eligible(geometry: str, members: Sequence[_Case]) -> list[_Case]:
    """Datasets the uncoupled closed form applies to (a half-space or half-plane only)."""
    return [c for c in members if c.geometry == geometry and c.slab_ratio == 0.0]


def _reference_count(geometry: str, cases: Sequence[_Case]) -> int:
    """Legend entries :func:`_uncoupled_references` adds for ``geometry``."""
    return max(len({c.nu for c in _uncoupled_eligible(geometry, cases)}), 1)


def _reference_color(cases: Sequence[_Case], nu: float, colors: Sequence[str]) -> str:
    """The colour of the curve a closed form for ``nu`` belongs to: the first dataset of
    that nu, one of the default method where there is one (the paper's scheme at n = 16
    is a reproduction, not the converged curve)."""
    same = [c for c in cases if c.nu == nu]
    pick = next((c for c in same if not c.paper), same[0])
    return colors[pick.index % len(colors)]


def _uncoupled_references(ax: Axes, geometry: str, members: list[_Case],
                          colors: Sequence[str]) -> list[Line2D]:
    """Dashed uncoupled closed form for each Poisson's ratio present, in the colour of
    its curve (:func:`_reference_color`)."""
    eligible = _uncoupled_eligible(geometry, members)
    nus = sorted({c.nu for c in eligible})
    handles: list[Line2D] = []
    # gamma dense near 1, where k grows without bound
    gamma = 1.0 - (1.0 - np.linspace(0.0, 1.0, 401)[:-1]) ** 2
    ind = indenter(geometry)
    layered = ind.reports_half_space_ratio or any(c.slab_ratio > 0 for c in members)
    for i, nu in enumerate(nus):
        k = uncoupled_friction(geometry, nu, gamma)
        where = f", {ind.half_space_name}" if layered else ""
        (line,) = ax.plot(gamma, k, color=_reference_color(eligible, nu, colors), lw=1.0,
                          dashes=_DASHES[i % len(_DASHES)],
                          zorder=1, label=f"uncoupled closed form, ν = {fmt(nu)}{where}")
        handles.append(line)
    if indenter(geometry).accepts_layer and not eligible:
        handles.append(Line2D([], [], ls="none", label="(no uncoupled closed form "
                                                        "for a/h > 0)"))
    return handles


# ----------------------------------------------------------------------------- fig 3
def fig3_tractions(datasets: xr.Dataset | Sequence[xr.Dataset],
                   stick_ratios: Sequence[float] = FIG3_STICK_RATIOS) -> Figure:
    """Pressure and shear profiles for several stick ratios (the paper's Fig. 3).

    One column per dataset (more than four wrap into rows of columns,
    :func:`~contactlib.plot.base.panel_grid`): pressure p/p0 (top) and shear
    q/p0 (bottom) against xi = r/a (sphere) or x/a (cylinder), p0 the Hertz
    peak pressure at the same contact radius; shear is the traction on the elastic body,
    positive away from the axis. Drawn for the dataset's stick ratios
    nearest to the requested ones (each at most once; the legend gives the
    actual c/a and k and flags inconsistent or failed cases), coloured by
    c/a; a dot marks the stick edge xi = c/a on each shear curve. The Hertz
    pressure sqrt(1 - xi^2) is the dashed reference. The axes are scaled to
    the converged cases (and Hertz); a not-converged case that leaves them is
    cut, and its extreme value is written on the panel (gid
    ``off-scale-note``).

    Parameters
    ----------
    datasets : xarray.Dataset or sequence of xarray.Dataset
        With ``pressure``, ``shear`` and ``converged``.
    stick_ratios : sequence of float, optional
        Requested c/a values in [0, 1]; by default 1/16, 4/16, 8/16 and
        12/16, values of the paper's scheme (c/a = m/16) that the default
        scenes also hold, so both are compared at the same c/a.

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    ValueError
        If a dataset lacks ``pressure``, ``shear``, ``converged`` or
        ``xi`` (the message names it and the dataset), or ``stick_ratios``
        is empty or out of range.

    Examples
    --------
    >>> import contactlib
    >>> from contactlib.io import to_dataset
    >>> ds = to_dataset(contactlib.sweep("sphere", 0.3, [0.2, 0.6], n=32))
    >>> fig = fig3_tractions(ds, stick_ratios=[0.2, 0.6])
    >>> [ax.get_ylabel() for ax in fig.axes[:2]]
    ['pressure $p/p_0$', 'shear $q/p_0$ (positive outward)']
    """
    requested = _ratios(stick_ratios, "fig3_tractions")
    cases = _cases(datasets, "fig3_tractions", ("pressure", "shear", "converged"),
                   profiles=True)
    chosen = [_nearest(c.stick, requested, np.ones(c.stick.shape, bool)) for c in cases]
    with style_context():
        fig, axes, holders = panel_grid(len(cases), (2.1, 2.1),
                                         max(len(ch) for ch in chosen) + 2)
        for j, (case, picks) in enumerate(zip(cases, chosen)):
            ax_p, ax_q = axes[0, j], axes[1, j]
            xi = np.asarray(case.ds["xi"].values, dtype=float)
            ax_p.plot(xi, hertz_pressure(xi), color="black", lw=1.0, ls="--", zorder=1,
                      label=r"Hertz $\sqrt{1-\xi^2}$")
            converged = case.flag("converged")
            good = [i for i in picks if converged[i]] or picks
            for ax, name, extra in ((ax_p, "pressure", (0.0, 1.0)), (ax_q, "shear", (0.0,))):
                _scale_to(ax, case, name, good, picks, extra)
            for i in picks:
                c = float(case.stick[i])
                color = _ratio_color(c)
                style = _profile_style(bool(converged[i]))
                p = np.asarray(case.ds["pressure"].values[i], dtype=float)
                q = np.asarray(case.ds["shear"].values[i], dtype=float)
                ax_p.plot(xi, p, color=color, label=_case_label(case, i),
                          **style)  # type: ignore[arg-type]
                ax_q.plot(xi, q, color=color, **style)  # type: ignore[arg-type]
                if 0.0 < c < 1.0:
                    _stick_edge(ax_q, c, np.interp(c, xi, q), color)
            ax_p.set_title(_column_title(case))
            ax_q.set_xlabel(f"ξ = {indenter(case.geometry).coordinate}/a")
            ax_p.set_ylabel(r"pressure $p/p_0$")
            ax_q.set_ylabel(r"shear $q/p_0$ (positive outward)")
            ax_p.set_xlim(0.0, 1.0)
            ax_q.axhline(0.0, color="0.6", lw=0.6, zorder=0)
            handles, _ = ax_p.get_legend_handles_labels()
            _legend_below(holders[j], [*handles, _STICK_EDGE_KEY()])
        return finish(fig)


def _scale_to(ax: Axes, case: _Case, name: str, good: Sequence[int], picks: Sequence[int],
              extra: Sequence[float]) -> None:
    """Y limits from the ``good`` cases (5 % margins); note the cases cut off."""
    values = np.asarray(case.ds[name].values, dtype=float)
    shown = np.concatenate([values[i][np.isfinite(values[i])] for i in good] + [extra])
    low, high = float(shown.min()), float(shown.max())
    pad = 0.05 * (high - low or 1.0)
    low, high = low - pad, high + pad
    ax.set_ylim(low, high)
    notes = []
    for i in picks:
        v = values[i][np.isfinite(values[i])]
        if v.size and (v.min() < low or v.max() > high):
            worst = float(v.min()) if v.min() < low else float(v.max())
            notes.append(f"c/a = {float(case.stick[i]):.4g} (not converged): "
                         f"{'down' if worst < low else 'up'} to {worst:.3g} p0")
    if notes:
        text = ax.text(0.02, 0.02, "off the axis:\n" + "\n".join(notes), transform=ax.transAxes,
                       ha="left", va="bottom", fontsize=5.8, zorder=6, gid="off-scale-note",
                       bbox={"boxstyle": "square,pad=0.3", "fc": "white", "ec": "0.8",
                             "alpha": 0.9})
        text.set_in_layout(False)


def _case_label(case: _Case, i: int) -> str:
    """'c/a = 0.3, k = 0.117' plus [inconsistent, NOT CONVERGED] as they apply."""
    label = f"c/a = {float(case.stick[i]):.4g}"
    if "friction_coefficient" in case.ds and not bool(case.flag("converged")[i]) \
            and math.isnan(float(case.values("friction_coefficient")[i])):
        return label + ": no root (not converged), not drawn"
    if "friction_coefficient" in case.ds:
        label += f", k = {k_text(float(case.values('friction_coefficient')[i]))}"
    consistent = bool(case.flag("consistent")[i]) if "consistent" in case.ds else None
    return label + _status(bool(case.flag("converged")[i]), consistent)


def _stick_edge(ax: Axes, c: float, y: float, color: object) -> None:
    ax.plot([c], [y], ls="none", marker="o", ms=3.5, color=color, mec="black", mew=0.5,
            zorder=4)


def _STICK_EDGE_KEY() -> Line2D:  # noqa: N802 - a constant-like factory
    return Line2D([], [], ls="none", marker="o", ms=3.5, color="0.5", mec="black", mew=0.5,
                  label="stick edge ξ = c/a")


def _profile_style(converged: bool) -> dict[str, object]:
    """Solid profile; dotted with crosses (gid ``not-converged``) when failed."""
    if converged:
        return {"ls": "-", "lw": 1.3}
    return {"ls": ":", "lw": 1.3, "marker": "x", "ms": 5, "mew": 1.1, "markevery": 20,
            "gid": NOT_CONVERGED_GID}


# ----------------------------------------------------------------------------- fig 4
_LIMITS = (
    (0.0, "k = 0", "c/a = 0, frictionless", "--"),
    (1.0, "k = ∞", "c/a = 1, full adhesion", "-."),
)


def fig4_displacement(datasets: xr.Dataset | Sequence[xr.Dataset],
                      stick_ratios: Sequence[float] = DEFAULT_STICK_RATIOS) -> Figure:
    """Tangential surface displacement for several stick ratios (the paper's Fig. 4).

    One panel per dataset (more than four wrap into rows,
    :func:`~contactlib.plot.base.panel_grid`): u R/a^2 against xi = r/a (sphere) or x/a
    (cylinder), u positive away from the axis, for the partial-slip stick
    ratios (0 < c/a < 1) of the dataset nearest to the requested ones,
    coloured by c/a, with a dot at the stick edge xi = c/a. The limits are
    drawn in black when the dataset holds them: k = 0 (c/a = 0, frictionless
    Hertz; dashed) and k = inf (c/a = 1, full adhesion; dash-dotted). A
    missing limit is stated in the legend.

    Parameters
    ----------
    datasets : xarray.Dataset or sequence of xarray.Dataset
        With ``tangential_displacement`` and ``converged``.
    stick_ratios : sequence of float, optional
        Requested c/a values in [0, 1].

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    ValueError
        If a dataset lacks ``tangential_displacement``, ``converged`` or
        ``xi`` (the message names it and the dataset), or ``stick_ratios``
        is empty or out of range.

    Examples
    --------
    >>> import contactlib
    >>> from contactlib.io import to_dataset
    >>> ds = to_dataset(contactlib.sweep("sphere", 0.3, [0, 0.5, 1], n=64))
    >>> fig = fig4_displacement(ds)
    >>> [line.get_label() for line in fig.axes[0].lines if line.get_label()[0] != "_"]
    ['c/a = 0.5, k = 0.152', 'k = 0 (c/a = 0, frictionless)', 'k = ∞ (c/a = 1, full adhesion)']
    """
    requested = _ratios(stick_ratios, "fig4_displacement")
    cases = _cases(datasets, "fig4_displacement", ("tangential_displacement", "converged"),
                   profiles=True)
    chosen = [_nearest(c.stick, requested, (c.stick > 0.0) & (c.stick < 1.0)) for c in cases]
    with style_context():
        fig, axes, holders = panel_grid(len(cases), (2.4,),
                                         max(max(len(ch), 1) for ch in chosen) + 3)
        for j, (case, picks) in enumerate(zip(cases, chosen)):
            ax = axes[0, j]
            xi = np.asarray(case.ds["xi"].values, dtype=float)
            u = np.asarray(case.ds["tangential_displacement"].values, dtype=float)
            converged = case.flag("converged")
            for i in picks:
                c = float(case.stick[i])
                color = _ratio_color(c)
                ax.plot(xi, u[i], color=color, label=_case_label(case, i),
                        **_profile_style(bool(converged[i])))  # type: ignore[arg-type]
                _stick_edge(ax, c, np.interp(c, xi, u[i]), color)
            notes: list[Line2D] = []
            if not picks:
                notes.append(Line2D([], [], ls="none",
                                    label="no partial-slip case (0 < c/a < 1) in dataset"))
            for value, name, what, linestyle in _LIMITS:
                hits = np.flatnonzero(case.stick == value)
                if hits.size == 0:
                    notes.append(Line2D([], [], ls="none",
                                        label=f"{name} limit ({what}): not in dataset"))
                    continue
                i = int(hits[0])
                style = _profile_style(bool(converged[i]))
                style.update(lw=1.2, ls=linestyle if converged[i] else ":")
                ax.plot(xi, u[i], color="black", zorder=2,
                        label=f"{name} ({what})" + _status(bool(converged[i]), None),
                        **style)  # type: ignore[arg-type]
            ax.axhline(0.0, color="0.6", lw=0.6, zorder=0)
            ax.set_title(_column_title(case))
            ax.set_xlabel(f"ξ = {indenter(case.geometry).coordinate}/a")
            ax.set_ylabel(r"displacement $u R/a^2$ (positive outward)")
            ax.set_xlim(0.0, 1.0)
            handles, _ = ax.get_legend_handles_labels()
            _legend_below(holders[j], [*handles, *notes, _STICK_EDGE_KEY()])
        return finish(fig)


# ----------------------------------------------------------------------------- fig 5
def fig5_work(datasets: xr.Dataset | Sequence[xr.Dataset]) -> Figure:
    """Frictional work of the loading half-cycle against c/a (the paper's Fig. 5).

    Log-log axes, one panel per geometry present: ``frictional_work``
    V R^2/(E* a^5) (sphere) or V R^2/(E* a^4) per unit length over the whole
    contact (cylinder), loading 0 -> a, against c/a, for every stick ratio
    the data hold. A dotted vertical line marks c/a = 1/16, the smallest
    m/n the paper computed. The V axis is scaled to the converged cases; a
    not-converged case above it is drawn on the top edge (a cross) and its
    value written in the note. Values a log axis cannot show (V <= 0, V NaN,
    c/a = 0) are left out and counted, per dataset, in a text note on the
    panel. (The small-k asymptote :func:`contactlib.model.theory.small_k_work_sphere`
    is not drawn: k falls only like 1/ln(a/c), and at c/a = 0.001 the work
    is still 0.8 of it, so it never meets the curve on these axes.)

    Parameters
    ----------
    datasets : xarray.Dataset or sequence of xarray.Dataset
        With ``frictional_work``, ``consistent`` and ``converged``.

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    ValueError
        If a dataset lacks a needed variable (the message names it and the
        dataset).

    Examples
    --------
    >>> import contactlib
    >>> from contactlib.io import to_dataset
    >>> ds = to_dataset(contactlib.sweep("sphere", 0.3, [0.02, 0.1, 0.5, 1], n=32))
    >>> fig = fig5_work(ds)
    >>> fig.axes[0].get_xscale(), fig.axes[0].get_yscale()
    ('log', 'log')
    """
    cases = _cases(datasets, "fig5_work", ("frictional_work", "consistent", "converged"))
    groups = _by_geometry(cases)
    entries = max(len(members) for _, members in groups) + 2
    with style_context():
        colors = palette()
        ncol = len(groups)
        fig, axes, holders = panel_grid(ncol, (2.5,), entries,
                                         width=7.0 if ncol == 2 else 4.4)
        for j, (geometry, members) in enumerate(groups):
            ax = axes[0, j]
            handles: list[Line2D] = []
            notes: list[str] = []
            shown_x: list[float] = [PAPER_SMALLEST_STICK_RATIO]
            shown_v: list[float] = []  # converged cases: they set the V axis
            failed: list[tuple[_Case, float, float]] = []
            for case in members:
                color, marker, size, x, v, consistent, converged = _series(
                    case, "frictional_work", colors)
                shown = (x > 0) & np.isfinite(v) & (v > 0)
                shown_x += list(x[shown])
                shown_v += list(v[shown & converged])
                failed += [(case, float(a), float(b))
                           for a, b in zip(x[shown & ~converged], v[shown & ~converged])]
                ax.plot(x[shown], v[shown], color=color, zorder=2, **_line_style(case))
                _draw_points(ax, x[shown], v[shown], consistent[shown], marker=marker,
                             color=color, size=size)
                handles.append(_series_key(case, color, marker, size, consistent[shown]))
                note = _skip_note(x, v, converged)
                if note:
                    notes.append(f"{case.label}:\n   {note}")
            handles.append(ax.axvline(PAPER_SMALLEST_STICK_RATIO, color="0.35", lw=1.0,
                                      ls=":", zorder=1,
                                      label="c/a = 1/16, the paper's smallest m/n"))
            ax.set_xscale("log")
            ax.set_yscale("log")
            x_low = min(shown_x) / 1.6
            ax.set_xlim(x_low, 1.0)
            # 1-2-5 labels over up to two decades, decades only beyond that
            subs = (1.0, 2.0, 5.0) if x_low > 0.009 else (1.0,)
            ax.xaxis.set_major_locator(LogLocator(base=10.0, subs=subs))
            ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _pos: f"{v:g}"))
            ax.xaxis.set_minor_formatter(NullFormatter())
            top = max(shown_v) * 4.0 if shown_v else max((f[2] for f in failed), default=1.0)
            for case, xv, vv in failed:  # crosses; on the top edge when above the axis
                _draw_not_converged(ax, np.array([xv]), np.array([min(vv, top)]))
                if vv > top:
                    notes.append(f"{case.label}: not converged at c/a = {xv:.4g},\n"
                                 f"   V = {vv:.3g}, above the axis (cross on the top edge)")
            if shown_v:
                ax.set_ylim(min(shown_v) / 3.0, top)
            else:
                ax.text(0.5, 0.5, "no positive frictional work to show", ha="center",
                        va="center", transform=ax.transAxes)
            if notes:
                note = ax.text(0.02, 0.02, "not on the log axes:\n" + "\n".join(notes),
                               transform=ax.transAxes, ha="left", va="bottom", fontsize=5.6,
                               bbox={"boxstyle": "square,pad=0.3", "fc": "white", "ec": "0.8",
                                     "alpha": 0.9}, zorder=6, gid="skip-note")
                note.set_in_layout(False)
            ax.set_title(_TITLES[geometry], pad=9)  # clear of crosses on the top edge
            ax.set_xlabel("stick ratio c/a (log scale)")
            ax.set_ylabel(_WORK_LABEL[geometry])
            if failed:
                handles.append(Line2D([], [], ls="none", marker="x", ms=7, mew=1.3,
                                      color="black", label="not converged or not resolved"))
            _legend_below(holders[j], handles)
        return finish(fig)


def _skip_note(x: np.ndarray, v: np.ndarray, converged: np.ndarray) -> str:
    """Count the cases a log plot leaves out, by reason; '' when none."""
    nan = np.isnan(v)
    zero = ~nan & (v == 0)
    negative = ~nan & (v < 0)
    at_zero = ~nan & (v > 0) & (x <= 0)
    skipped = nan | zero | negative | at_zero
    if not np.any(skipped):
        return ""
    parts = []
    no_root = nan & ~converged
    for mask, what in ((zero, "V = 0"), (negative, "V < 0"), (nan & converged, "V NaN"),
                       (no_root, "no root"), (at_zero, "at c/a = 0")):
        n = int(mask.sum())
        if n:
            parts.append(f"{what}: {n}")
    text = f"{int(skipped.sum())} not shown ({', '.join(parts)})"
    failed = int((skipped & ~converged & ~no_root).sum())
    if failed:
        text = text[:-1] + f"; {failed} not converged)"
    return text


