"""The stress field under a history step on a layer on a rigid base (history_stresses).

Checked against identities of the layer (the surface tractions, the base's conditions,
the force across every plane) and against an independent solver: at the peak of a
frictionless load path the history's field is the self-similar solve's on the same layer.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from contactlib import history, solve
from contactlib.stresses import history_stresses, subsurface_stresses
from contactlib.validate import InputError

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


def test_a_coated_history_is_refused():
    res = history("cylinder", NU, 0.3, [0, 1], steps=4, n=16, slab_ratio=0.5, base="elastic",
                  substrate_modulus=2.0)
    with pytest.raises(InputError, match="coated body"):
        history_stresses(res, -1, [0.0], [0.1])
