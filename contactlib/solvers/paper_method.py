"""The paper's scheme as printed (Eqs. 9-16), for comparison.

* n equal rings (strips) of width a/n; step pressures p_j; shear elements
  q_j r/a on ring j for the sphere (paper Fig. 1d) and steps q_j for the
  cylinder.
* Eq. 9: w_0 - w_i = r_i^2 / (2R) at the ring edges r_i = i a/n, i = 1..n (the
  paper's w is positive out of the body; ours is positive into it).
* Eq. 10: u_i = i^2 u_1 for 2 <= i <= m.
* Eq. 11 (Coulomb in the slip rings m < i <= n): the print says q_i = k p_i,
  but q_i is the *coefficient* of a shear that grows like r/a across the ring.
  Two readings are offered:

  - ``coulomb="resultant"`` (``method="paper"``, the one we defend): the
    ring's friction force equals k times its normal force,
    q_i <r^2>_i / a = k p_i <r>_i, i.e. Coulomb's law on the element's
    resultant (for the cylinder the steps make both readings identical);
  - ``coulomb="coefficient"`` (``method="paper-literal"``): q_i = k p_i as
    printed, which makes the traction ratio k r/a instead of k.

* Eq. 12: q_1 = q_2 (sphere) or q_1 = q_2 / 2 (cylinder), and the adherence
  condition Eq. 8 at i = 1/2: u(a/2n) = u_1 / 4.
* Newton-Raphson from the paper's trial vector (frictionless pressures,
  q_j = 1, k = 0.1). A run that does not converge reports NaN for every value
  (its last iterate depends on the machine's round-off), with ``converged``
  False and a message.

Trap 1 of docs/methods.md: Eq. 9 uses only differences w_i - w_0, so nothing
excludes a flat-punch pressure; the scheme is kept as printed, and its
frictionless error is measured in the test-suite and docs/validation.md.
"""

from __future__ import annotations

import numpy as np
from scipy import linalg

from ..discrete import SelfSimilarSolution
from ..discretization.elements import uniform_mesh
from ..model import Contact
from ..discretization.operators import step_operator

__all__ = ["PaperSolution", "solve_paper", "ring_operator", "collocation_points"]


ring_operator = step_operator
"""Displacements (3, len(x), n) of unit step pressures (``part="normal"``) or unit
shear elements (``part="shear"``) on the rings: :func:`contactlib.discretization.operators.step_operator`."""


def _ring_operators(geometry: Contact, nodes: np.ndarray,
                    x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Displacements (3, len(x), n) of unit step pressures and unit shear elements."""
    return (step_operator(geometry, nodes, x, "normal"),
            step_operator(geometry, nodes, x, "shear"))


def collocation_points(n: int) -> np.ndarray:
    """The points the scheme evaluates displacements at: 0, a/2n and the ring edges."""
    r = np.linspace(0.0, 1.0, n + 1)
    return np.concatenate([[0.0, 0.5 / n], r[1:]])


class PaperSolution(SelfSimilarSolution):
    """Ring (strip) values of the paper's scheme (units E* = a = R = 1), the paper's kind.

    The fields are those of :class:`~contactlib.discrete.SelfSimilarSolution`:
    ``p`` the step pressures and ``traction`` the shear coefficients qc, one
    a ring; ``delta`` is NaN (Eq. 9 uses differences of w only) and there
    are no nodal displacements.
    """

    kind = "paper"

    @property
    def qc(self) -> np.ndarray:
        """The ring shear coefficients (``traction``)."""
        return self.traction

    def stick_points(self) -> np.ndarray:
        """Midpoints of the stick rings (step tractions)."""
        nodes, m = self.mesh.nodes, self.mesh.stick_index
        return 0.5 * (nodes[:m] + nodes[1:m + 1])

    def _ring(self, x: np.ndarray) -> np.ndarray:
        n = self.mesh.n
        return np.clip((np.asarray(x) * n).astype(int), 0, n - 1)

    def pressure(self, x: np.ndarray) -> np.ndarray:
        return np.where(np.asarray(x) <= 1.0, self.p[self._ring(x)], 0.0)

    def shear(self, x: np.ndarray) -> np.ndarray:
        return self.geometry.shear_shape(x) * self.qc[self._ring(x)]

    def displacements(self, x: np.ndarray):
        pr, sh = _ring_operators(self.geometry, self.mesh.nodes, np.asarray(x, dtype=float))
        with np.errstate(invalid="ignore"):  # du/dx is log-infinite on ring edges
            return tuple(pr[i] @ self.p + sh[i] @ self.qc for i in range(3))

    def tangential(self, x: np.ndarray):
        """(u, du/dx) at points x."""
        return self.displacements(x)[1:]

    def radial_displacement(self, x: np.ndarray) -> np.ndarray:
        """u at points x."""
        return self.displacements(x)[1]

    def slip_samples(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Slip-zone samples as the paper computes them: (x, weights, q, s).

        Ring midpoints of the slip rings, midpoint-rule weights, the shear
        there, and the slip rate s = 2u - xi du/dxi with du/dxi by central
        differences of the ring-midpoint displacements ("computed numerically
        from the discrete values of U").
        """
        r = self.mesh.nodes
        m = self.mesh.stick_index
        mids = 0.5 * (r[1:] + r[:-1])
        u = self.displacements(mids)[1]
        du = np.gradient(u, mids)
        s = 2.0 * u - mids * du
        return mids[m:], np.diff(r)[m:], self.shear(mids[m:]), s[m:]

    def load(self) -> float:
        """Total load of the step pressures (units E* a^3/R, or E* a^2/R per unit length)."""
        return self.geometry.indenter.load_of_steps(self.mesh.nodes, self.p)


def solve_paper(geometry: Contact, m: int, n: int, *, coulomb: str = "resultant",
                max_iter: int = 50, tol: float = 1e-12,
                ops: tuple[np.ndarray, np.ndarray | None] | None = None) -> PaperSolution:
    """Solve the paper's equations for stick ratio m/n.

    Parameters
    ----------
    geometry : Contact
    m : int
        Number of stick rings, 0 (frictionless) ... n (full adhesion).
    n : int
        Number of rings.
    coulomb : {"resultant", "coefficient"}
        Reading of Eq. 11 (see the module docstring).
    ops : (P, S), optional
        Precomputed ``ring_operator(geometry, nodes, collocation_points(n),
        part)`` for "normal" and "shear" (S may be None when m = 0).
    """
    mesh = uniform_mesh(n, m)
    r = mesh.nodes
    pts = collocation_points(n)
    if ops is None:
        pr, sh = _ring_operators(geometry, r, pts)
    else:
        pr, sh = ops
        want = (3, n + 2, n)
        if np.shape(pr) != want or (m > 0 and (sh is None or np.shape(sh) != want)):
            raise ValueError(f"precomputed ring operators must have shape {want}")
    w_p = pr[0][2:] - pr[0][0]
    rhs9 = -0.5 * r[1:] ** 2  # w positive into the body: w_i - w_0 = -r_i^2 / (2R)
    if m == 0:
        p = linalg.solve(w_p, rhs9)
        res = np.linalg.norm(w_p @ p - rhs9) / np.linalg.norm(rhs9)
        return PaperSolution(geometry, mesh, p, np.zeros(n), np.nan, 0.0, True, float(res), 1)

    w_q = sh[0][2:] - sh[0][0]
    u_p, u_q = pr[1], sh[1]
    # adherence rows: i = 2..m (Eq. 10) and i = 1/2
    idx = np.arange(2, m + 1) + 1  # row of r_i in pts is i + 1
    adh_p = np.vstack([u_p[idx] - (np.arange(2, m + 1) ** 2)[:, None] * u_p[2],
                       u_p[1] - 0.25 * u_p[2]])
    adh_q = np.vstack([u_q[idx] - (np.arange(2, m + 1) ** 2)[:, None] * u_q[2],
                       u_q[1] - 0.25 * u_q[2]])
    # Eq. 11 on the element's resultant: mean shear shape <r^2>/<r> of a ring, 1 of a strip
    ratio = geometry.indenter.mean_shear_shape(r) if coulomb == "resultant" else np.ones(n)
    eq12 = np.zeros(2 * n)
    eq12[n], eq12[n + 1] = 1.0, -geometry.indenter.paper_axis_shear_ratio

    if m == n:  # full adhesion: Eqs. 9, 10 and the i = 1/2 condition, linear
        a = np.vstack([np.hstack([w_p, w_q]), np.hstack([adh_p, adh_q])])
        b = np.concatenate([rhs9, np.zeros(n)])
        x = linalg.solve(a, b)
        res = np.linalg.norm(a @ x - b) / np.linalg.norm(b)
        return PaperSolution(geometry, mesh, x[:n], x[n:], np.nan, np.inf, True, float(res), 1)

    slip = np.arange(m, n)

    def residual(x: np.ndarray) -> np.ndarray:
        p, q, k = x[:n], x[n:2 * n], x[-1]
        return np.concatenate([w_p @ p + w_q @ q - rhs9, adh_p @ p + adh_q @ q,
                               ratio[slip] * q[slip] - k * p[slip], [eq12 @ x[:2 * n]]])

    def jacobian(x: np.ndarray) -> np.ndarray:
        p, k = x[:n], x[-1]
        jac = np.zeros((2 * n + 1, 2 * n + 1))
        jac[:n, :n], jac[:n, n:2 * n] = w_p, w_q
        jac[n:n + m, :n], jac[n:n + m, n:2 * n] = adh_p, adh_q
        rows = n + m + np.arange(slip.size)
        jac[rows, slip] = -k
        jac[rows, n + slip] = ratio[slip]
        jac[rows, -1] = -p[slip]
        jac[-1, :2 * n] = eq12
        return jac

    # paper's trial vector; k is signed here (q = k p in the slip zone: k < 0 for
    # beta < 0, outward slip) and reported >= 0
    sigma = -1.0 if geometry.slip_sign < 0 else 1.0
    x = np.concatenate([linalg.solve(w_p, rhs9), sigma * np.ones(n), [0.1 * sigma]])
    converged, it = False, 0
    for it in range(1, max_iter + 1):
        f = residual(x)
        dx = linalg.solve(jacobian(x), -f)
        x = x + dx
        if np.max(np.abs(dx)) <= tol * max(1.0, np.max(np.abs(x))):
            converged = True
            break
    res = float(np.linalg.norm(residual(x)) / np.linalg.norm(rhs9))
    msg = ""
    if not converged:
        # the last iterate of a run that did not converge is no data (it differs from one
        # BLAS kernel to the next): the case is kept, flagged, with NaN values
        msg = (f"Newton did not converge in {max_iter} iterations from the paper's trial "
               "vector; no root of the printed scheme is reported (NaN)")
        x = np.full_like(x, np.nan)
    return PaperSolution(geometry, mesh, x[:n], x[n:2 * n], np.nan, float(sigma * x[-1]),
                         converged, res, it, msg)
