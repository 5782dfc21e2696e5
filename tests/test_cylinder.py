"""Cylinder in plane strain: half-plane and slab through the default method."""

import numpy as np
import pytest

from contactlib import solve
from contactlib.solvers.default_method import solve_default
from contactlib.model.geometry import Geometry
from contactlib.model.theory import hertz_pressure, uncoupled_friction


def test_frictionless_half_plane_is_hertz():
    sol = solve("cylinder", 0.3, stick_ratio=0.0)
    assert np.max(np.abs(sol.pressure - hertz_pressure(sol.xi))) <= 1e-3
    assert abs(sol.load_ratio - 1.0) <= 1e-4


def test_slab_tends_to_half_plane_linearly_in_a_over_h():
    """k(slab) - k(half-plane) = O(a/h): the slab adds a uniform surface strain ~ P/h.

    At a/h = 1e-3 the difference is 0.13 %; it falls tenfold with a/h.
    """
    for c in (0.2, 0.6):
        k_half = solve_default(Geometry("cylinder", 0.3, 0.0), c, 128).k
        d3 = solve_default(Geometry("cylinder", 0.3, 1e-3), c, 128).k / k_half - 1
        d4 = solve_default(Geometry("cylinder", 0.3, 1e-4), c, 128).k / k_half - 1
        assert abs(d4) < 2e-4
        assert abs(d3 / d4 - 10.0) < 0.1


def test_half_plane_uncoupled_limit():
    for c in (0.3, 0.7):
        k = solve_default(Geometry("cylinder", 0.499), c, 128).k
        assert abs(k / uncoupled_friction("cylinder", 0.499, c) - 1) < 1e-3


def test_slab_k_curve_monotonic_and_consistent():
    ks = [solve("cylinder", 0.3, stick_ratio=c, slab_ratio=0.05, n=128, energy=False)
          for c in (0.02, 0.2, 0.5, 0.8, 0.98)]
    k = np.array([s.friction_coefficient for s in ks])
    assert np.all(np.diff(k) > 0)
    assert all(s.consistent and s.converged for s in ks)


@pytest.mark.parametrize("bad", [-1.0, float("nan"), "x"])
def test_bad_slab_ratio(bad):
    with pytest.raises(ValueError, match="slab_ratio"):
        solve("cylinder", 0.3, stick_ratio=0.3, slab_ratio=bad)
