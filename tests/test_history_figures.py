"""Tests for contactlib.plot.history (figures of a loading history)."""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest
import xarray as xr
from matplotlib.collections import QuadMesh
from matplotlib.figure import Figure
from matplotlib.layout_engine import ConstrainedLayoutEngine

from contactlib import history
from contactlib.io import history_to_dataset, stack_histories, write_figure
from contactlib.plot import history as hf

N = 60
STEPS = 10
KS = (0.1, 0.2, 0.3)
NOT_CONVERGED = "not-converged"
FUNCTIONS = {
    "stick_radius": hf.hist_stick_radius,
    "stick_map": hf.hist_stick_map,
    "displacement_loop": hf.hist_displacement_loop,
    "energy_per_cycle": hf.hist_energy_per_cycle,
}


def run(geometry: str, k: float, path: list[float], steps: int = STEPS) -> xr.Dataset:
    return history_to_dataset(history(geometry, 0.3, k, path, steps, n=N))


@pytest.fixture(scope="module")
def data() -> dict[str, xr.Dataset]:
    """Small histories, built once (well under a second in all)."""
    singles = {k: run("sphere", k, [0, 1, 0]) for k in KS}
    cylinder = run("cylinder", 0.2, [0, 1, 0])
    cylinder.attrs["scene"] = "half-plane"
    cycle = stack_histories([run("sphere", k, [0, 1, 0.5, 1, 0.5], 6) for k in (0.1, 0.3)])
    cycle.attrs["scene"] = "sphere-cycling"
    out = {
        "single": singles[0.2],
        "stack": stack_histories(list(singles.values())),
        "cycle": cycle,
        "cylinder": cylinder,
        "monotonic": stack_histories([run("sphere", k, [0, 1], 20) for k in (0.2, 0.3)]),
    }
    out["single-fail-3"] = fail(out["single"], 3)
    out["cycle-fail-20"] = fail(cycle, 20)  # a step of the last cycle (13-24), not of segment 1
    return out


@pytest.fixture(scope="module")
def figure(data):
    """``figure(name, *datasets, **options)``: the figure, built once per module.

    Every build is checked to leave the caller's rcParams untouched and to
    return a figure whose layout is frozen (no live constrained layout).
    """
    cache: dict[tuple, Figure] = {}

    def get(name: str, *which: str, **options: object) -> Figure:
        key = (name, which, tuple(sorted(options.items())))
        if key not in cache:
            before = dict(matplotlib.rcParams)
            items = [data[w] for w in which]
            fig = FUNCTIONS[name](items if len(items) > 1 else items[0], **options)
            assert dict(matplotlib.rcParams) == before
            assert isinstance(fig, Figure)
            assert not isinstance(fig.get_layout_engine(), ConstrainedLayoutEngine)
            cache[key] = fig
        return cache[key]

    return get


def lines(fig: Figure, gid: str) -> list:
    return [line for ax in fig.axes for line in ax.lines if line.get_gid() == gid]


def crosses(fig: Figure) -> np.ndarray:
    """(x, y) of every point drawn with the not-converged cross."""
    pts = [np.column_stack([line.get_xdata(), line.get_ydata()])
           for line in lines(fig, NOT_CONVERGED)]
    return np.concatenate(pts) if pts else np.empty((0, 2))


def legend_texts(fig: Figure) -> list[str]:
    return [t.get_text() for ax in fig.axes if ax.get_legend() is not None
            for t in ax.get_legend().get_texts()]


def fail(ds: xr.Dataset, step: int) -> xr.Dataset:
    """Copy of ``ds`` with ``step`` flagged as not converged (every k)."""
    out = ds.copy(deep=True)
    out["converged"].values[..., step] = False
    return out


def stick(ds: xr.Dataset) -> np.ndarray:
    return np.asarray((ds["stick_ratio"] * ds["contact_radius"]).values)


def same(a, b) -> bool:
    return np.array_equal(np.asarray(a, float), np.asarray(b, float), equal_nan=True)


# ----------------------------------------------------------------------------- common
# the richest input of each figure (several datasets where it takes them)
RICH = {
    "stick_radius": ("stack", "cycle"),
    "stick_map": ("stack",),
    "displacement_loop": ("single", "cycle", "cylinder"),
    "energy_per_cycle": ("stack", "cycle"),
}


@pytest.mark.parametrize("name", [pytest.param(name, marks=() if i == 0 else pytest.mark.slow)
                                  for i, name in enumerate(sorted(FUNCTIONS))])
def test_png_is_byte_reproducible(figure, name, tmp_path):
    fig = figure(name, *RICH[name])
    assert not lines(fig, NOT_CONVERGED)  # every step converged here
    first = write_figure(fig, tmp_path / "a.png")
    second = write_figure(fig, tmp_path / "b.png")
    raw = first.read_bytes()
    assert raw[:8] == b"\x89PNG\r\n\x1a\n"
    assert raw == second.read_bytes()


@pytest.mark.parametrize("name, variable", [
    ("stick_radius", "stick_ratio"),
    ("stick_map", "state"),
    ("displacement_loop", "tangential_displacement"),
    ("energy_per_cycle", "frictional_work"),
    ("energy_per_cycle", "converged"),
])
def test_missing_variable_is_named(data, name, variable):
    bad = data["single"].drop_vars(variable)
    with pytest.raises(ValueError, match=rf"'{variable}'.*dataset 0"):
        FUNCTIONS[name](bad)
    if name != "stick_map":  # the others take several datasets: the culprit is named
        bad = data["cycle"].drop_vars(variable)
        bad.attrs["scene"] = "broken-scene"
        with pytest.raises(ValueError, match=rf"'{variable}'.*dataset 1 \('broken-scene'\)"):
            FUNCTIONS[name]([data["stack"], bad])


def test_missing_friction_and_geometry(data):
    bad = data["single"].copy()
    del bad.attrs["friction_coefficient"]
    with pytest.raises(ValueError, match="friction_coefficient"):
        hf.hist_stick_radius(bad)
    bad = data["single"].copy()
    bad.attrs["geometry"] = "cone"
    with pytest.raises(ValueError, match="geometry"):
        hf.hist_energy_per_cycle(bad)
    with pytest.raises(TypeError):
        hf.hist_stick_radius([data["single"], "not a dataset"])
    with pytest.raises(ValueError, match="at least one"):
        hf.hist_displacement_loop([])


# ----------------------------------------------------------------------------- stick radius
def test_stick_radius_draws_the_data(data, figure):
    st = data["stack"]
    fig = figure("stick_radius", "stack")
    assert len(fig.axes) == 3  # load, radius, legend holder
    c_lines, a_lines = lines(fig, "stick-radius"), lines(fig, "contact-radius")
    assert len(c_lines) == len(a_lines) == len(KS)
    (load,) = lines(fig, "load")
    assert same(load.get_ydata(), st["load_ratio"])
    c, a = stick(st), st["contact_radius"].values
    for i, k in enumerate(KS):
        assert c_lines[i].get_label() == f"k = {k}"
        # x is the load travelled: on 0 -> 1 -> 0 in equal steps, step / STEPS
        np.testing.assert_allclose(c_lines[i].get_xdata(), st["step"].values / STEPS,
                                   rtol=1e-12, atol=1e-14)  # float sums of 0.1
        assert same(c_lines[i].get_ydata(), c[i])
        assert same(a_lines[i].get_ydata(), a[i])
    # one dotted line per panel at the end of segment 1 (load travelled 1)
    ends = lines(fig, "segment-end")
    assert len(ends) == 2 and all(line.get_xdata()[0] == pytest.approx(1.0) for line in ends)
    # the radius axis starts just below zero: a stick zone of radius ~0 stays visible
    assert -0.05 < fig.axes[1].get_ylim()[0] < 0.0


def test_stick_radius_several_datasets(figure):
    fig = figure("stick_radius", "stack", "cycle")
    assert len(lines(fig, "stick-radius")) == len(KS) + 2
    assert len(lines(fig, "load")) == 2  # two different paths
    colors = [matplotlib.colors.to_hex(line.get_color()) for line in lines(fig, "stick-radius")]
    assert len(set(colors)) == len(colors)
    assert "sphere-cycling: k = 0.3" in legend_texts(fig)


def test_stick_radius_single_equals_stacked(figure):
    one = lines(figure("stick_radius", "single"), "stick-radius")
    many = lines(figure("stick_radius", "stack"), "stick-radius")
    (match,) = [line for line in many if line.get_label() == "k = 0.2"]
    assert len(one) == 1 and one[0].get_label() == "k = 0.2"
    assert same(one[0].get_ydata(), match.get_ydata())
    assert same(one[0].get_xdata(), match.get_xdata())


def test_stick_radius_marks_failed_steps(data, figure):
    ds = data["single-fail-3"]
    fig = figure("stick_radius", "single-fail-3")
    (line,) = lines(fig, "stick-radius")
    assert len(line.get_xdata()) == ds.sizes["step"]  # the failed step is kept
    pts = crosses(fig)
    c, a = stick(ds)[3], float(ds["contact_radius"][3])
    x = 3.0 / STEPS  # the load travelled at step 3
    assert np.allclose(sorted(map(tuple, pts)), sorted([(x, c), (x, a)]))
    assert any("NOT CONVERGED at 1 step" in t for t in legend_texts(fig))


def test_stick_radius_marks_unresolved_steps_hollow():
    """A converged step whose stick radius's estimate exceeds max_error gets a hollow
    circle on its curve, at its (load travelled, c) and nowhere else; a dataset resolved
    everywhere (max_error 0.5) gets none and no legend entry."""
    for max_error, expect_marks in ((1e-3, True), (0.5, False)):
        ds = history_to_dataset(history("sphere", 0.3, 0.2, [0, 1, 0], STEPS, n=N,
                                        max_error=max_error))
        fig = hf.hist_stick_radius(ds)
        marks = lines(fig, "stick-radius-unresolved")
        loose = ((ds["stick_radius_error_estimate"].values > max_error)
                 & ds["converged"].values.astype(bool))
        assert bool(loose.any()) == expect_marks and len(marks) == int(expect_marks)
        has_key = any("not resolved to max_error" in t for t in legend_texts(fig))
        assert has_key == expect_marks
        if expect_marks:
            (line,) = lines(fig, "stick-radius")
            x, c = np.asarray(line.get_xdata()), np.asarray(line.get_ydata())
            assert np.array_equal(marks[0].get_xdata(), x[loose])
            assert np.array_equal(marks[0].get_ydata(), c[loose])
            assert marks[0].get_markerfacecolor() == "white"


def test_monotonic_loading_stick_zone_grows_inside_contact(figure):
    """Physics: loading only, the stick zone c never recedes and never exceeds a."""
    fig = figure("stick_radius", "monotonic")
    c_lines, a_lines = lines(fig, "stick-radius"), lines(fig, "contact-radius")
    assert len(c_lines) == 2
    for c_line, a_line in zip(c_lines, a_lines):
        c, a = np.asarray(c_line.get_ydata()), np.asarray(a_line.get_ydata())
        contact = a > 0
        assert np.all(np.isfinite(c[contact])) and np.all(np.isnan(c[~contact]))
        assert contact[1:].all()  # in contact from the first step on
        assert np.all(np.diff(c[1:]) >= 0)
        assert np.all(c[1:] <= a[1:])
        assert c[-1] > c[1] > 0


# ----------------------------------------------------------------------------- stick map
def mesh_of(ax) -> QuadMesh:
    (mesh,) = [m for m in ax.collections if isinstance(m, QuadMesh)]
    assert mesh.get_gid() == "state-map"
    return mesh


def drawn_state(ax, like: np.ndarray) -> np.ndarray:
    return np.asarray(mesh_of(ax).get_array()).reshape(like.T.shape)


def test_stick_map_single(data, figure):
    ds = data["single"]
    fig = figure("stick_map", "single")
    assert len(fig.axes) == 3  # load, one map, legend holder
    state = ds["state"].values
    assert same(drawn_state(fig.axes[1], state), state.T)
    xy = mesh_of(fig.axes[1]).get_coordinates()
    bounds = ds["xi_bounds"].values
    assert same(xy[0, :, 0], np.arange(ds.sizes["step"] + 1) - 0.5)
    assert same(xy[:, 0, 1], np.append(bounds[:, 0], bounds[-1, 1]))
    texts = legend_texts(fig)
    for name in ("separated", "stick", "slip toward the axis", "slip away from the axis"):
        assert name in texts
    (a_line,) = lines(fig, "contact-radius")
    assert same(a_line.get_ydata(), ds["contact_radius"])
    (c_line,) = lines(fig, "stick-radius")
    assert same(c_line.get_ydata(), stick(ds))


def test_stick_map_stack_panels_and_choice(data, figure):
    st = data["stack"]
    fig = figure("stick_map", "stack")
    assert len(fig.axes) == 2 + len(KS)
    for i, ax in enumerate(fig.axes[1:-1]):
        state = st["state"].values[i]
        assert same(drawn_state(ax, state), state.T)
        assert ax.get_title(loc="left") == f"k = {KS[i]}"
    # the single dataset draws the same map as its k in the stack
    one = figure("stick_map", "single").axes[1]
    assert same(mesh_of(one).get_array(), mesh_of(fig.axes[2]).get_array())
    fig = figure("stick_map", "stack", friction=0.26)  # nearest: 0.3
    assert len(fig.axes) == 3
    assert fig.axes[1].get_title(loc="left") == "k = 0.3"
    state = st["state"].sel(friction_coefficient=0.3).values
    assert same(drawn_state(fig.axes[1], state), state.T)


def test_stick_map_asks_for_friction(data):
    many = stack_histories([run("sphere", k, [0, 1, 0], 2) for k in (0.1, 0.2, 0.3, 0.4, 0.5)])
    with pytest.raises(ValueError, match="friction="):
        hf.hist_stick_map(many)
    for bad in (-1.0, float("nan"), "0.2", True):
        with pytest.raises(ValueError, match="friction"):
            hf.hist_stick_map(data["stack"], friction=bad)
    with pytest.raises(TypeError):
        hf.hist_stick_map([data["single"]])


def test_stick_map_marks_failed_steps(data, figure):
    ds = data["single-fail-3"]
    fig = figure("stick_map", "single-fail-3")
    pts = crosses(fig)
    assert pts.shape == (1, 2) and pts[0, 0] == 3.0
    assert np.asarray(mesh_of(fig.axes[1]).get_array()).size == ds["state"].size


# ----------------------------------------------------------------------------- loop
def test_displacement_loop_draws_the_data(data, figure):
    st = data["stack"]
    fig = figure("displacement_loop", "stack")  # default xi = 0.8
    ax = fig.axes[0]
    loops = lines(fig, "displacement-loop")
    assert len(loops) == len(KS)
    j = int(np.argmin(np.abs(st["xi"].values - 0.8)))
    used = float(st["xi"].values[j])
    assert f"{used:.4g}" in ax.get_title() and ax.get_title().count("\n") == 1  # two lines
    arrows = [t for t in ax.texts if t.get_gid() == "direction-arrow"]
    assert len(arrows) == 2 * len(KS)  # one a segment and k
    u = st["tangential_displacement"].values[:, :, j]
    for i, line in enumerate(loops):
        assert same(line.get_xdata(), st["load_ratio"])
        assert same(line.get_ydata(), u[i])
    # one direction arrow per k and path segment
    arrows = [t for t in ax.texts if getattr(t, "arrow_patch", None) is not None]
    assert len(arrows) == len(KS) * 2
    # the loading arrows point to larger loads, the unloading arrows to smaller ones
    heads = np.sort([a.xy[0] - a.xyann[0] for a in arrows])
    assert np.all(heads[:len(KS)] < 0) and np.all(heads[len(KS):] > 0)


def test_displacement_loop_several_and_single(figure):
    fig = figure("displacement_loop", "single", "cycle", "cylinder")
    assert len(fig.axes) == 6  # three panels, three legend holders
    assert len(lines(fig, "displacement-loop")) == 1 + 2 + 1
    panels = [ax for ax in fig.axes if ax.get_title()]
    assert len(panels) == 3 and "x/a_max" in panels[2].get_title()
    one = lines(figure("displacement_loop", "single"), "displacement-loop")
    many = lines(figure("displacement_loop", "stack"), "displacement-loop")
    (match,) = [line for line in many if line.get_label() == "k = 0.2"]
    assert len(one) == 1 and same(one[0].get_ydata(), match.get_ydata())


def test_displacement_loop_rejects_bad_xi(data):
    for bad in (5.0, -0.1, float("nan"), "0.8"):
        with pytest.raises(ValueError, match="xi"):
            hf.hist_displacement_loop(data["single"], xi=bad)


def test_displacement_loop_marks_failed_steps(data, figure):
    ds = data["single-fail-3"]
    fig = figure("displacement_loop", "single-fail-3")
    j = int(np.argmin(np.abs(ds["xi"].values - 0.8)))
    pts = crosses(fig)
    assert same(pts, [[ds["load_ratio"].values[3], ds["tangential_displacement"].values[3, j]]])


# ----------------------------------------------------------------------------- energy
def test_energy_per_cycle_values(data, figure):
    cyc, st = data["cycle"], data["stack"]
    fig = figure("energy_per_cycle", "stack", "cycle")
    assert len(fig.axes) == 3  # energy, ratio, legend holder (sphere only)
    ax = fig.axes[0]
    assert (ax.get_xscale(), ax.get_yscale()) == ("log", "log")
    assert "a_{max}^5" in ax.get_ylabel()
    cycle_lines, doubled_lines = lines(fig, "cycle-energy"), lines(fig, "doubled-loading")
    assert len(cycle_lines) == len(doubled_lines) == 2
    for line, doubled, ds in zip(cycle_lines, doubled_lines, (st, cyc)):
        w = ds["frictional_work"].values
        steps, levels = int(ds.attrs["steps"]), len(ds.attrs["load_path"])
        start = (levels - 3) * steps  # end of the segment before the last two
        assert same(line.get_xdata(), ds["friction_coefficient"])
        assert same(line.get_ydata(), w[:, -1] - w[:, start])
        assert same(doubled.get_ydata(), 2 * w[:, steps])
    # [0, 1, 0]: the cycle is the whole path; [0, 1, .5, 1, .5]: the last two segments
    assert same(cycle_lines[0].get_ydata(), st["frictional_work"].values[:, -1])
    first = np.flatnonzero(cyc["segment"].values == 3)[0]
    w = cyc["frictional_work"].values
    assert same(cycle_lines[1].get_ydata(), w[:, -1] - w[:, first - 1])
    ratio = lines(fig, "energy-ratio")
    assert same(ratio[1].get_ydata(),
                doubled_lines[1].get_ydata() / cycle_lines[1].get_ydata())


def test_energy_per_cycle_geometries_and_single(figure):
    fig = figure("energy_per_cycle", "stack", "cylinder")
    assert len(fig.axes) == 6  # two columns of energy, ratio, legend holder
    assert "a_{max}^5" in fig.axes[0].get_ylabel() and "a_{max}^4" in fig.axes[3].get_ylabel()
    one = lines(figure("energy_per_cycle", "single"), "cycle-energy")
    many = lines(figure("energy_per_cycle", "stack", "cycle"), "cycle-energy")
    assert same(one[0].get_xdata(), [0.2])
    assert same(one[0].get_ydata(), [many[0].get_ydata()[1]])


def test_energy_per_cycle_needs_a_cycle(data):
    with pytest.raises(ValueError, match="fewer than 3 levels"):
        hf.hist_energy_per_cycle(data["monotonic"])
    rising = run("sphere", 0.2, [0, 0.5, 1], 3)
    with pytest.raises(ValueError, match="one loading and one unloading"):
        hf.hist_energy_per_cycle(rising)
    bad = data["single"].copy()
    del bad.attrs["load_path"]
    with pytest.raises(ValueError, match="load_path"):
        hf.hist_energy_per_cycle(bad)


def test_energy_per_cycle_marks_failed_steps(figure):
    fig = figure("energy_per_cycle", "cycle-fail-20")
    (line,) = lines(fig, "cycle-energy")
    pts = crosses(fig)
    assert same(pts[:, 1], line.get_ydata())  # every k's cycle point, nothing else
