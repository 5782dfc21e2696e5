r"""Loading history: incremental stick-slip along any normal load path.

The paper (and :func:`contactlib.solve`) treats one self-similar loading
half-cycle with a single central stick zone. :func:`history` makes neither
assumption: it follows a prescribed path of normal loads in small steps and,
at every step and for every element, decides contact or separation and stick
or slip by Coulomb's law with full complementarity, carrying the tangential
state from step to step. It covers monotonic loading, unloading, repeated
cycles and the one-step ("one-shot") load, for the sphere on a half-space and
the cylinder on a half-plane or on a slab (where a/h changes along the path).
With ``relaxation`` and ``duration`` the body is viscoelastic (a Prony
series, constant Poisson's ratio; docs/theory.md, "Viscoelastic bodies"):
the path then has a time axis, E* is the instantaneous E*(0) in every
scaling below, and the result splits the indenter's work into stored,
viscous and frictional parts.

Definitions and scalings (docs/conventions.md, with ``a_max`` for ``a``)
-----------------------------------------------------------------------
* ``P_max``: the reference load, load level 1 of the path. Load levels are
  ``P / P_max`` in [0, 1]; the path need not reach 1.
* ``a_max``: the **frictionless (Hertz) contact radius at P_max** on the
  half-space / half-plane, ``a_max = (3 P_max R / (4 E*))^(1/3)`` (sphere) or
  ``(4 P_max R / (pi E*))^(1/2)`` (cylinder). It is the length scale of every
  output and is exactly known, so that scaled outputs do not inherit the
  discretization error of a measured radius. The computed contact radius at
  ``P_max`` differs from it by the friction (0.6 % smaller at k = 0.1, 1.5 %
  at k = 0.3 for the sphere at nu = 0.3) and, on a slab, by the slab's
  stiffness.
* ``slab_ratio`` = ``a_max / h`` (the slab thickness is fixed while a varies).
* ``pressure`` = p / p0 and ``shear`` = q / p0 with p0 the Hertz peak pressure
  at ``a_max`` (2 E* a_max / (pi R), sphere; E* a_max / (2 R), cylinder);
  shear is the traction on the elastic body, positive away from the axis.
* ``tangential_displacement`` = u R / a_max^2, ``indentation`` =
  delta R / a_max^2 (for the half-plane delta carries the Flamant reference
  length a_max: only its changes are meaningful).
* ``frictional_work`` = V R^2 / (E* a_max^5) (sphere) or V R^2 / (E* a_max^4)
  per unit length over both sides of the axis (cylinder), cumulative from the
  start of the path.
* ``contact_radius`` = a / a_max and ``stick_ratio`` = c / a, c the radius of
  the central stick zone (the run of stuck elements from the axis). a is
  resolved below the element size from the gap outside the contact, c from
  the stick-traction deficit, whose law differs where the stick edge
  advances (loading) and where it recedes (unloading); where neither law
  fits, c is an element edge, good to half an element (see
  :func:`contactlib.solvers.history_solver.contact_radius` and
  :func:`~contactlib.solvers.history_solver.stick_radius`). ``stick_ratio`` is NaN
  without contact.

Frictional work of a step: ``-sum_j (q_j^old + q_j^new)/2 du_j A_j`` over
the elements slipping at the end of the step and those that slipped and
separate in it (trapezoid rule in time, with the element's shear-weighted
area A_j: ``int (r/r_j) 2 pi r dr`` for a ring, ``2 dx`` for a strip pair;
:func:`contactlib.energy.step_work`). Where a step's sum is negative (the
end of an unloading) the fall is taken from the steps before it
(:func:`contactlib.energy.monotone_work`): no step dissipates a negative
amount, and the path's total is the trapezoid sum. Its error falls roughly like 1/steps
(0.2 % at 200 steps a segment for the sphere with c/a = 0.5); a slip zone
spanning few elements (c/a close to 1, large k) also needs a finer mesh, and
``message`` says so when the slip zone at the top load spans fewer than 12
elements.

The numerics live in :mod:`contactlib.solvers.history_solver`; writing a dataset is
``contactlib.io.write_dataset(contactlib.io.history_to_dataset(result), path)``.
This module is ``contactlib.history_api`` so that the package's public
function ``contactlib.history`` does not hide it.

Examples
--------
>>> from contactlib import history
>>> res = history("sphere", 0.3, 0.15, [0, 1, 0], 10, n=60)
>>> bool(res.converged.all()), float(res.load_ratio[10]), float(res.pressure[-1].max())
(True, 1.0, 0.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Callable, Sequence

import numpy as np

from .solvers import history_solver as hs
from .model import load_paths, profiles
from . import validate
from .kernels import layer
from .model.body import ElasticBody
from .model import Contact, accepts_model, contact
from .result import history_repr
from .threads import blas_single_threaded

__all__ = ["history", "HistoryResult", "DEFAULT_N", "MAX_N", "MAX_STEPS", "DEFAULT_MAX_ERROR",
           "load_levels", "step_times", "creep_extent", "layer_extent"]

DEFAULT_N = validate.HISTORY_DEFAULT_N  # elements over [0, 1.2 a_max]: size a_max / 200
MIN_N = validate.HISTORY_MIN_N
MAX_N = validate.HISTORY_MAX_N
MAX_STEPS = validate.MAX_STEPS  # steps a segment (about 3 min a segment at the default n)
_MIN_SLIP_ELEMENTS = hs.MIN_SLIP_ELEMENTS  # fewer slipping elements: not resolved
DEFAULT_MAX_ERROR = validate.PATH_DEFAULT_MAX_ERROR  # a load path's default accuracy
# tested: tests/test_history_error.py (the estimates against a fourfold refined run at 20 and 50
# steps a segment: below and above it)
_MIN_ORDER_STEPS = 40  # fewer steps a segment: no run C, order 1 (C would be too coarse)
# tested: tests/test_solver_limit.py (a work below the floor reads as zero)
WORK_FLOOR = 1e-4  # the work's error scale: at least this fraction of the indenter's work
# convention: the advice aims at half of max_error
_ADVICE_MARGIN = 2.0  # advice aims at max_error / 2 (see _advice)


@dataclass(repr=False)
class HistoryResult:
    """A followed load path, in the scalings of the module notes.

    Step 0 is the unloaded initial state; step ``i`` (1 ... S) ends the
    ``i``-th load step. Per-element arrays have shape ``(S + 1, n)``.

    Attributes
    ----------
    geometry, nu, friction, load_path, steps, n, slab_ratio
        The input (``friction`` may be ``inf``: no slip).
    xi : ndarray, shape (n,)
        Element midpoints r / a_max (collocation points).
    xi_bounds : ndarray, shape (n, 2)
        Element edges r / a_max.
    segment : ndarray of int, shape (S + 1,)
        Path segment of each step (1-based; 0 for the initial state).
    load_ratio : ndarray
        P / P_max.
    contact_radius, stick_ratio, indentation, frictional_work : ndarray
        a / a_max, c / a, delta R / a_max^2, cumulative work.
    state : ndarray of int8, shape (S + 1, n)
        0 separated, 1 stick, 2 slip toward the axis, 3 slip away from it.
    pressure, shear, tangential_displacement : ndarray, shape (S + 1, n)
        p / p0, q / p0, u R / a_max^2 at the element midpoints.
    converged : ndarray of bool
        Active-set iteration converged (a failed step is kept and flagged).
    iterations : ndarray of int
        Active-set iterations of the step.
    residual_norm : ndarray
        Largest scaled violation of any contact or friction condition.
    message : str
        Note on non-converged steps, degenerate cases; empty otherwise.
    stick_radius_error_estimate : ndarray
        Estimated absolute error of the stick radius c / a_max (NaN when the
        estimate was skipped); see :func:`history`.
    work_error_estimate : ndarray
        Estimated error of ``frictional_work`` relative to ``work_scale``,
        the path's total frictional work (NaN when skipped); at the last
        step the relative error of the path's work.
    energy_error_estimate : ndarray
        Estimated error of ``external_work``, ``stored_energy`` and
        ``viscous_work`` (the largest) relative to ``energy_scale``, the
        largest external work of the path; ``inf`` where a value is not
        finite (NaN when skipped).
    work_scale, energy_scale : float
        The scales of the two estimates (units of ``frictional_work``):
        the path's total frictional work, at least ``WORK_FLOOR`` (1e-4)
        times ``energy_scale``; the largest external work.
    resolved : ndarray of bool
        The step converged, every value it reports is finite, its slip zone
        is absent or spans at least 12 elements, and no estimate exceeds
        ``max_error``.
    resolved_quantities : dict of str to bool
        Whether ``frictional_work``, ``stick_radius`` and ``energies`` are
        resolved along the whole path (every step converged and within
        ``max_error`` at the quantity's scale; the work also needs a slip
        zone of at least 12 elements at the top load; the stick radius is
        not judged at the steps that move the contact edge over more than
        an element, from or to no contact, where each step is a one-step
        load that no refinement of equal steps resolves).
    unresolved_reasons : dict of str to str
        For each quantity of ``resolved_quantities`` that is not resolved, its
        first failing condition in words (the contact reaching the mesh's end,
        steps that did not converge, values that are not finite, a slip zone
        under 12 elements, or the estimate's largest value at the quantity's
        scale); resolved quantities are absent.
    max_error : float
        The accuracy a step must reach to be resolved.
    tolerance : float
        The tolerance planned for (:func:`history` with ``tolerance``; NaN otherwise).
    tolerance_met : bool or None
        Whether the planned run's estimates of the path's work and of the stick
        radius at the peak met it (None without a tolerance).
    relaxation, durations : tuple
        The body's Prony terms (g_i, tau_i) and the durations of the path
        segments (unit of tau); both empty for an elastic body.
    mesh_extent : float
        Mesh length over a_max (1.2; a viscoelastic body's mesh covers the
        creep of the contact, see :func:`history`).
    time : ndarray or None
        Time at the end of every step (unit of tau; 0 for step 0); None for
        an elastic body.
    external_work, stored_energy, viscous_work : ndarray
        Cumulative work of the indenter, the body's stored (free) energy and
        the cumulative dissipation of its dashpots, scaled as
        ``frictional_work``; external = stored + viscous + frictional (see
        :mod:`contactlib.energy`). ``viscous_work`` is 0 for an elastic body.
    profile, exponent : str, float
        The indenter's shape h ~ r^d (``"paraboloid"``, 2 by default; see
        :func:`history`).
    segment_steps : tuple of int
        For a shape or table (:mod:`contactlib.model.load_paths`): the steps of each
        segment, a monotone piece of the path (``steps`` is then the steps a
        unit of load travel); () for a list path (``steps`` each).
    load_shape : dict or None
        The shape's keys (or ``{"shape": "table", "points": m}``); None for a
        list path. ``load_path`` then holds the levels at the pieces' ends.
    interpolation_error : float
        Largest deviation of a shape from the straight lines between its steps
        (units of P_max; 0 for an elastic body, whose steps are the shape itself).
    model : contactlib.model.Contact or None
        The problem model that was solved: ask it rather than rebuilding it from
        the fields above, which copy it for the datasets (None when rebuilt from a
        dataset).

    Examples
    --------
    >>> from contactlib import history
    >>> res = history("cylinder", 0.3, 0.2, [0, 1], 4, n=40)
    >>> res.pressure.shape, res.state.shape    # (steps + 1, n)
    ((5, 40), (5, 40))
    >>> int(res.segment[0]), int(res.segment[-1])
    (0, 1)
    """

    geometry: str
    nu: float
    friction: float
    load_path: tuple[float, ...]
    steps: int
    n: int
    slab_ratio: float
    xi: np.ndarray
    xi_bounds: np.ndarray
    segment: np.ndarray
    load_ratio: np.ndarray
    contact_radius: np.ndarray
    stick_ratio: np.ndarray
    indentation: np.ndarray
    frictional_work: np.ndarray
    state: np.ndarray
    pressure: np.ndarray
    shear: np.ndarray
    tangential_displacement: np.ndarray
    converged: np.ndarray
    iterations: np.ndarray
    residual_norm: np.ndarray
    message: str = ""
    stick_radius_error_estimate: np.ndarray | None = None
    work_error_estimate: np.ndarray | None = None
    resolved: np.ndarray | None = None
    max_error: float = DEFAULT_MAX_ERROR
    tolerance: float = math.nan  # planned for (history(..., tolerance=)); NaN otherwise
    tolerance_met: bool | None = None  # None without a tolerance
    indenter_modulus_ratio: float = math.inf  # E1/E2 (inf: rigid)
    indenter_poisson_ratio: float = math.nan  # nu1 (the body's when rigid)
    dundurs_beta: float = math.nan  # beta of the pair (< 0: slip outward while loading)
    relaxation: tuple[tuple[float, float], ...] = ()  # Prony (g, tau); () elastic
    durations: tuple[float, ...] = ()  # of the path segments (viscoelastic only)
    mesh_extent: float = hs.MESH_EXTENT  # mesh length over a_max
    time: np.ndarray | None = None  # (S + 1,) viscoelastic only, unit of tau
    external_work: np.ndarray | None = None
    stored_energy: np.ndarray | None = None
    viscous_work: np.ndarray | None = None
    base: str = "smooth"  # the layer's base (irrelevant at slab_ratio 0); "elastic": coated
    substrate_modulus: float = math.inf  # E2/E1 of a coated body's substrate (inf otherwise)
    substrate_poisson_ratio: float = math.nan  # nu2 of a coated body's substrate (NaN otherwise)
    energy_error_estimate: np.ndarray | None = None
    work_scale: float = math.nan
    energy_scale: float = math.nan
    resolved_quantities: dict[str, bool] | None = None
    unresolved_reasons: dict[str, str] = field(default_factory=dict)
    profile: str = "paraboloid"  # the indenter's shape h ~ r^d (contactlib.model.profiles)
    exponent: float = 2.0
    flat_ratio: float = 0.0  # b/a_max of the rounded flat punch (0 otherwise)
    segment_steps: tuple[int, ...] = ()  # steps of each segment of a shape or table; ()
    load_shape: dict | None = None  # the shape or table (contactlib.model.load_paths); None: list
    interpolation_error: float = 0.0  # of a shape between the steps (units of P_max)
    model: Contact | None = field(default=None, repr=False, compare=False)  # what was solved

    def __repr__(self) -> str:  # a few lines: key numbers, arrays by shape
        return history_repr(self)

    def profile_shape(self) -> profiles.Profile:
        """The indenter's profile (:class:`contactlib.model.profiles.Profile`) of the run."""
        return profiles.of_result(self)

    def segment_work(self) -> np.ndarray:
        """Frictional work done during each path segment (scaled as ``frictional_work``)."""
        ends = [self.segment_end(i) for i in range(len(self.load_path))]
        return np.diff(self.frictional_work[ends])

    def segment_end(self, segment: int) -> int:
        """Step index at the end of path segment ``segment`` (1-based; 0: the start)."""
        if self.segment_steps:  # a shape or table: each segment its own steps
            return int(sum(self.segment_steps[:segment]))
        return int(segment * self.steps)


def load_levels(load_path: Sequence[float], steps: int) -> tuple[np.ndarray, np.ndarray]:
    """Load level of every step (``steps`` equal steps a segment) and its segment.

    Returns ``(levels, segment)``, both of length ``steps * (len(load_path) - 1) + 1``;
    ``levels[0] = load_path[0]``, ``segment[0] = 0``.
    """
    path = np.asarray(load_path, dtype=float)
    t = np.arange(1, steps + 1) / steps
    parts = [path[:1]] + [a + (b - a) * t for a, b in zip(path[:-1], path[1:])]
    levels = np.concatenate(parts)
    levels[steps::steps] = path[1:]  # exact path levels at the segment ends
    segment = np.concatenate([[0]] + [np.full(steps, i + 1) for i in range(path.size - 1)])
    return levels, segment


def step_times(durations: Sequence[float], steps: int) -> np.ndarray:
    """Time at the end of every step: ``steps`` equal steps in each segment's duration.

    Returns an array of length ``steps * len(durations) + 1`` starting at 0,
    matching :func:`load_levels`.
    """
    ends = np.concatenate([[0.0], np.cumsum(np.asarray(durations, dtype=float))])
    t = np.arange(1, steps + 1) / steps
    parts = [ends[:1]] + [a + (b - a) * t for a, b in zip(ends[:-1], ends[1:])]
    times = np.concatenate(parts)
    times[steps::steps] = ends[1:]
    return times


def creep_extent(model: Contact) -> float:
    """Mesh length over a_max that covers the creep of the contact (``MESH_EXTENT`` if elastic).

    Under a load held long enough the frictionless contact radius at P_max
    grows to the Hertz radius at E(inf): ``hertz_radius(1/g_inf)`` a_max,
    ``g_inf^(-1/3)`` (sphere) or ``g_inf^(-1/2)`` (cylinder on a half-plane;
    a slab on a rigid base grows less). The mesh keeps 1.2 times that.
    """
    relaxed = getattr(model.body, "relaxed_ratio", 1.0)
    return hs.MESH_EXTENT * model.frictionless_radius(1.0 / relaxed)


# tested: tests/test_thin_layer_history.py (the probe-sized mesh holds the contact)
_PROBE_N = 64  # elements of the frictionless probe that sizes a layer's mesh
# convention: beyond this a_max/h the cylinder's mesh on a thin layer (any base) is sized by
# the probe (tests/test_coated_history_thin.py); below it the mesh stays 1.2 a_max, as before
_CYLINDER_PROBE_RATIO = 20.0


def layer_extent(model: Contact, geometry: str, slab: float) -> float:
    """Mesh length over a_max on a layer or a coated body (``MESH_EXTENT`` where it fits).

    a_max is the Hertz radius at P_max of a half-space of the layer's material. Two
    cases need a mesh sized by the contact itself:

    * a substrate softer than the coating (m = E1*/E2* > 1) lets the contact grow
      beyond a_max, up to the substrate's own radius ``frictionless_radius(m)`` a_max
      (the coated body is stiffer than a half-space of the substrate);
    * a sphere on a layer thinner than the ring tables reach (a_max/h beyond
      ``layer.RATIO_MAX / MESH_EXTENT``, 16.7; the transform-domain sums of
      :mod:`contactlib.kernels.thin_layer` take over) has a contact well inside a_max
      (0.46 a_max at a_max/h = 30 on a bonded base, about (16 h/(3 pi a_max))^(1/4)
      a_max on a thin smooth one): a mesh over 1.2 a_max would spend most of its
      elements outside it; so does a cylinder on a smooth base or a coated one beyond
      a_max/h = ``_CYLINDER_PROBE_RATIO`` (20).

    There a frictionless one-step probe on ``_PROBE_N`` elements over ``MESH_EXTENT``
    times the bound (at most the kernels' reach) finds the radius a_p, and the mesh
    keeps ``MESH_EXTENT (a_p + one probe element)``. A viscoelastic layer creeps: its
    probe is the elastic layer at E(inf), load 1/g_inf in units of E(0) (the fully crept
    contact; the layer relaxes as a whole), bounded by the half-space's crept radius; a
    viscoelastic layer that is not thin keeps that bound (:func:`creep_extent`).
    Elsewhere the mesh is ``MESH_EXTENT`` (the contact stays within a_max).

    Raises
    ------
    validate.InputError
        Naming ``slab_ratio`` when the contact reaches beyond the kernels' range
        (a_max/h too large for this substrate).
    """
    body = model.body
    coated = getattr(body, "base", None) == validate.COATED_BASE
    m = 1.0
    if coated:
        sub = body.kernel_base
        m = (1.0 - sub.nu ** 2) / ((1.0 - body.nu ** 2) * float(body.substrate_modulus))
    # the farthest mesh point over h the kernels reach (the sphere's rings: the thin
    # sums' r/h <= 1200; the cylinder's coated strips: its a/h limit times the mesh's 1.2)
    if geometry == "sphere":
        reach = layer.THIN_RATIO_MAX
        thin = slab * hs.MESH_EXTENT > layer.RATIO_MAX
    else:
        reach = (validate.LAYER_RATIO_MAX[(geometry, validate.COATED_BASE)]
                 * validate.HISTORY_MESH_EXTENT) if coated else math.inf
        # a thin layer shrinks the contact well inside a_max (0.12 a_max at a_max/h = 500,
        # smooth base; 0.32 at 1000 on E2/E1 = 10; 0.098 at 1000 on a bonded base): a mesh
        # over 1.2 a_max left 19 ... 60 of n = 240 elements on it
        # (benchmarks/report_coated_history_thin.py, tests/test_coated_history_thin.py)
        thin = slab > _CYLINDER_PROBE_RATIO and getattr(body, "base", None) in (
            "smooth", "bonded", validate.COATED_BASE)
    relaxed = getattr(body, "relaxed_ratio", 1.0)
    if relaxed != 1.0 and not thin:
        extent = creep_extent(model)
        if extent * slab > reach:
            raise validate.InputError(
                "slab_ratio", "small enough that the crept contact stays within the "
                "kernels' range", slab, f"slab_ratio = {slab:g} is too large for this "
                f"relaxation: the mesh over the fully crept contact would reach "
                f"{extent * slab:.3g} h, beyond the {reach:g} h the layer's kernels cover")
        return extent
    if m <= 1.0 and not thin:
        return hs.MESH_EXTENT
    level = 1.0 / relaxed  # a creeping layer's contact at E(inf): the load 1/g_inf at E(0)
    bound = model.frictionless_radius(max(m, level)) if max(m, level) > 1.0 else 1.0
    probe = min(hs.MESH_EXTENT * bound, reach / slab)
    elastic = model if relaxed == 1.0 else replace(
        model, body=ElasticBody(body.nu, body.slab_ratio, body.base))
    raw = hs.run_history(hs.build_operators(elastic, _PROBE_N, probe), 0.0,
                         np.array([0.0, level]))
    extent = hs.MESH_EXTENT * (float(raw.contact_radius[-1]) + probe / _PROBE_N)
    if np.any(raw.state[-1, -2:] > 0) or extent * slab > reach:
        grows = (f"beyond {probe:.3g} a_max ({probe * slab:.3g} h)"
                 if np.any(raw.state[-1, -2:] > 0) else
                 f"to {extent / hs.MESH_EXTENT:.3g} a_max and the mesh of {hs.MESH_EXTENT:g} "
                 f"times that would reach {extent * slab:.3g} h")
        raise validate.InputError(
            "slab_ratio", "small enough that the contact stays within the kernels' range",
            slab, f"slab_ratio = {slab:g} is too large for this "
            + (f"soft substrate (E1*/E2* = {m:.3g})" if relaxed == 1.0 else "relaxation")
            + f": the contact grows {grows}, beyond the {reach:g} h the layer's "
            f"kernels cover; use a thicker coating (smaller slab_ratio)")
    return extent if thin else max(extent, hs.MESH_EXTENT)


def _relative(error: np.ndarray, scale: float) -> np.ndarray:
    """``error / scale``; 0 where the error is 0 (whatever the scale), inf where NaN."""
    with np.errstate(divide="ignore", invalid="ignore"):
        out = np.where(error == 0.0, 0.0, error / scale)
    return np.where(np.isnan(out), np.inf, out)


def _finite_steps(raw: hs.RawHistory, energies: Sequence[str]) -> np.ndarray:
    """Per step: every reported number is finite (NaN is never resolved; the stick radius is
    NaN by definition without contact and not judged here)."""
    ok = np.all(np.isfinite(raw.p) & np.isfinite(raw.q) & np.isfinite(raw.u), axis=1)
    for name in ("work", "delta", "contact_radius") + tuple(energies):
        ok &= np.isfinite(getattr(raw, name))
    return ok


def _advice(n: int, steps: int, needs: dict[str, tuple[float, float]],
            max_error: float) -> str:
    """The run predicted to resolve the path, if the tool accepts one.

    ``needs`` maps a quantity to (its largest estimate / ``max_error``, the
    order p of its error under joint refinement of n and steps, measured
    by :func:`contactlib.solvers.history_solver.error_estimates`; 1 for the stick
    radius), and ``slip_zone`` to (12 / the slip zone's elements at the top
    load, 1). The run aims at estimates of ``max_error / 2``: an estimate
    moves by about a factor 2 between neighbouring runs (the stick radius's
    differences on element edges come in whole elements), so a run aimed at
    ``max_error`` itself would miss it about half the time. Refining both
    by r divides the estimate by r^p, so the run is ``r = max
    (ratio^(1/p))`` times n and steps. Where that exceeds ``MAX_N`` or
    ``MAX_STEPS``, the largest accepted refinement is advised if it is
    predicted to reach ``max_error`` (without the margin); else no run is
    advised and the text says what that refinement is predicted to reach.
    """
    if not any(ratio > 1.0 for ratio, _ in needs.values()):
        return ""
    # aim at half of max_error: an estimate moves by about a factor 2 between neighbouring
    # runs (the stick radius's element-edge differences come in whole elements)
    needs = {q: (ratio * (_ADVICE_MARGIN if q != "slip_zone" else 1.0), order)
             for q, (ratio, order) in needs.items()}
    needs = {q: (ratio, order) for q, (ratio, order) in needs.items() if ratio > 1.0}
    if not all(math.isfinite(ratio) for ratio, _ in needs.values()):
        return "an estimate is not finite: no run can be advised"
    r = max(ratio ** (1.0 / order) for ratio, order in needs.values())
    n_new, steps_new = math.ceil(r * n), math.ceil(r * steps)
    if n_new <= MAX_N and steps_new <= MAX_STEPS:
        return f"n = {n_new} with {steps_new} steps a segment is predicted to resolve it"
    r_max = min(MAX_N / n, MAX_STEPS / steps)
    reach = max([ratio / r_max ** order for q, (ratio, order) in needs.items()
                 if q != "slip_zone"] or [0.0]) * max_error / _ADVICE_MARGIN
    slip_ok = needs.get("slip_zone", (1.0, 1.0))[0] <= r_max
    n_max, steps_max = math.floor(r_max * n), math.floor(r_max * steps)
    if reach <= max_error and slip_ok:  # the margin does not fit, the prediction does
        return (f"n = {n_max} with {steps_max} steps a segment (the largest the tool "
                f"accepts) is predicted to resolve it, estimates about {reach:.2g}")
    limit = f"n <= {MAX_N}" if n_new > MAX_N else f"steps <= {MAX_STEPS}"
    return (f"no accepted run resolves it ({limit}: it needs n = {n_new}, "
            f"{steps_new} steps); n = {n_max}, {steps_max} steps a segment is predicted "
            f"to reach {reach:.2g}")


# ----------------------------------------------------------------------------- public API
@accepts_model
@blas_single_threaded
def history(geometry: str, nu: float, friction: float, load_path: Sequence[float],
            steps: int | None = None, *, n: int | None = None, slab_ratio: float = 0.0,
            progress: Callable[[int, int], None] | None = None,
            max_error: float | None = None, error_estimate: bool = True,
            indenter_modulus: float = math.inf,
            indenter_nu: float | None = None,
            relaxation: Sequence[Sequence[float]] | None = None,
            duration: float | Sequence[float] | None = None,
            base: str = "smooth", profile: str = "paraboloid",
            exponent: float | None = None,
            tolerance: float | None = None, substrate_modulus: float | None = None,
            substrate_nu: float | None = None,
            flat_ratio: float | None = None) -> HistoryResult:
    """Follow a normal load path with incremental Coulomb stick-slip.

    Parameters
    ----------
    geometry : {"sphere", "cylinder"} or Contact
        Rigid sphere or cylinder (plane strain) on a half-space/half-plane
        (``slab_ratio = 0``), on a layer on a rigid base, or on a coated body
        (``base="elastic"``); or the whole model (:func:`contactlib.contact`), which
        then also gives ``nu`` and the body's, indenter's and profile's keywords
        (``history(model, friction, load_path, steps)``).
    nu : float
        Poisson's ratio, in (-1, 0.5].
    friction : float
        Coulomb coefficient k >= 0; ``inf`` forbids slip.
    load_path : sequence of float, or mapping
        Load levels P / P_max in [0, 1], starting at 0 (the body starts
        unloaded), e.g. ``[0, 1, 0]`` for a load-unload cycle, linear in
        between. Or a named periodic shape, ``{"shape": "sinusoidal" |
        "haversine", "amplitude": A, "mean": M, "frequency": f, "cycles": N}``
        (levels; f in 1 / unit of tau, needed with a relaxation only), or a
        sampled table ``{"time": [...], "load": [...]}`` (time in the unit of
        tau); see :mod:`contactlib.model.load_paths`. A shape or table is cut into
        monotone pieces, the path segments, and its durations come from its
        times (``duration`` is then not given).
    steps : int, optional
        Equal load steps per path segment of a list (>= 1; 1 gives the
        one-step load; default 200, :data:`contactlib.validate.HISTORY_DEFAULT_STEPS`).
        For a shape or table: steps a unit of load travel, each piece getting
        the steps its load change needs (a multiple of 4, at least
        ``min(steps, 40)``; :func:`contactlib.model.load_paths.plan`).
    n : int, optional
        Elements over ``[0, 1.2 a_max]`` (default 240: element size a_max/200);
        with a relaxation over ``[0, 1.2 a_inf]``, a_inf the fully crept
        contact radius (:func:`creep_extent`), so the elements are larger.
    slab_ratio : float
        a_max / h of the layer (0: half-space or half-plane); h is fixed
        while a grows. Up to 1000 for the sphere (any base) and as
        ``validate.LAYER_RATIO_MAX`` for the cylinder. Beyond a_max/h = 16.7
        the sphere's contact stays well inside a_max and its mesh is sized by
        a frictionless probe to 1.2 times the contact; on a coated body whose
        substrate is softer than the coating the contact outgrows a_max and
        the mesh with it (:func:`layer_extent`); a contact whose mesh would
        reach beyond the kernels' range (1200 h for the sphere) is refused
        naming ``slab_ratio``.
    progress : callable, optional
        ``progress(i, total)`` after each step of the main run.
    max_error : float
        Accuracy a step must reach to be flagged ``resolved``, in (0, 1): the
        bound on the stick radius error (units of a_max), on the error of the
        cumulative frictional work relative to the path's total work, and on
        the energies' error relative to the path's largest external work.
        Default (None) 1e-2 (see the notes).
    error_estimate : bool
        Estimate the errors from an embedded coarser run (default). If False
        the estimates are NaN and ``resolved`` reflects only convergence and
        the resolution of the slip zone.
    indenter_modulus, indenter_nu : float
        An elastic indenter, as for :func:`contactlib.solve` (E1/E2, default
        ``inf``: rigid; nu1, default the body's). Scalings use the composite
        E*; slip and shear take either sign.
    relaxation : sequence of (g, tau), optional
        A viscoelastic body (:class:`contactlib.model.body.ViscoelasticBody`):
        E(t)/E(0) = 1 - sum g_i (1 - exp(-t/tau_i)), g_i > 0, sum g_i < 1,
        tau_i > 0, with a constant Poisson's ratio. E* (so a_max, P_max and
        p0) is the instantaneous one, E*(0). Needs a rigid indenter.
    duration : float or sequence of float
        With a relaxation and a list path (required then, refused otherwise):
        the duration of the path (its segments equally long) or of each
        segment, in the unit of tau. Any unit will do if the relaxation
        times are in the same one (seconds with tau in seconds): only their
        ratios enter.
    base : {"smooth", "bonded", "elastic"}
        The layer's base (default smooth): rigid and frictionless or bonded,
        or ``"elastic"``, a coated body: the layer (E, ``nu``; E* is the
        layer's) bonded to an elastic half-space or half-plane of
        ``substrate_modulus`` and ``substrate_nu``, a_max/h <= 20/1.2 (elastic
        body only: a relaxation is refused on it).
    profile : {"paraboloid", "cone", "power", "flat", "rounded"}
        The indenter's shape h ~ r^d (default the paraboloid; :mod:`contactlib.model.profiles`).
        Then a_max is the profile's frictionless contact radius at P_max, P_max its
        frictionless load there, the pressure unit the peak pressure of the paraboloid
        with that load, and the work in units of E* (A d)^2 a_max^(2d+1) (per unit
        length a_max^(2d)) for h = A r^d. ``flat``: the flat punch, a_max its radius
        (units in docs/profiles.md); ``rounded``: the rounded flat punch, h = (|r| -
        b)^2/(2R) beyond its flat radius b, with R and the work scaled as the
        paraboloid's.
    exponent : float, optional
        d for ``profile="power"``, in [0.5, 8] (omitted otherwise).
    flat_ratio : float, optional
        b/a_max for ``profile="rounded"``, in [0, 0.9] (omitted otherwise).
    tolerance : float, optional
        Plan n and steps instead (``steps`` and ``n`` then None): the accuracy,
        in [1e-5, 1e-2], asked of the path's frictional work (relative to its
        total) and of the stick radius at the peak load (units of a_max); it
        becomes ``max_error``. The plan, the check of the run's estimates and
        the refinements: :mod:`contactlib.history_plan`. ``tolerance_met``
        says whether the run got there; a plan beyond the largest n raises
        :class:`contactlib.validate.SolverLimit`.
    substrate_modulus, substrate_nu : float, optional
        E2/E1 of the coated body's substrate over the layer, in [1e-2, 1e6]
        (required with ``base="elastic"``, refused otherwise), and its
        Poisson's ratio (default the layer's ``nu``), as for
        :func:`contactlib.solve`.

    Returns
    -------
    HistoryResult

    Raises
    ------
    ValueError
        For invalid input; the message names the argument.

    Notes
    -----
    Error estimates: the same path is followed on a mesh of ``n // 2``
    elements with ``steps // 2`` steps a segment (run A) and, from 40 steps a
    segment, on ``n // 4`` elements with ``steps // 4`` (run C); their
    values are interpolated to the same point of the path (see
    :func:`contactlib.solvers.history_solver.error_estimates`). The work's and the
    energies' order of convergence under this joint refinement is measured
    from the three runs, and their error is this run minus run A over
    ``2^p - 1`` (Richardson); the stick radius error is half of this run
    minus run A where the stick edge crosses an element within six steps
    (run A's quantization of the edge is twice the run's), at least the run's
    own deviation from a local quadratic there, in full where the edge
    crosses no element, not across a jump of A's stick radius, and at least
    half an element wherever the stick radius is an element edge. Measured against runs
    refined fourfold (4n elements, 4x steps;
    ``benchmarks/report_history_estimates.py``, docs/accuracy.md) at n =
    120, 50 steps and n = 240, 100 steps: the cycle work's estimate is 0.48
    ... 1.46 times its error (sphere and half-plane cycles and fretting, a
    viscoelastic body, a layer at n = 240; measured orders 1.3 ... 2.1), 16
    times on a layer whose slip annulus spans under 12 elements (n = 120: the
    runs are not asymptotic there, the measured order falls to its bound
    1/2); the stick radius's covers its error along the path (at least 0.50
    of it), its median over the largest error within two steps is 0.84 ...
    1.67 (located edges), a segment's largest is 0.97 ... 4.6 times the
    segment's largest error (9.9 on the half-plane at nu = 0, n = 120, whose
    stick zone of four elements keeps its edge), and 0.72 ... 18 times the
    error at the top load, where a step's error may be near 0 as the edge
    crosses an element, or the stick radius is an element edge (k = 0.05).
    The estimate costs about a third of the run. At ``friction = 0`` there is
    no stick zone (|q| < k p cannot hold): the stick radius is 0 with
    estimate 0, as :func:`contactlib.solve` says at friction 0.

    A step is flagged where a quantity is off by more than ``max_error`` at
    its own scale (above); ``resolved_quantities`` and ``message`` say which
    quantities the path resolves, and a flagged history's ``message`` names
    the n and steps that the measured orders predict will resolve it (aimed
    at ``max_error / 2``), or says that no run within ``MAX_N`` and
    ``MAX_STEPS`` is predicted to. ``max_error`` defaults to 1e-2
    (``validate.PATH_DEFAULT_MAX_ERROR``), what the default n = 240 and 200
    steps a segment deliver: a cycle's work to about 2e-3 (sphere, k = 0.2)
    and an element-edge stick radius to half an element (0.0025 a_max); ask
    ``max_error=1e-3`` (about 4 n and 4 x steps) or ``tolerance=1e-3``, which
    plans them.

    Measured against the self-similar solver (sphere, nu = 0.3, monotonic
    loading): c/a within 0.25 % for c/a = 0.2 ... 0.9 at n = 120 ... 480 and
    50 ... 800 steps. The work of a 0 -> 1 -> 0 cycle at the default n and
    1600 steps a segment agrees with n = 480 to 0.1 % (c/a = 0.7 at the top)
    and 0.5 % (c/a = 0.9); see ``benchmarks/report_history.py``.

    Examples
    --------
    A load-unload cycle, 10 steps a segment:

    >>> from contactlib import history
    >>> res = history("sphere", 0.3, 0.2, [0, 1, 0], 10, n=60)
    >>> res.load_ratio.shape      # step 0 (unloaded), then 2 x 10 steps
    (21,)
    >>> float(res.load_ratio[10]), float(res.load_ratio[-1])
    (1.0, 0.0)
    >>> bool(res.frictional_work[-1] > res.frictional_work[10] > 0)  # unloading slips too
    True

    Without friction, or without slip, nothing is dissipated:

    >>> [float(history("sphere", 0.3, k, [0, 1], 5, n=60).frictional_work[-1])
    ...  for k in (0.0, float("inf"))]
    [0.0, 0.0]
    """
    if tolerance is not None and base == validate.COATED_BASE:
        raise validate.InputError("tolerance", "unset on a coated body (base 'elastic')",
                                  tolerance, "tolerance is not planned on a coated body (base "
                                  "'elastic'), as in solve: give steps and n instead")
    if tolerance is not None:  # plan n and steps (contactlib.history_plan)
        from .history_plan import history_to_tolerance

        for name, value in (("steps", steps), ("n", n)):
            if value is not None:
                raise validate.InputError(name, "None with tolerance", value,
                                          f"{name} must be None with tolerance (the plan "
                                          f"picks it), got {value!r}")
        for name, value, default in (("max_error", max_error, None),
                                     ("error_estimate", error_estimate, True)):
            if value is not default and value != default:
                raise validate.InputError(name, "not given with tolerance", value,
                                          f"{name} must not be given with tolerance (the "
                                          f"tolerance is the accuracy asked for and needs "
                                          f"the estimates), got {value!r}")
        return history_to_tolerance(
            history, geometry, nu, friction, load_path, tolerance, slab_ratio=slab_ratio,
            progress=progress, indenter_modulus=indenter_modulus, indenter_nu=indenter_nu,
            relaxation=relaxation, duration=duration, base=base, profile=profile,
            exponent=exponent, substrate_modulus=substrate_modulus, substrate_nu=substrate_nu,
            flat_ratio=flat_ratio)
    geometry = validate.geometry(geometry)
    nu = validate.nu(nu)
    k = validate.friction(friction)
    shaped = load_paths.is_shaped(load_path)
    path = load_paths.load_path(load_path) if shaped else None
    levels_in = () if shaped else validate.load_path(load_path)
    steps = validate.steps(validate.HISTORY_DEFAULT_STEPS if steps is None else steps)
    n = validate.history_n(n)
    base = validate.base(base, coated=True)
    slab = validate.slab_ratio(slab_ratio, geometry, base, extent=validate.HISTORY_MESH_EXTENT)
    sub_modulus, sub_nu = validate.substrate(base, substrate_modulus, substrate_nu, geometry)
    progress = validate.callback("progress", progress)
    max_error = validate.max_error(DEFAULT_MAX_ERROR if max_error is None else max_error)
    error_estimate = validate.flag("error_estimate", error_estimate)
    ratio, nu1 = validate.indenter_material(indenter_modulus, indenter_nu)
    prony = validate.relaxation(relaxation)
    if shaped:
        step_plan = _shaped_plan(path, steps, prony, duration, max_error)
        levels_in = step_plan.knots
        durations = step_plan.durations if prony else ()
    else:
        durations = validate.duration(duration, len(levels_in) - 1, bool(prony))
    if prony and ratio != math.inf:
        raise validate.InputError("relaxation", "given with a rigid indenter", relaxation,
                                  "relaxation needs a rigid indenter (an elastic indenter's "
                                  "compliance would not relax with the body's)")
    if prony and base == validate.COATED_BASE:
        raise validate.InputError("relaxation", "not given on a coated body (base 'elastic')",
                                  relaxation, "relaxation is not available on a coated body "
                                  "(base 'elastic'): the substrate's kernels are elastic only; "
                                  "use a rigid base or an elastic layer")

    shape = profiles.profile(profile, exponent, flat_ratio)
    model = contact(geometry, nu, slab, ratio, nu1, base, relaxation=prony, profile=shape,
                    substrate_modulus=sub_modulus, substrate_nu=sub_nu)
    if shape.fixed_contact:  # the mesh is the punch's face: the contact neither grows nor creeps
        extent = 1.0
    else:
        extent = layer_extent(model, geometry, slab) if slab > 0 else creep_extent(model)
    ops = hs.build_operators(model, n, extent)
    if shaped:
        levels, times, segment = load_paths.sample(path, step_plan, bool(prony))
    else:
        levels, segment = load_levels(levels_in, steps)
        times = step_times(durations, steps) if prony else None

    def times_of(n_steps: int) -> np.ndarray | None:
        return step_times(durations, n_steps) if prony else None

    raw = hs.run_history(ops, k, levels, progress=progress, times=times)
    err_c = np.full(levels.size, np.nan)
    err_w = np.full(levels.size, np.nan)
    err_e = np.full(levels.size, np.nan)
    energy_scale = float(np.max(np.abs(raw.external_work)))  # NaN if any step's is
    work_scale = max(float(np.max(raw.work)), WORK_FLOOR * energy_scale)
    energies = ("external_work", "stored_energy") + (("viscous_work",) if prony else ())
    if error_estimate and shaped:  # the step points of runs A and C: every 2nd and 4th
        n_c = max(n // 2, 8)
        lv_c, t_c, segment_c = load_paths.sample(path, step_plan, bool(prony), 2)
        raw_c = hs.run_history(hs.build_operators(model, n_c, extent), k, lv_c, times=t_c)
        coarser = (None, None, None)
        if min(step_plan.counts) >= _MIN_ORDER_STEPS:
            lv_b, t_b, segment_b = load_paths.sample(path, step_plan, bool(prony), 4)
            ops_b = hs.build_operators(model, max(n_c // 2, 8), extent)
            coarser = (hs.run_history(ops_b, k, lv_b, times=t_b), 1, segment_b)
        # the path coordinate in units of four steps: the pieces' counts are multiples of
        # 4, so runs A and C (2 and 1 steps a unit) meet the run's steps as with a list
        err_c, diffs, orders = hs.error_estimates(raw, ops, 4, segment, raw_c, 2, segment_c,
                                                  *coarser, energies=energies)
    elif error_estimate:
        n_c = max(n // 2, 8)
        steps_c = steps // 2 if steps >= 4 else steps
        levels_c, segment_c = load_levels(levels_in, steps_c)
        ops_c = hs.build_operators(model, n_c, extent)
        raw_c = hs.run_history(ops_c, k, levels_c, times=times_of(steps_c))
        coarser = (None, None, None)
        if steps >= _MIN_ORDER_STEPS:  # the order measured: half the mesh and steps again
            steps_b = steps_c // 2
            levels_b, segment_b = load_levels(levels_in, steps_b)
            ops_b = hs.build_operators(model, max(n_c // 2, 8), extent)
            coarser = (hs.run_history(ops_b, k, levels_b, times=times_of(steps_b)), steps_b,
                       segment_b)
        err_c, diffs, orders = hs.error_estimates(raw, ops, steps, segment, raw_c, steps_c,
                                                  segment_c, *coarser, energies=energies)
    if error_estimate:
        err_w = _relative(diffs["work"], work_scale)
        err_e = np.max([_relative(diffs[name], energy_scale) for name in energies], axis=0)
    if k == 0.0:  # no friction, no stick zone (|q| < k p cannot hold): c = 0 exactly, as in
        # solve (the solver labels no element stuck), and its estimate 0 (not the element
        # edge's floor)
        raw.stick_radius[:] = 0.0
        err_c = np.zeros(levels.size)
    annulus = hs.annulus_resolved(k, raw.state)
    finite = _finite_steps(raw, energies)
    with np.errstate(invalid="ignore"):  # a NaN estimate: not estimated
        ok_c, ok_w, ok_e = (~(e > max_error) for e in (err_c, err_w, err_e))
    resolved = raw.converged & annulus & finite & ok_c & ok_w & ok_e

    with np.errstate(invalid="ignore", divide="ignore"):
        stick_ratio = np.where(raw.contact_radius > 0, raw.stick_radius / raw.contact_radius,
                               np.nan)
    notes = []
    bad = np.flatnonzero(~raw.converged)
    if bad.size:
        notes.append(f"{bad.size} of {levels.size - 1} steps did not converge (first: step "
                     f"{bad[0]}, largest residual {raw.residual[bad].max():.2g}); they are "
                     f"kept and flagged")
    top = int(np.argmax(levels))
    slipping = int(np.count_nonzero(raw.state[top] >= hs.SLIP_INWARD))
    if 0 < k < math.inf and 0 < slipping < _MIN_SLIP_ELEMENTS:
        notes.append(f"the slip zone at the largest load spans only {slipping} elements: "
                     f"the frictional work is poorly resolved, use a larger n")
    # the flat punch's mesh is its face: there the contact ends at the mesh's end by design
    overflow = not shape.fixed_contact and bool(np.any(raw.state[:, -2:] > 0))
    if overflow:
        notes.append("the contact reached the end of the mesh: results are not valid")
        resolved[:] = False
    labels = {"frictional_work": "frictional work", "stick_radius": "stick radius",
              "energies": "energies"}
    loaded = slice(1, None)
    # steps that move the contact edge by more than an element (from or to no contact): each
    # is a one-step load of its own, whose stick radius no refinement of equal steps resolves
    jump = np.concatenate([[False], np.abs(np.diff(raw.contact_radius)) > ops.edges[1]])
    regular = ~jump if not jump[loaded].all() else np.ones(levels.size, dtype=bool)
    verdicts = {  # a quantity is resolved where every step resolves it
        "frictional_work": bool(np.all((raw.converged & np.isfinite(raw.work) & ok_w)[loaded])
                                and not 0 < slipping < _MIN_SLIP_ELEMENTS),
        "stick_radius": bool(np.all((raw.converged & (ok_c | ~regular))[loaded])),
        "energies": bool(np.all((raw.converged & finite & ok_e)[loaded]))}
    if overflow:
        verdicts = dict.fromkeys(verdicts, False)
    with np.errstate(invalid="ignore"):
        worst = {"frictional_work": (np.max(err_w), "of its total"),
                 "stick_radius": (np.max(err_c[regular]), "a_max"),
                 "energies": (np.max(err_e), "of peak external work")}
    values = {"frictional_work": np.isfinite(raw.work), "stick_radius": ~np.zeros(
        levels.size, dtype=bool), "energies": finite}
    reasons = {}
    for q in (q for q, ok in verdicts.items() if not ok):  # the first failing condition
        failed = int(np.count_nonzero(~raw.converged[loaded]))
        missing = int(np.count_nonzero(~values[q][loaded]))
        reasons[q] = (
            "the contact reached the end of the mesh" if overflow else
            f"{failed} of {levels.size - 1} steps did not converge" if failed else
            f"not finite at {missing} of {levels.size - 1} steps" if missing else
            f"the slip zone at the largest load spans {slipping} of the "
            f"{_MIN_SLIP_ELEMENTS} elements it needs" if q == "frictional_work" and 0 < slipping
            < _MIN_SLIP_ELEMENTS else
            f"its estimate reaches {worst[q][0]:.2g} {worst[q][1]} (max_error {max_error:g})")
    if error_estimate:
        parts = [f"{labels[q]} ({worst[q][0]:.2g} {worst[q][1]})"
                 for q, ok in verdicts.items() if not ok]
        good = [labels[q] for q, ok in verdicts.items() if ok]
        notes.append(f"resolved to max_error {max_error:g}: {', '.join(good) or 'nothing'}"
                     + (f"; not: {', '.join(parts)}" if parts else ""))
    if not resolved[1:].all():
        why = [f"{np.count_nonzero(~ok[loaded])} {what}" for ok, what in (
            (raw.converged, "not converged"), (finite, "not finite"),
            (annulus, f"slip zone under {_MIN_SLIP_ELEMENTS} elements"),
            (ok_c, "stick radius"), (ok_w, "work"), (ok_e, "energies"),
            (ok_c | regular, "with the contact edge moving over an element, not judged"))
            if not ok[loaded].all()]
        advice = ""
        if error_estimate:
            needs = {"stick_radius": (worst["stick_radius"][0] / max_error, 1.0),
                     "frictional_work": (worst["frictional_work"][0] / max_error,
                                         orders["work"]),
                     "energies": (worst["energies"][0] / max_error,
                                  min(orders[e] for e in energies))}
            if 0 < slipping < _MIN_SLIP_ELEMENTS:  # the slip zone's elements grow like n
                needs["slip_zone"] = (_MIN_SLIP_ELEMENTS / slipping, 1.0)
            advice = _advice(n, steps, needs, max_error)
            if shaped:  # a shape's steps count a unit of load travel
                advice = advice.replace("steps a segment", "steps a unit of load travel")
        notes.append(f"{np.count_nonzero(~resolved[1:])}/{levels.size - 1} steps flagged "
                     f"({', '.join(why)})" + (f"; {advice}" if advice else ""))
    if shaped and step_plan.interpolation_error > max_error:
        notes.append(f"the shape deviates from the straight lines between its steps by up "
                     f"to {step_plan.interpolation_error:.2g} of P_max (more than max_error)")
    if model.decoupled and k > 0:
        cause = "nu = 0.5" if model.indenter.rigid else "beta = 0"
        notes.append(f"{cause}: the normal and tangential problems decouple; no shear arises")
    return HistoryResult(
        geometry=geometry, nu=nu, friction=k, load_path=levels_in, steps=steps, n=n,
        slab_ratio=slab, xi=ops.mid.copy(),
        xi_bounds=np.stack([ops.edges[:-1], ops.edges[1:]], axis=1),
        segment=segment, load_ratio=levels, contact_radius=raw.contact_radius,
        stick_ratio=stick_ratio, indentation=raw.delta, frictional_work=raw.work,
        state=raw.state, pressure=raw.p / ops.p0, shear=raw.q / ops.p0,
        tangential_displacement=raw.u, converged=raw.converged,
        iterations=raw.iterations, residual_norm=raw.residual, message="; ".join(notes),
        stick_radius_error_estimate=err_c, work_error_estimate=err_w, resolved=resolved,
        energy_error_estimate=err_e, work_scale=work_scale, energy_scale=energy_scale,
        resolved_quantities=verdicts, unresolved_reasons=reasons,
        max_error=max_error, indenter_modulus_ratio=float(ratio),
        indenter_poisson_ratio=float(model.indenter_poisson_ratio),
        dundurs_beta=float(model.beta), relaxation=prony, durations=durations,
        mesh_extent=float(extent), time=raw.time, external_work=raw.external_work,
        stored_energy=raw.stored_energy, viscous_work=raw.viscous_work, base=base,
        substrate_modulus=float(sub_modulus), substrate_poisson_ratio=(
            float(model.body.kernel_base.nu) if base == validate.COATED_BASE else math.nan),
        profile=shape.name, exponent=float(shape.exponent), flat_ratio=float(shape.flat),
        segment_steps=step_plan.counts if shaped else (),
        load_shape=path.describe() if shaped else None,
        interpolation_error=step_plan.interpolation_error if shaped else 0.0, model=model)


def _shaped_plan(path: load_paths.Path, steps: int, prony: tuple, duration: object,
                 max_error: float) -> load_paths.StepPlan:
    """The pieces and steps of a shape or table (:func:`contactlib.model.load_paths.plan`)."""
    if duration is not None:
        raise validate.InputError("duration", "", duration, "duration must not be given with "
                                  "a shape or table: its times give the durations")
    if prony and isinstance(path, load_paths.LoadShape) and path.frequency is None:
        raise validate.InputError("load_path.frequency", "", None, "load_path.frequency is "
                                  "required with a relaxation (1 / unit of tau)")
    return load_paths.plan(path, steps, bool(prony), max_error)
