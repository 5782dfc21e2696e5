"""The workflow's case records in npz files: every field accounted for, read strictly.

:func:`write_records` and :func:`read_records` carry the
:class:`~contactlib.result.CaseRecord` objects the workflow passes between its
stages, through :func:`contactlib.io.files.write_arrays` (atomic, with its
content check, no pickles); a missing field is an error naming the file and
the field, never a default.
"""

from __future__ import annotations

import dataclasses
import os
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from contactlib.io.checksums import damaged
from contactlib.io.files import read_arrays, write_arrays
from contactlib.result import CaseRecord

__all__ = ["write_records", "read_records"]


# fields of case records written by earlier versions and no longer kept (ignored on reading)
_RETIRED_RECORD_FIELDS = ("tolerance_message",)  # (merged into the message)
_RECORD_FIELDS = tuple(f.name for f in dataclasses.fields(CaseRecord))
_NONE_FIELDS = "none"  # "<i>/<field>" of every field that is None


def write_records(records: Sequence[CaseRecord], path: str | os.PathLike[str]) -> Path:
    """Write the case records of a scene (:func:`contactlib.stages.solve_cases`) to ``.npz``.

    The workflow's transport between its stages: every field of each
    :class:`~contactlib.result.CaseRecord` that is not None becomes an array
    named ``"<i>/<field>"`` (i the case's position), next to ``count``, the
    number of records, and ``none``, the names ``"<i>/<field>"`` of the
    fields that are None; written with :func:`write_arrays` (atomically,
    with its content check, no pickles). So every field of every record is
    accounted for, and :func:`read_records` needs no default.

    Parameters
    ----------
    records : sequence of CaseRecord
    path : str or os.PathLike
        Destination; must end in ``.npz``.

    Returns
    -------
    pathlib.Path
    """
    arrays: dict[str, np.ndarray] = {"count": np.array(len(records))}
    none: list[str] = []
    for i, rec in enumerate(records):
        for name in _RECORD_FIELDS:
            value = getattr(rec, name)
            if value is None:
                none.append(f"{i}/{name}")
            else:
                arrays[f"{i}/{name}"] = np.asarray(value)
    arrays[_NONE_FIELDS] = np.array(none, dtype=str)
    return write_arrays(arrays, path)


def _record_key(name: str, count: int) -> tuple[int, str]:
    """``"<i>/<field>"`` -> (i, field), i a record of the file."""
    i, _, key = name.partition("/")
    if not (i.isdigit() and int(i) < count and key):
        raise ValueError(f"unexpected array {name!r} (not '<case>/<field>' of {count} cases)")
    return int(i), key


def _record_fields(arrays: dict[str, np.ndarray], upgrade: bool) -> list[dict[str, Any]]:
    """The fields of each record; strict (every field accounted for) unless ``upgrade``."""
    count = arrays.get("count")
    if count is None or count.shape != () or count.dtype.kind not in "iu" or int(count) < 0:
        raise ValueError("no record count")
    fields: list[dict[str, Any]] = [{} for _ in range(int(count))]
    none = arrays.get(_NONE_FIELDS)
    if not upgrade:
        if none is None or none.ndim != 1 or (none.size and none.dtype.kind != "U"):
            raise ValueError("no list of the fields that are None")
        for name in none.tolist():
            i, key = _record_key(name, len(fields))
            fields[i][key] = None
    for name, value in arrays.items():
        if name in ("count", _NONE_FIELDS):
            continue
        i, key = _record_key(name, len(fields))
        if key in _RETIRED_RECORD_FIELDS and upgrade:
            continue
        if key not in _RECORD_FIELDS:
            raise ValueError(f"unknown field {name!r}")
        if key in fields[i]:
            raise ValueError(f"field {name!r} is both given and None")
        fields[i][key] = value.item() if value.ndim == 0 else value
    if not upgrade:
        for i, f in enumerate(fields):
            missing = [key for key in _RECORD_FIELDS if key not in f]
            if missing:
                raise ValueError(f"case {i} has no field {missing[0]!r}"
                                 + (f" (and {len(missing) - 1} more)" if len(missing) > 1
                                    else ""))
    return fields


def read_records(path: str | os.PathLike[str], *, upgrade: bool = False) -> list[CaseRecord]:
    """Read case records written by :func:`write_records`.

    Strict: the content check must be there and match, and every field of
    every record must be in the file (as an array, or named among the
    fields that are None); a missing field is an error naming the file and
    the field, never a default. 0-d arrays come back as Python scalars, so
    a record read back equals the one written field by field.

    Parameters
    ----------
    path : str or os.PathLike
    upgrade : bool
        The explicit reading of files of earlier versions (no content check,
        no list of None fields, fields added since then missing): fields
        not in the file take their defaults (None, or NaN for the
        estimates) and a retired field (``tolerance_message``) is skipped.
        Write the records again with :func:`write_records` to upgrade the
        file.

    Returns
    -------
    list of CaseRecord

    Raises
    ------
    DamagedFileError
        If the file exists but cannot be read back whole, does not match its
        content check, or does not hold complete case records; the message
        names the file and, for a missing field, the field.
    FileNotFoundError
        If there is no such file.

    Examples
    --------
    >>> import tempfile, os
    >>> from contactlib import stages
    >>> from contactlib.model import contact
    >>> recs = stages.solve_cases(contact("sphere", 0.3), "default", 16, [0.0])
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = write_records(recs, os.path.join(folder, "r.npz"))
    ...     back = read_records(path)
    >>> back[0].stick_ratio, back[0].k, back[0].p.shape
    (0.0, 0.0, (17,))
    """
    arrays = read_arrays(path, require_checksum=not upgrade)
    try:
        records = [CaseRecord(**f) for f in _record_fields(arrays, upgrade)]
    except (KeyError, ValueError, IndexError, TypeError) as exc:
        detail = str(exc) if isinstance(exc, ValueError) else f"{type(exc).__name__}: {exc}"
        raise damaged(path, "case-record npz", detail) from exc
    return records
