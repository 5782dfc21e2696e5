"""Rule influence: the parts of an influence set -> results/influence/<key>/<part>.npz."""

import sys
from pathlib import Path

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import io, pipeline  # noqa: E402

spec = snakemake.params.spec  # noqa: F821
folder = Path(snakemake.output[0])  # noqa: F821
folder.mkdir(parents=True, exist_ok=True)
for part in spec["parts"]:
    print(f"influence {part}: {spec}", flush=True)
    io.write_arrays(pipeline.influence(spec, part), folder / f"{part}.npz")
