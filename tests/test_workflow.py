"""The Snakemake workflow: DAG per scene, schema rejections, a tiny end-to-end run, lint.

Each test copies the workflow (Snakefile, workflow/, config/) into a temporary
folder, writes its own config, and runs snakemake there as a subprocess.
"""

from __future__ import annotations

import re
import shutil

import numpy as np
import pytest
import yaml

import contactlib
from conftest import REPO, job_counts, make_workdir, needs_snakemake, nothing_to_do, snakemake
from contactlib.io import read_dataset

pytestmark = [needs_snakemake, pytest.mark.workflow]


TINY = {
    "scenes": {
        "tiny-default": {"geometry": "sphere", "nu": 0.3, "method": "default", "n": 32,
                         "stick_ratios": [0.0, 0.3, 0.6, 1.0],
                         "outputs": ["k_curve", "stresses", "displacements", "energy"]},
        "tiny-paper": {"geometry": "cylinder", "nu": 0.3, "method": "paper", "n": 8,
                       "slab_ratio": 0.05, "stick_ratios": "all",
                       "outputs": ["k_curve", "energy"]},
    },
    "figures": {"fig2": ["tiny-default", "tiny-paper"], "fig3": ["tiny-default"],
                "fig4": ["tiny-default"], "fig5": ["tiny-default", "tiny-paper"]},
    "convergence": {
        "stick_ratios": [0.25, 0.5],
        "studies": {
            "s-default": {"geometry": "sphere", "nu": 0.3, "method": "default",
                          "n": [16, 32, 64, 128]},
            "s-paper": {"geometry": "sphere", "nu": 0.3, "method": "paper", "n": [8, 16, 32],
                        "reference": "s-default"},
        },
    },
}


# ----------------------------------------------------------------------------- DAG
def test_default_config_dag_has_exactly_the_scenes_jobs(tmp_path):
    wd = make_workdir(tmp_path)
    counts = job_counts(wd)
    cfg = yaml.safe_load((REPO / "config" / "config.yaml").read_text())
    kinds = [s.get("kind", "self-similar") for s in cfg["scenes"].values()]
    n_scenes = kinds.count("self-similar")
    histories = [s for s in cfg["scenes"].values() if s.get("kind") == "history"]
    # one influence job a set (every default scene has its own, normal and shear parts);
    # a history scene is one job (its runs, one a friction coefficient, in parallel)
    assert counts == {"influence": n_scenes, "solve": n_scenes, "check": n_scenes,
                      "energy": n_scenes, "assemble": n_scenes,
                      "history_run": len(histories),
                      # a physical scene: one job (dataset, table and figure in SI)
                      "physical_run": kinds.count("physical"),
                      # one job a family of figures (paper, history), its figures in parallel
                      "figures_paper": 1, "figures_history": 1,
                      "key_numbers": 1, "all": 1}


@pytest.mark.slow
def test_dag_builds_only_what_scenes_ask_for(tmp_path):
    cfg = {"scenes": {
        # frictionless: no shear matrices, no energy, no displacements
        "hertz": {"geometry": "sphere", "nu": 0.3, "n": 32, "stick_ratios": [0.0],
                  "outputs": ["k_curve", "stresses"]},
        # k-curve only: solve + check, nothing else
        "curve": {"geometry": "sphere", "nu": 0.3, "n": 32, "stick_ratios": [0.2, 0.5],
                  "outputs": ["k_curve"]},
        # the same influence set as "curve" (same geometry, nu, n, method, ratios)
        "curve-again": {"geometry": "sphere", "nu": 0.3, "n": 32,
                        "stick_ratios": [0.5, 0.2], "outputs": ["energy"]},
        # two paper scenes with different m/n share one set (rings do not depend on c)
        "paper-a": {"geometry": "sphere", "nu": 0.3, "method": "paper", "n": 8,
                    "stick_ratios": [0.25], "outputs": ["stresses"]},
        "paper-b": {"geometry": "sphere", "nu": 0.3, "method": "paper", "n": 8,
                    "stick_ratios": "all", "outputs": ["displacements"]},
    }, "figures": {}}
    wd = make_workdir(tmp_path, cfg)
    counts = job_counts(wd)
    # influence sets: hertz (normal only); curve (normal + shear, shared with
    # curve-again); paper (normal + shear, shared by paper-a and paper-b)
    assert counts["influence"] == 3
    assert counts["solve"] == 5 and counts["assemble"] == 5
    assert counts["check"] == 2  # hertz, curve
    assert counts["energy"] == 1  # curve-again
    assert "displacements" not in counts  # paper-b's profiles: its assemble job
    assert not any(rule.startswith("figure") for rule in counts)
    from contactlib.scene import parse_scenes
    scenes = parse_scenes(cfg["scenes"])
    # the frictionless set gets no shear part: build it and look
    key = scenes["hertz"].influence_key
    snakemake(wd, f"results/influence/{key}")
    assert sorted(p.name for p in (wd / "results" / "influence" / key).glob("*.npz")) == \
        ["normal.npz"]
    assert scenes["curve"].influence_key == scenes["curve-again"].influence_key
    assert scenes["paper-a"].influence_key == scenes["paper-b"].influence_key


def test_results_dir_moves_every_output(tmp_path):
    """A study of one's own (results_dir: studies/mine) writes nothing under results/."""
    wd = make_workdir(tmp_path, TINY)
    (wd / "mine.yaml").write_text(yaml.safe_dump({"results_dir": "studies/mine/"}))
    out = snakemake(wd, "--dry-run", "--configfile", "mine.yaml", cores=1)
    text = out.stdout + out.stderr
    paths = re.findall(r"[\w./-]+\.(?:nc|npz|png|pdf|csv|html|log|tsv)\b", text)
    assert "studies/mine/datasets/tiny-default.nc" in paths
    assert "studies/mine/figures/fig2.png" in paths
    assert "studies/mine/tables/key-numbers.csv" in paths
    assert "results/" not in text and all(p.startswith("studies/mine/") for p in paths), \
        [p for p in paths if not p.startswith("studies/mine/")]
    (wd / "bad.yaml").write_text(yaml.safe_dump({"results_dir": "../elsewhere"}))
    proc = snakemake(wd, "--dry-run", "--configfile", "bad.yaml", cores=1, check=False)
    assert proc.returncode != 0 and "results_dir" in proc.stdout + proc.stderr


# ----------------------------------------------------------------------------- schema
@pytest.mark.parametrize("key, value", [("nu", 0.7)] + [pytest.param(*p, marks=pytest.mark.slow) for p in (
    ("geometry", "cone"), ("n", 1), ("stick_ratios", [1.7]),
    ("method", "fem"), ("slab_ratio", -1.0), ("outputs", ["pictures"]))])
def test_bad_scene_is_refused_before_any_job_naming_the_key(tmp_path, key, value):
    wd = make_workdir(tmp_path)
    bad = {"geometry": "sphere", "nu": 0.3, "stick_ratios": [0.3]}
    bad[key] = value
    (tmp_path / "bad.yaml").write_text(yaml.safe_dump({"scenes": {"bad": bad}}))
    proc = snakemake(wd, "--configfile", "bad.yaml", check=False)
    assert proc.returncode != 0
    text = proc.stdout + proc.stderr
    assert f"scenes.bad.{key}" in text, text
    assert not (wd / "results").exists()  # nothing ran


@pytest.mark.slow
def test_library_rules_are_applied_after_the_schema(tmp_path):
    wd = make_workdir(tmp_path)
    cfg = {"scenes": {"bad": {"geometry": "sphere", "nu": 0.3, "method": "paper", "n": 16,
                              "stick_ratios": [0.3]}}}
    (tmp_path / "bad.yaml").write_text(yaml.safe_dump(cfg))
    proc = snakemake(wd, "--configfile", "bad.yaml", check=False)
    assert proc.returncode != 0
    assert "scenes.bad.stick_ratios" in proc.stderr + proc.stdout
    assert "multiple of 1/n" in proc.stderr + proc.stdout


@pytest.mark.slow
def test_figure_needing_an_output_the_scene_lacks_is_refused(tmp_path):
    cfg = {"scenes": {"s": {"geometry": "sphere", "nu": 0.3, "n": 32, "stick_ratios": [0.5],
                            "outputs": ["k_curve"]}},
           "figures": {"fig4": ["s"]}}
    wd = make_workdir(tmp_path, cfg)
    proc = snakemake(wd, "--dry-run", check=False)
    assert proc.returncode != 0
    assert "figures.fig4" in proc.stderr + proc.stdout
    assert "displacements" in proc.stderr + proc.stdout


# ----------------------------------------------------------------------------- end to end
MICRO = {"scenes": {"micro": {"geometry": "sphere", "nu": 0.3, "method": "default", "n": 32,
                              "stick_ratios": [0.0, 0.5], "outputs": ["k_curve"]}}}


@pytest.mark.slow  # (4.6 s; the fast tier keeps the DAG, lint and dry-run checks)
def test_micro_run_dataset_matches_the_library(tmp_path):
    """The fast tier's end-to-end run: one scene, two cases, no figures."""
    wd = make_workdir(tmp_path, MICRO)
    snakemake(wd)
    ds = read_dataset(wd / "results/datasets/micro.nc")
    ref = contactlib.sweep("sphere", 0.3, [0.0, 0.5], n=32, energy=False)
    np.testing.assert_array_equal(ds["friction_coefficient"].values,
                                  [s.friction_coefficient for s in ref])
    assert abs(float(ds["load_ratio"].values[0]) - 1.0) < 3e-3  # frictionless: Hertz
    assert ds["consistent"].values.all()
    assert (wd / "results/tables/key-numbers.csv").read_text().startswith("scene,")
    assert not list((wd / "results").rglob("*.tmp"))


@pytest.fixture(scope="module")
def tiny_run(tmp_path_factory):
    wd = make_workdir(tmp_path_factory.mktemp("tiny"), TINY)
    snakemake(wd)
    return wd


@pytest.mark.slow
def test_tiny_run_datasets_match_the_library(tiny_run):
    ds = read_dataset(tiny_run / "results/datasets/tiny-default.nc")
    ref = contactlib.sweep("sphere", 0.3, [0.0, 0.3, 0.6, 1.0], n=32)
    np.testing.assert_array_equal(ds["friction_coefficient"].values,
                                  [s.friction_coefficient for s in ref])
    np.testing.assert_allclose(ds["frictional_work"].values,
                               [s.frictional_work for s in ref], rtol=1e-13, atol=0)
    np.testing.assert_allclose(ds["tangential_displacement"].values,
                               np.stack([s.tangential_displacement for s in ref]),
                               rtol=1e-13, atol=1e-16)
    assert ds["consistent"].values.all()
    # physics, independently of the library: frictionless load is Hertz's
    assert abs(float(ds["load_ratio"].values[0]) - 1.0) < 2e-3
    assert ds.attrs["scene"] == "tiny-default"
    assert ds.attrs["contactlib_version"] == contactlib.__version__
    assert len(ds.attrs["scene_config_hash"]) == 16
    for name in ds.variables:
        assert "long_name" in ds[name].attrs and "units" in ds[name].attrs, name


@pytest.mark.slow
def test_tiny_run_datasets_hold_only_what_was_asked(tiny_run):
    ds = read_dataset(tiny_run / "results/datasets/tiny-paper.nc")
    assert "frictional_work" in ds and "consistent" in ds
    assert "pressure" not in ds and "tangential_displacement" not in ds
    np.testing.assert_allclose(ds["stick_ratio"].values, np.arange(1, 8) / 8)
    assert not (tiny_run / "results/profiles/tiny-paper.npz").exists()


@pytest.mark.slow
def test_tiny_run_outputs_and_no_partial_files(tiny_run):
    for fig in ("fig2", "fig3", "fig4", "fig5"):
        for ext in ("png", "pdf"):
            assert (tiny_run / f"results/figures/{fig}.{ext}").stat().st_size > 1000
    assert (tiny_run / "results/tables/key-numbers.csv").read_text().startswith("scene,")
    assert "<table>" in (tiny_run / "results/tables/key-numbers.html").read_text()
    assert not list((tiny_run / "results").rglob("*.tmp"))


@pytest.mark.slow
def test_second_run_has_nothing_to_do_and_a_change_reruns_only_its_scene(tiny_run, tmp_path):
    wd = make_workdir(tmp_path, TINY)
    shutil.copytree(tiny_run / "results", wd / "results")
    shutil.copytree(tiny_run / ".snakemake", wd / ".snakemake")
    assert nothing_to_do(wd)
    cfg = yaml.safe_load((wd / "config/config.yaml").read_text())
    cfg["scenes"]["tiny-paper"]["nu"] = 0.25
    (wd / "config/config.yaml").write_text(yaml.safe_dump(cfg, sort_keys=False))
    dry = snakemake(wd, "--dry-run").stdout
    jobs = re.findall(r"^rule (\w+):\n(?:.*\n)*?    output: (\S+)", dry, flags=re.M)
    outputs = [o for _, o in jobs]
    assert outputs, dry
    # only tiny-paper's own jobs, plus the figures and table that read its dataset
    for rule, out in jobs:
        if rule.startswith("figure") or rule in ("key_numbers", "all"):
            continue
        assert "tiny-paper" in out or "cylinder-nu0.25-paper" in out, (rule, out)
    assert not any("tiny-default" in o for o in outputs)
    figs = {r for r, _ in jobs if r.startswith("figure")}
    assert figs == {"figures_paper"}  # the family whose figures draw tiny-paper


@pytest.mark.slow
def test_convergence_target(tiny_run):
    assert not (tiny_run / "results/convergence").exists()  # not part of the main job
    snakemake(tiny_run, "convergence")
    own = read_dataset(tiny_run / "results/convergence/s-default.nc")
    order = own["observed_order"].sel(quantity="friction_coefficient").values
    # refinement converges (the differences shrink); at n <= 128 the sphere's k error
    # crosses zero (two-scale mesh: orders 2.9 and 6.0 here, pre-asymptotic), so the
    # method's order 2 is tested where it is asymptotic, in tests/test_convergence.py
    assert np.all(np.isfinite(order) & (order > 1.0)), order
    err = own["error"].sel(quantity="friction_coefficient").values
    assert np.all(np.diff(err, axis=0) < 0)  # refinement helps, every c/a
    paper = read_dataset(tiny_run / "results/convergence/s-paper.nc")
    np.testing.assert_array_equal(paper["reference"].values, own["reference"].values)
    assert paper.attrs["reference"] == "extrapolated values of the default method"
    assert (own["wall_time"].values > 0).all() and (own["peak_memory"].values > 0).all()
    assert (tiny_run / "results/figures/convergence.png").stat().st_size > 1000
    table = (tiny_run / "results/tables/convergence.csv").read_text().splitlines()
    assert table[0] == "study,n,time_s,median_error,max_error,peak_memory_MiB,time_per_digit"
    assert len(table) == 1 + 4 + 3  # one row a resolution of each study


def test_fretting_target_dag(tmp_path):
    """`fretting` runs the cylinder's amplitude study and the sphere's stick-zone map, each
    a study job and a figure job; `all` runs neither (the default DAG test)."""
    counts = job_counts(make_workdir(tmp_path), "fretting")
    assert counts == {"fretting_study": 1, "fretting_figure": 1,
                      "fretting_stick_map_study": 1, "fretting_stick_map": 1,
                      "fretting": 1}, counts


@pytest.mark.slow
def test_fretting_target(tiny_run):
    assert not (tiny_run / "results/fretting").exists()  # not part of the main job
    snakemake(tiny_run, "fretting")
    # the stick-zone map: its figure, and its table of radii with estimates, one row a
    # loaded path point (5) and direction (24) of each case (2)
    assert (tiny_run / "results/figures/fretting-stick-map.png").stat().st_size > 1000
    assert (tiny_run / "results/figures/fretting-stick-map.pdf").stat().st_size > 1000
    rows = (tiny_run / "results/tables/fretting-stick-map.csv").read_text().splitlines()
    assert rows[0].startswith("case,beta,point,P/P_max,Q/(k P_max),direction [deg],"
                              "stick radius/a_max,stick radius error estimate,"
                              "stick radius resolved")
    assert len(rows) == 1 + 2 * 5 * 24
    ds = read_dataset(tiny_run / "results/fretting/fretting.nc")
    beta0 = ds["dundurs_beta"].values == 0.0
    work = ds["cycle_work"].values[beta0, -1]
    closed = ds["mindlin_deresiewicz_work"].values[beta0]
    assert np.all(np.abs(work / closed - 1) < 2e-2)  # measured 6e-5 to 1.5e-2
    assert (tiny_run / "results/figures/fretting.png").stat().st_size > 1000
    table = (tiny_run / "results/tables/fretting.csv").read_text().splitlines()
    assert table[0].startswith("nu,beta,Q*/kP,cycle,work")


@pytest.mark.slow
def test_report_builds(tiny_run):
    snakemake(tiny_run, "--report", "results/report.html")
    html = (tiny_run / "results/report.html").read_text(errors="replace")
    assert len(html) > 10000


# ----------------------------------------------------------------------------- lint
def test_lint_is_clean(tmp_path):
    wd = make_workdir(tmp_path)
    proc = snakemake(wd, "--lint", check=False)
    text = proc.stdout + proc.stderr
    assert proc.returncode == 0, text
    assert "Lints for" not in text, text


# ----------------------------------------------------------------------------- example scenes:
# profiles, a coated body, fretting paths (config/examples/scenes.yaml; issues 36, 37, 39)
EXAMPLES = "config/examples/scenes.yaml"
EXAMPLE_OUT = "examples-results"


def _example_targets(*names: str) -> list[str]:
    out = []
    for name in names:
        out.append(f"{EXAMPLE_OUT}/datasets/{name}.nc")
        if name in ("cattaneo", "fretting-fatigue", "tin-on-steel", "fretting-pad",
                    "mindlin-sphere"):
            out += [f"{EXAMPLE_OUT}/tables/{name}.csv", f"{EXAMPLE_OUT}/figures/{name}.png"]
    return out


def test_example_scenes_dry_run_builds_each_scene_s_jobs(tmp_path):
    wd = make_workdir(tmp_path)
    names = yaml.safe_load((wd / EXAMPLES).read_text())["scenes"]
    counts = job_counts(wd, *_example_targets(*names), "--configfile", EXAMPLES)
    # three self-similar scenes on three influence sets (the cone's sphere set, the power
    # law's cylinder set and the coated cylinder's own), three histories (one a flat
    # punch), four fretting runs (a rounded pad, a sphere) and a coating in physical units
    assert counts == {"influence": 3, "solve": 3, "check": 3, "energy": 1, "assemble": 3,
                      "history_run": 3, "fretting_run": 4, "physical_run": 1}, counts


@pytest.mark.slow  # (about 8 s: two scenes end to end)
def test_a_cone_and_a_fretting_scene_run_and_match_closed_forms(tmp_path):
    """The cone's frictionless load is Love's (load_ratio 1 within its estimate); the
    fretting path's stick ratio is Cattaneo's c/a = sqrt(1 - Q/kP) for the cylinder at
    beta = 0 (nu = 0.5, rigid indenter) within its estimate; table and figure written."""
    wd = make_workdir(tmp_path)
    snakemake(wd, *_example_targets("cone-sphere", "cattaneo"), "--configfile", EXAMPLES)
    cone = read_dataset(wd / EXAMPLE_OUT / "datasets/cone-sphere.nc")
    assert cone.attrs["profile"] == "cone" and cone.attrs["scene"] == "cone-sphere"
    err = abs(float(cone["load_ratio"][0]) - 1.0)
    assert err <= float(cone["load_error_estimate"][0]) and err < 2e-4  # 5.6e-5 at n = 64
    # k(c/a) does not depend on the profile (docs/profiles.md): Hertz's at c/a = 0.5
    hertz = contactlib.solve("sphere", 0.3, stick_ratio=0.5, n=256).friction_coefficient
    assert abs(float(cone["friction_coefficient"][1]) - hertz) <= float(
        cone["error_estimate"][1]) * float(cone["friction_coefficient"][1])
    fr = read_dataset(wd / EXAMPLE_OUT / "datasets/cattaneo.nc")
    assert fr.attrs["dundurs_beta"] == 0.0 and fr.attrs["scene"] == "cattaneo"
    c, est = float(fr["stick_ratio"][-1]), float(fr["stick_ratio_error_estimate"][-1])
    assert abs(c - np.sqrt(1 - 0.5)) <= est < 2e-3, (c, est)  # 0.70654 +- 7.6e-4
    rows = (wd / EXAMPLE_OUT / "tables/cattaneo.csv").read_text().splitlines()
    assert rows[0].startswith("point,P/P_max,Q/(k P_max),sigma/p0,c/a") and len(rows) == 4
    assert (wd / EXAMPLE_OUT / "figures/cattaneo.png").stat().st_size > 1000
    assert not (wd / "results").exists()


def test_a_fretting_scene_may_not_take_the_name_of_the_workflow_s_own_figure(tmp_path):
    raw = {"kind": "history", "geometry": "cylinder", "nu": 0.5, "friction": 0.3,
           "load_path": [0, 1, 1], "tangential_path": [0, 0, 0.5], "steps": 8, "n": 64}
    wd = make_workdir(tmp_path, {"scenes": {"fretting": raw}})
    proc = snakemake(wd, "--dry-run", cores=1, check=False)
    assert proc.returncode != 0
    assert ("scenes.fretting: the name is taken by the workflow's own figure or table "
            "(figures/fretting.png, tables/fretting.csv); choose another") in proc.stderr + \
        proc.stdout
