# The `convergence` target: for each study (geometry, method, resolutions), solve
# the configured stick ratios at every n, measure wall time and memory, and the
# error against extrapolated values; one dataset a study and an error-vs-time
# figure. Not part of `all`: run `snakemake --cores 2 convergence`.


rule convergence_study:
    input:
        unpack(study_reference),
    output:
        f"{RESULTS}convergence/{{study}}.nc",
    params:
        study=lambda wildcards: CONVERGENCE["studies"][wildcards.study],
        stick_ratios=CONVERGENCE["stick_ratios"],
        version=VERSION,
    log:
        f"{RESULTS}logs/convergence/{{study}}.log",
    benchmark:
        f"{RESULTS}benchmarks/convergence/{{study}}.tsv"
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    resources:
        mem_mb=lambda wildcards, attempt: int(
            800 + 10 * operator_mb(max(CONVERGENCE["studies"][wildcards.study]["n"]))
        )
        * attempt,
        runtime=lambda wildcards, attempt: 120 * attempt,
    script:
        "../scripts/convergence.py"


rule convergence_figure:
    input:
        expand(f"{RESULTS}convergence/{{study}}.nc", study=sorted(CONVERGENCE["studies"])),
    output:
        png=report(
            f"{RESULTS}figures/convergence.png",
            caption="../report/convergence.rst",
            category="Convergence",
        ),
        pdf=f"{RESULTS}figures/convergence.pdf",
    params:
        version=VERSION,
    log:
        f"{RESULTS}logs/figures/convergence.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=5,
    script:
        "../scripts/convergence_figure.py"


rule convergence_table:
    input:
        expand(f"{RESULTS}convergence/{{study}}.nc", study=sorted(CONVERGENCE["studies"])),
    output:
        csv=f"{RESULTS}tables/convergence.csv",
        html=report(
            f"{RESULTS}tables/convergence.html",
            caption="../report/convergence_table.rst",
            category="Convergence",
        ),
    params:
        version=VERSION,
    log:
        f"{RESULTS}logs/tables/convergence.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    resources:
        mem_mb=800,
        runtime=5,
    script:
        "../scripts/convergence_table.py"


rule convergence:
    input:
        rules.convergence_figure.output,
        rules.convergence_table.output,
    default_target: False
