r"""Influence operators of a model: the displacements its element tractions produce.

Every solver builds its matrices here, from a :class:`~contactlib.model.Contact`
(any object with its ``pressure_kernel``, ``shear_kernel`` and
``length_degrees``). Two kinds of element traction on the half contact, cut
at ``edges`` (``nodes``) 0 = s_0 < ... < s_N:

* **steps** (:func:`step_operator`): a constant pressure, or a constant
  coefficient times the shear shape (``q = shape(r) q_j``: r on a ring, +-1 on
  a strip pair), on each element. Element j's load is the basic load of radius
  s_{j+1} minus that of radius s_j, so the operator is an exact difference of
  the closed-form kernels. The paper's rings and the incremental solver's
  elements.
* **piecewise linear** (:func:`operator_part`): the pressure ``p``, or the
  shear coefficient ``phi`` (``q = shape(r) phi(r)``), linear between nodal
  values with ``p_N = phi_N = 0``. The operator acts on the nodal values;
  its entries are element integrals of the kernels
  (:func:`contactlib.discretization.influence.element_integrals`). The default method's.
  On a layer under rings the kernels are the half-space's plus a smooth
  (analytic) remainder: the first part gets the singularity-aware rules of
  ``element_integrals``, the remainder a plain Gauss rule on panels of at
  most half a layer thickness, evaluated on the tensor grid of points by
  panel nodes (:func:`smooth_integrals`).

Units and scalings
------------------
Those of the model (:mod:`contactlib.model`): E* = R = 1, lengths in units of
the contact radius a (a_max in the incremental solver). Every operator has
shape (3, len(x), columns) with rows 0, 1, 2 the normal displacement w (into
the body), the tangential displacement u (away from the axis), both in
a^2/R per unit traction (E* a/R), and du/dx, at the points ``x``.

Examples
--------
>>> from contactlib.model import contact
>>> m = contact("sphere", 0.3)
>>> edges = np.linspace(0.0, 1.0, 5)
>>> step_operator(m, edges, 0.5 * (edges[1:] + edges[:-1]), "normal").shape
(3, 4, 4)
>>> operator_part(m, edges, edges, "shear").shape
(3, 5, 5)
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

import numpy as np

from .elements import Mesh, MeshStore, Store
from .influence import apply_difference, element_integrals
from ..kernels import thin_layer
from ..kernels.disc import gauss_tiers

if TYPE_CHECKING:
    from ..model import Contact

__all__ = ["PARTS", "parts_needed", "step_operator", "operator_part", "operators",
           "nodal_operator_part", "nodal_operators", "StickBlocks", "smooth_integrals",
           "restrict_nested", "restrict_with_slip_samples", "slip_zone_samples", "axis_w_rows",
           "u_difference_rows"]

PARTS = ("normal", "shear")
# measured: benchmarks/bench_layer.py (a layer's solve against the half-space's);
# tests/test_layer_contact.py checks the integrals against a 400-panel rule
_SMOOTH_POINTS = 8  # Gauss points a panel for the smooth remainder
# measured: benchmarks/bench_layer.py (a layer's solve against the half-space's);
# tests/test_layer_contact.py checks the integrals against a 400-panel rule
_SMOOTH_PANEL = 0.5  # longest panel, in layer thicknesses
# convention: scratch size (512 kB), the results do not depend on it
_RESTRICT_BLOCK = 1 << 16  # entries of restrict_nested's scratch (512 kB)
try:  # the compiled route of restrict_nested (setup.py; optional): the same bits
    from . import operators_fused as _fused
except ImportError:  # pragma: no cover - a build without a C compiler
    _fused = None
FUSED = _fused is not None
"""Whether :func:`restrict_nested` combines the columns compiled
(``contactlib/discretization/operators_fused.c``, built by ``pip install``): the same products and sums on
the same operands as its numpy route, so the same bits, in one pass a row
(``tests/test_kernels_fused.py``). False selects the numpy route."""

Kernel = Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray, np.ndarray]]


def parts_needed(geometry: Contact, stick_ratios: Sequence[float]) -> tuple[str, ...]:
    """The influence parts a set of cases needs: no shear when frictionless or nu = 0.5.

    Here rather than in :mod:`contactlib.stages` (which imports it) so that a scene's
    parts are known without importing the solvers (and scipy.linalg with them): the
    workflow asks for them in Snakemake's own process while it builds the DAG.
    """
    if geometry.decoupled or all(float(c) == 0.0 for c in stick_ratios):
        return ("normal",)
    return PARTS


def _kernel(model: Contact, part: str, with_w: bool = True, with_du: bool = True) -> Kernel:
    """The basic-load kernel of one part, as ``kernel(x, s) -> (w, u, du/dx)``."""
    if part == "normal":
        if with_w:
            return model.pressure_kernel
        return lambda xx, ss: model.pressure_kernel(xx, ss, with_w=False)
    if part == "shear":
        if with_du:
            return model.shear_kernel
        return lambda xx, ss: model.shear_kernel(xx, ss, with_du=False)
    raise ValueError(f"part must be 'normal' or 'shear', got {part!r}")


# ----------------------------------------------------------------------------- steps
def step_operator(model: Contact, edges: np.ndarray, x: np.ndarray, part: str) -> np.ndarray:
    """Displacements of unit step tractions on every element, shape (3, len(x), N).

    Parameters
    ----------
    model : Contact
    edges : ndarray, shape (N + 1,)
        Element edges, increasing from 0 (units a).
    x : ndarray, shape (m,)
        Evaluation points (>= 0, units a).
    part : {"normal", "shear"}
        A unit pressure on each element, or a unit shear coefficient (the
        traction is ``shape(r)``: r on a ring, +-1 on a strip pair).

    Returns
    -------
    ndarray, shape (3, m, N)
        w, u and du/dx at ``x`` (units a^2/R per unit traction; du/dx is
        log-infinite, and NaN here, where a point lies on an edge of a shear
        element).
    """
    kernel = _kernel(model, part)
    edges = np.asarray(edges, dtype=float)
    xx = np.asarray(x, dtype=float)[:, None]
    with np.errstate(invalid="ignore"):  # du/dx is log-infinite on element edges
        return np.diff(np.stack(kernel(xx, edges[None, :])), axis=2)


# ----------------------------------------------------------------------------- piecewise linear
def smooth_integrals(model: Contact, x: np.ndarray, nodes: np.ndarray,
                     part: str) -> np.ndarray | None:
    """Element integrals (3, len(x), N) of the model's smooth remainder, or None.

    ``G[k, i, j] = int_{nodes[j]}^{nodes[j+1]} R_k(x_i; s) ds`` with R
    :meth:`Contact.smooth_remainder` (None where the model has none). R is
    analytic with the layer thickness h as its length (its transform decays
    like exp(-2 k h)), so an 8-point Gauss rule on panels of at most h/2
    leaves ~(1/8)^16 relative; each element is cut into that many equal
    panels.
    """
    x = np.asarray(x, dtype=float).reshape(-1)
    nodes = np.asarray(nodes, dtype=float)
    h = model.body.thickness
    empty = np.empty(0)
    if not np.isfinite(h) or model.smooth_remainder(part, empty, empty) is None:
        return None  # (the empty probe: a slab under strips has no split kernels)
    lo, length = nodes[:-1], np.diff(nodes)
    panels = np.maximum(1, np.ceil(length / (_SMOOTH_PANEL * h))).astype(np.intp)
    owner = np.repeat(np.arange(lo.size), panels)  # element of each panel
    first = np.cumsum(panels) - panels  # each element's first panel
    k = np.arange(owner.size) - first[owner]  # panel index within its element
    plen = length[owner] / panels[owner]
    t, w = np.polynomial.legendre.leggauss(_SMOOTH_POINTS)
    s = (lo[owner] + plen * k)[:, None] + plen[:, None] * (0.5 * (t + 1.0))[None, :]
    weights = (0.5 * plen[:, None] * w[None, :]).ravel()
    return model.smooth_remainder(part, x, s.ravel(), weights,
                                  np.repeat(owner, _SMOOTH_POINTS))


def operator_part(model: Contact, nodes: np.ndarray, x: np.ndarray, part: str,
                  with_w: bool = True, with_du: bool = True) -> np.ndarray:
    """One displacement operator on nodal values, shape (3, len(x), N + 1).

    ``part="normal"``: of the nodal pressures p; ``part="shear"``: of the
    nodal shear coefficients phi. Row k = 0, 1, 2 gives w, u and du/dx at the
    points ``x`` (units E* = a = R = 1). ``with_w=False`` (normal) and
    ``with_du=False`` (shear) let the kernels skip an output they can skip
    cheaply (w as zeros, du/dx as NaN).
    """
    smooth = smooth_integrals(model, x, nodes, part)
    if smooth is None:
        g = element_integrals(_kernel(model, part, with_w, with_du), x, nodes)
    else:  # a layer: the half-space's singular kernels, plus the smooth remainder
        g = element_integrals(_kernel(model.half_space_twin, part, with_w, with_du), x, nodes)
        g += smooth
    # du/dx of an odd strip shear is log-infinite on the axis for every element
    # (the infinities cancel for a traction with q(0) = 0); it is never used
    # there, so the resulting inf - inf is left as NaN without a warning
    with np.errstate(invalid="ignore"):
        return apply_difference(g, nodes)


def _joint_kernel(model: Contact, with_w: bool = True,
                  with_du: bool = True) -> tuple[Kernel, Kernel]:
    """The pressure's and the shear's kernels, integrated together on the same points.

    :func:`~contactlib.discretization.influence.element_integrals` then classifies the (point, element)
    pairs and places the quadrature points once for both parts; each kernel is evaluated
    on exactly the points it would see alone, so each part's integrals are bit for bit
    those of its own call.
    """
    return _kernel(model, "normal", with_w), _kernel(model, "shear", with_du=with_du)


def _split_kernels(model: Contact) -> bool:
    """Whether a part's kernels are split into the half-space's and a smooth remainder."""
    empty = np.empty(0)
    return bool(np.isfinite(model.body.thickness)) and any(
        model.smooth_remainder(part, empty, empty) is not None for part in PARTS)


def operators(model: Contact, nodes: np.ndarray, x: np.ndarray,
              with_w: bool = True, with_du: bool = True,
              rows: tuple[int, ...] = (0, 1, 2)) -> tuple[np.ndarray, np.ndarray]:
    """Displacement operators on nodal values, each of shape (len(rows), len(x), N + 1).

    Returns ``(P, Q)`` with ``P[k] @ p`` and ``Q[k] @ phi`` the contributions to
    w (k = 0), u (1) and du/dx (2) at the points ``x``. ``with_w=False``
    leaves the pressure's w row unreliable (zeros for the sphere), which
    saves the elliptic integrals when only tangential displacements are needed;
    ``with_du=False`` leaves the shear's du/dx row NaN where that is cheaper (the
    disc). ``rows``: only these rows, in this order (the others' integrals are not
    formed). Equal bit for bit to the two :func:`operator_part` calls; both parts
    share one classification of the element pairs (one pass).
    """
    rows = tuple(rows)
    if _split_kernels(model):  # a layer: each part with its smooth remainder
        with thin_layer.both_kinds():  # (a thin layer's sums of both parts in one pass)
            return (operator_part(model, nodes, x, "normal", with_w)[list(rows)],
                    operator_part(model, nodes, x, "shear", with_du=with_du)[list(rows)])
    g = element_integrals(_joint_kernel(model, with_w, with_du), x, nodes,
                          outputs=rows + tuple(3 + k for k in rows))
    with np.errstate(invalid="ignore"):  # see operator_part: du/dx on a strip axis
        both = apply_difference(g, nodes)
    return both[:len(rows)], both[len(rows):]


class StickBlocks(Store):
    """Element integrals of reference stick meshes, kept for reuse across c/a.

    A bounded store (oldest entry dropped first) of the blocks
    :func:`nodal_operator_part` computes once per distinct (kernels, part,
    reference stick mesh). Memory: at most ``size`` blocks of 3 (M + 1) M
    doubles (64 blocks at n = 256: 19 MB). It carries the computation's
    graded meshes too (``meshes``, a :class:`~contactlib.discretization.elements.MeshStore`),
    so that the one store a caller threads through its solves serves both.
    """

    def __init__(self, size: int = 64) -> None:
        super().__init__(size)
        self.meshes = MeshStore()

    def clear(self) -> None:
        """Forget every block and every mesh."""
        super().clear()
        self.meshes.clear()


def nodal_operator_part(model: Contact, mesh: Mesh, part: str,
                        cache: StickBlocks | None = None) -> np.ndarray:
    """:func:`operator_part` at the mesh's own nodes, reusing the stick block across c.

    On the graded mesh the stick-zone nodes are c t_i with t_i fixed by
    (n, M, power), and where the kernels are homogeneous in length (the disc
    kernels of the half-space, see :meth:`Contact.length_degrees`) the
    element integrals of stick points over stick elements are c^d times
    those of the reference mesh t: a sweep over c/a computes that block once
    per distinct M (15 values for n a multiple of 16). Exact to round-off.

    Parameters
    ----------
    model : Contact
    mesh : Mesh
    part : {"normal", "shear"}
    cache : StickBlocks, optional
        Where the reference blocks are kept, owned by the caller (a sweep or
        a workflow job passes one store to all its cases); without one the
        block is computed for this call only. The reference block comes from
        the first c that needs it (``nodes / c`` equals t to round-off, not
        bit for bit across c), so within one store the last bits follow the
        order of the cases (k to ~1e-10); a call that owns its store gives
        the same bits whatever was computed before it in the process.
    """
    nodes, m, n = mesh.nodes, mesh.stick_index, mesh.n
    degrees = model.length_degrees(part) if part in PARTS else None
    if degrees is None or not 0 < m < n:
        return operator_part(model, nodes, nodes, part)
    c = float(nodes[m])
    kernel = _kernel(model, part)
    # nodes / c equals the generator's t_i to round-off, not bit for bit across c: the
    # key rounds them, the block is computed from the exact nodes of the first c that
    # needs it (rounding the nodes themselves would move the elements of ~1e-11 a next to
    # c by a relative 1e-3)
    ref_nodes = nodes[:m + 1] / c
    key = (model.indenter, model.body, part, np.round(ref_nodes, 13).tobytes())

    def compute() -> np.ndarray:
        return element_integrals(kernel, ref_nodes, ref_nodes)

    ref = compute() if cache is None else cache.get(key, compute)
    op = np.empty((3, n + 1, n + 1))
    g = op[:, :, :n]  # the element integrals, turned into the operator in place
    np.multiply(ref, (c ** degrees)[:, None, None], out=g[:, :m + 1, :m])
    element_integrals(kernel, nodes[:m + 1], nodes[m:], out=g[:, :m + 1, m:])
    element_integrals(kernel, nodes[m + 1:], nodes, out=g[:, m + 1:, :])
    return apply_difference(g, nodes, out=op)


def nodal_operators(model: Contact, mesh: Mesh,
                    cache: StickBlocks | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Both parts of :func:`nodal_operator_part`, ``(P, Q)``, in one pass over each block.

    Equal bit for bit to ``nodal_operator_part(model, mesh, "normal", cache)`` and
    ``(..., "shear", cache)`` called in turn (the same stick blocks in ``cache``): the
    two parts' kernels are integrated on the same points, classified once
    (:func:`_joint_kernel`): the classification and packing of the element pairs are
    done once instead of twice.
    """
    nodes, m, n = mesh.nodes, mesh.stick_index, mesh.n
    degrees = [model.length_degrees(part) for part in PARTS]
    if not 0 < m < n or all(d is None for d in degrees):  # (no stick block to reuse: one
        return operators(model, nodes, nodes)  # joint pass, the same bits as each part alone)
    if any(d is None for d in degrees):
        return tuple(nodal_operator_part(model, mesh, part, cache) for part in PARTS)
    c = float(nodes[m])
    joint = _joint_kernel(model)
    ref_nodes = nodes[:m + 1] / c  # (see nodal_operator_part: the key and the block)
    keys = [(model.indenter, model.body, part, np.round(ref_nodes, 13).tobytes())
            for part in PARTS]
    scale = np.concatenate([c ** d for d in degrees])
    both = np.empty((6, n + 1, n + 1))
    g = both[:, :, :n]  # the element integrals, turned into the operators in place
    if cache is None:  # the reference block written in place, then scaled (the same bits)
        element_integrals(joint, ref_nodes, ref_nodes, out=g[:, :m + 1, :m])
        g[:, :m + 1, :m] *= scale[:, None, None]
    else:
        if not any(key in cache for key in keys):
            ref = element_integrals(joint, ref_nodes, ref_nodes)
            blocks = [ref[:3], ref[3:]]
            for key, block in zip(keys, blocks):
                cache.get(key, lambda block=block: block)
            cache.misses -= 1  # (one computation for the two entries)
        else:  # one part stored already: the other alone, as nodal_operator_part would
            blocks = [cache.get(key, lambda part=part: element_integrals(
                _kernel(model, part), ref_nodes, ref_nodes)) for key, part in zip(keys, PARTS)]
        np.multiply(blocks[0], scale[:3, None, None], out=g[:3, :m + 1, :m])
        np.multiply(blocks[1], scale[3:, None, None], out=g[3:, :m + 1, :m])
        del blocks
    element_integrals(joint, nodes[:m + 1], nodes[m:], out=g[:, :m + 1, m:])
    element_integrals(joint, nodes[m + 1:], nodes, out=g[:, m + 1:, :])
    apply_difference(g, nodes, out=both)
    return both[:3], both[3:]


def restrict_nested(op: np.ndarray, fine: Mesh, odd_parts: tuple[int, ...] | None = None,
                    odd_from: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """A nodal operator of the nested mesh with every other node, from the fine one.

    The coarse hat functions are piecewise linear on the fine mesh (1 at their
    node, linear interpolation at the fine nodes between), so their columns
    are exact combinations of the fine columns; the coarse nodes are the even
    fine nodes and the coarse element midpoints... are not the odd ones on a
    graded mesh, so the odd rows (``at_odd``) are the operator at the odd
    fine nodes. Returns ``(at_nodes, at_odd)``; no kernel is evaluated.

    ``op`` has shape (parts, N + 1, N + 1); ``at_nodes`` every part at the even rows,
    ``at_odd`` the parts ``odd_parts`` (default all) at the odd rows from the
    ``odd_from``-th on (fine node 2 odd_from + 1): callers that sample u and du/dx in the
    slip zone restrict only those (a third less work than every odd row of every part). Every
    entry is the same bits whatever is asked.
    """
    x = fine.nodes
    left = (x[2::2] - x[1::2]) / (x[2::2] - x[:-1:2])  # weight of node 2j at 2j+1
    right = 1.0 - left
    parts = range(op.shape[0]) if odd_parts is None else odd_parts
    at_nodes = np.empty((op.shape[0], (op.shape[1] + 1) // 2, left.size + 1))
    for p in range(op.shape[0]):
        _restrict_columns(op[p, ::2], left, right, at_nodes[p])
    rows = op[0, 2 * odd_from + 1::2].shape[0]
    at_odd = np.empty((len(parts), rows, left.size + 1))
    for i, p in enumerate(parts):
        _restrict_columns(op[p, 2 * odd_from + 1::2], left, right, at_odd[i])
    return at_nodes, at_odd


def restrict_with_slip_samples(ops: tuple[np.ndarray, np.ndarray], fine: Mesh
                               ) -> tuple[tuple[np.ndarray, np.ndarray], tuple]:
    """Both parts' nodal operators restricted to the nested mesh with every other node, and
    what samples u and du/dx inside its slip elements (no kernel is evaluated).

    Returns ``((P, Q), odd)``: ``P`` and ``Q`` the coarse operators (:func:`restrict_nested`),
    ``odd = (x, P_odd, Q_odd)`` the odd fine nodes of the slip zone (one inside each coarse
    slip element) and the u and du/dx rows there, for :func:`slip_zone_samples`.
    """
    first = fine.stick_index // 2  # the coarse stick index: odd nodes from 2 first + 1 on
    (pc, po), (qc, qo) = (restrict_nested(op, fine, odd_parts=(1, 2), odd_from=first)
                          for op in ops)
    return (pc, qc), (fine.nodes[2 * first + 1::2], po, qo)


def slip_zone_samples(odd: tuple, p: np.ndarray, phi: np.ndarray) -> tuple:
    """(x, u, du/dx) inside the coarse slip elements of a solution (nodal ``p`` and ``phi``)
    from ``odd`` of :func:`restrict_with_slip_samples` (a ``DiscreteSolution``'s
    ``interior_samples``)."""
    x, po, qo = odd
    return x, po[0] @ p + qo[0] @ phi, po[1] @ p + qo[1] @ phi


def _restrict_columns(rows: np.ndarray, left: np.ndarray, right: np.ndarray,
                      out: np.ndarray) -> None:
    """out = the fine columns of ``rows`` combined into the coarse ones (rows a block at a
    time: small scratch, the same operations as on the whole array; compiled where built,
    :data:`FUSED`: one pass a row, the same bits)."""
    if FUSED and rows.shape[0] and rows.strides[1] == rows.itemsize:
        with np.errstate(invalid="ignore"):
            _fused.restrict(rows, left, right, out)
        return
    even, odd = rows[:, ::2], rows[:, 1::2]
    step = max(1, _RESTRICT_BLOCK // max(odd.shape[-1], 1))
    tmp = np.empty((min(step, odd.shape[0]), odd.shape[-1]))
    with np.errstate(invalid="ignore"):  # du/dx on a strip axis is NaN (see operators)
        for r0 in range(0, out.shape[0], step):
            o = out[r0:r0 + step]
            t = tmp[:o.shape[0]]
            o[...] = even[r0:r0 + step]
            np.multiply(odd[r0:r0 + step], left, out=t)
            o[:, :-1] += t
            np.multiply(odd[r0:r0 + step], right, out=t)
            o[:, 1:] += t

def axis_w_rows(model: Contact, nodes: np.ndarray, x: np.ndarray, part: str,
                ref: float = 0.0, quadrature: str = "standard") -> np.ndarray:
    """w(x) - w(ref) of the nodal values, shape (len(x), N + 1), without cancellation.

    The normal rows of :func:`operator_part` minus its row at the axis, from
    the kernels' own differences (:meth:`~contactlib.model.Contact.axis_w_kernel`).
    Near the axis w(x) - w(0) is O(x^2) while w is O(1): rows formed by
    subtracting the operator's rows keep an absolute round-off of ~1e-16,
    which is all of the signal of a stick zone of c/a = 1e-8 (the default
    method's normal rows there, see :func:`contactlib.solvers.default_method.assemble`).
    A node ``ref`` > 0 gives the rows relative to it (a thin slip annulus).
    Units as :func:`operator_part` (a^2/R per unit traction). ``quadrature``: the
    element rules (:data:`contactlib.discretization.influence.QUADRATURES`).
    """
    if part not in PARTS:
        raise ValueError(f"part must be 'normal' or 'shear', got {part!r}")

    def kernel(xx: np.ndarray, ss: np.ndarray):
        return model.axis_w_kernel(xx, ss, part, ref)

    g = element_integrals(kernel, np.asarray(x, dtype=float), nodes,
                          ref=ref if ref > 0.0 else None, outputs=(0,), quadrature=quadrature)
    return apply_difference(g, nodes)[0]


def u_difference_rows(model: Contact, nodes: np.ndarray, x: np.ndarray, part: str,
                      ref: float, quadrature: str = "standard") -> np.ndarray:
    """u(x) - u(ref) of the nodal values, shape (len(x), N + 1), without cancellation.

    For each (point, load radius) sample the kernel difference is the
    Gauss-Legendre integral (6, 10 or 16 points by distance,
    :func:`contactlib.kernels.disc.gauss_tiers`) of the kernel's own du/dx over the
    interval between ``ref`` and x where the load edge s lies at least the
    interval's length from it (the singularity of du/dx at s is then far
    enough for a relative error below 1e-16), else the plain difference of
    u (both points then within a few interval lengths of s). The rows of a
    thin slip annulus's stick condition (:func:`contactlib.solvers.default_method.assemble`):
    there u is O(beta) while its variation across the annulus is O(width).
    Units as :func:`operator_part`; ``quadrature`` as :func:`axis_w_rows`.
    """
    if part not in PARTS:
        raise ValueError(f"part must be 'normal' or 'shear', got {part!r}")
    kern = _kernel(model, part, with_w=False)

    def kernel(xx: np.ndarray, ss: np.ndarray):
        length = xx - ref
        gap = np.maximum(np.maximum(ss - np.maximum(xx, ref), np.minimum(xx, ref) - ss), 0.0)
        out = np.empty(xx.shape)
        smooth = np.zeros(xx.shape, dtype=bool)
        for tier, gt, gw in gauss_tiers(gap, np.abs(length)):
            if tier.any():
                ls, sv = length[tier], ss[tier]
                t = ref + ls[None, :] * gt[:, None]
                du = np.asarray(kern(t, np.broadcast_to(sv, t.shape))[2]).reshape(t.shape)
                out[tier] = ls * (gw @ du)
                smooth |= tier
        rest = ~smooth
        if rest.any():
            sv = ss[rest]
            out[rest] = (np.asarray(kern(xx[rest], sv)[1])
                         - np.asarray(kern(np.full(sv.shape, ref), sv)[1]))
        zero = np.zeros(xx.shape)
        return out, zero, zero

    g = element_integrals(kernel, np.asarray(x, dtype=float), nodes, ref=ref, outputs=(0,),
                          quadrature=quadrature)
    return apply_difference(g, nodes)[0]
