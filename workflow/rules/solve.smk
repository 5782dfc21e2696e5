# Solve every stick ratio of a scene (Newton per case) from the shared
# influence matrices. (The tangential-displacement profiles on the output grid,
# for scenes that ask for `displacements`, are computed by the assemble job.)


rule solve:
    input:
        unpack(influence_files),
    output:
        f"{RESULTS}solutions/{{scene}}.npz",
    params:
        scene=scene_params,
        version=VERSION,
    log:
        f"{RESULTS}logs/solve/{{scene}}.log",
    benchmark:
        f"{RESULTS}benchmarks/solve/{{scene}}.tsv"
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    priority: PRIORITY["solve"]
    resources:
        mem_mb=mem_solve,
        runtime=runtime_solve,
    script:
        "../scripts/solve.py"

