"""Content checks: the SHA-256 of an npz file's arrays or of a netCDF dataset.

Every file the workflow passes on carries one (npz: an array
``contactlib_sha256``; netCDF: a global attribute ``contactlib_sha256``),
computed here and written and verified by :mod:`contactlib.io.files`: a
truncated, corrupt or changed file is a :class:`DamagedFileError` naming it
and the fix, never used.
"""

from __future__ import annotations

import hashlib
import os
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:  # xarray is imported where a dataset is made or read (start-up time)
    import xarray as xr

__all__ = ["NPZ_CHECKSUM", "NC_CHECKSUM", "MISSING", "arrays_digest", "dataset_digest",
           "DamagedFileError", "damaged"]


# the content check of an npz file (write_arrays): SHA-256 over every other array's name,
# dtype, shape and bytes, stored as one more array
NPZ_CHECKSUM = "contactlib_sha256"


def arrays_digest(arrays: Mapping[str, np.ndarray]) -> str:
    """SHA-256 (hex) of every array's name, dtype, shape and bytes, ``NPZ_CHECKSUM`` left out."""
    h = hashlib.sha256()
    for name in sorted(arrays):
        if name == NPZ_CHECKSUM:
            continue
        value = np.ascontiguousarray(arrays[name])
        for part in (name, value.dtype.str, repr(value.shape)):
            text = part.encode("utf-8")
            h.update(len(text).to_bytes(8, "little") + text)
        h.update(value.nbytes.to_bytes(8, "little"))
        h.update(memoryview(value).cast("B") if value.nbytes else b"")
    return h.hexdigest()

class DamagedFileError(OSError):
    """A file exists but cannot be read back whole (truncated, corrupt or changed).

    The message is one line naming the file and the fix (delete it and
    rebuild it).
    """


# errors of a file that is there but unreadable; a missing or forbidden file
# (FileNotFoundError, PermissionError, IsADirectoryError) keeps its own error
MISSING = (FileNotFoundError, PermissionError, IsADirectoryError)

_REBUILD = ("delete it and make it again (in the workflow: delete it and run snakemake "
            "--rerun-incomplete, which rebuilds it)")


def damaged(path: str | os.PathLike[str], kind: str,
             exc: BaseException | str) -> DamagedFileError:
    """The one-line error of a damaged ``kind`` file (npz, netCDF), naming it and the fix."""
    detail = exc if isinstance(exc, str) else f"{type(exc).__name__}: {exc}"
    detail = " ".join(detail.split())
    if len(detail) > 160:
        detail = detail[:157] + "..."
    return DamagedFileError(
        f"{os.fspath(path)} is damaged or incomplete (not a readable {kind} file: {detail}); "
        f"{_REBUILD}")


# the content check of a netCDF file (write_dataset): a global attribute, the SHA-256 of the
# dataset as it reads back (every variable's name, dimensions, dtype, values and attributes,
# and the other global attributes)
NC_CHECKSUM = "contactlib_sha256"


def _attr_text(value: Any) -> str:
    if isinstance(value, str):
        return "s" + value
    arr = np.asarray(value)
    return f"{arr.dtype.str}{arr.shape}{arr.tolist()!r}"


def dataset_digest(ds: xr.Dataset) -> str:
    """SHA-256 of a dataset's content (not of its file's bytes), without ``NC_CHECKSUM``."""
    h = hashlib.sha256()

    def put(data: str | bytes | memoryview) -> None:
        raw = data.encode("utf-8", "surrogatepass") if isinstance(data, str) else data
        h.update(len(raw).to_bytes(8, "little"))
        h.update(raw)

    def put_attrs(attrs: Mapping[Any, Any]) -> None:
        for key in sorted(map(str, attrs)):
            if key != NC_CHECKSUM:
                put(key)
                put(_attr_text(attrs[key]))

    put_attrs(ds.attrs)
    put("coords:" + ",".join(sorted(map(str, ds.coords))))
    for name in sorted(map(str, ds.variables)):
        var = ds.variables[name]
        put(name)
        put(",".join(map(str, var.dims)))
        put_attrs(var.attrs)
        values = np.asarray(var.values)
        if values.dtype.kind in "OUS":  # text: str items, whatever the array's dtype
            put(f"text{values.shape}")
            for item in values.ravel().tolist():
                put(item if isinstance(item, bytes) else f"{type(item).__name__}:{item!r}")
        else:
            put(f"{values.dtype.str}{values.shape}")
            values = np.ascontiguousarray(values)
            put(memoryview(values).cast("B") if values.nbytes else b"")
    return h.hexdigest()
