"""Thin coatings under a cylinder (plane strain, a/h up to 1000 on an elastic substrate).

Beyond |x +- s|/h = 48 (the coated strip tables) the kernels use log-spaced tables of the
remainders' smooth parts (contactlib.kernels.strip, "Coated body"). Truths, none computed
with the code under test:

* the line-load slopes A, B, C by scipy's QAWO quadrature of their Fourier integrals, the
  transfer functions by the Love 6x6 solve of tests/test_coatings.py;
* the coated strip tables at |eta| <= 48 (continuity at the join);
* equal materials (E2/E1 = 1, nu2 = nu): the half-plane;
* a very stiff substrate: the bonded rigid base, departing at first order in E1/E2;
* a thin stiff coating: the substrate's half-plane (load ratio 1/m), departing like h/a;
* a thin soft coating on a very hard substrate: Winkler's bonded thin layer;
* convergence in n against the fourfold refinement, and the error estimates covering it.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import integrate, special
from test_coatings import love_coated

import contactlib
from contactlib import estimates, validate
from contactlib.discretization.elements import graded_mesh
from contactlib.kernels import strip
from contactlib.kernels.layer import Substrate

NU = 0.3
T_END, T_START = 30.0, 1e-5  # the remainders are < 1e-20 beyond T_END; below T_START by
# a 6-point Gauss rule


def _m(nu, modulus, nu2):
    return (1 - nu2**2) / ((1 - nu**2) * modulus)


def _head(f):
    """int_0^T_START f dt by 6-point Gauss-Legendre."""
    x, w = np.polynomial.legendre.leggauss(6)
    return 0.5 * T_START * sum(wi * f(0.5 * T_START * (xi + 1)) for xi, wi in zip(x, w))


def _slopes_by_quadrature(eta, nu, modulus, nu2):
    """(A, B, C)(eta) of the module notes by QAWO, the growth split off analytically:
    A = (2/pi)[int (Rww - R0)/t cos(t eta) dt - R0 ln eta], B = -(2/pi)[int (Rwu -
    Rwu0)/t sin(t eta) dt + Rwu0 pi/2], C = (2/pi)[int g (cos(t eta) - 1) dt - (R0/2)
    ln(1 + eta^2/4)], g = (Ruu - R0 exp(-2t))/t; tails beyond T_END by Si and Ci."""
    beta = (1 - 2 * nu) / (2 * (1 - nu))
    m = _m(nu, modulus, nu2)
    r0, rwu0 = m - 1, m * (1 - 2 * nu2) / (2 * (1 - nu2)) - beta

    def rem(t):
        c = love_coated(t, nu, modulus, nu2)
        return c[0] - 1, c[1] - beta, c[2] - 1

    def q(f, weight):
        head = _head(lambda t: f(t) * (np.cos(t * eta) if weight == "cos" else np.sin(t * eta)))
        return head + integrate.quad(f, T_START, T_END, weight=weight, wvar=eta, limit=2000,
                                     epsabs=1e-13, epsrel=1e-12)[0]

    si, ci = special.sici(T_END * eta)
    a = (2 / np.pi) * (q(lambda t: (rem(t)[0] - r0) / t, "cos") + r0 * ci - r0 * np.log(eta))
    b = -(2 / np.pi) * (q(lambda t: (rem(t)[1] - rwu0) / t, "sin") + rwu0 * si)

    def g(t):
        return (rem(t)[2] - r0 * np.exp(-2 * t)) / t

    plain = integrate.quad(g, T_START, T_END, points=[1e-3, 1e-2, 0.1, 0.3, 1.0, 3.0],
                           limit=800, epsabs=1e-14)[0] + _head(g)
    c = (2 / np.pi) * (q(g, "cos") - plain - 0.5 * r0 * np.log1p(eta**2 / 4))
    return a, b, c


@pytest.mark.parametrize("modulus, nu2", [(0.01, 0.3), pytest.param(0.1, 0.2, marks=pytest.mark.slow),
                                          pytest.param(10.0, 0.3, marks=pytest.mark.slow),
                                          (1e3, 0.45)])
@pytest.mark.filterwarnings("ignore::scipy.integrate.IntegrationWarning")
def test_far_slopes_against_fourier_quadrature(modulus, nu2):
    """Measured: within 2e-11 of max(1, m) (E2/E1 = 0.01 ... 1e3, eta to 3000, both signs)."""
    tab = strip._coated_table(NU, Substrate(modulus, nu2))
    scale = max(1.0, _m(NU, modulus, nu2))
    for eta in (61.3, 777.7, 2999.1):
        a, b, c = _slopes_by_quadrature(eta, NU, modulus, nu2)
        for sign in (1.0, -1.0):
            e = np.array([sign * eta])
            _, _, got_a, got_b = strip._coated_far_pair("pressure", e, tab, False)
            _, _, got_c, _ = strip._coated_far_pair("shear", e, tab, False)
            assert abs(got_a[0] - a) < 1e-9 * scale  # A, C even; B odd
            assert abs(got_b[0] - sign * b) < 1e-9 * scale
            assert abs(got_c[0] - c) < 1e-9 * scale


@pytest.mark.parametrize("modulus", [0.01, 10.0])
def test_far_values_continue_the_tables_at_48(modulus):
    """The strip kernels across |x + s|/h = 48 (table inside, far tables outside): the
    jump is that of the step (measured <= 2e-11 of scale)."""
    sub = Substrate(modulus, 0.2)
    h, s = 0.01, 0.3
    x = 48 * h - s + np.array([-1e-12, 1e-12])
    scale = max(1.0, _m(NU, modulus, 0.2)) * s
    for fn in (strip.pressure_strip, strip.shear_strip):
        w, u, _ = fn(x, s, NU, h, sub)
        hw, hu, _ = fn(x, s, NU)
        assert abs(np.diff(w - hw)[0]) < 1e-10 * scale
        assert abs(np.diff(u - hu)[0]) < 1e-10 * scale


def test_all_far_form_equals_the_sum_form():
    """Where every |eta| > 48 the kernel is the substrate's half-plane plus differences of
    smooth parts; the plain sum (half-plane + remainders with their growth) agrees to the
    round-off of the growth (measured 3e-13 of scale at a/h = 1000)."""
    sub = Substrate(0.1, 0.2)
    tab = strip._coated_table(NU, sub)
    h = 1e-3
    x, s = np.array([0.3, 0.9, -0.7]), np.array([0.2, 0.5, 0.1])
    for kind, hp, slab in (("pressure", strip._hp_pressure, strip._slab_pressure),
                           ("shear", strip._hp_shear, strip._slab_shear)):
        w, u, du = hp(x, s, strip._beta(NU))
        far = slab(x, s, h, tab, w, u, du)
        assert far.all()
        fw, fu, fdu = strip._coated_all_far(kind, x, s, h, tab)
        scale = _m(NU, 0.1, 0.2) * s
        assert np.all(np.abs(fw - w) < 1e-11 * scale)
        assert np.all(np.abs(fu - u) < 1e-11 * scale)
        assert np.all(np.abs(fdu - du) < 1e-11 * _m(NU, 0.1, 0.2))


def _kc(c, n=128, **kw):
    return contactlib.solve("cylinder", NU, stick_ratio=c, n=n, energy=False, **kw)


def test_equal_materials_are_the_half_plane_at_a_over_h_1000():
    """Kernels: zero remainder (< 1e-13 of scale); solve at c/a = 0.5: load and k equal to
    the half-plane's (measured 1.9e-12 and 5.7e-11)."""
    sub = Substrate(1.0, NU)
    x = np.linspace(-1.0, 1.0, 8)  # (not 0 nor +-s: the shear du is infinite there)
    for fn in (strip.pressure_strip, strip.shear_strip):
        got, ref = np.array(fn(x, 0.7, NU, 1e-3, sub)), np.array(fn(x, 0.7, NU))
        assert np.abs(got - ref).max() < 1e-13
    half = _kc(0.5)
    eq = _kc(0.5, slab_ratio=1000.0, base="elastic", substrate_modulus=1.0, substrate_nu=NU)
    assert abs(eq.load_ratio / half.load_ratio - 1) < 1e-10
    assert abs(eq.friction_coefficient / half.friction_coefficient - 1) < 1e-9


def test_stiff_substrate_tends_to_the_bonded_base_at_first_order():
    """a/h = 300, frictionless: load departure x E2/E1 measured -257.7, -338.3, -349.2,
    -350.3 at E2/E1 = 1e3, 1e4, 1e5, 1e6 (first order; the coefficient grows with a/h: the
    thin layer's stiffness M/h against the substrate's)."""
    bonded = _kc(0.0, slab_ratio=300.0, base="bonded").load_ratio
    mods = np.array([1e5, 1e6])
    dep = np.array([_kc(0.0, slab_ratio=300.0, base="elastic", substrate_modulus=e,
                        substrate_nu=NU).load_ratio / bonded - 1 for e in mods])
    scaled = dep * mods
    np.testing.assert_allclose(scaled, scaled[-1], rtol=0.01)
    assert abs(dep[-1]) < 1e-3  # -> 0 like E1/E2


def test_thin_stiff_coating_tends_to_the_substrate_half_plane():
    """E2/E1 = 0.5, frictionless: (load ratio x m / half-plane's - 1) x a/h measured 1.145,
    1.416, 1.669, 1.948 at a/h = 30, 100, 300, 1000: first order in h/a up to a logarithm
    (slope in ln(a/h) 0.225, 0.230, 0.232 between neighbours), as the sphere's."""
    m = _m(NU, 0.5, NU)
    half = _kc(0.0).load_ratio
    ratios = np.array([30.0, 100.0, 300.0, 1000.0])
    scaled = np.array([(_kc(0.0, slab_ratio=r, base="elastic", substrate_modulus=0.5,
                            substrate_nu=NU).load_ratio * m / half - 1) * r for r in ratios])
    assert np.all((scaled > 1.0) & (scaled < 2.2))  # departure ~ h/a: -> 0 as h/a -> 0
    slopes = np.diff(scaled) / np.diff(np.log(ratios))
    np.testing.assert_allclose(slopes, slopes.mean(), rtol=0.05)


def test_thin_soft_coating_on_a_hard_substrate_is_winkler_at_a_over_h_1000():
    """Frictionless, a/h = 1000: load over Winkler's 8 M a/(3 pi E* h) - 1 measured -0.104,
    -0.0112, -8.5e-4 at E2/E1 = 1e4, 1e5, 1e6, tending to the bonded base's +3.2e-4 at
    first order in E1/E2 (x E2/E1: -1156, -1168): Winkler needs E2/E1 >> a/h."""
    e_star, ratio = 1.0, 1000.0
    g = (1 - NU**2) / (2 * (1 + NU))
    winkler = 8 * (2 * g * (1 - NU) / (1 - 2 * NU)) * ratio / (3 * np.pi * e_star)
    bonded = _kc(0.0, slab_ratio=ratio, base="bonded").load_ratio / winkler - 1
    assert abs(bonded) < 1e-3
    mods = np.array([1e5, 1e6])
    dep = np.array([_kc(0.0, slab_ratio=ratio, base="elastic", substrate_modulus=e,
                        substrate_nu=NU).load_ratio / winkler - 1 for e in mods])
    np.testing.assert_allclose((dep - bonded) * mods, (dep[-1] - bonded) * mods[-1], rtol=0.02)
    assert abs(dep[-1]) < 1e-3


@pytest.mark.slow
@pytest.mark.parametrize("ratio, modulus", [(100.0, 0.1), (1000.0, 0.1), (1000.0, 10.0),
                                            (1000.0, 0.01), (1000.0, 1e3)])
def test_estimates_cover_the_fourfold_refinement_at_a_over_h_100_and_1000(ratio, modulus):
    """c/a = 0.5, nu2 = 0.2: the estimates of k and of the load at n = 64, 128, 256 against
    the truth |v(n)/v(4n) - 1|. |k(n)/k(4n) - 1| measured 1.1e-4, 1.9e-5, 5.4e-6 (a/h = 100,
    E2/E1 = 0.1), 1.9e-4, 9.6e-5, 5.7e-6 (1000, 0.1), 2.7e-4, 5.0e-5, 5.2e-6 (1000, 10),
    7.9e-4, 2.7e-4, 1.6e-5 (1000, 0.01), 8.1e-4, 1.9e-4, 4.4e-5 (1000, 1e3). Richardson on
    the nested levels alone covered it 0.59x (k, (100, 0.1), n = 256), 0.11x (k, (1000, 0.01),
    n = 64), 0.25x (load, (1000, 1e3), n = 128): the levels had not reached their
    asymptotic order (contactlib.estimates.coated_estimate). Now 1.34x ... 32x (k) and
    1.25x ... 16x (load); within 3x where the coarsest level's edge element is below 2h
    (a/h = 100, n = 128 and 256: 2.50x, 1.36x k, 1.73x, 1.54x load; python
    benchmarks/report_coated_estimates.py)."""
    sols = {n: _kc(0.5, n, slab_ratio=ratio, base="elastic", substrate_modulus=modulus,
                   substrate_nu=0.2) for n in (64, 128, 256, 512, 1024)}
    diffs = [abs(sols[n].friction_coefficient / sols[4 * n].friction_coefficient - 1)
             for n in (64, 128, 256)]
    assert diffs[0] > diffs[1] > diffs[2] and diffs[2] < 5e-5
    for n in (64, 128, 256):
        edge = estimates.edge_zone_resolved(graded_mesh(n // 4, 0.5).nodes, 1.0 / ratio)
        for est, attr in ((sols[n].error_estimate, "friction_coefficient"),
                          (sols[n].load_error_estimate, "load_ratio")):
            true = abs(getattr(sols[n], attr) / getattr(sols[4 * n], attr) - 1)
            assert est >= true, (n, attr, est / true)
            if edge:
                assert est <= 3.0 * true, (n, attr, est / true)
    assert all(sols[n].resolved for n in (256, 512, 1024))


def test_coated_estimate_covers_a_sequence_of_the_lowest_measured_order():
    """v(n) = 1 + n^-p exactly (the truth: v = 1). Past the edge zone the estimate covers
    the error of v(n) down to p = COATED_ORDER (equal there), where Richardson with the
    order observed at p = 2.5 would take d2/4.66; before it, a stall (differences 1e-3,
    1e-3, and two more) is covered."""
    for p in (estimates.COATED_ORDER, 2.0, 2.5):
        v = [1.0 + (64.0 / 4) ** -p, 1.0 + (64.0 / 2) ** -p, 1.0 + 64.0**-p]
        est = estimates.coated_estimate(*v, True) * v[-1]
        assert est >= 64.0**-p * (1 - 1e-12)
    stall = [1.0 + 2e-3, 1.0 + 1e-3, 1.0]  # differences 1e-3, 1e-3, then 1e-3, 1e-3 more
    assert estimates.coated_estimate(*stall, False) >= 2e-3 - 1e-15
    assert estimates.coated_estimate(*stall, True) < estimates.coated_estimate(*stall, False)


def test_edge_zone_resolved_compares_the_edge_element_with_the_thickness():
    """graded_mesh(n, 0.5)'s edge element: 5.2e-3 at n = 64, 1.5e-3 at 128, 3.9e-4 at 256;
    resolved below twice the thickness."""
    assert estimates.EDGE_ELEMENT_OVER_THICKNESS == 2.0
    for n, h_ok, h_not in ((64, 3e-3, 2e-3), (128, 1e-3, 5e-4), (256, 2.5e-4, 1e-4)):
        nodes = graded_mesh(n, 0.5).nodes
        assert estimates.edge_zone_resolved(nodes, h_ok)
        assert not estimates.edge_zone_resolved(nodes, h_not)


def test_beyond_1000_is_refused_naming_the_range():
    assert validate.LAYER_RATIO_MAX[("cylinder", "elastic")] == 1000.0
    with pytest.raises(validate.InputError, match="slab_ratio.*<= 1000"):
        _kc(0.5, slab_ratio=1001.0, base="elastic", substrate_modulus=0.5, substrate_nu=NU)
    with pytest.raises(ValueError, match="3072"):
        strip.pressure_strip(0.0, 4.0, NU, 1e-3, Substrate(0.5, NU))
