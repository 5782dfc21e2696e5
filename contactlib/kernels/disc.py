"""Surface displacements of an elastic half-space under axisymmetric disc loads.

Closed forms of the paper's Appendix, rewritten so that every removable
singularity is evaluated stably. Units: E* = E/(1 - nu^2) = 1, lengths in any
unit (the caller uses the contact radius a = 1). Conventions:

* ``w`` normal surface displacement, positive INTO the body (the direction of a
  compressive pressure);
* ``u`` radial surface displacement, positive away from the axis;
* ``beta = (1 - 2 nu) / (2 (1 - nu))``, so that (1-2nu)(1+nu)/(2E) = beta/E*.

Two loadings, each on a disc of radius ``s``:

``pressure_disc``
    uniform unit pressure p = 1 (compressive) on r < s.
``shear_disc``
    linear radial shear q = r (outward, "q0 r" with q0 = 1) on r < s.

The Appendix gives the normal displacement under outward shear with a plus
sign; Betti's reciprocal theorem (work of the pressure on the shear's ``w``
equals the work of the shear on the pressure's ``u``) fixes it as negative in
the convention above: outward shear lifts the surface inside the disc. The
test-suite checks this sign and every other one against direct integration of
the Boussinesq and Cerruti point-load solutions.

Stable evaluation: parameters m = r^2/s^2 (inside) and m' = s^2/r^2 (outside)
lie in [0, 1]. Near m -> 1 the factor (1-m) K(m) -> 0 is taken as 0 exactly at
m = 1. Near m -> 0 (r -> 0 inside, r >> s outside) the closed forms cancel to
leading order; there power series of K and E are summed instead.
"""

from __future__ import annotations

import numpy as np
from scipy import special

from ..theory import beta_of_nu

__all__ = ["beta_of_nu", "pressure_disc", "shear_disc"]

_SERIES_SWITCH = 0.25  # use power series for parameters below this
_NTERMS = 30  # 0.25**30 ~ 1e-18

# Power-series coefficients: K(m) = pi/2 sum k_n m^n, E(m) = pi/2 sum e_n m^n.
_n = np.arange(_NTERMS + 3)
_k = np.ones(_n.size)
for _i in range(1, _n.size):
    _k[_i] = _k[_i - 1] * ((2 * _i - 1) / (2 * _i)) ** 2
_e = _k / (1.0 - 2.0 * _n)


def _series(coef: np.ndarray, m: np.ndarray) -> np.ndarray:
    """Evaluate sum coef[j] m^j by Horner's rule."""
    out = np.zeros_like(m)
    for c in coef[::-1]:
        out = out * m + c
    return out


def _ke(m: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """K(m), E(m) and (1-m) K(m), finite at m = 1."""
    m = np.clip(m, 0.0, 1.0)
    k = special.ellipk(m)
    e = special.ellipe(m)
    one_minus = 1.0 - m
    with np.errstate(invalid="ignore"):
        omk = np.where(one_minus > 0.0, one_minus * k, 0.0)
    return k, e, omk


# --- series coefficients of the cancelling combinations (all times pi/2) ---
# A(m) = E - (1-m) K            = sum (e_n - k_n + k_{n-1}) m^n
_cA = _e[:_NTERMS] - _k[:_NTERMS] + np.concatenate([[0.0], _k[: _NTERMS - 1]])
# g(m) = (2m-1) E - (m-1) K      = sum (2 e_{n-1} - e_n - k_{n-1} + k_n) m^n
_km1 = np.concatenate([[0.0], _k[: _NTERMS - 1]])
_em1 = np.concatenate([[0.0], _e[: _NTERMS - 1]])
_cg = 2 * _em1 - _e[:_NTERMS] - _km1 + _k[:_NTERMS]
# gd(m) = (4m+1) E - (2m+1) K    = sum (4 e_{n-1} + e_n - 2 k_{n-1} - k_n) m^n
_cgd = 4 * _em1 + _e[:_NTERMS] - 2 * _km1 - _k[:_NTERMS]
# h(m') = (2/m' - 1) E - 2 (1/m' - 1) K = sum (2 e_{n+1} - e_n - 2 k_{n+1} + 2 k_n) m'^n
_ch = 2 * _e[1 : _NTERMS + 1] - _e[:_NTERMS] - 2 * _k[1 : _NTERMS + 1] + 2 * _k[:_NTERMS]
# hd(m') = 2 (K - E) - m' (E + K)/2 = sum (2 k_n - 2 e_n - (e_{n-1} + k_{n-1})/2) m'^n
_chd = 2 * _k[:_NTERMS] - 2 * _e[:_NTERMS] - 0.5 * (_em1 + _km1)


def _combo(m: np.ndarray, coef: np.ndarray, direct) -> np.ndarray:
    """pi/2 * series where m is small, else the closed form ``direct(K, E, (1-m)K, m)``."""
    small = m < _SERIES_SWITCH
    out = np.empty_like(m)
    if np.any(small):
        out[small] = 0.5 * np.pi * _series(coef, m[small])
    big = ~small
    if np.any(big):
        mb = m[big]
        k, e, omk = _ke(mb)
        out[big] = direct(k, e, omk, mb)
    return out


def _prepare(r, s):
    r = np.abs(np.asarray(r, dtype=float))
    s = np.asarray(s, dtype=float)
    r, s = np.broadcast_arrays(r, s)
    r = r.astype(float, copy=True)
    s = s.astype(float, copy=True)
    inside = r <= s
    positive = s > 0.0
    return r, s, inside, positive


def pressure_disc(r, s, nu: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Surface displacements under a uniform unit pressure on a disc.

    Parameters
    ----------
    r : array_like
        Radius of the surface point (>= 0).
    s : array_like
        Disc radius (>= 0); broadcast against ``r``. ``s = 0`` gives zeros.
    nu : float
        Poisson's ratio.

    Returns
    -------
    w, u, dudr : ndarray
        Normal displacement (into the body), radial displacement (outward)
        and its radial derivative, for p = 1 and E* = 1.

    Notes
    -----
    w = (4/pi) s E(r^2/s^2) for r <= s and
    w = (4/pi) r [E(s^2/r^2) - (1 - s^2/r^2) K(s^2/r^2)] for r >= s;
    u = -beta r (r <= s), -beta s^2/r (r >= s) (Johnson, Contact Mechanics, 3.19-3.21).

    Examples
    --------
    >>> w, u, du = pressure_disc(0.0, 1.0, 0.3)
    >>> round(float(w), 12) == round(2.0, 12)
    True
    """
    b = beta_of_nu(nu)
    r, s, inside, positive = _prepare(r, s)
    w = np.zeros_like(r)
    u = np.zeros_like(r)
    du = np.zeros_like(r)

    ii = inside & positive
    if np.any(ii):
        m = (r[ii] / s[ii]) ** 2
        w[ii] = (4.0 / np.pi) * s[ii] * special.ellipe(np.clip(m, 0.0, 1.0))
        u[ii] = -b * r[ii]
        du[ii] = -b
    oo = ~inside & positive
    if np.any(oo):
        mp = (s[oo] / r[oo]) ** 2
        a_val = _combo(mp, _cA, lambda k, e, omk, m: e - omk)
        w[oo] = (4.0 / np.pi) * r[oo] * a_val
        u[oo] = -b * s[oo] ** 2 / r[oo]
        du[oo] = b * mp
    return w, u, du


def shear_disc(r, s, nu: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Surface displacements under a linear radial shear q = r on a disc.

    Parameters
    ----------
    r : array_like
        Radius of the surface point (>= 0).
    s : array_like
        Disc radius (>= 0); ``s = 0`` gives zeros.
    nu : float
        Poisson's ratio.

    Returns
    -------
    w, u, dudr : ndarray
        Normal displacement (into the body), radial displacement (outward)
        and its radial derivative, for q(r) = r (q0 = 1, outward) on r < s
        and E* = 1.

    Notes
    -----
    With m = r^2/s^2 and m' = s^2/r^2:

    * u = (4/(3 pi)) s^3/r [(2m-1) E(m) - (m-1) K(m)] for r <= s,
      u = (4/(3 pi)) s^2 [(2/m'-1) E(m') - 2 (1/m'-1) K(m')] for r >= s;
    * du/dr = (4/(3 pi)) s^3/r^2 [(4m+1) E(m) - (2m+1) K(m)] inside,
      du/dr = -(8 r/(3 pi)) [2 (K - E) - m' (E + K)/2] outside
      (log-singular at r = s, integrable);
    * w = -beta (s^2 - r^2) for r < s and 0 outside (sign from Betti).

    Examples
    --------
    >>> w, u, du = shear_disc(1e-3, 1.0, 0.3)   # centre: u ~ s r
    >>> abs(float(u) - 1e-3) < 1e-9
    True
    """
    b = beta_of_nu(nu)
    r, s, inside, positive = _prepare(r, s)
    w = np.zeros_like(r)
    u = np.zeros_like(r)
    du = np.zeros_like(r)
    c = 4.0 / (3.0 * np.pi)

    ii = inside & positive
    if np.any(ii):
        ri, si = r[ii], s[ii]
        m = (ri / si) ** 2
        w[ii] = -b * (si**2 - ri**2)
        # u = c s^3/r g(m); g ~ (3 pi/4) m for small m -> use g(m)/m * m / r = g/m * r/s^2
        g_over_m = np.empty_like(m)
        small = m < _SERIES_SWITCH
        g_over_m[small] = 0.5 * np.pi * _series(_cg[1:], m[small])
        big = ~small
        if np.any(big):
            k, e, omk = _ke(m[big])
            g_over_m[big] = ((2 * m[big] - 1) * e + omk) / m[big]
        u[ii] = c * si * ri * g_over_m  # s^3/r * m = s r
        gd_over_m = np.empty_like(m)
        gd_over_m[small] = 0.5 * np.pi * _series(_cgd[1:], m[small])
        if np.any(big):
            gd_over_m[big] = ((4 * m[big] + 1) * e - (2 * m[big] + 1) * k) / m[big]
        du[ii] = c * si * gd_over_m  # s^3/r^2 * m = s
    oo = ~inside & positive
    if np.any(oo):
        ro, so = r[oo], s[oo]
        mp = (so / ro) ** 2
        h_val = _combo(mp, _ch, lambda k, e, omk, m: (2.0 / m - 1.0) * e - 2.0 * omk / m)
        u[oo] = c * so**2 * h_val
        hd = _combo(mp, _chd, lambda k, e, omk, m: 2.0 * (k - e) - 0.5 * m * (e + k))
        du[oo] = -2.0 * c * ro * hd
    return w, u, du
