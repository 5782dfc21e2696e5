# The `viscoelastic` target: one load cycle on a viscoelastic body (config
# `viscoelastic:`) for each cycle duration T, each a history scene visco-T<T>
# built by the usual history rule (history_run); this stage
# draws the dissipation per cycle against T/tau, split into viscous and frictional
# work, and the load-indentation loops at three durations. Not part of `all`:
# run `snakemake --cores 2 viscoelastic`.


rule viscoelastic_figure:
    input:
        expand(f"{RESULTS}datasets/{{scene}}.nc", scene=list(VISCO_SCENES)),
    output:
        png=report(
            f"{RESULTS}figures/viscoelastic.png",
            caption="../report/viscoelastic.rst",
            category="Figures",
            labels={"figure": "Viscoelastic body: dissipation per cycle against the rate",
                    "file": "viscoelastic.png"},
        ),
        pdf=f"{RESULTS}figures/viscoelastic.pdf",
    params:
        version=VERSION,
    log:
        f"{RESULTS}logs/figures/viscoelastic.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=5,
    script:
        "../scripts/viscoelastic_figure.py"


rule viscoelastic:
    input:
        rules.viscoelastic_figure.output,
    default_target: False
