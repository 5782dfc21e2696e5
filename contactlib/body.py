r"""The body the indenter is pressed into: its material and its kernels.

An :class:`ElasticBody` is a homogeneous, isotropic, linear elastic body: a
half-space (under rings) or half-plane (under strips, plane strain), or a
layer of thickness h on a smooth rigid base (today under strips only, the
paper's slab). It answers the basic loads the indenter puts on it (see
:mod:`contactlib.indenter`): a uniform pressure, or a shear element, on a disc
or a symmetric strip of radius ``s``, with the closed-form kernels of
:mod:`contactlib.kernels`.

Units and scalings
------------------
E* = E/(1 - nu^2) of the body = 1 and lengths in units of the length scale
of the problem (the contact radius ``a``, or ``a_max`` in the incremental
solver). The layer is given by ``slab_ratio`` = (length scale)/h, 0 for the
half-space or half-plane, so the thickness in these units is
``1/slab_ratio``. Displacements are w (into the body) and u (away from the
axis) in (length scale)^2/R per unit traction in E* (length scale)/R.

beta = (1 - 2 nu)/(2 (1 - nu)) is Dundurs' coupling parameter of a rigid
indenter on this body: 0 at nu = 0.5, where the normal and tangential
problems decouple.

Examples
--------
>>> from contactlib.body import ElasticBody
>>> body = ElasticBody(0.3)
>>> round(body.beta, 12), body.is_half_space
(0.285714285714, True)
>>> ElasticBody(0.3, slab_ratio=0.05).thickness
20.0
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .indenter import Displacements
from .kernels import disc, strip
from .theory import beta_of_nu

__all__ = ["ElasticBody"]
_HALF_SPACE_DEGREES = np.array([1.0, 1.0, 0.0])  # w, u ~ s; du/dx ~ s^0


@dataclass(frozen=True)
class ElasticBody:
    """A linear elastic body: half-space / half-plane, or a layer on a smooth rigid base.

    Parameters
    ----------
    nu : float
        Poisson's ratio, in (-1, 0.5].
    slab_ratio : float
        (length scale)/h of a layer of thickness h on a smooth rigid base;
        0 (default) is the half-space or half-plane.
    """

    nu: float
    slab_ratio: float = 0.0

    @property
    def thickness(self) -> float:
        """Layer thickness in units of the length scale (``inf``: half-space)."""
        return np.inf if self.slab_ratio == 0 else 1.0 / self.slab_ratio

    @property
    def is_half_space(self) -> bool:
        """True for the half-space / half-plane (no layer)."""
        return self.slab_ratio == 0

    @property
    def beta(self) -> float:
        """Dundurs' beta of a rigid indenter on this body, (1 - 2 nu)/(2 (1 - nu))."""
        return beta_of_nu(self.nu)

    # ------------------------------------------------------------------ rings (axisymmetric)
    def _ring_layer(self) -> None:
        if not self.is_half_space:
            raise NotImplementedError(
                f"ring loads on a layer (slab_ratio = {self.slab_ratio!r}) have no kernels "
                "yet: only the half-space is available under a sphere")

    def ring_pressure(self, x: np.ndarray, s: np.ndarray, with_w: bool = True) -> Displacements:
        """(w, u, du/dr) under a unit pressure on the disc r < s.

        :func:`contactlib.kernels.disc.pressure_disc`; a layer raises
        NotImplementedError.
        """
        self._ring_layer()
        return disc.pressure_disc(x, s, self.nu, with_w=with_w)

    def ring_shear(self, x: np.ndarray, s: np.ndarray, with_du: bool = True) -> Displacements:
        """(w, u, du/dr) under the shear q = r on the disc r < s.

        :func:`contactlib.kernels.disc.shear_disc`; a layer raises
        NotImplementedError.
        """
        self._ring_layer()
        return disc.shear_disc(x, s, self.nu, with_du=with_du)

    def ring_axis_w(self, x: np.ndarray, s: np.ndarray, part: str,
                    ref: float = 0.0) -> Displacements:
        """(w(x) - w(ref), 0, 0) of the disc load of ``part``, without cancellation.

        :func:`contactlib.kernels.disc.w_difference_disc`; a layer raises
        NotImplementedError.
        """
        self._ring_layer()
        return disc.w_difference_disc(x, ref, s, self.nu, part)

    @property
    def ring_kernel_degrees(self) -> np.ndarray | None:
        """Degrees of homogeneity in length of the disc kernels (w, u, du/dr) at unit load.

        The half-space has no length of its own: a unit pressure on a disc of
        radius s gives w, u ~ s and du/dr ~ s^0. None on a layer.
        """
        return _HALF_SPACE_DEGREES.copy() if self.is_half_space else None

    # ------------------------------------------------------------------ strips (plane strain)
    def strip_pressure(self, x: np.ndarray, s: np.ndarray) -> Displacements:
        """(w, u, du/dx) under a unit pressure on |x| < s (half-plane or slab).

        :func:`contactlib.kernels.strip.pressure_strip` with the thickness
        :attr:`thickness`.
        """
        return strip.pressure_strip(x, s, self.nu, self.thickness)

    def strip_axis_w(self, x: np.ndarray, s: np.ndarray, part: str,
                     ref: float = 0.0) -> Displacements:
        """(w(x) - w(ref), 0, 0) of the strip load of ``part``, without cancellation.

        :func:`contactlib.kernels.strip.w_difference_strip` with the thickness
        :attr:`thickness`.
        """
        return strip.w_difference_strip(x, ref, s, self.nu, part, self.thickness)

    def strip_shear(self, x: np.ndarray, s: np.ndarray) -> Displacements:
        """(w, u, du/dx) under the odd shear sgn(x) on |x| < s (half-plane or slab).

        :func:`contactlib.kernels.strip.shear_strip` with the thickness
        :attr:`thickness`.
        """
        return strip.shear_strip(x, s, self.nu, self.thickness)
