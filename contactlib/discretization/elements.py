"""Meshes of the half-contact 0 <= xi <= 1 (rings or strips)."""

from __future__ import annotations

from collections import OrderedDict
from dataclasses import dataclass
from typing import Any, Callable

import numpy as np

__all__ = ["Mesh", "Store", "MeshStore", "graded_mesh", "uniform_mesh", "MAX_ELEMENTS"]


@dataclass(frozen=True)
class Mesh:
    """Element nodes and the index of the stick-slip node.

    Attributes
    ----------
    nodes : ndarray, shape (N + 1,)
        0 = nodes[0] < ... < nodes[N] = 1 (units of a).
    stick_index : int
        M with nodes[M] = c (0 when frictionless, N at full adhesion).
    """

    nodes: np.ndarray
    stick_index: int

    @property
    def n(self) -> int:
        return self.nodes.size - 1


def _toward_end(t: np.ndarray, power: float) -> np.ndarray:
    """Map [0,1] -> [0,1], elements shrinking like power-law toward t = 1."""
    return 1.0 - (1.0 - t) ** power


# Two-scale grading (see graded_mesh). Element density in the distance d from
# c: a root-graded feature of length L (d < L: elements ~ sqrt(d L)/n, as a
# power-2 mesh) turning geometric beyond L (elements ~ d/n), plus a uniform
# part; the slip side adds the same feature at the contact edge.
# measured: benchmarks/report_error_map.py (the default n's error over c/a and nu, which the grading
# sets; 1.2 fixed the value below, tests/test_extremes.py checks extreme c/a)
_GEOMETRIC = 1.2  # weight of the geometric tail (1.0 left the sphere at nu = 0.499,
# c/a = 1e-6, n = 256 at 1.03e-4 from the closed form; 1.2: 8.4e-5, 1e-4: 5.8e-5)
# measured: benchmarks/report_error_map.py (a weight of the two-scale mesh, issue 12; the map
# re-measures the resolution it gives)
_UNIFORM = 0.5  # weight of the uniform part (per unit of a; of c on the stick side)
# measured: benchmarks/report_error_map.py (a weight of the two-scale mesh, issue 12)
_EDGE = 0.5  # weight of the contact-edge feature
# measured: benchmarks/report_error_map.py (a weight of the two-scale mesh, issue 12)
_STICK = 1.5  # weight of the stick side
# measured: benchmarks/report_error_map.py (the two-scale mesh, issue 12)
_EDGE_LENGTH = 0.5  # its length, at most (the slip-zone width when that is smaller)
# limit: validate.MAX_N, whose memory tests/test_extremes.py measures
MAX_ELEMENTS = 4096  # a grown mesh is scaled back to this many elements (memory: 3.4 GiB)


def _feature(d: np.ndarray, length: float) -> np.ndarray:
    """Cumulative element count of a root-graded feature that turns geometric.

    Density 1 / (2 sqrt(d (L + d / lam^2))): sqrt-graded for d << L, lam / (2 d)
    (a fixed count per e-fold) for d >> L; its integral in closed form.
    """
    lam = _GEOMETRIC
    return lam * np.arcsinh(np.sqrt(np.maximum(d, 0.0) / length) / lam)


def _side_counts(c: float) -> tuple[Callable, Callable]:
    """Cumulative element counts of the stick side (distance c - r) and slip side (r - c)."""
    w = 1.0 - c
    length = min(c, w)
    edge = min(w, _EDGE_LENGTH)

    def stick(d):
        return _STICK * (_feature(d, length) + _UNIFORM * d / max(c, 0.5))

    def slip(d):
        return (_feature(d, length) + _UNIFORM * d
                + _EDGE * (_feature(w, edge) - _feature(w - d, edge)))

    return stick, slip


def _invert(count: Callable, targets: np.ndarray, span: float) -> np.ndarray:
    """Distances d in [0, span] with count(d) = targets (monotone count; bisection in sqrt d).

    110 halvings (2^-110 of sqrt(span): below round-off of every node). A point
    whose bracket a halving leaves unchanged (the midpoint rounds onto an end)
    keeps it through every later one, so it drops out there: the same nodes bit for
    bit, in about half the work. A zero target (count(d) >= 0 is never below it)
    halves its upper end each time: sqrt(span) 2^-110 after all of them.
    """
    steps = 110
    out_lo = np.zeros_like(targets)
    out_hi = np.full_like(targets, np.sqrt(span))
    zero = targets == 0.0
    out_hi[zero] *= 2.0 ** -steps
    idx = np.flatnonzero(~zero)  # the points still moving, and their brackets
    lo, hi, tg = out_lo[idx], out_hi[idx], targets[idx]
    for _ in range(steps):
        if idx.size == 0:
            break
        mid = 0.5 * (lo + hi)
        below = count(mid * mid) < tg
        new_lo = np.where(below, mid, lo)
        new_hi = np.where(below, hi, mid)
        moved = (new_lo != lo) | (new_hi != hi)
        lo, hi = new_lo, new_hi
        if not moved.all():
            done = ~moved
            out_lo[idx[done]], out_hi[idx[done]] = lo[done], hi[done]
            idx, lo, hi, tg = idx[moved], lo[moved], hi[moved], tg[moved]
    out_lo[idx], out_hi[idx] = lo, hi
    return (0.5 * (out_lo + out_hi)) ** 2


class Store:
    """A bounded store of values by key, owned by the caller that fills it.

    Oldest entry dropped first; ``hits`` and ``misses`` count the requests
    answered from the store and the values computed. There is no
    process-wide store in contactlib: whoever owns a computation owns its
    stores (:class:`MeshStore`, :class:`contactlib.discretization.operators.StickBlocks`).
    """

    def __init__(self, size: int) -> None:
        self.size = int(size)
        self._values: OrderedDict[tuple, Any] = OrderedDict()
        self.hits = 0
        self.misses = 0

    def get(self, key: tuple, compute: Callable[[], Any]) -> Any:
        """The value of ``key``, computed by ``compute()`` and stored when missing."""
        found = self._values.get(key)
        if found is None:
            self.misses += 1
            found = compute()
            if len(self._values) >= self.size:
                self._values.popitem(last=False)
            self._values[key] = found
        else:
            self.hits += 1
        return found

    def __contains__(self, key: tuple) -> bool:
        return key in self._values

    def clear(self) -> None:
        """Forget every value."""
        self._values.clear()

    def __len__(self) -> int:
        return len(self._values)


class MeshStore(Store):
    """The graded meshes a computation has built, kept by its caller for reuse.

    A sweep with error estimates asks for each mesh several times (the fine
    mesh of a case for its operators and its solve, the nested n/2 and n/4
    meshes for the estimate), and the node placement inverts the element
    count by bisection (about 8 ms a mesh at n = 256): a sweep of ten cases
    at n = 256 asks for 70 meshes, of which 30 differ, and takes 1.25 times
    as long when every request builds its mesh again
    (``benchmarks/bench_meshes.py``).
    It holds (nodes, stick index) by the arguments of :func:`graded_mesh`,
    at most ``size`` of them (33 kB each at 4096 elements), and
    :func:`graded_mesh` hands out copies. The caller owns it
    (:class:`contactlib.discretization.operators.StickBlocks` carries one, so a sweep's
    store of stick blocks brings its meshes along).
    """

    def __init__(self, size: int = 128) -> None:
        super().__init__(size)


def graded_mesh(n: int, stick_ratio: float, power: float = 2.0,
                min_stick: int = 4, store: MeshStore | None = None) -> Mesh:
    """Mesh with a node at c that resolves both lengths, c and a - c.

    Near c the tractions and displacements have an edge behaviour on the
    scale L = min(c, a - c): elements are root-graded (size ~ sqrt(d L) / n at
    distance d from c, like a power-2 mesh) for d < L and grow geometrically
    beyond, with a fixed number of elements per e-fold, up to the uniform
    size; the contact edge a is root-graded as well. The element counts of
    the two sides follow from that density: n elements at c/a = 1/2, more
    where a tiny stick zone or a thin slip annulus adds e-folds (1.19 n at
    c/a = 0.1, 2.3 n at 1e-4, 3.8 n at 1e-8; 1.38 n at 0.9, 3.1 n at 0.9999,
    3.6 n at 1 - 1e-5), scaled back to :data:`MAX_ELEMENTS`.
    For n a multiple of 16 both counts are multiples of n/16, so halving n
    halves every element (nested meshes: clean Richardson estimates).

    Parameters
    ----------
    n : int
        Resolution: the number of elements at c/a = 1/2.
    stick_ratio : float
        c/a in [0, 1].
    power : float
        Grading exponent of the meshes without a stick-slip node (c/a = 0 or
        1), graded toward the contact edge.
    min_stick : int
        Minimum number of elements in each zone when 0 < c < 1.
    store : MeshStore, optional
        The caller's store of meshes already built (none: built here).
    """
    key = (int(n), float(stick_ratio), float(power), int(min_stick))
    if store is None:
        nodes, m = _graded_nodes(*key)
    else:
        nodes, m = store.get(key, lambda: _graded_nodes(*key))
    return Mesh(nodes.copy(), m)


def _graded_nodes(n: int, c: float, power: float, min_stick: int) -> tuple[np.ndarray, int]:
    """The nodes of :func:`graded_mesh` and its stick index."""
    if c <= 0.0 or c >= 1.0:
        t = np.linspace(0.0, 1.0, n + 1)
        nodes = _toward_end(t, power)
        nodes[0], nodes[-1] = 0.0, 1.0
        return nodes, 0 if c <= 0.0 else n
    stick, slip = _side_counts(c)
    ref_stick, ref_slip = _side_counts(0.5)
    ref = float(ref_stick(0.5) + ref_slip(0.5))
    shares = np.array([float(stick(c)), float(slip(1.0 - c))]) / ref
    if n * shares.sum() > MAX_ELEMENTS:
        shares *= MAX_ELEMENTS / (n * shares.sum())
    if n % 16 == 0:
        m, ms = ((n // 16) * np.maximum(1, np.floor(16 * shares + 0.5))).astype(int)
    else:
        m, ms = np.maximum(1, np.floor(n * shares + 0.5)).astype(int)
    m, ms = max(int(m), min_stick), max(int(ms), min_stick)
    ds = _invert(stick, float(stick(c)) * np.linspace(0.0, 1.0, m + 1), c)
    dl = _invert(slip, float(slip(1.0 - c)) * np.linspace(0.0, 1.0, ms + 1), 1.0 - c)
    nodes = np.concatenate([(c - ds[::-1])[:-1], c + dl])
    nodes[0], nodes[m], nodes[-1] = 0.0, c, 1.0
    return nodes, m


def uniform_mesh(n: int, stick_index: int) -> Mesh:
    """n equal elements (the paper's rings), stick-slip node at m/n."""
    return Mesh(np.linspace(0.0, 1.0, n + 1), stick_index)
