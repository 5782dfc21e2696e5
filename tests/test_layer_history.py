"""The history solver on a layer (h fixed while a grows): sphere, nu = 0.3, k = 0.2.

Truths, none computed with the code under test:

* a_max/h -> 0 is the half-space: the same cycle work within its estimate;
* monotonic loading on a layer is self-similar only approximately (a/h grows
  with a), so its c/a departs from the self-similar c/a(k) at the final a/h
  by a measured amount, while at a_max/h = 1e-3 it matches as on the
  half-space;
* energy balance: external work = stored energy + frictional work, the
  three computed apart (the indenter's work, <sigma, d>/2, the shear's work
  on the slip).

Measured numbers: docs/validation.md (Layers, history on a layer).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
import pytest

import contactlib
from conftest import trapezoid_work
from contactlib import history

NU, K, N, STEPS = 0.3, 0.2, 240, 100


@lru_cache(maxsize=None)
def _cycle(ratio: float, base: str):
    return history("sphere", NU, K, [0, 1, 0], STEPS, n=N, slab_ratio=ratio, base=base)


@pytest.mark.parametrize("base", ["smooth", "bonded"])
def test_vanishing_layer_gives_the_half_space_cycle_work(base):
    """a_max/h = 1e-3: cycle work within the work error estimate of the half-space's.

    Measured: relative difference -5.4e-6 (smooth), -5.9e-6 (bonded), estimate 8.0e-3.
    """
    half, layer = _cycle(0.0, "smooth"), _cycle(1e-3, base)
    assert half.converged.all() and layer.converged.all()
    gap = abs(layer.frictional_work[-1] / half.frictional_work[-1] - 1.0)
    assert gap <= half.work_error_estimate[-1]
    assert gap < 1e-4


@pytest.mark.slow  # (fast tier: test_vanishing_layer_gives_the_half_space_cycle_work)
@pytest.mark.parametrize("base", ["smooth", "bonded"])
def test_cycle_work_falls_with_the_layer_ratio(base):
    """W(a_max/h) for 0, 0.5, 1, 2 decreases by more than its error estimates.

    Measured W/W_half-space: smooth 0.323, 0.0454, 0.0024; bonded 0.333,
    0.0684, 0.0101 (estimates 2.3 %, 12 %, 70 % / 2.4 %, 4 %, 59 %: the slip
    annulus spans 23, 5, 2 / 24, 8, 3 elements at n = 240).
    """
    runs = [_cycle(0.0, "smooth")] + [_cycle(r, base) for r in (0.5, 1.0, 2.0)]
    w = np.array([res.frictional_work[-1] for res in runs])
    err = np.array([res.work_error_estimate[-1] for res in runs])
    assert all(res.converged.all() for res in runs)
    assert np.all(w[1:] * (1 + err[1:]) < w[:-1] * (1 - err[:-1]))
    assert 0.30 < w[1] / w[0] < 0.36 and err[1] < 0.03  # resolved at a_max/h = 0.5


@pytest.mark.parametrize("base", ["smooth", pytest.param("bonded", marks=pytest.mark.slow)])
def test_monotonic_loading_is_only_approximately_self_similar_on_a_layer(base):
    """c/a at P_max against the self-similar c/a(k) on the same layer at the final a/h.

    Measured departures (history above self-similar): a_max/h = 1e-3: +5.6e-4
    (the half-space's own, element a_max/200); 0.5: +11.4 % (smooth), +9.9 %
    (bonded); 1: +5.4 %, +4.5 % (slip annulus 5 and 8 elements). Stick radius
    estimates <= 5e-3 a_max; self-similar error estimates <= 4e-5.
    """
    deps = {}
    for ratio in (1e-3, 0.5, 1.0):
        res = _cycle(ratio, base)
        a, c = res.contact_radius[STEPS], res.stick_ratio[STEPS]  # at P_max
        ref = contactlib.solve("sphere", NU, friction=K, n=256, slab_ratio=ratio * a, base=base,
                               energy=False)
        assert ref.resolved and ref.consistent
        deps[ratio] = c / ref.stick_ratio - 1.0
    assert abs(deps[1e-3]) < 2e-3
    assert 0.08 < deps[0.5] < 0.14
    assert 0.03 < deps[1.0] < 0.07


@pytest.mark.parametrize("base", ["smooth", "bonded"])
@pytest.mark.parametrize("ratio", [0.5, 1.0, 2.0])
def test_energy_balance_holds_at_every_step_on_a_layer(ratio, base):
    """external = stored + frictional, step by step (loading: to 1e-4, well inside 1e-3).

    Measured: during loading within 1.1e-5 of the external work; over the
    cycle within 3.2e-6 of the peak external work. At the end of unloading
    the external work shrinks to the cycle's work, which on thin layers is
    small (2.4e-3 of the half-space's at a_max/h = 2, smooth), so the same
    residual is 0.17 %, 0.78 %, 12 % (smooth) and 0.13 %, 0.27 %, 0.21 %
    (bonded) of it at a_max/h = 0.5, 1, 2. The balance is that of the shear's
    work on the surface (trapezoid sums): ``frictional_work`` is their lower
    monotone envelope (no step dissipates a negative amount), lower only
    before a fall of the sums.
    """
    res = _cycle(ratio, base)
    rest = np.abs(res.external_work - res.stored_energy - trapezoid_work(res))
    loading = slice(1, STEPS + 1)
    assert np.all(rest[loading] <= 1e-4 * res.external_work[loading])
    assert np.all(rest <= 1e-5 * res.external_work.max())
