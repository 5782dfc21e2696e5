"""Stresses in the half-space under a tangential surface shear in a fixed direction (issue 38).

The sphere's self-similar and history solutions carry a radial shear, which
:mod:`contactlib.stresses` treats (an axisymmetric field). A tangential force Q along x
(sliding, Cattaneo-Mindlin partial slip, fretting) adds a shear q_x(r) whose direction is
fixed and whose magnitude depends on r only. Its field is not axisymmetric; it holds the
harmonics cos(theta), cos(3 theta) (normal stresses), cos(2 theta) and sin(2 theta) (out-of-
plane shears). This module gives the full Cartesian field of a pressure p(r), an optional
radial shear q_r(r) and a shear q_x(r), in the scalings of :mod:`contactlib.stresses`:
lengths over a, stresses in the unit of the tractions, tension positive, z positive into
the body, tractions on the body, so that the surface limits are sigma_zz = -p and sigma_xz =
-q_x on the axis.

Method
------
A Fourier transform in (x, y) of Navier's equations with the surface shear q_x gives the
stress of each wave; its angular integral reduces to Hankel transforms of orders 0 ... 3
(derived with a computer algebra system and checked against Hamilton's closed form of the
sliding Hertz contact to 1e-12, docs/stresses.md). With Q(xi) = int q_x J0(xi r) r dr and
t = xi z, each component is int xi Q e^{-t} [...] d xi with

    sigma_xx: cos(th) J1 (-(2 + nu/2) + 3t/4) - cos(3 th) J3 (nu/2 + t/4)
    sigma_yy: cos(th) J1 (-3 nu/2 + t/4) + cos(3 th) J3 (nu/2 + t/4)
    sigma_zz: -t cos(th) J1
    sigma_yz: -(t/2) sin(2 th) J2
    sigma_xz: J0 (t/2 - 1) - (t/2) cos(2 th) J2
    sigma_xy: sin(th) J1 (nu/2 - 1 + t/4) - sin(3 th) J3 (nu/2 + t/4)

(th the polar angle from the x axis). Q(xi) is in closed form for the piecewise-linear
tractions (:class:`contactlib.stresses.TractionPieces`), and the xi integral uses the same
Gauss-Legendre panels as the axisymmetric field (:func:`contactlib.stresses.xi_nodes`, to
``DEPTH_CUTOFF``/z_min). On the surface z = 0, sigma_zz, sigma_yz and sigma_xz are the
tractions themselves; the other three are the xi integral cut at ``XI_SURFACE``, as for
the radial shear.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import scipy.special as sp

from .halfspace import halfspace_stresses
from .inputs import CHUNK, check_grid, check_tractions
from .pieces import TractionPieces
from .quadrature import DEPTH_CUTOFF, XI_SURFACE, xi_nodes

__all__ = ["CARTESIAN", "shear_x_stresses", "cartesian_stresses", "cartesian_measures",
           "mindlin_tractions", "mindlin_deresiewicz_tractions", "mindlin_sphere_stresses"]

CARTESIAN = ("sigma_xx", "sigma_yy", "sigma_zz", "sigma_yz", "sigma_xz", "sigma_xy")
"""The Cartesian components, in the order of the returned dictionaries."""


def _axes(x: Any, y: Any, z: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    xs, zs = check_grid(x, z)
    ys, _ = check_grid(y, 0.0)
    return xs, ys, zs


def _pieces(xi: Any, values: Any) -> TractionPieces:
    """A shear tabulated on ``xi`` as linear pieces (in the pressure's slot: its J0 transform)."""
    r, v, zero = check_tractions(xi, values, np.zeros_like(np.asarray(values, dtype=float)))
    return TractionPieces.from_nodes(r, v, zero)


def _bessel(order: int, x: np.ndarray, j: list[np.ndarray]) -> np.ndarray:
    """J_order(x) from J_(order-1) and J_(order-2) by recurrence, jv where it cancels."""
    small = x <= order + 1.0
    out = 2.0 * (order - 1) * j[order - 1] / np.where(small, 1.0, x) - j[order - 2]
    out[small] = sp.jv(order, x[small])
    return out


def shear_x_stresses(xi: Any, shear: Any, x: Any, y: Any, z: Any,
                     nu: float) -> dict[str, np.ndarray]:
    """Cartesian stresses in the half-space under a surface shear q_x(r) along +x.

    Parameters
    ----------
    xi : array_like, shape (m,)
        Increasing radii r/a >= 0 of the tabulated shear.
    shear : array_like, shape (m,)
        The shear traction on the body along +x at ``xi`` (any stress unit, e.g. p0),
        piecewise linear between, zero beyond ``xi[-1]``.
    x, y, z : array_like, 1-d
        Output grid x/a, y/a and the depth z/a >= 0.
    nu : float
        Poisson's ratio of the body.

    Returns
    -------
    dict of str to ndarray, shape (len(z), len(y), len(x))
        :data:`CARTESIAN` components in the unit of the shear, tension positive. Error:
        the xi quadrature's, below 1e-9 of the shear at z > 0; on z = 0 sigma_xx,
        sigma_yy and sigma_xy carry the truncation at ``XI_SURFACE``.
    """
    xs, ys, zs = _axes(x, y, z)
    pieces = _pieces(xi, shear)
    rho = np.hypot(ys[:, None], xs[None, :])
    theta = np.arctan2(ys[:, None], xs[None, :])
    rr, inverse = np.unique(rho.ravel(), return_inverse=True)
    inside, surface = zs > 0, zs == 0
    xi_max = DEPTH_CUTOFF / zs[inside].min() if np.any(inside) else XI_SURFACE
    if np.any(surface):
        xi_max = max(xi_max, XI_SURFACE)
    k, w = xi_nodes(xi_max, float(max(rr.max(), pieces.sb.max())))
    transform, _ = pieces.hankel(k)
    # radial functions A[m][0] = int xi Q e^-t J_m, A[m][1] = int xi Q t e^-t J_m: (z, rho)
    a = np.zeros((4, 2, zs.size, rr.size))
    zmin = float(zs[inside].min()) if np.any(inside) else np.inf
    step = max(1, CHUNK // max(rr.size, zs.size, 1))
    for i in range(0, k.size, step):
        kc = k[i:i + step]
        weight = (w * k * transform)[i:i + step]
        arg = np.outer(rr, kc)
        j = [sp.j0(arg), sp.j1(arg)]
        j.append(_bessel(2, arg, j))
        j.append(_bessel(3, arg, j))
        kz = np.outer(kc, zs)
        e0 = np.where(kz < 40.0, np.exp(-np.minimum(kz, 40.0)), 0.0) * weight[:, None]
        e0[:, surface] *= (kc <= XI_SURFACE)[:, None]
        if kc[0] * zmin >= 40.0 and kc[0] > XI_SURFACE:
            break  # e^-t < 4e-18 at every depth, and past the surface's cut
        e1 = kz * e0
        for m in range(4):
            a[m, 0] += (j[m] @ e0).T
            a[m, 1] += (j[m] @ e1).T
    h = nu / 2.0
    fields = {
        "sigma_xx": (np.cos(theta), -(2 + h) * a[1, 0] + 0.75 * a[1, 1],
                     np.cos(3 * theta), -h * a[3, 0] - 0.25 * a[3, 1]),
        "sigma_yy": (np.cos(theta), -3 * h * a[1, 0] + 0.25 * a[1, 1],
                     np.cos(3 * theta), h * a[3, 0] + 0.25 * a[3, 1]),
        "sigma_zz": (np.cos(theta), -a[1, 1], None, None),
        "sigma_yz": (np.sin(2 * theta), -0.5 * a[2, 1], None, None),
        "sigma_xz": (np.ones_like(theta), 0.5 * a[0, 1] - a[0, 0],
                     np.cos(2 * theta), -0.5 * a[2, 1]),
        "sigma_xy": (np.sin(theta), (h - 1) * a[1, 0] + 0.25 * a[1, 1],
                     np.sin(3 * theta), -h * a[3, 0] - 0.25 * a[3, 1]),
    }
    out = {}
    shape = (zs.size,) + rho.shape
    for name in CARTESIAN:
        f1, g1, f2, g2 = fields[name]
        v = f1[None] * g1[:, inverse].reshape(shape)
        if f2 is not None:
            v = v + f2[None] * g2[:, inverse].reshape(shape)
        out[name] = v
    if np.any(surface):
        qx = pieces.at(rho.ravel())[0].reshape(rho.shape)
        out["sigma_zz"][surface] = 0.0
        out["sigma_yz"][surface] = 0.0
        out["sigma_xz"][surface] = -qx
    return out


def cartesian_stresses(xi: Any, pressure: Any, x: Any, y: Any, z: Any, nu: float, *,
                       radial_shear: Any = None, shear_x: Any = None) -> dict[str, np.ndarray]:
    """Cartesian stresses under a pressure, a radial shear and a shear along x, all tabulated.

    Parameters
    ----------
    xi : array_like, shape (m,)
        Increasing radii r/a >= 0 of the tabulated tractions.
    pressure : array_like, shape (m,)
        p at ``xi`` (any stress unit), positive in compression.
    x, y, z : array_like, 1-d
        Output grid x/a, y/a and depth z/a >= 0.
    nu : float
        Poisson's ratio of the body.
    radial_shear : array_like, shape (m,), optional
        The radial shear on the body, positive away from the axis (0 if omitted).
    shear_x : array_like, shape (m,), optional
        The magnitude of a shear along +x (:func:`shear_x_stresses`; 0 if omitted).

    Returns
    -------
    dict of str to ndarray, shape (len(z), len(y), len(x))
        :data:`CARTESIAN` components in the unit of the tractions, tension positive.
        The tractions are piecewise linear between the points and zero beyond the last.
    """
    xs, ys, zs = _axes(x, y, z)
    p = np.asarray(pressure, dtype=float)
    qr = np.zeros_like(p) if radial_shear is None else np.asarray(radial_shear, dtype=float)
    rho = np.hypot(ys[:, None], xs[None, :])
    rr, inverse = np.unique(rho.ravel(), return_inverse=True)
    axi = halfspace_stresses(xi, p, qr, rr, zs, nu)
    shape = (zs.size,) + rho.shape
    srr, stt, szz, srz = (axi[k][:, inverse].reshape(shape)
                          for k in ("sigma_rr", "sigma_tt", "sigma_zz", "sigma_rz"))
    theta = np.arctan2(ys[:, None], xs[None, :])[None]
    c, s = np.cos(theta), np.sin(theta)
    out = {"sigma_xx": srr * c * c + stt * s * s, "sigma_yy": srr * s * s + stt * c * c,
           "sigma_zz": szz, "sigma_yz": srz * s, "sigma_xz": srz * c,
           "sigma_xy": (srr - stt) * s * c}
    if shear_x is not None:
        tangential = shear_x_stresses(xi, shear_x, xs, ys, zs, nu)
        for name in CARTESIAN:
            out[name] = out[name] + tangential[name]
    return out


def cartesian_measures(s: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    """von Mises, Tresca, hydrostatic and principal stresses of a Cartesian field.

    Parameters
    ----------
    s : dict of str to ndarray
        The :data:`CARTESIAN` components (any stress unit), all of one shape.

    Returns
    -------
    dict of str to ndarray
        ``von_mises``, ``tresca`` ((s1 - s3)/2), ``hydrostatic`` (trace/3) and
        ``sigma_1`` >= ``sigma_2`` >= ``sigma_3`` (eigenvalues of the tensor), in the
        unit of ``s``.
    """
    xx, yy, zz, yz, xz, xy = (s[k] for k in CARTESIAN)
    tensor = np.stack([np.stack([xx, xy, xz], -1), np.stack([xy, yy, yz], -1),
                       np.stack([xz, yz, zz], -1)], -2)
    ev = np.linalg.eigvalsh(tensor)[..., ::-1]
    vm = np.sqrt(0.5 * ((xx - yy)**2 + (yy - zz)**2 + (zz - xx)**2)
                 + 3.0 * (yz**2 + xz**2 + xy**2))
    return {"von_mises": vm, "tresca": 0.5 * (ev[..., 0] - ev[..., 2]),
            "hydrostatic": (xx + yy + zz) / 3.0, "sigma_1": ev[..., 0],
            "sigma_2": ev[..., 1], "sigma_3": ev[..., 2]}


def mindlin_tractions(friction: float, load_ratio: float,
                      points: int = 401) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
    """Hertz pressure and Cattaneo-Mindlin shear of a sphere under P and then Q along x.

    Parameters
    ----------
    friction : float
        Coulomb's coefficient mu >= 0 (0: frictionless, no shear).
    load_ratio : float
        Q/(mu P) in [0, 1]; 1 is full sliding (q = mu p, Hamilton's case).
    points : int
        Sample points on [0, 1], graded towards r = 1 and r = c (each zone's square-root
        edge), at least 64.

    Returns
    -------
    xi, p, q_x : ndarray
        r/a and the tractions over p0: p = sqrt(1 - r^2), q_x = mu [sqrt(1 - r^2) -
        sqrt(c^2 - r^2)] (the second term for r < c only).
    c : float
        The stick radius over a, (1 - Q/(mu P))^(1/3).

    Notes
    -----
    Exact for bodies with Dundurs' beta = 0 and a zero Poisson term gamma (docs/fretting.md,
    "The sphere"); an approximation otherwise. Between the samples the tractions are
    linear; the field's error from that is measured in docs/stresses.md.
    """
    from ..validate import InputError
    if not (np.isfinite(friction) and friction >= 0):
        raise InputError("friction", "a finite friction coefficient >= 0", friction)
    if not (np.isfinite(load_ratio) and 0.0 <= load_ratio <= 1.0):
        raise InputError("load_ratio", "Q/(mu P) in [0, 1]", load_ratio)
    if not (isinstance(points, (int, np.integer)) and points >= 64):
        raise InputError("points", "an integer >= 64", points)
    c = float((1.0 - load_ratio) ** (1.0 / 3.0))
    # graded by sin on [0, 1] and on [0, c]: the square roots' edges at both ends resolved
    half = points // 2 if c > 0 else points
    t = np.sin(np.linspace(0.0, 0.5 * np.pi, points - half + 1 if c > 0 else points))
    xi = t if c == 0 else np.union1d(c * np.sin(np.linspace(0, 0.5 * np.pi, half)),
                                     c + (1 - c) * t)
    p = np.sqrt(np.clip(1.0 - xi * xi, 0.0, None))
    q = friction * (p - np.sqrt(np.clip(c * c - xi * xi, 0.0, None)))
    return xi, p, q, c


def mindlin_deresiewicz_tractions(friction: float, peak_ratio: float, load_ratio: float,
                                  points: int = 401
                                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray, float, float]:
    """Hertz pressure and Mindlin and Deresiewicz's shear after Q went 0 -> Q* -> Q along x.

    Parameters
    ----------
    friction : float
        Coulomb's coefficient mu >= 0.
    peak_ratio : float
        Q*/(mu P) in [0, 1): the force reached first (Cattaneo-Mindlin).
    load_ratio : float
        Q/(mu P) in [-Q*/(mu P), Q*/(mu P)]: the force after the reversal.
    points : int
        Sample points in each of the zones' sin-graded sets on [0, 1], [0, c], [0, c']
        (at least 64).

    Returns
    -------
    xi, p, q_x : ndarray
        r/a and the tractions over p0: p = sqrt(1 - r^2) and q_x = mu [-sqrt(1 - r^2)
        + 2 sqrt(c'^2 - r^2) - sqrt(c^2 - r^2)] (each root inside its radius only).
    c, c_reversed : float
        The stick radius at Q*, (1 - Q*/(mu P))^(1/3), and the radius inside which the
        shear has not changed since the reversal, (1 - (Q* - Q)/(2 mu P))^(1/3).

    Notes
    -----
    Exact for bodies with Dundurs' beta = 0 and gamma = 0, as :func:`mindlin_tractions`;
    at Q = Q* it is Cattaneo-Mindlin's shear, at Q = -Q* its opposite.
    """
    from ..validate import InputError
    if not (np.isfinite(friction) and friction >= 0):
        raise InputError("friction", "a finite friction coefficient >= 0", friction)
    if not (np.isfinite(peak_ratio) and 0.0 <= peak_ratio < 1.0):
        raise InputError("peak_ratio", "Q*/(mu P) in [0, 1)", peak_ratio)
    if not (np.isfinite(load_ratio) and -peak_ratio <= load_ratio <= peak_ratio):
        raise InputError("load_ratio", "Q/(mu P) in [-Q*/(mu P), Q*/(mu P)]", load_ratio)
    if not (isinstance(points, (int, np.integer)) and points >= 64):
        raise InputError("points", "an integer >= 64", points)
    c = float((1.0 - peak_ratio) ** (1.0 / 3.0))
    c_rev = float((1.0 - 0.5 * (peak_ratio - load_ratio)) ** (1.0 / 3.0))
    graded = np.sin(np.linspace(0.0, 0.5 * np.pi, points))
    xi = np.union1d(graded, np.concatenate([c * graded, c_rev * graded]))

    def inside(r: float) -> np.ndarray:
        return np.sqrt(np.clip(r * r - xi * xi, 0.0, None))

    p = inside(1.0)
    return xi, p, friction * (-p + 2.0 * inside(c_rev) - inside(c)), c, c_rev


def mindlin_sphere_stresses(friction: float, load_ratio: float, x: Any, y: Any, z: Any,
                            nu: float, *, points: int = 401) -> Any:
    """The Cartesian field under a Hertz sphere pressed and then pushed along x.

    Hertz pressure plus the Cattaneo-Mindlin shear (:func:`mindlin_tractions`);
    ``load_ratio`` = 1 is Hamilton's sliding contact (q = mu p).

    Parameters
    ----------
    friction, load_ratio : float
        mu and Q/(mu P) in [0, 1].
    x, y, z : array_like, 1-d
        Grid in units of the contact radius a; z >= 0 the depth into the body.
    nu : float
        Poisson's ratio of the body.
    points : int
        Samples of the tractions (:func:`mindlin_tractions`).

    Returns
    -------
    xarray.Dataset
        Dimensions (z, y, x); :data:`CARTESIAN` and :func:`cartesian_measures`, all in
        units of p0 (CF units "1"); attributes ``friction_coefficient``, ``load_ratio``,
        ``stick_ratio`` and ``poisson_ratio``.

    Examples
    --------
    >>> from contactlib.stresses.tangential import mindlin_sphere_stresses
    >>> ds = mindlin_sphere_stresses(0.3, 1.0, [0.0], [0.0], [0.0, 0.5], 0.3)
    >>> round(float(ds.sigma_xz[0, 0, 0]), 6)  # -q0 = -mu p0 on the surface centre
    -0.3
    """
    import xarray as xr

    from .. import validate
    nu = validate.nu(nu)
    xi, p, q, c = mindlin_tractions(friction, load_ratio, points)
    xs, ys, zs = _axes(x, y, z)
    fields = cartesian_stresses(xi, p, xs, ys, zs, nu, shear_x=q)
    fields.update(cartesian_measures(fields))
    data = {k: (("z", "y", "x"), v, {"units": "1"}) for k, v in fields.items()}
    coords = {"z": ("z", zs, {"units": "1", "long_name": "depth / a"}),
              "y": ("y", ys, {"units": "1", "long_name": "y / a"}),
              "x": ("x", xs, {"units": "1", "long_name": "x / a (along the tangential load)"})}
    attrs = {"friction_coefficient": float(friction), "load_ratio": float(load_ratio),
             "stick_ratio": c, "poisson_ratio": nu,
             "stress_unit": "p0, the Hertz peak pressure"}
    return xr.Dataset(data, coords=coords, attrs=attrs)
