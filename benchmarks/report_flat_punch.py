"""The flat punch under ``history`` against its closed forms and the self-similar solution.

Prints, for nu = 0.3 unless stated:

1. frictionless (Boussinesq) and no-slip (Mossakovskii) stiffness P/(2 E* a delta), sphere,
   at n = 120, 240, 480: the relative error, falling at first order;
2. the stick ratio c/a at k = 0.1 ... 0.5 against the self-similar default method's
   (n = 512; the same for every power law), and P/(2 E* a delta) against the
   paraboloid's dP/d(delta), at n = 240 and 480;
3. one load-unload cycle (k = 0.2, n = 240, 100 steps a segment): the frictional work
   at the top and at the end, with its estimate, against a run refined fourfold
   (n = 960, 400 steps).

Run: ``python benchmarks/report_flat_punch.py`` (about 2 min).
"""

from __future__ import annotations

import math

from contactlib import history, solve


def flat(geometry, nu, k, n, path=(0, 1), steps=2, **kw):
    return history(geometry, nu, k, list(path), steps, n=n, profile="flat",
                   error_estimate=kw.pop("error_estimate", False), **kw)


def main() -> None:
    meshes = (120, 240, 480)
    print("1. sphere stiffness P/(2 E* a delta): relative error at n =", meshes)
    for nu in (0.0, 0.3, 0.45):
        for k, exact, name in ((0.0, 1.0, "Boussinesq"),
                               (math.inf, (1 - nu) * math.log(3 - 4 * nu) / (1 - 2 * nu),
                                "Mossakovskii")):
            errs = [1.0 / flat("sphere", nu, k, n).indentation[-1] / exact - 1 for n in meshes]
            print(f"   nu = {nu:4}, {name:12} {exact:.6f}: "
                  + "  ".join(f"{e:+.2e}" for e in errs))

    print("2. partial slip against the self-similar solution (nu = 0.3)")
    print("   geometry   k    c/a self-similar   c/a - it at n = 240, 480"
          "      stiffness error at n = 240, 480")
    for geometry in ("sphere", "cylinder"):
        for k in (0.1, 0.2, 0.3, 0.5):
            s = solve(geometry, 0.3, friction=k, n=512)
            runs = [flat(geometry, 0.3, k, n) for n in (240, 480)]
            dc = "  ".join(f"{r.stick_ratio[-1] - s.stick_ratio:+.2e}" for r in runs)
            stiff = ""
            if geometry == "sphere":
                ratio = s.load_ratio / s.extra["indentation"]
                stiff = "  ".join(f"{1 / r.indentation[-1] / ratio - 1:+.2e}" for r in runs)
            print(f"   {geometry:9} {k:4}  {s.stick_ratio:.5f}          {dc}      {stiff}")

    print("3. a cycle (k = 0.2): work at the top and the end, estimate against n x 4, "
          "steps x 4")
    for geometry in ("sphere", "cylinder"):
        r = flat(geometry, 0.3, 0.2, 240, (0, 1, 0), 100, error_estimate=True)
        ref = flat(geometry, 0.3, 0.2, 960, (0, 1, 0), 400)
        for label, i, j in (("top", 100, 400), ("end", 200, 800)):
            err = abs(r.frictional_work[i] - ref.frictional_work[j]) / r.work_scale
            est = r.work_error_estimate[i]
            print(f"   {geometry:9} {label}: V = {r.frictional_work[i]:.6f}, error "
                  f"{err:.2e}, estimate {est:.2e} ({est / err:.2f} x)")
        err_c = abs(r.stick_ratio[100] - ref.stick_ratio[400])
        est_c = r.stick_radius_error_estimate[100]
        print(f"   {geometry:9} c/a at the top {r.stick_ratio[100]:.5f}: error {err_c:.2e}, "
              f"estimate {est_c:.2e} ({est_c / err_c:.2f} x)")


if __name__ == "__main__":
    main()
