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

Stable evaluation
-----------------
With ``q = min(r, s)/max(r, s)`` the elliptic parameter is m = q^2 (m = r^2/s^2
inside, m' = s^2/r^2 outside) and ``m1 = 1 - m`` is formed as
``((max - min)/max)(1 + q)``, accurate to a few ulps even at r -> s. Every
output is a polynomial factor times one of six functions of m,

=====  =========================================  ===========================
name   function                                   used for
=====  =========================================  ===========================
E      E(m)                                       w, pressure, inside
A1     [E - (1-m) K] / m                          w, pressure, outside
g1     [(2m-1) E + (1-m) K] / m                   u, shear, inside
gd1    [(4m+1) E - (2m+1) K] / m                  du/dr, shear, inside
h1     [(2-m) E - 2 (1-m) K] / m^2                u, shear, outside
hd2    [2 (K - E) - m (E + K)/2] / m^2            du/dr, shear, outside
=====  =========================================  ===========================

each finite at m = 0 (the removable singularities r -> 0 inside and r >> s
outside are divided out analytically, so nothing cancels there), and each is
evaluated as ``P(m1) + ln(m1) R(m1)`` with P and R polynomials of degree 10
(the Cephes form of K and E, fitted here to the combinations themselves). The
first two coefficients of R are the exact ones (so the logarithmic behaviour at
r -> s is exact); the rest come from a weighted least-squares fit to mpmath
values on 0 <= m1 <= 1 (``tests/test_kernels_disc.py`` regenerates them). Error
against mpmath: <= 4e-16 relative for E, A1, g1, gd1 (gd1 relative to its
scale, it has a zero), <= 4e-15 for h1, hd2 (their P and R cancel mildly).
At r = s exactly (m1 = 0) the logarithm is clamped (the R of E, A1, g1, h1
vanish there) and du/dr of the shear is set to its limit -inf.

Cost: ~60 (pressure) and ~110 (shear) array operations a point, in passes of
``_CHUNK`` points over per-thread scratch rows (no large temporaries); the
three outputs of a call share one allocation. Points inside (r <= s) and
outside the disc use different functions: they are evaluated on slices when
they come in two runs (as :func:`contactlib.discretization.influence.element_integrals`
orders them), on gathered copies otherwise.
"""

from __future__ import annotations

import threading

import numpy as np


try:  # the compiled route (setup.py; optional): the same bits, about five times faster
    from . import disc_fused as _fused
except ImportError:  # pragma: no cover - a build without a C compiler
    _fused = None

__all__ = ["beta_of_nu", "pressure_disc", "shear_disc", "axis_w_disc", "w_difference_disc"]


def beta_of_nu(nu: float) -> float:
    """Dundurs-type coupling beta = (1 - 2 nu) / (2 (1 - nu)) for a rigid indenter
    (defined here, with the closed forms that use it; :mod:`contactlib.model.theory` shows it)."""
    return (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu))


_C_W = 4.0 / np.pi  # w of the pressure: (4/pi) s E(m) inside, (4/pi) r A(m') outside
_C_SHEAR = 4.0 / (3.0 * np.pi)
_TINY = np.finfo(float).tiny  # ln(m1) clamp at m1 = 0 (r = s exactly)

# f(m) = P(m1) + ln(m1) R(m1), coefficients from low to high degree: (P, R).
# tested: tests/test_kernels_disc.py (regenerated with mpmath; the fits within 4e-15)
_FITS: dict[str, tuple[tuple[float, ...], tuple[float, ...]]] = {
    "E": (
        (1.0, 0.4431471805600135, 0.056805193631284744, 0.021831679422434032,
         0.011565046862782905, 0.00754757716672129, 0.007669021179375873, 0.010697788965526922,
         0.008800209907066805, 0.002573701428435828, 0.0001589276712547053),
        (0.0, -0.25, -0.09374999987402521, -0.05859369068700235, -0.04271928395505989,
         -0.03350035178930291, -0.02626604027006308, -0.017065033264807006,
         -0.0066370961520413885, -0.0010390329778296676, -3.3987365717190986e-05),
    ),
    "A1": (
        (1.0, 0.056852819438829943, 0.0170844060909396, 0.008025538263377884,
         0.004307470814746232, -0.003379772156793018, -0.04187715096985971, -0.11268583653589562,
         -0.10807642386552938, -0.032813557855938, -0.0020393298264295995),
        (0.0, 0.25, 0.2812499978311604, 0.29296776331074365, 0.2989860801549697,
         0.3005071155904735, 0.2819504230192695, 0.20399169872474243, 0.08340551422505572,
         0.013291864285983062, 0.00043597500947851553),
    ),
    "g1": (
        (1.0, 0.8294415416808093, 0.09652597721724046, 0.035636820322899436,
         0.018774639749944238, 0.01784508080402184, 0.05480089594843462, 0.1324566165678612,
         0.12825415523476097, 0.03991192866177784, 0.002546834004594996),
        (0.0, -0.75, -0.4687499981392596, -0.41015534742648063, -0.38443821066888656,
         -0.36776933027316794, -0.33622042149095627, -0.242350571793075, -0.10032354136837669,
         -0.016311077771698893, -0.0005471188955592048),
    ),
    "gd1": (
        (0.8411169166403284, 1.5397207708361733, 0.15164972736688154, 0.05053532442049998,
         0.02408581027621214, 0.007048925254088731, -0.035622261493159585, -0.10114291557361126,
         -0.092730255072103, -0.026863389119723628, -0.0016041633432416268),
        (1.5, -0.375, 0.11718749545033083, 0.20507651369806296, 0.24020861939764887,
         0.2563361930391558, 0.2455733050894259, 0.17570969747557785, 0.06972819057452116,
         0.010732150880702122, 0.0003407237152412662),
    ),
    "h1": (
        (1.0000000000000002, 0.6705584582983655, 0.6479218342684567, 0.6420641735547504,
         0.6342563628719063, 0.5301122511775552, -0.11501526293996574, -1.380959361624736,
         -1.5275748636184039, -0.48196781082143453, -0.03034715861840742),
        (0.0, 0.75, 1.4062499621065245, 2.0507642456507456, 2.6901787595382567,
         3.291749571488372, 3.5706142319261316, 2.8221555000999734, 1.2066523191125256,
         0.19628467896382787, 0.00649512213911845),
    ),
    "hd2": (
        (-0.4205584583201669, -0.6109773020024469, -0.6272204982316664, -0.6316510861571186,
         -0.625773351825386, -0.49599686785117364, 0.25377147920522436, 1.5979581992776566,
         1.631444116103068, 0.4885671917058501, 0.02948520064424518),
        (-0.75, -1.3125, -1.9335936750920706, -2.5634485519105423, -3.194202940183672,
         -3.779013422767144, -3.9781924112065385, -3.038460311528032, -1.251167980496229,
         -0.1960757553274723, -0.006265890062533288),
    ),
}


# Horner coefficient stacks, highest degree first, shaped (degree + 1, rows, 1):
# rows (P, R) of each function, so that one pass evaluates several polynomials.
def _stack(*names: str) -> np.ndarray:
    rows = [c for name in names for c in _FITS[name]]
    return np.array(rows, dtype=float).T[::-1, :, None].copy()


_STACKS = {"pressure": (_stack("E"), _stack("A1")),
           "shear": (_stack("g1", "gd1"), _stack("h1", "hd2")),
           "shear_u": (_stack("g1"), _stack("h1"))}

# convention: scratch size, the results do not depend on it (kernel speed:
# benchmarks/bench_kernels.py)
_CHUNK = 32768  # points per pass: scratch rows stay small and are reused


class _Scratch(threading.local):
    """Per-thread scratch rows of _CHUNK doubles, allocated once and reused.

    Fresh temporaries of a few hundred kB are slow where the allocator hands
    memory back to the system after every call (page faults on each reuse).
    """

    def __init__(self) -> None:
        self.f = np.empty((14, _CHUNK))
        self.inside = np.empty(_CHUNK, dtype=bool)
        self.flag = np.empty(_CHUNK, dtype=bool)


_SCRATCH = _Scratch()


def _horner(stack: np.ndarray, x: np.ndarray, out: np.ndarray) -> np.ndarray:
    """out[i] = sum_j stack[-1-j, i] x^j for every row i, in place."""
    np.multiply(stack[0], x, out=out)
    out += stack[1]
    for c in stack[2:]:
        out *= x
        out += c
    return out


def _log_form(stack: np.ndarray, m1: np.ndarray, lg: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """Rows 0, 2, ... of ``rows`` become P + ln(m1) R of each stacked function."""
    _horner(stack, m1, rows)
    for i in range(0, rows.shape[0], 2):
        rows[i + 1] *= lg
        rows[i] += rows[i + 1]
    return rows


def _flat(r, s):
    """r and s broadcast, as 1-d contiguous float arrays (no copy when already so)."""
    r = np.asarray(r, dtype=float)
    s = np.asarray(s, dtype=float)
    shape = np.broadcast_shapes(r.shape, s.shape)
    r = np.ascontiguousarray(np.broadcast_to(r, shape)).reshape(-1)
    s = np.ascontiguousarray(np.broadcast_to(s, shape)).reshape(-1)
    if s.size and not s.min() > 0.0:  # s <= 0 (or NaN): zero output, computed harmlessly
        bad = ~(s > 0.0)
        s = np.where(bad, 1.0, s)
        r = np.where(bad, 0.0, r)
        return r, s, shape, bad
    return r, s, shape, None


def _params(r: np.ndarray, s: np.ndarray, f: np.ndarray, inside: np.ndarray):
    """|r|, q = min/max, m1 = 1 - q^2 (accurate near q = 1), ln(m1) clamped; inside = |r| <= s.

    Uses scratch rows f[0:6]; returns (ra, q, m1, lg).
    """
    ra, big, onep, q, m1, lg = f[:6]
    np.abs(r, out=ra)
    np.less_equal(ra, s, out=inside)
    np.maximum(ra, s, out=big)
    np.minimum(ra, s, out=onep)
    np.divide(onep, big, out=q)
    np.subtract(big, onep, out=m1)  # exact when min >= max/2
    m1 /= big
    np.add(q, 1.0, out=onep)
    m1 *= onep  # (1 - q)(1 + q)
    np.maximum(m1, _TINY, out=lg)
    np.log(lg, out=lg)
    return ra, q, m1, lg


def _sides(inside: np.ndarray):
    """Selections (slice or index array; None if empty) of the points inside and outside."""
    k = inside.size
    n_in = int(np.count_nonzero(inside))
    if n_in == k:
        return slice(0, k), None
    if n_in == 0:
        return None, slice(0, k)
    if inside[:n_in].all():  # inside points first (as element_integrals orders them)
        return slice(0, n_in), slice(n_in, k)
    if inside[k - n_in:].all():
        return slice(k - n_in, k), slice(0, k - n_in)
    return np.flatnonzero(inside), np.flatnonzero(~inside)


def _get(a: np.ndarray, sel, buf: np.ndarray) -> np.ndarray:
    """a[sel]: a view for a slice (read only!), else gathered into buf."""
    if isinstance(sel, slice):
        return a[sel]
    return np.take(a, sel, out=buf[: sel.size])


def _scaled(a: np.ndarray, sel, c: float, buf: np.ndarray) -> np.ndarray:
    """c * a[sel] in buf (never writes to a)."""
    if isinstance(sel, slice):
        return np.multiply(a[sel], c, out=buf[: sel.stop - sel.start])
    out = np.take(a, sel, out=buf[: sel.size])
    out *= c
    return out


def _pressure_chunk_no_w(r, s, b, w, u, du, ws):
    """u and du/dr only (w left at 0): closed forms, no elliptic integrals."""
    k = r.size
    f = ws.f[:, :k]
    inside = ws.inside[:k]
    ra, big, onep, q = f[:4]
    np.abs(r, out=ra)
    np.less_equal(ra, s, out=inside)
    np.maximum(ra, s, out=big)
    np.minimum(ra, s, out=onep)
    np.divide(onep, big, out=q)
    np.multiply(s, q, out=u)  # r inside, s^2/r outside
    u *= -b
    np.multiply(q, q, out=du)  # m' outside
    du *= b
    du[inside] = -b
    w[:] = 0.0


def _pressure_chunk(r, s, b, w, u, du, ws):
    k = r.size
    f = ws.f[:, :k]
    inside = ws.inside[:k]
    ra, q, m1, lg = _params(r, s, f, inside)
    np.multiply(s, q, out=u)  # r inside, s^2/r outside
    u *= -b
    np.multiply(q, q, out=du)  # m' outside
    du *= b
    stack_in, stack_out = _STACKS["pressure"]
    sel_in, sel_out = _sides(inside)
    if sel_in is not None:
        m1s, lgs = _get(m1, sel_in, f[6]), _get(lg, sel_in, f[7])
        rows = _log_form(stack_in, m1s, lgs, f[10:12, : m1s.size])
        val = rows[0]
        val *= _get(s, sel_in, f[8])
        val *= _C_W  # (4/pi) s E(m)
        w[sel_in] = val
        du[sel_in] = -b
    if sel_out is not None:
        m1s, lgs = _get(m1, sel_out, f[6]), _get(lg, sel_out, f[7])
        rows = _log_form(stack_out, m1s, lgs, f[10:12, : m1s.size])
        val = rows[0]
        qs = _get(q, sel_out, f[8])
        val *= qs
        val *= qs
        val *= _get(ra, sel_out, f[9])
        val *= _C_W  # (4/pi) r m' A1(m')
        w[sel_out] = val


def _shear_chunk(r, s, b, w, u, du, ws, with_du: bool = True):
    k = r.size
    f = ws.f[:, :k]
    inside = ws.inside[:k]
    ra, q, m1, lg = _params(r, s, f, inside)
    np.multiply(ra, ra, out=w)
    np.multiply(s, s, out=f[6])
    w -= f[6]
    np.minimum(w, 0.0, out=w)
    w *= b  # -beta (s^2 - r^2) inside, 0 outside
    stack_in, stack_out = _STACKS["shear" if with_du else "shear_u"]
    nrows = 4 if with_du else 2
    sel_in, sel_out = _sides(inside)
    if sel_in is not None:
        m1s, lgs = _get(m1, sel_in, f[6]), _get(lg, sel_in, f[7])
        rows = _log_form(stack_in, m1s, lgs, f[10:10 + nrows, : m1s.size])
        cs = _scaled(s, sel_in, _C_SHEAR, f[8])
        g = rows[0]
        if with_du:
            gd = rows[2]
            gd *= cs  # du = c s^3/r^2 gd(m) = c s gd(m)/m
            du[sel_in] = gd
        g *= cs
        g *= _get(ra, sel_in, f[9])  # u = c s^3/r g(m) = c s r g(m)/m
        u[sel_in] = g
    if sel_out is not None:
        m1s, lgs = _get(m1, sel_out, f[6]), _get(lg, sel_out, f[7])
        rows = _log_form(stack_out, m1s, lgs, f[10:10 + nrows, : m1s.size])
        h, mq = rows[0], rows[1]  # row 1 (R of h1) is free now
        qs = _get(q, sel_out, f[8])
        np.multiply(qs, qs, out=mq)  # m'
        h *= mq
        cs = _scaled(s, sel_out, _C_SHEAR, f[9])
        h *= cs
        h *= _get(s, sel_out, f[8])  # (qs no longer needed)
        u[sel_out] = h  # u = c s^2 h(m') = c s^2 m' h1
        if with_du:
            hd = rows[2]
            mq *= mq
            hd *= mq
            hd *= _get(ra, sel_out, f[9])  # (cs no longer needed)
            hd *= -2.0 * _C_SHEAR
            du[sel_out] = hd  # du = -2 c r hd(m') = -2 c r m'^2 hd2
    if not with_du:
        du[:] = np.nan
        return
    zero = np.equal(m1, 0.0, out=ws.flag[:k])
    if zero.any():  # r = s exactly: du/dr is log-infinite
        du[zero] = -np.inf


def _shear_chunk_u(r, s, b, w, u, du, ws):
    """w and u only (du/dr left NaN): half the polynomial work."""
    _shear_chunk(r, s, b, w, u, du, ws, with_du=False)


def _fused_chunk(kind: str):
    """A chunk function of the compiled route (:data:`FUSED`): m1 there, ln(max(m1, tiny))
    by numpy (as :func:`_params` takes it), the rest there; the same bits as the numpy
    chunk function it replaces."""
    stack_in, stack_out = (np.ascontiguousarray(a[:, :, 0]) for a in _STACKS[kind])

    def chunk(r, s, b, w, u, du, ws):
        lg = ws.f[0, :r.size]
        _fused.m1(r, s, lg)
        np.maximum(lg, _TINY, out=lg)
        np.log(lg, out=lg)
        if kind == "pressure":
            _fused.pressure(r, s, lg, b, _C_W, stack_in, stack_out, w, u, du)
        else:
            _fused.shear(r, s, lg, b, _C_SHEAR, stack_in, stack_out, w, u, du,
                         kind == "shear")
    return chunk


# the numpy chunk functions the compiled route replaces, and their replacements
_FUSED_CHUNKS = {} if _fused is None else {
    _pressure_chunk: _fused_chunk("pressure"), _shear_chunk: _fused_chunk("shear"),
    _shear_chunk_u: _fused_chunk("shear_u")}
FUSED = _fused is not None
"""Whether the disc kernels (w of the pressure, everything of the shear) run compiled
(``contactlib/kernels/disc_fused.c``, built by ``pip install``): point by point the same
IEEE operations in the same order as the numpy chunk functions here, so the same bits
(``tests/test_kernels_fused.py``), about five times faster (``benchmarks/bench_kernels.py``).
Setting it to False selects the numpy route (e.g. to compare)."""


def _run(chunk_fn, r, s, nu):
    b = beta_of_nu(nu)
    r, s, shape, bad = _flat(r, s)
    out = np.empty((3, r.size))  # one block: a single allocation for the three outputs
    ws = _SCRATCH
    if FUSED:
        chunk_fn = _FUSED_CHUNKS.get(chunk_fn, chunk_fn)
    for a in range(0, r.size, _CHUNK):
        sl = slice(a, a + _CHUNK)
        chunk_fn(r[sl], s[sl], b, out[0, sl], out[1, sl], out[2, sl], ws)
    if bad is not None:
        out[:, bad] = 0.0
    return out[0].reshape(shape), out[1].reshape(shape), out[2].reshape(shape)


def pressure_disc(r, s, nu: float, *,
                  with_w: bool = True) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Surface displacements under a uniform unit pressure on a disc.

    Parameters
    ----------
    r : array_like
        Radius of the surface point (>= 0).
    s : array_like
        Disc radius (>= 0); broadcast against ``r``. ``s = 0`` gives zeros.
    nu : float
        Poisson's ratio.
    with_w : bool
        False: skip w (returned as zeros); u and du/dr are then closed forms
        without elliptic integrals (for tangential displacements only).

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
    return _run(_pressure_chunk if with_w else _pressure_chunk_no_w, r, s, nu)

def shear_disc(r, s, nu: float, *,
               with_du: bool = True) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Surface displacements under a linear radial shear q = r on a disc.

    Parameters
    ----------
    r : array_like
        Radius of the surface point (>= 0).
    s : array_like
        Disc radius (>= 0); ``s = 0`` gives zeros.
    nu : float
        Poisson's ratio.
    with_du : bool
        False: skip du/dr (returned as NaN), half the work (for u alone).

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
    return _run(_shear_chunk if with_du else _shear_chunk_u, r, s, nu)


# E(m) - pi/2 = (pi/2) sum_{n >= 1} a_n^2 m^n / (1 - 2n), a_n = (2n-1)!!/(2n)!!: the series
# coefficients of (E(m) - pi/2) / (pi/2), highest degree first, for Horner (m <= 1/2:
# 60 terms leave < 1e-19 of the first)
def _e_series(terms: int = 60) -> np.ndarray:
    a, out = 1.0, []
    for n in range(1, terms + 1):
        a *= (2.0 * n - 1.0) / (2.0 * n)
        out.append(a * a / (1.0 - 2.0 * n))
    return np.array(out[::-1])


_E_SERIES = _e_series()
# tested: tests/test_kernels_disc.py (the kernels against scipy's E and K)
_SERIES_M = 0.5  # below, the series; above, the fit of E minus pi/2 (cancels at most 7-fold)


def axis_w_disc(r, s, nu: float, part: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """w(r; s) - w(0; s): the normal displacement relative to the axis, without cancellation.

    Parameters
    ----------
    r, s : array_like
        Radius of the surface point and of the loaded disc (>= 0), broadcast.
    nu : float
        Poisson's ratio.
    part : {"normal", "shear"}
        The unit pressure on the disc (:func:`pressure_disc`) or the shear
        q = r (:func:`shear_disc`).

    Returns
    -------
    dw, zero, zero : ndarray
        w(r) - w(0) (into the body, E* = 1, units of length) and two zero
        arrays (the kernel triple of :func:`contactlib.discretization.influence.element_integrals`).

    Notes
    -----
    At a point near the axis (r << s) w(r) - w(0) is O(r^2/s), while w itself is
    O(s): the difference of the two closed forms loses all digits below about
    1e-16 s, which is the whole signal of a stick zone of c/a = 1e-8. Here,
    pressure, r <= s: 2 s (2/pi)(E(m) - pi/2), m = r^2/s^2, from the
    hypergeometric series for m <= 1/2 (relative error ~1e-16) and from the
    fit of E beyond (w(r) and 2 s differ by at least 14 %); r > s: w - 2 s
    (no cancellation, w <= (4/pi) s). Shear: beta min(r, s)^2 exactly.

    Examples
    --------
    >>> dw, _, _ = axis_w_disc(1e-8, 1.0, 0.3, "normal")   # -(r^2/2)/s, to 1e-16
    >>> abs(float(dw) + 0.5e-16) < 1e-30
    True
    """
    ra = np.abs(np.asarray(r, dtype=float))
    sa = np.asarray(s, dtype=float)
    ra, sa = np.broadcast_arrays(ra, sa)
    zero = np.zeros(ra.shape)
    if part == "shear":
        return beta_of_nu(nu) * np.minimum(ra, sa) ** 2, zero, zero.copy()
    if part != "normal":
        raise ValueError(f"part must be 'normal' or 'shear', got {part!r}")
    dw = np.empty(ra.shape)
    with np.errstate(divide="ignore", invalid="ignore"):
        m = np.where(sa > 0.0, (ra / np.where(sa > 0.0, sa, 1.0)) ** 2, np.inf)
    series = m <= _SERIES_M
    if series.any():
        ms = m[series]
        dw[series] = 2.0 * sa[series] * ms * np.polyval(_E_SERIES, ms)
    rest = ~series
    if rest.any():
        w = pressure_disc(ra[rest], sa[rest], nu)[0]
        dw[rest] = w - 2.0 * sa[rest]
    dw[~(sa > 0.0)] = 0.0
    return dw, zero, zero.copy()


# Gauss-Legendre rules on [0, 1] for an integrand with a log singularity at least
# ``gap`` interval lengths away (error ~ rho^(-2n), rho = 2 gap + 1 + sqrt((2 gap + 1)^2 - 1)
# for gap measured from the interval's end): (smallest gap, points), below 1e-18 each.
GAUSS_TIERS = tuple((gap, tuple(0.5 * (v + 1.0) if i == 0 else 0.5 * v
                                for i, v in enumerate(np.polynomial.legendre.leggauss(p))))
                    for gap, p in ((8.0, 6), (2.0, 10), (1.0, 16)))


def gauss_tiers(gap: np.ndarray, length: np.ndarray):
    """(mask, nodes, weights) for each tier of :data:`GAUSS_TIERS` (gap in units of length)."""
    ratio = np.where(length > 0.0, gap / np.where(length > 0.0, length, 1.0), np.inf)
    taken = np.zeros(gap.shape, dtype=bool)
    for lo, (t, w) in GAUSS_TIERS:
        mask = (ratio >= lo) & ~taken
        taken |= mask
        yield mask, t, w


# The complete elliptic integrals E(m) and K(m) as scipy.special evaluates them
# (``ellipe(m)``, ``ellipkm1(1 - m)``): the Cephes forms of S. L. Moshier (ellpe.c,
# ellpk.c), P(x) - ln(x) x Q(x) and P(x) - ln(x) Q(x) in x = 1 - m, with their
# coefficients (highest degree first), evaluated here on whole arrays. numpy's logarithm
# may differ from the C library's by one ulp, so the values agree with scipy to a few ulp
# (bit for bit at almost every point).
# exact: Cephes' published coefficients (ellpe.c)
_ELLPE_P = (1.53552577301013293365e-4, 2.50888492163602060990e-3, 8.68786816565889628429e-3,
            1.07350949056076193403e-2, 7.77395492516787092951e-3, 7.58395289413514708519e-3,
            1.15688436810574127319e-2, 2.18317996015557253103e-2, 5.68051945617860553470e-2,
            4.43147180560990850618e-1, 1.00000000000000000299e0)
# exact: Cephes' published coefficients (ellpe.c)
_ELLPE_Q = (3.27954898576485872656e-5, 1.00962792679356715133e-3, 6.50609489976927491433e-3,
            1.68862163993311317300e-2, 2.61769742454493659583e-2, 3.34833904888224918614e-2,
            4.27180926518931511717e-2, 5.85936634471101055642e-2, 9.37499997197644278445e-2,
            2.49999999999888314361e-1)
# exact: Cephes' published coefficients (ellpk.c)
_ELLPK_P = (1.37982864606273237150e-4, 2.28025724005875567385e-3, 7.97404013220415179367e-3,
            9.85821379021226008714e-3, 6.87489687449949877925e-3, 6.18901033637687613229e-3,
            8.79078273952743772254e-3, 1.49380448916805252718e-2, 3.08851465246711995998e-2,
            9.65735902811690126535e-2, 1.38629436111989062502e0)
# exact: Cephes' published coefficients (ellpk.c)
_ELLPK_Q = (2.94078955048598507511e-5, 9.14184723865917226571e-4, 5.94058303753167793257e-3,
            1.54850516649762399335e-2, 2.39089602715924892727e-2, 3.01204715227604046988e-2,
            3.73774314173823228969e-2, 4.88280347570998239232e-2, 7.03124996963957469739e-2,
            1.24999999999870820058e-1, 4.99999999999999999821e-1)
# exact: ln 4 (Cephes' C1, ellpk.c)
_ELLPK_LOG4 = 1.3862943611198906188e0  # K ~ ln 4 - ln(x)/2 for x <= _MACHEP
# exact: the double's unit round-off (Cephes' MACHEP)
_MACHEP = 2.0**-53
# E - K in one: P_E - P_K and x Q_E - Q_K, both in x = m1 (degree 10: one Horner pass for the
# two rows and one logarithm, half the work of E and K apart). Each coefficient is the exact
# difference of the double coefficients above, rounded once (tests/test_kernels_disc.py
# recomputes them). Against mpmath on 0 < m1 <= 1 (2000 points): within 1 ulp of K and
# 6e-14 of E - K itself (scipy's ellipe(1 - m1) - ellipkm1(m1): 2 ulp of K, 5e-13; its E
# sees 1 - (1 - m1) instead of m1).
_E_MINUS_K = np.array([
    (1.5569712694740056e-05, 0.0002286276815772646, 0.0007138280334547439,
     0.0008768811153953594, 0.0008990580506683717, 0.0013949425577582707, 0.0027780609415299744,
     0.006893754709875199, 0.025920048037114857, 0.3465735902798218, -0.3862943611198906),
    (3.387594352788736e-06, 9.54432029276499e-05, 0.0005655118622375976,
     0.0014011647343548927, 0.0022680139738568764, 0.0033629189660620874, 0.005340661234510824,
     0.009765628690010277, 0.023437500023368682, 0.12500000000001749, -0.5),
]).T[:, :, None].copy()  # (11, 2, 1): rows (P, Q) of E - K = P(x) - ln(x) Q(x)
# convention: scratch size, the results do not depend on it (kernel speed:
# benchmarks/bench_kernels.py)
_ELL_CHUNK = 16384  # points a pass of _dwdr_pressure


def _polevl(coef: tuple[float, ...], x: np.ndarray) -> np.ndarray:
    """sum_j coef[j] x^(n - j) by Horner's rule, as Cephes' polevl orders the operations."""
    out = coef[0] * x + coef[1]
    for c in coef[2:]:
        out *= x
        out += c
    return out


def _ellipe(m) -> np.ndarray:
    """E(m), complete elliptic integral of the second kind: ``scipy.special.ellipe(m)``.

    m <= 1 (NaN above); m < 0 by E(m) = E(1 - 1/x) sqrt(x), x = 1 - m, as Cephes.
    """
    x = 1.0 - np.asarray(m, dtype=float)
    out = np.full(x.shape, np.nan)
    out[x == 0.0] = 1.0
    mid = (x > 0.0) & (x <= 1.0)
    if mid.any():
        xm = x[mid]
        out[mid] = _polevl(_ELLPE_P, xm) - np.log(xm) * (xm * _polevl(_ELLPE_Q, xm))
    big = x > 1.0
    if big.any():
        xb = x[big]
        out[big] = _ellipe(1.0 - 1.0 / xb) * np.sqrt(xb)
    return out


def _ellipkm1(p) -> np.ndarray:
    """K(1 - p), complete elliptic integral of the first kind: ``scipy.special.ellipkm1(p)``.

    p >= 0 (NaN below); inf at p = 0, ln 4 - ln(p)/2 for p <= 2^-53, K(1 - 1/p)/sqrt(p)
    for p > 1 (0 at p = inf), as Cephes.
    """
    x = np.asarray(p, dtype=float)
    out = np.full(x.shape, np.nan)
    out[x == 0.0] = np.inf
    tiny = (x > 0.0) & (x <= _MACHEP)
    if tiny.any():
        out[tiny] = _ELLPK_LOG4 - 0.5 * np.log(x[tiny])
    mid = (x > _MACHEP) & (x <= 1.0)
    if mid.any():
        xm = x[mid]
        out[mid] = _polevl(_ELLPK_P, xm) - np.log(xm) * _polevl(_ELLPK_Q, xm)
    big = x > 1.0
    if big.any():
        xb = x[big]
        with np.errstate(divide="ignore", invalid="ignore"):  # (inf / inf at p = inf)
            out[big] = np.where(np.isinf(xb), 0.0, _ellipkm1(1.0 / xb) / np.sqrt(xb))
    return out


def _e_minus_k(m1: np.ndarray, out: np.ndarray, f: np.ndarray) -> np.ndarray:
    """E(1 - m1) - K(1 - m1) into ``out`` (1-d, at most _ELL_CHUNK points), without the
    cancellation of near-equal E and K beyond that of their Cephes forms.

    ``P(m1) - ln(m1) Q(m1)`` with the Cephes coefficients combined (:data:`_E_MINUS_K`),
    one Horner pass over scratch rows f[0:3] (shape (3, _ELL_CHUNK)); points outside
    Cephes' main branch (m1 <= 2^-53, m1 > 1, NaN) are taken from :func:`_ellipe` and
    :func:`_ellipkm1`.
    """
    k = m1.size
    rows, lg = f[0:2, :k], f[2, :k]
    _horner(_E_MINUS_K, m1, rows)
    with np.errstate(divide="ignore", invalid="ignore"):
        np.log(m1, out=lg)
        lg *= rows[1]
        np.subtract(rows[0], lg, out=out)
    _off_main_branch(m1, out)
    return out


def _off_main_branch(m1: np.ndarray, out: np.ndarray) -> None:
    """E(1 - m1) - K(1 - m1) into ``out`` where m1 lies off Cephes' main branch (m1 <= 2^-53,
    m1 > 1, NaN), from :func:`_ellipe` and :func:`_ellipkm1`; the rest left as it is."""
    if m1.size and not (m1.min() > _MACHEP and m1.max() <= 1.0):
        odd = ~((m1 > _MACHEP) & (m1 <= 1.0))
        mo = m1[odd]
        with np.errstate(invalid="ignore"):
            out[odd] = _ellipe(1.0 - mo) - _ellipkm1(mo)


class _EllScratch(threading.local):
    """Per-thread scratch of :func:`_dwdr_pressure` (rows of _ELL_CHUNK doubles)."""

    def __init__(self) -> None:
        self.f = np.empty((9, _ELL_CHUNK))
        self.lt = np.empty(_ELL_CHUNK, dtype=bool)


_ELL_SCRATCH = _EllScratch()


def _dwdr_pressure(t: np.ndarray, s: np.ndarray) -> np.ndarray:
    """dw/dr of the unit pressure disc: (4/pi)(s/r)(E(m) - K(m)) inside, (4/pi)(E(m') - K(m'))
    outside (m = r^2/s^2, m' = s^2/r^2), with 1 - m formed without cancellation.

    ``t`` and ``s`` broadcast to at most two dimensions; evaluated in passes of
    _ELL_CHUNK points over per-thread scratch rows, E - K by :func:`_e_minus_k`.
    """
    t, s = np.broadcast_arrays(np.asarray(t, dtype=float), np.asarray(s, dtype=float))
    out = np.empty(t.shape)
    t2, s2, o2 = (a.reshape(-1, a.shape[-1]) if a.ndim else a.reshape(1, 1)
                  for a in (t, s, out))
    ws = _ELL_SCRATCH
    for i in range(t2.shape[0]):
        for a in range(0, t2.shape[1], _ELL_CHUNK):
            tt, ss = t2[i, a:a + _ELL_CHUNK], s2[i, a:a + _ELL_CHUNK]
            k = tt.size
            if FUSED:
                _dwdr_fused(tt, ss, ws, o2[i, a:a + k])
                continue
            big, small, q, m1, diff, fac = ws.f[3:9, :k]
            np.maximum(tt, ss, out=big)
            np.minimum(tt, ss, out=small)
            np.divide(small, big, out=q)
            np.subtract(big, small, out=m1)
            m1 /= big
            q += 1.0
            m1 *= q  # (1 - q)(1 + q)
            _e_minus_k(m1, diff, ws.f)
            lt = np.less(tt, ss, out=ws.lt[:k])
            fac.fill(1.0)  # s/r inside (s where r = 0), 1 outside
            with np.errstate(divide="ignore", invalid="ignore"):
                np.divide(ss, tt, out=fac, where=lt)
            if k and not tt.min() > 0.0:
                at0 = lt & ~(tt > 0.0)
                fac[at0] = ss[at0]
            fac *= _C_W
            np.multiply(fac, diff, out=o2[i, a:a + k])
    return out


_E_MINUS_K_ROWS = np.ascontiguousarray(_E_MINUS_K[:, :, 0])  # (11, 2) for the compiled route


def _dwdr_fused(tt: np.ndarray, ss: np.ndarray, ws: _EllScratch, out: np.ndarray) -> None:
    """One chunk of :func:`_dwdr_pressure` by the compiled route (:data:`FUSED`): m1 there,
    ln(m1) by numpy, E - K and the factor there, the points off Cephes' main branch as
    :func:`_e_minus_k` takes them (:func:`_off_main_branch`); the same bits."""
    tt, ss = np.ascontiguousarray(tt), np.ascontiguousarray(ss)
    k = tt.size
    m1, lg, diff, fac = ws.f[3:7, :k]
    _fused.ell_m1(tt, ss, m1)
    with np.errstate(divide="ignore", invalid="ignore"):
        np.log(m1, out=lg)
    _fused.dwdr(tt, ss, m1, lg, _E_MINUS_K_ROWS, _C_W, diff, fac)
    _off_main_branch(m1, diff)
    np.multiply(fac, diff, out=out)


def w_difference_disc(r, r0: float, s, nu: float,
                      part: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """w(r; s) - w(r0; s) of the disc load of ``part``, without cancellation.

    Parameters
    ----------
    r, s : array_like
        Surface points and disc radii (>= 0), broadcast.
    r0 : float
        The reference point (>= 0); 0 gives :func:`axis_w_disc`.
    nu : float
        Poisson's ratio.
    part : {"normal", "shear"}

    Returns
    -------
    dw, zero, zero : ndarray
        As :func:`axis_w_disc`.

    Notes
    -----
    Shear: beta (min(r, s)^2 - min(r0, s)^2) as a product. Pressure: where the
    disc edge s lies at least |r - r0| from the interval between r0 and r,
    the Gauss-Legendre integral of dw/dr over it (6, 10 or 16 points as s
    is 8, 2 or 1 interval lengths away, :data:`GAUSS_TIERS`; the log
    singularity of dw/dr at s is then at least one interval length away: a
    relative error below 1e-14), else the plain difference of
    :func:`pressure_disc` (both points then within a few |r - r0| of s, where
    w varies on that scale and the difference keeps its digits).
    """
    if r0 == 0.0:
        return axis_w_disc(r, s, nu, part)
    ra = np.abs(np.asarray(r, dtype=float))
    sa = np.asarray(s, dtype=float)
    ra, sa = np.broadcast_arrays(ra, sa)
    zero = np.zeros(ra.shape)
    if part == "shear":
        a, b0 = np.minimum(ra, sa), np.minimum(r0, sa)
        return beta_of_nu(nu) * (a - b0) * (a + b0), zero, zero.copy()
    if part != "normal":
        raise ValueError(f"part must be 'normal' or 'shear', got {part!r}")
    length = np.abs(ra - r0)
    gap = np.maximum(np.maximum(sa - np.maximum(ra, r0), np.minimum(ra, r0) - sa), 0.0)
    dw = np.empty(ra.shape)
    smooth = np.zeros(ra.shape, dtype=bool)
    for tier, gt, gw in gauss_tiers(np.where(sa > 0.0, gap, -1.0), length):
        if tier.any():
            rs, ss = ra[tier], sa[tier]
            t = r0 + (rs - r0)[None, :] * gt[:, None]
            dw[tier] = (rs - r0) * (gw @ _dwdr_pressure(t, ss[None, :]))
            smooth |= tier
    rest = ~smooth
    if rest.any():
        dw[rest] = (pressure_disc(ra[rest], sa[rest], nu)[0]
                    - pressure_disc(np.full(int(rest.sum()), r0), sa[rest], nu)[0])
    return dw, zero, zero.copy()
