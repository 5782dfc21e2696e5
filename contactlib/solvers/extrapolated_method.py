"""The extrapolated method: the default discretization on four nested meshes, extrapolated.

Why
---
The default method's k error has a smooth expansion in the resolution n on
its graded, nested meshes (measured before this method was designed; see
docs/accuracy.md, "The extrapolated method"). With k(n) the default
method's root,

    k(n) = k + A n^-2 + B n^-3 + C n^-4 + ...,

the n^-2 and n^-3 terms of comparable size and opposite sign up to n ~ 500
(which is why the observed order of plain differences drifts from 0.7 to
1.9 for n = 384 ... 2048). Solving at n/8, n/4, n/2 and n on nested meshes
and eliminating the three terms (Richardson with the orders 2, 3, 4) gives
k to at most 6.0e-7 at n = 256 and 7.7e-8 at n = 512 (30 cases, c/a = 0.1
... 0.9, nu = 0 ... 0.45, both geometries, against
``tests/data/frontier_reference.json``), where the default method's own
n = 256 is 1e-5 ... 1.5e-4 off.

Cost
----
Only the finest mesh's operators are computed from the kernels; those of
n/2, n/4, n/8 are restricted from them exactly
(:func:`~contactlib.discretization.operators.restrict_nested`), so the coarse solves cost
small factorizations. The finest level starts Newton's method from the
expansion fitted to the coarse roots (within 2e-6 ... 5e-6 of its own root),
and one factorization with one step of extended-precision refinement
suffices (the error after a refined Newton step is ~0.4 step^2; a second
is taken only when the first exceeds :data:`ONE_STEP`). In a sweep the
coarse levels start from the previous case's level offsets.

Error estimate
--------------
``error_estimate`` is the last correction, |k_234 - k_23| / k, with k_23
the three-level extrapolation of (n/4, n/2, n) and k_234 the reported
value, plus a measured bound of the kernels' quadrature noise on the mesh
(:func:`quadrature_noise`): the true error was 0.1 ... 1.6 times it at c/a
= 1e-4 ... 0.99 (against the reference and the closed forms at
nu = 0.49999), and 3.5 times it in one strongly coupled case (nu = -0.5,
c/a = 0.98, k = 13.6). Where the highest-order term is not smaller than the
n^-2 term at the finest level, the levels are outside the expansion's
range: k is then the finest level's own root and the estimate the largest
difference between levels. The load is extrapolated and estimated the same
way; the frictional work is the finest level's, with the default method's
three-level estimate.

Units: E* = a = R = 1 (see :mod:`contactlib.solvers.default_method`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import energy, validate
from ..estimates import estimate
from .default_method import (AXIS_ROWS_BELOW, EDGE_ROWS_BELOW, NEAR_ROWS_FROM_N,
                             NEAR_ROWS_WIDTH, REFINED_FINAL_STEP, DiscreteSolution, assemble,
                             difference_rows, newton_on_k, solve_default)
from ..discretization.elements import Mesh, graded_mesh
from ..model import Contact
from ..discretization.operators import (StickBlocks, nodal_operators, restrict_nested,
                                        restrict_with_slip_samples, slip_zone_samples)

__all__ = ["ExtrapolatedSolution", "solve_extrapolated", "extrapolate", "ORDERS", "LEVELS",
           "ONE_STEP", "PREDICTED_FROM_N", "NEXT_FROM_N", "LOG_LEVEL_FROM_N",
           "extrapolate_with_log", "LAYER_FLOOR_FROM_N", "N_MULTIPLE", "resolving_n",
           "FINE_QUADRATURE_FROM_N", "quadrature_for", "EXTREMES_FINEST_FROM_N",
           "work_error",
           "quadrature_noise", "NOISE", "NOISE_POWER", "DIFFERENCE_NOISE",
           "DIFFERENCE_NOISE_POWER", "BAND_FROM_N", "BAND_WIDTH", "BAND_NOISE",
           "BAND_NOISE_POWER", "LOG_ESTIMATE_DIVISOR", "LOG_NOISE", "log_noise",
           "LOG_NOISE_POWER", "TRUNCATION_FACTOR", "TRUNCATION_FACTOR_COARSE",
           "truncation_factor",
           "LOG_LEVEL_MAX_OFFSET"]

# exact: the orders of the default method's error expansion, n^-2, n^-3, n^-4 (docs/accuracy.md)
ORDERS = (2.0, 3.0, 4.0)
"""The orders of the default method's error expansion that are eliminated."""

# exact: len(ORDERS) + 1, one level per eliminated order and the finest
LEVELS = 4
"""Nested meshes used: n/8, n/4, n/2, n."""

N_MULTIPLE = validate.EXTRAPOLATED_N_MULTIPLE
"""n must be a multiple of this (both zones' element counts divisible by 8: every level nested)."""

ONE_STEP = REFINED_FINAL_STEP
"""A first Newton step on the finest mesh below this (relative) is final (the default
method's :data:`~contactlib.solvers.default_method.REFINED_FINAL_STEP`: the error after a refined
step is about 0.4 step^2, under 4e-10 here)."""

# tested: tests/test_layer_accuracy.py (the layer's levels' noise, measured below)
LAYER_FLOOR_FROM_N = 512
"""From this finest n on, on a layer whose rows stay plain (the sphere's: ring kernels on a
layer have no cancellation-free w(x) - w(ref) away from the axis, so no band around c),
the estimate is at least the finest level's own (the default method's estimate from the
levels n/4, n/2, n): there the levels carry a noise the expansion in n does not describe
and the half-space's noise bound (:func:`quadrature_noise`) does not cover. Measured
(nu = 0.3, c/a = 0.1, 0.5, 0.7, 0.9, extrapolated k at n = 512, 1024, 2048): the
sphere's smooth layer a/h = 1/20 at c/a = 0.1, k(1024) 6.1e-8 from k(2048) with
estimates of 3e-9 and 4e-9; its bonded layer a/h = 1, 1.6e-7 ... 4.4e-7 apart with
estimates 2e-8 ... 2e-7. The cylinder's slab (band rows) is not concerned: with its
kernels' local coordinate fixed (:mod:`contactlib.kernels.strip`, a noise of 1e-13 that
had put up to 1e-6 into k at n = 2048) its levels agree within their own estimates
(a/h = 1/20 and 1, smooth and bonded base, c/a = 0.3 ... 0.9)."""

# measured: benchmarks/bench_frontier.py (the method's cost: one factorization of the level where it
# took three); tests/test_extrapolated_method.py checks the root
PREDICTED_FROM_N = 1024
"""A coarse level with at least this many elements (the level n/2 of a solve at n >= 2048)
starts, without a caller's guess, from the n^-2 trend of the two coarser levels, k(n/4) +
(k(n/4) - k(n/8)) / 4, and is solved as the finest is: refined steps, one final below
:data:`ONE_STEP`, on a system equilibrated in place. The trend is within a few 1e-7 of the
level's root (sphere, nu = 0.3, c/a = 0.5, n = 2048: 4e-7), so one factorization of the
level suffices where it took three (two plain Newton steps from k(n/4), then a refined
one); from the same n on, the finest level's system is also equilibrated in place (as the
default method's from n = 1024)."""

# measured: benchmarks/report_estimate_coverage.py (error / last correction at most 1.68, 1.29,
# 1.22, 1.15 at n = 128, 256, 512, 768)
TRUNCATION_FACTOR = 1.5
"""The four-level truncation estimate is the last correction (:func:`extrapolate`) times
this (times :data:`TRUNCATION_FACTOR_COARSE` below n = 256). The levels carry an n^-3 ln n
term the four-level fit leaves (:data:`LOG_LEVEL_FROM_N`); where it dominates, the error
is 8/7 of the last correction (the fits' residuals of h^3 ln h on h = 8, 4, 2, 1: 0.563
and 1.056), and below n ~ 500 the n^-4 term lowers the correction further. Against the
five-level k at n = 2048 (sphere and cylinder, nu = 0.4999999, 0.3, 0, -0.5, c/a = 0.1,
0.3, 0.5, 0.7, 0.9, 0.98) the error over the last correction was at most 1.68, 1.29,
1.22 and 1.15 at n = 128, 256, 512 and 768 (cylinder, c/a = 0.5, at the first two),
besides one case outside the expansion's range (:data:`LOG_LEVEL_MAX_OFFSET`). The load's
last correction likewise: at most 1.63, 1.25 and 1.09 at n = 128, 256 and 512 against the
load at n = 2048 (both geometries, nu = 0.3 and -0.5, c/a = 0.1, 0.5, 0.9)."""

# measured: benchmarks/report_estimate_coverage.py (error / last correction up to 1.68 at n = 128)
TRUNCATION_FACTOR_COARSE = 2.0
"""The factor of :data:`TRUNCATION_FACTOR` below n = 256 (error / last correction up to
1.68 at n = 128)."""


def truncation_factor(n: int) -> float:
    """The factor of the four-level k's (and load's) last correction at finest ``n``."""
    return TRUNCATION_FACTOR_COARSE if n < 256 else TRUNCATION_FACTOR


# measured: benchmarks/report_log_extrapolation.py (the n^-3 ln n term the five levels remove)
LOG_LEVEL_FROM_N = 1024
"""From this finest n (half-space bodies, the band of difference rows around c, levels
nested down to n/32) two more levels, n/16 and n/32, are solved (their operators restricted
from n/8, no kernel evaluated; 64 and 32 elements at n = 1024), and k is extrapolated from
the five levels n/16 ... n with an n^-3 ln n term besides n^-2, n^-3 and n^-4
(:func:`extrapolate_with_log`): the levels' roots carry that term, which the four-level
extrapolation leaves as its n^-3 truncation. Its error estimate (:data:`LOG_ESTIMATE_DIVISOR`,
:func:`log_noise`) compares it with the same extrapolation one level down (n/32 ... n/2).
The five-level k and its estimate are taken where that k lies within the four-level
estimate of the four-level k, its estimate is the smaller and the coarsest level is close
enough (:data:`LOG_LEVEL_MAX_OFFSET`); else the four-level k and estimate stay
(``k_four_levels`` either way). Against the closed forms at nu = 0.4999999 (sphere and
cylinder, c/a = 0.003 ... 0.995, n = 1024): four levels 1.2e-9 ... 8.5e-9 off, five 3e-13
... 1.1e-9 (at most 4e-10 for c/a <= 0.98). The estimates, with the noise bound
:data:`LOG_NOISE` measured over ten round-off draws a case, cover the error: at most 0.85
of it over 608 solves at n = 1024 ... 3072 (``python benchmarks/report_estimate_coverage.py``;
one solve a case, ``python benchmarks/report_log_extrapolation.py --estimate``, had shown
0.75 with a bound that 27 of the 608 exceeded)."""

# exact: 2^3 - 1, the divisor of an n^-3 remainder (error / estimate <= 0.69:
# benchmarks/report_log_extrapolation.py --estimate)
LOG_ESTIMATE_DIVISOR = 7.0
"""The five-level k's truncation estimate is |k5(n/2) - k5(n)| / 7, k5(n/2) the same
extrapolation one level down (the levels n/32 ... n/2): exact for a remaining error of
order n^-3; the remaining terms are of higher order (n^-4 ln n: the error fell 12 ... 17
times from n = 512 to 1024), so it overstates. Against the closed forms at nu = 0.4999999,
n = 1024 (both geometries, c/a = 0.003 ... 0.98), error / truncation estimate <= 0.69 where
the truncation dominates; the rest, from n = 1536 on and next to full stick, is the
quadrature noise (:func:`log_noise`)."""

# measured: benchmarks/report_estimate_coverage.py (offsets at most 3.9e-3 but one case, 6.1e-3)
LOG_LEVEL_MAX_OFFSET = 5e-3
"""The five-level k is taken only where the coarsest level n/32 lies within this of it
(relative): beyond, the levels n/32 and n/16 are too far outside the expansion's range
for its higher terms. Measured offsets were at most 3.9e-3 (sphere, nu = 0.4999999,
c/a = 2e-4, n = 1024; 2.5e-3 at c/a = 0.02, nu = -0.5) over nu = -0.5 ... 0.4999999 and
c/a = 2e-4 ... 0.9994, n = 1024 ... 4096, except sphere, nu = -0.5, c/a = 0.98 (k = 13.6):
3.6e-2, 1.6e-2, 8.6e-3, 6.1e-3 at n = 1024, 1536, 2048, 4096, where the five-level k at
n = 1536 lay 1.4e-8 from the values at n = 1024, 2048 and 4096 (which agree within 1.1e-9)
with an estimate of 3.7e-9. The margin is thin (3.9e-3 against 6.1e-3). The four-level
estimate uses the same bound on its coarsest level n/8: beyond, the finest level's own
estimate bounds the last correction (see :data:`TRUNCATION_FACTOR`)."""

# measured: benchmarks/report_estimate_coverage.py (the spread of k over stick ratios 1e-15 apart)
# and benchmarks/report_noise_kernels.py (other BLAS kernels)
LOG_NOISE = 1.5e-12
"""The five-level k's noise bound is ``LOG_NOISE (1 / (c/a) + 1 / (1 - c/a)^LOG_NOISE_POWER)``
(:func:`log_noise`, relative): the round-off the levels' roots keep, measured as the spread
of k over stick ratios 1e-15 apart, which leaves the discretization alone and moves the
round-off (``python benchmarks/report_estimate_coverage.py``). With the band's rows
relative to a cascade of reference nodes (:data:`~contactlib.solvers.default_method.BAND_REF_RATIO`)
it no longer grows with n: sphere and cylinder, nu = 0.4999999, three draws a case, the
standard deviation at n = 1536 and 2048 was 1e-13 (c/a = 0.5), 7e-13 (0.1), 3.6e-12
(0.02), 9e-12 (0.9), 4.5e-11 (0.97) and 8.4e-11 (0.98), the same at n = 1024 (1.05e-10 at
0.98), the bound's 7e-12, 1.7e-11, 7.5e-11, 4.7e-11, 2.9e-10 and 5.3e-10 there. Before the
cascade, with every band row relative to the band's edge, the spread was 1.2e-16 c / h_min
(about eps/2 c / h_min, h_min the smallest element, growing like n^2: 2.8e-9 at c/a = 0.97,
n = 2048) and the bound was 5e-16 max(c/a, 0.1) / h_min. It is also the floor under the
four-level band bound (:func:`quadrature_noise`)."""

# measured: benchmarks/report_estimate_coverage.py (the spread's growth toward full stick, c/a =
# 0.9, 0.97, 0.98)
LOG_NOISE_POWER = 1.5
"""Toward full stick the spread grows like (1 - c/a)^-1.5 (c/a = 0.9, 0.97, 0.98: 9e-12,
4.5e-11, 8.4e-11 over the 1 - c/a of 0.1, 0.03, 0.02); toward c/a = 0 like (c/a)^-1
(3.6e-12 at 0.02 against 7e-13 at 0.1)."""



# measured: benchmarks/bench_frontier.py (the method's cost: one factorization of the level where it
# took three); tests/test_extrapolated_method.py checks the root
NEXT_FROM_N = 512
"""A coarse level with at least this many elements (below :data:`PREDICTED_FROM_N`: the
level n/4 of a solve at n >= 2048, n/2 at n = 1024 ... 1920) starts, without a caller's
guess, from the next coarser level's k, continued by the n^-2 trend where the level below
that is solved too, and is solved with one refined step, final when it moves k by at most
:data:`ONE_STEP` (else refined Newton goes on): k(n/2) - k(n) is about 3 A n^-2 with
(k(n) - k) n^2 / k = A ~ 1 (the default method's expansion), under 1.2e-5 from n = 512.
One factorization of the level where it took three (two plain Newton steps and a refined
one); the same root to the refined step's error, 0.4 step^2 (level roots within 4.7e-11
of the plain path's at n = 2048, 2.4e-10 at c/a = 0.998, sphere and cylinder,
nu = -0.5 ... 0.3)."""

# The kernels' quadrature error (about 1e-11) and the round-off of O(1) displacements,
# amplified by the smallest elements next to c, put noise into each level's k that no
# expansion in n describes. Measured against the closed form at nu = 0.49999 (sharp there:
# the coupling correction is O(beta^2) ~ 4e-10) and against the converged reference at
# c/a = 0.9, both geometries, n = 256 and 512; each constant is the largest of its points.
# Plain rows (1e-4 < c/a < 1 - 5e-4): relative k noise up to NOISE[side] * h_min^-1.5,
# h_min the smallest element (units of a) on the side that holds it, "stick" for
# c/a < 1/2 (c/a = 1e-4 ... 1e-6 with plain rows: 4.5e-7 at h = 2.2e-9, 2.4e-5 at 9e-11,
# 5.5e-5 at 2.2e-11) and "annulus" above (c/a = 0.99 ... 0.9999: 3e-7 at h = 2.3e-7,
# 3.5e-5 at 9.3e-9, 6.8e-4 at 2.3e-9).
# measured: benchmarks/report_noise_kernels.py (plain rows, the largest errors above)
NOISE = {"stick": 4.6e-20, "annulus": 7.5e-17}
# measured: benchmarks/report_noise_kernels.py (the plain rows' growth with 1/h_min)
NOISE_POWER = 1.5
# Difference rows (default_method.difference_rows: c/a <= AXIS_ROWS_BELOW, the stick
# side, or 1 - c/a <= EDGE_ROWS_BELOW, the annulus side), which every level uses as the
# default method does: the noise grows much more slowly, DIFFERENCE_NOISE[side] *
# h_min^-0.5. Stick side, c/a = 1e-8, 1e-6, 1e-4 (h = 9e-13 ... 2.2e-9): largest errors
# 5.7e-5 (sphere, 1e-8, n = 512), 2.4e-6 (sphere, 1e-6, n = 512), 7.4e-8 (1e-4, n = 256);
# annulus side, c/a = 0.9999 and 1 - 1e-5 (h = 9.3e-9 ... 2.3e-10): 1.5e-5 (cylinder,
# 0.9999, n = 512), 1.8e-5 (cylinder, 1 - 1e-5, n = 512). With the plain rows the same
# cases were off by up to 1.3e-3 (sphere, 1e-8) and 9.4e-3 (sphere, 1 - 1e-5, n = 512).
# Checked on points not fitted (c/a = 1e-7, 1e-5, 3e-5, 0.9996, 0.99995, 1 - 5e-6 at
# n = 256 and 384): the stick side's c/a = 1e-7, n = 384 was 2.2 times the bound fitted
# above (sphere: 3.5e-5), so the stick constant is raised to cover it (2.7e-11 -> 6e-11);
# the annulus points lay within 0.64 of theirs.
# Margin for other CPUs (issue 42): the constants above were the largest errors on one
# machine's BLAS kernels; with another kernel (OPENBLAS_CORETYPE=Haswell, as on an AMD EPYC)
# the sphere at c/a = 1e-8, n = 1024 came out at 1.01 of its estimate. Over the kernels
# SkylakeX, Haswell and Sandybridge (python benchmarks/report_noise_kernels.py) the part
# of the error the levels' estimate leaves, (error - levels) / bound, was at most 0.96
# (sphere, 1e-8, n = 1024, Haswell; 0.53 with SkylakeX) and at most 0.5 in every other
# case, so both constants are doubled (6e-11 -> 1.2e-10, 7.2e-10 -> 1.44e-9): that part
# is then at most 0.48 of the bound, a factor 2 for a kernel not tried (the kernels moved
# it by 1.8x between them).
# measured: benchmarks/report_noise_kernels.py ((error - levels) / bound at most 0.96 before the
# doubling)
DIFFERENCE_NOISE = {"stick": 1.2e-10, "annulus": 1.44e-9}
# measured: benchmarks/report_noise_kernels.py (the difference rows' growth with 1/h_min)
DIFFERENCE_NOISE_POWER = 0.5

BAND_FROM_N = NEAR_ROWS_FROM_N  # 512, the default method's (one place)
"""From this finest n on, every level writes the band of rows around c as differences
(:func:`~contactlib.solvers.default_method.difference_rows` with ``band=True``, half-width
:data:`BAND_WIDTH`), the coarse levels below n = 512 included (the default method
writes the band from the same n, :data:`~contactlib.solvers.default_method.NEAR_ROWS_FROM_N`;
it used to start near n = 1500, where the elements next to c became small). Mixed
rows broke the levels' expansion in n at the band's 1e-8-level change of k: at
nu = 0.49999 against the closed form (c/a = 0.02 ... 0.98), the largest errors were
1.8e-7 at n = 1024 (sphere, c/a = 0.98, plain rows on every level) and 8.7e-8 at
n = 2048 (c/a = 0.95, the band on the finest level only); with the band on every level (c/a = 0.001 ... 0.999, both geometries) they
are 9e-9 ... 7.1e-8 at n = 512 (the truncation of the expansion), 1.3e-9 ... 8.7e-9 at
n = 1024 and 1.3e-10 ... 1.4e-9 at n = 2048 for c/a <= 0.95 (up to 4.7e-9 at 0.98 and
0.99, 6.8e-9 at 0.998, 2.2e-8 at 0.999). Below n = 512 the plain rows are kept (bit for
bit as before)."""
BAND_WIDTH = NEAR_ROWS_WIDTH  # 0.001, the default method's (one place)
"""Half-width of the band, in units of min(c, a - c) (the default method's
:data:`~contactlib.solvers.default_method.NEAR_ROWS_WIDTH` was 0.1, now the same). Rows are
equivalent in exact arithmetic whatever the width; in floating point the narrow band was
better at n = 2048
(nu = 0.49999 against the closed form, c/a = 0.02 ... 0.98, largest error): sphere 8.7e-8
(width 0.1, at c/a = 0.95), 2.6e-8 (0.03), 4.5e-9 (0.01), 1.5e-9 (0.003), 1.4e-9
(0.001); half-plane 8.8e-8 (0.1), 1.4e-9 (0.01), 2.9e-9 (0.003), 3.9e-9 (0.001, at
c/a = 0.98; 1.3e-9 at c/a <= 0.95); at
c/a = 0.999 (half-plane) 8.2e-8 (0.003), 2.2e-8 (0.001), 3.1e-8 (0.0003). At nu = 0.3 the
widths 0.001, 0.003 and 0.01 give k within 1.5e-9 of each other (n = 2048)."""
# The noise of k with the band on every level, interior c/a (neither the axis nor the edge
# rows): BAND_NOISE[side] * h_min^-BAND_NOISE_POWER. Fitted against the closed form at
# nu = 0.49999 (sphere and half-plane, c/a = 0.001 ... 0.999, n = 1024 and 2048, width
# 0.001): the part of |error| the truncation estimate leaves, times h_min^0.5, was at most
# 8.1e-13 at c/a < 0.5 ("stick") and 1.64e-12 at c/a >= 0.5 ("annulus"), both at n = 1024
# (at n = 2048: 1.5e-13 and 9.9e-13). The bound at n = 2048 is 2.3e-9 (c/a = 0.5) ...
# 1.2e-8 (c/a = 0.98), above the errors there: the estimate overstates at n = 2048.
# measured: benchmarks/report_noise_kernels.py (fitted at nu = 0.49999, n = 1024, 2048)
BAND_NOISE = {"stick": 1e-12, "annulus": 2e-12}
# measured: benchmarks/report_noise_kernels.py (the band rows' growth with 1/h_min)
BAND_NOISE_POWER = 0.5


@dataclass(repr=False)
class ExtrapolatedSolution(DiscreteSolution):
    """The finest level's nodal solution, with k (and the load) extrapolated.

    ``p`` and ``phi`` are those of the finest mesh (the profiles); ``k`` is
    the extrapolated friction coefficient, ``k_fine`` the finest mesh's own
    root. Units E* = a = R = 1.

    Attributes
    ----------
    levels : tuple of int
        n/8, n/4, n/2, n.
    level_k, level_load, level_work : tuple of float
        k, the load (units of :meth:`Contact.load`) and the frictional work
        on each level (``level_work`` without the finest when the caller
        completes it, see :func:`solve_extrapolated`).
    level_offsets : tuple of float
        k of each coarse level over the extrapolated k, minus 1.
    k_fine : float
        The finest level's own root.
    k_four_levels : float
        k extrapolated from the four levels alone (equal to ``k`` unless a fifth level
        was used, :data:`LOG_LEVEL_FROM_N`).
    log_level_k : tuple of float
        The roots on the levels n/32 and n/16 where they were solved
        (:data:`LOG_LEVEL_FROM_N`; else empty).
    extrapolated_load : float
        The extrapolated load (what :meth:`load` returns).
    error_estimate, load_error_estimate, work_error_estimate : float
        Estimated relative errors of k, of the load and of the work.
    """

    levels: tuple = ()
    level_k: tuple = ()
    level_load: tuple = ()
    level_work: tuple = ()
    k_fine: float = math.nan
    k_four_levels: float = math.nan
    log_level_k: tuple = ()
    level_offsets: tuple = ()
    extrapolated_load: float = math.nan
    error_estimate: float = math.nan
    load_error_estimate: float = math.nan
    work_error_estimate: float = math.nan

    def load(self) -> float:
        """The extrapolated load (units of :meth:`Contact.load`)."""
        return float(self.extrapolated_load)

    def estimates(self) -> dict:
        """The record entries this method sets (load, estimates)."""
        return {"load": float(self.extrapolated_load), "error_estimate": float(self.error_estimate),
                "load_error_estimate": float(self.load_error_estimate),
                "work_error_estimate": float(self.work_error_estimate)}


def extrapolate(values, orders=ORDERS) -> tuple[float, float]:
    """(value, relative error estimate) from values on nested meshes ..., n/4, n/2, n.

    Eliminates ``A n^-p`` for the first len(values) - 1 orders (Richardson).
    The estimate is the last correction: the extrapolation of all levels
    minus that of the finer len(values) - 1 levels without the highest
    order, relative; where the highest-order term is not smaller than every
    lower one at the finest level, the finest value and the largest difference
    between levels instead (outside the expansion's range).
    """
    v = np.asarray(values, dtype=float)
    if not np.all(np.isfinite(v)):
        return math.nan, math.inf
    h = 2.0 ** np.arange(v.size - 1, -1, -1)  # ..., n/4, n/2, n -> ..., 4, 2, 1 (units of 1/n)
    orders = tuple(orders)[:v.size - 1]
    full = np.linalg.solve(np.column_stack([np.ones(v.size)] + [h**p for p in orders]), v)
    part = np.linalg.solve(np.column_stack([np.ones(v.size - 1)] + [h[1:] ** p for p in
                                                                   orders[:-1]]), v[1:])
    value = float(full[0])
    scale = abs(value) if value != 0.0 else 1.0
    # h = 1: the highest-order term against the largest lower one at the finest level (not
    # the n^-2 term alone: its coefficient crosses zero as c/a varies, and at such a c/a
    # the levels are well inside the expansion; cylinder, nu = 0.3, c/a = 0.1945, n = 256:
    # A = -8e-10, B = -1.5e-7, C = 6e-9 fell back to k(256), 7e-7 off, estimate 2.8e-4)
    if v.size > 2 and abs(full[-1]) >= np.max(np.abs(full[1:-1])):
        return float(v[-1]), float(np.max(np.abs(np.diff(v)))) / abs(v[-1] or 1.0)
    return value, abs(value - float(part[0])) / scale


def extrapolate_with_log(values) -> float:
    """k from five nested levels n/16, n/8, n/4, n/2, n: k + A n^-2 + B n^-3 ln n + C n^-3
    + D n^-4 through the five (:data:`LOG_LEVEL_FROM_N`)."""
    v = np.asarray(values, dtype=float)
    h = 2.0 ** np.arange(v.size - 1, -1, -1)  # 16, 8, 4, 2, 1 (units of 1/n): h^3 ln h and
    # h^3 span n^-3 ln n and n^-3
    a = np.column_stack([np.ones(v.size), h**2, h**3 * np.log(h), h**3, h**4])
    return float(np.linalg.solve(a, v)[0])


def log_noise(mesh: Mesh) -> float:
    """Measured bound of the relative round-off noise of k on ``mesh`` (the finest) with the
    band rows: :data:`LOG_NOISE` (1 / (c/a) + 1 / (1 - c/a)^:data:`LOG_NOISE_POWER`) (7e-12 at
    c/a = 0.5, 7.5e-11 at 0.02, 2.9e-10 at 0.97, 5.3e-10 at 0.98, 1.5e-9 at 0.99, whatever
    n; the five-level k's, and a floor under :func:`quadrature_noise`'s band bound)."""
    c, _ = _noise_scales(mesh)
    return LOG_NOISE * (1.0 / c + (1.0 - c) ** -LOG_NOISE_POWER)


def _noise_scales(mesh: Mesh) -> tuple[float, float]:
    """(c/a, the smallest element) of ``mesh``: what every noise bound is a function of."""
    return float(mesh.nodes[mesh.stick_index]), float(np.min(np.diff(mesh.nodes)))


def _halved(mesh: Mesh) -> Mesh | None:
    """The nested mesh with every other node of ``mesh``, None where it has none (an odd
    element count in either zone)."""
    if mesh.n % 2 or mesh.stick_index % 2:
        return None
    return Mesh(mesh.nodes[::2].copy(), mesh.stick_index // 2)


def _log_levels(geometry: Contact, c: float, n: int, mesh: Mesh, ops, sols,
                side: float) -> list[DiscreteSolution]:
    """The levels n/16 and n/32 nested in ``mesh`` (the level n/8, operators ``ops``), for
    :func:`extrapolate_with_log` at n and at n/2 (its estimate), coarsest first: as many
    as could be solved (nested, converged, on the side of zero of the level n/8)."""
    found: list[DiscreteSolution] = []
    finer = list(sols)
    for divisor in (16, 32):
        sub = _halved(mesh)
        if sub is None:
            break
        ops = tuple(restrict_nested(op, mesh, odd_parts=())[0] for op in ops)  # no samples
        k2, k1 = finer[0].oriented_k, finer[1].oriented_k
        d = _level(geometry, c, n // divisor, sub, *ops, k2 + 4.0 * (k2 - k1), one_step=False,
                   rows=_rows(geometry, sub, n), reversed_side=side < 0.0)
        if not (_good(d) and d.oriented_k * k2 > 0.0):
            break
        found.insert(0, d)
        finer.insert(0, d)
        mesh = sub
    return found


def _predict(coarse_k, orders=ORDERS) -> float:
    """k on the next finer level from the expansion fitted to the coarse levels."""
    v = np.asarray(coarse_k, dtype=float)
    h = 2.0 ** np.arange(v.size, 0, -1)  # ..., 4, 2 (units of the finest level's 1/n)
    a = np.column_stack([np.ones(v.size)] + [h**p for p in orders[:v.size - 1]])
    coef = np.linalg.solve(a, v)
    return float(coef[0] + sum(coef[1:]))  # at h = 1


def quadrature_noise(mesh: Mesh, difference: bool | None = None, band: bool = False) -> float:
    """Measured bound of the relative k noise from the kernels' quadrature on ``mesh``.

    ``NOISE[side] * h_min^-1.5`` with the plain rows, ``DIFFERENCE_NOISE[side] *
    h_min^-0.5`` with the axis or edge difference rows, ``BAND_NOISE[side] *
    h_min^-0.5`` with the band around c on every level, or :func:`log_noise` where that is
    larger (see :data:`LOG_NOISE`; see :data:`NOISE`,
    :data:`DIFFERENCE_NOISE`, :data:`BAND_NOISE`): negligible (< 2e-9) at c/a = 0.02
    ... 0.98 up to n = 256, 2.3e-9 ... 1.2e-8 at n = 2048, the dominant error at c/a <= 1e-4
    and >= 0.999. ``difference``: whether the rows were the axis or edge differences
    (default: where :func:`~contactlib.solvers.default_method.difference_rows` writes them on a
    half-space, by c/a); ``band``: whether every level wrote the band around c (a solve at
    n >= :data:`BAND_FROM_N`; it applies where neither the axis nor the edge rows do).
    """
    c, h_min = _noise_scales(mesh)
    side = "stick" if c < 0.5 else "annulus"
    if difference is None:
        difference = c <= AXIS_ROWS_BELOW or 1.0 - c <= EDGE_ROWS_BELOW
    if difference:
        return DIFFERENCE_NOISE[side] * h_min ** -DIFFERENCE_NOISE_POWER
    if band:  # (the band rows' round-off: log_noise, see LOG_NOISE)
        return max(BAND_NOISE[side] * h_min ** -BAND_NOISE_POWER, log_noise(mesh))
    return NOISE[side] * h_min ** -NOISE_POWER


def resolving_n(n: int, error: float, max_error: float, max_n: int) -> int | None:
    """The n (a multiple of 64) that the n^-3 convergence says brings ``error`` to max_error/2."""
    if not math.isfinite(error) or error <= 0.0:
        return None
    need = N_MULTIPLE * math.ceil(n * (2.0 * error / max_error) ** (1.0 / 3.0) / N_MULTIPLE)
    return need if need <= max_n else None


# tested: tests/test_extrapolated_method.py (k near full stick against the closed form) and
# tests/test_influence_speedup.py (the fine rules' cost)
FINE_QUADRATURE_FROM_N = 1024
"""From this finest n on, the band of difference rows around c of every level is
integrated with :mod:`contactlib.discretization.influence`'s ``"fine"`` rules (:func:`quadrature_for`);
the operators and the axis and edge rows (c/a <= 1e-4, 1 - c/a <= 5e-4) keep the standard
ones (:func:`~contactlib.solvers.default_method.difference_rows`). A difference row is small
(w(x) - w(ref) is O(|x - ref|)) while the standard classes' bias is a fraction of the
kernels' own scale (up to 1e-10 of a row's largest entry on elements beyond 100 lengths),
so relative to the row it is larger, and near full stick k amplifies it: against the
closed form at nu = 0.4999999, n = 2048, cylinder, c/a = 0.95, 0.98, 0.99, 0.995, the k
error was 1.4e-9, 4.8e-9, -5.7e-9, -2.1e-8 and is 7.6e-10, 1.1e-10, 1.4e-9, 2.1e-9 (the
same with the fine rules on the operators too, and back to the first values with the
fine rules on the operators alone). Over c/a = 0.02 ... 0.98 (sphere and cylinder) the
largest error at n = 2048 fell from 4.8e-9 to 1.1e-9; the sphere moved by at most 1e-10
up to c/a = 0.99 (0.995: 3.0e-9 -> 9.2e-10). The estimate is unchanged: at n = 3072 and
4096 the errors at c/a = 0.98 were 1.2e-9 ... 5.5e-9 with either rule (the band rows'
round-off then, see :data:`LOG_NOISE`). It was 2048 until that round-off was removed
(:func:`~contactlib.solvers.default_method.band_references`); the standard rules' bias then
showed at n = 1536: sphere, nu = 0.4999999, c/a = 0.1 and 0.02, -6.9e-11 and -6.4e-11
against the closed form (the five-level truncation part 2.5e-11 and 2.9e-12), with the
fine rules -2.2e-11 and -1.8e-11. Below n = 1024 the standard rules, where the four-level
truncation dominates."""


# tested: tests/test_extrapolated_method.py (the extremes within their estimate)
EXTREMES_FINEST_FROM_N = 640
"""From this finest n on, at the extremes (the axis or edge difference rows: c/a <= 1e-4
or 1 - c/a <= 5e-4) the solution is the finest level's own, k not extrapolated, with the
default method's estimate from the levels n/4, n/2, n (plus the same noise bound). There
the levels' noise, which grows with n, is larger than the terms the expansion removes,
and the extrapolation amplified it beyond its estimate: against the closed form at
nu = 0.499, sphere, c/a = 1e-8, 1e-7, 1e-6 and 1 - 1e-5, the extrapolated k was off by
2.0e-3, 2.0e-4, 2.1e-5, 2.9e-4 at n = 1024 (estimates 3.8e-4, 9.3e-5, 2.7e-5, 1.1e-4) and
2.7e-3, 1.4e-4, 4.9e-5 at n = 2048 (4.2e-4, 8.4e-5, 3.8e-5), the finest level's own k by
9.8e-4, 1.2e-4, 2.2e-5, 1.9e-4 and 1.5e-3, 1.3e-4, 3.4e-5, each within the default
method's estimate (error / estimate 0.98 at most); at c/a = 1e-5, 1e-4 and 0.9999 the
extrapolation gained nothing either (sphere, n = 1024: 4.6e-6, 1.6e-6, 3.1e-5 against
7.3e-7, 2.0e-6, 1.3e-5). The noise bound of these rows (:data:`DIFFERENCE_NOISE`) was
fitted at n = 256 and 512, where the extrapolated k stays within its estimate; at
n = 768 and 896 it did not either (nu = 0.4999999, sphere, c/a = 1e-8, 1e-7: 4.6x and
3.4x, 4.1x and 3.3x short), hence the first n above the fit."""


def quadrature_for(n: int) -> str:
    """The element rules of the band rows of a solve at finest ``n``
    (:data:`FINE_QUADRATURE_FROM_N`)."""
    return "fine" if n >= FINE_QUADRATURE_FROM_N else "standard"


def _fine_ops(geometry: Contact, mesh: Mesh, ops, cache: StickBlocks | None):
    if ops is not None:
        return ops
    return nodal_operators(geometry, mesh, cache=cache)


def _level(geometry: Contact, c: float, n: int, mesh: Mesh, pw: np.ndarray, qw: np.ndarray,
           k0: float, one_step: bool, rows: tuple = (None, None),
           refine: bool = True, reversed_side: bool = False) -> DiscreteSolution:
    """One level: Newton on k from k0, the last step with extended-precision refinement.

    ``one_step``: k0 is within a few 1e-6 of the root (the finest level, and the
    level n/2 started from the trend: :data:`PREDICTED_FROM_N`), and one refined step
    is final when it moves k by at most :data:`ONE_STEP` (from
    :data:`PREDICTED_FROM_N` elements in one Newton call, the system equilibrated in
    place).
    Otherwise Newton runs plainly (refining only where it stagnates) and one
    refined step follows (``refine``; without it the round-off of a coarse
    level reached 2.7e-6 in k at nu = -0.5, c/a = 0.98, n = 256, k = 13.6). ``rows``:
    the difference rows of :func:`~contactlib.solvers.default_method.difference_rows` on ``mesh``
    (the default method's own; (None, None): the plain rows). The ordinary case (a root
    with the slip against the shear, converged) is finished here; anything else is
    handed to :func:`solve_default` on the same operators, which says what went wrong.
    ``reversed_side``: k0 is relative to sign(beta) (``DiscreteSolution.oriented_k``),
    negative because the levels already solved slip against it (outward on a layer);
    a root found on that side is then handed over as :func:`solve_default`'s start,
    which judges it (the reversed-slip checks and message live there) in one step.
    """
    system = assemble(geometry, mesh, pw, qw, *rows)
    sigma = -1.0 if geometry.slip_sign < 0 else 1.0
    k_start = sigma * k0
    iterations = 0
    if one_step and mesh.n >= PREDICTED_FROM_N:  # one call: the system equilibrated in
        # place (no scaled copies; it is not used again but for the residual), refined
        # steps, the first below ONE_STEP final (the default method's one-step solve)
        newton = newton_on_k(system, k_start, refine=True, refine_derivative=False,
                             final_step=ONE_STEP, overwrite=True)
    else:
        if not one_step:
            newton = newton_on_k(system, k_start, refine=False)
            iterations = newton.iterations
            if newton.converged:
                k_start = newton.k
        if one_step or (newton.converged and refine):
            newton = newton_on_k(system, k_start, max_iter=1, refine=True,
                                 refine_derivative=False)
            if not newton.converged:
                if abs(newton.k - k_start) <= ONE_STEP * abs(newton.k):
                    newton.converged = True
                else:
                    newton = newton_on_k(system, newton.k, refine=True,
                                         refine_derivative=False)
            newton.iterations += iterations
    k = newton.k
    if not (newton.converged and np.isfinite(k) and k * sigma > 0.0):
        guess = k0 if reversed_side else abs(k0)
        if np.isfinite(k):  # where Newton ended: a root on the other side of zero, judged
            # there in one step, or an iterate it goes on from (from k0 it repeated the
            # same iterations: 13-19 to the same root, or 30 to the same iterate without
            # converging; cylinder, nu = -0.5, c/a = 0.98)
            guess = sigma * k
        return solve_default(geometry, c, n, ops=(pw, qw), k_guess=guess, mesh=mesh)
    nn, m = mesh.n, mesh.stick_index
    x = newton.x
    p = np.append(x[:nn], 0.0)
    phi = np.zeros(nn + 1)
    phi[1:m] = x[nn + 1:nn + m]
    if not geometry.indenter.odd_shear:
        phi[0] = phi[1]
    phi[m:nn] = k * p[m:nn] / system.shape[m:nn]
    with np.errstate(invalid="ignore"):  # see operators(): du/dx on a strip axis
        nodal_u, nodal_du = pw[1] @ p + qw[1] @ phi, pw[2] @ p + qw[2] @ phi
    if geometry.indenter.odd_shear:  # du/dx on the strip axis: unused (see operators)
        nodal_du[0] = 0.0
    return DiscreteSolution(geometry, mesh, p, phi, float(x[nn]), float(sigma * k), True,
                            system.residual(x, k), newton.iterations, "", nodal_u, nodal_du,
                            float(newton.stagnated))


# convention: as the default method's warm start, which solves n = 64 first
START_N = 64
"""Without a starting k, the first level solved is the coarsest with at least this many
elements, from the uncoupled closed form (as the default method's own warm start, which
solves n = 64 from it: where the coupling is strong, e.g. nu = -0.5, c/a = 0.98 with
k = 13.6, the closed form is far off and a coarser mesh can land on another root); the
finer coarse levels follow from it, then the coarser ones. No kernel is evaluated for
this start: every level's operators are restricted from the finest mesh's."""


def _band(n: int) -> bool | None:
    """``difference_rows``'s ``band`` for every level of a solve at finest ``n``."""
    return True if n >= BAND_FROM_N else None


def _rows(geometry: Contact, mesh: Mesh, n: int) -> tuple:
    """The difference rows of a level's ``mesh`` in a solve at finest ``n``: every level's
    alike (the band from :data:`BAND_FROM_N`, its element rules :func:`quadrature_for`)."""
    return difference_rows(geometry, mesh, band=_band(n), width=BAND_WIDTH,
                           quadrature=quadrature_for(n))


def _next_on_trend(k: float, k_coarser: float) -> float:
    """k on the next finer level from the n^-2 trend of a level and the one below it."""
    return k + (k - k_coarser) / 4.0


def _trend_start(ns, sols, i: int) -> bool:
    """Whether coarse level i starts from the two coarser levels' trend (one refined step,
    :data:`PREDICTED_FROM_N`): large enough, and both coarser levels solved well."""
    return (i < len(ns) - 1 and ns[i] >= PREDICTED_FROM_N and i >= 2
            and _good(sols[i - 1]) and _good(sols[i - 2]))


def _next_start(ns, sols, i: int) -> bool:
    """Whether coarse level i starts from the next coarser level's k (one refined step,
    :data:`NEXT_FROM_N`): large enough, that level solved well, not a trend start."""
    return (i < len(ns) - 1 and ns[i] >= NEXT_FROM_N and i >= 1 and _good(sols[i - 1])
            and not _trend_start(ns, sols, i))


def _good(d: DiscreteSolution | None) -> bool:
    return d is not None and d.converged and bool(np.isfinite(d.k)) and d.k > 0.0


def _level_order(ns, guess: bool) -> list[int]:
    """The order in which the levels are solved (indices, coarsest = 0, finest last)."""
    coarse = list(range(len(ns) - 1))
    if guess:
        return coarse + [len(ns) - 1]
    first = next((i for i in coarse if ns[i] >= START_N), coarse[-1])
    return coarse[first:] + coarse[:first][::-1] + [len(ns) - 1]


def _start(geometry: Contact, c: float, mesh: Mesh, sols, i: int) -> float:
    """Newton's start on level i without a guess: from the finer levels solved, else the
    uncoupled closed form at the stick edge.

    Relative to sign(beta) (``DiscreteSolution.oriented_k``): negative when the levels
    solved slip against it (outward on a layer; on a half-space it is their k). Where the
    two coarser levels found no solution but ended on roots (beyond c*, reversed and
    tensile), those continued one halving (:func:`_root_trend`): from the closed form the
    level 768 of a solve at n = 1536 (cylinder, nu = -0.5, c/a = 0.98) wandered through 60
    steps without a root; from 13.4 and 22.2 continued it ends on its own, 38.4.
    """
    finer = [s.oriented_k for s in sols[i + 1:-1] if _good(s)]
    if len(finer) >= 2:  # the n^-2 trend of the two next finer levels, continued one level
        return finer[0] + 4.0 * (finer[0] - finer[1])
    if finer:
        return finer[0]
    below = _start_from_below(sols[:i])
    if below is not None:
        return below
    return float(geometry.uncoupled_friction(mesh.nodes[mesh.stick_index]))


def _retry_failed_levels(geometry: Contact, c: float, ns, meshes, opss, odds, sols) -> None:
    """Solve again, from the next coarser good level, a coarse level that failed.

    Without a guess the first level starts from the uncoupled closed form. Next to
    full stick at strong coupling that start can be far from the root and Newton
    lands on another one (sphere, nu = 0, c/a = 0.998, k = 4.85: the level n = 64
    from k = 1.10 ended on a tensile reversed root while n = 32 and 16 converged).
    The coarser level's k, continued by the n^-2 trend of the two below it, starts
    such a level anew. Then a level still failed whose next finer level is good starts
    from the finer levels (:func:`_start`): the coarsest level solved first has no
    coarser one (sphere, nu = -0.5, c/a = 0.98, n = 1024: the level n = 128 from the
    closed form failed while n = 256 and 512 converged, and k was not extrapolated).
    Levels that converged are not touched.
    """
    for j in range(1, len(sols) - 1):
        if _good(sols[j]) or not _good(sols[j - 1]):
            continue
        below = sols[j - 1].oriented_k
        k0 = _next_on_trend(below, sols[j - 2].oriented_k) if j > 1 and _good(sols[j - 2]) \
            else below
        _retry(geometry, c, ns, meshes, opss, odds, sols, j, k0)
    for j in range(len(sols) - 3, -1, -1):  # from the finer levels, finest first
        if not _good(sols[j]) and _good(sols[j + 1]):
            _retry(geometry, c, ns, meshes, opss, odds, sols, j,
                   _start(geometry, c, meshes[j], sols, j))


def _retry(geometry: Contact, c: float, ns, meshes, opss, odds, sols, j: int,
           k0: float) -> None:
    """Level j solved again from k0 (relative to sign(beta)); kept where it is good."""
    d = _level(geometry, c, ns[j], meshes[j], *opss[j], k0, one_step=False,
               rows=_rows(geometry, meshes[j], ns[-1]), reversed_side=k0 < 0.0)
    if _good(d):
        if odds[j] is not None:  # as for every level: u, du/dx inside its slip elements
            d.interior_samples = slip_zone_samples(odds[j], d.p, d.phi)
        sols[j] = d


def _start_from_below(coarse) -> float | None:
    """Newton's start (relative to sign(beta)) on a level from the levels ``coarse`` below
    it (None where not solved yet): the finest good one's k; without one, the roots the
    two finest ended at where they are not solutions (beyond c*: reversed roots with
    tensile pressure, growing with n), continued geometrically; else None. A coarse level
    then starts from the closed form (:func:`_start`); the finest, when a coarse level
    failed, from the default method's own start.

    Cylinder, nu = -0.5, c/a = 0.98 lies beyond c*: every level ends on such a root, whose
    |k| grows about 1.6 times a halving of the elements (6.7, 10.2, 16.4 at n = 64, 128,
    256, 27.8 at 512); from the uncoupled closed form (1.27) the finest level took 19
    Newton steps to it, each a factorization of the largest system, and 5 from the trend.
    The levels n/4 and n/2 are continued one halving (as every level is from the two below
    it, :func:`_start`). Over two halvings it worked once (from 13.4 and 22.2 at n = 192
    and 384 to 61.5 at 1536, 7 steps to its root 68.0, before the level 768 found its own);
    over three it failed: from n = 64 and 128 (10.2 x 1.5^3 = 35 at n = 1024) Newton did
    not converge in 30 steps to the root 48.5.
    """
    good = [s.oriented_k for s in coarse if _good(s)]
    if good:
        return good[-1]
    return _root_trend([getattr(s, "newton_root", math.nan) for s in coarse[-2:]])


def _root_trend(pair) -> float | None:
    """The roots (``newton_root``) of two consecutive levels continued to the next finer
    level, geometrically; None unless there are two, finite, on one side of zero and
    growing."""
    if len(pair) < 2:
        return None
    below, last = pair
    if below * last > 0.0 and abs(last) > abs(below):  # (False for NaN)
        return last * (last / below)
    return None


def _work(geometry: Contact, d: DiscreteSolution) -> float:
    xs, ws, q, s = d.slip_samples()
    return float(energy.frictional_work(xs, ws, q, s, geometry.work_factor,
                                        geometry.work_weight_power))


def solve_extrapolated(geometry: Contact, stick_ratio: float, n: int, *,
                       k_guess: float | None = None,
                       ops: tuple[np.ndarray, np.ndarray] | None = None,
                       cache: StickBlocks | None = None,
                       work: bool = True,
                       level_offsets: tuple[float, ...] | None = None,
                       ) -> ExtrapolatedSolution | DiscreteSolution:
    """Solve one stick ratio on the nested meshes n/8, n/4, n/2, n; extrapolate k and the load.

    Parameters
    ----------
    geometry : Contact
    stick_ratio : float
        c/a; 0 and 1 (k exact) are the default method's single solve.
    n : int
        Finest resolution, a multiple of :data:`N_MULTIPLE`.
    k_guess : float, optional
        Newton's start on the coarsest mesh (default: the solver's warm start).
    ops : (P, Q), optional
        The finest mesh's nodal operators (``nodal_operators``).
    cache : StickBlocks, optional
        The caller's store of stick blocks.
    level_offsets : tuple of float, optional
        k of each coarse level relative to the extrapolated k, minus 1, from a
        neighbouring case (``ExtrapolatedSolution.level_offsets``): with
        ``k_guess`` each coarse Newton starts at ``k_guess (1 + offset)``
        (a sweep's continuation: fewer iterations, the same roots).
    work : bool
        Also the frictional work on the finest level and its error estimate;
        without, ``level_work`` holds the coarse levels' only (whose slip
        samples come free from the restricted operators) and the caller
        completes it (:func:`work_error`) from its own samples of the finest.

    Returns
    -------
    ExtrapolatedSolution
        Or, for c/a = 0 or 1, the default method's :class:`DiscreteSolution`.
    """
    c = float(stick_ratio)
    if not 0.0 < c < 1.0:
        return solve_default(geometry, c, n, ops=ops, cache=cache)
    if n % N_MULTIPLE:
        raise ValueError(f"n must be a multiple of {N_MULTIPLE}, got {n}")
    fine = graded_mesh(n, c, store=None if cache is None else cache.meshes)
    pw, qw = _fine_ops(geometry, fine, ops, cache)
    meshes, opss, odds = [fine], [(pw, qw)], [None]
    nested = True
    for _ in range(LEVELS - 1):  # restrict level by level: n/2 from n, n/4 from n/2
        mesh = meshes[-1]
        sub = _halved(mesh)
        if sub is not None:  # every other node: nested
            (pc, qc), odd = restrict_with_slip_samples(opss[-1], mesh)
        else:  # a mesh scaled back to MAX_ELEMENTS: its own operators, not nested
            nested = False
            sub = graded_mesh(n // 2 ** len(meshes), c)
            pc, qc = _fine_ops(geometry, sub, None, cache)
            odd = None
        meshes.append(sub)
        opss.append((pc, qc))
        odds.append(odd)
    meshes, opss, odds = meshes[::-1], opss[::-1], odds[::-1]  # coarsest first
    ns = [n // 2 ** i for i in range(LEVELS - 1, -1, -1)]
    sols: list[DiscreteSolution | None] = [None] * LEVELS
    # the side of zero of k relative to sign(beta) (DiscreteSolution.oriented_k): -1 where
    # the slip runs against it (outward on some layers), then every level starts there;
    # the starts below are built from |k| and take this sign (+1 on a half-space)
    side = -1.0 if k_guess is not None and k_guess < 0.0 else 1.0
    guess = None if k_guess is None else abs(k_guess)
    for i in _level_order(ns, guess is not None):
        if i == LEVELS - 1:  # the finest root predicted from the coarse levels' expansion
            if guess is None:
                _retry_failed_levels(geometry, c, ns, meshes, opss, odds, sols)
            if not all(s.converged for s in sols[:-1]):  # k cannot be extrapolated: the
                # finest level only for its own answer and diagnosis, by the default method
                # at once (a level's own Newton first repeated its failure: cylinder,
                # nu = -0.5, c/a = 0.98, beyond c*: 175 factorizations, 38 s at n = 1024)
                sols[i] = solve_default(geometry, c, n, ops=opss[i], cache=cache,
                                        mesh=meshes[i], k_guess=_start_from_below(sols[:-1]))
                continue
            k0 = side * _predict([s.k for s in sols[:-1]])
        elif guess is not None and level_offsets is not None:  # continuation: each
            # coarse level from the neighbour's offset, corrected by the ratio the coarser
            # level found to its own guess (the guess's error is common to the levels)
            k0 = guess * (1.0 + level_offsets[i])
            if i and _good(sols[i - 1]):
                k0 *= sols[i - 1].k / (guess * (1.0 + level_offsets[i - 1]))
            k0 *= side
        elif guess is not None:
            k0 = side * (sols[i - 1].k if i and _good(sols[i - 1]) else guess)
        elif _trend_start(ns, sols, i):
            k0 = _next_on_trend(sols[i - 1].oriented_k, sols[i - 2].oriented_k)
        elif _next_start(ns, sols, i):  # the trend where two coarser levels are good
            k0 = sols[i - 1].oriented_k
            if i >= 2 and _good(sols[i - 2]):
                k0 = _next_on_trend(k0, sols[i - 2].oriented_k)
        else:
            k0 = _start(geometry, c, meshes[i], sols, i)
        near = (i == LEVELS - 1 or (level_offsets is not None and guess is not None and i > 0)
                or (guess is None and (_trend_start(ns, sols, i) or _next_start(ns, sols, i))))
        rows = _rows(geometry, meshes[i], n)
        if i == LEVELS - 1:  # the noise of the finest level's rows (see quadrature_noise)
            difference = rows != (None, None) and (c <= AXIS_ROWS_BELOW
                                                   or 1.0 - c <= EDGE_ROWS_BELOW)
            band = rows[1] is not None and not difference
        d = _level(geometry, c, ns[i], meshes[i], *opss[i], k0, one_step=near, rows=rows,
                   reversed_side=side < 0.0)
        if _good(d) and d.oriented_k < 0.0:  # the levels after it start on its side
            side = -1.0
        if odds[i] is not None:
            d.interior_samples = slip_zone_samples(odds[i], d.p, d.phi)
        sols[i] = d
    top = sols[-1]
    out = ExtrapolatedSolution(**{f: getattr(top, f) for f in (
        "geometry", "mesh", "p", "traction", "delta", "k", "converged", "residual_norm",
        "iterations", "message", "nodal_u", "nodal_du", "round_off")})
    out.iterations = sum(s.iterations for s in sols)
    out.levels = tuple(ns)
    out.level_k = tuple(float(s.k) for s in sols)
    out.level_load = tuple(float(geometry.load(s.mesh.nodes, s.p)) for s in sols)
    out.k_fine = float(top.k)
    out.k_four_levels = float(top.k)  # (the four-level value once extrapolated, below)
    if not all(s.converged for s in sols):
        bad = ", ".join(str(m) for m, s in zip(ns, sols) if not s.converged)
        out.converged = False
        out.error_estimate = out.load_error_estimate = out.work_error_estimate = math.inf
        out.extrapolated_load = out.level_load[-1]
        out.message = "; ".join(x for x in [top.message, f"the nested level n = {bad} did not "
                                            "converge: k not extrapolated"] if x)
        return out
    if nested:
        factor = truncation_factor(n)
        out.k, out.error_estimate = extrapolate(out.level_k)
        out.extrapolated_load, out.load_error_estimate = extrapolate(out.level_load)
        out.error_estimate *= factor
        out.load_error_estimate *= factor
        if abs(out.level_k[0] / out.k - 1.0) > LOG_LEVEL_MAX_OFFSET:  # the coarsest level
            # too far outside the expansion's range for its last correction (sphere,
            # nu = -0.5, c/a = 0.98, n = 256: n/8 3.6e-2 off, error 5.3e-6 against 2.2e-6):
            # the finest level's own estimate bounds it
            out.error_estimate = max(out.error_estimate, _finest_level_error(out.level_k))
        if not out.k * top.k > 0.0:  # levels far outside the expansion (sphere, nu = 0,
            # c/a = 0.999, n = 128: k = 94, 471, 4624, 1202 extrapolated to -1293): the
            # finest level's root, the largest difference between levels its estimate
            out.k = top.k
            out.error_estimate = float(np.max(np.abs(np.diff(out.level_k)))) / abs(top.k)
        if difference and n >= EXTREMES_FINEST_FROM_N:  # noise beyond the expansion: the
            # finest level's own root and the default method's estimate (see the constant)
            out.k = top.k
            out.error_estimate = _finest_level_error(out.level_k)
            out.extrapolated_load = out.level_load[-1]
            out.load_error_estimate = _finest_level_error(out.level_load)
    else:  # the expansion in n needs nested levels: the finest level, its differences
        out.error_estimate = float(np.max(np.abs(np.diff(out.level_k)))) / abs(top.k)
        out.extrapolated_load = out.level_load[-1]
        out.load_error_estimate = float(np.max(np.abs(np.diff(out.level_load)))) / out.extrapolated_load
        out.message = "; ".join(x for x in [top.message, "the meshes are not nested (scaled "
                                            "back to the largest element count): k not "
                                            "extrapolated"] if x)
    # the levels' Newton round-off floors (refined: ~1e-10) and the quadrature noise of
    # the smallest elements add to the estimate
    out.error_estimate += (2.0 * max(s.round_off for s in sols)
                           + quadrature_noise(top.mesh, difference=difference, band=band))
    if (not geometry.body.is_half_space and not (band or difference)
            and n >= LAYER_FLOOR_FROM_N):  # plain rows on a layer: see LAYER_FLOOR_FROM_N
        out.error_estimate = max(out.error_estimate, _finest_level_error(out.level_k))
    out.k_four_levels = out.k
    if (nested and n >= LOG_LEVEL_FROM_N and band and geometry.body.is_half_space
            and out.k != top.k and np.isfinite(out.error_estimate)):
        extra = _log_levels(geometry, c, n, meshes[0], opss[0], sols, side)
        out.log_level_k = tuple(float(d.k) for d in extra)
        out.iterations += sum(d.iterations for d in extra)
        if len(extra) == 2:  # k at n and, for its estimate, at n/2 (levels n/32 ... n/2)
            k5 = extrapolate_with_log(out.log_level_k[1:] + out.level_k)
            k5_half = extrapolate_with_log(out.log_level_k + out.level_k[:-1])
            estimate5 = (abs(k5_half / k5 - 1.0) / LOG_ESTIMATE_DIVISOR
                         + 2.0 * max(d.round_off for d in [*sols, *extra])
                         + log_noise(top.mesh))
            if (abs(k5 / out.k - 1.0) <= out.error_estimate and estimate5 < out.error_estimate
                    and abs(out.log_level_k[0] / k5 - 1.0) <= LOG_LEVEL_MAX_OFFSET):
                out.k, out.error_estimate = k5, estimate5
    out.level_offsets = tuple(float(s.k) / out.k - 1.0 for s in sols[:-1])
    if work:
        out.level_work = tuple(_work(geometry, s) for s in sols)
        out.work_error_estimate = work_error(out.level_work)
    else:  # the coarse levels' work (their slip samples are free); the caller adds the finest
        out.level_work = tuple(_work(geometry, s) for s in sols[:-1])
    return out


def work_error(level_work) -> float:
    """Relative error estimate of the finest level's work from its n/4, n/2, n levels: the
    default method's (:func:`contactlib.estimates.estimate`)."""
    return _finest_level_error(level_work)


def _finest_level_error(values) -> float:
    """The default method's relative error estimate of the last of ``values`` (levels ...,
    n/4, n/2, n) from its last three (:func:`contactlib.estimates.estimate`)."""
    return float(estimate(*tuple(values)[-3:])[0])
