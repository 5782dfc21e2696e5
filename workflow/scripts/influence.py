"""Rule influence: one part of an influence set -> results/influence/<key>/<part>.npz."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import io, pipeline  # noqa: E402

spec = snakemake.params.spec  # noqa: F821
part = snakemake.wildcards.part  # noqa: F821
print(f"influence {part}: {spec}", flush=True)
io.write_arrays(pipeline.influence(spec, part), snakemake.output[0])  # noqa: F821
