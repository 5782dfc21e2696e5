"""The shared base of every contactlib figure: style, colours, markers, panels, layout.

:mod:`contactlib.plot.paper` (the paper's figures 2-5),
:mod:`contactlib.plot.history` (loading histories) and
:mod:`contactlib.plot.convergence` (error against time) are built on these
names and on nothing private of one another.

Figures are built with :class:`matplotlib.figure.Figure` directly, never with
:mod:`matplotlib.pyplot`, so no backend is selected or needed and no global
figure registry holds on to them. Each figure function draws inside
:func:`style_context` (the caller's ``rcParams`` are left as they were) and
ends with :func:`finish`, which settles and freezes the layout so that every
save gives the same bytes. Nothing here touches the disk except reading the
style file; save with ``contactlib.io.write_figure(fig, path,
style=style_path())``.

Examples
--------
>>> from contactlib.plot.base import panel_grid, style_context, finish
>>> with style_context():
...     fig, axes, holders = panel_grid(2, (2.0,), legend_entries=3)
...     fig = finish(fig)
>>> axes.shape, len(holders)
((1, 2), 2)
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path

import matplotlib
import matplotlib.style
import numpy as np
import xarray as xr
from matplotlib.axes import Axes
from matplotlib.figure import Figure

__all__ = [
    "STYLE_FILE",
    "MARKERS",
    "NOT_CONVERGED_GID",
    "style_path",
    "style_context",
    "fmt",
    "as_list",
    "describe",
    "label_of",
    "palette",
    "k_text",
    "legend_height",
    "panel_grid",
    "MAX_COLUMNS",
    "finish",
]

STYLE_FILE = "contactlib.mplstyle"
MARKERS: tuple[str, ...] = ("o", "s", "D", "h", "p", "8")
"""Marker cycle of series (datasets, studies, histories)."""
NOT_CONVERGED_GID = "not-converged"
"""matplotlib ``gid`` of the black crosses over cases or steps that did not converge."""


# ----------------------------------------------------------------------------- style
def style_path() -> Path:
    """Return the path of the style file bundled with contactlib.

    Returns
    -------
    pathlib.Path
        ``contactlib/plot/contactlib.mplstyle``: DejaVu Sans (ships with
        matplotlib), figure size 7 x 3.2 in, 150 dpi when saved, TrueType
        (type 42) fonts in PDF, fixed SVG hash salt.

    Raises
    ------
    FileNotFoundError
        If the package was installed without its data file.

    Examples
    --------
    >>> from contactlib.plot import style_path
    >>> style_path().name
    'contactlib.mplstyle'
    """
    path = Path(__file__).resolve().with_name(STYLE_FILE)
    if not path.is_file():
        raise FileNotFoundError(f"contactlib style file is missing: {path}")
    return path


@contextmanager
def style_context() -> Iterator[None]:
    """Context in which the contactlib style (:func:`style_path`) is active."""
    with matplotlib.style.context(style_path()):
        yield


def palette() -> list[str]:
    """The colour cycle of the active style (Okabe-Ito inside :func:`style_context`)."""
    return list(matplotlib.rcParams["axes.prop_cycle"].by_key()["color"])


# ----------------------------------------------------------------------------- labels
def fmt(x: float) -> str:
    """Short number for labels (three significant digits)."""
    return f"{x:.3g}"


def k_text(k: float) -> str:
    """A friction coefficient for labels: three significant digits, ∞ and NaN spelled out."""
    if math.isinf(k):
        return "∞" if k > 0 else "−∞"
    if math.isnan(k):
        return "NaN"
    return f"{k:.3g}"


# ----------------------------------------------------------------------------- datasets
def as_list(datasets: xr.Dataset | Sequence[xr.Dataset]) -> list[xr.Dataset]:
    """One dataset or a sequence of them, as a non-empty list of datasets.

    Raises
    ------
    ValueError
        If the sequence is empty.
    TypeError
        If a member is not an :class:`xarray.Dataset` (the message names its index).
    """
    items = [datasets] if isinstance(datasets, xr.Dataset) else list(datasets)
    if not items:
        raise ValueError("datasets must contain at least one xarray.Dataset")
    for i, ds in enumerate(items):
        if not isinstance(ds, xr.Dataset):
            raise TypeError(f"datasets[{i}] is not an xarray.Dataset: {type(ds).__name__}")
    return items


def describe(ds: xr.Dataset, lead: str, slab_name: str = "a/h", steps: bool = False) -> str:
    """Short description of a dataset from its attributes, for labels and messages.

    Parameters
    ----------
    ds : xarray.Dataset
    lead : str
        The attribute named first (``"method"`` for self-similar datasets,
        ``"geometry"`` for histories).
    slab_name : str
        How the slab ratio reads (cylinder only).
    steps : bool
        Add the steps a segment (histories).

    Returns
    -------
    str
        E.g. ``"default, n = 256, ν = 0.3, a/h = 0.05"``.
    """
    attrs = ds.attrs
    parts = [str(attrs.get(lead, "?"))]
    if "elements" in attrs:
        parts.append(f"n = {int(attrs['elements'])}")
    if "poisson_ratio" in attrs:
        parts.append(f"ν = {fmt(float(attrs['poisson_ratio']))}")
    if "slab_ratio" in attrs:  # written for the bodies that may be layers
        parts.append(f"{slab_name} = {fmt(float(attrs.get('slab_ratio', 0.0)))}")
    if steps and "steps" in attrs:
        parts.append(f"{int(attrs['steps'])} steps a segment")
    return ", ".join(parts)


def label_of(ds: xr.Dataset, index: int, description: str) -> tuple[str, str]:
    """Legend label of a dataset (its ``scene``, else ``description``) and its name in errors.

    Returns
    -------
    tuple of str
        ``(label, where)``, ``where`` reading ``dataset <index> ('<label>')``.
    """
    scene = ds.attrs.get("scene")
    label = str(scene) if scene not in (None, "") else description
    return label, f"dataset {index} ({label!r})"


# ----------------------------------------------------------------------------- panels
# convention: a layout size at the style's legend font (inches)
_LEGEND_LINE_IN = 0.12  # height of one legend entry at the style's legend font, inches
# convention: a layout size at the style's legend font (inches)
_LEGEND_PAD_IN = 0.12


def legend_height(entries: int) -> float:
    """Height in inches of a single-column legend of ``entries`` entries."""
    return _LEGEND_PAD_IN + _LEGEND_LINE_IN * max(entries, 1)


# convention: panels side by side before they wrap (tests/test_figures.py)
MAX_COLUMNS = 4
"""Most panels side by side in :func:`panel_grid`; more wrap into rows (bands)."""


def panel_grid(ncol: int, rows_in: Sequence[float], legend_entries: int,
               width: float | None = None,
               max_columns: int = MAX_COLUMNS) -> tuple[Figure, np.ndarray, list[Axes]]:
    """Figure with ``len(rows_in)`` rows of plot panels and a legend row below.

    ``rows_in`` are the plot row heights in inches; the legend row is sized
    for ``legend_entries`` single-column entries. Plot panels share x within
    a column. Returns the figure, the plot axes (rows x columns) and one
    axis-free legend holder per column. ``width`` is in inches (default:
    3.2 in a column plus 0.7 in).

    More than ``max_columns`` (default :data:`MAX_COLUMNS`) columns wrap into
    bands of equal width, ceil(ncol / bands) columns each, every band with its
    own legend row below its panels; column j is still ``axes[:, j]`` and
    ``holders[j]``. A given ``width`` is that of one row of ``ncol`` columns
    and shrinks with the band's share of them.
    """
    legend_in = legend_height(legend_entries)
    bands = -(-ncol // max(1, max_columns))
    per_band = -(-ncol // bands)
    height = bands * (sum(rows_in) + legend_in + 0.35 * len(rows_in) + 0.35)
    if width is None:
        width = max(4.2, 0.7 + 3.2 * per_band)
    elif bands > 1:
        width = max(4.2, width * per_band / ncol)
    fig = Figure(figsize=(width, height), layout="constrained")
    span = len(rows_in) + 1  # grid rows of a band: its plot rows and its legend row
    grid = fig.add_gridspec(span * bands, per_band, height_ratios=[*rows_in, legend_in] * bands)
    axes = np.empty((len(rows_in), ncol), dtype=object)
    holders: list[Axes] = []
    for j in range(ncol):
        band, col = divmod(j, per_band)
        for i in range(len(rows_in)):
            axes[i, j] = fig.add_subplot(grid[band * span + i, col],
                                         sharex=axes[0, j] if i else None)
            if i < len(rows_in) - 1:
                axes[i, j].tick_params(labelbottom=False)
        holder = fig.add_subplot(grid[band * span + len(rows_in), col])
        holder.set_axis_off()
        holders.append(holder)
    return fig, axes, holders


# ----------------------------------------------------------------------------- layout
# convention: draws the frozen layout may take to settle
_SETTLE_DRAWS = 5
# convention: a fiftieth of a pixel at 150 dpi counts as settled
_SETTLE_TOLERANCE = 2e-5  # figure fraction: a fiftieth of a pixel at 150 dpi


def finish(fig: Figure) -> Figure:
    """Settle the constrained layout under the style, then freeze it.

    Constrained layout is not idempotent: each pass starts from the previous
    positions and moves the axes by a shrinking amount. Running the layout
    (at the style's dpi, the saving dpi) until the axes stop moving and then
    fixing the positions makes every later save of the figure render the
    same layout, whatever the format or the number of earlier saves, which
    is what byte-reproducible files need. Ticks are also created here, while
    the style is active.

    Each pass runs the layout engine alone, as a draw would before drawing
    the artists (the same positions, hence the same bytes, as settling by
    ``fig.draw_without_rendering()``), without the draw: the figures of the
    main job settle in 40 % less CPU time (5.5 s -> 3.5 s for the eight
    figures in one process).
    """
    engine = fig.get_layout_engine()
    if engine is None:  # a fixed layout: nothing to settle
        fig.draw_without_rendering()
        return fig
    previous = None
    for _ in range(_SETTLE_DRAWS):
        engine.execute(fig)
        current = np.array([ax.get_position().bounds for ax in fig.axes])
        if previous is not None and np.max(np.abs(current - previous)) < _SETTLE_TOLERANCE:
            break
        previous = current
    fig.set_layout_engine("none")
    return fig
