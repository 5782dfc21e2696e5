"""Datasets and files: every CF convention and the one atomic write of contactlib.

This is the only module of :mod:`contactlib` that touches the disk, and the
only one that knows the file conventions. It turns the results of the
numerics into CF-annotated :class:`xarray.Dataset` objects (variable names
and scalings of docs/conventions.md):

* :func:`to_dataset` for :class:`~contactlib.result.Solution` objects
  (``contactlib solve``/``sweep``), :func:`scene_to_dataset` for a workflow
  scene and :func:`set_provenance` for the workflow's attributes;
* :func:`history_to_dataset` and :func:`stack_histories` for loading
  histories (:class:`~contactlib.history_api.HistoryResult`);
* :func:`study_to_dataset` and :func:`study_from_dataset` for convergence
  studies (:class:`~contactlib.convergence.Study`);
* :func:`write_records` and :func:`read_records` for the case records
  (:class:`~contactlib.result.CaseRecord`) the workflow passes between its
  stages (npz).

Every file the workflow passes on carries a content check, the SHA-256 of
its content (npz: an array ``contactlib_sha256``; netCDF: a global attribute
``contactlib_sha256``), written by the writers and verified by the readers:
a truncated, corrupt or changed file is a :class:`DamagedFileError` naming
it, never used, and case records are read strictly (a missing field is an
error, not a default).

Every writer (:func:`write_dataset`, :func:`write_arrays`,
:func:`write_records`, :func:`write_table`, :func:`write_figure`) goes
through one atomic write: a temporary file in the destination folder, then
:func:`os.replace`, with SIGINT and SIGTERM held meanwhile; an existing
destination that is not a regular file (a link, a pipe, a device) is
refused. The numerics never import this module; it imports them
only for their types and constants, and only when a conversion needs them.

Examples
--------
>>> import numpy as np
>>> from contactlib.result import Solution
>>> from contactlib.io import to_dataset
>>> xi = np.linspace(0.0, 1.0, 5)
>>> sol = Solution("sphere", 0.3, "default", 4, 0.0, 0.5, 0.2, xi,
...                np.sqrt(1 - xi**2), 0.1 * xi, 0.5 * xi, 1.0)
>>> ds = to_dataset(sol)
>>> ds["pressure"].dims, float(ds["stick_ratio"])
(('xi',), 0.5)
"""

from __future__ import annotations

import dataclasses
import errno
import hashlib
import math
import os
import signal
import socket
import stat
import tempfile
import threading
import time
import zipfile
import zlib
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:  # xarray is imported where a dataset is made or read (start-up time)
    import xarray as xr

from contactlib.checks import FLAG_NAMES, VIOLATION_NAMES
from contactlib.indenter import indenter
from contactlib.result import CaseRecord, Solution

if TYPE_CHECKING:  # types only: the conversions import the numerics when they run
    from contactlib.convergence import Study
    from contactlib.history_api import HistoryResult
    from contactlib.layer_study import LayerStudy

__all__ = ["to_dataset", "scene_to_dataset", "set_provenance", "history_to_dataset",
           "stack_histories", "study_to_dataset", "study_from_dataset", "layer_study_to_dataset",
           "write_dataset",
           "read_dataset", "write_arrays", "read_arrays", "write_records", "read_records",
           "write_table", "write_figure", "check_writable", "check_yaml", "version",
           "cf_attrs", "DamagedFileError", "CONVENTIONS"]

# ----------------------------------------------------------------------------- conventions
CONVENTIONS = "CF-1.10"
COMPRESSION: dict[str, Any] = {"zlib": True, "complevel": 4, "shuffle": True}

_BOOL_FLAGS: dict[str, Any] = {
    "flag_values": np.array([0, 1], dtype=np.int8),
    "flag_meanings": "false true",
}

# name -> (long_name, comment); every variable here is dimensionless (units "1").
_PROFILE_ATTRS: dict[str, tuple[str, str]] = {
    "pressure": (
        "contact pressure over Hertz peak pressure",
        "p / p0, p0 = Hertz peak pressure at the same contact radius; "
        "positive in compression",
    ),
    "shear": (
        "shear traction over Hertz peak pressure",
        "q / p0, traction on the elastic body, positive away from the axis",
    ),
    "tangential_displacement": (
        "scaled tangential surface displacement",
        "u R / a**2, surface displacement, positive away from the axis",
    ),
}

def _work_comment(ind: Any) -> str:
    """The scaling of ``frictional_work`` for an indenter (rings or strips)."""
    per_length = (", V per unit length over the whole contact (both sides of the axis)"
                  if ind.plane_strain else "")
    return (f"V R**2 / (E* a**{ind.work_exponent}){per_length}; loading 0 -> a; "
            f"NaN when not computed")

_POINT_FLOAT_ATTRS: dict[str, tuple[str, str]] = {
    "friction_coefficient": (
        "coefficient of friction",
        "k; inf at full adhesion (stick_ratio = 1), 0 when frictionless",
    ),
    "load_ratio": (
        "normal load over Hertz load",
        "P / P_Hertz(a) at the same contact radius",
    ),
    "frictional_work": ("scaled frictional work of the loading half-cycle", ""),
    "residual_norm": ("norm of the final solver residual", "solver status"),
    "error_estimate": (
        "estimated relative error of friction_coefficient",
        "from the same case on the nested meshes n/4 and n/2 (Richardson with the observed "
        "order in [1, 2]; the larger difference where they do not converge cleanly); 0 "
        "where k is exact",
    ),
    "load_error_estimate": ("estimated relative error of load_ratio", "as error_estimate"),
    "work_error_estimate": (
        "estimated relative error of frictional_work",
        "as error_estimate; NaN when the work is not computed",
    ),
}

_POINT_BOOL_ATTRS: dict[str, tuple[str, str]] = {
    "slip_direction_ok": (
        "slip opposes shear at every slip point",
        "consistency flag",
    ),
    "stick_admissible": (
        "abs(q) <= k p at every stick point",
        "consistency flag",
    ),
    "consistent": (
        "slip direction and stick admissibility both hold",
        "consistency flag",
    ),
    "converged": ("solver converged", "solver status; failed cases are kept"),
    "resolved": (
        "converged with error_estimate at most max_error",
        "a case that is not resolved is not a good number (see message)",
    ),
}

_SHARED_FIELDS = ("geometry", "nu", "method", "slab_ratio", "base",
                  "indenter_modulus_ratio", "indenter_poisson_ratio", "profile", "exponent",
                  "substrate_modulus", "substrate_poisson_ratio")


def _layer_attrs(ind: Any, result: Any) -> dict[str, Any]:
    """The layer's global attributes: ``slab_ratio`` (a/h, or a_max/h in a history) and ``base``.

    ``slab_ratio`` where the indenter reports it (always for the cylinder, on
    a layer for the sphere: a sphere on the half-space keeps its attributes);
    ``base`` = "bonded" on a layer bonded to its base. Without ``base`` a
    layer is on a smooth base: the default, and the paper's slab, whose
    files keep the attributes they had before bases existed. A coated body
    (``base`` = "elastic") adds ``substrate_modulus`` (E2/E1) and
    ``substrate_poisson_ratio``.
    """
    slab = float(result.slab_ratio)
    base = str(getattr(result, "base", "smooth"))
    attrs: dict[str, Any] = {}
    if ind.reports_layer(slab):
        attrs["slab_ratio"] = slab
    if slab > 0 and base != "smooth":
        attrs["base"] = base
    if slab > 0 and base == "elastic":
        attrs["substrate_modulus"] = float(result.substrate_modulus)
        attrs["substrate_poisson_ratio"] = float(result.substrate_poisson_ratio)
    return attrs


def version() -> str:
    """The contactlib version written into every dataset (``contactlib_version``).

    Returns
    -------
    str
        ``contactlib.__version__``, the single source of the version (also
        read by ``pyproject.toml`` and ``contactlib --version``).

    Examples
    --------
    >>> import contactlib
    >>> version() == contactlib.__version__
    True
    """
    from contactlib import __version__

    return str(__version__)


def _same(a: Any, b: Any) -> bool:
    if isinstance(a, float) and isinstance(b, float):
        return a == b or (math.isnan(a) and math.isnan(b))
    return bool(a == b)


def _check(sols: list[Solution]) -> np.ndarray:
    """Validate that ``sols`` can share one dataset; return the common xi."""
    first = sols[0]
    xi = np.asarray(first.xi, dtype=float)
    if xi.ndim != 1:
        raise ValueError(f"xi must be one-dimensional, got shape {xi.shape}")
    for i, sol in enumerate(sols):
        if not isinstance(sol, Solution):
            raise TypeError(f"solutions[{i}] is not a Solution: {type(sol).__name__}")
        for name in _SHARED_FIELDS:
            if not _same(getattr(sol, name), getattr(first, name)):
                raise ValueError(
                    f"solutions[{i}].{name} = {getattr(sol, name)!r} differs from "
                    f"solutions[0].{name} = {getattr(first, name)!r}"
                )
        if not np.array_equal(np.asarray(sol.xi, dtype=float), xi):
            raise ValueError(f"solutions[{i}].xi differs from solutions[0].xi")
        for name in _PROFILE_ATTRS:
            value = getattr(sol, name)
            if (value is None) != (getattr(first, name) is None):
                raise ValueError(f"solutions[{i}].{name} is computed for some solutions only")
            shape = xi.shape if value is None else np.shape(value)
            if shape != xi.shape:
                raise ValueError(
                    f"solutions[{i}].{name} has shape {shape}, expected {xi.shape}"
                )
    return xi


def cf_attrs(long_name: str, units: str = "1", comment: str = "",
             **extra: Any) -> dict[str, Any]:
    """CF attributes of one variable: ``units``, ``long_name``, then ``comment`` and extras.

    Parameters
    ----------
    long_name : str
        CF ``long_name``.
    units : str
        CF ``units``; ``"1"`` (dimensionless, the default) for every scaled
        quantity of docs/conventions.md.
    comment : str
        Scaling, sign or provenance; left out when empty.
    **extra
        Further attributes (e.g. ``flag_values``, ``bounds``).

    Returns
    -------
    dict
        In this order, so that files are byte-reproducible.

    Examples
    --------
    >>> cf_attrs("wall time of one solve", "s")
    {'units': 's', 'long_name': 'wall time of one solve'}
    """
    attrs: dict[str, Any] = {"units": units, "long_name": long_name}
    if comment:
        attrs["comment"] = comment
    attrs.update(extra)
    return attrs


# ----------------------------------------------------------------------------- solutions
def to_dataset(solutions: Solution | Sequence[Solution]) -> xr.Dataset:
    """Convert one solution or a sweep of solutions to a dataset.

    Parameters
    ----------
    solutions : Solution or sequence of Solution
        A single solution gives a dataset with a scalar ``stick_ratio``
        coordinate and profiles on ``(xi,)``. A sequence (a sweep) gives a
        ``stick_ratio`` dimension, in the given order, and profiles on
        ``(stick_ratio, xi)``. All members must share geometry, nu, method,
        slab_ratio and xi. Where their n differ (a sweep to a tolerance, each
        stick ratio at the n that met it) an ``elements`` variable (stick_ratio)
        holds each one's n and the ``elements`` attribute the largest.

    Returns
    -------
    xarray.Dataset
        Variables and scalings of docs/conventions.md, each with CF
        ``units`` (``"1"``: everything is dimensionless) and ``long_name``.
        Flags are booleans (stored as int8 with ``flag_values`` and
        ``flag_meanings``). A ``message`` variable is added when any solution
        carries a non-empty message.

    Raises
    ------
    ValueError
        If the sequence is empty or its members are inconsistent.
    TypeError
        If a member is not a :class:`Solution`.

    Examples
    --------
    >>> import numpy as np
    >>> from contactlib.result import Solution
    >>> xi = np.linspace(0.0, 1.0, 3)
    >>> sols = [Solution("cylinder", 0.3, "default", 2, 0.0, g, g, xi,
    ...                  1 - xi**2, 0 * xi, 0 * xi, 1.0) for g in (0.2, 0.4)]
    >>> to_dataset(sols)["shear"].dims
    ('stick_ratio', 'xi')
    """
    single = isinstance(solutions, Solution)
    sols = [solutions] if single else list(solutions)  # type: ignore[list-item]
    if not sols:
        raise ValueError("solutions must contain at least one Solution")
    xi = _check(sols)
    first = sols[0]
    geometry = str(first.geometry)
    ind = indenter(geometry)
    axis = f"{ind.coordinate}/a"
    dims = ("stick_ratio",)

    coords = {
        "xi": (
            "xi",
            xi,
            cf_attrs(
                f"position over contact radius ({axis})",
                comment="0 on the axis, 1 at the contact edge",
            ),
        ),
        "stick_ratio": (
            dims,
            np.array([float(s.stick_ratio) for s in sols]),
            cf_attrs(
                "stick zone radius over contact radius (c/a)",
                comment="0 frictionless, 1 full adhesion",
            ),
        ),
    }
    data: dict[str, Any] = {}
    for name, (long_name, comment) in _PROFILE_ATTRS.items():
        if getattr(first, name) is None:
            continue  # not computed (a workflow scene that did not ask for it)
        values = np.stack([np.asarray(getattr(s, name), dtype=float) for s in sols])
        data[name] = (dims + ("xi",), values, cf_attrs(long_name, comment=comment))
    for name, (long_name, comment) in _POINT_FLOAT_ATTRS.items():
        if name == "frictional_work":
            comment = _work_comment(ind)
        values = np.array([float(getattr(s, name)) for s in sols])
        data[name] = (dims, values, cf_attrs(long_name, comment=comment))
    data["iterations"] = (
        dims,
        np.array([int(s.iterations) for s in sols], dtype=np.int32),
        cf_attrs("solver iterations", comment="solver status"),
    )
    for name, (long_name, comment) in _POINT_BOOL_ATTRS.items():
        values = np.array([bool(getattr(s, name)) for s in sols], dtype=bool)
        data[name] = (dims, values, cf_attrs(long_name, comment=comment, **_BOOL_FLAGS))
    ns = np.array([int(s.n) for s in sols], dtype=np.int32)
    if np.any(ns != ns[0]):
        data["elements"] = (dims, ns, cf_attrs(
            "elements used for this stick ratio",
            comment="a sweep to a tolerance: each stick ratio at the n planned for it, "
            "doubled where its estimate missed the tolerance"))
    messages = [str(s.message or "") for s in sols]
    if any(messages):
        data["message"] = (
            dims,
            np.array(messages, dtype=object),
            {"long_name": "solver message", "comment": "empty when none"},
        )

    attrs: dict[str, Any] = {
        "title": f"contactlib partial-slip solution ({geometry})",
        "geometry": geometry,
        "poisson_ratio": float(first.nu),
        "elements": int(ns.max()),
        "method": str(first.method),
    }
    max_errors = {float(s.max_error) for s in sols if math.isfinite(s.max_error)}
    if max_errors:
        attrs["max_error"] = max(max_errors)
    attrs.update(_layer_attrs(ind, first))
    if getattr(first, "profile", "paraboloid") != "paraboloid":  # Hertz's files stay as they were
        attrs["profile"] = str(first.profile)  # h = A r^d (contactlib.profiles)
        attrs["profile_exponent"] = float(first.exponent)
    for name in ("indenter_modulus_ratio", "indenter_poisson_ratio", "dundurs_beta"):
        attrs[name] = float(getattr(first, name, float("nan")))  # E1/E2 = inf: rigid
    attrs["contactlib_version"] = version()
    attrs["Conventions"] = CONVENTIONS

    import xarray as xr

    ds = xr.Dataset(data_vars=data, coords=coords, attrs=attrs)
    if single:
        ds = ds.isel(stick_ratio=0)
    return ds


_VIOLATION_COMMENT = "relative measure behind the flag; <= 1e-4 passes"


def scene_to_dataset(solutions: Sequence[Solution], *, outputs: Sequence[str],
                     scene: str, config_hash: str,
                     violations: Mapping[str, np.ndarray] | None = None,
                     elements: np.ndarray | None = None,
                     error_estimate: np.ndarray | None = None,
                     tolerance: float | None = None) -> xr.Dataset:
    """The dataset of a workflow scene: :func:`to_dataset` cut to the outputs it asked for.

    Parameters
    ----------
    solutions : sequence of Solution
        One a stick ratio (a sweep).
    outputs : sequence of str
        The scene's outputs: without ``k_curve`` the consistency flags are
        dropped, without ``energy`` the frictional work.
    scene, config_hash : str
        Provenance (:func:`set_provenance`).
    violations : mapping of str to ndarray, optional
        ``stick_violation`` and ``slip_violation``, one value a case (added
        with ``k_curve``).
    elements, error_estimate : ndarray, optional
        A scene with an accuracy target: the elements each case used and the
        estimated relative error of k (both needed with ``tolerance``).
    tolerance : float, optional
        The scene's accuracy target; adds the ``tolerance``, ``elements``
        (the most used) and ``tolerance_met`` attributes.

    Returns
    -------
    xarray.Dataset
    """
    want = set(outputs)
    ds = to_dataset(list(solutions))
    drop = []
    if "k_curve" not in want:
        drop += list(FLAG_NAMES)
    if "energy" not in want:
        drop += ["frictional_work", "work_error_estimate"]
    ds = ds.drop_vars([name for name in drop if name in ds])
    if "k_curve" in want:
        if violations is None:
            raise ValueError("a scene with k_curve needs the violations")
        for name in VIOLATION_NAMES:
            ds[name] = ("stick_ratio", np.asarray(violations[name], dtype=float),
                        cf_attrs(name.replace("_", " "), comment=_VIOLATION_COMMENT))
    if tolerance is not None:
        if elements is None or error_estimate is None:
            raise ValueError("a scene with a tolerance needs elements and error_estimate")
        used = np.asarray(elements, dtype=np.int32)
        ds["elements"] = ("stick_ratio", used, cf_attrs(
            "elements used for this stick ratio",
            comment="planned from the measured convergence, doubled where the "
            "a-posteriori estimate missed the tolerance"))
        estimate = np.asarray(error_estimate, dtype=float)
        ds["error_estimate"] = ("stick_ratio", estimate, cf_attrs(
            "estimated relative error of friction_coefficient",
            comment="from the same case at n/2 and n/4 (observed order, clipped to [1, 2])"))
        ds.attrs["tolerance"] = float(tolerance)
        ds.attrs["elements"] = int(used.max())
        ds.attrs["tolerance_met"] = int(bool(np.all(ds["error_estimate"].values
                                                    <= tolerance)))
    return set_provenance(ds, scene, config_hash, outputs=outputs)


_PROVENANCE = "scene_config_hash"  # the workflow's own datasets: read_dataset needs their check


def set_provenance(ds: xr.Dataset, scene: str, config_hash: str,
                   outputs: Sequence[str] | None = None) -> xr.Dataset:
    """Add the workflow's provenance attributes to ``ds`` (in place) and return it.

    Parameters
    ----------
    ds : xarray.Dataset
    scene : str
        The scene's name (attribute ``scene``).
    config_hash : str
        Hash of the scene's settings (attribute ``scene_config_hash``).
    outputs : sequence of str, optional
        The outputs the scene asked for (attribute ``outputs``, space separated).

    Returns
    -------
    xarray.Dataset
        ``ds``.
    """
    ds.attrs["scene"] = scene
    ds.attrs[_PROVENANCE] = config_hash
    if outputs is not None:
        ds.attrs["outputs"] = " ".join(outputs)
    return ds


# ----------------------------------------------------------------------------- histories
def history_to_dataset(result: HistoryResult) -> xr.Dataset:
    """CF-annotated :class:`xarray.Dataset` of a history (dimensions ``step``, ``xi``).

    Every variable has ``units`` (``"1"``: all dimensionless) and
    ``long_name``; the element state is int8 with ``flag_values`` and
    ``flag_meanings``; ``xi`` has CF ``bounds``. Global attributes: geometry,
    poisson_ratio, elements, friction_coefficient, load_path, steps,
    slab_ratio (cylinder), mesh_extent, contactlib_version, Conventions.
    Write it with :func:`write_dataset`.

    Parameters
    ----------
    result : HistoryResult
        From :func:`contactlib.history`.

    Returns
    -------
    xarray.Dataset

    Examples
    --------
    >>> from contactlib import history
    >>> ds = history_to_dataset(history("sphere", 0.3, 0.2, [0, 1], 4, n=40))
    >>> ds["pressure"].dims, ds.attrs["steps"]
    (('step', 'xi'), 4)
    """
    import xarray as xr

    from contactlib import history_solver as hs

    r = result
    ind = indenter(r.geometry)
    axis = ind.coordinate
    work_scale = f"V R**2 / (E* a_max**{ind.work_exponent})" + (
        ", V per unit length over both sides of the axis" if ind.plane_strain else "")
    shape = r.profile_shape()
    if not shape.is_paraboloid:  # h = A r^d, or a flat punch
        work_scale = shape.work_unit(not ind.plane_strain).replace("^", "**") + (
            ", over both sides of the axis" if ind.plane_strain else "")
    sd, ed = ("step",), ("step", "xi")
    coords = {
        "step": ("step", np.arange(r.load_ratio.size, dtype=np.int32),
                 cf_attrs("load step", comment="0: unloaded initial state")),
        "xi": ("xi", r.xi, cf_attrs(f"element midpoint over a_max ({axis}/a_max)",
                                    comment="collocation points; a_max = frictionless "
                                            "contact radius at load level 1",
                                    bounds="xi_bounds")),
    }
    bool_flags = _BOOL_FLAGS
    data = {
        "xi_bounds": (("xi", "nv"), r.xi_bounds, cf_attrs("element edges over a_max")),
        "segment": (sd, r.segment.astype(np.int32),
                    cf_attrs("load path segment", comment="1-based; 0 for the initial state")),
        "load_ratio": (sd, r.load_ratio, cf_attrs("normal load over maximum load (P/P_max)")),
        "contact_radius": (sd, r.contact_radius, cf_attrs(
            "contact radius over a_max (a/a_max)",
            comment="sub-element estimate from the gap outside the contact")),
        "stick_ratio": (sd, r.stick_ratio, cf_attrs(
            "central stick zone radius over contact radius (c/a)",
            comment="run of stuck elements from the axis, edge refined from the traction "
                    "deficit; NaN without contact")),
        "indentation": (sd, r.indentation, cf_attrs(
            "indentation (delta R / a_max**2)",
            comment="half-plane: relative to the Flamant reference length a_max")),
        "frictional_work": (sd, r.frictional_work, cf_attrs(
            "cumulative frictional work",
            comment=work_scale + "; trapezoid rule in time, a fall taken from the steps "
                                 "before it (never decreasing)")),
        "state": (ed, r.state.astype(np.int8), cf_attrs(
            "element contact state", flag_values=np.array([0, 1, 2, 3], dtype=np.int8),
            flag_meanings=hs.STATE_MEANINGS,
            comment="slip_inward: the body slips toward the axis (shear = +k p)")),
        "pressure": (ed, r.pressure, cf_attrs(
            "contact pressure over Hertz peak pressure at a_max",
            comment="p / p0(a_max); positive in compression")),
        "shear": (ed, r.shear, cf_attrs(
            "shear traction over Hertz peak pressure at a_max",
            comment="q / p0(a_max), traction on the elastic body, positive away from the axis")),
        "tangential_displacement": (ed, r.tangential_displacement, cf_attrs(
            "tangential surface displacement (u R / a_max**2)",
            comment="positive away from the axis")),
        "converged": (sd, r.converged.astype(bool), cf_attrs(
            "step converged", comment="solver status; failed steps are kept", **bool_flags)),
        "iterations": (sd, r.iterations.astype(np.int32), cf_attrs("active-set iterations")),
        "residual_norm": (sd, r.residual_norm, cf_attrs(
            "largest scaled violation of the contact and friction conditions")),
    }
    if r.resolved is not None:
        coarse = ("from the same path on about half the elements with half the steps a "
                  "segment (and a quarter of both, which measures the order of "
                  "convergence), interpolated by path coordinate; NaN: not estimated")
        data["stick_radius_error_estimate"] = (sd, r.stick_radius_error_estimate, cf_attrs(
            "estimated absolute error of the central stick zone radius over a_max (dc/a_max)",
            comment=coarse + "; at least half an element where the stick edge is an element "
                             "edge; 0 without contact; the error of stick_ratio is this over "
                             "contact_radius"))
        data["work_error_estimate"] = (sd, r.work_error_estimate, cf_attrs(
            "estimated error of the cumulative frictional work relative to the path's "
            "total frictional work (variable work_scale)",
            comment=coarse + "; the scale is at least 1e-4 of the indenter's largest work "
                             "(variable energy_scale); at the end, the relative error of "
                             "the path's work; 0 while no work is done"))
        if r.energy_error_estimate is not None:
            data["energy_error_estimate"] = (sd, r.energy_error_estimate, cf_attrs(
                "estimated error of the external work, stored energy and viscous work "
                "relative to the indenter's largest work (variable energy_scale)",
                comment=coarse + "; the largest of the three; inf where a value is not "
                                 "finite"))
        for name, what in (("work_scale", "the path's total frictional work, at least 1e-4 "
                                          "of energy_scale"),
                           ("energy_scale", "the path's largest external work")):
            data[name] = ((), float(getattr(r, name, np.nan)), cf_attrs(
                f"scale of the history's {name.split('_')[0]} error estimates",
                comment=what + "; units of frictional_work"))
        data["resolved"] = (sd, r.resolved.astype(bool), cf_attrs(
            "step resolved to max_error",
            comment=f"converged, every value finite, slip zone absent or over at least "
                    f"{hs.MIN_SLIP_ELEMENTS} elements, and every error estimate within the "
                    f"max_error attribute", **bool_flags))
    attrs: dict[str, Any] = {
        "title": f"contactlib loading history ({r.geometry})",
        "geometry": r.geometry,
        "poisson_ratio": float(r.nu),
        "elements": int(r.n),
        "friction_coefficient": float(r.friction),
        "load_path": np.asarray(r.load_path, dtype=float),
        "steps": int(r.steps),
    }
    if getattr(r, "segment_steps", ()):  # a shape or table (contactlib.load_paths)
        attrs["segment_steps"] = np.asarray(r.segment_steps, dtype=np.int32)
        attrs["steps_meaning"] = ("steps a unit of load travel (P_max); segment_steps: the "
                                  "steps of each segment, a monotone piece of the path, "
                                  "whose ends load_path gives")
        for key, value in (r.load_shape or {}).items():
            attrs[f"load_path_{key}"] = value
        attrs["load_path_interpolation_error"] = float(r.interpolation_error)
    attrs.update(_layer_attrs(ind, r))
    if not shape.is_paraboloid:  # as the self-similar datasets
        attrs.update(shape.attributes())
    for name in ("indenter_modulus_ratio", "indenter_poisson_ratio", "dundurs_beta"):
        attrs[name] = float(getattr(r, name, float("nan")))
    attrs["mesh_extent"] = float(r.mesh_extent)  # 1.2, or the creep extent (viscoelastic)
    if getattr(r, "relaxation", ()):  # a viscoelastic body: time, energies, relaxation
        _add_viscoelastic(r, data, attrs, sd, work_scale)
    if r.resolved is not None:
        attrs["max_error"] = float(r.max_error)
        if getattr(r, "resolved_quantities", None):
            attrs["resolved_quantities"] = " ".join(
                name for name, ok in r.resolved_quantities.items() if ok)
    attrs["length_scale"] = "a_max: frictionless (Hertz) contact radius at load level 1"
    attrs.update(shape.scale_attributes(not ind.plane_strain))  # the flat punch: no R
    if r.message:
        attrs["message"] = r.message
    attrs["contactlib_version"] = version()
    attrs["Conventions"] = CONVENTIONS
    return xr.Dataset(data_vars=data, coords=coords, attrs=attrs)


def _add_viscoelastic(r: HistoryResult, data: dict[str, Any], attrs: dict[str, Any],
                      sd: tuple[str, ...], work_scale: str) -> None:
    """The variables and attributes of a viscoelastic history (elastic ones have none)."""
    data["time"] = (sd, r.time, cf_attrs(
        "time at the end of the step", units="1",
        comment="in the unit of the relaxation times (relaxation_times); 0: initial state"))
    energy = ("; external = stored + viscous + frictional (contactlib.energy); " + work_scale)
    data["external_work"] = (sd, r.external_work, cf_attrs(
        "cumulative work of the indenter (int P d delta)",
        comment="pressure averaged over each step on the body's surface" + energy))
    data["stored_energy"] = (sd, r.stored_energy, cf_attrs(
        "free energy stored in the body",
        comment="g_inf/2 <e, K e> + sum g_i/2 <h_i, K h_i> at E*(0)" + energy))
    data["viscous_work"] = (sd, r.viscous_work, cf_attrs(
        "cumulative dissipation of the viscous body",
        comment="sum (g_i/tau_i) int <h_i, K h_i> dt, exact for e linear in each step"
                + energy))
    attrs["relaxation_weights"] = np.array([g for g, _ in r.relaxation], dtype=float)
    attrs["relaxation_times"] = np.array([t for _, t in r.relaxation], dtype=float)
    attrs["relaxed_modulus_ratio"] = float(1.0 - sum(g for g, _ in r.relaxation))
    attrs["segment_durations"] = np.asarray(r.durations, dtype=float)
    attrs["relaxation"] = ("Prony series E(t)/E(0) = 1 - sum g_i (1 - exp(-t/tau_i)), "
                           "g_i = relaxation_weights, tau_i = relaxation_times, constant "
                           "Poisson's ratio; a_max, P_max and p0 use E*(0)")


def stack_histories(datasets: Sequence[xr.Dataset]) -> xr.Dataset:
    """Histories that differ only in k, stacked along a ``friction_coefficient`` dimension.

    Parameters
    ----------
    datasets : sequence of xarray.Dataset
        From :func:`history_to_dataset`, same geometry, nu, load path, steps,
        n and slab ratio, distinct friction coefficients.

    Returns
    -------
    xarray.Dataset
        Every variable gains a leading ``friction_coefficient`` dimension
        (coordinate: k, increasing); the ``friction_coefficient`` attribute
        is dropped, ``message`` joins the members' notes and
        ``resolved_quantities`` their verdicts ("k = 0.1: ...; k = 0.2: ...").

    Raises
    ------
    ValueError
        When the histories differ in anything but k, or repeat a k.
    """
    import xarray as xr

    items = list(datasets)
    if not items:
        raise ValueError("stack_histories needs at least one history dataset")
    same = ("geometry", "poisson_ratio", "elements", "steps", "slab_ratio", "base",
            "substrate_modulus", "substrate_poisson_ratio", "relaxation_weights", "relaxation_times", "segment_durations")
    first = items[0].attrs
    for ds in items[1:]:
        for key in same:
            if key in first and not np.array_equal(np.atleast_1d(ds.attrs.get(key)),
                                                   np.atleast_1d(first[key])):
                raise ValueError(f"histories to stack must share {key}: "
                                 f"{first[key]!r} vs {ds.attrs.get(key)!r}")
        if not np.array_equal(np.asarray(ds.attrs["load_path"]), np.asarray(first["load_path"])):
            raise ValueError("histories to stack must share the load path")
    ks = np.array([float(ds.attrs["friction_coefficient"]) for ds in items])
    if np.unique(ks).size != ks.size:
        raise ValueError(f"histories to stack repeat a friction coefficient: {ks.tolist()}")
    order = np.argsort(ks)
    members = []
    for i in order:
        ds = items[i].copy()
        ds.attrs = {k: v for k, v in ds.attrs.items()
                    if k not in ("friction_coefficient", "message", "resolved_quantities")}
        members.append(ds)
    shared = ("xi_bounds", "segment", "load_ratio", "time")  # the path and the mesh: no k
    varying = [v for v in members[0].data_vars if v not in shared]
    out = xr.concat(members, dim="friction_coefficient", data_vars=varying, coords="minimal",
                    compat="equals", combine_attrs="override")
    out = out.assign_coords(friction_coefficient=ks[order])
    out["friction_coefficient"].attrs = cf_attrs("Coulomb friction coefficient k")
    notes = [f"k = {ks[i]:g}: {items[i].attrs['message']}" for i in order
             if items[i].attrs.get("message")]
    if notes:
        out.attrs["message"] = "; ".join(notes)
    resolved = [f"k = {ks[i]:g}: {items[i].attrs['resolved_quantities'] or 'none'}"
                for i in order if "resolved_quantities" in items[i].attrs]
    if resolved:
        out.attrs["resolved_quantities"] = "; ".join(resolved)
    return out


# ----------------------------------------------------------------------------- studies
_STUDY_QUANTITIES_COMMENT = ("friction_coefficient k; load_ratio P/P_Hertz; frictional_work "
                             "as in docs/conventions.md; peak_shear max q/p0")


def study_to_dataset(study: Study, name: str | None = None) -> xr.Dataset:
    """CF-annotated dataset of a convergence study (:func:`contactlib.convergence.study`).

    Parameters
    ----------
    study : contactlib.convergence.Study
    name : str, optional
        The study's name in the workflow config (global attribute ``study``).

    Returns
    -------
    xarray.Dataset
        ``value``, ``error`` (relative to the reference; NaN where it cannot
        be estimated), ``wall_time`` (s) and ``peak_memory`` (MiB) on
        (quantity, n, stick_ratio) or (n, stick_ratio); ``reference`` and
        ``observed_order`` on (quantity, stick_ratio). Global attributes:
        geometry, poisson_ratio, method, slab_ratio, reference (its source),
        contactlib_version, Conventions, and ``study`` when ``name`` is given.
    """
    import xarray as xr

    st = study
    ds = xr.Dataset(
        {
            "value": (("quantity", "n", "stick_ratio"), st.values,
                      cf_attrs("computed value", comment=_STUDY_QUANTITIES_COMMENT)),
            "reference": (("quantity", "stick_ratio"), st.reference,
                          cf_attrs("reference value (see the global attribute reference)")),
            "observed_order": (("quantity", "stick_ratio"), st.observed_order,
                               cf_attrs("observed order of convergence",
                                        comment="log2 of the ratio of successive differences; "
                                                "NaN when they do not shrink")),
            "error": (("quantity", "n", "stick_ratio"), st.error,
                      cf_attrs("relative error against the extrapolated value")),
            "wall_time": (("n", "stick_ratio"), st.wall_time,
                          cf_attrs("wall time of one solve", "s")),
            "peak_memory": (("n", "stick_ratio"), st.peak_memory,
                            cf_attrs("peak traced memory of one solve", "MiB",
                                     "numpy and Python allocations (tracemalloc)")),
        },
        coords={"quantity": ("quantity", list(st.quantities), {"long_name": "quantity"}),
                "n": ("n", np.asarray(st.ns), cf_attrs("elements across the half-contact")),
                "stick_ratio": ("stick_ratio", np.asarray(st.stick_ratios), cf_attrs("c/a"))},
        attrs={"geometry": st.geometry, "poisson_ratio": float(st.nu), "method": st.method,
               "slab_ratio": float(st.slab_ratio), "Conventions": CONVENTIONS,
               "reference": st.reference_source, "contactlib_version": version()},
    )
    if st.slab_ratio > 0 and st.base != "smooth":  # as every layer dataset (_layer_attrs)
        ds.attrs["base"] = st.base
    if name is not None:
        ds.attrs["study"] = name
    return ds


def study_from_dataset(ds: xr.Dataset) -> Study:
    """The :class:`~contactlib.convergence.Study` of a dataset of :func:`study_to_dataset`.

    The workflow reads a study back this way to serve as the reference of
    another (the paper's scheme is measured against the default method's
    extrapolated values).

    Parameters
    ----------
    ds : xarray.Dataset

    Returns
    -------
    contactlib.convergence.Study
    """
    from contactlib.convergence import Study

    return Study(
        geometry=str(ds.attrs["geometry"]), nu=float(ds.attrs["poisson_ratio"]),
        method=str(ds.attrs["method"]), slab_ratio=float(ds.attrs["slab_ratio"]),
        ns=tuple(int(n) for n in ds["n"].values),
        stick_ratios=tuple(float(c) for c in ds["stick_ratio"].values),
        quantities=tuple(str(q) for q in ds["quantity"].values),
        values=ds["value"].values, reference=ds["reference"].values,
        observed_order=ds["observed_order"].values, error=ds["error"].values,
        wall_time=ds["wall_time"].values, peak_memory=ds["peak_memory"].values,
        reference_source=str(ds.attrs["reference"]), base=str(ds.attrs.get("base", "smooth")))


def layer_study_to_dataset(st: LayerStudy) -> xr.Dataset:
    """A :class:`~contactlib.layer_study.LayerStudy` as a dataset.

    Dimensions ``geometry``, ``base``, ``poisson_ratio``, ``slab_ratio``
    (a/h) and ``stick_ratio``; variables ``load_ratio`` (frictionless
    P/P_Hertz) and ``load_error_estimate`` on the first four,
    ``friction_coefficient``, ``error_estimate`` and ``resolved`` on all five.
    With the study's load cycles, also ``cycle_work``,
    ``cycle_work_error_estimate`` and ``cycle_work_resolved`` on the first
    four (``slab_ratio`` is a_max/h for them) and the attributes
    ``history_friction``, ``history_elements`` and ``history_steps``.
    Global attributes ``elements``, ``method`` (default), ``Conventions`` and
    ``contactlib_version``.
    """
    import xarray as xr

    dims4 = ("geometry", "base", "poisson_ratio", "slab_ratio")
    dims5 = dims4 + ("stick_ratio",)
    cycles = {}
    if st.history_friction is not None and st.cycle_work is not None:
        cycles = {
            "cycle_work": (dims4, st.cycle_work, cf_attrs(
                "frictional work of the load cycle 0 -> 1 -> 0",
                comment="V R^2/(E* a_max^5) (sphere), per unit length V R^2/(E* a_max^4) "
                        "(cylinder); incremental history, a/h = a_max/h")),
            "cycle_work_error_estimate": (dims4, st.cycle_work_error_estimate, cf_attrs(
                "estimated relative error of cycle_work")),
            "cycle_work_resolved": (dims4, np.asarray(st.cycle_resolved, dtype=bool), cf_attrs(
                "every step converged and cycle_work_error_estimate within 1e-2",
                **_BOOL_FLAGS)),
        }
    ds = xr.Dataset(
        data_vars={
            "load_ratio": (dims4, st.load_ratio, cf_attrs(
                "frictionless load over the Hertz load at the same contact radius")),
            "load_error_estimate": (dims4, st.load_error_estimate,
                                    cf_attrs("estimated relative error of load_ratio")),
            "friction_coefficient": (dims5, st.friction, cf_attrs(
                "friction coefficient k", comment="self-similar loading, a/h held fixed")),
            "error_estimate": (dims5, st.error_estimate,
                               cf_attrs("estimated relative error of k")),
            "resolved": (dims5, st.resolved.astype(bool), cf_attrs(
                "converged, consistent and error_estimate at most 1e-3",
                comment="thin bonded layers whose slip reverses are not", **_BOOL_FLAGS)),
            **cycles,
        },
        coords={"geometry": ("geometry", list(st.geometries), {"long_name": "indenter"}),
                "base": ("base", list(st.bases), {"long_name": "rigid base under the layer"}),
                "poisson_ratio": ("poisson_ratio", np.asarray(st.nus, dtype=float),
                                  cf_attrs("Poisson's ratio of the body")),
                "slab_ratio": ("slab_ratio", np.asarray(st.ratios, dtype=float),
                               cf_attrs("a/h", comment="0: half-space or half-plane")),
                "stick_ratio": ("stick_ratio", np.asarray(st.stick_ratios, dtype=float),
                                cf_attrs("c/a"))},
        attrs={"title": "contactlib: layers, k and frictionless load against a/h",
               "elements": int(st.n), "method": "default", "Conventions": CONVENTIONS,
               "contactlib_version": version()})
    if cycles:
        ds.attrs.update(history_friction=float(st.history_friction),
                        history_elements=int(st.history_n), history_steps=int(st.history_steps))
    return ds


# ----------------------------------------------------------------------------- files
def _encoding(ds: xr.Dataset) -> dict[str, dict[str, Any]]:
    """Per-variable netCDF encoding: no fill on coordinates, zlib on data."""
    encoding: dict[str, dict[str, Any]] = {}
    for name in ds.coords:
        encoding[str(name)] = {"_FillValue": None}
    for name, var in ds.data_vars.items():
        if var.dtype.kind in "biuf" and var.ndim > 0:
            encoding[str(name)] = dict(COMPRESSION)
    return encoding


_FILE_KINDS = ((stat.S_ISLNK, "a symbolic link"), (stat.S_ISFIFO, "a named pipe (FIFO)"),
               (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
               (stat.S_ISSOCK, "a socket"))


def _refuse_special(path: Path) -> None:
    """Refuse to replace an existing ``path`` that is not a regular file (or a folder).

    The atomic write replaces whatever is at ``path``: a symbolic link, a
    named pipe or a device (``/dev/null``) would be replaced by a file, so
    only a regular file (or nothing) may be there.
    """
    try:
        mode = os.lstat(path).st_mode
    except (FileNotFoundError, NotADirectoryError):
        return
    except OSError:  # e.g. a name too long: the temporary file reports it
        return
    if stat.S_ISDIR(mode):
        raise IsADirectoryError(f"{path} is a folder, not a file")
    for test, kind in _FILE_KINDS:
        if test(mode):
            raise FileExistsError(f"{path} is {kind}, not a regular file: refusing to "
                                  f"replace it (give the path of a regular file)")


# temporary files: ".<name>.<host>-<pid>-<random>.tmp", so that a writer can tell a stale
# one (left by a killed process of this machine) from one that is being written
_HOST_TAG = hashlib.sha256(socket.gethostname().encode("utf-8", "replace")).hexdigest()[:6]
# convention: an hour-old temporary file of an earlier version counts as stale
_LEGACY_TMP_AGE = 3600.0  # s: ".<name>.<random>.tmp" of earlier versions, no owner recorded


def _pid_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:  # e.g. another user's process
        return True
    return True


def _remove_stale_temporaries(path: Path) -> None:
    """Remove temporary files of ``path`` left by killed writers (SIGKILL, power cut).

    Only those of this machine whose process is gone, and those of earlier
    versions (no owner recorded) older than an hour; never another running
    writer's.
    """
    prefix, own = f".{path.name}.", f"{_HOST_TAG}-{os.getpid()}-"
    try:
        names = [n for n in os.listdir(path.parent) if n.startswith(prefix)
                 and n.endswith(".tmp")]
    except OSError:
        return
    for name in names:
        middle = name[len(prefix):-len(".tmp")]
        parts = middle.split("-")
        stale = False
        if len(parts) == 3 and parts[0] == _HOST_TAG and parts[1].isdigit():
            stale = not middle.startswith(own) and not _pid_alive(int(parts[1]))
        elif len(parts) == 1 and len(middle) == 8:  # tempfile's random part alone
            try:
                stale = time.time() - os.lstat(path.parent / name).st_mtime > _LEGACY_TMP_AGE
            except OSError:
                continue
        if stale:
            try:
                (path.parent / name).unlink()
            except OSError:
                pass


def _atomic_target(path: str | os.PathLike[str]) -> tuple[Path, Path]:
    """Destination and a fresh temporary file beside it (parents created).

    Raises
    ------
    IsADirectoryError
        If ``path`` is a folder.
    FileExistsError
        If ``path`` exists and is not a regular file (a symbolic link, a
        named pipe, a device such as ``/dev/null``, a socket).
    """
    path = Path(path)
    if path.is_dir():
        raise IsADirectoryError(f"output path is a directory: {path}")
    _refuse_special(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp_name = tempfile.mkstemp(prefix=f".{path.name}.{_HOST_TAG}-{os.getpid()}-",
                                    suffix=".tmp", dir=path.parent)
    os.close(fd)
    umask = os.umask(0)  # mkstemp makes the file 0600: give it the usual permissions
    os.umask(umask)
    os.chmod(tmp_name, 0o666 & ~umask)
    return path, Path(tmp_name)


_DEFERRED = (signal.SIGINT, signal.SIGTERM)


class _DeferSignals:
    """Hold SIGINT and SIGTERM while a file is written and renamed (main thread only).

    An interrupt inside netCDF4/HDF5 can leave a lock held (Ctrl-C hung the
    write) and SIGTERM's default action ends the process before the
    temporary file is removed. Inside the ``with`` block a signal is only
    noted; :meth:`deliver` hands it on to the handler that was in place,
    after a cleanup. Leaving the block delivers what is still noted.
    """

    def __init__(self) -> None:
        self.received: list[int] = []
        self.previous: dict[int, Any] = {}

    def __enter__(self) -> _DeferSignals:
        if threading.current_thread() is not threading.main_thread():
            return self  # Python runs signal handlers in the main thread only
        for sig in _DEFERRED:
            handler = signal.getsignal(sig)
            if handler is None or handler is signal.SIG_IGN:
                continue  # not installed from Python, or ignored: left alone
            try:
                signal.signal(sig, self._note)
            except (ValueError, OSError):
                continue
            self.previous[sig] = handler
        return self

    def _note(self, signum: int, frame: Any) -> None:
        self.received.append(signum)

    def deliver(self, cleanup: Callable[[], None] = lambda: None) -> None:
        """If a signal came: restore the handlers, clean up, hand the signal on.

        ``cleanup`` runs before a signal whose action ends the process
        (``SIG_DFL``), and when a Python handler raises (KeyboardInterrupt);
        a handler that returns lets the caller go on.
        """
        if not self.received:
            return
        previous, received = self.previous, list(dict.fromkeys(self.received))
        self._restore()
        self.received = []
        for sig in received:
            if previous.get(sig) is signal.SIG_DFL:
                cleanup()
                signal.raise_signal(sig)  # ends the process
            else:
                try:
                    signal.raise_signal(sig)  # runs the handler: KeyboardInterrupt, ...
                except BaseException:
                    cleanup()
                    raise

    def _restore(self) -> None:
        for sig, handler in self.previous.items():
            signal.signal(sig, handler)
        self.previous = {}

    def __exit__(self, *exc: Any) -> None:
        self.deliver()
        self._restore()


def _disk_full(folder: Path) -> bool:
    """Whether the file system of ``folder`` has (next to) no space left."""
    try:
        st = os.statvfs(folder)
    except OSError:
        return False
    blocks = st.f_bfree if hasattr(os, "geteuid") and os.geteuid() == 0 else st.f_bavail
    return blocks * st.f_frsize < 1 << 20


def _write_error(path: Path, tmp: Path, exc: BaseException) -> BaseException | None:
    """One line naming ``path`` and the cause for an error of a write; None: keep ``exc``."""
    code = getattr(exc, "errno", None)
    if code in (errno.ENOSPC, errno.EDQUOT) or (
            isinstance(exc, (OSError, RuntimeError)) and _disk_full(tmp.parent)):
        reason = ("disk quota exceeded" if code == errno.EDQUOT
                  else "no space left on device")
        err = OSError(f"cannot write {path}: {reason} (nothing was written; free some "
                      f"space and run again)")
        err.errno = errno.EDQUOT if code == errno.EDQUOT else errno.ENOSPC
        return err
    if type(exc) is RuntimeError:  # netCDF4's errors name no file
        return RuntimeError(f"cannot write {path}: {exc}")
    return None


def _atomic_write(path: str | os.PathLike[str], write: Callable[[Path], None]) -> Path:
    """The one atomic write of contactlib: ``write(tmp)``, then ``os.replace(tmp, path)``.

    ``write`` fills a fresh temporary file beside ``path`` (same folder, so
    the replace is atomic; parent folders are created). On any failure the
    temporary file is removed and ``path`` is left as it was. SIGINT and
    SIGTERM are held while the file is written (in the main thread): one
    that comes then removes the temporary file, leaves ``path`` as it was
    and is handed on (KeyboardInterrupt, or the end of the process by
    SIGTERM). After a successful write the temporary files of ``path`` left
    by killed processes are removed. A full disk is an :class:`OSError`
    naming ``path`` and saying "no space left on device".
    """
    with _DeferSignals() as held:
        path, tmp = _atomic_target(path)

        def discard() -> None:
            tmp.unlink(missing_ok=True)

        try:
            write(tmp)
            held.deliver(discard)  # an interrupt during the write: no file
            os.replace(tmp, path)
        except BaseException as exc:
            replacement = _write_error(path, tmp, exc) if isinstance(exc, Exception) else None
            discard()
            held.deliver()
            if replacement is not None:
                raise replacement from exc
            raise
        _remove_stale_temporaries(path)
    return path


def check_writable(path: str | os.PathLike[str]) -> Path:
    """Check, before any work, that a writer of this module can write ``path``.

    Does what :func:`write_dataset` and the other writers do first (create
    missing parent folders, create the temporary file beside the
    destination), then removes the temporary file and every folder it
    created, so nothing is left behind. This catches an unwritable folder, a
    path through a file, a name too long (the temporary name is longer than
    the destination's) and an existing path that is not a regular file (a
    symbolic link, a named pipe, a device such as ``/dev/null``: the write
    would replace it) before a long computation rather than after it.

    Parameters
    ----------
    path : str or os.PathLike
        The destination file.

    Returns
    -------
    pathlib.Path
        ``path``; missing parent folders will be created by the writer.

    Raises
    ------
    OSError
        One line naming ``path`` and the reason (never the temporary name).
    """
    if os.fspath(path).strip() == "" or Path(path).name in ("", ".", ".."):
        raise OSError(f"{os.fspath(path)!r} is not a file name")
    path = Path(path)
    if path.is_dir():
        raise IsADirectoryError(f"{path} is a folder, not a file")
    _refuse_special(path)
    ancestors = [a for a in path.parents]
    for folder in ancestors:  # the nearest existing ancestor must be a folder
        if folder.exists() or folder.is_symlink():
            if not folder.is_dir():
                raise NotADirectoryError(f"cannot write {path}: {folder} is a file, not a folder")
            break
    created = [a for a in ancestors if not (a.exists() or a.is_symlink())]
    tmp: Path | None = None
    try:
        _, tmp = _atomic_target(path)
    except OSError as exc:
        reason = exc.strerror or type(exc).__name__
        if exc.errno == errno.ENAMETOOLONG:
            reason = "file name too long"
        raise type(exc)(f"cannot write {path}: {reason.lower()}") from None
    finally:
        if tmp is not None:
            tmp.unlink(missing_ok=True)
        for folder in created:  # deepest first
            try:
                folder.rmdir()
            except OSError:
                pass
    return path


# the content check of an npz file (write_arrays): SHA-256 over every other array's name,
# dtype, shape and bytes, stored as one more array
_NPZ_CHECKSUM = "contactlib_sha256"


def _arrays_digest(arrays: Mapping[str, np.ndarray]) -> str:
    h = hashlib.sha256()
    for name in sorted(arrays):
        if name == _NPZ_CHECKSUM:
            continue
        value = np.ascontiguousarray(arrays[name])
        for part in (name, value.dtype.str, repr(value.shape)):
            text = part.encode("utf-8")
            h.update(len(text).to_bytes(8, "little") + text)
        h.update(value.nbytes.to_bytes(8, "little"))
        h.update(memoryview(value).cast("B") if value.nbytes else b"")
    return h.hexdigest()


def write_arrays(arrays: dict[str, np.ndarray], path: str | os.PathLike[str]) -> Path:
    """Write named arrays (an intermediate of the workflow) to ``.npz``, atomically.

    Used for influence matrices and case records between workflow stages.
    Arrays are stored uncompressed (influence matrices do not compress) and
    without pickling: only numeric, boolean and string arrays are allowed.
    A content check goes with them: one more array, ``contactlib_sha256``,
    the SHA-256 of every array's name, dtype, shape and bytes, which
    :func:`read_arrays` verifies.

    Parameters
    ----------
    arrays : dict of str to array_like
    path : str or os.PathLike
        Destination; must end in ``.npz``.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    ValueError
        If the suffix is not ``.npz`` or an array is named ``contactlib_sha256``.
    TypeError
        If an array would need pickling.
    """
    if Path(path).suffix != ".npz":
        raise ValueError(f"path must end in .npz, got {str(path)!r}")
    data = {k: np.asarray(v) for k, v in arrays.items()}
    if _NPZ_CHECKSUM in data:
        raise ValueError(f"{_NPZ_CHECKSUM!r} is reserved for the content check")
    for k, v in data.items():
        if v.dtype.kind not in "biufUS":
            raise TypeError(f"array {k!r} has dtype {v.dtype}, which needs pickling")
    data[_NPZ_CHECKSUM] = np.array(_arrays_digest(data))

    def write(tmp: Path) -> None:
        with open(tmp, "wb") as fh:
            np.savez(fh, **data)

    return _atomic_write(path, write)


class DamagedFileError(OSError):
    """A file exists but cannot be read back whole (truncated, corrupt or changed).

    The message is one line naming the file and the fix (delete it and
    rebuild it).
    """


# errors of a file that is there but unreadable; a missing or forbidden file
# (FileNotFoundError, PermissionError, IsADirectoryError) keeps its own error
_MISSING = (FileNotFoundError, PermissionError, IsADirectoryError)

_REBUILD = ("delete it and make it again (in the workflow: delete it and run snakemake "
            "--rerun-incomplete, which rebuilds it)")


def _damaged(path: str | os.PathLike[str], kind: str,
             exc: BaseException | str) -> DamagedFileError:
    detail = exc if isinstance(exc, str) else f"{type(exc).__name__}: {exc}"
    detail = " ".join(detail.split())
    if len(detail) > 160:
        detail = detail[:157] + "..."
    return DamagedFileError(
        f"{os.fspath(path)} is damaged or incomplete (not a readable {kind} file: {detail}); "
        f"{_REBUILD}")


def read_arrays(path: str | os.PathLike[str], *,
                require_checksum: bool = True) -> dict[str, np.ndarray]:
    """Read arrays written by :func:`write_arrays` (no pickles are loaded).

    Every array is read whole and the content check is verified, so a
    truncated, corrupt or changed file (a broken zip directory, a CRC
    mismatch, a short array, an array removed or rewritten) is detected
    here and never used.

    Parameters
    ----------
    path : str or os.PathLike
    require_checksum : bool
        True (default): a file without the content check is refused (every
        file :func:`write_arrays` writes has one). False: a file without one
        (``numpy.savez``, an earlier version) is read unchecked; a check
        that is there is verified all the same.

    Returns
    -------
    dict of str to numpy.ndarray
        Without the content check.

    Raises
    ------
    DamagedFileError
        If the file exists but cannot be read back whole or its content
        does not match its check; the message names the file and the fix.
    FileNotFoundError
        If there is no such file.
    """
    try:
        with np.load(path, allow_pickle=False) as data:
            arrays = {k: data[k] for k in data.files}
    except _MISSING:
        raise
    except Exception as exc:  # noqa: BLE001 - whatever a damaged zip raises
        raise _damaged(path, "npz", exc) from exc
    stored = arrays.pop(_NPZ_CHECKSUM, None)
    if stored is None:
        if require_checksum:
            raise _damaged(path, "npz", "it has no content checksum (written by an earlier "
                                        "version, or changed)")
        return arrays
    if stored.shape != () or stored.dtype.kind != "U" or str(stored) != _arrays_digest(arrays):
        raise _damaged(path, "npz", "its content does not match its checksum (changed after "
                                    "it was written)")
    return arrays


# fields of case records written by earlier versions and no longer kept (ignored on reading)
_RETIRED_RECORD_FIELDS = ("tolerance_message",)  # (merged into the message)
_RECORD_FIELDS = tuple(f.name for f in dataclasses.fields(CaseRecord))
_NONE_FIELDS = "none"  # "<i>/<field>" of every field that is None


def write_records(records: Sequence[CaseRecord], path: str | os.PathLike[str]) -> Path:
    """Write the case records of a scene (:func:`contactlib.stages.solve_cases`) to ``.npz``.

    The workflow's transport between its stages: every field of each
    :class:`~contactlib.result.CaseRecord` that is not None becomes an array
    named ``"<i>/<field>"`` (i the case's position), next to ``count``, the
    number of records, and ``none``, the names ``"<i>/<field>"`` of the
    fields that are None; written with :func:`write_arrays` (atomically,
    with its content check, no pickles). So every field of every record is
    accounted for, and :func:`read_records` needs no default.

    Parameters
    ----------
    records : sequence of CaseRecord
    path : str or os.PathLike
        Destination; must end in ``.npz``.

    Returns
    -------
    pathlib.Path
    """
    arrays: dict[str, np.ndarray] = {"count": np.array(len(records))}
    none: list[str] = []
    for i, rec in enumerate(records):
        for name in _RECORD_FIELDS:
            value = getattr(rec, name)
            if value is None:
                none.append(f"{i}/{name}")
            else:
                arrays[f"{i}/{name}"] = np.asarray(value)
    arrays[_NONE_FIELDS] = np.array(none, dtype=str)
    return write_arrays(arrays, path)


def _record_key(name: str, count: int) -> tuple[int, str]:
    """``"<i>/<field>"`` -> (i, field), i a record of the file."""
    i, _, key = name.partition("/")
    if not (i.isdigit() and int(i) < count and key):
        raise ValueError(f"unexpected array {name!r} (not '<case>/<field>' of {count} cases)")
    return int(i), key


def _record_fields(arrays: dict[str, np.ndarray], upgrade: bool) -> list[dict[str, Any]]:
    """The fields of each record; strict (every field accounted for) unless ``upgrade``."""
    count = arrays.get("count")
    if count is None or count.shape != () or count.dtype.kind not in "iu" or int(count) < 0:
        raise ValueError("no record count")
    fields: list[dict[str, Any]] = [{} for _ in range(int(count))]
    none = arrays.get(_NONE_FIELDS)
    if not upgrade:
        if none is None or none.ndim != 1 or (none.size and none.dtype.kind != "U"):
            raise ValueError("no list of the fields that are None")
        for name in none.tolist():
            i, key = _record_key(name, len(fields))
            fields[i][key] = None
    for name, value in arrays.items():
        if name in ("count", _NONE_FIELDS):
            continue
        i, key = _record_key(name, len(fields))
        if key in _RETIRED_RECORD_FIELDS and upgrade:
            continue
        if key not in _RECORD_FIELDS:
            raise ValueError(f"unknown field {name!r}")
        if key in fields[i]:
            raise ValueError(f"field {name!r} is both given and None")
        fields[i][key] = value.item() if value.ndim == 0 else value
    if not upgrade:
        for i, f in enumerate(fields):
            missing = [key for key in _RECORD_FIELDS if key not in f]
            if missing:
                raise ValueError(f"case {i} has no field {missing[0]!r}"
                                 + (f" (and {len(missing) - 1} more)" if len(missing) > 1
                                    else ""))
    return fields


def read_records(path: str | os.PathLike[str], *, upgrade: bool = False) -> list[CaseRecord]:
    """Read case records written by :func:`write_records`.

    Strict: the content check must be there and match, and every field of
    every record must be in the file (as an array, or named among the
    fields that are None); a missing field is an error naming the file and
    the field, never a default. 0-d arrays come back as Python scalars, so
    a record read back equals the one written field by field.

    Parameters
    ----------
    path : str or os.PathLike
    upgrade : bool
        The explicit reading of files of earlier versions (no content check,
        no list of None fields, fields added since then missing): fields
        not in the file take their defaults (None, or NaN for the
        estimates) and a retired field (``tolerance_message``) is skipped.
        Write the records again with :func:`write_records` to upgrade the
        file.

    Returns
    -------
    list of CaseRecord

    Raises
    ------
    DamagedFileError
        If the file exists but cannot be read back whole, does not match its
        content check, or does not hold complete case records; the message
        names the file and, for a missing field, the field.
    FileNotFoundError
        If there is no such file.

    Examples
    --------
    >>> import tempfile, os
    >>> from contactlib import stages
    >>> from contactlib.model import contact
    >>> recs = stages.solve_cases(contact("sphere", 0.3), "default", 16, [0.0])
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = write_records(recs, os.path.join(folder, "r.npz"))
    ...     back = read_records(path)
    >>> back[0].stick_ratio, back[0].k, back[0].p.shape
    (0.0, 0.0, (17,))
    """
    arrays = read_arrays(path, require_checksum=not upgrade)
    try:
        records = [CaseRecord(**f) for f in _record_fields(arrays, upgrade)]
    except (KeyError, ValueError, IndexError, TypeError) as exc:
        detail = str(exc) if isinstance(exc, ValueError) else f"{type(exc).__name__}: {exc}"
        raise _damaged(path, "case-record npz", detail) from exc
    return records


def write_table(rows: Sequence[dict[str, Any]], path: str | os.PathLike[str],
                digits: int = 6, title: str = "") -> Path:
    """Write rows of a table (dicts with the same keys) as CSV or HTML, atomically.

    The format follows the suffix: ``.csv``, or ``.html`` (a standalone page
    with one table, for the workflow report). Floats get ``digits``
    significant digits (NaN as an empty cell), so the file is reproducible.
    """
    import csv
    import html
    import io as _io

    suffix = Path(path).suffix
    if suffix not in (".csv", ".html"):
        raise ValueError(f"table path must end in .csv or .html, got {str(path)!r}")
    if not rows:
        raise ValueError("rows must not be empty")
    columns = list(rows[0])

    def cell(v: Any) -> str:
        if isinstance(v, float):
            return "" if math.isnan(v) else f"{v:.{digits}g}"
        return str(v)

    buf = _io.StringIO()
    if suffix == ".csv":
        writer = csv.writer(buf, lineterminator="\n")
        writer.writerow(columns)
        for row in rows:
            writer.writerow([cell(row[c]) for c in columns])
    else:
        esc = html.escape
        buf.write("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\">"
                  f"<title>{esc(title)}</title><style>"
                  "body{font-family:sans-serif;font-size:13px}"
                  "table{border-collapse:collapse}td,th{border:1px solid #bbb;"
                  "padding:3px 6px;text-align:right}th{background:#eee}"
                  "td:first-child{text-align:left}</style></head><body>\n")
        if title:
            buf.write(f"<h3>{esc(title)}</h3>\n")
        buf.write("<table>\n<tr>" + "".join(f"<th>{esc(c)}</th>" for c in columns)
                  + "</tr>\n")
        for row in rows:
            buf.write("<tr>" + "".join(f"<td>{esc(cell(row[c]))}</td>" for c in columns)
                      + "</tr>\n")
        buf.write("</table>\n</body></html>\n")
    return _atomic_write(path, lambda tmp: tmp.write_text(buf.getvalue(), encoding="utf-8"))


# the content check of a netCDF file (write_dataset): a global attribute, the SHA-256 of the
# dataset as it reads back (every variable's name, dimensions, dtype, values and attributes,
# and the other global attributes)
_NC_CHECKSUM = "contactlib_sha256"


def _attr_text(value: Any) -> str:
    if isinstance(value, str):
        return "s" + value
    arr = np.asarray(value)
    return f"{arr.dtype.str}{arr.shape}{arr.tolist()!r}"


def _dataset_digest(ds: xr.Dataset) -> str:
    """SHA-256 of a dataset's content (not of its file's bytes), without ``_NC_CHECKSUM``."""
    h = hashlib.sha256()

    def put(data: str | bytes | memoryview) -> None:
        raw = data.encode("utf-8", "surrogatepass") if isinstance(data, str) else data
        h.update(len(raw).to_bytes(8, "little"))
        h.update(raw)

    def put_attrs(attrs: Mapping[Any, Any]) -> None:
        for key in sorted(map(str, attrs)):
            if key != _NC_CHECKSUM:
                put(key)
                put(_attr_text(attrs[key]))

    put_attrs(ds.attrs)
    put("coords:" + ",".join(sorted(map(str, ds.coords))))
    for name in sorted(map(str, ds.variables)):
        var = ds.variables[name]
        put(name)
        put(",".join(map(str, var.dims)))
        put_attrs(var.attrs)
        values = np.asarray(var.values)
        if values.dtype.kind in "OUS":  # text: str items, whatever the array's dtype
            put(f"text{values.shape}")
            for item in values.ravel().tolist():
                put(item if isinstance(item, bytes) else f"{type(item).__name__}:{item!r}")
        else:
            put(f"{values.dtype.str}{values.shape}")
            values = np.ascontiguousarray(values)
            put(memoryview(values).cast("B") if values.nbytes else b"")
    return h.hexdigest()


def _open_dataset(path: str | os.PathLike[str]) -> xr.Dataset:
    import xarray as xr

    with xr.open_dataset(path, engine="netcdf4") as ds:
        return ds.load()


def write_dataset(ds: xr.Dataset, path: str | os.PathLike[str]) -> Path:
    """Write ``ds`` to a netCDF-4 file, atomically and reproducibly, with a content check.

    The data go to a temporary file in the destination folder, which then
    replaces ``path`` with :func:`os.replace`; on any failure the temporary
    file is removed and ``path`` is left as it was. Parent folders are
    created. Data variables are zlib-compressed, coordinates get no
    ``_FillValue``. Identical datasets give byte-identical files. The
    global attribute ``contactlib_sha256`` holds the SHA-256 of the content
    as it reads back (every variable's values and attributes, the other
    global attributes); the file is read back and checked before it
    replaces ``path``, and :func:`read_dataset` verifies it.

    Parameters
    ----------
    ds : xarray.Dataset
        Typically the result of :func:`to_dataset`.
    path : str or os.PathLike
        Destination file.

    Returns
    -------
    pathlib.Path
        The destination path.

    Raises
    ------
    OSError
        If ``path`` is a folder or another existing thing that is not a
        regular file, or the disk is full ("no space left on device",
        naming ``path``).

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from contactlib import solve
    >>> from contactlib.io import read_dataset, to_dataset, write_dataset
    >>> ds = to_dataset(solve("sphere", 0.3, stick_ratio=0.5, n=64))
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     path = write_dataset(ds, pathlib.Path(tmp) / "case.nc")
    ...     back = read_dataset(path)
    ...     again = write_dataset(back, pathlib.Path(tmp) / "again.nc")
    ...     same_bytes = path.read_bytes() == again.read_bytes()
    >>> bool(back["friction_coefficient"].equals(ds["friction_coefficient"])), same_bytes
    (True, True)
    """
    encoding = _encoding(ds)
    if _NC_CHECKSUM in ds.attrs:  # e.g. a dataset opened with xarray itself
        ds = ds.copy(deep=False)
        del ds.attrs[_NC_CHECKSUM]

    def to_netcdf(data: xr.Dataset, tmp: Path) -> None:
        data.to_netcdf(tmp, mode="w", format="NETCDF4", engine="netcdf4", encoding=encoding)

    def write(tmp: Path) -> None:
        # the content as it reads back (attributes and types as netCDF keeps them) ...
        digest = _dataset_digest(ds)
        for _ in range(2):
            to_netcdf(ds.assign_attrs({_NC_CHECKSUM: digest}), tmp)
            back = _dataset_digest(_open_dataset(tmp))
            if back == digest:
                return
            digest = back  # ... differs from the dataset in memory: take the file's
        raise RuntimeError("the file does not read back as written; nothing was written")

    return _atomic_write(path, write)


def read_dataset(path: str | os.PathLike[str], *,
                 require_checksum: bool | None = None) -> xr.Dataset:
    """Read a dataset written by :func:`write_dataset` into memory, verifying its content.

    The file is closed before returning, so it may be replaced afterwards.
    Its content check (global attribute ``contactlib_sha256``, written by
    :func:`write_dataset`) is verified and left out of the returned
    dataset. A file without one is refused if it is the workflow's own (it
    has the provenance attribute ``scene_config_hash`` of
    :func:`set_provenance`), and read as it is otherwise (a dataset a user
    wrote with other tools).

    Parameters
    ----------
    path : str or os.PathLike
        A netCDF file.
    require_checksum : bool, optional
        True: refuse any file without a content check; False: read one
        without a check whatever it holds (an explicit upgrade of a file of
        an earlier version). None (default): required for the workflow's
        own files, as above. A check that is there is always verified.

    Returns
    -------
    xarray.Dataset
        Fully loaded; flags decode back to booleans.

    Raises
    ------
    DamagedFileError
        If the file exists but is not a readable netCDF file (e.g.
        truncated), or its content does not match its check (changed after
        it was written); the message names the file and the fix.
    FileNotFoundError
        If there is no such file.
    """
    try:
        ds = _open_dataset(path)
        stored = ds.attrs.pop(_NC_CHECKSUM, None)
        actual = None if stored is None else _dataset_digest(ds)
    except _MISSING:
        raise
    except Exception as exc:  # noqa: BLE001 - whatever netCDF4/HDF5/xarray raise
        raise _damaged(path, "netCDF", exc) from exc
    if require_checksum is None:
        require_checksum = _PROVENANCE in ds.attrs
    if stored is None and require_checksum:
        raise _damaged(path, "netCDF", "it has no content checksum (written by an earlier "
                                       "version, or changed)")
    if stored is not None and (not isinstance(stored, str) or stored != actual):
        raise _damaged(path, "netCDF", "its content does not match its checksum (changed "
                                       "after it was written)")
    return ds


def _unique_key_loader() -> type:
    """A safe YAML loader that refuses a key given twice in one mapping (any level)."""
    import yaml

    class UniqueKeyLoader(yaml.SafeLoader):
        def construct_mapping(self, node: Any, deep: bool = False) -> Any:
            if isinstance(node, yaml.MappingNode):
                seen: dict[Any, Any] = {}
                for key_node, _ in node.value:
                    if key_node.tag == "tag:yaml.org,2002:merge":
                        continue  # "<<: *base": keys given here override the merged ones
                    key = self.construct_object(key_node, deep=True)
                    try:
                        first = seen.get(key)
                    except TypeError:  # an unhashable key: SafeLoader reports it
                        continue
                    if first is not None:
                        raise yaml.constructor.ConstructorError(
                            None, None, f"duplicate key {key!r} (first at line "
                            f"{first.line + 1})", key_node.start_mark)
                    seen[key] = key_node.start_mark
            return super().construct_mapping(node, deep=deep)

    return UniqueKeyLoader


def check_yaml(path: str | os.PathLike[str]) -> Any:
    """Parse a YAML file, turning a syntax error into one line naming the file and line.

    A key given twice in one mapping (a scene name, or a key inside a
    scene) is an error too: YAML would keep the last one silently.

    Parameters
    ----------
    path : str or os.PathLike
        A YAML (or JSON) file, e.g. the workflow's ``config/config.yaml``.

    Returns
    -------
    object
        The parsed document (``None`` when the file is missing: the caller
        reports that in its own words).

    Raises
    ------
    ValueError
        ``<path>, line L, column C: <problem>`` for a syntax error or a
        duplicate key (lines and columns count from 1; ``duplicate key 'x'
        (first at line L)``), or ``<path>: <problem>`` when the path is a
        folder, not a regular file, unreadable or not UTF-8 text.
    """
    import yaml

    name = os.fspath(path)
    try:
        mode = os.stat(path).st_mode
        if stat.S_ISDIR(mode):
            raise ValueError(f"{name}: is a folder, not a YAML file")
        if not stat.S_ISREG(mode):  # a pipe or a device: reading could block or never end
            raise ValueError(f"{name}: is not a regular file")
        text = Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        return None
    except UnicodeDecodeError as exc:
        raise ValueError(f"{name}: not UTF-8 text (byte {exc.start + 1})") from None
    except OSError as exc:
        reason = (exc.strerror or type(exc).__name__).lower()
        raise ValueError(f"{name}: cannot be read: {reason}") from None
    try:
        return yaml.load(text, Loader=_unique_key_loader())  # noqa: S506 - a SafeLoader
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        where = f", line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        problem = " ".join(str(exc.problem or exc.context or "invalid YAML").split())
        kind = "" if problem.startswith("duplicate key") else "YAML syntax error: "
        raise ValueError(f"{name}{where}: {kind}{problem}") from None
    except yaml.YAMLError as exc:
        raise ValueError(f"{name}: YAML syntax error: "
                         f"{' '.join(str(exc).split())}") from None


_TABLE_COLUMNS = ("load", "force")


def read_load_table(path: str | os.PathLike[str], *, physical: bool = False
                    ) -> dict[str, list[float]]:
    """A load path sampled in time, from a CSV file (:mod:`contactlib.load_paths`).

    The file has a header row naming two columns, ``time`` first, then
    ``load`` (levels P/P_max, time in the unit of tau) or ``force`` (with
    ``physical``: N, time in s). A physical column may name its unit in
    brackets, ``time [ms]``, ``force [kN]`` (:data:`contactlib.physical.UNITS`).
    Lines starting with ``#`` and blank lines are skipped.

    Parameters
    ----------
    path : str or os.PathLike
        The CSV file.
    physical : bool
        Whether the path is in SI (a ``force`` column) or levels (``load``).

    Returns
    -------
    dict
        ``{"time": [...], "load" or "force": [...]}`` in the file's order, in
        the unit of tau and levels, or in s and N. The values are checked
        further by :func:`contactlib.load_paths.load_path` (or
        :func:`contactlib.physical.physical_history`).

    Raises
    ------
    ValueError
        One line naming the file (and line): missing, a folder, unreadable,
        not UTF-8, no header, other columns, a unit unknown for the column,
        a row without exactly two cells, a cell that is not a finite number,
        or fewer than two rows.
    """
    import csv

    from contactlib.physical import UNITS

    name = os.fspath(path)
    try:
        if stat.S_ISDIR(os.stat(path).st_mode):
            raise ValueError(f"{name}: is a folder, not a CSV file")
        text = Path(path).read_text(encoding="utf-8-sig")
    except FileNotFoundError:
        raise ValueError(f"{name}: no such file") from None
    except UnicodeDecodeError as exc:
        raise ValueError(f"{name}: not UTF-8 text (byte {exc.start + 1})") from None
    except OSError as exc:
        reason = (exc.strerror or type(exc).__name__).lower()
        raise ValueError(f"{name}: cannot be read: {reason}") from None
    rows = [(i, row) for i, row in enumerate(csv.reader(text.splitlines()), start=1)
            if row and any(c.strip() for c in row) and not row[0].lstrip().startswith("#")]
    want = "force" if physical else "load"
    header = f"a header 'time,{want}'" + (" (units in brackets allowed: 'time [s],force "
                                          "[N]')" if physical else "")
    if not rows:
        raise ValueError(f"{name}: empty: expected {header} and rows of numbers")
    line, head = rows[0]
    factors = []
    for cell, column, kind in zip(head, ("time", want), ("time", "force")):
        label, _, unit = cell.strip().partition("[")
        label, unit = label.strip().lower(), unit.rstrip("] ").strip()
        if label != column or (unit and not physical):
            raise ValueError(f"{name}, line {line}: expected {header}, got "
                             f"{','.join(c.strip() for c in head)!r}")
        if unit and unit not in UNITS[kind]:
            raise ValueError(f"{name}, line {line}: unknown unit {unit!r} of {column} "
                             f"(one of {', '.join(u for u in UNITS[kind] if u.isascii())})")
        factors.append(UNITS[kind][unit] if unit else 1.0)
    if len(head) != 2:
        raise ValueError(f"{name}, line {line}: expected {header}, got {len(head)} columns")
    cols: tuple[list[float], list[float]] = ([], [])
    for line, row in rows[1:]:
        if len(row) != 2:
            raise ValueError(f"{name}, line {line}: expected two cells (time,{want}), got "
                             f"{len(row)}: {','.join(row)!r}")
        for cell, col, factor in zip(row, cols, factors):
            try:
                value = float(cell)
            except ValueError:
                raise ValueError(f"{name}, line {line}: {cell.strip()!r} is not a number"
                                 ) from None
            if not math.isfinite(value):
                raise ValueError(f"{name}, line {line}: {cell.strip()!r} is not finite")
            col.append(value * factor)
    if len(cols[0]) < 2:
        raise ValueError(f"{name}: needs at least two rows of numbers (a start and an end), "
                         f"got {len(cols[0])}")
    return {"time": cols[0], want: cols[1]}


_FIGURE_METADATA: dict[str, dict[str, None]] = {
    # keys the backends would otherwise fill with version strings or the time
    "png": {"Software": None},
    "pdf": {"Creator": None, "Producer": None, "CreationDate": None, "ModDate": None},
}


def write_figure(fig: Any, path: str | os.PathLike[str], *,
                 style: str | os.PathLike[str] | Mapping[str, Any] | None = None) -> Path:
    """Save a matplotlib figure as PNG or PDF, atomically and reproducibly.

    The format follows the suffix (``.png`` or ``.pdf``, any case). The
    figure is rendered into a temporary file in the destination folder,
    which then replaces ``path`` with :func:`os.replace`; on any failure the
    temporary file is removed and ``path`` is left as it was. Parent folders
    are created. The metadata that would carry a matplotlib version or the
    time is dropped (PNG ``Software``; PDF ``Creator``, ``Producer``,
    ``CreationDate``, ``ModDate``), so the same figure gives byte-identical
    files on every save, in every process (checked with different
    ``PYTHONHASHSEED`` values in ``tests/test_figures.py``). This needs a
    layout that does not move between draws: the figures of
    :mod:`contactlib.plot` settle and freeze theirs, while a figure with a
    live constrained layout may shift by a fraction of a pixel per save.
    ``fig`` is typed ``Any`` so that this module does not import matplotlib
    until a figure is written.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        Typically from :mod:`contactlib.plot`.
    path : str or os.PathLike
        Destination file, ending in ``.png`` or ``.pdf``.
    style : str, os.PathLike or mapping, optional
        A matplotlib style (a ``.mplstyle`` path, a style name or a dict of
        rcParams) active while the figure is saved; it sets the resolution
        and the PDF font type. The figures of :mod:`contactlib.plot` are
        saved with theirs, :func:`contactlib.plot.style_path` (150 dpi,
        TrueType fonts in PDF), as the workflow does. ``None`` (default):
        the current rcParams.

    Returns
    -------
    pathlib.Path
        The destination path.

    Raises
    ------
    ValueError
        If the suffix is neither ``.png`` nor ``.pdf``.
    IsADirectoryError
        If ``path`` is an existing directory.
    """
    import contextlib

    import matplotlib.style

    path = Path(path)
    fmt = path.suffix.lower().lstrip(".")
    if fmt not in _FIGURE_METADATA:
        raise ValueError(f"figure path must end in .png or .pdf, got {path.name!r}")

    def write(tmp: Path) -> None:
        saving = (contextlib.nullcontext() if style is None
                  else matplotlib.style.context(style))  # type: ignore[arg-type]
        with open(tmp, "wb") as handle, saving:
            fig.savefig(handle, format=fmt, metadata=dict(_FIGURE_METADATA[fmt]))

    return _atomic_write(path, write)


# ----------------------------------------------------------------------------- physical units
__all__ += ["physical_to_dataset"]


def _scale_attrs(res: Any, a: float, a_label: str) -> dict[str, Any]:
    """The reference scales of a physical result as global attributes (SI, unit in the name)."""
    from contactlib.physical import SMALL_STRAIN_LIMIT

    attrs: dict[str, Any] = {
        "physical_units": "SI: the *_si variables carry CF units (m, Pa, N, J, s); the "
                          "dimensionless variables convert back with the scales below "
                          "(docs/conventions.md, docs/physical.md)",
        "composite_modulus_Pa": float(res.composite_modulus),
        "indenter_radius_m": float(res.radius),
        "contact_radius_scale_m": float(a),
        "contact_radius_scale": a_label,
        "hertz_peak_pressure_Pa": float(res.p0),
        "hertz_load_N": float(res.hertz_load),
        "indenter_material": str(res.indenter.name),
        "body_material": str(res.body.name),
        "body_youngs_modulus_Pa": float(res.body.E),
        "body_poisson_ratio": float(res.body.nu),
        "small_strain_limit": float(SMALL_STRAIN_LIMIT),
    }
    if not res.indenter.rigid:
        attrs["indenter_youngs_modulus_Pa"] = float(res.indenter.E)
    if res.geometry == "cylinder":
        attrs["cylinder_length_m"] = float(res.length)
    if math.isfinite(res.thickness):
        attrs["layer_thickness_m"] = float(res.thickness)
    if getattr(res, "substrate", None) is not None:  # a coated body's substrate
        attrs["substrate_material"] = str(res.substrate.name)
        attrs["substrate_youngs_modulus_Pa"] = float(res.substrate.E)
    if res.notes:
        attrs["validity_warning"] = "; ".join(res.notes)
    return attrs


def physical_to_dataset(result: Any) -> xr.Dataset:
    """The dataset of a physical result: the dimensionless one plus SI variables.

    Parameters
    ----------
    result : contactlib.physical.PhysicalSolution or PhysicalHistory
        From :func:`contactlib.physical.physical_solve` or
        :func:`~contactlib.physical.physical_history`.

    Returns
    -------
    xarray.Dataset
        :func:`to_dataset` (or :func:`history_to_dataset`) of the dimensionless
        result, and beside its variables the physical ones, named
        ``<quantity>_si``, each with its CF ``units`` ("m", "Pa", "N", "J", "s")
        and, for the scalars of a solve, a ``relative_error_estimate``
        attribute. The reference scales are global attributes with the unit in
        the name: ``composite_modulus_Pa`` (E*), ``indenter_radius_m`` (R),
        ``contact_radius_scale_m`` (a of a solve, a_max of a history),
        ``hertz_peak_pressure_Pa`` (p0 at that radius), ``hertz_load_N``
        (P_Hertz at that radius, a cylinder's over its length). Write it with
        :func:`write_dataset`.
    """
    from contactlib.physical import PhysicalHistory, PhysicalSolution

    if isinstance(result, PhysicalSolution):
        return _physical_solution_dataset(result)
    if isinstance(result, PhysicalHistory):
        return _physical_history_dataset(result)
    raise TypeError(f"result must be a PhysicalSolution or PhysicalHistory, got "
                    f"{type(result).__name__}")


def _physical_solution_dataset(res: Any) -> xr.Dataset:
    ds = to_dataset(res.solution)
    axis = indenter(res.geometry).coordinate
    per = " over the cylinder's length" if res.geometry == "cylinder" else ""

    def scalar(value: float, units: str, long_name: str, error: str | None,
               comment: str = "") -> tuple[tuple, float, dict[str, Any]]:
        extra = {}
        if error is not None:
            extra["relative_error_estimate"] = float(res.errors.get(error, math.nan))
        return ((), float(value), cf_attrs(long_name, units, comment, **extra))

    prof = res.profiles()
    data = {
        "normal_force_si": scalar(res.load, "N", "normal force P" + per, None),
        "contact_radius_si": scalar(res.contact_radius, "m", "contact radius a "
                                    "(half-width for the cylinder)", "contact_radius"),
        "stick_radius_si": scalar(res.stick_radius, "m", "stick zone radius c",
                                  "stick_radius"),
        "peak_pressure_si": scalar(res.peak_pressure, "Pa", "largest contact pressure",
                                   "peak_pressure"),
        "mean_pressure_si": scalar(res.mean_pressure, "Pa", "mean contact pressure",
                                   "mean_pressure"),
        "approach_si": scalar(res.approach, "m", "approach (indentation) delta",
                              "approach", "NaN for a cylinder on a half-plane (defined "
                                          "only to within a reference length)"),
        "frictional_energy_si": scalar(res.frictional_energy, "J", "frictional energy of "
                                       "the loading half-cycle" + per, "frictional_energy",
                                       "loading 0 -> P"),
        "position_si": (("xi",), prof["r"], cf_attrs(f"position {axis} from the axis", "m")),
        "pressure_si": (("xi",), prof["pressure"], cf_attrs("contact pressure", "Pa",
                                                            "positive in compression")),
        "shear_si": (("xi",), prof["shear"], cf_attrs(
            "shear traction on the body", "Pa", "positive away from the axis")),
        "tangential_displacement_si": (("xi",), prof["tangential_displacement"], cf_attrs(
            "tangential surface displacement", "m", "positive away from the axis")),
    }
    ds = ds.assign(data)
    ds.attrs.update(_scale_attrs(res, res.contact_radius, "a, the computed contact radius"))
    return ds


def _physical_history_dataset(res: Any) -> xr.Dataset:
    ds = history_to_dataset(res.result)
    sd, ed = ("step",), ("step", "xi")
    axis = indenter(res.geometry).coordinate
    per = " over the cylinder's length" if res.geometry == "cylinder" else ""
    r = res.result
    data: dict[str, Any] = {
        "normal_force_si": (sd, res.force, cf_attrs("normal force P" + per, "N")),
        "contact_radius_si": (sd, res.contact_radius, cf_attrs("contact radius a", "m")),
        "stick_radius_si": (sd, res.stick_radius, cf_attrs(
            "stick zone radius c", "m", "NaN without contact")),
        "stick_radius_error_estimate_si": (sd, res.stick_radius_error, cf_attrs(
            "estimated absolute error of the stick zone radius", "m")),
        "peak_pressure_si": (sd, res.peak_pressure, cf_attrs("largest contact pressure",
                                                             "Pa")),
        "approach_si": (sd, res.approach, cf_attrs(
            "approach (indentation) delta", "m",
            "NaN for a cylinder on a half-plane (defined only to within a reference length)")),
        "frictional_energy_si": (sd, res.frictional_energy, cf_attrs(
            "cumulative frictional energy" + per, "J",
            "relative error estimate: work_error_estimate")),
        "position_si": (("xi",), np.asarray(r.xi) * res.a_max, cf_attrs(
            f"element midpoint {axis}", "m")),
        "pressure_si": (ed, np.asarray(r.pressure) * res.p0, cf_attrs(
            "contact pressure", "Pa", "positive in compression")),
        "shear_si": (ed, np.asarray(r.shear) * res.p0, cf_attrs(
            "shear traction on the body", "Pa", "positive away from the axis")),
        "tangential_displacement_si": (ed, np.asarray(r.tangential_displacement)
                                       * res.a_max ** 2 / res.radius, cf_attrs(
            "tangential surface displacement", "m", "positive away from the axis")),
        "cycle_frictional_energy_si": (("cycle",), res.cycle_frictional_energy, cf_attrs(
            "frictional energy of each cycle" + per, "J",
            "a cycle ends where the force, having decreased, turns up, or at the path's end")),
        "cycle_energy_error_estimate_si": (("cycle",), res.cycle_energy_error, cf_attrs(
            "estimated absolute error of the cycle's frictional energy", "J")),
        "cycle_start": (("cycle",), np.array([s for s, _ in res.cycles], dtype=np.int32),
                        cf_attrs("path point where the cycle starts")),
        "cycle_end": (("cycle",), np.array([e for _, e in res.cycles], dtype=np.int32),
                      cf_attrs("path point where the cycle ends")),
    }
    if getattr(r, "relaxation", ()):
        data["viscous_energy_si"] = (sd, res.viscous_energy, cf_attrs(
            "cumulative viscous dissipation" + per, "J"))
        data["cycle_viscous_energy_si"] = (("cycle",), res.cycle_viscous_energy, cf_attrs(
            "viscous energy of each cycle" + per, "J"))
        data["time_si"] = (sd, res.time, cf_attrs("time at the end of the step", "s"))
    ds = ds.assign(data)
    ds.attrs.update(_scale_attrs(res, res.a_max, "a_max, the frictionless (Hertz) contact "
                                                 "radius at the largest force"))
    ds.attrs["load_path_N"] = np.asarray(res.load_path, dtype=float)
    return ds


# ----------------------------------------------------------------------------- fretting
def fretting_to_dataset(result: Any) -> xr.Dataset:
    """CF-annotated :class:`xarray.Dataset` of a fretting path (dimensions ``step``, ``x``, ``point``).

    Every variable is dimensionless (``units`` "1") in the units of
    :mod:`contactlib.fretting_api`. Per step: the loads, the contact and
    stick-zone edges, ``stick_ratio``, ``stick_offset``, the rigid
    displacements, the energies and the tractions; per path point: the error
    estimates and ``resolved``. Write it with :func:`write_dataset`.

    Parameters
    ----------
    result : FrettingResult
        From :func:`contactlib.fretting`.

    Returns
    -------
    xarray.Dataset
    """
    import xarray as xr

    from contactlib import fretting_solver as fs
    from contactlib import profiles

    r = result
    sphere = r.geometry == "sphere"
    work = "V R**2 / (E* a_max**5)" if sphere else "V R**2 / (E* a_max**4) per unit length"
    sd, ed, pd = ("step",), ("step", "x"), ("point",)
    side = ("step", "side")
    coords = {
        "step": ("step", np.arange(r.load_ratio.size, dtype=np.int32),
                 cf_attrs("load step", comment="0: unloaded initial state")),
        "x": ("x", r.x, cf_attrs("element midpoint over a_max (x/a_max)",
                                 comment="collocation points of the strip -1.2 <= x <= 1.2")),
        "point": ("point", np.arange(len(r.load_path), dtype=np.int32),
                  cf_attrs("load path point", comment="0: the unloaded start")),
        "side": ("side", np.array(["left", "right"]), cf_attrs("edge")),
    }
    data = {
        "segment": (sd, r.segment.astype(np.int32),
                    cf_attrs("load path segment", comment="1-based; 0 for the initial state")),
        "load_ratio": (sd, r.load_ratio, cf_attrs("normal load over maximum load (P/P_max)")),
        "tangential_load_ratio": (sd, r.force_ratio, cf_attrs(
            "tangential load over friction times maximum load (Q/(k P_max))",
            comment="Q: the force the indenter exerts on the body along +x, per unit length")),
        "bulk_stress": (sd, r.bulk_stress, cf_attrs(
            "bulk stress of the body along x over p0 (sigma/p0)")),
        "contact_edges": (side, r.contact_edges, cf_attrs(
            "contact edges over a_max", comment="sub-element fit of the pressure; NaN: "
                                                "no contact")),
        "stick_edges": (side, r.stick_edges, cf_attrs(
            "stick zone edges over a_max", comment="longest run of stuck elements, edges "
                                                   "from a sub-element fit of k p - |q|")),
        "stick_ratio": (sd, r.stick_ratio, cf_attrs(
            "stick zone radius over contact radius (c/a), area-equivalent radii" if sphere
            else "stick zone half-width over contact half-width (c/a)",
            comment="0 in full slip; NaN without contact")),
        "stick_offset": (sd, r.stick_offset, cf_attrs(
            "stick zone centre minus contact centre over a_max (e/a_max)")),
        "approach": (sd, r.approach, cf_attrs(
            "normal approach (delta R / a_max**2)",
            comment="half-plane: relative to the logarithm's datum at distance a_max")),
        "tangential_shift": (sd, r.shift, cf_attrs(
            "rigid tangential displacement of the indenter (s R / a_max**2)",
            comment="relative to the logarithm's datum at distance a_max; its changes "
                    "enclose the Q-s loop's area independently of the datum")),
        "frictional_work": (sd, r.dissipation, cf_attrs(
            "cumulative frictional work", comment=work + "; sum of k p |dv| over the "
                                                        "slipping elements, never decreasing")),
        "external_work": (sd, r.external_work, cf_attrs(
            "cumulative external work", comment=work + "; trapezoid rule in time")),
        "stored_energy": (sd, r.stored_energy, cf_attrs("stored elastic energy",
                                                       comment=work)),
        "converged": (sd, r.converged.astype(bool), cf_attrs("step converged", **_BOOL_FLAGS)),
        "pressure": (ed, r.pressure, cf_attrs(
            "contact pressure over p0", comment="p0: Hertz peak pressure at a_max")),
        "shear": (ed, r.shear, cf_attrs(
            "shear traction over p0", comment="traction on the body, positive along +x")),
        "slip": (ed, r.slip, cf_attrs(
            "slip increment of the step (body minus indenter) (dv R / a_max**2)",
            comment="0 where stuck or separated")),
        "tangential_compliance": (sd, r.tangential_compliance, cf_attrs(
            "tangential compliance over the step (ds/dQ, units 1/E*)",
            comment="secant over the step; its level depends on the half-plane's datum, "
                    "its changes do not; NaN where Q does not change")),
        "state": (ed, r.state.astype(np.int8), cf_attrs(
            "element contact state", flag_values=np.array([0, 1, 2, 3], dtype=np.int8),
            flag_meanings=fs.STATE_MEANINGS)),
        "point_step": (pd, r.point_step.astype(np.int32), cf_attrs(
            "step index of the load path point")),
        "stick_ratio_error_estimate": (pd, r.stick_ratio_error, cf_attrs(
            "estimated absolute error of stick_ratio at the path point",
            comment="difference to a run with n/2 elements and steps/2")),
        "stick_offset_error_estimate": (pd, r.stick_offset_error, cf_attrs(
            "estimated absolute error of stick_offset at the path point")),
        "frictional_work_error_estimate": (pd, r.dissipation_error, cf_attrs(
            "estimated absolute error of frictional_work at the path point",
            comment="Richardson estimate from runs with n/2 and n/4 elements (and steps)")),
        "resolved": (pd, r.resolved.astype(bool), cf_attrs(
            "path point resolved to max_error", **_BOOL_FLAGS)),
    }
    cyc = np.asarray([c[:2] for c in r.cycles], dtype=np.int32).reshape(-1, 2)
    attrs: dict[str, Any] = {
        "title": f"contactlib fretting path ({r.geometry})",
        "geometry": r.geometry,
        "poisson_ratio": float(r.nu),
        "dundurs_beta": float(r.beta),
        "friction_coefficient": float(r.friction),
        "elements": int(r.n),
        "steps": int(r.steps),
        "load_path": np.asarray(r.load_path, dtype=float),
        "tangential_path": np.asarray(r.tangential_path, dtype=float),
        "bulk_stress_path": np.asarray(r.bulk_stress_path, dtype=float),
        "max_error": float(r.max_error),
        "cycle_points": cyc.ravel(),
        "cycle_work": np.asarray([c[2] for c in r.cycles], dtype=float),
        "cycle_work_error_estimate": np.asarray([c[3] for c in r.cycles], dtype=float),
        "cycle_shaken_down": r.shaken_down.astype(np.int8),
        "p0": float(r.p0),  # the pressure unit at a_max (E* a_max/R): Hertz's 1/2 or 2/pi
        "p_max": float(r.p_max),  # the load unit (per unit length for the cylinder)
        **(profiles.of_result(r).attributes()
           if getattr(r, "profile", "paraboloid") != "paraboloid" else {}),
        "length_scale": "a_max: frictionless (Hertz) contact "
                        + ("radius" if sphere else "half-width") + " at load level 1",
        **({"field_row": "pressure, shear (x), slip (x), state: the cells at y = h/2 "
                         "next to the x axis"} if sphere else {}),
        "contactlib_version": version(),
        "Conventions": CONVENTIONS,
    }
    return xr.Dataset(data_vars=data, coords=coords, attrs=attrs)


def fretting_study_to_dataset(results: Sequence[Any]) -> xr.Dataset:
    """Dataset of :func:`contactlib.fretting_api.amplitude_study` (dimensions ``case``,
    ``cycle``, ``loop_step``).

    Per case: Poisson's ratio, beta, the amplitude Q*/(kP); per cycle: its frictional work
    and estimate, and whether every step of it converged; per case the last cycle's Q-s
    loop: Q/(kP) and the shift change (s - s0) over k p0 (units a_max^2/R), NaN where a
    step did not converge. Mindlin–Deresiewicz's closed form of the cylinder
    (:func:`contactlib.fretting_api.cylinder_cycle_work`) is stored beside the work where
    beta = 0.
    """
    import xarray as xr

    from contactlib.theory import cylinder_cycle_work

    rows = len(results)
    ncyc = min(len(r.cycles) for r in results)
    loop_len = 2 * results[0].steps + 1
    work = np.full((rows, ncyc), np.nan)
    est = np.full((rows, ncyc), np.nan)
    ok = np.zeros((rows, ncyc), dtype=bool)
    closed = np.full(rows, np.nan)
    loop_q = np.full((rows, loop_len), np.nan)
    loop_s = np.full((rows, loop_len), np.nan)
    amp = np.zeros(rows)
    for c, r in enumerate(results):
        amp[c] = max(abs(t) for t in r.tangential_path)
        for m, (i, j, w, e) in enumerate(r.cycles[:ncyc]):
            a, b = r.point_step[i], r.point_step[j]
            ok[c, m] = bool(r.converged[a:b + 1].all())
            work[c, m], est[c, m] = w, e
        i, j = r.cycles[ncyc - 1][:2]
        a, b = r.point_step[i], r.point_step[j]
        good = r.converged[a:b + 1]
        scale = r.friction * r.p0
        loop_q[c] = np.where(good, r.force_ratio[a:b + 1] / r.load_ratio[a:b + 1], np.nan)
        loop_s[c] = np.where(good, (r.shift[a:b + 1] - r.shift[a]) / scale, np.nan)
        if r.beta == 0.0:
            closed[c] = float(cylinder_cycle_work(amp[c], r.friction, r.p_max, r.p0))
    first = results[0]
    per = ("case",)
    data = {
        "poisson_ratio": (per, np.array([r.nu for r in results]), cf_attrs("Poisson's ratio")),
        "dundurs_beta": (per, np.array([r.beta for r in results]), cf_attrs("Dundurs' beta")),
        "amplitude": (per, amp, cf_attrs("tangential amplitude over friction times load "
                                         "(Q*/(k P))")),
        "cycle_work": (("case", "cycle"), work, cf_attrs(
            "frictional work of the cycle", comment="V R**2 / (E* a_max**4) per unit length")),
        "cycle_work_error_estimate": (("case", "cycle"), est, cf_attrs(
            "estimated absolute error of cycle_work")),
        "cycle_converged": (("case", "cycle"), ok, cf_attrs(
            "every step of the cycle converged", **_BOOL_FLAGS)),
        "mindlin_deresiewicz_work": (per, closed, cf_attrs(
            "closed-form cycle work of the cylinder (Mindlin-Deresiewicz)",
            comment="beta = 0 only; NaN otherwise")),
        "loop_tangential_load": (("case", "loop_step"), loop_q, cf_attrs(
            "Q/(k P) over the last cycle", comment="NaN where a step did not converge")),
        "loop_shift": (("case", "loop_step"), loop_s, cf_attrs(
            "shift change over the last cycle over k p0 ((s - s0) R / (k p0 a_max**2))",
            comment="NaN where a step did not converge")),
    }
    attrs = {"title": "contactlib fretting amplitude study (cylinder)",
             "friction_coefficient": float(first.friction), "elements": int(first.n),
             "steps": int(first.steps), "max_error": float(first.max_error),
             "contactlib_version": version(), "Conventions": CONVENTIONS}
    coords = {"case": ("case", np.arange(rows, dtype=np.int32), cf_attrs("case")),
              "cycle": ("cycle", np.arange(1, ncyc + 1, dtype=np.int32),
                        cf_attrs("cycle", comment="1: the first, from the first peak"))}
    return xr.Dataset(data_vars=data, coords=coords, attrs=attrs)


def physical_fretting_to_dataset(result: Any) -> xr.Dataset:
    """:func:`fretting_to_dataset` of a :class:`~contactlib.physical_fretting.PhysicalFretting`,
    with its SI variables (CF ``units`` "N", "m", "J") and scales as attributes.

    The dimensionless variables stay as they are; ``normal_force``, ``tangential_force``,
    ``contact_edges_si``, ``stick_edges_si``, ``stick_offset_si`` and
    ``frictional_work_si`` are the same quantities in SI, and the attributes
    ``composite_modulus`` [Pa], ``radius``, ``length``, ``a_max`` [m], ``p0`` [Pa] and
    ``load_max`` [N] convert the rest.
    """
    r = result.result
    ds = fretting_to_dataset(r)
    k, a, fmax = r.friction, result.a_max, result.load_max
    ds["normal_force"] = (("step",), r.load_ratio * fmax, cf_attrs("normal force", "N"))
    ds["tangential_force"] = (("step",), r.force_ratio * k * fmax,
                              cf_attrs("tangential force on the body along +x", "N"))
    ds["contact_edges_si"] = (("step", "side"), r.contact_edges * a,
                              cf_attrs("contact edges", "m"))
    ds["stick_edges_si"] = (("step", "side"), r.stick_edges * a,
                            cf_attrs("stick zone edges", "m"))
    ds["stick_offset_si"] = (("step",), r.stick_offset * a,
                             cf_attrs("stick zone centre minus contact centre", "m"))
    ds["frictional_work_si"] = (("step",), r.dissipation * result.work_unit,
                                cf_attrs("cumulative frictional work", "J",
                                         comment="over the cylinder's length"
                                         if r.geometry == "cylinder" else ""))
    ds.attrs.update({"composite_modulus": float(result.composite_modulus),
                     "radius": float(result.radius), "length": float(result.length),
                     "a_max": float(a), "p0": float(result.p0), "load_max": float(fmax),
                     "work_unit": float(result.work_unit),
                     "scales": "lengths in m = value * a_max; forces in N; work in J = value "
                               "* work_unit (" + ("E* a_max**5 / R**2" if r.geometry == "sphere"
                                                  else "E* a_max**4 / R**2 * length") + ")"})
    return ds
