"""Rule fretting_stick_map_study: the sphere's stick zone per direction under a growing Q,
two cases (contactlib.fretting_api.stick_map_study), one dataset each."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import fretting_api, io  # noqa: E402

for name, res in fretting_api.stick_map_study().items():
    io.write_dataset(io.fretting_to_dataset(res), snakemake.output[name])  # noqa: F821
    print(f"{name}: beta = {res.beta:.3g}, n = {res.n}, {res.steps} steps a segment, "
          f"converged: {bool(res.converged.all())}", flush=True)
