"""Fretting results to CF-annotated datasets: a fretting path and an amplitude study.

:func:`fretting_to_dataset` for a :class:`~contactlib.fretting_api.FrettingResult`
(dimensions ``step``, ``x``, ``point``) and :func:`fretting_study_to_dataset` for
:func:`contactlib.fretting_api.amplitude_study`, in the units of
:mod:`contactlib.fretting_api` and the conventions of :mod:`contactlib.io.conventions`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:  # xarray is imported where a dataset is made or read (start-up time)
    import xarray as xr

from contactlib.io.conventions import BOOL_FLAGS, CONVENTIONS, cf_attrs, version

__all__ = ["fretting_to_dataset", "fretting_study_to_dataset"]


# ----------------------------------------------------------------------------- fretting
def fretting_to_dataset(result: Any) -> xr.Dataset:
    """CF-annotated :class:`xarray.Dataset` of a fretting path (dimensions ``step``, ``x``, ``point``).

    Every variable is dimensionless (``units`` "1") in the units of
    :mod:`contactlib.fretting_api`. Per step: the loads, the contact and
    stick-zone edges, ``stick_ratio``, ``stick_offset`` (the sphere: also the zones' radii
    per ``direction``, ``stick_radius_directions`` and ``contact_radius_directions``), the rigid
    displacements, the energies and the tractions; per path point: the error
    estimates and ``resolved``. The attribute ``tangential_control`` is ``"force"``
    (``tangential_path`` is Q/(k P_max)) or ``"displacement"`` (the prescribed shift
    s R/a_max^2; then ``tangential_load_ratio_error_estimate`` holds the answered force's
    estimate per point). Write it with :func:`write_dataset`.

    Parameters
    ----------
    result : FrettingResult
        From :func:`contactlib.fretting`.

    Returns
    -------
    xarray.Dataset
    """
    import xarray as xr

    from contactlib.solvers import fretting_solver as fs
    from contactlib.model import profiles

    r = result
    sphere = r.geometry == "sphere"
    shifted = bool(getattr(r, "tangential_displacement", False))
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
            comment=("absolute (a half-space has no datum)" + ("; prescribed" if shifted
                                                              else "")) if sphere else
            "relative to the logarithm's datum at distance a_max; its changes "
            "enclose the Q-s loop's area independently of the datum")),
        "frictional_work": (sd, r.dissipation, cf_attrs(
            "cumulative frictional work", comment=work + "; sum of k p |dv| over the "
                                                        "slipping elements, never decreasing")),
        "external_work": (sd, r.external_work, cf_attrs(
            "cumulative external work", comment=work + "; trapezoid rule in time")),
        "stored_energy": (sd, r.stored_energy, cf_attrs("stored elastic energy",
                                                       comment=work)),
        "converged": (sd, r.converged.astype(bool), cf_attrs("step converged", **BOOL_FLAGS)),
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
            "path point resolved to max_error", **BOOL_FLAGS)),
    }
    if sphere and getattr(r, "direction_angles", None) is not None:
        coords["direction"] = ("direction", r.direction_angles, cf_attrs(
            "direction from the zone's centroid", "radian",
            comment="counterclockwise from +x, the tangential load's direction"))
        coords["component"] = ("component", np.array(["x", "y"]), cf_attrs("component"))
        rd, ptd = ("step", "direction"), ("point", "direction")
        data["stick_centre"] = (("step", "component"), r.stick_centre, cf_attrs(
            "stick zone centroid over a_max (x, y)",
            comment="the cells' centroid, origin of stick_radius_directions; NaN in full "
                    "slip or without contact"))
        data["contact_centre"] = (("step", "component"), r.contact_centre, cf_attrs(
            "contact centroid over a_max (x, y)",
            comment="the cells' centroid, origin of contact_radius_directions"))
        data["stick_radius_directions"] = (rd, r.stick_radius_directions, cf_attrs(
            "stick zone radius along the direction over a_max",
            comment="from stick_centre; the edge located inside the cells along the ray; "
                    "0 in full slip; NaN without contact"))
        data["contact_radius_directions"] = (rd, r.contact_radius_directions, cf_attrs(
            "contact radius along the direction over a_max",
            comment="from contact_centre; NaN without contact"))
        data["stick_radius_directions_error_estimate"] = (
            ptd, r.stick_radius_directions_error, cf_attrs(
                "estimated absolute error of stick_radius_directions at the path point",
                comment="difference to a run with n/2 cells and steps/2 plus the lattice "
                        "term, at least half a cell"))
        data["contact_radius_directions_error_estimate"] = (
            ptd, r.contact_radius_directions_error, cf_attrs(
                "estimated absolute error of contact_radius_directions at the path point",
                comment="difference to a run with n/2 cells and steps/2"))
    if shifted:  # Q is the answer: its estimate
        data["tangential_load_ratio_error_estimate"] = (pd, r.force_ratio_error, cf_attrs(
            "estimated absolute error of tangential_load_ratio at the path point",
            comment="difference to a run with n/2 cells and steps/2"))
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
        # force: tangential_path is Q/(k P_max); displacement: the shift s R / a_max**2
        "tangential_control": "displacement" if shifted else "force",
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

    from contactlib.model.theory import cylinder_cycle_work

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
            "every step of the cycle converged", **BOOL_FLAGS)),
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
