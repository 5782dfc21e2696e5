"""The cone (and the wedge) in SI: ``physical_solve(..., profile="cone", half_angle=alpha)``.

Truths, independent of the solver: Love's frictionless cone (1939; Sneddon 1965),
P = (pi/2) E* a^2 cot(alpha), approach (pi/2) a cot(alpha), mean pressure (E*/2)
cot(alpha); the frictionless wedge per unit length P = E* a cot(alpha); and the
scalings of a profile z = A r^d (lengths normal to the surface ~ A d a^d, loads ~ E* A d
a^(d+1), work ~ E* (A d a^d)^2 a) applied to the dimensionless solve.
"""

from __future__ import annotations

import math
import warnings

import pytest

import contactlib
from contactlib import cli, io as cio, validate
from contactlib.physical import SmallStrainWarning, physical_solve

E_STAR = 1e11  # a rigid cone on E = 1e11 (1 - nu^2) Pa
ALPHA = 80.0
COT = 1.0 / math.tan(math.radians(ALPHA))


def _solve(geometry: str, friction: float, nu: float = 0.5, **kw):
    body = (E_STAR * (1.0 - nu ** 2), nu)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SmallStrainWarning)
        return physical_solve(geometry, None, "1N", "rigid", body, profile="cone",
                              half_angle=ALPHA, friction=friction, n=128, **kw)


def test_frictionless_cone_is_love():
    """nu = 0.5 (uncoupled, so the frictionless answer at any k): a, approach and mean
    pressure against Love's cone within the run's own estimates."""
    r = _solve("sphere", 0.3)
    a = math.sqrt(2.0 * 1.0 / (math.pi * E_STAR * COT))
    assert abs(r.contact_radius / a - 1.0) <= max(r.errors["contact_radius"], 1e-12)
    assert abs(r.approach / (0.5 * math.pi * a * COT) - 1.0) <= r.errors["approach"] + 1e-4
    assert r.mean_pressure == pytest.approx(0.5 * E_STAR * COT, rel=3 * r.errors["mean_pressure"])
    assert r.hertz_contact_radius == pytest.approx(a, rel=1e-12)
    assert math.isinf(r.peak_pressure)  # log-infinite at the tip


def test_frictionless_wedge_is_the_closed_form():
    """The wedge (plane strain), per unit length P/L = E* a cot(alpha)."""
    r = _solve("cylinder", 0.3, length="10mm")
    a = (1.0 / 0.01) / (E_STAR * COT)
    assert r.hertz_contact_radius == pytest.approx(a, rel=1e-12)
    assert abs(r.contact_radius / a - 1.0) <= max(r.errors["contact_radius"], 1e-12)
    assert math.isnan(r.approach)  # undefined on a half-plane


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_with_friction_the_scalings_carry_the_dimensionless_solve(geometry):
    """nu = 0.3, k = 0.3: c/a, P/P_frictionless and the work are the dimensionless solve's,
    a is the root of P = L(a) P_frictionless(a), the work is V E* (a cot alpha)^2 a."""
    kw = {"length": "10mm"} if geometry == "cylinder" else {}
    r = _solve(geometry, 0.3, nu=0.3, **kw)
    sol = contactlib.solve(geometry, 0.3, friction=0.3, n=128, profile="cone")
    assert r.solution.stick_ratio == sol.stick_ratio
    assert r.load_ratio == sol.load_ratio > 1.0  # friction stiffens the contact
    axi = geometry == "sphere"
    a0 = r.hertz_contact_radius
    assert r.contact_radius == pytest.approx(a0 * r.load_ratio ** (-0.5 if axi else -1.0),
                                             rel=1e-12)
    a = r.contact_radius
    per = 1.0 if axi else 0.01
    unit = E_STAR * (a * COT) ** 2 * (a if axi else 1.0) * per
    assert r.frictional_energy == pytest.approx(sol.frictional_work * unit, rel=1e-12)
    assert r.stick_radius == pytest.approx(sol.stick_ratio * a, rel=1e-12)


def test_bad_cone_input_names_the_argument():
    for kw, name in (({"half_angle": None}, "half_angle"), ({"half_angle": 90}, "half_angle"),
                     ({"half_angle": "abc"}, "half_angle")):
        with pytest.raises(validate.InputError, match=name):
            physical_solve("sphere", None, "1N", "rigid", "steel", profile="cone",
                           friction=0.3, **kw)
    with pytest.raises(validate.InputError, match="radius"):
        physical_solve("sphere", "1mm", "1N", "rigid", "steel", profile="cone",
                       half_angle=70, friction=0.3)
    with pytest.raises(validate.InputError, match="half_angle"):
        physical_solve("sphere", "1mm", "1N", "rigid", "steel", half_angle=70, friction=0.3)
    with pytest.raises(validate.InputError, match="profile"):
        physical_solve("sphere", "1mm", "1N", "rigid", "steel", profile="flat", friction=0.3)


def test_command_line_cone_in_si(tmp_path, capsys):
    out = tmp_path / "cone.nc"
    rc = cli.main(["solve", "--geometry", "sphere", "--profile", "cone", "--half-angle",
                   "70.3", "--load", "10mN", "--body", "fused_silica", "--friction", "0.3",
                   "--n", "64", "--output", str(out)])
    text = capsys.readouterr()
    assert rc == 0, text.err
    assert "cone, half-angle 70.3 deg" in text.out and "infinite at the tip" in text.out
    assert "small-strain" in text.err  # cot(70.3 deg) = 0.36 > 0.1: warned, not refused
    ds = cio.read_dataset(out)
    assert ds.attrs["profile"] == "cone" and ds.attrs["indenter_half_angle_deg"] == 70.3
    assert "indenter_radius_m" not in ds.attrs


@pytest.mark.parametrize("extra, word", [
    (["--radius", "1mm"], "--radius"), (["--half-angle", "0"], "--half-angle"),
    ([], "--half-angle")])
def test_command_line_bad_cone_input_is_one_line(capsys, extra, word):
    rc = cli.main(["solve", "--geometry", "sphere", "--profile", "cone", "--load", "10mN",
                   "--body", "fused_silica", "--friction", "0.3"] + extra)
    err = capsys.readouterr().err
    assert rc == 2 and word in err and len(err.strip().splitlines()) == 1, err


def test_cone_history_in_si_balances_the_force_and_carries_the_scalings():
    """physical_history of a cone, 0 -> 1 N -> 0: a_max is Love's frictionless radius at
    1 N; at every loaded step the pressure integrates to the force (equilibrium, in N); the
    energies are the dimensionless history's times E* (a_max cot alpha)^2 a_max; the peak
    pressure is infinite where there is contact."""
    import numpy as np
    from contactlib.physical import physical_history

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SmallStrainWarning)
        r = physical_history("sphere", None, "0N,1N,0N", "rigid", (E_STAR * 0.91, 0.3), 0.3,
                             profile="cone", half_angle=ALPHA, steps=20, n=60)
    a_max = math.sqrt(2.0 * 1.0 / (math.pi * E_STAR * COT))
    assert r.a_max == pytest.approx(a_max, rel=1e-12)
    res = r.result
    xb = np.asarray(res.xi_bounds) * r.a_max
    area = math.pi * (xb[:, 1] ** 2 - xb[:, 0] ** 2)
    for j in np.flatnonzero(r.force > 0):
        assert np.sum(r.profiles(j)["pressure"] * area) == pytest.approx(r.force[j], rel=1e-9)
    unit = E_STAR * (a_max * COT) ** 2 * a_max
    assert r.frictional_energy[-1] == pytest.approx(res.frictional_work[-1] * unit, rel=1e-12)
    assert np.all(np.isinf(r.peak_pressure[r.contact_radius > 0]))
    assert "cone, half-angle 80 deg" in r.summary()


def test_command_line_cone_history_and_refusals(tmp_path, capsys):
    out = tmp_path / "ch.nc"
    args = ["history", "--geometry", "sphere", "--profile", "cone", "--half-angle", "80",
            "--load-path", "0N,1N,0N", "--body", "91GPa,0.3", "--friction", "0.3"]
    assert cli.main(args + ["--n", "40", "--steps", "10", "--output", str(out)]) == 0
    ds = cio.read_dataset(out)
    assert ds.attrs["profile"] == "cone" and ds.attrs["indenter_half_angle_deg"] == 80.0
    capsys.readouterr()
    rc = cli.main(args + ["--tangential-path", "0N,0N,0.1N"])
    err = capsys.readouterr().err
    assert rc == 2 and "--profile" in err and len(err.strip().splitlines()) == 1, err
