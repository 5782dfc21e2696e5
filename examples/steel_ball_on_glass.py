"""A steel ball on a glass flat, in SI units.

A steel ball of radius 5 mm is pressed on soda-lime glass to 100 N with a
friction coefficient of 0.2. Prints the contact radius, the stick radius,
the peak pressure and the frictional energy of the loading, each with its
estimated relative error (docs/physical.md explains every line).

    python examples/steel_ball_on_glass.py
"""

from contactlib import physical_solve

ball = physical_solve("sphere", "5mm", "100N", "steel", "soda_lime_glass",
                      friction=0.2)

print(ball)  # the full summary
print()
a, c = ball.contact_radius, ball.stick_radius  # m
print(f"contact radius a = {a * 1e6:.1f} µm")
print(f"stick radius   c = {c * 1e6:.1f} µm (c/a = {c / a:.4f})")
print(f"peak pressure    = {ball.peak_pressure / 1e9:.3f} GPa")
print(f"frictional energy on loading = {ball.frictional_energy * 1e9:.2f} nJ"
      f" (estimated relative error {ball.errors['frictional_energy']:.1e})")
