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
  resolved below the element size from the gap outside the contact, c where
  the stick edge advances (loading) from the stick-traction deficit; where it
  recedes or stands (unloading) c is an element edge, good to half an element
  (see :func:`contactlib.history_solver.contact_radius` and
  :func:`~contactlib.history_solver.stick_radius`). ``stick_ratio`` is NaN
  without contact.

Frictional work of a step: ``sum_j max(0, -(q_j^old + q_j^new)/2 du_j) A_j``
over the elements slipping at the end of the step and those that slipped
and separate in it (trapezoid rule in time, each element's term floored at
0 so that no step dissipates a negative amount, with the element's
shear-weighted area A_j: ``int (r/r_j) 2 pi r dr`` for a ring, ``2 dx`` for
a strip pair; :func:`contactlib.energy.step_work`). Its error falls roughly like 1/steps
(0.2 % at 200 steps a segment for the sphere with c/a = 0.5); a slip zone
spanning few elements (c/a close to 1, large k) also needs a finer mesh, and
``message`` says so when the slip zone at the top load spans fewer than 12
elements.

The numerics live in :mod:`contactlib.history_solver`; writing a dataset is
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
from dataclasses import dataclass
from typing import Callable, Sequence

import numpy as np

from . import history_solver as hs
from . import validate
from .model import Contact, contact
from .result import history_repr
from .threads import blas_single_threaded

__all__ = ["history", "HistoryResult", "DEFAULT_N", "MAX_N", "MAX_STEPS", "DEFAULT_MAX_ERROR",
           "load_levels", "step_times", "creep_extent"]

DEFAULT_N = validate.HISTORY_DEFAULT_N  # elements over [0, 1.2 a_max]: size a_max / 200
MIN_N = validate.HISTORY_MIN_N
MAX_N = validate.HISTORY_MAX_N
MAX_STEPS = validate.MAX_STEPS  # steps a segment (about 3 min a segment at the default n)
_MIN_SLIP_ELEMENTS = hs.MIN_SLIP_ELEMENTS  # fewer slipping elements: not resolved
DEFAULT_MAX_ERROR = validate.DEFAULT_MAX_ERROR
_MIN_SPLIT_STEPS = 40  # fewer steps a segment: one coarse run (B would be too coarse)


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
        Estimated relative error of ``frictional_work`` (NaN when skipped).
    resolved : ndarray of bool
        The step converged, its slip zone is absent or spans at least 12
        elements, and neither estimate exceeds ``max_error``.
    max_error : float
        The accuracy a step must reach to be resolved.
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
    base: str = "smooth"  # the layer's rigid base (irrelevant at slab_ratio 0)

    def __repr__(self) -> str:  # a few lines: key numbers, arrays by shape
        return history_repr(self)

    def segment_work(self) -> np.ndarray:
        """Frictional work done during each path segment (scaled as ``frictional_work``)."""
        ends = np.concatenate([[0], np.arange(1, len(self.load_path)) * self.steps])
        return np.diff(self.frictional_work[ends])

    def segment_end(self, segment: int) -> int:
        """Step index at the end of path segment ``segment`` (1-based)."""
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
    return hs.MESH_EXTENT * model.indenter.hertz_radius(1.0 / relaxed)


def _refinement(n: int, steps: int, err_c: float, err_w: float, max_error: float) -> str:
    """What would resolve the path's last step: n and steps scaled by estimate / max_error.

    Both errors fall about like 1/n and 1/steps together (the work's mesh and step
    parts are first order; the stick radius is good to a fraction of an element),
    so refining both by the ratio r of the last step's larger estimate to
    ``max_error`` resolves it; the time grows like r^3 or more.
    """
    ratio = max(err_c, err_w) / max_error
    if not np.isfinite(ratio) or ratio <= 1.0:
        return "use a larger n and more steps"
    r = math.ceil(ratio * 10.0) / 10.0
    return (f"the last step's estimate is {r:g} x max_error; about n = "
            f"{min(math.ceil(r * n), MAX_N)} with {math.ceil(r * steps)} steps a segment "
            f"would resolve it")


# ----------------------------------------------------------------------------- public API
@blas_single_threaded
def history(geometry: str, nu: float, friction: float, load_path: Sequence[float],
            steps: int, *, n: int | None = None, slab_ratio: float = 0.0,
            progress: Callable[[int, int], None] | None = None,
            max_error: float = DEFAULT_MAX_ERROR, error_estimate: bool = True,
            indenter_modulus: float = math.inf,
            indenter_nu: float | None = None,
            relaxation: Sequence[Sequence[float]] | None = None,
            duration: float | Sequence[float] | None = None,
            base: str = "smooth") -> HistoryResult:
    """Follow a normal load path with incremental Coulomb stick-slip.

    Parameters
    ----------
    geometry : {"sphere", "cylinder"}
        Rigid sphere or cylinder (plane strain) on a half-space/half-plane
        (``slab_ratio = 0``) or on a layer on a rigid base.
    nu : float
        Poisson's ratio, in (-1, 0.5].
    friction : float
        Coulomb coefficient k >= 0; ``inf`` forbids slip.
    load_path : sequence of float
        Load levels P / P_max in [0, 1], starting at 0 (the body starts
        unloaded), e.g. ``[0, 1, 0]`` for a load-unload cycle.
    steps : int
        Equal load steps per path segment (>= 1; 1 gives the one-step load).
    n : int, optional
        Elements over ``[0, 1.2 a_max]`` (default 240: element size a_max/200);
        with a relaxation over ``[0, 1.2 a_inf]``, a_inf the fully crept
        contact radius (:func:`creep_extent`), so the elements are larger.
    slab_ratio : float
        a_max / h of the layer (0: half-space or half-plane); h is fixed
        while a grows. The sphere's mesh reaches 1.2 a_max, so its bound is
        ``LAYER_RATIO_MAX / 1.2`` (16.7).
    progress : callable, optional
        ``progress(i, total)`` after each step of the main run.
    max_error : float
        Accuracy a step must reach to be flagged ``resolved``, in (0, 1): the
        bound on both the stick radius error (units of a_max) and the relative
        error of the cumulative frictional work. Default 1e-2, a history's own
        (see the notes).
    error_estimate : bool
        Estimate the errors from an embedded coarser run (default). If False
        the estimates are NaN and ``resolved`` reflects only convergence and
        the resolution of the slip zone.
    indenter_modulus, indenter_nu : float
        An elastic indenter, as for :func:`contactlib.solve` (E1/E2, default
        ``inf``: rigid; nu1, default the body's). Scalings use the composite
        E*; slip and shear take either sign.
    relaxation : sequence of (g, tau), optional
        A viscoelastic body (:class:`contactlib.body.ViscoelasticBody`):
        E(t)/E(0) = 1 - sum g_i (1 - exp(-t/tau_i)), g_i > 0, sum g_i < 1,
        tau_i > 0, with a constant Poisson's ratio. E* (so a_max, P_max and
        p0) is the instantaneous one, E*(0). Needs a rigid indenter.
    duration : float or sequence of float
        With a relaxation (required then, refused otherwise): the duration of
        the path (its segments equally long) or of each segment, in the
        unit of tau.
    base : {"smooth", "bonded"}
        The layer's rigid base (default smooth).

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
    segment, on the same coarse mesh with ``steps // 4`` (run B); their
    values are interpolated to the same point of the path (see
    :func:`contactlib.history_solver.error_estimates`). The work error is the
    mesh error and the step error estimated separately and added as absolute
    values, so that errors of opposite sign do not cancel; the stick radius
    error is this run minus run A (not across a jump of A's stick radius),
    at least half an element wherever the stick edge is an element edge.
    Measured against runs refined fourfold (4n elements, 4x steps;
    ``benchmarks/report_history.py errors errors_default``, docs/accuracy.md):
    at n = 120, 50 steps (17 paths: sphere and half-plane, nu = 0.3 and 0,
    k = 0.05 ... 0.5, cycles and fretting) the estimates are at least 0.36
    (stick radius) and 0.57 (work) of the error at every step whose slip
    annulus is resolved, and at most 9.3 and 8.5 times the largest error of a
    path segment; at the default n = 240 and 200 steps at least 0.40 and
    0.75 (0.49 over all steps), at most 2.0 and 4.0 times. The estimate
    costs 26 ... 38 % of the run (CPU time, the default config's history
    scenes).

    ``max_error`` defaults to 1e-3, as for self-similar cases. The
    default n = 240 and 200 steps a segment give the cumulative
    work to about 1 % while loading (0.05 ... 0.4 % at the end of a cycle,
    truth n = 960, 800 steps) and an element-edge stick radius to a quarter
    of an element, so at the defaults a history is flagged unless it asks
    for ``max_error=1e-2`` (as the workflow's history scenes do); 1e-3
    needs about 4 n and 4x steps. The ``message`` of a flagged history
    names the n and steps that would resolve its last step.

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
    geometry = validate.geometry(geometry)
    nu = validate.nu(nu)
    k = validate.friction(friction)
    levels_in = validate.load_path(load_path)
    steps = validate.steps(steps)
    n = validate.history_n(n)
    base = validate.base(base)
    slab = validate.slab_ratio(slab_ratio, geometry, base, extent=validate.HISTORY_MESH_EXTENT)
    progress = validate.callback("progress", progress)
    max_error = validate.max_error(max_error)
    error_estimate = validate.flag("error_estimate", error_estimate)
    ratio, nu1 = validate.indenter_material(indenter_modulus, indenter_nu)
    prony = validate.relaxation(relaxation)
    durations = validate.duration(duration, len(levels_in) - 1, bool(prony))
    if prony and ratio != math.inf:
        raise validate.InputError("relaxation", "given with a rigid indenter", relaxation,
                                  "relaxation needs a rigid indenter (an elastic indenter's "
                                  "compliance would not relax with the body's)")

    model = contact(geometry, nu, slab, ratio, nu1, base, relaxation=prony)
    extent = creep_extent(model)
    ops = hs.build_operators(model, n, extent)
    levels, segment = load_levels(levels_in, steps)

    def times_of(n_steps: int) -> np.ndarray | None:
        return step_times(durations, n_steps) if prony else None

    raw = hs.run_history(ops, k, levels, progress=progress, times=times_of(steps))
    err_c = np.full(levels.size, np.nan)
    err_w = np.full(levels.size, np.nan)
    if error_estimate:
        n_c = max(n // 2, 8)
        steps_c = steps // 2 if steps >= 4 else steps
        levels_c, segment_c = load_levels(levels_in, steps_c)
        ops_c = hs.build_operators(model, n_c, extent)
        raw_c = hs.run_history(ops_c, k, levels_c, times=times_of(steps_c))
        coarser = (None, None, None)
        if steps >= _MIN_SPLIT_STEPS:  # separate step error: the same mesh, half the steps again
            steps_b = steps_c // 2
            levels_b, segment_b = load_levels(levels_in, steps_b)
            coarser = (hs.run_history(ops_c, k, levels_b, times=times_of(steps_b)), steps_b,
                       segment_b)
        err_c, err_w = hs.error_estimates(raw, ops, steps, segment, raw_c, steps_c, segment_c,
                                          *coarser)
    annulus = hs.annulus_resolved(k, raw.state)
    with np.errstate(invalid="ignore"):
        accurate = ~((err_c > max_error) | (err_w > max_error))  # NaN: not estimated
    resolved = raw.converged & annulus & accurate

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
    if np.any(raw.state[:, -2:] > 0):
        notes.append("the contact reached the end of the mesh: results are not valid")
        resolved[:] = False
    if not resolved[1:].all():
        why = []
        if not annulus.all():
            why.append(f"{np.count_nonzero(~annulus)} with a slip zone under "
                       f"{_MIN_SLIP_ELEMENTS} elements")
        if not accurate.all():
            why.append(f"{np.count_nonzero(~accurate)} estimated above max_error = "
                       f"{max_error:g} (stick radius error up to {np.nanmax(err_c):.2g} a_max, "
                       f"relative work error up to {np.nanmax(err_w):.2g})")
        notes.append(f"{np.count_nonzero(~resolved[1:])} of {levels.size - 1} steps are flagged "
                     f"not resolved ({'; '.join(why) or 'not converged'}): "
                     f"{_refinement(n, steps, err_c[-1], err_w[-1], max_error)}")
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
        max_error=max_error, indenter_modulus_ratio=float(ratio),
        indenter_poisson_ratio=float(model.indenter_poisson_ratio),
        dundurs_beta=float(model.beta), relaxation=prony, durations=durations,
        mesh_extent=float(extent), time=raw.time, external_work=raw.external_work,
        stored_energy=raw.stored_energy, viscous_work=raw.viscous_work, base=base)
