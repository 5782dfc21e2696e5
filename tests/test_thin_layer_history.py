"""History of a sphere on thin layers and thin coatings: a_max/h beyond the ring tables.

Beyond a_max/h = 16.7 the history's ring kernels come from the transform-domain sums
(``kernels.thin_layer``) and its mesh is sized by a frictionless probe
(``history_api.layer_extent``). The truths:

* the frictionless contact radius at P_max is the root of L(a/h) a^3 = 1, L the
  self-similar frictionless solve's load over Hertz's at that a/h (an independent
  solver: the default method on its own mesh);
* energy balance (external work = stored energy + frictional work) with friction.

Measured (n = 120, 10 steps): a_top against the root, a_max/h = 30 bonded 0.45928 against
0.45952, 100 smooth 0.35857 against 0.35919, 1000 bonded 0.19216 against 0.19282,
100 on a substrate ten times stiffer 0.50791 against 0.50870.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import brentq

import contactlib
from contactlib import history, validate
from contactlib.history_api import layer_extent
from contactlib.model import contact

NU = 0.3
N = 120


def _root(slab: float, base: str, **kw) -> float:
    """a/a_max where the frictionless self-similar load on the layer equals P_max."""

    def gap(a):
        sol = contactlib.solve("sphere", NU, friction=0.0, n=128, slab_ratio=a * slab,
                               base=base, energy=False, **kw)
        return sol.load_ratio * a ** 3 - 1.0

    return brentq(gap, 0.05, 1.0, xtol=1e-6)


@pytest.mark.parametrize("slab, base, kw", [
    (30.0, "bonded", {}), (100.0, "smooth", {}), (1000.0, "bonded", {}),
    (100.0, "elastic", {"substrate_modulus": 10.0})])
def test_frictionless_contact_radius_matches_the_self_similar_solve(slab, base, kw):
    """Within one element of the history's mesh (which the probe sized to 1.2 times the
    contact, so that the contact spans about 100 of its 120 elements)."""
    res = history("sphere", NU, 0.0, [0, 1], 10, n=N, slab_ratio=slab, base=base,
                  error_estimate=False, **kw)
    element = res.xi_bounds[0, 1]
    assert res.converged.all() and "end of the mesh" not in res.message
    assert res.mesh_extent < 1.0  # the contact stays well inside a_max: a finer mesh
    assert res.contact_radius[-1] > 0.75 * res.mesh_extent
    assert abs(res.contact_radius[-1] - _root(slab, base, **kw)) <= element


def test_thin_layers_keep_the_energy_balance_with_friction():
    """external = stored + frictional at every step of a cycle (a_max/h = 300, bonded,
    k = 0.2), within 1e-5 of the peak external work."""
    res = history("sphere", NU, 0.2, [0, 1, 0], 40, n=N, slab_ratio=300.0, base="bonded")
    rest = np.abs(res.external_work - res.stored_energy - res.frictional_work)
    assert res.converged.all()
    assert np.all(rest <= 1e-5 * res.external_work.max())
    assert res.frictional_work[-1] > 0.0
    assert np.all(np.isfinite(res.work_error_estimate[1:]))


def test_the_mesh_is_the_old_one_where_the_tables_reach():
    """a_max/h <= 16.7 on a rigid base: the mesh stays 1.2 a_max (the numbers of the
    runs before thin layers do not move)."""
    model = contact("sphere", NU, 16.0, base="bonded")
    assert layer_extent(model, "sphere", 16.0) == 1.2


def test_a_contact_beyond_the_kernels_reach_is_refused_with_its_range():
    """A soft substrate at a_max/h = 1000: the contact (about 2 a_max) would need 2000 h,
    beyond the 1200 h of the thin sums: refused naming slab_ratio, the range in the
    message."""
    with pytest.raises(validate.InputError, match=r"slab_ratio.*1200 h"):
        history("sphere", NU, 0.0, [0, 1], 4, n=32, slab_ratio=1000.0, base="elastic",
                substrate_modulus=0.1, error_estimate=False)


def test_beyond_1000_is_refused_with_the_supported_range():
    with pytest.raises(validate.InputError, match="<= 1000"):
        history("sphere", NU, 0.2, [0, 1], 4, n=32, slab_ratio=1001.0, base="bonded")


@pytest.mark.parametrize("slab", [100.0, 1000.0])
def test_a_creeping_thin_layer_meshes_its_crept_contact(slab):
    """A viscoelastic layer (E(inf)/E(0) = 0.5, bonded base), loaded fast and held for
    1000 tau: the frictionless contact creeps to the elastic layer's at E(inf), the root of
    L(a/h) a^3 = 1/g_inf (the self-similar solve, an independent solver), within one
    element. The mesh is sized by a probe at E(inf) (about 1.2 times that contact), no
    longer by the half-space's crept radius 1.51 a_max, which left a quarter of the
    elements on the contact at a_max/h = 100 and refused a_max/h = 1000 (1510 h > 1200 h).
    Measured: 0.40714 against 0.40682 (a_max/h = 100, mesh 0.512 a_max), 0.22905 against
    0.22934 (1000, mesh 0.292 a_max); elements 0.0043 and 0.0024 a_max."""
    res = history("sphere", NU, 0.0, [0, 1, 1], 10, n=N, slab_ratio=slab, base="bonded",
                  relaxation=[(0.5, 1.0)], duration=[1e-6, 1e3], error_estimate=False)

    def gap(a):
        sol = contactlib.solve("sphere", NU, friction=0.0, n=64, slab_ratio=a * slab,
                               base="bonded", energy=False)
        return sol.load_ratio * a ** 3 - 2.0

    root = brentq(gap, 0.2, 0.6, xtol=1e-5)
    assert res.converged.all() and "end of the mesh" not in res.message
    assert res.mesh_extent < 1.3 * root + 2.0 * res.xi_bounds[0, 1]
    assert abs(res.contact_radius[-1] - root) <= res.xi_bounds[0, 1]
    assert res.contact_radius[10] < 0.9 * root  # the fast loading's contact, before creep
