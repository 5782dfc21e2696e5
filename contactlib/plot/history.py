"""Figures of a loading history, drawn from the datasets of :func:`contactlib.history`.

Every function takes a history dataset from
:func:`contactlib.io.history_to_dataset` (dimensions ``step`` and ``xi``,
a scalar ``friction_coefficient`` attribute), a stack of them from
:func:`contactlib.io.stack_histories` (a ``friction_coefficient``
dimension on the k-dependent variables; ``load_ratio``, ``segment`` and
``xi_bounds`` without it), or, where stated, a sequence of either, and
returns a new :class:`matplotlib.figure.Figure`. A single history is treated
as a stack of one k, so both forms draw the same curves. Lengths are scaled
by ``a_max``, the frictionless (Hertz) contact radius at load level 1; the
scalings are those of :mod:`contactlib.history_api`.

As for every figure of :mod:`contactlib.plot` (the shared base
:mod:`contactlib.plot.base`), figures are built with
:class:`matplotlib.figure.Figure` directly, never with
:mod:`matplotlib.pyplot`, and drawn inside the contactlib style; the caller's
``rcParams`` are left as they were, the layout is settled and frozen so that
every save gives the same bytes, and nothing here touches the disk (save with
``contactlib.io.write_figure(fig, path, style=style_path())``).

Conventions common to all figures:

* a dataset is labelled by its ``scene`` attribute when present, otherwise
  by its geometry, element count, Poisson's ratio, (cylinder) a_max/h and
  steps a segment;
* a step with ``converged`` false is always drawn and marked by a black
  cross (matplotlib ``gid`` ``"not-converged"``);
* in :func:`hist_stick_radius`, a converged step whose stick radius is not
  resolved (``stick_radius_error_estimate`` above the dataset's
  ``max_error``, in a_max) carries a hollow circle on its curve (``gid``
  ``"stick-radius-unresolved"``), as unresolved self-similar cases are
  hollow in the paper's figures;
* the drawn data carry a ``gid`` naming what they are (``"stick-radius"``,
  ``"contact-radius"``, ``"load"``, ``"segment-end"``, ``"state-map"``,
  ``"displacement-loop"``, ``"cycle-energy"``, ``"doubled-loading"``,
  ``"energy-ratio"``), so that the plotted numbers can be read back;
* a variable a figure needs but a dataset lacks raises :class:`ValueError`
  naming the variable and the dataset.

Examples
--------
>>> from contactlib import history
>>> from contactlib.io import history_to_dataset
>>> from contactlib.plot import hist_stick_radius
>>> ds = history_to_dataset(history("sphere", 0.3, 0.2, [0, 1, 0], 10, n=60))
>>> fig = hist_stick_radius(ds)
>>> fig.axes[1].get_ylabel()
'radius over $a_{max}$'
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from numbers import Real

import matplotlib
import numpy as np
import xarray as xr
from matplotlib.axes import Axes
from matplotlib.colors import BoundaryNorm, ListedColormap
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from matplotlib.ticker import FixedLocator, FuncFormatter, NullFormatter, NullLocator

from contactlib.model.indenter import indenter
from contactlib.validate import GEOMETRIES
from contactlib.plot.base import (
    MARKERS,
    NOT_CONVERGED_GID,
    as_list,
    describe,
    finish,
    fmt,
    k_text,
    label_of,
    palette,
    panel_grid,
    style_context,
)

__all__ = [
    "hist_displacement_loop",
    "hist_energy_per_cycle",
    "hist_stick_map",
    "hist_stick_radius",
]

_GEOMETRIES = GEOMETRIES
_K = "friction_coefficient"
_SHARED = ("load_ratio", "segment", "xi_bounds")  # the path and the mesh: no k in them
_ENERGY_LABEL = {
    "sphere": r"energy per cycle $V R^2/(E^* a_{max}^5)$",
    "cylinder": r"energy per cycle $V R^2/(E^* a_{max}^4)$, per unit length",
}
_STATES = (
    ("separated", "#EEEEEE"),
    ("stick", "#0072B2"),
    ("slip toward the axis", "#E69F00"),
    ("slip away from the axis", "#CC79A7"),
)
# convention: most state-map panels in one figure
_MAX_MAP_PANELS = 4
# convention: the line styles of the history figures (points on, off)
_DASHES = ((3.0, 1.5), (1.2, 1.2), (5.0, 1.5, 1.2, 1.5))
_CROSS = {"ls": "none", "marker": "x", "ms": 6, "mew": 1.2, "color": "black"}


# ----------------------------------------------------------------------------- datasets
@dataclass(frozen=True)
class _History:
    """One history dataset, with k always a (sorted) dimension."""

    index: int
    ds: xr.Dataset
    geometry: str
    label: str
    description: str
    ks: np.ndarray

    def values(self, name: str) -> np.ndarray:
        """``name`` with k first: shape (k, step) or (k, step, xi)."""
        da = self.ds[name]
        if _K not in da.dims:
            da = da.expand_dims({_K: self.ks})
        return np.asarray(da.transpose(_K, ...).values)

    def path(self, name: str) -> np.ndarray:
        """A variable of the load path (``load_ratio``, ``segment``), 1-D over steps."""
        da = self.ds[name]
        if _K in da.dims:
            da = da.isel({_K: 0})
        return np.asarray(da.values)

    @property
    def steps(self) -> np.ndarray:
        if "step" in self.ds.coords:
            return np.asarray(self.ds["step"].values, dtype=float)
        return np.arange(self.ds.sizes["step"], dtype=float)

    @property
    def travel(self) -> np.ndarray:
        """Path coordinate: the load travelled so far, sum of abs(ΔP)/P_max."""
        load = self.path("load_ratio").astype(float)
        return np.concatenate([[0.0], np.cumsum(np.abs(np.diff(load)))])

    def along(self, x: str) -> np.ndarray:
        """The x values of the steps: ``"step"`` or ``"travel"``."""
        return self.travel if x == "travel" else self.steps

    @property
    def levels(self) -> np.ndarray:
        return np.atleast_1d(np.asarray(self.ds.attrs["load_path"], dtype=float))


def _history(ds: xr.Dataset, index: int, figure: str, required: Sequence[str],
             attrs: Sequence[str] = ()) -> _History:
    """Validate one history dataset for ``figure``; a single k becomes a stack of one."""
    description = describe(ds, "geometry", slab_name="a_max/h", steps=True)
    label, where = label_of(ds, index, description)
    geometry = ds.attrs.get("geometry")
    if geometry not in _GEOMETRIES:
        raise ValueError(f"{figure}: {where} has geometry attribute {geometry!r}, "
                         f"expected one of {_GEOMETRIES}")
    if "step" not in ds.dims:
        raise ValueError(f"{figure}: {where} has no 'step' dimension; "
                         f"expected a loading history (contactlib.history)")
    for name in attrs:
        if name not in ds.attrs:
            raise ValueError(f"{figure}: {where} lacks the attribute {name!r}")
    for name in required:
        if name not in ds.variables:
            raise ValueError(f"{figure}: variable {name!r} is absent from {where}; "
                             f"the history that produced it did not store {name!r}")
    if _K in ds.dims:
        ds = ds.sortby(_K)
    else:
        if _K not in ds.attrs:
            raise ValueError(f"{figure}: {where} has neither a {_K!r} dimension nor a "
                             f"{_K!r} attribute")
        k = float(ds.attrs[_K])
        ds = ds.assign({name: ds[name].expand_dims({_K: [k]})
                        for name in ds.data_vars if name not in _SHARED})
        ds = ds.assign_coords({_K: [k]})
    return _History(index=index, ds=ds, geometry=str(geometry), label=label,
                    description=description,
                    ks=np.asarray(ds[_K].values, dtype=float))


def _histories(datasets: xr.Dataset | Sequence[xr.Dataset], figure: str,
               required: Sequence[str], attrs: Sequence[str] = ()) -> list[_History]:
    return [_history(ds, i, figure, required, attrs)
            for i, ds in enumerate(as_list(datasets))]


# ----------------------------------------------------------------------------- helpers
def _surface(h: _History) -> str:
    ind = indenter(h.geometry)
    slab = float(h.ds.attrs.get("slab_ratio", 0.0))
    body = f"slab, a_max/h = {fmt(slab)}" if slab else ind.half_space_name
    return f"{ind.name} on an elastic {body}" + (" (plane strain)" if ind.plane_strain else "")


def _path_text(h: _History) -> str:
    if "load_path" not in h.ds.attrs:
        return "load path not recorded"
    return "P/P_max " + " → ".join(fmt(float(v)) for v in h.levels)


def _title(h: _History) -> str:
    head = h.label if h.label != h.description else _surface(h)
    return f"{head}\n{h.description}\n{_path_text(h)}"


def _curve_colors(count: int) -> list[object]:
    """Okabe-Ito colours while they last, evenly spaced viridis beyond."""
    cycle = palette()
    if count <= len(cycle):
        return list(cycle[:count])
    cmap = matplotlib.colormaps["viridis"]
    return [cmap(v) for v in np.linspace(0.0, 0.88, count)]


def _distinct_colors(count: int) -> list[object]:
    """Like :func:`_curve_colors`, without the light blue that reads as a second blue."""
    cycle = [c for c in palette() if c.lower().lstrip("#") != "56b4e9"]
    if count <= len(cycle):
        return list(cycle[:count])
    return _curve_colors(count)


def _curve_label(h: _History, k: float, converged: np.ndarray, several: bool) -> str:
    label = f"k = {k_text(k)}"
    if several:
        label = f"{h.label}: {label}"
    failed = int(np.count_nonzero(~converged))
    if failed:
        label += f" [NOT CONVERGED at {failed} step{'s' if failed > 1 else ''}]"
    return label


def _crosses(ax: Axes, x: np.ndarray, y: np.ndarray) -> None:
    """Black crosses (gid ``not-converged``) at the finite points given."""
    keep = np.isfinite(x) & np.isfinite(y)
    if np.any(keep):
        ax.plot(x[keep], y[keep], zorder=5, clip_on=False, gid=NOT_CONVERGED_GID,
                **_CROSS)  # type: ignore[arg-type]


def _cross_key() -> Line2D:
    return Line2D([], [], label="step not converged (kept)", **_CROSS)  # type: ignore[arg-type]


_HOLLOW = {"ls": "none", "marker": "o", "ms": 3.2, "mew": 0.8, "mfc": "white"}


def _stick_unresolved(h: _History) -> np.ndarray | None:
    """(k, step): converged steps whose stick radius's estimate exceeds ``max_error``; None
    for a dataset without the estimate (or its ``max_error``)."""
    if "stick_radius_error_estimate" not in h.ds or "max_error" not in h.ds.attrs:
        return None
    est = h.values("stick_radius_error_estimate").astype(float)
    with np.errstate(invalid="ignore"):
        return (est > float(h.ds.attrs["max_error"])) & h.values("converged").astype(bool)


def _segment_ends(h: _History, along: str = "step") -> np.ndarray:
    """x values (step or travel) at which a path segment ends (all but the last)."""
    segment = h.path("segment")
    change = np.flatnonzero(np.diff(segment) != 0)
    return h.along(along)[change[1:]] if change.size else change.astype(float)


def _distinct_paths(members: Sequence[_History], along: str = "step") -> list[list[_History]]:
    """Datasets grouped by their (x, load ratio) path, in order of appearance."""
    groups: list[list[_History]] = []
    for h in members:
        x, p = h.along(along), h.path("load_ratio")
        for group in groups:
            if np.array_equal(x, group[0].along(along)) and np.array_equal(p, group[0].path(
                    "load_ratio")):
                group.append(h)
                break
        else:
            groups.append([h])
    return groups


def _load_panel(ax: Axes, members: Sequence[_History], along: str = "step") -> list[Line2D]:
    """Load ratio against step (or travel) for each distinct path (the first in black).

    Returns legend handles naming the datasets of each path when there are
    several paths, none otherwise.
    """
    groups = _distinct_paths(members, along)
    lines: list[Line2D] = []
    for g, group in enumerate(groups):
        style = {"color": "black", "lw": 1.1} if g == 0 else {
            "color": "0.45", "lw": 1.0, "dashes": _DASHES[(g - 1) % len(_DASHES)]}
        names = ", ".join(h.label for h in group)
        (line,) = ax.plot(group[0].along(along), group[0].path("load_ratio").astype(float),
                          gid="load", label=f"load path of {names}",
                          **style)  # type: ignore[arg-type]
        lines.append(line)
    ax.set_ylim(-0.06, 1.1)
    ax.set_ylabel("load\n$P/P_{max}$")
    return lines if len(groups) > 1 else []


def _mark_segments(axes: Sequence[Axes], members: Sequence[_History],
                   along: str = "step") -> None:
    ends = sorted({float(s) for h in members for s in _segment_ends(h, along)})
    for ax in axes:
        for s in ends:
            ax.axvline(s, color="0.55", lw=0.6, ls=":", zorder=0, gid="segment-end")


def _legend(holder: Axes, handles: Sequence[object], ncols: int) -> None:
    holder.legend(handles=handles, loc="upper center", borderaxespad=0.0, ncols=ncols)


def _legend_rows(entries: int, ncols: int) -> int:
    return math.ceil(max(entries, 1) / ncols)


# convention: a layout size at the style's legend font (inches)
_CHAR_IN = 0.052  # mean width of a legend character at the style's 6.5 pt, inches
# convention: a layout size at the style's legend font (inches)
_HANDLE_IN = 0.5  # legend handle, its padding and the column spacing, inches


def _legend_columns(labels: Sequence[str], width: float, most: int) -> int:
    """Legend columns (at most ``most``) whose estimated width fits ``width`` inches."""
    longest = max((len(line) for label in labels for line in label.split("\n")), default=1)
    fits = int((width - 0.4) // (_HANDLE_IN + _CHAR_IN * longest))
    return max(1, min(most, fits))


# ----------------------------------------------------------------------------- stick radius
def hist_stick_radius(datasets: xr.Dataset | Sequence[xr.Dataset]) -> Figure:
    """Stick-zone and contact radius along the load path.

    Two panels sharing the x axis, the path coordinate: the load travelled
    so far, the sum of abs(ΔP)/P_max over the steps (so datasets with
    different steps a segment line up: 0 -> 1 is 0 ... 1 for all). On top
    the load P/P_max (one black line for the path; a different path of a
    further dataset is grey and dashed, named in that panel's legend),
    below the radius of the central stick zone c/a_max = ``stick_ratio`` ×
    ``contact_radius`` (solid) and the contact radius a/a_max (dashed,
    thinner), one colour per k and per dataset (Okabe-Ito without its
    light blue, so no two curves are close blues). Dotted vertical lines
    mark the ends of the path segments. c is missing (a gap in the line)
    where there is no contact (``stick_ratio`` NaN); the radius axis
    starts just below zero so that a stick zone of almost zero radius stays
    visible.

    Parameters
    ----------
    datasets : xarray.Dataset or sequence of xarray.Dataset
        Histories or stacks of histories with ``stick_ratio``,
        ``contact_radius``, ``load_ratio``, ``segment`` and ``converged``.

    Returns
    -------
    matplotlib.figure.Figure
        Axes: the load panel, the radius panel, an axis-free legend holder.

    Raises
    ------
    ValueError
        If a dataset lacks a needed variable or attribute (the message names
        it and the dataset) or has an unknown geometry.

    Examples
    --------
    >>> from contactlib import history
    >>> from contactlib.io import history_to_dataset
    >>> ds = history_to_dataset(history("sphere", 0.3, 0.2, [0, 1], 5, n=40))
    >>> fig = hist_stick_radius(ds)
    >>> [line.get_label() for line in fig.axes[1].lines if line.get_gid() == "stick-radius"]
    ['k = 0.2']
    """
    members = _histories(datasets, "hist_stick_radius",
                         ("stick_ratio", "contact_radius", "load_ratio", "segment", "converged"))
    several = len(members) > 1
    curves = sum(h.ks.size for h in members)
    any_failed = any(not np.all(h.values("converged")) for h in members)
    unresolved = [_stick_unresolved(h) for h in members]
    any_unresolved = any(u is not None and u.any() for u in unresolved)
    entries = curves + 2 + int(any_failed) + int(any_unresolved)
    width = 6.4 if several else 5.6
    labels = [_curve_label(h, float(k), ok, several)
              for h in members for k, ok in zip(h.ks, h.values("converged").astype(bool))]
    labels += ["stick-zone radius c/a_max (c/a × a/a_max)"]
    ncols = 1 if entries <= 6 else _legend_columns(labels, width, 2)
    with style_context():
        colors = _distinct_colors(curves)
        fig, axes, holders = panel_grid(1, (0.85, 2.5), _legend_rows(entries, ncols),
                                         width=width)
        ax_p, ax = axes[0, 0], axes[1, 0]
        path_handles = _load_panel(ax_p, members, "travel")
        if path_handles:
            ax_p.legend(handles=path_handles, loc="upper right", fontsize=5.8,
                        borderaxespad=0.3)
        _mark_segments((ax_p, ax), members, "travel")
        handles: list[Line2D] = []
        n = 0
        for h in members:
            x = h.travel
            a_all = h.values("contact_radius").astype(float)
            c_all = h.values("stick_ratio").astype(float) * a_all
            ok_all = h.values("converged").astype(bool)
            for i, k in enumerate(h.ks):
                color = colors[n]
                n += 1
                label = _curve_label(h, float(k), ok_all[i], several)
                # the first dataset on top where two coincide (same k, same path so far)
                z = 2.5 - 0.1 * h.index
                (line,) = ax.plot(x, c_all[i], color=color, lw=1.4, label=label,
                                  gid="stick-radius", zorder=z)
                ax.plot(x, a_all[i], color=color, lw=0.9, dashes=(4.0, 2.0),
                        gid="contact-radius", zorder=z)
                bad = ~ok_all[i]
                _crosses(ax, x[bad], c_all[i][bad])
                _crosses(ax, x[bad], a_all[i][bad])
                loose = unresolved[h.index]
                if loose is not None and loose[i].any():
                    ax.plot(x[loose[i]], c_all[i][loose[i]], color=color, zorder=z + 0.05,
                            gid="stick-radius-unresolved", **_HOLLOW)  # type: ignore[arg-type]
                handles.append(line)
        handles += [
            Line2D([], [], color="0.35", lw=1.4,
                   label="stick-zone radius c/a_max (c/a × a/a_max)"),
            Line2D([], [], color="0.35", lw=0.9, dashes=(4.0, 2.0),
                   label="contact radius a/a_max"),
        ]
        if any_unresolved:
            handles.append(Line2D([], [], color="0.35", label="stick radius not resolved "
                                  "to max_error", **_HOLLOW))  # type: ignore[arg-type]
        if any_failed:
            handles.append(_cross_key())
        ax.set_ylim(bottom=-0.03)
        ax.set_xlim(0.0, max(float(h.travel[-1]) for h in members))
        ax.set_xlabel("path coordinate: load travelled, Σ |ΔP|/P_max "
                      "(dotted: end of a path segment)")
        ax.set_ylabel("radius over $a_{max}$")
        ax_p.set_title(_title(members[0]) if not several
                       else "stick-zone and contact radius along the load path")
        _legend(holders[0], handles, ncols)
        return finish(fig)


# ----------------------------------------------------------------------------- state map
def _friction_choice(friction: float | None, ks: np.ndarray) -> list[int]:
    if friction is None:
        if ks.size > _MAX_MAP_PANELS:
            raise ValueError(
                f"hist_stick_map: the stack holds {ks.size} friction coefficients "
                f"({', '.join(k_text(float(k)) for k in ks)}); at most "
                f"{_MAX_MAP_PANELS} are drawn as panels: choose one with friction=")
        return list(range(ks.size))
    if isinstance(friction, bool) or not isinstance(friction, Real) or math.isnan(friction) \
            or float(friction) < 0:
        raise ValueError(f"hist_stick_map: friction must be a number >= 0 (inf allowed), "
                         f"got {friction!r}")
    f = float(friction)
    if math.isinf(f):
        hits = np.flatnonzero(np.isinf(ks))
        return [int(hits[0]) if hits.size else int(np.argmax(ks))]
    with np.errstate(invalid="ignore"):
        distance = np.where(np.isinf(ks), np.inf, np.abs(ks - f))
    return [int(np.argmin(distance))]


def hist_stick_map(dataset: xr.Dataset, *, friction: float | None = None) -> Figure:
    """Element state (separated, stick, slip inward, slip outward) over step and r/a_max.

    A load panel (P/P_max against step) on top, then one map per friction
    coefficient: the ``state`` of every element at the end of every step as
    an image over (step, xi = r/a_max or x/a_max), cells bounded by the
    element edges ``xi_bounds`` and by step ± 1/2, in four discrete colours
    (legend below). The contact radius a/a_max (solid black; resolved below
    the element size) and the stick-zone radius c/a_max (dotted black) are
    drawn over the map; each map is headed by its k. Non-converged steps get
    a cross near the top edge.

    Parameters
    ----------
    dataset : xarray.Dataset
        One history or a stack of histories, with ``state``, ``xi_bounds``,
        ``contact_radius``, ``stick_ratio``, ``load_ratio``, ``segment`` and
        ``converged``.
    friction : float, optional
        For a stack: the k to draw (the nearest one held). By default every
        k of the stack gets a panel, up to four.

    Returns
    -------
    matplotlib.figure.Figure
        Axes: the load panel, one map per k drawn, an axis-free legend holder.

    Raises
    ------
    ValueError
        If the dataset lacks a needed variable (named in the message), if
        ``friction`` is not a number >= 0, or if a stack of more than four k
        is given without ``friction``.

    Examples
    --------
    >>> from contactlib import history
    >>> from contactlib.io import history_to_dataset
    >>> ds = history_to_dataset(history("sphere", 0.3, 0.2, [0, 1, 0], 5, n=40))
    >>> fig = hist_stick_map(ds)
    >>> len(fig.axes)  # load, map, legend holder
    3
    """
    if not isinstance(dataset, xr.Dataset):
        raise TypeError(f"hist_stick_map: dataset must be an xarray.Dataset, "
                        f"got {type(dataset).__name__}")
    h = _history(dataset, 0, "hist_stick_map",
                 ("state", "xi_bounds", "contact_radius", "stick_ratio", "load_ratio",
                  "segment", "converged"))
    picks = _friction_choice(friction, h.ks)
    any_failed = any(not np.all(h.values("converged")[i]) for i in picks)
    entries = len(_STATES) + 2 + int(any_failed)
    with style_context():
        fig, axes, holders = panel_grid(1, (0.8, *([1.75] * len(picks))),
                                         _legend_rows(entries, 3), width=6.0)
        _load_panel(axes[0, 0], [h])
        _mark_segments([axes[0, 0]], [h])
        x = h.steps
        x_edges = np.concatenate([x - 0.5, [x[-1] + 0.5]])
        bounds = np.asarray(h.ds["xi_bounds"].values, dtype=float)
        xi_edges = np.concatenate([bounds[:, 0], bounds[-1:, 1]])
        cmap = ListedColormap([color for _, color in _STATES], name="contact-state")
        norm = BoundaryNorm(np.arange(len(_STATES) + 1) - 0.5, cmap.N)
        state = h.values("state")
        a_all = h.values("contact_radius").astype(float)
        c_all = h.values("stick_ratio").astype(float) * a_all
        ok_all = h.values("converged").astype(bool)
        top = min(float(xi_edges[-1]), 1.15 * max(float(np.nanmax(a_all[picks])), 0.1))
        for row, i in enumerate(picks, start=1):
            ax = axes[row, 0]
            ax.pcolormesh(x_edges, xi_edges, state[i].T.astype(float), cmap=cmap, norm=norm,
                          shading="flat", gid="state-map",
                          rasterized=True)  # PDF: one image, not 10^5 cells
            ax.plot(x, a_all[i], color="black", lw=0.9, gid="contact-radius")
            ax.plot(x, c_all[i], color="black", lw=1.0, ls=":", gid="stick-radius")
            bad = ~ok_all[i]
            _crosses(ax, x[bad], np.full(int(bad.sum()), 0.94 * top))
            ax.grid(False)
            ax.set_ylim(0.0, top)
            ax.set_xlim(x_edges[0], x_edges[-1])
            ax.set_ylabel(f"ξ = {indenter(h.geometry).coordinate}/$a_{{max}}$")
            text = f"k = {k_text(float(h.ks[i]))}"
            if bad.any():
                text += f"  [NOT CONVERGED at {int(bad.sum())} steps]"
            ax.set_title(text, loc="left", fontsize=7.5, pad=2)
        axes[-1, 0].set_xlabel("load step (dotted on top: end of a path segment)")
        axes[0, 0].set_title(f"element contact state along the path\n{_title(h)}")
        handles: list[object] = [Patch(facecolor=color, edgecolor="0.5", label=name)
                                 for name, color in _STATES]
        handles += [Line2D([], [], color="black", lw=0.9, label="contact radius a/a_max"),
                    Line2D([], [], color="black", lw=1.0, ls=":",
                           label="stick-zone radius c/a_max")]
        if any_failed:
            handles.append(_cross_key())
        _legend(holders[0], handles, 3)
        return finish(fig)


# ----------------------------------------------------------------------------- displacement loop
def _arrow(ax: Axes, x: np.ndarray, y: np.ndarray, i: int, color: object) -> None:
    """Arrow head at point ``i + 1`` pointing along the path from point ``i``.

    A filled head with a thin white rim, large enough to read over the curves.
    """
    if not (np.isfinite(x[i:i + 2]).all() and np.isfinite(y[i:i + 2]).all()):
        return
    if x[i] == x[i + 1] and y[i] == y[i + 1]:
        return
    ax.annotate("", xy=(x[i + 1], y[i + 1]), xytext=(x[i], y[i]),
                arrowprops={"arrowstyle": "-|>,head_length=0.55,head_width=0.3",
                            "fc": color, "ec": "white", "lw": 0.4,
                            "mutation_scale": 14, "shrinkA": 0.0, "shrinkB": 0.0},
                zorder=4, annotation_clip=False, gid="direction-arrow")


def hist_displacement_loop(datasets: xr.Dataset | Sequence[xr.Dataset], *,
                           xi: float = 0.8) -> Figure:
    """Tangential displacement at one point against the load, over the whole path.

    One panel per dataset: ``tangential_displacement`` u R/a_max^2 (positive
    away from the axis) of the element whose midpoint is nearest to
    ``xi`` = r/a_max (sphere) or x/a_max (cylinder), against the load
    P/P_max, one curve per k, in order of the steps; an arrow head in the
    inner part of every path segment shows the direction of travel (loading:
    rightwards, unloading: leftwards; staggered from curve to curve), and an
    open circle marks the start of the path. The panel title gives the scene,
    the path and the element midpoint actually used (asked for: ``xi``);
    the legend title gives n, ν and the steps a segment.

    Parameters
    ----------
    datasets : xarray.Dataset or sequence of xarray.Dataset
        Histories or stacks with ``tangential_displacement``, ``load_ratio``,
        ``segment``, ``state`` and ``converged``.
    xi : float, optional
        Requested position over a_max, within the mesh (0 ... the last
        element edge).

    Returns
    -------
    matplotlib.figure.Figure
        Axes: one panel per dataset, then one axis-free legend holder each.

    Raises
    ------
    ValueError
        If a dataset lacks a needed variable (named in the message) or
        ``xi`` is not a number inside the mesh.

    Examples
    --------
    >>> from contactlib import history
    >>> from contactlib.io import history_to_dataset
    >>> ds = history_to_dataset(history("sphere", 0.3, 0.2, [0, 1, 0], 5, n=40))
    >>> fig = hist_displacement_loop(ds, xi=0.5)
    >>> fig.axes[0].get_xlabel()
    'load $P/P_{max}$'
    """
    if isinstance(xi, bool) or not isinstance(xi, Real) or not math.isfinite(xi):
        raise ValueError(f"hist_displacement_loop: xi must be a finite number, got {xi!r}")
    members = _histories(datasets, "hist_displacement_loop",
                         ("tangential_displacement", "load_ratio", "segment", "state",
                          "converged", "xi"))
    picks: list[int] = []
    for h in members:
        mid = np.asarray(h.ds["xi"].values, dtype=float)
        bounds = (np.asarray(h.ds["xi_bounds"].values, dtype=float)
                  if "xi_bounds" in h.ds else None)
        end = float(bounds[-1, 1]) if bounds is not None else float(mid[-1])
        if not 0.0 <= float(xi) <= end:
            raise ValueError(f"hist_displacement_loop: xi = {xi!r} is outside the mesh of "
                             f"dataset {h.index} ({h.label!r}): 0 ... {fmt(end)}")
        picks.append(int(np.argmin(np.abs(mid - float(xi)))))
    any_failed = any(not np.all(h.values("converged")) for h in members)
    entries = max(h.ks.size for h in members) + 2 + int(any_failed)
    with style_context():
        fig, axes, holders = panel_grid(len(members), (2.6,), entries,
                                         width=max(4.4, 0.7 + 3.7 * len(members)))
        for col, (h, j) in enumerate(zip(members, picks)):
            ax = axes[0, col]
            colors = _curve_colors(h.ks.size)
            p = h.path("load_ratio").astype(float)
            segment = h.path("segment")
            u_all = h.values("tangential_displacement").astype(float)[:, :, j]
            ok_all = h.values("converged").astype(bool)
            used = float(h.ds["xi"].values[j])
            handles: list[Line2D] = []
            for i, k in enumerate(h.ks):
                u = u_all[i]
                (line,) = ax.plot(p, u, color=colors[i], lw=1.3, gid="displacement-loop",
                                  label=_curve_label(h, float(k), ok_all[i], False))
                ax.plot(p[:1], u[:1], ls="none", marker="o", ms=4, mfc="white",
                        mec=colors[i], zorder=4)
                # arrows staggered along each segment, so the curves' arrows do not
                # sit on top of one another where the curves meet
                spot = 0.3 + 0.4 * (i + 0.5) / h.ks.size
                for s in np.unique(segment[segment > 0]):
                    where = np.flatnonzero(segment == s)
                    m = int(where[min(int(spot * where.size), where.size - 1)])
                    _arrow(ax, p, u, m - 1, colors[i])
                bad = ~ok_all[i]
                _crosses(ax, p[bad], u[bad])
                handles.append(line)
            handles += [
                Line2D([], [], color="0.35", lw=1.3, marker=">", ms=5,
                       label="arrow: direction of travel (→ loading, ← unloading)"),
                Line2D([], [], ls="none", marker="o", ms=4, mfc="white", mec="0.35",
                       label="start of the path"),
            ]
            if not ok_all.all():
                handles.append(_cross_key())
            axis = indenter(h.geometry).coordinate
            note = f"u at {axis}/a_max = {used:.4g}"
            if not np.any(h.values("state")[:, :, j] > 0):
                note += ", never in contact"
            head = h.label if h.label != h.description else _surface(h)
            ax.set_title(f"{head}: {_path_text(h)}\n{note}")
            ax.axhline(0.0, color="0.6", lw=0.6, zorder=0)
            ax.set_xlim(-0.02, 1.02)
            ax.set_xlabel("load $P/P_{max}$")
            ax.set_ylabel(r"displacement $u R/a_{max}^2$ (positive outward)")
            holders[col].legend(handles=handles, loc="upper center", borderaxespad=0.0,
                                title=h.description if h.label != h.description else None)
        return finish(fig)


# ----------------------------------------------------------------------------- energy
@dataclass(frozen=True)
class _Energy:
    """Energy per cycle of one dataset, one entry per k."""

    ks: np.ndarray
    cycle: np.ndarray       # work over the last two segments
    doubled: np.ndarray     # 2 x work of the first (loading) segment
    cycle_ok: np.ndarray    # every step up to the end of the path converged
    doubled_ok: np.ndarray  # every step of the first segment converged
    start: int              # step index at which the last cycle starts
    cycle_text: str


def _energy(h: _History) -> _Energy:
    levels = h.levels
    where = f"dataset {h.index} ({h.label!r})"
    if levels.size < 3:
        raise ValueError(
            f"hist_energy_per_cycle: {where} has the load path "
            f"{[float(v) for v in levels]} with fewer than 3 levels: it holds no cycle "
            f"(one loading and one unloading segment)")
    d1, d2 = levels[-2] - levels[-3], levels[-1] - levels[-2]
    if not d1 * d2 < 0:
        raise ValueError(
            f"hist_energy_per_cycle: {where}: the last two segments of the load path "
            f"{[float(v) for v in levels]} are not one loading and one unloading segment")
    segment = h.path("segment")
    count = levels.size - 1
    if int(segment.max()) != count:
        raise ValueError(f"hist_energy_per_cycle: {where}: variable 'segment' ends at "
                         f"{int(segment.max())}, the load path has {count} segments")
    start = int(np.flatnonzero(segment <= count - 2).max())  # end of segment count - 2
    first_end = int(np.flatnonzero(segment <= 1).max())      # end of segment 1
    work = h.values("frictional_work").astype(float)
    ok = h.values("converged").astype(bool)
    return _Energy(
        ks=h.ks, cycle=work[:, -1] - work[:, start],
        doubled=2.0 * (work[:, first_end] - work[:, 0]),
        cycle_ok=ok.all(axis=1), doubled_ok=ok[:, : first_end + 1].all(axis=1),
        start=start,
        cycle_text=" → ".join(fmt(float(v)) for v in levels[-3:]))


def _log_shown(k: np.ndarray, v: np.ndarray) -> np.ndarray:
    return np.isfinite(k) & (k > 0) & np.isfinite(v) & (v > 0)


def hist_energy_per_cycle(datasets: xr.Dataset | Sequence[xr.Dataset]) -> Figure:
    """Energy dissipated per load cycle against the friction coefficient k.

    One column per geometry present (sphere, then cylinder), log-log axes.
    For each dataset (one series, one colour; each k of a stack one point):
    the frictional work over the last two path segments, which form the last
    load cycle (one loading and one unloading segment, e.g. the whole path
    0 -> 1 -> 0, or the steady loop 1 -> 0.5 -> 1 ... of
    [0, 1, 0.5, 1, 0.5]: solid line, filled markers), and twice the work of
    the first, loading, segment (the paper's "double the half-cycle"
    estimate: dashed line, open markers). A panel below gives their ratio
    (estimate / cycle; 1 is exact). Points a log axis cannot show (k = 0,
    k = inf, work <= 0 or NaN) are left out and counted in a note.

    Parameters
    ----------
    datasets : xarray.Dataset or sequence of xarray.Dataset
        Histories or stacks of histories (e.g. one per scene) with
        ``frictional_work``, ``segment`` and ``converged`` and the
        ``load_path`` attribute.

    Returns
    -------
    matplotlib.figure.Figure
        Per geometry: the energy panel, the ratio panel and an axis-free
        legend holder. Energy is V R^2/(E* a_max^5) (sphere) or
        V R^2/(E* a_max^4) per unit length over both sides of the axis
        (cylinder).

    Raises
    ------
    ValueError
        If a dataset lacks a needed variable or the ``load_path`` attribute
        (named in the message), or its load path has fewer than 3 levels or
        does not end in one loading and one unloading segment.

    Examples
    --------
    >>> from contactlib import history
    >>> from contactlib.io import history_to_dataset
    >>> ds = history_to_dataset(history("sphere", 0.3, 0.2, [0, 1, 0], 5, n=40))
    >>> fig = hist_energy_per_cycle(ds)
    >>> fig.axes[0].get_xscale(), fig.axes[0].get_yscale()
    ('log', 'log')
    """
    members = _histories(datasets, "hist_energy_per_cycle",
                         ("frictional_work", "segment", "converged"), attrs=("load_path",))
    energies = [_energy(h) for h in members]
    geometries = [g for g in _GEOMETRIES if any(h.geometry == g for h in members)]
    any_failed = any(not (e.cycle_ok.all() and e.doubled_ok.all()) for e in energies)
    entries = 2 * max(sum(h.geometry == g for h in members) for g in geometries) + 4 \
        + int(any_failed)
    with style_context():
        colors = palette()
        ncol = len(geometries)
        fig, axes, holders = panel_grid(ncol, (2.4, 1.1), entries,
                                         width=7.0 if ncol == 2 else 4.6)
        for col, geometry in enumerate(geometries):
            ax, ax_r = axes[0, col], axes[1, col]
            handles: list[Line2D] = []
            notes: list[str] = []
            shown_k: list[float] = []
            shown_v: list[float] = []
            for h, e in zip(members, energies):
                if h.geometry != geometry:
                    continue
                color = colors[h.index % len(colors)]
                marker = MARKERS[h.index % len(MARKERS)]
                k = e.ks
                for values, ok, filled, dashes, gid in (
                        (e.cycle, e.cycle_ok, True, None, "cycle-energy"),
                        (e.doubled, e.doubled_ok, False, (4.0, 2.0), "doubled-loading")):
                    shown = _log_shown(k, values)
                    style: dict[str, object] = {"color": color, "marker": marker, "ms": 4,
                                                "mfc": color if filled else "white",
                                                "mec": color, "lw": 1.3 if filled else 1.0,
                                                "gid": gid}
                    if dashes is not None:
                        style["dashes"] = dashes
                    ax.plot(k[shown], values[shown], **style)  # type: ignore[arg-type]
                    _crosses(ax, k[shown & ~ok], values[shown & ~ok])
                    shown_k += list(k[shown])
                    shown_v += list(values[shown])
                    left = int(np.count_nonzero(~shown))
                    if left:
                        notes.append(f"{h.label} ({'cycle' if filled else '2 × loading'}): "
                                     f"{left} not shown")
                with np.errstate(divide="ignore", invalid="ignore"):
                    ratio = e.doubled / e.cycle
                shown = np.isfinite(k) & (k > 0) & np.isfinite(ratio)
                ax_r.plot(k[shown], ratio[shown], color=color, marker=marker, ms=3.5,
                          lw=1.0, gid="energy-ratio")
                handles.append(Line2D([], [], color=color, marker=marker, ms=4, lw=1.3,
                                      label=f"{h.label}\n    last cycle P/P_max "
                                            f"{e.cycle_text} (steps {e.start}–"
                                            f"{int(h.steps.size - 1)})"))
            handles += [
                Line2D([], [], color="0.35", marker="o", ms=4, lw=1.3,
                       label="work over the last two segments\n    (one load cycle)"),
                Line2D([], [], color="0.35", marker="o", ms=4, mfc="white", lw=1.0,
                       dashes=(4.0, 2.0),
                       label="2 × work of the first loading segment\n"
                             "    (the paper's doubled half-cycle)"),
            ]
            if any_failed:
                handles.append(Line2D([], [], label="point with a non-converged step",
                                      **_CROSS))  # type: ignore[arg-type]
            ax_r.axhline(1.0, color="0.45", lw=0.8, ls="--", zorder=1)
            # a tick and label at every k drawn
            ticks = sorted({float(v) for v in shown_k}) or [0.1]
            for a in (ax, ax_r):
                a.set_xscale("log")
                a.xaxis.set_major_locator(FixedLocator(ticks))
                a.xaxis.set_major_formatter(FuncFormatter(lambda v, _pos: f"{v:g}"))
                a.xaxis.set_minor_locator(NullLocator())
                a.xaxis.set_minor_formatter(NullFormatter())
            ax.set_yscale("log")
            if shown_k:
                ax.set_xlim(min(shown_k) / 1.4, max(shown_k) * 1.4)
                ax.set_ylim(min(shown_v) / 2.0, max(shown_v) * 2.0)
            else:
                ax.text(0.5, 0.5, "no positive frictional work at 0 < k < inf to show",
                        ha="center", va="center", transform=ax.transAxes)
            if notes:
                box = ax.text(0.02, 0.02, "not on the log axes (k = 0, k = inf or work <= 0):\n"
                              + "\n".join(notes), transform=ax.transAxes, ha="left",
                              va="bottom", fontsize=5.6, zorder=6, gid="skip-note",
                              bbox={"boxstyle": "square,pad=0.3", "fc": "white", "ec": "0.8",
                                    "alpha": 0.9})
                box.set_in_layout(False)
            ax.set_title(f"{_surface_of(geometry, members)}\ndissipated energy per load cycle")
            ax.set_ylabel(_ENERGY_LABEL[geometry])
            ax_r.set_ylabel("ratio")
            ax_r.set_title("ratio (2 × work of the first loading) / (work per cycle)",
                           fontsize=6.8, pad=3)
            ax_r.set_xlabel("friction coefficient k (log scale)")
            _legend(holders[col], handles, 1)
        return finish(fig)


def _surface_of(geometry: str, members: Sequence[_History]) -> str:
    """Panel title: the surface when all datasets of a geometry share it."""
    surfaces = {_surface(h) for h in members if h.geometry == geometry}
    if len(surfaces) == 1:
        return surfaces.pop()
    return geometry + (" (plane strain)" if indenter(geometry).plane_strain else "")
