#!/usr/bin/env bash
# Run by snakemake --use-conda after creating the environment, from the working
# directory (the repository root): install contactlib itself into it.
set -euo pipefail
python -m pip install --no-deps -e .
