r"""Load paths of any shape for :func:`contactlib.history`: named periodic shapes and tables.

A history's load path is either the piecewise-linear list of load levels of
:func:`contactlib.history` (``[0, 1, 0]``, ``steps`` equal steps a segment)
or one of the two paths of this module, given as a mapping:

* a **named periodic shape**, ``{"shape": "sinusoidal" | "haversine",
  "amplitude": A, "mean": M, "frequency": f, "cycles": N}`` (optionally
  ``"ramp"``, a duration):

  - sinusoidal: ``L(t) = M + A sin(2 pi f t)``, starting at the mean;
  - haversine: ``L(t) = M - A cos(2 pi f t)``, starting at its trough
    ``M - A`` (``M = A`` gives ``2 A sin^2(pi f t)``, from 0);

  for ``0 <= t <= N / f`` (N > 0, any real). The body starts unloaded, so a
  shape that starts above 0 is preceded by a linear ramp from 0 to its first
  value, lasting ``ramp`` (default a quarter period, ``1 / (4 f)``).
* a **sampled table**, ``{"time": [t_0, ...], "load": [L_0, ...]}``: the
  path is the piecewise-linear interpolant of the points in time; the times
  increase strictly and the first load is 0. (Reading a CSV file is the job
  of :func:`contactlib.io.read_load_table`; the numerics never do I/O.)

Loads are levels P / P_max as in :func:`contactlib.history` (in [0, 1]; the
shape's ``M + A`` at most 1). Times and the frequency are in the unit of
the relaxation times tau (any unit: the solver only sees their ratios, so
seconds with tau in seconds are as good as units of tau). An elastic body
has no time scale: its history depends on the sequence of load levels only,
so the frequency may be omitted there (and does not change the answer).

Stepping
--------
The path is cut at its turning points (and a table also where it holds
still) into **monotone pieces**, which become the path segments of the
history. ``steps`` then counts steps **a unit of load travel**: a piece that
moves the load by ``dL`` (units of P_max) gets about ``steps * dL`` steps
(:func:`piece_steps`), rounded up to a multiple of 4 (so that the error
estimate's runs on half and a quarter of the steps sample the same points)
and at least ``min(steps, 40)``; a segment 0 -> 1 thus gets ``steps``
steps, as in a list path.

* Elastic body: within a piece the steps are equal in load. That is the
  shape itself, not an approximation of it: a rate-independent body's
  answer depends only on the sequence of levels, and within a monotone
  piece every path between the same two levels is the same. A haversine
  from 0 is therefore exactly the list ``[0, 1, 0, 1, ...]``.
* Viscoelastic body: time matters. The steps are equal in the blended
  coordinate ``s = (dL / dL_piece + dt / dt_piece) / 2``, so a step moves
  the load by at most ``2 dL_piece / c`` and lasts at most ``2 dt_piece /
  c`` (c steps in the piece): the steps stay short where the load turns
  slowly. The pieces get twice the elastic count, and more where needed
  so that the largest deviation of the shape from its piecewise-linear
  interpolant between steps, ``A (2 pi f dt)^2 / 8``, stays below the run's
  tolerance (``max_error`` in units of P_max; :func:`interpolation_error`).
  A table's pieces are its monotone runs and holds; a hold (no load
  change) gets ``steps`` steps, as a list path's hold segment does.

The step points of every piece lie on the path itself, and the error
estimate's coarser runs take every second (fourth) of them, so the
estimate covers the sampling of the shape as well as the solver's steps.

Examples
--------
>>> from contactlib.model.load_paths import load_path, plan
>>> path = load_path({"shape": "haversine", "amplitude": 0.5, "mean": 0.5, "cycles": 2})
>>> steps = plan(path, 20, viscoelastic=False)
>>> steps.knots, steps.counts          # four half-cycles of 20 steps
((0.0, 1.0, 0.0, 1.0, 0.0), (20, 20, 20, 20))
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Mapping

import numpy as np

from .. import validate

__all__ = ["LoadShape", "LoadTable", "SHAPES", "load_path", "is_shaped", "plan", "sample",
           "StepPlan", "piece_steps", "interpolation_error", "MIN_PIECE_STEPS"]

SHAPES = ("sinusoidal", "haversine")
"""The named periodic shapes."""

# convention: as history_api's fewest steps for the estimate's order (run C)
MIN_PIECE_STEPS = 40
"""Fewest steps of a piece (if ``steps`` is at least this): the error estimate measures its
order from runs on a half and a quarter of the steps only from 40 steps a segment."""

_SHAPE_KEYS = ("shape", "amplitude", "mean", "frequency", "cycles", "ramp")
_TABLE_KEYS = ("time", "load")
# exact: 64 halvings take any duration below a double's resolution
_BISECTIONS = 64  # halvings of a piece's duration when placing a viscoelastic step


@dataclass(frozen=True)
class LoadShape:
    """A named periodic load path (levels P/P_max; times in the unit of tau).

    Attributes
    ----------
    shape : {"sinusoidal", "haversine"}
    amplitude, mean : float
        A > 0 and M with ``0 <= M - A`` and ``M + A <= 1``.
    frequency : float or None
        f > 0 [1 / unit of tau]; None for an elastic body (no time scale).
    cycles : float
        N > 0 periods.
    ramp : float or None
        Duration of the initial ramp from 0 (a shape that starts above 0);
        None: a quarter period.
    """

    shape: str
    amplitude: float
    mean: float
    frequency: float | None
    cycles: float
    ramp: float | None = None

    @property
    def period(self) -> float:
        """1 / f (1 when no frequency is given: an elastic body's times are immaterial)."""
        return 1.0 / (self.frequency or 1.0)

    @property
    def start(self) -> float:
        """The shape's value at t = 0 (the mean, or the trough of a haversine)."""
        return self.mean if self.shape == "sinusoidal" else self.mean - self.amplitude

    def value(self, t: np.ndarray) -> np.ndarray:
        """The load level at times ``t`` since the shape's start (after the ramp)."""
        phase = 2.0 * np.pi * np.asarray(t, dtype=float) / self.period
        if self.shape == "sinusoidal":
            return self.mean + self.amplitude * np.sin(phase)
        return self.mean - self.amplitude * np.cos(phase)

    def describe(self) -> dict[str, Any]:
        """The shape as a mapping (the input's keys; for datasets and summaries)."""
        out: dict[str, Any] = {"shape": self.shape, "amplitude": self.amplitude,
                               "mean": self.mean, "cycles": self.cycles}
        if self.frequency is not None:
            out["frequency"] = self.frequency
        if self.ramp is not None:
            out["ramp"] = self.ramp
        return out


@dataclass(frozen=True)
class LoadTable:
    """A sampled path: load levels at strictly increasing times, linear in between.

    Attributes
    ----------
    time : tuple of float
        Times [unit of tau], strictly increasing, finite.
    load : tuple of float
        Levels P/P_max in [0, 1], the first 0.
    """

    time: tuple[float, ...]
    load: tuple[float, ...]

    def describe(self) -> dict[str, Any]:
        return {"shape": "table", "points": len(self.time)}


Path = LoadShape | LoadTable


def is_shaped(value: Any) -> bool:
    """Whether ``value`` is a shape or table (a mapping or one of the classes), not a list."""
    return isinstance(value, (Mapping, LoadShape, LoadTable))


def _positive(name: str, value: Any) -> float:
    return validate.number(name, value, 0.0, None, lo_open=True)


def load_path(spec: Any, name: str = "load_path") -> Path:
    """A checked shape or table from its mapping (see the module notes).

    Parameters
    ----------
    spec : mapping, LoadShape or LoadTable
        ``{"shape": ..., "amplitude": ..., "mean": ..., "frequency": ...,
        "cycles": ...}`` or ``{"time": [...], "load": [...]}``.
    name : str
        The argument's name, for the error.

    Raises
    ------
    validate.InputError
        A ValueError naming the bad key: an unknown shape or key, a missing
        key, a non-finite or out-of-range number, a table whose columns
        differ in length, whose times do not increase or whose first load
        is not 0.
    """
    if isinstance(spec, (LoadShape, LoadTable)):
        return spec
    if not isinstance(spec, Mapping):
        raise validate.InputError(name, "a list of load levels, a shape {shape, amplitude, "
                                  "mean, frequency, cycles} or a table {time, load}", spec)
    keys = set(spec)
    if "shape" in keys:
        unknown = sorted(str(k) for k in keys - set(_SHAPE_KEYS))
        if unknown:
            raise validate.InputError(name, "", spec, f"{name}: unknown key {unknown[0]!r} of "
                                      f"a shape (keys: {', '.join(_SHAPE_KEYS)})")
        shape = spec["shape"]
        if shape not in SHAPES:
            raise validate.InputError(f"{name}.shape", f"one of {', '.join(SHAPES)}", shape)
        for key in ("amplitude", "mean", "cycles"):
            if key not in spec:
                raise validate.InputError(name, "", spec, f"{name}: a {shape} shape needs "
                                          f"{key!r} (amplitude, mean, cycles; frequency with "
                                          "a relaxation)")
        amp = _positive(f"{name}.amplitude", spec["amplitude"])
        mean = validate.number(f"{name}.mean", spec["mean"])
        cycles = _positive(f"{name}.cycles", spec["cycles"])
        freq = spec.get("frequency")
        freq = None if freq is None else _positive(f"{name}.frequency", freq)
        ramp = spec.get("ramp")
        ramp = None if ramp is None else _positive(f"{name}.ramp", ramp)
        if mean - amp < -1e-12 * amp:
            raise validate.InputError(f"{name}.mean", "", mean, f"{name}: mean - amplitude "
                                      f"= {mean - amp:g} < 0: the load would pull (no "
                                      "adhesion is modelled); give mean >= amplitude")
        if mean + amp > 1.0 + 1e-12:
            raise validate.InputError(f"{name}.mean", "", mean, f"{name}: mean + amplitude "
                                      f"= {mean + amp:g} > 1 (levels are P/P_max in [0, 1])")
        return LoadShape(str(shape), amp, max(mean, amp), freq, cycles, ramp)
    if keys == set(_TABLE_KEYS):
        cols = []
        for key in _TABLE_KEYS:
            col = spec[key]
            if not validate.is_sequence(col):
                raise validate.InputError(f"{name}.{key}", "a sequence of numbers", col)
            cols.append([validate.number(f"{name}.{key}", v) for v in col])
        t, load = cols
        if len(t) != len(load):
            raise validate.InputError(name, "", spec, f"{name}: the table's columns differ in "
                                      f"length ({len(t)} times, {len(load)} loads)")
        if len(t) < 2:
            raise validate.InputError(name, "", spec, f"{name}: a table needs at least two "
                                      f"points, got {len(t)}")
        bad = [i for i in range(1, len(t)) if not t[i] > t[i - 1]]
        if bad:
            raise validate.InputError(f"{name}.time", "", t, f"{name}.time must increase "
                                      f"strictly, got {t[bad[0] - 1]!r} then {t[bad[0]]!r} "
                                      f"(points {bad[0]} and {bad[0] + 1})")
        levels = validate.load_path(load)  # [0, 1], from 0, above 0 somewhere
        return LoadTable(tuple(float(v) for v in t), levels)
    missing = [k for k in _TABLE_KEYS if k not in keys]
    extra = sorted(str(k) for k in keys - set(_TABLE_KEYS))
    raise validate.InputError(name, "", spec, f"{name} must be a shape (with a 'shape' key: "
                              f"{', '.join(SHAPES)}) or a table with exactly the keys time "
                              f"and load; " + (f"missing {missing[0]!r}" if missing else
                                               f"unknown key {extra[0]!r}"))


# ----------------------------------------------------------------------------- pieces
@dataclass(frozen=True)
class _Piece:
    t0: float
    t1: float
    l0: float
    l1: float
    ramp: bool = False  # the linear ramp from 0 that precedes a shape starting above 0


def _shape_pieces(shape: LoadShape) -> list[_Piece]:
    """Monotone pieces of a shape (with its ramp), in time from 0."""
    period = shape.period
    pieces = []
    offset = 0.0
    if shape.start > 0.0:
        offset = period / 4.0 if shape.ramp is None else shape.ramp
        pieces.append(_Piece(0.0, offset, 0.0, shape.start, ramp=True))
    end = shape.cycles * period
    first = 0.25 if shape.shape == "sinusoidal" else 0.5  # first turning point, in periods
    turns = np.arange(first, shape.cycles, 0.5) * period
    bounds = np.concatenate([[0.0], turns[turns < end * (1 - 1e-12)], [end]])
    values = shape.value(bounds)
    if shape.shape == "sinusoidal":  # exact turning values
        values[1:-1] = np.where(values[1:-1] > shape.mean, shape.mean + shape.amplitude,
                                shape.mean - shape.amplitude)
    else:
        values[:-1] = np.where(values[:-1] > shape.mean, shape.mean + shape.amplitude,
                               shape.mean - shape.amplitude)
    values = np.clip(values, 0.0, 1.0)
    for a, b, la, lb in zip(bounds[:-1], bounds[1:], values[:-1], values[1:]):
        pieces.append(_Piece(offset + a, offset + b, float(la), float(lb)))
    return pieces


def _table_pieces(table: LoadTable, viscoelastic: bool) -> list[_Piece]:
    """Maximal runs of the table's intervals that rise, fall or (viscoelastic) hold."""
    t = np.asarray(table.time) - table.time[0]
    load = np.asarray(table.load)
    sign = np.sign(np.diff(load))
    pieces: list[_Piece] = []
    i = 0
    while i < sign.size:
        j = i
        while j + 1 < sign.size and sign[j + 1] == sign[i]:
            j += 1
        if sign[i] != 0 or viscoelastic:
            pieces.append(_Piece(float(t[i]), float(t[j + 1]), float(load[i]),
                                 float(load[j + 1])))
        i = j + 1
    return pieces


def _pieces(path: Path, viscoelastic: bool) -> list[_Piece]:
    return _shape_pieces(path) if isinstance(path, LoadShape) else \
        _table_pieces(path, viscoelastic)


def _round4(x: float) -> int:
    return int(4 * math.ceil(x / 4.0 - 1e-9))


def piece_steps(travel: float, steps: int, viscoelastic: bool) -> int:
    """Steps of a monotone piece that moves the load by ``travel`` (units of P_max).

    ``steps * travel`` (twice that for a viscoelastic body; ``steps`` for a hold,
    ``travel = 0``), rounded up to a multiple of 4, at least ``min(steps, 40)``
    rounded up likewise.
    """
    need = steps * travel * (2.0 if viscoelastic else 1.0) if travel > 0 else float(steps)
    return max(_round4(need), _round4(min(steps, MIN_PIECE_STEPS)))


def interpolation_error(path: Path, piece_duration: float, count: int) -> float:
    """Bound on the deviation of a shape from its linear interpolant between steps.

    A viscoelastic step lasts at most ``2 piece_duration / count``, so a shape
    deviates from the straight line between its step points by at most
    ``A (2 pi f dt)^2 / 8`` (units of P_max); 0 for a table (linear between its
    points; its corners are cut by less than a step's load change).
    """
    if not isinstance(path, LoadShape):
        return 0.0
    dt = 2.0 * piece_duration / count
    return path.amplitude * (2.0 * np.pi * dt / path.period) ** 2 / 8.0


@dataclass(frozen=True)
class StepPlan:
    """The pieces of a path and their steps.

    Attributes
    ----------
    knots : tuple of float
        Load levels at the piece ends, from 0 (the history's ``load_path``).
    durations : tuple of float
        Duration of each piece [unit of tau] (the history's ``durations``).
    counts : tuple of int
        Steps of each piece (multiples of 4).
    interpolation_error : float
        Largest deviation of the path from its linear interpolant between
        the steps (units of P_max; 0 for an elastic body).
    """

    knots: tuple[float, ...]
    durations: tuple[float, ...]
    counts: tuple[int, ...]
    interpolation_error: float
    pieces: tuple[_Piece, ...]


def plan(path: Path, steps: int, viscoelastic: bool, tolerance: float = 1e-3) -> StepPlan:
    """Cut ``path`` into monotone pieces and give each the steps its accuracy needs.

    Parameters
    ----------
    path : LoadShape or LoadTable
        From :func:`load_path`.
    steps : int
        Steps a unit of load travel (:func:`piece_steps`).
    viscoelastic : bool
        Whether time matters (see the module notes).
    tolerance : float
        Largest deviation of a shape from its interpolant between the steps
        of a viscoelastic body (units of P_max): the counts are doubled
        until :func:`interpolation_error` is below it.

    Returns
    -------
    StepPlan
    """
    pieces = _pieces(path, viscoelastic)
    counts, worst = [], 0.0
    for p in pieces:
        c = piece_steps(abs(p.l1 - p.l0), steps, viscoelastic)
        if viscoelastic:
            while interpolation_error(path, p.t1 - p.t0, c) > tolerance \
                    and c < validate.MAX_STEPS:
                c *= 2
            worst = max(worst, interpolation_error(path, p.t1 - p.t0, c))
        counts.append(c)
    knots = (0.0,) + tuple(p.l1 for p in pieces)
    return StepPlan(knots, tuple(float(p.t1 - p.t0) for p in pieces), tuple(counts),
                    float(worst), tuple(pieces))


def _level(path: Path, t: np.ndarray, piece: _Piece) -> np.ndarray:
    """The path's level at times ``t`` within ``piece``."""
    if isinstance(path, LoadShape):
        if piece.ramp:
            return piece.l1 * (t - piece.t0) / (piece.t1 - piece.t0)
        offset = path.period / 4.0 if path.ramp is None else path.ramp
        return path.value(t - (offset if path.start > 0.0 else 0.0))
    return np.interp(t, np.asarray(path.time) - path.time[0], np.asarray(path.load))


def sample(path: Path, step_plan: StepPlan, viscoelastic: bool, divide: int = 1
           ) -> tuple[np.ndarray, np.ndarray | None, np.ndarray]:
    """The load level (and time) of every step, and its segment (piece).

    Parameters
    ----------
    path, step_plan
        From :func:`load_path` and :func:`plan`.
    viscoelastic : bool
        As for :func:`plan`: steps equal in load (elastic) or in the blended
        coordinate of load and time.
    divide : {1, 2, 4}
        Take ``counts // divide`` steps a piece (the error estimate's coarser
        runs: their step points are every ``divide``-th of the full run's).

    Returns
    -------
    (levels, times, segment)
        Arrays of length ``sum(counts) / divide + 1`` from the unloaded
        state (level 0, time 0, segment 0); ``times`` is None for an
        elastic body.
    """
    levels, times, segment = [np.zeros(1)], [np.zeros(1)], [np.zeros(1, dtype=int)]
    for g, (p, c) in enumerate(zip(step_plan.pieces, step_plan.counts), start=1):
        m = c // divide
        s = np.arange(1, m + 1) / m
        if not viscoelastic:
            lv = p.l0 + (p.l1 - p.l0) * s
            tv = p.t0 + (p.t1 - p.t0) * s
        else:  # equal steps of (dL/dL_piece + dt/dt_piece) / 2, by bisection in time
            span = abs(p.l1 - p.l0)
            lo, hi = np.full(m, p.t0), np.full(m, p.t1)
            for _ in range(_BISECTIONS):
                mid = 0.5 * (lo + hi)
                frac = (mid - p.t0) / (p.t1 - p.t0)
                if span > 0:
                    frac = 0.5 * (frac + np.abs(_level(path, mid, p) - p.l0) / span)
                below = frac < s
                lo, hi = np.where(below, mid, lo), np.where(below, hi, mid)
            tv = 0.5 * (lo + hi)
            lv = _level(path, tv, p)
        lv[-1], tv[-1] = p.l1, p.t1  # exact piece ends
        levels.append(np.clip(lv, 0.0, 1.0))
        times.append(tv)
        segment.append(np.full(m, g))
    lev = np.concatenate(levels)
    return lev, (np.concatenate(times) if viscoelastic else None), np.concatenate(segment)
