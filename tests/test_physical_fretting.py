"""Fretting in SI (contactlib.physical_fretting): Hertz and Cattaneo in m, the cycle work in J
against the Mindlin–Deresiewicz closed form derived in SI, the round trip, bad input."""

from __future__ import annotations

import math

import numpy as np
import pytest

from contactlib import cli, fretting
from contactlib import io as cio
from contactlib.physical_fretting import physical_fretting

R, L, P, Q, K = 0.01, 0.02, 1000.0, 200.0, 0.5
E, NU = 207e9, 0.3  # the package's steel


def _run(**kw):
    return physical_fretting("10mm", "20mm", "0N,1000N,1000N,1000N,1000N",
                             "0N,0N,200N,-200N,200N", "steel", "steel", K, **kw)


def test_hertz_and_cattaneo_in_metres():
    r = _run()
    e_star = 1.0 / (2 * (1 - NU**2) / E)
    a = math.sqrt(4 * (P / L) * R / (math.pi * e_star))
    assert r.composite_modulus == pytest.approx(e_star, rel=1e-12)
    assert r.a_max == pytest.approx(a, rel=1e-12)
    assert r.p0 == pytest.approx(e_star * a / (2 * R), rel=1e-12)
    rows = r.points()
    assert rows[1]["contact half-width [m]"] == pytest.approx(a, rel=2e-4)
    c = a * math.sqrt(1 - Q / (K * P))
    assert abs(rows[2]["stick half-width [m]"] - c) <= 3 * rows[2]["stick half-width error [m]"]
    assert abs(rows[2]["stick half-width [m]"] - c) < 5e-4 * a  # measured 2.2e-4 a (n = 120)


def test_cycle_work_in_joules_is_mindlin_deresiewicz():
    """W = 2 k^2 (P/L) a^2 [x g(x) - 2 G(x)] L / R (the cylinder's closed form in SI:
    4 k^2 p0 P' a [...] / E* with p0 = E* a / (2R))."""
    r = _run()
    x = Q / (K * P)
    g = 0.5 * (1 - x) * math.log(1 - x)
    big_g = 0.5 * (0.25 * (1 - x) ** 2 - 0.5 * (1 - x) ** 2 * math.log(1 - x) - 0.25)
    exact = 2 * K**2 * (P / L) * r.a_max**2 * (x * g - 2 * big_g) / R * L
    (_, _, work, est), = r.cycles()
    assert abs(work - exact) <= est and abs(work / exact - 1) < 2e-3


def test_round_trip_through_the_dimensionless_api():
    r = _run()
    d = fretting("cylinder", NU, K, [0, 1, 1, 1, 1], [0, 0, 0.4, -0.4, 0.4], 40,
                 indenter_modulus=1.0, indenter_nu=NU)
    assert np.allclose(r.result.stick_ratio, d.stick_ratio, rtol=1e-12, atol=1e-15,
                       equal_nan=True)
    assert np.allclose(r.result.dissipation, d.dissipation, rtol=1e-12, atol=1e-18)


def test_bulk_stress_in_pascal_offsets_the_stick_zone():
    r = physical_fretting("10mm", "20mm", [0, 1000, 1000], [0, 0, 200], "steel", "steel", K,
                          bulk_stress=["0", "0", "50MPa"], steps=8)
    e = 50e6 / (4 * K * r.p0) * r.a_max  # Hills-Nowell, equal materials
    row = r.points()[-1]
    assert abs(row["stick offset [m]"] - e) <= 3 * row["stick offset error [m]"]
    assert abs(row["stick offset [m]"] - e) < 5e-3 * e  # measured 2.7e-3 (n = 120)


def test_command_line_writes_si_variables(tmp_path, capsys):
    out = tmp_path / "f.nc"
    rc = cli.main(["history", "--geometry", "cylinder", "--radius", "10mm", "--length", "20mm",
                   "--indenter", "steel", "--body", "steel", "--friction", "0.5",
                   "--load-path", "0N,1000N,1000N", "--tangential-path", "0N,0N,200N",
                   "--steps", "8", "--output", str(out)])
    assert rc == 0
    assert "µm" in capsys.readouterr().out
    ds = cio.read_dataset(out)
    assert ds["tangential_force"].attrs["units"] == "N"
    assert ds["frictional_work_si"].attrs["units"] == "J"
    assert ds["stick_edges_si"].attrs["units"] == "m"
    assert ds.attrs["a_max"] == pytest.approx(_run().a_max, rel=1e-12)


@pytest.mark.parametrize("extra,word", [
    (["--tangential-path", "0N,0N,600N"], "gross sliding"),
    (["--tangential-path", "0N,200N"], "--tangential-path"),
    (["--tangential-path", "0N,0N,20kg"], "unit"),
    (["--tangential-path", "0N,0N,200N", "--nu", "0.3"], "--nu"),
    (["--tangential-path", "0N,0N,200N", "--body", "unobtainium"], "unobtainium"),
])
def test_bad_physical_input_is_refused_with_one_line(tmp_path, capsys, extra, word):
    args = ["history", "--geometry", "cylinder", "--radius", "10mm", "--length", "20mm",
            "--friction", "0.5", "--load-path", "0N,1000N,1000N",
            "--output", str(tmp_path / "f.nc")]
    if "--body" not in extra:
        args += ["--body", "steel"]
    rc = cli.main(args + extra)
    err = capsys.readouterr().err
    assert rc == 2 and word in err and len(err.strip().splitlines()) == 1, err


def test_sphere_in_si_is_hertz_and_mindlin():
    """The sphere in SI: two equal steel-like bodies with nu = 0 (beta = gamma = 0), R = 10 mm,
    P = 100 N, Q = 0.5 k P. Hertz's a = (3PR/(4E*))^(1/3) and Mindlin's shift
    3kP(2 - nu)/(8 G a) [1 - (1 - x)^(2/3)] (two bodies) in metres, c/a within its estimate
    of (1 - x)^(1/3)."""
    e_mod, nu, radius, load, k, x = 200e9, 0.0, 0.01, 100.0, 0.3, 0.5
    r = physical_fretting(radius, None, [0, load, load], [0, 0, x * k * load], (e_mod, nu),
                          (e_mod, nu), k, geometry="sphere", n=32, steps=4)
    e_star = e_mod / (2 * (1 - nu**2))
    a = (3 * load * radius / (4 * e_star)) ** (1 / 3)
    assert r.a_max == pytest.approx(a, rel=1e-12)
    row = r.points()[2]
    assert row["contact radius [m]"] == pytest.approx(a, abs=2.4 * a / 32)  # a cell
    c = row["stick radius [m]"] / row["contact radius [m]"]
    assert abs(c - (1 - x) ** (1 / 3)) <= r.result.stick_ratio_error[2]
    g_mod = e_mod / (2 * (1 + nu))
    shift = 3 * k * load / (16 * a) * 2 * (2 - nu) / g_mod * (1 - (1 - x) ** (2 / 3))
    ours = r.result.shift[-1] * r.a_max**2 / r.radius
    assert ours == pytest.approx(shift, rel=1e-3)  # measured 1.6e-5 relative at n = 32
    assert r.work_unit == pytest.approx(e_star * a**5 / radius**2, rel=1e-12)
    assert "sphere R = 10 mm" in r.summary()
    ds = cio.physical_fretting_to_dataset(r)
    assert ds.attrs["geometry"] == "sphere" and "a_max**5" in ds.attrs["scales"]
    assert float(ds["frictional_work_si"][-1]) == pytest.approx(
        r.result.dissipation[-1] * e_star * a**5 / radius**2, rel=1e-12)


def test_command_line_sphere_in_newtons_is_the_python_door(tmp_path, capsys):
    """``history --geometry sphere`` with forces in N runs the sphere's fretting solver (it
    was refused as "cylinder only") and writes the dataset the Python door gives; the
    stick radius in metres is Cattaneo-Mindlin's a (1 - Q/kP)^(1/3) within its estimate
    (equal bodies, beta = 0)."""
    out = tmp_path / "s.nc"
    rc = cli.main(["history", "--geometry", "sphere", "--radius", "10mm",
                   "--indenter", "200GPa,0", "--body", "200GPa,0", "--friction", "0.3",
                   "--load-path", "0N,100N,100N", "--tangential-path", "0N,0N,15N",
                   "--n", "32", "--steps", "4", "--output", str(out)])
    assert rc == 0, capsys.readouterr().err
    assert "sphere R = 10 mm" in capsys.readouterr().out
    ds = cio.read_dataset(out)
    assert ds.attrs["geometry"] == "sphere" and ds["tangential_force"].attrs["units"] == "N"
    ref = physical_fretting(0.01, None, [0, 100, 100], [0, 0, 15], (200e9, 0.0),
                            (200e9, 0.0), 0.3, geometry="sphere", n=32, steps=4)
    assert float(ds["frictional_work_si"][-1]) == pytest.approx(
        ref.result.dissipation[-1] * ref.work_unit, rel=1e-9)
    row = ref.points()[-1]
    c = row["stick radius [m]"] / row["contact radius [m]"]
    assert abs(c - 0.5 ** (1 / 3)) <= ref.result.stick_ratio_error[-1]


def test_command_line_sphere_refuses_a_length(tmp_path, capsys):
    rc = cli.main(["history", "--geometry", "sphere", "--radius", "10mm", "--length", "5mm",
                   "--body", "steel", "--friction", "0.3", "--load-path", "0N,100N,100N",
                   "--tangential-path", "0N,0N,15N", "--output", str(tmp_path / "s.nc")])
    err = capsys.readouterr().err
    assert rc == 2 and "--length" in err and len(err.strip().splitlines()) == 1, err
