"""Every answer carries its error: the extremes, the estimates and the flags.

Truths, all independent of the code under test:

* nu = 0.499: the coupling beta is 1e-3, and the exact uncoupled closed forms
  (sphere k = beta artanh(g)/(g K'(g)), half-plane k = beta K(g)/K'(g))
  hold to about beta^2 ~ 1e-6 at every c/a;
* otherwise: the same case refined fourfold (nested meshes, error ~ n^-2,
  so the reference's own error is 1/16 of the case's).

A case passes when it agrees with the truth within its own estimate, or when
it is flagged (``resolved`` false). A resolved case must also not be
over-estimated by more than 10x (plus a floor for zero crossings).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from contactlib import solve, sweep
from contactlib.cli import main
from contactlib.discretization.elements import graded_mesh
from contactlib.model.theory import uncoupled_friction

BETA2 = ((1 - 2 * 0.499) / (2 * (1 - 0.499))) ** 2  # 4.0e-6 at nu = 0.499


def model_error(c: float) -> float:
    """The uncoupled closed form's own relative error at nu = 0.499.

    It neglects the coupling, an O(beta^2) effect whose coefficient grows as
    c/a -> 1: the coupled k over the closed form is 1 + 0.6 beta^2 at c/a = 0.5
    but 1 + 6.7 beta^2 (sphere) and 1 + 10.3 beta^2 (half-plane) at 0.9999
    (measured at nu = 0.3, beta^2 = 0.082, where the effect is large enough
    to see; tests/test_extremes.py checks its growth). So the closed form is a
    truth to about beta^2 = 4e-6 up to c/a = 0.5 and to 15 beta^2 = 6e-5 beyond.
    """
    return BETA2 if c <= 0.5 else 15.0 * BETA2


def _check_against(sol, truth: float, truth_error: float = 0.0) -> str:
    """'resolved' (and checked against the truth) or 'flagged' (with a message).

    A resolved case must agree with the truth within three times its estimate
    (plus the truth's own uncertainty) and its estimate must not exceed ten
    times the error (the error is only known to within the truth's uncertainty).
    """
    if not sol.resolved:
        assert sol.message, "an unresolved case must say why"
        return "flagged"
    err = abs(sol.friction_coefficient - truth) / truth
    assert err <= 3.0 * sol.error_estimate + truth_error, (
        f"c/a = {sol.stick_ratio}: error {err:.2e} not covered by estimate "
        f"{sol.error_estimate:.2e} (truth known to {truth_error:.1e})")
    assert sol.error_estimate <= 10.0 * (err + truth_error), (
        f"c/a = {sol.stick_ratio}: estimate {sol.error_estimate:.2e} inflated over the error "
        f"{err:.2e} (truth known to {truth_error:.1e})")
    return "resolved"


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
@pytest.mark.parametrize("c", [1e-8, 1e-6, 1e-4, 1e-2, 0.5, 0.99, 0.999, 0.9999, 1 - 1e-5])
def test_closed_form_at_default_resolution(geometry, c):
    """nu = 0.499, default n: k within 1e-4 of the closed form (was -61 % at 1e-6).

    c/a = 1e-8 and 1 - 1e-5 were flagged until the rows of a tiny stick zone and of a
    thin slip annulus were written as differences (sphere, 1e-8: -2.7e-4 before,
    -6.5e-5 now; 1 - 1e-5: -2.9e-4 before, 4e-6 now).
    """
    sol = solve(geometry, 0.499, stick_ratio=c, energy=False)
    truth = float(uncoupled_friction(geometry, 0.499, c))
    assert _check_against(sol, truth, model_error(c)) == "resolved"
    assert abs(sol.friction_coefficient - truth) / truth < 1e-4
    assert sol.error_estimate < 1e-3


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_near_full_stick_keeps_converging_at_high_n(geometry):
    """nu = 0.49999 (beta^2 = 1e-10: the closed form is a truth to ~1.5e-9), c/a = 0.999,
    n = 1024: k within 1e-6 of the closed form, and the estimate covers the error.

    Before the band of difference rows was written from n = 512
    (default_method.NEAR_ROWS_FROM_N), the plain rows' round-off grew with n here: k was
    off by 1.3e-4 (sphere) and 7.7e-5 (half-plane) at n = 1024, 6.4e-4 at 1536, against
    1.7e-6 at n = 512; now 4.3e-7 and 3.6e-7, error / estimate 0.95 and 0.92.
    """
    nu, c = 0.49999, 0.999
    sol = solve(geometry, nu, stick_ratio=c, n=1024, energy=False)
    truth = float(uncoupled_friction(geometry, nu, c))
    err = abs(sol.friction_coefficient / truth - 1.0)
    assert sol.resolved
    assert err < 1e-6
    assert err <= 1.5 * sol.error_estimate <= 15.0 * err


def test_default_estimate_carries_the_quadrature_noise_at_high_n():
    """A tiny stick zone at n = 1024 (nu = 0.49999, c/a = 1e-6): the round-off of the
    kernels' quadrature grows with n there, and the nested levels n/4, n/2 do not see it.
    The sphere's k error was 1.9e-5 against an estimate of 5.3e-6 (3.6x short); the
    estimate now adds the measured noise bound (accuracy.default_noise, 5.1e-5 with its
    margin for other CPUs). Below n = 512 the bound applies where the axis or edge
    difference rows do (tests/test_estimate_extremes.py), and is 0 elsewhere."""
    from contactlib.accuracy import default_noise
    from contactlib.model import contact

    nu, c = 0.49999, 1e-6
    sol = solve("sphere", nu, stick_ratio=c, n=1024, energy=False)
    truth = float(uncoupled_friction("sphere", nu, c))
    err = abs(sol.friction_coefficient / truth - 1.0)
    assert err > 1e-5  # the noise this is about (not a converged case)
    assert err <= sol.error_estimate
    noise = default_noise(contact("sphere", nu), c, 1024)
    assert noise < sol.error_estimate < 2.0 * noise + 2.0 * err
    assert default_noise(contact("sphere", nu), c, 256) > 0.0  # difference rows: every n
    assert default_noise(contact("sphere", nu), 0.5, 256) == 0.0  # plain rows below 512


FOURFOLD = [("cylinder", 0.9), pytest.param("sphere", 0.3, marks=pytest.mark.slow),
            pytest.param("sphere", 0.5, marks=pytest.mark.slow),
            pytest.param("sphere", 0.9, marks=pytest.mark.slow),
            pytest.param("cylinder", 0.1, marks=pytest.mark.slow)]


@pytest.mark.parametrize("geometry,c", FOURFOLD)
def test_estimate_against_fourfold_refinement(geometry, c):
    """Default n = 256 against n = 1024: each estimate within [err/3, 10 err].

    The truth's own error is taken as 1/15 of the difference (n^-2, measured
    from n = 128 on; below, the sphere's k error crosses zero between n = 32
    and 64, and at n = 128 the estimate from 32/64/128 misses it by 11x, see
    docs/accuracy.md).
    """
    coarse = solve(geometry, 0.3, stick_ratio=c)
    fine = solve(geometry, 0.3, stick_ratio=c, n=1024)
    for name, est in (("friction_coefficient", "error_estimate"),
                      ("load_ratio", "load_error_estimate"),
                      ("frictional_work", "work_error_estimate")):
        ref = getattr(fine, name)
        err = abs(getattr(coarse, name) - ref) / abs(ref) * 16.0 / 15.0
        e = getattr(coarse, est)
        assert err / 3.0 <= e <= 10.0 * err, (name, err, e)


@pytest.mark.parametrize("geometry,c,n,fine", [
    ("sphere", 0.5, 128, 512),  # error crosses zero between n = 32 and 64: r = 91 at 32/64/128
    ("sphere", 0.3, 128, 512),
    ("cylinder", 0.9999, 64, 256),  # k(16), k(32), k(64) agree to 2e-7 by chance: r = 1075
])
def test_non_asymptotic_levels(geometry, c, n, fine):
    """Where d2 = k(n/2) - k(n) is smaller than n^-2 predicts from d1 = k(n/4) - k(n/2)
    (ratio above 4), the estimate must still cover the error within a factor 3 (it missed
    by 11x, 8x and 280x when p was clipped at 2 and |d2|/3 taken) and not exceed it 10x.
    Truth: the same case at ``fine`` (fourfold at least), Richardson-extrapolated with the
    case at fine/2 where that is asymptotic, else taken as it is."""
    from contactlib.solvers.default_method import solve_default
    from contactlib.model.geometry import Geometry

    sol = solve(geometry, 0.3, stick_ratio=c, n=n, energy=False)
    g = Geometry(geometry, 0.3)
    k_fine, k_half = solve_default(g, c, fine).k, solve_default(g, c, fine // 2).k
    truth = k_fine + (k_fine - k_half) / 3.0 if geometry == "sphere" else k_fine
    err = abs(sol.friction_coefficient / truth - 1)
    assert err / 3.0 <= sol.error_estimate <= 10.0 * err, (err, sol.error_estimate)


def test_estimate_against_spence():
    """Spence (1975): nu = 0, k = 0.2986 gives c/a = 0.5.

    Spence's value is itself a numerical result, quoted to four digits; the
    converged k of this method is 0.29871 (n = 256 ... 1024, docs/validation.md),
    3.7e-4 above it. So Spence's point judges the estimate only to about 4e-4:
    a resolved case must agree with it within three times its estimate plus that.
    """
    sol = solve("sphere", 0.0, stick_ratio=0.5, energy=False)
    err = abs(sol.friction_coefficient - 0.2986) / 0.2986
    assert sol.resolved and sol.error_estimate <= 1e-3
    assert err <= 3.0 * sol.error_estimate + 4e-4


def test_flags_a_loss_of_consistency():
    """nu = 0, c/a = 0.999: was k = 118 'converged, consistent'; now never resolved."""
    sol = solve("sphere", 0.0, stick_ratio=0.999, energy=False)
    assert not sol.resolved
    assert sol.message


def test_max_error_names_the_resolving_n():
    sol = solve("sphere", 0.3, stick_ratio=0.5, energy=False, max_error=3e-6)
    assert not sol.resolved and sol.converged
    assert "max_error" in sol.message and "n = " in sol.message
    # the named n does resolve it
    need = int(sol.message.split("n = ")[-1].split()[0])
    assert solve("sphere", 0.3, stick_ratio=0.5, n=need, energy=False, max_error=3e-6).resolved
    # beyond the largest n: says so
    sol = solve("sphere", 0.3, stick_ratio=0.5, energy=False, max_error=1e-9)
    assert not sol.resolved and "no supported n" in sol.message
    assert solve("sphere", 0.3, stick_ratio=0.5, energy=False, max_error=1e-3).resolved


def test_exact_cases_carry_zero_k_error():
    for c in (0.0, 1.0):
        sol = solve("sphere", 0.3, stick_ratio=c)
        assert sol.error_estimate == 0.0 and sol.resolved
        assert math.isfinite(sol.load_error_estimate)


def test_paper_scheme_is_measured_not_trusted():
    sol = solve("sphere", 0.3, stick_ratio=0.5, method="paper", energy=False)
    assert sol.error_estimate > 0.3  # the printed scheme is 30-90 % off
    assert not sol.resolved


@pytest.mark.slow  # the inverse is also checked fast (Spence's point, tests/test_sphere.py)
def test_inverse_at_small_and_large_k():
    """--friction at tiny and large k: the stick ratio that reproduces k, with an estimate."""
    for k in (1.4e-4, 6e-3):  # c/a about 2e-6 and 0.9998
        sol = solve("sphere", 0.499, friction=k, energy=False)
        truth = float(uncoupled_friction("sphere", 0.499, sol.stick_ratio))
        assert abs(truth - k) / k < 1e-4 + 3 * sol.error_estimate
        assert sol.resolved


def test_sweep_dataset_has_the_estimates(tmp_path):
    out = tmp_path / "s.nc"
    assert main(["sweep", "--geometry", "sphere", "--nu", "0.3", "--stick-ratios", "0.2,0.6",
                 "--n", "64", "--output", str(out)]) == 0
    import xarray as xr

    with xr.open_dataset(out) as ds:
        for name in ("error_estimate", "load_error_estimate", "work_error_estimate", "resolved"):
            assert name in ds and ds[name].sizes["stick_ratio"] == 2
            assert ds[name].attrs["long_name"]
        assert ds.attrs["max_error"] == 1e-3


@pytest.mark.parametrize("value", ["0", "1", "nan", "abc", "-1e-3", "inf"])
def test_bad_max_error(value, tmp_path, capsys):
    out = tmp_path / "x.nc"
    code = main(["solve", "--geometry", "sphere", "--nu", "0.3", "--stick-ratio", "0.5",
                 f"--max-error={value}", "--output", str(out)])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1 and "--max-error" in err[0]
    assert not out.exists()


def test_library_rejects_bad_max_error():
    with pytest.raises(ValueError, match="max_error"):
        sweep("sphere", 0.3, [0.5], n=32, max_error=0.0)


def test_mesh_follows_both_lengths():
    """Elements next to c are a small fraction of min(c, a - c) on both sides."""
    for c in (1e-8, 1e-4, 0.5, 1 - 1e-5):
        mesh = graded_mesh(256, c)
        h = np.diff(mesh.nodes)
        m = mesh.stick_index
        length = min(c, 1.0 - c)
        assert mesh.nodes[m] == c
        assert h[m - 1] < 1e-3 * length and h[m] < 1e-3 * length
        assert np.all(h > 0)
    # nested: n/2 is every other node of n
    assert np.allclose(graded_mesh(256, 0.3).nodes[::2], graded_mesh(128, 0.3).nodes,
                       rtol=0, atol=1e-14)


GRID_C = [1e-8, 1e-6, 1e-4, 1e-2, 0.5, 0.99, 0.999, 0.9999, 0.99999]
GRID_NU = [-0.99, -0.5, 0.0, 0.3, 0.499, 0.5]
BODIES = [("sphere", 0.0), ("cylinder", 0.0), ("cylinder", 0.05), ("cylinder", 1.0)]


# (cylinder, nu = 0.3, c/a = 0.9999 at n = 64 was a known miss: k(16), k(32), k(64) agree
# to 2e-7 by chance while all are 5.3e-5 from k(256); the estimate 1.9e-7 under-covered it
# 280x. A ratio d1/d2 above 4 is now read as not asymptotic: test_non_asymptotic_levels.)


def _stability(geometry: str, slab: float, nu: float, n: int) -> dict[str, int]:
    """The issue's grid at resolution n, each case against the closed form (nu = 0.499,
    half-space and half-plane) or the same case refined fourfold (itself resolved)."""
    sols = sweep(geometry, nu, GRID_C, n=n, slab_ratio=slab, energy=False)
    closed = nu == 0.499 and slab == 0.0
    decoupled = nu == 0.5 and slab == 0.0  # a layer at nu = 0.5 is coupled
    refs = None if closed or decoupled else sweep(geometry, nu, GRID_C, n=4 * n,
                                                  slab_ratio=slab, energy=False)
    count = {"resolved": 0, "flagged": 0, "no truth": 0}
    for i, (c, sol) in enumerate(zip(GRID_C, sols)):
        if decoupled:  # k = 0 exactly for every c/a < 1
            assert sol.friction_coefficient == 0.0 and sol.resolved
            count["resolved"] += 1
        elif closed:
            count[_check_against(sol, float(uncoupled_friction(geometry, nu, c)),
                             model_error(c))] += 1
        elif not refs[i].consistent:  # the fine run found an inconsistent root: no truth
            assert not sol.resolved or sol.error_estimate > 0.0
            count["no truth"] += 1
        elif refs[i].resolved:
            count[_check_against(sol, refs[i].friction_coefficient, refs[i].error_estimate)] += 1
        else:  # no trustworthy truth: the coarse case must not claim more than the fine one
            assert not sol.resolved or sol.error_estimate > 0.0
            count["no truth"] += 1
    return count


@pytest.mark.parametrize("geometry,slab,nu", [
    ("sphere", 0.0, 0.3), pytest.param("cylinder", 0.0, -0.5, marks=pytest.mark.slow)])
def test_stability_grid_sample(geometry, slab, nu):
    """Two rows of the grid at n = 32 (fast): agree within the estimate, or flagged."""
    _stability(geometry, slab, nu, 32)


@pytest.mark.slow
@pytest.mark.parametrize("geometry,slab", BODIES)
@pytest.mark.parametrize("nu", GRID_NU)
def test_stability_grid(geometry, slab, nu):
    """The issue's grid: 9 c/a x 6 nu x 4 bodies at n = 64 against n = 256 or the closed
    form: every case agrees with its truth within its estimate, or is flagged."""
    count = _stability(geometry, slab, nu, 64)
    print(geometry, slab, nu, count)


@pytest.mark.parametrize("value", ["0", "1", "nan", "abc"])
def test_history_cli_bad_max_error(value, tmp_path, capsys):
    out = tmp_path / "h.nc"
    code = main(["history", "--geometry", "sphere", "--nu", "0.3", "--friction", "0.2",
                 "--load-path", "0,1", "--steps", "4", f"--max-error={value}",
                 "--output", str(out)])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1 and "--max-error" in err[0]
    assert not out.exists()


def test_history_cli_and_scene_pass_max_error(tmp_path, capsys):
    import xarray as xr

    from contactlib.scene import parse_scene

    out = tmp_path / "h.nc"
    assert main(["history", "--geometry", "sphere", "--nu", "0.3", "--friction", "0.2",
                 "--load-path", "0,1", "--steps", "4", "--n", "32", "--max-error", "0.5",
                 "--output", str(out)]) == 0
    assert "resolved steps (max error 0.5)" in capsys.readouterr().out
    with xr.open_dataset(out) as ds:
        assert ds.attrs["max_error"] == 0.5 and "resolved" in ds
    raw = {"kind": "history", "geometry": "sphere", "nu": 0.3, "friction": 0.2,
           "load_path": [0, 1], "steps": 4, "max_error": 0.01}
    assert parse_scene("h", raw).run_spec(0)["max_error"] == 0.01
    with pytest.raises(ValueError, match="max_error"):
        parse_scene("h", dict(raw, max_error=2))
    with pytest.raises(ValueError, match="max_error"):
        parse_scene("s", {"geometry": "sphere", "nu": 0.3, "stick_ratios": [0.5],
                          "max_error": "x"})


def test_solve_and_sweep_cli_pass_max_error(tmp_path, capsys):
    import xarray as xr

    out = tmp_path / "s.nc"
    assert main(["sweep", "--geometry", "cylinder", "--nu", "0.3", "--stick-ratios", "0.5",
                 "--n", "32", "--max-error", "1e-9", "--output", str(out)]) == 0
    with xr.open_dataset(out) as ds:
        assert ds.attrs["max_error"] == 1e-9 and not bool(ds["resolved"].values[0])
        assert "exceeds max_error" in str(ds["message"].values[0])


def test_estimate_rules():
    """accuracy.estimate on made-up levels k(h) = k* + a h^2 + b h^3 (h = 4, 2, 1 for n/4,
    n/2, n): outside the asymptotic range (r = d1/d2 > 4 or < 0) the estimate is |a| + |b|
    of the two-term fit (solved here as a 3x3 system), so a pure h^2 or h^3 error is
    estimated exactly and a cancellation of the two terms at level n hides nothing."""
    from contactlib.accuracy import estimate

    def levels(k, a, b):
        return [k + a * h**2 + b * h**3 for h in (4.0, 2.0, 1.0)]

    def fit(ks):
        m = np.array([[1.0, h**2, h**3] for h in (4.0, 2.0, 1.0)])
        _, a, b = np.linalg.solve(m, ks)
        return abs(a) + abs(b)

    k = 1.0
    for a, b in ((1e-5, 0.0), (0.0, 1e-5)):  # r = 4, r = 8: the error of k(n) itself
        ks = levels(k, a, b)
        assert estimate(*ks)[0] == pytest.approx(abs(ks[2] - k) / ks[2], rel=1e-6)
    for a, b in ((1e-5, -1e-5), (-3e-6, 1e-5), (2e-5, -1.5e-5), (1e-6, -4e-6)):
        ks = levels(k, a, b)
        d1, d2 = ks[0] - ks[1], ks[1] - ks[2]
        assert d1 / d2 > 4.0 or d1 / d2 < 0.0
        assert estimate(*ks)[0] == pytest.approx(fit(ks) / ks[2], rel=1e-6)
        assert estimate(*ks)[0] >= 0.9 * max(abs(a), abs(b))  # (1e-5, -1e-5): k(n) = k*
    # 2 <= r <= 4: Richardson with the observed order; 0 <= r < 2: the larger difference
    assert estimate(k + 5e-4, k + 1e-4, k)[0] == pytest.approx(1e-4 / 3, rel=1e-9)
    assert estimate(k + 3e-4, k + 1e-4, k)[0] == pytest.approx(1e-4, rel=1e-9)
    assert estimate(k + 2.5e-4, k + 1e-4, k)[0] == pytest.approx(1.5e-4, rel=1e-9)
    r4 = [estimate(k + (4.0 + e) * 1e-4 + 1e-4, k + 1e-4, k)[0] for e in (-1e-9, 1e-9)]
    assert r4[0] == pytest.approx(r4[1], rel=1e-6)  # continuous at r = 4


def test_tolerance_refinement_stops_where_the_noise_alone_exceeds_it():
    """solve_to_tolerance doubles n until the estimate meets the tolerance, but a noise
    bound that alone exceeds it and grows with n cannot be refined away: it stops at once
    and says so, without solving at 2n. A noise below the tolerance does not stop it."""
    from contactlib.accuracy import solve_to_tolerance

    calls = []

    def solve_k(m):
        calls.append(m)
        return 1.0 + 1e-6 * (128.0 / m) ** 2  # converged levels, error ~n^-2

    used, est, msg = solve_to_tolerance(solve_k, 512, 5e-6,
                                        noise=lambda m: 1e-5 * (m / 512.0) ** 0.5)
    assert used == 512 and sorted(calls) == [128, 256, 512]
    assert est > 1e-5 and "noise" in msg and "not met" in msg
    calls.clear()
    used, est, msg = solve_to_tolerance(solve_k, 128, 2e-8,
                                        noise=lambda m: 1e-9 * (m / 512.0) ** 0.5)
    assert msg == "" and used > 128 and est <= 2e-8
