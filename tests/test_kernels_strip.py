"""Tests of contactlib.kernels.strip (plane-strain strip kernels, half-plane and slab).

Units: E* = 1, unit loads; every tolerance is absolute relative to the kernel
scale, which is O(1) for strips of half-width s ~ 1 (O(1/h) for the thin-layer
shear u, where a relative tolerance is used).
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from scipy.integrate import IntegrationWarning, quad

from contactlib.kernels import strip
from contactlib.kernels.strip import pressure_strip, shear_strip
from contactlib.model.theory import beta_of_nu

NUS = [0.0, 0.3, 0.45]


def beta(nu: float) -> float:
    return (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu))


def q_shear(xp: float) -> float:
    """Outward unit shear traction at x' (+1 right of the axis, -1 left)."""
    return 1.0 if xp > 0 else -1.0


def integrate(f, lo: float, hi: float, points=()) -> float:
    pts = sorted({p for p in points if lo < p < hi})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", IntegrationWarning)
        return quad(f, lo, hi, points=pts or None, epsabs=1e-14, epsrel=1e-13, limit=400)[0]


# Flamant line loads at the origin (E* = 1), surface displacement at xi.
def flamant_w_normal(xi):
    return -(2.0 / np.pi) * np.log(abs(xi))


def flamant_u_normal(xi, nu):
    return -beta(nu) * np.sign(xi)


def flamant_u_tangential(xi):
    return -(2.0 / np.pi) * np.log(abs(xi))


def flamant_w_tangential(xi, nu):
    return beta(nu) * np.sign(xi)


# --------------------------------------------------------------------------
# 1. half-plane closed forms against direct integration of Flamant's solution
# --------------------------------------------------------------------------
X_POINTS = [0.0, 0.37, 1.0, -1.0, 1.6, -4.2, 25.0]


@pytest.mark.parametrize("nu", NUS)
@pytest.mark.parametrize("s", [1.0, 0.37])
def test_half_plane_pressure_matches_flamant_integral(nu, s):
    x = np.array(X_POINTS)
    w, u, du = pressure_strip(x, s, nu)
    wq = np.array([integrate(lambda t: flamant_w_normal(xx - t), -s, s, [xx]) for xx in x])
    uq = np.array([integrate(lambda t: flamant_u_normal(xx - t, nu), -s, s, [xx]) for xx in x])
    # w only up to a constant: compare differences to the point x0 = 0.37
    i0 = 1
    assert np.abs((w - w[i0]) - (wq - wq[i0])).max() < 1e-8
    # documented constant: exact integral of the unit-reference-length kernel
    assert np.abs(w - wq).max() < 1e-8
    assert np.abs(u - uq).max() < 1e-8
    # du/dx: u is piecewise linear, so central differences of the integral are
    # exact away from the edges; at x = +-s the mean of the one-sided slopes
    step = 1e-3
    for xx, d in zip(x, du):
        up = integrate(lambda t: flamant_u_normal(xx + step - t, nu), -s, s, [xx + step])
        um = integrate(lambda t: flamant_u_normal(xx - step - t, nu), -s, s, [xx - step])
        assert abs(d - (up - um) / (2 * step)) < 1e-8


@pytest.mark.parametrize("nu", NUS)
@pytest.mark.parametrize("s", [1.0, 0.37])
def test_half_plane_shear_matches_flamant_integral(nu, s):
    x = np.array(X_POINTS)
    w, u, du = shear_strip(x, s, nu)
    pts = lambda xx: [xx, 0.0]  # noqa: E731
    uq = np.array([integrate(lambda t: q_shear(t) * flamant_u_tangential(xx - t), -s, s, pts(xx))
                   for xx in x])
    wq = np.array([integrate(lambda t: q_shear(t) * flamant_w_tangential(xx - t, nu), -s, s, pts(xx))
                   for xx in x])
    assert np.abs(u - uq).max() < 1e-8
    assert np.abs(w - wq).max() < 1e-8
    # du/dx = (2/pi) PV int q(t)/(t - x) dt (Cauchy principal value, QAWC)
    for xx, d in zip(x, du):
        if xx == 0.0 or abs(xx) == s:
            assert np.isinf(d)  # log singularities
            continue
        total = 0.0
        for lo, hi, sign in ((-s, 0.0, -1.0), (0.0, s, 1.0)):
            if lo < xx < hi:
                total += sign * quad(lambda t: 1.0, lo, hi, weight="cauchy", wvar=xx)[0]
            else:
                total += sign * integrate(lambda t: 1.0 / (t - xx), lo, hi)
        assert abs(d - (2.0 / np.pi) * total) < 1e-8


# --------------------------------------------------------------------------
# 2. Betti reciprocity
# --------------------------------------------------------------------------
def _smooth_gauss(n: int = 40):
    """Gauss rule on [0, 1] mapped by the degree-7 smoothstep (clusters nodes at
    both ends, so x log x type end behaviour costs nothing)."""
    t, w = np.polynomial.legendre.leggauss(n)
    t, w = 0.5 * (t + 1.0), 0.5 * w
    phi = t**4 * (35.0 - 84.0 * t + 70.0 * t**2 - 20.0 * t**3)
    return phi, w * 140.0 * t**3 * (1.0 - t) ** 3


def integrate_pieces(f, lo: float, hi: float, kinks) -> float:
    """int_lo^hi f(x) dx for vectorised f, split at the kinks."""
    t, w = _smooth_gauss()
    edges = [lo] + sorted({k for k in kinks if lo < k < hi}) + [hi]
    total = 0.0
    for a, b in zip(edges[:-1], edges[1:]):
        total += (b - a) * np.dot(w, f(a + (b - a) * t))
    return total


@pytest.mark.parametrize("base", ["smooth", "bonded"])
@pytest.mark.parametrize("h", [np.inf, 20.0, 1.5, 0.3, 0.04])
@pytest.mark.parametrize("nu", [0.0, 0.3])
def test_betti_reciprocity(h, nu, base):
    s1, s2 = 0.7, 1.1
    kinks = [-s2, -s1, 0.0, s1, s2]

    def q(x):
        return np.where(x > 0, 1.0, -1.0)

    def work(f_load, s_load, s_other, shear_other):
        """Work of the load on |x| < s_other (pressure, or shear if shear_other)
        on the displacement f_load(x, s_load)."""
        g = (lambda x: q(x) * f_load(x, s_load)) if shear_other else (lambda x: f_load(x, s_load))
        return integrate_pieces(g, -s_other, s_other, kinks)

    wp = lambda x, s: pressure_strip(x, s, nu, h, base)[0]  # noqa: E731
    up = lambda x, s: pressure_strip(x, s, nu, h, base)[1]  # noqa: E731
    ws = lambda x, s: shear_strip(x, s, nu, h, base)[0]  # noqa: E731
    us = lambda x, s: shear_strip(x, s, nu, h, base)[1]  # noqa: E731

    # pressure (|x| < s1) on the shear's w  ==  shear (|x| < s2) on the pressure's u
    lhs = work(ws, s2, s1, False)
    rhs = work(up, s1, s2, True)
    assert abs(lhs) > 1e-4  # the cross work is not trivially zero (bonded, h = 0.04: 6.5e-4)
    assert abs(lhs - rhs) < 1e-9 * max(1.0, abs(lhs))
    # pressure-pressure and shear-shear symmetry
    a, b = work(wp, s2, s1, False), work(wp, s1, s2, False)
    assert abs(a - b) < 1e-9 * max(1.0, abs(a))
    c, d = work(us, s2, s1, True), work(us, s1, s2, True)
    assert abs(c - d) < 1e-9 * max(1.0, abs(c))


# --------------------------------------------------------------------------
# 3. slab -> half-plane as h -> infinity (up to a rigid-body constant in w)
# --------------------------------------------------------------------------
@pytest.mark.parametrize("base", ["smooth", "bonded"])
@pytest.mark.parametrize("kernel", [pressure_strip, shear_strip])
def test_thick_slab_tends_to_half_plane(kernel, base):
    nu = 0.3
    x = np.linspace(-3.0, 3.0, 61)
    x0 = 30  # index of x = 0
    errors = []
    for h in (1e2, 1e3, 1e4):
        for s in (0.4, 1.0):
            ws, us, ds = kernel(x, s, nu, h, base)
            wh, uh, dh = kernel(x, s, nu)
            ok = np.isfinite(dh)
            err = max(
                np.abs((ws - ws[x0]) - (wh - wh[x0])).max(),
                np.abs(us - uh).max(),
                np.abs(ds[ok] - dh[ok]).max(),
            )
            errors.append((h, s, err))
    by_h = {h: max(e for hh, _, e in errors if hh == h) for h in (1e2, 1e3, 1e4)}
    assert by_h[1e3] < 0.2 * by_h[1e2]
    assert by_h[1e4] < 0.2 * by_h[1e3]
    assert by_h[1e4] < 1e-3


# --------------------------------------------------------------------------
# 4. thin layer: the small-wavenumber (membrane) limit of the transform
# --------------------------------------------------------------------------
# w^ -> h p^,  u^ -> -i nu/((1-nu) k) p^   (uniaxial stress, Poisson expansion)
# u^ -> [1/(k^2 h) + 2h/3] q^,  w^ -> i nu/((1-nu) k) q^  (membrane, Poisson thinning)
# For a uniform load, interior points (distance d from the strip edges and
# from x = 0) differ from these by O(exp(-2.1 d/h)).
@pytest.mark.parametrize("nu", [0.0, 0.3, 0.45])
def test_thin_layer_limit(nu):
    s = 1.0
    k = nu / (1.0 - nu)
    xp = np.array([-0.5, 0.0, 0.5])
    xs = np.array([-0.5, 0.5])
    errs = []
    for h in (0.2, 0.1, 0.05, 0.03, 0.01):
        w, u, du = pressure_strip(xp, s, nu, h)
        e_p = max(np.abs(w - h).max() / h, np.abs(u - k * xp).max(), np.abs(du - k).max())
        w, u, du = shear_strip(xs, s, nu, h)
        u_ref = (s * xs - xs * np.abs(xs) / 2.0) / h + (2.0 * h / 3.0) * np.sign(xs)
        du_ref = (s - np.abs(xs)) / h
        w_ref = k * (s - np.abs(xs))
        e_s = max(np.abs(u - u_ref).max() / np.abs(u_ref).max(),
                  np.abs(du - du_ref).max() / np.abs(du_ref).max(),
                  np.abs(w - w_ref).max())
        errs.append(max(e_p, e_s))
    assert errs[0] > 1e-5  # h = 0.2 is not yet thin: the test can tell
    assert all(b < 0.1 * a for a, b in zip(errs, errs[1:]))
    assert errs[2] < 5e-9  # h = 0.05: exp(-21)
    assert errs[3] < 1e-12
    assert errs[4] < 1e-12  # every |x +- s|/h, |x|/h > 20: thin-layer closed forms


@pytest.mark.parametrize("kernel", [pressure_strip, shear_strip])
def test_switch_to_thin_layer_forms_is_continuous(kernel):
    """Where every argument (x, x +- s)/h passes 20 the kernels switch from
    table + far-field forms to the closed thin-layer forms: no jump."""
    nu, s, h = 0.3, 1.0, 0.045
    d = 1e-12
    for x0 in (s + 20 * h, 20 * h, -(s + 20 * h), s - 20 * h):
        lo = kernel(x0 - d, s, nu, h)
        hi = kernel(x0 + d, s, nu, h)
        for a, b in zip(lo, hi):
            assert abs(float(a) - float(b)) < 1e-10


# --------------------------------------------------------------------------
# 5. far field and removable points
# --------------------------------------------------------------------------
@pytest.mark.parametrize("nu", NUS)
def test_half_plane_far_field(nu):
    b = beta(nu)
    for s in (1.0, 0.3):
        x = np.array([1.0000001, 1.5, 3.0, 10.0, 1e3, 1e6]) * s
        x = np.concatenate([x, -x])
        # pressure: u exactly constant outside, du = 0
        w, u, du = pressure_strip(x, s, nu)
        assert np.all(u == -2.0 * b * s * np.sign(x))
        assert np.all(du == 0.0)
        # shear: w = 0 outside; u ~ (2/pi)(s^2/x + s^4/(6x^3) + s^6/(15x^5)); du = (2/pi) ln(1 - s^2/x^2)
        w, u, du = shear_strip(x, s, nu)
        assert np.all(w == 0.0)
        far = np.abs(x) >= 1e3 * s
        r = s / x[far]
        series = (2.0 / np.pi) * s * (r + r**3 / 6.0 + r**5 / 15.0)
        assert np.abs(u[far] / series - 1.0).max() < 1e-13
        assert np.abs(du[far] / ((2.0 / np.pi) * np.log1p(-r * r)) - 1.0).max() < 1e-13
    # pressure w: w + (4 s/pi) ln|x| = (2/pi)(s^3/(3 x^2) + s^5/(10 x^4) + ...)
    s = 1.0
    x = np.array([30.0, -30.0, 100.0])
    w = pressure_strip(x, s, nu)[0]
    rest = w + (4.0 * s / np.pi) * np.log(np.abs(x))
    ref = (2.0 / np.pi) * (s**3 / (3 * x**2) + s**5 / (10 * x**4) + s**7 / (21 * x**6))
    assert np.abs(rest - ref).max() < 1e-13


@pytest.mark.parametrize("h", [np.inf, 20.0, 2.0, 0.3])
@pytest.mark.parametrize("kernel", [pressure_strip, shear_strip])
def test_removable_points(h, kernel):
    nu = 0.3
    s = 0.8
    eps = 1e-10
    for x0 in (s, -s, 0.0):
        at = kernel(x0, s, nu, h)
        left = kernel(x0 - eps, s, nu, h)
        right = kernel(x0 + eps, s, nu, h)
        for i in (0, 1):  # w, u are continuous: |f(x0 +- eps) - f(x0)| = O(eps log eps)
            assert np.isfinite(at[i])
            assert abs(left[i] - at[i]) < 1e-8
            assert abs(right[i] - at[i]) < 1e-8
        d_at, d_l, d_r = at[2], left[2], right[2]
        if kernel is shear_strip:
            # log singularities of du/dx: +inf at 0, -inf at the edges
            assert d_at == (np.inf if x0 == 0.0 else -np.inf)
            assert (d_l > 10.0) if x0 == 0.0 else (d_l < -10.0)
        elif x0 == 0.0:
            assert abs(d_l - d_at) < 1e-8 and abs(d_r - d_at) < 1e-8
        else:  # jump of the pressure's du at the edge: mean of the one-sided limits
            assert abs(d_at - 0.5 * (d_l + d_r)) < 1e-8
            assert abs(d_l - d_r) > 0.1
    # s = 0: zeros; s -> 0+: values -> 0
    x = np.array([-2.0, -1e-12, 0.0, 1e-12, 0.5, 3.0])
    for out in kernel(x, 0.0, nu, h):
        assert np.all(out == 0.0)
    for out in kernel(np.array([-2.0, 0.5, 3.0]), 1e-12, nu, h):
        assert np.all(np.abs(out) < 1e-9)
    # odd / even symmetry (w and du even, u odd), to rounding of the slab sums
    # (thin layers far from the load: second differences of O(x^2/h) terms)
    x = np.linspace(0.0, 3.0, 31)
    wp, up, dp = kernel(x, s, nu, h)
    wm, um, dm = kernel(-x, s, nu, h)
    ok = np.isfinite(dp)
    assert np.array_equal(ok, np.isfinite(dm))
    for a, b in ((wp, wm), (up, -um), (dp[ok], dm[ok])):
        assert np.abs(a - b).max() < 1e-11


# --------------------------------------------------------------------------
# 6. slab against a brute-force Fourier integral of the full transform
# --------------------------------------------------------------------------
K0 = 30.0


def _den(t):
    return -np.expm1(-4 * t) + 4 * t * np.exp(-2 * t)  # (sinh 2t + 2t) 2 e^-2t


def _tw(t):  # (cosh 2t - 1)/(sinh 2t + 2t)
    return np.expm1(-2 * t) ** 2 / _den(t)


def _tu(t):  # (cosh 2t + 1)/(sinh 2t + 2t)
    return (1 + np.exp(-2 * t)) ** 2 / _den(t)


def _g(t, nu):  # [(1 - 2nu) sinh 2t - 2t] / [(1 - nu)(sinh 2t + 2t)]
    return 2 * beta(nu) - 8 * t * np.exp(-2 * t) / _den(t)


def _tail(f, omega, kind):
    """int_K0^inf f(k) cos/sin(omega k) dk."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", IntegrationWarning)
        if omega == 0.0:
            return quad(f, K0, np.inf, epsabs=1e-14, limit=500)[0] if kind == "cos" else 0.0
        sign = -1.0 if (omega < 0 and kind == "sin") else 1.0
        return sign * quad(f, K0, np.inf, weight=kind, wvar=abs(omega), limlst=200)[0]


def _head(f):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", IntegrationWarning)
        return quad(f, 0.0, K0, epsabs=1e-14, epsrel=1e-13, limit=4000)[0]


def _bonded(t, nu):
    """Bonded base, typed in from the closed forms (numerators and N times exp(-2t)):
    Tw = (2K sinh 2t - 4t)/N, Tu = (2K sinh 2t + 4t)/N,
    g = 2 [2K(K-1)(cosh 2t - 1) - 8t^2]/((K+1) N), N = 2K cosh 2t + 1 + K^2 + 4t^2."""
    k, e = 3 - 4 * nu, np.exp(-2 * t)
    n = k * (1 + e * e) + (1 + k * k + 4 * t * t) * e
    tw = (k * (1 - e * e) - 4 * t * e) / n
    tu = (k * (1 - e * e) + 4 * t * e) / n
    g = 2 * (k * (k - 1) * (1 - e) ** 2 - 8 * t * t * e) / ((k + 1) * n)
    return tw, tu, g


def _parts(base, nu):
    if base == "smooth":
        return _tw, _tu, lambda t: _g(t, nu)
    return (lambda t: _bonded(t, nu)[0], lambda t: _bonded(t, nu)[1],
            lambda t: _bonded(t, nu)[2])


def brute_pressure(x, s, nu, h, base="smooth"):
    """w, u, du/dx of the pressure strip from f(x) = (1/2pi) int f^(k) e^{ikx} dk,
    p^ = 2 sin(ks)/k, w^ = (2/k) Tw p^, u^ = (i/k) g p^."""
    _tw, _, g = _parts(base, nu)
    fw = lambda k: 4 * _tw(k * h) / k**2  # noqa: E731
    w = _head(lambda k: fw(k) * np.sin(k * s) * np.cos(k * x))
    w += 0.5 * (_tail(fw, s + x, "sin") + _tail(fw, s - x, "sin"))
    fu = lambda k: -2 * g(k * h) / k**2  # noqa: E731
    u = _head(lambda k: fu(k) * np.sin(k * s) * np.sin(k * x))
    u += 0.5 * (_tail(fu, x - s, "cos") - _tail(fu, x + s, "cos"))
    fd = lambda k: -2 * g(k * h) / k  # noqa: E731
    du = _head(lambda k: fd(k) * np.sin(k * s) * np.cos(k * x))
    du += 0.5 * (_tail(fd, s + x, "sin") + _tail(fd, s - x, "sin"))
    return w / np.pi, u / np.pi, du / np.pi


def brute_shear(x, s, nu, h, base="smooth"):
    """Same for the outward shear: q^ = -2i (1 - cos ks)/k, u^ = (2/k) Tu q^, w^ = -(i/k) g q^."""
    _, _tu, g = _parts(base, nu)
    one_m_cos = lambda k: 2 * np.sin(k * s / 2) ** 2  # noqa: E731
    fu = lambda k: 4 * _tu(k * h) / k**2  # noqa: E731
    u = _head(lambda k: fu(k) * one_m_cos(k) * np.sin(k * x))
    u += _tail(fu, x, "sin") - 0.5 * (_tail(fu, x + s, "sin") + _tail(fu, x - s, "sin"))
    fw = lambda k: -2 * g(k * h) / k**2  # noqa: E731
    w = _head(lambda k: fw(k) * one_m_cos(k) * np.cos(k * x))
    w += _tail(fw, x, "cos") - 0.5 * (_tail(fw, x + s, "cos") + _tail(fw, x - s, "cos"))
    fd = lambda k: 4 * _tu(k * h) / k  # noqa: E731
    du = _head(lambda k: fd(k) * one_m_cos(k) * np.cos(k * x))
    du += _tail(fd, x, "cos") - 0.5 * (_tail(fd, x + s, "cos") + _tail(fd, x - s, "cos"))
    return w / np.pi, u / np.pi, du / np.pi


@pytest.mark.parametrize("h", [0.4, 3.0, 20.0])
@pytest.mark.parametrize("nu", [0.0, 0.3])
def test_slab_against_fourier_integral(h, nu):
    s = 1.0
    for x in (0.0, 0.4, 1.0, 1.6, -2.5, 9.0):
        got_p = pressure_strip(x, s, nu, h)
        ref_p = brute_pressure(x, s, nu, h)
        got_s = shear_strip(x, s, nu, h)
        ref_s = brute_shear(x, s, nu, h)
        for g, r in zip(got_p + got_s, ref_p + ref_s):
            if np.isinf(g):  # shear du at x = 0, +-s: the integral diverges
                continue
            assert abs(float(g) - r) < 1e-8, (x, float(g), r)


@pytest.mark.parametrize("h", [0.05, 0.4, 3.0])
@pytest.mark.parametrize("nu", [0.0, 0.3, 0.5])
def test_bonded_slab_against_fourier_integral(h, nu):
    s = 1.0
    for x in (0.0, 0.4, 1.0, 1.6, -2.5, 9.0):
        got = pressure_strip(x, s, nu, h, "bonded") + shear_strip(x, s, nu, h, "bonded")
        ref = brute_pressure(x, s, nu, h, "bonded") + brute_shear(x, s, nu, h, "bonded")
        for g, r in zip(got, ref):
            if np.isinf(g):  # shear du at x = 0, +-s: the integral diverges
                continue
            assert abs(float(g) - r) < 1e-8, (x, float(g), r)


# --------------------------------------------------------------------------
# 7. bonded base: thin-layer limits (Winkler, simple shear, incompressible)
# --------------------------------------------------------------------------
def test_bonded_uniform_strip_interior_is_winkler_and_simple_shear():
    """Uniform strip, points far from the edges (d/h >= 10): w = p h / M with M the
    constrained modulus, u = 0; shear: u = q h / G; departures fall exponentially."""
    s = 1.0
    for nu in (0.0, 0.3, 0.45, 0.5):
        young = 1 - nu**2  # E* = 1
        m = young * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) if nu < 0.5 else np.inf
        g_mod = young / (2 * (1 + nu))
        errs = []
        for h in (0.05, 0.025, 0.01, 0.005):
            w, u, du = pressure_strip(np.array([0.0, 0.5]), s, nu, h, "bonded")
            e_p = max(np.abs(w - h / m).max() / h, np.abs(u).max() / h, np.abs(du).max())
            w, u, du = shear_strip(np.array([0.5, -0.5]), s, nu, h, "bonded")
            e_s = max(np.abs(u - np.sign([0.5, -0.5]) * h / g_mod).max() / h,
                      np.abs(w).max() / h, np.abs(du).max())
            errs.append(max(e_p, e_s))
        # d/h = 10, 20, 50, 100: exp(-0.74 d/h) at nu = 1/2 (slowest), faster below
        assert errs[0] < 1e-2 and errs[1] < 1e-5 and errs[2] < 1e-12 and errs[3] < 1e-12, errs


def _parabolic_w0(a, h, nu):
    """w(0) under p = 1 - x^2/a^2 on |x| < a: int_0^a (2s/a^2) w_strip(0; s) ds.

    The integrand varies on the scale h near s = 0 (the strip edge passes x = 0):
    Gauss pieces graded in h there."""
    t, wt = np.polynomial.legendre.leggauss(30)
    edges = [0.0] + [c * h for c in (1, 2, 5, 10, 20, 40, 80) if c * h < a] + [a]
    total = 0.0
    for lo, hi in zip(edges[:-1], edges[1:]):
        s = 0.5 * (hi - lo) * (t + 1) + lo
        total += np.sum(0.5 * (hi - lo) * wt * 2 * s / a**2 * pressure_strip(0.0, s, nu, h, "bonded")[0])
    return float(total)


@pytest.mark.parametrize("nu", [0.3, 0.45, 0.5])
def test_bonded_thin_layer_parabolic_pressure(nu):
    """w(0) = 2 c1 h + 4 c3 h^3/a^2 + O(h^5/a^4) with Tw = c1 t + c3 t^3 + ... (w^ = (2/|k|) Tw p^):
    compressible -> Winkler h/M (c1 = 2(K-1)/(K+1)^2... in E* = 1 units 1/(2M));
    incompressible (c1 = 0) -> w = -(h^3/(3G)) p'' = (8/3) h^3/a^2 (G = 1/4)."""
    k = 3 - 4 * nu
    c1 = 4 * (k - 1) / (k + 1) ** 2
    c3 = (8 * k * (k + 1) / 3 - 16 * (k - 1)) / (k + 1) ** 3
    if nu < 0.5:
        assert np.isclose(2 * c1, (1 - 2 * nu) / (1 - nu) ** 2)  # 1/M with E* = 1
    else:
        assert np.isclose(4 * c3, 8.0 / 3.0)
    a = 1.0
    for ratio in (10.0, 30.0, 100.0):
        h = a / ratio
        w0 = _parabolic_w0(a, h, nu)
        lead = 2 * c1 * h if c1 else 4 * c3 * h**3
        two = 2 * c1 * h + 4 * c3 * h**3
        if c1:  # the departure from Winkler is the next term of the expansion
            assert abs(w0 - two) <= 0.02 * abs(two - lead), (ratio, w0, two, lead)
        else:  # incompressible: exact up to the edge effect, exp-small in a/h
            assert abs(w0 / lead - 1) < (0.05 if ratio == 10 else 1e-6), (ratio, w0, lead)


def test_bonded_incompressible_limit_is_continuous():
    x = np.linspace(-3, 3, 25)
    for kernel in (pressure_strip, shear_strip):
        a = np.array(kernel(x, 1.0, 0.5, 0.3, "bonded"))
        b = np.array(kernel(x, 1.0, 0.5 - 1e-7, 0.3, "bonded"))
        ok = np.isfinite(a)
        assert np.array_equal(ok, np.isfinite(b)) and np.all(np.abs(a[ok] - b[ok]) < 1e-5)


def check_table(tab, eta, exact):
    """The packed interpolants (A1, B1; C1, B1 and B, C) against the quadrature."""
    sg = np.sign(eta)
    vp, dvp, _ = strip._pair("pressure", eta, tab)
    vs, dvs, _ = strip._pair("shear", eta, tab)
    assert np.abs(vp.real - sg * exact["A1"]).max() < 1e-12
    assert np.abs(vp.imag - exact["B1"]).max() < 1e-12
    assert np.abs(dvp - sg * exact["B"]).max() < 1e-10
    assert np.abs(vs.real - sg * exact["C1"]).max() < 1e-12
    assert np.abs(dvs - exact["C"]).max() < 1e-10


def test_bonded_table_and_far_field_constants():
    """Tables against the quadrature; far-field constants against closed forms:
    A1 -> ... + (1 - 2nu)/(2(1 - nu)^2) (Winkler), C1 -> ... + 1/(1 - nu) (simple shear)."""
    for nu in (0.0, 0.3, 0.5):
        tab = strip._slab_table("bonded", nu)
        assert abs(tab.a1_inf - (1 - 2 * nu) / (2 * (1 - nu) ** 2)) < 1e-12
        assert abs(tab.c1_inf - 1 / (1 - nu)) < 1e-12
        assert tab.b_inf == beta(nu) and tab.c_quad == 0.0
        rng = np.random.default_rng(4)
        eta = np.concatenate([rng.uniform(-48, 48, 300), [0.0, 48.0, -48.0]])
        exact = strip._remainder_exact_bonded(np.abs(eta), nu)
        check_table(tab, eta, exact)
        e = np.array([48.0 - 1e-13, 48.0 + 1e-13, 60.0])  # far-field forms continue the table
        vp, dvp, far = strip._pair("pressure", e, tab)
        ex = strip._remainder_exact_bonded(e, nu)
        assert list(far) == [False, True, True]
        assert np.abs(vp.real - ex["A1"]).max() < 1e-12 and np.abs(dvp - ex["B"]).max() < 1e-12


# --------------------------------------------------------------------------
# implementation checks: tables, asymptotes, broadcasting, validation
# --------------------------------------------------------------------------
def test_table_interpolation_and_far_field_constants():
    tab = strip._slab_table()
    rng = np.random.default_rng(3)
    eta = np.concatenate([rng.uniform(-20, 20, 400), rng.uniform(-0.05, 0.05, 100), [0.0, 20.0, -20.0]])
    exact = strip._remainder_exact(np.abs(eta))
    check_table(tab, eta, exact)
    # the far-field forms continue the table at |eta| = 20 (remainder ~ exp(-42))
    e = np.array([20.0 - 1e-13, 20.0 + 1e-13, -20.0 - 1e-13])
    vp, dvp, far = strip._pair("pressure", e, tab)
    assert list(far) == [False, True, True]
    assert abs(vp[0] - vp[1]) < 1e-11 and abs(dvp[0] - dvp[1]) < 1e-11
    vs, dvs, _ = strip._pair("shear", e, tab)
    assert abs(vs[0] - vs[1]) < 1e-11 and abs(dvs[0] - dvs[1]) < 1e-11
    # the slab's w far from the load tends to 0 (absolute, no free constant),
    # across the junction table / far-field forms (|eta| = 20 at x = 399 ... 401)
    x = np.array([399.0, 400.0, 401.0, 450.0, -420.0])
    w, u, _ = pressure_strip(x, 1.0, 0.3, 20.0)
    assert np.abs(w).max() < 1e-12
    # and the slab's u under pressure to +-s nu/(1-nu) (table at x = 300)
    assert np.abs(u - np.sign(x) * 0.3 / 0.7).max() < 1e-12
    assert abs(float(pressure_strip(300.0, 1.0, 0.3, 20.0)[1]) - 0.3 / 0.7) < 1e-12


@pytest.mark.parametrize("kernel", [pressure_strip, shear_strip])
@pytest.mark.parametrize("h", [np.inf, 20.0, 0.05])
def test_broadcasting_paths_agree(kernel, h):
    x = np.linspace(-1.5, 1.5, 41)
    s = np.linspace(0.0, 1.2, 37)
    grid = kernel(x[:, None], s[None, :], 0.3, h)  # x-only terms evaluated once
    xx, ss = np.meshgrid(x, s, indexing="ij")
    full = kernel(xx, ss, 0.3, h)
    one = [kernel(float(a), float(b), 0.3, h) for a, b in zip(xx.ravel()[::97], ss.ravel()[::97])]
    for g, f in zip(grid, full):
        assert g.shape == (41, 37)
        assert np.allclose(g, f, rtol=0, atol=1e-13, equal_nan=True)
        assert np.array_equal(np.isinf(g), np.isinf(f))
    for k, vals in enumerate(one):
        for i in range(3):
            ref = full[i].ravel()[::97][k]
            assert vals[i] == pytest.approx(ref, abs=1e-13) or (np.isinf(ref) and vals[i] == ref)


def test_validation():
    with pytest.raises(ValueError, match="s must be >= 0"):
        pressure_strip(0.0, -1.0, 0.3)
    with pytest.raises(ValueError, match="thickness"):
        shear_strip(0.0, 1.0, 0.3, 0.0)
    with pytest.raises(ValueError, match="Poisson"):
        shear_strip(0.0, 1.0, 0.7)


# w(x) - w(0) without cancellation (the default method's rows of a tiny stick zone)
@pytest.mark.parametrize("s", [1.0, 1e-8, 3.7e2])
def test_axis_w_half_plane_against_mpmath(s):
    """w(x; s) - w(0; s) of the half-plane pressure strip within 1e-14 of its own value,
    from x = 1e-9 s (where the plain difference has no correct digit) to 30 s, against
    mpmath's (2/pi)[F(s) - F(x + s) + F(x - s) + F(-s)], F(t) = t ln|t|; the shear's is
    2 beta min(|x|, s) exactly."""
    mp = pytest.importorskip("mpmath")
    mp.mp.dps = 40
    t = np.array([1e-9, 1e-6, 1e-3, 0.1, 0.49, 0.5, 0.9, 0.999999, 1.0, 1.000001, 1.5,
                  1.99, 2.0, 2.5, 30.0])
    x = t * s
    dw = strip.axis_w_strip(x, s, 0.3, "normal")[0]

    def f(v):
        return v * mp.log(abs(v)) if v != 0 else mp.mpf(0)
    for xi, got in zip(x, dw):
        xx, ss = mp.mpf(float(xi)), mp.mpf(float(s))
        ref = float(2 / mp.pi * (-f(xx + ss) + f(xx - ss) + f(ss) - f(-ss)))
        assert abs(got - ref) <= 1e-14 * abs(ref), (xi / s, got, ref)
    dws = strip.axis_w_strip(x, s, 0.3, "shear")[0]
    assert np.allclose(dws, 2.0 * beta_of_nu(0.3) * np.minimum(x, s), rtol=1e-15, atol=0)
    far = t >= 0.1
    plain = strip.pressure_strip(x[far], s, 0.3)[0] - strip.pressure_strip(0.0, s, 0.3)[0]
    assert np.allclose(dw[far], plain, rtol=0, atol=1e-14 * s * (1 + abs(np.log(s))))


@pytest.mark.parametrize("part", ["normal", "shear"])
def test_axis_w_slab_is_the_plain_difference(part):
    """On a slab the remainder's difference is formed directly: the result equals the
    plain difference of the kernels to round-off of the kernels themselves."""
    x = np.array([1e-3, 0.3, 0.9, 1.0, 1.7, 4.0])
    kernel = strip.pressure_strip if part == "normal" else strip.shear_strip
    dw = strip.axis_w_strip(x, 1.0, 0.3, part, h=2.0)[0]
    plain = kernel(x, 1.0, 0.3, 2.0)[0] - kernel(0.0, 1.0, 0.3, 2.0)[0]
    assert np.allclose(dw, plain, rtol=0, atol=1e-14)


@pytest.mark.parametrize("x0", [0.3, 1.0 - 4e-5])
def test_w_difference_half_plane_against_mpmath(x0):
    """w(x; s) - w(x0; s) of the half-plane pressure strip within 1e-14 of its value."""
    mp = pytest.importorskip("mpmath")
    mp.mp.dps = 40

    def f(v):
        return v * mp.log(abs(v)) if v != 0 else mp.mpf(0)

    width = 1.0 - x0 if x0 > 0.5 else 0.1
    for x in x0 + width * np.array([0.25, 0.75, 1.0 - 1e-4]):
        for s in (0.2, 0.9, x0 - 0.25 * width, x0 + 0.5 * width, x0 + width, 1.5):
            got = float(strip.w_difference_strip(np.array([x]), x0, np.array([s]), 0.3,
                                                 "normal")[0][0])
            xx, xr, ss = mp.mpf(float(x)), mp.mpf(float(x0)), mp.mpf(float(s))
            ref = float(2 / mp.pi * (-f(xx + ss) + f(xx - ss) + f(xr + ss) - f(xr - ss)))
            assert abs(got - ref) <= 1e-14 * abs(ref), (x, s, got, ref)
