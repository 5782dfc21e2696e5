"""Fretting of a cylinder or sphere in SI units: :func:`physical_fretting`.

The physical door of :func:`contactlib.fretting`, with the conversions of
:mod:`contactlib.physical` (one place for them): the normal and tangential
forces in N over the cylinder's length, the bulk stress in Pa, the answer in m,
Pa, N and J with the error estimate of each.

Scales: E* from the two materials; a_max = (4 P_max R/(pi E* L))^(1/2), the
frictionless half-width at the largest normal force P_max of the path; p0 =
E* a_max/(2R); lengths in units of a_max, work in E* a_max^4/R^2 per unit length
times L. The sphere (``geometry="sphere"``; a coupled pair, Dundurs beta != 0, with
``|beta| <= 0.5`` under ``|Q| <= 0.9 k P`` with ``n <= 64`` only): a_max = (3 P_max
R/(4 E*))^(1/3), p0 = 2 E* a_max/(pi R), work in E* a_max^5/R^2. The sphere also takes
a prescribed rigid shift in m (``tangential_displacement=True``), in units a_max^2/R inside.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from . import validate
from .fretting_api import FrettingResult, fretting, stick_shape
from .physical import (contact_radius_of_load, format_si, physical_problem, validity_notes,
                       hertz_peak_pressure, parse_force_path, parse_quantity)
from .validate import PATH_DEFAULT_MAX_ERROR as DEFAULT_MAX_ERROR

__all__ = ["PhysicalFretting", "physical_fretting", "parse_signed_path"]


def parse_signed_path(value: Any, kind: str, name: str) -> tuple[float, ...]:
    """A path of signed forces (N) or stresses (Pa): numbers in SI or strings with units.

    ``"0N,0N,200N,-200N"`` or a sequence; the first value 0.
    """
    items = value.split(",") if isinstance(value, str) else value
    req = f"a list of {kind}s (SI, or with a unit), starting at 0"
    if isinstance(items, (bytes, dict)) or not hasattr(items, "__iter__"):
        raise validate.InputError(name, req, value)
    out = []
    for item in items:
        sign = 1.0
        if isinstance(item, str) and item.strip().startswith("-"):
            sign, item = -1.0, item.strip()[1:]
        elif isinstance(item, (int, float)) and not isinstance(item, bool) and item < 0:
            sign, item = -1.0, -item
        out.append(sign * parse_quantity(item, kind, name, positive=False))
    if len(out) < 2 or out[0] != 0.0:
        raise validate.InputError(name, req, value)
    return tuple(out)


@dataclass(repr=False)
class PhysicalFretting:
    """A fretting path of a cylinder or sphere in SI (m, Pa, N, J), with the dimensionless result.

    Attributes
    ----------
    result : FrettingResult
        The dimensionless answer (units of :mod:`contactlib.fretting_api`).
    radius, length : float
        R and L [m] (L = 1 for the sphere).
    composite_modulus : float
        E* [Pa].
    a_max, p0, load_max : float
        The frictionless half-width [m] and Hertz peak pressure [Pa] at the largest
        normal force, and that force [N].
    work_unit : float
        The work unit E* a_max^4/R^2 L [J].
    shift_unit : float
        The displacement unit a_max^2/R [m].
    notes : list of str
        Where the contact leaves the theory's validity (a/R, a/L).
    """

    result: FrettingResult
    radius: float
    length: float
    composite_modulus: float
    a_max: float
    p0: float
    load_max: float
    work_unit: float
    heading: str
    notes: list[str]
    shift_unit: float = 0.0

    @property
    def size_name(self) -> str:
        """``"radius"`` (sphere) or ``"half-width"`` (cylinder): the zones' size in the keys."""
        return "radius" if self.result.geometry == "sphere" else "half-width"

    def points(self) -> list[dict[str, float]]:
        """The state at every path point in SI, with the estimates (m, N, J).

        The zones' sizes are ``"contact half-width [m]"`` and ``"stick half-width [m]"``
        (cylinder) or ``"contact radius [m]"`` and ``"stick radius [m]"`` (sphere). Under a
        prescribed shift also ``"tangential shift [m]"`` and ``"tangential force error
        [N]"`` (the answered force's estimate).
        """
        r = self.result
        size = self.size_name
        rows = []
        for i, j in enumerate(r.point_step):
            left, right = r.contact_edges[j]
            rows.append({
                "normal force [N]": float(r.load_ratio[j] * self.load_max),
                "tangential force [N]": float(r.force_ratio[j] * r.friction * self.load_max),
                f"contact {size} [m]": float(0.5 * (right - left) * self.a_max),
                f"stick {size} [m]": float(0.5 * r.stick_ratio[j] * (right - left)
                                           * self.a_max),
                f"stick {size} error [m]": float(0.5 * r.stick_ratio_error[i]
                                                 * (right - left) * self.a_max),
                "stick offset [m]": float(r.stick_offset[j] * self.a_max),
                "stick offset error [m]": float(r.stick_offset_error[i] * self.a_max),
                "frictional work [J]": float(r.dissipation[j] * self.work_unit),
                "frictional work error [J]": float(r.dissipation_error[i] * self.work_unit),
                "resolved": bool(r.resolved[i])})
            if r.tangential_displacement:
                rows[-1]["tangential shift [m]"] = float(r.shift[j] * self.shift_unit)
                rows[-1]["tangential force error [N]"] = float(
                    r.force_ratio_error[i] * r.friction * self.load_max)
        return rows

    def cycles(self) -> list[tuple[int, int, float, float]]:
        """(first point, last point, frictional work [J], its estimate [J]) per cycle."""
        return [(i, j, w * self.work_unit, e * self.work_unit)
                for i, j, w, e in self.result.cycles]

    def summary(self) -> str:
        """A few lines: the scales, each path point and each cycle in SI."""
        r = self.result
        lines = [self.heading,
                 f"E* = {format_si(self.composite_modulus, 'Pa')}, beta = {r.beta:.4g}, "
                 f"k = {r.friction:g}; at {format_si(self.load_max, 'N')}: a = "
                 f"{format_si(self.a_max, 'm')}, p0 = {format_si(self.p0, 'Pa')}",
                 "point  P         Q          " + ("(estimate) at shift s  " if
                                                     r.tangential_displacement else "")
                 + "a          c (estimate)           "
                 "offset      frictional work (estimate)  resolved"]
        for i, row in enumerate(self.points()):
            size = self.size_name
            c = row[f"stick {size} [m]"]
            if not math.isfinite(row[f"contact {size} [m]"]):
                lines.append(f"{i:5d}  {format_si(row['normal force [N]'], 'N'):9s} "
                             f"{format_si(row['tangential force [N]'], 'N'):10s} no contact")
                continue
            shift = (f"({row['tangential force error [N]']:.1e} N) at s = "
                     f"{format_si(row['tangential shift [m]'], 'm')}  "
                     if "tangential shift [m]" in row else "")
            lines.append(
                f"{i:5d}  {format_si(row['normal force [N]'], 'N'):9s} "
                f"{format_si(row['tangential force [N]'], 'N'):10s} {shift}"
                f"{format_si(row[f'contact {size} [m]'], 'm'):10s} "
                f"{format_si(c, 'm') if math.isfinite(c) else 'none':10s} "
                f"({row[f'stick {size} error [m]']:.1e} m)  "
                f"{row['stick offset [m]']:+.2e} m  "
                f"{format_si(row['frictional work [J]'], 'J'):10s} "
                f"({row['frictional work error [J]']:.1e} J)  "
                f"{'yes' if row['resolved'] else 'NO'}")
        for i, j, w, e in self.cycles():
            lines.append(f"cycle from point {i} to {j}: {format_si(w, 'J')} "
                         f"(estimate {e:.1e} J)")
        shape = stick_shape(r)  # the sphere: its stick zone per direction, in m
        if shape is not None:
            lines.append(shape.describe(self.a_max, format_si))
        lines += self.notes
        return "\n".join(lines)

    def __repr__(self) -> str:
        return self.summary()


def physical_fretting(radius: float | str, length: float | str, load_path: Any,
                      tangential_path: Any, indenter: Any, body: Any, friction: float, *,
                      geometry: str = "cylinder", steps: int | None = None,
                      n: int | None = None,
                      bulk_stress: Any = None, max_error: float = DEFAULT_MAX_ERROR,
                      progress: Callable[[int, int], None] | None = None,
                      tangential_displacement: bool = False) -> PhysicalFretting:
    """A cylinder or sphere pressed by forces in N, then loaded tangentially; answer in SI.

    Parameters
    ----------
    radius, length : float or str
        R and L of the cylinder, in m or with a unit ("10mm"); the sphere: R, and
        ``length=None``.
    load_path : sequence or str
        Normal forces [N] (or with units: "0N,500N,500N"), starting at 0; P_max is the
        largest.
    tangential_path : sequence or str
        Tangential forces [N] at the same points, signed, starting at 0, with |Q| < k P;
        with ``tangential_displacement`` the indenter's rigid shifts [m] (or with units:
        "0um,0um,2um,-2um"), 0 where the normal force is 0.
    indenter, body : str or (E, nu)
        Named materials of the package's table (``contactlib.model.materials``), or moduli in
        Pa (or with units) with Poisson's ratios; the indenter may be ``"rigid"``.
    friction : float
        k > 0.
    geometry : {"cylinder", "sphere"}
        The sphere: a coupled pair (Dundurs beta != 0) with ``|beta| <= 0.5`` under
        ``|Q| <= 0.9 k P`` with ``n <= 64`` only, as for :func:`contactlib.fretting`.
    steps, n, max_error, progress
        As for :func:`contactlib.fretting` (defaults per geometry).
    bulk_stress : sequence or str, optional
        The body's bulk stress along x [Pa] (or with units) at the same points.
    tangential_displacement : bool
        The sphere: ``tangential_path`` prescribes the shift (a displacement-controlled
        test) and the tangential force is the answer, as for :func:`contactlib.fretting`;
        the cylinder refuses it.

    Returns
    -------
    PhysicalFretting

    Raises
    ------
    ValueError
        Naming the argument, for input the physical door or :func:`contactlib.fretting`
        refuses.
    """
    prob = physical_problem(geometry, radius, indenter, body, length, None, "smooth")
    forces = parse_force_path(load_path, "load_path")
    tangential = parse_signed_path(tangential_path,
                                   "length" if tangential_displacement else "force",
                                   "tangential_path")
    if len(tangential) != len(forces):
        raise validate.InputError("tangential_path", f"as long as load_path ({len(forces)} "
                                  "points)", tangential_path)
    k = float(friction)
    load_max = max(forces)
    a_max = contact_radius_of_load(prob.geometry, prob.e_star, prob.radius,
                                   load_max / prob.length)
    p0 = hertz_peak_pressure(prob.geometry, prob.e_star, prob.radius, a_max)
    kwargs: dict[str, Any] = {}
    if bulk_stress is not None:
        stress = parse_signed_path(bulk_stress, "modulus", "bulk_stress")
        if len(stress) != len(forces):
            raise validate.InputError("bulk_stress", f"as long as load_path ({len(forces)} "
                                      "points)", bulk_stress)
        kwargs["bulk_stress"] = [s / p0 for s in stress]
    if not (math.isfinite(k) and k > 0):
        raise validate.InputError("friction", "a finite coefficient k > 0", friction)
    kwargs.update(prob.dimensionless())
    shift_unit = prob.displacement_unit(a_max)  # a_max^2/R
    res = fretting(prob.geometry, prob.body.nu, k, [f / load_max for f in forces],
                   [t / shift_unit for t in tangential] if tangential_displacement
                   else [q / (k * load_max) for q in tangential], steps, n=n,
                   max_error=max_error, progress=progress,
                   tangential_displacement=tangential_displacement, **kwargs)
    notes = validity_notes(prob, a_max)
    heading = prob.describe()
    return PhysicalFretting(result=res, radius=prob.radius, length=prob.length,
                            composite_modulus=prob.e_star, a_max=a_max, p0=p0,
                            load_max=load_max,
                            work_unit=prob.work_unit(a_max) * prob.length,
                            heading=heading, notes=notes,
                            shift_unit=shift_unit)

