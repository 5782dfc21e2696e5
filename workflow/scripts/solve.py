"""Rule solve: Newton per stick ratio of a scene -> results/solutions/<scene>.npz."""

import sys
from pathlib import Path

sys.stderr = sys.stdout = open(snakemake.log[0], "w")  # noqa: F821 (snakemake object)

from contactlib import io, pipeline  # noqa: E402
from contactlib.scene import parse_scene, scene_mapping  # noqa: E402

name = snakemake.params.scene["name"]  # noqa: F821
scene = parse_scene(name, scene_mapping(snakemake.config, name))  # noqa: F821
folder = Path(snakemake.input.influence)  # noqa: F821
parts = {part: io.read_arrays(folder / f"{part}.npz") for part in scene.parts}


def progress(i, total):
    print(f"{scene.name}: case {i}/{total} solved", flush=True)


records = pipeline.solve(scene, parts.get("normal"), parts.get("shear"), progress)
failed = [r.stick_ratio for r in records if not r.converged]
if failed:
    print(f"{scene.name}: not converged (kept, flagged): {failed}", flush=True)
io.write_records(records, snakemake.output[0])  # noqa: F821
