"""Error estimates and the ``resolved`` flag of the loading history (contactlib.history_api).

The truth is the same history refined fourfold (4n elements, 4 x steps a
segment): the estimates must cover its difference from the run within a
factor 3 at every step and not exceed it more than tenfold (largest estimate
over largest error, segment by segment).
"""

from __future__ import annotations

import re

import numpy as np
import pytest

from contactlib.solvers import history_solver as hs
from contactlib.history_api import DEFAULT_MAX_ERROR, MAX_N, MAX_STEPS, MIN_N, history
from contactlib.io import history_to_dataset, stack_histories

NU = 0.3
PATHS = {"cycle": (0, 1, 0), "fretting": (0, 1, 0.5, 1, 0.5, 1, 0.5, 1)}


def stick_radius(res) -> np.ndarray:
    return np.nan_to_num(res.stick_ratio * res.contact_radius)


@pytest.mark.slow
@pytest.mark.parametrize("path", list(PATHS))
@pytest.mark.parametrize("k", [0.1, 0.2, 0.3])
@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_estimates_cover_the_error_of_a_fourfold_refinement(geometry, k, path):
    """Estimate / true error >= 1/3 at every loaded step; segment maxima within 5x (stick
    radius) and 10x (work).

    The work's error is relative to the path's total work (the estimate's scale).

    Measured at n = 60, 20 steps (truth n = 240, 80 steps): the smallest
    estimate / error is 0.48 (stick radius) and 0.44 (work), the largest
    segment inflation 3.7 (stick radius, sphere k = 0.1 fretting) and 6.8 (work).
    (When the stick radius's estimate was |run - A| in full: 0.75 and 9.)
    """
    n, steps = 60, 20
    res = history(geometry, NU, k, PATHS[path], steps, n=n)
    ref = history(geometry, NU, k, PATHS[path], 4 * steps, n=4 * n, error_estimate=False)
    assert res.converged.all() and ref.converged.all()
    w_ref = ref.frictional_work[::4]
    true = {"stick radius": np.abs(stick_radius(res) - stick_radius(ref)[::4]),
            "work": np.abs(res.frictional_work - w_ref) / ref.frictional_work[-1]}
    est = {"stick radius": res.stick_radius_error_estimate, "work": res.work_error_estimate}
    loaded = res.load_ratio > 0
    for name in true:
        t, e = true[name], est[name]
        assert np.all(np.isfinite(e[loaded]) & (e[loaded] >= 0)), name
        m = loaded & (t > 0)
        assert np.all(e[m] >= t[m] / 3), (name, np.min(e[m] / t[m]))
        for g in range(1, len(PATHS[path])):
            s = loaded & (res.segment == g)
            if t[s].max() > 0:
                bound = 5 if name == "stick radius" else 10
                assert e[s].max() <= bound * t[s].max(), (name, g, e[s].max() / t[s].max())


def test_dataset_carries_estimates_flags_and_max_error():
    res = history("sphere", NU, 0.2, [0, 1, 0], 10, n=60, max_error=0.05)
    ds = history_to_dataset(res)
    for name in ("stick_radius_error_estimate", "work_error_estimate", "resolved"):
        assert ds[name].dims == ("step",)
        assert ds[name].attrs["units"] == "1" and ds[name].attrs["long_name"]
    assert ds["resolved"].dtype == bool
    assert ds.attrs["max_error"] == 0.05
    assert "a_max" in ds["stick_radius_error_estimate"].attrs["long_name"]
    assert "total frictional work" in ds["work_error_estimate"].attrs["long_name"]
    assert ds["energy_error_estimate"].dims == ("step",)
    assert float(ds["work_scale"]) == res.work_scale == res.frictional_work[-1]
    assert ds.attrs["resolved_quantities"] == " ".join(
        q for q, ok in res.resolved_quantities.items() if ok)
    # resolved = converged, values finite, slip zone resolved, every estimate within max_error
    annulus = hs.annulus_resolved(0.2, res.state)
    within = ((res.stick_radius_error_estimate <= 0.05) & (res.work_error_estimate <= 0.05)
              & (res.energy_error_estimate <= 0.05))
    assert np.array_equal(res.resolved, res.converged & annulus & within)
    assert res.resolved.any() and not res.resolved.all()
    assert "steps flagged" in res.message and "resolved to max_error 0.05" in res.message


def test_default_max_error_and_skipped_estimate():
    res = history("sphere", NU, 0.2, [0, 1], 8, n=40, error_estimate=False)
    assert res.max_error == DEFAULT_MAX_ERROR == 1e-2  # a load path's default (not 1e-3:
    # the default n and steps reach a cycle's work to ~2e-3, the stick radius to 2.5e-3 a_max)
    assert np.all(np.isnan(res.stick_radius_error_estimate))
    assert np.all(np.isnan(res.work_error_estimate))
    assert np.array_equal(res.resolved, res.converged & hs.annulus_resolved(0.2, res.state))


def test_thin_slip_zone_steps_are_flagged_and_still_reported():
    """k = 0.3 (c/a = 0.9 at the top): the slip annulus spans under 12 elements at n = 60."""
    res = history("sphere", NU, 0.3, [0, 1], 10, n=60, max_error=0.9)
    slipping = np.count_nonzero(res.state >= hs.SLIP_INWARD, axis=1)
    thin = (slipping > 0) & (slipping < hs.MIN_SLIP_ELEMENTS)
    assert thin[-1] and not res.resolved[thin].any()
    assert "slip zone at the largest load spans only" in res.message
    # the work's verdict names this cause, counted from the states, not by elimination
    assert not res.resolved_quantities["frictional_work"]
    assert res.unresolved_reasons["frictional_work"] == (
        f"the slip zone at the largest load spans {slipping[-1]} of the "
        f"{hs.MIN_SLIP_ELEMENTS} elements it needs")


def test_unresolved_reasons_name_the_estimate_and_only_unresolved_quantities():
    """A coarse cycle asked 1e-4: the quantities whose largest estimate passes it are
    unresolved, each with that estimate quoted; a resolved quantity has no reason."""
    res = history("sphere", NU, 0.2, [0, 1, 0], 8, n=80, max_error=1e-4)
    assert res.converged.all()
    worst_w = float(np.max(res.work_error_estimate))
    assert worst_w > 1e-4 and not res.resolved_quantities["frictional_work"]
    assert res.unresolved_reasons["frictional_work"] == (
        f"its estimate reaches {worst_w:.2g} of its total (max_error 0.0001)")
    assert set(res.unresolved_reasons) == {q for q, ok in res.resolved_quantities.items()
                                           if not ok}
    loose = history("sphere", NU, 0.2, [0, 1, 0], 8, n=80, max_error=0.5)
    assert all(loose.resolved_quantities.values()) and loose.unresolved_reasons == {}


def test_quantised_stick_edge_has_an_estimate_of_at_least_half_an_element():
    """Unloading: the stick edge is an element edge, good to h/2 only."""
    n = 60
    res = history("sphere", NU, 0.2, [0, 1, 0], 10, n=n)
    h = 1.2 / n
    c = stick_radius(res)
    on_edge = np.isclose(c / h, np.rint(c / h), rtol=0, atol=1e-9) & (c < res.contact_radius)
    assert on_edge[11:].any()
    assert np.all(res.stick_radius_error_estimate[on_edge] >= 0.5 * h)


def test_frictionless_work_estimate_is_zero():
    res = history("cylinder", NU, 0.0, [0, 1, 0], 6, n=40)
    assert np.all(res.work_error_estimate == 0.0)


@pytest.mark.parametrize("value", [0, 1, -1e-3, 1.5, float("nan"), float("inf"), "0.01",
                                   True])  # (None: the default, 1e-2)
def test_bad_max_error_is_refused_naming_it(value):
    with pytest.raises(ValueError, match="max_error"):
        history("sphere", NU, 0.2, [0, 1], 2, n=20, max_error=value)


@pytest.mark.parametrize("value", [1, "yes", None])
def test_bad_error_estimate_is_refused_naming_it(value):
    with pytest.raises(ValueError, match="error_estimate"):
        history("sphere", NU, 0.2, [0, 1], 2, n=20, error_estimate=value)


@pytest.mark.slow
def test_work_estimate_with_opposite_mesh_and_step_errors():
    """Sphere k = 0.2, 0 -> 1 -> 0, n = 120, 50 steps: the mesh error and the step error of the
    cycle work have opposite signs; estimated separately they no longer cancel (measured
    estimate / error 2.0 at the end, 0.08 when both were halved in one coarse run)."""
    res = history("sphere", NU, 0.2, PATHS["cycle"], 50, n=120)
    ref = history("sphere", NU, 0.2, PATHS["cycle"], 200, n=480, error_estimate=False)
    true = abs(res.frictional_work[-1] / ref.frictional_work[-1] - 1)
    assert true / 3 <= res.work_error_estimate[-1] <= 10 * true


def test_coarse_jump_between_two_coarse_steps_is_not_an_error():
    """A stick radius that jumps between two coarse steps (every other fine step): the
    fine step in between keeps at most its neighbours' difference; a smooth change keeps
    the interpolated difference."""
    h = 0.01
    segment = np.ones(9, dtype=int)
    segment[0] = 0
    touching = np.ones(9, dtype=bool)
    a = np.array([0.0, 0.47, 0.47, 0.47, 0.47, 0.35, 0.24, 0.24, 0.24])  # odd: interpolated
    f = np.array([0.0, 0.47, 0.47, 0.47, 0.46, 0.29, 0.25, 0.24, 0.24])
    out = hs.straddle(np.abs(f - a), a, segment, touching, h)
    assert out[5] == pytest.approx(0.01) and np.abs(f - a)[5] == pytest.approx(0.06)
    np.testing.assert_array_equal(np.delete(out, 5), np.delete(np.abs(f - a), 5))
    smooth = np.linspace(0.5, 0.3, 9)  # a steady change: not a jump
    d = np.abs(smooth + 0.003 * (np.arange(9) % 2) - smooth)
    np.testing.assert_array_equal(hs.straddle(d, smooth, segment, touching, h), d)


def test_smooth_deviation_measures_a_step_off_a_smooth_path():
    """A quadratic in each segment (the segments' values unrelated): zero deviation; one
    step moved by delta deviates by exactly delta (its neighbours' fit leaves it out);
    steps not located (garbage values) take no part and get 0; segment ends without two
    fitted neighbours on a side get 0."""
    segment = np.repeat([0, 1, 2], [1, 30, 30])
    i = np.arange(segment.size, dtype=float)
    values = np.where(segment == 1, 0.3 + 0.01 * i - 1e-4 * i**2, 0.9 - 0.02 * (i - 31) ** 2)
    fitted = segment > 0
    dev = hs.smooth_deviation(values, segment, fitted)
    np.testing.assert_allclose(dev, 0.0, atol=1e-12)
    moved = values.copy()
    moved[15] += 0.004
    moved[40:43] = [7.0, -3.0, 11.0]  # not located: an element edge, say
    fitted[40:43] = False
    dev = hs.smooth_deviation(moved, segment, fitted)
    assert dev[15] == pytest.approx(0.004, rel=1e-9)
    assert np.all(dev[40:43] == 0.0) and np.all(dev[43:] < 1e-9)
    assert dev[1] == dev[2] == dev[30] == dev[31] == 0.0  # one neighbour on a side


def _window_max(values, segment, half=2):
    """Largest value within ``half`` steps either side, in the same path segment."""
    return np.array([np.max(values[max(i - half, 0):i + half + 1]
                            [segment[max(i - half, 0):i + half + 1] == segment[i]])
                     for i in range(values.size)])


def _against_a_fourfold_refinement(geometry, nu, k, path, kwargs, max_error):
    """Estimates of n = 120, 50 steps against the run with 480 elements, 200 steps.

    Returns a dict: the cycle work's estimate / true error, the true errors of the steps
    flagged for the work and of those not flagged (relative to the refined path's total
    work); for the stick radius over the steps that move the contact edge by at most an
    element (those the verdict judges): the smallest estimate / true error ("cover"), the
    largest over path segments of the segment's largest estimate over its largest error
    ("inflation"), and the median of the estimate over the largest true error within two
    steps either side ("typical": one step's error may pass near 0 as the edge crosses the
    elements)."""
    n, steps = 120, 50
    res = history(geometry, nu, k, path, steps, n=n, max_error=max_error, **kwargs)
    ref = history(geometry, nu, k, path, 4 * steps, n=4 * n, error_estimate=False, **kwargs)
    assert res.converged.all() and ref.converged.all()
    true = np.abs(res.frictional_work - ref.frictional_work[::4]) / ref.frictional_work[-1]
    flagged = res.work_error_estimate > max_error
    c_true = np.abs(stick_radius(res) - stick_radius(ref)[::4])
    c_est = res.stick_radius_error_estimate
    regular = np.concatenate([[False], np.abs(np.diff(res.contact_radius))
                              <= res.xi_bounds[0, 1]]) & (res.load_ratio > 0)
    m = regular & (c_true > 0)
    segments = [regular & (res.segment == g) for g in range(1, len(path))]
    window = _window_max(c_true, res.segment)
    w = regular & (window > 0)
    return {"work": res.work_error_estimate[-1] / true[-1], "flagged": true[flagged],
            "unflagged": true[~flagged], "cover": np.min(c_est[m] / c_true[m]),
            "inflation": max(np.max(c_est[s]) / np.max(c_true[s]) for s in segments
                             if np.any(c_true[s] > 0)),
            "typical": np.median(c_est[w] / window[w])}


WORK_CASES = {  # label: geometry, nu, k, path, keyword arguments
    "sphere cycle": ("sphere", NU, 0.2, (0, 1, 0), {}),
    "cylinder cycle": ("cylinder", NU, 0.3, (0, 1, 0), {}),
    "sphere fretting": ("sphere", NU, 0.2, (0, 1, 0.5, 1, 0.5), {}),
    "cylinder fretting nu=0": ("cylinder", 0.0, 0.2, (0, 1, 0.5, 1, 0.5), {}),
    "sphere viscoelastic": ("sphere", NU, 0.2, (0, 1, 0),
                            {"relaxation": [(0.5, 1.0)], "duration": 1.0}),
}


@pytest.mark.parametrize("case", [pytest.param(c, marks=pytest.mark.slow)
                                  if c != "sphere cycle" else c for c in WORK_CASES])
def test_cycle_work_estimate_is_tight_and_its_flags_mean_an_error(case):
    """n = 120, 50 steps against 480, 200: the cycle work's estimate within a factor 3 of its
    error either way (measured 0.52 ... 1.25, benchmarks/report_history_estimates.py), and a
    step is flagged for the work only if its error, relative to the path's total work, is
    above max_error / 3; an unflagged step's error is below 3 max_error.

    The stick radius's estimate covers its error at every judged step (measured at least
    0.67 of it), a segment's largest estimate is at most 5 times its largest error (measured
    0.97 ... 3.5; 1.7 ... 6.9 when the estimate was |run - A| in full), 10 times on the
    half-plane at nu = 0, whose loading keeps a stick zone of four elements with an edge
    that crosses none (there |run - A| is a bias and is taken in full: 9.9, as before), and
    typically within a factor 2 of the largest error within two steps (median 0.84 ... 1.53;
    in full it was 1.7 ... 2.5).

    (Before the estimate measured its order of convergence it assumed first order and was
    3-4 times the error; relative to the work done so far every step was flagged.)
    """
    geometry, nu, k, path, kwargs = WORK_CASES[case]
    max_error = 1e-2
    out = _against_a_fourfold_refinement(geometry, nu, k, path, kwargs, max_error)
    assert 1 / 3 <= out["work"] <= 3
    assert np.all(out["flagged"] > max_error / 3)
    assert np.all(out["unflagged"] <= 3 * max_error)
    assert out["cover"] >= 1 / 3
    assert out["inflation"] <= (10 if case == "cylinder fretting nu=0" else 5)
    assert 1 / 2 <= out["typical"] <= 2


def test_a_value_that_is_not_finite_is_never_resolved(monkeypatch):
    """A viscous work that is NaN from some step on (as a path of duration 1e-300 tau gave
    before the dashpots' integrals were scaled): those steps and the energies are not
    resolved, whatever the other estimates say."""
    calls = {"n": 0}
    original = hs.viscous_step_work

    def nan_late(*args, **kwargs):
        calls["n"] += 1
        return np.nan if calls["n"] > 30 else original(*args, **kwargs)

    monkeypatch.setattr(hs, "viscous_step_work", nan_late)
    res = history("sphere", NU, 0.2, [0, 1, 0], 20, n=60, relaxation=[(0.5, 1.0)],
                  duration=1.0, max_error=0.9)
    bad = ~np.isfinite(res.viscous_work)
    assert bad.any() and not bad.all()
    assert not res.resolved[bad].any()
    assert np.all(np.isinf(res.energy_error_estimate[bad]))
    assert res.resolved_quantities["energies"] is False


@pytest.mark.parametrize("steps", [40, 100_000])
def test_advice_names_a_run_the_tool_accepts(steps):
    """The advised n and steps are within the limits; where the prediction needs more, the
    message says no accepted run is predicted to resolve it."""
    res = history("sphere", NU, 0.2, [0, 1], min(steps, 40), n=60, max_error=1e-4)
    text = res.message
    if "no accepted run" in text:
        m = re.search(r"n = (\d+), (\d+) steps a segment is predicted to reach", text)
    else:
        m = re.search(r"n = (\d+) with (\d+) steps a segment "
                      r"(?:\(the largest the tool accepts\) )?is predicted to resolve", text)
    assert m, text
    n_new, steps_new = int(m.group(1)), int(m.group(2))
    assert MIN_N <= n_new <= MAX_N and 1 <= steps_new <= MAX_STEPS


def test_advised_run_resolves_what_it_was_advised_for():
    """The measured convergence's prediction holds: sphere k = 0.2, 0 -> 1 -> 0 at n = 60 and
    40 steps with max_error 1e-2 advises a run (work and stick radius not resolved); that run
    resolves the frictional work and the stick radius to 1e-2 (its own estimates)."""
    max_error = 1e-2
    res = history("sphere", NU, 0.2, [0, 1, 0], 40, n=60, max_error=max_error)
    m = re.search(r"n = (\d+) with (\d+) steps a segment "
                  r"(?:\(the largest the tool accepts\) )?is predicted to resolve", res.message)
    assert m, res.message
    again = history("sphere", NU, 0.2, [0, 1, 0], int(m.group(2)), n=int(m.group(1)),
                    max_error=max_error)
    assert again.resolved_quantities["frictional_work"]
    assert again.resolved_quantities["stick_radius"]


@pytest.mark.slow
def test_cycle_work_estimate_covers_a_thin_annulus_on_a_layer():
    """Sphere on a layer, a_max/h = 1 (slip annulus under 12 elements at n = 120): the runs
    are not in the asymptotic range (the measured order falls to the bound 1/2), and the
    work's estimate then errs high (measured 16 times the error), never low; the path is not
    resolved. The stick radius's estimate stays tight there."""
    kwargs = {"slab_ratio": 1.0}
    out = _against_a_fourfold_refinement("sphere", NU, 0.2, (0, 1, 0), kwargs, 1e-2)
    assert out["work"] >= 1 / 3
    # the stick radius's estimate: measured 0.50 of the error at least, a segment's largest
    # 1.2 times its largest error (4.1 times at n = 240 when it was |run - A| in full)
    assert out["cover"] >= 1 / 3 and out["inflation"] <= 3
    res = history("sphere", NU, 0.2, [0, 1, 0], 50, n=120, max_error=1e-2, **kwargs)
    assert not res.resolved_quantities["frictional_work"]


def test_stacked_histories_keep_each_k_s_scales_and_verdicts():
    """The estimate scales and verdicts differ by k: stacking keeps them per k."""
    runs = [history("sphere", NU, k, [0, 1, 0], 10, n=40, max_error=0.05) for k in (0.1, 0.3)]
    ds = stack_histories([history_to_dataset(r) for r in runs])
    np.testing.assert_array_equal(ds["work_scale"].values, [r.work_scale for r in runs])
    np.testing.assert_array_equal(ds["energy_scale"].values, [r.energy_scale for r in runs])
    for k, r in zip((0.1, 0.3), runs):
        verdict = " ".join(q for q, ok in r.resolved_quantities.items() if ok) or "none"
        assert f"k = {k:g}: {verdict}" in ds.attrs["resolved_quantities"]
