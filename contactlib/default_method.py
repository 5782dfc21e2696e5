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
  self-similar adherence condition, paper Eq. 8); in the slip zone (nodes
  M..N-1) q = k p (Coulomb, traction ratio).

With k given, these equations are square; both conditions at c make the
shear continuous and bounded there.

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
:func:`nodal_operator_part`) are built by :mod:`contactlib.operators` and
re-exported here; the model (indenter and body) is a
:class:`~contactlib.model.Contact`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import linalg

from .elements import Mesh, graded_mesh
from .energy import slip_points
from .model import Contact
from .operators import nodal_operator_part, operator_part, operators
from .result import short_repr

__all__ = ["DiscreteSolution", "solve_default", "operators", "operator_part",
           "nodal_operator_part"]

# Extended precision for the residual of one step of iterative refinement (see
# solve_default): 80-bit on x86-64 Linux; where long double is plain double
# (e.g. Windows, Apple arm64) the step still helps, but k keeps a round-off
# floor of about 1e-5 relative at n = 1024.
_EXTENDED = np.longdouble
_REFINE_FROM_N = 384  # below, the round-off in k is < 1e-7 relative (4e-8 at n = 256)


@dataclass(repr=False)
class DiscreteSolution:
    """Nodal solution on a mesh (units E* = a = R = 1)."""

    __repr__ = short_repr  # a few lines: scalars, arrays by shape

    geometry: Contact
    mesh: Mesh
    p: np.ndarray  # nodal pressure, p[-1] = 0
    phi: np.ndarray  # nodal shear coefficient, q = shape * phi, phi[-1] = 0
    delta: float
    k: float
    converged: bool
    residual_norm: float
    iterations: int
    message: str = ""
    nodal_u: np.ndarray | None = None  # u at the nodes (from the solve's own operators)
    nodal_du: np.ndarray | None = None  # du/dx at the nodes

    @property
    def stick_ratio(self) -> float:
        return float(self.mesh.nodes[self.mesh.stick_index])

    def pressure(self, x: np.ndarray) -> np.ndarray:
        return np.interp(x, self.mesh.nodes, self.p)

    def shear(self, x: np.ndarray) -> np.ndarray:
        return self.geometry.shear_shape(x) * np.interp(x, self.mesh.nodes, self.phi)

    def slip_samples(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(x, weights, q, s) on the slip zone: its nodes and element midpoints (Simpson).

        s = 2u - xi du/dxi is the self-similar slip rate. At the nodes u and
        du/dxi come free from the solve (``nodal_u``, ``nodal_du``); only the
        midpoints need the exact kernels, one point an element. Simpson's
        rule on the slip elements integrates the work to within 2e-6 relative
        of an 8-point Gauss rule at n = 256 (1e-4 at n = 64), 30 times below
        the method's own error in the work; the slip-direction check sees
        nodes and midpoints.
        """
        return _slip_samples(self)

    def displacements(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(w, u, du/dx) at points x."""
        pw, qw = operators(self.geometry, self.mesh.nodes, x)
        with np.errstate(invalid="ignore"):  # see operators(): du/dx on a strip axis
            return tuple(pw[i] @ self.p + qw[i] @ self.phi for i in range(3))

    def tangential(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(u, du/dx) at points x, without the normal displacement (cheaper)."""
        pw, qw = operators(self.geometry, self.mesh.nodes, x, with_w=False)
        with np.errstate(invalid="ignore"):  # see operators(): du/dx on a strip axis
            return tuple(pw[i] @ self.p + qw[i] @ self.phi for i in (1, 2))

    def radial_displacement(self, x: np.ndarray) -> np.ndarray:
        """u at points x alone (cheapest: no w, no du/dx)."""
        pw = operator_part(self.geometry, self.mesh.nodes, x, "normal", with_w=False)
        qw = operator_part(self.geometry, self.mesh.nodes, x, "shear", with_du=False)
        return pw[1] @ self.p + qw[1] @ self.phi


def _slip_samples(sol: "DiscreteSolution", order: int | None = None):
    """Slip-zone samples: Simpson (nodes + midpoints; default) or Gauss points (order > 0)."""
    r, m = sol.mesh.nodes, sol.mesh.stick_index
    if order is None and sol.nodal_u is not None:
        xn = r[m:]
        h = np.diff(xn)
        mid = 0.5 * (xn[:-1] + xn[1:])
        u_mid, du_mid = sol.tangential(mid)
        wn = np.zeros(xn.size)
        wn[:-1] += h / 6.0
        wn[1:] += h / 6.0
        xs = np.concatenate([xn, mid])
        ws = np.concatenate([wn, 4.0 * h / 6.0])
        s_nodes = 2.0 * sol.nodal_u[m:] - xn * sol.nodal_du[m:]
        ss = np.concatenate([s_nodes, 2.0 * u_mid - mid * du_mid])
        return xs, ws, sol.shear(xs), ss
    xs, ws = slip_points(r, m, max(order or 4, 2))
    u, du = sol.tangential(xs)
    return xs, ws, sol.shear(xs), 2.0 * u - xs * du


def _tie_columns(geometry: Contact, q_ops: np.ndarray) -> np.ndarray:
    """Columns for phi_1..phi_{N-1}: phi_0 = phi_1 (rings) or phi_0 = 0 (odd strip shear)."""
    cols = q_ops[..., 1:-1].copy()
    if not geometry.indenter.odd_shear:
        cols[..., 0] += q_ops[..., 0]
    return cols


def _expand_phi(geometry: Contact, f: np.ndarray) -> np.ndarray:
    """Nodal phi (N + 1 values) from phi_1..phi_{N-1}."""
    first = 0.0 if geometry.indenter.odd_shear else f[0]
    return np.concatenate([[first], f, [0.0]])


def _extended_residual(a0: np.ndarray, a1_cols: np.ndarray, cols: np.ndarray, k: float,
                       y: np.ndarray, rhs: np.ndarray, block: int = 256) -> np.ndarray:
    """rhs - (a0 + k a1) y in extended precision, a block of rows at a time.

    ``a1`` is given by its nonzero columns ``cols`` only. Memory: two blocks
    of rows in long double (27 MB at n = 4096), never a full extended copy.
    """
    ye = y.astype(_EXTENDED)
    yc = ye[cols]
    ke = _EXTENDED(k)
    out = np.empty(rhs.size)
    for r0 in range(0, rhs.size, block):
        rows = slice(r0, r0 + block)
        acc = a0[rows].astype(_EXTENDED) @ ye + ke * (a1_cols[rows].astype(_EXTENDED) @ yc)
        out[rows] = (rhs[rows].astype(_EXTENDED) - acc).astype(float)
    return out


def solve_default(geometry: Contact, stick_ratio: float, n: int, *, power: float = 2.0,
                  k_guess: float | None = None, tol: float = 1e-9,
                  max_iter: int = 30,
                  ops: tuple[np.ndarray, np.ndarray | None] | None = None) -> DiscreteSolution:
    """Solve the self-similar partial-slip problem for a given stick ratio.

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
        Starting value for Newton's method on k (default: the uncoupled
        closed form for n <= 128, else the Richardson extrapolation of the
        n = 64 and n = 128 solutions).
    tol : float
        Relative size of a Newton step still counted as converged when the
        iteration stagnates at round-off (normally Newton stops after a step
        below 1e-6, which leaves an error in k near 1e-10).
    max_iter : int
        Newton iterations allowed.
    ops : (P, Q), optional
        Precomputed collocation operators ``operator_part(geometry, nodes,
        nodes, "normal")`` and ``(..., "shear")`` on this mesh (Q may be None
        when stick_ratio = 0); computed here when not given.

    Returns
    -------
    DiscreteSolution
    """
    mesh = graded_mesh(n, stick_ratio, power=power)
    r = mesh.nodes
    nn, m = mesh.n, mesh.stick_index
    if ops is None:
        pw = nodal_operator_part(geometry, mesh, "normal")
        qw = nodal_operator_part(geometry, mesh, "shear") if m > 0 else None
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
    rhs_normal = -0.5 * r**2
    ones = np.ones((nn + 1, 1))

    if m == 0:  # frictionless: q = 0
        a = np.hstack([pw[0][:, :-1], -ones])
        x = linalg.solve(a, rhs_normal)
        res = np.linalg.norm(a @ x - rhs_normal) / np.linalg.norm(rhs_normal)
        p = np.append(x[:nn], 0.0)
        phi = np.zeros(nn + 1)
        return DiscreteSolution(geometry, mesh, p, phi, float(x[nn]), 0.0, True, float(res), 1,
                                "", pw[1] @ p, pw[2] @ p)

    qx = _tie_columns(geometry, qw)  # (3, N+1, N-1): phi_1..phi_{N-1}
    shape = geometry.shear_shape(r)
    stick_rows = np.arange(1, m + 1)

    if m == nn:  # full adhesion: phi_1..phi_{N-1} free, phi_N = 0
        top = np.hstack([pw[0][:, :-1], -ones, qx[0], np.zeros((nn + 1, 1))])
        bot = np.hstack([pw[1][stick_rows, :-1], np.zeros((m, 1)), qx[1][stick_rows],
                         -(r[stick_rows] ** 2)[:, None]])
        a = np.vstack([top, bot])
        b = np.concatenate([rhs_normal, np.zeros(m)])
        x = linalg.solve(a, b)
        res = np.linalg.norm(a @ x - b) / np.linalg.norm(b)
        p = np.append(x[:nn], 0.0)
        phi = _expand_phi(geometry, x[nn + 1:2 * nn])
        return DiscreteSolution(geometry, mesh, p, phi, float(x[nn]), np.inf, True,
                                float(res), 1, "", pw[1] @ p + qw[1] @ phi,
                                pw[2] @ p + qw[2] @ phi)

    # partial slip: x = [p_0..p_{N-1}, delta, phi_1..phi_{M-1}, C]
    stick_cols = slice(0, m - 1)  # phi_1..phi_{M-1} in qx columns
    slip_nodes = np.arange(m, nn)  # phi_i = k p_i / shape_i
    slip_cols = slip_nodes - 1
    size = nn + 1 + (m - 1) + 1
    # A(k) = a0 + k a1, where a1 is nonzero only in the columns of the slip-zone
    # pressures: a1 is kept as that column block (a1b), never as a full matrix
    a0 = np.zeros((size, size))
    a1b = np.empty((size, slip_nodes.size))
    nr = nn + 1
    a0[:nr, :nn] = pw[0][:, :-1]
    a0[:nr, nn] = -1.0
    a0[:nr, nn + 1:nn + m] = qx[0][:, stick_cols]
    a1b[:nr] = qx[0][:, slip_cols] / shape[slip_nodes]
    a0[nr:, :nn] = pw[1][stick_rows, :-1]
    a0[nr:, nn + 1:nn + m] = qx[1][stick_rows][:, stick_cols]
    a0[nr:, nn + m] = -(r[stick_rows] ** 2)
    a1b[nr:] = qx[1][stick_rows][:, slip_cols] / shape[slip_nodes]
    b = np.concatenate([rhs_normal, np.zeros(m)])

    j = m - 1  # last node inside the stick zone: t_j = shape_j phi_j - k p_j = 0
    if k_guess is not None:
        k = float(k_guess)
    elif n > 128:  # Richardson-extrapolated coarse solves (O(h^2)) put Newton within
        # ~1e-6 of the answer: one or two fine factorizations
        k64 = solve_default(geometry, stick_ratio, 64, power=power).k
        k128 = solve_default(geometry, stick_ratio, 128, power=power, k_guess=k64).k
        k = k128 + (k128 - k64) / 3.0
    else:
        k = float(geometry.uncoupled_friction(r[m]))
    converged, it, g = False, 0, np.inf
    stagnated = 0.0
    x = None
    prev_step = np.inf
    # equilibrate rows and columns (the graded mesh has elements ~1/N^2 long):
    # solve (R A C) y = R b, x = C y
    a0s = a0.copy()
    a0s[:, slip_nodes] += k * a1b
    rs = 1.0 / np.max(np.abs(a0s), axis=1)
    a0s *= rs[:, None]
    cs = 1.0 / np.max(np.abs(a0s), axis=0)
    a0s = a0 * rs[:, None]
    a0s *= cs
    a1s = a1b * rs[:, None]
    a1s *= cs[slip_nodes]
    bs = b * rs
    # g is the traction difference at a node ~1/N^2 from c, where it and its
    # k-derivative are O(1/N^2) while the LU's round-off in p and phi is
    # ~eps cond(A) ~ eps N^2: g(k) was noisy at ~1e-5 relative in k for
    # N = 1024 (Newton stalled there). One step of iterative refinement with
    # the residual in extended precision removes the noise (k stable to
    # ~1e-10 at N = 1024 and 2048).
    refine = nn >= _REFINE_FROM_N
    for it in range(1, max_iter + 1):
        ak = a0s.copy()
        ak[:, slip_nodes] += k * a1s
        lu = linalg.lu_factor(ak, overwrite_a=True, check_finite=False)

        def refined(rhs: np.ndarray) -> np.ndarray:
            y = linalg.lu_solve(lu, rhs, check_finite=False)
            if not refine:
                return y
            res = _extended_residual(a0s, a1s, slip_nodes, k, y, rhs)
            return y + linalg.lu_solve(lu, res, check_finite=False)

        x = cs * refined(bs)
        g = shape[j] * x[nn + j] - k * x[j]
        xk = -cs * refined(rs * (a1b @ x[slip_nodes]))
        dg = shape[j] * xk[nn + j] - x[j] - k * xk[j]
        step = g / dg
        k -= step
        size_step = abs(step) / max(abs(k), 1e-12)
        # Newton converges quadratically (error after a step ~ 1e3 step^2 here):
        # stop after a step below 1e-6 relative. Beyond n ~ 1000 the stick-edge
        # condition reaches its round-off floor (k to ~1e-6): when the steps
        # stop shrinking there, keep the last iterate and say so.
        if size_step <= 1e-6:
            converged = True
            break
        if abs(step) > 0.5 * prev_step and size_step <= 1e-4:
            converged = True
            stagnated = size_step
            break
        prev_step = abs(step)
    # x at the final k from the last factorization: x(k) is smooth in k, so the
    # first-order update leaves an error of order step^2
    x = x - step * xk
    g = shape[j] * x[nn + j] - k * x[j]
    ax = a0 @ x + k * (a1b @ x[slip_nodes])
    res = float(np.linalg.norm(ax - b) / np.linalg.norm(b) + abs(g) / max(abs(x[j]), 1e-300))
    p = np.append(x[:nn], 0.0)
    phi = _expand_phi(geometry, np.concatenate([x[nn + 1:nn + m], np.zeros(nn - m)]))
    phi[m:nn] = k * p[m:nn] / shape[m:nn]
    msg = "" if converged else f"Newton on k did not converge in {max_iter} iterations"
    if not (np.isfinite(k) and k > 0.0):  # a partial-slip k is positive (inward slip)
        converged = False
        msg = (f"Newton on k ended at k = {k:.4g} <= 0: no physical root on this mesh (a stick "
               f"zone of c/a = {stick_ratio:.3g} below what n = {n} resolves, or a regime "
               "where the slip reverses); not a solution")
    elif stagnated:
        msg = (f"Newton on k stopped at the round-off floor of the stick-edge condition "
               f"(last step {stagnated:.1e} relative)")
    return DiscreteSolution(geometry, mesh, p, phi, float(x[nn]), float(k), converged, res,
                            it, msg, pw[1] @ p + qw[1] @ phi, pw[2] @ p + qw[2] @ phi)
