"""Rule convergence_table: the speed-accuracy trade of every study (CSV and HTML)."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import io  # noqa: E402
from contactlib.convergence import trade_table  # noqa: E402

rows = trade_table([io.read_dataset(p) for p in snakemake.input])  # noqa: F821
io.write_table(rows, snakemake.output.csv, digits=3)  # noqa: F821
io.write_table(rows, snakemake.output.html, digits=3,  # noqa: F821
               title="Speed-accuracy trade: error in k against time per solve")
