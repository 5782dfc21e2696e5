# Scenes of kind `history`: one incremental run a friction coefficient, in
# parallel worker processes of one job a scene (results/history/<scene>/k<i>.nc),
# then stacked along `friction_coefficient` into the scene's dataset.


rule history_run:
    output:
        directory("results/history/{hscene}"),
    params:
        run=history_params,
        version=VERSION,
    log:
        "results/logs/history/{hscene}.log",
    benchmark:
        "results/benchmarks/history/{hscene}.tsv"
    conda:
        "../envs/contactlib.yaml"
    threads: history_threads
    priority: PRIORITY["history_run"]
    resources:
        mem_mb=mem_history,
        runtime=runtime_history,
    script:
        "../scripts/history_run.py"


rule history_assemble:
    input:
        "results/history/{hscene}",
    output:
        "results/datasets/{hscene}.nc",
    params:
        scene=lambda wildcards: HISTORIES[wildcards.hscene].name,
        hash=lambda wildcards: HISTORIES[wildcards.hscene].hash,
        runs=lambda wildcards: len(HISTORIES[wildcards.hscene].frictions),
        version=VERSION,
    log:
        "results/logs/assemble/{hscene}.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    priority: PRIORITY["history_assemble"]
    resources:
        mem_mb=800,
        runtime=5,
    script:
        "../scripts/history_assemble.py"
