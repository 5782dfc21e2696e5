# Scenes of kind `history`: one incremental run a friction coefficient, in
# parallel worker processes of one job a scene, stacked along
# `friction_coefficient` into the scene's dataset by the same job (a separate
# stacking job cost a process start and a netCDF round trip a run).


rule history_run:
    output:
        f"{RESULTS}datasets/{{hscene}}.nc",
    params:
        run=history_params,
        version=VERSION,
    log:
        f"{RESULTS}logs/history/{{hscene}}.log",
    benchmark:
        f"{RESULTS}benchmarks/history/{{hscene}}.tsv"
    conda:
        "../envs/contactlib.yaml"
    threads: history_threads
    priority: PRIORITY["history_run"]
    resources:
        mem_mb=mem_history,
        runtime=runtime_history,
    script:
        "../scripts/history_run.py"
