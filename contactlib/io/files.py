"""Reading and writing files: netCDF datasets, npz arrays, CSV/HTML tables and figures.

Every writer (:func:`write_dataset`, :func:`write_arrays`,
:func:`write_table`, :func:`write_figure`) goes through the one atomic write
of :mod:`contactlib.io.atomic`; the readers (:func:`read_dataset`,
:func:`read_arrays`) verify the content check of
:mod:`contactlib.io.checksums` and read the file whole, so a damaged file is
a :class:`~contactlib.io.checksums.DamagedFileError`, never used.

Examples
--------
>>> import pathlib, tempfile
>>> import numpy as np
>>> with tempfile.TemporaryDirectory() as tmp:
...     path = write_arrays({"a": np.arange(3)}, pathlib.Path(tmp) / "a.npz")
...     back = read_arrays(path)
>>> back["a"].tolist()
[0, 1, 2]
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:  # xarray is imported where a dataset is made or read (start-up time)
    import xarray as xr

from contactlib.io.atomic import atomic_write
from contactlib.io.checksums import (MISSING, NC_CHECKSUM, NPZ_CHECKSUM, arrays_digest,
                                     damaged, dataset_digest)
from contactlib.io.conventions import PROVENANCE, netcdf_encoding

__all__ = ["write_dataset", "read_dataset", "write_arrays", "read_arrays", "write_table",
           "write_figure"]


def write_arrays(arrays: dict[str, np.ndarray], path: str | os.PathLike[str]) -> Path:
    """Write named arrays (an intermediate of the workflow) to ``.npz``, atomically.

    Used for influence matrices and case records between workflow stages.
    Arrays are stored uncompressed (influence matrices do not compress) and
    without pickling: only numeric, boolean and string arrays are allowed.
    A content check goes with them: one more array, ``contactlib_sha256``,
    the SHA-256 of every array's name, dtype, shape and bytes, which
    :func:`read_arrays` verifies.

    Parameters
    ----------
    arrays : dict of str to array_like
    path : str or os.PathLike
        Destination; must end in ``.npz``.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    ValueError
        If the suffix is not ``.npz`` or an array is named ``contactlib_sha256``.
    TypeError
        If an array would need pickling.
    """
    if Path(path).suffix != ".npz":
        raise ValueError(f"path must end in .npz, got {str(path)!r}")
    data = {k: np.asarray(v) for k, v in arrays.items()}
    if NPZ_CHECKSUM in data:
        raise ValueError(f"{NPZ_CHECKSUM!r} is reserved for the content check")
    for k, v in data.items():
        if v.dtype.kind not in "biufUS":
            raise TypeError(f"array {k!r} has dtype {v.dtype}, which needs pickling")
    data[NPZ_CHECKSUM] = np.array(arrays_digest(data))

    def write(tmp: Path) -> None:
        with open(tmp, "wb") as fh:
            np.savez(fh, **data)

    return atomic_write(path, write)


def read_arrays(path: str | os.PathLike[str], *,
                require_checksum: bool = True) -> dict[str, np.ndarray]:
    """Read arrays written by :func:`write_arrays` (no pickles are loaded).

    Every array is read whole and the content check is verified, so a
    truncated, corrupt or changed file (a broken zip directory, a CRC
    mismatch, a short array, an array removed or rewritten) is detected
    here and never used.

    Parameters
    ----------
    path : str or os.PathLike
    require_checksum : bool
        True (default): a file without the content check is refused (every
        file :func:`write_arrays` writes has one). False: a file without one
        (``numpy.savez``, an earlier version) is read unchecked; a check
        that is there is verified all the same.

    Returns
    -------
    dict of str to numpy.ndarray
        Without the content check.

    Raises
    ------
    DamagedFileError
        If the file exists but cannot be read back whole or its content
        does not match its check; the message names the file and the fix.
    FileNotFoundError
        If there is no such file.
    """
    try:
        with np.load(path, allow_pickle=False) as data:
            arrays = {k: data[k] for k in data.files}
    except MISSING:
        raise
    except Exception as exc:  # noqa: BLE001 - whatever a damaged zip raises
        raise damaged(path, "npz", exc) from exc
    stored = arrays.pop(NPZ_CHECKSUM, None)
    if stored is None:
        if require_checksum:
            raise damaged(path, "npz", "it has no content checksum (written by an earlier "
                                        "version, or changed)")
        return arrays
    if stored.shape != () or stored.dtype.kind != "U" or str(stored) != arrays_digest(arrays):
        raise damaged(path, "npz", "its content does not match its checksum (changed after "
                                    "it was written)")
    return arrays


def write_table(rows: Sequence[dict[str, Any]], path: str | os.PathLike[str],
                digits: int = 6, title: str = "") -> Path:
    """Write rows of a table (dicts with the same keys) as CSV or HTML, atomically.

    The format follows the suffix: ``.csv``, or ``.html`` (a standalone page
    with one table, for the workflow report). Floats get ``digits``
    significant digits (NaN as an empty cell), so the file is reproducible.
    """
    import csv
    import html
    import io as _io

    suffix = Path(path).suffix
    if suffix not in (".csv", ".html"):
        raise ValueError(f"table path must end in .csv or .html, got {str(path)!r}")
    if not rows:
        raise ValueError("rows must not be empty")
    columns = list(rows[0])

    def cell(v: Any) -> str:
        if isinstance(v, float):
            return "" if math.isnan(v) else f"{v:.{digits}g}"
        return str(v)

    buf = _io.StringIO()
    if suffix == ".csv":
        writer = csv.writer(buf, lineterminator="\n")
        writer.writerow(columns)
        for row in rows:
            writer.writerow([cell(row[c]) for c in columns])
    else:
        esc = html.escape
        buf.write("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\">"
                  f"<title>{esc(title)}</title><style>"
                  "body{font-family:sans-serif;font-size:13px}"
                  "table{border-collapse:collapse}td,th{border:1px solid #bbb;"
                  "padding:3px 6px;text-align:right}th{background:#eee}"
                  "td:first-child{text-align:left}</style></head><body>\n")
        if title:
            buf.write(f"<h3>{esc(title)}</h3>\n")
        buf.write("<table>\n<tr>" + "".join(f"<th>{esc(c)}</th>" for c in columns)
                  + "</tr>\n")
        for row in rows:
            buf.write("<tr>" + "".join(f"<td>{esc(cell(row[c]))}</td>" for c in columns)
                      + "</tr>\n")
        buf.write("</table>\n</body></html>\n")
    return atomic_write(path, lambda tmp: tmp.write_text(buf.getvalue(), encoding="utf-8"))


def _open_dataset(path: str | os.PathLike[str]) -> xr.Dataset:
    import xarray as xr

    with xr.open_dataset(path, engine="netcdf4") as ds:
        return ds.load()


def write_dataset(ds: xr.Dataset, path: str | os.PathLike[str]) -> Path:
    """Write ``ds`` to a netCDF-4 file, atomically and reproducibly, with a content check.

    The data go to a temporary file in the destination folder, which then
    replaces ``path`` with :func:`os.replace`; on any failure the temporary
    file is removed and ``path`` is left as it was. Parent folders are
    created. Data variables are zlib-compressed, coordinates get no
    ``_FillValue``. Identical datasets give byte-identical files. The
    global attribute ``contactlib_sha256`` holds the SHA-256 of the content
    as it reads back (every variable's values and attributes, the other
    global attributes); the file is read back and checked before it
    replaces ``path``, and :func:`read_dataset` verifies it.

    Parameters
    ----------
    ds : xarray.Dataset
        Typically the result of :func:`to_dataset`.
    path : str or os.PathLike
        Destination file.

    Returns
    -------
    pathlib.Path
        The destination path.

    Raises
    ------
    OSError
        If ``path`` is a folder or another existing thing that is not a
        regular file, or the disk is full ("no space left on device",
        naming ``path``).

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from contactlib import solve
    >>> from contactlib.io import read_dataset, to_dataset, write_dataset
    >>> ds = to_dataset(solve("sphere", 0.3, stick_ratio=0.5, n=64))
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     path = write_dataset(ds, pathlib.Path(tmp) / "case.nc")
    ...     back = read_dataset(path)
    ...     again = write_dataset(back, pathlib.Path(tmp) / "again.nc")
    ...     same_bytes = path.read_bytes() == again.read_bytes()
    >>> bool(back["friction_coefficient"].equals(ds["friction_coefficient"])), same_bytes
    (True, True)
    """
    encoding = netcdf_encoding(ds)
    if NC_CHECKSUM in ds.attrs:  # e.g. a dataset opened with xarray itself
        ds = ds.copy(deep=False)
        del ds.attrs[NC_CHECKSUM]

    def to_netcdf(data: xr.Dataset, tmp: Path) -> None:
        data.to_netcdf(tmp, mode="w", format="NETCDF4", engine="netcdf4", encoding=encoding)

    def write(tmp: Path) -> None:
        # the content as it reads back (attributes and types as netCDF keeps them) ...
        digest = dataset_digest(ds)
        for _ in range(2):
            to_netcdf(ds.assign_attrs({NC_CHECKSUM: digest}), tmp)
            back = dataset_digest(_open_dataset(tmp))
            if back == digest:
                return
            digest = back  # ... differs from the dataset in memory: take the file's
        raise RuntimeError("the file does not read back as written; nothing was written")

    return atomic_write(path, write)


def read_dataset(path: str | os.PathLike[str], *,
                 require_checksum: bool | None = None) -> xr.Dataset:
    """Read a dataset written by :func:`write_dataset` into memory, verifying its content.

    The file is closed before returning, so it may be replaced afterwards.
    Its content check (global attribute ``contactlib_sha256``, written by
    :func:`write_dataset`) is verified and left out of the returned
    dataset. A file without one is refused if it is the workflow's own (it
    has the provenance attribute ``scene_config_hash`` of
    :func:`set_provenance`), and read as it is otherwise (a dataset a user
    wrote with other tools).

    Parameters
    ----------
    path : str or os.PathLike
        A netCDF file.
    require_checksum : bool, optional
        True: refuse any file without a content check; False: read one
        without a check whatever it holds (an explicit upgrade of a file of
        an earlier version). None (default): required for the workflow's
        own files, as above. A check that is there is always verified.

    Returns
    -------
    xarray.Dataset
        Fully loaded; flags decode back to booleans.

    Raises
    ------
    DamagedFileError
        If the file exists but is not a readable netCDF file (e.g.
        truncated), or its content does not match its check (changed after
        it was written); the message names the file and the fix.
    FileNotFoundError
        If there is no such file.
    """
    try:
        ds = _open_dataset(path)
        stored = ds.attrs.pop(NC_CHECKSUM, None)
        actual = None if stored is None else dataset_digest(ds)
    except MISSING:
        raise
    except Exception as exc:  # noqa: BLE001 - whatever netCDF4/HDF5/xarray raise
        raise damaged(path, "netCDF", exc) from exc
    if require_checksum is None:
        require_checksum = PROVENANCE in ds.attrs
    if stored is None and require_checksum:
        raise damaged(path, "netCDF", "it has no content checksum (written by an earlier "
                                       "version, or changed)")
    if stored is not None and (not isinstance(stored, str) or stored != actual):
        raise damaged(path, "netCDF", "its content does not match its checksum (changed "
                                       "after it was written)")
    return ds


_FIGURE_METADATA: dict[str, dict[str, None]] = {
    # keys the backends would otherwise fill with version strings or the time
    "png": {"Software": None},
    "pdf": {"Creator": None, "Producer": None, "CreationDate": None, "ModDate": None},
}


def write_figure(fig: Any, path: str | os.PathLike[str], *,
                 style: str | os.PathLike[str] | Mapping[str, Any] | None = None) -> Path:
    """Save a matplotlib figure as PNG or PDF, atomically and reproducibly.

    The format follows the suffix (``.png`` or ``.pdf``, any case). The
    figure is rendered into a temporary file in the destination folder,
    which then replaces ``path`` with :func:`os.replace`; on any failure the
    temporary file is removed and ``path`` is left as it was. Parent folders
    are created. The metadata that would carry a matplotlib version or the
    time is dropped (PNG ``Software``; PDF ``Creator``, ``Producer``,
    ``CreationDate``, ``ModDate``), so the same figure gives byte-identical
    files on every save, in every process (checked with different
    ``PYTHONHASHSEED`` values in ``tests/test_figures.py``). This needs a
    layout that does not move between draws: the figures of
    :mod:`contactlib.plot` settle and freeze theirs, while a figure with a
    live constrained layout may shift by a fraction of a pixel per save.
    ``fig`` is typed ``Any`` so that this module does not import matplotlib
    until a figure is written.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        Typically from :mod:`contactlib.plot`.
    path : str or os.PathLike
        Destination file, ending in ``.png`` or ``.pdf``.
    style : str, os.PathLike or mapping, optional
        A matplotlib style (a ``.mplstyle`` path, a style name or a dict of
        rcParams) active while the figure is saved; it sets the resolution
        and the PDF font type. The figures of :mod:`contactlib.plot` are
        saved with theirs, :func:`contactlib.plot.style_path` (150 dpi,
        TrueType fonts in PDF), as the workflow does. ``None`` (default):
        the current rcParams.

    Returns
    -------
    pathlib.Path
        The destination path.

    Raises
    ------
    ValueError
        If the suffix is neither ``.png`` nor ``.pdf``.
    IsADirectoryError
        If ``path`` is an existing directory.
    """
    import contextlib

    import matplotlib.style

    path = Path(path)
    fmt = path.suffix.lower().lstrip(".")
    if fmt not in _FIGURE_METADATA:
        raise ValueError(f"figure path must end in .png or .pdf, got {path.name!r}")

    def write(tmp: Path) -> None:
        saving = (contextlib.nullcontext() if style is None
                  else matplotlib.style.context(style))  # type: ignore[arg-type]
        with open(tmp, "wb") as handle, saving:
            fig.savefig(handle, format=fmt, metadata=dict(_FIGURE_METADATA[fmt]))

    return atomic_write(path, write)
