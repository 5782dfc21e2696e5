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

The flat punch (fixed contact radius, square-root singular pressure) is not a
power law of this kind: it is not self-similar in a, and no solver takes it yet.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["Profile", "PARABOLOID", "profile", "PROFILES"]

PROFILES = ("paraboloid", "cone", "power")
"""The names :func:`profile` accepts."""

EXPONENT_RANGE = (0.5, 8.0)
"""The exponents d the solvers accept: measured down to d = 0.5 (the pressure's axis
singularity, r^(d-1), still integrable for the piecewise-linear elements) and up to
d = 8 (an almost flat punch with rounded edges)."""


@dataclass(frozen=True)
class Profile:
    """A power-law profile h(r) = r^d/d (units a = 1; see the module's notes).

    Parameters
    ----------
    name : {"paraboloid", "cone", "power"}
        The name it was made from (``paraboloid``: d = 2, ``cone``: d = 1).
    exponent : float
        d > 0.
    """

    name: str
    exponent: float

    @property
    def is_paraboloid(self) -> bool:
        """Whether d = 2: Hertz's profile, computed by the same operations as before."""
        return self.exponent == 2.0

    # ------------------------------------------------------------------ what solvers use
    def gap(self, r: np.ndarray) -> np.ndarray:
        """h(r) = r^d/d: the gap closed by the approach (w = delta - h)."""
        r = np.asarray(r, dtype=float)
        if self.is_paraboloid:
            return 0.5 * r**2
        d = self.exponent
        return np.abs(r) ** d / d

    def gap_difference(self, r: np.ndarray, ref: np.ndarray) -> np.ndarray:
        """h(r) - h(ref), without cancellation where r is close to ref."""
        r, ref = np.broadcast_arrays(np.asarray(r, dtype=float), np.asarray(ref, dtype=float))
        if self.is_paraboloid:
            return 0.5 * (r - ref) * (r + ref)
        return self.adherence_difference(r, ref) / self.exponent

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
        d = self.exponent
        if axisymmetric:
            return 2.0 / (d + 1.0) * self._gamma_ratio()
        return 0.5 * math.pi / self._gamma_ratio()

    def frictionless_approach(self) -> float:
        """delta at a = 1 of the axisymmetric profile (1 for the paraboloid, pi/2 for the cone)."""
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
        d = self.exponent
        return 2.0 * math.pi / (2.0 * d + 1.0) if axisymmetric else 1.0 / d

    def frictionless_pressure(self, x: np.ndarray, axisymmetric: bool) -> np.ndarray:
        """p(x) at a = 1 for the paraboloid and the cone/wedge (closed forms; E* = 1).

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
        else:
            raise NotImplementedError("closed-form pressure only for d = 1 and d = 2")
        return np.where(inside, p, 0.0)


PARABOLOID = Profile("paraboloid", 2.0)
"""Hertz's profile, the default."""


def profile(name: str = "paraboloid", exponent: float | None = None) -> Profile:
    """The profile of a name (and, for ``power``, an exponent); checked.

    Parameters
    ----------
    name : {"paraboloid", "cone", "power"}
        ``paraboloid`` (default): d = 2; ``cone``: d = 1 (a wedge for the cylinder);
        ``power``: d = ``exponent``.
    exponent : float, optional
        d for ``power``, in :data:`EXPONENT_RANGE`; must be omitted otherwise.

    Raises
    ------
    contactlib.validate.InputError
        On an unknown name, a missing or out-of-range exponent, or an exponent given
        with a named profile.
    """
    from . import validate

    name = validate.choice("profile", name, PROFILES)
    if name != "power":
        if exponent is not None:
            raise validate.InputError("exponent", f"omitted for the {name} profile (its d is "
                                      "fixed); use profile 'power'", exponent)
        return PARABOLOID if name == "paraboloid" else Profile("cone", 1.0)
    if exponent is None:
        raise validate.InputError("exponent", "given for the power profile", exponent)
    lo, hi = EXPONENT_RANGE
    d = validate.number("exponent", exponent, lo=lo, hi=hi)
    if d == 2.0:
        return PARABOLOID
    return Profile("power", d)
