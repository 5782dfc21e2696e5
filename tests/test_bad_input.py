"""Bad input everywhere: command line, library entry points, scenes, config schema.

Property-based (hypothesis): random invalid values and random argument lists
are thrown at ``contactlib.cli.main``, ``contactlib.solve`` / ``sweep`` and
``contactlib.scene.parse_scene``. Every one must be refused cleanly: exit
status 2 and one line ``contactlib: error: ...`` naming the option (CLI), a
ValueError naming the argument (library) or the key ``scenes.<name>.<key>``
(scenes), never a crash and never a file written. The workflow refuses a bad
configuration before any job, naming every bad key.

Inputs that once crashed (integers beyond the float range, a 5000-digit --n,
odd types in a scene) have tests of their own below.
"""

from __future__ import annotations

import contextlib
import io as _io
import math
import os
import re
from unittest import mock

import jsonschema
import numpy as np
import pytest
import yaml
from hypothesis import HealthCheck, assume, example, given, settings
from hypothesis import strategies as st

import contactlib
from conftest import REPO, dry_run, make_workdir, needs_snakemake
from contactlib import api, cli
from contactlib.result import Solution
from contactlib.scene import parse_scene

SCHEMA = yaml.safe_load((REPO / "workflow/schemas/config.schema.yaml").read_text())
FAST = settings(max_examples=150, deadline=None,
                suppress_health_check=[HealthCheck.function_scoped_fixture])


def _float(text: str) -> float | None:
    try:
        return float(text)
    except (ValueError, TypeError, OverflowError):
        return None


# ----------------------------------------------------------------------------- strategies
junk_text = st.text(min_size=0, max_size=12)
special_numbers = st.sampled_from(["nan", "NaN", "inf", "-inf", "+inf", "1e400", "-1e400",
                                   "1e-400", "0x10", "1,5", "1.2.3", "--", "", " ", "\n",
                                   "\x00", "½", "٠.٣"])
number_text = st.floats(allow_nan=True, allow_infinity=True).map(repr)


def text_outside(ok) -> st.SearchStrategy[str]:
    """Option values (strings) that the documented rule ``ok(float)`` refuses."""
    return st.one_of(junk_text, special_numbers, number_text,
                     st.integers(-10**30, 10**30).map(str)).filter(
        lambda t: (v := _float(t)) is None or not ok(v))


BAD_OPTION = {
    "--nu": text_outside(lambda v: -1 < v <= 0.5),
    "--stick-ratio": text_outside(lambda v: 0 <= v <= 1),
    "--friction": text_outside(lambda v: v >= 0),
    "--slab-ratio": text_outside(lambda v: math.isfinite(v) and v >= 0),
    # refused by the parser (not an integer >= 2) or by the library (> 4096; < 16 for
    # the default method)
    "--n": st.one_of(text_outside(lambda v: False).filter(
                         lambda t: not (re.fullmatch(r"\s*\+?[0-9]+\s*", t)
                                        and 16 <= int(t) <= 4096)),
                     st.integers(-10**6, 15).map(str),
                     st.integers(4097, 10**100).map(str)),
    "--geometry": junk_text.filter(lambda t: t not in ("sphere", "cylinder")),
    "--method": junk_text.filter(lambda t: t not in api.METHODS),
}
GOOD_SOLVE = {"--geometry": "sphere", "--nu": "0.3", "--stick-ratio": "0.5"}


def run_cli(argv: list[str]) -> tuple[int, str, str]:
    out, err = _io.StringIO(), _io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = cli.main(argv)
    return code, out.getvalue(), err.getvalue()


def assert_refused(code: int, out: str, err: str, names: tuple[str, ...]) -> None:
    assert code == 2, (code, err)
    assert err.startswith("contactlib: error: ") and err.endswith("\n"), err
    assert err.count("\n") == 1, err
    assert "Traceback" not in err and out == ""
    assert any(name in err for name in names), (names, err)


def _argv(options: dict[str, str], command: str = "solve") -> list[str]:
    argv = [command]
    for key, value in options.items():
        argv += [key, value] if value is not None else [key]
    return argv


# ----------------------------------------------------------------------------- CLI, real library
@FAST
@given(data=st.data())
def test_cli_refuses_any_invalid_value(data, tmp_path):
    option = data.draw(st.sampled_from(sorted(BAD_OPTION)), label="option")
    value = data.draw(BAD_OPTION[option], label="value")
    options = dict(GOOD_SOLVE)
    if option == "--friction":
        del options["--stick-ratio"]
    if option == "--slab-ratio":
        options["--geometry"] = "cylinder"
    options[option] = value
    out_file = tmp_path / "out" / "x.nc"
    argv = _argv(options) + ["--output", str(out_file)]
    code, out, err = run_cli(argv)
    # the option itself, or the library's name for it (n, nu, method, ...)
    names = (option, option.lstrip("-").replace("-", "_") + " must")
    assert_refused(code, out, err, names)
    assert not (tmp_path / "out").exists()


@FAST
@given(ratios=st.one_of(
    st.lists(text_outside(lambda v: 0 <= v <= 1), min_size=1, max_size=4).map(",".join),
    st.lists(st.sampled_from(["0.1", "0.2"]), min_size=2, max_size=3).filter(
        lambda xs: len(set(xs)) < len(xs)).map(",".join),  # duplicates
    st.sampled_from(["", ",", "0.1,", ",0.1", "al", "none", "0.1;0.2"])))
def test_cli_sweep_refuses_invalid_stick_ratio_lists(ratios, tmp_path):
    assume(ratios.strip().lower() != "all")
    out_file = tmp_path / "s.nc"
    code, out, err = run_cli(["sweep", "--geometry", "sphere", "--nu", "0.3", "--n", "16",
                              "--method", "paper", "--stick-ratios", ratios,
                              "--output", str(out_file)])
    assert_refused(code, out, err, ("--stick-ratios", "stick_ratios"))
    assert os.listdir(tmp_path) == []


@pytest.mark.parametrize("argv, name", [
    (["--n", "5000"], "--n must be an integer in [2, 4096]"),
    (["--n", "8"], "n must be at least 16"),
    (["--method", "paper", "--n", "16", "--stick-ratio", "0.3"], "multiple of 1/n"),
    (["--geometry", "sphere", "--slab-ratio", "1001"], "--slab-ratio"),
    (["--geometry", "cylinder", "--slab-ratio", "501"], "--slab-ratio"),
    (["--geometry", "cylinder", "--slab-ratio", "1001", "--base", "bonded"], "--slab-ratio"),
    (["--geometry", "sphere", "--slab-ratio", "1", "--base", "rigid"], "--base"),
])
def test_cli_refuses_what_only_the_library_knows(argv, name, tmp_path):
    options = dict(GOOD_SOLVE)
    options.update(dict(zip(argv[::2], argv[1::2])))
    code, out, err = run_cli(_argv(options) + ["--output", str(tmp_path / "o.nc")])
    assert_refused(code, out, err, (name,))
    assert os.listdir(tmp_path) == []


# ----------------------------------------------------------------------------- CLI, random argv
TOKENS = st.one_of(
    st.sampled_from(["solve", "sweep", "history", "--geometry", "--nu", "--stick-ratio",
                     "--friction", "--n", "--method", "--slab-ratio", "--output",
                     "--stick-ratios", "--no-energy", "--debug", "--", "-", "-x", "--nu=0.3",
                     "--geo", "sphere", "cylinder", "0.3", "0.5", "1", "0", "all", "16", "paper",
                     "default", "out.nc", "-0.5", "nan", "inf"]),
    junk_text)


class RecordingApi:
    """Stands in for contactlib.api: records what the parser lets through."""

    METHODS = api.METHODS

    def __init__(self) -> None:
        self.calls: list[dict] = []

    def _solution(self, geometry, nu, c, n, method, slab_ratio):
        xi = np.linspace(0.0, 1.0, 3)
        return Solution(geometry, nu, method, n or 16, slab_ratio, c, 0.1, xi, xi, xi, xi, 1.0)

    def solve(self, geometry, nu, *, stick_ratio=None, friction=None, n=None,
              method="default", slab_ratio=0.0, energy=True, max_error=1e-3):
        self.calls.append(dict(geometry=geometry, nu=nu, stick_ratio=stick_ratio,
                               friction=friction, n=n, slab_ratio=slab_ratio))
        c = 0.5 if stick_ratio is None else stick_ratio
        return self._solution(geometry, nu, c, n, method, slab_ratio)

    def sweep(self, geometry, nu, stick_ratios="all", *, n=None, method="default",
              slab_ratio=0.0, energy=True, progress=None, max_error=1e-3):
        self.calls.append(dict(geometry=geometry, nu=nu, stick_ratios=stick_ratios, n=n,
                               slab_ratio=slab_ratio))
        return [self._solution(geometry, nu, 0.5, n, method, slab_ratio)]


@settings(max_examples=300, deadline=None)
@given(argv=st.lists(TOKENS, max_size=12))
@example(argv=["solve", "--geometry", "sphere", "--nu", "0.3", "--stick-ratio", "0.5"])
@example(argv=["sweep", "--geometry", "cylinder", "--nu", "-0.5", "--output", "out.nc"])
@example(argv=["--help"])
def test_cli_never_crashes_on_random_arguments(argv):
    fake = RecordingApi()
    written = []

    def no_history():  # `history` needs --load-path and --steps, which are never drawn
        raise AssertionError("the history numerics were reached")

    with mock.patch.object(cli, "_api", lambda: fake), \
            mock.patch.object(cli, "_history_api", no_history, create=True), \
            mock.patch.object(cli, "_write", lambda obj, path: written.append(path)):
        code, out, err = run_cli(argv)
    if any(a in ("-h", "--help", "--version") for a in argv) and code == 0:
        return  # help and version print and exit without the library
    assert code in (0, 2), (code, err)
    if code == 2:
        assert err.startswith("contactlib: error: ") and err.count("\n") == 1, err
        assert fake.calls == [] and written == []
        return
    # accepted: the library got one call, with values in their documented ranges
    assert err == "" and len(fake.calls) == 1
    call = fake.calls[0]
    assert call["geometry"] in ("sphere", "cylinder")
    assert -1 < call["nu"] <= 0.5
    assert call["n"] is None or call["n"] >= 2
    assert math.isfinite(call["slab_ratio"]) and call["slab_ratio"] >= 0
    assert call["geometry"] == "cylinder" or call["slab_ratio"] == 0
    if call.get("stick_ratio") is not None:
        assert 0 <= call["stick_ratio"] <= 1
    if call.get("friction") is not None:
        assert call["friction"] >= 0
    ratios = call.get("stick_ratios")
    if isinstance(ratios, list):
        assert ratios and all(0 <= r <= 1 for r in ratios) and len(set(ratios)) == len(ratios)


def test_cli_refuses_an_integer_too_long_to_convert(tmp_path):
    options = dict(GOOD_SOLVE, **{"--n": "1" + "0" * 5000})
    code, out, err = run_cli(_argv(options))
    assert_refused(code, out, err, ("--n", "n must"))


# ----------------------------------------------------------------------------- library
wrong_type = st.one_of(st.booleans(), st.text(max_size=5), st.complex_numbers(),
                       st.lists(st.floats(), max_size=2),
                       st.dictionaries(st.text(), st.none(), max_size=1))
not_a_number = st.one_of(st.none(), wrong_type)
non_finite = st.sampled_from([math.nan, math.inf, -math.inf, np.float64("nan")])


def reals_outside(lo, hi, lo_open=False, hi_open=False):
    """Finite reals (float, int, numpy) outside the interval."""
    def bad(v):
        return (lo is not None and (v < lo or (lo_open and v == lo))) or \
               (hi is not None and (v > hi or (hi_open and v == hi)))
    return st.one_of(st.floats(allow_nan=False, allow_infinity=False),
                     st.integers(-10**300, 10**300),
                     st.floats(allow_nan=False, allow_infinity=False).map(np.float64)).filter(bad)


BAD_ARGUMENT = {
    "geometry": st.one_of(junk_text.filter(lambda t: t not in ("sphere", "cylinder")),
                          st.none(), st.integers(), st.lists(st.text(), max_size=2)),
    "method": st.one_of(junk_text.filter(lambda t: t not in api.METHODS),
                        st.integers()),  # None: the default method (or the planned one)
    "nu": st.one_of(not_a_number, non_finite, reals_outside(-1.0, 0.5, lo_open=True)),
    "stick_ratio": st.one_of(wrong_type, non_finite,
                             reals_outside(0.0, 1.0)),
    "friction": st.one_of(wrong_type,
                          st.sampled_from([math.nan, -math.inf]), reals_outside(0.0, None)),
    "n": st.one_of(st.text(max_size=4), st.booleans(), st.integers(-10**30, 15),
                   st.integers(4097, 10**300), st.floats().filter(
                       lambda v: not (math.isfinite(v) and v.is_integer() and 16 <= v <= 4096))),
    "slab_ratio": st.one_of(wrong_type, non_finite,
                            reals_outside(0.0, 1000.0)),  # 1000: the largest bound (sphere)
    "base": st.one_of(junk_text.filter(lambda t: t not in ("smooth", "bonded")), st.none(),
                      st.integers()),
}


@settings(max_examples=300, deadline=None)
@given(data=st.data())
def test_solve_refuses_invalid_arguments_with_a_value_error_naming_them(data):
    name = data.draw(st.sampled_from(sorted(BAD_ARGUMENT)), label="argument")
    value = data.draw(BAD_ARGUMENT[name], label="value")
    kwargs = dict(geometry="cylinder", nu=0.3, stick_ratio=0.5, n=16, method="default",
                  slab_ratio=0.0, energy=False)
    if name == "friction":
        kwargs.pop("stick_ratio")
    kwargs[name] = value
    with pytest.raises(ValueError) as err:
        contactlib.solve(**kwargs)
    assert str(err.value).startswith(f"{name} must") or name in str(err.value), err.value


@settings(max_examples=150, deadline=None)
@given(data=st.data())
def test_sweep_refuses_invalid_arguments_with_a_value_error_naming_them(data):
    name = data.draw(st.sampled_from(sorted(set(BAD_ARGUMENT) - {"stick_ratio", "friction"})
                                     + ["stick_ratios"]), label="argument")
    if name == "stick_ratios":
        value = data.draw(st.one_of(
            st.text(max_size=5).filter(lambda t: t != "all"), st.just([]), st.none(),
            st.integers(), st.lists(st.one_of(not_a_number, non_finite,
                                              reals_outside(0.0, 1.0)), min_size=1, max_size=3),
        ), label="value")
    else:
        value = data.draw(BAD_ARGUMENT[name], label="value")
    kwargs = dict(geometry="sphere", nu=0.3, stick_ratios=[0.5], n=16, method="default",
                  slab_ratio=0.0, energy=False)
    kwargs[name] = value
    with pytest.raises(ValueError) as err:
        contactlib.sweep(**kwargs)
    assert name in str(err.value), err.value


@pytest.mark.parametrize("kwargs, name", [
    (dict(nu=10**400, stick_ratio=0.5), "nu"),
    (dict(nu=0.3, stick_ratio=10**400), "stick_ratio"),
    (dict(nu=0.3, friction=10**400), "friction"),
    (dict(nu=0.3, friction=-10**400), "friction"),
    (dict(nu=0.3, stick_ratio=0.5, slab_ratio=10**400), "slab_ratio"),
])
def test_solve_refuses_integers_beyond_the_float_range(kwargs, name):
    with pytest.raises(ValueError, match=name):
        contactlib.solve("cylinder", n=16, **kwargs)


# ----------------------------------------------------------------------------- scenes and schema
GOOD_SCENE = {"geometry": "sphere", "nu": 0.3, "method": "default", "n": 32,
              "stick_ratios": [0.0, 0.5], "outputs": ["k_curve"]}
BAD_SCENE_VALUE = {
    "geometry": BAD_ARGUMENT["geometry"],
    "method": st.one_of(BAD_ARGUMENT["method"], st.none()),  # a scene's method: a name
    "nu": st.one_of(wrong_type, non_finite,
                    reals_outside(-1.0, 0.5, lo_open=True).filter(lambda v: abs(v) < 1e300)),
    "n": BAD_ARGUMENT["n"].filter(lambda v: not (isinstance(v, int) and abs(v) > 10**300)),
    "slab_ratio": st.one_of(wrong_type, non_finite,
                            reals_outside(0.0, None).filter(lambda v: abs(v) < 1e300),
                            st.floats(min_value=1000.001, max_value=1e6)),  # beyond the range
    "base": st.one_of(junk_text.filter(lambda t: t not in ("smooth", "bonded")),
                      st.integers()),
    "stick_ratios": st.one_of(st.text(max_size=5).filter(lambda t: t != "all"), st.just([]),
                              st.integers(), st.lists(st.one_of(
                                  non_finite, reals_outside(0.0, 1.0).filter(
                                      lambda v: abs(v) < 1e300), st.text(max_size=2)),
                                  min_size=1, max_size=3)),
    "outputs": st.one_of(st.text(max_size=8), st.just([]),
                         st.lists(st.text(max_size=8).filter(
                             lambda t: t not in ("k_curve", "stresses", "displacements",
                                                 "energy")), min_size=1, max_size=2)),
}
scene_names = st.from_regex(r"[A-Za-z0-9][A-Za-z0-9_-]{0,8}", fullmatch=True)


@FAST
@given(data=st.data())
def test_parse_scene_names_the_scene_and_key(data):
    name = data.draw(scene_names, label="name")
    key = data.draw(st.sampled_from(sorted(BAD_SCENE_VALUE) + ["unknown"]), label="key")
    raw = dict(GOOD_SCENE)
    if key == "unknown":
        key = data.draw(st.text(min_size=1, max_size=8).filter(lambda t: t not in raw),
                        label="unknown key")
        raw[key] = data.draw(st.integers(), label="value")
    elif data.draw(st.booleans(), label="drop it") and key in ("geometry", "nu", "stick_ratios"):
        del raw[key]  # a required key missing
    else:
        raw[key] = data.draw(BAD_SCENE_VALUE[key], label="value")
    with pytest.raises(ValueError) as err:
        parse_scene(name, raw)
    assert str(err.value).startswith(f"scenes.{name}.{key}: "), err.value


scene_values = {
    "geometry": st.one_of(st.sampled_from(["sphere", "cylinder"]), BAD_SCENE_VALUE["geometry"]),
    "nu": st.one_of(st.floats(-1, 0.5), BAD_SCENE_VALUE["nu"]),
    "method": st.one_of(st.sampled_from(api.METHODS), BAD_SCENE_VALUE["method"]),
    "n": st.one_of(st.integers(2, 4096), BAD_SCENE_VALUE["n"]),
    "slab_ratio": st.one_of(st.just(0.0), BAD_SCENE_VALUE["slab_ratio"]),
    "stick_ratios": st.one_of(st.just("all"), st.lists(st.floats(0, 1), min_size=1, max_size=3),
                              BAD_SCENE_VALUE["stick_ratios"]),
    "outputs": st.one_of(st.just(["k_curve"]), BAD_SCENE_VALUE["outputs"]),
}


def _from_yaml(value) -> bool:
    """Whether a YAML file could hold the value (no complex numbers, numpy scalars)."""
    if isinstance(value, (list, tuple)):
        return all(_from_yaml(v) for v in value)
    if isinstance(value, dict):
        return all(_from_yaml(k) and _from_yaml(v) for k, v in value.items())
    return value is None or type(value) in (bool, int, float, str)


@FAST
@given(raw=st.fixed_dictionaries({}, optional=scene_values).filter(_from_yaml))
def test_what_the_schema_accepts_the_library_accepts_or_refuses_by_key(raw):
    """Schema first, then the library: never a crash in between (as in common.smk)."""
    errors = list(jsonschema.Draft202012Validator(SCHEMA).iter_errors({"scenes": {"s": raw}}))
    if errors:
        return
    try:
        parse_scene("s", raw)
    except ValueError as exc:
        assert str(exc).startswith("scenes.s."), exc


@pytest.mark.parametrize("extra", [{"outputs": 5}, {"outputs": None}, {1: 2, "colour": 3}])
def test_parse_scene_refuses_odd_types(extra):
    raw = {**GOOD_SCENE, **extra}
    with pytest.raises(ValueError, match=r"^scenes\.s\."):
        parse_scene("s", raw)


# ----------------------------------------------------------------------------- workflow config
@needs_snakemake
@pytest.mark.workflow
def test_workflow_reports_every_schema_problem_by_key(tmp_path):
    ok = {"geometry": "sphere", "nu": 0.3, "n": 32, "stick_ratios": [0.3]}
    config = {
        "scenes": {
            "nu-text": dict(ok, nu="abc"),
            "n-float": dict(ok, n=2.5),
            "n-huge": dict(ok, n=5000),
            "ratios-word": dict(ok, stick_ratios="some"),
            "ratios-empty": dict(ok, stick_ratios=[]),
            "outputs-twice": dict(ok, outputs=["energy", "energy"]),
            "no-nu": {"geometry": "sphere", "stick_ratios": [0.3]},
            "extra-key": dict(ok, colour="red"),
            "bad name!": ok,
        },
        "figures": {"fig9": ["nu-text"]},
        "scene": {},
    }
    code, text = dry_run(make_workdir(tmp_path, config, folders=("workflow",)))
    assert code != 0
    for where in ("scenes.nu-text.nu", "scenes.n-float.n", "scenes.n-huge.n",
                  "scenes.ratios-word.stick_ratios", "scenes.ratios-empty.stick_ratios",
                  "scenes.outputs-twice.outputs", "scenes.no-nu.nu: is required",
                  "scenes.extra-key", "colour", "bad name!", "figures", "fig9", "scene"):
        assert where in text, (where, text)
    assert not (tmp_path / "results").exists()


@pytest.mark.parametrize("scene, where", [
    ({"geometry": "sphere", "nu": float("nan"), "stick_ratios": [0.3]}, "scenes.x.nu"),
    pytest.param({"geometry": "cylinder", "nu": 0.3, "slab_ratio": float("inf"),
                  "stick_ratios": [0.3]}, "scenes.x.slab_ratio", marks=pytest.mark.slow),
    pytest.param({"geometry": "sphere", "nu": 0.3, "n": 8, "stick_ratios": [0.3]}, "scenes.x.n",
                 marks=pytest.mark.slow),
])
@needs_snakemake
@pytest.mark.workflow
def test_workflow_library_rules_catch_what_the_schema_lets_through(tmp_path, scene, where):
    assert not list(jsonschema.Draft202012Validator(SCHEMA).iter_errors({"scenes": {"x": scene}}))
    code, text = dry_run(make_workdir(tmp_path, {"scenes": {"x": scene}}, folders=("workflow",)))
    assert code != 0 and where in text, text
    assert not (tmp_path / "results").exists()
