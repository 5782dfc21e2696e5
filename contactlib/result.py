"""Result object shared by every method and geometry."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


@dataclass
class Solution:
    """One solved partial-slip case, in the scalings of DESIGN.md section 2.

    All profile arrays live on ``xi`` (r/a or x/a, 0...1).

    Attributes
    ----------
    geometry : str
        ``"sphere"`` or ``"cylinder"``.
    nu : float
        Poisson's ratio of the elastic body.
    method : str
        Discretization (``"default"``, ``"paper"``, ...).
    n : int
        Number of elements (rings or strips) across the half-contact.
    slab_ratio : float
        a/h for the cylinder on a slab (0 = half-plane); 0 for the sphere.
    stick_ratio : float
        c/a, 0 (frictionless) ... 1 (full adhesion).
    friction_coefficient : float
        k; ``inf`` at full adhesion.
    xi : ndarray
        Output abscissae r/a.
    pressure : ndarray
        p / p0 with p0 the Hertz peak pressure at the same contact radius.
    shear : ndarray
        q / p0, traction on the elastic body, positive away from the axis.
    tangential_displacement : ndarray
        u R / a^2, positive away from the axis.
    load_ratio : float
        P / P_Hertz(a).
    frictional_work : float
        Loading half-cycle work, V R^2/(E* a^5) (sphere) or V R^2/(E* a^4)
        per unit length (cylinder, both sides of the axis). NaN when not
        requested.
    slip_direction_ok, stick_admissible, consistent : bool
        Consistency flags (see :mod:`contactlib.checks`).
    converged : bool
    residual_norm : float
    iterations : int
    message : str
        Human-readable note (e.g. why a case is degenerate).
    error_estimate : float
        Estimated relative error of ``friction_coefficient`` (embedded
        solves on the nested meshes n/4 and n/2; 0 where k is exact).
    load_error_estimate, work_error_estimate : float
        The same for ``load_ratio`` and ``frictional_work`` (NaN when not
        estimated).
    resolved : bool
        Converged, and ``error_estimate`` at most ``max_error``; a case that
        is not resolved is not to be used as a good number.
    max_error : float
        The accuracy asked for (relative error of k).
    """

    geometry: str
    nu: float
    method: str
    n: int
    slab_ratio: float
    stick_ratio: float
    friction_coefficient: float
    xi: np.ndarray
    pressure: np.ndarray
    shear: np.ndarray
    tangential_displacement: np.ndarray
    load_ratio: float
    frictional_work: float = float("nan")
    slip_direction_ok: bool = True
    stick_admissible: bool = True
    consistent: bool = True
    converged: bool = True
    residual_norm: float = 0.0
    iterations: int = 0
    message: str = ""
    error_estimate: float = float("nan")
    load_error_estimate: float = float("nan")
    work_error_estimate: float = float("nan")
    resolved: bool = False
    max_error: float = float("nan")
    extra: dict = field(default_factory=dict)
