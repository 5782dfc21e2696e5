"""The sphere's stick zone per direction (``stick_radius_directions``) and its map.

Independent truths: Cattaneo–Mindlin's c = (1 - Q/kP)^(1/3) a (equal bodies with nu = 0,
beta = gamma = 0, exact) in every direction; Spence's coupled normal loading (Q = 0,
beta = 0.286, axisymmetric) against the axisymmetric history solver's stick radius; the
mirror symmetry about the x axis of a coupled pair under Q along x; the polar area of the
outline against the area-equivalent stick radius; Hertz's contact radius in every direction.
"""

from __future__ import annotations

import numpy as np
import pytest

from contactlib import fretting, history
from contactlib import io as cio
from contactlib.physical_fretting import physical_fretting
from contactlib.solvers import fretting_sphere as fs

K = 0.3


def _exact_pair(n: int, load, tang, steps: int = 4):
    """Two equal bodies with nu = 0: beta = 0 and gamma = 0 (Cattaneo–Mindlin exact)."""
    return fretting("sphere", 0.0, K, load, tang, steps, n=n, indenter_modulus=1.0,
                    indenter_nu=0.0)


@pytest.fixture(scope="module")
def coupled():
    """A rigid sphere on nu = 0.3 (beta = 0.286): Q/kP 0 -> 0.3 -> 0.6, n = 32."""
    return fretting("sphere", 0.3, K, [0, 1, 1, 1], [0, 0, 0.3, 0.6], 4, n=32)


@pytest.mark.parametrize("n", [32, 64])
def test_cattaneo_mindlin_in_every_direction(n):
    """beta = gamma = 0: every direction's stick radius is (1 - x)^(1/3) a_max within its
    estimate at x = Q/kP = 0.5 and 0.9, the spread over the directions is below a cell,
    the stick zone's centroid is the contact's centre, and every direction's contact
    radius is Hertz's a_max within its estimate."""
    r = _exact_pair(n, [0, 1, 1, 1], [0, 0, 0.5, 0.9])
    assert r.converged.all()
    h = 2.4 / n
    assert r.direction_angles.size == fs.DIRECTIONS
    for i, x in ((2, 0.5), (3, 0.9)):
        j = r.point_step[i]
        c = r.stick_radius_directions[j]
        err = r.stick_radius_directions_error[i]
        assert np.all(np.isfinite(c)) and np.all(np.isfinite(err))
        miss = np.abs(c - (1 - x) ** (1 / 3))
        assert np.all(miss <= err), (n, x, miss.max(), err[np.argmax(miss)])
        assert np.ptp(c) <= h, (n, x, np.ptp(c), h)
        assert np.all(np.abs(r.stick_centre[j]) < 1e-9)
        a = r.contact_radius_directions[j]
        assert np.all(np.abs(a - 1.0) <= r.contact_radius_directions_error[i]), \
            (n, np.abs(a - 1.0).max())
        assert np.all(np.abs(a - 1.0) <= 0.25 * h)  # measured 0.15 h, 0.07 h at n = 32, 64


def test_spence_every_direction_is_the_axisymmetric_radius():
    """Q = 0 with beta = 0.286 (Spence's coupled normal loading, axisymmetric): every
    direction's stick radius is the history solver's c = (c/a) a within the estimates."""
    r = fretting("sphere", 0.3, K, [0, 1], [0, 0], 16, n=32)
    assert r.converged.all() and r.beta == pytest.approx(0.2857, abs=1e-4)
    h = history("sphere", 0.3, K, [0, 1], 40)
    truth = float(h.stick_ratio[-1] * h.contact_radius[-1])
    truth_err = float(h.stick_radius_error_estimate[-1])
    assert abs(truth - 0.8831) <= truth_err  # docs/fretting.md: 0.8831 at 960 rings
    j = r.point_step[-1]
    c = r.stick_radius_directions[j]
    err = r.stick_radius_directions_error[-1]
    miss = np.abs(c - truth)
    assert np.all(miss <= err + truth_err), (miss, err)
    assert np.ptp(c) <= 2.4 / 32


def test_mirror_symmetry_and_area(coupled):
    """beta != 0, Q along x: the outline is its own mirror image about the x axis
    (r(theta) = r(-theta), the centroid on the axis) to round-off, and its polar area's
    radius sqrt(mean r^2) is the area-equivalent stick radius within the estimates."""
    r = coupled
    assert r.converged.all() and r.beta != 0.0
    d = r.direction_angles.size
    mirror = (-np.arange(d)) % d
    for i in (2, 3):
        j = r.point_step[i]
        c = r.stick_radius_directions[j]
        assert np.all(np.isfinite(c))
        assert np.max(np.abs(c - c[mirror])) < 1e-9
        assert abs(r.stick_centre[j, 1]) < 1e-9
        a_area = r.contact_edges[j, 1]
        c_area = r.stick_ratio[j] * a_area
        est = float(np.mean(r.stick_radius_directions_error[i])) \
            + r.stick_ratio_error[i] * a_area
        assert abs(np.sqrt(np.mean(c**2)) - c_area) <= est
    # the stick zone moves against Q (towards -x) as Q grows
    assert r.stick_centre[r.point_step[3], 0] < r.stick_centre[r.point_step[2], 0] < 0


def test_full_slip_and_direction_radii_edges():
    """direction_radii: an empty zone has radius 0; a centre outside the zone gives NaN;
    a disc of cells with a field linear in the distance to its edge is located to a small
    fraction of a cell in every direction."""
    from contactlib.model import contact
    ops = fs.grid_operators(contact("sphere", 0.5), 64)
    angles = np.linspace(0, 2 * np.pi, 16, endpoint=False)
    empty = np.zeros((64, 64), dtype=bool)
    assert np.all(fs.direction_radii(ops, np.zeros((64, 64)), empty, angles)[0] == 0.0)
    xx, yy = np.meshgrid(ops.x, ops.x, indexing="ij")
    rho = np.hypot(xx + 0.1, yy)
    inside = rho < 0.6
    edge, half = fs.direction_radii(ops, np.maximum(0.6 - rho, 0.0), inside, angles,
                                    (-0.1, 0.0))
    assert np.all(np.abs(edge - 0.6) < 0.02 * ops.h)  # exact but for the disc's curvature
    assert np.all(np.abs(half - 0.6) <= ops.h)
    far = fs.direction_radii(ops, np.maximum(0.6 - rho, 0.0), inside, angles, (0.9, 0.0))
    assert np.all(np.isnan(far[0])) and np.all(np.isnan(far[1]))


def test_dataset_and_si_twin():
    """The dataset holds the radii per direction with their units, and the physical door's
    SI twin is the same in metres."""
    e_mod, radius, load = 200e9, 0.01, 100.0
    r = physical_fretting(radius, None, [0, load, load], [0, 0, 0.5 * K * load],
                          (e_mod, 0.0), (e_mod, 0.0), K, geometry="sphere", n=16, steps=4)
    ds = cio.physical_fretting_to_dataset(r)
    var = ds["stick_radius_directions"]
    assert var.dims == ("step", "direction") and var.attrs["units"] == "1"
    assert ds["direction"].attrs["units"] == "radian"
    assert ds["stick_radius_directions_error_estimate"].dims == ("point", "direction")
    assert ds["stick_centre"].dims == ("step", "component")
    si = ds["stick_radius_directions_si"]
    assert si.attrs["units"] == "m"
    np.testing.assert_allclose(si.values, var.values * r.a_max, rtol=1e-15)
    np.testing.assert_allclose(ds["contact_radius_directions_si"].values,
                               ds["contact_radius_directions"].values * r.a_max, rtol=1e-15)
    cyl = fretting("cylinder", 0.5, K, [0, 1, 1], [0, 0, 0.5], 4, n=16,
                   error_estimate=False)
    assert cyl.stick_radius_directions is None
    assert "direction" not in cio.fretting_to_dataset(cyl).dims


def test_figure_draws_one_outline_per_step(coupled):
    """The map draws one stick outline (and one Cattaneo–Mindlin circle) per step asked,
    one contact outline per panel, with equal aspect; a dataset without the radii is
    refused."""
    from contactlib.plot.fretting import fig_stick_zone_map
    ds = cio.fretting_to_dataset(coupled)
    steps = [int(j) for j in coupled.point_step[2:]]
    fig = fig_stick_zone_map([ds, ds], steps=steps)
    for ax in fig.axes[:2]:
        gids = [line.get_gid() for line in ax.get_lines()]
        assert gids.count("stick-outline") == len(steps)
        assert gids.count("cattaneo-mindlin") == len(steps)
        assert gids.count("contact-outline") == 1
        assert ax.get_aspect() == 1.0
    fig = fig_stick_zone_map(ds)  # default: the path points with Q != 0
    assert [line.get_gid() for line in fig.axes[0].get_lines()].count("stick-outline") == 2
    with pytest.raises(ValueError, match="stick_radius_directions"):
        fig_stick_zone_map(ds.drop_vars("stick_radius_directions"))
