"""Rule displacements: u R/a^2 on the output grid -> results/profiles/<scene>.npz."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import io, pipeline  # noqa: E402
from contactlib.scene import parse_scene, scene_mapping  # noqa: E402

name = snakemake.params.scene["name"]  # noqa: F821
scene = parse_scene(name, scene_mapping(snakemake.config, name))  # noqa: F821
records = io.read_records(snakemake.input.solutions)  # noqa: F821
io.write_arrays(pipeline.displacements(scene, records), snakemake.output[0])  # noqa: F821
