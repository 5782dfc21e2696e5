"""Consistency checks of a partial-slip solution (docs/methods.md, "Consistency flags").

* ``stick_admissible``: |q| <= k p at every checked point of the stick zone;
* ``slip_direction_ok``: the slip rate opposes the shear at every checked point
  of the slip zone, q * s <= 0 with s = 2 U - xi dU/dxi the self-similar slip
  rate (paper Eq. 18 divided by a da).

Violations are measured relative to the size of the quantities involved, with
a tolerance ``rtol = 1e-4``: the default method's own discretization error
at its default resolution is below it (the traction difference q - kp is
quadratic inside the last stick element, an O(h^2) artefact: 2.5e-5 at
c/a = 0.02 with n = 128), while a wrong k or a breakdown of the single stick
zone shows violations of order 1e-2 ... 1.
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["stick_violation", "slip_violation", "flags", "record_flags", "FLAG_NAMES",
           "VIOLATION_NAMES"]

# the names of the flags and of the measures behind them, written once: the workflow's
# check stage, the datasets and the summary take them from here
FLAG_NAMES = ("stick_admissible", "slip_direction_ok", "consistent")
VIOLATION_NAMES = ("stick_violation", "slip_violation")


def stick_violation(q: np.ndarray, p: np.ndarray, k: float) -> float:
    """max(|q| - k p) over stick points, relative to max|k p| (<= 0 when admissible)."""
    if np.isnan(k):  # no k (a failed solve): nothing is admissible
        return float("nan") if q.size else 0.0
    if q.size == 0 or not np.isfinite(k):
        return 0.0 if q.size == 0 else -np.inf
    scale = max(float(np.max(np.abs(k * p))), 1e-300)  # |.|: a scheme may give k < 0
    return float(np.max(np.abs(q) - k * p) / scale)


def slip_violation(q: np.ndarray, s: np.ndarray) -> float:
    """max(q s) over slip points, relative to max|q| max|s| (<= 0 when consistent)."""
    if q.size == 0:
        return 0.0
    scale = max(float(np.max(np.abs(q)) * np.max(np.abs(s))), 1e-300)
    return float(np.max(q * s) / scale)


def flags(stick_q, stick_p, k, slip_q, slip_s, rtol: float = 1e-4) -> dict:
    """The three consistency flags (docs/conventions.md) and the violation measures behind them."""
    sv = stick_violation(np.asarray(stick_q), np.asarray(stick_p), k)
    dv = slip_violation(np.asarray(slip_q), np.asarray(slip_s))
    ok_stick = bool(sv <= rtol)
    ok_slip = bool(dv <= rtol)
    return {"stick_admissible": ok_stick, "slip_direction_ok": ok_slip,
            "consistent": ok_stick and ok_slip,
            "stick_violation": sv, "slip_violation": dv}


def record_flags(rec: Any) -> dict[str, Any]:
    """:func:`flags` of a case record (:class:`contactlib.result.CaseRecord`: its stored
    stick-zone and slip-zone samples and k)."""
    return flags(rec.stick_q, rec.stick_p, rec.k, rec.slip_q, rec.slip_s)
