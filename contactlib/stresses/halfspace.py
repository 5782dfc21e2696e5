"""The half-space's field (axisymmetric, the sphere) of piecewise-linear tractions.

Hankel transforms (Boussinesq's potentials, Sneddon)

    sigma_zz = int xi e^{-xi z} J0 [-P (1 + xi z) + Q xi z] dxi,
    sigma_rz = int xi e^{-xi z} J1 [-P xi z - Q (1 - xi z)] dxi,

    sigma_rr = int xi e^{-xi z} {J0 [(2Q - P) + (P - Q) xi z] + J1/(xi r) B} dxi,
    sigma_tt = int xi e^{-xi z} {J0 2 nu (Q - P) - J1/(xi r) B} dxi,
    B = (1 - 2 nu) P - 2 (1 - nu) Q + (Q - P) xi z,

(Papkovich-Neuber potentials 2G u = grad(phi + z psi) - 4 (1 - nu) psi e_z), with P(xi) =
int p J0(xi r) r dr and Q(xi) = int q J1(xi r) r dr in closed form for the piecewise-linear
tractions (:class:`~contactlib.stresses.pieces.TractionPieces`). The xi integral is the
quadrature of :mod:`contactlib.stresses.quadrature`; each depth takes the xi values up to
40/z only. On the surface (z = 0) the field is in closed form: the pressure's part is
Johnson's (sigma_rr = (1 - 2 nu)/r^2 int_0^r p t dt - p, Johnson Ch. 3), the shear's part
:func:`~contactlib.stresses.surface.surface_shear`. Units and signs:
:mod:`contactlib.stresses`.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import scipy.special as sp

from .inputs import CHUNK, COMPONENTS, check_grid, check_tractions
from .pieces import TractionPieces
from .quadrature import DEPTH_CUTOFF, halfspace_nodes
from .surface import surface_shear

__all__ = ["halfspace_stresses", "halfspace_pieces", "SUM_CHUNK"]


def halfspace_stresses(xi: Any, pressure: Any, shear: Any, x: Any, z: Any,
                       nu: float) -> dict[str, np.ndarray]:
    """Axisymmetric stresses in the half-space z >= 0 under tabulated p(r) and radial q(r).

    Parameters
    ----------
    xi : array_like, shape (m,)
        Increasing radii r/a >= 0 of the tabulated tractions (usually 0 ... 1).
    pressure, shear : array_like, shape (m,)
        p and the radial shear q at ``xi`` (any stress unit, e.g. p0); piecewise linear
        between, zero beyond ``xi[-1]``.
    x, z : array_like, 1-d
        Output grid: radius r/a >= 0 (negative values are read as |r|) and depth z/a >= 0.
    nu : float
        Poisson's ratio of the body.

    Returns
    -------
    dict of str to ndarray, shape (len(z), len(x))
        ``sigma_rr``, ``sigma_tt`` (hoop), ``sigma_zz``, ``sigma_rz`` in the unit of the
        tractions, tension positive. Error: the xi quadrature's, below 1e-9 of the
        tractions at z > 0; on z = 0 the ring integrals', 2e-12 (closed forms otherwise).
        A radial shear with q(0) != 0 is log-infinite on the surface's axis: sigma_rr
        and sigma_tt are NaN there (a solve's shear vanishes on the axis).
    """
    r, p, q = check_tractions(xi, pressure, shear)
    return halfspace_pieces(TractionPieces.from_nodes(r, p, q), x, z, nu)


def halfspace_pieces(pieces: TractionPieces, x: Any, z: Any, nu: float) -> dict[str, np.ndarray]:
    """The half-space field of tractions given as linear pieces (:func:`halfspace_stresses`)."""
    xs, zs = check_grid(x, z)
    rr = np.abs(xs)
    out = {k: np.zeros((zs.size, rr.size)) for k in COMPONENTS["sphere"]}
    inside, surface = zs > 0, zs == 0
    if np.any(inside):
        r_max = float(max(rr.max(), pieces.sb.max()))
        k, w = halfspace_nodes(DEPTH_CUTOFF / zs[inside].min(), r_max, float(zs.max()))
        P, Q = pieces.hankel(k)
        _hankel_sums(out, k, w, P, Q, rr, zs, nu, inside)
    if np.any(surface):
        # closed forms: the pressure's part (Johnson Ch. 3) and the shear's (ring integrals)
        pr, qr = pieces.at(rr)
        p_axis = pieces.at(np.zeros(1))[0][0]
        with np.errstate(invalid="ignore", divide="ignore"):
            moment = np.where(rr > 0, pieces.moment(rr) / np.where(rr > 0, rr, 1)**2,
                              0.5 * p_axis)
        q_rr, q_tt = surface_shear(pieces, rr, nu)
        j = np.flatnonzero(surface)
        out["sigma_zz"][j] = -pr
        out["sigma_rz"][j] = -qr
        out["sigma_rr"][j] = -pr + (1 - 2 * nu) * moment + q_rr
        out["sigma_tt"][j] = -2 * nu * pr - (1 - 2 * nu) * moment + q_tt
    return out


# measured: benchmarks/bench_stresses.py (k values a chunk of the depth sums: depths drop
# out chunk by chunk as xi z passes 40; 32 to 64 were fastest, 512 1.2 times slower)
SUM_CHUNK = 32


def _hankel_sums(out: dict[str, np.ndarray], k: np.ndarray, w: np.ndarray, P: np.ndarray,
                 Q: np.ndarray, r: np.ndarray, z: np.ndarray, nu: float,
                 inside: np.ndarray) -> None:
    """Add the xi integrals of the depths z > 0 (``inside``) to ``out``: (J(k r) w) @
    (polynomial in k z times e^{-k z}), each depth only over the chunks of k (increasing)
    where k z < 40 (e^{-k z} < 4e-18 beyond)."""
    jin = np.flatnonzero(inside)
    zi = z[jin]
    step = max(1, min(SUM_CHUNK, CHUNK // max(r.size, zi.size, 1)))
    for i in range(0, k.size, step):
        kc, wc, Pc, Qc = k[i:i + step], w[i:i + step], P[i:i + step], Q[i:i + step]
        active = kc[0] * zi < 40.0
        if not active.any():
            break
        ja, kz = jin[active], np.outer(kc, zi[active])
        x = np.outer(r, kc)
        j0 = sp.j0(x) * wc
        j1 = sp.j1(x)
        j1x = np.where(x > 0, j1 / np.where(x > 0, x, 1.0), 0.5) * wc
        j1 = j1 * wc
        # exact zeros beyond e^-40 (denormals would slow every product down)
        e0 = np.where(kz < 40.0, np.exp(-np.minimum(kz, 40.0)), 0.0)
        e1 = kz * e0
        kP, kQ = (kc * Pc)[:, None], (kc * Qc)[:, None]
        a1 = (1 - 2 * nu) * kP - 2 * (1 - nu) * kQ  # the J1/(k r) bracket
        b1 = kQ - kP
        out["sigma_zz"][ja] += (j0 @ (-kP * e0 + b1 * e1)).T
        out["sigma_rz"][ja] += (j1 @ (-kQ * e0 + b1 * e1)).T
        bracket = j1x @ (a1 * e0 + b1 * e1)
        out["sigma_rr"][ja] += (j0 @ ((2 * kQ - kP) * e0 - b1 * e1)).T + bracket.T
        out["sigma_tt"][ja] += (j0 @ (2 * nu * b1 * e0)).T - bracket.T

