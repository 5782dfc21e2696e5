"""Power-law profiles h ~ r^d (cone, paraboloid, power): closed forms and partial slip.

Independent truths: the frictionless closed forms of Love (cone), Galin/Segedin (load and
approach of any power law) and their plane-strain counterparts, checked against quadrature
of the closed-form pressures and against the solver; the claim that the self-similar
k(c/a) does not depend on d (the rate problem sees the profile only through dw/da = const
in the contact), checked between different exponents (different gaps, adherence
conditions and pressure singularities: independent discrete systems) and against the
uncoupled closed form near nu = 1/2.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate

from contactlib import api, validate
from contactlib.solvers.default_method import solve_default
from contactlib.model import contact
from contactlib.model.profiles import PARABOLOID, profile
from contactlib.model.theory import uncoupled_friction


@pytest.mark.parametrize("axisymmetric", [True, False])
@pytest.mark.parametrize("name", ["paraboloid", "cone"])
def test_closed_form_load_is_the_integral_of_the_closed_form_pressure(name, axisymmetric):
    prof = profile(name)
    dens = (lambda x: 2.0 * math.pi * x) if axisymmetric else (lambda x: 2.0)
    load = integrate.quad(lambda x: prof.frictionless_pressure(x, axisymmetric) * dens(x),
                          0.0, 1.0, limit=200)[0]
    assert abs(load / prof.frictionless_load(axisymmetric) - 1.0) < 1e-10


def test_closed_forms_of_the_named_profiles():
    # Hertz (a = R = E* = 1): P = 4/3, pi/4, delta = 1; Love's cone: P = pi/2, delta = pi/2
    assert PARABOLOID.frictionless_load(True) == pytest.approx(4.0 / 3.0, rel=1e-15)
    assert PARABOLOID.frictionless_load(False) == pytest.approx(math.pi / 4.0, rel=1e-15)
    assert PARABOLOID.frictionless_approach() == pytest.approx(1.0, rel=1e-15)
    cone = profile("cone")
    assert cone.frictionless_load(True) == pytest.approx(math.pi / 2.0, rel=1e-15)
    assert cone.frictionless_load(False) == pytest.approx(1.0, rel=1e-15)
    assert cone.frictionless_approach() == pytest.approx(math.pi / 2.0, rel=1e-15)
    assert PARABOLOID.reference_pressure(True) == pytest.approx(2.0 / math.pi, rel=1e-15)


@pytest.mark.parametrize("d", [0.5, 1.0, 1.5, 3.0, 8.0])
def test_differences_do_not_cancel(d):
    prof = profile("power", d) if d != 1.0 else profile("cone")
    r = np.array([0.3, 0.9, 0.999999])
    rh = r + 1e-9
    h = rh - r  # the step the floating-point points really have
    exact = r ** (d - 1.0) * h * (1.0 + 0.5 * (d - 1.0) * h / r)  # to O(h^3)
    assert np.allclose(prof.gap_difference(rh, r), exact, rtol=1e-12, atol=0)
    assert np.allclose(prof.adherence_difference(rh, r), d * exact, rtol=1e-12, atol=0)


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
@pytest.mark.parametrize("d", [1.0, 1.5, 3.0])
def test_frictionless_load_converges_to_the_profiles_own(geometry, d):
    """load_ratio -> 1 at second order in n (Galin's load as the unit)."""
    prof = profile("power", d) if d != 1.0 else profile("cone")
    model = contact(geometry, 0.3, profile=prof)
    err = [abs(solve_default(model, 0.0, n).load() / model.hertz_load - 1.0)
           for n in (128, 256)]
    assert err[1] < 2e-5
    assert 3.0 < err[0] / err[1] < 5.0  # second order


def test_cone_approach_is_loves():
    model = contact("sphere", 0.3, profile=profile("cone"))
    sols = [solve_default(model, 0.0, n) for n in (128, 256)]
    errs = [abs(s.delta / (math.pi / 2.0) - 1.0) for s in sols]
    assert errs[1] < 1e-4 and errs[1] < errs[0]


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_cone_pressure_is_loves_arccosh(geometry):
    """p = (E*/2) cot(alpha) arccosh(a/r) (wedge: (E*/pi) ...), away from the log axis."""
    sol = api.solve(geometry, 0.3, stick_ratio=0.0, profile="cone")
    prof = profile("cone")
    ax = geometry == "sphere"
    x = sol.xi[(sol.xi >= 0.2) & (sol.xi <= 0.95)]
    exact = prof.frictionless_pressure(x, ax) / prof.reference_pressure(ax)
    got = np.interp(x, sol.xi, sol.pressure)
    assert np.max(np.abs(got - exact)) < 2e-4 * np.max(exact)
    assert sol.load_ratio == pytest.approx(1.0, abs=2e-5)


def test_paraboloid_profile_is_todays_bits():
    a = api.solve("sphere", 0.3, stick_ratio=0.5, n=64)
    b = api.solve("sphere", 0.3, stick_ratio=0.5, n=64, profile="power", exponent=2.0)
    assert a.friction_coefficient == b.friction_coefficient and a.load_ratio == b.load_ratio
    assert np.array_equal(a.pressure, b.pressure) and b.profile == "paraboloid"


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
@pytest.mark.parametrize("c", [0.2, 0.5, 0.8])
def test_stick_ratio_of_a_friction_does_not_depend_on_the_exponent(geometry, c):
    """k(c/a) of the cone and of d = 3 equals the paraboloid's within the estimates."""
    ref = api.solve(geometry, 0.3, stick_ratio=c, energy=False)
    assert ref.resolved
    for kw in ({"profile": "cone"}, {"profile": "power", "exponent": 3.0}):
        sol = api.solve(geometry, 0.3, stick_ratio=c, **kw)
        assert sol.resolved and sol.consistent
        diff = abs(sol.friction_coefficient / ref.friction_coefficient - 1.0)
        assert diff <= 2.0 * (sol.error_estimate + ref.error_estimate)


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_cone_matches_the_uncoupled_closed_form_near_incompressibility(geometry):
    """nu = 0.499 (beta ~ 1e-3): k/k_uncoupled = 1 + O(beta), as for the paraboloid."""
    for c in (0.25, 0.5):
        sol = api.solve(geometry, 0.499, stick_ratio=c, n=128, profile="cone")
        ratio = sol.friction_coefficient / uncoupled_friction(geometry, 0.499, c)
        assert abs(ratio - 1.0) < 2e-3


def test_friction_inverse_on_a_cone():
    k = api.solve("cylinder", 0.3, stick_ratio=0.5, n=128, profile="cone")
    back = api.solve("cylinder", 0.3, friction=k.friction_coefficient, n=128, profile="cone")
    assert back.resolved and abs(back.stick_ratio - 0.5) < 1e-8


def test_work_scaling_is_continuous_through_the_paraboloid():
    """d = 2 -+ 0.001 through the generic r^d/d path against Hertz's own constants
    (2 pi/5): the work moves linearly in d, with no jump at d = 2."""
    w2 = api.solve("sphere", 0.3, stick_ratio=0.5, n=128).frictional_work
    lo, hi = (api.solve("sphere", 0.3, stick_ratio=0.5, n=128, profile="power",
                        exponent=d).frictional_work for d in (1.999, 2.001))
    assert abs(hi - lo) > 1e-5 * w2  # d matters ...
    assert abs(lo + hi - 2.0 * w2) < 1e-3 * abs(hi - lo)  # ... smoothly, no jump at d = 2


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_cone_work_converges_and_its_estimate_covers_the_error(geometry):
    w = [api.solve(geometry, 0.3, stick_ratio=0.5, n=n, profile="cone")
         for n in (128, 256, 512)]
    v = [s.frictional_work for s in w]
    limit = v[2] + (v[2] - v[1]) / 3.0  # Richardson, second order (ratio measured 3.7)
    assert 3.0 < (v[1] - v[0]) / (v[2] - v[1]) < 5.0
    err = abs(v[1] / limit - 1.0)
    assert err <= w[1].work_error_estimate <= 3.0 * err


@pytest.mark.parametrize("kw, name", [
    ({"profile": "flat"}, "profile"),
    ({"profile": "cone", "exponent": 1.0}, "exponent"),
    ({"profile": "power"}, "exponent"),
    ({"profile": "power", "exponent": 0.1}, "exponent"),
    ({"profile": "power", "exponent": float("nan")}, "exponent"),
    ({"profile": "cone", "method": "extrapolated"}, "method"),
    ({"profile": "cone", "method": "paper", "n": 16}, "method"),
    ({"profile": "cone", "tolerance": 1e-4}, "tolerance"),
])
def test_bad_profiles_are_refused_by_name(kw, name):
    with pytest.raises(validate.InputError) as err:
        api.solve("sphere", 0.3, stick_ratio=0.5, **kw)
    assert err.value.name == name


def test_command_line_profile_and_its_dataset(tmp_path):
    import subprocess
    import sys

    import xarray as xr

    out = tmp_path / "cone.nc"
    cmd = [sys.executable, "-m", "contactlib", "sweep", "--geometry", "cylinder", "--nu", "0.3",
           "--stick-ratios", "0.5", "--n", "64", "--profile", "cone", "--output", str(out)]
    r = subprocess.run(cmd, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert "profile = cone (d = 1)" in r.stdout
    with xr.open_dataset(out) as ds:
        assert ds.attrs["profile"] == "cone" and ds.attrs["profile_exponent"] == 1.0
        k = float(ds["friction_coefficient"][0])
    assert k == api.solve("cylinder", 0.3, stick_ratio=0.5, n=64, profile="cone",
                          energy=False).friction_coefficient


@pytest.mark.parametrize("extra, option", [
    (["--profile", "flat"], "--profile"),
    (["--profile", "power"], "--exponent"),
    (["--profile", "power", "--exponent", "x"], "--exponent"),
    (["--profile", "cone", "--exponent", "2"], "--exponent"),
    (["--profile", "cone", "--method", "paper", "--n", "16"], "--method"),
])
def test_command_line_refuses_bad_profiles_in_one_line(extra, option):
    import subprocess
    import sys

    cmd = [sys.executable, "-m", "contactlib", "solve", "--geometry", "sphere", "--nu", "0.3",
           "--stick-ratio", "0.5", *extra]
    r = subprocess.run(cmd, capture_output=True, text=True)
    assert r.returncode == 2
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and option in lines[0]


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
@pytest.mark.parametrize("kw", [{"profile": "cone"}, {"profile": "power", "exponent": 3.0}])
def test_history_on_a_profile_reaches_the_self_similar_stick_ratio(geometry, kw):
    """Two independent methods on the same profile: the incremental history solver
    (constant elements, no self-similarity assumed) loaded monotonically to P_max, and
    the self-similar inverse k -> c/a; within two of the history's elements (1.2/n)."""
    from contactlib import history

    c_self = api.solve(geometry, 0.3, friction=0.2, **kw).stick_ratio
    res = history(geometry, 0.3, 0.2, [0, 1], 100, n=240, error_estimate=False, **kw)
    assert res.converged.all() and res.profile == kw["profile"]
    assert abs(res.stick_ratio[-1] - c_self) < 2 * 1.2 / 240


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_frictionless_history_on_a_cone_reaches_a_max(geometry):
    """k = 0: the contact radius at P_max is the profile's own frictionless a_max (1)."""
    from contactlib import history

    res = history(geometry, 0.3, 0.0, [0, 0.5, 1], 4, n=240, error_estimate=False,
                  profile="cone")
    assert abs(res.contact_radius[-1] - 1.0) < 1.2 / 240
    # P ~ a^(d+1) (rings) or a^d (strips): at half the load a = 0.5^(1/2) or 0.5
    mid = 0.5 ** (0.5 if geometry == "sphere" else 1.0)
    assert abs(res.contact_radius[4] - mid) < 1.2 / 240


@pytest.mark.slow  # two history runs at n = 480 (about 10 s)
@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_cone_work_of_history_converges_to_the_self_similar_work(geometry):
    """The frictional work of a monotonic loading, two independent ways: the history's
    time integral of the element dissipation, and the self-similar V at a = 1 scaled by
    (a_top/a_max)^(2d+1) (rings) or ^(2d) (strips), a_top the history's contact radius at
    P_max (below a_max with friction). Their ratio tends to 1 as the history refines:
    this checks the profile's work factor 2 pi/(2d + 1), 1/d and its units."""
    from contactlib import history

    ref = api.solve(geometry, 0.3, friction=0.2, profile="cone")
    power = 3.0 if geometry == "sphere" else 2.0
    gaps = []
    for n, steps in ((240, 100), (480, 200)):
        res = history(geometry, 0.3, 0.2, [0, 1], steps, n=n, error_estimate=False,
                      profile="cone")
        scaled = ref.frictional_work * res.contact_radius[-1] ** power
        gaps.append(abs(res.frictional_work[-1] / scaled - 1.0))
    assert gaps[1] < 0.6 * gaps[0]  # converges (measured 0.35 and 0.35 of the gap)
    assert gaps[1] < 0.015  # 1.1e-2 (sphere), 1.7e-3 (cylinder) at n = 480
