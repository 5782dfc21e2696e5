"""Frictional work of the loading half-cycle (paper Eqs. 17-21).

With the self-similar scalings p = a P(xi), u = a^2 U(xi), the slip of a point
when the contact radius grows by da is a (2U - xi U') da (Eq. 18), so that

* sphere:   V R^2/(E* a^5) = (2 pi / 5) int_c^1 xi q(xi) (-s(xi)) dxi,
* cylinder: V R^2/(E* a^4) = (1 / 2)    int_c^1    q(xi) (-s(xi)) dxi
  (per unit length, both sides of the axis),

in units E* = a = R = 1 where q and s = 2u - xi du/dxi are the traction and
slip rate at a = 1. ``du/dxi`` comes from the exact derivative kernels, not
from differences of nodal displacements.
"""

from __future__ import annotations

import numpy as np

__all__ = ["slip_points", "frictional_work"]


def slip_points(nodes: np.ndarray, stick_index: int, order: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss points and weights of every slip element (between node M and a)."""
    t, w = np.polynomial.legendre.leggauss(order)
    lo, hi = nodes[stick_index:-1], nodes[stick_index + 1:]
    h = hi - lo
    x = (lo[:, None] + 0.5 * h[:, None] * (t[None, :] + 1.0)).ravel()
    wt = (0.5 * h[:, None] * w[None, :]).ravel()
    return x, wt


def frictional_work(x: np.ndarray, weights: np.ndarray, q: np.ndarray, s: np.ndarray,
                    factor: float, power: int) -> float:
    """V in the scaling of docs/conventions.md: factor * sum w x^power q (-s)."""
    return float(factor * np.sum(weights * x**power * q * (-s)))
