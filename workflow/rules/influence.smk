# Influence matrices: the collocation operators of the kernels, one part
# ("normal": of the pressures; "shear": of the shears) for one influence set.
# A set is shared by every scene with the same key (geometry, nu, method, n,
# slab ratio and, for the default method, whose meshes carry a node at c, the
# stick ratios). A frictionless scene asks for no shear part.


rule influence:
    output:
        "results/influence/{key}/{part}.npz",
    params:
        spec=influence_spec,
        version=VERSION,
    log:
        "results/logs/influence/{key}-{part}.log",
    benchmark:
        "results/benchmarks/influence/{key}-{part}.tsv"
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    resources:
        mem_mb=mem_influence,
        runtime=lambda wildcards, attempt: 10 * attempt,
    script:
        "../scripts/influence.py"
