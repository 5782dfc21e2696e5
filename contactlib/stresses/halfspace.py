"""Stresses inside the elastic body under the solved surface tractions (issue 38).

The body is the elastic half-space (sphere, axisymmetric) or half-plane (cylinder, plane
strain) z >= 0 under a pressure p and a shear q on its surface z = 0, both tabulated on
``xi`` = r/a (x/a) in [0, 1], continuous and piecewise linear between the tabulated
points, zero outside. Lengths are in units of a, stresses in the unit of the tabulated
tractions (p0 for a :class:`~contactlib.result.Solution`). Signs: tension positive, z
positive into the body, p positive in compression and q the traction on the body,
positive away from the axis, so that the surface limits are sigma_zz = -p and
sigma_rz = -q (sigma_xz = -q for x > 0) (docs/conventions.md). The cylinder's shear is odd
in x: q(-x) = -q(x).

Method
------
Half-plane (plane strain), exact for the piecewise-linear tractions: the Flamant
kernels (Johnson, *Contact Mechanics*, 1985, Ch. 2) integrated in closed form over each
linear piece (antiderivatives of u^k / (u^2 + z^2)^2, k = 0 ... 4); only round-off is
added to the tractions' own discretization. sigma_yy = nu (sigma_xx + sigma_zz).

Half-space (axisymmetric): Hankel transforms (Boussinesq's potentials, Sneddon)

    sigma_zz = int xi e^{-xi z} J0 [-P (1 + xi z) + Q xi z] dxi,
    sigma_rz = int xi e^{-xi z} J1 [-P xi z - Q (1 - xi z)] dxi,

    sigma_rr = int xi e^{-xi z} {J0 [(2Q - P) + (P - Q) xi z] + J1/(xi r) B} dxi,
    sigma_tt = int xi e^{-xi z} {J0 2 nu (Q - P) - J1/(xi r) B} dxi,
    B = (1 - 2 nu) P - 2 (1 - nu) Q + (Q - P) xi z,

(Papkovich-Neuber potentials 2G u = grad(phi + z psi) - 4 (1 - nu) psi e_z), with P(xi) =
int p J0(xi r) r dr and Q(xi) = int q J1(xi r) r dr in closed form for the piecewise-linear
tractions (``scipy.special.itj0y0``). The xi integral is Gauss-Legendre on panels of width
``PANEL/(1 + max r)`` = 2 pi/(1 + max r) (8 points each; beyond the first few, panels of
``TAIL_PERIODS`` such widths with 32 points) up to 36/z_min (e^{-36} < 3e-16), where z_min
is the smallest positive depth asked for; each depth takes the xi values up to 40/z only.
Halving the panels changes the field by 1e-10 p0 (benchmarks/bench_stresses.py). On the
surface (z = 0) the field is in closed form: the pressure's part is Johnson's
(sigma_rr = (1 - 2 nu)/r^2 int_0^r p t dt - p, Johnson Ch. 3), the shear's part follows
from U(r) = int q(t) t W(r, t) dt with the ring kernel W = int_0^inf J1(k r) J1(k t) dk
(complete elliptic integrals K, E), integrated over each linear piece by Gauss-Legendre
(tanh-sinh next to the kernel's log singularity at t = r): 2e-12 p0 against rules of
twice the density, and the closed form of q = r on r < a to 1e-13 (benchmarks/
bench_stresses.py).

A layer of thickness h on a smooth or bonded rigid base (sphere and cylinder):
:func:`layer_stresses`, the half-space's field plus the correction of
:mod:`contactlib.stresses.layer` (its notes give the method).

Memory is bounded by working in chunks of about ``CHUNK`` numbers an array (a few arrays
of 8 * CHUNK bytes at once).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np
import scipy.special as sp

__all__ = ["halfplane_stresses", "halfplane_stresses_line", "halfspace_stresses",
           "stress_field", "principal_stresses", "von_mises", "tresca", "hydrostatic",
           "derived_measures", "subsurface_stresses", "field_maximum",
           "surface_radial_stress", "default_grid", "check_subsurface_request", "body_field",
           "with_subsurface", "first_yield", "history_stresses", "scene_subsurface",
           "cylinder_fretting_stresses",
           "field_error_estimate", "layer_stresses", "COMPONENTS", "XI_SURFACE", "PANEL",
           "CHUNK", "DEPTH_CUTOFF", "TAIL_PERIODS", "RING_TANH_SINH", "RING_GAUSS",
           "TractionPieces", "xi_nodes", "check_tractions",
           "check_grid"]

COMPONENTS = {"sphere": ("sigma_rr", "sigma_tt", "sigma_zz", "sigma_rz"),
              "cylinder": ("sigma_xx", "sigma_yy", "sigma_zz", "sigma_xz")}
"""The stress components of each geometry, in the order of the returned dictionaries
(``sigma_tt`` is the hoop stress sigma_theta_theta)."""

# measured: benchmarks/bench_stresses.py (the peak memory of a 100 x 100 field, 38-42 MiB)
CHUNK = 250_000
"""Numbers in one working array of a chunk (2 MB)."""

# tested: tests/test_stresses_tangential.py (the tangential field's surface row with this cut
# is the interior's limit to 1e-4; report_stresses.py section 3 measured 2.1e-5 p0 against a
# cut at 64000 for the axisymmetric surface, which is now in closed form)
XI_SURFACE = 4000.0
"""Upper end of the xi integral of the tangential field's surface (z = 0) stresses
(:mod:`contactlib.stresses.tangential`); the axisymmetric surface row is in closed form."""

# exact: e^-36 = 2.3e-16, below the double precision of the integrand's scale
DEPTH_CUTOFF = 36.0
"""xi_max z_min of the xi quadrature inside the body: e^-36 = 2.3e-16."""
_GAUSS = np.polynomial.legendre.leggauss(8)


# ----------------------------------------------------------------------------- input
def check_tractions(xi: Any, pressure: Any,
                    shear: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The tabulated tractions as float arrays, checked (nodes increasing in [0, inf))."""
    from ..validate import InputError

    r = np.asarray(xi, dtype=float)
    p = np.asarray(pressure, dtype=float)
    q = np.asarray(shear, dtype=float)
    if r.ndim != 1 or r.size < 2 or p.shape != r.shape or q.shape != r.shape:
        raise InputError("xi", "a 1-d array of at least 2 points, with pressure and shear "
                         "of the same shape", r.shape)
    if not (np.all(np.isfinite(r)) and np.all(np.isfinite(p)) and np.all(np.isfinite(q))):
        raise InputError("pressure", "finite (xi, pressure and shear)", "non-finite values")
    if r[0] < 0 or np.any(np.diff(r) <= 0):
        raise InputError("xi", "increasing and >= 0", r)
    return r, p, q


def check_grid(x: Any, z: Any) -> tuple[np.ndarray, np.ndarray]:
    """The output grid's coordinates: 1-d, finite, z >= 0."""
    from ..validate import InputError

    xs = np.atleast_1d(np.asarray(x, dtype=float))
    zs = np.atleast_1d(np.asarray(z, dtype=float))
    if xs.ndim != 1 or zs.ndim != 1 or not (np.all(np.isfinite(xs)) and np.all(np.isfinite(zs))):
        raise InputError("x", "1-d finite arrays (x and z)", (xs.shape, zs.shape))
    if np.any(zs < 0):
        raise InputError("z", "depths >= 0 (z is positive into the body)", zs.min())
    return xs, zs


# ----------------------------------------------------------------------------- half-plane
def _plane_antiderivatives(u: np.ndarray, z: np.ndarray) -> dict[str, np.ndarray]:
    """Antiderivatives in u of the Flamant kernels' moments, scaled to stay finite at z = 0.

    With D = u^2 + z^2 and M_k = int u^k / D^2 du: ``z3M0`` = z^3 M0, ``z2M1``, ``zM2``,
    ``M3``, ``M4``.
    """
    d = u * u + z * z
    dsafe = np.where(d > 0, d, 1.0)  # ln(dsafe) = 0 where d = 0
    zinv = z * (0.5 / dsafe)
    zu = zinv * u
    half_at = 0.5 * np.arctan2(u, z)
    z2M1 = -z * zinv
    return {"z3M0": half_at + zu,
            "z2M1": z2M1,
            "zM2": half_at - zu,
            "M3": 0.5 * np.log(dsafe) - z2M1,
            "M4": u - 3.0 * z * half_at - z2M1 * u}


def halfplane_stresses(xi: Any, pressure: Any, shear: Any, x: Any, z: Any,
                       nu: float) -> dict[str, np.ndarray]:
    """Plane-strain stresses in the half-plane z >= 0 under tabulated p(x) and q(x).

    Parameters
    ----------
    xi : array_like, shape (m,)
        Increasing abscissae x/a >= 0 of the tabulated tractions (usually 0 ... 1).
    pressure, shear : array_like, shape (m,)
        p and q at ``xi`` (any stress unit, e.g. p0); piecewise linear between, zero
        beyond ``xi[-1]``. p is even in x, q odd (positive away from the axis: q > 0
        acts in +x for x > 0).
    x, z : array_like, 1-d
        Output grid, x/a and depth z/a >= 0.
    nu : float
        Poisson's ratio of the body (enters sigma_yy only).

    Returns
    -------
    dict of str to ndarray, shape (len(z), len(x))
        ``sigma_xx``, ``sigma_yy``, ``sigma_zz``, ``sigma_xz`` in the unit of the
        tractions, tension positive; exact for the piecewise-linear tractions up to
        round-off.
    """
    r, p, q = check_tractions(xi, pressure, shear)
    # both halves: p(-x) = p(x), q(-x) = -q(x); a gap or a jump at x = 0 is two pieces
    # that do not meet
    starts = np.concatenate([-r[:0:-1], r[:-1]])
    ends = np.concatenate([-r[-2::-1], r[1:]])
    pa = np.concatenate([p[:0:-1], p[:-1]])
    pb = np.concatenate([p[-2::-1], p[1:]])
    qa = np.concatenate([-q[:0:-1], q[:-1]])
    qb = np.concatenate([-q[-2::-1], q[1:]])
    return _halfplane_pieces(starts, ends, pa, pb, qa, qb, x, z, nu)


def halfplane_stresses_line(s: Any, pressure: Any, shear: Any, x: Any, z: Any,
                            nu: float) -> dict[str, np.ndarray]:
    """:func:`halfplane_stresses` for tractions tabulated over the whole line.

    Parameters
    ----------
    s : array_like, shape (m,)
        Increasing abscissae x/a (any sign) of the tractions, zero outside
        [s[0], s[-1]].
    pressure, shear : array_like, shape (m,)
        p and the shear q in +x (no symmetry assumed: e.g. sliding, q = mu p).
    x, z, nu
        As for :func:`halfplane_stresses`.

    Returns
    -------
    dict of str to ndarray, shape (len(z), len(x))
        As :func:`halfplane_stresses`.
    """
    from ..validate import InputError

    t = np.asarray(s, dtype=float)
    p = np.asarray(pressure, dtype=float)
    q = np.asarray(shear, dtype=float)
    if t.ndim != 1 or t.size < 2 or p.shape != t.shape or q.shape != t.shape \
            or np.any(np.diff(t) <= 0):
        raise InputError("s", "an increasing 1-d array, pressure and shear of its shape", t)
    return _halfplane_pieces(t[:-1], t[1:], p[:-1], p[1:], q[:-1], q[1:], x, z, nu)


def _halfplane_pieces(sa: np.ndarray, sb: np.ndarray, pa: np.ndarray, pb: np.ndarray,
                      qa: np.ndarray, qb: np.ndarray, x: Any, z: Any,
                      nu: float) -> dict[str, np.ndarray]:
    """Johnson's half-plane integrals (Contact Mechanics, Ch. 2) done exactly over linear
    pieces [sa, sb] (values a -> b)."""
    xs, zs = check_grid(x, z)
    h = sb - sa
    mp, mq = (pb - pa) / h, (qb - qa) / h
    cp, cq = pa - mp * sa, qa - mq * sa  # f(s) = c + m s = (c + m x) - m u, u = x - s
    nodes = np.union1d(sa, sb)
    ia, ib = np.searchsorted(nodes, sa), np.searchsorted(nodes, sb)
    X, Z = np.meshgrid(xs, zs)
    xf, zf = X.ravel(), Z.ravel()
    out = {k: np.empty(xf.size) for k in ("sigma_xx", "sigma_zz", "sigma_xz")}
    # a sum over the pieces of c (F(x - sa) - F(x - sb)) as node weights times F at nodes
    cp, mp, cq, mq = (np.bincount(ia, v, nodes.size) - np.bincount(ib, v, nodes.size)
                      for v in (cp, mp, cq, mq))
    step = max(1, CHUNK // nodes.size)
    for i in range(0, xf.size, step):
        xc, zc = xf[i:i + step], zf[i:i + step]
        dm = _plane_antiderivatives(xc[:, None] - nodes, zc[:, None])
        # int over a piece of (A - m u) K(u) du, u from x - sb up to x - sa, A = c + m x

        def weighted(key: str, c: np.ndarray, m: np.ndarray) -> np.ndarray:
            d = dm[key]
            return d @ c + xc * (d @ m)

        zM3 = np.where(zc > 0, zc * (dm["M3"] @ mp), 0.0)  # z ln(D) -> 0 on the surface
        zM3q = np.where(zc > 0, zc * (dm["M3"] @ mq), 0.0)
        sxx = weighted("zM2", cp, mp) - zM3 + weighted("M3", cq, mq) - dm["M4"] @ mq
        szz = (weighted("z3M0", cp, mp) - zc * (dm["z2M1"] @ mp) + weighted("z2M1", cq, mq)
               - zc * (dm["zM2"] @ mq))
        sxz = weighted("z2M1", cp, mp) - zc * (dm["zM2"] @ mp) + weighted("zM2", cq, mq) - zM3q
        for name, v in (("sigma_xx", sxx), ("sigma_zz", szz), ("sigma_xz", sxz)):
            out[name][i:i + step] = -(2.0 / math.pi) * v
    res = {k: v.reshape(X.shape) for k, v in out.items()}
    res["sigma_yy"] = nu * (res["sigma_xx"] + res["sigma_zz"])
    return {k: res[k] for k in COMPONENTS["cylinder"]}


# ----------------------------------------------------------------------------- half-space
PANEL = 2.0 * math.pi
"""Panel width of the xi quadrature times (1 + max r): one period of the fastest
oscillation, cos((1 + r) xi), a panel of 8 Gauss-Legendre points."""

# tested: tests/test_stresses.py (the tail panels against 8 points a period everywhere, to
# 1e-11; the 32-point rule's relative error on e^{i 8 pi t} over a panel is 3e-19)
TAIL_PERIODS = 8
"""The half-space's xi quadrature beyond its first ``2 TAIL_PERIODS`` panels: panels of
TAIL_PERIODS periods of the fastest oscillation with 32 Gauss-Legendre points (4 a period
where the first panels have 8; the 8-point rule's relative error on one period is 2e-10,
the 32-point rule's on 8 periods 3e-19). A depth that still contributes there (xi z < 40)
decays by at most e^{-20} over such a panel, which the rule integrates as exactly."""
_GAUSS_TAIL = np.polynomial.legendre.leggauss(32)


def _gauss_panels(edges: np.ndarray, rule: tuple[np.ndarray, np.ndarray]
                  ) -> tuple[np.ndarray, np.ndarray]:
    """Nodes and weights of the Gauss-Legendre ``rule`` on the panels between ``edges``."""
    t, w = rule
    half = 0.5 * np.diff(edges)
    nodes = (0.5 * (edges[:-1] + edges[1:]))[:, None] + half[:, None] * t[None, :]
    return nodes.ravel(), (half[:, None] * w[None, :]).ravel()


def xi_nodes(xi_max: float, r_max: float) -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre nodes and weights on panels of width PANEL/(1 + r_max) on [0, xi_max]."""
    width = PANEL / (1.0 + r_max)
    panels = max(1, int(math.ceil(xi_max / width)))
    return _gauss_panels(np.linspace(0.0, xi_max, panels + 1), _GAUSS)


# tested: tests/test_stresses.py (deep points on the axis against Boussinesq's integral, to
# 1e-12 of the tractions at z = 4 ... 16 a; without the grading, 2e-7 at 4 a and 4e-6 at 8 a)
DEPTH_PANEL = 2.0
"""Near xi = 0 the half-space's panels are no wider than ``DEPTH_PANEL / z`` for every depth
z still above e^{-DEPTH_CUTOFF} there (xi z < DEPTH_CUTOFF), i.e. no wider than
max(DEPTH_PANEL / z_max, xi DEPTH_PANEL / DEPTH_CUTOFF): a depth's e^{-xi z} then falls by
at most e^{-2} over an 8-point panel. The oscillation's width PANEL/(1 + r_max) alone let
the deepest points of a grid fall by e^{-12} or more over the first panel."""


def _graded_edges(xi_max: float, width: float, z_max: float) -> np.ndarray:
    """Panel edges on [0, xi_max]: ``width`` wide, finer near 0 for the depth ``z_max``
    (:data:`DEPTH_PANEL`): uniform DEPTH_PANEL/z_max up to where xi DEPTH_PANEL/DEPTH_CUTOFF
    reaches it, then growing by the factor 1 + DEPTH_PANEL/DEPTH_CUTOFF up to ``width``."""
    fine = DEPTH_PANEL / z_max if z_max > 0 else math.inf
    if fine >= width:
        return np.linspace(0.0, xi_max, max(1, int(math.ceil(xi_max / width))) + 1)
    ratio = DEPTH_PANEL / DEPTH_CUTOFF
    start = fine / ratio  # where the graded widths begin to grow
    parts = [np.arange(0.0, min(start, xi_max), fine)]
    grow = int(math.ceil(math.log(width / fine) / math.log1p(ratio)))
    parts.append(start * (1.0 + ratio) ** np.arange(grow))  # widths fine ... width
    end = start * (1.0 + ratio) ** grow
    parts.append(end + width * np.arange(max(0, int(math.ceil((xi_max - end) / width))) + 1))
    edges = np.concatenate(parts)
    edges = np.concatenate([edges[edges < xi_max], [xi_max]])
    return edges


def _halfspace_nodes(xi_max: float, r_max: float, z_max: float = 0.0
                     ) -> tuple[np.ndarray, np.ndarray]:
    """Panels of :func:`xi_nodes` (graded near 0 for the depth ``z_max``,
    :data:`DEPTH_PANEL`) up to two tail panels, then the tail panels (``TAIL_PERIODS``)."""
    width = PANEL / (1.0 + r_max)
    tail = TAIL_PERIODS * width
    start = 2.0 * tail
    if xi_max <= start + tail:
        return _gauss_panels(_graded_edges(xi_max, width, z_max), _GAUSS)
    k0, w0 = _gauss_panels(_graded_edges(start, width, z_max), _GAUSS)
    panels = int(math.ceil((xi_max - start) / tail))
    k1, w1 = _gauss_panels(np.linspace(start, xi_max, panels + 1), _GAUSS_TAIL)
    return np.concatenate([k0, k1]), np.concatenate([w0, w1])


class TractionPieces:
    """Tractions as linear pieces: on [sa, sb], p = cp + mp r and q = cq + mq r.

    Adjacent pieces may share an end (continuous tabulated tractions) or not (element
    tractions of a history); zero outside every piece.
    """

    def __init__(self, sa: np.ndarray, sb: np.ndarray, pa: np.ndarray, pb: np.ndarray,
                 qa: np.ndarray, qb: np.ndarray) -> None:
        h = sb - sa
        self.sa, self.sb = sa, sb
        self.qa, self.qb = qa, qb
        self.mp, self.mq = (pb - pa) / h, (qb - qa) / h
        self.cp, self.cq = pa - self.mp * sa, qa - self.mq * sa
        self.nodes = np.union1d(sa, sb)
        self.ia, self.ib = np.searchsorted(self.nodes, sa), np.searchsorted(self.nodes, sb)

    @classmethod
    def from_nodes(cls, r: np.ndarray, p: np.ndarray, q: np.ndarray) -> "TractionPieces":
        return cls(r[:-1], r[1:], p[:-1], p[1:], q[:-1], q[1:])

    def on_nodes(self, c: np.ndarray) -> np.ndarray:
        """Per-node weights of a sum over the pieces of c (g(sb) - g(sa)): sum_j g(node_j)
        times the result."""
        n = self.nodes.size
        return np.bincount(self.ib, c, n) - np.bincount(self.ia, c, n)

    def at(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """p and q at ``x`` (the last piece starting at or before x; 0 outside them all)."""
        i = np.clip(np.searchsorted(self.sa, x, side="right") - 1, 0, self.sa.size - 1)
        inside = (x >= self.sa[i]) & (x <= self.sb[i])
        p = np.where(inside, self.cp[i] + self.mp[i] * x, 0.0)
        q = np.where(inside, self.cq[i] + self.mq[i] * x, 0.0)
        return p, q

    def moment(self, x: np.ndarray) -> np.ndarray:
        """int_0^x p(t) t dt, exactly."""
        lo = np.minimum(np.maximum(x[:, None], self.sa[None, :]), self.sb[None, :])
        return (self.cp * (lo**2 - self.sa**2) / 2.0
                + self.mp * (lo**3 - self.sa**3) / 3.0).sum(axis=1)

    def hankel(self, k: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """P(k) = int p J0(k r) r dr and Q(k) = int q J1(k r) r dr, in closed form.

        On each piece int r J0 = x J1 / k^2, int r^2 J0 = (x^2 J1 + x J0 - int_0^x J0) /
        k^3, int r J1 = (int_0^x J0 - x J0) / k^2, int r^2 J1 = x^2 J2 / k^3 (x = k r),
        summed over the pieces as weights on their ends (:meth:`on_nodes`).
        """
        P, Q = np.empty(k.size), np.empty(k.size)
        a0, a1, b0, b1 = (self.on_nodes(c) for c in (self.cp, self.mp, self.cq, self.mq))
        step = max(1, CHUNK // self.nodes.size)
        for i in range(0, k.size, step):
            kk = k[i:i + step]
            x = kk[:, None] * self.nodes[None, :]
            j0, j1 = sp.j0(x), sp.j1(x)
            ij0 = _integral_j0(x, j0, j1)
            small = x <= 1.0  # the recurrence J2 = 2 J1/x - J0 cancels at small x
            j2 = 2.0 * j1 / np.where(small, 1.0, x) - j0
            j2[small] = sp.jv(2, x[small])
            xj0, xj1 = x * j0, x * j1
            P[i:i + step] = (xj1 @ a0) / kk**2 + ((x * xj1 + xj0 - ij0) @ a1) / kk**3
            Q[i:i + step] = ((ij0 - xj0) @ b0) / kk**2 + ((x * x * j2) @ b1) / kk**3
        return P, Q


# tested: tests/test_stresses.py (int_0^x J0 against mpmath to 2e-11, x = 0.5 ... 4321);
# scipy's itj0y0 drifts beyond it
INTEGRAL_J0_SWITCH = 15.0
"""Up to this argument ``int_0^x J0`` is scipy's ``itj0y0`` (9.8e-12 off at 14.9). Beyond
it ``itj0y0`` drifts: 4.5e-10 off at 20 in scipy 1.13 and 1.17, and 1.13's is of order 1e10
from x ~ 21 on. Between it and ``INTEGRAL_J0_ASYMPTOTIC`` the integral is a Chebyshev
series of degree 32 (``_INTEGRAL_J0_MID``, within 1e-14 of mpmath) interpolating its value
at 15 (``_INTEGRAL_J0_AT_SWITCH``, from mpmath's x 1F2(1/2; 1, 3/2; -x^2/4) at 40 digits)
plus the rest by 24-point Gauss-Legendre (J0 is entire, the interval at most 15 long: below
1e-14)."""

# tested: tests/test_stresses.py (int_0^x J0 against mpmath to 2e-11, x = 0.5 ... 4321);
# the asymptotic series' ten terms are within 2.2e-13 from here on
INTEGRAL_J0_ASYMPTOTIC = 30.0
"""Above this argument ``int_0^x J0`` comes from the asymptotic series of the Struve
functions (Abramowitz & Stegun 12.1.31) and the Wronskian J1 Y0 - J0 Y1 = 2/(pi x):
int_0^x J0 = 1 + J1 S0 - x J0 T1 with S0 = sum_k (-1)^k ((2k-1)!!)^2 x^-2k and T1 =
sum_(k>=1) (-1)^k ((2k-1)!!)^2 / (1 - 2k) x^-2k, 10 terms. Against scipy 1.17's
``itj0y0`` it is within 2.2e-13 on [30, 80] and 2e-15 from 40 on. It replaces the
identity through Struve functions, x J0 + (pi x/2)(J1 H0 - J0 H1), whose cost dominated a
sphere's field (a 100 x 100 grid: 4.9 s CPU before, 1.9 s after, on one machine)."""

_GAUSS_24 = np.polynomial.legendre.leggauss(24)
_INTEGRAL_J0_AT_SWITCH = 1.205161936344904467  # exact: int_0^15 J0 (mpmath, 40 digits)
# tested: tests/test_stresses.py (int_0^x J0 to 2e-11 against mpmath up to x = 4321; the
# ten terms reach 2.2e-13 at x = 30)
_ASYMPTOTIC_TERMS = 10
_DOUBLE_FACTORIAL_SQUARED = np.cumprod([1.0] + [(2.0 * k - 1.0)**2
                                                for k in range(1, _ASYMPTOTIC_TERMS + 1)])


def _integral_j0_asymptotic(x: np.ndarray, j0: np.ndarray, j1: np.ndarray) -> np.ndarray:
    """int_0^x J0(t) dt for large x (see INTEGRAL_J0_ASYMPTOTIC), by Horner in 1/x^2;
    ``j0``, ``j1`` are J0(x) and J1(x)."""
    u = 1.0 / (x * x)
    c = _DOUBLE_FACTORIAL_SQUARED
    top = _ASYMPTOTIC_TERMS
    s0 = np.full_like(x, (-1)**top * c[top])
    t1 = np.full_like(x, (-1)**top * c[top] / (1 - 2 * top))
    for k in range(top - 1, -1, -1):
        s0 *= u
        s0 += (-1)**k * c[k]
        if k > 0:
            t1 *= u
            t1 += (-1)**k * c[k] / (1 - 2 * k)
    t1 *= u
    return 1.0 + j1 * s0 - x * j0 * t1


def _integral_j0_gauss(x: np.ndarray) -> np.ndarray:
    """int_0^x J0 for x in [INTEGRAL_J0_SWITCH, INTEGRAL_J0_ASYMPTOTIC]: the value at the
    switch plus 24-point Gauss-Legendre (fits ``_INTEGRAL_J0_MID`` once)."""
    start = INTEGRAL_J0_SWITCH
    half = 0.5 * (x - start)
    t, w = _GAUSS_24
    nodes = (start + half)[:, None] + half[:, None] * t[None, :]
    return _INTEGRAL_J0_AT_SWITCH + half * (sp.j0(nodes) @ w)


_MID_CENTRE = 0.5 * (INTEGRAL_J0_ASYMPTOTIC + INTEGRAL_J0_SWITCH)
_MID_HALF = 0.5 * (INTEGRAL_J0_ASYMPTOTIC - INTEGRAL_J0_SWITCH)
# tested: tests/test_stresses.py (int_0^x J0 against mpmath to 2e-11 across [15, 30]);
# degree 32 interpolates the Gauss-Legendre values to 1e-14 (28: 2e-14, 24: 2e-12)
_INTEGRAL_J0_MID_DEGREE = 32
_INTEGRAL_J0_MID = np.polynomial.chebyshev.chebinterpolate(
    lambda u: _integral_j0_gauss(_MID_CENTRE + _MID_HALF * u), _INTEGRAL_J0_MID_DEGREE)


def _integral_j0(x: np.ndarray, j0: np.ndarray | None = None,
                 j1: np.ndarray | None = None) -> np.ndarray:
    """int_0^x J0(t) dt, the same in every supported scipy (see INTEGRAL_J0_SWITCH);
    ``j0``, ``j1``: J0(x) and J1(x) if the caller has them. The asymptotic series is
    evaluated everywhere (no gathers of the large arrays) and replaced below its range."""
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        out = _integral_j0_asymptotic(x, sp.j0(x) if j0 is None else j0,
                                      sp.j1(x) if j1 is None else j1)
    below = x <= INTEGRAL_J0_ASYMPTOTIC
    if below.any():
        xb = x[below]
        vals = np.polynomial.chebyshev.chebval((xb - _MID_CENTRE) / _MID_HALF,
                                               _INTEGRAL_J0_MID)
        low = xb <= INTEGRAL_J0_SWITCH
        vals[low] = sp.itj0y0(xb[low])[0]
        out[below] = vals
    return out


def halfspace_stresses(xi: Any, pressure: Any, shear: Any, x: Any, z: Any,
                       nu: float) -> dict[str, np.ndarray]:
    """Axisymmetric stresses in the half-space z >= 0 under tabulated p(r) and radial q(r).

    Parameters
    ----------
    xi : array_like, shape (m,)
        Increasing radii r/a >= 0 of the tabulated tractions (usually 0 ... 1).
    pressure, shear : array_like, shape (m,)
        p and the radial shear q at ``xi`` (any stress unit, e.g. p0); piecewise linear
        between, zero beyond ``xi[-1]``.
    x, z : array_like, 1-d
        Output grid: radius r/a >= 0 (negative values are read as |r|) and depth z/a >= 0.
    nu : float
        Poisson's ratio of the body.

    Returns
    -------
    dict of str to ndarray, shape (len(z), len(x))
        ``sigma_rr``, ``sigma_tt`` (hoop), ``sigma_zz``, ``sigma_rz`` in the unit of the
        tractions, tension positive. Error: the xi quadrature's, below 1e-9 of the
        tractions at z > 0; on z = 0 the ring integrals', 2e-12 (closed forms otherwise).
        A radial shear with q(0) != 0 is log-infinite on the surface's axis: sigma_rr
        and sigma_tt are NaN there (a solve's shear vanishes on the axis).
    """
    r, p, q = check_tractions(xi, pressure, shear)
    return _halfspace_pieces(TractionPieces.from_nodes(r, p, q), x, z, nu)


def _halfspace_pieces(pieces: TractionPieces, x: Any, z: Any, nu: float) -> dict[str, np.ndarray]:
    """The half-space field of tractions given as linear pieces (:func:`halfspace_stresses`)."""
    xs, zs = check_grid(x, z)
    rr = np.abs(xs)
    out = {k: np.zeros((zs.size, rr.size)) for k in COMPONENTS["sphere"]}
    inside, surface = zs > 0, zs == 0
    if np.any(inside):
        r_max = float(max(rr.max(), pieces.sb.max()))
        k, w = _halfspace_nodes(DEPTH_CUTOFF / zs[inside].min(), r_max, float(zs.max()))
        P, Q = pieces.hankel(k)
        _hankel_sums(out, k, w, P, Q, rr, zs, nu, inside)
    if np.any(surface):
        # closed forms: the pressure's part (Johnson Ch. 3) and the shear's (ring integrals)
        pr, qr = pieces.at(rr)
        p_axis = pieces.at(np.zeros(1))[0][0]
        with np.errstate(invalid="ignore", divide="ignore"):
            moment = np.where(rr > 0, pieces.moment(rr) / np.where(rr > 0, rr, 1)**2,
                              0.5 * p_axis)
        q_rr, q_tt = _surface_shear(pieces, rr, nu)
        j = np.flatnonzero(surface)
        out["sigma_zz"][j] = -pr
        out["sigma_rz"][j] = -qr
        out["sigma_rr"][j] = -pr + (1 - 2 * nu) * moment + q_rr
        out["sigma_tt"][j] = -2 * nu * pr - (1 - 2 * nu) * moment + q_tt
    return out


def _hankel_sums(out: dict[str, np.ndarray], k: np.ndarray, w: np.ndarray, P: np.ndarray,
                 Q: np.ndarray, r: np.ndarray, z: np.ndarray, nu: float,
                 inside: np.ndarray) -> None:
    """Add the xi integrals of the depths z > 0 (``inside``) to ``out``: (J(k r) w) @
    (polynomial in k z times e^{-k z}), each depth only over the chunks of k (increasing)
    where k z < 40 (e^{-k z} < 4e-18 beyond)."""
    jin = np.flatnonzero(inside)
    zi = z[jin]
    step = max(1, min(SUM_CHUNK, CHUNK // max(r.size, zi.size, 1)))
    for i in range(0, k.size, step):
        kc, wc, Pc, Qc = k[i:i + step], w[i:i + step], P[i:i + step], Q[i:i + step]
        active = kc[0] * zi < 40.0
        if not active.any():
            break
        ja, kz = jin[active], np.outer(kc, zi[active])
        x = np.outer(r, kc)
        j0 = sp.j0(x) * wc
        j1 = sp.j1(x)
        j1x = np.where(x > 0, j1 / np.where(x > 0, x, 1.0), 0.5) * wc
        j1 = j1 * wc
        # exact zeros beyond e^-40 (denormals would slow every product down)
        e0 = np.where(kz < 40.0, np.exp(-np.minimum(kz, 40.0)), 0.0)
        e1 = kz * e0
        kP, kQ = (kc * Pc)[:, None], (kc * Qc)[:, None]
        a1 = (1 - 2 * nu) * kP - 2 * (1 - nu) * kQ  # the J1/(k r) bracket
        b1 = kQ - kP
        out["sigma_zz"][ja] += (j0 @ (-kP * e0 + b1 * e1)).T
        out["sigma_rz"][ja] += (j1 @ (-kQ * e0 + b1 * e1)).T
        bracket = j1x @ (a1 * e0 + b1 * e1)
        out["sigma_rr"][ja] += (j0 @ ((2 * kQ - kP) * e0 - b1 * e1)).T + bracket.T
        out["sigma_tt"][ja] += (j0 @ (2 * nu * b1 * e0)).T - bracket.T


# ----------------------------------------------------------------------------- surface shear
def _tanh_sinh(step: float, span: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Tanh-sinh nodes on [0, 1]: x, 1 - x (accurate near 1) and the weights."""
    s = np.arange(-span, span + 0.5 * step, step)
    y = 0.5 * math.pi * np.sinh(s)
    return (1.0 / (1.0 + np.exp(-2.0 * y)), 1.0 / (1.0 + np.exp(2.0 * y)),
            step * 0.25 * math.pi * np.cosh(s) / np.cosh(y)**2)


# measured: benchmarks/bench_stresses.py (the surface row against rules of twice the density,
# 2e-12 p0 on a grid through the tractions' nodes): 39 nodes, weights below 1e-20 at the ends
RING_TANH_SINH = (1.0 / 6.0, 3.2)
"""(step, span) of the tanh-sinh rule of the ring integrals next to the log singularity at
t = r: nodes s = -span ... span, step apart."""
# measured: benchmarks/bench_stresses.py (as RING_TANH_SINH): the nearest singularity (t = r)
# lies 3 half-lengths from a far piece's centre, 3.73^-20 = 4e-12
RING_GAUSS = 10
"""Gauss-Legendre points of a ring integral over a piece at least its length away from r."""
# exact: below it the series' next term is 5e-17 relative, above it the direct form loses
# at most 1e-13 to the cancellation of K - E
RING_SERIES_M = 1e-3
"""m = (min/max)^2 below which (K(m) - E(m))/sqrt(m) comes from its Taylor series."""
# measured: benchmarks/bench_stresses.py (k values a chunk of the depth sums: depths drop
# out chunk by chunk as xi z passes 40; 32 to 64 were fastest, 512 1.2 times slower)
SUM_CHUNK = 32


def _ring_kernel(r: np.ndarray, t: np.ndarray, delta: np.ndarray) -> np.ndarray:
    """W(r, t) = int_0^inf J1(k r) J1(k t) dk = 2/(pi M) (K(m) - E(m))/sqrt(m), M = max(r,
    t) > 0, m = (min/max)^2 (elliptic parameter); ``delta`` = t - r given accurately (the
    log singularity at t = r); 0 where min(r, t) = 0."""
    big = np.maximum(r, t)
    ratio = np.minimum(r, t) / big
    m1 = np.abs(delta) / big
    m1 *= 1.0 + ratio
    np.maximum(m1, 1e-300, out=m1)
    with np.errstate(invalid="ignore", divide="ignore"):
        out = (sp.ellipkm1(m1) - sp.ellipe(1.0 - m1)) / ratio
    small = ratio * ratio < RING_SERIES_M
    if small.any():
        q = ratio[small]
        m = q * q
        out[small] = q * (0.5 + m * (3 / 16 + m * (15 / 128 + m * (175 / 2048
                                                                  + m * 2205 / 32768))))
        out[small] *= 0.5 * math.pi
    out *= 2.0 / math.pi
    out /= big
    return out


def _ring_moments(r: np.ndarray, sa: np.ndarray, sb: np.ndarray) -> tuple[np.ndarray, ...]:
    """I_j[i, l] = int_{sa_l}^{sb_l} t^j W(r_i, t) dt for j = 1, 2 and r_i > 0: Gauss-Legendre
    (``RING_GAUSS`` points) for a piece at least its length away from r_i, else tanh-sinh
    (``RING_TANH_SINH``) on each side of r_i."""
    shape = (r.size, sa.size)
    R, A, B = (np.broadcast_to(v, shape) for v in (r[:, None], sa[None, :], sb[None, :]))
    far = np.maximum(np.maximum(A - R, R - B), 0.0) >= B - A
    moments = np.zeros((2,) + shape)
    t0, w0 = np.polynomial.legendre.leggauss(RING_GAUSS)
    rf, af, bf = R[far][:, None], A[far][:, None], B[far][:, None]
    t = 0.5 * (af + bf) + 0.5 * (bf - af) * t0
    wt = _ring_kernel(rf, t, t - rf) * (0.5 * (bf - af) * w0) * t
    moments[0][far], moments[1][far] = wt.sum(axis=1), (wt * t).sum(axis=1)
    rn, an, bn = R[~far][:, None], A[~far][:, None], B[~far][:, None]
    x, xc, wx = _tanh_sinh(*RING_TANH_SINH)
    cut = np.clip(rn, an, bn)
    for lo, hi in ((an, cut), (cut, bn)):
        length = hi - lo
        t = lo + length * x
        delta = np.where(x < 0.5, (lo - rn) + length * x, (hi - rn) - length * xc)
        wt = _ring_kernel(rn, t, delta) * (length * wx) * t
        moments[0][~far] += wt.sum(axis=1)
        moments[1][~far] += (wt * t).sum(axis=1)
    return moments[0], moments[1]


def _surface_shear(pieces: TractionPieces, r: np.ndarray,
                   nu: float) -> tuple[np.ndarray, np.ndarray]:
    """The radial shear's part of sigma_rr and sigma_tt on the surface z = 0, at r >= 0.

    With U(r) = int_0^inf Q(k) J1(k r) dk = int q(t) t W(r, t) dt (half the surface radial
    displacement times E*), sigma_rr = 2 U' + 2 nu U/r and sigma_tt = 2 nu U' + 2 U/r (the
    xi integrals of the module's notes at z = 0). W is homogeneous of degree -1, so r dW/dr
    = -W - t dW/dt, and by parts r U' = sum over the pieces of int (c t + 2 m t^2) W dt minus
    the jumps of q (ends included) times t^2 W(r, t) at them (a traction jump's stress is
    log-singular there). On the axis U' = U/r = (1/2) int_0^inf q/t dt (log-infinite if
    q(0) != 0, a radial traction that does not vanish on the axis: see the code).
    """
    out_rr, out_tt = np.zeros(r.size), np.zeros(r.size)
    if not (np.any(pieces.cq != 0) or np.any(pieces.mq != 0)):
        return out_rr, out_tt
    n = pieces.nodes.size
    jump = np.bincount(pieces.ib, pieces.qb, n) - np.bincount(pieces.ia, pieces.qa, n)
    jumps = np.flatnonzero(jump)
    axis = r == 0
    pos = np.flatnonzero(~axis)
    step = max(1, CHUNK // (pieces.sa.size * RING_GAUSS))
    for i in range(0, pos.size, step):
        idx = pos[i:i + step]
        rp = r[idx]
        i1, i2 = _ring_moments(rp, pieces.sa, pieces.sb)
        u = i1 @ pieces.cq + i2 @ pieces.mq
        tj = pieces.nodes[jumps]
        wj = _ring_kernel(rp[:, None], tj[None, :], tj[None, :] - rp[:, None])
        du = (i1 @ pieces.cq + 2.0 * (i2 @ pieces.mq) - (wj * tj**2) @ jump[jumps]) / rp
        out_rr[idx] = 2.0 * du + 2.0 * nu * u / rp
        out_tt[idx] = 2.0 * nu * du + 2.0 * u / rp
    if np.any(axis):
        # q(0) != 0 makes the axis value log-infinite: no number there (NaN)
        at_axis = pieces.sa == 0
        if np.any(at_axis & (pieces.cq != 0)):
            value = math.nan
        else:
            start = np.where(at_axis, 1.0, pieces.sa)  # (cq = 0 on the pieces from 0)
            with np.errstate(invalid="ignore", divide="ignore"):
                logs = np.where(pieces.cq != 0, pieces.cq * np.log(pieces.sb / start), 0.0)
            value = (1 + nu) * (logs.sum() + pieces.mq @ (pieces.sb - pieces.sa))
        out_rr[axis] = out_tt[axis] = value
    return out_rr, out_tt


def layer_stresses(xi: Any, pressure: Any, shear: Any, x: Any, z: Any, nu: float,
                   thickness: float, base: str, *, geometry: str = "sphere",
                   refine: int = 1, substrate: Any = None) -> dict[str, np.ndarray]:
    """Stresses in a layer on a rigid base, or in a coated body, under tabulated p and q.

    The half-space's (half-plane's) field (:func:`stress_field`) plus the layer's
    correction (:mod:`contactlib.stresses.layer`); in a coated body's substrate (z > h)
    the substrate's own field.

    Parameters
    ----------
    xi, pressure, shear : array_like, shape (m,)
        As for :func:`halfspace_stresses` (r/a) or :func:`halfplane_stresses` (x/a;
        p even and q odd in x), any stress unit.
    x, z : array_like, 1-d
        Output grid: r/a (|r| is used; x/a of either sign for the cylinder) and depth
        z/a in [0, h/a] on a rigid base, z/a >= 0 in a coated body (z <= h: the layer,
        z > h: the substrate).
    nu : float
        Poisson's ratio of the layer, -1 < nu <= 0.5.
    thickness : float
        h/a, the layer's thickness over the contact radius (1 / slab_ratio).
    base : {"smooth", "bonded", "elastic"}
        The rigid base at z = h, or ``"elastic"``: the layer bonded to ``substrate``.
    geometry : {"sphere", "cylinder"}
        Axisymmetric (Hankel) or plane strain (Fourier).
    refine : int
        Divides the panels of the correction's k integral (convergence checks).
    substrate : contactlib.kernels.layer_transfer.Substrate or (float, float), optional
        With ``base="elastic"`` only: E2/E1 and the substrate's Poisson's ratio nu2.

    Returns
    -------
    dict of str to ndarray, shape (len(z), len(x))
        The components of :data:`COMPONENTS` for ``geometry``, in the unit of the
        tractions, tension positive. Error: the half-space's plus the correction's
        quadrature, below 1e-10 of the tractions (tests/test_stresses_layer.py,
        tests/test_stresses_coated.py).

    Raises
    ------
    contactlib.validate.InputError
        For a depth beyond a rigid-based layer (z > h), a base other than smooth, bonded
        or elastic, ``base="elastic"`` without a substrate (or a substrate without it),
        or what :func:`halfspace_stresses` refuses.
    """
    from .layer import check_layer
    from ..validate import InputError

    kernel_base = _kernel_base(base, substrate)
    nu, h, kernel_base = check_layer(nu, thickness, kernel_base)
    r, p, q = check_tractions(xi, pressure, shear)
    xs, zs = check_grid(x, z)
    if isinstance(kernel_base, str) and np.any(zs > h * (1 + 1e-12)):
        raise InputError("z", f"depths within the layer, 0 <= z <= h = {h!r}", zs.max(),
                         f"z must lie within the layer (0 <= z <= h/a = {h!r}), got "
                         f"z = {zs.max()!r}")
    return _layer_field(geometry, nu, (r[:-1], r[1:], p[:-1], p[1:], q[:-1], q[1:]), xs, zs,
                        h, kernel_base, refine)


def _pieces_field(geometry: str, nu: float, pieces: tuple[np.ndarray, ...], xs: np.ndarray,
                  zs: np.ndarray) -> dict[str, np.ndarray]:
    """The half-space's (half-plane's) field of linear pieces (sa, sb, pa, pb, qa, qb) on
    r >= 0 (x >= 0: the cylinder's p is even and q odd, so each piece is mirrored)."""
    sa, sb, pa, pb, qa, qb = pieces
    if geometry == "sphere":
        return _halfspace_pieces(TractionPieces(sa, sb, pa, pb, qa, qb), xs, zs, nu)
    return _halfplane_pieces(np.concatenate([-sb[::-1], sa]), np.concatenate([-sa[::-1], sb]),
                             np.concatenate([pb[::-1], pa]), np.concatenate([pa[::-1], pb]),
                             np.concatenate([-qb[::-1], qa]), np.concatenate([-qa[::-1], qb]),
                             xs, zs, nu)


def _layer_field(geometry: str, nu: float, pieces: tuple[np.ndarray, ...], xs: np.ndarray,
                 zs: np.ndarray, h: float, kernel_base: Any, refine: int = 1
                 ) -> dict[str, np.ndarray]:
    """A layer's field (``kernel_base`` a rigid base's name: NaN below the layer; or a
    Substrate: the substrate's field there) of linear traction pieces (as
    :func:`_pieces_field`), checked arguments: :func:`layer_stresses`' method."""
    from .layer import PANEL_T, T_CUTOFF, add_correction, coated_nodes, \
        fourier_pieces, substrate_field

    coated = not isinstance(kernel_base, str)  # a Substrate
    sa, sb, pa, pb, qa, qb = pieces
    within = zs <= h * (1 + 1e-12)
    zin = np.minimum(zs[within], h)
    # panels no wider than PANEL/(1 + max r) (the oscillation) nor PANEL_T/h (the layer),
    # nor PANEL_T/z_max in a substrate (its field decays like e^{-k z})
    r_max = float(max(np.abs(xs).max(), sb.max()))
    if coated:
        width = min(PANEL / (1.0 + r_max), PANEL_T / max(h, float(zs.max()))) / max(1, refine)
        k, w = coated_nodes(width, h, nu, kernel_base, refine)
    else:
        width = min(PANEL / (1.0 + r_max), PANEL_T / h) / max(1, refine)
        k, w = xi_nodes(T_CUTOFF / h, PANEL / width - 1.0)
    if geometry == "sphere":
        P, Q = TractionPieces(*pieces).hankel(k)
        rs = np.abs(xs)
    else:
        P, Q = fourier_pieces(*pieces, k)
        P, Q, rs = P / k, Q / k, xs
    out = {name: np.full((zs.size, xs.size), np.nan) for name in COMPONENTS[geometry]}
    if zin.size:
        part = _pieces_field(geometry, nu, pieces, xs, zin)
        add_correction(part, k, w, P, Q, rs, zin, nu, h, kernel_base, geometry)
        for name, v in part.items():
            out[name][within] = v
    if coated and not np.all(within):
        part = substrate_field(k, w, P, Q, rs, zs[~within], nu, h, kernel_base, geometry)
        for name, v in part.items():
            out[name][~within] = v
    return out


def _kernel_base(base: str, substrate: Any) -> Any:
    """The rigid base's name, or a coated body's Substrate (base "elastic"), checked."""
    from ..kernels.layer_transfer import Substrate
    from ..validate import COATED_BASE, InputError

    if base != COATED_BASE:
        if substrate is not None:
            raise InputError("substrate", "given with base 'elastic' only", substrate,
                             f"substrate needs base='elastic' (a coated body), not {base!r}")
        return base
    if substrate is None:
        raise InputError("substrate", "given with base 'elastic'", None,
                         "substrate=(E2/E1, nu2) is needed with base 'elastic' (a coated "
                         "body)")
    if isinstance(substrate, Substrate):
        return substrate
    try:
        return Substrate(*substrate)
    except (TypeError, ValueError) as exc:
        raise InputError("substrate", "(E2/E1 in (0, inf), -1 < nu2 <= 0.5)", substrate,
                         f"substrate must be (E2/E1 in (0, inf), nu2 in (-1, 0.5]): "
                         f"{exc}") from None


# ----------------------------------------------------------------------------- dispatch
def stress_field(geometry: str, nu: float, xi: Any, pressure: Any, shear: Any, x: Any,
                 z: Any) -> dict[str, np.ndarray]:
    """The stress components of ``geometry`` (:data:`COMPONENTS`) on the grid (z, x).

    Parameters
    ----------
    geometry : {"sphere", "cylinder"}
        :func:`halfspace_stresses` or :func:`halfplane_stresses`.
    nu : float
        Poisson's ratio of the body.
    xi, pressure, shear : array_like, shape (m,)
        Tabulated tractions on r/a (x/a) >= 0, piecewise linear between, in any stress
        unit (p0 for a Solution's ``pressure`` and ``shear``).
    x, z : array_like, 1-d
        Output grid, r/a (x/a) and depth z/a >= 0.

    Returns
    -------
    dict of str to ndarray, shape (len(z), len(x))
        The components, in the unit of the tractions, tension positive.
    """
    if geometry == "sphere":
        return halfspace_stresses(xi, pressure, shear, x, z, nu)
    if geometry == "cylinder":
        return halfplane_stresses(xi, pressure, shear, x, z, nu)
    from ..validate import InputError
    raise InputError("geometry", "sphere or cylinder", geometry)


# ----------------------------------------------------------------------------- measures
def _split(geometry: str, s: dict[str, np.ndarray]) -> tuple[np.ndarray, ...]:
    """(in-plane normal, out-of-plane principal, zz, in-plane shear) of either geometry."""
    a, b, c, d = (s[k] for k in COMPONENTS[geometry])
    return a, b, c, d


def principal_stresses(geometry: str, s: dict[str, np.ndarray]) -> np.ndarray:
    """Principal stresses, largest first, stacked on a new leading axis (3, ...).

    The hoop stress (sphere) or sigma_yy (cylinder) is principal; the other two are the
    eigenvalues of the in-plane 2 x 2 tensor.

    Parameters
    ----------
    geometry : {"sphere", "cylinder"}
        Which components ``s`` holds (:data:`COMPONENTS`).
    s : dict of str to ndarray
        The components (any stress unit), e.g. from :func:`stress_field`.

    Returns
    -------
    ndarray, shape (3, ...)
        sigma_1 >= sigma_2 >= sigma_3, in the unit of ``s``.
    """
    a, b, c, d = _split(geometry, s)
    mean, radius = 0.5 * (a + c), np.hypot(0.5 * (a - c), d)
    return -np.sort(-np.stack([mean + radius, b, mean - radius]), axis=0)


def von_mises(geometry: str, s: dict[str, np.ndarray]) -> np.ndarray:
    """von Mises equivalent stress, in the unit of ``s``.

    sqrt(((s1-s2)^2 + (s2-s3)^2 + (s3-s1)^2)/2), from the components as sqrt(((a-b)^2 +
    (b-c)^2 + (c-a)^2)/2 + 3 d^2) (a, b, c the normal stresses, d the in-plane shear).
    Parameters as for :func:`principal_stresses`.
    """
    a, b, c, d = _split(geometry, s)
    return np.sqrt(0.5 * ((a - b)**2 + (b - c)**2 + (c - a)**2) + 3.0 * d * d)


def tresca(geometry: str, s: dict[str, np.ndarray]) -> np.ndarray:
    """Maximum shear stress (s1 - s3)/2, half the spread of the principal stresses.

    In the unit of ``s``; parameters as for :func:`principal_stresses`.
    """
    ps = principal_stresses(geometry, s)
    return 0.5 * (ps[0] - ps[2])


def hydrostatic(geometry: str, s: dict[str, np.ndarray]) -> np.ndarray:
    """Mean normal stress (trace / 3), tension positive, in the unit of ``s``.

    Parameters as for :func:`principal_stresses`.
    """
    a, b, c, _ = _split(geometry, s)
    return (a + b + c) / 3.0


def derived_measures(geometry: str, s: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    """von Mises, Tresca, hydrostatic and the principal stresses (s1 >= s2 >= s3).

    Parameters as for :func:`principal_stresses`.

    Returns
    -------
    dict of str to ndarray
        ``von_mises``, ``tresca``, ``hydrostatic``, ``sigma_1``, ``sigma_2``,
        ``sigma_3``, in the unit of ``s``.
    """
    ps = principal_stresses(geometry, s)
    return {"von_mises": von_mises(geometry, s), "tresca": 0.5 * (ps[0] - ps[2]),
            "hydrostatic": hydrostatic(geometry, s), "sigma_1": ps[0], "sigma_2": ps[1],
            "sigma_3": ps[2]}


# ----------------------------------------------------------------------------- Solution
_LONG_NAMES = {
    "sigma_rr": "radial normal stress / p0", "sigma_tt": "hoop normal stress / p0",
    "sigma_zz": "normal stress across planes z = const / p0",
    "sigma_rz": "shear stress sigma_rz / p0", "sigma_xx": "normal stress sigma_xx / p0",
    "sigma_yy": "out-of-plane normal stress nu (sigma_xx + sigma_zz) / p0",
    "sigma_xz": "shear stress sigma_xz / p0",
    "von_mises": "von Mises equivalent stress / p0",
    "tresca": "maximum shear stress (sigma_1 - sigma_3)/2 / p0",
    "hydrostatic": "mean normal stress (trace/3) / p0, tension positive",
    "sigma_1": "largest principal stress / p0", "sigma_2": "middle principal stress / p0",
    "sigma_3": "smallest principal stress / p0",
}


def _tractions_of(solution: Any, body: str) -> tuple[float, np.ndarray, np.ndarray]:
    """Poisson's ratio and tractions (p, q) on the body asked for, refusing a body name
    other than "body" or "indenter" (the layer's base is checked by :func:`_kernel_base`
    and :func:`contactlib.stresses.layer.check_layer`)."""
    from ..validate import InputError

    if body not in ("body", "indenter"):
        raise InputError("body", "'body' or 'indenter'", body)
    p = np.asarray(solution.pressure, dtype=float)
    q = np.asarray(solution.shear, dtype=float)
    if not bool(getattr(solution, "converged", True)):  # its tractions are no data
        raise InputError("solution", "a converged case", "not converged",
                         "the solution did not converge (its message says why): no "
                         "stresses from it")
    if not (np.all(np.isfinite(p)) and np.all(np.isfinite(q))):
        raise InputError("solution", "a converged case with finite tractions", "NaN tractions",
                         "the solution's tractions are NaN (a case that did not converge): "
                         "no stresses from it")
    if body == "body":
        return float(solution.nu), p, q
    if math.isinf(float(solution.indenter_modulus_ratio)):
        raise InputError("body", "'body' for a rigid indenter", body,
                         "body must be 'body' for a rigid indenter (it has no stress field), "
                         "got 'indenter'")
    return float(solution.indenter_poisson_ratio), p, -q


def _substrate_of(solution: Any) -> tuple[float, float] | None:
    """(E2/E1, nu2) of a coated body's solution (base "elastic"), None otherwise."""
    from ..validate import COATED_BASE

    if getattr(solution, "base", "smooth") != COATED_BASE:
        return None
    return (float(solution.substrate_modulus), float(solution.substrate_poisson_ratio))


def traction_samples(solution: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(xi, p/p0, q/p0) whose piecewise-linear interpolation the field integrates.

    The solve's own nodes and nodal tractions where the solution carries them
    (``solution.extra["nodes"]``, default and extrapolated methods: the field then
    converges with n), else its output points ``xi``, ``pressure``, ``shear``.
    """
    nodal = getattr(solution, "extra", None) or {}
    if "nodes" in nodal:
        return (np.asarray(nodal["nodes"], dtype=float),
                np.asarray(nodal["nodal_pressure"], dtype=float),
                np.asarray(nodal["nodal_shear"], dtype=float))
    return (np.asarray(solution.xi, dtype=float), np.asarray(solution.pressure, dtype=float),
            np.asarray(solution.shear, dtype=float))


def body_field(geometry: str, nu: float, xi: Any, p: Any, q: Any, xs: np.ndarray,
               zs: np.ndarray, slab_ratio: float = 0.0, base: str = "smooth",
               substrate: Any = None) -> dict[str, np.ndarray]:
    """The stress components in the body: the half-space's or half-plane's
    (:func:`stress_field`), or, at ``slab_ratio`` > 0, a layer's on its rigid base
    (:func:`layer_stresses`; NaN at the depths z > h = 1/slab_ratio, below the layer), or
    a coated body's (base "elastic" on ``substrate`` = (E2/E1, nu2): the layer for
    z <= h, the substrate below)."""
    if not slab_ratio > 0:
        return stress_field(geometry, nu, xi, p, q, xs, zs)
    h = 1.0 / float(slab_ratio)
    if substrate is not None:
        return layer_stresses(xi, p, q, xs, zs, nu, h, base, geometry=geometry,
                              substrate=substrate)
    within = zs <= h
    fields = {name: np.full((zs.size, xs.size), np.nan) for name in COMPONENTS[geometry]}
    if np.any(within):
        part = layer_stresses(xi, p, q, xs, zs[within], nu, h, base, geometry=geometry)
        for name, v in part.items():
            fields[name][within] = v
    return fields


def subsurface_stresses(solution: Any, x: Any, z: Any, *, body: str = "body",
                        measures: bool = True) -> Any:
    """The stress field under a solved case, as an xarray Dataset in units of p0.

    Parameters
    ----------
    solution : contactlib.result.Solution
        A solved case (:func:`contactlib.solve`) on a half-space or half-plane, or on a
        layer of thickness h = a / ``slab_ratio`` on a smooth or bonded rigid base
        (:func:`layer_stresses`; the depths z > h, below the layer, are NaN; attributes
        ``layer_thickness`` and ``base``), or a coated body (``base="elastic"``: z > h is
        the substrate; attributes also ``substrate_modulus`` E2/E1 and
        ``substrate_poisson_ratio``); its
        ``pressure`` and ``shear`` (p/p0, q/p0 on ``xi``, piecewise linear between the
        points) are the tractions. p0 is the Hertz peak pressure at the same contact
        radius (docs/conventions.md), so a frictionless case has p = sqrt(1 - xi^2).
    x, z : array_like, 1-d
        r/a (sphere) or x/a (cylinder) and the depth z/a >= 0, positive into the body.
    body : {"body", "indenter"}
        ``"body"``: the elastic body (the lower one, ``nu``). ``"indenter"``: an elastic
        indenter, taken as a half-space of its own Poisson's ratio under the same pressure
        and the opposite shear (Hertz's approximation: the contact is small against R),
        z then positive into the indenter; refused for a rigid indenter.
    measures : bool
        Add ``von_mises``, ``tresca``, ``hydrostatic`` and ``sigma_1`` ... ``sigma_3``.

    Returns
    -------
    xarray.Dataset
        Dimensions (z, x); the components of :data:`COMPONENTS` and the measures, all /p0
        (CF units ``"1"``), tension positive; attributes ``geometry``, ``poisson_ratio``
        (of the body asked for), ``body``, ``stick_ratio``, ``friction_coefficient``,
        ``elements``, ``method``, ``indenter_modulus_ratio`` and ``dundurs_beta``.

    Raises
    ------
    contactlib.validate.InputError
        For a case with NaN tractions, ``body="indenter"`` with a rigid indenter, or a
        bad grid.

    Examples
    --------
    >>> import numpy as np
    >>> from contactlib import solve
    >>> from contactlib.stresses import subsurface_stresses
    >>> sol = solve("sphere", 0.3, stick_ratio=0.0, n=64)
    >>> ds = subsurface_stresses(sol, [0.0], [0.0, 1.0])
    >>> np.round(ds.sigma_zz.values[:, 0], 3)  # Huber: -1/(1 + z^2) on the axis
    array([-1. , -0.5])
    """
    import xarray as xr

    nu, _, _ = _tractions_of(solution, body)
    xi, p, q = traction_samples(solution)
    q = q if body == "body" else -q
    xs, zs = check_grid(x, z)
    geometry = solution.geometry
    slab = float(getattr(solution, "slab_ratio", 0.0)) if body == "body" else 0.0
    substrate = _substrate_of(solution) if slab > 0 else None
    fields = body_field(geometry, nu, xi, p, q, xs, zs, slab, getattr(solution, "base", ""),
                        substrate)
    layer: dict[str, Any] = {}
    if slab > 0:
        layer = {"layer_thickness": 1.0 / slab, "base": str(solution.base),
                 "beyond_layer": "NaN at depths z > h (below the layer, the rigid base)"}
    if substrate is not None:
        layer.update(substrate_modulus=substrate[0], substrate_poisson_ratio=substrate[1],
                     beyond_layer="the substrate at depths z > h (E2/E1 substrate_modulus, "
                                  "Poisson's ratio substrate_poisson_ratio)")
    if measures:
        fields.update(derived_measures(geometry, fields))
    coords = {"z": ("z", zs, {"units": "1", "long_name": "depth / a, positive into the "
                                                         + ("indenter" if body == "indenter"
                                                            else "body")}),
              "x": ("x", xs, {"units": "1", "long_name": ("r / a" if geometry == "sphere"
                                                          else "x / a")})}
    data = {name: (("z", "x"), v, {"units": "1", "long_name": _LONG_NAMES[name]})
            for name, v in fields.items()}
    attrs = {"geometry": geometry, "poisson_ratio": nu, "body": body,
             "stick_ratio": float(solution.stick_ratio),
             "friction_coefficient": float(solution.friction_coefficient),
             "elements": int(solution.n), "method": str(solution.method),
             "indenter_modulus_ratio": float(solution.indenter_modulus_ratio),
             "dundurs_beta": float(solution.dundurs_beta),
             "stress_unit": "p0, the Hertz peak pressure at the same contact radius",
             **layer}
    return xr.Dataset(data, coords=coords, attrs=attrs)


def field_maximum(ds: Any, name: str = "tresca") -> dict[str, float]:
    """Value and place of the largest ``name`` on a Dataset's grid.

    The grid maximum, refined by a parabola through it and its neighbours along each
    axis (where it has both, equally spaced): value error O(h^2) -> O(h^3) of the grid
    spacing h for a smooth peak.

    Parameters
    ----------
    ds : xarray.Dataset
        A field of :func:`subsurface_stresses` (dimensions z, x).
    name : str
        The variable, e.g. ``"tresca"`` or ``"von_mises"``.

    Returns
    -------
    dict
        ``value`` (units of p0), ``x`` and ``z`` (units of a).
    """
    v = np.asarray(ds[name].values, dtype=float)
    xs, zs = np.asarray(ds["x"].values), np.asarray(ds["z"].values)
    iz, ix = np.unravel_index(int(np.nanargmax(v)), v.shape)
    value, place = float(v[iz, ix]), {"x": float(xs[ix]), "z": float(zs[iz])}
    for axis, (i, c) in enumerate(((iz, zs), (ix, xs))):
        if 0 < i < c.size - 1:
            f = v[i - 1:i + 2, ix] if axis == 0 else v[iz, i - 1:i + 2]
            h0, h1 = c[i] - c[i - 1], c[i + 1] - c[i]
            if abs(h0 - h1) > 1e-9 * h0:
                continue
            den = f[0] - 2 * f[1] + f[2]
            if den < 0:
                t = 0.5 * (f[0] - f[2]) / den
                place["z" if axis == 0 else "x"] = float(c[i] + t * h0)
                value += float(-0.125 * (f[0] - f[2])**2 / den)
    return {"value": value, **place}


def surface_radial_stress(solution: Any, x: Sequence[float] | np.ndarray, *,
                          body: str = "body") -> np.ndarray:
    """sigma_rr (sphere) or sigma_xx (cylinder) on the surface z = 0, units of p0.

    At and outside the contact edge (x >= 1) this is the tension that starts cone cracks
    in brittle bodies: (1 - 2 nu)/(3 x^2) for frictionless Hertz (sphere).

    Parameters
    ----------
    solution : contactlib.result.Solution
        A solved case on a half-space or half-plane.
    x : array_like, 1-d
        r/a (x/a) on the surface.
    body : {"body", "indenter"}
        As for :func:`subsurface_stresses`.

    Returns
    -------
    ndarray
        The radial (x) normal stress / p0 at ``x``, tension positive.
    """
    ds = subsurface_stresses(solution, x, [0.0], body=body, measures=False)
    return ds[COMPONENTS[solution.geometry][0]].values[0]


def default_grid() -> tuple[np.ndarray, np.ndarray]:
    """The grid of ``contactlib solve --subsurface``: x = r/a (x/a) and z = depth/a.

    :data:`contactlib.validate.SUBSURFACE_GRID`, 101 equally spaced points on [0, 2] each
    (the field is even in x, sigma_xz odd).

    Returns
    -------
    x, z : ndarray
    """
    from ..validate import SUBSURFACE_GRID

    (x0, x1, nx), (z0, z1, nz) = SUBSURFACE_GRID
    return np.linspace(x0, x1, nx), np.linspace(z0, z1, nz)


def check_subsurface_request(output: Any, slab_ratio: float, base: str = "smooth") -> None:
    """Refuse, before any solving, a subsurface request that cannot be met.

    ``slab_ratio`` and ``base`` are kept for callers; every body is covered (half-space,
    half-plane, a layer on a rigid base, a coated body).

    Raises
    ------
    contactlib.validate.InputError
        Without an output file.
    """
    from ..validate import InputError

    if output is None:
        raise InputError("subsurface", "given with an output file", True,
                         "subsurface needs an output file (--output FILE.nc) for the field")


def with_subsurface(dataset: Any, solution: Any, x: Any = None, z: Any = None) -> Any:
    """A solve's dataset (:func:`contactlib.io.to_dataset`) with the stress field added.

    Parameters
    ----------
    dataset : xarray.Dataset
        The dataset of ``solution``.
    solution : contactlib.result.Solution
        The solved case.
    x, z : array_like, optional
        The grid (default :func:`default_grid`).

    Returns
    -------
    xarray.Dataset
        ``dataset`` with the coordinates ``x``, ``z`` and the variables of
        :func:`subsurface_stresses` for the body (units of p0); with an elastic indenter
        also the indenter's field, each variable prefixed ``indenter_`` (z then into the
        indenter); the attribute ``subsurface_body`` (``"body"`` or ``"body indenter"``).
    """
    if x is None or z is None:
        gx, gz = default_grid()
        x, z = gx if x is None else x, gz if z is None else z
    field = subsurface_stresses(solution, x, z)
    out = dataset.copy()
    for name in field.coords:
        out = out.assign_coords({name: field[name]})
    for name in field.data_vars:
        out[name] = field[name]
    bodies = ["body"]
    if not math.isinf(float(solution.indenter_modulus_ratio)):
        other = subsurface_stresses(solution, x, z, body="indenter")
        for name in other.data_vars:
            out["indenter_" + name] = other[name].assign_attrs(
                long_name=other[name].attrs["long_name"] + " in the indenter (z into it)")
        bodies.append("indenter")
    out.attrs["subsurface_body"] = " ".join(bodies)
    return out


def first_yield(solution: Any, x: Any = None, z: Any = None, *,
                body: str = "body") -> dict[str, float]:
    """Where and at what peak pressure the body first yields (von Mises).

    The field is linear in the tractions, which scale with p0 for a self-similar case,
    so yield starts where von Mises / p0 is largest, at p0 / Y = 1 / max(von Mises / p0)
    for a yield stress Y in tension.

    Parameters
    ----------
    solution : contactlib.result.Solution
        A solved case (half-space or half-plane).
    x, z : array_like, optional
        The grid searched (default: r/a (x/a) on [0, 1.5] and z/a on [0, 1], spacing
        0.01); the maximum is refined by a parabola along each axis
        (:func:`field_maximum`).
    body : {"body", "indenter"}
        As for :func:`subsurface_stresses`.

    Returns
    -------
    dict
        ``p0_over_yield`` (p0 / Y at first yield), ``load_over_yield`` (the load there:
        P / (Y a^2) for the sphere, P / (Y a) per unit length for the cylinder, from the
        solution's ``load_ratio``), ``x`` and ``z`` (units of a) of the first yield.
    """
    xs = np.linspace(0.0, 1.5, 151) if x is None else x
    zs = np.linspace(0.0, 1.0, 101) if z is None else z
    top = field_maximum(subsurface_stresses(solution, xs, zs, body=body), "von_mises")
    ratio = 1.0 / top["value"]
    # P_Hertz(a) / (p0 a^2) = 2 pi / 3 (sphere), pi / 2 per unit length (cylinder)
    hertz = 2.0 * math.pi / 3.0 if solution.geometry == "sphere" else math.pi / 2.0
    return {"p0_over_yield": ratio, "load_over_yield": ratio * hertz * solution.load_ratio,
            "x": top["x"], "z": top["z"]}


def history_stresses(result: Any, step: int, x: Any, z: Any, *, body: str = "body",
                     measures: bool = True) -> Any:
    """The stress field under one step of a loading history, as an xarray Dataset.

    Parameters
    ----------
    result : contactlib.history_api.HistoryResult
        A followed load path (:func:`contactlib.history`) on a half-space or half-plane,
        on a layer on a smooth or bonded rigid base (``slab_ratio`` = a_max/h > 0: the
        depths below the layer, z > h, are NaN) or on a coated body (base "elastic":
        below the layer the substrate's field; :func:`layer_stresses`).
        Its tractions are element-wise, as the history solver has them: on element j
        (edges ``xi_bounds[j]``) the pressure is constant and the shear is q_j r / r_j
        (sphere) or constant (cylinder, odd in x), r_j the midpoint ``xi[j]``.
    step : int
        The step, 0 ... S (negative counts from the end).
    x, z : array_like, 1-d
        r / a_max (x / a_max) and the depth z / a_max >= 0.
    body : {"body", "indenter"}
        As for :func:`subsurface_stresses`.
    measures : bool
        Add the derived measures (:func:`derived_measures`).

    Returns
    -------
    xarray.Dataset
        As :func:`subsurface_stresses`, lengths in units of a_max and stresses in units of
        p0(a_max), the Hertz peak pressure at a_max (docs/conventions.md, histories);
        attributes ``step``, ``load_ratio`` and ``contact_radius`` of the step. A
        viscoelastic body's field is its elastic one: under given tractions the stresses
        of a half-space depend on Poisson's ratio alone, which contactlib's relaxation
        keeps constant.

    Raises
    ------
    contactlib.validate.InputError
        As :func:`subsurface_stresses` (a coated body, a step that did not converge),
        and for a step out of range.
    """
    import xarray as xr

    from ..validate import InputError

    from ..profiles import takes

    if not takes(getattr(result, "profile", "paraboloid"), "stresses"):
        raise InputError("result", "a history of a power-law profile", "profile 'flat'",
                         "result of profile 'flat': stresses are not available under the "
                         "flat punch, whose pressure is "
                         "singular at the sharp edge, where the element-wise field does not "
                         "converge")
    steps = np.asarray(result.pressure).shape[0]
    if not isinstance(step, (int, np.integer)) or not -steps <= int(step) < steps:
        raise InputError("step", f"an integer in [-{steps}, {steps - 1}]", step)
    step = int(step) % steps

    class _Step:  # the step's tractions in the shape _tractions_of reads
        pressure = np.asarray(result.pressure)[step]
        shear = np.asarray(result.shear)[step]
        converged = bool(np.asarray(result.converged)[step])

    for name in ("slab_ratio", "nu", "indenter_modulus_ratio", "indenter_poisson_ratio"):
        setattr(_Step, name, getattr(result, name, math.inf if "modulus" in name else 0.0))
    _Step.base = getattr(result, "base", "smooth")
    nu, p, q = _tractions_of(_Step, body)
    xs, zs = check_grid(x, z)
    bounds = np.asarray(result.xi_bounds, dtype=float)
    mid = np.asarray(result.xi, dtype=float)
    sa, sb = bounds[:, 0], bounds[:, 1]
    geometry = result.geometry
    # element tractions: p constant, q = q_j r/r_j (sphere) or constant (cylinder)
    pieces = ((sa, sb, p, p, q * sa / mid, q * sb / mid) if geometry == "sphere"
              else (sa, sb, p, p, q, q))
    slab = float(getattr(result, "slab_ratio", 0.0))
    if slab > 0 and body == "body":  # the layer (h = a_max/slab_ratio) holds the body's field
        from .layer import check_layer

        kernel_base = _kernel_base(_Step.base, _substrate_of(result))
        nu, h, kernel_base = check_layer(nu, 1.0 / slab, kernel_base)
        fields = _layer_field(geometry, nu, pieces, xs, zs, h, kernel_base)
    else:  # a half-space, or an elastic indenter (a half-space) on a layer
        fields = _pieces_field(geometry, nu, pieces, xs, zs)
    if measures:
        fields.update(derived_measures(geometry, fields))
    into = "indenter" if body == "indenter" else "body"
    coords = {"z": ("z", zs, {"units": "1", "long_name": f"depth / a_max, into the {into}"}),
              "x": ("x", xs, {"units": "1", "long_name": ("r / a_max" if geometry == "sphere"
                                                          else "x / a_max")})}
    data = {name: (("z", "x"), v, {"units": "1",
                                   "long_name": _LONG_NAMES[name].replace("p0", "p0(a_max)")})
            for name, v in fields.items()}
    attrs = {"geometry": geometry, "poisson_ratio": nu, "body": body, "step": step,
             "load_ratio": float(np.asarray(result.load_ratio)[step]),
             "contact_radius": float(np.asarray(result.contact_radius)[step]),
             "slab_ratio": float(getattr(result, "slab_ratio", 0.0)),
             "friction_coefficient": float(result.friction), "elements": int(result.n),
             "indenter_modulus_ratio": float(getattr(result, "indenter_modulus_ratio",
                                                     math.inf)),
             "stress_unit": "p0(a_max), the Hertz peak pressure at a_max"}
    if attrs["slab_ratio"] > 0:
        attrs["base"] = _Step.base
        if _substrate_of(result) is not None:
            attrs["substrate_modulus"], attrs["substrate_poisson_ratio"] = _substrate_of(result)
    return xr.Dataset(data, coords=coords, attrs=attrs)


def scene_subsurface(dataset: Any, scene: Any, profiles: Sequence[dict[str, np.ndarray]],
                     xi: np.ndarray) -> Any:
    """A scene's dataset with the ``subsurface`` output: the field of every stick ratio.

    Parameters
    ----------
    dataset : xarray.Dataset
        The scene's dataset (:func:`contactlib.io.scene_to_dataset`), dimension
        ``stick_ratio``.
    scene : contactlib.scene.Scene
        The scene (its ``geometry``, ``nu`` and ``subsurface_grid``).
    profiles : sequence of dict
        One a stick ratio, in the dataset's order: ``pressure`` and ``shear`` (p/p0,
        q/p0) on ``xi``, and the solve's nodal tractions where it has them (``nodes``,
        ``nodal_pressure``, ``nodal_shear``: :func:`contactlib.stages.nodal_tractions`),
        which the field then integrates.
    xi : ndarray
        The profiles' abscissae.

    Returns
    -------
    xarray.Dataset
        ``dataset`` with the coordinates ``x``, ``z`` and the variables of
        :func:`subsurface_stresses` on (stick_ratio, z, x), in units of p0; NaN for a case
        whose tractions are NaN (not converged). With an elastic indenter also its field
        (prefix ``indenter_``; its Poisson's ratio, the opposite shear, z into it, as
        :func:`subsurface_stresses` with ``body="indenter"``); attribute
        ``subsurface_body``.
    """
    from ..validate import COATED_BASE

    (x0, x1, nx), (z0, z1, nz) = scene.subsurface_grid
    xs, zs = np.linspace(x0, x1, nx), np.linspace(z0, z1, nz)
    geometry = scene.geometry
    names = COMPONENTS[geometry] + ("von_mises", "tresca", "hydrostatic", "sigma_1",
                                    "sigma_2", "sigma_3")
    bodies = {"": (float(scene.nu), 1.0)}  # prefix: (Poisson's ratio, sign of the shear)
    if not math.isinf(float(scene.indenter_modulus)):
        nu1 = scene.nu if scene.indenter_nu is None else scene.indenter_nu
        bodies["indenter_"] = (float(nu1), -1.0)
    stack = {prefix + name: np.full((len(profiles), zs.size, xs.size), np.nan)
             for prefix in bodies for name in names}
    substrate = None  # a coated body's (E2/E1, nu2; nu2 None: the layer's)
    if getattr(scene, "base", "smooth") == COATED_BASE:
        nu2 = scene.nu if scene.substrate_nu is None else scene.substrate_nu
        substrate = (float(scene.substrate_modulus), float(nu2))
    for i, prof in enumerate(profiles):
        p, q = np.asarray(prof["pressure"]), np.asarray(prof["shear"])
        if not (np.all(np.isfinite(p)) and np.all(np.isfinite(q))):
            continue
        at = xi
        if "nodes" in prof:  # the solve's own tractions, as the API's field (traction_samples)
            at, p, q = prof["nodes"], prof["nodal_pressure"], prof["nodal_shear"]
        for prefix, (nu, sign) in bodies.items():
            slab = float(getattr(scene, "slab_ratio", 0.0)) if not prefix else 0.0
            fields = body_field(geometry, nu, at, p, sign * q, xs, zs, slab,
                                getattr(scene, "base", "smooth"), substrate)
            fields.update(derived_measures(geometry, fields))
            for name in names:
                stack[prefix + name][i] = fields[name]
    out = dataset.assign_coords(
        z=("z", zs, {"units": "1", "long_name": "depth / a, positive into the body "
                                                "(into the indenter for indenter_*)"}),
        x=("x", xs, {"units": "1", "long_name": "r / a" if geometry == "sphere" else "x / a"}))
    dims = ("stick_ratio", "z", "x") if "stick_ratio" in dataset.dims else ("z", "x")
    for prefix in bodies:
        for name in names:
            value = stack[prefix + name]
            long_name = _LONG_NAMES[name] + (" in the indenter" if prefix else "")
            out[prefix + name] = (dims, value if len(dims) == 3 else value[0],
                                  {"units": "1", "long_name": long_name})
    out.attrs["subsurface_body"] = "body indenter" if len(bodies) > 1 else "body"
    return out


def field_error_estimate(solution: Any, x: Any, z: Any, *, body: str = "body") -> Any:
    """Estimated discretization error of :func:`subsurface_stresses`: the change from n/2.

    The same case (c/a, materials, indenter) is solved again on n/2 elements and the
    estimate is the absolute difference of the two fields, variable by variable (no
    Richardson division: at n = 128 the field's convergence in n is not yet regular).
    The field integrates the solve's own nodal tractions (:func:`traction_samples`), so
    it converges with n. Measured (tests/test_stresses.py, sphere and cylinder, c/a =
    0.5 and 0.9, n = 128): at the maxima of von Mises and Tresca it covers the difference
    to the field at 4n, which it exceeds by 1.3 ... 2.8 times; on the whole 31 x 31 grid
    it covers it everywhere but at one surface point of the cylinder at c/a = 0.9, where
    the n/2 difference crosses zero (0.5x there, of an error 1e-2 of the grid's largest).

    Parameters
    ----------
    solution : contactlib.result.Solution
        A case of the default method (n >= 2 * the method's smallest n).
    x, z : array_like, 1-d
        As for :func:`subsurface_stresses`.
    body : {"body", "indenter"}
        As for :func:`subsurface_stresses`.

    Returns
    -------
    xarray.Dataset
        The variables of :func:`subsurface_stresses`, each the estimated absolute error
        (units of p0), attribute ``reference_elements`` (n/2).

    Raises
    ------
    contactlib.validate.InputError
        For another method, an n too small to halve, or what
        :func:`subsurface_stresses` refuses.
    """
    from .. import api
    from ..validate import MIN_N_DEFAULT_METHOD, InputError

    if solution.method != "default":
        raise InputError("method", "default for a field error estimate", solution.method)
    half = int(solution.n) // 2
    if half < MIN_N_DEFAULT_METHOD:
        raise InputError("n", f">= {2 * MIN_N_DEFAULT_METHOD} for a field error estimate",
                         solution.n)
    fine = subsurface_stresses(solution, x, z, body=body)
    kw: dict[str, Any] = ({"base": solution.base, "slab_ratio": float(solution.slab_ratio)}
                          if solution.slab_ratio > 0 else {})
    substrate = _substrate_of(solution) if solution.slab_ratio > 0 else None
    if substrate is not None:
        kw.update(substrate_modulus=substrate[0], substrate_nu=substrate[1])
    if not math.isinf(float(solution.indenter_modulus_ratio)):
        kw.update(indenter_modulus=float(solution.indenter_modulus_ratio),
                  indenter_nu=float(solution.indenter_poisson_ratio))
    coarse_solution = api.solve(solution.geometry, solution.nu,
                                stick_ratio=float(solution.stick_ratio), n=half, energy=False,
                                **kw)
    coarse = subsurface_stresses(coarse_solution, x, z, body=body)
    out = abs(fine - coarse)
    for name in out.data_vars:
        out[name].attrs = {"units": "1",
                           "long_name": "estimated error of " + fine[name].attrs["long_name"]}
    out.attrs = dict(fine.attrs, reference_elements=half)
    return out


def _strip_field(mid: np.ndarray, p: np.ndarray, q: np.ndarray, sigma: float, xs: np.ndarray,
                 zs: np.ndarray, body: str, nu: float) -> dict[str, np.ndarray]:
    """The components under a cylinder's fretting step: its element tractions (constant p
    and q on equal strip elements of midpoints ``mid``) plus, in the body, the bulk stress
    ``sigma`` along x (plane strain). Units p0(a_max), a_max."""
    half = 0.5 * float(mid[1] - mid[0])
    if body == "indenter":  # the indenter's surface carries p and the opposite shear
        q = -q
    fields = _halfplane_pieces(mid - half, mid + half, p, p, q, q, xs, zs, nu)
    if body == "body":
        fields["sigma_xx"] = fields["sigma_xx"] + sigma
        fields["sigma_yy"] = fields["sigma_yy"] + nu * sigma
    return fields


def cylinder_fretting_stresses(result: Any, step: int, x: Any, z: Any, *,
                               body: str = "body", error_estimate: bool = True,
                               measures: bool = True) -> Any:
    """The plane-strain stress field under a step of ``contactlib.fretting("cylinder", ...)``.

    The tractions are the run's own, constant on each strip element over the whole
    strip (tangential loading breaks the symmetry of p and q), integrated exactly
    (Johnson's half-plane kernels, as :func:`halfplane_stresses_line`); in the body the
    step's bulk stress sigma along x is added (sigma_xx += sigma, sigma_yy += nu sigma:
    plane strain, as the solver's bulk strain). On the surface itself the field of
    element tractions has a logarithmic spike at every element edge, so z > 0.

    Parameters
    ----------
    result : contactlib.fretting_api.FrettingResult
        A cylinder's fretting path.
    step : int
        The step (``result.point_step`` holds the path points'); negative counts from
        the end. With ``error_estimate`` a multiple of 4 (the coarse runs have a half and
        a quarter of the steps; every path point is one).
    x, z : array_like, 1-d
        x / a_max (either sign, x along the tangential load) and depth z / a_max > 0.
    body : {"body", "indenter"}
        The body (default), or an elastic indenter taken as a half-plane of its own
        Poisson's ratio under the same pressure and the opposite shear, z into it.
    error_estimate : bool
        Add ``<name>_error``, the larger of |field(n) - field(n/2)| and |field(n/2) -
        field(n/4)| (the same path with n/2 and n/4 elements and a half and a quarter of
        the steps, from ``result.model``; together about 0.2 of the run's cost), and the
        attributes ``<name>_max_error`` for the maxima of von Mises and Tresca (the same
        rule on the maxima, and never below the field's estimate at the maximum).
        Measured (tests/test_fretting_stresses_cylinder.py): it covers the change to the
        run with 4n elements and 4 times the steps at the maxima. Default True.
    measures : bool
        Add the derived measures (:func:`derived_measures`).

    Returns
    -------
    xarray.Dataset
        On (z, x), in units of p0(a_max) (the Hertz peak pressure at P_max) and a_max:
        sigma_xx, sigma_yy, sigma_zz, sigma_xz and the measures; attributes ``step``,
        ``load_ratio``, ``force_ratio`` (Q/(k P_max)), ``bulk_stress``, ``contact_edges``,
        ``stick_edges``, and ``max_<name>`` with its place for von Mises and Tresca.

    Raises
    ------
    contactlib.validate.InputError
        Not a cylinder's result, a step out of range (or not a multiple of 4 with the
        estimate), z <= 0, a rigid indenter's field, or an estimate for a result without
        its model.
    contactlib.validate.SolverLimit
        The step (or a coarse run's) did not converge: its tractions are not data.
    """
    import xarray as xr

    from .. import validate

    if getattr(result, "geometry", None) != "cylinder":
        raise validate.InputError("result", "a cylinder's FrettingResult (contactlib.fretting("
                                  "'cylinder', ...); the sphere's: contactlib.stresses.grid."
                                  "fretting_stresses)", getattr(result, "geometry", result))
    if body not in ("body", "indenter"):
        raise validate.InputError("body", "'body' or 'indenter'", body)
    total = len(result.load_ratio)
    if not isinstance(step, (int, np.integer)) or not -total <= int(step) < total:
        raise validate.InputError("step", f"an integer in [-{total}, {total - 1}]", step)
    step = int(step) % total
    xs, zs = check_grid(x, z)
    if np.any(zs <= 0):
        raise validate.InputError("z", "depths z > 0 (on the surface the field of element "
                                  "tractions spikes at every element edge)", float(zs.min()))
    model = getattr(result, "model", None)
    nu = float(result.nu)
    if body == "indenter":
        if model is None or math.isinf(float(model.indenter.modulus_ratio)):
            raise validate.InputError("body", "'body' for a rigid indenter (or a result "
                                      "without its model)", body)
        nu = float(model.indenter.nu if model.indenter.nu is not None else result.nu)
    p = np.asarray(result.pressure, dtype=float)[step]
    q = np.asarray(result.shear, dtype=float)[step]
    if not (bool(np.asarray(result.converged)[step]) and np.all(np.isfinite(p))
            and np.all(np.isfinite(q))):
        raise validate.SolverLimit(f"fretting stresses: step {step} did not converge, so its "
                                   "tractions are not data; refine the steps")
    sigma = float(np.asarray(result.bulk_stress, dtype=float)[step])
    fields = _strip_field(np.asarray(result.x, dtype=float), p, q, sigma, xs, zs, body, nu)
    coarse: list[dict[str, np.ndarray]] = []
    if error_estimate:
        from ..fretting_api import run_path

        if step % 4:
            raise validate.InputError(
                "step", "a multiple of 4 with error_estimate (the coarse runs have a half and "
                "a quarter of the steps; every path point is one); pass "
                "error_estimate=False for this step", step)
        if model is None:
            raise validate.InputError("result", "a result that carries its model for the "
                                      "estimate", "model None", "result: it carries no model "
                                      "(rebuilt elsewhere); pass error_estimate=False")
        path = [np.asarray(v, dtype=float) for v in
                (result.load_path, result.tangential_path, result.bulk_stress_path)]
        for div in (2, 4):
            ops, raw = run_path(model, int(result.n) // div, int(result.steps) // div,
                                float(result.friction), *path)
            s = step // div
            if not bool(raw.converged[s]):
                raise validate.SolverLimit(
                    f"fretting stresses: step {s} of the estimate's run with n = "
                    f"{int(result.n) // div} did not converge; pass error_estimate=False")
            coarse.append(_strip_field(ops.mid, raw.p[s] / ops.p0, raw.q[s] / ops.p0,
                                       float(raw.strain[s] / (ops.p0 * ops.strain_share)),
                                       xs, zs, body, nu))
    if measures:
        for f in [fields, *coarse]:
            f.update(derived_measures("cylinder", f))
    into = "indenter" if body == "indenter" else "body"
    data = {name: (("z", "x"), v, {"units": "1",
                                   "long_name": _LONG_NAMES[name].replace("p0", "p0(a_max)")})
            for name, v in fields.items()}
    attrs: dict[str, Any] = {
        "geometry": "cylinder", "poisson_ratio": nu, "body": body, "step": step,
        "load_ratio": float(np.asarray(result.load_ratio)[step]),
        "force_ratio": float(np.asarray(result.force_ratio)[step]),
        "bulk_stress": sigma,
        "contact_edges": [float(v) for v in np.asarray(result.contact_edges)[step]],
        "stick_edges": [float(v) for v in np.asarray(result.stick_edges)[step]],
        "friction_coefficient": float(result.friction), "elements": int(result.n),
        "stress_unit": "p0(a_max), the Hertz peak pressure at P_max"}
    if coarse:
        for name, v in fields.items():
            err = np.maximum(np.abs(v - coarse[0][name]),
                             np.abs(coarse[0][name] - coarse[1][name]))
            data[f"{name}_error"] = (("z", "x"), err,
                                     {"units": "1", "long_name": f"estimated error of {name}"})
        attrs["reference_elements"] = f"{int(result.n) // 2} {int(result.n) // 4}"
    coords = {"z": ("z", zs, {"units": "1", "long_name": f"depth / a_max, into the {into}"}),
              "x": ("x", xs, {"units": "1",
                              "long_name": "x / a_max (along the tangential load)"})}
    ds = xr.Dataset(data, coords=coords, attrs=attrs)
    if measures:
        for name in ("von_mises", "tresca"):
            top = field_maximum(ds, name)
            ds.attrs[f"max_{name}"] = top["value"]
            ds.attrs[f"max_{name}_x"], ds.attrs[f"max_{name}_z"] = top["x"], top["z"]
            if coarse:
                tops = [float(np.max(f[name])) for f in (fields, *coarse)]
                v = ds[f"{name}_error"].values
                at = float(v[np.unravel_index(int(np.argmax(fields[name])), v.shape)])
                ds.attrs[f"{name}_max_error"] = max(abs(tops[0] - tops[1]),
                                                    abs(tops[1] - tops[2]), at)
    return ds
