"""Frictional work: of the self-similar loading half-cycle, and of an incremental step.

Self-similar loading (paper Eqs. 17-21)
---------------------------------------
With the self-similar scalings p = a P(xi), u = a^2 U(xi), the slip of a point
when the contact radius grows by da is a (2U - xi U') da (Eq. 18), so that

* sphere:   V R^2/(E* a^5) = (2 pi / 5) int_c^1 xi q(xi) (-s(xi)) dxi,
* cylinder: V R^2/(E* a^4) = (1 / 2)    int_c^1    q(xi) (-s(xi)) dxi
  (per unit length, both sides of the axis),

in units E* = a = R = 1 where q and s = 2u - xi du/dxi are the traction and
slip rate at a = 1. ``du/dxi`` comes from the exact derivative kernels, not
from differences of nodal displacements. The factor and the power are the
indenter's (:attr:`contactlib.indenter.Indenter.work_factor`,
:attr:`~contactlib.indenter.Indenter.work_weight_power`).

Incremental steps (:mod:`contactlib.history_solver`)
----------------------------------------------------
A load step moves element j by ``du_j`` against a traction that changes
from ``q_j^old`` to ``q_j^new``; its work is taken by the trapezoid rule in
time, ``|(q_old + q_new)/2| |du| A_j``, over the elements slipping at the end
of the step (stuck elements have ``du = 0``, and an element that separates
releases its traction without slip under load). ``A_j`` is the element's
shear resultant per unit shear at its midpoint; in units E* = R = a_max = 1
the sum is V R^2/(E* a_max^5) (sphere) or V R^2/(E* a_max^4) per unit length
(cylinder).
"""

from __future__ import annotations

import numpy as np

__all__ = ["slip_points", "frictional_work", "step_work"]


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


def step_work(q_old: np.ndarray, q_new: np.ndarray, du: np.ndarray, shear_area: np.ndarray,
              slipping: np.ndarray) -> float:
    """Frictional work of one incremental load step (trapezoid rule in time).

    Parameters
    ----------
    q_old, q_new : ndarray, shape (n,)
        Shear at the start and at the end of the step (units E* a_max/R).
    du : ndarray, shape (n,)
        Tangential displacement increment of the step (units a_max^2/R).
    shear_area : ndarray, shape (n,)
        Shear resultant of each element per unit midpoint shear (units
        a_max^2, or a_max per unit length).
    slipping : ndarray of bool, shape (n,)
        Elements slipping at the end of the step.

    Returns
    -------
    float
        sum over the slipping elements of ``|(q_old + q_new)/2| |du| A_j`` (>= 0).
    """
    return float(np.sum((np.abs(0.5 * (q_old + q_new)) * np.abs(du) * shear_area)[slipping]))
