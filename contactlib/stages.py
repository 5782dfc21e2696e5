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
  each: a flat ``dict`` of the nodal solution, its status and, when asked,
  the samples the checks and the energy need (slip rate at Gauss points of
  the slip zone, tractions at stick-zone points).
* :func:`check_case`, :func:`work_case`, :func:`profiles` -- the consistency
  flags, the frictional work, and the profiles on the output grid.
* :func:`to_solution` -- a :class:`~contactlib.result.Solution` from the pieces.

Units inside: E* = a = R = 1 (see :mod:`contactlib.default_method`).
"""

from __future__ import annotations

from typing import Any, Callable, Iterator, Sequence

import numpy as np

from . import checks, energy, validate
from .default_method import DiscreteSolution, nodal_operator_part, solve_default
from .elements import Mesh, graded_mesh, uniform_mesh
from .model import Contact
from .paper_method import PaperSolution, collocation_points, ring_operator, solve_paper
from .result import Solution

__all__ = ["PARTS", "OUTPUTS", "parts_needed", "influence", "solve_cases", "iter_cases", "check_case",
           "work_case", "profiles", "to_solution", "decoupled_message"]

PARTS = ("normal", "shear")
OUTPUTS = ("k_curve", "stresses", "displacements", "energy")

Record = dict[str, Any]


def decoupled_message() -> str:
    """The note attached to every nu = 0.5 case."""
    return ("nu = 0.5: the normal and tangential problems decouple; no shear arises (q = 0) "
            "and every stick ratio is consistent with any k >= 0")


def _decoupled(geometry: Contact) -> bool:
    return geometry.decoupled


def parts_needed(geometry: Contact, stick_ratios: Sequence[float]) -> tuple[str, ...]:
    """The influence parts a set of cases needs: no shear when frictionless or nu = 0.5."""
    if _decoupled(geometry) or all(float(c) == 0.0 for c in stick_ratios):
        return ("normal",)
    return PARTS


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
        Default method: ``stick_ratios`` (K,), ``nodes`` (K, n+1) and ``ops``
        (K, 3, n+1, n+1), the w, u, du/dx at the nodes of nodal tractions.
        Paper methods: ``nodes`` (n+1,) and ``ops`` (3, n+2, n) at
        :func:`~contactlib.paper_method.collocation_points`. Memory:
        24 (n+1)^2 bytes a mesh and part (1.6 MB at n = 256, 25 MB at 1024).
    """
    if part not in PARTS:
        raise ValueError(f"part must be one of {', '.join(PARTS)}, got {part!r}")
    if method == "default":
        cs = np.unique([_solved_ratio(geometry, c) for c in stick_ratios])
        meshes = [graded_mesh(n, c) for c in cs]
        ops = np.stack([nodal_operator_part(geometry, mesh, part) for mesh in meshes])
        return {"stick_ratios": cs, "nodes": np.stack([mesh.nodes for mesh in meshes]),
                "ops": ops}
    r = uniform_mesh(n, 0).nodes
    return {"nodes": r, "ops": ring_operator(geometry, r, collocation_points(n), part)}


def _lookup(table: dict[str, np.ndarray] | None, method: str, c: float,
            nodes: np.ndarray) -> np.ndarray | None:
    """The operator of one case from an influence set (None when not given)."""
    if table is None:
        return None
    if method != "default":
        if not np.array_equal(table["nodes"], nodes):
            raise ValueError("influence matrices were built for another mesh")
        return table["ops"]
    hit = np.flatnonzero(table["stick_ratios"] == c)
    if hit.size == 0 or not np.array_equal(table["nodes"][hit[0]], nodes):
        raise ValueError(f"influence matrices hold no mesh for stick ratio {c!r}")
    return table["ops"][hit[0]]


# ----------------------------------------------------------------------------- solve
def _discrete(geometry: Contact, method: str, n: int, c: float, normal, shear,
              k_guess: float | None = None):
    if method == "default":
        mesh = graded_mesh(n, c)
        pw = _lookup(normal, method, c, mesh.nodes)
        qw = _lookup(shear, method, c, mesh.nodes) if 0.0 < c else None
        ops = None if pw is None else (pw, qw)
        return solve_default(geometry, c, n, ops=ops, k_guess=k_guess)
    m = validate.paper_multiple(c, n)
    r = uniform_mesh(n, m).nodes
    pr = _lookup(normal, method, c, r)
    sh = _lookup(shear, method, c, r) if m > 0 else None
    ops = None if pr is None else (pr, sh)
    coulomb = "coefficient" if method == "paper-literal" else "resultant"
    return solve_paper(geometry, m, n, coulomb=coulomb, ops=ops)


def _record(geometry: Contact, d: DiscreteSolution | PaperSolution, samples: bool) -> Record:
    nodes, m = d.mesh.nodes, d.mesh.stick_index
    paper = isinstance(d, PaperSolution)
    rec: Record = {
        "kind": "paper" if paper else "default",
        "stick_ratio": float(nodes[m]), "nodes": np.asarray(nodes, dtype=float),
        "stick_index": int(m), "p": np.asarray(d.p, dtype=float),
        "traction": np.asarray(d.qc if paper else d.phi, dtype=float),
        "k": float(d.k), "delta": float(getattr(d, "delta", np.nan)),
        "converged": bool(d.converged), "residual_norm": float(d.residual_norm),
        "iterations": int(d.iterations), "message": str(d.message or ""),
        "load": float(d.load() if paper else geometry.load(nodes, d.p)),
    }
    if not paper:
        rec["nodal_u"] = np.asarray(d.nodal_u, dtype=float)
        rec["nodal_du"] = np.asarray(d.nodal_du, dtype=float)
    if samples:
        if 0 < m < d.mesh.n:
            xs, ws, q_slip, s_slip = d.slip_samples()
        else:
            xs = ws = q_slip = s_slip = np.empty(0)
        # stick-zone points: element midpoints (and nodes for continuous tractions)
        mids = 0.5 * (nodes[:m] + nodes[1:m + 1])
        pts = mids if paper else np.concatenate([nodes[1:m], mids])
        rec.update(slip_x=xs, slip_w=ws, slip_q=q_slip, slip_s=s_slip,
                   stick_q=d.shear(pts), stick_p=d.pressure(pts))
        if not np.all(np.isfinite(s_slip)):  # never a silent NaN in a converged case
            rec["converged"] = False
            rec["message"] = "; ".join(x for x in (rec["message"], (
                "the slip-rate samples hit a kernel singularity (a slip zone narrower than "
                "the quadrature resolves); flags and work are not reliable")) if x)
    return rec


def _rebuild(geometry: Contact, rec: Record) -> DiscreteSolution | PaperSolution:
    mesh = Mesh(np.asarray(rec["nodes"], dtype=float), int(rec["stick_index"]))
    common = dict(k=float(rec["k"]), converged=bool(rec["converged"]),
                  residual_norm=float(rec["residual_norm"]),
                  iterations=int(rec["iterations"]), message=str(rec["message"]))
    if rec["kind"] == "paper":
        return PaperSolution(geometry, mesh, rec["p"], rec["traction"], **common)
    return DiscreteSolution(geometry, mesh, rec["p"], rec["traction"], float(rec["delta"]),
                            nodal_u=rec.get("nodal_u"), nodal_du=rec.get("nodal_du"), **common)


def solve_cases(geometry: Contact, method: str, n: int, stick_ratios: Sequence[float], *,
                normal: dict[str, np.ndarray] | None = None,
                shear: dict[str, np.ndarray] | None = None, samples: bool = True,
                tolerance: float | None = None,
                progress: Callable[[int, int], None] | None = None) -> list[Record]:
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

    Returns
    -------
    list of dict
        Case records (see the module docstring). A case that fails to
        converge is kept, with ``converged`` False and a message.
    """
    out = []
    for i, rec in enumerate(iter_cases(geometry, method, n, stick_ratios, normal=normal,
                                       shear=shear, samples=samples, tolerance=tolerance)):
        out.append(rec)
        if progress is not None:
            progress(i + 1, len(stick_ratios))
    return out


def iter_cases(geometry: Contact, method: str, n: int, stick_ratios: Sequence[float], *,
               normal: dict[str, np.ndarray] | None = None,
               shear: dict[str, np.ndarray] | None = None, samples: bool = True,
               tolerance: float | None = None) -> Iterator[Record]:
    """The case records of :func:`solve_cases`, one at a time, in the given order.

    Successive default-method cases continue from each other: Newton's
    starting k comes from the cases already solved (:func:`_continuation_guess`).
    """
    known: list[tuple[float, float]] = []  # (c, k / k_uncoupled) of converged cases
    for c in stick_ratios:
        c = float(c)
        solved = _solved_ratio(geometry, c)
        guess = _continuation_guess(geometry, solved, known) if method == "default" else None
        d = _discrete(geometry, method, n, solved, normal, shear, guess)
        if method == "default" and d.converged and 0.0 < solved < 1.0 and d.k > 0.0:
            known.append((solved, d.k / float(geometry.uncoupled_friction(solved))))
        extra = {}
        if tolerance is not None:
            d, extra = _to_tolerance(geometry, method, n, solved, d, tolerance)
        rec = _record(geometry, d, samples)
        rec.update(extra)
        if extra.get("tolerance_message"):
            rec["message"] = "; ".join(x for x in (rec["message"], extra["tolerance_message"])
                                       if x)
        if solved != c:  # nu = 0.5: Hertz for every stick ratio, k undetermined
            rec["stick_ratio"] = c
            rec["k"] = np.inf if c == 1.0 else 0.0
            rec["message"] = decoupled_message()
        yield rec


def _continuation_guess(geometry: Contact, c: float,
                        known: Sequence[tuple[float, float]]) -> float | None:
    """Newton's starting k for c/a from the cases already solved in this sweep.

    The ratio of k to the uncoupled closed form varies slowly with c/a
    (1.04 ... 1.12 at nu = 0.3 for c/a up to 0.98), so it is interpolated
    (or extrapolated) from the three (or two) solved cases nearest in c/a,
    within 0.25 of it: quadratically, which puts a 50-point sweep's guesses
    within about 1e-6 and Newton converges in one or two steps. None (the
    solver's own warm start) when fewer than two are known.
    """
    if not 0.0 < c < 1.0 or len(known) < 2:
        return None
    near = sorted(known, key=lambda t: abs(t[0] - c))[:3]
    cs = np.array([t[0] for t in near])
    rs = np.array([t[1] for t in near])
    if np.unique(cs).size < cs.size or np.max(np.abs(cs - c)) > 0.25:
        return None
    # Lagrange interpolation (quadratic with three neighbours, else linear)
    ratio = 0.0
    for i in range(cs.size):
        others = np.delete(cs, i)
        ratio += rs[i] * float(np.prod((c - others) / (cs[i] - others)))
    k_unc = float(geometry.uncoupled_friction(c))
    guess = ratio * k_unc
    return guess if np.isfinite(guess) and guess > 0.0 else None


def _to_tolerance(geometry: Contact, method: str, n: int, c: float, d: DiscreteSolution,
                  tolerance: float) -> tuple[DiscreteSolution, Record]:
    """Refine one case until its a-posteriori k error meets the tolerance."""
    from . import accuracy

    if method != "default":
        raise ValueError("a tolerance needs the default method (the paper's scheme does not "
                         "converge to the physical k)")
    if not 0.0 < c < 1.0:  # frictionless, full adhesion, or nu = 0.5: k is exact
        return d, {"elements": n, "error_estimate": 0.0, "tolerance_message": ""}
    sols = {n: d}

    def solve_k(m: int) -> float:
        sols[m] = solve_default(geometry, c, m)
        return sols[m].k

    used, est, msg = accuracy.solve_to_tolerance(solve_k, n, tolerance, known={n: d.k})
    return sols[used], {"elements": used, "error_estimate": est, "tolerance_message": msg}


# ----------------------------------------------------------------------------- post-processing
def check_case(rec: Record) -> dict[str, Any]:
    """Consistency flags of a case (see :mod:`contactlib.checks`)."""
    return checks.flags(rec["stick_q"], rec["stick_p"], rec["k"], rec["slip_q"], rec["slip_s"])


def work_case(geometry: Contact, rec: Record) -> float:
    """Frictional work of the loading half-cycle (docs/conventions.md scaling; 0 without slip)."""
    if rec["slip_x"].size == 0:
        return 0.0  # frictionless (k = 0), full adhesion, or nu = 0.5: nothing slips
    return energy.frictional_work(rec["slip_x"], rec["slip_w"], rec["slip_q"], rec["slip_s"],
                                  geometry.work_factor, geometry.work_weight_power)


def profiles(geometry: Contact, rec: Record, xi: np.ndarray, *, stresses: bool = True,
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


def to_solution(geometry: Contact, method: str, n: int, rec: Record, xi: np.ndarray, *,
                flags: dict[str, Any] | None = None, work: float = float("nan"),
                profile: dict[str, np.ndarray] | None = None,
                message: str = "") -> Solution:
    """Assemble a :class:`Solution`; profiles not computed are left as None."""
    profile = profile or {}
    fl = flags or {}
    msg = "; ".join(x for x in (message, rec["message"]) if x)
    return Solution(
        geometry=geometry.indenter.name, nu=geometry.body.nu, method=method, n=n,
        slab_ratio=geometry.body.slab_ratio, stick_ratio=float(rec["stick_ratio"]),
        friction_coefficient=float(rec["k"]), xi=xi,
        pressure=profile.get("pressure"), shear=profile.get("shear"),
        tangential_displacement=profile.get("tangential_displacement"),
        load_ratio=float(rec["load"]) / geometry.hertz_load, frictional_work=float(work),
        slip_direction_ok=bool(fl.get("slip_direction_ok", True)),
        stick_admissible=bool(fl.get("stick_admissible", True)),
        consistent=bool(fl.get("consistent", True)),
        converged=bool(rec["converged"]), residual_norm=float(rec["residual_norm"]),
        iterations=int(rec["iterations"]), message=msg,
        extra={"stick_violation": fl.get("stick_violation", float("nan")),
               "slip_violation": fl.get("slip_violation", float("nan")),
               "indentation": float(rec["delta"])})
