# The `materials` target: named material pairs (config `materials:`), an elastic
# indenter on a half-space. Each pair's self-similar scene (k against c/a) and
# history scene (frictional work of the load cycle) are built by the usual rules
# (influence, solve, check, assemble; history_run); these stages
# draw them in one figure and sum them up in a key-numbers table (with the
# indenter's E1/E2, nu1 and the pair's beta). Not part of `all`: run `snakemake --cores 2 materials`.


rule materials_figure:
    input:
        self_similar=expand(f"{RESULTS}datasets/{{scene}}.nc", scene=list(MATERIAL_PAIRS)),
        cycles=expand(
            f"{RESULTS}datasets/{{scene}}.nc", scene=[h for h, _ in MATERIAL_PAIRS.values()]
        ),
    output:
        png=report(
            f"{RESULTS}figures/materials.png",
            caption="../report/materials.rst",
            category="Figures",
            labels={"figure": "Material pairs: k against c/a and work per cycle",
                    "file": "materials.png"},
        ),
        pdf=f"{RESULTS}figures/materials.pdf",
    params:
        labels=[label for _, label in MATERIAL_PAIRS.values()],
        version=VERSION,
    log:
        f"{RESULTS}logs/figures/materials.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=5,
    script:
        "../scripts/materials_figure.py"


rule materials_key_numbers:
    input:
        expand(f"{RESULTS}datasets/{{scene}}.nc", scene=list(MATERIAL_SCENES)),
    output:
        csv=f"{RESULTS}tables/materials-key-numbers.csv",
        html=report(
            f"{RESULTS}tables/materials-key-numbers.html",
            caption="../report/key_numbers.rst",
            category="Key numbers",
        ),
    params:
        version=VERSION,
        title="contactlib: key numbers of the material pairs",
    log:
        f"{RESULTS}logs/tables/materials-key-numbers.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    resources:
        mem_mb=800,
        runtime=5,
    script:
        "../scripts/key_numbers.py"


rule materials:
    input:
        rules.materials_figure.output,
        rules.materials_key_numbers.output,
    default_target: False
