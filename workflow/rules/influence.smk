# Influence matrices: the collocation operators of the kernels, one file a part
# ("normal": of the pressures; "shear": of the shears) in the folder of one
# influence set, results/influence/<key>/<part>.npz. A set is shared by every
# scene with the same key (geometry, nu, method, n, slab ratio and, for the
# default method, whose meshes carry a node at c, the stick ratios); it holds
# the parts those scenes need (no shear part if all of them are frictionless).
# Temporary: removed once the scenes' solve jobs have read it (281 MB for the main
# job's two n = 256 sets; rebuilt in seconds if a solve has to run again).


rule influence:
    output:
        temp(directory(f"{RESULTS}influence/{{key}}")),
    params:
        spec=influence_spec,
        version=VERSION,
    log:
        f"{RESULTS}logs/influence/{{key}}.log",
    benchmark:
        f"{RESULTS}benchmarks/influence/{{key}}.tsv"
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    priority: PRIORITY["influence"]
    resources:
        mem_mb=mem_influence,
        runtime=lambda wildcards, attempt: 10 * attempt,
    script:
        "../scripts/influence.py"
