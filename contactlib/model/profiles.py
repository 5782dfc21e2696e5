r"""Indenter profiles: the gap between the bodies before they touch.

A profile is the shape h(r) of the indenter over the body, as a power law

    h(r) = A |r|^d,   d > 0,

with r the radius (``sphere``: axisymmetric) or the distance from the line of
symmetry (``cylinder``: plane strain). d = 2 is the paraboloid of Hertz
(A = 1/(2R)), d = 1 the cone (A = cot alpha, alpha the half-angle) or the wedge.
Every power law with d > 0 meets the body with a smooth edge (p ~ sqrt(a - r)),
and under a monotonic load its contact is self-similar: the contact radius a
sets the scale, and the solution at every load is the same in r/a.

Units
-----
The solvers work at a = 1, E* = 1, with A = 1/d: h(r) = r^d/d, so that the
paraboloid is today's h = r^2/2 (R = 1), bit for bit. Loads are reported over
the profile's own frictionless load at the same contact radius
(:meth:`Profile.frictionless_load`; P_Hertz for the paraboloid), so a
frictionless case has ``load_ratio`` 1 for every profile. Pressures are in units
of the profile's reference pressure :meth:`Profile.reference_pressure`: the peak
pressure of the paraboloid that carries the same frictionless load on the same
contact (Hertz's p0 for the paraboloid; finite for the cone, whose own peak is
infinite).

Frictionless closed forms (Galin, Segedin; Love for the cone)
--------------------------------------------------------------
Axisymmetric, h = A r^d:

    delta = A a^d sqrt(pi) Gamma(d/2 + 1) / Gamma(d/2 + 1/2),
    P     = 2 E* A a^(d+1) d/(d + 1) sqrt(pi) Gamma(d/2 + 1) / Gamma(d/2 + 1/2).

Plane strain, per unit length:

    P = (E*/2) A d a^d sqrt(pi) Gamma(d/2 + 1/2) / Gamma(d/2 + 1).

Cone (d = 1): p(r) = (E* A/2) arccosh(a/r); wedge: p(x) = (E* A/pi) arccosh(a/|x|).

Partial slip
------------
In the self-similar problem a point of the stick zone keeps its tangential
displacement while a grows; with u(r, a) = a^d U(r/a) that makes U ~ (r/a)^d:
the adherence condition is u = C r^d (:meth:`Profile.adherence`), C unknown.

The flat punch
--------------
The flat punch (``flat``: h = 0 for r <= a, the punch's fixed radius) is the limit
d -> infinity. Its pressure is square-root singular at the sharp edge (Boussinesq:
P = 2 E* a delta, p = P/(2 pi a sqrt(a^2 - r^2)); plane strain p = P/(pi sqrt(a^2 - x^2)),
with no finite approach). Its contact does not grow, so it is not self-similar in a
and only the incremental ``history`` solver takes it. Under a monotonic load every
increment is the same problem, so the solution is proportional to P: the stick zone
is fixed, and it is the stick zone of the increment problem that the self-similar
solution of every power law solves as a grows (the pressure increment at fixed r is
~ (a^2 - r^2)^(-1/2) for every profile). Hence c/a(k) of the flat punch is the k(c/a)
of the power laws, and P/(2 E* a delta) is their dP/d(delta) over 2 E* a.

The rounded flat punch
----------------------
``rounded``: flat over r <= b and a paraboloid beyond it, h = (|r| - b)^2/(2R) for
|r| > b (``flat_ratio`` = b over the length unit; Ciavarella's rounded punch of fretting
pads). Its contact grows from b, so the pressure has a smooth edge, and the increment at
contact radius a is again the flat punch's problem on a: under a monotonic load its stick
ratio is the power laws' c/a(k) at every load. Frictionless closed forms (Sneddon's
integrals; R = E* = 1):

    delta = a [sqrt(a^2 - b^2) - b acos(b/a)],
    P     = 2 [(2 a^2/3 - b^2/6) sqrt(a^2 - b^2) - (a^2 b/2) acos(b/a)],
    P     = (1/2) [a^2 acos(b/a) - b sqrt(a^2 - b^2)] per unit length (plane strain),
    p(r)  = (1/pi) int_max(r, b)^a [2 sqrt(t^2 - b^2) - b acos(b/t)] / sqrt(t^2 - r^2) dt.

Only ``history`` takes it; its length unit is a_max, the frictionless contact radius at
P_max, so ``flat_ratio`` = b/a_max.

Units of the flat punch: a = E* = 1 and the load unit is ``frictionless_load``, 2
(sphere: P = 2 E* a delta at delta = 1) or 1 (cylinder: E* a per unit length), so
displacements are in units of P_max/(2 E* a) (sphere) or P_max/E* (cylinder).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = ["Profile", "PARABOLOID", "FLAT", "profile", "of_result", "PROFILES",
           "FLAT_RATIO_RANGE", "SOLVERS", "takes"]

PROFILES = ("paraboloid", "cone", "power", "flat", "rounded")
"""The names :func:`profile` accepts."""

# limit: d = 0.5 ... 8 measured in tests/test_profiles.py (the closed forms at d = 0.5, 1, 1.5, 3,
# 8)
EXPONENT_RANGE = (0.5, 8.0)
"""The exponents d the solvers accept: measured down to d = 0.5 (the pressure's axis
singularity, r^(d-1), still integrable for the piecewise-linear elements) and up to
d = 8 (an almost flat punch with rounded edges)."""

SOLVERS = ("self-similar", "history", "fretting", "stresses")
"""What may take a profile: the self-similar methods (``solve``, ``sweep``), ``history``,
``fretting`` (a tangential load) and the subsurface stresses of a solution or history step."""

_SOLVERS_OF = {"flat": ("history",), "rounded": ("history", "fretting", "stresses")}  # others: all


def takes(name: str, solver: str) -> bool:
    """Whether the profile called ``name`` is taken by ``solver`` (one of :data:`SOLVERS`).

    A solver asks this before it builds the profile (which may need parameters it has
    not been given), and refuses in its own words where it is False. A name that is
    not a profile's is taken: :func:`profile` refuses it with the list of names.
    """
    return not isinstance(name, str) or solver in _SOLVERS_OF.get(name, SOLVERS)


# limit: b/a_max up to 0.9 measured in tests/test_flat_punch.py (b = 0, 0.5, 0.9)
FLAT_RATIO_RANGE = (0.0, 0.9)
"""b/a_max of the rounded flat punch: up to 0.9, where the rounded edge a_max - b spans
0.1 a_max (24 elements of the default history mesh)."""


@dataclass(frozen=True)
class Profile:
    """A power-law profile h(r) = r^d/d (units a = 1; see the module's notes).

    Parameters
    ----------
    name : {"paraboloid", "cone", "power", "flat", "rounded"}
        The name it was made from (``paraboloid``: d = 2, ``cone``: d = 1, ``flat``:
        d = inf, the flat punch of radius 1; ``rounded``: the rounded flat punch).
    exponent : float
        d > 0 (``inf`` for the flat punch, 2 for the rounded one's edge).
    flat : float
        b, the rounded punch's flat radius in the length unit (0 otherwise).
    """

    name: str
    exponent: float
    flat: float = 0.0

    @property
    def is_paraboloid(self) -> bool:
        """Whether d = 2 with no flat: Hertz's profile, computed by the same operations as
        before."""
        return self.exponent == 2.0 and self.name != "rounded"

    @property
    def is_rounded(self) -> bool:
        """Whether this is the rounded flat punch (flat to b, a paraboloid beyond)."""
        return self.name == "rounded"

    @property
    def is_flat(self) -> bool:
        """Whether this is the flat punch (d = inf): fixed contact radius 1, sharp edge."""
        return math.isinf(self.exponent)

    def takes(self, solver: str) -> bool:
        """Whether ``solver`` (one of :data:`SOLVERS`) takes this profile (:func:`takes`)."""
        return takes(self.name, solver)

    @property
    def fixed_contact(self) -> bool:
        """Whether the contact radius is the punch's at every load (the flat punch): the
        history mesh is then the punch's face, and its end is the contact's edge."""
        return self.is_flat

    @property
    def stick_edge_power(self) -> float:
        """q of the stick-edge fit, the power of the traction deficit d = 1 - |q|/(kp)
        that is linear at the edge: 2/3 where the stick edge advances with the contact
        (d ~ (c - r)^(3/2)), 2 where it stands (the flat punch, d ~ (c - r)^(1/2))."""
        return 2.0 if self.fixed_contact else 2.0 / 3.0

    def label(self) -> str:
        """The profile's parameter as the summaries show it: " (d = 3)", " (b/a_max =
        0.5)", or "" for the flat punch."""
        if self.is_flat:
            return ""
        if self.is_rounded:
            return f" (b/a_max = {self.flat:g})"
        return f" (d = {self.exponent:g})"

    def attributes(self) -> dict[str, float | str]:
        """Dataset attributes of the profile: ``profile``, ``profile_exponent`` and, for the
        rounded punch, ``profile_flat_ratio``."""
        out: dict[str, float | str] = {"profile": self.name,
                                       "profile_exponent": float(self.exponent)}
        if self.is_rounded:
            out["profile_flat_ratio"] = float(self.flat)
        return out

    def scale_attributes(self, axisymmetric: bool) -> dict[str, str]:
        """Dataset attributes that replace the paraboloid's scalings of a history: the flat
        punch has no R (lengths over its radius, displacements over delta0)."""
        if not self.is_flat:
            return {}
        return {"length_scale": "a_max: the flat punch's radius a",
                "displacement_scale": "tangential_displacement and indentation are over "
                + ("delta0 = P_max/(2 E* a)" if axisymmetric else
                   "delta0 = P_max/E* (P_max per unit length)")}

    def frictionless_radius(self, level: float, axisymmetric: bool) -> float:
        """Frictionless contact radius at load level P/P_max (units of the radius at P_max):
        P ~ a^(d+1) (rings) or a^d (strips) for h ~ r^d; 1 for the flat punch; the root
        of the closed-form load for the rounded one."""
        if self.is_flat:
            return 1.0
        if self.is_rounded:
            load = level * self.frictionless_load(axisymmetric)
            return self.rounded_radius(load, axisymmetric) if load > 0 else self.flat
        d = self.exponent
        return float(level ** (1.0 / (d + 1.0 if axisymmetric else d)))

    # ------------------------------------------------------------------ what solvers use
    def gap(self, r: np.ndarray) -> np.ndarray:
        """h(r) = r^d/d: the gap closed by the approach (w = delta - h)."""
        r = np.asarray(r, dtype=float)
        if self.is_paraboloid:
            return 0.5 * r**2
        if self.is_flat:  # the punch's face; beyond its edge the body never reaches it
            return np.where(np.abs(r) <= 1.0, 0.0, np.inf)
        if self.is_rounded:
            return 0.5 * np.maximum(np.abs(r) - self.flat, 0.0) ** 2
        d = self.exponent
        return np.abs(r) ** d / d

    def gap_difference(self, r: np.ndarray, ref: np.ndarray) -> np.ndarray:
        """h(r) - h(ref), without cancellation where r is close to ref."""
        r, ref = np.broadcast_arrays(np.asarray(r, dtype=float), np.asarray(ref, dtype=float))
        if self.is_paraboloid:
            return 0.5 * (r - ref) * (r + ref)
        return self.adherence_difference(r, ref) / self.exponent

    def gap_scale(self, r_edge: float, delta: float) -> float:
        """The scale of the gap near a contact reaching ``r_edge`` at approach ``delta``:
        2 h(r_edge) (r_edge^2 for the paraboloid), and |delta| for the flat punch, whose
        gap is 0 over the whole contact."""
        if self.is_flat:
            return abs(float(delta))
        if self.is_rounded:  # the edge's (r - b)^2, or the approach while the edge is short
            return max(2.0 * float(self.gap(r_edge)), abs(float(delta)))
        return 2.0 * float(self.gap(r_edge))

    def adherence(self, r: np.ndarray) -> np.ndarray:
        """r^d: the stick zone's tangential displacement is u = C r^d."""
        r = np.asarray(r, dtype=float)
        if self.is_paraboloid:
            return r**2
        return np.abs(r) ** self.exponent

    def adherence_difference(self, r: np.ndarray, ref: np.ndarray) -> np.ndarray:
        """r^d - ref^d, without cancellation where r is close to ref."""
        r, ref = np.broadcast_arrays(np.asarray(r, dtype=float), np.asarray(ref, dtype=float))
        if self.is_paraboloid:
            return (r - ref) * (r + ref)
        d = self.exponent
        out = np.abs(r) ** d - np.abs(ref) ** d
        pos = ref > 0
        with np.errstate(divide="ignore", invalid="ignore"):
            close = np.abs(ref) ** d * np.expm1(d * np.log1p((r - ref) / np.where(pos, ref, 1)))
        return np.where(pos & (r > 0), close, out)

    # ------------------------------------------------------------------ frictionless closed forms
    def _gamma_ratio(self) -> float:
        """sqrt(pi) Gamma(d/2 + 1) / Gamma(d/2 + 1/2)."""
        h = 0.5 * self.exponent
        return math.sqrt(math.pi) * math.exp(math.lgamma(h + 1.0) - math.lgamma(h + 0.5))

    def frictionless_load(self, axisymmetric: bool) -> float:
        """P at a = 1, E* = 1 (per unit length in plane strain), h = r^d/d (Galin).

        4/3 and pi/4 for the paraboloid (P_Hertz in units E* a^3/R and E* a^2/R).
        """
        if self.is_flat:  # Boussinesq's 2 E* a delta at delta = 1; E* a per length
            return 2.0 if axisymmetric else 1.0
        if self.is_rounded:
            return self.rounded_load(1.0, axisymmetric)
        d = self.exponent
        if axisymmetric:
            return 2.0 / (d + 1.0) * self._gamma_ratio()
        return 0.5 * math.pi / self._gamma_ratio()

    def rounded_load(self, a: float, axisymmetric: bool) -> float:
        """The rounded punch's frictionless load at contact radius ``a`` >= b (R = E* = 1;
        per unit length in plane strain; see the module's notes)."""
        b = self.flat
        root = math.sqrt(max(a * a - b * b, 0.0))
        angle = math.acos(min(b / a, 1.0)) if a > 0 else 0.5 * math.pi
        if axisymmetric:
            return 2.0 * ((2.0 * a * a / 3.0 - b * b / 6.0) * root - 0.5 * a * a * b * angle)
        return 0.5 * (a * a * angle - b * root)

    def rounded_radius(self, load: float, axisymmetric: bool) -> float:
        """The contact radius a > b at which :meth:`rounded_load` is ``load`` (> 0)."""
        from scipy.optimize import brentq

        hi = 1.0
        while self.rounded_load(hi, axisymmetric) < load:
            hi *= 2.0
        return float(brentq(lambda a: self.rounded_load(a, axisymmetric) - load, self.flat,
                            hi, xtol=1e-15, rtol=1e-15))

    def frictionless_approach(self) -> float:
        """delta at a = 1 of the axisymmetric profile (1 for the paraboloid, pi/2 for the cone,
        1 for the flat punch at its load unit)."""
        if self.is_flat:
            return 1.0
        if self.is_rounded:
            b = self.flat
            return math.sqrt(1.0 - b * b) - b * math.acos(b)
        return self._gamma_ratio() / self.exponent

    def reference_pressure(self, axisymmetric: bool) -> float:
        """The pressure unit: the peak pressure of the paraboloid of the same frictionless load.

        Hertz's p0 (2/pi and 1/2 at a = 1) for the paraboloid; P/(2/3 pi) for the sphere and
        2P/pi for the cylinder in general.
        """
        load = self.frictionless_load(axisymmetric)
        return load * 1.5 / math.pi if axisymmetric else load * 2.0 / math.pi

    def work_factor(self, axisymmetric: bool) -> float:
        """The frictional work's factor of a monotonic loading to a = 1 (units E* (A d)^2
        a^(2d+1), per unit length a^(2d)): fields ~ a^(d-1) times slip rates ~ a^(d-1)
        over the area a^2 (a), integrated in a: 2 pi/(2d + 1) and 2/(2d)."""
        if self.is_flat or self.is_rounded:
            raise ValueError(f"the {self.name} punch has no self-similar loading; its work "
                             f"comes from history")
        d = self.exponent
        return 2.0 * math.pi / (2.0 * d + 1.0) if axisymmetric else 1.0 / d

    def work_unit(self, axisymmetric: bool, length: str = "a_max") -> str:
        """The unit of a work or energy of this profile, as text (``length``: the name of
        the contact radius the scalings use).

        V R^2/(E* a^5) (a^4 per unit length) for the paraboloid, V/(E* (A d)^2 a^(2d+1))
        for h = A r^d, and V/(E* a delta0^2) with delta0 = P_max/(2 E* a) for the flat
        punch of radius a (plane strain: V/(E* delta0^2) per unit length, delta0 =
        P_max/E*)."""
        per = "" if axisymmetric else " per unit length"
        if self.is_paraboloid or self.is_rounded:
            return f"V R^2/(E* {length}^{5 if axisymmetric else 4}){per}"
        if self.is_flat:
            if axisymmetric:
                return "V/(E* a delta0^2), delta0 = P_max/(2 E* a), a the punch's radius"
            return "V/(E* delta0^2) per unit length, delta0 = P_max/E*"
        power = 2.0 * self.exponent + (1.0 if axisymmetric else 0.0)
        return f"V/(E* (A d)^2 {length}^{power:g}){per}, h = A r^d"

    def frictionless_pressure(self, x: np.ndarray, axisymmetric: bool) -> np.ndarray:
        """p(x) at a = 1 for the paraboloid, the cone/wedge and the flat punch (closed forms;
        E* = 1; the flat punch at its load unit :meth:`frictionless_load`).

        Raises
        ------
        NotImplementedError
            For other exponents (their pressure is Segedin's integral, not tabulated here).
        """
        x = np.abs(np.asarray(x, dtype=float))
        inside = x < 1.0
        xs = np.where(inside, x, 0.5)
        if self.is_paraboloid:
            p = (2.0 / math.pi) * np.sqrt(1.0 - xs**2) if axisymmetric \
                else 0.5 * np.sqrt(1.0 - xs**2)
        elif self.exponent == 1.0:
            with np.errstate(divide="ignore"):
                p = np.arccosh(1.0 / xs) * (0.5 if axisymmetric else 1.0 / math.pi)
        elif self.is_flat:  # P/(2 pi sqrt(1 - r^2)) at P = 2; P/(pi sqrt(1 - x^2)) at P = 1
            p = 1.0 / (math.pi * np.sqrt(1.0 - xs**2))
        else:
            raise NotImplementedError("closed-form pressure only for d = 1 and d = 2")
        return np.where(inside, p, 0.0)


PARABOLOID = Profile("paraboloid", 2.0)
"""Hertz's profile, the default."""

FLAT = Profile("flat", math.inf)
"""The flat punch of radius 1 (``history`` only)."""


def of_result(result: Any) -> Profile:
    """The profile a result records (its ``profile``, ``exponent`` and ``flat_ratio``)."""
    name = getattr(result, "profile", "paraboloid")
    return profile(name, result.exponent if name == "power" else None,
                   getattr(result, "flat_ratio", 0.0) if name == "rounded" else None)


def profile(name: str = "paraboloid", exponent: float | None = None,
            flat_ratio: float | None = None) -> Profile:
    """The profile of a name (and, for ``power``, an exponent); checked.

    Parameters
    ----------
    name : {"paraboloid", "cone", "power", "flat", "rounded"}
        ``paraboloid`` (default): d = 2; ``cone``: d = 1 (a wedge for the cylinder);
        ``power``: d = ``exponent``; ``flat``: the flat punch; ``rounded``: the rounded
        flat punch (these two ``history`` only).
    exponent : float, optional
        d for ``power``, in :data:`EXPONENT_RANGE`; must be omitted otherwise.
    flat_ratio : float, optional
        b/a_max for ``rounded``, in :data:`FLAT_RATIO_RANGE`; must be omitted otherwise.

    Raises
    ------
    contactlib.validate.InputError
        On an unknown name, a missing or out-of-range exponent or flat ratio, or either
        given with a profile that does not take it.
    """
    from .. import validate

    name = validate.choice("profile", name, PROFILES)
    if name != "rounded" and flat_ratio is not None:
        raise validate.InputError("flat_ratio", f"omitted for the {name} profile (it is the "
                                  "rounded punch's b/a_max); use profile 'rounded'", flat_ratio)
    if name == "rounded":
        if exponent is not None:
            raise validate.InputError("exponent", "omitted for the rounded profile (its edge "
                                      "is a paraboloid)", exponent)
        if flat_ratio is None:
            raise validate.InputError("flat_ratio", "given for the rounded profile (b/a_max)",
                                      flat_ratio)
        lo, hi = FLAT_RATIO_RANGE
        return Profile("rounded", 2.0, validate.number("flat_ratio", flat_ratio, lo=lo, hi=hi))
    if name != "power":
        if exponent is not None:
            raise validate.InputError("exponent", f"omitted for the {name} profile (its d is "
                                      "fixed); use profile 'power'", exponent)
        return {"paraboloid": PARABOLOID, "flat": FLAT}.get(name, Profile("cone", 1.0))
    if exponent is None:
        raise validate.InputError("exponent", "given for the power profile", exponent)
    lo, hi = EXPONENT_RANGE
    d = validate.number("exponent", exponent, lo=lo, hi=hi)
    if d == 2.0:
        return PARABOLOID
    return Profile("power", d)
