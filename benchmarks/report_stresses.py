"""Numbers quoted in docs/stresses.md (run: python benchmarks/report_stresses.py).

1. Errors against the closed forms (Huber, McEwen, Smith-Liu) from exact samples of
   sqrt(1 - x^2) on m = 201 and 2001 points, and through a Solution (n = 256).
2. The maximum shear (Tresca) of the closed forms against the field's.
3. The method's own errors: the xi quadrature (panels halved) and the surface row's ring
   integrals (rules of twice the density).
4. The partial-slip field as n grows (128, 256, 512).
5. The sphere against c/a (nu = 0.3, n = 256): k, the maxima of Tresca and von Mises
   and where they are, the surface radial stress at r = a and its largest value.
6. First yield (von Mises) against c/a and k, both geometries: p0/Y and where.
7. Surface radial stress at r = a and its largest value outside, sphere (nu = 0.3),
   rigid and elastic indenters (E1/E2 = 3 and 0.5, nu1 = 0.2), in the body and in the
   indenter.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import minimize_scalar

import contactlib.stresses as st
from contactlib import solve

NU = 0.3


def huber_axis(z):
    return (-1.0 / (1.0 + z**2),
            -(1.0 + NU) * (1.0 - z * np.arctan(1.0 / z)) + 0.5 / (1.0 + z**2))


def _mn(x, z):
    a = 1.0 - x**2 + z**2
    root = np.sqrt(a**2 + 4.0 * x**2 * z**2)
    return np.sqrt(0.5 * (root + a)), np.sign(x) * np.sqrt(np.maximum(0.5 * (root - a), 0.0))


def mcewen(x, z):
    m, n = _mn(x, z)
    s = m * m + n * n
    return {"sigma_xx": -(m * (1 + (z * z + n * n) / s) - 2 * z),
            "sigma_zz": -m * (1 - (z * z + n * n) / s), "sigma_xz": -n * (m * m - z * z) / s}


def closed_forms() -> None:
    print("## 1. Largest error against the closed forms (units of p0)")
    print("| tractions | sphere axis (Huber), z in [0.02, 4] | cylinder field (McEwen), "
          "|x| <= 1.95, z in [0, 2] |")
    print("|---|---|---|")
    z = np.linspace(0.02, 4.0, 200)
    xg, zg = np.linspace(-1.95, 1.95, 40), np.linspace(0.0, 2.0, 41)
    ref = mcewen(*np.meshgrid(xg, zg))
    for m in (201, 2001):
        xi = np.linspace(0.0, 1.0, m)
        p = np.sqrt(1 - xi**2)
        f = st.halfspace_stresses(xi, p, 0 * xi, [0.0], z, NU)
        szz, srr = huber_axis(z)
        e1 = max(np.max(np.abs(f["sigma_zz"][:, 0] - szz)),
                 np.max(np.abs(f["sigma_rr"][:, 0] - srr)))
        g = st.halfplane_stresses(xi, p, 0 * xi, xg, zg, NU)
        e2 = max(np.max(np.abs(g[k] - ref[k])) for k in ref)
        print(f"| sqrt(1 - x^2) on {m} points | {e1:.1e} | {e2:.1e} |")
    for geometry in ("sphere", "cylinder"):
        sol = solve(geometry, NU, stick_ratio=0.0, n=256, energy=False)
        if geometry == "sphere":
            ds = st.subsurface_stresses(sol, [0.0], z)
            szz, srr = huber_axis(z)
            e = max(np.max(np.abs(ds.sigma_zz.values[:, 0] - szz)),
                    np.max(np.abs(ds.sigma_rr.values[:, 0] - srr)))
            print(f"| solve('sphere', 0.3, stick_ratio=0, n=256) | {e:.1e} | |")
        else:
            ds = st.subsurface_stresses(sol, np.abs(xg), zg)
            sgn = np.sign(xg)
            e = max(np.max(np.abs(ds[k].values * (sgn if k == "sigma_xz" else 1) - ref[k]))
                    for k in ref)
            print(f"| solve('cylinder', 0.3, stick_ratio=0, n=256) | | {e:.1e} |")


def maxima() -> None:
    print("\n## 2. Maximum shear (Tresca), closed form against the field (n = 256)")
    print("| case | closed form: value, z/a | field: value, z/a |")
    print("|---|---|---|")

    def sphere_tau(z):
        szz, srr = huber_axis(np.array([z]))
        return 0.5 * abs(srr[0] - szz[0])

    def cyl_tau(z):
        r = mcewen(np.array([0.0]), np.array([z]))
        return 0.5 * abs(r["sigma_xx"][0] - r["sigma_zz"][0])

    for geometry, tau in (("sphere", sphere_tau), ("cylinder", cyl_tau)):
        best = minimize_scalar(lambda z: -tau(z), bounds=(0.2, 1.5), method="bounded",
                               options={"xatol": 1e-10})
        sol = solve(geometry, NU, stick_ratio=0.0, n=256, energy=False)
        ds = st.subsurface_stresses(sol, np.linspace(0.0, 1.0, 51), np.linspace(0.2, 1.2, 101))
        top = st.field_maximum(ds, "tresca")
        print(f"| {geometry} | {-best.fun:.5f}, {best.x:.4f} | {top['value']:.5f}, "
              f"{top['z']:.4f} (x = {top['x']:g}) |")


def method_errors() -> None:
    print("\n## 3. The sphere's method errors (c/a = 0.5, n = 256, 100 x 100 grid on [0, 2]^2)")
    sol = solve("sphere", NU, stick_ratio=0.5, n=256, energy=False)
    x = z = np.linspace(0.0, 2.0, 100)
    args = (sol.xi, sol.pressure, sol.shear)
    base = st.halfspace_stresses(*args, x, z, NU)
    panel = st.quadrature.PANEL
    try:
        st.quadrature.PANEL = panel / 2
        half = st.halfspace_stresses(*args, x, z, NU)
    finally:
        st.quadrature.PANEL = panel
    e = max(np.max(np.abs(base[k][1:] - half[k][1:])) for k in base)
    print(f"xi quadrature (panels halved), z > 0: {e:.1e}")
    xs = np.linspace(0.0, 2.0, 2001)  # through every node of the tractions
    base = st.halfspace_stresses(*args, xs, [0.0], NU)
    rules = st.surface.RING_TANH_SINH, st.surface.RING_GAUSS
    try:
        st.surface.RING_TANH_SINH, st.surface.RING_GAUSS = (1.0 / 12.0, 4.0), 20
        fine = st.halfspace_stresses(*args, xs, [0.0], NU)
    finally:
        st.surface.RING_TANH_SINH, st.surface.RING_GAUSS = rules
    e = max(np.max(np.abs(base[k] - fine[k])) for k in base)
    print(f"surface row z = 0 (ring integrals against rules of twice the density): {e:.1e}")


def convergence() -> None:
    print("\n## 4. Partial slip (sphere, c/a = 0.5) as n grows: von Mises on [0, 1.5]^2, 31 x 31")
    x = z = np.linspace(0.0, 1.5, 31)
    vm = {n: st.subsurface_stresses(solve("sphere", NU, stick_ratio=0.5, n=n, energy=False),
                                    x, z).von_mises.values for n in (128, 256, 512)}
    d1, d2 = np.max(np.abs(vm[256] - vm[128])), np.max(np.abs(vm[512] - vm[256]))
    print(f"max |256 - 128| = {d1:.1e}, max |512 - 256| = {d2:.1e}, observed order "
          f"{np.log2(d1 / d2):.2f}")


def against_stick_ratio() -> None:
    print("\n## 5. Sphere, nu = 0.3, n = 256: maxima and surface tension against c/a")
    print("| c/a | k | max Tresca (x, z) | max von Mises (x, z) | sigma_rr(a, 0) | "
          "max surface sigma_rr (r/a) |")
    print("|---|---|---|---|---|---|")
    x, z = np.linspace(0.0, 1.5, 76), np.linspace(0.0, 1.0, 51)
    xs = np.linspace(0.9, 3.0, 211)
    for c in (0.0, 0.25, 0.5, 0.75, 0.9, 1.0):
        sol = solve("sphere", NU, stick_ratio=c, n=256, energy=False)
        ds = st.subsurface_stresses(sol, x, z)
        t, v = st.field_maximum(ds, "tresca"), st.field_maximum(ds, "von_mises")
        srr = st.surface_radial_stress(sol, xs)
        i = int(np.argmax(srr))
        edge = srr[np.argmin(np.abs(xs - 1.0))]
        print(f"| {c:g} | {sol.friction_coefficient:.4g} | {t['value']:.4f} ({t['x']:.2f}, "
              f"{t['z']:.3f}) | {v['value']:.4f} ({v['x']:.2f}, {v['z']:.3f}) | {edge:.4f} | "
              f"{srr[i]:.4f} ({xs[i]:.3f}) |")


def yield_table() -> None:
    print("\n## 6. First yield (von Mises), nu = 0.3, n = 256")
    print("| geometry | c/a | k | p0/Y | P/(Y a^2) or P/(Y a) | place (x/a, z/a) |")
    print("|---|---|---|---|---|---|")
    for geometry in ("sphere", "cylinder"):
        for c in (0.0, 0.25, 0.5, 0.75, 0.9):
            sol = solve(geometry, NU, stick_ratio=c, n=256, energy=False)
            y = st.first_yield(sol)
            print(f"| {geometry} | {c:g} | {sol.friction_coefficient:.4g} | "
                  f"{y['p0_over_yield']:.4f} | {y['load_over_yield']:.4f} | "
                  f"({y['x']:.2f}, {y['z']:.3f}) |")


def indenters() -> None:
    print("\n## 7. Surface radial stress / p0 of the sphere, nu = 0.3, n = 256 (nu1 = 0.2)")
    print("| indenter | body | beta | c/a | k | sigma_rr(a, 0) | max outside (r/a) |")
    print("|---|---|---|---|---|---|---|")
    xs = np.linspace(1.0, 3.0, 401)
    for ratio, body in ((np.inf, "body"), (3.0, "body"), (3.0, "indenter"), (0.5, "body"),
                        (0.5, "indenter")):
        for c in (0.0, 0.5, 0.9):
            kw = {} if np.isinf(ratio) else {"indenter_modulus": ratio, "indenter_nu": 0.2}
            sol = solve("sphere", NU, stick_ratio=c, n=256, energy=False, **kw)
            srr = st.surface_radial_stress(sol, xs, body=body)
            i = int(np.argmax(srr))
            who = "rigid" if np.isinf(ratio) else f"E1/E2 = {ratio:g}"
            print(f"| {who} | {body} | {sol.dundurs_beta:+.3f} | {c:g} | "
                  f"{sol.friction_coefficient:.4g} | {srr[0]:.4f} | {srr[i]:.4f} ({xs[i]:.3f}) |")


if __name__ == "__main__":
    closed_forms()
    maxima()
    method_errors()
    convergence()
    against_stick_ratio()
    yield_table()
    indenters()
