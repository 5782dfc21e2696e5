"""The field under one step of a cylinder's fretting path (plane strain).

The sphere's is :mod:`contactlib.stresses.grid`.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .halfplane import halfplane_pieces
from .inputs import check_grid
from .measures import derived_measures, field_maximum
from .solution import LONG_NAMES

__all__ = ["cylinder_fretting_stresses"]


def _strip_field(mid: np.ndarray, p: np.ndarray, q: np.ndarray, sigma: float, xs: np.ndarray,
                 zs: np.ndarray, body: str, nu: float) -> dict[str, np.ndarray]:
    """The components under a cylinder's fretting step: its element tractions (constant p
    and q on equal strip elements of midpoints ``mid``) plus, in the body, the bulk stress
    ``sigma`` along x (plane strain). Units p0(a_max), a_max."""
    half = 0.5 * float(mid[1] - mid[0])
    if body == "indenter":  # the indenter's surface carries p and the opposite shear
        q = -q
    fields = halfplane_pieces(mid - half, mid + half, p, p, q, q, xs, zs, nu)
    if body == "body":
        fields["sigma_xx"] = fields["sigma_xx"] + sigma
        fields["sigma_yy"] = fields["sigma_yy"] + nu * sigma
    return fields


def cylinder_fretting_stresses(result: Any, step: int, x: Any, z: Any, *,
                               body: str = "body", error_estimate: bool = True,
                               measures: bool = True) -> Any:
    """The plane-strain stress field under a step of ``contactlib.fretting("cylinder", ...)``.

    The tractions are the run's own, constant on each strip element over the whole
    strip (tangential loading breaks the symmetry of p and q), integrated exactly
    (Johnson's half-plane kernels, as :func:`halfplane_stresses_line`); in the body the
    step's bulk stress sigma along x is added (sigma_xx += sigma, sigma_yy += nu sigma:
    plane strain, as the solver's bulk strain). On the surface itself the field of
    element tractions has a logarithmic spike at every element edge, so z > 0.

    Parameters
    ----------
    result : contactlib.fretting_api.FrettingResult
        A cylinder's fretting path.
    step : int
        The step (``result.point_step`` holds the path points'); negative counts from
        the end. With ``error_estimate`` a multiple of 4 (the coarse runs have a half and
        a quarter of the steps; every path point is one).
    x, z : array_like, 1-d
        x / a_max (either sign, x along the tangential load) and depth z / a_max > 0.
    body : {"body", "indenter"}
        The body (default), or an elastic indenter taken as a half-plane of its own
        Poisson's ratio under the same pressure and the opposite shear, z into it.
    error_estimate : bool
        Add ``<name>_error``, the larger of |field(n) - field(n/2)| and |field(n/2) -
        field(n/4)| (the same path with n/2 and n/4 elements and a half and a quarter of
        the steps, from ``result.model``; together about 0.2 of the run's cost), and the
        attributes ``<name>_max_error`` for the maxima of von Mises and Tresca (the same
        rule on the maxima, and never below the field's estimate at the maximum).
        Measured (tests/test_fretting_stresses_cylinder.py): it covers the change to the
        run with 4n elements and 4 times the steps at the maxima. Default True.
    measures : bool
        Add the derived measures (:func:`derived_measures`).

    Returns
    -------
    xarray.Dataset
        On (z, x), in units of p0(a_max) (the Hertz peak pressure at P_max) and a_max:
        sigma_xx, sigma_yy, sigma_zz, sigma_xz and the measures; attributes ``step``,
        ``load_ratio``, ``force_ratio`` (Q/(k P_max)), ``bulk_stress``, ``contact_edges``,
        ``stick_edges``, and ``max_<name>`` with its place for von Mises and Tresca.

    Raises
    ------
    contactlib.validate.InputError
        Not a cylinder's result, a step out of range (or not a multiple of 4 with the
        estimate), z <= 0, a rigid indenter's field, or an estimate for a result without
        its model.
    contactlib.validate.SolverLimit
        The step (or a coarse run's) did not converge: its tractions are not data.
    """
    import xarray as xr

    from .. import validate

    if getattr(result, "geometry", None) != "cylinder":
        raise validate.InputError("result", "a cylinder's FrettingResult (contactlib.fretting("
                                  "'cylinder', ...); the sphere's: contactlib.stresses.grid."
                                  "fretting_stresses)", getattr(result, "geometry", result))
    if body not in ("body", "indenter"):
        raise validate.InputError("body", "'body' or 'indenter'", body)
    total = len(result.load_ratio)
    if not isinstance(step, (int, np.integer)) or not -total <= int(step) < total:
        raise validate.InputError("step", f"an integer in [-{total}, {total - 1}]", step)
    step = int(step) % total
    xs, zs = check_grid(x, z)
    if np.any(zs <= 0):
        raise validate.InputError("z", "depths z > 0 (on the surface the field of element "
                                  "tractions spikes at every element edge)", float(zs.min()))
    model = getattr(result, "model", None)
    nu = float(result.nu)
    if body == "indenter":
        if model is None or math.isinf(float(model.indenter.modulus_ratio)):
            raise validate.InputError("body", "'body' for a rigid indenter (or a result "
                                      "without its model)", body)
        nu = float(model.indenter.nu if model.indenter.nu is not None else result.nu)
    p = np.asarray(result.pressure, dtype=float)[step]
    q = np.asarray(result.shear, dtype=float)[step]
    if not (bool(np.asarray(result.converged)[step]) and np.all(np.isfinite(p))
            and np.all(np.isfinite(q))):
        raise validate.SolverLimit(f"fretting stresses: step {step} did not converge, so its "
                                   "tractions are not data; refine the steps")
    sigma = float(np.asarray(result.bulk_stress, dtype=float)[step])
    fields = _strip_field(np.asarray(result.x, dtype=float), p, q, sigma, xs, zs, body, nu)
    coarse: list[dict[str, np.ndarray]] = []
    if error_estimate:
        from ..fretting_api import run_path

        if step % 4:
            raise validate.InputError(
                "step", "a multiple of 4 with error_estimate (the coarse runs have a half and "
                "a quarter of the steps; every path point is one); pass "
                "error_estimate=False for this step", step)
        if model is None:
            raise validate.InputError("result", "a result that carries its model for the "
                                      "estimate", "model None", "result: it carries no model "
                                      "(rebuilt elsewhere); pass error_estimate=False")
        path = [np.asarray(v, dtype=float) for v in
                (result.load_path, result.tangential_path, result.bulk_stress_path)]
        for div in (2, 4):
            ops, raw = run_path(model, int(result.n) // div, int(result.steps) // div,
                                float(result.friction), *path)
            s = step // div
            if not bool(raw.converged[s]):
                raise validate.SolverLimit(
                    f"fretting stresses: step {s} of the estimate's run with n = "
                    f"{int(result.n) // div} did not converge; pass error_estimate=False")
            coarse.append(_strip_field(ops.mid, raw.p[s] / ops.p0, raw.q[s] / ops.p0,
                                       float(raw.strain[s] / (ops.p0 * ops.strain_share)),
                                       xs, zs, body, nu))
    if measures:
        for f in [fields, *coarse]:
            f.update(derived_measures("cylinder", f))
    into = "indenter" if body == "indenter" else "body"
    data = {name: (("z", "x"), v, {"units": "1",
                                   "long_name": LONG_NAMES[name].replace("p0", "p0(a_max)")})
            for name, v in fields.items()}
    attrs: dict[str, Any] = {
        "geometry": "cylinder", "poisson_ratio": nu, "body": body, "step": step,
        "load_ratio": float(np.asarray(result.load_ratio)[step]),
        "force_ratio": float(np.asarray(result.force_ratio)[step]),
        "bulk_stress": sigma,
        "contact_edges": [float(v) for v in np.asarray(result.contact_edges)[step]],
        "stick_edges": [float(v) for v in np.asarray(result.stick_edges)[step]],
        "friction_coefficient": float(result.friction), "elements": int(result.n),
        "stress_unit": "p0(a_max), the Hertz peak pressure at P_max"}
    if coarse:
        for name, v in fields.items():
            err = np.maximum(np.abs(v - coarse[0][name]),
                             np.abs(coarse[0][name] - coarse[1][name]))
            data[f"{name}_error"] = (("z", "x"), err,
                                     {"units": "1", "long_name": f"estimated error of {name}"})
        attrs["reference_elements"] = f"{int(result.n) // 2} {int(result.n) // 4}"
    coords = {"z": ("z", zs, {"units": "1", "long_name": f"depth / a_max, into the {into}"}),
              "x": ("x", xs, {"units": "1",
                              "long_name": "x / a_max (along the tangential load)"})}
    ds = xr.Dataset(data, coords=coords, attrs=attrs)
    if measures:
        for name in ("von_mises", "tresca"):
            top = field_maximum(ds, name)
            ds.attrs[f"max_{name}"] = top["value"]
            ds.attrs[f"max_{name}_x"], ds.attrs[f"max_{name}_z"] = top["x"], top["z"]
            if coarse:
                tops = [float(np.max(f[name])) for f in (fields, *coarse)]
                v = ds[f"{name}_error"].values
                at = float(v[np.unravel_index(int(np.argmax(fields[name])), v.shape)])
                ds.attrs[f"{name}_max_error"] = max(abs(tops[0] - tops[1]),
                                                    abs(tops[1] - tops[2]), at)
    return ds
