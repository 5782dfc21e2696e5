"""A load-unload cycle with the incremental stick-slip solver.

A sphere on a half-space (Poisson's ratio 0.3, friction 0.2) is loaded from
0 to the top load and unloaded again, 100 steps a segment. Prints, every 20
steps, the load P/P_max, the contact and stick radii in units of a_max and
the cumulative frictional work, then the work of the whole cycle with its
estimated error.

    python examples/load_cycle.py
"""

from contactlib import history

res = history("sphere", 0.3, 0.2, [0, 1, 0], 100)

print(" step  P/P_max  a/a_max  c/a_max  work (E* a_max^5 / R^2)")
for i in range(20, len(res.load_ratio) - 1, 20):  # the ends have no contact
    a = res.contact_radius[i]
    c = res.stick_ratio[i] * a
    print(f" {i:4d}  {res.load_ratio[i]:7.3f}  {a:7.4f}  {c:7.4f}  "
          f"{res.frictional_work[i]:.4e}")

work, error = res.frictional_work[-1], res.work_error_estimate[-1]
print(f"\nfrictional work of the cycle: {work:.4e} "
      f"(estimated relative error {error:.1e})")
print(f"all steps converged: {bool(res.converged.all())}")
