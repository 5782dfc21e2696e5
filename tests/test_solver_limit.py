"""A solver limit (valid input the self-similar solver cannot answer): its own exception
(contactlib.validate.SolverLimit, a ValueError), its own exit status (3, bad input keeps
2) and the commands that answer the case, with the arguments filled in (issue 35)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

import contactlib
from contactlib import api, cli, validate

ROOT = Path(__file__).resolve().parents[1]


def test_solver_limit_is_a_value_error_apart_from_bad_input() -> None:
    exc = validate.SolverLimit("why", [("solve", {"stick_ratio": 1.0})])
    assert isinstance(exc, ValueError) and not isinstance(exc, validate.InputError)
    assert str(exc) == "why" and exc.remedies == [("solve", {"stick_ratio": 1.0})]
    assert cli.EXIT_SOLVER_LIMIT == 3 and cli.EXIT_BAD_INPUT == 2


def test_friction_beyond_the_largest_stick_zone_library() -> None:
    """The library raises the limit (still a ValueError for the API's contract)."""
    with pytest.raises(validate.SolverLimit, match="is too large") as info:
        contactlib.solve("sphere", 0.49, friction=50.0, n=32)
    assert info.value.remedies == [("solve", {"stick_ratio": 1.0})]


def test_friction_beyond_the_largest_stick_zone_cli(capsys) -> None:
    argv = ["solve", "--geometry", "sphere", "--nu", "0.49", "--friction", "50", "--n", "32"]
    assert cli.main(argv) == 3
    out, err = capsys.readouterr()
    lines = err.splitlines()
    assert out == "" and len(lines) == 2
    assert lines[0].startswith("contactlib: error: friction 50.0 is too large: the stick zone "
                               "covers more than 0.99999 of the contact")
    assert lines[1] == ("contactlib: answer it with: contactlib solve --geometry sphere "
                        "--nu 0.49 --n 32 --stick-ratio 1")
    # the command named answers the case
    assert cli.main(lines[1].split()[5:]) == 0
    assert "c/a    = 1\n" in capsys.readouterr().out


def test_bad_input_keeps_status_2(capsys) -> None:
    assert cli.main(["solve", "--geometry", "sphere", "--nu", "0.7", "--friction", "50"]) == 2
    assert "answer it with" not in capsys.readouterr().err


class _Limited:
    """An API whose solve meets a solver limit with the given remedies."""

    def __init__(self, remedies):
        self.remedies = remedies

    def solve(self, *args, **kwargs):
        raise validate.SolverLimit("friction 0.5: the contact is most likely fully stuck",
                                   self.remedies)


def test_remedies_our_own_rules_refuse_are_not_named(capsys, monkeypatch) -> None:
    """A history plans for tolerances 1e-5 ... 1e-2 only: a solve asked for 1e-7 is not
    sent there; solve --stick-ratio 1 is. At 1e-3 the history is named, with the
    tolerance and without steps (the plan picks them)."""
    monkeypatch.setattr(cli, "_api", lambda: _Limited([
        ("solve", {"stick_ratio": 1.0}),
        ("history", {"friction": 0.5, "load_path": [0.0, 1.0]})]))
    argv = ["solve", "--geometry", "sphere", "--nu", "0.3", "--friction", "0.5", "--base",
            "bonded", "--slab-ratio", "2", "--output", "out.nc", "--tolerance"]
    assert cli.main(argv + ["1e-7"]) == 3
    lines = capsys.readouterr().err.splitlines()
    assert lines == [
        "contactlib: error: friction 0.5: the contact is most likely fully stuck",
        "contactlib: answer it with: contactlib solve --geometry sphere --nu 0.3 --base "
        "bonded --slab-ratio 2 --tolerance 1e-7 --stick-ratio 1 "
        "--output out.nc"]
    assert cli.main(argv + ["1e-3"]) == 3
    lines = capsys.readouterr().err.splitlines()
    assert lines[2] == ("contactlib: answer it with: contactlib history --geometry sphere "
                        "--nu 0.3 --base bonded --slab-ratio 2 --tolerance 1e-3 --friction "
                        "0.5 --load-path 0,1 --output history.nc")
    assert len(lines) == 3


def test_physical_remedy_is_a_path_in_newtons(capsys, monkeypatch) -> None:
    monkeypatch.setattr(api, "solve", _Limited([
        ("history", {"friction": 0.5, "load_path": [0.0, 1.0]})]).solve)
    argv = ["solve", "--geometry", "sphere", "--radius", "10mm", "--load", "100",
            "--body", "steel", "--friction", "0.5"]
    assert cli.main(argv) == 3
    lines = capsys.readouterr().err.splitlines()
    assert lines[1] == ("contactlib: answer it with: contactlib history --geometry sphere "
                        "--radius 10mm --body steel --friction 0.5 --load-path 0N,100N "
                        "--output history.nc")


@pytest.mark.slow
def test_issue_case_full_stick_on_a_bonded_layer() -> None:
    """The case of issue 35 (about 12 s): exit 3, the reason, and both commands."""
    argv = ["solve", "--geometry", "sphere", "--nu", "0.49", "--friction", "0.5",
            "--slab-ratio", "2", "--base", "bonded"]
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    run = subprocess.run([sys.executable, "-m", "contactlib", *argv], capture_output=True,
                         text=True, cwd=ROOT, env=env)
    assert run.returncode == 3 and run.stdout == ""
    lines = run.stderr.splitlines()
    assert lines[0].startswith("contactlib: error: friction 0.5: no converged stick ratio "
                               "found; the solutions end at c/a = 0.94")
    assert "most likely holds the whole contact stuck" in lines[0]
    assert lines[1:] == [
        "contactlib: answer it with: contactlib solve --geometry sphere --nu 0.49 "
        "--slab-ratio 2 --base bonded --stick-ratio 1",
        "contactlib: answer it with: contactlib history --geometry sphere --nu 0.49 "
        "--slab-ratio 2 --base bonded --friction 0.5 --load-path 0,1 --steps 200 "
        "--output history.nc"]


# ----------------------------------------------------------------------------------------
# no relative error for a value that is zero at its scale


def _error_column(text: str) -> list[str]:
    rows = [line for line in text.splitlines() if line[:7].strip().isdigit()]
    return [line[-8:].strip() for line in rows]


def test_history_summary_prints_no_relative_error_of_zero_work() -> None:
    """Full stick (k = inf): V = 0 at every row, so no V error but '(zero)'; with slip the
    relative errors are printed and (zero) is not explained."""
    stuck = contactlib.history("sphere", 0.3, friction=float("inf"), load_path=[0, 1, 0],
                               steps=8, n=32)
    assert float(abs(stuck.frictional_work).max()) == 0.0
    text = cli.format_history(stuck)
    assert _error_column(text) == ["(zero)", "(zero)"]
    assert "(zero): V total is zero at its scale" in text
    slips = contactlib.history("sphere", 0.3, friction=0.2, load_path=[0, 1, 0], steps=8, n=32)
    text = cli.format_history(slips)
    errors = _error_column(text)
    assert len(errors) == 2 and all(float(e) > 0 for e in errors)
    assert "(zero)" not in text


def test_zero_at_its_scale_is_below_the_work_floor() -> None:
    from contactlib.history_api import WORK_FLOOR

    assert cli._relative_text(8.3, 0.5 * WORK_FLOOR, WORK_FLOOR) == "  (zero)"
    assert cli._relative_text(8.3, 2.0 * WORK_FLOOR, WORK_FLOOR) == " 8.3e+00"


def test_physical_summary_prints_no_relative_error_of_a_zero() -> None:
    from contactlib.physical import physical_solve

    res = physical_solve("sphere", 0.01, 100.0, "rigid", "steel", friction=0.0, n=64)
    lines = {line.split("  ")[1]: line for line in res.summary().splitlines()
             if line.startswith("  ") and "  " in line[2:]}
    assert "relative error" not in lines["stick radius c"]
    assert "relative error" not in lines["frictional energy"]
    assert "relative error" in lines["contact radius a"]


def test_repr_prints_no_relative_error_of_a_zero() -> None:
    stuck = contactlib.solve("sphere", 0.3, stick_ratio=1.0, n=32)
    lines = {line.split(":")[0].strip(): line for line in repr(stuck).splitlines()}
    assert stuck.frictional_work == 0.0
    assert lines["frictional_work"].endswith("frictional_work: 0")
    assert "relative error" in lines["load_ratio"]


def test_remedies_keep_the_options_their_command_takes(capsys, monkeypatch) -> None:
    """The indenter's profile goes along to each command that takes it (history takes
    --profile since issue 36); solve-only options (--method) do not go to history, nor
    --n (another meaning there)."""
    monkeypatch.setattr(cli, "_api", lambda: _Limited([
        ("solve", {"stick_ratio": 1.0}),
        ("history", {"friction": 0.5, "load_path": [0.0, 1.0]})]))
    argv = ["solve", "--geometry", "sphere", "--nu", "0.3", "--friction", "0.5",
            "--profile", "cone", "--method", "default", "--n", "64"]
    assert cli.main(argv) == 3
    lines = capsys.readouterr().err.splitlines()
    assert lines[1] == ("contactlib: answer it with: contactlib solve --geometry sphere --nu "
                        "0.3 --profile cone --method default --n 64 --stick-ratio 1")
    cone = " --profile cone" if "--profile" in cli._taken("history") else ""
    assert lines[2] == ("contactlib: answer it with: contactlib history --geometry sphere "
                        f"--nu 0.3{cone} --friction 0.5 --load-path 0,1 --steps 200 "
                        "--output history.nc")


def test_a_layer_radius_without_a_solution_is_a_solver_limit() -> None:
    """Physical input on a layer: no converged solution at the a/h tried is a solver limit
    (status 3), not bad input."""
    from types import SimpleNamespace

    from contactlib.physical import _layer_radius

    prob = SimpleNamespace(geometry="sphere", base="smooth", thickness=1e-3)
    with pytest.raises(validate.SolverLimit, match="no converged solution at a/h = 0.1 "
                                                   r"\(Newton failed\)"):
        _layer_radius(prob, 1e-4, lambda s: (SimpleNamespace(message="Newton failed"),
                                             float("nan")))
