r"""Fretting of the cylinder: :func:`fretting`, a normal and a tangential load path.

The numerics are in :mod:`contactlib.solvers.fretting_solver`; this module checks the input,
plans the runs, estimates the errors from coarser runs and a run on a shifted mesh
(:func:`fretting`, ``error_estimate``) and returns a :class:`FrettingResult`. Units are those of
:mod:`contactlib.history_api`: E* = R = 1, lengths in units of ``a_max`` (the
frictionless contact half-width at ``P_max``), the pressure unit ``p0``
(1/2 for Hertz's cylinder), work per unit length in ``E* a_max^4/R^2``.

The path
--------
``load_path`` gives P/P_max and ``tangential_path`` Q/(k P_max) at the same
points; both vary linearly between them, ``steps`` equal steps a segment. The
first point is the unloaded start (both 0), so every path begins with the
normal loading the history solver also follows, and the radial (here: inward
or outward) shear that loading locks in is the initial state of the tangential
loading. ``bulk_stress`` optionally gives the body's stress along x, in units
of ``p0``, at the same points (the fretting-fatigue specimen under tension).

Gross sliding (|Q| = k P) has no stick zone and no equilibrium under a force
control, so every point with P > 0 must have |Q| < k P (|tangential_path| <
load_path), and Q = 0 where P = 0.

The sphere also follows a prescribed rigid shift (``tangential_displacement=True``:
``tangential_path`` gives s R/a_max^2, 0 where P = 0): Q is then the answer, and gross
sliding (Q = k P, no stick zone) is reached like any other state. The cylinder refuses it:
a half-plane's rigid shift is defined only up to its logarithmic datum.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from .solvers import fretting_solver as fr
from .solvers import fretting_sphere as fsph
from . import validate
from .history_api import load_levels
from .solvers.history_solver import ORDER_MAX, measured_order
from .model import contact
from .model.profiles import takes
from .model.profiles import profile as make_profile
from .model.theory import cylinder_cycle_work
from .threads import blas_single_threaded
from .validate import PATH_DEFAULT_MAX_ERROR as DEFAULT_MAX_ERROR

__all__ = ["FrettingResult", "fretting", "finer_run", "check_input", "amplitude_study",
           "STUDY_AMPLITUDES",
           "DEFAULT_N", "DEFAULT_STEPS", "SPHERE_DEFAULT_N", "SPHERE_DEFAULT_STEPS", "defaults",
           "sphere_fretting", "cylinder_cycle_work", "run_path", "StickShape", "stick_shape",
           "stick_map_study", "STICK_MAP_CASES", "STICK_MAP_PATH", "STICK_MAP_MAX_ERROR"]

# convention: the cylinder's default elements (element a_max/100)
DEFAULT_N = 120  # elements over 1.2 a_max, each side of the axis: element a_max/100
# convention: the cylinder's default steps a segment
DEFAULT_STEPS = 40  # equal steps a path segment
# convention: the sphere's default grid
SPHERE_DEFAULT_N = 64  # the sphere: cells a side of [-1.2, 1.2]^2 a_max (cell a_max/27)
# convention: the sphere's default steps a segment
SPHERE_DEFAULT_STEPS = 8
# convention: the largest grid accepted (memory and time of the FFT products)
SPHERE_N_MAX = 256
# convention: the cylinder's largest n (the strip has 2n elements; dense operators of order 2n)
CYLINDER_N_MAX = 1024
# convention: the coarsest grid the sphere's estimates use
SPHERE_N_MIN = 16  # the coarsest grid the sphere's estimates use for a Richardson order
# measured: benchmarks/report_fretting_sphere_estimate.py (a cycle's work averaged over
# 4 x 4 placements of the grid under the contact: 1.1e-3 off Mindlin-Deresiewicz at n = 16
# and 4.1e-4 at n = 32, from 4.3e-2 and 1.7e-2 on the centred grid; over 2 x 2: 1.7e-3)
SPHERE_OFFSETS = 4  # placements a cell side that average out a sphere cycle's lattice error
# convention: the distance kept from gross sliding, relative to k P
_GROSS_SLIP_MARGIN = 1e-6  # |Q| <= (1 - margin) k P
# tested: tests/test_fretting_sphere_displacement.py (the answered Q/(k P_max) to round-off:
# 2e-16 in gross sliding, 4e-13 at Q = 0; the solver stops at 1e-11 of k p)
_FORCE_FLOOR = 1e-10  # the least estimate of Q/(k P_max) under a prescribed shift
# measured: benchmarks/figure_fretting_stick_map.py --accuracy (the stick radius per
# direction off by up to 0.62, 0.56, 0.30, 0.28 cells at n = 16, 32, 64, 128,
# Cattaneo–Mindlin; 0.39, 0.36 at n = 32, 64, Spence); tests/test_fretting_sphere_map.py
_STICK_LATTICE = 0.5  # the least lattice term of a stick radius per direction, in cells
# measured: benchmarks/figure_fretting_stick_map.py --accuracy (the contact radius per
# direction off by up to 0.27, 0.15, 0.07, 0.14 cells at n = 16, 32, 64, 128, Hertz)
_CONTACT_LATTICE = 0.25  # the lattice term of a contact radius per direction, in cells
# convention: under a prescribed shift, a change of Q below this of k P_max over a step
# (gross sliding) gives no compliance ds/dQ (NaN)
_STILL_FORCE = 1e-9


@dataclass(frozen=True)
class FrettingResult:
    """A fretting path of the cylinder (units E* = R = a_max = 1, per unit length).

    Per step (``steps * segments + 1`` values, the unloaded start first):
    ``load_ratio`` P/P_max, ``force_ratio`` Q/(k P_max), ``bulk_stress``
    sigma/p0, ``contact_edges`` and ``stick_edges`` (left, right; units
    a_max, NaN where there is none), ``stick_ratio`` the stick zone's
    half-width over the contact's, ``stick_offset`` the stick zone's centre
    minus the contact's (units a_max), ``approach`` delta and ``shift`` s (the
    indenter's rigid displacements, units a_max^2/R, up to the half-plane's
    logarithmic datum, see :mod:`contactlib.solvers.fretting_solver`), ``dissipation``
    (cumulative frictional work), ``external_work`` and ``stored_energy``,
    ``converged``, ``tangential_compliance`` ds/dQ over the step (units 1/E*; its
    level carries the half-plane's datum, its changes do not; NaN where Q does not
    change). ``pressure``,
    ``shear`` (units p0), ``slip`` (the step's slip increment, body minus
    indenter, units a_max^2/R; 0 where stuck or separated) and ``state`` per
    step and element at ``x`` (midpoints, units a_max).

    Per path point (``segments + 1`` values): ``point_step`` (the step index),
    the estimates ``stick_ratio_error`` (absolute), ``stick_offset_error``
    (units a_max) and ``dissipation_error`` (absolute, the cumulative
    frictional work), and ``resolved``: the stick ratio within ``max_error``
    and the dissipation within ``max_error`` of the path's total.

    ``cycles`` lists the closed cycles of the path: for each path point that
    repeats an earlier one (same P, Q and bulk stress), the pair of point
    indices, the frictional work of the cycle and its estimate. ``shaken_down``
    per cycle: its work is within its estimate of zero (the slip has stopped).

    ``model`` is the :class:`contactlib.model.Contact` that was solved (None for a
    result rebuilt elsewhere): ask it rather than rebuilding it from the fields.

    ``tangential_displacement``: the path prescribed the rigid shift (the sphere):
    ``tangential_path`` holds s R/a_max^2 at the path points, ``force_ratio`` is the
    answer, and ``force_ratio_error`` its estimate per path point (absolute, in Q/(k P_max);
    None under force control, where Q is prescribed).

    The sphere's zones per direction (None for the cylinder): ``direction_angles`` (D
    angles, radians from +x, the tangential load's direction), ``stick_radius_directions``
    and ``contact_radius_directions`` per step and direction (units a_max, each from its
    zone's centroid ``stick_centre`` and ``contact_centre``, (x, y) in units a_max; 0 in
    full slip), and their estimates per path point and direction
    ``stick_radius_directions_error`` and ``contact_radius_directions_error`` (units
    a_max); see :func:`sphere_fretting`.
    """

    geometry: str
    nu: float
    friction: float
    n: int
    steps: int
    max_error: float
    beta: float
    p_max: float
    p0: float
    load_path: tuple[float, ...]
    tangential_path: tuple[float, ...]
    bulk_stress_path: tuple[float, ...]
    x: np.ndarray
    segment: np.ndarray
    load_ratio: np.ndarray
    force_ratio: np.ndarray
    bulk_stress: np.ndarray
    contact_edges: np.ndarray
    stick_edges: np.ndarray
    stick_ratio: np.ndarray
    stick_offset: np.ndarray
    approach: np.ndarray
    shift: np.ndarray
    dissipation: np.ndarray
    external_work: np.ndarray
    stored_energy: np.ndarray
    converged: np.ndarray
    pressure: np.ndarray
    shear: np.ndarray
    slip: np.ndarray
    tangential_compliance: np.ndarray
    state: np.ndarray
    point_step: np.ndarray
    stick_ratio_error: np.ndarray
    stick_offset_error: np.ndarray
    dissipation_error: np.ndarray
    resolved: np.ndarray
    cycles: tuple[tuple[int, int, float, float], ...]
    orders: dict[str, float]
    profile: str = "paraboloid"  # the indenter's profile (contactlib.model.profiles)
    exponent: float = 2.0
    flat_ratio: float = 0.0  # b/a_max of the rounded flat punch (0 otherwise)
    tangential_displacement: bool = False  # the path prescribed the shift (the sphere)
    force_ratio_error: np.ndarray | None = None  # per point, displacement control only
    direction_angles: np.ndarray | None = None  # the sphere: (D,) radians from +x
    stick_radius_directions: np.ndarray | None = None  # the sphere: (steps, D), a_max
    contact_radius_directions: np.ndarray | None = None  # the sphere: (steps, D), a_max
    stick_centre: np.ndarray | None = None  # the sphere: (steps, 2), a_max
    contact_centre: np.ndarray | None = None  # the sphere: (steps, 2), a_max
    stick_radius_directions_error: np.ndarray | None = None  # the sphere: (points, D)
    contact_radius_directions_error: np.ndarray | None = None  # the sphere: (points, D)
    model: Any = field(default=None, repr=False, compare=False)  # the Contact solved

    @property
    def shaken_down(self) -> np.ndarray:
        """Per cycle: its frictional work is within its estimate of zero (slip has stopped)."""
        return np.array([abs(w) <= e for _, _, w, e in self.cycles], dtype=bool)

    @property
    def all_resolved(self) -> bool:
        """Every path point converged and resolved within ``max_error``."""
        return bool(np.all(self.resolved) and np.all(self.converged))


def _path(name: str, values: Sequence[float] | None, size: int | None) -> np.ndarray:
    if values is None:
        return np.zeros(size or 0)
    try:
        arr = np.asarray([float(v) for v in values], dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name}: expected a list of numbers, got {values!r}") from None
    if arr.ndim != 1 or arr.size < 2:
        raise ValueError(f"{name}: needs at least two points (the start and one more), "
                         f"got {arr.size}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name}: every value must be finite, got {values!r}")
    if size is not None and arr.size != size:
        raise ValueError(f"{name}: has {arr.size} points but load_path has {size}; "
                         "give one value at every point of load_path")
    if arr[0] != 0.0:
        raise ValueError(f"{name}: must start at 0 (the unloaded body), got {arr[0]:g}")
    return arr


CYLINDER_SHIFT_REFUSAL = (
    "tangential_displacement: a displacement-controlled path is solved for the sphere only: "
    "a half-plane's rigid shift is defined only up to its logarithmic datum, so a prescribed "
    "shift would fix the answer to a datum rather than to the specimen; prescribe the "
    "tangential force on the cylinder, or use geometry 'sphere'")


def _check(geometry: str, friction: float, load: np.ndarray, tang: np.ndarray,
           n: int, steps: int, max_error: float, displacement: bool = False) -> None:
    if geometry not in ("cylinder", "sphere"):
        raise ValueError(f"fretting: geometry {geometry!r} is not covered; the tangential load "
                         "is solved for the cylinder (plane strain) and the sphere")
    if displacement and geometry != "sphere":
        raise ValueError(CYLINDER_SHIFT_REFUSAL)
    if not (isinstance(friction, (int, float)) and math.isfinite(friction) and friction > 0):
        raise ValueError(f"friction: a tangential load needs a finite friction coefficient "
                         f"k > 0, got {friction!r}")
    if np.any(load < 0.0) or np.any(load > 1.0):
        raise ValueError("load_path: P/P_max must lie in [0, 1] (load level 1 is the "
                         f"reference load), got {load.tolist()}")
    if displacement:
        loose = (load == 0.0) & (tang != 0.0)
        if loose.any():
            i = int(np.flatnonzero(loose)[0])
            raise ValueError(f"tangential_path: the shift is {tang[i]:g} at point {i}, where "
                             "P = 0: a detached indenter has no shift; give 0 where P = 0")
    over = np.abs(tang) > (1.0 - _GROSS_SLIP_MARGIN) * load
    if over.any() and not displacement:
        i = int(np.flatnonzero(over)[0])
        raise ValueError(
            f"tangential_path: |Q|/(k P_max) = {abs(tang[i]):g} at point {i} reaches the "
            f"load there (P/P_max = {load[i]:g}): that is gross sliding, which a force-"
            "controlled path cannot follow. Keep |Q| < k P at every point")
    if geometry == "sphere":
        if not (isinstance(n, (int, np.integer)) and 16 <= n <= SPHERE_N_MAX and n % 4 == 0):
            raise ValueError(f"n: the sphere's cells a side of [-1.2, 1.2]^2 a_max must be a "
                             f"multiple of 4 in [16, {SPHERE_N_MAX}] (the estimate runs n/2), "
                             f"got {n!r}")
    elif not (isinstance(n, (int, np.integer)) and 16 <= n <= CYLINDER_N_MAX and n % 4 == 0):
        raise ValueError(f"n: elements over 1.2 a_max must be a multiple of 4 in [16, "
                         f"{CYLINDER_N_MAX}] "
                         f"(the estimate runs n/2 and n/4), got {n!r}")
    if not (isinstance(steps, (int, np.integer)) and steps >= 4 and steps % 4 == 0):
        raise ValueError(f"steps: steps a segment must be a multiple of 4 and >= 4 "
                         f"(the estimate runs steps/2 and steps/4), got {steps!r}")
    if not (0.0 < max_error < 1.0):
        raise ValueError(f"max_error: must lie in (0, 1), got {max_error!r}")


def run_path(model: Any, n: int, steps: int, k: float, load: np.ndarray, tang: np.ndarray,
             sigma: np.ndarray, progress: Callable[[int, int], None] | None = None,
             offset: float = 0.0) -> tuple[fr.StripOperators, fr.RawFretting]:
    """Run a cylinder's fretting path on ``2 n`` strip elements, ``steps`` a segment.

    Parameters
    ----------
    model : contactlib.model.Contact
        The cylinder's contact.
    n, steps : int
        Elements over 1.2 a_max on each side (any n >= 1, unchecked) and equal steps a
        segment.
    k : float
        The friction coefficient.
    load, tang, sigma : ndarray
        P/P_max, Q/(k P_max) and the bulk stress over p0 at the path's points.
    progress : callable, optional
        As for :func:`fretting`.
    offset : float
        The mesh's shift in elements (:func:`contactlib.solvers.fretting_solver.strip_operators`).

    Returns
    -------
    (StripOperators, RawFretting)
        The operators and the raw run (forces in E* a_max^2/R, tractions in E* a_max/R).
    """
    ops = fr.strip_operators(model, 2 * n, offset=offset)
    big_p = load_levels(load, steps)[0][1:] * ops.p_max
    big_q = load_levels(tang, steps)[0][1:] * k * ops.p_max
    strain = load_levels(sigma, steps)[0][1:] * ops.p0 * ops.strain_share
    return ops, fr.run_fretting(ops, k, big_p, big_q, strain, progress)


def _derived(raw: fr.RawFretting) -> tuple[np.ndarray, np.ndarray]:
    left, right, sl, sr = raw.edges.T
    with np.errstate(invalid="ignore", divide="ignore"):
        ratio = np.where(np.isfinite(sl), (sr - sl) / (right - left), 0.0)
        offset = np.where(np.isfinite(sl), 0.5 * (sl + sr) - 0.5 * (left + right), np.nan)
    ratio = np.where(np.isfinite(left), ratio, np.nan)
    return ratio, offset


def _estimate(fine: np.ndarray, coarse: np.ndarray, coarser: np.ndarray,
              max_order: float = ORDER_MAX) -> tuple[np.ndarray, float]:
    """Richardson estimate of the fine run's error at each point, and the measured order.

    The order is measured over the path points
    (:func:`~contactlib.solvers.history_solver.measured_order`) and capped at
    ``max_order`` (2 for the works: the discretizations are second order at best, a
    higher measured order is pre-asymptotic luck).
    """
    ok = np.isfinite(fine) & np.isfinite(coarse) & np.isfinite(coarser)
    order = measured_order(fine[ok], coarse[ok], coarser[ok]) if ok.any() else 1.0
    order = min(order, max_order)
    err = np.abs(fine - coarse) / (2.0**order - 1.0)
    return np.where(ok, err, np.where(np.isfinite(fine), np.inf, np.nan)), order


def _edge_estimate(fine: np.ndarray, shifted: np.ndarray, coarse: np.ndarray,
                   order: float) -> np.ndarray:
    """Error estimate of a zone edge measure (stick ratio, stick offset) at each point.

    The sub-element edge fit (:func:`~contactlib.solvers.fretting_solver.zone_edges`) has two
    errors. One depends on where the edge falls within its element and changes sign
    from element to element, so it is not smooth in the element size and a twofold
    difference can miss it or inflate it (measured: 0.015x to 11x the error against a
    run refined fourfold): ``|fine - shifted|``, the run on the mesh shifted by half an
    element, samples it at the same resolution. The other is the tractions' error in
    the fitted band, smooth in the element size, of ``order``: the Richardson term
    ``|fine - coarse|/(2^order - 1)``. The estimate is the larger of the two; infinite
    where the fine value is finite and a comparison run has none, NaN where the fine
    value is NaN (no contact).
    """
    both = np.isfinite(fine) & np.isfinite(shifted) & np.isfinite(coarse)
    with np.errstate(invalid="ignore"):
        err = np.maximum(np.abs(fine - shifted), np.abs(fine - coarse) / (2.0**order - 1.0))
    return np.where(both, err, np.where(np.isfinite(fine), np.inf, np.nan))


def _ratio_resolved(ratio: np.ndarray, error: np.ndarray, load: np.ndarray,
                    max_error: float) -> np.ndarray:
    """The stick ratio within ``max_error`` (absolute): a point without load has none to
    resolve; a loaded point whose ratio or estimate is NaN is never resolved."""
    with np.errstate(invalid="ignore"):
        ok = np.isfinite(ratio) & (error <= max_error)
    return np.where(load > 0.0, ok, True)


def _work_estimate(fine: np.ndarray, shifted: np.ndarray, mesh_2: np.ndarray,
                   mesh_4: np.ndarray, steps_2: np.ndarray, steps_4: np.ndarray
                   ) -> tuple[np.ndarray, float, float]:
    """Error estimate of a frictional work (cumulative, or a cycle's), and its two orders.

    The mesh and the load steps contribute errors of different orders, and under the
    joint refinement they can cancel in one twofold difference and not in the next (a
    coupled cycle's work: 2e-6 between n/2 and n, 2.2e-5 off the run refined fourfold),
    so they are estimated apart. The mesh's: ``fine`` (n, S) against ``mesh_2`` (n/2, S)
    at the order measured with ``mesh_4`` (n/4, S), capped at 2 (midpoint collocation
    and the trapezoid rule are second order: more is pre-asymptotic luck), and at least
    the difference to the run on the mesh shifted by half an element, ``shifted``,
    which samples the part that depends on where the zone edges fall in their elements.
    The steps': ``mesh_2`` against ``steps_2`` (n/2, S/2) at the order measured with
    ``steps_4`` (n/2, S/4), capped at 2 (where the contact or the slip zone moves during
    a step, the quadrature of the step's slip is first order: measured 1.0-1.2); the
    step error hardly depends on the mesh, so the n/2 ladder stands for the fine one.
    The estimate is their sum.
    """
    mesh, o_mesh = _estimate(fine, mesh_2, mesh_4, 2.0)
    with np.errstate(invalid="ignore"):
        mesh = np.maximum(mesh, np.abs(fine - shifted))
    step, o_step = _estimate(mesh_2, steps_2, steps_4, 2.0)
    return mesh + step, o_mesh, o_step


def _compliance(shift: np.ndarray, force: np.ndarray, tol: float = 0.0) -> np.ndarray:
    """ds/dQ over each step (NaN at the start and where Q changes by ``tol`` or less)."""
    dq = np.diff(force)
    moved = np.abs(dq) > tol
    with np.errstate(invalid="ignore", divide="ignore"):
        out = np.where(moved, np.diff(shift) / np.where(moved, dq, 1.0), np.nan)
    return np.concatenate(([np.nan], out))


def _closed(load: np.ndarray, tang: np.ndarray, sigma: np.ndarray) -> list[tuple[int, int]]:
    """(i, j): point j repeats point i (same P, Q, sigma), the latest such i, j - i >= 2."""
    out = []
    for j in range(1, load.size):
        for i in range(j - 1, 0, -1):
            if load[i] == load[j] and tang[i] == tang[j] and sigma[i] == sigma[j]:
                if j - i >= 2:
                    out.append((i, j))
                break
    return out


def _cycles(load: np.ndarray, tang: np.ndarray, sigma: np.ndarray,
            work: np.ndarray, error: np.ndarray) -> tuple[tuple[int, int, float, float], ...]:
    return tuple((i, j, float(work[j] - work[i]), float(e))
                 for (i, j), e in zip(_closed(load, tang, sigma), error))


def defaults(geometry: str) -> tuple[int, int]:
    """The default ``(n, steps)`` of :func:`fretting` for ``geometry``."""
    if geometry == "sphere":
        return SPHERE_DEFAULT_N, SPHERE_DEFAULT_STEPS
    return DEFAULT_N, DEFAULT_STEPS


def check_input(geometry: str, friction: float, load_path: Sequence[float],
                tangential_path: Sequence[float], steps: int | None = None,
                n: int | None = None, bulk_stress: Sequence[float] | None = None,
                max_error: float = DEFAULT_MAX_ERROR, *, nu: float | None = None,
                indenter_modulus: float = math.inf, indenter_nu: float | None = None,
                tangential_displacement: bool = False) -> None:
    """Raise ValueError (naming the argument) on input :func:`fretting` refuses; no numerics.

    The sphere needs ``nu`` (and the indenter's material): a tangential load on a
    coupled pair (Dundurs beta != 0) is solved for ``|beta| <= SPHERE_COUPLED_BETA_MAX``,
    ``|Q| <= SPHERE_COUPLED_FORCE_MAX k P`` and ``n <= SPHERE_COUPLED_N_MAX`` only
    (``validate.SolverLimit`` otherwise; under ``tangential_displacement`` the force is
    checked after the run).
    Without ``nu`` the sphere is refused; the cylinder refuses ``tangential_displacement``.
    """
    load = _path("load_path", load_path, None)
    tang = _path("tangential_path", tangential_path, load.size)
    if bulk_stress is not None:
        _path("bulk_stress", bulk_stress, load.size)
    if geometry == "sphere" and nu is None:
        raise ValueError("fretting: geometry 'sphere' is not covered without nu: a tangential "
                         "load on the sphere depends on the pair's Dundurs beta, "
                         "which needs the materials (pass nu to check_input)")
    n0, steps0 = defaults(geometry)
    if not isinstance(tangential_displacement, (bool, np.bool_)):
        raise ValueError(f"tangential_displacement: True or False, got "
                         f"{tangential_displacement!r}")
    _check(geometry, friction, load, tang, n0 if n is None else n,
           steps0 if steps is None else steps, max_error, bool(tangential_displacement))
    if geometry == "sphere":
        if bulk_stress is not None and any(float(v) for v in bulk_stress):
            raise ValueError("bulk_stress: the sphere takes no bulk stress (it is solved for "
                             "the cylinder only); give none")
        e1, nu1 = validate.indenter_material(indenter_modulus, indenter_nu)
        model = contact("sphere", validate.nu(nu), indenter_modulus=e1, indenter_nu=nu1)
        _refuse_coupled(model, load, tang, n0 if n is None else n,
                        bool(tangential_displacement))


@blas_single_threaded
def fretting(geometry: str, nu: float, friction: float, load_path: Sequence[float],
             tangential_path: Sequence[float], steps: int | None = None, *,
             n: int | None = None, bulk_stress: Sequence[float] | None = None,
             indenter_modulus: float = math.inf, indenter_nu: float | None = None,
             profile: str = "paraboloid", exponent: float | None = None,
             flat_ratio: float | None = None, max_error: float = DEFAULT_MAX_ERROR,
             error_estimate: bool = True, tangential_displacement: bool = False,
             progress: Callable[[int, int], None] | None = None) -> FrettingResult:
    """Follow a normal and a tangential load path of a cylinder or sphere with Coulomb friction.

    Parameters
    ----------
    geometry : {"cylinder", "sphere"}
        The cylinder (plane strain) on a half-plane, or the sphere on a half-space
        (:func:`sphere_fretting`; a coupled pair, Dundurs beta != 0, with
        ``|beta| <= 0.5`` under ``|Q| <= 0.9 k P`` with ``n <= 64`` only).
    nu : float
        Poisson's ratio of the body, in (-1, 0.5].
    friction : float
        Coulomb coefficient, ``0 < k < inf``.
    load_path : sequence of float
        P/P_max at the path's points, in [0, 1], starting at 0.
    tangential_path : sequence of float
        Q/(k P_max) at the same points, starting at 0, with
        ``|Q/(k P_max)| < P/P_max`` wherever P > 0 (no gross sliding). With
        ``tangential_displacement``: the indenter's rigid shift s R/a_max^2 (the units of
        the result's ``shift``), 0 where P = 0.
    steps : int, optional
        Equal steps a segment (multiple of 4; default 40, the sphere 8).
    n : int, optional
        Elements over 1.2 a_max on each side of the axis, as for
        :func:`contactlib.history` (the strip ``[-1.2, 1.2] a_max`` has 2n;
        a multiple of 4 in [16, 1024]; default 120: element a_max/100). The
        sphere: cells a side of ``[-1.2, 1.2]^2 a_max`` (multiple of 4 in
        [16, 256], default 64).
    bulk_stress : sequence of float, optional
        The body's bulk stress along x over p0 at the same points (starting
        at 0); default none.
    indenter_modulus, indenter_nu : float
        An elastic indenter, E1/E2 and nu1 (default rigid; nu1 the body's).
    profile, exponent, flat_ratio : str, float, float
        The indenter's profile, as for :func:`contactlib.history`: a power law or the
        rounded flat punch (``flat_ratio`` = b/a_max); the flat punch is refused.
    max_error : float
        Accuracy for ``resolved``: of the stick ratio (absolute) and of the
        cumulative frictional work relative to the path's total (default 1e-2, as
        for :func:`contactlib.history`).
    error_estimate : bool
        Estimate the errors (default). The cylinder runs the path again on the mesh
        shifted by half an element (the zone edges' error that depends on where they
        fall in their elements) and with (n/2, steps/2), (n/2, steps), (n/4, steps)
        and (n/2, steps/4) (the mesh's and the steps' errors of the work, apart):
        about 1.3 times the main run. The sphere runs (n/2, steps/2) and, from
        n = 64, (n/4, steps/4); for a closed cycle's work also (n/2, steps) and
        12 placements of the grid at (n/2, steps/4) and, from n = 64, at
        (n/4, steps/4): the estimates then cost 0.8 to 2.9 times the main run
        (benchmarks/report_fretting_sphere_estimate.py). If False the estimates
        are NaN and nothing is ``resolved``.
    tangential_displacement : bool
        The sphere only: ``tangential_path`` prescribes the rigid shift (a displacement-
        controlled test); Q is the answer (``force_ratio``, its estimate
        ``force_ratio_error``) and may reach k P (gross sliding: no stick zone). A coupled
        pair (beta != 0) is refused when |Q| passed ``0.9 k P`` (checked after the run).
        The cylinder refuses it (its shift has a logarithmic datum).
    progress : callable, optional
        ``progress(i, total)`` after each step of the main run.

    Returns
    -------
    FrettingResult

    Raises
    ------
    ValueError
        On input outside the ranges above (the message names the argument).

    Examples
    --------
    >>> from contactlib import fretting
    >>> r = fretting("cylinder", 0.5, 0.3, [0, 1, 1], [0, 0, 0.5], 8, n=32)
    >>> round(float(r.stick_ratio[-1]), 1)  # Cattaneo-Mindlin: sqrt(1 - 0.5) = 0.71
    0.7
    """
    load = _path("load_path", load_path, None)
    tang = _path("tangential_path", tangential_path, load.size)
    sigma = _path("bulk_stress", bulk_stress, load.size) if bulk_stress is not None \
        else np.zeros(load.size)
    n0, steps0 = defaults(geometry)
    n = n0 if n is None else n
    steps = steps0 if steps is None else steps
    check_input(geometry, friction, load, tang, steps, n, bulk_stress, max_error, nu=nu,
                indenter_modulus=indenter_modulus, indenter_nu=indenter_nu,
                tangential_displacement=tangential_displacement)
    nu = validate.nu(nu)
    indenter_modulus, indenter_nu = validate.indenter_material(indenter_modulus, indenter_nu)
    if not takes(profile, "fretting"):
        raise validate.InputError("profile", "a power law (paraboloid, cone, power) or rounded "
                                  "for fretting", profile, f"profile {profile!r} is not taken "
                                  "by fretting yet: the fretting solvers cover the power laws "
                                  "and the rounded flat punch (profile 'rounded' with "
                                  "flat_ratio), not a sharp edge")
    prof = make_profile(profile, exponent, flat_ratio)
    model = contact(geometry, nu, indenter_modulus=indenter_modulus, indenter_nu=indenter_nu,
                    profile=prof)
    k = float(friction)
    if geometry == "sphere":
        res = sphere_fretting(model, k, load, tang, steps, n, max_error, error_estimate,
                              progress, bool(tangential_displacement))
        return replace(res, profile=prof.name, exponent=float(prof.exponent),
                       flat_ratio=float(prof.flat), model=model)
    ops, raw = run_path(model, n, steps, k, load, tang, sigma, progress)
    ratio, offset = _derived(raw)
    points = np.arange(load.size) * steps
    if error_estimate:
        # (n/2, S/2), (n, S) on the mesh shifted by half an element, then the mesh
        # ladder (n/2, S), (n/4, S) and the step ladder (n/2, S/4)
        plan = [(n // 2, steps // 2, 0.0), (n, steps, 0.5), (n // 2, steps, 0.0),
                (n // 4, steps, 0.0), (n // 2, steps // 4, 0.0)]
        runs = [run_path(model, m, s, k, load, tang, sigma, offset=off)[1]
                for m, s, off in plan]
        at = [r.dissipation[np.arange(load.size) * s] for r, (_, s, _) in zip(runs, plan)]
        der = [_derived(r) for r in runs[:2]]
        half = np.arange(load.size) * (steps // 2)
        # the edges' smooth error: where the friction reserve vanishes as a square root
        # (beta = 0: Cattaneo's form) the fit of its square is exact in form and the
        # fitted tractions converge at second order; with the coupling (beta != 0) the
        # edges were measured to converge at first order
        o1, o2 = (2.0 if ops.beta == 0.0 else 1.0), 1.0
        ratio_err = _edge_estimate(ratio[points], der[1][0][points], der[0][0][half], o1)
        off_err = _edge_estimate(offset[points], der[1][1][points], der[0][1][half], o2)
        fine = raw.dissipation[points]
        diss_err, o3, o4 = _work_estimate(fine, at[1], at[2], at[3], at[0], at[4])
        orders = {"stick_ratio": o1, "stick_offset": o2, "dissipation_mesh": o3,
                  "dissipation_steps": o4}
        # a cycle's work from its own values (the cumulative work's errors cancel
        # in the difference: its endpoint estimates inflated it 400-fold)
        closed = _closed(load, tang, sigma)
        works = [np.array([d[j] - d[i] for i, j in closed]) for d in [fine] + at]
        cycle_err = (_work_estimate(works[0], works[2], works[3], works[4], works[1],
                                    works[5])[0] if closed else works[0])
        # a stick zone too narrow for the edge fit is known to an element at best
        left, right, sl, sr = raw.edges[points].T
        narrow = np.nan_to_num(sr - sl, nan=0.0) < (fr.EDGE_SKIP + fr.EDGE_FIT + 2) * ops.width
        floor = np.where(narrow & np.isfinite(left), ops.width / (right - left), 0.0)
        ratio_err = np.maximum(ratio_err, floor)
        scale = max(float(raw.dissipation[-1]), 1e-300)
        resolved = (_ratio_resolved(ratio[points], ratio_err, raw.load[points], max_error)
                    & (diss_err <= max_error * scale) & raw.converged[points])
        if not all(r.converged.all() for r in runs):
            resolved &= False
    else:
        ratio_err = off_err = diss_err = np.full(load.size, np.nan)
        cycle_err = np.full(len(_closed(load, tang, sigma)), np.nan)
        orders = {}
        resolved = np.zeros(load.size, dtype=bool)
    segment = load_levels(load, steps)[1]
    edges = raw.edges
    return FrettingResult(
        geometry=geometry, nu=float(nu), friction=k, n=int(n), steps=int(steps),
        max_error=float(max_error), beta=ops.beta, p_max=ops.p_max, p0=ops.p0,
        load_path=tuple(load.tolist()), tangential_path=tuple(tang.tolist()),
        bulk_stress_path=tuple(sigma.tolist()), x=ops.mid, segment=segment,
        load_ratio=raw.load / ops.p_max, force_ratio=raw.force / (k * ops.p_max),
        bulk_stress=raw.strain / (ops.p0 * ops.strain_share), contact_edges=edges[:, :2],
        stick_edges=edges[:, 2:], stick_ratio=ratio, stick_offset=offset,
        approach=raw.delta, shift=raw.shift, dissipation=raw.dissipation,
        external_work=raw.external_work, stored_energy=raw.stored_energy,
        converged=raw.converged, pressure=raw.p / ops.p0, shear=raw.q / ops.p0,
        slip=raw.slip, tangential_compliance=_compliance(raw.shift, raw.force),
        state=raw.state, point_step=points, stick_ratio_error=ratio_err,
        stick_offset_error=off_err, dissipation_error=diss_err, resolved=resolved,
        cycles=_cycles(load, tang, sigma, raw.dissipation[points], cycle_err), orders=orders,
        profile=prof.name, exponent=float(prof.exponent), flat_ratio=float(prof.flat),
        model=model)


# limit: |Q|/(k P) of a coupled pair's tangential load, verified converged and checked in
# tests/test_fretting_sphere_coupled.py (beta = +-0.5 and 0.286 at 0.9)
SPHERE_COUPLED_FORCE_MAX = 0.9
# limit: cells a side for a coupled pair, verified converged in
# tests/test_fretting_sphere_coupled.py (n = 64: beta = 0.286 at Q = 0.5 k P, 0.5 at 0.9 k P)
SPHERE_COUPLED_N_MAX = 64
# limit: |beta| of a coupled pair's tangential load, verified in
# tests/test_fretting_sphere_coupled.py at +-0.5 (beta > 0.5 needs a body with nu < 0)
SPHERE_COUPLED_BETA_MAX = 0.5
SPHERE_COUPLED_REFUSAL = (
    "fretting: a tangential load on the sphere is solved for Dundurs beta = 0 only, or for a "
    "coupled pair with |beta| <= {bmax:g}, |Q| <= {fmax:g} k P and n <= {nmax}: got beta = "
    "{beta:.4g}, |Q|/(k P) = {x:.4g} and n = {n}, beyond the range whose coupled steps were "
    "verified to converge. Keep |Q| <= {fmax:g} k P and pass n <= {nmax}, or use the "
    "cylinder, or a pair with |beta| <= {bmax:g}")
SPHERE_COUPLED_SHIFT_REFUSAL = (
    "fretting: a prescribed shift on the sphere is solved for Dundurs beta = 0, or for a "
    "coupled pair with |beta| <= {bmax:g} and n <= {nmax} while |Q| stays <= {fmax:g} k P: "
    "got beta = {beta:.4g}, n = {n}{reached}, beyond the range whose coupled steps were "
    "verified. Keep the shift smaller, pass n <= {nmax}, or use a pair with beta = 0")


def _coupled(beta: float, tangential: np.ndarray) -> bool:
    """A tangential load on a coupled pair (beta != 0), which the coupled limits bound; the
    coupled normal loading alone (Q = 0) is not bounded."""
    return beta != 0.0 and bool(np.any(tangential != 0.0))


def finer_run(res: FrettingResult) -> tuple[int, int]:
    """The n and steps a segment of the next finer run that :func:`fretting` accepts.

    Twice the steps, and twice n where the limit of the case allows it (the cylinder's
    ``CYLINDER_N_MAX``, the sphere's ``SPHERE_N_MAX``, a coupled tangential load's
    ``SPHERE_COUPLED_N_MAX``); at the limit n stays.
    """
    if res.geometry == "sphere":
        tangential = np.nan_to_num(np.asarray(res.force_ratio, dtype=float))
        n_max = SPHERE_COUPLED_N_MAX if _coupled(res.beta, tangential) else SPHERE_N_MAX
    else:
        n_max = CYLINDER_N_MAX
    return (2 * res.n if 2 * res.n <= n_max else res.n), 2 * res.steps


def _refuse_coupled(model, load: np.ndarray, tang: np.ndarray, n: int,
                    displacement: bool = False) -> float:
    """The pair's Dundurs beta; SolverLimit for a coupled tangential load beyond the
    verified range (|beta| <= SPHERE_COUPLED_BETA_MAX, |Q|/(k P) <= SPHERE_COUPLED_FORCE_MAX,
    n <= SPHERE_COUPLED_N_MAX). A prescribed shift (``displacement``): beta and n only; the
    force is checked after the run (:func:`_refuse_coupled_force`)."""
    beta = float(model.beta) if not model.decoupled else 0.0
    if not _coupled(beta, tang):
        return beta
    if displacement:
        if n > SPHERE_COUPLED_N_MAX or abs(beta) > SPHERE_COUPLED_BETA_MAX:
            raise validate.SolverLimit(SPHERE_COUPLED_SHIFT_REFUSAL.format(
                beta=beta, bmax=SPHERE_COUPLED_BETA_MAX, fmax=SPHERE_COUPLED_FORCE_MAX,
                nmax=SPHERE_COUPLED_N_MAX, n=n, reached=""))
        return beta
    with np.errstate(invalid="ignore", divide="ignore"):
        x = float(np.max(np.where(load > 0, np.abs(tang) / np.where(load > 0, load, 1.0),
                                  0.0)))
    if x > SPHERE_COUPLED_FORCE_MAX * (1.0 + 1e-12) or n > SPHERE_COUPLED_N_MAX \
            or abs(beta) > SPHERE_COUPLED_BETA_MAX:
        raise validate.SolverLimit(SPHERE_COUPLED_REFUSAL.format(
            beta=beta, bmax=SPHERE_COUPLED_BETA_MAX, fmax=SPHERE_COUPLED_FORCE_MAX,
            nmax=SPHERE_COUPLED_N_MAX, x=x, n=n))
    return beta


def _refuse_coupled_force(raw: fsph.RawSphereFretting, k: float, n: int, beta: float,
                          steps: int) -> None:
    """SolverLimit when a prescribed shift drove a coupled pair's |Q| beyond
    ``SPHERE_COUPLED_FORCE_MAX k P`` at a loaded step (the coupled steps are verified up to
    it only): its number is not reported."""
    with np.errstate(invalid="ignore", divide="ignore"):
        x = np.where(raw.load > 0, np.abs(raw.force) / (k * raw.load), 0.0)
    over = x > SPHERE_COUPLED_FORCE_MAX * (1.0 + 1e-12)
    if over.any():
        j = int(np.flatnonzero(over)[0])
        raise validate.SolverLimit(SPHERE_COUPLED_SHIFT_REFUSAL.format(
            beta=beta, bmax=SPHERE_COUPLED_BETA_MAX, fmax=SPHERE_COUPLED_FORCE_MAX,
            nmax=SPHERE_COUPLED_N_MAX, n=n,
            reached=f" and |Q| = {x[j]:.4g} k P reached in segment {(j - 1) // steps + 1}"))


def _sphere_run(model, n: int, steps: int, k: float, load: np.ndarray, tang: np.ndarray,
                keep: bool, progress=None, displacement: bool = False,
                offset: tuple[float, float] = (0.0, 0.0)
                ) -> tuple[fsph.GridOperators, fsph.RawSphereFretting]:
    ops = fsph.grid_operators(model, n, offset=offset)
    big_p = load_levels(load, steps)[0][1:] * ops.p_max
    path = load_levels(tang, steps)[0][1:]
    if displacement:  # the shift, in a_max^2/R already
        raw = fsph.run_sphere_fretting(ops, k, big_p, None, keep_fields=keep,
                                       progress=progress, shift=path)
    else:
        raw = fsph.run_sphere_fretting(ops, k, big_p, path * k * ops.p_max, keep_fields=keep,
                                       progress=progress)
    return ops, _sphere_masked(raw, displacement)


def _cycle_works(raw: fsph.RawSphereFretting, steps: int, size: int,
                 closed: list[tuple[int, int]]) -> np.ndarray:
    """The frictional work of each closed cycle (point i to point j) of a run."""
    d = raw.dissipation[np.arange(size) * steps]
    return np.array([d[j] - d[i] for i, j in closed])


def _placements(model, n: int, steps: int, k: float, load: np.ndarray, tang: np.ndarray,
                displacement: bool, closed: list[tuple[int, int]]
                ) -> tuple[np.ndarray, np.ndarray, np.ndarray, bool]:
    """The cycles' works over ``SPHERE_OFFSETS^2`` placements of the grid (the profile's axis
    moved by i/m and j/m of a cell, m = ``SPHERE_OFFSETS``; y -> -y maps j onto m - j, which
    halves the runs): their mean, the mean over the 2 x 2 placements among them, the
    centred grid's works and whether every run converged."""
    m = SPHERE_OFFSETS
    works, ok = {}, True
    for i in range(m):
        for j in range(m // 2 + 1):
            _, raw = _sphere_run(model, n, steps, k, load, tang, False,
                                 displacement=displacement, offset=(i / m, j / m))
            works[i, j] = _cycle_works(raw, steps, load.size, closed)
            ok = ok and bool(raw.converged.all())

    def mean(stride: int) -> np.ndarray:
        cells = [(i, min(j, m - j)) for i in range(0, m, stride) for j in range(0, m, stride)]
        return np.mean([works[c] for c in cells], axis=0)

    return mean(1), mean(m // 2), works[0, 0], ok


def _sphere_cycle_errors(model, n: int, steps: int, k: float, load: np.ndarray,
                         tang: np.ndarray, displacement: bool, closed: list[tuple[int, int]],
                         fine: np.ndarray, half_steps: np.ndarray
                         ) -> tuple[np.ndarray, float, bool]:
    """Error estimate of the sphere's cycle works ``fine`` (the run with n cells, S steps).

    The mesh's error of a cycle's work is mostly a lattice error: it depends on how the
    contact and stick discs fall on the cells, changes sign from one n to the next and
    from one placement of the grid to another (4.3e-2, -1.7e-2 and -7e-4 off Mindlin-
    Deresiewicz at n = 16, 32 and 64, Q*/kP = 0.5), and the placements' mean converges
    smoothly (at order 2.3 to 2.6). A twofold difference therefore measures the coarse
    run's lattice error, up to 20 times the fine one's. The steps' error is separate: 0 at
    beta = 0 and constant P, the larger part at beta != 0 (order 1 to 2).

    * The steps': ``|W(n/2, S) - W(n/2, S/2)|`` (``half_steps`` the latter), 1 to 3 times
      the error for an order between 1 and 2; for a lower order, measured with
      ``W(n/2, S/4)``, the Richardson term at that order.
    * The mesh's: the fine work's distance to ``M(n/2)``, the n/2 run freed of its lattice
      error, plus ``M(n/2)``'s own error. ``M(n/2) = W(n/2, S) - L``, ``L`` the centred
      grid's lattice term measured at S/4 steps (it hardly depends on the steps) as its
      difference to the mean over the placements (:func:`_placements`). ``M(n/2)``'s error:
      the placements' mean against the 2 x 2 placements' (the average's), and from n = 64
      on the means' smooth error at order 2, a third of the mean's difference to the mean
      at n/4 (also at S/4).

    Returns
    -------
    error : ndarray
        Per closed cycle (units of the work).
    order : float
        The steps' order measured at n/2.
    converged : bool
        Every run converged.
    """
    quarter = max(steps // 4, 1)
    _, mid = _sphere_run(model, n // 2, steps, k, load, tang, False, displacement=displacement)
    w_mid = _cycle_works(mid, steps, load.size, closed)
    mean, mean_2, centred, ok = _placements(model, n // 2, quarter, k, load, tang,
                                            displacement, closed)
    ok = ok and bool(mid.converged.all())
    with np.errstate(invalid="ignore"):
        mesh = np.abs(fine - (w_mid - (centred - mean))) + np.abs(mean - mean_2)
        if n // 4 >= SPHERE_N_MIN:
            coarse_mean, _, _, ok_4 = _placements(model, n // 4, quarter, k, load, tang,
                                                  displacement, closed)
            mesh = mesh + np.abs(mean - coarse_mean) / 3.0
            ok = ok and ok_4
        order = measured_order(w_mid, half_steps, centred)
        step = np.abs(w_mid - half_steps) * max(1.0, 1.0 / (2.0**order - 1.0))
    return mesh + step, order, ok


def _sphere_masked(raw: fsph.RawSphereFretting, displacement: bool = False
                   ) -> fsph.RawSphereFretting:
    """The run with its per-step numbers NaN from the first step that did not converge on
    (a later step starts from that step's state): never reported as data. The prescribed
    one of the force and the shift is kept, the answered one masked."""
    bad = np.maximum.accumulate(~raw.converged)
    if not bad.any():
        return raw
    nan = {name: np.where(bad, np.nan, getattr(raw, name)) for name in (
        "delta", "contact_radius", "stick_radius", "stick_offset", "stick_area",
        "contact_area", "dissipation", "external_work", "stored_energy")
        + (("force",) if displacement else ())}
    shift = raw.shift if displacement else np.where(bad[:, None], np.nan, raw.shift)
    rays = {name: np.where(bad[:, None, None], np.nan, getattr(raw, name))
            for name in ("contact_directions", "stick_directions")}
    rays.update({name: np.where(bad[:, None], np.nan, getattr(raw, name))
                 for name in ("contact_centre", "stick_centre")})
    return replace(raw, shift=shift, **nan, **rays)


def _sphere_measures(raw: fsph.RawSphereFretting) -> tuple[np.ndarray, np.ndarray]:
    """Stick ratio (area-equivalent radii, c/a; 0 in full slip) and stick offset per step."""
    a = raw.contact_radius
    with np.errstate(invalid="ignore", divide="ignore"):
        ratio = np.where(np.isfinite(a), raw.stick_radius / a, np.nan)
    return ratio, raw.stick_offset


def _sphere_lattice(raw: fsph.RawSphereFretting, h: float) -> np.ndarray:
    """The stick ratio's lattice error per step where the stick zone grew over the step: the
    area-equivalent radii against the edges located inside their cells
    (:func:`contactlib.solvers.fretting_sphere.edge_radius`), c's difference plus c/a times
    a's, over a; a cell (h/a) where a stick zone holds fewer than two cells on an axis' row.
    0 where the zone shrank (a receding edge: Cattaneo's area-equivalent radius was 0.12 and
    0.035 h off at n = 32 and 64, within the twofold difference, and the term at every step
    raised the coupled cycles' estimates up to 37 times their error; docs/fretting.md) and
    in full slip."""
    a, c = raw.contact_radius, raw.stick_radius
    grew = np.diff(raw.stick_area, prepend=0.0) > 0
    with np.errstate(invalid="ignore", divide="ignore"):
        term = (np.abs(raw.stick_edge_radius - c)
                + c / a * np.abs(raw.contact_edge_radius - a)) / a
        return np.where(grew & (c > 0), np.where(np.isfinite(term), term, h / a), 0.0)


def _sphere_directions(raw: fsph.RawSphereFretting) -> tuple[np.ndarray, np.ndarray,
                                                               np.ndarray]:
    """The zones' radii per step and direction (units a_max): the contact's and the stick
    zone's edge measures of :func:`contactlib.solvers.fretting_sphere.direction_radii`
    (the stick zone's half-level measure where its edge measure is NaN), and the stick
    zone's lattice term: the two measures' difference (a cell where one is NaN)."""
    edge, half = raw.stick_directions[:, 0], raw.stick_directions[:, 1]
    stick = np.where(np.isfinite(edge), edge, half)
    lattice = np.abs(edge - half)
    return raw.contact_directions[:, 0], stick, lattice


def _direction_estimates(raw: fsph.RawSphereFretting, coarse: fsph.RawSphereFretting,
                         points: np.ndarray, cpts: np.ndarray, h: float
                         ) -> tuple[np.ndarray, np.ndarray]:
    """Per path point and direction, the estimates of the stick zone's and the contact's
    radii (units a_max): the difference to the ``n/2`` run plus a lattice term, which that
    difference does not see (the edge located from cell values is off by an amount that
    changes from cell to cell, not smoothly in n). The stick zone's: its edge and
    half-level measures' difference, at least ``_STICK_LATTICE h``; 0 in full slip (no
    stick zone at either grid). The contact's: ``_CONTACT_LATTICE h``."""
    a, c, lattice = _sphere_directions(raw)
    ca, cc, _ = _sphere_directions(coarse)
    with np.errstate(invalid="ignore"):
        full_slip = (c[points] == 0.0) & (cc[cpts] == 0.0)
        term = np.where(np.isfinite(lattice[points]),
                        np.maximum(lattice[points], _STICK_LATTICE * h), h)
        stick_err = np.where(full_slip, 0.0, np.abs(c[points] - cc[cpts]) + term)
    return stick_err, np.abs(a[points] - ca[cpts]) + _CONTACT_LATTICE * h


def sphere_fretting(model, k: float, load: np.ndarray, tang: np.ndarray, steps: int, n: int,
                    max_error: float = DEFAULT_MAX_ERROR, error_estimate: bool = True,
                    progress: Callable[[int, int], None] | None = None,
                    displacement: bool = False) -> FrettingResult:
    """The sphere's path for :func:`fretting` (checked input; units E* = R = a_max = 1).

    The numerics are :mod:`contactlib.solvers.fretting_sphere` (``n x n`` cells over
    ``[-1.2, 1.2]^2 a_max``). In the :class:`FrettingResult`, ``stick_ratio`` is
    the stick zone's area-equivalent radius over the contact's, ``contact_edges``
    and ``stick_edges`` are ``centre -+ radius`` along x (units a_max), the
    approach and the shift are absolute (a half-space has no datum), forces are
    in ``E* a_max^3/R`` (``p_max``), work in ``E* a_max^5/R^2``, and
    ``pressure``, ``shear`` (x component), ``slip`` (x component) and ``state``
    are those of the row of cells next to the x axis (``y = h/2``). The
    estimates are the differences to the run with ``n/2`` cells and ``steps/2``
    (``orders`` records the order 1 this assumes: the radii's lattice error is
    not smooth in the cell size); the stick ratio's adds its lattice term, the
    area-equivalent radii against the edges located inside their cells along
    the axes (:func:`contactlib.solvers.fretting_sphere.edge_radius`). From ``n = 64``
    the frictional work's estimates
    are Richardson's from a third run with ``n/4`` cells at the measured order
    (``orders["dissipation"]``, at most 2). A closed cycle's work has its own estimate
    (:func:`_sphere_cycle_errors`): the steps' error from ``n/2`` cells at S and S/2 steps
    (``orders["cycle_steps"]`` the order measured with S/4), and the mesh's from the
    ``n/2`` run freed of its lattice error, measured over 4 x 4 placements of the grid under
    the contact at S/4 steps (and from ``n = 64`` those at ``n/4``). Under a prescribed shift
    (``displacement``) the force's estimate is its difference to the ``n/2`` run and, from
    ``n = 64``, at least half the ``n/2`` run's difference to the ``n/4`` one (its lattice
    error is not monotonic in n), and at least ``_FORCE_FLOOR`` (round-off).

    The zones per direction (``stick_radius_directions``, ``contact_radius_directions``,
    ``direction_angles``) are those of
    :func:`contactlib.solvers.fretting_sphere.direction_radii` from each zone's centroid
    (``stick_centre``, ``contact_centre``): the edge measure, the stick zone's half-level
    measure where the edge has none. Their estimates: the difference to the ``n/2`` run
    plus a lattice term, the stick zone's two measures' difference but at least
    ``_STICK_LATTICE`` cells, the contact's ``_CONTACT_LATTICE`` cells.

    Parameters
    ----------
    model : Contact
        A sphere on a half-space; a tangential load on a coupled pair (beta != 0) needs
        ``|beta| <= SPHERE_COUPLED_BETA_MAX``, ``|Q| <= SPHERE_COUPLED_FORCE_MAX k P`` and
        ``n <= SPHERE_COUPLED_N_MAX``.
    k : float
        Coulomb coefficient.
    load, tang : ndarray
        P/P_max and Q/(k P_max) at the path's points (checked by :func:`check_input`);
        with ``displacement`` the shift s R/a_max^2 instead of Q.
    steps, n : int
        Steps a segment and cells a side.
    max_error, error_estimate, progress
        As for :func:`fretting`.
    displacement : bool
        ``tangential_path`` prescribes the shift (:func:`fretting`'s
        ``tangential_displacement``).

    Returns
    -------
    FrettingResult

    Raises
    ------
    contactlib.validate.SolverLimit
        (a ValueError) A coupled pair's tangential load beyond the verified range (under
        a prescribed shift, after the main run).
    """
    beta = _refuse_coupled(model, load, tang, n, displacement)
    ops, raw = _sphere_run(model, n, steps, k, load, tang, True, progress, displacement)
    if displacement and beta != 0.0:
        _refuse_coupled_force(raw, k, n, beta, steps)
    ratio, offset = _sphere_measures(raw)
    points = np.arange(load.size) * steps
    sigma = np.zeros(load.size)
    closed = _closed(load, tang, sigma)
    force_err = None
    if error_estimate:
        _, coarse = _sphere_run(model, n // 2, steps // 2, k, load, tang, False,
                                displacement=displacement)
        cpts = np.arange(load.size) * (steps // 2)
        if displacement:
            force_err = np.maximum(np.abs(raw.force[points] - coarse.force[cpts])
                                   / (k * ops.p_max), _FORCE_FLOOR)
        c_ratio, c_offset = _sphere_measures(coarse)
        # the twofold difference does not see the radii's lattice error (the stick cells
        # end about a cell inside an advancing edge): the two add
        ratio_err = (np.abs(ratio[points] - c_ratio[cpts])
                     + _sphere_lattice(raw, ops.h)[points])
        dir_err = _direction_estimates(raw, coarse, points, cpts, ops.h)
        off_err = np.abs(offset[points] - c_offset[cpts])
        diss = [raw.dissipation[points], coarse.dissipation[cpts]]
        ok = bool(coarse.converged.all())
        if n // 4 >= SPHERE_N_MIN:
            # the work converges fast but unevenly (the contact disc's cell count):
            # Richardson from three runs at the order they show, capped at 2 as the
            # cylinder's (a twofold difference inflated the cycle work's error 20-fold
            # at n = 64)
            _, coarser = _sphere_run(model, n // 4, steps // 4, k, load, tang, False,
                                     displacement=displacement)
            diss.append(coarser.dissipation[np.arange(load.size) * (steps // 4)])
            ok = ok and bool(coarser.converged.all())
            if displacement:
                # Q's lattice error is not monotonic in n (Q/kP at s = 0.9 s*: 1.1e-4,
                # 1.9e-5, 2.4e-5 off at n = 16, 32, 64): the coarser pair's difference at
                # order 1 as well
                c_force = coarser.force[np.arange(load.size) * (steps // 4)]
                force_err = np.maximum(force_err, 0.5 * np.abs(coarse.force[cpts] - c_force)
                                       / (k * ops.p_max))
            diss_err, o3 = _estimate(*diss, 2.0)
        else:  # no third run on a useful grid: the twofold difference (order 1)
            diss_err, o3 = np.abs(diss[0] - diss[1]), 1.0
        orders = {"stick_ratio": 1.0, "stick_offset": 1.0, "dissipation": o3}
        if closed:
            cycle_err, orders["cycle_steps"], ok_c = _sphere_cycle_errors(
                model, n, steps, k, load, tang, displacement, closed,
                _cycle_works(raw, steps, load.size, closed),
                _cycle_works(coarse, steps // 2, load.size, closed))
            ok = ok and ok_c
        else:
            cycle_err = np.zeros(0)
        scale = max(float(raw.dissipation[-1]), 1e-300)
        resolved = (_ratio_resolved(ratio[points], ratio_err, raw.load[points], max_error)
                    & (diss_err <= max_error * scale) & raw.converged[points] & ok)
        if force_err is not None:  # the answered force within max_error (of k P_max)
            with np.errstate(invalid="ignore"):
                resolved &= force_err <= max_error
    else:
        ratio_err = off_err = diss_err = np.full(load.size, np.nan)
        cycle_err = np.full(len(closed), np.nan)
        orders = {}
        resolved = np.zeros(load.size, dtype=bool)
        force_err = np.full(load.size, np.nan) if displacement else None
        dir_err = (np.full((load.size, raw.angles.size), np.nan),) * 2
    dir_a, dir_c, _ = _sphere_directions(raw)
    a, c = raw.contact_radius, raw.stick_radius
    centre = np.where(c > 0, raw.stick_offset, np.nan)
    contact_edges = np.stack([-a, a], axis=1)
    stick_edges = np.stack([centre - c, centre + c], axis=1)
    row = n // 2  # cells at y = h/2, next to the x axis
    zero = np.zeros(n)
    p_row = np.array([zero] + [f[:, row] for f in raw.p]) / ops.p0
    q_row = np.array([zero] + [f[0][:, row] for f in raw.q]) / ops.p0
    v_row = np.array([zero] + [f[0][:, row] for f in raw.v])
    stick_row = np.array([zero.astype(bool)] + [f[:, row] for f in raw.stick])
    touching = p_row > 0
    slip = np.where(touching & ~stick_row, np.diff(v_row, axis=0, prepend=0.0), 0.0)
    state = np.where(~touching, fr.SEPARATED, np.where(
        stick_row, fr.STICK, np.where(q_row >= 0, fr.SLIP_POSITIVE, fr.SLIP_NEGATIVE)))
    bad = np.maximum.accumulate(~raw.converged)[:, None]
    p_row, q_row, slip = (np.where(bad, np.nan, f) for f in (p_row, q_row, slip))
    force = raw.force
    return FrettingResult(
        geometry="sphere", nu=float(model.body.nu), friction=k, n=int(n), steps=int(steps),
        max_error=float(max_error), beta=beta, p_max=ops.p_max, p0=ops.p0,
        load_path=tuple(load.tolist()), tangential_path=tuple(tang.tolist()),
        bulk_stress_path=tuple(sigma.tolist()), x=ops.x, segment=load_levels(load, steps)[1],
        load_ratio=raw.load / ops.p_max, force_ratio=force / (k * ops.p_max),
        bulk_stress=np.zeros(force.size), contact_edges=contact_edges,
        stick_edges=stick_edges, stick_ratio=ratio, stick_offset=offset,
        approach=raw.delta, shift=raw.shift[:, 0], dissipation=raw.dissipation,
        external_work=raw.external_work, stored_energy=raw.stored_energy,
        converged=raw.converged, pressure=p_row, shear=q_row, slip=slip,
        tangential_compliance=_compliance(raw.shift[:, 0], force,
                                          _STILL_FORCE * k * ops.p_max if displacement else 0.0),
        state=state.astype(np.int8),
        point_step=points, stick_ratio_error=ratio_err, stick_offset_error=off_err,
        dissipation_error=diss_err, resolved=resolved,
        cycles=_cycles(load, tang, sigma, raw.dissipation[points], cycle_err), orders=orders,
        model=model, tangential_displacement=displacement, force_ratio_error=force_err,
        direction_angles=raw.angles, stick_radius_directions=dir_c,
        stick_centre=raw.stick_centre, contact_centre=raw.contact_centre,
        contact_radius_directions=dir_a, stick_radius_directions_error=dir_err[0],
        contact_radius_directions_error=dir_err[1])


# convention: the amplitudes of amplitude_study, Q*/(k P)
STUDY_AMPLITUDES = (0.1, 0.25, 0.5, 0.75, 0.9)


def amplitude_study(nus: Sequence[float] = (0.5, 0.3), friction: float = 0.3,
                    amplitudes: Sequence[float] = STUDY_AMPLITUDES, cycles: int = 3,
                    steps: int = DEFAULT_STEPS, n: int = DEFAULT_N,
                    progress: Callable[[int, int], None] | None = None
                    ) -> list[FrettingResult]:
    """Tangential cycles between +-Q* at constant P = P_max for several Q*/kP (rigid cylinder).

    Parameters
    ----------
    nus : sequence of float
        Poisson's ratios of the body (0.5: beta = 0, Mindlin–Deresiewicz applies; 0.3:
        beta = 0.286, coupled).
    friction : float
        k.
    amplitudes : sequence of float
        Q*/(k P_max), each in (0, 1).
    cycles : int
        Full cycles after the first quarter (Q from 0 to Q*), >= 1.
    steps, n : int
        As for :func:`fretting`.
    progress : callable, optional
        ``progress(i, total)`` after each path.

    Returns
    -------
    list of FrettingResult
        For each nu, each amplitude: the path 0 -> P_max, then Q: 0 -> Q* -> -Q* -> Q* ...
        (``cycles`` full cycles), nu-major.
    """
    if not (isinstance(cycles, (int, np.integer)) and cycles >= 1):
        raise ValueError(f"cycles: a positive integer, got {cycles!r}")
    out = []
    total = len(nus) * len(amplitudes)
    for nu in nus:
        for x in amplitudes:
            load = [0.0] + [1.0] * (2 * cycles + 2)
            tang = [0.0, 0.0] + [x, -x] * cycles + [x]
            out.append(fretting("cylinder", nu, friction, load, tang, steps, n=n))
            if progress is not None:
                progress(len(out), total)
    return out


# convention: the stick-zone map's cases: name -> (title, fretting("sphere", ...)'s body and
# indenter); equal bodies with nu = 0 (beta = gamma = 0) make Cattaneo–Mindlin exact
STICK_MAP_CASES = {
    "coupled": ("rigid sphere on ν = 0.3 (β = 0.286)", {"nu": 0.3}),
    "uncoupled": ("equal bodies, ν = 0 (β = γ = 0)",
                  {"nu": 0.0, "indenter_modulus": 1.0, "indenter_nu": 0.0}),
}
# convention: the stick-zone map's path, P/P_max and Q/(k P_max) at its points
STICK_MAP_PATH = ((0.0, 1.0, 1.0, 1.0, 1.0, 1.0), (0.0, 0.0, 0.3, 0.5, 0.7, 0.9))
# convention: the stick-zone map's accuracy asked, units a_max: its departures from a circle
# are 0.02 to 0.1 a_max; a radius per direction at n = 64 is known to half a cell (1.9e-2
# a_max) at best, so under 1e-2 none would be resolved
STICK_MAP_MAX_ERROR = 0.05


def stick_map_study(friction: float = 0.3, n: int = SPHERE_COUPLED_N_MAX, steps: int = 4,
                    max_error: float = STICK_MAP_MAX_ERROR,
                    progress: Callable[[int, int], None] | None = None
                    ) -> dict[str, FrettingResult]:
    """The sphere's stick zone per direction under a growing Q (the stick-zone map).

    Each case of :data:`STICK_MAP_CASES` (a rigid sphere on nu = 0.3, beta = 0.286; equal
    bodies with nu = 0, beta = gamma = 0, where Cattaneo–Mindlin is exact) follows
    :data:`STICK_MAP_PATH`: P to P_max, then Q/(kP) 0 -> 0.3 -> 0.5 -> 0.7 -> 0.9 at
    constant P, with the estimate runs (:func:`sphere_fretting`).

    Parameters
    ----------
    friction : float
        k.
    n, steps : int
        Cells a side and steps a segment (default n = 64, the largest a coupled pair takes,
        and 4 steps: about 30 s for both cases).
    max_error : float
        As for :func:`fretting` (default :data:`STICK_MAP_MAX_ERROR`, 0.05): a radius per
        direction is resolved where its estimate (units a_max) is within it.
    progress : callable, optional
        ``progress(i, total)`` after each case.

    Returns
    -------
    dict of str to FrettingResult
        By the names of :data:`STICK_MAP_CASES`, in its order.
    """
    load, tang = STICK_MAP_PATH
    out = {}
    for name, (_, body) in STICK_MAP_CASES.items():
        kw = dict(body)
        out[name] = fretting("sphere", kw.pop("nu"), friction, load, tang, steps, n=n,
                             max_error=max_error, **kw)
        if progress is not None:
            progress(len(out), len(STICK_MAP_CASES))
    return out


@dataclass(frozen=True)
class StickShape:
    """The sphere's stick zone at one path point, its radius per direction (from
    :func:`stick_shape`; lengths in units of a_max, directions in degrees from +x, the
    direction of Q).

    ``smallest`` and ``largest`` are the least and greatest stick radius c(theta)/a_max over
    the directions (from the stick zone's centroid), at ``smallest_direction`` and
    ``largest_direction``, with their estimates (absolute, units a_max). In units of a_max,
    not of the contact's radius a (``contact_radius``, area-equivalent): a's error would add
    to both, and at P = P_max for beta = 0, a = a_max (Hertz). ``offset`` is the stick zone's
    centre minus the contact's along x, e/a_max, with its estimate. ``converged``: every step
    up to the point converged (else no value is data). ``reason``: why this point (empty when
    it was asked for). ``floor``: half a cell (units a_max), the least error of a radius per
    direction on this grid; below it ``describe`` says that max_error cannot be met.
    """

    point: int
    step: int
    force_ratio: float
    load_ratio: float
    contact_radius: float
    smallest: float
    smallest_error: float
    smallest_direction: float
    largest: float
    largest_error: float
    largest_direction: float
    offset: float
    offset_error: float
    max_error: float
    converged: bool
    reason: str = ""
    floor: float = math.nan  # half a cell (units a_max): a radius per direction's best error

    @property
    def full_slip(self) -> bool:
        """No stick zone (every direction's radius 0)."""
        return self.largest == 0.0

    @property
    def radii_resolved(self) -> bool:
        """Both radii within ``max_error`` (their estimates, units a_max)."""
        return self.converged and all(e <= self.max_error
                                      for e in (self.smallest_error, self.largest_error))

    @property
    def offset_resolved(self) -> bool:
        """e/a_max within ``max_error`` (its estimate)."""
        return self.converged and bool(self.offset_error <= self.max_error)

    @property
    def round(self) -> bool:
        """The spread over the directions within the two estimates: a circle at this grid."""
        return bool(self.largest - self.smallest <= self.largest_error + self.smallest_error)

    def describe(self, a_max: float | None = None,
                 si: Callable[[float, str, int], str] | None = None) -> str:
        """Two lines for a summary: the stick radius's range over the directions and the
        centre's offset, each with its estimate and to the digits the estimate supports, and
        whether each is resolved to ``max_error``.

        Parameters
        ----------
        a_max : float, optional
            a_max in m, with ``si``: the radii and the offset in m instead, the estimates in m.
        si : callable, optional
            ``si(value, unit, digits)``, the formatter of SI values
            (:func:`contactlib.physical.format_si`).
        """
        head = (f"stick zone at point {self.point} (Q/(kP_max) = {self.force_ratio:.4g}"
                + (f", {self.reason}" if self.reason else "") + ")")
        if not self.converged:
            return head + ": a step up to it did not converge; no value is data"
        if self.full_slip:
            return head + ": full slip, no stick zone"
        physical = a_max is not None and si is not None
        scale = a_max if physical else 1.0

        def value(x: float, e: float) -> str:
            if physical:
                x, e = x * scale, e * scale
                return f"{si(x, 'm', _si_digits(x, e))} ({e:.1e} m)"
            return f"{x:.{_decimals(e)}f} ({e:.1e})"

        verdict = ("no estimate" if not math.isfinite(self.smallest_error + self.largest_error)
                   else "a circle within the estimates" if self.round else
                   "not a circle: the spread exceeds the estimates")
        return (f"{head}, from its centroid: {'radius' if physical else 'c/a_max'} (estimate) "
                f"{value(self.smallest, self.smallest_error)} at "
                f"{self.smallest_direction:.0f} deg to "
                f"{value(self.largest, self.largest_error)} at "
                f"{self.largest_direction:.0f} deg, {verdict}\n"
                "  its centre's offset from the contact's along x"
                f"{'' if physical else ', e/a_max'} (estimate) "
                f"{value(self.offset, self.offset_error)}; resolved to max_error = "
                f"{self.max_error:g}: radii {'yes' if self.radii_resolved else 'NO'}, centre "
                f"{'yes' if self.offset_resolved else 'NO'}"
                + (f" (a radius per direction is known to half a cell at best, "
                   f"{self.floor * scale:.1e}{' m' if physical else ' a_max'}, above max_error: "
                   "ask a larger max_error or more cells)"
                   if not self.radii_resolved and self.max_error < self.floor else ""))


def _decimals(error: float) -> int:
    """Decimals a value with this absolute estimate supports: its first uncertain digit
    (6 where the estimate is 0 or not finite)."""
    if not (math.isfinite(error) and error > 0.0):
        return 6
    return int(min(6, max(0, math.floor(-math.log10(error)) + 1)))


def _si_digits(value: float, error: float) -> int:
    """Significant digits of ``value`` down to its first uncertain one (1 to 6), and at
    least its integer digits under an engineering prefix (152 µm, not 1.5e+02 µm)."""
    if not (math.isfinite(error) and error > 0.0 and value != 0.0):
        return 6
    lead = math.floor(math.log10(abs(value)))
    return int(min(6, max(1, lead % 3 + 1, lead - math.floor(math.log10(error)) + 1)))


def stick_shape(res: FrettingResult, point: int | None = None) -> StickShape | None:
    """The sphere's stick zone per direction at a path point: its range of c/a and its
    centre's offset, with their estimates (:class:`StickShape`).

    Parameters
    ----------
    res : FrettingResult
        A sphere's (None is returned for the cylinder's, which has no directions).
    point : int, optional
        The path point. Default: the point of the largest |Q|/(kP), the last of equal ones.
        That is the smallest stick zone of the path, so the widest slip annulus, where the
        surfaces fret; on a cycled path the last such point is the state the cycles
        return to, not the first loading.

    Returns
    -------
    StickShape or None
    """
    if res.stick_radius_directions is None or res.stick_radius_directions_error is None:
        return None
    steps = res.point_step
    reason = ""
    if point is None:
        reason = "the largest |Q|/kP"
        load = res.load_ratio[steps]
        with np.errstate(divide="ignore", invalid="ignore"):
            x = np.where(load > 0, np.abs(res.force_ratio[steps]) / load, -1.0)
        x = np.where(np.isfinite(x), x, -1.0)
        point = int(np.flatnonzero(x >= x.max() * (1.0 - 1e-9))[-1])
    j = int(steps[point])
    ratio = res.stick_radius_directions[j]
    err = res.stick_radius_directions_error[point]
    finite = np.isfinite(ratio)
    converged = bool(res.converged[:j + 1].all()) and bool(finite.any())
    lo = int(np.nanargmin(np.where(finite, ratio, np.inf))) if finite.any() else 0
    hi = int(np.nanargmax(np.where(finite, ratio, -np.inf))) if finite.any() else 0
    deg = np.degrees(res.direction_angles)
    return StickShape(
        point=point, step=j, force_ratio=float(res.force_ratio[j]),
        load_ratio=float(res.load_ratio[j]), contact_radius=float(res.contact_edges[j, 1]),
        smallest=float(ratio[lo]), smallest_error=float(err[lo]),
        smallest_direction=float(deg[lo]), largest=float(ratio[hi]),
        largest_error=float(err[hi]), largest_direction=float(deg[hi]),
        offset=float(res.stick_offset[j]), offset_error=float(res.stick_offset_error[point]),
        max_error=float(res.max_error), converged=converged, reason=reason,
        floor=fsph.MESH_EXTENT / res.n)  # half a cell of 2 L / n
