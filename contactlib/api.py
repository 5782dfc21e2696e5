"""Public entry points: validate, solve, post-process, sweep.

Examples
--------
>>> from contactlib import solve
>>> sol = solve("sphere", 0.3, stick_ratio=0.0, n=64)
>>> abs(sol.load_ratio - 1.0) < 1e-3
True
"""

from __future__ import annotations

import functools
import math
from typing import Any, Callable, Sequence

import numpy as np

from .model import profiles
from . import stages, validate
from .solvers.default_method import DiscreteSolution, solve_default
from .discrete import SelfSimilarSolution
from .model.geometry import Geometry
from .model import accepts_model
from .discretization.operators import StickBlocks
from .result import CaseRecord, Solution
from .threads import blas_single_threaded

PAPER_METHODS = ("paper", "paper-literal")  # c/a restricted to multiples of 1/n

__all__ = ["solve", "sweep", "stick_ratio_for_friction", "DEFAULT_N", "METHODS", "GEOMETRIES",
           "output_grid"]

GEOMETRIES = validate.GEOMETRIES
METHODS = validate.METHODS
DEFAULT_N = validate.DEFAULT_N
MAX_N = validate.MAX_N
# convention: the output grid of x = r/a, 201 equally spaced points
_OUTPUT_POINTS = 201


def output_grid() -> np.ndarray:
    """The common xi grid of every dataset: 201 equally spaced points on [0, 1]."""
    return np.linspace(0.0, 1.0, _OUTPUT_POINTS)


# ----------------------------------------------------------------------------- validation
def _validate_common(geometry, nu, n, method, slab_ratio, indenter_modulus=math.inf,
                     indenter_nu=None, base="smooth", profile="paraboloid",
                     exponent=None, substrate_modulus=None, substrate_nu=None,
                     planned=None) -> tuple[Geometry, int, str]:
    """The problem's arguments, checked one by one with :mod:`contactlib.validate`."""
    geometry = validate.geometry(geometry)
    method = validate.method(validate.DEFAULT_METHOD if method is None else method)
    nu = validate.nu(nu)
    base = validate.base(base, coated=True)
    slab = validate.slab_ratio(slab_ratio, geometry, base)
    sub_modulus, sub_nu = validate.substrate(base, substrate_modulus, substrate_nu, geometry,
                                             method)
    if planned is not None and base == validate.COATED_BASE:
        raise validate.InputError("tolerance", "unset on a coated body (base 'elastic')",
                                  planned, "tolerance is not planned on a coated body (base "
                                  "'elastic'): give n (method 'default') instead")
    n = validate.n(n, method)
    ratio, nu1 = validate.indenter_material(indenter_modulus, indenter_nu)
    if not profiles.takes(profile, "self-similar"):
        raise validate.InputError(
            "profile", "a power law (paraboloid, cone, power) for solve and sweep", profile,
            f"profile {profile!r} is for history only: the punch's contact does not grow "
            f"self-similarly; run history with profile {profile!r} (contactlib history "
            f"--profile {profile}); its stick ratio is the power laws' c/a at the same k")
    shape = profiles.profile(profile, exponent)
    if not shape.is_paraboloid and not validate.method_of(method).any_profile:
        raise validate.InputError("method", f"'default' for the {shape.name} profile", method,
                                  f"method {method!r} is measured for the paraboloid only (the "
                                  "paper's scheme and the extrapolated method's error model); "
                                  f"use method 'default' for the {shape.name} profile")
    return Geometry(geometry, nu, slab, ratio, nu1, base, sub_modulus, sub_nu,
                    profile=shape), n, method


# ----------------------------------------------------------------------------- post-processing
def _finish(geom: Geometry, d: SelfSimilarSolution, method: str, n: int,
            want_energy: bool, message: str = "",
            max_error: float = validate.DEFAULT_MAX_ERROR) -> Solution:
    """Profiles on the output grid, load, flags, work and error estimates of a discrete solution."""
    rec = stages.case_record(geom, d, samples=True)
    rec = stages.estimate_case(geom, method, n, rec, max_error=max_error, solution=d)
    return _from_record(geom, rec, method, n, want_energy, message)


def _from_record(geom: Geometry, rec: CaseRecord, method: str, n: int, want_energy: bool,
                 message: str = "") -> Solution:
    xi = output_grid()
    work = stages.work_case(geom, rec) if want_energy else float("nan")
    profile: dict[str, Any] = stages.profiles(geom, rec, xi, displacements=False)
    # u needs the kernels at every xi: computed when the caller first reads it
    profile["tangential_displacement"] = functools.partial(_displacement, geom, rec, xi)
    sol = stages.to_solution(geom, method, n, rec, xi, flags=stages.check_case(rec),
                             work=work, profile=profile, message=message)
    sol.extra.update(stages.nodal_tractions(geom, rec))  # for the subsurface stresses
    if geom.body.base == validate.COATED_BASE:  # a coated body: its substrate
        sol.substrate_modulus = float(geom.body.substrate_modulus)
        sol.substrate_poisson_ratio = float(geom.body.kernel_base.nu)
    return sol


def _displacement(geom: Geometry, rec: CaseRecord, xi: np.ndarray) -> np.ndarray:
    """The tangential-displacement profile of a case (its kernel work)."""
    return stages.profiles(geom, rec, xi, stresses=False)["tangential_displacement"]


def _discrete(geom: Geometry, c: float, n: int, method: str, k_guess: float | None = None):
    """Solve one stick ratio with the chosen method (no post-processing)."""
    if validate.method_of(method).nested_estimate:
        return solve_default(geom, c, n, k_guess=k_guess)
    return stages.solve_one(geom, method, n, c, None, None)


# ----------------------------------------------------------------------------- inverse problem
# limit: resolved at the default n down to c/a = 1e-8 (tests/test_extremes.py)
SMALLEST_STICK_RATIO = 1e-8  # the inverse's floor: the smallest c/a resolved at the default n
# limit: resolved at the default n up to c/a = 1 - 1e-5 (tests/test_stability_full_stick.py;
# CHANGELOG, near full stick at strong coupling)
LARGEST_STICK_RATIO = 1.0 - 1e-5  # its ceiling: the largest c/a resolved at the default n
# tested: tests/test_stability_full_stick.py (the inverse near full stick); the k at an end moves by
# 4e-10 with Newton's start, see below
ENDPOINT_RTOL = 1e-7  # a friction within this of the k at an end is that end: warm-started
#   Newton's k at c/a = 0.99999 moves by up to 4e-10 relative with its start (measured,
#   sphere and cylinder, nu = 0.3 and 0.49), and its error estimate there is above 1e-5


def stick_ratio_for_friction(geometry: Geometry, friction: float, n: int,
                             xtol: float = 1e-10) -> tuple[float, DiscreteSolution]:
    """Stick ratio c/a that a friction coefficient k produces (default method).

    k(c) increases monotonically from 0 (c = 0); the root of k(c) = friction
    is bracketed from the uncoupled estimate and refined by Brent's method,
    warm-starting Newton on k from the last solve. Near full stick k(c)
    grows without bound as c/a approaches a limit c* that is below 1 where
    the coupling is strong (sphere nu = -0.99: c* = 0.952; nu = 0: 0.9990;
    docs/accuracy.md, "Near full stick"); beyond c* there is no
    single-zone solution (the root found there slips outward with tensile
    pressure, and ``solve_default`` reports k as NaN), so a failed solve
    above c/a = 1/2, or a root there that slips the other way than the first
    one found or fails the checks at the nodes (beyond c* Newton also finds
    inconsistent inward roots, e.g. k = 5 at c/a = 1 - 3e-6 for the sphere at
    nu = -0.99), is taken as lying past the root (k above any friction), and
    a failed solve below c/a = 1/2 as lying under it (a stick zone too small
    to resolve).

    Raises
    ------
    contactlib.validate.SolverLimit
        A :class:`ValueError` for valid input the method cannot answer: when
        the stick zone lies outside [SMALLEST_STICK_RATIO,
        LARGEST_STICK_RATIO] (the message gives the small-k estimate
        c/a ~ 4 exp(-A/k), A = k ln(4 a/c) at the floor), or when no
        converged root is found (the message names where the solutions end).
        Its ``remedies`` name the calls that answer the case (full adhesion,
        a history, a larger n).
    """
    cache: dict[float, DiscreteSolution] = {}
    blocks = StickBlocks()  # this search's store of stick blocks, shared by its solves
    last: dict[str, float | None] = {"k": None, "way": None}

    def f(c: float) -> float:
        d = solve_default(geometry, c, n, k_guess=last["k"], cache=blocks)
        cache[c] = d
        if not (d.converged and np.isfinite(d.k)):  # no self-similar solution found here:
            return friction if c > 0.5 else -friction  # past c* above, unresolved below
        slip = np.arange(d.mesh.stick_index, d.mesh.n)
        j = slip[np.argmax(np.abs(d.p[slip]))]
        way = float(np.sign(d.traction[j] * d.p[j]))  # sign of the root's k: its slip direction
        if last["way"] is None:
            last["way"] = way  # the branch of the first (smallest) stick ratio tried
        elif c > 0.5 and (way != last["way"] or not d.node_flags()["consistent"]):
            return friction  # the root came back through k = inf, or is no solution: past c*
        last["k"] = d.k
        return d.k - friction

    gam = np.linspace(1e-4, 1 - 1e-9, 4001)
    k_unc = geometry.uncoupled_friction(gam)
    c0 = float(np.interp(friction, k_unc, gam))
    lo, hi = max(c0 * 0.8, 1e-3), min(c0 + 0.2 * (1 - c0), LARGEST_STICK_RATIO)
    flo = f(lo)
    while flo > 0 and lo > SMALLEST_STICK_RATIO:
        hi, lo = lo, max(lo * 0.03, SMALLEST_STICK_RATIO)
        flo = f(lo)
    fhi = f(hi)
    while fhi < 0 and hi < LARGEST_STICK_RATIO:
        lo, hi = hi, min(1 - (1 - hi) * 0.1, LARGEST_STICK_RATIO)
        fhi = f(hi)
    # the ends themselves: a friction equal to the k there (to round-off) is that end's c/a
    for end, val in ((hi, fhi), (lo, flo)):
        d = cache.get(end)
        if d is not None and abs(val) <= ENDPOINT_RTOL * friction and d.converged:
            return end, d
    if flo > 0:
        k_floor = flo + friction
        amp = k_floor * np.log(4.0 / lo)  # k ~ A / ln(4 a/c) for small stick zones
        log10_c = (np.log(4.0) - amp / friction) / np.log(10.0)
        raise validate.SolverLimit(
            f"friction {friction!r} gives a stick zone below c/a = {lo:.3g}, the smallest "
            f"resolved (k = {k_floor:.4g} there); by the small-k law k ~ {amp:.3g}/ln(4 a/c) "
            f"it is c/a ~ 1e{log10_c:.0f}: nearly the whole contact slips; use friction 0 for "
            "Hertz", [("solve", {"friction": 0.0})])
    if fhi < 0:
        raise validate.SolverLimit(
            f"friction {friction!r} is too large: the stick zone covers more than {hi:.5f} of "
            f"the contact, the largest resolved (k = {fhi + friction:.4g} there); use "
            "stick_ratio 1 (full adhesion)", [("solve", {"stick_ratio": 1.0})])
    from scipy import optimize  # here, not at import: it costs a workflow job 0.3 s

    try:
        c = optimize.brentq(f, lo, hi, xtol=xtol)
    except ValueError:  # the ends, solved again from another start, no longer bracket:
        ends = {lo: flo, hi: fhi}  # search from the values that did
        c = optimize.brentq(lambda x: ends[x] if x in ends else f(x), lo, hi, xtol=xtol)
    d = cache.get(c) or solve_default(geometry, c, n, k_guess=last["k"], cache=blocks)
    if not (d.converged and np.isfinite(d.k)
            and abs(d.k - friction) <= 1e-3 * friction):  # else a jump, not a root
        why = d.message or "k = " + format(d.k, ".4g")
        hint = ("; a friction this large most likely holds the whole contact stuck (no "
                "single slip annulus reaches it): use stick_ratio 1 (full adhesion), or "
                "`history` with this friction and load path 0,1, which assumes no "
                "self-similar stick zone and shows where slip occurs") if c > 0.5 else (
                "; a larger n resolves smaller stick zones")
        remedies = [("solve", {"stick_ratio": 1.0}),
                    ("history", {"friction": friction, "load_path": [0.0, 1.0]})] \
            if c > 0.5 else ([("solve", {"n": min(4 * n, validate.MAX_N)})]
                             if n < validate.MAX_N else [])
        raise validate.SolverLimit(f"friction {friction!r}: no converged stick ratio found; "
                                   f"the solutions end at c/a = {c:.7f} ({why}){hint}", remedies)
    return c, d


def _check_planned(tolerance, n, method) -> float | None:
    """The checked tolerance (None when not given); it excludes a given n and method."""
    if tolerance is None:
        return None
    tol = validate.planned_tolerance(tolerance)
    if n is not None or method is not None:
        raise validate.InputError("tolerance", "given without n and method (the plan picks "
                                  "them)", tolerance)
    return tol


def _check_planned_profile(planned: float | None, geom: Geometry) -> None:
    """A tolerance is planned from error models measured on the paraboloid only."""
    if planned is not None and not geom.profile.is_paraboloid:
        raise validate.InputError("tolerance", "given for the paraboloid only", planned,
                                  "tolerance plans n from error models measured on the "
                                  f"paraboloid; for the {geom.profile.name} profile give n "
                                  "and read error_estimate")


def _planned_sweep(geom: Geometry, ratios: Sequence[float], tolerance: float, energy: bool,
                   progress: Callable[[int, int], None] | None = None) -> list[Solution]:
    """Cases solved with the planned method and n, refined to the tolerance."""
    from . import accuracy

    try:
        groups = {accuracy.plan(geom, ratios, tolerance, methods=accuracy.PLANNED_METHODS):
                  list(range(len(ratios)))}
    except ValueError as exc:  # one n for all cannot meet it: each stick ratio its own plan
        groups = _plans_by_stick_ratio(geom, ratios, tolerance, str(exc))
    out: list[Solution | None] = [None] * len(ratios)
    done = 0
    for (method, n), where in groups.items():
        cases = stages.iter_cases(geom, method, n, [ratios[i] for i in where], samples=True,
                                  tolerance=tolerance, max_error=tolerance)
        for i, rec in zip(where, cases):
            used = int(rec.elements) if rec.elements is not None else n
            out[i] = _from_record(geom, rec, method, used, energy)
            done += 1
            if progress is not None:
                progress(done, len(ratios))
    return out  # type: ignore[return-value]


def _plans_by_stick_ratio(geom: Geometry, ratios: Sequence[float], tolerance: float,
                          why: str) -> dict[tuple[str, int], list[int]]:
    """Indices of ``ratios`` by the (method, n) planned for each alone, where no single
    (method, n) meets the tolerance at all of them: the truncation falls with n while the
    quadrature noise of the smallest elements grows, so at 1e-9 c/a = 0.5 needs n = 1536
    and 0.02 at most 1024. Refused (naming ``tolerance``, with the plan's reason ``why``)
    where one of them alone cannot be met, or where they would need different methods
    (one dataset holds one method)."""
    from . import accuracy

    groups: dict[tuple[str, int], list[int]] = {}
    for i, c in enumerate(ratios):
        try:
            key = accuracy.plan(geom, [c], tolerance, methods=accuracy.PLANNED_METHODS)
        except ValueError as exc:
            raise validate.InputError("tolerance", "met by a supported method and n",
                                      tolerance, str(exc)) from None
        groups.setdefault(key, []).append(i)
    if len({method for method, _ in groups}) > 1:
        raise validate.InputError("tolerance", "met by a supported method and n", tolerance,
                                  why + "; planned one stick ratio at a time, they would "
                                  "need different methods")
    return groups


def _extrapolated_for_friction(geometry: Geometry, friction: float, n: int,
                               rtol: float = 1e-10) -> tuple[float, DiscreteSolution]:
    """Stick ratio whose extrapolated k is ``friction``: the default method's c at n, then
    secant steps on the extrapolated k(c) (smooth and increasing; two or three steps).

    The extrapolated k carries round-off of a few 1e-10 relative (its levels' Newton
    tolerance, amplified by the Richardson weights; measured on c steps of 2e-10), so
    the secant stops at ``rtol`` or after 8 steps and returns the converged iterate
    whose k is nearest ``friction``: further steps only chase that noise."""
    from .solvers.extrapolated_method import solve_extrapolated

    c0, d0 = stick_ratio_for_friction(geometry, friction, n)
    blocks = StickBlocks()

    def at(c: float):
        return solve_extrapolated(geometry, c, n, k_guess=d0.k, cache=blocks, work=False)

    c1 = c0 + 1e-4 * min(c0, 1.0 - c0)
    s0, s1 = at(c0), at(c1)
    tried = [(c0, s0), (c1, s1)]
    for _ in range(8):
        if not (s0.converged and s1.converged) or s1.k == s0.k:
            break
        if abs(s1.k / friction - 1.0) <= rtol:
            break
        c2 = c1 - (s1.k - friction) * (c1 - c0) / (s1.k - s0.k)
        c2 = min(max(c2, 0.5 * c1), c1 + 0.5 * (1.0 - c1))  # stay inside (0, 1)
        c0, s0, c1 = c1, s1, c2
        s1 = at(c1)
        tried.append((c1, s1))
    good = [(c, s) for c, s in tried if s.converged and np.isfinite(s.k)]
    if not good:
        return c1, s1
    return min(good, key=lambda cs: abs(cs[1].k - friction))


# ----------------------------------------------------------------------------- public API
@accepts_model
@blas_single_threaded
def solve(geometry: str, nu: float, *, stick_ratio: float | None = None,
          friction: float | None = None, n: int | None = None, method: str | None = None,
          slab_ratio: float = 0.0, energy: bool = True, indenter_modulus: float = math.inf,
          indenter_nu: float | None = None,
          max_error: float = validate.DEFAULT_MAX_ERROR, base: str = "smooth",
          tolerance: float | None = None, profile: str = "paraboloid",
          exponent: float | None = None, substrate_modulus: float | None = None,
          substrate_nu: float | None = None) -> Solution:
    """Solve one partial-slip case, for a given stick ratio or friction coefficient.

    Parameters
    ----------
    geometry : {"sphere", "cylinder"} or Contact
        Rigid sphere or cylinder on a half-space/half-plane or a layer; or the whole
        model (:func:`contactlib.contact`), which then also gives ``nu`` and the
        body's, indenter's and profile's keywords (giving one of them again is refused).
    nu : float
        Poisson's ratio of the elastic body, in (-1, 0.5].
    stick_ratio : float, optional
        c/a in [0, 1] (0: frictionless, 1: full adhesion). Exactly one of
        ``stick_ratio`` and ``friction`` must be given.
    friction : float, optional
        Friction coefficient k >= 0 (``inf`` for full adhesion).
    n : int, optional
        Number of elements (default 256 for ``"default"``, 16 for the paper).
    method : {"default", "paper", "paper-literal", "extrapolated"}, optional
        Default ``"default"`` (ours), or planned when ``tolerance`` is given.
        ``"paper"``: the printed scheme (c/a restricted to m/n).
        ``"extrapolated"``: the default discretization at n/8, n/4, n/2 and
        n on nested meshes, k and the load extrapolated in n (orders 2, 3,
        4; k to about 1e-6 at its default n = 256; n a multiple of 128;
        with ``friction``, the c/a whose extrapolated k it is). See
        docs/accuracy.md.
    slab_ratio : float
        a/h of an elastic layer of thickness h on a rigid base; 0 (default)
        is the half-space or half-plane. At most
        ``validate.LAYER_RATIO_MAX[(geometry, base)]`` (sphere 1000).
    energy : bool
        Integrate the frictional work of the loading half-cycle (``True`` or
        ``False``; anything else is refused).
    indenter_modulus : float
        E1/E2, Young's modulus of the indenter over the body's, in (0, inf];
        ``inf`` (default) is rigid. Scalings use the composite E*, 1/E* =
        (1 - nu1^2)/E1 + (1 - nu^2)/E2.
    indenter_nu : float, optional
        Poisson's ratio of the indenter, in (-1, 0.5] (default: the body's;
        refused with a rigid indenter).
    max_error : float
        Accuracy asked for, in (0, 1): a case whose estimated relative error
        of k (``error_estimate``, from the same case on the nested meshes
        n/4 and n/2) exceeds it is reported with ``resolved = False`` and a
        message that names the n that would resolve it, or says why none
        will. Default 1e-3.
    base : {"smooth", "bonded", "elastic"}
        The layer's rigid base: frictionless (default, the paper's slab) or
        bonded; irrelevant at ``slab_ratio = 0``. ``"elastic"``: a coated
        body, the layer (E, ``nu``; E* is the layer's) bonded to an elastic
        half-space or half-plane (``substrate_modulus``, ``substrate_nu``);
        method "default", a/h <= 1000 (both geometries; docs/models.md).
    tolerance : float, optional
        A relative error of k to reach instead of a resolution, in
        [1e-9, 0.1] (:func:`contactlib.validate.planned_tolerance`): the
        method and n are planned (:func:`contactlib.accuracy.plan` over the
        default and the extrapolated method, the cheapest whose measured
        error model meets it; give neither ``n`` nor ``method``), n is
        doubled where the case's own estimate falls short, and ``max_error``
        becomes the tolerance. Refused, naming ``tolerance``, where no method
        is predicted to meet it (e.g. 1e-6 at c/a = 0.9999); with
        stick_ratio, not friction; paraboloid only.
    profile : {"paraboloid", "cone", "power"}
        The indenter's shape h ~ r^d (:mod:`contactlib.model.profiles`): ``"paraboloid"``
        (default, Hertz, d = 2), ``"cone"`` (d = 1; a wedge for the cylinder) or
        ``"power"`` with ``exponent``. Other profiles take the default method; their
        ``load_ratio`` is P over the profile's own frictionless load, the pressure is in
        units of the peak pressure of the paraboloid with that load, and the work in
        units of E* (A d)^2 a^(2d+1) (per unit length a^(2d)) for h = A r^d.
    exponent : float, optional
        d for ``profile="power"``, in [0.5, 8] (omitted otherwise).
    substrate_modulus : float, optional
        E2/E1, the substrate's Young's modulus over the layer's, in
        ``validate.SUBSTRATE_MODULUS_RANGE`` ([1e-2, 1e6]); required with
        ``base="elastic"``, refused otherwise.
    substrate_nu : float, optional
        The substrate's Poisson's ratio in (-1, 0.5] (default: the layer's
        ``nu``); only with ``base="elastic"``.

    Returns
    -------
    Solution
        Profiles and scalars in the scalings of docs/conventions.md.

    Raises
    ------
    ValueError
        For invalid input (:class:`contactlib.validate.InputError`); the
        message names the argument.
    contactlib.validate.SolverLimit
        A :class:`ValueError` for a ``friction`` the self-similar solution
        cannot reach (the contact most likely fully stuck, or the stick zone
        below the smallest resolved); its ``remedies`` name the calls that
        answer it.

    Examples
    --------
    Without friction the load and the central pressure are Hertz's:

    >>> from contactlib import solve
    >>> sol = solve("sphere", 0.3, stick_ratio=0.0, n=64)
    >>> round(sol.load_ratio, 3), round(float(sol.pressure[0]), 3)
    (1.0, 1.0)

    The stick zone a friction coefficient produces; Spence (1975) has
    c/a = 0.5 for nu = 0 and k = 0.2986:

    >>> sol = solve("sphere", 0.0, friction=0.2986, n=64)
    >>> round(sol.stick_ratio, 3), bool(sol.consistent)
    (0.5, True)
    """
    planned = _check_planned(tolerance, n, method)
    geom, n, method = _validate_common(geometry, nu, n, method, slab_ratio, indenter_modulus,
                                       indenter_nu, base, profile, exponent, substrate_modulus,
                                       substrate_nu, planned)
    _check_planned_profile(planned, geom)
    energy = validate.flag("energy", energy)
    max_error = validate.max_error(max_error)
    if (stick_ratio is None) == (friction is None):
        raise validate.InputError("stick_ratio", "given, or friction given", stick_ratio,
                                  "give exactly one of stick_ratio and friction")
    if stick_ratio is not None:
        c = validate.stick_ratio(stick_ratio)
        if planned is not None:
            return _planned_sweep(geom, [c], planned, energy)[0]
        if method in PAPER_METHODS:
            validate.paper_multiple(c, n)  # before solving
        rec = stages.solve_cases(geom, method, n, [c], max_error=max_error)[0]
        return _from_record(geom, rec, method, n, energy)

    k = validate.friction(friction)
    if planned is not None:
        raise validate.InputError("tolerance", "given with stick_ratio (not friction)",
                                  tolerance)
    if k == math.inf:
        return solve(geometry, nu, stick_ratio=1.0, n=n, method=method, slab_ratio=slab_ratio,
                     energy=energy, indenter_modulus=indenter_modulus, indenter_nu=indenter_nu,
                     max_error=max_error, base=base, profile=profile, exponent=exponent,
                     substrate_modulus=substrate_modulus, substrate_nu=substrate_nu)
    if k == 0.0:
        return _finish(geom, _discrete(geom, 0.0, n, method), method, n, energy,
                       max_error=max_error)
    if geom.decoupled:
        d = _discrete(geom, 0.0, n, method)
        sol = _finish(geom, d, method, n, energy,
                      stages.decoupled_message(geom) + "; nothing tends to slip, so the whole "
                      "contact sticks (c/a = 1)", max_error=max_error)
        sol.stick_ratio, sol.friction_coefficient = 1.0, k
        return sol
    if validate.method_of(method).nested_estimate:
        c, d = stick_ratio_for_friction(geom, k, n)
        return _finish(geom, d, method, n, energy, max_error=max_error)
    if validate.method_of(method).own_estimate:
        c, d = _extrapolated_for_friction(geom, k, n)
        return _finish(geom, d, method, n, energy, max_error=max_error)
    # paper method: c/a only at m/n; pick the m/n whose k is nearest
    table = [_discrete(geom, m / n, n, method) for m in range(0, n)]
    ks = np.array([d.k for d in table])
    m = int(np.argmin(np.abs(ks - k)))
    c_interp = float(np.interp(k, ks, np.arange(n) / n)) if np.all(np.diff(ks) > 0) else m / n
    return _finish(geom, table[m], method, n, energy,
                   f"paper method: c/a restricted to m/n; nearest m/n = {m}/{n} has "
                   f"k = {ks[m]:.6g}; linear interpolation in the k(m/n) table gives "
                   f"c/a = {c_interp:.6g} for k = {k:.6g}", max_error=max_error)


@accepts_model
@blas_single_threaded
def sweep(geometry: str, nu: float, stick_ratios: str | Sequence[float] = "all", *,
          n: int | None = None, method: str | None = None, slab_ratio: float = 0.0,
          energy: bool = True,
          progress: Callable[[int, int], None] | None = None,
          indenter_modulus: float = math.inf,
          indenter_nu: float | None = None,
          max_error: float = validate.DEFAULT_MAX_ERROR,
          base: str = "smooth", tolerance: float | None = None,
          profile: str = "paraboloid", exponent: float | None = None,
          substrate_modulus: float | None = None,
          substrate_nu: float | None = None) -> list[Solution]:
    """Solve a list of stick ratios (``"all"``: m/n for m = 1 ... n-1).

    Newton's method on k starts each point from the points already solved
    (continuation: the ratio of k to the uncoupled closed form, interpolated
    in c/a), the first two from the solver's own warm start. A point that
    fails to converge is kept and flagged (``converged = False``), never
    dropped. Every argument is checked before the first point is solved.
    Every case carries ``error_estimate`` and ``resolved`` (see
    :func:`solve`, ``max_error``).

    Parameters
    ----------
    geometry, nu, n, method, slab_ratio, energy, indenter_modulus, indenter_nu, max_error, base
        As for :func:`solve`.
    profile, exponent, substrate_modulus, substrate_nu
        As for :func:`solve` (default the paraboloid; no substrate).
    tolerance : float, optional
        As for :func:`solve`: planned over all the stick ratios (a list, not
        ``"all"``) at one method and n; where no single n meets it at all of
        them (at 1e-9 the truncation needs n = 1536 at c/a = 0.5 while the
        noise of the smallest elements allows at most 1024 at 0.02), each
        stick ratio is planned alone and solved at its own n (``Solution.n``;
        the dataset's ``elements`` variable). Refused where one of them alone
        cannot be met.
    stick_ratios : "all" or sequence of float
        c/a values in [0, 1], each at most once (they index the dataset);
        ``"all"`` is m/n for m = 1 ... n-1.
    progress : callable, optional
        ``progress(i, total)`` is called after each point.

    Returns
    -------
    list of Solution
        One per stick ratio, all on the same ``xi`` grid.

    Examples
    --------
    Near incompressibility (beta -> 0) the uncoupled closed form is exact:

    >>> from contactlib import sweep
    >>> from contactlib.model.theory import uncoupled_friction
    >>> sols = sweep("sphere", 0.499, [0.25, 0.5], n=64)
    >>> [f"{s.friction_coefficient / uncoupled_friction('sphere', 0.499, s.stick_ratio):.3f}"
    ...  for s in sols]
    ['1.000', '1.000']
    """
    planned = _check_planned(tolerance, n, method)
    if planned is not None and isinstance(stick_ratios, str):
        raise validate.InputError("stick_ratios", "a list of stick ratios with a tolerance "
                                  "('all' means m/n and needs a given n)", stick_ratios)
    geom, n, method = _validate_common(geometry, nu, n, method, slab_ratio, indenter_modulus,
                                       indenter_nu, base, profile, exponent, substrate_modulus,
                                       substrate_nu, planned)
    _check_planned_profile(planned, geom)
    energy = validate.flag("energy", energy)
    progress = validate.callback("progress", progress)
    max_error = validate.max_error(max_error)
    ratios = validate.stick_ratios(stick_ratios, n)
    if planned is not None:
        return _planned_sweep(geom, ratios, planned, energy, progress)
    if method in PAPER_METHODS:
        for c in ratios:
            validate.paper_multiple(c, n, "stick_ratios")  # all before solving any
    out = []
    for i, rec in enumerate(stages.iter_cases(geom, method, n, ratios, samples=True,
                                                      max_error=max_error)):
        out.append(_from_record(geom, rec, method, n, energy))
        if progress is not None:
            progress(i + 1, len(ratios))
    return out
