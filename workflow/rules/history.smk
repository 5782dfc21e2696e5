# Scenes of kind `history`: one incremental run a friction coefficient (jobs in
# parallel), stacked along `friction_coefficient` into the scene's dataset.


rule history_run:
    output:
        "results/history/{hscene}/k{index}.nc",
    params:
        run=history_params,
        version=VERSION,
    log:
        "results/logs/history/{hscene}-k{index}.log",
    benchmark:
        "results/benchmarks/history/{hscene}-k{index}.tsv"
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    resources:
        mem_mb=mem_history,
        runtime=runtime_history,
    script:
        "../scripts/history_run.py"


rule history_assemble:
    input:
        history_runs,
    output:
        "results/datasets/{hscene}.nc",
    params:
        scene=lambda wildcards: HISTORIES[wildcards.hscene].name,
        hash=lambda wildcards: HISTORIES[wildcards.hscene].hash,
        version=VERSION,
    log:
        "results/logs/assemble/{hscene}.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    resources:
        mem_mb=800,
        runtime=5,
    script:
        "../scripts/history_assemble.py"
