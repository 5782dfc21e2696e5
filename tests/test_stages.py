"""The staged computation (what the workflow runs rule by rule) and scenes.

Identity checks: precomputed influence matrices give exactly the numbers of an
in-process solve; a round trip through the npz intermediates loses nothing;
scene validation names the key; a frictionless or nu = 0.5 scene needs no shear
matrices.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import contactlib
from contactlib import io, pipeline, stages, validate
from contactlib.model.geometry import Geometry
from contactlib.discrete import SelfSimilarSolution
from contactlib.result import CaseRecord
from contactlib.scene import config_hash, parse_scene, parse_scenes

def assert_same_record(a, b):
    """Two case records hold the same numbers, field by field (None where one is None)."""
    for f in dataclasses.fields(CaseRecord):
        x, y = getattr(a, f.name), getattr(b, f.name)
        assert (x is None) == (y is None), f.name
        if x is not None:
            np.testing.assert_array_equal(x, y, err_msg=f.name)


CASES = [
    ("sphere", 0.3, 0.0, "default", 32, [0.0, 0.4, 1.0]),
    ("cylinder", 0.3, 0.05, "default", 32, [0.25, 0.7]),
    ("sphere", 0.3, 0.0, "paper", 8, [0.0, 0.25, 0.5]),
    ("cylinder", 0.2, 0.0, "paper-literal", 8, [0.125, 1.0]),
]


@pytest.mark.parametrize("geometry, nu, slab, method, n, ratios", CASES)
def test_precomputed_influence_gives_the_same_numbers(geometry, nu, slab, method, n, ratios):
    geom = Geometry(geometry, nu, slab)
    normal = stages.influence(geom, method, n, ratios, "normal")
    shear = stages.influence(geom, method, n, ratios, "shear")
    staged = stages.solve_cases(geom, method, n, ratios, normal=normal, shear=shear)
    direct = stages.solve_cases(geom, method, n, ratios)
    for a, b in zip(staged, direct):
        assert_same_record(a, b)


def test_records_survive_the_npz_round_trip(tmp_path):
    geom = Geometry("sphere", 0.3)
    recs = stages.solve_cases(geom, "default", 32, [0.0, 0.5, 1.0])
    path = io.write_records(recs, tmp_path / "s.npz")
    back = io.read_records(path)
    assert len(back) == 3
    for a, b in zip(recs, back):
        assert_same_record(a, b)
        assert isinstance(b.converged, bool) and isinstance(b.message, str)
        assert isinstance(b.stick_index, int) and isinstance(b.iterations, int)


def test_records_are_frozen_and_typed():
    rec = stages.solve_cases(Geometry("sphere", 0.3), "paper", 8, [0.5])[0]
    assert isinstance(rec, CaseRecord) and rec.kind == "paper"
    with pytest.raises(dataclasses.FrozenInstanceError):
        rec.k = 0.0  # type: ignore[misc]
    assert rec.nodal_u is None and rec.slip_x.size == 4 and len(repr(rec)) < 1200


def test_records_of_an_earlier_version_still_read(tmp_path):
    """The npz layout of the dict records ("<i>/<field>", a retired tolerance_message)."""
    rec = stages.solve_cases(Geometry("sphere", 0.3), "default", 16, [0.5], estimate=False)[0]
    old = {f"0/{f.name}": np.asarray(getattr(rec, f.name)) for f in dataclasses.fields(rec)
           if getattr(rec, f.name) is not None and f.default is dataclasses.MISSING}
    old.update({"count": np.array(1), "0/tolerance_message": np.asarray("")})
    path = io.write_arrays(old, tmp_path / "old.npz")
    back = io.read_records(path, upgrade=True)[0]
    assert np.isnan(back.error_estimate) and back.elements is None and not back.resolved
    np.testing.assert_array_equal(back.p, rec.p)
    io.write_arrays({"count": np.array(1), "0/k": np.asarray(0.1)}, tmp_path / "bad.npz")
    with pytest.raises(io.DamagedFileError, match="case-record"):
        io.read_records(tmp_path / "bad.npz")


def test_write_arrays_is_atomic_and_refuses_pickles(tmp_path):
    with pytest.raises(TypeError, match="pickling"):
        io.write_arrays({"x": np.array([object()])}, tmp_path / "a.npz")
    with pytest.raises(ValueError, match=".npz"):
        io.write_arrays({"x": np.zeros(2)}, tmp_path / "a.bin")
    assert list(tmp_path.iterdir()) == []


def test_influence_operators_must_match_the_mesh():
    geom = Geometry("sphere", 0.3)
    normal = stages.influence(geom, "default", 32, [0.5], "normal")
    with pytest.raises(ValueError, match="no mesh for stick ratio 0.4"):
        stages.solve_cases(geom, "default", 32, [0.4], normal=normal, shear=normal)
    paper = stages.influence(geom, "paper", 8, [0.5], "normal")
    with pytest.raises(ValueError, match="another mesh"):
        stages.solve_cases(geom, "paper", 16, [0.0], normal=paper)


def test_one_paper_influence_set_serves_every_m():
    geom = Geometry("sphere", 0.3)
    a = stages.influence(geom, "paper", 8, [0.125], "shear")
    b = stages.influence(geom, "paper", 8, [0.75, 0.5], "shear")
    np.testing.assert_array_equal(a["ops"], b["ops"])


@pytest.mark.parametrize("nu, ratios, parts", [
    (0.3, [0.0], ("normal",)),
    (0.3, [0.0, 0.5], ("normal", "shear")),
    (0.5, [0.2, 0.9], ("normal",)),
])
def test_parts_needed(nu, ratios, parts):
    assert stages.parts_needed(Geometry("sphere", nu), ratios) == parts


def test_decoupled_scene_solves_hertz_without_shear_matrices():
    scene = parse_scene("inc", {"geometry": "sphere", "nu": 0.5, "n": 32,
                                "stick_ratios": [0.3, 1.0]})
    assert scene.parts == ("normal",)
    normal = pipeline.influence(scene.influence_spec(), "normal")
    assert normal["sizes"].shape == (1,)  # one mesh (c = 0) serves both cases
    recs = pipeline.solve(scene, normal)
    ds = pipeline.assemble(scene, recs, checks=pipeline.check(recs),
                           work=pipeline.energy(scene, recs),
                           profiles=pipeline.displacements(scene, recs))
    np.testing.assert_array_equal(ds["shear"].values, 0.0)
    assert list(ds["friction_coefficient"].values) == [0.0, np.inf]
    # Hertz pressure at nu = 0.5 (no coupling), independent of the stick ratio
    xi = ds["xi"].values
    np.testing.assert_allclose(ds["pressure"].values[0], np.sqrt(1 - xi**2), atol=2e-3)


def test_pipeline_dataset_equals_the_library_sweep():
    raw = {"geometry": "cylinder", "nu": 0.25, "n": 32, "slab_ratio": 0.1,
           "stick_ratios": [0.0, 0.3, 0.8]}
    scene = parse_scene("c", raw)
    parts = {p: pipeline.influence(scene.influence_spec(), p) for p in scene.parts}
    recs = pipeline.solve(scene, parts["normal"], parts["shear"])
    ds = pipeline.assemble(scene, recs, checks=pipeline.check(recs),
                           work=pipeline.energy(scene, recs),
                           profiles=pipeline.displacements(scene, recs))
    ref = io.to_dataset(contactlib.sweep("cylinder", 0.25, raw["stick_ratios"], n=32,
                                         slab_ratio=0.1))
    for name in ref.data_vars:
        np.testing.assert_array_equal(ds[name].values, ref[name].values, err_msg=name)
    assert ds.attrs["scene_config_hash"] == config_hash(raw)


def test_assemble_requires_what_the_scene_asked_for():
    scene = parse_scene("s", {"geometry": "sphere", "nu": 0.3, "n": 32, "stick_ratios": [0.5],
                              "outputs": ["energy"]})
    recs = pipeline.solve(scene, None)
    with pytest.raises(ValueError, match="work must be given"):
        pipeline.assemble(scene, recs)
    ds = pipeline.assemble(scene, recs, work=pipeline.energy(scene, recs))
    assert "frictional_work" in ds and "consistent" not in ds and "pressure" not in ds


@pytest.mark.parametrize("raw, key", [
    ({"geometry": "sphere", "nu": 0.7, "stick_ratios": [0.3]}, "nu"),
    ({"geometry": "cone", "nu": 0.3, "stick_ratios": [0.3]}, "geometry"),
    ({"geometry": "sphere", "nu": 0.3, "n": 1, "stick_ratios": [0.3]}, "n"),
    ({"geometry": "sphere", "nu": 0.3, "stick_ratios": [1.7]}, "stick_ratios"),
    ({"geometry": "sphere", "nu": 0.3, "stick_ratios": []}, "stick_ratios"),
    ({"geometry": "sphere", "nu": 0.3, "method": "paper", "stick_ratios": [0.3]},
     "stick_ratios"),
    ({"geometry": "sphere", "nu": 0.3, "stick_ratios": [0.3], "slab_ratio": 1001},
     "slab_ratio"),
    ({"geometry": "sphere", "nu": 0.3, "stick_ratios": [0.3], "slab_ratio": 1, "base": "x"},
     "base"),
    ({"geometry": "sphere", "nu": 0.3, "stick_ratios": [0.3], "outputs": ["x"]}, "outputs"),
    ({"geometry": "sphere", "nu": 0.3, "stick_ratios": [0.3], "colour": 1}, "colour"),
    ({"geometry": "sphere", "stick_ratios": [0.3]}, "nu"),
])
def test_scene_validation_names_the_key(raw, key):
    with pytest.raises(ValueError, match=rf"^scenes\.bad\.{key}: "):
        parse_scene("bad", raw)


def test_scene_defaults_and_keys():
    s = parse_scene("s", {"geometry": "sphere", "nu": 0.3, "stick_ratios": "all",
                          "method": "paper"})
    assert s.n == 16 and s.stick_ratios == tuple(m / 16 for m in range(1, 16))
    assert s.outputs == validate.DEFAULT_OUTPUTS  # every output but the opt-in subsurface
    assert s.influence_key == "sphere-nu0.3-paper-n16"
    d = parse_scene("d", {"geometry": "cylinder", "nu": 0.3, "stick_ratios": [0.5, 0.2],
                          "slab_ratio": 0.05})
    e = parse_scene("e", {"geometry": "cylinder", "nu": 0.3, "stick_ratios": [0.2, 0.5],
                          "slab_ratio": 0.05, "outputs": ["k_curve"]})
    assert d.influence_key == e.influence_key and d.n == 256
    assert d.hash != e.hash
    with pytest.raises(ValueError, match="non-empty mapping"):
        parse_scenes({})


def test_both_self_similar_solvers_give_one_shape():
    """Default and paper solutions share one base: the record never asks which made it."""
    geom = Geometry("sphere", 0.3)
    for method, n, kind in (("default", 32, "default"), ("paper", 8, "paper")):
        d = stages.solve_one(geom, method, n, 0.5, None, None)
        assert isinstance(d, SelfSimilarSolution) and d.kind == kind
        assert [f.name for f in dataclasses.fields(d)] == [
            f.name for f in dataclasses.fields(SelfSimilarSolution)]
        rec = stages.case_record(geom, d, samples=True)
        assert rec.kind == kind and rec.load == d.load()
        np.testing.assert_array_equal(rec.traction, d.phi if kind == "default" else d.qc)
        assert (rec.nodal_u is None) == (kind == "paper") and np.isnan(rec.delta) == (
            kind == "paper")
