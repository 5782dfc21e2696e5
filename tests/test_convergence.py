"""Richardson extrapolation and the convergence study (error against time)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from contactlib import io
from contactlib.convergence import richardson, study


@pytest.mark.parametrize("order", [1.0, 2.0, 3.5])
def test_richardson_recovers_limit_and_order_of_a_power_law(order):
    n = np.array([16, 32, 64])
    values = 0.7 + 3.0 / n**order
    limit, p = richardson(values)
    assert limit == pytest.approx(0.7, abs=1e-14)
    assert p == pytest.approx(order, rel=1e-12)


def test_richardson_refuses_non_shrinking_differences():
    limit, p = richardson(np.array([1.0, 0.5, 1.5]))
    assert math.isnan(p) and limit == 1.5
    assert math.isnan(richardson(np.array([1.0, 2.0]))[1])


def test_study_rejects_non_doubling_resolutions():
    with pytest.raises(ValueError, match="double"):
        study("sphere", 0.3, "default", [16, 32, 48], [0.5])


@pytest.mark.slow
def test_default_method_errors_shrink_at_order_two_on_the_cylinder():
    """k converges at order 2, approached from below on the two-scale mesh.

    The mesh resolves two lengths (c and a - c) and the contact edge, whose
    errors have different signs: at c/a = 0.3 (a/h = 1/20) the k error
    crosses zero between n = 32 and 64 and the observed order over
    successive triples is 3.6, -, 1.39, 1.75 (n = 32 ... 1024); at 0.8 it is
    0.44, 1.44, 1.71, 1.82. (The earlier mesh showed order 2 from n = 16, but
    missed k at the extremes by up to 61 %.) So the order is measured where
    it is asymptotic, from the finest three of n = 128 ... 1024.
    """
    st = study("cylinder", 0.3, "default", [128, 256, 512, 1024], [0.3, 0.8], slab_ratio=0.05)
    order = st.order_of("friction_coefficient")
    assert np.all((order > 1.7) & (order < 2.7)), order
    err = st.error_of("load_ratio")
    assert np.all(np.isfinite(err[:-1]))
    ds = io.study_to_dataset(st)  # the dataset the workflow writes, and back
    np.testing.assert_array_equal(ds["observed_order"].sel(quantity="friction_coefficient"),
                                  order)
    assert ds["wall_time"].attrs["units"] == "s" and ds.attrs["Conventions"] == "CF-1.10"
    back = io.study_from_dataset(ds)
    assert back.ns == st.ns and back.reference_source == st.reference_source
    np.testing.assert_array_equal(back.error, st.error)


def test_trade_table_time_per_digit_follows_from_order_and_cost():
    """A synthetic study with error ~ n^-2 and time ~ n^3: one digit costs 10^(3/2)."""
    import xarray as xr

    from contactlib.convergence import trade_table

    ns = np.array([64, 128, 256])
    err = 1e-2 * (64.0 / ns)[:, None] ** 2 * np.ones((1, 2))
    ds = xr.Dataset(
        {"error": (("quantity", "n", "stick_ratio"), err[None]),
         "wall_time": (("n", "stick_ratio"), 1e-3 * (ns / 64.0)[:, None] ** 3 * np.ones((1, 2))),
         "peak_memory": (("n", "stick_ratio"), np.ones((3, 2)))},
        coords={"quantity": ["friction_coefficient"], "n": ns, "stick_ratio": [0.3, 0.5]},
        attrs={"geometry": "sphere", "method": "default"})
    rows = trade_table([ds])
    assert [r["n"] for r in rows] == [64, 128, 256]
    assert np.isnan(rows[0]["time_per_digit"])
    for r in rows[1:]:
        assert r["time_per_digit"] == pytest.approx(10 ** 1.5, rel=1e-12)
    assert rows[2]["median_error"] == pytest.approx(1e-2 / 16)


def test_converged_richardson_skips_a_floor():
    # a power law of order 2 that reaches a floor at the finest value: the last triple's
    # differences shrink by only 1.01 (order 0.014: its extrapolation would run away), so
    # the finest triple that converges is used
    from contactlib.convergence import converged_richardson

    n = np.array([64, 128, 256, 512, 1024])
    v = 0.7 + 3.0 / n**2.0
    v[-1] = v[-2] + 0.99 * (v[-2] - v[-3])
    assert 0.0 < richardson(v)[1] < 0.1  # what the last triple alone gives
    limit, order, end = converged_richardson(v)
    assert end == 3 and order == pytest.approx(2.0, rel=1e-9)
    assert limit == pytest.approx(0.7, abs=1e-13)
    # no triple in range: the finest value, NaN
    flat = converged_richardson(np.array([1.0, 0.9, 0.85, 0.84]), min_order=3.0)
    assert math.isnan(flat[1]) and flat[0] == 0.84 and flat[2] == 3


def test_trade_table_leaves_time_per_digit_empty_at_a_floor():
    """An error that falls by less than MIN_DIGIT_FALL a doubling (a floor) buys no digit:
    empty, not (t ratio) ** (1 / log2(1.03)) = 3.8e42 as the formula gives."""
    import xarray as xr

    from contactlib.convergence import MIN_DIGIT_FALL, trade_table

    ns = np.array([64, 128, 256])
    med = np.array([1e-6, 8.37e-8, 8.15e-8])
    ds = xr.Dataset(
        {"error": (("quantity", "n", "stick_ratio"), (med[:, None] * np.ones((1, 2)))[None]),
         "wall_time": (("n", "stick_ratio"), np.array([[1.0], [3.0], [10.0]]) * np.ones((1, 2))),
         "peak_memory": (("n", "stick_ratio"), np.ones((3, 2)))},
        coords={"quantity": ["friction_coefficient"], "n": ns, "stick_ratio": [0.3, 0.5]},
        attrs={"geometry": "sphere", "method": "default"})
    rows = trade_table([ds])
    assert MIN_DIGIT_FALL > 8.37 / 8.15
    assert rows[1]["time_per_digit"] == pytest.approx(3.0 ** (1.0 / np.log10(1e-6 / 8.37e-8)))
    assert np.isnan(rows[2]["time_per_digit"])
