"""Error estimates from nested refinements: the a posteriori check of a solver's value.

A leaf of the numerics (numpy only): :mod:`contactlib.accuracy` checks the default
method's k with it, and :mod:`contactlib.solvers.extrapolated_method` its levels' work.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["estimate", "coated_estimate", "edge_zone_resolved", "COATED_ORDER",
           "EDGE_ELEMENT_OVER_THICKNESS"]

# measured: benchmarks/report_coated_estimates.py (ratios of successive differences at n = 256,
# 512, 1024 on coated bodies: k 3.04 ... 9.2, the load 3.20 ... 4.93; below only the sphere's
# k at a/h = 1000, 2.17 and a sign change, not resolved by these levels)
COATED_ORDER = 1.6
# measured: benchmarks/report_coated_estimates.py (the floor of COATED_ORDER covers wherever the
# coarsest level's edge element is below 4 h; at 5.2 h it fell short, 0.93x: cylinder, E2/E1 =
# 1e3, a/h = 300, n = 128, the load): the edge element below 2 h resolves the edge zone
EDGE_ELEMENT_OVER_THICKNESS = 2.0


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


def edge_zone_resolved(nodes: np.ndarray, thickness: float) -> bool:
    """Whether the mesh's contact-edge element is below EDGE_ELEMENT_OVER_THICKNESS x h.

    Parameters
    ----------
    nodes : ndarray
        The mesh's nodes on [0, 1] (units of the contact radius a), the contact edge last.
    thickness : float
        The coating's thickness h/a.

    Within about h of the edge the tractions of a coated body leave their thin-layer form
    (the edge zone). Until the coarsest of the nested levels has its edge element near h,
    the levels straddle that zone: their differences change sign, stall or drop tenfold
    from one level to the next, and no three of them give an order (coated cylinder, E2/E1
    = 0.01, a/h = 1000, n = 64: error 7.9e-4, Richardson 8.7e-5).
    """
    return bool(nodes[-1] - nodes[-2] < EDGE_ELEMENT_OVER_THICKNESS * thickness)


def coated_estimate(v_quarter: float, v_half: float, v_full: float,
                    edge_resolved: bool) -> float:
    """Relative error estimate of ``v_full`` on a coated body, from nested n/4, n/2, n.

    :func:`estimate` assumes that the order observed over the three levels holds beyond
    them. On a coated body it does not: the coating's thickness h is a second length, and
    the levels' differences fall fast while the mesh resolves the edge zone of width ~h,
    then slow down to the asymptotic order (ratios 7 ... 18, then 3.3 ... 4.7). Hence:

    * ``edge_resolved`` (:func:`edge_zone_resolved` of the coarsest level): the larger of
      :func:`estimate` and |d2| / (2^p - 1) with p = :data:`COATED_ORDER`, the lowest order
      measured past the edge zone;
    * otherwise (pre-asymptotic): the larger of :func:`estimate` and 2 |d2|, what the next
      two refinements bring where the differences stall (ratio 1.0 ... 1.4 measured) rather
      than contract; where they change sign (d2 small by chance) :func:`estimate`'s two-term
      fit is the larger.

    Relative to |v_full|; inf where a value is not finite or v_full is 0 with a change.
    Measured coverage of the fourfold-refined difference: docs/validation.md (coatings).
    """
    values = np.array([v_quarter, v_half, v_full], dtype=float)
    if not np.all(np.isfinite(values)):
        return math.inf
    d1, d2 = abs(v_quarter - v_half), abs(v_half - v_full)
    if v_full == 0.0:
        return 0.0 if d1 == d2 == 0.0 else math.inf
    bound = d2 / (2.0**COATED_ORDER - 1.0) if edge_resolved else 2.0 * d2
    return max(estimate(v_quarter, v_half, v_full)[0], bound / abs(v_full))
