"""The fields behind the stress figures of ``snakemake stresses`` (issue 38).

Three groups of :mod:`xarray` Datasets, each in units of p0 (docs/stresses.md):

* ``partial_slip``: the rigid sphere on a half-space at c/a = 0 ... 0.9
  (:func:`contactlib.stresses.subsurface_stresses` of :func:`contactlib.solve`);
* ``edge``: the surface radial stress near the edge for a rigid indenter and elastic
  indenters (E1/E2 = 3 and 0.5, nu1 = 0.2), in the body and in the indenter, frictionless
  and at c/a = 0.5;
* ``tangential``: the sphere pressed and then pushed along x, sliding at mu = 0, 0.2 and
  0.4 and in partial slip (Cattaneo-Mindlin, mu = 0.4, Q/(mu P) = 0.5), in the plane
  y = 0 (:func:`contactlib.stresses.tangential.mindlin_sphere_stresses`).

Numerics only: the workflow's script writes the datasets, the figures and the table.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from .api import solve
from .stresses import default_grid, field_maximum, subsurface_stresses
from .stresses.tangential import mindlin_sphere_stresses

__all__ = ["STICK_RATIOS", "TANGENTIAL_CASES", "partial_slip_fields", "edge_fields",
           "tangential_fields", "maxima_rows", "study"]

# convention: the c/a of the figures and the table of docs/stresses.md
STICK_RATIOS = (0.0, 0.25, 0.5, 0.75, 0.9)
"""c/a of the partial-slip maps and maxima."""

# convention: the cases of the tangential figure of docs/stresses.md
TANGENTIAL_CASES = ((0.0, 1.0), (0.2, 1.0), (0.4, 1.0), (0.4, 0.5))
"""(mu, Q/(mu P)) of the tangential maps: sliding, and partial slip at half the force."""


def partial_slip_fields(nu: float = 0.3, stick_ratios: Sequence[float] = STICK_RATIOS,
                        n: int = 256) -> list[Any]:
    """Fields of the rigid sphere at each c/a on the default grid (r/a, z/a in [0, 2])."""
    x, z = default_grid()
    return [subsurface_stresses(solve("sphere", nu, stick_ratio=c, n=n, energy=False), x, z)
            for c in stick_ratios]


def edge_fields(nu: float = 0.3, n: int = 256) -> list[Any]:
    """Surface rows (z = 0, r/a in [0.5, 2.5]) for rigid and elastic indenters, c/a 0 and 0.5."""
    x = np.linspace(0.5, 2.5, 201)
    out = []
    for ratio, bodies in ((np.inf, ("body",)), (3.0, ("body", "indenter")),
                          (0.5, ("body", "indenter"))):
        kw = {} if np.isinf(ratio) else {"indenter_modulus": ratio, "indenter_nu": 0.2}
        for c in (0.0, 0.5):
            sol = solve("sphere", nu, stick_ratio=c, n=n, energy=False, **kw)
            out += [subsurface_stresses(sol, x, [0.0], body=b) for b in bodies]
    return out


def tangential_fields(nu: float = 0.3,
                      cases: Sequence[tuple[float, float]] = TANGENTIAL_CASES) -> list[Any]:
    """The plane y = 0 (x/a in [-1.6, 1.6], z/a in [0, 1.2]) of each (mu, Q/(mu P))."""
    x = np.linspace(-1.6, 1.6, 161)
    z = np.linspace(0.0, 1.2, 61)
    return [mindlin_sphere_stresses(mu, ratio, x, [0.0], z, nu).isel(y=0)
            for mu, ratio in cases]


def maxima_rows(partial: Sequence[Any], tangential: Sequence[Any]) -> list[dict[str, Any]]:
    """One row a map: the case, the largest von Mises and Tresca and where, p0/Y at yield.

    The maxima of the partial-slip maps are refined by a parabola
    (:func:`contactlib.stresses.field_maximum`); those of the tangential maps are grid
    maxima (spacing 0.02 a).
    """
    rows = []
    for ds in partial:
        vm, tr = field_maximum(ds, "von_mises"), field_maximum(ds, "tresca")
        rows.append({"case": "radial shear (self-similar loading)",
                     "c/a": ds.attrs["stick_ratio"], "k": ds.attrs["friction_coefficient"],
                     "Q/(k P)": 0.0, "max von Mises / p0": vm["value"], "x/a (vM)": vm["x"],
                     "z/a (vM)": vm["z"], "max Tresca / p0": tr["value"],
                     "x/a (Tresca)": tr["x"], "z/a (Tresca)": tr["z"],
                     "p0/Y at first yield": 1.0 / vm["value"]})
    for ds in tangential:
        row: dict[str, Any] = {"case": "tangential load along x (Cattaneo-Mindlin)",
                               "c/a": ds.attrs["stick_ratio"],
                               "k": ds.attrs["friction_coefficient"],
                               "Q/(k P)": ds.attrs["load_ratio"]}
        for name, label in (("von_mises", "vM"), ("tresca", "Tresca")):
            v = np.asarray(ds[name].values)
            i, j = np.unravel_index(int(np.argmax(v)), v.shape)
            top = "max von Mises / p0" if name == "von_mises" else "max Tresca / p0"
            row.update({top: float(v[i, j]), f"x/a ({label})": float(ds["x"][j]),
                        f"z/a ({label})": float(ds["z"][i])})
        row["p0/Y at first yield"] = 1.0 / row["max von Mises / p0"]
        rows.append(row)
    return rows


def study(nu: float = 0.3, n: int = 256) -> dict[str, list[Any]]:
    """All three groups: ``{"partial_slip": [...], "edge": [...], "tangential": [...]}``."""
    return {"partial_slip": partial_slip_fields(nu, n=n), "edge": edge_fields(nu, n=n),
            "tangential": tangential_fields(nu)}
