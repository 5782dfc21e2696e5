"""The main job's outputs against a stored fingerprint, compared for meaning, not bits.

``tests/data/mainjob_reference.json`` holds the file list, the structure and the
numbers of every dataset, the key-numbers table and the figures' SHA-256 of the
README Quickstart's main job (``snakemake --cores 2``, ``config/config.yaml``);
``tests/data/mainjob_reference.py`` regenerates it and says when that is allowed
(only in a commit that names the bug it fixes).

What is compared, and how closely (another CPU's BLAS kernel moves round-off, and
Newton's last step, but not what the numbers mean):

* a value with no data (NaN: a solver that did not converge) must be NaN in both;
* a converged value of the default method within its own error estimate (k with
  ``error_estimate``, the load with ``load_error_estimate``, the work with
  ``work_error_estimate``; profiles with k's), never closer than :data:`ROUNDOFF`;
* the paper's scheme (n = 16) and the histories to :data:`ROUNDOFF` of the
  variable's scale: their roots are converged to round-off, and two OpenBLAS
  kernels (SkylakeX and Sandybridge) moved them by at most 1e-10;
* error estimates as estimates, within a factor :data:`ESTIMATE_FACTOR`;
* Newton's iteration counts and residuals (round-off diagnostics) not at all;
* every key number within one unit of its last quoted digit (each is quoted to the
  digits its estimate supports);
* figures: byte-identical when drawn twice on this machine (across machines their
  content is that of the datasets, checked above).

The main job takes minutes (``slow``, ``workflow``). A cheap check of the same
numbers stays in the fast tier: the paper-scheme scenes (n = 16) solved in process
must give the stored k, load and work.
"""

from __future__ import annotations

import hashlib
import importlib.util
import json
import math
import re

import numpy as np
import pytest
import yaml

import contactlib
from conftest import DATA, make_workdir, needs_snakemake, snakemake
from contactlib.scene import parse_scenes

REFERENCE = json.loads((DATA / "mainjob_reference.json").read_text())
ROUNDOFF = 1e-8
"""Relative to a variable's scale: the agreement of values converged to round-off (two
OpenBLAS kernels moved them by at most 1e-10), with a margin of 100."""
ESTIMATE_FACTOR = 2.0
"""Error estimates agree within this factor (two kernels moved them by at most 9 %)."""
DIAGNOSTICS = ("iterations", "residual_norm")
"""Round-off diagnostics of Newton, not compared."""
VIOLATIONS = ("stick_violation", "slip_violation")
"""Consistency margins (units of p0): round-off near zero at a consistent case (two OpenBLAS
kernels moved them by up to 1e-14), compared to :data:`ROUNDOFF` absolute."""
ESTIMATE_OF = {"friction_coefficient": "error_estimate", "load_ratio": "load_error_estimate",
               "frictional_work": "work_error_estimate"}
"""Which estimate bounds a variable of the default method (profiles: k's)."""


def _script():
    spec = importlib.util.spec_from_file_location("mainjob_reference",
                                                  DATA / "mainjob_reference.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _float(v) -> float:
    if isinstance(v, str):
        return float(v)  # "inf", "-inf"
    return math.nan if v is None else float(v)


def assert_close(got, want, tol: float, where: str) -> None:
    """Numbers within ``tol`` (absolute); NaN and infinities exactly."""
    g, w = _float(got), _float(want)
    if not math.isfinite(w) or not math.isfinite(g):
        assert (math.isnan(g) and math.isnan(w)) or g == w, (where, got, want)
        return
    assert abs(g - w) <= tol, (where, got, want, tol)


def assert_estimate(got, want, where: str) -> None:
    """Two estimates within ESTIMATE_FACTOR of each other (or both round-off small)."""
    g, w = _float(got), _float(want)
    if not (math.isfinite(w) and math.isfinite(g)):
        assert (math.isnan(g) and math.isnan(w)) or g == w, (where, got, want)
        return
    if max(abs(g), abs(w)) <= 1e-12:
        return
    assert w / ESTIMATE_FACTOR <= g <= w * ESTIMATE_FACTOR, (where, got, want)


def _scale(fp: dict) -> float:
    stored = [fp.get("values"), list(fp.get("samples", {}).values())]
    scale = max([abs(_float(v)) for vs in stored if vs for v in vs
                 if v is not None and math.isfinite(_float(v))] + [0.0])
    if fp.get("abs_sum") is not None:
        scale = max(scale, float(fp["abs_sum"]) / max(1, int(np.prod(fp["shape"]))))
    return scale


def _relative_tolerances(dataset: dict, name: str) -> np.ndarray | None:
    """Per case (first dimension) relative tolerance of a default-method variable."""
    if dataset["attrs"].get("method") not in ("default", "extrapolated"):
        return None
    variables = dataset["variables"]
    est = variables.get(ESTIMATE_OF.get(name, "error_estimate"))
    if est is None or variables[name]["dims"][:1] != ["stick_ratio"]:
        return None
    e = np.array([_float(v) for v in est["values"]])
    return np.where(np.isfinite(e), np.maximum(e, ROUNDOFF), ROUNDOFF)


def assert_same_variable(got: dict, want: dict, dataset: dict, name: str, where: str) -> None:
    """One variable's fingerprint against the stored one, by what the variable means."""
    for key in ("dtype", "shape", "dims", "attrs"):
        assert got[key] == want[key], (where, key, got[key], want[key])
    if name in DIAGNOSTICS:
        return
    if "text" in want:
        # messages quote estimates and last steps: their words must agree, not their digits
        norm = [[re.sub(r"[-+]?\d[\d.]*(e[-+]?\d+)?", "#", t) for t in texts]
                if isinstance(texts, list) else texts for texts in (got["text"], want["text"])]
        assert norm[0] == norm[1], (where, got["text"], want["text"])
        return
    if name.endswith("error_estimate"):
        for key in ("values", "samples"):
            items = (enumerate(want[key]) if isinstance(want.get(key), list)
                     else want.get(key, {}).items())
            for i, w in items:
                g = got[key][int(i)] if isinstance(want[key], list) else got[key][i]
                assert_estimate(g, w, f"{where}[{i}]")
        if "sum" in want:
            assert_estimate(got["sum"], want["sum"], f"{where}.sum")
        return
    assert got.get("nan_count") == want.get("nan_count"), (where, "NaN count")
    scale = max(_scale(want), 1.0) if name in VIOLATIONS else _scale(want)
    rel = _relative_tolerances(dataset, name)
    per_case = int(np.prod(want["shape"][1:])) if len(want["shape"]) > 1 else 1
    if "values" in want:
        for i, (g, w) in enumerate(zip(got["values"], want["values"])):
            size = abs(_float(w)) if per_case == 1 and math.isfinite(_float(w)) else scale
            tol = (0.0 if rel is None else rel[i // per_case] * size) + ROUNDOFF * scale
            assert_close(g, w, tol, f"{where}[{i}]")
        return
    for i, w in want["samples"].items():
        tol = (0.0 if rel is None else rel[int(i) // per_case] * scale) + ROUNDOFF * scale
        assert_close(got["samples"][i], w, tol, f"{where}.samples[{i}]")
    r = ROUNDOFF + (0.0 if rel is None else float(np.max(rel)))
    for key in ("sum", "abs_sum"):
        assert_close(got[key], want[key], r * float(want["abs_sum"]), f"{where}.{key}")


def assert_same_dataset(got: dict, want: dict, where: str) -> None:
    """A dataset's fingerprint: structure exactly, numbers by meaning."""
    assert got["sizes"] == want["sizes"], where
    assert sorted(got["attrs"]) == sorted(want["attrs"]), where
    for key, w in want["attrs"].items():
        g = got["attrs"][key]
        if isinstance(w, float):
            assert_close(g, w, ROUNDOFF * abs(w), f"{where}.attrs.{key}")
        else:
            assert g == w, (where, key, g, w)
    assert sorted(got["variables"]) == sorted(want["variables"]), where
    for name, w in want["variables"].items():
        assert_same_variable(got["variables"][name], w, want, name, f"{where}.{name}")


def _last_digit(cell: float) -> float:
    """One unit of the last significant digit a number was written with (6 at most)."""
    if cell == 0 or not math.isfinite(cell):
        return 0.0
    digits = len(re.sub(r"^0\.0*|[.-]|e.*$", "", f"{cell:.6g}".lstrip("-")).rstrip("0")) or 1
    return 10.0 ** (math.floor(math.log10(abs(cell))) - digits + 1)


def assert_same_table(got: list, want: list, where: str) -> None:
    """Key numbers: text exactly, each number within one unit of its last quoted digit."""
    assert len(got) == len(want), where
    for r, (grow, wrow) in enumerate(zip(got, want)):
        assert len(grow) == len(wrow), (where, r)
        for c, (g, w) in enumerate(zip(grow, wrow)):
            if isinstance(w, float) and isinstance(g, float):
                assert_close(g, w, 1.01 * _last_digit(w), f"{where}[{r}][{c}]")
            else:
                assert g == w, (where, r, c, g, w)


# ----------------------------------------------------------------------------- fast tier
def _stored(dataset: str, name: str) -> list:
    return REFERENCE["datasets"][f"datasets/{dataset}.nc"]["variables"][name]["values"]


@pytest.mark.parametrize("scene, geometry, slab", [("sphere-paper", "sphere", 0.0),
                                                   ("cylinder-paper", "cylinder", 0.05)])
def test_paper_scenes_in_process_give_the_stored_numbers(scene, geometry, slab):
    ratios = [_float(c) for c in _stored(scene, "stick_ratio")]
    sols = contactlib.sweep(geometry, 0.3, ratios, n=16, method="paper", slab_ratio=slab)
    for name in ("friction_coefficient", "load_ratio", "frictional_work"):
        want = _stored(scene, name)
        got = [getattr(s, name) for s in sols]
        scale = max(abs(_float(w)) for w in want if w is not None)
        for i, (g, w) in enumerate(zip(got, want)):
            assert_close(g, w, ROUNDOFF * scale, f"{scene}.{name}[{i}]")


def test_a_case_that_did_not_converge_has_no_numbers():
    # the paper's scheme at n = 16 on the slab: Newton finds no root at c/a = 8/16
    sol = contactlib.solve("cylinder", 0.3, stick_ratio=0.5, n=16, method="paper",
                           slab_ratio=0.05)
    assert not sol.converged and not sol.resolved
    assert "did not converge" in sol.message
    for name in ("friction_coefficient", "load_ratio", "frictional_work", "error_estimate"):
        assert math.isnan(getattr(sol, name)), name
    assert np.all(np.isnan(sol.pressure)) and np.all(np.isnan(sol.shear))


def test_the_comparison_sees_a_change_beyond_the_estimate():
    want = REFERENCE["datasets"]["datasets/sphere-default.nc"]
    assert_same_dataset(json.loads(json.dumps(want)), want, "copy")
    est = _float(want["variables"]["error_estimate"]["values"][16])
    for factor, seen in ((0.5, False), (3.0, True)):
        got = json.loads(json.dumps(want))
        got["variables"]["friction_coefficient"]["values"][16] *= 1 + factor * est
        if seen:
            with pytest.raises(AssertionError, match="friction_coefficient"):
                assert_same_dataset(got, want, "changed")
        else:
            assert_same_dataset(got, want, "changed")
    got = json.loads(json.dumps(want))
    got["variables"]["error_estimate"]["values"][16] *= 2.5
    with pytest.raises(AssertionError, match="error_estimate"):
        assert_same_dataset(got, want, "estimate")
    paper = REFERENCE["datasets"]["datasets/cylinder-paper.nc"]
    got = json.loads(json.dumps(paper))
    got["variables"]["friction_coefficient"]["values"][0] *= 1 + 1e-6
    with pytest.raises(AssertionError, match="friction_coefficient"):
        assert_same_dataset(got, paper, "paper")


def test_the_table_comparison_allows_one_unit_of_the_last_digit():
    assert _last_digit(0.3081) == pytest.approx(1e-4)
    assert _last_digit(2.8) == pytest.approx(0.1)
    assert _last_digit(0.00128844) == pytest.approx(1e-8)
    assert_same_table([["a", 0.3082]], [["a", 0.3081]], "t")
    with pytest.raises(AssertionError):
        assert_same_table([["a", 0.3083]], [["a", 0.3081]], "t")


# ----------------------------------------------------------------------------- the main job
@pytest.fixture(scope="module")
def main_job(tmp_path_factory):
    wd = make_workdir(tmp_path_factory.mktemp("mainjob"))
    snakemake(wd, timeout=3600)
    return wd / "results"


@pytest.fixture(scope="module")
def fingerprint(main_job):
    return _script().fingerprint(main_job)


@needs_snakemake
@pytest.mark.workflow
@pytest.mark.slow
def test_main_job_writes_the_stored_files(fingerprint):
    assert fingerprint["files"] == REFERENCE["files"]


@needs_snakemake
@pytest.mark.workflow
@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(REFERENCE["datasets"]))
def test_main_job_dataset_matches_the_reference(fingerprint, name):
    assert_same_dataset(fingerprint["datasets"][name], REFERENCE["datasets"][name], name)


@needs_snakemake
@pytest.mark.workflow
@pytest.mark.slow
def test_main_job_tables_match_the_reference(fingerprint):
    for name, want in REFERENCE["tables"].items():
        assert_same_table(fingerprint["tables"][name], want, name)


@needs_snakemake
@pytest.mark.workflow
@pytest.mark.slow
def test_main_job_draws_no_value_of_a_case_that_did_not_converge(main_job):
    import xarray as xr

    for path in sorted((main_job / "datasets").glob("*-paper.nc")):
        with xr.open_dataset(path) as ds:
            failed = ~ds["converged"].values.astype(bool)
            assert failed.any(), path.name  # the printed scheme fails at n = 16
            for name in ("friction_coefficient", "load_ratio", "frictional_work",
                         "pressure", "shear", "tangential_displacement"):
                assert np.all(np.isnan(ds[name].values[failed])), (path.name, name)


@needs_snakemake
@pytest.mark.workflow
@pytest.mark.slow
def test_main_job_figures_are_byte_identical_when_drawn_again(main_job, fingerprint):
    snakemake(main_job.parent, "--forcerun", "figures_paper", "figures_history", "key_numbers",
              timeout=1200)
    again = {f: hashlib.sha256((main_job / f).read_bytes()).hexdigest()
             for f in fingerprint["figures"]["sha256"]}
    assert again == fingerprint["figures"]["sha256"]


# ----------------------------------------------------------------------------- report, captions
REPORT = DATA.parent.parent / "workflow" / "report"


def _report_results(html: str) -> dict:
    """The ``var results = {...};`` table of a Snakemake report: file -> name, caption."""
    start = html.index("var results = {") + len("var results = ")
    return json.JSONDecoder().raw_decode(html[start:])[0]


@needs_snakemake
@pytest.mark.workflow
@pytest.mark.slow
def test_report_lists_every_figure_with_its_caption_and_the_table(main_job):
    snakemake(main_job.parent, "--report", "results/report.html", timeout=600)
    results = _report_results((main_job / "report.html").read_text())
    figures = sorted(p.name for p in (main_job / "figures").glob("*.png"))
    assert figures
    physical = {name for name, raw in parse_scenes(
        yaml.safe_load((main_job.parent / "config" / "config.yaml").read_text())["scenes"]
    ).items() if raw.kind == "physical"}  # one caption for every physical scene's figure
    for name in figures + ["key-numbers.html"]:
        entry = results.get(f"results/figures/{name}") or results.get(f"results/tables/{name}")
        assert entry is not None, f"{name} is not in the report"
        stem = "key_numbers" if name == "key-numbers.html" else name[:-4]
        stem = "physical" if stem in physical else stem
        title = re.search(r"\*\*(.+?)\*\*", (REPORT / f"{stem}.rst").read_text()).group(1)
        assert title in entry["caption"], (name, title)


def _dataset(results, scene):
    import xarray as xr

    return xr.open_dataset(results / "datasets" / f"{scene}.nc")


# Every number the captions of figures 2, 3 and 5 quote from the data: (caption, the text
# as quoted, the value from the main job's datasets and table, its format).
def _caption_claims(r):
    sp, sd = _dataset(r, "sphere-paper"), _dataset(r, "sphere-default")
    cp, cd = _dataset(r, "cylinder-paper"), _dataset(r, "cylinder-default")
    k = "friction_coefficient"
    table = {row[0]: row for row in _script().fingerprint_table(r / "tables/key-numbers.csv")}
    columns = table["scene"]
    load0 = float(table["sphere-paper"][columns.index("frictionless P/P_Hertz")])
    beta = 0.4 / 1.4  # nu = 0.3, rigid indenter: (1 - 2 nu) / (2 (1 - nu))

    def at(ds, name, c):
        return float(ds[name].sel(stick_ratio=c, method="nearest"))

    def asymptote(c):  # V ~ (16/5 pi)(pi/4 - 2/3) k beta
        return 16 / (5 * math.pi) * (math.pi / 4 - 2 / 3) * at(sd, k, c) * beta

    inner = {"stick_ratio": slice(0.001, 0.98)}
    return [
        ("fig2", "0.29 against\n0.152", (at(sp, k, 0.5), at(sd, k, 0.5)), "{:.2f} against\n{:.3f}"),
        ("fig2", "k = −0.572", at(cp, k, 0.25), "k = {:.3f}"),
        ("fig3", "k = −0.572", at(cp, k, 0.25), "k = {:.3f}"),
        ("fig3", "4.2% above\nHertz", 100 * (load0 - 1), "{:.1f}% above\nHertz"),
        ("fig3", "dip to 0.34 p0", float(cp.pressure.sel(stick_ratio=0.25).min()),
         "dip to {:.2f} p0"),
        ("fig3", "pressure of −23 p0", float(cp.pressure.sel(stick_ratio=0.3125).min()),
         "pressure of {:.0f} p0"),
        ("fig3", "load of −6.1 times", at(cp, "load_ratio", 0.3125), "load of {:.1f} times"),
        ("fig3", "0 ≤ p ≤ 1.11 p0", (float(cd.pressure.sel(**inner).min()) + 0.0,
                                     float(cd.pressure.sel(**inner).max())), "{:.0f} ≤ p ≤ {:.2f} p0"),
        ("fig3", "1.090 p0 at c/a = 0.001 and 1.097 p0 at c/a = 0.9",
         (float(sd.pressure.sel(stick_ratio=0.001)[0]), float(sd.pressure.sel(stick_ratio=0.9)[0])),
         "{:.3f} p0 at c/a = 0.001 and {:.3f} p0 at c/a = 0.9"),
        ("fig5", "0.99e-3 at c/a = 0.001 to a maximum of 1.51e-3 near\nc/a = 0.15",
         (1e3 * at(sd, "frictional_work", 0.001), 1e3 * float(sd.frictional_work.max()),
          float(sd.stick_ratio[int(sd.frictional_work.argmax("stick_ratio"))])),
         "{:.2f}e-3 at c/a = 0.001 to a maximum of {:.2f}e-3 near\nc/a = {:.2f}"),
        ("fig5", "from 0.98e-3 to 1.29e-3 near c/a = 1/16",
         (1e3 * at(cd, "frictional_work", 0.001), 1e3 * float(cd.frictional_work.max()),
          16 * float(cd.stick_ratio[int(cd.frictional_work.argmax("stick_ratio"))])),
         "from {:.2f}e-3 to {:.2f}e-3 near c/a = {:.0f}/16"),
        ("fig5", "k = 0.036 at c/a = 0.001", at(sd, k, 0.001), "k = {:.3f} at c/a = 0.001"),
        ("fig5", "0.80 of it (0.54 at c/a = 0.1)",
         (at(sd, "frictional_work", 0.001) / asymptote(0.001),
          at(sd, "frictional_work", 0.1) / asymptote(0.1)), "{:.2f} of it ({:.2f} at c/a = 0.1)"),
    ]


@needs_snakemake
@pytest.mark.workflow
@pytest.mark.slow
def test_caption_numbers_are_those_of_the_data(main_job):
    for caption, quoted, value, form in _caption_claims(main_job):
        text = " ".join((REPORT / f"{caption}.rst").read_text().split())
        want = " ".join(quoted.split())
        assert want in text, (caption, want)
        values = value if isinstance(value, tuple) else (value,)
        got = re.sub(r"(^|[\s(])-", "\\1−", " ".join(form.format(*values).split()))
        assert got == want, (caption, got, want)


@needs_snakemake
@pytest.mark.workflow
@pytest.mark.slow
def test_caption_statements_hold_in_the_data(main_job):
    sp, sd = _dataset(main_job, "sphere-paper"), _dataset(main_job, "sphere-default")
    cp, cd = _dataset(main_job, "cylinder-paper"), _dataset(main_job, "cylinder-default")
    # fig2: the printed scheme's work changes sign between c/a = 4/16 and 5/16 (sphere); ours
    # is consistent from 0.001 to 0.98 for both geometries
    w = sp.frictional_work
    assert float(w.sel(stick_ratio=0.25)) > 0 > float(w.sel(stick_ratio=0.3125))
    for ds in (sd, cd):
        assert bool(ds.consistent.sel(stick_ratio=slice(0.001, 0.98)).all())
    # fig3: Newton finds no root at 8/16 and 12/16 on the slab
    assert not cp.converged.sel(stick_ratio=[0.5, 0.75]).any()
    # fig5: negative work from c/a = 5/16 on (sphere, where the scheme has a value)
    late = w.sel(stick_ratio=slice(0.3, 1.0))
    assert bool((late.where(sp.converged.sel(stick_ratio=late.stick_ratio)) < 0).sum()
                == sp.converged.sel(stick_ratio=late.stick_ratio).sum())
