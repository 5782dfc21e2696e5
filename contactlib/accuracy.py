"""Accuracy targets: pick the method and n for a tolerance on k, then check it.

A scene (or a call) may ask for a relative error in the friction coefficient
k instead of a resolution. Two steps:

1. **Plan** (:func:`plan`, before anything is solved): the cheapest method
   and n that the *measured* convergence says will meet the tolerance at
   every requested stick ratio (the default method, or the extrapolated one
   of :mod:`contactlib.solvers.extrapolated_method` with its own error model,
   :func:`predicted_method_error`). The measurements are the convergence study
   (``snakemake convergence``, :mod:`contactlib.convergence`): the default
   method's k error at n = 256 against Richardson extrapolation, over c/a
   from 0.02 to 0.98 (:data:`ERROR_AT_256`), falling like n^-2 (observed
   order 1.8 ... 2.4 at every c/a for n = 16 ... 2048). The plan aims at
   half the tolerance and rounds n up to a multiple of 64. The paper's scheme
   never qualifies: its k does not converge to the physical value (38 % off
   at c/a = 0.1, 83-126 % at 0.5 for n = 10 ... 320), so no n meets any
   tolerance below 0.3.
2. **Check** (:func:`estimate`, after the solve): the error of each case is
   estimated a posteriori from the same case at n/2 and n/4 (nested meshes):
   with d1 = k(n/4) - k(n/2), d2 = k(n/2) - k(n) and the observed order
   p = log2(d1/d2) in [1, 2], the error of k(n) is estimated as
   |d2| / (2^p - 1); outside that range the levels are not asymptotic and
   the estimate is the larger difference (0 < p < 1), or the size of the
   two leading terms a h^2, b h^3 fitted to the three levels (p > 2, or
   differences of opposite sign; see :func:`estimate`). Where that
   exceeds the tolerance the case is solved again at 2n (up to
   :data:`MAX_N`); the n used and the estimate are recorded. A target that
   cannot be met at MAX_N is reported as such, never silently.

Both use relative errors, |k_n - k| / k.

**Layers.** The error models were measured on the half-space (sphere) and on
the half-plane and the paper's smooth slab a/h = 0.05 (cylinder) only
(:func:`planned_body`). On any other layer the plan takes the default
method alone, whose n^-2 model serves only as the starting n: the a
posteriori check (step 2), which covers the difference to a solution
refined fourfold on layers too (docs/validation.md#layers), then decides
the n. The extrapolated method is not planned there: neither its error
model nor its own estimate has been measured on a layer.
"""

from __future__ import annotations

import math
from typing import Callable, Sequence

import numpy as np

from . import validate
from .estimates import estimate  # the a posteriori check (step 2), in its leaf module
from .model import Contact

__all__ = ["ERROR_AT_256", "MAX_N", "MIN_TOLERANCE", "check_tolerance", "predicted_error",
           "plan", "estimate", "solve_to_tolerance",
           "resolving_n", "DEFAULT_MAX_ERROR", "EXTRAPOLATED_ERROR_AT_256",
           "PLANNED_METHODS", "predicted_method_error", "relative_cost", "planned_body",
           "default_noise",
           "MODEL_SLAB_RATIO"]

MAX_N = validate.MAX_N
# exact: 4 x 16: the default method's n/4 keeps its sixteenths, nested in n/2 and n
MIN_N = 64  # n/4 >= 16 for the order estimate, and n a multiple of 64 (nested meshes)
MIN_TOLERANCE = validate.MIN_TOLERANCE
MAX_TOLERANCE = validate.MAX_TOLERANCE
SAFETY = validate.DEFAULT_PLAN_SAFETY  # the default method's plan aims at tolerance / SAFETY
DEFAULT_MAX_ERROR = validate.DEFAULT_MAX_ERROR  # a larger estimated k error: not resolved

# Relative k error of the default method at n = 256 (nu = 0.3) against the
# Richardson extrapolation of n = 16 ... 2048 (convergence study, observed
# order 1.8 ... 2.4 at every c/a). Sphere on the half-space; cylinder: the
# larger of the half-plane and a/h = 0.05. Columns: c/a. The sphere's error
# changes sign near c/a = 0.7 (measured 0 there, to the study's resolution);
# the table carries the larger neighbour instead.
_C_TABLE = np.array([0.02, 0.1, 0.3, 0.5, 0.7, 0.9, 0.98])
ERROR_AT_256 = {
    "sphere": np.array([7.2e-5, 2.7e-5, 1.6e-5, 1.6e-5, 3.1e-5, 3.1e-5, 1.5e-4]),
    "cylinder": np.array([1.8e-5, 1.9e-5, 2.0e-5, 1.4e-5, 1.1e-5, 3.3e-5, 1.4e-4]),
}


# Relative k error of the extrapolated method at n = 256, the largest over nu = 0, 0.3, 0.45
# and both geometries at each c/a: against tests/data/frontier_reference.json at 0.1 ... 0.9
# (6.0e-7 at most), against n = 512 at 0.02, 0.05, 0.95, 0.98; falling like n^-3 (6.0e-7 ->
# 7.7e-8 from n = 256 to 512), plus the quadrature noise of the mesh's smallest elements
# (extrapolated_method.quadrature_noise), which grows with n. Columns: _X_TABLE.
_X_TABLE = np.array([0.02, 0.05, 0.1, 0.3, 0.5, 0.7, 0.9, 0.95, 0.98])
EXTRAPOLATED_ERROR_AT_256 = np.array([1.5e-7, 1.6e-7, 2.1e-7, 4.0e-7, 6.1e-7, 6.0e-7, 3.3e-7,
                                      2.6e-7, 2.4e-7])
# The five-level estimate of the extrapolated method from n = 1024 (extrapolated_method.
# LOG_LEVEL_FROM_N: half-space bodies, 1e-4 < c/a < 1 - 5e-4, n a multiple of 512 so that
# the levels nest down to n/32): its truncation part |k5(n/2) - k5(n)| / 7 at n = 1024, the
# largest measured at each c/a of _X_TABLE (nu = 0.4999999, both geometries, c/a = 0.003 ...
# 0.995; nu = -0.5, 0, 0.3, sphere, c/a = 0.02, 0.1, 0.5, 0.9, 0.98), rounded up, falling
# like n^-4 (0.87e-9 -> 0.19e-9 from n = 1024 to 1536 at c/a = 0.5, nu = 0.4999999; n^-4
# gives 0.17e-9), plus its noise bound (extrapolated_method.log_noise), a function of c/a
# alone (with the band rows relative to a cascade of references; it grew like n^2 before).
# Re-measured with that cascade and the fine rules on the band rows from n = 1024 (sphere
# and cylinder, nu = 0.4999999, c/a = 0.005 ... 0.99): at most 1.6e-10 (0.02), 8.9e-10
# (0.5), 2.4e-10 (0.9), 1.4e-10 (0.97), 1.1e-10 (0.98), within the table. Columns: _X_TABLE.
LOG_ESTIMATE_AT_1024 = np.array([2.0e-10, 2.0e-10, 2.8e-10, 5.3e-10, 9.0e-10, 6.3e-10, 3.3e-10,
                                 2.4e-10, 2.4e-10])
# exact: 32 x 16: the five levels nest down to n/32, a mesh of sixteenths
LOG_N_MULTIPLE = 512
PLANNED_METHODS = tuple(name for name, m in validate.METHOD_REGISTRY.items() if m.planned)
# The largest a/h of the (smooth-base) slab the error models were measured on: the paper's
# cylinder case, a/h = 1/20 (the sphere's models are the half-space's alone)
# limit: the slabs the error models were measured on (benchmarks/report_convergence_table.py; the
# paper's cylinder case a/h = 1/20)
MODEL_SLAB_RATIO = {"sphere": 0.0, "cylinder": 0.05}


def planned_body(geometry: Contact) -> bool:
    """Whether the planner's error models were measured on ``geometry``'s body.

    True on the half-space or half-plane, and for the cylinder on the smooth
    slab up to a/h = :data:`MODEL_SLAB_RATIO` (the paper's case); False on
    every other layer, where :func:`plan` takes the default method alone.
    """
    body = geometry.body
    if body.is_half_space:
        return True
    limit = MODEL_SLAB_RATIO.get(geometry.indenter.name, 0.0)
    return body.base == "smooth" and float(body.slab_ratio) <= limit


def predicted_method_error(method: str, geometry: str, stick_ratio: float, n: int) -> float:
    """Measured-model relative k error of ``method`` (``"default"`` or ``"extrapolated"``)
    on the half-space (the extrapolated method's: its four-level model, or from n = 1024
    the five-level estimate where that is the smaller)."""
    if validate.method_of(method).nested_estimate:
        return predicted_error(geometry, stick_ratio, n)
    c = float(stick_ratio)
    if c <= 0.0 or c >= 1.0:
        return 0.0
    return min(_extrapolated_truncation(np.array([c]), n) + _extrapolated_noise(c, n),
               _five_level_estimate(True, np.array([c]), n))


def _five_level_estimate(half_space: bool, stick_ratios: np.ndarray, n: int) -> float:
    """The largest predicted five-level estimate of the extrapolated method over
    ``stick_ratios`` (all inside (0, 1)) at n: the measured truncation part
    (:data:`LOG_ESTIMATE_AT_1024`, n^-4) plus the noise bound at each stick ratio; inf
    where the method does not extrapolate from five levels (below n = 1024, n not a multiple
    of 512, a layer, c/a <= 1e-4 or >= 1 - 5e-4)."""
    from .solvers.default_method import AXIS_ROWS_BELOW, EDGE_ROWS_BELOW
    from .discretization.elements import graded_mesh
    from .solvers.extrapolated_method import LOG_LEVEL_FROM_N, log_noise

    if (n < LOG_LEVEL_FROM_N or n % LOG_N_MULTIPLE or not half_space
            or stick_ratios.size == 0 or stick_ratios.min() <= AXIS_ROWS_BELOW
            or 1.0 - stick_ratios.max() <= EDGE_ROWS_BELOW):
        return math.inf
    truncation = float(np.max(np.interp(stick_ratios, _X_TABLE, LOG_ESTIMATE_AT_1024))
                       * (LOG_LEVEL_FROM_N / n) ** 4)
    return truncation + max(log_noise(graded_mesh(n, float(c))) for c in set(stick_ratios))


def _extrapolated_truncation(stick_ratios: np.ndarray, n: int) -> float:
    """The largest truncation part of the extrapolated method's model over ``stick_ratios``."""
    at256 = np.interp(stick_ratios, _X_TABLE, EXTRAPOLATED_ERROR_AT_256)
    return float(np.max(at256) * (256.0 / n) ** 3)


def _extrapolated_noise(stick_ratio: float, n: int) -> float:
    """The quadrature-noise part of the extrapolated method's model at one stick ratio."""
    from .discretization.elements import graded_mesh
    from .solvers.extrapolated_method import BAND_FROM_N, quadrature_noise

    return float(quadrature_noise(graded_mesh(n, stick_ratio), band=n >= BAND_FROM_N))


def default_noise(geometry: Contact, stick_ratio: float, n: int) -> float:
    """The quadrature-noise bound added to the default method's k estimate (relative).

    From n = :data:`~contactlib.solvers.default_method.NEAR_ROWS_FROM_N` (512) on, the
    default method's mesh and rows at n are those of the extrapolated method's
    finest level, whose noise bound
    (:func:`~contactlib.solvers.extrapolated_method.quadrature_noise`) was measured on the
    half-space and half-plane; there it is added to the estimate from the nested
    levels, which do not see a noise that grows with n. It matters at the extremes:
    nu = 0.49999 against the closed form, c/a = 1e-6, n = 1024, the sphere's k error
    was 1.9e-5 against an estimate of 5.3e-6 from the levels (3.6x short), the
    half-plane's 4.5e-5 against 2.9e-5 at n = 2048; the bound there is 5.1e-5 and 6.8e-5
    (2.5e-5 and 3.4e-5 before its margin for other CPUs, see
    :data:`~contactlib.solvers.extrapolated_method.DIFFERENCE_NOISE`).
    At c/a = 0.02 ... 0.98 it is at most 1.2e-8 (n = 2048), below the method's error.
    Below n = 512 it is the bound of the axis or edge difference rows
    (:data:`~contactlib.solvers.extrapolated_method.DIFFERENCE_NOISE`) where those rows apply
    (c/a <= 1e-4, 1 - c/a <= 5e-4), and 0 elsewhere (the levels' estimate was measured to
    cover the error there, docs/accuracy.md). At the extremes the levels did not cover
    it (nu = 0.4999999 against the closed form; issue 42): sphere, c/a = 1e-8, n = 384,
    error 1.23e-4 against 3.0e-5 from the levels (the error grows from n = 256, 6.5e-5:
    noise); c/a = 1 - 1e-5, n = 384, 5.2e-6 against 8.8e-7; the half-plane at c/a = 1e-8,
    n = 64 ... 256, 1.4 ... 1.7 times its estimate, at 1e-6, n = 256, 4.5e-7 against 3.8e-7
    (an n-independent floor: 4.6e-7 at n = 128). 0 at c/a = 0 and 1 (k exact) and on a
    layer (not measured).
    """
    from .solvers.default_method import AXIS_ROWS_BELOW, EDGE_ROWS_BELOW, NEAR_ROWS_FROM_N
    from .discretization.elements import graded_mesh
    from .solvers.extrapolated_method import quadrature_noise

    c = float(stick_ratio)
    if not 0.0 < c < 1.0 or not geometry.body.is_half_space:
        return 0.0
    if n < NEAR_ROWS_FROM_N:
        if c <= AXIS_ROWS_BELOW or 1.0 - c <= EDGE_ROWS_BELOW:  # the difference rows
            return float(quadrature_noise(graded_mesh(n, c), difference=True))
        return 0.0
    return _extrapolated_noise(c, n)  # the same mesh and rows (the band from n = 512)


def relative_cost(method: str, n: int) -> float:
    """Time of one case, in units of the default method's at n = 256: ~n^2 (kernels) up to
    n = 1024, the dense LU's n^3 beyond."""
    scale = (n / 256.0) ** 2 * max(1.0, n / 1024.0)
    return validate.method_of(method).relative_cost * scale


def _cheapest_n(method: str, geometry: Contact, stick_ratios: Sequence[float],
                tolerance: float) -> int | None:
    """The smallest admissible n whose predicted error is within tolerance / safety.

    The default method's prediction includes the noise bound its estimate carries
    (:func:`default_noise`, from n = 512): at the extremes that bound grows with n, and
    without it the plan picked an n whose solve could not meet the tolerance (sphere,
    nu = 0.4999999, c/a = 1e-6, tolerance 3e-6: n = 1792, 19 s, estimate 6.4e-5).
    """
    step = max(validate.method_of(method).n_multiple, 64)  # 64: the default method's plan
    inside = np.array([float(c) for c in stick_ratios if 0.0 < float(c) < 1.0])
    limit = tolerance / validate.method_of(method).plan_safety
    for n in range(max(step, MIN_N), MAX_N + 1, step):
        if validate.method_of(method).own_estimate:  # c/a = 0 and 1 are exact
            # the truncation part is largest where its table is (mid c/a), the noise at the
            # extreme c/a on either side (the smallest elements): each bounded by its largest
            # (from n = 1024 the five-level estimate where it is the smaller: the method
            # takes the smaller of the two)
            meets = inside.size == 0 or min(
                _extrapolated_truncation(inside, n)
                + max(_extrapolated_noise(c, n) for c in {inside.min(), inside.max()}),
                _five_level_estimate(geometry.body.is_half_space, inside, n)) <= limit
        else:
            meets = all(predicted_method_error(method, geometry.indenter.name, c, n)
                        + default_noise(geometry, c, n) <= limit for c in stick_ratios)
        if meets:
            return n
    return None


def check_tolerance(value: object) -> float:
    """A relative tolerance on k, in [MIN_TOLERANCE, MAX_TOLERANCE] (:func:`validate.tolerance`)."""
    return validate.tolerance(value)


def predicted_error(geometry: str, stick_ratio: float, n: int) -> float:
    """Measured-model relative k error of the default method (0 at c/a = 0 and 1: exact)."""
    c = float(stick_ratio)
    if c <= 0.0 or c >= 1.0:
        return 0.0
    table = ERROR_AT_256[geometry]
    if c > _C_TABLE[-1]:  # thinner slip zone than measured: scale like the last interval
        slope = np.log(table[-1] / table[-2]) / np.log((1 - _C_TABLE[-2]) / (1 - _C_TABLE[-1]))
        at256 = table[-1] * ((1 - _C_TABLE[-1]) / (1 - c)) ** slope
    else:
        at256 = float(np.exp(np.interp(c, _C_TABLE, np.log(table))))
    return float(at256 * (256.0 / n) ** 2)


def plan(geometry: Contact, stick_ratios: Sequence[float], tolerance: float,
         methods: Sequence[str] = (validate.DEFAULT_METHOD,)) -> tuple[str, int]:
    """The cheapest (method, n) predicted to meet ``tolerance`` at every stick ratio.

    With ``methods = ("default",)``: ``("default", n)`` with n a multiple of
    64 in [64, MAX_N]. With :data:`PLANNED_METHODS` (scenes, the command
    line's and the library's ``tolerance``): of the methods whose measured
    error model (:func:`predicted_method_error`) meets tolerance / safety at
    some n, the one of least :func:`relative_cost` (the extrapolated method
    from about 1e-5 down: 1e-6 costs it n = 256, the default n = 2048).

    On a layer the models were not measured on (:func:`planned_body`) only
    the default method is planned, its n^-2 model giving the starting n; the
    a posteriori check after the solve decides the n used.

    Raises
    ------
    ValueError
        When even ``MAX_N`` is predicted to miss the tolerance (names the
        worst stick ratio and the n it would need).
    """
    tol = check_tolerance(tolerance)
    layer_note = ""
    if not planned_body(geometry):
        methods = (validate.DEFAULT_METHOD,)
        layer_note = (" (on this layer only the default method is planned: the error models "
                      "were measured on the half-space)")
    if tuple(methods) != (validate.DEFAULT_METHOD,):
        options = []
        for method in methods:
            n = _cheapest_n(method, geometry, stick_ratios, tol)
            if n is not None:
                options.append((relative_cost(method, n), method, n))
        if options:
            return min(options)[1:]
        name = geometry.indenter.name
        worst = max(stick_ratios, key=lambda c: predicted_error(name, c, 256))
        need = 64 * math.ceil(256.0 * math.sqrt(SAFETY * predicted_error(name, worst, 256)
                                                / tol) / 64)
        default_part = (f"the default method would need about n = {need} at c/a = {worst:g}, "
                        f"beyond the largest supported n = {MAX_N}" if need > MAX_N else
                        "the default method's quadrature noise (from the smallest elements) "
                        "stays above it at some requested c/a")
        beyond = [c for c in stick_ratios
                  if _cheapest_n("extrapolated", geometry, [c], tol) is None]
        where = (f"at c/a = {', '.join(f'{c:g}' for c in beyond[:5])}"
                 f"{' ...' if len(beyond) > 5 else ''}" if beyond else
                 "at every n that serves all the requested c/a at once")
        raise ValueError(f"tolerance {validate.shown(tol)} is beyond every method: "
                         f"{default_part}, and the extrapolated method's noise bound (the "
                         f"round-off of the rows next to c, measured by c/a and n) stays above "
                         f"it {where}")
    worst = max(stick_ratios, key=lambda c: predicted_error(geometry.indenter.name, c, 256))
    e256 = predicted_error(geometry.indenter.name, worst, 256)
    if e256 == 0.0:
        return validate.DEFAULT_METHOD, MIN_N
    need = 256.0 * math.sqrt(SAFETY * e256 / tol)
    n = max(MIN_N, 64 * math.ceil(need / 64))
    if n > MAX_N:
        raise ValueError(f"tolerance {validate.shown(tol)} needs about n = {n} at c/a = "
                         f"{worst:g} (measured k error {e256:.1e} at n = 256, falling like "
                         f"n^-2), beyond the "
                         f"largest supported n = {MAX_N}{layer_note}")
    return validate.DEFAULT_METHOD, n


def resolving_n(n: int, error: float, max_error: float) -> int | None:
    """The n (a multiple of 64) that the n^-2 convergence says brings ``error`` to max_error/2.

    None when that exceeds :data:`MAX_N` or the error is not finite.
    """
    if not math.isfinite(error):
        return None
    need = 64 * math.ceil(n * math.sqrt(SAFETY * error / max_error) / 64)
    return need if need <= MAX_N else None


def solve_to_tolerance(solve_k: Callable[[int], float], n: int, tolerance: float,
                       known: dict[int, float] | None = None,
                       noise: Callable[[int], float] | None = None) -> tuple[int, float, str]:
    """Refine n (doubling, up to MAX_N) until the a-posteriori estimate meets the tolerance.

    Parameters
    ----------
    solve_k : callable
        ``solve_k(n) -> k`` for one case (only called for the n not in ``known``).
    n : int
        Planned resolution (a multiple of 64).
    tolerance : float
    known : dict, optional
        k already computed, by n (e.g. the planned solve itself).
    noise : callable, optional
        ``noise(n)``, a bound added to the estimate at n (:func:`default_noise`). Where
        it alone exceeds the tolerance and grows with n, the refinement stops there (a
        solve at 2n, up to n = 4096 at 17 s and 3 GiB, could not meet it).

    Returns
    -------
    (n_used, error_estimate, message)
        ``message`` is empty when the target is met.
    """
    ks = dict(known or {})

    def k_at(m: int) -> float:
        if m not in ks:
            ks[m] = float(solve_k(m))
        return ks[m]

    while True:
        est, _ = estimate(k_at(n // 4), k_at(n // 2), k_at(n))
        part = 0.0 if noise is None else noise(n)
        est += part
        if est <= tolerance:
            return n, est, ""
        if 2 * n > MAX_N:
            return n, est, (f"tolerance {tolerance:g} not met: estimated k error {est:.2g} at "
                            f"the largest n = {n}")
        if part > tolerance and noise(2 * n) >= part:  # refining cannot help: stop here
            return n, est, (f"tolerance {tolerance:g} not met: estimated k error {est:.2g} at "
                            f"n = {n}, where the kernels' quadrature noise alone ({part:.2g}) "
                            "exceeds it and grows with n (no n meets it)")
        n *= 2
