r"""The body the indenter is pressed into: its material and its kernels.

An :class:`ElasticBody` is a homogeneous, isotropic, linear elastic body: a
half-space (under rings) or half-plane (under strips, plane strain), or a
layer of thickness h on a rigid base, smooth (frictionless, the paper's
slab) or bonded, or on an elastic half-space / half-plane (``base="elastic"``, a
coated body: the layer bonded to a substrate of its own modulus and Poisson's
ratio; rings only). It answers the basic loads the indenter puts on it (see
:mod:`contactlib.model.indenter`): a uniform pressure, or a shear element, on a disc
or a symmetric strip of radius ``s``, with the closed-form kernels of
:mod:`contactlib.kernels`.

Units and scalings
------------------
E* = E/(1 - nu^2) of the body = 1 and lengths in units of the length scale
of the problem (the contact radius ``a``, or ``a_max`` in the incremental
solver). The layer is given by ``slab_ratio`` = (length scale)/h, 0 for the
half-space or half-plane, so the thickness in these units is
``1/slab_ratio``; ``base`` is "smooth" (u_z = 0, no shear on the base) or
"bonded" (u_z = u_r = 0), or "elastic" (a bonded substrate with
``substrate_modulus`` = E2/E1 of the substrate over the layer and
``substrate_nu``; E* is the layer's), and is ignored on the half-space.
Displacements are w (into the body) and u (away from the
axis) in (length scale)^2/R per unit traction in E* (length scale)/R.

beta = (1 - 2 nu)/(2 (1 - nu)) is Dundurs' coupling parameter of a rigid
indenter on this body: 0 at nu = 0.5, where the normal and tangential
problems decouple.

Examples
--------
>>> from contactlib.model.body import ElasticBody
>>> body = ElasticBody(0.3)
>>> round(body.beta, 12), body.is_half_space
(0.285714285714, True)
>>> ElasticBody(0.3, slab_ratio=0.05).thickness
20.0
>>> ElasticBody(0.3, slab_ratio=1.0, base="bonded").ring_kernel_degrees is None
True
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .indenter import Displacements
from ..kernels import disc, layer, strip
from .theory import beta_of_nu

__all__ = ["ElasticBody"]
_HALF_SPACE_DEGREES = np.array([1.0, 1.0, 0.0])  # w, u ~ s; du/dx ~ s^0


@dataclass(frozen=True)
class ElasticBody:
    """A linear elastic body: half-space / half-plane, or a layer on a rigid base.

    Parameters
    ----------
    nu : float
        Poisson's ratio, in (-1, 0.5].
    slab_ratio : float
        (length scale)/h of a layer of thickness h on a rigid base; 0
        (default) is the half-space or half-plane.
    base : {"smooth", "bonded", "elastic"}
        The layer's base: rigid and frictionless (default, the paper's slab),
        rigid and bonded, or an elastic half-space bonded to the layer (a
        coated body; rings only). Irrelevant on the half-space.
    substrate_modulus : float
        E2/E1, the elastic substrate's Young's modulus over the layer's, in
        (0, inf); only with ``base="elastic"``.
    substrate_nu : float, optional
        The substrate's Poisson's ratio (None: the layer's); only with
        ``base="elastic"``.
    """

    nu: float
    slab_ratio: float = 0.0
    base: str = "smooth"
    substrate_modulus: float = np.inf
    substrate_nu: float | None = None

    @property
    def kernel_base(self) -> str | layer.Substrate:
        """The ``base`` argument of the layer kernels: the base's name, or the
        :class:`contactlib.kernels.layer.Substrate` of a coated body."""
        if self.base != "elastic":
            return self.base
        nu2 = self.nu if self.substrate_nu is None else self.substrate_nu
        return layer.Substrate(self.substrate_modulus, nu2)

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
    def ring_pressure(self, x: np.ndarray, s: np.ndarray, with_w: bool = True) -> Displacements:
        """(w, u, du/dr) under a unit pressure on the disc r < s.

        :func:`contactlib.kernels.disc.pressure_disc` on the half-space,
        :func:`contactlib.kernels.layer.pressure_disc` on a layer (which
        raises ValueError beyond ``max(r, s)/h = 20``).
        """
        if self.is_half_space:
            return disc.pressure_disc(x, s, self.nu, with_w=with_w)
        return layer.pressure_disc(x, s, self.nu, self.thickness, self.kernel_base, with_w=with_w)

    def ring_shear(self, x: np.ndarray, s: np.ndarray, with_du: bool = True) -> Displacements:
        """(w, u, du/dr) under the shear q = r on the disc r < s.

        :func:`contactlib.kernels.disc.shear_disc` on the half-space,
        :func:`contactlib.kernels.layer.shear_disc` on a layer.
        """
        if self.is_half_space:
            return disc.shear_disc(x, s, self.nu, with_du=with_du)
        return layer.shear_disc(x, s, self.nu, self.thickness, self.kernel_base, with_du=with_du)

    def ring_remainder(self, kind: str, x: np.ndarray, s: np.ndarray,
                       weights: np.ndarray | None = None,
                       owner: np.ndarray | None = None) -> np.ndarray | None:
        """What the layer adds to the half-space ring kernels, on the grid x by s.

        ``kind`` "pressure" or "shear"; shape (3, x.size, s.size), rows (w, u,
        du/dr), or with quadrature ``weights`` and ``owner`` their weighted
        sums (:func:`contactlib.kernels.layer.remainder_grid`); analytic in
        (x, s). None on the half-space.
        """
        if self.is_half_space:
            return None
        return layer.remainder_grid(kind, x, s, self.nu, self.thickness, self.kernel_base,
                                    weights, owner)

    @property
    def half_space(self) -> ElasticBody:
        """The same material unbounded: the singular part of a layer's kernels."""
        return ElasticBody(self.nu)

    def ring_axis_w(self, x: np.ndarray, s: np.ndarray, part: str,
                    ref: float = 0.0) -> Displacements:
        """(w(x) - w(ref), 0, 0) of the disc load of ``part``, without cancellation.

        :func:`contactlib.kernels.disc.w_difference_disc`. On a layer, relative
        to the axis (ref = 0) and for x/h <= :data:`contactlib.kernels.layer.AXIS_RHO_MAX`:
        the half-space's difference plus the remainder's
        (:func:`contactlib.kernels.layer.remainder_axis_w`). Otherwise a layer
        raises NotImplementedError (the default method then keeps its plain
        normal rows).
        """
        if self.is_half_space:
            return disc.w_difference_disc(x, ref, s, self.nu, part)
        h = self.thickness
        if ref != 0.0 or np.max(np.abs(x), initial=0.0) > layer.AXIS_RHO_MAX * h:
            raise NotImplementedError(
                f"no cancellation-free w(x) - w(ref) of ring loads on a layer away from the "
                f"axis (slab_ratio = {self.slab_ratio!r}, ref = {ref!r})")
        dw, zero, zero2 = disc.w_difference_disc(x, 0.0, s, self.nu, part)
        kind = "pressure" if part == "normal" else "shear"
        return dw + layer.remainder_axis_w(kind, x, s, self.nu, h, self.kernel_base), zero, zero2

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
        :attr:`thickness` and the :attr:`base`.
        """
        return strip.pressure_strip(x, s, self.nu, self.thickness, self.kernel_base)

    def strip_axis_w(self, x: np.ndarray, s: np.ndarray, part: str,
                     ref: float = 0.0) -> Displacements:
        """(w(x) - w(ref), 0, 0) of the strip load of ``part``, without cancellation.

        :func:`contactlib.kernels.strip.w_difference_strip` with the thickness
        :attr:`thickness` and the :attr:`base`.
        """
        return strip.w_difference_strip(x, ref, s, self.nu, part, self.thickness, self.kernel_base)

    def strip_shear(self, x: np.ndarray, s: np.ndarray) -> Displacements:
        """(w, u, du/dx) under the odd shear sgn(x) on |x| < s (half-plane or slab).

        :func:`contactlib.kernels.strip.shear_strip` with the thickness
        :attr:`thickness` and the :attr:`base`.
        """
        return strip.shear_strip(x, s, self.nu, self.thickness, self.kernel_base)


# ----------------------------------------------------------------------------- viscoelastic body
__all__ += ["ViscoelasticBody"]


@dataclass(frozen=True)
class ViscoelasticBody(ElasticBody):
    r"""A linear viscoelastic body with a constant Poisson's ratio (Prony relaxation).

    E(t)/E(0) = 1 - sum_i g_i (1 - exp(-t/tau_i)) = g_inf + sum_i g_i exp(-t/tau_i),
    ``g_inf = 1 - sum g_i`` (E(inf)/E(0)). Shear and bulk moduli relax in
    proportion (nu constant), so every kernel of the body scales with the
    same E(t)/E(0): its answer to a traction history is the elastic kernel at
    E(0) (the inherited ring/strip methods, in units of E*(0)) convolved in
    time with E(t)/E(0), and Dundurs' beta does not change in time.

    Parameters
    ----------
    nu, slab_ratio, base
        As for :class:`ElasticBody` (the kernels are those at E(0)).
    relaxation : tuple of (g, tau)
        The Prony terms: g_i > 0, sum g_i < 1, tau_i > 0 (the time unit is
        the caller's; the path's duration uses the same one).

    Examples
    --------
    >>> body = ViscoelasticBody(0.3, relaxation=((0.5, 1.0),))
    >>> body.relaxed_ratio, round(float(body.relaxation_ratio(1.0)), 6)
    (0.5, 0.68394)
    """

    relaxation: tuple[tuple[float, float], ...] = ()

    @property
    def weights(self) -> np.ndarray:
        """g_i of the Prony terms."""
        return np.array([g for g, _ in self.relaxation], dtype=float)

    @property
    def times(self) -> np.ndarray:
        """tau_i of the Prony terms (the caller's time unit)."""
        return np.array([t for _, t in self.relaxation], dtype=float)

    @property
    def relaxed_ratio(self) -> float:
        """E(inf)/E(0) = 1 - sum g_i."""
        return float(1.0 - sum(g for g, _ in self.relaxation))

    def relaxation_ratio(self, t: np.ndarray | float) -> np.ndarray:
        """E(t)/E(0) at times ``t`` >= 0."""
        t = np.asarray(t, dtype=float)
        return self.relaxed_ratio + np.sum(
            self.weights * np.exp(-t[..., None] / self.times), axis=-1)
