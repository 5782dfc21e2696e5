"""The fast collocation operators against independent references.

``contactlib.kernels.disc`` (polynomial-logarithmic fits instead of
``scipy.special.ellipk``/``ellipe`` and power series) and
``contactlib.discretization.influence`` (one rule per element, grouped kernel calls) were
rewritten for speed. Two checks keep them honest, neither using git history
or the package's own kernels as the reference:

* the sphere's operators with the package's kernels against the same
  operators with a reference kernel written here (the Appendix closed forms
  with ``scipy.special.ellipk``/``ellipe``, power series where they cancel;
  the form the package used before the speed-up), row by row: the largest
  difference in a row must stay below 1e-10 of the row's largest entry, for w,
  u and du/dx, at the nodes and at the Gauss points of the slip zone, on the
  graded meshes of n = 64 and 256;
* the element integrals against a 40-point smoothstep rule on every element
  (split at x), with the reference kernel: the quadrature of the operators.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import special

from contactlib.discretization import influence
from contactlib.discretization.elements import graded_mesh
from contactlib.energy import slip_points
from contactlib.model.geometry import Geometry
from contactlib.kernels import disc

GATE = 1e-10


# ----------------------------------------------------------------------------- reference kernels
_SWITCH = 0.25  # power series below this parameter
_TERMS = 30  # 0.25**30 ~ 1e-18
_j = np.arange(_TERMS + 3)
_K = np.cumprod(np.concatenate([[1.0], ((2 * _j[1:] - 1) / (2 * _j[1:])) ** 2]))
_E = _K / (1.0 - 2.0 * _j)  # K(m) = pi/2 sum _K[j] m^j, E(m) = pi/2 sum _E[j] m^j
_K1 = np.concatenate([[0.0], _K[:_TERMS - 1]])
_E1 = np.concatenate([[0.0], _E[:_TERMS - 1]])
_SERIES = {  # the cancelling combinations, as series in m (times pi/2)
    "A": _E[:_TERMS] - _K[:_TERMS] + _K1,  # E - (1-m) K
    "g": 2 * _E1 - _E[:_TERMS] - _K1 + _K[:_TERMS],  # (2m-1) E - (m-1) K
    "gd": 4 * _E1 + _E[:_TERMS] - 2 * _K1 - _K[:_TERMS],  # (4m+1) E - (2m+1) K
    "h": (2 * _E[1:_TERMS + 1] - _E[:_TERMS] - 2 * _K[1:_TERMS + 1]  # (2/m-1) E - 2 (1/m-1) K
          + 2 * _K[:_TERMS]),
    "hd": 2 * _K[:_TERMS] - 2 * _E[:_TERMS] - 0.5 * (_E1 + _K1),  # 2 (K-E) - m (E+K)/2
}
_DIRECT = {
    "A": lambda k, e, omk, m: e - omk,
    "g/m": lambda k, e, omk, m: ((2 * m - 1) * e + omk) / m,
    "gd/m": lambda k, e, omk, m: ((4 * m + 1) * e - (2 * m + 1) * k) / m,
    "h": lambda k, e, omk, m: (2.0 / m - 1.0) * e - 2.0 * omk / m,
    "hd": lambda k, e, omk, m: 2.0 * (k - e) - 0.5 * m * (e + k),
}


def _combo(name: str, m: np.ndarray) -> np.ndarray:
    """A combination of K(m), E(m): power series below _SWITCH, closed form above."""
    coef = {"g/m": _SERIES["g"][1:], "gd/m": _SERIES["gd"][1:]}.get(name, _SERIES.get(name))
    out = np.empty_like(m)
    small = m < _SWITCH
    out[small] = 0.5 * np.pi * np.polynomial.polynomial.polyval(m[small], coef)
    mb = np.clip(m[~small], 0.0, 1.0)
    k, e = special.ellipk(mb), special.ellipe(mb)
    with np.errstate(invalid="ignore"):
        omk = np.where(mb < 1.0, (1.0 - mb) * k, 0.0)  # (1-m) K(m) -> 0 at m = 1
    out[~small] = _DIRECT[name](k, e, omk, mb)
    return out


def _split(r, s):
    r, s = np.broadcast_arrays(np.abs(np.asarray(r, float)), np.asarray(s, float))
    out = np.zeros((3,) + r.shape)
    return r, s, (r <= s) & (s > 0), (r > s) & (s > 0), out


def ref_pressure_disc(r, s, nu):
    """w, u, du/dr under p = 1 on r < s (E* = 1; Johnson 3.19-3.21)."""
    b = disc.beta_of_nu(nu)
    r, s, ii, oo, (w, u, du) = _split(r, s)
    m = (r[ii] / s[ii]) ** 2
    w[ii] = 4.0 / np.pi * s[ii] * special.ellipe(np.clip(m, 0.0, 1.0))
    u[ii], du[ii] = -b * r[ii], -b
    mp = (s[oo] / r[oo]) ** 2
    w[oo] = 4.0 / np.pi * r[oo] * _combo("A", mp)
    u[oo], du[oo] = -b * s[oo] ** 2 / r[oo], b * mp
    return w, u, du


def ref_shear_disc(r, s, nu):
    """w, u, du/dr under q = r (outward) on r < s (E* = 1; w < 0 inside, from Betti)."""
    b, c = disc.beta_of_nu(nu), 4.0 / (3.0 * np.pi)
    r, s, ii, oo, (w, u, du) = _split(r, s)
    ri, si = r[ii], s[ii]
    m = (ri / si) ** 2
    w[ii] = -b * (si**2 - ri**2)
    u[ii] = c * si * ri * _combo("g/m", m)
    du[ii] = c * si * _combo("gd/m", m)
    ro, so = r[oo], s[oo]
    mp = (so / ro) ** 2
    u[oo] = c * so**2 * _combo("h", mp)
    du[oo] = -2.0 * c * ro * _combo("hd", mp)
    return w, u, du


def test_reference_kernels_at_points_known_exactly():
    """The reference kernels on the axis, on the rim, far away (leading terms of the
    series by hand, and Boussinesq), and against scipy's K, E where nothing cancels."""
    nu, b, s = 0.3, disc.beta_of_nu(0.3), 1.5
    x = np.array([0.0, s, 100 * s, 0.3 * s, 2.0 * s])
    w, u, du = ref_pressure_disc(x, s, nu)
    assert w[0] == pytest.approx(2 * s, rel=1e-15)  # (4/pi) s E(0)
    assert w[1] == pytest.approx(4 * s / np.pi, rel=1e-15)  # (4/pi) s E(1)
    assert w[2] == pytest.approx(s**2 / x[2], rel=1e-3)  # point load P = pi s^2: P/(pi E* r)
    assert w[3] == pytest.approx(4 / np.pi * s * special.ellipe(0.09), rel=1e-15)
    m = 0.25
    assert w[4] == pytest.approx(4 / np.pi * x[4] * (special.ellipe(m) - (1 - m) *
                                                     special.ellipk(m)), rel=1e-13)
    out = np.maximum(x, s)  # outside the disc only
    np.testing.assert_allclose(u, np.where(x <= s, -b * x, -b * s**2 / out), rtol=1e-15)
    np.testing.assert_allclose(du, np.where(x <= s, -b, b * s**2 / out**2), rtol=1e-15)
    w, u, du = ref_shear_disc(x, s, nu)
    np.testing.assert_allclose(w, np.where(x < s, -b * (s**2 - x**2), 0.0), rtol=1e-15)
    assert (u[0], du[0]) == (0.0, pytest.approx(s, rel=1e-15))  # u ~ s r at the centre
    assert u[2] == pytest.approx(s**4 / (4 * x[2] ** 2), rel=1e-3)  # far field
    m = 0.09  # inside, m = r^2/s^2
    k, e = special.ellipk(m), special.ellipe(m)
    assert u[3] == pytest.approx(4 / (3 * np.pi) * s**3 / x[3] * ((2 * m - 1) * e - (m - 1) * k),
                                 rel=1e-12)
    m = 0.25  # outside, m' = s^2/r^2
    k, e = special.ellipk(m), special.ellipe(m)
    assert u[4] == pytest.approx(4 / (3 * np.pi) * s**2 * ((2 / m - 1) * e - 2 * (1 / m - 1) * k),
                                 rel=1e-13)
    assert du[4] == pytest.approx(-8 * x[4] / (3 * np.pi) * (2 * (k - e) - m * (e + k) / 2),
                                  rel=1e-13)


def _operators(kernels, nodes, x, nu=0.3):
    out = []
    for kernel in kernels:
        g = influence.element_integrals(lambda a, s, k=kernel: k(a, s, nu), x, nodes)
        with np.errstate(invalid="ignore"):
            out.append(influence.apply_difference(g, nodes))
    return out


def _row_errors(new: np.ndarray, ref: np.ndarray) -> np.ndarray:
    """max |new - ref| / max |ref| per output and row (0 where both rows vanish)."""
    diff = np.max(np.abs(new - ref), axis=-1)
    scale = np.max(np.abs(ref), axis=-1)
    return np.where(scale > 0, diff / np.where(scale > 0, scale, 1.0), np.where(diff > 0, np.inf, 0.0))


@pytest.mark.parametrize("n", [64, 256])
@pytest.mark.parametrize("stick_ratio", [0.02, 0.5, 0.98])
def test_operators_match_the_reference_kernels(n, stick_ratio):
    mesh = graded_mesh(n, stick_ratio)
    nodes = mesh.nodes
    gauss, _ = slip_points(nodes, mesh.stick_index, 4)
    for where, x in (("nodes", nodes), ("gauss", gauss)):
        ref = _operators((ref_pressure_disc, ref_shear_disc), nodes, x)
        new = _operators((disc.pressure_disc, disc.shear_disc), nodes, x)
        for part, a, b in zip(("normal", "shear"), new, ref):
            assert a.shape == b.shape == (3, x.size, mesh.n + 1)  # mesh.n >= n (two-scale)
            assert np.all(np.isfinite(a)) and np.all(np.isfinite(b))  # sphere: no NaN rows
            err = _row_errors(a, b)
            for k, name in enumerate(("w", "u", "du/dx")):
                assert err[k].max() <= GATE, (where, part, name, err[k].max())
            # the reference differs from the package's kernels at all (not the same code)
            assert np.any(a != b), (where, part)


def _smoothstep(n):
    t, w = np.polynomial.legendre.leggauss(n)
    t, w = 0.5 * (t + 1.0), 0.5 * w
    return t**4 * (35 - 84 * t + 70 * t**2 - 20 * t**3), w * 140 * t**3 * (1 - t) ** 3


def _reference_integrals(kernel, x, nodes, order=40):
    """Every (point, element) pair by a smoothstep rule of ``order`` points, split at x."""
    t, w = _smoothstep(order)
    lo, hi = nodes[:-1][None, :], nodes[1:][None, :]
    xx = x[:, None]
    cut = np.clip(xx, lo, hi)
    out = np.zeros((3, x.size, nodes.size - 1))
    for a, b in ((lo, cut), (cut, hi)):
        length = np.broadcast_to(b - a, out.shape[1:])
        s = a[..., None] + length[..., None] * t
        vals = kernel(np.broadcast_to(xx[..., None], s.shape), s)
        with np.errstate(invalid="ignore"):
            for k in range(3):
                out[k] += np.where(length > 0, (vals[k] * w).sum(-1) * length, 0.0)
    return out


@pytest.mark.parametrize("stick_ratio", [0.1, 0.7])
def test_element_integrals_against_a_finer_rule(stick_ratio):
    """Quadrature error of the element integrals, as operators (row-relative), with the
    reference kernels in the 40-point rule.

    w and u: < 1e-10. du/dx: the pressure's jump at s = x is exact (split);
    the shear's log singularity at s = x is left to the 16-point smoothstep rule
    on the pieces touching x, which the speed-up kept unchanged: ~1e-7.
    """
    g = Geometry("sphere", 0.3)
    mesh = graded_mesh(48, stick_ratio)
    nodes = mesh.nodes
    x = np.concatenate([nodes, slip_points(nodes, mesh.stick_index, 2)[0]])
    for kernel, reference, tol_du in ((g.pressure_kernel, ref_pressure_disc, 1e-10),
                                      (g.shear_kernel, ref_shear_disc, 1e-6)):
        ref = influence.apply_difference(
            _reference_integrals(lambda a, s, f=reference: f(a, s, 0.3), x, nodes), nodes)
        new = influence.apply_difference(influence.element_integrals(kernel, x, nodes), nodes)
        err = _row_errors(new, ref)
        assert err[0].max() <= 1e-10 and err[1].max() <= 1e-10, err.max(axis=1)
        assert err[2].max() <= tol_du, err[2].max()


def test_element_integrals_chunking_and_order_do_not_matter():
    """Row blocks, kernel-call packing and the order of the points change nothing."""
    g = Geometry("sphere", 0.3)
    nodes = graded_mesh(40, 0.4).nodes
    rng = np.random.default_rng(3)
    x = rng.permutation(np.concatenate([nodes, rng.uniform(0.0, 1.0, 60)]))
    full = influence.element_integrals(g.shear_kernel, x, nodes)
    assert np.all(np.isfinite(full))
    atol = 1e-15 * np.abs(full).max()  # summation order of the weighted sums only
    small = influence.element_integrals(g.shear_kernel, x, nodes, chunk=50)
    np.testing.assert_allclose(small, full, rtol=0, atol=atol)
    order = np.argsort(x)
    sorted_ = influence.element_integrals(g.shear_kernel, x[order], nodes)
    np.testing.assert_allclose(sorted_, full[:, order], rtol=0, atol=atol)
    assert influence.element_integrals(g.shear_kernel, x[:0], nodes).shape == (3, 0, nodes.size - 1)


def test_apply_difference_matches_its_definition():
    rng = np.random.default_rng(0)
    nodes = np.sort(np.concatenate([[0.0, 1.0], rng.uniform(0, 1, 9)]))
    g = rng.standard_normal((3, 5, 10))
    h = np.diff(nodes)
    ref = np.zeros((3, 5, 11))
    ref[..., :-1] += g / h
    ref[..., 1:] -= g / h
    np.testing.assert_array_equal(influence.apply_difference(g, nodes), ref)
    np.testing.assert_array_equal(influence.apply_difference(g[0, 0], nodes), ref[0, 0])


@pytest.mark.parametrize("kind", ["sphere", "cylinder", "sphere elastic indenter",
                                  "cylinder layer", "sphere layer"])
def test_both_parts_in_one_pass_equal_each_alone_bit_for_bit(kind):
    """operators.nodal_operators / operators (the two parts' kernels integrated on one
    classification of the element pairs) give each part exactly the bits of its own
    call; with a shared store of stick blocks, in either order of filling it."""
    from contactlib.discretization import operators as ops
    from contactlib.model import contact

    geometry = kind.split()[0]
    kw = {"indenter_modulus": 2.0, "indenter_nu": 0.2} if "elastic" in kind else {}
    model = contact(geometry, 0.3, slab_ratio=0.5 if "layer" in kind else 0.0, **kw)
    for c in (0.0, 0.37, 1.0):
        mesh = graded_mesh(64, c)
        alone = [ops.nodal_operator_part(model, mesh, part) for part in ops.PARTS]
        together = ops.nodal_operators(model, mesh)
        for a, b in zip(alone, together):
            np.testing.assert_array_equal(a, b)
        store = ops.StickBlocks()
        ops.nodal_operator_part(model, mesh, "shear", cache=store)  # one part stored first
        for a, b in zip(alone, ops.nodal_operators(model, mesh, cache=store)):
            np.testing.assert_array_equal(a, b)
        for a, b in zip(alone, ops.nodal_operators(model, mesh, cache=store)):  # both stored
            np.testing.assert_array_equal(a, b)
        x = np.linspace(0.0, 1.3, 37)
        for with_w, with_du in ((True, True), (False, True), (False, False)):
            pw, qw = ops.operators(model, mesh.nodes, x, with_w=with_w, with_du=with_du)
            np.testing.assert_array_equal(pw, ops.operator_part(model, mesh.nodes, x, "normal",
                                                                with_w=with_w))
            np.testing.assert_array_equal(qw, ops.operator_part(model, mesh.nodes, x, "shear",
                                                                with_du=with_du))
            for rows in ((1, 2), (1,), (2, 0)):  # only some rows: the same bits
                pr, qr = ops.operators(model, mesh.nodes, x, with_w=with_w, with_du=with_du,
                                       rows=rows)
                np.testing.assert_array_equal(pr, pw[list(rows)])
                np.testing.assert_array_equal(qr, qw[list(rows)])


def test_element_integrals_into_a_column_block_give_the_same_bits():
    """``out=``: a block of columns of a wider array (as nodal_operators fills its
    operators) receives exactly the bits of a fresh result; the other columns are
    untouched; a wrong shape or layout is refused."""
    g = Geometry("sphere", 0.3)
    nodes = graded_mesh(48, 0.4).nodes
    x = np.concatenate([nodes, np.linspace(0.0, 1.2, 23)])
    kernels = (g.pressure_kernel, g.shear_kernel)
    fresh = influence.element_integrals(kernels, x, nodes[10:], chunk=300)
    wide = np.full((6, x.size, nodes.size - 11 + 7), -7.0)
    got = influence.element_integrals(kernels, x, nodes[10:], chunk=300, out=wide[:, :, 3:-4])
    assert got.base is not None and np.shares_memory(got, wide)
    np.testing.assert_array_equal(wide[:, :, 3:-4], fresh)
    assert (wide[:, :, :3] == -7.0).all() and (wide[:, :, -4:] == -7.0).all()
    rows = np.empty((2, x.size, nodes.size - 11))
    influence.element_integrals(kernels, x, nodes[10:], chunk=300, outputs=(2, 4), out=rows)
    np.testing.assert_array_equal(rows, fresh[[2, 4]])
    wrong_shape = np.empty((6, x.size, nodes.size))
    strided = np.empty((6, x.size, 2 * (nodes.size - 11)))[:, :, ::2]
    for bad in (wrong_shape, strided):
        with pytest.raises(ValueError, match="out"):
            influence.element_integrals(kernels, x, nodes[10:], out=bad)


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_fine_rules_reach_round_off_beyond_the_near_elements(geometry):
    """``quadrature="fine"`` against a 40-point Gauss rule on every element at least 2
    lengths from the point (graded mesh n = 128, c/a = 0.9, nu = 0.3), row-relative: the
    fine classes are at round-off (measured <= 1.6e-14 at n = 256); the standard ones
    leave up to ~1e-10 (the shear's u and du/dx), which is why they are not used near the
    floor (extrapolated_method.FINE_QUADRATURE_FROM_N)."""
    from contactlib.model import contact

    g = contact(geometry, 0.3)
    nodes = graded_mesh(128, 0.9).nodes
    x = nodes.copy()
    lo, length = nodes[:-1], np.diff(nodes)
    gap = np.maximum(np.maximum(lo[None] - x[:, None], x[:, None] - nodes[1:][None]), 0.0)
    far = gap >= 2.0 * length[None]
    t, w = np.polynomial.legendre.leggauss(40)
    t, w = 0.5 * (t + 1.0), 0.5 * w
    ii, jj = np.nonzero(far)
    s = lo[jj][:, None] + length[jj][:, None] * t[None]
    worst = {}
    for kernel, name in ((g.pressure_kernel, "pressure"), (g.shear_kernel, "shear")):
        vals = kernel(np.broadcast_to(x[ii][:, None], s.shape).ravel(), s.ravel())
        ref = np.zeros((3, x.size, lo.size))
        for k in range(3):
            ref[k, ii, jj] = (np.asarray(vals[k]).reshape(s.shape) @ w) * length[jj]
        scale = np.abs(ref).max(axis=2, keepdims=True)
        for quadrature in influence.QUADRATURES:
            got = influence.element_integrals(kernel, x, nodes, quadrature=quadrature)
            with np.errstate(invalid="ignore", divide="ignore"):
                err = np.where(far[None], np.abs(got - ref), 0.0) / scale
            worst[name, quadrature] = float(np.nanmax(err))
    assert max(v for (_, q), v in worst.items() if q == "fine") <= 1e-13, worst
    assert max(v for (_, q), v in worst.items() if q == "standard") >= 1e-12, worst


def test_unknown_quadrature_is_refused():
    with pytest.raises(ValueError, match="quadrature"):
        influence.element_integrals(lambda x, s: (x, x, x), np.array([0.5]),
                                    np.linspace(0.0, 1.0, 5), quadrature="exact")
