"""Results to CF-annotated datasets and back: solutions, scenes, histories and studies.

Turns the results of the numerics into :class:`xarray.Dataset` objects in
the variable names and scalings of docs/conventions.md (the names and
attributes of :mod:`contactlib.io.conventions`):

* :func:`to_dataset` for :class:`~contactlib.result.Solution` objects
  (``contactlib solve``/``sweep``), :func:`scene_to_dataset` for a workflow
  scene;
* :func:`history_to_dataset` and :func:`stack_histories` for loading
  histories (:class:`~contactlib.history_api.HistoryResult`);
* :func:`study_to_dataset` and :func:`study_from_dataset` for convergence
  studies (:class:`~contactlib.convergence.Study`), and
  :func:`layer_study_to_dataset` for a :class:`~contactlib.layer_study.LayerStudy`.

It imports the numerics only for their types and constants, and only when a
conversion needs them; it writes no file (:mod:`contactlib.io.files` does).
The examples are those of each function and of :mod:`contactlib.io`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:  # xarray is imported where a dataset is made or read (start-up time)
    import xarray as xr

from contactlib.checks import FLAG_NAMES, VIOLATION_NAMES
from contactlib.model.indenter import indenter
from contactlib.io.conventions import (BOOL_FLAGS, CONVENTIONS, POINT_BOOL_ATTRS,
                                       POINT_FLOAT_ATTRS, PROFILE_ATTRS, cf_attrs,
                                       layer_attrs, set_provenance, version, work_comment)
from contactlib.result import Solution

if TYPE_CHECKING:  # types only: the conversions import the numerics when they run
    from contactlib.convergence import Study
    from contactlib.history_api import HistoryResult
    from contactlib.layer_study import LayerStudy

__all__ = ["to_dataset", "scene_to_dataset", "history_to_dataset", "stack_histories",
           "study_to_dataset", "study_from_dataset", "layer_study_to_dataset"]


_SHARED_FIELDS = ("geometry", "nu", "method", "slab_ratio", "base",
                  "indenter_modulus_ratio", "indenter_poisson_ratio", "profile", "exponent",
                  "substrate_modulus", "substrate_poisson_ratio")

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
        for name in PROFILE_ATTRS:
            value = getattr(sol, name)
            if (value is None) != (getattr(first, name) is None):
                raise ValueError(f"solutions[{i}].{name} is computed for some solutions only")
            shape = xi.shape if value is None else np.shape(value)
            if shape != xi.shape:
                raise ValueError(
                    f"solutions[{i}].{name} has shape {shape}, expected {xi.shape}"
                )
    return xi


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
    for name, (long_name, comment) in PROFILE_ATTRS.items():
        if getattr(first, name) is None:
            continue  # not computed (a workflow scene that did not ask for it)
        values = np.stack([np.asarray(getattr(s, name), dtype=float) for s in sols])
        data[name] = (dims + ("xi",), values, cf_attrs(long_name, comment=comment))
    for name, (long_name, comment) in POINT_FLOAT_ATTRS.items():
        if name == "frictional_work":
            comment = work_comment(ind)
        values = np.array([float(getattr(s, name)) for s in sols])
        data[name] = (dims, values, cf_attrs(long_name, comment=comment))
    data["iterations"] = (
        dims,
        np.array([int(s.iterations) for s in sols], dtype=np.int32),
        cf_attrs("solver iterations", comment="solver status"),
    )
    for name, (long_name, comment) in POINT_BOOL_ATTRS.items():
        values = np.array([bool(getattr(s, name)) for s in sols], dtype=bool)
        data[name] = (dims, values, cf_attrs(long_name, comment=comment, **BOOL_FLAGS))
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
    attrs.update(layer_attrs(ind, first))
    if getattr(first, "profile", "paraboloid") != "paraboloid":  # Hertz's files stay as they were
        attrs["profile"] = str(first.profile)  # h = A r^d (contactlib.model.profiles)
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

    from contactlib.solvers import history_solver as hs

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
    bool_flags = BOOL_FLAGS
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
    if getattr(r, "segment_steps", ()):  # a shape or table (contactlib.model.load_paths)
        attrs["segment_steps"] = np.asarray(r.segment_steps, dtype=np.int32)
        attrs["steps_meaning"] = ("steps a unit of load travel (P_max); segment_steps: the "
                                  "steps of each segment, a monotone piece of the path, "
                                  "whose ends load_path gives")
        for key, value in (r.load_shape or {}).items():
            attrs[f"load_path_{key}"] = value
        attrs["load_path_interpolation_error"] = float(r.interpolation_error)
    attrs.update(layer_attrs(ind, r))
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
    if st.slab_ratio > 0 and st.base != "smooth":  # as every layer dataset (layer_attrs)
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
                **BOOL_FLAGS)),
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
                comment="thin bonded layers whose slip reverses are not", **BOOL_FLAGS)),
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
