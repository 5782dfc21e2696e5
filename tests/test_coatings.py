"""A coated body: an elastic layer bonded to an elastic half-space (``base="elastic"``).

References (none computed by the code under test):

* the transfer functions from a numerical 6x6 solve of the axisymmetric Love
  strain-function problem of the layer and the substrate, written out here
  (the module solves the plane-strain Airy problem for the correction field);
* the classical closed form of the normal transfer function of a layer
  bonded to a half-space (Dundurs-type constants; the form used by Perriot &
  Barthel 2004 after King 1987), typed in here, which reduces to the bonded
  rigid base for E2/E1 -> inf and to 1 for equal materials;
* the half-space kernels of ``contactlib.kernels.disc`` and the rigid-base
  layer kernels (both verified in their own tests) as the limits;
* direct ``scipy.integrate.quad`` of the Hankel integrals of the remainders;
* the frictionless load of a rigid sphere on the coated body from a Nystrom
  solution of the Fredholm equation of the second kind of the layered Hertz
  problem (Sneddon's representation, the kernel by ``quad`` of the typed-in
  transfer function), written out here;
* Betti's reciprocal theorem;
* convergence in n and the error estimate against the fourfold refinement.

Units: the layer's E* = 1 (E1* = E1/(1 - nu^2)); m = E1*/E2*.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from scipy import integrate, special

import contactlib
from contactlib.kernels import disc, layer

NU = 0.3
# (layer nu, E2/E1, substrate nu): soft and stiff substrates, both compressibilities
MATERIALS = [(0.3, 0.1, 0.2), (0.45, 10.0, 0.3), (0.0, 3.0, 0.5), (0.5, 0.01, 0.3),
             (0.3, 1e6, 0.3)]


def stiffness_ratio(nu, modulus, nu2):
    """m = E1*/E2*."""
    return (1.0 - nu2**2) / ((1.0 - nu**2) * modulus)


# --- transfer functions from the Love strain function ---------------------------
def _love_rows(d, nu, g):
    """(u_r, u_z, s_z, t_rz) rows of the basis (columns f, f', f'', f''') of a material of
    shear modulus g (Timoshenko & Goodier, as in test_kernels_layer.py)."""
    f, f1, f2, f3 = d.T
    lf, lf1 = f2 - f, f3 - f1
    return (f1 / 2.0 / g, (2 * (1 - nu) * lf - f2) / 2.0 / g, (2 - nu) * lf1 - f3,
            -((1 - nu) * lf - f2))


def love_coated(t, nu, modulus, nu2):
    """(Cww, Cwu, Cuu, u under pressure) of a layer (0 < z < t, G = 1) bonded to a
    half-space z > t (G2 = modulus (1 + nu)/(1 + nu2)); k = 1, plain 6x6 solve."""

    def layer_basis(z):
        e1, e2 = np.exp(z - t), np.exp(-z)
        return np.array([[e1, e1, e1, e1], [z * e1, (z + 1) * e1, (z + 2) * e1, (z + 3) * e1],
                         [e2, -e2, e2, -e2], [z * e2, (1 - z) * e2, (z - 2) * e2, (3 - z) * e2]])

    sub = np.array([[1.0, -1.0, 1.0, -1.0], [0.0, 1.0, -2.0, 3.0]])  # e^-y, y e^-y at y = 0
    g2 = modulus * (1 + nu) / (1 + nu2)
    ur0, uz0, sz0, trz0 = _love_rows(layer_basis(0.0), nu, 1.0)
    lt = _love_rows(layer_basis(t), nu, 1.0)
    st = _love_rows(sub, nu2, g2)
    a = np.zeros((6, 6))
    a[0, :4], a[1, :4] = sz0, trz0
    for i in range(4):
        a[2 + i, :4], a[2 + i, 4:] = lt[i], -st[i]
    cp = np.linalg.solve(a, [-1.0, 0, 0, 0, 0, 0])
    cq = np.linalg.solve(a, [0, -1.0, 0, 0, 0, 0])
    half = 1.0 / (1.0 - nu)  # E*/2 with G = 1
    return (uz0 @ cp[:4] * half, -uz0 @ cq[:4] * half, ur0 @ cq[:4] * half,
            ur0 @ cp[:4] * half)


def closed_form_cww_remainder(t, nu, modulus, nu2):
    """Cww - 1 of the closed form C = (1 + 4 b t e - a b e^2)/(1 - (a + b + 4 b t^2) e + a b e^2),
    e = exp(-2t), alpha = G1/G2, a = (alpha k2 - k1)/(1 + alpha k2), b = (alpha - 1)/(alpha + k1),
    k = 3 - 4 nu; written as a difference of the numerator and denominator (no cancellation)."""
    alpha = (1 + nu2) / ((1 + nu) * modulus)
    k1, k2 = 3 - 4 * nu, 3 - 4 * nu2
    a, b = (alpha * k2 - k1) / (1 + alpha * k2), (alpha - 1) / (alpha + k1)
    e = np.exp(-2 * t)
    den = 1 - (a + b + 4 * b * t * t) * e + a * b * e * e
    return (4 * b * t * e + (a + b + 4 * b * t * t) * e - 2 * a * b * e * e) / den


@pytest.mark.parametrize("nu, modulus, nu2", MATERIALS)
def test_transfer_functions_match_the_love_solution(nu, modulus, nu2):
    """C = beta-part + remainder against the Love 6x6 solve (1e-11), and Betti in
    transform space (u under pressure = -Cwu) in the Love solve itself."""
    sub = layer.Substrate(modulus, nu2)
    for t in [1e-3, 0.05, 0.5, 1.0, 2.5, 8.0, 20.0]:
        ref = love_coated(t, nu, modulus, nu2)
        got = [float(v) for v in layer.transfer(t, nu, sub)]
        scale = max(1.0, stiffness_ratio(nu, modulus, nu2))
        assert np.allclose(got, ref[:3], rtol=1e-11, atol=1e-13 * scale), (t, got, ref)
        assert abs(ref[3] + ref[1]) < 1e-12 * scale


@pytest.mark.parametrize("nu, modulus, nu2", MATERIALS)
def test_normal_transfer_function_matches_the_closed_form(nu, modulus, nu2):
    """Rww against the typed-in closed form, relative 1e-9 where |R| > 1e-12 (t <= 12)."""
    t = np.concatenate([np.geomspace(1e-6, 1.0, 30), np.linspace(1.0, 12.0, 45)])
    got = layer.remainder_transfer(t, nu, layer.Substrate(modulus, nu2))[0]
    ref = closed_form_cww_remainder(t, nu, modulus, nu2)
    keep = np.abs(ref) > 1e-12
    np.testing.assert_allclose(got[keep], ref[keep], rtol=1e-9)


def test_transfer_limits():
    """t -> 0: the substrate's half-space in the layer's units (m - 1, m beta2 - beta,
    m - 1); equal materials: no remainder; E2/E1 -> inf: the bonded rigid base, with a
    first-order difference in E1/E2."""
    def beta(v):
        return (1 - 2 * v) / (2 * (1 - v))

    for nu, modulus, nu2 in MATERIALS:
        m = stiffness_ratio(nu, modulus, nu2)
        # R(0) by linear extrapolation from t = 1e-9, 2e-9: the slope is O(m^2) (a stiff
        # layer on a soft substrate bends), the curvature error O(m^3 t^2) < 1e-11
        got = layer.remainder_transfer(np.array([1e-9, 2e-9]), nu,
                                       layer.Substrate(modulus, nu2))
        np.testing.assert_allclose([float(2 * g[0] - g[1]) for g in got],
                                   [m - 1, m * beta(nu2) - beta(nu), m - 1],
                                   rtol=1e-9, atol=1e-12)
    t = np.concatenate([np.geomspace(1e-6, 1.0, 20), np.linspace(1.0, 40.0, 40), [400.0]])
    for nu in (0.0, 0.3, 0.5):
        same = layer.remainder_transfer(t, nu, layer.Substrate(1.0, nu))
        assert max(np.max(np.abs(r)) for r in same) < 1e-15
        bonded = layer.remainder_transfer(t, nu, "bonded")
        diff = {e: max(np.max(np.abs(a - b)) for a, b in zip(
            layer.remainder_transfer(t, nu, layer.Substrate(e, 0.3)), bonded))
            for e in (1e5, 1e6)}
        assert diff[1e6] < 2e-6  # measured ~1e-6 x E1/E2 ... 1.3e-6 at E2/E1 = 1e6
        assert 9.9 < diff[1e5] / diff[1e6] < 10.1  # first order in E1/E2


def test_overflow_free_at_large_t():
    t = np.array([50.0, 300.0, 800.0, 1e4])
    for r in layer.remainder_transfer(t, 0.3, layer.Substrate(0.01, 0.3)):
        assert np.all(np.isfinite(r)) and np.all(np.abs(r) < 1e-35)


# --- kernels ---------------------------------------------------------------------
def _love_remainders(t, nu, modulus, nu2):
    beta = (1 - 2 * nu) / (2 * (1 - nu))
    cww, cwu, cuu, _ = love_coated(t, nu, modulus, nu2)
    return cww - 1.0, cwu - beta, cuu - 1.0


def quad_remainder(kind, r, s, h, nu, modulus, nu2):
    """(dw, du, ddu) = coated - half-space by quad of the Hankel integrals in t = k h
    (t < 30; the remainders are < 1e-20 beyond), the transfer functions by the Love solve."""
    idx = {"ww": 0, "wu": 1, "uu": 2}
    rho, sig = r / h, s / h

    def integral(name, f):
        def g(t):
            return _love_remainders(t, nu, modulus, nu2)[idx[name]] * f(t)
        val, _ = integrate.quad(g, 0.0, 30.0, points=np.arange(0.5, 30.0, 0.5), limit=800,
                                epsabs=1e-13, epsrel=1e-12)
        return val

    def dj1(x):
        return 0.5 * (special.j0(x) - special.jv(2, x))

    if kind == "pressure":
        return (2 * s * integral("ww", lambda t: special.j1(sig * t) * special.j0(rho * t) / t),
                -2 * s * integral("wu", lambda t: special.j1(sig * t) * special.j1(rho * t) / t),
                -2 * sig * integral("wu", lambda t: special.j1(sig * t) * dj1(rho * t)))
    return (-2 * s * s * integral("wu", lambda t: special.jv(2, sig * t) * special.j0(rho * t) / t),
            2 * s * s * integral("uu", lambda t: special.jv(2, sig * t) * special.j1(rho * t) / t),
            2 * s * sig * integral("uu", lambda t: special.jv(2, sig * t) * dj1(rho * t)))


# (r, s, h): table cells, the series corner (h = 5) and a thin layer
POINTS = [(0.0, 1.0, 1.0), (0.3, 1.0, 1.0), (2.5, 1.0, 1.0), (0.7, 1.5, 0.4), (0.5, 1.0, 5.0),
          (0.2, 0.9, 0.15)]


@pytest.mark.parametrize("kind", ["pressure", "shear"])
@pytest.mark.parametrize("nu, modulus, nu2", [(0.3, 0.1, 0.2), (0.45, 10.0, 0.3)])
def test_kernels_against_hankel_quadrature(kind, nu, modulus, nu2):
    """1e-9 of the scale (max(r, s)^p and its derivative) times max(1, m)."""
    sub = layer.Substrate(modulus, nu2)
    fn = layer.pressure_disc if kind == "pressure" else layer.shear_disc
    hs = disc.pressure_disc if kind == "pressure" else disc.shear_disc
    m = max(1.0, stiffness_ratio(nu, modulus, nu2))
    for r, s, h in POINTS:
        got = np.array(fn(r, s, nu, h, sub)) - np.array(hs(r, s, nu))
        ref = np.array(quad_remainder(kind, r, s, h, nu, modulus, nu2))
        p = 1 if kind == "pressure" else 2
        scale = m * np.array([max(r, s) ** p, max(r, s) ** p, max(r, s) ** (p - 1)])
        assert np.all(np.abs(got - ref) <= 1e-9 * scale), (r, s, h, got, ref)


@pytest.mark.parametrize("modulus, nu2", [(0.01, 0.3),
                                          pytest.param(10.0, 0.5, marks=pytest.mark.slow),
                                          pytest.param(1e6, 0.3, marks=pytest.mark.slow)])
def test_table_against_the_module_quadrature(modulus, nu2):
    """Implementation check over the whole range (docs: <= 1e-11 of scale x max(1, |m - 1|);
    measured 6e-12 at E2/E1 = 1e-2, 4e-12 at 10, 3e-12 at 1e6)."""
    sub = layer.Substrate(modulus, nu2)
    tab = layer.layer_table(NU, sub)
    rng = np.random.default_rng(11)
    rho = np.concatenate([rng.uniform(0, layer.RATIO_MAX, 150), rng.uniform(0, 0.3, 30)])
    sig = np.concatenate([rng.uniform(0, layer.RATIO_MAX, 150), rng.uniform(0, 0.3, 30)])
    big = np.maximum(1.0, np.maximum(rho, sig))
    m = max(1.0, abs(stiffness_ratio(NU, modulus, nu2) - 1.0))
    for kind, scales in (("pressure", (1, 1, 1)), ("shear", (big**2, big**2, big))):
        ref = [np.diag(v) for v in layer._remainder_quadrature(kind, rho, sig, NU, sub)]
        got = layer._remainders(kind, rho, sig, tab)
        for f in range(3):
            assert np.max(np.abs(got[f] - ref[f]) / (m * scales[f])) < 1e-11, (kind, f)


@pytest.mark.parametrize("nu, modulus, nu2, h", [(0.3, 0.1, 0.2, 0.5), (0.5, 10.0, 0.3, 0.2)])
def test_betti_reciprocity(nu, modulus, nu2, h):
    """int_0^s2 r u_p(r; s1) 2 pi r dr = int_0^s1 w_q(r; s2) 2 pi r dr."""
    sub = layer.Substrate(modulus, nu2)
    g, wg = np.polynomial.legendre.leggauss(60)

    def integral(f, hi, brk):
        edges = [0.0, brk, hi] if 0 < brk < hi else [0.0, hi]
        return sum(0.5 * (up - lo) * np.sum(wg * f(0.5 * (up - lo) * g + 0.5 * (up + lo)))
                   for lo, up in itertools.pairwise(edges))

    for s1, s2 in ((1.0, 0.6), (0.5, 1.3), (1.0, 1.0)):
        lhs = integral(lambda r: r * layer.pressure_disc(r, s1, nu, h, sub)[1] * 2 * np.pi * r,
                       s2, s1)
        rhs = integral(lambda r: layer.shear_disc(r, s2, nu, h, sub)[0] * 2 * np.pi * r, s1, s2)
        assert abs(lhs - rhs) <= 1e-10 * max(abs(lhs), 1e-3), (s1, s2, lhs, rhs)


def test_thin_layer_kernels_tend_to_the_substrate_half_space():
    """h -> 0: m times the substrate's half-space kernels (disc, nu2), first order in h/s
    (the layer's own compliance, ~h/E1*)."""
    nu, modulus, nu2 = 0.3, 2.0, 0.2
    sub, m = layer.Substrate(modulus, nu2), stiffness_ratio(nu, modulus, nu2)
    r = np.array([0.0, 0.4, 0.8])
    ref_w = disc.pressure_disc(r, 1.0, nu2)[0]
    dep = []
    for h in (0.1, 0.05):
        w = layer.pressure_disc(r, 1.0, nu, h, sub)[0]
        dep.append(np.max(np.abs(w / (m * ref_w) - 1.0)))
    assert dep[1] < 0.06
    assert 1.8 < dep[0] / dep[1] < 2.2, dep  # first order in h


# --- the contact ---------------------------------------------------------------------
def _k(c, n, nu=NU, **kw):
    return contactlib.solve("sphere", nu, stick_ratio=c, n=n, energy=False, **kw)


@pytest.mark.parametrize("slab, kw", [
    (1.0, {}), (5.0, {}), (2.0, {"indenter_modulus": 2.0, "indenter_nu": 0.2}),
    (2.0, {"profile": "cone"})])
def test_equal_materials_give_the_half_space(slab, kw):
    """E2/E1 = 1, nu2 = nu: the remainder is < 1e-15 in transform and the tables interpolate
    it to < 1e-11; k and the load equal the half-space's to 1e-9 (measured 5e-12, 3e-13;
    an elastic indenter 6e-11), also for an elastic indenter and a cone. The cone's k
    itself carries round-off of about 1e-9 (the half-space case alone spreads by 1.2e-9
    over the OpenBLAS kernels and numpy 2.0/2.4; the paraboloid's by 2e-10), so it is
    held to 1e-8 (measured 5e-10 here, 2.5e-9 with numpy 2.0), four decades below its
    error estimate (3.9e-4)."""
    rtol = 1e-8 if kw.get("profile") == "cone" else 1e-9
    half = _k(0.5, 128, **kw)
    coated = _k(0.5, 128, slab_ratio=slab, base="elastic", substrate_modulus=1.0, **kw)
    assert abs(coated.friction_coefficient / half.friction_coefficient - 1.0) < rtol
    assert abs(coated.load_ratio / half.load_ratio - 1.0) < rtol


def test_stiff_substrate_gives_the_bonded_rigid_base():
    """E2/E1 -> inf: the bonded base, the difference first order in E1/E2 (k at a/h = 1,
    measured relative 2.0e-5 and 2.0e-6 at 1e5 and 1e6; the load at a/h = 5 (where k reverses
    on the bonded base), 3.5e-5 and 3.5e-6); the coefficient ~2-4 as the transform's ~1."""
    bonded = _k(0.5, 128, slab_ratio=1.0, base="bonded")
    thin = _k(0.0, 128, slab_ratio=5.0, base="bonded")
    dk, dp = {}, {}
    for e in (1e5, 1e6):
        dk[e] = _k(0.5, 128, slab_ratio=1.0, base="elastic", substrate_modulus=e
                   ).friction_coefficient / bonded.friction_coefficient - 1.0
        dp[e] = _k(0.0, 128, slab_ratio=5.0, base="elastic", substrate_modulus=e
                   ).load_ratio / thin.load_ratio - 1.0
    for d in (dk, dp):
        assert abs(d[1e6]) < 1e-5
        assert 9.8 < d[1e5] / d[1e6] < 10.2


def test_thick_layer_gives_the_coating_half_space():
    """a/h -> 0: the coating's half-space; k departs at second order in a/h (the uniform
    first-order shift of w only moves the approach): measured 2.17 (a/h)^2 at E2/E1 = 0.1."""
    half = _k(0.5, 128)
    dep = [_k(0.5, 128, slab_ratio=r, base="elastic", substrate_modulus=0.1, substrate_nu=0.2
              ).friction_coefficient / half.friction_coefficient - 1.0 for r in (0.01, 0.02)]
    assert dep[0] < 3e-4
    assert 3.9 < dep[1] / dep[0] < 4.1


# --- frictionless load against a Fredholm solution --------------------------------------
def fredholm_load_ratio(h, nu, modulus, nu2, n_nodes):
    """P/P_Hertz (P_Hertz = 4 E1* a^3/(3R)) of a rigid sphere, frictionless, a = R = 1.

    Sneddon: p(r) = -int_r^1 phi'(y)/sqrt(y^2 - r^2) dy, P(k) = int_0^1 phi(y) cos(ky) dy;
    w = 2 int C(kh) P(k) J0(kr) dk (E1* = 1) and the Abel transform of w = delta - r^2/2
    give pi phi(x) + int_0^1 phi(y) [K(x - y) + K(x + y)] dy = delta - x^2, with
    K(u) = int_0^inf (C(kh) - 1) cos(ku) dk; phi(1) = 0 fixes delta; P = 2 pi int phi.
    Nystrom on n_nodes Gauss-Legendre points (K is analytic and smooth on the scale h).
    """
    x, w = np.polynomial.legendre.leggauss(n_nodes)
    x, w = 0.5 * (x + 1.0), 0.5 * w

    def kern(u):
        val, _ = integrate.quad(lambda t: closed_form_cww_remainder(t, nu, modulus, nu2), 0.0,
                                60.0, weight="cos", wvar=abs(u) / h, limit=400, epsabs=1e-14)
        return val / h

    diff, summ = x[:, None] - x[None, :], x[:, None] + x[None, :]
    uniq, inv = np.unique(np.round(np.abs(np.concatenate([diff.ravel(), summ.ravel()])), 13),
                          return_inverse=True)
    kv = np.array([kern(u) for u in uniq])[inv]
    kmat = kv[:x.size**2].reshape(x.size, x.size) + kv[x.size**2:].reshape(x.size, x.size)
    a = np.pi * np.eye(x.size) + kmat * w[None, :]
    phi1, phi2 = np.linalg.solve(a, np.ones(x.size)), np.linalg.solve(a, x**2)
    ka = np.array([kern(1.0 - xi) + kern(1.0 + xi) for xi in x])
    at_edge1, at_edge2 = (1.0 - ka @ (w * phi1)) / np.pi, (1.0 - ka @ (w * phi2)) / np.pi
    phi = (at_edge2 / at_edge1) * phi1 - phi2
    return 2.0 * np.pi * np.sum(w * phi) / (4.0 / 3.0)


def test_fredholm_reference_is_hertz_on_equal_materials():
    assert abs(fredholm_load_ratio(1.0, NU, 1.0, NU, 12) - 1.0) < 1e-13


FREDHOLM_CASES = [(1.0, 0.1, 0.2, 24), (5.0, 10.0, 0.3, 32), (10.0, 0.01, 0.45, 48),
                  pytest.param(20.0, 1e3, 0.3, 96, marks=pytest.mark.slow)]


@pytest.mark.parametrize("slab, modulus, nu2, nodes", FREDHOLM_CASES)
def test_frictionless_load_against_the_fredholm_solution(slab, modulus, nu2, nodes):
    """The default method's frictionless load converges to the Fredholm load at second order
    (measured relative errors at n = 256: 4.1e-6, 6.8e-6, 4.6e-6, 7.6e-6; a quarter at 512);
    the reference is converged in its nodes to < 1e-9 (checked here with 3/4 of them)."""
    ref = fredholm_load_ratio(1.0 / slab, NU, modulus, nu2, nodes)
    coarse = fredholm_load_ratio(1.0 / slab, NU, modulus, nu2, 3 * nodes // 4)
    assert abs(coarse / ref - 1.0) < 1e-9
    err = {n: _k(0.0, n, slab_ratio=slab, base="elastic", substrate_modulus=modulus,
                 substrate_nu=nu2).load_ratio / ref - 1.0 for n in (256, 512)}
    assert abs(err[256]) < 1e-5
    assert 3.6 < err[256] / err[512] < 4.4  # second order, toward the reference


# --- convergence ---------------------------------------------------------------------------
@pytest.mark.parametrize("kw", [
    {"slab_ratio": 5.0, "substrate_modulus": 0.1, "substrate_nu": 0.2},
    pytest.param({"slab_ratio": 20.0, "substrate_modulus": 10.0}, marks=pytest.mark.slow)])
def test_error_estimate_covers_the_fourfold_refinement(kw):
    """k(c/a = 0.5): the estimate at n covers |k(n)/k(4n) - 1| (measured 1.3-170x) and the
    differences shrink with n."""
    sols = {n: _k(0.5, n, base="elastic", **kw) for n in (64, 128, 256, 512)}
    k = {n: s.friction_coefficient for n, s in sols.items()}
    for n in (64, 128):
        true = abs(k[n] / k[4 * n] - 1.0)
        assert true <= sols[n].error_estimate, (n, true, sols[n].error_estimate)
        assert sols[n].resolved
    assert abs(k[512] - k[256]) < abs(k[128] - k[64])


# --- input -----------------------------------------------------------------------------
@pytest.mark.parametrize("kwargs, name", [
    ({"base": "elastic"}, "substrate_modulus"),
    ({"base": "elastic", "substrate_modulus": 0.0}, "substrate_modulus"),
    ({"base": "elastic", "substrate_modulus": 1e-3}, "substrate_modulus"),
    ({"base": "elastic", "substrate_modulus": float("inf")}, "substrate_modulus"),
    ({"base": "elastic", "substrate_modulus": 2.0, "substrate_nu": 0.6}, "substrate_nu"),
    ({"base": "bonded", "substrate_modulus": 2.0}, "substrate_modulus"),
    ({"base": "smooth", "substrate_nu": 0.2}, "substrate_nu"),
    ({"base": "elastic", "substrate_modulus": 2.0, "slab_ratio": 1001.0}, "slab_ratio"),
    ({"base": "elastic", "substrate_modulus": 2.0, "method": "extrapolated"}, "method"),
])
def test_bad_substrate_input_names_the_argument(kwargs, name):
    kw = {"slab_ratio": 1.0, "n": 128} | kwargs
    with pytest.raises(contactlib.validate.InputError) as err:
        contactlib.solve("sphere", NU, stick_ratio=0.5, **kw)
    assert err.value.name == name and str(err.value).startswith(name)


# --- command line ------------------------------------------------------------------------
def test_cli_solve_on_a_coated_body(capsys):
    from contactlib import cli

    argv = ["solve", "--geometry", "sphere", "--nu", "0.3", "--stick-ratio", "0.5", "--n", "64",
            "--slab-ratio", "5", "--base", "elastic"]
    assert cli.main(argv + ["--substrate-modulus", "0.1", "--substrate-nu", "0.2"]) == 0
    text = capsys.readouterr().out
    k = _k(0.5, 64, slab_ratio=5.0, base="elastic", substrate_modulus=0.1, substrate_nu=0.2)
    assert f"{k.friction_coefficient:.6g}" in text
    assert "(elastic base: E2/E1 = 0.1, nu2 = 0.2)" in text
    for extra, option in ((["--substrate-modulus", "1e-3"], "--substrate-modulus"),
                          ([], "--substrate-modulus"),
                          (["--substrate-modulus", "2", "--substrate-nu", "0.7"], "--substrate-nu")):
        assert cli.main(argv + extra) == 2
        assert option in capsys.readouterr().err
    bonded = argv[:-1] + ["bonded", "--substrate-modulus", "2"]
    assert cli.main(bonded) == 2 and "--substrate-modulus" in capsys.readouterr().err


# --- the cylinder (plane strain, strip loads) ----------------------------------------------
def _quad_t(f, h):
    """int_0^inf f(k) dk with k = t/h, t < 30 (the remainders are < 1e-20 beyond)."""
    val, _ = integrate.quad(lambda t: f(t / h) / h, 0.0, 30.0, points=np.arange(0.5, 30.0, 0.5),
                            limit=800, epsabs=1e-13, epsrel=1e-12)
    return val


@pytest.mark.parametrize("nu, modulus, nu2", [(0.3, 0.1, 0.2), (0.45, 10.0, 0.3)])
def test_strip_kernels_against_fourier_quadrature(nu, modulus, nu2):
    """Coated minus half-plane strip kernels against quad of their Fourier integrals, the
    transfer functions by the Love solve (the plane-strain ones are the same functions of
    |k| h): pressure du/dx = -(4/pi) int Rwu sin ks cos kx dk/k, w(x1) - w(x2) = (4/pi) int
    Rww sin ks (cos kx1 - cos kx2) dk/k^2; shear du/dx = (4/pi) int Ruu (1 - cos ks)
    cos kx dk/k (the odd shear sgn x on |x| < s). Within 1e-9 times max(1, m)."""
    from contactlib.kernels import strip

    sub = layer.Substrate(modulus, nu2)
    m = max(1.0, stiffness_ratio(nu, modulus, nu2))

    def rem(i, h):
        return lambda k: _love_remainders(k * h, nu, modulus, nu2)[i]

    for x, x2, s, h in [(0.3, 0.0, 1.0, 1.0), (1.7, 0.5, 0.6, 0.4), (0.2, 0.9, 1.0, 0.1),
                        (0.5, 0.0, 1.0, 5.0)]:
        hp = np.array(strip.pressure_strip([x, x2], s, nu))
        co = np.array(strip.pressure_strip([x, x2], s, nu, h, sub))
        rww, rwu = rem(0, h), rem(1, h)
        du = -(4 / np.pi) * _quad_t(lambda k: rwu(k) * np.sin(k * s) * np.cos(k * x) / k, h)
        dw = (4 / np.pi) * _quad_t(lambda k: rww(k) * np.sin(k * s)
                                   * (np.cos(k * x) - np.cos(k * x2)) / k**2, h)
        assert abs((co[2, 0] - hp[2, 0]) - du) < 1e-9 * m, (x, s, h)
        got_dw = (co[0, 0] - co[0, 1]) - (hp[0, 0] - hp[0, 1])
        assert abs(got_dw - dw) < 1e-9 * m * s, (x, x2, s, h, got_dw, dw)
        hs = np.array(strip.shear_strip(x, s, nu))
        cs = np.array(strip.shear_strip(x, s, nu, h, sub))
        ruu = rem(2, h)
        dus = (4 / np.pi) * _quad_t(lambda k: ruu(k) * (1 - np.cos(k * s)) * np.cos(k * x) / k,
                                     h)
        assert abs((cs[2] - hs[2]) - dus) < 1e-9 * m, (x, s, h, cs[2] - hs[2], dus)


def _kc(c, n, **kw):
    return contactlib.solve("cylinder", NU, stick_ratio=c, n=n, energy=False, **kw)


def test_cylinder_limits():
    """Equal materials: the half-plane (k to 1e-9; measured 3e-11, 1e-11); E2/E1 -> inf:
    the bonded base at first order in E1/E2 (k 6.8e-5, 6.8e-6 at 1e5, 1e6); a/h -> 0: the
    coating's half-plane at first order in a/h (plane strain: u's remainder ~ x s/h;
    measured 3.67 a/h at E2/E1 = 0.1)."""
    half = _kc(0.5, 128)
    for slab in (1.0, 5.0):
        eq = _kc(0.5, 128, slab_ratio=slab, base="elastic", substrate_modulus=1.0)
        assert abs(eq.friction_coefficient / half.friction_coefficient - 1.0) < 1e-9
        assert abs(eq.load_ratio / half.load_ratio - 1.0) < 1e-9
    bonded = _kc(0.5, 128, slab_ratio=1.0, base="bonded")
    d = {e: _kc(0.5, 128, slab_ratio=1.0, base="elastic", substrate_modulus=e)
         .friction_coefficient / bonded.friction_coefficient - 1.0 for e in (1e5, 1e6)}
    assert abs(d[1e6]) < 2e-5 and 9.8 < d[1e5] / d[1e6] < 10.2
    dep = [_kc(0.5, 128, slab_ratio=r, base="elastic", substrate_modulus=0.1, substrate_nu=0.2
               ).friction_coefficient / half.friction_coefficient - 1.0 for r in (0.01, 0.02)]
    assert 1.96 < dep[1] / dep[0] < 2.04


@pytest.mark.parametrize("kw, share", [
    ({"slab_ratio": 5.0, "substrate_modulus": 0.1, "substrate_nu": 0.2}, 1.0),
    pytest.param({"slab_ratio": 20.0, "substrate_modulus": 0.01}, 0.5,
                 marks=pytest.mark.slow)])
def test_cylinder_error_estimate_against_the_fourfold_refinement(kw, share):
    """k(c/a = 0.5) on the coated half-plane: the estimate at n against |k(n)/k(4n) - 1|.
    At a/h = 5, E2/E1 = 0.1 it covers it (measured 1.49x, 1.50x at n = 64, 128); on a very
    soft substrate at a/h = 20 it falls short, measured 0.71x and 0.94x (docs/models.md):
    asserted here as at least half."""
    sols = {n: _kc(0.5, n, base="elastic", **kw) for n in (64, 128, 256, 512)}
    for n in (64, 128):
        true = abs(sols[n].friction_coefficient / sols[4 * n].friction_coefficient - 1.0)
        assert share * true <= sols[n].error_estimate, (n, true, sols[n].error_estimate)


def erdogan_gupta_load_ratio(h, nu, modulus, nu2, n_nodes):
    """P/P_Hertz (P_Hertz = pi E1* a^2/(4R) per unit length) of a rigid cylinder,
    frictionless, a = R = 1, on the coated half-plane.

    The slope of w: (2/pi) PV int p(y)/(y - x) dy + int p(y) r'(x - y) dy = -x on |x| < 1,
    r'(u) = -(2/pi) int_0^inf Rww(kh) sin(ku) dk (the line load's remainder, by quad of the
    typed-in closed form); p = sqrt(1 - y^2) phi(y), bounded at both edges: Gauss-Chebyshev
    of the second kind (Erdogan & Gupta 1972), n_nodes unknowns, n_nodes + 1 collocation
    points, least squares (the residual is round-off when a is the contact's).
    """
    i = np.arange(1, n_nodes + 1)
    y = np.cos(i * np.pi / (n_nodes + 1))
    w = np.pi / (n_nodes + 1) * np.sin(i * np.pi / (n_nodes + 1)) ** 2
    x = np.cos((2 * np.arange(1, n_nodes + 2) - 1) * np.pi / (2 * (n_nodes + 1)))
    u = x[:, None] - y[None, :]
    uniq, inv = np.unique(np.round(np.abs(u).ravel(), 13), return_inverse=True)

    def slope(v):
        val, _ = integrate.quad(lambda t: closed_form_cww_remainder(t, nu, modulus, nu2), 0.0,
                                60.0, weight="sin", wvar=v / h, limit=400, epsabs=1e-14)
        return -2.0 / (np.pi * h) * val

    rp = np.array([slope(v) for v in uniq])[inv].reshape(u.shape) * np.sign(u)
    a = (2.0 / np.pi) * w[None, :] / (y[None, :] - x[:, None]) + w[None, :] * rp
    phi = np.linalg.lstsq(a, -x, rcond=None)[0]
    assert np.linalg.norm(a @ phi + x) < 1e-12
    return np.sum(w * phi) / (np.pi / 4.0)


@pytest.mark.parametrize("slab, modulus, nu2, nodes", [
    (1.0, 0.1, 0.2, 32), (5.0, 10.0, 0.3, 64),
    pytest.param(10.0, 0.01, 0.45, 96, marks=pytest.mark.slow)])
def test_cylinder_frictionless_load_against_erdogan_gupta(slab, modulus, nu2, nodes):
    """Second order toward the independent load (measured relative errors 2.2e-6, 4.8e-6,
    3.1e-6 at n = 256, a quarter at 512); the reference converged in its nodes to < 1e-9
    (3/4 of them: 1e-16, 2e-14, 1e-13); on equal materials it is Hertz's."""
    assert abs(erdogan_gupta_load_ratio(1.0, NU, 1.0, NU, 12) - 1.0) < 1e-13
    ref = erdogan_gupta_load_ratio(1.0 / slab, NU, modulus, nu2, nodes)
    assert abs(erdogan_gupta_load_ratio(1.0 / slab, NU, modulus, nu2, 3 * nodes // 4) / ref
               - 1.0) < 1e-9
    err = {n: _kc(0.0, n, slab_ratio=slab, base="elastic", substrate_modulus=modulus,
                  substrate_nu=nu2).load_ratio / ref - 1.0 for n in (256, 512)}
    assert abs(err[256]) < 1e-5
    assert 3.6 < err[256] / err[512] < 4.4


def test_datasets_record_the_substrate(tmp_path, capsys):
    """A coated body's solution and its dataset carry E2/E1 and nu2 (nu2 defaults to nu)."""
    from contactlib import cli, io

    sol = _k(0.5, 32, slab_ratio=2.0, base="elastic", substrate_modulus=3.0)
    assert sol.substrate_modulus == 3.0 and sol.substrate_poisson_ratio == NU
    assert "E2/E1 = 3, nu2 = 0.3" in repr(sol)
    assert np.isinf(_k(0.5, 32, slab_ratio=2.0, base="bonded").substrate_modulus)
    out = tmp_path / "coated.nc"
    assert cli.main(["sweep", "--geometry", "cylinder", "--nu", "0.3", "--stick-ratios",
                     "0.3,0.6", "--n", "32", "--slab-ratio", "2", "--base", "elastic",
                     "--substrate-modulus", "0.5", "--substrate-nu", "0.2",
                     "--output", str(out)]) == 0
    capsys.readouterr()
    ds = io.read_dataset(out)
    assert ds.attrs["base"] == "elastic" and ds.attrs["substrate_modulus"] == 0.5
    assert ds.attrs["substrate_poisson_ratio"] == 0.2
    ref = contactlib.sweep("cylinder", NU, [0.3, 0.6], n=32, slab_ratio=2.0, base="elastic",
                           substrate_modulus=0.5, substrate_nu=0.2, energy=False)
    np.testing.assert_allclose(ds["friction_coefficient"].values,
                               [r.friction_coefficient for r in ref], rtol=1e-12)
