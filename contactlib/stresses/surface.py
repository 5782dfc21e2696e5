"""The half-space's surface row (z = 0) under a radial shear, in closed form.

The shear's part of sigma_rr and sigma_tt follows from U(r) = int q(t) t W(r, t) dt with the
ring kernel W = int_0^inf J1(k r) J1(k t) dk (complete elliptic integrals K, E), integrated
over each linear piece by Gauss-Legendre (``RING_GAUSS``; tanh-sinh, ``RING_TANH_SINH``,
next to the kernel's log singularity at t = r): 2e-12 p0 against rules of twice the
density, and the closed form of q = r on r < a to 1e-13 (benchmarks/bench_stresses.py).
The pressure's part is Johnson's (:mod:`contactlib.stresses.halfspace`).
"""

from __future__ import annotations

import math

import numpy as np
import scipy.special as sp

from .inputs import CHUNK
from .pieces import TractionPieces

__all__ = ["RING_TANH_SINH", "RING_GAUSS", "RING_SERIES_M", "surface_shear"]


def _tanh_sinh(step: float, span: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Tanh-sinh nodes on [0, 1]: x, 1 - x (accurate near 1) and the weights."""
    s = np.arange(-span, span + 0.5 * step, step)
    y = 0.5 * math.pi * np.sinh(s)
    return (1.0 / (1.0 + np.exp(-2.0 * y)), 1.0 / (1.0 + np.exp(2.0 * y)),
            step * 0.25 * math.pi * np.cosh(s) / np.cosh(y)**2)


# measured: benchmarks/bench_stresses.py (the surface row against rules of twice the density,
# 2e-12 p0 on a grid through the tractions' nodes): 39 nodes, weights below 1e-20 at the ends
RING_TANH_SINH = (1.0 / 6.0, 3.2)
"""(step, span) of the tanh-sinh rule of the ring integrals next to the log singularity at
t = r: nodes s = -span ... span, step apart."""
# measured: benchmarks/bench_stresses.py (as RING_TANH_SINH): the nearest singularity (t = r)
# lies 3 half-lengths from a far piece's centre, 3.73^-20 = 4e-12
RING_GAUSS = 10
"""Gauss-Legendre points of a ring integral over a piece at least its length away from r."""
# exact: below it the series' next term is 5e-17 relative, above it the direct form loses
# at most 1e-13 to the cancellation of K - E
RING_SERIES_M = 1e-3
"""m = (min/max)^2 below which (K(m) - E(m))/sqrt(m) comes from its Taylor series."""


def _ring_kernel(r: np.ndarray, t: np.ndarray, delta: np.ndarray) -> np.ndarray:
    """W(r, t) = int_0^inf J1(k r) J1(k t) dk = 2/(pi M) (K(m) - E(m))/sqrt(m), M = max(r,
    t) > 0, m = (min/max)^2 (elliptic parameter); ``delta`` = t - r given accurately (the
    log singularity at t = r); 0 where min(r, t) = 0."""
    big = np.maximum(r, t)
    ratio = np.minimum(r, t) / big
    m1 = np.abs(delta) / big
    m1 *= 1.0 + ratio
    np.maximum(m1, 1e-300, out=m1)
    with np.errstate(invalid="ignore", divide="ignore"):
        out = (sp.ellipkm1(m1) - sp.ellipe(1.0 - m1)) / ratio
    small = ratio * ratio < RING_SERIES_M
    if small.any():
        q = ratio[small]
        m = q * q
        out[small] = q * (0.5 + m * (3 / 16 + m * (15 / 128 + m * (175 / 2048
                                                                  + m * 2205 / 32768))))
        out[small] *= 0.5 * math.pi
    out *= 2.0 / math.pi
    out /= big
    return out


def _ring_moments(r: np.ndarray, sa: np.ndarray, sb: np.ndarray) -> tuple[np.ndarray, ...]:
    """I_j[i, l] = int_{sa_l}^{sb_l} t^j W(r_i, t) dt for j = 1, 2 and r_i > 0: Gauss-Legendre
    (``RING_GAUSS`` points) for a piece at least its length away from r_i, else tanh-sinh
    (``RING_TANH_SINH``) on each side of r_i."""
    shape = (r.size, sa.size)
    R, A, B = (np.broadcast_to(v, shape) for v in (r[:, None], sa[None, :], sb[None, :]))
    far = np.maximum(np.maximum(A - R, R - B), 0.0) >= B - A
    moments = np.zeros((2,) + shape)
    t0, w0 = np.polynomial.legendre.leggauss(RING_GAUSS)
    rf, af, bf = R[far][:, None], A[far][:, None], B[far][:, None]
    t = 0.5 * (af + bf) + 0.5 * (bf - af) * t0
    wt = _ring_kernel(rf, t, t - rf) * (0.5 * (bf - af) * w0) * t
    moments[0][far], moments[1][far] = wt.sum(axis=1), (wt * t).sum(axis=1)
    rn, an, bn = R[~far][:, None], A[~far][:, None], B[~far][:, None]
    x, xc, wx = _tanh_sinh(*RING_TANH_SINH)
    cut = np.clip(rn, an, bn)
    for lo, hi in ((an, cut), (cut, bn)):
        length = hi - lo
        t = lo + length * x
        delta = np.where(x < 0.5, (lo - rn) + length * x, (hi - rn) - length * xc)
        wt = _ring_kernel(rn, t, delta) * (length * wx) * t
        moments[0][~far] += wt.sum(axis=1)
        moments[1][~far] += (wt * t).sum(axis=1)
    return moments[0], moments[1]


def surface_shear(pieces: TractionPieces, r: np.ndarray,
                   nu: float) -> tuple[np.ndarray, np.ndarray]:
    """The radial shear's part of sigma_rr and sigma_tt on the surface z = 0, at r >= 0.

    With U(r) = int_0^inf Q(k) J1(k r) dk = int q(t) t W(r, t) dt (half the surface radial
    displacement times E*), sigma_rr = 2 U' + 2 nu U/r and sigma_tt = 2 nu U' + 2 U/r (the
    xi integrals of the module's notes at z = 0). W is homogeneous of degree -1, so r dW/dr
    = -W - t dW/dt, and by parts r U' = sum over the pieces of int (c t + 2 m t^2) W dt minus
    the jumps of q (ends included) times t^2 W(r, t) at them (a traction jump's stress is
    log-singular there). On the axis U' = U/r = (1/2) int_0^inf q/t dt (log-infinite if
    q(0) != 0, a radial traction that does not vanish on the axis: see the code).
    """
    out_rr, out_tt = np.zeros(r.size), np.zeros(r.size)
    if not (np.any(pieces.cq != 0) or np.any(pieces.mq != 0)):
        return out_rr, out_tt
    n = pieces.nodes.size
    jump = np.bincount(pieces.ib, pieces.qb, n) - np.bincount(pieces.ia, pieces.qa, n)
    jumps = np.flatnonzero(jump)
    axis = r == 0
    pos = np.flatnonzero(~axis)
    step = max(1, CHUNK // (pieces.sa.size * RING_GAUSS))
    for i in range(0, pos.size, step):
        idx = pos[i:i + step]
        rp = r[idx]
        i1, i2 = _ring_moments(rp, pieces.sa, pieces.sb)
        u = i1 @ pieces.cq + i2 @ pieces.mq
        tj = pieces.nodes[jumps]
        wj = _ring_kernel(rp[:, None], tj[None, :], tj[None, :] - rp[:, None])
        du = (i1 @ pieces.cq + 2.0 * (i2 @ pieces.mq) - (wj * tj**2) @ jump[jumps]) / rp
        out_rr[idx] = 2.0 * du + 2.0 * nu * u / rp
        out_tt[idx] = 2.0 * nu * du + 2.0 * u / rp
    if np.any(axis):
        # q(0) != 0 makes the axis value log-infinite: no number there (NaN)
        at_axis = pieces.sa == 0
        if np.any(at_axis & (pieces.cq != 0)):
            value = math.nan
        else:
            start = np.where(at_axis, 1.0, pieces.sa)  # (cq = 0 on the pieces from 0)
            with np.errstate(invalid="ignore", divide="ignore"):
                logs = np.where(pieces.cq != 0, pieces.cq * np.log(pieces.sb / start), 0.0)
            value = (1 + nu) * (logs.sum() + pieces.mq @ (pieces.sb - pieces.sa))
        out_rr[axis] = out_tt[axis] = value
    return out_rr, out_tt
