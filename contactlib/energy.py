"""Frictional work: of the self-similar loading half-cycle, and of an incremental step.

Self-similar loading (paper Eqs. 17-21)
---------------------------------------
With the self-similar scalings p = a P(xi), u = a^2 U(xi), the slip of a point
when the contact radius grows by da is a (2U - xi U') da (Eq. 18), so that

* sphere:   V R^2/(E* a^5) = (2 pi / 5) int_c^1 xi q(xi) (-s(xi)) dxi,
* cylinder: V R^2/(E* a^4) = (1 / 2)    int_c^1    q(xi) (-s(xi)) dxi
  (per unit length, both sides of the axis),

in units E* = a = R = 1 where q and s = 2u - xi du/dxi are the traction and
slip rate at a = 1. ``du/dxi`` comes from the exact derivative kernels, not
from differences of nodal displacements. The factor and the power are the
indenter's (:attr:`contactlib.model.indenter.Indenter.work_factor`,
:attr:`~contactlib.model.indenter.Indenter.work_weight_power`).

Incremental steps (:mod:`contactlib.solvers.history_solver`)
----------------------------------------------------
A load step moves element j by ``du_j`` against a traction that changes
from ``q_j^old`` to ``q_j^new``; its work is taken by the trapezoid rule in
time, ``-(q_old + q_new)/2 du A_j`` (the shear opposes the slip), over the
elements slipping at the end of the step and those that slipped before it
and separate in it, releasing their shear while they slide (stuck elements
have ``du = 0``; a stuck element that separates does no frictional work).
Leaving the separating elements out, as earlier versions did, lost 0.9 % of
a load-unload cycle's work at 100 steps a segment and 0.1 % at 400 (sphere,
nu = 0.3, k = 0.2, n = 120); with them the errors are 0.16 % and 1e-5.

As a trapezoid rule in time a step's sum can come out slightly negative
where the slip reverses or the contact shrinks within a step: an element
that separates and springs back past the point where it lost contact, or
one whose shear reverses sign within the step. This made the cumulative
work fall in the last steps of every unloading (by 5.2e-7 of 9.06e-4 for
the sphere at nu = 0.3, k = 0.2, n = 240, 200 steps a segment; 1.5e-7 and
4.7e-8 at n = 480 and 960 with 400 and 800 steps). Dissipation is
``|q| |slip rate| >= 0`` at every instant, so the reported cumulative work
is :func:`monotone_work` of the trapezoid sums: the largest non-decreasing
sequence not above them. A fall is taken from the steps before it, which
the trapezoid rule had credited with too much (the sum at the end of a
closed cycle is the area of the load-indentation loop, and it is kept);
every step's dissipation is then >= 0 and the path's total is unchanged.
Flooring each element's or each step's term at 0 instead adds the falls to
the total, away from the refined value: a steel-on-glass cycle's work (k =
0.2, n = 240, 200 steps a segment), 0.35 % above the value at n = 480 with
800 steps, came out 0.96 % (per element) and 0.79 % (per step) above it.
``A_j`` is the element's
shear resultant per unit shear at its midpoint; in units E* = R = a_max = 1
the sum is V R^2/(E* a_max^5) (sphere) or V R^2/(E* a_max^4) per unit length
(cylinder).

Energy balance of an incremental history (elastic or viscoelastic body)
--------------------------------------------------------------------------
With the surface traction sigma = (p, q) on the elements and the body's
surface displacement d = (w, u) at the collocation points, the inner product
``<sigma, d> = sum_j A_j p_j w_j + As_j q_j u_j`` (A_j the element area, As_j
its shear-weighted area) is the work density of the discretisation. With a
constant Poisson's ratio and the Prony relaxation E(t)/E(0) = g_inf + sum g_i
exp(-t/tau_i), write d = K e with K the elastic operator at E(0) and e the
*elastic-equivalent traction*; then sigma = g_inf e + sum g_i h_i with
h_i' = e' - h_i/tau_i (the generalised Maxwell body, branch i a spring g_i
E(0) in series with a dashpot). Free (stored) energy and dissipation rate:

    Phi = g_inf/2 <e, K e> + sum_i g_i/2 <h_i, K h_i>,
    D   = sum_i (g_i/tau_i) <h_i, K h_i>  >= 0,

so that <sigma, d'> = Phi' + D: the work done on the body is stored or
dissipated by its dashpots. The indenter does work P delta' (rigid, without
tangential motion), equal to the work of the pressure on the body's surface,
int p w' dA; the work of the shear on the body's surface, <q, u'>, is the
negative of the frictional dissipation (q opposes the slip, and stuck
elements do not move). Hence external = stored + viscous + frictional. An
elastic body is g_i = 0, Phi = <sigma, d>/2.

The step functions below take e linear in time within a step (the
history solver's recursion, exact for it): h_i(t) = a(t) h_i^old +
(1 - a(t)) tau_i e', a(t) = exp(-t/tau_i), and D is integrated exactly
over the step; the external work is the work of the mean pressure of the
step on the body's surface under the same assumption (:func:`mean_traction`,
:func:`step_external_work`). With these, external = stored + viscous +
(work of the shear on the body's surface) holds step by step up to the
asymmetry of the collocated K (1e-4 of its largest term at n = 240), and
:func:`step_work` is that shear work with its sign changed (the
reported cumulative work, :func:`monotone_work` of its sums, differs from
it only in the steps before a fall of the sums, and by at most the fall).
Units as for :func:`step_work`.
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["slip_points", "frictional_work", "record_work", "step_work", "monotone_work", "dot",
           "step_external_work", "mean_traction", "one_minus_b_over_x", "stored_energy",
           "decay_integrals",
           "viscous_step_work"]


def slip_points(nodes: np.ndarray, stick_index: int, order: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss points and weights of every slip element (between node M and a)."""
    t, w = np.polynomial.legendre.leggauss(order)
    lo, hi = nodes[stick_index:-1], nodes[stick_index + 1:]
    h = hi - lo
    x = (lo[:, None] + 0.5 * h[:, None] * (t[None, :] + 1.0)).ravel()
    wt = (0.5 * h[:, None] * w[None, :]).ravel()
    return x, wt


def frictional_work(x: np.ndarray, weights: np.ndarray, q: np.ndarray, s: np.ndarray,
                    factor: float, power: int) -> float:
    """V in the scaling of docs/conventions.md: factor * sum w x^power q (-s)."""
    return float(factor * np.sum(weights * x**power * q * (-s)))


def record_work(record: Any, factor: float, power: int) -> float:
    """V of one self-similar case from its stored slip samples (0 without slip).

    ``record`` is a :class:`contactlib.result.CaseRecord` (its ``slip_x``,
    ``slip_w``, ``slip_q``, ``slip_s``); ``factor`` and ``power`` are the
    indenter's ``work_factor`` and ``work_weight_power``. Nothing slips
    without friction (k = 0), in full adhesion or at nu = 0.5.
    """
    if record.slip_x.size == 0:
        return 0.0
    return frictional_work(record.slip_x, record.slip_w, record.slip_q, record.slip_s,
                           factor, power)


def step_work(q_old: np.ndarray, q_new: np.ndarray, du: np.ndarray, shear_area: np.ndarray,
              moving: np.ndarray) -> float:
    """Frictional work of one incremental load step (trapezoid rule in time).

    Parameters
    ----------
    q_old, q_new : ndarray, shape (n,)
        Shear at the start and at the end of the step (units E* a_max/R).
    du : ndarray, shape (n,)
        Tangential displacement increment of the step (units a_max^2/R).
    shear_area : ndarray, shape (n,)
        Shear resultant of each element per unit midpoint shear (units
        a_max^2, or a_max per unit length).
    moving : ndarray of bool, shape (n,)
        Elements that slip in the step: those slipping at its end, and those
        that were slipping at its start and separate in it (a stuck element
        that separates does no frictional work).

    Returns
    -------
    float
        ``-sum A_j (q_old + q_new)_j/2 du_j`` over the moving elements
        (units E* a_max^5/R^2, or E* a_max^4/R^2 per unit length): the
        negative of the shear's work on the body's surface (the shear
        opposes the slip, so each term is >= 0 up to the time
        discretisation; stuck and separated elements do no work). The
        cumulative sums go through :func:`monotone_work`.
    """
    terms = -0.5 * (q_old + q_new) * du * shear_area
    return float(np.sum(terms[moving]))


def monotone_work(cumulative: np.ndarray) -> np.ndarray:
    """The largest non-decreasing sequence not above ``cumulative`` (module notes).

    Parameters
    ----------
    cumulative : ndarray, shape (S + 1,)
        Cumulative trapezoid sums of :func:`step_work` (units of the work).

    Returns
    -------
    ndarray
        ``W_i = min_{j >= i} cumulative_j``: every increment is >= 0, the last
        value is the last sum, and a step whose sum was negative takes its
        fall from the steps before it. NaN where ``cumulative`` is NaN (a
        NaN is not passed on to other steps).
    """
    w = np.asarray(cumulative, dtype=float)
    out = np.fmin.accumulate(w[::-1])[::-1]
    out[np.isnan(w)] = np.nan
    return out


# ----------------------------------------------------------------------------- energy balance



def dot(weights: np.ndarray, traction: np.ndarray, displacement: np.ndarray) -> float:
    """``<sigma, d>``: sum of weights * traction * displacement (arrays of shape (2, n))."""
    return float(np.sum(weights * traction * displacement))


def step_external_work(area: np.ndarray, p_mean: np.ndarray, w_old: np.ndarray,
                       w_new: np.ndarray) -> float:
    """Work of the indenter in one step: ``sum_j A_j pbar_j (w_new - w_old)_j``.

    In the continuum the indenter's work P d(delta) is the work of the
    pressure on the body's surface, int p dw dA (w = delta - r^2/(2R) in
    the contact, p = 0 outside). ``p_mean`` is the pressure averaged over
    the step: (p_old + p_new)/2 for an elastic body (the trapezoid rule,
    exact for an elastic body from rest whatever the contact does within
    the step, where ``(P_old + P_new)/2 d(delta)`` is not: a step from no
    contact overestimates the sphere's work by a quarter), and
    :func:`mean_traction` for a viscoelastic one.
    """
    return float(np.sum(area * p_mean * (w_new - w_old)))


def mean_traction(relaxed: float, g: np.ndarray, tau: np.ndarray, dt: float,
                  e_old: np.ndarray, e_new: np.ndarray, h_old: np.ndarray) -> np.ndarray:
    """Traction averaged over a step with e linear in time (the recursion's assumption).

    ``sigma = g_inf e + sum g_i h_i`` with ``h_i(t) = a(t) h_i^old + (1 - a(t))
    tau_i e'``: the mean is ``g_inf (e_old + e_new)/2 + sum g_i (b_i h_i^old +
    (1 - b_i) tau_i (e_new - e_old)/dt)``, ``b_i = (tau_i/dt)(1 - exp(-dt/tau_i))``.
    Where dt >> tau_i the traction jumps to its viscous part within the
    step, which the trapezoid rule would halve.
    """
    x = dt / tau
    b = -np.expm1(-x) / x
    c = one_minus_b_over_x(x)  # (1 - b_i) tau_i / dt, without cancelling for small dt
    de = e_new - e_old
    out = 0.5 * relaxed * (e_old + e_new)
    for gi, bi, ci, hi in zip(g, b, c, h_old):
        out = out + gi * (bi * hi + ci * de)
    return out


def one_minus_b_over_x(x: np.ndarray) -> np.ndarray:
    """``(1 - b) / x`` with ``b = (1 - exp(-x)) / x``, accurate for every x > 0 (dimensionless).

    Equal to ``(x - 1 + exp(-x)) / x^2``: below x = 1e-3 its Taylor series
    ``1/2 - x/6 + x^2/24 - x^3/120`` (truncation below 2e-15 relative), where
    ``1 - b`` cancels (to nothing at x = 1e-300, which lost the half of a
    step's traction change that the dashpots take up in an instantaneous
    step); above, the expression itself.
    """
    x = np.asarray(x, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        direct = (1.0 + np.expm1(-x) / x) / x
    series = 0.5 - x / 6.0 + x * x / 24.0 - x**3 / 120.0
    return np.where(x < 1e-3, series, direct)


def stored_energy(weights: np.ndarray, relaxed: float, g: np.ndarray, e: np.ndarray,
                  d: np.ndarray, h: np.ndarray, kh: np.ndarray) -> float:
    """Phi = g_inf/2 <e, d> + sum_i g_i/2 <h_i, K h_i> (module notes).

    Parameters
    ----------
    weights : ndarray, shape (2, n)
        Element areas (pressure row) and shear-weighted areas (shear row).
    relaxed : float
        g_inf = E(inf)/E(0) (1 for an elastic body).
    g : ndarray, shape (N,)
        Prony weights.
    e, d : ndarray, shape (2, n)
        Elastic-equivalent traction and the displacement d = K e.
    h, kh : ndarray, shape (N, 2, n)
        Branch variables h_i and K h_i.
    """
    out = 0.5 * relaxed * dot(weights, e, d)
    if g.size:
        out += 0.5 * float(np.sum(g * np.sum(weights * h * kh, axis=(1, 2))))
    return out


def decay_integrals(x: np.ndarray, scaled: bool = False) -> np.ndarray:
    """int_0^x of exp(-2s), exp(-s)(1 - exp(-s)), (1 - exp(-s))^2 ds; shape (3,) + x.shape.

    Closed forms for x >= 1; 12-point Gauss-Legendre below (the closed
    forms cancel there; the integrands are smooth, so the rule is exact to
    round-off). With ``scaled`` the second is divided by x and the third by
    x^2 (the factors tau/dt with which :func:`viscous_step_work` weighs
    them), computed from ``(1 - exp(-s))/x`` inside the integral so that
    nothing under- or overflows however small x is (dimensionless).
    """
    x = np.atleast_1d(np.asarray(x, dtype=float))
    t, w = np.polynomial.legendre.leggauss(12)
    s = 0.5 * x[..., None] * (t + 1.0)
    a = np.exp(-s)
    b = -np.expm1(-s)
    if scaled:
        b = b / x[..., None]
    half = 0.5 * x[..., None] * w
    quad = np.stack([np.sum(half * a * a, -1), np.sum(half * a * b, -1),
                     np.sum(half * b * b, -1)])
    e1, e2 = -np.expm1(-x), -np.expm1(-2.0 * x)
    closed = np.stack([0.5 * e2, e1 - 0.5 * e2, x - 2.0 * e1 + 0.5 * e2])
    if scaled:
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            closed = closed / np.stack([np.ones_like(x), x, x * x])  # used for x >= 1 only
    return np.where(x >= 1.0, closed, quad)


def viscous_step_work(weights: np.ndarray, g: np.ndarray, tau: np.ndarray, dt: float,
                      h_old: np.ndarray, kh_old: np.ndarray, de: np.ndarray,
                      dd: np.ndarray, integrals: np.ndarray | None = None) -> float:
    """Dissipation of the dashpots in one step, int D dt, for e linear in time.

    Parameters
    ----------
    weights : ndarray, shape (2, n)
    g, tau : ndarray, shape (N,)
        Prony weights and relaxation times.
    dt : float
        Duration of the step (> 0, unit of tau).
    h_old, kh_old : ndarray, shape (N, 2, n)
        Branch variables at the start of the step and K h_i.
    de, dd : ndarray, shape (2, n)
        Increment of the elastic-equivalent traction and of the displacement
        (dd = K de).
    integrals : ndarray, shape (3, N), optional
        ``decay_integrals(dt / tau, scaled=True)`` (computed when not given;
        a caller with many steps of one duration passes it once computed).

    Returns
    -------
    float
        sum_i (g_i/tau_i) int <h_i, K h_i> dt >= 0 (up to the asymmetry of K),
        with h_i(t) = a h_i^old + (1 - a) Y_i, Y_i = tau_i de/dt.
    """
    if g.size == 0:
        return 0.0
    if integrals is None:
        integrals = decay_integrals(dt / tau, scaled=True)
    # (3, N): int a^2 dt, y int a(1-a) dt, y^2 int (1-a)^2 dt with y = tau/dt (Y_i = y de,
    # K Y_i = y dd): the factors y taken into the integrals, which stay finite as dt -> 0
    ints = integrals * tau
    xx = np.sum(weights * h_old * kh_old, axis=(1, 2))
    xy = 0.5 * (np.sum(weights * h_old * dd, axis=(1, 2))
                + np.sum(weights * de * kh_old, axis=(1, 2)))
    yy = dot(weights, de, dd)
    return float(np.sum(g / tau * (ints[0] * xx + 2.0 * ints[1] * xy + ints[2] * yy)))
