"""Write a sweep to netCDF with the command line, then read it with xarray.

Runs ``contactlib sweep`` (the same as typing it in a shell) into a
temporary folder, opens the dataset with xarray, and shows some of its
variables and k against the stick ratio; the conventions of every variable
are in docs/conventions.md.

    python examples/read_dataset.py
"""

import subprocess
import sys
import tempfile
from pathlib import Path

import xarray as xr

with tempfile.TemporaryDirectory() as tmp:
    path = Path(tmp) / "sweep.nc"
    subprocess.run([sys.executable, "-m", "contactlib", "sweep",
                    "--geometry", "cylinder", "--nu", "0.3",
                    "--stick-ratios", "0.2,0.4,0.6,0.8",
                    "--output", str(path)], check=True)

    with xr.open_dataset(path) as ds:
        print(ds.attrs.get("title", ""), "\n")
        for name in ("friction_coefficient", "error_estimate", "pressure"):
            var = ds[name]
            print(f"{name:21s} {var.dims}: {var.attrs.get('long_name', '')}")
        print()
        k = ds["friction_coefficient"]
        for ratio, value in zip(ds["stick_ratio"].values, k.values):
            print(f"c/a = {ratio:.1f}: k = {value:.6f}")
        # the profiles are functions of the position xi = x/a
        centre = ds["pressure"].sel(xi=0.0, method="nearest")
        print("\npressure p/p0 at the centre:", centre.values.round(5))
