"""The one shape of a discrete self-similar solution, whichever solver made it.

:class:`SelfSimilarSolution` holds what every self-similar solver hands on
(the mesh, the pressure and shear coefficients, k, the indentation, the
status, and the displacements at the nodes where the solver knows them) and
names what each discretization answers in its own way: the tractions between
the nodes, the displacements anywhere, the slip-zone samples of the checks and
the work, the stick-zone points the checks look at, and the load. The default
method's :class:`~contactlib.solvers.default_method.DiscreteSolution` (nodal,
piecewise-linear tractions) and the paper's
:class:`~contactlib.solvers.paper_method.PaperSolution` (steps on rings or strips)
are its two kinds, so :mod:`contactlib.stages` and the checks and energy
never ask which solver made a solution.

Units: E* = a = R = 1 (see :mod:`contactlib.solvers.default_method`).
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from .discretization.elements import Mesh
from .model import Contact
from .result import short_repr

__all__ = ["SelfSimilarSolution"]


@dataclass(repr=False)
class SelfSimilarSolution(ABC):
    """A discrete self-similar solution (units E* = a = R = 1).

    Attributes
    ----------
    kind : str
        Class attribute: ``"default"`` or ``"paper"`` (the record's ``kind``).
    geometry : Contact
    mesh : Mesh
        Nodes r/a (x/a) and the stick index M (nodes[M] = c).
    p : ndarray
        Pressure, units E* a/R: nodal values (N + 1) or one a ring (N).
    traction : ndarray
        Shear coefficient in the layout of ``p``: q = shape(xi) traction,
        shape = r/a for rings, 1 for strips (``phi`` of the default method,
        ``qc`` of the paper's scheme).
    delta : float
        Indentation, units a^2/R (NaN where the scheme has none).
    k : float
        Friction coefficient (>= 0, ``inf`` at full adhesion).
    converged : bool
    residual_norm : float
    iterations : int
    message : str
    nodal_u, nodal_du : ndarray or None
        u and du/dx at the nodes from the solve's own operators (None where
        the scheme does not give them).
    round_off : float
        Last relative Newton step when Newton stopped on the round-off floor.
    interior_samples : tuple of ndarray or None
        (x, u, du/dx) at one interior point of every element of the slip zone (from
        c to a), when known without the kernels (a nested coarse mesh).
    """

    __repr__ = short_repr  # a few lines: scalars, arrays by shape
    kind: ClassVar[str] = ""

    geometry: Contact
    mesh: Mesh
    p: np.ndarray
    traction: np.ndarray
    delta: float
    k: float
    converged: bool
    residual_norm: float
    iterations: int
    message: str = ""
    nodal_u: np.ndarray | None = None
    nodal_du: np.ndarray | None = None
    round_off: float = 0.0
    interior_samples: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None

    @property
    def stick_ratio(self) -> float:
        """c/a of the mesh."""
        return float(self.mesh.nodes[self.mesh.stick_index])

    @abstractmethod
    def pressure(self, x: np.ndarray) -> np.ndarray:
        """p at points x (units E* a/R)."""

    @abstractmethod
    def shear(self, x: np.ndarray) -> np.ndarray:
        """q at points x (units E* a/R), positive away from the axis."""

    @abstractmethod
    def displacements(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(w, u, du/dx) at points x."""

    @abstractmethod
    def tangential(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(u, du/dx) at points x."""

    @abstractmethod
    def radial_displacement(self, x: np.ndarray) -> np.ndarray:
        """u at points x (units a^2/R)."""

    @abstractmethod
    def slip_samples(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(x, weights, q, s) on the slip zone: points, quadrature weights, shear, slip rate."""

    @abstractmethod
    def stick_points(self) -> np.ndarray:
        """The stick-zone points the admissibility check samples."""

    @abstractmethod
    def load(self) -> float:
        """Total load, units E* a^3/R (sphere) or E* a^2/R per unit length (cylinder)."""
