"""Rule layers_study: frictionless load and k on layers against a/h (one dataset)."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import io, layer_study  # noqa: E402

study = layer_study.layer_study()
io.write_dataset(io.layer_study_to_dataset(study), snakemake.output[0])  # noqa: F821
print(f"layers: {study.friction.size} cases at n = {study.n}")
