"""Load paths of any shape (issue 40, item 5): named periodic shapes and sampled tables.

Truths: identities (an elastic haversine is the list [0, 1, 0, 1, 0]; a table with the
list's points is the list; an elastic answer does not depend on the time unit), the
same viscoelastic path as a dense piecewise-linear list (within the estimate, and
converging to it), the same path in seconds and in units of tau converted by hand, and
the interpolation error bound measured on the steps.
"""

from __future__ import annotations

import contextlib
import io as _io

import numpy as np
import pytest

import contactlib
from contactlib import cli
from contactlib.model import load_paths
from contactlib.io import read_dataset, read_load_table
from contactlib.physical import physical_history

ARRAYS = ("load_ratio", "segment", "contact_radius", "stick_ratio", "indentation",
          "frictional_work", "pressure", "shear", "tangential_displacement", "state",
          "work_error_estimate", "stick_radius_error_estimate", "energy_error_estimate")
HAVERSINE = {"shape": "haversine", "amplitude": 0.5, "mean": 0.5, "cycles": 2}
SINE = {"shape": "sinusoidal", "amplitude": 0.4, "mean": 0.6, "frequency": 0.5, "cycles": 2}
RELAX = [(0.5, 1.0)]


def run_cli(argv: list[str]) -> tuple[int, str, str]:
    out, err = _io.StringIO(), _io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = cli.main(argv)
    return code, out.getvalue(), err.getvalue()


def same(a, b, names=ARRAYS) -> None:
    """The solutions bit for bit; the estimates to round-off (their path coordinates are
    counted in other units: four steps, or a list's segment)."""
    for name in names:
        x, y = np.asarray(getattr(a, name)), np.asarray(getattr(b, name))
        if name.endswith("estimate"):
            assert np.allclose(x, y, rtol=1e-12, atol=1e-15, equal_nan=True), name
        else:
            assert np.array_equal(x, y, equal_nan=True), name


# ----------------------------------------------------------------------------- plan
def test_haversine_pieces_are_its_half_cycles() -> None:
    plan = load_paths.plan(load_paths.load_path(HAVERSINE), 40, viscoelastic=False)
    assert plan.knots == (0.0, 1.0, 0.0, 1.0, 0.0)
    assert plan.counts == (40, 40, 40, 40) and plan.interpolation_error == 0.0


def test_sinusoid_from_its_mean_gets_a_ramp_and_steps_by_load_travel() -> None:
    path = load_paths.load_path(SINE)
    plan = load_paths.plan(path, 100, viscoelastic=False)
    assert plan.knots == pytest.approx((0.0, 0.6, 1.0, 0.2, 1.0, 0.2, 0.6), abs=1e-15)
    # ramp 0 -> 0.6, quarter 0.6 -> 1, half-cycles 1 -> 0.2: steps = 100 x travel, >= 40
    assert plan.counts == (60, 40, 80, 80, 80, 40)
    assert plan.durations == pytest.approx((0.5, 0.5, 1.0, 1.0, 1.0, 0.5))
    assert all(c % 4 == 0 for c in plan.counts)


@pytest.mark.parametrize("tolerance", [1e-3, 1e-5])
def test_interpolation_error_bound_holds_on_the_steps(tolerance) -> None:
    """The largest deviation of the shape from the straight lines between its viscoelastic
    steps, measured on a fine grid, is within the plan's bound, and that is within the
    tolerance asked for."""
    path = load_paths.load_path(SINE)
    plan = load_paths.plan(path, 20, viscoelastic=True, tolerance=tolerance)
    levels, times, _ = load_paths.sample(path, plan, viscoelastic=True)
    assert plan.interpolation_error <= tolerance
    assert np.all(np.diff(times) > 0)
    ramp = plan.durations[0]
    t = np.linspace(ramp, times[-1], 200001)
    exact = path.value(t - ramp)
    worst = float(np.max(np.abs(np.interp(t, times, levels) - exact)))
    assert 0.1 * plan.interpolation_error < worst <= plan.interpolation_error * (1 + 1e-9)


def test_viscoelastic_steps_stay_short_in_time_where_the_load_turns() -> None:
    path = load_paths.load_path(SINE)
    plan = load_paths.plan(path, 50, viscoelastic=True, tolerance=1.0)  # no refinement
    levels, times, segment = load_paths.sample(path, plan, viscoelastic=True)
    for g, (c, d) in enumerate(zip(plan.counts, plan.durations), start=1):
        steps = segment == g
        span = abs(plan.knots[g] - plan.knots[g - 1])
        dt = np.diff(np.concatenate([[times[np.flatnonzero(steps)[0] - 1]], times[steps]]))
        dl = np.diff(np.concatenate([[levels[np.flatnonzero(steps)[0] - 1]], levels[steps]]))
        assert dt.max() <= 2 * d / c * (1 + 1e-9)
        assert np.abs(dl).max() <= 2 * span / c * (1 + 1e-9)


def test_coarse_runs_take_every_second_and_fourth_step() -> None:
    path = load_paths.load_path(SINE)
    plan = load_paths.plan(path, 40, viscoelastic=True)
    full = load_paths.sample(path, plan, True)
    for divide in (2, 4):
        part = load_paths.sample(path, plan, True, divide)
        # each piece's count is a multiple of 4, so the coarse steps are every divide-th
        assert np.allclose(part[0], full[0][::divide], rtol=0, atol=1e-12)
        assert np.allclose(part[1], full[1][::divide], rtol=0, atol=1e-12)
        assert np.array_equal(part[2], full[2][::divide])


# ----------------------------------------------------------------------------- identities
def test_elastic_haversine_is_the_list_path() -> None:
    """Rate-independent body: a haversine from 0 is exactly [0, 1, 0, 1, 0], estimates too."""
    shape = contactlib.history("sphere", 0.3, 0.2, HAVERSINE, 40, n=60)
    listed = contactlib.history("sphere", 0.3, 0.2, [0, 1, 0, 1, 0], 40, n=60)
    same(shape, listed)
    assert shape.segment_steps == (40, 40, 40, 40) and listed.segment_steps == ()
    assert np.array_equal(shape.segment_work(), listed.segment_work())
    assert [shape.segment_end(i) for i in range(5)] == [listed.segment_end(i)
                                                         for i in range(5)]
    assert shape.load_shape == HAVERSINE and shape.time is None


def test_elastic_answer_does_not_depend_on_the_time_unit() -> None:
    base = contactlib.history("cylinder", 0.3, 0.2, dict(SINE, frequency=1.0), 40, n=40)
    for frequency in (None, 1e-3, 7.0):
        spec = dict(SINE)
        spec.pop("frequency")
        if frequency is not None:
            spec["frequency"] = frequency
        same(contactlib.history("cylinder", 0.3, 0.2, spec, 40, n=40), base)


def test_csv_table_is_the_list_path(tmp_path) -> None:
    """A table with the list's points: the same history (elastic: times immaterial)."""
    csv = tmp_path / "path.csv"
    csv.write_text("# a load-unload cycle and a reload to 0.6\ntime,load\n0,0\n0.5,1\n"
                   "2,0\n\n3,0.6\n")
    table = read_load_table(csv)
    assert table == {"time": [0.0, 0.5, 2.0, 3.0], "load": [0.0, 1.0, 0.0, 0.6]}
    res = contactlib.history("sphere", 0.3, 0.2, table, 40, n=60)
    assert res.segment_steps == (40, 40, 40)  # 40 x travel 1, 1, 0.6 (at least 40)
    listed = contactlib.history("sphere", 0.3, 0.2, [0, 1, 0, 0.6], 40, n=60)
    same(res, listed)


def test_viscoelastic_table_is_the_list_path_with_its_durations() -> None:
    """A table's straight pieces are the list's segments with their durations: the
    blended steps are equal steps there, so the runs agree to round-off."""
    table = {"time": [0.0, 0.5, 1.5], "load": [0.0, 1.0, 0.0]}
    res = contactlib.history("sphere", 0.3, 0.2, table, 20, n=40, relaxation=RELAX)
    assert res.segment_steps == (40, 40) and res.durations == (0.5, 1.0)
    listed = contactlib.history("sphere", 0.3, 0.2, [0, 1, 0], 40, n=40, relaxation=RELAX,
                                duration=[0.5, 1.0])
    for name in ("load_ratio", "time", "frictional_work", "viscous_work", "stored_energy"):
        assert np.allclose(getattr(res, name), getattr(listed, name), rtol=1e-9,
                           atol=1e-15), name


# ----------------------------------------------------------------------------- convergence
def dense_sine(m: int) -> tuple[list[float], list[float]]:
    """SINE with its ramp as a list of 2m + m/4 points (durations in the unit of tau)."""
    path = load_paths.load_path(SINE)
    t = np.linspace(0.0, 4.0, 2 * m + 1)
    ramp = np.linspace(0.0, 0.6, m // 4 + 1)
    return list(ramp) + list(path.value(t)[1:]), [0.5 / (m // 4)] * (m // 4) + \
        list(np.diff(t))


@pytest.mark.slow
def test_viscoelastic_sinusoid_against_a_dense_list() -> None:
    """The adaptive steps of a sinusoid and the same path as a dense list (1000 points a
    cycle, one step each) agree within the shape's estimates, and the difference falls
    under refinement of the shape's steps."""
    levels, durations = dense_sine(1000)
    dense = contactlib.history("sphere", 0.3, 0.2, levels, 1, n=60, relaxation=RELAX,
                               duration=durations, error_estimate=False)
    res = contactlib.history("sphere", 0.3, 0.2, SINE, 50, n=60, relaxation=RELAX)
    work = abs(res.frictional_work[-1] - dense.frictional_work[-1])
    assert work <= res.work_error_estimate[-1] * res.work_scale
    viscous = abs(res.viscous_work[-1] - dense.viscous_work[-1])
    assert viscous <= res.energy_error_estimate[-1] * res.energy_scale
    diffs = [viscous]
    for steps in (100, 200):
        finer = contactlib.history("sphere", 0.3, 0.2, SINE, steps, n=60, relaxation=RELAX,
                                   error_estimate=False)
        diffs.append(abs(finer.viscous_work[-1] - dense.viscous_work[-1]))
    assert diffs[2] < diffs[1] / 2 < diffs[0] / 4


# ----------------------------------------------------------------------------- seconds
def test_viscoelastic_shape_in_seconds_is_the_one_in_units_of_tau() -> None:
    """Ball on a polymer, 60 N +- 40 N at 1 Hz, tau = 0.2 s: the dimensionless history with
    tau = 1 and f = 0.2 per tau, levels over P_max = 100 N, converted by hand."""
    e0, nu, radius = 10e9, 0.4, 5e-3
    es = e0 / (1 - nu ** 2)
    spec = {"shape": "sinusoidal", "amplitude": "40N", "mean": "60N", "frequency": "1Hz",
            "cycles": 1}
    res = physical_history("sphere", "5mm", spec, "rigid", ("10GPa", nu), 0.2,
                           relaxation=[(0.5, "200ms")], steps=20, n=40)
    dim = contactlib.history("sphere", nu, 0.2, {"shape": "sinusoidal", "amplitude": 0.4,
                                                 "mean": 0.6, "frequency": 0.2, "cycles": 1},
                             20, n=40, relaxation=[(0.5, 1.0)])
    a_max = (3.0 * 100.0 * radius / (4.0 * es)) ** (1.0 / 3.0)
    w = es * a_max ** 5 / radius ** 2
    assert res.result.segment_steps == dim.segment_steps
    assert np.allclose(res.time, dim.time * 0.2, rtol=1e-12, atol=0)
    # the solver rounds each step's duration to 10 digits (contactlib.solvers.history_solver.
    # run_history, so that equal steps share their operators): in s and in units of tau
    # the roundings differ, by up to 5e-11 of a step (measured: 3.8e-10 of the energies)
    assert np.allclose(res.frictional_energy, dim.frictional_work * w, rtol=2e-9, atol=0)
    assert np.allclose(res.viscous_energy, dim.viscous_work * w, rtol=2e-9, atol=0)
    assert res.load_path == pytest.approx((0, 60, 100, 20, 60), rel=1e-12)
    assert res.times == pytest.approx((0, 0.25, 0.5, 1.0, 1.25), rel=1e-12)


def test_table_units_in_the_header(tmp_path) -> None:
    """time [ms], force [kN] in the header: the same history as s and N."""
    a, b = tmp_path / "a.csv", tmp_path / "b.csv"
    a.write_text("time,force\n0,0\n0.5,100\n1.5,0\n")
    b.write_text("time [ms],force [kN]\n0,0\n500,0.1\n1500,0\n")
    runs = [physical_history("sphere", "5mm", read_load_table(p, physical=True), "rigid",
                             ("10GPa", 0.4), 0.2, relaxation=[(0.5, "0.2s")], steps=20, n=40)
            for p in (a, b)]
    assert np.allclose(runs[0].viscous_energy, runs[1].viscous_energy, rtol=1e-12, atol=0)
    assert np.allclose(runs[0].time, runs[1].time, rtol=1e-12, atol=0)


def test_cli_table_and_shape_match_the_library(tmp_path) -> None:
    csv = tmp_path / "p.csv"
    csv.write_text("time,load\n0,0\n1,1\n2,0\n")
    common = ["history", "--geometry", "sphere", "--nu", "0.3", "--friction", "0.2",
              "--steps", "20", "--n", "40"]
    code, out, err = run_cli(common + ["--load-table", str(csv), "--output",
                                       str(tmp_path / "t.nc")])
    assert code == 0, err
    code, out2, err = run_cli(common + ["--load-shape", "haversine", "--amplitude", "0.5",
                                        "--mean", "0.5", "--cycles", "1", "--output",
                                        str(tmp_path / "s.nc")])
    assert code == 0, err
    t, s = read_dataset(tmp_path / "t.nc"), read_dataset(tmp_path / "s.nc")
    lib = contactlib.history("sphere", 0.3, 0.2, [0, 1, 0], 20, n=40)
    for ds in (t, s):
        assert np.array_equal(ds["frictional_work"].values, lib.frictional_work)
        assert list(ds.attrs["segment_steps"]) == [20, 20]
    assert s.attrs["load_path_shape"] == "haversine" and t.attrs["load_path_shape"] == "table"
    assert "steps per load travel of P_max" in out2


# ----------------------------------------------------------------------------- bad input
BAD_API = [
    ({"shape": "square", "amplitude": 0.5, "mean": 0.5, "cycles": 1}, "load_path.shape"),
    ({"shape": "sinusoidal", "amplitude": 0.5, "mean": 0.5, "cycles": 1, "frequency": -1},
     "load_path.frequency"),
    ({"shape": "sinusoidal", "amplitude": 0.5, "mean": 0.5, "cycles": 1,
      "frequency": float("inf")}, "load_path.frequency"),
    ({"shape": "sinusoidal", "amplitude": float("nan"), "mean": 0.5, "cycles": 1},
     "load_path.amplitude"),
    ({"shape": "sinusoidal", "amplitude": 0.5, "mean": 0.5, "cycles": 0}, "load_path.cycles"),
    ({"shape": "sinusoidal", "amplitude": 0.5, "mean": 0.4, "cycles": 1}, "mean - amplitude"),
    ({"shape": "sinusoidal", "amplitude": 0.5, "mean": 0.6, "cycles": 1}, "mean + amplitude"),
    ({"shape": "sinusoidal", "amplitude": 0.5, "mean": 0.5}, "needs 'cycles'"),
    ({"shape": "sinusoidal", "amplitude": 0.5, "mean": 0.5, "cycles": 1, "phase": 0},
     "unknown key 'phase'"),
    ({"shape": "haversine", "amplitude": "0.5", "mean": 0.5, "cycles": 1},
     "load_path.amplitude"),
    ({"time": [0, 1], "load": [0, 1, 0]}, "differ in length"),
    ({"time": [0, 1, 1], "load": [0, 1, 0]}, "load_path.time must increase"),
    ({"time": [0, 1, float("nan")], "load": [0, 1, 0]}, "load_path.time"),
    ({"time": [0, 1], "load": [0.5, 1]}, "must start at 0"),
    ({"time": [0, 1], "load": [0, 2]}, "load_path"),
    ({"time": [0], "load": [0]}, "at least two points"),
    ({"time": [0, 1], "force": [0, 1]}, "exactly the keys time and load"),
    ({"t": [0, 1]}, "missing 'time'"),
]


@pytest.mark.parametrize("spec, words", BAD_API, ids=[w for _, w in BAD_API])
def test_bad_shape_or_table_is_a_value_error_naming_it(spec, words) -> None:
    with pytest.raises(ValueError, match="load_path") as info:
        contactlib.history("sphere", 0.3, 0.2, spec, 4, n=40)
    assert words in str(info.value)


def test_shape_with_duration_or_without_frequency_under_relaxation() -> None:
    with pytest.raises(ValueError, match="duration must not be given"):
        contactlib.history("sphere", 0.3, 0.2, HAVERSINE, 4, n=40, relaxation=RELAX,
                           duration=1.0)
    with pytest.raises(ValueError, match="frequency is required"):
        contactlib.history("sphere", 0.3, 0.2, HAVERSINE, 4, n=40, relaxation=RELAX)
    with pytest.raises(ValueError, match="times must not be given"):
        physical_history("sphere", "5mm", {"time": [0, 1], "force": [0, 10]}, "rigid",
                         ("3GPa", 0.4), 0.2, times=[0, 1])


BAD_CSV = [
    ("", "empty"),
    ("time,force\n0,0\n1,1\n", "expected a header 'time,load'"),
    ("t,load\n0,0\n1,1\n", "expected a header"),
    ("time,load,extra\n0,0,0\n1,1,1\n", "3 columns"),
    ("time\n0\n1\n", "expected a header"),
    ("time,load\n0,0\n1\n", "line 3: expected two cells"),
    ("time,load\n0,0\n1,1,2\n", "line 3: expected two cells"),
    ("time,load\n0,0\n1,abc\n", "line 3: 'abc' is not a number"),
    ("time,load\n0,0\n1,nan\n", "line 3: 'nan' is not finite"),
    ("time,load\n0,0\ninf,1\n", "'inf' is not finite"),
    ("time,load\n0,0\n", "at least two rows"),
    ("time [s],load\n0,0\n1,1\n", "expected a header"),
    ("time,load\n0,0\n1,1\n1,0\n", "--load-table must increase"),
    ("time,load\n0,0.5\n1,1\n", "must start at 0"),
    ("time,load\n0,0\n1,-1\n", "--load-table"),
    ("time,load\n0,0\n1,1.5\n", "--load-table"),
]


@pytest.mark.parametrize("text, words", BAD_CSV, ids=[w for _, w in BAD_CSV])
def test_malformed_csv_is_one_line_and_exit_2(tmp_path, text, words) -> None:
    csv = tmp_path / "bad.csv"
    csv.write_text(text)
    out_file = tmp_path / "o.nc"
    code, out, err = run_cli(["history", "--geometry", "sphere", "--nu", "0.3", "--friction",
                              "0.2", "--steps", "4", "--load-table", str(csv), "--output",
                              str(out_file)])
    assert code == 2, (code, err)
    assert err.startswith("contactlib: error: --load-table") and err.count("\n") == 1, err
    assert words in err, err
    assert "Traceback" not in err and out == "" and not out_file.exists()


def test_csv_reader_errors_are_value_errors(tmp_path) -> None:
    with pytest.raises(ValueError, match="no such file"):
        read_load_table(tmp_path / "missing.csv")
    with pytest.raises(ValueError, match="is a folder"):
        read_load_table(tmp_path)
    bad = tmp_path / "latin.csv"
    bad.write_bytes(b"time,load\n0,0\n1,\xe9\n")
    with pytest.raises(ValueError, match="not UTF-8"):
        read_load_table(bad)
    unit = tmp_path / "unit.csv"
    unit.write_text("time [fortnight],force\n0,0\n1,1\n")
    with pytest.raises(ValueError, match="unknown unit 'fortnight'"):
        read_load_table(unit, physical=True)


HIST = ["history", "--geometry", "sphere", "--nu", "0.3", "--friction", "0.2", "--steps",
        "4"]
PHYS = ["history", "--geometry", "sphere", "--radius", "5mm", "--body", "3GPa,0.4",
        "--friction", "0.2"]
SHAPE = ["--load-shape", "sinusoidal", "--amplitude", "0.4", "--mean", "0.6", "--cycles", "1"]
PSHAPE = ["--load-shape", "sinusoidal", "--amplitude", "40N", "--mean", "60N", "--cycles",
          "1", "--frequency", "1Hz"]
BAD_CLI = [
    (HIST + ["--load-shape", "square", "--amplitude", "0.5", "--mean", "0.5", "--cycles", "1"],
     "--load-shape must be one of sinusoidal, haversine"),
    (HIST + SHAPE + ["--frequency", "-1"], "--frequency must be > 0"),
    (HIST + SHAPE + ["--frequency", "nan"], "--frequency must be finite"),
    (HIST + SHAPE + ["--frequency", "fast"], "--frequency must be"),
    (HIST + SHAPE[:-2], "missing --cycles"),
    (HIST + SHAPE + ["--ramp", "0"], "--ramp must be > 0"),
    (HIST + ["--load-shape", "haversine", "--amplitude", "0.5", "--mean", "0.2", "--cycles",
             "1"], "--mean: mean - amplitude"),
    (HIST + SHAPE + ["--load-path", "0,1"], "give one of --load-path, --load-shape"),
    (HIST, "give one of --load-path, --load-shape and --load-table"),
    (HIST + ["--load-path", "0,1", "--cycles", "2"], "--cycles goes with --load-shape"),
    (HIST + SHAPE + ["--relaxation", "0.5:1"], "--frequency is required"),
    (HIST + SHAPE + ["--frequency", "1", "--relaxation", "0.5:1", "--duration", "2"],
     "--duration is not used with --load-shape"),
    (PHYS + PSHAPE + ["--relaxation", "0.5:0.2s", "--times", "0s,1s"],
     "--times is not used with --load-shape"),
    (PHYS + PSHAPE[:-2] + ["--frequency", "1s"], "'s' is a unit of time"),
    (PHYS + PSHAPE[:4] + ["--mean", "60Pa", "--cycles", "1"], "--mean must be"),
    (PHYS + PSHAPE[:-2] + ["--frequency", "-1Hz"], "--frequency must be"),
    (PHYS + ["--load-table", "/nonexistent/p.csv"], "--load-table: /nonexistent/p.csv: no such"),
]


@pytest.mark.parametrize("argv, words", BAD_CLI, ids=[w for _, w in BAD_CLI])
def test_bad_shape_options_are_one_line_and_exit_2(tmp_path, argv, words) -> None:
    out_file = tmp_path / "o.nc"
    code, out, err = run_cli(argv + ["--output", str(out_file)])
    assert code == 2, (code, err)
    assert err.startswith("contactlib: error: ") and err.count("\n") == 1, err
    assert words in err, err
    assert "Traceback" not in err and out == "" and not out_file.exists()


def test_at_least_thirty_bad_path_inputs() -> None:
    assert len(BAD_API) + len(BAD_CSV) + len(BAD_CLI) >= 30
