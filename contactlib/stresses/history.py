"""The field under one step of a loading history (:func:`contactlib.history`)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .dispatch import checked_base, layer_field, pieces_field
from .inputs import check_grid
from .measures import derived_measures
from .solution import LONG_NAMES, substrate_of, tractions_of

__all__ = ["history_stresses"]


def history_stresses(result: Any, step: int, x: Any, z: Any, *, body: str = "body",
                     measures: bool = True) -> Any:
    """The stress field under one step of a loading history, as an xarray Dataset.

    Parameters
    ----------
    result : contactlib.history_api.HistoryResult
        A followed load path (:func:`contactlib.history`) on a half-space or half-plane,
        on a layer on a smooth or bonded rigid base (``slab_ratio`` = a_max/h > 0: the
        depths below the layer, z > h, are NaN) or on a coated body (base "elastic":
        below the layer the substrate's field; :func:`layer_stresses`).
        Its tractions are element-wise, as the history solver has them: on element j
        (edges ``xi_bounds[j]``) the pressure is constant and the shear is q_j r / r_j
        (sphere) or constant (cylinder, odd in x), r_j the midpoint ``xi[j]``.
    step : int
        The step, 0 ... S (negative counts from the end).
    x, z : array_like, 1-d
        r / a_max (x / a_max) and the depth z / a_max >= 0.
    body : {"body", "indenter"}
        As for :func:`subsurface_stresses`.
    measures : bool
        Add the derived measures (:func:`derived_measures`).

    Returns
    -------
    xarray.Dataset
        As :func:`subsurface_stresses`, lengths in units of a_max and stresses in units of
        p0(a_max), the Hertz peak pressure at a_max (docs/conventions.md, histories);
        attributes ``step``, ``load_ratio`` and ``contact_radius`` of the step. A
        viscoelastic body's field is its elastic one: under given tractions the stresses
        of a half-space depend on Poisson's ratio alone, which contactlib's relaxation
        keeps constant.

    Raises
    ------
    contactlib.validate.InputError
        As :func:`subsurface_stresses` (a coated body, a step that did not converge),
        and for a step out of range.
    """
    import xarray as xr

    from ..validate import InputError

    from ..model.profiles import takes

    if not takes(getattr(result, "profile", "paraboloid"), "stresses"):
        raise InputError("result", "a history of a power-law profile", "profile 'flat'",
                         "result of profile 'flat': stresses are not available under the "
                         "flat punch, whose pressure is "
                         "singular at the sharp edge, where the element-wise field does not "
                         "converge")
    steps = np.asarray(result.pressure).shape[0]
    if not isinstance(step, (int, np.integer)) or not -steps <= int(step) < steps:
        raise InputError("step", f"an integer in [-{steps}, {steps - 1}]", step)
    step = int(step) % steps

    class _Step:  # the step's tractions in the shape tractions_of reads
        pressure = np.asarray(result.pressure)[step]
        shear = np.asarray(result.shear)[step]
        converged = bool(np.asarray(result.converged)[step])

    for name in ("slab_ratio", "nu", "indenter_modulus_ratio", "indenter_poisson_ratio"):
        setattr(_Step, name, getattr(result, name, math.inf if "modulus" in name else 0.0))
    _Step.base = getattr(result, "base", "smooth")
    nu, p, q = tractions_of(_Step, body)
    xs, zs = check_grid(x, z)
    bounds = np.asarray(result.xi_bounds, dtype=float)
    mid = np.asarray(result.xi, dtype=float)
    sa, sb = bounds[:, 0], bounds[:, 1]
    geometry = result.geometry
    # element tractions: p constant, q = q_j r/r_j (sphere) or constant (cylinder)
    pieces = ((sa, sb, p, p, q * sa / mid, q * sb / mid) if geometry == "sphere"
              else (sa, sb, p, p, q, q))
    slab = float(getattr(result, "slab_ratio", 0.0))
    if slab > 0 and body == "body":  # the layer (h = a_max/slab_ratio) holds the body's field
        from .layer import check_layer

        kernel_base = checked_base(_Step.base, substrate_of(result))
        nu, h, kernel_base = check_layer(nu, 1.0 / slab, kernel_base)
        fields = layer_field(geometry, nu, pieces, xs, zs, h, kernel_base)
    else:  # a half-space, or an elastic indenter (a half-space) on a layer
        fields = pieces_field(geometry, nu, pieces, xs, zs)
    if measures:
        fields.update(derived_measures(geometry, fields))
    into = "indenter" if body == "indenter" else "body"
    coords = {"z": ("z", zs, {"units": "1", "long_name": f"depth / a_max, into the {into}"}),
              "x": ("x", xs, {"units": "1", "long_name": ("r / a_max" if geometry == "sphere"
                                                          else "x / a_max")})}
    data = {name: (("z", "x"), v, {"units": "1",
                                   "long_name": LONG_NAMES[name].replace("p0", "p0(a_max)")})
            for name, v in fields.items()}
    attrs = {"geometry": geometry, "poisson_ratio": nu, "body": body, "step": step,
             "load_ratio": float(np.asarray(result.load_ratio)[step]),
             "contact_radius": float(np.asarray(result.contact_radius)[step]),
             "slab_ratio": float(getattr(result, "slab_ratio", 0.0)),
             "friction_coefficient": float(result.friction), "elements": int(result.n),
             "indenter_modulus_ratio": float(getattr(result, "indenter_modulus_ratio",
                                                     math.inf)),
             "stress_unit": "p0(a_max), the Hertz peak pressure at a_max"}
    if attrs["slab_ratio"] > 0:
        attrs["base"] = _Step.base
        if substrate_of(result) is not None:
            attrs["substrate_modulus"], attrs["substrate_poisson_ratio"] = substrate_of(result)
    return xr.Dataset(data, coords=coords, attrs=attrs)
