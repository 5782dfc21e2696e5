"""The field under a solved case (:class:`~contactlib.result.Solution`), an xarray Dataset.

:func:`subsurface_stresses` integrates the tractions a solve returns
(:func:`traction_samples`), in units of p0 and a, in the body or in an elastic indenter;
:func:`surface_radial_stress` and :func:`first_yield` read it.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from .dispatch import body_field
from .inputs import COMPONENTS, check_grid
from .measures import derived_measures, field_maximum

__all__ = ["LONG_NAMES", "tractions_of", "substrate_of", "traction_samples", "subsurface_stresses",
           "surface_radial_stress", "first_yield"]

LONG_NAMES = {
    "sigma_rr": "radial normal stress / p0", "sigma_tt": "hoop normal stress / p0",
    "sigma_zz": "normal stress across planes z = const / p0",
    "sigma_rz": "shear stress sigma_rz / p0", "sigma_xx": "normal stress sigma_xx / p0",
    "sigma_yy": "out-of-plane normal stress nu (sigma_xx + sigma_zz) / p0",
    "sigma_xz": "shear stress sigma_xz / p0",
    "von_mises": "von Mises equivalent stress / p0",
    "tresca": "maximum shear stress (sigma_1 - sigma_3)/2 / p0",
    "hydrostatic": "mean normal stress (trace/3) / p0, tension positive",
    "sigma_1": "largest principal stress / p0", "sigma_2": "middle principal stress / p0",
    "sigma_3": "smallest principal stress / p0",
}


def tractions_of(solution: Any, body: str) -> tuple[float, np.ndarray, np.ndarray]:
    """Poisson's ratio and tractions (p, q) on the body asked for, refusing a body name
    other than "body" or "indenter" (the layer's base is checked by :func:`checked_base`
    and :func:`contactlib.stresses.layer.check_layer`)."""
    from ..validate import InputError

    if body not in ("body", "indenter"):
        raise InputError("body", "'body' or 'indenter'", body)
    p = np.asarray(solution.pressure, dtype=float)
    q = np.asarray(solution.shear, dtype=float)
    if not bool(getattr(solution, "converged", True)):  # its tractions are no data
        raise InputError("solution", "a converged case", "not converged",
                         "the solution did not converge (its message says why): no "
                         "stresses from it")
    if not (np.all(np.isfinite(p)) and np.all(np.isfinite(q))):
        raise InputError("solution", "a converged case with finite tractions", "NaN tractions",
                         "the solution's tractions are NaN (a case that did not converge): "
                         "no stresses from it")
    if body == "body":
        return float(solution.nu), p, q
    if math.isinf(float(solution.indenter_modulus_ratio)):
        raise InputError("body", "'body' for a rigid indenter", body,
                         "body must be 'body' for a rigid indenter (it has no stress field), "
                         "got 'indenter'")
    return float(solution.indenter_poisson_ratio), p, -q


def substrate_of(solution: Any) -> tuple[float, float] | None:
    """(E2/E1, nu2) of a coated body's solution (base "elastic"), None otherwise."""
    from ..validate import COATED_BASE

    if getattr(solution, "base", "smooth") != COATED_BASE:
        return None
    return (float(solution.substrate_modulus), float(solution.substrate_poisson_ratio))


def traction_samples(solution: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(xi, p/p0, q/p0) whose piecewise-linear interpolation the field integrates.

    The solve's own nodes and nodal tractions where the solution carries them
    (``solution.extra["nodes"]``, default and extrapolated methods: the field then
    converges with n), else its output points ``xi``, ``pressure``, ``shear``.
    """
    nodal = getattr(solution, "extra", None) or {}
    if "nodes" in nodal:
        return (np.asarray(nodal["nodes"], dtype=float),
                np.asarray(nodal["nodal_pressure"], dtype=float),
                np.asarray(nodal["nodal_shear"], dtype=float))
    return (np.asarray(solution.xi, dtype=float), np.asarray(solution.pressure, dtype=float),
            np.asarray(solution.shear, dtype=float))


def subsurface_stresses(solution: Any, x: Any, z: Any, *, body: str = "body",
                        measures: bool = True) -> Any:
    """The stress field under a solved case, as an xarray Dataset in units of p0.

    Parameters
    ----------
    solution : contactlib.result.Solution
        A solved case (:func:`contactlib.solve`) on a half-space or half-plane, or on a
        layer of thickness h = a / ``slab_ratio`` on a smooth or bonded rigid base
        (:func:`layer_stresses`; the depths z > h, below the layer, are NaN; attributes
        ``layer_thickness`` and ``base``), or a coated body (``base="elastic"``: z > h is
        the substrate; attributes also ``substrate_modulus`` E2/E1 and
        ``substrate_poisson_ratio``); its
        ``pressure`` and ``shear`` (p/p0, q/p0 on ``xi``, piecewise linear between the
        points) are the tractions. p0 is the Hertz peak pressure at the same contact
        radius (docs/conventions.md), so a frictionless case has p = sqrt(1 - xi^2).
    x, z : array_like, 1-d
        r/a (sphere) or x/a (cylinder) and the depth z/a >= 0, positive into the body.
    body : {"body", "indenter"}
        ``"body"``: the elastic body (the lower one, ``nu``). ``"indenter"``: an elastic
        indenter, taken as a half-space of its own Poisson's ratio under the same pressure
        and the opposite shear (Hertz's approximation: the contact is small against R),
        z then positive into the indenter; refused for a rigid indenter.
    measures : bool
        Add ``von_mises``, ``tresca``, ``hydrostatic`` and ``sigma_1`` ... ``sigma_3``.

    Returns
    -------
    xarray.Dataset
        Dimensions (z, x); the components of :data:`COMPONENTS` and the measures, all /p0
        (CF units ``"1"``), tension positive; attributes ``geometry``, ``poisson_ratio``
        (of the body asked for), ``body``, ``stick_ratio``, ``friction_coefficient``,
        ``elements``, ``method``, ``indenter_modulus_ratio`` and ``dundurs_beta``.

    Raises
    ------
    contactlib.validate.InputError
        For a case with NaN tractions, ``body="indenter"`` with a rigid indenter, or a
        bad grid.

    Examples
    --------
    >>> import numpy as np
    >>> from contactlib import solve
    >>> from contactlib.stresses import subsurface_stresses
    >>> sol = solve("sphere", 0.3, stick_ratio=0.0, n=64)
    >>> ds = subsurface_stresses(sol, [0.0], [0.0, 1.0])
    >>> np.round(ds.sigma_zz.values[:, 0], 3)  # Huber: -1/(1 + z^2) on the axis
    array([-1. , -0.5])
    """
    import xarray as xr

    nu, _, _ = tractions_of(solution, body)
    xi, p, q = traction_samples(solution)
    q = q if body == "body" else -q
    xs, zs = check_grid(x, z)
    geometry = solution.geometry
    slab = float(getattr(solution, "slab_ratio", 0.0)) if body == "body" else 0.0
    substrate = substrate_of(solution) if slab > 0 else None
    fields = body_field(geometry, nu, xi, p, q, xs, zs, slab, getattr(solution, "base", ""),
                        substrate)
    layer: dict[str, Any] = {}
    if slab > 0:
        layer = {"layer_thickness": 1.0 / slab, "base": str(solution.base),
                 "beyond_layer": "NaN at depths z > h (below the layer, the rigid base)"}
    if substrate is not None:
        layer.update(substrate_modulus=substrate[0], substrate_poisson_ratio=substrate[1],
                     beyond_layer="the substrate at depths z > h (E2/E1 substrate_modulus, "
                                  "Poisson's ratio substrate_poisson_ratio)")
    if measures:
        fields.update(derived_measures(geometry, fields))
    coords = {"z": ("z", zs, {"units": "1", "long_name": "depth / a, positive into the "
                                                         + ("indenter" if body == "indenter"
                                                            else "body")}),
              "x": ("x", xs, {"units": "1", "long_name": ("r / a" if geometry == "sphere"
                                                          else "x / a")})}
    data = {name: (("z", "x"), v, {"units": "1", "long_name": LONG_NAMES[name]})
            for name, v in fields.items()}
    attrs = {"geometry": geometry, "poisson_ratio": nu, "body": body,
             "stick_ratio": float(solution.stick_ratio),
             "friction_coefficient": float(solution.friction_coefficient),
             "elements": int(solution.n), "method": str(solution.method),
             "indenter_modulus_ratio": float(solution.indenter_modulus_ratio),
             "dundurs_beta": float(solution.dundurs_beta),
             "stress_unit": "p0, the Hertz peak pressure at the same contact radius",
             **layer}
    return xr.Dataset(data, coords=coords, attrs=attrs)


def surface_radial_stress(solution: Any, x: Sequence[float] | np.ndarray, *,
                          body: str = "body") -> np.ndarray:
    """sigma_rr (sphere) or sigma_xx (cylinder) on the surface z = 0, units of p0.

    At and outside the contact edge (x >= 1) this is the tension that starts cone cracks
    in brittle bodies: (1 - 2 nu)/(3 x^2) for frictionless Hertz (sphere).

    Parameters
    ----------
    solution : contactlib.result.Solution
        A solved case on a half-space or half-plane.
    x : array_like, 1-d
        r/a (x/a) on the surface.
    body : {"body", "indenter"}
        As for :func:`subsurface_stresses`.

    Returns
    -------
    ndarray
        The radial (x) normal stress / p0 at ``x``, tension positive.
    """
    ds = subsurface_stresses(solution, x, [0.0], body=body, measures=False)
    return ds[COMPONENTS[solution.geometry][0]].values[0]


def first_yield(solution: Any, x: Any = None, z: Any = None, *,
                body: str = "body") -> dict[str, float]:
    """Where and at what peak pressure the body first yields (von Mises).

    The field is linear in the tractions, which scale with p0 for a self-similar case,
    so yield starts where von Mises / p0 is largest, at p0 / Y = 1 / max(von Mises / p0)
    for a yield stress Y in tension.

    Parameters
    ----------
    solution : contactlib.result.Solution
        A solved case (half-space or half-plane).
    x, z : array_like, optional
        The grid searched (default: r/a (x/a) on [0, 1.5] and z/a on [0, 1], spacing
        0.01); the maximum is refined by a parabola along each axis
        (:func:`field_maximum`).
    body : {"body", "indenter"}
        As for :func:`subsurface_stresses`.

    Returns
    -------
    dict
        ``p0_over_yield`` (p0 / Y at first yield), ``load_over_yield`` (the load there:
        P / (Y a^2) for the sphere, P / (Y a) per unit length for the cylinder, from the
        solution's ``load_ratio``), ``x`` and ``z`` (units of a) of the first yield.
    """
    xs = np.linspace(0.0, 1.5, 151) if x is None else x
    zs = np.linspace(0.0, 1.0, 101) if z is None else z
    top = field_maximum(subsurface_stresses(solution, xs, zs, body=body), "von_mises")
    ratio = 1.0 / top["value"]
    # P_Hertz(a) / (p0 a^2) = 2 pi / 3 (sphere), pi / 2 per unit length (cylinder)
    hertz = 2.0 * math.pi / 3.0 if solution.geometry == "sphere" else math.pi / 2.0
    return {"p0_over_yield": ratio, "load_over_yield": ratio * hertz * solution.load_ratio,
            "x": top["x"], "z": top["z"]}
