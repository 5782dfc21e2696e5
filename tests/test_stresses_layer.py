"""Stresses inside a layer on a rigid base (stresses.layer_stresses and
contactlib.stresses.layer, issue 38 item 1).

Independent truths: the layer's surface transfer functions (contactlib.kernels.layer_transfer,
checked there against a numerical boundary-value solution), Huber's closed forms on the
axis under Hertz pressure (a thick layer is a half-space), the base conditions, the
surface tractions, the force across every plane z = const, the thin-layer limits
(uniaxial strain on a bonded base, plane stress on a smooth one) and convergence under
refinement of the quadrature and of the solved case's mesh.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from contactlib import solve
from contactlib.kernels.layer_transfer import transfer
from contactlib.stresses import (
    field_error_estimate,
    halfplane_stresses,
    halfspace_stresses,
    layer_stresses,
    subsurface_stresses,
)
from contactlib.stresses.layer import surface_transfer
from contactlib.validate import InputError

NU = 0.3
XI = np.linspace(0.0, 1.0, 401)
HERTZ = np.sqrt(1.0 - XI**2)
ZERO = np.zeros_like(XI)


def hertz_at(x):
    return np.sqrt(np.clip(1.0 - np.asarray(x) ** 2, 0.0, None))


@pytest.mark.parametrize("base", ["smooth", "bonded"])
@pytest.mark.parametrize("nu", [0.0, 0.3, 0.5])
def test_surface_of_the_interior_solution_is_the_layer_kernel(base, nu):
    t = np.array([1e-3, 0.1, 0.5, 1.0, 2.0, 5.0, 10.0, 30.0, 60.0])
    ours = np.array(surface_transfer(t, nu, base))
    theirs = np.array(transfer(t, nu, base))
    # relative to max(1, |C|): the smooth base's Cuu ~ 1/(2t) is 500 at t = 1e-3
    assert (np.abs(ours - theirs) / np.maximum(1.0, np.abs(theirs))).max() < 1e-12


@pytest.mark.parametrize("base", ["smooth", "bonded"])
def test_thick_layer_is_the_half_space(base):
    z, x = np.array([0.0, 0.25, 0.5, 1.0, 2.0]), np.array([0.0, 0.5, 1.5])
    half = halfspace_stresses(XI, HERTZ, ZERO, x, z, NU)
    dev = {}
    for h in (100.0, 1000.0):
        f = layer_stresses(XI, HERTZ, ZERO, x, z, NU, h, base)
        dev[h] = max(np.abs(f[c] - half[c]).max() for c in f)
    # the layer's effect falls like (a/h)^2: 3.3e-5 (smooth), 3.6e-5 (bonded) at h = 100 a
    assert dev[100.0] < 5e-5
    assert dev[100.0] / dev[1000.0] == pytest.approx(100.0, rel=0.02)
    # Huber on the axis, within the half-space's own error of the tabulated sqrt (2e-5)
    f = layer_stresses(XI, HERTZ, ZERO, [0.0], z, NU, 1000.0, base)
    zz = -1.0 / (1.0 + z**2)
    zp = np.where(z > 0, z, 1.0)
    rr = -(1.0 + NU) * (1.0 - np.where(z > 0, z * np.arctan(1.0 / zp), 0.0)) \
        + 0.5 / (1.0 + z**2)
    assert np.abs(f["sigma_zz"][:, 0] - zz).max() < 3e-5
    assert np.abs(f["sigma_rr"][:, 0] - rr).max() < 6e-5
    assert np.abs(f["sigma_tt"][:, 0] - rr).max() < 6e-5  # axis: sigma_tt = sigma_rr


@pytest.mark.parametrize("base", ["smooth", "bonded"])
def test_surface_tractions_and_base_conditions(base):
    h, x = 1.0, np.linspace(0.0, 3.0, 13)
    z = np.array([0.0, 0.5, h])
    p, q = HERTZ, 0.2 * XI * HERTZ  # a radial shear vanishes on the axis (else sigma_rr is inf)
    f = layer_stresses(XI, p, q, x, z, NU, h, base)
    assert np.abs(f["sigma_zz"][0] + hertz_at(x)).max() < 1e-12
    assert np.abs(f["sigma_rz"][0] + 0.2 * x * hertz_at(x)).max() < 1e-12
    if base == "smooth":  # shear-free base
        assert np.abs(f["sigma_rz"][-1]).max() < 1e-10
    else:  # u = 0 on z = h: eps_rr = eps_tt = 0, so sigma_rr = sigma_tt = nu/(1 - nu) sigma_zz
        lateral = NU / (1.0 - NU) * f["sigma_zz"][-1]
        assert np.abs(f["sigma_rr"][-1] - lateral).max() < 1e-10
        assert np.abs(f["sigma_tt"][-1] - lateral).max() < 1e-10
    # halving the panels of the correction's k integral moves the field by < 1e-9
    g = layer_stresses(XI, p, q, x, z, NU, h, base, refine=2)
    assert max(np.abs(f[c] - g[c]).max() for c in f) < 1e-9


def _load(xi, p):
    """2 pi int p r dr of the piecewise-linear p, exactly (Simpson on each piece)."""
    a, b, pa, pb = xi[:-1], xi[1:], p[:-1], p[1:]
    return 2.0 * math.pi * np.sum((b - a) / 6.0 * (pa * (2 * a + b) + pb * (a + 2 * b)))


def _radial_rule(r_max, panels):
    t, w = np.polynomial.legendre.leggauss(16)
    edges = np.linspace(0.0, r_max, panels + 1)
    half = 0.5 * np.diff(edges)
    nodes = (0.5 * (edges[:-1] + edges[1:]))[:, None] + half[:, None] * t
    return nodes.ravel(), (half[:, None] * w).ravel()


@pytest.mark.parametrize("base", ["smooth", "bonded"])
def test_force_across_every_plane_is_the_load(base):
    """2 pi int sigma_zz r dr = -P on z = const, P the load of the tabulated pressure
    (2 pi/3 p0 a^2 less 2.3e-4 for the 401 points of sqrt(1 - r^2)).

    The shear adds nothing (its Hankel transform has no k = 0 part). The field decays
    exponentially in r/h: the part beyond r = 30 h is below 1e-9 (beyond 15 h, 2e-6)."""
    r, w = _radial_rule(30.0, 120)  # panels break at r = 1 (the pressure's edge)
    z = np.array([0.3, 0.7, 1.0])
    f = layer_stresses(XI, HERTZ, 0.3 * HERTZ, r, z, NU, 1.0, base)
    force = 2.0 * math.pi * (f["sigma_zz"] * r) @ w
    assert np.abs(force + _load(XI, HERTZ)).max() < 1e-8  # measured 6e-10


def test_thin_bonded_layer_is_in_uniaxial_strain():
    """Winkler: sigma_zz = -p through the thickness and sigma_rr = sigma_tt =
    nu/(1 - nu) sigma_zz, away from the edge; the departure falls like (h/a)^2."""
    x = np.array([0.0, 0.3, 0.5])
    err = {}
    for h in (0.05, 0.02):
        z = np.array([0.0, 0.5 * h, h])
        f = layer_stresses(XI, HERTZ, ZERO, x, z, NU, h, "bonded")
        err[h] = max(np.abs(f["sigma_zz"] + hertz_at(x)).max(),
                     np.abs(f["sigma_rr"] - NU / (1 - NU) * f["sigma_zz"])[1:].max(),
                     np.abs(f["sigma_tt"] - NU / (1 - NU) * f["sigma_zz"])[1:].max())
    assert err[0.02] < 4e-4  # measured 2.7e-4
    assert err[0.05] / err[0.02] > 0.8 * (0.05 / 0.02) ** 2


def test_thin_smooth_layer_is_a_plate_in_plane_stress():
    """sigma_zz = -p through the thickness, and the in-plane stresses are those of a plate
    whose thickness strain is free: sigma_rr + sigma_tt = -nu p (docs/theory.md, Layers);
    the departure falls like (h/a)^2."""
    x = np.array([0.0, 0.3, 0.5])
    err = {}
    for h in (0.05, 0.02):
        z = np.array([0.0, 0.5 * h, h])
        f = layer_stresses(XI, HERTZ, ZERO, x, z, NU, h, "smooth")
        assert np.abs(f["sigma_zz"] + hertz_at(x)).max() < 1e-5
        err[h] = np.abs(f["sigma_rr"] + f["sigma_tt"] + NU * hertz_at(x)).max()
    assert err[0.02] < 6e-4  # measured 4.7e-4
    assert err[0.05] / err[0.02] > 0.8 * (0.05 / 0.02) ** 2


def test_solved_layer_converges_and_its_estimate_covers_the_error():
    """A solved sphere on a bonded layer (a/h = 1, c/a = 0.5): the field at n = 128, its
    estimate (the change from n = 64) against the difference to n = 512."""
    x, z = np.linspace(0.0, 1.5, 16), np.linspace(0.0, 1.0, 11)
    kw = {"stick_ratio": 0.5, "slab_ratio": 1.0, "base": "bonded", "energy": False}
    fine = subsurface_stresses(solve("sphere", NU, n=128, **kw), x, z)
    ref = subsurface_stresses(solve("sphere", NU, n=512, **kw), x, z)
    est = field_error_estimate(solve("sphere", NU, n=128, **kw), x, z)
    assert est.attrs["layer_thickness"] == 1.0 and est.attrs["base"] == "bonded"
    for name in ("sigma_zz", "sigma_rr", "sigma_rz", "von_mises", "tresca"):
        true = np.abs(fine[name] - ref[name]).values
        e = est[name].values
        assert true.max() < 2e-3  # measured 1.2e-3 (sigma_rr)
        assert np.all(e[1:] >= true[1:])  # below the surface, everywhere on the grid
    # equilibrium of the solved case: the force across z = h is the solver's load
    r, w = _radial_rule(30.0, 120)
    sol = solve("sphere", NU, n=128, **kw)
    f = subsurface_stresses(sol, r, [0.5, 1.0], measures=False)
    force = 2.0 * math.pi * (f["sigma_zz"].values * r) @ w
    load = _load(np.asarray(sol.extra["nodes"]), np.asarray(sol.extra["nodal_pressure"]))
    assert np.abs(force + load).max() < 1e-8 * load
    # and the solver's own load, P / P_Hertz(a) = load_ratio, to its discretization
    assert load / (2.0 * math.pi / 3.0) == pytest.approx(sol.load_ratio, rel=1e-3)


def test_layer_routing_and_refusals():
    sol = solve("sphere", NU, stick_ratio=0.0, n=32, slab_ratio=2.0, energy=False)
    ds = subsurface_stresses(sol, [0.0, 0.5], [0.0, 0.25, 0.5, 0.75])
    assert ds.attrs["layer_thickness"] == 0.5 and ds.attrs["base"] == "smooth"
    assert np.all(np.isnan(ds["sigma_zz"].values[-1]))  # z = 0.75 > h: below the layer
    assert np.all(np.isfinite(ds["von_mises"].values[:-1]))
    with pytest.raises(InputError, match="within the layer"):
        layer_stresses(XI, HERTZ, ZERO, [0.0], [0.6], NU, 0.5, "smooth")
    with pytest.raises(InputError, match="coated body"):
        layer_stresses(XI, HERTZ, ZERO, [0.0], [0.1], NU, 0.5, "elastic")


# ----------------------------------------------------------------------------- cylinder
@pytest.mark.parametrize("base", ["smooth", "bonded"])
def test_cylinder_thick_layer_is_the_half_plane(base):
    """In plane strain the layer's effect falls like a/h (the half-plane's stress at depth
    h is P/(pi h)): 7.7e-3 p0 (smooth), 6.5e-3 (bonded) at h = 100 a."""
    x, z = np.array([-1.5, -0.5, 0.0, 0.5, 1.5]), np.array([0.0, 0.25, 0.5, 1.0, 2.0])
    half = halfplane_stresses(XI, HERTZ, ZERO, x, z, NU)
    dev = {}
    for h in (100.0, 1000.0):
        f = layer_stresses(XI, HERTZ, ZERO, x, z, NU, h, base, geometry="cylinder")
        dev[h] = max(np.abs(f[c] - half[c]).max() for c in f)
    assert dev[1000.0] < 1e-3
    assert dev[100.0] / dev[1000.0] == pytest.approx(10.0, rel=0.01)


@pytest.mark.parametrize("base", ["smooth", "bonded"])
def test_cylinder_surface_base_and_force(base):
    h, x = 1.0, np.linspace(-3.0, 3.0, 13)
    z = np.array([0.0, 0.5, h])
    f = layer_stresses(XI, HERTZ, 0.2 * HERTZ, x, z, NU, h, base, geometry="cylinder")
    assert np.abs(f["sigma_zz"][0] + hertz_at(x)).max() < 1e-12
    assert np.abs(f["sigma_xz"][0] + 0.2 * np.sign(x) * hertz_at(x)).max() < 1e-12
    assert np.abs(f["sigma_yy"] - NU * (f["sigma_xx"] + f["sigma_zz"])).max() < 1e-14
    if base == "smooth":
        assert np.abs(f["sigma_xz"][-1]).max() < 1e-12
    else:  # u = 0 on z = h: eps_xx = 0, so sigma_xx = nu/(1 - nu) sigma_zz
        assert np.abs(f["sigma_xx"][-1] - NU / (1 - NU) * f["sigma_zz"][-1]).max() < 1e-12
    g = layer_stresses(XI, HERTZ, 0.2 * HERTZ, x, z, NU, h, base, geometry="cylinder",
                       refine=2)
    assert max(np.abs(f[c] - g[c]).max() for c in f) < 1e-9
    # 2 int_0^inf sigma_zz dx = -int p dx over the line (shear odd: no net part)
    r, w = _radial_rule(30.0, 120)
    f = layer_stresses(XI, HERTZ, 0.3 * HERTZ, r, np.array([0.3, 0.7, 1.0]), NU, 1.0, base,
                       geometry="cylinder")
    line_load = np.sum(np.diff(XI) * (HERTZ[:-1] + HERTZ[1:]))  # exact, both halves
    assert np.abs(2.0 * f["sigma_zz"] @ w + line_load).max() < 1e-9  # measured 2e-11


def test_cylinder_thin_layer_limits():
    """Bonded: sigma_zz = -p and sigma_xx = nu/(1 - nu) sigma_zz (no lateral strain).
    Smooth: sigma_zz = -p and sigma_xx = 0 (a plate free to stretch in x, held in y).
    Below the surface (z = h/2, h), r <= 0.5 a; departures fall like (h/a)^2."""
    x = np.array([0.0, 0.3, 0.5])
    err = {"bonded": {}, "smooth": {}}
    for h in (0.05, 0.02):
        z = np.array([0.5 * h, h])
        b = layer_stresses(XI, HERTZ, ZERO, x, z, NU, h, "bonded", geometry="cylinder")
        s = layer_stresses(XI, HERTZ, ZERO, x, z, NU, h, "smooth", geometry="cylinder")
        err["bonded"][h] = max(np.abs(b["sigma_zz"] + hertz_at(x)).max(),
                               np.abs(b["sigma_xx"] - NU / (1 - NU) * b["sigma_zz"]).max())
        err["smooth"][h] = max(np.abs(s["sigma_zz"] + hertz_at(x)).max(),
                               np.abs(s["sigma_xx"]).max())
    for e in err.values():
        assert e[0.02] < 3e-4  # measured 2.2e-4 (bonded), 2.1e-4 (smooth)
        assert e[0.05] / e[0.02] > 0.8 * (0.05 / 0.02) ** 2


def test_cylinder_solved_layer_converges():
    """A solved cylinder on a bonded layer (a/h = 1, c/a = 0.5): n = 128 against n = 512;
    the estimate (the change from n = 64) bounds the grid's largest error of each
    component and covers the error at the maxima of von Mises and Tresca."""
    x, z = np.linspace(-1.5, 1.5, 31), np.linspace(0.0, 1.0, 11)
    kw = {"stick_ratio": 0.5, "slab_ratio": 1.0, "base": "bonded", "energy": False}
    sol = solve("cylinder", NU, n=128, **kw)
    fine = subsurface_stresses(sol, x, z)
    ref = subsurface_stresses(solve("cylinder", NU, n=512, **kw), x, z)
    est = field_error_estimate(sol, x, z)
    for name in ("sigma_zz", "sigma_xx", "sigma_xz", "von_mises", "tresca"):
        true = np.abs(fine[name] - ref[name]).values
        assert true.max() < 2e-3  # measured 1.4e-3 (sigma_xx)
        assert est[name].values.max() >= true.max()
    for name in ("von_mises", "tresca"):
        at = np.unravel_index(int(np.argmax(fine[name].values)), fine[name].shape)
        assert est[name].values[at] >= abs(fine[name] - ref[name]).values[at]
