r"""Fretting of the cylinder: a tangential load on top of the normal one (numerics only).

The public entry point is :func:`contactlib.fretting` (module
:mod:`contactlib.fretting_api`); this module holds the discretization and the
incremental solver. It never touches the disk.

Units and scalings
------------------
As for :mod:`contactlib.solvers.history_solver`: E* = R = 1 and lengths in units of
``a_max``, the frictionless contact half-width at the reference load ``P_max``
(the profile's frictionless load at ``a = 1``: ``pi/4`` per unit length for the
paraboloid, Hertz's cylinder). The pressure unit is ``p0`` (1/2 for the
paraboloid), displacements are in ``a_max^2/R`` and work in ``E* a_max^4/R^2``
per unit length. The tangential force ``Q`` is per unit length, like ``P``.

The body (half-plane, plane strain) and the indenter are elastic or rigid; the
pair enters through the composite modulus (E* = 1) and Dundurs' beta
(:attr:`contactlib.model.Contact.beta`).

Kernels
-------
The strip ``-L <= x <= L`` (``L = 1.2 a_max``) carries ``n`` equal elements
of constant pressure ``p_j`` and shear ``q_j`` (the traction the indenter
exerts on the body, along +x). The relative surface displacements (body
minus indenter) at the midpoints are (Johnson 1985, eq. 2.19, two bodies)

.. math::

    w(x) = -\frac{2}{\pi}\int p(\xi)\ln|x-\xi|\,d\xi
           + \beta\int q(\xi)\,\mathrm{sgn}(x-\xi)\,d\xi, \qquad
    u(x) = -\frac{2}{\pi}\int q(\xi)\ln|x-\xi|\,d\xi
           - \beta\int p(\xi)\,\mathrm{sgn}(x-\xi)\,d\xi,

``w`` positive into the bodies (closing the gap), ``u`` along +x. The
logarithm's datum (unit distance = a_max) is the half-plane's free rigid-body
term; it moves the approach ``delta`` and the rigid shift ``s`` by amounts
proportional to ``P`` and ``Q``, never a stick-slip state, a traction or an
energy dissipated. Both integrals over an element are closed forms
(:func:`strip_operators`), and the matrices are symmetric in the sense of
Betti's theorem (``u`` under ``p`` is ``w`` under ``q`` transposed).

A bulk stress ``sigma`` along x in the body (a fretting-fatigue specimen under
tension) adds the body's uniform strain ``c2 sigma`` to ``du/dx`` (``c2`` the
body's share of the compliance, :attr:`contactlib.model.Contact.compliance_weights`;
plane strain), i.e. ``c2 sigma x`` to ``u``.

Conditions at the midpoints
---------------------------
* normal: gap ``g_i = w_i - delta + h(x_i) >= 0``, ``p_i >= 0``, ``p_i g_i = 0``,
  with ``h`` the profile (``x^2/2``) and the load ``sum p_j dx = P`` given;
* tangential: the slip ``v_i = u_i + c2 sigma x_i - s`` (``s`` the indenter's
  rigid shift) and its increment ``dv_i`` over the step; stick ``dv_i = 0``,
  ``|q_i| <= k p_i``; slip ``q_i = -k p_i sgn(dv_i)``; the force
  ``sum q_j dx = Q`` given (force control), which fixes ``s``.

Each step is solved by the same primal-dual active-set iteration as
:mod:`contactlib.solvers.history_solver` (Kalker's switching rules): for given sets
the conditions are one linear system, solved by LU; an element moves between
sets where its condition fails; a repeated set switches to one change at a
time. The frictional dissipation of a step is ``sum k p_i |dv_i| dx`` over
the elements slipping at the step's end, with ``p_i`` the mean of its values at
the step's ends (the trapezoid rule, second order in the step: the end-of-step
pressure alone overestimated a monotonic loading's work by 17 % with 40 steps),
non-negative by construction.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from scipy import linalg

from ..model import Contact
from ..model.profiles import Profile

__all__ = ["SEPARATED", "STICK", "SLIP_POSITIVE", "SLIP_NEGATIVE", "STATE_MEANINGS",
           "MESH_EXTENT", "StripOperators", "strip_operators", "FrettingStep",
           "solve_step", "zone_edges", "RawFretting", "run_fretting"]

SEPARATED, STICK, SLIP_POSITIVE, SLIP_NEGATIVE = 0, 1, 2, 3
STATE_MEANINGS = "separated stick slip_positive_shear slip_negative_shear"
# convention: the mesh reaches 20 % beyond the largest contact (as history_solver's)
MESH_EXTENT = 1.2  # mesh half-length over a_max
# tested: tests/test_fretting.py (Cattaneo's stick ratio and traction)
_REL_TOL = 1e-10  # set-switching tolerance relative to the current scales
# convention: a step not settled in 100 set switches is reported as not converged
_MAX_ITER = 100


@dataclass(frozen=True)
class StripOperators:
    """Influence matrices of the full strip (units E* = R = a_max = 1).

    Attributes
    ----------
    edges : ndarray, shape (n + 1,)
        Element edges, ``-L`` to ``L``.
    mid : ndarray, shape (n,)
        Midpoints (collocation points).
    width : float
        Element width ``2 L / n``.
    pw, qw, pu, qu : ndarray, shape (n, n)
        w and u at midpoint i of a unit pressure / unit shear on element j.
    gap0 : ndarray, shape (n,)
        The profile's gap ``h(x_i)`` at the midpoints.
    p_max, p0 : float
        Reference load (per unit length) and pressure unit.
    strain_share : float
        c2: the body's share of the compliance (its strain under a bulk
        stress ``sigma`` in units E* is ``c2 sigma``).
    beta : float
        Dundurs' beta of the pair.
    exponent : float
        The profile's exponent d (``h = |x|^d/d``; 2: the paraboloid).
    shape : Profile
        The profile itself (its frictionless half-width at a load).
    """

    edges: np.ndarray
    mid: np.ndarray
    width: float
    pw: np.ndarray
    qw: np.ndarray
    pu: np.ndarray
    qu: np.ndarray
    gap0: np.ndarray
    p_max: float
    p0: float
    strain_share: float
    beta: float
    exponent: float
    shape: Profile

    @property
    def n(self) -> int:
        return self.mid.size


def _log_integral(t: np.ndarray) -> np.ndarray:
    """t ln|t| - t (0 at t = 0): an antiderivative of ln|t|."""
    with np.errstate(divide="ignore", invalid="ignore"):
        out = t * np.log(np.abs(t)) - t
    return np.where(t == 0.0, 0.0, out)


def strip_operators(model: Contact, n: int, extent: float = MESH_EXTENT,
                    offset: float = 0.0) -> StripOperators:
    """Influence matrices of ``n`` equal elements over ``[-extent, extent]`` (units a_max).

    Parameters
    ----------
    model : Contact
        A cylinder on a half-plane (the composite modulus is the unit; the
        pair's Dundurs beta couples the normal and tangential problems).
    n : int
        Number of elements (even, so that no midpoint lies on the axis).
    extent : float
        Half-length of the mesh over a_max.
    offset : float
        The mesh's shift along x, in elements (0: symmetric about the axis; 1/2 moves
        every element edge by half an element, which changes where the zone edges fall
        within their elements and nothing else: the error estimates use it).

    Returns
    -------
    StripOperators
    """
    edges = np.linspace(-extent, extent, n + 1) + offset * (2.0 * extent / n)
    mid = 0.5 * (edges[:-1] + edges[1:])
    d_lo = mid[:, None] - edges[None, :-1]
    d_hi = mid[:, None] - edges[None, 1:]
    log_part = -(2.0 / np.pi) * (_log_integral(d_lo) - _log_integral(d_hi))
    sign_part = np.abs(d_lo) - np.abs(d_hi)  # int over the element of sgn(x - xi)
    beta = float(model.beta) if not model.decoupled else 0.0
    prof = model.profile
    p_max = float(prof.frictionless_load(False))
    return StripOperators(edges=edges, mid=mid, width=float(edges[1] - edges[0]),
                          pw=log_part, qw=beta * sign_part, pu=-beta * sign_part,
                          qu=log_part, gap0=prof.gap(np.abs(mid)), p_max=p_max,
                          p0=float(prof.reference_pressure(False)),
                          strain_share=float(model.compliance_weights[1]), beta=beta,
                          exponent=float(prof.exponent), shape=prof)


@dataclass
class FrettingStep:
    """The solution of one load step (units E* = R = a_max = 1).

    ``v`` is the slip displacement (body minus indenter, the rigid shift and
    the bulk strain included); ``delta`` the approach and ``shift`` the
    indenter's rigid tangential displacement ``s``.
    """

    p: np.ndarray
    q: np.ndarray
    v: np.ndarray
    gap: np.ndarray
    delta: float
    shift: float
    state: np.ndarray
    converged: bool
    iterations: int


def _solve_sets(ops: StripOperators, k: float, state: np.ndarray, load: float, force: float,
                strain: float, v_old: np.ndarray, shift_old: float) -> tuple[np.ndarray, ...]:
    """p, q, delta, s for given sets (one linear system)."""
    n = ops.n
    contact = np.flatnonzero(state != SEPARATED)
    stick = np.flatnonzero(state == STICK)
    slip = state >= SLIP_POSITIVE
    sgn = np.where(state == SLIP_POSITIVE, 1.0, np.where(state == SLIP_NEGATIVE, -1.0, 0.0))
    # the slip shears q_j = sgn_j k p_j fold into the pressure columns
    fold = np.where(slip, sgn * k, 0.0)
    pw_eff = ops.pw[:, contact] + ops.qw[:, contact] * fold[contact]
    pu_eff = ops.pu[:, contact] + ops.qu[:, contact] * fold[contact]
    nc, nt = contact.size, stick.size
    size = nc + nt + 2
    a = np.zeros((size, size))
    b = np.zeros(size)
    h = ops.width
    # contact rows: w_i - delta = -gap0_i
    a[:nc, :nc] = pw_eff[contact]
    a[:nc, nc:nc + nt] = ops.qw[np.ix_(contact, stick)]
    a[:nc, -2] = -1.0
    b[:nc] = -ops.gap0[contact]
    # stick rows: u_i + strain x_i - s = v_old_i
    a[nc:nc + nt, :nc] = pu_eff[stick]
    a[nc:nc + nt, nc:nc + nt] = ops.qu[np.ix_(stick, stick)]
    a[nc:nc + nt, -1] = -1.0
    b[nc:nc + nt] = v_old[stick] - strain * ops.mid[stick]
    # load and force
    a[-2, :nc] = h
    b[-2] = load
    a[-1, :nc] = h * fold[contact]
    a[-1, nc:nc + nt] = h
    b[-1] = force
    if nt == 0:  # no stuck element: the shift is free (the force is checked by the caller)
        a[-1, :] = 0.0
        a[-1, -1] = 1.0
        b[-1] = shift_old
    x = linalg.solve(a, b, check_finite=False)
    p = np.zeros(n)
    q = np.zeros(n)
    p[contact] = x[:nc]
    q[stick] = x[nc:nc + nt]
    q[slip] = (fold * p)[slip]
    return p, q, float(x[-2]), float(x[-1])


def _fields(ops: StripOperators, p: np.ndarray, q: np.ndarray, delta: float, shift: float,
            strain: float) -> tuple[np.ndarray, np.ndarray]:
    """Gap and slip displacement at the midpoints."""
    gap = ops.pw @ p + ops.qw @ q - delta + ops.gap0
    v = ops.pu @ p + ops.qu @ q + strain * ops.mid - shift
    return gap, v


def _violations(k: float, state: np.ndarray, p: np.ndarray, q: np.ndarray, gap: np.ndarray,
                dv: np.ndarray, scales: tuple[float, float, float]) -> np.ndarray:
    """Signed amount by which each element breaks its set's condition (0: it holds)."""
    ps, gs, vs = scales
    out = np.zeros(state.size)
    sep = state == SEPARATED
    out[sep] = np.maximum(-gap[sep] / gs, 0.0)
    con = ~sep
    out[con] = np.maximum(-p[con] / ps, 0.0)
    st = state == STICK
    out[st] = np.maximum(out[st], (np.abs(q[st]) - k * p[st]) / ps)
    sp = state == SLIP_POSITIVE  # q = +k p needs dv <= 0
    out[sp] = np.maximum(out[sp], dv[sp] / vs)
    sn = state == SLIP_NEGATIVE
    out[sn] = np.maximum(out[sn], -dv[sn] / vs)
    return out


def _next_state(ops: StripOperators, k: float, state: np.ndarray, p: np.ndarray,
                q: np.ndarray, gap: np.ndarray, dv: np.ndarray, bad: np.ndarray) -> np.ndarray:
    """The sets with the elements in ``bad`` moved to the set their violation points to.

    An element touching down starts stuck if the shear that would hold it (its slip
    increment over its own tangential compliance) is within k times the pressure that
    would push it back (its penetration over its own normal compliance); else it slips
    against its increment (the history solver's rule).
    """
    new = state.copy()
    for_sep = bad & (state == SEPARATED)
    if for_sep.any():
        i = np.flatnonzero(for_sep)
        hold = np.abs(dv[i]) / ops.qu[i, i]
        push = k * np.maximum(-gap[i], 0.0) / ops.pw[i, i]
        new[i] = np.where(hold <= push, STICK,
                          np.where(dv[i] < 0.0, SLIP_POSITIVE, SLIP_NEGATIVE))
    lift = bad & (state != SEPARATED) & (p < 0.0)
    new[lift] = SEPARATED
    rest = bad & ~for_sep & ~lift
    st = rest & (state == STICK)
    new[st] = np.where(q[st] > 0.0, SLIP_POSITIVE, SLIP_NEGATIVE)
    new[rest & (state >= SLIP_POSITIVE)] = STICK
    return new


def solve_step(ops: StripOperators, k: float, load: float, force: float, strain: float,
               v_old: np.ndarray, state0: np.ndarray, shift_old: float = 0.0) -> FrettingStep:
    """One load step: the sets, tractions and displacements at the step's end.

    Parameters
    ----------
    ops : StripOperators
    k : float
        Coulomb coefficient, ``0 < k < inf``.
    load, force : float
        P and Q at the step's end (per unit length, units E* a_max^2/R).
    strain : float
        The body's bulk strain ``c2 sigma`` at the step's end.
    v_old : ndarray
        Slip displacement at the step's start.
    state0 : ndarray
        Sets at the step's start (the first guess).

    Returns
    -------
    FrettingStep
    """
    state = state0.copy()
    seen: set[bytes] = set()
    one_at_a_time = False
    for it in range(1, _MAX_ITER + 1):
        p, q, delta, shift = _solve_sets(ops, k, state, load, force, strain, v_old, shift_old)
        gap, v = _fields(ops, p, q, delta, shift, strain)
        dv = v - v_old
        ps = max(float(np.max(np.abs(p))), 1e-300)
        gs = max(float(np.max(np.abs(ops.gap0))), 1e-300)
        vs = max(float(np.max(np.abs(dv))), ps * ops.width, 1e-300)
        viol = _violations(k, state, p, q, gap, dv, (ps, gs, vs))
        bad = viol > _REL_TOL
        balanced = abs(ops.width * float(np.sum(q)) - force) <= 1e-9 * (
            k * abs(load) + abs(force)) + 1e-300
        if not bad.any() and balanced:
            return FrettingStep(p, q, v, gap, delta, shift, state, True, it)
        if not bad.any():
            # every element slips but the shears miss Q: the stick zone is narrower than an
            # element; keep the element closest to sticking stuck
            con = np.flatnonzero(state != SEPARATED)
            reserve = k * np.maximum(p[con], 0.0) - np.abs(q[con])
            state = state.copy()
            state[con[int(np.argmax(reserve))]] = STICK
            continue
        key = state.tobytes()
        if key in seen:
            one_at_a_time = True
        seen.add(key)
        if one_at_a_time:
            only = np.zeros_like(bad)
            only[int(np.argmax(viol))] = True
            bad = only
        state = _next_state(ops, k, state, p, q, gap, dv, bad)
    return FrettingStep(p, q, v, gap, delta, shift, state, False, _MAX_ITER)


# measured: benchmarks/report_fretting.py (part 1: c/a against Cattaneo; the skipped elements'
# tractions were 2-30 % off the closed form); tests/test_fretting.py checks it
EDGE_SKIP = 2  # elements next to an edge whose traction carries the edge's local error
# measured: benchmarks/report_fretting.py (part 1: c/a against Cattaneo); tests/test_fretting.py
# checks it within its estimate, and the stick offset against Hills and Nowell
EDGE_FIT = 7  # elements beyond those fitted by a quadratic in f^2


def _run_edge(x: np.ndarray, f: np.ndarray, inside: np.ndarray, width: float
              ) -> tuple[float, float]:
    """Left and right ends of the longest run of ``inside`` elements, sub-element.

    ``f`` vanishes as a square root at a smooth edge (the pressure at a contact
    edge, the friction reserve ``k p - |q|`` at a stick edge), so ``f**2`` is
    smooth there. It is fitted by a quadratic in x over ``EDGE_FIT`` elements,
    leaving out the ``EDGE_SKIP`` elements next to the edge (whose tractions
    carry the discretization's local error: measured 2-30 % against
    Cattaneo's closed form, against 0.1 % further in), and the fit's root next
    to the run's last element is the edge. Where the run is too short, or the
    root is not within two elements of it, the edge is the last element's
    outer boundary. NaN, NaN where nothing is inside.
    """
    idx = np.flatnonzero(inside)
    if idx.size == 0:
        return float("nan"), float("nan")
    breaks = np.flatnonzero(np.diff(idx) > 1)
    starts = np.concatenate(([0], breaks + 1))
    stops = np.concatenate((breaks, [idx.size - 1]))
    longest = int(np.argmax(stops - starts))
    lo, hi = int(idx[starts[longest]]), int(idx[stops[longest]])
    need = EDGE_SKIP + EDGE_FIT

    def end(last: int, direction: int) -> float:
        base = float(x[last] + 0.5 * direction * width)
        if hi - lo + 1 < need + 2:
            return base
        sel = last - direction * np.arange(EDGE_SKIP, need)
        f2 = f[sel] ** 2
        if not (np.all(np.diff(f2) > 0.0) and f2[-1] > 2.0 * f2[0]):
            return base  # f does not rise from a front here (e.g. a zone at the limit)
        t = (x[sel] - x[last]) / width
        c2, c1, c0 = np.polyfit(t, f2, 2)
        roots = np.roots([c2, c1, c0]) if c2 != 0.0 else np.array([-c0 / c1])
        roots = roots[np.isreal(roots)].real * direction
        roots = roots[(roots > -1.0) & (roots < 2.0)]
        if roots.size == 0:
            return base
        return float(x[last] + direction * width * roots.min())

    return end(lo, -1), end(hi, 1)


def zone_edges(ops: StripOperators, k: float, step: FrettingStep
               ) -> tuple[float, float, float, float]:
    """Contact ends and stick-zone ends (units a_max), sub-element by square-root fits.

    Returns
    -------
    (left, right, stick_left, stick_right) : float
        The contact's ends from the pressure, the stick zone's from the
        friction reserve ``k p - |q|`` (both vanish as a square root at an
        edge of a smooth profile). NaN where there is no contact or no stick.
    """
    left, right = _run_edge(ops.mid, step.p, step.state != SEPARATED, ops.width)
    reserve = np.maximum(k * step.p - np.abs(step.q), 0.0)
    s_left, s_right = _run_edge(ops.mid, reserve, step.state == STICK, ops.width)
    # a stick zone ends where the contact does at the latest
    return left, right, max(s_left, left), min(s_right, right)


def _frictionless_width(ops: StripOperators, load: float) -> float:
    """Frictionless half-width at load P (units a_max): P/P_max = a^d for h = |x|^d/d (the
    profile's :meth:`~contactlib.model.profiles.Profile.frictionless_radius`)."""
    return ops.shape.frictionless_radius(max(load, 0.0) / ops.p_max, False)


@dataclass
class RawFretting:
    """Per-step arrays of one run (units E* = R = a_max = 1; step 0 is the unloaded start)."""

    load: np.ndarray
    force: np.ndarray
    strain: np.ndarray
    delta: np.ndarray
    shift: np.ndarray
    edges: np.ndarray  # (steps + 1, 4): left, right, stick left, stick right
    dissipation: np.ndarray  # cumulative frictional work
    external_work: np.ndarray  # cumulative, trapezoid rule in time
    stored_energy: np.ndarray
    converged: np.ndarray
    iterations: np.ndarray
    p: np.ndarray  # (steps + 1, n)
    q: np.ndarray
    state: np.ndarray
    slip: np.ndarray  # (steps + 1, n): the step's slip increment dv (body minus indenter)
    mid: np.ndarray = field(default_factory=lambda: np.zeros(0))


def run_fretting(ops: StripOperators, k: float, load: np.ndarray, force: np.ndarray,
                 strain: np.ndarray,
                 progress: Callable[[int, int], None] | None = None) -> RawFretting:
    """Follow a path of (P, Q, bulk strain) values from the unloaded start.

    Parameters
    ----------
    ops : StripOperators
    k : float
        Coulomb coefficient, ``0 < k < inf``.
    load, force, strain : ndarray, shape (m,)
        P, Q (per unit length, units E* a_max^2/R) and the body's bulk strain
        at the end of each step; the start (all zero) is not included.
    progress : callable, optional
        ``progress(i, m)`` after each step.

    Returns
    -------
    RawFretting
        Arrays of length ``m + 1`` (the unloaded start first).
    """
    m = load.size
    n = ops.n
    state = np.full(n, SEPARATED, dtype=np.int8)
    v = np.zeros(n)
    out = {name: np.zeros(m + 1) for name in ("delta", "shift", "dissipation",
                                                "external_work", "stored_energy")}
    edges = np.full((m + 1, 4), np.nan)
    conv = np.ones(m + 1, dtype=bool)
    iters = np.zeros(m + 1, dtype=np.int32)
    p_all = np.zeros((m + 1, n))
    q_all = np.zeros((m + 1, n))
    dv_all = np.zeros((m + 1, n))
    s_all = np.zeros((m + 1, n), dtype=np.int8)
    prev_load = prev_force = prev_strain = 0.0
    prev_delta = prev_shift = 0.0
    prev_q = np.zeros(n)
    h = ops.width
    for i in range(m):
        if not (state != SEPARATED).any() and load[i] > 0.0:
            # first touch: start from the frictionless contact, all stuck
            a_guess = _frictionless_width(ops, float(load[i]))
            state = np.where(np.abs(ops.mid) < a_guess, STICK, SEPARATED).astype(np.int8)
            if not (state != SEPARATED).any():
                state[np.argsort(np.abs(ops.mid))[:2]] = STICK
        step = solve_step(ops, k, float(load[i]), float(force[i]), float(strain[i]), v, state,
                          prev_shift)
        j = i + 1
        # external work: P d(delta) + Q ds - (interface shear) . x d(strain), trapezoid rule
        d_strain = float(strain[i]) - prev_strain
        w_ext = (0.5 * (prev_load + load[i]) * (step.delta - prev_delta)
                 + 0.5 * (prev_force + force[i]) * (step.shift - prev_shift)
                 - 0.5 * h * float((prev_q + step.q) @ ops.mid) * d_strain)
        out["external_work"][j] = out["external_work"][j - 1] + w_ext
        slip = step.state >= SLIP_POSITIVE  # k p |dv|, p by the trapezoid rule: >= 0
        diss = 0.5 * k * h * float(np.sum((p_all[j - 1, slip] + np.maximum(step.p[slip], 0.0))
                                          * np.abs(step.v[slip] - v[slip])))
        out["dissipation"][j] = out["dissipation"][j - 1] + diss
        w = ops.pw @ step.p + ops.qw @ step.q  # the elastic relative displacements
        u = ops.pu @ step.p + ops.qu @ step.q
        out["stored_energy"][j] = 0.5 * h * float(step.p @ w + step.q @ u)
        out["delta"][j] = step.delta
        out["shift"][j] = step.shift
        edges[j] = zone_edges(ops, k, step)
        conv[j] = step.converged
        iters[j] = step.iterations
        p_all[j], q_all[j], s_all[j] = step.p, step.q, step.state
        dv_all[j] = np.where(step.state != SEPARATED, step.v - v, 0.0)
        v, state = step.v, step.state
        prev_load, prev_force, prev_strain = float(load[i]), float(force[i]), float(strain[i])
        prev_delta, prev_shift, prev_q = step.delta, step.shift, step.q
        if progress is not None:
            progress(j, m)
    return RawFretting(load=np.concatenate(([0.0], load)), force=np.concatenate(([0.0], force)),
                       strain=np.concatenate(([0.0], strain)), delta=out["delta"],
                       shift=out["shift"], edges=edges, dissipation=out["dissipation"],
                       external_work=out["external_work"], stored_energy=out["stored_energy"],
                       converged=conv, iterations=iters, p=p_all, q=q_all, state=s_all, slip=dv_all,
                       mid=ops.mid)
