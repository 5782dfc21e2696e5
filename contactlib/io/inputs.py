"""Reading the user's text inputs: YAML configurations and CSV load tables.

:func:`check_yaml` parses a YAML file strictly (a key given twice is an
error) and :func:`read_load_table` reads a load path sampled in time; both
turn a bad file into one line naming the file and the line (a
:class:`ValueError`).
"""

from __future__ import annotations

import math
import os
import stat
from pathlib import Path
from typing import Any

__all__ = ["check_yaml", "read_load_table"]


def _unique_key_loader() -> type:
    """A safe YAML loader that refuses a key given twice in one mapping (any level)."""
    import yaml

    class UniqueKeyLoader(yaml.SafeLoader):
        def construct_mapping(self, node: Any, deep: bool = False) -> Any:
            if isinstance(node, yaml.MappingNode):
                seen: dict[Any, Any] = {}
                for key_node, _ in node.value:
                    if key_node.tag == "tag:yaml.org,2002:merge":
                        continue  # "<<: *base": keys given here override the merged ones
                    key = self.construct_object(key_node, deep=True)
                    try:
                        first = seen.get(key)
                    except TypeError:  # an unhashable key: SafeLoader reports it
                        continue
                    if first is not None:
                        raise yaml.constructor.ConstructorError(
                            None, None, f"duplicate key {key!r} (first at line "
                            f"{first.line + 1})", key_node.start_mark)
                    seen[key] = key_node.start_mark
            return super().construct_mapping(node, deep=deep)

    return UniqueKeyLoader


def check_yaml(path: str | os.PathLike[str]) -> Any:
    """Parse a YAML file, turning a syntax error into one line naming the file and line.

    A key given twice in one mapping (a scene name, or a key inside a
    scene) is an error too: YAML would keep the last one silently.

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
        ``<path>, line L, column C: <problem>`` for a syntax error or a
        duplicate key (lines and columns count from 1; ``duplicate key 'x'
        (first at line L)``), or ``<path>: <problem>`` when the path is a
        folder, not a regular file, unreadable or not UTF-8 text.
    """
    import yaml

    name = os.fspath(path)
    try:
        mode = os.stat(path).st_mode
        if stat.S_ISDIR(mode):
            raise ValueError(f"{name}: is a folder, not a YAML file")
        if not stat.S_ISREG(mode):  # a pipe or a device: reading could block or never end
            raise ValueError(f"{name}: is not a regular file")
        text = Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        return None
    except UnicodeDecodeError as exc:
        raise ValueError(f"{name}: not UTF-8 text (byte {exc.start + 1})") from None
    except OSError as exc:
        reason = (exc.strerror or type(exc).__name__).lower()
        raise ValueError(f"{name}: cannot be read: {reason}") from None
    try:
        return yaml.load(text, Loader=_unique_key_loader())  # noqa: S506 - a SafeLoader
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        where = f", line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        problem = " ".join(str(exc.problem or exc.context or "invalid YAML").split())
        kind = "" if problem.startswith("duplicate key") else "YAML syntax error: "
        raise ValueError(f"{name}{where}: {kind}{problem}") from None
    except yaml.YAMLError as exc:
        raise ValueError(f"{name}: YAML syntax error: "
                         f"{' '.join(str(exc).split())}") from None


_TABLE_COLUMNS = ("load", "force")


def read_load_table(path: str | os.PathLike[str], *, physical: bool = False
                    ) -> dict[str, list[float]]:
    """A load path sampled in time, from a CSV file (:mod:`contactlib.model.load_paths`).

    The file has a header row naming two columns, ``time`` first, then
    ``load`` (levels P/P_max, time in the unit of tau) or ``force`` (with
    ``physical``: N, time in s). A physical column may name its unit in
    brackets, ``time [ms]``, ``force [kN]`` (:data:`contactlib.physical.UNITS`).
    Lines starting with ``#`` and blank lines are skipped.

    Parameters
    ----------
    path : str or os.PathLike
        The CSV file.
    physical : bool
        Whether the path is in SI (a ``force`` column) or levels (``load``).

    Returns
    -------
    dict
        ``{"time": [...], "load" or "force": [...]}`` in the file's order, in
        the unit of tau and levels, or in s and N. The values are checked
        further by :func:`contactlib.model.load_paths.load_path` (or
        :func:`contactlib.physical.physical_history`).

    Raises
    ------
    ValueError
        One line naming the file (and line): missing, a folder, unreadable,
        not UTF-8, no header, other columns, a unit unknown for the column,
        a row without exactly two cells, a cell that is not a finite number,
        or fewer than two rows.
    """
    import csv

    from contactlib.physical import UNITS

    name = os.fspath(path)
    try:
        if stat.S_ISDIR(os.stat(path).st_mode):
            raise ValueError(f"{name}: is a folder, not a CSV file")
        text = Path(path).read_text(encoding="utf-8-sig")
    except FileNotFoundError:
        raise ValueError(f"{name}: no such file") from None
    except UnicodeDecodeError as exc:
        raise ValueError(f"{name}: not UTF-8 text (byte {exc.start + 1})") from None
    except OSError as exc:
        reason = (exc.strerror or type(exc).__name__).lower()
        raise ValueError(f"{name}: cannot be read: {reason}") from None
    rows = [(i, row) for i, row in enumerate(csv.reader(text.splitlines()), start=1)
            if row and any(c.strip() for c in row) and not row[0].lstrip().startswith("#")]
    want = "force" if physical else "load"
    header = f"a header 'time,{want}'" + (" (units in brackets allowed: 'time [s],force "
                                          "[N]')" if physical else "")
    if not rows:
        raise ValueError(f"{name}: empty: expected {header} and rows of numbers")
    line, head = rows[0]
    factors = []
    for cell, column, kind in zip(head, ("time", want), ("time", "force")):
        label, _, unit = cell.strip().partition("[")
        label, unit = label.strip().lower(), unit.rstrip("] ").strip()
        if label != column or (unit and not physical):
            raise ValueError(f"{name}, line {line}: expected {header}, got "
                             f"{','.join(c.strip() for c in head)!r}")
        if unit and unit not in UNITS[kind]:
            raise ValueError(f"{name}, line {line}: unknown unit {unit!r} of {column} "
                             f"(one of {', '.join(u for u in UNITS[kind] if u.isascii())})")
        factors.append(UNITS[kind][unit] if unit else 1.0)
    if len(head) != 2:
        raise ValueError(f"{name}, line {line}: expected {header}, got {len(head)} columns")
    cols: tuple[list[float], list[float]] = ([], [])
    for line, row in rows[1:]:
        if len(row) != 2:
            raise ValueError(f"{name}, line {line}: expected two cells (time,{want}), got "
                             f"{len(row)}: {','.join(row)!r}")
        for cell, col, factor in zip(row, cols, factors):
            try:
                value = float(cell)
            except ValueError:
                raise ValueError(f"{name}, line {line}: {cell.strip()!r} is not a number"
                                 ) from None
            if not math.isfinite(value):
                raise ValueError(f"{name}, line {line}: {cell.strip()!r} is not finite")
            col.append(value * factor)
    if len(cols[0]) < 2:
        raise ValueError(f"{name}: needs at least two rows of numbers (a start and an end), "
                         f"got {len(cols[0])}")
    return {"time": cols[0], want: cols[1]}
