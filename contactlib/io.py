"""netCDF input/output for :class:`~contactlib.result.Solution` objects.

This is the only module of :mod:`contactlib` that touches the disk. It turns
solutions into a CF-annotated :class:`xarray.Dataset` (variable names and
scalings of docs/conventions.md), writes it atomically and reproducibly, and
reads it back.

Examples
--------
>>> import numpy as np
>>> from contactlib.result import Solution
>>> from contactlib.io import to_dataset
>>> xi = np.linspace(0.0, 1.0, 5)
>>> sol = Solution("sphere", 0.3, "default", 4, 0.0, 0.5, 0.2, xi,
...                np.sqrt(1 - xi**2), 0.1 * xi, 0.5 * xi, 1.0)
>>> ds = to_dataset(sol)
>>> ds["pressure"].dims, float(ds["stick_ratio"])
(('xi',), 0.5)
"""

from __future__ import annotations

import errno
import math
import os
import tempfile
import zipfile
import zlib
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from contactlib.result import Solution

__all__ = ["to_dataset", "write_dataset", "read_dataset", "write_arrays", "read_arrays",
           "write_table", "write_figure", "check_writable", "check_yaml", "DamagedFileError"]

CONVENTIONS = "CF-1.10"
COMPRESSION: dict[str, Any] = {"zlib": True, "complevel": 4, "shuffle": True}

_BOOL_FLAGS: dict[str, Any] = {
    "flag_values": np.array([0, 1], dtype=np.int8),
    "flag_meanings": "false true",
}

# name -> (long_name, comment); every variable here is dimensionless (units "1").
_PROFILE_ATTRS: dict[str, tuple[str, str]] = {
    "pressure": (
        "contact pressure over Hertz peak pressure",
        "p / p0, p0 = Hertz peak pressure at the same contact radius; "
        "positive in compression",
    ),
    "shear": (
        "shear traction over Hertz peak pressure",
        "q / p0, traction on the elastic body, positive away from the axis",
    ),
    "tangential_displacement": (
        "scaled tangential surface displacement",
        "u R / a**2, surface displacement, positive away from the axis",
    ),
}

_WORK_COMMENT = {
    "sphere": "V R**2 / (E* a**5); loading 0 -> a; NaN when not computed",
    "cylinder": (
        "V R**2 / (E* a**4), V per unit length over the whole contact "
        "(both sides of the axis); loading 0 -> a; NaN when not computed"
    ),
}

_POINT_FLOAT_ATTRS: dict[str, tuple[str, str]] = {
    "friction_coefficient": (
        "coefficient of friction",
        "k; inf at full adhesion (stick_ratio = 1), 0 when frictionless",
    ),
    "load_ratio": (
        "normal load over Hertz load",
        "P / P_Hertz(a) at the same contact radius",
    ),
    "frictional_work": ("scaled frictional work of the loading half-cycle", ""),
    "residual_norm": ("norm of the final solver residual", "solver status"),
}

_POINT_BOOL_ATTRS: dict[str, tuple[str, str]] = {
    "slip_direction_ok": (
        "slip opposes shear at every slip point",
        "consistency flag",
    ),
    "stick_admissible": (
        "abs(q) <= k p at every stick point",
        "consistency flag",
    ),
    "consistent": (
        "slip direction and stick admissibility both hold",
        "consistency flag",
    ),
    "converged": ("solver converged", "solver status; failed cases are kept"),
}

_SHARED_FIELDS = ("geometry", "nu", "method", "n", "slab_ratio")


def _version() -> str:
    """Return the contactlib version from its single source."""
    try:
        import contactlib

        return str(contactlib.__version__)
    except (ImportError, AttributeError):  # pragma: no cover - defensive
        from importlib.metadata import PackageNotFoundError, version

        try:
            return version("contactlib")
        except PackageNotFoundError:
            return "unknown"


def _same(a: Any, b: Any) -> bool:
    if isinstance(a, float) and isinstance(b, float):
        return a == b or (math.isnan(a) and math.isnan(b))
    return bool(a == b)


def _check(sols: list[Solution]) -> np.ndarray:
    """Validate that ``sols`` can share one dataset; return the common xi."""
    first = sols[0]
    xi = np.asarray(first.xi, dtype=float)
    if xi.ndim != 1:
        raise ValueError(f"xi must be one-dimensional, got shape {xi.shape}")
    for i, sol in enumerate(sols):
        if not isinstance(sol, Solution):
            raise TypeError(f"solutions[{i}] is not a Solution: {type(sol).__name__}")
        for name in _SHARED_FIELDS:
            if not _same(getattr(sol, name), getattr(first, name)):
                raise ValueError(
                    f"solutions[{i}].{name} = {getattr(sol, name)!r} differs from "
                    f"solutions[0].{name} = {getattr(first, name)!r}"
                )
        if not np.array_equal(np.asarray(sol.xi, dtype=float), xi):
            raise ValueError(f"solutions[{i}].xi differs from solutions[0].xi")
        for name in _PROFILE_ATTRS:
            value = getattr(sol, name)
            if (value is None) != (getattr(first, name) is None):
                raise ValueError(f"solutions[{i}].{name} is computed for some solutions only")
            shape = xi.shape if value is None else np.shape(value)
            if shape != xi.shape:
                raise ValueError(
                    f"solutions[{i}].{name} has shape {shape}, expected {xi.shape}"
                )
    return xi


def _attrs(long_name: str, comment: str = "", **extra: Any) -> dict[str, Any]:
    attrs: dict[str, Any] = {"units": "1", "long_name": long_name}
    if comment:
        attrs["comment"] = comment
    attrs.update(extra)
    return attrs


def to_dataset(solutions: Solution | Sequence[Solution]) -> xr.Dataset:
    """Convert one solution or a sweep of solutions to a dataset.

    Parameters
    ----------
    solutions : Solution or sequence of Solution
        A single solution gives a dataset with a scalar ``stick_ratio``
        coordinate and profiles on ``(xi,)``. A sequence (a sweep) gives a
        ``stick_ratio`` dimension, in the given order, and profiles on
        ``(stick_ratio, xi)``. All members must share geometry, nu, method,
        n, slab_ratio and xi.

    Returns
    -------
    xarray.Dataset
        Variables and scalings of docs/conventions.md, each with CF
        ``units`` (``"1"``: everything is dimensionless) and ``long_name``.
        Flags are booleans (stored as int8 with ``flag_values`` and
        ``flag_meanings``). A ``message`` variable is added when any solution
        carries a non-empty message.

    Raises
    ------
    ValueError
        If the sequence is empty or its members are inconsistent.
    TypeError
        If a member is not a :class:`Solution`.

    Examples
    --------
    >>> import numpy as np
    >>> from contactlib.result import Solution
    >>> xi = np.linspace(0.0, 1.0, 3)
    >>> sols = [Solution("cylinder", 0.3, "default", 2, 0.0, g, g, xi,
    ...                  1 - xi**2, 0 * xi, 0 * xi, 1.0) for g in (0.2, 0.4)]
    >>> to_dataset(sols)["shear"].dims
    ('stick_ratio', 'xi')
    """
    single = isinstance(solutions, Solution)
    sols = [solutions] if single else list(solutions)  # type: ignore[list-item]
    if not sols:
        raise ValueError("solutions must contain at least one Solution")
    xi = _check(sols)
    first = sols[0]
    geometry = str(first.geometry)
    axis = "r/a" if geometry == "sphere" else "x/a"
    dims = ("stick_ratio",)

    coords = {
        "xi": (
            "xi",
            xi,
            _attrs(
                f"position over contact radius ({axis})",
                "0 on the axis, 1 at the contact edge",
            ),
        ),
        "stick_ratio": (
            dims,
            np.array([float(s.stick_ratio) for s in sols]),
            _attrs(
                "stick zone radius over contact radius (c/a)",
                "0 frictionless, 1 full adhesion",
            ),
        ),
    }
    data: dict[str, Any] = {}
    for name, (long_name, comment) in _PROFILE_ATTRS.items():
        if getattr(first, name) is None:
            continue  # not computed (a workflow scene that did not ask for it)
        values = np.stack([np.asarray(getattr(s, name), dtype=float) for s in sols])
        data[name] = (dims + ("xi",), values, _attrs(long_name, comment))
    for name, (long_name, comment) in _POINT_FLOAT_ATTRS.items():
        if name == "frictional_work":
            comment = _WORK_COMMENT.get(geometry, "")
        values = np.array([float(getattr(s, name)) for s in sols])
        data[name] = (dims, values, _attrs(long_name, comment))
    data["iterations"] = (
        dims,
        np.array([int(s.iterations) for s in sols], dtype=np.int32),
        _attrs("solver iterations", "solver status"),
    )
    for name, (long_name, comment) in _POINT_BOOL_ATTRS.items():
        values = np.array([bool(getattr(s, name)) for s in sols], dtype=bool)
        data[name] = (dims, values, _attrs(long_name, comment, **_BOOL_FLAGS))
    messages = [str(s.message or "") for s in sols]
    if any(messages):
        data["message"] = (
            dims,
            np.array(messages, dtype=object),
            {"long_name": "solver message", "comment": "empty when none"},
        )

    attrs: dict[str, Any] = {
        "title": f"contactlib partial-slip solution ({geometry})",
        "geometry": geometry,
        "poisson_ratio": float(first.nu),
        "elements": int(first.n),
        "method": str(first.method),
    }
    if geometry == "cylinder":
        attrs["slab_ratio"] = float(first.slab_ratio)
    attrs["contactlib_version"] = _version()
    attrs["Conventions"] = CONVENTIONS

    ds = xr.Dataset(data_vars=data, coords=coords, attrs=attrs)
    if single:
        ds = ds.isel(stick_ratio=0)
    return ds


def _encoding(ds: xr.Dataset) -> dict[str, dict[str, Any]]:
    """Per-variable netCDF encoding: no fill on coordinates, zlib on data."""
    encoding: dict[str, dict[str, Any]] = {}
    for name in ds.coords:
        encoding[str(name)] = {"_FillValue": None}
    for name, var in ds.data_vars.items():
        if var.dtype.kind in "biuf" and var.ndim > 0:
            encoding[str(name)] = dict(COMPRESSION)
    return encoding


def _atomic_target(path: str | os.PathLike[str]) -> tuple[Path, Path]:
    """Destination and a fresh temporary file beside it (parents created)."""
    path = Path(path)
    if path.is_dir():
        raise IsADirectoryError(f"output path is a directory: {path}")
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp_name = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    os.close(fd)
    umask = os.umask(0)  # mkstemp makes the file 0600: give it the usual permissions
    os.umask(umask)
    os.chmod(tmp_name, 0o666 & ~umask)
    return path, Path(tmp_name)


def check_writable(path: str | os.PathLike[str]) -> Path:
    """Check, before any work, that a writer of this module can write ``path``.

    Does what :func:`write_dataset` and the other writers do first (create
    missing parent folders, create the temporary file beside the
    destination), then removes the temporary file and every folder it
    created, so nothing is left behind. This catches an unwritable folder, a
    path through a file and a name too long (the temporary name is longer
    than the destination's) before a long computation rather than after it.

    Parameters
    ----------
    path : str or os.PathLike
        The destination file.

    Returns
    -------
    pathlib.Path
        ``path``; missing parent folders will be created by the writer.

    Raises
    ------
    OSError
        One line naming ``path`` and the reason (never the temporary name).
    """
    if os.fspath(path).strip() == "" or Path(path).name in ("", ".", ".."):
        raise OSError(f"{os.fspath(path)!r} is not a file name")
    path = Path(path)
    if path.is_dir():
        raise IsADirectoryError(f"{path} is a folder, not a file")
    ancestors = [a for a in path.parents]
    for folder in ancestors:  # the nearest existing ancestor must be a folder
        if folder.exists() or folder.is_symlink():
            if not folder.is_dir():
                raise NotADirectoryError(f"cannot write {path}: {folder} is a file, not a folder")
            break
    created = [a for a in ancestors if not (a.exists() or a.is_symlink())]
    tmp: Path | None = None
    try:
        _, tmp = _atomic_target(path)
    except OSError as exc:
        reason = exc.strerror or type(exc).__name__
        if exc.errno == errno.ENAMETOOLONG:
            reason = "file name too long"
        raise type(exc)(f"cannot write {path}: {reason.lower()}") from None
    finally:
        if tmp is not None:
            tmp.unlink(missing_ok=True)
        for folder in created:  # deepest first
            try:
                folder.rmdir()
            except OSError:
                pass
    return path


def write_arrays(arrays: dict[str, np.ndarray], path: str | os.PathLike[str]) -> Path:
    """Write named arrays (an intermediate of the workflow) to ``.npz``, atomically.

    Used for influence matrices and case records between workflow stages.
    Arrays are stored uncompressed (influence matrices do not compress) and
    without pickling: only numeric, boolean and string arrays are allowed.

    Parameters
    ----------
    arrays : dict of str to array_like
    path : str or os.PathLike
        Destination; must end in ``.npz``.

    Returns
    -------
    pathlib.Path
    """
    if Path(path).suffix != ".npz":
        raise ValueError(f"path must end in .npz, got {str(path)!r}")
    data = {k: np.asarray(v) for k, v in arrays.items()}
    for k, v in data.items():
        if v.dtype.kind not in "biufUS":
            raise TypeError(f"array {k!r} has dtype {v.dtype}, which needs pickling")
    path, tmp = _atomic_target(path)
    try:
        with open(tmp, "wb") as fh:
            np.savez(fh, **data)
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    return path


class DamagedFileError(OSError):
    """A file exists but cannot be read back whole (truncated or corrupt).

    The message is one line naming the file and the fix (delete it and
    rebuild it).
    """


# errors of a file that is there but unreadable; a missing or forbidden file
# (FileNotFoundError, PermissionError, IsADirectoryError) keeps its own error
_MISSING = (FileNotFoundError, PermissionError, IsADirectoryError)


def _damaged(path: str | os.PathLike[str], kind: str, exc: BaseException) -> DamagedFileError:
    detail = " ".join(f"{type(exc).__name__}: {exc}".split())
    if len(detail) > 160:
        detail = detail[:157] + "..."
    return DamagedFileError(
        f"{os.fspath(path)} is damaged or incomplete (not a readable {kind} file: {detail}); "
        f"delete it and make it again (in the workflow: remove the file and rerun "
        f"snakemake, which rebuilds it)")


def read_arrays(path: str | os.PathLike[str]) -> dict[str, np.ndarray]:
    """Read arrays written by :func:`write_arrays` (no pickles are loaded).

    Every array is read whole, so a truncated or corrupt file (a broken zip
    directory, a CRC mismatch, a short array) is detected here.

    Raises
    ------
    DamagedFileError
        If the file exists but cannot be read back whole; the message names
        the file and the fix.
    FileNotFoundError
        If there is no such file.
    """
    try:
        with np.load(path, allow_pickle=False) as data:
            return {k: data[k] for k in data.files}
    except _MISSING:
        raise
    except (zipfile.BadZipFile, zlib.error, EOFError, ValueError, KeyError, OSError) as exc:
        raise _damaged(path, "npz", exc) from exc


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
    path, tmp = _atomic_target(path)
    try:
        tmp.write_text(buf.getvalue(), encoding="utf-8")
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    return path


def write_dataset(ds: xr.Dataset, path: str | os.PathLike[str]) -> Path:
    """Write ``ds`` to a netCDF-4 file, atomically and reproducibly.

    The data go to a temporary file in the destination folder, which then
    replaces ``path`` with :func:`os.replace`; on any failure the temporary
    file is removed and ``path`` is left as it was. Parent folders are
    created. Data variables are zlib-compressed, coordinates get no
    ``_FillValue``. Identical datasets give byte-identical files.

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
    path, tmp = _atomic_target(path)
    try:
        ds.to_netcdf(
            tmp, mode="w", format="NETCDF4", engine="netcdf4", encoding=_encoding(ds)
        )
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    return path


def read_dataset(path: str | os.PathLike[str]) -> xr.Dataset:
    """Read a dataset written by :func:`write_dataset` into memory.

    The file is closed before returning, so it may be replaced afterwards.

    Parameters
    ----------
    path : str or os.PathLike
        A netCDF file.

    Returns
    -------
    xarray.Dataset
        Fully loaded; flags decode back to booleans.

    Raises
    ------
    DamagedFileError
        If the file exists but is not a readable netCDF file (e.g. truncated);
        the message names the file and the fix.
    FileNotFoundError
        If there is no such file.
    """
    try:
        with xr.open_dataset(path, engine="netcdf4") as ds:
            return ds.load()
    except _MISSING:
        raise
    except (OSError, RuntimeError, ValueError, KeyError, IndexError) as exc:
        raise _damaged(path, "netCDF", exc) from exc


def check_yaml(path: str | os.PathLike[str]) -> Any:
    """Parse a YAML file, turning a syntax error into one line naming the file and line.

    Parameters
    ----------
    path : str or os.PathLike
        A YAML (or JSON) file, e.g. the workflow's ``config/config.yaml``.

    Returns
    -------
    object
        The parsed document (``None`` when the file is missing: the caller
        reports that in its own words).

    Raises
    ------
    ValueError
        ``<path>, line L, column C: <problem>`` for a syntax error (lines
        and columns count from 1).
    """
    import yaml

    try:
        text = Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        return None
    try:
        return yaml.safe_load(text)
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        where = f", line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        problem = " ".join(str(exc.problem or exc.context or "invalid YAML").split())
        raise ValueError(f"{os.fspath(path)}{where}: YAML syntax error: {problem}") from None
    except yaml.YAMLError as exc:
        raise ValueError(f"{os.fspath(path)}: YAML syntax error: "
                         f"{' '.join(str(exc).split())}") from None


_FIGURE_METADATA: dict[str, dict[str, None]] = {
    # keys the backends would otherwise fill with version strings or the time
    "png": {"Software": None},
    "pdf": {"Creator": None, "Producer": None, "CreationDate": None, "ModDate": None},
}


def write_figure(fig: Any, path: str | os.PathLike[str]) -> Path:
    """Save a matplotlib figure as PNG or PDF, atomically and reproducibly.

    The format follows the suffix (``.png`` or ``.pdf``, any case). The
    figure is rendered into a temporary file in the destination folder,
    which then replaces ``path`` with :func:`os.replace`; on any failure the
    temporary file is removed and ``path`` is left as it was. Parent folders
    are created. Saving happens inside the contactlib style
    (:func:`contactlib.figures.style_path`: 150 dpi, TrueType fonts in PDF),
    and the metadata that would carry a matplotlib version or the time is
    dropped (PNG ``Software``; PDF ``Creator``, ``Producer``,
    ``CreationDate``, ``ModDate``), so the same figure gives byte-identical
    files on every save, in every process (checked with different
    ``PYTHONHASHSEED`` values in ``tests/test_figures.py``). This needs a
    layout that does not move between draws: the figures of
    :mod:`contactlib.figures` settle and freeze theirs, while a figure with a
    live constrained layout may shift by a fraction of a pixel per save.
    ``fig`` is typed ``Any`` so that this module does not import matplotlib
    until a figure is written.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        Typically from :mod:`contactlib.figures`.
    path : str or os.PathLike
        Destination file, ending in ``.png`` or ``.pdf``.

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
    import matplotlib.style

    from contactlib.figures import style_path

    path = Path(path)
    fmt = path.suffix.lower().lstrip(".")
    if fmt not in _FIGURE_METADATA:
        raise ValueError(f"figure path must end in .png or .pdf, got {path.name!r}")
    path, tmp = _atomic_target(path)
    try:
        with open(tmp, "wb") as handle, matplotlib.style.context(style_path()):
            fig.savefig(handle, format=fmt, metadata=dict(_FIGURE_METADATA[fmt]))
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    return path
