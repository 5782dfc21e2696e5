"""The main job's outputs against a stored fingerprint (guard for restructurings).

``tests/data/mainjob_reference.json`` holds the file list, the structure and the
numbers of every dataset, the key-numbers table and the figures' SHA-256 of the
README Quickstart's main job (``snakemake --cores 2``, ``config/config.yaml``);
``tests/data/mainjob_reference.py`` regenerates it and says when that is allowed
(only in a commit that names the bug it fixes).

The main job takes minutes (``slow``, ``workflow``). A cheap check of the same
numbers stays in the fast tier: the paper-scheme scenes (n = 16) solved in process
must give the stored k, load and work to 1e-12.
"""

from __future__ import annotations

import importlib.util
import json
import math

import numpy as np
import pytest

import contactlib
from conftest import DATA, make_workdir, needs_snakemake, snakemake

REFERENCE = json.loads((DATA / "mainjob_reference.json").read_text())
RTOL = 1e-12  # bit-level reproducibility, with room for another BLAS's last digits


def _script():
    spec = importlib.util.spec_from_file_location("mainjob_reference",
                                                  DATA / "mainjob_reference.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _float(v) -> float:
    return math.nan if v is None else float(v)


def assert_close(got, want, scale: float, where: str) -> None:
    """Numbers equal to RTOL (relative to the value, or to the variable's scale near 0)."""
    g, w = _float(got), _float(want)
    if math.isnan(w) or math.isinf(w):
        assert (math.isnan(g) and math.isnan(w)) or g == w, (where, got, want)
        return
    assert abs(g - w) <= RTOL * max(abs(w), scale), (where, got, want)


def assert_same_fingerprint(got: dict, want: dict, where: str) -> None:
    """Recursive comparison: numbers to RTOL, everything else exactly."""
    if isinstance(want, dict):
        assert sorted(got) == sorted(want), (where, sorted(set(got) ^ set(want)))
        stored = [want.get("values"), list(want.get("samples", {}).values())]
        scale = max([abs(_float(v)) for vs in stored if vs for v in vs
                     if v is not None and not isinstance(v, str)] + [0.0])
        if "abs_sum" in want and want["abs_sum"] is not None:
            scale = max(scale, float(want["abs_sum"]) / max(1, np.prod(want["shape"])))
        for key in want:
            sub = f"{where}.{key}"
            if key in ("values", "samples", "sum", "abs_sum"):
                if isinstance(want[key], dict):
                    for i in want[key]:
                        assert_close(got[key][i], want[key][i], scale, f"{sub}[{i}]")
                elif isinstance(want[key], list):
                    assert len(got[key]) == len(want[key]), sub
                    for i, (g, w) in enumerate(zip(got[key], want[key])):
                        assert_close(g, w, scale, f"{sub}[{i}]")
                else:
                    assert_close(got[key], want[key], scale * max(1, np.prod(want["shape"])),
                                 sub)
            else:
                assert_same_fingerprint(got[key], want[key], sub)
    elif isinstance(want, list):
        assert len(got) == len(want), (where, got, want)
        for i, (g, w) in enumerate(zip(got, want)):
            assert_same_fingerprint(g, w, f"{where}[{i}]")
    elif isinstance(want, float) and isinstance(got, float):
        assert_close(got, want, 0.0, where)
    else:
        assert got == want, (where, got, want)


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
            assert_close(g, w, scale, f"{scene}.{name}[{i}]")


def test_the_comparison_sees_a_change_in_the_last_digits():
    want = REFERENCE["datasets"]["datasets/sphere-default.nc"]
    got = json.loads(json.dumps(want))
    assert_same_fingerprint(got, want, "copy")
    k = got["variables"]["friction_coefficient"]["values"]
    k[16] *= 1 + 1e-11
    with pytest.raises(AssertionError, match="friction_coefficient"):
        assert_same_fingerprint(got, want, "changed")


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
    assert_same_fingerprint(fingerprint["datasets"][name], REFERENCE["datasets"][name], name)


@needs_snakemake
@pytest.mark.workflow
@pytest.mark.slow
def test_main_job_tables_match_the_reference(fingerprint):
    assert_same_fingerprint(fingerprint["tables"], REFERENCE["tables"], "tables")


@needs_snakemake
@pytest.mark.workflow
@pytest.mark.slow
def test_main_job_figures_are_byte_identical(fingerprint):
    import matplotlib

    want = REFERENCE["figures"]
    if matplotlib.__version__ != want["matplotlib"]:
        pytest.skip(f"figures stored with matplotlib {want['matplotlib']}, "
                    f"this is {matplotlib.__version__}")
    assert fingerprint["figures"]["sha256"] == want["sha256"]
