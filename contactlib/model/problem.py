r"""The model: an indenter pressed into a body.

A :class:`Contact` joins an :class:`~contactlib.model.indenter.Indenter` (what is
pressed: sphere or cylinder) and an :class:`~contactlib.model.body.ElasticBody`
(what it is pressed into). It is all a solver needs to know about the
physics: the kernels of the basic loads (the indenter chooses rings or
strips, the body answers them), the Hertz references and the measures of an
element. :mod:`contactlib.discretization.operators` turns it into influence matrices, and
every solver (default, paper, history) takes it.

Units and scalings
------------------
E* = R = 1, lengths in units of the contact radius a (a_max in the
incremental solver): see :mod:`contactlib.model.indenter` and
:mod:`contactlib.model.body`. E* is the composite modulus every scaling uses,

    1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2,

(1: indenter, 2: body), the body's E2/(1 - nu2^2) under a rigid indenter.

Two elastic bodies
------------------
The kernels of :mod:`contactlib.model.body` are in units of each body's own
E*_i = E_i/(1 - nu_i^2); in units of the composite E* they carry the weights
c_i = E*/E*_i (c1 + c2 = 1). The gap closes by the normal displacements of
both bodies, and the relative tangential displacement is that of the body
minus that of the indenter, which carries the opposite shear (-q). So

* pressure: (c2 w_b + c1 w_i, c2 u_b - c1 u_i, c2 du_b - c1 du_i),
* shear:    (c2 w_b - c1 w_i, c2 u_b + c1 u_i, c2 du_b + c1 du_i),

with ``_i`` the indenter material's kernels of the same basic load (a
half-space under rings, a half-plane under strips, also over a slab body).
On a half-space the coupling terms combine to Dundurs' beta = c2 beta2 -
c1 beta1 (beta_i = (1 - 2 nu_i)/(2 (1 - nu_i))), positive for a rigid
indenter; no case is special.

Examples
--------
>>> from contactlib.model import contact
>>> m = contact("cylinder", 0.3, slab_ratio=0.05)
>>> m.indenter.name, m.body.thickness, m.hertz_load == m.indenter.hertz_load
('cylinder', 20.0, True)
>>> w, u, du = m.pressure_kernel(np.array([0.0]), np.array([1.0]))
>>> bool(w[0] > 0)
True
"""

from __future__ import annotations

import functools
import inspect
import math
from dataclasses import dataclass, field
from typing import Any, Callable, TypeVar

import numpy as np

from .body import ElasticBody, ViscoelasticBody
from .indenter import Displacements, Indenter, indenter
from .profiles import PARABOLOID, Profile
from ..validate import InputError

# convention: the scale of k on a layer whose material has |beta| below it (beta of
# nu = 0.45, about 0.09); only starting guesses use it (tests/test_layer_incompressible.py)
LAYER_BETA_SCALE = 1.0 / 11.0

__all__ = ["Contact", "contact", "accepts_model"]


@dataclass(frozen=True)
class Contact:
    """An indenter pressed into a body (units E* = a = R = 1).

    Parameters
    ----------
    indenter : Indenter
        The sphere or cylinder, rigid or with its material
        (``modulus_ratio`` E1/E2 and ``nu``).
    body : ElasticBody
        The body under it (its ``slab_ratio`` in units of the contact radius).
    profile : Profile
        The indenter's shape, keyword only (default :data:`~contactlib.model.profiles.PARABOLOID`:
        Hertz's r^2/(2R)); see :mod:`contactlib.model.profiles`.

    Notes
    -----
    The kernels are always reached through :meth:`pressure_kernel` and
    :meth:`shear_kernel` of the contact (never the body's directly): that is
    where the compliance of a second elastic body adds to the first, and
    where a subclass may rescale them (the tests evaluate them at physical
    lengths).
    """

    indenter: Indenter
    body: ElasticBody
    profile: Profile = field(default=PARABOLOID, kw_only=True)

    # ------------------------------------------------------------------ materials
    @property
    def indenter_poisson_ratio(self) -> float:
        """Poisson's ratio of the indenter (the body's when the indenter gives none)."""
        return self.body.nu if self.indenter.nu is None else float(self.indenter.nu)

    @property
    def indenter_body(self) -> ElasticBody:
        """The indenter's material as an unbounded body (half-space / half-plane)."""
        return ElasticBody(self.indenter_poisson_ratio)

    @property
    def compliance_weights(self) -> tuple[float, float]:
        """(c1, c2) = (E*/E*_1, E*/E*_2): the shares of the compliance, c1 + c2 = 1.

        E*_i = E_i/(1 - nu_i^2); a rigid indenter gives (0, 1) exactly.
        """
        ratio = self.indenter.modulus_ratio
        if ratio == math.inf:
            return 0.0, 1.0
        a1 = (1.0 - self.indenter_poisson_ratio**2) / ratio  # E2/E*_1
        a2 = 1.0 - self.body.nu**2  # E2/E*_2
        return a1 / (a1 + a2), a2 / (a1 + a2)

    @property
    def body_modulus(self) -> float:
        """E*_2/E* = 1/c2: the body's own E2/(1 - nu2^2) in units of the composite E*."""
        return 1.0 / self.compliance_weights[1]

    # ------------------------------------------------------------------ kernels
    @property
    def merged_half_space(self) -> ElasticBody | None:
        """One unbounded body whose kernels are the summed ones (None: they are summed).

        The kernels of an unbounded body (half-space under rings, half-plane
        under strips; :mod:`contactlib.kernels.disc`, ``strip``) are affine in
        its material: K = D + beta_i C, with D (the direct terms) and C (the
        coupling terms) independent of nu. Over an unbounded body the summed
        kernels c2 K_2 +- c1 K_1 (module notes) are then D + (c2 beta2 -
        c1 beta1) C: those of one unbounded body with |beta| = |c2 beta2 - c1 beta1|
        (Poisson's ratio (1 - 2 |beta|)/(2 (1 - |beta|)), in (-1, 0.5]), whose
        coupling terms (u and du/dx of a pressure, w of a shear) change sign
        when beta < 0. Evaluated once, this costs what a rigid indenter costs;
        equal to the explicit sum to round-off (``tests/test_elastic_indenter.py``).
        None for a rigid indenter (the body alone) and over a layer (the
        layer's kernels depend on nu otherwise).
        """
        c1, _ = self.compliance_weights
        if c1 == 0.0 or not self.body.is_half_space:
            return None
        beta = abs(self.beta)
        return ElasticBody((1.0 - 2.0 * beta) / (2.0 * (1.0 - beta)))

    def _summed(self, kernel, x: np.ndarray, s: np.ndarray, coupling: float,
                merge: bool = True, **kw) -> Displacements:
        """c2 (body) + c1 (indenter) kernels; ``coupling`` -1 flips the indenter's u, du.

        ``merge=False`` sums the two bodies' kernels explicitly even where
        :attr:`merged_half_space` gives them in one evaluation (for tests).
        """
        merged = self.merged_half_space if merge else None
        direct = -coupling  # the w term has the opposite sign to the u terms
        if merged is not None:
            w, u, du = kernel(merged, x, s, **kw)
            if self.beta >= 0.0:
                return w, u, du
            # beta < 0: the coupling terms (the indenter's negative ones) change sign
            return (direct * w, coupling * u, coupling * du)
        wb, ub, dub = kernel(self.body, x, s, **kw)
        c1, c2 = self.compliance_weights
        if c1 == 0.0:  # rigid indenter: the body alone, bit for bit
            return wb, ub, dub
        wi, ui, dui = kernel(self.indenter_body, x, s, **kw)
        return (c2 * wb + direct * c1 * wi, c2 * ub + coupling * c1 * ui,
                c2 * dub + coupling * c1 * dui)

    def pressure_kernel(self, x: np.ndarray, s: np.ndarray, with_w: bool = True,
                        merge: bool = True) -> Displacements:
        """(w, u, du/dx) of a unit uniform pressure on a disc / symmetric strip of radius s.

        Both bodies' compliances summed (module notes): w the closing of the
        gap, u the body's tangential displacement relative to the indenter.
        ``with_w=False`` may skip w (zeros) where that is cheaper (the disc).
        ``merge=False``: the explicit sum (see :attr:`merged_half_space`).
        """
        return self._summed(self.indenter.pressure_kernel, x, s, -1.0, merge, with_w=with_w)

    def shear_kernel(self, x: np.ndarray, s: np.ndarray, with_du: bool = True,
                     merge: bool = True) -> Displacements:
        """(w, u, du/dx) of the unit shear element: q = r on a disc, or +-1 on a strip.

        q acts on the body and -q on the indenter (module notes).
        ``with_du=False`` may skip du/dx (NaN) where that is cheaper (the disc).
        ``merge=False``: the explicit sum (see :attr:`merged_half_space`).
        """
        return self._summed(self.indenter.shear_kernel, x, s, 1.0, merge, with_du=with_du)

    def smooth_remainder(self, part: str, x: np.ndarray, s: np.ndarray,
                         weights: np.ndarray | None = None,
                         owner: np.ndarray | None = None) -> np.ndarray | None:
        """The body's smooth remainder (layer minus half-space) on the grid x by s, or None.

        (3, x.size, s.size), or its weighted sums over s (see
        :meth:`Indenter.smooth_remainder`), in units of the composite E*
        (weight c2): the
        kernels of :meth:`pressure_kernel` / :meth:`shear_kernel` are those of
        :attr:`half_space_twin` plus this (:mod:`contactlib.discretization.operators`
        integrates the two parts with different rules).
        """
        rem = self.indenter.smooth_remainder(self.body, part, x, s, weights, owner)
        if rem is None:
            return None
        c1, c2 = self.compliance_weights
        return rem if c1 == 0.0 else c2 * rem

    @property
    def half_space_twin(self) -> Contact:
        """The same indenter on the body's material unbounded (the singular part)."""
        return Contact(self.indenter, self.body.half_space)

    def axis_w_kernel(self, x: np.ndarray, s: np.ndarray, part: str,
                      ref: float = 0.0) -> Displacements:
        """(w(x) - w(ref), 0, 0) of the basic load of ``part``, both bodies, without cancellation.

        The closing of the gap relative to the axis (centre line): where w
        is O(s) and the difference O(x^2/s), this keeps its relative accuracy
        (a tiny stick zone's normal rows, see
        :func:`contactlib.discretization.operators.axis_w_rows`).
        """
        def kernel(body, xx, ss):
            return self.indenter.axis_w_kernel(body, xx, ss, part, ref)
        return self._summed(kernel, x, s, -1.0 if part == "normal" else 1.0)

    def length_degrees(self, part: str) -> np.ndarray | None:
        """Homogeneity degrees of the element integrals (see :meth:`Indenter.length_degrees`)."""
        return self.indenter.length_degrees(self.body, part)

    # ------------------------------------------------------------------ coupling
    @property
    def beta(self) -> float:
        """Dundurs' beta of the pair, c2 beta2 - c1 beta1.

        Sign: a rigid indenter on a body of Poisson's ratio nu gives
        (1 - 2 nu)/(2 (1 - nu)) > 0 (inward slip); beta < 0 slips outward.
        """
        c1, c2 = self.compliance_weights
        if c1 == 0.0:
            return self.body.beta
        return c2 * self.body.beta - c1 * self.indenter_body.beta

    @property
    def decoupled(self) -> bool:
        """beta = 0 (to round-off) between half-spaces: the normal and tangential problems decouple.

        A layer or coating is never decoupled: its surface moves radially under a
        pressure at any nu (an incompressible layer is squeezed along its base), so
        Dundurs' beta of its material does not measure its coupling.
        """
        if not self.body.is_half_space:
            return False
        c1, c2 = self.compliance_weights
        scale = abs(c2 * self.body.beta) + abs(c1 * self.indenter_body.beta)
        return bool(abs(self.beta) <= 8.0 * np.finfo(float).eps * scale)

    @property
    def slip_sign(self) -> float:
        """Sign of the slip-zone shear q = slip_sign k p: +1 inward slip (beta > 0), -1 outward.

        0 when decoupled.
        """
        return 0.0 if self.decoupled else float(np.sign(self.beta))

    def uncoupled_friction(self, gamma: np.ndarray) -> np.ndarray:
        """k >= 0 of the uncoupled limit at stick ratio ``gamma``, with |beta| (indenter's formula).

        The solvers take it as the scale of k (starting guesses, continuation). On a
        layer, whose coupling is not beta's (:attr:`decoupled`), |beta| is raised to at
        least :data:`LAYER_BETA_SCALE`, so that an incompressible layer (beta = 0) has
        a scale too.
        """
        beta = abs(self.beta)
        if not self.body.is_half_space:
            beta = max(beta, LAYER_BETA_SCALE)
        return self.indenter.uncoupled_friction(beta, gamma)

    # ------------------------------------------------------------------ Hertz and measures
    @property
    def p0(self) -> float:
        """Hertz peak pressure at a = 1 (units E* a/R): the pressure unit.

        For another profile, the peak pressure of the paraboloid with the same
        frictionless load (:meth:`~contactlib.model.profiles.Profile.reference_pressure`)."""
        if self.profile.is_paraboloid:
            return self.indenter.p0
        return self.profile.reference_pressure(self.indenter.name == "sphere")

    @property
    def hertz_load(self) -> float:
        """Hertz load at a = 1 (E* a^3/R, or E* a^2/R per unit length): the load unit.

        For another profile, its own frictionless load at a = 1
        (:meth:`~contactlib.model.profiles.Profile.frictionless_load`)."""
        if self.profile.is_paraboloid:
            return self.indenter.hertz_load
        return self.profile.frictionless_load(self.indenter.name == "sphere")

    def frictionless_radius(self, level: float) -> float:
        """Frictionless contact radius at load level P/P_max, in units of a_max: P ~ a^(d+1)
        (rings) or a^d (strips) for h ~ r^d; Hertz's for the paraboloid; 1 for the flat punch;
        the root of the closed-form load for the rounded one."""
        if self.profile.is_paraboloid:
            return self.indenter.hertz_radius(level)
        return self.profile.frictionless_radius(level, self.indenter.name == "sphere")

    def shear_shape(self, x: np.ndarray) -> np.ndarray:
        """Shear = shape(x) * phi(x): shape r for the sphere, 1 for the cylinder."""
        return self.indenter.shear_shape(x)

    def load(self, nodes: np.ndarray, p: np.ndarray) -> float:
        """Total load of a piecewise-linear pressure (:meth:`Indenter.load_of_linear`)."""
        return self.indenter.load_of_linear(nodes, p)

    @property
    def work_factor(self) -> float:
        """V = factor * int_c^1 xi^power q (-s) dxi (see :mod:`contactlib.energy`).

        The loading half-cycle integrates q ds/da ~ a^(2d) over a (rings) or a^(2d - 1)
        (strips): 2 pi/(2d + 1) and 1/d, 2 pi/5 and 1/2 for the paraboloid."""
        if self.profile.is_paraboloid:
            return self.indenter.work_factor
        return self.profile.work_factor(self.indenter.name == "sphere")

    @property
    def work_weight_power(self) -> int:
        """Power of xi in the work integrand (1 for rings, 0 for strips)."""
        return self.indenter.work_weight_power

    # ------------------------------------------------------------------ the public keywords
    def keywords(self) -> dict[str, Any]:
        """The public entry points' keywords that build this model (:func:`contact`'s inverse).

        ``solve(**m.keywords(), stick_ratio=0.5)`` solves this model, as does
        ``solve(m, stick_ratio=0.5)`` (:func:`accepts_model`). Keywords at their
        defaults are left out, so each entry point is given only what it takes.

        Examples
        --------
        >>> from contactlib.model import contact
        >>> contact("sphere", 0.3, slab_ratio=2.0, base="bonded").keywords()
        {'geometry': 'sphere', 'nu': 0.3, 'slab_ratio': 2.0, 'base': 'bonded'}
        """
        body, ind, prof = self.body, self.indenter, self.profile
        kw: dict[str, Any] = {"geometry": ind.name, "nu": float(body.nu)}
        if body.slab_ratio > 0.0:
            kw.update(slab_ratio=float(body.slab_ratio), base=body.base)
            if body.base == "elastic":
                kw["substrate_modulus"] = float(body.substrate_modulus)
                if body.substrate_nu is not None:
                    kw["substrate_nu"] = float(body.substrate_nu)
        if ind.modulus_ratio != math.inf:
            kw["indenter_modulus"] = float(ind.modulus_ratio)
        if ind.nu is not None:
            kw["indenter_nu"] = float(ind.nu)
        if getattr(body, "relaxation", ()):
            kw["relaxation"] = [list(term) for term in body.relaxation]
        if prof.name != PARABOLOID.name:
            kw["profile"] = prof.name
            if prof.name == "power":
                kw["exponent"] = float(prof.exponent)
            if prof.name == "rounded":
                kw["flat_ratio"] = float(prof.flat)
        return kw


def contact(geometry: str, nu: float, slab_ratio: float = 0.0,
            indenter_modulus: float = math.inf, indenter_nu: float | None = None,
            base: str = "smooth",
            relaxation: tuple[tuple[float, float], ...] = (),
            profile: Profile = PARABOLOID, substrate_modulus: float = math.inf,
            substrate_nu: float | None = None) -> Contact:
    """The model of the public interface's names: an indenter on an elastic body.

    Parameters
    ----------
    geometry : {"sphere", "cylinder"}
    nu : float
        Poisson's ratio of the body.
    slab_ratio : float
        a/h of a layer on a rigid base (0: half-space or half-plane).
    indenter_modulus : float
        E1/E2 of the indenter over the body (``inf``: rigid, the default).
    indenter_nu : float, optional
        Poisson's ratio of the indenter (None: the body's).
    base : {"smooth", "bonded", "elastic"}
        The layer's base (default smooth; "elastic": a coated body).
    relaxation : tuple of (g, tau), optional
        Prony terms of a viscoelastic body (:class:`~contactlib.model.body.ViscoelasticBody`;
        its kernels are the elastic ones at E(0)); empty: elastic.
    profile : Profile
        The indenter's shape (default the paraboloid; :func:`contactlib.model.profiles.profile`).
    substrate_modulus, substrate_nu : float
        E2/E1 and Poisson's ratio (None: the layer's) of the elastic substrate
        of a coated body (``base="elastic"``).
    """
    body = ViscoelasticBody(nu, slab_ratio, base, relaxation=tuple(relaxation)) \
        if relaxation else ElasticBody(nu, slab_ratio, base, substrate_modulus, substrate_nu)
    return Contact(indenter(geometry, indenter_modulus, indenter_nu), body, profile=profile)


_Entry = TypeVar("_Entry", bound=Callable[..., Any])


def accepts_model(func: _Entry) -> _Entry:
    """Let an entry point ``f(geometry, nu, ...)`` take a :class:`Contact` instead.

    ``f(model, ...)`` is ``f(**model.keywords(), ...)``: the positional arguments
    after the model fill the parameters after ``nu``. A model keyword given again,
    or one the entry point does not take (a viscoelastic body for ``solve``), is
    refused with an :class:`~contactlib.validate.InputError` naming it.
    """
    signature = inspect.signature(func).parameters
    params = list(signature)
    positional = [name for name, p in signature.items()
                  if p.kind is inspect.Parameter.POSITIONAL_OR_KEYWORD][2:]

    @functools.wraps(func)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        if not (args and isinstance(args[0], Contact)):
            if isinstance(kwargs.get("geometry"), Contact):
                kwargs = dict(kwargs)
                args = (kwargs.pop("geometry"), *args)
            else:
                return func(*args, **kwargs)
        model, rest = args[0], args[1:]
        if len(rest) > len(positional):
            raise InputError("model", f"followed by at most {len(positional)} positional "
                             f"argument(s) of {func.__name__} ({', '.join(positional) or 'none'}"
                             "; the model gives geometry and nu)", len(rest))
        given = dict(zip(positional, rest))
        for name, value in model.keywords().items():
            if name in given or name in kwargs:
                raise InputError(name, "given once: by the model or as a keyword, not both",
                                 given.get(name, kwargs.get(name)))
            if name not in params:
                raise InputError("model", f"a model {func.__name__} takes ({name} is not "
                                 f"one of its parameters)", name,
                                 f"{func.__name__} does not take a model with {name}="
                                 f"{value!r}: " + ("use history for a viscoelastic body"
                                                   if name == "relaxation" else
                                                   f"{func.__name__} takes no {name}"))
            given[name] = value
        return func(**given, **kwargs)

    return wrapper  # type: ignore[return-value]
