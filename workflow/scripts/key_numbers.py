"""Rules key_numbers and materials_key_numbers: a table of key numbers of scenes (CSV, HTML)."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import io, summary  # noqa: E402

table = summary.key_numbers([io.read_dataset(path) for path in snakemake.input])  # noqa: F821
io.write_table(table, snakemake.output.csv)  # noqa: F821
title = getattr(snakemake.params, "title", "contactlib: key numbers of every scene")  # noqa: F821
io.write_table(summary.report_rows(table), snakemake.output.html,  # noqa: F821
               title=title)
