"""A sweep of stick ratios with the Python API: k(c/a) for a sphere.

A sphere on an elastic half-space, Poisson's ratio 0.3: for each stick ratio
c/a the friction coefficient k, the load over the Hertz load, the frictional
work of the loading and the estimated relative error of k; then the inverse
problem, the stick ratio that a given k produces.

    python examples/stick_ratio_sweep.py
"""

from contactlib import solve, sweep

solutions = sweep("sphere", 0.3, [0.1, 0.3, 0.5, 0.7, 0.9])

print("V: frictional work of the loading in units of E* a^5 / R^2\n")
print(" c/a   k          P/P_Hertz  V           error of k  resolved")
for s in solutions:
    print(f" {s.stick_ratio:<5g} {s.friction_coefficient:<10.6f} "
          f"{s.load_ratio:<10.6f} {s.frictional_work:<11.4e} "
          f"{s.error_estimate:<11.1e} {s.resolved}")

# the inverse: which stick ratio does k = 0.2 give?
inverse = solve("sphere", 0.3, friction=0.2)
print(f"\nk = 0.2 gives c/a = {inverse.stick_ratio:.5f}")
