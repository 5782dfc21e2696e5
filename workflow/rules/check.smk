# Consistency of every case: the slip opposes the shear at every slip point
# (the paper's check) and abs(q) <= k p at every stick point (the one the paper
# leaves out). Run for scenes that ask for the k-curve.


rule check:
    input:
        solutions=f"{RESULTS}solutions/{{scene}}.npz",
    output:
        f"{RESULTS}checks/{{scene}}.npz",
    params:
        scene=scene_params,
        version=VERSION,
    log:
        f"{RESULTS}logs/check/{{scene}}.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    priority: PRIORITY["check"]
    resources:
        mem_mb=500,
        runtime=5,
    script:
        "../scripts/check.py"
