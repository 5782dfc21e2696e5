# One tidy, CF-annotated, compressed netCDF dataset a scene, written atomically,
# with provenance (contactlib version, the scene's config hash).


rule assemble:
    input:
        unpack(stage_files),
    output:
        "results/datasets/{scene}.nc",
    params:
        scene=scene_params,
        version=VERSION,
    log:
        "results/logs/assemble/{scene}.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    priority: PRIORITY["assemble"]
    resources:
        mem_mb=800,
        runtime=5,
    script:
        "../scripts/assemble.py"
