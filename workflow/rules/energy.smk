# Frictional work of the loading half-cycle (paper Eqs. 17-21, both sides of the
# axis for the cylinder). Run only for scenes that ask for `energy`.


rule energy:
    input:
        solutions=f"{RESULTS}solutions/{{scene}}.npz",
    output:
        f"{RESULTS}energy/{{scene}}.npz",
    params:
        scene=scene_params,
        version=VERSION,
    log:
        f"{RESULTS}logs/energy/{{scene}}.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    priority: PRIORITY["energy"]
    resources:
        mem_mb=500,
        runtime=5,
    script:
        "../scripts/energy.py"
