r"""Fretting of the sphere: a tangential load on top of the normal one (numerics only).

A sphere (or any axisymmetric profile) is pressed onto a half-space by a normal
force ``P`` and loaded tangentially by a force ``Q`` along x, both following a
path, with Coulomb friction. The tractions are a vector field on the contact
area and the slip direction is unknown. This module never touches the disk.

Units and scalings
------------------
E* = R = 1 and lengths in units of ``a_max``, the frictionless contact radius
at the reference load ``P_max`` (4/3 for the paraboloid, Hertz's sphere). The
pressure unit is ``p0`` (2/pi for the paraboloid), displacements are in
``a_max^2/R``, forces in ``E* a_max^3/R`` and work in ``E* a_max^5/R^2``.

The discretization
------------------
A uniform square grid of ``n x n`` cells of side ``h = 2 L/n`` covers
``[-L, L]^2`` (``L = 1.2 a_max``). Each cell carries a constant pressure
``p`` and shear ``(qx, qy)`` (the traction the indenter exerts on the body);
the conditions are imposed at the cell centres. The relative surface
displacements (body minus indenter) of a point force on two half-spaces are
(Johnson 1985, eqs. 3.19 and 3.86; the two bodies' compliances summed)

.. math::

    w = \frac{P}{\pi r}, \quad
    u_x = \frac{Q_x}{\pi r}\Big(1 + \gamma\frac{X^2}{r^2}\Big)
        + \frac{Q_y}{\pi}\gamma\frac{XY}{r^3} - \frac{\beta}{\pi}\frac{P X}{r^2},

and ``u_y`` likewise (``X, Y`` from the force to the point), with
``w = (beta/pi) (Q_x X + Q_y Y)/r^2`` from the shear (Betti's theorem).
``beta`` is Dundurs' (:attr:`contactlib.model.Contact.beta`, the sign of
the cylinder's kernels in :mod:`contactlib.fretting_solver`, to which these
reduce when integrated along a line), and

.. math::

    \gamma = \sum_i c_i \frac{\nu_i}{1 - \nu_i}, \qquad c_i = E^*/E^*_i,

the tangential compliances' Poisson term (``nu/(1 - nu)`` for a rigid
indenter). Mindlin's compliance is ``C = sum (2 - nu_i)/G_i = 4 + 2 gamma``
in these units. The integrals over a square cell are closed forms
(:func:`grid_operators`); as the kernels depend on the offset only, they are
applied by zero-padded FFT convolution, ``O(n^2 log n)`` a product.

Conditions at the cell centres
------------------------------
* normal: gap ``g = w - delta + h(r) >= 0``, ``p >= 0``, ``p g = 0``,
  ``sum p h^2 = P``; solved by Polonsky and Keer's (1999) constrained
  conjugate gradients;
* tangential: the slip ``v = u - s`` (``s`` the indenter's rigid shift, a
  2-vector) and its increment ``dv`` over the step; stick: ``dv = 0`` and
  ``|q| <= k p``; slip: ``q = -k p dv/|dv|``; ``sum q h^2 = (Q, 0)``
  (force control). At a given shift ``s`` (:func:`solve_shifted`), for given
  sets and slip directions, the stuck cells' shear solves a symmetric positive
  definite system, by conjugate gradients. Sets and directions are then
  updated by Kalker's rules: a stuck cell whose shear exceeds ``k p`` slips
  along its shear; a slipping cell whose slip does not oppose its shear sticks;
  the others take the direction opposite to the slip the other cells and the
  shift impose on them, the fixed point accelerated by Anderson mixing. The
  loop ends when nothing changes and the directions agree to
  ``_DIRECTION_TOL``; a loop that does not is run again with a patient rule
  (no cell sticks while the directions still turn by more than
  ``_PATIENT_TURN``), which the coupled pairs need. The force is met by a safeguarded
  secant method on ``s_x`` (:func:`solve_tangential`; ``s_y = 0`` by symmetry). Force control
  inside the active set made the shift oscillate and grow.
* coupling (beta != 0): the normal and tangential problems are solved in
  turn until the pressure and the shear change by less than
  ``_COUPLING_TOL`` of their scales; at beta = 0 the normal problem is solved
  once per load level.

The frictional work of a step is ``sum k p |dv| h^2`` over the cells slipping
at its end, ``p`` the mean of its values at the step's ends; the external work
``P d(delta) + Q d(s_x)`` by the trapezoid rule; the stored energy
``(p.w + q.u) h^2/2``. A step that does not converge is flagged
(``converged`` False), never silently accepted.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from .model import Contact

__all__ = [
    "MESH_EXTENT",
    "GridOperators",
    "RawSphereFretting",
    "SphereStep",
    "grid_operators",
    "mindlin_compliance",
    "run_sphere_fretting",
    "solve_normal",
    "solve_shifted",
    "solve_tangential",
    "tangential_gamma",
    "zone_radius",
]

# convention: the grid reaches 20 % beyond the largest contact (as fretting_solver's)
MESH_EXTENT = 1.2  # grid half-width over a_max
# tested: tests/test_fretting_sphere.py (Hertz's contact, Cattaneo–Mindlin within estimates)
_CG_TOL = 1e-11  # conjugate gradients: residual relative to the right-hand side's scale
# convention: a solve not done in 2000 iterations is reported as not converged
_CG_MAX = 2000
# tested: tests/test_fretting_sphere.py (Cattaneo–Mindlin's stick ratio within its estimate)
_SET_TOL = 1e-9  # set switching, relative to the traction / slip scales
# tested: tests/test_fretting_sphere.py (rigid on nu = 0.5: the slip not along the load)
_DIRECTION_TOL = 1e-7  # slip directions' fixed point (radians, roughly)
# tested: tests/test_fretting_sphere_coupled.py (tiny beta: within 1e-4 of beta = 0)
_COUPLING_TOL = 1e-9
# convention: an active set not settled in 200 iterations is reported as not converged
_MAX_SETS = 200
# convention: a coupled step not settled in 100 alternations is reported as not converged
_MAX_COUPLING = 100
# tested: tests/test_fretting_sphere_api.py (the shift at Q* against Mindlin's)
_FORCE_TOL = 1e-10  # the force Q, relative to k P
# convention: a force not met in 60 secant steps is reported as not converged
_MAX_SECANT = 60
# tested: tests/test_fretting_sphere.py (the cycles' work against Mindlin–Deresiewicz)
_PINNED_TOL = 1e-6  # a pinned cell's slip along its shear, relative to the slip scale
# tested: tests/test_fretting_sphere.py (every step of the cycles converged)
_MIX = 0.5  # damping of the slip directions' update (plain updates diverged)
# tested: tests/test_fretting_sphere.py (every step of the cycles converged)
_ANDERSON = 5  # Anderson mixing of the slip directions: steps kept
# tested: tests/test_fretting_sphere_coupled.py (the step at Q = 0.375 k P, n = 32, converges)
_PATIENT_TURN = 1e-3  # the retried active set: directions' turn below which cells may stick


def tangential_gamma(model: Contact) -> float:
    r"""The Poisson term of the tangential compliance, ``gamma = sum c_i nu_i/(1 - nu_i)``.

    Parameters
    ----------
    model : Contact
        The pair (rigid or elastic indenter on a half-space).

    Returns
    -------
    float
        Dimensionless; ``nu/(1 - nu)`` for a rigid indenter on a body of
        Poisson's ratio nu, 0 for two bodies with nu = 0.
    """
    c1, c2 = model.compliance_weights
    nu1, nu2 = model.indenter_poisson_ratio, model.body.nu
    return float(c1 * nu1 / (1.0 - nu1) + c2 * nu2 / (1.0 - nu2))


def mindlin_compliance(model: Contact) -> float:
    """Mindlin's ``C = (2 - nu1)/G1 + (2 - nu2)/G2`` in units of 1/E*: ``4 + 2 gamma``."""
    return 4.0 + 2.0 * tangential_gamma(model)


@dataclass(frozen=True)
class GridOperators:
    """Influence coefficients of the square grid, as FFTs (units E* = R = a_max = 1).

    Attributes
    ----------
    n : int
        Cells along each side.
    h : float
        Cell side (units a_max).
    x : ndarray, shape (n,)
        Cell centres along each axis (the grid is ``x[i], x[j]``).
    gap0 : ndarray, shape (n, n)
        The profile's gap ``h(r)`` at the centres (units a_max^2/R).
    beta, gamma : float
        Dundurs' beta and the tangential Poisson term.
    p_max, p0 : float
        Reference load and pressure unit.
    kernels : dict of str to ndarray
        rfft2 of the zero-padded (2n x 2n) offset kernels ``"pw"`` (w from p),
        ``"xx"``, ``"xy"``, ``"yy"`` (u from q) and ``"cx"``, ``"cy"`` (u_x, u_y
        from p; w from (qx, qy) is minus these).
    self_normal, self_tangential : float
        Diagonal coefficients (a cell's own influence) of w from p and u_x from qx.
    """

    n: int
    h: float
    x: np.ndarray
    gap0: np.ndarray
    beta: float
    gamma: float
    p_max: float
    p0: float
    kernels: dict
    self_normal: float
    self_tangential: float

    def _conv(self, name: str, f_hat: np.ndarray) -> np.ndarray:
        n = self.n
        return np.fft.irfft2(self.kernels[name] * f_hat, s=(2 * n, 2 * n))[:n, :n]

    def _hat(self, f: np.ndarray) -> np.ndarray:
        return np.fft.rfft2(f, s=(2 * self.n, 2 * self.n))

    def normal(self, p: np.ndarray, q: np.ndarray | None = None) -> np.ndarray:
        """w (units a_max^2/R) at the centres from p and, if given, q (shape (2, n, n))."""
        w_hat = self.kernels["pw"] * self._hat(p)
        if q is not None and self.beta != 0.0:
            w_hat = w_hat - self.kernels["cx"] * self._hat(q[0]) \
                - self.kernels["cy"] * self._hat(q[1])
        return np.fft.irfft2(w_hat, s=(2 * self.n, 2 * self.n))[:self.n, :self.n]

    def tangential(self, q: np.ndarray, p: np.ndarray | None = None) -> np.ndarray:
        """(u_x, u_y) (shape (2, n, n), units a_max^2/R) from q and, if given, p."""
        qx, qy = self._hat(q[0]), self._hat(q[1])
        ux = self.kernels["xx"] * qx + self.kernels["xy"] * qy
        uy = self.kernels["xy"] * qx + self.kernels["yy"] * qy
        if p is not None and self.beta != 0.0:
            ph = self._hat(p)
            ux = ux + self.kernels["cx"] * ph
            uy = uy + self.kernels["cy"] * ph
        s = (2 * self.n, 2 * self.n)
        return np.stack([np.fft.irfft2(ux, s=s)[:self.n, :self.n],
                         np.fft.irfft2(uy, s=s)[:self.n, :self.n]])


def _cell_integral(prim: Callable[[np.ndarray, np.ndarray], np.ndarray], X: np.ndarray,
                   Y: np.ndarray, h: float) -> np.ndarray:
    """Integral over the cell centred at offset 0 of f(X - xi, Y - eta), F_xy = f."""
    a = 0.5 * h
    return prim(X + a, Y + a) - prim(X - a, Y + a) - prim(X + a, Y - a) + prim(X - a, Y - a)


def _asinh_ratio(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """u asinh(v/|u|), an antiderivative part of the 1/r kernels (u != 0 at cell corners)."""
    return u * np.arcsinh(v / np.abs(u))


def grid_operators(model: Contact, n: int, extent: float = MESH_EXTENT) -> GridOperators:
    """Influence coefficients of ``n x n`` square cells over ``[-extent, extent]^2``.

    Parameters
    ----------
    model : Contact
        A sphere (axisymmetric profile) on a half-space, rigid or elastic.
    n : int
        Cells along each side (even: no centre lies on an axis).
    extent : float
        Half-width of the grid over a_max.

    Returns
    -------
    GridOperators
    """
    h = 2.0 * extent / n
    x = -extent + h * (np.arange(n) + 0.5)
    off = h * np.arange(-(n - 1), n)
    X, Y = np.meshgrid(off, off, indexing="ij")
    beta = float(model.beta) if not model.decoupled else 0.0
    gamma = tangential_gamma(model)

    def f1(u, v):  # int int 1/r
        return _asinh_ratio(u, v) + _asinh_ratio(v, u)

    def fyy_over(u, v):  # int int Y^2/r^3 = X asinh(Y/|X|)
        return _asinh_ratio(u, v)

    def fxx_over(u, v):  # int int X^2/r^3
        return _asinh_ratio(v, u)

    def fxy(u, v):  # int int XY/r^3
        return -np.hypot(u, v)

    def fcx(u, v):  # int int X/r^2
        return u * np.arctan(v / u) + 0.5 * v * np.log(u * u + v * v)

    def fcy(u, v):
        return fcx(v, u)

    one = _cell_integral(f1, X, Y, h) / np.pi
    raw = {
        "pw": one,
        "xx": one + gamma * _cell_integral(fxx_over, X, Y, h) / np.pi,
        "yy": one + gamma * _cell_integral(fyy_over, X, Y, h) / np.pi,
        "xy": gamma * _cell_integral(fxy, X, Y, h) / np.pi,
        "cx": -beta * _cell_integral(fcx, X, Y, h) / np.pi,
        "cy": -beta * _cell_integral(fcy, X, Y, h) / np.pi,
    }
    kernels = {}
    for name, k in raw.items():
        pad = np.zeros((2 * n, 2 * n))
        idx = np.arange(-(n - 1), n) % (2 * n)
        pad[np.ix_(idx, idx)] = k
        kernels[name] = np.fft.rfft2(pad)
    prof = model.profile
    xx, yy = np.meshgrid(x, x, indexing="ij")
    return GridOperators(n=n, h=h, x=x, gap0=prof.gap(np.hypot(xx, yy)), beta=beta,
                         gamma=gamma, p_max=float(prof.frictionless_load(True)),
                         p0=float(prof.reference_pressure(True)), kernels=kernels,
                         self_normal=float(raw["pw"][n - 1, n - 1]),
                         self_tangential=float(raw["xx"][n - 1, n - 1]))


# ----------------------------------------------------------------------------- normal
def solve_normal(ops: GridOperators, load: float, extra_gap: np.ndarray,
                 p_start: np.ndarray | None = None) -> tuple[np.ndarray, float, bool]:
    """Frictionless contact for a given gap: Polonsky and Keer's constrained CG.

    Parameters
    ----------
    ops : GridOperators
    load : float
        P (units E* a_max^3/R), > 0.
    extra_gap : ndarray, shape (n, n)
        Added to the profile's gap: the normal displacement the shear causes
        (beta != 0), units a_max^2/R.
    p_start : ndarray, optional
        First guess (the previous step's pressure).

    Returns
    -------
    p : ndarray
        Pressure (units E* a_max/R).
    delta : float
        The approach (units a_max^2/R).
    converged : bool
    """
    h2 = ops.h * ops.h
    f = ops.gap0 + extra_gap
    if p_start is None or not np.any(p_start > 0):
        a = (load / ops.p_max) ** (1.0 / 3.0)
        r2 = 2.0 * ops.gap0
        p = np.where(r2 < a * a, np.sqrt(np.maximum(1.0 - r2 / (a * a), 0.0)), 0.0)
        if not p.any():
            p[ops.n // 2 - 1: ops.n // 2 + 1, ops.n // 2 - 1: ops.n // 2 + 1] = 1.0
    else:
        p = np.maximum(p_start, 0.0).copy()
    p *= load / (h2 * p.sum())
    t = np.zeros_like(p)
    g_old = 1.0
    conj = False
    scale = load / h2
    for _ in range(_CG_MAX):
        u = ops.normal(p) + f
        act = p > 0
        delta = float(u[act].mean())
        g = u - delta
        gn = float(np.sum(g[act] ** 2))
        t = np.where(act, g + (gn / g_old) * t if conj else g, 0.0)
        g_old = gn
        r = ops.normal(t)
        r = r - r[act].mean()
        den = float(np.sum(r[act] * t[act]))
        tau = float(np.sum(g[act] * t[act])) / den if den != 0.0 else 0.0
        p_new = np.maximum(p - tau * t, 0.0)
        over = (p_new == 0.0) & (g < 0.0)
        conj = not over.any()
        if over.any():
            p_new[over] -= tau * g[over]
        p_new *= load / (h2 * p_new.sum())
        change = float(np.sum(np.abs(p_new - p))) / scale
        p = p_new
        if change < _CG_TOL * 10:
            u = ops.normal(p) + f
            act = p > 0
            delta = float(u[act].mean())
            g = u - delta
            ok = bool(np.all(g[~act] >= -1e-8 * max(float(np.abs(f).max()), 1e-300)))
            return p, delta, ok
    return p, delta, False


# ----------------------------------------------------------------------------- tangential
def _stick_solve(ops: GridOperators, stick: np.ndarray, q: np.ndarray, b: np.ndarray
                 ) -> tuple[np.ndarray, bool]:
    """The stick cells' shear for given slip shear and shift: u = b on the stick cells.

    Conjugate gradients on the stick cells' shear (the operator restricted to
    them is symmetric positive definite); ``b`` holds the shift already.
    """
    ns = int(stick.sum())
    q = q.copy()
    if ns == 0:
        return q, True
    m = np.broadcast_to(stick, q.shape)
    res = ops.tangential(q) - b
    r = -np.where(m, res, 0.0)
    d = r.copy()
    rr = float(np.sum(r * r))
    bscale = max(float(np.abs(b[m]).max()), float(np.abs(res[m]).max()), 1e-300)
    for _ in range(_CG_MAX):
        if np.sqrt(rr / (2 * ns)) <= _CG_TOL * bscale:
            return q, True
        kd = np.where(m, ops.tangential(d), 0.0)
        alpha = rr / float(np.sum(d * kd))
        q += alpha * d
        r -= alpha * kd
        rr_new = float(np.sum(r * r))
        d = r + (rr_new / rr) * d
        rr = rr_new
    return q, False


def solve_shifted(ops: GridOperators, k: float, p: np.ndarray, u_p: np.ndarray,
                  shift: np.ndarray, v_old: np.ndarray, q_start: np.ndarray,
                  stick_start: np.ndarray, dir_start: np.ndarray
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray, bool, int]:
    """The shear for a given pressure and rigid shift: Kalker's active set.

    Parameters
    ----------
    ops : GridOperators
    k : float
        Coulomb coefficient.
    p : ndarray, shape (n, n)
        Pressure (cells with p > 0 are in contact).
    u_p : ndarray, shape (2, n, n)
        Tangential displacements the pressure causes (beta != 0).
    shift : ndarray, shape (2,)
        The indenter's rigid shift s at the step's end.
    v_old : ndarray, shape (2, n, n)
        Slip displacement at the step's start.
    q_start, stick_start, dir_start : ndarray
        First guesses: shear, stick set and the unit shear direction of
        slipping cells (shape (2, n, n)).

    Returns
    -------
    q : ndarray, shape (2, n, n)
    v : ndarray, shape (2, n, n)
        Slip displacement at the step's end.
    stick : ndarray of bool, shape (n, n)
    converged : bool
    iterations : int

    Notes
    -----
    A slipping cell's direction is that opposite to the slip its neighbours and
    the shift impose (its own shear's share removed: using the slip itself flips
    the direction of weakly slipping cells back and forth), and it sticks when
    its own shear could hold it (that slip's magnitude below its self-compliance
    times ``k p``). A stuck cell whose shear exceeds ``k p`` slips along it.

    When that loop does not converge, it is run again from the same start with
    a patient rule: a slipping cell sticks only once the directions have turned
    by less than ``_PATIENT_TURN`` in an iteration. Switching cells while the
    directions were still far from their fixed point made one cell at the stick
    edge go back and forth, and the cycling rule then eroded the stick zone a
    cell an iteration (measured: the coupled cycle of a rigid sphere on nu = 0.3,
    n = 32, 8 steps, at Q = 0.375 k P; the patient run converged in 23
    iterations). A loop that converged is kept unchanged.
    """
    first = _active_set(ops, k, p, u_p, shift, v_old, q_start, stick_start, dir_start, 0.0)
    if first[3]:
        return first
    second = _active_set(ops, k, p, u_p, shift, v_old, q_start, stick_start, dir_start,
                         _PATIENT_TURN)
    return second[:4] + (first[4] + second[4],)


def _active_set(ops: GridOperators, k: float, p: np.ndarray, u_p: np.ndarray,
                shift: np.ndarray, v_old: np.ndarray, q_start: np.ndarray,
                stick_start: np.ndarray, dir_start: np.ndarray, patient: float
                ) -> tuple[np.ndarray, np.ndarray, np.ndarray, bool, int]:
    """Kalker's active set for :func:`solve_shifted`; ``patient`` > 0: no slipping cell
    sticks while the directions turn by more than that in an iteration."""
    contact = p > 0
    g = k * np.where(contact, p, 0.0)
    stick = stick_start & contact
    q = np.where(contact, q_start, 0.0)
    e = dir_start.copy()
    slip = contact & ~stick
    b = v_old - u_p + shift[:, None, None]
    gscale = max(float(g.max()), 1e-300)
    kself = ops.self_tangential
    seen: set[bytes] = set()
    cycling = False
    pinned = np.zeros_like(stick)
    hist_x: list[np.ndarray] = []
    hist_f: list[np.ndarray] = []
    for it in range(1, _MAX_SETS + 1):
        q = np.where(slip, g * e, np.where(stick, q, 0.0))
        q, ok = _stick_solve(ops, stick, q, b)
        v = ops.tangential(q) + u_p - shift[:, None, None]
        dv = v - v_old
        vscale = max(float(np.hypot(dv[0], dv[1])[contact].max(initial=0.0)),
                     gscale * kself, 1e-300)
        qmag = np.hypot(q[0], q[1])
        over = stick & (qmag > g * (1.0 + _SET_TOL) + _SET_TOL * gscale)
        rest = dv - kself * q
        rmag = np.hypot(rest[0], rest[1])
        along = rmag - kself * g  # > 0: the imposed slip overcomes k p
        slip_along = dv[0] * e[0] + dv[1] * e[1]
        back = slip & (slip_along > np.where(pinned, _PINNED_TOL, _SET_TOL) * vscale)
        new_e = np.where(rmag > 0, -rest / np.where(rmag > 0, rmag, 1.0), e)
        turn = float(np.max(np.hypot(*(new_e - e))[slip & ~back], initial=0.0))
        if patient and turn > patient:
            back = np.zeros_like(back)
        if not over.any() and not back.any() and turn <= _DIRECTION_TOL and ok:
            # a cell kept slipping to end a cycle must slip (nearly) against its shear
            ok_pinned = not np.any(pinned & slip & (slip_along > _PINNED_TOL * vscale))
            return q, v, stick, ok_pinned, it
        key = stick.tobytes()
        if (over.any() or back.any()) and key in seen:
            cycling = True
        seen.add(key)
        if cycling:  # switch only the worst offender; it then stays slipping
            o_val = np.where(over, qmag / np.maximum(g, 1e-300), 0.0)
            b_val = np.where(back, -along, 0.0)
            over = np.zeros_like(over)
            back = np.zeros_like(back)
            if o_val.max() > 0:
                over.flat[int(np.argmax(o_val))] = True
            elif b_val.max() > 0:
                back.flat[int(np.argmax(b_val))] = True
        if cycling:
            pinned |= over
        if over.any():  # the stuck cells over the limit first: moving both sets at
            back = np.zeros_like(back)  # once alternated between two states at reversals
        frozen = not over.any() and not back.any()
        if frozen:
            # the directions' fixed point converges linearly (a Jacobi-like update, its
            # rate measured up to 0.8): Anderson's mixing over the last _ANDERSON steps
            sel = np.broadcast_to(slip, e.shape)
            x_k, f_k = e[sel], (new_e - e)[sel]
            hist_x.append(x_k)
            hist_f.append(f_k)
            if len(hist_x) > _ANDERSON + 1:
                hist_x.pop(0)
                hist_f.pop(0)
            if len(hist_x) > 1:
                dF = np.stack([hist_f[i + 1] - hist_f[i] for i in range(len(hist_f) - 1)], 1)
                dX = np.stack([hist_x[i + 1] - hist_x[i] for i in range(len(hist_x) - 1)], 1)
                gam, *_ = np.linalg.lstsq(dF, f_k, rcond=None)
                x_new = x_k + _MIX * f_k - (dX + _MIX * dF) @ gam
            else:
                x_new = x_k + _MIX * f_k
            flip = (new_e[0] * e[0] + new_e[1] * e[1]) < 0.0  # reversed: no mixing
            e = e.copy()
            e[sel] = x_new
            e = np.where(flip & slip, new_e, e)
        else:
            hist_x.clear()
            hist_f.clear()
            flip = (new_e[0] * e[0] + new_e[1] * e[1]) < 0.0  # reversed: no mixing
            e = np.where(slip & ~back, np.where(flip, new_e, e + _MIX * (new_e - e)), e)
        emag = np.hypot(e[0], e[1])
        e = np.where(emag > 0, e / np.where(emag > 0, emag, 1.0), e)
        e = np.where(over, q / np.where(qmag > 0, qmag, 1.0), e)
        stick = (stick & ~over) | back
        slip = contact & ~stick
    return q, v, stick, False, _MAX_SETS


def solve_tangential(ops: GridOperators, k: float, p: np.ndarray, u_p: np.ndarray,
                     force: float, v_old: np.ndarray, q_start: np.ndarray,
                     stick_start: np.ndarray, shift_start: float
                     ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, bool, int]:
    """The shear for a given pressure and tangential force Q along x (force control).

    The shift ``s_x`` is found by a safeguarded secant method on the force
    ``Q(s_x)`` (monotonic), each value from :func:`solve_shifted`; ``s_y = 0``
    by the symmetry of the problem in y. The force is met to ``_FORCE_TOL``
    of ``k P``.

    Parameters
    ----------
    ops, k, p, u_p, v_old, q_start, stick_start
        As for :func:`solve_shifted`.
    force : float
        Q_x at the step's end (units E* a_max^3/R), ``|Q| < k P``.
    shift_start : float
        The shift at the step's start.

    Returns
    -------
    q, shift, v, stick, converged, iterations
        ``shift`` shape (2,); the others as for :func:`solve_shifted`
        (iterations: the active-set iterations summed).
    """
    h2 = ops.h * ops.h
    contact = p > 0
    kp = k * float(p.sum()) * h2
    tol = _FORCE_TOL * max(kp, 1e-300)
    mag = np.hypot(q_start[0], q_start[1])
    e0 = np.where(mag > 0, q_start / np.where(mag > 0, mag, 1.0), 0.0)
    total = 0
    state = {"q": q_start, "stick": stick_start, "e": e0, "patient": False}

    def evaluate(sx: float):
        # as solve_shifted; once a loop needed the patient retry, the step's later shifts
        # start patient (at n = 64 each first loop failed after _MAX_SETS iterations)
        nonlocal total
        args = (ops, k, p, u_p, np.array([sx, 0.0]), v_old, state["q"], state["stick"],
                state["e"])
        ok = False
        if not state["patient"]:
            q, v, st, ok, it = _active_set(*args, 0.0)
            total += it
        if not ok:
            q, v, st, ok, it = _active_set(*args, _PATIENT_TURN)
            total += it
            state["patient"] = True
        return float(q[0].sum()) * h2, (q, v, st, ok)

    s0 = float(shift_start)
    f0, sol0 = evaluate(s0)
    if abs(f0 - force) <= tol or not sol0[3]:
        return sol0[0], np.array([s0, 0.0]), sol0[1], sol0[2], sol0[3], total
    state.update(q=sol0[0], stick=sol0[2])
    # first secant step from the stick zone's stiffness, 8 c / C (Mindlin's, c its radius)
    c = np.sqrt(max(float((sol0[2] & contact).sum()) * h2, h2) / np.pi)
    stiff = 8.0 * c / (4.0 + 2.0 * ops.gamma)
    lo = hi = None  # (s, f) brackets: f < force, f > force
    if f0 < force:
        lo = (s0, f0)
    else:
        hi = (s0, f0)
    s1 = s0 + (force - f0) / stiff
    sa, fa = s0, f0
    for _ in range(_MAX_SECANT):
        f1, sol1 = evaluate(s1)
        if not sol1[3]:
            return sol1[0], np.array([s1, 0.0]), sol1[1], sol1[2], False, total
        if abs(f1 - force) <= tol:
            return sol1[0], np.array([s1, 0.0]), sol1[1], sol1[2], True, total
        state.update(q=sol1[0], stick=sol1[2])
        if f1 < force:
            lo = (s1, f1) if lo is None or s1 > lo[0] else lo
        else:
            hi = (s1, f1) if hi is None or s1 < hi[0] else hi
        if f1 != fa:
            s2 = s1 + (force - f1) * (s1 - sa) / (f1 - fa)
        else:
            s2 = s1 + (force - f1) / stiff
        if lo is not None and hi is not None and not (lo[0] < s2 < hi[0]):
            s2 = 0.5 * (lo[0] + hi[0])  # bisect when the secant leaves the bracket
        sa, fa = s1, f1
        s1 = s2
    return sol1[0], np.array([s1, 0.0]), sol1[1], sol1[2], False, total


# ----------------------------------------------------------------------------- path
@dataclass
class SphereStep:
    """One step's solution (units E* = R = a_max = 1)."""

    p: np.ndarray
    q: np.ndarray
    v: np.ndarray
    stick: np.ndarray
    delta: float
    shift: np.ndarray
    converged: bool
    iterations: int


@dataclass
class RawSphereFretting:
    """Per-step arrays of one run (step 0 the unloaded start; units E* = R = a_max = 1).

    ``contact_radius`` and ``stick_radius`` are the mean radii (units a_max)
    from :func:`zone_radius`, ``stick_offset`` the stick zone's centre minus
    the contact's along x; ``p`` (n, n) and ``q`` (2, n, n) per step are kept only
    when asked for.
    """

    load: np.ndarray
    force: np.ndarray
    delta: np.ndarray
    shift: np.ndarray  # (m + 1, 2)
    contact_radius: np.ndarray
    stick_radius: np.ndarray
    stick_offset: np.ndarray
    stick_area: np.ndarray
    contact_area: np.ndarray
    dissipation: np.ndarray
    external_work: np.ndarray
    stored_energy: np.ndarray
    converged: np.ndarray
    iterations: np.ndarray
    p: list
    q: list
    stick: list
    v: list


def zone_radius(ops: GridOperators, inside: np.ndarray) -> tuple[float, float]:
    """Mean radius and x-centre of a zone of cells: the disc of the same area.

    Parameters
    ----------
    ops : GridOperators
    inside : ndarray of bool, shape (n, n)
        The zone's cells (in contact, or stuck).

    Returns
    -------
    radius, centre_x : float
        ``sqrt(area/pi)`` and the centroid's x (units a_max); NaN, NaN when
        the zone is empty.

    Notes
    -----
    The area counts whole cells, so the radius carries a lattice error that
    is not smooth in the cell size (measured below 1e-3 of the radius from
    n = 64 on; see ``tests/test_fretting_sphere.py``). A fit of the square of
    the field that vanishes at the edge, as the cylinder uses, was tried:
    exact where that square is a quadratic (Hertz, Cattaneo), it missed the
    coupled solution's contact radius by 4 % at n = 32, whose pressure has a
    kink at the stick edge inside the fitted band.
    """
    if not inside.any():
        return float("nan"), float("nan")
    area = float(inside.sum()) * ops.h * ops.h
    xx = np.broadcast_to(ops.x[:, None], inside.shape)
    return float(np.sqrt(area / np.pi)), float(xx[inside].mean())


def _step(ops: GridOperators, k: float, load: float, force: float, v_old: np.ndarray,
          p_prev: np.ndarray, q_prev: np.ndarray, stick_prev: np.ndarray,
          load_prev: float, shift_prev: float) -> SphereStep:
    """One load step: the normal and tangential problems, in turn when coupled."""
    n = ops.n
    coupled = ops.beta != 0.0
    if load <= 0.0:
        z = np.zeros((n, n))
        return SphereStep(z, np.zeros((2, n, n)), v_old.copy(), z.astype(bool), 0.0,
                          np.zeros(2), True, 0)
    q = q_prev.copy()
    p = p_prev
    ok_n = True
    delta = float("nan")
    same_load = (load == load_prev) and not coupled and np.any(p_prev > 0)
    stick = stick_prev.copy()
    iters = 0
    for _ in range(_MAX_COUPLING):
        if same_load:
            p_new = p_prev
            delta = float("nan")
        else:
            extra = ops.normal(np.zeros((n, n)), q) if coupled else np.zeros((n, n))
            p_new, delta, ok_n = solve_normal(ops, load, extra, p)
        new_contact = (p_new > 0) & ~(p > 0)
        stick = stick | new_contact  # touching down: first guess stuck
        u_p = ops.tangential(np.zeros((2, n, n)), p_new) if coupled else np.zeros((2, n, n))
        q_new, shift, v, stick, ok_t, it = solve_tangential(ops, k, p_new, u_p, force, v_old,
                                                            q, stick, shift_prev)
        shift_prev = float(shift[0])
        iters += it
        dp = float(np.abs(p_new - p).max()) if p is not None else np.inf
        dq = float(np.abs(q_new - q).max())
        p, q = p_new, q_new
        if not coupled or (dp <= _COUPLING_TOL * p.max() and dq <= _COUPLING_TOL * p.max()
                           and ok_t):
            break
    else:
        ok_t = False
    if not np.isfinite(delta):
        w = ops.normal(p, q if coupled else None) + ops.gap0
        delta = float(w[p > 0].mean())
    return SphereStep(p, q, v, stick, delta, shift, bool(ok_n and ok_t), iters)


def run_sphere_fretting(ops: GridOperators, k: float, load: np.ndarray, force: np.ndarray,
                        keep_fields: bool = False,
                        progress: Callable[[int, int], None] | None = None
                        ) -> RawSphereFretting:
    """Follow a path of (P, Q_x) values from the unloaded start.

    Parameters
    ----------
    ops : GridOperators
    k : float
        Coulomb coefficient, ``0 < k < inf``.
    load, force : ndarray, shape (m,)
        P and Q_x (units E* a_max^3/R) at the end of each step; the start
        (both 0) is not included. ``|Q| < k P`` wherever P > 0.
    keep_fields : bool
        Keep p, q, the stick set and the slip v of every step.
    progress : callable, optional
        ``progress(i, m)`` after each step.

    Returns
    -------
    RawSphereFretting
        Arrays of length ``m + 1`` (the unloaded start first).
    """
    m = load.size
    n = ops.n
    h2 = ops.h ** 2
    out = {name: np.zeros(m + 1) for name in ("delta", "dissipation", "external_work",
                                                "stored_energy", "stick_area",
                                                "contact_area")}
    radii = np.full((m + 1, 3), np.nan)
    shifts = np.zeros((m + 1, 2))
    conv = np.ones(m + 1, dtype=bool)
    iters = np.zeros(m + 1, dtype=np.int32)
    p = np.zeros((n, n))
    q = np.zeros((2, n, n))
    v = np.zeros((2, n, n))
    stick = np.zeros((n, n), dtype=bool)
    prev_load, prev_force = 0.0, 0.0
    fields_p, fields_q, fields_s, fields_v = [], [], [], []
    for i in range(m):
        st = _step(ops, k, float(load[i]), float(force[i]), v, p, q, stick, prev_load,
                   float(shifts[i, 0]))
        j = i + 1
        w_ext = (0.5 * (prev_load + load[i]) * (st.delta - out["delta"][j - 1])
                 + 0.5 * (prev_force + force[i]) * (st.shift[0] - shifts[j - 1, 0]))
        out["external_work"][j] = out["external_work"][j - 1] + w_ext
        slipping = (st.p > 0) & ~st.stick
        dv = np.hypot(*(st.v - v))
        out["dissipation"][j] = out["dissipation"][j - 1] + 0.5 * k * h2 * float(
            np.sum(((p + st.p) * dv)[slipping]))
        w = ops.normal(st.p, st.q if ops.beta != 0.0 else None)
        u = ops.tangential(st.q, st.p if ops.beta != 0.0 else None)
        out["stored_energy"][j] = 0.5 * h2 * float(np.sum(st.p * w) + np.sum(st.q * u))
        out["delta"][j] = st.delta
        shifts[j] = st.shift
        contact = st.p > 0
        out["contact_area"][j] = contact.sum() * h2
        out["stick_area"][j] = (st.stick & contact).sum() * h2
        if contact.any():
            a, ca = zone_radius(ops, contact)
            c, cc = zone_radius(ops, st.stick & contact)
            radii[j] = (a, c if st.stick.any() else 0.0,
                        cc - ca if st.stick.any() else np.nan)
        conv[j] = st.converged
        iters[j] = st.iterations
        if keep_fields:
            fields_p.append(st.p)
            fields_q.append(st.q)
            fields_s.append(st.stick)
            fields_v.append(st.v)
        p, q, v, stick = st.p, st.q, st.v, st.stick
        prev_load, prev_force = float(load[i]), float(force[i])
        if progress is not None:
            progress(j, m)
    return RawSphereFretting(
        load=np.concatenate(([0.0], load)), force=np.concatenate(([0.0], force)),
        delta=out["delta"], shift=shifts, contact_radius=radii[:, 0],
        stick_radius=radii[:, 1], stick_offset=radii[:, 2], stick_area=out["stick_area"],
        contact_area=out["contact_area"], dissipation=out["dissipation"],
        external_work=out["external_work"], stored_energy=out["stored_energy"],
        converged=conv, iterations=iters, p=fields_p, q=fields_q, stick=fields_s,
        v=fields_v)
