"""Stresses inside the elastic bodies under the solved surface tractions (issue 38).

The field numerics live in :mod:`contactlib.stresses.halfspace` (moved there unchanged from
``contactlib/stresses.py``); every public name is re-exported here, so ``contactlib.stresses.X``
and ``from contactlib.stresses import X`` are the way to use them.
"""

from __future__ import annotations

from contactlib.stresses.halfspace import (
    CHUNK, COMPONENTS, DEPTH_CUTOFF, DEPTH_PANEL, INTEGRAL_J0_ASYMPTOTIC, INTEGRAL_J0_SWITCH,
    PANEL, RING_GAUSS, RING_SERIES_M, RING_TANH_SINH, SUM_CHUNK, TAIL_PERIODS, XI_SURFACE,
    TractionPieces, body_field, check_grid, check_subsurface_request, check_tractions,
    cylinder_fretting_stresses, default_grid, derived_measures, field_error_estimate,
    field_maximum, first_yield, halfplane_stresses, halfplane_stresses_line, halfspace_stresses,
    history_stresses, hydrostatic, layer_stresses, principal_stresses, scene_subsurface,
    stress_field, subsurface_stresses, surface_radial_stress, traction_samples, tresca,
    von_mises, with_subsurface, xi_nodes)

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
# public before the split, outside __all__ (kept out of `import *` and the reference page)
_ALSO_PUBLIC = (DEPTH_PANEL, INTEGRAL_J0_ASYMPTOTIC, INTEGRAL_J0_SWITCH, RING_SERIES_M,
                SUM_CHUNK, traction_samples)
