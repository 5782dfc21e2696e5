"""The sphere's stick-zone map of the workflow (rule fretting_stick_map, issue 37): the
library's study, its table of radii per direction and the figure's estimate marks.

The study at n = 16 and 4 steps a segment (the workflow runs n = 64; about 5 s
here): its uncoupled case (equal bodies, nu = 0, beta = gamma = 0) against
Cattaneo–Mindlin's c = (1 - Q/kP)^(1/3) a_max in every direction within the estimates.
"""

from __future__ import annotations

import numpy as np
import pytest

from contactlib import io, summary
from contactlib.fretting_api import (STICK_MAP_CASES, STICK_MAP_MAX_ERROR, STICK_MAP_PATH,
                                     stick_map_study)
from contactlib.plot.fretting import fig_stick_zone_map


@pytest.fixture(scope="module")
def study():
    return stick_map_study(n=16, steps=4)


def test_study_cases_and_mindlin(study):
    """Both cases, in the order of STICK_MAP_CASES, converged, on the map's path; the
    uncoupled case's radius in every direction within its estimate of Mindlin's."""
    assert list(study) == list(STICK_MAP_CASES)
    coupled, uncoupled = study.values()
    assert coupled.beta == pytest.approx(2 / 7) and uncoupled.beta == 0.0
    for r in study.values():
        assert r.converged.all() and r.max_error == STICK_MAP_MAX_ERROR
        assert r.tangential_path == STICK_MAP_PATH[1] and r.load_path == STICK_MAP_PATH[0]
    r = uncoupled
    for i, x in enumerate(STICK_MAP_PATH[1]):
        if i < 2:
            continue
        c = r.stick_radius_directions[r.point_step[i]]
        e = r.stick_radius_directions_error[i]
        assert np.all(np.abs(c - (1 - x) ** (1 / 3)) <= e), (x, c, e)


def test_table_rows(study):
    """One row a case, loaded path point and direction; resolved where the estimate is
    within the dataset's max_error; the values are the dataset's."""
    datasets = [io.fretting_to_dataset(r) for r in study.values()]
    rows = summary.stick_direction_rows(datasets, list(study))
    points = len(STICK_MAP_PATH[0]) - 1  # the unloaded start has no row
    assert len(rows) == 2 * points * 24
    ds = datasets[0]
    first = [row for row in rows if row["case"] == "coupled" and row["point"] == 3]
    err = ds["stick_radius_directions_error_estimate"].values[3]
    radius = ds["stick_radius_directions"].values[ds["point_step"].values[3]]
    assert [row["stick radius resolved"] for row in first] == list(err <= STICK_MAP_MAX_ERROR)
    np.testing.assert_allclose([float(row["stick radius/a_max"]) for row in first], radius,
                               rtol=1e-5)
    assert [float(row["direction [deg]"]) for row in first] == pytest.approx(
        np.arange(24) * 15.0)


def test_figure_marks_resolved_and_unresolved_directions(study):
    """Per step a band of +- the estimate and one marker a direction: filled where the radius
    is resolved, open where not; a step that is no path point gets markers alone."""
    ds = io.fretting_to_dataset(study["coupled"])
    pts = [int(j) for j in ds["point_step"].values[2:]]
    fig = fig_stick_zone_map(ds)
    ax = fig.axes[0]
    lines = {g: [x for x in ax.get_lines() if x.get_gid() == g]
             for g in ("stick-resolved", "stick-unresolved")}
    assert len(lines["stick-resolved"]) == len(lines["stick-unresolved"]) == len(pts)
    err = ds["stick_radius_directions_error_estimate"].values[2:]
    for k in range(len(pts)):
        ok = int(np.sum(err[k] <= STICK_MAP_MAX_ERROR))
        assert len(lines["stick-resolved"][k].get_xdata()) == ok
        assert len(lines["stick-unresolved"][k].get_xdata()) == 24 - ok
    assert [p.get_gid() for p in ax.patches].count("stick-estimate") == len(pts)
    fig = fig_stick_zone_map(ds, steps=[pts[0] - 1])  # between two path points
    gids = [x.get_gid() for x in fig.axes[0].get_lines()]
    assert gids.count("stick-direction") == 1 and "stick-resolved" not in gids
