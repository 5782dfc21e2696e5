"""The coated body's effective modulus against Perriot & Barthel's fit (2004).

Perriot & Barthel (J. Mater. Res. 19, 600) fit the effective modulus of a coated
half-space, defined by the flat punch's stiffness S = dP/d(delta) = 2 a E'_eq, as
E'_eq = E'_f + (E'_s - E'_f)/(1 + (k0 t/a)^n), log10 k0 = -0.093 + 0.792 x + 0.05 x^2,
x = log10(E'_s/E'_f), n ~ 1.06 ... 1.32, stated accurate to a few percent.

Here E'_eq/E'_f is the frictionless flat punch's P/delta on the coated body (history,
profile 'flat', one load step, n = 240) over the half-space's at the same n (the
discretization cancels: n = 480 changes the ratio by 2e-4 at a/h = 1, E2/E1 = 0.1 and
3e-4 at a/h = 10, E2/E1 = 100), at nu = nu2 = 0.3, so E'_s/E'_f = E2/E1. For each
E2/E1 the script prints the fit's exponent in [1.06, 1.32] that fits best and the
largest relative departure over a/h = 0.1 ... 16 with it (and with the range's ends).

    python benchmarks/bench_perriot_barthel.py
"""

import numpy as np

from contactlib import history
from contactlib.coating_study import perriot_barthel_modulus

NU = 0.3
RATIOS = (0.1, 0.3, 1.0, 3.0, 10.0, 16.0)
MODULI = (0.5, 0.1, 10.0, 100.0)


def stiffness(ratio: float, modulus: float | None, n: int = 240) -> float:
    """Frictionless flat punch P/delta (scaled), on a coated body or the half-space (None)."""
    kw = {} if modulus is None else {"base": "elastic", "substrate_modulus": modulus,
                                     "substrate_nu": NU}
    r = history("sphere", NU, 0.0, [0.0, 1.0], 2, n=n, slab_ratio=ratio, profile="flat", **kw)
    return float(r.load_ratio[-1] / r.indentation[-1])


def main() -> None:
    half = stiffness(0.0, None)
    exponents = np.linspace(1.06, 1.32, 27)
    print(f"{'E2/E1':>7} {'best n':>7} {'max dep (best n)':>17} {'n=1.06':>8} {'n=1.32':>8}")
    for m in MODULI:
        eq = np.array([stiffness(r, m) for r in RATIOS]) / half
        dep = np.array([np.max(np.abs(perriot_barthel_modulus(RATIOS, m, e) / eq - 1.0))
                        for e in exponents])
        best = int(np.argmin(dep))
        print(f"{m:7g} {exponents[best]:7.2f} {dep[best]:17.3%} {dep[0]:8.2%} {dep[-1]:8.2%}")
        print("   a/h:", " ".join(f"{r:g}" for r in RATIOS))
        print("   E'_eq/E'_f:", " ".join(f"{v:.4f}" for v in eq))


if __name__ == "__main__":
    main()
