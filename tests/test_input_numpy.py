"""Numpy scalars, 0-d arrays and numpy booleans are valid inputs; degenerate load paths are not
(issue 42, item 9)."""

from __future__ import annotations

import numpy as np
import pytest

import contactlib
from contactlib import validate


def test_numpy_scalars_and_0d_arrays_are_accepted_as_the_numbers_they_hold():
    plain = contactlib.solve("sphere", 0.3, stick_ratio=0.5, n=32, energy=False)
    given = contactlib.solve("sphere", np.array(0.3), stick_ratio=np.float64(0.5),
                             n=np.array(32), energy=np.bool_(False))
    assert given.friction_coefficient == plain.friction_coefficient
    assert validate.flag("energy", np.array(True)) is True
    assert validate.integer("n", np.int64(64), 1) == 64


@pytest.mark.parametrize("bad", [np.array([0.3, 0.2]), np.array("x"), True, np.bool_(True),
                                 np.array(np.nan), "0.3"])
def test_arrays_strings_bools_and_nan_are_still_refused_as_numbers(bad):
    with pytest.raises(ValueError, match="nu must be"):
        contactlib.solve("sphere", bad, stick_ratio=0.5, n=32)


@pytest.mark.parametrize("bad", ["yes", 1, np.array([True, False])])
def test_a_flag_is_a_boolean(bad):
    with pytest.raises(ValueError, match="energy must be True or False"):
        contactlib.solve("sphere", 0.3, stick_ratio=0.5, n=32, energy=bad)


@pytest.mark.parametrize("path", [[0, 0], [0.0, 0.0, 0.0]])
def test_a_load_path_that_never_rises_is_refused(path):
    with pytest.raises(ValueError, match="never rises above 0"):
        contactlib.history("sphere", 0.3, 0.2, path, 10)


def test_the_cli_refuses_a_flat_load_path_in_one_line(tmp_path, capsys):
    from contactlib.cli import main

    out = tmp_path / "x.nc"
    code = main(["history", "--geometry", "sphere", "--nu", "0.3", "--friction", "0.2",
                 "--load-path", "0,0", "--steps", "10", "--output", str(out)])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "never rises above 0" in err
    assert not out.exists()
