"""The compiled parts (``contactlib/kernels/disc_fused.c``, ``strip_fused.c``,
``contactlib/discretization/operators_fused.c``) against the numpy routes they replace.

The compiled route promises the same bits as the numpy chunk functions of
:mod:`contactlib.kernels.disc` (the same IEEE operations in the same order, no fused
multiply-adds), so every comparison here is exact: ``array_equal``, not a tolerance. The
numpy route itself is checked against independent integrals in ``test_kernels_disc.py``.
"""

from __future__ import annotations

import numpy as np
import pytest

from contactlib.discretization import influence, operators
from contactlib.solvers import default_method
from contactlib.discretization.elements import graded_mesh
from contactlib.kernels import disc, strip
from contactlib.model import contact
from contactlib.discretization.operators import nodal_operators

needs_fused = pytest.mark.skipif(not (disc.FUSED and strip.FUSED and influence.FUSED
                                      and operators.FUSED and default_method.FUSED),
                                 reason="the compiled parts are not built")


@pytest.fixture
def numpy_route(monkeypatch):
    """Run the block with the numpy routes (disc.FUSED, influence.FUSED False), then restore."""
    def call(f, *args, **kwargs):
        for module in (disc, strip, influence, operators, default_method):
            monkeypatch.setattr(module, "FUSED", False)
        try:
            return f(*args, **kwargs)
        finally:
            monkeypatch.undo()
    return call


def _points(seed: int = 0, size: int = 200_000) -> tuple[np.ndarray, np.ndarray]:
    """Random (r, s) with the removable and singular places the kernels treat apart."""
    rng = np.random.default_rng(seed)
    r = rng.random(size) * 3.0 - 0.5  # negative r: |r| (a strip axis, symmetric)
    s = rng.random(size) * 1.5 - 0.1  # s <= 0: zero output
    k = size // 10
    r[:k] = s[:k]  # r = s exactly: m1 = 0, du/dr of the shear -inf
    r[k:2 * k] = s[k:2 * k] * (1.0 + 1e-15 * rng.standard_normal(k))  # r -> s
    r[2 * k:3 * k] = 0.0  # the axis
    r[3 * k:4 * k] = s[3 * k:4 * k] * 1e-9  # r << s: m -> 0 inside
    s[4 * k:5 * k] = r[4 * k:5 * k] * 1e-9  # s << r: m' -> 0 outside
    order = np.argsort(np.abs(r) <= s, kind="stable")  # runs inside/outside, as in use
    return np.concatenate([r, r[order]]), np.concatenate([s, s[order]])


@needs_fused
@pytest.mark.parametrize("nu", [0.3, -0.99, 0.5, 0.0])
@pytest.mark.parametrize("kernel, options", [
    (disc.pressure_disc, {}), (disc.pressure_disc, {"with_w": False}),
    (disc.shear_disc, {}), (disc.shear_disc, {"with_du": False})])
def test_compiled_kernels_give_the_numpy_bits(numpy_route, kernel, options, nu):
    r, s = _points()
    got = kernel(r, s, nu, **options)
    want = numpy_route(kernel, r, s, nu, **options)
    for name, g, w in zip(("w", "u", "du"), got, want):
        assert np.array_equal(g, w, equal_nan=True), (name, np.flatnonzero(
            ~((g == w) | (np.isnan(g) & np.isnan(w))))[:5])
    on_edge = (np.abs(r) == s) & (s > 0.0)  # the shear's du/dr is -inf there, and only there
    assert on_edge.sum() > 1000
    if kernel is disc.shear_disc and not options:
        assert np.array_equal(np.isneginf(got[2]), on_edge)


@needs_fused
@pytest.mark.parametrize("nu", [0.3, -0.99, 0.5])
@pytest.mark.parametrize("kernel", [strip.pressure_strip, strip.shear_strip])
def test_compiled_strip_kernels_give_the_numpy_bits(numpy_route, kernel, nu):
    """The half-plane (and, through it, the slab's) strip kernels, edges and axis included."""
    r, s = _points(1)
    s = np.abs(s)  # (a strip's half-width is refused below 0)
    for h in (np.inf, 0.7):
        got = kernel(r, s, nu, h)
        want = numpy_route(kernel, r, s, nu, h)
        for name, g, w in zip(("w", "u", "du"), got, want):
            assert np.array_equal(g, w, equal_nan=True), (name, h)


@needs_fused
@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_compiled_kernels_give_the_numpy_operators(numpy_route, geometry):
    """The nodal operators (every kernel route, through influence) bit for bit."""
    model, mesh = contact(geometry, 0.3), graded_mesh(64, 0.4)
    got = nodal_operators(model, mesh)
    want = numpy_route(nodal_operators, model, mesh)
    for g, w in zip(got, want):
        assert np.array_equal(g, w, equal_nan=True)


@needs_fused
def test_compiled_kernels_refuse_bad_buffers():
    """Wrong lengths or types are errors, never a read past an array."""
    from contactlib.kernels import disc_fused as fused

    r = np.ones(4)
    with pytest.raises(ValueError, match="expected 4"):
        fused.m1(r, np.ones(3), np.empty(4))
    with pytest.raises(TypeError, match="float64"):
        fused.m1(r, np.ones(4, dtype=np.float32), np.empty(4))
    stack = np.ones((11, 2))
    with pytest.raises(ValueError, match="stack_in has 22 values, expected 44"):
        fused.shear(r, r, r, 0.1, 1.0, stack, stack, np.empty(4), np.empty(4), np.empty(4),
                    True)


@needs_fused
def test_compiled_difference_gives_the_numpy_bits(numpy_route):
    """apply_difference: a fresh output, and in place (g the first N columns of out)."""
    rng = np.random.default_rng(3)
    nodes = np.concatenate([[0.0], np.cumsum(rng.random(40) ** 3 + 1e-12)])
    g = rng.standard_normal((3, 17, 40)) * 10.0 ** rng.integers(-12, 3, (3, 17, 1))
    want = numpy_route(influence.apply_difference, g, nodes)
    assert np.array_equal(influence.apply_difference(g, nodes), want)
    both = np.empty((3, 17, 41))
    both[:, :, :40] = g
    influence.apply_difference(both[:, :, :40], nodes, out=both)
    assert np.array_equal(both, want)
    with pytest.raises(ValueError, match="difference needs"):
        from contactlib.discretization import operators_fused
        operators_fused.difference(np.ones((2, 3)), np.ones(2), np.empty((2, 4)))


@needs_fused
def test_compiled_restriction_gives_the_numpy_bits(numpy_route):
    """restrict_nested (both parts' operators, NaN du/dx on a strip axis included)."""
    mesh = graded_mesh(64, 0.5)
    for op in operators.nodal_operators(contact("cylinder", 0.3), mesh):
        want = numpy_route(operators.restrict_nested, op, mesh)
        got = operators.restrict_nested(op, mesh)
        for g, w in zip(got, want):
            assert np.array_equal(g, w, equal_nan=True)


@needs_fused
@pytest.mark.parametrize("r0", [0.2, 0.5, 0.999])
def test_compiled_w_differences_give_the_numpy_bits(numpy_route, r0):
    """w(r) - w(r0) of the pressure (Gauss integrals of dw/dr, E - K near and at m = 1)."""
    r, s = _points(2, 50_000)
    r, s = np.abs(r), np.abs(s)
    r[:500] = r0  # r = r0: an empty interval
    s[500:1000] = r0  # the disc edge at the reference point
    got = disc.w_difference_disc(r, r0, s, 0.3, "normal")
    want = numpy_route(disc.w_difference_disc, r, r0, s, 0.3, "normal")
    for g, w in zip(got, want):
        if np.lib.NumpyVersion(np.__version__) >= "2.4.0":
            assert np.array_equal(g, w, equal_nan=True)
        else:  # older numpy rounds some elementwise functions differently from the C
            # library (numpy 2.0.0: 155 of 50,000 values, by at most 1.5 ulp)
            same = (g == w) | (np.isnan(g) & np.isnan(w))
            assert np.count_nonzero(~same) <= 0.01 * g.size
            np.testing.assert_array_max_ulp(g[~same], w[~same], maxulp=2)


@needs_fused
@pytest.mark.parametrize("geometry, c", [("sphere", 0.5), ("cylinder", 0.9)])
def test_compiled_newton_set_up_gives_the_numpy_bits(numpy_route, geometry, c):
    """newton_on_k with overwrite (n >= 1024): equilibration, scaling and the first A(k)
    compiled; the same k and solution, bit for bit."""
    model, mesh = contact(geometry, 0.3), graded_mesh(1024, c)
    ops = nodal_operators(model, mesh)

    def newton():
        system = default_method.assemble(model, mesh, *ops)
        out = default_method.newton_on_k(system, 0.9 * float(model.uncoupled_friction(c)),
                                         refine=True, overwrite=True)
        return out, system.scales

    got, got_scales = newton()
    want, want_scales = numpy_route(newton)
    assert got.k == want.k and got.iterations == want.iterations and got.converged
    assert np.array_equal(got.x, want.x)
    for g, w in zip(got_scales, want_scales):
        assert np.array_equal(g, w)


@needs_fused
@pytest.mark.parametrize("size, nb, start", [(3201, 1100, 2000), (8193, 8, 100),
                                             (9000, 8500, 300), (13, 0, 4), (1, 1, 0)])
def test_compiled_residual_gives_the_einsum_bits(numpy_route, size, nb, start):
    """The extended-precision residual rhs - (a0 + k a1) y (n >= 1024): compiled, numpy's
    einsum loop for long double, rows longer than its 8192-element runs included (9000:
    split); entries over 40 orders of magnitude, so that a different order of summation
    shows in the last bits."""
    rng = np.random.default_rng(size)
    a0 = rng.standard_normal((size, size)) * np.exp(rng.uniform(-20.0, 20.0, (size, size)))
    a1 = rng.standard_normal((size, nb)) * np.exp(rng.uniform(-5.0, 5.0, (size, nb)))
    y = rng.standard_normal(size) * np.exp(rng.uniform(-10.0, 10.0, size))
    rhs = rng.standard_normal(size)
    cols = slice(start, start + nb)  # (newton_on_k's block of a1 columns)
    args = (a0, a1, cols, 0.37, y, rhs)
    got = default_method._extended_residual(*args, fused=True)
    want = numpy_route(default_method._extended_residual, *args, fused=True)
    assert np.array_equal(got, want)
    exact = rhs.astype(np.longdouble) - (a0.astype(np.longdouble) @ y.astype(np.longdouble)
                                         + np.longdouble(0.37) * (a1.astype(np.longdouble)
                                                                  @ y[cols].astype(np.longdouble)))
    scale = np.abs(a0) @ np.abs(y) + 0.37 * np.abs(a1) @ np.abs(y[cols]) + np.abs(rhs)
    assert np.all(np.abs(got - exact.astype(float)) <= 1e-15 * scale + 1e-300)
