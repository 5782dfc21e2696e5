"""The cylinder on a thin layer on a smooth (frictionless) rigid base, a/h to 500.

Below a/h = 80 Newton started from the half-plane's (uncoupled, inward) k; beyond ~100 that
start, ~100 times the answer and of the wrong sign, took Newton to wrong roots (9 of 11
c/a at a/h = 200 and 1000, nu = 0.3). The kernels were not the cause. Truths, none computed
with the code under test:

* the strip kernels (pressure and shear, w and u) by scipy's QAWF quadrature of their
  Fourier integrals (integrands by mpmath at 40-50 digits), |x +- s|/h up to 3000;
* the thin-layer limit w = p h (E* = 1): the frictionless load over 8 (a/h) / (3 pi),
  departing at first order in h/a;
* k under refinement: the n = 256 estimate covers the difference to n = 1024.
"""

from __future__ import annotations

import math
import warnings

import mpmath as mp
import numpy as np
import pytest
from scipy import integrate

import contactlib
from contactlib import validate
from contactlib.solvers import default_method
from contactlib.kernels import strip

NU = 0.3


def _fw(t: float) -> float:
    """Cww(t)/t^2 - 1/(2t), Cww = (cosh 2t - 1)/D, D = sinh 2t + 2t (smooth base)."""
    if t == 0.0:
        return 0.0
    with mp.workdps(40):
        t = mp.mpf(t)
        return float((mp.cosh(2 * t) - 1) / (mp.sinh(2 * t) + 2 * t) / t**2 - 1 / (2 * t))


def _fu(t: float) -> float:
    """(g(t) + nu/(1 - nu))/t^2 = (1 - 4t/D)/t^2 (the cross term g = 2 beta - 4t/D)."""
    if t == 0.0:
        return 1.0 / 3.0
    with mp.workdps(40):
        t = mp.mpf(t)
        return float((1 - 4 * t / (mp.sinh(2 * t) + 2 * t)) / t**2)


def _fs(t: float) -> float:
    """Cuu(t)/t^2 - 1/(2t^3) - 1/(3t), Cuu = (cosh 2t + 1)/D (membrane and local shear off)."""
    if t == 0.0:
        return 0.0
    with mp.workdps(50):
        t = mp.mpf(t)
        cuu = (mp.cosh(2 * t) + 1) / (mp.sinh(2 * t) + 2 * t)
        return float(cuu / t**2 - 1 / (2 * t**3) - 1 / (3 * t))


def _qawf(f, e: float, weight: str) -> float:
    """int_0^inf f(t) sin|cos(t e) dt by QAWF."""
    if e == 0.0:
        return 0.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", integrate.IntegrationWarning)
        v = integrate.quad(f, 0.0, np.inf, weight=weight, wvar=abs(e), limlst=200,
                           epsabs=1e-13)[0]
    return -v if (weight == "sin" and e < 0.0) else v


def _pressure_strip_by_quadrature(x: float, s: float, h: float, nu: float):
    """(w, u) under unit pressure on |x'| < s, from w^ = (2/|k|) Cww p^, u^ = (i/k) g p^:
    w = (2h/pi) int Cww/t^2 [sin(t e+) - sin(t e-)] dt, u = -(h/pi) int g/t^2 [cos(t e-) -
    cos(t e+)] dt, e+- = (x +- s)/h, the parts 1/(2t) and -nu/(1 - nu) split off exactly."""
    ep, em = (x + s) / h, (x - s) / h
    nup = nu / (1.0 - nu)
    w = (2.0 / np.pi) * h * (0.25 * np.pi * (np.sign(ep) - np.sign(em))
                             + _qawf(_fw, ep, "sin") - _qawf(_fw, em, "sin"))
    u = -(h / np.pi) * (-nup * 0.5 * np.pi * (abs(ep) - abs(em))
                        + _qawf(_fu, em, "cos") - _qawf(_fu, ep, "cos"))
    return w, u


def _shear_strip_by_quadrature(x: float, s: float, h: float, nu: float):
    """(w, u) under the outward unit shear on |x'| < s (q^ = -2i (1 - cos ks)/k):
    u = (2h/pi) int Cuu/t^2 [2 sin(t e0) - sin(t e+) - sin(t e-)] dt, w = -(h/pi) int g/t^2
    [2 cos(t e0) - cos(t e+) - cos(t e-)] dt, with int (sin(at) - at)/t^3 dt = -(pi/4) a|a|
    for the membrane part 1/(2t^3) and the Dirichlet integral for 1/(3t)."""
    e0, ep, em = x / h, (x + s) / h, (x - s) / h
    nup = nu / (1.0 - nu)
    sq, sg = (lambda e: e * abs(e)), np.sign
    u = (2.0 * h / np.pi) * (-(np.pi / 8.0) * (2 * sq(e0) - sq(ep) - sq(em))
                             + (np.pi / 6.0) * (2 * sg(e0) - sg(ep) - sg(em))
                             + 2 * _qawf(_fs, e0, "sin") - _qawf(_fs, ep, "sin")
                             - _qawf(_fs, em, "sin"))
    w = -(h / np.pi) * (-nup * 0.5 * np.pi * (abs(ep) + abs(em) - 2 * abs(e0))
                        + 2 * _qawf(_fu, e0, "cos") - _qawf(_fu, ep, "cos")
                        - _qawf(_fu, em, "cos"))
    return w, u


FAR_POINTS = [(0.999, 1.0), (0.9999, 1.0), (1.001, 1.0), (0.5, 1.0), (2.0, 1.0), (0.3, 0.31)]


@pytest.mark.parametrize("x,s", FAR_POINTS)
def test_shear_strip_against_quadrature_far_out(x, s):
    h = 1e-3
    w_ref, u_ref = _shear_strip_by_quadrature(x, s, h, NU)
    w, u, _ = strip.shear_strip(np.array([x]), np.array([s]), NU, h, base="smooth")
    assert abs(w[0] - w_ref) < 1e-13  # w ~ 1e-4 ... 0.2; measured <= 7e-17
    assert abs(u[0] - u_ref) < 1e-13 * abs(u_ref)  # the membrane: u ~ s^2/h; measured 6e-16


@pytest.mark.parametrize("x,s", FAR_POINTS)
def test_pressure_strip_against_quadrature_far_out(x, s):
    # h = a/1000: one argument near, the other up to |x + s|/h = 3000 (the table's
    # |eta| <= 20, then its exponentially exact far forms)
    h = 1e-3
    w_ref, u_ref = _pressure_strip_by_quadrature(x, s, h, NU)
    w, u, _ = strip.pressure_strip(np.array([x]), np.array([s]), NU, h, base="smooth")
    assert abs(w[0] - w_ref) < 1e-10 * h  # measured <= 2.1e-12 h
    assert abs(u[0] - u_ref) < 1e-11  # u ~ 0.43; measured <= 1.1e-13


def test_frictionless_load_tends_to_the_thin_limit():
    # Winkler on a smooth base, w = p h: p = (1 - x^2)/(2h), load 2/(3h) over pi/4
    departures = []
    for ratio in (100.0, 500.0):
        r = contactlib.solve("cylinder", NU, stick_ratio=0.0, n=256, slab_ratio=ratio,
                             base="smooth", energy=False)
        departures.append(r.load_ratio / (8.0 * ratio / (3.0 * np.pi)) - 1.0)
    scaled = np.array(departures) * np.array([100.0, 500.0])  # measured 0.532, 0.527
    assert np.all(scaled > 0.0) and np.all(scaled < 0.6)
    np.testing.assert_allclose(scaled[1], scaled[0], rtol=0.05)  # first order in h/a


def _k(c: float, ratio: float, n: int, nu: float = NU):
    return contactlib.solve("cylinder", nu, stick_ratio=c, n=n, slab_ratio=ratio,
                            base="smooth", energy=False)


def _check_covered(c: float, ratio: float, nu: float = NU) -> None:
    coarse, fine = _k(c, ratio, 256, nu), _k(c, ratio, 1024, nu)
    assert coarse.resolved and fine.resolved
    assert "outward" in coarse.message  # the thin layer's Poisson expansion: slip outward
    diff = abs(coarse.friction_coefficient / fine.friction_coefficient - 1.0)
    assert diff <= coarse.error_estimate  # measured cover 1.4 ... 4.9 (a/h = 100 ... 500)
    assert fine.error_estimate < coarse.error_estimate / 4.0  # converging


def test_k_converges_and_the_estimate_covers_it_a_h_500():
    _check_covered(0.3, 500.0)  # cover 1.50, the smallest of c/a = 0.05 ... 0.95


@pytest.mark.slow
@pytest.mark.parametrize("c,ratio,nu", [(0.05, 100.0, NU), (0.95, 100.0, NU), (0.05, 500.0, NU),
                                        (0.95, 500.0, NU), (0.5, 500.0, 0.45)])
def test_k_converges_and_the_estimate_covers_it(c, ratio, nu):
    _check_covered(c, ratio, nu)


def test_thin_start_reaches_the_root_the_old_start_found_below_80(monkeypatch):
    new = _k(0.5, 60.0, 256).friction_coefficient
    monkeypatch.setattr(default_method, "THIN_START_FROM", math.inf)
    old = _k(0.5, 60.0, 256).friction_coefficient
    assert abs(new / old - 1.0) < 1e-8  # measured 1e-11 at a/h = 20 ... 60


def test_thin_start_is_a_start_within_10_percent_at_nu_03():
    geom = contactlib.model.contact("cylinder", NU, slab_ratio=500.0, base="smooth")
    for c in (0.05, 0.5, 0.95):
        k0 = default_method.thin_smooth_layer_k(geom, c)
        k = _k(c, 500.0, 256).friction_coefficient
        assert k0 < 0.0  # outward, against sign(beta) > 0
        assert 0.85 < -k0 / k < 1.0  # measured 0.91 ... 0.92 (the inner layer at c adds)


def test_beyond_the_range_is_refused_with_it():
    hi = validate.LAYER_RATIO_MAX[("cylinder", "smooth")]
    assert hi == 500.0
    with pytest.raises(ValueError, match="<= 500 for a cylinder on a smooth base"):
        contactlib.solve("cylinder", NU, stick_ratio=0.5, slab_ratio=hi * 1.01, base="smooth")
    with pytest.raises(ValueError, match="<= 500 for a cylinder on a smooth base"):
        contactlib.history("cylinder", NU, 0.2, [0, 1], 4, slab_ratio=501.0)
