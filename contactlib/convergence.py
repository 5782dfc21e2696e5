"""Convergence under refinement: error against time, per method and geometry.

For one geometry and method, :func:`study` solves fixed stick ratios at a
sequence of resolutions n (each twice the last), records per solve the
friction coefficient k, the load ratio, the frictional work and the peak
shear, with the wall time and the peak memory of the solve, and measures the
error of each against a Richardson-extrapolated value from the three finest
resolutions (observed order p = log2 of the ratio of successive differences).
It returns a :class:`Study` (arrays); :func:`contactlib.io.study_to_dataset`
makes it a dataset.

Examples
--------
>>> st = study("sphere", 0.3, "default", [32, 64, 128], [0.5])
>>> float(st.order_of("friction_coefficient")[0]) > 1.5
True
"""

from __future__ import annotations

import time
import tracemalloc
from dataclasses import dataclass
from typing import Callable, Sequence

import numpy as np
import xarray as xr

from . import api
from .model.indenter import indenter

__all__ = ["study", "Study", "trade_table", "QUANTITIES", "richardson", "converged_richardson",
           "MIN_ORDER"]

QUANTITIES = ("friction_coefficient", "load_ratio", "frictional_work", "peak_shear")


@dataclass(frozen=True)
class Study:
    """A convergence study: values, errors and costs on (quantity, n, stick_ratio).

    Attributes
    ----------
    geometry, nu, method, slab_ratio
        The problem, as for :func:`contactlib.solve`.
    base : {"smooth", "bonded"}
        The layer's rigid base (as for :func:`contactlib.solve`; "smooth" on
        the half-space).
    ns : tuple of int
        Resolutions (elements), each twice the previous.
    stick_ratios : tuple of float
        c/a of every case.
    quantities : tuple of str
        :data:`QUANTITIES`: k, P/P_Hertz, the scaled frictional work, max q/p0.
    values : ndarray, shape (quantities, ns, stick_ratios)
        Computed values (dimensionless, docs/conventions.md).
    reference : ndarray, shape (quantities, stick_ratios)
        The values taken as the truth: the Richardson value of the finest triple
        (n, 2n, 4n) whose observed order is at least :data:`MIN_ORDER`
        (:func:`converged_richardson`; finer n are then measured against it).
    observed_order : ndarray, shape (quantities, stick_ratios)
        log2 of the ratio of successive differences of that triple (NaN when no
        triple reaches :data:`MIN_ORDER`).
    error : ndarray, shape (quantities, ns, stick_ratios)
        Relative error against ``reference`` (NaN where it cannot be estimated).
    wall_time : ndarray, shape (ns, stick_ratios)
        Wall time of one solve, s.
    peak_memory : ndarray, shape (ns, stick_ratios)
        Peak traced memory of one solve, MiB.
    reference_source : str
        Where ``reference`` comes from.
    """

    geometry: str
    nu: float
    method: str
    slab_ratio: float
    ns: tuple[int, ...]
    stick_ratios: tuple[float, ...]
    quantities: tuple[str, ...]
    values: np.ndarray
    reference: np.ndarray
    observed_order: np.ndarray
    error: np.ndarray
    wall_time: np.ndarray
    peak_memory: np.ndarray
    reference_source: str
    base: str = "smooth"

    def order_of(self, quantity: str) -> np.ndarray:
        """Observed order of ``quantity`` (one of :attr:`quantities`), one a stick ratio."""
        return self.observed_order[self.quantities.index(quantity)]

    def error_of(self, quantity: str) -> np.ndarray:
        """Relative error of ``quantity``, shape (ns, stick_ratios)."""
        return self.error[self.quantities.index(quantity)]


def richardson(values: np.ndarray) -> tuple[float, float]:
    """Extrapolated limit and observed order from the last three values of a sequence
    computed at n, 2n, 4n.

    Returns (limit, order); the order is NaN (and the limit the finest value)
    when the differences do not shrink monotonically.
    """
    v = np.asarray(values, dtype=float)
    if v.size < 3:
        return float(v[-1]), float("nan")
    d1, d2 = v[-2] - v[-3], v[-1] - v[-2]
    if d2 == 0.0:
        return float(v[-1]), float("inf")
    ratio = d1 / d2
    if not np.isfinite(ratio) or ratio <= 1.0:
        return float(v[-1]), float("nan")
    order = float(np.log2(ratio))
    return float(v[-1] + d2 / (ratio - 1.0)), order


# tested: tests/test_convergence.py (a triple whose differences do not shrink is refused); the
# runaway it guards against was measured at cylinder, slab, c/a = 0.7 (docstring)
MIN_ORDER = 1.0
"""Smallest observed order a triple's Richardson value is taken at (differences shrinking at
least twofold a doubling); below it the triple is outside the asymptotic range or on a
floor, and its extrapolation runs away (cylinder on the slab, nu = 0.3, c/a = 0.7,
n = 1024/2048/4096: order 0.02, a limit 4e-5 off every k computed)."""


def converged_richardson(values: np.ndarray, min_order: float = MIN_ORDER,
                         max_order: float = np.inf) -> tuple[float, float, int]:
    """Richardson value of the finest triple (n, 2n, 4n) whose observed order lies in
    [``min_order``, ``max_order``].

    Returns (limit, order, index of the triple's finest value); (the finest value, NaN,
    last index) when no triple does.
    """
    v = np.asarray(values, dtype=float)
    for end in range(v.size, 2, -1):
        limit, order = richardson(v[:end])
        if min_order <= order <= max_order:
            return limit, order, end - 1
    return float(v[-1]), float("nan"), v.size - 1


def _measure(fn: Callable[[], api.Solution]) -> tuple[api.Solution, float, float]:
    tracemalloc.start()
    t0 = time.perf_counter()
    try:
        sol = fn()
        elapsed = time.perf_counter() - t0
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    return sol, elapsed, peak / 2**20


def study(geometry: str, nu: float, method: str, ns: Sequence[int],
          stick_ratios: Sequence[float], *, slab_ratio: float = 0.0, base: str = "smooth",
          reference: Study | None = None,
          progress: Callable[[str], None] | None = None) -> Study:
    """Solve every (n, c/a) and measure errors against the extrapolated values.

    Parameters
    ----------
    geometry, nu, method, slab_ratio, base
        As for :func:`contactlib.solve`.
    ns : sequence of int
        Resolutions, each twice the previous (at least three for an order).
        For the paper methods every stick ratio must be a multiple of 1/n.
    stick_ratios : sequence of float
        c/a values in (0, 1).
    reference : Study, optional
        Another study of the same problem (same geometry, nu, slab ratio, base
        and stick ratios) whose extrapolated values serve as the truth, e.g. the
        default method's for the paper's scheme, whose k converges too
        slowly and erratically to extrapolate on its own (the workflow reads
        it back with :func:`contactlib.io.study_from_dataset`).

    Returns
    -------
    Study
        Values, errors (relative to the extrapolated value; NaN where it
        cannot be estimated), wall times (s) and peak memory (MiB,
        Python-tracked allocations, i.e. numpy arrays);
        :func:`contactlib.io.study_to_dataset` makes it a dataset.
    """
    ns = [int(n) for n in ns]
    if any(b != 2 * a for a, b in zip(ns, ns[1:])):
        raise ValueError(f"ns must double at every step, got {ns}")
    cs = [float(c) for c in stick_ratios]
    values = np.full((len(QUANTITIES), len(ns), len(cs)), np.nan)
    times = np.full((len(ns), len(cs)), np.nan)
    memory = np.full((len(ns), len(cs)), np.nan)
    for i, n in enumerate(ns):
        for j, c in enumerate(cs):
            sol, times[i, j], memory[i, j] = _measure(lambda: api.solve(
                geometry, nu, stick_ratio=c, n=n, method=method, slab_ratio=slab_ratio,
                base=base))
            values[:, i, j] = (sol.friction_coefficient, sol.load_ratio, sol.frictional_work,
                               float(np.max(np.abs(sol.shear))))
            if progress is not None:
                progress(f"{geometry} {method} n={n} c/a={c}: {times[i, j]:.2f} s")
    ref = np.full((len(QUANTITIES), len(cs)), np.nan)
    order = np.full_like(ref, np.nan)
    for q in range(len(QUANTITIES)):
        for j in range(len(cs)):
            ref[q, j], order[q, j], _ = converged_richardson(values[q, :, j])
    with np.errstate(invalid="ignore", divide="ignore"):
        error = np.abs(values - ref[:, None, :]) / np.abs(ref[:, None, :])
    error = np.where(np.isfinite(order)[:, None, :], error, np.nan)
    ref_source = "own Richardson extrapolation"
    if reference is not None:
        same = (reference.geometry == geometry
                and float(reference.nu) == float(nu)
                and float(reference.slab_ratio) == float(slab_ratio)
                and reference.base == base
                and np.array_equal(np.asarray(reference.stick_ratios), np.array(cs)))
        if not same:
            raise ValueError("reference must be a study of the same geometry, nu, slab ratio, "
                             "base and stick ratios")
        ref = np.asarray(reference.reference)
        with np.errstate(invalid="ignore", divide="ignore"):
            error = np.abs(values - ref[:, None, :]) / np.abs(ref[:, None, :])
        ref_source = f"extrapolated values of the {reference.method} method"
    return Study(geometry=geometry, nu=float(nu), method=method, slab_ratio=float(slab_ratio),
                 ns=tuple(ns), stick_ratios=tuple(cs), quantities=QUANTITIES, values=values,
                 reference=ref, observed_order=order, error=error, wall_time=times,
                 peak_memory=memory, reference_source=ref_source, base=base)


# convention: an order of 0.58, well below the methods' own orders of 2 and more (docs/accuracy.md)
MIN_DIGIT_FALL = 1.5
"""The smallest fall of the median error from n/2 to n for which the trade table gives a
time per digit (an order of 0.58; the method's own orders are 2 and more)."""


def trade_table(datasets: Sequence[xr.Dataset], quantity: str = "friction_coefficient",
                ) -> list[dict[str, object]]:
    """The speed-accuracy trade of every study as table rows, one a resolution.

    Columns: study (geometry, method, a/h), n, the median wall time of one
    solve (s), the median and the largest relative error of ``quantity``
    over the stick ratios, the peak memory (MiB), and "time per digit": the
    factor in time that buys one more correct digit from this n on,
    (t(n) / t(n/2)) ** (1 / log2(e(n/2) / e(n))) with the median errors and
    times of this n and the previous one (empty where the error falls by less
    than :data:`MIN_DIGIT_FALL` a doubling: at a floor, or at the reference's own
    error, the formula's exponent runs away, e.g. 3.8e42 for a fall from 8.37e-8
    to 8.15e-8).
    """
    rows: list[dict[str, object]] = []
    for ds in datasets:
        geometry, method = ds.attrs["geometry"], ds.attrs["method"]
        label = f"{geometry} {method}"
        if indenter(geometry).reports_layer(float(ds.attrs.get("slab_ratio", 0.0))):
            label += f" a/h={float(ds.attrs['slab_ratio']):g}"
            if ds.attrs.get("base", "smooth") != "smooth":
                label += f" {ds.attrs['base']}"
        err = ds["error"].sel(quantity=quantity).values  # (n, stick_ratio)
        times = ds["wall_time"].values
        ns = ds["n"].values
        med_e = np.nanmedian(np.where(np.isfinite(err), err, np.nan), axis=1) \
            if np.isfinite(err).any() else np.full(ns.size, np.nan)
        med_t = np.median(times, axis=1)
        for i, n in enumerate(ns):
            per_digit = float("nan")
            if i > 0 and np.isfinite(med_e[i]) and np.isfinite(med_e[i - 1]) and \
                    0 < med_e[i] * MIN_DIGIT_FALL <= med_e[i - 1] and med_t[i] > 0 and \
                    med_t[i - 1] > 0:
                halvings = np.log2(med_e[i - 1] / med_e[i])  # error falls 2^h per doubling
                per_digit = float((med_t[i] / med_t[i - 1]) ** (np.log2(10.0) / halvings))
            rows.append({
                "study": label, "n": int(n), "time_s": float(med_t[i]),
                "median_error": float(med_e[i]),
                "max_error": float(np.nanmax(err[i])) if np.isfinite(err[i]).any()
                else float("nan"),
                "peak_memory_MiB": float(np.max(ds["peak_memory"].values[i])),
                "time_per_digit": per_digit,
            })
    return rows
