"""Which field a body gets: the half-space's or half-plane's, a layer's, a coated body's.

:func:`stress_field` takes the half-space (sphere) or the half-plane (cylinder);
:func:`layer_stresses` adds, for a layer of thickness h on a smooth or bonded rigid base or
bonded to an elastic substrate, the layer's correction of :mod:`contactlib.stresses.layer`
(its notes give the method); :func:`body_field` chooses between them from a solution's
``slab_ratio`` and base.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .halfplane import halfplane_pieces, halfplane_stresses
from .halfspace import halfspace_pieces, halfspace_stresses
from .inputs import COMPONENTS, check_grid, check_tractions
from .pieces import TractionPieces
from .quadrature import PANEL, xi_nodes

__all__ = ["stress_field", "layer_stresses", "pieces_field", "layer_field", "checked_base",
           "body_field"]


def layer_stresses(xi: Any, pressure: Any, shear: Any, x: Any, z: Any, nu: float,
                   thickness: float, base: str, *, geometry: str = "sphere",
                   refine: int = 1, substrate: Any = None) -> dict[str, np.ndarray]:
    """Stresses in a layer on a rigid base, or in a coated body, under tabulated p and q.

    The half-space's (half-plane's) field (:func:`stress_field`) plus the layer's
    correction (:mod:`contactlib.stresses.layer`); in a coated body's substrate (z > h)
    the substrate's own field.

    Parameters
    ----------
    xi, pressure, shear : array_like, shape (m,)
        As for :func:`halfspace_stresses` (r/a) or :func:`halfplane_stresses` (x/a;
        p even and q odd in x), any stress unit.
    x, z : array_like, 1-d
        Output grid: r/a (|r| is used; x/a of either sign for the cylinder) and depth
        z/a in [0, h/a] on a rigid base, z/a >= 0 in a coated body (z <= h: the layer,
        z > h: the substrate).
    nu : float
        Poisson's ratio of the layer, -1 < nu <= 0.5.
    thickness : float
        h/a, the layer's thickness over the contact radius (1 / slab_ratio).
    base : {"smooth", "bonded", "elastic"}
        The rigid base at z = h, or ``"elastic"``: the layer bonded to ``substrate``.
    geometry : {"sphere", "cylinder"}
        Axisymmetric (Hankel) or plane strain (Fourier).
    refine : int
        Divides the panels of the correction's k integral (convergence checks).
    substrate : contactlib.kernels.layer_transfer.Substrate or (float, float), optional
        With ``base="elastic"`` only: E2/E1 and the substrate's Poisson's ratio nu2.

    Returns
    -------
    dict of str to ndarray, shape (len(z), len(x))
        The components of :data:`COMPONENTS` for ``geometry``, in the unit of the
        tractions, tension positive. Error: the half-space's plus the correction's
        quadrature, below 1e-10 of the tractions (tests/test_stresses_layer.py,
        tests/test_stresses_coated.py).

    Raises
    ------
    contactlib.validate.InputError
        For a depth beyond a rigid-based layer (z > h), a base other than smooth, bonded
        or elastic, ``base="elastic"`` without a substrate (or a substrate without it),
        or what :func:`halfspace_stresses` refuses.
    """
    from .layer import check_layer
    from ..validate import InputError

    kernel_base = checked_base(base, substrate)
    nu, h, kernel_base = check_layer(nu, thickness, kernel_base)
    r, p, q = check_tractions(xi, pressure, shear)
    xs, zs = check_grid(x, z)
    if isinstance(kernel_base, str) and np.any(zs > h * (1 + 1e-12)):
        raise InputError("z", f"depths within the layer, 0 <= z <= h = {h!r}", zs.max(),
                         f"z must lie within the layer (0 <= z <= h/a = {h!r}), got "
                         f"z = {zs.max()!r}")
    return layer_field(geometry, nu, (r[:-1], r[1:], p[:-1], p[1:], q[:-1], q[1:]), xs, zs,
                        h, kernel_base, refine)


def pieces_field(geometry: str, nu: float, pieces: tuple[np.ndarray, ...], xs: np.ndarray,
                  zs: np.ndarray) -> dict[str, np.ndarray]:
    """The half-space's (half-plane's) field of linear pieces (sa, sb, pa, pb, qa, qb) on
    r >= 0 (x >= 0: the cylinder's p is even and q odd, so each piece is mirrored)."""
    sa, sb, pa, pb, qa, qb = pieces
    if geometry == "sphere":
        return halfspace_pieces(TractionPieces(sa, sb, pa, pb, qa, qb), xs, zs, nu)
    return halfplane_pieces(np.concatenate([-sb[::-1], sa]), np.concatenate([-sa[::-1], sb]),
                             np.concatenate([pb[::-1], pa]), np.concatenate([pa[::-1], pb]),
                             np.concatenate([-qb[::-1], qa]), np.concatenate([-qa[::-1], qb]),
                             xs, zs, nu)


def layer_field(geometry: str, nu: float, pieces: tuple[np.ndarray, ...], xs: np.ndarray,
                 zs: np.ndarray, h: float, kernel_base: Any, refine: int = 1
                 ) -> dict[str, np.ndarray]:
    """A layer's field (``kernel_base`` a rigid base's name: NaN below the layer; or a
    Substrate: the substrate's field there) of linear traction pieces (as
    :func:`pieces_field`), checked arguments: :func:`layer_stresses`' method."""
    from .layer import PANEL_T, T_CUTOFF, add_correction, coated_nodes, \
        fourier_pieces, substrate_field

    coated = not isinstance(kernel_base, str)  # a Substrate
    sa, sb, pa, pb, qa, qb = pieces
    within = zs <= h * (1 + 1e-12)
    zin = np.minimum(zs[within], h)
    # panels no wider than PANEL/(1 + max r) (the oscillation) nor PANEL_T/h (the layer),
    # nor PANEL_T/z_max in a substrate (its field decays like e^{-k z})
    r_max = float(max(np.abs(xs).max(), sb.max()))
    if coated:
        width = min(PANEL / (1.0 + r_max), PANEL_T / max(h, float(zs.max()))) / max(1, refine)
        k, w = coated_nodes(width, h, nu, kernel_base, refine)
    else:
        width = min(PANEL / (1.0 + r_max), PANEL_T / h) / max(1, refine)
        k, w = xi_nodes(T_CUTOFF / h, PANEL / width - 1.0)
    if geometry == "sphere":
        P, Q = TractionPieces(*pieces).hankel(k)
        rs = np.abs(xs)
    else:
        P, Q = fourier_pieces(*pieces, k)
        P, Q, rs = P / k, Q / k, xs
    out = {name: np.full((zs.size, xs.size), np.nan) for name in COMPONENTS[geometry]}
    if zin.size:
        part = pieces_field(geometry, nu, pieces, xs, zin)
        add_correction(part, k, w, P, Q, rs, zin, nu, h, kernel_base, geometry)
        for name, v in part.items():
            out[name][within] = v
    if coated and not np.all(within):
        part = substrate_field(k, w, P, Q, rs, zs[~within], nu, h, kernel_base, geometry)
        for name, v in part.items():
            out[name][~within] = v
    return out


def checked_base(base: str, substrate: Any) -> Any:
    """The rigid base's name, or a coated body's Substrate (base "elastic"), checked."""
    from ..kernels.layer_transfer import Substrate
    from ..validate import COATED_BASE, InputError

    if base != COATED_BASE:
        if substrate is not None:
            raise InputError("substrate", "given with base 'elastic' only", substrate,
                             f"substrate needs base='elastic' (a coated body), not {base!r}")
        return base
    if substrate is None:
        raise InputError("substrate", "given with base 'elastic'", None,
                         "substrate=(E2/E1, nu2) is needed with base 'elastic' (a coated "
                         "body)")
    if isinstance(substrate, Substrate):
        return substrate
    try:
        return Substrate(*substrate)
    except (TypeError, ValueError) as exc:
        raise InputError("substrate", "(E2/E1 in (0, inf), -1 < nu2 <= 0.5)", substrate,
                         f"substrate must be (E2/E1 in (0, inf), nu2 in (-1, 0.5]): "
                         f"{exc}") from None


def stress_field(geometry: str, nu: float, xi: Any, pressure: Any, shear: Any, x: Any,
                 z: Any) -> dict[str, np.ndarray]:
    """The stress components of ``geometry`` (:data:`COMPONENTS`) on the grid (z, x).

    Parameters
    ----------
    geometry : {"sphere", "cylinder"}
        :func:`halfspace_stresses` or :func:`halfplane_stresses`.
    nu : float
        Poisson's ratio of the body.
    xi, pressure, shear : array_like, shape (m,)
        Tabulated tractions on r/a (x/a) >= 0, piecewise linear between, in any stress
        unit (p0 for a Solution's ``pressure`` and ``shear``).
    x, z : array_like, 1-d
        Output grid, r/a (x/a) and depth z/a >= 0.

    Returns
    -------
    dict of str to ndarray, shape (len(z), len(x))
        The components, in the unit of the tractions, tension positive.
    """
    if geometry == "sphere":
        return halfspace_stresses(xi, pressure, shear, x, z, nu)
    if geometry == "cylinder":
        return halfplane_stresses(xi, pressure, shear, x, z, nu)
    from ..validate import InputError
    raise InputError("geometry", "sphere or cylinder", geometry)


def body_field(geometry: str, nu: float, xi: Any, p: Any, q: Any, xs: np.ndarray,
               zs: np.ndarray, slab_ratio: float = 0.0, base: str = "smooth",
               substrate: Any = None) -> dict[str, np.ndarray]:
    """The stress components in the body: the half-space's or half-plane's
    (:func:`stress_field`), or, at ``slab_ratio`` > 0, a layer's on its rigid base
    (:func:`layer_stresses`; NaN at the depths z > h = 1/slab_ratio, below the layer), or
    a coated body's (base "elastic" on ``substrate`` = (E2/E1, nu2): the layer for
    z <= h, the substrate below)."""
    if not slab_ratio > 0:
        return stress_field(geometry, nu, xi, p, q, xs, zs)
    h = 1.0 / float(slab_ratio)
    if substrate is not None:
        return layer_stresses(xi, p, q, xs, zs, nu, h, base, geometry=geometry,
                              substrate=substrate)
    within = zs <= h
    fields = {name: np.full((zs.size, xs.size), np.nan) for name in COMPONENTS[geometry]}
    if np.any(within):
        part = layer_stresses(xi, p, q, xs, zs[within], nu, h, base, geometry=geometry)
        for name, v in part.items():
            fields[name][within] = v
    return fields
