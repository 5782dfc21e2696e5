"""Rule convergence_study: one study's errors, times and memory -> results/convergence/."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import convergence, io  # noqa: E402

st = snakemake.params.study  # noqa: F821
ref = snakemake.input.get("reference")  # noqa: F821
result = convergence.study(
    st["geometry"], st["nu"], st["method"], st["n"], snakemake.params.stick_ratios,  # noqa: F821
    slab_ratio=st.get("slab_ratio", 0.0),
    reference=io.study_from_dataset(io.read_dataset(ref)) if ref else None,
    progress=lambda text: print(text, flush=True),
)
ds = io.study_to_dataset(result, name=snakemake.wildcards.study)  # noqa: F821
io.write_dataset(ds, snakemake.output[0])  # noqa: F821
