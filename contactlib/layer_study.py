r"""k(c/a), the frictionless load and the work per cycle on layers against a/h.

The ``layers`` target's numbers. For each geometry (sphere, cylinder), base
(smooth, bonded), Poisson's ratio and layer ratio a/h, one self-similar
sweep (default method) gives the frictionless load ratio P/P_Hertz (c/a = 0)
and the friction coefficient k at the chosen stick ratios, each with its
error estimate and ``resolved`` flag; a/h is held fixed while the contact
grows (see docs/theory.md, "Layers"). One incremental history (load 0 -> 1
-> 0 at one friction coefficient, :func:`contactlib.history`) gives the
frictional work of that load cycle with its error estimate; there a/h is
a_max/h, the layer ratio at the peak load, and a/h changes while a grows.
:func:`contactlib.io.layer_study_to_dataset` turns the result into a
dataset; :func:`contactlib.plot.fig_layers` draws it.

Units and scalings: those of :func:`contactlib.solve` (k dimensionless,
P/P_Hertz at the same contact radius, ``slab_ratio`` = a/h, 0 the half-space
or half-plane).

Examples
--------
>>> from contactlib.layer_study import layer_study
>>> st = layer_study(geometries=("sphere",), bases=("bonded",), nus=(0.3,),
...                  ratios=(0.0, 1.0), stick_ratios=(0.5,), n=32, history_friction=None)
>>> st.friction.shape, round(float(st.load_ratio[0, 0, 0, 0]), 3)
((1, 1, 1, 2, 1), 1.0)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from . import validate
from .api import sweep
from .history_api import history
from .result import short_repr

__all__ = ["LayerStudy", "layer_study", "DEFAULT_RATIOS", "DEFAULT_NUS",
           "DEFAULT_STICK_RATIOS", "HISTORY_MAX_ERROR"]

# convention: the study's grid of a/h (0: the half-space)
DEFAULT_RATIOS = (0.0, 0.5, 1.0, 2.0, 5.0, 10.0)
# convention: the study's Poisson's ratios
DEFAULT_NUS = (0.3, 0.45)
# convention: the study's stick ratios
DEFAULT_STICK_RATIOS = (0.25, 0.5, 0.75)
# the accuracy a cycle's work must reach to count as resolved: that of the main job's
# history scenes (config/config.yaml); on layers with a_max/h >= 1 even 1e-2 takes
# n ~ 960 and 400 steps a segment (docs/validation.md, "History on a layer")
# convention: that of the main job's history scenes (config/config.yaml)
HISTORY_MAX_ERROR = 1e-2


@dataclass(repr=False)
class LayerStudy:
    """Frictionless load and k on layers, indexed (geometry, base, nu, a/h[, c/a]).

    Attributes
    ----------
    geometries, bases, nus, ratios, stick_ratios : tuple
        The axes (``ratios``: a/h).
    n : int
        Elements of every solve (default method).
    load_ratio, load_error_estimate : ndarray, shape (G, B, V, R)
        Frictionless P/P_Hertz(a) and its estimated relative error.
    friction, error_estimate : ndarray, shape (G, B, V, R, C)
        k at each stick ratio and its estimated relative error.
    resolved : ndarray of bool, shape (G, B, V, R, C)
        The case converged, is consistent and its estimate is within 1e-3
        (thin bonded layers whose slip reverses are not).
    history_friction : float or None
        k of the load cycles (None: no histories; the arrays below are NaN).
    history_n, history_steps : int
        Elements and load steps a segment of each history.
    cycle_work, cycle_work_error_estimate : ndarray, shape (G, B, V, R)
        Frictional work of the load cycle 0 -> 1 -> 0 (the scaling of
        :func:`contactlib.history`: V R^2/(E* a_max^5) for the sphere, per
        unit length with a_max^4 for the cylinder) and its estimated
        relative error.
    cycle_resolved : ndarray of bool, shape (G, B, V, R)
        Every step of the history converged and the work's estimate is
        within :data:`HISTORY_MAX_ERROR`.
    """

    __repr__ = short_repr

    geometries: tuple[str, ...]
    bases: tuple[str, ...]
    nus: tuple[float, ...]
    ratios: tuple[float, ...]
    stick_ratios: tuple[float, ...]
    n: int
    load_ratio: np.ndarray
    load_error_estimate: np.ndarray
    friction: np.ndarray
    error_estimate: np.ndarray
    resolved: np.ndarray
    history_friction: float | None = None
    history_n: int = 0
    history_steps: int = 0
    cycle_work: np.ndarray | None = None
    cycle_work_error_estimate: np.ndarray | None = None
    cycle_resolved: np.ndarray | None = None


def layer_study(geometries: Sequence[str] = validate.GEOMETRIES,
                bases: Sequence[str] = validate.BASES,
                nus: Sequence[float] = DEFAULT_NUS,
                ratios: Sequence[float] = DEFAULT_RATIOS,
                stick_ratios: Sequence[float] = DEFAULT_STICK_RATIOS,
                n: int = 128, history_friction: float | None = 0.2,
                history_n: int = 240, history_steps: int = 100) -> LayerStudy:
    """Solve every (geometry, base, nu, a/h): one sweep over c/a = 0 and ``stick_ratios``,
    and one load cycle at ``history_friction``.

    Parameters
    ----------
    geometries, bases : sequence of str
        Default both of each.
    nus : sequence of float
        Poisson's ratios of the body (default 0.3, 0.45).
    ratios : sequence of float
        a/h (default 0, 0.5, 1, 2, 5, 10), each within the supported range.
    stick_ratios : sequence of float
        c/a in (0, 1) where k is reported (default 1/4, 1/2, 3/4).
    n : int
        Elements (default method, default 128).
    history_friction : float or None
        Friction coefficient of the load cycle 0 -> 1 -> 0 (default 0.2);
        None: no histories.
    history_n, history_steps : int
        Elements and steps a segment of the histories (default 240 and 100:
        the cycle work to about 2 % at a_max/h = 1, see docs/validation.md).

    Returns
    -------
    LayerStudy
    """
    geometries = tuple(validate.geometry(g) for g in geometries)
    bases = tuple(validate.base(b) for b in bases)
    nus = tuple(validate.nu(v) for v in nus)
    cs = tuple(validate.stick_ratio(c) for c in stick_ratios)
    for g in geometries:
        for b in bases:
            for r in ratios:
                validate.slab_ratio(r, g, b)
    n = validate.n(n, "default")
    if history_friction is not None:
        history_friction = validate.friction(history_friction)
    shape = (len(geometries), len(bases), len(nus), len(ratios))
    work, work_err = np.full(shape, np.nan), np.full(shape, np.nan)
    work_ok = np.zeros(shape, dtype=bool)
    load, load_err = np.empty(shape), np.empty(shape)
    k, k_err = np.empty(shape + (len(cs),)), np.empty(shape + (len(cs),))
    ok = np.zeros(shape + (len(cs),), dtype=bool)
    for i, g in enumerate(geometries):
        for j, b in enumerate(bases):
            for v, nu in enumerate(nus):
                for r, ratio in enumerate(ratios):
                    sols = sweep(g, nu, [0.0, *cs], n=n, slab_ratio=float(ratio), base=b,
                                 energy=False)
                    load[i, j, v, r] = sols[0].load_ratio
                    load_err[i, j, v, r] = sols[0].load_error_estimate
                    k[i, j, v, r] = [s.friction_coefficient for s in sols[1:]]
                    k_err[i, j, v, r] = [s.error_estimate for s in sols[1:]]
                    ok[i, j, v, r] = [s.resolved and s.consistent for s in sols[1:]]
                    if history_friction is None:
                        continue
                    res = history(g, nu, history_friction, [0.0, 1.0, 0.0], history_steps,
                                  n=history_n, slab_ratio=float(ratio), base=b,
                                  max_error=HISTORY_MAX_ERROR)
                    work[i, j, v, r] = res.frictional_work[-1]
                    work_err[i, j, v, r] = res.work_error_estimate[-1]
                    work_ok[i, j, v, r] = bool(np.all(res.converged) and res.resolved[-1])
    return LayerStudy(geometries=geometries, bases=bases, nus=nus,
                      ratios=tuple(float(r) for r in ratios), stick_ratios=cs, n=n,
                      load_ratio=load, load_error_estimate=load_err, friction=k,
                      error_estimate=k_err, resolved=ok, history_friction=history_friction,
                      history_n=history_n if history_friction is not None else 0,
                      history_steps=history_steps if history_friction is not None else 0,
                      cycle_work=work, cycle_work_error_estimate=work_err,
                      cycle_resolved=work_ok)
