r"""Plane-strain surface displacements under uniform strip loads.

Three bodies: the elastic half-plane (``h = inf``) and an elastic layer (slab) of
thickness ``h`` on a rigid base, smooth (frictionless; the default) or bonded
(``base="bonded"``, see the last section). Two loadings,
each on a strip of half-width ``s`` centred at the origin:

``pressure_strip``
    uniform unit pressure p = 1 (compressive) on ``|x'| < s``;
``shear_strip``
    outward unit shear: traction +1 (in +x) on ``0 < x' < s`` and -1 on
    ``-s < x' < 0`` (self-equilibrated).

Units and conventions
---------------------
Plane strain, ``E* = E / (1 - nu**2) = 1``; lengths in any unit (the caller
uses the contact half-width a = 1, so the slab thickness is ``h = 1/slab_ratio``).
``w`` is the normal surface displacement, positive INTO the body (the direction
of a compressive pressure); ``u`` is the tangential surface displacement,
positive in +x; ``du`` is ``du/dx``. ``beta = (1 - 2 nu) / (2 (1 - nu))`` (so
that ``(1 - 2 nu)(1 + nu) / (2 E) = beta / E*``). Displacements scale like
(load per unit area) * length / E*.

Half-plane (Flamant)
--------------------
Unit line loads at the origin, surface displacement at ``xi = x - x'``:

* normal load (compressive):   ``w = -(2/pi) ln|xi|``, ``u = -beta sgn(xi)``;
* tangential load (in +x):     ``u = -(2/pi) ln|xi|``, ``w = +beta sgn(xi)``

(Johnson, *Contact Mechanics*, eqs 2.19-2.20; Betti fixes the cross signs).
The logarithm uses a unit reference length: the half-plane ``w`` is only
defined up to an additive constant, and this module takes the constant that
makes the strip kernels the exact integrals of the line-load kernels above.
Integrating over the strips (``F(t) = t ln|t|``, with ``0 ln 0 = 0``):

* pressure: ``w = (2/pi) [2s - F(x+s) + F(x-s)]``,
  ``u = -beta (|x+s| - |x-s|)`` (``-2 beta x`` inside, ``-+2 beta s`` outside:
  exactly constant outside), ``du = -beta (sgn(x+s) - sgn(x-s))``;
* shear: ``u = (2/pi) [F(x+s) + F(x-s) - 2 F(x)]`` (odd, no free constant;
  ``~ (2/pi) s^2/x`` for ``|x| >> s``), ``du = (2/pi) ln|1 - s^2/x^2|``,
  ``w = -beta (|x+s| + |x-s| - 2|x|) = -2 beta (s - |x|)`` inside, 0 outside
  (outward shear lifts the surface: sign fixed by Betti).

For ``|x| > 2s`` the forms ``log1p(2s/(|x|-s))`` and ``log1p(-s^2/x^2)`` replace
the differences of logarithms, so the far field has no cancellation.

Slab on a smooth rigid base: derivation
---------------------------------------
Layer ``0 < z < h`` (``z`` into the body). With ``f(x) = (1/2pi) int f^(k)
e^{ikx} dk``, take the Airy function ``phi = e^{ikx} [(A + Bz) cosh kz + (C +
Dz) sinh kz]``, ``sxx = phi_zz``, ``szz = phi_xx``, ``sxz = -phi_xz``, and the
displacements from plane-strain Hooke's law (``u_x = exx/(ik)``, ``u_z`` from
``2 exz``). Boundary conditions: at ``z = 0`` ``szz = -p``, ``sxz = -q`` (surface
tractions p into the body and q in +x); at ``z = h`` ``u_z = 0`` and ``sxz = 0``.
Solving the 4x4 system gives, with ``t = |k| h`` and ``D(t) = sinh 2t + 2t``::

    w^ = (2/|k|) (cosh 2t - 1)/D  p^  -  (i/k) g(t) q^
    u^ = (i/k) g(t) p^  +  (2/|k|) (cosh 2t + 1)/D  q^
    g(t) = [(1 - 2nu) sinh 2t - 2t] / [(1 - nu) D] = 2 beta - 4t/D

The cross terms are equal and opposite (Betti). As ``t -> inf`` the
coefficients tend to ``2/|k|`` and ``2 i beta/k``: the half-plane (the Flamant
kernels above). As ``t -> 0`` (thin layer): ``w^ -> h p^`` (uniaxial stress,
``szz = -p``, ``sxx = 0``), ``u^ -> -i nu/((1-nu) k) p^`` (lateral Poisson
expansion ``du/dx = nu/(1-nu) p``), ``u^ -> [1/(k^2 h) + 2h/3 + O(k^2 h^3)] q^``
(membrane stretching ``h u'' = -q`` plus a local shear term ``2h q/3``) and
``w^ -> i nu/((1-nu) k) q^`` (Poisson thinning, ``w = -nu/(1-nu) int_{-inf}^x q``).

Remainders. The slab line-load kernels minus the half-plane ones are smooth
functions of ``eta = xi/h`` (their transforms decay like ``exp(-2t)``) and do
not depend on ``nu``:

* normal load, ``w``:  ``A(eta) + (2/pi) ln h`` with ``A(eta) = w1(eta) + (2/pi)
  ln|eta|`` and ``w1(eta) = (2/pi) int_0^inf (cosh 2t - 1)/(t D) cos(t eta) dt``
  the slab's absolute ``w`` (``w1 -> 0`` as ``|eta| -> inf``; ``int w1 = 1``);
* normal load, ``u``:  ``B(eta) = (4/pi) int_0^inf sin(t eta)/D dt``;
* tangential load, ``w``: ``-B(eta)``;
* tangential load, ``u``: ``C(eta) = (2/pi) int_0^inf (cosh 2t + 1 - D)/(t D)
  (cos t eta - 1) dt``. A tangential line load on a layer over a smooth base is
  unbalanced (``u ~ -|xi|/(2h)``, defined up to a rigid translation); the
  normalisation ``C(0) = 0`` is arbitrary and cancels in the self-equilibrated
  shear strip.

With the antiderivatives ``A1, B1, C1`` (``X1(eta) = int_0^eta X``), ``e0 = x/h``,
``e+- = (x +- s)/h``, the strip kernels are the half-plane ones plus::

    pressure: w += h [A1(e+) - A1(e-)] + (4 s/pi) ln h
              u += h [B1(e+) - B1(e-)],          du += B(e+) - B(e-)
    shear:    u += h [2 C1(e0) - C1(e+) - C1(e-)], du += 2 C(e0) - C(e+) - C(e-)
              w -= h [2 B1(e0) - B1(e+) - B1(e-)]

The ``(2/pi) ln h`` term converts the half-plane's unit reference length so
that the slab's ``w`` is absolute: it tends to 0 far from the load (the slab's
line-load ``w`` decays exponentially and integrates to ``h``). Far field
(``|eta| -> inf``; corrections ``O(exp(-2.106 |eta|))`` from the zero of ``D``
at ``t = 1.1254 + 2.1062 i``), for ``eta > 0`` (``A1, B, C1`` odd; ``A, B1, C``
even)::

    A  -> (2/pi) ln eta,            A1 -> (2/pi)(eta ln eta - eta) + 1/2
    B  -> 1/2,                      B1 -> eta/2 + b1,   b1 = (4/pi) int_0^inf (1/D - 1/(4t)) dt/t
    C  -> -eta/2 + (2/pi) ln eta + c0,
    C1 -> -eta^2/4 + (2/pi)(eta ln eta - eta) + c0 eta + 1/3,
    c0 = (2/pi) (1 - ln 2 - int_0^inf f3 dt),  f3 = (cosh 2t + 1 - D)/(t^2 D) - exp(-2t)/(2 t^2)

So far from the strip the slab's ``u`` under pressure tends to
``+-s nu/(1-nu)`` (instead of the half-plane's ``-+2 beta s``).

Numerics of the slab. ``A1, B1, C1`` and their first two derivatives are
computed once per process (``functools.lru_cache``, ~0.2 s; the tables depend
on neither ``nu`` nor ``h``) on the nodes ``eta = 0, 0.02, ..., 20`` by
composite 20-point Gauss-Legendre quadrature of the transform integrals
(``0 < t < 25``, 50 panels), after subtracting known transforms (``exp(-2t)``
terms) so that every integrand is regular at ``t = 0``; numerators that cancel
are summed as series of ``expm1`` tails. ``b1 = -0.3277425951...`` and
``c0 = 0.5516261035...`` come from the same quadrature. Evaluation: piecewise
quintic Hermite interpolation on ``-20 <= eta <= 20`` (C2; ``B`` and ``C`` are
the derivatives of the ``B1`` and ``C1`` interpolants), with the pairs
(A1, B1) and (C1, B1) packed as complex numbers so one gather fetches both;
interpolation error ~1e-13 (values) and ~5e-12 (derivatives) in ``eta``
units. Beyond ``|eta| = 20`` the far-field forms are used, and where every
argument is beyond it the thin-layer closed forms of ``_layer_far`` (in which
the half-plane logarithms cancel analytically) replace the sum. Evaluation is
chunked (16384 points) to stay in cache; for the shear the terms at ``x/h``
are evaluated once on ``x``'s own shape when ``x`` is broadcast against a
larger ``s``.

Slab on a bonded rigid base
---------------------------
Same layer, with ``u_x = u_z = 0`` at ``z = h``. With ``kappa = 3 - 4 nu`` and
``N = 2 kappa cosh 2t + 1 + kappa^2 + 4 t^2`` the coefficients of ``w^`` and ``u^``
above become (``2/|k|`` times, for the direct terms; ``2 i/k`` for the cross term)::

    Cww = (2 kappa sinh 2t - 4t)/N,   Cuu = (2 kappa sinh 2t + 4t)/N,
    Cwu = [2 kappa (kappa - 1)(cosh 2t - 1) - 8 t^2] / ((kappa + 1) N)

(the same functions as the axisymmetric layer of :mod:`contactlib.kernels.layer`,
where they are checked against a Love-function solution). Their remainders
``Rww = Cww - 1``, ``Rwu = Cwu - beta``, ``Ruu = Cuu - 1`` (all ``-> -1, -beta,
-1`` as ``t -> 0``; ``O(t^2 e^{-2t})`` as ``t -> inf``) define, for the line
loads::

    A(eta)  = (2/pi) [int_0^inf (Rww cos(t eta) + e^{-2t})/t dt + ln 2]
    B(eta)  = -(2/pi) int_0^inf Rwu sin(t eta)/t dt
    C(eta)  = (2/pi) int_0^inf Ruu (cos(t eta) - 1)/t dt

(with the smooth base's ``R`` these are exactly the ``A, B, C`` above), and the
strip kernels are built from ``A1, B1, C1`` by the same formulas. They depend
on ``nu``: one table per ``nu`` (``lru_cache``, 8 entries). The bonded layer's
line-load response is local (its transforms are analytic at ``k = 0``), so far
from the load (``|eta| -> inf``)::

    A  -> (2/pi) ln eta,          A1 -> (2/pi)(eta ln eta - eta) + a1,  a1 = (1 - 2nu)/(2 (1 - nu)^2)
    B  -> beta,                   B1 -> beta eta + b1
    C  -> (2/pi) ln eta + c0,     C1 -> (2/pi)(eta ln eta - eta) + c0 eta + c1,  c1 = 1/(1 - nu)

so that a uniform strip far from its edges gives Winkler's ``w = p h / M``
(``M = E (1 - nu)/((1 + nu)(1 - 2 nu))``, i.e. ``2 a1 h`` for ``E* = 1``), no
``u``, and the shear ``u = q h / G`` (``2 c1 h``). The corrections decay like
``exp(-gamma |eta|)`` with gamma from the complex zeros of ``N``: measured
~1.2 at nu = 0, ~0.9 at nu = 0.3 and only ~0.74 at nu = 1/2. The tables
therefore cover ``|eta| <= 48`` (same spacing 0.02, quintic Hermite; quadrature
panels of 0.25), and ``a1, b1, c0, c1`` are matched to the quadrature at
``eta = 48`` (``a1`` and ``c1`` agree with their closed forms to the
quadrature's precision: a test). Beyond, the far-field forms are used, and
where every argument is beyond, the local closed forms of ``_bonded_far``.
At ``nu = 1/2`` (``kappa = 1``, ``beta = 0``) nothing is 0/0.

Coated body
-----------
``base = Substrate(modulus, nu2)`` (:class:`contactlib.kernels.layer.Substrate`): the
layer bonded to an elastic half-plane, the remainders of
:func:`contactlib.kernels.layer.coated_remainder`. They tend to ``R0 = m - 1``,
``m beta2 - beta``, ``m - 1`` at ``t -> 0`` (``m = E1*/E2*``), so ``A`` takes the
integrand ``(Rww cos t eta - R0 e^{-2t})/t`` and the constant ``-R0 ln 2``, and the
pressure strip's ``(4 s/pi) ln h`` is multiplied by ``1 - m`` (``-R0``; 1 on the rigid
bases): far away the line load's ``w`` is ``-(2/pi) m ln|xi|``, the substrate's
half-plane with the unit reference length. The line-load remainders decay only
algebraically (``1/eta^2``: the transforms are not analytic at ``k = 0``), so there
are no exponentially accurate far-field forms: the tables (``|eta| <= 48``, spacing
0.02, one per (nu, substrate), the quadrature with 32 panels on ``0 < t < 2 min(1,
m^(-1/3))`` before the panels of 0.25) are followed, on ``48 < |eta| <= 3072``, by
log-spaced tables of the smooth parts ``G = X1 - K`` (:func:`_coated_far`), where ``K``
is the growth that makes the substrate's half-plane::

    K_A1 = K_C1 = -(2/pi) R0 (eta ln|eta| - eta),   K_B1 = -Rwu0 |eta|

(``R0 = m - 1``, ``Rwu0 = m beta2 - beta``): quintic Hermite pieces uniform in
``ln|eta|`` (40 per doubling of ``eta``), their nodal values and two derivatives by
the same quadrature with panels ``12/eta_max`` wide, octave by octave (built on first
use, only the octaves a call reaches: ~0.1 s to eta = 200, ~2.5 s to 3072). Where every
argument is beyond 48 the kernel is the substrate's half-plane ``m hp(beta2)`` plus
differences of ``G`` (:func:`_coated_all_far`; the growing ``K`` never enters). Measured
(tests/test_thin_coatings_cylinder.py): the slopes ``A, B, C`` equal an independent
QAWO quadrature of their Fourier integrals within 2e-11 of ``max(1, m)`` up to
``eta = 3000`` (E2/E1 = 0.01 ... 1e3), the tables and the far tables join within the
step at ``eta = 48``. Beyond ``|x +- s|/h = 3072`` (a/h = 1536 for ``x, s <= a``) a
``ValueError`` is raised.

Removable points and limits: ``x = +-s`` (``F(0) = 0``), ``x = 0`` and ``s = 0``
(all outputs 0) are exact. ``du`` of the pressure strip jumps at ``x = +-s``:
the value there is the mean of the one-sided limits. ``du`` of the shear strip
has integrable logarithmic singularities at ``x = 0`` (``+inf``) and
``x = +-s`` (``-inf``), returned as such.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from math import factorial

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .layer import Substrate, coated_remainder

__all__ = ["BASES", "pressure_strip", "shear_strip", "axis_w_strip", "w_difference_strip"]

Arr = NDArray[np.float64]
_TWO_PI = 2.0 / np.pi

# --- slab tables -------------------------------------------------------------
# tested: tests/test_kernels_strip.py (table and far-field forms meet without a jump)
_ETA_MAX = 20.0  # tabulated range of |eta|; beyond: far-field forms (error ~ e^-42)
# tested: tests/test_kernels_strip.py (the tables against scipy's quad); cost:
# benchmarks/bench_kernels.py
_N_PIECES = 1000  # pieces on each side of eta = 0
_DELTA = _ETA_MAX / _N_PIECES
_INV_DELTA = 1.0 / _DELTA
# tested: tests/test_kernels_strip.py (the transforms against scipy's quad; the integrands are O(t^2
# exp(-2t)) beyond)
_T_MAX = 25.0  # transform integrands are O(t^2 exp(-2t)) beyond
# tested: tests/test_kernels_strip.py (the bonded slab against its Fourier integral)
_ETA_MAX_BONDED = 48.0  # bonded base: corrections decay like exp(-0.74 |eta|) at nu = 1/2
# tested: tests/test_kernels_strip.py (the bonded slab against its Fourier integral)
_PANEL_BONDED = 0.25  # finer panels: t * eta up to 25 * 48
BASES = ("smooth", "bonded")
# tested: tests/test_kernels_strip.py (the tables' quadrature against scipy's quad)
_PANEL = 0.5
# tested: tests/test_kernels_strip.py (the tables' quadrature against scipy's quad)
_GL_ORDER = 20
# convention: scratch size, the results do not depend on it (speed: benchmarks/bench_kernels.py)
_CHUNK = 16384  # points per chunk (keeps temporaries in cache)


def _beta(nu: float) -> float:
    """beta = (1 - 2 nu) / (2 (1 - nu))."""
    return (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu))


def _exp_tail(m: int, x: NDArray[np.float64]) -> NDArray[np.float64]:
    """sum_{n >= m} x**n / n!, accurate for |x| small (series) and large (expm1)."""
    out = np.empty_like(x)
    small = np.abs(x) < 2.0
    xs = x[small]
    term = xs**m / factorial(m)
    acc = term.copy()
    for n in range(m + 1, m + 40):  # 2**40 / 40! ~ 1e-36
        term = term * xs / n
        acc += term
    out[small] = acc
    xl = x[~small]
    r = np.expm1(xl)
    for n in range(1, m):
        r -= xl**n / factorial(n)
    out[~small] = r
    return out


def _sinh_tail(x: NDArray[np.float64]) -> NDArray[np.float64]:
    """sinh(x) - x without cancellation."""
    out = np.empty_like(x)
    small = np.abs(x) < 2.0
    xs = x[small]
    term = xs**3 / 6.0
    acc = term.copy()
    for n in range(5, 80, 2):
        term = term * xs * xs / ((n - 1) * n)
        acc += term
    out[small] = acc
    out[~small] = np.sinh(x[~small]) - x[~small]
    return out


def _gauss_panels(panel: float = _PANEL) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Composite Gauss-Legendre nodes and weights on 0 < t < _T_MAX."""
    g, w = np.polynomial.legendre.leggauss(_GL_ORDER)
    edges = np.arange(0.0, _T_MAX + 0.5 * panel, panel)
    lo, hi = edges[:-1, None], edges[1:, None]
    t = (0.5 * (hi - lo) * g + 0.5 * (lo + hi)).ravel()
    wt = (0.5 * (hi - lo) * w).ravel()
    return t, wt


def _integrand_parts(t: NDArray[np.float64]) -> tuple[NDArray[np.float64], ...]:
    """Regularised transform factors a2(t), b(t), f3(t) (see ``_remainder_exact``)."""
    D = np.sinh(2.0 * t) + 2.0 * t
    # a2 = (cosh2t - 1)/D - 1 + exp(-2t)
    a2 = (_exp_tail(2, -2 * t) - 0.5 * _exp_tail(2, -4 * t) + 2 * t * _exp_tail(1, -2 * t)) / D
    # b = 1/D - exp(-2t)/(4t)
    b = (0.5 * _exp_tail(2, -4 * t) - 2 * t * _exp_tail(1, -2 * t)) / (4.0 * t * D)
    # f3 = (cosh2t + 1 - D)/(t^2 D) - exp(-2t)/(2t^2)
    f3 = 0.5 * _exp_tail(3, -4 * t) / (2.0 * t * t * D)
    return D, a2, b, f3


def _remainder_exact(eta: ArrayLike) -> dict[str, NDArray[np.float64]]:
    """Remainder functions by quadrature (slow path; for tabulation and tests).

    Parameters
    ----------
    eta : array_like
        Points ``eta = xi/h >= 0`` (at most a few thousand).

    Returns
    -------
    dict
        ``A, dA, A1, B, dB, B1, C, dC, C1`` at ``eta`` (see the module notes;
        ``dX = X'``, ``X1 = int_0^eta X``).

    Notes
    -----
    Identities used (``c > 0``): ``int_0^inf exp(-ct) sin(bt)/t dt = atan(b/c)``,
    ``int_0^inf exp(-ct)(1 - cos bt)/t dt = ln(1 + b^2/c^2)/2``,
    ``int_0^inf exp(-ct)(1 - cos bt)/t^2 dt = b atan(b/c) - (c/2) ln(1 + b^2/c^2)``
    and Frullani's ``ln|eta| = ln 2 + int_0^inf (exp(-2t) - cos t eta)/t dt``.
    """
    t, wt = _gauss_panels()
    _, a2, b, f3 = _integrand_parts(t)
    e = np.atleast_1d(np.asarray(eta, dtype=float))
    te = t * e[:, None]
    cs = np.cos(te)
    sn = np.sin(te)
    hs2 = 2.0 * np.sin(0.5 * te) ** 2  # 1 - cos
    at = np.arctan(0.5 * e)
    lg = np.log1p(0.25 * e * e)
    ln2 = np.log(2.0)
    pi = np.pi
    out = {}
    out["A"] = _TWO_PI * (cs @ (wt * a2 / t) + 0.5 * lg + ln2)
    out["dA"] = _TWO_PI * (-(sn @ (wt * a2)) + e / (4.0 + e * e))
    out["A1"] = _TWO_PI * (sn @ (wt * a2 / t**2) + 0.5 * (e * lg - 2.0 * e + 4.0 * at) + e * ln2)
    out["B"] = (4.0 / pi) * (sn @ (wt * b)) + at / pi
    out["dB"] = (4.0 / pi) * (cs @ (wt * t * b)) + (2.0 / pi) / (4.0 + e * e)
    out["B1"] = (4.0 / pi) * (hs2 @ (wt * b / t)) + (e * at - lg) / pi
    out["C"] = _TWO_PI * (-0.5 * (e * at - lg) - hs2 @ (wt * f3))
    out["dC"] = _TWO_PI * (-0.5 * at - sn @ (wt * t * f3))
    g = (0.5 * e * e - 2.0) * at + e - e * lg
    out["C1"] = _TWO_PI * (-0.5 * g + (sn / t - e[:, None]) @ (wt * f3))
    return out


def _sin_tail(x: NDArray[np.float64]) -> NDArray[np.float64]:
    """sin(x) - x without cancellation."""
    out = np.empty_like(x)
    small = np.abs(x) < 2.0
    xs = x[small]
    term = -xs**3 / 6.0
    acc = term.copy()
    for n in range(5, 80, 2):
        term = -term * xs * xs / ((n - 1) * n)
        acc += term
    out[small] = acc
    out[~small] = np.sin(x[~small]) - x[~small]
    return out


def _bonded_transfer(t: NDArray[np.float64], nu: float) -> tuple[NDArray[np.float64], ...]:
    """Bonded-base remainders (Cww - 1, Cwu - beta, Cuu - 1), written with e = exp(-2t).

    ``N e = kappa (1 + e^2) + (1 + kappa^2 + 4t^2) e``, ``kappa = 3 - 4 nu``; see the
    module notes.
    """
    k = 3.0 - 4.0 * nu
    e = np.exp(-2.0 * t)
    ns = k * (1.0 + e * e) + (1.0 + k * k + 4.0 * t * t) * e
    common = 2.0 * k * e + 1.0 + k * k + 4.0 * t * t
    return (-e * (common + 4.0 * t) / ns, -e * (k * k - 1.0 + 4.0 * t * t) / ns,
            -e * (common - 4.0 * t) / ns)


def _remainder_exact_bonded(eta: ArrayLike, nu: float) -> dict[str, NDArray[np.float64]]:
    """Bonded-base remainder functions by quadrature (slow path; tables and tests).

    Parameters
    ----------
    eta : array_like
        Points ``eta = xi/h >= 0``.
    nu : float
        Poisson's ratio.

    Returns
    -------
    dict
        ``A, dA, A1, B, dB, B1, C, dC, C1`` of the module notes (bonded base).

    Notes
    -----
    ``A`` uses Frullani's ``ln|eta| = ln 2 + int_0^inf (exp(-2t) - cos t eta)/t dt``
    so that its integrand ``(Rww cos t eta + exp(-2t))/t`` is regular at ``t = 0``
    (``Rww(0) = -1``); ``1 - cos`` and ``sin x - x`` are formed without cancellation.
    """
    t, wt = _gauss_panels(_PANEL_BONDED)
    return _remainder_integrals(eta, t, wt, _bonded_transfer(t, float(nu)), -1.0)


def _remainder_integrals(eta: ArrayLike, t: Arr, wt: Arr, rem: tuple[Arr, Arr, Arr],
                         r0: float) -> dict[str, NDArray[np.float64]]:
    """``A, dA, A1, B, dB, B1, C, dC, C1`` at ``eta`` from the remainders ``rem`` =
    (Rww, Rwu, Ruu) on the quadrature (t, wt), ``r0 = Rww(0)`` (-1 on the bonded base).

    ``A``'s integrand ``(Rww cos t eta - r0 exp(-2t))/t`` is regular at ``t = 0``, with
    the constant ``-r0 ln 2`` (Frullani); with ``r0 = -1`` every operation is the bonded
    base's as it was written before coated bodies (the same bits).
    """
    rww, rwu, ruu = rem
    e = np.atleast_1d(np.asarray(eta, dtype=float))
    te = t * e[:, None]
    cs = np.cos(te)
    sn = np.sin(te)
    hs2 = 2.0 * np.sin(0.5 * te) ** 2  # 1 - cos
    ex = np.exp(-2.0 * t)
    ln2 = np.log(2.0)
    out = {}
    out["A"] = _TWO_PI * (((rww * cs - r0 * ex) / t) @ wt - r0 * ln2)
    out["dA"] = -_TWO_PI * (sn @ (wt * rww))
    # A1: (Rww sin(t eta)/t - r0 eta exp(-2t))/t = Rww (sin - t eta)/t^2 + eta (Rww - r0
    # exp(-2t))/t
    out["A1"] = _TWO_PI * (_sin_tail(te) @ (wt * rww / t**2)
                           + e * (((rww - r0 * ex) / t) @ wt) - r0 * e * ln2)
    out["B"] = -_TWO_PI * (sn @ (wt * rwu / t))
    out["dB"] = -_TWO_PI * (cs @ (wt * rwu))
    out["B1"] = -_TWO_PI * (hs2 @ (wt * rwu / t**2))
    out["C"] = -_TWO_PI * (hs2 @ (wt * ruu / t))
    out["dC"] = -_TWO_PI * (sn @ (wt * ruu))
    out["C1"] = _TWO_PI * (_sin_tail(te) @ (wt * ruu / t**2))
    return out


def _remainder_exact_coated(eta: ArrayLike, nu: float,
                            sub: Substrate) -> dict[str, NDArray[np.float64]]:
    """Coated-body remainder functions by quadrature (slow path; tables and tests).

    As :func:`_remainder_exact_bonded` with the remainders of
    :func:`contactlib.kernels.layer.coated_remainder`, which tend to
    ``R0 = Rww(0) = m - 1`` (not -1): ``A`` takes the integrand
    ``(Rww cos t eta - R0 exp(-2t))/t`` and the constant ``-R0 ln 2`` (Frullani), so
    that ``A -> -(2/pi) R0 ln eta`` far away and the line load's ``w`` is
    ``-(2/pi) m ln|xi|`` there (the substrate's half-plane) with the kernel's
    ``(2/pi) (1 - m) ln h``. Quadrature: 32 panels on ``0 < t < 2 f``, ``f = min(1,
    m^(-1/3))`` (the bending scale of a stiff layer on a soft substrate), then panels
    of ``_PANEL_BONDED`` to ``_T_MAX``.
    """
    g, wg = np.polynomial.legendre.leggauss(_GL_ORDER)
    f = min(1.0, sub.stiffness_ratio_of(nu) ** (-1.0 / 3.0))
    edges = np.arange(0.0, _T_MAX + 0.5 * _PANEL_BONDED, _PANEL_BONDED)
    edges = np.concatenate([np.linspace(0.0, 2.0 * f, 33), edges[edges > 2.0 * f]])
    lo, hi = edges[:-1, None], edges[1:, None]
    t = (0.5 * (hi - lo) * g + 0.5 * (lo + hi)).ravel()
    wt = (0.5 * (hi - lo) * wg).ravel()
    return _remainder_integrals(eta, t, wt, coated_remainder(t, nu, sub.modulus, sub.nu),
                                sub.stiffness_ratio_of(nu) - 1.0)


def _far_constants() -> tuple[float, float]:
    """(b1, c0) of the far-field forms, by the same quadrature."""
    t, wt = _gauss_panels()
    D, _, _, f3 = _integrand_parts(t)
    # (1/D - 1/(4t))/t = -(sinh 2t - 2t)/(4 t^2 D); tail beyond T_MAX: -1/(4t^2)
    b1 = (4.0 / np.pi) * (-(_sinh_tail(2.0 * t) / (4.0 * t * t * D)) @ wt - 0.25 / _T_MAX)
    c0 = _TWO_PI * (1.0 - np.log(2.0) - f3 @ wt)
    return float(b1), float(c0)


@dataclass(frozen=True)
class _SlabTable:
    """Packed piecewise-quintic coefficients on -_ETA_MAX <= eta <= _ETA_MAX.

    ``pres[k]`` (k = 0..5) holds the u**k coefficients of A1 + i B1 and
    ``shear[k]`` those of C1 + i B1, one complex number per piece, so that one
    gather fetches two functions.
    """

    pres: tuple[NDArray[np.complex128], ...]
    shear: tuple[NDArray[np.complex128], ...]
    b1_const: float
    c0_const: float
    # far-field forms (eta > eta_max): B -> b_inf, B1 -> b_inf eta + b1_const,
    # A1 -> (2/pi)(eta ln eta - eta) + a1_inf, C -> 2 c_quad eta + (2/pi) ln eta + c0_const,
    # C1 -> c_quad eta^2 + (2/pi)(eta ln eta - eta) + c0_const eta + c1_inf
    base: str = "smooth"
    n_pieces: int = _N_PIECES
    b_inf: float = 0.5
    a1_inf: float = 0.5
    c_quad: float = -0.25
    c1_inf: float = 1.0 / 3.0
    # -Rww(0): the factor of the (2/pi) ln h that makes the remainder's w scale with h (1 on
    # the rigid bases; 1 - m on a coated body, m = E1*/E2*)
    log_factor: float = 1.0
    # a coated body: its layer's nu and substrate (the key of its far table, _coated_far)
    nu: float = float("nan")
    substrate: Substrate | None = None


def _quintic_hermite(f: NDArray[np.float64], df: NDArray[np.float64],
                     d2f: NDArray[np.float64], d: float = _DELTA) -> list[NDArray[np.float64]]:
    """Monomial coefficients in u in [0, 1] on each piece (width d) from nodal f, f', f''."""
    f0, f1 = f[:-1], f[1:]
    g0, g1 = d * df[:-1], d * df[1:]
    k0, k1 = d * d * d2f[:-1], d * d * d2f[1:]
    c0, c1, c2 = f0, g0, 0.5 * k0
    r0 = f1 - (c0 + c1 + c2)
    r1 = g1 - (c1 + 2.0 * c2)
    r2 = k1 - 2.0 * c2
    c3 = 10.0 * r0 - 4.0 * r1 + 0.5 * r2
    c4 = -15.0 * r0 + 7.0 * r1 - r2
    c5 = 6.0 * r0 - 3.0 * r1 + 0.5 * r2
    return [c0, c1, c2, c3, c4, c5]


@functools.lru_cache(maxsize=8)
def _slab_table(base: str = "smooth", nu: float | None = None) -> _SlabTable:
    """Build (once per process and key) the interpolation tables of A1, B1, C1.

    The smooth base's tables depend on nothing (``nu`` ignored: pass None);
    the bonded base's depend on ``nu``.
    """
    if base == "bonded":
        return _bonded_table(float(nu))
    pos = np.linspace(0.0, _ETA_MAX, _N_PIECES + 1)
    r = _remainder_exact(pos)
    a1, b1, c1 = _full_tables(r)
    b1c, c0c = _far_constants()
    return _SlabTable(
        pres=tuple(np.ascontiguousarray(x + 1j * y) for x, y in zip(a1, b1)),
        shear=tuple(np.ascontiguousarray(x + 1j * y) for x, y in zip(c1, b1)),
        b1_const=b1c,
        c0_const=c0c,
    )


def _full_tables(r: dict[str, NDArray[np.float64]]) -> tuple[list, list, list]:
    """Quintic pieces of A1, B1, C1 on -eta_max..eta_max from values at eta >= 0."""

    def full(v, odd):  # extend from eta >= 0 to eta <= 0 by parity
        neg = -v[:0:-1] if odd else v[:0:-1]
        return np.concatenate([neg, v])

    parity = {"A1": True, "A": False, "dA": True, "B1": False, "B": True, "dB": False,
              "C1": True, "C": False, "dC": True}
    r = {k: full(v, parity[k]) for k, v in r.items()}
    return (_quintic_hermite(r["A1"], r["A"], r["dA"]),
            _quintic_hermite(r["B1"], r["B"], r["dB"]),
            _quintic_hermite(r["C1"], r["C"], r["dC"]))


def _bonded_table(nu: float) -> _SlabTable:
    """Tables of the bonded base on 0 <= |eta| <= _ETA_MAX_BONDED.

    The far-field constants are matched to the quadrature at the last node
    (exact up to the exponentially small corrections, <= 1e-15 there).
    """
    n = int(round(_ETA_MAX_BONDED / _DELTA))
    pos = np.linspace(0.0, _ETA_MAX_BONDED, n + 1)
    r = _remainder_exact_bonded(pos, nu)
    e, le = _ETA_MAX_BONDED, np.log(_ETA_MAX_BONDED)
    b_inf = _beta(nu)
    b1c = float(r["B1"][-1] - b_inf * e)
    a1c = float(r["A1"][-1] - _TWO_PI * (e * le - e))
    c0c = float(r["C"][-1] - _TWO_PI * le)
    c1c = float(r["C1"][-1] - _TWO_PI * (e * le - e) - c0c * e)
    a1, b1, c1 = _full_tables(r)
    return _SlabTable(
        pres=tuple(np.ascontiguousarray(x + 1j * y) for x, y in zip(a1, b1)),
        shear=tuple(np.ascontiguousarray(x + 1j * y) for x, y in zip(c1, b1)),
        b1_const=b1c, c0_const=c0c, base="bonded", n_pieces=n, b_inf=b_inf,
        a1_inf=a1c, c_quad=0.0, c1_inf=c1c,
    )


@functools.lru_cache(maxsize=8)
def _coated_table(nu: float, sub: Substrate) -> _SlabTable:
    """Tables of a coated body on 0 <= |eta| <= _ETA_MAX_BONDED (its line-load remainders
    decay algebraically: beyond, the log-spaced tables of :func:`_coated_far`)."""
    n = int(round(_ETA_MAX_BONDED / _DELTA))
    pos = np.linspace(0.0, _ETA_MAX_BONDED, n + 1)
    a1, b1, c1 = _full_tables(_remainder_exact_coated(pos, nu, sub))
    nan = float("nan")
    return _SlabTable(
        pres=tuple(np.ascontiguousarray(x + 1j * y) for x, y in zip(a1, b1)),
        shear=tuple(np.ascontiguousarray(x + 1j * y) for x, y in zip(c1, b1)),
        b1_const=nan, c0_const=nan, base="elastic", n_pieces=n, b_inf=nan, a1_inf=nan,
        c_quad=nan, c1_inf=nan, log_factor=1.0 - sub.stiffness_ratio_of(nu), nu=nu,
        substrate=sub,
    )


# --- coated body beyond the tables: log-spaced tables of the smooth parts ----------------
_ETA_FAR = _ETA_MAX_BONDED * 2.0**6  # 3072: |x +- s|/h of the coated far tables
# tested: tests/test_thin_coatings_cylinder.py (slopes within 2e-11 of an independent QAWO
# quadrature; tables 46 kB: benchmarks/bench_thin_coatings_cylinder.py)
_FAR_PER_OCTAVE = 40  # pieces per doubling of |eta| (uniform in ln|eta|; interpolation ~1e-15)
_FAR_DU = np.log(2.0) / _FAR_PER_OCTAVE
# tested: tests/test_thin_coatings_cylinder.py (the far tables against an independent QAWO
# quadrature)
_FAR_PHASE = 12.0  # panel width times eta: as the tables' panels of 0.25 at eta = 48
# convention: scratch size (8 MB an array), the results do not depend on it
_FAR_BLOCK = 1_000_000  # (eta, t) pairs a quadrature block (8 MB an array)


@dataclass(frozen=True)
class _FarTable:
    """A coated body's smooth parts ``G = X1 - K`` on ``48 <= |eta| <= 3072``.

    Quintic Hermite pieces in ``u = ln(|eta|/48)`` (width :data:`_FAR_DU`): ``pres[k]``
    holds the ``u**k`` coefficients of ``G_A1 + i G_B1``, ``shear[k]`` those of
    ``G_C1 + i G_B1`` (``eta > 0``; ``G_A1``, ``G_C1`` odd, ``G_B1`` even).
    """

    pres: tuple[NDArray[np.complex128], ...]
    shear: tuple[NDArray[np.complex128], ...]
    r0: float  # Rww(0) = Ruu(0) = m - 1
    rwu0: float  # Rwu(0) = m beta2 - beta


def _coated_nodes(nu: float, sub: Substrate, eta_max: float) -> tuple[Arr, Arr]:
    """The coated tables' quadrature (32 panels on ``0 < t < 2 f``, then panels to
    ``_T_MAX``), every panel at most ``_FAR_PHASE / eta_max`` wide."""
    g, wg = np.polynomial.legendre.leggauss(_GL_ORDER)
    f = min(1.0, sub.stiffness_ratio_of(nu) ** (-1.0 / 3.0))
    width = min(_PANEL_BONDED, _FAR_PHASE / eta_max)
    low = np.linspace(0.0, 2.0 * f, max(32, int(np.ceil(2.0 * f / width))) + 1)
    high = np.linspace(2.0 * f, _T_MAX, int(np.ceil((_T_MAX - 2.0 * f) / width)) + 1)
    edges = np.concatenate([low, high[1:]])
    lo, hi = edges[:-1, None], edges[1:, None]
    return (0.5 * (hi - lo) * g + 0.5 * (lo + hi)).ravel(), (0.5 * (hi - lo) * wg).ravel()


def _coated_far_exact(eta: Arr, nu: float, sub: Substrate, eta_max: float) -> dict[str, Arr]:
    """``_remainder_integrals`` of a coated body at ``eta`` (``48 <= eta <= eta_max``), on
    panels resolving ``cos(t eta_max)``, in blocks of :data:`_FAR_BLOCK` pairs."""
    t, wt = _coated_nodes(nu, sub, eta_max)
    rem = coated_remainder(t, nu, sub.modulus, sub.nu)
    r0 = sub.stiffness_ratio_of(nu) - 1.0
    step = max(1, _FAR_BLOCK // t.size)
    parts = [_remainder_integrals(eta[i:i + step], t, wt, rem, r0)
             for i in range(0, eta.size, step)]
    return {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}


@functools.lru_cache(maxsize=16)
def _coated_far(nu: float, sub: Substrate, octaves: int = 6) -> _FarTable:
    """Build (once per process and key) the far tables of a coated body on
    ``48 <= |eta| <= 48 * 2**octaves`` (octaves <= 6; each octave's nodes and quadrature
    do not depend on ``octaves``, so a shorter table is a prefix of a longer one).

    The known growth ``K`` (the substrate's half-plane: ``K_A1 = K_C1 = -(2/pi) R0 (eta
    ln|eta| - eta)``, ``K_B1 = -Rwu0 |eta|``) is taken out; what is left varies on the
    scale of ``eta`` itself (algebraic decay, and the bending waves of a stiff layer on a
    soft substrate, damped over ``~ h m^(1/3)``), so pieces uniform in ``ln|eta|`` fit it.
    The nodal values are quadratures, octave by octave (panels ``12/eta_max`` wide).
    """
    m = sub.stiffness_ratio_of(nu)
    r0, rwu0 = m - 1.0, m * _beta(sub.nu) - _beta(nu)
    pieces = octaves * _FAR_PER_OCTAVE
    eta = _ETA_MAX_BONDED * np.exp(_FAR_DU * np.arange(pieces + 1))
    cut = np.arange(0, pieces + 1, _FAR_PER_OCTAVE)
    eta[cut] = _ETA_MAX_BONDED * 2.0 ** np.arange(octaves + 1)  # exact octave ends
    parts = [_coated_far_exact(eta[lo:hi + 1] if hi == pieces else eta[lo:hi], nu, sub,
                               float(eta[hi])) for lo, hi in zip(cut[:-1], cut[1:])]
    r = {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}
    le, k_log = np.log(eta), _TWO_PI * r0
    funcs = {  # (G, G', G'') in eta
        "A": (r["A1"] + k_log * (eta * le - eta), r["A"] + k_log * le, r["dA"] + k_log / eta),
        "B": (r["B1"] + rwu0 * eta, r["B"] + rwu0, r["dB"]),
        "C": (r["C1"] + k_log * (eta * le - eta), r["C"] + k_log * le, r["dC"] + k_log / eta),
    }
    pieces = {name: _quintic_hermite(g, eta * dg, eta * dg + eta * eta * d2g, _FAR_DU)
              for name, (g, dg, d2g) in funcs.items()}
    return _FarTable(
        pres=tuple(np.ascontiguousarray(x + 1j * y) for x, y in zip(pieces["A"], pieces["B"])),
        shear=tuple(np.ascontiguousarray(x + 1j * y) for x, y in zip(pieces["C"], pieces["B"])),
        r0=r0, rwu0=rwu0)


def _coated_far_pair(kind: str, eta: Arr, tab: _SlabTable,
                     smooth_only: bool) -> tuple[Arr, Arr, Arr, Arr]:
    """A coated body's ``(F1, B1, F, B)`` at ``48 < |eta| <= 3072`` (``F`` = A for the
    pressure, C for the shear); ``smooth_only``: their smooth parts ``G`` only."""
    ae = np.abs(eta)
    if ae.size and ae.max() > _ETA_FAR:
        raise ValueError(f"|x +- s|/h = {float(ae.max()):.6g} is beyond the coated body's strip "
                         f"kernels (<= {_ETA_FAR:g}: a/h <= {_ETA_FAR / 2:g} for x, s <= a)")
    v = np.log(ae * (1.0 / _ETA_MAX_BONDED)) * (1.0 / _FAR_DU)
    octaves = int(np.clip(np.ceil(v.max(initial=0.0) / _FAR_PER_OCTAVE), 1, 6))
    far = _coated_far(tab.nu, tab.substrate, octaves)
    coef = far.pres if kind == "pressure" else far.shear
    cell = np.clip(np.floor(v), 0.0, octaves * _FAR_PER_OCTAVE - 1.0)
    u = v - cell
    idx = cell.astype(np.intp)
    val = coef[5].take(idx)
    der = 5.0 * val
    for k in (4, 3, 2, 1):
        c = coef[k].take(idx)
        val = val * u + c
        der = der * u + k * c
    val = val * u + coef[0].take(idx)
    der /= _FAR_DU * ae  # d/d|eta|
    sg = np.sign(eta)
    f1, b1 = sg * val.real, val.imag.copy()
    f, b = der.real.copy(), sg * der.imag
    if not smooth_only:
        k_log = _TWO_PI * far.r0
        la = np.log(ae)
        f1 -= k_log * (eta * la - eta)
        f -= k_log * la
        b1 -= far.rwu0 * ae
        b -= far.rwu0 * sg
    return f1, b1, f, b


def _coated_all_far(kind: str, x: Arr, s: Arr, h: float,
                    tab: _SlabTable) -> tuple[Arr, Arr, Arr]:
    """A coated body where every ``|eta| > 48``: the substrate's half-plane plus the
    differences of the smooth parts (no cancellation of the growing ``K``)::

        pressure: m hp(beta2) + (h [G_A1(e+) - G_A1(e-)], h [G_B1(e+) - G_B1(e-)],
                                 G_B(e+) - G_B(e-))
        shear:    m hp(beta2) + (h [G_B1(e+) + G_B1(e-) - 2 G_B1(e0)],
                                 h [2 G_C1(e0) - G_C1(e+) - G_C1(e-)],
                                 2 G_C(e0) - G_C(e+) - G_C(e-))

    (``hp`` the half-plane strip of the layer's material, ``m = E1*/E2*``: the growth
    ``K`` of the remainders plus the layer's half-plane is the substrate's half-plane.)
    """
    sub = tab.substrate
    m = sub.stiffness_ratio_of(tab.nu)
    inv_h = 1.0 / h
    hp = _hp_pressure if kind == "pressure" else _hp_shear
    w, u, du = hp(x, s, _beta(sub.nu))
    w *= m
    u *= m
    du *= m
    f1p, b1p, fp, bp = _coated_far_pair(kind, (x + s) * inv_h, tab, True)
    f1m, b1m, fm, bm = _coated_far_pair(kind, (x - s) * inv_h, tab, True)
    if kind == "pressure":
        w += h * (f1p - f1m)
        u += h * (b1p - b1m)
        du += bp - bm
        return w, u, du
    f10, b10, f0, _ = _coated_far_pair(kind, x * inv_h, tab, True)
    u += h * (2.0 * f10 - f1p - f1m)
    du += 2.0 * f0 - fp - fm
    w += h * (b1p + b1m - 2.0 * b10)
    return w, u, du


def _table_of(base: str | Substrate, nu: float) -> _SlabTable:
    """The slab table of a base: smooth, bonded (per nu) or a coated body (per nu, substrate)."""
    if isinstance(base, Substrate):
        return _coated_table(float(nu), base)
    return _slab_table() if base == "smooth" else _slab_table("bonded", float(nu))


def _far_pair(kind: str, eta: NDArray[np.float64], tab: _SlabTable) -> tuple[Arr, Arr, Arr, Arr]:
    """Far-field forms (|eta| > _ETA_MAX): values and derivatives of the packed pair."""
    if tab.base == "elastic":
        return _coated_far_pair(kind, eta, tab, smooth_only=False)
    ae = np.abs(eta)
    sg = np.sign(eta)
    la = np.log(ae)
    xl = ae * la - ae
    b1 = tab.b_inf * ae + tab.b1_const
    b = tab.b_inf * sg
    if kind == "pressure":
        f1 = sg * (_TWO_PI * xl + tab.a1_inf)  # A1
        f = _TWO_PI * la  # A
    else:
        f1 = sg * (tab.c_quad * ae * ae + _TWO_PI * xl + tab.c0_const * ae + tab.c1_inf)  # C1
        f = 2.0 * tab.c_quad * ae + _TWO_PI * la + tab.c0_const  # C
    return f1, b1, f, b


def _locate(eta: Arr, pieces: int) -> tuple[NDArray[np.intp], Arr, NDArray[np.bool_]]:
    """(piece index, local coordinate in [0, 1], beyond the table) of each eta.

    The position in pieces from eta = 0 and within its piece: v - floor(v) is exact
    (Sterbenz) where |v| >= 1 and within 1e-16 below. (It was v + pieces with its integer
    part then removed: the offset of 1000 (2400 bonded) cost the local coordinate ~10
    bits, a noise of 1e-13 in the slab kernels that the smallest elements turned into k
    noise of up to 1e-6 at n = 2048.) Beyond the table the coordinate is 0 (the callers
    use the far-field forms there).
    """
    v = eta * _INV_DELTA
    far = (v < -pieces) | (v > pieces)
    cell = np.clip(np.floor(v), -pieces, pieces - 1.0)
    u = v - cell
    u[far] = 0.0
    idx = cell.astype(np.intp)
    idx += pieces
    return idx, u, far


def _pair(kind: str, eta: Arr, tab: _SlabTable) -> tuple[NDArray[np.complex128], Arr, NDArray[np.bool_]]:
    """Packed values (F1, B1) and one derivative at eta (1-D, contiguous).

    Returns ``val`` (complex: F1 + i B1, with F1 = A1 for the pressure and C1
    for the shear), ``der`` (real: B = B1' for the pressure, C = C1' for the
    shear) and the mask of points beyond the table (far-field forms used).
    """
    pressure = kind == "pressure"
    coef = tab.pres if pressure else tab.shear
    comp = 1 if pressure else 0  # component whose derivative is needed
    idx, vc, far = _locate(eta, tab.n_pieces)
    u2 = np.empty(2 * vc.size)
    u2[0::2] = vc
    u2[1::2] = vc
    p = coef[5].take(idx)
    pf = p.view(np.float64)
    dp = pf[comp::2].copy()
    pf *= u2
    pf += coef[4].take(idx).view(np.float64)
    for k in (3, 2, 1, 0):
        dp *= vc
        dp += pf[comp::2]
        pf *= u2
        pf += coef[k].take(idx).view(np.float64)
    dp *= _INV_DELTA
    if far.any():
        f1, b1, f, b = _far_pair(kind, eta[far], tab)
        p[far] = f1 + 1j * b1
        dp[far] = b if pressure else f
    return p, dp, far


def _eta_only(kind: str, eta: Arr,
              tab: _SlabTable) -> tuple[NDArray[np.complex128], Arr, NDArray[np.bool_]]:
    """``_pair`` for an array of any shape (used for the x-only terms)."""
    flat = np.ascontiguousarray(eta, dtype=float).ravel()
    p, dp, far = _pair(kind, flat, tab)
    return p.reshape(eta.shape), dp.reshape(eta.shape), far.reshape(eta.shape)


# --- half-plane pieces (chunk level) -------------------------------------------
def _hp_pressure(x: Arr, s: Arr, b: float) -> tuple[Arr, Arr, Arr]:
    """Half-plane pressure strip on a chunk (see module notes)."""
    a = np.abs(x)
    d = a - s
    ad = np.abs(d)
    m = np.minimum(a, s)
    lp = np.log(a + s)
    q = np.log1p(2.0 * m / ad)  # ln((a+s)/|a-s|), accurate for all a
    w = 1.0 - lp
    w *= 2.0 * s
    w -= d * q
    edge = ad == 0.0
    if edge.any():  # (a - s) ln|a - s| -> 0
        w[edge] = 2.0 * s[edge] * (1.0 - lp[edge])
    w *= _TWO_PI
    u = np.copysign(m, x)
    u *= -2.0 * b
    du = (a < s).astype(np.float64)
    du += a <= s
    du *= -b
    return w, u, du


def _hp_shear(x: Arr, s: Arr, b: float) -> tuple[Arr, Arr, Arr]:
    """Half-plane shear strip on a chunk (see module notes)."""
    a = np.abs(x)
    d = a - s
    ad = np.abs(d)
    m = np.minimum(a, s)
    q = np.log1p(2.0 * m / ad)  # ln((a+s)/|a-s|)
    l1 = np.log((a + s) * ad / (a * a))  # ln|1 - s^2/x^2| (near field)
    r = s / a
    r *= r
    far = a > 2.0 * s
    np.copyto(l1, np.log1p(-r), where=far)  # far field, no cancellation
    g = a * l1
    g += s * q
    bad = (a == 0.0) | (ad == 0.0)
    if bad.any():  # removable points: g(0) = 0, g(s) = 2 s ln 2
        g[bad] = np.where(a[bad] == 0.0, 0.0, 2.0 * np.log(2.0) * s[bad])
    u = np.copysign(g, x)
    u *= _TWO_PI
    du = l1 * _TWO_PI
    w = np.maximum(s - a, 0.0)
    w *= -2.0 * b
    return w, u, du


try:  # the compiled route (setup.py; optional): the same bits, the arithmetic in one pass
    from . import strip_fused as _fused
except ImportError:  # pragma: no cover - a build without a C compiler
    _fused = None
FUSED = _fused is not None
"""Whether the half-plane strip kernels run their arithmetic compiled
(``contactlib/kernels/strip_fused.c``, built by ``pip install``), the logarithms by numpy
between two passes: the same IEEE operations in the same order as :func:`_hp_pressure` and
:func:`_hp_shear`, so the same bits (``tests/test_kernels_fused.py``). False selects the
numpy route."""
_LN4 = 2.0 * np.log(2.0)  # g(s) = 2 s ln 2 of the shear (as _hp_shear forms it)


def _hp_pressure_fused(x: Arr, s: Arr, b: float) -> tuple[Arr, Arr, Arr]:
    """:func:`_hp_pressure` by the compiled route (:data:`FUSED`)."""
    x, s = np.ascontiguousarray(x), np.ascontiguousarray(s)
    lp, q = np.empty(x.size), np.empty(x.size)
    _fused.args(False, x, s, lp, q)
    np.log(lp, out=lp)
    np.log1p(q, out=q)
    w, u, du = np.empty(x.size), np.empty(x.size), np.empty(x.size)
    _fused.finish(False, x, s, lp, q, b, _TWO_PI, _LN4, w, u, du)
    return w, u, du


def _hp_shear_fused(x: Arr, s: Arr, b: float) -> tuple[Arr, Arr, Arr]:
    """:func:`_hp_shear` by the compiled route (:data:`FUSED`)."""
    x, s = np.ascontiguousarray(x), np.ascontiguousarray(s)
    q, l1, far_arg = np.empty(x.size), np.empty(x.size), np.empty(x.size)
    _fused.args(True, x, s, q, l1, far_arg)
    np.log1p(q, out=q)
    np.log(l1, out=l1)
    np.log1p(far_arg, out=l1, where=np.abs(x) > 2.0 * s)  # far field, no cancellation
    w, u, du = np.empty(x.size), np.empty(x.size), np.empty(x.size)
    _fused.finish(True, x, s, q, l1, b, _TWO_PI, _LN4, w, u, du)
    return w, u, du


# --- slab remainders (chunk level) ---------------------------------------------
def _slab_pressure(x: Arr, s: Arr, h: float, tab: _SlabTable, out_w: Arr, out_u: Arr,
                   out_du: Arr) -> NDArray[np.bool_]:
    """Add the slab remainders of the pressure strip; return the all-far mask."""
    inv_h = 1.0 / h
    pp, dpp, farp = _pair("pressure", (x + s) * inv_h, tab)
    pm, dpm, farm = _pair("pressure", (x - s) * inv_h, tab)
    pp -= pm
    dpp -= dpm
    val = pp.view(np.float64)
    val *= h
    out_w += val[0::2]
    out_w += s * (2.0 * _TWO_PI * np.log(h) * tab.log_factor)
    out_u += val[1::2]
    out_du += dpp
    return farp & farm


def _slab_shear(x: Arr, s: Arr, h: float, tab: _SlabTable, out_w: Arr, out_u: Arr, out_du: Arr,
                centre: tuple | None = None) -> NDArray[np.bool_]:
    """Add the slab remainders of the shear strip; return the all-far mask."""
    inv_h = 1.0 / h
    if centre is None:
        p0, dp0, far0 = _pair("shear", x * inv_h, tab)
    else:
        p0, dp0, far0 = centre
    pp, dpp, farp = _pair("shear", (x + s) * inv_h, tab)
    pm, dpm, farm = _pair("shear", (x - s) * inv_h, tab)
    pp += pm
    dpp += dpm
    pp -= 2.0 * p0
    dpp -= 2.0 * dp0  # now -(2 X(e0) - X(e+) - X(e-))
    val = pp.view(np.float64)
    val *= h
    out_u -= val[0::2]
    out_w += val[1::2]
    out_du -= dpp
    return farp & farm & far0


def _layer_far(kind: str, x: Arr, s: Arr, h: float, nu: float,
               tab: _SlabTable) -> tuple[Arr, Arr, Arr]:
    """Exact slab kernels when every |eta| > _ETA_MAX (up to O(exp(-42))).

    The far-field forms of the remainders cancel the half-plane logarithms
    analytically; what is left is the thin-layer (membrane) answer::

        pressure: w = (h/2)(sgn(x+s) - sgn(x-s)),  u = k (|x+s| - |x-s|),
                  du = k (sgn(x+s) - sgn(x-s)),    k = nu / (2 (1 - nu))
        shear:    u = -(2x|x| - (x+s)|x+s| - (x-s)|x-s|)/(4h)
                      + (h/3)(2 sgn x - sgn(x+s) - sgn(x-s)),
                  du = -(2|x| - |x+s| - |x-s|)/(2h),
                  w = k (|x+s| + |x-s| - 2|x|)
    """
    if tab.base == "elastic":
        return _coated_all_far(kind, x, s, h, tab)
    xp, xm = x + s, x - s
    if tab.base == "bonded":
        return _bonded_far(kind, x, xp, xm, h, tab)
    k = nu / (2.0 * (1.0 - nu))
    if kind == "pressure":
        jump = np.sign(xp) - np.sign(xm)
        return 0.5 * h * jump, k * (np.abs(xp) - np.abs(xm)), k * jump
    ax, axp, axm = np.abs(x), np.abs(xp), np.abs(xm)
    u = -(2.0 * x * ax - xp * axp - xm * axm) / (4.0 * h)
    u += (h / 3.0) * (2.0 * np.sign(x) - np.sign(xp) - np.sign(xm))
    du = -(2.0 * ax - axp - axm) / (2.0 * h)
    w = k * (axp + axm - 2.0 * ax)
    return w, u, du


def _bonded_far(kind: str, x: Arr, xp: Arr, xm: Arr, h: float,
                tab: _SlabTable) -> tuple[Arr, Arr, Arr]:
    """Bonded base, every |eta| > _ETA_MAX_BONDED: the local (thin-layer) answer.

    The half-plane logarithms and the linear terms cancel analytically::

        pressure: w = a1_inf h (sgn(x+s) - sgn(x-s)),  u = 0,  du = 0
        shear:    u = c1_inf h (2 sgn x - sgn(x+s) - sgn(x-s)),  du = 0,  w = 0

    with ``a1_inf = (1 - 2nu)/(2 (1 - nu)^2)`` (Winkler: ``w = p h / M``) and
    ``c1_inf = 1/(1 - nu)`` (simple shear: ``u = q h / G``), both from the tables.
    """
    zero = np.zeros_like(x)
    if kind == "pressure":
        return tab.a1_inf * h * (np.sign(xp) - np.sign(xm)), zero, zero.copy()
    u = tab.c1_inf * h * (2.0 * np.sign(x) - np.sign(xp) - np.sign(xm))
    return zero, u, zero.copy()


# --- driver --------------------------------------------------------------------
def _validate(s: NDArray[np.float64], nu: float, h: float,
              base: str | Substrate = "smooth") -> float:
    if not isinstance(base, Substrate) and base not in BASES:
        raise ValueError(f"base={base!r} must be one of {BASES} or a Substrate")
    nu = float(nu)
    if not -1.0 < nu <= 0.5:
        raise ValueError(f"Poisson's ratio nu={nu!r} must satisfy -1 < nu <= 0.5")
    h = float(h)
    if not h > 0.0:  # also rejects NaN
        raise ValueError(f"slab thickness h={h!r} must be > 0 (np.inf: half-plane)")
    if np.any(s < 0.0):
        raise ValueError("strip half-width s must be >= 0")
    return h


def _evaluate(kind: str, x: ArrayLike, s: ArrayLike, nu: float, h: float,
              base: str = "smooth") -> tuple[Arr, Arr, Arr]:
    """Broadcast, validate and evaluate chunk by chunk."""
    x = np.asarray(x, dtype=float)
    s = np.asarray(s, dtype=float)
    h = _validate(s, nu, h, base)
    b = _beta(nu)
    slab = bool(np.isfinite(h))
    tab = None
    if slab:
        tab = _table_of(base, nu)
    hp = _hp_pressure if kind == "pressure" else _hp_shear
    if FUSED:
        hp = _hp_pressure_fused if kind == "pressure" else _hp_shear_fused
    ops: list = [x, s]
    dtypes: list = [np.float64, np.float64]
    centre = False
    total = int(np.prod(np.broadcast_shapes(x.shape, s.shape), dtype=np.int64))
    if slab and kind == "shear" and 8 * x.size <= total:
        # x-only terms at eta0 = x/h are evaluated once on x's own shape
        with np.errstate(divide="ignore", invalid="ignore"):
            p0, dp0, far0 = _eta_only("shear", x / h, tab)
        ops += [p0, dp0, far0]
        dtypes += [np.complex128, np.float64, np.bool_]
        centre = True
    nin = len(ops)
    it = np.nditer(
        ops + [None, None, None],
        flags=["external_loop", "buffered", "zerosize_ok"],
        op_flags=[["readonly"]] * nin + [["writeonly", "allocate"]] * 3,
        op_dtypes=dtypes + [np.float64] * 3,
        buffersize=_CHUNK,
    )
    with it, np.errstate(divide="ignore", invalid="ignore"):
        for chunk in it:
            xc, sc = chunk[0], chunk[1]
            wc, uc, dc = chunk[nin:]
            w, u, du = hp(xc, sc, b)
            if slab:
                if centre:
                    far = _slab_shear(xc, sc, h, tab, w, u, du, centre=chunk[2:5])
                elif kind == "shear":
                    far = _slab_shear(xc, sc, h, tab, w, u, du)
                else:
                    far = _slab_pressure(xc, sc, h, tab, w, u, du)
                if far.any():
                    wf, uf, df = _layer_far(kind, xc[far], sc[far], h, float(nu), tab)
                    w[far] = wf
                    u[far] = uf
                    du[far] = df
            zero = sc == 0.0
            if zero.any():
                w[zero] = 0.0
                u[zero] = 0.0
                du[zero] = 0.0
            wc[...] = w
            uc[...] = u
            dc[...] = du
        return it.operands[nin], it.operands[nin + 1], it.operands[nin + 2]


def pressure_strip(
    x: ArrayLike, s: ArrayLike, nu: float, h: float = np.inf, base: str = "smooth"
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Surface displacements under a uniform unit pressure on ``|x'| < s``.

    Parameters
    ----------
    x : array_like
        Surface point (any real), in the length unit of the problem (contact
        half-width a = 1 in contactlib).
    s : array_like
        Half-width of the loaded strip (>= 0); broadcast against ``x``.
        ``s = 0`` gives zeros.
    nu : float
        Poisson's ratio, -1 < nu <= 0.5.
    h : float, optional
        Thickness of the layer on a rigid base, same unit; ``np.inf``
        (default) is the half-plane.
    base : {"smooth", "bonded"} or Substrate, optional
        The rigid base: frictionless (default) or bonded; or an elastic
        substrate bonded to the layer (a coated body, module notes).

    Returns
    -------
    w, u, du : ndarray
        Normal displacement (into the body), tangential displacement (+x) and
        ``du/dx`` for p = 1 and E* = 1 (scale with p/E*; ``w``, ``u`` also
        with the length unit). Half-plane ``w`` carries the constant of the
        unit-reference-length Flamant kernel (see module notes); the slab's
        ``w`` is absolute (-> 0 far away).

    Notes
    -----
    Half-plane: ``w = (2/pi)[2s - (x+s) ln|x+s| + (x-s) ln|x-s|]``,
    ``u = -beta (|x+s| - |x-s|)``, ``du = -beta (sgn(x+s) - sgn(x-s))``
    (``-beta`` at ``x = +-s``). Slab: half-plane plus the remainders of the
    module notes.

    Examples
    --------
    >>> w, u, du = pressure_strip([0.0, 2.0], 1.0, 0.3)
    >>> [round(float(v), 12) for v in u] == [0.0, round(-2 * 0.2857142857142857, 12)]
    True
    """
    return _evaluate("pressure", x, s, nu, h, base)


def shear_strip(
    x: ArrayLike, s: ArrayLike, nu: float, h: float = np.inf, base: str = "smooth"
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Surface displacements under an outward unit shear on ``|x'| < s``.

    The traction on the body is +1 (in +x) on ``0 < x' < s`` and -1 on
    ``-s < x' < 0``.

    Parameters
    ----------
    x : array_like
        Surface point (any real).
    s : array_like
        Half-width of the loaded strip (>= 0); ``s = 0`` gives zeros.
    nu : float
        Poisson's ratio, -1 < nu <= 0.5.
    h : float, optional
        Layer thickness on a rigid base; ``np.inf`` is the half-plane.
    base : {"smooth", "bonded"} or Substrate, optional
        The rigid base: frictionless (default) or bonded; or an elastic
        substrate bonded to the layer (a coated body, module notes).

    Returns
    -------
    w, u, du : ndarray
        Normal displacement (into the body), tangential displacement (+x) and
        ``du/dx`` for unit shear and E* = 1. ``u`` is odd in ``x`` (no free
        constant); ``du`` is ``+inf`` at ``x = 0`` and ``-inf`` at ``x = +-s``
        (integrable logarithmic singularities).

    Notes
    -----
    Half-plane: ``u = (2/pi)[(x+s) ln|x+s| + (x-s) ln|x-s| - 2x ln|x|]``,
    ``du = (2/pi) ln|1 - s^2/x^2|``, ``w = -2 beta max(s - |x|, 0)``.

    Examples
    --------
    >>> w, u, du = shear_strip(1e4, 1.0, 0.3)    # far field: u ~ (2/pi) s^2/x
    >>> abs(float(u) / (2 / 3.141592653589793 * 1e-4) - 1) < 1e-8
    True
    """
    return _evaluate("shear", x, s, nu, h, base)


def _hp_axis_w_pressure(t: Arr) -> Arr:
    """(pi/2) [w(x) - w(0)] / s of the half-plane pressure strip, t = |x|/s, no cancellation.

    -(1+t) ln(1+t) + (t-1) ln|t-1|, as -log1p(-t^2) - 2 t artanh(t) for t < 1/2,
    as written for 1/2 <= t < 2, and as -ln(t^2-1) - t log1p(2/(t-1)) for t >= 2.
    """
    out = np.empty(t.shape)
    small = t < 0.5
    big = t >= 2.0
    mid = ~(small | big)
    ts = t[small]
    out[small] = -np.log1p(-ts * ts) - 2.0 * ts * np.arctanh(ts)
    tm = t[mid]
    with np.errstate(divide="ignore", invalid="ignore"):
        gap = np.abs(tm - 1.0)
        out[mid] = -(1.0 + tm) * np.log1p(tm) + np.where(
            gap > 0.0, np.sign(tm - 1.0) * gap * np.log(np.where(gap > 0.0, gap, 1.0)), 0.0)
    tb = t[big]
    out[big] = -np.log((tb - 1.0) * (tb + 1.0)) - tb * np.log1p(2.0 / (tb - 1.0))
    return out


def axis_w_strip(x: ArrayLike, s: ArrayLike, nu: float, part: str, h: float = np.inf,
                 base: str = "smooth") -> tuple[Arr, Arr, Arr]:
    """w(x; s) - w(0; s): the normal displacement relative to the centre, without cancellation.

    Parameters
    ----------
    x, s : array_like
        Surface point and strip half-width (>= 0), broadcast.
    nu : float
        Poisson's ratio.
    part : {"normal", "shear"}
        :func:`pressure_strip` or :func:`shear_strip`.
    h, base :
        As :func:`pressure_strip`.

    Returns
    -------
    dw, zero, zero : ndarray
        w(x) - w(0) (into the body, E* = 1, length units) and two zero arrays
        (the kernel triple of :func:`contactlib.discretization.influence.element_integrals`).

    Notes
    -----
    Near the centre (|x| << s) w(x) - w(0) is O(x^2/s) while w is O(s ln s):
    the difference of the closed forms loses every digit below ~1e-16 s.
    Half-plane, pressure: (2/pi) s [-(1+t) ln(1+t) + (t-1) ln|t-1|], t = |x|/s,
    in the forms of ``_hp_axis_w_pressure`` (relative error ~1e-16); shear:
    2 beta min(|x|, s) exactly. A slab adds the difference of its remainder
    (the slab minus the half-plane) at x and at 0: for x <= 1e-3 h as the
    integral of the remainder's slope over [0, x] (:func:`_remainder_axis_w`;
    relative accuracy ~1e-4 of that part at x = 1e-8, which is itself ~1e-3 of
    w(x) - w(0) there), beyond formed directly (its absolute round-off, ~1e-16
    s, is then small against the difference). Formed directly everywhere, as
    before, the slab's c/a = 1e-8 lost the whole remainder part.

    Examples
    --------
    >>> dw, _, _ = axis_w_strip(1e-8, 1.0, 0.3, "normal")   # -(2/pi) x^2/s
    >>> abs(float(dw) + 2.0 / np.pi * 1e-16) < 1e-30
    True
    """
    xa = np.abs(np.asarray(x, dtype=float))
    sa = np.asarray(s, dtype=float)
    xa, sa = np.broadcast_arrays(xa, sa)
    zero = np.zeros(xa.shape)
    if part == "shear":
        dw = 2.0 * _beta(nu) * np.minimum(xa, sa)
    elif part == "normal":
        with np.errstate(divide="ignore", invalid="ignore"):
            t = np.where(sa > 0.0, xa / np.where(sa > 0.0, sa, 1.0), 0.0)
        dw = (2.0 / np.pi) * sa * _hp_axis_w_pressure(t)
    else:
        raise ValueError(f"part must be 'normal' or 'shear', got {part!r}")
    dw = np.where(sa > 0.0, dw, 0.0)
    if np.isfinite(h):
        kind = "pressure" if part == "normal" else "shear"
        h = _validate(sa, nu, h, base)
        near = (xa <= _AXIS_SLOPE_UP_TO * h) & (sa > 0.0)  # (dw is a fresh array)
        if near.any():  # the remainder's difference as the integral of its slope
            tab = _table_of(base, nu)
            dw[near] += _remainder_axis_w(kind, xa[near], sa[near], h, tab)
        rest = ~near
        if rest.any():  # formed directly: its absolute round-off (~1e-16 s) stays
            xr, sr = xa[rest], sa[rest]
            rem_x = _evaluate(kind, xr, sr, nu, h, base)[0] - _evaluate(kind, xr, sr, nu, np.inf)[0]
            zx = np.zeros(xr.shape)
            rem_0 = _evaluate(kind, zx, sr, nu, h, base)[0] - _evaluate(kind, zx, sr, nu, np.inf)[0]
            dw[rest] += rem_x - rem_0
    return dw, zero, zero.copy()


# tested: tests/test_kernels_strip.py (axis_w_strip near the axis)
_AXIS_SLOPE_UP_TO = 1e-3  # x/h below which axis_w_strip integrates the remainder's slope
# tested: tests/test_kernels_strip.py (axis_w_strip near the axis)
_AXIS_SLOPE_POINTS = 8  # Gauss points on [0, x] (the slope is smooth on the scale h)


def _pair_slopes(kind: str, eta: Arr, tab: _SlabTable) -> tuple[Arr, Arr]:
    """d/d(eta) of both packed functions (F1, B1) at eta: (A or C, B), table or far field."""
    coef = tab.pres if kind == "pressure" else tab.shear
    idx, u, far = _locate(eta, tab.n_pieces)
    d = 5.0 * coef[5].take(idx)
    for k in (4, 3, 2, 1):
        d = d * u + k * coef[k].take(idx)
    d *= _INV_DELTA
    if far.any():
        _, _, f, b = _far_pair(kind, eta[far], tab)
        d[far] = f + 1j * b
    return d.real, d.imag


def _remainder_axis_w(kind: str, x: Arr, s: Arr, h: float, tab: _SlabTable) -> Arr:
    """w_R(x) - w_R(0) of the slab's remainder, as the integral of its slope over [0, x].

    Pressure: w_R = h (A1(e+) - A1(e-)) + const, e+- = (x +- s)/h, slope A(e+) - A(e-);
    shear: w_R = h (B1(e+) + B1(e-) - 2 B1(x/h)), slope B(e+) + B(e-) - 2 B(x/h). The
    slope vanishes at x = 0 and is smooth on the scale h, so an 8-point Gauss rule on
    [0, x] (x <= 1e-3 h) keeps the relative accuracy of O(x^2 / h) that the difference of
    the remainders at x and 0 (each O(s)) loses to round-off as x -> 0.
    """
    t, w = np.polynomial.legendre.leggauss(_AXIS_SLOPE_POINTS)
    pts = 0.5 * (t[:, None] + 1.0) * x[None, :]  # (points, cases)
    ss = np.broadcast_to(s, pts.shape)
    inv_h = 1.0 / h
    if kind == "pressure":
        slope = (_pair_slopes(kind, ((pts + ss) * inv_h).ravel(), tab)[0]
                 - _pair_slopes(kind, ((pts - ss) * inv_h).ravel(), tab)[0])
    else:
        slope = (_pair_slopes(kind, ((pts + ss) * inv_h).ravel(), tab)[1]
                 + _pair_slopes(kind, ((pts - ss) * inv_h).ravel(), tab)[1]
                 - 2.0 * _pair_slopes(kind, (pts * inv_h).ravel(), tab)[1])
    return 0.5 * x * (w @ slope.reshape(pts.shape))


def _f_difference(a: Arr, b: Arr, d: Arr) -> Arr:
    """F(a) - F(b), F(t) = t ln|t|, with d = a - b given exactly; no cancellation where a, b
    have one sign (else the plain difference: both within |d| of 0, both small)."""
    out = np.empty(a.shape)
    same = (a * b > 0.0)
    asame, bsame, dsame = a[same], b[same], d[same]
    out[same] = dsame * np.log(np.abs(asame)) + bsame * np.log1p(dsame / bsame)
    other = ~same
    with np.errstate(divide="ignore", invalid="ignore"):
        fa = np.where(a[other] != 0.0, a[other] * np.log(np.abs(np.where(a[other] != 0.0,
                                                                          a[other], 1.0))), 0.0)
        fb = np.where(b[other] != 0.0, b[other] * np.log(np.abs(np.where(b[other] != 0.0,
                                                                          b[other], 1.0))), 0.0)
    out[other] = fa - fb
    return out


def w_difference_strip(x: ArrayLike, x0: float, s: ArrayLike, nu: float, part: str,
                       h: float = np.inf, base: str = "smooth") -> tuple[Arr, Arr, Arr]:
    """w(x; s) - w(x0; s) of the strip load of ``part``, without cancellation.

    Parameters
    ----------
    x, s : array_like
        Surface points (their absolute values are used) and strip
        half-widths (>= 0), broadcast.
    x0 : float
        The reference point (>= 0); 0 gives :func:`axis_w_strip`.
    nu, part, h, base :
        As :func:`axis_w_strip`.

    Returns
    -------
    dw, zero, zero : ndarray
        As :func:`axis_w_strip`.

    Notes
    -----
    Half-plane, pressure: (2/pi)[-(F(x+s) - F(x0+s)) + F(x-s) - F(x0-s)],
    each difference of F(t) = t ln|t| as (a - b) ln|a| + b log1p((a - b)/b)
    with a - b = x - x0 (no cancellation where a and b have one sign); shear:
    2 beta (min(x, s) - min(x0, s)). A slab's remainder is differenced
    directly (its absolute round-off, ~1e-16 s, stays).
    """
    if x0 == 0.0:
        return axis_w_strip(x, s, nu, part, h, base)
    xa = np.abs(np.asarray(x, dtype=float))
    sa = np.asarray(s, dtype=float)
    xa, sa = np.broadcast_arrays(xa, sa)
    zero = np.zeros(xa.shape)
    d = xa - x0
    if part == "shear":
        dw = 2.0 * _beta(nu) * (np.minimum(xa, sa) - np.minimum(x0, sa))
    elif part == "normal":
        dw = (2.0 / np.pi) * (_f_difference(xa - sa, x0 - sa, d)
                              - _f_difference(xa + sa, x0 + sa, d))
    else:
        raise ValueError(f"part must be 'normal' or 'shear', got {part!r}")
    dw = np.where(sa > 0.0, dw, 0.0)
    if np.isfinite(h):
        kind = "pressure" if part == "normal" else "shear"
        ref = np.full(xa.shape, float(x0))
        rem_x = _evaluate(kind, xa, sa, nu, h, base)[0] - _evaluate(kind, xa, sa, nu, np.inf)[0]
        rem_0 = _evaluate(kind, ref, sa, nu, h, base)[0] - _evaluate(kind, ref, sa, nu, np.inf)[0]
        dw = dw + (rem_x - rem_0)
    return dw, zero, zero.copy()
