"""Measures of a stress field: principal stresses, von Mises, Tresca, hydrostatic, maxima."""

from __future__ import annotations

from typing import Any

import numpy as np

from .inputs import COMPONENTS

__all__ = ["principal_stresses", "von_mises", "tresca", "hydrostatic", "derived_measures",
           "field_maximum"]


def _split(geometry: str, s: dict[str, np.ndarray]) -> tuple[np.ndarray, ...]:
    """(in-plane normal, out-of-plane principal, zz, in-plane shear) of either geometry."""
    a, b, c, d = (s[k] for k in COMPONENTS[geometry])
    return a, b, c, d


def principal_stresses(geometry: str, s: dict[str, np.ndarray]) -> np.ndarray:
    """Principal stresses, largest first, stacked on a new leading axis (3, ...).

    The hoop stress (sphere) or sigma_yy (cylinder) is principal; the other two are the
    eigenvalues of the in-plane 2 x 2 tensor.

    Parameters
    ----------
    geometry : {"sphere", "cylinder"}
        Which components ``s`` holds (:data:`COMPONENTS`).
    s : dict of str to ndarray
        The components (any stress unit), e.g. from :func:`stress_field`.

    Returns
    -------
    ndarray, shape (3, ...)
        sigma_1 >= sigma_2 >= sigma_3, in the unit of ``s``.
    """
    a, b, c, d = _split(geometry, s)
    mean, radius = 0.5 * (a + c), np.hypot(0.5 * (a - c), d)
    return -np.sort(-np.stack([mean + radius, b, mean - radius]), axis=0)


def von_mises(geometry: str, s: dict[str, np.ndarray]) -> np.ndarray:
    """von Mises equivalent stress, in the unit of ``s``.

    sqrt(((s1-s2)^2 + (s2-s3)^2 + (s3-s1)^2)/2), from the components as sqrt(((a-b)^2 +
    (b-c)^2 + (c-a)^2)/2 + 3 d^2) (a, b, c the normal stresses, d the in-plane shear).
    Parameters as for :func:`principal_stresses`.
    """
    a, b, c, d = _split(geometry, s)
    return np.sqrt(0.5 * ((a - b)**2 + (b - c)**2 + (c - a)**2) + 3.0 * d * d)


def tresca(geometry: str, s: dict[str, np.ndarray]) -> np.ndarray:
    """Maximum shear stress (s1 - s3)/2, half the spread of the principal stresses.

    In the unit of ``s``; parameters as for :func:`principal_stresses`.
    """
    ps = principal_stresses(geometry, s)
    return 0.5 * (ps[0] - ps[2])


def hydrostatic(geometry: str, s: dict[str, np.ndarray]) -> np.ndarray:
    """Mean normal stress (trace / 3), tension positive, in the unit of ``s``.

    Parameters as for :func:`principal_stresses`.
    """
    a, b, c, _ = _split(geometry, s)
    return (a + b + c) / 3.0


def derived_measures(geometry: str, s: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    """von Mises, Tresca, hydrostatic and the principal stresses (s1 >= s2 >= s3).

    Parameters as for :func:`principal_stresses`.

    Returns
    -------
    dict of str to ndarray
        ``von_mises``, ``tresca``, ``hydrostatic``, ``sigma_1``, ``sigma_2``,
        ``sigma_3``, in the unit of ``s``.
    """
    ps = principal_stresses(geometry, s)
    return {"von_mises": von_mises(geometry, s), "tresca": 0.5 * (ps[0] - ps[2]),
            "hydrostatic": hydrostatic(geometry, s), "sigma_1": ps[0], "sigma_2": ps[1],
            "sigma_3": ps[2]}


def field_maximum(ds: Any, name: str = "tresca") -> dict[str, float]:
    """Value and place of the largest ``name`` on a Dataset's grid.

    The grid maximum, refined by a parabola through it and its neighbours along each
    axis (where it has both, equally spaced): value error O(h^2) -> O(h^3) of the grid
    spacing h for a smooth peak.

    Parameters
    ----------
    ds : xarray.Dataset
        A field of :func:`subsurface_stresses` (dimensions z, x).
    name : str
        The variable, e.g. ``"tresca"`` or ``"von_mises"``.

    Returns
    -------
    dict
        ``value`` (units of p0), ``x`` and ``z`` (units of a).
    """
    v = np.asarray(ds[name].values, dtype=float)
    xs, zs = np.asarray(ds["x"].values), np.asarray(ds["z"].values)
    iz, ix = np.unravel_index(int(np.nanargmax(v)), v.shape)
    value, place = float(v[iz, ix]), {"x": float(xs[ix]), "z": float(zs[iz])}
    for axis, (i, c) in enumerate(((iz, zs), (ix, xs))):
        if 0 < i < c.size - 1:
            f = v[i - 1:i + 2, ix] if axis == 0 else v[iz, i - 1:i + 2]
            h0, h1 = c[i] - c[i - 1], c[i + 1] - c[i]
            if abs(h0 - h1) > 1e-9 * h0:
                continue
            den = f[0] - 2 * f[1] + f[2]
            if den < 0:
                t = 0.5 * (f[0] - f[2]) / den
                place["z" if axis == 0 else "x"] = float(c[i] + t * h0)
                value += float(-0.125 * (f[0] - f[2])**2 / den)
    return {"value": value, **place}
