"""Rule assemble: the scene's dataset (with its displacement profiles, if asked for)
-> results/datasets/<scene>.nc (atomic)."""

import sys

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import io, pipeline  # noqa: E402
from contactlib.scene import parse_scene, scene_mapping  # noqa: E402

name = snakemake.params.scene["name"]  # noqa: F821
scene = parse_scene(name, scene_mapping(snakemake.config, name))  # noqa: F821
inp = snakemake.input  # noqa: F821
records = io.read_records(inp.solutions)
ds = pipeline.assemble(
    scene,
    records,
    checks=io.read_arrays(inp.check) if "check" in inp.keys() else None,
    work=io.read_arrays(inp.energy) if "energy" in inp.keys() else None,
    profiles=(pipeline.displacements(scene, records) if "displacements" in scene.outputs
              else None),
)
io.write_dataset(ds, snakemake.output[0])  # noqa: F821
print(f"{name}: {ds.sizes['stick_ratio']} cases written", flush=True)
