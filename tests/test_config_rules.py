"""One source of input rules (issue 35, item 5): the workflow's schema follows
contactlib.validate, and `contactlib check-config` refuses exactly what the workflow
refuses, with the same words.

The bad configurations are checked one by one by check-config (in-process) and all at
once by one `snakemake --dry-run` (the workflow reports every scene's problems
independently, so its lines split by scene); the two YAML-level ones (a scene name and
a key inside a scene given twice) need a dry run each.
"""

from __future__ import annotations

import re

import pytest
import yaml

from conftest import REPO, make_workdir, needs_snakemake, snakemake
from contactlib.model import profiles
from contactlib import validate
from contactlib.cli import check_config
from contactlib.scene import KINDS

SCHEMA = yaml.safe_load((REPO / "workflow" / "schemas" / "config.schema.yaml").read_text())
SCENE = SCHEMA["properties"]["scenes"]
KEYS = SCENE["additionalProperties"]["properties"]


def test_schema_follows_validate() -> None:
    """Every enum, bound and pattern of a scene's keys is validate's (the schema must be
    edited with the constant; this test names the one that drifted)."""
    assert SCENE["propertyNames"]["pattern"] == validate.SCENE_NAME_PATTERN
    assert SCHEMA["properties"]["results_dir"]["pattern"] == validate.RESULTS_DIR_PATTERN
    assert KEYS["kind"]["enum"] == list(KINDS)
    assert KEYS["geometry"]["enum"] == list(validate.GEOMETRIES)
    assert KEYS["method"]["enum"] == list(validate.METHODS)
    assert KEYS["base"]["enum"] == list(validate.BASES) + [validate.COATED_BASE]
    assert (KEYS["substrate_modulus"]["minimum"], KEYS["substrate_modulus"]["maximum"]) == \
        validate.SUBSTRATE_MODULUS_RANGE
    assert KEYS["substrate_nu"]["exclusiveMinimum"] == -1 and KEYS["substrate_nu"]["maximum"] == 0.5
    assert KEYS["profile"]["enum"] == list(profiles.PROFILES)
    assert (KEYS["exponent"]["minimum"], KEYS["exponent"]["maximum"]) == profiles.EXPONENT_RANGE
    assert (KEYS["flat_ratio"]["minimum"], KEYS["flat_ratio"]["maximum"]) == \
        profiles.FLAT_RATIO_RANGE
    assert KEYS["outputs"]["items"]["enum"] == list(validate.OUTPUTS)
    assert KEYS["n"]["maximum"] == max(validate.MAX_N, validate.HISTORY_MAX_N)
    assert KEYS["n"]["minimum"] == min(validate.DEFAULT_N["paper"], validate.HISTORY_MIN_N,
                                       validate.MIN_N_DEFAULT_METHOD, 2)
    assert KEYS["steps"]["maximum"] == validate.MAX_STEPS
    assert (KEYS["tolerance"]["minimum"], KEYS["tolerance"]["maximum"]) == \
        (validate.MIN_TOLERANCE, validate.MAX_TOLERANCE)
    assert KEYS["nu"]["exclusiveMinimum"] == -1 and KEYS["nu"]["maximum"] == 0.5
    validate.nu(0.5)
    for bad in (-1.0, 0.5000001):
        with pytest.raises(validate.InputError):
            validate.nu(bad)
    for name in ("sphere-1", "A_b", "9x"):
        assert re.match(SCENE["propertyNames"]["pattern"], name)
        validate.scene_name(name)


OK = {"geometry": "sphere", "nu": 0.3, "n": 32, "stick_ratios": [0.3]}
HISTORY = {"kind": "history", "geometry": "sphere", "nu": 0.3, "friction": 0.1,
           "load_path": [0, 1], "steps": 4}


def _without(raw: dict, key: str) -> dict:
    return {k: v for k, v in raw.items() if k != key}


# one bad scene a configuration (each merged over config/config.yaml)
BAD = {
    "name.with.dot": OK,
    "tolerance-low": dict(_without(_without(OK, "n"), "method"), tolerance=5e-10),
    "tolerance-and-n": dict(OK, tolerance=1e-3),
    "nu-high": dict(OK, nu=0.7),
    "nu-text": dict(OK, nu="abc"),
    "nu-missing": _without(OK, "nu"),
    "geometry-cone": dict(OK, geometry="cone"),
    "method-fem": dict(OK, method="fem"),
    "n-one": dict(OK, n=1),
    "n-float": dict(OK, n=2.5),
    "n-huge": dict(OK, n=5000),
    "ratios-above-one": dict(OK, stick_ratios=[1.7]),
    "ratios-word": dict(OK, stick_ratios="some"),
    "ratios-empty": dict(OK, stick_ratios=[]),
    "ratios-repeated": dict(OK, stick_ratios=[0.3, 0.3]),
    "outputs-twice": dict(OK, outputs=["energy", "energy"]),
    "outputs-unknown": dict(OK, outputs=["pictures"]),
    "key-unknown": dict(OK, colour="red"),
    "slab-negative": dict(OK, slab_ratio=-1.0),
    "base-glued": dict(OK, base="glued"),
    "max-error-one": dict(OK, max_error=1),
    "kind-unknown": dict(OK, kind="fatigue"),
    "not-a-mapping": 3,
    "grid-short": dict(OK, outputs=["subsurface"], subsurface_grid={"x": [0, 1]}),
    "indenter-negative": dict(OK, indenter={"modulus_ratio": -1}),
    "history-steps-zero": dict(HISTORY, steps=0),
    "history-steps-huge": dict(HISTORY, steps=validate.MAX_STEPS + 1),
    "history-path-short": dict(HISTORY, load_path=[0]),
    "history-friction-repeated": dict(HISTORY, friction=[0.1, 0.1]),
    "history-no-path": _without(HISTORY, "load_path"),
    "history-relaxation-pair": dict(HISTORY, relaxation=[[0.5]], duration=1.0),
    # profiles, coated bodies and fretting paths (issues 36, 37, 39)
    "profile-cube": dict(OK, profile="cube"),
    "profile-power-no-exponent": dict(OK, profile="power"),
    "profile-exponent-huge": dict(OK, profile="power", exponent=20),
    "profile-cone-exponent": dict(OK, profile="cone", exponent=1),
    "profile-cone-paper": dict(OK, profile="cone", method="paper", n=16, stick_ratios=[0.25]),
    "history-profile-word": dict(HISTORY, profile=3),
    "coated-no-modulus": dict(OK, base="elastic", slab_ratio=0.5),
    "coated-modulus-small": dict(OK, base="elastic", slab_ratio=0.5, substrate_modulus=1e-3),
    "coated-nu-high": dict(OK, base="elastic", slab_ratio=0.5, substrate_modulus=2,
                           substrate_nu=0.7),
    "substrate-without-coating": dict(OK, substrate_modulus=2),
    "history-coated": dict(HISTORY, base="elastic"),
    "history-coated-relaxation": dict(HISTORY, base="elastic", slab_ratio=0.5,
                                      substrate_modulus=2, relaxation=[[0.5, 1.0]],
                                      duration=1.0),
    "fretting-sphere": dict(HISTORY, tangential_path=[0, 0.5]),
    "fretting-gross-slip": dict(HISTORY, geometry="cylinder", tangential_path=[0, 1.0]),
    "fretting-path-length": dict(HISTORY, geometry="cylinder", tangential_path=[0, 0, 0.5]),
    "fretting-path-word": dict(HISTORY, geometry="cylinder", tangential_path="back and forth"),
    "fretting-two-k": dict(HISTORY, geometry="cylinder", friction=[0.1, 0.2],
                           tangential_path=[0, 0.5]),
    "fretting-layer": dict(HISTORY, geometry="cylinder", slab_ratio=0.5,
                           tangential_path=[0, 0.5]),
    "fretting-n": dict(HISTORY, geometry="cylinder", n=30, tangential_path=[0, 0.5]),
    "bulk-stress-alone": dict(HISTORY, bulk_stress=[0, 1]),
}


# at the edges of the rules: accepted by both
GOOD = {
    "tolerance-edge": dict(_without(_without(OK, "n"), "method"), tolerance=5e-9),
    "9-digit-first_and_underscore": OK,
    "cone-edge": dict(OK, profile="power", exponent=8),
    "coated-edge": dict(OK, base="elastic", slab_ratio=0.5, substrate_modulus=1e6,
                        substrate_nu=0.5),
    "history-coated-edge": dict(HISTORY, base="elastic", slab_ratio=0.5,
                                substrate_modulus=0.01),
    "fretting-edge": dict(HISTORY, geometry="cylinder", n=16, tangential_path=[0, 0.999],
                          bulk_stress=[0, 0.5]),
}


def _check_config_lines(tmp_path, name: str, raw) -> list[str]:
    path = tmp_path / f"{name}.yaml"
    path.write_text(yaml.safe_dump({"scenes": {name: raw}}, sort_keys=False))
    return check_config([str(REPO / "config" / "config.yaml"), str(path)])


def _workflow_lines(text: str) -> list[str]:
    """The lines of the workflow's "invalid configuration:" error."""
    block = text[text.index("invalid configuration:"):].splitlines()[1:]
    return [line.strip() for line in block if line.startswith("  ") and not
            line.startswith("  File ")]


def _by_scene(lines: list[str]) -> dict[str, list[str]]:
    out: dict[str, list[str]] = {}
    for line in lines:
        name = next(n for n in sorted(BAD, key=len, reverse=True)
                    if line.startswith((f"scenes.{n}.", f"scenes.{n}:")))
        out.setdefault(name, []).append(line)
    return out


@needs_snakemake
@pytest.mark.workflow
def test_check_config_and_the_workflow_refuse_the_same_scenes_in_the_same_words(tmp_path):
    assert len(BAD) >= 20
    expected = {name: _check_config_lines(tmp_path, name, raw) for name, raw in BAD.items()}
    refused_by_check = {name for name, lines in expected.items() if lines}
    assert refused_by_check == set(BAD), set(BAD) - refused_by_check
    wd = make_workdir(tmp_path / "wd" if (tmp_path / "wd").mkdir() is None else tmp_path)
    assert all(_check_config_lines(tmp_path, name, raw) == [] for name, raw in GOOD.items())
    (wd / "bad.yaml").write_text(yaml.safe_dump({"scenes": {**BAD, **GOOD}}, sort_keys=False))
    proc = snakemake(wd, "--dry-run", "--configfile", "bad.yaml", cores=1, check=False,
                     timeout=300)
    text = proc.stdout + proc.stderr
    assert proc.returncode != 0 and not (wd / "results").exists()
    got = _by_scene(_workflow_lines(text))  # no line about a GOOD scene (or it fails here)
    for name in BAD:
        assert sorted(got.get(name, [])) == sorted(expected[name]), name


@needs_snakemake
@pytest.mark.workflow
def test_a_bad_results_dir_is_refused_by_both_in_the_same_words(tmp_path):
    wd = make_workdir(tmp_path / "wd" if (tmp_path / "wd").mkdir() is None else tmp_path)
    (wd / "bad.yaml").write_text(yaml.safe_dump({"results_dir": "../elsewhere"}))
    problems = check_config([str(wd / "config" / "config.yaml"), str(wd / "bad.yaml")])
    assert problems == ["results_dir: results_dir must be a relative path starting with a "
                        "letter, digit or '_', of letters, digits, '_', '.', '/' and '-', "
                        "got '../elsewhere'"]
    proc = snakemake(wd, "--dry-run", "--configfile", "bad.yaml", cores=1, check=False,
                     timeout=300)
    assert proc.returncode != 0 and not (wd / "results").exists()
    assert _workflow_lines(proc.stdout + proc.stderr) == problems


@needs_snakemake
@pytest.mark.workflow
@pytest.mark.parametrize("text, where", [
    ("scenes:\n  twice: {geometry: sphere, nu: 0.3, stick_ratios: [0.3]}\n"
     "  twice: {geometry: sphere, nu: 0.2, stick_ratios: [0.3]}\n",
     "line 3, column 3: duplicate key 'twice' (first at line 2)"),
    ("scenes:\n  s:\n    geometry: sphere\n    nu: 0.3\n    nu: 0.2\n"
     "    stick_ratios: [0.3]\n",
     "line 5, column 5: duplicate key 'nu' (first at line 4)"),
])
def test_a_key_given_twice_is_refused_by_both(tmp_path, text, where):
    wd = make_workdir(tmp_path / "wd" if (tmp_path / "wd").mkdir() is None else tmp_path)
    (wd / "bad.yaml").write_text(text)
    problems = check_config([str(wd / "config" / "config.yaml"), str(wd / "bad.yaml")])
    assert problems == [f"{wd / 'bad.yaml'}, {where}"]
    proc = snakemake(wd, "--dry-run", "--configfile", "bad.yaml", cores=1, check=False,
                     timeout=300)
    assert proc.returncode != 0 and not (wd / "results").exists()
    assert _workflow_lines(proc.stdout + proc.stderr) == problems  # the same words
