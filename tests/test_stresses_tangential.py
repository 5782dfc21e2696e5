"""The field of a shear along x (contactlib.stresses.tangential) against independent truths.

Hamilton's closed form on the axis, Cerruti's point force in the far field, the force
balance on a plane, the equations of equilibrium and compatibility, and the surface limit.
"""

import numpy as np
import pytest

from contactlib.stresses import halfspace_stresses
from contactlib.stresses.tangential import (CARTESIAN, cartesian_measures, cartesian_stresses,
                                            mindlin_sphere_stresses, mindlin_tractions,
                                            shear_x_stresses)

NU = 0.3


def _hertz_shear(points=401):
    xi, _, q, _ = mindlin_tractions(1.0, 1.0, points)  # q = sqrt(1 - r^2): q0 = 1
    return xi, q


def _cerruti(x, y, z, force, nu):
    """Cerruti's point force along +x on the half-space (Johnson, Contact Mechanics, 3.?)."""
    r = np.sqrt(x * x + y * y + z * z)
    c, m, rz = force / (2 * np.pi), 1 - 2 * nu, r + z
    return {
        "sigma_xx": c * (-3 * x**3 / r**5 + m * (x / r**3 - 3 * x / (r * rz**2)
                                                + x**3 / (r**3 * rz**2)
                                                + 2 * x**3 / (r**2 * rz**3))),
        "sigma_yy": c * (-3 * x * y * y / r**5 + m * (x / r**3 - x / (r * rz**2)
                                                      + x * y * y / (r**3 * rz**2)
                                                      + 2 * x * y * y / (r**2 * rz**3))),
        "sigma_zz": -3 * c * x * z * z / r**5,
        "sigma_xy": c * (-3 * x * x * y / r**5 + m * (-y / (r * rz**2)
                                                      + x * x * y / (r**3 * rz**2)
                                                      + 2 * x * x * y / (r**2 * rz**3))),
        "sigma_xz": -3 * c * x * x * z / r**5,
        "sigma_yz": -3 * c * x * y * z / r**5,
    }


def test_axis_matches_hamiltons_closed_form_and_converges_at_second_order():
    z = np.array([0.05, 0.1, 0.25, 0.48, 0.8, 1.3, 2.0])
    exact = -1 + 1.5 * z * np.arctan(1 / z) - z * z / (2 * (1 + z * z))
    errors = []
    for points in (101, 401):
        xi, q = _hertz_shear(points)
        s = shear_x_stresses(xi, q, [0.0], [0.0], z, NU)
        errors.append(np.abs(s["sigma_xz"][:, 0, 0] - exact).max())
        for name in ("sigma_xx", "sigma_yy", "sigma_zz", "sigma_xy", "sigma_yz"):
            assert np.abs(s[name]).max() < 1e-12  # no cos/sin harmonic survives on the axis
    assert errors[1] < 1e-5
    assert 10 < errors[0] / errors[1] < 22  # 4x the points: 16x smaller (graded samples)


def test_far_field_is_cerrutis_point_force():
    xi, q = _hertz_shear(201)
    force = 2 * np.pi / 3  # int q 2 pi r dr for q = sqrt(1 - r^2)
    misses = []
    for distance in (16.0, 32.0):
        x = distance * np.array([0.6, -0.3])
        y = distance * np.array([0.5])
        z = distance * np.array([0.4, 0.9])
        s = shear_x_stresses(xi, q, x, y, z, NU)
        zz, yy, xx = np.meshgrid(z, y, x, indexing="ij")
        ref = _cerruti(xx, yy, zz, force, NU)
        scale = force / (2 * np.pi * distance**2)
        misses.append(max(np.abs(s[k] - ref[k]).max() for k in CARTESIAN) / scale)
    assert misses[0] < 0.02
    assert 3.0 < misses[0] / misses[1] < 5.0  # the disc's size enters as (a/distance)^2


def test_the_shear_across_any_plane_carries_the_tangential_force():
    xi, q = _hertz_shear(201)
    force = 2 * np.pi / 3
    depth, outer = 0.5, 24.0
    t, w = np.polynomial.legendre.leggauss(16)
    edges = np.concatenate([np.linspace(0, 4, 17), np.linspace(4, outer, 21)[1:]])
    half = np.diff(edges) / 2
    rho = ((edges[:-1] + edges[1:]) / 2)[:, None] + half[:, None] * t
    weight = (half[:, None] * w).ravel()
    rho = rho.ravel()
    along_x = shear_x_stresses(xi, q, rho, [0.0], [depth], NU)["sigma_xz"][0, 0]
    along_y = shear_x_stresses(xi, q, [0.0], rho, [depth], NU)["sigma_xz"][0, :, 0]
    mean = 0.5 * (along_x + along_y)  # the cos(2 theta) part averages out
    near = 2 * np.pi * np.sum(weight * mean * rho)
    u = outer**2 + depth**2  # Cerruti's tail beyond `outer`, its angular mean in closed form
    tail = -1.5 * force * depth * 0.5 * (2 / np.sqrt(u) - (2 / 3) * depth**2 / u**1.5)
    assert near + tail == pytest.approx(-force, rel=2e-4)


def test_equilibrium_and_compatibility_hold_pointwise():
    xi, q = _hertz_shear(201)
    h, g = 1e-3, 2e-2
    offsets = np.array([-g, -h, 0.0, h, g])
    x0, y0, z0 = 0.43, 0.31, 0.37
    s = shear_x_stresses(xi, q, x0 + offsets, y0 + offsets, z0 + offsets, NU)
    c = 2  # the centre's index on every axis; s[name][z, y, x]

    def d(name, axis):  # central difference, step h
        lo, hi = [c, c, c], [c, c, c]
        lo[axis], hi[axis] = 1, 3
        return (s[name][tuple(hi)] - s[name][tuple(lo)]) / (2 * h)

    x_, y_, z_ = 2, 1, 0
    balance = [d("sigma_xx", x_) + d("sigma_xy", y_) + d("sigma_xz", z_),
               d("sigma_xy", x_) + d("sigma_yy", y_) + d("sigma_yz", z_),
               d("sigma_xz", x_) + d("sigma_yz", y_) + d("sigma_zz", z_)]
    size = max(abs(d(k, a)) for k in CARTESIAN for a in (0, 1, 2))
    assert np.abs(balance).max() < 1e-5 * size
    # Beltrami-Michell: (1 + nu) lap(sigma_xz) + d2(trace)/dx dz = 0 (step g)
    xz = s["sigma_xz"]
    lap = ((xz[c, c, 4] - 2 * xz[c, c, c] + xz[c, c, 0])
           + (xz[c, 4, c] - 2 * xz[c, c, c] + xz[c, 0, c])
           + (xz[4, c, c] - 2 * xz[c, c, c] + xz[0, c, c])) / g**2
    trace = s["sigma_xx"] + s["sigma_yy"] + s["sigma_zz"]
    cross = (trace[4, c, 4] - trace[0, c, 4] - trace[4, c, 0] + trace[0, c, 0]) / (4 * g * g)
    assert abs((1 + NU) * lap + cross) < 2e-3 * max(abs(lap), abs(cross))


def test_the_field_tends_to_the_tractions_at_the_surface():
    xi, q = _hertz_shear(401)
    x, y = np.array([-0.7, 0.0, 0.35, 0.6]), np.array([0.0, 0.3])
    s = shear_x_stresses(xi, q, x, y, [0.0, 0.01, 0.02], NU)
    qx = np.sqrt(1 - np.hypot(*np.meshgrid(x, y))**2)
    assert np.allclose(s["sigma_xz"][0], -qx, atol=1e-12)
    assert np.all(s["sigma_zz"][0] == 0) and np.all(s["sigma_yz"][0] == 0)
    # inside the contact the interior field leaves the tractions like z (sigma_zz, sigma_xz)
    # or z^2 (sigma_yz): the surface limit of the interior field is the tractions
    for name, order, limit in (("sigma_zz", 1, 0.0), ("sigma_xz", 1, -qx),
                               ("sigma_yz", 2, 0.0)):
        near, far = (np.abs(s[name][i] - limit).max() for i in (1, 2))
        assert far / near == pytest.approx(2.0**order, rel=0.1)
    # the surface row's in-plane stresses (xi cut at XI_SURFACE) are the interior's limit
    for name in ("sigma_xx", "sigma_yy", "sigma_xy"):
        extrapolated = 2 * s[name][1] - s[name][2]
        assert np.abs(s[name][0] - extrapolated).max() < 1e-4


def test_the_axisymmetric_part_is_the_radial_field_turned_into_cartesian_axes():
    xi = np.linspace(0, 1, 101)
    p, qr = np.sqrt(1 - xi**2), 0.2 * xi * np.sqrt(1 - xi**2)
    x, y, z = np.array([0.3, 0.8]), np.array([0.0, 0.5]), np.array([0.2, 0.6])
    cart = cartesian_stresses(xi, p, x, y, z, NU, radial_shear=qr)
    measures = cartesian_measures(cart)
    for j, yy in enumerate(y):
        rho = np.hypot(x, yy)
        radial = halfspace_stresses(xi, p, qr, rho, z, NU)
        trace = radial["sigma_rr"] + radial["sigma_tt"] + radial["sigma_zz"]
        assert np.allclose(3 * measures["hydrostatic"][:, j], trace, atol=1e-12)
        assert np.allclose(cart["sigma_zz"][:, j], radial["sigma_zz"], atol=1e-12)
        assert np.allclose(np.hypot(cart["sigma_xz"][:, j], cart["sigma_yz"][:, j]),
                           np.abs(radial["sigma_rz"]), atol=1e-12)
    # von Mises from the components equals that from the principal stresses
    s1, s2, s3 = measures["sigma_1"], measures["sigma_2"], measures["sigma_3"]
    assert np.allclose(measures["von_mises"],
                       np.sqrt(0.5 * ((s1 - s2)**2 + (s2 - s3)**2 + (s3 - s1)**2)), atol=1e-12)


def test_sliding_sphere_dataset_and_its_maximum_moves_to_the_surface_with_friction():
    z = np.linspace(0.0, 1.0, 21)
    x = np.linspace(-1.2, 1.2, 25)
    frictionless = mindlin_sphere_stresses(1e-9, 1.0, x, [0.0], z, NU, points=201)
    sliding = mindlin_sphere_stresses(0.4, 1.0, x, [0.0], z, NU, points=201)
    assert sliding.attrs["stick_ratio"] == 0.0
    tau0 = frictionless.tresca.values[:, 0, :]
    i = np.unravel_index(np.argmax(tau0), tau0.shape)
    assert z[i[0]] == pytest.approx(0.48, abs=0.05)  # Huber's 0.31 p0 at 0.48 a
    assert tau0.max() == pytest.approx(0.31, abs=0.01)
    tau = sliding.tresca.values[:, 0, :]
    assert z[np.unravel_index(np.argmax(tau), tau.shape)[0]] == 0.0  # mu = 0.4 > 0.3
    assert sliding.von_mises.max() > frictionless.von_mises.max()


def test_mindlin_tractions_hold_the_stick_zone_and_refuse_bad_input():
    xi, p, q, c = mindlin_tractions(0.5, 0.875)
    assert c == pytest.approx(0.5)
    assert np.all(q <= 0.5 * p + 1e-15)  # never beyond Coulomb
    slip = xi >= c
    assert np.allclose(q[slip], 0.5 * p[slip])
    total = np.trapezoid(q * 2 * np.pi * xi, xi) / np.trapezoid(p * 2 * np.pi * xi, xi)
    assert total == pytest.approx(0.5 * 0.875, rel=1e-4)
    for bad in ({"friction": -1.0, "load_ratio": 0.5}, {"friction": 0.3, "load_ratio": 1.5},
                {"friction": 0.3, "load_ratio": float("nan")}):
        with pytest.raises(ValueError):
            mindlin_tractions(**bad)
    with pytest.raises(ValueError):
        shear_x_stresses(xi, q, [0.0], [0.0], [-0.1], NU)


def test_the_tangential_figure_and_the_maxima_table():
    from contactlib import solve, stress_study
    from contactlib.plot import fig_tangential_stresses
    from contactlib.stresses import subsurface_stresses

    x, z = np.linspace(-1.5, 1.5, 31), np.linspace(0.0, 1.0, 11)
    fields = [mindlin_sphere_stresses(mu, ratio, x, [0.0], z, NU, points=101).isel(y=0)
              for mu, ratio in ((0.4, 1.0), (0.4, 0.5))]
    fig = fig_tangential_stresses(fields)
    assert len(fig.axes) == 5  # two maps, two surface rows, one colour bar
    with pytest.raises(ValueError, match="surface row"):
        fig_tangential_stresses(fields[0].isel(z=slice(1, None)))
    g = np.linspace(0.0, 1.0, 11)
    partial = [subsurface_stresses(solve("sphere", NU, stick_ratio=0.0, n=32), g, g)]
    rows = stress_study.maxima_rows(partial, fields)
    assert [r["Q/(k P)"] for r in rows] == [0.0, 1.0, 0.5]
    assert rows[0]["p0/Y at first yield"] == pytest.approx(1.613, abs=0.01)  # Hertz
    assert rows[1]["x/a (vM)"] == -1.0 and rows[1]["z/a (vM)"] == 0.0  # the trailing edge
