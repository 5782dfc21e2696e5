"""Independent verification of the layer kernels in ``contactlib.kernels.layer``.

References (none computed by the code under test):

* the transfer functions from a numerical 4x4 solve of the axisymmetric Love
  strain-function problem (``phi = J0(kr) f(z)``, written out here), not from
  the closed forms;
* direct ``scipy.integrate.quad`` of the Hankel integrals of the remainders,
  with the transfer functions typed in literally from the closed forms (which
  the Love solve checks);
* the half-space kernels of ``contactlib.kernels.disc`` (verified against
  Boussinesq/Cerruti in ``test_kernels_disc.py``) and the moment that the
  thick-layer limit predicts;
* thin-layer asymptotics: w = h p / E* (smooth base), Winkler w = p h / M
  (bonded, compressible) and w = -(h^3 / 3G) lap p (bonded, incompressible),
  with the next term of the small-t expansion of the transfer function;
* Betti's reciprocal theorem between the pressure and shear kernels.

Units: E* = 1, so E = 1 - nu^2, G = 1/(2(1 + nu)) (1 - nu^2) = (1 - nu)/2.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import integrate, special

from contactlib.kernels import disc, layer

BASES = ["smooth", "bonded"]


# --- transfer functions from the Love strain function ---------------------------
def love_transfer(t: float, nu: float, base: str) -> tuple[float, float, float]:
    """(Cww, Cwu, Cuu) by solving the Love-function boundary-value problem numerically.

    phi = J0(kr) f(z), k = 1, layer 0 < z < t, z into the body, G = 1;
    2G u_r = k J1 f', 2G u_z = J0 [2(1-nu) L f - f''], sz = J0 [(2-nu)(Lf)' - f'''],
    trz = -k J1 [(1-nu) L f - f''] with L f = f'' - f (Timoshenko & Goodier).
    Basis: exp(z - t), z exp(z - t), exp(-z), z exp(-z) (bounded on 0 < z < t).
    """

    def derivs(z):  # rows: basis function; columns: f, f', f'', f'''
        e1, e2 = np.exp(z - t), np.exp(-z)
        return np.array([
            [e1, e1, e1, e1],
            [z * e1, (z + 1) * e1, (z + 2) * e1, (z + 3) * e1],
            [e2, -e2, e2, -e2],
            [z * e2, (1 - z) * e2, (z - 2) * e2, (3 - z) * e2],
        ])

    def rows(z):
        d = derivs(z)
        f, f1, f2, f3 = d.T
        lf, lf1 = f2 - f, f3 - f1
        ur = f1 / 2.0
        uz = (2 * (1 - nu) * lf - f2) / 2.0
        sz = (2 - nu) * lf1 - f3
        trz = -((1 - nu) * lf - f2)
        return ur, uz, sz, trz

    ur0, uz0, sz0, trz0 = rows(0.0)
    urh, uzh, _, trzh = rows(t)
    a = np.array([sz0, trz0, uzh, trzh if base == "smooth" else urh])
    estar_half = 1.0 / (1.0 - nu)  # E*/2 with G = 1
    cp = np.linalg.solve(a, [-1.0, 0.0, 0.0, 0.0])
    cq = np.linalg.solve(a, [0.0, -1.0, 0.0, 0.0])
    return (float(uz0 @ cp) * estar_half, -float(uz0 @ cq) * estar_half,
            float(ur0 @ cq) * estar_half)


@pytest.mark.parametrize("base", BASES)
@pytest.mark.parametrize("nu", [-0.5, 0.0, 0.3, 0.49, 0.5])
def test_transfer_functions_match_love_solution(base, nu):
    for t in [1e-3, 0.05, 0.5, 1.0, 2.5, 8.0, 20.0]:
        ref = love_transfer(t, nu, base)
        got = layer.transfer(t, nu, base)
        assert np.allclose([float(g) for g in got], ref, rtol=1e-11, atol=1e-13), (t, got, ref)


def test_cross_terms_equal_in_love_solution():
    """Betti in transform space: u under pressure = -(w under shear), from the Love solve."""
    for base in BASES:
        for nu in (0.1, 0.3, 0.45):
            for t in (0.2, 1.3, 4.0):
                _, cwu, _ = love_transfer(t, nu, base)  # from w under the shear mode
                assert abs(_love_u_under_pressure(t, nu, base) + cwu) < 1e-12


def _love_u_under_pressure(t, nu, base):
    """u coefficient (times E*/2) under the unit pressure mode, from the Love system."""
    e = np.exp
    d0 = np.array([[e(-t), e(-t), e(-t), e(-t)], [0, e(-t), 2 * e(-t), 3 * e(-t)],
                   [1, -1, 1, -1], [0, 1, -2, 3]], dtype=float)
    dh = np.array([[1, 1, 1, 1], [t, t + 1, t + 2, t + 3],
                   [e(-t), -e(-t), e(-t), -e(-t)],
                   [t * e(-t), (1 - t) * e(-t), (t - 2) * e(-t), (3 - t) * e(-t)]])

    def rows(d):
        f, f1, f2, f3 = d.T
        lf, lf1 = f2 - f, f3 - f1
        return f1 / 2.0, (2 * (1 - nu) * lf - f2) / 2.0, (2 - nu) * lf1 - f3, -((1 - nu) * lf - f2)

    ur0, uz0, sz0, trz0 = rows(d0)
    urh, uzh, _, trzh = rows(dh)
    a = np.array([sz0, trz0, uzh, trzh if base == "smooth" else urh])
    cp = np.linalg.solve(a, [-1.0, 0.0, 0.0, 0.0])
    return float(ur0 @ cp) / (1.0 - nu)


# --- literal closed forms for the quadrature checks -------------------------------
def literal_remainders(t, nu, base):
    """C - C(inf) typed in from the closed forms (plain cosh/sinh; t <= 30)."""
    beta = (1 - 2 * nu) / (2 * (1 - nu))
    if base == "smooth":
        d = np.sinh(2 * t) + 2 * t
        return ((np.cosh(2 * t) - 1) / d - 1, -2 * t / d, (np.cosh(2 * t) + 1) / d - 1)
    k = 3 - 4 * nu
    n = 2 * k * np.cosh(2 * t) + 1 + k * k + 4 * t * t
    cwu = (2 * k * (k - 1) * (np.cosh(2 * t) - 1) - 8 * t * t) / ((k + 1) * n)
    return ((2 * k * np.sinh(2 * t) - 4 * t) / n - 1, cwu - beta,
            (2 * k * np.sinh(2 * t) + 4 * t) / n - 1)


def quad_remainder(kind, r, s, h, nu, base):
    """(dw, du, ddu) = layer - half-space by quad of the Hankel integrals in k."""
    idx = {"ww": 0, "wu": 1, "uu": 2}

    def integral(f):
        # t = k h up to 30 (integrands < 1e-20 beyond); break points every 0.5
        pts = np.arange(0.5, 30.0, 0.5)
        val, _ = integrate.quad(f, 0.0, 30.0, points=pts, limit=800, epsabs=1e-14, epsrel=1e-13)
        return val

    rho, sig = r / h, s / h

    def rem(name):
        return lambda t: literal_remainders(t, nu, base)[idx[name]]

    def dj1(x):
        return 0.5 * (special.j0(x) - special.jv(2, x))

    if kind == "pressure":
        dw = 2 * s * integral(lambda t: rem("ww")(t) * special.j1(sig * t) * special.j0(rho * t) / t)
        du = -2 * s * integral(lambda t: rem("wu")(t) * special.j1(sig * t) * special.j1(rho * t) / t)
        ddu = -2 * sig * integral(lambda t: rem("wu")(t) * special.j1(sig * t) * dj1(rho * t))
        return dw, du, ddu
    dw = -2 * s * s * integral(lambda t: rem("wu")(t) * special.jv(2, sig * t) * special.j0(rho * t) / t)
    du = 2 * s * s * integral(lambda t: rem("uu")(t) * special.jv(2, sig * t) * special.j1(rho * t) / t)
    ddu = 2 * s * sig * integral(lambda t: rem("uu")(t) * special.jv(2, sig * t) * dj1(rho * t))
    return dw, du, ddu


# (r, s, h): table cells (rho, sigma in 0.5..6), the series corner (h = 5) and the edge r = s
POINTS = [(0.0, 1.0, 1.0), (0.3, 1.0, 1.0), (1.0, 1.0, 1.0), (2.5, 1.0, 1.0),
          (0.7, 1.5, 0.4), (1.7, 0.4, 0.3), (0.9, 0.95, 0.25), (0.5, 1.0, 5.0), (2.0, 1.2, 5.0),
          (0.2, 0.9, 0.15), (0.95, 1.0, 0.05), (0.3, 0.99, 0.05)]


@pytest.mark.parametrize("base,nu", [("smooth", 0.3),
                                     pytest.param("bonded", 0.3, marks=pytest.mark.slow),
                                     pytest.param("bonded", 0.5, marks=pytest.mark.slow)])
@pytest.mark.parametrize("kind", ["pressure", "shear"])
def test_kernels_against_hankel_quadrature(kind, base, nu):
    fn = layer.pressure_disc if kind == "pressure" else layer.shear_disc
    hs = disc.pressure_disc if kind == "pressure" else disc.shear_disc
    for r, s, h in POINTS:
        with np.errstate(invalid="ignore"):  # du of the shear at r = s: -inf - -inf
            got = np.array(fn(r, s, nu, h, base)) - np.array(hs(r, s, nu))
        ref = np.array(quad_remainder(kind, r, s, h, nu, base))
        p = 1 if kind == "pressure" else 2
        scale = np.array([max(r, s) ** p, max(r, s) ** p, max(r, s) ** (p - 1)])
        if r == s:  # du/dr of the shear is -inf there in both; compare w, u only
            got, ref, scale = got[:2], ref[:2], scale[:2]
        assert np.all(np.abs(got - ref) <= 1e-9 * scale), (r, s, h, got, ref)


# --- thick layer ---------------------------------------------------------------------
@pytest.mark.parametrize("base", [b if b == "smooth" else pytest.param(b, marks=pytest.mark.slow)
                                  for b in BASES])
def test_thick_layer_tends_to_half_space(base):
    """Layer minus half-space = the leading terms of the thick-layer (power-series) limit.

    With M_k(R) = int_0^inf R(t) t^k dt (quad here): pressure dw = (s^2/h) M0(Rww)
    (a uniform shift, |M0| s/h relative: 1.2e-4 smooth, 1.4e-4 bonded at h/s = 1e4),
    du = -(s^2 r/(2 h^2)) M1(Rwu); shear dw = -s^4 M1(Rwu)/(4 h^2), du = s^4 r M2(Ruu)/(8 h^3),
    d(du)/dr = s^4 M2(Ruu)/(8 h^3). The next terms are O((max(r, s)/h)^2) relative.
    """
    nu, s = 0.3, 1.0
    r = np.array([0.0, 0.5, 1.0, 1.5, 3.0])

    def moment(k, i):
        return integrate.quad(lambda t: t**k * literal_remainders(t, nu, base)[i], 0, 30, limit=400)[0]

    m0, m1, m2 = moment(0, 0), moment(1, 1), moment(2, 2)
    for h in (1e3, 1e4):
        tol = 5.0 * (np.maximum(r, s) / h) ** 2
        w, u, du = layer.pressure_disc(r, s, nu, h, base)
        w0, u0, du0 = disc.pressure_disc(r, s, nu)
        assert np.all(np.abs((w - w0) / (s * s / h * m0) - 1) < tol)
        pred = -(s * s * r / (2 * h * h)) * m1
        assert np.all(np.abs(u - u0 - pred) <= tol * np.abs(pred) + 1e-16)
        if h > 1e3:  # the shear differences (O(h^-3)) reach the round-off of u at 1e4
            continue
        ws, us, dus = layer.shear_disc(r, s, nu, h, base)
        ws0, us0, dus0 = disc.shear_disc(r, s, nu)
        assert np.all(np.abs((ws - ws0) / (-s**4 * m1 / (4 * h * h)) - 1) < tol)
        pred = s**4 * r * m2 / (8 * h**3)
        assert np.all(np.abs(us - us0 - pred) <= tol * np.abs(pred) + 1e-16)
        finite = np.isfinite(dus0)
        with np.errstate(invalid="ignore"):
            ddu = (dus - dus0) / (s**4 * m2 / (8 * h**3)) - 1
        assert np.all(np.abs(ddu[finite]) < tol[finite])


def test_infinite_thickness_is_half_space_exactly():
    r = np.linspace(0, 2, 9)
    for fn, hs in ((layer.pressure_disc, disc.pressure_disc), (layer.shear_disc, disc.shear_disc)):
        a = np.array(fn(r, 1.0, 0.3))
        b = np.array(hs(r, 1.0, 0.3))
        assert np.array_equal(a, b, equal_nan=True)


# --- thin layer ----------------------------------------------------------------------
def parabolic_w_kernel(r, a, h, nu, base):
    """w(r) of p = 1 - r^2/a^2 on r < a, as int_0^a (2s/a^2) w_disc(r; s) ds with the kernels."""
    g, wg = np.polynomial.legendre.leggauss(40)
    out = []
    for ri in np.atleast_1d(r):
        edges = [0.0, ri, a] if 0 < ri < a else [0.0, a]
        tot = 0.0
        for lo, hi in zip(edges[:-1], edges[1:]):
            s = 0.5 * (hi - lo) * g + 0.5 * (hi + lo)
            ww, _, _ = layer.pressure_disc(ri, s, nu, h, base)
            tot += 0.5 * (hi - lo) * np.sum(wg * 2 * s / a**2 * ww)
        out.append(tot)
    return np.array(out)


def taylor_cww(nu, base):
    """(c1, c3) of Cww = c1 t + c3 t^3 + O(t^5), expanded by hand from the closed forms."""
    if base == "smooth":  # (2t^2 + 2t^4/3)/(4t + 4t^3/3) + O(t^5) = t/2 + O(t^5)
        return 0.5, 0.0
    k = 3 - 4 * nu  # numerator 4t(k-1) + (8k/3) t^3, denominator (k+1)[(k+1) + 4t^2]
    return 4 * (k - 1) / (k + 1) ** 2, (8 * k * (k + 1) / 3 - 16 * (k - 1)) / (k + 1) ** 3


@pytest.mark.parametrize("base,nu", [("smooth", 0.3), ("bonded", 0.3),
                                     pytest.param("bonded", 0.45, marks=pytest.mark.slow),
                                     ("bonded", 0.5)])
def test_thin_layer_limits(base, nu):
    """Centre deflection under p = 1 - r^2/a^2 at a/h = 10 and 20 (the kernels).

    Asymptotics, with Cww = c1 t + c3 t^3 + ...: w(0) = 2 c1 h + 8 c3 h^3/a^2 + O(h^5/a^4),
    i.e. smooth: w = h p/E*; bonded: Winkler w = h p/M (M = (1-nu)^2/(1-2nu) in E* units);
    incompressible (c1 = 0): w = (16/3) h^3/a^2 = -(h^3/(3G)) lap p with G = 1/4.
    """
    a = 1.0
    c1, c3 = taylor_cww(nu, base)
    if base == "bonded" and nu < 0.5:
        m = (1 - nu) ** 2 / (1 - 2 * nu)
        assert np.isclose(2 * c1, 1 / m, rtol=1e-14)  # Winkler modulus
    dep = []
    for ratio in (10.0, 20.0):
        h = a / ratio
        w0 = float(parabolic_w_kernel(0.0, a, h, nu, base)[0])
        lead = 2 * c1 * h if c1 else 8 * c3 * h**3 / a**2
        two = 2 * c1 * h + 8 * c3 * h**3 / a**2
        if c1:  # compressible: the departure from the leading law is the next term
            assert abs(w0 - two) <= 0.02 * abs(two - lead) + 1e-9 * abs(lead), (ratio, w0, two)
        dep.append(abs(w0 / lead - 1))
    if not c1:  # incompressible: only an edge effect, exponentially small in a/h
        assert dep[0] < 0.02 and dep[1] < 1e-2 * dep[0]


@pytest.mark.parametrize("base,nu", [("smooth", 0.3), ("bonded", 0.3), ("bonded", 0.45),
                                     ("bonded", 0.5)])
def test_thin_layer_model_beyond_the_table(base, nu):
    """a/h = 30 and 100 (beyond RATIO_MAX: the tables end; the transform sums are
    checked against this integral in tests/test_thin_layers.py): the model's transfer
    function, integrated here, against the same thin-layer asymptotics.

    w(0) under p = 1 - r^2/a^2: half-space 4a/3 plus 4 h int Rww(t) J2(t a/h)/t^2 dt.
    """
    a = 1.0
    c1, c3 = taylor_cww(nu, base)
    for ratio in (30.0, 100.0):
        h = a / ratio
        def f(t):
            return layer.remainder_transfer(t, nu, base)[0] * special.jv(2, t * ratio) / t**2

        v, _ = integrate.quad(f, 0.0, 30.0, points=np.arange(0.05, 30.0, 0.05), limit=5000,
                              epsabs=1e-15)
        w0 = 4 * a / 3 + 4 * h * v
        lead = 2 * c1 * h if c1 else 8 * c3 * h**3 / a**2
        two = 2 * c1 * h + 8 * c3 * h**3 / a**2
        if c1:
            assert abs(w0 - two) <= 0.02 * abs(two - lead) + 1e-9 * abs(lead), (ratio, w0, two)
        else:
            assert abs(w0 / lead - 1) < 1e-6, (ratio, w0, lead)


def test_incompressible_thin_layer_uniform_deflection_profile():
    """nu = 1/2, bonded, a/h = 20: w is uniform under p = 1 - r^2/a^2 (lap p = -4/a^2).

    The thin-layer law holds at >= 10 h from the edge (r <= a/2); nearer the edge the
    departure is an edge effect (5.9 % at r = 0.7 a, 6 h from the edge).
    """
    a, h = 1.0, 0.05
    r = np.array([0.0, 0.3, 0.5])
    w = parabolic_w_kernel(r, a, h, 0.5, "bonded")
    ref = (16.0 / 3.0) * h**3 / a**2
    assert np.all(np.abs(w / ref - 1) < 0.01)


# --- Betti ---------------------------------------------------------------------------
@pytest.mark.parametrize("base,nu,h", [("smooth", 0.3, 0.5), ("bonded", 0.3, 0.2),
                                       ("bonded", 0.5, 1.0), ("smooth", 0.0, 3.0)])
def test_betti_reciprocity(base, nu, h):
    """int_0^s2 r u_p(r; s1) 2 pi r dr = int_0^s1 w_q(r; s2) 2 pi r dr."""
    g, wg = np.polynomial.legendre.leggauss(60)
    for s1, s2 in ((1.0, 0.6), (0.5, 1.3), (1.0, 1.0)):
        def integral(f, hi, brk):
            edges = [0.0, brk, hi] if 0 < brk < hi else [0.0, hi]
            tot = 0.0
            for lo, up in zip(edges[:-1], edges[1:]):
                x = 0.5 * (up - lo) * g + 0.5 * (up + lo)
                tot += 0.5 * (up - lo) * np.sum(wg * f(x))
            return tot

        lhs = integral(lambda r: r * layer.pressure_disc(r, s1, nu, h, base)[1] * 2 * np.pi * r, s2, s1)
        rhs = integral(lambda r: layer.shear_disc(r, s2, nu, h, base)[0] * 2 * np.pi * r, s1, s2)
        assert abs(lhs - rhs) <= 1e-10 * max(abs(lhs), 1e-3), (s1, s2, lhs, rhs)


# --- nu -> 1/2, range, bad input --------------------------------------------------------
def test_incompressible_limit_is_continuous():
    r = np.linspace(0.0, 3.0, 13)
    for base in BASES:
        for fn in (layer.pressure_disc, layer.shear_disc):
            a = np.array(fn(r, 1.0, 0.5, 0.3, base))
            b = np.array(fn(r, 1.0, 0.5 - 1e-7, 0.3, base))
            ok = np.isfinite(a)
            assert np.array_equal(ok, np.isfinite(b))
            assert np.all(np.abs(a[ok] - b[ok]) < 1e-5)
    # beta = 0: no coupling through the half-space part; the layer's coupling stays
    _, u, _ = layer.pressure_disc(0.5, 1.0, 0.5, 1e6, "bonded")
    assert abs(float(u)) < 1e-9


def test_supported_range_and_bad_input():
    layer.pressure_disc(1.0, 1.0, 0.3, 1.0 / layer.THIN_RATIO_MAX, "bonded")  # the edge: fine
    with pytest.raises(ValueError, match="supported range"):
        layer.pressure_disc(1.0, 1.0, 0.3, 0.99 / layer.THIN_RATIO_MAX, "bonded")
    with pytest.raises(ValueError, match="supported range"):
        layer.shear_disc(0.5, 2.1, 0.3, 0.001)
    with pytest.raises(ValueError, match="base"):
        layer.pressure_disc(0.5, 1.0, 0.3, 1.0, "glued")
    with pytest.raises(ValueError, match="thickness"):
        layer.pressure_disc(0.5, 1.0, 0.3, 0.0)
    with pytest.raises(ValueError, match="Poisson"):
        layer.pressure_disc(0.5, 1.0, 0.51, 1.0)


def test_zero_disc_and_shapes():
    w, u, du = layer.pressure_disc(np.zeros((3, 1)), np.array([0.0, 0.5]), 0.3, 0.5, "bonded")
    assert w.shape == (3, 2)
    assert np.all(w[:, 0] == 0) and np.all(u[:, 0] == 0) and np.all(du[:, 0] == 0)
    w, u, du = layer.shear_disc(0.3, 1.0, 0.3, 0.5, with_du=False)
    assert np.isnan(du)


@pytest.mark.parametrize("base,nu", [("smooth", 0.3), ("bonded", 0.5)])
def test_table_against_the_module_quadrature(base, nu):
    """Implementation check: Chebyshev table and power series against the quadrature
    they are built from, at random points over the whole range (docs: <= 5.2e-12 of scale)."""
    tab = layer.layer_table(nu, base)
    rng = np.random.default_rng(11)
    rho = np.concatenate([rng.uniform(0, layer.RATIO_MAX, 150), rng.uniform(0, 0.3, 30)])
    sig = np.concatenate([rng.uniform(0, layer.RATIO_MAX, 150), rng.uniform(0, 0.3, 30)])
    big = np.maximum(1.0, np.maximum(rho, sig))
    for kind, scales in (("pressure", (1, 1, 1)), ("shear", (big**2, big**2, big))):
        ref = [np.diag(v) for v in layer._remainder_quadrature(kind, rho, sig, nu, base)]
        got = layer._remainders(kind, rho, sig, tab)
        for f in range(3):
            assert np.max(np.abs(got[f] - ref[f]) / scales[f]) < 1e-11, (kind, f)
