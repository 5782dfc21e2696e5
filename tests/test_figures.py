"""Tests for contactlib.plot.paper (the paper's figs 2-5), the plot base and contactlib.io.write_figure."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap

import matplotlib
import matplotlib.style
import numpy as np
import pytest
import xarray as xr
from matplotlib.figure import Figure
from matplotlib.layout_engine import ConstrainedLayoutEngine
from PIL import Image

import contactlib
from contactlib import plot
from contactlib.plot import paper as figures
from contactlib.io import read_dataset, to_dataset, write_dataset, write_figure

FIGURES = {
    "fig2": figures.fig2_friction,
    "fig3": figures.fig3_tractions,
    "fig4": figures.fig4_displacement,
    "fig5": figures.fig5_work,
}
NOT_CONVERGED = "not-converged"


@pytest.fixture(scope="module")
def data() -> dict[str, xr.Dataset]:
    """Small sweeps of both geometries and both schemes, built once."""
    ratios = [0.0, 0.05, 0.3, 0.7, 1.0]
    # n = 32 keeps the tests fast; its k errors (up to ~1e-3) are asked to be resolved to
    # 5 %, so that only the cases a test marks failed are crossed out
    out = {
        "sphere": to_dataset(contactlib.sweep("sphere", 0.3, ratios, n=32, max_error=0.05)),
        "cylinder": to_dataset(contactlib.sweep("cylinder", 0.3, ratios, n=32,
                                                max_error=0.05)),
        "sphere-paper": to_dataset(contactlib.sweep(
            "sphere", 0.3, [0.0, 1 / 8, 3 / 8, 5 / 8, 1.0], n=8, method="paper")),
        "cylinder-paper": to_dataset(contactlib.sweep(
            "cylinder", 0.3, [0.0, 1 / 8, 1 / 2, 1.0], n=8, method="paper", slab_ratio=0.05)),
    }
    out["sphere"].attrs["scene"] = "sphere-default"
    return out


def crosses(fig: Figure) -> int:
    """Number of points drawn with the not-converged mark (k and work plots)."""
    return sum(len(line.get_xdata()) for ax in fig.axes for line in ax.lines
               if line.get_gid() == NOT_CONVERGED)


def legend_texts(fig: Figure) -> list[str]:
    texts = [t.get_text() for leg in fig.legends for t in leg.get_texts()]
    for ax in fig.axes:
        if ax.get_legend() is not None:
            texts += [t.get_text() for t in ax.get_legend().get_texts()]
    return texts


def fail(ds: xr.Dataset, *indices: int) -> xr.Dataset:
    """Copy of ``ds`` with the given cases marked as not converged."""
    out = ds.copy(deep=True)
    for i in indices:
        out["converged"].values[i] = False
    return out


# ----------------------------------------------------------------------------- building
@pytest.mark.parametrize("name", sorted(FIGURES))
@pytest.mark.parametrize("which", [("sphere", "cylinder", "sphere-paper", "cylinder-paper"),
                                   ("sphere",), ("cylinder-paper",)])
def test_figures_build(data, name, which):
    datasets = [data[w] for w in which]
    before = dict(matplotlib.rcParams)
    fig = FIGURES[name](datasets if len(datasets) > 1 else datasets[0])
    assert isinstance(fig, Figure)
    assert not isinstance(fig.get_layout_engine(), ConstrainedLayoutEngine)  # frozen
    assert dict(matplotlib.rcParams) == before  # style applied in a context only
    titles = [ax.get_title() for ax in fig.axes if ax.get_title()]
    geometries = {data[w].attrs["geometry"] for w in which}
    if name in ("fig2", "fig5"):  # one panel per geometry
        assert len(titles) == len(geometries)
    else:  # one column per dataset
        assert len(titles) == len(datasets)


def test_fig2_references_markers_and_clip(data):
    fig = figures.fig2_friction([data["sphere"], data["sphere-paper"], data["cylinder"]])
    sphere_ax, cylinder_ax = [ax for ax in fig.axes if ax.get_title()]
    for ax in (sphere_ax, cylinder_ax):  # sphere and half-plane cylinder
        refs = [ln for ln in ax.lines if ln.get_label().startswith("uncoupled closed form")]
        assert len(refs) == 1 and refs[0].get_linestyle() == "--"
        assert ax.get_ylim()[1] == 1.0
        assert "cut at 1" in ax.get_ylabel()
    # every case is drawn: filled (consistent) + open (inconsistent) markers
    ds = data["sphere-paper"]
    fig = figures.fig2_friction(ds)
    ax = next(ax for ax in fig.axes if ax.get_title())
    marks = [ln for ln in ax.lines if ln.get_linestyle() == "None" and ln.get_gid() is None]
    open_ = sum(len(ln.get_xdata()) for ln in marks if ln.get_markerfacecolor() == "white")
    filled = sum(len(ln.get_xdata()) for ln in marks if ln.get_markerfacecolor() != "white")
    assert open_ == int((~ds["consistent"].values).sum()) > 0
    assert open_ + filled == ds.sizes["stick_ratio"]
    # k = inf at c/a = 1 sits on the top edge as a triangle
    tops = [ln for ln in marks if ln.get_marker() == "^"]
    assert any(1.0 in ln.get_xdata() and set(ln.get_ydata()) == {1.0} for ln in tops)
    assert any("range" in t for t in legend_texts(fig))


def test_fig2_no_uncoupled_reference_for_slab(data):
    fig = figures.fig2_friction(data["cylinder-paper"])
    ax = next(ax for ax in fig.axes if ax.get_title())
    assert not [ln for ln in ax.lines if ln.get_label().startswith("uncoupled")]
    assert any("no uncoupled closed form" in t for t in legend_texts(fig))


def test_fig2_k_max_and_validation(data):
    fig = figures.fig2_friction(data["sphere"], k_max=0.25)
    assert next(ax for ax in fig.axes if ax.get_title()).get_ylim()[1] == 0.25
    with pytest.raises(ValueError, match="k_max"):
        figures.fig2_friction(data["sphere"], k_max=0.0)


def test_fig3_picks_nearest_stick_ratios(data):
    fig = figures.fig3_tractions(data["sphere"], stick_ratios=(0.1, 0.3, 0.31))
    labels = [ln.get_label() for ln in fig.axes[0].lines if not ln.get_label().startswith("_")]
    assert labels[0].startswith("Hertz")
    assert [lb.split(",")[0] for lb in labels[1:]] == ["c/a = 0.05", "c/a = 0.3"]
    xi = data["sphere"]["xi"].values
    hertz = fig.axes[0].lines[0]
    np.testing.assert_allclose(hertz.get_ydata(), np.sqrt(1 - xi**2))


@pytest.mark.parametrize("bad", [(), (0.5, 1.5), ("a",), 0.3])
def test_profile_figures_reject_bad_stick_ratios(data, bad):
    for fn in (figures.fig3_tractions, figures.fig4_displacement):
        with pytest.raises(ValueError, match="stick_ratios"):
            fn(data["sphere"], stick_ratios=bad)


def test_fig4_limits_drawn_or_noted(data):
    fig = figures.fig4_displacement(data["sphere"])
    ax = fig.axes[0]
    limits = {ln.get_label().split(" (")[0]: ln for ln in ax.lines
              if ln.get_label().startswith("k = ")}
    assert set(limits) == {"k = 0", "k = ∞"}
    assert all(ln.get_color() == "black" for ln in limits.values())
    assert limits["k = 0"].get_linestyle() != limits["k = ∞"].get_linestyle()
    partial = data["sphere"].isel(stick_ratio=[1, 2, 3])
    fig = figures.fig4_displacement(partial)
    texts = legend_texts(fig)
    assert any(t.startswith("k = 0 limit") and "not in dataset" in t for t in texts)
    assert any(t.startswith("k = ∞ limit") and "not in dataset" in t for t in texts)


def test_fig5_log_axes_reference_and_skip_note(data):
    ds = data["sphere-paper"].copy(deep=True)
    ds["frictional_work"].values[1] = np.nan
    fig = figures.fig5_work([data["sphere"], ds])
    ax = next(ax for ax in fig.axes if ax.get_title())
    assert ax.get_xscale() == "log" and ax.get_yscale() == "log"
    vlines = [ln for ln in ax.lines if "1/16" in ln.get_label()]
    assert len(vlines) == 1 and vlines[0].get_xdata()[0] == pytest.approx(1 / 16)
    # the small-k asymptote is 1.25x the work even at c/a = 0.001: not drawn
    assert not [ln for ln in ax.lines if ln.get_label().startswith("small-k")]
    ok = data["sphere"]["stick_ratio"].values > 0
    assert min(data["sphere"]["stick_ratio"].values[ok]) < 1 / 16  # drawn below 1/16
    note = next(t.get_text() for t in ax.texts if t.get_gid() == "skip-note")
    v = ds["frictional_work"].values
    skipped = int((~(np.isfinite(v) & (v > 0))).sum())
    assert f"{skipped} not shown" in note and "V NaN: 1" in note
    assert f"V < 0: {int((v < 0).sum())}" in note
    # the default sweep has V = 0 at c/a = 0 and 1 only
    assert "sphere-default:\n   2 not shown (V = 0: 2)" in note


def test_fig5_not_converged_case_does_not_stretch_the_axis(data):
    ds = fail(data["sphere"], 2)
    ds["frictional_work"].values[2] = 0.5
    top = next(ax for ax in figures.fig5_work(data["sphere"]).axes if ax.get_title())
    ax = next(ax for ax in figures.fig5_work(ds).axes if ax.get_title())
    assert ax.get_ylim() == top.get_ylim()  # set by the converged cases only
    cross = [ln for ln in ax.lines if ln.get_gid() == "not-converged"]
    assert len(cross) == 1 and cross[0].get_ydata()[0] == ax.get_ylim()[1]  # on the edge
    note = next(t.get_text() for t in ax.texts if t.get_gid() == "skip-note")
    assert "V = 0.5, above the axis" in note


def test_fig2_negative_k_does_not_squeeze_the_axis(data):
    ds = data["sphere-paper"].copy(deep=True)
    ds["friction_coefficient"].values[2] = -0.57
    ax = next(ax for ax in figures.fig2_friction(ds).axes if ax.get_title())
    assert -0.2 < ax.get_ylim()[0] < 0.0
    assert any(t.get_text() == "k = -0.57" for t in ax.texts)
    # every case of the paper scheme is inconsistent: its legend marker is open
    paper = data["sphere-paper"].copy(deep=True)
    paper["consistent"].values[:] = False
    for ds, face in ((paper, "white"), (data["sphere-paper"], "#0072B2")):
        fig = figures.fig2_friction(ds)
        holder = [a for a in fig.axes if a.get_legend() is not None][0]
        assert holder.get_legend().legend_handles[0].get_markerfacecolor() == face


def test_fig3_compares_paper_and_ours_at_the_same_stick_ratios(data):
    fig = figures.fig3_tractions([data["sphere"], data["cylinder"]], stick_ratios=(0.3, 0.7))
    labels = [[ln.get_label().split(",")[0] for ln in fig.axes[i].lines
               if ln.get_label().startswith("c/a")] for i in (0, 3)]  # p panels
    assert labels[0] == labels[1] == ["c/a = 0.3", "c/a = 0.7"]
    assert figures.FIG3_STICK_RATIOS == (1 / 16, 4 / 16, 8 / 16, 12 / 16)


def test_fig3_off_scale_failed_case_is_cut_and_noted(data):
    ds = fail(data["sphere"], 3)
    ds["pressure"].values[3, 5] = -20.0
    ratios = tuple(float(v) for v in ds["stick_ratio"].values[[2, 3]])
    ax = figures.fig3_tractions(ds, stick_ratios=ratios).axes[0]
    assert ax.get_ylim()[0] > -0.2
    note = next(t.get_text() for t in ax.texts if t.get_gid() == "off-scale-note")
    assert "not converged" in note and "down to -20 p0" in note


def test_fig5_cylinder_has_no_asymptote(data):
    fig = figures.fig5_work(data["cylinder"])
    ax = next(ax for ax in fig.axes if ax.get_title())
    assert not [ln for ln in ax.lines if ln.get_label().startswith("small-k")]
    assert "a^4" in ax.get_ylabel()


# ----------------------------------------------------------------------------- inputs
@pytest.mark.parametrize("name, variable", [
    ("fig2", "friction_coefficient"), ("fig2", "consistent"), ("fig3", "pressure"),
    ("fig3", "shear"), ("fig4", "tangential_displacement"), ("fig5", "frictional_work"),
    ("fig5", "converged"),
])
def test_missing_variable_names_variable_and_dataset(data, name, variable):
    ds = data["cylinder"].drop_vars(variable)
    ds.attrs["scene"] = "no-profiles"
    with pytest.raises(ValueError, match=variable) as err:
        FIGURES[name]([data["sphere"], ds])
    assert "no-profiles" in str(err.value) and "dataset 1" in str(err.value)


def test_unknown_geometry_and_empty_input(data):
    ds = data["sphere"].copy()
    ds.attrs["geometry"] = "cone"
    with pytest.raises(ValueError, match="cone"):
        figures.fig2_friction(ds)
    with pytest.raises(ValueError, match="at least one"):
        figures.fig5_work([])
    with pytest.raises(TypeError, match="xarray.Dataset"):
        figures.fig5_work([data["sphere"], "sphere.nc"])


def test_single_solve_and_netcdf_round_trip(data, tmp_path):
    one = to_dataset(contactlib.solve("sphere", 0.3, stick_ratio=0.5, n=32))
    assert one["stick_ratio"].ndim == 0
    for fn in FIGURES.values():
        assert isinstance(fn(one), Figure)
    back = read_dataset(write_dataset(data["cylinder-paper"], tmp_path / "c.nc"))
    for fn in FIGURES.values():
        assert isinstance(fn(back), Figure)


# ----------------------------------------------------------------------------- failed cases
def test_not_converged_cases_are_drawn_and_marked(data):
    sphere = fail(data["sphere"], 2, 4)  # c/a = 0.3 and 1 (k = inf: top edge)
    paper = data["cylinder-paper"].copy(deep=True)
    paper["friction_coefficient"].values[1] = np.nan  # NaN k still gets a mark
    paper = fail(paper, 1)
    n_failed = int((~sphere["converged"].values).sum() + (~paper["converged"].values).sum())
    fig = figures.fig2_friction([sphere, paper])
    assert crosses(fig) == n_failed

    fig = figures.fig5_work(sphere)
    v = sphere["frictional_work"].values
    assert crosses(fig) == int(((v > 0) & ~sphere["converged"].values).sum()) == 1
    note = next(t.get_text() for ax in fig.axes for t in ax.texts if t.get_gid() == "skip-note")
    assert "1 not converged" in note  # the failed full-adhesion case has V = 0

    for fn in (figures.fig3_tractions, figures.fig4_displacement):
        fig = fn(sphere, stick_ratios=(0.3,))
        marked = [ln for ln in fig.axes[0].lines if ln.get_gid() == NOT_CONVERGED]
        assert marked and all(ln.get_marker() == "x" for ln in marked)
        assert any("NOT CONVERGED" in ln.get_label() for ln in marked)


# ----------------------------------------------------------------------------- style
def test_style_file_is_bundled_and_self_contained():
    path = plot.style_path()
    assert path.is_file() and path.suffix == ".mplstyle"
    with matplotlib.style.context(path):
        rc = matplotlib.rcParams
        assert rc["font.sans-serif"][0] == "DejaVu Sans"
        assert rc["pdf.fonttype"] == 42
        assert rc["savefig.dpi"] == 150
        assert rc["svg.hashsalt"] == "contactlib"
        assert tuple(rc["figure.figsize"]) == (7.0, 3.2)


# ----------------------------------------------------------------------------- write_figure
@pytest.mark.parametrize("name", [pytest.param(name, marks=() if name == "fig2" else
                                               pytest.mark.slow) for name in sorted(FIGURES)])
def test_write_figure_is_byte_reproducible(data, name, tmp_path):
    fig = FIGURES[name]([data["sphere"], data["cylinder-paper"]])
    for ext in ("png", "pdf", "PNG"):
        first = write_figure(fig, tmp_path / f"a.{ext}", style=plot.style_path()).read_bytes()
        second = write_figure(fig, tmp_path / "sub" / f"b.{ext}",
                              style=plot.style_path()).read_bytes()
        assert first == second
    pdf = (tmp_path / "a.pdf").read_bytes()
    assert pdf.startswith(b"%PDF")
    for key in (b"/CreationDate", b"/ModDate", b"/Producer", b"/Creator"):
        assert key not in pdf
    png = (tmp_path / "a.png").read_bytes()
    assert png.startswith(b"\x89PNG") and b"Software" not in png and b"Matplotlib" not in png
    with Image.open(tmp_path / "a.png") as im:  # saved at the style's 150 dpi
        assert np.allclose(im.size, 150 * fig.get_size_inches(), atol=1)
    assert sorted(p.name for p in tmp_path.rglob("*")) == ["a.PNG", "a.pdf", "a.png",
                                                           "b.PNG", "b.pdf", "b.png", "sub"]


_SCRIPT = textwrap.dedent("""
    import sys
    import contactlib
    from contactlib import plot
    from contactlib.io import to_dataset, write_figure
    out = sys.argv[1]
    sphere = to_dataset(contactlib.sweep("sphere", 0.3, [0, 0.1, 0.5, 1], n=16))
    paper = to_dataset(contactlib.sweep("cylinder", 0.3, [0, 0.25, 0.5, 1], n=8,
                                        method="paper"))
    for name in ("fig2_friction", "fig3_tractions", "fig4_displacement", "fig5_work"):
        fig = getattr(plot, name)([sphere, paper])
        for ext in ("png", "pdf"):
            write_figure(fig, f"{out}/{name}.{ext}", style=plot.style_path())
    print("pyplot imported:", "matplotlib.pyplot" in sys.modules)
""")


@pytest.mark.slow
def test_write_figure_is_byte_reproducible_across_processes(tmp_path):
    """Fresh interpreters with different hash seeds write identical files."""
    procs = []
    for seed in ("1", "4242"):  # run side by side
        env = {**os.environ, "PYTHONHASHSEED": seed}
        procs.append(subprocess.Popen([sys.executable, "-c", _SCRIPT, str(tmp_path / seed)],
                                      env=env, stdout=subprocess.PIPE,
                                      stderr=subprocess.PIPE, text=True))
    outputs = []
    for seed, proc in zip(("1", "4242"), procs):
        stdout, stderr = proc.communicate(timeout=300)
        assert proc.returncode == 0, stderr
        assert "pyplot imported: False" in stdout  # figures need no pyplot/backend
        outputs.append({p.name: p.read_bytes() for p in sorted((tmp_path / seed).iterdir())})
    assert len(outputs[0]) == 8
    assert outputs[0].keys() == outputs[1].keys()
    for name in outputs[0]:
        assert outputs[0][name] == outputs[1][name], name


@pytest.mark.parametrize("name", ["fig.svg", "fig.png.txt", "fig", "fig.jpeg"])
def test_write_figure_rejects_other_suffixes(data, name, tmp_path):
    fig = figures.fig5_work(data["sphere"])
    with pytest.raises(ValueError, match="png or .pdf"):
        write_figure(fig, tmp_path / name)
    assert list(tmp_path.iterdir()) == []


def test_write_figure_is_atomic(data, tmp_path, monkeypatch):
    fig = figures.fig5_work(data["sphere"])
    target = tmp_path / "fig5.png"
    target.write_bytes(b"old")

    def broken(*args, **kwargs):
        raise RuntimeError("disk full")

    monkeypatch.setattr(fig, "savefig", broken)
    with pytest.raises(RuntimeError, match="disk full"):
        write_figure(fig, target)
    assert target.read_bytes() == b"old"
    assert [p.name for p in tmp_path.iterdir()] == ["fig5.png"]  # no temporary left
    monkeypatch.undo()
    assert write_figure(fig, target) == target and target.read_bytes() != b"old"
    (tmp_path / "dir.png").mkdir()
    with pytest.raises(IsADirectoryError):
        write_figure(fig, tmp_path / "dir.png")


def test_a_case_not_resolved_is_drawn_as_a_failure(data):
    """A converged case whose error estimate exceeds max_error is crossed out like a failure."""
    ds = data["sphere"]
    assert bool(ds["converged"].all()) and "resolved" in ds
    base = crosses(figures.fig2_friction(ds)) + crosses(figures.fig5_work(ds))
    unresolved = ds.copy(deep=True)
    unresolved["resolved"].values[2] = False  # converged, but not to the accuracy asked
    after = crosses(figures.fig2_friction(unresolved)) + crosses(figures.fig5_work(unresolved))
    assert after == base + 2  # one more cross in each figure
    assert "not converged or not resolved" in legend_texts(figures.fig2_friction(unresolved))


# ----------------------------------------------------------------------------- own studies
def _legend_colors(fig) -> dict[str, object]:
    """Label -> colour of every legend entry (the curves' keys are legend handles)."""
    legends = list(fig.legends) + [ax.get_legend() for ax in fig.axes if ax.get_legend()]
    return {text.get_text(): handle.get_color() for leg in legends
            for text, handle in zip(leg.get_texts(), leg.legend_handles)
            if hasattr(handle, "get_color")}


def test_fig2_reference_lines_take_the_colour_of_their_curve(data):
    """One closed form per nu, in the colour of the curve of that nu (the default
    method's where the paper's scheme has the same nu)."""
    other = to_dataset(contactlib.sweep("sphere", 0.2, [0.0, 0.3, 0.7, 1.0], n=32,
                                        max_error=0.05))
    other.attrs["scene"] = "sphere-nu0.2"
    paper = data["sphere-paper"].copy()
    paper.attrs["scene"] = "sphere-paper"
    fig = figures.fig2_friction([paper, data["sphere"], other])
    ax = next(ax for ax in fig.axes if ax.get_title())
    refs = {ln.get_label(): ln.get_color() for ln in ax.lines
            if ln.get_label().startswith("uncoupled closed form")}
    keys = _legend_colors(fig)
    assert refs == {"uncoupled closed form, ν = 0.2": keys["sphere-nu0.2"],
                    "uncoupled closed form, ν = 0.3": keys["sphere-default"]}
    assert len(set(refs.values())) == 2 and keys["sphere-paper"] not in refs.values()


@pytest.mark.parametrize("count, rows, columns", [(2, 1, 2), (4, 1, 4), (5, 2, 3),
                                                  (8, 2, 4)])
def test_profile_panels_wrap_into_rows(data, count, rows, columns):
    """fig4 with 8 scenes was one row of 3945 x 627 px; at most MAX_COLUMNS panels a row,
    the rows of equal length, the figure no wider than four columns."""
    from contactlib.plot.base import MAX_COLUMNS

    datasets = []
    for i in range(count):
        ds = data["sphere" if i % 2 else "cylinder"].copy()
        ds.attrs["scene"] = f"scene-{i}"
        datasets.append(ds)
    fig = figures.fig4_displacement(datasets)
    panels = [ax for ax in fig.axes if ax.get_title()]
    assert [ax.get_title().splitlines()[0] for ax in panels] == [f"scene-{i}"
                                                                 for i in range(count)]
    xs = sorted({round(ax.get_position().x0, 3) for ax in panels})
    ys = sorted({round(ax.get_position().y0, 3) for ax in panels})
    assert (len(ys), len(xs)) == (rows, columns) and columns <= MAX_COLUMNS
    width, height = fig.get_size_inches()
    assert width <= 0.7 + 3.2 * MAX_COLUMNS and height < 5.0 * rows
