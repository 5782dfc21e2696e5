"""The default method: continuous c/a, piecewise-linear tractions, k from the physics.

Discretization (units E* = a = R = 1)
-------------------------------------
* Pressure p(r): continuous piecewise linear on a mesh with a node at c, graded
  toward c (both sides) and toward a; p(a) = 0 (smooth edge).
* Shear q(r) = shape(r) phi(r) with phi piecewise linear on the same mesh:
  shape = r for the sphere (q ~ r at the axis, as the paper's r/a elements),
  shape = 1 for the cylinder (phi(0) = 0: q is odd in x); q(a) = 0.
* Collocation at every node: w = delta - r^2/2 (normal, delta unknown); in the
  stick zone (nodes 1..M, node M at c) u = C r^2 with C unknown (the
  self-similar adherence condition, paper Eq. 8); for a power-law profile
  (:mod:`contactlib.model.profiles`) w = delta - r^d/d and u = C r^d; in the slip zone (nodes
  M..N-1) q = k p (Coulomb, traction ratio).

With k given, these equations are square; both conditions at c make the
shear continuous and bounded there.

Direction of slip: the slip-zone condition is q = sigma k p with sigma =
sign(beta) (:attr:`~contactlib.model.Contact.slip_sign`): inward slip and
q = k p for beta > 0 (every rigid indenter), outward slip and q = -k p for
beta < 0 (a compliant, compressible indenter on a stiffer, less
compressible body). Newton's method runs on the signed ratio sigma k
(:func:`newton_on_k` is sign-blind); the solution reports k >= 0. A root of
the other sign is kept when the solution is consistent at the nodes (a thin
or nearly incompressible slab, whose surface moves outward under a rigid
indenter); otherwise the slip would change direction within the slip zone,
which one self-similar stick zone cannot hold, and the message says to use
the history solver.

What fixes k
------------
In the exact self-similar problem the traction difference t = q - k p in the
stick zone behaves like B (c - r)^(1/2 + theta) near c, and the slip rate in
the slip zone like -B' (r - c)^(1/2 + theta) (theta -> 0 as k beta -> 0): for
B > 0 the stick zone violates |q| <= k p, for B < 0 the slip near c runs the
wrong way. Only B = 0 is physical; equivalently the *rate* of the stick
traction, t - r t', must vanish at c (no stress-intensity factor in the
incremental problem). On the piecewise-linear mesh this reads t'(c-) = 0,
i.e. t = 0 at the last node inside the stick zone, whose distance to c shrinks
like 1/N^2 on the graded mesh. This is one scalar equation g(k) = 0, solved by
Newton's method with the derivative from the same LU factorization.

The collocation operators (:func:`operator_part`, :func:`operators`,
:func:`nodal_operator_part`) are built by :mod:`contactlib.discretization.operators` and
re-exported here; the model (indenter and body) is a
:class:`~contactlib.model.Contact`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import linalg

from .. import checks
from ..discrete import SelfSimilarSolution
from ..discretization.elements import Mesh, graded_mesh
from ..energy import slip_points
from ..model import Contact
from ..discretization.operators import (StickBlocks, axis_w_rows, nodal_operator_part,
                                        nodal_operators, operator_part, operators,
                                        u_difference_rows)

__all__ = ["DiscreteSolution", "solve_default", "assemble", "difference_rows", "band_references",
           "BAND_REF_RATIO", "BAND_REF_INNER", "start_k",
           "newton_on_k", "REFINED_FINAL_STEP", "PartialSlipSystem", "NewtonResult",
           "operators", "operator_part", "nodal_operator_part"]

try:  # Newton's set-up on large systems compiled (setup.py; optional): the same bits
    from . import solver_fused as _fused
except ImportError:  # pragma: no cover - a build without a C compiler
    _fused = None
FUSED = _fused is not None
"""Whether :func:`newton_on_k` with ``overwrite`` (n >= 1024) equilibrates the system,
forms its first A(k) and computes the extended-precision residuals compiled
(``contactlib/solvers/solver_fused.c``, built by ``pip install``): two passes over the matrix where
numpy makes six, and einsum's own long-double loop without its buffered casts; the same
operations on the same operands, so the same bits (``tests/test_kernels_fused.py``). False
selects the numpy route."""

# Extended precision for the residual of one step of iterative refinement (see
# solve_default): 80-bit on x86-64 Linux; where long double is plain double
# (e.g. Windows, Apple arm64) the step still helps, but k keeps a round-off
# floor of about 1e-5 relative at n = 1024.
_EXTENDED = np.longdouble
# c/a at or below which the stick zone's normal rows are written relative to the axis
# (w(r_i) - w(0), :func:`assemble`): near the axis w is O(1) and its variation O(r^2),
# so the plain rows leave a round-off of ~1e-16/c in the stick-zone pressure, which the
# stick-edge condition amplifies (nu = 0.499, n = 256, c/a = 1e-8: k off by 2.9e-4
# (sphere) and 8.6e-4 (half-plane) instead of 6e-5 and 1.4e-5; c/a = 1e-7: 9e-5; 1e-5:
# 6e-7). Above 1e-4 the plain rows are kept (bit for bit as before, no extra element
# integrals; benchmarks/bench_axis_rows.py).
# measured: benchmarks/bench_axis_rows.py (the rows' cost and k against the closed form at c/a =
# 1e-8 ... 1e-4)
AXIS_ROWS_BELOW = 1e-4
# 1 - c/a at or below which the thin slip annulus's normal rows (nodes beyond r_i0, the
# first node beyond 1 - EDGE_REF_WIDTHS (1 - c/a)) and stick rows are written relative
# to r_i0 (:func:`assemble`): there w and u are O(1) and O(beta) while the annulus's
# tractions act on its width; a perturbation of 1e-16 of the pressure operator moved k by
# 3e-4 (sphere, nu = 0.499, c/a = 1 - 1e-5, n = 256). nu = 0.49999, relative k error at
# n = 64 ... 512, plain rows: 6.4e-5, 2.1e-4, -2.9e-4, 5.7e-3; difference rows: 4.4e-5,
# 1.5e-5, 4.0e-6, 6.1e-6 (half-plane 4.0e-5, 1.3e-5, 1.1e-6, -1.1e-5). Above, the plain
# rows (bit for bit as before).
# measured: benchmarks/bench_axis_rows.py (the rows' cost and k against the closed form near full
# stick)
EDGE_ROWS_BELOW = 5e-4
# measured: benchmarks/bench_axis_rows.py (the annulus's rows, k against the closed form)
EDGE_REF_WIDTHS = 4.0
# High n: where the elements next to c are below NEAR_ROWS_BELOW min(c, a - c) (n >~ 1500;
# never at the default n = 256, whose are ~9e-5 of it), the normal rows within
# NEAR_ROWS_WIDTH min(c, a - c) of c and the stick rows from there to c are written
# relative to the node just inside c - that width (:func:`assemble`, as for the annulus;
# since 2026-11-28 each relative to its own reference, a cascade toward c: BAND_REF_RATIO).
# The measurements below are of the rows relative to that one node.
# Sphere, nu = 0.3, c/a = 0.5, (k(n) - k_inf) n^2 / k_inf with the plain rows: 0.83, 0.83,
# 0.83 at n = 1024, 1536, 2048, then 0.95, 1.86, 0.12, 3.05 at 2560 ... 4096 (k(4096)
# 1.3e-7 off the n^-2 trend); with these rows 0.80, 0.75, 0.73, 0.69, 0.82 at 2048 ... 4096
# (Richardson from 2048/4096 within 2.2e-9 of the plain 512/1024/2048 one). The width
# was 0.1; 0.001 (the extrapolated method's, measured there against the closed forms)
# halves the solve at n = 2048 (sphere, nu = 0.49999, c/a = 0.5: 2.9 -> 1.6 s) and moves
# k by at most 5e-8 (c/a = 0.02 ... 0.98, n = 2048; the method's own error there is
# 1.1e-7 ... 4.1e-7). nu = 0.49999 against the closed form, (k(n) - k_inf) n^2 / k_inf:
# sphere c/a = 0.5 at 2048, 3072, 4096: 1.036, 1.085, 1.730 (width 0.1), 1.023, 1.040,
# 1.045 (0.001); c/a = 0.95 (0.89 ... 1.01 at n = 256 ... 1280, plain rows): 0.77, 1.18,
# 1.43 and 1.00, 1.46, 2.06; half-plane c/a = 0.1 (-0.11 ... -0.06): -0.031, -0.110,
# 0.020 and -0.047, -0.043, -0.092. Neither width keeps the n^-2 trend to 4096 at every
# c/a; the differences, <= 3.6e-8 relative, are below the method's error there.
# measured: benchmarks/bench_axis_rows.py (the band's cost at high n)
NEAR_ROWS_BELOW = 2e-6
# tested: tests/test_sphere.py (k at n = 2048 with the band; the solve at n = 2048:
# benchmarks/bench_frontier.py --b)
NEAR_ROWS_WIDTH = 0.001
# tested: tests/test_extremes.py (the cascade of references; its noise:
# benchmarks/report_estimate_coverage.py)
BAND_REF_RATIO = 2.0
# tested: tests/test_extremes.py (the cascade of references; its noise:
# benchmarks/report_estimate_coverage.py)
BAND_REF_INNER = 2.0
"""The band's rows are written relative to a cascade of reference nodes
(:func:`band_references`): a row within w of c relative to the node just inside c - w,
for the widths w = NEAR_ROWS_WIDTH min(c, a - c) / BAND_REF_RATIO^l down to BAND_REF_INNER
elements next to c. A row relative to one node at the band's edge keeps a round-off of
~eps times its own size, width x slope, which the stick-edge condition amplifies by
about width / h_min: moving the last stick node by 1e-16 c moved the root of a level by
8.5e-11 (cylinder, nu = 0.4999999, c/a = 0.9, n = 1024, one refined Newton step from a
fixed k), and it is the round-off noise of the extrapolated method's k
(:data:`~contactlib.solvers.extrapolated_method.LOG_NOISE`); relative to the cascade, by 1e-12."""
# tested: tests/test_error_estimate.py (near full stick at n >= 512)
NEAR_ROWS_FROM_N = 512
"""From this n on the band of difference rows around c is written at every c/a (as well
as where the elements next to c are below :data:`NEAR_ROWS_BELOW` min(c, a - c), which
first happens near n = 1500). Near full stick the plain rows' round-off grew with n
before the elements' rule switched the band on: nu = 0.49999 against the closed form,
relative k error at n = 512, 768, 1024, 1536 with the plain rows: sphere c/a = 0.999
6.2e-6, -3.6e-5, -1.3e-4, 6.4e-4; half-plane c/a = 0.999 -1.8e-6, -1.7e-5, -7.7e-5,
-1.6e-4; c/a = 0.98 ... 0.995 up to 1.1e-5 (the a-posteriori estimate fell up to 5x
short of these). With the band from n = 512: 1.7e-6, 7.6e-7, 4.3e-7, 2.0e-7 and 1.4e-6,
6.4e-7, 3.6e-7, 1.7e-7, the method's n^-2 (c/a = 0.02 ... 0.999, both geometries: at
most 6.4e-6 at n = 512 and 7.0e-7 at n = 1536). At nu = 0.3 and c/a = 0.02 ... 0.95 the
band moves k by at most 1.7e-7 at n <= 1536 (the plain rows' round-off). The
extrapolated method writes it on every level from the same n
(:data:`~contactlib.solvers.extrapolated_method.BAND_FROM_N`). Below n = 512 the plain rows
are kept: the default n = 256 is bit for bit as before."""


def _near_c_h(r: np.ndarray, m: int) -> float:
    """The smaller of the two elements next to c."""
    return float(min(r[m] - r[m - 1], r[m + 1] - r[m]))
# measured: benchmarks/bench_frontier.py --b (the solve at n = 2048: one factorization fewer);
# tests/test_sphere.py checks the root is Newton's
REFINED_FINAL_STEP = 3e-5
"""A refined Newton step below this (relative) is final: the error after it is about
0.4 step^2 (measured: 1e-5 -> 2e-11 ... 2e-9, 1e-4 -> 1.2e-9 ... 6.2e-9 at c/a = 0.1 ...
0.98, n = 256 and 512; n = 2048: 2.8e-5 -> 1.4e-11 (sphere, c/a = 0.5), 1.2e-5 ->
2.3e-10 (cylinder, 0.9); but n = 512 at c/a = 0.99: 2.7e-9 from a step near 3e-5).
The default method uses it from n = 1024, where its own start (three coarse levels) is
within ~1e-6 (one factorization fewer a solve, where one costs most)."""
# measured: benchmarks/bench_frontier.py --b (the solve at n = 2048: one factorization fewer)
_THREE_LEVEL_START_FROM_N = 1024  # start_k from n = 64, 128, 256 (orders 2 and 3) instead
# of 64 and 128 (order 2): within ~1e-6 of the root instead of 1e-5 ... 3e-5, so that
# one refined step is final (REFINED_FINAL_STEP) where a factorization costs most
# measured: benchmarks/report_reproducibility.py (the main job under other BLAS kernels: k at
# n = 256 agreed to 1e-10 between kernels with the refinement)
_REFINE_FROM_N = 256  # from n = 256 every solve is refined: without it the round-off in k
# was 2.7e-5 at n = 256 (half-plane, nu = 0.3, c/a = 0.9, OpenBLAS Sandybridge kernel; its
# estimate from the levels 3.4e-6, 10x short) where this machine's kernel had 4e-8, and
# the two kernels' k agreed to 1e-10 with it, at no measurable cost (0.07-0.08 s) ...
# ... and whenever Newton's steps stop shrinking on the round-off floor: then the
# iteration goes on with the refinement (nu = 0.3, c/a = 0.99 at n = 128 and 0.9999
# at n = 128 stagnated without it and converge with it)


class DiscreteSolution(SelfSimilarSolution):
    """Nodal solution on a mesh (units E* = a = R = 1), the default method's kind.

    The fields are those of :class:`~contactlib.discrete.SelfSimilarSolution`:
    ``p`` the nodal pressure (p[-1] = 0), ``traction`` the nodal shear
    coefficient phi (q = shape phi, phi[-1] = 0), ``nodal_u``/``nodal_du``
    from the solve's own operators; ``interior_samples`` (a nested coarse
    mesh: its slip elements' fine nodes) replace the midpoints of the slip samples.
    """

    kind = "default"
    newton_root: float = math.nan
    """The root Newton's method on k ended at, relative to sign(beta) (as
    :attr:`oriented_k`), also where it is not a solution and ``k`` is reported NaN (e.g. a
    reversed root with tensile pressure beyond c*); NaN where Newton did not converge. A
    finer mesh of the same case starts from it (the extrapolated method's finest level,
    when no coarse level found a solution)."""

    @property
    def phi(self) -> np.ndarray:
        """The nodal shear coefficient (``traction``)."""
        return self.traction

    @property
    def oriented_k(self) -> float:
        """k relative to sign(beta): ``-k`` when the slip runs against it, else ``k``.

        The reported k is >= 0 whatever the slip direction. On a layer whose
        slip runs against sign(beta) (outward under a rigid indenter) Newton on
        a finer mesh must start on that side: from +k it took 4-5 steps to
        cross zero (sphere, a/h = 20, n = 256 and 1024). The direction is that
        of the shear at the first slip node (q = sign(k) p there).
        """
        m = self.mesh.stick_index
        lead = self.phi[m] if 0 < m < self.mesh.n else np.nan
        reversed_slip = bool(np.isfinite(lead) and lead * self.geometry.slip_sign < 0.0)
        return -self.k if reversed_slip else self.k

    def load(self) -> float:
        """Total load of the piecewise-linear pressure (:meth:`Contact.load`)."""
        return self.geometry.load(self.mesh.nodes, self.p)

    def stick_points(self) -> np.ndarray:
        """Stick-zone nodes inside (0, c) and element midpoints (continuous tractions)."""
        nodes, m = self.mesh.nodes, self.mesh.stick_index
        return np.concatenate([nodes[1:m], 0.5 * (nodes[:m] + nodes[1:m + 1])])

    def pressure(self, x: np.ndarray) -> np.ndarray:
        return np.interp(x, self.mesh.nodes, self.p)

    def shear(self, x: np.ndarray) -> np.ndarray:
        return self.geometry.shear_shape(x) * np.interp(x, self.mesh.nodes, self.phi)

    def slip_samples(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(x, weights, q, s) on the slip zone: its nodes and element midpoints (Simpson).

        s = d u - xi du/dxi is the self-similar slip rate (d the profile's exponent: 2 for
        the paraboloid, where u ~ a^2). At the nodes u and
        du/dxi come free from the solve (``nodal_u``, ``nodal_du``); only the
        midpoints need the exact kernels, one point an element. Simpson's
        rule on the slip elements integrates the work to within 2e-6 relative
        of an 8-point Gauss rule at n = 256 (1e-4 at n = 64), 30 times below
        the method's own error in the work; the slip-direction check sees
        nodes and midpoints.
        """
        return _slip_samples(self)

    def node_flags(self) -> dict:
        """The consistency flags (:func:`contactlib.checks.flags`) at the nodes alone.

        Cheap (no kernel evaluation: u and du/dx at the nodes come from the
        solve); the full check also sees element midpoints. Used to tell a
        physical root of Newton's iteration from another one.
        """
        return _node_flags(self.mesh, self.geometry.shear_shape(self.mesh.nodes) * self.phi,
                           self.p, self.k, self.nodal_u, self.nodal_du,
                           self.geometry.profile.exponent)

    def displacements(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(w, u, du/dx) at points x."""
        pw, qw = operators(self.geometry, self.mesh.nodes, x)
        with np.errstate(invalid="ignore"):  # see operators(): du/dx on a strip axis
            return tuple(pw[i] @ self.p + qw[i] @ self.phi for i in range(3))

    def tangential(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(u, du/dx) at points x, without the normal displacement (cheaper)."""
        pw, qw = operators(self.geometry, self.mesh.nodes, x, with_w=False, rows=(1, 2))
        with np.errstate(invalid="ignore"):  # see operators(): du/dx on a strip axis
            return tuple(pw[i] @ self.p + qw[i] @ self.phi for i in (0, 1))

    def radial_displacement(self, x: np.ndarray) -> np.ndarray:
        """u at points x alone (cheapest: no w, no du/dx)."""
        pw, qw = operators(self.geometry, self.mesh.nodes, x, with_w=False, with_du=False,
                           rows=(1,))
        return pw[0] @ self.p + qw[0] @ self.phi


def _slip_samples(sol: "DiscreteSolution", order: int | None = None):
    """Slip-zone samples: Simpson (nodes + midpoints; default) or Gauss points (order > 0)."""
    r, m = sol.mesh.nodes, sol.mesh.stick_index
    d = sol.geometry.profile.exponent  # s = d u - x du/dx (u ~ a^d at fixed r/a)
    if order is None and sol.nodal_u is not None:
        xn = r[m:]
        h = np.diff(xn)
        if sol.interior_samples is not None:
            mid, u_mid, du_mid = sol.interior_samples  # (the slip zone's elements only)
        else:
            mid = 0.5 * (xn[:-1] + xn[1:])
            u_mid, du_mid = sol.tangential(mid)
        # three-point (quadratic) rule on each element; Simpson's at the midpoint
        t = (mid - xn[:-1]) / h
        wn = np.zeros(xn.size)
        wn[:-1] += h * (3.0 * t - 1.0) / (6.0 * t)
        wn[1:] += h * (2.0 - 3.0 * t) / (6.0 * (1.0 - t))
        xs = np.concatenate([xn, mid])
        ws = np.concatenate([wn, h / (6.0 * t * (1.0 - t))])
        s_nodes = d * sol.nodal_u[m:] - xn * sol.nodal_du[m:]
        ss = np.concatenate([s_nodes, d * u_mid - mid * du_mid])
        return xs, ws, sol.shear(xs), ss
    xs, ws = slip_points(r, m, max(order or 4, 2))
    u, du = sol.tangential(xs)
    return xs, ws, sol.shear(xs), d * u - xs * du


def _node_flags(mesh: Mesh, q: np.ndarray, p: np.ndarray, k: float, nodal_u, nodal_du,
                exponent: float = 2.0) -> dict:
    """Consistency flags at the nodes: stick nodes 1..M-1, slip nodes M..N-1 (k's sign ignored);
    the slip rate is exponent * u - r du/dr (the profile's d)."""
    r, m, nn = mesh.nodes, mesh.stick_index, mesh.n
    if nodal_u is None or nodal_du is None or not np.isfinite(k):
        return {**dict.fromkeys(checks.FLAG_NAMES, False),
                **dict.fromkeys(checks.VIOLATION_NAMES, np.nan)}
    return checks.flags(q[1:m], p[1:m], abs(k), q[m:nn],
                        exponent * nodal_u[m:nn] - r[m:nn] * nodal_du[m:nn])


def _tie_columns(geometry: Contact, q_ops: np.ndarray) -> np.ndarray:
    """Columns for phi_1..phi_{N-1}: phi_0 = phi_1 (rings) or phi_0 = 0 (odd strip shear)."""
    cols = q_ops[..., 1:-1].copy()
    if not geometry.indenter.odd_shear:
        cols[..., 0] += q_ops[..., 0]
    return cols


def _put_shear(tie: bool, q: np.ndarray, m: int, nn: int, shape: np.ndarray,
               stick: np.ndarray, slip: np.ndarray) -> None:
    """Write rows of a shear operator (columns phi_0..phi_N) into the system, in place.

    ``stick[:] = `` the columns of phi_1..phi_{M-1} and ``slip[:] = `` those of
    phi_M..phi_{N-1} divided by the shear shape (phi_i = k p_i / shape_i there), the
    column of phi_1 tied to phi_0 when ``tie`` (:func:`_tie_columns`: the same bits,
    without a tied copy of the whole operator).
    """
    stick[...] = q[:, 1:m]
    np.divide(q[:, m:nn], shape[m:nn], out=slip)
    if tie and m > 1:
        stick[:, 0] += q[:, 0]
    elif tie:  # M = 1: phi_1 is the first slip node
        slip[:, 0] = (q[:, 1] + q[:, 0]) / shape[1]


def _expand_phi(geometry: Contact, f: np.ndarray) -> np.ndarray:
    """Nodal phi (N + 1 values) from phi_1..phi_{N-1}."""
    first = 0.0 if geometry.indenter.odd_shear else f[0]
    return np.concatenate([[first], f, [0.0]])


# numpy's einsum hands a row of a matrix-vector product over in runs of at most this many
# elements (its fixed buffer, NPY_BUFSIZE; np.setbufsize does not change it); the compiled
# residual sums the runs the same way (solver_fused.residual)
# exact: numpy's NPY_BUFSIZE, fixed in numpy (the compiled residual sums alike)
_EINSUM_RUN = 8192


def _c_doubles(*arrays: np.ndarray) -> bool:
    return all(a.dtype == np.float64 and a.flags.c_contiguous for a in arrays)


def _extended_residual(a0: np.ndarray, a1_cols: np.ndarray, cols: np.ndarray | slice, k: float,
                       y: np.ndarray, rhs: np.ndarray, block: int = 256,
                       extended: tuple[np.ndarray, np.ndarray] | None = None,
                       fused: bool = False) -> np.ndarray:
    """rhs - (a0 + k a1) y in extended precision, a block of rows at a time.

    ``a1`` is given by its nonzero columns ``cols`` (indices, or a slice: newton_on_k's
    ``block``; the compiled route needs the slice) only. Memory: two blocks
    of rows in long double (27 MB at n = 4096), never a full extended copy,
    unless the caller gives ``extended``, (a0, a1_cols) already in long double
    (the same numbers: the conversion is exact), to reuse across solves.
    ``fused``: the products by ``einsum`` with y in long double over the whole
    matrix instead (numpy converts the double rows in its own small buffers): 39
    instead of 52 ms at 3201 x 3201, the same precision but another order of
    summation, so the last bits of k differ; used from n = 1024
    (:func:`newton_on_k` with ``overwrite``), the block route below (bit for bit
    as before). Where built (:data:`FUSED`) the fused route runs compiled
    (``solver_fused.residual``: einsum's own loop for long double, four products at
    a time, in its runs of 8192; the same bits, 15 instead of 57 ms at 3201 x 3201).
    """
    if (fused and extended is None and FUSED and isinstance(cols, slice)
            and _c_doubles(a0, a1_cols, y, rhs)):  # compiled: the einsum route's bits
        out = np.empty(rhs.size)
        _fused.residual(a0, a1_cols, cols.start, float(k), y, rhs, _EINSUM_RUN, out)
        return out
    ye = y.astype(_EXTENDED)
    yc = ye[cols]
    ke = _EXTENDED(k)
    if fused:
        e0, e1 = (a0, a1_cols) if extended is None else extended
        acc = np.einsum("ij,j->i", e0, ye)
        acc += ke * np.einsum("ij,j->i", e1, yc)
        return (rhs.astype(_EXTENDED) - acc).astype(float)
    out = np.empty(rhs.size)
    for r0 in range(0, rhs.size, block):
        rows = slice(r0, r0 + block)
        if extended is None:
            e0, e1 = a0[rows].astype(_EXTENDED), a1_cols[rows].astype(_EXTENDED)
        else:
            e0, e1 = extended[0][rows], extended[1][rows]
        acc = e0 @ ye + ke * (e1 @ yc)
        out[rows] = (rhs[rows].astype(_EXTENDED) - acc).astype(float)
    return out


# systems up to this size keep their long-double copy through one Newton iteration
# (:func:`newton_on_k`; 2 x 16 size^2 bytes, 32 MB at 1024) instead of converting
# the rows again for every refined solve
# convention: a memory bound, 32 MB at 1024; the results do not depend on it
_EXTENDED_COPY_UP_TO = 1024


@dataclass
class PartialSlipSystem:
    """The linear system A(k) x = b of one partial-slip case (0 < c/a < 1).

    Unknowns ``x = [p_0..p_{N-1}, delta, phi_1..phi_{M-1}, C]``: the nodal
    pressures, the indentation, the stick-zone shear nodes and the stick
    constant. ``A(k) = a0 + k a1``, where ``a1`` is nonzero only in the
    columns of the slip-zone pressures, so it is kept as that column block
    ``a1b`` (rows x slip nodes), never as a full matrix.

    Attributes
    ----------
    a0 : ndarray, shape (size, size)
    a1b : ndarray, shape (size, N - M)
    b : ndarray, shape (size,)
    slip_nodes : ndarray of int
        The nodes M ... N-1, whose shear is k p / shape (also their columns).
    shape : ndarray
        The shear shape at the nodes (r for rings, 1 for strips).
    nn, m : int
        Elements N and the stick-edge node M (at c).
    scales : (ndarray, ndarray) or None
        (R, C) once :func:`newton_on_k` has equilibrated ``a0`` and ``a1b`` in
        place (``overwrite=True``): they then hold R A C (by blocks) and b is
        unchanged; :meth:`residual` accounts for it.
    """

    a0: np.ndarray
    a1b: np.ndarray
    b: np.ndarray
    slip_nodes: np.ndarray
    shape: np.ndarray
    nn: int
    m: int
    scales: tuple[np.ndarray, np.ndarray] | None = None

    @property
    def stick_edge(self) -> int:
        """j = M - 1, the last node inside the stick zone, where t_j = shape_j phi_j - k p_j."""
        return self.m - 1

    def edge_traction(self, x: np.ndarray, k: float) -> float:
        """g(k) = shape_j phi_j - k p_j, the stick-edge condition (zero at the physical k)."""
        j = self.stick_edge
        return float(self.shape[j] * x[self.nn + j] - k * x[j])

    def residual(self, x: np.ndarray, k: float) -> float:
        """Relative residual of A(k) x = b plus the relative stick-edge traction."""
        if self.scales is None:
            ax = self.a0 @ x + k * (self.a1b @ x[self.slip_nodes])
        else:  # R A C held in place: A x = R^-1 (R A C) (x / C)
            rs, cs = self.scales
            y = x / cs
            ax = (self.a0 @ y + k * (self.a1b @ y[self.slip_nodes])) / rs
        return float(np.linalg.norm(ax - self.b) / np.linalg.norm(self.b)
                     + abs(self.edge_traction(x, k)) / max(abs(x[self.stick_edge]), 1e-300))


def assemble(geometry: Contact, mesh: Mesh, pw: np.ndarray, qw: np.ndarray,
             axis: tuple[np.ndarray, np.ndarray] | None = None,
             edge: tuple | None = None) -> PartialSlipSystem:
    """The partial-slip system on ``mesh`` from the nodal operators (see the module notes).

    Rows: normal collocation at every node (w = delta - r^2/2), then the
    stick condition u = C r^2 at nodes 1 ... M. The slip-zone shear is
    eliminated by Coulomb's law, phi_i = k p_i / shape_i. ``axis`` (the
    rows w(r_i) - w(0) of the pressure and of the shear at nodes 1 ... M,
    :func:`~contactlib.discretization.operators.axis_w_rows`) replaces the normal rows
    1 ... M by w(r_i) - w(0) = -r_i^2/2: the same equations, without the
    cancellation of O(1) displacements near the axis of a tiny stick zone.
    ``edge`` = (i0, w rows of the pressure and of the shear, u rows of the
    pressure and of the shear) replaces the normal rows i0 + 1 ... N by
    w(r_i) - w(r_i0) = -(r_i^2 - r_i0^2)/2 and the stick rows i0 + 1 ... M by
    u(r_i) - u(r_i0) = C (r_i^2 - r_i0^2) (a thin slip annulus), from
    :func:`~contactlib.discretization.operators.axis_w_rows` and
    :func:`~contactlib.discretization.operators.u_difference_rows` with ``ref = r_i0``. A sixth
    element, an int array, gives each of those rows its own reference node instead of
    i0 (the band around c, :func:`band_references`): w(r_i) - w(r_ref) = -(r_i^2 -
    r_ref^2)/2 and u(r_i) - u(r_ref) = C (r_i^2 - r_ref^2).
    """
    r = mesh.nodes
    nn, m = mesh.n, mesh.stick_index
    tie = not geometry.indenter.odd_shear  # phi_0 = phi_1 (see _tie_columns)
    shape = geometry.shear_shape(r)
    stick_rows = np.arange(1, m + 1)
    stick_cols = slice(0, m - 1)  # phi_1..phi_{M-1} in tied columns
    slip_nodes = np.arange(m, nn)
    slip_cols = slip_nodes - 1
    size = nn + 1 + (m - 1) + 1
    a0 = np.empty((size, size))  # every entry written below (blocks, zeros, constants)
    a1b = np.empty((size, slip_nodes.size))
    nr = nn + 1
    a0[:nr, :nn] = pw[0][:, :-1]
    a0[:nr, nn] = -1.0
    _put_shear(tie, qw[0], m, nn, shape, a0[:nr, nn + 1:nn + m], a1b[:nr])
    a0[:nr, nn + m] = 0.0
    a0[nr:, :nn] = pw[1][1:m + 1, :-1]
    a0[nr:, nn] = 0.0
    _put_shear(tie, qw[1][1:m + 1], m, nn, shape, a0[nr:, nn + 1:nn + m], a1b[nr:])
    prof = geometry.profile  # the gap h(r) and the adherence u = C r^d (r^2/2, r^2 for Hertz)
    a0[nr:, nn + m] = -prof.adherence(r[stick_rows])
    b = np.concatenate([-prof.gap(r), np.zeros(m)])
    if axis is not None:  # rows 0 ... M: w(0) - w(r_{M+1}), w(r_i) - w(0) (i = 1 ... M)
        dqx = _tie_columns(geometry, axis[1])
        near = np.arange(m + 1)
        sign = np.where(near == 0, -1.0, 1.0)[:, None]
        at = np.concatenate([[m], np.arange(m)])  # axis rows are at r_1 ... r_{M+1}
        a0[near, :nn] = sign * axis[0][at, :-1]
        a0[near, nn] = 0.0  # delta drops out of every difference
        a0[near, nn + 1:nn + m] = sign * dqx[at][:, stick_cols]
        a1b[near] = sign * dqx[at][:, slip_cols] / shape[slip_nodes]
        b[0] = prof.gap(r[m + 1])  # w(0) - w(r_{M+1}); -h(r_i) for the others as before
    if edge is not None:  # rows i0+1 ...: w(r_i) - w(r_ref) = -(r_i^2 - r_ref^2)/2
        i0, dp, dq, up, uq = edge[:5]
        rows = slice(i0 + 1, i0 + 1 + dp.shape[0])
        # each row's reference: its own (the band's cascade) or i0 for all (an annulus)
        ref = r[edge[5] if len(edge) > 5 else np.full(dp.shape[0], i0)]
        a0[rows, :nn] = dp[:, :-1]
        a0[rows, nn] = 0.0
        _put_shear(tie, dq, m, nn, shape, a0[rows, nn + 1:nn + m], a1b[rows])
        b[rows] = -prof.gap_difference(r[rows], ref)
        srows = slice(nr + i0, nr + m)  # stick rows of the nodes i0 + 1 ... M
        sref = ref[:m - i0]
        a0[srows, :nn] = up[:m - i0, :-1]
        _put_shear(tie, uq[:m - i0], m, nn, shape, a0[srows, nn + 1:nn + m], a1b[srows])
        a0[srows, nn + m] = -prof.adherence_difference(r[i0 + 1:m + 1], sref)
    return PartialSlipSystem(a0, a1b, b, slip_nodes, shape, nn, m)


@dataclass
class NewtonResult:
    """Newton on k for one :class:`PartialSlipSystem`.

    Attributes
    ----------
    x : ndarray
        The unknowns at the final k (first-order update from the last
        factorization).
    k : float
        The friction coefficient.
    converged : bool
    iterations : int
    stagnated : float
        The last relative step when Newton stopped on the round-off floor of
        the stick-edge condition, else 0.
    """

    x: np.ndarray
    k: float
    converged: bool
    iterations: int
    stagnated: float


def _refined_solve(lu: tuple, a0s: np.ndarray, a1s: np.ndarray, cols: np.ndarray | slice,
                   k: float,
                   rhs: np.ndarray, refine: bool,
                   extended: tuple[np.ndarray, np.ndarray] | None = None,
                   in_place: bool = False) -> np.ndarray:
    """Solve with the LU of A(k), plus one step of extended-precision refinement if asked.

    ``in_place`` (:func:`newton_on_k` with ``overwrite``): ``lu`` factors A(k)^T (the
    solves transpose back) and the residual is the fused one of :func:`_extended_residual`.
    """
    trans = 1 if in_place else 0
    y = linalg.lu_solve(lu, rhs, trans=trans, check_finite=False)
    if not refine:
        return y
    res = _extended_residual(a0s, a1s, cols, k, y, rhs, extended=extended, fused=in_place)
    return y + linalg.lu_solve(lu, res, trans=trans, check_finite=False)


def _equilibration(a0: np.ndarray, a1b: np.ndarray, block, k: float,
                   rows: int = 64) -> tuple[np.ndarray, np.ndarray]:
    """Row and column scales of A(k) = a0 + k a1 (a1's columns ``block`` = a1b).

    rs = 1 / max_j |A_ij|, then cs = 1 / max_i |rs_i A_ij|: formed a block of ``rows``
    rows at a time in scratch (the same operations on each entry, and maxima are exact:
    the same bits as on the whole matrix, without its copies).
    """
    size = a0.shape[0]
    rs = np.empty(size)
    colmax = np.zeros(a0.shape[1])
    buf = np.empty((min(rows, size), a0.shape[1]))
    for r0 in range(0, size, rows):
        blk = buf[:min(rows, size - r0)]
        blk[...] = a0[r0:r0 + rows]
        blk[:, block] += k * a1b[r0:r0 + rows]
        np.abs(blk, out=blk)
        top = np.max(blk, axis=1)
        np.divide(1.0, top, out=rs[r0:r0 + blk.shape[0]])
        blk *= rs[r0:r0 + blk.shape[0], None]
        np.maximum(colmax, np.max(blk, axis=0), out=colmax)
    return rs, 1.0 / colmax


def newton_on_k(system: PartialSlipSystem, k: float, *, max_iter: int = 30,
                refine: bool = False, refine_derivative: bool = True,
                final_step: float = 0.0, overwrite: bool = False) -> NewtonResult:
    """Newton's method on the stick-edge condition g(k) = 0.

    Each iteration factorizes A(k) once; the derivative dg/dk comes from the
    same factorization (dx/dk = -A^-1 a1 x). Rows and columns are equilibrated
    at the starting k (the graded mesh has elements ~1/N^2 long): the
    iteration solves (R A C) y = R b, x = C y.

    g is the traction difference at a node ~1/N^2 from c, where it and its
    k-derivative are O(1/N^2) while the LU's round-off in p and phi is
    ~eps cond(A) ~ eps N^2: g(k) was noisy at ~1e-5 relative in k for
    N = 1024 (Newton stalled there). ``refine`` adds one step of iterative
    refinement with the residual in extended precision, which removes the
    noise (k stable to ~1e-10 at N = 1024 and 2048). ``refine_derivative=False``
    refines the solution but not dx/dk: the derivative's round-off then only
    scales the step (a relative error e of dg/dk moves k by e times the last
    step), which costs half the extended-precision residuals. ``final_step``: a
    refined step of at most this (relative) is the last one (the error after a
    refined step is about 0.4 step^2: see :data:`REFINED_FINAL_STEP`).
    ``overwrite``: equilibrate the system's ``a0`` and ``a1b`` in place (no scaled
    copies: 2 x 8 size (size + N - M) bytes fewer, 108 MB at n = 2048, and one pass);
    the system records its scales (:attr:`PartialSlipSystem.scales`) and cannot be
    given to this function again.
    """
    sysm = system
    if sysm.scales is not None:
        raise ValueError("this system was equilibrated in place by an earlier call "
                         "(overwrite=True); assemble it again")
    slip, nn, j = sysm.slip_nodes, sysm.nn, sysm.stick_edge
    if slip.size and np.array_equal(slip, np.arange(slip[0], slip[0] + slip.size)):
        block = slice(int(slip[0]), int(slip[0]) + slip.size)  # (assemble's: M ... N-1)
    else:
        block = slip  # the same columns, by index (slower)
    first_ak = None
    if (overwrite and FUSED and isinstance(block, slice) and sysm.a0.flags.c_contiguous
            and sysm.a1b.flags.c_contiguous):  # compiled: two passes, the same bits
        rs, colmax = np.empty(sysm.b.size), np.empty(sysm.b.size)
        _fused.equilibrate(sysm.a0, sysm.a1b, block.start, float(k), rs, colmax)
        cs = 1.0 / colmax
        first_ak = np.empty_like(sysm.a0)
        _fused.scale_form(sysm.a0, sysm.a1b, block.start, rs, cs, float(k), first_ak)
        a0s, a1s = sysm.a0, sysm.a1b
        sysm.scales = (rs, cs)
    else:
        rs, cs = _equilibration(sysm.a0, sysm.a1b, block, k)
        if overwrite:
            a0s, a1s = sysm.a0, sysm.a1b
            a0s *= rs[:, None]
            a1s *= rs[:, None]
            sysm.scales = (rs, cs)
        else:
            a0s = sysm.a0 * rs[:, None]
            a1s = sysm.a1b * rs[:, None]
        a0s *= cs
        a1s *= cs[block]
    bs = sysm.b * rs
    shape = sysm.shape
    converged, it, stagnated = False, 0, 0.0
    x = xk = None
    step, prev_step = 0.0, np.inf
    extended = None
    for it in range(1, max_iter + 1):
        if first_ak is not None:  # A(k) at the first k, formed with the scaling
            ak, first_ak = first_ak, None
        else:
            ak = a0s.copy()
            ak[:, block] += k * a1s
        # overwrite: LAPACK factors A^T in ak's own memory (a C array is A^T in Fortran
        # order), where lu_factor(ak) would copy A into Fortran order first (82 MB at
        # n = 2048, fresh pages); the solves then use the transposed factors (trans=1)
        lu = linalg.lu_factor(ak.T if overwrite else ak, overwrite_a=True,
                              check_finite=False)
        if refine and extended is None and bs.size <= _EXTENDED_COPY_UP_TO:
            extended = (a0s.astype(_EXTENDED), a1s.astype(_EXTENDED))
        x = cs * _refined_solve(lu, a0s, a1s, block, k, bs, refine, extended, overwrite)
        g = shape[j] * x[nn + j] - k * x[j]
        a1x = a1s @ (x[slip] / cs[block]) if overwrite else rs * (sysm.a1b @ x[slip])
        xk = -cs * _refined_solve(lu, a0s, a1s, block, k, a1x,
                                  refine and refine_derivative, extended, overwrite)
        dg = shape[j] * xk[nn + j] - x[j] - k * xk[j]
        step = g / dg
        k -= step
        size_step = abs(step) / max(abs(k), 1e-12)
        if refine and size_step <= final_step:  # converged to well below 1e-9: final
            converged = True
            break
        # Newton converges quadratically (error after a step ~ 1e3 step^2 here):
        # stop after a step below 1e-6 relative. Beyond n ~ 1000 the stick-edge
        # condition reaches its round-off floor (k to ~1e-6): when the steps
        # stop shrinking there, keep the last iterate and say so.
        if size_step <= 1e-6:
            converged = True
            break
        if abs(step) > 0.5 * prev_step and not refine:
            # not converging quadratically: round-off in the LU (noise in g of up to
            # 1e-3 relative in k was seen near c/a = 1); refine the solves and go on
            refine, prev_step = True, np.inf
            continue
        if abs(step) > 0.5 * prev_step and size_step <= 1e-4:
            converged = True
            stagnated = size_step
            break
        prev_step = abs(step)
    # x at the final k from the last factorization: x(k) is smooth in k, so the
    # first-order update leaves an error of order step^2
    x = x - step * xk
    return NewtonResult(x, float(k), converged, it, stagnated)


def start_k(geometry: Contact, stick_ratio: float, n: int, power: float,
            k_guess: float | None = None, edge: float | None = None,
            cache: StickBlocks | None = None) -> float:
    """Newton's starting k relative to sign(beta): the caller's guess, else a cheap estimate.

    For n > 128 the Richardson extrapolation of the n = 64 and n = 128
    solutions (error O(h^2)) puts Newton within 1e-5 ... 3e-5 of the answer,
    so one or two fine factorizations suffice; from n = 1024 on the n = 256
    solution is added and k + A n^-2 + B n^-3 fitted through the three
    (within ~1e-6: one refined step is then final, see REFINED_FINAL_STEP); for smaller n the uncoupled closed
    form (with |beta|) at the stick-edge node ``edge`` (default c/a). The
    solver multiplies it by sign(beta); it is negative when the coarse
    solutions slip against sign(beta) (see :attr:`DiscreteSolution.oriented_k`).
    """
    if k_guess is not None:
        return float(k_guess)
    if n > 128:
        k64 = solve_default(geometry, stick_ratio, 64, power=power, cache=cache).oriented_k
        k128 = solve_default(geometry, stick_ratio, 128, power=power,
                             k_guess=k64 if np.isfinite(k64) else None,
                             cache=cache).oriented_k
        if n >= _THREE_LEVEL_START_FROM_N and np.isfinite(k64) and np.isfinite(k128):
            k256 = solve_default(geometry, stick_ratio, 256, power=power,
                                 k_guess=k128 + (k128 - k64) / 3.0, cache=cache).oriented_k
            if np.isfinite(k256):  # k + A n^-2 + B n^-3 through the three levels
                return (32.0 * k256 - 12.0 * k128 + k64) / 21.0
        if np.isfinite(k64) and np.isfinite(k128):  # (a failed coarse solve reports NaN)
            return k128 + (k128 - k64) / 3.0
        if np.isfinite(k128):
            return k128
    c = stick_ratio if edge is None else edge
    thin = thin_smooth_layer_k(geometry, c)
    if thin is not None:
        return thin
    return float(geometry.uncoupled_friction(c))


# tested: tests/test_thin_layers_cylinder_smooth.py (k at a/h = 100 ... 1000 from this start; at
# a/h = 200 and more the uncoupled start ended at wrong roots at 9 of 11 c/a, nu = 0.3)
THIN_START_FROM = 20.0


def thin_smooth_layer_k(geometry: Contact, stick_ratio: float) -> float | None:
    """Starting k of a cylinder on a thin layer on a smooth base (relative to sign(beta)).

    The thin-layer limit (``h = 1/slab_ratio``, a = 1): a Winkler pressure
    ``p ~ (1 - x^2)``, the Poisson expansion ``du/dx = nu/(1 - nu) p`` and the membrane
    ``h u'' = -q``; stick (``u ~ x |x|``) on ``|x| < c``, the membrane force balanced at
    ``c`` and ``q`` continuous there give ``q = -k p`` in the slip zone with
    ``k = 3 h nu (1 + c^2) / (2 (1 - nu)(1 - c^3))``: outward slip for nu > 0, against
    sign(beta). It is within 9 % of the solutions at a/h = 100 ... 1000 for nu = 0.3 and
    38 % for nu = 0.45 (c/a = 0.05 ... 0.95; the inner layer at c adds), where the uncoupled
    half-plane start (inward, ~100 times too large) took Newton to wrong roots. None where
    it does not apply (a sphere, another base, a/h below :data:`THIN_START_FROM`, nu = 0).
    """
    body = geometry.body
    if (geometry.indenter.name != "cylinder" or body.base != "smooth"
            or body.slab_ratio < THIN_START_FROM or body.nu == 0.0):
        return None
    c = float(stick_ratio)
    k = 1.5 * body.nu * (1.0 + c * c) / ((1.0 - body.nu) * (1.0 - c**3) * body.slab_ratio)
    return -k if geometry.slip_sign >= 0 else k


def _nodal_operators(geometry: Contact, mesh: Mesh,
                     ops: tuple[np.ndarray, np.ndarray | None] | None,
                     cache: StickBlocks | None = None) -> tuple[np.ndarray, np.ndarray | None]:
    """(P, Q) nodal operators on ``mesh``: given (checked, copied where edited) or built."""
    nn, m = mesh.n, mesh.stick_index
    if ops is None:
        if m > 0:
            pw, qw = nodal_operators(geometry, mesh, cache=cache)
        else:
            pw, qw = nodal_operator_part(geometry, mesh, "normal", cache=cache), None
    else:
        copy = geometry.indenter.odd_shear  # the axis row is edited below
        pw = np.array(ops[0], dtype=float, copy=copy)
        qw = None if ops[1] is None else np.array(ops[1], dtype=float, copy=copy)
        want = (3, nn + 1, nn + 1)
        if pw.shape != want or (m > 0 and (qw is None or qw.shape != want)):
            raise ValueError(f"precomputed operators must have shape {want} "
                             f"(normal{' and shear' if m > 0 else ''})")
    if geometry.indenter.odd_shear:  # du/dx on the axis: unused, NaN (see operators)
        pw[2][0] = 0.0
        if qw is not None:
            qw[2][0] = 0.0
    return pw, qw


def _frictionless(geometry: Contact, mesh: Mesh, pw: np.ndarray) -> DiscreteSolution:
    """c/a = 0: q = 0, one linear solve for p and delta."""
    r, nn = mesh.nodes, mesh.n
    rhs = -geometry.profile.gap(r)
    a = np.hstack([pw[0][:, :-1], -np.ones((nn + 1, 1))])
    x = linalg.solve(a, rhs)
    res = np.linalg.norm(a @ x - rhs) / np.linalg.norm(rhs)
    p = np.append(x[:nn], 0.0)
    return DiscreteSolution(geometry, mesh, p, np.zeros(nn + 1), float(x[nn]), 0.0, True,
                            float(res), 1, "", pw[1] @ p, pw[2] @ p)


def _full_adhesion(geometry: Contact, mesh: Mesh, pw: np.ndarray,
                   qw: np.ndarray) -> DiscreteSolution:
    """c/a = 1: phi_1..phi_{N-1} free, phi_N = 0; one linear solve."""
    r, nn, m = mesh.nodes, mesh.n, mesh.stick_index
    qx = _tie_columns(geometry, qw)
    stick_rows = np.arange(1, m + 1)
    top = np.hstack([pw[0][:, :-1], -np.ones((nn + 1, 1)), qx[0], np.zeros((nn + 1, 1))])
    bot = np.hstack([pw[1][stick_rows, :-1], np.zeros((m, 1)), qx[1][stick_rows],
                     -geometry.profile.adherence(r[stick_rows])[:, None]])
    a = np.vstack([top, bot])
    b = np.concatenate([-geometry.profile.gap(r), np.zeros(m)])
    x = linalg.solve(a, b)
    res = np.linalg.norm(a @ x - b) / np.linalg.norm(b)
    p = np.append(x[:nn], 0.0)
    phi = _expand_phi(geometry, x[nn + 1:2 * nn])
    return DiscreteSolution(geometry, mesh, p, phi, float(x[nn]), np.inf, True, float(res), 1,
                            "", pw[1] @ p + qw[1] @ phi, pw[2] @ p + qw[2] @ phi)


def difference_rows(geometry: Contact, mesh: Mesh, band: bool | None = None,
                    width: float = NEAR_ROWS_WIDTH,
                    quadrature: str = "standard") -> tuple[tuple | None, tuple | None]:
    """The rows :func:`assemble` writes as differences on ``mesh``: (axis, edge), each or None.

    ``axis`` for a tiny stick zone (c/a <= :data:`AXIS_ROWS_BELOW`), ``edge`` for a
    thin slip annulus (1 - c/a <= :data:`EDGE_ROWS_BELOW`) or, at high resolution,
    the band around c (n >= :data:`NEAR_ROWS_FROM_N`, or elements next to c below
    :data:`NEAR_ROWS_BELOW` min(c, a - c);
    ``band=True`` asks for the band at any resolution, ``False`` never: the extrapolated
    method writes every level's rows alike; ``width``: the band's half-width in units of
    min(c, a - c)); None where the plain rows are kept, or the
    indenter has no kernel differences. Their kernels are evaluated here (only in those
    three cases). ``quadrature``: the element rules of the band's rows
    (:data:`contactlib.discretization.influence.QUADRATURES`); the axis and edge rows keep the standard
    ones (with the fine rules the edge rows were worse: cylinder, nu = 0.499,
    c/a = 1 - 1e-5, extrapolated at n = 2048, k error -1.5e-3 against -9.7e-5).
    """
    r, m = mesh.nodes, mesh.stick_index
    axis = None
    if r[m] <= AXIS_ROWS_BELOW:  # tiny stick zone: its normal rows relative to the axis
        try:
            axis = tuple(axis_w_rows(geometry, r, r[1:m + 2], part)
                         for part in ("normal", "shear"))
        except NotImplementedError:  # an indenter without w(x) - w(0): the plain rows
            axis = None
    edge = None
    if 1.0 - r[m] <= EDGE_ROWS_BELOW:  # thin slip annulus: its normal rows relative to r_i0
        i0 = int(np.searchsorted(r, 1.0 - EDGE_REF_WIDTHS * (1.0 - r[m])))
        try:
            ref = float(r[i0])
            edge = (i0,) + tuple(axis_w_rows(geometry, r, r[i0 + 1:], part, ref=ref)
                                 for part in ("normal", "shear")) + tuple(
                u_difference_rows(geometry, r, r[i0 + 1:m + 1], part, ref)
                for part in ("normal", "shear"))
        except NotImplementedError:
            edge = None
    elif axis is None and ((mesh.n >= NEAR_ROWS_FROM_N
                            or _near_c_h(r, m) < NEAR_ROWS_BELOW * min(r[m], 1.0 - r[m]))
                           if band is None else band):
        try:
            edge = _band_rows(geometry, mesh, width * min(r[m], 1.0 - r[m]), quadrature)
        except NotImplementedError:
            edge = None
    return axis, edge


def band_references(mesh: Mesh, width: float) -> tuple[int, np.ndarray]:
    """The band's first reference node i0 and each band node's reference, (i0, refs).

    The band is the nodes i0 + 1 ... i1 within ``width`` (units a) of c; ``refs[j]`` is
    the node the row of node i0 + 1 + j is written relative to: the node just inside
    c - w_l for the innermost of the widths w_l = width / :data:`BAND_REF_RATIO`^l
    (down to :data:`BAND_REF_INNER` elements next to c) whose band holds the node. Every
    reference is itself a node of the next wider band (or i0), so the rows are the plain
    ones combined by an invertible (triangular) transformation: the same equations.
    """
    r, m = mesh.nodes, mesh.stick_index
    i0 = int(np.searchsorted(r, r[m] - width))
    i1 = int(np.searchsorted(r, r[m] + width))
    refs = np.full(i1 - i0, i0, dtype=np.intp)
    node = np.arange(i0 + 1, i1 + 1)
    inner = BAND_REF_INNER * _near_c_h(r, m)
    w = width / BAND_REF_RATIO
    while w >= inner:
        j0 = int(np.searchsorted(r, r[m] - w))
        if j0 >= m:
            break
        j1 = int(np.searchsorted(r, r[m] + w))
        refs[(node > j0) & (node <= j1)] = j0
        w /= BAND_REF_RATIO
    return i0, refs


def _band_rows(geometry: Contact, mesh: Mesh, width: float, quadrature: str) -> tuple:
    """The band's difference rows (i0, w rows of p and phi, u rows of p and phi, refs).

    Each row relative to its own reference node (:func:`band_references`), one kernel pass
    per distinct reference.
    """
    r, m = mesh.nodes, mesh.stick_index
    i0, refs = band_references(mesh, width)
    node = np.arange(i0 + 1, i0 + 1 + refs.size)
    cols = r.size
    dp, dq = np.empty((refs.size, cols)), np.empty((refs.size, cols))
    up, uq = np.empty((m - i0, cols)), np.empty((m - i0, cols))
    for ref in np.unique(refs):
        sel = np.flatnonzero(refs == ref)
        stick = sel[node[sel] <= m]
        x = float(r[ref])
        dp[sel], dq[sel] = (axis_w_rows(geometry, r, r[node[sel]], part, ref=x,
                                        quadrature=quadrature) for part in ("normal", "shear"))
        if stick.size:
            up[stick], uq[stick] = (u_difference_rows(geometry, r, r[node[stick]], part, x,
                                                      quadrature)
                                    for part in ("normal", "shear"))
    return i0, dp, dq, up, uq, refs


def solve_default(geometry: Contact, stick_ratio: float, n: int, *, power: float = 2.0,
                  k_guess: float | None = None, tol: float = 1e-9,
                  max_iter: int = 30,
                  ops: tuple[np.ndarray, np.ndarray | None] | None = None,
                  cache: StickBlocks | None = None,
                  mesh: Mesh | None = None) -> DiscreteSolution:
    """Solve the self-similar partial-slip problem for a given stick ratio.

    The stages: the mesh and its nodal operators; :func:`assemble` the
    system A(k) x = b; :func:`start_k`; :func:`newton_on_k` (with the
    extended-precision refinement from n = 256 on); the nodal solution and
    its messages. c/a = 0 and 1 are single linear solves.

    Parameters
    ----------
    geometry : Contact
    stick_ratio : float
        c/a in [0, 1]; 0 is frictionless (k = 0), 1 full adhesion (k = inf).
    n : int
        Number of elements across the half-contact.
    power : float
        Mesh grading exponent.
    k_guess : float, optional
        Starting value for Newton's method on k (default: see :func:`start_k`).
    tol : float
        Kept for compatibility; Newton's stopping rules are in
        :func:`newton_on_k`.
    max_iter : int
        Newton iterations allowed.
    ops : (P, Q), optional
        Precomputed collocation operators ``operator_part(geometry, nodes,
        nodes, "normal")`` and ``(..., "shear")`` on this mesh (Q may be None
        when stick_ratio = 0); computed here when not given.
    cache : StickBlocks, optional
        The caller's store of stick blocks (see
        :func:`~contactlib.discretization.operators.nodal_operator_part`) and of graded
        meshes (its ``meshes``), shared by the cases of a sweep; the numbers
        do not depend on it.
    mesh : Mesh, optional
        The mesh (default: ``graded_mesh(n, stick_ratio, power)``); given by the
        extrapolated method for a level that is a halving of a finer mesh, which differs
        from the graded mesh of its n where the finest was scaled back to the largest
        element count.

    Returns
    -------
    DiscreteSolution
    """
    if mesh is None:
        mesh = graded_mesh(n, stick_ratio, power=power,
                           store=None if cache is None else cache.meshes)
    r = mesh.nodes
    nn, m = mesh.n, mesh.stick_index
    pw, qw = _nodal_operators(geometry, mesh, ops, cache)
    if m == 0:
        return _frictionless(geometry, mesh, pw)
    if m == nn:
        return _full_adhesion(geometry, mesh, pw, qw)

    axis, edge = difference_rows(geometry, mesh)
    system = assemble(geometry, mesh, pw, qw, axis, edge)
    sigma = -1.0 if geometry.slip_sign < 0 else 1.0  # q = sigma k p in the slip zone
    k0 = sigma * start_k(geometry, stick_ratio, n, power, k_guess, edge=r[m], cache=cache)
    # with one refined step final (n >= 1024): dx/dk from the plain LU solve (as the
    # extrapolated method's levels; its round-off only scales a step below 3e-5: k moved by
    # at most 1.6e-14 over c/a = 0.02 ... 0.999, both geometries, nu = 0.3 and 0.49999,
    # n = 1024 and 2048; one extended-precision residual fewer, 0.17 LU(3201) at n = 2048),
    # and the system equilibrated in place (it is not used again but for the residual)
    one_step = n >= _THREE_LEVEL_START_FROM_N
    newton = newton_on_k(system, k0, max_iter=max_iter, refine=nn >= _REFINE_FROM_N,
                         final_step=REFINED_FINAL_STEP if one_step else 0.0,
                         refine_derivative=not one_step, overwrite=one_step)
    x, k = newton.x, newton.k  # signed: q = k p in the slip zone
    res = system.residual(x, k)
    p = np.append(x[:nn], 0.0)
    phi = _expand_phi(geometry, np.concatenate([x[nn + 1:nn + m], np.zeros(nn - m)]))
    phi[m:nn] = k * p[m:nn] / system.shape[m:nn]
    converged = newton.converged
    msg = "" if converged else f"Newton on k did not converge in {max_iter} iterations"
    nodal_u, nodal_du = pw[1] @ p + qw[1] @ phi, pw[2] @ p + qw[2] @ phi
    reversed_ok = False
    tensile = bool(np.min(p[m:nn]) <= 0.0)  # no pressure in the slip zone: past c* (below)
    if np.isfinite(k) and k * sigma < 0.0 and not tensile:  # the root slips against sign(beta)
        # physical when consistent at every node (e.g. a thin or nearly incompressible
        # slab, whose surface moves outward under a rigid indenter)
        reversed_ok = _node_flags(mesh, system.shape * phi, p, k, nodal_u, nodal_du,
                                  geometry.profile.exponent)["consistent"]
    way = "outward (q = -k p)" if k < 0 else "inward (q = k p)"
    k = abs(k) if reversed_ok else sigma * k  # report k >= 0
    if not (np.isfinite(k) and k > 0.0):  # never a negative (or non-finite) k as if good
        converged = False
        if np.isfinite(k) and tensile:
            msg = (f"Newton on k ended at a root that slips the other way ({way}, |k| = "
                   f"{abs(k):.4g}) with tensile pressure at the stick edge: c/a = "
                   f"{stick_ratio:.7g} most likely lies beyond the largest stick ratio c* < 1 "
                   f"that one slip zone reaches at this coupling (beta = {geometry.beta:.3g}; k "
                   "grows without bound as c/a approaches c*, the roots past it are of this "
                   "kind, and no friction coefficient gives such a stick ratio: the full-stick "
                   "solution itself has tensile pressure at the edge; docs/accuracy.md, 'Near "
                   "full stick'), unless Newton started far from a root just below c* (a "
                   "larger n, or a sweep from smaller c/a, tells which); not a solution, k is "
                   "reported as NaN")
        elif np.isfinite(k):
            msg = (f"Newton on k ended at a root with slip {way} (|k| = {abs(k):.4g}), against "
                   f"the sign of beta ({geometry.beta:.3g}), where the slip does not oppose the "
                   f"shear: either a stick zone of c/a = {stick_ratio:.3g} below what n = {n} "
                   "resolves, or the slip direction changes within the slip zone, which one "
                   "self-similar stick zone cannot hold: solve it with history; not a "
                   "solution, k is reported as NaN")
        else:
            msg = (f"Newton on k diverged (last iterate {k}); not a solution, k is reported "
                   "as NaN")
        k = np.nan
    elif reversed_ok:
        why = (f"against the sign of the half-space beta ({geometry.beta:.3g}): the body's "
               "coupling reverses it") if geometry.slip_sign else (
            "the layer's own coupling sets it (its material's beta is 0)")
        msg = "; ".join(x for x in (msg, f"the slip runs {way}, {why}") if x)
    elif newton.stagnated:
        msg = (f"Newton on k stopped at the round-off floor of the stick-edge condition "
               f"(last step {newton.stagnated:.1e} relative)")
    out = DiscreteSolution(geometry, mesh, p, phi, float(x[nn]), float(k), converged, res,
                           newton.iterations, msg, nodal_u, nodal_du, float(newton.stagnated))
    if newton.converged and np.isfinite(newton.k):
        out.newton_root = float(sigma * newton.k)
    return out
