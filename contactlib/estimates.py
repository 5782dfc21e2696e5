"""Error estimates from nested refinements: the a posteriori check of a solver's value.

A leaf of the numerics (numpy only): :mod:`contactlib.accuracy` checks the default
method's k with it, and :mod:`contactlib.solvers.extrapolated_method` its levels' work.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["estimate"]


def estimate(k_quarter: float, k_half: float, k_full: float) -> tuple[float, float]:
    """(relative error estimate of k_full, order used) from nested n/4, n/2, n.

    With d1 = k(n/4) - k(n/2), d2 = k(n/2) - k(n) and r = d1/d2: in the
    asymptotic range (2 <= r <= 4, observed order 1 ... 2) the error of k(n)
    is |d2| / (2^p - 1) with p = log2(r). Otherwise the solutions are not in
    their asymptotic range:

    * 0 <= r < 2 (the differences do not shrink at first order): the larger
      difference, max(|d1|, |d2|), which bounds an error that is not yet
      converging;
    * r > 4 or r < 0 (d2 smaller than the method's n^-2 predicts from d1,
      or of the other sign: the coarse error crossed zero, or two levels
      agree by chance; sphere, c/a = 0.5 at 32/64/128: r = 91; cylinder,
      c/a = 0.9999 at 16/32/64: r = 1075): the three levels are fitted with
      the two leading terms of the expansion, k(h) = k + a h^2 + b h^3
      (h = 4, 2, 1), b = (d1 - 4 d2)/28, a = (d2 - 7 b)/3, and the error of
      k(n) is bounded by |a| + |b|, the size of each term, so that their
      cancellation at level n hides nothing. It is |d2|/3 at r = 4 and
      |d2|/7 at r = 8 (a pure h^2 or h^3 error, exactly), continuous with
      Richardson at r = 4. Taking |d2|/3 there (p clipped at 2, as before)
      under-covered the error 11x and 280x in those two cases.

    Measured coverage: docs/accuracy.md; tests/test_error_estimate.py.
    """
    d1, d2 = k_quarter - k_half, k_half - k_full
    if not all(np.isfinite([k_quarter, k_half, k_full])) or k_full == 0.0:
        return math.inf, math.nan
    if d2 == 0.0:
        return abs(d1) / 3.0 / abs(k_full), math.nan
    ratio = d1 / d2
    if ratio < 0.0 or ratio > 4.0:  # not asymptotic: the two leading terms h^2, h^3
        b = (d1 - 4.0 * d2) / 28.0  # h^3 term at level n
        a = (d2 - 7.0 * b) / 3.0  # h^2 term at level n
        return (abs(a) + abs(b)) / abs(k_full), math.nan
    if ratio < 2.0:
        return max(abs(d1), abs(d2)) / abs(k_full), math.nan
    p = float(np.log2(ratio))
    return abs(d2) / (2.0**p - 1.0) / abs(k_full), p
