"""Scenes in physical units (issue 40, item 4): parsing, the table, the figure, the workflow.

Truths: the scene's call is the library's physical_history with the same SI input (the
dataset, the table and the figure's lines equal its numbers, converted by hand to µm
and MPa where drawn), and a bad key is one line naming the scene and the key, in
check-config and in the library.
"""

from __future__ import annotations

import csv

import numpy as np
import pytest
import yaml

from conftest import make_workdir, needs_snakemake, snakemake
from contactlib.cli import check_config
from contactlib.io import read_dataset
from contactlib.physical import physical_history
from contactlib.plot.physical import physical_history_figure, physical_table
from contactlib.scene import ConfigError, PhysicalScene, parse_scene

BALL = {"kind": "physical", "geometry": "sphere", "radius": "5mm", "indenter": "steel",
        "body": "soda_lime_glass", "friction": 0.2, "load_path": ["0N", "100N", "0N"],
        "steps": 8, "n": 40, "max_error": 1.0e-2}


def test_physical_scene_parses_to_si() -> None:
    s = parse_scene("ball", BALL)
    assert isinstance(s, PhysicalScene) and s.kind == "physical"
    assert s.run_spec() == {"geometry": "sphere", "radius": 0.005, "indenter": "steel",
                            "body": "soda_lime_glass", "friction": 0.2,
                            "load_path": [0.0, 100.0, 0.0], "steps": 8, "n": 40,
                            "max_error": 0.01}
    pairs = parse_scene("p", dict(BALL, body=["3GPa", 0.4], indenter="rigid",
                                  relaxation=[[0.5, "200ms"]], times=["0s", "0.5s", "1s"]))
    assert pairs.run_spec()["body"] == [3e9, 0.4]
    assert pairs.run_spec()["relaxation"] == [[0.5, 0.2]]
    assert pairs.run_spec()["times"] == [0.0, 0.5, 1.0]
    shape = {"shape": "haversine", "amplitude": "50N", "mean": "50N", "cycles": 2}
    assert parse_scene("s", dict(BALL, load_path=shape)).run_spec()["load_path"] == shape


BAD = [
    ({"radius": "5kg"}, "scenes.b.radius"),
    ({"radius": None}, "scenes.b.radius"),
    ({"body": "cheese"}, "scenes.b.body"),
    ({"indenter": "unobtainium"}, "scenes.b.indenter"),
    ({"friction": -0.1}, "scenes.b.friction"),
    ({"load_path": ["0N", "100Pa"]}, "scenes.b.load_path"),
    ({"load_path": ["10N", "100N"]}, "scenes.b.load_path"),
    ({"load_path": {"shape": "square", "amplitude": "1N", "mean": "1N", "cycles": 1}},
     "scenes.b.load_path"),
    ({"steps": 0}, "scenes.b.steps"),
    ({"n": 8}, "scenes.b.n"),
    ({"nu": 0.3}, "scenes.b.nu: unknown key"),
    ({"geometry": "cylinder"}, "scenes.b.length: is required"),
    ({"length": "10mm"}, "scenes.b.length: is for a cylinder only"),
    ({"relaxation": [[0.5, "2N"]], "indenter": "rigid"}, "scenes.b.relaxation"),
    ({"relaxation": [[0.5, "0.2s"]], "indenter": "rigid"}, "scenes.b.times"),
    ({"relaxation": [[0.5, "0.2s"]], "times": ["0s", "1s", "2s"]}, "scenes.b.relaxation"),
    ({"times": ["0s", "1s", "2s"]}, "scenes.b.times"),
    ({"thickness": "0.01um"}, "scenes.b.slab_ratio"),
    ({"substrate": "steel"}, "scenes.b.substrate"),  # a substrate needs base elastic
    ({"base": "elastic", "thickness": "20um"}, "scenes.b.base"),  # ... and base one
    ({"base": "elastic", "thickness": "20um", "substrate": "rigid"}, "scenes.b.substrate"),
    ({"base": "elastic", "substrate": "steel"}, "scenes.b.thickness"),
]


@pytest.mark.parametrize("change, text", BAD, ids=[t for _, t in BAD])
def test_bad_physical_scene_names_the_key(change, text) -> None:
    raw = {k: v for k, v in {**BALL, **change}.items() if v is not None}
    with pytest.raises(ConfigError) as info:
        parse_scene("b", raw)
    assert any(line.startswith(text) for line in info.value.problems), info.value.problems


def test_a_coated_physical_scene_is_the_physical_door_on_a_coated_body() -> None:
    coated = dict(BALL, body=["400GPa", 0.25], indenter="steel", thickness="20um",
                  base="elastic", substrate="steel")
    spec = parse_scene("tin", coated).run_spec()
    assert spec["substrate"] == "steel" and spec["base"] == "elastic"
    assert spec["thickness"] == pytest.approx(2e-5)
    # a coating of the substrate's own material is the uncoated body (independent run)
    same = parse_scene("same", dict(coated, body="steel")).run_spec()
    plain = physical_history(**parse_scene("plain", dict(BALL, body="steel")).run_spec())
    res = physical_history(**same)
    assert np.allclose(res.contact_radius, plain.contact_radius, rtol=1e-9, atol=0)
    assert np.allclose(res.frictional_energy, plain.frictional_energy, rtol=1e-9, atol=1e-30)


def test_check_config_refuses_a_bad_physical_scene(tmp_path) -> None:
    path = tmp_path / "c.yaml"
    path.write_text(yaml.safe_dump({"scenes": {"b": dict(BALL, radius="5kg")}}))
    lines = check_config([str(path)])
    assert len(lines) == 1 and lines[0].startswith("scenes.b.radius: radius must be"), lines


def test_table_and_figure_are_the_history_in_si() -> None:
    res = physical_history(**parse_scene("ball", BALL).run_spec())
    rows = physical_table(res)
    assert [r["at"] for r in rows] == ["point 0", "point 1", "point 2",
                                       "cycle 1 (points 0-2)"]
    top = res.result.segment_end(1)
    assert rows[1]["contact radius [m]"] == float(res.contact_radius[top])
    assert rows[3]["frictional energy [J]"] == float(res.cycle_frictional_energy[0])
    fig = physical_history_figure(res, "ball")
    lines = {line.get_gid(): line for ax in fig.axes for line in ax.get_lines()}
    assert np.allclose(lines["contact-radius"].get_ydata(), res.contact_radius * 1e6,
                       rtol=1e-15, atol=0)
    peak = int(np.argmax(res.force))
    assert np.allclose(lines["pressure"].get_ydata(),
                       res.result.pressure[peak] * res.p0 / 1e6, rtol=1e-14, atol=0)


@needs_snakemake
@pytest.mark.workflow
@pytest.mark.slow
def test_workflow_writes_the_physical_dataset_table_and_figure(tmp_path) -> None:
    wd = make_workdir(tmp_path, {"scenes": {"ball": BALL}})
    snakemake(wd)
    res = physical_history(**parse_scene("ball", BALL).run_spec())
    ds = read_dataset(wd / "results" / "datasets" / "ball.nc")
    assert ds["frictional_energy_si"].attrs["units"] == "J"
    assert np.allclose(ds["frictional_energy_si"].values, res.frictional_energy, rtol=1e-9,
                       atol=0)
    assert np.allclose(ds["contact_radius_si"].values, res.contact_radius, rtol=1e-9, atol=0)
    with open(wd / "results" / "tables" / "ball.csv", newline="") as fh:
        table = list(csv.DictReader(fh))
    assert table[-1]["at"] == "cycle 1 (points 0-2)"
    assert float(table[-1]["frictional energy [J]"]) == pytest.approx(
        float(res.cycle_frictional_energy[0]), rel=1e-5)  # six digits in the table
    for suffix in ("png", "pdf"):
        assert (wd / "results" / "figures" / f"ball.{suffix}").stat().st_size > 1000
    keys = (wd / "results" / "tables" / "key-numbers.csv").read_text()
    assert "ball," in keys
