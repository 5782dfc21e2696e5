"""Tests for contactlib.io: layout, CF attributes, round trip, atomic and
reproducible writes."""

from __future__ import annotations

import math
import os
import time

import numpy as np
import pytest
import xarray as xr

import contactlib
from contactlib import io
from contactlib.result import Solution

PROFILES = ("pressure", "shear", "tangential_displacement")
POINT_VARS = (
    "friction_coefficient", "load_ratio", "frictional_work", "slip_direction_ok",
    "stick_admissible", "consistent", "converged", "residual_norm", "iterations",
)
FLAGS = ("slip_direction_ok", "stick_admissible", "consistent", "converged")


def fake_solution(geometry: str = "sphere", stick_ratio: float = 0.5, *,
                  n: int = 8, message: str = "", converged: bool = True,
                  work: float = 0.01) -> Solution:
    xi = np.linspace(0.0, 1.0, n + 1)
    k = math.inf if stick_ratio == 1.0 else 0.3 * stick_ratio
    return Solution(
        geometry=geometry, nu=0.3, method="default", n=n,
        slab_ratio=0.5 if geometry == "cylinder" else 0.0,
        stick_ratio=stick_ratio, friction_coefficient=k, xi=xi,
        pressure=np.sqrt(1.0 - xi**2), shear=stick_ratio * xi * (1 - xi),
        tangential_displacement=0.1 * xi, load_ratio=1.0 - 0.01 * stick_ratio,
        frictional_work=work, slip_direction_ok=True, stick_admissible=stick_ratio < 0.9,
        consistent=stick_ratio < 0.9, converged=converged,
        residual_norm=1e-12 if converged else 0.5, iterations=7, message=message,
    )


def fake_sweep(geometry: str = "sphere", ratios=(0.25, 0.5, 1.0), **kw) -> list[Solution]:
    return [fake_solution(geometry, g, **kw) for g in ratios]


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_single_layout(geometry: str) -> None:
    ds = io.to_dataset(fake_solution(geometry))
    assert ds["stick_ratio"].ndim == 0 and "stick_ratio" in ds.coords
    assert float(ds["stick_ratio"]) == 0.5
    for name in PROFILES:
        assert ds[name].dims == ("xi",)
    for name in POINT_VARS:
        assert ds[name].dims == ()
    for name in FLAGS:
        assert ds[name].dtype == bool


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_sweep_layout(geometry: str) -> None:
    ds = io.to_dataset(fake_sweep(geometry))
    assert ds.sizes == {"stick_ratio": 3, "xi": 9}
    np.testing.assert_array_equal(ds["stick_ratio"], [0.25, 0.5, 1.0])
    for name in PROFILES:
        assert ds[name].dims == ("stick_ratio", "xi")
    for name in POINT_VARS:
        assert ds[name].dims == ("stick_ratio",)
    assert np.isinf(ds["friction_coefficient"][-1])
    # a sweep of one point still has the stick_ratio dimension
    assert io.to_dataset(fake_sweep(geometry, (0.5,)))["pressure"].dims == (
        "stick_ratio", "xi")


@pytest.mark.parametrize("obj", [fake_solution("sphere"), fake_sweep("cylinder")],
                         ids=["single", "sweep"])
def test_attributes_everywhere(obj) -> None:
    ds = io.to_dataset(obj)
    for name, var in ds.variables.items():
        assert var.attrs.get("long_name"), name
        if var.dtype.kind != "O":  # text has no units
            assert var.attrs.get("units") == "1", name
    for name in FLAGS:
        assert list(ds[name].attrs["flag_values"]) == [0, 1]
        assert ds[name].attrs["flag_meanings"] == "false true"
    geometry = ds.attrs["geometry"]
    assert ds.attrs["Conventions"] == "CF-1.10"
    assert ds.attrs["contactlib_version"] == contactlib.__version__
    assert ds.attrs["poisson_ratio"] == 0.3 and ds.attrs["elements"] == 8
    assert ds.attrs["method"] == "default"
    assert ("slab_ratio" in ds.attrs) == (geometry == "cylinder")
    assert not any("time" in key.lower() or "date" in key.lower() for key in ds.attrs)


def test_message_only_when_present() -> None:
    assert "message" not in io.to_dataset(fake_sweep())
    ds = io.to_dataset([fake_solution("sphere", g, message="degenerate" if g == 1 else "")
                        for g in (0.5, 1.0)])
    assert list(ds["message"].values) == ["", "degenerate"]


@pytest.mark.parametrize("obj", [fake_solution("cylinder", message="note"),
                                 fake_sweep("sphere", converged=False, work=math.nan)],
                         ids=["single", "sweep"])
def test_round_trip(tmp_path, obj) -> None:
    ds = io.to_dataset(obj)
    path = io.write_dataset(ds, tmp_path / "sub" / "dir" / "out.nc")
    assert path.exists()
    back = io.read_dataset(path)
    xr.testing.assert_identical(back, ds)
    for name in FLAGS:
        assert back[name].dtype == bool
    assert sorted(os.listdir(path.parent)) == ["out.nc"]


def test_file_encoding(tmp_path) -> None:
    netCDF4 = pytest.importorskip("netCDF4")
    path = io.write_dataset(io.to_dataset(fake_sweep()), tmp_path / "x.nc")
    with netCDF4.Dataset(path) as nc:
        for name in ("xi", "stick_ratio"):
            assert "_FillValue" not in nc[name].ncattrs()
        for name in PROFILES + ("converged", "frictional_work"):
            assert nc[name].filters()["zlib"], name


@pytest.mark.parametrize("obj", [fake_solution("sphere"), fake_sweep("cylinder")],
                         ids=["single", "sweep"])
def test_byte_identical(tmp_path, obj) -> None:
    a = io.write_dataset(io.to_dataset(obj), tmp_path / "a.nc")
    time.sleep(1.05)  # a timestamp with 1 s resolution would now differ
    b = io.write_dataset(io.to_dataset(obj), tmp_path / "b.nc")
    assert a.read_bytes() == b.read_bytes()


def test_failed_write_leaves_nothing(tmp_path, monkeypatch) -> None:
    def boom(*args, **kwargs):
        raise RuntimeError("disk full")

    monkeypatch.setattr(xr.Dataset, "to_netcdf", boom)
    with pytest.raises(RuntimeError, match="disk full"):
        io.write_dataset(io.to_dataset(fake_solution()), tmp_path / "out.nc")
    assert os.listdir(tmp_path) == []


def test_failed_write_keeps_old_file(tmp_path, monkeypatch) -> None:
    path = io.write_dataset(io.to_dataset(fake_solution()), tmp_path / "out.nc")
    before = path.read_bytes()
    real = xr.Dataset.to_netcdf

    def half_then_boom(self, target, *args, **kwargs):
        real(self, target, *args, **kwargs)  # the temp file is fully written ...
        raise OSError("interrupted")  # ... but the rename never happens

    monkeypatch.setattr(xr.Dataset, "to_netcdf", half_then_boom)
    with pytest.raises(OSError, match="interrupted"):
        io.write_dataset(io.to_dataset(fake_sweep()), path)
    assert os.listdir(tmp_path) == ["out.nc"]
    assert path.read_bytes() == before


def test_overwrite(tmp_path) -> None:
    path = tmp_path / "out.nc"
    io.write_dataset(io.to_dataset(fake_solution()), path)
    io.write_dataset(io.to_dataset(fake_sweep()), path)
    assert io.read_dataset(path).sizes["stick_ratio"] == 3
    assert os.listdir(tmp_path) == ["out.nc"]


def test_write_to_directory_fails(tmp_path) -> None:
    with pytest.raises(IsADirectoryError):
        io.write_dataset(io.to_dataset(fake_solution()), tmp_path)


@pytest.mark.parametrize("field,value", [("nu", 0.25), ("geometry", "cylinder"),
                                         ("method", "paper")])
def test_inconsistent_sweep_rejected(field: str, value) -> None:
    sols = fake_sweep()
    setattr(sols[1], field, value)
    with pytest.raises(ValueError, match=field):
        io.to_dataset(sols)


def test_sweep_with_n_by_stick_ratio_records_each(tmp_path) -> None:
    # a sweep to a tolerance solves each stick ratio at the n that met it (planned alone,
    # or doubled): the dataset keeps each n (it raised "solutions[1].n differs" before)
    sols = fake_sweep()
    assert "elements" not in io.to_dataset(sols)  # one n: the attribute alone
    sols[1].n = 16
    ds = io.to_dataset(sols)
    assert list(ds["elements"].values) == [8, 16, 8] and ds.attrs["elements"] == 16
    path = tmp_path / "mixed.nc"
    io.write_dataset(ds, path)
    assert list(io.read_dataset(path)["elements"].values) == [8, 16, 8]


def test_empty_and_mismatched_rejected() -> None:
    with pytest.raises(ValueError):
        io.to_dataset([])
    sols = fake_sweep()
    sols[2].xi = sols[2].xi * 0.5
    with pytest.raises(ValueError, match="xi"):
        io.to_dataset(sols)


def test_write_table_csv_and_html(tmp_path):
    from contactlib.io import write_table

    rows = [{"scene": "a<b", "k": 0.123456789, "w": float("nan")}, {"scene": "c", "k": 2.0,
                                                                     "w": 1e-7}]
    csv_text = write_table(rows, tmp_path / "t.csv").read_text()
    assert csv_text == "scene,k,w\na<b,0.123457,\nc,2,1e-07\n"
    html_text = write_table(rows, tmp_path / "t.html", title="T").read_text()
    assert "<td>a&lt;b</td>" in html_text and html_text.count("<tr>") == 3
    with pytest.raises(ValueError, match=".csv or .html"):
        write_table(rows, tmp_path / "t.txt")
    with pytest.raises(ValueError, match="empty"):
        write_table([], tmp_path / "u.csv")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["t.csv", "t.html"]


def test_flag_names_are_written_once():
    """The consistency flags and their measures are named in contactlib.checks alone: the
    check stage, the datasets and checks.flags agree on them."""
    from contactlib import checks, pipeline
    from contactlib.solvers.default_method import solve_default
    from contactlib.model.geometry import Geometry

    fl = checks.flags(np.array([0.1]), np.array([1.0]), 0.2, np.array([0.2]), np.array([-1.0]))
    assert set(fl) == set(checks.FLAG_NAMES) | set(checks.VIOLATION_NAMES)
    from contactlib import stages
    from contactlib.model import contact

    rec = stages.solve_cases(contact("sphere", 0.3), "default", 16, [0.5], estimate=False)[0]
    assert set(pipeline.check([rec])) == set(fl)
    d = solve_default(Geometry("sphere", 0.3), 0.5, 16)
    assert set(d.node_flags()) == set(fl)
    ds = io.to_dataset(contactlib.solve("sphere", 0.3, stick_ratio=0.5, n=16))
    assert all(name in ds for name in checks.FLAG_NAMES)
