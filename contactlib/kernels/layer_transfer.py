r"""Transfer functions of a layer in the transform domain (numerics only).

The layer of :mod:`contactlib.kernels.layer` (thickness h, Poisson's ratio nu,
on a smooth or bonded rigid base, or bonded to an elastic :class:`Substrate`)
answers a surface load of wavenumber k through transfer functions of
``t = k h``: :func:`transfer` gives ``(Cww, Cwu, Cuu)``,
:func:`remainder_transfer` their parts beyond the half-space's
(:func:`coated_remainder` on a substrate), and :func:`fine_panel` the scale
below which a coated body's quadrature needs finer panels. Both the ring
tables (:mod:`contactlib.kernels.layer`) and the transform-domain sums of thin
layers (:mod:`contactlib.kernels.thin_layer`) integrate them; this module
imports neither, so the two do not import each other. The formulas and their
checks are in the notes of :mod:`contactlib.kernels.layer`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .disc import beta_of_nu

__all__ = ["BASES", "FINE_PANELS", "FINE_T", "Substrate", "check_base", "check_nu",
           "coated_remainder", "fine_panel", "remainder_transfer", "transfer"]

Arr = NDArray[np.float64]

# convention: the rigid bases a layer rests on (a Substrate is the elastic one)
BASES = ("smooth", "bonded")
# tested: tests/test_thin_coatings.py (the coated tables against their quadrature and limits)
FINE_T = 2.0
"""A coated body: the fine panels cover ``0 < t < FINE_T f`` (f = :func:`fine_panel`)."""
# tested: tests/test_thin_coatings.py (the coated tables against their quadrature and limits)
FINE_PANELS = 32
"""A coated body: panels on ``0 < t < FINE_T f`` (the tables' quadrature; at least this
many in :mod:`contactlib.kernels.thin_layer`)."""


@dataclass(frozen=True)
class Substrate:
    """An elastic half-space (half-plane) bonded under the layer: a coated body.

    Passed as ``base`` to the layer kernels (hashable: one table per (layer nu,
    substrate)). The interface is bonded (u, w and the tractions continuous).

    Parameters
    ----------
    modulus : float
        Young's modulus of the substrate over the layer's, E2/E1, in (0, inf).
    nu : float
        Poisson's ratio of the substrate, -1 < nu <= 0.5.
    """

    modulus: float
    nu: float

    def __post_init__(self) -> None:
        m = float(self.modulus)
        if not 0.0 < m < np.inf:
            raise ValueError(f"substrate modulus E2/E1={self.modulus!r} must be in (0, inf)")
        check_nu(self.nu)
        object.__setattr__(self, "modulus", m)
        object.__setattr__(self, "nu", float(self.nu))

    def stiffness_ratio_of(self, nu: float) -> float:
        """m = E1*/E2* of a layer of Poisson's ratio ``nu`` on this substrate."""
        return (1.0 - self.nu**2) / ((1.0 - nu**2) * self.modulus)


def check_base(base: str | Substrate) -> str | Substrate:
    """The base, checked: 'smooth', 'bonded' or a :class:`Substrate` (ValueError otherwise)."""
    if isinstance(base, Substrate):
        return base
    if base not in BASES:
        raise ValueError(f"base={base!r} must be one of {BASES} or a Substrate")
    return base


def check_nu(nu: float) -> float:
    """Poisson's ratio as a float, checked: -1 < nu <= 0.5 (ValueError otherwise)."""
    nu = float(nu)
    if not -1.0 < nu <= 0.5:
        raise ValueError(f"Poisson's ratio nu={nu!r} must satisfy -1 < nu <= 0.5")
    return nu


def transfer(t: ArrayLike, nu: float, base: str | Substrate) -> tuple[Arr, Arr, Arr]:
    """Layer transfer functions ``(Cww, Cwu, Cuu)`` at ``t = k h > 0``.

    Parameters
    ----------
    t : array_like
        Dimensionless wavenumber ``k h`` (> 0).
    nu : float
        Poisson's ratio, -1 < nu <= 0.5.
    base : {"smooth", "bonded"} or Substrate
        Condition at the rigid base, or the elastic substrate (coated body).

    Returns
    -------
    cww, cwu, cuu : ndarray
        Dimensionless; the half-space values are (1, beta, 1). See the module
        notes for the formulas and for how they enter ``w`` and ``u``.
    """
    rww, rwu, ruu = remainder_transfer(t, nu, base)
    return 1.0 + rww, beta_of_nu(check_nu(nu)) + rwu, 1.0 + ruu


def remainder_transfer(t: ArrayLike, nu: float,
                       base: str | Substrate) -> tuple[Arr, Arr, Arr]:
    """``(Cww - 1, Cwu - beta, Cuu - 1)`` at ``t = k h > 0``, without cancellation.

    Parameters
    ----------
    t : array_like
        Dimensionless wavenumber ``k h`` (> 0; any size, nothing overflows).
    nu : float
        Poisson's ratio, -1 < nu <= 0.5 (the smooth base does not depend on it).
    base : {"smooth", "bonded"} or Substrate
        A rigid base, or the elastic substrate of a coated body
        (:func:`coated_remainder`).

    Returns
    -------
    rww, rwu, ruu : ndarray
        ``O(t^2 exp(-2t))`` as ``t -> inf``.
    """
    nu = check_nu(nu)
    t = np.asarray(t, dtype=float)
    if isinstance(check_base(base), Substrate):
        return coated_remainder(t, nu, base.modulus, base.nu)
    e = np.exp(-2.0 * t)
    if base == "smooth":
        ds = -np.expm1(-4.0 * t) + 4.0 * t * e
        return (2.0 * e * (np.expm1(-2.0 * t) - 2.0 * t) / ds, -4.0 * t * e / ds,
                2.0 * e * (e + 1.0 - 2.0 * t) / ds)
    k = 3.0 - 4.0 * nu
    ns = k * (1.0 + e * e) + (1.0 + k * k + 4.0 * t * t) * e
    common = 2.0 * k * e + 1.0 + k * k + 4.0 * t * t
    return (-e * (common + 4.0 * t) / ns, -e * (k * k - 1.0 + 4.0 * t * t) / ns,
            -e * (common - 4.0 * t) / ns)


def coated_remainder(t: ArrayLike, nu: float, modulus: float,
                     nu2: float) -> tuple[Arr, Arr, Arr]:
    r"""``(Cww - 1, Cwu - beta, Cuu - 1)`` of a layer bonded to an elastic half-space.

    Parameters
    ----------
    t : array_like
        Dimensionless wavenumber ``k h`` (> 0; any size, nothing overflows).
    nu : float
        Poisson's ratio of the layer, -1 < nu <= 0.5 (``E* = E1/(1 - nu^2) = 1``).
    modulus : float
        E2/E1, the substrate's Young's modulus over the layer's, in (0, inf).
    nu2 : float
        Poisson's ratio of the substrate.

    Returns
    -------
    rww, rwu, ruu : ndarray
        Dimensionless, in units of the layer's E*. ``O(t^2 exp(-2t))`` as
        ``t -> inf``; as ``t -> 0`` they tend to ``m - 1``, ``m beta2 - beta``,
        ``m - 1`` with ``m = E1*/E2*`` (the substrate's half-space); 0 when the
        two materials are equal.

    Notes
    -----
    Solved per ``t`` (a batched 6x6 linear system, plane strain; the
    axisymmetric transfer functions are the same functions of ``t``) for the
    *correction* to the layer material's half-space field, so that the
    remainder is computed directly, without cancellation. Airy function
    ``phi = e^{ikx} f(kz)``; the modes ``f = e^{-y}, y e^{-y}`` (decaying into
    the body) and ``e^{y}, y e^{y}`` (decaying towards the surface) with
    ``y = kz`` for the first pair and ``y = kz - t`` for the second in the
    layer, and the decaying pair with ``y = kz - t`` in the substrate. Their
    state vectors ``(2 k i u_x, 2 k u_z) G`` and ``(s_zz, i s_xz)`` are, for
    ``e^{-y}``: ``(1, 1, -1, -1) e^{-y}``; ``y e^{-y}``: ``(y - 2(1 - nu), 1 -
    2 nu + y, -y, 1 - y) e^{-y}``; ``e^{y}``: ``(1, -1, -1, 1) e^{y}``; ``y e^{y}``:
    ``(y + 2(1 - nu), 1 - 2 nu - y, -y, 1 + y) e^{y}``. Every coefficient of
    the system is bounded by 1 (``e^{-t}``, ``t e^{-t}``), the right-hand side
    (the half-space field at the interface) is ``O(t e^{-t})`` and the surface
    correction ``O(t^2 e^{-2t})``, all in relative precision.
    """
    nu = check_nu(nu)
    nu2 = check_nu(nu2)
    t = np.asarray(t, dtype=float)
    shape = t.shape
    t = t.reshape(-1)
    g = float(modulus) * (1.0 + nu) / (1.0 + nu2)  # G2/G1
    e = np.exp(-t)
    n = t.size
    one, zero = np.ones(n), np.zeros(n)
    c1, d1 = 2.0 * (1.0 - nu), 1.0 - 2.0 * nu
    c2, d2 = 2.0 * (1.0 - nu2), 1.0 - 2.0 * nu2
    # unknowns: layer e^{-y}, y e^{-y} (y = kz); e^{y}, y e^{y} (y = kz - t); substrate
    # e^{-y}, y e^{-y} (y = kz - t). Rows: surface s_zz, i s_xz; interface 2k i u_x,
    # 2k u_z (G1 = 1), s_zz, i s_xz (layer minus substrate).
    mat = np.stack([
        np.stack([-one, zero, -e, t * e, zero, zero], axis=-1),
        np.stack([-one, one, e, (1.0 - t) * e, zero, zero], axis=-1),
        np.stack([e, (t - c1) * e, one, c1 * one, -one / g, c2 / g * one], axis=-1),
        np.stack([e, (d1 + t) * e, -one, d1 * one, -one / g, -d2 / g * one], axis=-1),
        np.stack([-e, -t * e, -one, zero, one, zero], axis=-1),
        np.stack([-e, (1.0 - t) * e, one, one, one, -one], axis=-1),
    ], axis=-2)  # (n, 6, 6)
    # the layer's half-space field: amplitudes (A0, B0) = (P, P - Q); columns P = 1 and Q = 1
    inc = np.array([[1.0, 0.0], [1.0, -1.0]])  # (a or b, load)
    rhs = np.zeros((n, 6, 2))
    rhs[:, 2:, :] = -mat[:, 2:, :2] @ inc
    x = np.linalg.solve(mat, rhs)  # (n, 6, 2)
    # surface correction: (2k i u_x, 2k u_z) at z = 0; W = 2k u_z/(2(1 - nu)), U likewise
    disp = np.stack([
        np.stack([one, -c1 * one, e, (c1 - t) * e], axis=-1),
        np.stack([one, d1 * one, -e, (d1 + t) * e], axis=-1)], axis=-2)  # (n, 2, 4)
    corr = (disp @ x[:, :4, :]) / c1  # (n, 2 (U, W), 2 (P, Q))
    rww = corr[:, 1, 0]
    rwu = -corr[:, 1, 1]
    ruu = corr[:, 0, 1]
    return rww.reshape(shape), rwu.reshape(shape), ruu.reshape(shape)


def fine_panel(nu: float, base: str | Substrate) -> float | None:
    """Scale of the fine panels near t = 0 of a coated body (None on a rigid base).

    Parameters
    ----------
    nu : float
        Poisson's ratio of the layer.
    base : {"smooth", "bonded"} or Substrate

    Returns
    -------
    float or None
        ``f = min(1, m^(-1/3))`` (dimensionless, in ``t = k h``) on a
        :class:`Substrate`; None on a rigid base (a uniform rule).

    Notes
    -----
    A stiff layer on a soft substrate (m = E1*/E2* >> 1) is a plate on a
    compliant foundation: its remainder falls from m - 1 at t = 0 over
    ``t ~ (3/m)^(1/3)`` (bending against the substrate), with complex poles
    that close; panels of 0.25 missed 9e-4 of scale at E2/E1 = 1e-2. Returns
    the scale ``f = min(1, m^(-1/3))``: ``FINE_PANELS`` panels on
    ``0 < t < FINE_T f``, then the uniform ones.
    """
    if not isinstance(base, Substrate):
        return None
    return min(1.0, base.stiffness_ratio_of(nu) ** (-1.0 / 3.0))
