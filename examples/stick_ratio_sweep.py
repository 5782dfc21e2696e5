"""A sweep of stick ratios with the Python API: k(c/a) for a sphere on a half-space.

For Poisson's ratio 0.3 the friction coefficient k that goes with each stick ratio
c/a, the load over the Hertz load, the frictional work of the loading and the
estimated relative error of k; then the inverse problem, the stick ratio that a
given k produces.

    python examples/stick_ratio_sweep.py
"""

from contactlib import solve, sweep

ratios = [0.1, 0.3, 0.5, 0.7, 0.9]
solutions = sweep("sphere", 0.3, ratios)

print(" c/a      k          P/P_Hertz   V          error of k  resolved")
print(" (V: frictional work of the loading in units of E* a^5 / R^2)")
for sol in solutions:
    print(f" {sol.stick_ratio:<8g} {sol.friction_coefficient:<10.6f} {sol.load_ratio:<11.6f} "
          f"{sol.frictional_work:<10.4e} {sol.error_estimate:<11.1e} {sol.resolved}")

# the inverse: which stick ratio does k = 0.2 give?
inverse = solve("sphere", 0.3, friction=0.2)
print(f"\nk = 0.2 gives c/a = {inverse.stick_ratio:.5f}")
