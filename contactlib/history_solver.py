r"""Incremental stick-slip solver for an arbitrary normal load path (numerics only).

The public entry point is :func:`contactlib.history.history`; this module holds
the discretization, the per-step active-set solver and the post-processing of
one state. It never touches the disk.

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
logarithmic kernel singularities are not met).

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
Each step is a linear complementarity problem with a non-symmetric
(Coulomb) coupling, solved by a primal-dual active-set iteration: for given
sets (separated / stick / slip inward / slip outward) the conditions are one
linear system in the pressures and shears of the contact elements and
``delta`` (size ``2 m + 1``), solved by LU; then the sets are updated
element by element:

* separated -> contact if ``g_i < 0``; contact -> separated if ``p_i < 0``;
* stick -> slip (in the direction that makes ``q`` the friction force) if
  ``|q_i| > k p_i``;
* slip -> stick if the slip increment runs the wrong way (``q_i du_i > 0``);
* an element touching down starts slipping against its current increment.

The iteration stops when the sets reproduce themselves, i.e. every condition
holds. A set that repeats (a cycle) switches the update to one change at a
time (the largest violation first); after ``max_iter`` iterations the step is
kept and flagged as not converged, with its residual.

The slip->stick rule is the classical one of Kalker's active-set algorithms;
it is the limit of the semi-smooth Newton method on
``q - proj_[-kp, kp](q - eps du) = 0`` with a small ``eps``, and was found
free of the cycling the larger ``eps`` produces when many elements touch down
in one step.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import linalg

from .geometry import Geometry

__all__ = ["SEPARATED", "STICK", "SLIP_INWARD", "SLIP_OUTWARD", "STATE_MEANINGS",
           "Operators", "StepResult", "build_operators", "solve_step", "contact_radius",
           "stick_radius", "MESH_EXTENT", "RawHistory", "run_history", "hertz_radius"]

SEPARATED, STICK, SLIP_INWARD, SLIP_OUTWARD = 0, 1, 2, 3
STATE_MEANINGS = "separated stick slip_inward slip_outward"
MESH_EXTENT = 1.2  # mesh length over a_max

_REL_TOL = 1e-10  # set-switching tolerance relative to the current scales


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

    @property
    def n(self) -> int:
        return self.mid.size


def build_operators(geometry: Geometry, n: int, extent: float = MESH_EXTENT) -> Operators:
    """Influence matrices of ``n`` equal elements over ``[0, extent]`` (vectorised)."""
    edges = np.linspace(0.0, extent, n + 1)
    mid = 0.5 * (edges[:-1] + edges[1:])
    x = np.broadcast_to(mid[:, None], (n, n + 1))
    s = np.broadcast_to(edges[None, :], (n, n + 1))
    wp, up, _ = geometry.pressure_kernel(x, s)
    wq, uq, _ = geometry.shear_kernel(x, s)
    shape = geometry.shear_shape(mid)  # r (sphere) or 1 (cylinder)
    if geometry.name == "sphere":
        area = np.pi * np.diff(edges**2)
        shear_area = (2.0 * np.pi / 3.0) * np.diff(edges**3) / mid
    else:
        area = 2.0 * np.diff(edges)
        shear_area = area.copy()
    return Operators(edges=edges, mid=mid, area=area, shear_area=shear_area,
                     pw=np.diff(wp, axis=1), pu=np.diff(up, axis=1),
                     qw=np.diff(wq, axis=1) / shape[None, :],
                     qu=np.diff(uq, axis=1) / shape[None, :],
                     p_max=float(geometry.hertz_load), p0=float(geometry.p0))


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
    system_size: int  # size of the last linear system solved


def _assemble(ops: Operators, k: float, load: float, u_old: np.ndarray,
              state: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Linear system of the conditions for the given sets; unknowns (p_c, q_c, delta)."""
    c = np.flatnonzero(state)
    m = c.size
    a = np.zeros((2 * m + 1, 2 * m + 1))
    b = np.zeros(2 * m + 1)
    # normal: w_i - delta = -r_i^2 / 2 on the contact elements
    a[:m, :m] = ops.pw[np.ix_(c, c)]
    a[:m, m:2 * m] = ops.qw[np.ix_(c, c)]
    a[:m, 2 * m] = -1.0
    b[:m] = -0.5 * ops.mid[c] ** 2
    st = state[c]
    rows = m + np.arange(m)
    if k == 0.0:  # frictionless: q = 0
        a[rows, rows] = 1.0
    else:
        stick = np.flatnonzero(st == STICK)
        a[np.ix_(rows[stick], np.arange(m))] = ops.pu[np.ix_(c[stick], c)]
        a[np.ix_(rows[stick], m + np.arange(m))] = ops.qu[np.ix_(c[stick], c)]
        b[rows[stick]] = u_old[c[stick]]
        for code, sign in ((SLIP_INWARD, 1.0), (SLIP_OUTWARD, -1.0)):
            sel = np.flatnonzero(st == code)
            a[rows[sel], m + sel] = 1.0
            a[rows[sel], sel] = -sign * k
    a[2 * m, :m] = ops.area[c]
    b[2 * m] = load
    return a, b, c


def _violations(ops: Operators, k: float, state: np.ndarray, p: np.ndarray, q: np.ndarray,
                du: np.ndarray, gap: np.ndarray) -> tuple[np.ndarray, np.ndarray, float]:
    """Proposed new sets, the size of each element's violation, and the residual.

    Violations are scaled by the current pressure and displacement scales; the
    residual is the largest scaled violation of any condition (complementarity,
    sign and Coulomb), including those the current sets impose as equalities.
    """
    p_scale = max(float(np.max(np.abs(p))), 1e-300)
    g_scale = max(float(np.max(ops.mid[state > 0] ** 2)) if np.any(state > 0) else 0.0,
                  float(np.max(np.abs(gap))), 1e-300)
    d_scale = max(float(np.max(np.abs(du))), 1e-300)
    tol_p, tol_g, tol_d = _REL_TOL * p_scale, _REL_TOL * g_scale, _REL_TOL * d_scale
    new = state.copy()
    viol = np.zeros(state.size)
    contact = state > 0

    # normal sets
    lose = contact & (p < -tol_p)
    gain = ~contact & (gap < -tol_g)
    new[lose] = SEPARATED
    viol[lose] = -p[lose] / p_scale
    viol[gain] = -gap[gain] / g_scale
    if k == 0.0 or np.isinf(k):
        new[gain] = SLIP_INWARD if k == 0.0 else STICK
    else:  # touching down: slip against the current increment
        new[gain] = np.where(du[gain] > 0.0, SLIP_OUTWARD, SLIP_INWARD)

    stay = contact & ~lose
    if k == 0.0:
        pass  # q = 0 everywhere; the slip direction is labelled afterwards
    elif np.isinf(k):
        new[stay] = STICK
    else:
        kp = k * np.maximum(p, 0.0)
        stick = stay & (state == STICK)
        over = stick & (np.abs(q) > kp + k * tol_p)
        new[over & (q > 0)] = SLIP_INWARD
        new[over & (q < 0)] = SLIP_OUTWARD
        viol[over] = (np.abs(q[over]) - kp[over]) / p_scale
        wrong_in = stay & (state == SLIP_INWARD) & (du > tol_d)
        wrong_out = stay & (state == SLIP_OUTWARD) & (du < -tol_d)
        wrong = wrong_in | wrong_out
        new[wrong] = STICK
        viol[wrong] = np.abs(du[wrong]) / d_scale

    # residual of every condition (the equalities of the current sets included)
    res = 0.0
    if np.any(contact):
        res = max(res, float(np.max(np.abs(gap[contact]))) / g_scale,
                  float(np.max(np.maximum(-p[contact], 0.0))) / p_scale)
    if np.any(~contact):
        res = max(res, float(np.max(np.maximum(-gap[~contact], 0.0))) / g_scale,
                  float(np.max(np.abs(p[~contact]) + np.abs(q[~contact]))) / p_scale)
    if k > 0.0 and np.any(contact):
        kp = k * np.maximum(p, 0.0) if np.isfinite(k) else np.full(p.size, np.inf)
        st = contact & (state == STICK)
        if np.any(st):
            res = max(res, float(np.max(np.abs(du[st]))) / d_scale,
                      float(np.max(np.maximum(np.abs(q[st]) - kp[st], 0.0))) / p_scale)
        sl = contact & (state >= SLIP_INWARD)
        if np.any(sl):
            res = max(res, float(np.max(np.abs(np.abs(q[sl]) - kp[sl]))) / p_scale,
                      float(np.max(np.maximum(q[sl] * du[sl], 0.0))) / (p_scale * d_scale))
    return new, viol, res


def solve_step(ops: Operators, k: float, load: float, u_old: np.ndarray,
               guess: np.ndarray, max_iter: int = 200) -> StepResult:
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
    """
    state = guess.astype(np.int8, copy=True)
    if not np.any(state):
        state[0] = STICK
    if k == 0.0:
        state[state > 0] = SLIP_INWARD
    seen: set[bytes] = {state.tobytes()}
    one_at_a_time = False
    p = q = u = gap = np.zeros(ops.n)
    delta, res, size = 0.0, np.inf, 0
    for it in range(1, max_iter + 1):
        a, b, c = _assemble(ops, k, load, u_old, state)
        size = b.size
        x = linalg.solve(a, b, check_finite=False)
        m = c.size
        p = np.zeros(ops.n)
        q = np.zeros(ops.n)
        p[c], q[c], delta = x[:m], x[m:2 * m], float(x[2 * m])
        w = ops.pw @ p + ops.qw @ q
        u = ops.pu @ p + ops.qu @ q
        gap = w - delta + 0.5 * ops.mid**2
        du = u - u_old
        new, viol, res = _violations(ops, k, state, p, q, du, gap)
        if np.array_equal(new, state):
            return StepResult(p, q, u, gap, delta, _label(k, state, du), True, it, res, size)
        if one_at_a_time or new.tobytes() in seen:
            # a cycle: from now on change one element at a time, largest violation first
            one_at_a_time = True
            i = int(np.argmax(np.where(new != state, viol, -1.0)))
            nxt = state.copy()
            nxt[i] = new[i]
            new = nxt
        seen.add(new.tobytes())
        state = new
    return StepResult(p, q, u, gap, delta, _label(k, state, u - u_old), False, max_iter, res,
                      size)


def _label(k: float, state: np.ndarray, du: np.ndarray) -> np.ndarray:
    """Final state labels; frictionless contact elements are labelled by their slip."""
    out = state.copy()
    if k == 0.0:
        contact = state > 0
        tol = _REL_TOL * max(float(np.max(np.abs(du))), 1e-300)
        out[contact] = STICK
        out[contact & (du < -tol)] = SLIP_INWARD
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
                 a: float) -> float:
    """Radius of the central stick zone (units a_max) with sub-element resolution.

    The central stick zone is the run of stuck elements from the axis. If it
    reaches the contact edge the result is ``a``; if the axis element is not
    stuck it is 0. Otherwise its edge is refined from the traction deficit
    ``d = 1 - |q|/(k p)`` of the last two stuck elements: at a stick edge whose
    stick traction has no stress-intensity factor (the physical condition of
    continued loading) ``d`` grows like ``(c - r)^(3/2)``, so ``d^(2/3)`` is
    extrapolated linearly to zero; the result is kept between the midpoint of
    the last stuck element and that of the first slipping one (else the
    element edge is returned).
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
    if j < 2 or not np.isfinite(k) or k <= 0.0:
        return edge
    with np.errstate(divide="ignore", invalid="ignore"):
        d1 = 1.0 - abs(q[j - 1]) / (k * p[j - 1])
        d2 = 1.0 - abs(q[j - 2]) / (k * p[j - 2])
    if not (np.isfinite(d1) and np.isfinite(d2) and d2 > d1 >= 0.0):
        return edge
    t1, t2 = d1 ** (2.0 / 3.0), d2 ** (2.0 / 3.0)
    c = r[j - 1] + t1 * (r[j - 1] - r[j - 2]) / (t2 - t1)
    return float(np.clip(c, r[j - 1], r[j]))


@dataclass
class RawHistory:
    """Every step of a history (row 0: the unloaded initial state), units a_max = 1."""

    load: np.ndarray  # (S+1,) P / P_max
    p: np.ndarray  # (S+1, n)
    q: np.ndarray
    u: np.ndarray
    delta: np.ndarray  # (S+1,)
    state: np.ndarray  # (S+1, n) int8
    work: np.ndarray  # (S+1,) cumulative frictional work
    work_implicit: np.ndarray  # (S+1,) same with end-of-step tractions (diagnostic)
    contact_radius: np.ndarray  # (S+1,)
    stick_radius: np.ndarray  # (S+1,)
    converged: np.ndarray  # (S+1,) bool
    iterations: np.ndarray  # (S+1,) int
    residual: np.ndarray  # (S+1,)
    system_size: np.ndarray  # (S+1,) int


def hertz_radius(geometry: str, level: float) -> float:
    """Frictionless contact radius at load level P/P_max (units a_max)."""
    return float(level ** (1.0 / 3.0) if geometry == "sphere" else np.sqrt(level))


def run_history(ops: Operators, geometry: str, k: float, levels: np.ndarray,
                progress=None, max_iter: int = 200) -> RawHistory:
    """Follow the load levels ``levels`` (P/P_max; ``levels[0]`` must be 0).

    Frictional work of a step: ``sum |(q_old + q_new)/2| |du| A_j`` over the
    elements slipping at the end of the step (trapezoid in time; stuck
    elements have ``du = 0``, and an element that separates releases its
    traction without slip under load). ``work_implicit`` uses the end-of-step
    traction instead (the dissipation of the implicit step), as a check.
    """
    levels = np.asarray(levels, dtype=float)
    steps = levels.size
    n = ops.n
    z = np.zeros((steps, n))
    out = RawHistory(levels.copy(), z.copy(), z.copy(), z.copy(), np.zeros(steps),
                     np.zeros((steps, n), dtype=np.int8), np.zeros(steps), np.zeros(steps),
                     np.zeros(steps), np.full(steps, np.nan), np.ones(steps, dtype=bool),
                     np.zeros(steps, dtype=np.int64), np.zeros(steps),
                     np.zeros(steps, dtype=np.int64))
    state = np.zeros(n, dtype=np.int8)
    u_old = np.zeros(n)
    q_old = np.zeros(n)
    work = work_imp = 0.0
    for i in range(1, steps):
        level = float(levels[i])
        if level == 0.0:
            res = StepResult(np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n), 0.0,
                             np.zeros(n, dtype=np.int8), True, 0, 0.0, 0)
        else:
            guess = state
            if not np.any(guess):
                guess = np.where(ops.mid < hertz_radius(geometry, level), STICK,
                                 SEPARATED).astype(np.int8)
            res = solve_step(ops, k, level * ops.p_max, u_old, guess, max_iter)
        du = res.u - u_old
        slipping = res.state >= SLIP_INWARD
        work += float(np.sum((np.abs(0.5 * (q_old + res.q)) * np.abs(du)
                              * ops.shear_area)[slipping]))
        work_imp += float(np.sum((np.abs(res.q) * np.abs(du) * ops.shear_area)[slipping]))
        out.p[i], out.q[i], out.u[i] = res.p, res.q, res.u
        out.delta[i] = res.delta
        out.state[i] = res.state
        out.work[i], out.work_implicit[i] = work, work_imp
        a = contact_radius(ops, res.state, res.gap)
        out.contact_radius[i] = a
        out.stick_radius[i] = stick_radius(ops, k, res.state, res.p, res.q, a) if a > 0 \
            else np.nan
        out.converged[i], out.iterations[i] = res.converged, res.iterations
        out.residual[i], out.system_size[i] = res.residual, res.system_size
        state, u_old, q_old = res.state, res.u, res.q
        if progress is not None:
            progress(i, steps - 1)
    return out
