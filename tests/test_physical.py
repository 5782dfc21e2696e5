"""Physical units in and out (issue 40): contactlib.physical, its CLI options and datasets.

Every truth here is a closed form in SI written out in the test (Hertz, E* of a pair),
or the dimensionless API converted by hand with the scalings of docs/conventions.md.
"""

from __future__ import annotations

import contextlib
import io as _io
import math
import warnings

import numpy as np
import pytest
import yaml

import contactlib
from contactlib import cli
from contactlib.model import materials
from contactlib.io import physical_to_dataset, read_dataset, write_dataset
from contactlib.physical import (SmallStrainWarning, composite_modulus, material,
                                 parse_quantity, physical_history, physical_solve)

STEEL = (207e9, 0.30)  # Callister Table 6.1, as in contactlib/data/materials.yaml
GLASS = (69e9, 0.23)


def e_star(e1: float, nu1: float, e2: float, nu2: float) -> float:
    """1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, by hand."""
    return 1.0 / ((1.0 - nu1 ** 2) / e1 + (1.0 - nu2 ** 2) / e2)


def run_cli(argv: list[str]) -> tuple[int, str, str]:
    out, err = _io.StringIO(), _io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = cli.main(argv)
    return code, out.getvalue(), err.getvalue()


# ----------------------------------------------------------------------------- units
@pytest.mark.parametrize("text, kind, si", [
    ("5mm", "length", 5e-3), ("5 mm", "length", 5e-3), ("2um", "length", 2e-6),
    ("0.005", "length", 5e-3), (0.005, "length", 5e-3), ("1e-3m", "length", 1e-3),
    ("100N", "force", 100.0), ("1.5kN", "force", 1500.0), ("210GPa", "modulus", 210e9),
    ("3MPa", "modulus", 3e6), ("1ms", "time", 1e-3), ("2min", "time", 120.0),
])
def test_parse_quantity(text, kind, si) -> None:
    assert parse_quantity(text, kind, "x") == pytest.approx(si, rel=1e-15)


# ----------------------------------------------------------------------------- E* of every pair
def test_composite_modulus_of_every_pair_against_its_formula() -> None:
    table = materials.materials()
    names = list(table)
    for n1 in names:
        for n2 in names:
            e1, nu1 = float(table[n1]["E"]) * 1e9, float(table[n1]["nu"])
            e2, nu2 = float(table[n2]["E"]) * 1e9, float(table[n2]["nu"])
            truth = e_star(e1, nu1, e2, nu2)
            got = composite_modulus(material(n1, "indenter"), material(n2, "body"))
            assert got == pytest.approx(truth, rel=1e-14), (n1, n2)
        rigid = composite_modulus(material("rigid", "indenter"), material(n1, "body"))
        e, nu = float(table[n1]["E"]) * 1e9, float(table[n1]["nu"])
        assert rigid == pytest.approx(e / (1.0 - nu ** 2), rel=1e-14)


def test_table_has_the_example_materials_with_sources() -> None:
    table = materials.materials()
    for name, (e, nu) in (("steel", STEEL), ("soda_lime_glass", GLASS)):
        assert float(table[name]["E"]) * 1e9 == e and float(table[name]["nu"]) == nu
        assert table[name]["source"]


# ----------------------------------------------------------------------------- Hertz in SI
def test_hertz_sphere_in_si() -> None:
    """Frictionless steel on glass: a = (3PR/4E*)^(1/3), p0 = 3P/(2 pi a^2), delta = a^2/R."""
    R, P = 5e-3, 100.0
    es = e_star(*STEEL, *GLASS)
    a = (3.0 * P * R / (4.0 * es)) ** (1.0 / 3.0)
    p0 = 3.0 * P / (2.0 * math.pi * a ** 2)
    delta = a ** 2 / R
    res = physical_solve("sphere", R, P, STEEL, GLASS, friction=0.0)
    assert res.contact_radius == pytest.approx(a, rel=1e-5)
    assert res.hertz_contact_radius == pytest.approx(a, rel=1e-14)
    assert res.stick_radius == 0.0
    assert res.peak_pressure == pytest.approx(p0, rel=2e-5)
    assert res.mean_pressure == pytest.approx(2.0 / 3.0 * p0, rel=1e-5)
    assert res.approach == pytest.approx(delta, rel=2e-5)
    assert res.frictional_energy == 0.0
    assert res.composite_modulus == pytest.approx(es, rel=1e-14)
    assert abs(res.contact_radius / a - 1.0) <= 3.0 * res.errors["contact_radius"] + 1e-12


def test_hertz_cylinder_in_si() -> None:
    """Per unit length P' = P/L: a = (4P'R/(pi E*))^(1/2), p0 = 2P'/(pi a); rigid indenter."""
    R, P, L = 10e-3, 2000.0, 20e-3
    e, nu = 69e9, 0.33  # aluminium
    es = e / (1.0 - nu ** 2)
    q = P / L
    a = math.sqrt(4.0 * q * R / (math.pi * es))
    p0 = 2.0 * q / (math.pi * a)
    res = physical_solve("cylinder", "10mm", "2kN", "rigid", "aluminium", friction=0.0,
                         length="20mm")
    assert res.contact_radius == pytest.approx(a, rel=1e-5)
    assert res.peak_pressure == pytest.approx(p0, rel=2e-5)
    assert res.mean_pressure == pytest.approx(q / (2.0 * a), rel=1e-5)
    assert math.isnan(res.approach)  # undefined on a half-plane
    assert res.hertz_load == pytest.approx(P, rel=1e-5)


def test_full_stick_raises_the_load_ratio_as_the_dimensionless_solver_says() -> None:
    R, P = 5e-3, 100.0
    res = physical_solve("sphere", R, P, "rigid", GLASS, friction=math.inf, n=64)
    dimless = contactlib.solve("sphere", GLASS[1], stick_ratio=1.0, n=64)
    es = GLASS[0] / (1.0 - GLASS[1] ** 2)
    a = (3.0 * P * R / (4.0 * es * dimless.load_ratio)) ** (1.0 / 3.0)
    assert res.load_ratio == dimless.load_ratio > 1.0
    assert res.contact_radius == pytest.approx(a, rel=1e-13)
    assert res.stick_radius == pytest.approx(a, rel=1e-13)


# ----------------------------------------------------------------------------- round trip
@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_round_trip_against_the_dimensionless_api(geometry) -> None:
    R, P, L = 5e-3, 100.0, 10e-3
    e1, nu1 = STEEL
    e2, nu2 = GLASS
    es = e_star(e1, nu1, e2, nu2)
    kw = {"length": L} if geometry == "cylinder" else {}
    res = physical_solve(geometry, R, P, "steel", "soda_lime_glass", friction=0.2, n=64, **kw)
    sol = contactlib.solve(geometry, nu2, friction=0.2, n=64, indenter_modulus=e1 / e2,
                           indenter_nu=nu1)
    lr = sol.load_ratio
    if geometry == "sphere":
        a = (3.0 * P * R / (4.0 * es * lr)) ** (1.0 / 3.0)
        p0 = 2.0 * es * a / (math.pi * R)
        work = sol.frictional_work * es * a ** 5 / R ** 2
        approach = sol.extra["indentation"] * a ** 2 / R
        mean = P / (math.pi * a ** 2)
    else:
        a = math.sqrt(4.0 * (P / L) * R / (math.pi * es * lr))
        p0 = es * a / (2.0 * R)
        work = sol.frictional_work * es * a ** 4 / R ** 2 * L
        approach = math.nan
        mean = P / (2.0 * a * L)
    tol = 1e-12
    assert res.contact_radius == pytest.approx(a, rel=tol)
    assert res.stick_radius == pytest.approx(sol.stick_ratio * a, rel=tol)
    assert res.p0 == pytest.approx(p0, rel=tol)
    assert res.peak_pressure == pytest.approx(float(np.max(sol.pressure)) * p0, rel=tol)
    assert res.mean_pressure == pytest.approx(mean, rel=tol)
    assert res.frictional_energy == pytest.approx(work, rel=tol)
    assert res.load_ratio == lr
    if geometry == "sphere":
        assert res.approach == pytest.approx(approach, rel=tol)
    else:
        assert math.isnan(res.approach)
    prof = res.profiles()
    assert np.allclose(prof["r"], sol.xi * a, rtol=tol, atol=0)
    assert np.allclose(prof["shear"], sol.shear * p0, rtol=tol, atol=0)
    assert np.allclose(prof["tangential_displacement"], sol.tangential_displacement * a ** 2 / R,
                       rtol=tol, atol=0)


def test_history_round_trip_and_cycle_energy() -> None:
    R, P = 5e-3, 100.0
    e1, nu1 = STEEL
    e2, nu2 = GLASS
    es = e_star(e1, nu1, e2, nu2)
    res = physical_history("sphere", "5mm", "0N,100N,0N", "steel", "soda_lime_glass", 0.2,
                           steps=20, n=60)
    dim = contactlib.history("sphere", nu2, 0.2, [0, 1, 0], 20, n=60, indenter_modulus=e1 / e2,
                             indenter_nu=nu1)
    a_max = (3.0 * P * R / (4.0 * es)) ** (1.0 / 3.0)
    w = es * a_max ** 5 / R ** 2
    assert res.a_max == pytest.approx(a_max, rel=1e-12)
    assert np.allclose(res.contact_radius, dim.contact_radius * a_max, rtol=1e-12, atol=0)
    assert np.allclose(res.frictional_energy, dim.frictional_work * w, rtol=1e-12, atol=0)
    assert np.allclose(res.force, dim.load_ratio * P, rtol=1e-12, atol=0)
    assert res.cycles == [(0, 2)]
    assert res.cycle_frictional_energy[0] == pytest.approx(dim.frictional_work[-1] * w,
                                                           rel=1e-12)
    assert res.p0 == pytest.approx(2.0 * es * a_max / (math.pi * R), rel=1e-12)


def test_layer_thickness_is_consistent_with_the_contact_radius() -> None:
    res = physical_solve("sphere", "5mm", "100N", "rigid", GLASS, friction=0.0, n=32,
                         thickness="0.5mm")
    assert res.slab_ratio == pytest.approx(res.contact_radius / 0.5e-3, rel=1e-10)
    assert res.contact_radius < res.hertz_contact_radius  # a layer on a rigid base is stiffer


# ----------------------------------------------------------------------------- validity
def test_small_strain_warning() -> None:
    with pytest.warns(SmallStrainWarning, match="a/R"):
        res = physical_solve("sphere", "1mm", "10N", "rigid", "natural_rubber", friction=0.0,
                             n=32)
    assert res.contact_radius / 1e-3 > 0.1 and "warning" in res.summary()
    with warnings.catch_warnings():
        warnings.simplefilter("error", SmallStrainWarning)
        physical_solve("sphere", "5mm", "100N", "steel", "soda_lime_glass", friction=0.0, n=32)


# ----------------------------------------------------------------------------- CLI
def test_the_two_commands_of_the_issue(tmp_path) -> None:
    ball, cycle = tmp_path / "ball.nc", tmp_path / "cycle.nc"
    code, out, err = run_cli(["solve", "--geometry", "sphere", "--radius", "5mm", "--load",
                              "100N", "--indenter", "steel", "--body", "soda_lime_glass",
                              "--friction", "0.2", "--output", str(ball)])
    assert code == 0, err
    assert "contact radius a" in out and "µm" in out
    ds = read_dataset(ball)
    units = {name: ds[name].attrs["units"] for name in ds.data_vars if name.endswith("_si")}
    assert units["contact_radius_si"] == "m" and units["peak_pressure_si"] == "Pa"
    assert units["normal_force_si"] == "N" and units["frictional_energy_si"] == "J"
    assert ds["pressure"].attrs["units"] == "1"  # the dimensionless ones stay
    assert float(ds["contact_radius_si"]) * 1e3 == pytest.approx(0.188, abs=5e-4)
    assert float(ds["stick_radius_si"]) * 1e3 == pytest.approx(0.169, abs=5e-4)
    assert float(ds["peak_pressure_si"]) / 1e6 == pytest.approx(1380, abs=5)
    es = e_star(*STEEL, *GLASS)
    assert ds.attrs["composite_modulus_Pa"] == pytest.approx(es, rel=1e-14)
    assert ds.attrs["indenter_radius_m"] == 5e-3
    a = float(ds["contact_radius_si"])
    assert ds.attrs["hertz_peak_pressure_Pa"] == pytest.approx(2 * es * a / (math.pi * 5e-3),
                                                               rel=1e-14)
    assert ds.attrs["hertz_load_N"] == pytest.approx(4 * es * a ** 3 / (3 * 5e-3), rel=1e-14)
    # the dimensionless variables convert back with the attributes
    assert float(ds["pressure"].max()) * ds.attrs["hertz_peak_pressure_Pa"] == pytest.approx(
        float(ds["peak_pressure_si"]), rel=1e-14)

    code, out, err = run_cli(["history", "--geometry", "sphere", "--radius", "5mm",
                              "--load-path", "0N,100N,0N", "--indenter", "steel", "--body",
                              "soda_lime_glass", "--friction", "0.2", "--output", str(cycle)])
    assert code == 0, err
    assert "cycle 1" in out
    ds = read_dataset(cycle)
    assert ds["frictional_energy_si"].attrs["units"] == "J"
    assert ds["normal_force_si"].attrs["units"] == "N"
    assert ds["pressure_si"].attrs["units"] == "Pa"
    assert ds["stick_radius_si"].attrs["units"] == "m"
    energy = float(ds["cycle_frictional_energy_si"][0])
    assert energy == pytest.approx(49e-9, rel=0.05)
    assert ds.attrs["contact_radius_scale_m"] == pytest.approx(
        (3 * 100 * 5e-3 / (4 * es)) ** (1 / 3), rel=1e-14)


def test_viscoelastic_history_in_seconds(tmp_path) -> None:
    """Relaxation times and path times in s: the dimensionless history with tau and the
    durations in the same unit, the energies converted by hand."""
    e0, nu = 3e9, 0.4
    es = e0 / (1 - nu ** 2)
    res = physical_history("sphere", "5mm", ["0N", "10N", "0N"], "rigid", ("3GPa", nu), 0.2,
                           times=["0s", "500ms", "1s"], relaxation=[(0.5, "200ms")], steps=10,
                           n=40)
    dim = contactlib.history("sphere", nu, 0.2, [0, 1, 0], 10, n=40, relaxation=[[0.5, 0.2]],
                             duration=[0.5, 0.5])
    a_max = (3.0 * 10.0 * 5e-3 / (4.0 * es)) ** (1.0 / 3.0)
    w = es * a_max ** 5 / 5e-3 ** 2
    assert np.allclose(res.viscous_energy, dim.viscous_work * w, rtol=1e-12, atol=0)
    assert np.allclose(res.time, dim.time, rtol=1e-12, atol=0)
    assert res.cycle_viscous_energy[0] == pytest.approx(dim.viscous_work[-1] * w, rel=1e-12)
    ds = physical_to_dataset(res)
    assert ds["time_si"].attrs["units"] == "s" and ds["viscous_energy_si"].attrs["units"] == "J"
    code, out, err = run_cli(HIST_VE + ["--steps", "10", "--n", "40", "--output",
                                        str(tmp_path / "v.nc")])
    assert code == 0, err
    assert "viscous" in out


def test_a_dimensionless_load_path_keeps_its_meaning(tmp_path) -> None:
    out = tmp_path / "h.nc"
    code, _, err = run_cli(["history", "--geometry", "sphere", "--nu", "0.3", "--friction",
                            "0.2", "--load-path", "0,1,0", "--steps", "4", "--n", "40",
                            "--output", str(out)])
    assert code == 0, err
    assert "normal_force_si" not in read_dataset(out)


def test_physical_dataset_writes_and_reads_back(tmp_path) -> None:
    res = physical_solve("cylinder", "10mm", "2kN", "rigid", "aluminium", friction=0.1,
                         length="20mm", n=32)
    ds = physical_to_dataset(res)
    back = read_dataset(write_dataset(ds, tmp_path / "c.nc"))
    assert back.attrs["cylinder_length_m"] == 0.02
    assert back["approach_si"].attrs["units"] == "m"
    assert "contactlib_sha256" not in back.attrs  # checked and removed by read_dataset


SOLVE = ["solve", "--geometry", "sphere", "--radius", "5mm", "--load", "100N", "--indenter",
         "steel", "--body", "soda_lime_glass", "--friction", "0.2"]
HIST = ["history", "--geometry", "sphere", "--radius", "5mm", "--load-path", "0N,100N,0N",
        "--indenter", "steel", "--body", "soda_lime_glass", "--friction", "0.2"]


def _with(argv: list[str], option: str, value: str | None) -> list[str]:
    """``argv`` with ``option`` set to ``value`` (None: removed)."""
    out = list(argv)
    if option in out:
        i = out.index(option)
        del out[i:i + 2]
    return out + ([option, value] if value is not None else [])


BAD = [
    (SOLVE, "--radius", "5 parsecs", "--radius"),
    (SOLVE, "--radius", "5mN", "--radius"),   # a unit of force
    (SOLVE, "--radius", "-5mm", "--radius"),
    (SOLVE, "--radius", "0mm", "--radius"),
    (SOLVE, "--radius", "nan", "--radius"),
    (SOLVE, "--radius", "inf", "--radius"),
    (SOLVE, "--radius", "1e400", "--radius"),
    (SOLVE, "--radius", "mm", "--radius"),
    (SOLVE, "--radius", "5 m m", "--radius"),
    (SOLVE, "--radius", None, "--radius"),
    (SOLVE, "--load", "100Pa", "--load"),
    (SOLVE, "--load", "-100N", "--load"),
    (SOLVE, "--load", "0N", "--load"),
    (SOLVE, "--load", "100Nm", "--load"),
    (SOLVE, "--load", "", "--load"),
    (SOLVE, "--load", None, "--load"),
    (SOLVE, "--indenter", "unobtainium", "--indenter"),
    (SOLVE, "--indenter", "Steel", "--indenter"),
    (SOLVE, "--indenter", "210GPa", "--indenter"),
    (SOLVE, "--indenter", "210GPa,0.7", "--indenter"),
    (SOLVE, "--indenter", "-210GPa,0.3", "--indenter"),
    (SOLVE, "--indenter", "210N,0.3", "--indenter"),
    (SOLVE, "--body", "rigid", "--body"),
    (SOLVE, "--body", "glass", "--body"),
    (SOLVE, "--body", "69GPa,nan", "--body"),
    (SOLVE, "--body", "69GPa,0.2,0.3", "--body"),
    (SOLVE, "--body", None, "--body"),
    (SOLVE, "--length", "10mm", "--length"),   # a sphere has no length
    (_with(SOLVE, "--geometry", "cylinder"), "--length", None, "--length"),
    (_with(SOLVE, "--geometry", "cylinder"), "--length", "-1mm", "--length"),
    (SOLVE, "--thickness", "0um", "--thickness"),
    (SOLVE, "--thickness", "1 furlong", "--thickness"),
    (SOLVE, "--friction", "-0.2", "--friction"),
    (SOLVE, "--nu", "0.3", "--nu"),             # --body gives nu
    (SOLVE, "--slab-ratio", "1", "--slab-ratio"),
    (SOLVE, "--indenter-modulus", "3", "--indenter-modulus"),
    (HIST, "--load-path", "0N,100N,-5N", "--load-path"),
    (HIST, "--load-path", "10N,100N,0N", "--load-path"),
    (HIST, "--load-path", "0N,100Pa,0N", "--load-path"),
    (HIST, "--load-path", "0N", "--load-path"),
    (HIST, "--load-path", "0N,0N", "--load-path"),
    (HIST, "--load-path", "0N,100,0N", "--load-path"),   # a bare number among forces
    (HIST, "--load-path", "0N,,0N", "--load-path"),
    (HIST, "--load-path", "0N,nanN,0N", "--load-path"),
    (HIST, "--load-path", "0,1,0", "--load-path"),       # levels with physical units
    (HIST, "--steps", "0", "--steps"),
    (HIST, "--body", "cheese", "--body"),
    (HIST, "--radius", "5kg", "--radius"),
    (HIST, "--times", "0s,1s,2s", "--relaxation"),      # times without relaxation
    (HIST, "--duration", "1", "--duration"),
]
HIST_VE = _with(_with(HIST, "--body", "3GPa,0.4"), "--indenter", None) + [
    "--relaxation", "0.5:200ms", "--times", "0s,0.5s,1s"]
BAD += [
    (HIST_VE, "--times", "0s,0.5,xs", "--times"),
    (HIST_VE, "--times", "0s,1s", "--times"),
    (HIST_VE, "--times", "0s,1s,1s", "--times"),
    (HIST_VE, "--relaxation", "0.5:-2s", "--relaxation"),
    (HIST_VE, "--relaxation", "1.5:2s", "--relaxation"),
    (HIST_VE, "--relaxation", "0.5:2N", "--relaxation"),
]


@pytest.mark.parametrize("argv, option, value, named", BAD,
                         ids=[f"{b[0][0]} {b[1]} {b[2]!r}" for b in BAD])
def test_bad_physical_input_is_one_line_and_exit_2(tmp_path, argv, option, value,
                                                   named) -> None:
    out_file = tmp_path / "o.nc"
    code, out, err = run_cli(_with(argv, option, value) + ["--output", str(out_file)])
    assert code == 2, (code, err)
    assert err.startswith("contactlib: error: ") and err.count("\n") == 1, err
    assert named in err, err
    assert "Traceback" not in err and out == ""
    assert not out_file.exists()


def test_at_least_thirty_bad_inputs() -> None:
    assert len(BAD) >= 30


def test_materials_yaml_is_the_package_table() -> None:
    doc = yaml.safe_load(materials.MATERIALS_FILE.read_text(encoding="utf-8"))
    assert set(doc["materials"]) == set(materials.materials())


def test_docs_page_gives_the_two_tested_commands() -> None:
    from pathlib import Path

    page = (Path(__file__).resolve().parents[1] / "docs" / "physical.md").read_text()
    for argv in (SOLVE + ["--output", "ball.nc"], HIST + ["--output", "cycle.nc"]):
        assert "contactlib " + " ".join(argv) in page
