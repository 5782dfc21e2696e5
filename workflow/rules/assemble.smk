# One tidy, CF-annotated, compressed netCDF dataset a scene, written atomically,
# with provenance (contactlib version, the scene's config hash). The job also
# computes the tangential-displacement profiles of a scene that asks for them
# (the costly kernels at the output grid); a job of their own cost more in
# process start-up than the profiles themselves for most scenes.


rule assemble:
    input:
        unpack(stage_files),
    output:
        f"{RESULTS}datasets/{{scene}}.nc",
    params:
        scene=scene_params,
        version=VERSION,
    log:
        f"{RESULTS}logs/assemble/{{scene}}.log",
    benchmark:
        f"{RESULTS}benchmarks/assemble/{{scene}}.tsv"
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    priority: PRIORITY["assemble"]
    resources:
        mem_mb=800,
        runtime=runtime_solve,
    script:
        "../scripts/assemble.py"
