"""Key numbers of a set of scene datasets: one row a scene, for the report.

Examples
--------
>>> from contactlib import sweep
>>> from contactlib.io import to_dataset
>>> ds = to_dataset(sweep("sphere", 0.3, [0.0, 0.5], n=32))
>>> row = key_numbers([ds])[0]
>>> row["k at c/a = 0.5"] > 0, row["consistent up to c/a"]
(True, 0.5)
"""

from __future__ import annotations

from typing import Any, Sequence

import numpy as np
import xarray as xr

__all__ = ["key_numbers", "COLUMNS"]

COLUMNS = (
    "scene", "geometry", "method", "elements", "nu", "slab ratio a/h", "cases",
    "converged", "consistent", "consistent up to c/a", "frictionless P/P_Hertz",
    "k at c/a = 0.25", "k at c/a = 0.5", "k at c/a = 0.75", "largest finite k",
    "work at c/a = 0.5", "largest work",
)


def _at(ds: xr.Dataset, name: str, c: float) -> float:
    """Value of a per-case variable at stick ratio c exactly (NaN when absent)."""
    if name not in ds:
        return float("nan")
    hit = np.flatnonzero(np.isclose(ds["stick_ratio"].values, c, rtol=0, atol=1e-12))
    return float(ds[name].values[hit[0]]) if hit.size else float("nan")


def key_numbers(datasets: Sequence[xr.Dataset]) -> list[dict[str, Any]]:
    """One row of key numbers a dataset (columns :data:`COLUMNS`).

    ``consistent up to c/a`` is the largest stick ratio below which every
    case converged and passed both consistency checks (NaN when the
    dataset has no flags); values at a given c/a are taken only where the
    dataset has that case (never interpolated), else NaN.
    """
    rows = []
    for ds in datasets:
        c = np.atleast_1d(ds["stick_ratio"].values)
        k = np.atleast_1d(ds["friction_coefficient"].values)
        conv = np.atleast_1d(ds["converged"].values).astype(bool)
        order = np.argsort(c)
        if "consistent" in ds:
            ok = (np.atleast_1d(ds["consistent"].values).astype(bool) & conv)[order]
            bad = np.flatnonzero(~ok)
            upto = float(c[order][bad[0] - 1]) if bad.size and bad[0] > 0 else (
                float("nan") if bad.size else float(c.max()))
            n_consistent = int(ok.sum())
        else:
            upto, n_consistent = float("nan"), float("nan")
        finite = k[np.isfinite(k)]
        work = np.atleast_1d(ds["frictional_work"].values) if "frictional_work" in ds else None
        rows.append({
            "scene": str(ds.attrs.get("scene", "")),
            "geometry": str(ds.attrs["geometry"]),
            "method": str(ds.attrs["method"]),
            "elements": int(ds.attrs["elements"]),
            "nu": float(ds.attrs["poisson_ratio"]),
            "slab ratio a/h": float(ds.attrs.get("slab_ratio", 0.0)),
            "cases": int(c.size),
            "converged": int(conv.sum()),
            "consistent": n_consistent,
            "consistent up to c/a": upto,
            "frictionless P/P_Hertz": _at(ds, "load_ratio", 0.0),
            "k at c/a = 0.25": _at(ds, "friction_coefficient", 0.25),
            "k at c/a = 0.5": _at(ds, "friction_coefficient", 0.5),
            "k at c/a = 0.75": _at(ds, "friction_coefficient", 0.75),
            "largest finite k": float(finite.max()) if finite.size else float("nan"),
            "work at c/a = 0.5": _at(ds, "frictional_work", 0.5),
            "largest work": float(np.nanmax(work)) if work is not None and
            np.isfinite(work).any() else float("nan"),
        })
    return rows
