r"""The model: an indenter pressed into a body.

A :class:`Contact` joins an :class:`~contactlib.indenter.Indenter` (what is
pressed: sphere or cylinder) and an :class:`~contactlib.body.ElasticBody`
(what it is pressed into). It is all a solver needs to know about the
physics: the kernels of the basic loads (the indenter chooses rings or
strips, the body answers them), the Hertz references and the measures of an
element. :mod:`contactlib.operators` turns it into influence matrices, and
every solver (default, paper, history) takes it.

Units and scalings
------------------
E* = R = 1, lengths in units of the contact radius a (a_max in the
incremental solver): see :mod:`contactlib.indenter` and
:mod:`contactlib.body`. E* is the modulus the scalings use: for the rigid
indenter of today the body's E/(1 - nu^2).

Examples
--------
>>> from contactlib.model import contact
>>> m = contact("cylinder", 0.3, slab_ratio=0.05)
>>> m.indenter.name, m.body.thickness, m.hertz_load == m.indenter.hertz_load
('cylinder', 20.0, True)
>>> w, u, du = m.pressure_kernel(np.array([0.0]), np.array([1.0]))
>>> bool(w[0] > 0)
True
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .body import ElasticBody
from .indenter import Displacements, Indenter, indenter

__all__ = ["Contact", "contact"]


@dataclass(frozen=True)
class Contact:
    """An indenter pressed into a body (units E* = a = R = 1).

    Parameters
    ----------
    indenter : Indenter
        The rigid sphere or cylinder.
    body : ElasticBody
        The body under it (its ``slab_ratio`` in units of the contact radius).

    Notes
    -----
    The kernels are always reached through :meth:`pressure_kernel` and
    :meth:`shear_kernel` of the contact (never the body's directly): that is
    where the compliance of a second elastic body adds to the first, and
    where a subclass may rescale them (the tests evaluate them at physical
    lengths).
    """

    indenter: Indenter
    body: ElasticBody

    # ------------------------------------------------------------------ kernels
    def pressure_kernel(self, x: np.ndarray, s: np.ndarray, with_w: bool = True) -> Displacements:
        """(w, u, du/dx) of a unit uniform pressure on a disc / symmetric strip of radius s.

        ``with_w=False`` may skip w (zeros) where that is cheaper (the disc).
        """
        return self.indenter.pressure_kernel(self.body, x, s, with_w=with_w)

    def shear_kernel(self, x: np.ndarray, s: np.ndarray, with_du: bool = True) -> Displacements:
        """(w, u, du/dx) of the unit shear element: q = r on a disc, or +-1 on a strip.

        ``with_du=False`` may skip du/dx (NaN) where that is cheaper (the disc).
        """
        return self.indenter.shear_kernel(self.body, x, s, with_du=with_du)

    def length_degrees(self, part: str) -> np.ndarray | None:
        """Homogeneity degrees of the element integrals (see :meth:`Indenter.length_degrees`)."""
        return self.indenter.length_degrees(self.body, part)

    # ------------------------------------------------------------------ coupling
    @property
    def beta(self) -> float:
        """Dundurs' beta of the pair (rigid indenter: the body's (1 - 2 nu)/(2 (1 - nu)))."""
        return self.body.beta

    @property
    def decoupled(self) -> bool:
        """beta = 0: the normal and tangential problems decouple (no shear arises)."""
        return self.beta == 0.0

    def uncoupled_friction(self, gamma: np.ndarray) -> np.ndarray:
        """k of the uncoupled limit at stick ratio ``gamma`` (see the indenter's formula)."""
        return self.indenter.uncoupled_friction(self.beta, gamma)

    # ------------------------------------------------------------------ Hertz and measures
    @property
    def p0(self) -> float:
        """Hertz peak pressure at a = 1 (units E* a/R)."""
        return self.indenter.p0

    @property
    def hertz_load(self) -> float:
        """Hertz load at a = 1 (E* a^3/R, or E* a^2/R per unit length)."""
        return self.indenter.hertz_load

    def shear_shape(self, x: np.ndarray) -> np.ndarray:
        """Shear = shape(x) * phi(x): shape r for the sphere, 1 for the cylinder."""
        return self.indenter.shear_shape(x)

    def load(self, nodes: np.ndarray, p: np.ndarray) -> float:
        """Total load of a piecewise-linear pressure (:meth:`Indenter.load_of_linear`)."""
        return self.indenter.load_of_linear(nodes, p)

    @property
    def work_factor(self) -> float:
        """V = factor * int_c^1 xi^power q (-s) dxi (see :mod:`contactlib.energy`)."""
        return self.indenter.work_factor

    @property
    def work_weight_power(self) -> int:
        """Power of xi in the work integrand (1 for rings, 0 for strips)."""
        return self.indenter.work_weight_power


def contact(geometry: str, nu: float, slab_ratio: float = 0.0) -> Contact:
    """The model of the public interface's names: a rigid indenter on an elastic body.

    Parameters
    ----------
    geometry : {"sphere", "cylinder"}
    nu : float
        Poisson's ratio of the body.
    slab_ratio : float
        a/h of a layer on a smooth rigid base (0: half-space or half-plane).
    """
    return Contact(indenter(geometry), ElasticBody(nu, slab_ratio))
