# The `layers` target: a sphere and a cylinder on an elastic layer, smooth and
# bonded base, at nu = 0.3 and 0.45: the frictionless load ratio and k(c/a)
# against a/h = 0 ... 10 (one dataset, a figure and a table). Not part of
# `all`: run `snakemake --cores 2 layers`.


rule layers_study:
    output:
        f"{RESULTS}layers/layers.nc",
    params:
        version=VERSION,
    log:
        f"{RESULTS}logs/layers/study.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=20,
    script:
        "../scripts/layers_study.py"


rule layers_figure:
    input:
        rules.layers_study.output,
    output:
        png=report(
            f"{RESULTS}figures/layers.png",
            caption="../report/layers.rst",
            category="Figures",
            labels={"figure": "Layers: frictionless load and k against a/h",
                    "file": "layers.png"},
        ),
        pdf=f"{RESULTS}figures/layers.pdf",
        csv=f"{RESULTS}tables/layers.csv",
    params:
        version=VERSION,
    log:
        f"{RESULTS}logs/layers/figure.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=5,
    script:
        "../scripts/layers_figure.py"


rule layers:
    input:
        rules.layers_figure.output,
    default_target: False
