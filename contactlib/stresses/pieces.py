"""Tractions as linear pieces and their Hankel transforms in closed form.

:class:`TractionPieces` holds p = cp + mp r and q = cq + mq r on each piece and gives
P(xi) = int p J0(xi r) r dr and Q(xi) = int q J1(xi r) r dr exactly for them, through
int_0^x J0, the same in every supported scipy (``INTEGRAL_J0_SWITCH``,
``INTEGRAL_J0_ASYMPTOTIC``); and the values and moments the surface row's closed forms need.
"""

from __future__ import annotations

import numpy as np
import scipy.special as sp

from .inputs import CHUNK

__all__ = ["TractionPieces", "INTEGRAL_J0_SWITCH", "INTEGRAL_J0_ASYMPTOTIC"]


class TractionPieces:
    """Tractions as linear pieces: on [sa, sb], p = cp + mp r and q = cq + mq r.

    Adjacent pieces may share an end (continuous tabulated tractions) or not (element
    tractions of a history); zero outside every piece.
    """

    def __init__(self, sa: np.ndarray, sb: np.ndarray, pa: np.ndarray, pb: np.ndarray,
                 qa: np.ndarray, qb: np.ndarray) -> None:
        h = sb - sa
        self.sa, self.sb = sa, sb
        self.qa, self.qb = qa, qb
        self.mp, self.mq = (pb - pa) / h, (qb - qa) / h
        self.cp, self.cq = pa - self.mp * sa, qa - self.mq * sa
        self.nodes = np.union1d(sa, sb)
        self.ia, self.ib = np.searchsorted(self.nodes, sa), np.searchsorted(self.nodes, sb)

    @classmethod
    def from_nodes(cls, r: np.ndarray, p: np.ndarray, q: np.ndarray) -> "TractionPieces":
        return cls(r[:-1], r[1:], p[:-1], p[1:], q[:-1], q[1:])

    def on_nodes(self, c: np.ndarray) -> np.ndarray:
        """Per-node weights of a sum over the pieces of c (g(sb) - g(sa)): sum_j g(node_j)
        times the result."""
        n = self.nodes.size
        return np.bincount(self.ib, c, n) - np.bincount(self.ia, c, n)

    def at(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """p and q at ``x`` (the last piece starting at or before x; 0 outside them all)."""
        i = np.clip(np.searchsorted(self.sa, x, side="right") - 1, 0, self.sa.size - 1)
        inside = (x >= self.sa[i]) & (x <= self.sb[i])
        p = np.where(inside, self.cp[i] + self.mp[i] * x, 0.0)
        q = np.where(inside, self.cq[i] + self.mq[i] * x, 0.0)
        return p, q

    def moment(self, x: np.ndarray) -> np.ndarray:
        """int_0^x p(t) t dt, exactly."""
        lo = np.minimum(np.maximum(x[:, None], self.sa[None, :]), self.sb[None, :])
        return (self.cp * (lo**2 - self.sa**2) / 2.0
                + self.mp * (lo**3 - self.sa**3) / 3.0).sum(axis=1)

    def hankel(self, k: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """P(k) = int p J0(k r) r dr and Q(k) = int q J1(k r) r dr, in closed form.

        On each piece int r J0 = x J1 / k^2, int r^2 J0 = (x^2 J1 + x J0 - int_0^x J0) /
        k^3, int r J1 = (int_0^x J0 - x J0) / k^2, int r^2 J1 = x^2 J2 / k^3 (x = k r),
        summed over the pieces as weights on their ends (:meth:`on_nodes`).
        """
        P, Q = np.empty(k.size), np.empty(k.size)
        a0, a1, b0, b1 = (self.on_nodes(c) for c in (self.cp, self.mp, self.cq, self.mq))
        step = max(1, CHUNK // self.nodes.size)
        for i in range(0, k.size, step):
            kk = k[i:i + step]
            x = kk[:, None] * self.nodes[None, :]
            j0, j1 = sp.j0(x), sp.j1(x)
            ij0 = _integral_j0(x, j0, j1)
            small = x <= 1.0  # the recurrence J2 = 2 J1/x - J0 cancels at small x
            j2 = 2.0 * j1 / np.where(small, 1.0, x) - j0
            j2[small] = sp.jv(2, x[small])
            xj0, xj1 = x * j0, x * j1
            P[i:i + step] = (xj1 @ a0) / kk**2 + ((x * xj1 + xj0 - ij0) @ a1) / kk**3
            Q[i:i + step] = ((ij0 - xj0) @ b0) / kk**2 + ((x * x * j2) @ b1) / kk**3
        return P, Q


# tested: tests/test_stresses.py (int_0^x J0 against mpmath to 2e-11, x = 0.5 ... 4321);
# scipy's itj0y0 drifts beyond it
INTEGRAL_J0_SWITCH = 15.0
"""Up to this argument ``int_0^x J0`` is scipy's ``itj0y0`` (9.8e-12 off at 14.9). Beyond
it ``itj0y0`` drifts: 4.5e-10 off at 20 in scipy 1.13 and 1.17, and 1.13's is of order 1e10
from x ~ 21 on. Between it and ``INTEGRAL_J0_ASYMPTOTIC`` the integral is a Chebyshev
series of degree 32 (``_INTEGRAL_J0_MID``, within 1e-14 of mpmath) interpolating its value
at 15 (``_INTEGRAL_J0_AT_SWITCH``, from mpmath's x 1F2(1/2; 1, 3/2; -x^2/4) at 40 digits)
plus the rest by 24-point Gauss-Legendre (J0 is entire, the interval at most 15 long: below
1e-14)."""

# tested: tests/test_stresses.py (int_0^x J0 against mpmath to 2e-11, x = 0.5 ... 4321);
# the asymptotic series' ten terms are within 2.2e-13 from here on
INTEGRAL_J0_ASYMPTOTIC = 30.0
"""Above this argument ``int_0^x J0`` comes from the asymptotic series of the Struve
functions (Abramowitz & Stegun 12.1.31) and the Wronskian J1 Y0 - J0 Y1 = 2/(pi x):
int_0^x J0 = 1 + J1 S0 - x J0 T1 with S0 = sum_k (-1)^k ((2k-1)!!)^2 x^-2k and T1 =
sum_(k>=1) (-1)^k ((2k-1)!!)^2 / (1 - 2k) x^-2k, 10 terms. Against scipy 1.17's
``itj0y0`` it is within 2.2e-13 on [30, 80] and 2e-15 from 40 on. It replaces the
identity through Struve functions, x J0 + (pi x/2)(J1 H0 - J0 H1), whose cost dominated a
sphere's field (a 100 x 100 grid: 4.9 s CPU before, 1.9 s after, on one machine)."""

_GAUSS_24 = np.polynomial.legendre.leggauss(24)
_INTEGRAL_J0_AT_SWITCH = 1.205161936344904467  # exact: int_0^15 J0 (mpmath, 40 digits)
# tested: tests/test_stresses.py (int_0^x J0 to 2e-11 against mpmath up to x = 4321; the
# ten terms reach 2.2e-13 at x = 30)
_ASYMPTOTIC_TERMS = 10
_DOUBLE_FACTORIAL_SQUARED = np.cumprod([1.0] + [(2.0 * k - 1.0)**2
                                                for k in range(1, _ASYMPTOTIC_TERMS + 1)])


def _integral_j0_asymptotic(x: np.ndarray, j0: np.ndarray, j1: np.ndarray) -> np.ndarray:
    """int_0^x J0(t) dt for large x (see INTEGRAL_J0_ASYMPTOTIC), by Horner in 1/x^2;
    ``j0``, ``j1`` are J0(x) and J1(x)."""
    u = 1.0 / (x * x)
    c = _DOUBLE_FACTORIAL_SQUARED
    top = _ASYMPTOTIC_TERMS
    s0 = np.full_like(x, (-1)**top * c[top])
    t1 = np.full_like(x, (-1)**top * c[top] / (1 - 2 * top))
    for k in range(top - 1, -1, -1):
        s0 *= u
        s0 += (-1)**k * c[k]
        if k > 0:
            t1 *= u
            t1 += (-1)**k * c[k] / (1 - 2 * k)
    t1 *= u
    return 1.0 + j1 * s0 - x * j0 * t1


def _integral_j0_gauss(x: np.ndarray) -> np.ndarray:
    """int_0^x J0 for x in [INTEGRAL_J0_SWITCH, INTEGRAL_J0_ASYMPTOTIC]: the value at the
    switch plus 24-point Gauss-Legendre (fits ``_INTEGRAL_J0_MID`` once)."""
    start = INTEGRAL_J0_SWITCH
    half = 0.5 * (x - start)
    t, w = _GAUSS_24
    nodes = (start + half)[:, None] + half[:, None] * t[None, :]
    return _INTEGRAL_J0_AT_SWITCH + half * (sp.j0(nodes) @ w)


_MID_CENTRE = 0.5 * (INTEGRAL_J0_ASYMPTOTIC + INTEGRAL_J0_SWITCH)
_MID_HALF = 0.5 * (INTEGRAL_J0_ASYMPTOTIC - INTEGRAL_J0_SWITCH)
# tested: tests/test_stresses.py (int_0^x J0 against mpmath to 2e-11 across [15, 30]);
# degree 32 interpolates the Gauss-Legendre values to 1e-14 (28: 2e-14, 24: 2e-12)
_INTEGRAL_J0_MID_DEGREE = 32
_INTEGRAL_J0_MID = np.polynomial.chebyshev.chebinterpolate(
    lambda u: _integral_j0_gauss(_MID_CENTRE + _MID_HALF * u), _INTEGRAL_J0_MID_DEGREE)


def _integral_j0(x: np.ndarray, j0: np.ndarray | None = None,
                 j1: np.ndarray | None = None) -> np.ndarray:
    """int_0^x J0(t) dt, the same in every supported scipy (see INTEGRAL_J0_SWITCH);
    ``j0``, ``j1``: J0(x) and J1(x) if the caller has them. The asymptotic series is
    evaluated everywhere (no gathers of the large arrays) and replaced below its range."""
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        out = _integral_j0_asymptotic(x, sp.j0(x) if j0 is None else j0,
                                      sp.j1(x) if j1 is None else j1)
    below = x <= INTEGRAL_J0_ASYMPTOTIC
    if below.any():
        xb = x[below]
        vals = np.polynomial.chebyshev.chebval((xb - _MID_CENTRE) / _MID_HALF,
                                               _INTEGRAL_J0_MID)
        low = xb <= INTEGRAL_J0_SWITCH
        vals[low] = sp.itj0y0(xb[low])[0]
        out[below] = vals
    return out
