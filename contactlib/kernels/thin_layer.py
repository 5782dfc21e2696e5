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
  20-point Gauss-Legendre panels of width ``min(0.25, PANEL_SPAN/(rho + sigma))``
  (``PANEL_SPAN = 30``: ~5 periods a panel; 40 loses 7e-10 of the scale), so
  the number of nodes grows like ``max(rho + sigma)`` (24,000 at a/h = 1000);
* memory: each chunk of nodes holds up to ``10 (n_s + n_r)`` values a node,
  kept under :data:`MEMORY_BYTES` (48 MB) whatever the size.

Accuracy (tests/test_thin_layers.py): equal to the tables to 1e-10 of their
scale where both apply, to an independent ``quad`` of a disc's w(0) to 1e-12, unchanged (< 1e-12) when the panels are halved at
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
        Panels of width ``min(0.25, PANEL_SPAN/span)`` (and ``2 f/32`` below
        ``2 f``), 20 nodes each.
    """
    width = min(0.25, PANEL_SPAN / max(float(span), 1.0))
    edges = np.linspace(0.0, T_MAX, int(np.ceil(T_MAX / width)) + 1)
    if fine is not None:
        t_fine = layer_transfer.FINE_T * fine  # as the tables' quadrature
        step = min(width, t_fine / layer_transfer.FINE_PANELS)
        low = np.linspace(0.0, t_fine, int(np.ceil(t_fine / step)) + 1)
        edges = np.concatenate([low, edges[edges > t_fine]])
    g, w = np.polynomial.legendre.leggauss(_GL_ORDER)
    lo, hi = edges[:-1, None], edges[1:, None]
    return (0.5 * (hi - lo) * g + 0.5 * (lo + hi)).ravel(), (0.5 * (hi - lo) * w).ravel()


def _bessel(name: str, x: Arr, j0: Arr | None = None, j1: Arr | None = None) -> Arr:
    """J0, J1, J2 or J1' = (J0 - J2)/2 of x >= 0 (J2 by recurrence above x = 2)."""
    from scipy import special  # here, not at import (as contactlib.kernels.layer)

    if name == "J0":
        return special.j0(x) if j0 is None else j0
    if name == "J1":
        return special.j1(x) if j1 is None else j1
    j0 = special.j0(x) if j0 is None else j0
    j1 = special.j1(x) if j1 is None else j1
    big = x > 2.0
    j2 = np.where(big, 2.0 * j1 / np.where(big, x, 1.0) - j0, special.jv(2, np.where(big, 0.0, x)))
    return j2 if name == "J2" else 0.5 * (j0 - j2)


def remainders(kind: str, rho: ArrayLike, sigma: ArrayLike, nu: float, base: str,
               weights: ArrayLike | None = None, owner: ArrayLike | None = None) -> Arr:
    """The remainder functions of a layer (rigid base or coated), on the grid rho x sigma.

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
    rho = np.abs(np.asarray(rho, dtype=float).reshape(-1))
    sigma = np.asarray(sigma, dtype=float).reshape(-1)
    specs = _SPECS[kind]
    power = specs[0][1]
    if weights is None:
        factor, starts, rows = sigma ** power, None, np.arange(sigma.size)
        m = sigma.size
    else:
        own = np.asarray(owner, dtype=np.intp).reshape(-1)
        factor = np.asarray(weights, dtype=float).reshape(-1) * sigma ** power
        starts = np.flatnonzero(np.r_[True, np.diff(own) != 0]) if own.size else own
        rows, m = own[starts], int(own.max(initial=-1)) + 1
    out = np.zeros((3, rho.size, m))
    if rho.size == 0 or sigma.size == 0:
        return out
    t, wt = nodes(float(rho.max() + sigma.max()), layer_transfer.fine_panel(nu, base))
    chunk = max(64, int(MEMORY_BYTES / (8.0 * 10 * (sigma.size + rho.size))))
    for lo in range(0, t.size, chunk):
        tt, ww = t[lo:lo + chunk], wt[lo:lo + chunk]
        rem = dict(zip(("ww", "wu", "uu"), layer_transfer.remainder_transfer(tt, nu, base)))
        s_fun = _bessel("J1" if kind == "pressure" else "J2", np.multiply.outer(sigma, tt))
        s_fun *= factor[:, None]
        if starts is not None:
            s_fun = np.add.reduceat(s_fun, starts, axis=0)
        rt = np.multiply.outer(rho, tt)
        j0, j1 = _bessel("J0", rt), _bessel("J1", rt)
        for i, (rname, _, _, _, rfun, tpow) in enumerate(specs):
            jr = _bessel(rfun, rt, j0, j1)
            out[i][:, rows] += (jr * (ww * rem[rname] * tt**tpow)) @ s_fun.T
    for i, (_, _, sign, _, _, _) in enumerate(specs):
        out[i] *= 2.0 * sign
    return out
