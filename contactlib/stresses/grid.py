"""Stresses in the half-space under cell-wise constant tractions on a square grid (issue 38).

The sphere's fretting solver (:mod:`contactlib.solvers.fretting_sphere`) carries a pressure p and a
shear (q_x, q_y), each constant on the cells of a uniform square grid; the shear is a
2-D vector field, which neither the axisymmetric field of :mod:`contactlib.stresses` nor
the fixed-direction shear of :mod:`contactlib.stresses.tangential` covers. This module
gives the full Cartesian field of such tractions, and of one step of a fretting run.

Signs and units are those of :mod:`contactlib.stresses`: tension positive, z > 0 the
depth into the body, p positive in compression, (q_x, q_y) the traction the indenter
exerts on the body (docs/conventions.md), so that the surface limits are sigma_zz = -p,
sigma_xz = -q_x and sigma_yz = -q_y. Stresses are in the unit of the tractions, lengths
in the unit of the grid.

Method
------
Exact for the piecewise-constant tractions: the Boussinesq and Cerruti point-force
stresses are integrated in closed form over each rectangle (Love 1929 for sigma_zz under
a pressure). With Johnson's potentials (*Contact Mechanics*, 1985, eqs. 3.6-3.7),
Omega = z ln(rho + z) - rho, every component of a uniform traction t on a rectangle is a
sum of derivatives of I = int int Omega(x - xi, y - eta, z) d xi d eta (a harmonic
function) with coefficients linear in z and nu; with d^2/dy^2 = -d^2/dx^2 - d^2/dz^2 they
reduce to 14 derivatives D = d^a/dx^a d^b/dy^b d^c/dz^c, b <= 1. Each is the corner sum
C(x - xi1, y - eta1) - C(x - xi2, y - eta1) - C(x - xi1, y - eta2) + C(x - xi2, y - eta2)
of an elementary function C with d^2 C/dX dY = D Omega (``_corners``; derived with a
computer algebra system and checked by differentiation). On a grid the corner sums of
all cells collapse to one sum over the grid's corners, weighted by the second difference
of the tractions. Only round-off is added: the field agrees with Love's closed form to
1e-14 of the pressure (tests/test_stresses_grid.py). Two routes sum over the corners:

* :func:`grid_stresses` / :func:`stresses_at`, at any points: a matrix product, in chunks
  of ``CHUNK`` numbers an array; (points) x (corners where the tractions change)
  evaluations of the 14 functions;
* :func:`lattice_stresses`, on the lattice of the cell corners (or of h/refine): a
  zero-padded FFT convolution at each depth, the whole (x, y) plane for 14 function
  tables of (2n + 1)^2 points and 20 FFTs of (2n + 2)^2; it agrees with the direct sum
  to 1e-14 and costs about 190 times less a point (n = 64: 65^2 x 100 points in 0.72 s,
  a 100 x 100 plane by the direct sum in 3.2 s; benchmarks/bench_stresses_grid.py).

On the surface (z = 0) the in-plane stresses of piecewise-constant tractions are
singular at the cell edges: the field is defined for z > 0 only, and at depths below a
few cells it shows the cells (the estimate of :func:`fretting_step_stresses` says how
much).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .inputs import CHUNK
from .tangential import CARTESIAN, cartesian_measures

__all__ = ["grid_stresses", "stresses_at", "lattice_stresses", "corner_weights",
           "fretting_step_stresses", "fretting_stresses", "field_maxima"]

_TRACTIONS = ("p", "qx", "qy")

# (a, b, c) of each derivative d^a/dx^a d^b/dy^b d^c/dz^c of I, in the order of _corners
# exact: the derivatives Johnson's potentials need, d^2/dy^2 reduced by harmonicity
_ORDERS = ((0, 0, 3), (0, 0, 4), (0, 1, 2), (0, 1, 3), (1, 0, 2), (1, 0, 3), (1, 1, 1),
           (1, 1, 2), (2, 0, 1), (2, 0, 2), (2, 1, 0), (2, 1, 1), (3, 0, 0), (3, 0, 1))

# stress = sum over (order, a0 + a1 nu + a2 z) / (2 pi) times the corner sum of the order
# exact: Johnson's potentials reduced with the harmonic d^2/dy^2, derived symbolically
# (checked against Love, Cerruti and Huber in tests/test_stresses_grid.py)
_COEFFICIENTS = {
    "p": {
        "sigma_xx": {(2, 0, 1): (-1, 2, 0), (0, 0, 3): (0, 2, 0), (2, 0, 2): (0, 0, -1)},
        "sigma_yy": {(0, 0, 3): (1, 0, 0), (2, 0, 1): (1, -2, 0), (0, 0, 4): (0, 0, 1),
                     (2, 0, 2): (0, 0, 1)},
        "sigma_zz": {(0, 0, 3): (1, 0, 0), (0, 0, 4): (0, 0, -1)},
        "sigma_yz": {(0, 1, 3): (0, 0, -1)},
        "sigma_xz": {(1, 0, 3): (0, 0, -1)},
        "sigma_xy": {(1, 1, 1): (-1, 2, 0), (1, 1, 2): (0, 0, -1)},
    },
    "qx": {
        "sigma_xx": {(1, 0, 2): (2, 2, 0), (3, 0, 0): (0, 2, 0), (3, 0, 1): (0, 0, -1)},
        "sigma_yy": {(3, 0, 0): (0, -2, 0), (1, 0, 3): (0, 0, 1), (3, 0, 1): (0, 0, 1)},
        "sigma_zz": {(1, 0, 3): (0, 0, -1)},
        "sigma_yz": {(1, 1, 2): (0, 0, -1)},
        "sigma_xz": {(0, 0, 3): (1, 0, 0), (2, 0, 2): (0, 0, -1)},
        "sigma_xy": {(0, 1, 2): (1, 0, 0), (2, 1, 0): (0, 2, 0), (2, 1, 1): (0, 0, -1)},
    },
    "qy": {
        "sigma_xx": {(2, 1, 0): (0, 2, 0), (0, 1, 2): (0, 2, 0), (2, 1, 1): (0, 0, -1)},
        "sigma_yy": {(0, 1, 2): (2, 0, 0), (2, 1, 0): (0, -2, 0), (0, 1, 3): (0, 0, 1),
                     (2, 1, 1): (0, 0, 1)},
        "sigma_zz": {(0, 1, 3): (0, 0, -1)},
        "sigma_yz": {(0, 0, 3): (1, 0, 0), (2, 0, 2): (0, 0, 1), (0, 0, 4): (0, 0, 1)},
        "sigma_xz": {(1, 1, 2): (0, 0, -1)},
        "sigma_xy": {(1, 0, 2): (1, -2, 0), (3, 0, 0): (0, -2, 0), (3, 0, 1): (0, 0, 1),
                     (1, 0, 3): (0, 0, 1)},
    },
}


def _log_shift(u: np.ndarray, r: np.ndarray, rest2: np.ndarray) -> np.ndarray:
    """u + r (r = sqrt(u^2 + rest2) > |u|) without cancellation for u < 0."""
    neg = u < 0
    return np.where(neg, rest2 / np.where(neg, r - u, 1.0), u + r)


def _corners(X: np.ndarray, Y: np.ndarray, z: np.ndarray) -> list[np.ndarray]:
    """The 14 corner functions C of :data:`_ORDERS` at offsets (X, Y) and depth z > 0.

    d^2 C/dX dY = D Omega with Omega = z ln(r + z) - r, r = sqrt(X^2 + Y^2 + z^2);
    each is continuous in (X, Y) for z > 0 (no branch cut), up to terms f(X) + g(Y)
    that cancel in a corner sum.
    """
    x2, y2, z2 = X * X, Y * Y, z * z
    r = np.sqrt(x2 + y2 + z2)
    sx = _log_shift(X, r, y2 + z2)  # X + r
    sy = _log_shift(Y, r, x2 + z2)  # Y + r
    sz = r + z
    ir = 1.0 / r
    xy = X * Y
    lsy = np.log(sy)
    dxz = x2 * r + y2 * z  # 0 only at X = Y = 0, where C(2,0,1) tends to 0
    c201 = np.arctan(xy * (x2 + y2) / (sz * np.where(dxz > 0, dxz, 1.0)))
    return [
        -np.arctan(xy / (z * r)),                                  # (0, 0, 3)
        xy * (r * r + z2) * ir / ((x2 + z2) * (y2 + z2)),           # (0, 0, 4)
        np.log(sx),                                                 # (0, 1, 2)
        z * ir / sx,                                                # (0, 1, 3)
        lsy,                                                        # (1, 0, 2)
        z * ir / sy,                                                # (1, 0, 3)
        np.log(sz),                                                 # (1, 1, 1)
        ir,                                                         # (1, 1, 2)
        c201,                                                       # (2, 0, 1)
        X * ir / sy,                                                # (2, 0, 2)
        -X / sz,                                                    # (2, 1, 0)
        X * ir / sz,                                                # (2, 1, 1)
        Y / sz - lsy,                                               # (3, 0, 0)
        -Y * ir / sz - z * ir / sy,                                 # (3, 0, 1)
    ]


def corner_weights(p: Any, q: Any = None) -> np.ndarray:
    """The tractions' second difference at the grid's corners, shape (3, n + 1, m + 1).

    Parameters
    ----------
    p : array_like, shape (n, m)
        Pressure on cell (i, j) (x index first), any stress unit.
    q : array_like, shape (2, n, m), optional
        Shear (q_x, q_y) on the cells (0 if omitted).

    Returns
    -------
    ndarray
        ``w[t, k, l] = t[k, l] - t[k - 1, l] - t[k, l - 1] + t[k - 1, l - 1]`` (zero
        outside the grid) for t = p, q_x, q_y: the field is the sum over corners of
        ``w`` times the corner functions.
    """
    p = np.asarray(p, dtype=float)
    q = np.zeros((2,) + p.shape) if q is None else np.asarray(q, dtype=float)
    t = np.zeros((3, p.shape[0] + 2, p.shape[1] + 2))
    t[0, 1:-1, 1:-1] = p
    t[1:, 1:-1, 1:-1] = q
    return t[:, 1:, 1:] - t[:, :-1, 1:] - t[:, 1:, :-1] + t[:, :-1, :-1]


def _check_tractions(p: Any, q: Any) -> tuple[np.ndarray, np.ndarray]:
    from ..validate import InputError

    p = np.asarray(p, dtype=float)
    if p.ndim != 2 or min(p.shape) < 1:
        raise InputError("p", "a 2-d array of cell pressures (n, m)", p.shape)
    q = np.zeros((2,) + p.shape) if q is None else np.asarray(q, dtype=float)
    if q.shape != (2,) + p.shape:
        raise InputError("q", f"shape (2,) + {p.shape} (q_x, q_y on the cells)", q.shape)
    if not (np.all(np.isfinite(p)) and np.all(np.isfinite(q))):
        raise InputError("p", "finite tractions (p and q)", "non-finite values")
    return p, q


def _check_origin(origin: Any) -> tuple[float, float]:
    from ..validate import InputError

    o = np.asarray(origin, dtype=float)
    if o.shape != (2,) or not np.all(np.isfinite(o)):
        raise InputError("origin", "two finite numbers (x0, y0), the grid's lower corner",
                         origin)
    return float(o[0]), float(o[1])


def _check_axes(x: Any, y: Any, z: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    from ..validate import InputError

    out = []
    for name, v in (("x", x), ("y", y), ("z", z)):
        a = np.atleast_1d(np.asarray(v, dtype=float))
        if a.ndim != 1 or a.size < 1 or not np.all(np.isfinite(a)):
            raise InputError(name, "a 1-d array of finite numbers", a.shape)
        out.append(a)
    if np.any(out[2] <= 0):
        raise InputError("z", "depths > 0 (z is positive into the body; on the surface the "
                         "in-plane stresses of cell-wise constant tractions are singular at "
                         "the cell edges)", float(out[2].min()))
    return out[0], out[1], out[2]


def stresses_at(p: Any, q: Any, h: float, origin: tuple[float, float], points: Any,
                nu: float) -> dict[str, np.ndarray]:
    """Cartesian stresses of cell-wise constant tractions at a list of points.

    Parameters
    ----------
    p, q, h, origin, nu
        As for :func:`grid_stresses`.
    points : array_like, shape (M, 3)
        (x, y, z) of each point, in the unit of ``h``; z > 0.

    Returns
    -------
    dict of str to ndarray, shape (M,)
        :data:`~contactlib.stresses.tangential.CARTESIAN` components in the unit of the
        tractions.
    """
    from .. import validate

    p, q = _check_tractions(p, q)
    if not (isinstance(h, (int, float, np.floating)) and math.isfinite(h) and h > 0):
        raise validate.InputError("h", "a finite cell side > 0", h)
    nu = validate.nu(nu)
    origin = _check_origin(origin)
    pts = np.asarray(points, dtype=float)
    if pts.ndim != 2 or pts.shape[1] != 3 or not np.all(np.isfinite(pts)):
        raise validate.InputError("points", "an (M, 3) array of finite (x, y, z)", pts.shape)
    _check_axes(pts[:1, 0], pts[:1, 1], pts[:, 2])
    w = corner_weights(p, q)
    xi = float(origin[0]) + h * np.arange(p.shape[0] + 1)
    eta = float(origin[1]) + h * np.arange(p.shape[1] + 1)
    kk, ll = np.nonzero(np.any(w != 0.0, axis=0))  # only where the tractions change
    out = {name: np.zeros(pts.shape[0]) for name in CARTESIAN}
    if kk.size == 0:
        return out
    wl = w[:, kk, ll].T  # (corners, 3)
    cx, cy = xi[kk], eta[ll]
    tables = {(t, name): [(_ORDERS.index(o), a) for o, a in _COEFFICIENTS[t][name].items()]
              for t in _TRACTIONS for name in CARTESIAN}
    rows = max(1, CHUNK // kk.size)
    for s in range(0, pts.shape[0], rows):
        chunk = pts[s:s + rows]
        X = chunk[:, 0:1] - cx[None, :]
        Y = chunk[:, 1:2] - cy[None, :]
        sums = [c @ wl for c in _corners(X, Y, chunk[:, 2:3])]  # each (points, 3)
        zp = chunk[:, 2]
        for ti, t in enumerate(_TRACTIONS):
            for name in CARTESIAN:
                acc = np.zeros(chunk.shape[0])
                for k, (a0, a1, a2) in tables[t, name]:
                    acc += (a0 + a1 * nu + a2 * zp) * sums[k][:, ti]
                out[name][s:s + rows] += acc / (2.0 * math.pi)
    return out


def grid_stresses(p: Any, q: Any, h: float, origin: tuple[float, float], x: Any, y: Any,
                  z: Any, nu: float) -> dict[str, np.ndarray]:
    """Cartesian stresses of cell-wise constant tractions on a uniform square grid.

    Parameters
    ----------
    p : array_like, shape (n, m)
        Pressure on cell (i, j), positive in compression (any stress unit).
    q : array_like, shape (2, n, m) or None
        Shear (q_x, q_y) the indenter exerts on the body on each cell (None: 0).
    h : float
        Cell side (any length unit).
    origin : (float, float)
        The corner (x, y) of cell (0, 0) with the smallest coordinates: cell (i, j) is
        ``[x0 + i h, x0 + (i + 1) h] x [y0 + j h, y0 + (j + 1) h]``.
    x, y, z : array_like, 1-d
        The output grid, in the unit of ``h``; z > 0 the depth into the body.
    nu : float
        Poisson's ratio of the body, in (-1, 0.5].

    Returns
    -------
    dict of str to ndarray, shape (len(z), len(y), len(x))
        :data:`~contactlib.stresses.tangential.CARTESIAN` components in the unit of the
        tractions, tension positive. Exact for the piecewise-constant tractions up to
        round-off (1e-14 of the traction against Love's closed form).

    Raises
    ------
    contactlib.validate.InputError
        Tractions of mismatched shapes or not finite, h <= 0, z <= 0, or nu out of range.

    Examples
    --------
    >>> from contactlib.stresses.grid import grid_stresses
    >>> s = grid_stresses([[1.0]], None, 2.0, (-1.0, -1.0), [0.0], [0.0], [1.0], 0.3)
    >>> round(float(s["sigma_zz"][0, 0, 0]), 6)  # Love: -(2/pi)(pi/6 + 1/sqrt(3))
    -0.700886
    """
    xs, ys, zs = _check_axes(x, y, z)
    zz, yy, xx = np.meshgrid(zs, ys, xs, indexing="ij")
    pts = np.stack([xx.ravel(), yy.ravel(), zz.ravel()], axis=1)
    flat = stresses_at(p, q, h, origin, pts, nu)
    return {name: v.reshape(zz.shape) for name, v in flat.items()}


def lattice_stresses(p: Any, q: Any, h: float, origin: tuple[float, float], z: Any,
                     nu: float, refine: int = 1) -> dict[str, np.ndarray]:
    """The field of :func:`grid_stresses` on the lattice of the cell corners, by FFT.

    The same exact corner functions, summed over the corners by a zero-padded FFT
    convolution at each depth: the full (x, y) plane of every depth for the cost of a
    few FFTs of (2n + 2)^2 points, rather than (points) x (corners) evaluations.

    Parameters
    ----------
    p, q, h, origin, nu
        As for :func:`grid_stresses` (cells (n, m)).
    z : array_like, 1-d
        Depths > 0, in the unit of ``h``.
    refine : int
        Points a cell side: the output lies at ``x0 + i h/refine``, i = 0 ... refine n
        (and likewise in y); 1 gives the cell corners, 2 adds the edges' midpoints and
        the centres. Costs ``refine^2`` convolutions.

    Returns
    -------
    dict of str to ndarray, shape (len(z), refine m + 1, refine n + 1)
        :data:`~contactlib.stresses.tangential.CARTESIAN` on (z, y, x), as
        :func:`grid_stresses` on ``x = x0 + i h/refine``, ``y = y0 + j h/refine``
        (agrees with it to 1e-14 of the tractions, tests/test_stresses_grid.py).
    """
    from .. import validate

    p, q = _check_tractions(p, q)
    if not (isinstance(h, (int, float, np.floating)) and math.isfinite(h) and h > 0):
        raise validate.InputError("h", "a finite cell side > 0", h)
    if not (isinstance(refine, (int, np.integer)) and refine >= 1):
        raise validate.InputError("refine", "an integer >= 1", refine)
    nu = validate.nu(nu)
    origin = _check_origin(origin)
    _, _, zs = _check_axes([0.0], [0.0], z)
    n1, n2 = p.shape
    m1, m2 = 2 * n1 + 2, 2 * n2 + 2  # circular convolution without wrap for |i - k| <= n
    w_hat = np.fft.rfft2(corner_weights(p, q), s=(m1, m2))  # (3, m1, m2 // 2 + 1)
    d1, d2 = np.arange(-n1, n1 + 1), np.arange(-n2, n2 + 1)
    place = np.ix_(d1 % m1, d2 % m2)
    out = {name: np.zeros((zs.size, refine * n2 + 1, refine * n1 + 1)) for name in CARTESIAN}
    for a in range(refine):
        for b in range(refine):
            X = (d1 * h + a * h / refine)[:, None]
            Y = (d2 * h + b * h / refine)[None, :]
            rows, cols = n1 + 1 - (a > 0), n2 + 1 - (b > 0)
            for iz, zv in enumerate(zs):
                k_hat = []
                for c in _corners(X, Y, np.float64(zv)):
                    pad = np.zeros((m1, m2))
                    pad[place] = c
                    k_hat.append(np.fft.rfft2(pad))
                for name in CARTESIAN:
                    spec = np.zeros_like(k_hat[0])
                    for ti, t in enumerate(_TRACTIONS):
                        for o, (a0, a1, a2) in _COEFFICIENTS[t][name].items():
                            coef = (a0 + a1 * nu + a2 * zv) / (2.0 * math.pi)
                            spec += coef * k_hat[_ORDERS.index(o)] * w_hat[ti]
                    field = np.fft.irfft2(spec, s=(m1, m2))[:rows, :cols]
                    out[name][iz, b::refine, a::refine] = field.T
    return out


# ----------------------------------------------------------------------------- fretting
_MEASURES = ("von_mises", "tresca")
# tested: tests/test_stresses_grid.py (second order of the field in the cell size, measured
# 1.8 ... 2.1): the change expected from n/2 to n is a quarter of that from n/4 to n/2
_NEXT_CHANGE = 0.25


def field_maxima(ds: Any, names: tuple[str, ...] = _MEASURES) -> dict[str, dict[str, float]]:
    """The largest value of each of ``names`` on a Dataset's grid, and where.

    Parameters
    ----------
    ds : xarray.Dataset
        A field on (z, y, x), e.g. of :func:`fretting_step_stresses`.
    names : tuple of str
        The variables.

    Returns
    -------
    dict of str to dict
        For each name: ``value`` (the unit of the field), ``x``, ``y``, ``z`` (grid
        points: no refinement between them) and, where the Dataset holds the estimate
        ``<name>_error``, ``error``: the larger of the estimate at the place and the
        change of the maximum itself (``<name>_coarse_max`` attribute).
    """
    out = {}
    for name in names:
        v = np.asarray(ds[name].values, dtype=float)
        iz, iy, ix = np.unravel_index(int(np.nanargmax(v)), v.shape)
        row = {"value": float(v[iz, iy, ix]), "x": float(ds["x"][ix]),
               "y": float(ds["y"][iy]), "z": float(ds["z"][iz])}
        if f"{name}_error" in ds:
            err = float(ds[f"{name}_error"].values[iz, iy, ix])
            change = ds.attrs.get(f"{name}_max_change")
            coarse = ds.attrs.get(f"{name}_coarse_max")
            if change is not None:
                err = max(err, float(change))
            elif coarse is not None:
                err = max(err, abs(row["value"] - float(coarse)))
            row["error"] = err
        out[name] = row
    return out


def _step_fields(ops: Any, raw: Any, step: int, xs: np.ndarray, ys: np.ndarray,
                 zs: np.ndarray, nu: float, refine: int = 0) -> dict[str, np.ndarray]:
    """The field of one step of a run with fields kept, in units of p0(a_max).

    ``refine`` > 0: on the lattice of spacing h/refine (``xs``, ``ys`` are its points),
    by :func:`lattice_stresses`; 0: at the product grid of ``xs``, ``ys``, ``zs``.
    """
    if step == 0:
        return {name: np.zeros((zs.size, ys.size, xs.size)) for name in CARTESIAN}
    p = np.asarray(raw.p[step - 1]) / ops.p0
    q = np.asarray(raw.q[step - 1]) / ops.p0
    half = 0.5 * ops.n * ops.h
    if refine:
        return lattice_stresses(p, q, ops.h, (-half, -half), zs, nu, refine)
    return grid_stresses(p, q, ops.h, (-half, -half), xs, ys, zs, nu)


def _check_step(raw: Any, step: Any) -> int:
    from ..validate import InputError

    steps = len(raw.load)
    if not isinstance(step, (int, np.integer)) or not -steps <= int(step) < steps:
        raise InputError("step", f"an integer in [-{steps}, {steps - 1}]", step)
    if len(raw.p) != steps - 1:
        raise InputError("raw", "a run with its fields kept (run_sphere_fretting(..., "
                         "keep_fields=True))", f"{len(raw.p)} kept steps of {steps - 1}")
    return int(step) % steps


def fretting_step_stresses(ops: Any, raw: Any, step: int, x: Any, y: Any, z: Any, *,
                           nu: float, coarse: tuple[Any, Any, int] | None = None,
                           coarser: tuple[Any, Any, int] | None = None,
                           refine: int = 1) -> Any:
    """The stress field under one step of a sphere's fretting run, as an xarray Dataset.

    Parameters
    ----------
    ops : contactlib.solvers.fretting_sphere.GridOperators
        The run's grid (n x n cells of side h over [-1.2, 1.2]^2 a_max).
    raw : contactlib.solvers.fretting_sphere.RawSphereFretting
        The run, with its fields kept (``run_sphere_fretting(..., keep_fields=True)``).
    step : int
        The step, 0 (unloaded) ... m; negative counts from the end.
    x, y : array_like, 1-d, or None
        The grid in units of a_max (x along the tangential load). Both None: the lattice
        of spacing h/``refine`` over the run's grid [-1.2, 1.2]^2 (its cell corners for
        ``refine`` = 1), computed by FFT (:func:`lattice_stresses`: the whole 3-D field
        for less than a plane of points costs otherwise, benchmarks/bench_stresses_grid.py).
    z : array_like, 1-d
        Depths z > 0 into the body, in units of a_max.
    nu : float
        Poisson's ratio of the body.
    coarse : (ops, raw, step), optional
        A coarser run of the same path (n/2 cells, half the steps) and its step at the
        same point of the path: the estimate is the change of the field.
    coarser : (ops, raw, step), optional
        With ``coarse``, a run with n/4 cells (a quarter of the steps): the estimate is
        then the larger of the change from n/2 and a quarter of the change from n/4 to
        n/2 (the field converges at second order, measured 1.8 ... 2.1; the tractions of
        a fretting run converge unevenly and a twofold change alone can be small by
        chance: at n = 64 it missed the change to n = 128 at the von Mises maximum by
        1.3 times, tests/test_stresses_grid.py).
    refine : int
        Points a cell side of the lattice when ``x`` and ``y`` are None.

    Returns
    -------
    xarray.Dataset
        On (z, y, x): :data:`~contactlib.stresses.tangential.CARTESIAN` and
        :func:`~contactlib.stresses.tangential.cartesian_measures`, in units of
        p0(a_max), the Hertz peak pressure at a_max (CF units "1"). With ``coarse``,
        each variable's estimated error ``<name>_error`` = |fine - coarse| (no
        Richardson division; see ``coarser``) and the attributes ``<name>_coarse_max``.
        Attributes:
        ``step``, ``load_ratio`` (P/P_max), ``force`` (Q_x, units E* a_max^3/R),
        ``contact_radius`` and ``stick_radius`` of the step (units a_max),
        ``cells``, ``cell_side`` (units a_max), ``poisson_ratio`` and ``converged``.

    Raises
    ------
    contactlib.validate.InputError
        A step out of range, a run without its fields, z <= 0, or nu out of range.
    contactlib.validate.SolverLimit
        The step (or the coarse run's) did not converge: its tractions are not data.
    """
    import xarray as xr

    from .. import validate

    nu = validate.nu(nu)
    lattice = x is None and y is None
    if lattice:
        if not (isinstance(refine, (int, np.integer)) and refine >= 1):
            raise validate.InputError("refine", "an integer >= 1", refine)
        half = 0.5 * ops.n * ops.h
        x = y = -half + ops.h / refine * np.arange(refine * ops.n + 1)
    elif x is None or y is None:
        raise validate.InputError("x", "given with y, or both None (the lattice)",
                                  "one of x, y None")
    xs, ys, zs = _check_axes(x, y, z)
    step = _check_step(raw, step)
    runs = [(ops, raw, step)]
    if coarser is not None and coarse is None:
        raise validate.InputError("coarser", "given with coarse (the n/2 run)", "coarse=None")
    for extra in (coarse, coarser):
        if extra is not None:
            c_ops, c_raw, c_step = extra
            runs.append((c_ops, c_raw, _check_step(c_raw, c_step)))
    for r_ops, r_raw, r_step in runs:
        if not bool(r_raw.converged[r_step]):
            raise validate.SolverLimit(
                f"fretting stresses: step {r_step} of the run with n = {r_ops.n} did not "
                "converge, so its tractions are not data; refine the steps or the grid")
    fields = _step_fields(ops, raw, step, xs, ys, zs, nu, refine if lattice else 0)
    fields.update(cartesian_measures(fields))
    dims = ("z", "y", "x")
    data = {k: (dims, v, {"units": "1", "long_name": f"{k} / p0(a_max)"})
            for k, v in fields.items()}
    attrs: dict[str, Any] = {
        "step": step, "load_ratio": float(raw.load[step] / ops.p_max),
        "force": float(raw.force[step]), "contact_radius": float(raw.contact_radius[step]),
        "stick_radius": float(raw.stick_radius[step]), "cells": int(ops.n),
        "cell_side": float(ops.h), "poisson_ratio": nu, "converged": True,
        "stress_unit": "p0(a_max), the Hertz peak pressure at a_max"}
    if coarse is not None:
        others = []
        for c_ops, c_raw, c_step in runs[1:]:
            ratio = round(c_ops.h / ops.h)
            if lattice and abs(ratio * ops.h - c_ops.h) > 1e-12 * c_ops.h:
                raise validate.InputError("coarse", "runs whose cell side is a multiple of "
                                          "the run's (n/2, n/4) for the lattice", c_ops.n)
            other = _step_fields(c_ops, c_raw, c_step, xs, ys, zs, nu,
                                 refine * ratio if lattice else 0)
            other.update(cartesian_measures(other))
            others.append(other)
        for k, v in fields.items():
            err = np.abs(v - others[0][k])
            if len(others) > 1:
                err = np.maximum(err, _NEXT_CHANGE * np.abs(others[0][k] - others[1][k]))
            data[f"{k}_error"] = (dims, err,
                                  {"units": "1", "long_name": f"estimated error of {k}"})
        for name in _MEASURES:
            tops = [float(np.max(o[name])) for o in others]
            # the maximum's own change, as the field's: a bound on the fine one's error
            attrs[f"{name}_coarse_max"] = tops[0]
            if len(tops) > 1:
                attrs[f"{name}_max_change"] = max(abs(float(np.max(fields[name])) - tops[0]),
                                                  _NEXT_CHANGE * abs(tops[0] - tops[1]))
        attrs["reference_cells"] = " ".join(str(int(r[0].n)) for r in runs[1:])
    coords = {"z": ("z", zs, {"units": "1", "long_name": "depth / a_max, into the body"}),
              "y": ("y", ys, {"units": "1", "long_name": "y / a_max"}),
              "x": ("x", xs, {"units": "1",
                              "long_name": "x / a_max (along the tangential load)"})}
    ds = xr.Dataset(data, coords=coords, attrs=attrs)
    for name, top in field_maxima(ds).items():
        for key, value in top.items():
            ds.attrs[f"max_{name}" + ("" if key == "value" else f"_{key}")] = value
    return ds


def _model_of(result: Any, indenter_modulus: float, indenter_nu: float | None) -> Any:
    """The contact of a sphere's FrettingResult, with the indenter's material given."""
    from .. import validate
    from ..model import contact
    from ..model.profiles import profile as make_profile

    e1, nu1 = validate.indenter_material(indenter_modulus, indenter_nu)
    prof = make_profile(result.profile,
                        result.exponent if result.profile == "power" else None,
                        result.flat_ratio if result.profile == "rounded" else None)
    model = contact("sphere", result.nu, indenter_modulus=e1, indenter_nu=nu1, profile=prof)
    beta = float(model.beta) if not model.decoupled else 0.0
    if abs(beta - float(result.beta)) > 1e-12:
        raise validate.InputError(
            "indenter_modulus", "the indenter of the run (its Dundurs beta)",
            indenter_modulus, f"indenter_modulus, indenter_nu: the pair has beta = "
            f"{beta:.6g} but the run's is {float(result.beta):.6g}; pass the indenter "
            "material the run was made with")
    return model


def _replay(model: Any, result: Any, n: int, steps: int) -> tuple[Any, Any]:
    from ..solvers.fretting_sphere import grid_operators, run_sphere_fretting
    from ..history_api import load_levels

    ops = grid_operators(model, n)
    big_p = load_levels(result.load_path, steps)[0][1:] * ops.p_max
    path = load_levels(result.tangential_path, steps)[0][1:]
    if getattr(result, "tangential_displacement", False):  # the shift prescribed
        return ops, run_sphere_fretting(ops, result.friction, big_p, None, keep_fields=True,
                                        shift=path)
    return ops, run_sphere_fretting(ops, result.friction, big_p,
                                    path * result.friction * ops.p_max, keep_fields=True)


def fretting_stresses(result: Any, step: int, x: Any, y: Any, z: Any, *,
                      indenter_modulus: float = math.inf, indenter_nu: float | None = None,
                      error_estimate: bool = True, refine: int = 1) -> Any:
    """The stress field under a step of ``contactlib.fretting("sphere", ...)``.

    The result keeps only the row of cells next to the x axis, so the path is run again
    with its fields kept (the same grid and steps: the same tractions) and, for the
    estimate, with n/2 cells and half the steps and, from n = 64, with n/4 cells and a
    quarter of the steps (as the result's own estimates; see
    :func:`fretting_step_stresses`, ``coarser``).

    Parameters
    ----------
    result : contactlib.fretting_api.FrettingResult
        A sphere's fretting path.
    step : int
        The step (``result.point_step`` holds the path points'); negative counts from
        the end. With ``error_estimate`` it must be even, from n = 64 a multiple of 4
        (the coarse runs have fewer steps; every path point is).
    x, y, z : array_like, 1-d
        The grid in units of a_max, z > 0; x and y both None: the lattice of the run's
        cell corners (``refine`` points a cell side), by FFT, as
        :func:`fretting_step_stresses`.
    indenter_modulus, indenter_nu : float
        The indenter the run was made with (the result does not keep them); its Dundurs
        beta is checked against the result's.
    error_estimate : bool
        Add the estimate (the runs with n/2 and n/4 cells; about 1/8 of the main run's
        cost). Default True.

    Returns
    -------
    xarray.Dataset
        As :func:`fretting_step_stresses`; lengths in units of a_max (the step's contact
        radius is the attribute ``contact_radius``), stresses in units of p0(a_max).
        Attributes ``max_von_mises``, ``max_tresca``, their places and their
        ``..._error`` estimates.

    Raises
    ------
    contactlib.validate.InputError
        Not a sphere's result, a step out of range (or not a multiple of 2 or 4 with the
        estimate), an
        indenter that does not match the run, or z <= 0.
    contactlib.validate.SolverLimit
        The step did not converge (in the run or the coarse run).
    """
    from .. import validate

    if getattr(result, "geometry", None) != "sphere":
        raise validate.InputError("result", "a sphere's FrettingResult (contactlib.fretting("
                                  "'sphere', ...); the cylinder's: contactlib.stresses."
                                  "cylinder_fretting_stresses)",
                                  getattr(result, "geometry", result))
    total = len(result.load_ratio)
    if not isinstance(step, (int, np.integer)) or not -total <= int(step) < total:
        raise validate.InputError("step", f"an integer in [-{total}, {total - 1}]", step)
    step = int(step) % total
    from ..fretting_api import SPHERE_N_MIN

    third = result.n // 4 >= SPHERE_N_MIN
    if error_estimate and step % (4 if third else 2):
        raise validate.InputError(
            "step", f"a multiple of {4 if third else 2} with error_estimate (the coarse runs "
            "have fewer steps; every path point is one); pass error_estimate=False for this "
            "step", step)
    _check_axes(0.0 if x is None else x, 0.0 if y is None else y, z)
    model = _model_of(result, indenter_modulus, indenter_nu)
    ops, raw = _replay(model, result, result.n, result.steps)
    if abs(float(raw.contact_radius[step]) - float(result.contact_edges[step, 1])) > 1e-9:
        raise validate.InputError("result", "a run this pair reproduces", "another contact "
                                  "radius", "result: the run again with this indenter does "
                                  "not reproduce its contact radius; pass the indenter "
                                  "material the run was made with")
    coarse = coarser = None
    if error_estimate:
        coarse = (*_replay(model, result, result.n // 2, result.steps // 2), step // 2)
        if third:
            coarser = (*_replay(model, result, result.n // 4, result.steps // 4), step // 4)
    return fretting_step_stresses(ops, raw, step, x, y, z, nu=result.nu, coarse=coarse,
                                  coarser=coarser, refine=refine)
