"""The computation in stages: influence -> solve -> check / energy / profiles.

Each stage is a pure function of numpy arrays and plain values, so the
Snakemake workflow can run one stage a rule and hand the arrays on through
:mod:`contactlib.io`, while :func:`contactlib.solve` runs the same functions in
one process: both give the same numbers.

* :func:`influence` -- the collocation operators ("influence matrices") of one
  part, ``"normal"`` (of the pressures) or ``"shear"`` (of the shears). The
  paper's rings do not depend on c/a, so one set serves every m/n. The default
  method puts a node at c, so its operators depend on c: the set holds one
  mesh per distinct stick ratio.
* :func:`solve_cases` -- Newton per stick ratio, giving one *case record*
  each (:class:`~contactlib.result.CaseRecord`): the discrete solution, its
  status, its error estimates and, when asked, the samples the checks and
  the energy need (slip rate at points of the slip zone, tractions at
  stick-zone points).
* :func:`check_case`, :func:`work_case`, :func:`profiles` -- the consistency
  flags, the frictional work, and the profiles on the output grid.
* :func:`to_solution` -- a :class:`~contactlib.result.Solution` from the pieces.

Units inside: E* = a = R = 1 (see :mod:`contactlib.solvers.default_method`).
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any, Callable, Iterator, Sequence

import numpy as np

from . import checks, energy, validate
from .solvers.default_method import DiscreteSolution, nodal_operator_part, solve_default
from .discrete import SelfSimilarSolution
from .discretization.operators import (PARTS, StickBlocks, nodal_operators, parts_needed,
                                       restrict_with_slip_samples, slip_zone_samples)
from .discretization.elements import Mesh, MeshStore, graded_mesh, uniform_mesh
from .model import Contact
from .solvers.paper_method import PaperSolution, collocation_points, ring_operator, solve_paper
from .result import CaseRecord, Solution
from .estimates import coated_estimate, edge_zone_resolved
from .accuracy import (MAX_N, SAFETY, default_noise, estimate, planned_body, predicted_error,
                       resolving_n)
from .solvers import extrapolated_method
__all__ = ["PARTS", "OUTPUTS", "parts_needed", "influence", "solve_cases", "iter_cases",
           "check_case", "work_case", "profiles", "to_solution", "decoupled_message", "solve_one",
           "case_record", "estimate_case", "QUADRATURE_FLOOR_H"]

# Elements shorter than this (in a) next to c are never reported as resolved: below them
# k is not known to converge under refinement. Both floors were the round-off of O(1)
# displacements amplified in the stick-edge condition, not the element quadrature: a
# tiny stick zone's normal rows are now relative to the axis (c/a <= 1e-4), a thin slip
# annulus's normal and stick rows relative to a node a few widths inside (1 - c/a <=
# 5e-4) (contactlib.solvers.default_method.AXIS_ROWS_BELOW, EDGE_ROWS_BELOW). nu = 0.499 against
# the closed form, sphere, c/a = 1e-8: -1.24e-3, -3.1e-4, -6.0e-5, +4.5e-5 at n = 64 ...
# 512 (before -1.2e-3, -2.2e-4, -2.7e-4, and erratic); c/a = 1 - 1e-5: 4.4e-5, 1.5e-5,
# 4.0e-6, 6.1e-6 (before 6.4e-5, 2.1e-4, -2.9e-4, 5.7e-3); half-plane within 1.4e-5 at
# every n for both. The floors were 5e-11 (stick) and 5e-9 (annulus); they are now the
# smallest elements measured (n = 512: 2.25e-13 a at c/a = 1e-8, 2.3e-10 a at 1 - 1e-5).
# limit: the smallest elements measured (n = 512 at c/a = 1e-8 and 1 - 1e-5);
# tests/test_extremes.py checks tiny stick zones against the closed form
QUADRATURE_FLOOR_H = {"stick": 2e-13, "annulus": 2e-10}
OUTPUTS = validate.OUTPUTS
NODAL_METHODS = tuple(name for name, m in validate.METHOD_REGISTRY.items()
                      if m.nodal)  # nodal tractions on the graded mesh at c


def decoupled_message(geometry: Contact | None = None) -> str:
    """The note attached to every decoupled (beta = 0) case: nu = 0.5, or identical materials."""
    cause = ("nu = 0.5" if geometry is None or geometry.indenter.rigid else
             f"beta = 0 (E1/E2 = {geometry.indenter.modulus_ratio:g}, "
             f"nu1 = {geometry.indenter_poisson_ratio:g}, nu2 = {geometry.body.nu:g})")
    return (f"{cause}: the normal and tangential problems decouple; no shear arises (q = 0) "
            "and every stick ratio is consistent with any k >= 0")


def _decoupled(geometry: Contact) -> bool:
    return geometry.decoupled


def _solved_ratio(geometry: Contact, c: float) -> float:
    """The stick ratio actually solved: nu = 0.5 reduces every case to Hertz (c = 0)."""
    return 0.0 if _decoupled(geometry) else float(c)


# ----------------------------------------------------------------------------- influence
def influence(geometry: Contact, method: str, n: int, stick_ratios: Sequence[float],
              part: str) -> dict[str, np.ndarray]:
    """Collocation operators of one part for a set of cases.

    Parameters
    ----------
    geometry : Contact
    method : {"default", "paper", "paper-literal"}
    n : int
        Elements across the half-contact.
    stick_ratios : sequence of float
        The c/a of the cases (the default method needs one mesh per value).
    part : {"normal", "shear"}

    Returns
    -------
    dict
        Default method: ``stick_ratios`` (K,), ``sizes`` (K,) the element
        count N_i of each case's mesh (it grows toward c/a = 0 and 1, see
        :func:`~contactlib.discretization.elements.graded_mesh`), ``nodes`` (K, N+1),
        N = max N_i, NaN-padded beyond N_i + 1, and ``ops``, the meshes'
        operators (3, N_i+1, N_i+1) (the w, u, du/dx at the nodes of nodal
        tractions) raveled and concatenated in the order of ``sizes``
        (unpadded: the default config's 28 meshes of n = 256 take 73 MB a
        part instead of the 166 MB of a (K, 3, N+1, N+1) block, written
        and read again by the workflow).
        Paper methods: ``nodes`` (n+1,) and ``ops`` (3, n+2, n) at
        :func:`~contactlib.solvers.paper_method.collocation_points`. Memory:
        24 (N_i+1)^2 bytes a mesh and part (1.6 MB at N_i = 256, 25 MB at 1024).
    """
    if part not in PARTS:
        raise ValueError(f"part must be one of {', '.join(PARTS)}, got {part!r}")
    if method in NODAL_METHODS:
        cs = np.unique([_solved_ratio(geometry, c) for c in stick_ratios])
        meshes = [graded_mesh(n, c) for c in cs]
        sizes = np.array([mesh.n for mesh in meshes])
        size = int(sizes.max()) + 1  # the mesh's element count depends on c: NaN-padded
        nodes = np.full((len(meshes), size), np.nan)
        starts = _op_starts(sizes)
        ops = np.empty(starts[-1])
        cache = StickBlocks()  # this call's: the stick blocks shared across its c/a
        for i, mesh in enumerate(meshes):
            m = mesh.n + 1
            nodes[i, :m] = mesh.nodes
            ops[starts[i]:starts[i + 1]] = nodal_operator_part(geometry, mesh, part,
                                                               cache=cache).ravel()
        return {"stick_ratios": cs, "sizes": sizes, "nodes": nodes, "ops": ops}
    r = uniform_mesh(n, 0).nodes
    return {"nodes": r, "ops": ring_operator(geometry, r, collocation_points(n), part)}


def _op_starts(sizes: np.ndarray) -> np.ndarray:
    """Where each mesh's operator (3, N_i+1, N_i+1) starts in a default set's ``ops``, and the end."""
    return np.concatenate([[0], np.cumsum(3 * (np.asarray(sizes, dtype=np.int64) + 1) ** 2)])


def _meshes(cache: StickBlocks | None) -> MeshStore | None:
    """The caller's store of graded meshes, carried by its store of stick blocks."""
    return None if cache is None else cache.meshes


def _lookup(table: dict[str, np.ndarray] | None, method: str, c: float,
            nodes: np.ndarray) -> np.ndarray | None:
    """The operator of one case from an influence set (None when not given)."""
    if table is None:
        return None
    if method not in NODAL_METHODS:
        if not np.array_equal(table["nodes"], nodes):
            raise ValueError("influence matrices were built for another mesh")
        return table["ops"]
    hit = np.flatnonzero(table["stick_ratios"] == c)
    m = int(table["sizes"][hit[0]]) + 1 if hit.size else 0
    if hit.size == 0 or not np.array_equal(table["nodes"][hit[0], :m], nodes):
        raise ValueError(f"influence matrices hold no mesh for stick ratio {c!r}")
    if table["ops"].ndim == 4:  # a set written before the unpadded layout: (K, 3, N+1, N+1)
        return table["ops"][hit[0], :, :m, :m]
    starts = _op_starts(table["sizes"])
    return table["ops"][starts[hit[0]]:starts[hit[0] + 1]].reshape(3, m, m)


# ----------------------------------------------------------------------------- solve
def solve_one(geometry: Contact, method: str, n: int, c: float, normal, shear,
              k_guess: float | None = None, ops: tuple | None = None,
              cache: StickBlocks | None = None, level_offsets: tuple | None = None):
    """One stick ratio with the chosen method, no post-processing (a discrete solution).

    ``normal``/``shear`` are influence sets from :func:`influence` (or None:
    computed on the fly); ``ops`` the default method's operators on its mesh;
    ``cache`` the caller's store of stick blocks; ``level_offsets`` the
    extrapolated method's coarse-level starts from a neighbouring case.
    """
    if method in NODAL_METHODS:
        if ops is None:
            mesh = graded_mesh(n, c, store=_meshes(cache))
            pw = _lookup(normal, method, c, mesh.nodes)
            qw = _lookup(shear, method, c, mesh.nodes) if 0.0 < c else None
            ops = None if pw is None else (pw, qw)
        if validate.method_of(method).own_estimate:  # the samples give the finest level's work
            return extrapolated_method.solve_extrapolated(geometry, c, n, ops=ops,
                                                          k_guess=k_guess, cache=cache,
                                                          work=False,
                                                          level_offsets=level_offsets)
        return solve_default(geometry, c, n, ops=ops, k_guess=k_guess, cache=cache)
    m = validate.paper_multiple(c, n)
    r = uniform_mesh(n, m).nodes
    pr = _lookup(normal, method, c, r)
    sh = _lookup(shear, method, c, r) if m > 0 else None
    ops = None if pr is None else (pr, sh)
    return solve_paper(geometry, m, n, coulomb=validate.method_of(method).coulomb, ops=ops)


def case_record(geometry: Contact, d: SelfSimilarSolution, samples: bool) -> CaseRecord:
    """The case record of a discrete solution (and, with ``samples``, what checks and work need)."""
    nodes, m = d.mesh.nodes, d.mesh.stick_index
    converged, message = bool(d.converged), str(d.message or "")
    extra: dict[str, Any] = {}
    if d.nodal_u is not None:
        extra.update(nodal_u=np.asarray(d.nodal_u, dtype=float),
                     nodal_du=np.asarray(d.nodal_du, dtype=float))
    if samples:
        if 0 < m < d.mesh.n:
            xs, ws, q_slip, s_slip = d.slip_samples()
        else:
            xs = ws = q_slip = s_slip = np.empty(0)
        pts = d.stick_points()
        extra.update(slip_x=xs, slip_w=ws, slip_q=q_slip, slip_s=s_slip,
                     stick_q=d.shear(pts), stick_p=d.pressure(pts))
        if converged and not np.all(np.isfinite(s_slip)):  # never a silent NaN as converged
            converged = False
            message = "; ".join(x for x in (message, (
                "the slip-rate samples hit a kernel singularity (a slip zone narrower than "
                "the quadrature resolves); flags and work are not reliable")) if x)
    return CaseRecord(
        kind=d.kind, stick_ratio=float(nodes[m]), nodes=np.asarray(nodes, dtype=float),
        stick_index=int(m), p=np.asarray(d.p, dtype=float),
        traction=np.asarray(d.traction, dtype=float), k=float(d.k), delta=float(d.delta),
        converged=converged, residual_norm=float(d.residual_norm),
        iterations=int(d.iterations), message=message, load=float(d.load()),
        round_off=float(d.round_off), **extra)


# the discrete solution of each record kind (the interpolation between its nodes)
_KINDS: dict[str, type[SelfSimilarSolution]] = {
    cls.kind: cls for cls in (DiscreteSolution, PaperSolution)}


def _rebuild(geometry: Contact, rec: CaseRecord) -> SelfSimilarSolution:
    """The discrete solution a case record holds (no solve: its fields as they are)."""
    mesh = Mesh(np.asarray(rec.nodes, dtype=float), int(rec.stick_index))
    return _KINDS[rec.kind](geometry, mesh, rec.p, rec.traction, float(rec.delta),
                            k=float(rec.k), converged=bool(rec.converged),
                            residual_norm=float(rec.residual_norm),
                            iterations=int(rec.iterations), message=str(rec.message),
                            nodal_u=rec.nodal_u, nodal_du=rec.nodal_du)


def solve_cases(geometry: Contact, method: str, n: int, stick_ratios: Sequence[float], *,
                normal: dict[str, np.ndarray] | None = None,
                shear: dict[str, np.ndarray] | None = None, samples: bool = True,
                tolerance: float | None = None,
                progress: Callable[[int, int], None] | None = None,
                max_error: float = validate.DEFAULT_MAX_ERROR,
                estimate: bool = True) -> list[CaseRecord]:
    """Solve every stick ratio; one case record each, in the given order.

    Parameters
    ----------
    geometry : Contact
    method : {"default", "paper", "paper-literal"}
    n : int
    stick_ratios : sequence of float
        c/a values in [0, 1] (multiples of 1/n for the paper methods).
    normal, shear : dict, optional
        Influence sets from :func:`influence` (computed on the fly when not
        given).
    samples : bool
        Also store the samples :func:`check_case` and :func:`work_case` need.
    tolerance : float, optional
        Relative error in k to reach (default method): each case's error is
        estimated from n/2 and n/4 and n doubled where it falls short (see
        :func:`contactlib.accuracy.solve_to_tolerance`); the record then
        holds ``elements`` (the n used) and ``error_estimate``.
    progress : callable, optional
        ``progress(i, total)`` after each case.
    max_error : float
        Relative k error above which a case is not ``resolved`` (default 1e-3).
    estimate : bool
        Estimate the errors (default). ``False`` skips the nested coarse
        solves and leaves the records without estimates and ``resolved``
        (their cost is measured this way in ``benchmarks/bench_error_estimate.py``).

    Returns
    -------
    list of CaseRecord
        One a stick ratio (see :class:`~contactlib.result.CaseRecord`). A
        case that fails to converge is kept, with ``converged`` False and a
        message.
    """
    out = []
    for i, rec in enumerate(iter_cases(geometry, method, n, stick_ratios, normal=normal,
                                       shear=shear, samples=samples, tolerance=tolerance,
                                       max_error=max_error, estimate=estimate)):
        out.append(rec)
        if progress is not None:
            progress(i + 1, len(stick_ratios))
    return out


def iter_cases(geometry: Contact, method: str, n: int, stick_ratios: Sequence[float], *,
               normal: dict[str, np.ndarray] | None = None,
               shear: dict[str, np.ndarray] | None = None, samples: bool = True,
               tolerance: float | None = None,
               max_error: float = validate.DEFAULT_MAX_ERROR,
               estimate: bool = True) -> Iterator[CaseRecord]:
    """The case records of :func:`solve_cases`, one at a time, in the given order.

    Successive default-method cases continue from each other: Newton's
    starting k comes from the cases already solved (:func:`_continuation_guess`).
    Every record carries an error estimate (:func:`_embedded_estimate`) and
    ``resolved``: converged, and the estimated relative error of k at most
    ``max_error``.
    """
    known: list[tuple[float, float]] = []  # (c, oriented k / k_uncoupled) of converged cases
    offsets = None  # the extrapolated method's coarse levels, from the last case
    cache = StickBlocks()  # this sweep's store of stick blocks (see nodal_operator_part)
    for c in stick_ratios:
        c = float(c)
        solved = _solved_ratio(geometry, c)
        cont = (_continuation_guess(geometry, solved, known) if method in NODAL_METHODS
                else None)
        with_coarse = (estimate and validate.method_of(method).nested_estimate
                       and tolerance is None)
        d, coarse, ops = _solve_from(geometry, method, n, solved, cont, normal, shear, cache,
                                     with_coarse, level_offsets=offsets)
        if cont is not None and _suspect(d, cont):
            # the continuation guess extrapolates k/k_uncoupled in c/a and can land outside
            # Newton's basin, or in that of another, unphysical root (cylinder, a/h = 1,
            # nu = 0.499, c/a = 0.01 after 1e-8, 1e-6, 1e-4 at n = 256: k = 42.1, against
            # 0.0832 alone): solve the case again as alone, and keep that unless it is worse
            lone, lone_coarse, _ = _solve_from(geometry, method, n, solved, None, normal,
                                               shear, cache, with_coarse, ops)
            if lone.converged and (not d.converged or not _suspect(lone, None)
                                   or _suspect(d, None)):
                d, coarse = lone, lone_coarse
        if method in NODAL_METHODS and d.converged and 0.0 < solved < 1.0 and d.k > 0.0:
            known.append((solved, d.oriented_k / float(geometry.uncoupled_friction(solved))))
            offsets = getattr(d, "level_offsets", None) or None
        extra, note = {}, ""
        if tolerance is not None:
            d, extra, note = _to_tolerance(geometry, method, n, solved, d, tolerance, cache)
        rec = case_record(geometry, d, samples)
        if isinstance(d, extrapolated_method.ExtrapolatedSolution):
            extra = {**_extrapolated_estimates(geometry, d, rec, samples), **extra}
        if note:
            extra["message"] = "; ".join(x for x in (rec.message, note) if x)
        if solved != c:  # nu = 0.5: Hertz for every stick ratio, k undetermined
            extra.update(stick_ratio=c, k=np.inf if c == 1.0 else 0.0,
                         message=decoupled_message(geometry))
        rec = dataclasses.replace(rec, **extra)
        if estimate:
            rec = _embedded_estimate(geometry, method, n, rec, coarse, samples, max_error,
                                     cache)
        yield rec


def _solve_from(geometry: Contact, method: str, n: int, c: float, guess: float | None,
                normal, shear, cache: StickBlocks, with_coarse: bool,
                ops: tuple | None = None, level_offsets: tuple | None = None
                ) -> tuple[Any, dict[int, DiscreteSolution], tuple | None]:
    """One case from a starting k (None: as alone): (solution, nested coarse solves, operators).

    With ``with_coarse`` (default method, 0 < c < 1), the nested n/2 and n/4
    solves come first; without a guess their Richardson extrapolation starts
    the fine Newton. A fine Newton that fails from the guess starts again from
    the n/2 solution, or from the solver's own warm start. ``level_offsets``:
    the extrapolated method's coarse levels relative to its k, from the
    previous case of a sweep (its guesses for the levels).
    """
    coarse: dict[int, DiscreteSolution] = {}
    if with_coarse and 0.0 < c < 1.0:
        ops = ops or _fine_operators(geometry, n, c, normal, shear, cache)
        coarse = _coarse_solves(geometry, n, c, guess, ops, cache)
        half, quarter = coarse.get(n // 2), coarse.get(n // 4)
        if half is not None and half.converged and guess is None:
            guess = half.oriented_k  # (a continuation guess is closer: ~1e-6 in a sweep)
            if quarter is not None and quarter.converged:
                guess = half.oriented_k + (half.oriented_k - quarter.oriented_k) / 3.0  # n^-2
    d = solve_one(geometry, method, n, c, normal, shear, guess, ops=ops, cache=cache,
                  level_offsets=level_offsets if guess is not None else None)
    if method in NODAL_METHODS and not d.converged and guess is not None and 0.0 < c < 1.0:
        half = coarse.get(n // 2)
        retry = half.oriented_k if half is not None and half.converged else None
        d = solve_one(geometry, method, n, c, normal, shear, retry, ops=ops, cache=cache)
    return d, coarse, ops


def _suspect(d, guess: float | None) -> bool:
    """A partial-slip root not to trust from a continuation guess.

    Not converged; inconsistent at the nodes (:meth:`DiscreteSolution.node_flags`);
    or, with ``guess``, more than 50 % away from it (a sweep's guesses are
    within about 1e-6, and a few per cent where its points are far apart; both
    relative to sign(beta), :attr:`DiscreteSolution.oriented_k`).
    """
    if not isinstance(d, DiscreteSolution) or not 0.0 < d.stick_ratio < 1.0:
        return False
    if not d.converged or not np.isfinite(d.k):
        return True
    if guess is not None and abs(d.oriented_k / guess - 1.0) > 0.5:
        return True
    return not d.node_flags()["consistent"]


def estimate_case(geometry: Contact, method: str, n: int, rec: CaseRecord, *,
                  samples: bool = True, max_error: float = validate.DEFAULT_MAX_ERROR,
                  solution: SelfSimilarSolution | None = None) -> CaseRecord:
    """The error estimates and ``resolved`` of a case record solved outside :func:`iter_cases`.

    Used for the inverse problem (k given): the nested coarse solves are made
    at the record's stick ratio; an extrapolated ``solution`` brings its own
    estimates (and load). Returns a new record (records are frozen).
    """
    if isinstance(solution, extrapolated_method.ExtrapolatedSolution):
        rec = dataclasses.replace(rec, **_extrapolated_estimates(geometry, solution, rec,
                                                                 samples))
    c = _solved_ratio(geometry, float(rec.stick_ratio))
    cache = StickBlocks()
    coarse = {}
    if validate.method_of(method).nested_estimate and 0.0 < c < 1.0:
        # the coarse Newton starts on the root's side: k relative to sign(beta)
        d = solution if isinstance(solution, DiscreteSolution) else _rebuild(geometry, rec)
        coarse = _coarse_solves(geometry, n, c, d.oriented_k, cache=cache)
    return _embedded_estimate(geometry, method, n, rec, coarse, samples, max_error, cache)


def _fine_operators(geometry: Contact, n: int, c: float, normal, shear,
                    cache: StickBlocks | None = None) -> tuple:
    """Collocation operators (normal, shear) of a partial-slip case on its mesh n."""
    mesh = graded_mesh(n, c, store=_meshes(cache))
    pw = _lookup(normal, validate.DEFAULT_METHOD, c, mesh.nodes)
    qw = _lookup(shear, validate.DEFAULT_METHOD, c, mesh.nodes)
    if pw is None and qw is None:
        return nodal_operators(geometry, mesh, cache=cache)
    if pw is None:
        pw = nodal_operator_part(geometry, mesh, "normal", cache=cache)
    if qw is None:
        qw = nodal_operator_part(geometry, mesh, "shear", cache=cache)
    return pw, qw


def _coarse_solves(geometry: Contact, n: int, c: float, guess: float | None,
                   ops: tuple | None = None,
                   cache: StickBlocks | None = None) -> dict[int, DiscreteSolution]:
    """The same case on the nested meshes n/2 and n/4 (those with at least 8 elements).

    With the fine operators ``ops`` given, the coarse ones are restricted
    from them (:func:`~contactlib.discretization.operators.restrict_nested`) where the meshes are nested, which costs
    no kernel evaluations.
    """
    out: dict[int, DiscreteSolution] = {}
    mesh = graded_mesh(n, c, store=_meshes(cache))
    for m in (n // 2, n // 4):
        if m < 8:
            continue
        sub = graded_mesh(m, c, store=_meshes(cache))
        nested = (ops is not None and 2 * sub.n == mesh.n
                  and 2 * sub.stick_index == mesh.stick_index
                  and np.allclose(mesh.nodes[::2], sub.nodes, rtol=0.0, atol=1e-13))
        odd = None
        if nested:
            ops, odd = restrict_with_slip_samples(ops, mesh)
            mesh = sub
        else:
            ops = None
        d = solve_default(geometry, c, m, k_guess=guess, ops=ops, cache=cache)
        if odd is not None:  # u, du/dx inside each coarse slip element, from the fine operators
            d.interior_samples = slip_zone_samples(odd, d.p, d.phi)
        out[m] = d
        if d.converged and d.k > 0.0:
            guess = d.oriented_k  # (negative when the slip runs against sign(beta))
    return out


def _extrapolated_estimates(geometry: Contact, d, rec: CaseRecord,
                            samples: bool) -> dict[str, float]:
    """The extrapolated method's load and estimates; its work estimate from the levels."""
    out = d.estimates()
    if samples and rec.slip_x is not None and rec.slip_x.size and len(d.level_work) == len(d.levels) - 1:
        out["work_error_estimate"] = extrapolated_method.work_error(
            tuple(d.level_work) + (_record_work(geometry, rec),))
    return out


def _relative(values: Sequence[float], edge: bool | None = None) -> float:
    """Relative error estimate of the last of nested (v(n/4), v(n/2), v(n)) or (v(n/2), v(n)).

    Three levels: :func:`contactlib.accuracy.estimate` (Richardson with the
    observed order where the differences shrink at least twofold; the larger
    difference where they do not, which bounds an error that is not yet
    converging or changes sign). Two levels (n = 16 ... 31): the difference
    itself, three times the error of v(n) once the n^-2 convergence is
    asymptotic (for k on the measured bodies :func:`_embedded_estimate` floors it by
    the measured n^-2 model: two levels can agree by chance). Measured coverage:
    docs/accuracy.md, tests/test_error_estimate.py, tests/test_estimate_collapse.py.
    ``edge`` (a coated body's three levels, else None): whether the coarsest level resolves
    the coating's edge zone, for :func:`contactlib.estimates.coated_estimate`.
    """
    full = values[-1]
    if not np.all(np.isfinite(values)):
        return math.inf
    if len(values) == 3 and edge is not None:
        return coated_estimate(*values, edge)
    if len(values) == 3:
        if full == 0.0:
            return 0.0 if values[0] == values[1] == 0.0 else math.inf
        return estimate(*values)[0]
    return abs(values[0] - full) / abs(full) if full != 0.0 else (
        0.0 if values[0] == 0.0 else math.inf)


def _embedded_estimate(geometry: Contact, method: str, n: int, rec: CaseRecord,
                       coarse: dict[int, DiscreteSolution], samples: bool,
                       max_error: float, cache: StickBlocks | None = None) -> CaseRecord:
    """The record with ``error_estimate``, ``load_error_estimate``, ``work_error_estimate``,
    ``resolved`` and ``max_error``.

    Default method: k, the load and (with samples) the work of the same case
    on the nested meshes n/4 and n/2 give the estimates (:func:`_relative`);
    where Newton stopped on the round-off floor, twice its last step is added
    to the k estimate, and the quadrature-noise bound
    (:func:`contactlib.accuracy.default_noise`: from n = 512, and at every n where the
    axis or edge difference rows apply). A mesh with elements below
    :data:`QUADRATURE_FLOOR_H` is never resolved (a limit of the method; the message says so).
    Frictionless, full adhesion and nu = 0.5 are exact in k (estimate 0) and
    carry the estimate of the load. The paper's scheme is measured against
    the default method at n = 64 (its own k does not converge to the
    physical value).
    """
    c = float(rec.stick_ratio)
    solved = _solved_ratio(geometry, c)
    out: dict[str, Any] = {}  # the fields this adds (the record is frozen)
    notes = []
    limit = False  # below the quadrature floor: refining does not help
    # k exact (0 or inf: frictionless, full adhesion, decoupled): the answer is the load
    # (and the work, where there is one), which ``resolved`` judges instead of k
    exact_k = method in NODAL_METHODS and not 0.0 < solved < 1.0
    if (exact_k and validate.method_of(method).own_estimate
            and not np.isfinite(rec.load_error_estimate)):
        method_for_levels = validate.DEFAULT_METHOD  # (the extrapolated method solved it so)
    else:
        method_for_levels = method
    if rec.elements is not None or validate.method_of(method_for_levels).own_estimate:
        # a tolerance scene estimated k itself, or the extrapolated method did
        if validate.method_of(method).own_estimate:
            limit = _below_floor(rec, solved, notes)
    elif method not in NODAL_METHODS:
        ref = solve_default(geometry, solved, 64, cache=cache)
        k_ref, load_ref = ref.k, ref.load()
        if not rec.converged:  # no value, so no error of it
            out["error_estimate"] = math.nan
        elif 0.0 < solved < 1.0 and not k_ref > 0.0:
            # no measure: the reference found no solution here (its estimate was 0, so a
            # layer's root with k < 0 where the slip does not oppose the shear was resolved)
            out["error_estimate"] = math.inf
            notes.append("no error estimate: the default method at n = 64 found no solution "
                         f"here ({ref.message})")
        elif 0.0 < solved < 1.0:
            out["error_estimate"] = abs(rec.k - k_ref) / k_ref
            if not rec.k > 0.0:
                notes.append(f"the printed scheme's root has k = {rec.k:.4g}: its slip runs "
                             f"against sign(beta), the default method's k is {k_ref:.4g}")
        else:
            out["error_estimate"] = 0.0
        out["load_error_estimate"] = abs(rec.load - load_ref) / load_ref
        if samples:
            out["work_error_estimate"] = _relative([_work(geometry, ref), _record_work(
                geometry, rec)]) if 0.0 < solved < 1.0 else 0.0
        notes.append("the paper's scheme as printed: error measured against the default "
                     "method at n = 64")
    else:
        levels = sorted(coarse)  # n/4, n/2
        sols = [coarse[m] for m in levels]
        if bool(rec.converged) and 0.0 < solved < 1.0:
            # a coarse Newton that started from the continuation guess and failed
            # starts again from the fine k, within the discretization error of its root
            sols = [s if s.converged else solve_default(geometry, solved, m,
                                                        k_guess=float(rec.k), cache=cache)
                    for m, s in zip(levels, sols)]
        if not 0.0 < solved < 1.0:  # k exact (0 or inf); the load still has an error
            sols = [solve_default(geometry, solved, m, cache=cache)
                    for m in (n // 4, n // 2) if m >= 8]
        # a coated body's levels: does the coarsest resolve the coating's edge zone?
        edge = (edge_zone_resolved(sols[0].mesh.nodes, geometry.body.thickness)
                if geometry.body.base == "elastic" and len(sols) == 2 else None)
        if not 0.0 < solved < 1.0:
            out["error_estimate"] = 0.0
        elif not sols:
            out["error_estimate"] = math.nan
        elif not all(s.converged for s in sols):
            out["error_estimate"] = math.inf
            bad = ", ".join(str(m) for m, s in zip(levels, sols) if not s.converged)
            notes.append(f"no error estimate: the same case on the nested mesh n = {bad} "
                         "did not converge")
        else:
            out["error_estimate"] = _relative([s.k for s in sols] + [float(rec.k)], edge)
            if len(sols) == 1 and planned_body(geometry):
                # two levels (n = 16 ... 31): no observed order to check, and where the
                # error is not monotone in n the levels n/2 and n agree by chance (cylinder,
                # c/a = 0.06, n = 16: error 1.2e-3, |k8 - k16| 6.6e-5). Floor: the measured
                # n^-2 model (accuracy.predicted_error) times the planner's SAFETY, 0.48 of
                # which the error reached at most (c/a = 0.5; both slabs, c/a = 0.02 ...
                # 0.9; python benchmarks/report_estimate_collapse.py)
                out["error_estimate"] = max(float(out["error_estimate"]), SAFETY * predicted_error(
                    geometry.indenter.name, solved, n))
        loads = [s.load() for s in sols] + [float(rec.load)]
        out["load_error_estimate"] = _relative(loads, edge) if len(loads) > 1 else math.nan
        if samples and sols and rec.slip_x.size and 0.0 < solved < 1.0:
            out["work_error_estimate"] = _relative([_work(geometry, s) for s in sols]
                                                   + [_record_work(geometry, rec)], edge)
        elif samples:  # no slip (full adhesion) or no shear (frictionless): no work
            out["work_error_estimate"] = 0.0
        limit = _below_floor(rec, solved, notes)
        # Newton stopped on the round-off floor: its iterates scatter by about the
        # last step, twice which is added to the discretization estimate; from n = 512
        # (at the extremes at every n) the kernels' quadrature noise, which the nested
        # levels do not see
        out["error_estimate"] = float(out["error_estimate"]) + 2.0 * float(
            rec.round_off) + default_noise(geometry, solved, n)
    est, what = float(out.get("error_estimate", rec.error_estimate)), "k"
    if exact_k:  # the load's estimate, and the work's where there is work (not NaN)
        est, what = _exact_k_estimate(out, rec), "load"
    good = bool(rec.converged) and np.isfinite(est) and est <= max_error and not limit
    out["resolved"] = good
    out["max_error"] = float(max_error)
    if not good and bool(rec.converged) and np.isfinite(est) and est > max_error:
        need = (resolving_n(n, est, max_error)
                if (validate.method_of(method).nested_estimate or exact_k) and not limit else
                extrapolated_method.resolving_n(n, est, max_error, MAX_N)
                if validate.method_of(method).own_estimate and not limit else None)
        hint = (f"n = {need} should resolve it" if need is not None else
                "no n resolves it" if limit else
                f"no supported n (up to {MAX_N}) resolves it" if method in NODAL_METHODS else
                "use the default method")
        notes.append(f"estimated {what} error {est:.1e} exceeds max_error {max_error:g}"
                     f"{' (k is exact here)' if exact_k else ''}: {hint}")
    if notes:
        out["message"] = "; ".join(x for x in [rec.message] + notes if x)
    return dataclasses.replace(rec, **out)


def _exact_k_estimate(out: dict[str, Any], rec: CaseRecord) -> float:
    """Where k is exact (c/a = 0 or 1, or decoupled), the estimate ``resolved`` judges: the
    larger of the load's and the work's (the work's where it is estimated, not NaN); NaN
    when the load has no estimate."""
    load = float(out.get("load_error_estimate", rec.load_error_estimate))
    work = float(out.get("work_error_estimate", rec.work_error_estimate))
    if not np.isfinite(load) and not math.isinf(load):
        return math.nan
    return max(load, work) if np.isfinite(work) or math.isinf(work) else load


def _below_floor(rec: CaseRecord, solved: float, notes: list[str]) -> bool:
    """Whether the mesh has elements below :data:`QUADRATURE_FLOOR_H` (then a note)."""
    h_min = float(np.min(np.diff(np.asarray(rec.nodes, dtype=float))))
    floor = QUADRATURE_FLOOR_H["stick" if solved < 0.5 else "annulus"]
    limit = 0.0 < solved < 1.0 and h_min < floor
    if limit:
        notes.append(f"not resolved: the mesh needs elements of {h_min:.0e} a next to "
                     f"c; below about {floor:g} a the kernels' quadrature "
                     "error (about 1e-11) is amplified in the stick-edge condition, k is "
                     "uncertain at the 1e-4 ... 1e-3 level and refining makes it worse, "
                     "so no n resolves it (a limit of the method)")
    return limit


def _work(geometry: Contact, d: DiscreteSolution) -> float:
    """Frictional work of a discrete solution from its Simpson slip samples."""
    xs, ws, q, sl = d.slip_samples()
    return float(energy.frictional_work(xs, ws, q, sl, geometry.work_factor,
                                        geometry.work_weight_power))


def _record_work(geometry: Contact, rec: CaseRecord) -> float:
    """Frictional work of a case record from its stored slip samples."""
    return float(energy.frictional_work(rec.slip_x, rec.slip_w, rec.slip_q,
                                        rec.slip_s, geometry.work_factor,
                                        geometry.work_weight_power))


def _continuation_guess(geometry: Contact, c: float,
                        known: Sequence[tuple[float, float]]) -> float | None:
    """Newton's starting k for c/a from the cases already solved in this sweep.

    The ratio of k to the uncoupled closed form varies slowly with c/a
    (1.04 ... 1.12 at nu = 0.3 for c/a up to 0.98), so it is interpolated
    (or extrapolated) from the three (or two) solved cases nearest in c/a
    that lie within 0.25 of it: quadratically, which puts a 50-point sweep's guesses
    within about 1e-6 and Newton converges in one or two steps. None (the
    solver's own warm start) when fewer than two are known, or when the
    ratio comes out beyond half the smallest or twice the largest known one.

    The ratios and the guess are relative to sign(beta)
    (:attr:`DiscreteSolution.oriented_k`): negative on a layer whose slip runs
    outward, so that Newton starts on the root's side of zero (from the
    reported |k| it crossed zero first: 4 iterations instead of 2 at n = 256,
    sphere on a smooth layer, a/h = 20, nu = 0.3; 9 instead of 2 at nu = 0.45).
    None where the known cases lie on both sides.
    """
    if not 0.0 < c < 1.0 or len(known) < 2:
        return None
    near = [t for t in sorted(known, key=lambda t: abs(t[0] - c))[:3] if abs(t[0] - c) <= 0.25]
    cs = np.array([t[0] for t in near])
    rs = np.array([t[1] for t in near])
    if cs.size < 2 or np.unique(cs).size < cs.size:
        return None  # (a sweep with steps over 0.125 in c/a: linear from the two nearest)
    # Lagrange interpolation (quadratic with three neighbours, else linear)
    ratio = 0.0
    for i in range(cs.size):
        others = np.delete(cs, i)
        ratio += rs[i] * float(np.prod((c - others) / (cs[i] - others)))
    side = 1.0 if np.all(rs > 0.0) else -1.0 if np.all(rs < 0.0) else 0.0
    if not (side and 0.5 * np.min(side * rs) <= side * ratio <= 2.0 * np.max(side * rs)):
        return None  # an extrapolation far beyond the points (quadratic from 1e-8, 1e-6,
        # 1e-4 to 1e-2 amplifies their differences 1e4 times): not a guess
    k_unc = float(geometry.uncoupled_friction(c))
    guess = ratio * k_unc
    return guess if np.isfinite(guess) and side * guess > 0.0 else None


def _to_tolerance(geometry: Contact, method: str, n: int, c: float, d: DiscreteSolution,
                  tolerance: float,
                  cache: StickBlocks | None = None
                  ) -> tuple[DiscreteSolution, dict[str, Any], str]:
    """Refine one case until its a-posteriori k error meets the tolerance.

    Returns the solution, the record fields ``elements`` and
    ``error_estimate``, and a note for the message (empty when none).
    """
    from . import accuracy

    if method not in NODAL_METHODS:
        raise ValueError("a tolerance needs the default or the extrapolated method (the "
                         "paper's scheme does not converge to the physical k)")
    if not 0.0 < c < 1.0:  # frictionless, full adhesion, or nu = 0.5: k is exact, and
        # the tolerance applies to the load (both methods solve it as the default method)
        return _load_to_tolerance(geometry, n, c, d, tolerance, cache)
    if validate.method_of(method).own_estimate:  # n doubled while it falls short
        while d.error_estimate > tolerance and 2 * n <= MAX_N and d.converged:
            finer = extrapolated_method.solve_extrapolated(geometry, c, 2 * n,
                                                           k_guess=d.oriented_k,
                                                           cache=cache, work=False)
            if finer.error_estimate >= d.error_estimate:  # the quadrature noise grows
                break
            d, n = finer, 2 * n
        msg = ("" if d.error_estimate <= tolerance else
               f"tolerance {tolerance:g} not met: estimated k error {d.error_estimate:.2g} "
               f"at n = {n}")
        return d, {"elements": n, "error_estimate": float(d.error_estimate)}, msg
    sols = {n: d}

    def solve_k(m: int) -> float:
        sols[m] = solve_default(geometry, c, m, cache=cache)
        return sols[m].k

    used, est, msg = accuracy.solve_to_tolerance(
        solve_k, n, tolerance, known={n: d.k},
        noise=lambda m: default_noise(geometry, c, m))
    return sols[used], {"elements": used, "error_estimate": est}, msg


def _load_to_tolerance(geometry: Contact, n: int, c: float, d: DiscreteSolution,
                       tolerance: float, cache: StickBlocks | None = None
                       ) -> tuple[DiscreteSolution, dict[str, Any], str]:
    """Where k is exact (c/a = 0 or 1, decoupled): refine n (doubling) until the load's
    estimate from n/4, n/2, n (:func:`_relative`) meets the tolerance; stop where the n^-2
    convergence needs an n beyond :data:`MAX_N` (:func:`~contactlib.accuracy.resolving_n`),
    with a message. The work is 0 there (no shear, or no slip)."""
    loads = {n: d.load()}

    def load_at(m: int) -> float:
        if m not in loads:
            loads[m] = solve_default(geometry, c, m, cache=cache).load()
        return loads[m]

    while True:
        est = _relative([load_at(m) for m in (n // 4, n // 2, n)])
        if est <= tolerance:
            msg = ""
            break
        need = resolving_n(n, est, tolerance)
        if need is None or 2 * n > MAX_N:
            msg = (f"tolerance {tolerance:g} not met: k is exact here, and the estimated "
                   f"load error is {est:.2g} at n = {n}; the load's n^-2 convergence needs "
                   f"{'about n = ' + str(need) if need else 'an n'} beyond the largest "
                   f"supported n = {MAX_N}" if need is None or need > MAX_N else
                   f"tolerance {tolerance:g} not met: estimated load error {est:.2g} at "
                   f"the largest n = {n}")
            break
        n *= 2
        d = solve_default(geometry, c, n, cache=cache)
        loads[n] = d.load()
    return d, {"elements": n, "error_estimate": 0.0, "load_error_estimate": float(est),
               "work_error_estimate": 0.0}, msg


# ----------------------------------------------------------------------------- post-processing
def check_case(rec: CaseRecord) -> dict[str, Any]:
    """Consistency flags of a case (see :mod:`contactlib.checks`)."""
    return checks.record_flags(rec)


def work_case(geometry: Contact, rec: CaseRecord) -> float:
    """Frictional work of the loading half-cycle (docs/conventions.md scaling; 0 without slip)."""
    return energy.record_work(rec, geometry.work_factor, geometry.work_weight_power)


def profiles(geometry: Contact, rec: CaseRecord, xi: np.ndarray, *, stresses: bool = True,
             displacements: bool = True) -> dict[str, np.ndarray]:
    """Profiles on ``xi`` in the docs/conventions.md scalings (p/p0, q/p0, u R/a^2).

    The tractions are interpolated from the nodal values; the displacement
    needs the kernels at every ``xi`` (the costly part).
    """
    d = _rebuild(geometry, rec)
    out: dict[str, np.ndarray] = {}
    if stresses:
        out["pressure"] = d.pressure(xi) / geometry.p0
        out["shear"] = d.shear(xi) / geometry.p0
    if displacements:
        out["tangential_displacement"] = d.radial_displacement(xi)
    return out


def nodal_tractions(geometry: Contact, rec: CaseRecord) -> dict[str, np.ndarray]:
    """The solve's own piecewise-linear tractions at its nodes (default-method records).

    ``nodes`` (r/a or x/a), ``nodal_pressure`` and ``nodal_shear`` (p/p0, q/p0): what the
    subsurface stresses integrate, so that their field converges with n instead of
    stopping at the interpolation of the 201 output points. Empty for the paper's
    step tractions.
    """
    if rec.kind != DiscreteSolution.kind or rec.nodes is None:
        return {}
    nodes = np.asarray(rec.nodes, dtype=float)
    return {"nodes": nodes, "nodal_pressure": np.asarray(rec.p, dtype=float) / geometry.p0,
            "nodal_shear": geometry.shear_shape(nodes) * np.asarray(rec.traction, dtype=float)
            / geometry.p0}


def to_solution(geometry: Contact, method: str, n: int, rec: CaseRecord, xi: np.ndarray, *,
                flags: dict[str, Any] | None = None, work: float = float("nan"),
                profile: dict[str, np.ndarray] | None = None,
                message: str = "") -> Solution:
    """Assemble a :class:`Solution`; profiles not computed are left as None.

    A profile may be given as a zero-argument callable
    (``tangential_displacement``: the kernels at every ``xi``); the solution calls it when
    the profile is first read.
    """
    profile = profile or {}
    fl = flags or {}
    reversal = ""
    if method in NODAL_METHODS and rec.converged and not fl.get("slip_direction_ok", True):
        # (the paper's scheme is inconsistent on its own: no physical reading there)
        reversal = ("the slip runs along the shear somewhere in the slip zone: its direction "
                    "changes there, which one self-similar stick zone cannot hold; solve it "
                    "with history")
    # a converged root that breaks the single stick zone's conditions is no answer,
    # however well resolved its discretization is (strong coupling next to full stick)
    inconsistent = (method in NODAL_METHODS and bool(rec.converged)
                    and not fl.get("consistent", True))
    if inconsistent and not fl.get("stick_admissible", True):
        reversal = "; ".join(x for x in (reversal, (
            f"the stick zone needs |q| > k p somewhere (violation "
            f"{fl.get('stick_violation', float('nan')):.1e}): either one self-similar stick "
            "zone cannot hold at this c/a or n is too coarse to show that it does (a larger "
            "n tells which), so k is not resolved"
            + ("; next to full stick, no friction reaches a c/a beyond the largest stick "
               "ratio c* < 1 of this coupling (docs/accuracy.md, 'Near full stick')"
               if rec.stick_ratio > 0.5 else ""))) if x)
    msg = "; ".join(x for x in (message, rec.message, reversal) if x)
    return Solution(
        geometry=geometry.indenter.name, nu=geometry.body.nu, method=method, n=n,
        slab_ratio=geometry.body.slab_ratio, stick_ratio=float(rec.stick_ratio),
        friction_coefficient=float(rec.k), xi=xi,
        pressure=profile.get("pressure"), shear=profile.get("shear"),
        tangential_displacement=profile.get("tangential_displacement"),
        load_ratio=float(rec.load) / geometry.hertz_load, frictional_work=float(work),
        slip_direction_ok=bool(fl.get("slip_direction_ok", True)),
        stick_admissible=bool(fl.get("stick_admissible", True)),
        consistent=bool(fl.get("consistent", True)),
        converged=bool(rec.converged), residual_norm=float(rec.residual_norm),
        iterations=int(rec.iterations), message=msg,
        error_estimate=float(rec.error_estimate),
        load_error_estimate=float(rec.load_error_estimate),
        work_error_estimate=(float(rec.work_error_estimate)
                             if np.isfinite(work) else math.nan),
        resolved=bool(rec.resolved) and not inconsistent,
        max_error=float(rec.max_error),
        extra={"stick_violation": fl.get("stick_violation", float("nan")),
               "slip_violation": fl.get("slip_violation", float("nan")),
               "indentation": float(rec.delta)},
        indenter_modulus_ratio=float(geometry.indenter.modulus_ratio),
        indenter_poisson_ratio=float(geometry.indenter_poisson_ratio),
        dundurs_beta=float(geometry.beta), base=geometry.body.base,
        profile=geometry.profile.name, exponent=float(geometry.profile.exponent),
        model=geometry)
