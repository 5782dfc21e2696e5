"""The field added to a solve's dataset (``contactlib solve --subsurface``) and to a scene's."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from .dispatch import body_field
from .inputs import COMPONENTS
from .measures import derived_measures
from .solution import LONG_NAMES, subsurface_stresses

__all__ = ["default_grid", "check_subsurface_request", "with_subsurface", "scene_subsurface"]


def default_grid() -> tuple[np.ndarray, np.ndarray]:
    """The grid of ``contactlib solve --subsurface``: x = r/a (x/a) and z = depth/a.

    :data:`contactlib.validate.SUBSURFACE_GRID`, 101 equally spaced points on [0, 2] each
    (the field is even in x, sigma_xz odd).

    Returns
    -------
    x, z : ndarray
    """
    from ..validate import SUBSURFACE_GRID

    (x0, x1, nx), (z0, z1, nz) = SUBSURFACE_GRID
    return np.linspace(x0, x1, nx), np.linspace(z0, z1, nz)


def check_subsurface_request(output: Any, slab_ratio: float, base: str = "smooth") -> None:
    """Refuse, before any solving, a subsurface request that cannot be met.

    ``slab_ratio`` and ``base`` are kept for callers; every body is covered (half-space,
    half-plane, a layer on a rigid base, a coated body).

    Raises
    ------
    contactlib.validate.InputError
        Without an output file.
    """
    from ..validate import InputError

    if output is None:
        raise InputError("subsurface", "given with an output file", True,
                         "subsurface needs an output file (--output FILE.nc) for the field")


def with_subsurface(dataset: Any, solution: Any, x: Any = None, z: Any = None) -> Any:
    """A solve's dataset (:func:`contactlib.io.to_dataset`) with the stress field added.

    Parameters
    ----------
    dataset : xarray.Dataset
        The dataset of ``solution``.
    solution : contactlib.result.Solution
        The solved case.
    x, z : array_like, optional
        The grid (default :func:`default_grid`).

    Returns
    -------
    xarray.Dataset
        ``dataset`` with the coordinates ``x``, ``z`` and the variables of
        :func:`subsurface_stresses` for the body (units of p0); with an elastic indenter
        also the indenter's field, each variable prefixed ``indenter_`` (z then into the
        indenter); the attribute ``subsurface_body`` (``"body"`` or ``"body indenter"``).
    """
    if x is None or z is None:
        gx, gz = default_grid()
        x, z = gx if x is None else x, gz if z is None else z
    field = subsurface_stresses(solution, x, z)
    out = dataset.copy()
    for name in field.coords:
        out = out.assign_coords({name: field[name]})
    for name in field.data_vars:
        out[name] = field[name]
    bodies = ["body"]
    if not math.isinf(float(solution.indenter_modulus_ratio)):
        other = subsurface_stresses(solution, x, z, body="indenter")
        for name in other.data_vars:
            out["indenter_" + name] = other[name].assign_attrs(
                long_name=other[name].attrs["long_name"] + " in the indenter (z into it)")
        bodies.append("indenter")
    out.attrs["subsurface_body"] = " ".join(bodies)
    return out


def scene_subsurface(dataset: Any, scene: Any, profiles: Sequence[dict[str, np.ndarray]],
                     xi: np.ndarray) -> Any:
    """A scene's dataset with the ``subsurface`` output: the field of every stick ratio.

    Parameters
    ----------
    dataset : xarray.Dataset
        The scene's dataset (:func:`contactlib.io.scene_to_dataset`), dimension
        ``stick_ratio``.
    scene : contactlib.scene.Scene
        The scene (its ``geometry``, ``nu`` and ``subsurface_grid``).
    profiles : sequence of dict
        One a stick ratio, in the dataset's order: ``pressure`` and ``shear`` (p/p0,
        q/p0) on ``xi``, and the solve's nodal tractions where it has them (``nodes``,
        ``nodal_pressure``, ``nodal_shear``: :func:`contactlib.stages.nodal_tractions`),
        which the field then integrates.
    xi : ndarray
        The profiles' abscissae.

    Returns
    -------
    xarray.Dataset
        ``dataset`` with the coordinates ``x``, ``z`` and the variables of
        :func:`subsurface_stresses` on (stick_ratio, z, x), in units of p0; NaN for a case
        whose tractions are NaN (not converged). With an elastic indenter also its field
        (prefix ``indenter_``; its Poisson's ratio, the opposite shear, z into it, as
        :func:`subsurface_stresses` with ``body="indenter"``); attribute
        ``subsurface_body``.
    """
    from ..validate import COATED_BASE

    (x0, x1, nx), (z0, z1, nz) = scene.subsurface_grid
    xs, zs = np.linspace(x0, x1, nx), np.linspace(z0, z1, nz)
    geometry = scene.geometry
    names = COMPONENTS[geometry] + ("von_mises", "tresca", "hydrostatic", "sigma_1",
                                    "sigma_2", "sigma_3")
    bodies = {"": (float(scene.nu), 1.0)}  # prefix: (Poisson's ratio, sign of the shear)
    if not math.isinf(float(scene.indenter_modulus)):
        nu1 = scene.nu if scene.indenter_nu is None else scene.indenter_nu
        bodies["indenter_"] = (float(nu1), -1.0)
    stack = {prefix + name: np.full((len(profiles), zs.size, xs.size), np.nan)
             for prefix in bodies for name in names}
    substrate = None  # a coated body's (E2/E1, nu2; nu2 None: the layer's)
    if getattr(scene, "base", "smooth") == COATED_BASE:
        nu2 = scene.nu if scene.substrate_nu is None else scene.substrate_nu
        substrate = (float(scene.substrate_modulus), float(nu2))
    for i, prof in enumerate(profiles):
        p, q = np.asarray(prof["pressure"]), np.asarray(prof["shear"])
        if not (np.all(np.isfinite(p)) and np.all(np.isfinite(q))):
            continue
        at = xi
        if "nodes" in prof:  # the solve's own tractions, as the API's field (traction_samples)
            at, p, q = prof["nodes"], prof["nodal_pressure"], prof["nodal_shear"]
        for prefix, (nu, sign) in bodies.items():
            slab = float(getattr(scene, "slab_ratio", 0.0)) if not prefix else 0.0
            fields = body_field(geometry, nu, at, p, sign * q, xs, zs, slab,
                                getattr(scene, "base", "smooth"), substrate)
            fields.update(derived_measures(geometry, fields))
            for name in names:
                stack[prefix + name][i] = fields[name]
    out = dataset.assign_coords(
        z=("z", zs, {"units": "1", "long_name": "depth / a, positive into the body "
                                                "(into the indenter for indenter_*)"}),
        x=("x", xs, {"units": "1", "long_name": "r / a" if geometry == "sphere" else "x / a"}))
    dims = ("stick_ratio", "z", "x") if "stick_ratio" in dataset.dims else ("z", "x")
    for prefix in bodies:
        for name in names:
            value = stack[prefix + name]
            long_name = LONG_NAMES[name] + (" in the indenter" if prefix else "")
            out[prefix + name] = (dims, value if len(dims) == 3 else value[0],
                                  {"units": "1", "long_name": long_name})
    out.attrs["subsurface_body"] = "body indenter" if len(bodies) > 1 else "body"
    return out
