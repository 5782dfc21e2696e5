# The paper's figures (PNG and PDF, byte-reproducible) and a table of key
# numbers, each drawn by a contactlib function from the scenes' datasets.


# one rule a family of figures (figures_paper: fig2 ... fig5 from the self-similar
# scenes; figures_history: history_* from the history scenes), one job each that
# draws the family's figures in parallel worker processes (threads), forked
# after the imports (matplotlib, xarray: most of a figure's time when it had a
# process of its own); each figure keeps its own report caption. The history
# family's datasets are ready early: it takes at most half of the cores
# (side_threads), so that it runs beside the self-similar scenes' jobs instead
# of waiting for all of them; the paper family, last in line, takes two.
for _family, _figs in FIGURE_FAMILIES.items():

    rule:
        name:
            f"figures_{_family}"
        input:
            figure_inputs(_figs),
        output:
            **figure_outputs(_figs),
        params:
            figures={fig: figure_scenes(fig) for fig in _figs},
            version=VERSION,
        log:
            f"{RESULTS}logs/figures/{_family}.log",
        benchmark:
            f"{RESULTS}benchmarks/figures/{_family}.tsv"
        conda:
            "../envs/contactlib.yaml"
        threads: figure_threads(_family, min(2, len(_figs)))
        priority: PRIORITY[f"figures_{_family}"]
        resources:
            mem_mb=800 + 400 * min(2, len(_figs)),
            runtime=5 + len(_figs),
        script:
            "../scripts/figure.py"


rule key_numbers:
    input:
        expand(f"{RESULTS}datasets/{{scene}}.nc", scene=sorted(ALL_SCENES)),
    output:
        csv=f"{RESULTS}tables/key-numbers.csv",
        html=report(
            f"{RESULTS}tables/key-numbers.html",
            caption="../report/key_numbers.rst",
            category="Key numbers",
        ),
    params:
        version=VERSION,
    log:
        f"{RESULTS}logs/tables/key-numbers.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    priority: PRIORITY["key_numbers"]
    resources:
        mem_mb=800,
        runtime=5,
    script:
        "../scripts/key_numbers.py"
