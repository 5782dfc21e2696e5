# Solve every stick ratio of a scene (Newton per case) from the shared
# influence matrices; the tangential-displacement profiles on the output grid
# are a separate stage, run only for scenes that ask for `displacements`.


rule solve:
    input:
        unpack(influence_files),
    output:
        "results/solutions/{scene}.npz",
    params:
        scene=scene_params,
        version=VERSION,
    log:
        "results/logs/solve/{scene}.log",
    benchmark:
        "results/benchmarks/solve/{scene}.tsv"
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    priority: PRIORITY["solve"]
    resources:
        mem_mb=mem_solve,
        runtime=runtime_solve,
    script:
        "../scripts/solve.py"


rule displacements:
    input:
        solutions="results/solutions/{scene}.npz",
    output:
        "results/profiles/{scene}.npz",
    params:
        scene=scene_params,
        version=VERSION,
    log:
        "results/logs/displacements/{scene}.log",
    benchmark:
        "results/benchmarks/displacements/{scene}.tsv"
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    priority: PRIORITY["displacements"]
    resources:
        mem_mb=mem_solve,
        runtime=runtime_solve,
    script:
        "../scripts/displacements.py"
