# Scenes of kind `physical`: a path of forces in SI (radius, materials, forces;
# contactlib.physical.physical_history), one job a scene writing its dataset (the
# history's dimensionless variables and the SI ones beside them), a table of the
# path points and cycles in N, m, Pa and J, and a figure in those units.


rule physical_run:
    output:
        dataset=f"{RESULTS}datasets/{{pscene}}.nc",
        table=f"{RESULTS}tables/{{pscene}}.csv",
        png=report(
            f"{RESULTS}figures/{{pscene}}.png",
            caption="../report/physical.rst",
            category="Physical units",
        ),
        pdf=f"{RESULTS}figures/{{pscene}}.pdf",
    params:
        run=physical_params,
        version=VERSION,
    log:
        f"{RESULTS}logs/physical/{{pscene}}.log",
    benchmark:
        f"{RESULTS}benchmarks/physical/{{pscene}}.tsv"
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    priority: PRIORITY["physical_run"]
    resources:
        mem_mb=600,
        runtime=10,
    script:
        "../scripts/physical_run.py"
