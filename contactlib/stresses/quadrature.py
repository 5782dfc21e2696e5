"""The xi quadrature of the half-space's Hankel integrals.

Gauss-Legendre on panels of width ``PANEL/(1 + max r)`` = 2 pi/(1 + max r) (8 points each;
beyond the first few, panels of ``TAIL_PERIODS`` such widths with 32 points) up to
``DEPTH_CUTOFF``/z_min = 36/z_min (e^{-36} < 3e-16), where z_min is the smallest positive
depth asked for; near xi = 0 the panels are graded for the deepest point (``DEPTH_PANEL``).
Halving the panels changes the field by 9.5e-15 p0 (benchmarks/bench_stresses.py).
:func:`xi_nodes` gives the plain panels (the layer's correction and the tangential field
use them), :func:`halfspace_nodes` the graded ones and the tail.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["XI_SURFACE", "DEPTH_CUTOFF", "PANEL", "TAIL_PERIODS", "xi_nodes", "DEPTH_PANEL",
           "halfspace_nodes"]

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


def halfspace_nodes(xi_max: float, r_max: float, z_max: float = 0.0
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
