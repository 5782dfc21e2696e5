r"""The indenter: a rigid sphere or cylinder, and everything that depends on its shape.

Every difference between the sphere and the cylinder lives here, as methods of
:class:`Sphere` and :class:`Cylinder`: which kernels of the body they load
(rings or strips), the shape of their shear elements, the measure of an
element (ring area or strip width), the shear resultant, and the Hertz
formulas. Code elsewhere asks the indenter instead of comparing geometry
names.

Units and scalings
------------------
E* = R = 1 and lengths in units of the contact radius (half-width) ``a``, so
that a traction is in units of E* a/R, a displacement in a^2/R, a load in
E* a^3/R (sphere) or E* a^2/R per unit length (cylinder), and a frictional
work in E* a^5/R^2 (sphere) or E* a^4/R^2 per unit length (cylinder). The
incremental solver uses the same formulas with ``a_max`` for ``a``. E* is
the composite modulus of the pair, 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2:
the body's E/(1 - nu^2) under a rigid indenter (see :mod:`contactlib.model`).

Elements
--------
The half contact 0 <= xi <= 1 is cut at ``edges`` into elements: rings
(sphere) or pairs of strips symmetric about the axis (cylinder). A traction
is a superposition of *basic loads* on a disc or symmetric strip of radius
``s``: a uniform pressure 1, or a shear ``shape(xi)`` (xi on a disc, +-1 on a
strip, positive away from the axis).

Examples
--------
>>> from contactlib.model.indenter import indenter
>>> sphere = indenter("sphere")
>>> round(sphere.hertz_load, 6), sphere.hertz_radius(0.125)
(1.333333, 0.5)
>>> indenter("cylinder").element_areas(np.array([0.0, 0.5, 1.0])).tolist()
[1.0, 1.0]
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, ClassVar

import numpy as np

from ..validate import GEOMETRIES

if TYPE_CHECKING:  # the body is passed in, never built here
    from .body import ElasticBody

__all__ = ["Indenter", "Sphere", "Cylinder", "GEOMETRIES", "indenter", "Displacements"]

Displacements = tuple[np.ndarray, np.ndarray, np.ndarray]
"""(w, u, du/dx) of a basic load at the surface points."""


@dataclass(frozen=True)
class Indenter(ABC):
    """A round indenter (abstract): the shape, its element measures and its material.

    Parameters
    ----------
    modulus_ratio : float
        E1/E2, Young's modulus of the indenter over that of the body, in
        (0, inf]; ``inf`` (default) is a rigid indenter.
    nu : float or None
        Poisson's ratio nu1 of the indenter, in (-1, 0.5]; None (default)
        takes the body's. Irrelevant for a rigid indenter.

    Attributes
    ----------
    name : str
        The geometry name of the public interface ("sphere", "cylinder").
    coordinate : str
        Symbol of the surface coordinate: "r" (radius) or "x" (plane).
    p0 : float
        Hertz peak pressure at the contact radius a, in E* a/R.
    hertz_load : float
        Hertz load at a: E* a^3/R (sphere) or E* a^2/R per unit length.
    load_exponent : int
        P_Hertz grows like a^load_exponent (3 sphere, 2 cylinder).
    work_exponent : int
        The frictional work is scaled by E* a^work_exponent / R^2 (5, 4).
    plane_strain : bool
        The plane problem: loads and works are per unit length of the cylinder.
    half_space_name : str
        What the unbounded body is called under this indenter: "half-space"
        or "half-plane".
    accepts_layer : bool
        The body may be a layer of finite thickness (``slab_ratio > 0``):
        the body has layer kernels for this indenter's basic loads (rings:
        :mod:`contactlib.kernels.layer`; strips: :mod:`contactlib.kernels.strip`).
    reports_half_space_ratio : bool
        Results and datasets name the slab ratio even when it is 0 (the
        cylinder's, which had its slab first); the sphere names it, and the
        base, only on a layer (see :meth:`reports_layer`).
    work_factor : float
        V = work_factor * int xi^work_weight_power q (-s) dxi over the slip
        zone (q traction, s self-similar slip rate, units E* = a = R = 1).
    work_weight_power : int
        Power of xi in that integrand (1 rings, 0 strips).
    odd_shear : bool
        The shear is odd across the axis (plane problem): its coefficient
        vanishes on the axis, and du/dx of the strip shear kernel is
        log-infinite there. False for rings, whose shear shape ``r`` already
        vanishes on the axis.
    paper_axis_shear_ratio : float
        q_1 / q_2 of the paper's Eq. 12 (1 sphere, 1/2 cylinder).
    """

    name: ClassVar[str]
    coordinate: ClassVar[str]
    p0: ClassVar[float]
    hertz_load: ClassVar[float]
    load_exponent: ClassVar[int]
    work_exponent: ClassVar[int]
    plane_strain: ClassVar[bool]
    half_space_name: ClassVar[str]
    accepts_layer: ClassVar[bool]
    reports_half_space_ratio: ClassVar[bool]
    work_factor: ClassVar[float]
    work_weight_power: ClassVar[int]
    odd_shear: ClassVar[bool]
    paper_axis_shear_ratio: ClassVar[float]

    modulus_ratio: float = math.inf
    nu: float | None = None

    def reports_layer(self, slab_ratio: float) -> bool:
        """Whether results and datasets carry ``slab_ratio`` (a/h) for this indenter.

        On a layer always; on the half-space only where the indenter's
        reports always did (:attr:`reports_half_space_ratio`, the cylinder).
        """
        return bool(slab_ratio > 0 or self.reports_half_space_ratio)

    @property
    def rigid(self) -> bool:
        """E1/E2 = inf: the indenter does not deform."""
        return self.modulus_ratio == math.inf

    # ------------------------------------------------------------------ kernels
    @abstractmethod
    def pressure_kernel(self, body: ElasticBody, x: np.ndarray, s: np.ndarray,
                        with_w: bool = True) -> Displacements:
        """(w, u, du/dx) of the body under a unit pressure on a disc / strip of radius s.

        Parameters
        ----------
        body : ElasticBody
            The body the basic load acts on.
        x, s : ndarray
            Surface points and load radii (broadcast), units a.
        with_w : bool
            False lets the kernel skip w (zeros) where that is cheaper.

        Returns
        -------
        w, u, dudx : ndarray
            Normal displacement (into the body), tangential displacement
            (away from the axis), both in a^2/R per unit p (E* a/R), and
            du/dx.
        """

    @abstractmethod
    def shear_kernel(self, body: ElasticBody, x: np.ndarray, s: np.ndarray,
                     with_du: bool = True) -> Displacements:
        """(w, u, du/dx) of the body under the unit shear element of radius s.

        The element is ``shape(x)`` on the disc / strip (see
        :meth:`shear_shape`); ``with_du=False`` lets the kernel skip du/dx
        (NaN) where that is cheaper. Units as :meth:`pressure_kernel`.
        """

    def smooth_remainder(self, body: ElasticBody, part: str, x: np.ndarray, s: np.ndarray,
                         weights: np.ndarray | None = None,
                         owner: np.ndarray | None = None) -> np.ndarray | None:
        """The body's smooth remainder over the half-space kernels on the grid x by s.

        (3, x.size, s.size) for the basic loads of ``part`` ("normal" or
        "shear"), or its weighted sums over s (quadrature ``weights``, sums
        indexed by ``owner``), or None where the body's kernels are not split
        that way (the half-space; strips, whose slab kernels are evaluated
        whole).
        """
        return None

    def axis_w_kernel(self, body: ElasticBody, x: np.ndarray, s: np.ndarray,
                      part: str, ref: float = 0.0) -> Displacements:
        """(w(x) - w(ref), 0, 0) of the basic load of ``part`` on the body, without cancellation.

        The normal displacement relative to the axis (centre line; ref = 0):
        O(x^2/s) near it, where w itself is O(s); or relative to a point ref
        nearby. Units as :meth:`pressure_kernel`.
        An indenter without it raises NotImplementedError (the default
        method then keeps its plain normal rows).
        """
        raise NotImplementedError(f"{self.name}: no axis-referenced kernel w(x) - w(0)")

    @abstractmethod
    def length_degrees(self, body: ElasticBody, part: str) -> np.ndarray | None:
        """Degrees of homogeneity in length of the element integrals (w, u, du/dx).

        ``G(lambda x; lambda nodes) = lambda^d G(x; nodes)`` for the element
        integrals of the basic loads of ``part`` ("normal" or "shear"), or
        None when the kernels carry a length of their own (a log, a layer
        thickness) and are not homogeneous.
        """

    # ------------------------------------------------------------------ shape
    @abstractmethod
    def shear_shape(self, x: np.ndarray) -> np.ndarray:
        """The shear element's shape: q = shape(x) phi(x), shape r (rings) or 1 (strips)."""

    # ------------------------------------------------------------------ measures
    @abstractmethod
    def element_areas(self, edges: np.ndarray) -> np.ndarray:
        """Area of each element (units a^2; a per unit length for strips).

        Ring: pi (s_{j+1}^2 - s_j^2); strip pair: 2 (s_{j+1} - s_j).
        """

    @abstractmethod
    def shear_resultants(self, edges: np.ndarray) -> np.ndarray:
        """Integral of the shear shape over each element's area.

        Ring: int r 2 pi r dr = (2 pi / 3)(s_{j+1}^3 - s_j^3); strip pair:
        as :meth:`element_areas`. Units a^3 (rings) or a (strips).
        """

    @abstractmethod
    def mean_shear_shape(self, edges: np.ndarray) -> np.ndarray:
        """Area-weighted mean of the shear shape over each element.

        :meth:`shear_resultants` / :meth:`element_areas`: (2/3)(s_{j+1}^3 -
        s_j^3)/(s_{j+1}^2 - s_j^2) on a ring, 1 on a strip pair.
        """

    @abstractmethod
    def load_of_steps(self, edges: np.ndarray, p: np.ndarray) -> float:
        """Total load of a piecewise-constant pressure (``p[j]`` on element j)."""

    @abstractmethod
    def load_of_linear(self, nodes: np.ndarray, p: np.ndarray) -> float:
        """Total load of a piecewise-linear pressure (nodal values, ``p[-1] = 0``), exact.

        Sphere: int p 2 pi r dr; cylinder: int_{-1}^{1} p dx (per unit length).
        """

    # ------------------------------------------------------------------ Hertz and limits
    @abstractmethod
    def hertz_radius(self, level: float) -> float:
        """Frictionless contact radius at load level P/P_max, in units of a_max."""

    @abstractmethod
    def uncoupled_friction(self, beta: float, gamma: np.ndarray) -> np.ndarray:
        """Friction coefficient k of the uncoupled limit (exact as beta -> 0).

        Parameters
        ----------
        beta : float
            Dundurs' coupling parameter of the contact.
        gamma : array_like
            Stick ratio c/a.
        """


def _complement_k(g: np.ndarray) -> np.ndarray:
    """K'(g) = K(sqrt(1 - g^2)), without losing it as g -> 0."""
    from scipy import special  # here, so that reading results does not import scipy

    return special.ellipkm1(g**2)


@dataclass(frozen=True)
class Sphere(Indenter):
    """A rigid sphere of radius R: ring elements, shear element q = r.

    Hertz: p0 = 2 E* a/(pi R), P_H = 4 E* a^3/(3 R), a ~ P^(1/3).
    """

    name: ClassVar[str] = "sphere"
    coordinate: ClassVar[str] = "r"
    p0: ClassVar[float] = 2.0 / np.pi
    hertz_load: ClassVar[float] = 4.0 / 3.0
    load_exponent: ClassVar[int] = 3
    work_exponent: ClassVar[int] = 5
    plane_strain: ClassVar[bool] = False
    half_space_name: ClassVar[str] = "half-space"
    accepts_layer: ClassVar[bool] = True
    reports_half_space_ratio: ClassVar[bool] = False
    work_factor: ClassVar[float] = 2.0 * np.pi / 5.0
    work_weight_power: ClassVar[int] = 1
    odd_shear: ClassVar[bool] = False
    paper_axis_shear_ratio: ClassVar[float] = 1.0

    def pressure_kernel(self, body: ElasticBody, x: np.ndarray, s: np.ndarray,
                        with_w: bool = True) -> Displacements:
        return body.ring_pressure(x, s, with_w=with_w)

    def shear_kernel(self, body: ElasticBody, x: np.ndarray, s: np.ndarray,
                     with_du: bool = True) -> Displacements:
        return body.ring_shear(x, s, with_du=with_du)

    def smooth_remainder(self, body: ElasticBody, part: str, x: np.ndarray, s: np.ndarray,
                         weights: np.ndarray | None = None,
                         owner: np.ndarray | None = None) -> np.ndarray | None:
        return body.ring_remainder("pressure" if part == "normal" else "shear", x, s,
                                   weights, owner)

    def axis_w_kernel(self, body: ElasticBody, x: np.ndarray, s: np.ndarray,
                      part: str, ref: float = 0.0) -> Displacements:
        return body.ring_axis_w(x, s, part, ref)

    def length_degrees(self, body: ElasticBody, part: str) -> np.ndarray | None:
        d = body.ring_kernel_degrees
        if d is None:
            return None
        return d + (2.0 if part == "shear" else 1.0)  # + shape r, + ds of the element

    def shear_shape(self, x: np.ndarray) -> np.ndarray:
        return np.asarray(x, dtype=float).copy()

    def element_areas(self, edges: np.ndarray) -> np.ndarray:
        return np.pi * np.diff(edges**2)

    def shear_resultants(self, edges: np.ndarray) -> np.ndarray:
        return (2.0 * np.pi / 3.0) * np.diff(edges**3)

    def mean_shear_shape(self, edges: np.ndarray) -> np.ndarray:
        r0, r1 = edges[:-1], edges[1:]
        return (2.0 / 3.0) * (r1**3 - r0**3) / (r1**2 - r0**2)

    def load_of_steps(self, edges: np.ndarray, p: np.ndarray) -> float:
        return float(np.sum(p * np.pi * (edges[1:] ** 2 - edges[:-1] ** 2)))

    def load_of_linear(self, nodes: np.ndarray, p: np.ndarray) -> float:
        r0, r1 = nodes[:-1], nodes[1:]
        p0, p1 = p[:-1], p[1:]
        # int_{r0}^{r1} (p0 + (p1-p0)(r-r0)/h) r dr, exact
        h = r1 - r0
        val = h * (p0 * (2 * r0 + r1) + p1 * (r0 + 2 * r1)) / 6.0
        return float(2.0 * np.pi * val.sum())

    def hertz_radius(self, level: float) -> float:
        return float(level ** (1.0 / 3.0))

    def uncoupled_friction(self, beta: float, gamma: np.ndarray) -> np.ndarray:
        """k = beta artanh(g) / (g K'(g)) (Spence 1975), K'(g) = K(sqrt(1 - g^2))."""
        g = np.asarray(gamma, dtype=float)
        kp = _complement_k(g)
        with np.errstate(divide="ignore", invalid="ignore"):
            ratio = np.where(g > 0, np.arctanh(g) / np.where(g > 0, g, 1.0), 1.0)
        return beta * ratio / kp


@dataclass(frozen=True)
class Cylinder(Indenter):
    """A rigid cylinder of radius R in plane strain: strip pairs, shear element +-1.

    Hertz: p0 = E* a/(2 R), P_H = pi E* a^2/(4 R) per unit length, a ~ P^(1/2).
    """

    name: ClassVar[str] = "cylinder"
    coordinate: ClassVar[str] = "x"
    p0: ClassVar[float] = 0.5
    hertz_load: ClassVar[float] = np.pi / 4.0
    load_exponent: ClassVar[int] = 2
    work_exponent: ClassVar[int] = 4
    plane_strain: ClassVar[bool] = True
    half_space_name: ClassVar[str] = "half-plane"
    accepts_layer: ClassVar[bool] = True
    reports_half_space_ratio: ClassVar[bool] = True
    work_factor: ClassVar[float] = 0.5
    work_weight_power: ClassVar[int] = 0
    odd_shear: ClassVar[bool] = True
    paper_axis_shear_ratio: ClassVar[float] = 0.5

    def pressure_kernel(self, body: ElasticBody, x: np.ndarray, s: np.ndarray,
                        with_w: bool = True) -> Displacements:
        return body.strip_pressure(x, s)

    def shear_kernel(self, body: ElasticBody, x: np.ndarray, s: np.ndarray,
                     with_du: bool = True) -> Displacements:
        return body.strip_shear(x, s)

    def axis_w_kernel(self, body: ElasticBody, x: np.ndarray, s: np.ndarray,
                      part: str, ref: float = 0.0) -> Displacements:
        return body.strip_axis_w(x, s, part, ref)

    def length_degrees(self, body: ElasticBody, part: str) -> np.ndarray | None:
        return None  # the half-plane's w carries a log, a layer its thickness

    def shear_shape(self, x: np.ndarray) -> np.ndarray:
        return np.ones_like(np.asarray(x, dtype=float))

    def element_areas(self, edges: np.ndarray) -> np.ndarray:
        return 2.0 * np.diff(edges)

    def shear_resultants(self, edges: np.ndarray) -> np.ndarray:
        return 2.0 * np.diff(edges)

    def mean_shear_shape(self, edges: np.ndarray) -> np.ndarray:
        return np.ones(np.size(edges) - 1)

    def load_of_steps(self, edges: np.ndarray, p: np.ndarray) -> float:
        return float(2.0 * np.sum(p * np.diff(edges)))

    def load_of_linear(self, nodes: np.ndarray, p: np.ndarray) -> float:
        return float(2.0 * (0.5 * (p[:-1] + p[1:]) * (nodes[1:] - nodes[:-1])).sum())

    def hertz_radius(self, level: float) -> float:
        return float(np.sqrt(level))

    def uncoupled_friction(self, beta: float, gamma: np.ndarray) -> np.ndarray:
        """k = beta K(g) / K'(g) on a half-plane (Spence 1973)."""
        from scipy import special

        g = np.asarray(gamma, dtype=float)
        return beta * special.ellipk(g**2) / _complement_k(g)


_INDENTERS: dict[str, Indenter] = {cls.name: cls() for cls in (Sphere, Cylinder)}
# the geometry names of the public interface are written once, in validate (a leaf
# module the command line loads without numpy); every indenter must be one of them
if tuple(_INDENTERS) != GEOMETRIES:  # pragma: no cover - a programming error
    raise ImportError(f"indenters {tuple(_INDENTERS)} differ from validate.GEOMETRIES "
                      f"{GEOMETRIES}")


def indenter(name: str, modulus_ratio: float = math.inf, nu: float | None = None) -> Indenter:
    """The indenter of a geometry name, rigid or of a given material.

    Parameters
    ----------
    name : {"sphere", "cylinder"}
    modulus_ratio : float
        E1/E2 of the indenter over the body (``inf``: rigid, the default).
    nu : float, optional
        Poisson's ratio of the indenter (None: the body's).

    Raises
    ------
    ValueError
        For a name that is not one of :data:`GEOMETRIES`.
    """
    try:
        rigid = _INDENTERS[name]
    except (KeyError, TypeError):
        raise ValueError(f"geometry must be one of {', '.join(GEOMETRIES)}, "
                         f"got {name!r}") from None
    if modulus_ratio == math.inf and nu is None:
        return rigid
    return replace(rigid, modulus_ratio=float(modulus_ratio),
                   nu=None if nu is None else float(nu))
