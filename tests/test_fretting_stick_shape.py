"""The sphere's stick zone per direction in the fretting summary (issue 37, outputs).

``contactlib history --geometry sphere --tangential-path`` ends its summary with the stick
radius's range over the directions and the stick zone's centre, each with its estimate, at
the path point of the largest |Q|/kP (:func:`contactlib.fretting_api.stick_shape`). Checked
against Cattaneo–Mindlin at beta = gamma = 0 (equal bodies, nu = 0: c = (1 - Q/kP)^(1/3)
a_max, a circle about the contact's centre), against the mirror identity at beta != 0 (Q
reversed: the zone mirrored about the y axis), and the physical door's metres against the
dimensionless numbers. n = 16 and 32, 4 steps: about 15 s.
"""

from __future__ import annotations

import re

import pytest

from contactlib import cli, fretting
from contactlib.fretting_api import StickShape, stick_shape

EQUAL = ["--nu", "0", "--indenter-modulus", "1", "--indenter-nu", "0"]  # beta = gamma = 0
NUMBER = r"([-+]?\d+(?:\.\d*)?)"
LINE = re.compile(
    r"stick zone at point (\d+) \(Q/\(kP_max\) = ([-\d.e+]+), the largest \|Q\|/kP\), from its "
    r"centroid: c/a_max \(estimate\) " + NUMBER + r" \(([\d.e+-]+)\) at (\d+) deg to "
    + NUMBER + r" \(([\d.e+-]+)\) at (\d+) deg, (.*)\n  its centre's offset from the "
    r"contact's along x, e/a_max \(estimate\) " + NUMBER + r" \(([\d.e+-]+)\); resolved to "
    r"max_error = ([\d.e+-]+): radii (yes|NO), centre (yes|NO)")


def _history(capsys, *args: str) -> str:
    code = cli.main(["history", "--geometry", "sphere", "--friction", "0.3", "--steps", "4",
                     *args])
    out = capsys.readouterr().out
    assert code == 0, out
    return out


def _parse(out: str) -> dict:
    m = LINE.search(out)
    assert m, out
    g = m.groups()
    return {"point": int(g[0]), "q": float(g[1]), "lo": float(g[2]), "lo_err": float(g[3]),
            "lo_deg": int(g[4]), "hi": float(g[5]), "hi_err": float(g[6]),
            "hi_deg": int(g[7]), "verdict": g[8], "e": float(g[9]), "e_err": float(g[10]),
            "max_error": float(g[11]), "radii": g[12], "centre": g[13]}


def test_beta_zero_range_collapses_to_mindlin_s_circle(capsys):
    """Equal bodies with nu = 0, Q/kP: 0 -> 0.5 -> -0.5 at P_max, n = 32: the summary names the
    last point of the largest |Q| (the cycled state), both ends of the range lie within their
    estimates of Mindlin's c/a = (1 - Q/kP)^(1/3) (a = a_max at P_max, Hertz), the spread
    within the two estimates ("a circle"), and the centre on the contact's. The per-direction
    estimates (at least half a cell, 3.75e-2 a_max) exceed the default max_error 1e-2: NO."""
    out = _history(capsys, *EQUAL, "--load-path", "0,1,1,1",
                   "--tangential-path", "0,0,0.5,-0.5", "--n", "32")
    s = _parse(out)
    assert s["point"] == 3 and s["q"] == -0.5
    mindlin = (1 - 0.5) ** (1 / 3)
    for end in ("lo", "hi"):
        # the printed value is rounded to the estimate's first uncertain digit: half a unit
        # of that digit more
        rounding = 0.5 * 10.0 ** -(len(str(s[end]).partition(".")[2]))
        assert abs(s[end] - mindlin) <= s[end + "_err"] + rounding, s
    assert s["hi"] - s["lo"] <= s["lo_err"] + s["hi_err"]
    assert s["verdict"] == "a circle within the estimates"
    assert abs(s["e"]) <= s["e_err"] + 1e-6
    assert s["max_error"] == 0.01 and s["radii"] == "NO"
    assert s["lo_err"] > 0.5 * 2.4 / 32 and s["hi_err"] > 0.5 * 2.4 / 32
    # and says why: max_error is below half a cell, a radius per direction's best
    assert f"known to half a cell at best, {1.2 / 32:.1e} a_max, above max_error" in out


def test_resolved_radii_are_said_so(capsys):
    """The same case at Q/kP = 0.5 asked to 0.2 a_max: the radii and the centre resolved."""
    s = _parse(_history(capsys, *EQUAL, "--load-path", "0,1,1", "--tangential-path", "0,0,0.5",
                        "--n", "32", "--max-error", "0.2"))
    assert s["point"] == 2 and max(s["lo_err"], s["hi_err"]) <= 0.2
    assert (s["radii"], s["centre"], s["max_error"]) == ("yes", "yes", 0.2)
    assert "half a cell" not in _history(capsys, *EQUAL, "--load-path", "0,1,1",
                                         "--tangential-path", "0,0,0.5", "--n", "32",
                                         "--max-error", "0.2")


def test_coupled_pair_mirrors_with_q(capsys):
    """A rigid sphere on nu = 0.3 (beta = 0.286), n = 16, Q/kP = +0.6 and -0.6: reversing Q
    mirrors the stick zone about the y axis (the problem's symmetry), so the range's values
    and estimates are the same, their directions go to 180 deg minus themselves, and the
    centre's offset changes sign. The zone moves against Q."""
    plus = _parse(_history(capsys, "--nu", "0.3", "--load-path", "0,1,1",
                           "--tangential-path", "0,0,0.6", "--n", "16"))
    minus = _parse(_history(capsys, "--nu", "0.3", "--load-path", "0,1,1",
                            "--tangential-path", "0,0,-0.6", "--n", "16"))
    for key in ("lo", "lo_err", "hi", "hi_err", "e_err"):
        assert plus[key] == minus[key], key
    assert minus["e"] == -plus["e"] and plus["e"] < 0 < minus["e"]
    for key in ("lo_deg", "hi_deg"):
        assert (plus[key] + minus[key]) % 360 == 180, (plus, minus)
    assert plus["radii"] == "NO"  # half a cell at n = 16 is 7.5e-2 a_max


def test_library_numbers_and_the_cylinder(capsys):
    """stick_shape's numbers are those of the result (the point of the largest |Q|/kP, its
    radii per direction and their estimates); the cylinder has none and no summary line."""
    r = fretting("sphere", 0.3, 0.3, [0, 1, 1, 1], [0, 0, 0.3, 0.6], 4, n=16)
    s = stick_shape(r)
    j = r.point_step[3]
    c = r.stick_radius_directions[j]
    assert (s.point, s.step) == (3, j)
    assert s.smallest == c.min() and s.largest == c.max()
    assert s.smallest_error == r.stick_radius_directions_error[3][c.argmin()]
    assert s.offset == r.stick_offset[j] and s.offset_error == r.stick_offset_error[3]
    assert stick_shape(r, point=2).point == 2 and stick_shape(r, point=2).reason == ""
    cyl = fretting("cylinder", 0.3, 0.3, [0, 1, 1], [0, 0, 0.5], 4, n=32)
    assert stick_shape(cyl) is None
    assert cli.main(["history", "--geometry", "cylinder", "--nu", "0.3", "--friction", "0.3",
                     "--load-path", "0,1,1", "--tangential-path", "0,0,0.5", "--n", "32",
                     "--steps", "4"]) == 0
    assert "stick zone at point" not in capsys.readouterr().out


def test_full_slip_and_no_data():
    """Gross sliding under a prescribed shift has no stick zone; a point behind a step that
    did not converge quotes no value."""
    r = fretting("sphere", 0.0, 0.3, [0, 1, 1], [0, 0, 5.0], 4, n=16, indenter_modulus=1.0,
                 indenter_nu=0.0, tangential_displacement=True)
    assert stick_shape(r).describe().endswith("full slip, no stick zone")
    shape = _shape(converged=False)
    assert shape.describe().endswith("no value is data") and not shape.radii_resolved


def _shape(**kw) -> StickShape:
    base = dict(point=2, step=8, force_ratio=0.5, load_ratio=1.0, contact_radius=1.0,
                smallest=0.79372, smallest_error=0.012, smallest_direction=180.0,
                largest=0.85, largest_error=0.0031, largest_direction=0.0, offset=-0.3127,
                offset_error=2.2e-3, max_error=0.01, converged=True)
    return StickShape(**{**base, **kw})


def test_digits_follow_the_estimate():
    """Each value to its estimate's first uncertain digit; resolved only within max_error;
    in metres under an engineering prefix, never in exponent form."""
    from contactlib.physical import format_si

    text = _shape().describe()
    assert "0.79 (1.2e-02) at 180 deg to 0.850 (3.1e-03) at 0 deg" in text
    assert "not a circle: the spread exceeds the estimates" in text
    assert "e/a_max (estimate) -0.313 (2.2e-03)" in text
    assert "radii NO, centre yes" in text
    si = _shape().describe(a_max=190e-6, si=format_si)
    assert "radius (estimate) 151 µm (2.3e-06 m) at 180 deg to 161.5 µm (5.9e-07 m)" in si
    assert "along x (estimate) -59.4 µm (4.2e-07 m)" in si
    assert _shape(largest=0.80).round
    unknown = _shape(smallest_error=0.001, largest_error=float("nan"), offset_error=float("nan"))
    assert not unknown.radii_resolved and not unknown.offset_resolved
    assert "no estimate" in unknown.describe() and "radii NO, centre NO" in unknown.describe()


def test_physical_door_prints_metres():
    """The physical summary's line is the dimensionless one in metres: the same point, the
    radii c/a_max times a_max (to the estimate's digits) and the same verdicts."""
    from contactlib import physical_fretting

    res = physical_fretting.physical_fretting(
        "10mm", None, "0N,100N,100N", "0N,0N,15N", "steel", "soda_lime_glass", 0.3,
        geometry="sphere", n=16, steps=4)
    text = res.summary()
    s = stick_shape(res.result)
    line = [x for x in text.splitlines() if x.startswith("stick zone at point")]
    assert len(line) == 1 and line[0].startswith(f"stick zone at point {s.point} ")
    m = re.search(r"radius \(estimate\) ([\d.]+) µm \(([\d.e+-]+) m\)", line[0])
    assert m, text
    assert abs(float(m.group(1)) * 1e-6 - s.smallest * res.a_max) <= 0.5e-6 + 1e-12
    assert float(m.group(2)) == pytest.approx(s.smallest_error * res.a_max, rel=0.05)
    assert ("radii NO" in text) == (not s.radii_resolved)
