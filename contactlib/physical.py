r"""Physical units in and out: the one place where contactlib converts to and from SI.

The solvers (:func:`contactlib.solve`, :func:`contactlib.history`) work in the
dimensionless scalings of ``docs/conventions.md``. This module takes a
physical problem (radius in m, force in N, materials by name or as E in Pa
and nu), calls them, and reports in SI with the error estimate of each
number. Every conversion of the package lives here:

=================  ==============================  ================================
quantity           sphere                          cylinder (per unit length)
=================  ==============================  ================================
E*                 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (E1 = inf: rigid indenter)
p0                 2 E* a / (pi R)                 E* a / (2 R)
P_Hertz(a)         4 E* a^3 / (3 R)                pi E* a^2 / (4 R)  [N/m]
a of a load P      (3 P R / (4 E* L))^(1/3)        (4 P R / (pi E* L))^(1/2)
approach delta     (delta R / a^2) a^2 / R         (delta R / a^2) a^2 / R (layer only)
work V             W E* a^5 / R^2                  W E* a^4 / R^2 per unit length
=================  ==============================  ================================

with L = P / P_Hertz(a), the load ratio the self-similar solver returns for
the stick ratio c/a (it depends on c/a, nu and the pair only, not on a, on
the half-space and half-plane), so that the contact radius of a given force
follows by inverting P = L P_Hertz(a). On a layer of given thickness h the
ratio a/h is unknown until a is: it is found by iterating a = a(L(a/h)).
A history's length scale is a_max, the frictionless Hertz radius at the
largest force of the path (:mod:`contactlib.history_api`).

The approach of a cylinder on a half-plane is not defined (the half-plane's
normal displacement holds an arbitrary additive constant, the Flamant
reference length), so it is NaN there; on a layer it is measured from the
rigid base.

Validity: the theory is linear elasticity with small strains and the
parabolic (Hertz) profile, z = r^2/(2R). This module warns
(:class:`SmallStrainWarning`, and a line of the summary) where a/R exceeds
:data:`SMALL_STRAIN_LIMIT` = 0.1: there the parabola is off the circle by
(a/R)^2/4 = 0.25 % of the gap at the contact edge, and the contact strains,
of order a/R (the mean strain under the indenter is about 0.2 a/R), are no
longer small against 1, so that the geometric nonlinearity of the large
deformation theory, of relative size O(a/R), reaches the percent level.

Examples
--------
The steel ball on glass of issue 40 (R = 5 mm, 100 N, k = 0.2):

>>> from contactlib.physical import physical_solve
>>> res = physical_solve("sphere", "5mm", "100N", "steel", "soda_lime_glass",
...                      friction=0.2, n=64)
>>> round(res.contact_radius * 1e3, 3), round(res.stick_radius * 1e3, 3)  # mm
(0.188, 0.169)
"""

from __future__ import annotations

import math
import re
import warnings
from dataclasses import dataclass, field
from typing import Any, Callable, Sequence

import numpy as np

from .model import profiles
from . import validate
from .model.profiles import PARABOLOID, Profile

__all__ = ["physical_solve", "physical_history", "PhysicalSolution", "PhysicalHistory",
           "Material", "material", "composite_modulus", "parse_quantity", "parse_force_path",
           "hertz_peak_pressure", "hertz_load", "hertz_radius", "contact_radius_of_load",
           "work_scale", "check_history", "SMALL_STRAIN_LIMIT", "SmallStrainWarning",
           "UNITS", "format_si", "PHYSICAL_PROFILES", "HALF_ANGLE_RANGE", "parse_half_angle",
           "PhysicalProblem", "physical_problem"]

# convention: the usual bound of the small-strain Hertz theory, a/R <= 0.1 (a warning, not a
# refusal)
SMALL_STRAIN_LIMIT = 0.1
"""Largest a/R (a_max/R in a history) reported without a warning (see the module notes)."""

# convention: a strip at most a tenth of the cylinder's length counts as plane strain (a warning,
# not a refusal)
PLANE_STRAIN_LIMIT = 0.1
"""Largest a/length of a cylinder reported without a warning (plane strain needs a long
contact: the strip's half-width small against its length)."""

PHYSICAL_PROFILES = ("paraboloid", "cone")
"""The profiles :func:`physical_solve` takes: Hertz's paraboloid (``radius`` R) and the
cone or wedge (``half_angle``)."""

# convention: open bounds of the cone's half-angle in degrees (0: a needle; 90: a flat face)
HALF_ANGLE_RANGE = (0.0, 90.0)
"""The cone's half-angle alpha [degrees], exclusive bounds."""

DEFAULT_HISTORY_STEPS = validate.HISTORY_DEFAULT_STEPS
"""Load steps a segment of a physical history when none are given (the default n = 240
and 200 steps give the work of a cycle to about 1 %; docs/accuracy.md, "History")."""


class SmallStrainWarning(UserWarning):
    """The contact is too large for the small-strain, parabolic-profile theory."""


# ----------------------------------------------------------------------------- units
# exact: SI factors of the unit suffixes
UNITS: dict[str, dict[str, float]] = {
    "length": {"m": 1.0, "cm": 1e-2, "mm": 1e-3, "um": 1e-6, "µm": 1e-6, "μm": 1e-6,
               "nm": 1e-9},
    "force": {"N": 1.0, "kN": 1e3, "MN": 1e6, "mN": 1e-3, "uN": 1e-6, "µN": 1e-6,
              "μN": 1e-6},
    "modulus": {"Pa": 1.0, "kPa": 1e3, "MPa": 1e6, "GPa": 1e9},
    "time": {"s": 1.0, "ms": 1e-3, "us": 1e-6, "µs": 1e-6, "μs": 1e-6, "min": 60.0,
             "h": 3600.0},
    "frequency": {"Hz": 1.0, "kHz": 1e3, "mHz": 1e-3},
}
"""Unit suffixes accepted for each kind of quantity, with their factor to SI (m, N, Pa, s,
Hz)."""

_SI = {"length": "m", "force": "N", "modulus": "Pa", "time": "s", "frequency": "Hz"}
_QUANTITY = re.compile(r"^\s*([+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?)"
                       r"\s*([A-Za-zµμ]*)\s*$")


def _requirement(kind: str, lo: str) -> str:
    units = ", ".join(dict.fromkeys(u for u in UNITS[kind] if u.isascii()))
    return f"a {lo} {kind} in {_SI[kind]} or a number with a unit ({units})"


def parse_quantity(value: Any, kind: str, name: str, *, positive: bool = True) -> float:
    """A physical quantity in SI: a number (already SI) or a string with a unit suffix.

    Parameters
    ----------
    value : float or str
        ``0.005``, ``"5mm"``, ``"5 mm"``, ``"210GPa"``, ``"100N"``, ``"2um"``.
        A string without a unit is taken in SI (m, N, Pa, s).
    kind : {"length", "force", "modulus", "time", "frequency"}
        Which units apply (:data:`UNITS`).
    name : str
        The argument's name, for the error.
    positive : bool
        Require > 0 (else >= 0).

    Returns
    -------
    float
        The value in m, N, Pa or s.

    Raises
    ------
    validate.InputError
        Naming ``name``: an unknown unit, a unit of another kind, a value that
        is not a finite number, or one out of range.

    Examples
    --------
    >>> parse_quantity("5mm", "length", "radius")
    0.005
    >>> parse_quantity("210GPa", "modulus", "E")
    210000000000.0
    """
    req = _requirement(kind, "positive" if positive else "non-negative")
    if isinstance(value, str):
        match = _QUANTITY.match(value)
        if not match:
            raise validate.InputError(name, req, value)
        number, unit = float(match.group(1)), match.group(2)
        if unit and unit not in UNITS[kind]:
            other = [k for k, table in UNITS.items() if unit in table]
            why = f" ({unit!r} is a unit of {other[0]})" if other else f" (unknown unit {unit!r})"
            raise validate.InputError(name, req, value,
                                      f"{name} must be {req}, got {value!r}{why}")
        v = number * (UNITS[kind][unit] if unit else 1.0)
    elif isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise validate.InputError(name, req, value)
    else:
        v = float(value)
    if not math.isfinite(v) or v < 0 or (positive and v == 0):
        raise validate.InputError(name, req, value)
    return v


def parse_force_path(value: Any, name: str = "load_path") -> tuple[float, ...]:
    """A path of forces in N: a sequence (numbers in N or strings with units) or a string
    ``"0N,100N,0N"``; at least two, each >= 0, starting at 0, with a largest > 0."""
    req = "a list of at least two forces >= 0 (N, or with a unit), starting at 0, not all 0"
    items = value.split(",") if isinstance(value, str) else value
    if isinstance(items, (bytes, dict)) or not hasattr(items, "__iter__"):
        raise validate.InputError(name, req, value)
    forces = tuple(parse_quantity(v, "force", name, positive=False) for v in items)
    if len(forces) < 2 or forces[0] != 0.0 or max(forces) <= 0.0:
        raise validate.InputError(name, req, value)
    return forces


def format_si(value: float, unit: str, digits: int = 4) -> str:
    """``value`` with an engineering prefix: ``1.8815e-4, "m"`` -> ``"188.2 µm"``."""
    if not math.isfinite(value):
        return f"{value} {unit}"
    if value == 0.0:
        return f"0 {unit}"
    prefixes = {-12: "p", -9: "n", -6: "µ", -3: "m", 0: "", 3: "k", 6: "M", 9: "G", 12: "T"}
    exp3 = int(math.floor(math.log10(abs(value)) / 3.0) * 3)
    exp3 = max(-12, min(12, exp3))
    return f"{value / 10.0 ** exp3:.{digits}g} {prefixes[exp3]}{unit}"


# ----------------------------------------------------------------------------- materials
@dataclass(frozen=True)
class Material:
    """An isotropic elastic material: Young's modulus E [Pa] (inf: rigid) and nu."""

    name: str
    E: float
    nu: float
    source: str = ""

    @property
    def rigid(self) -> bool:
        return self.E == math.inf

    @property
    def plane_modulus(self) -> float:
        """E / (1 - nu^2) [Pa] (inf when rigid)."""
        return math.inf if self.rigid else self.E / (1.0 - self.nu ** 2)

    def __str__(self) -> str:
        if self.rigid:
            return "rigid"
        return f"{self.name} (E = {format_si(self.E, 'Pa')}, nu = {self.nu:g})"


def material(value: Any, role: str = "body") -> Material:
    """A material from the package table, ``"rigid"`` (indenter only), or (E [Pa], nu).

    Parameters
    ----------
    value : str or (E, nu)
        A name of :func:`contactlib.model.materials.materials`; ``"rigid"`` for the
        indenter; a pair (E, nu) with E in Pa (a number or a string with a
        unit, ``"210GPa"``), or the same as a string ``"210GPa,0.3"``.
    role : {"indenter", "body"}
        The argument's name, for the error.

    Raises
    ------
    validate.InputError
        Naming ``role``: unknown name, "rigid" for the body, bad E or nu.
    """
    from .model import materials as table_module

    if isinstance(value, Material):
        if value.rigid and role != "indenter":
            raise validate.InputError(role, "an elastic material (not rigid)", value.name)
        return value
    table = table_module.materials()
    if isinstance(value, str) and "," not in value:
        key = value.strip()
        if key == "rigid" and role == "indenter":
            return Material("rigid", math.inf, math.nan, "")
        if key in table:
            entry = table[key]
            source = "; ".join(map(str, entry.get("source", [])))
            return Material(key, float(entry["E"]) * 1e9, float(entry["nu"]), source)
        names = ("rigid, " if role == "indenter" else "") + ", ".join(table)
        raise validate.InputError(role, f"one of {names}, or E,nu (e.g. 210GPa,0.3)", value)
    items = value.split(",") if isinstance(value, str) else value
    try:
        e_value, nu_value = list(items)
    except (TypeError, ValueError):
        raise validate.InputError(role, "a material name or a pair E,nu (e.g. 210GPa,0.3)",
                                  value) from None
    modulus = parse_quantity(e_value.strip() if isinstance(e_value, str) else e_value,
                             "modulus", role)
    if isinstance(nu_value, str):
        try:
            nu_value = float(nu_value)
        except ValueError:
            pass
    try:
        nu = validate.nu(nu_value)
    except validate.InputError:
        raise validate.InputError(role, "a pair E,nu with nu in (-1, 0.5]", value) from None
    return Material("E,nu", modulus, nu, "given")


def composite_modulus(indenter: Material, body: Material) -> float:
    """E* [Pa]: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (a rigid indenter adds nothing)."""
    compliance = 1.0 / body.plane_modulus
    if not indenter.rigid:
        compliance += 1.0 / indenter.plane_modulus
    return 1.0 / compliance


# ----------------------------------------------------------------------------- Hertz scales
def hertz_peak_pressure(geometry: str, e_star: float, radius: float, a: float) -> float:
    """p0 [Pa] at contact radius (half-width) a: 2E*a/(pi R) or E*a/(2R)."""
    return 2.0 * e_star * a / (math.pi * radius) if geometry == "sphere" else \
        e_star * a / (2.0 * radius)


def hertz_load(geometry: str, e_star: float, radius: float, a: float) -> float:
    """P_Hertz(a): 4E*a^3/(3R) [N] (sphere) or pi E* a^2/(4R) [N/m] (cylinder)."""
    return 4.0 * e_star * a ** 3 / (3.0 * radius) if geometry == "sphere" else \
        math.pi * e_star * a ** 2 / (4.0 * radius)


def contact_radius_of_load(geometry: str, e_star: float, radius: float, load: float,
                           load_ratio: float = 1.0) -> float:
    """a [m] with load = load_ratio P_Hertz(a); load in N (sphere) or N/m (cylinder).

    Sphere: a = (3 P R / (4 E* L))^(1/3); cylinder: a = (4 P R / (pi E* L))^(1/2).
    """
    if geometry == "sphere":
        return (3.0 * load * radius / (4.0 * e_star * load_ratio)) ** (1.0 / 3.0)
    return math.sqrt(4.0 * load * radius / (math.pi * e_star * load_ratio))


hertz_radius = contact_radius_of_load
"""The frictionless (L = 1) contact radius of a load: the same function."""


def work_scale(geometry: str, e_star: float, radius: float, a: float) -> float:
    """The work unit E* a^5/R^2 [J] (sphere) or E* a^4/R^2 [J/m] (cylinder)."""
    power = 5 if geometry == "sphere" else 4
    return e_star * a ** power / radius ** 2


# ----------------------------------------------------------------------------- problem
@dataclass(frozen=True)
class PhysicalProblem:
    """A checked problem in SI, made by :func:`physical_problem`: the bodies' materials,
    the profile with its SI parameter, and the scales at a contact radius.

    ``radius`` R [m] is the paraboloid's (NaN for the cone), ``half_angle`` alpha
    [degrees] the cone's (NaN for the paraboloid); ``slope`` is A d of the profile
    z = A r^d in both cases (1/R, cot alpha), so that every scale below is one formula
    for every profile.
    """

    geometry: str
    radius: float
    indenter: Material
    body: Material
    e_star: float
    length: float  # m; 1.0 for the sphere (a per-length quantity times 1)
    thickness: float  # m; inf on the half-space / half-plane
    base: str
    substrate: Material | None = None  # a coated body's substrate (base "elastic")
    shape: Profile = PARABOLOID  # the indenter's profile (paraboloid: z = r^2/(2R))
    slope: float = math.nan  # A d of z = A r^d [m^(1-d)]: 1/R, or cot(alpha) for the cone
    half_angle: float = math.nan  # the cone's (wedge's) half-angle alpha [degrees]

    def describe(self) -> str:
        """``sphere R = 5 mm: indenter ..., body ...`` (the cone: its half-angle; the layer
        and the substrate where there are any)."""
        if self.shape.is_paraboloid:
            shape = f"{self.geometry} R = {format_si(self.radius, 'm')}"
        else:
            shape = (f"{'cone' if self.geometry == 'sphere' else 'wedge'}, half-angle "
                     f"{self.half_angle:g} deg")
        if self.geometry == "cylinder":
            shape += f", length {format_si(self.length, 'm')}"
        layer = "" if self.thickness == math.inf else \
            f", layer h = {format_si(self.thickness, 'm')} ({self.base} base)"
        if self.substrate is not None:
            layer += f" on substrate {self.substrate}"
        return f"{shape}: indenter {self.indenter}, body {self.body}{layer}"

    @property
    def reference_name(self) -> str:
        """The frictionless solution the load is compared with: ``"Hertz"`` for the
        paraboloid, ``"frictionless"`` (Love's cone, Sneddon's wedge) otherwise."""
        return "Hertz" if self.shape.is_paraboloid else "frictionless"

    @property
    def per_length(self) -> float:
        """Divisor of a total force into the solver's load: the length (cylinder) or 1."""
        return self.length

    def dimensionless(self) -> dict[str, Any]:
        """The material keywords of the dimensionless API."""
        kwargs: dict[str, Any] = {}
        if not self.indenter.rigid:
            kwargs["indenter_modulus"] = self.indenter.E / self.body.E
            kwargs["indenter_nu"] = self.indenter.nu
        if self.thickness != math.inf and self.base != "smooth":
            kwargs["base"] = self.base
        if self.substrate is not None:  # E2/E1 over the coating's E, nu2
            kwargs["substrate_modulus"] = self.substrate.E / self.body.E
            kwargs["substrate_nu"] = self.substrate.nu
        if not self.shape.is_paraboloid:
            kwargs["profile"] = self.shape.name
        return kwargs

    # the scales at a contact radius a [m]; the paraboloid's are Hertz's functions (below),
    # a profile z = A r^d scales lengths normal to the surface by A d a^d (a^2/R)
    def displacement_unit(self, a: float) -> float:
        """The unit of the approach and the tangential displacements [m]: a^2/R, A d a^d."""
        if self.shape.is_paraboloid:
            return a ** 2 / self.radius
        return self.slope * a ** self.shape.exponent

    def load_unit(self, a: float) -> float:
        """The profile's frictionless load at contact radius a [N, N/m for the cylinder]:
        P_Hertz(a) for the paraboloid (:func:`hertz_load`)."""
        if self.shape.is_paraboloid:
            return hertz_load(self.geometry, self.e_star, self.radius, a)
        axi = self.geometry == "sphere"
        return (self.shape.frictionless_load(axi) * self.e_star
                * self.displacement_unit(a) * (a if axi else 1.0))

    def pressure_unit(self, a: float) -> float:
        """The pressure unit at contact radius a [Pa]: Hertz's p0 for the paraboloid, else
        the peak pressure of the paraboloid carrying the same frictionless load."""
        if self.shape.is_paraboloid:
            return hertz_peak_pressure(self.geometry, self.e_star, self.radius, a)
        axi = self.geometry == "sphere"
        return self.shape.reference_pressure(axi) * self.e_star * self.displacement_unit(a) / a

    def radius_of_load(self, load: float, load_ratio: float = 1.0) -> float:
        """a [m] at which ``load`` [N, N/m] is ``load_ratio`` times the frictionless load."""
        if self.shape.is_paraboloid:
            return contact_radius_of_load(self.geometry, self.e_star, self.radius, load,
                                          load_ratio)
        axi = self.geometry == "sphere"
        d = self.shape.exponent
        unit = self.shape.frictionless_load(axi) * self.e_star * self.slope * load_ratio
        return (load / unit) ** (1.0 / (d + 1.0 if axi else d))

    def work_unit(self, a: float) -> float:
        """The work unit at contact radius a [J, J/m]: E* a^5/R^2 (sphere) or E* a^4/R^2,
        E* (A d a^d)^2 a or E* (A d a^d)^2."""
        if self.shape.is_paraboloid:
            return work_scale(self.geometry, self.e_star, self.radius, a)
        return (self.e_star * self.displacement_unit(a) ** 2
                * (a if self.geometry == "sphere" else 1.0))

    def edge_slope(self, a: float) -> float:
        """The profile's slope at the contact edge, the strain's order: a/R, A d a^(d-1)."""
        return self.displacement_unit(a) / a


def physical_problem(geometry: Any, radius: Any, indenter: Any, body: Any, length: Any,
                     thickness: Any, base: Any, substrate: Any = None,
                     profile: str = "paraboloid", half_angle: Any = None) -> PhysicalProblem:
    """The checked problem; ``substrate`` (a material) only with ``base="elastic"`` (a
    coated body: ``body`` the coating, of ``thickness`` h), E2/E1 in
    :data:`contactlib.validate.SUBSTRATE_MODULUS_RANGE`. ``profile`` is ``"paraboloid"``
    (z = r^2/(2R), ``radius`` R) or ``"cone"`` (a wedge for the cylinder: z = r cot(alpha),
    ``half_angle`` alpha in degrees, no ``radius``)."""
    geometry = validate.geometry(geometry)
    shape = profiles.profile(validate.choice("profile", profile, PHYSICAL_PROFILES))
    if shape.is_paraboloid:
        if half_angle is not None:
            raise validate.InputError("half_angle", "given only for the cone (profile "
                                      "'cone')", half_angle)
        r = parse_quantity(radius, "length", "radius")
        slope, alpha = 1.0 / r, math.nan
    else:
        if radius is not None:
            raise validate.InputError("radius", "omitted for the cone (its half_angle gives "
                                      "the profile)", radius)
        alpha = parse_half_angle(half_angle)
        r, slope = math.nan, 1.0 / math.tan(math.radians(alpha))
    ind = material(indenter, "indenter")
    bod = material(body, "body")
    if geometry == "cylinder":
        if length is None:
            raise validate.InputError("length", "given for a cylinder (its length in m; "
                                      "forces are divided by it)", length)
        ell = parse_quantity(length, "length", "length")
    else:
        if length is not None:
            raise validate.InputError("length", "given only for a cylinder", length)
        ell = 1.0
    h = math.inf if thickness is None else parse_quantity(thickness, "length", "thickness")
    base = validate.base(base, coated=True)
    sub = _substrate(base, substrate, bod, h)
    return PhysicalProblem(geometry, r, ind, bod, composite_modulus(ind, bod), ell, h, base,
                           sub, shape, slope, alpha)


def parse_half_angle(value: Any) -> float:
    """The cone's half-angle alpha in degrees, in :data:`HALF_ANGLE_RANGE` (open)."""
    lo, hi = HALF_ANGLE_RANGE
    req = f"the cone's half-angle in degrees, {lo:g} < alpha < {hi:g}"
    if value is None:
        raise validate.InputError("half_angle", req, value, "half_angle is required for "
                                  "the cone: its half-angle alpha in degrees (70.3 for the "
                                  "cone of a Berkovich tip's area)")
    text = value.strip().removesuffix("deg").strip() if isinstance(value, str) else value
    try:
        alpha = float(text)
    except (TypeError, ValueError):
        raise validate.InputError("half_angle", req, value) from None
    if not (math.isfinite(alpha) and lo < alpha < hi):
        raise validate.InputError("half_angle", req, value)
    return alpha


def _shown(value: Any) -> str:
    """A material as the user named it (a :class:`Material` by its text), else its repr."""
    return str(value) if isinstance(value, Material) else repr(value)


def _substrate(base: str, substrate: Any, body: Material, thickness: float) -> Material | None:
    """The substrate material of a coated body (None on any other body), its E2/E1 checked."""
    if base != validate.COATED_BASE:
        if substrate is not None:
            raise validate.InputError("substrate", "given only with base 'elastic'", substrate,
                                      f"substrate needs base='elastic' (a coated body), not "
                                      f"base={base!r}: a rigid base carries no substrate "
                                      f"material, got {_shown(substrate)}")
        return None
    if substrate is None:
        raise validate.InputError("base", "given with a substrate", base,
                                  "base 'elastic' (a coated body) is not available without a "
                                  "substrate: give substrate (its material, a name or E,nu) "
                                  "and the coating's thickness")
    if thickness == math.inf:
        raise validate.InputError("thickness", "given with base 'elastic'", None,
                                  "thickness (the coating's, in m) is required with "
                                  "base='elastic'")
    sub = material(substrate, "substrate")
    lo, hi = validate.SUBSTRATE_MODULUS_RANGE
    ratio = sub.E / body.E
    if not lo <= ratio <= hi:
        raise validate.InputError("substrate", f"E2/E1 in [{lo:g}, {hi:g}]", substrate,
                                  f"substrate {sub} over body {body}: E2/E1 = {ratio:.3g} is "
                                  f"outside [{lo:g}, {hi:g}], the verified range of a coated "
                                  f"body")
    return sub


def validity_notes(problem: PhysicalProblem, a: float) -> list[str]:
    """Warnings (issued, and returned as lines) where the contact leaves the theory."""
    notes = []
    if problem.shape.is_paraboloid and a / problem.radius > SMALL_STRAIN_LIMIT:
        notes.append(f"a/R = {a / problem.radius:.3g} exceeds the small-strain limit "
                     f"{SMALL_STRAIN_LIMIT:g} (parabolic profile, linear elasticity): the "
                     f"results are outside the theory's validity")
    elif not problem.shape.is_paraboloid and problem.edge_slope(a) > SMALL_STRAIN_LIMIT:
        notes.append(f"cot(alpha) = {problem.edge_slope(a):.3g} exceeds the small-strain "
                     f"limit {SMALL_STRAIN_LIMIT:g} (linear elasticity; Sneddon's cone "
                     f"neglects the surface's radial displacement, an error of this order): "
                     f"the results are outside the theory's validity at that order")
    if problem.geometry == "cylinder" and a / problem.length > PLANE_STRAIN_LIMIT:
        notes.append(f"a/length = {a / problem.length:.3g} exceeds {PLANE_STRAIN_LIMIT:g}: "
                     "plane strain needs a contact long against its width")
    for note in notes:
        warnings.warn(note, SmallStrainWarning, stacklevel=3)
    return notes


# ----------------------------------------------------------------------------- solve
@dataclass(repr=False)
class _Setup:
    """The physical problem shared by both results (see :class:`PhysicalSolution`)."""

    geometry: str
    radius: float
    length: float
    thickness: float
    base: str
    indenter: Material
    body: Material
    composite_modulus: float
    substrate: Material | None

    def scales(self) -> PhysicalProblem:
        """The problem behind the result, whose methods give its scales at a contact radius
        (``load_unit``, ``pressure_unit``, ``displacement_unit``, ``work_unit``)."""
        return self.problem

    def _head(self) -> str:
        """``sphere R = 5 mm: indenter ..., body ...`` (and the layer)."""
        return self.problem.describe()


@dataclass(repr=False)
class PhysicalSolution(_Setup):
    """A self-similar loading to a normal force, in SI (m, Pa, N, J).

    Attributes
    ----------
    geometry : str
    radius, length, thickness : float
        R [m]; the cylinder's length [m] (1 for the sphere); the layer's
        thickness h [m] (inf on the half-space / half-plane).
    indenter, body : Material
    composite_modulus : float
        E* [Pa].
    load : float
        The normal force P [N] (a cylinder's over its whole length).
    friction : float
        k (given, or the result of a given stick ratio).
    contact_radius, stick_radius : float
        a and c [m] (the cylinder's half-widths).
    peak_pressure, mean_pressure : float
        max p and P / (pi a^2) (sphere) or P / (2 a length) (cylinder) [Pa].
    approach : float
        delta [m]: sphere; cylinder on a layer only (NaN on a half-plane).
    load_ratio : float
        P / P_Hertz(a).
    frictional_energy : float
        Work of friction during the loading 0 -> P [J] (a cylinder's over its length).
    hertz_contact_radius : float
        The frictionless a of the same force on the half-space [m].
    p0, hertz_load : float
        Hertz peak pressure [Pa] and Hertz load [N] at the computed a; for the cone, the
        pressure unit (the peak pressure of the paraboloid carrying the same frictionless
        load) and the cone's frictionless load (Love).
    slab_ratio : float
        a/h of the layer (0: half-space).
    profile : str
        ``"paraboloid"`` or ``"cone"`` (the wedge for the cylinder).
    half_angle : float
        The cone's half-angle alpha [degrees] (NaN for the paraboloid; ``radius`` is NaN
        for the cone).
    problem : PhysicalProblem
        The checked problem it solved; ``scales()`` returns it.
    errors : dict
        Estimated relative error of each quantity above, by name (see
        :func:`physical_solve`); 0 where exact, NaN where not estimated.
    notes : list of str
        The validity warnings.
    solution : contactlib.Solution
        The dimensionless solution behind it (its ``resolved`` and
        ``message`` apply unchanged).
    """

    load: float
    friction: float
    contact_radius: float
    stick_radius: float
    peak_pressure: float
    mean_pressure: float
    approach: float
    load_ratio: float
    frictional_energy: float
    hertz_contact_radius: float
    p0: float
    hertz_load: float
    slab_ratio: float
    errors: dict[str, float]
    notes: list[str]
    solution: Any
    profile: str = "paraboloid"
    half_angle: float = math.nan
    problem: PhysicalProblem | None = field(default=None, repr=False, compare=False)

    @property
    def resolved(self) -> bool:
        return bool(self.solution.resolved)

    def profiles(self) -> dict[str, np.ndarray]:
        """Profiles in physical coordinates on the solution's 201 points 0 ... a.

        Returns
        -------
        dict
            ``r`` (x for the cylinder) [m], ``pressure`` p and ``shear`` q
            [Pa] (q on the body, positive away from the axis),
            ``tangential_displacement`` u [m].
        """
        sol = self.solution
        a = self.contact_radius
        unit = self.scales().displacement_unit(a)  # a^2/R, a cot(alpha)
        return {"r": np.asarray(sol.xi) * a,
                "pressure": np.asarray(sol.pressure) * self.p0,
                "shear": np.asarray(sol.shear) * self.p0,
                "tangential_displacement": np.asarray(sol.tangential_displacement) * unit}

    def summary(self) -> str:
        """The answer with units and the estimated relative error of each number."""
        e = self.errors
        c_over_a = self.solution.stick_ratio

        def row(label: str, value: str, name: str | None = None) -> str:
            err = e.get(name, math.nan) if name else math.nan
            if name and getattr(self, name, math.nan) == 0.0:  # zero: no relative error
                err = math.nan
            tail = f"   (estimated relative error {err:.1e})" if math.isfinite(err) and err > 0 \
                else ("   (exact)" if name and err == 0.0 else "")
            return f"  {label:<22}{value}{tail}"

        layer = "" if self.thickness == math.inf else f" (a/h = {self.slab_ratio:.4g})"
        lines = [
            self._head() + layer,
            f"  E* = {format_si(self.composite_modulus, 'Pa')}, P = "
            f"{format_si(self.load, 'N')}, k = {self.friction:.6g}",
            row("contact radius a", format_si(self.contact_radius, "m"), "contact_radius"),
            row("stick radius c", format_si(self.stick_radius, "m") +
                f" (c/a = {c_over_a:.6g})", "stick_radius"),
            row("peak pressure", format_si(self.peak_pressure, "Pa")
                if math.isfinite(self.peak_pressure) else "infinite at the tip (logarithmic)",
                "peak_pressure"),
            row("mean pressure", format_si(self.mean_pressure, "Pa"), "mean_pressure"),
            row("approach", format_si(self.approach, "m") if math.isfinite(self.approach)
                else "undefined on a half-plane", "approach"),
            row(f"P/P_{self.problem.reference_name}(a)",
                f"{self.load_ratio:.6g}", "load_ratio"),
            row("frictional energy", format_si(self.frictional_energy, "J") +
                " (loading 0 -> P)", "frictional_energy"),
            f"  {self.problem.reference_name}"
            f"{' (frictionless)' if self.problem.shape.is_paraboloid else ''} "
            f"a = {format_si(self.hertz_contact_radius, 'm')}, p0(a) = "
            f"{format_si(self.p0, 'Pa')}"
            + ("" if self.problem.shape.is_paraboloid else
               " (the paraboloid's peak pressure at this load)")
            + f"; resolved: {'yes' if self.resolved else 'no'} "
            f"(max error {self.solution.max_error:g})",
        ]
        lines += [f"  warning: {note}" for note in self.notes]
        if self.solution.message:
            lines.append(f"  message: {self.solution.message}")
        return "\n".join(lines)

    __str__ = summary

    def __repr__(self) -> str:
        return "PhysicalSolution:\n" + self.summary()


def _stick_ratio_error(sol: Any, model: Any, friction_given: bool) -> float:
    """Estimated absolute error of c/a: 0 for a given c/a; from k's relative error and the
    log-slope of k(c/a) of the uncoupled closed form where k was given."""
    gamma = float(sol.stick_ratio)
    if not friction_given or gamma in (0.0, 1.0) or model.decoupled:
        return 0.0
    err_k = float(sol.error_estimate)
    h = 1e-6 * min(gamma, 1.0 - gamma)
    k_lo, k_hi = model.uncoupled_friction(np.array([gamma - h, gamma + h]))
    slope = (math.log(k_hi) - math.log(k_lo)) / (2.0 * h)  # d ln k / d(c/a)
    return err_k / slope if slope > 0 else math.nan


def physical_solve(geometry: str, radius: float | str | None, load: float | str,
                   indenter: Any, body: Any, *, profile: str = "paraboloid",
                   half_angle: float | str | None = None, friction: float | None = None,
                   stick_ratio: float | None = None, length: float | str | None = None,
                   thickness: float | str | None = None, base: str = "smooth",
                   substrate: Any = None,
                   n: int | None = None, method: str | None = None,
                   tolerance: float | None = None,
                   max_error: float = validate.DEFAULT_MAX_ERROR,
                   energy: bool = True) -> PhysicalSolution:
    """Press an indenter to a normal force, self-similarly; the answer in SI.

    Parameters
    ----------
    geometry : {"sphere", "cylinder"}
        Axisymmetric, or plane strain (the cone is then a wedge).
    radius : float or str
        R, in m or with a unit (``"5mm"``); None for the cone.
    load : float or str
        The normal force P, in N or with a unit (``"100N"``); a cylinder's
        over its whole ``length``.
    profile : {"paraboloid", "cone"}
        The indenter's profile: z = r^2/(2R) (Hertz; default) or z = r cot(alpha)
        (Love's cone, Sneddon). The pressure unit is then the peak pressure of the
        paraboloid carrying the same frictionless load, ``p0`` and ``hertz_load`` are
        the cone's frictionless closed forms at a (P = (pi/2) E* a^2 cot(alpha), per unit
        length of the wedge E* a cot(alpha)), displacements are in units of a cot(alpha).
    half_angle : float or str, optional
        The cone's half-angle alpha in degrees (``70.3`` or ``"70.3deg"``), in
        :data:`HALF_ANGLE_RANGE`; only for the cone.
    indenter : str or (E, nu)
        A material name (:mod:`contactlib.model.materials`), ``"rigid"``, or (E [Pa], nu).
    body : str or (E, nu)
        The elastic body (the layer's material on a layer).
    friction, stick_ratio : float
        Exactly one: Coulomb's k (``inf``: full adhesion), or c/a.
    length : float or str
        The cylinder's length [m] (required for the cylinder, refused for the sphere).
    thickness : float or str, optional
        h [m] of an elastic layer on a rigid base, or of the coating of a coated
        body; None: half-space / half-plane. The self-similar solution holds at
        one a/h: a is found by iterating a/h = a(L(a/h))/h to 1e-12.
    base : {"smooth", "bonded", "elastic"}
        The layer's base; ``"elastic"``: a coated body, ``body`` (the coating, of
        ``thickness``) bonded to a half-space (half-plane) of ``substrate``.
    substrate : str or (E, nu), optional
        A coated body's substrate material (name or (E [Pa], nu)); only with
        ``base="elastic"`` (required there), E2/E1 of substrate over coating in
        [1e-2, 1e6]. The scalings (E*, p0, a_Hertz) are the coating's.
    n, method, tolerance, max_error, energy
        Passed to :func:`contactlib.solve`.

    Returns
    -------
    PhysicalSolution
        With ``errors``, the estimated relative error of each number, from the
        dimensionless estimates (``load_error_estimate`` eps_L, ``error_estimate``
        of k, ``work_error_estimate`` eps_W): a (1/3 eps_L sphere, 1/2 eps_L
        cylinder), c (that of a plus the c/a error, which is k's relative error
        over d ln k/d(c/a) of the uncoupled closed form where k was given; 0
        where c/a was given), peak pressure and approach (that of p0 or a^2 plus
        eps_L, the load's estimate standing for the profile's discretization
        error), mean pressure (2 or 1 times a's), work (5 or 4 times a's plus
        eps_W), P/P_Hertz (eps_L).

    Raises
    ------
    validate.InputError
        A ValueError naming the bad argument.

    Warns
    -----
    SmallStrainWarning
        Where a/R > :data:`SMALL_STRAIN_LIMIT` (or a cylinder's a/length > 0.1).
    """
    from . import api

    prob = physical_problem(geometry, radius, indenter, body, length, thickness, base, substrate,
                            profile, half_angle)
    force = parse_quantity(load, "force", "load")
    per_length = force / prob.per_length
    kwargs = dict(prob.dimensionless(), n=n, method=method, max_error=max_error,
                  energy=energy)
    if tolerance is not None:
        kwargs["tolerance"] = tolerance
    if friction is not None:
        kwargs["friction"] = friction
    if stick_ratio is not None:
        kwargs["stick_ratio"] = stick_ratio
    nu = prob.body.nu
    a_hertz = prob.radius_of_load(per_length)

    def run(slab: float) -> tuple[Any, float]:
        sol = api.solve(prob.geometry, nu, slab_ratio=slab, **kwargs)
        return sol, prob.radius_of_load(per_length, sol.load_ratio)

    if prob.thickness == math.inf:
        slab = 0.0
        sol, a = run(slab)
    else:
        slab, sol, a = _layer_radius(prob, a_hertz, run)
    g = prob.geometry
    p0 = prob.pressure_unit(a)
    eps_l = float(sol.load_error_estimate)
    d = prob.shape.exponent  # a ~ P^(1/(d + 1)) (sphere) or P^(1/d); units ~ a^d, a^(d - 1)
    err_a = eps_l / (d + 1.0 if g == "sphere" else d)
    err_gamma = _stick_ratio_error(sol, sol.model, friction is not None)
    gamma = float(sol.stick_ratio)
    delta = float(sol.extra.get("indentation", math.nan))
    approach = delta * prob.displacement_unit(a) if (g == "sphere" or slab > 0) else math.nan
    mean = force / (math.pi * a ** 2) if g == "sphere" else force / (2.0 * a * prob.length)
    work = float(sol.frictional_work) * prob.work_unit(a) * prob.per_length
    # the cone's pressure is logarithmically infinite at the tip: no finite peak
    peak = float(np.max(sol.pressure)) * p0 if d > 1.0 else math.inf
    errors = {
        "contact_radius": err_a,
        "stick_radius": err_a + (err_gamma / gamma if gamma > 0 else 0.0),
        "peak_pressure": err_a * (d - 1.0) + eps_l if d > 1.0 else math.nan,
        "mean_pressure": err_a * (2.0 if g == "sphere" else 1.0),
        "approach": d * err_a + eps_l if math.isfinite(approach) else math.nan,
        "load_ratio": eps_l,
        "frictional_energy": (float(sol.work_error_estimate)
                              + err_a * (2.0 * d + (1.0 if g == "sphere" else 0.0))),
        "friction": float(sol.error_estimate) if friction is None else 0.0,
    }
    return PhysicalSolution(
        geometry=g, radius=prob.radius, length=prob.length, thickness=prob.thickness,
        base=prob.base, indenter=prob.indenter, body=prob.body, substrate=prob.substrate,
        composite_modulus=prob.e_star, load=force, friction=float(sol.friction_coefficient),
        contact_radius=a, stick_radius=gamma * a,
        peak_pressure=peak, mean_pressure=mean,
        approach=approach, load_ratio=float(sol.load_ratio), frictional_energy=work,
        hertz_contact_radius=a_hertz, p0=p0,
        hertz_load=prob.load_unit(a) * prob.per_length,
        slab_ratio=slab, errors=errors, notes=validity_notes(prob, a), solution=sol,
        profile=prob.shape.name, half_angle=prob.half_angle, problem=prob)


def _layer_radius(prob: PhysicalProblem, a_hertz: float,
                  run: Callable[[float], tuple[Any, float]]) -> tuple[float, Any, float]:
    """(a/h, solution, a) on a layer of thickness h: the root of s = a(L(s))/h by secant
    steps from s = a_Hertz/h (a/h and a agree to 1e-12)."""
    hi = validate.LAYER_RATIO_MAX[(prob.geometry, prob.base)]

    def f(s: float) -> tuple[float, Any, float]:
        if s > hi:
            raise validate.InputError("thickness", f"thick enough that a/h <= {hi:g}",
                                      prob.thickness,
                                      f"thickness {prob.thickness!r} m is too thin: the "
                                      f"contact would reach a/h > {hi:g}, the supported range")
        sol, a = run(s)
        if not math.isfinite(a):
            raise validate.SolverLimit(f"thickness {prob.thickness!r}: no converged solution "
                                       f"at a/h = {s:.6g} ({sol.message})")
        return a / prob.thickness - s, sol, a

    s0 = a_hertz / prob.thickness
    r0, sol, a = f(s0)
    s1 = a / prob.thickness
    for _ in range(40):
        r1, sol, a = f(s1)
        if abs(r1) <= 1e-12 * max(s1, 1e-300):
            return s1, sol, a
        s0, s1 = s1, (s1 - r1 * (s1 - s0) / (r1 - r0)) if r1 != r0 else a / prob.thickness
        r0 = r1
        s1 = max(s1, 1e-12)
    raise validate.SolverLimit(f"thickness {prob.thickness!r}: the contact radius on the layer "
                               "did not converge")


# ----------------------------------------------------------------------------- history
@dataclass(repr=False)
class PhysicalHistory(_Setup):
    """A followed path of normal forces, in SI; per-step arrays have the steps' length.

    Attributes
    ----------
    geometry, radius, length, thickness, base, indenter, body, composite_modulus
        As for :class:`PhysicalSolution`; so are ``profile``, ``half_angle`` and
        ``problem``.
    load_path : tuple of float
        The path's forces [N].
    times : ndarray or None
        Time of each path point [s] (viscoelastic bodies).
    a_max, p0, max_load : float
        The length scale (frictionless Hertz a at the largest force) [m],
        the Hertz peak pressure there [Pa], the largest force [N].
    force, contact_radius, stick_radius, peak_pressure, approach : ndarray
        Per step: P [N], a [m], c [m] (NaN without contact), max p [Pa],
        delta [m] (NaN on a half-plane).
    stick_radius_error : ndarray
        Estimated absolute error of c [m].
    frictional_energy, viscous_energy : ndarray
        Cumulative dissipation [J] (viscous: 0 for an elastic body).
    energy_error : ndarray
        Estimated relative error of ``frictional_energy``.
    time : ndarray or None
        Time at each step [s] (viscoelastic only).
    cycles : list of (int, int)
        Path points that start and end each cycle: a cycle ends where the
        force, having decreased, turns up again, or at the end of the path.
    cycle_frictional_energy, cycle_energy_error, cycle_viscous_energy : ndarray
        Per cycle: the frictional energy [J], its estimated absolute error [J],
        the viscous energy [J].
    segment_frictional_energy : ndarray
        Per path segment [J]; the first of a path from 0 is the loading half-cycle.
    notes : list of str
    result : HistoryResult
        The dimensionless history behind it.
    """

    friction: float
    load_path: tuple[float, ...]
    times: np.ndarray | None
    a_max: float
    p0: float
    max_load: float
    slab_ratio: float
    force: np.ndarray
    contact_radius: np.ndarray
    stick_radius: np.ndarray
    stick_radius_error: np.ndarray
    peak_pressure: np.ndarray
    approach: np.ndarray
    frictional_energy: np.ndarray
    energy_error: np.ndarray
    viscous_energy: np.ndarray
    time: np.ndarray | None
    cycles: list[tuple[int, int]]
    cycle_frictional_energy: np.ndarray
    cycle_energy_error: np.ndarray
    cycle_viscous_energy: np.ndarray
    segment_frictional_energy: np.ndarray
    notes: list[str]
    result: Any
    profile: str = "paraboloid"
    half_angle: float = math.nan
    problem: PhysicalProblem | None = field(default=None, repr=False, compare=False)

    @property
    def hertz_load(self) -> float:
        """P_Hertz(a_max) [N] = the largest force of the path (the cone's frictionless
        load at a_max, for the cone)."""
        return self.max_load

    def load_ratio_hertz(self, step: int) -> float:
        """P / P_Hertz(a) at a step, a the computed contact radius there (over the cone's
        frictionless load at a, for the cone)."""
        a = float(self.contact_radius[step])
        if a <= 0:
            return math.nan
        return float(self.force[step]) / (self.scales().load_unit(a) * self.length)

    def profiles(self, step: int) -> dict[str, np.ndarray]:
        """Profiles at a step: ``r`` [m] (element midpoints), ``pressure``, ``shear`` [Pa],
        ``tangential_displacement`` [m]."""
        r = self.result
        return {"r": np.asarray(r.xi) * self.a_max,
                "pressure": np.asarray(r.pressure[step]) * self.p0,
                "shear": np.asarray(r.shear[step]) * self.p0,
                "tangential_displacement": np.asarray(r.tangential_displacement[step])
                * self.scales().displacement_unit(self.a_max)}

    def summary(self) -> str:
        """The path's state at each segment end, and the energy of each cycle, with units."""
        res = self.result
        lines = [self._head(),
                 f"  E* = {format_si(self.composite_modulus, 'Pa')}, k = {self.friction:g}, "
                 f"a_max = {format_si(self.a_max, 'm')} "
                 f"({self.problem.reference_name} at "
                 f"{format_si(self.max_load, 'N')}), p0(a_max) = {format_si(self.p0, 'Pa')}, "
                 f"n = {res.n}, {res.steps} steps a "
                 f"{'load travel of P_max' if res.segment_steps else 'segment'}",
                 f"  {'point':>5} {'P':>10} {'a':>11} {'c':>11} {'p_max':>11} "
                 f"{'P/P_' + self.problem.reference_name[0] + '(a)':>9} "
                 f"{'E_friction':>11}"]
        for i in range(len(self.load_path)):
            j = res.segment_end(i) if i else 0
            c = float(self.stick_radius[j])
            lines.append(f"  {i:5d} {format_si(float(self.force[j]), 'N'):>10} "
                         f"{format_si(float(self.contact_radius[j]), 'm'):>11} "
                         f"{format_si(c, 'm') if math.isfinite(c) else '-':>11} "
                         f"{format_si(float(self.peak_pressure[j]), 'Pa'):>11} "
                         f"{self.load_ratio_hertz(j):9.5g} "
                         f"{format_si(float(self.frictional_energy[j]), 'J'):>11}")
        for m, (s, e) in enumerate(self.cycles):
            err = float(self.cycle_energy_error[m])
            rel = err / abs(float(self.cycle_frictional_energy[m])) \
                if self.cycle_frictional_energy[m] else math.nan
            line = (f"  cycle {m + 1} (path points {s} -> {e}): frictional energy "
                    f"{format_si(float(self.cycle_frictional_energy[m]), 'J')}")
            if math.isfinite(rel):
                line += f" (estimated relative error {rel:.1e})"
            if getattr(res, "relaxation", ()):
                line += f", viscous {format_si(float(self.cycle_viscous_energy[m]), 'J')}"
            lines.append(line)
        if self.segment_frictional_energy.size:
            lines.append(f"  loading half-cycle (segment 1): "
                         f"{format_si(float(self.segment_frictional_energy[0]), 'J')}")
        if res.resolved is not None:
            lines.append(f"  resolved steps (max error {res.max_error:g}): "
                         f"{int(res.resolved[1:].sum())}/{res.resolved.size - 1}")
        lines += [f"  warning: {note}" for note in self.notes]
        if res.message:
            lines.append(f"  message: {res.message}")
        return "\n".join(lines)

    __str__ = summary

    def __repr__(self) -> str:
        return "PhysicalHistory:\n" + self.summary()


def force_shape(spec: Any, name: str = "load_path") -> tuple[Any, float, float]:
    """A shape or table of forces as levels: ``(level spec, P_max [N], start time [s])``.

    ``spec`` is a shape with ``amplitude`` and ``mean`` in N (or with a unit),
    ``frequency`` in Hz and ``ramp`` in s (or with units), or a table
    ``{"time": [s], "force": [N]}``; the levels are forces over P_max (the
    shape's mean + amplitude, the table's largest force), the times shifted
    to start at 0 (the start returned). Checked further by
    :func:`contactlib.model.load_paths.load_path`.

    Raises
    ------
    validate.InputError
        Naming the bad key.
    """
    from .model import load_paths

    if not isinstance(spec, dict):
        spec = dict(spec)
    if "shape" in spec:
        out = dict(spec)
        for key in ("amplitude", "mean"):
            if key in spec:
                out[key] = parse_quantity(spec[key], "force", f"{name}.{key}",
                                          positive=key == "amplitude")
        if spec.get("frequency") is not None:
            out["frequency"] = parse_quantity(spec["frequency"], "frequency",
                                              f"{name}.frequency")
        if spec.get("ramp") is not None:
            out["ramp"] = parse_quantity(spec["ramp"], "time", f"{name}.ramp")
        if "amplitude" in out and "mean" in out:
            p_max = out["amplitude"] + out["mean"]
            out["amplitude"] /= p_max
            out["mean"] /= p_max
        else:
            p_max = 1.0
        load_paths.load_path(out, name)  # every key checked, in the levels
        return out, p_max, 0.0
    if set(spec) != {"time", "force"}:
        raise validate.InputError(name, "", spec, f"{name} must be a shape (with a 'shape' "
                                  f"key: {', '.join(load_paths.SHAPES)}) or a table with "
                                  f"exactly the keys time [s] and force [N], got keys "
                                  f"{', '.join(map(str, spec))}")
    cols = {}
    for key, kind in (("time", "time"), ("force", "force")):
        col = spec[key]
        if not validate.is_sequence(col):
            raise validate.InputError(f"{name}.{key}", "a sequence", col)
        cols[key] = [parse_quantity(v, kind, f"{name}.{key}", positive=False)
                     if not (kind == "time" and isinstance(v, (int, float)) and not
                             isinstance(v, bool) and math.isfinite(v)) else float(v)
                     for v in col]
    if not cols["force"] or max(cols["force"]) <= 0.0:
        raise validate.InputError(f"{name}.force", "", cols["force"], f"{name}.force never "
                                  "rises above 0 (no contact to follow)")
    p_max = max(cols["force"])
    t0 = cols["time"][0] if cols["time"] else 0.0
    out = {"time": [t - t0 for t in cols["time"]], "load": [f / p_max for f in cols["force"]]}
    load_paths.load_path(out, name)
    return out, p_max, float(t0)


def check_history(geometry: str, radius: float | str, load_path: Any, indenter: Any = "rigid",
                  body: Any = None, friction: float = 0.0, **kwargs: Any) -> None:
    """Check the input of :func:`physical_history` without computing anything.

    Raises
    ------
    validate.InputError
        As :func:`physical_history` would, naming the bad argument (the rules that join
        several inputs included: a relaxation and its times, a layer's a_max/h).
    """
    physical_history(geometry, radius, load_path, indenter, body, friction, _check_only=True,
                     **kwargs)


def path_cycles(forces: Sequence[float]) -> list[tuple[int, int]]:
    """(start, end) path points of each cycle: a cycle ends where the force, having
    decreased, increases next, or at the end of the path."""
    ends = [i for i in range(1, len(forces) - 1)
            if forces[i] < forces[i - 1] and forces[i + 1] > forces[i]]
    ends.append(len(forces) - 1)
    starts = [0] + ends[:-1]
    return list(zip(starts, ends))


def physical_history(geometry: str, radius: float | str, load_path: Any, indenter: Any,
                     body: Any, friction: float, *, times: Sequence[Any] | None = None,
                     relaxation: Sequence[Sequence[Any]] | None = None,
                     steps: int = DEFAULT_HISTORY_STEPS, length: float | str | None = None,
                     thickness: float | str | None = None, base: str = "smooth",
                     substrate: Any = None, profile: str = "paraboloid",
                     half_angle: float | str | None = None,
                     n: int | None = None, max_error: float = validate.PATH_DEFAULT_MAX_ERROR,
                     error_estimate: bool = True,
                     progress: Callable[[int, int], None] | None = None,
                     _check_only: bool = False) -> PhysicalHistory:
    """Follow a path of normal forces with incremental stick-slip; the answer in SI.

    Parameters
    ----------
    geometry, radius, indenter, body, length, thickness, base, substrate, profile, half_angle
        As for :func:`physical_solve` (the layer's a_max/h with a_max below; a coated
        body refuses a ``relaxation``; the cone: ``radius=None``, ``half_angle`` in
        degrees, a_max its frictionless contact radius at P_max).
    load_path : sequence, str or mapping
        Forces [N] (numbers, or strings with units), or ``"0N,100N,0N"``;
        starting at 0. The largest is P_max, load level 1. Or a shape
        ``{"shape": "sinusoidal" | "haversine", "amplitude": N, "mean": N,
        "frequency": Hz, "cycles": number}`` (optionally ``"ramp"``, s; P_max =
        mean + amplitude), or a table ``{"time": [s, ...], "force": [N, ...]}``
        (P_max its largest force); numbers in SI or strings with units. The
        steps and pieces are those of :mod:`contactlib.model.load_paths`: ``steps``
        then counts steps a load travel of P_max, and a viscoelastic body's
        times are the shape's (``times`` is not given).
    friction : float
        Coulomb's k (``inf``: no slip).
    times : sequence, optional
        Time of each path point [s, or with a unit], increasing; needed with
        ``relaxation`` only (the segment durations are their differences).
    relaxation : sequence of (g, tau), optional
        A viscoelastic body: the Prony series of :func:`contactlib.history`,
        tau in s (or with a unit); ``body`` then gives E(0) and nu.
    steps : int
        Load steps a segment (default 200); a load travel of P_max for a shape or table.
    n, max_error, error_estimate, progress
        Passed to :func:`contactlib.history`.

    Returns
    -------
    PhysicalHistory
        The length scale a_max = (3 P_max R / (4 E*))^(1/3) (sphere) or
        (4 P_max R / (pi E* length))^(1/2) (cylinder) is exact, so the
        errors are those of the dimensionless estimates times their scales.

    Raises
    ------
    validate.InputError
        Naming the bad argument.

    Warns
    -----
    SmallStrainWarning
        Where the largest contact radius exceeds ``SMALL_STRAIN_LIMIT`` R.
    """
    from . import history_api

    from .model import load_paths

    prob = physical_problem(geometry, radius, indenter, body, length, thickness, base, substrate,
                            profile, half_angle)
    shaped = load_paths.is_shaped(load_path)
    if shaped:
        if times is not None:
            raise validate.InputError("times", "", times, "times must not be given with a "
                                      "shape or table: the path gives its own times")
        levels, p_max, t_start = force_shape(load_path)
        forces: tuple[float, ...] = ()
    else:
        forces = parse_force_path(load_path)
        p_max = max(forces)
        levels = [f / p_max for f in forces]
    g = prob.geometry
    kwargs: dict[str, Any] = dict(prob.dimensionless(), n=n, max_error=max_error,
                                  error_estimate=error_estimate, progress=progress)
    t_points = None
    if relaxation is not None:
        prony: list[Any] = []
        req = "a list of pairs (g, tau) with tau in s or with a unit"
        for item in relaxation:
            if isinstance(item, (str, bytes)) or not hasattr(item, "__iter__") or \
                    len(list(item)) != 2:
                raise validate.InputError("relaxation", req, relaxation)
            weight, tau = list(item)
            prony.append([weight, parse_quantity(tau, "time", "relaxation")])
        kwargs["relaxation"] = prony
        if times is None and not shaped:
            raise validate.InputError("times", "given with a relaxation (the time of each "
                                      "path point, in s)", times)
    if times is not None:
        if relaxation is None:
            raise validate.InputError("times", "given only with a relaxation (an elastic "
                                      "body has no time scale)", times)
        items = times.split(",") if isinstance(times, str) else list(times)
        t_points = np.array([parse_quantity(t, "time", "times", positive=False)
                             for t in items])
        if t_points.size != len(forces) or np.any(np.diff(t_points) <= 0):
            raise validate.InputError("times", f"{len(forces)} increasing times, one a path "
                                      "point", times)
        kwargs["duration"] = list(np.diff(t_points))
    a_max = prob.radius_of_load(p_max / prob.per_length)
    slab = 0.0 if prob.thickness == math.inf else a_max / prob.thickness
    if _check_only:  # the rules of contactlib.history that join several inputs, no numerics
        validate.slab_ratio(slab, g, prob.base, extent=validate.HISTORY_MESH_EXTENT)
        if relaxation is not None and not prob.indenter.rigid:
            raise validate.InputError("relaxation", "", relaxation, "relaxation needs a "
                                      "rigid indenter")
        if relaxation is not None and prob.substrate is not None:
            raise validate.InputError("relaxation", "", relaxation, "relaxation is not "
                                      "available on a coated body (base 'elastic')")
        if relaxation is not None and shaped and "shape" in levels and \
                levels.get("frequency") is None:
            raise validate.InputError("load_path.frequency", "", None, "load_path.frequency "
                                      "is required with a relaxation (Hz)")
        return None
    try:
        res = history_api.history(g, prob.body.nu, friction, levels, steps, slab_ratio=slab,
                                  **kwargs)
    except validate.InputError as exc:  # a_max/h comes from the thickness here
        if exc.name != "slab_ratio":
            raise
        raise validate.InputError("thickness", "thick enough for the largest force", thickness,
                                  f"thickness {prob.thickness!r} m is too thin for this path "
                                  f"(a_max/h = {slab:.3g}): {exc}") from None
    if shaped:  # the path's levels at the ends of its pieces, and their times
        forces = tuple(float(v) * p_max for v in res.load_path)
        if res.durations:
            t_points = t_start + np.concatenate([[0.0], np.cumsum(res.durations)])
    p0 = prob.pressure_unit(a_max)
    w_unit = prob.work_unit(a_max) * prob.per_length
    a = np.asarray(res.contact_radius) * a_max
    with np.errstate(invalid="ignore"):
        c = np.asarray(res.stick_ratio) * a
    wf = np.asarray(res.frictional_work) * w_unit
    wv = (np.zeros_like(wf) if res.viscous_work is None
          else np.asarray(res.viscous_work) * w_unit)
    err_w = np.asarray(res.work_error_estimate if res.work_error_estimate is not None
                       else np.full(wf.shape, np.nan), dtype=float)
    w_scale = float(getattr(res, "work_scale", np.nan)) * w_unit
    err_c = np.asarray(res.stick_radius_error_estimate
                       if res.stick_radius_error_estimate is not None
                       else np.full(wf.shape, np.nan), dtype=float) * a_max
    approach = (np.asarray(res.indentation) * prob.displacement_unit(a_max)
                if (g == "sphere" or slab > 0) else np.full(wf.shape, np.nan))
    cycles = path_cycles(forces)
    cyc_f, cyc_e, cyc_v = [], [], []
    for s, e in cycles:
        js, je = res.segment_end(s) if s else 0, res.segment_end(e)
        cyc_f.append(wf[je] - wf[js])
        # the work's estimate is relative to the path's total work (res.work_scale)
        cyc_e.append(abs(err_w[je] * w_scale) + (abs(err_w[js] * w_scale) if js else 0.0))
        cyc_v.append(wv[je] - wv[js])
    time = None if res.time is None else np.asarray(res.time) + (t_points[0] if t_points
                                                                 is not None else 0.0)
    notes = validity_notes(prob, float(np.nanmax(a)))
    peak = np.max(np.asarray(res.pressure), axis=1) * p0
    if prob.shape.exponent <= 1.0:  # the cone's pressure is log-infinite at the tip
        peak = np.where(a > 0, math.inf, peak)
    return PhysicalHistory(
        geometry=g, radius=prob.radius, length=prob.length, thickness=prob.thickness,
        base=prob.base, indenter=prob.indenter, body=prob.body, substrate=prob.substrate,
        composite_modulus=prob.e_star, friction=float(res.friction), load_path=forces,
        times=t_points, a_max=a_max, p0=p0,
        max_load=p_max, slab_ratio=slab, force=np.asarray(res.load_ratio) * p_max,
        contact_radius=a, stick_radius=c, stick_radius_error=err_c,
        peak_pressure=peak, approach=approach,
        frictional_energy=wf, energy_error=err_w, viscous_energy=wv, time=time,
        cycles=cycles, cycle_frictional_energy=np.array(cyc_f),
        cycle_energy_error=np.array(cyc_e), cycle_viscous_energy=np.array(cyc_v),
        segment_frictional_energy=np.asarray(res.segment_work()) * w_unit,
        notes=notes, result=res, profile=prob.shape.name, half_angle=prob.half_angle,
        problem=prob)
