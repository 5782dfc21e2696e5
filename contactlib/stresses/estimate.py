"""The estimated discretization error of a solve's field: the change from n/2 elements."""

from __future__ import annotations

import math
from typing import Any

from .solution import substrate_of, subsurface_stresses

__all__ = ["field_error_estimate"]


def field_error_estimate(solution: Any, x: Any, z: Any, *, body: str = "body") -> Any:
    """Estimated discretization error of :func:`subsurface_stresses`: the change from n/2.

    The same case (c/a, materials, indenter) is solved again on n/2 elements and the
    estimate is the absolute difference of the two fields, variable by variable (no
    Richardson division: at n = 128 the field's convergence in n is not yet regular).
    The field integrates the solve's own nodal tractions (:func:`traction_samples`), so
    it converges with n. Measured (tests/test_stresses.py, sphere and cylinder, c/a =
    0.5 and 0.9, n = 128): at the maxima of von Mises and Tresca it covers the difference
    to the field at 4n, which it exceeds by 1.3 ... 2.8 times; on the whole 31 x 31 grid
    it covers it everywhere but at one surface point of the cylinder at c/a = 0.9, where
    the n/2 difference crosses zero (0.5x there, of an error 1e-2 of the grid's largest).

    Parameters
    ----------
    solution : contactlib.result.Solution
        A case of the default method (n >= 2 * the method's smallest n).
    x, z : array_like, 1-d
        As for :func:`subsurface_stresses`.
    body : {"body", "indenter"}
        As for :func:`subsurface_stresses`.

    Returns
    -------
    xarray.Dataset
        The variables of :func:`subsurface_stresses`, each the estimated absolute error
        (units of p0), attribute ``reference_elements`` (n/2).

    Raises
    ------
    contactlib.validate.InputError
        For another method, an n too small to halve, or what
        :func:`subsurface_stresses` refuses.
    """
    from .. import api
    from ..validate import MIN_N_DEFAULT_METHOD, InputError, method_of

    if not method_of(solution.method).nested_estimate:  # the default method: n/2 nested
        raise InputError("method", "default for a field error estimate", solution.method)
    half = int(solution.n) // 2
    if half < MIN_N_DEFAULT_METHOD:
        raise InputError("n", f">= {2 * MIN_N_DEFAULT_METHOD} for a field error estimate",
                         solution.n)
    fine = subsurface_stresses(solution, x, z, body=body)
    kw: dict[str, Any] = ({"base": solution.base, "slab_ratio": float(solution.slab_ratio)}
                          if solution.slab_ratio > 0 else {})
    substrate = substrate_of(solution) if solution.slab_ratio > 0 else None
    if substrate is not None:
        kw.update(substrate_modulus=substrate[0], substrate_nu=substrate[1])
    if not math.isinf(float(solution.indenter_modulus_ratio)):
        kw.update(indenter_modulus=float(solution.indenter_modulus_ratio),
                  indenter_nu=float(solution.indenter_poisson_ratio))
    coarse_solution = api.solve(solution.geometry, solution.nu,
                                stick_ratio=float(solution.stick_ratio), n=half, energy=False,
                                **kw)
    coarse = subsurface_stresses(coarse_solution, x, z, body=body)
    out = abs(fine - coarse)
    for name in out.data_vars:
        out[name].attrs = {"units": "1",
                           "long_name": "estimated error of " + fine[name].attrs["long_name"]}
    out.attrs = dict(fine.attrs, reference_elements=half)
    return out
