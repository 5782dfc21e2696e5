r"""Coatings: the frictionless load, k(c/a) and the work of a load cycle against a/h.

The ``coatings`` target's numbers (issue 39, item 4). A coating (the body's
E1, nu, thickness h) bonded to an elastic substrate of E2/E1 =
``substrate_modulus`` (default 0.5 and 0.1: hard coatings, E1/E2 = 2 and 10;
10 and 100: soft coatings, E1/E2 = 0.1 and 0.01), nu = nu2 = 0.3. For each
geometry, substrate and a/h one self-similar sweep (default method, a/h held
fixed while the contact grows) gives the frictionless load ratio P/P_Hertz
(Hertz on the coating's material at the same contact radius) and k at the
chosen stick ratios, each with its error estimate and ``resolved`` flag. One
incremental history (load 0 -> 1 -> 0 at k = ``history_friction``,
:func:`contactlib.history`) gives the frictional work of the cycle, there
against a_max/h (a_max: the coating's frictionless Hertz radius at the peak
load, h fixed while a grows).

Only a/h within what the coated body supports is computed: the default grid
reaches a/h = 1000 for both geometries (a/h beyond a geometry's limit would be
NaN with ``covered`` False). The
history's mesh reaches 1.2 times the contact, and a soft substrate lets the
contact outgrow a_max, so some a_max/h are refused: those cases are NaN with
``cycle_refused`` set. Nothing beyond is extrapolated.

Units and scalings: those of :func:`contactlib.solve` and
:func:`contactlib.history` with the coating's E* (work: V R^2/(E* a_max^5)
for the sphere, per unit length with a_max^4 for the cylinder).

Examples
--------
>>> from contactlib.coating_study import coating_study
>>> st = coating_study(geometries=("sphere",), substrate_moduli=(0.1,), ratios=(0.01, 1.0),
...                    stick_ratios=(0.5,), n=32, history_ratios=())
>>> st.friction.shape, bool(st.load_ratio[0, 0, 1] < 1.0)
((1, 1, 2, 1), True)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from . import validate
from .api import sweep
from .history_api import history
from .result import short_repr

__all__ = [
    "DEFAULT_HISTORY_RATIOS",
    "DEFAULT_RATIOS",
    "DEFAULT_STICK_RATIOS",
    "DEFAULT_SUBSTRATE_MODULI",
    "HISTORY_MAX_ERROR",
    "ISSUE_RATIO_MAX",
    "MAX_ERROR",
    "CoatingStudy",
    "coating_rows",
    "coating_study",
    "perriot_barthel_modulus",
]

# convention: the study's grid of E2/E1, hard and soft coatings
DEFAULT_SUBSTRATE_MODULI = (0.5, 0.1, 10.0, 100.0)
"""E2/E1 of the study: hard coatings (E1/E2 = 2, 10) and soft ones (0.1, 0.01)."""
# convention: the study's grid of a/h
DEFAULT_RATIOS = (0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0,
                  200.0, 500.0, 1000.0)
# convention: the study's grid of a_max/h for the history's cycle work
DEFAULT_HISTORY_RATIOS = (0.01, 0.1, 0.3, 1.0, 3.0, 10.0, 16.0)
# convention: the study's stick ratios, as the layer study's
DEFAULT_STICK_RATIOS = (0.25, 0.5, 0.75)
# convention: as validate.DEFAULT_MAX_ERROR, the accuracy a result is asked by default
MAX_ERROR = 1e-3
"""Accuracy a load ratio or a k must reach (by its estimate) to count as resolved."""
# convention: as layer_study.HISTORY_MAX_ERROR, the main job's history scenes
HISTORY_MAX_ERROR = 1e-2
"""Accuracy a cycle's work must reach to count as resolved (as the layers study)."""
# convention: the a/h issue 39 asks for (tests/test_coating_study.py checks the study says how far
# its grid covers it)
ISSUE_RATIO_MAX = 1000.0
"""The a/h issue 39 asks for; the study covers its grid only and says so."""


@dataclass(repr=False)
class CoatingStudy:
    """Frictionless load, k and cycle work on coatings, indexed (geometry, E2/E1, a/h[, c/a]).

    Attributes
    ----------
    geometries, substrate_moduli, ratios, stick_ratios : tuple
        The axes (``substrate_moduli``: E2/E1; ``ratios``: a/h).
    nu : float
        Poisson's ratio of the coating and of the substrate.
    n : int
        Elements of every self-similar solve (default method).
    covered : ndarray of bool, shape (G, R)
        The geometry's coated body supports the a/h (else every number is NaN).
    load_ratio, load_error_estimate : ndarray, shape (G, M, R)
        Frictionless P/P_Hertz(a) (coating's E*) and its estimated relative error.
    load_resolved : ndarray of bool, shape (G, M, R)
        Converged and the load's estimate within :data:`MAX_ERROR`.
    friction, error_estimate : ndarray, shape (G, M, R, C)
        k at each stick ratio and its estimated relative error.
    resolved : ndarray of bool, shape (G, M, R, C)
        Converged, consistent (the slip does not reverse) and the estimate
        within :data:`MAX_ERROR`.
    history_ratios : tuple of float
        a_max/h of the load cycles.
    history_friction : float
        k of the load cycles.
    history_n, history_steps : int
        Elements and load steps a segment of each history.
    cycle_work, cycle_work_error_estimate : ndarray, shape (G, M, H)
        Frictional work of the cycle 0 -> 1 -> 0 and its estimated relative
        error (NaN where refused).
    cycle_resolved : ndarray of bool, shape (G, M, H)
        The history's verdict on the work (``resolved_quantities["frictional_work"]``):
        every step converged, the work's estimate within :data:`HISTORY_MAX_ERROR` and
        the slip zone at the top load absent or at least 12 elements wide.
    cycle_refused : ndarray of bool, shape (G, M, H)
        The history refused a_max/h (the contact on a soft substrate would
        outgrow the coated kernels).
    cycle_status : ndarray of str, shape (G, M, H)
        ``resolved``, ``refused (...)`` or ``unresolved (...)`` with the reason: a step
        that did not converge, the work's largest estimate along the path, or a slip
        zone under 12 elements at the top load.
    """

    __repr__ = short_repr

    geometries: tuple[str, ...]
    substrate_moduli: tuple[float, ...]
    nu: float
    ratios: tuple[float, ...]
    stick_ratios: tuple[float, ...]
    n: int
    covered: np.ndarray
    load_ratio: np.ndarray
    load_error_estimate: np.ndarray
    load_resolved: np.ndarray
    friction: np.ndarray
    error_estimate: np.ndarray
    resolved: np.ndarray
    history_ratios: tuple[float, ...]
    history_friction: float
    history_n: int
    history_steps: int
    cycle_work: np.ndarray
    cycle_work_error_estimate: np.ndarray
    cycle_resolved: np.ndarray
    cycle_refused: np.ndarray
    cycle_status: np.ndarray


def coating_study(geometries: Sequence[str] = validate.GEOMETRIES,
                  substrate_moduli: Sequence[float] = DEFAULT_SUBSTRATE_MODULI,
                  nu: float = 0.3, ratios: Sequence[float] = DEFAULT_RATIOS,
                  stick_ratios: Sequence[float] = DEFAULT_STICK_RATIOS, n: int = 256,
                  history_ratios: Sequence[float] = DEFAULT_HISTORY_RATIOS,
                  history_friction: float = 0.2, history_n: int = 360,
                  history_steps: int = 150) -> CoatingStudy:
    """Solve every (geometry, E2/E1, a/h) self-similarly and every (geometry, E2/E1, a_max/h)
    as a load cycle.

    Parameters
    ----------
    geometries : sequence of str
        Default both (sphere, cylinder).
    substrate_moduli : sequence of float
        E2/E1, each in :data:`contactlib.validate.SUBSTRATE_MODULUS_RANGE`
        (default 0.5, 0.1, 10, 100).
    nu : float
        Poisson's ratio of coating and substrate (default 0.3).
    ratios : sequence of float
        a/h > 0 of the self-similar solves (default 0.01 ... 100, 13 points);
        those beyond a geometry's range (:data:`contactlib.validate.LAYER_RATIO_MAX`)
        are left out for it and marked in ``covered``; one beyond every
        geometry's is refused.
    stick_ratios : sequence of float
        c/a in (0, 1) where k is reported (default 1/4, 1/2, 3/4).
    n : int
        Elements of the self-similar solves (default 256).
    history_ratios : sequence of float
        a_max/h of the load cycles (default 0.01 ... 16, 7 points); empty: none.
    history_friction : float
        k of the load cycles (default 0.2).
    history_n, history_steps : int
        Elements and steps a segment of the histories (default 360 and 150).

    Returns
    -------
    CoatingStudy

    Raises
    ------
    ValueError
        If an argument is out of its range (a/h beyond the coated body's, for one).
    """
    geometries = tuple(validate.geometry(g) for g in geometries)
    nu = validate.nu(nu)
    moduli = tuple(validate.substrate(validate.COATED_BASE, m, nu, geometries[0])[0]
                   for m in substrate_moduli)
    cs = tuple(validate.stick_ratio(c) for c in stick_ratios)
    tops = [validate.LAYER_RATIO_MAX[(g, validate.COATED_BASE)] for g in geometries]
    for r in ratios:
        if validate.slab_ratio(r) <= 0.0:
            raise ValueError("ratios: a/h must be > 0 on a coated body's log axis")
        if r > max(tops):  # beyond every geometry: the validator's message
            validate.slab_ratio(r, geometries[tops.index(max(tops))], validate.COATED_BASE)
    covered = np.array([[r <= top for r in ratios] for top in tops], dtype=bool)
    n = validate.n(n, "default")
    history_friction = validate.friction(history_friction)
    shape = (len(geometries), len(moduli), len(ratios))
    load, load_err = np.full(shape, np.nan), np.full(shape, np.nan)
    load_ok = np.zeros(shape, dtype=bool)
    k, k_err = np.full(shape + (len(cs),), np.nan), np.full(shape + (len(cs),), np.nan)
    ok = np.zeros(shape + (len(cs),), dtype=bool)
    hshape = (len(geometries), len(moduli), len(history_ratios))
    work, work_err = np.full(hshape, np.nan), np.full(hshape, np.nan)
    work_ok, refused = np.zeros(hshape, dtype=bool), np.zeros(hshape, dtype=bool)
    status = np.full(hshape, "resolved", dtype=object)
    for i, g in enumerate(geometries):
        for j, m in enumerate(moduli):
            body = {"base": validate.COATED_BASE, "substrate_modulus": m, "substrate_nu": nu}
            for r, ratio in enumerate(ratios):
                if not covered[i, r]:
                    continue
                sols = sweep(g, nu, [0.0, *cs], n=n, slab_ratio=float(ratio), energy=False,
                             **body)
                load[i, j, r] = sols[0].load_ratio
                load_err[i, j, r] = sols[0].load_error_estimate
                load_ok[i, j, r] = bool(sols[0].converged
                                        and sols[0].load_error_estimate <= MAX_ERROR)
                k[i, j, r] = [s.friction_coefficient for s in sols[1:]]
                k_err[i, j, r] = [s.error_estimate for s in sols[1:]]
                ok[i, j, r] = [bool(s.converged and s.consistent
                                    and s.error_estimate <= MAX_ERROR) for s in sols[1:]]
            for r, ratio in enumerate(history_ratios):
                try:
                    res = history(g, nu, history_friction, [0.0, 1.0, 0.0], history_steps,
                                  n=history_n, slab_ratio=float(ratio),
                                  max_error=HISTORY_MAX_ERROR, **body)
                except validate.InputError as exc:  # the contact would outgrow the kernels
                    if exc.name != "slab_ratio":  # (a soft substrate); anything else is a bug
                        raise
                    refused[i, j, r] = True
                    status[i, j, r] = "refused (contact beyond the coated kernels)"
                    continue
                work[i, j, r] = res.frictional_work[-1]
                work_err[i, j, r] = res.work_error_estimate[-1]
                # the work's own verdict (every step converged, the work within
                # max_error of its total, a slip zone of 12 elements or none at the top
                # load), not the last step's, which also judges the stick radius
                work_ok[i, j, r] = bool(res.resolved_quantities["frictional_work"])
                if not work_ok[i, j, r]:
                    status[i, j, r] = ("unresolved (the work: "
                                       f"{res.unresolved_reasons['frictional_work']})")
    return CoatingStudy(geometries=geometries, substrate_moduli=moduli, nu=nu,
                        ratios=tuple(float(r) for r in ratios), stick_ratios=cs, n=n,
                        covered=covered,
                        load_ratio=load, load_error_estimate=load_err, load_resolved=load_ok,
                        friction=k, error_estimate=k_err, resolved=ok,
                        history_ratios=tuple(float(r) for r in history_ratios),
                        history_friction=history_friction, history_n=history_n,
                        history_steps=history_steps, cycle_work=work,
                        cycle_work_error_estimate=work_err, cycle_resolved=work_ok,
                        cycle_refused=refused, cycle_status=status)


def coating_rows(study: CoatingStudy) -> list[dict[str, object]]:
    """Rows of the coatings table: one a (geometry, E2/E1, a/h), then one a load cycle.

    Columns: geometry, quantity (``self-similar`` or ``load cycle``), E1/E2, E2/E1,
    a/h (a_max/h for a cycle), the frictionless load ratio with its estimate,
    k at each stick ratio with its estimate, the cycle's work with its
    estimate, and ``status``: ``resolved``, ``unresolved: ...`` (the number is
    given with its estimate but is not data) or ``refused``. A value that is
    not resolved is blank. a/h beyond the study's grid up to the issue's
    1000, where the grid stops short of it, gets one ``not covered`` row a geometry.
    """
    rows: list[dict[str, object]] = []
    cs = study.stick_ratios
    blank = {"P/P_Hertz": "", "P estimate": "", **{f"k at c/a = {c:g}": "" for c in cs},
             **{f"k estimate at c/a = {c:g}": "" for c in cs}, "work per cycle": "",
             "work estimate": ""}
    for i, g in enumerate(study.geometries):
        for j, m in enumerate(study.substrate_moduli):
            head = {"geometry": g, "E1/E2": float(1.0 / m), "E2/E1": float(m)}
            for r, ratio in enumerate(study.ratios):
                row: dict[str, object] = {**head, "kind": "self-similar", "a/h": ratio,
                                          **blank}
                if not study.covered[i, r]:
                    row["status"] = "not covered (beyond the coated body's range)"
                    rows.append(row)
                    continue
                bad = []
                if study.load_resolved[i, j, r]:
                    row["P/P_Hertz"] = float(study.load_ratio[i, j, r])
                else:
                    bad.append("load")
                row["P estimate"] = float(study.load_error_estimate[i, j, r])
                for c_i, c in enumerate(cs):
                    if study.resolved[i, j, r, c_i]:
                        row[f"k at c/a = {c:g}"] = float(study.friction[i, j, r, c_i])
                    else:
                        bad.append(f"k at c/a = {c:g}")
                    row[f"k estimate at c/a = {c:g}"] = float(study.error_estimate[i, j, r, c_i])
                row["status"] = "resolved" if not bad else "unresolved: " + ", ".join(bad)
                rows.append(row)
            for r, ratio in enumerate(study.history_ratios):
                row = {**head, "kind": "load cycle", "a/h": ratio, **blank}
                row["status"] = str(study.cycle_status[i, j, r])
                if not study.cycle_refused[i, j, r]:
                    if study.cycle_resolved[i, j, r]:
                        row["work per cycle"] = float(study.cycle_work[i, j, r])
                    row["work estimate"] = float(study.cycle_work_error_estimate[i, j, r])
                rows.append(row)
        top = max((r for r, c in zip(study.ratios, study.covered[i]) if c), default=0.0)
        if top >= ISSUE_RATIO_MAX:
            continue
        rows.append({"geometry": g, "E1/E2": "", "E2/E1": "", "kind": "not covered",
                     "a/h": f"{top:g} < a/h <= {ISSUE_RATIO_MAX:g}", **blank,
                     "status": "not computed in this study: no extrapolation"})
    return rows


def perriot_barthel_modulus(ratio: np.ndarray | float, substrate_modulus: float,
                            exponent: float) -> np.ndarray:
    """Perriot & Barthel's (2004) fit of a coated body's effective modulus, over the film's.

    E'/E'_f = 1 + (E'_s/E'_f - 1)/(1 + (k0 t/a)^n), log10 k0 = -0.093 +
    0.792 x + 0.05 x^2, x = log10(E'_s/E'_f) (t = h, the coating's thickness).

    Parameters
    ----------
    ratio : array_like
        a/h > 0.
    substrate_modulus : float
        E'_s/E'_f (plane-strain moduli; equal Poisson's ratios: E2/E1).
    exponent : float
        The fit's n (1.06 ... 1.32 in the paper, by modulus ratio).

    Returns
    -------
    ndarray
        E'/E'_f at each a/h.
    """
    x = np.log10(substrate_modulus)
    k0 = 10.0 ** (-0.093 + 0.792 * x + 0.05 * x * x)
    t_over_a = 1.0 / np.asarray(ratio, dtype=float)
    return 1.0 + (substrate_modulus - 1.0) / (1.0 + (k0 * t_over_a) ** exponent)
