"""Rule check: slip direction and stick admissibility -> results/checks/<scene>.npz."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import io, pipeline  # noqa: E402

records = io.read_records(snakemake.input.solutions)  # noqa: F821
flags = pipeline.check(records)
print(f"consistent: {int(flags['consistent'].sum())} of {len(records)} cases", flush=True)
io.write_arrays(flags, snakemake.output[0])  # noqa: F821
