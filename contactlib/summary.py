"""Key numbers of a set of scene datasets, for the report.

Self-similar scenes (a ``stick_ratio`` sweep) get a row, loading histories
(a ``step`` dimension, :func:`contactlib.history`) a row a run (one a
friction coefficient: long format); :func:`key_numbers` gives the full,
tidy rows (the CSV: one value a cell, the scalings in the column names) and
:func:`report_rows` a compact view of them (the HTML table of the report:
fewer, merged columns, four significant digits).

Examples
--------
>>> from contactlib import sweep
>>> from contactlib.io import to_dataset
>>> ds = to_dataset(sweep("sphere", 0.3, [0.0, 0.5], n=64))
>>> row = key_numbers([ds])[0]
>>> row["k at c/a = 0.5"] > 0, row["consistent up to c/a"]
(True, 0.5)
"""

from __future__ import annotations

import math
from typing import Any, Sequence

import numpy as np
import xarray as xr

from . import validate
from .model.indenter import indenter

__all__ = ["layer_rows", "fretting_rows", "fretting_path_rows", "stick_direction_rows",
           "key_numbers", "report_rows", "COLUMNS", "INDENTER_COLUMNS",
           "REPORT_COLUMNS", "WORK_AT_HALF", "LARGEST_WORK", "CYCLE_WORK"]

_WORK_SCALE = "V R^2/(E* a^5); cylinder: V R^2/(E* a^4) per unit length"
WORK_AT_HALF = f"work at c/a = 0.5 [{_WORK_SCALE}]"
LARGEST_WORK = f"largest work [{_WORK_SCALE}]"
CYCLE_WORK = ("history work per cycle [V R^2/(E* a_max^5); cylinder: V R^2/(E* a_max^4) per "
              "unit length]")

COLUMNS = (
    "scene", "geometry", "method", "elements", "nu", "slab ratio a/h", "cases",
    "converged", "consistent", "consistent up to c/a", "frictionless P/P_Hertz",
    "frictionless source",
    "k at c/a = 0.25", "k at c/a = 0.5", "k at c/a = 0.75", "largest finite k",
    WORK_AT_HALF, LARGEST_WORK,
    "history k", "history c/a at peak load", CYCLE_WORK,
)
"""Columns of :func:`key_numbers` (the CSV).

Each cell holds one value; the work columns name their scaling. ``cases`` /
``converged`` count the stick ratios of a self-similar scene; a history row
is one run (one friction coefficient, ``history k``): ``cases`` 1,
``converged`` 1 when every step converged, else 0. A case of the default method counts as converged only when it is
also resolved (its error estimate within the scene's ``max_error``): a
case that is not resolved is treated as a failure. (The paper's scheme is
a reproduction whose k is not the physical one; its consistency columns
judge it.) ``frictionless source`` is ``dataset`` when the scene holds the case
c/a = 0, ``solve`` when it was computed by a frictionless solve with the
scene's geometry, ν, method, n and a/h. The ``history`` columns are empty
(NaN) on self-similar rows, the per-case columns NaN on history rows.
``history c/a at peak load`` is taken at the first step of the largest load, or, on a
fretting path (a tangential load), of the largest tangential load |Q|.
"""

INDENTER_COLUMNS = ("indenter E1/E2", "indenter nu", "dundurs beta")
"""Columns :func:`key_numbers` adds after :data:`COLUMNS` when a scene has an elastic
indenter (the material scenes): E1/E2 (``inf`` for a rigid one), its Poisson ratio and
Dundurs' beta of the pair (> 0: inward slip, q = k p; < 0: outward, q = -k p)."""

REPORT_COLUMNS = (
    "scene", "body", "method", "cases / converged / consistent", "consistent up to c/a",
    "P/P_Hertz frictionless", "k at c/a = 0.25 | 0.5 | 0.75", "largest finite k",
    "work at c/a = 0.5 | largest", "history, each k: c/a at peak load, work per cycle",
)
"""Columns of :func:`report_rows` (the HTML table of the report)."""

# convention: the stick ratios the report's table shows
_RATIOS = (0.25, 0.5, 0.75)


# the relative error estimate of each quoted variable
_ESTIMATES = {"friction_coefficient": "error_estimate", "load_ratio": "load_error_estimate",
              "frictional_work": "work_error_estimate"}


def quoted(value: float, relative_error: float, max_error: float = float("nan")) -> float:
    """``value`` rounded to the significant digits that its accuracy supports.

    The accuracy is ``max_error`` for a case within it (the accuracy asked for, which
    the case meets) and the error estimate for one beyond it:
    floor(-log10(max(relative_error, max_error))) digits, between 2 and 6 (6 with
    neither). The digits of a resolved case then follow from the configuration alone,
    never from its estimate, whose last digits are round-off: a quoted number must not
    change with the machine's BLAS kernel (an estimate of 0.99e-5 here and 1.01e-5 there
    would otherwise quote 5 digits here and 4 there).

    >>> quoted(0.30809448, 2e-5), quoted(0.30809448, float("nan")), quoted(2.784, 0.3)
    (0.3081, 0.308094, 2.8)
    >>> quoted(0.30809448, 2e-5, 1e-3), quoted(0.30809448, 9e-6, 1e-3), quoted(2.784, 0.3, 1e-3)
    (0.308, 0.308, 2.8)
    """
    if not (math.isfinite(value) and value != 0.0):
        return float(value)
    digits = 6
    accuracy = [x for x in (relative_error, max_error) if math.isfinite(x) and x > 0.0]
    if accuracy:
        digits = int(np.clip(math.floor(-math.log10(max(accuracy))), 2, 6))
    return float(f"{value:.{digits}g}")


def _values(ds: xr.Dataset, name: str) -> np.ndarray:
    """A per-case variable as quoted: NaN where the solver did not converge (no data
    there), elsewhere rounded to the digits its accuracy supports (:func:`quoted`: the
    dataset's ``max_error`` where the case is within it, else its error estimate)."""
    v = np.atleast_1d(np.asarray(ds[name].values, dtype=float))
    if "converged" in ds:
        v = np.where(np.atleast_1d(ds["converged"].values).astype(bool), v, np.nan)
    est = _ESTIMATES.get(name)
    err = (np.atleast_1d(np.asarray(ds[est].values, dtype=float)) if est in ds
           else np.full(v.shape, np.nan))
    asked = float(ds.attrs.get("max_error", float("nan")))
    return np.array([quoted(float(x), float(e), asked) for x, e in zip(v, err)])


def _at(ds: xr.Dataset, name: str, c: float) -> float:
    """Value of a per-case variable at stick ratio c exactly (NaN when absent or not converged)."""
    if name not in ds:
        return float("nan")
    hit = np.flatnonzero(np.isclose(np.atleast_1d(ds["stick_ratio"].values), c, rtol=0,
                                    atol=1e-12))
    return float(_values(ds, name)[hit[0]]) if hit.size else float("nan")


def _frictionless(ds: xr.Dataset) -> tuple[float, str]:
    """P/P_Hertz at c/a = 0: from the dataset, else by a frictionless solve."""
    value = _at(ds, "load_ratio", 0.0)
    if not math.isnan(value):
        return value, "dataset"
    if "load_ratio" not in ds or "elements" not in ds.attrs:
        return float("nan"), ""
    from contactlib.api import solve  # the solver only when a scene lacks c/a = 0

    ratio = _indenter_ratio(ds)
    kw = {} if math.isinf(ratio) else {
        "indenter_modulus": ratio, "indenter_nu": float(ds.attrs["indenter_poisson_ratio"])}
    sol = solve(str(ds.attrs["geometry"]), float(ds.attrs["poisson_ratio"]), stick_ratio=0.0,
                n=int(ds.attrs["elements"]), method=str(ds.attrs.get("method", "default")),
                slab_ratio=float(ds.attrs.get("slab_ratio", 0.0)), energy=False,
                base=str(ds.attrs.get("base", "smooth")), **kw)
    return float(sol.load_ratio), "solve"


def _indenter_ratio(ds: xr.Dataset) -> float:
    """E1/E2 of the dataset's indenter (``inf``: rigid, also when the attribute is absent)."""
    return float(ds.attrs.get("indenter_modulus_ratio", "inf"))


def _common(ds: xr.Dataset) -> dict[str, Any]:
    ratio = _indenter_ratio(ds)
    return {
        "scene": str(ds.attrs.get("scene", "")),
        "geometry": str(ds.attrs["geometry"]),
        "elements": int(ds.attrs["elements"]),
        "nu": float(ds.attrs["poisson_ratio"]),
        "slab ratio a/h": float(ds.attrs.get("slab_ratio", 0.0)),
        "indenter E1/E2": ratio,
        "indenter nu": float(ds.attrs.get("indenter_poisson_ratio", ds.attrs["poisson_ratio"])),
        "dundurs beta": float(ds.attrs.get("dundurs_beta", "nan")),
    }


def _self_similar(ds: xr.Dataset) -> dict[str, Any]:
    c = np.atleast_1d(ds["stick_ratio"].values)
    k = _values(ds, "friction_coefficient")
    conv = np.atleast_1d(ds["converged"].values).astype(bool)
    if "resolved" in ds and validate.estimates(ds.attrs.get("method")):  # not resolved: a
        # failure
        conv &= np.atleast_1d(ds["resolved"].values).astype(bool)
    order = np.argsort(c)
    if "consistent" in ds:
        ok = (np.atleast_1d(ds["consistent"].values).astype(bool) & conv)[order]
        bad = np.flatnonzero(~ok)
        upto = float(c[order][bad[0] - 1]) if bad.size and bad[0] > 0 else (
            float("nan") if bad.size else float(c.max()))
        n_consistent: float = int(ok.sum())
    else:
        upto, n_consistent = float("nan"), float("nan")
    finite = k[np.isfinite(k)]
    work = _values(ds, "frictional_work") if "frictional_work" in ds else None
    p0, source = _frictionless(ds)
    row = _common(ds)
    row.update({
        "method": str(ds.attrs["method"]),
        "cases": int(c.size),
        "converged": int(conv.sum()),
        "consistent": n_consistent,
        "consistent up to c/a": upto,
        "frictionless P/P_Hertz": p0,
        "frictionless source": source,
    })
    for r in _RATIOS:
        row[f"k at c/a = {r:g}"] = _at(ds, "friction_coefficient", r)
    row.update({
        "largest finite k": float(finite.max()) if finite.size else float("nan"),
        WORK_AT_HALF: _at(ds, "frictional_work", 0.5),
        LARGEST_WORK: float(np.nanmax(work)) if work is not None and
        np.isfinite(work).any() else float("nan"),
        "history k": float("nan"), "history c/a at peak load": float("nan"),
        CYCLE_WORK: float("nan"),
    })
    return row


def _cycle_work(ds: xr.Dataset, work: np.ndarray) -> np.ndarray:
    """Work over the last two path segments when they are one load cycle, else NaN."""
    levels = np.atleast_1d(np.asarray(ds.attrs.get("load_path", []), dtype=float))
    if levels.size < 3 or "segment" not in ds or not (
            (levels[-2] - levels[-3]) * (levels[-1] - levels[-2]) < 0):
        return np.full(work.shape[0], np.nan)
    segment = np.asarray(ds["segment"].values)
    start = int(np.flatnonzero(segment <= levels.size - 3).max())
    return work[:, -1] - work[:, start]


def _history(ds: xr.Dataset) -> list[dict[str, Any]]:
    name = "friction_coefficient"

    def by_k(var: str) -> np.ndarray:
        da = ds[var]
        if name not in da.dims:
            da = da.expand_dims({name: np.atleast_1d(ds[name].values)
                                 if name in ds else [float(ds.attrs[name])]})
        return np.asarray(da.transpose(name, ...).values)

    ks = np.atleast_1d(ds[name].values if name in ds else ds.attrs[name]).astype(float)
    conv = by_k("converged").astype(bool).reshape(ks.size, -1)
    load = np.asarray(ds["load_ratio"].values, dtype=float)
    if load.ndim > 1:
        load = load.reshape(-1, load.shape[-1])[0]
    peak = int(np.argmax(load))  # the first step at the largest load
    if "tangential_load_ratio" in ds:  # fretting: the first step at the largest |Q|
        tangential = np.abs(np.asarray(ds["tangential_load_ratio"].values, dtype=float))
        tangential = tangential.reshape(-1, tangential.shape[-1])[0]
        if np.any(tangential > 0):
            peak = int(np.argmax(tangential))
    done = conv.all(axis=1)  # a run with a step that did not converge has no data
    c_peak = np.where(done, by_k("stick_ratio").astype(float).reshape(ks.size, -1)[:, peak],
                      np.nan)
    work = by_k("frictional_work").astype(float).reshape(ks.size, -1) \
        if "frictional_work" in ds else np.full((ks.size, load.size), np.nan)
    work = np.where(done[:, None], work, np.nan)
    nan = float("nan")
    cycle = _cycle_work(ds, work)
    # quoted to the digits their accuracy supports, as the self-similar values: the
    # estimates at the peak (stick radius, units of a_max) and at the end (work, relative
    # to the path's total work), taken relative to the value quoted
    asked = float(ds.attrs.get("max_error", nan))

    def last_estimate(var: str, step: int) -> np.ndarray:
        if var not in ds:
            return np.full(ks.size, nan)
        return by_k(var).astype(float).reshape(ks.size, -1)[:, step]

    radius = by_k("contact_radius").astype(float).reshape(ks.size, -1)[:, peak] \
        if "contact_radius" in ds else np.full(ks.size, nan)
    with np.errstate(divide="ignore", invalid="ignore"):
        c_rel = last_estimate("stick_radius_error_estimate", peak) / (c_peak * radius)
        scale = (by_k("work_scale").astype(float).reshape(-1) if "work_scale" in ds
                 else np.full(ks.size, nan))
        w_rel = last_estimate("work_error_estimate", -1) * scale / np.abs(cycle)
    rows = []
    for i, k in enumerate(ks):  # long format: one row a run
        row = _common(ds)
        row.update({
            "method": "history",
            "cases": 1,
            "converged": int(done[i]),
            "consistent": nan, "consistent up to c/a": nan,
            "frictionless P/P_Hertz": nan, "frictionless source": "",
            **{f"k at c/a = {r:g}": nan for r in _RATIOS},
            "largest finite k": nan, WORK_AT_HALF: nan, LARGEST_WORK: nan,
            "history k": float(k),
            "history c/a at peak load": quoted(float(c_peak[i]), float(c_rel[i]), asked),
            CYCLE_WORK: quoted(float(cycle[i]), float(w_rel[i]), asked),
        })
        rows.append(row)
    return rows


def key_numbers(datasets: Sequence[xr.Dataset]) -> list[dict[str, Any]]:
    """Key numbers (columns :data:`COLUMNS`): one row a self-similar dataset, one a run
    of a history.

    Parameters
    ----------
    datasets : sequence of xarray.Dataset
        Self-similar scene datasets (:func:`contactlib.io.to_dataset`) and
        loading histories (a ``step`` dimension; one run or a stack over
        ``friction_coefficient``), in any mix.

    Returns
    -------
    list of dict
        Self-similar rows: ``consistent up to c/a`` is the largest stick
        ratio below which every case converged and passed both consistency
        checks (NaN when the dataset has no flags); values at a given c/a
        are taken only where the dataset has that case (never
        interpolated), else NaN; ``frictionless P/P_Hertz`` is the load at
        c/a = 0 over the Hertz load at the same contact radius, from the
        dataset, or, when the scene lacks that case, from a frictionless
        solve with the scene's settings (``frictionless source``). Work is
        V R²/(E* a⁵) (sphere) or V R²/(E* a⁴) per unit length (cylinder).
        History rows, one a friction coefficient ``history k`` (long
        format, in the dataset's order): the stick ratio c/a at the first
        step of the largest load, and the frictional work over the last two
        path segments when they form one load cycle (scaled with a_max),
        else NaN; the other per-case columns are NaN. When a scene has an elastic indenter, every
        row also has :data:`INDENTER_COLUMNS`.
    """
    rows = [row for ds in datasets
            for row in (_history(ds) if "step" in ds.dims else [_self_similar(ds)])]
    elastic = any(not math.isinf(row["indenter E1/E2"]) for row in rows)
    columns = COLUMNS + INDENTER_COLUMNS if elastic else COLUMNS
    return [{name: row[name] for name in columns} for row in rows]


def _g(x: Any, digits: int = 4) -> str:
    if isinstance(x, str):
        return x
    x = float(x)
    return "–" if math.isnan(x) else f"{x:.{digits}g}"


def _joined(values: Sequence[float]) -> str:
    """Values joined by " | ", or one "–" when none is a number."""
    if all(math.isnan(float(v)) for v in values):
        return "–"
    return " | ".join(_g(v) for v in values)


def report_rows(rows: Sequence[dict[str, Any]]) -> list[dict[str, str]]:
    """The rows of :func:`key_numbers` as a compact table for the report.

    Columns :data:`REPORT_COLUMNS`: the body (geometry, ν, a/h, and an
    elastic indenter's E1/E2, ν1 and the pair's β) and the
    method (with n) merged, the three k values and the two work values
    each in one cell, numbers to four significant digits, "–" where a value
    does not apply or is absent, a frictionless load from a separate solve
    marked "(solve)"; a history's runs in one cell, "k: c/a, work" each, to
    three significant digits.

    Parameters
    ----------
    rows : sequence of dict
        From :func:`key_numbers`.

    Returns
    -------
    list of dict
        Strings only, one row a scene (a history's runs, consecutive rows
        of one scene, in one).
    """
    out: list[dict[str, str]] = []
    for row, runs in _by_scene(rows):
        body = f"{row['geometry']}, ν = {_g(row['nu'])}"
        slab = float(row["slab ratio a/h"])
        if indenter(row["geometry"]).reports_layer(slab):
            body += f", a/h = {_g(slab)}" if slab > 0 else ", half-plane"
        if not math.isinf(float(row.get("indenter E1/E2", math.inf))):
            body += (f"; indenter E1/E2 = {_g(row['indenter E1/E2'])}, "
                     f"ν1 = {_g(row['indenter nu'])}, β = {float(row['dundurs beta']):+.4g}")
        history = row["method"] == "history"
        p0 = _g(row["frictionless P/P_Hertz"], 5)
        if row["frictionless source"] == "solve":
            p0 += " (solve)"
        each = [f"{_g(r['history k'], 3)}: {_g(r['history c/a at peak load'], 3)}, "
                f"{_g(r[CYCLE_WORK], 3)}" for r in runs]
        cases = sum(r["cases"] for r in runs) if history else row["cases"]
        converged = sum(r["converged"] for r in runs) if history else row["converged"]
        out.append({
            "scene": row["scene"],
            "body": body,
            "method": f"{row['method']}, n = {row['elements']}",
            "cases / converged / consistent": " / ".join(
                (str(cases), str(converged),
                 "–" if history else _g(row["consistent"]))),
            "consistent up to c/a": _g(row["consistent up to c/a"]),
            "P/P_Hertz frictionless": p0,
            "k at c/a = 0.25 | 0.5 | 0.75": _joined([row[f"k at c/a = {r:g}"] for r in _RATIOS]),
            "largest finite k": _g(row["largest finite k"]),
            "work at c/a = 0.5 | largest": _joined([row[WORK_AT_HALF], row[LARGEST_WORK]]),
            "history, each k: c/a at peak load, work per cycle":
                "; ".join(each) if history else "–",
        })
    return out


def _by_scene(rows: Sequence[dict[str, Any]]) -> list[tuple[dict[str, Any], list]]:
    """Each self-similar row alone, a history's consecutive rows of one scene together:
    ``(first row, its rows)``."""
    groups: list[tuple[dict[str, Any], list]] = []
    for row in rows:
        last = groups[-1][0] if groups else None
        if row["method"] == "history" and last is not None and last["method"] == "history" \
                and last["scene"] == row["scene"]:
            groups[-1][1].append(row)
        else:
            groups.append((row, [row]))
    return groups


def layer_rows(ds: xr.Dataset) -> list[dict[str, object]]:
    """Rows of the layers table: one a (geometry, base, nu, a/h).

    Columns: geometry, base, nu, a/h, the frictionless load ratio P/P_Hertz,
    and k at each stick ratio of the dataset (of
    :func:`contactlib.io.layer_study_to_dataset`), blank where the case is
    not resolved (the slip reverses on thin bonded layers, or the error
    estimate exceeds 1e-3). With the study's load cycles also the work of a
    cycle (a/h then a_max/h), its estimated relative error and whether it is
    resolved to 1e-2: given even where it is not, since the error comes
    with it.
    """
    rows: list[dict[str, object]] = []
    cs = [float(c) for c in ds["stick_ratio"].values]
    cycles = "cycle_work" in ds.variables
    for g, geometry in enumerate(ds["geometry"].values):
        for b, base in enumerate(ds["base"].values):
            for v, nu in enumerate(ds["poisson_ratio"].values):
                for r, ratio in enumerate(ds["slab_ratio"].values):
                    row: dict[str, object] = {
                        "geometry": str(geometry), "base": str(base), "nu": float(nu),
                        "a/h": float(ratio),
                        "frictionless P/P_Hertz": float(ds["load_ratio"].values[g, b, v, r])}
                    for i, c in enumerate(cs):
                        ok = bool(ds["resolved"].values[g, b, v, r, i])
                        k = float(ds["friction_coefficient"].values[g, b, v, r, i])
                        row[f"k at c/a = {c:g}"] = f"{k:.6g}" if ok else ""
                    if cycles:
                        at = (g, b, v, r)
                        row["work per cycle"] = f"{float(ds['cycle_work'].values[at]):.4g}"
                        row["work error estimate"] = (
                            f"{float(ds['cycle_work_error_estimate'].values[at]):.2g}")
                        row["work resolved"] = bool(ds["cycle_work_resolved"].values[at])
                    rows.append(row)
    return rows


def fretting_path_rows(ds: xr.Dataset) -> list[dict[str, object]]:
    """Rows of a fretting scene's table: one a path point of
    :func:`contactlib.io.fretting_to_dataset`.

    Columns: the point, P/P_max, Q/(k P_max), the bulk stress sigma/p0, the stick ratio
    c/a and the stick zone's offset e/a_max with their estimates, the cumulative
    frictional work and its estimate (units E* a_max^4/R^2 per unit length), the work of
    the cycle a point closes (blank elsewhere) with its estimate, and ``resolved``. A
    value is blank where a step up to the point did not converge. Under a prescribed shift
    (the dataset's ``tangential_control`` "displacement") the shift s R/a_max^2 comes before
    Q, and Q, the answer, is followed by its estimate.
    """
    shifted = ds.attrs.get("tangential_control") == "displacement"
    steps = ds["point_step"].values
    conv = np.cumprod(ds["converged"].values.astype(bool)).astype(bool)
    closing = {int(j): (float(w), float(e)) for (_, j), w, e in zip(
        np.asarray(ds.attrs["cycle_points"]).reshape(-1, 2),
        np.atleast_1d(ds.attrs["cycle_work"]), np.atleast_1d(ds.attrs["cycle_work_error_estimate"]))}
    rows: list[dict[str, object]] = []
    for i, step in enumerate(steps):
        ok = bool(conv[step])

        def cell(value: float, fmt: str = ".6g") -> str:
            return f"{value:{fmt}}" if ok and np.isfinite(value) else ""

        w, e = closing.get(i, (float("nan"), float("nan")))
        q = float(ds["tangential_load_ratio"].values[step])
        tangential: dict[str, object] = {"Q/(k P_max)": q}
        if shifted:  # the shift prescribed, Q answered
            tangential = {
                "s R/a_max^2": float(ds["tangential_shift"].values[step]),
                "Q/(k P_max)": cell(q),
                "Q error estimate": cell(float(
                    ds["tangential_load_ratio_error_estimate"].values[i]), ".2g")}
        rows.append({
            "point": i, "P/P_max": float(ds["load_ratio"].values[step]), **tangential,
            "sigma/p0": float(ds["bulk_stress"].values[step]),
            "c/a": cell(float(ds["stick_ratio"].values[step])),
            "c/a error estimate": cell(float(ds["stick_ratio_error_estimate"].values[i]), ".2g"),
            "e/a_max": cell(float(ds["stick_offset"].values[step])),
            "e/a_max error estimate": cell(float(ds["stick_offset_error_estimate"].values[i]),
                                           ".2g"),
            "frictional work": cell(float(ds["frictional_work"].values[step])),
            "work error estimate": cell(float(ds["frictional_work_error_estimate"].values[i]),
                                        ".2g"),
            "cycle work": cell(w), "cycle work error estimate": cell(e, ".2g"),
            "resolved": bool(ds["resolved"].values[i])})
    return rows


def stick_direction_rows(datasets: Sequence[xr.Dataset], cases: Sequence[str]
                         ) -> list[dict[str, object]]:
    """Rows of the stick-zone map's table: one a (case, loaded path point, direction) of
    sphere paths of :func:`contactlib.io.fretting_to_dataset`.

    Columns: the case, beta, the point, P/P_max, Q/(k P_max), the direction (degrees from
    +x, Q's direction), the stick zone's radius from its centroid and its estimate (units
    a_max), whether that radius is resolved (its estimate within the dataset's
    ``max_error``), the contact's radius from its centroid and its estimate, and the stick
    zone's centroid (x, y over a_max). A value is blank where a step up to the point did not
    converge (and the radius is then not resolved).
    """
    rows: list[dict[str, object]] = []
    for case, ds in zip(cases, datasets):
        conv = np.cumprod(ds["converged"].values.astype(bool)).astype(bool)
        deg = np.degrees(ds["direction"].values)
        asked = float(ds.attrs["max_error"])
        for i, step in enumerate(ds["point_step"].values):
            if float(ds["load_ratio"].values[step]) <= 0.0:
                continue
            ok = bool(conv[step])
            radius = ds["stick_radius_directions"].values[step]
            err = ds["stick_radius_directions_error_estimate"].values[i]
            contact = ds["contact_radius_directions"].values[step]
            c_err = ds["contact_radius_directions_error_estimate"].values[i]
            cx, cy = ds["stick_centre"].values[step]

            def cell(value: float, fmt: str = ".6g") -> str:
                return f"{value:{fmt}}" if ok and np.isfinite(value) else ""

            for d, angle in enumerate(deg):
                rows.append({
                    "case": case, "beta": f"{float(ds.attrs['dundurs_beta']):.6g}",
                    "point": i, "P/P_max": float(ds["load_ratio"].values[step]),
                    "Q/(k P_max)": float(ds["tangential_load_ratio"].values[step]),
                    "direction [deg]": f"{angle:.6g}",
                    "stick radius/a_max": cell(float(radius[d])),
                    "stick radius error estimate": cell(float(err[d]), ".2g"),
                    "stick radius resolved": bool(ok and err[d] <= asked),
                    "contact radius/a_max": cell(float(contact[d])),
                    "contact radius error estimate": cell(float(c_err[d]), ".2g"),
                    "stick centre x/a_max": cell(float(cx)),
                    "stick centre y/a_max": cell(float(cy))})
    return rows


def fretting_rows(ds: xr.Dataset) -> list[dict[str, object]]:
    """Rows of the fretting table: one a (case, cycle) of
    :func:`contactlib.io.fretting_study_to_dataset`.

    Columns: nu, beta, Q*/kP, cycle, the cycle's frictional work and its estimate
    (units E* a_max^4/R^2 per unit length), Mindlin–Deresiewicz's work where beta = 0 and
    the relative difference to it; blank where a step of the cycle did not converge.
    """
    rows: list[dict[str, object]] = []
    for c in range(ds.sizes["case"]):
        closed = float(ds["mindlin_deresiewicz_work"].values[c])
        for m, cyc in enumerate(ds["cycle"].values):
            ok = bool(ds["cycle_converged"].values[c, m])
            w = float(ds["cycle_work"].values[c, m])
            e = float(ds["cycle_work_error_estimate"].values[c, m])
            rows.append({
                "nu": float(ds["poisson_ratio"].values[c]),
                "beta": f"{float(ds['dundurs_beta'].values[c]):.6g}",
                "Q*/kP": float(ds["amplitude"].values[c]), "cycle": int(cyc),
                "work": f"{w:.6g}" if ok else "", "work error estimate": f"{e:.2g}" if ok else "",
                "Mindlin-Deresiewicz": f"{closed:.6g}" if np.isfinite(closed) else "",
                "relative difference": (f"{w / closed - 1:.2e}"
                                        if ok and np.isfinite(closed) else "")})
    return rows
