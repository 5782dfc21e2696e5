"""The half-space field of cell-wise constant tractions (contactlib.stresses.grid, issue 38).

Each check is against an independent truth: Love's closed form under a uniformly loaded
rectangle, Cerruti's point force, Huber's axis, the Hankel route of
contactlib.stresses.tangential for the Cattaneo-Mindlin tractions, the force balance on a
plane, the symmetry of a rotation by 90 degrees, and the refinement of a fretting run.
"""

import math

import numpy as np
import pytest

from contactlib import fretting
from contactlib.solvers.fretting_sphere import grid_operators, run_sphere_fretting
from contactlib.history_api import load_levels
from contactlib.model import contact
from contactlib.stresses.grid import (corner_weights, fretting_step_stresses,
                                      fretting_stresses, grid_stresses, lattice_stresses,
                                      stresses_at)
from contactlib.stresses.tangential import (CARTESIAN, cartesian_stresses,
                                            mindlin_deresiewicz_tractions,
                                            mindlin_sphere_stresses)
from contactlib.validate import InputError
from test_stresses_tangential import _cerruti

NU = 0.3


def _love_corner(a, b, z):
    """sigma_zz / p below a corner of an a x b rectangle under a uniform pressure p (Love)."""
    r = math.sqrt(a * a + b * b + z * z)
    return -(math.atan(a * b / (z * r))
             + a * b * z / r * (1 / (a * a + z * z) + 1 / (b * b + z * z))) / (2 * math.pi)


def test_uniform_pressure_on_a_rectangle_is_loves_closed_form():
    h = 0.4
    p = np.ones((2, 1))  # the rectangle [0, 2h] x [0, h]
    for nu in (0.0, 0.3, 0.5):
        z = np.array([0.05, 0.3, 1.0, 3.0])
        corner = grid_stresses(p, None, h, (0.0, 0.0), [0.0], [0.0], z, nu)["sigma_zz"]
        centre = grid_stresses(p, None, h, (0.0, 0.0), [h], [h / 2], z, nu)["sigma_zz"]
        for i, zi in enumerate(z):
            assert corner[i, 0, 0] == pytest.approx(_love_corner(2 * h, h, zi), abs=1e-14)
            assert centre[i, 0, 0] == pytest.approx(4 * _love_corner(h, h / 2, zi), abs=1e-14)


@pytest.mark.parametrize("nu", [0.0, 0.3, 0.5])
def test_a_shear_cell_far_away_is_cerrutis_point_force(nu):
    h = 0.1
    misses = []
    for distance in (2.0, 4.0):
        x = distance * np.array([0.6, -0.3])
        y = distance * np.array([0.5, -0.2])
        z = distance * np.array([0.4, 0.9])
        q = np.zeros((2, 1, 1))
        q[0] = 1.0
        s = grid_stresses(np.zeros((1, 1)), q, h, (-h / 2, -h / 2), x, y, z, nu)
        zz, yy, xx = np.meshgrid(z, y, x, indexing="ij")
        ref = _cerruti(xx, yy, zz, h * h, nu)
        scale = h * h / (2 * np.pi * distance**2)
        misses.append(max(np.abs(s[k] - ref[k]).max() for k in CARTESIAN) / scale)
    assert misses[0] < 0.02  # measured 8.2e-3 at distance 20 h (nu = 0)
    assert 3.5 < misses[0] / misses[1] < 4.5  # the cell's size enters as (h/distance)^2


def test_a_shear_along_y_is_the_shear_along_x_turned_by_90_degrees():
    rng = np.random.default_rng(3)
    n, h = 6, 0.25
    qy = rng.normal(size=(n, n))
    # frame turned: x' = y, y' = -x; cell (i, j) of the grid becomes (j, n - 1 - i)
    qx_turned = np.zeros((2, n, n))
    qx_turned[0] = np.rot90(qy, -1)  # t'[a, b] = t[n - 1 - b, a]
    q = np.zeros((2, n, n))
    q[1] = qy
    x, y, z = np.array([-0.4, 0.3, 1.1]), np.array([-0.7, 0.05, 0.6]), np.array([0.1, 0.7])
    s = grid_stresses(np.zeros((n, n)), q, h, (-n * h / 2, -n * h / 2), x, y, z, NU)
    # the turned field at (x', y') = (y, -x): arrays on (z, y', x') = (z, -x, y)
    t = grid_stresses(np.zeros((n, n)), qx_turned, h, (-n * h / 2, -n * h / 2), y, -x, z, NU)
    turned = {k: np.swapaxes(v, 1, 2) for k, v in t.items()}  # back on (z, y, x)
    pairs = {"sigma_xx": ("sigma_yy", 1), "sigma_yy": ("sigma_xx", 1),
             "sigma_zz": ("sigma_zz", 1), "sigma_xy": ("sigma_xy", -1),
             "sigma_yz": ("sigma_xz", 1), "sigma_xz": ("sigma_yz", -1)}
    for name, (other, sign) in pairs.items():
        np.testing.assert_allclose(s[name], sign * turned[other], atol=1e-13)


def test_the_force_across_a_plane_is_the_tractions_force():
    rng = np.random.default_rng(7)
    n, h = 8, 0.2
    p, q = rng.uniform(0, 1, (n, n)), rng.normal(size=(2, n, n))
    force = h * h * np.array([q[0].sum(), q[1].sum(), p.sum()])  # (Q_x, Q_y, P)
    t, w = np.polynomial.legendre.leggauss(8)
    outer = 40.0
    edges = np.concatenate([np.linspace(0, 2.0, 9), np.geomspace(2.0, outer, 13)[1:]])
    half = np.diff(edges) / 2
    rho = (((edges[:-1] + edges[1:]) / 2)[:, None] + half[:, None] * t).ravel()
    wr = (half[:, None] * w).ravel() * rho
    phi = np.linspace(0, 2 * np.pi, 48, endpoint=False)  # exact for the ring's harmonics
    xs, ys = (rho[:, None] * np.cos(phi)).ravel(), (rho[:, None] * np.sin(phi)).ravel()
    for depth in (0.3, 1.2):
        pts = np.stack([xs, ys, np.full(xs.size, depth)], axis=1)
        s = stresses_at(p, q, h, (-0.8, -0.8), pts, NU)
        # beyond the outer ring the field is a point force's (Boussinesq, Cerruti); the
        # load's moments add odd harmonics, which the rings integrate to zero
        d = math.hypot(outer, depth)
        shear_tail = 1.5 * depth * (1 / d - depth**2 / (3 * d**3))
        normal_tail = depth**3 / d**3
        got = []
        for name, tail in (("sigma_xz", shear_tail), ("sigma_yz", shear_tail),
                           ("sigma_zz", normal_tail)):
            inner = float(np.sum(s[name].reshape(rho.size, phi.size).mean(axis=1)
                                 * 2 * np.pi * wr))
            got.append(inner / (1 - tail))
        # the layer above the plane is in equilibrium: int sigma_iz = -(Q_x, Q_y, P), as on
        # the surface (sigma_xz = -q_x, sigma_zz = -p); z points into the body
        np.testing.assert_allclose(got, -force, atol=1e-5 * np.abs(force).max())


@pytest.mark.parametrize("refine", [1, 2, 3])
def test_the_lattice_by_fft_is_the_direct_sum(refine):
    rng = np.random.default_rng(refine)
    n1, n2, h, origin = 6, 5, 0.3, (-0.9, -0.7)
    p, q = rng.normal(size=(n1, n2)), rng.normal(size=(2, n1, n2))
    z = [0.05, 0.4]
    lat = lattice_stresses(p, q, h, origin, z, NU, refine)
    x = origin[0] + np.arange(refine * n1 + 1) * h / refine
    y = origin[1] + np.arange(refine * n2 + 1) * h / refine
    direct = grid_stresses(p, q, h, origin, x, y, z, NU)
    for name in CARTESIAN:
        np.testing.assert_allclose(lat[name], direct[name], rtol=0, atol=1e-13)


def test_huber_axis_under_the_cells_of_a_hertz_pressure():
    z = np.array([0.2, 0.48, 1.0, 2.0])
    huber_zz = -1 / (1 + z * z)
    huber_rr = -(1 + NU) * (1 - z * np.arctan(1 / z)) + 1 / (2 * (1 + z * z))
    errors = []
    for n in (32, 64):
        h = 2.4 / n
        c = -1.2 + h * (np.arange(n) + 0.5)
        p = np.sqrt(np.clip(1 - c[:, None] ** 2 - c[None, :] ** 2, 0, None))
        s = grid_stresses(p, None, h, (-1.2, -1.2), [0.0], [0.0], z, NU)
        errors.append(max(np.abs(s["sigma_zz"][:, 0, 0] - huber_zz).max(),
                          np.abs(s["sigma_xx"][:, 0, 0] - huber_rr).max(),
                          np.abs(s["sigma_yy"][:, 0, 0] - huber_rr).max()))
        for name in ("sigma_xy", "sigma_xz", "sigma_yz"):  # the axis of a symmetric load
            assert np.abs(s[name]).max() < 1e-12
    assert errors[1] < 2e-4
    assert errors[0] / errors[1] > 3.0  # second order, measured 3.4 ... 4.3


def _mindlin_cells(n, friction, ratio):
    """Hertz pressure and Cattaneo-Mindlin shear sampled at the centres of n x n cells."""
    h = 2.4 / n
    c = -1.2 + h * (np.arange(n) + 0.5)
    r2 = c[:, None] ** 2 + c[None, :] ** 2
    stick = (1 - ratio) ** (1 / 3)
    p = np.sqrt(np.clip(1 - r2, 0, None))
    q = np.zeros((2, n, n))
    q[0] = friction * (p - np.sqrt(np.clip(stick**2 - r2, 0, None)))
    return p, q, h


def test_cattaneo_mindlin_cells_converge_to_the_hankel_field_at_second_order():
    friction, ratio = 0.3, 0.5
    x, y, z = np.array([-0.8, 0.0, 0.5]), np.array([0.0, 0.3]), np.array([0.3, 0.5, 0.8])
    ref = mindlin_sphere_stresses(friction, ratio, x, y, z, NU, points=1601)  # error ~1e-7
    errors = []
    for n in (24, 48, 96):
        p, q, h = _mindlin_cells(n, friction, ratio)
        s = grid_stresses(p, q, h, (-1.2, -1.2), x, y, z, NU)
        errors.append(max(np.abs(s[k] - ref[k].values).max() for k in CARTESIAN))
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert errors[-1] < 3e-4  # measured 1.9e-4 at n = 96 (h = 0.025 a)
    assert np.all(orders > 1.6)  # measured 2.1 and 1.8


def _fretting_run(n, steps=4, tangential=(0, 0, 0.5)):
    """Equal nu = 0 bodies (beta = gamma = 0), mu = 0.3, P to P_max, then Q/(mu P_max)."""
    model = contact("sphere", 0.0, indenter_modulus=1.0, indenter_nu=0.0)
    ops = grid_operators(model, n)
    big_p = load_levels([0] + [1] * (len(tangential) - 1), steps)[0][1:] * ops.p_max
    big_q = load_levels(tangential, steps)[0][1:] * 0.3 * ops.p_max
    return ops, run_sphere_fretting(ops, 0.3, big_p, big_q, keep_fields=True)


FRET_X = np.linspace(-1.2, 1.2, 25)
FRET_Z = np.linspace(0.1, 1.0, 10)


def test_fretting_field_converges_and_its_estimate_covers_the_finer_run_at_the_maxima():
    runs = {n: _fretting_run(n) for n in (16, 32, 64, 128)}
    last = 8  # Q = 0.5 mu P, the end of the path (same steps: the mesh's error alone)
    ds = {n: fretting_step_stresses(
        *runs[n], last, FRET_X, [0.0], FRET_Z, nu=0.0,
        coarse=(*runs[n // 2], last) if n > 16 else None,
        coarser=(*runs[n // 4], last) if n > 32 else None) for n in (16, 32, 64, 128)}
    change = [float(np.abs(ds[2 * n].von_mises - ds[n].von_mises).max()) for n in (16, 32, 64)]
    assert change[2] < change[1] < 0.1 * change[0]  # measured 4.6e-2, 2.8e-3, 2.0e-3
    assert float(ds[32].von_mises_error.max()) == pytest.approx(change[0])
    # Cattaneo-Mindlin is exact for this pair (beta = gamma = 0): the fields converge to it
    ref = mindlin_sphere_stresses(0.3, 0.5, FRET_X, [0.0], FRET_Z, 0.0)
    exact = float(ref.von_mises.max())
    for n in (32, 64):
        fine, finer = ds[n], ds[2 * n]
        for name in ("von_mises", "tresca"):
            top = fine.attrs[f"max_{name}"]
            est = fine.attrs[f"max_{name}_error"]
            assert abs(top - finer.attrs[f"max_{name}"]) <= est
            at = {"z": fine.attrs[f"max_{name}_z"], "y": 0.0, "x": fine.attrs[f"max_{name}_x"]}
            assert abs(float(fine[name].sel(at) - finer[name].sel(at))) <= float(
                fine[f"{name}_error"].sel(at))
        assert abs(fine.attrs["max_von_mises"] - exact) <= fine.attrs["max_von_mises_error"]
    assert float(np.abs(ds[128].von_mises - ref.von_mises).max()) < 2e-4  # measured 8.1e-5
    # the whole lattice (x, y None: the cell corners, by FFT) holds the same values
    lat = fretting_step_stresses(*runs[32], last, None, None, FRET_Z, nu=0.0,
                                 coarse=(*runs[16], last), refine=2)
    assert lat.sizes == {"z": 10, "y": 65, "x": 65}
    sub = lat.isel(x=slice(None, None, 3), y=[32])  # y = 0
    direct = fretting_step_stresses(*runs[32], last, sub.x.values, [0.0], FRET_Z, nu=0.0,
                                    coarse=(*runs[16], last))
    for name in ("sigma_xx", "sigma_yz", "von_mises", "von_mises_error"):
        np.testing.assert_allclose(sub[name].values, direct[name].values, atol=1e-12)


def test_mindlin_deresiewicz_tractions_carry_the_force_and_reduce_to_cattaneo():
    for load in (0.5, 0.1, -0.25, -0.5):
        xi, p, q, c, _ = mindlin_deresiewicz_tractions(0.3, 0.5, load, 801)
        force = np.trapezoid(q * 2 * np.pi * xi, xi)  # Q/p0 a^2; mu P = mu 2 pi/3
        assert force == pytest.approx(0.3 * 2 * np.pi / 3 * load, abs=2e-5)
        if abs(load) == 0.5:  # no reversal yet, or a full one: Cattaneo's shear, +-
            cattaneo = 0.3 * (p - np.sqrt(np.clip(c * c - xi * xi, 0, None)))
            np.testing.assert_allclose(q, np.sign(load) * cattaneo, atol=1e-15)


def test_after_a_reversal_the_fretting_field_is_mindlin_deresiewiczs():
    """Q: 0 -> 0.5 mu P -> -0.25 mu P at constant P, equal nu = 0 bodies (beta = gamma = 0):
    the tractions are Mindlin and Deresiewicz's; their field by the Hankel route is the
    truth."""
    xi, p, q, _, _ = mindlin_deresiewicz_tractions(0.3, 0.5, -0.25, 1001)
    ref = cartesian_stresses(xi, p, FRET_X, [0.0], FRET_Z, 0.0, shear_x=q)
    errors = []
    for n in (32, 64):
        run = _fretting_run(n, tangential=(0, 0, 0.5, -0.25))
        ds = fretting_step_stresses(*run, 12, FRET_X, [0.0], FRET_Z, nu=0.0)
        errors.append(max(float(np.abs(ds[k].values - ref[k]).max()) for k in CARTESIAN))
    assert errors[1] < 3e-3  # measured 9.5e-3, 1.6e-3 (and 4.8e-4 at n = 128)
    assert errors[0] / errors[1] > 3.0


def test_a_turning_shear_keeps_the_mirror_symmetry_of_the_load():
    """Equal nu = 0.3 bodies (beta = 0, gamma = 0.43): the shear turns off x (q_y up to 5 %
    of q_x at n = 32) and is odd in y, q_x even; so sigma_xy and sigma_yz are odd in y and
    the other components even, and the q_y part of the field is not negligible."""
    model = contact("sphere", 0.3, indenter_modulus=1.0, indenter_nu=0.3)
    ops = grid_operators(model, 32)
    big_p = load_levels([0, 1, 1], 4)[0][1:] * ops.p_max
    big_q = load_levels([0, 0, 0.5], 4)[0][1:] * 0.3 * ops.p_max
    raw = run_sphere_fretting(ops, 0.3, big_p, big_q, keep_fields=True)
    q = raw.q[-1]
    assert np.abs(q[1]).max() > 0.03 * np.abs(q[0]).max()
    ds = fretting_step_stresses(ops, raw, 8, FRET_X, [-0.3, 0.0, 0.3], FRET_Z, nu=0.3)
    for name in CARTESIAN:
        sign = -1.0 if name in ("sigma_xy", "sigma_yz") else 1.0
        np.testing.assert_allclose(ds[name].sel(y=0.3), sign * ds[name].sel(y=-0.3),
                                   atol=1e-10)
    only_x = grid_stresses(raw.p[-1] / ops.p0, np.stack([q[0], 0 * q[1]]) / ops.p0, ops.h,
                           (-1.2, -1.2), FRET_X, [0.3], FRET_Z, 0.3)
    # the q_y part of sigma_yz at y = 0.3: measured 1.3e-3 p0
    assert np.abs(only_x["sigma_yz"][:, 0] - ds.sigma_yz.sel(y=0.3).values).max() > 5e-4


def test_fretting_stresses_replays_the_result_and_refuses_bad_input():
    r = fretting("sphere", 0.0, 0.3, [0, 1, 1], [0, 0, 0.5], 4, n=32,
                 indenter_modulus=1.0, indenter_nu=0.0)
    ds = fretting_stresses(r, -1, FRET_X, [0.0], FRET_Z, indenter_modulus=1.0,
                           indenter_nu=0.0)
    own = fretting_step_stresses(*_fretting_run(32), 8, FRET_X, [0.0], FRET_Z, nu=0.0)
    np.testing.assert_array_equal(ds.von_mises.values, own.von_mises.values)
    assert ds.attrs["contact_radius"] == pytest.approx(r.contact_edges[-1, 1])
    assert ds.attrs["reference_cells"] == "16" and "tresca_error" in ds
    with pytest.raises(InputError, match="beta"):
        fretting_stresses(r, -1, FRET_X, [0.0], FRET_Z)  # a rigid indenter: another pair
    with pytest.raises(InputError, match="multiple of 2"):
        fretting_stresses(r, 7, FRET_X, [0.0], FRET_Z, indenter_modulus=1.0, indenter_nu=0.0)
    with pytest.raises(InputError, match="step"):
        fretting_stresses(r, 9, FRET_X, [0.0], FRET_Z, indenter_modulus=1.0, indenter_nu=0.0)
    with pytest.raises(InputError, match="z"):
        fretting_stresses(r, 8, FRET_X, [0.0], [0.0, 0.5], indenter_modulus=1.0,
                          indenter_nu=0.0)
    with pytest.raises(InputError, match="sphere"):
        fretting_stresses(None, 8, FRET_X, [0.0], FRET_Z)
    with pytest.raises(InputError, match="lattice"):
        fretting_stresses(r, 8, None, [0.0], FRET_Z, indenter_modulus=1.0, indenter_nu=0.0)


def test_grid_input_is_checked():
    with pytest.raises(InputError, match="q"):
        grid_stresses(np.ones((2, 2)), np.ones((2, 3, 3)), 0.1, (0, 0), [0], [0], [1], NU)
    with pytest.raises(InputError, match="h"):
        grid_stresses(np.ones((2, 2)), None, -0.1, (0, 0), [0], [0], [1], NU)
    with pytest.raises(InputError, match="nu"):
        grid_stresses(np.ones((2, 2)), None, 0.1, (0, 0), [0], [0], [1], 0.7)
    with pytest.raises(InputError, match="origin"):
        grid_stresses(np.ones((2, 2)), None, 0.1, (0, np.nan), [0], [0], [1], NU)
    w = corner_weights(np.ones((2, 2)))
    assert w.shape == (3, 3, 3) and w[0].sum() == 0.0 and w[0, 0, 0] == 1.0
