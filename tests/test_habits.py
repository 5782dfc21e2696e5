"""Command-line and library habits a new user meets first (issue 'Fit for a new user').

``--version``; negative numbers in exponent form; help texts; ``--output``
checked before any computing; a short ``repr`` of every result; library input
checks (duplicate stick ratios, ``progress``, ``energy``, range wording);
configuration errors all at once, YAML syntax errors with file and line;
damaged intermediates named with the fix.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import jsonschema
import numpy as np
import pytest
import yaml

import contactlib
from conftest import ENV, REPO, dry_run, make_workdir, needs_snakemake
from contactlib import api, cli, io, stages
from contactlib.model import contact
from contactlib.result import Solution, short_repr
from contactlib.scene import ConfigError, parse_scene, parse_scenes

GOOD = ["--geometry", "sphere", "--nu", "0.3"]


def run(capsys, *argv: str) -> tuple[int, str, str]:
    code = cli.main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def assert_refused(code: int, err: str, name: str) -> None:
    assert code == 2, (code, err)
    assert err.startswith("contactlib: error: ") and err.count("\n") == 1, err
    assert name in err and "Traceback" not in err, err


def _solution(n: int = 8, iterations: int = 5) -> Solution:
    xi = np.linspace(0.0, 1.0, 201)
    return Solution("sphere", 0.3, "default", n, 0.0, 0.5, 0.152481, xi, np.sqrt(1 - xi**2),
                    0.1 * xi, 0.5 * xi, 1.02738, frictional_work=0.00100515,
                    iterations=iterations, residual_norm=6.3e-15)


class FakeApi:
    """Records calls; stands in for contactlib.api (no numerics)."""

    METHODS = api.METHODS

    def __init__(self) -> None:
        self.calls: list[dict] = []

    def solve(self, geometry, nu, **kw):
        self.calls.append(dict(geometry=geometry, nu=nu, **kw))
        if kw.get("friction") is not None and kw["friction"] > 100:
            raise ValueError("friction is too large for this fake")
        return _solution()

    def sweep(self, geometry, nu, stick_ratios="all", **kw):
        self.calls.append(dict(geometry=geometry, nu=nu, stick_ratios=stick_ratios, **kw))
        return [_solution()]


class FakeHistory:
    """Stands in for the contactlib.history_api module: records the call, then stops."""

    MAX_STEPS, MIN_N, MAX_N = 100_000, 16, 2048

    def __init__(self) -> None:
        self.calls: list[dict] = []

    def history(self, **kw):
        self.calls.append(kw)
        raise ValueError("fake history: stop here")


@pytest.fixture
def fake(monkeypatch) -> SimpleNamespace:
    f = SimpleNamespace(api=FakeApi(), history=FakeHistory())
    monkeypatch.setattr(cli, "_api", lambda: f.api)
    monkeypatch.setattr(cli, "_history_api", lambda: f.history)
    return f


HISTORY = ["history", "--geometry", "sphere", "--nu", "0.3", "--friction", "0.2",
           "--load-path", "0,1,0", "--steps", "4"]


def _with(argv: list[str], option: str, value: str) -> list[str]:
    out = list(argv)
    out[out.index(option) + 1] = value
    return out


# ----------------------------------------------------------------------------- --version
def test_version(capsys) -> None:
    code, out, err = run(capsys, "--version")
    assert code == 0 and out == f"contactlib {contactlib.__version__}\n" and err == ""


def test_version_python_m() -> None:
    proc = subprocess.run([sys.executable, "-m", "contactlib", "--version"], cwd=REPO, env=ENV,
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0 and proc.stdout == f"contactlib {contactlib.__version__}\n"


# ----------------------------------------------------------------------------- negative numbers
@pytest.mark.parametrize("value, expected", [("-1e-3", -1e-3), ("-2.5E-1", -0.25),
                                             ("-.5", -0.5), ("-5e-1", -0.5)])
def test_negative_exponent_numbers_are_accepted_by_value(capsys, tmp_path, fake, value,
                                                         expected) -> None:
    code, _, err = run(capsys, "solve", "--geometry", "sphere", "--nu", value,
                       "--stick-ratio", "0.5")
    assert code == 0, err
    assert fake.api.calls[0]["nu"] == expected
    code, _, err = run(capsys, "sweep", "--geometry", "sphere", "--nu", value,
                       "--output", str(tmp_path / "s.nc"))
    assert code == 0, err
    assert fake.api.calls[1]["nu"] == expected
    code, _, err = run(capsys, *_with(HISTORY, "--nu", value), "--output",
                       str(tmp_path / "h.nc"))
    assert code == 2 and "fake history: stop here" in err  # the numerics were reached ...
    assert fake.history.calls[0]["nu"] == expected  # ... with the value


@pytest.mark.parametrize("argv, option, value", [
    (["solve", *GOOD, "--stick-ratio", "0.5"], "--nu", "-1e3"),
    (["solve", *GOOD, "--stick-ratio", "0.5"], "--nu", "-inf"),
    (["solve", *GOOD, "--stick-ratio", "0.5"], "--stick-ratio", "-1e-3"),
    (["solve", *GOOD, "--friction", "0.5"], "--friction", "-1e-3"),
    (["solve", *GOOD, "--friction", "0.5"], "--friction", "-inf"),
    (["solve", "--geometry", "cylinder", "--nu", "0.3", "--stick-ratio", "0.5",
      "--slab-ratio", "0"], "--slab-ratio", "-1e-3"),
    (["solve", *GOOD, "--stick-ratio", "0.5", "--n", "16"], "--n", "-1e3"),
    (["sweep", *GOOD, "--stick-ratios", "all"], "--stick-ratios", "-1e-3,0.5"),
    (["sweep", *GOOD, "--stick-ratios", "all"], "--stick-ratios", "-0.1"),
    (HISTORY, "--nu", "-1e3"),
    (HISTORY, "--friction", "-1e-3"),
    (HISTORY, "--load-path", "-1e-3,1"),
    (HISTORY, "--steps", "-1e3"),
])
def test_negative_exponent_numbers_reach_the_validator(capsys, tmp_path, fake, argv, option,
                                                       value) -> None:
    code, _, err = run(capsys, *_with(argv, option, value), "--output", str(tmp_path / "o.nc"))
    assert_refused(code, err, option)
    assert repr(value) in err  # refused by value, not "expected one argument"
    assert fake.api.calls == [] and fake.history.calls == [] and os.listdir(tmp_path) == []


# ----------------------------------------------------------------------------- help
def _help(capsys, monkeypatch, *argv: str) -> str:
    monkeypatch.setenv("COLUMNS", "400")  # no wrapping inside words like paper-literal
    assert cli.main([*argv, "--help"]) == 0
    return " ".join(capsys.readouterr().out.split())


def test_help_texts(capsys, monkeypatch) -> None:
    top = _help(capsys, monkeypatch)
    assert "(self-similar loading)" not in top and "history" in top and "--version" in top
    for command in ("solve", "sweep"):
        text = _help(capsys, monkeypatch, command)
        for method in api.METHODS:
            assert f"'{method}'" in text, (command, method)
        assert "missing parent folders are created" in text
    assert "missing parent folders are created" in _help(capsys, monkeypatch, "history")


def test_one_iteration_is_singular() -> None:
    assert "(residual 6.3e-15, 1 iteration)" in cli.format_summary(_solution(iterations=1))
    assert "2 iterations)" in cli.format_summary(_solution(iterations=2))
    assert "(1 iteration, residual" in repr(_solution(iterations=1))


# ----------------------------------------------------------------------------- --output
def _unwritable(tmp_path: Path) -> Path | None:
    """A folder nobody may write to (chmod when not root; /sys is read-only to root too)."""
    if os.geteuid() != 0:
        folder = tmp_path / "locked"
        folder.mkdir()
        folder.chmod(0o500)
        return folder
    probe = Path("/sys/contactlib-probe.nc")
    try:
        probe.open("w").close()
    except OSError:
        return Path("/sys")
    probe.unlink()
    return None


def bad_outputs(tmp_path: Path) -> dict[str, Path]:
    (tmp_path / "a-file").write_text("x")
    out = {
        "through a file": tmp_path / "a-file" / "x.nc",
        "through a file, deeper": tmp_path / "a-file" / "sub" / "x.nc",
        "name too long": tmp_path / ("n" * 250 + ".nc"),  # fine alone; its temporary is not
        "folder name too long": tmp_path / ("d" * 300) / "x.nc",
        "a folder": tmp_path,
    }
    locked = _unwritable(tmp_path)
    if locked is not None:
        out["unwritable"] = locked / "x.nc"
    return out


@pytest.mark.parametrize("command", ["solve", "sweep", "history"])
def test_output_is_checked_before_any_computing(capsys, tmp_path, fake, command) -> None:
    argv = {"solve": ["solve", *GOOD, "--stick-ratio", "0.5"],
            "sweep": ["sweep", *GOOD], "history": HISTORY}[command]
    for case, path in bad_outputs(tmp_path).items():
        before = sorted(os.listdir(tmp_path))
        code, out, err = run(capsys, *argv, "--output", str(path))
        assert_refused(code, err, "--output")
        assert ".tmp" not in err and len(err) < 300, (case, err)
        assert fake.api.calls == [] and fake.history.calls == [], case
        assert sorted(os.listdir(tmp_path)) == before, case


def test_output_folders_are_created_and_removed_again_on_failure(capsys, tmp_path, fake):
    target = tmp_path / "new" / "deeper" / "o.nc"
    code, _, err = run(capsys, "solve", *GOOD, "--friction", "1000", "--output", str(target))
    assert code == 2 and "too large" in err  # refused by the library, after the check
    assert os.listdir(tmp_path) == []  # the probe's folders are gone
    code, out, _ = run(capsys, "solve", *GOOD, "--friction", "0.2", "--output", str(target))
    assert code == 0 and target.is_file() and os.listdir(target.parent) == ["o.nc"]


def test_check_writable_leaves_nothing(tmp_path) -> None:
    assert io.check_writable(tmp_path / "a" / "b" / "c.nc") == tmp_path / "a" / "b" / "c.nc"
    assert os.listdir(tmp_path) == []
    for path in bad_outputs(tmp_path).values():
        with pytest.raises(OSError) as err:
            io.check_writable(path)
        assert str(path)[:40] in str(err.value) and ".tmp" not in str(err.value)


# ----------------------------------------------------------------------------- short repr
def test_solution_repr_is_short_and_shows_the_key_numbers() -> None:
    sol = _solution()
    text = repr(sol)
    assert str(sol) == text and len(text.splitlines()) <= 12 and len(text) < 800, text
    for shown in ("stick_ratio: 0.5", "friction_coefficient: 0.152481", "load_ratio: 1.02738",
                  "frictional_work: 0.00100515", "(201,)", "method = default"):
        assert shown in text, shown
    assert "0.005" not in text  # no array contents (xi[1] = 0.005)


def test_solution_repr_carries_the_error_estimates() -> None:
    # every answer carries its error: printing a solve shows k with its estimate and
    # whether it is resolved (the estimate itself is tested in test_error_estimate.py)
    sol = contactlib.solve("sphere", 0.3, stick_ratio=0.5, n=64)
    text = repr(sol)
    assert len(text.splitlines()) <= 12, text
    assert f"friction_coefficient: {sol.friction_coefficient:.6g} (estimated relative error " \
        f"{sol.error_estimate:.1e})" in text, text
    assert f"resolved: {sol.resolved} (max_error 0.001)" in text, text


def test_history_repr_is_short() -> None:
    res = contactlib.history("sphere", 0.3, 0.2, [0, 1, 0], 3, n=16)
    text = repr(res)
    assert len(text.splitlines()) <= 14 and len(text) < 1200, text
    assert "0 -> 1 -> 0" in text and f"({res.load_ratio.size}, 16)" in text
    assert f"{float(res.frictional_work[-1]):.6g}" in text


def test_history_repr_carries_the_work_error_estimate() -> None:
    res = contactlib.history("sphere", 0.3, 0.2, [0, 1, 0], 10, n=32)
    assert (f"frictional_work: at the end (cumulative): {res.frictional_work[-1]:.6g} "
            f"(estimated relative error {res.work_error_estimate[-1]:.1e})") in repr(res)


def test_internal_results_and_scenes_have_a_short_repr() -> None:
    scene = parse_scene("s", {"geometry": "sphere", "nu": 0.3, "n": 4096,
                              "stick_ratios": "all", "outputs": ["k_curve"]})
    assert len(repr(scene)) < 800 and "4095 values" in repr(scene)
    geom = scene.geometry_object
    d = stages.solve_one(geom, "paper", 16, 0.5, None, None)
    assert len(repr(d)) < 800 and "(16,)" in repr(d)
    assert "Mesh" in short_repr(d) and "array(" not in repr(d)


# ----------------------------------------------------------------------------- library checks
@pytest.fixture
def no_solving(monkeypatch):
    def boom(*args, **kwargs):
        raise AssertionError("a case was solved before the input was checked")

    monkeypatch.setattr(stages, "iter_cases", boom)
    monkeypatch.setattr(stages, "solve_cases", boom)


@pytest.mark.parametrize("ratios, shown", [([0.5, 0.2, 0.5], "0.5"),
                                           ([0.25, np.float64(0.25)], "0.25"),
                                           ([1, 1.0], "1")])
def test_sweep_refuses_duplicate_stick_ratios(no_solving, ratios, shown) -> None:
    with pytest.raises(ValueError, match=f"stick_ratios must not repeat a value: .*{shown}"):
        contactlib.sweep("sphere", 0.3, ratios, n=16)


def test_scenes_refuse_duplicate_stick_ratios() -> None:
    raw = {"geometry": "sphere", "nu": 0.3, "n": 32, "stick_ratios": [0.1, 0.3, 0.1]}
    with pytest.raises(ValueError, match=r"^scenes\.s\.stick_ratios: .*repeat.*0\.1"):
        parse_scene("s", raw)
    schema = yaml.safe_load((REPO / "workflow/schemas/config.schema.yaml").read_text())
    errors = list(jsonschema.Draft202012Validator(schema).iter_errors({"scenes": {"s": raw}}))
    assert [list(e.absolute_path) for e in errors] == [["scenes", "s", "stick_ratios"]]


def test_cli_names_the_duplicate(capsys, tmp_path, fake) -> None:
    code, _, err = run(capsys, "sweep", *GOOD, "--stick-ratios", "0.1,0.5,0.50",
                       "--output", str(tmp_path / "s.nc"))
    assert_refused(code, err, "--stick-ratios")
    assert "'0.50' at position 2 repeats '0.5' at position 1" in err


@pytest.mark.parametrize("kwargs, message", [
    (dict(progress=5), "progress must be callable or None, got 5"),
    (dict(progress="yes"), "progress must be callable"),
    (dict(energy="no"), "energy must be True or False, got 'no'"),
    (dict(energy=0), "energy must be True or False, got 0"),
    (dict(energy=None), "energy must be True or False"),
])
def test_sweep_checks_progress_and_energy_before_solving(no_solving, kwargs, message) -> None:
    with pytest.raises(ValueError, match=message):
        contactlib.sweep("sphere", 0.3, [0.2, 0.5], n=16, **kwargs)


def test_solve_refuses_a_truthy_energy(no_solving) -> None:
    with pytest.raises(ValueError, match="energy must be True or False, got 'no'"):
        contactlib.solve("sphere", 0.3, stick_ratio=0.5, n=16, energy="no")


@pytest.mark.parametrize("kwargs, message", [
    (dict(friction=-1), "friction must be >= 0, got -1"),
    (dict(stick_ratio=0.5, slab_ratio=-0.5), "slab_ratio must be >= 0, got -0.5"),
    (dict(stick_ratio=1.5), "stick_ratio must be in [0, 1], got 1.5"),
    (dict(stick_ratio=0.5, nu=0.7), "nu must be in (-1, 0.5], got 0.7"),
])
def test_range_messages_read_well(no_solving, kwargs, message) -> None:
    kwargs = {"nu": 0.3, **kwargs}
    with pytest.raises(ValueError) as err:
        contactlib.solve("cylinder", n=16, **kwargs)
    assert str(err.value) == message
    assert "None" not in str(err.value) and ".0," not in str(err.value)


# ----------------------------------------------------------------------------- config errors
def test_parse_scenes_reports_every_problem_at_once() -> None:
    scenes = {
        "a": {"geometry": "cone", "nu": 0.7, "stick_ratios": [0.2], "colour": 1},
        "b": {"geometry": "sphere", "nu": 0.3, "n": 32, "stick_ratios": [0.5, 0.5]},
        "h": {"kind": "history", "geometry": "sphere", "nu": 0.3, "friction": -1,
              "load_path": [0, 1], "steps": 0},
        "ok": {"geometry": "sphere", "nu": 0.3, "n": 32, "stick_ratios": [0.5]},
    }
    with pytest.raises(ConfigError) as err:
        parse_scenes(scenes)
    where = [line.split(":", 1)[0] for line in err.value.problems]
    assert where == ["scenes.a.colour", "scenes.a.geometry", "scenes.a.nu",
                     "scenes.b.stick_ratios", "scenes.h.friction", "scenes.h.steps"], where
    assert str(err.value).count("\n") == len(where) - 1


@needs_snakemake
@pytest.mark.workflow
@pytest.mark.slow  # fast tier: test_parse_scenes_reports_every_problem_at_once
def test_workflow_reports_scene_and_figure_problems_in_one_pass(tmp_path) -> None:
    config = {
        "scenes": {
            "cycle": {"kind": "history", "geometry": "sphere", "nu": 0.3, "friction": 0.2,
                      "load_path": [0, 1, 0], "steps": 0},
            "curve": {"geometry": "sphere", "nu": 0.3, "n": 8, "stick_ratios": [0.5]},
        },
        "figures": {"history_loop": ["cylce"], "fig2": ["curve", "curves"]},
    }
    code, text = dry_run(make_workdir(tmp_path, config, folders=("workflow",)))
    assert code != 0
    for where in ("scenes.cycle.steps:",
                  "scenes.curve.n: n must be at least 16",
                  "figures.history_loop: no scene named 'cylce'",
                  "figures.fig2: no scene named 'curves'"):
        assert where in text, (where, text)
    assert text.count("invalid configuration") == 1
    assert not (tmp_path / "results").exists()


@needs_snakemake
@pytest.mark.workflow
@pytest.mark.slow  # fast tier: test_check_yaml
def test_workflow_yaml_syntax_error_names_file_and_line(tmp_path) -> None:
    text = "scenes:\n  a:\n    geometry: sphere\n    nu: 0.3\n   n: [32\n"
    code, out = dry_run(make_workdir(tmp_path, text, folders=("workflow",)))
    assert code != 0 and "config/config.yaml, line 5, column 4: YAML syntax error" in out, out


def test_check_yaml(tmp_path) -> None:
    path = tmp_path / "c.yaml"
    path.write_text("a: 1\nb:\n\t- 2\n")
    with pytest.raises(ValueError, match=r"c\.yaml, line 3, column 1: YAML syntax error"):
        io.check_yaml(path)
    path.write_text("a: [1, 2\n")
    with pytest.raises(ValueError, match=r"c\.yaml, line 2, column 1: YAML syntax error"):
        io.check_yaml(path)
    path.write_text("a: [1, 2]\n")
    assert io.check_yaml(path) == {"a": [1, 2]}
    assert io.check_yaml(tmp_path / "missing.yaml") is None


# ----------------------------------------------------------------------------- damaged files
def _assert_named(err: pytest.ExceptionInfo, path: Path) -> None:
    text = str(err.value)
    assert text.startswith(f"{path} is damaged or incomplete") and "delete it" in text, text
    assert "\n" not in text and "snakemake" in text


def test_truncated_or_corrupt_npz_is_named_with_the_fix(tmp_path) -> None:
    good = io.write_arrays({"a": np.arange(500.0), "b": np.eye(4)}, tmp_path / "good.npz")
    raw = good.read_bytes()
    bad = tmp_path / "bad.npz"
    for cut in (0, 10, len(raw) // 3, len(raw) // 2, len(raw) - 30, len(raw) - 1):
        bad.write_bytes(raw[:cut])
        with pytest.raises(io.DamagedFileError) as err:
            io.read_arrays(bad)
        _assert_named(err, bad)
    flipped = bytearray(raw)
    flipped[len(raw) // 4] ^= 0xFF  # inside the data of 'a': the zip CRC catches it
    bad.write_bytes(bytes(flipped))
    with pytest.raises(io.DamagedFileError):
        io.read_arrays(bad)
    np.testing.assert_array_equal(io.read_arrays(good)["a"], np.arange(500.0))
    with pytest.raises(FileNotFoundError):
        io.read_arrays(tmp_path / "missing.npz")


def test_truncated_dataset_is_named_with_the_fix(tmp_path) -> None:
    good = io.write_dataset(io.to_dataset([_solution(), _solution()]), tmp_path / "good.nc")
    raw = good.read_bytes()
    bad = tmp_path / "bad.nc"
    for cut in (0, 100, len(raw) // 2, len(raw) - 1):
        bad.write_bytes(raw[:cut])
        with pytest.raises(io.DamagedFileError) as err:
            io.read_dataset(bad)
        _assert_named(err, bad)
    assert float(io.read_dataset(good)["friction_coefficient"][0]) == 0.152481
    with pytest.raises(FileNotFoundError):
        io.read_dataset(tmp_path / "missing.nc")


# ----------------------------------------------------------------------------- check-config
def test_check_config_names_file_and_line_of_a_yaml_syntax_error(tmp_path, capsys) -> None:
    """Snakemake reads a --configfile before the workflow starts and its message names
    neither file nor line; `contactlib check-config` does."""
    bad = tmp_path / "my.yaml"
    bad.write_text("scenes:\n  a: {geometry: sphere\n  b: 1\n")
    code, out, err = run(capsys, "check-config", str(bad))
    assert code == 2 and out == ""
    assert err.strip() == (f"contactlib: error: {bad}, line 3, column 4: YAML syntax error: "
                           "expected ',' or '}', but got ':'")


def test_check_config_merges_like_snakemake_and_reports_every_scene_problem(tmp_path,
                                                                           capsys) -> None:
    base = REPO / "config" / "config.yaml"
    over = tmp_path / "over.yaml"
    over.write_text("scenes:\n  sphere-default: {n: 128}\n")  # merged key by key
    code, out, err = run(capsys, "check-config", str(base), str(over))
    assert (code, err) == (0, "") and "no problems found" in out
    code, out, err = run(capsys, "check-config", str(over))  # alone it lacks keys
    assert code == 2 and "scenes.sphere-default.geometry: is required" in err
    bad = tmp_path / "bad.yaml"
    bad.write_text("scenes:\n  a: {geometry: sphere, nu: 0.7, stick_ratios: [0.5]}\n"
                   "  b: {kind: history, geometry: sphere, nu: 0.3, friction: 0.2}\n")
    code, out, err = run(capsys, "check-config", str(bad), str(tmp_path / "none.yaml"))
    lines = err.strip().splitlines()
    assert code == 2 and len(lines) == 1 and lines[0].endswith("none.yaml: no such file")
    code, out, err = run(capsys, "check-config", str(bad))
    assert code == 2
    for where in ("scenes.a.nu: nu must be in (-1, 0.5], got 0.7",
                  "scenes.b.load_path: is required"):  # (steps default to 200)
        assert where in err, (where, err)


def test_a_closed_pipe_on_stdout_stops_quietly_and_keeps_the_file(tmp_path) -> None:
    # `contactlib solve ... | head -1`: the file is written before the summary, and the
    # broken pipe ends the command without a message (status 141, as for SIGPIPE)
    import subprocess
    import sys

    out = tmp_path / "x.nc"
    cmd = (f"{sys.executable} -m contactlib solve --geometry sphere --nu 0.3 --stick-ratio 0.5"
           f" --n 32 --output {out} | head -c 1 > /dev/null; echo ${{PIPESTATUS[0]}} >&2")
    run = subprocess.run(["bash", "-c", cmd], capture_output=True, text=True, timeout=120)
    assert run.stderr.strip() in ("0", "141"), run.stderr  # 0 if it all fitted the pipe
    assert out.exists() and out.stat().st_size > 0


def test_history_table_shows_the_work_error_estimate() -> None:
    res = contactlib.history("sphere", 0.3, 0.2, [0, 1, 0], 10, n=32)
    text = cli.format_history(res)
    assert "V error" in text.splitlines()[1]
    top = res.segment_end(1)
    assert f"{res.work_error_estimate[top]:8.1e}" in text.splitlines()[2]
    bare = contactlib.history("sphere", 0.3, 0.2, [0, 1, 0], 10, n=32, error_estimate=False)
    assert "V error" not in cli.format_history(bare)  # no estimate, no column


# ----------------------------------------------------------------------------- what is read
def test_displacement_profile_is_computed_when_read(monkeypatch) -> None:
    """A sweep asking for k pays no kernel work for u(xi) (the costliest profile) until the
    caller reads it; then it is the same numbers as the record's profile, computed once."""
    calls = []
    real = stages.profiles

    def counting(*args, **kwargs):
        if kwargs.get("displacements", True):
            calls.append(1)
        return real(*args, **kwargs)

    monkeypatch.setattr(stages, "profiles", counting)
    sols = contactlib.sweep("sphere", 0.3, [0.3, 0.6], n=32)
    assert not calls and sols[0].pressure is not None and sols[0].friction_coefficient > 0
    u = sols[1].tangential_displacement
    assert len(calls) == 1 and sols[1].tangential_displacement is u  # once, then kept
    model = contact("sphere", 0.3)
    rec = stages.solve_cases(model, "default", 32, [0.3, 0.6])[1]  # as the sweep solved it
    assert np.array_equal(u, real(model, rec, sols[1].xi)["tangential_displacement"])
    import pickle
    back = pickle.loads(pickle.dumps(sols[0]))  # a solution not yet read pickles too
    assert np.array_equal(back.tangential_displacement, sols[0].tangential_displacement)


def test_repr_shows_poisson_ratio_as_given():
    """nu = 0.4999999 is not shown as 0.5 (six significant digits did): the first line of a
    solution's repr gives nu to ten digits, 0.3 still as 0.3."""
    import contactlib

    for nu, shown in ((0.4999999, "nu = 0.4999999,"), (0.3, "nu = 0.3,")):
        head = repr(contactlib.solve("sphere", nu, stick_ratio=0.5, n=64)).splitlines()[0]
        assert shown in head, head
