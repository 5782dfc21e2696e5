"""Rule fretting_study: tangential cycles of the cylinder at several amplitudes (one dataset)."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import fretting_api, io  # noqa: E402

results = fretting_api.amplitude_study()
io.write_dataset(io.fretting_study_to_dataset(results), snakemake.output[0])  # noqa: F821
print(f"fretting: {len(results)} paths, n = {results[0].n}, {results[0].steps} steps a segment")
