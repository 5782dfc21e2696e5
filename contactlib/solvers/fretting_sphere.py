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
the cylinder's kernels in :mod:`contactlib.solvers.fretting_solver`, to which these
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
  (force control). For a given pressure these are the optimality conditions of
  a convex problem, the minimum of ``q.(K q)/2 + q.(u_p - v_old)`` over the
  shear fields inside the discs ``|q| <= k p`` that carry the force, ``K`` the
  symmetric positive definite shear operator and ``s`` the force's multiplier
  (:func:`solve_tangential`): one minimum, found by accelerated projected
  gradients with restarts. It replaced Kalker's active set with a secant on
  the shift, whose sets cycled at n = 64 on the coupled pairs. Displacement
  control (``s_x`` prescribed): the minimum of
  ``q.(K q)/2 + q.(u_p - v_old - s_x e_x)`` over the discs alone, Q the output;
  gross sliding (``|Q| = k P``, no stuck cell) is reached like any other state.
* coupling (beta != 0): the normal and tangential problems are solved in
  turn until the pressure and the shear change by less than
  ``_COUPLING_TOL`` of the pressure's scale, the shear to a tolerance that
  follows the change (``_INEXACT``); at beta = 0 the normal problem is solved
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

from ..model import Contact

__all__ = [
    "MESH_EXTENT",
    "GridOperators",
    "RawSphereFretting",
    "SphereStep",
    "DIRECTIONS",
    "direction_radii",
    "edge_radius",
    "zone_centre",
    "grid_operators",
    "mindlin_compliance",
    "run_sphere_fretting",
    "solve_normal",
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
# tested: tests/test_fretting_sphere_coupled.py (tiny beta: within 1e-4 of beta = 0)
_COUPLING_TOL = 1e-9
# convention: a coupled step not settled in 100 alternations is reported as not converged
_MAX_COUPLING = 100
# tested: tests/test_fretting_sphere_api.py (the shift at Q* against Mindlin's)
_FORCE_TOL = 1e-12  # the force Q met by the projection, relative to k P
# convention: a projection's force not met in 200 Newton-bisection steps: not converged
_PROJECT_MAX = 200
# tested: tests/test_fretting_sphere.py (Cattaneo–Mindlin within estimates; the cycles' work)
_QP_TOL = 1e-11  # the shear's projected-gradient step at which it stops, relative to k p
# convention: a shear not settled in 20000 projected-gradient steps is not converged
_QP_MAX = 20000
# tested: tests/test_fretting_sphere.py (Cattaneo–Mindlin's stick ratio within its estimate)
_SLIP_TOL = 1e-7  # a cell slips when its slip increment exceeds this of the slip scale
# measured: benchmarks/report_fretting_sphere.py (the coupled cycles' cost)
_INEXACT = 1e-2  # a coupled alternation's shear tolerance over the last change
# measured: benchmarks/report_fretting_sphere.py (the coupled cycles' cost)
_QP_LOOSE = 1e-6  # the first alternation's shear tolerance


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


def grid_operators(model: Contact, n: int, extent: float = MESH_EXTENT,
                   offset: tuple[float, float] = (0.0, 0.0)) -> GridOperators:
    """Influence coefficients of ``n x n`` square cells over ``[-extent, extent]^2``.

    Parameters
    ----------
    model : Contact
        A sphere (axisymmetric profile) on a half-space, rigid or elastic.
    n : int
        Cells along each side (even: no centre lies on an axis).
    extent : float
        Half-width of the grid over a_max.
    offset : (float, float)
        The profile's axis at ``(offset[0] h, offset[1] h)`` (in cells; default on the
        grid's centre, a cell corner). The kernels depend on the cells' offsets only, so
        the offset moves the gap alone: the grid's placement under the contact, whose
        lattice error it samples (the work over a cycle changes by up to 4 % with it at
        n = 16; benchmarks/report_fretting_sphere_estimate.py). The zone measures along
        the axes (:func:`edge_radius`, the rows next to y = 0) assume no offset.

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
    r = np.hypot(xx - offset[0] * h, yy - offset[1] * h)
    return GridOperators(n=n, h=h, x=x, gap0=prof.gap(r), beta=beta,
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
def _lipschitz(ops: GridOperators) -> float:
    """The largest eigenvalue of the shear-to-displacement operator's circulant embedding
    (an upper bound of the restricted operator's; units a_max/E*)."""
    kx, ky, kxy = (ops.kernels[name].real for name in ("xx", "yy", "xy"))
    return float((0.5 * (kx + ky) + np.sqrt(0.25 * (kx - ky) ** 2 + kxy ** 2)).max())


def _discs(z: np.ndarray, g: np.ndarray, mu: float
           ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The projection of ``z + mu e_x`` (shape (2, m)) on the discs ``|q_i| <= g_i``; also
    ``|z_i + mu e_x|`` and where it lies outside its disc."""
    wx, zy = z[0] + mu, z[1]
    r = np.hypot(wx, zy)
    out = r > g
    f = np.where(out, g / np.where(out, r, 1.0), 1.0)
    return np.stack([wx * f, zy * f]), r, out


def _project(z: np.ndarray, g: np.ndarray, target: float, mu: float
             ) -> tuple[np.ndarray, float, bool]:
    """The projection of ``z`` (shape (2, m)) on the discs ``|q_i| <= g_i`` and the force
    ``sum q_x = target``: ``q_i`` the disc's point nearest ``z_i + mu e_x``, ``mu`` found by
    a safeguarded Newton method (the sum grows with ``mu``); ``mu`` in is the first guess.
    Returns the projection, ``mu`` and whether the force was met to ``_FORCE_TOL``."""
    zx, zy = z
    gsum = float(g.sum())
    span = float(np.abs(zx).max(initial=0.0) + np.abs(zy).max(initial=0.0) + g.max())
    lo, hi = -np.inf, np.inf
    q = z
    for _ in range(_PROJECT_MAX):
        q, r, out = _discs(z, g, mu)
        rr = np.where(out, r, 1.0)
        val = float(q[0].sum()) - target
        if abs(val) <= _FORCE_TOL * gsum:
            return q, mu, True
        if val < 0.0:
            lo = mu
        else:
            hi = mu
        der = float(np.where(out, g * zy * zy / rr ** 3, 1.0).sum())
        step = mu - val / der if der > 0.0 else np.nan
        if np.isfinite(lo) and np.isfinite(hi):
            if hi - lo <= 1e-15 * span:
                break  # the force's mismatch at the bracket's resolution
            if not lo < step < hi:
                step = 0.5 * (lo + hi)
        elif not np.isfinite(step):
            step = mu + (span if val < 0.0 else -span)
        mu = step
    return q, mu, bool(abs(float(q[0].sum()) - target) <= _FORCE_TOL * gsum)


def solve_tangential(ops: GridOperators, k: float, p: np.ndarray, u_p: np.ndarray,
                     force: float | None, v_old: np.ndarray, q_start: np.ndarray,
                     tol: float = 0.0, shift: float | None = None
                     ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, bool, int]:
    """The shear for a given pressure and tangential force Q, or rigid shift s, along x.

    For a given pressure the step's conditions (stick: ``dv = 0``, ``|q| <= k p``;
    slip: ``q = -k p dv/|dv|``; ``sum q h^2 = (Q, 0)``) are those of the minimum of
    ``q.(K q)/2 + q.(u_p - v_old)`` over the shear fields with ``|q| <= k p`` cell by
    cell and the force Q, ``K`` the symmetric positive definite shear-to-displacement
    operator: a convex problem with one minimum, whose force multiplier is the rigid
    shift ``s_x``. It is solved by accelerated projected gradients (FISTA, restarted
    when the step turns back; the step ``1/L``, ``L`` from :func:`_lipschitz`), the
    projection on the discs and the force by :func:`_project`. ``s_y = 0`` (symmetry).

    With the shift ``s_x`` prescribed (displacement control) the minimum is that of
    ``q.(K q)/2 + q.(u_p - v_old - s_x e_x)`` over the discs alone: no force constraint,
    the projection on the discs only; Q is the output (``sum q_x h^2``), and gross
    sliding (every cell slipping, ``|Q| = k P``) is a solution like any other.

    Parameters
    ----------
    ops : GridOperators
    k : float
        Coulomb coefficient.
    p : ndarray, shape (n, n)
        Pressure (cells with p > 0 are in contact).
    u_p : ndarray, shape (2, n, n)
        Tangential displacements the pressure causes (beta != 0), units a_max^2/R.
    force : float or None
        Q_x at the step's end (units E* a_max^3/R), ``|Q| < k P``; ignored when
        ``shift`` is given.
    v_old : ndarray, shape (2, n, n)
        Slip displacement at the step's start.
    q_start : ndarray, shape (2, n, n)
        First guess of the shear (the previous step's).
    tol : float
        The projected-gradient step's size at which the iteration stops, relative to
        ``max k p``; at most ``_QP_TOL`` is used (a looser value: a coupled step's
        early alternations).
    shift : float, optional
        The prescribed rigid shift ``s_x`` at the step's end (units a_max^2/R):
        displacement control.

    Returns
    -------
    q : ndarray, shape (2, n, n)
    shift : ndarray, shape (2,)
        ``(s_x, 0)``: the force's multiplier, or the prescribed shift.
    v : ndarray, shape (2, n, n)
        Slip displacement at the step's end (``v_old`` on the stuck cells).
    stick : ndarray of bool, shape (n, n)
        Cells in contact whose slip increment is below ``_SLIP_TOL`` of the slip scale.
    converged : bool
        The iteration stopped at ``max(tol, _QP_TOL)`` within ``_QP_MAX`` iterations and
        its last projection met the force to ``_FORCE_TOL`` (force control).
    iterations : int
    """
    n = ops.n
    h2 = ops.h * ops.h
    contact = p > 0
    g = k * p[contact]
    gscale = max(float(g.max(initial=0.0)), 1e-300)
    c = (u_p - v_old)[:, contact]
    t = 1.0 / _lipschitz(ops)
    stop = max(tol, _QP_TOL) * gscale
    full = np.zeros((2, n, n))

    def grad(x: np.ndarray) -> np.ndarray:
        full[:, contact] = x
        return ops.tangential(full)[:, contact] + c

    if shift is None:
        def project(z: np.ndarray, mu: float) -> tuple[np.ndarray, float, bool]:
            return _project(z, g, force / h2, mu)

        q, mu, _ = project(q_start[:, contact], 0.0)
    else:  # the shift's term of the gradient, -s_x e_x, enters the projection as mu = t s_x
        def project(z: np.ndarray, mu: float) -> tuple[np.ndarray, float, bool]:
            return _discs(z, g, t * shift)[0], t * shift, True

        q, mu = _discs(q_start[:, contact], g, 0.0)[0], t * shift
    y = q
    theta = 1.0
    ok = False
    it = 0
    for it in range(1, _QP_MAX + 1):
        q_new, mu, met = project(y - t * grad(y), mu)
        if float(np.abs(q_new - y).max()) <= stop:
            q, ok = q_new, met
            break
        if float(np.sum((y - q_new) * (q_new - q))) > 0.0:  # turned back: restart
            theta, y = 1.0, q_new
        else:
            theta_new = 0.5 * (1.0 + np.sqrt(1.0 + 4.0 * theta * theta))
            y = q_new + ((theta - 1.0) / theta_new) * (q_new - q)
            theta = theta_new
        q = q_new
    # the force's multiplier (or the prescribed shift): K q + u_p - v_old = s where stuck
    s_vec = np.array([mu / t if shift is None else shift, 0.0])
    q_full = np.zeros((2, n, n))
    q_full[:, contact] = q
    v = ops.tangential(q_full) + u_p - s_vec[:, None, None]
    dv = np.hypot(*(v - v_old))
    vscale = max(float(dv[contact].max(initial=0.0)), gscale * ops.self_tangential)
    stick = contact & (dv <= _SLIP_TOL * vscale)
    return q_full, s_vec, np.where(stick, v_old, v), stick, ok, it

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
    the contact's along x, ``contact_edge_radius`` and ``stick_edge_radius`` the
    radii from :func:`edge_radius` (a second measure of the same zones); ``p``
    (n, n) and ``q`` (2, n, n) per step are kept only
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
    contact_edge_radius: np.ndarray
    stick_edge_radius: np.ndarray
    dissipation: np.ndarray
    external_work: np.ndarray
    stored_energy: np.ndarray
    converged: np.ndarray
    iterations: np.ndarray
    p: list
    q: list
    stick: list
    v: list
    angles: np.ndarray | None = None  # (D,), radians from +x
    contact_directions: np.ndarray | None = None  # (m + 1, 2, D): edge, half level
    stick_directions: np.ndarray | None = None  # (m + 1, 2, D): edge, half level
    contact_centre: np.ndarray | None = None  # (m + 1, 2): the contact rays' origin
    stick_centre: np.ndarray | None = None  # (m + 1, 2): the stick rays' origin


def zone_centre(ops: GridOperators, inside: np.ndarray) -> tuple[float, float]:
    """The centroid ``(x, y)`` of a zone of cells (units a_max); NaN, NaN when empty."""
    if not inside.any():
        return float("nan"), float("nan")
    i, j = np.nonzero(inside)
    return float(ops.x[i].mean()), float(ops.x[j].mean())


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


# exact: d ~ (c - r)^(3/2) inside an advancing stick edge, (c - r)^(1/2) inside a receding
# one (Spence; Cattaneo)
EDGE_EXPONENTS = (2.0 / 3.0, 2.0)


def edge_radius(ops: GridOperators, field: np.ndarray, inside: np.ndarray) -> float:
    """A zone's radius from its edge located inside the cells, along the axes.

    On the rows of cells next to the x and y axes, the edge on each side lies
    past the zone's outermost cell's centre where ``field`` (linear in the
    distance to the edge there) vanishes, extrapolated from that cell and its
    inner neighbour and kept within one cell (the next cell is outside). The
    radius is the mean of the zone's half-widths along x and along y: a second
    measure of the zone next to :func:`zone_radius`'s.

    Parameters
    ----------
    ops : GridOperators
    field : ndarray, shape (n, n)
        Vanishes linearly at the edge: ``p^2`` at a contact's edge, the traction
        deficit ``d = 1 - |q|/(k p)`` raised to ``EDGE_EXPONENTS`` at a stick
        zone's (dimensionless or units E*^2).
    inside : ndarray of bool, shape (n, n)
        The zone's cells.

    Returns
    -------
    float
        Radius (units a_max); NaN when a row holds fewer than two of the
        zone's cells or the field does not fall towards an edge.
    """
    row = ops.n // 2  # the cells at +h/2 from the axis
    half = []
    for line, st in ((field[:, row], inside[:, row]), (field[row, :], inside[row, :])):
        cells = np.flatnonzero(st)
        if cells.size < 2:
            return float("nan")
        width = float(ops.x[cells[-1]] - ops.x[cells[0]])
        for i, inner in ((cells[-1], -1), (cells[0], 1)):
            f1, f0 = line[i], line[i + inner]
            if not (st[i + inner] and f0 > f1):
                return float("nan")
            width += ops.h * min(f1 / (f0 - f1), 1.0)
        half.append(0.5 * width)
    return float(0.5 * (half[0] + half[1]))


# convention: directions of the per-direction radii, from +x (the tangential load's) on
DIRECTIONS = 24
# convention: samples a cell along each ray (the bilinear interpolants' resolution)
_RAY_SAMPLES = 4


def direction_radii(ops: GridOperators, field: np.ndarray, inside: np.ndarray,
                    angles: np.ndarray, centre: tuple[float, float] = (0.0, 0.0)
                    ) -> tuple[np.ndarray, np.ndarray]:
    """A zone's radius along each direction from a centre (the zone's centroid).

    Along each ray from ``centre``, samples ``_RAY_SAMPLES`` a cell interpolate the cell
    values bilinearly (between the four nearest cell centres). Two measures of the edge:

    * the *edge*: from the last sample whose four cells are in the zone, ``field``
      (vanishing linearly at the edge, as for :func:`edge_radius`) is extrapolated with
      the sample one cell further in to its zero, at most ``sqrt(2) h`` on; on the axes
      from a centre on the x axis this is :func:`edge_radius`'s fit along x (the rows at
      y = +-h/2 are mirror images);
    * the *half level*: where the bilinear interpolant of the zone's indicator (1 in, 0
      out) first falls to 1/2: halfway between the last cell in and the first out along
      an axis.

    Vectorized over the rays and their samples.

    Parameters
    ----------
    ops : GridOperators
    field : ndarray, shape (n, n)
        Vanishes linearly at the edge (``p^2``, or ``d^e``; see :func:`edge_radius`).
    inside : ndarray of bool, shape (n, n)
        The zone's cells.
    angles : ndarray, shape (D,)
        Directions (radians from +x).
    centre : (float, float)
        The rays' origin (units a_max).

    Returns
    -------
    edge, half : ndarray, shape (D,)
        Radii (units a_max); 0 for an empty zone; NaN where the centre is outside the zone
        (a ray from it does not describe the zone), where the ray leaves the grid, or
        where the field does not fall towards the edge (``edge`` only).
    """
    d = angles.size
    if not inside.any():
        return np.zeros(d), np.zeros(d)
    n, h = ops.n, ops.h
    step = h / _RAY_SAMPLES
    t = step * np.arange(int(np.ceil(np.sqrt(2.0) * MESH_EXTENT / step)) + 1)
    px = centre[0] + t[:, None] * np.cos(angles)[None, :]
    py = centre[1] + t[:, None] * np.sin(angles)[None, :]
    u, v = (px - ops.x[0]) / h, (py - ops.x[0]) / h
    i0, j0 = np.floor(u).astype(int), np.floor(v).astype(int)
    on = (i0 >= 0) & (i0 < n - 1) & (j0 >= 0) & (j0 < n - 1)
    i0, j0 = np.clip(i0, 0, n - 2), np.clip(j0, 0, n - 2)
    fx, fy = u - i0, v - j0
    w = ((1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy)
    corners = ((i0, j0), (i0 + 1, j0), (i0, j0 + 1), (i0 + 1, j0 + 1))
    ins = inside.astype(float)
    level = sum(wk * ins[c] for wk, c in zip(w, corners))
    value = sum(wk * field[c] for wk, c in zip(w, corners))
    # a corner of no weight (a sample on a line of centres) does not count
    all_in = on & np.all([inside[c] | (wk < 1e-12) for wk, c in zip(w, corners)], axis=0)
    cols = np.arange(d)
    # half level: the first sample below 1/2, linear between it and the one before
    below = ~on | (level < 0.5)
    k1 = np.argmax(below, axis=0)
    ok1 = below.any(axis=0) & (k1 > 0) & on[np.maximum(k1, 0), cols]
    prev = level[np.maximum(k1 - 1, 0), cols]
    with np.errstate(invalid="ignore", divide="ignore"):
        half = t[np.maximum(k1 - 1, 0)] + step * (prev - 0.5) / (prev - level[k1, cols])
    half = np.where(ok1, half, np.nan)
    # edge: the last sample with its four cells in, and the one a cell further in
    out = ~all_in
    k2 = np.argmax(out, axis=0) - 1
    back = k2 - _RAY_SAMPLES
    ok2 = out.any(axis=0) & (back >= 0) & on[np.minimum(k2 + 1, t.size - 1), cols]
    f_in = value[np.maximum(k2, 0), cols]
    f_back = value[np.maximum(back, 0), cols]
    ok2 &= all_in[np.maximum(back, 0), cols] & (f_back > f_in)
    with np.errstate(invalid="ignore", divide="ignore"):
        ext = np.minimum(h * f_in / (f_back - f_in), np.sqrt(2.0) * h)
    edge = np.where(ok2, t[np.maximum(k2, 0)] + ext, np.nan)
    return edge, half


def _step(ops: GridOperators, k: float, load: float, force: float | None, v_old: np.ndarray,
          p_prev: np.ndarray, q_prev: np.ndarray, load_prev: float,
          shift: float | None = None) -> SphereStep:
    """One load step: the normal and tangential problems, in turn when coupled (the force
    Q, or with ``shift`` the rigid shift, prescribed: :func:`solve_tangential`).

    A coupled step's alternations solve the shear to ``_INEXACT`` times the last
    alternation's change (between ``_QP_TOL`` and ``_QP_LOOSE``); the step is accepted
    once the pressure and the shear change by less than ``_COUPLING_TOL`` of the
    pressure's scale after a shear solved to ``_QP_TOL``.
    """
    n = ops.n
    coupled = ops.beta != 0.0
    if load <= 0.0:
        z = np.zeros((n, n))
        return SphereStep(z, np.zeros((2, n, n)), v_old.copy(), z.astype(bool), 0.0,
                          np.zeros(2), True, 0)
    q = q_prev.copy()
    p = p_prev
    ok_n = ok = False
    delta = float("nan")
    same_load = (load == load_prev) and not coupled and np.any(p_prev > 0)
    iters = 0
    tol = _QP_LOOSE if coupled else _QP_TOL
    u_p = np.zeros((2, n, n))
    for _ in range(_MAX_COUPLING):
        if same_load:
            p_new, ok_n = p_prev, True
        else:
            extra = ops.normal(np.zeros((n, n)), q) if coupled else np.zeros((n, n))
            p_new, delta, ok_n = solve_normal(ops, load, extra, p)
        if coupled:
            u_p = ops.tangential(np.zeros((2, n, n)), p_new)
        q_new, s_vec, v, stick, ok_t, it = solve_tangential(ops, k, p_new, u_p, force, v_old,
                                                            q, tol, shift)
        iters += it
        change = max(float(np.abs(p_new - p).max()), float(np.abs(q_new - q).max())) \
            / float(p_new.max())
        exact = tol <= _QP_TOL
        p, q = p_new, q_new
        if not coupled or (change <= _COUPLING_TOL and exact):
            ok = ok_n and ok_t
            break
        tol = min(max(_INEXACT * change, _QP_TOL), _QP_LOOSE)
    if not np.isfinite(delta):
        w = ops.normal(p, q if coupled else None) + ops.gap0
        delta = float(w[p > 0].mean())
    return SphereStep(p, q, v, stick, delta, s_vec, bool(ok), iters)


def run_sphere_fretting(ops: GridOperators, k: float, load: np.ndarray,
                        force: np.ndarray | None, keep_fields: bool = False,
                        progress: Callable[[int, int], None] | None = None, *,
                        shift: np.ndarray | None = None,
                        directions: int = DIRECTIONS) -> RawSphereFretting:
    """Follow a path of (P, Q_x) values, or of (P, s_x) values, from the unloaded start.

    Parameters
    ----------
    ops : GridOperators
    k : float
        Coulomb coefficient, ``0 < k < inf``.
    load, force : ndarray, shape (m,)
        P and Q_x (units E* a_max^3/R) at the end of each step; the start
        (both 0) is not included. ``|Q| < k P`` wherever P > 0. ``force`` is
        ignored (None) when ``shift`` is given.
    keep_fields : bool
        Keep p, q, the stick set and the slip v of every step.
    progress : callable, optional
        ``progress(i, m)`` after each step.
    shift : ndarray, shape (m,), optional
        The prescribed rigid shift s_x (units a_max^2/R) at the end of each step
        (displacement control, 0 where P = 0): Q_x is then the output, ``force`` of the
        result, and may reach ``k P`` (gross sliding: no stuck cell).
    directions : int
        Directions of the per-direction radii (:func:`direction_radii`), evenly spaced
        from +x.

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
    edge = np.full((m + 1, 2), np.nan)
    angles = 2.0 * np.pi * np.arange(directions) / directions
    rays = np.full((2, m + 1, 2, directions), np.nan)
    centres = np.full((2, m + 1, 2), np.nan)
    shifts = np.zeros((m + 1, 2))
    conv = np.ones(m + 1, dtype=bool)
    iters = np.zeros(m + 1, dtype=np.int32)
    p = np.zeros((n, n))
    q = np.zeros((2, n, n))
    v = np.zeros((2, n, n))
    prev_load, prev_force = 0.0, 0.0
    fields_p, fields_q, fields_s, fields_v = [], [], [], []
    forces = np.zeros(m)
    for i in range(m):
        if shift is None:
            st = _step(ops, k, float(load[i]), float(force[i]), v, p, q, prev_load)
            forces[i] = force[i]
        else:
            st = _step(ops, k, float(load[i]), None, v, p, q, prev_load, float(shift[i]))
            forces[i] = float(st.q[0].sum()) * h2
        j = i + 1
        w_ext = (0.5 * (prev_load + load[i]) * (st.delta - out["delta"][j - 1])
                 + 0.5 * (prev_force + forces[i]) * (st.shift[0] - shifts[j - 1, 0]))
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
            grew = out["stick_area"][j] > out["stick_area"][j - 1]
            with np.errstate(divide="ignore", invalid="ignore"):
                deficit = np.clip(1.0 - np.hypot(*st.q) / (k * st.p), 0.0, 1.0)
            power = deficit ** EDGE_EXPONENTS[0 if grew else 1]
            edge[j] = (edge_radius(ops, st.p ** 2, contact),
                       edge_radius(ops, power, st.stick & contact))
            centres[0, j] = zone_centre(ops, contact)
            centres[1, j] = zone_centre(ops, st.stick & contact)
            rays[0, j] = direction_radii(ops, st.p ** 2, contact, angles, centres[0, j])
            rays[1, j] = direction_radii(ops, power, st.stick & contact, angles,
                                         centres[1, j])
        conv[j] = st.converged
        iters[j] = st.iterations
        if keep_fields:
            fields_p.append(st.p)
            fields_q.append(st.q)
            fields_s.append(st.stick)
            fields_v.append(st.v)
        p, q, v = st.p, st.q, st.v
        prev_load, prev_force = float(load[i]), float(forces[i])
        if progress is not None:
            progress(j, m)
    return RawSphereFretting(
        load=np.concatenate(([0.0], load)), force=np.concatenate(([0.0], forces)),
        delta=out["delta"], shift=shifts, contact_radius=radii[:, 0],
        stick_radius=radii[:, 1], stick_offset=radii[:, 2], stick_area=out["stick_area"],
        contact_area=out["contact_area"], contact_edge_radius=edge[:, 0],
        stick_edge_radius=edge[:, 1],
        dissipation=out["dissipation"],
        external_work=out["external_work"], stored_energy=out["stored_energy"],
        converged=conv, iterations=iters, p=fields_p, q=fields_q, stick=fields_s,
        v=fields_v, angles=angles, contact_directions=rays[0], stick_directions=rays[1],
        contact_centre=centres[0], stick_centre=centres[1])
