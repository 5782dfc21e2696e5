"""Element integrals of the disc/strip kernels: the influence matrices.

Every traction in this package is written as a superposition of the basic
loads of :mod:`contactlib.kernels` (a uniform pressure, or a shear of fixed
shape, on a disc or symmetric strip of radius ``s``)::

    t(r) = shape(r) * phi(r),     phi(r) = int_0^1 sigma(s) H(s - r) ds,

with ``sigma = -phi'``. For ``phi`` piecewise linear on the nodes
``r_0 < ... < r_N`` (``phi(r_N) = 0``), ``sigma`` is constant on each element
and the displacement at a point ``x`` is ``sum_j sigma_j G_j(x)`` with
``G_j(x) = int_{r_j}^{r_{j+1}} K(x; s) ds``. This module computes ``G`` for the
three kernel outputs (w, u, du/dx) at once.

Quadrature. ``K(x; s)`` is smooth in ``s`` except at ``s = |x|``, where it
behaves like ``(s - x) log|s - x|`` (``du/dx``: like ``log|s - x|``, or a jump
for the pressure). Each element is split at ``x`` when ``x`` lies in it; the
pieces that touch ``x``, and the elements closer to ``x`` than 2 of their
lengths, get 16 Gauss-Legendre points mapped by a degree-7 smoothstep (which
clusters points at both ends and makes the end singularity harmless). An
element ``d >= 2`` lengths from ``x`` gets plain ``n``-point Gauss-Legendre: 6
points below d = 2.5, 5 below 5, 4 below 12, 3 below 100 and 2 beyond. The
error of the ``n``-point rule for ``log|s - x|`` over an element of length
``L`` at distance ``d L`` is ``L^(2n+1) (n!)^4 / ((2n+1) ((2n)!)^3)
max|f^(2n)|`` with ``|f^(2n)| <= (2n-1)! / (d L)^(2n)``: relative to the
logarithm's coefficient, ``c_n d^(-2n)`` with c_2 = 1.4e-3, c_3 = 6.0e-5,
c_4 = 2.8e-6, c_5 = 1.4e-7, c_6 = 7.5e-9, i.e. at most 2e-11 at each threshold
(the 2- and 3-point classes set it; ``w`` and ``u`` are one order smoother).
``tests/test_influence_speedup.py`` checks the operators against a 40-point
rule on every element: below 1e-10 of each row's largest entry, except ``du/dx``
of a log-singular kernel (the disc shear) on the pieces touching ``x``, where
the smoothstep rule leaves ~1e-7 (as it always has). Against a 40-point Gauss rule on
the elements beyond 2 lengths alone these classes leave up to ~1e-10 of a row's largest
entry (the shear's u and du/dx; the bound above is the logarithm's, not the disc
kernels'); ``quadrature="fine"`` (:data:`QUADRATURES`: 16, 12, 10, 8, 6, 4 points from 2,
3, 5, 12, 40, 100 lengths on) leaves round-off there (1.6e-14). The extrapolated method
integrates its band of difference rows around c so from n = 2048, where the standard
classes' bias reached k near full stick.

Organisation. Every element is integrated once, by its own rule. The (point,
element) pairs are classified in row blocks and grouped by rule and by side
(element above or below ``x``: the disc kernels then see runs of points
inside, and outside, the loaded disc); the points of consecutive groups are
packed into kernel calls of ``_CALL_POINTS`` points laid out rule point by
rule point, and the weighted sums are matrix-vector products. Work arrays are
per-thread and reused (fresh temporaries of a few hundred kB cost page faults
where the allocator returns freed memory to the system).
"""

from __future__ import annotations

import threading
from collections.abc import Callable

import numpy as np

try:  # the compiled routes (setup.py; optional): the same bits
    from . import operators_fused as _fused
except ImportError:  # pragma: no cover - a build without a C compiler
    _fused = None

FUSED = _fused is not None
"""Whether :func:`apply_difference` and the classification of :func:`element_integrals` run
compiled (``contactlib/discretization/operators_fused.c``, built by ``pip install``): the same divisions
and subtractions on the same operands as the numpy route, one pass a row; the same keys of
the (point, element) pairs, grouped by one counting sort in the order the numpy route's
``flatnonzero`` gives; so the same bits (``tests/test_kernels_fused.py``). False selects
the numpy routes."""

Kernel = Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray, np.ndarray]]

__all__ = ["apply_difference", "element_integrals", "QUADRATURES"]

# tested: tests/test_influence_speedup.py (the element integrals against a 40-point rule)
_NEAR = 2.0  # distance/length below which an element gets the smoothstep rule
# (lower distance/length bound, Gauss points), nearest class first
_CLASSES = ((_NEAR, 6), (2.5, 5), (5.0, 4), (12.0, 3), (100.0, 2))
# the "fine" classes: more points in every class beyond _NEAR lengths
_FINE_CLASSES = ((_NEAR, 16), (3.0, 12), (5.0, 10), (12.0, 8), (40.0, 6), (100.0, 4))
QUADRATURES = ("standard", "fine")
"""The rule sets of :func:`element_integrals` (its ``quadrature``). ``"standard"``: the
classes of the module text, at most ~2e-11 of a row's scale at each threshold by the
logarithm's bound; measured against the "fine" rules on the nodal operators (n = 2048,
c/a = 0.9, sphere and cylinder) its largest error is 4e-13 (pressure) and 1.9e-11 (shear,
du/dx) of a row's largest entry, and near full stick that bias reaches k: 4.8e-9 at
c/a = 0.98 (cylinder, nu = 0.4999999, extrapolated method at n = 2048, against the closed
form, through its band rows). ``"fine"``: 16, 12, 10, 8, 6 and 4 Gauss points from
2, 3, 5, 12, 40 and 100 element lengths on (the near pieces as before): round-off against a
40-point rule, and that k error is 1.1e-10 with the band rows integrated so
(:data:`contactlib.solvers.extrapolated_method.FINE_QUADRATURE_FROM_N`). It costs about 1.35-1.4x
the kernel time of the standard rules."""
# convention: scratch size, the results do not depend on it (the solve's speed:
# benchmarks/bench_solve.py)
_BLOCK_PAIRS = 1 << 17  # (point, element) pairs classified at once
# convention: scratch size, the results do not depend on it (the solve's speed:
# benchmarks/bench_solve.py)
_CALL_POINTS = 1 << 15  # kernel points per call


def _gauss(n: int) -> tuple[np.ndarray, np.ndarray]:
    t, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (t + 1.0), 0.5 * w


def _smoothstep_rule(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss rule on [0, 1] mapped by phi(t) = 35t^4 - 84t^5 + 70t^6 - 20t^7."""
    t, w = _gauss(n)
    phi = t**4 * (35.0 - 84.0 * t + 70.0 * t**2 - 20.0 * t**3)
    dphi = 140.0 * t**3 * (1.0 - t) ** 3
    return phi, w * dphi


_RULE_NEAR = _smoothstep_rule(16)
# per quadrature: (lower thresholds, Gauss rules) of the classes beyond the near one
_SETS = {name: (tuple(d for d, _ in classes), tuple(_gauss(p) for _, p in classes))
         for name, classes in (("standard", _CLASSES), ("fine", _FINE_CLASSES))}


class _Scratch(threading.local):
    """Per-thread work arrays, allocated once and reused.

    Fresh temporaries of a few hundred kB cost page faults wherever the
    allocator hands freed memory back to the system; these do not.
    """

    def __init__(self) -> None:
        self.x = np.empty(_CALL_POINTS)  # kernel arguments
        self.s = np.empty(_CALL_POINTS)
        self.dist = np.empty(_BLOCK_PAIRS)  # classification of a row block
        self.tmp = np.empty(_BLOCK_PAIRS)
        self.code = np.empty(_BLOCK_PAIRS, dtype=np.int8)
        self.side = np.empty(_BLOCK_PAIRS, dtype=bool)
        self.x_of = np.empty(_BLOCK_PAIRS)  # point of each pair of a block
        self.j_of = np.empty(_BLOCK_PAIRS, dtype=np.intp)  # element of each pair
        self.j_of_n = 0  # number of elements j_of was filled for
        self.order = np.empty(_BLOCK_PAIRS, dtype=np.int64)  # pairs grouped by key (compiled)


_SCRATCH = _Scratch()


class _Packer:
    """Collects groups of quadrature pieces and evaluates them in few kernel calls.

    A group is k pieces [start, start + length] with one evaluation point
    each, all integrated by the same rule (points ``t``, weights ``w`` on
    [0, 1]); ``put(a, b, res)`` receives the integrals (3, b - a) of pieces
    a..b. The points of consecutive groups share kernel calls of at most
    ``_CALL_POINTS`` points, laid out point-major (rule point, piece).
    """

    def __init__(self, kernels: tuple[Kernel, ...], dest: list) -> None:
        self.kernels = kernels
        self.dest = dest  # per kernel: (its output, row of the result) of the rows wanted
        self.ws = _SCRATCH
        self.fill = 0
        self.pending: list = []

    def add(self, xs: np.ndarray, start: np.ndarray, length: np.ndarray,
            rule: tuple[np.ndarray, np.ndarray], put, touch: bool = False) -> None:
        t, w = rule
        p = t.size
        k = xs.size
        a = 0
        while a < k:
            room = (_CALL_POINTS - self.fill) // p
            if room == 0:
                self.flush()
                continue
            b = min(k, a + room)
            lo, hi = self.fill, self.fill + (b - a) * p
            self.ws.x[lo:hi].reshape(p, b - a)[...] = xs[None, a:b]
            s = self.ws.s[lo:hi].reshape(p, b - a)
            np.multiply(t[:, None], length[None, a:b], out=s)  # start + length t, as before
            s += start[None, a:b]
            if touch:  # pieces ending at x: no rule point may round onto x itself
                _off_the_point(s, xs[a:b], start[a:b])
            self.pending.append((lo, a, b, w, length, put))
            self.fill = hi
            a = b

    def flush(self) -> None:
        """Evaluate the kernels (one after the other: one output block alive at a time)."""
        if not self.fill:
            return
        x, s = self.ws.x[:self.fill], self.ws.s[:self.fill]
        for kernel, pairs in zip(self.kernels, self.dest):
            if not pairs:
                continue
            vals = [np.asarray(v, dtype=float).reshape(-1) for v in kernel(x, s)]
            rows = [row for _, row in pairs]
            with np.errstate(invalid="ignore"):  # inf * weight - inf of a log-infinite du
                for lo, a, b, w, length, put in self.pending:
                    res = np.empty((len(pairs), b - a))
                    hi = lo + (b - a) * w.size
                    for i, (k_out, _) in enumerate(pairs):
                        np.dot(w, vals[k_out][lo:hi].reshape(w.size, b - a), out=res[i])
                    res *= length[a:b]
                    put(a, b, res, rows)
            del vals
        self.pending = []
        self.fill = 0


def _off_the_point(s: np.ndarray, xs: np.ndarray, start: np.ndarray) -> None:
    """Move rule points that rounded onto their point x one ulp into their piece, in place.

    A piece of length L next to x puts its outermost smoothstep point at
    about 2e-8 L from x, which rounds onto x once L is below ~5e-9 x (a slip
    annulus of 1e-5 a at n = 256): the kernels' du/dx is log-infinite there.
    One ulp into the piece the integrand is finite; the weight of that point
    (~1e-8 of the piece) makes the change of the integral negligible.
    """
    hit = s == xs[None, :]
    if hit.any():
        toward = np.where(start >= xs, np.inf, -np.inf)
        s[hit] = np.nextafter(np.broadcast_to(xs, s.shape)[hit],
                              np.broadcast_to(toward, s.shape)[hit])


def _positions(idx: np.ndarray, r0: int, n: int, stride: int) -> np.ndarray:
    """Flat positions in the output of the pairs ``idx`` (row-major over n elements) of the
    row block starting at row ``r0``; rows lie ``stride`` apart in memory."""
    if stride == n:
        return idx + r0 * n
    return idx + (idx // n) * (stride - n) + r0 * stride


def _sink(flat: list, pos: np.ndarray, add: bool = False):
    """``put`` for the packer: write (or add) piece results at flat positions ``pos``."""
    def put(a, b, res, rows):
        sel = pos[a:b]
        for i, row in enumerate(rows):
            if add:
                flat[row][sel] += res[i]
            else:
                flat[row][sel] = res[i]
    return put


def element_integrals(kernel: Kernel | tuple[Kernel, ...], x: np.ndarray, nodes: np.ndarray,
                      chunk: int = 2_000_000, ref: float | None = None,
                      outputs: tuple[int, ...] | None = None,
                      out: np.ndarray | None = None,
                      quadrature: str = "standard") -> np.ndarray:
    """Integrals of a kernel over every element for every evaluation point.

    Parameters
    ----------
    kernel : callable or tuple of callables
        ``kernel(x, s) -> (w, u, dudx)``, vectorized, for a unit basic load of
        radius (half-width) ``s``. Several kernels (a tuple: a pressure's and a
        shear's) share one classification of the (point, element) pairs and one
        set of quadrature points, evaluated by each kernel in turn; each output is
        integrated exactly as it would be alone, bit for bit.
    x : ndarray, shape (m,)
        Evaluation points (>= 0).
    nodes : ndarray, shape (N + 1,)
        Increasing element nodes, ``nodes[0] = 0``.
    chunk : int
        Maximum number of (point, element) pairs handled at once (memory).
    ref : float, optional
        A node where the kernel is singular as well as at ``x`` (a kernel
        difference K(x; s) - K(ref; s)): the elements are classified by
        their distance to the nearer of ``x`` and ``ref``.
    outputs : tuple of int, optional
        The kernel outputs to integrate (0, 1, 2 the first kernel's w, u, du/dx,
        3, 4, 5 the second's, ...), in the order of the result's rows; default all.
        The others are not integrated (a kernel none of whose outputs is asked
        for is not evaluated); those asked for are the same bits either way.
    out : ndarray, optional
        Where to write the result (float, shape as returned, its last axis
        contiguous; e.g. a block of columns of a larger array): the same bits,
        without a fresh array and a copy.
    quadrature : {"standard", "fine"}
        The Gauss classes of the elements beyond 2 lengths (:data:`QUADRATURES`); the
        pieces touching the point get the same smoothstep rule either way.

    Returns
    -------
    ndarray, shape (3 K, m, N) for K kernels (or (len(outputs), m, N))
        ``G[k, i, j] = int_{nodes[j]}^{nodes[j+1]} K_k(x_i; s) ds`` for
        k = 0 (w), 1 (u), 2 (du/dx) (3, 4, 5 those of a second kernel, ...).
    """
    if quadrature not in _SETS:
        raise ValueError(f"quadrature must be one of {QUADRATURES}, not {quadrature!r}")
    thresholds, rules = _SETS[quadrature]
    kernels = tuple(kernel) if isinstance(kernel, tuple) else (kernel,)
    wanted = tuple(range(3 * len(kernels))) if outputs is None else tuple(outputs)
    dest = [[(k % 3, row) for row, k in enumerate(wanted) if k // 3 == i]
            for i in range(len(kernels))]
    count = len(wanted)
    x = np.ascontiguousarray(x, dtype=float).reshape(-1)
    nodes = np.asarray(nodes, dtype=float)
    lo_e, hi_e = nodes[:-1], nodes[1:]
    length = hi_e - lo_e
    m, n = x.size, lo_e.size
    if out is None:
        out = np.empty((count, m, n))
    elif (out.shape != (count, m, n) or out.dtype != np.float64
          or (n > 1 and out.strides[2] != out.itemsize) or not out.flags.writeable
          or (m > 1 and out.strides[1] < n * out.itemsize)):
        raise ValueError(f"out must be a writeable float array of shape {(count, m, n)} "
                         "with a contiguous last axis")
    if m == 0 or n == 0:
        return out
    # each output as one flat run of memory: pair (i, j) at i * stride + j (stride = n
    # unless ``out`` is a column block of a wider array, whose gaps are never written)
    stride = out.strides[1] // out.itemsize if m > 1 else n
    flat = [np.lib.stride_tricks.as_strided(out[k], shape=((m - 1) * stride + n,),
                                            strides=(out.itemsize,)) for k in range(count)]
    with np.errstate(divide="ignore"):
        inv_len = 1.0 / length
    dist_ref = None
    if ref is not None:  # distance (in lengths) of each element to the node ref
        with np.errstate(invalid="ignore"):
            dist_ref = np.maximum(np.maximum(lo_e - ref, ref - hi_e), 0.0) * inv_len
    rows = max(1, min(int(chunk), _BLOCK_PAIRS) // n)
    ws = _SCRATCH
    if FUSED:  # the compiled classification's arguments
        lo_e, hi_e = np.ascontiguousarray(lo_e), np.ascontiguousarray(hi_e)
        ref_arg = _NO_REF if dist_ref is None else np.ascontiguousarray(dist_ref)
        thr_arg = np.array(thresholds, dtype=float)
        offsets = np.empty(2 * len(thresholds) + 3, dtype=np.int64)
    packer = _Packer(kernels, dest)
    for r0 in range(0, m, rows):
        xr = x[r0:r0 + rows]
        mb = xr.size
        k = mb * n
        small = k <= _BLOCK_PAIRS
        if FUSED:  # compiled: the same keys, grouped in one pass (counting sort)
            order = ws.order[:k] if small else np.empty(k, dtype=np.int64)
            _fused.classify(xr, lo_e, hi_e, inv_len, ref_arg, thr_arg, order, offsets)

            def bucket(c: int) -> np.ndarray:  # np.flatnonzero(key == c); c = 0: key < 2
                return order[offsets[c]:offsets[c + 1]]

            def points(idx: np.ndarray) -> np.ndarray:
                return xr.take(idx // n)

            def elements(idx: np.ndarray) -> np.ndarray:
                return idx % n
        else:
            bucket, points, elements = _classify(xr, lo_e, hi_e, inv_len, dist_ref,
                                                 thresholds, ws, small)
        near = None
        idx = bucket(0)
        if idx.size:
            xs_near, jj = points(idx), elements(idx)
            lo, hi = lo_e.take(jj), hi_e.take(jj)
            cut = np.clip(xs_near, lo, hi)
            pos = _positions(idx, r0, n, stride)
            for k_out in range(count):
                flat[k_out][pos] = 0.0  # the pieces on either side of x add up here
            near = (pos, ((cut, hi), (lo, cut)))
        # above x first (inside the disc), then below; near pieces last on each side
        for sd in (1, 0):
            for cls in range(1, len(rules) + 1):
                idx = bucket(2 * cls + sd)
                if idx.size:
                    jj = elements(idx)
                    packer.add(points(idx), lo_e.take(jj), length.take(jj), rules[cls - 1],
                               _sink(flat, _positions(idx, r0, n, stride)))
            if near is None:
                continue
            a_end, b_end = near[1][1 - sd]
            piece = np.flatnonzero(b_end > a_end)  # empty pieces contribute 0
            if piece.size:
                pa = a_end.take(piece)
                packer.add(xs_near.take(piece), pa, b_end.take(piece) - pa, _RULE_NEAR,
                           _sink(flat, near[0].take(piece), add=True), touch=True)
    packer.flush()
    return out


_NO_REF = np.empty(0)  # (no reference node: the compiled classification's empty dist_ref)


def _classify(xr: np.ndarray, lo_e: np.ndarray, hi_e: np.ndarray, inv_len: np.ndarray,
              dist_ref: np.ndarray | None, thresholds: tuple, ws: "_Scratch", small: bool):
    """The numpy route of :func:`element_integrals`' classification of a row block:
    ``(bucket, points, elements)``, bucket(c) the pairs of key c (c = 0: keys 0 and 1, the
    near pairs), points and elements the evaluation point and element of pairs."""
    mb, n = xr.size, lo_e.size
    k = mb * n
    # classify: distance to the element in element lengths, side of x
    dist = ws.dist[:k].reshape(mb, n) if small else np.empty((mb, n))
    tmp = ws.tmp[:k].reshape(mb, n) if small else np.empty((mb, n))
    side = ws.side[:k].reshape(mb, n) if small else np.empty((mb, n), dtype=bool)
    code = ws.code[:k].reshape(mb, n) if small else np.empty((mb, n), dtype=np.int8)
    np.subtract(lo_e[None, :], xr[:, None], out=dist)
    np.greater_equal(dist, 0.0, out=side)  # element above x: inside the disc
    np.subtract(xr[:, None], hi_e[None, :], out=tmp)
    np.maximum(dist, tmp, out=dist)
    np.maximum(dist, 0.0, out=dist)
    with np.errstate(invalid="ignore"):
        dist *= inv_len
    if dist_ref is not None:
        np.minimum(dist, dist_ref[None, :], out=dist)
    code[...] = side  # key = 2 * class + side; class 0 = near (< _NEAR lengths)
    for t in thresholds:
        np.greater_equal(dist, t, out=side)
        code += side
        code += side
    key = code.reshape(-1)
    if small:
        x_of = ws.x_of[:k].reshape(mb, n)
        if ws.j_of_n != n:  # fill for the most rows a block can have
            full = _BLOCK_PAIRS // n
            ws.j_of[:full * n].reshape(full, n)[...] = np.arange(n)
            ws.j_of_n = n
        j_of = ws.j_of[:k]
    else:
        x_of = np.empty((mb, n))
        j_of = np.broadcast_to(np.arange(n), (mb, n)).ravel()
    x_of[...] = xr[:, None]
    x_of = x_of.reshape(-1)

    def bucket(c: int) -> np.ndarray:
        return np.flatnonzero(key < 2) if c == 0 else np.flatnonzero(key == c)

    return bucket, x_of.take, j_of.take


def apply_difference(g: np.ndarray, nodes: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
    """Element integrals (per unit sigma) -> operators on nodal values of phi.

    ``sigma_j = (phi_j - phi_{j+1}) / h_j``, so column l of the result is
    g[..., l] / h_l - g[..., l-1] / h_{l-1}; O(size) work, no dense product.
    ``out`` (shape ``g.shape[:-1] + (N + 1,)``) receives the result; ``g`` may be
    its first N columns (``out[..., :N]``): a block of rows is read whole before
    it is written, so no second array of the operator's size is needed.
    """
    h = np.diff(np.asarray(nodes, dtype=float))
    g = np.asarray(g)
    n = h.size
    if n == 0:
        return np.zeros(g.shape[:-1] + (1,))
    if out is None:
        out = np.empty(g.shape[:-1] + (n + 1,))
    g2 = g.reshape(-1, n)
    o2 = out.reshape(-1, n + 1)
    if FUSED and g2.dtype == np.float64 and o2.dtype == np.float64:
        _fused.difference(g2, np.ascontiguousarray(h), o2)  # one pass a row, the same bits
        return out
    step = max(1, 16384 // max(n, 1))  # rows at a time: small temporaries
    for a in range(0, g2.shape[0], step):
        scaled = g2[a:a + step] / h
        o = o2[a:a + step]
        o[:, 0] = scaled[:, 0]
        np.subtract(scaled[:, 1:], scaled[:, :-1], out=o[:, 1:n])
        np.negative(scaled[:, -1], out=o[:, n])
    return out
