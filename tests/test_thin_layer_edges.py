"""Closed-form disc-radius integrals of the thin-layer sums (contactlib.kernels.thin_layer).

An element's Gauss rule over the disc radius is replaced by the exact integral
``int_a^b s^p J_p(s t) ds`` (:func:`thin_layer.disc_integrals`). Checked here:
the antiderivatives against mpmath (independent: Struve functions at 40 digits),
the element sums against the direct Gauss sums (the rule evaluated point by
point, WIDE_ELEMENT = inf) on a graded mesh to a/h = 300 (elements 1e-9 h ... 4 h), and one
element's integral against scipy's quad of the transform integral.
"""

from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest
from scipy import integrate, special

from contactlib.kernels import layer, thin_layer

NU = 0.25


def _exact(order: int, x: float) -> float:
    """int_0^x y^p J_p(y) dy from int_0^x J0 = x J0 + (pi x/2)(J1 H0 - J0 H1), 40 digits."""
    with mp.workdps(40):
        xm = mp.mpf(x)
        j0, j1 = mp.besselj(0, xm), mp.besselj(1, xm)
        int_j0 = xm * j0 + mp.pi * xm / 2 * (j1 * mp.struveh(0, xm) - j0 * mp.struveh(1, xm))
        g1 = int_j0 - xm * j0
        return float(g1 if order == 1 else 3 * g1 - xm * xm * j1)


@pytest.mark.parametrize("order", [1, 2])
def test_disc_integrals_against_mpmath(order):
    """Every branch and both hand-overs (x = 4, 60): 2e-14 of the scale x^(p - 1/2), beside
    what scipy's own J0(x), J1(x) carry in (x J0 and x^2 J1: measured 1.5e-13 at x = 4000)."""
    xs = np.array([1e-6, 0.3, 2.0, 3.999, 4.001, 9.0, 25.0, 59.99, 60.01, 97.3, 512.0, 4000.5])
    got = thin_layer.disc_integrals(order, xs)
    for x, value in zip(xs, got):
        truth = _exact(order, x)
        scale = abs(truth) if x < 4.0 else x ** (order - 0.5)
        d0 = abs(special.j0(x) - float(mp.besselj(0, x)))
        d1 = abs(special.j1(x) - float(mp.besselj(1, x)))
        carried = 3.0 * x * d0 + (3.0 * x + x * x) * d1
        assert abs(value - truth) <= 2e-14 * scale + carried, (x, value, truth)


def _mesh_rule(edges: np.ndarray, h: float = 1.0):
    """As contactlib.discretization.operators.smooth_integrals: 8 Gauss points on panels of at most h/2."""
    lo, length = edges[:-1], np.diff(edges)
    panels = np.maximum(1, np.ceil(length / (0.5 * h))).astype(np.intp)
    owner = np.repeat(np.arange(lo.size), panels)
    k = np.arange(owner.size) - (np.cumsum(panels) - panels)[owner]
    plen = length[owner] / panels[owner]
    g, w = np.polynomial.legendre.leggauss(8)
    s = (lo[owner] + plen * k)[:, None] + plen[:, None] * (0.5 * (g + 1.0))[None, :]
    return s.ravel(), (0.5 * plen[:, None] * w[None, :]).ravel(), np.repeat(owner, 8)


@pytest.mark.parametrize("base", ["bonded", "smooth", layer.Substrate(0.525, 0.3)])
@pytest.mark.parametrize("kind", ["pressure", "shear"])
def test_element_sums_equal_the_direct_sums(monkeypatch, base, kind):
    """Wide elements in closed form, narrow ones (to 1e-9 h) by their points: measured 5e-14."""
    edges = np.r_[np.linspace(0.0, 300.0, 80), 300.0 + np.cumsum(np.geomspace(1e-9, 4.0, 30))]
    rho = np.r_[edges[::7], 37.3]
    s, w, owner = _mesh_rule(edges)
    new = thin_layer.remainders(kind, rho, s, NU, base, w, owner)
    wide = thin_layer._closed_elements(s, w, np.flatnonzero(np.r_[True, np.diff(owner)]))[0]
    assert 70 < wide.sum() < wide.size  # both kinds of element present
    monkeypatch.setattr(thin_layer, "WIDE_ELEMENT", np.inf)
    direct = thin_layer.remainders(kind, rho, s, NU, base, w, owner)
    scale = np.abs(direct).max(axis=(1, 2))[:, None, None]
    assert np.all(np.abs(new - direct) < 1e-12 * scale)


@pytest.mark.filterwarnings("ignore::scipy.integrate.IntegrationWarning")  # (round-off notes)
def test_element_integral_against_quad():
    """One element's Pw integral: int_a^b 2 s int R J1(s t) J0(r t) dt/t ds by scipy's quad."""
    a, b, r = 300.0, 302.5, 301.0
    s, w, owner = _mesh_rule(np.array([a, b]))
    got = thin_layer.remainders("pressure", [r], s, NU, "bonded", w, owner)[0, 0, 0]

    def inner(t):  # int_a^b s J1(s t) ds in closed form by another route: Struve-free
        return integrate.quad(lambda x: x * special.j1(x * t), a, b, limit=200)[0]

    def integrand(t):
        rww = layer.remainder_transfer(np.array([t]), NU, "bonded")[0][0]
        return 2.0 * rww * special.j0(r * t) * inner(t) / t

    pts = np.linspace(0.0, thin_layer.T_MAX, 721)
    truth = sum(integrate.quad(integrand, lo, hi, epsabs=1e-15, epsrel=1e-12)[0]
                for lo, hi in zip(pts[:-1], pts[1:]))
    assert abs(got - truth) < 1e-10 * abs(truth)


def test_rules_that_are_not_one_interval_stay_direct():
    """Random weights (no Gauss rule): every group summed point by point."""
    rng = np.random.default_rng(4)
    s = np.sort(rng.uniform(0.0, 50.0, 40))
    w = rng.random(40)
    starts = np.arange(0, 40, 4)
    assert not thin_layer._closed_elements(s, w, starts)[0].any()
