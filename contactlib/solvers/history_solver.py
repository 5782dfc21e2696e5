r"""Incremental stick-slip solver for an arbitrary normal load path (numerics only).

The public entry point is :func:`contactlib.history` (module
:mod:`contactlib.history_api`); this module holds the discretization, the
per-step active-set solver and the post-processing of one state. It never
touches the disk.

Units and scalings
------------------
E* = R = 1 and lengths in units of ``a_max``, the frictionless (Hertz) contact
radius at the reference load ``P_max`` (load level 1 of the path). So
``P_max = 4/3`` (sphere, E* a_max^3/R) or ``pi/4`` (cylinder, E* a_max^2/R per
unit length), the pressure scale is the Hertz peak pressure at ``a_max``,
``p0 = 2/pi`` (sphere) or ``1/2`` (cylinder), displacements are in
``a_max^2/R`` and work in ``E* a_max^5/R^2`` (sphere) or ``E* a_max^4/R^2`` per
unit length (cylinder). The slab thickness is ``h = a_max / slab_ratio``.

Discretization
--------------
A fixed uniform mesh of ``n`` rings (sphere) or strip pairs (cylinder, both
sides of the axis) over ``0 <= r <= L`` (``L = 1.2 a_max``). On element ``j``
the pressure is constant, ``p_j``; the shear is ``q_j r / r_j`` (sphere: the
disc kernel's linear shear, zero on the axis) or constant ``q_j`` (cylinder,
odd in x), with ``r_j`` the element midpoint. The influence matrices are exact
differences of the closed-form disc/strip kernels at the element edges,
evaluated at the midpoints (collocation points, never on an edge, so the
logarithmic kernel singularities are not met): the step operators of
:func:`contactlib.discretization.operators.step_operator`, with element areas and shear
resultants from the indenter (:mod:`contactlib.model.indenter`).

Conditions at the collocation points (w positive into the body, u outward; the
indenter is rigid and has no tangential motion):

* normal: gap ``g_i = w_i - delta + r_i^2/2 >= 0``, ``p_i >= 0``,
  ``p_i g_i = 0`` (``delta`` the indentation, unknown: the load
  ``sum_j p_j A_j`` is prescribed, which also fixes the half-plane's free
  constant);
* tangential, with the slip increment ``du_i = u_i - u_i^old`` of the step
  (the body's displacement relative to the rigid indenter): stick
  ``du_i = 0`` and ``|q_i| <= k p_i``; slip ``q_i = -k p_i sign(du_i)``
  (``q_i = +k p_i`` while the body slips toward the axis). Separated
  elements carry no traction; the displacement ``u^old`` they have when
  they touch down is the state their stick condition holds on to.

Solver
------
Each step is a complementarity problem with a non-symmetric (Coulomb: the
friction bound depends on the unknown pressure) coupling, solved by a
primal-dual active-set iteration: for given sets (separated / stick / slip
inward / slip outward) the conditions are one linear system in the pressures
of the contact elements, the shears of the stuck ones and ``delta`` (the slip
shears ``+-k p`` are eliminated), solved by LU; then the sets are updated
element by element:

* separated -> contact if ``g_i < 0``; contact -> separated if ``p_i < 0``;
* stick -> slip (in the direction that makes ``q`` the friction force) if
  ``|q_i| > k p_i``;
* slip -> stick if the slip increment runs the wrong way (``q_i du_i > 0``);
* an element touching down starts as stick if the shear that would hold it
  (its increment times its own tangential stiffness) is below k times the
  pressure that would push it back (its penetration times its own normal
  stiffness), else slipping against its increment.

The iteration stops when the sets reproduce themselves, i.e. every condition
holds (switching tolerances 1e-10 of the current pressure, gap and slip
scales). A set that repeats (a cycle) switches the update to one change at a
time (the largest violation first); after ``max_iter`` iterations the step is
kept and flagged as not converged, with its residual. The matrix depends only
on the sets, so the first iteration of a step reuses the factorization of the
previous step's last one.

These switching rules are the semi-smooth Newton method on
``p - max(0, p - eps g) = 0``, ``q - proj_[-kp, kp](q - eps du) = 0`` in the
limit of a small ``eps`` (Kalker's classical active-set rules). With ``eps``
of the order of the element stiffness the iteration was seen to cycle when
many elements touch down in one step; with these rules a step of a 200-step
cycle takes about 3 iterations.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np
from scipy import linalg

from ..energy import (decay_integrals, dot, mean_traction, monotone_work, step_external_work,
                     step_work, stored_energy, viscous_step_work)
from ..model import Contact
from ..validate import HISTORY_MESH_EXTENT
from ..discretization.operators import step_operator

__all__ = ["SEPARATED", "STICK", "SLIP_INWARD", "SLIP_OUTWARD", "STATE_MEANINGS",
           "Operators", "StepResult", "build_operators", "solve_step", "contact_radius",
           "stick_radius", "MESH_EXTENT", "RawHistory", "run_history",
           "MIN_SLIP_ELEMENTS", "prony_step", "path_interpolate", "error_estimates",
           "annulus_resolved", "straddle", "measured_order", "ORDER_MIN", "ORDER_MAX",
           "smooth_deviation", "EDGE_COARSE_RATIO"]

# convention: the element states the datasets store (meanings in STATE_MEANINGS)
SEPARATED, STICK, SLIP_INWARD, SLIP_OUTWARD = 0, 1, 2, 3
STATE_MEANINGS = "separated stick slip_inward slip_outward"
MESH_EXTENT = HISTORY_MESH_EXTENT  # mesh length over a_max (validate bounds layers with it)

# tested: tests/test_history.py (set switching within 1e-10 of the current scales: the
# energy balance and the closed forms there hold to 1e-5 and below)
_REL_TOL = 1e-10
# tested: tests/test_history_error.py (a slip zone over fewer elements is not resolved)
MIN_SLIP_ELEMENTS = 12
# exact: d ~ (c - r)^(1/2), so d^2 is linear at a standing or receding stick edge
# (stick_radius; benchmarks/report_stick_edge.py measures the located edge)
STANDING_EDGE_POWER = 2.0
# measured: benchmarks/report_history_estimates.py. Bounds of a measured order of
# convergence (error_estimates): below 1/2 the runs are not converging, and above 3 the
# three runs' differences are at round-off or coincidence
ORDER_MIN, ORDER_MAX = 0.5, 3.0
# convention: step durations whose scaled operators a viscoelastic run keeps (a cache)
_MAX_DURATIONS = 4
# the LAPACK routines behind scipy.linalg.lu_factor / lu_solve, called without their
# wrappers' checks (a step's many small systems made those a tenth of its time)
_GETRF, _GETRS = linalg.get_lapack_funcs(("getrf", "getrs"), (np.zeros((1, 1)),))


@dataclass(frozen=True)
class Operators:
    """Influence matrices of one mesh (units E* = R = a_max = 1).

    Attributes
    ----------
    edges : ndarray, shape (n + 1,)
        Element edges 0 = s_0 < ... < s_n = L.
    mid : ndarray, shape (n,)
        Midpoints (collocation points).
    area : ndarray, shape (n,)
        Area carrying a unit pressure: pi (s_{j+1}^2 - s_j^2) (ring) or
        2 (s_{j+1} - s_j) (strip pair, per unit length).
    shear_area : ndarray, shape (n,)
        Integral of the element's shear shape over its area (ring:
        int (r/r_j) 2 pi r dr; strip pair: as ``area``).
    pw, pu, qw, qu : ndarray, shape (n, n)
        w and u at midpoint i of unit pressure / unit shear (value at the
        midpoint) on element j.
    p_max : float
        Reference load P_max (Hertz load at a_max = 1).
    p0 : float
        Hertz peak pressure at a_max.
    model : Contact
        The model the matrices were built from (lengths in units of a_max).
    """

    edges: np.ndarray
    mid: np.ndarray
    area: np.ndarray
    shear_area: np.ndarray
    pw: np.ndarray
    pu: np.ndarray
    qw: np.ndarray
    qu: np.ndarray
    p_max: float
    p0: float
    model: Contact

    @property
    def n(self) -> int:
        return self.mid.size


def build_operators(model: Contact, n: int, extent: float = MESH_EXTENT) -> Operators:
    """Influence matrices of ``n`` equal elements over ``[0, extent]`` (units a_max).

    Parameters
    ----------
    model : Contact
        The indenter and the body, lengths in units of a_max (so the body's
        ``slab_ratio`` is a_max/h).
    n : int
        Number of elements.
    extent : float
        Mesh length over a_max.
    """
    edges = np.linspace(0.0, extent, n + 1)
    mid = 0.5 * (edges[:-1] + edges[1:])
    pw, pu, _ = step_operator(model, edges, mid, "normal")
    qw, qu, _ = step_operator(model, edges, mid, "shear")
    shape = model.shear_shape(mid)  # the shear unknown is its value at the midpoint
    ind = model.indenter
    return Operators(edges=edges, mid=mid, area=ind.element_areas(edges),
                     shear_area=ind.shear_resultants(edges) / shape,
                     pw=pw, pu=pu, qw=qw / shape[None, :], qu=qu / shape[None, :],
                     p_max=float(model.hertz_load), p0=float(model.p0), model=model)


@dataclass
class StepResult:
    """Solution of one load step (units E* = R = a_max = 1)."""

    p: np.ndarray
    q: np.ndarray
    u: np.ndarray
    gap: np.ndarray
    delta: float
    state: np.ndarray  # int8, one of SEPARATED, STICK, SLIP_INWARD, SLIP_OUTWARD
    converged: bool
    iterations: int
    residual: float


def _rows(index: np.ndarray) -> np.ndarray | slice:
    """``index`` as a slice when it is a contiguous run (a view instead of a gather)."""
    if index.size and int(index[-1]) - int(index[0]) + 1 == index.size:
        return slice(int(index[0]), int(index[-1]) + 1)
    return index


def _block(mat: np.ndarray, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
    """``mat[np.ix_(rows, cols)]``, by slicing where the indices are contiguous runs."""
    r, c = _rows(rows), _rows(cols)
    if isinstance(r, slice):
        return mat[r, c]
    return mat[r][:, c]


def _slip_columns(ops: Operators, k: float, cache: dict) -> tuple[np.ndarray, ...]:
    """``pw + k qw``, ``pw - k qw``, ``pu + k qu``, ``pu - k qu``: the slip elements' columns.

    Computed once per operators and k (kept in ``cache``); each entry is the
    sum :func:`_assemble` forms, ``pw + qw * (+-k)``, so the matrix is the same
    to the last bit.
    """
    key = (id(ops), k)
    if cache.get("slip_key") != key:
        cache.update(slip_key=key, slip=(ops.pw + ops.qw * k, ops.pw + ops.qw * -k,
                                         ops.pu + ops.qu * k, ops.pu + ops.qu * -k))
    return cache["slip"]


def _assemble(ops: Operators, k: float, state: np.ndarray, cache: dict | None = None
              ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Matrix of the conditions for the given sets (it depends on nothing else).

    The slip shears are eliminated (``q_i = +-k p_i``), so the unknowns are the
    contact pressures, the stick shears and ``delta``: size ``m + m_stick + 1``.
    Rows: normal collocation on the contact elements, stick collocation, load.
    Returns ``(A, c, factor, stick)``: the contact elements ``c``, the factor
    with ``q_c = factor * p_c`` on the slip elements, and the positions (within
    ``c``) of the stick elements. ``A`` is in Fortran order (LAPACK's).
    """
    c = np.flatnonzero(state)
    m = c.size
    st = state[c]
    factor = np.zeros(m)
    slipping = 0.0 < k < np.inf
    if slipping:
        inward, outward = st == SLIP_INWARD, st == SLIP_OUTWARD
        factor[inward] = k
        factor[outward] = -k
    stick = np.flatnonzero(st == STICK) if k > 0.0 else np.zeros(0, dtype=np.int64)
    cs = c[stick]
    ms = cs.size
    size = m + ms + 1
    a = np.zeros((size, size), order="F")
    # normal: w_i - delta = -r_i^2 / 2 on the contact elements (a slip element's
    # column carries its shear +-k p)
    a[:m, :m] = _block(ops.pw, c, c)
    a[:m, m:m + ms] = _block(ops.qw, c, cs)
    a[:m, -1] = -1.0
    # stick: u_i = u_i^old
    a[m:m + ms, :m] = _block(ops.pu, cs, c)
    a[m:m + ms, m:m + ms] = _block(ops.qu, cs, cs)
    if slipping:
        w_in, w_out, u_in, u_out = _slip_columns(ops, k, {} if cache is None else cache)
        for pos, w_mat, u_mat in ((np.flatnonzero(inward), w_in, u_in),
                                  (np.flatnonzero(outward), w_out, u_out)):
            if pos.size:
                a[:m, pos] = _block(w_mat, c, c[pos])
                a[m:m + ms, pos] = _block(u_mat, cs, c[pos])
    # load
    a[-1, :m] = ops.area[c]
    return a, c, factor, stick


def _rhs(ops: Operators, load: float, u_old: np.ndarray, c: np.ndarray,
         stick: np.ndarray) -> np.ndarray:
    """Right-hand side matching :func:`_assemble`."""
    m, ms = c.size, stick.size
    b = np.empty(m + ms + 1)
    b[:m] = -ops.model.profile.gap(ops.mid[c])  # -r^2/2 for the paraboloid
    b[m:m + ms] = u_old[c[stick]]
    b[-1] = load
    return b


def _scales(ops: Operators, state: np.ndarray, p: np.ndarray, du: np.ndarray,
            gap: np.ndarray, delta: float) -> tuple[float, float, float]:
    """Pressure, gap and slip scales of the switching tolerances and the residual.

    The gap scale is the larger of the largest gap and the profile's gap scale
    at the outermost contact element (r^2 for the paraboloid, the approach for
    the flat punch: :meth:`~contactlib.model.profiles.Profile.gap_scale`); the slip
    scale is the largest slip increment, floored at 1e-6 of the gap scale
    (a^2/R) so that a step with no motion has a finite scale.
    """
    p_scale = max(float(np.abs(p).max()), 1e-300)
    last = np.flatnonzero(state)[-1:]  # the midpoints increase outward
    g_scale = max(ops.model.profile.gap_scale(ops.mid[last[0]], delta) if last.size else 0.0,
                  float(np.abs(gap).max()), 1e-300)
    d_scale = max(float(np.abs(du).max()), 1e-6 * g_scale)
    return p_scale, g_scale, d_scale


def _violations(ops: Operators, k: float, state: np.ndarray, p: np.ndarray, q: np.ndarray,
                du: np.ndarray, gap: np.ndarray,
                scales: tuple[float, float, float]) -> tuple[np.ndarray, np.ndarray]:
    """Proposed new sets and the size of each element's violation.

    Violations are scaled by the current pressure and displacement scales
    (:func:`_scales`).
    """
    p_scale, g_scale, d_scale = scales
    tol_p, tol_g, tol_d = _REL_TOL * p_scale, _REL_TOL * g_scale, _REL_TOL * d_scale
    new = state.copy()
    viol = np.zeros(state.size)
    contact = state > 0

    # normal sets
    lose = contact & (p < -tol_p)
    gain = ~contact & (gap < -tol_g)
    new[lose] = SEPARATED
    viol[lose] = -p[lose] / p_scale
    ii = np.flatnonzero(gain)
    if ii.size:
        viol[ii] = -gap[ii] / g_scale
        if k == 0.0 or np.isinf(k):
            new[ii] = SLIP_INWARD if k == 0.0 else STICK
        else:
            # touching down: the projection rule at p = q = 0 with the element's own
            # stiffnesses, i.e. stick if the traction that would hold the element
            # (-du / qu_ii) is within k times the pressure that would push it back
            # (-g / pw_ii); else slip against the increment
            p_trial = -gap[ii] / ops.pw[ii, ii]
            q_trial = -du[ii] / ops.qu[ii, ii]
            new[ii] = np.where(np.abs(q_trial) <= k * p_trial, STICK,
                               np.where(q_trial > 0.0, SLIP_INWARD, SLIP_OUTWARD))

    stay = contact & ~lose
    if k == 0.0:
        pass  # q = 0 everywhere; the slip direction is labelled afterwards
    elif np.isinf(k):
        new[stay] = STICK
    else:
        kp = k * np.maximum(p, 0.0)
        over = stay & (state == STICK) & (np.abs(q) > kp + k * tol_p)
        if over.any():
            new[over & (q > 0)] = SLIP_INWARD
            new[over & (q < 0)] = SLIP_OUTWARD
            viol[over] = (np.abs(q[over]) - kp[over]) / p_scale
        wrong = stay & (((state == SLIP_INWARD) & (du > tol_d))
                        | ((state == SLIP_OUTWARD) & (du < -tol_d)))
        if wrong.any():
            new[wrong] = STICK
            viol[wrong] = np.abs(du[wrong]) / d_scale
    return new, viol


def _residual(k: float, state: np.ndarray, p: np.ndarray, q: np.ndarray, du: np.ndarray,
              gap: np.ndarray, scales: tuple[float, float, float]) -> float:
    """Largest scaled violation of any condition (complementarity, sign and Coulomb).

    The equalities the current sets impose are included; scaled by
    :func:`_scales`.
    """
    p_scale, g_scale, d_scale = scales
    contact = state > 0
    # contact: gap = 0, p >= 0; separated: gap >= 0, p = q = 0
    res = np.where(contact, np.maximum(np.abs(gap) / g_scale, np.maximum(-p, 0.0) / p_scale),
                   np.maximum(np.maximum(-gap, 0.0) / g_scale,
                              (np.abs(p) + np.abs(q)) / p_scale))
    if k > 0.0:
        kp = k * np.maximum(p, 0.0) if np.isfinite(k) else np.full(p.size, np.inf)
        excess = np.abs(q) - kp
        st = state == STICK
        if st.any():  # stick: du = 0, |q| <= k p
            res[st] = np.maximum(res[st], np.maximum(np.abs(du[st]) / d_scale,
                                                     np.maximum(excess[st], 0.0) / p_scale))
        sl = state >= SLIP_INWARD
        if sl.any():  # slip: |q| = k p, q du <= 0
            res[sl] = np.maximum(res[sl], np.maximum(
                np.abs(excess[sl]) / p_scale,
                np.maximum(q[sl] * du[sl], 0.0) / (p_scale * d_scale)))
    return float(res.max())


def solve_step(ops: Operators, k: float, load: float, u_old: np.ndarray,
               guess: np.ndarray, max_iter: int = 200,
               cache: dict | None = None, w_shift: np.ndarray | None = None,
               u_shift: np.ndarray | None = None) -> StepResult:
    """Solve one load step by the active-set iteration (see the module notes).

    Parameters
    ----------
    ops : Operators
    k : float
        Friction coefficient (0: frictionless, ``inf``: no slip).
    load : float
        Prescribed total load P (units of ``ops``; > 0).
    u_old : ndarray
        Tangential displacement at the end of the previous step.
    guess : ndarray of int8
        Initial sets (usually the previous step's); must contain a contact element.
    max_iter : int
        Active-set iterations allowed.
    cache : dict, optional
        Keeps the last LU factorization between calls (same ``ops`` and ``k``):
        the matrix depends only on the sets, so a step that starts from the
        previous step's final sets reuses its factorization. It also keeps
        the slip elements' columns ``pw +- k qw``, ``pu +- k qu`` of ``ops``
        and ``k`` (:func:`_slip_columns`).
    w_shift, u_shift : ndarray, optional
        Displacements the step adds whatever its tractions (a viscoelastic
        body's memory, :func:`run_history`): w = pw p + qw q + w_shift,
        u = pu p + qu q + u_shift. None: zero (an elastic body).
    """
    state = guess.astype(np.int8, copy=True)
    if not np.any(state):
        state[0] = STICK
    if k == 0.0:
        state[state > 0] = SLIP_INWARD
    cache = {} if cache is None else cache
    seen: set[bytes] = {state.tobytes()}
    one_at_a_time = False
    p = q = u = gap = np.zeros(ops.n)
    delta, last = 0.0, None
    it = 0
    for it in range(1, max_iter + 1):
        key = state.tobytes()
        if cache.get("key") != key:
            a, c, factor, stick = _assemble(ops, k, state, cache)
            lu, piv, _ = _GETRF(a, overwrite_a=True)  # LAPACK directly: lu_factor's own call
            cache.update(key=key, lu=(lu, piv), c=c, factor=factor, stick=stick)
        lu, c, factor, stick = cache["lu"], cache["c"], cache["factor"], cache["stick"]
        b = _rhs(ops, load, u_old, c, stick)
        if w_shift is not None:
            b[:c.size] -= w_shift[c]
            b[c.size:c.size + stick.size] -= u_shift[c[stick]]
        x = _GETRS(*lu, b, overwrite_b=True)[0]  # a singular U gives inf/nan (below)
        if not np.all(np.isfinite(x)):  # singular system for these sets
            cache.clear()
            break
        m = c.size
        p = np.zeros(ops.n)
        q = np.zeros(ops.n)
        p[c] = x[:m]
        qc = factor * x[:m]
        qc[stick] = x[m:-1]
        q[c] = qc
        delta = float(x[-1])
        w = ops.pw @ p + ops.qw @ q
        u = ops.pu @ p + ops.qu @ q
        if w_shift is not None:
            w += w_shift
            u += u_shift
        gap = w - delta + ops.model.profile.gap(ops.mid)
        du = u - u_old
        scales = _scales(ops, state, p, du, gap, delta)
        last = (k, state, p, q, du, gap, scales)  # the residual's arguments, if kept
        new, viol = _violations(ops, k, state, p, q, du, gap, scales)
        if np.array_equal(new, state):
            return StepResult(p, q, u, gap, delta, _label(k, state, du), True, it,
                              _residual(k, state, p, q, du, gap, scales))
        if one_at_a_time or new.tobytes() in seen:
            # a cycle: from now on change one element at a time, largest violation first
            one_at_a_time = True
            i = int(np.argmax(np.where(new != state, viol, -1.0)))
            nxt = state.copy()
            nxt[i] = new[i]
            new = nxt
        seen.add(new.tobytes())
        state = new
    res = np.inf if last is None else _residual(*last)
    return StepResult(p, q, u, gap, delta, _label(k, state, u - u_old), False, it, res)


def _label(k: float, state: np.ndarray, du: np.ndarray) -> np.ndarray:
    """Final state labels. Without friction nothing sticks (|q| < k p cannot hold): every
    contact element slips, labelled by its slip's sign; nil slip (within round-off: nu =
    0.5, a thin bonded layer's centre) reads slip_inward."""
    out = state.copy()
    if k == 0.0:
        contact = state > 0
        tol = _REL_TOL * max(float(np.max(np.abs(du))), 1e-300)
        out[contact] = SLIP_INWARD
        out[contact & (du > tol)] = SLIP_OUTWARD
    return out


def contact_radius(ops: Operators, state: np.ndarray, gap: np.ndarray) -> float:
    """Contact radius (units a_max) with sub-element resolution.

    The contact set is taken from the axis to the last contact element
    (index ``m - 1``). Near the contact edge the gap grows like
    ``(r - a)^(3/2)``, so ``g^(2/3)`` of the first two separated elements is
    extrapolated linearly to zero; the result is kept between the midpoint
    of the last contact element and that of the first separated one (else
    the element edge ``s_m`` is returned). 0 without contact.
    """
    contact = np.flatnonzero(state > 0)
    if contact.size == 0:
        return 0.0
    m = int(contact[-1]) + 1
    r = ops.mid
    if m + 1 >= ops.n:
        return float(ops.edges[m])
    g1, g2 = gap[m], gap[m + 1]
    if not (g2 > g1 > 0.0):
        return float(ops.edges[m])
    t1, t2 = g1 ** (2.0 / 3.0), g2 ** (2.0 / 3.0)
    a = r[m] - t1 * (r[m + 1] - r[m]) / (t2 - t1)
    lo = r[m - 1] if m >= 1 else 0.0
    return float(np.clip(a, lo, r[m]))


def stick_radius(ops: Operators, k: float, state: np.ndarray, p: np.ndarray, q: np.ndarray,
                 a: float, receding: bool = False, fit: bool = True) -> float:
    """Radius of the central stick zone (units a_max), sub-element where the deficit allows.

    The central stick zone is the run of stuck elements from the axis. If it
    reaches the contact edge the result is ``a``; if the axis element is not
    stuck it is 0. Otherwise the estimate is the edge between the last stuck
    and the first other element, refined from the traction deficit
    ``d = 1 - |q|/(k p)`` of the last three stuck elements, which follows one
    of two laws near a stick edge:

    * an advancing edge (the stick zone growing with the contact, as under
      increasing or held load) carries no stress-intensity factor (the
      physical condition of continued loading, see
      :mod:`contactlib.solvers.default_method`), so ``d ~ (c - r)^(3/2)`` and
      ``d^(2/3)`` is linear;
    * a receding edge (``receding``: the load decreases, and the stick zone
      shrinks as a slip zone of the other sign spreads inward) or a standing
      one (the flat punch's under a monotonic load, whose solution is
      proportional to the load) has ``d ~ (c - r)^(1/2)``, and ``d^2`` is
      linear (:data:`STANDING_EDGE_POWER`,
      :attr:`contactlib.model.profiles.Profile.stick_edge_power`).

    With ``t = d^power`` of that law, the last two slopes of ``t`` over the
    three elements must agree within a factor 1.5; then ``t`` of the last two
    is extrapolated linearly to zero, kept below the midpoint of the first
    element not stuck and rejected more than two elements beyond the last
    stuck midpoint. Where the law does not fit (fewer than three stuck
    elements, a deficit that is not monotonic, slopes that disagree) the
    element edge is returned, good to half an element; so it is at the
    first step after a turning point of the load (``fit`` False), where the
    edge has not yet moved and the deficit follows neither law (sphere, nu =
    0, k = 0.3, 0-1-0.5-1-...: a d^2 fit there was 0.55 of an element off).

    Measured (``python benchmarks/report_stick_edge.py``: sphere, nu = 0.3, k =
    0.2, 0 -> 1 -> 0 in 50 steps a segment, n = 120, against n = 480 and 200
    steps, every fourth step of the unloading): the element edge was 0.25 ...
    0.5 of an element off at every step; now the stick radius is within 0.15 of
    an element at 11 of 13 steps (the cylinder at k = 0.3: 10 of 13); the last,
    at P = 0.02 P_max, moves the contact edge over several elements a step.
    """
    contact = state > 0
    if not contact[0] or state[0] != STICK:
        return 0.0
    not_stuck = np.flatnonzero(state != STICK)
    j = int(not_stuck[0]) if not_stuck.size else ops.n  # first element not stuck
    if j >= ops.n or not contact[j]:
        return float(a)  # stuck up to the contact edge
    r = ops.mid
    edge = float(ops.edges[j])
    if j < 3 or not np.isfinite(k) or k <= 0.0 or not fit:
        return edge
    with np.errstate(divide="ignore", invalid="ignore"):
        d = 1.0 - np.abs(q[j - 3:j]) / (k * p[j - 3:j])  # elements j-3, j-2, j-1
    if not (np.all(np.isfinite(d)) and d[0] > d[1] > d[2] >= 0.0):
        return edge
    power = STANDING_EDGE_POWER if receding else ops.model.profile.stick_edge_power
    t = d ** power
    last, before = t[1] - t[2], t[0] - t[1]
    if not (1.0 / 1.5 <= last / before <= 1.5):
        return edge
    h = r[j - 1] - r[j - 2]
    c = r[j - 1] + t[2] * h / last
    if c > r[j - 1] + 2.0 * h:  # deficit too large for an edge near the last stuck element
        return edge
    return float(min(c, r[j]))


@dataclass
class RawHistory:
    """Every step of a history (row 0: the unloaded initial state), units a_max = 1.

    The energies are cumulative, in the units of ``work`` (see
    :mod:`contactlib.energy`); ``time`` is None for an elastic body.
    """

    load: np.ndarray  # (S+1,) P / P_max
    p: np.ndarray  # (S+1, n)
    q: np.ndarray
    u: np.ndarray
    delta: np.ndarray  # (S+1,)
    state: np.ndarray  # (S+1, n) int8
    work: np.ndarray  # (S+1,) cumulative frictional work
    contact_radius: np.ndarray  # (S+1,)
    stick_radius: np.ndarray  # (S+1,)
    converged: np.ndarray  # (S+1,) bool
    iterations: np.ndarray  # (S+1,) int
    residual: np.ndarray  # (S+1,)
    time: np.ndarray | None = None  # (S+1,) viscoelastic body only
    external_work: np.ndarray | None = None  # (S+1,) cumulative P d(delta)
    stored_energy: np.ndarray | None = None  # (S+1,) free energy of the body
    viscous_work: np.ndarray | None = None  # (S+1,) cumulative dashpot dissipation


def prony_step(g: np.ndarray, tau: np.ndarray, dt: float) -> tuple[np.ndarray, np.ndarray, float]:
    """Coefficients of the recursive hereditary integral over a step of duration ``dt``.

    For each Prony term the branch variable h_i = int exp(-(t - s)/tau_i) de(s)
    (e the elastic-equivalent traction, linear in time within the step)
    updates exactly as ``h_i^new = a_i h_i^old + b_i (e^new - e^old)`` with
    ``a_i = exp(-dt/tau_i)`` and ``b_i = (tau_i/dt)(1 - a_i)``; the traction
    ``sigma = g_inf e + sum g_i h_i`` is then ``beta e^new + sigma_hist`` with
    ``beta = g_inf + sum g_i b_i`` in (g_inf, 1].

    Returns
    -------
    (a, b, beta)
    """
    x = dt / tau
    a = np.exp(-x)
    b = -np.expm1(-x) / x
    return a, b, float(1.0 - np.sum(g) + np.sum(g * b))


def run_history(ops: Operators, k: float, levels: np.ndarray,
                progress: Callable[[int, int], None] | None = None,
                max_iter: int = 200, times: np.ndarray | None = None) -> RawHistory:
    """Follow the load levels ``levels`` (P/P_max; ``levels[0]`` must be 0).

    The frictional work of a step is :func:`contactlib.energy.step_work`
    (trapezoid in time over the elements slipping at the end of the step and
    those that slipped before it and separate in it); the cumulative work is
    :func:`contactlib.energy.monotone_work` of its sums, so it never falls.
    A step from no contact starts from the Hertz contact radius of its load
    (:meth:`contactlib.model.indenter.Indenter.hertz_radius`).

    A viscoelastic body (``ops.model.body`` a
    :class:`~contactlib.model.body.ViscoelasticBody`) needs the ``times`` of the
    steps (``times[0] = 0``, unit of its tau). Its displacements are
    d = K e, K the elastic operator at E(0) (``ops``) and e the
    elastic-equivalent traction, and sigma = g_inf e + sum g_i h_i
    (:func:`prony_step`). A step is therefore the elastic step with the
    operator K/beta and the shift -K sigma_hist/beta; K h_i is carried
    along with h_i (``K h_i^new = a_i K h_i^old + b_i (d^new - d^old)``), so
    a step needs no product with K beyond the elastic step's: memory
    ``(2 N + 2) 2 n`` numbers and time per step independent of the number
    of steps. The energies are those of :mod:`contactlib.energy`.
    """
    levels = np.asarray(levels, dtype=float)
    steps = levels.size
    n = ops.n
    z = np.zeros((steps, n))
    out = RawHistory(levels.copy(), z.copy(), z.copy(), z.copy(), np.zeros(steps),
                     np.zeros((steps, n), dtype=np.int8), np.zeros(steps),
                     np.zeros(steps), np.full(steps, np.nan), np.ones(steps, dtype=bool),
                     np.zeros(steps, dtype=np.int64), np.zeros(steps),
                     external_work=np.zeros(steps), stored_energy=np.zeros(steps),
                     viscous_work=np.zeros(steps))
    body = ops.model.body
    g = np.asarray(getattr(body, "weights", np.zeros(0)), dtype=float)
    tau = np.asarray(getattr(body, "times", np.zeros(0)), dtype=float)
    visco = g.size > 0
    if visco:
        if times is None:
            raise ValueError("a viscoelastic body needs the times of the steps")
        out.time = np.asarray(times, dtype=float).copy()
    weights = np.stack([ops.area, ops.shear_area])
    relaxed = float(1.0 - np.sum(g))
    half_r2 = ops.model.profile.gap(ops.mid)  # the gap before contact, r^2/2 for Hertz
    e_old = np.zeros((2, n))  # elastic-equivalent traction (p, q rows)
    d_old = np.zeros((2, n))  # displacement (w, u rows) = K e_old
    h = np.zeros((g.size, 2, n))
    kh = np.zeros((g.size, 2, n))
    per_dt: dict[float, tuple] = {}
    state = np.zeros(n, dtype=np.int8)
    u_old = np.zeros(n)
    q_old = np.zeros(n)
    cache: dict = {}
    work = external = viscous = 0.0
    p_old = w_old = np.zeros(n)
    hertz_radius = ops.model.frictionless_radius
    last_direction = 0.0  # sign of the last load change (0 before any)
    for i in range(1, steps):
        level = float(levels[i])
        step_ops, step_cache, shift = ops, cache, (None, None)
        if visco:
            # the step's duration to 10 digits: the steps of a segment share it (and one
            # scaled copy of the operators and one factorization cache), although the
            # differences of the times differ in their last bits
            dt = float(f"{out.time[i] - out.time[i - 1]:.10g}")
            if dt not in per_dt:
                if len(per_dt) >= _MAX_DURATIONS:  # bounded memory: drop the oldest
                    per_dt.pop(next(iter(per_dt)))
                a, b, beta = prony_step(g, tau, dt)
                scaled = replace(ops, pw=ops.pw / beta, pu=ops.pu / beta, qw=ops.qw / beta,
                                 qu=ops.qu / beta)
                per_dt[dt] = (a, b, beta, scaled, {}, decay_integrals(dt / tau, scaled=True))
            a, b, beta, step_ops, step_cache, integrals = per_dt[dt]
            sigma_hist = np.tensordot(g * a, h, axes=1) - np.sum(g * b) * e_old
            shift = -(np.tensordot(g * a, kh, axes=1) - np.sum(g * b) * d_old) / beta
        if level == 0.0:
            zero = np.zeros(n)
            if visco:  # no traction: the surface recovers; the indenter just touches it
                delta = float(np.min(shift[0] + half_r2))
                res = StepResult(zero, zero.copy(), shift[1].copy(),
                                 shift[0] - delta + half_r2, delta,
                                 np.zeros(n, dtype=np.int8), True, 0, 0.0)
            else:  # no traction, no displacement (gap r^2/2)
                res = StepResult(zero, zero.copy(), zero.copy(), half_r2.copy(), 0.0,
                                 np.zeros(n, dtype=np.int8), True, 0, 0.0)
        else:
            guess = state
            if not np.any(guess):
                guess = np.where(ops.mid < hertz_radius(level), STICK,
                                 SEPARATED).astype(np.int8)
            res = solve_step(step_ops, k, level * ops.p_max, u_old, guess, max_iter,
                             step_cache, *shift)
        work += step_work(q_old, res.q, res.u - u_old, ops.shear_area,
                          (res.state >= SLIP_INWARD)
                          | ((res.state == SEPARATED) & (state >= SLIP_INWARD)))
        sigma = np.stack([res.p, res.q])
        d = np.stack([res.gap + res.delta - half_r2, res.u])
        if visco:
            e = (sigma - sigma_hist) / beta
            de, dd = e - e_old, d - d_old
            p_mean = mean_traction(relaxed, g, tau, dt, e_old, e, h)[0]
            external += step_external_work(ops.area, p_mean, w_old, d[0])
            viscous += viscous_step_work(weights, g, tau, dt, h, kh, de, dd, integrals)
            h = a[:, None, None] * h + b[:, None, None] * de
            kh = a[:, None, None] * kh + b[:, None, None] * dd
            e_old, d_old = e, d
            out.stored_energy[i] = stored_energy(weights, relaxed, g, e, d, h, kh)
        else:
            external += step_external_work(ops.area, 0.5 * (p_old + res.p), w_old, d[0])
            out.stored_energy[i] = 0.5 * dot(weights, sigma, d)
        out.external_work[i] = external
        out.viscous_work[i] = viscous
        out.p[i], out.q[i], out.u[i] = res.p, res.q, res.u
        out.delta[i] = res.delta
        out.state[i] = res.state
        out.work[i] = work
        a_c = contact_radius(ops, res.state, res.gap)
        out.contact_radius[i] = a_c
        # the first step against the last direction of the load (across any hold between)
        direction = float(np.sign(level - levels[i - 1]))
        turned = direction * last_direction < 0.0
        last_direction = direction or last_direction
        out.stick_radius[i] = stick_radius(ops, k, res.state, res.p, res.q, a_c,
                                           receding=level < float(levels[i - 1]),
                                           fit=not turned) if a_c > 0 else np.nan
        out.converged[i], out.iterations[i] = res.converged, res.iterations
        out.residual[i] = res.residual
        state, u_old, q_old = res.state, res.u, res.q
        p_old, w_old = res.p, d[0]
        if progress is not None:
            progress(i, steps - 1)
    out.work = monotone_work(out.work)  # no step dissipates a negative amount
    return out


# ----------------------------------------------------------------------------- error estimates
def path_interpolate(x: np.ndarray, segment: np.ndarray, x_coarse: np.ndarray,
                     segment_coarse: np.ndarray, values: np.ndarray) -> np.ndarray:
    """Coarse-run values at the fine run's path coordinates, segment by segment.

    Parameters
    ----------
    x, x_coarse : ndarray
        Path coordinate of every step (segments done, so ``i / steps``).
    segment, segment_coarse : ndarray of int
        Path segment of every step (0 for the initial state).
    values : ndarray
        Coarse-run values, one per coarse step (finite).

    Returns
    -------
    ndarray, shape like ``x``
        Linear interpolation within each segment; the fine steps before the
        segment's first coarse step are extrapolated linearly from its first
        two (never across a turning point of the path, where the stick radius
        jumps). The initial state takes the coarse initial state.
    """
    out = np.empty(x.size)
    out[segment == 0] = values[segment_coarse == 0][0]
    for g in np.unique(segment[segment > 0]):
        f, c = segment == g, segment_coarse == g
        xs, ys = x_coarse[c], values[c]
        y = np.interp(x[f], xs, ys)
        if xs.size >= 2:
            lo = x[f] < xs[0]
            y[lo] = ys[0] + (ys[1] - ys[0]) / (xs[1] - xs[0]) * (x[f][lo] - xs[0])
        out[f] = y
    return out


def annulus_resolved(k: float, state: np.ndarray) -> np.ndarray:
    """Per step: the slip zone is absent or spans at least ``MIN_SLIP_ELEMENTS`` elements."""
    slipping = np.count_nonzero(state >= SLIP_INWARD, axis=1)
    if not 0.0 < k < np.inf:
        return np.ones(state.shape[0], dtype=bool)
    return (slipping == 0) | (slipping >= MIN_SLIP_ELEMENTS)


# measured: benchmarks/report_history_estimates.py (coverage and inflation of the
# estimates): steps either side over which a difference is maximised
_WINDOW = 2


def _window_max(values: np.ndarray, segment: np.ndarray, half_width: int = _WINDOW
                ) -> np.ndarray:
    """Largest value within ``half_width`` steps either side, in the same path segment."""
    out = values.copy()
    for shift in range(1, half_width + 1):
        same = segment[shift:] == segment[:-shift]
        out[shift:] = np.where(same, np.maximum(out[shift:], values[:-shift]), out[shift:])
        out[:-shift] = np.where(same, np.maximum(out[:-shift], values[shift:]), out[:-shift])
    return out


def straddle(diff: np.ndarray, a: np.ndarray, segment: np.ndarray, touching: np.ndarray,
              h: float) -> np.ndarray:
    """``diff`` at a fine step inside a jump of the coarse run: at most its neighbours'.

    With half the steps, the coarse run's steps are the fine run's even
    steps, and an odd fine step takes a value interpolated between two coarse
    steps. Where the stick radius jumps between those two (the stick zone
    collapsing near the top of a reloading) the interpolated value lies far
    from either and from the fine value, which has jumped at a step of its
    own: the difference there is no error of the fine run. At such a step
    (a coarse change over the two steps above two fine elements and more
    than twice the coarse changes either side of it, both neighbours in the
    same segment and in contact) the difference is at most the larger of
    the two neighbours', where fine and coarse steps coincide.

    Parameters
    ----------
    diff : ndarray
        |fine - coarse| at every fine step (units of the quantity).
    a : ndarray
        The coarse values at the fine steps (exact at the even steps).
    segment : ndarray of int
        Path segment of every fine step.
    touching : ndarray of bool
        The fine run is in contact at the step.
    h : float
        Fine element size (units a_max).

    Returns
    -------
    ndarray
        ``diff`` with the steps inside a coarse jump lowered.
    """
    out = diff.copy()
    size = diff.size
    i = np.arange(1, size - 1, 2)
    i = i[(segment[i - 1] == segment[i]) & (segment[i + 1] == segment[i])
          & touching[i - 1] & touching[i + 1]]
    centre = np.abs(a[i + 1] - a[i - 1])
    before = np.where(i >= 3, np.abs(a[i - 1] - a[np.maximum(i - 3, 0)]), 0.0)
    after = np.where(i + 3 < size, np.abs(a[np.minimum(i + 3, size - 1)] - a[i + 1]), 0.0)
    jump = (centre > 2.0 * h) & (centre > 2.0 * (before + after))
    j = i[jump]
    out[j] = np.minimum(diff[j], np.maximum(diff[j - 1], diff[j + 1]))
    return out


# measured: benchmarks/report_history_estimates.py. The located stick edge's error is
# about proportional to the element size and changes sign from step to step as the edge
# crosses the elements, so run A's (elements twice as large) is about twice the run's and
# |run - A| lies between 1 and 3 times the run's error: the estimate takes half of it
EDGE_COARSE_RATIO = 2.0
# measured: benchmarks/report_history_estimates.py (steps either side of the local
# quadratic fit whose deviation measures the run's own edge quantization, smooth_deviation)
_SMOOTH_HALF_WIDTH = 6


def smooth_deviation(values: np.ndarray, segment: np.ndarray, fitted: np.ndarray,
                     half_width: int = _SMOOTH_HALF_WIDTH) -> np.ndarray:
    """Each step's deviation from a quadratic fitted to its neighbours (leave one out).

    The stick radius along a path is smooth in the load, while its located value
    carries a quantization error that changes sign from step to step as the edge
    crosses the elements; a step's distance from the least-squares quadratic
    through the other ``fitted`` steps within ``half_width`` steps either side
    (same path segment, at least two on each side: no extrapolation across a
    turning point) measures that error in the run itself.

    Parameters
    ----------
    values : ndarray, shape (S+1,)
        The quantity at every step (units a_max).
    segment : ndarray of int, shape (S+1,)
        Path segment of every step.
    fitted : ndarray of bool, shape (S+1,)
        Steps whose value takes part (a stick radius located below the element
        size); the others get 0.
    half_width : int
        Steps either side.

    Returns
    -------
    ndarray, shape (S+1,)
        ``|value - fit|`` (units of ``values``); 0 where the step is not
        ``fitted`` or has fewer than two fitted neighbours on a side.
    """
    size = values.size
    offsets = np.concatenate([np.arange(-half_width, 0), np.arange(1, half_width + 1)])
    idx = np.arange(size)[:, None] + offsets[None, :]
    inside = (idx >= 0) & (idx < size)
    idx = np.clip(idx, 0, size - 1)
    use = inside & fitted[idx] & (segment[idx] == segment[:, None]) & fitted[:, None]
    enough = (np.sum(use & (offsets < 0), axis=1) >= 2) & (np.sum(use & (offsets > 0), axis=1)
                                                           >= 2)
    t = offsets[None, :] / float(half_width)  # scaled abscissa: a well-conditioned system
    w = use.astype(float)
    moments = np.stack([np.sum(w * t**m, axis=1) for m in range(5)], axis=1)
    normal = moments[:, [[0, 1, 2], [1, 2, 3], [2, 3, 4]]]  # (S+1, 3, 3)
    rhs = np.stack([np.sum(w * t**m * values[idx], axis=1) for m in range(3)], axis=1)
    out = np.zeros(size)
    rows = np.flatnonzero(enough)
    if rows.size:
        coef = np.linalg.solve(normal[rows], rhs[rows][:, :, None])[:, 0, 0]
        out[rows] = np.abs(values[rows] - coef)
    return out


def _lead_from_first(diff: np.ndarray, x: np.ndarray, segment: np.ndarray,
                     x_coarse: np.ndarray, segment_coarse: np.ndarray) -> np.ndarray:
    """``diff`` at the fine steps before a segment's first coarse step: the difference at
    the first fine step that the coarse run reaches.

    There :func:`path_interpolate` extrapolates the coarse run from its first two steps
    of the segment. Right after a turning point the stick radius falls with a slope that
    is unbounded at the turn (the reverse slip zone spreading in from the contact edge),
    so that extrapolation is no estimate of anything (the sphere at k = 0.2, n = 240, the
    first step of the unloading: 1.2 elements, against a true error of 0.18 at most in
    that segment).
    """
    out = diff.copy()
    for g in np.unique(segment[segment > 0]):
        fine_steps = np.flatnonzero(segment == g)
        coarse_x = x_coarse[segment_coarse == g]
        if coarse_x.size == 0:
            continue
        reached = x[fine_steps] >= coarse_x[0] - 1e-12
        if reached.any() and not reached.all():
            out[fine_steps[~reached]] = diff[fine_steps[reached][0]]
    return out


def measured_order(fine: np.ndarray, coarse: np.ndarray, coarser: np.ndarray) -> float:
    """Order of convergence of one quantity measured from three runs refined twofold each.

    Parameters
    ----------
    fine, coarse, coarser : ndarray
        The quantity at the same points of the path (steps that all three
        runs have) from runs with (n, S), (n/2, S/2) and (n/4, S/4) elements
        and steps a segment.

    Returns
    -------
    float
        ``log2(max|coarse - coarser| / max|fine - coarse|)``, kept within
        ``[ORDER_MIN, ORDER_MAX]``; ``ORDER_MIN`` where the fine difference
        does not shrink or a difference is not finite (no asymptotic
        convergence seen: the estimate then takes the slowest order).
    """
    d1 = float(np.max(np.abs(fine - coarse), initial=0.0))
    d2 = float(np.max(np.abs(coarse - coarser), initial=0.0))
    if not (np.isfinite(d1) and np.isfinite(d2)) or d1 <= 0.0 or d2 <= d1:
        return ORDER_MIN if not d1 == d2 == 0.0 else ORDER_MAX
    return float(np.clip(np.log2(d2 / d1), ORDER_MIN, ORDER_MAX))


def error_estimates(fine: RawHistory, ops: Operators, steps: int, segment: np.ndarray,
                    coarse: RawHistory, steps_coarse: int, segment_coarse: np.ndarray,
                    coarser: RawHistory | None = None, steps_coarser: int | None = None,
                    segment_coarser: np.ndarray | None = None,
                    energies: tuple[str, ...] = ()
                    ) -> tuple[np.ndarray, dict[str, np.ndarray], dict[str, float]]:
    """Per-step error estimates of the stick radius, the cumulative work and the energies.

    ``coarse`` (A) is the same path with about n/2 elements and half the
    steps; ``coarser`` (C), if given, the path with about n/4 elements and a
    quarter of the steps. Both are interpolated onto the fine run's (F)
    steps by path coordinate (:func:`path_interpolate`).

    The work and the energies: with C, their order of convergence under the
    joint refinement of mesh and steps, ``p``, is measured from the three
    runs at the steps they share (:func:`measured_order`), and the error of
    F is ``|F - A| / (2^p - 1)`` (Richardson: an error ``E h^p`` leaves
    ``F - A = E h^p (1 - 2^p)``). The cumulative work of a cycle converges
    about like the second power of the element size and of the step (the
    floored trapezoid rule, :func:`contactlib.energy.step_work`); assuming
    first order had overstated its error 3-4 fold. Without C (fewer than
    40 steps a segment, :func:`contactlib.history`) the order is taken as 1 and the
    estimate is ``|F - A|``. The stick radius takes ``|F - A| /``
    :data:`EDGE_COARSE_RATIO` where its edge crosses an element within
    ``_SMOOTH_HALF_WIDTH`` steps either side (or is an element edge), and at
    least the run's own deviation from a smooth path there
    (:func:`smooth_deviation`: a quadratic through the neighbouring steps,
    kept below half an element). The located edge's error is about
    proportional to the element size and changes sign from step to step as
    the edge crosses the elements; A's is about twice the run's, so ``|F -
    A|`` is 1 ... 3 times the run's error (taken in full it was 1.7 ... 9.9
    times a segment's largest error at n = 120; now 0.97 ... 4.6, 9.9 on a
    stick zone whose edge crosses no element, and at least 0.50 of the error
    at every step, ``benchmarks/report_history_estimates.py``). Where the
    edge crosses no element (a stick zone over a few elements) ``|F - A|``
    is a bias and is taken in full (order 1). Where A's stick radius jumps
    between two of its steps (the stick zone collapsing near the top of a
    reloading) the fine steps in between take at most their neighbours'
    difference (:func:`straddle`): the interpolated coarse value there is
    no estimate of anything, and it had inflated the estimate 12-fold. For
    the same reason the fine steps before a segment's first coarse step take
    the difference at the first step that A reaches (right after a turning
    point, where A is extrapolated: :func:`_lead_from_first`).

    Each estimate is the largest within two steps either side (same path
    segment). The stick radius is an element edge wherever its sub-element
    fit does not apply (see :func:`stick_radius`): there its error is up to
    half an element whatever the differences say (the coarse edges are fine
    edges too, so they vanish by coincidence), and its difference counts as
    at least ``h / 2`` (h = element size, after the division by
    :data:`EDGE_COARSE_RATIO`), also in its neighbours' windows
    (a fit next to two edges that coincide with the coarse run's had an
    estimate of 2e-16 against an error of 0.29 of an element). A fit kept at
    the midpoint of the first element not stuck is not such a fallback: its
    error is the fit's, which the differences measure (the cylinder at k =
    0.3, n = 240: 0.065 of an element at the top, where the floor had made
    the estimate 7.7 times it).

    Parameters
    ----------
    fine : RawHistory
        The run whose errors are estimated.
    ops : Operators
        Its operators (for the element size).
    steps : int
        Its steps a segment.
    segment : ndarray of int
        Its path segment of every step.
    coarse, steps_coarse, segment_coarse
        Run A, its steps a segment and segments.
    coarser, steps_coarser, segment_coarser
        Run C, its steps a segment and segments (optional).
    energies : tuple of str
        Further cumulative energies of :class:`RawHistory` (``external_work``,
        ``stored_energy``, ``viscous_work``) estimated as the work is.

    Returns
    -------
    (stick_radius_error, energy_errors, orders)
        Absolute error of the stick radius in units of a_max (0 without
        contact); a dict of the absolute errors of ``work`` and of each of
        ``energies`` (units of the work; ``inf`` where a value of any run
        is not finite), which the caller scales (:func:`contactlib.history`);
        and a dict of the orders ``p`` used, with ``stick_radius`` 1.
    """
    x = np.arange(segment.size) / steps

    def coarse_values(run: RawHistory, n_steps: int, seg: np.ndarray,
                      name: str) -> np.ndarray:
        values = getattr(run, name)
        return path_interpolate(x, segment, np.arange(seg.size) / n_steps, seg,
                                np.nan_to_num(values) if name == "stick_radius" else values)

    def estimate(name: str) -> tuple[np.ndarray, float]:
        f = getattr(fine, name)
        if name == "stick_radius":
            f = np.nan_to_num(f)  # no contact: no stick zone
        a = coarse_values(coarse, steps_coarse, segment_coarse, name)
        diff = np.abs(f - a)
        if name == "stick_radius":  # an edge's difference may vanish by coincidence
            # the edge crosses an element within the fit's window: A's error is its
            # quantization, twice the run's; else (a stick zone over a few elements, its
            # edge standing) the difference is a bias, the run's in full (order 1)
            span = (_window_max(f, segment, _SMOOTH_HALF_WIDTH)
                    + _window_max(-f, segment, _SMOOTH_HALF_WIDTH))
            diff = np.where(on_edge | (span >= h), diff / EDGE_COARSE_RATIO, diff)
            diff = np.where(on_edge, np.maximum(diff, 0.5 * h), diff)
            if steps == 2 * steps_coarse:
                diff = straddle(diff, a, segment, fine.contact_radius > 0, h)
            diff = _lead_from_first(diff, x, segment, np.arange(segment_coarse.size)
                                    / steps_coarse, segment_coarse)
            located = ~on_edge & (f > 0.0) & (f < fine.contact_radius)
            # at most half an element: a larger deviation is the path's own kink (the stick
            # zone collapsing near the end of an unloading), which |F - A| measures
            own = np.minimum(smooth_deviation(f, segment, located), 0.5 * h)
            return np.maximum(_window_max(diff, segment), _window_max(own, segment)), 1.0
        if coarser is None:
            return _window_max(diff, segment), 1.0
        common = (np.arange(segment.size) * steps_coarser) % steps == 0  # C's own steps
        c = coarse_values(coarser, steps_coarser, segment_coarser, name)
        p = measured_order(f[common], a[common], c[common])
        return _window_max(diff, segment) / (2.0**p - 1.0), p

    c_fine = np.nan_to_num(fine.stick_radius)
    h = float(ops.edges[1] - ops.edges[0])
    # stick_radius's fallback is an element edge (a value kept at the midpoint of the first
    # element not stuck is a fit that overshot it, whose error the differences measure)
    edges = ops.edges
    k_right = np.clip(np.searchsorted(edges, c_fine), 1, edges.size - 1)
    on_edge = ((np.minimum(np.abs(c_fine - edges[k_right - 1]), np.abs(c_fine - edges[k_right]))
                <= 1e-12) & (c_fine < fine.contact_radius))
    err_c, orders = estimate("stick_radius")[0], {"stick_radius": 1.0}
    err_c = np.where(on_edge, np.maximum(err_c, 0.5 * h), err_c)
    err_c[np.isnan(fine.stick_radius)] = 0.0
    diffs = {}
    with np.errstate(invalid="ignore"):
        for name in ("work",) + tuple(energies):
            d, orders[name] = estimate(name)
            diffs[name] = np.where(np.isfinite(d), d, np.inf)  # a NaN is never small
    return err_c, diffs, orders
