"""Stresses inside an elastic layer on a rigid base, or in a coated body, under surface tractions.

The body is a layer 0 <= z <= h of Poisson's ratio nu on a rigid base at z = h, either
**smooth** (u_z = 0 and sigma_rz = 0 there) or **bonded** (u_r = u_z = 0), or bonded to an
elastic substrate z > h (a coated body, :class:`contactlib.kernels.layer_transfer.Substrate`:
E2/E1 and nu2), loaded on z = 0
by the pressure p and the shear q of :mod:`contactlib.stresses`: axisymmetric (sphere, q
radial) or in plane strain (cylinder, p even and q odd in x), tabulated on r/a (x/a),
piecewise linear, zero beyond the table. Lengths in units of a, stresses in the unit of
the tractions, the signs of :mod:`contactlib.stresses` (tension positive, z into the body;
sigma_zz = -p and sigma_rz = -q on the surface).

Method
------
The field is the half-space's (:func:`contactlib.stresses.halfspace_stresses`) plus a
correction that has no traction on z = 0 and cancels the half-space's displacements
(bonded) or its u_z and sigma_rz (smooth) on z = h. With P(k) = int p J0(k r) r dr and
Q(k) = int q J1(k r) r dr, y = k z and t = k h, the correction is

    sigma_zz = int k J0 S_zz dk,  sigma_rz = int k J1 S_rz dk,
    sigma_rr = int k (J0 S_rr + J1/(k r) B) dk,  sigma_tt = int k (J0 S_tt - J1/(k r) B) dk,

each S a sum over the four Papkovich-Neuber modes (2G u = grad(phi + z psi) -
4 (1 - nu) psi e_z, phi and psi harmonic) e^{-y}, y e^{-y} (phi, psi decaying from the
surface) and e^{-(t - y)}, (y - t) e^{-(t - y)} (decaying from the base), with
coefficients linear in P and Q from a 4 x 4 system per k (:func:`correction_coefficients`).
Every entry of that system is bounded (e^{-t}, t e^{-t}), so nothing overflows and the
correction is computed directly, in relative precision. The cylinder's correction is
the same with cos(k x), sin(k x) for J0, J1, no B term, sigma_yy = nu (sigma_xx +
sigma_zz) and the Fourier amplitudes of :func:`fourier_amplitudes` divided by k for P, Q
(the modes and the 4 x 4 system do not change: the plane-strain transfer functions are
the axisymmetric ones). It decays like t^2 e^{-t} at
every depth of the layer: the k integral stops at ``T_CUTOFF / h`` and uses Gauss-Legendre
panels (8 points) no wider than 2 pi/(1 + max r) nor 1/h. The surface transfer functions
of this solution equal :func:`contactlib.kernels.layer_transfer.transfer` (tested).

Coated body
-----------
In the layer the field is again the half-space's plus a correction of the four modes, and
in the substrate it is the two modes decaying from the interface, e^{-s} and s e^{-s}
with s = k (z - h), of the substrate's Poisson's ratio nu2 (its displacements 2 G2 u):
six amplitudes per k from a 6 x 6 system (:func:`coated_coefficients`: no correction
traction on z = 0; u_r, u_z, sigma_zz, sigma_rz continuous at z = h, with G2/G1 =
(E2/E1)(1 + nu)/(1 + nu2)). Every entry is bounded as on a rigid base; the substrate's
amplitudes are O(t e^{-t}) and its field decays like e^{-k z}, so the same k range
(``T_CUTOFF / h``) serves z > h; its panels are no wider than ``PANEL_T / z_max`` either,
and a stiff layer on a soft substrate adds the fine panels of its kernels near k = 0
(:func:`coated_nodes`). The surface transfer functions of this solution equal
:func:`contactlib.kernels.layer_transfer.transfer` on the substrate (tested,
tests/test_stresses_coated.py). :func:`substrate_field` gives the substrate's field.

:func:`contactlib.stresses.layer_stresses` adds the correction (:func:`add_correction`)
to the half-space's (half-plane's) field; this module imports nothing of :mod:`contactlib.stresses`.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import scipy.special as sp

from ..kernels.layer_transfer import BASES, FINE_PANELS, FINE_T, Substrate, fine_panel

__all__ = [
    "CHUNK",
    "FINE_SPLIT",
    "PANEL_T",
    "T_CUTOFF",
    "add_correction",
    "check_layer",
    "coated_coefficients",
    "coated_nodes",
    "correction_coefficients",
    "fourier_amplitudes",
    "fourier_pieces",
    "substrate_field",
    "surface_transfer",
]

# exact: the correction decays like t^2 e^{-t}: 45^2 e^{-45} = 5.8e-17
T_CUTOFF = 45.0
"""k h at which the correction's k integral stops."""

# tested: tests/test_stresses_layer.py (halving the panels changes the field by < 1e-9 p0)
PANEL_T = 1.0
"""Widest Gauss-Legendre panel of the correction's k integral, in t = k h."""

# tested: tests/test_stresses_coated.py (E2/E1 = 0.01, a/h = 20: with 1, halving the panels
# moved sigma_xx by 5e-8 p0 on the axis at z = h; with 4, by 3e-14 ... 5e-11)
FINE_SPLIT = 4
"""The coated kernels' fine panels near k = 0 (FINE_PANELS), each split this many times:
the field's quadrature needs them finer than the surface kernels' do."""

# convention: a working array of 2 MB, as contactlib.stresses.CHUNK
CHUNK = 250_000
"""Numbers in one working array of a chunk."""


def check_layer(nu: float, thickness: float,
                base: str | Substrate) -> tuple[float, float, str | Substrate]:
    """(nu, h, base) checked: -1 < nu <= 0.5, 0 < h < inf, base smooth, bonded or a
    :class:`~contactlib.kernels.layer_transfer.Substrate` (a coated body)."""
    from ..validate import InputError

    nu = float(nu)
    if not -1.0 < nu <= 0.5:
        raise InputError("nu", "in (-1, 0.5]", nu)
    h = float(thickness)
    if not (math.isfinite(h) and h > 0):
        raise InputError("thickness", "finite and > 0 (h / a)", thickness)
    if not (isinstance(base, Substrate) or base in BASES):
        raise InputError("base", f"one of {BASES} or a substrate", base,
                         f"base must be one of {BASES} (a rigid base) or, for a coated body, "
                         f"the substrate (E2/E1, nu2), got {base!r}")
    return nu, h, base


def _decaying(y: np.ndarray, nu: float) -> dict[str, np.ndarray]:
    """The modes e^{-y}, y e^{-y} (decaying into the body), values as :func:`_modes`,
    shape (..., 2)."""
    e = np.exp(-y)
    return {"U": np.stack([-e, -y * e], axis=-1),
            "W": np.stack([-e, -(3 - 4 * nu + y) * e], axis=-1),
            "zz": np.stack([e, (2 - 2 * nu + y) * e], axis=-1),
            "rz": np.stack([e, (1 - 2 * nu + y) * e], axis=-1),
            "rr": np.stack([-e, -(y - 2 * nu) * e], axis=-1),
            "B": np.stack([e, y * e], axis=-1),
            "tt": np.stack([0 * e, 2 * nu * e], axis=-1)}


def _modes(y: np.ndarray, t: np.ndarray, nu: float) -> dict[str, np.ndarray]:
    """Mode values (stresses / k, 2G u with 2G = 1), shape (..., 4), at y = k z, t = k h."""
    f = np.exp(-(t - y))
    s = y - t
    down = _decaying(y, nu)
    up = {"U": (-f, -s * f), "W": (f, (4 * nu - 3 + s) * f), "zz": (f, (2 * nu - 2 + s) * f),
          "rz": (-f, -(2 * nu - 1 + s) * f), "rr": (-f, -(2 * nu + s) * f), "B": (f, s * f),
          "tt": (0 * f, -2 * nu * f)}
    return {name: np.concatenate([down[name], np.stack(up[name], axis=-1)], axis=-1)
            for name in down}


def _halfspace_coefficients(nu: float) -> np.ndarray:
    """(2, 2): the half-space's amplitudes of e^{-y}, y e^{-y} for P = 1 and Q = 1."""
    # surface: c1 + (2 - 2 nu) c2 = -P, c1 + (1 - 2 nu) c2 = -Q
    return np.array([[-1.0 + (2 - 2 * nu), -(2 - 2 * nu)], [-1.0, 1.0]])


def correction_coefficients(t: Any, nu: float, base: str | Substrate) -> np.ndarray:
    """Amplitudes of the four modes of the correction, per unit P and per unit Q.

    Parameters
    ----------
    t : array_like
        k h > 0, dimensionless.
    nu : float
        Poisson's ratio.
    base : {"smooth", "bonded"} or Substrate
        A rigid base, or a coated body's substrate (the first four of
        :func:`coated_coefficients`).

    Returns
    -------
    ndarray, shape (len(t), 4, 2)
        Mode j (e^{-y}, y e^{-y}, e^{-(t-y)}, (y-t) e^{-(t-y)}) of the load P = 1
        (column 0) or Q = 1 (column 1).
    """
    if isinstance(base, Substrate):
        return coated_coefficients(t, nu, base)[:, :4, :]
    t = np.atleast_1d(np.asarray(t, dtype=float))
    zero = np.zeros_like(t)
    top = _modes(zero, t, nu)
    bottom = _modes(t, t, nu)
    rows = ("W", "rz") if base == "smooth" else ("U", "W")
    mat = np.stack([top["zz"], top["rz"], bottom[rows[0]], bottom[rows[1]]], axis=-2)
    hs = _halfspace_coefficients(nu)  # (mode, load)
    rhs = np.zeros((t.size, 4, 2))
    for i, name in enumerate(rows):
        rhs[:, 2 + i, :] = -bottom[name][:, :2] @ hs
    return np.linalg.solve(mat, rhs)


def coated_coefficients(t: Any, nu: float, substrate: Substrate) -> np.ndarray:
    """A coated body's six amplitudes per unit P and per unit Q: the layer's correction
    and the substrate's field.

    Parameters
    ----------
    t : array_like
        k h > 0, dimensionless.
    nu : float
        Poisson's ratio of the layer.
    substrate : Substrate
        E2/E1 and nu2 of the substrate bonded at z = h.

    Returns
    -------
    ndarray, shape (len(t), 6, 2)
        Modes 0-3 as :func:`correction_coefficients` (the layer's correction to its
        half-space field, 2 G1 = 1); modes 4, 5: e^{-s} and s e^{-s}, s = k (z - h), of
        the substrate's Poisson's ratio, its whole field (stresses in the unit of the
        tractions, 2 G2 u = 2 G1 u G2/G1). Load P = 1 (column 0) or Q = 1 (column 1).
    """
    t = np.atleast_1d(np.asarray(t, dtype=float))
    nu2 = float(substrate.nu)
    g = float(substrate.modulus) * (1.0 + nu) / (1.0 + nu2)  # G2/G1
    top = _modes(np.zeros_like(t), t, nu)
    bottom = _modes(t, t, nu)
    below = _decaying(np.zeros_like(t), nu2)  # the substrate's modes at s = 0
    zero = np.zeros((t.size, 2))
    rows = [np.concatenate([top[name], zero], axis=-1) for name in ("zz", "rz")]
    for name, scale in (("U", 1.0 / g), ("W", 1.0 / g), ("zz", 1.0), ("rz", 1.0)):
        rows.append(np.concatenate([bottom[name], -scale * below[name]], axis=-1))
    mat = np.stack(rows, axis=-2)  # (n, 6, 6)
    hs = _halfspace_coefficients(nu)
    rhs = np.zeros((t.size, 6, 2))
    for i, name in enumerate(("U", "W", "zz", "rz")):
        rhs[:, 2 + i, :] = -bottom[name][:, :2] @ hs
    return np.linalg.solve(mat, rhs)


def coated_nodes(width: float, thickness: float, nu: float, base: str | Substrate,
                 refine: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """Nodes (1/a) and weights of the correction's k integral on [0, T_CUTOFF/h].

    Gauss-Legendre panels (8 points) of at most ``width`` (1/a); on a
    :class:`Substrate` at least ``FINE_SPLIT * FINE_PANELS * refine`` panels on
    ``0 < k h < FINE_T f``
    (f = :func:`contactlib.kernels.layer_transfer.fine_panel`), the scale over which a
    stiff layer on a soft substrate bends, as its kernels' quadrature.
    """
    h = float(thickness)
    x, wx = np.polynomial.legendre.leggauss(8)
    f = fine_panel(nu, base)
    top = T_CUTOFF / h
    edges = np.zeros(1)
    if f is not None:
        fine = min(FINE_T * f / h, top)
        count = max(FINE_SPLIT * FINE_PANELS * max(1, refine), math.ceil(fine / width))
        edges = np.linspace(0.0, fine, count + 1)
    n = max(1, math.ceil((top - edges[-1]) / width))
    e = np.concatenate([edges[:-1], np.linspace(edges[-1], top, n + 1)])
    mid, half = 0.5 * (e[:-1] + e[1:]), 0.5 * np.diff(e)
    return ((mid[:, None] + half[:, None] * x).ravel(), (half[:, None] * wx).ravel())


def surface_transfer(t: Any, nu: float, base: str | Substrate
                     ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(Cww, Cwu, Cuu) of the layer from this module's interior solution (for checks).

    Parameters and scalings as :func:`contactlib.kernels.layer_transfer.transfer`.
    """
    t = np.atleast_1d(np.asarray(t, dtype=float))
    d = correction_coefficients(t, nu, base)
    top = _modes(np.zeros_like(t), t, nu)
    hs = _halfspace_coefficients(nu)
    w = np.einsum("nj,njl->nl", top["W"], d) + top["W"][:, :2] @ hs
    u = np.einsum("nj,njl->nl", top["U"], d) + top["U"][:, :2] @ hs
    c = 2.0 * (1.0 - nu)
    return w[:, 0] / c, -w[:, 1] / c, u[:, 1] / c


def fourier_amplitudes(x: np.ndarray, pressure: np.ndarray, shear: np.ndarray,
                       k: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(2/pi) int_0^inf p cos(k x) dx and (2/pi) int_0^inf q sin(k x) dx, exactly.

    Parameters
    ----------
    x, pressure, shear : ndarray, shape (m,)
        Increasing x/a >= 0 and p, q there, piecewise linear between, zero beyond.
    k : ndarray
        Wavenumbers (1/a), > 0.

    Returns
    -------
    ndarray, ndarray
        The surface amplitudes of the cylinder (p even, q odd in x): p(x) = int of the
        first times cos(k x) dk, q(x) = int of the second times sin(k x) dk.
    """
    return fourier_pieces(x[:-1], x[1:], pressure[:-1], pressure[1:], shear[:-1], shear[1:], k)


def fourier_pieces(sa: np.ndarray, sb: np.ndarray, pa: np.ndarray, pb: np.ndarray,
                   qa: np.ndarray, qb: np.ndarray, k: np.ndarray
                   ) -> tuple[np.ndarray, np.ndarray]:
    """:func:`fourier_amplitudes` of tractions given as linear pieces on [sa, sb] (x/a >= 0).

    On each piece p runs linearly from ``pa`` to ``pb`` and q from ``qa`` to ``qb``; the
    pieces need not meet (element-wise tractions of a history). Zero outside them all.
    """
    s = 0.5 * (sa + sb)
    d = 0.5 * (sb - sa)
    ps, mp = 0.5 * (pa + pb), (pb - pa) / (2 * d)
    qs, mq = 0.5 * (qa + qb), (qb - qa) / (2 * d)
    step = max(1, CHUNK // max(s.size, 1))
    P, Q = np.empty(k.size), np.empty(k.size)
    for i in range(0, k.size, step):
        kc = k[i:i + step, None]
        y = kc * d
        sinc = 2 * d * np.sinc(y / np.pi)  # int_{-d}^{d} cos(k u) du
        ys = np.where(y < 0.1, 0.1, y)
        g = np.where(y < 0.1, y / 3 - y**3 / 30 + y**5 / 840 - y**7 / 45360,
                     (np.sin(ys) - ys * np.cos(ys)) / ys**2)
        usin = 2 * d * d * g  # int_{-d}^{d} u sin(k u) du
        c, sn = np.cos(kc * s), np.sin(kc * s)
        P[i:i + step] = (c * sinc) @ ps - (sn * usin) @ mp
        Q[i:i + step] = (sn * sinc) @ qs + (c * usin) @ mq
    return 2.0 / math.pi * P, 2.0 / math.pi * Q


def _names(sphere: bool) -> tuple[str, str, str, str]:
    return (("sigma_rr", "sigma_tt", "sigma_zz", "sigma_rz") if sphere
            else ("sigma_xx", "sigma_yy", "sigma_zz", "sigma_xz"))


def _add_modes(out: dict[str, np.ndarray], kc: np.ndarray, wc: np.ndarray,
               prof: dict[str, np.ndarray], r: np.ndarray, sphere: bool) -> None:
    """Add the k integral (nodes ``kc``, weights ``wc``) of the depth profiles ``prof``
    (stresses / k times k, shape (n, nz)) to ``out`` on (z, r): Hankel or Fourier."""
    names = _names(sphere)
    x_ = np.outer(r, kc)
    if sphere:
        j0 = sp.j0(x_) * wc
        j1 = sp.j1(x_)
        j1x = np.where(x_ > 0, j1 / np.where(x_ > 0, x_, 1.0), 0.5) * wc
        j1 = j1 * wc
        bracket = j1x @ prof["B"]
    else:  # plane strain: no hoop term
        j0, j1 = np.cos(x_) * wc, np.sin(x_) * wc
        bracket = 0.0
    out[names[2]] += (j0 @ prof["zz"]).T
    out[names[3]] += (j1 @ prof["rz"]).T
    out[names[0]] += (j0 @ prof["rr"] + bracket).T
    if sphere:
        out[names[1]] += (j0 @ prof["tt"] - bracket).T


def add_correction(out: dict[str, np.ndarray], k: np.ndarray, w: np.ndarray, P: np.ndarray,
                   Q: np.ndarray, r: np.ndarray, z: np.ndarray, nu: float, thickness: float,
                   base: str | Substrate, geometry: str = "sphere") -> None:
    """Add the layer's correction to the half-space (half-plane) field ``out``.

    Parameters
    ----------
    out : dict of str to ndarray
        The half-space's ``sigma_rr``, ``sigma_tt``, ``sigma_zz``, ``sigma_rz`` (sphere)
        or the half-plane's ``sigma_xx``, ``sigma_yy``, ``sigma_zz``, ``sigma_xz``
        (cylinder) on the grid (len(z), len(r)), in the unit of the tractions; updated in
        place.
    k, w : ndarray
        Nodes (1/a) and weights of the k integral on [0, T_CUTOFF/h]: Gauss-Legendre
        panels no wider than 2 pi/(1 + max r) nor PANEL_T/h
        (:func:`contactlib.stresses.layer_stresses`; on a substrate :func:`coated_nodes`).
    P, Q : ndarray
        Sphere: int p J0(k r) r dr and int q J1(k r) r dr at ``k``. Cylinder:
        :func:`fourier_amplitudes` divided by k.
    r, z : ndarray
        r/a >= 0 (x/a, any sign, for the cylinder) and depths 0 <= z/a <= h/a.
    nu, thickness, base
        As for :func:`check_layer`.
    geometry : {"sphere", "cylinder"}
        Hankel (J0, J1) or Fourier (cos, sin) kernels; the cylinder's sigma_yy is
        nu (sigma_xx + sigma_zz).
    """
    h = float(thickness)
    sphere = geometry == "sphere"
    step = max(1, CHUNK // max(r.size, 4 * z.size, 1))
    for i in range(0, k.size, step):
        kc, wc = k[i:i + step], w[i:i + step]
        d = correction_coefficients(kc * h, nu, base)  # (n, 4, 2)
        amp = kc[:, None] * (d[:, :, 0] * P[i:i + step, None] + d[:, :, 1] * Q[i:i + step, None])
        m = _modes(np.outer(kc, z), (kc * h)[:, None], nu)  # (n, nz, 4)
        prof = {name: np.einsum("nzj,nj->nz", m[name], amp) for name in
                ("zz", "rz", "rr", "B", "tt")}
        _add_modes(out, kc, wc, prof, r, sphere)
    if not sphere:
        out["sigma_yy"] = nu * (out["sigma_xx"] + out["sigma_zz"])


def substrate_field(k: np.ndarray, w: np.ndarray, P: np.ndarray, Q: np.ndarray,
                    r: np.ndarray, z: np.ndarray, nu: float, thickness: float,
                    substrate: Substrate, geometry: str = "sphere") -> dict[str, np.ndarray]:
    """The stress field in a coated body's substrate, depths z >= h.

    Parameters
    ----------
    k, w, P, Q, r, geometry
        As for :func:`add_correction` (nodes of :func:`coated_nodes`).
    z : ndarray
        Depths z/a >= h/a (below the layer).
    nu, thickness : float
        The layer's Poisson's ratio and h/a.
    substrate : Substrate
        E2/E1 and nu2.

    Returns
    -------
    dict of str to ndarray, shape (len(z), len(r))
        The four components of ``geometry`` (as ``out`` of :func:`add_correction`), in
        the unit of the tractions, tension positive; the cylinder's sigma_yy is
        nu2 (sigma_xx + sigma_zz).
    """
    h = float(thickness)
    sphere = geometry == "sphere"
    out = {name: np.zeros((z.size, r.size)) for name in _names(sphere)}
    step = max(1, CHUNK // max(r.size, 4 * z.size, 1))
    for i in range(0, k.size, step):
        kc, wc = k[i:i + step], w[i:i + step]
        d = coated_coefficients(kc * h, nu, substrate)[:, 4:, :]  # (n, 2, 2)
        amp = kc[:, None] * (d[:, :, 0] * P[i:i + step, None] + d[:, :, 1] * Q[i:i + step, None])
        m = _decaying(np.outer(kc, z - h), float(substrate.nu))  # (n, nz, 2)
        prof = {name: np.einsum("nzj,nj->nz", m[name], amp) for name in
                ("zz", "rz", "rr", "B", "tt")}
        _add_modes(out, kc, wc, prof, r, sphere)
    if not sphere:
        out["sigma_yy"] = float(substrate.nu) * (out["sigma_xx"] + out["sigma_zz"])
    return out
