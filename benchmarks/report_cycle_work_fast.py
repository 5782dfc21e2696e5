"""A load cycle's frictional work to 1e-4, fast? What extrapolation in n and the steps give.

Run: python benchmarks/report_cycle_work_fast.py [--fine] [--only G:K,...]
(``--fine`` adds n = 960 to the ladder, about 1-3 min a case, and takes the reference
from n = 240, 480, 960; ``--only cylinder:0.2,sphere:0.05`` runs the listed cases)

For the sphere and the cylinder (half-plane) at nu = 0.3, k = 0.05, 0.2, 0.5, path
0, 1, 0 (issue 41, item 3: the cycle's work and the stick radius at the peak to 1e-4
relative in at most 1 s of CPU), it runs plain histories (``contactlib.history``, no
estimate) on a ladder of n with three steps a segment per element and prints, per case:

* the **reference** cycle work: the Richardson extrapolation of the ladder's top three
  runs (n = 120, 240, 480; with ``--fine`` 240, 480, 960) with their measured order,
  and its own uncertainty, the spread of that extrapolation over orders 1.5 ... 2.5
  (a case whose measured order is outside 1 ... 3 gets no reference: the ladder is not
  converging);
* for each recipe, the cycle work, its relative error against the reference, the
  recipe's own error estimate and the CPU of all its runs in units of one dense LU
  factorization of order 1024 (``scipy.linalg.lu_factor`` of a random matrix, median of
  5, ``time.process_time``) measured in the same run, and in seconds. The recipes:

  - ``plain n``: one run (estimate: none);
  - ``R2(n/2, n)``: Richardson in n with steps proportional to n, order 2 fixed
    (estimate: the largest change of the extrapolation over orders 1.5 ... 2.5);
  - ``Rp(n/4, n/2, n)``: Richardson with the order measured from the three runs
    (estimate: its difference from ``R2(n/2, n)``; no value where the measured order is
    outside 1 ... 3);
  - ``fit2(60 ... 160)``: least squares W = W_inf + C n^-2 over n = 60, 80, 96, 120, 160,
    which averages the stick edge's quantization over five meshes (estimate: twice the
    standard error of W_inf from the residuals);
  - ``inverse's loading + ...``: the loading half's work from the self-similar inverse
    (``contactlib.solve(geometry, 0.3, friction=k)``: the path's first segment is a
    monotonic loading from zero, whose states are self-similar) plus the history's
    unloading half, plain at n = 240 or R2(120, 240) (estimate: the inverse's work
    estimate, plus the R2 band for the second);
* the stick radius at the peak (units a_max) of the history at n = 240 (sub-element, from
  ``history_solver.stick_radius``) against the self-similar inverse
  ``contactlib.solve(geometry, 0.3, friction=k)``: c = (c/a) a(P_max), a(P_max) =
  load_ratio^(-1/3) (sphere) or ^(-1/2) (cylinder), an independent truth, since the path's
  first segment is a monotonic loading from zero; and the inverse's own CPU;
* the mesh's phase: the cycle work at n = 60, 120, 240 on meshes stretched so that the
  element edges near a_max shift by 0, 1/4, 1/2, 3/4 of an element (the spread is the
  quantization's noise; the mean averages it), and R2 of the means;
* the steps' share: at n = 120, the cycle work at 1, 2, 3 and 6 steps a segment per
  element, relative to 12 (the steps' limit at fixed n).
"""

from __future__ import annotations

import math
import os
import sys
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

import contactlib  # noqa: E402
from contactlib import history  # noqa: E402
from contactlib.solvers import history_solver as hs  # noqa: E402
from contactlib.history_api import load_levels  # noqa: E402
from contactlib.history_plan import peak_step  # noqa: E402
from contactlib.model import contact  # noqa: E402
# the same LU(1024) unit as the tolerance report (this script's folder is on sys.path)
from report_history_tolerance import lu_unit  # noqa: E402

NU = 0.3
PATH = (0, 1, 0)
CASES = [(g, k) for g in ("sphere", "cylinder") for k in (0.05, 0.2, 0.5)]
PER_ELEMENT = 3  # steps a segment per element
FIT_N = (60, 80, 96, 120, 160)
LADDER = sorted(set(FIT_N) | {30, 240, 480})
ORDER_BAND = (1.5, 2.5)  # orders over which an extrapolation's spread is its uncertainty
STEPS_N, STEPS_PER = 120, (1, 2, 3, 6, 12)
PHASE_N, PHASES = (60, 120, 240), (0.0, 0.25, 0.5, 0.75)


def run(geometry: str, k: float, n: int, steps: int) -> tuple[float, float, float, float]:
    """(cycle work, its unloading part, stick radius at the peak in a_max, CPU s) of one
    plain history."""
    t0 = time.process_time()
    res = history(geometry, NU, k, PATH, steps, n=n, error_estimate=False)
    cpu = time.process_time() - t0
    if not res.converged.all():
        return math.nan, math.nan, math.nan, cpu  # a step that did not converge: no value
    top = peak_step(res.load_ratio)
    c = float(np.nan_to_num(res.stick_ratio[top] * res.contact_radius[top]))
    work = res.frictional_work
    return float(work[-1]), float(work[-1] - work[top]), c, cpu


def shifted_work(geometry: str, k: float, n: int, shift: float) -> float:
    """Cycle work of a plain history on the mesh stretched to ``MESH_EXTENT (1 + shift /
    n)``: every element edge near a_max moves by about ``shift / MESH_EXTENT`` of an
    element (the element size changes by ``shift / n``, relatively)."""
    ops = hs.build_operators(contact(geometry, NU), n, hs.MESH_EXTENT * (1.0 + shift / n))
    levels, _ = load_levels(PATH, PER_ELEMENT * n)
    raw = hs.run_history(ops, k, levels)
    return float(raw.work[-1]) if raw.converged.all() else math.nan


def richardson(coarse: float, fine: float, order: float, ratio: float = 2.0) -> float:
    return fine + (fine - coarse) / (ratio**order - 1.0)


def measured_order(w1: float, w2: float, w4: float) -> float:
    """Order of convergence of W(n/4), W(n/2), W(n); NaN where the changes alternate."""
    with np.errstate(divide="ignore", invalid="ignore"):
        q = (w1 - w2) / (w2 - w4)
    return math.log2(q) if q > 0.0 and math.isfinite(q) else math.nan


def band(coarse: float, fine: float) -> float:
    """Largest change of the order-2 extrapolation over the orders of ORDER_BAND."""
    mid = richardson(coarse, fine, 2.0)
    return max(abs(richardson(coarse, fine, p) - mid) for p in ORDER_BAND)


def fit2(ns: tuple[int, ...], works: list[float]) -> tuple[float, float]:
    """(W_inf, twice its standard error) of W = W_inf + C n^-2 by least squares."""
    a = np.column_stack([np.ones(len(ns)), np.asarray(ns, float) ** -2.0])
    y = np.asarray(works)
    coef, *_ = np.linalg.lstsq(a, y, rcond=None)
    resid = y - a @ coef
    dof = len(ns) - 2
    sigma2 = float(resid @ resid) / dof
    cov = sigma2 * np.linalg.inv(a.T @ a)
    return float(coef[0]), 2.0 * math.sqrt(cov[0, 0])


def inverse(geometry: str, k: float) -> tuple[float, float, float, float]:
    """The self-similar inverse's monotonic loading to P_max: (stick radius at the peak,
    units a_max; the loading's frictional work and its estimated error, units of the
    history's work; CPU s)."""
    t0 = time.process_time()
    sol = contactlib.solve(geometry, NU, friction=k)
    cpu = time.process_time() - t0
    power = 3.0 if geometry == "sphere" else 2.0  # P ~ a^power
    a = sol.load_ratio ** (-1.0 / power)  # a(P_max) / a_max
    work = sol.frictional_work * a ** (power + 2.0)  # V R^2 / (E* a^(power + 2)) -> a_max
    return float(sol.stick_ratio * a), work, work * sol.work_error_estimate, cpu


def case(geometry: str, k: float, ladder: list[int], unit: float) -> None:
    runs = {n: run(geometry, k, n, PER_ELEMENT * n) for n in ladder}
    w = {n: r[0] for n, r in runs.items()}
    unload = {n: r[1] for n, r in runs.items()}
    cpu = {n: r[3] for n, r in runs.items()}
    n3 = ladder[-1]
    n1, n2 = n3 // 4, n3 // 2
    p = measured_order(w[n1], w[n2], w[n3])
    print(f"\n### {geometry}, k = {k:g}\n")
    print("ladder (n: cycle work, CPU s): " + ", ".join(
        f"{n}: {w[n]:.7e}, {cpu[n]:.2f}" for n in ladder))
    if ORDER_BAND[0] - 0.5 <= p <= ORDER_BAND[1] + 0.5:
        ref = richardson(w[n2], w[n3], p)
        ref_unc = max(abs(richardson(w[n2], w[n3], q) - ref) for q in ORDER_BAND) / ref
        print(f"reference: Richardson of n = {n1}, {n2}, {n3} with their order {p:.2f}: "
              f"{ref:.7e} (its uncertainty over orders {ORDER_BAND[0]} ... "
              f"{ORDER_BAND[1]}: {ref_unc:.1e} relative)\n")
    else:
        ref = math.nan
        print(f"reference: none (the order measured from n = {n1}, {n2}, {n3} is {p:.2f}: "
              f"the ladder is not converging)\n")

    def err(value: float) -> str:
        return f"{(value - ref) / ref:+.1e}" if math.isfinite(ref * value) else "-"

    rows = []
    for n in (240, 480):
        rows.append((f"plain {n}", w[n], math.nan, cpu[n]))
    for n in (120, 240):
        rows.append((f"R2({n // 2}, {n})", richardson(w[n // 2], w[n], 2.0),
                     band(w[n // 2], w[n]), cpu[n // 2] + cpu[n]))
    for n in (120, 240):
        q = measured_order(w[n // 4], w[n // 2], w[n])
        value = richardson(w[n // 2], w[n], q) if 1.0 <= q <= 3.0 else math.nan
        rows.append((f"Rp({n // 4}, {n // 2}, {n}), p = {q:.2f}", value,
                     abs(value - richardson(w[n // 2], w[n], 2.0)),
                     cpu[n // 4] + cpu[n // 2] + cpu[n]))
    value, estimate = fit2(FIT_N, [w[n] for n in FIT_N])
    rows.append((f"fit2({FIT_N[0]} ... {FIT_N[-1]})", value, estimate,
                 sum(cpu[n] for n in FIT_N)))
    c_true, v_load, v_load_err, c_cpu = inverse(geometry, k)
    rows.append(("inverse's loading + unloading of plain 240", v_load + unload[240],
                 v_load_err, c_cpu + cpu[240]))
    rows.append(("inverse's loading + R2(120, 240) of the unloading",
                 v_load + richardson(unload[120], unload[240], 2.0),
                 v_load_err + band(unload[120], unload[240]), c_cpu + cpu[120] + cpu[240]))
    print("| recipe | cycle work | error vs reference | its estimate | CPU in LU(1024) (s) |")
    print("|---|---|---|---|---|")
    scale = ref if math.isfinite(ref) else w[ladder[-1]]
    for name, value, estimate, seconds in rows:
        est = f"{estimate / scale:.1e}" if math.isfinite(estimate) else "-"
        print(f"| {name} | {value:.7e} | {err(value)} | {est} | {seconds / unit:.0f} "
              f"({seconds:.2f}) |")

    c_hist = {n: runs[n][2] for n in (120, 240, ladder[-1])}
    print(f"\nstick radius at the peak (a_max): inverse {c_true:.6f} ({c_cpu / unit:.0f} "
          f"LU(1024), {c_cpu:.2f} s); history " + ", ".join(
              f"n = {n}: {c:.6f} ({c - c_true:+.1e})" for n, c in c_hist.items()))

    shifted = {n: [shifted_work(geometry, k, n, s) for s in PHASES] for n in PHASE_N}
    mean = {n: float(np.mean(v)) for n, v in shifted.items()}
    q = measured_order(*(mean[n] for n in PHASE_N))
    scale = ref if math.isfinite(ref) else w[ladder[-1]]
    print(f"mesh phase (edges shifted by {', '.join(f'{s:g}' for s in PHASES)} of an element "
          f"at about a_max): " + ", ".join(
              f"n = {n}: spread {(max(v) - min(v)) / scale:.1e}, mean's error "
              f"{err(mean[n])}" for n, v in shifted.items())
          + f"; R2 of the means at n = {PHASE_N[-1]}: "
          f"{err(richardson(mean[PHASE_N[-2]], mean[PHASE_N[-1]], 2.0))}, their order {q:.2f}")
    steps = {s: run(geometry, k, STEPS_N, s * STEPS_N)[0] for s in STEPS_PER}
    last = steps[STEPS_PER[-1]]
    print(f"steps at n = {STEPS_N} (per element: work relative to {STEPS_PER[-1]} an "
          f"element): " + ", ".join(f"{s}: {(steps[s] - last) / last:+.1e}"
                                    for s in STEPS_PER[:-1])
          + (f"; the mesh's error at this n: {err(w[STEPS_N])}" if math.isfinite(ref)
             else ""), flush=True)


def main(argv: list[str]) -> None:
    ladder = list(LADDER)
    if "--fine" in argv:
        argv = [a for a in argv if a != "--fine"]
        ladder.append(960)
    cases = CASES
    if "--only" in argv:
        i = argv.index("--only")
        cases = [(g, float(k)) for g, k in (c.split(":") for c in argv[i + 1].split(","))]
    unit = lu_unit()
    print(f"## A cycle's frictional work, fast (nu = {NU}, path {PATH}, {PER_ELEMENT} steps "
          f"a segment per element); LU(1024) = {unit * 1e3:.1f} ms CPU")
    for geometry, k in cases:
        case(geometry, k, ladder, unit)


if __name__ == "__main__":
    main(sys.argv[1:])
