# The paper's figures (PNG and PDF, byte-reproducible) and a table of key
# numbers, each drawn by a contactlib function from the scenes' datasets.


# the title a figure is listed under in the report (its caption holds the rest)
FIGURE_TITLES = {
    "fig2": "Fig. 2: friction coefficient k against stick ratio c/a",
    "fig3": "Fig. 3: pressure and shear across the contact",
    "fig4": "Fig. 4: tangential surface displacement",
    "fig5": "Fig. 5: frictional work of a loading half-cycle",
    "history_stick_radius": "History: stick-zone radius along the load path",
    "history_stick_map": "History: stick/slip map over the path",
    "history_loop": "History: displacement loop under load-unload",
    "history_energy": "History: energy dissipated per load cycle",
}


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
                labels={"figure": FIGURE_TITLES.get(_fig, _fig), "file": f"{_fig}.png"},
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
