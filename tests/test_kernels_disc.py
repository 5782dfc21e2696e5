"""Independent verification of the disc-load kernels in ``contactlib.kernels.disc``.

Nothing here uses elliptic integrals: the references are

* direct numerical integration of the Boussinesq (normal) and Cerruti
  (tangential) point-load solutions over the loaded disc (Johnson, Contact
  Mechanics, eqs 3.85-3.86), in two independent ways:
  (A) polar coordinates centred on the field point, which removes the 1/rho
      singularity exactly (the Jacobian rho cancels it; the radial integral of a
      polynomial in rho is done in closed form, the angular one with ``quad``);
  (B) polar coordinates centred on the disc (ring radius t, angle phi), with
      the raw Cartesian point-load formulas and nested ``quad`` (break point
      at the singular ring t = r);
* multipole / Hankel-transform series for the far field;
* Betti's reciprocal theorem between the kernels;
* Richardson-extrapolated finite differences for ``dudr``.

Conventions (as in the module): E* = E/(1-nu^2) = 1, w positive INTO the body,
u radial positive outward, beta = (1-2nu)/(2(1-nu)).

Sign of the Cerruti normal displacement (derived here by Betti, see
``test_point_load_betti_sign``): for a tangential force Q_x at the origin,

    w(x, y) = + (1-2nu)(1+nu)/(2 pi E) * Q_x x / rho^2     (w into the body),

i.e. the surface AHEAD of the force (x > 0) sinks, the surface behind it rises.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from scipy import integrate, special

from contactlib.kernels import disc
from contactlib.kernels.disc import beta_of_nu, pressure_disc, shear_disc

NUS = [0.0, 0.3, 0.45]
# field radii r/s: centre, r -> 0, inside, edge (exact and just off), outside, far
RADII = [0.0, 1e-6, 0.3, 0.5, 0.9, 0.999, 1 - 1e-6, 1.0, 1 + 1e-6, 1.001, 1.5, 2.0, 3.0, 10.0, 100.0]
TOL_DIRECT = 1e-8  # relative to the kernel scale (s for pressure, s^2 for shear)


def _f(x) -> float:
    return float(np.asarray(x))


# --------------------------------------------------------------------------
# point-load solutions (Johnson 3.85-3.86), written with E and nu literally
# --------------------------------------------------------------------------
def _young(nu):
    return 1.0 - nu**2  # so that E* = E / (1 - nu^2) = 1


def boussinesq(dx, dy, nu, P=1.0):
    """Unit normal force at the origin; field point (dx, dy). Returns (ux, uy, w)."""
    E = _young(nu)
    rho = math.hypot(dx, dy)
    w = (1 - nu**2) * P / (math.pi * E * rho)
    ur = -(1 - 2 * nu) * (1 + nu) * P / (2 * math.pi * E * rho)  # toward the load
    return ur * dx / rho, ur * dy / rho, w


CERRUTI_W_SIGN = +1.0  # fixed by Betti in test_point_load_betti_sign


def cerruti(dx, dy, nu, Qx=0.0, Qy=0.0):
    """Tangential force (Qx, Qy) at the origin; field point (dx, dy). Returns (ux, uy, w)."""
    E = _young(nu)
    rho = math.hypot(dx, dy)
    c = (1 + nu) / (2 * math.pi * E)
    ux = c * Qx / rho * (2 * (1 - nu) + 2 * nu * dx * dx / rho**2) + c * Qy * 2 * nu * dx * dy / rho**3
    uy = c * Qy / rho * (2 * (1 - nu) + 2 * nu * dy * dy / rho**2) + c * Qx * 2 * nu * dx * dy / rho**3
    w = CERRUTI_W_SIGN * (1 - 2 * nu) * (1 + nu) / (2 * math.pi * E) * (Qx * dx + Qy * dy) / rho**2
    return ux, uy, w


@pytest.mark.parametrize("nu", NUS)
@pytest.mark.parametrize("a", [0.3, 1.0, 7.0])
def test_point_load_betti_sign(nu, a):
    """P at O, Q_x at A = (a, 0):  P * w_O(Q) = Q * u_x,A(P)  fixes the Cerruti sign."""
    P, Q = 1.3, 0.7
    ux_A = boussinesq(a, 0.0, nu, P)[0]  # displacement at A due to P at O
    w_O = cerruti(-a, 0.0, nu, Qx=Q)[2]  # displacement at O due to Q at A (O - A = (-a, 0))
    assert P * w_O == pytest.approx(Q * ux_A, rel=1e-14, abs=0)
    if nu < 0.5:
        # the field point O lies BEHIND the force: it rises (w < 0, w is into the body)
        assert w_O < 0
        assert cerruti(a, 0.0, nu, Qx=Q)[2] > 0  # ahead of the force: sinks


# --------------------------------------------------------------------------
# reference A: polar coordinates about the field point P = (r, 0)
# --------------------------------------------------------------------------
def _quad(f, a, b, scale, points=None):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", integrate.IntegrationWarning)
        val, err = integrate.quad(f, a, b, points=points, epsabs=1e-14 * scale, epsrel=1e-12, limit=1000)
    assert err < 1e-11 * scale, (val, err)
    return val


def direct_polar(r, s, nu):
    """Disc loads by point-load superposition, polar coordinates about the field point.

    A source point is S = P + rho (cos th, sin th). Per unit load the point
    solutions are 1/(pi rho) x (direction factor), so with dA = rho d rho d th the
    radial integrand is a polynomial in rho and is integrated exactly; the angular
    integral is done numerically. Returns dict(wp, up, ws, us).
    """
    b = beta_of_nu(nu)
    kap = nu / (1 - nu)
    if r <= s:
        # chord from P to the boundary in direction th: [0, R(th)]; integrand even in th
        d2 = (s - r) * (s + r)

        def R(th):
            c = math.cos(th)
            S = math.sqrt(d2 + (r * c) ** 2)
            return d2 / (S + r * c) if c > 0 else S - r * c

        # pressure p = 1: w = 1/(pi rho); horizontal displacement beta/(pi rho) towards S
        def fwp(th):
            return 2 / math.pi * R(th)

        def fup(th):
            return 2 * b / math.pi * math.cos(th) * R(th)

        # shear traction F = S (q = t, radial): F = (r + rho c, rho s_th), F.e = r c + rho
        def fus(th):
            c, RR = math.cos(th), R(th)
            # int_0^R [F_x + kap (F.e) c] d rho
            return 2 / math.pi * ((r + kap * r * c * c) * RR + (1 + kap) * c * RR * RR / 2)

        def fws(th):
            c, RR = math.cos(th), R(th)
            # w = +beta (F.d)/(pi rho^2), d = P - S = -rho e  ->  -beta (F.e)/(pi rho)
            return -2 * b / math.pi * (r * c * RR + RR * RR / 2)

        lim, pts = (0.0, math.pi), [math.pi / 2]
    else:
        # th = pi + phi, |phi| < arcsin(s/r); chord rho in [r cos phi - h, r cos phi + h],
        # h = sqrt(s^2 - r^2 sin^2 phi). Substitute sin phi = (s/r) sin psi: h = s cos psi.
        g = (r - s) * (r + s) / r**2

        def parts(psi):
            sp, cp = math.sin(psi), math.cos(psi)
            cphi = math.sqrt(cp * cp + g * sp * sp)
            sphi = s / r * sp
            h = s * cp
            jac = s / r * cp / cphi  # d phi / d psi
            return cphi, sphi, h, jac

        def fwp(psi):
            cphi, sphi, h, jac = parts(psi)
            return 2 / math.pi * 2 * h * jac

        def fup(psi):
            cphi, sphi, h, jac = parts(psi)
            return 2 * b / math.pi * (-cphi) * 2 * h * jac

        def fus(psi):
            cphi, sphi, h, jac = parts(psi)
            c = -cphi
            i0, i1 = 2 * h, 2 * r * cphi * h  # int d rho, int rho d rho
            return 2 / math.pi * ((r + kap * r * c * c) * i0 + (1 + kap) * c * i1) * jac

        def fws(psi):
            cphi, sphi, h, jac = parts(psi)
            c = -cphi
            i0, i1 = 2 * h, 2 * r * cphi * h
            return -2 * b / math.pi * (r * c * i0 + i1) * jac

        lim, pts = (0.0, math.pi / 2), None
    return {
        "wp": _quad(fwp, *lim, s, pts),
        "up": _quad(fup, *lim, s, pts),
        "ws": _quad(fws, *lim, s * s, pts),
        "us": _quad(fus, *lim, s * s, pts),
    }


# --------------------------------------------------------------------------
# reference B: ring coordinates (t, phi) about the disc centre, raw formulas
# --------------------------------------------------------------------------
def direct_rings(r, s, nu, which):
    def inner(t):
        def f(ph):
            sx, sy = t * math.cos(ph), t * math.sin(ph)
            dx, dy = r - sx, -sy
            if which in ("wp", "up"):
                ux, uy, w = boussinesq(dx, dy, nu)
            else:
                ux, uy, w = cerruti(dx, dy, nu, Qx=sx, Qy=sy)  # q = t, radial: F = (sx, sy)
            return w if which[0] == "w" else ux  # at (r, 0) radial = x

        with warnings.catch_warnings():
            warnings.simplefilter("ignore", integrate.IntegrationWarning)
            return 2 * t * integrate.quad(f, 0.0, math.pi, epsabs=1e-14, epsrel=1e-12, limit=500)[0]

    pts = [r] if 0 < r < s else None
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", integrate.IntegrationWarning)
        return integrate.quad(inner, 0.0, s, points=pts, epsabs=1e-13, epsrel=1e-12, limit=500)[0]


# --------------------------------------------------------------------------
# 1. agreement with direct integration
# --------------------------------------------------------------------------
@pytest.mark.parametrize("nu", NUS)
@pytest.mark.parametrize("x", RADII)
@pytest.mark.parametrize("s", [1.0, 0.37])
def test_against_point_load_integration(x, nu, s):
    r = x * s
    ref = direct_polar(r, s, nu)
    wp, up, _ = pressure_disc(r, s, nu)
    ws, us, _ = shear_disc(r, s, nu)
    assert abs(_f(wp) - ref["wp"]) <= TOL_DIRECT * s
    assert abs(_f(up) - ref["up"]) <= TOL_DIRECT * s
    assert abs(_f(ws) - ref["ws"]) <= TOL_DIRECT * s**2
    assert abs(_f(us) - ref["us"]) <= TOL_DIRECT * s**2
    # achieved level (documented): both references agree with the kernels to ~1e-15
    err = max(
        abs(_f(wp) - ref["wp"]) / s,
        abs(_f(up) - ref["up"]) / s,
        abs(_f(ws) - ref["ws"]) / s**2,
        abs(_f(us) - ref["us"]) / s**2,
    )
    assert err < 1e-12


@pytest.mark.parametrize(
    "x, nu", [(0.0, 0.3), (0.5, 0.3), (1.0, 0.3), (1.5, 0.3), (10.0, 0.3), (0.5, 0.45), (0.7, 0.0)]
)
def test_ring_coordinate_integration(x, nu):
    """Reference B (raw Cartesian Boussinesq/Cerruti, ring coordinates) confirms A and the kernels."""
    s = 1.0
    r = x * s
    kern = {
        "wp": _f(pressure_disc(r, s, nu)[0]),
        "up": _f(pressure_disc(r, s, nu)[1]),
        "ws": _f(shear_disc(r, s, nu)[0]),
        "us": _f(shear_disc(r, s, nu)[1]),
    }
    for key, val in kern.items():
        assert abs(direct_rings(r, s, nu, key) - val) <= 1e-10 * s**2, key


def _richardson(fun, r, h):
    """Central difference, extrapolated twice (error O(h^6))."""

    def d(hh):
        return (fun(r + hh) - fun(r - hh)) / (2 * hh)

    d1, d2, d3 = d(h), d(h / 2), d(h / 4)
    r1, r2 = (4 * d2 - d1) / 3, (4 * d3 - d2) / 3
    return (16 * r2 - r1) / 15


@pytest.mark.parametrize("nu", NUS)
@pytest.mark.parametrize(
    "x", [1e-6, 0.1, 0.3, 0.49, 0.5, 0.51, 0.7, 0.9, 0.99, 0.999, 1.001, 1.01, 1.5, 1.99, 2.0, 2.01, 3.0, 10.0, 100.0]
)
@pytest.mark.parametrize("kernel, dscale", [(pressure_disc, 0), (shear_disc, 1)])
def test_dudr_finite_difference(kernel, dscale, x, nu):
    s = 0.8
    r = x * s
    h = 0.05 * min(r, abs(r - s))  # stay clear of the kinks at r = 0 (|r|) and r = s

    def u(rr):
        return _f(kernel(rr, s, nu)[1])

    fd = _richardson(u, r, h)
    du = _f(kernel(r, s, nu)[2])
    assert abs(du - fd) <= 1e-8 * s**dscale, (du, fd)


# --------------------------------------------------------------------------
# 2. Betti reciprocity between the kernels
# --------------------------------------------------------------------------
def _radial_integral(fun, a, breaks):
    """int_0^a fun(r) 2 pi r dr."""
    pts = [p for p in breaks if 0 < p < a]
    with warnings.catch_warnings():
        warnings.simplefilter("error", integrate.IntegrationWarning)
        val, err = integrate.quad(
            lambda r: fun(r) * 2 * math.pi * r, 0.0, a, points=pts or None, epsabs=0.0, epsrel=1e-13, limit=500
        )
    return val


S_PAIRS = [(0.5, 1.0), (1.0, 0.5), (0.3, 0.9), (1.2, 0.7), (1.0, 1.0), (0.01, 2.0)]


@pytest.mark.parametrize("nu", NUS)
@pytest.mark.parametrize("s1, s2", S_PAIRS)
def test_betti_pressure_shear(s1, s2, nu):
    """int_{disc s1} 1 * w_shear(s2) dA == int_{disc s2} r * u_pressure(s1) dA."""
    lhs = _radial_integral(lambda r: _f(shear_disc(r, s2, nu)[0]), s1, [s2])
    rhs = _radial_integral(lambda r: r * _f(pressure_disc(r, s1, nu)[1]), s2, [s1])
    assert lhs == pytest.approx(rhs, rel=1e-10, abs=0)
    if nu < 0.5:
        # non-trivial: the opposite (paper's printed) sign of w_shear would fail
        assert lhs < 0 and abs(lhs) > 1e-3 * beta_of_nu(nu) * min(s1, s2) ** 4


@pytest.mark.parametrize("s1, s2", S_PAIRS)
def test_betti_pressure_pressure(s1, s2):
    nu = 0.3
    a = _radial_integral(lambda r: _f(pressure_disc(r, s1, nu)[0]), s2, [s1])
    b = _radial_integral(lambda r: _f(pressure_disc(r, s2, nu)[0]), s1, [s2])
    assert a == pytest.approx(b, rel=1e-10, abs=0)


@pytest.mark.parametrize("nu", [0.0, 0.45])
@pytest.mark.parametrize("s1, s2", S_PAIRS)
def test_betti_shear_shear(s1, s2, nu):
    a = _radial_integral(lambda r: r * _f(shear_disc(r, s1, nu)[1]), s2, [s1])
    b = _radial_integral(lambda r: r * _f(shear_disc(r, s2, nu)[1]), s1, [s2])
    assert a == pytest.approx(b, rel=1e-10, abs=0)


# --------------------------------------------------------------------------
# 3. far field: independent multipole / Hankel series (valid for r > s)
# --------------------------------------------------------------------------
_NS = 60


def series_pressure_w(r, s):
    """(1/pi) int_disc dA/|x-y|; 1/|x-y| = sum (t^n/r^{n+1}) P_n(cos phi), <P_n(cos phi)>_phi = P_n(0)^2.

    w = 2 sum_k P_{2k}(0)^2 s^{2k+2} / ((2k+2) r^{2k+1}) = s^2/r + s^4/(8 r^3) + 3 s^6/(64 r^5) + ...
    """
    k = np.arange(_NS)
    p2 = (special.comb(2 * k, k, exact=False) / 4.0**k) ** 2
    x = (s / r) ** 2
    terms = 2 * p2 * s**2 / ((2 * k + 2) * r) * x**k
    dterms = -2 * p2 * s**2 / (2 * k + 2) * (2 * k + 1) / r**2 * x**k
    return terms[::-1].sum(), dterms[::-1].sum()


def series_shear_u(r, s):
    """u = (2/E*) int q~_1(k) J_1(k r) dk, q~_1 = int q(t) J_1(k t) t dt (radial shear is irrotational).

    Weber-Schafheitlin: int_0^inf J_1(kt) J_1(kr) dk = t/(2 r^2) 2F1(3/2, 1/2; 2; t^2/r^2) for t < r, so
    u = sum_n c_n s^{2n+4} / ((2n+4) r^{2n+2}),  c_n = (3/2)_n (1/2)_n / ((2)_n n!)
      = s^4/(4 r^2) [1 + (1/4)(s/r)^2 + (15/128)(s/r)^4 + ...].
    """
    n = np.arange(_NS)
    c = special.poch(1.5, n) * special.poch(0.5, n) / (special.poch(2.0, n) * special.factorial(n))
    x = (s / r) ** 2
    terms = c * s**4 / ((2 * n + 4) * r**2) * x**n
    dterms = -c * s**4 * (2 * n + 2) / ((2 * n + 4) * r**3) * x**n
    return terms[::-1].sum(), dterms[::-1].sum()


@pytest.mark.parametrize("x", [2.0, 3.0, 10.0])
def test_far_field_series_vs_direct_integration(x):
    """Validates the series (the far-field reference) against point-load integration."""
    s, nu = 1.0, 0.3
    ref = direct_polar(x * s, s, nu)
    assert series_pressure_w(x * s, s)[0] == pytest.approx(ref["wp"], rel=1e-12, abs=0)
    assert series_shear_u(x * s, s)[0] == pytest.approx(ref["us"], rel=1e-12, abs=0)


@pytest.mark.parametrize("nu", [0.0, 0.3])
@pytest.mark.parametrize("s", [1.0, 1e-3, 2.5e3])
@pytest.mark.parametrize("x", [1e2, 1e4, 1e8])
def test_far_field(x, s, nu):
    r = x * s
    b = beta_of_nu(nu)
    wp, up, dup = (_f(v) for v in pressure_disc(r, s, nu))
    ws, us, dus = (_f(v) for v in shear_disc(r, s, nu))
    sw, sdw = series_pressure_w(r, s)
    su, sdu = series_shear_u(r, s)
    # full values, relative to themselves (no cancellation)
    assert wp == pytest.approx(sw, rel=1e-12, abs=0)
    assert up == pytest.approx(-b * s**2 / r, rel=1e-14, abs=0)
    assert dup == pytest.approx(b * s**2 / r**2, rel=1e-14, abs=0)
    assert us == pytest.approx(su, rel=1e-12, abs=0)
    assert dus == pytest.approx(sdu, rel=1e-12, abs=0)
    assert ws == 0.0
    # leading terms: total load pi s^2 acting as a point load (w ~ s^2/r), shear dipole s^4/(4 r^2);
    # relative corrections a (s/r)^2 with a = 1/8 (w), 1/4 (u_shear), 1/2 (du_shear)
    if x <= 1e4:
        eps = (s / r) ** 2
        for val, lead, a in [(wp, s**2 / r, 1 / 8), (us, s**4 / (4 * r**2), 1 / 4), (dus, -(s**4) / (2 * r**3), 1 / 2)]:
            e = (val / lead - 1) / eps
            assert abs(e - a) <= 1e-3 * a, (e, a)


# --------------------------------------------------------------------------
# 4. removable singularities, scales, warnings
# --------------------------------------------------------------------------
def _strict(fun, *args):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        # NaN / inf / overflow are errors; gradual underflow to 0 (r = 1e-300 s) is harmless
        with np.errstate(divide="raise", invalid="raise", over="raise", under="ignore"):
            return [np.asarray(v, dtype=float) for v in fun(*args)]


@pytest.mark.parametrize("nu", NUS)
@pytest.mark.parametrize("s", [1.0, 1e-9, 1e9])
def test_centre(s, nu):
    b = beta_of_nu(nu)
    w, u, du = _strict(pressure_disc, 0.0, s, nu)
    assert (w, u, du) == (pytest.approx(2 * s, rel=1e-15), 0.0, pytest.approx(-b, rel=1e-15))
    w, u, du = _strict(shear_disc, 0.0, s, nu)
    assert w == pytest.approx(-b * s**2, rel=1e-15, abs=0) and u == 0.0
    assert du == pytest.approx(s, rel=1e-14)
    for eps in [1e-300, 1e-15, 1e-8]:
        r = eps * s
        w, u, du = _strict(pressure_disc, r, s, nu)
        assert abs(w - 2 * s) <= 1e-14 * s and abs(u + b * r) <= 1e-15 * r
        w, u, du = _strict(shear_disc, r, s, nu)
        assert abs(w + b * s**2) <= 1e-14 * s**2
        assert abs(u - s * r) <= 1e-14 * s * r + s * r * eps**2  # u = s r (1 + O(r^2/s^2))
        assert abs(du - s) <= 1e-14 * s + 3 * s * eps**2


def _log_asymptote(r, s):
    """du/dr of shear_disc near r = s (both sides), delta = |r - s|/s:

    du/dr = (2 s / pi) [10/3 - ln(8/delta)] + O(delta ln delta).

    From K(m) = ln 4 - ln(1-m)/2 + O((1-m) ln), E -> 1 with 1-m ~ 2 delta. The coefficient
    -(2/pi) q(s) ln(1/delta) is the plane-strain result for a jump of q across the edge:
    du/dx = -(2/(pi E*)) PV int q(xi)/(x - xi) dxi.
    """
    delta = abs(r - s) / s
    return 2 * s / math.pi * (10.0 / 3.0 - math.log(8.0 / delta))


@pytest.mark.parametrize("nu", NUS)
@pytest.mark.parametrize("s", [1.0, 2.0, 0.5, 3.7, 1e-9, 1e9])
def test_edge(s, nu):
    b = beta_of_nu(nu)
    wp, up, dup = _strict(pressure_disc, s, s, nu)
    assert wp == pytest.approx(4 * s / math.pi, rel=1e-15) and up == pytest.approx(-b * s, rel=1e-15)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ws, us, dus = (np.asarray(v) for v in shear_disc(s, s, nu))  # 0 * inf inside is guarded
    assert ws == 0.0 and us == pytest.approx(4 * s**2 / (3 * math.pi), rel=1e-15)
    assert dus == -np.inf or dus < -1e3 * s  # log-infinite
    for rel in [1e-15, 2.0**-52, 1e-12, 2.0**-40, 1e-9]:
        for r in [s * (1 - rel), s * (1 + rel)]:
            p = _strict(pressure_disc, r, s, nu)
            q = _strict(shear_disc, r, s, nu)
            assert all(np.isfinite(v) for v in p + q)
            # continuity of w and u across the edge
            slope = 3 * max(1.0, math.log(1 / rel))  # |d/dr| <~ log for w_p, u_s
            assert abs(p[0] - wp) <= (1e-15 + slope * rel) * s
            assert abs(p[1] - up) <= (1e-15 + rel) * s
            assert abs(q[0] - ws) <= (1e-15 + 2 * rel) * s**2
            assert abs(q[1] - us) <= (1e-15 + slope * rel) * s**2
            # pressure: du jumps from -beta to +beta
            assert p[2] == pytest.approx(-b if r <= s else b, rel=1e-8, abs=1e-15)
            # shear: log asymptote; tolerance = truncation + conditioning (1 ulp of r or r/s)
            asym = _log_asymptote(r, s)
            delta = abs(r - s) / s
            tol = 1e-9 * abs(asym) + 2 * s / math.pi * (10 * delta * math.log(1 / delta) + 4 * 2.2e-16 / delta)
            assert abs(q[2] - asym) <= tol, (rel, q[2], asym)
    # exactly representable cases (s a power of two): tight
    if s in (1.0, 2.0, 0.5):
        for rel in [2.0**-40, 2.0**-45, 2.0**-50]:
            for r in [s * (1 - rel), s * (1 + rel)]:
                dus_r = _strict(shear_disc, r, s, nu)[2]
                assert dus_r == pytest.approx(_log_asymptote(r, s), rel=1e-10)


@pytest.mark.parametrize("nu", NUS)
def test_zero_radius_disc(nu):
    r = np.array([0.0, 1e-12, 0.5, 1.0, 1e8])
    for fun in (pressure_disc, shear_disc):
        for v in _strict(fun, r, 0.0, nu):
            assert v.shape == r.shape and np.all(v == 0.0)
        # continuity s -> 0 at fixed r
        tiny = 1e-13  # != any r (r = s is the log-infinite edge of du_shear)
        w, u, du = _strict(fun, r, tiny, nu)
        assert np.all(np.abs(w) <= 2 * tiny) and np.all(np.abs(u) <= tiny) and np.all(np.isfinite(du))
        assert np.all(np.abs(w[2:]) <= tiny**2 / r[2:] * 1.2)


SCALE_X = [0.0, 1e-6, 0.25, 0.5, 0.75, 0.999, 1.0, 1.001, 1.5, 2.0, 4.0, 10.0, 1e4]


@pytest.mark.parametrize("nu", [0.0, 0.3, 0.45])
@pytest.mark.parametrize("lam", [1e-9, 1e9, 3.3e-5])
def test_scaling(lam, nu):
    x = np.array(SCALE_X)
    p1 = _strict(pressure_disc, x, 1.0, nu)
    pl = _strict(pressure_disc, lam * x, lam, nu)
    s1 = _strict(shear_disc, x, 1.0, nu)
    sl = _strict(shear_disc, lam * x, lam, nu)
    fin = x != 1.0  # du of the shear disc is -inf exactly at the edge
    for got, ref, k in [(pl[0], p1[0], 1), (pl[1], p1[1], 1), (pl[2], p1[2], 0), (sl[1], s1[1], 2)]:
        np.testing.assert_allclose(got, lam**k * ref, rtol=1e-13, atol=0)
    # w_shear = -beta (s^2 - r^2): the rounding of r = lam x is amplified by 1/(1 - x^2) (conditioning)
    np.testing.assert_allclose(sl[0], lam**2 * s1[0], rtol=1e-13, atol=4e-16 * lam**2)
    np.testing.assert_allclose(sl[2][fin], lam * s1[2][fin], rtol=1e-12, atol=0)
    assert np.all(np.isfinite(np.concatenate(p1 + pl + [s1[0], s1[1], sl[0], sl[1]])))
    assert sl[2][~fin][0] == -np.inf or sl[2][~fin][0] < -1e3 * lam


# --------------------------------------------------------------------------
# 5. continuity across the series / closed-form switch (parameter 0.25)
# --------------------------------------------------------------------------
def _neighbours(r0, k=3):
    lo, hi, out = r0, r0, [r0]
    for _ in range(k):
        lo, hi = np.nextafter(lo, 0.0), np.nextafter(hi, np.inf)
        out = [lo] + out + [hi]
    return np.array(out)


@pytest.mark.parametrize("nu", [0.0, 0.3])
@pytest.mark.parametrize("s", [1.0, 3.7, 1e-3, 6.1e4])
@pytest.mark.parametrize("where", ["outside", "inside"])
def test_series_switch_continuity(where, s, nu):
    r0 = 2 * s if where == "outside" else s / 2
    r = _neighbours(r0)
    par = (s / r) ** 2 if where == "outside" else (r / s) ** 2
    assert np.any(par < 0.25) and np.any(par >= 0.25)  # both branches are exercised
    p = _strict(pressure_disc, r, s, nu)
    q = _strict(shear_disc, r, s, nu)
    for vals, scale in [(p[0], s), (p[1], s), (p[2], 1.0), (q[0], s**2), (q[1], s**2), (q[2], s)]:
        assert np.ptp(vals) <= 1e-14 * scale
    # and both sides equal the independent reference at the switch
    if where == "outside":
        for rr, pw, qu, qd in zip(r, p[0], q[1], q[2]):
            sw, _ = series_pressure_w(rr, s)
            su, sdu = series_shear_u(rr, s)
            assert abs(pw - sw) <= 1e-14 * s
            assert abs(qu - su) <= 1e-14 * s**2
            assert abs(qd - sdu) <= 1e-14 * s
    else:
        ref = direct_polar(r0, s, nu)
        assert np.all(np.abs(p[0] - ref["wp"]) <= 1e-14 * s)
        assert np.all(np.abs(q[1] - ref["us"]) <= 1e-14 * s**2)


# --------------------------------------------------------------------------
# 6. against mpmath (independent high-precision closed forms), random and extreme
# --------------------------------------------------------------------------
def _mp():
    return pytest.importorskip("mpmath")


def _mp_kernels(r, s, nu):
    """(w, u, du) of both loads from the Appendix closed forms in mpmath, at the exact r, s."""
    mpmath = _mp()
    mp = mpmath.mp
    lo, hi = min(r, s), max(r, s)
    cancel = 2 * max(0.0, -2 * math.log10(lo / hi)) if lo > 0 else 0.0  # digits lost at m -> 0
    with mpmath.workdps(int(60 + cancel)):
        r, s = mp.mpf(r), mp.mpf(s)
        nu = mp.mpf(nu)
        b = (1 - 2 * nu) / (2 * (1 - nu))
        c = 4 / (3 * mp.pi)
        if r <= s:
            m = (r / s) ** 2
            K, E = (mp.ellipk(m), mp.ellipe(m)) if m < 1 else (mp.inf, mp.mpf(1))
            p = (4 / mp.pi * s * E, -b * r, -b)
            if r == 0:
                q = (-b * s**2, mp.mpf(0), c * s * 3 * mp.pi / 4)
            elif m == 1:
                q = (mp.mpf(0), c * s**2, -mp.inf)
            else:
                q = (-b * (s**2 - r**2), c * s**3 / r * ((2 * m - 1) * E - (m - 1) * K),
                     c * s**3 / r**2 * ((4 * m + 1) * E - (2 * m + 1) * K))
        else:
            m = (s / r) ** 2
            K, E = mp.ellipk(m), mp.ellipe(m)
            p = (4 / mp.pi * r * (E - (1 - m) * K), -b * s**2 / r, b * m)
            q = (mp.mpf(0), c * s**2 * ((2 / m - 1) * E - 2 * (1 / m - 1) * K),
                 -2 * c * r * (2 * (K - E) - m * (E + K) / 2))
        return [float(v) for v in p], [float(v) for v in q]


def _mp_points():
    rng = np.random.default_rng(2024)
    edge = 1.0 + np.array([-1, 1])[:, None] * 10.0 ** -np.arange(1, 16)[None, :]
    return np.concatenate([
        rng.uniform(0.0, 3.0, 100),  # random
        10.0 ** rng.uniform(-12, 12, 50),  # r << s and r >> s
        edge.ravel(), [0.0, 1.0, 0.5, 2.0, 0.25, 4.0, 1e-150, 1e150],  # extremes
    ])


@pytest.mark.parametrize("s", [1.0, 0.37, 2.5e3])
def test_kernels_against_mpmath(s):
    """Every output within 1e-13 of its scale, and of its value where it has a removable
    singularity (r -> 0, r >> s) or exceeds its scale (du/dr of the shear at r -> s).

    Scales: s (w, u of the pressure; du/dr of the shear), 1 (du/dr of the
    pressure), s^2 (w, u of the shear). The shear's w = -beta (s^2 - r^2) near
    r = s is limited by the rounding of r^2 (its conditioning), not by the kernel.
    """
    nu = 0.3
    r = _mp_points() * s
    got_p = pressure_disc(r, s, nu)
    got_q = shear_disc(r, s, nu)
    scales = ((s, s, 1.0), (s * s, s * s, s))
    worst = 0.0
    for i, ri in enumerate(r):
        ref_p, ref_q = _mp_kernels(float(ri), s, nu)
        x = ri / s
        for got, ref, scale, shear in ((got_p, ref_p, scales[0], False),
                                       (got_q, ref_q, scales[1], True)):
            for k in range(3):
                g, t = float(got[k][i]), ref[k]
                if math.isinf(t):
                    assert g == t
                    continue
                if shear and k == 0:  # -beta (s^2 - r^2): conditioning of the difference
                    assert abs(g - t) <= 4e-16 * scale[0], (x, g, t)
                    continue
                if x < 1e-2 or x > 1e2 or abs(t) > scale[k]:
                    rel = abs(g - t) / abs(t) if t else abs(g)
                else:
                    rel = abs(g - t) / max(abs(t), scale[k])
                worst = max(worst, rel)
                assert rel <= 1e-13, (x, shear, k, g, t)
    print(f"s = {s}: worst relative error {worst:.1e}")


def _fit_combination(name, deg=10, nfix=2):
    """Regenerate the (P, R) coefficients of ``disc._FITS[name]`` with mpmath.

    f(m) = P(m1) + ln(m1) R(m1), m1 = 1 - m: R's first ``nfix`` coefficients
    are those of the exact logarithmic part (R_K = -K(m1)/pi, R_E = -(K(m1) -
    E(m1))/pi, times the combination's factors), the rest of R and all of P a
    least-squares fit relative to |f| on 4 (2 deg + 2) Chebyshev points of
    [0, 1] in m1 plus m1 = 10^-1 ... 10^-19.5 (QR at 50 digits).
    """
    mpmath = _mp()
    mp = mpmath.mp
    combos = {  # f = (a(m) E + b(m) K) / m^p with polynomial a, b
        "E": ((1,), (0,), 0), "A1": ((1,), (-1, 1), 1), "g1": ((-1, 2), (1, -1), 1),
        "gd1": ((1, 4), (-1, -2), 1), "h1": ((2, -1), (-2, 2), 2),
        "hd2": ((-2, -0.5), (2, -0.5), 2),
    }
    a, b, p = combos[name]
    with mpmath.workdps(50):
        def poly(coef, m):
            return sum(mp.mpf(c) * m**i for i, c in enumerate(coef))

        def f(m):
            return (poly(a, m) * mp.ellipe(m) + poly(b, m) * mp.ellipk(m)) / m**p

        def r_exact(m1):
            m = 1 - m1
            k1, e1 = mp.ellipk(m1), mp.ellipe(m1)
            return -(poly(a, m) * (k1 - e1) + poly(b, m) * k1) / (mp.pi * m**p)

        fixed = mp.taylor(r_exact, 0, nfix - 1)
        nsamp = 4 * (2 * deg + 2)
        xs = [(1 + mp.cos(mp.pi * (j + mp.mpf(1) / 2) / nsamp)) / 2 for j in range(nsamp)]
        xs += [mp.mpf(10) ** (-mp.mpf(k) / 2) for k in range(2, 40)]
        rows, rhs = [], []
        for v in (v for v in xs if 0 < v < 1):
            y = f(max(1 - v, mp.mpf("1e-40")))
            lg = mp.log(v)
            rows.append([v**j / abs(y) for j in range(deg + 1)]
                        + [lg * v**j / abs(y) for j in range(nfix, deg + 1)])
            rhs.append((y - lg * sum(fixed[j] * v**j for j in range(nfix))) / abs(y))
        c = mp.qr_solve(mp.matrix(rows), mp.matrix(rhs))[0]
        return ([float(v) for v in c[:deg + 1]],
                [float(v) for v in fixed] + [float(v) for v in c[deg + 1:]])


@pytest.mark.parametrize("name", ["E", "A1", "g1", "gd1", "h1", "hd2"])
def test_fit_coefficients_are_reproducible(name):
    """The stored coefficients are what the documented fit gives (provenance)."""
    P, R = _fit_combination(name)
    P0, R0 = disc._FITS[name]
    np.testing.assert_allclose(P, P0, rtol=1e-10, atol=1e-15)
    np.testing.assert_allclose(R, R0, rtol=1e-10, atol=1e-15)


# ----------------------------------------------------------------------------- 7.
# w(r) - w(0) without cancellation (the default method's rows of a tiny stick zone)
@pytest.mark.parametrize("s", [1.0, 1e-8, 3.7e2])
def test_axis_w_against_mpmath(s):
    """w(r; s) - w(0; s) of the pressure disc within 1e-14 of its own value (not of s),
    from r = 1e-9 s (where the plain difference of w has no correct digit) to 5 s;
    the shear's is beta min(r, s)^2 exactly."""
    mp = _mp()
    mp.mp.dps = 40
    t = np.array([1e-9, 1e-6, 1e-3, 0.1, 0.5, 0.7, 0.70710678, 0.72, 0.9, 0.999999, 1.0,
                  1.000001, 1.3, 5.0])
    r = t * s
    dw = disc.axis_w_disc(r, s, 0.3, "normal")[0]
    for ri, got in zip(r, dw):
        rr, ss = mp.mpf(float(ri)), mp.mpf(float(s))
        if rr <= ss:
            w = 4 / mp.pi * ss * mp.ellipe((rr / ss) ** 2)
        else:
            m = (ss / rr) ** 2
            w = 4 / mp.pi * rr * (mp.ellipe(m) - (1 - m) * mp.ellipk(m))
        ref = float(w - 2 * ss)
        assert abs(got - ref) <= 1e-14 * abs(ref), (ri / s, got, ref)
    dws = disc.axis_w_disc(r, s, 0.3, "shear")[0]
    assert np.array_equal(dws, beta_of_nu(0.3) * np.minimum(r, s) ** 2)
    # consistent with the kernels where the plain difference is accurate
    far = t >= 0.1
    plain = pressure_disc(r[far], s, 0.3)[0] - pressure_disc(0.0, s, 0.3)[0]
    assert np.allclose(dw[far], plain, rtol=0, atol=2e-15 * s)


@pytest.mark.parametrize("r0", [0.3, 1.0 - 4e-5])
def test_w_difference_against_mpmath(r0):
    """w(r; s) - w(r0; s) of the pressure disc within 1e-14 of its value where the load
    edge s is at least |r - r0| from the points (the plain difference loses 1e-12 ... 1e-11
    there), within 1e-15 s where s is between or next to them (the plain difference of
    the kernels, whose absolute round-off is ~1e-16 s)."""
    mp = _mp()
    mp.mp.dps = 40

    def w(r, s):
        r, s = mp.mpf(float(r)), mp.mpf(float(s))
        if r <= s:
            return 4 / mp.pi * s * mp.ellipe((r / s) ** 2)
        m = (s / r) ** 2
        return 4 / mp.pi * r * (mp.ellipe(m) - (1 - m) * mp.ellipk(m))

    width = 1.0 - r0 if r0 > 0.5 else 0.1
    for r in r0 + width * np.array([0.25, 0.75, 1.0 - 1e-4]):
        for s in (0.2, 0.9, r0 - 0.25 * width, r0 + 0.5 * width, r0 + width, 1.5):
            got = float(disc.w_difference_disc(np.array([r]), r0, np.array([s]), 0.3,
                                               "normal")[0][0])
            ref = float(w(r, s) - w(r0, s))
            far = max(s - max(r, r0), min(r, r0) - s, 0.0) >= abs(r - r0)
            tol = 1e-14 * abs(ref) if far else 1e-15 * s
            assert abs(got - ref) <= tol, (r, s, got, ref)
    sh = disc.w_difference_disc(np.array([r0 + 0.5 * width]), r0,
                                np.array([0.1, r0 + 0.25 * width, 2.0]), 0.3, "shear")[0]
    b = beta_of_nu(0.3)
    x = r0 + 0.5 * width
    want = [0.0] + [float(b * (mp.mpf(float(a)) ** 2 - mp.mpf(r0) ** 2))
                     for a in (r0 + 0.25 * width, x)]
    assert np.allclose(sh, want, rtol=1e-14, atol=0)


# ----------------------------------------------------------------------------- 8.
# the complete elliptic integrals of the difference rows (dw/dr of the pressure disc)
def _elliptic_arguments():
    """m1 = 1 - m over [0, inf]: Cephes' branch points, tiny values, the whole of (0, 1]."""
    rng = np.random.default_rng(18)
    machep = 2.0**-53
    special_points = [0.0, 5e-324, 1e-300, 1e-200, 1e-17, np.nextafter(machep, 0.0), machep,
                      np.nextafter(machep, 1.0), 2.0**-52, 1e-15, 0.25, 0.5, 1.0 - 2.0**-53,
                      1.0, np.nextafter(1.0, 2.0), 1.5, 1e10, np.inf]
    return np.concatenate([special_points, 10.0 ** rng.uniform(-320, 0, 2000),
                           10.0 ** rng.uniform(-16, 0, 20000), rng.random(20000),
                           1.0 + 10.0 ** rng.uniform(-16, 3, 2000)])


def _ulps(got, want):
    return np.abs(got - want) / np.spacing(np.abs(want))


def test_elliptic_integrals_against_scipy():
    """The vectorized Cephes forms of E and K give scipy.special's ellipe(1 - m1) and
    ellipkm1(m1) (an independent implementation, compiled C) to 2 ulp over m1 in [0, inf],
    the branches included (m1 <= 2^-53, m1 > 1, m1 = 0 and 1, inf); the rest of the
    difference is numpy's logarithm against the C library's."""
    m1 = _elliptic_arguments()
    for m in (1.0 - m1, -10.0 ** np.linspace(-16, 3, 200), np.array([0.0, 1.0, -np.inf])):
        got, want = disc._ellipe(m), special.ellipe(m)
        finite = np.isfinite(want)
        assert np.array_equal(got[~finite], want[~finite], equal_nan=True)
        assert _ulps(got[finite], want[finite]).max() <= 2.0
        assert np.mean(got == want) > 0.99  # the same operations: mostly the same bits
    got, want = disc._ellipkm1(m1), special.ellipkm1(m1)
    finite = np.isfinite(want)
    assert np.array_equal(got[~finite], want[~finite], equal_nan=True)
    assert _ulps(got[finite], want[finite]).max() <= 2.0
    assert np.mean(got == want) > 0.99
    assert np.isnan(disc._ellipkm1(np.array([-1e-300, -1.0]))).all()
    assert np.isnan(disc._ellipe(np.array([np.nextafter(1.0, 2.0), 2.0]))).all()


def test_e_minus_k_coefficients_are_the_cephes_differences():
    """The fused rows of E - K are the differences of the Cephes double coefficients,
    each formed exactly (rational arithmetic) and rounded once."""
    from fractions import Fraction

    def exact(coef):
        return [Fraction(c) for c in coef]

    p = [a - b for a, b in zip(exact(disc._ELLPE_P), exact(disc._ELLPK_P))]
    q = [a - b for a, b in zip(exact(disc._ELLPE_Q) + [Fraction(0)], exact(disc._ELLPK_Q))]
    stored = disc._E_MINUS_K[:, :, 0]
    assert stored[:, 0].tolist() == [float(v) for v in p]
    assert stored[:, 1].tolist() == [float(v) for v in q]


def test_e_minus_k_against_mpmath_and_scipy():
    """E(m) - K(m) (m = 1 - m1) in one pass: within 2 ulp of K of mpmath's value over
    0 < m1 <= 1, and 1e-12 relative to itself where it is at least 1e-3 (scipy's ellipe(1 -
    m1) - ellipkm1(m1): 2 ulp of K); equal to scipy's difference to 3 ulp of K; the branch
    points as scipy's."""
    mpmath = _mp()
    m1 = _elliptic_arguments()
    f = np.empty((3, disc._ELL_CHUNK))

    def e_minus_k(x):
        parts = [x[a:a + f.shape[1]] for a in range(0, x.size, f.shape[1])]
        return np.concatenate([disc._e_minus_k(p, np.empty(p.size), f) for p in parts])

    got = e_minus_k(m1)
    with np.errstate(invalid="ignore"):
        want = special.ellipe(1.0 - m1) - special.ellipkm1(m1)
    finite = np.isfinite(want)
    assert np.array_equal(got[~finite], want[~finite], equal_nan=True)
    k = special.ellipkm1(m1[finite])
    assert (np.abs(got[finite] - want[finite]) <= 3.0 * np.spacing(k)).all()
    rng = np.random.default_rng(7)
    sample = np.concatenate([m1[:14], rng.choice(m1[(m1 > 0.0) & (m1 <= 1.0)], 400)])
    sample = sample[(sample > 0.0) & (sample <= 1.0)]
    truth = []
    for v in sample:  # m = 1 - m1 held exactly: digits enough for the smallest m1
        with mpmath.workdps(30 + int(-math.log10(v))):
            m = 1 - mpmath.mpf(float(v))
            truth.append(float(mpmath.ellipe(m) - mpmath.ellipk(m)))
    truth = np.array(truth)
    ours = e_minus_k(sample)
    kk = special.ellipkm1(sample)
    assert (np.abs(ours - truth) <= 2.0 * np.spacing(kk)).all()
    away = np.abs(truth) >= 1e-3  # (E - K -> 0 like -pi m/4 as m -> 0: an absolute bound)
    assert (np.abs(ours - truth)[away] <= 1e-12 * np.abs(truth[away])).all()


def test_dwdr_pressure_against_mpmath():
    """dw/dr of the unit pressure disc, (4/pi)(s/r)(E - K)(r^2/s^2) inside and
    (4/pi)(E - K)(s^2/r^2) outside, to 1e-12 of mpmath's value, on arrays of one and two
    dimensions (a row longer than a pass of scratch rows) and at r = 0 (s/r replaced by s,
    E - K = 0 there)."""
    mpmath = _mp()
    rng = np.random.default_rng(11)
    s = np.concatenate([[1.0, 0.5, 2.0], rng.uniform(0.01, 2.0, disc._ELL_CHUNK + 7)])
    t = np.concatenate([[0.0, 0.5 - 1e-9, 0.3], rng.uniform(0.01, 2.0, disc._ELL_CHUNK + 7)])
    got = disc._dwdr_pressure(t, s)
    got2 = disc._dwdr_pressure(np.stack([t, t[::-1]]), s[None, :])
    assert np.array_equal(got2[0], got)
    assert np.array_equal(got2[1], disc._dwdr_pressure(t[::-1], s))
    idx = np.concatenate([np.arange(3), rng.choice(np.arange(3, t.size), 200, replace=False)])
    with mpmath.workdps(40):
        for i in idx:
            r, a = mpmath.mpf(float(t[i])), mpmath.mpf(float(s[i]))
            if r < a:
                m = (r / a) ** 2
                scale = a / r if r > 0 else a
                ref = 4 / mpmath.pi * scale * (mpmath.ellipe(m) - mpmath.ellipk(m))
            else:
                m = (a / r) ** 2
                ref = 4 / mpmath.pi * (mpmath.ellipe(m) - mpmath.ellipk(m))
            ref = float(ref)
            assert abs(got[i] - ref) <= 1e-12 * abs(ref) + 1e-300, (t[i], s[i], got[i], ref)
