"""Stresses in a coated body: an elastic layer bonded to an elastic half-space (sphere) or
half-plane (cylinder) (stresses.layer_stresses with base "elastic", issues 38 and 39).

Independent truths: the coated surface transfer functions of
contactlib.kernels.layer_transfer (a separate solution, Airy functions), the half-space's
closed forms and Boussinesq's point-load integral when the two materials are equal, the
bonded rigid base as E2/E1 -> inf, the interface conditions (sigma_zz, sigma_rz and the
tangential strains continuous: the jump of sigma_rr is Hooke's), the force across every
plane z = const (extrapolated in the radius of the plane's disc) and convergence of a
solved case under mesh refinement with its error estimate.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_stresses_layer import _load  # 2 pi int p r dr of piecewise-linear p, exactly

from contactlib import solve
from contactlib.kernels.layer_transfer import Substrate, transfer
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
XI = np.linspace(0.0, 1.0, 101)
HERTZ = np.sqrt(1.0 - XI**2)
SHEAR = 0.3 * XI * HERTZ  # zero on the axis (a radial shear there makes sigma_rr infinite)
SUBSTRATES = [(0.25, 0.2), (4.0, 0.45)]  # (E2/E1, nu2): a soft and a stiff substrate


@pytest.mark.parametrize("substrate", [(1.0, NU), (0.01, 0.45), (0.25, 0.2), (4.0, 0.45),
                                       (1e6, 0.0)])
@pytest.mark.parametrize("nu", [0.0, 0.3, 0.5])
def test_surface_of_the_interior_solution_is_the_coated_kernel(substrate, nu):
    t = np.array([1e-3, 0.1, 0.5, 1.0, 2.0, 5.0, 10.0, 30.0, 60.0])
    base = Substrate(*substrate)
    ours = np.array(surface_transfer(t, nu, base))
    theirs = np.array(transfer(t, nu, base))
    # relative to max(1, |C|): a soft substrate's Cww ~ E1*/E2* = 92 at small t
    assert (np.abs(ours - theirs) / np.maximum(1.0, np.abs(theirs))).max() < 1e-12


def _boussinesq_axis_zz(z: float) -> float:
    """sigma_zz on the axis of a half-space under the tabulated pressure (piecewise
    linear on XI): -int 3 p(r) z^3 r / (r^2 + z^2)^(5/2) dr, Gauss on every piece."""
    t, w = np.polynomial.legendre.leggauss(20)
    a, b = XI[:-1], XI[1:]
    r = 0.5 * (a + b)[:, None] + 0.5 * (b - a)[:, None] * t
    p = np.interp(r, XI, HERTZ)
    return float(-np.sum(3.0 * p * z**3 * r / (r * r + z * z) ** 2.5
                         * 0.5 * (b - a)[:, None] * w))


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_equal_materials_are_the_half_space(geometry):
    """E2 = E1, nu2 = nu: the layer's correction and the substrate's modes make up the
    half-space's (half-plane's) field, in the layer and below it."""
    h = 0.5
    x = np.array([0.0, 0.3, 0.9, 1.1, 2.0])
    if geometry == "cylinder":
        x = np.concatenate([-x[:0:-1], x])
    z = np.array([0.0, 0.1, 0.25, 0.5, 0.6, 1.0])
    f = layer_stresses(XI, HERTZ, SHEAR, x, z, NU, h, "elastic", geometry=geometry,
                       substrate=(1.0, NU))
    ref = (halfspace_stresses if geometry == "sphere" else halfplane_stresses)(
        XI, HERTZ, SHEAR, x, z, NU)
    dev = max(np.abs(f[c] - ref[c]).max() for c in f)
    assert dev < 1e-10  # measured 1.5e-11 (sphere), 1.3e-14 (cylinder)
    if geometry == "sphere":  # deeper, on the axis: Boussinesq's integral
        deep = np.array([2.0, 4.0])
        g = layer_stresses(XI, HERTZ, 0.0 * HERTZ, [0.0], deep, NU, h, "elastic",
                           substrate=(1.0, NU))
        want = np.array([_boussinesq_axis_zz(d) for d in deep])
        assert np.abs(g["sigma_zz"][:, 0] - want).max() < 1e-12  # measured 1.1e-14


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_a_rigid_substrate_is_the_bonded_base(geometry):
    """E2/E1 -> inf: the field in the layer tends to the bonded rigid base's, like E1/E2."""
    h = 0.5
    x = np.array([0.0, 0.5, 1.0, 2.0])
    z = np.array([0.0, 0.1, 0.25, 0.5])
    b = layer_stresses(XI, HERTZ, SHEAR, x, z, NU, h, "bonded", geometry=geometry)
    dev = {}
    for m in (1e5, 1e6):
        f = layer_stresses(XI, HERTZ, SHEAR, x, z, NU, h, "elastic", geometry=geometry,
                           substrate=(m, 0.2))
        dev[m] = max(np.abs(f[c] - b[c]).max() for c in f)
    assert dev[1e6] < 1e-6  # measured 4.9e-7 (sphere), 8.0e-7 (cylinder)
    assert dev[1e5] / dev[1e6] == pytest.approx(10.0, rel=0.01)


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
@pytest.mark.parametrize("substrate", SUBSTRATES)
def test_interface_continuity_and_the_hooke_jump(geometry, substrate):
    """At z = h: sigma_zz and sigma_rz continuous, and so the tangential strains (u_r is):
    the jump of sigma_rr (sigma_tt) is the one Hooke's law gives. Evaluated at z = h
    (the layer) and h (1 + 1e-10) (the substrate). On z = 0 the tractions are -p, -q."""
    h, (m, nu2) = 0.5, substrate
    x = np.linspace(0.0, 2.5, 11) if geometry == "sphere" else np.linspace(-2.5, 2.5, 11)
    f = layer_stresses(XI, HERTZ, SHEAR, x, [0.0, h, h * (1 + 1e-10)], NU, h,
                       "elastic", geometry=geometry, substrate=substrate)
    rr, tt, zz, rz = (f[c] for c in f)
    p = np.sqrt(np.clip(1.0 - x**2, 0.0, None))
    assert np.abs(zz[0] + p).max() < 1e-12
    assert np.abs(rz[0] + 0.3 * x * p).max() < 1e-12
    assert np.abs(zz[2] - zz[1]).max() < 1e-10  # measured 2.9e-11
    assert np.abs(rz[2] - rz[1]).max() < 1e-10  # measured 1.3e-11
    assert np.abs(rr[2] - rr[1]).max() > 0.1  # a real jump (0.11 ... 0.55 here)
    if geometry == "sphere":  # E eps_rr = sigma_rr - nu (sigma_tt + sigma_zz), as eps_tt
        for a, b in ((rr, tt), (tt, rr)):
            layer = a[1] - NU * (b[1] + zz[1])
            below = (a[2] - nu2 * (b[2] + zz[2])) / m
            assert np.abs(layer - below).max() < 1e-10  # measured 2.7e-11
    else:  # plane strain: E eps_xx = (1 - nu^2) sigma_xx - nu (1 + nu) sigma_zz
        layer = (1 - NU**2) * rr[1] - NU * (1 + NU) * zz[1]
        below = ((1 - nu2**2) * rr[2] - nu2 * (1 + nu2) * zz[2]) / m
        assert np.abs(layer - below).max() < 1e-10  # measured 4.4e-11
        assert np.abs(tt[2] - nu2 * (rr[2] + zz[2])).max() < 1e-14  # the substrate's nu


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
@pytest.mark.parametrize("h,substrate", [(0.05, (0.01, 0.3)), (1.0, (0.01, 0.45))])
def test_halving_the_k_panels_moves_the_field_by_little(geometry, h, substrate):
    """A stiff coating on a very soft substrate (E2/E1 = 0.01, the fine panels near k = 0
    matter), thin (a/h = 20) and thick (a/h = 1), the grid through layer and substrate:
    halving every panel of the k integral moves the field by < 1e-9 p0 (measured 2.3e-13,
    3.3e-14 thin; 1.9e-12, 5.0e-11 thick, sphere, cylinder; the field reaches 12 p0).
    With the kernels' fine panels unsplit (FINE_SPLIT = 1) the thin cylinder moved 5e-8."""
    x = np.linspace(0.0, 2.0, 11)
    if geometry == "cylinder":
        x = np.concatenate([-x[:0:-1], x])
    z = np.unique(np.concatenate([np.linspace(0.0, 2.0, 11), [h / 2, h]]))
    f, g = (layer_stresses(XI, HERTZ, SHEAR, x, z, NU, h, "elastic", geometry=geometry,
                           substrate=substrate, refine=refine) for refine in (1, 2))
    assert max(np.abs(f[c] - g[c]).max() for c in f) < 1e-9


@pytest.mark.parametrize("geometry,substrate", [("sphere", (0.25, 0.2)),
                                                ("cylinder", (0.25, 0.2)),
                                                ("cylinder", (4.0, 0.45))])
def test_force_across_every_plane_is_the_load(geometry, substrate):
    """The force across z = const (layer and substrate) is the load. The field decays
    algebraically in r (the substrate is elastic), so the disc's force is computed to
    R = 128 and 256 (16-point Gauss on [0, 0.5], [0.5, 1] and octaves) and extrapolated
    with the tail's R^-3 (Boussinesq, Flamant: the residual falls 60 times from R = 64
    to 256)."""
    xi = np.linspace(0.0, 1.0, 21)
    p = np.sqrt(1.0 - xi**2)
    z = np.array([0.3, 0.5, 1.0, 2.0])  # h = 0.5
    t, w = np.polynomial.legendre.leggauss(16)
    if geometry == "sphere":
        load = _load(xi, p)
    else:
        load = float(np.sum(np.diff(xi) * (p[:-1] + p[1:])))  # both halves, exactly
    residual = []
    for octaves in (7, 8):
        e = np.array([0.0, 0.5, 1.0] + [2.0**j for j in range(1, octaves + 1)])
        r = (0.5 * (e[:-1] + e[1:])[:, None] + 0.5 * np.diff(e)[:, None] * t).ravel()
        wr = (0.5 * np.diff(e)[:, None] * w).ravel()
        f = layer_stresses(xi, p, 0.3 * p, r, z, NU, 0.5, "elastic", geometry=geometry,
                           substrate=substrate)
        ring = 2.0 * math.pi * r if geometry == "sphere" else 2.0 * np.ones_like(r)
        residual.append((f["sigma_zz"] * ring) @ wr + load)
    extrapolated = residual[1] + (residual[1] - residual[0]) / 7.0
    assert np.abs(residual[1]).max() < 5e-6 * load  # measured 3.1e-6 (z = 2, sphere)
    # measured 3.5e-8 (sphere, soft), 1.2e-8 (cylinder, soft), 2e-11 (cylinder, stiff)
    assert np.abs(extrapolated).max() < 1e-7 * load


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_a_solved_coated_case_converges_and_its_estimate_covers_the_error(geometry):
    """A solved case on a coating (a/h = 1, E2/E1 = 0.5, nu2 = 0.2, c/a = 0.5): the field
    at n = 128 against n = 512 on a grid through layer and substrate; the estimate (the
    change from n = 64) bounds the grid's largest error of each component and covers the
    error at the maxima of von Mises and Tresca."""
    x, z = np.linspace(0.0, 1.5, 16), np.linspace(0.0, 2.0, 21)
    if geometry == "cylinder":
        x = np.linspace(-1.5, 1.5, 31)
    kw = {"stick_ratio": 0.5, "slab_ratio": 1.0, "base": "elastic", "substrate_modulus": 0.5,
          "substrate_nu": 0.2, "energy": False}
    sol = solve(geometry, NU, n=128, **kw)
    fine = subsurface_stresses(sol, x, z)
    ref = subsurface_stresses(solve(geometry, NU, n=512, **kw), x, z)
    est = field_error_estimate(sol, x, z)
    assert fine.attrs["substrate_modulus"] == 0.5
    assert fine.attrs["substrate_poisson_ratio"] == 0.2 and fine.attrs["base"] == "elastic"
    assert est.attrs["substrate_modulus"] == 0.5 and est.attrs["reference_elements"] == 64
    assert np.all(np.isfinite(fine["von_mises"].values))  # z > h is the substrate
    for name in fine.data_vars:
        true = np.abs(fine[name] - ref[name]).values
        assert true.max() < 1e-2  # measured 3.0e-3 (sphere), 6.5e-3 (cylinder), sigma_rr/xx
        assert est[name].values.max() >= true.max()
    for name in ("von_mises", "tresca"):
        at = np.unravel_index(int(np.argmax(fine[name].values)), fine[name].shape)
        assert est[name].values[at] >= abs(fine[name] - ref[name]).values[at]


def test_coated_requests_and_refusals():
    with pytest.raises(InputError, match="^substrate=.*needed with base 'elastic'"):
        layer_stresses(XI, HERTZ, 0 * HERTZ, [0.0], [0.1], NU, 0.5, "elastic")
    with pytest.raises(InputError, match="^substrate needs base='elastic'"):
        layer_stresses(XI, HERTZ, 0 * HERTZ, [0.0], [0.1], NU, 0.5, "bonded",
                       substrate=(2.0, 0.3))
    with pytest.raises(InputError, match="^substrate must be"):
        layer_stresses(XI, HERTZ, 0 * HERTZ, [0.0], [0.1], NU, 0.5, "elastic",
                       substrate=(-1.0, 0.3))
    # a Substrate and the pair are the same body
    a = layer_stresses(XI, HERTZ, 0 * HERTZ, [0.0, 1.0], [0.1, 0.9], NU, 0.5, "elastic",
                       substrate=Substrate(2.0, 0.3))
    b = layer_stresses(XI, HERTZ, 0 * HERTZ, [0.0, 1.0], [0.1, 0.9], NU, 0.5, "elastic",
                       substrate=(2.0, 0.3))
    assert all(np.array_equal(a[c], b[c]) for c in a)


def test_scene_subsurface_of_a_coated_body_is_the_api_field():
    """A scene's ``subsurface`` output on a coated body (substrate_nu unset: the layer's)."""
    from contactlib import pipeline
    from contactlib.scene import parse_scene

    scene = parse_scene("coated", {
        "geometry": "sphere", "nu": NU, "n": 64, "stick_ratios": [0.5], "slab_ratio": 2.0,
        "base": "elastic", "substrate_modulus": 2.0, "outputs": ["subsurface"],
        "subsurface_grid": {"x": [0.0, 1.5, 7], "z": [0.0, 1.0, 5]}})
    parts = {p: pipeline.influence(scene.influence_spec(), p) for p in scene.parts}
    ds = pipeline.assemble(scene, pipeline.solve(scene, parts["normal"], parts["shear"]))
    sol = solve("sphere", NU, stick_ratio=0.5, n=64, slab_ratio=2.0, base="elastic",
                substrate_modulus=2.0, energy=False)
    ref = subsurface_stresses(sol, np.linspace(0.0, 1.5, 7), np.linspace(0.0, 1.0, 5))
    assert np.all(np.isfinite(ref["von_mises"].values))  # z = 0.75, 1 > h: the substrate
    for name in ("von_mises", "sigma_rr", "sigma_zz", "sigma_rz"):
        value = ds[name].values
        assert np.max(np.abs((value[0] if value.ndim == 3 else value) - ref[name].values)) \
            < 1e-12, name
