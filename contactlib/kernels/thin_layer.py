r"""Ring remainders of a thin layer or coating (a/h up to 1000) by transform-domain quadrature.

The layer kernels of :mod:`contactlib.kernels.layer` are the half-space's plus
smooth remainders, functions of ``rho = r/h`` and ``sigma = s/h`` such as::

    Pw(rho, sigma) = 2 sigma int_0^inf Rww(t) J1(sigma t) J0(rho t) dt / t

(all six in the notes of :mod:`contactlib.kernels.layer`). Its Chebyshev tables
cover ``rho, sigma <= 20`` (beyond, a table would need ~190 MB). Here the
integrals are summed directly, as the matrix product ``(J(rho_i t_q) w_q R(t_q))
(J(sigma_j t_q))^T`` over Gauss nodes ``t_q``, in chunks of ``t``:

* ``R(t)`` (:func:`contactlib.kernels.layer.remainder_transfer`) decays like
  ``t^2 exp(-2t)``: the integrals stop at ``t = 18`` (``R < 1e-13``);
* the Bessel product oscillates with frequency up to ``rho + sigma``: composite
  20-point Gauss-Legendre panels of width ``min(0.8, PANEL_SPAN/(rho + sigma))``
  (``PANEL_SPAN = 30``: ~5 periods a panel; 40 loses 7e-10 of the scale), or
  where they need fewer nodes (mostly from ``rho + sigma = 42`` on) 64-point panels five
  times as wide (4.2 nodes a period become 2.7; six times as wide loses 5e-12),
  so the number of nodes grows like ``max(rho + sigma)`` (15,360 at a/h = 1000,
  24,000 with 20-point panels);
* the pressure's and the shear's element sums in one pass where the caller asks
  for both (:func:`both_kinds`: shared Bessel values, transfer functions and
  ``int_0^x J0``), the second kept for its call;
* memory: each chunk of nodes holds up to ``12 (n_s + n_r)`` values a node,
  kept under :data:`MEMORY_BYTES` (48 MB) whatever the size;
* element sums (``weights``, ``owner``: the operators' Gauss rules over the disc
  radius, 8 points on panels of h/2, ~17,000 points at a/h = 1000): a rule that
  spans one interval ``[a, b]``, ``b - a >= WIDE_ELEMENT max(b, 1)`` (in h), is replaced
  by the exact integral ``int_a^b s^p J_p(s t) ds = (G(b t) - G(a t))/t^(p+1)``
  (:func:`disc_integrals`), so the Bessel values are needed at the ~n + 1
  element edges only, and these are the points ``rho`` of a mesh's own nodes
  (their J0, J1 are shared). Equal to the point-by-point sums to 5e-14 of each
  function's scale (tests/test_thin_layer_edges.py); one solve at a/h = 1000,
  n = 256 takes ~10x less (benchmarks/bench_thin_coatings.py).

Accuracy (tests/test_thin_layers.py): the 64-point panels equal to the 20-point
ones at half their width to 2e-13 of each function's scale
(tests/test_thin_layer_panels.py); equal to the tables to 1e-10 of their
scale where both apply, to an independent ``quad`` of a disc's w(0) to 1e-12,
unchanged (< 1e-12) when the panels are halved at
``rho + sigma = 2400``, and the thin-layer limits (Winkler's ``w = p h/M`` of a
bonded layer, ``w = p h`` of a smooth one, in ``E* = 1``) to ~1e-15 inside a wide
disc.

Coated bodies (``base = layer.Substrate``, tests/test_thin_coatings.py): the
remainders of :func:`contactlib.kernels.layer.coated_remainder` tend to ``m -
1`` at ``t = 0`` and fall over ``t ~ m^(-1/3)`` on a soft substrate (``m =
E1*/E2* >> 1``), so the panels are also at most ``2 f/32`` wide on ``0 < t <
2 f``, ``f = min(1, m^(-1/3))`` (:func:`contactlib.kernels.layer.fine_panel`, as
the tables' quadrature). They decay like the rigid bases' (``|R(18)| <= 3e-13``
for E2/E1 in [1e-2, 1e6]). Measured: equal to the coated tables to 6e-12 of
each function's scale where both apply (E2/E1 = 0.01 ... 1e3); ``T_MAX`` 18 ->
24, halved panels and doubled fine panels change the sums by < 2e-13 of scale
at ``rho + sigma = 2400``; zero (< 1e-13) for equal materials.
"""

from __future__ import annotations

import threading
from collections.abc import Iterator
from contextlib import contextmanager
from math import factorial

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import layer_transfer

Arr = NDArray[np.float64]

# tested: tests/test_thin_layers.py and tests/test_thin_coatings.py (the sums against the ring
# tables and the thin limits; the remainders are below 1e-13 beyond)
T_MAX = 18.0
"""Upper end of the t = k h integrals (the remainders are below 1e-13 beyond)."""

# measured: benchmarks/bench_thin_layers.py (cost and accuracy against Winkler's limit);
# tests/test_thin_layers.py checks the sums
PANEL_SPAN = 30.0
"""Panel width times (rho + sigma): ~5 periods of the Bessel product a panel."""

# measured: benchmarks/bench_thin_layers.py (the peak memory of a solve)
MEMORY_BYTES = 48e6
"""Bound on the Bessel values held at once (bytes)."""

# tested: tests/test_thin_layers.py (the sums against the ring tables, with PANEL_SPAN)
_GL_ORDER = 20

# tested: tests/test_thin_layer_panels.py (the sums at rho, sigma <= 60 against 20-point panels
# of at most 0.125 wide, all bases: measured <= 4e-14 of each function's scale; 1.0: 4e-14)
MAX_PANEL = 0.8
"""Widest 20-point panel (in t = k h), where the oscillation allows it (rho + sigma < 38)."""

# tested: tests/test_thin_layer_panels.py (the sums with these panels against the 20-point
# ones of half their width, measured <= 2e-13 of each function's scale; 64 nodes on panels
# of 6 PANEL_SPAN/span lose 5e-12)
HIGH_ORDER = 64
"""Nodes of the wide panels, used where they need fewer nodes (span >= 42)."""

# tested: tests/test_thin_layer_panels.py (with HIGH_ORDER; 6.5 fails it)
HIGH_WIDER = 5.0
"""Width of the HIGH_ORDER panels over the 20-point ones' (PANEL_SPAN/span)."""

# tested: tests/test_thin_layer_edges.py (an element at least this wide relative to its outer
# edge b, in h when b < h, is integrated in closed form: G(b t) - G(a t) loses at most
# ~b/(b - a) x 1e-16 of the element's integral, here 2e-13)
WIDE_ELEMENT = 1e-3
"""Narrowest element (over max(b/h, 1)) whose disc-radius integral is taken in closed form."""

# tested: tests/test_thin_layer_edges.py (disc_integrals against mpmath): power series below
_SERIES_X = 4.0
# tested: tests/test_thin_layer_edges.py (disc_integrals against mpmath): Miller up to, then
# the asymptotic series (its 11th term at x = 60 is ~1e-18 of the first)
_ASYMPTOTIC_X = 60.0
# tested: tests/test_thin_layer_edges.py (disc_integrals against mpmath): start order of
# Miller's recurrence (J_140(60) ~ 1e-25)
_MILLER_START = 140
# tested: tests/test_thin_layer_edges.py (disc_integrals against mpmath): terms of the
# asymptotic series used beyond _ASYMPTOTIC_X
_TAIL_TERMS = 11
# tested: tests/test_thin_layer_edges.py (disc_integrals against mpmath): terms of the series
_SERIES_TERMS = 25

# row: (remainder, power of sigma, sign, Bessel order in sigma, function of rho, power of t)
_SPECS = {
    "pressure": (("ww", 1, 1.0, 1, "J0", -1), ("wu", 1, -1.0, 1, "J1", -1),
                 ("wu", 1, -1.0, 1, "dJ1", 0)),
    "shear": (("wu", 2, -1.0, 2, "J0", -1), ("uu", 2, 1.0, 2, "J1", -1),
              ("uu", 2, 1.0, 2, "dJ1", 0)),
}


def nodes(span: float, fine: float | None = None) -> tuple[Arr, Arr]:
    """Composite Gauss-Legendre nodes and weights on ``0 < t < T_MAX``.

    Parameters
    ----------
    span : float
        ``max(rho) + max(sigma)``, the highest frequency of the integrands.
    fine : float, optional
        A coated body's scale ``f = min(1, m^(-1/3))`` near t = 0
        (:func:`contactlib.kernels.layer.fine_panel`): on ``0 < t < 2 f`` the
        panels are also at most ``2 f/32`` wide (a stiff layer on a soft
        substrate bends over ``t ~ m^(-1/3)``).

    Returns
    -------
    t, weights : ndarray
        On each range (below ``2 f``, above) the rule with fewer nodes (20 on
        a tie) of: 20 nodes on panels of width ``min(MAX_PANEL,
        PANEL_SPAN/span)`` (``MAX_PANEL = 0.8``), or :data:`HIGH_ORDER` (64)
        nodes on panels :data:`HIGH_WIDER` (5) times as wide for the
        oscillation (``min(2.56, 5 PANEL_SPAN/span)``: 36% fewer nodes from
        ``span = 59``); below ``2 f`` also at most ``2 f/32`` wide.
    """
    span = max(float(span), 1.0)
    low = (0.0, layer_transfer.FINE_T * fine if fine is not None else 0.0)  # as the tables
    t, w = [], []
    for lo, hi, fine_step in (low + (low[1] / layer_transfer.FINE_PANELS,),
                              (low[1], T_MAX, np.inf)):
        if hi <= lo:
            continue
        rules = [(order, min(cap, wider * PANEL_SPAN / span, fine_step))
                 for order, cap, wider in ((_GL_ORDER, MAX_PANEL, 1.0),
                                           (HIGH_ORDER, MAX_PANEL * HIGH_ORDER / _GL_ORDER,
                                            HIGH_WIDER))]
        count = [int(np.ceil((hi - lo) / width)) for _, width in rules]
        pick = int(np.argmin([c * r[0] for c, r in zip(count, rules)]))  # (a tie: 20 nodes)
        order, edges = rules[pick][0], np.linspace(lo, hi, count[pick] + 1)
        g, gw = np.polynomial.legendre.leggauss(order)
        a, b = edges[:-1, None], edges[1:, None]
        t.append((0.5 * (b - a) * g + 0.5 * (a + b)).ravel())
        w.append((0.5 * (b - a) * gw).ravel())
    return np.concatenate(t), np.concatenate(w)


def _bessel(name: str, x: Arr, j0: Arr | None = None, j1: Arr | None = None) -> Arr:
    """J0, J1, J2 or J1' = (J0 - J2)/2 of x >= 0 (J2 by recurrence above x = 2)."""
    from scipy import special  # here, not at import (as contactlib.kernels.layer)

    if name == "J0":
        return special.j0(x) if j0 is None else j0
    if name == "J1":
        return special.j1(x) if j1 is None else j1
    j0 = special.j0(x) if j0 is None else j0
    j1 = special.j1(x) if j1 is None else j1
    small = x <= 2.0
    j2 = 2.0 * j1 / np.where(small, 1.0, x) - j0
    j2[small] = special.jv(2, x[small])  # (jv only where the recurrence would cancel)
    return j2 if name == "J2" else 0.5 * (j0 - j2)


def _power_series(order: int) -> Arr:
    """Coefficients c_k of ``int_0^X x^p J_p(x) dx = X^(2p+1) sum_k c_k X^(2k)``, p = order."""
    return np.array([(-1.0) ** k / (factorial(k) * factorial(k + order)
                                    * 2.0 ** (2 * k + order) * (2 * k + 2 * order + 1))
                     for k in range(_SERIES_TERMS)])


def _horner(coef: Arr, z: Arr) -> Arr:
    acc = np.full_like(z, coef[-1])
    for c in coef[-2::-1]:
        acc *= z
        acc += c
    return acc


def _integral_j0(x: Arr) -> Arr:
    """``int_0^x J0`` for ``_SERIES_X <= x <= _ASYMPTOTIC_X``: Miller's backward recurrence.

    ``int_0^x J0 = 2 sum_k J_{2k+1}(x)`` and ``1 = J0 + 2 sum_k J_{2k}(x)``: the
    unnormalized values of the recurrence from order ``_MILLER_START`` (where
    ``J_n(60)`` is ~1e-25 of ``J_0``) give both sums and their ratio.
    """
    inv = 2.0 / x
    after, f = np.zeros_like(x), np.full_like(x, 1e-30)
    even, odd = np.zeros_like(x), np.zeros_like(x)
    for n in range(_MILLER_START, 0, -1):
        (even if n % 2 == 0 else odd).__iadd__(f)
        after, f = f, (n * inv) * f - after
    return 2.0 * odd / (f + 2.0 * even)


def _asymptotic_tails(x: Arr) -> tuple[Arr, Arr]:
    """``e0, e1`` with ``H0 - Y0 = (2/pi) e0`` and ``H1 - Y1 = (2/pi)(1 + e1)`` (Struve), x > 60.

    The asymptotic series (Abramowitz & Stegun 12.1.31): ``e0 = 1/x - 1/x^3 +
    9/x^5 - ...``, ``e1 = 1/x^2 - 3/x^4 + 45/x^6 - ...``.
    """
    z = 1.0 / (x * x)
    return _horner(_TAIL0, z) / x, _horner(_TAIL1, z) * z


def _tail_coefficients() -> tuple[Arr, Arr]:
    c, d = [1.0], [1.0]
    for k in range(_TAIL_TERMS - 1):
        c.append(-c[-1] * (2 * k + 1) ** 2)
        d.append(d[-1] * (2 * k + 3) * (-1 - 2 * k))
    return np.array(c), np.array(d)


_SERIES = {1: _power_series(1), 2: _power_series(2)}
_TAIL0, _TAIL1 = _tail_coefficients()


def disc_integrals(order: int, x: ArrayLike, j0: Arr | None = None,
                   j1: Arr | None = None) -> Arr:
    """``int_0^x y^p J_p(y) dy`` for ``p = order`` (1 or 2), to ~1e-15 of its scale.

    The disc loads' Bessel factors integrated over the disc radius:
    ``int_a^b s^p J_p(s t) ds = (G(b t) - G(a t)) / t^(p + 1)``. Power series
    below ``x = 4``; above, ``G1 = int_0^x J0 - x J0(x)`` and ``G2 = 3 G1 - x^2
    J1(x)``, with ``int_0^x J0`` by Miller's recurrence up to ``x = 60`` and beyond
    as ``1 + x J1 e0 - x J0 e1`` (the Struve functions' asymptotic series, the
    Wronskian ``J1 Y0 - J0 Y1 = 2/(pi x)``). Tested against mpmath
    (tests/test_thin_layer_edges.py).

    Parameters
    ----------
    order : {1, 2}
    x : array_like
        Arguments >= 0 (dimensionless).
    j0, j1 : ndarray, optional
        ``J0(x)`` and ``J1(x)`` when the caller has them.

    Returns
    -------
    ndarray
        The integrals, the shape of ``x``.
    """
    return _disc_pair(np.asarray(x, dtype=float), j0, j1)[order]


def _disc_pair(x: Arr, j0: Arr | None = None, j1: Arr | None = None) -> dict[int, Arr]:
    """:func:`disc_integrals` of order 1 and 2 together (they share ``int_0^x J0``)."""
    from scipy import special

    j0 = special.j0(x) if j0 is None else j0
    j1 = special.j1(x) if j1 is None else j1
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        e0, e1 = _asymptotic_tails(x)  # all, then the smaller x replaced
        g1 = 1.0 + x * (j1 * e0 - j0 * (1.0 + e1))
    xf, g1f = x.reshape(-1), g1.reshape(-1)
    mid = np.flatnonzero((xf >= _SERIES_X) & (xf <= _ASYMPTOTIC_X))
    g1f[mid] = _integral_j0(xf[mid]) - xf[mid] * j0.reshape(-1)[mid]
    out = {1: g1, 2: 3.0 * g1 - x * x * j1}
    small = np.flatnonzero(xf < _SERIES_X)
    xs = xf[small]
    for order, g in out.items():
        g.reshape(-1)[small] = _horner(_SERIES[order], xs * xs) * xs ** (2 * order + 1)
    return out


def remainders(kind: str, rho: ArrayLike, sigma: ArrayLike, nu: float, base: str,
               weights: ArrayLike | None = None, owner: ArrayLike | None = None) -> Arr:
    """The remainder functions of a layer (rigid base or coated), on the grid rho x sigma.

    Inside :func:`both_kinds` (the operators, which ask for both, pressure
    then shear), element sums (``weights`` given) of both kinds are summed in
    one pass over the nodes ``t`` (they share the Bessel values of ``rho t``
    and of the element edges, the transfer functions and ``int_0^x J0``); the
    other kind's sums are kept for the next call with the same arguments and
    handed out once. Each kind's sums equal those of its own pass bit for bit
    (tests/test_thin_layer_panels.py): only the cost depends on the context.

    Parameters
    ----------
    kind : {"pressure", "shear"}
        The disc load of :func:`contactlib.kernels.layer.pressure_disc` or
        :func:`contactlib.kernels.layer.shear_disc`.
    rho, sigma : array_like, 1-d
        ``r/h >= 0`` and ``s/h >= 0``, any size.
    nu : float
        Poisson's ratio, -1 < nu <= 0.5.
    base : {"smooth", "bonded"} or contactlib.kernels.layer.Substrate
        The rigid base, or the elastic substrate of a coated body.
    weights, owner : array_like, optional
        Quadrature weights of the points ``sigma`` and the (non-decreasing)
        index of the integral each belongs to: then the weighted sums over
        each owner are returned (summed in the transform domain, no grid).

    Returns
    -------
    ndarray, shape (3, rho.size, sigma.size) or (3, rho.size, owner.max() + 1)
        ``(Pw, Pu, Pd)`` or ``(Sw, Su, Sd)`` of the notes of
        :mod:`contactlib.kernels.layer` (dimensionless; the caller scales by
        powers of h), or their weighted sums.
    """
    if kind not in _SPECS:
        raise ValueError(f"kind must be 'pressure' or 'shear', got {kind!r}")
    if not isinstance(base, layer_transfer.Substrate) and base not in layer_transfer.BASES:
        raise ValueError(f"base must be 'smooth', 'bonded' or a Substrate, got {base!r}")
    kept = getattr(_KEPT, "sums", None)
    _KEPT.sums = None
    if weights is None or not getattr(_KEPT, "depth", 0):  # (one kind asked for)
        return _sums((kind,), rho, sigma, nu, base, weights, owner)[kind]
    key = _key(rho, sigma, nu, base, weights, owner)
    if kept is not None and kept[0] == kind and _same(kept[1], key):
        return kept[2]
    both = _sums(tuple(_SPECS), rho, sigma, nu, base, weights, owner)
    other = "shear" if kind == "pressure" else "pressure"
    _KEPT.sums = (other, key, both[other])
    return both[kind]


_KEPT = threading.local()  # the other kind's sums of the last call, and both_kinds' depth


@contextmanager
def both_kinds() -> Iterator[None]:
    """Context: the caller asks for both kinds' element sums (:func:`remainders`) in turn.

    Each pressure (shear) call inside then sums the shear (pressure) too, in
    the same pass, and keeps it for the next call; the kept sums are dropped
    on leaving. Values do not depend on it, only the cost.
    """
    _KEPT.depth = getattr(_KEPT, "depth", 0) + 1
    try:
        yield
    finally:
        _KEPT.depth -= 1
        _KEPT.sums = None


def _key(rho: ArrayLike, sigma: ArrayLike, nu: float, base: str | layer_transfer.Substrate,
         weights: ArrayLike | None, owner: ArrayLike | None) -> tuple:
    """A call's arguments and the constants its sums depend on (copied: compared exactly)."""
    arrays = tuple(None if a is None else np.array(a, dtype=float).reshape(-1)
                   for a in (rho, sigma, weights, owner))
    return arrays + (float(nu), base, T_MAX, PANEL_SPAN, WIDE_ELEMENT,
                     layer_transfer.FINE_T, layer_transfer.FINE_PANELS)


def _same(a: tuple, b: tuple) -> bool:
    """Whether two keys of :func:`_key` are equal (arrays element by element)."""
    for x, y in zip(a, b):
        if isinstance(x, np.ndarray) or isinstance(y, np.ndarray):
            if x is None or y is None or x.shape != y.shape or not np.array_equal(x, y):
                return False
        elif x != y:
            return False
    return True


def _sums(kinds: tuple[str, ...], rho: ArrayLike, sigma: ArrayLike, nu: float, base: str,
          weights: ArrayLike | None = None, owner: ArrayLike | None = None) -> dict[str, Arr]:
    """:func:`remainders` of each of ``kinds``, in one pass over the nodes ``t``."""
    rho = np.abs(np.asarray(rho, dtype=float).reshape(-1))
    sigma = np.asarray(sigma, dtype=float).reshape(-1)
    powers = {kind: _SPECS[kind][0][1] for kind in kinds}
    closed = None
    if weights is None:
        starts, rows = None, np.arange(sigma.size)
        m = sigma.size
        wts = np.ones(sigma.size)
    else:
        own = np.asarray(owner, dtype=np.intp).reshape(-1)
        wts = np.asarray(weights, dtype=float).reshape(-1)
        starts = np.flatnonzero(np.r_[True, np.diff(own) != 0]) if own.size else own
        rows, m = own[starts], int(own.max(initial=-1)) + 1
        closed = _closed_elements(sigma, wts, starts)
        direct = ~np.repeat(closed[0], np.diff(np.r_[starts, sigma.size]))
        sigma, own, wts = sigma[direct], own[direct], wts[direct]
        starts = np.flatnonzero(np.r_[True, np.diff(own) != 0]) if own.size else own
    factors = {kind: (sigma ** p if weights is None else wts * sigma ** p)
               for kind, p in powers.items()}
    out = {kind: np.zeros((3, rho.size, m)) for kind in kinds}
    if rho.size == 0 or rows.size == 0:
        return out
    top = max(float(sigma.max(initial=0.0)),
              0.0 if closed is None else float(closed[1].max(initial=0.0)))
    t, wt = nodes(float(rho.max()) + top, layer_transfer.fine_panel(nu, base))
    n_s = sigma.size + (0 if closed is None else closed[1].size)
    chunk = max(64, int(MEMORY_BYTES / (8.0 * 12 * (n_s + rho.size))))
    if closed is not None:
        wide, ends, i_lo, i_hi, lam = closed
        shared, src = _shared_points(ends, rho)
        ends[shared] = rho[src]  # the same points, so the same Bessel values
    for lo in range(0, t.size, chunk):
        tt, ww = t[lo:lo + chunk], wt[lo:lo + chunk]
        rem = dict(zip(("ww", "wu", "uu"), layer_transfer.remainder_transfer(tt, nu, base)))
        rt = np.multiply.outer(rho, tt)
        j0, j1 = _bessel("J0", rt), _bessel("J1", rt)
        jr = {"J0": j0, "J1": j1, "dJ1": _bessel("dJ1", rt, j0, j1)}
        if sigma.size:
            st = np.multiply.outer(sigma, tt)
            sj0, sj1 = _bessel("J0", st), _bessel("J1", st)
        if closed is not None and ends.size:
            xe = np.multiply.outer(ends, tt)
            ej0, ej1 = np.empty_like(xe), np.empty_like(xe)
            ej0[shared], ej1[shared] = j0[src], j1[src]
            ej0[~shared], ej1[~shared] = _bessel("J0", xe[~shared]), _bessel("J1", xe[~shared])
            g = _disc_pair(xe, ej0, ej1)
        for kind in kinds:
            p, specs = powers[kind], _SPECS[kind]
            s_fun = (_bessel("J1" if kind == "pressure" else "J2", st, sj0, sj1)
                     * factors[kind][:, None]) if sigma.size else np.zeros((0, tt.size))
            if closed is not None:
                part = s_fun
                s_fun = np.zeros((rows.size, tt.size))
                if sigma.size:
                    s_fun[~wide] = np.add.reduceat(part, starts, axis=0)
                if ends.size:
                    gp = g[p]
                    s_fun[wide] = (gp[i_hi] - gp[i_lo]) * lam[:, None] / tt ** (p + 1)
            for i, (rname, _, _, _, rfun, tpow) in enumerate(specs):
                out[kind][i][:, rows] += (jr[rfun] * (ww * rem[rname] * tt**tpow)) @ s_fun.T
    for kind in kinds:
        for i, (_, _, sign, _, _, _) in enumerate(_SPECS[kind]):
            out[kind][i] *= 2.0 * sign
    return out


def _shared_points(ends: Arr, rho: Arr) -> tuple[NDArray[np.bool_], NDArray[np.intp]]:
    """Which ``ends`` equal a point of ``rho`` to 1e-14 (a mesh's edges and nodes), and which."""
    if rho.size == 0:
        return np.zeros(ends.size, dtype=bool), np.zeros(0, dtype=np.intp)
    order = np.argsort(rho, kind="stable")
    ordered = rho[order]
    k = np.clip(np.searchsorted(ordered, ends), 1, max(ordered.size - 1, 1))
    k = np.where(np.abs(ordered[k - 1] - ends) <= np.abs(ordered[np.minimum(k, ordered.size - 1)]
                                                        - ends), k - 1, k)
    k = np.minimum(k, ordered.size - 1)
    shared = np.abs(ordered[k] - ends) <= 1e-14 * np.maximum(ends, 1.0)
    return shared, order[k[shared]]


def _closed_elements(sigma: Arr, weights: Arr, starts: NDArray[np.intp]
                     ) -> tuple[NDArray[np.bool_], Arr, NDArray[np.intp], NDArray[np.intp], Arr]:
    """Which element rules are replaced by the closed form, and their intervals.

    A group of points (one owner) whose weights integrate the moments about
    their centre up to degree 6 as a rule on one interval ``[lo, hi]`` would
    (to 1e-10: Gauss panels spanning an element), of width ``>= WIDE_ELEMENT
    max(hi, 1)`` and ``lo >= 0``, is summed as ``lam int_lo^hi s^p J_p(s t) ds``
    (:func:`disc_integrals`), ``lam`` the weight per unit of ``sigma``.

    Returns
    -------
    wide : bool array, one per group
    ends : the distinct interval ends of the wide groups (ends closer than
        1e-14 of their size merged: the elements' shared edges)
    i_lo, i_hi : indices into ``ends`` of each wide group's interval
    lam : weight per unit ``sigma`` of each wide group
    """
    counts = np.diff(np.r_[starts, sigma.size])
    s0 = np.add.reduceat(weights, starts)
    safe = np.where(s0 > 0.0, s0, 1.0)
    mid = np.add.reduceat(weights * sigma, starts) / safe
    d = sigma - np.repeat(mid, counts)
    d2 = d * d
    m2 = np.add.reduceat(weights * d2, starts) / safe
    m4 = np.add.reduceat(weights * d2 * d2, starts) / safe
    m6 = np.add.reduceat(weights * d2 * d2 * d2, starts) / safe
    half = np.sqrt(3.0 * np.maximum(m2, 0.0))  # m2 = half^2/3 on one interval
    reach = np.maximum.reduceat(np.abs(d), starts)
    with np.errstate(invalid="ignore", divide="ignore"):
        wide = ((s0 > 0.0) & (half >= 0.5 * WIDE_ELEMENT * np.maximum(mid + half, 1.0))
                & (mid >= half * (1.0 - 1e-12))
                & (np.abs(m4 / half**4 - 0.2) <= 2e-11)
                & (np.abs(m6 / half**6 - 1.0 / 7.0) <= 2e-11)
                & (reach <= half * (1.0 + 1e-12)))
    lo, hi = np.maximum(mid - half, 0.0)[wide], (mid + half)[wide]
    lam = s0[wide] / (2.0 * half[wide])
    both = np.r_[lo, hi]
    order = np.argsort(both, kind="stable")
    ordered = both[order]
    new = np.diff(ordered, prepend=-np.inf) > 1e-14 * np.maximum(ordered, 1.0)
    group = np.cumsum(new) - 1
    ends = ordered[new]
    index = np.empty(both.size, dtype=np.intp)
    index[order] = group
    return wide, ends, index[:lo.size], index[lo.size:], lam
