"""Stresses inside the elastic bodies under the solved surface tractions (issue 38).

The body is the elastic half-space (sphere, axisymmetric) or half-plane (cylinder, plane
strain) z >= 0 under a pressure p and a shear q on its surface z = 0, both tabulated on
``xi`` = r/a (x/a) in [0, 1], continuous and piecewise linear between the tabulated
points, zero outside; or a layer on a rigid base, or a coated body. Lengths are in units
of a, stresses in the unit of the tabulated tractions (p0 for a
:class:`~contactlib.result.Solution`). Signs: tension positive, z positive into the body,
p positive in compression and q the traction on the body, positive away from the axis, so
that the surface limits are sigma_zz = -p and sigma_rz = -q (sigma_xz = -q for x > 0)
(docs/conventions.md). The cylinder's shear is odd in x: q(-x) = -q(x).

One concern a module; every public name of the axisymmetric and plane fields is
re-exported here, so ``contactlib.stresses.X`` and ``from contactlib.stresses import X``
are the way to use them:

* :mod:`contactlib.stresses.inputs`: the tractions and the grid checked
  (:func:`check_tractions`, :func:`check_grid`), :data:`COMPONENTS`, :data:`CHUNK`;
* :mod:`contactlib.stresses.halfplane`: the half-plane's field in closed form
  (:func:`halfplane_stresses`, :func:`halfplane_stresses_line`);
* :mod:`contactlib.stresses.quadrature`: the xi quadrature of the half-space's Hankel
  integrals (:func:`xi_nodes`, :data:`PANEL`, :data:`TAIL_PERIODS`, :data:`DEPTH_CUTOFF`,
  :data:`XI_SURFACE`);
* :mod:`contactlib.stresses.pieces`: the tractions as linear pieces and their Hankel
  transforms in closed form (:class:`TractionPieces`);
* :mod:`contactlib.stresses.surface`: the half-space's surface row under a radial shear,
  in closed form (:data:`RING_TANH_SINH`, :data:`RING_GAUSS`);
* :mod:`contactlib.stresses.halfspace`: the half-space's field
  (:func:`halfspace_stresses`);
* :mod:`contactlib.stresses.layer`: the correction of a layer on a rigid base or on an
  elastic substrate (its notes give the method);
* :mod:`contactlib.stresses.dispatch`: which field a body gets (:func:`stress_field`,
  :func:`layer_stresses`, :func:`body_field`);
* :mod:`contactlib.stresses.measures`: :func:`principal_stresses`, :func:`von_mises`,
  :func:`tresca`, :func:`hydrostatic`, :func:`derived_measures`, :func:`field_maximum`;
* :mod:`contactlib.stresses.solution`: the field under a solved case as a Dataset
  (:func:`subsurface_stresses`, :func:`surface_radial_stress`, :func:`first_yield`);
* :mod:`contactlib.stresses.datasets`: the field added to a solve's dataset and to a
  scene's (:func:`with_subsurface`, :func:`scene_subsurface`, :func:`default_grid`,
  :func:`check_subsurface_request`);
* :mod:`contactlib.stresses.estimate`: :func:`field_error_estimate`;
* :mod:`contactlib.stresses.history`: :func:`history_stresses`, a step of a loading
  history;
* :mod:`contactlib.stresses.fretting`: :func:`cylinder_fretting_stresses`, a step of a
  cylinder's fretting path;
* :mod:`contactlib.stresses.tangential` (a tangential load along x on the sphere) and
  :mod:`contactlib.stresses.grid` (cell-wise constant tractions, the sphere's fretting
  steps): Cartesian fields, used through their own module paths.

Each module's notes give its method and its measured error.
"""

from __future__ import annotations

from contactlib.stresses.datasets import (check_subsurface_request, default_grid,
                                          scene_subsurface, with_subsurface)
from contactlib.stresses.dispatch import body_field, layer_stresses, stress_field
from contactlib.stresses.estimate import field_error_estimate
from contactlib.stresses.fretting import cylinder_fretting_stresses
from contactlib.stresses.halfplane import halfplane_stresses, halfplane_stresses_line
from contactlib.stresses.halfspace import SUM_CHUNK, halfspace_stresses
from contactlib.stresses.history import history_stresses
from contactlib.stresses.inputs import CHUNK, COMPONENTS, check_grid, check_tractions
from contactlib.stresses.measures import (derived_measures, field_maximum, hydrostatic,
                                          principal_stresses, tresca, von_mises)
from contactlib.stresses.pieces import (INTEGRAL_J0_ASYMPTOTIC, INTEGRAL_J0_SWITCH,
                                        TractionPieces)
from contactlib.stresses.quadrature import (DEPTH_CUTOFF, DEPTH_PANEL, PANEL, TAIL_PERIODS,
                                            XI_SURFACE, xi_nodes)
from contactlib.stresses.solution import (first_yield, subsurface_stresses,
                                          surface_radial_stress, traction_samples)
from contactlib.stresses.surface import RING_GAUSS, RING_SERIES_M, RING_TANH_SINH

__all__ = ["halfplane_stresses", "halfplane_stresses_line", "halfspace_stresses",
           "stress_field", "principal_stresses", "von_mises", "tresca", "hydrostatic",
           "derived_measures", "subsurface_stresses", "field_maximum",
           "surface_radial_stress", "default_grid", "check_subsurface_request", "body_field",
           "with_subsurface", "first_yield", "history_stresses", "scene_subsurface",
           "cylinder_fretting_stresses",
           "field_error_estimate", "layer_stresses", "COMPONENTS", "XI_SURFACE", "PANEL",
           "CHUNK", "DEPTH_CUTOFF", "TAIL_PERIODS", "RING_TANH_SINH", "RING_GAUSS",
           "TractionPieces", "xi_nodes", "check_tractions",
           "check_grid"]
# public before the split, outside __all__ (kept out of `import *` and the reference page).
# The tuned constants are read where they are used: set them there (e.g.
# contactlib.stresses.quadrature.PANEL), not here.
_ALSO_PUBLIC = (DEPTH_PANEL, INTEGRAL_J0_ASYMPTOTIC, INTEGRAL_J0_SWITCH, RING_SERIES_M,
                SUM_CHUNK, traction_samples)
