"""The key-numbers table: self-similar and history rows, the compact report view."""

from __future__ import annotations

import math

import numpy as np
import pytest

import contactlib
from contactlib import history
from contactlib.io import history_to_dataset, stack_histories
from contactlib.io import to_dataset
from contactlib.summary import (COLUMNS, CYCLE_WORK, LARGEST_WORK, REPORT_COLUMNS, WORK_AT_HALF,
                                key_numbers, quoted, report_rows)


@pytest.fixture(scope="module")
def rows():
    sweep = to_dataset(contactlib.sweep("sphere", 0.3, [0.0, 0.25, 0.5], n=64))
    sweep.attrs["scene"] = "s-default"
    paper = to_dataset(contactlib.sweep("sphere", 0.3, "all", n=16, method="paper"))
    paper.attrs["scene"] = "s-paper"
    runs = [history_to_dataset(history("sphere", 0.3, k, [0, 1, 0], 8, n=60))
            for k in (0.0, 0.2)]
    stack = stack_histories(runs)
    stack.attrs["scene"] = "s-cycle"
    return key_numbers([sweep, paper, stack]), runs


def test_columns_one_value_a_cell_and_a_row_a_run(rows):
    """Tidy: a self-similar scene a row, a history a row a run (long format), one value a
    cell (a number or a word, never a list), the work columns naming their scaling."""
    table, _ = rows
    assert [r["scene"] for r in table] == ["s-default", "s-paper", "s-cycle", "s-cycle"]
    assert all(list(r) == list(COLUMNS) for r in table)
    for row in table:
        for name, value in row.items():
            assert isinstance(value, (int, float)) or (isinstance(value, str) and " " not in
                                                        value.strip()), (name, value)
    for name in (WORK_AT_HALF, LARGEST_WORK):
        assert "V R^2/(E* a^5)" in name and "a^4) per unit length" in name
    assert "V R^2/(E* a_max^5)" in CYCLE_WORK


def test_frictionless_load(rows):
    table, _ = rows
    # our method at c/a = 0 is Hertz (exact on a half-space), read from the dataset
    assert table[0]["frictionless source"] == "dataset"
    assert abs(table[0]["frictionless P/P_Hertz"] - 1.0) < 2e-4
    # the paper's scheme holds only m/16, m >= 1: a frictionless solve fills the gap
    # with its 4.2 % excess at n = 16 (the paper states 0.3 %)
    assert table[1]["frictionless source"] == "solve"
    assert 1.041 < table[1]["frictionless P/P_Hertz"] < 1.043


def test_history_rows(rows):
    table, runs = rows
    first, second = table[2:]
    for row in (first, second):
        assert row["method"] == "history" and row["cases"] == 1 and row["converged"] == 1
        assert np.isnan(row["k at c/a = 0.5"])
    assert (first["history k"], second["history k"]) == (0.0, 0.2)
    # the peak of a 0 -> 1 -> 0 path is its middle step; c/a there is the run's own
    peak = int(np.argmax(runs[1]["load_ratio"].values))
    assert peak == 8
    # (each quoted to the digits its accuracy supports: summary.quoted)
    ds = runs[1]
    asked = float(ds.attrs["max_error"])
    c_est = float(ds["stick_radius_error_estimate"].values[peak])
    c = float(ds["stick_ratio"].values[peak])
    c_rel = c_est / (c * float(ds["contact_radius"].values[peak]))
    assert second["history c/a at peak load"] == quoted(c, c_rel, asked)
    assert abs(second["history c/a at peak load"] - c) <= 0.5 * 10 ** math.floor(
        math.log10(c) - math.floor(-math.log10(max(c_rel, asked))) + 1)  # rounding only
    # the whole path is the cycle: its work is the final cumulative work; none without
    # friction
    assert first[CYCLE_WORK] == 0.0
    w = float(ds["frictional_work"].values[-1])
    assert abs(second[CYCLE_WORK] / w - 1.0) < 0.05  # w to at most 2 ... 6 digits
    assert np.isnan(table[0]["history k"]) and np.isnan(table[0][CYCLE_WORK])


def test_report_rows_are_compact(rows):
    table, _ = rows
    view = report_rows(table)
    assert all(list(r) == list(REPORT_COLUMNS) for r in view)
    assert [r["scene"] for r in view] == ["s-default", "s-paper", "s-cycle"]  # a row a scene
    assert view[2]["cases / converged / consistent"] == "2 / 2 / –"
    assert len(REPORT_COLUMNS) <= 10
    assert view[1]["P/P_Hertz frictionless"] == "1.042 (solve)"
    assert view[2]["history, each k: c/a at peak load, work per cycle"].startswith("0: ")
    assert view[2]["k at c/a = 0.25 | 0.5 | 0.75"] == "–"
    assert view[0]["cases / converged / consistent"] == "3 / 3 / 3"


def test_a_case_not_resolved_counts_as_a_failure():
    """The key numbers count a converged but unresolved case as not converged."""
    ds = to_dataset(contactlib.sweep("sphere", 0.3, [0.25, 0.5, 0.75], n=64))
    ds.attrs["scene"] = "s"
    row = key_numbers([ds])[0]
    assert row["converged"] == 3 == int(ds["resolved"].sum())
    ds["resolved"].values[1] = False  # c/a = 0.5: its estimate above max_error
    row = key_numbers([ds])[0]
    assert row["converged"] == 2
    assert row["consistent up to c/a"] < 0.5  # the good range stops before it


def test_fretting_key_number_is_the_stick_ratio_at_the_largest_tangential_load():
    """beta = 0 (nu = 1/2): Cattaneo's c/a = sqrt(1 - Q/kP) at Q = 0.5 k P, not the full
    stick (c/a = 1) of the normal loading before it."""
    from contactlib import fretting

    from contactlib.io import fretting_to_dataset

    ds = fretting_to_dataset(fretting("cylinder", 0.5, 0.3, [0, 1, 1], [0, 0, 0.5], 8,
                                         n=64, max_error=1e-3))  # quoted to 3 digits
    row = key_numbers([ds])[0]
    assert abs(row["history c/a at peak load"] - math.sqrt(0.5)) < 2e-3
