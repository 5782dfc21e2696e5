# The paper's figures (PNG and PDF, byte-reproducible) and a table of key
# numbers, each drawn by a contactlib function from the scenes' datasets.


# one rule a figure (figure_fig2 ... figure_fig5), each with its own report caption
for _fig in FIGURES:

    rule:
        name:
            f"figure_{_fig}"
        input:
            [f"results/datasets/{s}.nc" for s in figure_scenes(_fig)],
        output:
            png=report(
                f"results/figures/{_fig}.png",
                caption=f"../report/{_fig}.rst",
                category="Figures",
                labels={"figure": _fig},
            ),
            pdf=f"results/figures/{_fig}.pdf",
        params:
            fig=_fig,
            scenes=figure_scenes(_fig),
            version=VERSION,
        log:
            f"results/logs/figures/{_fig}.log",
        conda:
            "../envs/contactlib.yaml"
        threads: 1
        resources:
            mem_mb=1000,
            runtime=5,
        script:
            "../scripts/figure.py"


rule key_numbers:
    input:
        expand("results/datasets/{scene}.nc", scene=sorted(ALL_SCENES)),
    output:
        csv="results/tables/key-numbers.csv",
        html=report(
            "results/tables/key-numbers.html",
            caption="../report/key_numbers.rst",
            category="Key numbers",
        ),
    params:
        version=VERSION,
    log:
        "results/logs/tables/key-numbers.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    resources:
        mem_mb=800,
        runtime=5,
    script:
        "../scripts/key_numbers.py"
