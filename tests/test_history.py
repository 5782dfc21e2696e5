"""Incremental stick-slip along a load path (contactlib.history, module contactlib.history_api).

Every check is against an independent truth: Hertz theory, the self-similar
default method (``contactlib.solve``, a different discretization and
formulation), Spence's published point, the energy balance of a closed cycle
(the area of the load-indentation loop), or the contact conditions themselves.
"""

from __future__ import annotations

import math
import os

import numpy as np
import pytest

from conftest import trapezoid_work
from contactlib import cli, io, solve
from contactlib.solvers import history_solver as hs
from contactlib.energy import monotone_work
from contactlib.model.geometry import Geometry
from contactlib.history_api import DEFAULT_N, HistoryResult, history, load_levels
from contactlib.io import history_to_dataset

P_MAX = {"sphere": 4.0 / 3.0, "cylinder": math.pi / 4.0}  # E* = R = a_max = 1
P0 = {"sphere": 2.0 / math.pi, "cylinder": 0.5}


def hertz_radius(geometry: str, level: float) -> float:
    return level ** (1 / 3) if geometry == "sphere" else math.sqrt(level)


def element_area(res: HistoryResult) -> np.ndarray:
    lo, hi = res.xi_bounds[:, 0], res.xi_bounds[:, 1]
    return np.pi * (hi**2 - lo**2) if res.geometry == "sphere" else 2.0 * (hi - lo)


def loop_area(res: HistoryResult) -> float:
    """Closed-cycle integral of P d(delta): the energy the contact dissipates."""
    load = res.load_ratio * P_MAX[res.geometry]
    return float(np.sum(0.5 * (load[1:] + load[:-1]) * np.diff(res.indentation)))


# ----------------------------------------------------------------------------- Hertz
@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
@pytest.mark.parametrize("nu,k", [(0.3, 0.0), (0.5, 0.3)], ids=["frictionless", "nu=0.5"])
def test_frictionless_and_uncoupled_loading_is_hertz(geometry, nu, k):
    """k = 0, or nu = 0.5 (no coupling), gives Hertz a(P) and p(r) at every step."""
    res = history(geometry, nu, k, [0, 1], 4, n=120)
    for i in range(1, 5):
        a_h = hertz_radius(geometry, res.load_ratio[i])
        assert abs(res.contact_radius[i] / a_h - 1) < 2e-3
        inner = res.xi < 0.9 * a_h
        exact = a_h * np.sqrt(1 - (res.xi[inner] / a_h) ** 2)  # p/p0(a_max)
        assert np.max(np.abs(res.pressure[i][inner] - exact)) < 3e-4
    assert np.max(np.abs(res.shear)) < 1e-12
    assert np.all(res.frictional_work == 0.0)
    if nu == 0.5:  # nothing tends to slip: the whole contact sticks
        assert np.all(res.stick_ratio[1:] == 1.0) and "decouple" in res.message


# ----------------------------------------------------------------------------- self-similar
@pytest.mark.parametrize("geometry,k", [("sphere", 0.10), ("sphere", 0.15), ("sphere", 0.30),
                                        ("cylinder", 0.20)])
def test_monotonic_loading_reproduces_self_similar_stick_ratio(geometry, k):
    """c/a(k) of incremental loading = the self-similar solver's, within 0.5 %.

    (k = 0.10, 0.15, 0.30 give c/a = 0.20, 0.49, 0.90 for the sphere at nu = 0.3;
    measured deviation at n = 120, 50 steps: -0.24 %, -0.03 %, +0.13 %.)
    """
    ref = solve(geometry, 0.3, friction=k, n=64, energy=False).stick_ratio
    res = history(geometry, 0.3, k, [0, 1], 50, n=120)
    assert res.converged.all()
    assert abs(res.stick_ratio[-1] / ref - 1) < 5e-3
    # self-similar all along the path once the contact spans enough elements
    assert np.max(np.abs(res.stick_ratio[25:] / ref - 1)) < 1e-2


def test_spence_point():
    """Spence (1975): nu = 0, k = 0.2986 gives c/a = 0.5."""
    res = history("sphere", 0.0, 0.2986, [0, 1], 50, n=240)
    assert abs(res.stick_ratio[-1] / 0.5 - 1) < 5e-3


def test_one_step_load_gives_smaller_stick_zone():
    one = history("sphere", 0.3, 0.15, [0, 1], 1, n=120)
    inc = history("sphere", 0.3, 0.15, [0, 1], 50, n=120)
    assert one.converged.all()
    assert one.stick_ratio[-1] < inc.stick_ratio[-1] - 0.1


# ----------------------------------------------------------------------------- energy
@pytest.mark.parametrize("geometry,slab_ratio", [("sphere", 0.0), ("cylinder", 0.0),
                                                 ("cylinder", 0.05)])
def test_cycle_work_equals_hysteresis_loop_area(geometry, slab_ratio):
    """Over a closed cycle the frictional work is the area of the P-delta loop.

    The two are computed independently (sum of |q| |du| over the slip
    elements vs the indenter's external work); both converge like 1/steps.
    """
    gaps = []
    for steps in (25, 100):
        res = history(geometry, 0.3, 0.15, [0, 1, 0], steps, n=60, slab_ratio=slab_ratio)
        gaps.append(abs(loop_area(res) / res.frictional_work[-1] - 1))
    assert gaps[1] < 5e-3 and gaps[1] < 0.3 * gaps[0]


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_elastic_energy_balance_holds_at_every_step(geometry):
    """External work = stored energy + shear work on the surface, step by step (elastic body).

    The external work is the pressure's work on the surface and the stored
    energy <sigma, d>/2, both computed apart from the frictional work; the
    balance fails by about 1 % of a cycle's work when the elements that
    separate while slipping are left out of the frictional work. The
    reported frictional work is the lower monotone envelope of that shear
    work (no step dissipates a negative amount): it keeps the total and
    differs only before a fall of the trapezoid sums, by a time
    discretisation error that vanishes as the steps are refined.
    """
    lowered = []
    for steps in (50, 200):
        res = history(geometry, 0.3, 0.2, [0, 1, 0.5, 1, 0], steps, n=120,
                      error_estimate=False)
        plain = trapezoid_work(res)
        rest = res.external_work - res.stored_energy - plain
        assert np.all(np.abs(rest[1:]) <= 1e-3 * res.external_work[1:])
        np.testing.assert_allclose(res.frictional_work, monotone_work(plain), rtol=1e-12,
                                   atol=1e-15)
        assert res.frictional_work[-1] == pytest.approx(plain[-1], rel=1e-12)
        lowered.append(np.max(plain - res.frictional_work) / plain[-1])
    assert lowered[1] <= lowered[0] / 2  # first order or better (the cylinder: no fall)


@pytest.mark.parametrize("path", [(0, 1, 0), (0, 1, 0.5, 1, 0.5)])
@pytest.mark.parametrize("k", [0.2, 0.3])
@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_cumulative_work_never_falls(geometry, k, path):
    """Every step's dissipation is >= 0, also at the end of an unloading.

    The plain trapezoid sums fell in the last unloading steps (5e-7 of
    9.06e-4 for the sphere, k = 0.2, n = 240, 200 steps), where separating
    elements spring back and shears reverse within a step.
    """
    res = history(geometry, 0.3, k, path, 30, n=60, error_estimate=False)
    assert res.converged.all()
    assert np.all(np.diff(res.frictional_work) >= 0.0)
    assert res.frictional_work[-1] > 0.0


def test_monotone_work_is_the_lower_monotone_envelope():
    """Identities: non-decreasing, never above its input, equal to a non-decreasing input,
    the last value kept, each value one of the later inputs; a NaN stays where it is."""
    rng = np.random.default_rng(7)
    w = np.cumsum(rng.normal(0.5, 1.0, 200))
    env = monotone_work(w)
    assert np.all(np.diff(env) >= 0) and np.all(env <= w) and env[-1] == w[-1]
    assert all(env[i] in w[i:] for i in range(w.size))
    inc = np.cumsum(rng.random(50))
    np.testing.assert_array_equal(monotone_work(inc), inc)
    nan = w.copy()
    nan[100] = np.nan
    out = monotone_work(nan)
    assert np.isnan(out[100]) and np.isfinite(np.delete(out, 100)).all()


def test_cycle_work_converges_in_the_step_count():
    """A load-unload cycle's work at 100 steps a segment is within 3e-3 of 800 steps.

    (0.9 % off when the slipping elements that separate in a step were left out.)
    """
    coarse, fine = (history("sphere", 0.3, 0.2, [0, 1, 0], steps, n=120,
                            error_estimate=False).frictional_work[-1] for steps in (100, 800))
    assert abs(coarse / fine - 1) < 3e-3


def test_conditions_equilibrium_and_unloading_along_a_cycle():
    geometry, k = "sphere", 0.2
    res = history(geometry, 0.3, k, [0, 1, 0.4, 1, 0], 15, n=80)
    assert res.converged.all() and np.all(res.iterations[res.load_ratio > 0] >= 1)
    # no step dissipates a negative amount (each element's increment is floored at 0)
    assert np.all(np.diff(res.frictional_work) >= 0.0)
    assert np.all(res.segment_work() > 0.0)
    area = element_area(res)
    p0 = P0[geometry]
    for i in range(1, res.load_ratio.size):
        p, q, st = res.pressure[i] * p0, res.shear[i] * p0, res.state[i]
        load = res.load_ratio[i] * P_MAX[geometry]
        assert abs(np.sum(p * area) - load) <= 1e-9 * max(load, 1e-300)  # equilibrium
        scale = max(np.max(p), 1e-300)
        assert np.all(p[st == 0] == 0) and np.all(q[st == 0] == 0)
        assert np.all(p[st > 0] >= -1e-12 * scale)
        assert np.all(np.abs(q[st == 1]) <= k * p[st == 1] + 1e-12 * scale)  # stick
        du = res.tangential_displacement[i] - res.tangential_displacement[i - 1]
        assert np.allclose(du[st == 1], 0.0, atol=1e-12)
        inward, outward = st == 2, st == 3  # slip: q = -k p sign(du)
        assert np.allclose(q[inward], k * p[inward], atol=1e-12 * scale)
        assert np.allclose(q[outward], -k * p[outward], atol=1e-12 * scale)
        assert np.all(du[inward] <= 0) and np.all(du[outward] >= 0)
    # unloading reverses the slip at the contact edge
    assert np.any(res.state[res.segment_end(2)] == 3)
    # unloading to zero leaves no traction and no displacement
    assert np.all(res.pressure[-1] == 0) and np.all(res.shear[-1] == 0)
    assert np.all(res.tangential_displacement[-1] == 0) and res.contact_radius[-1] == 0
    assert math.isnan(res.stick_ratio[-1])


@pytest.mark.parametrize("k", [math.inf, 1e6])
def test_full_stick_dissipates_nothing(k):
    res = history("sphere", 0.3, k, [0, 1, 0.3, 1, 0], 10, n=60)
    assert res.converged.all()
    assert np.all(res.frictional_work == 0.0)
    assert set(np.unique(res.state)) <= {0, 1}
    loaded = res.load_ratio > 0
    assert np.all(res.stick_ratio[loaded] == 1.0)


# ----------------------------------------------------------------------------- slab
def test_slab_is_stiffer_than_half_plane_and_holds_a_larger_stick_zone():
    half = history("cylinder", 0.3, 0.2, [0, 1], 20, n=80)
    slab = history("cylinder", 0.3, 0.2, [0, 1], 20, n=80, slab_ratio=0.05)
    assert slab.converged.all()
    assert slab.contact_radius[-1] < half.contact_radius[-1]
    assert slab.stick_ratio[-1] > half.stick_ratio[-1] + 0.05


def test_slab_growing_with_the_contact_is_self_similar():
    """With h proportional to a (rebuilt every step) the slab problem is exactly
    self-similar, and the incremental solution must give the self-similar c/a at
    that a/h: this isolates the effect of a/h changing along a real path."""
    ratio, k, steps, n = 0.05, 0.2, 25, 80
    state, u_old = np.zeros(n, dtype=np.int8), np.zeros(n)
    for level in np.arange(1, steps + 1) / steps:
        a_h = math.sqrt(level)
        ops = hs.build_operators(Geometry("cylinder", 0.3, ratio / a_h), n)
        guess = state if state.any() else (ops.mid < a_h).astype(np.int8)
        step = hs.solve_step(ops, k, level * ops.p_max, u_old, guess)
        assert step.converged
        state, u_old = step.state, step.u
    a = hs.contact_radius(ops, step.state, step.gap)
    c = hs.stick_radius(ops, k, step.state, step.p, step.q, a)
    ref = solve("cylinder", 0.3, friction=k, n=64, energy=False,
                slab_ratio=ratio * a).stick_ratio
    assert abs(c / a / ref - 1) < 5e-3


# ----------------------------------------------------------------------------- dataset
def test_dataset_attributes_and_round_trip(tmp_path):
    res = history("cylinder", 0.3, 0.2, [0, 1, 0], 5, n=40, slab_ratio=0.05)
    ds = history_to_dataset(res)
    assert ds.sizes["step"] == 11 and ds.sizes["xi"] == 40
    for name in list(ds.data_vars) + list(ds.coords):
        assert "units" in ds[name].attrs and "long_name" in ds[name].attrs, name
    assert ds["state"].dtype == np.int8
    assert list(ds["state"].attrs["flag_values"]) == [0, 1, 2, 3]
    assert ds["state"].attrs["flag_meanings"] == "separated stick slip_inward slip_outward"
    assert ds["pressure"].dims == ("step", "xi")
    for name in ("load_ratio", "contact_radius", "stick_ratio", "frictional_work"):
        assert ds[name].dims == ("step",)
    attrs = ds.attrs
    assert attrs["geometry"] == "cylinder" and attrs["poisson_ratio"] == 0.3
    assert attrs["elements"] == 40 and attrs["friction_coefficient"] == 0.2
    assert list(attrs["load_path"]) == [0.0, 1.0, 0.0] and attrs["steps"] == 5
    assert attrs["slab_ratio"] == 0.05 and attrs["Conventions"] == "CF-1.10"
    assert "contactlib_version" in attrs
    path = io.write_dataset(ds, tmp_path / "h.nc")
    back = io.read_dataset(path)
    assert back["state"].dtype == np.int8
    np.testing.assert_array_equal(back["shear"].values, ds["shear"].values)
    np.testing.assert_array_equal(back["converged"].values, res.converged)
    assert "slab_ratio" not in history_to_dataset(history("sphere", 0.3, 0.2, [0, 1], 2,
                                                          n=20)).attrs


def test_progress_and_segment_work():
    calls = []
    res = history("sphere", 0.3, 0.2, [0, 1, 0.5], 3, n=20,
                  progress=lambda i, total: calls.append((i, total)))
    assert calls == [(i, 6) for i in range(1, 7)]
    assert res.segment_work().shape == (2,)
    assert math.isclose(res.segment_work().sum(), res.frictional_work[-1])
    assert res.segment_end(2) == 6 and list(res.segment) == [0, 1, 1, 1, 2, 2, 2]


def test_load_levels():
    levels, segment = load_levels([0, 1, 0.5], 4)
    np.testing.assert_allclose(levels, [0, .25, .5, .75, 1, .875, .75, .625, .5])
    assert levels[4] == 1.0 and levels[8] == 0.5
    assert list(segment) == [0, 1, 1, 1, 1, 2, 2, 2, 2]
    assert DEFAULT_N == 240


# ----------------------------------------------------------------------------- bad input
GOOD = dict(geometry="sphere", nu=0.3, friction=0.2, load_path=[0, 1], steps=5, n=20)
BAD = [
    ("steps", 0), ("steps", -2), ("steps", 2.5), ("steps", True), ("steps", "5"),
    ("friction", -0.1), ("friction", float("nan")), ("friction", "x"),
    ("load_path", []), ("load_path", [0]), ("load_path", [0, 1.5]), ("load_path", [0, -0.1]),
    ("load_path", [0.5, 1]), ("load_path", "0,1"), ("load_path", [0, "a"]),
    ("load_path", 1.0), ("geometry", "cone"), ("nu", 0.6), ("nu", -1.0), ("n", 4),
    ("n", 10.5), ("slab_ratio", 1001.0), ("slab_ratio", -1.0), ("base", "glued"),
]


@pytest.mark.parametrize("name,value", BAD, ids=[f"{b[0]}={b[1]!r}" for b in BAD])
def test_bad_input_is_refused_naming_the_argument(name, value):
    kwargs = dict(GOOD, **{name: value})
    geometry = kwargs.pop("geometry")
    if name == "slab_ratio" and value < 0:
        geometry = "cylinder"
    with pytest.raises(ValueError, match=name):
        history(geometry, **kwargs)


def test_cli_history_writes_dataset(capsys, tmp_path):
    out = tmp_path / "h.nc"
    code = cli.main(["history", "--geometry", "sphere", "--nu", "0.3", "--friction", "0.2",
                     "--load-path", "0,1,0", "--steps", "4", "--n", "40",
                     "--output", str(out)])
    text = capsys.readouterr().out
    assert code == 0 and out.exists()
    assert "converged steps: 8/8" in text and f"wrote {out}" in text
    ds = io.read_dataset(out)
    assert ds.sizes["step"] == 9 and ds.attrs["steps"] == 4


CLI_BAD = [
    (["--steps", "0"], "--steps"), (["--steps", "-3"], "--steps"),
    (["--steps", "2.5"], "--steps"), (["--friction", "-1"], "--friction"),
    (["--load-path", ""], "--load-path"), (["--load-path", "0,1.5"], "--load-path"),
    (["--load-path", "0.2,1"], "--load-path"), (["--load-path", "0,x"], "--load-path"),
    (["--nu", "0.7"], "--nu"), (["--geometry", "cone"], "--geometry"),
    (["--slab-ratio", "1001"], "--slab-ratio"), (["--base", "glued"], "--base"),
    (["--n", "4"], "n must"),
]


@pytest.mark.parametrize("args,option", CLI_BAD, ids=[" ".join(c[0]) for c in CLI_BAD])
def test_cli_history_bad_input_one_line(capsys, tmp_path, args, option):
    base = {"--geometry": "sphere", "--nu": "0.3", "--friction": "0.2",
            "--load-path": "0,1", "--steps": "3", "--n": "20"}
    base[args[0]] = args[1]
    argv = ["history"] + [x for kv in base.items() for x in kv] + [
        "--output", str(tmp_path / "bad.nc")]
    code = cli.main(argv)
    _, err = capsys.readouterr()
    assert code == 2
    assert err.count("\n") == 1 and err.startswith("contactlib: error: ") and option in err
    assert os.listdir(tmp_path) == []


@pytest.mark.parametrize("nu, kw", [(0.5, {}), (0.3, {}), (0.3, {"slab_ratio": 5.0,
                                                                  "base": "bonded"})])
def test_no_friction_has_no_stick_zone_and_says_so_exactly(nu, kw):
    """k = 0: |q| < k p cannot hold, so c = 0 at every step, as the self-similar solve says
    (c/a = 0 at friction 0), with estimate 0; before, nu = 0.5 (no slip: the surfaces do
    not move apart tangentially) read as full stick, and c = 0 was flagged at half an
    element (0.01 a_max) at every step, a flag that always fired."""
    import contactlib as cl

    res = cl.history("sphere", nu, 0.0, [0, 1, 0], 20, n=60, **kw)
    assert np.all(np.nan_to_num(res.stick_ratio) == 0.0)
    assert not np.any(res.state == hs.STICK)  # nil slip is not stick: every contact slips
    assert np.any(res.state == hs.SLIP_INWARD)
    assert np.all(res.stick_radius_error_estimate == 0.0)
    assert res.resolved_quantities["stick_radius"]
    assert cl.solve("sphere", nu, friction=0.0, n=64, **kw).stick_ratio == 0.0
