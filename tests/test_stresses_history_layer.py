"""The stress field under a history step on a layer (history_stresses): on a rigid base,
and on an elastic substrate (a coated body).

Checked against identities of the layer (the surface tractions, the base's conditions,
the force across every plane) and against an independent solver: at the peak of a
frictionless load path the history's field is the self-similar solve's on the same layer.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from contactlib import history, solve
from contactlib.stresses import history_stresses, subsurface_stresses

NU = 0.3
SLAB = 1.0  # a_max / h: the layer is a_max thick


def _rule(r_max, panels, order=16):
    t, w = np.polynomial.legendre.leggauss(order)
    edges = np.linspace(0.0, r_max, panels + 1)
    half = 0.5 * np.diff(edges)
    nodes = (0.5 * (edges[:-1] + edges[1:]))[:, None] + half[:, None] * t
    return nodes.ravel(), (half[:, None] * w).ravel()


@pytest.fixture(scope="module", params=[("sphere", "smooth"), ("sphere", "bonded"),
                                        ("cylinder", "smooth"), ("cylinder", "bonded")],
                ids=lambda c: "-".join(c))
def partial_slip(request):
    geometry, base = request.param
    res = history(geometry, NU, 0.3, [0, 1], steps=4, n=60, slab_ratio=SLAB, base=base)
    assert 0 < res.stick_ratio[-1] < 1 and res.converged[-1]  # partial slip at the peak
    return geometry, base, res


def test_surface_tractions_and_base_conditions(partial_slip):
    """On z = 0 the field's tractions are the step's element tractions (sigma_zz = -p,
    sigma_rz = -q at the element midpoints); on the base z = h, sigma_rz = 0 (smooth) or
    the lateral stresses are nu/(1 - nu) sigma_zz (bonded: no lateral strain)."""
    geometry, base, res = partial_slip
    mid = np.asarray(res.xi)[::7]  # midpoints in and beyond the contact
    p, q = np.asarray(res.pressure)[-1][::7], np.asarray(res.shear)[-1][::7]
    h = 1.0 / SLAB
    ds = history_stresses(res, -1, mid, [0.0, 0.5 * h, h], measures=False)
    shear = "sigma_rz" if geometry == "sphere" else "sigma_xz"
    lateral = ("sigma_rr", "sigma_tt") if geometry == "sphere" else ("sigma_xx",)
    assert np.abs(ds["sigma_zz"].values[0] + p).max() < 1e-12  # measured 1e-16
    assert np.abs(ds[shear].values[0] + q).max() < 1e-12
    if base == "smooth":
        assert np.abs(ds[shear].values[-1]).max() < 1e-9
    else:
        for name in lateral:
            assert np.abs(ds[name].values[-1]
                          - NU / (1 - NU) * ds["sigma_zz"].values[-1]).max() < 1e-9


def test_force_across_every_plane_is_the_step_load(partial_slip):
    """int sigma_zz dA = -P on z = const within the layer, P the sum of the element
    pressures over their areas (the shear's net force is zero by symmetry). The field
    decays exponentially in r/h beyond the contact; 30 h holds it to 1e-9."""
    geometry, _, res = partial_slip
    edges = np.asarray(res.xi_bounds)
    p = np.asarray(res.pressure)[-1]
    r, w = _rule(30.0, 240)
    ds = history_stresses(res, -1, r, [0.3, 0.7, 1.0], measures=False)
    if geometry == "sphere":
        load = math.pi * np.sum(p * (edges[:, 1] ** 2 - edges[:, 0] ** 2))
        force = 2.0 * math.pi * (ds["sigma_zz"].values * r) @ w
    else:
        load = 2.0 * np.sum(p * (edges[:, 1] - edges[:, 0]))  # both halves
        force = 2.0 * ds["sigma_zz"].values @ w
    assert np.abs(force + load).max() < 1e-8 * load  # measured 3e-10


def test_below_the_layer_is_nan_and_the_attributes_say_so(partial_slip):
    geometry, _, res = partial_slip
    ds = history_stresses(res, -1, [0.0, 0.5], [0.5, 1.0, 1.5])
    assert np.all(np.isnan(ds["sigma_zz"].values[-1]))  # z = 1.5 a_max > h = a_max
    assert np.all(np.isfinite(ds["von_mises"].values[:-1]))
    assert ds.attrs["slab_ratio"] == SLAB


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
@pytest.mark.parametrize("base", ["smooth", "bonded"])
def test_frictionless_peak_is_the_self_similar_solve(geometry, base):
    """Two solvers, one layer: the history's frictionless peak (element tractions, n = 120
    elements over 1.2 a_max, contact radius a to its edge fit) and the self-similar solve
    at the same a/h (nodal tractions, n = 256), compared in the history's units (a_max,
    p0(a_max) = a p0(a)). Below z = 0.25 a_max the element tractions' field is smooth and
    the two agree to 1.0e-3 ... 1.6e-3 p0(a_max) (n = 120; 0.3e-3 ... 1.4e-3 at n = 240,
    8.5e-3 at the coarsest n = 60: first order in the element, a_max/100 here)."""
    res = history(geometry, NU, 0.0, [0, 1], steps=4, n=120, slab_ratio=SLAB, base=base)
    a = float(res.contact_radius[-1])
    x, z = np.linspace(0.0, 1.5, 31), np.linspace(0.25, 1.0, 16)
    ds = history_stresses(res, -1, x, z, measures=False)
    sol = solve(geometry, NU, stick_ratio=0.0, n=256, slab_ratio=a * SLAB, base=base,
                energy=False)
    ref = subsurface_stresses(sol, x / a, z / a, measures=False)
    diff = max(float(np.abs(ds[c].values - a * ref[c].values).max()) for c in ds.data_vars)
    assert diff < 5e-3


@pytest.fixture(scope="module", params=["sphere", "cylinder"])
def coated(request):
    """A cycle's peak on a coating a_max thick on a substrate half as stiff (E2/E1 = 0.5,
    nu2 = 0.2), with partial slip."""
    res = history(request.param, NU, 0.3, [0, 1], steps=4, n=60, slab_ratio=SLAB,
                  base="elastic", substrate_modulus=0.5, substrate_nu=0.2)
    assert 0 < res.stick_ratio[-1] < 1 and res.converged[-1]
    return request.param, res


def test_coated_step_interface_and_attributes(coated):
    """At the interface z = h the tractions sigma_zz and sigma_rz (sigma_xz) are continuous
    (layer side against substrate side, h -+ 1e-9), while the surface keeps the step's
    tractions; the dataset names the substrate."""
    geometry, res = coated
    shear = "sigma_rz" if geometry == "sphere" else "sigma_xz"
    x = np.linspace(0.0, 2.0, 21)
    h = 1.0 / SLAB
    ds = history_stresses(res, -1, x, [0.0, h - 1e-9, h + 1e-9, 2.0 * h], measures=False)
    for name in ("sigma_zz", shear):
        v = ds[name].values
        assert np.abs(v[1] - v[2]).max() < 1e-7 * np.abs(v[1]).max()
        assert np.all(np.isfinite(v[3]))  # the substrate's field below the coating
    mid = np.asarray(res.xi)[::7]
    top = history_stresses(res, -1, mid, [0.0], measures=False)
    assert np.abs(top["sigma_zz"].values[0] + np.asarray(res.pressure)[-1][::7]).max() < 1e-12
    assert (ds.attrs["base"], ds.attrs["substrate_modulus"],
            ds.attrs["substrate_poisson_ratio"]) == ("elastic", 0.5, 0.2)


def test_coated_step_force_across_planes(coated):
    """The force across planes in the coating and in the substrate is the step's load. The
    coated far field decays algebraically (the substrate is a half-space), so the plane
    integral to R has a tail: the result at R = 64 and 128 a_max is extrapolated with the
    R^-3 (sphere) or R^-2 (cylinder) tail of a point load at depth z."""
    geometry, res = coated
    edges = np.asarray(res.xi_bounds)
    p = np.asarray(res.pressure)[-1]
    if geometry == "sphere":
        load = math.pi * np.sum(p * (edges[:, 1] ** 2 - edges[:, 0] ** 2))
    else:
        load = 2.0 * np.sum(p * (edges[:, 1] - edges[:, 0]))
    z = [0.5, 1.5, 3.0]
    forces = []
    for big in (64.0, 128.0):
        grid = np.concatenate([np.linspace(0.0, 4.0, 41), np.geomspace(4.0, big, 60)[1:]])
        t, w = np.polynomial.legendre.leggauss(16)
        half = 0.5 * np.diff(grid)
        r = ((0.5 * (grid[:-1] + grid[1:]))[:, None] + half[:, None] * t).ravel()
        wr = (half[:, None] * w).ravel()
        ds = history_stresses(res, -1, r, z, measures=False)
        forces.append(2.0 * math.pi * (ds["sigma_zz"].values * r) @ wr if geometry == "sphere"
                      else 2.0 * ds["sigma_zz"].values @ wr)
    order = 3.0 if geometry == "sphere" else 2.0
    limit = (2.0**order * forces[1] - forces[0]) / (2.0**order - 1.0)
    assert np.abs(limit + load).max() < 1e-4 * load  # measured 1.3e-6, 2.2e-5 (cylinder)


def test_equal_substrate_is_the_half_space_field():
    """A coating on a substrate of its own material is a half-space: the field of the
    step's tractions through the coated route equals the half-space route's."""
    res = history("sphere", NU, 0.3, [0, 1], steps=4, n=40, slab_ratio=SLAB, base="elastic",
                  substrate_modulus=1.0, substrate_nu=NU)
    x, z = np.linspace(0.0, 2.0, 11), np.array([0.2, 0.8, 1.5, 3.0])
    coated_field = history_stresses(res, -1, x, z, measures=False)
    ref = history_stresses(replace(res, slab_ratio=0.0), -1, x, z, measures=False)
    assert coated_field.attrs["base"] == "elastic" and "base" not in ref.attrs
    for name in ref.data_vars:  # measured 9e-10 (the coated k quadrature)
        assert np.abs(coated_field[name].values - ref[name].values).max() < 1e-8, name
