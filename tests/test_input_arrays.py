"""0-d numpy arrays and numpy booleans wherever a Python number or bool is accepted, in every
entry point (solve, sweep, history), and degenerate load paths refused in one line (issue 42,
item 9). ``tests/test_input_numpy.py`` has the first cases (nu, n, energy; a flat path)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import contactlib
from contactlib import validate
from contactlib.cli import main


def test_a_0d_infinite_friction_and_indenter_modulus_are_full_adhesion_and_rigid():
    """inf is allowed for friction and indenter_modulus: as a 0-d array too (it was refused
    as 'must be finite')."""
    assert validate.friction(np.array(np.inf)) == math.inf
    assert validate.indenter_modulus(np.array(np.inf)) == math.inf
    assert validate.friction(np.array(0.25)) == 0.25
    sol = contactlib.solve("sphere", 0.3, friction=np.array(np.inf), n=32, energy=False,
                           indenter_modulus=np.array(np.inf))
    assert sol.stick_ratio == 1.0


def test_sweep_takes_numpy_arguments():
    plain = contactlib.sweep("sphere", 0.3, [0.25, 0.5], n=32, energy=False)
    given = contactlib.sweep("sphere", np.array(0.3), np.array([0.25, 0.5]), n=np.int64(32),
                             energy=np.bool_(False), max_error=np.array(1e-3),
                             slab_ratio=np.array(0.0))
    assert [s.friction_coefficient for s in given] == [s.friction_coefficient for s in plain]


def test_history_takes_numpy_arguments():
    kwargs = dict(n=40, error_estimate=False, max_error=0.01)
    plain = contactlib.history("sphere", 0.3, 0.2, [0, 1], 4, **kwargs)
    given = contactlib.history("sphere", np.array(0.3), np.array(0.2),
                               np.array([0.0, 1.0]), np.array(4), n=np.array(40),
                               error_estimate=np.bool_(False), max_error=np.array(0.01))
    assert np.array_equal(given.stick_ratio, plain.stick_ratio, equal_nan=True)
    assert validate.duration(np.array(2.0), 2, True) == (1.0, 1.0)
    assert validate.relaxation([[np.array(0.5), np.array(2.0)]]) == ((0.5, 2.0),)


@pytest.mark.parametrize("name, value", [
    ("friction", np.array([0.1, 0.2])), ("friction", np.array("0.2")),
    ("friction", np.bool_(True)), ("friction", np.array(True)), ("friction", np.array(np.nan)),
    ("steps", np.array(2.5)), ("steps", np.array([4])), ("error_estimate", np.array(1)),
    ("error_estimate", np.array([True])), ("load_path", np.array(1.0)),
    ("duration", np.array([1.0, 2.0, 3.0])), ("relaxation", np.array(0.5)),
])
def test_history_still_refuses_what_is_not_a_scalar_of_the_right_kind(name, value):
    kwargs = dict(geometry="sphere", nu=0.3, friction=0.2, load_path=[0, 1], steps=4, n=40)
    if name in ("duration", "relaxation"):
        kwargs.update(relaxation=[[0.5, 1.0]], duration=1.0)
    kwargs[name] = value
    with pytest.raises(validate.InputError) as err:
        contactlib.history(**kwargs)
    assert err.value.name == name and str(err.value).startswith(name)
    assert "\n" not in str(err.value)


@pytest.mark.parametrize("path, says", [
    ([0], "needs at least two levels"), ([0.5], "needs at least two levels"),
    ([0, -0.5], "must be in [0, 1], got -0.5"), ([0, -1, 1], "must be in [0, 1], got -1"),
    ([0.5, 1], "must start at 0"), ([0, 1.5], "must be in [0, 1], got 1.5"),
    ([0, 0, 0], "never rises above 0"), (np.zeros(3), "got [0.0, 0.0, 0.0]"),
    ([], "must not be empty"), (np.array(0.0), "load_path must be a sequence"),
])
def test_degenerate_load_paths_are_refused_naming_the_bad_value(path, says):
    with pytest.raises(validate.InputError) as err:
        contactlib.history("sphere", 0.3, 0.2, path, 4, n=40)
    assert err.value.name == "load_path" and says in str(err.value)


@pytest.mark.parametrize("text, says", [("0", "at least two levels"),
                                        ("0,-1", "must be in [0, 1]"),
                                        ("0,0,0", "never rises above 0")])
def test_the_cli_refuses_degenerate_load_paths_in_one_line(text, says, tmp_path, capsys):
    out = tmp_path / "x.nc"
    code = main(["history", "--geometry", "sphere", "--nu", "0.3", "--friction", "0.2",
                 "--load-path", text, "--steps", "4", "--output", str(out)])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and not out.exists()
    assert err.startswith("contactlib: error: --load-path") and says in err
