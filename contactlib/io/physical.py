"""Physical (SI) results to datasets: the dimensionless dataset plus ``*_si`` variables.

:func:`physical_to_dataset` for a :class:`~contactlib.physical.PhysicalSolution`
or :class:`~contactlib.physical.PhysicalHistory` and
:func:`physical_fretting_to_dataset` for a
:class:`~contactlib.physical_fretting.PhysicalFretting`: the datasets of
:mod:`contactlib.io.datasets` and :mod:`contactlib.io.fretting` with the same
quantities in SI (CF ``units`` "m", "Pa", "N", "J", "s") and the reference
scales as global attributes.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:  # xarray is imported where a dataset is made or read (start-up time)
    import xarray as xr

from contactlib.model.indenter import indenter
from contactlib.io.conventions import cf_attrs
from contactlib.io.datasets import history_to_dataset, to_dataset
from contactlib.io.fretting import fretting_to_dataset

__all__ = ["physical_to_dataset", "physical_fretting_to_dataset"]


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
    if getattr(res, "profile", "paraboloid") == "cone":  # no R: the half-angle gives the cone
        del attrs["indenter_radius_m"]
        attrs["indenter_half_angle_deg"] = float(res.half_angle)
        attrs["profile_scales"] = ("cone (wedge) z = r cot(alpha): hertz_load_N is its "
                                   "frictionless load at the contact radius, "
                                   "hertz_peak_pressure_Pa the pressure unit (the peak "
                                   "pressure of the paraboloid carrying that load); "
                                   "displacements in units of a cot(alpha)")
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
                                       * res.scales().displacement_unit(res.a_max), cf_attrs(
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

def physical_fretting_to_dataset(result: Any) -> xr.Dataset:
    """:func:`fretting_to_dataset` of a :class:`~contactlib.physical_fretting.PhysicalFretting`,
    with its SI variables (CF ``units`` "N", "m", "J") and scales as attributes.

    The dimensionless variables stay as they are; ``normal_force``, ``tangential_force``,
    ``contact_edges_si``, ``stick_edges_si``, ``stick_offset_si``,
    ``frictional_work_si`` (and the sphere's ``stick_radius_directions_si``,
    ``contact_radius_directions_si``, ``stick_centre_si`` and ``contact_centre_si``) are
    the same quantities in SI, and the attributes
    ``composite_modulus`` [Pa], ``radius``, ``length``, ``a_max`` [m], ``p0`` [Pa] and
    ``load_max`` [N] convert the rest.
    """
    r = result.result
    ds = fretting_to_dataset(r)
    k, a, fmax = r.friction, result.a_max, result.load_max
    ds["normal_force"] = (("step",), r.load_ratio * fmax, cf_attrs("normal force", "N"))
    ds["tangential_force"] = (("step",), r.force_ratio * k * fmax,
                              cf_attrs("tangential force on the body along +x", "N"))
    if r.tangential_displacement:
        ds["tangential_shift_si"] = (("step",), r.shift * result.shift_unit,
                                     cf_attrs("prescribed rigid shift of the indenter", "m"))
    ds["contact_edges_si"] = (("step", "side"), r.contact_edges * a,
                              cf_attrs("contact edges", "m"))
    ds["stick_edges_si"] = (("step", "side"), r.stick_edges * a,
                            cf_attrs("stick zone edges", "m"))
    ds["stick_offset_si"] = (("step",), r.stick_offset * a,
                             cf_attrs("stick zone centre minus contact centre", "m"))
    if "stick_radius_directions" in ds:  # the sphere's zones per direction
        for name in ("stick", "contact"):
            ds[f"{name}_radius_directions_si"] = (
                ("step", "direction"), ds[f"{name}_radius_directions"].values * a,
                cf_attrs(f"{name} radius along the direction", "m",
                         comment=f"from {name}_centre_si"))
            ds[f"{name}_centre_si"] = (("step", "component"), ds[f"{name}_centre"].values * a,
                                       cf_attrs(f"{name} centroid (x, y)", "m"))
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
