"""Closed-form references: Hertz and the uncoupled partial-slip limit, by geometry name.

Units throughout the package: E* = 1, contact radius (half-width) a = 1,
indenter radius R = 1, so that lengths are r/a, tractions are in E* a/R and
displacements in a^2/R.

The formulas that depend on the shape live with the indenter
(:mod:`contactlib.model.indenter`); the functions here look the indenter up by its
geometry name, for callers that hold a name (figures, tests).
"""

from __future__ import annotations

import numpy as np

from .indenter import indenter
from ..kernels.disc import beta_of_nu  # the kernels' closed forms own it

__all__ = ["cylinder_cycle_work", "beta_of_nu", "hertz_p0", "hertz_load", "hertz_pressure",
           "uncoupled_friction", "small_k_work_sphere"]


def hertz_p0(geometry: str) -> float:
    """Hertz peak pressure in units E* a / R: 2/pi (sphere), 1/2 (cylinder)."""
    return indenter(geometry).p0


def hertz_load(geometry: str) -> float:
    """Hertz load: 4/3 (sphere, E* a^3/R) or pi/4 (cylinder, E* a^2/R per length)."""
    return indenter(geometry).hertz_load


def hertz_pressure(xi):
    """p / p0 = sqrt(1 - xi^2) inside the contact, 0 outside."""
    xi = np.asarray(xi, dtype=float)
    return np.sqrt(np.clip(1.0 - xi**2, 0.0, None))


def uncoupled_friction(geometry: str, nu: float, gamma):
    """Friction coefficient of the uncoupled limit (exact as beta -> 0).

    Sphere: k = beta artanh(g) / (g K'(g)); cylinder on a half-plane:
    k = beta K(g) / K'(g), with K the complete elliptic integral of modulus g
    and K'(g) = K(sqrt(1 - g^2)) (Spence 1973, 1975); beta of a rigid
    indenter on a body of Poisson's ratio ``nu``. The formulas are
    :meth:`contactlib.model.indenter.Indenter.uncoupled_friction`.

    Examples
    --------
    At g = 1/sqrt(2), K(g) = K'(g), so the cylinder's k is beta:

    >>> from contactlib.model.theory import beta_of_nu, uncoupled_friction
    >>> k = uncoupled_friction("cylinder", 0.3, 2**-0.5)
    >>> round(float(k), 12) == round(beta_of_nu(0.3), 12)
    True
    >>> float(uncoupled_friction("sphere", 0.5, 0.5))  # beta = 0: no coupling
    0.0
    """
    return indenter(geometry).uncoupled_friction(beta_of_nu(nu), gamma)


def small_k_work_sphere(nu: float, k: float) -> float:
    """Small-k asymptote of the sphere's loading work, V R^2 / (E* a^5).

    V ~ (16 / (5 pi)) (pi/4 - 2/3) k beta: the frictionless Hertz slip with
    q = k p everywhere.
    """
    return 16.0 / (5.0 * np.pi) * (np.pi / 4.0 - 2.0 / 3.0) * k * beta_of_nu(nu)


def cylinder_cycle_work(x: np.ndarray | float, friction: float, load: float, p0: float
                        ) -> np.ndarray:
    r"""Frictional work of one tangential cycle between +-Q* of the cylinder (beta = 0).

    Cattaneo–Mindlin for plane strain with Masing's rule (Mindlin–Deresiewicz):
    the shift at the stick zone's centre is ``s = k p0 [L x + g(x)]`` with
    ``g(x) = (1 - x) ln(1 - x)/2`` and x = Q/(kP) (a = 1, E* = 1; the linear
    term L is the half-plane's datum and encloses no area), so

    .. math:: W = 4 k^2 p_0 P\,[x g(x) - 2 G(x)],\qquad
              G(x) = \int_0^x g = \tfrac12\left[\tfrac{(1-x)^2}{4}
              - \tfrac{(1-x)^2}{2}\ln(1-x) - \tfrac14\right].

    Parameters
    ----------
    x : float or ndarray
        Q*/(k P), in [0, 1].
    friction, load, p0 : float
        k, P (per unit length) and the Hertz peak pressure at the contact
        half-width (units E* = R = a = 1: P = pi/4, p0 = 1/2).

    Returns
    -------
    ndarray
        W per unit length (units E* a^4/R^2); ``~ k^2 p0 P x^3/3`` for small x.
    """
    x = np.asarray(x, dtype=float)
    one = 1.0 - x
    with np.errstate(divide="ignore", invalid="ignore"):
        log = np.where(one > 0.0, np.log(np.where(one > 0.0, one, 1.0)), 0.0)
    g = 0.5 * one * log
    big_g = 0.5 * (0.25 * one**2 - 0.5 * one**2 * log - 0.25)
    return 4.0 * friction**2 * p0 * load * (x * g - 2.0 * big_g)
