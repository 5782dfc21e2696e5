"""Thin incompressible layer bonded to a rigid base, frictionless rigid indenter.

Truth, not computed with the code under test: the leading-order thin-layer
(squeeze-film) asymptotics of an incompressible layer (nu = 1/2, shear
modulus G = E*/4) bonded to a rigid base with a frictionless top
(derived in docs/theory.md#thin-layer-limits; no published statement of the
frictionless-surface case could be checked, see there). The
layer's radial displacement is parabolic across the thickness, volume is
conserved, so (h^3 / 3G) lap p = -w with p = dp/dr = 0 at the contact edge:

* sphere: p = 3 G (a^2 - r^2)^2 / (32 R h^3), P = pi G a^6 / (32 R h^3),
  P / P_Hertz = (3 pi / 512) (a/h)^3;
* cylinder (plane strain): p = G (a^2 - x^2)^2 / (8 R h^3),
  P = 2 G a^5 / (15 R h^3) per unit length, P / P_Hertz = (2 / (15 pi)) (a/h)^3.

The layer's load lies above the leading term by a relative O(h/a): measured,
it is the leading term with the contact radius widened by beta h,
beta = 1.45 for both geometries (an edge zone of width ~h, where the
pressure leaves the (1 - r^2/a^2)^2 profile). Numbers in docs/validation.md.

Under a no-slip indenter the top is bonded too: the flux is -h^3 p'/(12 G)
instead of -h^3 p'/(3 G), so the same deflection needs four times the
pressure, and the no-slip load over the frictionless one at the same contact
radius tends to 4 as a/h grows, at first order in h/a. On a half-space nu = 1/2
decouples (Dundurs' beta = 0); on a layer it does not.
"""

from __future__ import annotations

import numpy as np
import pytest

import contactlib
from contactlib.kernels import disc, layer
from contactlib.model import contact

NU = 0.5  # incompressible: the kernels accept nu = 1/2 (validate.nu: (-1, 0.5])


def _leading_load_ratio(geometry: str, a_over_h: float) -> float:
    """P/P_Hertz of the thin incompressible bonded layer's leading term (E* = a = R = 1)."""
    if geometry == "sphere":  # pi (E*/4) a^6/(32 R h^3) over 4 E* a^3/(3 R)
        return 3.0 * np.pi / 512.0 * a_over_h ** 3
    return 2.0 / (15.0 * np.pi) * a_over_h ** 3  # 2 (E*/4) a^5/(15 R h^3) over pi E* a^2/(4 R)


CASES = {"sphere": ((5.0, 10.0, 20.0), 256, 6),  # ratios, n, power of a in P
         "cylinder": ((10.0, 30.0, 100.0), 1024, 5)}


def _frictionless(geometry, ratio, n):
    sol = contactlib.solve(geometry, NU, stick_ratio=0.0, n=n, slab_ratio=ratio, base="bonded",
                           energy=False)
    assert sol.resolved
    assert np.all(np.asarray(sol.shear) == 0.0)  # stick_ratio = 0: frictionless
    return sol


@pytest.mark.parametrize("geometry", ["sphere", pytest.param("cylinder", marks=pytest.mark.slow)])
def test_load_tends_to_the_thin_incompressible_asymptote(geometry):
    """P/P_asymptote - 1 falls with h/a; it is the asymptote with a widened by 1.45 h.

    Measured (load error estimates <= 1.7e-5 sphere, 3.4e-5 cylinder):
    sphere 3.32, 1.23, 0.522 at a/h = 5, 10, 20 (beta = 1.38, 1.43, 1.45);
    cylinder 0.960, 0.2675, 0.0751 at a/h = 10, 30, 100 (beta = 1.441, 1.457, 1.458).
    """
    ratios, n, power = CASES[geometry]
    dep = []
    for r in ratios:
        sol = _frictionless(geometry, r, n)
        assert sol.load_error_estimate < 1e-4
        dep.append(sol.load_ratio / _leading_load_ratio(geometry, r) - 1.0)
    dep = np.array(dep)
    ratios = np.array(ratios)
    assert np.all(dep > 0)  # the edge zone adds load
    assert np.all(dep[1:] / dep[:-1] < 0.5)  # falls at least as fast as h/a
    beta = ratios * ((1.0 + dep) ** (1.0 / power) - 1.0)  # (1 + beta h/a)^power = 1 + dep
    assert np.all((beta > 1.35) & (beta < 1.5))
    assert abs(beta[-1] - beta[-2]) < 0.02  # a first-order edge correction in h/a


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_pressure_tends_to_the_squeeze_profile(geometry):
    """max |p/p(0) - (1 - r^2/a^2)^2| over the contact falls with h/a.

    Measured: sphere 0.185, 0.116, 0.065 at a/h = 5, 10, 20; cylinder 0.113,
    0.045, 0.0145 at a/h = 10, 30, 100.
    """
    ratios, n, _ = CASES[geometry]
    gaps = []
    for r in ratios:
        # (cylinder, a/h = 100: n = 256 leaves the load 2e-3 off, estimate 3.9e-3)
        sol = _frictionless(geometry, r, min(n, 256 if geometry == "sphere" else 512))
        x, p = np.asarray(sol.xi), np.asarray(sol.pressure)
        inside = x < 1.0
        gaps.append(np.max(np.abs(p[inside] / p[0] - (1.0 - x[inside] ** 2) ** 2)))
    gaps = np.array(gaps)
    assert np.all(np.diff(gaps) < 0)
    assert gaps[-1] < (0.07 if geometry == "sphere" else 0.02)


@pytest.mark.parametrize("base", ["smooth", "bonded"])
def test_a_layer_at_nu_one_half_is_coupled(base):
    x, s = np.array([0.3, 0.8, 1.5]), np.ones(3)
    u_layer = layer.pressure_disc(x, s, 0.5, 1.0, base)[1]
    u_half = disc.pressure_disc(x, s, 0.5)[1]
    assert np.all(np.abs(u_layer) > 0.05) and np.all(u_half == 0.0)
    for geometry in ("sphere", "cylinder"):
        assert contact(geometry, 0.5).decoupled
        assert not contact(geometry, 0.5, 1.0, base=base).decoupled


def _load_ratio(geometry, slab, stick_ratio):
    sol = contactlib.solve(geometry, NU, stick_ratio=stick_ratio, slab_ratio=slab,
                           base="bonded", energy=False)
    assert sol.resolved, sol.message
    return sol.load_ratio


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_no_slip_carries_four_times_the_load_on_a_thin_bonded_layer(geometry):
    slabs = np.array([10.0, 20.0, 40.0])
    ratio = np.array([_load_ratio(geometry, s, 1.0) / _load_ratio(geometry, s, 0.0)
                      for s in slabs])
    # measured: 2.527, 3.126, 3.522 (sphere); 2.759, 3.285, 3.614 (cylinder)
    assert np.all(np.diff(ratio) > 0.0) and np.all(ratio < 4.0)
    deficit = 4.0 - ratio
    halving = deficit[:-1] / deficit[1:]  # first order in h/a: 2 per doubling of a/h
    assert np.all((halving > 1.6) & (halving < 2.2))  # measured 1.69 ... 1.83
    first = 2.0 * ratio[1:] - ratio[:-1]  # Richardson at first order
    second = (4.0 * first[1] - first[0]) / 3.0
    assert abs(first[1] - 4.0) < abs(first[0] - 4.0)
    assert abs(second - 4.0) < 0.03  # measured 3.983 (sphere), 3.988 (cylinder)


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_a_thick_incompressible_layer_is_nearly_the_decoupled_half_space(geometry):
    ratio = _load_ratio(geometry, 0.3, 1.0) / _load_ratio(geometry, 0.3, 0.0)
    assert 1.0 < ratio < 1.0 + 2e-3  # measured 1 + 5e-5 (sphere), 1 + 1.0e-3 (cylinder)


def test_partial_slip_on_an_incompressible_layer_runs_outward():
    sol = contactlib.solve("sphere", 0.5, stick_ratio=0.5, slab_ratio=10.0, base="bonded",
                           energy=False)
    assert sol.resolved and sol.friction_coefficient > 0.0
    assert "outward" in sol.message and "own coupling" in sol.message
    # the friction that gives this stick ratio is not the decoupled answer k = 0
    lone = contactlib.solve("sphere", 0.5, friction=sol.friction_coefficient,
                            slab_ratio=10.0, base="bonded", energy=False)
    assert abs(lone.stick_ratio - 0.5) < 1e-3


def test_history_on_an_incompressible_layer_balances_its_energy():
    r = contactlib.history("sphere", 0.5, 0.3, [0, 1, 0], 40, n=120, slab_ratio=10.0,
                           base="bonded")
    assert r.converged.all()
    assert np.nanmax(np.abs(r.shear)) > 0.0 and r.frictional_work[-1] > 0.0
    assert np.all(np.diff(r.frictional_work) >= 0.0)
    balance = r.external_work[-1] - r.frictional_work[-1] - r.stored_energy[-1]
    assert abs(balance) < 1e-4 * np.max(r.external_work)
