"""The flat punch (``profile="flat"``) and the rounded flat punch (``"rounded"``) under
``history``: closed forms and partial slip.

Independent truths:

- frictionless: Boussinesq, P = 2 E* a delta and p = P/(2 pi a sqrt(a^2 - r^2)); plane
  strain p = P/(pi sqrt(a^2 - x^2)) (the closed-form element averages);
- no slip: Mossakovskii's bonded punch, P/(2 E* a delta) = (1 - nu) ln(3 - 4 nu)/(1 - 2 nu),
  and in plane strain the bonded punch's q/p = tan(eta ln((a + x)/(a - x))), eta =
  ln(3 - 4 nu)/(2 pi);
- partial slip: the solution is proportional to the load (identity: every increment is
  the same problem), and its stick ratio and stiffness are those of the self-similar
  power-law problem at the same k, whose pressure increment at fixed r is the flat
  punch's: the stick ratio of the self-similar default method (a different discrete
  system: piecewise-linear tractions on a growing contact, k found for a given c/a) and
  its dP/d(delta), load_ratio/indentation.

On layers and coatings (rigid base smooth or bonded, elastic substrate), where no
self-similar solution holds:

- frictionless, the flat punch's stiffness P/delta is dP/d(delta) of the paraboloid at the
  same a/h (any frictionless contact: its load increment is the flat punch's), from the
  self-similar solve's load and approach at a/h (1 -+ 1e-3), differentiated in a;
- with friction, the stick ratio is that of the paraboloid's ``history`` at the top of a
  monotonic loading, whose increment at contact radius a is the flat punch's problem at
  a/h (a growing contact on another mesh: a different discrete system).

Every comparison converges at first order in the element size (the square-root edge
singularity on constant elements): each is checked at two meshes, the error falling by
about half.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from contactlib import fretting, history, solve, validate
from contactlib.cli import main
from contactlib.model.profiles import FLAT, profile
from contactlib.scene import parse_scene
from contactlib.stresses import history_stresses


def _run(geometry: str, nu: float, k: float, n: int, path=(0, 1), steps: int = 2, **kw):
    return history(geometry, nu, k, list(path), steps, n=n, profile="flat",
                   error_estimate=False, **kw)


def _halving(errors: list[float]) -> None:
    """First-order convergence: each refinement halves the error (within 0.4-0.6)."""
    for coarse, fine in zip(errors[:-1], errors[1:]):
        assert 0.4 < fine / coarse < 0.6, errors


def test_the_profile_is_the_flat_punch():
    assert profile("flat") is FLAT and FLAT.is_flat and not FLAT.is_paraboloid
    assert FLAT.frictionless_load(True) == 2.0 and FLAT.frictionless_load(False) == 1.0
    r = np.array([0.0, 0.5, 1.0, 1.5])
    assert np.array_equal(FLAT.gap(r), [0.0, 0.0, 0.0, np.inf])
    with pytest.raises(ValueError):
        profile("flat", 3.0)  # the flat punch has no exponent


@pytest.mark.parametrize("geometry, axisymmetric", [("sphere", True), ("cylinder", False)])
def test_frictionless_is_boussinesq(geometry, axisymmetric):
    errors_p, errors_d = [], []
    for n in (120, 240):
        r = _run(geometry, 0.3, 0.0, n)
        assert r.converged.all() and "end of the mesh" not in r.message
        a, b = r.xi_bounds.T
        assert b[-1] == 1.0  # the mesh is the punch's face
        if axisymmetric:  # the average of 1/(pi sqrt(1 - r^2)) over each ring
            exact = 2.0 * (np.sqrt(1 - a**2) - np.sqrt(1 - b**2)) / ((b**2 - a**2) * math.pi)
        else:
            exact = (np.arcsin(b) - np.arcsin(a)) / ((b - a) * math.pi)
        p = r.pressure[-1] * FLAT.reference_pressure(axisymmetric)
        inner = r.xi < 0.9
        errors_p.append(float(np.max(np.abs(p[inner] / exact[inner] - 1.0))))
        if axisymmetric:  # delta = P/(2 E* a) = 1 at the load unit
            errors_d.append(abs(r.indentation[-1] - 1.0))
        assert np.all(r.shear == 0.0) and r.frictional_work[-1] == 0.0
    assert errors_p[-1] < 5e-3
    _halving(errors_p)
    if axisymmetric:
        assert errors_d[-1] < 1e-3
        _halving(errors_d)


@pytest.mark.parametrize("nu", [0.0, 0.3, 0.45])
def test_no_slip_sphere_has_mossakovskii_stiffness(nu):
    expected = (1 - nu) * math.log(3 - 4 * nu) / (1 - 2 * nu)  # P/(2 E* a delta)
    errors = []
    for n in (120, 240):
        r = _run("sphere", nu, math.inf, n)
        assert r.converged.all()
        errors.append(abs(2.0 / (2.0 * r.indentation[-1]) / expected - 1.0))
    assert errors[-1] < 1e-3
    _halving(errors)


@pytest.mark.parametrize("nu", [0.1, 0.3])
def test_no_slip_cylinder_has_the_bonded_punch_tractions(nu):
    eta = math.log(3 - 4 * nu) / (2 * math.pi)
    errors = []
    for n in (120, 240):
        r = _run("cylinder", nu, math.inf, n)
        assert r.converged.all()
        x = r.xi[r.xi < 0.8]
        ratio = r.shear[-1][: x.size] / r.pressure[-1][: x.size]
        errors.append(float(np.max(np.abs(ratio - np.tan(eta * np.log((1 + x) / (1 - x)))))))
    assert errors[-1] < 1e-3
    _halving(errors)


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_partial_slip_is_proportional_to_the_load(geometry):
    r = _run(geometry, 0.3, 0.2, 120, steps=5)
    load = r.load_ratio[1:, None]
    assert np.ptp(r.stick_ratio[1:]) < 1e-12  # the stick zone does not move
    for field in (r.pressure, r.shear, r.tangential_displacement):
        per_load = field[1:] / load
        assert np.max(np.abs(per_load - per_load[-1])) < 1e-10 * np.max(np.abs(field))


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
@pytest.mark.parametrize("k", [0.1, 0.3, 0.5])
def test_stick_ratio_is_the_self_similar_one(geometry, k):
    exact = solve(geometry, 0.3, friction=k, n=512)
    assert exact.converged
    for n in (240, 480):  # within half an element (measured: up to 0.26 of one)
        r = _run(geometry, 0.3, k, n)
        assert abs(r.stick_ratio[-1] - exact.stick_ratio) < 0.5 / n


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
@pytest.mark.parametrize("modulus, nu1", [(0.5, 0.0), (3.0, 0.45)])
def test_stick_ratio_with_an_elastic_indenter_is_the_self_similar_one(geometry, modulus, nu1):
    pair = {"indenter_modulus": modulus, "indenter_nu": nu1}  # beta < 0 and > 0
    exact = solve(geometry, 0.3, friction=0.2, n=512, **pair)
    assert exact.converged
    r = _run(geometry, 0.3, 0.2, 480, **pair)
    assert abs(r.stick_ratio[-1] - exact.stick_ratio) < 0.5 / 480  # measured 0.22 at most


def test_no_slip_oscillation_finer_than_an_element_is_flagged():
    """No slip at nu = 0: the bonded punch's pressure changes sign within 2 exp(-pi/(2 eta))
    a = 2.5e-4 a of the edge (eta = ln 3/(2 pi)). Elements of 2e-3 a (n = 480) already
    cannot keep contact there: the active set cycles, and the step says so."""
    r = _run("cylinder", 0.0, math.inf, 480)
    assert not r.converged[-1] and not r.resolved[-1]
    assert "did not converge" in r.message


@pytest.mark.parametrize("k", [0.1, 0.3])
def test_stiffness_is_the_self_similar_one(k):
    """P/(2 E* a delta) of the flat punch = dP/d(delta) of the paraboloid over 2 E* a."""
    s = solve("sphere", 0.3, friction=k, n=512)
    expected = s.load_ratio / s.extra["indentation"]
    errors = [abs(1.0 / _run("sphere", 0.3, k, n).indentation[-1] / expected - 1.0)
              for n in (120, 240)]
    assert errors[-1] < 1e-3
    _halving(errors)


def _paraboloid_stiffness(geometry: str, t: float, **layer) -> float:
    """dP/d(delta) of the frictionless paraboloid at a/h = t, over E* a (a = R = E* = 1)."""
    def measures(ratio: float) -> tuple[float, float]:
        s = solve(geometry, 0.3, stick_ratio=0.0, n=256, slab_ratio=ratio, **layer)
        assert s.converged
        return s.load_ratio, s.extra["indentation"]

    (lo_l, lo_d), (l, d), (hi_l, hi_d) = (measures(t * f) for f in (1 - 1e-3, 1.0, 1 + 1e-3))
    dl, dd = (hi_l - lo_l) / 2e-3, (hi_d - lo_d) / 2e-3  # t dL/dt and t dD/dt
    # P = L P_Hertz(a) ~ L a^3 (a^2), delta = D a^2: d/da at fixed h
    if geometry == "sphere":
        return 4.0 / 3.0 * (3.0 * l + dl) / (2.0 * d + dd)
    return math.pi / 4.0 * (2.0 * l + dl) / (2.0 * d + dd)


@pytest.mark.parametrize("geometry, layer", [
    ("sphere", {"base": "bonded"}), ("sphere", {"base": "smooth"}),
    ("sphere", {"base": "elastic", "substrate_modulus": 0.1}),
    ("cylinder", {"base": "bonded"}), ("cylinder", {"base": "smooth"})])
def test_frictionless_stiffness_on_a_layer_is_the_paraboloids(geometry, layer):
    expected = _paraboloid_stiffness(geometry, 1.0, **layer)
    load = FLAT.frictionless_load(geometry == "sphere")
    errors = [abs(load / _run(geometry, 0.3, 0.0, n, slab_ratio=1.0, **layer).indentation[-1]
                  / expected - 1.0) for n in (120, 240)]
    assert errors[-1] < 2e-3  # measured 1.3e-3 at most
    _halving(errors)


@pytest.mark.parametrize("geometry, layer", [
    ("sphere", {"base": "bonded", "slab_ratio": 1.0}),
    ("cylinder", {"base": "smooth", "slab_ratio": 0.5})])
def test_stick_ratio_on_a_layer_is_the_paraboloid_history_at_its_top(geometry, layer):
    n = 480
    top = history(geometry, 0.3, 0.2, [0, 1], 200, n=n, error_estimate=False, **layer)
    a = top.contact_radius[-1]  # units a_max: the flat punch's a/h is a times a_max/h
    flat = _run(geometry, 0.3, 0.2, n, base=layer["base"], slab_ratio=layer["slab_ratio"] * a)
    assert abs(flat.stick_ratio[-1] - top.stick_ratio[-1]) < 1.0 / n  # measured 0.32, 0.05


def test_decoupled_body_has_no_shear():
    r = _run("sphere", 0.5, 0.2, 60)
    assert np.all(r.shear == 0.0) and "decouple" in r.message


def test_cycle_is_resolved_and_balanced():
    r = history("sphere", 0.3, 0.2, [0, 1, 0], 40, n=120, profile="flat")
    assert r.converged.all() and r.profile == "flat"
    assert "end of the mesh" not in r.message
    assert np.all(np.diff(r.frictional_work) >= 0.0)
    # energy balance at the end of the cycle: the indenter's work went into friction
    assert abs(r.external_work[-1] - r.frictional_work[-1]) < 1e-3 * r.frictional_work[-1]
    assert np.isfinite(r.work_error_estimate).all()


def test_refused_where_it_is_not_covered():
    with pytest.raises(validate.InputError, match="history only"):
        solve("sphere", 0.3, friction=0.2, profile="flat")
    with pytest.raises(validate.InputError, match="fretting"):
        fretting("cylinder", 0.3, 0.2, [0, 1, 1], [0, 0, 0.5], profile="flat")
    r = _run("sphere", 0.3, 0.2, 30)
    with pytest.raises(validate.InputError, match="flat punch"):
        history_stresses(r, -1, [0.5], [0.5])
    scene = {"kind": "history", "geometry": "cylinder", "nu": 0.3, "friction": [0.2],
             "load_path": [0, 1, 1], "steps": 20, "n": 60, "profile": "flat"}
    assert parse_scene("s", scene).profile == "flat"  # a history scene takes it
    with pytest.raises(ValueError, match=r"^scenes\.s\.profile: profile 'flat' is not taken"):
        parse_scene("s", dict(scene, tangential_path=[0, 0, 0.5]))


def test_command_line(tmp_path, capsys):
    assert main(["solve", "--geometry", "sphere", "--nu", "0.3", "--friction", "0.2",
                 "--profile", "flat"]) == 2
    assert "history only" in capsys.readouterr().err
    out = tmp_path / "flat.nc"
    assert main(["history", "--geometry", "sphere", "--nu", "0.3", "--friction", "0.2",
                 "--load-path", "0,1", "--steps", "4", "--n", "60", "--profile", "flat",
                 "--output", str(out)]) == 0
    text = capsys.readouterr().out
    assert "profile = flat" in text and "delta0" in text and out.exists()


# ----------------------------------------------------------------------------- rounded punch
# Flat to b, a paraboloid beyond (R = 1): h = (|r| - b)^2/2. Truths: Sneddon's integrals of
# the frictionless load, approach and pressure (scipy.integrate.quad of their definitions),
# the paraboloid at b = 0, and, with friction, the power laws' c/a(k) at every load (the
# increment at contact radius a is the flat punch's problem on a).
def _rounded(geometry, k, n, steps, b, path=(0, 1)):
    return history(geometry, 0.3, k, list(path), steps, n=n, profile="rounded",
                   flat_ratio=b, error_estimate=False)


@pytest.mark.parametrize("b", [0.0, 0.5, 0.9])
def test_rounded_closed_forms_are_sneddons_integrals(b):
    from scipy import integrate

    shape = profile("rounded", flat_ratio=b)
    slope = lambda x: max(x - b, 0.0)  # noqa: E731  h'(x), R = 1
    # h' = 0 below b; 1/sqrt(1 - x^2) = (1 - x)^(-1/2) (1 + x)^(-1/2): on [b, 1] the
    # algebraic weight takes the first factor
    weight = lambda f: integrate.quad(f, b, 1.0, weight="alg", wvar=(0.0, -0.5),  # noqa
                                      limit=200)[0]
    load = 2.0 * weight(lambda x: x * x * slope(x) / math.sqrt(1.0 + x))
    approach = weight(lambda x: slope(x) / math.sqrt(1.0 + x))
    strip = weight(lambda x: x * slope(x) / math.sqrt(1.0 + x))  # (1/2) int_-1^1 |x| h'
    assert shape.frictionless_load(True) == pytest.approx(load, rel=1e-10)
    assert shape.frictionless_approach() == pytest.approx(approach, rel=1e-10)
    assert shape.frictionless_load(False) == pytest.approx(strip, rel=1e-10)


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_rounded_with_no_flat_is_the_paraboloid(geometry):
    par = history(geometry, 0.3, 0.2, [0, 1, 0], 10, n=60, error_estimate=False)
    r = _rounded(geometry, 0.2, 60, 10, 0.0, (0, 1, 0))
    assert np.allclose(r.pressure, par.pressure, rtol=0, atol=1e-12)
    assert r.frictional_work[-1] == pytest.approx(par.frictional_work[-1], rel=1e-12)


def test_rounded_frictionless_is_sneddons():
    """Sphere, b = 0.5: contact radius within 0.2 of an element, approach at second and
    pressure at first order (measured: 1.6e-6 and 1.1e-4 of the peak at n = 240)."""
    from scipy import integrate

    b = 0.5
    shape = profile("rounded", flat_ratio=b)

    def pressure(x):  # p(r) = (1/pi) int_max(r,b)^1 [2 sqrt(t^2 - b^2) - b acos(b/t)] / ...
        f = lambda t: (2 * math.sqrt(t * t - b * b) - b * math.acos(b / t)) / math.sqrt(  # noqa
            t * t - x * x)
        return integrate.quad(f, max(x, b), 1.0, limit=200)[0] / math.pi

    errors_d, errors_p = [], []
    for n in (120, 240):
        r = _rounded("sphere", 0.0, n, 4, b)
        total = shape.frictionless_load(True)
        a = np.array([shape.rounded_radius(lv * total, True) for lv in r.load_ratio[1:]])
        assert np.max(np.abs(r.contact_radius[1:] - a)) < 0.2 * 1.2 / n
        delta = a * (np.sqrt(a * a - b * b) - b * np.arccos(b / a))
        errors_d.append(float(np.max(np.abs(r.indentation[1:] - delta))))
        inner = r.xi < 0.9
        exact = np.array([pressure(x) for x in r.xi[inner]])
        p = r.pressure[-1][inner] * shape.reference_pressure(True)
        errors_p.append(float(np.max(np.abs(p - exact)) / exact.max()))
    assert errors_d[-1] < 3e-6 and 0.15 < errors_d[1] / errors_d[0] < 0.35
    assert errors_p[-1] < 2e-4
    _halving(errors_p)


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_rounded_stick_ratio_is_the_self_similar_one_at_every_load(geometry):
    exact = solve(geometry, 0.3, friction=0.2, n=512).stick_ratio
    n, steps = 480, 200
    r = _rounded(geometry, 0.2, n, steps, 0.6)
    for i in (steps // 4, steps // 2, steps):  # measured within 0.4 of an element
        assert abs(r.stick_ratio[i] - exact) < 1.2 / n


def test_rounded_interface():
    with pytest.raises(validate.InputError, match="history only"):
        solve("sphere", 0.3, friction=0.2, profile="rounded")
    with pytest.raises(validate.InputError, match="^flat_ratio"):
        history("sphere", 0.3, 0.2, [0, 1], 4, profile="rounded")
    with pytest.raises(validate.InputError, match="^flat_ratio"):
        history("sphere", 0.3, 0.2, [0, 1], 4, profile="cone", flat_ratio=0.5)
    with pytest.raises(validate.InputError, match=r"^flat_ratio .*\[0, 0\.9\]"):
        history("sphere", 0.3, 0.2, [0, 1], 4, profile="rounded", flat_ratio=0.95)
    with pytest.raises(validate.InputError, match="^flat_ratio"):
        fretting("cylinder", 0.3, 0.2, [0, 1, 1], [0, 0, 0.5], profile="rounded")
    scene = {"kind": "history", "geometry": "cylinder", "nu": 0.3, "friction": [0.2],
             "load_path": [0, 1, 0], "steps": 20, "n": 60, "profile": "rounded",
             "flat_ratio": 0.5}
    spec = parse_scene("s", scene).run_spec(0)
    assert spec["profile"] == "rounded" and spec["flat_ratio"] == 0.5
    with pytest.raises(ValueError, match=r"^scenes\.s\.flat_ratio"):
        parse_scene("s", dict(scene, profile="cone"))


def test_rounded_command_line(tmp_path, capsys):
    out = tmp_path / "rounded.nc"
    assert main(["history", "--geometry", "cylinder", "--nu", "0.3", "--friction", "0.2",
                 "--load-path", "0,1,0", "--steps", "8", "--n", "60", "--profile", "rounded",
                 "--flat-ratio", "0.5", "--output", str(out)]) == 0
    assert "profile = rounded (b/a_max = 0.5)" in capsys.readouterr().out
    import xarray as xr

    with xr.open_dataset(out) as ds:
        assert ds.attrs["profile"] == "rounded" and ds.attrs["profile_flat_ratio"] == 0.5
    assert main(["history", "--geometry", "sphere", "--nu", "0.3", "--friction", "0.2",
                 "--load-path", "0,1", "--steps", "4", "--profile", "rounded",
                 "--output", str(out)]) == 2
    assert "--flat-ratio" in capsys.readouterr().err


# Fretting (beta = 0): Cattaneo's superposition holds for any profile (Ciavarella): the stick
# zone under Q after P is the contact of the same punch under the load P (1 - Q/(k P)).
@pytest.mark.parametrize("b", [0.5, 0.8])
def test_rounded_fretting_stick_zone_is_ciavarellas(b):
    shape = profile("rounded", flat_ratio=b)
    exact = shape.rounded_radius(0.5 * shape.frictionless_load(False), False)
    n = 240
    r = fretting("cylinder", 0.5, 0.3, [0, 1, 1], [0, 0, 0.5], 8, n=n, profile="rounded",
                 flat_ratio=b)
    left, right = r.stick_edges[-1]
    assert abs(0.5 * (right - left) - exact) < 0.05 * 2.4 / n  # measured 0.03 element
    assert r.profile == "rounded" and r.flat_ratio == b
    from contactlib.io import fretting_to_dataset

    assert fretting_to_dataset(r).attrs["profile_flat_ratio"] == b


def test_rounded_fretting_sphere_within_its_estimate():
    """Equal bodies, nu = 0 (beta = gamma = 0: Cattaneo-Mindlin exact), b = 0.5."""
    shape = profile("rounded", flat_ratio=0.5)
    exact = shape.rounded_radius(0.5 * shape.frictionless_load(True), True)
    r = fretting("sphere", 0.0, 0.3, [0, 1, 1], [0, 0, 0.5], 4, n=64, profile="rounded",
                 flat_ratio=0.5, indenter_modulus=1.0, indenter_nu=0.0)
    assert r.converged.all() and 0 < r.stick_ratio_error[-1] < 0.05
    assert abs(r.stick_ratio[-1] - exact) <= r.stick_ratio_error[-1]
