"""A first figure: the friction coefficient k against the stick ratio c/a.

For a rigid sphere on a half-space and a rigid cylinder on a half-plane, at
three Poisson's ratios, the friction coefficient k that gives each stick
ratio c/a under normal loading (at nu = 0.5 the problem decouples and
k = 0). Writes a PNG (default friction_curve.png; the README's figure,
docs/img/friction-curve.png, is this script's output).

    python examples/friction_curve.py [OUTPUT.png]
"""

import sys

import matplotlib

matplotlib.use("Agg")  # no window: write the file only
import matplotlib.pyplot as plt  # noqa: E402

from contactlib import plot, sweep  # noqa: E402

output = sys.argv[1] if len(sys.argv) > 1 else "friction_curve.png"
ratios = [0.02, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95]

with plt.style.context(plot.style_path()):
    fig, axes = plt.subplots(1, 2, figsize=(7.0, 3.0), sharey=True)
    for ax, geometry, body in zip(axes, ["sphere", "cylinder"],
                                  ["half-space", "half-plane"]):
        for nu in (0.0, 0.3, 0.45):
            sols = sweep(geometry, nu, ratios, energy=False)
            ax.plot([s.stick_ratio for s in sols],
                    [s.friction_coefficient for s in sols],
                    marker="o", markersize=3, label=f"ν = {nu:g}")
        ax.set_title(f"rigid {geometry} on a {body}")
        ax.set_xlabel("stick ratio c/a")
        ax.set_xlim(0, 1)
        ax.set_ylim(0, 1.2)
    axes[0].set_ylabel("friction coefficient k")
    axes[0].legend(loc="upper left")
    fig.savefig(output, dpi=120)
print(f"wrote {output}")
