"""Scenes of kind history and scenes with a tolerance: parsing, the workflow, the data.

The workflow part copies the workflow into a temporary folder (the
helpers of tests/conftest.py) and runs a tiny history scene end to end.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import dry_run, make_workdir, needs_snakemake, snakemake
from contactlib import history
from contactlib.io import history_to_dataset, stack_histories
from contactlib.io import read_dataset
from contactlib.scene import HistoryScene, Scene, parse_scene


HIST = {"kind": "history", "geometry": "sphere", "nu": 0.3, "friction": [0.3, 0.1],
        "load_path": [0, 1, 0], "steps": 4, "n": 40}


# ----------------------------------------------------------------------------- parsing
def test_history_scene_parses_with_every_friction():
    s = parse_scene("h", HIST)
    assert isinstance(s, HistoryScene) and s.frictions == (0.3, 0.1)
    assert s.run_spec(1) == {"geometry": "sphere", "nu": 0.3, "friction": 0.1,
                             "load_path": [0.0, 1.0, 0.0], "steps": 4, "n": 40,
                             "slab_ratio": 0.0, "max_error": 1e-2}  # a load path's default
    assert parse_scene("h", dict(HIST, friction=0.2)).frictions == (0.2,)


def test_steps_default_to_the_librarys():
    """Without ``steps`` a history scene takes contactlib.history's 200 a segment and a
    fretting scene contactlib.fretting's 40 (the cylinder's), as the command line does."""
    from contactlib import fretting_api, validate

    plain = {k: v for k, v in HIST.items() if k != "steps"}
    assert parse_scene("h", plain).steps == validate.HISTORY_DEFAULT_STEPS == 200
    fret = {k: v for k, v in FRET.items() if k != "steps"}
    assert parse_scene("f", fret).steps == fretting_api.DEFAULT_STEPS == 40


@pytest.mark.parametrize("key, value, text", [
    ("friction", -0.1, "scenes.h.friction"), ("friction", [], "scenes.h.friction"),
    ("friction", [0.1, 0.1], "repeats"), ("load_path", [0.5, 1], "scenes.h.load_path"),
    ("load_path", [0, 1.5], "scenes.h.load_path"), ("steps", 0, "scenes.h.steps"),
    ("steps", 10**9, "scenes.h.steps"), ("n", 8, "scenes.h.n"),
    ("stick_ratios", [0.5], "unknown key"), ("kind", "cycle", "scenes.h.kind"),
    ("slab_ratio", 1001, r"scenes\.h\.slab_ratio: .*<= 1000"),
    ("base", "glued", "scenes.h.base"),
])
def test_bad_history_scene_is_refused_naming_the_key(key, value, text):
    with pytest.raises(ValueError, match=text):
        parse_scene("h", dict(HIST, **{key: value}))


def test_history_scene_takes_an_elastic_indenter():
    given = parse_scene("h", dict(HIST, indenter={"modulus_ratio": 0.3, "nu": 0.0}))
    assert (given.indenter_modulus, given.indenter_nu) == (0.3, 0.0)
    spec = given.run_spec(0)
    assert spec["indenter_modulus"] == 0.3 and spec["indenter_nu"] == 0.0
    named = parse_scene("h", dict(HIST, nu=0.33, indenter="steel", body="aluminium"))
    assert named.indenter_modulus == pytest.approx(207 / 69) and named.indenter_nu == 0.3
    assert named.run_spec(1)["friction"] == 0.1
    rigid = parse_scene("h", HIST)  # no indenter: the keywords stay out of the call
    assert rigid.indenter_modulus == float("inf") and "indenter_modulus" not in rigid.run_spec(0)


@pytest.mark.parametrize("extra, text", [
    ({"indenter": {"modulus_ratio": -1.0}}, "scenes.h.indenter.modulus_ratio"),
    ({"indenter": {"modulus_ratio": 2.0, "nu": 0.7}}, "scenes.h.indenter.nu"),
    ({"indenter": "steel"}, "scenes.h.body"),
    ({"indenter": "unobtainium", "body": "steel"}, "scenes.h.indenter"),
    ({"indenter": "steel", "body": "aluminium"}, "scenes.h.nu"),  # nu 0.3, aluminium 0.33
    ({"body": "steel"}, "scenes.h.body"),
])
def test_bad_history_indenter_is_refused_naming_the_key(extra, text):
    with pytest.raises(ValueError, match=text):
        parse_scene("h", dict(HIST, **extra))


def test_history_scene_indenter_reaches_the_dataset():
    s = parse_scene("h", dict(HIST, friction=0.2, indenter={"modulus_ratio": 1.0, "nu": 0.0},
                              load_path=[0, 1], steps=3))
    ds = history_to_dataset(history(**s.run_spec(0)))
    assert ds.attrs["indenter_modulus_ratio"] == 1.0
    assert ds.attrs["indenter_poisson_ratio"] == 0.0
    assert ds.attrs["dundurs_beta"] < 0  # compressible indenter on a less compressible body


def test_tolerance_scene_plans_the_default_method_and_refuses_n_with_it():
    s = parse_scene("t", {"geometry": "sphere", "nu": 0.3, "tolerance": 1e-3,
                          "stick_ratios": [0.1, 0.5]})
    assert isinstance(s, Scene) and s.method == "default" and s.tolerance == 1e-3
    assert s.n % 64 == 0
    tighter = parse_scene("t", {"geometry": "sphere", "nu": 0.3, "tolerance": 1e-5,
                                "stick_ratios": [0.1, 0.5]})
    assert tighter.n > s.n  # the error model falls like n^-2: 100x tighter ~ 10x n
    for extra in ({"n": 64}, {"method": "paper"}):
        with pytest.raises(ValueError, match="either tolerance or n/method"):
            parse_scene("t", {"geometry": "sphere", "nu": 0.3, "tolerance": 1e-3,
                              "stick_ratios": [0.5], **extra})
    with pytest.raises(ValueError, match="scenes.t.tolerance"):
        parse_scene("t", {"geometry": "sphere", "nu": 0.3, "tolerance": 0.0,
                          "stick_ratios": [0.5]})
    with pytest.raises(ValueError, match="beyond the largest supported n"):
        parse_scene("t", {"geometry": "sphere", "nu": 0.3, "tolerance": 1e-9,
                          "stick_ratios": [0.99]})  # (1e-9 is met up to c/a = 0.98)


# ----------------------------------------------------------------------------- stacking
def test_stacked_histories_equal_the_single_runs():
    runs = [history_to_dataset(history("sphere", 0.3, k, [0, 1, 0], 4, n=40))
            for k in (0.3, 0.1)]
    st = stack_histories(runs)
    assert st["friction_coefficient"].values.tolist() == [0.1, 0.3]
    for ds in runs:
        k = ds.attrs["friction_coefficient"]
        for name in ("frictional_work", "state", "shear", "stick_ratio"):
            np.testing.assert_array_equal(st[name].sel(friction_coefficient=k).values,
                                          ds[name].values)
    assert st["load_ratio"].dims == ("step",)  # the path carries no k
    with pytest.raises(ValueError, match="load path"):
        stack_histories([runs[0], history_to_dataset(history("sphere", 0.3, 0.2, [0, 1], 4,
                                                             n=40))])
    with pytest.raises(ValueError, match="repeat"):
        stack_histories([runs[0], runs[0]])


# ----------------------------------------------------------------------------- workflow
@needs_snakemake
@pytest.mark.workflow
@pytest.mark.slow
def test_workflow_runs_a_history_scene_and_its_figures(tmp_path):
    cfg = {"scenes": {"cyc": HIST},
           "figures": {"history_stick_radius": ["cyc"], "history_stick_map": ["cyc"],
                       "history_loop": ["cyc"], "history_energy": ["cyc"]}}
    wd = make_workdir(tmp_path, cfg)
    snakemake(wd)
    ds = read_dataset(wd / "results" / "datasets" / "cyc.nc")
    assert ds.attrs["scene"] == "cyc" and ds.sizes["friction_coefficient"] == 2
    direct = history("sphere", 0.3, 0.1, [0, 1, 0], 4, n=40)
    np.testing.assert_array_equal(ds["frictional_work"].sel(friction_coefficient=0.1).values,
                                  direct.frictional_work)
    for fig in cfg["figures"]:
        assert (wd / "results" / "figures" / f"{fig}.png").stat().st_size > 0


@needs_snakemake
@pytest.mark.workflow
def test_workflow_refuses_a_history_scene_in_a_paper_figure(tmp_path):
    cfg = {"scenes": {"cyc": HIST}, "figures": {"fig2": ["cyc"]}}
    wd = make_workdir(tmp_path, cfg)
    code, text = dry_run(wd)
    assert code != 0
    assert "figures.fig2: scene 'cyc' is of kind history" in text


@needs_snakemake
@pytest.mark.workflow
@pytest.mark.slow  # fast tier: test_bad_history_scene_is_refused_naming_the_key
def test_workflow_schema_names_a_bad_history_key(tmp_path):
    cfg = {"scenes": {"cyc": dict(HIST, steps=0)}}
    wd = make_workdir(tmp_path, cfg)
    code, text = dry_run(wd)
    assert code != 0 and "scenes.cyc.steps" in text


# ----------------------------------------------------------------------------- tolerance
def _reference_k(geometry: str, slab: float, c: float, n: int) -> float:
    """Richardson extrapolation of the default method at n and n/2 (order 2, measured)."""
    from contactlib.solvers.default_method import solve_default
    from contactlib.model.geometry import Geometry

    g = Geometry(geometry, 0.3, slab)
    k_half, k_full = solve_default(g, c, n // 2).k, solve_default(g, c, n).k
    return k_full + (k_full - k_half) / 3.0


@pytest.mark.parametrize("geometry, slab, tolerance, reference_n", [
    ("cylinder", 0.05, 1e-3, 512),   # planned n ~ 64: the reference is 8x finer
    pytest.param("sphere", 0.0, 1e-5, 2048,  # planned n ~ 640: the reference is 3x finer
                 marks=pytest.mark.slow),
])
def test_tolerance_scene_meets_its_target_against_a_much_finer_solution(
        geometry, slab, tolerance, reference_n):
    from contactlib import pipeline

    ratios = [0.1, 0.5, 0.9]
    raw = {"geometry": geometry, "nu": 0.3, "tolerance": tolerance, "stick_ratios": ratios,
           "outputs": ["k_curve"]}
    if slab:
        raw["slab_ratio"] = slab
    scene = parse_scene("tol", raw)
    assert reference_n >= 3 * scene.n
    records = pipeline.solve(scene, None, None)
    ds = pipeline.assemble(scene, records, checks=pipeline.check(records))
    assert ds.attrs["tolerance"] == tolerance and ds.attrs["tolerance_met"] == 1
    for i, c in enumerate(ratios):
        truth = _reference_k(geometry, slab, c, reference_n)
        achieved = abs(float(ds["friction_coefficient"][i]) - truth) / truth
        assert achieved <= tolerance, (c, achieved)
        # the recorded estimate is an honest one: within a factor 3 of the achieved error
        # or both far below the target
        est = float(ds["error_estimate"][i])
        assert est <= tolerance
        assert achieved <= 3 * est or achieved <= tolerance / 20, (c, achieved, est)
        assert int(ds["elements"][i]) >= scene.n


# ----------------------------------------------------------------------------- profiles,
# coated bodies and fretting paths in scenes (issues 36, 37, 39)
SELF = {"geometry": "sphere", "nu": 0.3, "n": 32, "stick_ratios": [0.0, 0.5],
        "outputs": ["k_curve", "energy"]}
FRET = {"kind": "history", "geometry": "cylinder", "nu": 0.5, "friction": 0.3,
        "load_path": [0, 1, 1], "tangential_path": [0, 0, 0.5], "steps": 8, "n": 64}


def test_a_paraboloid_scene_keeps_its_keys_and_specs():
    """Defaults leave the jobs' keys and parameters as they were (the main job's reference)."""
    s = parse_scene("s", SELF)
    assert (s.profile, s.exponent, s.base, s.substrate_modulus) == ("paraboloid", None,
                                                                    "smooth", float("inf"))
    assert s.solve_spec() == {}
    assert s.influence_key.startswith("sphere-nu0.3-default-n32-c")
    assert set(s.influence_spec()) == {"geometry", "nu", "method", "n", "slab_ratio",
                                       "stick_ratios"}
    assert parse_scene("s", dict(SELF, profile="paraboloid")).influence_key == s.influence_key
    assert "profile" not in parse_scene("h", HIST).run_spec(0)


def test_profile_keys_follow_the_command_line_spelling():
    cone = parse_scene("s", dict(SELF, profile="cone"))
    assert cone.geometry_object.profile.exponent == 1.0 and cone.solve_spec() == {
        "profile": "cone"}
    assert cone.influence_key == parse_scene("s", SELF).influence_key  # operators shared
    d3 = parse_scene("s", dict(SELF, profile="power", exponent=3))
    assert d3.solve_spec() == {"profile": "power", "exponent": 3.0}
    h = parse_scene("h", dict(HIST, profile="power", exponent=1.5))
    assert h.run_spec(0)["profile"] == "power" and h.run_spec(0)["exponent"] == 1.5


@pytest.mark.parametrize("extra, text", [
    ({"profile": "square"}, r"^scenes\.s\.profile: profile must be one of paraboloid, cone, "),
    ({"profile": "flat"}, r"^scenes\.s\.profile: profile 'flat' is for history only"),
    ({"profile": "power"}, r"^scenes\.s\.exponent: exponent must be given"),
    ({"profile": "cone", "exponent": 1}, r"^scenes\.s\.exponent: exponent must be omitted"),
    ({"profile": "power", "exponent": 0.2}, r"^scenes\.s\.exponent: .*\[0\.5, 8\]"),
    ({"profile": "cone", "method": "paper", "n": 16, "stick_ratios": [0.25]},
     r"^scenes\.s\.method: method 'paper' is measured for the paraboloid only"),
    ({"profile": "cone", "tolerance": 1e-3, "n": None},
     r"^scenes\.s\.tolerance: tolerance is planned for the paraboloid only"),
    ({"base": "elastic", "slab_ratio": 0.5},
     r"^scenes\.s\.substrate_modulus: substrate_modulus .* is required"),
    ({"substrate_modulus": 2.0}, r"^scenes\.s\.substrate_modulus: .*needs base='elastic'"),
    ({"base": "elastic", "slab_ratio": 0.5, "substrate_modulus": 1e7},
     r"^scenes\.s\.substrate_modulus: .*\[0\.01, 1e6\]"),
    ({"base": "elastic", "slab_ratio": 0.5, "substrate_modulus": 2, "substrate_nu": 0.6},
     r"^scenes\.s\.substrate_nu: "),
    ({"base": "elastic", "slab_ratio": 0.5, "substrate_modulus": 2, "method": "paper",
      "n": 16, "stick_ratios": [0.25]}, r"^scenes\.s\.method: .*coated body"),
])
def test_bad_profile_or_coating_is_one_line_naming_the_key(extra, text):
    raw = {k: v for k, v in dict(SELF, **extra).items() if v is not None}
    with pytest.raises(ValueError, match=text) as info:
        parse_scene("s", raw)
    assert len(info.value.problems) == 1, info.value.problems


@pytest.mark.parametrize("kind, extra, key", [
    ("history", {"base": "elastic"}, "substrate_modulus"),
    ("history", {"substrate_modulus": 2.0}, "substrate_modulus"),
    ("history", {"base": "elastic", "substrate_modulus": 2.0, "relaxation": [[0.5, 1.0]],
                 "duration": 1.0}, "relaxation"),
    ("physical", {"profile": "cone"}, "profile"),
    ("physical", {"base": "elastic"}, "base"),
])
def test_bad_coatings_in_histories_and_physical_ones_are_refused(kind, extra, key):
    raw = dict(HIST, **extra) if kind == "history" else dict(
        {"kind": "physical", "geometry": "sphere", "radius": "5mm", "indenter": "steel",
         "body": "steel", "friction": 0.2, "load_path": ["0N", "10N"]}, **extra)
    with pytest.raises(ValueError) as info:
        parse_scene("x", raw)
    assert len(info.value.problems) == 1, info.value.problems
    line = info.value.problems[0]
    assert line.startswith(f"scenes.x.{key}: ")
    if kind == "physical":
        assert ("not available" in line) if key == "base" else ("paraboloid only" in line)


def test_a_coated_scene_keys_its_substrate_and_equals_the_homogeneous_body_at_e2_over_e1_1():
    """Identity: a coating on a substrate of its own material is the homogeneous body."""
    from contactlib import pipeline

    raw = dict(SELF, geometry="cylinder", slab_ratio=0.5, base="elastic")
    coated = parse_scene("c", dict(raw, substrate_modulus=1.0))
    stiffer = parse_scene("c", dict(raw, substrate_modulus=2.0, substrate_nu=0.2))
    assert coated.influence_key != stiffer.influence_key  # the substrate is in the operators
    assert stiffer.influence_spec()["substrate_modulus"] == 2.0
    plain = parse_scene("p", dict(SELF, geometry="cylinder"))

    def run(s):
        parts = {p: pipeline.influence(s.influence_spec(), p) for p in s.parts}
        recs = pipeline.solve(s, parts.get("normal"), parts.get("shear"))
        return pipeline.assemble(s, recs, checks=pipeline.check(recs),
                                 work=pipeline.energy(s, recs))

    a, b = run(coated), run(plain)
    assert a.attrs["base"] == "elastic" and a.attrs["substrate_modulus"] == 1.0
    for name in ("friction_coefficient", "load_ratio", "frictional_work"):
        np.testing.assert_allclose(a[name].values, b[name].values, rtol=1e-9, atol=1e-13)


def test_a_coated_history_scene_runs_the_coated_history():
    """E2/E1 = 1, nu2 = nu: the coated history is the homogeneous body's (identity); a
    stiffer substrate reaches the call and the dataset."""
    raw = dict(HIST, friction=0.2, load_path=[0, 1, 0], steps=4, slab_ratio=0.5,
               base="elastic")
    s = parse_scene("h", dict(raw, substrate_modulus=2.0, substrate_nu=0.2))
    spec = s.run_spec(0)
    assert (spec["base"], spec["substrate_modulus"], spec["substrate_nu"]) == ("elastic", 2.0,
                                                                               0.2)
    assert "substrate_modulus" not in parse_scene("h", HIST).run_spec(0)
    ds = history_to_dataset(history(**s.run_spec(0)))
    assert ds.attrs["base"] == "elastic" and ds.attrs["substrate_modulus"] == 2.0
    same = history(**parse_scene("h", dict(raw, substrate_modulus=1.0)).run_spec(0))
    plain = history(**parse_scene("h", dict(HIST, friction=0.2, load_path=[0, 1, 0],
                                             steps=4)).run_spec(0))
    scale = float(np.max(plain.frictional_work))
    np.testing.assert_allclose(same.frictional_work, plain.frictional_work, rtol=0,
                               atol=1e-12 * scale)
    np.testing.assert_allclose(same.stick_ratio, plain.stick_ratio, rtol=0, atol=1e-12)


def test_a_cone_scene_carries_love_s_frictionless_load():
    """The cone's frictionless load at a = 1 (E* = 1, cot alpha = 1) is Love's pi/2: the
    dataset's load_ratio (P over the profile's own load) is 1 within its estimate."""
    from contactlib import pipeline
    from contactlib.model import profiles

    s = parse_scene("cone", dict(SELF, profile="cone"))
    assert profiles.profile("cone").frictionless_load(True) == pytest.approx(math.pi / 2,
                                                                              rel=1e-14)
    parts = {p: pipeline.influence(s.influence_spec(), p) for p in s.parts}
    recs = pipeline.solve(s, parts.get("normal"), parts.get("shear"))
    ds = pipeline.assemble(s, recs, checks=pipeline.check(recs), work=pipeline.energy(s, recs))
    assert ds.attrs["profile"] == "cone"
    err = abs(float(ds["load_ratio"][0]) * math.pi / 2 - math.pi / 2) / (math.pi / 2)
    assert err <= float(ds["load_error_estimate"][0]) and err < 5e-4  # 2.1e-4 at n = 32


def test_fretting_scene_parses_to_the_fretting_call():
    s = parse_scene("f", dict(FRET, bulk_stress=[0, 0, 0.1]))
    assert s.fretting and s.run_spec(0) == {
        "geometry": "cylinder", "nu": 0.5, "friction": 0.3, "load_path": [0.0, 1.0, 1.0],
        "tangential_path": [0.0, 0.0, 0.5], "steps": 8, "n": 64, "max_error": 1e-2,
        "bulk_stress": [0.0, 0.0, 0.1]}
    assert parse_scene("f", {k: v for k, v in FRET.items() if k != "n"}).n == 120
    assert not parse_scene("h", HIST).fretting


def test_sphere_fretting_scene_of_a_beta_zero_pair():
    """A rigid sphere on nu = 1/2 (beta = 0): the scene runs contactlib.fretting, whose
    dataset records the sphere's pressure unit (Hertz's 2/pi) for the figure's shift axis."""
    s = parse_scene("f", dict(FRET, geometry="sphere", n=16, steps=4))
    assert s.fretting and s.run_spec(0)["geometry"] == "sphere"
    from contactlib import fretting
    from contactlib.io import fretting_to_dataset

    ds = fretting_to_dataset(fretting(**s.run_spec(0)))
    assert ds.attrs["p0"] == pytest.approx(2 / np.pi, rel=1e-15)
    assert ds.attrs["p_max"] == pytest.approx(4 / 3, rel=1e-15)


@pytest.mark.parametrize("extra, key, text", [
    ({"geometry": "sphere", "nu": 0.3, "tangential_path": [0, 0, 0.95]}, "geometry",
     "Dundurs beta = 0 only"),  # beyond the coupled pairs' 0.9 k P
    ({"tangential_path": [0, 0.5]}, "tangential_path", "has 2 points but load_path has 3"),
    ({"tangential_path": [0, 0, 1]}, "tangential_path", "gross sliding"),
    ({"tangential_path": [0.1, 0, 0.5]}, "tangential_path", "must start at 0"),
    ({"bulk_stress": [0, 1]}, "bulk_stress", "has 2 points"),
    ({"friction": [0.1, 0.3]}, "friction", "takes one friction coefficient"),
    ({"friction": 0}, "friction", "k > 0"),
    ({"steps": 6}, "steps", "multiple of 4"),
    ({"n": 62}, "n", "multiple of 4"),
    ({"slab_ratio": 0.5}, "slab_ratio", "not with tangential_path"),
    ({"relaxation": [[0.5, 1.0]], "duration": 1.0}, "relaxation", "not with tangential_path"),
])
def test_bad_fretting_scene_is_one_line_with_the_library_s_words(extra, key, text):
    with pytest.raises(ValueError) as info:
        parse_scene("f", dict(FRET, **extra))
    lines = [line for line in info.value.problems if line.startswith(f"scenes.f.{key}: ")]
    assert lines and text in lines[0], info.value.problems
    assert len(info.value.problems) <= 2, info.value.problems  # (relaxation: and duration)


def test_bulk_stress_needs_a_tangential_path():
    with pytest.raises(ValueError, match=r"^scenes\.h\.bulk_stress: needs tangential_path"):
        parse_scene("h", dict(HIST, bulk_stress=[0, 1, 0]))
