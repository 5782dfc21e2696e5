"""The half-plane's field (plane strain, the cylinder) of piecewise-linear tractions.

Exact for the piecewise-linear tractions: the Flamant kernels (Johnson, *Contact
Mechanics*, 1985, Ch. 2) integrated in closed form over each linear piece (antiderivatives
of u^k / (u^2 + z^2)^2, k = 0 ... 4); only round-off is added to the tractions' own
discretization. sigma_yy = nu (sigma_xx + sigma_zz). Units and signs:
:mod:`contactlib.stresses`.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .inputs import CHUNK, COMPONENTS, check_grid, check_tractions

__all__ = ["halfplane_stresses", "halfplane_stresses_line", "halfplane_pieces"]


def _plane_antiderivatives(u: np.ndarray, z: np.ndarray) -> dict[str, np.ndarray]:
    """Antiderivatives in u of the Flamant kernels' moments, scaled to stay finite at z = 0.

    With D = u^2 + z^2 and M_k = int u^k / D^2 du: ``z3M0`` = z^3 M0, ``z2M1``, ``zM2``,
    ``M3``, ``M4``.
    """
    d = u * u + z * z
    dsafe = np.where(d > 0, d, 1.0)  # ln(dsafe) = 0 where d = 0
    zinv = z * (0.5 / dsafe)
    zu = zinv * u
    half_at = 0.5 * np.arctan2(u, z)
    z2M1 = -z * zinv
    return {"z3M0": half_at + zu,
            "z2M1": z2M1,
            "zM2": half_at - zu,
            "M3": 0.5 * np.log(dsafe) - z2M1,
            "M4": u - 3.0 * z * half_at - z2M1 * u}


def halfplane_stresses(xi: Any, pressure: Any, shear: Any, x: Any, z: Any,
                       nu: float) -> dict[str, np.ndarray]:
    """Plane-strain stresses in the half-plane z >= 0 under tabulated p(x) and q(x).

    Parameters
    ----------
    xi : array_like, shape (m,)
        Increasing abscissae x/a >= 0 of the tabulated tractions (usually 0 ... 1).
    pressure, shear : array_like, shape (m,)
        p and q at ``xi`` (any stress unit, e.g. p0); piecewise linear between, zero
        beyond ``xi[-1]``. p is even in x, q odd (positive away from the axis: q > 0
        acts in +x for x > 0).
    x, z : array_like, 1-d
        Output grid, x/a and depth z/a >= 0.
    nu : float
        Poisson's ratio of the body (enters sigma_yy only).

    Returns
    -------
    dict of str to ndarray, shape (len(z), len(x))
        ``sigma_xx``, ``sigma_yy``, ``sigma_zz``, ``sigma_xz`` in the unit of the
        tractions, tension positive; exact for the piecewise-linear tractions up to
        round-off.
    """
    r, p, q = check_tractions(xi, pressure, shear)
    # both halves: p(-x) = p(x), q(-x) = -q(x); a gap or a jump at x = 0 is two pieces
    # that do not meet
    starts = np.concatenate([-r[:0:-1], r[:-1]])
    ends = np.concatenate([-r[-2::-1], r[1:]])
    pa = np.concatenate([p[:0:-1], p[:-1]])
    pb = np.concatenate([p[-2::-1], p[1:]])
    qa = np.concatenate([-q[:0:-1], q[:-1]])
    qb = np.concatenate([-q[-2::-1], q[1:]])
    return halfplane_pieces(starts, ends, pa, pb, qa, qb, x, z, nu)


def halfplane_stresses_line(s: Any, pressure: Any, shear: Any, x: Any, z: Any,
                            nu: float) -> dict[str, np.ndarray]:
    """:func:`halfplane_stresses` for tractions tabulated over the whole line.

    Parameters
    ----------
    s : array_like, shape (m,)
        Increasing abscissae x/a (any sign) of the tractions, zero outside
        [s[0], s[-1]].
    pressure, shear : array_like, shape (m,)
        p and the shear q in +x (no symmetry assumed: e.g. sliding, q = mu p).
    x, z, nu
        As for :func:`halfplane_stresses`.

    Returns
    -------
    dict of str to ndarray, shape (len(z), len(x))
        As :func:`halfplane_stresses`.
    """
    from ..validate import InputError

    t = np.asarray(s, dtype=float)
    p = np.asarray(pressure, dtype=float)
    q = np.asarray(shear, dtype=float)
    if t.ndim != 1 or t.size < 2 or p.shape != t.shape or q.shape != t.shape \
            or np.any(np.diff(t) <= 0):
        raise InputError("s", "an increasing 1-d array, pressure and shear of its shape", t)
    return halfplane_pieces(t[:-1], t[1:], p[:-1], p[1:], q[:-1], q[1:], x, z, nu)


def halfplane_pieces(sa: np.ndarray, sb: np.ndarray, pa: np.ndarray, pb: np.ndarray,
                      qa: np.ndarray, qb: np.ndarray, x: Any, z: Any,
                      nu: float) -> dict[str, np.ndarray]:
    """Johnson's half-plane integrals (Contact Mechanics, Ch. 2) done exactly over linear
    pieces [sa, sb] (values a -> b)."""
    xs, zs = check_grid(x, z)
    h = sb - sa
    mp, mq = (pb - pa) / h, (qb - qa) / h
    cp, cq = pa - mp * sa, qa - mq * sa  # f(s) = c + m s = (c + m x) - m u, u = x - s
    nodes = np.union1d(sa, sb)
    ia, ib = np.searchsorted(nodes, sa), np.searchsorted(nodes, sb)
    X, Z = np.meshgrid(xs, zs)
    xf, zf = X.ravel(), Z.ravel()
    out = {k: np.empty(xf.size) for k in ("sigma_xx", "sigma_zz", "sigma_xz")}
    # a sum over the pieces of c (F(x - sa) - F(x - sb)) as node weights times F at nodes
    cp, mp, cq, mq = (np.bincount(ia, v, nodes.size) - np.bincount(ib, v, nodes.size)
                      for v in (cp, mp, cq, mq))
    step = max(1, CHUNK // nodes.size)
    for i in range(0, xf.size, step):
        xc, zc = xf[i:i + step], zf[i:i + step]
        dm = _plane_antiderivatives(xc[:, None] - nodes, zc[:, None])
        # int over a piece of (A - m u) K(u) du, u from x - sb up to x - sa, A = c + m x

        def weighted(key: str, c: np.ndarray, m: np.ndarray) -> np.ndarray:
            d = dm[key]
            return d @ c + xc * (d @ m)

        zM3 = np.where(zc > 0, zc * (dm["M3"] @ mp), 0.0)  # z ln(D) -> 0 on the surface
        zM3q = np.where(zc > 0, zc * (dm["M3"] @ mq), 0.0)
        sxx = weighted("zM2", cp, mp) - zM3 + weighted("M3", cq, mq) - dm["M4"] @ mq
        szz = (weighted("z3M0", cp, mp) - zc * (dm["z2M1"] @ mp) + weighted("z2M1", cq, mq)
               - zc * (dm["zM2"] @ mq))
        sxz = weighted("z2M1", cp, mp) - zc * (dm["zM2"] @ mp) + weighted("zM2", cq, mq) - zM3q
        for name, v in (("sigma_xx", sxx), ("sigma_zz", szz), ("sigma_xz", sxz)):
            out[name][i:i + step] = -(2.0 / math.pi) * v
    res = {k: v.reshape(X.shape) for k, v in out.items()}
    res["sigma_yy"] = nu * (res["sigma_xx"] + res["sigma_zz"])
    return {k: res[k] for k in COMPONENTS["cylinder"]}
