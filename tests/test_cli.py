"""Tests for the command line (contactlib.cli), with a fake library API."""

from __future__ import annotations

import math
import os
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from contactlib import cli, io
from contactlib.result import Solution

GOOD = ["--geometry", "sphere", "--nu", "0.3"]


def _fake_solution(geometry: str, nu: float, stick_ratio: float, *, n: int | None,
                   method: str, slab_ratio: float, energy: bool,
                   max_error: float = 1e-3) -> Solution:
    n = n or 8
    xi = np.linspace(0.0, 1.0, n + 1)
    return Solution(
        geometry=geometry, nu=nu, method=method, n=n, slab_ratio=slab_ratio,
        stick_ratio=stick_ratio,
        friction_coefficient=math.inf if stick_ratio == 1 else 0.4 * stick_ratio,
        xi=xi, pressure=np.sqrt(1 - xi**2), shear=0.1 * xi, tangential_displacement=xi,
        load_ratio=1.0, frictional_work=0.02 if energy else math.nan, iterations=5,
        residual_norm=1e-13, message="fake" if stick_ratio == 1 else "",
        error_estimate=0.0 if stick_ratio == 1 else 2e-5, load_error_estimate=1e-5,
        work_error_estimate=3e-5 if energy else math.nan, resolved=True, max_error=max_error,
    )


class FakeApi:
    """Records calls; behaves like contactlib.api for valid input."""

    def __init__(self) -> None:
        self.calls: list[tuple[str, dict]] = []

    def solve(self, geometry, nu, *, stick_ratio=None, friction=None, n=None,
              method="default", slab_ratio=0.0, energy=True, max_error=1e-3):
        self.calls.append(("solve", dict(geometry=geometry, nu=nu, stick_ratio=stick_ratio,
                                         friction=friction, n=n, method=method,
                                         slab_ratio=slab_ratio, energy=energy,
                                         max_error=max_error)))
        if friction is not None and friction > 100:
            raise ValueError("friction is too large for this fake, got 1000")
        g = stick_ratio if stick_ratio is not None else min(friction, 1.0)
        return _fake_solution(geometry, nu, g, n=n, method=method,
                              slab_ratio=slab_ratio, energy=energy, max_error=max_error)

    def sweep(self, geometry, nu, stick_ratios="all", *, n=None, method="default",
              slab_ratio=0.0, energy=True, progress=None, max_error=1e-3):
        self.calls.append(("sweep", dict(stick_ratios=stick_ratios, n=n, energy=energy,
                                         progress=progress, max_error=max_error)))
        m = n or 8
        ratios = [i / m for i in range(1, m)] if stick_ratios == "all" else stick_ratios
        out = []
        for i, g in enumerate(ratios, 1):
            out.append(_fake_solution(geometry, nu, g, n=n, method=method,
                                      slab_ratio=slab_ratio, energy=energy,
                                      max_error=max_error))
            if progress is not None:
                progress(i, len(ratios))
        return out


@pytest.fixture
def api(monkeypatch) -> FakeApi:
    fake = FakeApi()
    monkeypatch.setattr(cli, "_api", lambda: fake)
    return fake


def run(capsys, *argv: str) -> tuple[int, str, str]:
    code = cli.main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


BAD = [
    (["--nu", "0.7", "--stick-ratio", "0.5"], "--nu", "sphere"),
    (["--nu", "abc", "--stick-ratio", "0.5"], "--nu", "sphere"),
    (["--nu", "nan", "--stick-ratio", "0.5"], "--nu", "sphere"),
    (["--nu", "-1", "--stick-ratio", "0.5"], "--nu", "sphere"),
    (["--nu", "0.3", "--n", "1", "--stick-ratio", "0.5"], "--n", "sphere"),
    (["--nu", "0.3", "--n", "2.5", "--stick-ratio", "0.5"], "--n", "sphere"),
    (["--nu", "0.3", "--n", "ten", "--stick-ratio", "0.5"], "--n", "sphere"),
    (["--nu", "0.3", "--stick-ratio", "1.7"], "--stick-ratio", "sphere"),
    (["--nu", "0.3", "--stick-ratio", "nan"], "--stick-ratio", "sphere"),
    (["--nu", "0.3", "--friction", "-0.1"], "--friction", "sphere"),
    (["--nu", "0.3", "--friction", "nan"], "--friction", "sphere"),
    (["--nu", "0.3", "--stick-ratio", "0.5"], "--geometry", "cone"),
    (["--nu", "0.3", "--stick-ratio", "0.5", "--method", "foo"], "--method", "sphere"),
    (["--nu", "0.3", "--stick-ratio", "0.5", "--friction", "0.2"], "--friction", "sphere"),
    (["--nu", "0.3"], "--stick-ratio", "sphere"),
    (["--nu", "0.3", "--stick-ratio", "0.5", "--slab-ratio", "-1"], "--slab-ratio",
     "cylinder"),
    (["--nu", "0.3", "--stick-ratio", "0.5", "--slab-ratio", "x"], "--slab-ratio",
     "cylinder"),
    (["--nu", "0.3", "--stick-ratio", "0.5", "--slab-ratio", "inf"], "--slab-ratio",
     "cylinder"),
    (["--nu", "0.3", "--stick-ratio", "0.5", "--slab-ratio", "1000.5"], "--slab-ratio",
     "sphere"),  # beyond the sphere's supported range (1000)
    (["--nu", "0.3", "--stick-ratio", "0.5", "--slab-ratio", "501"], "--slab-ratio",
     "cylinder"),  # beyond the smooth-base cylinder's (500)
    (["--nu", "0.3", "--stick-ratio", "0.5", "--slab-ratio", "1", "--base", "glued"],
     "--base", "sphere"),
    (["--stick-ratio", "0.5"], "--nu", "sphere"),
]


@pytest.mark.parametrize("args,option,geometry", BAD,
                         ids=[" ".join(b[0][-2:]) + f" [{b[2]}]" for b in BAD])
def test_solve_bad_input(capsys, tmp_path, api, args, option, geometry) -> None:
    out_file = tmp_path / "out.nc"
    code, out, err = run(capsys, "solve", "--geometry", geometry, *args,
                         "--output", str(out_file))
    assert code == 2
    assert err.count("\n") == 1 and err.startswith("contactlib: error: ")
    assert option in err
    assert "Traceback" not in err
    assert not out_file.exists() and os.listdir(tmp_path) == []
    assert api.calls == []


@pytest.mark.parametrize("ratios", ["0.1,abc", "0.1,,0.2", "1.5", "0.2,0.2", "", "nan"])
def test_sweep_bad_ratios(capsys, tmp_path, api, ratios) -> None:
    code, _, err = run(capsys, "sweep", *GOOD, "--stick-ratios", ratios,
                       "--output", str(tmp_path / "s.nc"))
    assert code == 2 and err.count("\n") == 1 and "--stick-ratios" in err
    assert os.listdir(tmp_path) == [] and api.calls == []


def test_sweep_requires_output(capsys, api) -> None:
    code, _, err = run(capsys, "sweep", *GOOD)
    assert code == 2 and err.count("\n") == 1 and "--output" in err


def test_library_value_error_is_one_line(capsys, tmp_path, api) -> None:
    code, _, err = run(capsys, "solve", *GOOD, "--friction", "1000",
                       "--output", str(tmp_path / "o.nc"))
    assert code == 2 and err == "contactlib: error: friction is too large for this fake, got 1000\n"
    assert os.listdir(tmp_path) == []


@pytest.mark.parametrize("debug", [False, True])
def test_unexpected_error_status_1(capsys, tmp_path, monkeypatch, debug) -> None:
    def broken():
        raise RuntimeError("kaput")

    monkeypatch.setattr(cli, "_api", broken)
    argv = ["solve", *GOOD, "--stick-ratio", "0.5", "--output", str(tmp_path / "o.nc")]
    code, _, err = run(capsys, *argv, *(["--debug"] if debug else []))
    assert code == 1
    assert err.startswith("contactlib: error: RuntimeError: kaput\n")
    assert ("Traceback" in err) == debug
    assert os.listdir(tmp_path) == []


def test_solve_writes_and_summarizes(capsys, tmp_path, api) -> None:
    out_file = tmp_path / "deep" / "one.nc"
    code, out, err = run(capsys, "solve", "--geometry", "cylinder", "--nu", "0.25",
                         "--stick-ratio", "1", "--n", "16", "--slab-ratio", "0.5",
                         "--output", str(out_file))
    assert code == 0 and err == ""
    for text in ("cylinder", "nu = 0.25", "n = 16", "c/a", "k      = inf", "P/P_H",
                 "converged: yes", "message: fake", "wrote"):
        assert text in out, text
    ds = io.read_dataset(out_file)
    assert float(ds["stick_ratio"]) == 1.0 and ds["pressure"].dims == ("xi",)
    assert ds.attrs["slab_ratio"] == 0.5
    assert api.calls[0][1] == dict(geometry="cylinder", nu=0.25, stick_ratio=1.0,
                                   friction=None, n=16, method="default",
                                   slab_ratio=0.5, energy=True, max_error=1e-3)


def test_solve_friction_no_output(capsys, tmp_path, api, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    code, out, _ = run(capsys, "solve", *GOOD, "--friction", "0.2", "--method", "paper",
                       "--no-energy")
    assert code == 0 and "V      = nan" in out
    assert api.calls[0][1]["friction"] == 0.2 and api.calls[0][1]["stick_ratio"] is None
    assert api.calls[0][1]["energy"] is False and api.calls[0][1]["method"] == "paper"
    assert os.listdir(tmp_path) == []


@pytest.mark.parametrize("ratios,expected", [("all", "all"), ("0.1, 0.3,0.5", [0.1, 0.3, 0.5])])
def test_sweep_writes_table(capsys, tmp_path, api, ratios, expected) -> None:
    out_file = tmp_path / "sweep.nc"
    # the paper method: n = 4 is allowed (the default method needs n >= 16)
    code, out, err = run(capsys, "sweep", *GOOD, "--method", "paper", "--n", "4",
                         "--stick-ratios", ratios,
                         "--output", str(out_file))
    assert code == 0
    assert err == ""  # stderr is not a TTY here: no progress
    call = api.calls[0][1]
    assert call["stick_ratios"] == expected and call["progress"] is None
    ds = io.read_dataset(out_file)
    npts = 3
    assert ds.sizes["stick_ratio"] == npts and ds["shear"].dims == ("stick_ratio", "xi")
    assert out.count("\n") >= npts + 2 and "c/a" in out


def test_progress_only_on_tty(capsys) -> None:
    class Tty:
        def __init__(self) -> None:
            self.text = ""

        def isatty(self) -> bool:
            return True

        def write(self, s: str) -> None:
            self.text += s

        def flush(self) -> None:
            pass

    tty = Tty()
    progress = cli._progress_printer(tty)
    assert progress is not None
    progress(1, 3)
    progress(3, 3)
    assert tty.text == "\rsweep: 1/3\rsweep: 3/3"
    assert cli._progress_printer(SimpleNamespace(isatty=lambda: False)) is None


def test_help_exit_zero(capsys) -> None:
    assert cli.main(["--help"]) == 0
    assert "solve" in capsys.readouterr().out


def test_python_m_help() -> None:
    root = str(Path(__file__).resolve().parents[1])
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(
        p for p in (root, os.environ.get("PYTHONPATH", "")) if p)}
    kw = dict(capture_output=True, text=True, timeout=60, cwd=root, env=env)
    proc = subprocess.run([sys.executable, "-m", "contactlib", "--help"], **kw)
    assert proc.returncode == 0 and "sweep" in proc.stdout
    proc = subprocess.run([sys.executable, "-m", "contactlib", "solve", "--geometry",
                           "sphere", "--nu", "abc", "--stick-ratio", "0.5"], **kw)
    assert proc.returncode == 2
    assert proc.stderr == "contactlib: error: --nu must be a number in (-1, 0.5], got 'abc'\n"


class _Terminal:
    """A stream that says it is a terminal and keeps what is written."""

    def __init__(self, tty: bool = True):
        self.tty, self.text = tty, ""

    def isatty(self) -> bool:
        return self.tty

    def write(self, s: str) -> None:
        self.text += s

    def flush(self) -> None:
        pass


def test_ticker_shows_elapsed_time_on_a_terminal_and_clears_it():
    import time

    from contactlib.cli import _ticker

    term = _Terminal()
    with _ticker(term, "solve", after=0.05, every=0.05):
        time.sleep(0.3)
    assert "\rsolve: 0 s" in term.text and term.text.endswith("\r\033[K")
    quiet = _Terminal()
    with _ticker(quiet, "solve", after=5.0):  # a short run shows nothing
        pass
    assert quiet.text == ""
    piped = _Terminal(tty=False)
    with _ticker(piped, "solve", after=0.0, every=0.01):
        time.sleep(0.05)
    assert piped.text == ""  # not a terminal: silent


def test_history_without_output_prints_the_summary_and_writes_nothing(capsys, tmp_path,
                                                                       monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, out, err = run(capsys, "history", "--geometry", "cylinder", "--nu", "0.3",
                         "--friction", "0.2", "--load-path", "0,1,0", "--n", "40")
    assert code == 0, err
    assert "200 steps per segment" in out  # the default steps (validate.HISTORY_DEFAULT_STEPS)
    assert "nothing written" in out and list(tmp_path.iterdir()) == []
