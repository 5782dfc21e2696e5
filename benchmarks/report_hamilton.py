"""The sliding and partially slipping sphere's field against Hamilton's closed form.

Run: python benchmarks/report_hamilton.py [--reference PATH/TO/Hertz.py]

Hamilton (Proc. IMechE 197C, 53-59, 1983) gives the whole Cartesian field under a Hertz
pressure with q = mu p along x in closed form. ContactMechanics ships it
(``ContactMechanics/ReferenceSolutions/Hertz.py``: ``stress_Cartesian`` for the pressure,
``stress_for_tangential_loading`` for the shear, both in units of p0 with a = 1). That
file needs only numpy; it is read from PATH, or downloaded with ``pip download --no-deps
contactmechanics==1.8.3`` into a temporary folder. It is not a dependency of contactlib.

Prints, for mu = 0.4 and nu = 0.3 at 600 random points (|x|, |y| < 2, 0.02 < z < 1.6),
the largest difference of each component to Hamilton's, in units of p0, for 101 ... 801
samples of the tractions, with the CPU time of each field.
"""

from __future__ import annotations

import argparse
import importlib.util
import subprocess
import sys
import tempfile
import time
import zipfile
from pathlib import Path

import numpy as np

from contactlib.stresses.tangential import CARTESIAN, mindlin_sphere_stresses

NU, MU = 0.3, 0.4


def _reference(path: str | None):
    if path is None:
        folder = Path(tempfile.mkdtemp())
        subprocess.run([sys.executable, "-m", "pip", "download", "-q", "--no-deps",
                        "contactmechanics==1.8.3", "-d", str(folder)], check=True)
        wheel = next(folder.glob("*.whl"))
        with zipfile.ZipFile(wheel) as z:
            z.extract("ContactMechanics/ReferenceSolutions/Hertz.py", folder)
        path = str(folder / "ContactMechanics/ReferenceSolutions/Hertz.py")
    spec = importlib.util.spec_from_file_location("hamilton_reference", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--reference", help="path of ContactMechanics' Hertz.py")
    ref = _reference(parser.parse_args().reference)
    rng = np.random.default_rng(2026)
    x = np.sort(rng.uniform(-2, 2, 20))
    y = np.sort(rng.uniform(-2, 2, 5))
    z = np.sort(rng.uniform(0.02, 1.6, 6))
    zz, yy, xx = np.meshgrid(z, y, x, indexing="ij")
    args = (xx.ravel(), yy.ravel(), zz.ravel())
    normal = ref.stress_Cartesian(*args, poisson=NU)
    tangential = ref.stress_for_tangential_loading(*args, poisson=NU)
    order = ("sigma_xx", "sigma_yy", "sigma_zz", "sigma_yz", "sigma_xz", "sigma_xy")
    exact = {k: (a + MU * b).reshape(xx.shape) for k, a, b in zip(order, normal, tangential)}
    print(f"mu = {MU}, nu = {NU}, {xx.size} points; largest |field - Hamilton| / p0")
    print("samples  " + "  ".join(f"{k:>9}" for k in CARTESIAN) + "   CPU s")
    for points in (101, 201, 401, 801):
        t0 = time.process_time()
        ds = mindlin_sphere_stresses(MU, 1.0, x, y, z, NU, points=points)
        cpu = time.process_time() - t0
        err = [float(np.abs(ds[k].values - exact[k]).max()) for k in CARTESIAN]
        print(f"{points:7d}  " + "  ".join(f"{e:9.1e}" for e in err) + f"  {cpu:6.2f}")




def maxima() -> None:
    """Largest von Mises in the plane y = 0 (spacing 0.02 a) against mu and Q/(mu P)."""
    x = np.linspace(-1.5, 1.5, 151)
    z = np.linspace(0.0, 1.0, 51)
    print(f"\nnu = {NU}; largest von Mises / p0 in the plane y = 0 and where (x/a, z/a)")
    print("    mu  Q/(mu P)   c/a  von Mises      x      z  p0/Y at first yield")
    for mu, ratio in ((0.0, 1.0), (0.1, 1.0), (0.2, 1.0), (0.3, 1.0), (0.4, 1.0),
                      (0.5, 1.0), (0.4, 0.5), (0.4, 0.9)):
        ds = mindlin_sphere_stresses(mu, ratio, x, [0.0], z, NU)
        vm = ds.von_mises.values[:, 0, :]
        i, j = np.unravel_index(np.argmax(vm), vm.shape)
        print(f"{mu:6.2f}  {ratio:8.2f}  {ds.attrs['stick_ratio']:4.2f}  {vm[i, j]:9.4f}  "
              f"{x[j]:5.2f}  {z[i]:5.2f}  {1 / vm[i, j]:8.4f}")


if __name__ == "__main__":
    main()
    maxima()
