"""What differs between the sphere (rings) and the cylinder (strips)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .kernels import disc
from .theory import hertz_load, hertz_p0

__all__ = ["Geometry"]


@dataclass(frozen=True)
class Geometry:
    """Geometry and material of one problem (units E* = a = R = 1).

    Parameters
    ----------
    name : {"sphere", "cylinder"}
    nu : float
        Poisson's ratio.
    slab_ratio : float
        a/h of the slab under the cylinder (0: half-plane). Ignored for the sphere.
    """

    name: str
    nu: float
    slab_ratio: float = 0.0

    @property
    def p0(self) -> float:
        return hertz_p0(self.name)

    @property
    def hertz_load(self) -> float:
        return hertz_load(self.name)

    @property
    def thickness(self) -> float:
        return np.inf if self.slab_ratio == 0 else 1.0 / self.slab_ratio

    def pressure_kernel(self, x, s, with_w: bool = True):
        """(w, u, du/dx) of a unit uniform pressure on a disc / symmetric strip of radius s.

        ``with_w=False`` may skip w (zeros) where that is cheaper (the disc).
        """
        if self.name == "sphere":
            return disc.pressure_disc(x, s, self.nu, with_w=with_w)
        from .kernels import strip
        return strip.pressure_strip(x, s, self.nu, self.thickness)

    def shear_kernel(self, x, s, with_du: bool = True):
        """(w, u, du/dx) of the unit shear element: q = r on a disc, or +-1 on a strip.

        ``with_du=False`` may skip du/dx (NaN) where that is cheaper (the disc).
        """
        if self.name == "sphere":
            return disc.shear_disc(x, s, self.nu, with_du=with_du)
        from .kernels import strip
        return strip.shear_strip(x, s, self.nu, self.thickness)

    def shear_shape(self, x):
        """Shear = shape(x) * phi(x): shape r for the sphere, 1 for the cylinder."""
        x = np.asarray(x, dtype=float)
        return x.copy() if self.name == "sphere" else np.ones_like(x)

    def load(self, nodes: np.ndarray, p: np.ndarray) -> float:
        """Total load of a piecewise-linear pressure (nodal values p, p[-1] = 0).

        Sphere: int p 2 pi r dr; cylinder: int_{-1}^{1} p dx (per unit length).
        """
        r0, r1 = nodes[:-1], nodes[1:]
        p0, p1 = p[:-1], p[1:]
        if self.name == "sphere":
            # int_{r0}^{r1} (p0 + (p1-p0)(r-r0)/h) r dr, exact
            h = r1 - r0
            val = h * (p0 * (2 * r0 + r1) + p1 * (r0 + 2 * r1)) / 6.0
            return float(2.0 * np.pi * val.sum())
        return float(2.0 * (0.5 * (p0 + p1) * (r1 - r0)).sum())

    @property
    def work_weight_power(self) -> int:
        """Power of xi in the work integrand (1 for rings, 0 for strips)."""
        return 1 if self.name == "sphere" else 0

    @property
    def work_factor(self) -> float:
        """V = factor * int_c^1 xi^power q (-s) dxi in the scalings of docs/conventions.md."""
        return 2.0 * np.pi / 5.0 if self.name == "sphere" else 0.5
