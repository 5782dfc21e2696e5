"""Rule history_assemble: a history scene's runs stacked along k -> results/datasets/<scene>.nc."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import io  # noqa: E402

ds = io.stack_histories([io.read_dataset(path) for path in snakemake.input])  # noqa: F821
io.set_provenance(ds, snakemake.params.scene, snakemake.params.hash)  # noqa: F821
io.write_dataset(ds, snakemake.output[0])  # noqa: F821
print(f"{snakemake.params.scene}: {ds.sizes['friction_coefficient']} histories written")  # noqa: F821
