"""The tabulated tractions and the output grid, checked; the components and the chunk size.

Every field of :mod:`contactlib.stresses` takes a pressure p and a shear q tabulated on
``xi`` = r/a (x/a) >= 0, continuous and piecewise linear between the tabulated points,
zero outside (:func:`check_tractions`), and returns the components of :data:`COMPONENTS` on
a grid (z, x) of depths z >= 0 (:func:`check_grid`). Memory is bounded by working in chunks
of about ``CHUNK`` numbers an array (a few arrays of 8 * CHUNK bytes at once).
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["COMPONENTS", "CHUNK", "check_tractions", "check_grid"]

COMPONENTS = {"sphere": ("sigma_rr", "sigma_tt", "sigma_zz", "sigma_rz"),
              "cylinder": ("sigma_xx", "sigma_yy", "sigma_zz", "sigma_xz")}
"""The stress components of each geometry, in the order of the returned dictionaries
(``sigma_tt`` is the hoop stress sigma_theta_theta)."""

# measured: benchmarks/bench_stresses.py (the peak memory of a 100 x 100 field, 38-42 MiB)
CHUNK = 250_000
"""Numbers in one working array of a chunk (2 MB)."""


def check_tractions(xi: Any, pressure: Any,
                    shear: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The tabulated tractions as float arrays, checked (nodes increasing in [0, inf))."""
    from ..validate import InputError

    r = np.asarray(xi, dtype=float)
    p = np.asarray(pressure, dtype=float)
    q = np.asarray(shear, dtype=float)
    if r.ndim != 1 or r.size < 2 or p.shape != r.shape or q.shape != r.shape:
        raise InputError("xi", "a 1-d array of at least 2 points, with pressure and shear "
                         "of the same shape", r.shape)
    if not (np.all(np.isfinite(r)) and np.all(np.isfinite(p)) and np.all(np.isfinite(q))):
        raise InputError("pressure", "finite (xi, pressure and shear)", "non-finite values")
    if r[0] < 0 or np.any(np.diff(r) <= 0):
        raise InputError("xi", "increasing and >= 0", r)
    return r, p, q


def check_grid(x: Any, z: Any) -> tuple[np.ndarray, np.ndarray]:
    """The output grid's coordinates: 1-d, finite, z >= 0."""
    from ..validate import InputError

    xs = np.atleast_1d(np.asarray(x, dtype=float))
    zs = np.atleast_1d(np.asarray(z, dtype=float))
    if xs.ndim != 1 or zs.ndim != 1 or not (np.all(np.isfinite(xs)) and np.all(np.isfinite(zs))):
        raise InputError("x", "1-d finite arrays (x and z)", (xs.shape, zs.shape))
    if np.any(zs < 0):
        raise InputError("z", "depths >= 0 (z is positive into the body)", zs.min())
    return xs, zs
