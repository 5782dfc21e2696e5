r"""Axisymmetric surface displacements of an elastic layer on a rigid base.

The body is an elastic layer ``0 < z < h`` (``z`` into the body) resting on a
rigid base at ``z = h``, either **smooth** (frictionless: ``u_z = 0``,
``tau_rz = 0``) or **bonded** (``u_z = u_r = 0``). The loads and outputs are
those of :mod:`contactlib.kernels.disc` (same conventions, same signatures
plus ``h`` and ``base``):

``pressure_disc``
    uniform unit pressure p = 1 (compressive) on ``r < s``;
``shear_disc``
    linear radial shear q = r (outward) on ``r < s``.

Units and conventions: ``E* = E / (1 - nu**2) = 1``; ``w`` normal surface
displacement positive INTO the body, ``u`` radial, positive away from the axis,
``du`` = ``du/dr``; ``beta = (1 - 2 nu) / (2 (1 - nu))``, ``kappa = 3 - 4 nu``.
Displacements scale like (traction) * length / E*.

Transfer functions
------------------
With the Hankel transforms ``P(k) = int_0^inf p(r) J0(kr) r dr`` and
``Q(k) = int_0^inf q(r) J1(kr) r dr`` and ``t = k h``::

    w(r) = 2 int_0^inf [ Cww(t) P(k) - Cwu(t) Q(k) ] J0(kr) dk
    u(r) = 2 int_0^inf [-Cwu(t) P(k) + Cuu(t) Q(k) ] J1(kr) dk

The half-space has ``Cww = Cuu = 1``, ``Cwu = beta`` (the Boussinesq/Cerruti
kernels of ``disc``). The layer (derived here from the Love strain function
``phi = J0(kr) f(z)``, ``f = (A + Bz) e^{kz} + (C + Dz) e^{-kz}``, four boundary
conditions; the axisymmetric transfer functions equal the plane-strain ones of
:mod:`contactlib.kernels.strip` in ``|k|h``)::

    smooth:  D = sinh 2t + 2t
             Cww = (cosh 2t - 1)/D,  Cuu = (cosh 2t + 1)/D,  Cwu = beta - 2t/D
    bonded:  N = 2 kappa cosh 2t + 1 + kappa^2 + 4 t^2
             Cww = (2 kappa sinh 2t - 4t)/N,  Cuu = (2 kappa sinh 2t + 4t)/N,
             Cwu = [2 kappa (kappa - 1)(cosh 2t - 1) - 8 t^2] / ((kappa + 1) N)

(the bonded ``Cww`` is the classical one, e.g. Vorovich et al.; the cross
terms are equal, as Betti requires). Thin-layer limits ``t -> 0``: smooth
``Cww -> t`` (uniaxial stress: ``w = h p / E*``), bonded ``Cww -> t (1 - 2
nu)/(2 (1 - nu)^2)`` (``w = p h / M``, ``M = E (1 - nu)/((1 + nu)(1 - 2 nu))``
the constrained modulus: Winkler), and at ``nu = 1/2`` bonded ``Cww -> (2/3)
t^3`` (``w = -(h^3 / (3G)) lap p``: the thin incompressible layer). Nothing is
0/0 at ``nu = 1/2`` (``kappa = 1``, ``beta = 0``).

Remainders
----------
``R = C - C(inf)`` decays like ``t^2 exp(-2t)``; written with ``e = exp(-2t)``
so that nothing overflows or cancels::

    smooth:  Ds = 1 - e^2 + 4 t e  (= 2 e D)
             Rww = 2 e (e - 1 - 2t)/Ds, Rwu = -4 t e/Ds, Ruu = 2 e (e + 1 - 2t)/Ds
    bonded:  Ns = kappa (1 + e^2) + (1 + kappa^2 + 4 t^2) e  (= e N)
             Rww = -e (2 kappa e + 1 + kappa^2 + 4t + 4t^2)/Ns
             Ruu = -e (2 kappa e + 1 + kappa^2 - 4t + 4t^2)/Ns
             Rwu = -e (kappa^2 - 1 + 4 t^2)/Ns

(smooth ``Ruu ~ 1/(2t)`` at ``t -> 0``: membrane stretching; the integrals
below stay regular). For the disc loads ``P = s J1(ks)/k``, ``Q = s^2
J2(ks)/k``; with ``rho = r/h``, ``sigma = s/h`` and ``J1'(x) = (J0 - J2)/2``,
the layer kernels are the half-space kernels of ``disc`` plus::

    pressure:  w += h Pw,   u += h Pu,   du += Pd
    shear:     w += h^2 Sw, u += h^2 Su, du += h Sd

    Pw = 2 sigma   int Rww J1(sigma t) J0(rho t)  dt/t
    Pu = -2 sigma  int Rwu J1(sigma t) J1(rho t)  dt/t,  Pd = dPu/drho
       = -2 sigma  int Rwu J1(sigma t) J1'(rho t) dt
    Su = 2 sigma^2 int Ruu J2(sigma t) J1(rho t)  dt/t,  Sd = dSu/drho
       = 2 sigma^2 int Ruu J2(sigma t) J1'(rho t) dt
    Sw = -2 sigma^2 int Rwu J2(sigma t) J0(rho t) dt/t

all over ``0 < t < inf``. These six functions of (rho, sigma) are smooth
(analytic: the singular parts at ``r = s`` are all in the half-space part).

Numerics
--------
*Quadrature* (table build, ``_remainder_quadrature``): composite 20-point
Gauss-Legendre on ``0 < t < 24`` in panels of 0.25 (1920 nodes; the integrands
are ``O(t^2 e^{-2t})``, below 1e-18 beyond; 20 points resolve the Bessel
oscillations ``(rho + sigma) t`` for ``rho + sigma <= 40``), evaluated as matrix
products ``J(rho_i t_q) w_q R(t_q) J(sigma_j t_q)`` on tensor grids; converged
to ~1e-13 of scale against a rule with panels of 0.1, 30 points, ``t < 36``.

*Table* (``layer_table``, once per (nu, base), ``functools.lru_cache``; the
smooth table does not depend on nu): tensor Chebyshev interpolation of the
six functions on cells of 0.5 x 0.5 covering ``0 <= rho, sigma <= RATIO_MAX
= 20``, degree 10 in each variable at the Chebyshev-Lobatto points (which
include the cell edges, so that neighbouring cells agree on their common edge
and the table is continuous to round-off; 121 coefficients a cell and
function; 8.9 MiB a table; built in 2-3 s). Measured interpolation error at
random points against the quadrature: <= 5e-13 (smooth), <= 1.7e-12 (bonded,
nu = 0.3) and <= 5.2e-12 (bonded, nu = 1/2) of the scale (1 for Pw, Pu, Pd;
max(1, rho, sigma) for Sd; max(1, rho, sigma)^2 for Su, Sw), largest for the
derivatives. (Degree 9 at interior Chebyshev points: <= 1.6e-11, and jumps of
that size across cell edges, which the default method's finest elements turned
into k errors of 2e-3 at n = 2048.) Evaluation sorts the points by cell and
sums each cell's points with one small matrix product (``_chebyshev_eval``).

*Small arguments* (``max(rho, sigma) < 0.25``, i.e. thick layers): the table's
absolute error would be multiplied by ``h`` or ``h^2``; there the double power
series of the Bessel functions is summed instead, with the moments
``M_k = int_0^inf R(t) t^k dt`` (same quadrature on ``t < 96``; 14 terms a
variable; 2e-14 relative against the quadrature). It hands over to the table
smoothly: the share ``b(rho) b(sigma)`` of the series, ``b`` = 1 below 0.2 and
0 from 0.25, quintic between (``_series_weight``), so nothing jumps. The leading term gives the
thick-layer limit, e.g. for the pressure ``w - w_halfspace -> (s^2/h)
M_0(Rww)`` (uniform, O(s/h) relative).

Supported range: ``max(r, s) / h <= RATIO_MAX = 20`` for the tables; beyond
it, up to ``THIN_RATIO_MAX = 1200``, on a rigid base (smooth, bonded) and on a
coated body alike, the remainders are summed in the transform domain instead
(:mod:`contactlib.kernels.thin_layer`); beyond that a ``ValueError`` is
raised. ``h = inf`` is the half-space.

Coated body
-----------
``base = Substrate(modulus, nu2)``: the layer (E1, nu; ``E* = E1*`` = 1) bonded
to an elastic half-space (E2 = ``modulus`` E1, nu2). Its remainders come from
:func:`coated_remainder` (a batched 6x6 solve a t for the correction to the
layer material's half-space field: no overflow, no cancellation) and enter the
same tables, series and quadratures. They tend to constants at ``t -> 0``
(``m - 1``, ``m beta2 - beta``, ``m - 1``, ``m = E1*/E2*``: the substrate's
half-space), as the rigid bonded base's do (-1, -beta, -1), so every integral
above stays regular, and decay like ``t^2 e^{-2t}``. A stiff layer on a soft
substrate (``m >> 1``) bends over ``t ~ m^(-1/3)``: the quadratures then take
32 panels on ``0 < t < 2 min(1, m^(-1/3))`` (``fine_panel``); against a rule
of panels 0.1, 30 points, ``t < 36``, converged to 7e-12 of the scale at
E2/E1 = 1e-2, 7e-13 at 0.1, 5e-14 at 1e6 (1e-8 at 1e-3, outside the
supported range). Measured table error at random points: <= 1e-11 of the
scale above times ``max(1, |m - 1|)`` for E2/E1 in [1e-2, 1e6]
(``tests/test_coatings.py``). One table per (nu, substrate): 8.9 MiB a
table (the ``lru_cache`` holds 8), 2-5 s to build.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from math import factorial

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import disc, thin_layer
from .layer_transfer import (BASES, FINE_PANELS, FINE_T, Substrate, check_base, check_nu,
                             coated_remainder, fine_panel, remainder_transfer, transfer)

__all__ = ["AXIS_RHO_MAX", "BASES", "RATIO_MAX", "THIN_RATIO_MAX", "LayerTable", "Substrate",
           "coated_remainder", "fine_panel", "FINE_T", "FINE_PANELS",
           "layer_table", "pressure_disc",
           "remainder_axis_w", "remainder_grid", "remainder_transfer", "shear_disc", "transfer"]

Arr = NDArray[np.float64]

# limit: the tables' range, checked against quadrature in tests/test_kernels_layer.py
RATIO_MAX = 20.0  # max(r, s)/h covered by the tables
# limit: the transform-domain sums to 1.2 x 1000 h (tests/test_thin_layers.py,
# tests/test_thin_coatings.py: a/h = 1000 and its mesh's 20 % beyond)
THIN_RATIO_MAX = 1200.0  # max(r, s)/h of the transform-domain sums (thin_layer)

# tested: tests/test_kernels_layer.py (the tables against quadrature); their cost:
# benchmarks/bench_layer.py
_CELL = 0.5  # table cell width in rho and sigma
# tested: tests/test_kernels_layer.py (the tables against quadrature); their cost:
# benchmarks/bench_layer.py
_DEG = 10  # Chebyshev degree in each variable
_N_CELLS = int(round(RATIO_MAX / _CELL))
# tested: tests/test_kernels_layer.py (table and power series against the quadrature)
_SERIES_MAX = 0.25  # max(rho, sigma) below which the power series is used
# tested: tests/test_kernels_layer.py (table and power series against the quadrature)
_BLEND = 0.05  # the series hands over to the table smoothly over _SERIES_MAX - _BLEND ... MAX
# tested: tests/test_kernels_layer.py (table and power series against the quadrature)
_SERIES_TERMS = 14
# tested: tests/test_kernels_layer.py (the tables' quadrature against scipy's quad)
_T_MAX = 24.0
# tested: tests/test_kernels_layer.py (the tables' quadrature against scipy's quad)
_T_PANEL = 0.25
# tested: tests/test_kernels_layer.py (the tables' quadrature against scipy's quad)
_GL_ORDER = 20
# convention: scratch size, the results do not depend on it (speed: benchmarks/bench_layer.py)
_CHUNK = 65536  # points per pass
# measured: benchmarks/bench_layer.py (kernel evaluation for 2048 rings against the half-space)
_GROUP_MIN = 48  # mean points a cell above which points are grouped by cell
# measured: benchmarks/bench_layer.py (kernel evaluation for 2048 rings against the half-space);
# tests/test_layer_accuracy.py checks grid and points agree
_GRID_MIN = 256  # points of an outer-product (r, s) grid above which it is evaluated as one

# (name, remainder, power of sigma in the prefactor (2 sigma^a), sign, Bessel order in
#  sigma, function of rho t, power of t in the measure (dt/t: -1))
_SPECS = {
    "pressure": (("w", "ww", 1, 1.0, 1, "J0", -1),
                 ("u", "wu", 1, -1.0, 1, "J1", -1),
                 ("du", "wu", 1, -1.0, 1, "dJ1", 0)),
    "shear": (("w", "wu", 2, -1.0, 2, "J0", -1),
              ("u", "uu", 2, 1.0, 2, "J1", -1),
              ("du", "uu", 2, 1.0, 2, "dJ1", 0)),
}


def _gauss_panels(t_max: float, fine: float | None = None) -> tuple[Arr, Arr]:
    """Composite Gauss-Legendre nodes and weights on 0 < t < t_max.

    Panels of ``_T_PANEL``; with ``fine`` (:func:`fine_panel`), 32 panels on
    ``0 < t < FINE_T fine`` before them.
    """
    g, w = np.polynomial.legendre.leggauss(_GL_ORDER)
    edges = np.arange(0.0, t_max + 0.5 * _T_PANEL, _T_PANEL)
    if fine is not None:
        t_fine = FINE_T * fine
        edges = np.concatenate([np.linspace(0.0, t_fine, FINE_PANELS + 1),
                                edges[edges > t_fine]])
    lo, hi = edges[:-1, None], edges[1:, None]
    return (0.5 * (hi - lo) * g + 0.5 * (lo + hi)).ravel(), (0.5 * (hi - lo) * w).ravel()


def _rho_function(name: str, x: Arr) -> Arr:
    # here, not at import: contactlib.scene imports this module (Snakemake's own process)
    from scipy import special

    if name == "J0":
        return special.j0(x)
    if name == "J1":
        return special.j1(x)
    return 0.5 * (special.j0(x) - special.jv(2, x))  # J1'


def _remainder_quadrature(kind: str, rho: ArrayLike, sigma: ArrayLike, nu: float,
                          base: str) -> tuple[Arr, Arr, Arr]:
    """The three remainder functions on the tensor grid ``rho x sigma`` (slow path).

    Parameters
    ----------
    kind : {"pressure", "shear"}
    rho, sigma : array_like
        1-d arrays of ``r/h`` and ``s/h`` (``rho + sigma <= 40``).
    nu : float
    base : {"smooth", "bonded"}

    Returns
    -------
    fw, fu, fdu : ndarray, shape (rho.size, sigma.size)
        ``(Pw, Pu, Pd)`` or ``(Sw, Su, Sd)`` of the module notes.
    """
    # here, not at import: contactlib.scene imports this module (Snakemake's own process)
    from scipy import special

    t, wt = _gauss_panels(_T_MAX, fine_panel(nu, base))
    rem = dict(zip(("ww", "wu", "uu"), remainder_transfer(t, nu, base)))
    rho = np.atleast_1d(np.asarray(rho, dtype=float))
    sigma = np.atleast_1d(np.asarray(sigma, dtype=float))
    st = np.multiply.outer(sigma, t)
    js = {1: special.j1(st), 2: special.jv(2, st)}
    rt = np.multiply.outer(rho, t)
    jr = {}
    out = []
    for _, rname, power, sign, order, rfun, tpow in _SPECS[kind]:
        if rfun not in jr:
            jr[rfun] = _rho_function(rfun, rt)
        weights = wt * rem[rname] * (t**tpow)
        val = (jr[rfun] * weights) @ js[order].T
        val *= 2.0 * sign * sigma[None, :] ** power
        out.append(val)
    return out[0], out[1], out[2]


# --- small-argument series -------------------------------------------------------
def _bessel_series(order: int, n: int) -> tuple[Arr, Arr]:
    """Coefficients c_m and powers p_m with J_order(x) = sum c_m x^p_m (m < n)."""
    m = np.arange(n)
    c = np.array([(-1.0) ** i / (factorial(i) * factorial(i + order) * 2.0 ** (2 * i + order))
                  for i in range(n)])
    return c, 2 * m + order


def _rho_series(name: str, n: int) -> tuple[Arr, Arr]:
    if name == "J0":
        return _bessel_series(0, n)
    if name == "J1":
        return _bessel_series(1, n)
    c0, p0 = _bessel_series(0, n)  # J1' = (J0 - J2)/2; J2's x^(2m) is its term m - 1
    c2, _ = _bessel_series(2, n)
    c = 0.5 * c0
    c[1:] -= 0.5 * c2[:-1]
    return c, p0


def _moments(nu: float, base: str, kmax: int) -> dict[str, Arr]:
    """M_k = int_0^inf R(t) t^k dt, k = 0..kmax, for the three remainders."""
    t, wt = _gauss_panels(96.0, fine_panel(nu, base))
    rem = remainder_transfer(t, nu, base)
    powers = t[None, :] ** np.arange(kmax + 1)[:, None]
    return {name: powers @ (wt * r) for name, r in zip(("ww", "wu", "uu"), rem)}


@dataclass(frozen=True)
class LayerTable:
    """Interpolation data of the six remainder functions for one (nu, base).

    Attributes
    ----------
    nu, base :
        The material and base the table was built for (``nu`` is None for the
        smooth base, whose remainders do not depend on it).
    coef : dict
        ``coef[kind]`` (kind "pressure" or "shear"), shape
        ``(_N_CELLS**2, 3 * (_DEG + 1), _DEG + 1)``: Chebyshev coefficients
        ``c[i * _N_CELLS + j, f * (_DEG + 1) + l, k]`` of T_k(x) T_l(y) for the
        (w, u, du) remainder f in cell (i, j) of (rho, sigma), x and y the
        cell's local coordinates in [-1, 1].
    series : dict
        ``series[kind]``: list of three (prefactor power, sign, sigma
        coefficients and powers, rho coefficients and powers, moment matrix).
    """

    nu: float | None
    base: str
    coef: dict
    series: dict

    @property
    def nbytes(self) -> int:
        """Memory of the coefficient arrays in bytes."""
        return int(sum(c.nbytes for c in self.coef.values()))


def _chebyshev_nodes() -> Arr:
    """Chebyshev-Lobatto points cos(pi j / _DEG), j = 0.._DEG (both ends of the cell)."""
    return np.cos(np.pi * np.arange(_DEG + 1) / _DEG)


def _lobatto_inverse() -> Arr:
    """(k, j): values at :func:`_chebyshev_nodes` -> Chebyshev coefficients (DCT-I)."""
    k = np.arange(_DEG + 1)
    inv = (2.0 / _DEG) * np.cos(np.pi * np.outer(k, k) / _DEG)
    inv[:, [0, _DEG]] *= 0.5
    inv[[0, _DEG]] *= 0.5
    return inv


@functools.lru_cache(maxsize=8)
def _build_table(nu: float | None, base: str) -> LayerTable:
    # Lobatto points include the cell edges: two neighbouring cells interpolate the same
    # values on their common edge, so the table is continuous across cells (to round-off).
    # With interior (Gauss-Chebyshev) points it jumped by ~1e-11 there, and the default
    # method's finest elements next to a stick edge on a cell edge (c = 0.5 h) turned that
    # jump into k errors of 2e-4 (n = 1024) and 2e-3 (n = 2048).
    x = _chebyshev_nodes()
    pts = ((np.arange(_N_CELLS)[:, None] + 0.5) * _CELL + 0.5 * _CELL * x[None, :]).ravel()
    inv = _lobatto_inverse()
    nu_eff = 0.3 if nu is None else nu
    coef = {}
    for kind in ("pressure", "shear"):
        vals = _remainder_quadrature(kind, pts, pts, nu_eff, base)
        # layout (cell = i * _N_CELLS + j, f * (_DEG + 1) + l, k): contiguous rows for
        # value_f = sum_l T_l(y) sum_k c[cell, f, l, k] T_k(x)
        c = np.empty((_N_CELLS, _N_CELLS, 3, _DEG + 1, _DEG + 1))
        for f, v in enumerate(vals):
            v = v.reshape(_N_CELLS, _DEG + 1, _N_CELLS, _DEG + 1)
            c[:, :, f] = np.einsum("ka,iajb,lb->ijlk", inv, v, inv, optimize=True)
        coef[kind] = c.reshape(_N_CELLS * _N_CELLS, 3 * (_DEG + 1), _DEG + 1)
    n = _SERIES_TERMS
    mom = _moments(nu_eff, base, 4 * n + 4)
    series = {}
    for kind, specs in _SPECS.items():
        rows = []
        for _, rname, power, sign, order, rfun, tpow in specs:
            cs, ps = _bessel_series(order, n)
            cr, pr = _rho_series(rfun, n)
            idx = ps[:, None] + pr[None, :] + tpow
            rows.append((power, sign, cs, ps, cr, pr, mom[rname][idx]))
        series[kind] = rows
    return LayerTable(nu=nu, base=base, coef=coef, series=series)


def layer_table(nu: float, base: str | Substrate) -> LayerTable:
    """The (cached) interpolation table for Poisson's ratio ``nu`` and ``base``.

    Parameters
    ----------
    nu : float
        Poisson's ratio, -1 < nu <= 0.5.
    base : {"smooth", "bonded"} or Substrate

    Returns
    -------
    LayerTable
        Built once per process and key (``functools.lru_cache``, 8 entries);
        the smooth base shares one table for all ``nu``.
    """
    nu = check_nu(nu)
    base = check_base(base)
    return _build_table(None if base == "smooth" else nu, base)


def _series_factors(rows: list, rho: Arr, sigma: Arr):
    """Per function: (prefactor on sigma, A = sigma part @ moments, rho part) of the series.

    The function is ``pref[j] * sum_l A[j, l] R[i, l]`` at (rho_i, sigma_j).
    """
    n = _SERIES_TERMS
    s2 = np.cumprod(np.broadcast_to((sigma * sigma)[:, None], (sigma.size, n - 1)), axis=1)
    r2 = np.cumprod(np.broadcast_to((rho * rho)[:, None], (rho.size, n - 1)), axis=1)
    even_s = np.hstack([np.ones((sigma.size, 1)), s2])  # sigma^(2m)
    even_r = np.hstack([np.ones((rho.size, 1)), r2])  # rho^(2l)
    for power, sign, cs, ps, cr, pr, mmat in rows:
        sv = even_s * (sigma[:, None] ** int(ps[0])) * cs  # sigma^(2m + order) c_m
        rv = even_r * cr if pr[0] == 0 else even_r * (rho[:, None] * cr)
        yield 2.0 * sign * sigma**power, sv @ mmat, rv


def _series_eval(rows: list, rho: Arr, sigma: Arr) -> list[Arr]:
    """The three functions of one kind by their double power series (small rho, sigma)."""
    return np.array([pref * np.einsum("nl,nl->n", a, rv)
                     for pref, a, rv in _series_factors(rows, rho, sigma)])


def _series_grid(rows: list, rho: Arr, sigma: Arr) -> Arr:
    """(3, rho.size, sigma.size): the series on the tensor grid rho x sigma."""
    return np.array([(rv @ a.T) * pref for pref, a, rv in _series_factors(rows, rho, sigma)])


def _chebyshev_basis(z: Arr) -> Arr:
    """(_DEG + 1, n) Chebyshev polynomials T_0..T_deg at z in [-1, 1] (contiguous rows)."""
    tz = np.empty((_DEG + 1, z.size))
    tz[0] = 1.0
    tz[1] = z
    for d in range(2, _DEG + 1):
        np.multiply(z, tz[d - 1], out=tz[d])
        tz[d] *= 2.0
        tz[d] -= tz[d - 2]
    return tz


# tested: tests/test_layer_accuracy.py (u near the axis, 3e-9 of the quadrature down to rho = 1e-8)
_PARITY_MAX = 0.05  # rho below which u takes the odd part of its interpolant in rho ...
# tested: tests/test_layer_accuracy.py (u near the axis, 3e-9 of the quadrature down to rho = 1e-8)
_PARITY_FULL = 0.03  # ... wholly below this, blended (C^2) between
_EVEN_MAX, _EVEN_FULL = 0.005, 0.003  # the same for the even part of w and du/dr: the
# interpolant's even part extrapolates the cell to rho < 0, whose error grows like rho^2
# (w: 1e-15, 1.4e-13, 2.3e-12 at rho = 1e-3, 1e-2, 4e-2, against ~1e-11 rho for its odd
# part; du/dr about 5 times both; bonded, nu = 0.3, sigma = 0.3 ... 1)


def _blend(z: Arr, full: float, width: float) -> Arr:
    """1 below ``full``, 0 from ``full + width``, quintic (C^2) between."""
    x = np.clip((np.asarray(z, dtype=float) - full) / width, 0.0, 1.0)
    return 1.0 - x * x * x * (10.0 - 15.0 * x + 6.0 * x * x)


def _parity_weight(rho: Arr) -> Arr:
    """(3, n): the share of the parity part in w, u, du/dr (:func:`_parity_bases`)."""
    even = _blend(rho, _EVEN_FULL, _EVEN_MAX - _EVEN_FULL)
    return np.stack([even, _blend(rho, _PARITY_FULL, _PARITY_MAX - _PARITY_FULL), even])


def _parity_bases(rho: Arr) -> tuple[Arr, Arr, Arr]:
    """(_DEG + 1, n) each: the parts of T_k(4 rho - 1) of the parity of w, u, du/dr in rho
    (w and du/dr are even, J0 and J1' transforms; u is odd, J1).

    T_k(-1 + d) = sum_m M[k, m] d^m with d = 4 rho (:func:`_axis_powers`): the even
    powers for w and du/dr, the odd ones for u (rho in the first cell). The interpolant's
    part of the other parity is its error: near the axis, where u ~ rho, the even part
    of u (~1e-12 at rho = 0) would be a relative error of 1e-12/rho in the stick zone's
    rows; the odd part of w (~1e-11 rho) is a cone in w that, at c/a = 1e-6 on a layer of
    a/h = 1, is 1e-4 of the gap c^2 between the slip-zone rows next to c and moved k by
    2.3e-5 at n = 512 (``docs/theory.md``, near the axis).
    """
    d = 4.0 * rho
    powers = d[None, :] ** np.arange(_DEG + 1)[:, None]  # (m, n)
    full = _ALL_POWERS
    even = full[:, 0::2] @ powers[0::2]
    return even, full[:, 1::2] @ powers[1::2], even


def _near_axis(coef: NDArray[np.float64], rho: Arr, cell_j: NDArray[np.intp],
               ty: Arr) -> Arr:
    """(3, n) w, u, du/dr at scattered points from their parity parts (rho_n in the first
    rho cell, sigma cell cell_j[n], T(y) ty)."""
    nl = _DEG + 1
    return np.stack([np.einsum("nlk,kn,ln->n", coef[cell_j, f * nl:(f + 1) * nl, :], base, ty,
                               optimize=True)
                     for f, base in enumerate(_parity_bases(rho))])


def _chebyshev_eval(coef: NDArray[np.float64], rho: Arr, sigma: Arr) -> Arr:
    """(3, n) values of the tabulated functions at (rho, sigma) in the table range.

    Points are sorted by cell (radix sort) and each cell's points are evaluated
    with one small matrix product (no copies of coefficients) when there are
    many points a cell; otherwise each point gathers its cell's coefficients.
    """
    u = rho * (1.0 / _CELL)
    v = sigma * (1.0 / _CELL)
    i = np.minimum(u.astype(np.intp), _N_CELLS - 1)
    j = np.minimum(v.astype(np.intp), _N_CELLS - 1)
    u -= i
    v -= j
    cell = i * _N_CELLS + j
    n = rho.size
    counts = np.bincount(cell, minlength=_N_CELLS * _N_CELLS)
    occupied = np.flatnonzero(counts)
    if occupied.size * _GROUP_MIN > n:  # few points a cell: gather
        tx = _chebyshev_basis(2.0 * u - 1.0)
        ty = _chebyshev_basis(2.0 * v - 1.0)
        c = coef[cell].reshape(n, 3, _DEG + 1, _DEG + 1)  # (n, f, l, k)
        cx = np.einsum("nflk,kn->nfl", c, tx)
        return np.einsum("nfl,ln->fn", cx, ty)
    order = np.argsort(cell.astype(np.int16), kind="stable")  # radix sort (cells < 2^15)
    tx = _chebyshev_basis(2.0 * u[order] - 1.0)
    ty = _chebyshev_basis(2.0 * v[order] - 1.0)
    ends = np.cumsum(counts[occupied])
    starts = ends - counts[occupied]
    res = np.empty((3, n))
    for c_id, a, b in zip(occupied.tolist(), starts.tolist(), ends.tolist()):
        part = (coef[c_id] @ tx[:, a:b]).reshape(3, _DEG + 1, b - a)  # (f, l, m)
        part *= ty[None, :, a:b]
        np.sum(part, axis=1, out=res[:, a:b])
    out = np.empty((3, n))
    out[:, order] = res
    return out


def _series_weight(z: Arr) -> Arr:
    """The series' share b(z): 1 below _SERIES_MAX - _BLEND, 0 from _SERIES_MAX, C^2 between.

    A point takes b(rho) b(sigma) of the series and the rest of the table: a product, so
    that the grid and integrated evaluations keep their tensor structure, and no jump (the
    table's ~1e-12 error against the series at the switch was one: the default method's
    finest elements next to a stick edge there turned it into k errors of ~1e-5).
    """
    return _blend(z, _SERIES_MAX - _BLEND, _BLEND)


def _remainders(kind: str, rho: Arr, sigma: Arr, tab: LayerTable) -> Arr:
    """(3, n) remainder functions of ``kind`` at 1-d (rho, sigma), chunk by chunk."""
    out = np.empty((3, rho.size))
    for a in range(0, rho.size, _CHUNK):
        sl = slice(a, a + _CHUNK)
        r, g = rho[sl], sigma[sl]
        m = np.maximum(r, g)
        if np.all(m < _SERIES_MAX - _BLEND):
            out[:, sl] = _series_eval(tab.series[kind], r, g)
            continue
        val = _chebyshev_eval(tab.coef[kind], r, g)
        near = np.flatnonzero(r < _PARITY_MAX)
        if near.size:  # each function: the part of the interpolant of its parity in rho
            j, y = _cells(g[near])
            par = _near_axis(tab.coef[kind], r[near], j, _chebyshev_basis(y))
            share = _parity_weight(r[near])  # (1 - b) v + b p: exactly p where b = 1
            val[:, near] = (1.0 - share) * val[:, near] + share * par
        small = m < _SERIES_MAX
        if small.any():
            b = _series_weight(r[small]) * _series_weight(g[small])
            ser = _series_eval(tab.series[kind], r[small], g[small])
            val[:, small] += b * (ser - val[:, small])
        out[:, sl] = val
    return out


def _cells(z: Arr) -> tuple[NDArray[np.intp], Arr]:
    """Table cell of each coordinate and the local coordinate in [-1, 1]."""
    u = z * (1.0 / _CELL)
    i = np.minimum(u.astype(np.intp), _N_CELLS - 1)
    return i, 2.0 * (u - i) - 1.0


def _groups(cell: NDArray[np.intp]) -> list[tuple[int, slice | NDArray[np.intp]]]:
    """Each cell with its points: a slice where they are contiguous (sorted input), else indices."""
    out: list[tuple[int, slice | NDArray[np.intp]]] = []
    for c in np.unique(cell).tolist():
        idx = np.flatnonzero(cell == c)
        contiguous = idx[-1] - idx[0] + 1 == idx.size
        out.append((c, slice(int(idx[0]), int(idx[-1]) + 1) if contiguous else idx))
    return out


def _remainders_grid(kind: str, rho: Arr, sigma: Arr, tab: LayerTable) -> Arr:
    """(3, rho.size, sigma.size) remainder functions on the tensor grid rho x sigma.

    The tensor Chebyshev sum factorizes on a grid: for the points of one rho
    cell and one sigma cell, ``T(x)^T C^T T(y)``, two small matrix products
    (~10 multiply-adds a point and function instead of ~100 at scattered
    points). Where ``max(rho, sigma) < _SERIES_MAX`` (a rectangle of the grid)
    the power series is summed instead, as at scattered points.
    """
    out = np.empty((3, rho.size, sigma.size))
    ci, x = _cells(rho)
    cj, y = _cells(sigma)
    tx = _chebyshev_basis(x)  # (k, i)
    ty = _chebyshev_basis(y)  # (l, j)
    coef = tab.coef[kind]
    col_groups = _groups(cj)
    for a, rows in _groups(ci):
        txa = np.ascontiguousarray(tx[:, rows].T)  # (i, k)
        for b, cols in col_groups:
            left = (txa @ coef[a * _N_CELLS + b].T).reshape(-1, _DEG + 1)  # (i f, l)
            block = (left @ ty[:, cols]).reshape(txa.shape[0], 3, -1).transpose(1, 0, 2)
            if isinstance(rows, slice) and isinstance(cols, slice):
                out[:, rows, cols] = block
            else:
                out[:, np.arange(rho.size)[rows][:, None], np.arange(sigma.size)[cols]] = block
    near = np.flatnonzero(rho < _PARITY_MAX)
    if near.size:  # each function: the part of the interpolant of its parity in rho
        bases = [base.T for base in _parity_bases(rho[near])]  # (i, k) each
        share = _parity_weight(rho[near])[:, :, None]
        nl = _DEG + 1
        for b, cols in col_groups:
            for f, base in enumerate(bases):
                cf = coef[b, f * nl:(f + 1) * nl, :]  # (l, k): rows of f of cell (0, b)
                idx = (f, near[:, None], np.arange(sigma.size)[cols])
                out[idx] = ((1.0 - share[f]) * out[idx]
                            + share[f] * ((base @ cf.T) @ ty[:, cols]))
    small_r = np.flatnonzero(rho < _SERIES_MAX)
    small_s = np.flatnonzero(sigma < _SERIES_MAX)
    if small_r.size and small_s.size:
        idx = (slice(None), small_r[:, None], small_s[None, :])
        b = _series_weight(rho[small_r])[:, None] * _series_weight(sigma[small_s])[None, :]
        ser = _series_grid(tab.series[kind], rho[small_r], sigma[small_s])
        out[idx] += b * (ser - out[idx])
    return out


def _segments(owner: NDArray[np.intp]) -> tuple[NDArray[np.intp], NDArray[np.intp]]:
    """Starts of the runs of equal ``owner`` (non-decreasing) and their owners."""
    starts = np.flatnonzero(np.r_[True, owner[1:] != owner[:-1]])
    return starts, owner[starts]


def _remainders_integrated(kind: str, rho: Arr, sigma: Arr, weights: Arr,
                           owner: NDArray[np.intp], n_out: int, tab: LayerTable) -> Arr:
    """(3, rho.size, n_out): sum over q of weights[q] R(rho_i, sigma_q) into column owner[q].

    ``sigma`` must be non-decreasing (and ``owner`` with it), so that every
    table cell and the series' range are runs of q. The weights are
    contracted with the Chebyshev polynomials in sigma first, so the cost is
    ~10 (rho.size) (n_out) a function and cell instead of rho.size sigma.size.
    """
    ci, x = _cells(rho)
    cj, y = _cells(sigma)
    tx = _chebyshev_basis(x)  # (k, i)
    tyw = _chebyshev_basis(y) * weights  # (l, q), weighted
    coef = tab.coef[kind]
    small_r = rho < _SERIES_MAX
    n_small = int(np.searchsorted(sigma, _SERIES_MAX))  # sigma[:n_small] < _SERIES_MAX
    b_r = _series_weight(rho)  # the series' share b(rho) b(sigma) (_series_weight)
    wb = weights[:n_small] * _series_weight(sigma[:n_small])
    tywb = tyw[:, :n_small] * _series_weight(sigma[:n_small])
    used = np.unique(cj)
    nl = _DEG + 1
    # left[u] (f i, l): the coefficients of cell (cell of rho_i, used[u]) summed against
    # T(x_i); one matrix product a rho cell (all sigma cells at once)
    left = np.empty((used.size, 3, rho.size, nl))
    span = slice(int(used[0]), int(used[-1]) + 1) \
        if used[-1] - used[0] + 1 == used.size else used  # a view where the cells are a run
    for a, rows in _groups(ci):
        prod = coef[a * _N_CELLS:(a + 1) * _N_CELLS][span].reshape(-1, nl) @ tx[:, rows]
        left[:, :, rows, :] = prod.reshape(used.size, 3, nl, -1).transpose(0, 1, 3, 2)
    near = np.flatnonzero(rho < _PARITY_MAX)
    if near.size:  # each function: the part of the interpolant of its parity in rho
        share = _parity_weight(rho[near])[:, None, :, None]
        for f, base in enumerate(_parity_bases(rho[near])):
            cf = coef[used, f * nl:(f + 1) * nl, :]  # (u, l, k): rows of f of cells (0, used)
            par = np.matmul(cf, base).transpose(0, 2, 1)  # (u, i, l)
            left[:, f, near, :] = (1.0 - share[f]) * left[:, f, near, :] + share[f] * par
    left = left.reshape(used.size, 3 * rho.size, nl)
    # runs of q in one sigma cell, of one owner, on one side of n_small; their sums of T(y) w
    cut = np.r_[True, (cj[1:] != cj[:-1]) | (owner[1:] != owner[:-1])]
    if 0 < n_small < sigma.size:
        cut[n_small] = True
    starts = np.flatnonzero(cut)
    ib = np.add.reduceat(tyw, starts, axis=1)  # (l, runs)
    k_small = int(np.searchsorted(starts, n_small))  # runs [0, k_small): sigma < _SERIES_MAX
    if k_small:  # the table's share 1 - b(rho) b(sigma) there: b(rho) b(sigma) T subtracted
        ibb = np.add.reduceat(tywb, starts[:k_small], axis=1)
        b_fi = np.tile(b_r, 3)[:, None]
    run_cell = np.searchsorted(used, cj[starts])
    per_run = np.empty((3 * rho.size, starts.size))  # (f i, run)
    bounds = np.flatnonzero(np.r_[True, run_cell[1:] != run_cell[:-1], True])
    for r0, r1 in zip(bounds[:-1].tolist(), bounds[1:].tolist()):
        lf = left[run_cell[r0]]  # (f i, l)
        per_run[:, r0:r1] = lf @ ib[:, r0:r1]
        if r0 < k_small:
            r2 = min(r1, k_small)
            per_run[:, r0:r2] -= (lf @ ibb[:, r0:r2]) * b_fi
    # each owner's runs into its column: the first run of each, then the rest (an element
    # across a cell edge)
    per_run = per_run.reshape(3, rho.size, starts.size)
    run_owner = owner[starts]
    first = np.r_[True, run_owner[1:] != run_owner[:-1]]
    rest = np.flatnonzero(~first)
    owners = run_owner[first]
    if owners.size == n_out and owners[-1] == n_out - 1:  # every owner 0 ... n_out - 1
        out = per_run if rest.size == 0 else per_run[:, :, np.flatnonzero(first)]
    else:
        out = np.zeros((3, rho.size, n_out))
        out[:, :, owners] = per_run[:, :, first]
    if rest.size:
        extra = run_owner[rest]
        if np.all(np.diff(extra) > 0):  # no owner twice among them
            out[:, :, extra] += per_run[:, :, rest]
        else:
            np.add.at(out, (slice(None), slice(None), extra), per_run[:, :, rest])
    rs = np.flatnonzero(small_r)
    if rs.size and n_small:
        starts, cols = _segments(owner[:n_small])
        for f, (pref, amat, rv) in enumerate(_series_factors(tab.series[kind], rho[rs],
                                                             sigma[:n_small])):
            bmat = np.add.reduceat(amat * (pref * wb)[:, None], starts, axis=0)
            out[f, rs[:, None], cols[None, :]] += (rv * b_r[rs, None]) @ bmat.T
    return out


AXIS_RHO_MAX = _SERIES_MAX - _BLEND  # r/h below which remainder_axis_w applies (series share 1)


def _axis_powers() -> Arr:
    """(k, m): T_k(-1 + d) = sum_m [k, m] d^m, m = 0 ... _DEG.

    T_k(1 - d) = k sum_m (-2)^m (k + m - 1)! / ((k - m)! (2m)!) d^m (k >= 1), and
    T_k(-1 + d) = (-1)^k T_k(1 - d).
    """
    out = np.zeros((_DEG + 1, _DEG + 1))
    out[0, 0] = 1.0
    for k in range(1, _DEG + 1):
        for m in range(k + 1):
            out[k, m] = (-1.0) ** k * k * (-2.0) ** m * factorial(k + m - 1) / (
                factorial(k - m) * factorial(2 * m))
    return out


_AXIS_POWERS = _axis_powers()[:, 2::2]  # the even powers from d^2 (differences from the axis)
_ALL_POWERS = _axis_powers()  # (k, m), every power (the parity parts near the axis)


def remainder_axis_w(kind: str, r: ArrayLike, s: ArrayLike, nu: float, h: float,
                     base: str | Substrate) -> Arr:
    """w(r; s) - w(0; s) of the layer's smooth remainder, without cancellation.

    Parameters
    ----------
    kind : {"pressure", "shear"}
        The basic load (unit pressure, or shear q = r, on the disc of radius s).
    r, s : array_like
        Surface points and disc radii (broadcast; ``s <= 0`` gives 0), with
        ``r/h <= AXIS_RHO_MAX`` (0.2) and ``max(r, s)/h <= RATIO_MAX``.
    nu, h, base :
        As :func:`pressure_disc` (``h`` finite).

    Returns
    -------
    ndarray
        The difference (units of w), O(r^2) near the axis, with the relative
        accuracy of the remainder's second derivative: the table's Chebyshev
        sum in rho is differenced term by term as polynomials in d = 4 rho,
        keeping the even powers (the function is even in rho; the odd powers
        are interpolation error, ~2e-11 rho, which would swamp r^2 near the
        axis), and the power series drops its rho^0 term; nothing is
        subtracted.
        Added to the half-space's :func:`contactlib.kernels.disc.axis_w_disc`
        it gives the layer's axis-referenced rows of the default method.
    """
    if kind not in _SPECS:
        raise ValueError(f"kind must be 'pressure' or 'shear', got {kind!r}")
    nu, h, base = _check_layer(nu, h, base)
    rb, sb = np.broadcast_arrays(np.abs(np.asarray(r, dtype=float)),
                                 np.asarray(s, dtype=float))
    shape = rb.shape
    rho, sigma, pos = _scaled_rho_sigma(rb.ravel(), sb.ravel(), h)
    if rho.size and rho.max() > AXIS_RHO_MAX:
        raise ValueError(f"remainder_axis_w needs r/h <= {AXIS_RHO_MAX}, got {rho.max():.3g}")
    tab = layer_table(nu, base)
    nl = _DEG + 1
    # table: cell (0, j); w's coefficients c[l, k] of T_k(4 rho - 1) T_l(y), each T_k as a
    # polynomial in d = 4 rho with its even powers only (the remainder is even in rho; the
    # odd ones are the interpolant's error, which would dominate as rho -> 0)
    j, y = _cells(sigma)
    d = 4.0 * rho
    dk = _AXIS_POWERS @ (d[None, :] ** np.arange(2, nl, 2)[:, None])  # (k, n)
    coef = tab.coef[kind][j, :nl, :]  # (n, l, k): the w rows of cell (0, j)
    table = np.einsum("nlk,kn,ln->n", coef, dk, _chebyshev_basis(y), optimize=True)
    out = table
    small = sigma < _SERIES_MAX
    if small.any():  # the series' share b(sigma) (b(rho) = 1 here), its rho^0 term dropped
        pref, amat, rv = next(_series_factors(tab.series[kind], rho[small], sigma[small]))
        series = pref * np.einsum("nl,nl->n", amat[:, 1:], rv[:, 1:])
        b = _series_weight(sigma[small])
        out[small] += b * (series - out[small])
    out = np.where(pos, out, 0.0) * _scales(kind, h)[0]
    return out.reshape(shape)


def _grid_axes(r: Arr, s: Arr) -> bool:
    """True when (r, s) broadcast as an outer product: r of shape (m, 1), s of (1, n)."""
    return r.ndim == 2 and s.ndim == 2 and r.shape[1] == 1 and s.shape[0] == 1 \
        and r.shape[0] * s.shape[1] >= _GRID_MIN


def _check_layer(nu: float, h: float, base: str) -> tuple[float, float, str]:
    nu = check_nu(nu)
    base = check_base(base)
    h = float(h)
    if not h > 0.0:  # also rejects NaN
        raise ValueError(f"layer thickness h={h!r} must be > 0 (np.inf: half-space)")
    return nu, h, base


def _scaled_rho_sigma(rb: Arr, sb: Arr, h: float,
                      limit: float = RATIO_MAX) -> tuple[Arr, Arr, NDArray[np.bool_]]:
    """r/h, s/h (0 where s <= 0) and the mask s > 0; refuses beyond ``limit``."""
    pos = sb > 0.0
    rho = np.abs(rb) * (1.0 / h)
    sigma = np.where(pos, sb, 0.0) * (1.0 / h)
    big = max(float(rho.max(initial=0.0)), float(sigma.max(initial=0.0)))
    if not big <= limit:
        raise ValueError(
            f"max(r, s)/h = {big:.6g} is beyond the supported range of the layer "
            f"kernels (<= {limit:g}: a/h <= {limit:g} for r, s <= a)")
    return rho, sigma, pos


def _thin(base: str | Substrate, rb: Arr, sb: Arr, h: float) -> bool:
    """True where the transform-domain sums replace the tables (beyond RATIO_MAX = 20)."""
    big = max(float(np.max(np.abs(rb), initial=0.0)), float(np.max(sb, initial=0.0)))
    return big > RATIO_MAX * h


def _scales(kind: str, h: float) -> Arr:
    """Factors of (w, u, du) on the remainder functions: h, h, 1 or h^2, h^2, h."""
    scale = h if kind == "pressure" else h * h
    return np.array([scale, scale, scale / h])


def remainder_grid(kind: str, r: ArrayLike, s: ArrayLike, nu: float, h: float,
                   base: str | Substrate, weights: ArrayLike | None = None,
                   owner: ArrayLike | None = None) -> Arr:
    """The layer's smooth remainder (layer minus half-space) on the tensor grid r x s.

    Parameters
    ----------
    kind : {"pressure", "shear"}
        The basic load: unit pressure or shear q = r on the disc of radius s.
    r, s : array_like, 1-d
        Surface radii and disc radii (``s <= 0`` gives zeros), length unit
        of the problem; ``max(r, s)/h <= RATIO_MAX``.
    nu, h, base :
        As :func:`pressure_disc` (``h`` finite).

    weights, owner : array_like, optional
        Quadrature weights of the points ``s`` (non-decreasing) and the
        index of the integral each belongs to (non-decreasing): then the
        weighted sums ``sum_{q: owner[q] = j} weights[q] R(r_i, s_q)`` are
        returned instead of the values, without forming the grid.

    Returns
    -------
    ndarray, shape (3, r.size, s.size) or (3, r.size, owner.max() + 1)
        What the layer adds to the half-space kernels of ``disc`` at (r_i,
        s_j): (w, u, du/dr), or its weighted sums. Analytic in (r, s) (the
        singular parts are all in the half-space kernels), so a plain Gauss
        rule on elements of up to ~h integrates it; evaluated with the
        factorized Chebyshev sum (:func:`_remainders_grid`,
        :func:`_remainders_integrated`), ~10 multiply-adds a point and
        function.
    """
    if kind not in _SPECS:
        raise ValueError(f"kind must be 'pressure' or 'shear', got {kind!r}")
    nu, h, base = _check_layer(nu, h, base)
    if not np.isfinite(h):
        raise ValueError("remainder_grid needs a finite layer thickness h")
    rb, sb = np.asarray(r, dtype=float).reshape(-1), np.asarray(s, dtype=float).reshape(-1)
    if rb.size == 0 or sb.size == 0:  # (a probe: no table is built for it)
        cols = sb.size if weights is None else int(np.max(owner, initial=-1)) + 1
        return np.zeros((3, rb.size, cols))
    if _thin(base, rb, sb, h):
        rho, sigma, pos = _scaled_rho_sigma(rb, sb, h, THIN_RATIO_MAX)
        wts = None if weights is None else np.where(
            pos, np.asarray(weights, dtype=float).reshape(-1), 0.0)
        rem = thin_layer.remainders(kind, rho, sigma, nu, base, wts, owner)
        rem *= _scales(kind, h)[:, None, None]
        return rem
    rho, sigma, pos = _scaled_rho_sigma(rb, sb, h)
    tab = layer_table(nu, base)
    if weights is None:
        rem = _remainders_grid(kind, rho, sigma, tab)
        rem[:, :, ~pos] = 0.0
    else:
        own = np.asarray(owner, dtype=np.intp).reshape(-1)
        if not (np.all(np.diff(sigma) >= 0) and np.all(np.diff(own) >= 0)):
            raise ValueError("remainder_grid: s and owner must be non-decreasing with weights")
        wts = np.where(pos, np.asarray(weights, dtype=float).reshape(-1), 0.0)
        rem = _remainders_integrated(kind, rho, sigma, wts, own,
                                     int(own.max(initial=-1)) + 1, tab)
    rem *= _scales(kind, h)[:, None, None]
    return rem


def _layer(kind: str, r: ArrayLike, s: ArrayLike, nu: float, h: float, base: str,
           with_w: bool, with_du: bool) -> tuple[Arr, Arr, Arr]:
    nu, h, base = _check_layer(nu, h, base)
    r = np.asarray(r, dtype=float)
    s = np.asarray(s, dtype=float)
    if kind == "pressure":
        w, u, du = disc.pressure_disc(r, s, nu, with_w=with_w)
    else:
        w, u, du = disc.shear_disc(r, s, nu, with_du=with_du)
    if not np.isfinite(h):
        return w, u, du
    shape = w.shape
    if _grid_axes(r, s):  # the step operators' grid of points x edges
        rem = remainder_grid(kind, r[:, 0], s[0], nu, h, base).reshape(3, -1)
    elif _thin(base, r, s, h):  # on the grid of the distinct r and s, then picked
        ru, ri = np.unique(np.abs(np.broadcast_to(r, shape)).ravel(), return_inverse=True)
        su, si = np.unique(np.broadcast_to(s, shape).ravel(), return_inverse=True)
        rem = remainder_grid(kind, ru, su, nu, h, base)[:, ri.ravel(), si.ravel()]
    else:
        rho, sigma, pos = _scaled_rho_sigma(np.broadcast_to(r, shape).ravel(),
                                            np.broadcast_to(s, shape).ravel(), h)
        rem = _remainders(kind, rho, sigma, layer_table(nu, base))
        rem[:, ~pos] = 0.0
        rem *= _scales(kind, h)[:, None]
    w = w + rem[0].reshape(shape) if with_w else w
    u = u + rem[1].reshape(shape)
    if with_du:
        du = du + rem[2].reshape(shape)
    return w, u, du


def pressure_disc(r: ArrayLike, s: ArrayLike, nu: float, h: float = np.inf,
                  base: str | Substrate = "smooth", *,
                  with_w: bool = True) -> tuple[Arr, Arr, Arr]:
    """Surface displacements of a layer under a uniform unit pressure on a disc.

    Parameters
    ----------
    r : array_like
        Radius of the surface point (>= 0), in the length unit of the problem.
    s : array_like
        Disc radius (>= 0); broadcast against ``r``. ``s = 0`` gives zeros.
    nu : float
        Poisson's ratio, -1 < nu <= 0.5.
    h : float, optional
        Layer thickness, same unit; ``np.inf`` (default) is the half-space
        (:func:`contactlib.kernels.disc.pressure_disc`).
    base : {"smooth", "bonded"} or Substrate, optional
        Rigid base, frictionless (default) or bonded, or an elastic
        substrate bonded to the layer (:class:`Substrate`; then E* is the
        layer's).
    with_w : bool, optional
        False: w returned as zeros (as in ``disc``).

    Returns
    -------
    w, u, dudr : ndarray
        Normal displacement (into the body, absolute: -> 0 far away), radial
        displacement (outward) and ``du/dr``, for p = 1 and E* = 1 (scale with
        p/E*; ``w`` and ``u`` also with the length unit).

    Raises
    ------
    ValueError
        If ``max(r, s)/h > THIN_RATIO_MAX`` (1200, any base), an
        unknown base, ``h <= 0`` or
        ``nu`` out of range.

    Examples
    --------
    >>> w, u, du = pressure_disc(0.0, 1.0, 0.3, h=1e8)   # thick: the half-space, w = 2 s
    >>> abs(float(w) - 2.0) < 1e-7
    True
    """
    return _layer("pressure", r, s, nu, h, base, with_w, True)


def shear_disc(r: ArrayLike, s: ArrayLike, nu: float, h: float = np.inf,
               base: str | Substrate = "smooth", *,
               with_du: bool = True) -> tuple[Arr, Arr, Arr]:
    """Surface displacements of a layer under a linear radial shear q = r on a disc.

    Parameters
    ----------
    r : array_like
        Radius of the surface point (>= 0).
    s : array_like
        Disc radius (>= 0); ``s = 0`` gives zeros.
    nu : float
        Poisson's ratio, -1 < nu <= 0.5.
    h : float, optional
        Layer thickness; ``np.inf`` (default) is the half-space.
    base : {"smooth", "bonded"} or Substrate, optional
    with_du : bool, optional
        False: du/dr returned as NaN (as in ``disc``).

    Returns
    -------
    w, u, dudr : ndarray
        For q(r) = r (outward) on r < s and E* = 1: ``w`` and ``u`` scale with
        q0 s^2 / E*, ``du/dr`` with q0 s / E*. ``du/dr`` is ``-inf`` at
        ``r = s`` (integrable logarithmic singularity of the half-space part).

    Raises
    ------
    ValueError
        As :func:`pressure_disc`.

    Examples
    --------
    >>> w, u, du = shear_disc(0.5, 1.0, 0.3, h=1.0, base="bonded")
    >>> bool(u > 0)
    True
    """
    return _layer("shear", r, s, nu, h, base, True, with_du)
