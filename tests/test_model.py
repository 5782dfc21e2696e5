"""The model layer: indenter measures, body kernels, the contact and its operators.

Every formula of :mod:`contactlib.model.indenter` is checked against an independent
evaluation (quadrature of its definition, the Hertz relations), and the two
operator kinds of :mod:`contactlib.discretization.operators` against each other.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import contactlib

from contactlib.solvers import history_solver as hs
from contactlib import validate
from contactlib.model.body import ElasticBody
from contactlib.discretization.elements import MeshStore, graded_mesh
from contactlib.model.geometry import Geometry
from contactlib.model.indenter import GEOMETRIES, Cylinder, Sphere, indenter
from contactlib.kernels import disc, layer, strip
from contactlib.model import Contact, contact
from contactlib.model.profiles import profile
from contactlib.discretization.operators import (StickBlocks, nodal_operator_part, operator_part,
                                                 step_operator)
from contactlib.model.theory import beta_of_nu, hertz_pressure

EDGES = np.array([0.0, 0.1, 0.35, 0.6, 0.95, 1.2])


def _quad(f, lo: float, hi: float, order: int = 12) -> float:
    t, w = np.polynomial.legendre.leggauss(order)
    x = lo + 0.5 * (hi - lo) * (t + 1.0)
    return float(0.5 * (hi - lo) * np.sum(w * f(x)))


def _measure(ind, x):
    """dA/dx: 2 pi r (ring) or 2 (strip pair, both sides of the axis)."""
    return 2.0 * np.pi * x if isinstance(ind, Sphere) else 2.0 * np.ones_like(x)


@pytest.mark.parametrize("name", GEOMETRIES)
def test_element_measures_are_integrals_of_their_definitions(name):
    ind = indenter(name)
    lo, hi = EDGES[:-1], EDGES[1:]
    area = [_quad(lambda x: _measure(ind, x), a, b) for a, b in zip(lo, hi)]
    res = [_quad(lambda x: ind.shear_shape(x) * _measure(ind, x), a, b) for a, b in zip(lo, hi)]
    np.testing.assert_allclose(ind.element_areas(EDGES), area, rtol=1e-13)
    np.testing.assert_allclose(ind.shear_resultants(EDGES), res, rtol=1e-13)
    np.testing.assert_allclose(ind.mean_shear_shape(EDGES), np.divide(res, area), rtol=1e-13)
    p = np.array([3.0, 1.0, 2.0, 0.5, 4.0])
    assert ind.load_of_steps(EDGES, p) == pytest.approx(float(np.dot(p, area)), rel=1e-13)
    # a piecewise-linear pressure, integrated exactly
    nodal = np.array([2.0, 1.5, 1.0, 0.7, 0.2, 0.0])

    def linear(x):
        return np.interp(x, EDGES, nodal) * _measure(ind, x)
    exact = sum(_quad(linear, a, b) for a, b in zip(lo, hi))
    assert ind.load_of_linear(EDGES, nodal) == pytest.approx(exact, rel=1e-13)


@pytest.mark.parametrize("name", GEOMETRIES)
def test_hertz_formulas_agree(name):
    """The Hertz load is the load of the Hertz pressure p0 sqrt(1 - x^2), and P ~ a^d."""
    ind = indenter(name)
    nodes = np.linspace(0.0, 1.0, 20001)
    p = ind.p0 * hertz_pressure(nodes)
    assert ind.load_of_linear(nodes, p) == pytest.approx(ind.hertz_load, rel=1e-5)
    for level in (0.001, 0.3, 1.0):
        a = ind.hertz_radius(level)
        assert a ** ind.load_exponent == pytest.approx(level, rel=1e-14)
    assert ind.work_exponent == ind.load_exponent + 2


def test_uncoupled_friction_limits():
    """Both closed forms vanish at c/a = 0 and grow without bound as c/a -> 1."""
    beta = beta_of_nu(0.3)
    for ind in (Sphere(), Cylinder()):
        k = ind.uncoupled_friction(beta, np.array([0.0, 0.5, 1.0 - 1e-12]))
        assert k[0] == 0.0 and 0.0 < k[1] < k[2] and k[2] > 1.0
    # sphere near c = 0: k ~ beta / K'(g), which is ~ beta / ln(4/g)
    g = 1e-8
    assert Sphere().uncoupled_friction(beta, g) == pytest.approx(beta / math.log(4 / g), rel=1e-6)


def test_unknown_geometry_is_refused_with_the_name():
    with pytest.raises(ValueError, match="'cone'"):
        indenter("cone")
    with pytest.raises(ValueError, match="sphere, cylinder"):
        contact("cone", 0.3)


@pytest.mark.slow  # (2 s; the kernels' own tests check the closed forms in the fast tier)
def test_the_body_answers_rings_and_strips_with_the_closed_forms():
    x, s = np.array([0.2, 0.7, 1.5]), np.array([1.0, 1.0, 1.0])
    half = ElasticBody(0.25)
    for got, want in ((half.ring_pressure(x, s), disc.pressure_disc(x, s, 0.25)),
                      (half.ring_shear(x, s), disc.shear_disc(x, s, 0.25)),
                      (half.strip_pressure(x, s), strip.pressure_strip(x, s, 0.25, np.inf)),
                      (ElasticBody(0.25, 0.1).strip_shear(x, s),
                       strip.shear_strip(x, s, 0.25, 10.0))):
        for a, b in zip(got, want):
            np.testing.assert_array_equal(a, b)
    for base in ("smooth", "bonded"):  # a layer: the layer kernels with h = 1/slab_ratio
        body = ElasticBody(0.25, 0.1, base)
        for got, want in ((body.ring_pressure(x, s), layer.pressure_disc(x, s, 0.25, 10.0, base)),
                          (body.ring_shear(x, s), layer.shear_disc(x, s, 0.25, 10.0, base)),
                          (body.strip_pressure(x, s),
                           strip.pressure_strip(x, s, 0.25, 10.0, base))):
            for a, b in zip(got, want):
                np.testing.assert_array_equal(a, b)
        assert body.ring_kernel_degrees is None
        assert contact("sphere", 0.25, 0.1, base=base).length_degrees("normal") is None


@pytest.mark.parametrize("name, slab", [("sphere", 0.0), ("cylinder", 0.0), ("cylinder", 0.05)])
def test_geometry_is_the_contact_of_its_names(name, slab):
    g = Geometry(name, 0.3, slab)
    m = contact(name, 0.3, slab)
    assert isinstance(g, Contact)
    assert (g.indenter, g.body) == (m.indenter, m.body)
    assert g.thickness == m.body.thickness
    assert (g.p0, g.hertz_load, g.work_factor) == (m.p0, m.hertz_load, m.work_factor)
    # nu = 0.5 decouples a half-space, never a layer (tests/test_layer_incompressible.py)
    assert m.decoupled is False and contact(name, 0.5, slab).decoupled is (slab == 0.0)


@pytest.mark.parametrize("name, slab", [("sphere", 0.0), ("cylinder", 0.0), ("cylinder", 0.05)])
def test_step_operator_is_the_linear_operator_of_step_tractions(name, slab):
    """A step traction on element j is a piecewise-linear one with a jump: the
    difference of two nearly coincident nodes gives the same displacements."""
    m = contact(name, 0.3, slab)
    edges = np.linspace(0.0, 1.0, 5)
    x = np.array([0.05, 0.4, 0.77, 1.3])
    eps = 1e-7
    for part in ("normal", "shear"):
        steps = step_operator(m, edges, x, part)
        # the step on [e_j, e_{j+1}] = linear hat sum on nodes with eps-wide ramps
        nodes = np.unique(np.concatenate([edges, edges[1:] - eps]))
        lin = operator_part(m, nodes, x, part)
        for j in range(edges.size - 1):
            phi = ((nodes >= edges[j]) & (nodes <= edges[j + 1] - eps)).astype(float)
            if j == edges.size - 2:
                phi[-1] = 0.0  # phi_N = 0: the last ramp ends at the contact edge
            np.testing.assert_allclose((lin @ phi)[:2], steps[:2, :, j], atol=2e-6)


def test_history_operators_come_from_the_step_operator_and_the_indenter():
    m = contact("sphere", 0.3)
    ops = hs.build_operators(m, 12)
    np.testing.assert_array_equal(ops.pw, step_operator(m, ops.edges, ops.mid, "normal")[0])
    np.testing.assert_array_equal(ops.qu,
                                  step_operator(m, ops.edges, ops.mid, "shear")[1] / ops.mid)
    np.testing.assert_array_equal(ops.area, m.indenter.element_areas(ops.edges))
    assert ops.model is m and ops.p_max == m.hertz_load


def test_stick_blocks_are_a_caller_owned_store():
    """With a store of its own a caller gets the same operator, and the store holds the block."""
    m = contact("sphere", 0.3)
    mesh = graded_mesh(32, 0.5)
    store = StickBlocks(size=1)
    a = nodal_operator_part(m, mesh, "normal", cache=store)
    b = operator_part(m, mesh.nodes, mesh.nodes, "normal")
    assert len(store) == 1
    np.testing.assert_allclose(a, b, rtol=0, atol=1e-12 * np.max(np.abs(b)))
    nodal_operator_part(m, graded_mesh(32, 0.5), "shear", cache=store)
    assert len(store) == 1  # bounded: the oldest block went
    # the half-plane's kernels are not homogeneous: nothing is stored
    nodal_operator_part(contact("cylinder", 0.3), mesh, "normal", cache=store)
    assert len(store) == 1


def test_graded_meshes_are_kept_by_a_caller_owned_store_only():
    """A store builds each mesh once and hands out copies; without one nothing is kept."""
    store = MeshStore(size=2)
    a = graded_mesh(64, 0.3, store=store)
    a.nodes[:] = -1.0  # a caller's copy: the store's nodes are untouched
    b = graded_mesh(64, 0.3, store=store)
    np.testing.assert_array_equal(b.nodes, graded_mesh(64, 0.3).nodes)
    assert (store.misses, store.hits, len(store)) == (1, 1, 1)
    graded_mesh(64, 0.4, store=store)
    graded_mesh(64, 0.5, store=store)
    assert len(store) == 2  # bounded: the oldest mesh went
    assert isinstance(StickBlocks().meshes, MeshStore)  # a sweep's store brings its meshes


def test_stick_blocks_do_not_make_results_depend_on_earlier_calls():
    """Each call owns its store: no bits carry over from earlier calls in the process."""
    m = contact("sphere", 0.3)
    target = graded_mesh(64, 0.5)
    alone = nodal_operator_part(m, target, "shear")
    store = StickBlocks()
    for c in (0.3, 0.7):  # other c/a fill the store first
        nodal_operator_part(m, graded_mesh(64, c), "shear", cache=store)
    warm = nodal_operator_part(m, target, "shear", cache=store)
    b = operator_part(m, target.nodes, target.nodes, "shear")
    for a in (alone, warm):  # the reuse is exact to round-off
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-12 * np.max(np.abs(b)))
    # and a call gives the same bits before and after other calls in the process
    first = contactlib.sweep("sphere", 0.3, [0.5], n=64, energy=False)[0].friction_coefficient
    contactlib.sweep("sphere", 0.3, [0.2, 0.35, 0.7], n=64, energy=False)
    again = contactlib.sweep("sphere", 0.3, [0.5], n=64, energy=False)[0].friction_coefficient
    assert first == again


def test_history_mesh_extent_is_the_one_validate_bounds_the_layer_with():
    assert validate.HISTORY_MESH_EXTENT == hs.MESH_EXTENT


def test_graded_mesh_nodes_are_those_of_all_110_bisection_steps():
    """elements._invert drops a point once a halving leaves its bracket unchanged: the
    nodes must be bit for bit those of the plain 110-step bisection (written out here)."""
    from contactlib.discretization import elements

    def plain(count, targets, span):
        lo, hi = np.zeros_like(targets), np.full_like(targets, np.sqrt(span))
        for _ in range(110):
            mid = 0.5 * (lo + hi)
            below = count(mid * mid) < targets
            lo, hi = np.where(below, mid, lo), np.where(below, hi, mid)
        return (0.5 * (lo + hi)) ** 2

    for c in (1e-8, 1e-4, 0.02, 0.3, 0.5, 0.77, 0.98, 0.9999, 1 - 1e-5):
        stick, slip = elements._side_counts(c)
        for count, span in ((stick, c), (slip, 1.0 - c)):
            targets = float(count(span)) * np.linspace(0.0, 1.0, 97)
            got = elements._invert(count, targets, span)
            np.testing.assert_array_equal(got, plain(count, targets, span))


def test_results_carry_the_model_they_solved():
    """A result carries its problem model; the flat fields copy it for the datasets."""
    import contactlib

    sol = contactlib.solve("sphere", 0.3, stick_ratio=0.5, n=32, slab_ratio=2.0,
                           base="bonded", energy=False)
    want = contact("sphere", 0.3, 2.0, base="bonded")
    assert isinstance(sol.model, Contact)
    assert (sol.model.indenter, sol.model.body) == (want.indenter, want.body)
    assert sol.model.beta == sol.dundurs_beta and sol.model.body.base == sol.base
    res = contactlib.history("cylinder", 0.25, 0.2, [0, 1], 4, n=40)
    assert isinstance(res.model, Contact) and res.model.beta == res.dundurs_beta
    assert res.model.profile.name == res.profile


MODELS = [dict(geometry="sphere", nu=0.3),
          dict(geometry="cylinder", nu=0.25, slab_ratio=0.5, base="bonded"),
          dict(geometry="sphere", nu=0.3, slab_ratio=2.0, base="elastic", substrate_modulus=10.0,
               substrate_nu=0.2),
          dict(geometry="sphere", nu=0.3, indenter_modulus=2.0, indenter_nu=0.1),
          dict(geometry="cylinder", nu=0.3, profile="power", exponent=3.0),
          dict(geometry="sphere", nu=0.3, profile="rounded", flat_ratio=0.5),
          dict(geometry="sphere", nu=0.3, relaxation=[[0.5, 1.0]])]


def _model_of(kw):
    kw = dict(kw)
    shape = profile(kw.pop("profile", "paraboloid"), kw.pop("exponent", None),
                    kw.pop("flat_ratio", None))
    kw["relaxation"] = tuple(tuple(t) for t in kw.pop("relaxation", ()))
    return contact(**kw, profile=shape)


@pytest.mark.parametrize("kw", MODELS, ids=lambda kw: "-".join(map(str, kw.values())))
def test_keywords_are_the_inverse_of_contact(kw):
    m = _model_of(kw)
    assert m.keywords() == kw
    again = _model_of(m.keywords())
    assert (again.indenter, again.body, again.profile) == (m.indenter, m.body, m.profile)


def test_entry_points_take_the_model():
    import contactlib

    for kw in MODELS[:5]:
        m = _model_of(kw)
        a = contactlib.solve(m, stick_ratio=0.3, n=32, energy=False)
        b = contactlib.solve(**kw, stick_ratio=0.3, n=32, energy=False)
        assert a.friction_coefficient == b.friction_coefficient and a.converged
        assert (a.model.indenter, a.model.body, a.model.profile) == (m.indenter, m.body,
                                                                      m.profile)
    m = _model_of(MODELS[1])
    assert [s.friction_coefficient for s in contactlib.sweep(m, [0.2, 0.6], n=32,
                                                              energy=False)] == \
        [s.friction_coefficient for s in contactlib.sweep(**MODELS[1], stick_ratios=[0.2, 0.6],
                                                           n=32, energy=False)]
    for kw in (MODELS[5], MODELS[6]):  # positional arguments after the model: friction, path
        m = _model_of(kw)
        extra = {"duration": 1.0} if "relaxation" in kw else {}
        a = contactlib.history(m, 0.2, [0, 1, 0], 4, n=40, **extra)
        b = contactlib.history(**kw, friction=0.2, load_path=[0, 1, 0], steps=4, n=40,
                               **extra)
        np.testing.assert_array_equal(a.stick_ratio, b.stick_ratio)


def test_a_model_given_with_its_keywords_or_to_the_wrong_door_is_refused():
    import contactlib
    from contactlib.validate import InputError

    m = _model_of(MODELS[1])
    with pytest.raises(InputError, match="slab_ratio must be given once"):
        contactlib.solve(m, stick_ratio=0.3, slab_ratio=1.0)
    with pytest.raises(InputError, match="at most 0 positional"):
        contactlib.solve(m, 0.3, stick_ratio=0.3)
    with pytest.raises(InputError, match="use history for a viscoelastic body"):
        contactlib.solve(_model_of(MODELS[6]), stick_ratio=0.3)
